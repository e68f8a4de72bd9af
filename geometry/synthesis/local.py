"""Step 4 of the synthesis: the local synthesis of the pinion's shape at M.

At M the pinion surface is tangent to the gear's, the contact path on the gear leaves M in
a prescribed direction, the transmission function has the prescribed second derivative
−a21 and the contact ellipse has the prescribed major axis at the elastic approach δ. This
gives the pinion's shape operator (principal curvatures and directions) at M (Litvin &
Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, ch. 9; Litvin, Fuentes et al.,
Mech. Mach. Theory 37 (2002) 441).

Public functions
----------------
LocalSynthesis   the pinion's shape operator at M and what it was made from
local_synthesis  pinion shape operator at M from the local-synthesis conditions
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from geometry.core.errors import InputError
from geometry.synthesis.gear import tangent_basis, unit

__all__ = [
    "LocalSynthesis",
    "local_synthesis",
]

# --------------------------------------------------------------------------- local synthesis
class LocalSynthesis(NamedTuple):
    """Result of :func:`local_synthesis` (pair frame)."""

    pinion_shape: np.ndarray  # (3, 3) [1/mm] pinion shape operator at M (dn = W dr)
    relative_shape: np.ndarray  # (3, 3) [1/mm] W_p + W_g (relative curvature)
    path_gear: np.ndarray  # (3,) [mm/rad] velocity of the contact point on the gear surface
    path_pinion: np.ndarray  # (3,) [mm/rad] ... on the pinion surface (per rad pinion roll)
    ellipse_axis: np.ndarray  # (3,) [1] direction of the ellipse's major axis
    relative_curvatures: tuple[float, float]  # [1/mm] principal relative curvatures (min, max)


def local_synthesis(point, normal, gear_shape, pinion_axis, pinion_origin, gear_axis,
                    gear_origin, *, pinion_sense: int, gear_sense: int, ratio: float,
                    a21: float, path_direction, curvature_gap: float) -> LocalSynthesis:
    """Pinion shape operator at the mean point from the local-synthesis conditions.

    Parameters
    ----------
    point : array_like (3,) — [mm]
        Mean contact point M (pair frame).
    normal : array_like (3,) — [1]
        Pinion unit normal at M, out of the pinion material (the gear's is −normal).
    gear_shape : array_like (3, 3) — [1/mm]
        Gear shape operator W_g at M (dn_g = W_g dr with the gear's own outward normal; convex
        positive, :mod:`geometry.machine.curvature`).
    pinion_axis, gear_axis : array_like (3,) — [1]
        Unit axes (each member's +z) in the pair frame.
    pinion_origin, gear_origin : array_like (3,) — [mm]
        Points on the axes.
    pinion_sense, gear_sense : int
        ±1: senses of rotation (about the axes) when the pinion drives on this flank.
    ratio : float — [1]
        z1/z2.
    a21 : float — [1/rad]
        Prescribed −d²φ₂/dφ₁² at M (parabolic transmission error φ₂ lagging by a21 φ₁²/2).
    path_direction : array_like (3,) — [1]
        Unit tangent of the contact path on the gear surface at M (either orientation).
    curvature_gap : float — [1/mm]
        Smallest principal relative curvature at M, 2δ/a² for an ellipse of semi-major axis a
        at the elastic approach δ (0: the conjugate limit, line contact).

    Returns
    -------
    LocalSynthesis

    Raises
    ------
    InputError
        If the prescriptions are incompatible (the path direction makes the contact-point
        velocity infinite, or no pinion curvature gives the ellipse).

    Notes
    -----
    Litvin's local synthesis (Litvin & Fuentes 2004, §9.4–9.5; Litvin, Fuentes et al. 2002),
    written here in vector form and derived from three conditions at M, with Ω₁ = s₁ a₁,
    Ω₂ = s₂ (z1/z2 − a21 φ₁) a₂ per unit pinion roll, ω⁽¹²⁾ = Ω₁ − Ω₂,
    v⁽¹²⁾ = Ω₁ × (r − o₁) − Ω₂ × (r − o₂), v_r⁽ⁱ⁾ the velocity of the contact point over
    surface i:

    * contact point: v_r⁽¹⁾ = v_r⁽²⁾ − v⁽¹²⁾;
    * common normal: W₁ v_r⁽¹⁾ = −W₂ v_r⁽²⁾ − ω⁽¹²⁾ × n (normal derivatives dn = W dr, the
      gear's with respect to its own normal −n);
    * meshing kept along the path, d(n·v⁽¹²⁾)/dt = 0, written with the gear side:
      v_r⁽²⁾·[−W₂ v⁽¹²⁾ + n × ω⁽¹²⁾] + (Ω₂ × n)·v⁽¹²⁾ + n·(ω⁽¹²⁾ × v₂)
      − n·(Ω̇₂ × (r − o₂)) = 0, Ω̇₂ = −s₂ a21 a₂, which fixes |v_r⁽²⁾| along the prescribed
      path direction.

    The normal condition fixes W₁ up to t w wᵀ, w ⟂ v_r⁽¹⁾ in the tangent plane; t is chosen
    so that the smallest eigenvalue of W₁ + W₂ equals ``curvature_gap``. With a21 = 0 and a
    zero gap W₁ is the conjugate pinion's, whatever the path direction (tested against the
    toolkit's generated conjugate pinions).
    """
    r = np.asarray(point, float)
    n = unit(np.asarray(normal, float))
    w2 = np.asarray(gear_shape, float)
    a1, a2 = unit(np.asarray(pinion_axis, float)), unit(np.asarray(gear_axis, float))
    o1, o2 = np.asarray(pinion_origin, float), np.asarray(gear_origin, float)
    om1 = pinion_sense * a1
    om2 = gear_sense * ratio * a2
    dom2 = -gear_sense * a21 * a2
    v1 = np.cross(om1, r - o1)
    v2 = np.cross(om2, r - o2)
    v12 = v1 - v2
    w12 = om1 - om2
    proj = np.eye(3) - np.outer(n, n)
    e = proj @ np.asarray(path_direction, float)
    e = unit(e)
    c = proj @ (-w2 @ v12 + np.cross(n, w12))
    d = (np.cross(om2, n) @ v12 + n @ np.cross(w12, v2) - n @ np.cross(dom2, r - o2))
    if abs(c @ e) < 1e-12 * (np.linalg.norm(c) + 1e-300):
        raise InputError("path_angle: the contact path cannot leave M in this direction (the "
                         "contact-point velocity would be infinite); choose another angle")
    vr2 = -d / (c @ e) * e
    vr1 = vr2 - v12
    b = proj @ (-w2 @ vr2 - np.cross(w12, n))
    vv = vr1 @ vr1
    w1p = (np.outer(b, vr1) + np.outer(vr1, b)) / vv - (b @ vr1) * np.outer(vr1, vr1) / vv**2
    w = unit(np.cross(n, vr1))
    tb = tangent_basis(n)
    a0 = tb.T @ (w1p + w2) @ tb
    ww = tb.T @ np.outer(w, w) @ tb
    bm = a0 - curvature_gap * np.eye(2)
    adj = np.array([[bm[1, 1], -bm[0, 1]], [-bm[1, 0], bm[0, 0]]])
    den = float(np.trace(adj @ ww))
    if abs(den) < 1e-300:
        raise InputError("ellipse_length: no pinion curvature gives this contact ellipse")
    t = -float(np.linalg.det(bm)) / den
    w1 = w1p + t * np.outer(w, w)
    rel = tb.T @ (w1 + w2) @ tb
    lam, vec = np.linalg.eigh(rel)
    if lam[0] < curvature_gap * (1 - 1e-9) - 1e-12 or lam[1] <= 0:
        raise InputError(
            "ellipse_length: the prescriptions give no contact ellipse (relative curvatures "
            f"{lam[0]:.3g}, {lam[1]:.3g} 1/mm); change the path angle or the ellipse length")
    return LocalSynthesis(pinion_shape=proj @ w1 @ proj, relative_shape=proj @ (w1 + w2) @ proj,
                          path_gear=vr2, path_pinion=vr1, ellipse_axis=tb @ vec[:, 0],
                          relative_curvatures=(float(lam[0]), float(lam[1])))
