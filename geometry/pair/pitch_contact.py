"""Do the blanks of a case fit its pair data? The gap between the assembled mean pitch circles.

A hypoid or spiral bevel pair is designed (ISO 23509) so that, assembled at its shaft angle
Σ and offset E, the two pitch cones touch at the mean point P: the pinion's mean pitch
circle (radius R_m1 sin δ1 at R_m1 cos δ1 from its pitch apex) and the gear's meet there.
A case whose ``pair.offset`` (or shaft angle) is not the one its blanks were designed for
— a typing error, a sign, an offset from another drawing — has pitch circles that miss
each other; the analysis would then fail later with a message about the surface of action
or the ease-off, or worse, run on a pair that does not exist. The bundled cases touch to
within 2.5 µm (the blanks' own round-off); an offset 5 mm off opens a gap of 0.5 mm.

Public functions
----------------
pitch_circle_gap   least distance between the assembled mean pitch circles [mm]
check_pitch_contact  refuse a case whose pitch circles miss by more than the tolerance
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import minimize_scalar

from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment, member_transform

__all__ = ["PITCH_GAP_TOLERANCE", "check_pitch_contact", "pitch_circle_gap"]

#: [mm] largest gap between the assembled mean pitch circles of a consistent pair: the
#: bundled cases touch within 2.5 µm; 0.1 mm leaves room for blanks typed from drawings to
#: 0.01 mm, while a pair offset 1 mm off its blanks' (11×41 case: 20 → 21 mm) opens ~0.1 mm
PITCH_GAP_TOLERANCE = 0.1


def _mean_circle(blank) -> tuple[float, float]:
    """(radius, axial position) [mm] of a blank's mean pitch circle in its member frame
    (z from the apex side into the body, origin at the crossing point; the pitch apex at
    z = −t_zm)."""
    rm = blank.outer_cone_distance - 0.5 * blank.face_width
    return rm * math.sin(blank.pitch_angle), -blank.pitch_apex + rm * math.cos(blank.pitch_angle)


def pitch_circle_gap(case, *, offset: float | None = None) -> tuple[float, float]:
    """Least distance between the pinion's and the gear's mean pitch circles, assembled.

    Parameters
    ----------
    case : geometry.case.Case
    offset : float, optional — [mm]
        Hypoid offset to assemble with (default the case's ``pair.offset``).

    Returns
    -------
    gap : float — [mm]
        0 for a pair whose blanks were designed for its shaft angle and offset.
    phi : float — [rad]
        Gear angle of the closest point (about the gear axis, from the global x axis).

    Notes
    -----
    ISO 23509:2016 §5 (the pitch cones of a hypoid pair are tangent at the mean point P);
    the frames are those of :func:`geometry.pair.assembly.member_transform` without
    misalignment. The distance of a gear point to the pinion circle is exact (in the
    pinion frame: √((ρ − r₁)² + (z − z₁)²)); the gear angle is searched on 3600 points,
    then refined by Brent's method.
    """
    rg, zg = _mean_circle(case.gear.blank)
    rp, zp = _mean_circle(case.pinion.blank)
    # the gap is a function of these numbers alone: each study point's case (a new object,
    # its misalignment replaced) asked for it again (~1.5 ms a point, issue 75)
    return _memo_gap(case.pair.shaft_angle, case.pair.offset if offset is None else offset,
                     case.gear.hand, rg, zg, rp, zp)


@memoised(maxsize=32)
def _memo_gap(shaft_angle: float, offset: float, gear_hand: str, rg: float, zg: float,
              rp: float, zp: float) -> tuple[float, float]:
    """:func:`pitch_circle_gap` of the shaft angle [rad], offset [mm], gear hand and the
    mean circles (radius, axial position) [mm] of the gear (rg, zg) and pinion (rp, zp)."""
    kw = dict(shaft_angle=shaft_angle, offset=offset, gear_hand=gear_hand,
              misalignment=Misalignment())
    tp = member_transform("pinion", **kw)
    tg = member_transform("gear", **kw)

    def distance(phi):
        phi = np.atleast_1d(np.asarray(phi, float))
        pg = np.stack([rg * np.cos(phi), rg * np.sin(phi), np.full_like(phi, zg)])
        q = ((tg[:3, :3] @ pg).T + tg[:3, 3] - tp[:3, 3]) @ tp[:3, :3]
        return np.hypot(np.hypot(q[:, 0], q[:, 1]) - rp, q[:, 2] - zp)

    grid = np.linspace(0.0, 2.0 * math.pi, 3600, endpoint=False)
    d = distance(grid)
    i = int(np.argmin(d))
    step = grid[1] - grid[0]
    res = minimize_scalar(lambda p: float(distance(p)[0]),
                          bounds=(grid[i] - step, grid[i] + step), method="bounded",
                          options={"xatol": 1e-10})
    if res.fun < d[i]:
        return float(res.fun), float(res.x % (2.0 * math.pi))
    return float(d[i]), float(grid[i])


def check_pitch_contact(case, tolerance: float = PITCH_GAP_TOLERANCE) -> float:
    """Refuse a case whose pair offset (or shaft angle) does not fit its blanks.

    Parameters
    ----------
    case : geometry.case.Case
    tolerance : float — [mm]
        Largest gap accepted (:data:`PITCH_GAP_TOLERANCE`).

    Returns
    -------
    float — [mm]
        The gap (:func:`pitch_circle_gap`).

    Raises
    ------
    InputError
        ``pair.offset``: the assembled mean pitch circles miss each other by more than
        ``tolerance``; the message gives the gap, and the offset at which they would
        touch when one exists within ±50 % of the pitch diameter of the pinion.
    """
    gap, _ = pitch_circle_gap(case)
    if gap <= tolerance:
        return gap
    e0 = case.pair.offset
    span = max(abs(e0), case.pinion.blank.outer_cone_distance
               * math.sin(case.pinion.blank.pitch_angle))
    # the gap is not unimodal in the offset: a grid (0.5 % of the span), then Brent
    offsets = np.linspace(e0 - span, e0 + span, 401)
    gaps = np.array([pitch_circle_gap(case, offset=e)[0] for e in offsets])
    # the circles can meet at more than one offset: every local minimum that fits,
    # refined, nearest to e0 first
    de = offsets[1] - offsets[0]
    fits = []
    for i in range(1, offsets.size - 1):
        if gaps[i] <= gaps[i - 1] and gaps[i] <= gaps[i + 1]:
            res = minimize_scalar(lambda e: pitch_circle_gap(case, offset=e)[0],
                                  bounds=(offsets[i] - de, offsets[i] + de),
                                  method="bounded", options={"xatol": 1e-4})
            if min(res.fun, gaps[i]) <= tolerance:
                fits.append(float(res.x if res.fun < gaps[i] else offsets[i]))
    fits.sort(key=lambda e: abs(e - e0))
    hint = ("; the blanks fit an offset of " + " or ".join(f"{e:.4g}" for e in fits) + " mm"
            if fits else "; no offset fits the blanks at this shaft angle")
    raise InputError(
        f"pair.offset: {e0:g} mm is inconsistent with the blanks: assembled at this offset "
        f"and shaft angle {math.degrees(case.pair.shaft_angle):g} deg the pinion's and the "
        f"gear's mean pitch circles miss each other by {gap:.3g} mm (at most {tolerance:g} "
        f"mm){hint}")
