"""The near-miss step's blade step with the pinion's tip edge relieved (issue 71,
Deliver 1: the pattern's height by the pressure-angle change *and* the profile crowning,
its edges by the tip relief).

Where every blade-angle step of :func:`~contact.optimize.development_pattern_steps.
checked_near_miss` lowered a high light-load pattern but gave up the edge or the plastic
target the design met (:data:`RELIEVED_LOST`: the lower pattern brings the pinion's tip
edge onto the gear's lower flank at the design torque), :func:`checked_height_relieved`
aims the blade-angle change at the target centre v (the slope measured by those steps,
:func:`measured_slope`), and gives it the pinion's edges relieved at once
(:func:`relief_ladder`): the profile crowning raised by a crowning step (the pattern
shorter in depth, off both edges) with the tip relief × :data:`TIP_GAIN`, then the same
tip relief started :data:`LATER_START` later (its ramp off the transfer, the light-load
LTE kept). A design that misses, of the targets the design met, the pattern length alone
(the lower pattern runs longer along the face) is tried with the ellipse shortened to the
length's band (:func:`~contact.optimize.development_pattern_steps.length_aim`). Where no
design at the target centre is kept, the same at half the tolerance above it
(:data:`UPPER_AIM`). Each design placed and checked at ``ltca run``'s sampling and kept
by the check's one rule (:func:`~contact.optimize.development_keep.kept_why`: it meets
more targets, gives up none the design met nor the local pitting bound at the design
torque, nor raises the LTE above the verdict's limit at a torque between the light and
the design torque, and is tolerant at the mounting excursions).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import CROWNING_STEP, footprint_centre_v
from contact.optimize.development_targets import (
    CROWNING_NAME,
    HEIGHT_NAME,
    DevelopmentTargets,
)
from contact.optimize.development_variant import pattern_length, said_variant
from geometry.case import Case
from geometry.core.errors import InputError

#: the targets met before whose loss by a near-miss blade step starts
#: :func:`checked_height_relieved`: the edge share and the plastic segments at the design
#: torque (the lower pattern on the pinion's tip edge)
RELIEVED_LOST = ("edge", "plastic")
#: the tip relief of :func:`relief_ladder`: × this (within its bounds), the 1.5 of the
#: edge-peak step's longer tip relief (:mod:`contact.optimize.development_edge_peak`).
#: Measured on the truck hypoid 8×47 at a 45 (benchmarks/data/unseen_designs,
#: ``ltca run``'s sampling at 264.7 / 1765 N m, ``benchmarks/development_levers.py
#: --check``, 2026-11-28): blade −0.15°: plastic 2.0 % → 0 with the tip relief 21.4 →
#: 32.2 µm (centre v 0.56 → 0.59), 1.6 % with the crowning 23 → 30 µm alone
TIP_GAIN = 1.5
#: [1 of the way from M to the tip end] how much later :func:`relief_ladder`'s second
#: rung starts the tip relief (within ``tip_relief_start``'s bounds): the 8×47 at blade
#: −0.2° with the tip relief 32.2 µm and crowning 30 µm: centre v 0.57, edge 1.4 %;
#: from 0.608 + 0.1: v 0.54, edge 0.8 %, no plastic
LATER_START = 0.1
#: [1 of ``centre_tolerance``] where :func:`checked_height_relieved` aims the centre v
#: after the target itself kept nothing: this far from the target, on the side the
#: design missed it (a smaller blade step: less of the tip edge to relieve)
UPPER_AIM = 0.5
#: most designs of :func:`checked_height_relieved` (each a synthesis of steps 3-6 where
#: the ellipse changes, a check and, where every other rule keeps it, four coarse
#: analyses at the mounting excursions)
RELIEVED_DESIGNS = 8
#: [1/deg] the least slope d(centre v)/d(blade angle) :func:`measured_slope` returns
#: (below it the blade steps did not move the pattern: no step is aimed on it)
LEAST_SLOPE = 0.05


def relieved_applies(best: DevelopmentEvaluation, refused: Sequence[DevelopmentEvaluation],
                     targets: DevelopmentTargets) -> bool:
    """Whether :func:`checked_height_relieved` works on ``best``: a checked design whose
    light-load centre v misses its band, with the blade-angle change, the profile
    crowning and the tip relief developed (in its values and the targets' variables),
    and at least one near-miss blade step (``refused``) that gave up one of
    :data:`RELIEVED_LOST` the design met.

    Raises nothing; a pure function of its inputs (no analysis)."""
    if (not best.checked_full or best.full[2]
            or best.full[1].get("centre_v", 0.0) <= 0.0
            or not all(n in targets.variables and n in best.values
                       for n in (HEIGHT_NAME, CROWNING_NAME, "tip_relief"))):
        return False
    return any(e.checked_full and set(lost_targets(best, e)) & set(RELIEVED_LOST)
               for e in refused)


def measured_slope(x0: float, v0: float, points: Sequence[tuple[float, float]]) -> float:
    """[1/deg] d(centre v)/d(blade angle) through the design (``x0`` [deg], ``v0`` [1])
    and the blade steps' ``points`` ((blade angle [deg], centre v [1]) each): the least
    squares slope of the changes, NaN where it is below :data:`LEAST_SLOPE` or not
    finite.

    Raises
    ------
    InputError
        No point, or one not finite.

    Source: the near-miss step's secant (:func:`~contact.optimize.development_pattern_steps.
    checked_near_miss`), over every step it measured."""
    pts = np.asarray(points, float).reshape(-1, 2)
    if pts.shape[0] == 0 or not np.all(np.isfinite(pts)):
        raise InputError(f"blade steps: give finite (blade angle, centre v) points, got "
                         f"{points!r}")
    dx, dv = pts[:, 0] - float(x0), pts[:, 1] - float(v0)
    den = float(np.sum(dx * dx))
    s = float(np.sum(dx * dv)) / den if den > 0.0 else math.nan
    return s if math.isfinite(s) and s > LEAST_SLOPE else math.nan


def relief_ladder(values: Mapping[str, float], targets: DevelopmentTargets
                  ) -> list[dict[str, float]]:
    """The pinion's edges relieved at the bearing ``values`` [file units]: the profile
    crowning raised by :data:`~contact.optimize.development_stages.CROWNING_STEP` ×
    ``targets.size_scale`` µm with the tip relief × :data:`TIP_GAIN` (each within its
    bounds of ``targets.variables``), then the same with ``tip_relief_start`` raised by
    :data:`LATER_START` (where it is developed). A rung equal to ``values`` or to one
    before it is left out.

    Raises nothing; a pure function of its inputs."""
    c_lo, c_hi = (float(x) for x in targets.variables[CROWNING_NAME])
    t_lo, t_hi = (float(x) for x in targets.variables["tip_relief"])
    crowning = float(values[CROWNING_NAME])
    both = dict(values) | {
        "tip_relief": float(np.clip(TIP_GAIN * float(values["tip_relief"]), t_lo, t_hi)),
        CROWNING_NAME: float(np.clip(crowning + CROWNING_STEP * targets.size_scale,
                                     max(c_lo, crowning), c_hi))}
    rungs = [both]
    if "tip_relief_start" in values and "tip_relief_start" in targets.variables:
        s_lo, s_hi = (float(x) for x in targets.variables["tip_relief_start"])
        rungs.append(both | {"tip_relief_start": float(np.clip(
            float(values["tip_relief_start"]) + LATER_START, s_lo, s_hi))})
    out: list[dict[str, float]] = []
    for r in rungs:
        if r != dict(values) and r not in out:
            out.append(r)
    return out


def checked_height_relieved(best: DevelopmentEvaluation,
                            refused: Sequence[DevelopmentEvaluation],
                            targets: DevelopmentTargets, setup: Mapping[str, Any],
                            teeth: KeptTeeth | None, say: Callable[[str], None],
                            placed: Callable[[Mapping[str, float]], Case],
                            better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation],
                                             bool]) -> DevelopmentEvaluation | None:
    """A design whose near-miss blade steps (``refused``) lowered the pattern but gave up
    the edge or plastic target (:func:`relieved_applies`), given the blade step aimed at
    the target centre v with the pinion's edges relieved (module notes): for each aim
    (the target, then :data:`UPPER_AIM` of the tolerance above it) the blade-angle change
    on :func:`measured_slope` and each rung of :func:`relief_ladder` there, a rung that
    gives up the pattern length alone once more with the ellipse shortened to the
    length's band; at most :data:`RELIEVED_DESIGNS` designs, the first kept returned.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the near-miss step started from (checked at ``ltca run``'s sampling).
    refused : sequence of DevelopmentEvaluation
        The near-miss step's blade steps, analysed and not kept.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``blade_angle_change``
        [deg], ``profile_crowning`` and ``tip_relief`` [µm], ``tip_relief_start`` and
        ``ellipse_length`` [1]; ``pattern_centre_v``, ``centre_tolerance`` [1]).
    setup : mapping
        The development's setup (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis with step 8 (the case as written).
    better : callable (best, e) → bool
        The near-miss step's rule: ``e`` meets more targets than ``best``.

    Returns
    -------
    DevelopmentEvaluation or None
        The design kept (``stage`` ``"height relieved"``), None where none was (or the
        step does not apply).

    Raises
    ------
    Nothing (a design whose synthesis or analysis fails is not kept).

    Notes
    -----
    Source: issue 71 Deliver 1 (the height by the pressure-angle change and the profile
    crowning, the edges by the tip and root relief; Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: pressure angle for the height, profile crowning and tip relief for
    the pattern's depth and its tip edge). Measured on the truck hypoid 8×47 at a 45 of
    benchmarks/data/unseen_designs (written with centre v 0.64 against 0.541 ± 0.08, the
    near-miss steps −0.073° / −0.124° refused for 0.9 / 1.8 % plastic): docs/synthesis.md,
    "The 8×47's pattern centred in depth".
    """
    from contact.optimize.development_edge_peak import (
        design_pitting_limit,
        lte_lost,
        pitting_lost,
    )
    from contact.optimize.development_pattern_steps import LENGTH_PER_ELLIPSE, length_aim
    from contact.study.verdicts import LTE_LIMIT

    if not relieved_applies(best, refused, targets):
        return None
    x0, v0 = float(best.values[HEIGHT_NAME]), footprint_centre_v(best)
    points = [(float(e.values[HEIGHT_NAME]), footprint_centre_v(e)) for e in refused
              if e.checked_full and math.isfinite(footprint_centre_v(e))]
    if not math.isfinite(v0) or not points:
        return None
    slope = measured_slope(x0, v0, points)
    if not math.isfinite(slope):
        return None
    lo, hi = (float(x) for x in targets.variables[HEIGHT_NAME])
    target = float(targets.pattern_centre_v if targets.pattern_centre_v is not None
                   else setup["centre_v"])
    pitting = pitting_lost(design_pitting_limit(best, setup))
    lte = lte_lost(setup, teeth, float(LTE_LIMIT))  # judged between the torques too

    def lost(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        return pitting(kept, e) or lte(kept, e)

    e_lo, e_hi = targets.variables.get("ellipse_length", (math.nan, math.nan))
    count, tried = 0, []
    for aim in (target, target + math.copysign(UPPER_AIM * targets.centre_tolerance,
                                               v0 - target)):
        x = float(np.clip(x0 - (v0 - aim) / slope, lo, hi))
        if any(abs(x - t) < 1e-3 for t in tried) or abs(x - x0) < 1e-4:
            continue
        tried.append(x)
        queue = relief_ladder(dict(best.values) | {HEIGHT_NAME: x}, targets)
        while queue and count < RELIEVED_DESIGNS:
            values = queue.pop(0)
            count += 1
            e = said_variant(best, values, "height relieved",
                             f"with {HEIGHT_NAME} {x:.3g} deg aimed at centre v {aim:.3f}, "
                             f"tip_relief {values['tip_relief']:.3g} um from "
                             f"{values.get('tip_relief_start', math.nan):.3g}, "
                             f"{CROWNING_NAME} {values[CROWNING_NAME]:.3g} um, ellipse_length "
                             f"{values.get('ellipse_length', math.nan):.3g} (the blade step's "
                             "tip edge relieved)", targets, setup, teeth, say, placed)
            if e is None:
                continue
            if not kept_why(best, e, targets, setup, teeth, say,
                            "the relieved blade step", lost=lost, lost_first=True,
                            better=better):
                return e
            if (lost_targets(best, e) == ["length"] and "ellipse_length" in values
                    and math.isfinite(float(e_lo))):
                length = pattern_length(e)
                shorter = float(np.clip(
                    float(values["ellipse_length"])
                    + (length_aim(length, targets) - length) / LENGTH_PER_ELLIPSE,
                    float(e_lo), float(e_hi)))
                if shorter < float(values["ellipse_length"]) - 1e-6:
                    queue.insert(0, values | {"ellipse_length": shorter})
    return None
