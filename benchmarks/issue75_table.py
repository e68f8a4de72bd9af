"""Issue 75's table, measured in one run: where users wait, in CPU seconds and peak memory.

    python benchmarks/issue75_table.py                    # everything (~5 min of CPU)
    python benchmarks/issue75_table.py --only fe warm     # some rows
    python benchmarks/issue75_table.py --before ace80ff   # the FE build of that commit too
    python benchmarks/issue75_table.py --only design --design a.toml b.toml  # other designs

Rows (each command in a fresh child process, its CPU time ``ru_utime + ru_stime`` and its
peak resident memory ``ru_maxrss`` from ``os.wait4``: the process and the children it
waited for, so the FE build's solver worker counts; the largest of them, not the sum):

* ``design`` — a new design from basic data to its verdict: ``ltca synthesize`` of
  ``tests/data/designs/pc_hypoid_10x43.toml`` and a cold ``ltca run`` of the case it
  writes, both with one FE cache that is empty at the start (a new design: the FE models
  synthesize builds for its root-stress checks are there for ``ltca run``, as on a user's
  machine; before 2026-11-25 synthesize used the user's cache and the run an empty one,
  so the drive models were built twice, or synthesize's not at all where the user's cache
  held them); the numba cache as this machine has it;
* ``design-fresh`` — the same on a fresh machine: the numba cache (``NUMBA_CACHE_DIR``) a
  temporary directory, empty at the start and shared by the two commands (what
  synthesize compiles, ``ltca run`` reads);
* ``cold`` — the first ``ltca run`` of the default case on a fresh machine: empty numba
  cache (``NUMBA_CACHE_DIR``) and empty FE cache (``HYPOID_LTCA_CACHE``), both temporary
  directories;
* ``fe`` — the FE build of both members' root-stress coefficients alone
  (:func:`contact.compliance.fe.influence_coefficients`, empty cache), of this tree and,
  with ``--before REV``, of commit REV (``git archive`` into a temporary directory, run
  from there): the build's before/after in one run, and the peak root-stress
  coefficients of both compared (``fillet_max_principal``, max relative difference);
* ``warm`` — one warm analysis at 250 N·m in this process (``run_analysis`` as ``ltca
  run`` runs it, root stress read from the FE cache, after one warm-up; median of 5)
  against a 1500² Cholesky (``numpy.linalg.cholesky``, one BLAS thread, median of 5),
  with each stage's CPU (``benchmarks/stage_clock.py``);
* (with ``warm``) a warm analysis at a torque new to the process, five torques from 0.8 to
  1.2 × 250 N·m in turn: what a torque series at one misalignment pays per analysis
* ``study`` — a study point's CPU in this process (:func:`contact.study.engine.
  analyse_point` at 250 N·m, 5 misalignments, median).

The anchors (docs/performance.md): the seed's 45 s per analysis (seed §3.4), BECAL's "a
few minutes", the seed's FE run of 15 minutes. Targets (issue 75, the 2-core machine):
design ≤ 20 s CPU (``design-fresh`` ≤ 30 s), cold ≤ 25 s and ≤ 1.0 GB, warm ≤ 3 ×
the Cholesky, a study point ≤ 0.12 s. CPU times vary with the machine's load (another
process's cache traffic), much less than wall times; ratios of one run are the stable
numbers.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
DESIGN = ROOT / "tests" / "data" / "designs" / "pc_hypoid_10x43.toml"
TORQUE = 250.0
SEED_ANALYSIS_S = 45.0  # seed §3.4: one LTCA, 3.0 GHz PC
SEED_FE_S = 15 * 60.0  # the seed's FE run
ROWS = ("design", "design-fresh", "cold", "fe", "warm", "study")

#: the FE build of both members in a child process: prints the peak coefficient file
_FE_CHILD = r"""
import os, sys
import numpy as np
from contact.catalogue import bundled_case_path
from contact.compliance.fe.influence import influence_coefficients
from geometry.case import load_case
case = load_case(bundled_case_path())
for member in ("pinion", "gear"):
    ds = influence_coefficients(case, member, cache_dir=sys.argv[1], progress=False)
    np.save(os.path.join(sys.argv[2], member + ".npy"), ds["fillet_max_principal"].values)
"""


def child(args: list[str], *, cwd: Path = ROOT, env: dict | None = None,
          log: Path | None = None) -> tuple[float, float, float]:
    """(CPU [s], peak RSS [GB], wall [s]) of a command run to its end; raises if it fails."""
    t0 = time.perf_counter()
    out = open(log, "w") if log is not None else subprocess.DEVNULL
    try:
        proc = subprocess.Popen(args, cwd=cwd, env={**os.environ, **(env or {})},
                                stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
    finally:
        if log is not None:
            out.close()
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, args))} failed ({proc.returncode}); see {log}")
    return (usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 2**20,
            time.perf_counter() - t0)


def _cli(*words) -> list[str]:
    return [sys.executable, "-m", "contact", *map(str, words)]


def row_design(tmp: Path, design: Path = DESIGN, fresh_numba: bool = False) -> list[list]:
    """The new-design rows of one basic file (its stem names them where it is not
    :data:`DESIGN`), in ``tmp/<stem>/`` (``tmp/<stem>-fresh/`` with ``fresh_numba``): one
    FE cache, empty at the start; with ``fresh_numba`` one numba cache, empty too."""
    here = tmp / (design.stem + ("-fresh" if fresh_numba else ""))
    here.mkdir(parents=True, exist_ok=True)
    case = here / "design.toml"
    # one empty FE cache for both commands, as on the user's machine: a new design has no
    # FE model in it, synthesize builds what it checks and ltca run reads what it finds
    fe = {"HYPOID_LTCA_CACHE": str(here / "fe-design")}
    if fresh_numba:  # a fresh machine: what synthesize compiles (if anything) ltca run reads
        fe["NUMBA_CACHE_DIR"] = str(here / "numba-fresh")
    s = child(_cli("synthesize", design, "-o", case, "-q"), env=fe,
              log=here / "synthesize.log")
    r = child(_cli("run", case, "-o", here / "design.nc", "-q"), env=fe,
              log=here / "design-run.log")
    what = "new design" if design == DESIGN else f"new design {design.stem}"
    if fresh_numba:
        what += ", fresh numba cache"
    return [[f"{what}: synthesize", s[0], s[1], ""],
            [f"{what}: cold run (empty FE cache)", r[0], r[1], ""],
            [f"{what}: basic data to verdict", s[0] + r[0], max(s[1], r[1]),
             "target 30 s (issue 75)" if fresh_numba
             else "target 120 s (issue 71), 20 s (issue 75)"]]


def row_cold(tmp: Path) -> list[list]:
    r = child(_cli("run", "-o", tmp / "cold.nc", "-q"),
              env={"HYPOID_LTCA_CACHE": str(tmp / "fe-cold"),
                   "NUMBA_CACHE_DIR": str(tmp / "numba-cold")}, log=tmp / "cold.log")
    return [["first ltca run, fresh numba and FE caches", r[0], r[1],
             "target 25 s, 1.0 GB"]]


def export_tree(rev: str, tmp: Path) -> Path:
    """The tree of commit ``rev`` in a directory of its own (``git archive``)."""
    dest = tmp / f"tree-{rev}"
    dest.mkdir()
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(dest)], input=archive, check=True)
    return dest


def row_fe(tmp: Path, before: str | None) -> list[list]:
    import numpy as np

    trees = [("this tree", ROOT)]
    if before:
        trees.insert(0, (before, export_tree(before, tmp)))
    rows, peaks = [], {}
    for name, tree in trees:
        out = tmp / f"fe-out-{len(rows)}"
        out.mkdir()
        c = child([sys.executable, "-c", _FE_CHILD, str(tmp / f"fe-cache-{len(rows)}"),
                   str(out)], cwd=tree, log=tmp / f"fe-{len(rows)}.log")
        peaks[name] = [np.load(out / f"{m}.npy") for m in ("pinion", "gear")]
        rows.append([f"FE build, pinion + gear ({name})", c[0], c[1],
                     f"the seed's FE run 15 min: / {SEED_FE_S / c[0]:.0f}"])
    if before:
        diff = max(float(np.abs(a - b).max() / np.abs(b).max())
                   for a, b in zip(peaks["this tree"], peaks[before], strict=True))
        rows.append(["  ratio this tree / before", rows[1][1] / rows[0][1],
                     rows[1][2] / rows[0][2],
                     f"fillet_max_principal max rel. difference {diff:.1e}"])
    return rows


def cholesky_seconds() -> float:
    """Median CPU seconds of five 1500² Cholesky factorisations (one BLAS thread): the
    reference the warm analysis is measured against (also benchmarks/warm_pair.py)."""
    import numpy as np

    a = np.random.default_rng(0).standard_normal((1500, 1500))
    a = a @ a.T + 1500 * np.eye(1500)
    times = []
    for _ in range(5):
        t0 = time.process_time()
        np.linalg.cholesky(a)
        times.append(time.process_time() - t0)
    return statistics.median(times)


def row_warm(tmp: Path) -> tuple[list[list], dict]:
    from stage_clock import StageClock

    from contact.catalogue import bundled_case_path
    from contact.pipeline import run_analysis
    from geometry.case import load_case

    os.environ["HYPOID_LTCA_CACHE"] = str(tmp / "fe-cold")  # built by the cold row, or now
    case = load_case(bundled_case_path())
    run_analysis(case, [TORQUE])  # warm-up (and the FE coefficients, if not built yet)
    clock = StageClock().install()
    times, stages = [], []
    try:
        for _ in range(5):
            clock.reset()
            t0 = time.process_time()
            run_analysis(case, [TORQUE])
            times.append(time.process_time() - t0)
            stages.append(dict(clock.cpu))
    finally:
        clock.remove()
    c = cholesky_seconds()
    # a torque series at the case's misalignment: each torque new to the process (the
    # ease-off, its curve segments and the shell's per-segment work are kept, the edge
    # segments, the pools' selection, the solves and the root stress are not)
    series = []
    for k in range(5):
        t0 = time.process_time()
        run_analysis(case, [TORQUE * (0.8 + 0.1 * k) + 1.0])
        series.append(time.process_time() - t0)
    t = statistics.median(times)
    t_new = statistics.median(series)
    med = {k: statistics.median(s.get(k, 0.0) for s in stages) for k in stages[0]}
    med["rest (chain, datasets, writing groups)"] = t - sum(med.values())
    return ([["warm analysis at 250 N·m (median of 5)", t, None,
              f"{t / c:.1f} × Cholesky 1500² ({c * 1e3:.0f} ms); target 3 ×; seed 45 s: "
              f"/ {SEED_ANALYSIS_S / t:.0f}"],
             ["warm analysis at a torque new to the process (median of 5)", t_new, None,
              f"{t_new / c:.1f} × Cholesky; a torque series at one misalignment"]], med)


def row_study() -> list[list]:
    from contact.catalogue import bundled_case_path
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from geometry.case import load_case

    case = load_case(bundled_case_path())
    shared = StudyInputs(case=case, torque=(TORQUE,))
    m = case.misalignment
    # warm-up at a point none of the five repeats: a study never analyses a point twice,
    # and the ease-off of a point analysed before is a memo hit (contact.utca.ease_off)
    analyse_point(shared, 0, {"delta_E": m.delta_E + 0.05, "delta_P": m.delta_P - 0.03})
    cpu = []
    for i in range(5):
        point = {"delta_E": m.delta_E + 0.02 * (i - 2), "delta_P": m.delta_P + 0.01 * (2 - i)}
        t0 = time.process_time()
        res = analyse_point(shared, 0, point)
        cpu.append(time.process_time() - t0)
        if res.status == 2:
            raise RuntimeError(f"study point {point} failed: {res.reason}")
    return [["study point, one process (median of 5)", statistics.median(cpu), None,
             "target 0.12 s"]]


def main(argv: list[str] | None = None) -> None:
    from tabulate import tabulate

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", nargs="+", choices=ROWS, default=list(ROWS))
    ap.add_argument("--before", metavar="REV", help="also the FE build of this commit")
    ap.add_argument("--design", metavar="BASIC", nargs="+", type=Path, default=[DESIGN],
                    help="the basic design files of the design row (default "
                         "tests/data/designs/pc_hypoid_10x43.toml); each its own rows")
    ap.add_argument("--keep", metavar="DIR", help="work in DIR (kept) instead of a temporary "
                                                  "directory")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    sys.path.insert(0, str(ROOT))  # the in-process rows measure this tree, as the children
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "-uno"],
                           capture_output=True, text=True).stdout.strip()
    with tempfile.TemporaryDirectory(prefix="issue75-") as scratch:
        tmp = Path(args.keep or scratch)
        tmp.mkdir(parents=True, exist_ok=True)
        rows, stages = [], None
        for name in args.only:
            if name == "design":
                for design in args.design:
                    rows += row_design(tmp, design.resolve())
            elif name == "design-fresh":
                for design in args.design:
                    rows += row_design(tmp, design.resolve(), fresh_numba=True)
            elif name == "cold":
                rows += row_cold(tmp)
            elif name == "fe":
                rows += row_fe(tmp, args.before)
            elif name == "warm":
                more, stages = row_warm(tmp)
                rows += more
            else:
                rows += row_study()
    when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    print(f"issue 75 table: commit {commit}{' (modified)' if dirty else ''}, "
          f"load average {os.getloadavg()[0]:.1f}, {when}")
    print(tabulate([[r[0], f"{r[1]:.2f}", "" if r[2] is None else f"{r[2]:.2f}", r[3]]
                    for r in rows], headers=["what", "CPU [s]", "peak RSS [GB]", "note"],
                   tablefmt="github"))
    if stages:
        total = sum(stages.values())
        print("\nwarm analysis by stage (exclusive CPU, median of 5)")
        print(tabulate([[k, f"{v * 1e3:.0f}", f"{100 * v / total:.0f} %"]
                        for k, v in sorted(stages.items(), key=lambda kv: -kv[1])],
                       headers=["stage", "CPU [ms]", "share"], tablefmt="github"))


if __name__ == "__main__":
    main()
