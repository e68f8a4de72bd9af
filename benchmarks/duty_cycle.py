"""Benchmark of duty cycles: bins per second on 1 and 2 local workers (issue 36).

    python benchmarks/duty_cycle.py               # the 7-bin illustrative spectrum
    python benchmarks/duty_cycle.py --bins 4      # its first 4 bins, quicker

Runs :func:`contact.study.duty_cycle.run_duty_cycle` on the bundled default case with the
illustrative axle spectrum (:func:`contact.study.duty_cycle_inputs.example_duty_cycle`),
once in this process (``scheduler="synchronous"``) and on LocalClusters of 1 and 2
single-threaded workers (the engine of the sweeps, :func:`contact.study.engine.
open_client`), all in this one run, and prints bins per second and their ratios to the
synchronous run. Wall-clock rates: they depend on the machine's load (printed). The
cluster's start-up and each worker's one-off tooth models are inside the timings (what a
user waits for); with as few bins as workers a second worker cannot help much.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


def main() -> None:
    from tabulate import tabulate

    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study.duty_cycle import run_duty_cycle
    from contact.study.duty_cycle_inputs import example_duty_cycle
    from contact.study.run import StudyRun

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bins", type=int, default=7, help="bins of the spectrum (1-7)")
    ap.add_argument("--rolls-per-cycle", type=int, default=20)
    args = ap.parse_args()
    case = resolve_case(None)
    duty = example_duty_cycle(bins=args.bins)
    options = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle)
    rows = []
    base = None
    for label, scheduler, workers in (("this process", "synchronous", None),
                                      ("1 worker", None, 1), ("2 workers", None, 2)):
        t0 = time.perf_counter()
        ds = run_duty_cycle(case, duty, StudyRun(options=options, scheduler=scheduler,
                                                 n_workers=workers),
                            root_stress=False)  # the bins' contact alone, as measured before
        dt = time.perf_counter() - t0
        rate = duty.n_bins / dt
        base = base or rate
        rows.append((label, f"{dt:.1f}", f"{rate:.3f}", f"{rate / base:.2f}"))
    print(f"duty cycle of {case.name}: {duty.n_bins} bins, {args.rolls_per_cycle} rolls per "
          f"cycle; load average {os.getloadavg()[0]:.2f}; cycle efficiency "
          f"{100 * float(ds['cycle_efficiency']):.3f} %")
    print(tabulate(rows, headers=["where", "wall [s]", "bins/s", "ratio to this process"],
                   tablefmt="github"))


if __name__ == "__main__":
    main()
