"""Where a study point's or a warm analysis's CPU goes, by sampling the Python stack.

    python benchmarks/sample_profile.py study                # 12 study points
    python benchmarks/sample_profile.py warm --tasks 20      # 20 warm analyses
    python benchmarks/sample_profile.py torque               # each at a torque new to it
    python benchmarks/sample_profile.py study --lines "shell_tooth|conjugate_map"

For machines without ``py-spy``: a CPU-time timer (``signal.ITIMER_PROF``, every 0.5 ms
of this process's CPU) interrupts the tasks, and each interrupt records the Python stack
(``sys._current_frames`` of the main thread: the signal handler runs there). The tasks
are issue 75's (``benchmarks/issue75_table.py``): a study point is
:func:`contact.study.engine.analyse_point` of the default case at 250 N·m, each point a
new ΔE, ΔP; a warm analysis is :func:`contact.pipeline.run_analysis` of the default case
at 250 N·m (``torque``: each at a torque of its own, 0.8–1.2 × 250 N·m, as the table's
row "a torque new to the process"); one warm-up of each first. Printed, in CPU ms per
task (the samples' share of the measured CPU time): each function's inclusive time (on
the stack) and exclusive time (on top), the compiled kernels' time by caller, and with
``--lines`` the inclusive time of each line of the functions whose ``file:function``
matches the regular expression.

Why not cProfile: it costs a function call's worth of bookkeeping at every call, so on
the study point's ~100 000 calls of small NumPy functions it doubled the CPU (0.50 s a
point against 0.25 s) and shifted the shares toward the many cheap calls (``_context``
of the envelope solver read 0.34 ms a call under it, 0.07 ms timed alone). A sampler
costs ~1 % here. How it sees compiled code: a signal is handled between bytecodes, so a
numba kernel's time lands on the first Python frame after the kernel (numba's
``_numba_unpickle``, which the kernels call back into on their way out, or the line that
called the kernel); the kernels' block names the calling line.
"""

from __future__ import annotations

import argparse
import collections
import os
import re
import signal
import sys
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
TORQUE = 250.0
INTERVAL = 0.0005  # [s] of process CPU between samples


_NAMES: dict = {}  # code object → its name (resolved once: the handler stays cheap)


def _name(code) -> str:
    """``file:function`` of a code object, the file relative to the repository."""
    name = _NAMES.get(code)
    if name is None:
        path = code.co_filename
        try:
            path = str(Path(path).resolve().relative_to(ROOT))
        except ValueError:
            path = os.path.basename(path)
        name = _NAMES[code] = f"{path}:{code.co_name}"
    return name


class Sampler:
    """Stacks of the main thread recorded every :data:`INTERVAL` of process CPU."""

    def __init__(self) -> None:
        self.samples = 0
        self.inclusive: collections.Counter = collections.Counter()
        self.exclusive: collections.Counter = collections.Counter()
        self.kernels: collections.Counter = collections.Counter()
        self.lines: collections.Counter = collections.Counter()

    def _record(self, signum, frame) -> None:
        self.samples += 1
        seen = set()
        top = True
        while frame is not None:
            key = _name(frame.f_code)
            if top:
                self.exclusive[key] += 1
                if frame.f_code.co_name == "_numba_unpickle" and frame.f_back is not None:
                    caller = frame.f_back
                    self.kernels[f"{_name(caller.f_code)}:{caller.f_lineno}"] += 1
                top = False
            if key not in seen:
                seen.add(key)
                self.inclusive[key] += 1
                self.lines[f"{key}:{frame.f_lineno}"] += 1
            frame = frame.f_back

    def __enter__(self) -> Sampler:
        signal.signal(signal.SIGPROF, self._record)
        signal.setitimer(signal.ITIMER_PROF, INTERVAL, INTERVAL)
        return self

    def __exit__(self, *exc) -> None:
        signal.setitimer(signal.ITIMER_PROF, 0.0, 0.0)
        signal.signal(signal.SIGPROF, signal.SIG_DFL)


def tasks(kind: str):
    """The task of ``kind`` (``"study"``, ``"warm"``, ``"torque"``: a warm analysis at a
    torque new to the process) as a function of its index i of n, after one warm-up."""
    from contact.catalogue import bundled_case_path
    from contact.pipeline import run_analysis
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from geometry.case import load_case

    case = load_case(bundled_case_path())
    shared = StudyInputs(case=case, torque=(TORQUE,))
    m = case.misalignment
    analyse_point(shared, 0, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})
    run_analysis(case, [TORQUE])

    def study(i: int, n: int) -> None:
        f = (i - (n - 1) / 2) / max(n - 1, 1)  # -1/2 ... 1/2: every point new
        res = analyse_point(shared, 0, {"delta_E": m.delta_E + 0.08 * f,
                                        "delta_P": m.delta_P - 0.04 * f})
        if res.status == 2:
            raise RuntimeError(f"study point {i} failed: {res.reason}")

    def warm(i: int, n: int) -> None:
        run_analysis(case, [TORQUE])

    def torque(i: int, n: int) -> None:
        # issue 75's warm row at a torque new to the process: each task a torque of its own
        run_analysis(case, [TORQUE * (0.8 + 0.4 * i / max(n, 1)) + 1.0])

    return {"study": study, "warm": warm, "torque": torque}[kind]


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("kind", choices=("study", "warm", "torque"))
    ap.add_argument("--tasks", type=int, default=12, help="tasks sampled (12)")
    ap.add_argument("--top", type=int, default=40, help="functions listed (40)")
    ap.add_argument("--lines", metavar="REGEX",
                    help="also each line of the functions whose file:function matches")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    task = tasks(args.kind)
    n = args.tasks
    t0 = time.process_time()
    with Sampler() as s:
        for i in range(n):
            task(i, n)
    cpu = (time.process_time() - t0) / n
    per = 1e3 * cpu / max(s.samples, 1)  # ms per sample per task

    def show(title: str, counter: collections.Counter, top: int, floor: float = 0.0):
        print(f"\n{title}")
        for key, count in counter.most_common(top):
            if count * per < floor:
                break
            print(f"{count * per:8.1f}  {key}")

    print(f"{args.kind}: {1e3 * cpu:.1f} ms CPU a task, {n} tasks, {s.samples} samples, "
          f"load average {os.getloadavg()[0]:.1f}")
    show("inclusive [ms a task]", s.inclusive, args.top)
    show("exclusive [ms a task]", s.exclusive, args.top)
    show("compiled kernels by calling line [ms a task]", s.kernels, args.top)
    if args.lines:
        pat = re.compile(args.lines)
        show(f"lines of {args.lines!r}, inclusive [ms a task]",
             collections.Counter({k: v for k, v in s.lines.items() if pat.search(k)}),
             10 * args.top, floor=0.5)


if __name__ == "__main__":
    main()
