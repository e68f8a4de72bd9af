"""How fast a SIGTERM ends ``ltca run`` during a first FE build, and what a rerun reuses.

Issue 64: a process inside an FE build answered SIGTERM only after 3 min 41 s (the handler
waited for the native factorisation), and an interrupted build kept nothing. Prints one
table, measured in one run: ``ltca run`` of the default case (one torque, a small LTCA,
no efficiency stage) into an empty temporary FE cache, sent SIGTERM when its log (``-v``)
shows a phase of the first member's build (2 s into the native factorisation, or as the
first block of unit loads is kept), in two set-ups —

* ``worker``: as shipped, the factorisation and the solves in a worker process
  (:func:`contact.compliance.fe.elasticity.factorise` with ``isolated=True``);
* ``in-process``: the same run with the worker switched off (``isolation_available``
  patched to False), the previous behaviour —

with the seconds from the signal to the process's exit, its exit code, the blocks of unit
loads kept in the cache, and for the interrupted solve phase the time of the rerun that
resumes against a cold build's.

Run: ``python benchmarks/fe_interrupt.py``. ~3-4 min on the 2-core machine (cold builds of
the default model). Nothing is written outside a temporary directory.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from tabulate import tabulate

#: the phases at which the signal is sent: (label, the log line's text, then a delay [s]:
#: 2 s after "factorising" the native factorisation of the default model (≥ 5 s) runs)
PHASES = (("factorisation", "factorising", 2.0),
          ("unit-load solves", "unit loads 0-32 of", 0.0))

_RUN = """
import sys
if sys.argv[1] == "in-process":
    import contact.compliance.fe.elasticity as e
    e.isolation_available = lambda: False
from contact.cli import main
sys.exit(main(sys.argv[2:]))
"""


def run(mode: str, cache: Path, out: Path, stop_at: str | None, delay: float = 0.0) -> dict:
    """One ``ltca run``; SIGTERM ``delay`` seconds after a stderr line contains
    ``stop_at``."""
    env = {**os.environ, "HYPOID_LTCA_CACHE": str(cache),
           "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    args = ["run", "--torque", "50", "--rolls-per-cycle", "4", "--segments", "8",
            "--speed", "0", "--no-progress", "-v", "-o", str(out)]
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-c", _RUN, mode, *args], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    sent = None
    for line in proc.stderr:
        if stop_at is not None and sent is None and stop_at in line:
            time.sleep(delay)
            proc.send_signal(signal.SIGTERM)
            sent = time.perf_counter()
    proc.wait()
    end = time.perf_counter()
    return {"rc": proc.returncode, "total_s": end - t0,
            "to_exit_s": end - sent if sent is not None else float("nan"),
            "parts": len(list(cache.glob("fe-*.part-*.nc")))}


def main() -> None:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for mode in ("worker", "in-process"):
            for label, text, delay in PHASES:
                cache = Path(tmp) / f"{mode}-{label[:5]}"
                r = run(mode, cache, Path(tmp) / "r.nc", text, delay)
                rerun = cold = float("nan")
                if mode == "worker" and r["parts"]:
                    rerun = run(mode, cache, Path(tmp) / "r.nc", None)["total_s"]
                    cold = run(mode, Path(tmp) / "cold", Path(tmp) / "r.nc", None)["total_s"]
                rows.append((mode, label, f"{r['to_exit_s']:.2f}", r["rc"], r["parts"],
                             f"{rerun:.1f}", f"{cold:.1f}"))
    print(f"SIGTERM during a first FE build of `ltca run` (default case; load average "
          f"{os.getloadavg()[0]:.1f})")
    print(tabulate(rows, headers=["factor in", "signal during", "signal to exit [s]", "rc",
                                  "blocks kept", "rerun [s]", "cold run [s]"],
                   tablefmt="github"))


if __name__ == "__main__":
    main()
