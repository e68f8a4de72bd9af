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

Block pivoting can cycle in theory. Guard: an iteration cap and a record of the
sets already visited; when either trips, the solver falls back to a primal
active-set method (Nocedal & Wright 2006, Alg. 16.3), which keeps a feasible
point, decreases the objective monotonically and therefore terminates.
"""

from __future__ import annotations

import time

import numpy as np

from contact.qp.problem import ContactProblem, reduced_kkt, schur_floor, solve_on_contact_set

__all__ = ["block_pivoting", "initial_contact_set", "primal_active_set"]

# Sign tests are relative to the problem's reference force f₀ and length δ₀;
# 1e-12 sits above round-off of the reduced KKT solve (κ ≲ 1e8 → ~1e-8 relative
# error only in ill-conditioned directions, where it is absorbed by the residual
# check) and far below any physical force or gap.
_SIGN_TOL = 1e-12


def _thresholds(problem: ContactProblem) -> tuple[float, float]:
    sc = problem.scale
    return _SIGN_TOL * sc.force, _SIGN_TOL * sc.length


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


def primal_active_set(
    problem: ContactProblem, *, max_iterations: int | None = None
) -> tuple[np.ndarray, float, int, bool]:
    """Primal active-set method for min ½FᵀCF + sᵀF s.t. F ≥ 0, RᵀF = T.

    Starts from the feasible point that puts the whole torque on the segment with
    the largest moment arm; each iteration solves the equality-constrained problem
    on the free set, steps to it as far as feasibility allows, and frees the bound
    with the most negative multiplier (the gap Y) when the step is complete.
    The objective decreases monotonically, so the method terminates (Nocedal &
    Wright, *Numerical Optimization*, 2nd ed., 2006, Alg. 16.3).

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
    R = problem.moment_arm
    _, y_tol = _thresholds(problem)
    if max_iterations is None:
        max_iterations = 10 * n + 10
    k = int(np.argmax(R))
    F = np.zeros(n)
    F[k] = problem.torque / R[k]
    free = np.zeros(n, dtype=bool)
    free[k] = True
    theta = 0.0
    for it in range(1, max_iterations + 1):
        sol = solve_on_contact_set(problem, free)
        if sol is None:  # cannot happen from a feasible start with R_k > 0; guard anyway
            return F, theta, it, False
        F_star, theta = sol
        p = F_star - F
        blocking = free & (p < 0) & (F_star < 0)
        if np.any(blocking):
            ratios = F[blocking] / -p[blocking]
            j = int(np.argmin(ratios))
            alpha = float(ratios[j])
            F = F + alpha * p
            leave = np.flatnonzero(blocking)[j]
            F[leave] = 0.0
            free[leave] = False
            continue
        F = F_star
        Y = problem.gap(F, theta)
        Y[free] = 0.0
        j = int(np.argmin(Y))
        if Y[j] >= -y_tol:
            return F, theta, it, True
        free[j] = True
    return F, theta, max_iterations, False


def block_pivoting(
    problem: ContactProblem,
    *,
    initial_active_set: np.ndarray | None = None,
    max_iterations: int = 50,
    fallback: bool = True,
) -> dict:
    """Solve the contact LCP by block principal pivoting with a guarded fallback.

    Parameters
    ----------
    problem : ContactProblem
    initial_active_set : bool array (N,), optional
        Warm start, e.g. ``previous_solution.active_set``. Default:
        :func:`initial_contact_set`.
    max_iterations : int
        Cap on block-pivoting iterations before falling back (default 50; 3–6 are
        typical for LTCA problems).
    fallback : bool
        Fall back to :func:`primal_active_set` on cycling or the cap (default True).

    Returns
    -------
    dict with ``force`` [N], ``rotation`` [rad], ``iterations``, ``converged``,
    ``status``, ``solve_time`` [s], ``fallback`` (bool).
    """
    t0 = time.perf_counter()
    n = problem.size
    C, s, R, T = problem.compliance, problem.separation, problem.moment_arm, problem.torque
    f_tol, y_tol = _thresholds(problem)
    floor = schur_floor(problem)
    if initial_active_set is None:
        active = initial_contact_set(problem)
    else:
        active = np.asarray(initial_active_set, dtype=bool).copy()
        if active.shape != (n,) or not np.any(active & (R > 0)):
            active = initial_contact_set(problem)
    seen: set[bytes] = set()
    reason = f"iteration cap ({max_iterations}) reached"
    F = np.zeros(n)
    theta = 0.0
    for it in range(1, max_iterations + 1):
        key = active.tobytes()
        if key in seen:
            reason = "cycled (contact set repeated)"
            break
        seen.add(key)
        idx = active.nonzero()[0]
        sol = reduced_kkt(C, s, R, T, idx, floor) if idx.size else None
        if sol is None:
            # the set cannot carry the torque: add the loaded-side segments back
            active = active | (R > 0)
            idx = active.nonzero()[0]
            sol = reduced_kkt(C, s, R, T, idx, floor)
            if sol is None:
                reason = "contact set cannot carry the torque"
                break
        F_A, theta = sol
        F = np.zeros(n)
        F[idx] = F_A
        # the gaps Y = C F + s − R Θ: on A they vanish by construction, off A they must
        # not be negative; on A the forces must not be negative (count_nonzero: the
        # cheapest test of a small boolean array)
        Y = C @ F + s - R * theta
        drop = F_A < -f_tol
        add = Y < -y_tol
        add[idx] = False
        if not np.count_nonzero(drop) and not np.count_nonzero(add):
            return {
                "force": F,
                "rotation": theta,
                "iterations": it,
                "converged": True,
                "status": "solved",
                "solve_time": time.perf_counter() - t0,
                "fallback": False,
            }
        active[idx[drop]] = False
        active |= add
    if not fallback:
        return {
            "force": F,
            "rotation": theta,
            "iterations": max_iterations,
            "converged": False,
            "status": f"block pivoting {reason}; fallback disabled",
            "solve_time": time.perf_counter() - t0,
            "fallback": False,
        }
    F, theta, its, ok = primal_active_set(problem)
    return {
        "force": F,
        "rotation": theta,
        "iterations": its,
        "converged": ok,
        "status": ("solved" if ok else "failed")
        + f" (fallback: primal active set; block pivoting {reason})",
        "solve_time": time.perf_counter() - t0,
        "fallback": True,
    }
