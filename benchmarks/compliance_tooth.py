"""Shell compliance of GENERATED teeth against 3-D finite elements of the same teeth.

Prints three tables, all measured in one run:

1. the fitted shell of seed Eq. 3.1 per case and member (thicknesses, heights,
   tooth length, shell radius) with the misfit of the linear thickness function and
   the whole depth of the blank at the heel (ISO 23509 Annex F data of the case);
2. the FE study: for both example cases, both members, both flanks and two load
   places, the tip-line deflection of the shell model (5 × 9 and 6 × 21 modes)
   against 3-D FE (scikit-fem, triquadratic hexahedra) of the generated tooth under
   the same unit patch load — peak ratio shell/FE and the largest difference along
   the tip relative to the FE peak;
3. the LTCA workload: ``mesh_compliance`` for two tooth pairs of the conjugate
   hypoid pair, first call (measures both teeth, factorises both shells) and the
   median of later calls (one roll position).

Run: ``python benchmarks/compliance_tooth.py [--quick]`` (``--quick``: hypoid only).
The FE model and the patch-load shell read-out are those of
``tests/test_compliance_tooth.py`` (imported from there).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]
sys.path.insert(0, str(_HERE.parent / "tests"))

import test_compliance_tooth as tct  # noqa: E402

from contact.compliance.mesh import mesh_compliance  # noqa: E402


def table_dimensions(cases):
    print("\n1. Fitted shell (seed Eq. 3.1) of the generated teeth [mm]")
    print(f"{'case':>26} {'member':>7} {'t_toe':>6} {'t_heel':>6} {'t_tip':>6} {'h_toe':>6} "
          f"{'h_heel':>6} {'ISO h_e':>7} {'length':>7} {'R':>6} {'fit err t':>9} "
          f"{'build [s]':>9}")
    for name in cases:
        for member in ("pinion", "gear"):
            d = tct._tooth(name, member)
            t = d.tooth
            bl = tct._case(name).member(member).blank
            print(f"{name:>26} {member:>7} {t.thickness_toe_root:6.3f} "
                  f"{t.thickness_heel_root:6.3f} {t.thickness_tip:6.3f} {t.height_toe:6.3f} "
                  f"{t.height_heel:6.3f} {bl.outer_addendum + bl.outer_dedendum:7.3f} "
                  f"{t.face_width:7.2f} {t.radius:6.2f} {d.thickness_fit_error:9.3f} "
                  f"{d.build_time:9.3f}")


def table_fe(cases):
    print("\n2. Shell vs FE of the generated tooth: unit patch load, tip-line deflection "
          "(ratio = shell peak / FE peak, err = max|shell − FE| / FE peak)")
    print(f"{'case':>26} {'member':>7} {'flank':>8} {'load (u, v)':>12} {'FE peak':>10} "
          f"{'FE [s]':>7} {'5×9 ratio':>9} {'err':>6} {'6×21 ratio':>10} {'err':>6}")
    for name in cases:
        case = tct._case(name)
        for member in ("pinion", "gear"):
            data = tct._tooth(name, member)
            for side in (1, -1):
                for load in ((0.5, 0.5), (0.25, 0.75)):
                    t0 = time.perf_counter()
                    tips, w_fe = tct.fe_generated_tooth(case, member, data.concave_shift, load,
                                                        side)
                    t_fe = time.perf_counter() - t0
                    peak = np.max(np.abs(w_fe))
                    row = []
                    for modes in ((5, 9), (6, 21)):
                        model = data.shell_model("seed", *modes)
                        w_sh = tct.shell_tip_deflection(case, member, data, tips, load, side,
                                                        model=model)
                        row += [np.max(np.abs(w_sh)) / peak, np.max(np.abs(w_sh - w_fe)) / peak]
                    flank = "convex" if side > 0 else "concave"
                    print(f"{name:>26} {member:>7} {flank:>8} {load!s:>12} {peak:10.3e} "
                          f"{t_fe:7.2f} {row[0]:9.3f} {row[1]:6.3f} {row[2]:10.3f} "
                          f"{row[3]:6.3f}")


def table_workload(repeats=5):
    print("\n3. LTCA workload: mesh_compliance, conjugate hypoid pair, two tooth pairs")
    case, seg, _ = tct._conjugate_segments()
    opts = dict(n_height=6, n_face=21, pinion_material=(206000.0, 0.3001))  # fresh memo
    t0 = time.perf_counter()
    mesh_compliance(case, seg, **opts)
    first = time.perf_counter() - t0
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        mesh_compliance(case, seg, **opts)
        times.append(time.perf_counter() - t0)
    print(f"{'segments':>9} {'first call [s]':>15} {'later calls, median [s]':>24}")
    print(f"{seg.size:9d} {first:15.3f} {float(np.median(times)):24.4f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="hypoid example only")
    args = ap.parse_args()
    cases = tct.CASES[:1] if args.quick else tct.CASES
    table_dimensions(cases)
    table_fe(cases)
    table_workload()


if __name__ == "__main__":
    main()
