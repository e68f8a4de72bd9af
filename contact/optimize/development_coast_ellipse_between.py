"""The coast flank's ellipse between its design's and the longest, its pattern's height kept
(issue 71: "LTE p-p ≤ 60 µrad at every torque", both flanks).

The coast capacity LTE step (:func:`~contact.optimize.development_coast_capacity_lte.
checked_coast_capacity_lte`) tries the longest ellipse and lighter reliefs. On the
face-hobbed spiral bevel 25x31 of m_et 9.52 mm (benchmarks/data/unseen_designs, its coast
design torque the given 3780 N m) each of them was refused: the longest ellipse ran the
pattern to toe and heel with 0.5 % of the torque on plastic segments, the lighter reliefs
carried 1.2-3.0 % plastic, and the coast flank was written at 59 / 53 µrad at 567 / 3780
N m and 68.6 µrad at 1638 N m between them. An ellipse between the two keeps the limit
there, but raises the light-load pattern off the depth band the design met (its centre v
0.63 at the band's edge 0.636, the ellipse 0.5 at 0.64): its blade angle brings it back
(:func:`recentred`). :func:`ellipse_between_designs` tries the ellipse
:data:`~contact.optimize.development_lte_steps.ELLIPSE_STEP` × each of :data:`STEPS`
longer than the design's, each where its centre v is lost re-centred (at most
:data:`HEIGHT_TRIES` designs, the slope d v / d blade angle measured between them,
:func:`height_slope`), until one is kept by the caller's rule.

Public names
------------
STEPS, HEIGHT_TRIES, ellipses_between, recentred, height_slope, ellipse_between_designs
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from contact.optimize.development_keep import lost_targets
from contact.optimize.development_lte_steps import ELLIPSE_STEP
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import (
    HEIGHT_SLOPE,
    HEIGHT_SLOPE_MIN,
    footprint_centre_v,
)
from contact.optimize.development_targets import HEIGHT_NAME, DevelopmentTargets

__all__ = ["HEIGHT_TRIES", "STEPS", "ellipse_between_designs", "ellipses_between",
           "height_slope", "recentred"]

#: the ellipse's lengthenings tried, in :data:`~contact.optimize.development_lte_steps.
#: ELLIPSE_STEP` (0.05 of the face) from the design's, strictly below the longest (the
#: variable's upper bound, the capacity step's first design), as the drive's range step
#: (:data:`~contact.optimize.development_range_lte.ELLIPSE_STEPS`). Measured on the 25x31's
#: coast flank as written (path −58.75°, ellipse 0.4, tip / root relief 20 / 26.7 µm;
#: ``benchmarks/development_levers.py --flank coast --from-case --check --at``, 2026-11-28;
#: LTE p-p light / design, largest between at 567 / 1370 / 1638 / 2709 / 3780 N m [µrad],
#: centre v): ellipse 0.45: 55 / 46, 64, v 0.64; 0.5: 47 / 41, 59, v 0.64; 0.55: 38 / 38,
#: 54, v 0.65 (the design 59 / 53, 69, v 0.63; the band 0.556 ± 0.08)
STEPS = (1, 2, 3)

#: re-centring designs per ellipse at most (:func:`recentred`): the first at the slope
#: :data:`~contact.optimize.development_stages.HEIGHT_SLOPE`, the second at the secant
#: between the two measured (:func:`height_slope`)
HEIGHT_TRIES = 2


def ellipses_between(values: Mapping[str, float], targets: DevelopmentTargets,
                     steps: Sequence[int] = STEPS) -> list[dict[str, float]]:
    """``values`` [file units] with ``ellipse_length`` :data:`~contact.optimize.
    development_lte_steps.ELLIPSE_STEP` × each of ``steps`` longer, those strictly between
    the design's and the upper bound of the variable (the longest), in order.

    Parameters
    ----------
    values : mapping name → float
        The coast design's prescriptions [file units] (``ellipse_length`` [1 of the face]).
    targets : DevelopmentTargets
        Its ``variables`` (the bounds).
    steps : sequence of int, optional
        The multiples of the step (default :data:`STEPS`).

    Returns
    -------
    list of dict
        Empty where the targets do not vary the ellipse or ``values`` lack it.

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: the contact ellipse's length by the lengthwise crowning (Litvin & Fuentes,
    *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4); docs/synthesis.md, "The
    coast ellipse between, its height kept".
    """
    name = "ellipse_length"
    if name not in targets.variables or name not in values:
        return []
    now = float(values[name])
    top = float(max(targets.variables[name]))
    out = []
    for k in steps:
        x = round(now + k * ELLIPSE_STEP, 6)
        if now + 1e-9 < x < top - 1e-9:
            out.append(dict(values) | {name: x})
    return out


def height_slope(points: Sequence[tuple[float, float]]) -> float:
    """d(centre v)/d(blade-angle change) [1/deg] of the last two of ``points`` (blade
    angle change [deg], light-load centre v [1]) whose blade angles differ, floored at
    :data:`~contact.optimize.development_stages.HEIGHT_SLOPE_MIN`;
    :data:`~contact.optimize.development_stages.HEIGHT_SLOPE` where none is measurable.

    Parameters
    ----------
    points : sequence of (float, float)
        The designs tried at one ellipse, in order.

    Returns
    -------
    float — [1/deg], > 0

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: :func:`~contact.optimize.development_stages._note_slope` (the height stage's
    secant, floored alike). On the 25x31's coast flank at the ellipse 0.5 the slope is
    about 1/deg (blade angle 0 / −0.02 / −0.04°: v 0.64 / 0.63 / 0.61), 3.6 × the
    default's.
    """
    finite = [(float(b), float(v)) for b, v in points
              if math.isfinite(float(b)) and math.isfinite(float(v))]
    for i in range(len(finite) - 1, 0, -1):
        (b1, v1), (b0, v0) = finite[i], finite[i - 1]
        if abs(b1 - b0) > 1e-9:
            return max((v1 - v0) / (b1 - b0), HEIGHT_SLOPE_MIN)
    return HEIGHT_SLOPE


def recentred(values: Mapping[str, float], centre_v: float, aim: float, slope: float,
              targets: DevelopmentTargets) -> dict[str, float] | None:
    """``values`` with the blade-angle change (:data:`~contact.optimize.
    development_targets.HEIGHT_NAME`) moved by (``aim`` − ``centre_v``) / ``slope``,
    within its bounds: the light-load pattern's centre v brought to ``aim``.

    Parameters
    ----------
    values : mapping name → float
        The design's prescriptions [file units] (``blade_angle_change`` [deg]).
    centre_v : float — [1]
        Its light-load footprint centre v.
    aim : float — [1]
        The centre v aimed at (the written design's).
    slope : float — [1/deg]
        d(centre v)/d(blade-angle change), > 0 (:func:`height_slope`).
    targets : DevelopmentTargets
        Its ``variables`` (the bounds).

    Returns
    -------
    dict or None
        None where the blade angle is not varied (or not in ``values``), a value is not
        finite, ``slope`` is not > 0 or the bound leaves the angle where it is.

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: the pattern's height by the blade's pressure-angle change about M (Stadtfeld,
    *Gleason Bevel Gear Technology*, 2014; :mod:`geometry.synthesis.blade_change`), as
    the development's height stage sets it (:data:`~contact.optimize.development_stages.
    HEIGHT_SLOPE`).
    """
    if HEIGHT_NAME not in targets.variables or HEIGHT_NAME not in values:
        return None
    if not (math.isfinite(centre_v) and math.isfinite(aim) and slope > 0.0):
        return None
    lo, hi = (float(x) for x in targets.variables[HEIGHT_NAME])
    now = float(values[HEIGHT_NAME])
    blade = float(np.clip(now + (aim - centre_v) / slope, lo, hi))
    if abs(blade - now) < 1e-4:
        return None
    return dict(values) | {HEIGHT_NAME: round(blade, 4)}


def ellipse_between_designs(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                            tried: Callable[[Mapping[str, float], str],
                                            DevelopmentEvaluation | None],
                            kept: Callable[[DevelopmentEvaluation], bool],
                            limit: float) -> DevelopmentEvaluation | None:
    """The coast designs of the ellipse between the design's and the longest
    (:func:`ellipses_between`), in order, until one is kept: each ellipse as it is, and
    where it loses the light-load centre v target ``best`` met while its LTE p-p at its
    two torques keeps ``limit``, re-centred by the blade angle at ``best``'s centre v
    (:func:`recentred`; at most :data:`HEIGHT_TRIES` designs, the second at the slope
    measured, :func:`height_slope`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design, checked (its ``values`` [file units], its light-load
        ``pattern_centre_v`` [1] and scores).
    targets : DevelopmentTargets
        The development's (the bounds).
    tried : callable (values, why) → DevelopmentEvaluation or None
        Places, checks and judges a design (the caller's rule, its lines said); None where
        it could not be analysed.
    kept : callable DevelopmentEvaluation → bool
        Whether the caller kept a design ``tried`` returned.
    limit : float — [µrad]
        The verdict's LTE limit.

    Returns
    -------
    DevelopmentEvaluation or None
        The first design kept; None where none is (or nothing was tried).

    Raises
    ------
    Nothing: ``tried`` reports a failed design as None.

    Notes
    -----
    Measured on the 25x31's coast flank (the design's centre v 0.63 in its band 0.556 ±
    0.08; ``benchmarks/development_levers.py --flank coast --from-case --check --at``,
    2026-11-28; LTE p-p light / design and largest between [µrad], flank peak [MPa]):
    ellipse 0.5 at 47.2 / 41.2, 59, 1153, v 0.64 (lost); with the blade angle −0.02° 47.5 /
    40.3, 57, 1140, v 0.63; −0.04° 46.0 / 39.4, 55, 1128, v 0.61; ellipse 0.55 with −0.03°
    40.0 / 36.4, 52, 1133, v 0.62 (with −0.06°: v 0.59 but 2.1 % on the edges, the 2 %
    target lost); the design 59.3 / 52.6, 69, 1158. Source: issue 71; docs/synthesis.md,
    "The coast ellipse between, its height kept".
    """
    aim = footprint_centre_v(best)
    for values in ellipses_between(best.values, targets):
        x = float(values["ellipse_length"])
        e = tried(values, f"an ellipse between the design's and the longest, {x:.3g}")
        if e is None:
            continue
        if kept(e):
            return e
        points = [(float(values.get(HEIGHT_NAME, math.nan)), footprint_centre_v(e))]
        here = e
        for _ in range(HEIGHT_TRIES):
            if ("centre_v" not in lost_targets(best, here)
                    or not float(np.nanmax(here.metrics["lte_peak_to_peak"])) <= limit):
                break
            moved = recentred(here.values, footprint_centre_v(here), aim,
                              height_slope(points), targets)
            if moved is None:
                break
            here = tried(moved, f"the ellipse {x:.3g} with its light-load pattern's height "
                                f"back at v {aim:.2f} by the blade angle")
            if here is None:
                break
            if kept(here):
                return here
            points.append((float(moved[HEIGHT_NAME]), footprint_centre_v(here)))
    return None
