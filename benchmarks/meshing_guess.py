"""Envelope solver with and without a starting guess (geometry.machine.meshing.solve_envelope).

For every flank of the example cases the 41 × 21 projection-plane grid is solved once
without a guess; then targets moved by (0.05, 0.03) mm are solved without a guess and
from the first solution (``guess=``). Prints both times (best of N, one core), the ratio
and the largest position difference. Run: ``python benchmarks/meshing_guess.py``.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

from geometry.case import load_case  # noqa: E402
from geometry.machine.flank import projection_grid  # noqa: E402
from geometry.machine.meshing import solve_envelope  # noqa: E402

ROOT = _HERE.parent
CASES = ("spiral_bevel_iso23509_s1", "hypoid_iso23509_s2", "kolivand2009_fm_11x41")


def best_of(tool, z, p, kw, repeat=5):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = solve_envelope(tool.blade, tool.machine, z, p, **kw)
        times.append(time.perf_counter() - t)
    return min(times), out


def main() -> int:
    print(f"{'case':28s} {'member':7s} {'flank':8s} {'no guess [ms]':>13s} "
          f"{'guess [ms]':>10s} {'ratio':>6s} {'max |dr| [mm]':>13s}")
    for name in CASES:
        path = ROOT / "cases" / f"{name}.toml"
        if not path.exists():
            continue
        case = load_case(path)
        for member in ("pinion", "gear"):
            mem = case.member(member)
            bl = mem.blank
            g = projection_grid(bl, 41, 21, (0.0, 1.0), (0.0, 1.0))
            kw = dict(length_scale=bl.outer_cone_distance,
                      depth=bl.outer_addendum + bl.outer_dedendum)
            for flank in ("concave", "convex"):
                tool = mem.flank(flank)
                old = solve_envelope(tool.blade, tool.machine, g.axial, g.radius, **kw)
                z, p = g.axial + 0.05, g.radius + 0.03
                t0, a = best_of(tool, z, p, kw)
                t1, b = best_of(tool, z, p, {**kw, "guess": old})
                ok = (a.reason == 0) & (b.reason == 0)
                d = float(np.max(np.abs(a.position[ok] - b.position[ok]))) if ok.any() else 0.0
                print(f"{name:28s} {member:7s} {flank:8s} {t0 * 1e3:13.1f} {t1 * 1e3:10.1f} "
                      f"{t0 / t1:6.2f} {d:13.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
