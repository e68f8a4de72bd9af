"""The coast design torque no higher than where the written coast bearing keeps its LTE
within the verdict's limit at every torque (issue 71: "LTE p-p ≤ 60 µrad at every torque",
both flanks).

The coast steps (:mod:`~contact.optimize.development_coast_steps`: ellipse, path, tip
relief start, TE level, reliefs; :mod:`~contact.optimize.development_coast_capacity_lte`:
the peak allowed up to the static strength; the coast edge steps) vary the coast bearing
where its LTE exceeds 60 µrad; the coast capacity search
(:func:`~contact.optimize.development_coast_flank.coast_flank_capacity`) lowers the coast
design torque for the flank's static strength, plastic segments, root stress and local
pitting safety, but not for its LTE. :func:`~contact.optimize.
development_coast_capacity_lte.coast_torque_that_holds` lowers it for the LTE only where
that step kept a bearing (or its LTE FAILs the verdict, above 2 × 60 µrad), so a coast
flank whose every bearing step was refused, at an LTE between 60 and 120 µrad, was
written with an LTE the verdict flags at its own design torque, while the drive's design
torque is written no higher than where the drive keeps 60 µrad at the verdict's limit
itself (:func:`~contact.optimize.development_written_lte.written_lte_capacity`).

:func:`coast_lte_torque` is that rule on the coast flank, after every coast step: where
the written coast bearing's LTE p-p over ``ltca run --flank coast``'s ``lte_range``
torques (:func:`~contact.optimize.development_range_lte.range_lte`, the crossing
bisected) exceeds 60 µrad and its light torque keeps it, the coast design torque is
lowered to the torque up to which it keeps it (:func:`~contact.study.lte_within.
within_torque`, linear between the torques analysed), the coast capacity searched from
there (every criterion: it may lower it further) and kept only where the LTE over the
lowered torques' own range keeps the limit at every torque. The bearing is not changed
(no step runs again) and the drive flank is not touched. The coast light torque is the
same share of the coast design torque as the drive's of the design torque
(:func:`contact.pipeline.flank_torques`), so a lower coast design torque lowers it too:
where the light torque's LTE exceeds the limit already, or the lowered light torque's
does, no lower torque is tried (as the drive's rule). The coast design torque is not
lowered below :data:`~contact.optimize.development_process.TORQUE_CUT_FRACTION` (½) of the
coast design torque it had, nor below the drive's light torque (a coast design torque cut
below it is a failed outcome, :func:`~contact.optimize.development_process.
failed_outcome`): a cut deeper than half for an LTE the verdict calls an attention is not a
design torque a reverse gear or an e-axle's regeneration lives with (the lead's gate on
branch coastlte77: the FH spiral bevel 20x24 at Σ 100° keeps 603.3 N·m, coast 61 / 104
µrad, rather than 169.4 N·m, 28 % of it); there the LTE is said with the torque it would
need and the face-width remedy of the contact-ratio note is the lever. Nor is a torque
kept where the coast bearing's counted edges peak above the static strength there and
higher than at the coast design torque before (the 20x24's 2488 MPa at 169.4 N·m). A
design torque or coast design torque the basic file gives is kept (as the drive's rule
keeps a given design torque).

Public names
------------
coast_lte_torque, lte_torque_reason, LTE_TRIES
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any

from contact.optimize.development_coast import CoastCapacity
from contact.optimize.development_coast_flank import coast_flank_capacity
from contact.optimize.development_evaluate import KeptTeeth, bearing_key
from contact.optimize.development_process import TORQUE_CUT_FRACTION
from contact.optimize.development_range_lte import development_lte_limit, range_lte
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_written_lte import lowered_torque
from geometry.case import Case
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import BasicDesign

log = logging.getLogger("contact.optimize.development")

__all__ = ["LTE_TRIES", "coast_lte_torque", "lte_torque_reason"]

#: lowered coast design torques analysed at most (as the drive's
#: :func:`~contact.optimize.development_written_lte.written_lte_capacity` and the coast's
#: :func:`~contact.optimize.development_coast_capacity_lte.coast_torque_for_lte`)
LTE_TRIES = 3


def _curve(found: tuple[tuple[float, ...], tuple[float, ...]]) -> str:
    """``"a / b / c urad at t1 / t2 / t3 N m"`` of a range (torques [N·m], LTE [µrad])."""
    return (f"{' / '.join(f'{x:.1f}' for x in found[1])} urad at "
            f"{' / '.join(plain_number(t) for t in found[0])} N m")


def lte_torque_reason(before: tuple[tuple[float, ...], tuple[float, ...]],
                      there: tuple[tuple[float, ...], tuple[float, ...]],
                      design: float, torque: float, limit: float) -> str:
    """The reason :func:`coast_lte_torque` writes for a coast design torque it lowered.

    Parameters
    ----------
    before : (tuple of float, tuple of float) — [N·m], [µrad]
        The written coast bearing's LTE p-p over ``ltca run --flank coast``'s range at the
        coast design torque before.
    there : (tuple of float, tuple of float) — [N·m], [µrad]
        The same at the lowered coast design torque.
    design : float — [N·m]
        The coast design torque before.
    torque : float — [N·m]
        The lowered coast design torque.
    limit : float — [µrad]
        The verdict's LTE limit.

    Returns
    -------
    str
        What the coast flank could not hold and where it holds, with the numbers.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s verdict (:data:`contact.study.verdicts.LTE_LIMIT`), issue 71.
    """
    return (f"the torque up to which the written coast bearing keeps its LTE within "
            f"{limit:g} urad at every torque: at {plain_number(design)} N m its LTE p-p "
            f"was {_curve(before)} after every coast step (none of its bearing steps kept "
            f"{limit:g} urad there); {_curve(there)} at the coast design torque "
            f"{plain_number(torque)} N m")


def coast_lte_torque(case: Case, basic: BasicDesign, coast: Any, cap: CoastCapacity | None,
                     drive: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: dict[str, Any], teeth: KeptTeeth | None, root_stress: bool,
                     say: Callable[[str], None], *, own_torque: bool = False
                     ) -> tuple[Any, CoastCapacity | None]:
    """The written coast flank at a coast design torque no higher than where its LTE p-p
    keeps the development's aim at every torque ``ltca run --flank coast`` judges (the
    verdict's limit less the sampling margin,
    :func:`~contact.optimize.development_range_lte.development_lte_limit`; off by default:
    the verdict's 60 µrad).

    Parameters
    ----------
    case : Case
        The case written (both flanks), as the coast capacity search analyses it.
    basic : BasicDesign
        The basic file as given (its ``operating`` and ``rating`` tables).
    coast : NamedTuple
        The coast outcome after every coast step (its ``best`` checked at its ``torques``
        [N·m], light and coast design torque; ``metrics["lte_peak_to_peak"]`` [µrad]).
    cap : CoastCapacity or None
        The coast capacity written so far (None: the coast design torque is the drive's
        design torque, not searched).
    drive : DevelopmentEvaluation
        The drive design written (its bearing keys the kept pinion teeth).
    targets : DevelopmentTargets
        The development's targets (``coast_max_evaluations`` 0: the coast development is
        off and nothing is done).
    setup : dict
        The development's setup (its range analyses are kept in it).
    teeth : KeptTeeth or None
        The kept shell teeth.
    root_stress : bool
        The capacity search checks S_F,FE and S_H,loc (``ltca run``'s FE root stress and
        rating).
    say : callable str → None
        Where the lines go.
    own_torque : bool, optional
        The design torque ``basic`` gives is the development's own, not the basic file's
        (the drive developed again in its LTE window, ``develop``'s ``torque_name``): not
        kept as a given one. Default False.

    Returns
    -------
    (outcome, CoastCapacity or None)
        The coast outcome and capacity at the lowered coast design torque (its metrics and
        torques the capacity search's check there, its reason :func:`lte_torque_reason`
        after ``cap``'s) where one keeps the limit over its own range; else ``coast`` and
        ``cap`` as given.

    Raises
    ------
    Nothing: a failed analysis leaves the coast flank as it was (logged or said).

    Notes
    -----
    Why: the coast flank carries the full torque in reverse gear and ``ltca run --flank
    coast`` judges its LTE at its own torques; where no bearing step keeps 60 µrad at
    the coast design torque, that torque is the one the coast flank cannot hold. Measured
    (``ltca synthesize``, 2026-11-29, branch coastlte99): the FM spiral bevel 13x17 at
    Σ 50° of benchmarks/data/unseen_designs (ε_vβ 0.70) wrote its coast flank at the
    drive's 122.7 N m with LTE p-p 56 / 90 µrad (79.6 at 87.9 N m between), its coast
    steps' designs at 94-135 µrad there. Source: ``ltca run``'s ``lte`` check and
    ``lte_range`` step (:mod:`contact.ltca.lte_range`), issue 71's Done-when; the
    crossing as the drive's (:func:`~contact.optimize.development_written_lte.
    written_lte_capacity`).
    """
    limit = development_lte_limit()  # the verdict's 60 µrad less the sampling margin

    e = coast.best if coast is not None else None
    if (e is None or not e.checked_full or len(coast.torques) != 2
            or targets.coast_max_evaluations == 0):
        return coast, cap
    key = (*bearing_key(drive.values), "coast")
    light, design = (float(t) for t in coast.torques)
    before = range_lte(e, dict(setup, torques=[light, design]), teeth, flank="coast",
                       key_prefix=key)
    if before is None or not max(before[1]) > limit:
        return coast, cap
    if basic is not None and ((basic.gives_design_torque and not own_torque)
                              or basic.rating.get("coast_design_torque") is not None):
        say(f"development: the written coast LTE p-p {_curve(before)}, above "
            f"{limit:g} urad; the design torque the basic file gives is kept")
        return coast, cap
    seen = dict(zip(before[0], before[1], strict=True))
    # never below half the coast design torque (a cut, development_process) nor the
    # drive's light torque (a failed outcome)
    floor = max(float(setup.get("torques", (light,))[0]), TORQUE_CUT_FRACTION * design)
    edge_before = (float(cap.final.edge_peak) if cap is not None and cap.final is not None
                   else math.nan)
    crossing = math.nan
    tried: list[str] = []
    # a coast root check refined on the default FE model at a torque not kept says
    # nothing of the torque written (coast_flank_capacity records it in the setup)
    fe_why = setup.get("fe_level_why")
    for _ in range(LTE_TRIES):
        ts = sorted(seen)
        new = lowered_torque(ts, [seen[t] for t in ts], limit, design)
        if not (math.isfinite(new) and new > floor):
            crossing = new  # the light torque above the limit already, or a deep cut
            break
        again, there = coast_flank_capacity(case, basic, coast, targets, setup, new,
                                            root_stress, True, say)
        if (there is None or not there.holds or again.best is None
                or len(again.torques) != 2 or not float(again.torques[1]) > floor):
            break
        edge = float(there.final.edge_peak) if there.final is not None else math.nan
        if (math.isfinite(edge) and edge > float(there.final.limit)
                and not edge <= edge_before):
            tried.append(f"at {plain_number(there.torque)} N m its edges peak {edge:.0f} MPa, "
                         f"above the static strength {float(there.final.limit):.0f} MPa")
            break
        at = [float(t) for t in again.torques]
        found = range_lte(again.best, dict(setup, torques=at), teeth, flank="coast",
                          key_prefix=key)
        if found is None:
            break
        if not max(found[1]) > limit:
            reason = lte_torque_reason(before, found, design, at[1], limit)
            say(f"development: coast design torque {plain_number(design)} -> "
                f"{plain_number(at[1])} N m: {reason}")
            prior = (cap.reason + "; ") if cap is not None and cap.reason else ""
            if there.reason:
                reason = f"{reason}; {there.reason}"
            return again, CoastCapacity(
                float(at[1]), cap.start if cap is not None else design,
                (cap.checks if cap is not None else ()) + tuple(there.checks),
                prior + reason, True)
        tried.append(f"at {plain_number(at[1])} N m {_curve(found)}")
        seen.update(zip(found[0], found[1], strict=True))
        if found[1][0] > limit:  # the lowered light torque above the limit already
            break
    if fe_why is None:
        setup.pop("fe_level_why", None)
    else:
        setup["fe_level_why"] = fe_why
    say(f"development: the written coast LTE p-p {_curve(before)}, above {limit:g} "
        f"urad: no coast design torque below {plain_number(design)} N m found where it "
        f"keeps it at every torque" + _why_not(tried, before, crossing, design, floor))
    return coast, cap


def _why_not(tried: list[str], before: tuple[tuple[float, ...], tuple[float, ...]],
             crossing: float, design: float, floor: float) -> str:
    """The clause of :func:`coast_lte_torque`'s line where it lowers nothing: the
    torques tried, the light torque's LTE above the limit, or the crossing below the
    floor (half the coast design torque or the drive's light torque) [N·m]."""
    limit = development_lte_limit()  # the verdict's 60 µrad less the sampling margin

    if tried:
        return f" (tried {'; '.join(tried)})"
    if before[1][0] > limit:
        return " (its light torque's above it already)"
    if math.isfinite(crossing):
        bound = (f"{TORQUE_CUT_FRACTION:g} of it" if floor <= TORQUE_CUT_FRACTION * design
                 else "the drive's light torque")
        return (f" at or above {plain_number(floor)} N m: it keeps {limit:g} urad up to "
                f"{plain_number(crossing)} N m only, {crossing / design:.0%} of "
                f"{plain_number(design)} N m, and a coast design torque is not cut below "
                f"{bound} for an LTE the verdict calls an attention; "
                "the coast flank cannot hold its LTE at its design torque on this bearing "
                "(the contact ratio's remedy, if offered, is the lever)")
    return ""
