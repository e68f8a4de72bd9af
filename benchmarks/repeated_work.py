"""Repeated work in ``ltca synthesize``: analyses and tip-plane placements asked for again
with the same inputs (issue 71's CPU of a new design; issue 75).

``ltca synthesize BASIC`` runs in this process with its defaults (the development on), with
two of its functions wrapped where they are looked up: every design analysis
(:func:`contact.optimize.development_evaluate.analyse_design`, the coarse search's, the
check's, the tolerance excursions' and the coast flank's) keyed by its inputs — both
members of the case, the torques, the misalignment, the LTCA options, the flank and the
kept teeth with the pinion's key — and every tip-plane placement of a synthesis (step 8,
:func:`geometry.synthesis.tip_plane.tip_plane_on_root_cone` as
:mod:`geometry.synthesis.case_synthesis` calls it) keyed by its blade, settings, blank and
hand. Printed: the calls and their CPU seconds (``time.process_time``: this process),
those repeated (a key seen before: work a memo could have kept) and the number of
distinct cases analysed. ``--calls FILE`` writes one line per call (kind, key, case key,
CPU s, flank, torques).

Measured (cpu71c, 2026-11-26; hypoid 10x37 at Σ 75° of tests/data/designs, empty FE
cache): 149 analyses (57.8 s; 99 distinct cases, the others the same case at other
torques or excursions) and 32 tip placements (21.8 s), none repeated
(docs/own_gear_set.md, "Re-measured on the merged tree of 2026-11-26").

Usage: ``python benchmarks/repeated_work.py BASIC.toml [-o CASE.toml] [--calls FILE]``.
One design takes 2–4 min of CPU; point ``HYPOID_LTCA_CACHE`` at an empty directory for a
new design's FE builds.
"""

from __future__ import annotations

import argparse
import collections
import hashlib
import sys
import tempfile
import time
from pathlib import Path


def _key(*parts: object) -> str:
    return hashlib.sha1(repr(parts).encode()).hexdigest()[:16]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("basic", help="basic design file (TOML)")
    parser.add_argument("-o", "--output", help="case file to write (default a temporary one)")
    parser.add_argument("--calls", help="write one line per wrapped call to this file")
    args = parser.parse_args(argv)

    import contact.optimize.development_evaluate as evaluation
    import geometry.synthesis.case_synthesis as case_synthesis
    from contact.cli import main as ltca

    calls: list[tuple[str, str, str, float, str, tuple[float, ...]]] = []
    analyse = evaluation.analyse_design
    place = case_synthesis.tip_plane_on_root_cone

    def analyse_design(case, torques, misalignment=None, options=evaluation.COARSE_LTCA,
                       teeth=None, pinion_key=(), flank="drive"):
        t0 = time.process_time()
        try:
            return analyse(case, torques, misalignment, options, teeth, pinion_key, flank)
        finally:
            ts = tuple(float(t) for t in torques)
            key = _key(repr(case.pinion), repr(case.gear), repr(case.misalignment),
                       repr(misalignment), ts, repr(options), flank,
                       pinion_key if teeth is not None else None, id(teeth))
            calls.append(("analyse", key, _key(repr(case.pinion), repr(case.gear)),
                          time.process_time() - t0, flank, ts))

    def tip_plane_on_root_cone(blade, settings, blank, hand, **kw):
        t0 = time.process_time()
        try:
            return place(blade, settings, blank, hand, **kw)
        finally:
            calls.append(("tip plane", _key(repr(blade), repr(settings), repr(blank), hand),
                          "", time.process_time() - t0, blade.side, ()))

    evaluation.analyse_design = analyse_design
    case_synthesis.tip_plane_on_root_cone = tip_plane_on_root_cone
    with tempfile.TemporaryDirectory() as tmp:
        out = args.output or str(Path(tmp) / "case.toml")
        rc = ltca(["synthesize", args.basic, "-o", out, "--no-progress"])
    seen: set[tuple[str, str]] = set()
    n, cpu = collections.Counter(), collections.Counter()
    n_rep, cpu_rep = collections.Counter(), collections.Counter()
    cases = set()
    for kind, key, case_key, seconds, _, _ in calls:
        n[kind] += 1
        cpu[kind] += seconds
        if (kind, key) in seen:
            n_rep[kind] += 1
            cpu_rep[kind] += seconds
        seen.add((kind, key))
        if case_key:
            cases.add(case_key)
    for kind in n:
        print(f"{kind}: {n[kind]} calls, {cpu[kind]:.1f} s CPU; repeated with the same "
              f"inputs {n_rep[kind]} ({cpu_rep[kind]:.1f} s)")
    print(f"distinct cases analysed: {len(cases)}")
    if args.calls:
        with open(args.calls, "w", encoding="utf-8") as f:
            for kind, key, case_key, seconds, flank, ts in calls:
                f.write(f"{kind}\t{key}\t{case_key}\t{seconds:.3f}\t{flank}\t{ts}\n")
    return int(rc or 0)


if __name__ == "__main__":
    sys.exit(main())
