"""Compiled kernels of the shell tooth's point mapping (numba; issue 32).

A loaded analysis maps every contact segment's collocation points (both members, all
rolls: ~10⁴ points per study point) into the shell coordinates of its tooth
(:func:`contact.compliance.tooth.shell_points_many`): the foot of each point on the tooth's
mid-surface by Newton's method (:func:`contact.compliance.tooth._project_to_mid`), then
the orthogonal trajectory from the foot to the mid-height lengthwise curve by RK4
(:func:`contact.compliance.tooth_map.trajectory`). In NumPy both are batched over the
points but cost a few hundred array operations per call, and the projection iterates its
whole batch until the slowest point has converged. These kernels run the same formulas
point by point:

- the mid-surface M(u, v) = (ρ cos φ, ρ sin φ, z) with the bilinear blank map (z, ρ) and
  the flank-angle polynomial φ(u, v) in power form (:class:`~contact.compliance.tooth_map.
  Surface`, rows φ, φ_u, φ_v, φ_uu, φ_uv, φ_vv; each tooth of a stacked batch its own);
- the projection's Newton step with the exact Hessian (the NumPy path's own formula,
  :func:`~contact.compliance.tooth_map.projection_step`, compiled) and its stopping rule
  |Δu| + |Δv| < 1e-14 (here per point: a point stops when it has converged, not when the
  batch has; the iterates then differ by round-off);
- the trajectory's slope du/dv = −(M_u·M_v)/(M_u·M_u) and the classical RK4 scheme with
  the same steps.

The polynomials are evaluated by Horner's scheme instead of a Vandermonde product, so
the results agree with the NumPy path to round-off (the fractions to ~1e-15; checked to
1e-13 in ``tests/test_compliance_fast_paths.py``); numba does not contract or reassociate without
``fastmath``, so they do not depend on the CPU.

The module also holds (re-exported from :mod:`contact.compliance.shell_loads_numba`) the
compiled fill of the shell's grouped load-vector factors,
:func:`~contact.compliance.shell_loads_numba.load_vector_factors`: the compliance's
kernels are chosen and cached as one module.

This module imports numba; :mod:`contact.compliance.tooth_map` and
:mod:`contact.compliance.tooth` use it where numba is installed and ``LTCA_KERNELS`` is
not ``numpy`` (:func:`geometry.core.kernels.kernels_module`).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from contact.compliance.shell_loads_numba import load_vector_factors
from contact.compliance.tooth_map import projection_step

#: (``load_vector_factors`` re-exported: the shell's grouped load vectors use this module's
#: kernels choice, and :func:`geometry.core.kernels.cache_ready` checks its cache here)
__all__ = ["load_vector_factors", "project_to_mid", "trajectory"]

_jit = numba.njit(cache=True, nogil=True)

#: helpers called from compiled code only: no CPython or C wrapper to compile
_helper = numba.njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)

#: the Newton step of the foot on the mid-surface: the NumPy path's own formula, compiled
_projection_step = _helper(projection_step)


@_helper
def _columns(power, m, du, dv, tv, q, level):
    """The coefficients of t_u^i of φ_u and φ_v at t_v (the trajectory's rows 1, 2) into
    q[level, 0 or 1, i]: Horner in t_v, the two rows' chains interleaved."""
    for i in range(du + 1):
        base = i * (dv + 1)
        a = 0.0
        b = 0.0
        for j in range(dv, -1, -1):
            a = a * tv + power[m, 1, base + j]
            b = b * tv + power[m, 2, base + j]
        q[level, 0, i] = a
        q[level, 1, i] = b


@_helper
def _slope(z, rho, p, q, level, du, u, v):
    """du/dv = −(M_u·M_v)/(M_u·M_u) of the orthogonal trajectory at (u, v) of point p, the
    angle polynomials' coefficients of t_u^i at v given (``q[level]``, :func:`_columns`)."""
    tu = 2.0 * u - 1.0
    phi_u = 0.0
    phi_v = 0.0
    for i in range(du, -1, -1):
        phi_u = phi_u * tu + q[level, 0, i]
        phi_v = phi_v * tu + q[level, 1, i]
    pu_z = z[1, p] + z[3, p] * v
    pu_r = rho[1, p] + rho[3, p] * v
    r = rho[0, p] + rho[2, p] * v + pu_r * u
    rfu = r * r * phi_u
    num = pu_z * (z[2, p] + z[3, p] * u) + pu_r * (rho[2, p] + rho[3, p] * u) + rfu * phi_v
    return -num / (pu_z * pu_z + pu_r * pu_r + rfu * phi_u)


@_jit
def trajectory(u, v0, v1, z, rho, power, member, du, dv, steps):
    """u at profile fraction v1 on the orthogonal trajectory through (u, v0), per point.

    Parameters
    ----------
    u, v0, v1 : ndarray (P,) — [1]
    z, rho : ndarray (4, P) — [mm]
        The bilinear blank map's coefficients b₀, b_u, b_v, b_uv of each point's tooth.
    power : ndarray (M, 8, (du + 1)(dv + 1)) — [rad]
        The teeth's angle polynomials (:class:`contact.compliance.tooth_map.Surface`).
    member : int ndarray (P,)
        Each point's tooth.
    du, dv : int
        The polynomials' degrees.
    steps : int
        RK4 steps.

    Returns
    -------
    ndarray (P,) — [1]

    Notes
    -----
    The stages sit at the 2·steps + 1 profile fractions v0 + k h/2, so the polynomials'
    v-parts are evaluated once per fraction and a stage costs a polynomial in t_u (as the
    NumPy path does).
    """
    out = np.empty(u.size)
    q = np.empty((2 * steps + 1, 2, du + 1))
    for p in range(u.size):
        m = member[p]
        x = u[p]
        h = (v1[p] - v0[p]) / steps
        h2 = 0.5 * h
        h6 = h / 6.0
        for level in range(2 * steps + 1):
            _columns(power, m, du, dv, 2.0 * (v0[p] + level * h2) - 1.0, q, level)
        for k in range(steps):
            lv = 2 * k
            va = v0[p] + lv * h2
            vb = v0[p] + (lv + 1) * h2
            vc = v0[p] + (lv + 2) * h2
            k1 = _slope(z, rho, p, q, lv, du, x, va)
            k2 = _slope(z, rho, p, q, lv + 1, du, x + h2 * k1, vb)
            k3 = _slope(z, rho, p, q, lv + 1, du, x + h2 * k2, vb)
            k4 = _slope(z, rho, p, q, lv + 2, du, x + h * k3, vc)
            x = x + h6 * (k1 + 2.0 * (k2 + k3) + k4)
        out[p] = x
    return out


@_helper
def _six(power, m, du, dv, tu, tv):
    """φ, φ_u, φ_v, φ_uu, φ_uv, φ_vv (rows 0, 1, 2, 5, 6, 7) of tooth m at (t_u, t_v): six
    Horner schemes with their chains interleaved."""
    a0 = a1 = a2 = a5 = a6 = a7 = 0.0
    for i in range(du, -1, -1):
        base = i * (dv + 1)
        r0 = r1 = r2 = r5 = r6 = r7 = 0.0
        for j in range(dv, -1, -1):
            c = base + j
            r0 = r0 * tv + power[m, 0, c]
            r1 = r1 * tv + power[m, 1, c]
            r2 = r2 * tv + power[m, 2, c]
            r5 = r5 * tv + power[m, 5, c]
            r6 = r6 * tv + power[m, 6, c]
            r7 = r7 * tv + power[m, 7, c]
        a0 = a0 * tu + r0
        a1 = a1 * tu + r1
        a2 = a2 * tu + r2
        a5 = a5 * tu + r5
        a6 = a6 * tu + r6
        a7 = a7 * tu + r7
    return a0, a1, a2, a5, a6, a7


@_jit
def project_to_mid(px, py, pz, u, v, z, rho, power, member, du, dv, n_iter):
    """Foot (u, v) of the points (px, py, pz) (P,) [mm] on their tooth's mid-surface, by
    Newton's method with the exact Hessian from the starts (u, v) (P,) [1], at most
    ``n_iter`` steps, each point until |Δu| + |Δv| < 1e-14 (arguments as
    :func:`trajectory`). Returns (u, v) (P,) each."""
    uo = u.copy()
    vo = v.copy()
    for p in range(u.size):
        m = member[p]
        rho_p = math.hypot(px[p], py[p])
        phi_p = math.atan2(py[p], px[p])
        z0, zu0, zv0, z_uv = z[0, p], z[1, p], z[2, p], z[3, p]
        r0, ru0, rv0, r_uv = rho[0, p], rho[1, p], rho[2, p], rho[3, p]
        a = uo[p]
        b = vo[p]
        for _ in range(n_iter):
            tu = 2.0 * a - 1.0
            tv = 2.0 * b - 1.0
            zu = zu0 + z_uv * b
            ru = ru0 + r_uv * b
            zv = zv0 + z_uv * a
            rv = rv0 + r_uv * a
            zz = z0 + zu0 * a + b * zv
            r = r0 + ru0 * a + b * rv
            phi, fu, fv, fuu, fuv, fvv = _six(power, m, du, dv, tu, tv)
            step_u, step_v = _projection_step(rho_p, phi_p, pz[p], zz, r, zu, ru, zv, rv,
                                              z_uv, r_uv, phi, fu, fv, fuu, fuv, fvv)
            a += step_u
            b += step_v
            if abs(step_u) + abs(step_v) < 1e-14:
                break
        uo[p] = a
        vo[p] = b
    return uo, vo
