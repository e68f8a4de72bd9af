"""Every installed ``qpsolvers`` backend, with settings that reach the toolkit's accuracy.

Each backend gets the same dimensionless QP (:meth:`ContactProblem.scaled`), so
one absolute tolerance means the same thing for every case. One accuracy level
maps onto each backend's own parameter names as qpbenchmark's ``SolverSettings``
does (Caron et al., qpbenchmark, ``solver_settings.py``); iteration caps are
raised so first-order methods can reach it. The dense → sparse conversion some
backends need is done here and timed as build time.

Source of the dual sign: qpsolvers writes the Lagrangian with ``+ yᵀ(A x − b)``,
so with A = R̃ᵀ the equality multiplier is y = −Θ̃.

Force limits (:attr:`ContactProblem.upper_bound`) go in as inequality rows G F̃ ≤ h, one
per segment that has a limit (G the rows of the identity, h = F_max/f₀): no backend then
sees an infinite bound (ECOS refuses them in qpsolvers' box bound ``ub``).
"""

from __future__ import annotations

import logging
import time
import warnings
from typing import Any

import numpy as np

from contact.qp.problem import ContactProblem
from contact.qp.solvers.backend import ACCURACY_LEVELS, Backend, RawResult, quiet_highs_banner

__all__ = ["BACKEND_FAMILIES", "backend_settings", "backends"]

log = logging.getLogger(__name__)

try:  # the registry must survive a missing or broken qpsolvers
    import qpsolvers
    import scipy.sparse as sp
except ImportError:  # pragma: no cover - qpsolvers is a hard dependency
    qpsolvers = None

#: Algorithm family of each qpsolvers backend (for reports and tolerance tables).
BACKEND_FAMILIES: dict[str, str] = {
    "clarabel": "interior-point",
    "cvxopt": "interior-point",
    "daqp": "active-set",
    "ecos": "interior-point",
    "gurobi": "barrier/simplex",
    "highs": "active-set",
    "hpipm": "interior-point",
    "mosek": "interior-point",
    "osqp": "ADMM",
    "piqp": "interior-point",
    "proxqp": "augmented-Lagrangian",
    "qpalm": "augmented-Lagrangian",
    "qpoases": "active-set",
    "qpswift": "interior-point",
    "quadprog": "active-set",
    "scs": "ADMM",
    "sip": "interior-point",
}

#: Wall-time cap [s] passed to backends that accept one: first-order methods at 1e-9
#: on N ≈ 2000 dense problems would otherwise run for minutes; the polish step
#: usually certifies their answer from the contact set they reached by then.
_TIME_LIMIT = 10.0

_WARM_START = {"osqp", "proxqp", "qpalm", "qpoases", "gurobi", "highs", "piqp", "scs"}


def backend_settings(solver: str, accuracy: str) -> dict[str, Any]:
    """Settings passed to ``qpsolvers.solve_problem`` for one backend and accuracy level.

    Parameters
    ----------
    solver : str
        qpsolvers name.
    accuracy : {"high", "default", "low"}
        Absolute tolerance 1e-9, the backend's own defaults, or 1e-3, on the
        scaled problem (relative tolerances set to 0 where the backend has them,
        as in qpbenchmark); iteration caps of 20 000 for first-order methods and a
        10 s time limit where the backend takes one.

    Returns
    -------
    dict
    """
    eps = ACCURACY_LEVELS[accuracy]
    s: dict[str, Any] = {}
    if eps is not None:
        table: dict[str, dict[str, Any]] = {
            "clarabel": {
                "tol_feas": eps,
                "tol_gap_abs": eps,
                "tol_gap_rel": 0.0,
                "tol_ktratio": eps,
                "max_iter": 300,
                "time_limit": _TIME_LIMIT,
            },
            "cvxopt": {"feastol": eps, "abstol": eps, "reltol": eps, "maxiters": 300},
            "daqp": {"primal_tol": eps, "dual_tol": eps},
            "ecos": {"feastol": eps, "abstol": eps, "reltol": eps, "max_iters": 300},
            "highs": {
                "dual_feasibility_tolerance": eps,
                "primal_feasibility_tolerance": eps,
                "time_limit": _TIME_LIMIT,
            },
            "osqp": {
                "eps_abs": eps,
                "eps_rel": 0.0,
                "max_iter": 20_000,
                "polishing": True,
                "time_limit": _TIME_LIMIT,
            },
            "piqp": {
                "eps_abs": eps,
                "eps_rel": 0.0,
                "eps_duality_gap_abs": eps,
                "eps_duality_gap_rel": 0.0,
                "max_iter": 500,
            },
            "proxqp": {
                "eps_abs": eps,
                "eps_rel": 0.0,
                "eps_duality_gap_abs": eps,
                "eps_duality_gap_rel": 0.0,
            },
            "qpalm": {
                "eps_abs": eps,
                "eps_rel": 0.0,
                "max_iter": 20_000,
                "time_limit": _TIME_LIMIT,
            },
            "scs": {
                "eps_abs": eps,
                "eps_rel": 0.0,
                "max_iters": 20_000,
                "time_limit_secs": _TIME_LIMIT,
            },
        }
        s.update(table.get(solver, {}))
    return s


def _theta_from_force(problem: ContactProblem, F: np.ndarray) -> float:
    """Least-squares Θ over the loaded segments when a backend gives no dual [rad]."""
    loaded = F > 1e-9 * problem.scale.force
    if not np.any(loaded):
        loaded = F >= np.max(F)
    R = problem.moment_arm[loaded]
    r = (problem.compliance @ F + problem.separation)[loaded]
    return float(R @ r / (R @ R)) if R @ R > 0 else float("nan")


def _make_solve(name: str):
    sparse_only = name in qpsolvers.sparse_solvers and name not in qpsolvers.dense_solvers

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
        P = sp.csc_matrix(Cs) if sparse_only else Cs
        A = sp.csc_matrix(Rs[None, :]) if sparse_only else Rs[None, :]
        G = h = None
        if problem.has_bounds:
            b = np.flatnonzero(problem.bounded)
            G = np.zeros((b.size, problem.size))
            G[np.arange(b.size), b] = 1.0
            G = sp.csc_matrix(G) if sparse_only else G
            h = problem.scaled_upper_bound()[b]
        qp = qpsolvers.Problem(P, ss, G, h, A, np.array([Ts]), np.zeros(problem.size), None)
        if name == "highs":
            quiet_highs_banner()
        settings = backend_settings(name, accuracy)
        settings.update(options)
        initvals = None if initial is None else np.asarray(initial, float) / sc.force
        t1 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sol = qpsolvers.solve_problem(qp, solver=name, initvals=initvals, **settings)
        t2 = time.perf_counter()
        x = sol.x
        if x is None or np.shape(x) != (problem.size,) or not np.all(np.isfinite(x)):
            return RawResult(None, None, False, "backend returned no solution", t1 - t0, t2 - t1)
        F = np.asarray(x, float) * sc.force
        y = sol.y
        if y is not None and np.size(y) == 1 and np.all(np.isfinite(y)):
            theta = -float(np.ravel(y)[0]) * sc.rotation
            dual_source = "backend"
        else:
            theta = _theta_from_force(problem, F)
            dual_source = "least squares over loaded segments"
        extras = {"dual_source": dual_source}
        iters = -1
        ext = getattr(sol, "extras", None) or {}
        for key in ("iter", "iterations", "iters"):
            if key in ext:
                try:
                    iters = int(ext[key])
                except (TypeError, ValueError):
                    pass
        claimed = bool(sol.found) if sol.found is not None else True
        status = "backend reports success" if claimed else "backend reports failure"
        return RawResult(F, theta, claimed, status, t1 - t0, t2 - t1, iters, extras)

    return solve


def backends() -> list[Backend]:
    """One :class:`Backend` per qpsolvers solver installed here."""
    if qpsolvers is None:  # pragma: no cover
        return []
    out = []
    for name in sorted(qpsolvers.available_solvers):
        out.append(
            Backend(
                name=name,
                family=BACKEND_FAMILIES.get(name, "unknown"),
                solve=_make_solve(name),
                warm_start=name in _WARM_START,
                description=f"qpsolvers backend {name!r}",
            )
        )
    return out
