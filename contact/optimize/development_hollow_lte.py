"""A slightly hollow pinion profile, the reliefs rebalanced, for a drive LTE the other
check steps left above the verdict's limit over the torques (issue 71: "LTE p-p ≤ 60 µrad
at every torque").

The check's LTE steps shape the bearing along the face (the ellipse, the path) and the
relief's depth; they leave the profile's own curvature at the search's crowning (≥ 0: a
crowned profile, which shortens the pattern in depth). On a spiral bevel whose face contact
ratio is low (ε_vβ 1.16) the LTE from the middle to the design torque is that of the
stiffness's swing as a second and third pair take load and leave it, and no ellipse, path,
TE parabola or lighter relief brought its peak below 62 µrad (docs/synthesis.md, "The drive
LTE over the torques: the hollow profile"). A profile a few micrometres hollow (negative
``profile_crowning``: the blade's profile curvature, the normal ease-off at ±m_mn of blade
height from M) spreads each pair's loaded contact over more of the depth, so that the
entering and leaving pairs share the load earlier and the mesh stiffness swings less
(loaded pairs at the design torque 2.30 → 2.35); the relief must then end nearer the
tooth's ends: the tip relief started :data:`START_EARLIER` earlier and deeper
(:data:`TIP_FACTOR`), the root relief from :data:`START_EARLIER` earlier and shallower
(:data:`ROOT_FACTOR`), the blade turned by :data:`BLADE_STEP` to hold the pattern's height.

Measured (``benchmarks/development_levers.py --check --tolerance --at``, ``ltca run``'s
sampling, 2026-11-28, branch lte84) on the FM spiral bevel 14x36 at Σ 70° of
benchmarks/data/unseen_designs (generated gear; path −75°, ellipse 0.75, tip relief 10 µm
from 0.9, root relief 60 µm from 0.2, TE 10 µrad; LTE p-p 17 / 60 / 72 / 69 µrad at 55.6 /
160.8 / 266 / 371.2 N m): with tip relief 15 µm from 0.85, root relief 45 µm from 0.15 and
the blade −0.02°: no crowning 16 / 53 / 77 / 74; crowning −4 / −5 / −6 µm: 14 / 57 / 61 / 55,
14 / 59 / 59 / 52, 15 / 61 / 57 / 50 µrad, centre v 0.63 / 0.62 / 0.63, edge 0.8 / 0.9 /
1.1 %, no plastic segment, the pattern 0.70 long (0.60 before), tolerant at ΔE/ΔP ± 0.05 mm
(−6 µm: 0.1 % plastic at ΔE +0.05 mm). A deeper hollow (−10 to −20 µm) lowers the design
torque's LTE further (38 µrad at −20) but raises the light torque's (83 µrad) and the
pattern's centre.

Not for the development's own LTE target (40 µrad) alone: on the face-hobbed hypoid 9x39 at
Σ 95° of benchmarks/data/unseen_designs (ε_vα 0.94; LTE 38 / 44 µrad at 42.9 / 286 N m,
within 60 over the torques) the hollow profile with the tip relief deeper alone (−5 / −3 µm,
tip relief 13.9 → 20.9 µm) met every target in ``benchmarks/development_levers.py`` (LTE 34 /
37 and 36 / 38 µrad, edge 1.4 / 1.1 %), but tried here it read edge 2.4 / 2.1 % (above 2 %)
and was refused, and the rebalanced designs lost the tip clearance and the edge target; on
the hypoid 13x39 at Σ 85° (48 µrad against 40) both lose the centre v (docs/synthesis.md).
The step acts on the verdict's limit only. The 1 % was two designs, not two readings: the
bench varied the written design, whose root relief the edge-peak step (after this one) had
deepened 9.55 → 15 µm; the recipe is tried there, by
:mod:`contact.optimize.development_hollow_target` (branch edge85).

Public names
------------
HOLLOW_CROWNING, START_EARLIER, TIP_FACTOR, ROOT_FACTOR, BLADE_STEP, STAGE,
hollow_runs_on, hollow_designs, checked_hollow_lte
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why
from contact.optimize.development_range_lte import (
    development_lte_limit,
    kept_range_said,
    range_better,
    range_lost,
    range_lte,
    range_peak,
)
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import VARIABLES, DevelopmentTargets
from contact.optimize.development_variant import changed_values, said_variant
from geometry.case import Case
from geometry.core.text import plain_number

__all__ = ["BLADE_STEP", "HOLLOW_CROWNING", "ROOT_FACTOR", "STAGE", "START_EARLIER",
           "TIP_FACTOR", "checked_hollow_lte", "hollow_designs", "hollow_runs_on"]

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "hollow lte"

#: [µm at a mean normal module of 3 mm and above; × the development's size scale] the
#: profile crowning of the step's designs, tried in turn (negative: hollow); on the 14x36
#: −5 µm kept the limit over the torques (59 µrad), −4 and −6 µm 61 µrad (module docstring)
HOLLOW_CROWNING = (-5.0, -4.0, -6.0)

#: [1] how much earlier (of the way from M to each end) both reliefs start
START_EARLIER = 0.05

#: [1] the tip relief's depth × this (10 → 15 µm on the 14x36)
TIP_FACTOR = 1.5

#: [1] the root relief's depth × this (60 → 45 µm on the 14x36)
ROOT_FACTOR = 0.75

#: [deg] the blade-angle change added (−0.01° left the 14x36's centre v at 0.63, above its
#: band's 0.629; −0.02° and −0.03°: 0.62)
BLADE_STEP = -0.02

_NAMES = ("profile_crowning", "tip_relief", "root_relief", "relief_start",
          "tip_relief_start", "blade_angle_change")


def hollow_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                   setup: Mapping[str, Any], teeth: KeptTeeth | None) -> bool:
    """The step's gate: ``best`` is checked, its prescriptions carry every input the step
    changes (the profile crowning not already hollow), it misses no target but its LTE
    (and the pattern's length), and its largest drive LTE p-p over ``ltca run``'s
    ``lte_range`` torques exceeds the verdict's limit
    (:func:`~contact.optimize.development_range_lte.range_lte`, memoised; asked last).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept (checked at ``ltca run``'s sampling).
    targets : DevelopmentTargets
        The development's targets (``variables``).
    setup : mapping
        The development's state (``torques`` [N·m], light and design).
    teeth : KeptTeeth or None
        The kept shell teeth.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque"); the verdict's limit
    :data:`contact.study.verdicts.LTE_LIMIT`.
    """
    if not best.checked_full or best.case is None or best.metrics is None:
        return False
    if not all(n in best.values for n in _NAMES):
        return False
    if float(best.values["profile_crowning"]) < 0.0:
        return False
    if any(v > 0.0 for k, v in best.full[1].items() if k not in ("lte", "length")):
        return False
    peak = range_peak(range_lte(best, setup, teeth))[0]
    return math.isfinite(peak) and peak > development_lte_limit()


def hollow_designs(values: Mapping[str, float], targets: DevelopmentTargets
                   ) -> list[dict[str, float]]:
    """The step's designs from a design's prescriptions: for each of
    :data:`HOLLOW_CROWNING` (× the size scale of ``targets``' crowning bound against
    :data:`~contact.optimize.development_targets.VARIABLES`'), that profile crowning, the
    tip relief × :data:`TIP_FACTOR` and the root relief × :data:`ROOT_FACTOR` (each within
    the upper bound of its ``targets`` variable), both reliefs' starts
    :data:`START_EARLIER` earlier (not below 0) and the blade angle changed by
    :data:`BLADE_STEP`.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units: µm, deg, 1].
    targets : DevelopmentTargets
        The development's bounds (``variables``; the size scale read from the crowning's).

    Returns
    -------
    list of dict
        The designs' prescriptions [file units]; empty where an input is not given.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the lever measured on the spiral bevel 14x36 at Σ 70° (module docstring).
    The crowning and the relief starts go outside the search's box (crowning ≥ 0, relief
    start ≥ 0.2) on purpose: the box is the bearing search's, where a hollow profile
    lengthens the pattern in depth against its target.
    """
    if not all(n in values for n in _NAMES):
        return []
    bound = targets.variables.get("profile_crowning", VARIABLES["profile_crowning"])
    scale = float(bound[1]) / float(VARIABLES["profile_crowning"][1])
    tip_hi = float(targets.variables.get("tip_relief", (0.0, math.inf))[1])
    root_hi = float(targets.variables.get("root_relief", (0.0, math.inf))[1])
    common = {
        "tip_relief": round(min(TIP_FACTOR * float(values["tip_relief"]), tip_hi), 4),
        "root_relief": round(min(ROOT_FACTOR * float(values["root_relief"]), root_hi), 4),
        "relief_start": round(max(float(values["relief_start"]) - START_EARLIER, 0.0), 4),
        "tip_relief_start": round(max(float(values["tip_relief_start"]) - START_EARLIER,
                                      0.0), 4),
        "blade_angle_change": round(float(values["blade_angle_change"]) + BLADE_STEP, 4),
    }
    return [dict(values) | common | {"profile_crowning": round(c * scale, 4)}
            for c in HOLLOW_CROWNING]


def checked_hollow_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       setup: Mapping[str, Any], teeth: KeptTeeth | None,
                       say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case]
                       ) -> DevelopmentEvaluation:
    """The check's last step: a design whose drive LTE over ``ltca run``'s ``lte_range``
    torques is still above the verdict's limit and that misses nothing else but the
    development's LTE target and the pattern's length (:func:`hollow_runs_on`) given a
    slightly hollow profile with the reliefs rebalanced (:func:`hollow_designs`, at most
    three designs, each the blade of step 7 placed and checked at ``ltca run``'s sampling
    and analysed over the range), each kept by the check's one rule with ``better`` judged
    on its largest LTE over the range (:func:`~contact.optimize.development_range_lte.
    range_better`), no met target lost (the pattern's length apart where its LTE over the
    range keeps the limit: :func:`~contact.optimize.development_range_lte.range_lost`) and
    tolerant at the mounting excursions; the first kept within the limit over the range
    ends it.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept last (its ``stage`` :data:`STAGE`), its LTE over the range
        recorded (:func:`~contact.optimize.development_range_lte.recorded_range`); ``best``
        itself where the gate does not hold or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: the loaded TE of a pair of low contact ratios follows the mesh stiffness's swing
    as pairs enter and leave; a profile eased off less towards its ends in depth (hollow)
    lets the entering pair carry load earlier (the profile modification sized to the load,
    Stadtfeld, *Gleason Bevel Gear Technology*, 2014; Litvin & Fuentes, *Gear Geometry and
    Applied Theory*, 2nd ed., 2004, §9.4 on the TE's shape under load). Measured in the
    module docstring. Cost on a design the gate passes: at most three checked designs (no
    new synthesis of steps 3–6: the crowning, the blade change and the relief act after
    them), their analyses over the range and the mounting excursions of those that rank
    better.
    """
    if not hollow_runs_on(best, targets, setup, teeth):
        return best
    limit = development_lte_limit()
    better = range_better(setup, teeth, limit)
    lost = range_lost(setup, teeth, limit)
    start = best
    peak, at = range_peak(range_lte(start, setup, teeth))
    why = f"its LTE {peak:.0f} urad at {plain_number(at)} N m above {limit:g}"
    for values in hollow_designs(start.values, targets):
        e = said_variant(start, values, STAGE, f"with {changed_values(values, start.values)} "
                         f"(the hollow profile, the reliefs rebalanced; {why})",
                         targets, setup, teeth, say, placed)
        if e is None:
            continue
        if not kept_why(best, e, targets, setup, teeth, say, "the hollow profile",
                        better=better, lost=lost):
            best = e
            if range_peak(range_lte(best, setup, teeth))[0] <= limit:
                break
    kept_range_said(setup, start, best, teeth, say, "the hollow profile")
    return best
