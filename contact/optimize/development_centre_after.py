"""The check's steps again on the drive design the edge-peak step left, and a pattern
still high lowered by both reliefs at once (issue 71, "``ltca synthesize`` meets every
development target on the drive flank", branch len99).

The check's steps (:func:`~contact.optimize.development_check.check_steps`) run before the
edge-peak step (:func:`~contact.optimize.development_edge_peak.checked_edge_peak`); the
relief that step gives an edge changes what those steps can do: a design refused for its
tolerance before may be tolerant on the deeper relief, and a design that missed the edge
target (outside the near-miss step's margin) becomes a near miss on its pattern.
:func:`checked_after_edge_peak` runs them again there and keeps their design only where it
meets every target; where it misses the centre v alone, :func:`height_by_reliefs` moves
the tip and the root relief together (each alone is barred or refused on such a design).

Measured (``ltca synthesize -v``, 2026-11-29; docs/synthesis.md, "The check's steps again
after the edge-peak step, and the height by both reliefs"): the FM hypoid 9x35 at Σ 88° of
benchmarks/data/unseen_designs — its path step (−80°: centre v 0.63, LTE 23 / 30 µrad)
refused in the check for the edge at ΔE +0.05 mm, tolerant on the edge-peak step's root
relief 15.25 µm, then the length step's ellipse 0.583: every drive target (v 0.62 against
0.541 ± 0.08, LTE 30 / 38 µrad), 385.8 N m kept; the FM hypoid 12x31 at a 0.20 d_e2 — the
steps again end on the ellipse 0.575 (0.60 long, v 0.65, not tolerant), both reliefs then
(tip relief 18 µm from 0.9, root relief 22.5 µm, ``te_level`` 25): every drive target (v
0.619 against 0.540 ± 0.08, LTE 30 / 36 µrad, tolerant), 677.1 N m kept (S_F,FE 1.31).
Kept by rank instead, the 12x31's steps-again design cut its torque to 663 N m.

Public names
------------
AFTER_TARGETS, STAGE, after_runs_on, height_by_reliefs, relief_designs,
checked_after_edge_peak
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_height_steps import TIP_FRACTIONS
from contact.optimize.development_pattern_steps import NEAR_MISS_TE_STEP
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import footprint_centre_v
from contact.optimize.development_targets import TE_NAME, DevelopmentTargets
from contact.optimize.development_tolerance import (
    TOLERANCE_RELIEF,
    TOLERANCE_RELIEF_STEP,
    tolerant_variant,
)
from contact.optimize.development_variant import changed_values, said_variant
from geometry.case import Case

__all__ = ["AFTER_TARGETS", "STAGE", "after_runs_on", "checked_after_edge_peak",
           "height_by_reliefs", "relief_designs"]

#: the stage of the reliefs' designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "height by the reliefs"

#: the targets the design after the edge-peak step may miss for the check's steps to run
#: again on it: the light-load pattern's length and height and the LTE (those steps'
#: own targets); a design missing any other (an edge, a clearance, plastic) is left as
#: the edge-peak step wrote it
AFTER_TARGETS = frozenset({"length", "centre_v", "lte"})


def after_runs_on(before: DevelopmentEvaluation, after: DevelopmentEvaluation,
                  targets: DevelopmentTargets) -> bool:
    """Whether the check's steps run again on ``after``: the edge-peak step changed the
    design (``after`` is not ``before``), ``after`` was checked at ``ltca run``'s sampling
    and misses a target, every one it misses among :data:`AFTER_TARGETS`.

    Parameters
    ----------
    before, after : DevelopmentEvaluation
        The drive design before and after the edge-peak step.
    targets : DevelopmentTargets
        The development's targets (unused but for the signature every gate has).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.
    """
    del targets
    if after is before or not after.checked_full or bool(after.full[2]):
        return False
    missed = {k for k, v in after.full[1].items() if v > 0.0}
    return bool(missed) and missed <= AFTER_TARGETS


def relief_designs(values: Mapping[str, float], targets: DevelopmentTargets
                   ) -> list[dict[str, float]]:
    """The designs :func:`height_by_reliefs` tries from a design's prescriptions, in turn:
    the tip relief shortened to the tip step's first fraction (:data:`~contact.optimize.
    development_height_steps.TIP_FRACTIONS`) from the upper bound of ``tip_relief_start``,
    with the root relief raised as the tolerance step raises it (× :data:`~contact.
    optimize.development_tolerance.TOLERANCE_RELIEF`, by at least :data:`~contact.optimize.
    development_tolerance.TOLERANCE_RELIEF_STEP` µm × the size scale), each within its
    bounds; first with ``te_level`` lowered by the near-miss step's :data:`~contact.
    optimize.development_pattern_steps.NEAR_MISS_TE_STEP` (within its bounds, where
    developed), then without.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units: µm, 1, µrad].
    targets : DevelopmentTargets
        The development's bounds (``variables``) and ``size_scale``.

    Returns
    -------
    list of dict
        The designs' prescriptions; empty where a relief is not developed or neither
        relief would change.

    Raises
    ------
    Nothing: a pure function of its inputs.

    Notes
    -----
    Source: the FM hypoid 12x31 at a 0.20 d_e2 (module docstring of
    :func:`height_by_reliefs`).
    """
    names = ("tip_relief", "tip_relief_start", "root_relief")
    if not all(n in targets.variables and n in values for n in names):
        return []
    (t_lo, t_hi), (_, s_hi), (r_lo, r_hi) = (
        (float(a), float(b)) for a, b in (targets.variables[n] for n in names))
    root0 = float(values["root_relief"])
    tip = round(float(np.clip(TIP_FRACTIONS[0] * float(values["tip_relief"]), t_lo, t_hi)), 4)
    root = round(float(np.clip(max(TOLERANCE_RELIEF * root0,
                                   root0 + TOLERANCE_RELIEF_STEP * targets.size_scale),
                               r_lo, r_hi)), 4)
    relieved = dict(values) | {"tip_relief": tip, "tip_relief_start": s_hi,
                               "root_relief": root}
    if all(relieved[n] == float(values[n]) for n in names):
        return []
    out = [relieved]
    if TE_NAME in targets.variables and TE_NAME in values:
        te0 = float(values[TE_NAME])
        te = max(float(targets.variables[TE_NAME][0]), te0 - NEAR_MISS_TE_STEP)
        if te < te0 - 1e-9:
            out.insert(0, relieved | {TE_NAME: te})
    return out


def height_by_reliefs(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: Mapping[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case]
                      ) -> DevelopmentEvaluation | None:
    """A design whose light-load pattern is above its depth centre and which misses that
    alone, lowered by both reliefs at once (:func:`relief_designs`, at most two designs,
    each placed as written and checked at ``ltca run``'s sampling): the first that meets
    every target and is tolerant at the mounting excursions, else None.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps ended on after the edge-peak step (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).

    Returns
    -------
    DevelopmentEvaluation or None

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why both together: each of the check's height levers alone is barred or refused on such
    a design. The tip step (a shorter tip relief started later) is barred where the edge
    share at the design torque exceeds half its limit; the tolerance step raises a relief
    only on a design meeting every target; the blade step costs the LTE. On the FM hypoid
    12x31 at a 0.20 d_e2 of benchmarks/data/unseen_designs (101.5 / 677.1 N m), after the
    check's steps again (path −80°, ellipse 0.575, tip relief 22.5 µm from 0.85, root
    relief 15 µm from 0.5, ``te_level`` 45: 0.60 long, centre v 0.65 against 0.540 ± 0.08,
    edge 1.7 %, not tolerant), ``benchmarks/development_levers.py --check --tolerance``
    (2026-11-29, branch len99): the tip relief 18 µm from 0.9 with the root relief 22.5
    µm: centre v 0.62, LTE 36.7 / 39.6 µrad, edge 0.9 %, tolerant, every target met; with
    ``te_level`` 25: LTE 29.7 / 35.6 µrad, every target met; the tip relief alone (ellipse
    0.556, ``te_level`` 25): v 0.63, not tolerant (edge 2.5 % at ΔE +0.05 mm); blade-angle
    steps to v 0.56–0.62 missed the length and the LTE (46–67 µrad). Stadtfeld, *Gleason
    Bevel Gear Technology* (2014): the pattern's height by the profile relief at the
    mating member's tip and root.
    """
    short = best.full[1] if best.full is not None else {}
    if {k for k, v in short.items() if v > 0.0} != {"centre_v"}:
        return None
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    v = footprint_centre_v(best)
    if not (math.isfinite(v) and v > float(target)):
        return None
    for values in relief_designs(best.values, targets):
        e = said_variant(best, values, STAGE, f"with {changed_values(values, best.values)} "
                         f"(its centre v {v:.2f} high, the tip step barred by the edge "
                         "share)", targets, setup, teeth, say, placed)
        if e is None or not bool(e.full[2]):
            continue
        if tolerant_variant(e, targets, setup, teeth, say):
            return e
    return None


def checked_after_edge_peak(before: DevelopmentEvaluation, after: DevelopmentEvaluation,
                            targets: DevelopmentTargets, say: Callable[[str], None],
                            steps: Callable[[DevelopmentEvaluation], DevelopmentEvaluation],
                            relieved: Callable[[DevelopmentEvaluation],
                                               DevelopmentEvaluation | None] | None = None
                            ) -> DevelopmentEvaluation:
    """The check's steps (``steps``) again on the design the edge-peak step wrote, where
    :func:`after_runs_on`; their design kept only where it meets every target. Where it
    does not, ``relieved`` (:func:`height_by_reliefs` with the development's state bound)
    is asked for a design from it that does; else ``after`` (a "not kept" line said).

    Parameters
    ----------
    before, after : DevelopmentEvaluation
        The drive design before and after the edge-peak step.
    targets : DevelopmentTargets
        The development's targets.
    say : callable str → None
        Gets the step's line.
    steps : callable DevelopmentEvaluation → DevelopmentEvaluation
        The check's steps (:func:`~contact.optimize.development_check.check_steps` with
        the development's state bound).
    relieved : callable DevelopmentEvaluation → DevelopmentEvaluation or None, optional
        The design from the steps' one meeting every target, or None (default: not asked).

    Returns
    -------
    DevelopmentEvaluation

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (the steps log it).
    """
    if not after_runs_on(before, after, targets):
        return after
    missed = ", ".join(k for k, v in after.full[1].items() if v > 0.0)
    say(f"  the check's steps again on the design the edge-peak step wrote (it misses "
        f"{missed})")
    again = steps(after)
    if not bool(again.full[2]) and relieved is not None:
        # the pattern still high alone: both reliefs at once (height_by_reliefs)
        lowered = relieved(again)
        if lowered is not None:
            return lowered
    if again is after:
        return after
    if not bool(again.full[2]):
        say(f"  not kept: the check's steps again end on a design that misses "
            f"{', '.join(k for k, v in again.full[1].items() if v > 0.0)} (kept only "
            "where every target is met)")
        return after
    return again
