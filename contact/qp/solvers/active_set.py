"""Our own exact solver of the loaded-contact LCP: a contact-set (block principal pivoting) method.

For dense SPD compliance matrices of LTCA size (N ≈ 50–2000) an exact pivoting
method on the KKT system beats general QP codes: each iteration is one Cholesky
factorisation of the compliance restricted to the current contact set, and the
contact set of a gear mesh changes little from one roll position to the next.

Algorithm (block principal pivoting, Kostreva 1978; Júdice & Pires 1994, with
the equilibrium equation carried by the scalar Schur complement):

1. start from a contact set A (warm start: the previous roll position's; cold:
   the exact solution of a lumped-compliance approximation, :func:`initial_contact_set`);
2. solve the KKT system on A exactly (:func:`contact.qp.problem.solve_on_contact_set`);
3. drop the segments of A whose force is negative, add those outside A that
   penetrate (Y < 0), and repeat until neither exists.

With force limits (0 ≤ F ≤ F_max, :class:`contact.qp.ContactProblem`'s ``upper_bound``)
each segment is in one of three states — open (F = 0), loaded (0 < F < F_max, Y = 0) or
at its limit (F = F_max, Y ≤ 0) — and step 3 pivots between them (the box-constrained
block pivoting of Júdice & Pires 1994, §5): a loaded segment with F < 0 opens, one with
F > F_max goes to its limit; an open one that penetrates (Y < 0) and one at its limit
whose gap opens (Y > 0) are loaded again. Without limits it is the method above, step
for step.

Block pivoting can cycle in theory. Guard: an iteration cap and a record of the
sets already visited; when either trips, the solver falls back to a primal
active-set method (Nocedal & Wright 2006, Alg. 16.3), which keeps a feasible
point, decreases the objective monotonically and therefore terminates.

References
----------
M. M. Kostreva (1978). Block pivoting methods for solving the complementarity problem.
Linear Algebra Appl. 21, 207–215.
J. J. Júdice and F. M. Pires (1994). A block principal pivoting algorithm for large-scale
strictly monotone linear complementarity problems. Comput. Oper. Res. 21, 587–596.
J. Nocedal and S. J. Wright (2006). *Numerical Optimization*, 2nd ed., Springer, §16.5.
"""

from __future__ import annotations

import time

import numpy as np

from contact.qp.problem import (
    ContactProblem,
    ProblemScale,
    reduced_kkt,
    schur_floor,
    solve_on_contact_set,
)
from geometry.core.kernels import kernels_module

#: the compiled block pivoting's module (:func:`geometry.core.kernels.kernels_module`)
PIVOTING_KERNELS = "contact.qp.solvers.pivoting_numba"
_KERNEL_MODULE = PIVOTING_KERNELS

#: the block pivoting's outcomes (its NumPy and compiled loops): solved, a contact set
#: visited again, a set that cannot carry the torque, the iteration cap
SOLVED, CYCLED, CANNOT_CARRY, ITERATION_CAP = 0, 1, 2, 3
_OUTCOMES = {CYCLED: "cycled (contact set repeated)",
             CANNOT_CARRY: "contact set cannot carry the torque"}

__all__ = [
    "PIVOTING_KERNELS",
    "block_pivoting",
    "initial_contact_set",
    "initial_contact_sets",
    "pivoting_thresholds",
    "primal_active_set",
]

# Sign tests are relative to the problem's reference force f₀ and length δ₀;
# 1e-12 sits above round-off of the reduced KKT solve (κ ≲ 1e8 → ~1e-8 relative
# error only in ill-conditioned directions, where it is absorbed by the residual
# check) and far below any physical force or gap.
_SIGN_TOL = 1e-12


def _thresholds(problem: ContactProblem) -> tuple[float, float]:
    return pivoting_thresholds(problem.scale)[:2]


def pivoting_thresholds(scale: ProblemScale) -> tuple[float, float, float]:
    """The block pivoting's thresholds of a problem of this scale: the sign tests' force
    [N] and gap [mm] (1e-12 of f₀ and δ₀) and the least Schur complement taken as
    positive [mm·N] (:func:`contact.qp.problem.schur_floor`).

    Parameters
    ----------
    scale : contact.qp.problem.ProblemScale

    Returns
    -------
    (f_tol, y_tol, floor) : (float, float, float) — [N], [mm], [mm·N]
    """
    return _SIGN_TOL * scale.force, _SIGN_TOL * scale.length, scale.schur_floor


def initial_contact_set(problem: ContactProblem) -> np.ndarray:
    """A cold-start contact set from a lumped (row-sum) compliance, solved exactly.

    With each segment's deflection approximated by cᵢ Fᵢ, cᵢ = Σⱼ Cᵢⱼ (exact for a
    uniform load on a smooth influence field), the contact problem decouples:
    Fᵢ(Θ) = max(0, (Rᵢ Θ − sᵢ)/cᵢ) and Σ Rᵢ Fᵢ(Θ) = T is piecewise linear and
    increasing in Θ ("water filling"), solved exactly by sorting the break points
    Θᵢ = sᵢ/Rᵢ. The loaded set of that approximation starts the block pivoting.

    Returns
    -------
    bool array (N,)
    """
    R, s = problem.moment_arm, problem.separation
    c = problem.compliance.sum(axis=1)
    idx = ((R > 0) & (c > 0)).nonzero()[0]
    if idx.size == 0:
        return R > 0
    brk = s.take(idx) / R.take(idx)
    order = brk.argsort()
    idx, brk = idx.take(order), brk.take(order)
    R_i, s_i, c_i = R.take(idx), s.take(idx), c.take(idx)
    a = (R_i * R_i / c_i).cumsum()
    b = (R_i * s_i / c_i).cumsum()
    theta = (problem.torque + b) / a  # Θ if the first k+1 segments are loaded
    # the first k whose Θ lies before the next break point (the last one always does)
    before = theta[:-1] <= brk[1:]
    k = int(before.argmax()) if np.count_nonzero(before) else idx.size - 1
    active = np.zeros(problem.size, dtype=bool)
    active[idx[: k + 1]] = True
    return active


def initial_contact_sets(problem: ContactProblem) -> tuple[np.ndarray, np.ndarray]:
    """The cold-start sets of :func:`initial_contact_set` for a problem with force limits.

    With the lumped compliance cᵢ = Σⱼ Cᵢⱼ each segment's force is
    Fᵢ(Θ) = clip((Rᵢ Θ − sᵢ)/cᵢ, 0, F_max,ᵢ): loaded from Θ = sᵢ/Rᵢ, at its limit from
    Θ = (sᵢ + cᵢ F_max,ᵢ)/Rᵢ. Σ Rᵢ Fᵢ(Θ) is piecewise linear and non-decreasing; sorting
    the break points of both kinds gives it piece by piece and the Θ where it equals T,
    exactly. Without limits this is :func:`initial_contact_set`.

    Returns
    -------
    (loaded, at_limit) : bool arrays (N,), disjoint
    """
    if not problem.has_bounds:
        return initial_contact_set(problem), np.zeros(problem.size, dtype=bool)
    R, s, U = problem.moment_arm, problem.separation, problem.upper_bound
    c = problem.compliance.sum(axis=1)
    idx = ((R > 0) & (c > 0)).nonzero()[0]
    none = np.zeros(problem.size, dtype=bool)
    if idx.size == 0:
        return R > 0, none
    R_i, s_i, c_i, U_i = R[idx], s[idx], c[idx], U[idx]
    a, b = R_i * R_i / c_i, R_i * s_i / c_i
    lo = s_i / R_i
    fin = np.isfinite(U_i)
    hi = np.where(fin, (s_i + c_i * np.where(fin, U_i, 0.0)) / R_i, np.inf)
    # events: (place, change of slope, change of the constant of g(Θ) = slope Θ + const)
    where = np.r_[lo, hi[fin]]
    d_slope = np.r_[a, -a[fin]]
    d_const = np.r_[-b, b[fin] + R_i[fin] * U_i[fin]]
    order = np.argsort(where, kind="stable")
    where, slope, const = where[order], np.cumsum(d_slope[order]), np.cumsum(d_const[order])
    nxt = np.r_[where[1:], np.inf]
    with np.errstate(divide="ignore", invalid="ignore"):
        theta = (problem.torque - const) / slope
    ok = (slope > 0) & (theta >= where) & (theta <= nxt)
    if not np.any(ok):  # the lumped segments cannot carry T at their limits
        return R > 0, none
    th = float(theta[int(np.argmax(ok))])
    loaded, at_limit = none.copy(), none.copy()
    at_limit[idx] = fin & (th >= hi)
    loaded[idx] = (th > lo) & ~at_limit[idx]
    if not np.any(loaded):  # keep one loaded segment to carry Θ
        loaded[idx[int(np.argmin(np.abs(th - hi)))]] = True
        at_limit &= ~loaded
    return loaded, at_limit


def _feasible_start(problem: ContactProblem) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A feasible point of the bounded problem and its working sets: the torque put on
    the segments of largest moment arm, each filled to its limit in turn.

    Returns
    -------
    (F (N,) [N], free (N,) bool, at_limit (N,) bool)
    """
    n = problem.size
    R, U, T = problem.moment_arm, problem.upper_bound, problem.torque
    F = np.zeros(n)
    free = np.zeros(n, dtype=bool)
    at_limit = np.zeros(n, dtype=bool)
    rest = T
    for i in np.argsort(-R, kind="stable"):
        if R[i] <= 0:
            break
        f = min(U[i], rest / R[i])
        F[i] = f
        rest -= R[i] * f
        if f < U[i] or rest <= 1e-14 * T:
            free[i] = True  # the last one carries Θ
            break
        at_limit[i] = True
    return F, free, at_limit


def primal_active_set(
    problem: ContactProblem, *, max_iterations: int | None = None
) -> tuple[np.ndarray, float, int, bool]:
    """Primal active-set method for min ½FᵀCF + sᵀF s.t. 0 ≤ F ≤ F_max, RᵀF = T.

    Starts from a feasible point (the whole torque on the segment with the largest moment
    arm; with force limits, the segments of largest arm filled to their limits in turn);
    each iteration solves the equality-constrained problem on the free set (the others
    held at 0 or at their limits), steps to it as far as feasibility allows, and frees the
    bound with the most negative multiplier when the step is complete — the gap Y of an
    open segment, −Y of one at its limit. The objective decreases monotonically, so the
    method terminates (Nocedal & Wright, *Numerical Optimization*, 2nd ed., 2006,
    Alg. 16.3).

    Parameters
    ----------
    problem : ContactProblem
    max_iterations : int, optional
        Default 10 N + 10.

    Returns
    -------
    force : ndarray (N,) — [N]
    rotation : float — [rad]
    iterations : int
    converged : bool
    """
    n = problem.size
    U = problem.upper_bound
    _, y_tol = _thresholds(problem)
    if max_iterations is None:
        max_iterations = 10 * n + 10
    F, free, upper = _feasible_start(problem)
    theta = 0.0
    for it in range(1, max_iterations + 1):
        sol = solve_on_contact_set(problem, free, upper)
        if sol is None:  # cannot happen from a feasible start with R_k > 0; guard anyway
            return F, theta, it, False
        F_star, theta = sol
        p = F_star - F
        to_lower = free & (p < 0) & (F_star < 0)
        to_upper = free & (p > 0) & (F_star > U)
        if np.any(to_lower) or np.any(to_upper):
            ratios = np.full(n, np.inf)
            ratios[to_lower] = F[to_lower] / -p[to_lower]
            ratios[to_upper] = (U[to_upper] - F[to_upper]) / p[to_upper]
            leave = int(np.argmin(ratios))
            F = F + float(ratios[leave]) * p
            free[leave] = False
            if to_upper[leave]:
                F[leave] = U[leave]
                upper[leave] = True
            else:
                F[leave] = 0.0
            continue
        F = F_star
        # multipliers of the bounds in the working set: Y of the open segments, −Y of
        # those at their limits; the most negative is freed
        Y = problem.gap(F, theta)
        mult = np.where(upper, -Y, Y)
        mult[free] = np.inf
        j = int(np.argmin(mult))
        if mult[j] >= -y_tol:
            return F, theta, it, True
        free[j] = True
        upper[j] = False
    return F, theta, max_iterations, False


def block_pivoting(
    problem: ContactProblem,
    *,
    initial_active_set: np.ndarray | None = None,
    initial_upper_set: np.ndarray | None = None,
    max_iterations: int = 50,
    fallback: bool = True,
) -> dict:
    """Solve the contact LCP by block principal pivoting with a guarded fallback.

    Parameters
    ----------
    problem : ContactProblem
    initial_active_set : bool array (N,), optional
        Warm start, e.g. ``previous_solution.active_set``. Default:
        :func:`initial_contact_sets`.
    initial_upper_set : bool array (N,), optional
        Warm start of the segments at their force limits (e.g.
        ``previous_solution.at_limit(problem)``); ignored where a segment has no limit.
    max_iterations : int
        Cap on block-pivoting iterations before falling back (default 50; 3–6 are
        typical for LTCA problems).
    fallback : bool
        Fall back to :func:`primal_active_set` on cycling or the cap (default True).

    Returns
    -------
    dict with ``force`` [N], ``rotation`` [rad], ``iterations``, ``converged``,
    ``status``, ``solve_time`` [s], ``fallback`` (bool).

    Notes
    -----
    Where numba is installed (and ``LTCA_KERNELS`` is not ``numpy``) the iterations run
    compiled (:mod:`contact.qp.solvers.pivoting_numba`: the same sets, tests and pivots,
    ~6× faster on LTCA problems); the fallback runs in NumPy either way.
    """
    t0 = time.perf_counter()
    f_tol, y_tol = _thresholds(problem)
    floor = schur_floor(problem)
    active, upper = _start_sets(problem, initial_active_set, initial_upper_set)
    kernels = kernels_module(_KERNEL_MODULE)
    if kernels is not None:  # the same iterations, compiled
        # C and s as writable copies, R and F_max as the problem's read-only arrays: the
        # array types (numba specialises on the read-only flag) of the Weber iteration's
        # compiled warm solve (pivoting_numba.warm_solve), so that the kernel is compiled
        # once for both, not twice on a fresh numba cache
        F, theta, it, outcome = kernels.block_pivoting(
            np.array(problem.compliance), np.array(problem.separation), problem.moment_arm,
            float(problem.torque), problem.upper_bound, problem.has_bounds, f_tol, y_tol,
            floor, active, upper, int(max_iterations))
    else:
        F, theta, it, outcome = _pivot(problem, active, upper, floor, f_tol, y_tol,
                                       max_iterations)
    if outcome == SOLVED:
        return _result(F, float(theta), int(it), True, "solved", t0, False)
    reason = _OUTCOMES.get(outcome, f"iteration cap ({max_iterations}) reached")
    if not fallback:
        return _result(F, theta, max_iterations, False,
                       f"block pivoting {reason}; fallback disabled", t0, False)
    F, theta, its, ok = primal_active_set(problem)
    return _result(F, theta, its, ok, ("solved" if ok else "failed")
                   + f" (fallback: primal active set; block pivoting {reason})", t0, True)


def _pivot(problem: ContactProblem, active: np.ndarray, upper: np.ndarray, floor: float,
           f_tol: float, y_tol: float, max_iterations: int):
    """The block pivoting's iterations from the sets ``active`` and ``upper`` (updated in
    place), in NumPy: F (N,) [N], Θ [rad], iterations and the outcome (:data:`SOLVED`,
    :data:`CYCLED`, :data:`CANNOT_CARRY` or :data:`ITERATION_CAP`; F, Θ the last solution
    otherwise). :func:`contact.qp.solvers.pivoting_numba.block_pivoting` is the same
    loop, compiled."""
    n = problem.size
    C, s, R = problem.compliance, problem.separation, problem.moment_arm
    bounded = problem.has_bounds
    F = np.zeros(n)
    theta = 0.0
    seen: set[bytes] = set()
    for it in range(1, max_iterations + 1):
        key = active.tobytes() + upper.tobytes()
        if key in seen:
            return F, theta, it, CYCLED
        seen.add(key)
        sol = _solve_sets(problem, active, upper, floor)
        if sol is None:
            # the set cannot carry the torque: add the loaded-side segments back
            active = (active | (R > 0)) & ~upper
            sol = _solve_sets(problem, active, upper, floor)
            if sol is None:
                return F, theta, it, CANNOT_CARRY
        F, theta = sol
        idx = active.nonzero()[0]
        F_A = F[idx]
        # the gaps Y = C F + s − R Θ: on A they vanish by construction, off A they must
        # not be negative (nor positive at a limit); on A the forces must lie within
        # [0, F_max] (count_nonzero: the cheapest test of a small boolean array)
        Y = C @ F + s - R * theta
        drop = F_A < -f_tol
        add = Y < -y_tol
        add[idx] = False
        if not bounded:
            if not np.count_nonzero(drop) and not np.count_nonzero(add):
                return F, theta, it, SOLVED
            active[idx[drop]] = False
            active |= add
            continue
        U = problem.upper_bound
        raise_ = F_A > U[idx] + f_tol
        add[upper] = False
        release = upper & (Y > y_tol)
        if not (np.count_nonzero(drop) or np.count_nonzero(add) or np.count_nonzero(raise_)
                or np.count_nonzero(release)):
            return F, theta, it, SOLVED
        active[idx[drop | raise_]] = False
        upper[idx[raise_]] = True
        upper &= ~release
        active |= add | release
    return F, theta, max_iterations, ITERATION_CAP


def _start_sets(problem: ContactProblem, active0: np.ndarray | None,
                upper0: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """The block pivoting's first (loaded, at-limit) sets: the warm start where it can
    carry the torque, else the cold start (:func:`initial_contact_sets`)."""
    n, R = problem.size, problem.moment_arm
    upper = np.zeros(n, dtype=bool)
    if upper0 is not None and problem.has_bounds:
        upper = np.asarray(upper0, dtype=bool).copy()
        if upper.shape != (n,):
            upper = np.zeros(n, dtype=bool)
        upper &= problem.bounded
    if active0 is None:
        return initial_contact_sets(problem)
    active = np.asarray(active0, dtype=bool).copy()
    if active.shape != (n,):
        return initial_contact_sets(problem)
    active &= ~upper
    if not np.any(active & (R > 0)):
        return initial_contact_sets(problem)
    return active, upper


def _solve_sets(problem: ContactProblem, active: np.ndarray, upper: np.ndarray,
                floor: float) -> tuple[np.ndarray, float] | None:
    """(F (N,) [N], Θ [rad]) on the loaded set with the at-limit set at its limits, or None
    (:func:`contact.qp.problem.reduced_kkt`)."""
    idx = active.nonzero()[0]
    if idx.size == 0:
        return None
    if not np.any(upper):  # the unbounded path of the method, unchanged
        sol = reduced_kkt(problem.compliance, problem.separation, problem.moment_arm,
                          problem.torque, idx, floor)
        if sol is None:
            return None
        F = np.zeros(problem.size)
        F[idx] = sol[0]
        return F, sol[1]
    return solve_on_contact_set(problem, active, upper)


def _result(F: np.ndarray, theta: float, iterations: int, converged: bool, status: str,
            t0: float, fallback: bool) -> dict:
    return {
        "force": F,
        "rotation": theta,
        "iterations": iterations,
        "converged": converged,
        "status": status,
        "solve_time": time.perf_counter() - t0,
        "fallback": fallback,
    }
