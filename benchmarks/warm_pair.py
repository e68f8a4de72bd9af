"""One warm analysis of this tree and of an earlier commit, alternated in one process.

    python benchmarks/warm_pair.py --before 0bca452            # 30 analyses each
    python benchmarks/warm_pair.py --before 0bca452 --runs 50 --torque 500
    python benchmarks/warm_pair.py --before /tmp/tree-0bca452  # a tree exported before
    python benchmarks/warm_pair.py --before 0bca452 --study    # and a study point each

With ``--study`` each round also runs one study point per tree (issue 75's study row,
``benchmarks/issue75_table.py``: :func:`contact.study.engine.analyse_point` of the default
case at 250 N·m, each round a new ΔE, ΔP, the same in both trees), so the table's warm
and study rows are measured interleaved in one process; the study point's medians and
paired difference are printed below the warm analysis' table.

Both trees are imported into this one process, each with its own modules (``git
archive`` of ``--before`` into a temporary directory, or a directory given, whose numba
cache a first run has filled; the modules of ``contact``,
``geometry`` and ``friction`` are swapped in ``sys.modules`` before each analysis, so each
tree runs its own code and keeps its own memos), and their analyses are alternated
(before, after, after, before, …): ``run_analysis`` of the default case at one torque (as
``ltca run`` runs it, root stress from the FE cache), after two warm-ups per tree. Each
analysis' CPU time (``time.process_time``) and its stages (:class:`stage_clock.StageClock`,
one clock per tree, with the result tree's build as a stage of its own) are recorded;
printed are the medians per tree, the median of the paired differences, and both against a
1500² Cholesky (``numpy.linalg.cholesky``, one BLAS thread, median of 5) in the same
process, issue 75's measure. On the shared machine, where another process's load moves a
lone measurement by tens of percent, the two trees then see the same load: the paired
difference is what a change buys (helper warm75h; separate processes, as
``benchmarks/issue75_table.py`` measures one tree, read 150–205 ms for the same tree).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "geometry", "friction")
#: the result tree's build, a stage of its own (nested in none of stage_clock's)
EXTRA = (("contact.pipeline", "_datatree", "result tree (DataTree)"),)


def _ours(name: str) -> bool:
    return name.split(".")[0] in PACKAGES


class Tree:
    """One tree's modules, run_analysis, case and stage clock, in this process."""

    def __init__(self, path: Path) -> None:
        from stage_clock import StageClock  # this tree's benchmarks/, on sys.path

        self.path = str(path)
        for name in [n for n in sys.modules if _ours(n)]:
            del sys.modules[name]
        sys.path.insert(0, self.path)
        try:
            from contact.catalogue import bundled_case_path
            from contact.pipeline import run_analysis
            from contact.study.engine import analyse_point
            from contact.study.points import StudyInputs
            from geometry.case import load_case

            self.case = load_case(bundled_case_path())
            self.run_analysis = run_analysis
            self.analyse_point = analyse_point
            self.shared = StudyInputs(case=self.case, torque=(250.0,))
            self.clock = StageClock(EXTRA).install()
        finally:
            sys.path.remove(self.path)
        self.modules = {n: m for n, m in sys.modules.items() if _ours(n)}
        self._check()

    def _check(self) -> None:
        stray = [n for n, m in self.modules.items()
                 if getattr(m, "__file__", None) and not m.__file__.startswith(self.path)]
        if stray:
            raise RuntimeError(f"modules of another tree in {self.path}: {stray[:3]}")

    def analyse(self, torque: float) -> tuple[float, dict[str, float]]:
        """CPU seconds of one analysis and its stages [s]."""
        return self._timed(lambda: self.run_analysis(self.case, [torque]))

    def study_point(self, f: float) -> tuple[float, dict[str, float]]:
        """CPU seconds of one study point at ΔE + 0.08 f, ΔP − 0.04 f [mm] (f in
        [−0.5, 0.5]: ``benchmarks/sample_profile.py``'s points) and its stages [s]."""
        m = self.case.misalignment
        point = {"delta_E": m.delta_E + 0.08 * f, "delta_P": m.delta_P - 0.04 * f}

        def run():
            res = self.analyse_point(self.shared, 0, point)
            if res.status == 2:
                raise RuntimeError(f"study point {point} failed: {res.reason}")
        return self._timed(run)

    def _timed(self, task) -> tuple[float, dict[str, float]]:
        for name in [n for n in sys.modules if _ours(n)]:
            del sys.modules[name]
        sys.modules.update(self.modules)  # a module imported lazily: this tree's
        sys.path.insert(0, self.path)
        self.clock.reset()
        try:
            t0 = time.process_time()
            task()
            cpu = time.process_time() - t0
        finally:
            sys.path.remove(self.path)
        self.modules.update({n: m for n, m in sys.modules.items() if _ours(n)})
        self._check()
        return cpu, dict(self.clock.cpu)


def main(argv: list[str] | None = None) -> None:
    from issue75_table import cholesky_seconds, export_tree  # this script's folder
    from tabulate import tabulate

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--before", required=True,
                    help="the earlier commit (git archive), or the directory of its tree")
    ap.add_argument("--runs", type=int, default=30, help="analyses per tree (30)")
    ap.add_argument("--torque", type=float, default=250.0, help="pinion torque [N m]")
    ap.add_argument("--study", action="store_true",
                    help="also a study point per tree and round (issue 75's study row)")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="warm_pair_") as tmp:
        before = Path(args.before)
        if not before.is_dir():
            before = export_tree(args.before, Path(tmp))
        trees = {args.before: Tree(before), "this tree": Tree(ROOT)}
        names = list(trees)
        for tree in trees.values():  # two warm-ups each
            tree.analyse(args.torque)
            tree.analyse(args.torque)
            if args.study:
                tree.study_point(0.625)  # a point none of the rounds repeats
        cpu: dict[str, list[float]] = {n: [] for n in names}
        stages: dict[str, list[dict]] = {n: [] for n in names}
        study: dict[str, list[float]] = {n: [] for n in names}
        for i in range(args.runs):
            for name in names if i % 2 == 0 else names[::-1]:
                t, s = trees[name].analyse(args.torque)
                cpu[name].append(t)
                stages[name].append(s)
                if args.study:
                    f = (i - (args.runs - 1) / 2) / max(args.runs - 1, 1)
                    study[name].append(trees[name].study_point(f)[0])
    chol = cholesky_seconds()
    keys = list(dict.fromkeys(k for n in names for s in stages[n] for k in s))
    rows = [[k, *(1e3 * statistics.median(s.get(k, 0.0) for s in stages[n])
                  for n in names)] for k in keys]
    rows.append(["rest (chain, attributes, summary, merges)",
                 *(1e3 * statistics.median(t - sum(s.values())
                                           for t, s in zip(cpu[n], stages[n], strict=True))
                   for n in names)])
    rows.append(["analysis (median)", *(1e3 * statistics.median(cpu[n]) for n in names)])
    rows.append(["× Cholesky 1500²", *(statistics.median(cpu[n]) / chol for n in names)])
    diff = [b - a for b, a in zip(cpu[names[0]], cpu[names[1]], strict=True)]
    print(f"warm analysis at {args.torque:g} N·m, CPU [ms], {args.runs} alternated "
          f"analyses per tree; Cholesky 1500² {1e3 * chol:.0f} ms; load "
          f"{os.getloadavg()[0]:.1f}")
    print(tabulate(rows, headers=["stage (exclusive, median)", *names], floatfmt=".1f"))
    print(f"paired difference ({names[0]} − this tree): median "
          f"{1e3 * statistics.median(diff):.1f} ms, mean {1e3 * statistics.mean(diff):.1f} "
          f"± {1e3 * statistics.stdev(diff) / len(diff) ** 0.5:.1f} ms (standard error)")
    if args.study:
        sd = [b - a for b, a in zip(study[names[0]], study[names[1]], strict=True)]
        ratio = [a / b for b, a in zip(study[names[0]], study[names[1]], strict=True)]
        print(f"\nstudy point at 250 N·m, CPU [ms], {args.runs} alternated points per tree "
              "(target 120 ms)")
        print(tabulate([["study point (median)",
                         *(1e3 * statistics.median(study[n]) for n in names)],
                        ["study point (least)", *(1e3 * min(study[n]) for n in names)]],
                       headers=["", *names], floatfmt=".1f"))
        print(f"paired difference ({names[0]} − this tree): median "
              f"{1e3 * statistics.median(sd):.1f} ms, mean {1e3 * statistics.mean(sd):.1f} "
              f"± {1e3 * statistics.stdev(sd) / len(sd) ** 0.5:.1f} ms; per-point ratio "
              f"(this tree / {names[0]}) median {statistics.median(ratio):.3f}")


if __name__ == "__main__":
    main()
