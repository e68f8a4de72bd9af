"""How much does a written case's LTE p-p rise at a finer sampling than ``ltca run``'s?
(issue 71, "LTE p-p ≤ 60 µrad at every torque": the development's margin below 60 µrad,
branch margin101.)

A case's flank is analysed (the LTCA alone: no efficiency, root stress or mesh interface)
at ``--torques`` evenly spaced torques from ``LIGHT`` to ``DESIGN`` at ``ltca run``'s
sampling (20 rolls a mesh cycle, 24 segments), at 40 rolls and at 48 segments; then at
each of ``--rolls`` (default 80 160) at the three torques about the largest p-p at 40
rolls. One JSON line per sampling: its label, rolls, segments, torques [N·m], LTE p-p
[µrad] and the CPU of this process [s] (the roll pool's workers not counted).

Usage: ``python benchmarks/lte_sampling.py CASE.toml drive|coast LIGHT DESIGN
[--torques 12] [--rolls 80 160]``. Measured: docs/synthesis.md, "The development's LTE
margin below 60 µrad" (about 1–3 min wall per case on 2 shared cores).
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

import contact
from contact.ltca import LTCAOptions


def lte_pp(case: str, flank: str, torques: list[float], rolls: int, segments: int
           ) -> tuple[list[float], float]:
    """The LTE p-p [µrad] of ``case``'s ``flank`` at ``torques`` [N·m] with ``rolls`` a
    mesh cycle and ``segments`` a contact curve, and the CPU it took [s]."""
    t0 = time.process_time()
    tree = contact.run_analysis(case, torques, flank=flank,
                                options=LTCAOptions(rolls_per_cycle=rolls, segments=segments),
                                steps=contact.AnalysisChain.analysis().without("efficiency"),
                                root_stress=False, mesh_interface=False)
    pp = np.asarray(tree["ltca"]["lte_peak_to_peak"].values, float)
    return [round(float(x), 3) for x in pp], round(time.process_time() - t0, 1)


def main() -> None:
    """Run the samplings and print one JSON line each."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("case")
    parser.add_argument("flank", choices=("drive", "coast"))
    parser.add_argument("light", type=float)
    parser.add_argument("design", type=float)
    parser.add_argument("--torques", type=int, default=12)
    parser.add_argument("--rolls", type=int, nargs="*", default=[80, 160])
    args = parser.parse_args()
    grid = [float(t) for t in np.linspace(args.light, args.design, args.torques)]
    found = {}
    for label, rolls, segments in (("run", 20, 24), ("rolls40", 40, 24),
                                   ("segments48", 20, 48)):
        lte, cpu = lte_pp(args.case, args.flank, grid, rolls, segments)
        found[label] = lte
        print(json.dumps({"label": label, "rolls": rolls, "segments": segments,
                          "torques": grid, "lte": lte, "cpu": cpu}), flush=True)
    k = int(np.argmax(found["rolls40"]))
    near = grid[max(0, k - 1): k + 2]
    for rolls in args.rolls:
        lte, cpu = lte_pp(args.case, args.flank, near, rolls, 24)
        print(json.dumps({"label": f"rolls{rolls}", "rolls": rolls, "segments": 24,
                          "torques": near, "lte": lte, "cpu": cpu}), flush=True)


if __name__ == "__main__":
    main()
