"""Where a new design's ``ltca synthesize`` spends its CPU, analysis by analysis (issue 75:
a new design to its verdict in 20 s; which trials and checks there are, and what each
costs).

``ltca synthesize BASIC`` runs in this process with an empty FE cache of its own
(``HYPOID_LTCA_CACHE`` a fresh temporary directory, a user's new design) and with four
functions wrapped where the development looks them up:

* every design analysis (:func:`contact.optimize.development_evaluate.analyse_design`,
  the analysis seam of the development: the coarse search's trials, the checks at the
  default sampling, the tolerance excursions, the coast flank's);
* every full analysis (:func:`contact.pipeline.run_analysis`: the root-stress, pitting
  and coast-capacity checks, with the FE root stress and the ISO 10300 rating);
* every synthesis (:func:`geometry.synthesis.case_synthesis.synthesize`: the trials'
  designs, the checked designs placed as written, the final passes);
* the FE builds of both members (:func:`contact.optimize.development_root.
  both_flanks_built`), with the CPU of the solver worker it waits for (the
  factorisation and the unit-load solves run in a worker process, counted by
  ``resource.RUSAGE_CHILDREN`` when the worker ends, at the end of its session).

Printed: one line per analysis (CPU, kind, torques, flank and the development step that
asked for it: the innermost functions of ``contact.optimize.development*`` on the
stack), then a table of the synthesize's CPU by kind. CPU is user + system time of this
process and of its ended children; the numba cache must be warm (run a tree once).

Usage: ``python benchmarks/synthesis_calls.py [BASIC.toml] [--cache DIR] [--quiet]``
(default ``tests/data/designs/pc_hypoid_10x43.toml``, the design of issue 75's table).
One design takes ~20 s of CPU.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import traceback
from collections import defaultdict
from pathlib import Path

from _common import Wrapped, import_development
from _common import cpu_seconds as _cpu

ROOT = Path(__file__).resolve().parent.parent
DESIGN = ROOT / "tests" / "data" / "designs" / "pc_hypoid_10x43.toml"

#: (module, function, kind) wrapped; ``kind`` None: the analysis' kind is read from its
#: options (coarse, default sampling, misaligned)
WRAPPED = (
    ("contact.optimize.development_evaluate", "analyse_design", None),
    ("contact.pipeline", "run_analysis", "full analysis (root stress, rating)"),
    ("geometry.synthesis.case_synthesis", "synthesize", "syntheses"),
    ("contact.optimize.development_root", "both_flanks_built",
     "FE builds of both members (solver worker included)"),
)


def _step() -> str:
    """The innermost development functions on the stack (at most three, innermost first):
    the step that asked for the call."""
    frames = [f for f in traceback.extract_stack()[:-3]
              if "/contact/optimize/development" in f.filename.replace(os.sep, "/")]
    names = [f"{Path(f.filename).stem.removeprefix('development_')}.{f.name}"
             for f in reversed(frames)]
    return " < ".join(names[:3])


def _analysis_kind(args: tuple, kwargs: dict) -> str:
    """coarse trial / default sampling / misaligned, from analyse_design's arguments."""
    from contact.optimize.development_evaluate import COARSE_LTCA

    options = kwargs.get("options", args[3] if len(args) > 3 else COARSE_LTCA)
    misaligned = kwargs.get("misalignment", args[2] if len(args) > 2 else None) is not None
    what = ("coarse LTCA" if (options.rolls_per_cycle, options.segments)
            == (COARSE_LTCA.rolls_per_cycle, COARSE_LTCA.segments) else "default sampling")
    return f"design analysis, {what}" + (", misaligned" if misaligned else "")


class CallClock:
    """The wrapped functions' calls: (CPU [s], kind, torques, flank, step), outermost calls
    of each function only (a synthesis inside a synthesis counts once)."""

    def __init__(self) -> None:
        self.calls: list[tuple[float, str, tuple[float, ...], str, str]] = []
        self._depth: dict[str, int] = defaultdict(int)
        self._wrapped = Wrapped("synthesis calls")

    def install(self) -> CallClock:
        for module, name, kind in WRAPPED:
            self._wrapped.wrap(module, name,
                               lambda fn, name=name, kind=kind: self._timed(fn, name, kind))
        return self

    def remove(self) -> None:
        self._wrapped.remove()

    def _timed(self, fn, name: str, kind: str | None):
        clock = self

        def timed(*args, **kwargs):
            if clock._depth[name]:
                return fn(*args, **kwargs)
            clock._depth[name] += 1
            c0 = _cpu()
            try:
                return fn(*args, **kwargs)
            finally:
                clock._depth[name] -= 1
                seconds = _cpu() - c0
                torques = kwargs.get("torques", args[1] if len(args) > 1 else ())
                try:
                    torques = tuple(round(float(t), 1) for t in torques)
                except TypeError:  # a synthesis or an FE build: no torques
                    torques = ()
                flank = str(kwargs.get("flank", args[6] if name == "analyse_design"
                                       and len(args) > 6 else "drive"))
                what = kind if kind is not None else _analysis_kind(args, kwargs)
                clock.calls.append((seconds, what, torques,
                                    flank if torques else "", _step()))

        return timed


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("basic", nargs="?", default=str(DESIGN), help="basic design file")
    parser.add_argument("--cache", help="FE cache directory (default an empty temporary one)")
    parser.add_argument("--quiet", action="store_true", help="the table only, no call lines")
    args = parser.parse_args(argv)

    with tempfile.TemporaryDirectory() as tmp:
        os.environ["HYPOID_LTCA_CACHE"] = args.cache or str(Path(tmp) / "fe")
        import_development()
        from contact.cli import main as ltca

        clock = CallClock().install()
        c0 = _cpu()
        try:
            rc = ltca(["synthesize", args.basic, "-o", str(Path(tmp) / "case.toml"), "-q"])
        finally:
            clock.remove()
        total = _cpu() - c0
    if not args.quiet:
        print(f"\n{'CPU [s]':>7}  kind | torques [N m] | flank | step")
        for seconds, kind, torques, flank, step in clock.calls:
            if torques:
                print(f"{seconds:7.2f}  {kind} | {'/'.join(f'{t:g}' for t in torques)} | "
                      f"{flank} | {step}")
    by_kind: dict[str, list[float]] = defaultdict(list)
    for seconds, kind, *_ in clock.calls:
        by_kind[kind].append(seconds)
    print(f"\n{Path(args.basic).stem}: synthesize {total:.1f} s CPU (imports excluded)"
          + ("" if rc == 0 else f", exit code {rc}"))
    print("| kind | calls | CPU [s] | share |\n|---|---|---|---|")
    for kind, times in sorted(by_kind.items(), key=lambda kv: -sum(kv[1])):
        print(f"| {kind} | {len(times)} | {sum(times):.2f} | {sum(times) / total:.0%} |")
    rest = total - sum(sum(t) for t in by_kind.values())
    print(f"| the rest (ratings, steps' bookkeeping, writing) | | {rest:.2f} | "
          f"{rest / total:.0%} |")
    return int(rc or 0)


if __name__ == "__main__":
    sys.exit(main())
