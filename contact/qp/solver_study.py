"""The solver-comparison study: every backend on a set of contact problems.

Results are a labelled ``xarray.Dataset`` over (``solver``, ``problem``); the
summary follows qpbenchmark (Caron et al.): success rate, shifted geometric mean
of the solve time relative to the best backend, worst residuals.

Conventions of the summary
--------------------------
- *Success*: the solution is certified by our own residuals (``found``).
- *Time*: build + solve (+ polish) wall time, the minimum over ``repeats`` runs.
  Failures are charged ``time_limit`` as qpbenchmark charges its time limit.
- *Shifted geometric mean*: exp(mean(ln(t + sh))) − sh, divided by the smallest over
  backends, twice: with t in milliseconds and sh = 1 ms (LTCA problems solve in
  milliseconds, and this shift keeps the ratio a ratio of typical times), and as
  qpbenchmark computes it (``qpbenchmark.report``: t in seconds, sh = 10 — on
  millisecond problems close to the ratio of the arithmetic means).
- *Force error*: ‖F − F_ref‖∞ / ‖F_ref‖∞ against our exact solver ``active_set``.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Iterable, Sequence
from typing import NamedTuple

import numpy as np
import xarray as xr

from contact.qp.benchmark_problems import TestProblem
from contact.qp.problem import DEFAULT_TOLERANCE, RESIDUALS, ContactProblem, ContactSolution
from contact.qp.run_environment import machine_info, solver_versions
from contact.qp.solvers import (
    DEFAULT_SOLVER,
    SOLVERS_EXTRA,
    available_solvers,
    get_backend,
    missing_backends,
    solve_contact,
)

__all__ = [
    "QPBENCHMARK_SHIFT",
    "compare_solvers",
    "default_study_solvers",
    "not_installed_text",
    "shifted_geometric_mean",
    "summarize",
]

log = logging.getLogger(__name__)

#: Shift [s] of qpbenchmark's shifted geometric mean of solve times (``qpbenchmark.report``).
QPBENCHMARK_SHIFT = 10.0


def shifted_geometric_mean(values: Iterable[float], shift: float) -> float:
    """exp(mean(ln(v + sh))) − sh (Mittelmann; qpbenchmark ``shgeom``).

    Parameters
    ----------
    values : iterable of float, ≥ 0
    shift : float, ≥ 1 (same unit as ``values``)

    Returns
    -------
    float
    """
    v = np.asarray(list(values), float)
    if v.size == 0 or np.any(v < 0) or shift < 1:
        raise ValueError("shifted_geometric_mean: needs non-negative values and shift ≥ 1")
    return float(np.exp(np.mean(np.log(v + shift))) - shift)


def default_study_solvers() -> list[str]:
    """Every available backend except the ``cvxpy:NAME`` variants (``cvxpy`` stays)."""
    return [s for s in available_solvers() if not s.startswith("cvxpy:")]


def compare_solvers(
    problems: Sequence[TestProblem],
    solvers: Sequence[str] | None = None,
    *,
    accuracy: str = "high",
    polish: bool = True,
    tolerance: float = DEFAULT_TOLERANCE,
    repeats: int = 1,
    max_size: dict[str, int] | None = None,
    progress: bool = False,
    blas_threads: int | None = 1,
) -> xr.Dataset:
    """Run every solver on every problem and collect certified results.

    Parameters
    ----------
    problems : sequence of TestProblem
    solvers : sequence of str, optional
        Registry names; default :func:`default_study_solvers`.
    accuracy, polish, tolerance
        Passed to :func:`contact.solve_contact`.
    repeats : int
        Runs per (solver, problem); the minimum time is kept (≥ 1).
    max_size : dict of str to int, optional
        Skip a solver on problems larger than this N (recorded as not run, status
        ``skipped``); for backends known to take minutes on large dense problems.
    progress : bool
        Show a tqdm progress bar.
    blas_threads : int or None
        BLAS threads during the study (default 1: the compiled backends are
        single-threaded, so one thread compares like with like, and on a shared
        machine a threaded BLAS oversubscribes the cores; None leaves BLAS as is).

    Returns
    -------
    xarray.Dataset
        dims (``solver``, ``problem``): ``found``, ``claimed_success``, ``polished``,
        ``ran`` [0/1], ``solve_time``, ``build_time`` [s], residuals
        ``residual_primal`` … [1], ``force_error``, ``rotation_error`` [1], ``iterations``,
        ``status``; coords ``problem_size``, ``problem_kind``, ``solver_family``,
        ``solver_version`` (:func:`contact.qp.run_environment.solver_versions`); attrs
        the settings and the machine (``cpu``, ``cpu_count``, ``blas``, ``blas_threads``,
        ``platform``, ``python``, NumPy, SciPy and qpsolvers versions:
        :func:`contact.qp.run_environment.machine_info`), and ``solvers_not_installed``, the
        known backends missing here with their install line (:func:`not_installed_text`).
    """
    kwargs = dict(accuracy=accuracy, polish=polish, tolerance=tolerance, repeats=repeats,
                  max_size=max_size, progress=progress)
    if blas_threads is None:
        return _study(problems, solvers, blas_threads="as found", **kwargs)
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=blas_threads, user_api="blas"):
        return _study(problems, solvers, blas_threads=blas_threads, **kwargs)


def _study(
    problems: Sequence[TestProblem],
    solvers: Sequence[str] | None,
    *,
    accuracy: str,
    polish: bool,
    tolerance: float,
    repeats: int,
    max_size: dict[str, int] | None,
    progress: bool,
    blas_threads: int | str,
) -> xr.Dataset:
    """:func:`compare_solvers` with BLAS threads already set (``blas_threads`` recorded)."""
    solvers = list(solvers) if solvers is not None else default_study_solvers()
    for name in solvers:
        get_backend(name)  # unknown names fail before any work
    if repeats < 1:
        raise ValueError(f"repeats: must be ≥ 1, got {repeats}")
    max_size = dict(max_size or {})
    ns, npb = len(solvers), len(problems)
    table = _empty_table(ns, npb)
    refs = [solve_contact(tp.problem, DEFAULT_SOLVER) for tp in problems]
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=ns * npb, desc="compare-solvers", unit="solve")
    for j, (tp, ref) in enumerate(zip(problems, refs, strict=True)):
        for i, name in enumerate(solvers):
            if bar is not None:
                bar.set_postfix_str(f"{name} on {tp.name}", refresh=False)
            if tp.problem.size > max_size.get(name, math.inf):
                table.status[i, j] = f"skipped: N = {tp.problem.size} > {max_size[name]}"
            else:
                sol = _fastest_of_repeats(
                    tp.problem, name, repeats, accuracy=accuracy, polish=polish, tolerance=tolerance
                )
                _record(table, i, j, sol, ref)
            if bar is not None:
                bar.update()
    if bar is not None:
        bar.close()
    attrs = {
        "title": "hypoid-ltca solver comparison",
        "accuracy": accuracy,
        "polish": int(polish),
        "tolerance": tolerance,
        "repeats": repeats,
        "reference_solver": DEFAULT_SOLVER,
        "blas_threads": blas_threads,
        "solvers_not_installed": not_installed_text(),
        **machine_info(),
    }
    return _study_dataset(table, problems, solvers, attrs)


def not_installed_text() -> str:
    """The known open-source backends not installed here and the line that installs them,
    as one sentence (empty when every one is installed): what the solver study records in
    its ``solvers_not_installed`` attribute and ``ltca compare-solvers`` prints.

    Returns
    -------
    str
        E.g. ``"daqp, quadprog (pip install 'hypoid-ltca[solvers]')"``.
    """
    missing = missing_backends()
    return f"{', '.join(missing)} ({SOLVERS_EXTRA})" if missing else ""


class _Table(NamedTuple):
    """The study's results, each array over (solver, problem), filled in place."""

    floats: dict[str, np.ndarray]  # times [s], errors and residuals [1]; NaN: not run
    flags: dict[str, np.ndarray]  # int8 0/1: found, claimed_success, polished, ran
    iterations: np.ndarray  # int64, -1: not reported or not run
    status: np.ndarray  # object (str), "" where not run


def _empty_table(n_solvers: int, n_problems: int) -> _Table:
    """A :class:`_Table` of (n_solvers, n_problems) arrays of no result: NaN times [s],
    errors and residuals [1], flags 0, iterations −1 and empty statuses."""
    f = lambda: np.full((n_solvers, n_problems), np.nan)  # noqa: E731
    floats = {
        k: f()
        for k in (
            "solve_time",
            "build_time",
            "force_error",
            "rotation_error",
            *(f"residual_{r}" for r in RESIDUALS),
        )
    }
    flags = {
        k: np.zeros((n_solvers, n_problems), dtype=np.int8)
        for k in ("found", "claimed_success", "polished", "ran")
    }
    iterations = np.full((n_solvers, n_problems), -1, dtype=np.int64)
    status = np.full((n_solvers, n_problems), "", dtype=object)
    return _Table(floats, flags, iterations, status)


def _fastest_of_repeats(
    problem: ContactProblem,
    name: str,
    repeats: int,
    *,
    accuracy: str,
    polish: bool,
    tolerance: float,
) -> ContactSolution:
    """The solution of ``repeats`` runs of backend ``name`` on ``problem`` with the
    smallest build + solve time [s] (the first of equal times)."""
    best = None
    for _ in range(repeats):
        sol = solve_contact(
            problem, name, accuracy=accuracy, polish_solution=polish, tolerance=tolerance
        )
        t = sol.solve_time + sol.build_time
        if best is None or t < best[0]:
            best = (t, sol)
    return best[1]


def _record(table: _Table, i: int, j: int, sol: ContactSolution, ref: ContactSolution) -> None:
    """Write solution ``sol`` of solver i on problem j into ``table``: flags, times [s],
    residuals [1] (capped at 1e300), iterations, status, and where its forces are finite
    and the reference ``ref`` was found the relative force and rotation errors [1]."""
    table.flags["ran"][i, j] = 1
    table.flags["found"][i, j] = sol.found
    table.flags["claimed_success"][i, j] = bool(sol.extras.get("claimed_success", False))
    table.flags["polished"][i, j] = sol.status == "solved (polished)"
    out = table.floats
    out["solve_time"][i, j] = sol.solve_time
    out["build_time"][i, j] = sol.build_time
    for r in RESIDUALS:
        out[f"residual_{r}"][i, j] = min(sol.residuals[r], 1e300)
    if np.all(np.isfinite(sol.force)) and ref.found:
        out["force_error"][i, j] = float(
            np.max(np.abs(sol.force - ref.force)) / np.max(np.abs(ref.force))
        )
        out["rotation_error"][i, j] = abs(sol.rotation - ref.rotation) / abs(ref.rotation)
    table.iterations[i, j] = sol.iterations
    table.status[i, j] = sol.status


#: (units, long name) of the floating-point variables of the study
_FLOAT_META = {
    "solve_time": ("s", "backend wall time incl. polishing (min over repeats)"),
    "build_time": ("s", "problem conversion time (scaling, dense to sparse, modelling)"),
    "force_error": ("1", "max force error relative to the exact active-set solution"),
    "rotation_error": (
        "1",
        "transmission-error (rotation) error relative to the exact solution",
    ),
    **{
        f"residual_{r}": ("1", f"relative {r} residual computed by the toolkit")
        for r in RESIDUALS
    },
}

#: long names of the 0/1 variables of the study
_FLAG_NAMES = {
    "found": "certified solution found (1) or not (0)",
    "claimed_success": "backend claimed success (1) or not (0)",
    "polished": "answer certified only after polishing (1) or not (0)",
    "ran": "backend was run on this problem (1) or skipped (0)",
}


def _study_dataset(
    table: _Table,
    problems: Sequence[TestProblem],
    solvers: list[str],
    attrs: dict,
) -> xr.Dataset:
    """The study's dataset over (solver, problem): the variables of ``table`` with their
    units and long names, the problems' sizes [1] and kinds and the solvers' families as
    coordinates, ``attrs`` as attributes (see :func:`compare_solvers`)."""
    dims = ("solver", "problem")
    data = {
        k: (dims, v, {"units": _FLOAT_META[k][0], "long_name": _FLOAT_META[k][1]})
        for k, v in table.floats.items()
    }
    data.update(
        {k: (dims, v, {"units": "1", "long_name": _FLAG_NAMES[k]}) for k, v in table.flags.items()}
    )
    data["iterations"] = (
        dims,
        table.iterations,
        {"units": "1", "long_name": "backend iterations (-1: not reported)"},
    )
    data["status"] = (dims, table.status.astype(str), {"long_name": "solution status"})
    coords = {
        "solver": ("solver", list(solvers), {"long_name": "solver backend (registry name)"}),
        "problem": ("problem", [tp.name for tp in problems], {"long_name": "problem name"}),
        "problem_size": (
            "problem",
            np.array([tp.problem.size for tp in problems]),
            {"units": "1", "long_name": "number of contact segments N"},
        ),
        "problem_kind": ("problem", [tp.kind for tp in problems], {"long_name": "problem family"}),
        "solver_family": (
            "solver",
            [get_backend(s).family for s in solvers],
            {"long_name": "algorithm family"},
        ),
        "solver_version": (
            "solver",
            [solver_versions(solvers)[s] for s in solvers],
            {"long_name": "package versions behind the backend"},
        ),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def summarize(
    results: xr.Dataset, *, time_limit: float = 10.0, shift_ms: float = 1.0
) -> xr.Dataset:
    """qpbenchmark-style summary per solver of a :func:`compare_solvers` result.

    Parameters
    ----------
    results : xarray.Dataset
    time_limit : float — [s]
        Time charged for a failure or a skipped problem.
    shift_ms : float — [ms]
        Shift of the shifted geometric mean.

    Returns
    -------
    xarray.Dataset over ``solver``: ``success_rate`` [%], ``time_shgeom`` [ms],
    ``time_relative`` [1] (to the best), ``time_relative_qpbenchmark`` [1] (to the best,
    qpbenchmark's shift of 10 s on times in seconds), ``worst_residual``,
    ``worst_force_error`` [1] (over certified solutions), ``polished_rate`` [%].
    """
    found = results["found"].values.astype(bool)
    t = (results["solve_time"] + results["build_time"]).values * 1e3
    t = np.where(found, t, time_limit * 1e3)
    sg = np.array([shifted_geometric_mean(row, shift_ms) for row in t])
    sg_qpb = np.array([shifted_geometric_mean(row * 1e-3, QPBENCHMARK_SHIFT) for row in t])
    res = np.max(np.stack([results[f"residual_{r}"].values for r in RESIDUALS]), axis=0)
    worst_res = np.array(
        [np.max(r[f], initial=0.0) if f.any() else np.inf for r, f in zip(res, found, strict=True)]
    )
    ferr = results["force_error"].values
    worst_ferr = np.array(
        [np.max(e[f], initial=0.0) if f.any() else np.inf for e, f in zip(ferr, found, strict=True)]
    )
    n = found.shape[1]
    return xr.Dataset(
        {
            "success_rate": (
                "solver",
                100.0 * found.sum(axis=1) / n,
                {"units": "percent", "long_name": "certified solutions"},
            ),
            "time_shgeom": (
                "solver",
                sg,
                {"units": "ms", "long_name": "shifted geometric mean of time"},
            ),
            "time_relative": (
                "solver",
                sg / np.min(sg),
                {"units": "1", "long_name": "shifted geometric mean time / best"},
            ),
            "time_relative_qpbenchmark": (
                "solver",
                sg_qpb / np.min(sg_qpb),
                {"units": "1", "long_name": "shifted geometric mean time / best, "
                 "qpbenchmark's shift of 10 s"},
            ),
            "worst_residual": (
                "solver",
                worst_res,
                {"units": "1", "long_name": "worst residual of certified solutions"},
            ),
            "worst_force_error": (
                "solver",
                worst_ferr,
                {"units": "1", "long_name": "worst force error (certified)"},
            ),
            "polished_rate": (
                "solver",
                100.0 * results["polished"].values.sum(axis=1) / n,
                {"units": "percent", "long_name": "certified only after polishing"},
            ),
        },
        coords={"solver": results["solver"], "solver_family": results["solver_family"]},
        attrs={"time_limit_s": time_limit, "shift_ms": shift_ms},
    ).sortby("time_relative")
