"""Peak memory of a first ``ltca run`` with a cold FE cache (issue 62 item 6: ≤ 1.5 GB).

Prints one table, measured in one run: the default ``ltca run`` of a case (its torques,
root stress and rating on, the default LTCA and FE model) into an empty temporary FE
cache, each in a fresh process, in two set-ups —

* ``worker``: as shipped, the FE factorisation and solves in a worker process
  (:func:`contact.compliance.fe.elasticity.factorise` with ``isolated=True``);
* ``in-process``: the worker switched off (``isolation_available`` patched to False), as
  before —

with, sampled every 0.2 s over the process and its children (psutil):

* ``peak PSS`` — the proportional set size summed over the processes (shared pages split
  between them): the physical memory the run takes, the number the target is about;
* ``largest RSS`` — the largest peak resident set of one process of the tree, what
  ``/usr/bin/time -v`` reports (``getrusage(RUSAGE_CHILDREN).ru_maxrss``, also printed);
* wall and CPU time (children included).

Run: ``python benchmarks/fe_memory.py [--case NAME] [--modes worker in-process]``.
~2-5 min per run on the 2-core machine (the FE builds of both members).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import psutil
from tabulate import tabulate

_RUN = """
import sys
if sys.argv[1] == "in-process":
    import contact.compliance.fe.elasticity as e
    e.isolation_available = lambda: False
from contact.cli import main
sys.exit(main(sys.argv[2:]))
"""


def measure(mode: str, case: str | None, tmp: Path) -> dict:
    """One cold ``ltca run`` in a fresh process; its peak memory and times."""
    cache = tmp / f"cache-{mode}"
    env = {**os.environ, "HYPOID_LTCA_CACHE": str(cache),
           "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    args = ["run", *([case] if case else []), "--no-progress", "-q", "-o",
            str(tmp / f"{mode}.nc")]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-c", _RUN, mode, *args], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    peak = {"pss": 0.0, "rss": 0.0}
    done = threading.Event()

    def sample() -> None:
        root = psutil.Process(proc.pid)
        while not done.is_set():
            pss = 0.0
            try:
                for p in [root, *root.children(recursive=True)]:
                    try:
                        info = p.memory_full_info()
                    except (psutil.NoSuchProcess, psutil.AccessDenied):
                        continue
                    pss += info.pss
                    peak["rss"] = max(peak["rss"], info.rss)
            except psutil.NoSuchProcess:
                return
            peak["pss"] = max(peak["pss"], pss)
            time.sleep(0.2)

    thread = threading.Thread(target=sample, daemon=True)
    thread.start()
    _, err = proc.communicate()
    done.set()
    thread.join()
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode not in (0, 1):  # 1: a verdict FAIL still writes the file
        raise RuntimeError(f"ltca run ({mode}) failed: {err.decode()[-2000:]}")
    return {"mode": mode, "pss_gb": peak["pss"] / 2**30, "rss_gb": peak["rss"] / 2**30,
            "maxrss_gb": after.ru_maxrss / 2**20, "wall_s": wall,
            "cpu_s": (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=None, help="case (default the default case)")
    ap.add_argument("--modes", nargs="+", default=["worker", "in-process"],
                    choices=["worker", "in-process"])
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for mode in a.modes:
            r = measure(mode, a.case, Path(tmp))
            rows.append((r["mode"], f"{r['pss_gb']:.2f}", f"{r['rss_gb']:.2f}",
                         f"{r['wall_s']:.0f}", f"{r['cpu_s']:.0f}"))
    print(f"first `ltca run` {a.case or '(default case)'} with a cold FE cache (load "
          f"average {os.getloadavg()[0]:.1f}; target peak <= 1.5 GB)")
    print(tabulate(rows, headers=["FE factor in", "peak PSS, all processes [GB]",
                                  "largest peak RSS of one process [GB]", "wall [s]",
                                  "CPU [s]"], tablefmt="github"))
    print("ru_maxrss of the runs (RUSAGE_CHILDREN, what /usr/bin/time -v reports for the "
          f"largest): {resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 2**20:.2f} GB")


if __name__ == "__main__":
    main()
