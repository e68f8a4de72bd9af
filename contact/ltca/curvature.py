"""Normal curvatures of the real flanks at contact segments: R_eq across a contact line.

R_eq = 1/κ_rel, κ_rel(w) = κ_p(w) + κ_g(w) along w = n × t (t the contact line's tangent),
each member's normal curvature from its principal curvatures (Euler), evaluated on the
real surfaces (:func:`geometry.machine.flank.flank_at`) at the segment midpoints (seed Eq. 2.13).
The envelope solves start from the ease-off's envelope parameters interpolated in the gear
grid cell (the nearest node's where the cell's nodes lie on different sections).

Public functions
----------------
pinion_curvature   κ of the real pinion at the mates of gear places, along given directions
gear_curvature     κ of the real gear at gear-frame points, along given directions
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import RectBivariateSpline

from contact.ltca.discretisation import gear_to_pair
from contact.utca import EaseOff
from geometry.core.caches import Same, memoised
from geometry.machine.curvature import normal_curvature
from geometry.machine.flank import blank_outline, flank_at, projection_fractions
from geometry.pair.assembly import rotate_about_axis

__all__ = ["gear_curvature", "pinion_curvature"]


def _spline(eo: EaseOff, field: np.ndarray) -> RectBivariateSpline:
    vals = np.array(field, dtype=float)
    ok = np.isfinite(vals)
    if not np.all(ok):  # fill masked nodes from the nearest valid node along the profile
        for i in range(vals.shape[0]):
            row = vals[i]
            good = np.flatnonzero(np.isfinite(row))
            if good.size:
                vals[i] = np.interp(np.arange(row.size), good, row[good])
        for j in range(vals.shape[1]):
            col = vals[:, j]
            good = np.flatnonzero(np.isfinite(col))
            if good.size:
                vals[:, j] = np.interp(np.arange(col.size), good, col[good])
    return RectBivariateSpline(eo.u, eo.v, np.nan_to_num(vals), kx=3, ky=3, s=0)


@memoised(maxsize=8)  # each entry holds its ease-off: as many as the ease-off memo keeps
def _mate_splines(eo: Same) -> tuple[RectBivariateSpline, RectBivariateSpline]:
    """The splines of the pinion mates' axial position and radius [mm] over the gear grid
    of the ease-off ``eo.obj`` (:func:`_spline`), built once per ease-off object: an
    analysis reads them twice, for the curve segments and for the edge segments (issue 75:
    ≈ 0.35 ms of a study point; the same splines, so the same numbers bit for bit)."""
    e = eo.obj
    return _spline(e, e.pinion_axial), _spline(e, e.pinion_radius)


def pinion_curvature(case, eo: EaseOff, u, v, w_gear, phi):
    """Normal curvature [1/mm] of the real pinion, at the mates of gear places (u, v),
    along gear-frame directions ``w_gear`` (..., 3), the pinion turned by φ [rad] (any
    shape that broadcasts against ``u``: one per curve, for instance) and the gear at its
    ideal rotation (the directions are carried to the pinion frame).

    Notes
    -----
    Source: Euler's formula for the normal curvature from the principal curvatures of the
    real flank (seed Eq. 2.13); module docstring.
    """
    kin = eo.kinematics
    axial, radius = _mate_splines(Same(eo))
    ps = flank_at(case, "pinion", eo.pinion_flank, axial.ev(u, v), radius.ev(u, v),
                  guess=_node_guess(eo, eo.pinion_parameters, eo.pinion_section, u, v))
    w_pair = gear_to_pair(kin, eo.gear_phase - phi / eo.ratio, w_gear, vec=True)
    w_p = rotate_about_axis(kin.pinion_axis, np.broadcast_to(-phi, u.shape), w_pair) @ \
        kin.pinion_place[:3, :3]
    return normal_curvature(ps.kappa1, ps.kappa2, ps.dir1, w_p)


def _node_guess(eo: EaseOff, params, section, u, v):
    """Envelope-parameter guesses (s, θ, q, section) at gear places (u, v): interpolated
    bilinearly in the gear grid cell holding each place where its four nodes have
    parameters on one section, else those of the nearest node (``params`` (nu, nv, 3),
    ``section`` (nu, nv) of the ease-off; None where the ease-off has none)."""
    if params is None or section is None:
        return None
    fu = np.interp(u, eo.u, np.arange(eo.u.size))
    fv = np.interp(v, eo.v, np.arange(eo.v.size))
    iu, iv = np.rint(fu).astype(int), np.rint(fv).astype(int)
    par = params[iu, iv]
    sec = section[iu, iv]
    u0 = np.minimum(np.floor(fu).astype(int), eo.u.size - 2)
    v0 = np.minimum(np.floor(fv).astype(int), eo.v.size - 2)
    a, b = (fu - u0)[..., None], (fv - v0)[..., None]
    p00, p10 = params[u0, v0], params[u0 + 1, v0]
    p01, p11 = params[u0, v0 + 1], params[u0 + 1, v0 + 1]
    s00 = section[u0, v0]
    same = ((section[u0 + 1, v0] == s00) & (section[u0, v0 + 1] == s00)
            & (section[u0 + 1, v0 + 1] == s00))
    lin = (1 - a) * ((1 - b) * p00 + b * p01) + a * ((1 - b) * p10 + b * p11)
    use = same & np.all(np.isfinite(lin), axis=-1)
    par = np.where(use[..., None], lin, par)
    sec = np.where(use, s00, sec)
    return par[..., 0], par[..., 1], par[..., 2], sec


def gear_curvature(case, eo: EaseOff, position, w_gear):
    """Normal curvature [1/mm] of the real gear at gear-frame points along ``w_gear``.

    Notes
    -----
    Source: Euler's formula for the normal curvature from the principal curvatures of the
    real flank (seed Eq. 2.13); module docstring.
    """
    z, rho = position[..., 2], np.hypot(position[..., 0], position[..., 1])
    u, v = projection_fractions(blank_outline(case.gear.blank).corners, z, rho)
    guess = _node_guess(eo, eo.gear_parameters, eo.gear_section, np.clip(u, 0.0, 1.0),
                        np.clip(v, eo.v[0], eo.v[-1]))
    gs = flank_at(case, "gear", eo.gear_flank, z, rho, guess=guess)
    return normal_curvature(gs.kappa1, gs.kappa2, gs.dir1, w_gear)
