"""One design of a development and the whole development's result, in words and in the
case (:mod:`contact.optimize.development`).

:class:`DevelopmentEvaluation` is one analysed design, :class:`DevelopmentResult` what
:func:`contact.optimize.development.develop` did: its headline (each missed target with
its value and limit, both flanks' peak pressure), the paragraph and the informational
``[development]`` table written into the case, and the coast design torque capped at the
coast flank's static capacity. Imported through :mod:`contact.optimize.development`.

:attr:`DevelopmentEvaluation.checked_full` is the one test the development's steps make
of the checked best design before they read its metrics or full score.

Public names
------------
DevelopmentEvaluation, DevelopmentResult, COAST_STATUS, STATIC_MARGIN, floor_torque,
metrics_text
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from contact.ltca.edges import EDGE_KINDS
from contact.ltca.plausibility import LTE_SPREAD_LIMIT
from contact.optimize.development_targets import DevelopmentTargets, development_score
from contact.pipeline import case_torques, floor_torque  # the coast's light torque's rule
from geometry.case import Case
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import FLANK_OPTION_UNITS, BasicDesign

__all__ = ["COAST_STATUS", "STATIC_MARGIN", "TOLERANCE_KEYS", "UNWRITTEN_METRICS",
           "DevelopmentEvaluation", "DevelopmentResult", "case_torques", "floor_torque",
           "metrics_text", "scored"]

#: the development's metrics its ``[development]`` tables leave out: each edge kind's peak
#: pressure per torque whatever its share (``edge_pressure_<kind>`` [MPa],
#: :func:`~contact.optimize.development_evaluate.light_edge_metrics`), the reading by which
#: the coast light-edge step chooses its lever, not a result the case records (the table's
#: ``pressure_max_edge`` is their largest); the case written stays as before where the step
#: keeps nothing
UNWRITTEN_METRICS = tuple(f"edge_pressure_{k}" for k in EDGE_KINDS)

#: relative shortfall [1] within which a design torque written counts as the torque it was
#: cut from (raised back to all of it, not lowered): the rating's torques are written to
#: 4 significant digits (0.1 N·m of 439.2 is 2.3e-4 of it), a cut is a step of several %
TORQUE_KEPT = 1e-3


# --------------------------------------------------------------------------- evaluation
@dataclass(frozen=True, eq=False)
class DevelopmentEvaluation:
    """One analysed design of a development.

    Attributes
    ----------
    index : int
    values : dict name → float
        The developed inputs [file units].
    metrics : dict name → ndarray (2,)
        :data:`METRIC_NAMES` at (light, design) torque; NaN when it failed.
    objective : float
    shortfalls : dict name → float
    met : bool
    reason : str
        Why the design failed (empty if it did not).
    seconds : float
        CPU time of its synthesis and analysis [s].
    case : Case or None
        The synthesised case (None when the synthesis failed).
    full : (objective, shortfalls, met) or None
        The score on every target (stage ``"relief"``), for comparing designs of both
        stages; None when it failed.
    checked : bool
        ``metrics`` and ``full`` are those of the final check at the default sampling
        (:data:`CHECK_LTCA`), not of the coarse search.
    stage : str
        ``"bearing"`` or ``"relief"``.
    """

    index: int
    values: dict[str, float]
    metrics: dict[str, np.ndarray]
    objective: float
    shortfalls: dict[str, float]
    met: bool
    reason: str
    seconds: float
    case: Case | None = None
    full: tuple[float, dict[str, float], bool] | None = None
    checked: bool = False
    stage: str = ""

    @property
    def checked_full(self) -> bool:
        """True when this design was scored on every target at the final check.

        Certifies that ``full`` is not None (the design was scored on every target),
        ``checked`` is set (``metrics`` and ``full`` are those of the final check at
        :data:`CHECK_LTCA`, not of the coarse search) and ``metrics`` is not None: the
        condition the development's steps require of the checked best design before
        they read its metrics or full score.
        """
        return self.full is not None and self.checked and self.metrics is not None


def scored(e: DevelopmentEvaluation, metrics: Mapping[str, np.ndarray],
           grid: tuple[float, float, float, float, float], targets: DevelopmentTargets,
           centre_v: float | None, **changes: Any) -> DevelopmentEvaluation:
    """``e`` with ``metrics`` and the full score they get (every target):
    :func:`~contact.optimize.development_targets.development_score` on ``grid``'s gear-grid
    rows with its static strength as the pressure limit, and ``changes`` (other fields:
    ``values``, ``case``, ``checked``, ``stage``, ...).

    Parameters
    ----------
    e : DevelopmentEvaluation
    metrics : mapping name → ndarray (2,)
        :data:`~contact.optimize.development_targets.METRIC_NAMES` at the (light, design)
        torque [N·m].
    grid : (u_toe, u_heel, v_root, v_tip, static strength)
        The gear grid's outermost rows [1] and the static strength [MPa], as
        :func:`~contact.optimize.development_evaluate.analyse_design` returns them.
    targets : DevelopmentTargets
    centre_v : float or None — [1]
        The depth centre aimed at (the development's ``setup["centre_v"]``).
    **changes
        Further fields of the result.

    Returns
    -------
    DevelopmentEvaluation
        Its ``metrics``, ``objective``, ``shortfalls``, ``met`` and ``full``
        (``development_score``'s triple) those of ``metrics``.

    Raises
    ------
    Nothing but what ``development_score`` raises.

    Notes
    -----
    Source: the issue-71 development's targets (docs/synthesis.md, "Development bearing").
    """
    full = development_score(metrics, targets, grid[:4], centre_v=centre_v,
                             pressure_limit=grid[4])
    return dataclasses.replace(e, metrics=metrics, objective=full[0], shortfalls=full[1],
                               met=full[2], full=full, **changes)


@dataclass(frozen=True, eq=False)
class DevelopmentResult:
    """What :func:`develop` did.

    Attributes
    ----------
    basic : BasicDesign
        The design with the developed prescriptions of the drive flank (and of the coast
        flank where :attr:`coast_status` is ``"developed"``).
    case : Case
        Its synthesis (the developed case).
    report : geometry.synthesis.case_synthesis.SynthesisReport
        The synthesis report of ``case``.
    best : DevelopmentEvaluation
        The chosen design (every target met, else the least objective).
    evaluations : tuple of DevelopmentEvaluation
        Every design analysed, in order.
    torque : (float, float) — [N·m]
        Light and design pinion torque.
    torque_source : str
        Where the design torque came from (:func:`design_torque_of`).
    tolerance : dict label → (metrics, shortfalls)
        The developed design at each excursion (``dE+0.05`` …) at (light, design) torque,
        with the shortfalls of the clearance, edge and plastic targets there.
    targets : DevelopmentTargets
    seconds : float
        CPU time of the whole development [s].
    centre_v : float — [1]
        The depth centre aimed at (``targets.pattern_centre_v`` or the working depth's
        middle, :func:`working_depth_centre`).
    coast : dict name → ndarray (2,) or None
        :data:`METRIC_NAMES` of the written case's coast flank at (light, design) torque
        at :data:`CHECK_LTCA`; None where that analysis failed.
    check_seconds : float
        CPU time [s] of the drive flank's final check, the final synthesis and the
        tolerance check (the rest of ``seconds`` is the designs' and the coast flank's,
        :attr:`stage_seconds`).
    torque_lowered : bool
        The design torque is the bearing's static flank capacity, below the rating's
        (:func:`~contact.optimize.development_check.static_capacity`); :meth:`recorded`
        writes it as the case's ``[rating] design_torque``.
    coast_best : DevelopmentEvaluation or None
        The coast flank written: a design of its search (checked at :data:`CHECK_LTCA`)
        or, stage ``"synthesised"``, the flank as synthesised from its own prescriptions;
        None where its analysis failed.
    coast_evaluations : tuple of DevelopmentEvaluation
        Every design of the coast flank's search, in order (empty where none ran).
    coast_status : str
        A key of :data:`COAST_STATUS`: ``"developed"``, ``"met"`` (every target met as
        synthesised: no search), ``"off"`` (``coast_max_evaluations`` = 0), ``"not
        improved"`` (the search found nothing better) or ``"not checked"``; empty where
        not known (a result made by hand).
    coast_before : dict name → ndarray (2,) or None
        The coast flank's metrics as synthesised where its search ran (else None).
    coast_seconds : float
        CPU time [s] of the coast flank's check and development.
    pressure_limit : float — [MPa]
        The flank peak pressure allowed at the design torque (``max_flank_pressure`` or
        the static strength, :func:`static_strength`); inf where not known.
    root_safety : float — [1]
        S_F,FE of the weaker member at the design torque written, from the FE root stress
        of the written case (:func:`contact.optimize.development_root.root_capacity`);
        NaN where not computed (no rating, the FE model failed); at a design torque the
        basic file gives, its S_F,FE there
        (:func:`contact.optimize.development_root.given_torque_root`).
    root_text : str
        Why the design torque was lowered to the root-stress capacity (empty where not).
    coast_torques : tuple of float — [N·m]
        The (light, design) torque of :attr:`coast`: the coast side's own design torque
        (the smaller of the design torque and the coast side's rated one, lowered to
        :attr:`coast_capacity` where that is set); empty where not known (then
        :attr:`torque`).
    coast_capacity : float — [N·m]
        The coast flank's capacity at its developed bearing where it is below the coast
        side's rated torque (:func:`contact.optimize.development_coast.coast_capacity`:
        flank peak within the static strength, no plastic segment, S_F,FE >= S_Fmin, each
        step analysed as ``ltca run --flank coast``); NaN where nothing was lowered.
    coast_capacity_text : str
        Why, in numbers (empty where not lowered).
    gear_process_text : str
        Which gear process was kept and why, where ``gear_process = "auto"`` developed the
        generated gear too
        (:func:`~contact.optimize.development_process.with_generated_gear`); empty where
        not.
    lte_reach : dict or None
        The drive design of least LTE p-p the check's last LTE step saw at :attr:`torque`
        (:func:`contact.optimize.development_check.checked_crowning_lte`): ``"light"``,
        ``"design"`` [µrad], ``"what"`` it is (its change, or "the design written"),
        ``"why"`` not kept (empty where kept); None where the step did not run.
    tolerant_torque : (float, float) — [N·m]
        Where the design is not tolerant at its design torque on the edges: the largest
        torque found at which every mounting excursion's edges hold and the least at which
        one does not (:func:`contact.optimize.development_check.tolerant_torque`); NaN
        where not found (tolerant, a clearance missed, or the edges failing at the light
        torque: then the second is the light torque).
    lte_range : dict or None
        The drive design's LTE p-p judged between :attr:`torque` as ``ltca run``'s
        ``lte_range`` step judges it, by the check's last step
        (:func:`contact.optimize.development_range_lte.range_record`: ``"torques"`` [N·m],
        ``"lte"`` [µrad], ``"peak"`` [µrad], ``"at"`` [N·m]); None where the check's steps
        did not judge it at these torques.
    coast_lte_range : dict or None
        The written coast design's LTE p-p judged between :attr:`coast_torques` as ``ltca
        run --flank coast``'s ``lte_range`` step judges it
        (:func:`contact.optimize.development_range_lte.range_lte` on the coast flank, the
        keys of :attr:`lte_range`); None where the coast flank was not checked at two
        torques or its analysis failed.
    remedy : contact.optimize.development_remedy.AppliedRemedy or None
        The contact-ratio remedy applied to the user's basic data before this development
        (``develop(..., apply_remedy=True)``, ``ltca synthesize --apply-remedy``; its
        ``basic`` the remedied basic data as given); None where none was.
    fe_level_text : str
        Where the root stress limited a torque on a coarser FE level than the default,
        why the torque was decided on the default model and the case written names it
        (:func:`contact.optimize.development_root.refined_for_root`); empty where the
        case keeps the level it was developed with.
    lte_torque : float — [N·m]
        The design torque the drive LTE window set: the torque up to which the written
        drive bearing keeps the verdict's LTE limit at every torque
        (:func:`~contact.optimize.development_written_lte.written_lte_capacity`), or the
        upper end of that window the drive was developed again at
        (:func:`~contact.optimize.development_written_lte.redeveloped_in_window`); NaN
        where the window lowered nothing. A cut to it is the contact ratio's, not the gear
        process's (:func:`~contact.optimize.development_process.failed_outcome`).
    given_root_text : str
        Where the design torque the basic file gives is above the developed bearing's
        root-stress capacity (S_F,FE < S_Fmin there, which ``ltca run`` rates FAIL): the
        numbers and the torque that would hold
        (:func:`contact.optimize.development_root.given_torque_root`); empty where not.
    hollow_further : Further or None
        The hollow profile one step further after a design-torque cut
        (:func:`contact.optimize.development_hollow_further.checked_hollow_further`): its
        readings and the written case's load-sharing floor, which ``ltca synthesize``'s
        drive LTE line reuses; None where the development did not reach it.
    root_ceiling : float — [N·m]
        The torque a root-stress cut was made from, where the bearing developed at the cut
        torque was raised back towards it (:func:`contact.optimize.development._regained`);
        NaN where not. A design torque written at all of it was not lowered by that cut
        (:attr:`root_cut_regained`; :meth:`headline` says so).
    memo : dict or None
        The synthesis memo of the development that wrote the case
        (:func:`geometry.synthesis.case_synthesis.synthesize`'s ``memo``): a later
        synthesis of the written prescriptions reads its steps 3–6 back
        (:func:`contact.optimize.remedy_check.unrelieved_te_pp`); None where not kept.
        Not in the result's text.
    """

    basic: BasicDesign
    case: Case
    report: Any
    best: DevelopmentEvaluation
    evaluations: tuple[DevelopmentEvaluation, ...]
    torque: tuple[float, float]
    torque_source: str
    tolerance: dict[str, tuple[dict[str, np.ndarray], dict[str, float]]]
    targets: DevelopmentTargets
    seconds: float
    centre_v: float = 0.5
    coast: dict[str, np.ndarray] | None = None
    check_seconds: float = 0.0
    torque_lowered: bool = False
    coast_best: DevelopmentEvaluation | None = None
    coast_evaluations: tuple[DevelopmentEvaluation, ...] = ()
    coast_status: str = ""
    coast_before: dict[str, np.ndarray] | None = None
    coast_seconds: float = 0.0
    pressure_limit: float = math.inf
    root_safety: float = math.nan
    root_text: str = ""
    coast_torques: tuple[float, ...] = ()
    coast_capacity: float = math.nan
    coast_capacity_text: str = ""
    gear_process_text: str = ""
    lte_reach: dict | None = None
    tolerant_torque: tuple[float, float] = (math.nan, math.nan)
    lte_range: dict | None = None
    remedy: Any = None
    coast_lte_range: dict | None = None
    fe_level_text: str = ""
    given_root_text: str = ""
    lte_torque: float = math.nan
    hollow_further: Any = None
    root_ceiling: float = math.nan
    memo: dict | None = dataclasses.field(default=None, repr=False)

    @property
    def root_cut_regained(self) -> bool:
        """A root-stress cut raised back to all of the torque it was made from, the design
        torque written that torque (:attr:`root_ceiling`): the cut lowered nothing."""
        return (math.isfinite(self.root_ceiling)
                and float(self.torque[1]) >= self.root_ceiling * (1.0 - TORQUE_KEPT))

    @property
    def tolerant(self) -> bool:
        """At every excursion the pattern stays clear of toe and heel at light load and the
        edges elastic with at most the edge share allowed."""
        return all(all(s[k] == 0.0 for k in TOLERANCE_KEYS)
                   for _, s in self.tolerance.values())

    @property
    def stage_seconds(self) -> dict[str, float]:
        """CPU time [s] of the drive flank's bearing stage, its relief stage (their
        designs' syntheses and coarse LTCAs), the final checks and the coast flank (its
        check and development)."""
        out = {st: sum(e.seconds for e in self.evaluations if e.stage == st)
               for st in ("bearing", "height", "relief", "te")}
        return out | {"check": self.check_seconds, "coast": self.coast_seconds}

    def summary(self) -> str:
        """One paragraph for the case's ``source``: prescriptions, targets, achieved."""
        b, t = self.best, self.targets
        m = b.metrics
        vals = _values_text(b.values)
        tl, td = self.torque
        tol = "; ".join(
            f"{lab}: pattern {ms['pattern_toe_u'][0]:.2f}-{ms['pattern_heel_u'][0]:.2f}, edge "
            f"{100 * ms['edge_load_share'][1]:.1f} %, plastic "
            f"{100 * np.max(ms['plastic_share']):.1f} %"
            for lab, (ms, _) in self.tolerance.items())
        return (
            f"Development bearing (contact.optimize.development, {len(self.evaluations)} "
            f"designs, coarse LTCA, the chosen one "
            f"{'checked at the default sampling' if b.checked else 'not checked'}): drive "
            f"flank {vals}; targets at {plain_number(tl)} N m (light, "
            f"{t.light_load:g} x design) pattern {t.pattern_length:g} +/- "
            f"{t.pattern_length_tolerance:g} of the face width centred at "
            f"({t.pattern_centre_u:g}, {self.centre_v:.3g}), clear of the flank ends by "
            f"{t.clearance:g}; at {plain_number(td)} N m (design, {self.torque_source}) edge "
            f"share <= "
            f"{100 * t.max_edge_share:g} %, plastic <= {100 * t.max_plastic_share:g} %; LTE "
            f"p-p <= {t.max_lte:g} urad. Achieved: pattern u {m['pattern_toe_u'][0]:.2f}-"
            f"{m['pattern_heel_u'][0]:.2f}, v {m['pattern_root_v'][0]:.2f}-"
            f"{m['pattern_tip_v'][0]:.2f}, centre ({m['pattern_centre_u'][0]:.2f}, "
            f"{m['pattern_centre_v'][0]:.2f}); edge share {100 * m['edge_load_share'][0]:.1f}/"
            f"{100 * m['edge_load_share'][1]:.1f} %, plastic "
            f"{100 * m['plastic_share'][0]:.1f}/{100 * m['plastic_share'][1]:.1f} %, LTE p-p "
            f"{m['lte_peak_to_peak'][0]:.1f}/{m['lte_peak_to_peak'][1]:.1f} urad, flank "
            f"peak pressure {m['pressure_max_flank'][0]:.0f}/"
            f"{m['pressure_max_flank'][1]:.0f} MPa (light/design); {self._met_text()}. "
            f"Tolerance (dE = +/-{t.offset_tolerance:g} mm, dP = +/-"
            f"{t.mounting_tolerance:g} mm): {tol}"
            f" ({'tolerant' if self.tolerant else 'not tolerant'}"
            f"{self._tolerant_torque_text()}). "
            + self._coast_text().rstrip()
            + (f" {self.gear_process_text}" if self.gear_process_text else ""))

    def headline(self) -> str:
        """One line: the chosen design, whether it met its targets and is tolerant, and
        what became of the coast flank."""
        b, t = self.best, self.targets
        m = b.metrics
        return (f"development: design {b.index + 1} of {len(self.evaluations)}, "
                f"{self.missed_text(b)}; light-load pattern {m['pattern_toe_u'][0]:.2f}-"
                f"{m['pattern_heel_u'][0]:.2f} of the face, edge share "
                f"{100 * m['edge_load_share'][1]:.1f} % and LTE p-p "
                f"{m['lte_peak_to_peak'][1]:.0f} urad at {plain_number(self.torque[1])} N m; "
                f"{'tolerant' if self.tolerant else 'not tolerant'} at dE +/-"
                f"{t.offset_tolerance:g} mm, dP +/-{t.mounting_tolerance:g} mm"
                f"{self._intolerance_text()}; "
                f"{self._coast_headline()}; {self._pressures_text()}"
                f"{self._root_headline()}; {self.seconds:.0f} s CPU")

    def _intolerance_text(self) -> str:
        """Where the chosen design is not tolerant: each mounting excursion that misses a
        :data:`TOLERANCE_KEYS` target, with the value and its limit (:func:`_missed`), in
        parentheses; "" where it is tolerant. The headline said only "not tolerant at dE
        +/-0.05 mm, dP +/-0.05 mm", the numbers left to the case's ``source`` (issue 71's
        unseen designs, round 9: the spiral bevel 14x38 at Sigma 65 deg and the 21x29)."""
        parts = []
        for lab, (ms, short) in self.tolerance.items():
            missed = [k for k in TOLERANCE_KEYS if short.get(k, 0.0) > 0.0]
            if not missed:
                continue
            if not np.any(np.isfinite(np.asarray(ms["edge_load_share"], float))):
                parts.append(f"{lab}: not analysed")  # the excursion's analysis failed
                continue
            parts.append(f"{lab}: " + ", ".join(
                _missed(k, ms, self.targets, self.centre_v, self.pressure_limit)
                for k in missed))
        return (f" ({'; '.join(parts)})" if parts else "") + self._tolerant_torque_text()

    def _tolerant_torque_text(self) -> str:
        """Where the design is not tolerant on its edges at the design torque, the torque
        up to which it is (:attr:`tolerant_torque`), the design torque said kept; "" where
        not found."""
        holds, fails = self.tolerant_torque
        t = self.targets
        at = f"at dE/dP +/-{t.offset_tolerance:g}/{t.mounting_tolerance:g} mm"
        if math.isfinite(holds):
            return (f"; tolerant up to {plain_number(holds)} N m {at} (not at "
                    f"{plain_number(fails)} N m; the "
                    f"design torque {plain_number(self.torque[1])} N m kept)")
        if math.isfinite(fails):
            return f"; not tolerant {at} at the light torque {plain_number(fails)} N m either"
        return ""

    def _root_headline(self) -> str:
        if not math.isfinite(self.root_safety):
            return ""
        why = (f" (design torque lowered to {self.root_text.split(':')[0]})"
               if self.root_text and not self.root_cut_regained else
               f" (its cut to {self.root_text.split(':')[0]} raised back to all of "
               f"{plain_number(self.root_ceiling)} N m, on the bearing developed at the cut "
               "torque)" if self.root_text else " (below S_Fmin: the given torque is above its "
               "root-stress capacity, see the note)" if self.given_root_text else "")
        return (f"; FE root stress S_F,FE {self.root_safety:.2f} at "
                f"{plain_number(self.torque[1])} N m{why}")

    @property
    def coast_static_capacity(self) -> float:
        """The coast flank's capacity [N·m] at its developed bearing where it is below the
        coast side's rated torque, else NaN (:attr:`coast_capacity`: each step analysed at
        ``ltca run --flank coast``'s sampling, not extrapolated)."""
        return self.coast_capacity

    @property
    def coast_design_torques(self) -> tuple[float, float]:
        """The coast flank's (light, design) torque [N·m] of :attr:`coast`."""
        t = self.coast_torques or self.torque
        return float(min(t)), float(max(t))

    def written_case(self, design_torque: float | None = None, *,
                     noted: bool = False) -> Case:
        """The case ``ltca synthesize`` writes of this development: :attr:`case` with its
        rating's design torques, the ``[development]`` table and the operating torques
        (:func:`contact.optimize.development_written.written_case`, which says how) and,
        with ``noted``, the contact-ratio remedies' record
        (:func:`contact.optimize.written_notes.noted_case`).

        Parameters
        ----------
        design_torque : float — [N·m], optional
            The basic file's ``[synthesis] design_torque``; default that of :attr:`basic`.
        noted : bool
            Also check the contact-ratio remedies where a contact ratio is below its
            limit and record them in the case's
            :data:`~contact.optimize.remedy_check.RECORD_TABLE` table, which ``ltca run``'s
            next step reads, and each flank's scuffing safety at its design torque in
            ``[development.scuffing]``
            (:func:`contact.optimize.written_scuffing.checked_scuffing`): the case ``ltca
            synthesize`` writes (one synthesis for each remedy checked, two LTCAs at one
            torque each). Default False: the case without it, as before
            (issue 71, branch api88). The command's lines and notes:
            :func:`contact.optimize.synthesized_case.synthesize_case`.

        Returns
        -------
        geometry.case.Case
            What ``case.to_toml()`` writes and ``ltca run`` of that file reads.
        """
        from contact.optimize.development_written import written_case

        written = written_case(self, design_torque)
        case = written.case
        if not noted:
            return case
        from contact.optimize.written_notes import noted_case
        from contact.optimize.written_scuffing import checked_scuffing

        return checked_scuffing(noted_case(self.basic, case, self)[0], written.torque).case

    def with_coast_capacity(self, case: Case) -> tuple[Case, float]:
        """``case`` with ``[rating] coast_design_torque`` lowered to
        :attr:`coast_capacity` where that is below the coast side's design torque (its
        ``coast_design_torque``, else the design torque), with :attr:`coast_capacity_text`
        in the rating's ``source``; the torque written (NaN where unchanged). Each flank's
        design torque is then no higher than what its own developed bearing carries."""
        import json
        from types import MappingProxyType

        cap = self.coast_capacity
        rating = dict(case.extra.get("rating") or {})
        now = rating.get("coast_design_torque", rating.get("design_torque"))
        if not math.isfinite(cap) or now is None or cap >= float(now):
            return case, math.nan
        rating["coast_design_torque"] = cap
        rating["source"] = (str(rating.get("source", "")).rstrip()
                            + f" coast_design_torque {cap:g} N m: "
                            f"{self.coast_capacity_text} (contact.optimize.development).")
        extra = json.loads(json.dumps({**case.extra, "rating": rating}))
        return dataclasses.replace(case, extra=MappingProxyType(extra)), cap

    def missed_text(self, e: DevelopmentEvaluation | None = None) -> str:
        """Whether ``e`` (default the chosen drive design) met every target, else each
        missed target with its value and its limit, in numbers."""
        e = self.best if e is None else e
        if e.full is None:
            return "not analysed"
        if e.full[2]:
            return "every target met" + self._between_text(e)
        return "not every target met: " + "; ".join(
            _missed(k, e.metrics, self.targets, self.centre_v, self.pressure_limit)
            for k, v in e.full[1].items() if v > 0)

    def _between_text(self, e: DevelopmentEvaluation) -> str:
        """Where ``e``, the written drive or coast design, meets every target at its two
        torques and its record of the LTE over ``ltca run``'s ``lte_range`` torques
        (:attr:`lte_range`, :attr:`coast_lte_range`) is above the verdict's limit between
        them: that peak, its torque and the limit (issue 71: "at every torque"); else "".
        """
        from contact.study.verdicts import LTE_LIMIT  # imports contact.ltca

        record = (self.lte_range if e is self.best else
                  self.coast_lte_range if e is self.coast_best else None)
        if not record or record.get("values") != dict(e.values):
            return ""
        peak = float(record.get("peak", math.nan))
        if not peak > LTE_LIMIT:
            return ""
        return (f" at its two torques, but LTE p-p {peak:.1f} urad at "
                f"{plain_number(float(record['at']))} N m between them (limit {LTE_LIMIT:g})")

    def _pressures_text(self) -> str:
        """Both flanks' flank peak pressure at the design torque against the limit."""
        drive = float(self.best.metrics["pressure_max_flank"][1])
        coast = (float(self.coast["pressure_max_flank"][1]) if self.coast
                 else math.nan)
        lim = (f" (limit {self.pressure_limit:.0f} MPa)"
               if math.isfinite(self.pressure_limit) else "")
        tc = self.coast_design_torques[1]
        at = "" if tc == self.torque[1] else f" at its design torque {plain_number(tc)} N m"
        # a coast flank whose analysis failed has no peak: said so, not "coast nan MPa"
        # (the unseen industrial 11x43 of m_mn 12, issue 71 round 13)
        said = (f"coast {coast:.0f} MPa{at}" if math.isfinite(coast)
                else f"coast not analysed{at}")
        return (f"flank peak pressure at {plain_number(self.torque[1])} N m drive {drive:.0f} MPa, "
                f"{said}{lim}")

    def recorded(self, case: Case) -> Case:
        """``case`` (the developed case, maybe with its rating's design torque set) with
        :meth:`summary` appended to its ``source``, :meth:`table` as its informational
        ``[development]`` table and, where the basic file's ``[operating]`` gives no
        torques, the light and the design torque as its operating torques [N·m]; where a
        contact-ratio remedy was applied (:attr:`remedy`), its informational
        :data:`~contact.optimize.development_remedy.REMEDY_TABLE` table."""
        import json
        from types import MappingProxyType

        tables: dict[str, Any] = {"development": self.table()}
        if self.remedy is not None:
            from contact.optimize.development_remedy import REMEDY_TABLE, applied_table

            tables[REMEDY_TABLE] = applied_table(self.remedy)
        extra = json.loads(json.dumps({**case.extra, **tables}))
        if self.torque_lowered:  # the rating's design torque is the bearing's capacity
            rating = dict(extra.get("rating") or {})
            rated = float(rating.get("design_torque", math.nan))
            # raised back to all of the rating's torque after a cut: kept, not lowered
            how = ("kept at" if math.isfinite(rated) and float(self.torque[1])
                   >= rated * (1.0 - TORQUE_KEPT) else "lowered to")
            rating["design_torque"] = float(self.torque[1])
            rating["source"] = (str(rating.get("source", "")).rstrip()
                                + f" design_torque {how} {self.torque[1]:g} N m by the "
                                f"development: {self.torque_source}.").lstrip()
            extra["rating"] = rating
        more: dict[str, Any] = {}
        if "torque" not in self.basic.operating:
            # the loads the bearing was developed for are the case's operating torques
            # (the seed's 50/250/500 N·m otherwise, unrelated to this design's size)
            # (to 0.1 N·m, rounded down: the design torque is the rating's long-life
            # capacity by default, at which S_H = S_H,min exactly; rounded up it would fail
            # the rating by round-off)
            more["operating"] = dataclasses.replace(
                case.operating, torque=tuple(floor_torque(t) for t in self.torque))
        return dataclasses.replace(case, source=case.source.rstrip() + " " + self.summary(),
                                   extra=MappingProxyType(extra), **more)

    def _coast_text(self) -> str:
        c = self.coast
        if not c:
            return "Coast flank: not checked (its analysis failed). "
        achieved = (f"pattern u {c['pattern_toe_u'][0]:.2f}-{c['pattern_heel_u'][0]:.2f}, v "
                    f"{c['pattern_root_v'][0]:.2f}-{c['pattern_tip_v'][0]:.2f}, centre "
                    f"({c['pattern_centre_u'][0]:.2f}, {c['pattern_centre_v'][0]:.2f}); edge share "
                    f"{100 * c['edge_load_share'][0]:.1f}/{100 * c['edge_load_share'][1]:.1f}"
                    f" %, plastic {100 * c['plastic_share'][0]:.1f}/"
                    f"{100 * c['plastic_share'][1]:.1f} %, flank peak pressure "
                    f"{c['pressure_max_flank'][0]:.0f}/{c['pressure_max_flank'][1]:.0f} MPa, "
                    f"LTE p-p {c['lte_peak_to_peak'][0]:.1f}/{c['lte_peak_to_peak'][1]:.1f} "
                    f"urad at {plain_number(self.coast_design_torques[0])}/"
                    f"{plain_number(self.coast_design_torques[1])} N m (light/design)")
        if self.coast_capacity_text:
            achieved += f"; coast design torque {self.coast_capacity_text}"
        b = self.coast_best
        met = "" if b is None or b.full is None else f"; {_met_text(b.full)}"
        if self.coast_status == "developed":
            before = self.coast_before
            was = ("" if not before else
                   f"; as synthesised plastic {100 * np.max(before['plastic_share']):.1f} %, "
                   f"edge share {100 * before['edge_load_share'][1]:.1f} %, LTE p-p "
                   f"{before['lte_peak_to_peak'][0]:.1f}/"
                   f"{before['lte_peak_to_peak'][1]:.1f} urad")
            n = len(self.coast_evaluations)
            return (f"Coast flank (developed, {n} design{'s' if n != 1 else ''} at its "
                    f"own torques on the same targets, the chosen one checked at the default "
                    f"sampling): {_values_text(b.values)}{was}. Achieved: {achieved}{met}. ")
        why = COAST_STATUS.get(self.coast_status, "not developed")
        if self.coast_status == "not improved":
            why += f" ({len(self.coast_evaluations)} designs)"
        return f"Coast flank ({why}): {achieved}{met}. "

    def _coast_headline(self) -> str:
        low = (f", coast design torque {plain_number(self.coast_capacity)} N m (its capacity)"
               if math.isfinite(self.coast_capacity) else "")
        return self._coast_state() + low

    def _coast_state(self) -> str:
        b = self.coast_best
        if self.coast_status == "developed":
            return (f"coast flank developed ({len(self.coast_evaluations)} designs): plastic "
                    f"{100 * np.max(b.metrics['plastic_share']):.1f} %, "
                    f"{self.missed_text(b)}")
        if b is None or b.full is None:
            return "coast flank not checked"
        what = {"met": "met every target as synthesised", "off": "coast development off",
                "not improved": "its search found nothing better"}.get(self.coast_status,
                                                                      "not developed")
        return (f"coast flank not developed ({what}): plastic "
                f"{100 * np.max(b.metrics['plastic_share']):.1f} %, {self.missed_text(b)}")

    def _met_text(self) -> str:
        return _met_text(self.best.full)

    def table(self) -> dict[str, Any]:
        """The case's informational ``[development]`` table (TOML-safe values)."""
        b = self.best
        m = _rounded(b.metrics)
        return {
            "note": "informational (contact.optimize.development): the developed drive-flank "
                    "prescriptions and what the LTCA gave at [light, design] torque "
                    + ("(the final check at ltca run's default sampling)" if b.checked
                       else "(the coarse LTCA of the search)")
                    + "; coast: the coast flank at its own torques on the same targets (its "
                    "development, the prescriptions written, achieved at the default "
                    "sampling); coast_achieved: the same metrics as achieved",
            "torque_Nm": [float(x) for x in self.torque],
            "design_torque_source": self.torque_source,
            "root_safety_fe": (round(float(self.root_safety), 4)
                               if math.isfinite(self.root_safety) else "not computed"),
            "prescriptions": {k: float(v) for k, v in b.values.items()},
            "targets_met": int(b.full[2]),
            "tolerant": int(self.tolerant),
            **({"tolerant_up_to_Nm": float(self.tolerant_torque[0])}
               if math.isfinite(self.tolerant_torque[0]) else {}),
            "evaluations": len(self.evaluations),
            "cpu_seconds": round(self.seconds, 1),
            "cpu_seconds_stages": {k: round(v, 1) for k, v in self.stage_seconds.items()},
            "achieved": m,
            "coast": self._coast_table(),
        } | ({"coast_achieved": _rounded(self.coast)} if self.coast else {})

    def _coast_table(self) -> dict[str, Any]:
        c = self.coast_best
        out: dict[str, Any] = {
            "development": COAST_STATUS.get(self.coast_status, "not developed"),
            "evaluations": len(self.coast_evaluations),
            "cpu_seconds": round(self.coast_seconds, 1),
            "torque_Nm": list(self.coast_design_torques)}
        if self.coast_capacity_text:
            out["design_torque_source"] = self.coast_capacity_text
        if c is not None:
            out["prescriptions"] = {k: float(v) for k, v in c.values.items()}
            if c.full is not None:
                out["targets_met"] = int(c.full[2])
                out["missed"] = [k for k, v in c.full[1].items() if v > 0]
        if self.coast_before:
            out["as_synthesised"] = _rounded(self.coast_before)
        return out


#: what the ``[development]`` table writes for a metric the analysis did not compute (NaN,
#: which TOML cannot hold), as its ``root_safety_fe``
NOT_COMPUTED = "not computed"


def _rounded(metrics: Mapping[str, np.ndarray]) -> dict[str, list[float | str]]:
    """The metrics at (light, design) torque rounded to 6 decimals for the case's
    informational ``[development]`` table; a NaN (an analysis that gave none: the FM 14x19
    at Sigma 60's coast flank as synthesised, LTE p-p "2280/nan" at its design torque) as
    :data:`NOT_COMPUTED`, so that the table stays TOML-safe: ``ltca synthesize`` stopped on
    "to_toml: non-finite value nan" there, reported as its unloaded contact's failure
    (branch unseen98)."""
    return {k: [round(float(x), 6) if not math.isnan(float(x)) else NOT_COMPUTED for x in v]
            for k, v in metrics.items() if k not in UNWRITTEN_METRICS}


def _met_text(full: tuple[float, dict[str, float], bool]) -> str:
    _, short, met = full
    return ("every target met" if met else "not every target met: "
            + ", ".join(k for k, v in short.items() if v > 0))


def _missed(name: str, m: Mapping[str, np.ndarray], t: DevelopmentTargets,
            centre_v: float, pressure_limit: float) -> str:
    """One missed target of :func:`development_score` with its value and its limit (with
    the decimals that show it beyond the limit: :func:`contact.study.verdicts.
    shown_above`, :func:`~contact.study.verdicts.shown_below`)."""
    from contact.study.verdicts import shown_above, shown_below

    def band(value: float, target: float, tol: float) -> str:
        if value > target + tol:
            return shown_above(value, target + tol, 2)
        return shown_below(value, target - tol, 2)

    if name == "length":
        length = m["pattern_heel_u"][0] - m["pattern_toe_u"][0]
        return (f"pattern length "
                f"{band(length, t.pattern_length, t.pattern_length_tolerance)} (target "
                f"{t.pattern_length:g} +/- "
                f"{t.pattern_length_tolerance:g})")
    if name == "centre_u":
        cu = float(m["pattern_centre_u"][0])
        return (f"centre u {band(cu, t.pattern_centre_u, t.centre_tolerance)} (target "
                f"{t.pattern_centre_u:g} "
                f"+/- {t.centre_tolerance:g})")
    if name == "centre_v":
        cv = float(m["pattern_centre_v"][0])
        return (f"centre v {band(cv, centre_v, t.centre_tolerance)} (target "
                f"{centre_v:.3g} +/- "
                f"{t.centre_tolerance:g})")
    ends = {"toe": ("pattern_toe_u", "toe u"), "heel": ("pattern_heel_u", "heel u"),
            "root": ("pattern_root_v", "root v"), "tip": ("pattern_tip_v", "tip v")}
    if name in ends:
        key, what = ends[name]
        return (f"{name} clearance: pattern {what} {m[key][0]:.2f} (clear of the grid's "
                f"end by {t.clearance:g})")
    if name == "edge":
        edge = 100 * float(m["edge_load_share"][1])
        return (f"edge share {shown_above(edge, 100 * t.max_edge_share, 1)} % (limit "
                f"{100 * t.max_edge_share:g} %)")
    if name == "plastic":
        plastic = 100 * float(np.max(m["plastic_share"]))
        return (f"plastic share {shown_above(plastic, 100 * t.max_plastic_share, 1)} % ("
                "limit "
                f"{100 * t.max_plastic_share:g} %)")
    if name == "lte":
        lte = float(np.max(m["lte_peak_to_peak"]))
        return (f"LTE p-p {shown_above(lte, t.max_lte, 0)} urad (limit "
                f"{t.max_lte:g})")
    if name == "pressure":
        lim = t.max_flank_pressure if t.max_flank_pressure is not None else pressure_limit
        p = float(m["pressure_max_flank"][1])
        return (f"flank peak pressure {shown_above(p, lim, 0)} MPa (limit {lim:.0f})")
    if name == "spread":
        spread = float(np.max(m["lte_spread"]))
        return (f"LTE spread {shown_above(spread, LTE_SPREAD_LIMIT, 2)} (limit "
                f"{LTE_SPREAD_LIMIT:g})")
    return name


def _values_text(values: Mapping[str, float]) -> str:
    return ", ".join(f"{k} {v:.4g}" + (f" {FLANK_OPTION_UNITS[k]}"
                                        if FLANK_OPTION_UNITS[k] != "1" else "")
                     for k, v in values.items())


#: the shortfalls a design must be free of at every mounting excursion to be tolerant
#: (:attr:`DevelopmentResult.tolerant`)
TOLERANCE_KEYS = ("toe", "heel", "edge", "plastic")

#: margin below the flank's static strength that
#: :func:`~contact.optimize.development_check.static_capacity` aims at [1]
STATIC_MARGIN = 0.99


#: the outcomes of the coast flank's development (``DevelopmentResult.coast_status``)
COAST_STATUS = {
    "developed": "developed",
    "met": "not developed: met every target as synthesised",
    "off": "not developed: coast development off (coast_max_evaluations = 0)",
    "not improved": "not developed: no design of its search did better than as synthesised",
    "not checked": "not checked: its analysis failed",
}


def metrics_text(m: Mapping[str, np.ndarray]) -> str:
    """A design's metrics in one phrase (light-load pattern and its footprint centre,
    design-torque edge share — with its edge peak where above the flank's static strength,
    ``edge_peak`` and ``edge_static_strength`` —, worst plastic share, LTE at both
    torques)."""
    peak = ""
    if "edge_peak" in m and "edge_static_strength" in m:
        p, static = float(m["edge_peak"][1]), float(m["edge_static_strength"][1])
        peak = f" (peak {p:.0f} MPa above {static:.0f})" if p > static else ""
    return (f"pattern {m['pattern_toe_u'][0]:.2f}-{m['pattern_heel_u'][0]:.2f} x "
            f"{m['pattern_root_v'][0]:.2f}-{m['pattern_tip_v'][0]:.2f} centre "
            f"({m['pattern_centre_u'][0]:.2f}, {m['pattern_centre_v'][0]:.2f}), edge "
            f"{100 * m['edge_load_share'][1]:.1f} %{peak}, plastic "
            f"{100 * np.max(m['plastic_share']):.1f} %, LTE "
            f"{m['lte_peak_to_peak'][0]:.0f}/{m['lte_peak_to_peak'][1]:.0f} urad")
