"""A study point's CPU time by stage, of this tree and of an earlier commit, in one run.

    python benchmarks/study_point.py                   # this tree, 8 points
    python benchmarks/study_point.py --before aa62cb2  # and that commit, same points
    python benchmarks/study_point.py --points 16

Each tree runs in a child process of its own (``git archive`` of ``--before`` into a
temporary directory, on ``PYTHONPATH``) the points of issue 75's study row
(``benchmarks/issue75_table.py``: :func:`contact.study.engine.analyse_point` of the
default case at 250 N·m, each point a new misalignment ΔE, ΔP, so nothing is a memo hit),
after one warm-up point, with :class:`stage_clock.StageClock` (this tree's, for both)
adding up the exclusive CPU time of each stage, and prints per stage the mean CPU per
point [ms] of each tree. With two trees the children run side by side and take the points
in turn, point by point (each tree first every other point), so the machine's load moves
both columns alike; the ratio row of the point is then also the median of the per-point
ratios. CPU time ``time.process_time`` (issue 75's measure: the machine
is shared, wall times mean little); the point's median and mean over the points.

The stages are those of ``benchmarks/stage_clock.py`` and, nested in them, the parts issue
75 item 4 names: the ease-off's node placement (Newton on the exact conjugate map), the
LTCA's curve and edge segments (and in them the contact curves — the UTCA's iso-line
searches —, the R_eq curvature solves, the flank boundary and the gear flank's foot under
a pinion edge), the shell mapping (contact points onto the shell model's parameters; in it
the foot on the mid-surface and the orthogonal trajectory) and the shell matrices; the
result datasets a point builds (the ``/utca`` and ``/ltca`` Datasets, the result tree).
Below the stages, the cyclic garbage collector's CPU per point (``gc.callbacks``; it runs
inside the stages, so it is part of their times, not added to them), young generations and
full collections apart: a full collection visits every tracked object of the process.
Target (issue 75): a point ≤ 0.12 s.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from issue75_table import export_tree  # this script's folder is on sys.path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
TORQUE = 250.0

#: the finer stages (module, function, name), nested in the stage clock's
EXTRA = (
    ("contact.utca.easeoff", "map_gear_nodes", "ease-off: node placement (Newton)"),
    ("contact.ltca.segments", "_curve_part_of", "LTCA curve segments"),
    ("contact.ltca.segments", "contact_curves", "LTCA curve segments: contact curves"),
    ("contact.ltca.segments", "_curve_r_eq", "LTCA curve segments: R_eq (curvatures)"),
    ("contact.ltca.segments", "flank_boundary", "LTCA curve segments: flank boundary"),
    ("contact.ltca.segments", "edge_segments", "LTCA edge segments"),
    ("contact.ltca.edges", "_edge_r_eq_of", "LTCA edge segments: R_eq (curvatures)"),
    ("contact.ltca.edges", "gear_flank_under", "LTCA edge segments: gear flank foot"),
    ("contact.compliance.mesh", "_kept_mapping", "LTCA shell mapping"),
    ("contact.compliance.tooth", "_project_to_mid", "LTCA shell mapping: foot (Newton)"),
    ("contact.compliance.tooth", "trajectory", "LTCA shell mapping: trajectory (RK4)"),
    ("contact.compliance.mesh", "shell_matrices", "LTCA shell matrices"),
    ("contact.utca.datasets", "utca_dataset", "UTCA dataset"),
    ("contact.ltca.roll_loop", "ltca_dataset", "LTCA dataset"),
    ("contact.pipeline", "_datatree", "result tree"),
)

#: the child: the points of one tree with the stage clock; prints one JSON line
_CHILD = r"""
import gc, json, statistics, sys, time
sys.path.insert(0, sys.argv[1])  # this tree's benchmarks/ (stage_clock)
from stage_clock import StageClock
from contact.catalogue import bundled_case_path
from contact.study.engine import analyse_point
from contact.study.points import StudyInputs
from geometry.case import load_case

n, torque, extra = int(sys.argv[2]), float(sys.argv[3]), json.loads(sys.argv[4])
case = load_case(bundled_case_path())
shared = StudyInputs(case=case, torque=(torque,))
m = case.misalignment
analyse_point(shared, 0, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})
clock = StageClock(tuple(map(tuple, extra))).install()
gcs = {"young": 0.0, "oldest": 0.0, "n_oldest": 0, "t0": 0.0}

def on_gc(phase, info):  # the cyclic collector's CPU, by generation (nested in the stages)
    if phase == "start":
        gcs["t0"] = time.process_time()
    else:
        key = "oldest" if info["generation"] == 2 else "young"
        gcs[key] += time.process_time() - gcs["t0"]
        gcs["n_oldest"] += info["generation"] == 2

gc.callbacks.append(on_gc)
cpu = []
print("ready", flush=True)
for line in sys.stdin:  # the parent's turn: the index of the next point
    i = int(line)
    f = (i - (n - 1) / 2) / max(n - 1, 1)  # -1/2 ... 1/2
    point = {"delta_E": m.delta_E + 0.08 * f, "delta_P": m.delta_P - 0.04 * f}
    t0 = time.process_time()
    res = analyse_point(shared, 0, point)
    cpu.append(time.process_time() - t0)
    if res.status == 2:
        raise RuntimeError(f"study point {point} failed: {res.reason}")
    print(cpu[-1], flush=True)
clock.remove()
gc.callbacks.remove(on_gc)
print(json.dumps({"cpu": cpu, "stages": {k: v / n for k, v in clock.cpu.items()},
                  "gc": {"young": gcs["young"] / n, "oldest": gcs["oldest"] / n,
                         "n_oldest": gcs["n_oldest"], "objects": len(gc.get_objects())}}))
"""


def measure(trees: list[Path], points: int) -> list[dict]:
    """The children's results, one per tree: ``cpu`` per point [s], ``stages`` [s per
    point]; the trees' children take the points in turn (each first every other point)."""
    procs = [subprocess.Popen([sys.executable, "-c", _CHILD, str(ROOT / "benchmarks"),
                               str(points), str(TORQUE), json.dumps(EXTRA)], cwd=tree,
                              env={**os.environ, "PYTHONPATH": str(tree)},
                              stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
             for tree in trees]
    try:
        for p in procs:
            if p.stdout.readline().strip() != "ready":
                raise RuntimeError("a study point child failed before its points")
        for i in range(points):
            for p in procs if i % 2 == 0 else procs[::-1]:
                p.stdin.write(f"{i}\n")
                p.stdin.flush()
                if not p.stdout.readline():
                    raise RuntimeError(f"a study point child failed at point {i}")
        out = []
        for p in procs:
            p.stdin.close()
            out.append(json.loads(p.stdout.read().strip().splitlines()[-1]))
            if p.wait() != 0:
                raise RuntimeError("a study point child failed")
        return out
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()


def prime_kernels(tree: Path) -> None:
    """Fill the numba cache of an exported tree (``ltca compile`` run in it), so that its
    child loads the compiled kernels from the cache as this tree's does. Without it the
    child compiled them in its warm-up (a fresh ``git archive`` has no ``__pycache__``) and
    its points ran 2–3 % slower than the same code's in this tree: an A/A run (``--before``
    this tree's own commit) read a median per-point ratio of 0.98, 130,000 more objects
    tracked by the collector in that child (docs/performance.md, helper study104)."""
    subprocess.run([sys.executable, "-m", "contact.cli", "compile"], cwd=tree, check=True,
                   env={**os.environ, "PYTHONPATH": str(tree)}, capture_output=True)


def main(argv: list[str] | None = None) -> None:
    import statistics

    from tabulate import tabulate

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--before", help="also measure this commit (git archive)")
    ap.add_argument("--points", type=int, default=8, help="study points per tree (8)")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="study_point_") as tmp:
        trees = [("this tree", ROOT)]
        if args.before:
            trees.insert(0, (args.before, export_tree(args.before, Path(tmp))))
            prime_kernels(trees[0][1])
        res = dict(zip([name for name, _ in trees],
                       measure([tree for _, tree in trees], args.points), strict=True))
    names = [name for name, _ in trees]
    stages = sorted({s for r in res.values() for s in r["stages"]},
                    key=lambda s: -res["this tree"]["stages"].get(s, 0.0))
    rows = [[s, *(1e3 * res[n]["stages"].get(s, 0.0) for n in names)] for s in stages]
    rows.append(["point, mean", *(1e3 * statistics.mean(res[n]["cpu"]) for n in names)])
    rows.append(["point, median", *(1e3 * statistics.median(res[n]["cpu"]) for n in names)])
    gc_rows = [["of which cyclic GC, young generations", *(1e3 * res[n]["gc"]["young"]
                                                            for n in names)],
               ["of which cyclic GC, full collections", *(1e3 * res[n]["gc"]["oldest"]
                                                          for n in names)]]
    rows += gc_rows
    if len(names) == 2:
        for r in rows:
            r.append(f"{r[2] / r[1]:.2f} ×" if r[1] else "")
        names.append("ratio")
        pairs = [b / a for a, b in zip(res[names[0]]["cpu"], res[names[1]]["cpu"],
                                       strict=True)]
        rows.append(["point, median of the per-point ratios", None, None,
                     f"{statistics.median(pairs):.2f} ×"])
    print(f"a study point's CPU [ms] by stage (exclusive), {args.points} points, "
          f"{TORQUE:g} N·m; target 120 ms")
    print(tabulate(rows, headers=["stage", *names], floatfmt=".1f"))
    print("full collections in the run: " + ", ".join(
        f"{n} {res[n]['gc']['n_oldest']} (tracked objects {res[n]['gc']['objects']})"
        for n in names[:len(trees)]))


if __name__ == "__main__":
    main()
