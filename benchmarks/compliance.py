"""Tooth compliance benchmark: shell Rayleigh–Ritz model vs 3-D finite elements.

Prints four tables, all measured in one run:

1. FE mesh study of the reference (scikit-fem, triquadratic hexahedra): the
   tip-line peak deflection as the mesh is refined;
2. the shell model's convergence like seed Fig. 3.4: modes (ICF × IFF) vs error
   against the finest FE vs time, for the three kinematic theories;
3. the LTCA workload: compliance matrices of both members for three tooth pairs ×
   60 contact segments (shell bending/shear + Sainsot base + Weber diagonal);
   target ≤ 0.5 s;
4. speed ratio shell / FE at ≤ 10 % tip-deflection error; target ≥ 100×.

Run: ``python benchmarks/compliance.py [--quick]``. BLAS is limited to one thread
unless ``OPENBLAS_NUM_THREADS``/``OMP_NUM_THREADS`` are set: the matrices are small
(≤ 1 000 unknowns) and a threaded BLAS on a shared 2-core machine is slower.
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

# benchmarks/ holds scripts named like the packages (geometry.py …): keep it off the
# path so that ``import geometry`` finds the package; tests/ holds the FE model.
_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]
sys.path.insert(0, str(_HERE.parent / "tests"))

from fe_tooth import shell_patch_tip_deflection, solve_fe_tooth  # noqa: E402

from contact.compliance import (  # noqa: E402
    THEORIES,
    ShellTooth,
    ToothFoundation,
    build_shell_model,
    compliance_matrix,
    flank_normals,
    foundation_matrix,
    load_angle_from_normals,
    load_line_height,
    weber_compliance,
)
from geometry.core.hertz import STEEL  # noqa: E402

E, NU = STEEL

# Typical automotive hypoid pair (the brief's ranges): gear and pinion teeth.
GEAR = ShellTooth.from_face_width(
    thickness_toe_root=8.0, thickness_heel_root=10.0, thickness_tip=2.75,
    height_toe=10.0, height_heel=12.0, face_width=33.0, radius=95.0,
    youngs_modulus=E, poisson_ratio=NU,
)
PINION = ShellTooth.from_face_width(
    thickness_toe_root=9.0, thickness_heel_root=10.5, thickness_tip=2.5,
    height_toe=10.5, height_heel=11.5, face_width=35.0, radius=110.0,
    youngs_modulus=E, poisson_ratio=NU,
)


def fe_mesh_study(meshes):
    print("\n1. FE reference (gear tooth, unit patch load on the convex flank at mid face/profile)")
    print(f"{'mesh (h×f×t)':>14} {'unknowns':>9} {'peak [nm/N]':>12} {'assemble [s]':>13} "
          f"{'solve [s]':>10}")
    results = []
    for mesh in meshes:
        r = solve_fe_tooth(GEAR, n_height=mesh[0], n_face=mesh[1], n_thick=mesh[2])
        results.append((mesh, r))
        print(f"{'×'.join(map(str, mesh)):>14} {r.n_dofs:9d} {r.deflection.max() * 1e6:12.4f} "
              f"{r.assemble_time:13.2f} {r.solve_time:10.2f}")
    return results[-1][1]


def shell_study(fe, modes):
    print("\n2. Shell model vs finest FE (seed Fig. 3.4): error = max|shell − FE| / FE peak")
    print(f"{'theory':>13} {'ICF':>4} {'IFF':>4} {'unknowns':>9} {'error %':>8} "
          f"{'peak ratio':>11} {'time [s]':>9}")
    rows = []
    for theory in THEORIES:
        for m, n in modes:
            t0 = time.perf_counter()
            model = build_shell_model(GEAR, m, n, theory=theory)
            d = shell_patch_tip_deflection(model, fe.theta)
            el = time.perf_counter() - t0
            err = np.max(np.abs(d - fe.deflection)) / np.max(fe.deflection)
            rows.append((theory, m, n, err, el))
            print(f"{theory:>13} {m:4d} {n:4d} {model.n_dof:9d} {100 * err:8.2f} "
                  f"{d.max() / fe.deflection.max():11.3f} {el:9.4f}")
    return rows


def contact_lines(tooth: ShellTooth, n_pairs: int, n_seg: int):
    """Three diagonal contact lines (normalised coords) split into n_seg segments."""
    lines = []
    for k in range(n_pairs):
        p0 = np.array([0.15 + 0.25 * k, 0.02])
        p1 = np.array([0.35 + 0.25 * k, 0.98])
        s = np.linspace(0.0, 1.0, n_seg + 1)
        pts = p0 + s[:, None] * (p1 - p0)
        th = pts[:, 1] * tooth.subtended_angle
        shell = np.column_stack([pts[:, 0] * tooth.height(th), th])
        lines.append(np.stack([shell[:-1], shell[1:]], axis=1))
    return lines


def ltca_workload(theory, m, n, n_pairs=3, n_seg=60, repeats=5):
    times = {"shell build": [], "shell matrices": [], "base + Weber": [], "total": []}
    for _ in range(repeats):
        t_tot = time.perf_counter()
        mats = []
        t_build = t_mat = t_rest = 0.0
        for tooth, side in ((PINION, -1.0), (GEAR, 1.0)):
            t0 = time.perf_counter()
            model = build_shell_model(tooth, m, n, theory=theory)
            t_build += time.perf_counter() - t0
            fnd = ToothFoundation(root_radius=80.0, inner_radius=35.0, root_half_angle=0.07,
                                  face_width=tooth.face_width, youngs_modulus=E)
            for seg in contact_lines(tooth, n_pairs, n_seg):
                t0 = time.perf_counter()
                centres = seg.mean(axis=1)
                nrm = flank_normals(tooth, centres, side)
                c = compliance_matrix(model, seg, nrm).matrix
                t_mat += time.perf_counter() - t0
                t0 = time.perf_counter()
                alpha = load_angle_from_normals(nrm)
                u_f = load_line_height(centres[:, 0], tooth.thickness(*centres.T), alpha)
                c = c + foundation_matrix(fnd, u_f, alpha)
                mats.append(c)
                t_rest += time.perf_counter() - t0
        t0 = time.perf_counter()
        for k in range(n_pairs):  # pair matrices: pinion + gear + Weber diagonal
            seg_len = np.full(n_seg, 0.6)
            weber = weber_compliance(np.full(n_seg, 50.0), seg_len, 4.0, 4.0, e1=E, nu1=NU,
                                     e2=E, nu2=NU, r_eq=15.0)
            _ = mats[k] + mats[n_pairs + k] + np.diag(weber)
        t_rest += time.perf_counter() - t0
        times["shell build"].append(t_build)
        times["shell matrices"].append(t_mat)
        times["base + Weber"].append(t_rest)
        times["total"].append(time.perf_counter() - t_tot)
    return {k: float(np.median(v)) for k, v in times.items()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller FE meshes")
    args = ap.parse_args()
    meshes = [(4, 12, 2), (6, 16, 2)] if args.quick else [
        (4, 12, 2), (6, 16, 2), (8, 24, 2), (10, 32, 2), (10, 32, 4)]
    fe_last = fe_mesh_study(meshes)  # the finest mesh is the reference
    fe_ref_time = fe_last.total_time  # mesh + assembly + solve of that one load case

    modes = [(3, 5), (5, 3), (5, 5), (5, 9), (5, 15), (8, 15), (10, 21)]
    rows = shell_study(fe_last, modes)

    print("\n3. LTCA workload: both members, 3 tooth pairs × 60 segments, median of 5 runs")
    print(f"{'theory':>13} {'ICF×IFF':>8} {'build [s]':>10} {'matrices [s]':>13} "
          f"{'base+Weber [s]':>15} {'total [s]':>10} {'≤ 0.5 s':>8}")
    for theory, m, n in (("seed", 5, 9), ("seed", 5, 15), ("mindlin", 5, 9),
                         ("higher-order", 5, 9), ("higher-order", 5, 15)):
        t = ltca_workload(theory, m, n)
        verdict = "yes" if t["total"] <= 0.5 else "NO"
        print(f"{theory:>13} {f'{m}×{n}':>8} {t['shell build']:10.4f} {t['shell matrices']:13.4f} "
              f"{t['base + Weber']:15.4f} {t['total']:10.4f} {verdict:>8}")

    print(f"\n4. Speed vs FE (reference FE solve {fe_ref_time:.2f} s, "
          f"{fe_last.n_dofs} unknowns, one load case)")
    print(f"{'theory':>13} {'ICF×IFF':>8} {'error %':>8} {'shell [s]':>10} {'FE/shell':>9} "
          f"{'≥ 100× at ≤ 10 %':>17}")
    for theory in THEORIES:
        ok = [r for r in rows if r[0] == theory and r[3] <= 0.10]
        if not ok:
            print(f"{theory:>13} no mode set within 10 %")
            continue
        best = min(ok, key=lambda r: r[4])
        ratio = fe_ref_time / best[4]
        print(f"{theory:>13} {f'{best[1]}×{best[2]}':>8} {100 * best[3]:8.2f} {best[4]:10.4f} "
              f"{ratio:9.0f} {'yes' if ratio >= 100 else 'NO':>17}")


if __name__ == "__main__":
    main()
