"""What each step of the analysis chain costs (issue 63: studies run the steps they need).

One ``contact.run_analysis`` of the default case at one torque (250 N·m, the default
discretisation, one BLAS thread as the studies' workers run), from the contact alone — the
steps a study's point runs (``contact.study.engine``: no flanks, root stress, mesh
interface, efficiency or rating) — adding one step at a time up to the whole chain that
``ltca run`` runs. Prints, per chain, the least wall and CPU time of ``--repeat`` runs and
its ratio to the contact alone, then the steps' own times (the file's ``time_*_s``
attributes) of the whole chain. The FE coefficients of the root stress are read from the
cache (a first run of the design builds them: ~15–20 s per member, not timed here; run it
once before).

Usage::

    python benchmarks/chain_steps.py [--repeat 3] [--torque 250]
"""

from __future__ import annotations

import argparse
import time

from tabulate import tabulate
from threadpoolctl import threadpool_limits

from contact import run_analysis
from contact.catalogue import resolve_case

#: the chains timed, each adding one step to the one before
CHAINS = (
    ("contact only (a study's point)", dict(geometry=False, root_stress=False,
                                            mesh_interface=False, operating=False,
                                            steps={"load_capacity": None})),
    ("+ root stress", dict(geometry=False, mesh_interface=False, operating=False,
                           steps={"load_capacity": None})),
    ("+ mesh interface", dict(geometry=False, operating=False,
                              steps={"load_capacity": None})),
    ("+ efficiency", dict(geometry=False, steps={"load_capacity": None})),
    ("+ load capacity", dict(geometry=False)),
    ("+ geometry (= ltca run)", {}),
)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--torque", type=float, default=250.0)
    args = p.parse_args()
    case = resolve_case(None)
    rows, base, last = [], None, None
    with threadpool_limits(limits=1, user_api="blas"):
        run_analysis(case, [args.torque])  # warm-up: imports, memos, the FE cache read
        for name, kw in CHAINS:
            wall, cpu = [], []
            for _ in range(args.repeat):
                w, c = time.perf_counter(), time.process_time()
                last = run_analysis(case, [args.torque], **kw)
                wall.append(time.perf_counter() - w)
                cpu.append(time.process_time() - c)
            base = base or min(wall)
            rows.append((name, f"{min(wall):.2f}", f"{min(cpu):.2f}", f"{min(wall) / base:.2f}"))
    print(f"{case.name} at {args.torque:g} N m, least of {args.repeat} runs, one BLAS thread:")
    print(tabulate(rows, headers=["chain", "wall [s]", "CPU [s]", "wall / contact only"],
                   tablefmt="github"))
    steps = {k[5:-2]: v for k, v in last.attrs.items() if k.startswith("time_")}
    print("the whole chain's steps [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in steps.items()))


if __name__ == "__main__":
    main()
