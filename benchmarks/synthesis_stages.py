"""Where ``ltca synthesize`` spends its CPU, per stage of the development (issue 71's
"Done when": a new design from basic data to its verdict, synthesize + the first ``ltca
run``, within 2 min of CPU; issue 75: cheaper development trials).

For each basic file (default: the slowest designs of docs/own_gear_set.md's table "Issue
71's criteria on twenty-one designs" among ``tests/data/designs/``) ``ltca synthesize``
runs in this process with an empty FE cache of its own (``HYPOID_LTCA_CACHE`` a fresh
temporary directory, as a user's first design), the development's functions wrapped
where they are looked up, and its CPU is split per stage, exclusive of the stages nested
in it (:class:`StageCPU`): the coarse search's trials, the confirmation of the best
designs at the default sampling, the check steps (variants at the default sampling), the
tolerance checks at ΔE/ΔP, the static, root-stress and pitting capacity checks, the coast
flank's development and capacity checks, the FE builds of both members, and, nested in
those, the synthesis' steps 3–6 of each bearing design and the tip planes (step 8). Then
``ltca run`` of the written case runs as a subprocess on the same FE cache (the first run
after synthesize, as a user runs it) and its CPU is added: the issue's budget.

CPU is user + system time of this process and of its children (the FE solver worker,
``resource.getrusage``); a child's CPU is counted in the stage that waits for it to end.
CPU, not wall time: the machine may be shared. The numba cache must be warm for the tree
run (a first run of a new worktree or environment compiles the kernels inside the first
trials: 34–37 s more on the spiral bevels 19x23 at beta_m 46 deg, 18x27 and the miter
20x20, docs/own_gear_set.md "Where the slowest designs' synthesize goes"): run a tree
once before comparing it. Also ``--diff DIR``: compare the case files
written with ``DIR/<design>.toml`` (e.g. an earlier tree's), line for line but for the
development's CPU seconds and the basic file's directory, which the file records.

``--cache DIR``: the FE cache ``DIR`` instead of an empty one (a cache already warm for
the designs: the development's CPU alone, the FE builds read from it; issue 75's split
of a new design's synthesize into its FE builds and the development).

Usage: ``python benchmarks/synthesis_stages.py [BASIC.toml ...] [--keep DIR] [--no-run]
[--diff DIR] [--cache DIR] [--progress]``. One design takes 2–4 min of CPU.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

from _common import Wrapped, import_development
from _common import cpu_seconds as _cpu

ROOT = Path(__file__).resolve().parent.parent
DESIGNS = [ROOT / "tests" / "data" / "designs" / f"{n}.toml" for n in
           ("hypoid_10x37_s75", "fh_hypoid_10x37_m2", "eaxle_hypoid_11x39_s80",
            "fh_spiral_bevel_12x37_m3")]
#: the issue's budget for synthesize + the first ltca run [s CPU]
BUDGET = 120.0

#: (module, function, stage) timed; the function is wrapped in every loaded module of the
#: toolkit that holds it (a ``from ... import`` name too). Stages nested in another are
#: exclusive of it: a check's LTCA inside the search is the search's, its synthesis'
#: steps 3-6 and tip planes their own.
STAGES = (
    ("contact.optimize.development_stages", "search_flank",
     "search: coarse LTCA trials (drive; coast nested in coast development)"),
    ("contact.optimize.development_check", "checked_best",
     "confirmation of the best designs at the default sampling"),
    ("contact.optimize.development_check", "check_steps",
     "check steps: variants at the default sampling"),
    ("contact.optimize.development_check", "static_capacity", "static capacity checks"),
    ("contact.optimize.development_root", "root_capacity",
     "root-stress / pitting capacity checks"),
    ("contact.optimize.development_check", "tolerance_checks", "tolerance checks at dE/dP"),
    ("contact.optimize.development_coast_flank", "coast_development",
     "coast flank development"),
    ("contact.optimize.development_coast_flank", "coast_flank_capacity",
     "coast capacity checks"),
    ("contact.optimize.development_coast_flank", "coast_at_its_torque",
     "coast flank developed again at its torque"),
    ("contact.optimize.development_root", "both_flanks_built",
     "FE builds of both members (solver worker included)"),
    ("contact.compliance.fe.influence", "build_influence_model", "FE builds (counted)"),
    ("geometry.synthesis.case_synthesis", "_unrelieved_flank",
     "synthesis steps 3-6 of a bearing design (nested)"),
    ("geometry.synthesis.case_synthesis", "tip_plane_on_root_cone",
     "tip planes, step 8 (nested)"),
)


class StageCPU:
    """Exclusive CPU seconds and calls per stage of :data:`STAGES` while installed, and
    each stage's inclusive CPU (its outermost calls, the stages nested in them included:
    the coast flank developed again at its torque with its search and checks)."""

    def __init__(self) -> None:
        self.cpu: dict[str, float] = defaultdict(float)
        self.inclusive: dict[str, float] = defaultdict(float)
        self.calls: dict[str, int] = defaultdict(int)
        self._stack: list[list] = []
        self._wrapped = Wrapped("synthesis stages")

    def install(self) -> StageCPU:
        for module, name, stage in STAGES:
            self._wrapped.wrap(module, name, lambda fn, stage=stage: self._timed(fn, stage))
        return self

    def remove(self) -> None:
        self._wrapped.remove()

    def _timed(self, fn, stage: str):
        clock = self

        def timed(*args, **kwargs):
            now = _cpu()
            if clock._stack:
                clock.cpu[clock._stack[-1][0]] += now - clock._stack[-1][1]
            outer = all(st != stage for st, _, _ in clock._stack)
            clock._stack.append([stage, now, now])
            clock.calls[stage] += 1
            try:
                return fn(*args, **kwargs)
            finally:
                now = _cpu()
                st, start, entered = clock._stack.pop()
                clock.cpu[st] += now - start
                if outer:
                    clock.inclusive[st] += now - entered
                if clock._stack:
                    clock._stack[-1][1] = now

        return timed


def run_design(basic: Path, work: Path, run: bool = True, cache: Path | None = None,
               progress: bool = False) -> dict:
    """Synthesise one design in this process (stages timed), then ``ltca run`` it; with
    the FE cache ``cache`` (default: an empty one of its own under ``work``);
    ``progress``: the development's progress lines on standard error."""
    from contact.cli import main

    case = work / f"{basic.stem}.toml"
    if cache is None:
        cache = Path(tempfile.mkdtemp(prefix="ltca-fe-", dir=work))
    os.environ["HYPOID_LTCA_CACHE"] = str(cache)
    import_development()
    clock = StageCPU().install()
    c0, w0 = _cpu(), time.perf_counter()
    try:
        rc = main(["synthesize", str(basic), "-o", str(case),
                   *(() if progress else ("--no-progress",))])
    finally:
        clock.remove()
    row = {"design": basic.stem, "rc": rc, "synth_cpu": _cpu() - c0,
           "synth_wall": time.perf_counter() - w0, "stages": dict(clock.cpu),
           "inclusive": dict(clock.inclusive), "calls": dict(clock.calls), "case": case}
    row["stages"]["development other (develop, final syntheses, records)"] = (
        row["synth_cpu"] - sum(clock.cpu.values()))
    if run and rc == 0:
        c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        p = subprocess.run([sys.executable, "-m", "contact", "run", str(case), "-o",
                            str(work / f"{basic.stem}.nc"), "-q"], capture_output=True,
                           text=True, check=False, env=dict(os.environ))
        c2 = resource.getrusage(resource.RUSAGE_CHILDREN)
        row["run_cpu"] = (c2.ru_utime + c2.ru_stime) - (c1.ru_utime + c1.ru_stime)
        row["run_rc"] = p.returncode
    return row


def print_row(row: dict, diff: Path | None) -> None:
    print(f"\n{row['design']}: synthesize {row['synth_cpu']:.1f} s CPU"
          + (f" + first ltca run {row['run_cpu']:.1f} s = "
             f"{row['synth_cpu'] + row['run_cpu']:.1f} s (budget {BUDGET:g})"
             if "run_cpu" in row else "") + ("" if row["rc"] == 0 else " (synthesize failed)"))
    print("| stage | CPU [s] | share | inclusive [s] | calls |\n|---|---|---|---|---|")
    total = row["synth_cpu"]
    for stage, cpu in sorted(row["stages"].items(), key=lambda kv: -kv[1]):
        inc = row.get("inclusive", {}).get(stage)
        print(f"| {stage} | {cpu:.1f} | {100 * cpu / total:.0f} % | "
              f"{'' if inc is None else f'{inc:.1f}'} | {row['calls'].get(stage, '')} |")
    if diff is not None:
        old = diff / f"{row['design']}.toml"
        same = old.is_file() and _same_numbers(old) == _same_numbers(Path(row["case"]))
        print(f"case file against {old}: {'identical' if same else 'DIFFERENT or missing'} "
              "(but for its CPU seconds and the basic file's path)")


def _same_numbers(path: Path) -> list[str]:
    """A case file written by ``ltca synthesize`` without what differs between two runs of
    the same numbers: the development's CPU seconds (``cpu_seconds``, the table
    ``[development.cpu_seconds_stages]``) and the basic file's directory as given."""
    out, skip = [], False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("["):
            skip = line.strip() == "[development.cpu_seconds_stages]"
        if not (skip or line.startswith("cpu_seconds =")):
            out.append(re.sub(r"[^\s`\"]*/(?=[^/\s`\"]+\.toml)", "", line))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("basic", nargs="*", type=Path, help="basic design files (default: "
                    + ", ".join(p.stem for p in DESIGNS) + ")")
    ap.add_argument("--keep", type=Path, help="write the cases, runs and FE caches here")
    ap.add_argument("--no-run", dest="run", action="store_false",
                    help="synthesize only (no ltca run)")
    ap.add_argument("--diff", type=Path, help="compare each case written with DIR/<design>"
                    ".toml byte for byte")
    ap.add_argument("--progress", action="store_true", help="the development's progress "
                    "lines on standard error (which designs each stage analysed)")
    ap.add_argument("--cache", type=Path, help="use this FE cache (warm: the development "
                    "alone) instead of an empty one per design")
    args = ap.parse_args(argv)
    work = args.keep or Path(tempfile.mkdtemp(prefix="synthesis-stages-"))
    work.mkdir(parents=True, exist_ok=True)
    for basic in args.basic or DESIGNS:
        print_row(run_design(basic.resolve(), work.resolve(), args.run,
                             None if args.cache is None else args.cache.resolve(),
                             args.progress), args.diff)
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
