"""Wear simulation benchmark: time per wear step against one ``run_analysis``.

A wear step (contact.wear.simulate_wear) analyses the current worn surfaces — ease-off
update by the deviation grids (seed Eq. 4.3–4.10), UTCA, LTCA at one torque — and computes
the Archard depth of one mesh on both deviation grids. Measured in one run on the default
case (``kolivand2009_fm_11x41``, 200 N·m, default LTCA options):

1. one ``run_analysis`` of the theoretical surfaces at the same torque (geometry,
   ease-off/UTCA, LTCA; the reference);
2. ``simulate_wear`` with ``--steps`` steps: the median time of a step (``step_time``,
   from the second analysis on: the first pays the one-off caches) and the whole run
   divided by its analyses (steps + 1, with the one-off ease-off and contact-line speeds);
3. their ratios to 1. Target (issue 23): a wear step ≤ 2 × one ``run_analysis``.

Run: ``python benchmarks/wear.py [--steps N] [--repeat N]``. BLAS is limited to one thread
unless ``OPENBLAS_NUM_THREADS``/``OMP_NUM_THREADS`` are set.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

from tabulate import tabulate  # noqa: E402

from contact.catalogue import DEFAULT_CASE, resolve_case  # noqa: E402
from contact.pipeline import run_analysis  # noqa: E402
from contact.wear import simulate_wear  # noqa: E402

TORQUE = 200.0  # [N·m]
TARGET = 2.0  # wear step / run_analysis


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=4)
    ap.add_argument("--repeat", type=int, default=2, help="best of N (default 2)")
    args = ap.parse_args()
    case = resolve_case(DEFAULT_CASE)
    t_run = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        # the steps a wear step repeats (no root stress or rating: issue 63's defaults)
        run_analysis(case, TORQUE, deviations=False, root_stress=False,
                     steps={"load_capacity": None})
        t_run.append(time.perf_counter() - t0)
    t_ref = min(t_run)
    step_med, per_analysis = [], []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        ds = simulate_wear(case, TORQUE, wear_coefficient=1e-17, cycles=1e6,
                           steps=args.steps, deviations=False)
        total = time.perf_counter() - t0
        step_med.append(float(np.median(ds["step_time"].values[1:])))
        per_analysis.append(total / (args.steps + 1))
    t_step, t_avg = min(step_med), min(per_analysis)
    rows = [
        ("run_analysis (1 torque, theoretical)", f"{t_ref:.2f}", "1.00"),
        ("wear step (median, steps 1..)", f"{t_step:.2f}", f"{t_step / t_ref:.2f}"),
        (f"wear run / {args.steps + 1} analyses", f"{t_avg:.2f}", f"{t_avg / t_ref:.2f}"),
    ]
    print(f"case {case.name}, {TORQUE:g} N m, best of {args.repeat}")
    print(tabulate(rows, headers=["", "time [s]", "ratio"], tablefmt="github"))
    ok = t_step / t_ref <= TARGET
    print(f"target: wear step <= {TARGET:g} x run_analysis: {'met' if ok else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
