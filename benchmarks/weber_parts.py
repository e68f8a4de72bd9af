"""A study point's Weber stage, part by part: what one compiled loop per roll could remove.

    python benchmarks/weber_parts.py             # 20 points of the default case
    python benchmarks/weber_parts.py --points 10

Runs issue 75's study points (:func:`contact.study.engine.analyse_point` of the default
case at 250 N·m, each point a new misalignment ΔE, ΔP) after one warm-up point, first
unwrapped (the point's median CPU), then with ``time.process_time`` wrappers around
:func:`contact.ltca.weber.weber_solve` (where :mod:`contact.ltca.roll_loop` looks it up)
and the parts inside it: the compiled warm solve, its Python wrapper, the base
``ContactProblem`` (its Cholesky check), ``WeberSegments.of`` and ``secant_tangent``, and
the last solve's ``_warm_solution``. Prints each part's mean CPU a point [ms]; the loop's
own NumPy and Python is the stage less its parts. CPU time, not wall time (the machine is
shared). Each pass has its own points (a point analysed before is a memo hit).
Measured for docs/performance.md "A study point's stages against one compiled
pass each" (issue 75 item 4, helper speed91).
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections import defaultdict

TORQUE = 250.0  # [N·m], issue 75's study row


def _timed(acc: dict, key: str, fn):
    """``fn`` adding its CPU time [s] and calls to ``acc[key]``."""
    def wrapper(*args, **kwargs):
        t0 = time.process_time()
        try:
            return fn(*args, **kwargs)
        finally:
            acc[key][0] += time.process_time() - t0
            acc[key][1] += 1
    return wrapper


class _TimedKernels:
    """The warm-solve kernels' module with ``warm_solve`` timed."""

    def __init__(self, module, acc: dict) -> None:
        self._module = module
        self.SOLVED = module.SOLVED
        self.warm_solve = _timed(acc, "compiled warm_solve", module.warm_solve)


def _wrap(acc: dict) -> None:
    import contact.compliance.weber as cw
    import contact.ltca.roll_loop as roll_loop
    import contact.ltca.weber as w

    whole = _timed(acc, "the whole stage (weber_solve)", w.weber_solve)
    w.weber_solve = roll_loop.weber_solve = whole
    w.ContactProblem = _timed(acc, "base ContactProblem", w.ContactProblem)
    w._warm_solve = _timed(acc, "_warm_solve with the kernel", w._warm_solve)
    w._warm_solution = _timed(acc, "_warm_solution", w._warm_solution)
    segments = cw.WeberSegments
    segments.secant_tangent = _timed(acc, "secant_tangent", segments.secant_tangent)
    segments.of = classmethod(_timed(acc, "WeberSegments.of", segments.of.__func__))
    kernels = w._warm_kernels

    def timed_kernels(solver):
        module = kernels(solver)
        return None if module is None else _TimedKernels(module, acc)
    w._warm_kernels = timed_kernels


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=20, help="study points (20)")
    args = ap.parse_args(argv)

    from contact.catalogue import bundled_case_path
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from geometry.case import load_case

    case = load_case(bundled_case_path())
    shared = StudyInputs(case=case, torque=(TORQUE,))
    m = case.misalignment
    analyse_point(shared, 0, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})

    def run(shift: float) -> float:
        # each pass its own points: a point analysed before is a memo hit (the ease-off)
        cpu = []
        for i in range(args.points):
            point = {"delta_E": m.delta_E + 0.01 * (i % 5 - 2) + shift,
                     "delta_P": m.delta_P + 0.007 * (i // 5 - 2)}
            t0 = time.process_time()
            analyse_point(shared, 0, point)
            cpu.append(time.process_time() - t0)
        return statistics.median(cpu) * 1e3

    plain = run(0.0)
    acc: dict = defaultdict(lambda: [0.0, 0])
    _wrap(acc)
    wrapped = run(0.003)
    n = args.points
    print(f"point median [ms]: unwrapped {plain:.1f}, wrapped {wrapped:.1f}")
    print(f"{'part, a point':42s} {'ms':>7s} {'calls':>7s}")
    for key, (seconds, calls) in acc.items():
        print(f"{key:42s} {seconds / n * 1e3:7.2f} {calls / n:7.1f}")
    w = acc["the whole stage (weber_solve)"][0]
    inner = (acc["_warm_solve with the kernel"][0] + acc["base ContactProblem"][0]
             + acc["secant_tangent"][0] + acc["_warm_solution"][0]
             + acc["WeberSegments.of"][0])
    print(f"{'the loop own NumPy and Python':42s} {(w - inner) / n * 1e3:7.2f}")


if __name__ == "__main__":
    main()
