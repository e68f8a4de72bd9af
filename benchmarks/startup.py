"""Start-up benchmark: the CPU time of ``ltca --help``, ``ltca cases`` and ``import contact``.

    python benchmarks/startup.py [--repeat 7]

Each is run in a fresh interpreter ``--repeat`` times; the table gives the median and the
least CPU time (user + system of the child, which the machine's load moves less than the
wall time) and the median wall time, with the bare interpreter's start for comparison.
Target (issue 32): ``ltca --help`` and ``ltca cases`` ≤ 0.5 s. Each command module imports
its own dependencies inside its run function and the packages' public names are imported
when first used, so ``ltca --help`` imports no NumPy (``tests/test_startup.py``).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time

from tabulate import tabulate

TARGET_S = 0.5

COMMANDS = {
    "python (bare interpreter)": [sys.executable, "-c", "pass"],
    "import contact": [sys.executable, "-c", "import contact"],
    "ltca --help": [sys.executable, "-c", "from contact.cli import main; main(['--help'])"],
    "ltca cases": [sys.executable, "-c", "from contact.cli import main; main(['cases'])"],
}


def child_cpu(argv: list[str]) -> tuple[float, float]:
    """(CPU [s], wall [s]) of one run of ``argv`` in a fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False,
                   env={**os.environ, "PYTHONWARNINGS": "ignore"})
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args()
    runs = {name: [] for name in COMMANDS}
    for _ in range(max(args.repeat, 1)):  # round robin: a change of load falls on all alike
        for name, argv in COMMANDS.items():
            runs[name].append(child_cpu(argv))
    rows = []
    for name, r in runs.items():
        cpu = [c for c, _ in r]
        wall = [w for _, w in r]
        verdict = ""
        if name.startswith("ltca"):
            verdict = "met" if statistics.median(cpu) <= TARGET_S else "NOT met"
        rows.append((name, statistics.median(cpu), min(cpu), statistics.median(wall),
                     verdict))
    print(f"fresh interpreters, {args.repeat} runs each; load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(tabulate(rows, headers=("command", "CPU median [s]", "CPU least [s]",
                                  "wall median [s]", f"target <= {TARGET_S:g} s CPU"),
                   tablefmt="github", floatfmt=".3f"))


if __name__ == "__main__":
    main()
