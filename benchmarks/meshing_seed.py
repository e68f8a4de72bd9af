"""The envelope solver's seed search before and after issue 32's speed-up, in one run.

    python benchmarks/meshing_seed.py [CASE] [--repeat 5]

The seed search (``geometry.machine.meshing._seed``) now memoises its candidate grids per
process and runs Newton's method on the candidates of all its passes in one batch; the
search as it was (each pass in turn, every grid evaluated afresh) is kept as the reference
in ``tests/test_meshing_seed.py`` (``_seed_reference``), which also checks that both give
the same root bit for bit. This script times, with each in turn (the two taking turns in
every repeat, so a change of the machine's load falls on both alike), in this process with
BLAS on one thread:

* the ease-off of the case (drive flank, its own mounting),
* the whole analysis at 250 N·m (``run_analysis``, as ``ltca run``),
* a study point (``contact.study.engine.analyse_point``) at misalignments around the
  case's own (the ease-off's placement iterations seed a new target each time),

and prints the CPU-time medians (``time.process_time``; fastest runs in brackets), the
ratio after/before, the seed searches per study point and their CPU time. The default
case is the bundled reference design, whose pinion blade has four sections: the
placement's middle targets lie on the flankrem, where the old search ran all eight passes.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from tabulate import tabulate  # noqa: E402

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]
sys.path.insert(0, str(_HERE.parent / "tests"))

from test_meshing_seed import _seed_reference  # noqa: E402

import geometry.machine.meshing as meshing  # noqa: E402
from contact.catalogue import resolve_case  # noqa: E402
from contact.ltca import LTCAOptions  # noqa: E402
from contact.pipeline import run_analysis  # noqa: E402
from contact.study.engine import analyse_point  # noqa: E402
from contact.study.points import StudyInputs  # noqa: E402
from contact.utca.easeoff import ease_off  # noqa: E402

TORQUE = 250.0


def _jobs(case):
    mis = case.misalignment
    inputs = StudyInputs(case=case, torque=(TORQUE,), options=LTCAOptions())

    def point(i):
        return analyse_point(inputs, 0, {"delta_E": mis.delta_E + 0.02 * ((i % 5) - 2),
                                         "delta_P": mis.delta_P + 0.015 * ((i * 3) % 5 - 2)})

    return {"ease-off (drive)": lambda i: ease_off(case),
            f"whole analysis at {TORQUE:g} N·m": lambda i: run_analysis(case, torque=TORQUE),
            "study point": point}


class _Counted:
    """A seed search that counts its calls and their CPU time."""

    def __init__(self, search):
        self.search, self.calls, self.cpu = search, 0, 0.0

    def __call__(self, ctx, z0, p0, depth, solved=None):
        # (the reference search runs its own Newton; the fast one may take the results of
        # its starts run along with solve_envelope's guesses, ``solved``)
        args = (ctx, z0, p0, depth) if self.search is _seed_reference else (ctx, z0, p0, depth,
                                                                            solved)
        t = time.process_time()
        out = self.search(*args)
        self.cpu += time.process_time() - t
        self.calls += 1
        return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", nargs="?", default=None, help="bundled case or file (default: "
                    "the bundled default)")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    case = resolve_case(args.case)
    jobs = _jobs(case)
    searches = {"before": _Counted(_seed_reference), "after": _Counted(meshing._seed)}
    for search in searches.values():  # warm-up: imports, memos, the candidate grids
        meshing._seed = search
        for job in jobs.values():
            job(0)
    times = {(name, which): [] for name in jobs for which in searches}
    for search in searches.values():
        search.calls, search.cpu = 0, 0.0
    load = os.getloadavg()[0]
    for i in range(args.repeat):
        for name, job in jobs.items():
            for which, search in searches.items():
                meshing._seed = search
                t = time.process_time()
                job(i)
                times[(name, which)].append(time.process_time() - t)
    rows = []
    for name in jobs:
        b, a = (statistics.median(times[(name, w)]) for w in searches)
        rows.append([name, f"{b:.3f} ({min(times[(name, 'before')]):.3f})",
                     f"{a:.3f} ({min(times[(name, 'after')]):.3f})", f"{a / b:.2f}x"])
    print(f"{case.name}: CPU s, medians of {args.repeat} runs (fastest), one BLAS thread; "
          f"load average {load:.1f} -> {os.getloadavg()[0]:.1f}")
    print(tabulate(rows, headers=["", "before [s]", "after [s]", "after/before"]))
    runs = args.repeat * len(jobs)
    for which, search in searches.items():
        print(f"  seed search {which}: {search.calls / runs:.1f} calls per run, "
              f"{1e3 * search.cpu / max(search.calls, 1):.1f} ms each")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
