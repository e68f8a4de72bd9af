"""Duty cycles: a load spectrum with torque-dependent misalignment, its efficiency and damage.

Each bin of a :class:`~contact.study.duty_cycle_inputs.DutyCycle` is one
:func:`contact.run_analysis` of the case at the bin's pinion torque and misalignment (the
deflection table's at that torque plus the case's assembly misalignment), with the
efficiency stage at the bin's speed and oil temperature; the bins run on the study engine
(:func:`contact.study.engine.run_tasks`: Dask, one process per core, or
``"synchronous"``), stream to ``OUTPUT.parts/`` as they finish and resume after a kill
(:class:`contact.study.store.ResultStore`). From the bins' stresses the durability code
(:mod:`contact.load_capacity.durability`) sums Miner's damage per flank point and per fillet point.

Public names
------------
DutyInputs       what every bin shares (case, duty cycle, options)
analyse_bin      one bin's results (runs on a worker)
bin_envelopes    a bin's pressure envelopes: line contacts, corner clips left out, edges
duty_cycle_result  the /duty_cycle dataset from the bins' results
bin_table        the rows of the per-bin table the CLI prints
run_duty_cycle   the whole duty cycle: per-bin results, cycle totals, damage and life
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import logging
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from contact.catalogue import resolve_case
from contact.load_capacity.durability import (
    cumulative_damage,
    life_at_first_failure,
    member_cycles,
    peak_fillet_stress,
    pressure_envelopes,
    sn_curves,
    static_contact_strength,
)
from contact.ltca import LTCAOptions
from contact.ltca.options import json_options
from contact.ltca.plausibility import CAUSES, EDGE_SHARE_MIN
from contact.qp.solvers import solver_name
from contact.study.duty_cycle_inputs import DutyCycle
from contact.study.run import StudyRun
from contact.study.store import ChunkSpec, ResultStore
from geometry import __version__
from geometry.case import Case
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, raise_if_interrupted
from geometry.core.text import plain_number

if TYPE_CHECKING:
    from contact.ltca.summary import FlankPeak

__all__ = ["BIN_VARIABLES", "DutyInputs", "analyse_bin", "bin_envelopes", "bin_table",
           "duty_cycle_result", "duty_root_stress", "judged_edge_peak", "run_duty_cycle"]

log = logging.getLogger(__name__)

#: per-bin scalars: name → (units, long name)
BIN_VARIABLES = {
    "lte_mean": ("urad", "mean loaded transmission error"),
    "lte_peak_to_peak": ("urad", "peak-to-peak loaded transmission error"),
    "pressure_max_flank": ("MPa", "peak Hertzian pressure of the flank (contact-curve) "
                           "segments"),
    "pressure_max_edge": ("MPa", "peak Hertzian pressure of the edge-contact segments"),
    "edge_peak_pressure": ("MPa", "peak Hertzian pressure of the edge kinds that carry at "
                           "least EDGE_SHARE_MIN of the torque, below the edges' "
                           "contact-pressure limit (contact.study.verdicts.edge_peaks; 0 "
                           "where none); what ltca run's edge_pressure check judges"),
    "flank_peak_pressure": ("MPa", "peak Hertzian pressure of the flank's line contacts: "
                            "pressure_max_flank without the contact curves shorter than "
                            "their Hertz contact width 2b carrying <= 1 % of their roll's "
                            "load (contact.ltca.summary.flank_peak); what the static check "
                            "and ltca run's verdict judge"),
    "flank_corner_curves": ("1", "contact curves left out of flank_peak_pressure (clipped "
                            "into a flank corner: no line contact)"),
    "edge_load_share": ("1", "share of the gear torque carried by edge contact"),
    "plastic_load_share": ("1", "largest share of the gear torque that segments at the "
                           "material's contact-pressure limit (plastic edges) carry at one "
                           "roll position (/ltca/plastic_load_share; 0 where none)"),
    "efficiency": ("1", "mechanical mesh efficiency, mean over the mesh cycles"),
    "power_loss": ("W", "mesh power loss, mean over the mesh cycles"),
}


@dataclass(frozen=True)
class DutyInputs:
    """What every bin of a duty cycle shares (scattered once to every worker).

    Parameters
    ----------
    case : geometry.case.Case
    duty : DutyCycle
    options : contact.ltca.LTCAOptions
    flank : str or None
    root_stress : bool or contact.compliance.fe.FEOptions
        Each bin's analysis also computes the tooth-root stress (``run_analysis``'s
        ``root_stress``; FE influence coefficients, docs/fe.md), so the bending side
        (ISO 6336-3 S–N curve) has its fillet stresses. FEOptions: that FE model.
    coefficients : tuple of xarray.Dataset
        The FE influence coefficients the client built or read (set by
        :func:`run_duty_cycle`, not by the user): every worker writes them into its own
        cache before its first bin (:func:`contact.compliance.fe.prime_cache`), so no
        worker builds them (issue 53). Not part of the fingerprint.
    """

    case: Case
    duty: DutyCycle
    options: LTCAOptions
    flank: str | None = None
    root_stress: Any = False
    coefficients: tuple = ()

    def fingerprint(self) -> str:
        """A hash of everything deciding the bins' analyses (a resumed run must match):
        case, options, flank, and each bin's torque, speed, temperature and misalignment —
        not the durations, grade or Miner's rule, which only the damage reads (a run with
        other durations reuses the analyses)."""
        d = self.duty
        mis = [dataclasses.astuple(d.misalignment(i, self.case.misalignment))
               for i in range(d.n_bins)]
        bins = {"torque": d.torque.tolist(), "speed": d.pinion_speed.tolist(), "misalignment": mis,
                "temperature": None if d.temperature is None else d.temperature.tolist()}
        text = json.dumps({"case": self.case.to_toml(), "bins": bins,
                           "options": json_options(self.options), "flank": self.flank,
                           "root_stress": repr(self.root_stress)},
                          sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()


def bin_envelopes(ltca: xr.Dataset, peak: FlankPeak | None = None
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A bin's pressure envelopes on the gear grid: the flank's line contacts (what the
    damage and the local S_H read), the contact curves the flank peak leaves out, the edge
    segments.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` of one torque: ``pressure_max`` (torque, roll, pair, segment) [MPa],
        ``segment_u``, ``segment_v`` (roll, pair, segment) [1], the coordinates ``u``,
        ``v`` [1] and ``segment_kind`` (segment), and what
        :func:`contact.ltca.summary.flank_peak` reads.
    peak : contact.ltca.summary.FlankPeak, optional
        ``flank_peak(ltca)`` where the caller has it.

    Returns
    -------
    line, corner, edge : ndarray (u, v) — [MPa]
        The largest pressure landing on each node (the nearest-node rule of
        :func:`contact.load_capacity.durability.pressure_envelopes`) of the contact curves
        the flank peak keeps (``line``: its peak is ``flank_peak(ltca).pressure[0]``), of
        those it leaves out (shorter than their Hertz contact width 2b, carrying at most
        :data:`contact.ltca.summary.CORNER_LOAD_SHARE` of their roll's load), and of the
        edge segments; 0 where none. Their largest is ``/ltca/pressure_envelope``.

    Raises
    ------
    KeyError
        A variable above absent.

    Notes
    -----
    One rule judges a flank (issue 71): the static check, ``ltca run``'s verdict and the
    development leave out a curve clipped into a flank corner, whose load per length is a
    ratio of two vanishing numbers (:func:`contact.ltca.summary.flank_peak`, Johnson,
    *Contact Mechanics*, 1985, §4.3); the damage on the ISO 6336-2 S–N curve leaves it out
    too, else the same bin's flank would be judged two ways.
    """
    from contact.ltca.summary import flank_peak

    fp = flank_peak(ltca) if peak is None else peak
    edge = np.asarray(ltca["segment_kind"].values) != "curve"
    corner = (~fp.line[0])[..., None] & ~edge  # (roll, pair, segment)
    pmax = np.asarray(ltca["pressure_max"].values[0], float)
    su, sv = ltca["segment_u"].values, ltca["segment_v"].values
    u, v = ltca["u"].values, ltca["v"].values
    line, edge_env = pressure_envelopes(np.where(corner, np.nan, pmax), su, sv, edge, u, v)
    left_out, _ = pressure_envelopes(np.where(corner, pmax, np.nan), su, sv, edge, u, v)
    return line, left_out, edge_env


def analyse_bin(shared: DutyInputs, index: int) -> xr.Dataset:
    """Analyse one bin (the function Dask runs on a worker).

    Parameters
    ----------
    shared : DutyInputs
    index : int
        The bin.

    Returns
    -------
    xarray.Dataset
        Over a ``point`` dim of length 1 (the bin; the store's dim): the
        :data:`BIN_VARIABLES`, ``lte_harmonics`` (harmonic) [µrad], ``pressure_envelope``
        (u, v) [MPa] of the flank's line contacts (the contact curves
        :func:`contact.ltca.summary.flank_peak` keeps: what the damage and the local S_H
        read, whose peak is ``flank_peak_pressure``), ``corner_pressure_envelope`` of the
        curves it leaves out and ``edge_pressure_envelope`` of the edge segments (the
        largest of the three is ``/ltca/pressure_envelope``) and, when the
        analysis has ``root_stress``, ``root_stress_peak`` (member, fillet_point) [MPa];
        ``status`` 0 ok, 1 uncertified rolls, 2 failed (``reason``); ``plausibility``, the
        CF flag of the causes ``ltca run`` warns of (:func:`contact.study.summary.
        plausibility_bits`, as every study point). A failing bin does not raise.

    Notes
    -----
    Exactly :func:`contact.run_analysis` at the bin's torque and misalignment (no
    geometry, no mesh interface) and :func:`friction.efficiency.efficiency_analysis` at its
    speed and oil temperature.
    """
    from contact.chain import AnalysisChain
    from contact.ltca.summary import edge_load_share, flank_peak
    from contact.pipeline import operating_conditions, run_analysis
    from contact.study.summary import plausibility_bits
    from friction.efficiency import efficiency_analysis

    case, duty = shared.case, shared.duty
    torque = float(duty.torque[index])
    ltca = None
    if shared.coefficients:   # the client's FE coefficients into this worker's cache
        from contact.compliance.fe import prime_cache

        prime_cache(shared.coefficients)
    try:
        mis = duty.misalignment(index, case.misalignment)
        tree = run_analysis(dataclasses.replace(case, misalignment=mis), [torque],
                            flank=shared.flank, options=shared.options, theoretical=False,
                            steps=AnalysisChain.contact_only().with_root_stress(
                                shared.root_stress))
        ltca = tree["/ltca"].to_dataset()
        temp = None if duty.temperature is None else float(duty.temperature[index])
        op = operating_conditions(case, pinion_speed=float(duty.pinion_speed[index]),
                                  temperature=temp)
        fr = efficiency_analysis(ltca, op)
        fp = flank_peak(ltca)  # the peak the static check judges, as ltca run's verdict
        vals = {
            "lte_mean": ltca["lte_mean"].values[0],
            "lte_peak_to_peak": ltca["lte_peak_to_peak"].values[0],
            "pressure_max_flank": ltca["pressure_max_flank"].values[0],
            "pressure_max_edge": ltca["pressure_max_edge"].values[0],
            "edge_peak_pressure": judged_edge_peak(ltca),
            "flank_peak_pressure": fp.pressure[0],
            "flank_corner_curves": fp.corner_curves[0],
            "edge_load_share": edge_load_share(ltca)[0],
            "plastic_load_share": (
                np.max(np.nan_to_num(ltca["plastic_load_share"].values[0], nan=0.0))
                if "plastic_load_share" in ltca else 0.0),
            "efficiency": fr["efficiency_mean"].values[0],
            "power_loss": fr["power_loss_mean"].values[0],
        }
        status = 0 if bool(np.all(ltca["found"].values > 0)) else 1
        reason = ""
        if tree.attrs.get("analysis_status") == "failed":  # no certified roll at all
            status, reason = 2, str(tree.attrs["analysis_status_reason"])
        harm = ltca["lte_harmonics"].values[0]
        u, v = ltca["u"].values, ltca["v"].values
        env, corner_env, edge_env = bin_envelopes(ltca, fp)
        root = (peak_fillet_stress(ltca["root_stress"].values[0])
                if "root_stress" in ltca else None)
        fillet_u = ltca["fillet_u"].values if "root_stress" in ltca else None
    except Exception as exc:  # one failing bin never stops the cycle
        raise_if_interrupted(exc)
        log.info("duty-cycle bin %d failed: %s", index, exc)
        status, reason = 2, f"{type(exc).__name__}: {exc}".splitlines()[0]
        vals = dict.fromkeys(BIN_VARIABLES, np.nan)
        harm, u, v, root, fillet_u = np.full(3, np.nan), [0.0], [0.0], None, None
        env = edge_env = corner_env = np.full((1, 1), np.nan)
        ltca = None  # the input alone is judged
    data = {k: data_var(("point",), np.array([float(x)]), *BIN_VARIABLES[k])
            for k, x in vals.items()}
    # the causes ltca run warns of, as the studies flag every point (contact.study.summary)
    try:
        bits = plausibility_bits(ltca, case, duty.misalignment(index, case.misalignment), 1)
    except InputError:  # a misalignment the table cannot give: the bin failed for it
        bits = np.zeros(1, np.int8)
    data["plausibility"] = data_var(
        ("point",), bits, "1", "causes for which the bin's results are implausible, as "
        "ltca run warns (contact.ltca.plausibility; 0 none)",
        flag_masks=np.array([1 << k for k in range(len(CAUSES))], dtype=np.int8),
        flag_meanings=" ".join(CAUSES))
    data["lte_harmonics"] = data_var(("point", "harmonic"), np.asarray(harm, float)[None],
                                     "urad", "amplitude of the first three mesh harmonics "
                                     "of the loaded transmission error")
    data["pressure_envelope"] = data_var(
        ("point", "u", "v"), np.asarray(env, float)[None], "MPa",
        "peak contact pressure of the flank (contact-curve) segments of a tooth mesh on the "
        "gear's contact grid")
    data["edge_pressure_envelope"] = data_var(
        ("point", "u", "v"), np.asarray(edge_env, float)[None], "MPa",
        "peak contact pressure of the edge-contact segments of a tooth mesh on the gear's "
        "contact grid")
    data["corner_pressure_envelope"] = data_var(
        ("point", "u", "v"), np.asarray(corner_env, float)[None], "MPa",
        "peak contact pressure of the contact curves left out of the flank peak (shorter "
        "than their Hertz contact width, <= 1 % of their roll's load: "
        "contact.ltca.summary.flank_peak) on the gear's contact grid; 0 where none")
    if root is not None:
        data["root_stress_peak"] = data_var(
            ("point", "member", "fillet_point"), root[None], "MPa",
            "peak tensile fillet stress of a tooth mesh")
    data["status"] = data_var(("point",), np.array([status], np.int8), "1",
                              "outcome of the bin's analysis (0 ok, 1 uncertified, 2 failed)")
    data["reason"] = data_var(("point",), np.array([reason], dtype=object), None,
                              "why the bin failed (empty when it did not)")
    coords = {"point": ("point", [index], {"units": "1", "long_name": "bin index"}),
              "u": ("u", np.asarray(u, float), {"units": "1",
                                                "long_name": "gear lengthwise fraction"}),
              "v": ("v", np.asarray(v, float), {"units": "1",
                                                "long_name": "gear profile fraction"})}
    if fillet_u is not None:
        coords["fillet_u"] = (("member", "fillet_point"), np.asarray(fillet_u, float),
                              {"units": "1", "long_name": "lengthwise fraction of the fillet "
                                                          "face station (toe 0, heel 1)"})
    return xr.Dataset(data, coords=coords)


#: the data variables of a bin's chunk (:func:`analyse_bin`; ``root_stress_peak`` only
#: with the root stress, at the bins that did not fail)
_BIN_CHUNK_VARIABLES = (*BIN_VARIABLES, "lte_harmonics", "pressure_envelope",
                        "edge_pressure_envelope", "corner_pressure_envelope", "plausibility",
                        "status", "reason")

#: finite at every bin whose ``status`` is 0 (every roll certified: the LTE is defined;
#: the envelopes are 0 where no segment lands): NaN there is a damaged chunk
_FINITE_WHEN_OK = ("lte_mean", "lte_peak_to_peak", "pressure_envelope",
                   "edge_pressure_envelope", "corner_pressure_envelope")


def _bins(shared: DutyInputs, run: StudyRun) -> xr.Dataset:
    """Every bin's dataset, from the parts of an interrupted run and the engine.

    A chunk of the parts that is not this duty cycle's (unreadable, other variables, NaN
    where a bin's status is 0) is named in a warning, moved to ``OUTPUT.parts/set-aside/``
    and its bins analysed again (:class:`contact.study.store.ResultStore`)."""
    from contact.study.engine import stream_tasks

    n = shared.duty.n_bins
    store = None
    done: set[int] = set()
    if run.output is not None:
        out = Path(run.output)
        if not out.parent.is_dir():
            raise InputError(f"output: directory {str(out.parent)!r} does not exist")
        store = ResultStore(out, {"fingerprint": shared.fingerprint(), "kind": "duty_cycle",
                                  "bins": n}, chunk_size=1,
                            spec=ChunkSpec(points=n, variables=_BIN_CHUNK_VARIABLES,
                                           optional=("root_stress_peak",),
                                           finite=_FINITE_WHEN_OK))
        done = store.done()
    todo = [(i,) for i in range(n) if i not in done]
    kept = stream_tasks(analyse_bin, shared, todo, lambda ds: ds, store=store,
                        progress=run.progress, desc="duty cycle", unit="bin", total=n,
                        initial=len(done), scheduler=run.scheduler, n_workers=run.n_workers)
    # coords "minimal": a failed bin has no ``fillet_u`` (no root stress), the others
    # share it; the failed bin is then named by the damage (_durability), not a traceback
    parts = [store.combined(coords="minimal")] if store is not None else kept
    if store is not None and parts[0].sizes["point"] != n:
        raise InputError(f"output: {parts[0].sizes['point']} of {n} bins in "
                         f"{str(store.parts)!r} after the run (a chunk failed its check, "
                         "see the warning); start the duty cycle again to analyse the "
                         "missing bins")
    ds = xr.concat(parts, dim="point", join="outer", coords="minimal")
    ds = ds.isel(point=np.argsort(ds["point"].values, kind="stable"))
    ds.attrs["bins_resumed"] = len(done)
    return ds.rename(point="bin")


def _cycle(duty: DutyCycle, ds: xr.Dataset) -> dict[str, Any]:
    """Per-bin energy and the cycle's totals (energy in, lost, efficiency)."""
    omega = duty.pinion_speed * 2.0 * math.pi / 60.0  # rad/s
    power_in = duty.torque * omega  # W
    seconds = duty.hours * 3600.0
    e_in = power_in * seconds / 3.6e6  # kWh
    e_lost = ds["power_loss"].values * seconds / 3.6e6
    e_out = ds["efficiency"].values * e_in
    return {"power_in": power_in, "energy_in": e_in, "energy_lost": e_lost,
            "energy_out": e_out}


def _rated_curves(curve, rated: xr.Dataset | None, kind: str, k: int):
    """The S-N curve of each bin on the rating's allowables (``rated``: the bins'
    :func:`contact.load_capacity.iso10300.bin_ratings`; ``kind`` contact or bending, member index
    ``k``):
    :meth:`contact.load_capacity.durability.SNCurve.rated` with the bin's long-life influence
    factors
    (Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp; Y_δ,relT Y_R,relT Y_X), those that are 1 for the static
    stress taken out at the static end (ISO 6336-2/-3); the material's bare curve, one for
    every bin, without a rating."""
    if rated is None:
        return curve
    f = rated[f"{kind}_allowable_factor"].values[:, k]
    z = rated[f"{kind}_static_influence"].values[:, k]
    return [curve.rated(float(a), float(b)) for a, b in zip(f, z, strict=True)]


def _peak(curves, b: int):
    """The curve of bin ``b`` (one curve for all bins, or one per bin)."""
    return curves[b] if isinstance(curves, list) else curves


def _durability(case: Case, duty: DutyCycle, ds: xr.Dataset,
                rated: xr.Dataset | None = None) -> dict[str, Any]:
    """Damage per flank and fillet point, life and safety factors (the /duty_cycle vars),
    on the rating's allowables of each bin where ``rated`` (the bins' ratings) is given,
    else on the material's bare σ_Hlim and σ_FE."""
    if np.any(ds["status"].values == 2):
        bad = int(np.argmax(ds["status"].values == 2))
        from contact.errors import AnalysisFailedError

        reason = str(ds["reason"].values[bad])
        where = ""
        if duty.deflection is not None and reason.startswith("InputError: misalignment"):
            # the reason names ltca run's options; here the deflection table set them
            where = (f"; bin {bad}'s misalignment is the [duty_cycle] deflection table's "
                     f"at its {plain_number(float(duty.torque[bad]))} N m plus the case's own")
            if duty.illustrative:
                where += (" — the ILLUSTRATIVE table of `ltca duty-cycle` without --duty "
                          "(at the top torque dE 0.05, dP -0.03, dG 0.03 mm, dSigma "
                          "0.01 deg, whatever the gear's size): give this design's "
                          "deflections (--duty FILE, docs/cases.md)")
        raise AnalysisFailedError(f"duty_cycle bin {bad}: its analysis failed "
                                  f"({reason}); no damage without every bin{where}")
    out: dict[str, Any] = {}
    cycles = member_cycles(duty.revolutions, case.pinion.blank.teeth, case.gear.blank.teeth)
    members = ("pinion", "gear")
    hours = float(duty.hours.sum())
    peak_bin = int(np.argmax(duty.torque))
    for m in members:
        mat = case.member(m).material
        curves = sn_curves(mat, duty.grade)
        k = members.index(m)
        contact = _rated_curves(curves["contact"], rated, "contact", k)
        bend = _rated_curves(curves["bending"], rated, "bending", k)
        env = ds["pressure_envelope"].values
        d = cumulative_damage(env, cycles[m], contact, duty.miner_rule)
        out[f"flank_damage_{m}"] = d
        total = d.sum(axis=0)
        life, idx = life_at_first_failure(total, hours)
        out[f"flank_life_{m}"] = life
        out[f"flank_location_{m}"] = (float(ds["u"].values[idx[0]]),
                                      float(ds["v"].values[idx[1]]))
        out[f"contact_safety_{m}"] = (_peak(contact, peak_bin).allowable
                                      / float(env[peak_bin].max()))
        out[f"contact_allowable_{m}"] = _peak(contact, peak_bin).allowable
        # the static check judges the bin's flank peak as ltca run's verdict does
        # (contact.ltca.summary.flank_peak: no contact curve clipped into a flank corner);
        # bins of a run before it (no flank_peak_pressure) their envelope's peak
        judged = (np.asarray(ds["flank_peak_pressure"].values, float)
                  if "flank_peak_pressure" in ds else env.reshape(env.shape[0], -1).max(-1))
        # the static strength ltca run's verdict judges (the material's σ_Hlim Z_NT,stat Z_W
        # Z_X, ISO 6336-2 at the static stress); the S-N line above keeps the rating's
        # allowables (its Z_K Z_Hyp) for the damage between the knee and 1e5 cycles
        strength = np.full(env.shape[0], static_contact_strength(
            mat, duty.grade).strength)
        out[f"static_strength_{m}"] = strength
        out[f"static_exceeded_{m}"] = bool(np.any(np.nan_to_num(judged) > strength))
        if "root_stress_peak" in ds:
            root = ds["root_stress_peak"].values[:, k, :]
            rd = cumulative_damage(root, cycles[m], bend, duty.miner_rule)
            out[f"root_damage_{m}"] = rd
            rlife, ridx = life_at_first_failure(rd.sum(axis=0), hours)
            out[f"root_life_{m}"] = rlife
            out[f"root_location_{m}"] = int(ridx[0])
            out[f"bending_safety_{m}"] = (_peak(bend, peak_bin).allowable
                                          / max(float(root[peak_bin].max()), 1e-300))
    out["cycles"] = cycles
    out["peak_bin"] = peak_bin
    return out


def _bin_ratings(shared: DutyInputs) -> tuple[xr.Dataset | None, str]:
    """The ISO 10300 rating of every bin (:func:`contact.load_capacity.iso10300.bin_ratings`),
    or None and why (a bad [rating] table does not lose the bins' work: it is said)."""
    from contact.load_capacity.iso10300 import bin_ratings

    try:
        return bin_ratings(shared.case, shared.duty.torque, shared.duty.pinion_speed, shared.flank)
    except InputError as exc:
        return None, f"ISO 10300 rating not computed: {exc}"


def _iso_rating(shared: DutyInputs, ds: xr.Dataset, members: list[str],
                rated: tuple[xr.Dataset | None, str] | None = None
                ) -> tuple[dict[str, Any], str]:
    """Per bin the local safety factors (σ_Hlim over the bin's peak flank pressure, σ_FE
    over its peak fillet stress) beside the ISO 10300 rating's S_H, S_F at the bin's torque
    and speed (:func:`contact.load_capacity.iso10300.bin_ratings`), and the line that says where
    the rating
    comes from or why it is absent (a bad [rating] table does not lose the bins' work: it
    is said there)."""
    duty, case = shared.duty, shared.case
    iso, why = _bin_ratings(shared) if rated is None else rated
    curves = [sn_curves(case.member(m).material, duty.grade) for m in members]
    bm = ("bin", "member")
    # the allowables at long life (life factor 1): the rating's of each bin where there is
    # one (sigma_Hlim and sigma_FE times its influence factors), else the bare numbers
    f_h = (iso["contact_allowable_factor"].values if iso is not None
           else np.ones((duty.n_bins, len(members))))
    f_f = (iso["bending_allowable_factor"].values if iso is not None
           else np.ones((duty.n_bins, len(members))))
    which = ("the rating's sigma_HP/Z_NT of the bin" if iso is not None else "sigma_Hlim")
    # the flank peak the static check and the damage judge (contact.ltca.summary.
    # flank_peak: no curve clipped into a flank corner); bins before it the dataset's
    p = np.asarray(ds["flank_peak_pressure" if "flank_peak_pressure" in ds
                      else "pressure_max_flank"].values, float)
    out = {"local_contact_safety": data_var(bm, np.stack(
        [c["contact"].allowable for c in curves])[None, :] * f_h / p[:, None], "1",
        f"{which} / peak flank contact pressure of the bin (life factor 1)")}
    if "root_stress_peak" in ds:
        peak = np.asarray(ds["root_stress_peak"].values, float).max(axis=-1)  # bin, member
        out["local_bending_safety"] = data_var(bm, np.stack(
            [c["bending"].allowable for c in curves])[None, :] * f_f
            / np.maximum(peak, 1e-300), "1",
            ("the rating's sigma_FP/Y_NT" if iso is not None else "sigma_FE")
            + " / peak tensile fillet stress of the bin (life factor 1)")
    if iso is None:
        return out, why
    if "local_bending_safety" in out and {"K_A_K_v", "S_Fmin"} <= set(iso.variables):
        # ltca run's S_F,FE of the bin (its K_A K_v on the peak fillet stress), judged as
        # ltca run judges it (contact.study.verdict_checks.root_safety_severity, issue 71)
        out["root_stress_safety"] = data_var(
            bm, out["local_bending_safety"][1] / iso["K_A_K_v"].values[:, None], "1",
            "S_F,FE of ltca run's root_stress check at the bin: the rating's sigma_FP/Y_NT "
            "/ (peak tensile fillet stress x K_A K_v of the bin), long life")
        out["bending_safety_min"] = iso["S_Fmin"].variable
        out["rating_design_torque"] = iso["design_torque"].variable
    for name, var in (("iso_contact_stress", "sigma_H"), ("iso_root_stress", "sigma_F"),
                      ("iso_contact_safety", "S_H"), ("iso_bending_safety", "S_F")):
        out[name] = iso[var].variable
    # the minima and design torque the verdict's rating check judges the bins' S_H, S_F
    # by, as ltca run's (contact.study.verdicts, issue 71)
    if "S_Hmin" in iso:
        out["contact_safety_min"] = iso["S_Hmin"].variable
    out.setdefault("bending_safety_min", iso["S_Fmin"].variable)
    out.setdefault("rating_design_torque", iso["design_torque"].variable)
    return out, (f"ISO 10300-1/-2/-3:2014 Method B1 at each bin's torque and speed "
                 f"({iso.attrs.get('side', '')} side; the case's [rating] table, "
                 "docs/rating.md)")


def duty_cycle_result(shared: DutyInputs, ds: xr.Dataset) -> xr.Dataset:
    """The ``/duty_cycle`` dataset from the bins' analyses (what :func:`run_duty_cycle`
    returns after running them).

    Parameters
    ----------
    shared : DutyInputs
    ds : xarray.Dataset
        Over ``bin``: :func:`analyse_bin`'s variables of every bin (``point`` renamed).

    Returns
    -------
    xarray.Dataset
        As :func:`run_duty_cycle`.

    Raises
    ------
    contact.errors.AnalysisFailedError
        A failed bin (named, with its reason: an error, or no certified contact solution).
    InputError
        An unknown grade.
    """
    duty, case = shared.duty, shared.case
    cyc = _cycle(duty, ds)
    rated = _bin_ratings(shared)
    dur = _durability(case, duty, ds, rated[0])
    members = ["pinion", "gear"]
    out = ds.drop_vars([v for v in ("pressure_envelope", "edge_pressure_envelope",
                                     "corner_pressure_envelope", "root_stress_peak")
                        if v in ds])
    out = out.assign_coords(member=("member", members, {"long_name": "gear member"}))
    bin_ = ("bin",)
    out["torque"] = data_var(bin_, duty.torque, "N m", "pinion torque of the bin")
    out["speed"] = data_var(bin_, duty.pinion_speed, "rpm", "pinion speed of the bin")
    out["hours"] = data_var(bin_, duty.hours, "h", "duration of the bin")
    out["revolutions"] = data_var(bin_, duty.revolutions, "1", "pinion revolutions of the bin")
    if duty.temperature is not None:
        out["temperature"] = data_var(bin_, duty.temperature, "degC",
                                      "oil inlet temperature of the bin")
    mis = [duty.misalignment(i, case.misalignment) for i in range(duty.n_bins)]
    for name, unit, scale in (("delta_E", "mm", 1.0), ("delta_P", "mm", 1.0),
                              ("delta_G", "mm", 1.0), ("delta_Sigma", "rad", 1.0)):
        out[name] = data_var(bin_, np.array([getattr(m, name) * scale for m in mis]), unit,
                             f"misalignment {name} of the bin (deflection + assembly)")
    out["power_in"] = data_var(bin_, cyc["power_in"], "W", "input (pinion) power of the bin")
    out["energy_in"] = data_var(bin_, cyc["energy_in"], "kW h", "energy in over the bin")
    out["energy_lost"] = data_var(bin_, cyc["energy_lost"], "kW h",
                                  "energy lost in the mesh over the bin")
    ein, elost = float(cyc["energy_in"].sum()), float(cyc["energy_lost"].sum())
    out["cycle_energy_in"] = data_var((), np.float64(ein), "kW h",
                                      "energy in over the duty cycle")
    out["cycle_energy_lost"] = data_var((), np.float64(elost), "kW h",
                                        "energy lost in the mesh over the duty cycle")
    out["cycle_efficiency"] = data_var((), np.float64(1.0 - elost / ein), "1",
                                       "cycle-average mesh efficiency (energy out / in)")
    out["cycles_per_tooth"] = data_var(
        ("bin", "member"), np.stack([dur["cycles"][m] for m in members], -1), "1",
        "load cycles of a tooth point in the bin (one per tooth mesh)")
    out["flank_damage"] = data_var(
        ("bin", "member", "u", "v"), np.stack([dur[f"flank_damage_{m}"] for m in members], 1),
        "1", "Miner damage of the flank points in the bin (at the gear-grid point in contact)")
    out["flank_damage_total"] = out["flank_damage"].sum("bin").assign_attrs(
        units="1", long_name="cumulative Miner damage of the flank points over the cycle")
    out["pressure_envelope"] = ds["pressure_envelope"]
    out["edge_pressure_envelope"] = ds["edge_pressure_envelope"]
    if "corner_pressure_envelope" in ds:  # the curves the damage leaves out, kept to read
        out["corner_pressure_envelope"] = ds["corner_pressure_envelope"]
    out["damage"] = data_var(("member",), np.array(
        [float(out["flank_damage_total"].sel(member=m).max()) for m in members]), "1",
        "largest cumulative flank (pitting) damage of the duty cycle")
    out["life"] = data_var(("member",), np.array([dur[f"flank_life_{m}"] for m in members]),
                           "h", "flank (pitting) life: hours to damage 1 at the first point")
    out["life_u"] = data_var(("member",), np.array(
        [dur[f"flank_location_{m}"][0] for m in members]), "1",
        "gear lengthwise fraction of the flank point first reaching damage 1")
    out["life_v"] = data_var(("member",), np.array(
        [dur[f"flank_location_{m}"][1] for m in members]), "1",
        "gear profile fraction of the flank point first reaching damage 1")
    out["contact_static_strength"] = data_var(
        ("bin", "member"), np.stack([dur[f"static_strength_{m}"] for m in members], -1),
        "MPa", "static contact strength sigma_Hlim x Z_NT,stat x Z_W x Z_X of the member's "
        "material at the cycle's grade (ISO 6336-2 at the static stress; "
        "contact.load_capacity.durability.static_contact_strength, the limit of ltca run's "
        "verdict), which the static check holds flank_peak_pressure against")
    out["contact_safety_factor"] = data_var(("member",), np.array(
        [dur[f"contact_safety_{m}"] for m in members]), "1",
        "allowable at long life (the rating's sigma_HP/Z_NT of the bin, else sigma_Hlim; "
        "the attribute allowables) / peak contact pressure of the peak-torque bin")
    bending = "root_stress_peak" in ds
    if bending:
        out["root_stress_peak"] = ds["root_stress_peak"]
        out["root_damage"] = data_var(
            ("bin", "member", "fillet_point"),
            np.stack([dur[f"root_damage_{m}"] for m in members], 1), "1",
            "Miner damage of the fillet points in the bin")
        out["root_damage_max"] = data_var(("member",), np.array(
            [float(dur[f"root_damage_{m}"].sum(0).max()) for m in members]), "1",
            "largest cumulative root (bending) damage of the duty cycle")
        out["root_life"] = data_var(("member",), np.array(
            [dur[f"root_life_{m}"] for m in members]), "h",
            "root (bending) life: hours to damage 1 at the first fillet point")
        out["root_life_point"] = data_var(("member",), np.array(
            [dur[f"root_location_{m}"] for m in members]), "1",
            "fillet point first reaching damage 1")
        out["bending_safety_factor"] = data_var(("member",), np.array(
            [dur[f"bending_safety_{m}"] for m in members]), "1",
            "allowable at long life (the rating's sigma_FP/Y_NT of the bin, else sigma_FE; "
            "the attribute allowables) / peak tensile fillet stress of the peak-torque bin")
    iso, iso_note = _iso_rating(shared, ds, members, rated)
    out.update(iso)
    out = out.assign_coords(bin=("bin", np.arange(duty.n_bins),
                                 {"units": "1", "long_name": "duty-cycle bin"}),
                            harmonic=("harmonic", np.arange(1, 4),
                                      {"units": "1", "long_name": "mesh harmonic order"}))
    out["reason"] = out["reason"].astype(str)
    out.attrs = {
        "title": f"hypoid-ltca duty cycle of {case.name}",
        "case": case.name,
        "toolkit_version": __version__,
        "duty_cycle": duty.name,
        "illustrative": int(duty.illustrative),
        "grade": duty.grade,
        "miner_rule": duty.miner_rule,
        "bending": ("available" if bending else
                    "unavailable: the bins' analyses have no root_stress (run with "
                    "root_stress=True, `ltca duty-cycle --root-stress`); no bending damage "
                    "or life is reported"),
        "contact_static_limit_exceeded": int(any(dur[f"static_exceeded_{m}"]
                                                 for m in members)),
        "contact_static_check": (
            "the bins' flank_peak_pressure (pressure_max_flank without contact curves "
            "clipped into a flank corner, contact.ltca.summary.flank_peak) against "
            "contact_static_strength" if "flank_peak_pressure" in ds else
            "the bins' pressure_envelope peak against contact_static_strength"),
        "flank_damage_curves": (
            "the flank damage, contact_safety and local_contact_safety read the contact "
            "curves the static check judges (pressure_envelope, flank_peak_pressure: "
            "without the curves shorter than their Hertz contact width that carry <= 1 % "
            "of their roll's load, contact.ltca.summary.flank_peak; those in "
            "corner_pressure_envelope)" if "corner_pressure_envelope" in ds else
            "the flank damage reads every contact curve (pressure_envelope)"),
        "edge_contact": "edge-contact pressures (edge_pressure_envelope, pressure_max_edge) "
                        "are not counted in the pitting damage: the S-N curve of ISO 6336-2 "
                        "is of Hertzian flank contact; the LTCA bounds edge pressures by the "
                        "elastic-perfectly-plastic (shakedown) limit instead",
        "flank_damage_location": "both members' flank damage is placed at the gear's "
                                 "contact-grid point (u, v) in contact",
        "peak_bin": dur["peak_bin"],
        "iso_rating": iso_note,
        "allowables": (
            "the S-N curves of each bin on the ISO 10300 rating's allowables: sigma_Hlim "
            "Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp and sigma_FE Y_delta,relT Y_R,relT Y_X of the "
            "bin's speed at the knee (sigma_HP/Z_NT, sigma_FP/Y_NT), Z_L Z_v Z_R and "
            "Y_R,relT Y_X taken as 1 at the static end (ISO 6336-2/-3), the life factor "
            "Z_NT, Y_NT on the line between (contact.load_capacity.durability.SNCurve.rated)"
            if rated[0] is not None else
            "the material's bare sigma_Hlim and sigma_FE (no ISO 10300 rating: "
            + rated[1] + ")"),
        "bins_resumed": int(ds.attrs.get("bins_resumed", 0)),
        "solver": solver_name(shared.options.solver),
        "flank": shared.flank or "drive",
    }
    return out


def run_duty_cycle(case: Case | str | os.PathLike[str] | None, duty: DutyCycle,
                   run: StudyRun | None = None, *, root_stress: Any = None) -> xr.Dataset:
    """Analyse every bin of a duty cycle and its damage, life and cycle efficiency.

    Parameters
    ----------
    case : Case, path, bundled name or None (the default case)
        The gear set (its ``misalignment`` is the assembly misalignment;
        :func:`contact.resolve_case`).
    duty : DutyCycle
        Bins (torque [N·m], pinion speed [rpm], revolutions, temperature [degC]), deflection
        table, grade and Miner's rule.
    run : contact.study.StudyRun, optional
        LTCA options, flank, output (streaming to ``OUTPUT.parts/`` and resume; a chunk
        of the parts that is not this cycle's is set aside and its bin analysed again),
        scheduler and workers. ``operating`` is not used (each bin sets its own speed and
        temperature; the case's lubricant, roughness, friction model). The default
        scheduler, a local cluster, spawns worker processes that import the calling
        script again: a script calls this under ``if __name__ == "__main__":`` (else each
        worker re-runs the script's top before the start fails with an InputError that
        says so; round 30 of docs/own_gear_set.md: a synthesis of 98 s CPU re-run, 21 min
        of wall time to the error), or passes ``StudyRun(scheduler="synchronous")``.
    root_stress : bool or contact.compliance.fe.FEOptions, optional
        Also the tooth-root stress of each bin (FE influence coefficients of the
        generated teeth, built once per design and cached; docs/fe.md) and with it the
        bending side: root damage, life and safety factor per member. True: the case's
        FE model (its ``[root_stress] fe_level``, else the default one); FEOptions: that
        one; False: none (the bending side "unavailable", its checks not made). Default
        (None) ``run.root_stress`` where it is set (True or FEOptions), else True — as
        ``ltca duty-cycle`` (``--root-stress`` on by default), so a script and the
        command get the same bins and verdict.

    Returns
    -------
    xarray.Dataset
        The ``/duty_cycle`` group, dims ``bin``, ``member``, ``harmonic``, ``u``, ``v``
        (``fillet_point`` with the bending side): per bin the :data:`BIN_VARIABLES`,
        ``lte_harmonics`` [µrad], misalignment, ``power_in`` [W], ``energy_in``,
        ``energy_lost`` [kW h], ``flank_damage`` [1]; over the cycle ``cycle_energy_in``,
        ``cycle_energy_lost``, ``cycle_efficiency``, ``damage`` [1] and ``life`` [h] per
        member with its location ``life_u``, ``life_v``, ``contact_safety_factor``;
        ``contact_static_strength`` [MPa] per bin and member, against which the static
        check (attribute ``contact_static_limit_exceeded``) holds the bins'
        ``flank_peak_pressure`` (:func:`contact.ltca.summary.flank_peak`); with
        root stress in the analysis ``root_damage``, ``root_life`` [h],
        ``bending_safety_factor``; else the attribute ``bending`` says it is unavailable.

    Raises
    ------
    contact.errors.AnalysisFailedError
        A failed bin (named, with its reason: an error, or no certified contact solution
        at its torque); the parts on disk keep every bin's status.
    InputError
        A bin outside the deflection table (named), an unknown grade, parts of another
        run at ``OUTPUT.parts``, bins missing from the parts after the run (a chunk set
        aside meanwhile: the run started again analyses them); ``root_stress`` not True,
        False, None or FEOptions, or other than a ``run.root_stress`` that is set (both
        named).

    Notes
    -----
    Damage by Miner's rule on the ISO 6336-2/-3 S–N curves of the members' material
    (:mod:`contact.load_capacity.durability`), one load cycle per tooth mesh; local stresses
    from the LTCA (peak Hertz pressure of the contact grid, peak tensile fillet stress).
    """
    case = resolve_case(case)
    if not isinstance(duty, DutyCycle):
        raise InputError(f"duty: must be a DutyCycle, got {type(duty).__name__}")
    run = run or StudyRun()
    for m in ("pinion", "gear"):  # an unknown grade or material fails before any bin runs
        sn_curves(case.member(m).material, duty.grade)
    root_stress = duty_root_stress(root_stress, run.root_stress)
    coefficients: tuple = ()
    fe_failed = ""
    if root_stress is not False:  # built once here, handed to every worker (primed caches)
        from contact.ltca.root_stress import prepare_coefficients
        from geometry.core.errors import LTCAError

        try:
            coefficients = tuple(prepare_coefficients(
                case, run.flank, None if root_stress is True else root_stress,
                progress=run.progress is True).values())  # a bar on a terminal only
        except LTCAError as exc:
            # the FE model of these teeth could not be built (an inverted element): the
            # duty cycle runs on without the bending side, as `ltca run` does without
            # root stress (contact.chain.root_stress_fe), and says why
            fe_failed = f"root stress not computed: the FE model failed ({exc})"
            log.warning("%s", fe_failed)
            root_stress = False
    shared = DutyInputs(case, duty, run.options or LTCAOptions(), run.flank, root_stress,
                        coefficients)
    out = duty_cycle_result(shared, _bins(shared, run))
    if fe_failed:
        out.attrs["bending"] = (f"unavailable: {fe_failed}; no bending damage or life is "
                                "reported")
    return out


def duty_root_stress(root_stress: Any, run_root_stress: Any = None) -> Any:
    """The root stress a duty cycle runs with: :func:`run_duty_cycle`'s ``root_stress``
    as given, else the StudyRun's where it is set, else True (``ltca duty-cycle``'s
    default, ``--root-stress``).

    Parameters
    ----------
    root_stress : None, bool or contact.compliance.fe.FEOptions
        The call's keyword (None: not given).
    run_root_stress : None, bool or contact.compliance.fe.FEOptions
        The call's ``StudyRun.root_stress`` (its default None, or False, the default
        before api83: not set).

    Returns
    -------
    bool or contact.compliance.fe.FEOptions

    Raises
    ------
    InputError
        ``root_stress`` of another type (``root_stress: …``), or given beside a
        ``run.root_stress`` that is set and differs (both named).

    Notes
    -----
    Why (issue 71, branch api82): the keyword defaulted to False where the command's
    option is on, so a script following docs/duty_cycle.md ran the bins without the
    bending side and its verdict had no ``bending`` check where the command's had one;
    and ``StudyRun.root_stress``, which the sweeps read, was ignored here.
    """
    if root_stress is not None and not isinstance(root_stress, bool):
        from contact.compliance.fe import FEOptions

        if not isinstance(root_stress, FEOptions):
            raise InputError("root_stress: must be None, True, False or a "
                             f"contact.compliance.fe.FEOptions, got {root_stress!r}")
    if run_root_stress is None or run_root_stress is False:
        return True if root_stress is None else root_stress
    if root_stress is not None and root_stress != run_root_stress:
        raise InputError(f"root_stress, run.root_stress: two different root stresses "
                         f"({root_stress!r} and {run_root_stress!r}); give one of them")
    return run_root_stress


def judged_edge_peak(ltca: xr.Dataset) -> float:
    """The edge peak pressure [MPa] of a one-torque analysis as ``ltca run``'s
    ``edge_pressure`` check judges it: the largest over the edge kinds that carry at least
    :data:`~contact.ltca.plausibility.EDGE_SHARE_MIN` of the torque and stay below the
    edges' contact-pressure limit (:func:`contact.study.verdicts.edge_peaks`), 0 where none
    does; the analysis's ``pressure_max_edge`` where the verdict cannot read the edges (no
    material named, or one it does not know).

    Parameters
    ----------
    ltca : xarray.Dataset — ``/ltca`` at one torque (``pressure_max_edge`` (torque) [MPa];
        its segments' ``pressure_max``, ``force``, ``moment_arm``, ``segment_kind``)

    Returns
    -------
    float — [MPa]

    Raises
    ------
    KeyError
        No ``pressure_max_edge`` in ``ltca``.

    Notes
    -----
    Why: a bin judged its ``pressure_max_edge`` (the peak over every edge) against the
    bins' total edge share, so a duty cycle named another edge peak than ``ltca run`` at
    the same torque: the hypoid 9×41 at a = 0.2 d_e2 (benchmarks/data/unseen_designs,
    round 20) at 330.4 N·m, ``ltca run`` "2462 MPa on the pinion edge", its duty cycle
    "2730 MPa in bin 4" (the gear heel's, below 0.05 % of the torque). Source: the
    ``edge_pressure`` check (docs/verdicts.md).
    """
    from contact.study.verdicts import edge_peaks

    raw = float(np.nan_to_num(np.asarray(ltca["pressure_max_edge"].values, float)[0]))
    try:
        found = edge_peaks(ltca)
    except InputError:
        found = None
    if found is None:
        return raw
    return max((float(v[0]) for v in found.peaks.values()), default=0.0)


def bin_table(ds: xr.Dataset) -> list[Mapping[str, Any]]:
    """Rows of the per-bin table the CLI prints (torque, speed, hours, LTE, pressure, …)."""
    rows = []
    for i in range(ds.sizes["bin"]):
        rows.append({k: float(ds[k].values[i]) for k in (
            "torque", "speed", "hours", "lte_mean", "lte_peak_to_peak",
            "pressure_max_flank", "pressure_max_edge", "edge_load_share", "efficiency",
            "power_loss")})
    return rows


def share_percent(share: float) -> str:
    """A share of the torque as the percentage text the duty cycle's summary prints.

    Parameters
    ----------
    share : float — a fraction of the torque [1] (0.0022 % is 2.2e-5)

    Returns
    -------
    str — 100 × ``share`` with two decimals, or with two significant digits where two
        decimals would print "0.00" (0 < 100 × share < 0.005), without the % sign

    Notes
    -----
    Why: a trace edge share was printed as "0.00 %" beside its pressure (issue 71 round 34:
    the FM hypoid 5×48's top bin read "up to 0.00 % of the torque in bin 2, edge peak
    pressure up to 1214 MPa"; its share was 0.0022 %).
    """
    pct = 100.0 * float(share)
    if 0.0 < pct < 0.005:
        return f"{pct:.2g}"
    return f"{pct:.2f}"


def edge_note(ds: xr.Dataset) -> str | None:
    """The sentence a duty cycle's summary prints about its edge contact: edge pressures
    are not counted as pitting damage, with the bins' largest edge share of the torque [%]
    and edge peak pressure [MPa]; None when no bin has edge contact."""
    share = np.nan_to_num(np.asarray(ds["edge_load_share"].values, float))
    if not np.any(share > 0.0):
        return None
    peak = np.nan_to_num(np.asarray(ds["pressure_max_edge"].values, float))
    i = int(np.argmax(share))
    # bins below EDGE_SHARE_MIN are no edge contact to the verdict: said apart, so that
    # the count agrees with the verdict's (a 9x40 at Σ 70°: "3 of 7 bins" here, "1 of 7"
    # in the verdict, two bins at < 0.05 %)
    found = int(np.sum(share >= EDGE_SHARE_MIN))
    trace = int(np.sum((share > 0) & (share < EDGE_SHARE_MIN)))
    below = f"below {100 * EDGE_SHARE_MIN:g} % of the torque, no finding"
    if not found:
        count = f"{below}, in {trace} of {share.size} bins"
    else:
        count = f"in {found} of {share.size} bins"
        if trace:
            count += f" ({trace} more {below})"
    return (f"edge contact {count} (up to "
            f"{share_percent(share[i])} % of the torque in bin {i}, edge peak pressure up to "
            f"{np.max(peak):.0f} MPa): edge pressures are NOT counted in the pitting damage "
            "(the ISO 6336-2 S-N curve is of Hertzian flank contact; the LTCA caps edges at "
            "the shakedown limit) — judge the edges by their own limit")
