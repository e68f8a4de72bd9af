"""Compiled block principal pivoting of the contact LCP (numba; issue 32).

:func:`contact.qp.solvers.active_set.block_pivoting` on an LTCA problem (N ≈ 60–140
segments, ~50 loaded, 1–4 pivots) spends most of its ~0.3 ms in the interpreter: the
KKT solve on a contact set is ~25 k flops. This kernel runs the same iterations in one
compiled loop: the same start sets, the same KKT system on each contact set (seed
Eq. 3.12–3.14: C_AA F_A − R_A Θ = −(s_A + C_AB F_max,B), R_Aᵀ F_A = T − R_Bᵀ F_max,B,
by a Cholesky factorisation of C_AA and the scalar Schur complement,
:func:`contact.qp.problem.reduced_kkt`), the same sign tests, the same pivots and the
same record of visited sets (Kostreva 1978; Júdice & Pires 1994, §5).

The factorisation is the Cholesky–Banachiewicz recurrence (Golub & Van Loan, *Matrix
Computations*, 4th ed., 2013, Alg. 4.2.1) instead of LAPACK's blocked ``potrf``: the two
agree to round-off (the forces to ~1e-13 relative on these problems), so a pivot decision
could differ only where a force or gap lies within round-off of the ±1e-12 sign
thresholds, i.e. where either decision gives a solution within them. The answer is
certified afterwards by :func:`contact.qp.problem.contact_residuals` in NumPy, never here;
the fallback (primal active set) stays in NumPy.

This module imports numba; :mod:`contact.qp.solvers.active_set` uses it where numba is
installed and ``LTCA_KERNELS`` is not ``numpy`` (:func:`geometry.core.kernels.kernels_module`).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from contact.qp.solvers.active_set import CANNOT_CARRY, CYCLED, ITERATION_CAP, SOLVED

__all__ = ["CANNOT_CARRY", "COLD_START", "CYCLED", "ITERATION_CAP", "SOLVED", "block_pivoting",
           "warm_solve"]

#: :func:`warm_solve`'s outcome where the warm start loads no segment that can carry the
#: torque (the cold start, :func:`contact.qp.solvers.active_set.initial_contact_sets`, is
#: the caller's); the others are the kernel's outcomes, those of the NumPy loop (the
#: wrapper words them)
COLD_START = 4

_jit = numba.njit(cache=True, nogil=True)

#: helpers called from compiled code only: no CPython or C wrapper to compile
_helper = numba.njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)


@_helper
def _kkt(C, s, R, T, U, active, upper, floor, L, x_s, x_r, F):
    """The KKT solution on the loaded set ``active`` with ``upper`` at its limits into F
    (N,) [N]; returns Θ [rad], or NaN where C_AA is not positive definite or the Schur
    complement R_Aᵀ C_AA⁻¹ R_A ≤ ``floor`` (the set cannot carry the torque). L, x_s,
    x_r: work arrays (N, N), (N,), (N,)."""
    n = s.size
    idx = np.flatnonzero(active)
    k = idx.size
    if k == 0:
        return np.nan
    # the limits' share: s_A + C_AB F_max,B and T − R_Bᵀ F_max,B
    t_eff = T
    for j in range(n):
        F[j] = 0.0
    jdx = np.flatnonzero(upper)
    for j in jdx:
        F[j] = U[j]
        t_eff -= R[j] * U[j]
    for a in range(k):
        i = idx[a]
        v = s[i]
        for j in jdx:
            v += C[i, j] * U[j]
        x_s[a] = v
        x_r[a] = R[i]
    # C_AA = L Lᵀ
    for a in range(k):
        ia = idx[a]
        d = C[ia, ia]
        for p in range(a):
            d -= L[a, p] * L[a, p]
        if not d > 0.0:
            return np.nan
        d = math.sqrt(d)
        L[a, a] = d
        for b in range(a + 1, k):
            v = C[idx[b], ia]
            for p in range(a):
                v -= L[b, p] * L[a, p]
            L[b, a] = v / d
    # x = C_AA⁻¹ [s_A', R_A]: L y = b, then Lᵀ x = y
    for a in range(k):
        v_s, v_r = x_s[a], x_r[a]
        for p in range(a):
            v_s -= L[a, p] * x_s[p]
            v_r -= L[a, p] * x_r[p]
        x_s[a] = v_s / L[a, a]
        x_r[a] = v_r / L[a, a]
    for a in range(k - 1, -1, -1):
        v_s, v_r = x_s[a], x_r[a]
        for p in range(a + 1, k):
            v_s -= L[p, a] * x_s[p]
            v_r -= L[p, a] * x_r[p]
        x_s[a] = v_s / L[a, a]
        x_r[a] = v_r / L[a, a]
    schur = 0.0
    r_xs = 0.0
    for a in range(k):
        schur += R[idx[a]] * x_r[a]
        r_xs += R[idx[a]] * x_s[a]
    if not schur > floor:
        return np.nan
    theta = (t_eff + r_xs) / schur
    for a in range(k):
        F[idx[a]] = theta * x_r[a] - x_s[a]
    return theta


@_jit
def block_pivoting(C, s, R, T, U, bounded, f_tol, y_tol, floor, active, upper,
                   max_iterations):
    """Block principal pivoting from the sets ``active`` (loaded) and ``upper`` (at their
    limits), as :func:`contact.qp.solvers.active_set.block_pivoting` before its fallback.

    Parameters
    ----------
    C : ndarray (N, N) — [mm/N], symmetric positive definite
    s, R : ndarray (N,) — [mm]
    T : float — [N·mm]
    U : ndarray (N,) — [N], ``inf`` where no limit
    bounded : bool
        Whether any segment has a limit.
    f_tol, y_tol : float — [N], [mm]
        The sign tests' thresholds.
    floor : float — [mm·N]
        The least Schur complement taken as positive.
    active, upper : bool ndarray (N,)
        The start sets (copied).
    max_iterations : int

    Returns
    -------
    F (N,) [N], Θ [rad], iterations, outcome (:data:`SOLVED`, :data:`CYCLED`,
    :data:`CANNOT_CARRY` or :data:`ITERATION_CAP`; F, Θ the last solution otherwise).
    """
    n = s.size
    active = active.copy()
    upper = upper.copy()
    L = np.empty((n, n))
    x_s = np.empty(n)
    x_r = np.empty(n)
    F = np.zeros(n)
    F_out = np.zeros(n)
    theta_out = 0.0
    Y = np.empty(n)
    seen = np.empty((max_iterations, n), dtype=np.int8)
    for it in range(1, max_iterations + 1):
        if _visited(seen, it - 1, active, upper):
            return F_out, theta_out, it, CYCLED
        theta = _kkt(C, s, R, T, U, active, upper, floor, L, x_s, x_r, F)
        if math.isnan(theta):
            # the set cannot carry the torque: add the loaded-side segments back
            for i in range(n):
                active[i] = (active[i] or R[i] > 0) and not upper[i]
            theta = _kkt(C, s, R, T, U, active, upper, floor, L, x_s, x_r, F)
            if math.isnan(theta):
                return F_out, theta_out, it, CANNOT_CARRY
        for i in range(n):  # not F_out[:] = F: a slice assignment compiles numba's
            F_out[i] = F[i]  # shape-mismatch message (~2.6 s on a fresh cache, issue 75)
        theta_out = theta
        # the gaps Y = C F + s − R Θ
        for i in range(n):
            v = 0.0
            for j in range(n):
                v += C[i, j] * F[j]
            Y[i] = v + s[i] - R[i] * theta
        if not _pivot(active, upper, F, Y, U, bounded, f_tol, y_tol):
            return F_out, theta_out, it, SOLVED
    return F_out, theta_out, max_iterations, ITERATION_CAP


@_helper
def _visited(seen, row, active, upper):
    """Record the sets as row ``row`` of ``seen`` (0 open, 1 loaded, 2 at the limit) and
    whether an earlier row holds the same sets (a cycle)."""
    n = active.size
    for i in range(n):
        seen[row, i] = np.int8(1 if active[i] else (2 if upper[i] else 0))
    for r in range(row):
        same = True
        for i in range(n):
            if seen[r, i] != seen[row, i]:
                same = False
                break
        if same:
            return True
    return False


@_helper
def _pivot(active, upper, F, Y, U, bounded, f_tol, y_tol):
    """One block pivot of every segment (in place), and whether any moved: a loaded one
    with F < −f_tol opens, one with F > F_max + f_tol goes to its limit; one at its limit
    whose gap opens (Y > y_tol) is loaded again, an open one that penetrates (Y < −y_tol)
    is loaded. Each segment's move depends on its own F and Y only, so moving them in one
    pass is the NumPy path's test of all, then its moves."""
    moved = False
    for i in range(active.size):
        if active[i]:
            if F[i] < -f_tol:
                active[i] = False
                moved = True
            elif bounded and F[i] > U[i] + f_tol:
                active[i] = False
                upper[i] = True
                moved = True
        elif upper[i]:
            if Y[i] > y_tol:
                upper[i] = False
                active[i] = True
                moved = True
        elif Y[i] < -y_tol:
            active[i] = True
            moved = True
    return moved


@_jit
def warm_solve(C0, diagonal, s, R, T, U, bounded, has_bounds, f_tol, y_tol, floor, start,
               tolerance, f0, d0, r0, max_iterations):
    """One warm-started solve of a problem that differs from a checked one only on C's
    diagonal and in s (Weber's iteration, :mod:`contact.ltca.weber`), certified: what
    :func:`contact.qp.solve_contact` does with the ``active_set`` backend, ``initial``
    forces and the default accuracy, up to its certification, in one compiled call.

    Parameters
    ----------
    C0 : ndarray (N, N) — [mm/N]
        The checked problem's (symmetric) compliance; its diagonal is replaced.
    diagonal : ndarray (N,) — [mm/N]
        The new diagonal of C.
    s, R : ndarray (N,) — [mm]
        Separations and moment arms.
    T : float — [N·mm]
    U : ndarray (N,) — [N], ``inf`` where no limit
    bounded : bool ndarray (N,)
        The segments with a limit.
    has_bounds : bool
    f_tol, y_tol, floor : float — [N], [mm], [mm·N]
        The block pivoting's thresholds (:func:`block_pivoting`) of the new problem.
    start : ndarray (N,) — [N]
        The warm start's forces (finite).
    tolerance : float — [1]
        The certification's relative tolerance on every residual.
    f0, d0, r0 : float — [N], [mm], [mm]
        The new problem's scale (:class:`contact.qp.problem.ProblemScale`).
    max_iterations : int

    Returns
    -------
    F (N,) [N], Θ [rad], iterations, outcome (:data:`SOLVED`, :data:`CYCLED`,
    :data:`CANNOT_CARRY`, :data:`ITERATION_CAP` or :data:`COLD_START`), and whether every
    residual of :func:`contact.qp.contact_residuals` is within ``tolerance`` (the
    caller's certification decides what it reports; this one only whether the solve
    needs the general path's fallback or polish).

    Notes
    -----
    The start sets are :func:`contact.qp.solvers.active_set.block_pivoting`'s from
    ``initial`` forces: loaded where F > 0, at the limit where F ≥ F_max (1 − 1e-9), the
    loaded ones not at their limit; the iterations are :func:`block_pivoting`'s on the same
    arrays (the same forces to the bit). The residuals are those of seed Eq. 3.12–3.14
    (:func:`contact.qp.contact_residuals`), their products summed in order (not BLAS's):
    equal to round-off, so only a residual within round-off of ``tolerance`` could be
    judged otherwise.
    """
    n = s.size
    C = C0.copy()
    for i in range(n):
        C[i, i] = diagonal[i]
    active = np.zeros(n, dtype=np.bool_)
    upper = np.zeros(n, dtype=np.bool_)
    carries = False
    for i in range(n):
        if has_bounds:
            upper[i] = bounded[i] and start[i] >= U[i] * (1.0 - 1e-9)
        active[i] = start[i] > 0 and not upper[i]
        if active[i] and R[i] > 0:
            carries = True
    if not carries:
        return np.zeros(n), 0.0, 0, COLD_START, False
    F, theta, it, outcome = block_pivoting(C, s, R, T, U, has_bounds, f_tol, y_tol, floor,
                                           active, upper, max_iterations)
    if outcome != SOLVED:
        return F, theta, it, outcome, False
    return F, theta, it, outcome, _certified(C, s, R, T, U, bounded, has_bounds, F, theta,
                                             tolerance, f0, d0, r0)


@_helper
def _certified(C, s, R, T, U, bounded, has_bounds, F, theta, tolerance, f0, d0, r0):
    """Whether the residuals of :func:`contact.qp.contact_residuals` of (F, Θ) are finite
    and within ``tolerance`` (their arithmetic, the products summed in order)."""
    n = s.size
    f_abs = 0.0
    for i in range(n):
        f_abs = max(f_abs, abs(F[i]))
    if not (math.isfinite(f_abs) and math.isfinite(theta)):
        return False
    Y = np.empty(n)
    cf_abs = 0.0
    rf = 0.0
    for i in range(n):
        v = 0.0
        for j in range(n):
            v += C[i, j] * F[j]
        cf_abs = max(cf_abs, abs(v))
        Y[i] = v + s[i] - R[i] * theta
        rf += R[i] * F[i]
    f_ref = max(f_abs, f0)
    d_ref = max(cf_abs, abs(theta) * r0, d0)
    primal = 0.0
    dual = 0.0
    comp = 0.0
    upper = 0.0
    for i in range(n):
        neg_y = max(-Y[i], 0.0)
        primal = max(primal, -F[i])
        if has_bounds:
            primal = max(primal, F[i] - U[i])
        if has_bounds and bounded[i]:
            upper = max(upper, min(max(U[i] - F[i], 0.0) / f_ref, neg_y / d_ref))
        else:
            dual = max(dual, neg_y)
        comp = max(comp, min(max(F[i], 0.0) / f_ref, max(Y[i], 0.0) / d_ref))
    worst = max(primal / f_ref, dual / d_ref, comp, abs(rf - T) / T, upper)
    return math.isfinite(worst) and worst <= tolerance
