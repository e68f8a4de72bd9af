"""Conditions per second of the friction study on 1 and 2 Dask workers, in one run.

    python benchmarks/friction_study.py [--points 256] [--nodes 512]

A fixed Sobol design of the gear-contact box (``GEAR_CONTACT_RANGE``, seed 2009: the
committed study's first points) solved by
:func:`contact.study.friction_study.run_friction_study` on a LocalCluster of 1 and of 2
single-threaded workers (the cluster's start excluded: it is timed from the
first submitted point, after a warm-up design that makes every worker import the solver),
and once in this process (``synchronous``) as the reference. The
table prints conditions per second and the speed-up over one worker (issue 34 target
≥ 1.7 on 2 workers; a machine shared with other jobs gives less). Failed (not converged)
conditions count: they are part of a study's cost. The solver is the study's own, the
stochastic one (512 nodes, issue 51); the resolved transient model the study ran before
(issue 34: 0.23 conditions/s) left it in issue 61 (docs/ehl.md).
"""

from __future__ import annotations

import argparse
import time

from tabulate import tabulate

from contact.study.engine import open_client
from contact.study.friction_study import run_friction_study
from friction.study.design import GEAR_CONTACT_RANGE, space_filling_design
from friction.study.points import SolveSettings


def _rate(design, settings, scheduler) -> tuple[float, int]:
    t = time.perf_counter()
    ds = run_friction_study(design, settings, scheduler=scheduler)
    n = ds.sizes["point"]
    return n / (time.perf_counter() - t), int((ds["status"].values == 0).sum())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=256)
    ap.add_argument("--nodes", type=int, default=512)
    args = ap.parse_args()
    design = space_filling_design(args.points, seed=2009, box=GEAR_CONTACT_RANGE)
    settings = SolveSettings(nodes=args.nodes)
    rows = []
    rate, ok = _rate(design, settings, "synchronous")
    rows.append(["this process (synchronous)", f"{rate:.2f}", ok, "-"])
    base = None
    for workers in (1, 2):
        # the study's own LocalCluster (open_client: single-threaded workers started without
        # distributed's malloc trim, as `ltca friction-study` runs them)
        with open_client(None, n_workers=workers) as client:
            client.wait_for_workers(workers)
            # warm-up: every worker imports the solver and solves one condition first (the
            # imports cost seconds on a busy machine, as much as tens of conditions)
            warm = space_filling_design(2 * workers, seed=7, box=GEAR_CONTACT_RANGE)
            run_friction_study(warm, settings, scheduler=client)
            rate, ok = _rate(design, settings, client)
        base = base or rate
        rows.append([f"LocalCluster, {workers} worker(s)", f"{rate:.2f}", ok,
                     f"{rate / base:.2f}"])
    print(f"friction study: {args.points} Sobol conditions of the gear box, stochastic "
          f"solver, {args.nodes} nodes")
    print(tabulate(rows, headers=["where", "conditions/s", "converged",
                                  "speed-up over 1 worker"]))


if __name__ == "__main__":
    main()
