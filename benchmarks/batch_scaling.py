"""A study point's segment geometry and shell mapping: per call or per point?

    python benchmarks/batch_scaling.py
    python benchmarks/batch_scaling.py --reps 30

Issue 75 item 4 read most of the NumPy time of the segment geometry as call overhead on
small arrays, to be batched away over rolls and segments. This script measures what
batching could remove: it runs one study point of issue 75's study row
(:func:`contact.study.engine.analyse_point` of the default case at 250 N·m, a new ΔE, ΔP)
and records the arguments of the calls the segment geometry and the shell mapping make —
the contact curves (:func:`contact.utca.contact_curves`, as :mod:`contact.ltca.segments`
calls it), the R_eq envelope solves (:func:`geometry.machine.flank.flank_at`, as
:mod:`contact.ltca.curvature` calls it), the gear flank's foot under the pinion edges
(:func:`contact.ltca.edges.gear_flank_under`) and the shell mapping
(:func:`contact.compliance.tooth.shell_points_many`, as :mod:`contact.compliance.mesh`
calls it). Then each call is timed (``time.process_time``, mean of ``--reps``) with its own
points and with its points doubled (the same points twice; the contact curves' targets
with a copy moved by 1e-4 rad), and the difference split into a part per call (what
merging calls could save) and a part per point (what only less work per point saves).
Prints one line per call; the calls are those of one point, so their sum is the point's.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


def main(argv: list[str] | None = None) -> None:
    import numpy as np
    from tabulate import tabulate

    import contact.compliance.mesh as mesh
    import contact.ltca.curvature as curvature
    import contact.ltca.edges as edges
    import contact.ltca.segments as segments
    from contact.catalogue import bundled_case_path
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from geometry.case import load_case

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--reps", type=int, default=15, help="timed repetitions per call (15)")
    args = ap.parse_args(argv)

    calls: dict[str, list] = {}
    spied = ((curvature, "flank_at"), (mesh, "shell_points_many"),
             (segments, "contact_curves"), (edges, "gear_flank_under"))
    originals = {}
    for mod, name in spied:
        fn = originals[name] = getattr(mod, name)

        def spy(*a, _fn=fn, _name=name, **k):
            calls.setdefault(_name, []).append((a, k))
            return _fn(*a, **k)

        setattr(mod, name, spy)
    case = load_case(bundled_case_path())
    shared = StudyInputs(case=case, torque=(250.0,))
    m = case.misalignment
    analyse_point(shared, 0, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})
    calls.clear()
    analyse_point(shared, 0, {"delta_E": m.delta_E - 0.03, "delta_P": m.delta_P + 0.02})
    for mod, name in spied:
        setattr(mod, name, originals[name])

    def cpu(fn) -> float:
        fn()
        t0 = time.process_time()
        for _ in range(args.reps):
            fn()
        return (time.process_time() - t0) / args.reps * 1e3

    def twice(x):
        return None if x is None else np.concatenate([np.asarray(x)] * 2)

    rows = []

    def row(what: str, n: int, one, two) -> None:
        a, b = cpu(one), cpu(two)
        per_point = (b - a) / n
        rows.append([what, n, a, a - per_point * n, 1e3 * per_point])

    fa = originals["flank_at"]
    for a, k in calls.get("flank_at", []):
        guess = k.get("guess")
        g2 = None if guess is None else tuple(twice(x) for x in guess)
        row(f"R_eq solve, {a[1]} {np.shape(a[3])}", int(np.size(a[3])),
            lambda a=a, k=k: fa(*a, **k),
            lambda a=a, g2=g2: fa(a[0], a[1], a[2], twice(a[3]), twice(a[4]), guess=g2))
    gfu = originals["gear_flank_under"]
    for a, k in calls.get("gear_flank_under", []):
        doubled = (a[0], a[1], *(twice(x) for x in a[2:]))
        row("gear flank foot (pinion edges)", np.size(a[2]), lambda a=a, k=k: gfu(*a, **k),
            lambda doubled=doubled: gfu(*doubled))
    spm = originals["shell_points_many"]
    for a, k in calls.get("shell_points_many", []):
        jobs, tol = a
        n = sum(j[1].shape[0] + (0 if j[4] is None else j[4].shape[0]) for j in jobs)
        jobs2 = [(j[0], twice(j[1]), twice(j[2]), j[3], twice(j[4])) for j in jobs]
        row(f"shell mapping, {len(jobs)} members", n, lambda a=a, k=k: spm(*a, **k),
            lambda jobs2=jobs2, tol=tol: spm(jobs2, tol))
    cc = originals["contact_curves"]
    for a, k in calls.get("contact_curves", []):
        eo, target = a
        row(f"contact curves {target.shape} (UTCA)", target.size,
            lambda a=a, k=k: cc(*a, **k),
            lambda eo=eo, target=target, k=k: cc(eo, np.concatenate([target, target + 1e-4]),
                                                 **k))
    rows.append(["sum", sum(r[1] for r in rows), sum(r[2] for r in rows),
                 sum(r[3] for r in rows), ""])
    print(f"a study point's calls, each alone and with its points doubled (mean of {args.reps})")
    print(tabulate(rows, headers=["call", "points", "CPU [ms]", "per call [ms]",
                                  "per point [µs]"], floatfmt=".2f"))


if __name__ == "__main__":
    main()
