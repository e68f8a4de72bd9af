"""Solver benchmark: each backend's time as a ratio to one dense Cholesky of C, same run.

    python benchmarks/solvers.py [--sizes 100 240 300 1000] [--instances 3] [--solvers ...]

For each size N, LTCA-like instances (``contact.qp.benchmark_problems.ltca_like_problem``) are
solved by every backend; times are the median over repeats of build + solve (+ polish),
divided by the median time of one dense Cholesky factorisation of the same C measured
in the same run — a ratio, so the table is comparable across machines. The issue's
target: at N = 240 our exact solver ``active_set`` takes ≤ 5 Cholesky and is fastest.
A warm-started row (previous solution's contact set) shows the roll-to-roll case.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
import scipy.linalg
from tabulate import tabulate

from contact import available_solvers, solve_contact
from contact.qp.benchmark_problems import ltca_like_problem


def _median_time(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100, 240, 300, 1000])
    parser.add_argument("--instances", type=int, default=3)
    parser.add_argument("--solvers", nargs="+", default=None)
    args = parser.parse_args()
    solvers = args.solvers or [s for s in available_solvers() if not s.startswith("cvxpy:")]
    rows = {s: [] for s in [*solvers, "active_set (warm)"]}
    chol_ms = []
    for n in args.sizes:
        ratios = {s: [] for s in rows}
        chol_list = []
        for k in range(args.instances):
            problem = ltca_like_problem(n, seed=1000 * n + k).problem
            C = problem.compliance
            reps = 30 if n <= 300 else 5
            t_chol = _median_time(lambda C=C: scipy.linalg.cho_factor(C, check_finite=False), reps)
            chol_list.append(t_chol)
            ref = solve_contact(problem)
            for s in solvers:
                r = 10 if n <= 300 else 2
                if s != "active_set":
                    r = 3 if n <= 300 else 1

                def run(s=s, problem=problem, n=n):
                    sol = solve_contact(problem, s)
                    if not sol.found:
                        raise RuntimeError(f"{s} failed on N={n}: {sol.status}")
                    return sol

                try:
                    run()  # warm up imports and caches
                    ratios[s].append(_median_time(run, r) / t_chol)
                except RuntimeError:
                    ratios[s].append(np.inf)
            ratios["active_set (warm)"].append(
                _median_time(lambda p=problem, ref=ref: solve_contact(p, initial=ref), 10) / t_chol
            )
        chol_ms.append(1e3 * statistics.median(chol_list))
        for s in rows:
            rows[s].append(statistics.median(ratios[s]))
    table = sorted(
        ([s, *v] for s, v in rows.items()),
        key=lambda r: r[1 + args.sizes.index(240)] if 240 in args.sizes else r[1],
    )
    print("time of each backend / time of one dense Cholesky of C (median over instances)")
    print(
        tabulate(
            table,
            headers=["solver", *(f"N={n}" for n in args.sizes)],
            tablefmt="github",
            floatfmt=".1f",
        )
    )
    print(
        "one Cholesky [ms]: "
        + ", ".join(f"N={n}: {t:.3f}" for n, t in zip(args.sizes, chol_ms, strict=True))
    )


if __name__ == "__main__":
    main()
