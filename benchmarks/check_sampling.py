"""Could some of a development's checks at ``ltca run``'s sampling run at the search's
coarse sampling instead? (issue 75: a new design to its verdict in 20 s of CPU.)

``ltca synthesize BASIC`` runs twice, each in a child process with an empty FE cache of
its own (a user's new design): once as it is, once with the analyses of one group of
the development's checks at :data:`contact.optimize.development_evaluate.COARSE_LTCA`
(1 mesh cycle, 8 rolls, 12 segments) instead of :data:`~contact.optimize.
development_evaluate.CHECK_LTCA` (``ltca run``'s 2 cycles, 20 rolls, 24 segments):

* ``variants`` — the check's variants (:func:`contact.optimize.development_variant.
  checked_variant`: the relief, tip-relief and long-bearing variants of a checked
  design, each kept or refused on its own metrics);
* ``range`` — the LTE between the light and the design torque
  (:func:`contact.optimize.development_range_lte.range_lte`, printed by synthesize and
  read by the coast flank's edge-peak step).

Printed: each run's CPU (``ru_utime + ru_stime`` of the child and the solver worker it
waited for, ``os.wait4``) and the words of the written cases and of synthesize's printed
output that differ, the CPU records left out (the same design gives the same case but
for them).

Usage: ``python benchmarks/check_sampling.py [BASIC.toml] [--coarse variants|range]
[--keep DIR]`` (default ``tests/data/designs/pc_hypoid_10x43.toml``, ``variants``);
about 2 × 20 s of CPU on the 10×43. Measured: docs/performance.md, "A new design to its
verdict: the FE level and the check's sampling measured as levers" (helper speed86).
"""

from __future__ import annotations

import argparse
import difflib
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DESIGN = ROOT / "tests" / "data" / "designs" / "pc_hypoid_10x43.toml"

#: the child: ``ltca synthesize`` with the group ``argv[3]`` at the coarse sampling
#: (``"none"``: as it is)
_CHILD = r"""
import sys
sys.path.insert(0, sys.argv[1])
from contact.optimize import development_evaluate as ev
group = sys.argv[4]
if group == "variants":
    from contact.optimize import development_variant as dv
    checked_variant = dv.checked_variant

    def coarse_variant(*a, **k):
        dv.CHECK_LTCA = ev.COARSE_LTCA
        try:
            return checked_variant(*a, **k)
        finally:
            dv.CHECK_LTCA = ev.CHECK_LTCA

    dv.checked_variant = coarse_variant  # said_variant looks it up here
elif group == "range":
    from contact.optimize import development_range_lte as dr
    dr.CHECK_LTCA = ev.COARSE_LTCA
from contact.cli import main
sys.exit(main(["synthesize", sys.argv[2], "-o", sys.argv[3], "--no-progress"]))
"""


def synthesized(basic: Path, out: Path, group: str, cache: Path) -> float:
    """``ltca synthesize basic -o out`` in a child with ``group`` at the coarse sampling
    (``"none"``: as it is) and the FE cache ``cache``; its CPU [s] (child and worker)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT), "HYPOID_LTCA_CACHE": str(cache)}
    with out.with_suffix(".txt").open("w") as said:
        proc = subprocess.Popen([sys.executable, "-c", _CHILD, str(ROOT), str(basic),
                                 str(out), group], env=env, stdout=said,
                                stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status):
        raise RuntimeError(f"synthesize {basic.name} ({group}) failed")
    return usage.ru_utime + usage.ru_stime


def case_lines(path: Path) -> list[str]:
    """The written case's lines but its CPU records (``cpu_seconds`` and the table
    ``[development.cpu_seconds_stages]``) and the source path of the basic file."""
    lines, table = [], ""
    for x in path.read_text().splitlines():
        if x.startswith("["):
            table = x
        if "cpu_seconds" not in x and "cpu_seconds" not in table:
            lines.append(x)
    return lines


def said_lines(path: Path) -> list[str]:
    """What synthesize printed (its stdout) but the lines of CPU seconds and paths."""
    return [x for x in path.read_text().splitlines()
            if " CPU" not in x and not x.startswith("wrote ")]


def words_changed(old: list[str], new: list[str]) -> list[str]:
    """The words of ``old`` and ``new`` (lines) that differ, as ``old -> new`` spans."""
    a, b = " ".join(old).split(), " ".join(new).split()
    return [f"{' '.join(a[i1:i2])} -> {' '.join(b[j1:j2])}" for tag, i1, i2, j1, j2 in
            difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes()
            if tag != "equal"]


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("basic", nargs="?", type=Path, default=DESIGN)
    ap.add_argument("--coarse", choices=("variants", "range"), default="variants")
    ap.add_argument("--keep", type=Path, help="write both cases into this directory")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="check_sampling_") as tmp:
        where = args.keep if args.keep is not None else Path(tmp)
        where.mkdir(parents=True, exist_ok=True)
        cases, cpu = {}, {}
        for group in ("none", args.coarse):
            cases[group] = where / f"{args.basic.stem}_{group}.toml"
            cpu[group] = synthesized(args.basic, cases[group], group,
                                     Path(tmp) / f"fe_{group}")
            print(f"{args.basic.stem}: synthesize with {group} at the coarse sampling: "
                  f"{cpu[group]:.2f} s CPU", flush=True)
        for what, lines in (("written case", case_lines), ("printed summary", said_lines)):
            a = lines(cases["none"] if what == "written case"
                      else cases["none"].with_suffix(".txt"))
            b = lines(cases[args.coarse] if what == "written case"
                      else cases[args.coarse].with_suffix(".txt"))
            changed = [(i1, i2, j1, j2) for tag, i1, i2, j1, j2 in
                       difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes()
                       if tag != "equal"]
            print(f"{what}: {'the same' if not changed else f'{len(changed)} changes'} "
                  "(CPU records left out)")
            for i1, i2, j1, j2 in changed:
                print("  " + " | ".join(words_changed(a[i1:i2], b[j1:j2])))


if __name__ == "__main__":
    main()
