"""Surface velocities at contact points: sliding, rolling (entraining), slide-to-roll (seed §5.2.1).

At a contact point r (pair frame) the surface velocities of the two members are
v_p = ω_p a_p × (r − O_p) and v_g = ω_g a_g × (r − O_g), with the members turning in
opposite senses in the toolkit's pair frame (``geometry.pair.assembly``): ω_g = −ω_p z_p/z_g.
Their parts in the common tangent plane (normal n) are v_pt = v_p − (v_p·n) n and
v_gt likewise; the normal parts are equal at a true contact point (equation of
meshing), which is checked. With t the unit tangent of the contact line and
w = n × t the direction across it (seed Eq. 5.1–5.6):

- sliding velocity V_s = v_pt − v_gt, its components along the line (V_s·t) and across
  it (V_s·w) and its magnitude;
- rolling (entraining) velocity across the line V_r = ½ (v_pt + v_gt)·w — the speed at
  which lubricant is drawn into a line contact;
- slide-to-roll ratio SR = (V_s·w) / V_r (across the line, where the EHL film forms).

Units: positions in mm, angular speed from the pinion speed in rpm, velocities in m/s.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from geometry.core.errors import InputError
from geometry.core.validation import positive, real_array

__all__ = ["surface_velocities"]

_NORMAL_TOLERANCE = 1e-6  # relative mismatch of the normal velocities allowed at contact


def _vectors(name: str, value: ArrayLike, unit: str = "mm") -> np.ndarray:
    arr = real_array(name, value, unit=unit)
    if arr.shape[-1:] != (3,):
        raise InputError(f"{name}: must have shape (..., 3), got {arr.shape}")
    return arr


def _unit(name: str, value: ArrayLike) -> np.ndarray:
    v = _vectors(name, value, "1")
    norm = np.linalg.norm(v, axis=-1)
    if np.any(np.abs(norm - 1.0) > 1e-6):
        raise InputError(f"{name}: must be unit vectors (|v| = 1 within 1e-6)")
    return v


def surface_velocities(
    points: ArrayLike,
    normals: ArrayLike,
    tangents: ArrayLike,
    *,
    pinion_axis: ArrayLike,
    pinion_origin: ArrayLike,
    gear_axis: ArrayLike,
    gear_origin: ArrayLike,
    pinion_speed: float,
    ratio: float,
    check_meshing: bool = True,
) -> dict[str, np.ndarray]:
    """Surface, sliding and rolling velocities at contact points (seed Eq. 5.1–5.6).

    Parameters
    ----------
    points : array (..., 3) — [mm]
        Contact points in the pair frame.
    normals : array (..., 3) — [1]
        Unit common normals (either sense).
    tangents : array (..., 3) — [1]
        Unit tangents of the contact line (in the tangent plane).
    pinion_axis, gear_axis : array (3,) — [1]
        Unit member axes in the pair frame.
    pinion_origin, gear_origin : array (3,) — [mm]
        A point on each axis (the crossing points).
    pinion_speed : float — [rpm]
        Pinion speed n_p > 0.
    ratio : float — [1]
        z_g / z_p > 0.
    check_meshing : bool
        Raise if the normal velocities of the two surfaces differ by more than 1e-6 of
        the surface speed (the points are not contact points of the two axes).

    Returns
    -------
    dict of arrays — [m/s] (SR [1])
        ``pinion_velocity``, ``gear_velocity`` (..., 3); ``pinion_tangential``,
        ``gear_tangential`` (..., 3); ``sliding_velocity`` (magnitude),
        ``sliding_along``, ``sliding_across``; ``rolling_velocity`` (entraining, across
        the line, ≥ 0 by taking the magnitude); ``slide_to_roll`` (SR = sliding across /
        rolling, signed); ``normal_mismatch`` [m/s].

    Raises
    ------
    InputError
        Shapes, non-unit vectors, non-positive speed or ratio, or (with
        ``check_meshing``) points that are not contact points.

    Notes
    -----
    Seed §5.2.1, Eq. 5.1–5.6 (garbled in the extraction; the relations above are the
    standard kinematics of crossed-axis gearing, Litvin & Fuentes 2004, §6.1).
    """
    r = _vectors("points", points)
    n = _unit("normals", normals)
    t = _unit("tangents", tangents)
    ap, ag = _unit("pinion_axis", pinion_axis), _unit("gear_axis", gear_axis)
    op, og = _vectors("pinion_origin", pinion_origin), _vectors("gear_origin", gear_origin)
    pinion_speed = positive("pinion_speed", pinion_speed, "rpm")
    ratio = positive("ratio", ratio, "1")
    w_p = 2 * math.pi * pinion_speed / 60.0  # rad/s
    w_g = -w_p / ratio
    v_p = w_p * np.cross(ap, r - op) * 1e-3  # mm/s → m/s
    v_g = w_g * np.cross(ag, r - og) * 1e-3
    vn_p = np.sum(v_p * n, axis=-1)
    vn_g = np.sum(v_g * n, axis=-1)
    mismatch = np.abs(vn_p - vn_g)
    if check_meshing:
        scale = np.maximum(np.linalg.norm(v_p, axis=-1), 1e-12)
        if np.any(mismatch > _NORMAL_TOLERANCE * scale + 1e-12):
            worst = float(np.max(mismatch / scale))
            raise InputError(
                f"points: not contact points of the two axes (normal velocities differ by "
                f"{worst:.2e} of the surface speed; the equation of meshing requires 0)"
            )
    vpt = v_p - vn_p[..., None] * n
    vgt = v_g - vn_g[..., None] * n
    across = np.cross(n, t)
    vs = vpt - vgt
    s_along = np.sum(vs * t, axis=-1)
    s_across = np.sum(vs * across, axis=-1)
    roll = 0.5 * np.sum((vpt + vgt) * across, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        sr = np.where(np.abs(roll) > 1e-12, s_across / np.abs(roll), np.inf * np.sign(s_across))
    return {
        "pinion_velocity": v_p,
        "gear_velocity": v_g,
        "pinion_tangential": vpt,
        "gear_tangential": vgt,
        "sliding_velocity": np.linalg.norm(vs, axis=-1),
        "sliding_along": s_along,
        "sliding_across": s_across,
        "rolling_velocity": np.abs(roll),
        "slide_to_roll": sr,
        "normal_mismatch": mismatch,
    }
