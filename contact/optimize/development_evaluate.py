"""One design of the development analysed and scored: the coarse LTCA of a synthesised
case at the light and the design torque, its metrics, and the search's objective.

:func:`analyse_design` runs the contact of a design's flank (the ease-off and the LTCA of
:func:`contact.pipeline.run_analysis`'s contact-only chain, without its datasets of the
unloaded TCA and its tree), at :data:`COARSE_LTCA` inside the search or :data:`CHECK_LTCA`
at the check, with the shell teeth kept across designs (:class:`KeptTeeth`), and summarises
it (:func:`ltca_metrics`: the LTE, peak pressure, edge share and pattern of
:func:`contact.study.summary.point_summary`, the footprint centre, the plastic share,
:func:`lte_spread`; the grid and :func:`static_strength`).
:func:`evaluator` makes the objective of one side's search from it: each design
synthesised, analysed, scored (:func:`development_score`), recorded and printed, the
stage ended by :class:`StageStop`. :func:`design_torque_of` is the torque the bearing is
checked at. Split out of :mod:`contact.optimize.development` (issue 71), which
re-exports every public name.

The analysis seam: the other modules of the development call :func:`analyse_design` through
this module (``development_evaluate.analyse_design``), so that one ``monkeypatch.setattr`` on
this module replaces the analysis of the search, the check and the coast flank alike.
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import math
import time
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import xarray as xr

from contact.compliance.fe.worker_cpu import cpu_seconds
from contact.ltca import LTCAOptions
from contact.ltca.edges import EDGE_KINDS
from contact.ltca.summary import flank_peak_pressure  # re-exported: the development's name
from contact.optimize.development_result import (
    DevelopmentEvaluation,
    case_torques,
    metrics_text,
)
from contact.optimize.development_targets import (
    CROWNING_NAME,
    FAILED,
    HEIGHT_NAME,
    METRIC_NAMES,
    RELIEF_NAMES,
    STAGE_TERMS,
    DevelopmentTargets,
    development_score,
    footprint_centre,
    working_depth_centre,
)
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number
from geometry.machine.meshing import WarmSeeds
from geometry.pair.assembly import Misalignment
from geometry.synthesis.basic_design import BasicDesign

#: the development's one logger, whichever of its modules logs
log = logging.getLogger("contact.optimize.development")


#: LTCA settings inside the loop: one mesh cycle, 8 roll positions, 12 segments per curve
#: (the default analysis has 2 × 20 and 24); shell compliance, no root stress. On the
#: passenger-car hypoid of tests/data the pattern ends move by at most one grid node and
#: the LTE by a few µrad against the default sampling — enough to rank designs; the
#: developed design is reported with the default sampling by ``ltca run``.
COARSE_LTCA = LTCAOptions(cycles=1, rolls_per_cycle=8, segments=12)


#: the decimals to which the development's memos key a design's values (file units: µm,
#: µrad, degrees, fractions): the coarse search's (:func:`evaluator`) and the check's
#: (:func:`~contact.optimize.development_variant.checked_analysis`); far below any step
#: the development takes (≥ 0.1 µrad, 0.01 of a fraction), far above round-off (~1e-14),
#: so a design reached again through another computation of the same number is the same
MEMO_DECIMALS = 9


#: LTCA settings of the final check: ``ltca run``'s defaults (2 mesh cycles, 20 roll
#: positions each, 24 segments per curve, shell compliance)
CHECK_LTCA = LTCAOptions()


#: the tip edges of the flank boundary (:data:`contact.ltca.edges.EDGE_KINDS`): the gear's
#: tip edge and the pinion's edge (where the pinion mate leaves its blank: its tip line on
#: the gear flank, the pinion's face being the wider); the load they carry is the
#: ``tip_edge_share`` metric (:func:`ltca_metrics`) the tip-relief LTE step asks
#: (:data:`contact.optimize.development_relief_lte.TIP_LTE`)
TIP_EDGE_KINDS = ("gear_tip", "pinion_edge")


def design_torque_of(basic: BasicDesign, case: Case) -> tuple[float, str]:
    """The pinion torque [N·m] the development checks the bearing at, and where it is from.

    ``[synthesis] design_torque`` of the basic file if given, else the synthesised case's
    ``[rating] design_torque``, else the ISO 10300 capacity of the case (the torque at
    which the long-life safety reaches S_H,min or S_F,min;
    :func:`contact.load_capacity.iso10300.capacity.with_design_torque`); where the rating
    cannot give one,
    the largest torque of the case's ``[operating]`` table.
    """
    from contact.load_capacity.iso10300.capacity import with_design_torque

    _, torque, why = with_design_torque(case, basic.options.design_torque)
    if math.isfinite(torque) and torque > 0:
        return float(torque), why
    log.info("design torque from the rating unavailable (%s)", why)
    return float(max(case.operating.torque)), f"largest [operating] torque ({why})"


def _ltca(tree):
    """The ``/ltca`` group of an analysis' tree, or the ``/ltca`` dataset itself."""
    return tree if isinstance(tree, xr.Dataset) else tree["/ltca"]


def static_strength(tree) -> float:
    """The static strength σ_Hlim·Z_NT,stat·Z_W·Z_X [MPa] of the weaker member's material of
    an analysis (the ``/ltca`` attributes ``material_pinion``, ``material_gear`` of its tree
    or of the ``/ltca`` dataset) at the verdict's grade: the verdict's own
    (:func:`contact.study.verdicts.flank_static_strength`, ISO 6336-2 at the static
    stress); inf where the tree names no material."""
    from contact.study.verdicts import flank_static_strength

    found = flank_static_strength(_ltca(tree))
    return math.inf if found is None else float(found.strength)


def design_metrics(tree, case: Case) -> dict[str, np.ndarray]:
    """The development's metrics of one analysis (``tree``, its ``/ltca`` group) of
    ``case``, per torque (arrays of shape (n_torques,)): :func:`ltca_metrics` of its
    ``/ltca`` dataset."""
    return ltca_metrics(tree["/ltca"].to_dataset(), case)


def ltca_metrics(ltca, case: Case) -> dict[str, np.ndarray]:
    """The development's metrics of an ``/ltca`` dataset (:func:`contact.ltca.loaded_tca`)
    of ``case``, per torque (arrays of shape (n_torques,)): those of
    :func:`contact.study.summary.point_summary` named in :data:`METRIC_NAMES` (the LTE
    peak-to-peak and the flank's peak pressure of the dataset, the edge load share,
    :func:`contact.ltca.summary.edge_load_share`, and the pattern's extent,
    :func:`contact.study.summary.pattern_dimensions`: what ``point_summary`` gives them
    from, without its ``/utca`` summaries the development does not score), the footprint
    centre ``pattern_centre_u``/``pattern_centre_v`` [1 of the face width / working depth]
    (:func:`footprint_centre`), ``plastic_share`` [1] (the largest segment's),
    ``lte_spread`` [1] (:func:`lte_spread`) and ``tip_edge_share`` [1] (the edge load
    share of the tip edges alone, :data:`TIP_EDGE_KINDS`). The flank peak pressure is
    :func:`flank_peak_pressure`'s: the dataset's without the contact curves shorter than
    their own contact width."""
    from contact.ltca.summary import edge_load_share
    from contact.study.summary import pattern_dimensions

    s = {"lte_peak_to_peak": ltca["lte_peak_to_peak"].values,
         "pressure_max_flank": flank_peak_pressure(ltca),
         "edge_load_share": edge_load_share(ltca), **pattern_dimensions(ltca, case)}
    out = {k: np.asarray(s[k], float) for k in METRIC_NAMES if k in s}
    # the centre of the footprint, not of the pressure (footprint_centre's notes)
    env = ltca["pressure_envelope"].transpose("torque", "u", "v")
    out["pattern_centre_u"], out["pattern_centre_v"] = footprint_centre(
        env.values, ltca["u"].values, ltca["v"].values)
    share = (np.nan_to_num(ltca["plastic_load_share"].values, nan=0.0)
             if "plastic_load_share" in ltca
             else np.zeros((len(out["lte_peak_to_peak"]), 1)))
    out["plastic_share"] = share.max(axis=1)
    out["lte_spread"] = lte_spread(ltca)
    out["tip_edge_share"] = np.asarray(edge_load_share(ltca, kinds=TIP_EDGE_KINDS), float)
    out.update(edge_peak_metrics(ltca))
    out.update(light_edge_metrics(ltca))
    return out


def light_edge_metrics(ltca) -> dict[str, np.ndarray]:
    """The edge contact of an ``/ltca`` dataset per torque, as ``ltca run`` prints and
    judges it: ``pressure_max_edge`` [MPa] (its table's ``p_max edge``, 0 where no edge
    segment is loaded) and ``edge_contact_share`` [1] (the ``edge_contact`` check's
    counted share, :func:`contact.study.verdicts.edge_contact_share`); none where the
    dataset has neither. The edge-peak steps' light-torque rule reads them
    (:mod:`contact.optimize.development_light_edge`). Where the dataset has its
    segments' kinds and peaks, also ``edge_pressure_<kind>`` [MPa] for each edge kind
    (:data:`contact.ltca.edges.EDGE_KINDS`): the peak of ``pressure_max`` over that kind's
    segments, whatever share of the torque they carry (0 where none is loaded) — which
    edge ``p_max edge`` is on, read by the coast flank's light-edge step
    (:mod:`contact.optimize.development_coast_light_edge`; the case's ``[development]``
    tables leave them out: :data:`~contact.optimize.development_result.
    UNWRITTEN_METRICS`)."""
    from contact.study.verdicts import edge_contact_share  # imports contact.ltca

    out = {}
    if "pressure_max_edge" in ltca:
        out["pressure_max_edge"] = np.nan_to_num(
            np.asarray(ltca["pressure_max_edge"].values, float))
    if {"force", "moment_arm", "segment_kind"} <= set(ltca.variables):
        out["edge_contact_share"] = np.asarray(edge_contact_share(ltca), float)
    if {"pressure_max", "segment_kind"} <= set(ltca.variables):
        kind = np.asarray(ltca["segment_kind"].values).astype(str)
        pressure = np.nan_to_num(np.asarray(
            ltca["pressure_max"].transpose("torque", ...).values, float))
        for k in EDGE_KINDS:
            on = pressure[..., kind == k].reshape(pressure.shape[0], -1)
            out[f"edge_pressure_{k}"] = (on.max(axis=1) if on.size
                                         else np.zeros(pressure.shape[0]))
    return out


#: the metrics :func:`edge_peak_metrics` adds, each per torque [MPa]: the largest edge
#: peak ``ltca run``'s ``edge_pressure`` check judges, the static strength it judges it
#: against, and the peak of each edge kind (:data:`contact.ltca.edges.EDGE_KINDS`)
EDGE_PEAK_METRICS = ("edge_peak", "edge_static_strength",
                     *(f"edge_peak_{k}" for k in EDGE_KINDS))


def edge_peak_metrics(ltca) -> dict[str, np.ndarray]:
    """The edge peaks of an ``/ltca`` dataset as ``ltca run``'s verdict judges them
    (:func:`contact.study.verdicts.edge_peaks`), per torque: ``edge_peak`` [MPa] the
    largest over the edge kinds counted (0: no edge carries
    :data:`~contact.study.verdicts.EDGE_SHARE_MIN` of the torque below the edges'
    contact-pressure limit), ``edge_static_strength`` [MPa] the weaker member's flank
    static strength σ_Hlim·Z_NT the ``edge_pressure`` attention compares it with, and
    ``edge_peak_<kind>`` [MPa] each kind's (:data:`EDGE_PEAK_METRICS`); none where the
    dataset names no material. The edge-peak step of the development reads them
    (:mod:`contact.optimize.development_edge_peak`)."""
    from contact.study.verdicts import edge_peaks  # imports contact.ltca

    found = edge_peaks(ltca)
    if found is None:
        return {}
    n = int(ltca.sizes["torque"])
    zero = np.zeros(n)
    out = {f"edge_peak_{k}": np.asarray(found.peaks.get(k, zero), float) for k in EDGE_KINDS}
    out["edge_peak"] = np.max([np.asarray(p, float) for p in found.peaks.values()] + [zero],
                              axis=0)
    out["edge_static_strength"] = np.full(n, float(found.static))
    return {k: out[k] for k in EDGE_PEAK_METRICS}


def lte_spread(ltca) -> np.ndarray:
    """The LTE spread of an ``/ltca`` dataset per torque [1]: LTE peak-to-peak over its
    mean where the mean exceeds the unloaded TE's peak-to-peak, else 0 — the quantity the
    verdict's plausibility check compares with
    :data:`contact.ltca.plausibility.LTE_SPREAD_LIMIT` (its module docstring: seed
    Table 3.1 gives 0.04–0.12 for a mesh that carries its load on the flanks)."""
    pp = np.asarray(ltca["lte_peak_to_peak"].values, float)
    mean = np.asarray(ltca["lte_mean"].values, float)
    ute = np.asarray(ltca["unloaded_transmission_error"].values, float)
    ute_pp = float(np.nanmax(ute) - np.nanmin(ute)) if np.any(np.isfinite(ute)) else 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(mean > ute_pp, pp / mean, 0.0)


def grid_bounds(tree) -> tuple[float, float, float, float]:
    """The ends of an analysis' contact grid: (u first, u last, v first, v last) [1], the
    face and the working depth the pattern is judged on (:func:`development_score`);
    ``tree``: an analysis' tree or its ``/ltca`` dataset."""
    lt = _ltca(tree)
    u, v = lt["u"].values, lt["v"].values
    return float(u[0]), float(u[-1]), float(v[0]), float(v[-1])


class KeptTeeth:
    """The shell tooth models (seed Eq. 3.1–3.11) of a development's designs, each built
    once: the LTCA's ``"shell"`` compliance with the teeth kept across designs.

    Every design of a development has the same gear (the Formate gear of the basic
    design's blank; the development varies only the pinion's flanks), so the gear's
    tooth is measured and its shell factorised once, keyed by the case's pair and gear
    data. The pinion's tooth is keyed by the caller's ``pinion_key``: the development
    gives the bearing-stage prescriptions (the coast flank's search: the drive's and the
    coast's), so the designs of the relief stage (the same
    flanks but for the blade's toprem and flankrem, ≤ 60 µm of normal ease-off at the
    flank's ends) share the tooth of their bearing design. The shell's thickness and
    height are least-squares fits over the whole tooth (a linear thickness from toe to
    heel and root to tip, :func:`contact.compliance.tooth.shell_tooth_from_case`), which
    such a relief moves by far less than the fit's own residual; the developed design is
    analysed with its own teeth by ``ltca run``.

    It also keeps each analysis' result (:meth:`analysed`, :func:`analyse_design`) for a
    development of the same basic design run again with these teeth
    (:meth:`begin_development`): there the n-th analysis of the same inputs — the same
    case to the last bit, torques, LTCA options, pinion-tooth key and flank — is read
    back as the n-th one of the first run gave it (issue 71: the Formate development run
    in full after the stop on a foreseen torque cut repeats the stopped one's search and
    check design for design, :mod:`contact.optimize.development_shared`), the repeated
    run's numbers its first run's. Within one development every analysis is computed, as
    before: an earlier analysis of the same inputs there ran with other envelope seeds
    continued from other trials, and the same inputs' LTCA is not reproducible to the last
    design from one process to the next (two of the 9x31's designs, docs/performance.md),
    so a read-back there could be another number than the run computes.
    """

    def __init__(self) -> None:
        self._teeth: dict[tuple, Any] = {}
        self._ease_offs: dict[tuple, Any] = {}
        self._analyses: dict[tuple, list[Any]] = {}
        self._asked: dict[tuple, int] = {}
        self.built = 0
        self.ease_offs_reused = 0
        self.analyses_reused = 0

    def begin_development(self) -> None:
        """Start a development's run with these teeth: its analyses are counted anew, so
        that the n-th analysis of an input it asks for reads back the n-th result an
        earlier run kept (:meth:`analysed`)."""
        self._asked = {}

    def analysed(self, key: tuple, analyse: Callable[[], Any]) -> Any:
        """The n-th analysis of ``key`` (:func:`analysis_key`) in this development's run:
        the n-th result kept under it by an earlier run (:meth:`begin_development`), a deep
        copy (a caller may change what it is handed); else ``analyse()``, kept as the n-th.
        An analysis that raises keeps nothing (it raises again when asked again).

        Parameters
        ----------
        key : tuple — what the result is a function of (hashable)
        analyse : callable () → result

        Returns
        -------
        The result (metrics dict, grid tuple for :func:`analyse_design`).
        """
        import copy

        n = self._asked.get(key, 0)
        self._asked[key] = n + 1
        kept = self._analyses.setdefault(key, [])
        if n < len(kept):
            self.analyses_reused += 1
            return copy.deepcopy(kept[n])
        result = analyse()
        if n == len(kept):
            kept.append(result)
        return copy.deepcopy(result)

    def ease_off(self, case: Case, flank: str):
        """The ease-off (:func:`contact.utca.easeoff.ease_off`) of ``case``'s ``flank``
        [rad], each design's computed once per development: keyed by its teeth
        (:meth:`~geometry.case.Case.teeth_key`), misalignment and flank — what the
        ease-off is a function of, not of the torque. Inside a trial's
        :class:`~geometry.machine.meshing.WarmSeeds` block the process memo is off
        (:func:`~contact.utca.easeoff.ease_off`), so the coast flank developed again at its
        own design torque (:func:`~contact.optimize.development_coast_flank.coast_at_its_torque`:
        the same designs, their syntheses from the memo) computed each trial's ease-off a
        second time (issue 75: 0.07 s each on the passenger-car hypoid 10x43); kept here,
        for the development's own analyses alone. Outside a block the process memo serves."""
        from contact.utca.easeoff import ease_off
        from geometry.machine.meshing import warm_seeds_active

        if not warm_seeds_active():
            return ease_off(case, flank=flank)
        key = (case.teeth_key(), repr(case.misalignment), flank)
        eo = self._ease_offs.get(key)
        if eo is None:
            eo = ease_off(case, flank=flank)
            self._ease_offs[key] = eo
        else:
            self.ease_offs_reused += 1
        return eo

    def _tooth(self, case: Case, member: str, key: tuple, options: LTCAOptions):
        from contact.compliance.tooth import shell_tooth_from_case

        full = (member, key, options.theory, options.n_height, options.n_face,
                options.youngs_modulus, options.poisson_ratio)
        tooth = self._teeth.get(full)
        if tooth is None:
            tooth = shell_tooth_from_case(case, member, youngs_modulus=options.youngs_modulus,
                                          poisson_ratio=options.poisson_ratio)
            tooth.shell_model(options.theory, options.n_height, options.n_face)
            self._teeth[full] = tooth
            self.built += 1
        return tooth

    def compliance(self, pinion_key: tuple):
        """The ``"shell"`` compliance model (:mod:`contact.ltca.compliance_models`) with
        the pinion tooth kept under ``pinion_key`` and the gear tooth of the case's gear."""
        from contact.ltca.compliance_models import ComplianceModel

        def prepare(case: Case, easeoff: Any, options: LTCAOptions):
            from contact.compliance.mesh import PairComplianceModel, mesh_compliance_many

            t0 = time.perf_counter()
            model = PairComplianceModel(
                pinion=self._tooth(case, "pinion", ("pinion", repr(case.pair), *pinion_key),
                                   options),
                gear=self._tooth(case, "gear", ("gear", repr(case.pair), repr(case.gear)),
                                 options),
                theory=options.theory, n_height=options.n_height, n_face=options.n_face,
                build_time=time.perf_counter() - t0)
            return functools.partial(mesh_compliance_many, case, model=model)

        return ComplianceModel("shell", prepare, "the shell model, teeth kept across the "
                               "designs of a development (contact.optimize.development)")


def analyse_design(case: Case, torques: list[float], misalignment: Misalignment | None = None,
                   options: LTCAOptions = COARSE_LTCA, teeth: KeptTeeth | None = None,
                   pinion_key: tuple = (), flank: str = "drive"):
    """One design's ``flank`` (``"drive"`` or ``"coast"``) analysed at ``torques`` [N·m]
    (contact only, no deviations), at ``misalignment`` if given, with ``options`` (default
    :data:`COARSE_LTCA`) and, where ``teeth`` is given, the shell teeth it keeps (the
    pinion's under ``pinion_key``). Returns the metrics (:func:`ltca_metrics`) and (u
    first, u last, v first, v last, static strength [MPa]) (:func:`grid_bounds`,
    :func:`static_strength`). The analysis seam (module docstring); its errors propagate.

    The ease-off (:func:`contact.utca.easeoff.ease_off`) and the LTCA
    (:func:`contact.ltca.loaded_tca`, from the ease-off's transitions) of
    :func:`contact.pipeline.run_analysis`'s contact-only chain, without what the metrics
    do not read: the ``/easeoff`` and ``/utca`` datasets (the unloaded TCA's contact
    curves over 30 rolls of 3 pairs) and the analysis tree (issue 75: the same metrics,
    bit for bit, tests/test_development.py)."""
    from contact.ltca import loaded_tca
    from contact.utca.easeoff import ease_off

    c = case if misalignment is None else dataclasses.replace(case, misalignment=misalignment)
    if teeth is None:
        eo = ease_off(c, flank=flank)
        ltca = loaded_tca(c, torques, flank=flank, options=options, easeoff=eo)
        return ltca_metrics(ltca, c), (*grid_bounds(ltca), static_strength(ltca))

    def analyse():
        kept = dataclasses.replace(options, compliance=teeth.compliance(pinion_key))
        eo = teeth.ease_off(c, flank)
        ltca = loaded_tca(c, torques, flank=flank, options=kept, easeoff=eo)
        return ltca_metrics(ltca, c), (*grid_bounds(ltca), static_strength(ltca))

    # the same inputs analysed by an earlier run of this basic design's development
    # (development_shared): read back
    return teeth.analysed(analysis_key(c, torques, options, pinion_key, flank), analyse)


def analysis_key(case: Case, torques, options: LTCAOptions, pinion_key: tuple,
                 flank: str) -> tuple:
    """What :func:`analyse_design`'s result with kept teeth is a function of: the case
    analysed (its full ``repr``, every float to the last bit, its misalignment,
    operating point and tables included), the torques [N·m], the LTCA options (their
    ``repr``: a compliance model handed in, which carries no value ``repr`` of its own,
    makes the key of one object alone), the key of the pinion tooth kept
    (:class:`KeptTeeth`) and the flank.

    Parameters
    ----------
    case : geometry.case.Case — as analysed (misalignment applied)
    torques : sequence of float, shape (n,) — [N·m]
    options : LTCAOptions — before the kept teeth's compliance is put in
    pinion_key : tuple
    flank : str — ``"drive"`` or ``"coast"``

    Returns
    -------
    tuple — hashable
    """
    return (repr(case), tuple(float(t) for t in np.ravel(torques)), repr(options),
            tuple(pinion_key), flank)


class StageStop(Exception):
    """Raised inside the objective when a design meets every target of its stage or the
    stage's budget is spent."""


def _ratios_text(case: Case) -> str:
    """The contact ratios ε_vα, ε_vβ of a case's basic design as the development's first
    line says them ("; contact ratios eps_va …, eps_vb … (ISO 10300-1 …)"; "" where the
    case has no ``[design]`` table to read them from): ``ltca synthesize`` printed them
    only after the development, minutes later (round 18's 6x29 hypoid, ε_vβ 0.82, told
    after 12 min of wall time). Source: ISO 10300-1:2014 Annex A
    (:func:`~contact.optimize.development_matched_te.contact_ratios`).
    """
    from contact.optimize.development_matched_te import contact_ratios  # (import cycle)

    eps_va, eps_vb = contact_ratios(case)
    if not (math.isfinite(eps_va) and math.isfinite(eps_vb)):
        return ""
    return (f"; contact ratios eps_va {eps_va:.2f}, eps_vb {eps_vb:.2f} (ISO 10300-1 virtual "
            f"cylindrical gears)")


def evaluator(basic: BasicDesign, targets: DevelopmentTargets, setup: dict[str, Any],
              teeth: KeptTeeth, say: Callable[[str], None],
              evals: list[DevelopmentEvaluation], side: str, n_max: int,
              key_prefix: tuple = (),
              torque_name: str = "",
              confirm: Callable[[DevelopmentEvaluation], DevelopmentEvaluation | None]
              | None = None) -> Callable[..., DevelopmentEvaluation]:
    """The objective of one side's search (:func:`develop`): ``evaluate(values, stage,
    make, budget, pinion_key)`` synthesises a design (``make()``), analyses its ``side``
    flank (``"drive"`` or ``"coast"``) by :data:`COARSE_LTCA` at the light and the design
    torque, appends it to ``evals``, prints its line and raises :class:`StageStop` where it
    meets every target of ``stage`` or the stage's ``budget`` is spent. The first design
    of the drive flank fixes ``setup`` (torques, the depth centre aimed at; the design
    torque's source ``torque_name`` where given and ``basic`` gives a design torque: the
    development's own torque, :func:`contact.optimize.development_written_lte.window_name`,
    not the basic file's). The pinion tooth is kept under ``key_prefix + pinion_key``
    (:class:`KeptTeeth`). The designs are
    synthesised and analysed inside one :class:`geometry.machine.meshing.WarmSeeds`: the
    envelope seeds of each design's tools continued from the earlier designs' (issue 75;
    a design's metrics as a cold analysis gives them, to the envelope solver's
    tolerance; the check, :mod:`contact.optimize.development_check`, analyses cold).
    ``confirm``: where given, a design scored "all targets met" (every target, not a
    stage's fewer) stops the search only where ``confirm(design)`` is None; else the design
    it returns (refuted at the default sampling, its objective the check's:
    :func:`contact.optimize.development_confirm.confirmer`) is recorded in its place and
    the search goes on."""
    seen: dict[tuple, DevelopmentEvaluation] = {}
    label = "" if side == "drive" else f"{side} "
    # the trials' envelope seeds continued from the earlier trials' (issue 75): a new tool
    # per trial searched every blade section for the ease-off's seed (≈ 0.2 s each)
    seeds = WarmSeeds()

    def evaluate(values: dict[str, float], stage: str, make: Callable[[], Case],
                 budget: int, pinion_key: tuple) -> DevelopmentEvaluation:
        key = (stage, *(round(v, MEMO_DECIMALS) for v in values.values()))
        if key in seen:  # a design analysed before (the simplex returns to its start)
            if seen[key].met:
                # (a bearing met on every target, reached again by the relief stage: its
                # stop confirmed there, development_confirm)
                refuted = _refuted(seen[key], stage)
                if refuted is None:
                    raise StageStop
                seen[key] = refuted
            return seen[key]
        if len(evals) >= budget:
            raise StageStop
        c0 = cpu_seconds()
        case = None
        try:
            with seeds:
                case = make()
            if not setup:
                torque, source = design_torque_of(basic, case)
                if torque_name and basic.gives_design_torque:  # the development's own
                    source = torque_name
                setup.update(torques=case_torques(targets.light_load, torque),
                             source=source,
                             lowered=False,
                             centre_v=working_depth_centre(case))
                say(f"development: drive flank {basic.options.drive_flank}, light "
                    f"{plain_number(setup['torques'][0])} N m, design {plain_number(torque)} N m "
                    f"({source})"
                    f"{_ratios_text(case)}; varying {', '.join(targets.variables)} (at most "
                    f"{targets.max_evaluations} designs, coarse LTCA)")
            with seeds:
                metrics, grid = analyse_design(case, setup["torques"], teeth=teeth,
                                               pinion_key=(*key_prefix, *pinion_key),
                                               flank=side)
            setup["pressure_limit"] = grid[4]
            obj, short, met = development_score(metrics, targets, grid[:4],
                                                centre_v=setup["centre_v"], stage=stage,
                                                pressure_limit=grid[4])
            reason = ""
        except Exception as exc:  # one failing design never ends the development
            raise_if_interrupted(exc)
            log.info("development %sdesign %s failed: %s", label, values, exc)
            metrics = {k: np.full(2, np.nan) for k in METRIC_NAMES}
            obj, short, met, grid = FAILED, {}, False, None
            reason = f"{type(exc).__name__}: {exc}".splitlines()[0]
        e = DevelopmentEvaluation(len(evals), dict(values), metrics, obj, short, met, reason,
                                  cpu_seconds() - c0, case, stage=stage)
        if grid is not None:  # the full score too: designs of both stages are compared
            full = development_score(metrics, targets, grid[:4], centre_v=setup["centre_v"],
                                     pressure_limit=grid[4])
            e = dataclasses.replace(e, full=full)
        evals.append(e)
        say(evaluation_line(e, n_max, label + stage))
        if met:
            # a coarse "all met" confirmed at the default sampling before it stops the
            # search; refuted, the design scores the check's objective and the search
            # goes on (development_confirm)
            refuted = _refuted(e, stage)
            if refuted is not None:
                e = evals[-1] = refuted
        seen[key] = e
        if stage in ("bearing", "height") and grid is not None:  # the relief starts here
            seen[("relief", *key[1:])] = dataclasses.replace(e, objective=e.full[0],
                                                             shortfalls=e.full[1],
                                                             met=e.full[2])
        if e.met:
            raise StageStop
        return e

    def _refuted(e: DevelopmentEvaluation, stage: str) -> DevelopmentEvaluation | None:
        """``confirm``'s verdict on a design met at ``stage`` where that stage scores the
        edges and the plastic share (not the bearing stage's fewer targets) and the
        design meets every target; None (the stop stands) otherwise."""
        terms = STAGE_TERMS.get(stage, ())
        if (confirm is None or e.full is None or not e.full[2]
                or "plastic" not in terms or "edge" not in terms):
            return None
        return confirm(e)

    evaluate.evals = evals  # type: ignore[attr-defined]  (read by _centre_height)
    evaluate.setup = setup  # type: ignore[attr-defined]
    evaluate.slopes = {}  # type: ignore[attr-defined]  (per bearing, _note_slope)
    return evaluate


def bearing_key(values: Mapping[str, float]) -> tuple:
    """The prescriptions of a design that shape its pinion tooth (all but the relief):
    :class:`KeptTeeth`'s key."""
    return tuple(sorted((k, v) for k, v in values.items()
                        if k not in (*RELIEF_NAMES, HEIGHT_NAME, CROWNING_NAME)))


def met_text(e: DevelopmentEvaluation) -> str:
    """What ``e.met`` means, for its progress line: ``" (all targets met)"`` where its
    stage scores every target, ``" (the <stage> stage's targets met; <keys> left to the
    later stages)"`` where it scores fewer (the bearing stage leaves the edges, the
    plastic share, the centre v to the relief, :data:`~contact.optimize.
    development_targets.STAGE_TERMS`), empty where not met.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A scored design (its ``met`` and ``stage``).

    Returns
    -------
    str
        The parenthesis, with its leading space, or empty.

    Notes
    -----
    Source: round 29 (docs/own_gear_set.md): the 13x50's bearing stage said "(all targets
    met)" of a design carrying 1.7 % of its torque plastic (issue 71, branch tol89).
    """
    if not e.met:
        return ""
    terms = STAGE_TERMS.get(e.stage)
    left = [k for k in STAGE_TERMS["relief"] if terms is not None and k not in terms]
    if not left:
        return " (all targets met)"
    return f" (the {e.stage} stage's targets met; {', '.join(left)} left to the later stages)"


def evaluation_line(e: DevelopmentEvaluation, n: int, stage: str = "relief") -> str:
    """The progress line of design ``e`` of at most ``n`` at ``stage``: its values, then
    its metrics and objective (or why it failed), what its targets met are
    (:func:`met_text`) and its CPU seconds."""
    vals = ", ".join(f"{k} {v:.3g}" for k, v in e.values.items())
    if e.reason:
        return f"  {stage} design {e.index + 1}/{n}: {vals}: failed ({e.reason})"
    return (f"  {stage} design {e.index + 1}/{n}: {vals}: {metrics_text(e.metrics)}; "
            f"objective {e.objective:.3g}{met_text(e)} "
            f"[{e.seconds:.0f} s]")

