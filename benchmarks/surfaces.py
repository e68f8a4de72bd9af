"""Benchmark: tooth-surface generation of both flanks of both members on a 41×21 grid.

Run from the repository root::

    python benchmarks/surfaces.py [--repeat N]

Prints, per case and flank, the best-of-N wall time of :func:`geometry.machine.flank.flank_surface`
(equation of meshing + curvatures), the generated fraction of the grid and the largest
meshing residual, then the four-flank total against the 0.1 s target (one core), and the
face-hobbed pair (``tests/data/fh_iso23509_s2_crown.toml``, same blank data as the FM
hypoid) as a ratio to the face-milled hypoid measured in the same run (target ≤ 2×: the
indexing adds the θ-terms of the work rotation and a space-curve edge, not a second
solve). numpy is limited to one thread through the environment before it is imported.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from geometry.case import load_case  # noqa: E402
from geometry.machine.flank import flank_surface  # noqa: E402

CASES = ("cases/spiral_bevel_iso23509_s1.toml", "cases/hypoid_iso23509_s2.toml",
         "tests/data/fh_iso23509_s2_crown.toml")
TARGET = 0.1  # [s] four flanks, one core
FH_RATIO_TARGET = 2.0  # FH pair time / FM hypoid pair time


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="best of N runs (default 5)")
    parser.add_argument("--nu", type=int, default=41)
    parser.add_argument("--nv", type=int, default=21)
    args = parser.parse_args()
    print(f"grid {args.nu} x {args.nv}, best of {args.repeat}")
    print(f"{'case':<32}{'member':<8}{'flank':<9}{'time [ms]':>10}{'generated':>11}"
          f"{'max |f|':>10}")
    totals = {}
    for name in CASES:
        case = load_case(ROOT / name)
        total = 0.0
        for member in ("pinion", "gear"):
            for flank in ("concave", "convex"):
                best = np.inf
                for _ in range(args.repeat):
                    t0 = time.perf_counter()
                    fs = flank_surface(case, member, flank, nu=args.nu, nv=args.nv)
                    best = min(best, time.perf_counter() - t0)
                total += best
                res = np.nanmax(np.abs(fs.meshing_residual))
                print(f"{case.name:<32}{member:<8}{flank:<9}{1e3 * best:>10.1f}"
                      f"{fs.valid.mean():>10.1%}{res:>10.1e}")
        verdict = "meets" if total <= TARGET else "misses"
        print(f"{case.name:<32}{'all four flanks':<17}{1e3 * total:>10.1f} ms "
              f"({verdict} the {1e3 * TARGET:.0f} ms target)")
        totals[case.pair.method] = total
    ratio = totals["FH"] / totals["FM"]
    verdict = "meets" if ratio <= FH_RATIO_TARGET else "misses"
    print(f"face hobbing / face milling (last FM case), four flanks: {ratio:.2f}x "
          f"({verdict} the {FH_RATIO_TARGET:g}x target)")


if __name__ == "__main__":
    main()
