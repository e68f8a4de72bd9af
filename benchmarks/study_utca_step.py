"""A study point with the ``utca`` step's full ``/utca`` against its UTE alone, in one process.

    python benchmarks/study_utca_step.py            # 16 points
    python benchmarks/study_utca_step.py --points 24

Issue 75 item 4 (docs/performance.md, "A study point's UTCA without its curves"): a study
point (:func:`contact.study.engine.analyse_point`, the default case at 250 N·m) runs the
chain's ``utca="ute"`` step (:func:`contact.chain.utca_ute`). Here each point is analysed
twice, once with that step and once with the default step in its place (the full
``/utca``: ``contact.chain.STEPS["utca"]["ute"]`` swapped for this process only), the
order alternated point by point, each from emptied ease-off, cycle and fields memos (so
both compute the point's ease-off and everything after it); each point a new ΔE, ΔP.
Printed: the medians of the CPU time (``time.process_time``), the median of the per-point
ratios, and how many summary arrays differ between the two (expected: none, bit for bit).
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


def main(argv: list[str] | None = None) -> None:
    import numpy as np

    import contact.chain as chain
    from contact.catalogue import bundled_case_path
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from contact.utca.datasets import clear_cycle_memo
    from contact.utca.easeoff import clear_ease_off_memo
    from contact.utca.fields import clear_fields_memo
    from geometry.case import load_case

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=16)
    n = ap.parse_args(argv).points
    case = load_case(bundled_case_path())
    m = case.misalignment
    shared = StudyInputs(case=case, torque=(250.0,))
    steps = {"full": chain.utca_easeoff, "ute": chain.utca_ute}

    def run(name: str, point: dict) -> tuple[float, dict]:
        chain.STEPS["utca"]["ute"] = steps[name]  # type: ignore[index]
        clear_ease_off_memo()
        clear_cycle_memo()
        clear_fields_memo()
        t0 = time.process_time()
        res = analyse_point(shared, 0, point)
        cpu = time.process_time() - t0
        if res.status != 0:
            raise RuntimeError(f"study point {point}: {res.reason}")
        return cpu, res.summary

    try:
        for name in steps:  # warm-up at a point the others do not repeat
            run(name, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})
        cpu: dict[str, list[float]] = {name: [] for name in steps}
        differ = 0
        for i in range(n):
            point = {"delta_E": m.delta_E + 0.01 * (i - n // 2),
                     "delta_P": m.delta_P + 0.006 * (n // 3 - i)}
            summaries = {}
            for name in (("full", "ute") if i % 2 == 0 else ("ute", "full")):
                t, summaries[name] = run(name, point)
                cpu[name].append(t)
            differ += sum(np.asarray(summaries["full"][k]).tobytes()
                          != np.asarray(summaries["ute"][k]).tobytes()
                          for k in summaries["full"])
    finally:
        chain.STEPS["utca"]["ute"] = chain.utca_ute  # type: ignore[index]
    ratio = [b / a for a, b in zip(cpu["full"], cpu["ute"], strict=True)]
    saved = statistics.mean(a - b for a, b in zip(cpu["full"], cpu["ute"], strict=True))
    print(f"load average {os.getloadavg()[0]:.1f}; {n} points; CPU median: full /utca "
          f"{statistics.median(cpu['full']) * 1e3:.1f} ms, the UTE alone "
          f"{statistics.median(cpu['ute']) * 1e3:.1f} ms; per-point ratios' median "
          f"{statistics.median(ratio):.3f} ({sum(r < 1 for r in ratio)} of {n} lower); "
          f"mean difference {saved * 1e3:.1f} ms; "
          f"summary arrays differing: {differ}")


if __name__ == "__main__":
    main()
