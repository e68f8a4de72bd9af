"""The written drive profile one step hollower after a design-torque cut, where its LTE
misses the development's target above the load sharing's floor (issue 71: "``ltca
synthesize`` meets every development target on the drive flank").

Why a step of its own, at the end of the drive development: the hollow-target step
(:mod:`contact.optimize.development_hollow_target`) runs only on a profile not hollow yet
and before the design torque is cut. The FM spiral bevel 7x29 of
benchmarks/data/unseen_designs was given −5 µm there at 133.3 N·m, then cut to its local
pitting capacity and written at 4.7 / 31.7 N·m with drive LTE 33 / 41 µrad against the
target 40 (floor 21 µrad). On that written case, at ``ltca run``'s sampling (branch lte97,
docs/synthesis.md "The 13×33's hollow profile against the edge levers"): −6 µm reads 30.6
/ 39.9 µrad, every drive target met, tolerant at ±0.05 mm, flank peak 1600 MPa against
its local pitting limit 1606.4 MPa at 31.7 N·m; −7 / −8 µm 1613 / 1625 MPa, above it.

The step (:func:`checked_hollow_further`): gated by :func:`further_runs_on` (a cut made,
the written profile hollow, the written drive LTE above the target and the floor below
it), the written drive prescriptions with the profile crowning :data:`~contact.optimize.
development_hollow_limit.HOLLOW_STEP` (× the size scale) hollower, then twice that
(:data:`FURTHER_DESIGNS`), each written with the coast flank as written and analysed as
``ltca run`` reads the case (:func:`analysed_further`: one analysis per design, the same
as :func:`~contact.optimize.development_hollow_limit.hollow_probes`', whose reading the
``ltca synthesize`` line reuses); each kept by the check's one rule
(:func:`~contact.optimize.development_keep.kept_why`: ranks better, no met target lost,
tolerant at ΔE/ΔP ± 0.05 mm) with :func:`further_lost` added (no plastic, no edge at the
light torque, the flank peak within the local pitting limit at the design torque — the
torque is not cut again for it). The first kept meeting every target ends it.

Public names
------------
STAGE, FURTHER_DESIGNS, Further, further_runs_on, further_crownings, further_lost,
analysed_further, checked_hollow_further, lte_missed, probes_for
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from contact.compliance.fe.worker_cpu import cpu_seconds
from contact.optimize.development_hollow_limit import HOLLOW_STEP, HollowProbe
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets

__all__ = ["FURTHER_DESIGNS", "STAGE", "Further", "analysed_further", "checked_hollow_further",
           "further_crownings", "further_lost", "further_runs_on", "lte_missed", "probes_for"]

log = logging.getLogger("contact.optimize.development")

#: the stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "hollow further"

#: the step's designs at most: the profile crowning 1 and 2 × :data:`HOLLOW_STEP` (× the
#: size scale) hollower than written (the 7x29: −6 met every target, −7 read 1613 MPa
#: above its local pitting limit 1606.4 MPa; module docstring)
FURTHER_DESIGNS = 2


@dataclasses.dataclass(frozen=True)
class Further:
    """What :func:`checked_hollow_further` did.

    Attributes
    ----------
    best : DevelopmentEvaluation
        The drive design kept (the one given where none was).
    case : Case or None
        The kept design's case (both flanks, as written); None where none was kept.
    report : Any
        Its synthesis report; None where none was kept.
    values : dict or None
        Its drive prescriptions [file units]; None where none was kept.
    probes : tuple of HollowProbe
        The designs' readings (one analysis each), for the ``ltca synthesize`` line.
    floor : float — [µrad]
        The written case's load-sharing floor (NaN: not analysed).
    seconds : float — [s]
        CPU of the step.
    """

    best: DevelopmentEvaluation
    case: Any = None
    report: Any = None
    values: dict[str, float] | None = None
    probes: tuple[HollowProbe, ...] = ()
    floor: float = math.nan
    seconds: float = 0.0


def further_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets, cut: bool,
                    floor: float) -> bool:
    """The step's gate: the design torque was cut, ``best`` is checked at ``ltca run``'s
    sampling, its profile crowning is hollow (negative) already, its drive LTE p-p misses
    the target ``max_lte`` at either torque and the load sharing's ``floor`` is below the
    target (the bearing, not the contact ratio, misses it).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The written drive design (:func:`~contact.optimize.development_written_drive.
        written_drive_check`).
    targets : DevelopmentTargets
        The development's targets.
    cut : bool
        Whether the design torque was cut to a capacity.
    floor : float — [µrad]
        The written case's load-sharing floor (:func:`~contact.optimize.
        development_lte_floor.load_sharing_floor`); NaN: not known.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (module docstring).
    """
    if not (_gate_before_floor(best, targets, cut) and best.case is not None):
        return False
    return math.isfinite(floor) and floor < float(targets.max_lte)


def _gate_before_floor(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       cut: bool) -> bool:
    """:func:`further_runs_on`'s conditions that need no floor (a cut made, ``best``
    checked, its profile hollow, its LTE missed): the step asks for the floor's analysis
    only where they hold."""
    return (cut and best.checked_full
            and float(best.values.get("profile_crowning", 0.0)) < 0.0
            and lte_missed(best, targets))


def lte_missed(best: DevelopmentEvaluation, targets: DevelopmentTargets) -> bool:
    """Whether ``best``'s drive LTE p-p exceeds ``max_lte`` at either torque (light first)
    [µrad], within ``ltca run``'s verdict limit (above it other steps act)."""
    from contact.study.verdicts import LTE_LIMIT

    lte = np.asarray(best.metrics["lte_peak_to_peak"], float).ravel()
    worst = max(float(lte[0]), float(lte[-1]))
    return float(targets.max_lte) < worst <= LTE_LIMIT


def further_crownings(values: Mapping[str, float], scale: float) -> list[float]:
    """The step's profile crownings [µm]: the written one less 1, …,
    :data:`FURTHER_DESIGNS` × :data:`HOLLOW_STEP` × ``scale``, rounded to 0.1 nm.

    Parameters
    ----------
    values : mapping
        The written drive prescriptions [file units]; their ``profile_crowning`` [µm].
    scale : float — [1]
        The design's size scale (:meth:`BasicDesign.size_scale`).

    Returns
    -------
    list of float
        Shallowest first; empty where no crowning is given or ``scale`` is not positive.

    Raises
    ------
    Nothing.
    """
    if "profile_crowning" not in values or not (math.isfinite(scale) and scale > 0.0):
        return []
    own = float(values["profile_crowning"])
    return [round(own - k * HOLLOW_STEP * scale, 4) for k in range(1, FURTHER_DESIGNS + 1)]


def further_lost(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                 probe: HollowProbe) -> list[str]:
    """What the step's design ``e`` loses against ``best`` besides the targets: the met
    targets (:func:`~contact.optimize.development_keep.lost_targets`), a plastic share,
    edge contact at the light torque (:func:`~contact.optimize.development_light_edge.
    light_edge_lost`) and the flank peak above the local pitting limit at the design
    torque (``probe``, the same analysis).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The written design and the step's, scored at the same torques.
    probe : HollowProbe
        ``e``'s reading (flank peak and local pitting limit [MPa], plastic share [1]).

    Returns
    -------
    list of str
        Empty where nothing is lost.

    Raises
    ------
    Nothing.
    """
    from contact.optimize.development_keep import lost_targets
    from contact.optimize.development_light_edge import light_edge_lost

    out = lost_targets(best, e)
    if probe.plastic > 0.0:
        out.append(f"no plastic (plastic {100 * probe.plastic:.1f} %)")
    out += light_edge_lost(best, e)
    if not probe.flank_peak <= probe.pitting_limit:
        out.append(f"the local pitting limit (flank peak {probe.flank_peak:.1f} MPa above "
                   f"{probe.pitting_limit:.1f} MPa at the design torque)")
    return out


def analysed_further(case: Any, values: Mapping[str, float], crowning: float,
                     base: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any]
                     ) -> tuple[DevelopmentEvaluation, HollowProbe]:
    """One design of the step, its drive flank analysed as ``ltca run`` reads the written
    case (its sampling, :data:`~contact.optimize.development_evaluate.CHECK_LTCA`, the
    shell teeth of the case, the contact analysis alone) at the development's torques:
    scored on every target and read as a :class:`HollowProbe`, one analysis for both.

    Parameters
    ----------
    case : geometry.case.Case
        The design's case (both flanks, as written).
    values : mapping
        Its drive prescriptions [file units].
    crowning : float — [µm]
        Its profile crowning.
    base : DevelopmentEvaluation
        The written design (its other fields kept).
    targets : DevelopmentTargets
        The development's targets.
    setup : mapping
        ``torques`` (light, design) [N·m], ``centre_v`` [1].

    Returns
    -------
    (DevelopmentEvaluation, HollowProbe)

    Raises
    ------
    InputError, ValueError, KeyError, ArithmeticError
        From the analysis.

    Notes
    -----
    The analysis is :func:`~contact.optimize.development_hollow_limit.checked_contact`,
    the hollow probes' own.
    """
    from contact.optimize.development_evaluate import (
        KeptTeeth,
        grid_bounds,
        ltca_metrics,
        static_strength,
    )
    from contact.optimize.development_hollow_limit import checked_contact, probe_of
    from contact.optimize.development_pitting import pitting_pressure_limit
    from contact.optimize.development_targets import development_score

    c0 = cpu_seconds()
    light, design = (float(t) for t in setup["torques"])
    tree = checked_contact(case, values, (light, design), KeptTeeth())
    ltca = tree["/ltca"].to_dataset()
    static = static_strength(ltca)
    ms = ltca_metrics(ltca, case)
    grid = grid_bounds(ltca)
    full = development_score(ms, targets, grid[:4], centre_v=setup["centre_v"],
                             pressure_limit=static)
    probe = probe_of(ltca, case, crowning, pitting_pressure_limit(case, design), static)
    e = dataclasses.replace(base, values=dict(values), metrics=ms, objective=full[0],
                            shortfalls=full[1], met=full[2], full=full, case=case,
                            checked=True, stage=STAGE,
                            seconds=cpu_seconds() - c0)
    return e, probe


def checked_hollow_further(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                           setup: Mapping[str, Any], teeth: Any,
                           say: Callable[[str], None], *, cut: bool, scale: float,
                           floor: Callable[[], float],
                           write: Callable[[Mapping[str, float]], tuple[Any, Any]]
                           ) -> Further:
    """The step (module docstring): the written drive profile 1, then 2 ×
    :data:`HOLLOW_STEP` (× ``scale``) hollower where :func:`further_runs_on`, each written
    and analysed once (:func:`analysed_further`), kept by the check's rule with
    :func:`further_lost`.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The written drive design, read on the written case.
    targets : DevelopmentTargets
        The development's targets.
    setup : mapping
        The development's state (``torques`` as written [N·m], ``centre_v``).
    teeth : KeptTeeth or None
        The kept shell teeth (the tolerance's analyses).
    say : callable str → None
        Where the lines go.
    cut : bool
        Whether the design torque was cut to a capacity (the gate).
    scale : float — [1]
        The size scale.
    floor : callable () → float
        The written case's load-sharing floor [µrad] (one analysis; asked only where the
        rest of the gate holds).
    write : callable values → (Case, report)
        The written basic design with these drive prescriptions, synthesised as written.

    Returns
    -------
    Further
        ``best`` with no case where the gate does not hold or nothing is kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Cost on the 7x29: the floor's analysis and one synthesis and analysis per design
    (docs/synthesis.md, "The 7×29's hollow profile one step further"). Source of the lever:
    Stadtfeld, *Gleason Bevel Gear Technology*, 2014 (profile crowning); Litvin & Fuentes,
    *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4.
    """
    from contact.optimize.development_keep import kept_why
    from geometry.core.errors import InputError

    c0 = cpu_seconds()
    if not _gate_before_floor(best, targets, cut):
        return Further(best)
    low = float(floor())
    if not further_runs_on(best, targets, cut, low):
        return Further(best, floor=low, seconds=cpu_seconds() - c0)
    lte = np.asarray(best.metrics["lte_peak_to_peak"], float).ravel()
    why = (f"its LTE {lte[0]:.1f}/{lte[-1]:.1f} urad against {targets.max_lte:g} above the "
           f"load sharing's floor {low:.0f} urad, after the design torque was cut")
    start, kept = best, Further(best)
    probes: list[HollowProbe] = []
    for c in further_crownings(best.values, scale):
        values = dict(start.values) | {"profile_crowning": c}
        try:
            case, report = write(values)
            e, probe = analysed_further(case, values, c, start, targets, setup)
        except (InputError, ValueError, KeyError, ArithmeticError) as exc:
            log.info("development: the profile crowning %g um not analysed: %s", c, exc)
            continue
        probes.append(probe)
        missed = sorted(k for k, v in e.full[1].items() if v > 0.0)
        say(f"  design {start.index + 1} with profile_crowning {c:g} (the hollow profile "
            f"one step further; {why}), at the default sampling: LTE "
            f"{probe.lte[0]:.1f}/{probe.lte[1]:.1f} urad, edge "
            f"{100 * probe.edge_share:.1f} %, plastic {100 * probe.plastic:.1f} %, flank "
            f"peak {probe.flank_peak:.1f} MPa (local pitting limit "
            f"{probe.pitting_limit:.1f}), "
            + ("every target met" if e.met else "missed: " + ", ".join(missed)))
        if not kept_why(kept.best, e, targets, setup, teeth, say,
                        "the hollow profile one step further",
                        lost=lambda b, x, p=probe: further_lost(b, x, p)):
            kept = Further(e, case, report, values)
            if e.met:
                break
    seconds = cpu_seconds() - c0
    if kept.case is None:
        say(f"development: the hollow profile one step further kept nothing "
            f"[{seconds:.1f} s CPU]")
        return Further(best, probes=tuple(probes), floor=low, seconds=seconds)
    say(f"development: the profile crowning {start.values['profile_crowning']:g} -> "
        f"{kept.values['profile_crowning']:g} um kept (the hollow profile one step "
        f"further at {float(setup['torques'][1]):g} N m) [{seconds:.1f} s CPU]")
    return dataclasses.replace(kept, probes=tuple(probes), floor=math.nan, seconds=seconds)


def probes_for(probes: Sequence[HollowProbe], crownings: Sequence[float]
               ) -> dict[float, HollowProbe]:
    """The step's readings among ``crownings`` [µm], by crowning (0.1 nm apart at most)."""
    return {c: p for c in crownings for p in probes if abs(p.crowning - c) <= 1e-4}
