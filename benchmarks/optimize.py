"""Benchmark of ``contact.optimize``: the reference-design optimisation on local workers.

Runs the optimisation of the bundled 11×41 case at the seed's Table 3.1 conditions
(torques 50/250/500 N·m, misalignment ΔE = −0.15, ΔP = 0.12 mm) with the reference
design's limits (edge share ≤ 1 % at 50 N·m and ≤ 5 % at 500 N·m, flank peak ≤ 2000 MPa
at 500 N·m, LTE peak-to-peak 5–25 µrad) over the tip and root relief and the first-order
modified roll and helical motion, and prints evaluations per second, the wall time and the
start/result numbers. Target on the 2-core machine (issue 19): the run finishes in
≤ 10 min.

    python benchmarks/optimize.py                      # 2 workers, 60 designs
    python benchmarks/optimize.py --evaluations 20 --workers 1
"""

from __future__ import annotations

import argparse
import dataclasses
import time

from tabulate import tabulate

from contact.catalogue import SEED_TABLE_3_1, resolve_case
from contact.ltca import LTCAOptions
from contact.optimize import DesignVariable, OptimizeProblem, optimize

VARIABLES = [DesignVariable("tip_relief", 0.0, 40.0), DesignVariable("root_relief", 0.0, 40.0),
             DesignVariable("2C", -0.05, 0.05), DesignVariable("H1", -2.0, 2.0)]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--evaluations", type=int, default=60)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--rolls-per-cycle", type=int, default=10)
    ap.add_argument("--segments", type=int, default=12)
    args = ap.parse_args()
    # the edge-loaded start (the long-bearing synthesis), not the default reference design
    case = dataclasses.replace(resolve_case("kolivand2009_fm_11x41"),
                               misalignment=SEED_TABLE_3_1["misalignment"])
    problem = OptimizeProblem(
        torque=SEED_TABLE_3_1["torque"], max_edge_share=(0.01, 1.0, 0.05),
        max_flank_pressure=(float("inf"), float("inf"), 2000.0),
        lte_peak_to_peak_range=(5.0, 25.0),
        options=LTCAOptions(rolls_per_cycle=args.rolls_per_cycle, segments=args.segments))
    t0 = time.perf_counter()
    res = optimize(case, VARIABLES, problem, max_evaluations=args.evaluations,
                   n_workers=args.workers, progress=True)
    wall = time.perf_counter() - t0
    n = res.log.sizes["evaluation"]
    print(tabulate([(args.workers, n, f"{wall:.1f}", f"{n / wall:.3f}",
                     f"{float(res.log['seconds'].mean()):.2f}", res.feasible,
                     "yes" if wall <= 600 else "NO")],
                   headers=["workers", "designs", "wall [s]", "designs/s",
                            "s per design (worker)", "feasible", "<= 10 min"],
                   tablefmt="github"))
    rows = [(name, u, f"{a:.4g}", f"{b:.4g}") for name, u, a, b in
            zip(res.names, res.units, res.start, res.best, strict=True)]
    print(tabulate(rows, headers=["variable", "unit", "start", "result"], tablefmt="github"))
    s, b = res.start_evaluation.metrics, res.best_evaluation.metrics
    rows = [(k, " / ".join(f"{v:.4g}" for v in s[k][0]), " / ".join(f"{v:.4g}" for v in b[k][0]))
            for k in ("lte_mean", "lte_peak_to_peak", "edge_load_share", "pressure_max_flank",
                      "pressure_max_edge", "pattern_centre_u", "pattern_centre_v")]
    print(tabulate(rows, headers=["at 50/250/500 N m", "start", "result"], tablefmt="github"))


if __name__ == "__main__":
    main()
