"""Our exact solver against daqp (and others) on the real LTCA problems, qpbenchmark's way.

    python benchmarks/active_set_real.py [--problems DIR] [--solvers active_set daqp ...]
                                         [--repeats 5] [--every K]

The problems are the exported real ones (``ltca export-problems -o benchmarks/problems``;
exported first if the directory has no manifest): every roll of a mesh cycle of every
bundled case at 50/250/500 N·m, aligned and misaligned. Each solver solves each problem
cold (no warm start: each problem on its own, as in qpbenchmark) through
``contact.solve_contact``, which certifies the answer with the toolkit's residuals; the
solvers take turns problem by problem, on one BLAS thread, and the fastest of
``--repeats`` runs counts (the shared machine's load only ever adds time).

Times: *backend* is the solver call alone (for a qpsolvers backend ``solve_problem`` on
the already scaled problem, as qpbenchmark's ``time_solve_problem`` times it; for
``active_set`` the block pivoting), plus an exact polish where one was needed; *total*
adds the problem's conversion (scaling, the qpsolvers ``Problem``). Failures are
charged qpbenchmark's time limit, 10 s. Summary per solver: certified problems, the
shifted geometric mean relative to the best with qpbenchmark's shift (10 s on seconds,
``qpbenchmark.report``) and with a 1 ms shift (which weighs the typical problem rather than
the total), the median, and the mean over bands of N. The issue's target (issue 21, item 8):
``active_set`` at most daqp's shifted geometric mean of the backend time, every problem
certified.
"""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path

import numpy as np
from tabulate import tabulate
from threadpoolctl import threadpool_limits

from contact.qp.problem_files import MANIFEST, read_problem_set
from contact.qp.run_environment import machine_info, solver_versions
from contact.qp.solver_study import QPBENCHMARK_SHIFT, shifted_geometric_mean
from contact.qp.solvers import solve_contact

HERE = Path(__file__).resolve().parent
TIME_LIMIT = 10.0  # [s] charged for a failure, as qpbenchmark's high_accuracy settings
BANDS = ((0, 60), (60, 120), (120, 200), (200, 10_000))


def _problems(directory: Path, every: int):
    if not (directory / MANIFEST).is_file():
        from contact.catalogue import bundled_cases
        from contact.commands.export_problems import export_problems

        print(f"no exported problems in {directory}: exporting every bundled case first")
        export_problems([c.removesuffix(".toml") for c in bundled_cases()], directory,
                        command="benchmarks/active_set_real.py (first use)")
    return read_problem_set(directory)[::every]


def _time(problems, solvers, repeats):
    """(solver → backend times [s], total times [s], certified flags), fastest of repeats."""
    shape = (len(solvers), len(problems))
    backend = np.full(shape, np.inf)
    total = np.full(shape, np.inf)
    found = np.ones(shape, dtype=bool)
    for j, tp in enumerate(problems):
        for _ in range(repeats):
            for i, name in enumerate(solvers):  # solvers take turns: load drifts hit all
                sol = solve_contact(tp.problem, name)
                found[i, j] &= sol.found
                backend[i, j] = min(backend[i, j], sol.solve_time)
                total[i, j] = min(total[i, j], sol.solve_time + sol.build_time)
    backend[~found] = TIME_LIMIT
    total[~found] = TIME_LIMIT
    return backend, total, found


def _relative(times: np.ndarray, shift: float) -> np.ndarray:
    sg = np.array([shifted_geometric_mean(row, shift) for row in times])
    return sg / sg.min()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--problems", type=Path, default=HERE / "problems",
                        help="exported problem set (default benchmarks/problems)")
    parser.add_argument("--solvers", nargs="+", default=["active_set", "daqp"])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--every", type=int, default=1,
                        help="take every K-th problem only (a quicker look)")
    args = parser.parse_args()
    problems = _problems(args.problems, args.every)
    n = np.array([tp.problem.size for tp in problems])
    with threadpool_limits(limits=1, user_api="blas"):
        info = machine_info()
        for name in args.solvers:  # imports and first-call caches out of the timing
            solve_contact(problems[0].problem, name)
        backend, total, found = _time(problems, args.solvers, args.repeats)
    versions = solver_versions(args.solvers)
    print(f"{len(problems)} real LTCA problems (N = {n.min()}…{n.max()}) from {args.problems}; "
          f"fastest of {args.repeats} cold solves each, one BLAS thread")
    print(f"{info['cpu']} ({info['cpu_count']} CPUs), {info['platform']}, Python "
          f"{info['python']}, NumPy {info['numpy_version']}, SciPy {info['scipy_version']}")
    print(f"BLAS: {info['blas']}")
    print("solvers: " + "; ".join(f"{s}: {versions[s]}" for s in args.solvers))
    rows = []
    rel = {
        "backend": _relative(backend, QPBENCHMARK_SHIFT),
        "backend_ms": _relative(backend * 1e3, 1.0),
        "total": _relative(total, QPBENCHMARK_SHIFT),
        "total_ms": _relative(total * 1e3, 1.0),
    }
    for i, name in enumerate(args.solvers):
        rows.append([
            name,
            f"{100.0 * found[i].mean():.1f}",
            f"{rel['backend'][i]:.2f}",
            f"{rel['backend_ms'][i]:.2f}",
            f"{rel['total'][i]:.2f}",
            f"{rel['total_ms'][i]:.2f}",
            f"{1e3 * statistics.median(backend[i]):.3f}",
            *(f"{1e3 * backend[i][(n >= lo) & (n < hi)].mean():.3f}"
              if np.any((n >= lo) & (n < hi)) else "-" for lo, hi in BANDS),
        ])
    headers = ["solver", "certified [%]", "shm backend (10 s)", "shm backend (1 ms)",
               "shm total (10 s)", "shm total (1 ms)", "median backend [ms]",
               *(f"mean N {lo}–{hi if hi < 10_000 else '∞'} [ms]" for lo, hi in BANDS)]
    print(tabulate(rows, headers=headers, tablefmt="github"))
    print("shm: shifted geometric mean / the best solver's (qpbenchmark's shift 10 s, and "
          "1 ms); backend: the solver call (+ polish); total: + conversion; failures "
          f"charged {TIME_LIMIT:g} s")
    print("bands: " + ", ".join(f"N {lo}–{hi if hi < 10_000 else '∞'}: "
                                f"{int(np.sum((n >= lo) & (n < hi)))}" for lo, hi in BANDS))
    if "active_set" in args.solvers and "daqp" in args.solvers:
        a, d = args.solvers.index("active_set"), args.solvers.index("daqp")
        ratio = rel["backend"][a] / rel["backend"][d]
        ratio_ms = rel["backend_ms"][a] / rel["backend_ms"][d]
        ok = ratio <= 1.0 and found[a].all()
        print(f"target (issue 21, item 8): active_set / daqp shifted geometric mean of backend "
              f"time = {ratio:.2f} (qpbenchmark's shift; {ratio_ms:.2f} with 1 ms), "
              f"{int(found[a].sum())}/{found.shape[1]} certified: "
              f"{'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
