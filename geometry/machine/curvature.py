"""Principal curvatures and directions of generated tooth surfaces (seed §2.2.4, Eq. 2.9–2.13).

Sign convention (used everywhere in the toolkit): with n the unit normal pointing out of the
material, the normal curvature along a unit tangent t is κ(t) = −(∂²r/∂σ²)·n along a
unit-speed surface curve, i.e. positive where the surface is **convex** (a sphere of radius
R seen from outside has κ = +1/R). Two mating surfaces touch with opposite normals, so their
relative normal curvature along a common tangent is κ_p(t) + κ_g(t) and the equivalent radius
is R_eq = 1/(κ_p + κ_g) = R_p R_g/(R_p + R_g) (seed §2.2.4).

Generated surface. In Generate the surface is r_g(s, θ, q(s, θ)) with q implicit in the
equation of meshing f(s, θ, q) = 0, so q_s = −f_s/f_q and q_θ = −f_θ/f_q. Because
n·∂r_g/∂q = 0 on the envelope, the second fundamental form needs no second derivatives of q:

    L = −(r_ss + 2 r_sq q_s + r_qq q_s²)·n
    M = −(r_sθ + r_sq q_θ + r_θq q_s + r_qq q_s q_θ)·n
    N = −(r_θθ + 2 r_θq q_θ + r_qq q_θ²)·n

(implicit differentiation; Litvin & Fuentes 2004, §8.5 obtain the same forms). The seed's
route is then followed literally: normal curvature k_t1 and geodesic torsion τ along the
s-line direction t1 (Eq. 2.10–2.11), normal curvature k_t2 along t2 = n × t1 (Eq. 2.12–2.13),
and Euler's relation gives κ_1,2 = (k_t1 + k_t2)/2 ± √(((k_t1 − k_t2)/2)² + τ²) with
e_1 at the angle φ = ½ atan2(2τ, k_t1 − k_t2) from t1.

Public functions
----------------
PrincipalCurvatures        κ_1 ≥ κ_2 [1/mm] and unit directions e_1, e_2 (e_2 = n × e_1)
principal_from_directional Euler's relation from (k_t1, k_t2, τ) on an orthonormal pair
surface_curvatures         principal curvatures of the generated surface at solved points
normal_curvature           Euler's formula κ(t) = κ_1 cos²φ + κ_2 sin²φ
relative_curvature         principal relative curvatures of two mating surfaces
equivalent_radius          R_eq = R_p R_g/(R_p + R_g) from curvatures
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from geometry.core.errors import InputError
from geometry.core.vectors import cross
from geometry.machine.family import GeneratedFamily, dot, meshing_function

__all__ = [
    "PrincipalCurvatures",
    "equivalent_radius",
    "normal_curvature",
    "principal_from_directional",
    "relative_curvature",
    "surface_curvatures",
]


class PrincipalCurvatures(NamedTuple):
    """Principal curvatures κ_1 ≥ κ_2 [1/mm] and unit principal directions (..., 3)."""

    kappa1: np.ndarray
    kappa2: np.ndarray
    dir1: np.ndarray
    dir2: np.ndarray


def principal_from_directional(k_t1, k_t2, tau, t1, t2) -> PrincipalCurvatures:
    """Euler's relation: principal curvatures from two orthogonal directions (seed Eq. 2.9–2.13).

    Parameters
    ----------
    k_t1, k_t2 : array_like — [1/mm]
        Normal curvatures along the orthonormal tangents t1 and t2.
    tau : array_like — [1/mm]
        Geodesic torsion along t1 (the off-diagonal of the shape operator in (t1, t2)).
    t1, t2 : array_like (..., 3) — [1]
        Orthonormal tangent vectors with t2 = n × t1.

    Returns
    -------
    PrincipalCurvatures
        κ_1 ≥ κ_2 and e_1 = cos φ t1 + sin φ t2, e_2 = −sin φ t1 + cos φ t2 (= n × e_1),
        φ = ½ atan2(2τ, k_t1 − k_t2) taken in (−π/4, 3π/4].

    Notes
    -----
    Seed §2.2.4 cites Euler's equation (refs. 2.11, 2.12) without writing it; this is the
    eigen-decomposition of the symmetric 2×2 shape operator [[k_t1, τ], [τ, k_t2]].

    A principal direction is defined only up to its sign. The sign convention is
    e_1 · (t1 + t2) > 0, i.e. φ in (−π/4, 3π/4]: its branch cut lies where e_1 is at 45°
    to both tangents, away from the common cases e_1 ∥ t1 and e_1 ∥ t2. The bare
    φ ∈ (−π/2, π/2] of atan2 cuts at e_1 ∥ t2, where the torsion τ crosses zero: there a
    round-off of τ's sign (another CPU's or BLAS build's last digit) flipped e_1 and e_2,
    so files differed between machines (issue 31).
    """
    k_t1, k_t2, tau = (np.asarray(a, dtype=float) for a in (k_t1, k_t2, tau))
    mean = 0.5 * (k_t1 + k_t2)
    rad = np.hypot(0.5 * (k_t1 - k_t2), tau)
    phi = 0.5 * np.arctan2(2.0 * tau, k_t1 - k_t2)
    phi = np.where(phi <= -0.25 * np.pi, phi + np.pi, phi)
    c, s = np.cos(phi)[..., None], np.sin(phi)[..., None]
    t1, t2 = np.asarray(t1, dtype=float), np.asarray(t2, dtype=float)
    return PrincipalCurvatures(mean + rad, mean - rad, c * t1 + s * t2, -s * t1 + c * t2)


def surface_curvatures(family: GeneratedFamily, generate: bool,
                       length_scale: float = 1.0) -> PrincipalCurvatures:
    """Principal curvatures and directions of the generated surface at solved points.

    Parameters
    ----------
    family : geometry.machine.family.GeneratedFamily
        r_g and its derivatives evaluated at points that satisfy the equation of meshing
        (e.g. ``EnvelopeSolution.family``), shape (..., 3).
    generate : bool
        True for a generated member (q implicit), False for Formate (q fixed).
    length_scale : float — [mm]
        Normalising length of the meshing function (cancels; any positive value).

    Returns
    -------
    PrincipalCurvatures
        κ_1 ≥ κ_2 [1/mm] (positive convex) and unit directions in the blank frame.

    Where the envelope is singular (∂f/∂q = 0: no regular parametrisation, the edge of
    undercut) the curvatures are NaN; :func:`geometry.machine.meshing.solve_envelope` masks points
    beyond that line as ``undercut``.

    Notes
    -----
    Seed Eq. 2.9–2.13 with the fundamental forms of the module docstring.
    """
    fam = family
    n = fam.normal
    if generate:
        _, grad = meshing_function(fam, length_scale)
        fq = grad[..., 2]
        singular = np.abs(fq) < 1e-14 * (np.abs(grad[..., 0]) + np.abs(grad[..., 1]) + 1e-300)
        fq = np.where(singular, np.nan, fq)
        qs = (-grad[..., 0] / fq)[..., None]
        qt = (-grad[..., 1] / fq)[..., None]
        rs = fam.r_s + fam.r_q * qs
        rt = fam.r_theta + fam.r_q * qt
        big_l = -dot(fam.r_ss + 2.0 * fam.r_sq * qs + fam.r_qq * qs * qs, n)
        big_m = -dot(fam.r_stheta + fam.r_sq * qt + fam.r_thetaq * qs + fam.r_qq * qs * qt, n)
        big_n = -dot(fam.r_thetatheta + 2.0 * fam.r_thetaq * qt + fam.r_qq * qt * qt, n)
    else:
        rs, rt = fam.r_s, fam.r_theta
        big_l, big_m, big_n = (-dot(fam.r_ss, n), -dot(fam.r_stheta, n),
                               -dot(fam.r_thetatheta, n))
    e, f, g = dot(rs, rs), dot(rs, rt), dot(rt, rt)
    len1 = np.sqrt(e)
    # t1 along the s-line, projected on the tangent plane (r_s·n is O(meshing residual))
    t1 = rs - dot(rs, n)[..., None] * n
    t1 = t1 / np.linalg.norm(t1, axis=-1, keepdims=True)
    t2 = cross(n, t1)
    # t2 = α r_s + β r_θ from the first fundamental form
    b1, b2 = dot(rs, t2), dot(rt, t2)
    det = e * g - f * f
    alpha = (g * b1 - f * b2) / det
    beta = (e * b2 - f * b1) / det
    a1 = 1.0 / len1
    k_t1 = big_l * a1 * a1
    tau = a1 * (big_l * alpha + big_m * beta)
    k_t2 = big_l * alpha**2 + 2.0 * big_m * alpha * beta + big_n * beta**2
    return principal_from_directional(k_t1, k_t2, tau, t1, t2)


def normal_curvature(kappa1, kappa2, dir1, direction):
    """Normal curvature along a tangent direction by Euler's formula (seed Eq. 2.15).

    Parameters
    ----------
    kappa1, kappa2 : array_like — [1/mm]
        Principal curvatures.
    dir1 : array_like (..., 3) — [1]
        Unit principal direction of κ_1.
    direction : array_like (..., 3)
        Tangent direction (normalised here; its normal component must be negligible).

    Returns
    -------
    ndarray — [1/mm]
        κ = κ_1 cos²φ + κ_2 sin²φ with cos φ = t·e_1; NaN where ``direction`` is zero
        (no direction: e.g. the padding of absent contact segments, masked by the
        callers).
    """
    t = np.asarray(direction, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = t / np.linalg.norm(t, axis=-1, keepdims=True)
    c2 = dot(t, np.asarray(dir1, dtype=float)) ** 2
    return np.asarray(kappa1) * c2 + np.asarray(kappa2) * (1.0 - c2)


def relative_curvature(pinion: PrincipalCurvatures, gear: PrincipalCurvatures
                       ) -> PrincipalCurvatures:
    """Principal relative curvatures of two surfaces touching at a point (opposite normals).

    Parameters
    ----------
    pinion, gear : PrincipalCurvatures
        Each in its own sign convention (convex positive with its own outward normal), the
        directions expressed in one common frame, tangent planes coincident.

    Returns
    -------
    PrincipalCurvatures
        Extremes of κ_p(t) + κ_g(t) over tangent directions t and their directions (in the
        pinion's tangent basis; ``dir2`` = pinion normal × ``dir1``).

    Notes
    -----
    Seed §2.2.4 and Eq. 2.16–2.18: "principal directions of the difference surface are the
    directions in which two contacting surfaces have the extremes of the relative
    curvatures". The two shape operators are added in the pinion basis (e_1p, e_2p) and the
    sum is diagonalised; equals Hertz's A + B, B − A construction for crossed principal axes.
    """
    e1, e2 = pinion.dir1, pinion.dir2
    k11 = np.asarray(pinion.kappa1) + normal_curvature(gear.kappa1, gear.kappa2, gear.dir1, e1)
    k22 = np.asarray(pinion.kappa2) + normal_curvature(gear.kappa1, gear.kappa2, gear.dir1, e2)
    # off-diagonal of the gear's shape operator in (e1, e2)
    g1, g2 = dot(e1, gear.dir1), dot(e2, gear.dir1)
    h1, h2 = dot(e1, gear.dir2), dot(e2, gear.dir2)
    k12 = np.asarray(gear.kappa1) * g1 * g2 + np.asarray(gear.kappa2) * h1 * h2
    return principal_from_directional(k11, k22, k12, e1, e2)


def equivalent_radius(kappa_p, kappa_g):
    """Equivalent radius of two mating surfaces along one common direction (seed §2.2.4).

    Parameters
    ----------
    kappa_p, kappa_g : array_like — [1/mm]
        Normal curvatures of pinion and gear along the same tangent direction, each convex
        positive with its own outward normal.

    Returns
    -------
    ndarray — [mm]
        R_eq = 1/(κ_p + κ_g) = R_p R_g/(R_p + R_g); +inf where κ_p + κ_g ≤ 0 (conformal or
        separating: no Hertzian contact along that direction).

    Raises
    ------
    InputError
        If an input is not finite.
    """
    kp, kg = np.asarray(kappa_p, dtype=float), np.asarray(kappa_g, dtype=float)
    if not (np.all(np.isfinite(kp)) and np.all(np.isfinite(kg))):
        raise InputError("kappa_p, kappa_g: curvatures must be finite")
    tot = kp + kg
    with np.errstate(divide="ignore"):
        return np.where(tot > 0.0, 1.0 / np.where(tot > 0.0, tot, 1.0), np.inf)
