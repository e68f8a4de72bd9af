"""The contact QP through cvxpy: ``cvxpy`` (its default solver) and ``cvxpy:NAME``.

The quadratic form uses ``psd_wrap`` (C is SPD by construction and checked by
:class:`ContactProblem`), so cvxpy skips its own eigenvalue test. Build time is
cvxpy's canonicalisation; solve time is the wall time of the solver call.
The equality multiplier of ``R̃ᵀF̃ == T̃`` is read with cvxpy's sign convention
(checked on a two-variable problem: the dual of ``R̃ᵀF̃ == T̃`` is the
negative of our Θ̃), so Θ̃ = −y. Force limits (:attr:`ContactProblem.upper_bound`) are
the constraint F̃_b ≤ F_max,b/f₀ on the segments b that have one.
"""

from __future__ import annotations

import time
import warnings
from typing import Any

import numpy as np

from contact.qp.problem import ContactProblem
from contact.qp.solvers.backend import ACCURACY_LEVELS, Backend, RawResult, quiet_highs_banner

__all__ = ["backends"]

try:
    import cvxpy as cp
except ImportError:  # pragma: no cover - cvxpy is a dependency, but keep the registry alive
    cp = None

# cvxpy solvers able to take a convex QP (LP-only and mixed-integer ones left out).
# CVXOPT is left out on purpose: through cvxpy's conic reformulation it failed on every
# LTCA-like problem with N ≥ 60 tried here (cvxpy 1.9, cvxopt 1.3), at default and tight
# settings alike; it stays available directly as the qpsolvers backend "cvxopt".
_QP_CAPABLE = (
    "CLARABEL",
    "OSQP",
    "SCS",
    "ECOS",
    "PIQP",
    "PROXQP",
    "QPALM",
    "DAQP",
    "HIGHS",
    "GUROBI",
    "MOSEK",
)

_FAMILY = {
    "CLARABEL": "interior-point",
    "ECOS": "interior-point",
    "PIQP": "interior-point",
    "OSQP": "ADMM",
    "SCS": "ADMM",
    "PROXQP": "augmented-Lagrangian",
    "QPALM": "augmented-Lagrangian",
    "DAQP": "active-set",
    "HIGHS": "active-set",
}


def _accuracy_options(solver: str | None, accuracy: str) -> dict[str, Any]:
    eps = ACCURACY_LEVELS[accuracy]
    if eps is None or solver is None:  # "cvxpy" keeps its default solver's own settings
        return {}
    table = {
        "CLARABEL": {"tol_feas": eps, "tol_gap_abs": eps, "tol_gap_rel": 0.0, "tol_ktratio": eps},
        "OSQP": {"eps_abs": eps, "eps_rel": 0.0, "max_iter": 20_000, "polishing": True},
        "SCS": {"eps_abs": eps, "eps_rel": 0.0, "max_iters": 20_000},
        "ECOS": {"feastol": eps, "abstol": eps, "reltol": eps},
        "PIQP": {"eps_abs": eps, "eps_rel": 0.0},
        "PROXQP": {"eps_abs": eps, "eps_rel": 0.0},
        "QPALM": {"eps_abs": eps, "eps_rel": 0.0},
    }
    return dict(table.get(solver, {}))


def _make_solve(solver: str | None):
    def solve(
        problem: ContactProblem,
        *,
        accuracy: str = "high",
        initial: np.ndarray | None = None,
        **options: Any,
    ) -> RawResult:
        t0 = time.perf_counter()
        Cs, ss, Rs, Ts = problem.scaled()
        sc = problem.scale
        F = cp.Variable(problem.size)
        equilibrium = Rs @ F == Ts
        constraints = [F >= 0, equilibrium]
        if problem.has_bounds:
            b = np.flatnonzero(problem.bounded)
            constraints.append(F[b] <= problem.scaled_upper_bound()[b])
        prob = cp.Problem(
            cp.Minimize(0.5 * cp.quad_form(F, cp.psd_wrap(Cs)) + ss @ F), constraints
        )
        if initial is not None:
            F.value = np.asarray(initial, float) / sc.force
        kwargs = _accuracy_options(solver, accuracy)
        kwargs.update(options)
        if solver in (None, "HIGHS"):  # cvxpy's own choice may be HiGHS
            quiet_highs_banner()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t1 = time.perf_counter()
            try:
                prob.solve(solver=solver, warm_start=initial is not None, **kwargs)
            except cp.error.SolverError as exc:
                t2 = time.perf_counter()
                return RawResult(None, None, False, f"cvxpy solver error: {exc}", t1 - t0, t2 - t1)
        t2 = time.perf_counter()
        stats = prob.solver_stats
        compile_time = float(getattr(prob, "compilation_time", 0.0) or 0.0)
        solver_time = stats.solve_time if stats and stats.solve_time is not None else None
        status = str(prob.status)
        claimed = status in (cp.OPTIMAL,)
        if F.value is None or equilibrium.dual_value is None:
            return RawResult(
                None,
                None,
                False,
                f"cvxpy status {status}",
                t1 - t0 + compile_time,
                t2 - t1 - compile_time,
            )
        force = np.asarray(F.value, float).ravel() * sc.force
        theta = -float(np.ravel(equilibrium.dual_value)[0]) * sc.rotation
        extras = {
            "cvxpy_status": status,
            "solver_reported_time": solver_time,
            "solver_name": stats.solver_name if stats else "",
        }
        iters = int(stats.num_iters) if stats and stats.num_iters is not None else -1
        return RawResult(
            force,
            theta,
            claimed,
            f"cvxpy status {status}",
            t1 - t0 + compile_time,
            t2 - t1 - compile_time,
            iters,
            extras,
        )

    return solve


def backends() -> list[Backend]:
    """``cvxpy`` (default solver) and ``cvxpy:NAME`` for each installed QP-capable solver."""
    if cp is None:  # pragma: no cover
        return []
    installed = set(cp.installed_solvers())
    out = [
        Backend("cvxpy", "modelling", _make_solve(None), True, "cvxpy with its default QP solver")
    ]
    for name in _QP_CAPABLE:
        if name in installed:
            out.append(
                Backend(
                    f"cvxpy:{name}",
                    _FAMILY.get(name, "modelling"),
                    _make_solve(name),
                    name in ("OSQP", "SCS", "PROXQP", "QPALM", "PIQP"),
                    f"cvxpy with solver {name}",
                )
            )
    return out
