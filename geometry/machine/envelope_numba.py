"""Compiled kernel of the envelope solve's Newton method (numba; issue 32).

:func:`geometry.machine.meshing._newton` solves the point equations of the generated
surface (axial position, radius and, in Generate, the equation of meshing; seed Eq. 2.7a,
2.8) by a damped Newton method over a batch of points. In NumPy most of its time is the
interpreter's: a batch is a few to a few hundred points, and each iteration evaluates the
family buffer (:func:`geometry.machine.family.family_buffer`, ~100 array operations). This
kernel runs the same iteration point by point in a compiled loop:

- the cutter vectors of :func:`geometry.machine.family.cutter_buffer` (the blade's
  constant-curvature sections, seed Eq. 2.5–2.6; a placed face-hobbing blade's edge and
  its surface of revolution's normal);
- the family r_g(s, θ, q) and its derivatives of
  :func:`geometry.machine.family.family_buffer` (the folded machine chain, the cradle and
  work rotations, helical and vertical motion, modified roll, face hobbing's indexing
  terms and swept normal);
- the residuals, the analytic Jacobian and the normalised meshing function of
  :func:`geometry.machine.meshing._evaluate` and
  :func:`geometry.machine.family.meshing_buffer`;
- the Cramer's-rule step, the step limits, the stall test and the final check of
  :func:`geometry.machine.meshing._newton`;

and :func:`family` and :func:`evaluate` give the family buffer with its meshing function,
and the residuals with their Jacobian, at given points (the solve's roots, the Jacobians
of its seeds and continuation) without NumPy's per-call overhead.

One compiled kernel, :func:`newton`: :func:`family` and :func:`evaluate` are Python
functions that call it without iterations (``max_iter`` 0), where it evaluates the point's
family buffer and equations at the starts and returns them. On a fresh numba cache, which
``ltca synthesize`` compiles (issue 75), numba compiles every jitted function of the call
graph on its own and again, optimised and linked, into each caller: the kernel was four
entry points and fifteen helpers (24 compilations with the helpers' constant-argument
specialisations, 6.3–6.6 s of CPU), it is one entry point and nine helpers, each of one
signature (10 compilations, 3.2 s; docs/performance.md, "Fewer envelope kernels to
compile"). The helpers take floats or arrays, never a constant index (numba compiles a
function once per constant argument), are compiled without the wrappers that would make
them callable from Python (``_helper``), and are not inlined at numba's IR
(``inline="always"`` compiled in 26 s: each caller types the whole inlined body again).

Every expression is the NumPy path's, in its order, but the two paths do not agree to the
last bit: NumPy forms the chain's products with BLAS (whose kernels may fuse multiply-adds
and sum in another order) and evaluates sin and cos with its own SIMD routines. Both are
the same Newton iteration on the same equations, converged to the same tolerances
(|Δz|, |Δρ| < 1e-10 mm, |f| < 1e-12), so a root differs by the residual's round-off
divided by the Jacobian, ~1e-13 mm or rad (``tests/test_envelope_kernel.py``), far inside
what the guards allow (the 5×5 sweep to 1e-9 relative, which the NumPy path on another BLAS
also meets). The NumPy path stays the reference (``LTCA_KERNELS=numpy``).

This module imports numba; :mod:`geometry.machine.meshing` imports it through
:func:`geometry.core.kernels.kernels_module` only where numba is installed (the ``fast``
extra). The first call compiles the kernel (a few seconds), which numba caches on disk.
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["evaluate", "family", "newton"]

_jit = numba.njit(cache=True, nogil=True)
#: the helpers, called from compiled code only: numba builds (optimises and compiles to
#: machine code) no CPython or C wrapper for them, which unboxed each argument
_helper = numba.njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)

_EPS = float(np.finfo(float).eps)  # np.sinc's stand-in for 0 (geometry.machine.cutter)


@_helper
def _sign(x):
    """np.sign of a float: −1, 0, +1, or NaN."""
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    return x  # 0.0 or NaN


@_helper
def _taylor(coef, q):
    """f, f′, f″ at q of a Taylor motion's coefficients (meshing's ``_taylor_values``)."""
    f = coef[0, 0]
    d1 = coef[0, 1]
    d2 = coef[0, 2]
    power = 1.0
    for i in range(1, coef.shape[0]):
        power = q if i == 1 else power * q
        f += power * coef[i, 0]
        d1 += power * coef[i, 1]
        d2 += power * coef[i, 2]
    return f, d1, d2


@_helper
def _turn(w0, w1, w2, c, sn):
    """R_z(θ) w (c, sn: cos θ, sin θ); floats only, so that numba compiles it once (a
    column index passed as a constant would be compiled once per constant)."""
    return c * w0 - sn * w1, sn * w0 + c * w1, w2


@_helper
def _cutter(sec, sigma, placed, place, s, theta, k, v):
    """The cutter vectors (3, 7) of ``cutter_buffer`` at one point, into ``v``."""
    # blade_profile / _curve_point: the constant-curvature section k at arc length s
    t = s - sec[0, k]
    kappa = sec[4, k]
    half = 0.5 * kappa * t
    y = math.pi * (half / math.pi)
    if y == 0.0:
        y = _EPS
    sinc = math.sin(y) / y
    mid = sec[3, k] + half
    rho = sec[1, k] + t * math.cos(mid) * sinc
    h = sec[2, k] + t * math.sin(mid) * sinc
    psi = sec[3, k] + kappa * t
    drho = math.cos(psi)
    dh = math.sin(psi)
    d2rho = -kappa * dh
    d2h = kappa * drho
    c = math.cos(theta)
    sn = math.sin(theta)
    if not placed:
        v[0, 0] = rho * c
        v[0, 1] = drho * c
        v[0, 3] = d2rho * c
        v[0, 6] = -sigma * dh * c
        v[1, 0] = rho * sn
        v[1, 1] = drho * sn
        v[1, 3] = d2rho * sn
        v[1, 6] = -sigma * dh * sn
        v[2, 0] = -h
        v[2, 1] = -dh
        v[2, 3] = -d2h
        v[2, 6] = -sigma * drho
        v[0, 2] = -rho * sn
        v[1, 2] = rho * c
        v[0, 4] = -drho * sn
        v[1, 4] = drho * c
    else:
        # blade_edge: e = M + (ρ − r_p) a1 − h a2 and its s-derivatives, turned by θ
        rr = rho - place[9]
        e0 = place[0] + rr * place[3] - h * place[6]
        e1 = place[1] + rr * place[4] - h * place[7]
        e2 = place[2] + rr * place[5] - h * place[8]
        s0 = drho * place[3] - dh * place[6]
        s1 = drho * place[4] - dh * place[7]
        s2 = drho * place[5] - dh * place[8]
        v[0, 0], v[1, 0], v[2, 0] = _turn(e0, e1, e2, c, sn)
        v[0, 1], v[1, 1], v[2, 1] = _turn(s0, s1, s2, c, sn)
        v[0, 3], v[1, 3], v[2, 3] = _turn(d2rho * place[3] - d2h * place[6],
                                          d2rho * place[4] - d2h * place[7],
                                          d2rho * place[5] - d2h * place[8], c, sn)
        # revolution_normal: −σ e′ × (e_z × e), normalised
        b0 = -e1
        b1 = e0
        b2 = 0.0
        n0 = -sigma * (s1 * b2 - s2 * b1)
        n1 = -sigma * (s2 * b0 - s0 * b2)
        n2 = -sigma * (s0 * b1 - s1 * b0)
        norm = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
        v[0, 6], v[1, 6], v[2, 6] = _turn(n0 / norm, n1 / norm, n2 / norm, c, sn)
        v[0, 2] = -v[1, 0]
        v[1, 2] = v[0, 0]
        v[0, 4] = -v[1, 1]
        v[1, 4] = v[0, 1]
    v[0, 5] = -v[0, 0]
    v[1, 5] = -v[1, 0]
    v[2, 2] = 0.0
    v[2, 4] = 0.0
    v[2, 5] = 0.0


@_helper
def _roll(roll_coef, ratio_of_roll, generate, q):
    """The work rotation φ(q) and its derivatives φ′, φ″ (φ″ only with modified roll,
    ``has_d2``): φ = R_a q, or R_a (q − C q² − …) from the Taylor coefficients."""
    if not generate:
        return 0.0, 0.0, 0.0, False
    if roll_coef.shape[0]:
        phi, d1, d2 = _taylor(roll_coef, q)
        return ratio_of_roll * phi, ratio_of_roll * d1, ratio_of_roll * d2, True
    return ratio_of_roll * q, ratio_of_roll, 0.0, False


@_helper
def _family(k_lin, k_point, r2_y, r2_z, motion, em_coef, xb_coef, roll_coef, scalars,
            generate, v, q, theta, pk, dc, d2c, y, out):
    """The family buffer (3, 11) of ``family_buffer`` at one point, into ``out``."""
    cradle, blank_offset, sliding_base, ratio_of_roll, kappa = (
        scalars[0], scalars[1], scalars[2], scalars[3], scalars[4])
    for r in range(9):
        for j in range(7):
            pk[r, j] = k_lin[r, 0] * v[0, j] + k_lin[r, 1] * v[1, j] + k_lin[r, 2] * v[2, j]
        pk[r, 0] += k_point[r]
    a = cradle + q
    ca = math.cos(a)
    sa = math.sin(a)
    for i in range(3):
        for j in range(7):
            y[i, j] = pk[i, j] * ca + pk[3 + i, j] * sa + pk[6 + i, j]
        for j in range(3):
            dc[i, j] = pk[3 + i, j] * ca - pk[i, j] * sa
        d2c[i] = -(pk[i, 0] * ca + pk[3 + i, 0] * sa)
    if motion:
        # the vertical motion E_m(q) and helical motion X_b(q), added to c, c′ and c″
        if em_coef.shape[0]:
            em, dem, d2em = _taylor(em_coef, q)
        else:
            em, dem, d2em = blank_offset, 0.0, 0.0
        if xb_coef.shape[0]:
            xb, dxb, d2xb = _taylor(xb_coef, q)
        else:
            xb, dxb, d2xb = sliding_base, 0.0, 0.0
        for i in range(3):
            y[i, 0] += r2_y[i] * -em + r2_z[i] * xb
            dc[i, 0] += r2_y[i] * -dem + r2_z[i] * dxb
            d2c[i] += r2_y[i] * -d2em + r2_z[i] * d2xb
    if not generate and kappa == 0.0:
        for i in range(3):
            for j in range(7):
                out[i, j] = y[i, j]
            for j in range(3):
                out[i, 7 + j] = dc[i, j]
            out[i, 10] = d2c[i]
        return
    phi, d1, d2, has_d2 = _roll(roll_coef, ratio_of_roll, generate, q)
    for j in range(3):
        y[0, 7 + j] = dc[0, j] + d1 * y[1, j]
        y[1, 7 + j] = dc[1, j] - d1 * y[0, j]
        y[2, 7 + j] = dc[2, j]
    y[0, 10] = d2c[0] + 2.0 * d1 * dc[1, 0] - d1 * d1 * y[0, 0]
    y[1, 10] = d2c[1] - 2.0 * d1 * dc[0, 0] - d1 * d1 * y[1, 0]
    y[2, 10] = d2c[2]
    if has_d2:
        y[0, 10] += d2 * y[1, 0]
        y[1, 10] -= d2 * y[0, 0]
    if kappa != 0.0:
        # _index_terms: S y_k = (−y_y, y_x, 0), taken before the updates
        s_c0, s_c1 = -y[1, 0], y[0, 0]
        s_cs0, s_cs1 = -y[1, 1], y[0, 1]
        s_ct0, s_ct1 = -y[1, 2], y[0, 2]
        s_yq0, s_yq1 = -y[1, 7], y[0, 7]
        y[0, 5] += -2.0 * kappa * s_ct0 - kappa * kappa * y[0, 0]
        y[1, 5] += -2.0 * kappa * s_ct1 - kappa * kappa * y[1, 0]
        y[0, 2] -= kappa * s_c0
        y[1, 2] -= kappa * s_c1
        y[0, 4] -= kappa * s_cs0
        y[1, 4] -= kappa * s_cs1
        y[0, 9] -= kappa * s_yq0
        y[1, 9] -= kappa * s_yq1
        phi = phi + kappa * theta
    cf = math.cos(phi)
    sf = -math.sin(phi)
    for j in range(11):
        out[0, j] = cf * y[0, j] - sf * y[1, j]
        out[1, j] = sf * y[0, j] + cf * y[1, j]
        out[2, j] = y[2, j]
    if kappa != 0.0:
        # _swept_normal: ±(r_s × r_θ)/|r_s × r_θ|, oriented by the revolution normal
        n0 = out[1, 1] * out[2, 2] - out[2, 1] * out[1, 2]
        n1 = out[2, 1] * out[0, 2] - out[0, 1] * out[2, 2]
        n2 = out[0, 1] * out[1, 2] - out[1, 1] * out[0, 2]
        scale = (_sign(n0 * out[0, 6] + n1 * out[1, 6] + n2 * out[2, 6])
                 / math.sqrt(n0 * n0 + n1 * n1 + n2 * n2))
        out[0, 6] = n0 * scale
        out[1, 6] = n1 * scale
        out[2, 6] = n2 * scale


@_helper
def _cross(a0, a1, a2, b0, b1, b2):
    """a × b (``_cross0``'s components); floats only, so that numba compiles it once (a
    column index passed as a constant would be compiled once per constant)."""
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@_helper
def _meshing(out, length_scale, grad):
    """f and its gradient (into ``grad`` (3,)) of ``meshing_buffer`` at one point."""
    rs0, rs1, rs2 = out[0, 1], out[1, 1], out[2, 1]  # r_s
    rt0, rt1, rt2 = out[0, 2], out[1, 2], out[2, 2]  # r_θ
    n0, n1, n2 = _cross(rs0, rs1, rs2, rt0, rt1, rt2)
    nn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
    sign = _sign(n0 * out[0, 6] + n1 * out[1, 6] + n2 * out[2, 6])
    scale = sign / (nn * length_scale)
    g = n0 * out[0, 7] + n1 * out[1, 7] + n2 * out[2, 7]
    for j in range(3):
        # dN/d(s, θ, q) = (r_ss, r_sθ, r_sq) × r_θ + r_s × (r_sθ, r_θθ, r_θq)
        ia = 3 if j == 0 else 4 if j == 1 else 8
        ib = 4 if j == 0 else 5 if j == 1 else 9
        ic = 8 if j == 0 else 9 if j == 1 else 10
        t0, t1, t2 = _cross(out[0, ia], out[1, ia], out[2, ia], rt0, rt1, rt2)
        u0, u1, u2 = _cross(rs0, rs1, rs2, out[0, ib], out[1, ib], out[2, ib])
        d0 = t0 + u0
        d1 = t1 + u1
        d2 = t2 + u2
        dg = ((d0 * out[0, 7] + d1 * out[1, 7] + d2 * out[2, 7])
              + (out[0, ic] * n0 + out[1, ic] * n1 + out[2, ic] * n2))
        dnn = (n0 * d0 + n1 * d1 + n2 * d2) / nn
        grad[j] = (dg - g * dnn / nn) * scale
    return g * scale


@_helper
def _step(jac, f, m, limit, dx):
    """The Newton step J dx = −f into ``dx`` (``_safe_solve``) and the factor (≤ 1) that
    holds it within ``limit``; NaN where J is (near-)singular or the step is not finite."""
    # _safe_solve: Cramer's rule, singular where |det J| ≤ 1e-13 Π|J_i|
    norms = 1.0
    for r in range(m):
        acc = jac[r, 0] * jac[r, 0]
        for j in range(1, m):
            acc += jac[r, j] * jac[r, j]
        norms = math.sqrt(acc) if r == 0 else norms * math.sqrt(acc)
    b0, b1 = -f[0], -f[1]
    if m == 2:
        a00, a01, a10, a11 = jac[0, 0], jac[0, 1], jac[1, 0], jac[1, 1]
        det = a00 * a11 - a01 * a10
        good = abs(det) > 1e-13 * (norms if norms > 0 else 1.0)
        if not good:
            return math.nan
        inv_det = 1.0 / det
        dx[0] = (a11 * b0 + -a01 * b1) * inv_det
        dx[1] = (-a10 * b0 + a00 * b1) * inv_det
    else:
        b2 = -f[2]
        a00, a01, a02 = jac[0, 0], jac[0, 1], jac[0, 2]
        a10, a11, a12 = jac[1, 0], jac[1, 1], jac[1, 2]
        a20, a21, a22 = jac[2, 0], jac[2, 1], jac[2, 2]
        c0 = a11 * a22 - a12 * a21
        c1 = a12 * a20 - a10 * a22
        c2 = a10 * a21 - a11 * a20
        det = a00 * c0 + a01 * c1 + a02 * c2
        good = abs(det) > 1e-13 * (norms if norms > 0 else 1.0)
        if not good:
            return math.nan
        inv_det = 1.0 / det
        dx[0] = (c0 * b0 + (a02 * a21 - a01 * a22) * b1
                 + (a01 * a12 - a02 * a11) * b2) * inv_det
        dx[1] = (c1 * b0 + (a00 * a22 - a02 * a20) * b1
                 + (a02 * a10 - a00 * a12) * b2) * inv_det
        dx[2] = (c2 * b0 + (a01 * a20 - a00 * a21) * b1
                 + (a00 * a11 - a01 * a10) * b2) * inv_det
    # the step limit: min over the unknowns of limit / |dx| (NaN propagates)
    factor = math.inf
    for j in range(m):
        a = abs(dx[j])
        ratio = limit[j] / (a if (a > 1e-300 or a != a) else 1e-300)
        if ratio != ratio or factor != factor:
            factor = math.nan
        elif ratio < factor:
            factor = ratio
    if factor == factor and factor > 1.0:
        factor = 1.0
    return factor


@_jit
def newton(x0, section, z, p, sec, sigma, placed, place, k_lin, k_point, r2_y, r2_z,
           motion, em_coef, xb_coef, roll_coef, scalars, generate, limit, controls,
           max_iter, stall_iter):
    """Damped Newton on the point equations, point by point (meshing's ``_newton``).

    Parameters
    ----------
    x0 : (n, m) float
        Starts (s [mm], θ [rad][, q [rad]]); m = 3 in Generate, 2 in Formate.
    section : (n,) int
        Blade section of each point.
    z, p : (n,) float — [mm]
        Target axial positions and radii.
    sec : (5, n_sec) float
        The sections' s_ref, ρ_ref, h_ref, ψ_ref, κ (:class:`ProfileSections`).
    sigma : float
        Side sign σ (±1).
    placed : bool
        A placed (face-hobbing) blade; ``place`` (10,): M (3), a1 (3), a2 (3) of
        :func:`geometry.machine.cutter.placement_vectors` and the point radius.
    k_lin, k_point, r2_y, r2_z, motion
        The folded chain (:class:`geometry.machine.family.Chain`), k_point flat (9,).
    em_coef, xb_coef, roll_coef : (k, 3) float
        Taylor coefficients of the vertical motion, helical motion and modified roll
        (k = 0: none).
    scalars : (6,) float
        Cradle angle [rad], blank offset [mm], sliding base [mm], ratio of roll,
        indexing ratio, length scale L [mm].
    generate : bool
        Generate (q solved) or Formate (q ≡ 0).
    limit : (m,) float
        Largest Newton step per unknown [mm, rad, rad].
    controls : (3,) float
        Position tolerance [mm], meshing tolerance [1], stall size [mm].
    max_iter, stall_iter : int
        Iteration limit; the iteration after which far points are abandoned
        (``max_iter`` 0: the family buffer and the equations at the starts,
        :func:`family` and :func:`evaluate`).

    Returns
    -------
    x : (n, m) float
        The iterates (roots where converged).
    done : (n,) bool
        Converged.
    f_last : (n, m) float
        The residuals at each point's last evaluated iterate (its root where converged,
        its start where ``max_iter`` is 0): axial position, radius [mm] and, in Generate,
        the normalised meshing function [1].
    jac_last : (n, m, m) float
        Their Jacobian in (s, θ[, q]).
    buf_last : (3, 11, n) float
        The family buffer there (:func:`geometry.machine.family.family_buffer`).
    """
    n, m = x0.shape
    x = x0.copy()
    done = np.empty(n, np.bool_)  # (each written below)
    f_last = np.empty((n, m))
    jac_last = np.empty((n, m, m))
    buf_last = np.empty((3, 11, n))
    length_scale = scalars[5]
    tol_pos, tol_mesh, stall_size = controls[0], controls[1], controls[2]
    v = np.empty((3, 7))  # (every entry written by _cutter)
    pk = np.empty((9, 7))
    dc = np.empty((3, 3))
    d2c = np.empty(3)
    y = np.empty((3, 11))
    out = np.empty((3, 11))
    grad = np.empty(3)
    f = np.empty(m)
    jac = np.empty((m, m))
    dx = np.empty(m)
    xi = np.empty(m)
    for i in range(n):
        for j in range(m):
            xi[j] = x[i, j]
        k = section[i]
        dead = False
        converged = False
        for it in range(max_iter + 1):
            q = xi[2] if generate else 0.0
            # the point's family buffer (seed Eq. 2.7a)
            _cutter(sec, sigma, placed, place, xi[0], xi[1], k, v)
            _family(k_lin, k_point, r2_y, r2_z, motion, em_coef, xb_coef, roll_coef, scalars,
                    generate, v, q, xi[1], pk, dc, d2c, y, out)
            # its equations (meshing's _evaluate): the residuals f (m,) (axial position,
            # radius [mm], and in Generate the normalised meshing function) and their
            # Jacobian jac (m, m) in (s, θ[, q])
            rho = math.hypot(out[0, 0], out[1, 0])
            rho_safe = rho if rho > 0 else 1.0
            f[0] = out[2, 0] - z[i]
            f[1] = rho - p[i]
            for j in range(m):
                col = 1 if j == 0 else 2 if j == 1 else 7
                jac[0, j] = out[2, col]
                jac[1, j] = (out[0, 0] * out[0, col] + out[1, 0] * out[1, col]) / rho_safe
            if generate:
                f[2] = _meshing(out, length_scale, grad)
                for j in range(3):
                    jac[2, j] = grad[j]
            converged = abs(f[0]) < tol_pos and abs(f[1]) < tol_pos
            if generate:
                converged = converged and abs(f[2]) < tol_mesh
            if converged or it == max_iter:
                break  # (it == max_iter: the final check after the last update)
            if it >= stall_iter:
                size = abs(f[0]) + abs(f[1]) + (length_scale * abs(f[2]) if generate
                                                else 0.0)
                if size > stall_size:
                    dead = True
                    break
            factor = _step(jac, f, m, limit, dx)
            if factor != factor:  # singular Jacobian (or a NaN step)
                dead = True
                break
            finite = True
            for j in range(m):
                xi[j] += factor * dx[j]
                if not math.isfinite(xi[j]):
                    finite = False
            if not finite:
                dead = True
                break
        for j in range(m):
            x[i, j] = xi[j]
            f_last[i, j] = f[j]
            for b in range(m):
                jac_last[i, j, b] = jac[j, b]
        for a in range(3):
            for b in range(11):
                buf_last[a, b, i] = out[a, b]
        done[i] = converged and not dead
    return x, done, f_last, jac_last, buf_last


def family(s, theta, q, section, sec, sigma, placed, place, k_lin, k_point, r2_y, r2_z,
           motion, em_coef, xb_coef, roll_coef, scalars, generate):
    """The family buffer (3, 11, n) of :func:`geometry.machine.family.family_buffer` (seed
    Eq. 2.7a and its derivatives) at the points (s [mm], θ [rad], q [rad], section) (n,)
    (q ignored in Formate), and in Generate the normalised meshing function f (n,) [1]
    (seed Eq. 2.8) with its gradient (3, n) [1/mm, 1/rad, 1/rad] of the buffer
    (:func:`geometry.machine.family.meshing_buffer` point by point; in Formate empty (0,)
    and (3, 0)); the constant arguments as :func:`newton`'s. :func:`newton` with no
    iteration (``max_iter`` 0), which evaluates the buffer and the equations at the
    starts: one compiled kernel to compile on a fresh cache, not three (issue 75)."""
    n = s.size
    x = np.stack((s, theta, q) if generate else (s, theta), axis=-1)
    f, jac, buf = _at_starts(x, section, np.zeros(n), np.zeros(n), sec, sigma, placed,
                             place, k_lin, k_point, r2_y, r2_z, motion, em_coef, xb_coef,
                             roll_coef, scalars, generate)
    if not generate:
        return buf, np.empty(0), np.empty((3, 0))
    return buf, f[:, 2], jac[:, 2].T


def evaluate(x, section, z, p, sec, sigma, placed, place, k_lin, k_point, r2_y, r2_z,
             motion, em_coef, xb_coef, roll_coef, scalars, generate):
    """Residuals F (n, m) and Jacobian J (n, m, m) of the point equations (seed Eq. 2.7a:
    axial position and radius [mm]; in Generate Eq. 2.8, the normalised meshing function)
    at the points x (n, m) on their sections, targets (z, p) (n,) [mm]: meshing's
    ``_evaluate`` (the constant arguments as :func:`newton`'s); :func:`newton` with no
    iteration (:func:`family`)."""
    return _at_starts(x, section, z, p, sec, sigma, placed, place, k_lin, k_point, r2_y,
                      r2_z, motion, em_coef, xb_coef, roll_coef, scalars, generate)[:2]


def _at_starts(x, section, z, p, *constants):
    """:func:`newton`'s residuals, Jacobian and family buffer at the starts x (no
    iteration; the step limits and tolerances unused)."""
    m = x.shape[1]
    return newton(x, section, z, p, *constants, np.ones(m), np.zeros(3), 0, 0)[2:]
