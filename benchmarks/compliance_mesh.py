"""Micro-benchmark of ``mesh_compliance`` on the LTCA's own contact segments.

    python benchmarks/compliance_mesh.py [CASE] [--torque 250] [--repeats 5]
                                         [--save REF.npz] [--check REF.npz]

Runs the LTCA of the case once (default ``cases/kolivand2009_fm_11x41.toml``) and
records the :class:`contact.compliance.mesh.ContactSegments` it passes to
:func:`contact.compliance.mesh.mesh_compliance` at every roll position; then times
``mesh_compliance`` on them (median of ``--repeats`` calls per roll position, the
tooth models already built) and its parts: the projection of the segment midpoints
and ends onto both members' shells (:func:`contact.compliance.tooth.shell_coordinates`)
and the Ritz compliance of the shell blocks (:func:`contact.compliance.shell.compliance_matrix`).
Prints a table. ``--save`` stores the segments, matrices and asymmetries; ``--check``
recomputes the matrices on the stored segments and compares them with the stored ones
(largest entry difference relative to the largest entry; the requirement for a pure
speed change is 1e-10). BLAS is limited to one thread.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
from tabulate import tabulate  # noqa: E402

import contact.ltca as ltca_mod  # noqa: E402
import contact.ltca.pool as pool_mod  # noqa: E402
from contact.catalogue import resolve_case  # noqa: E402
from contact.compliance import mesh as mesh_mod  # noqa: E402
from contact.compliance import tooth as tooth_mod  # noqa: E402


def record_segments(case, torque: float):
    """The (segments, model) of every pool the LTCA assembles in one run (the LTCA maps
    them in batches with ``mesh_compliance_many``: each element is one roll's pool)."""
    calls = []
    original = pool_mod.mesh_compliance_many

    def recorder(case_, batch, **kw):
        calls.extend((segs, kw["model"]) for segs in batch)
        return original(case_, batch, **kw)

    pool_mod.mesh_compliance_many = recorder
    try:
        ltca_mod.loaded_tca(case, [torque])
    finally:
        pool_mod.mesh_compliance_many = original
    return calls


_FIELDS = ("midpoints", "ends", "normals", "length", "r_eq", "pair_index", "load",
           "pinion_rotation", "gear_rotation")


def segments_to(segs, k: int) -> dict:
    return {f"s{k}_{f}": np.asarray(getattr(segs, f)) for f in _FIELDS}


def segments_from(store, k: int):
    return mesh_mod.ContactSegments(**{f: store[f"s{k}_{f}"] for f in _FIELDS})


def timed(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case", nargs="?", default=None)
    parser.add_argument("--torque", type=float, default=250.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--save", default=None)
    parser.add_argument("--check", default=None)
    args = parser.parse_args()
    case = resolve_case(args.case)
    calls = record_segments(case, args.torque)
    if args.check:  # the stored segments: the check does not depend on the LTCA's geometry
        ref = np.load(args.check)
        calls = [(segments_from(ref, k), calls[0][1]) for k in range(int(ref["n_roll"]))]
    model = calls[0][1]
    sizes = np.array([s.size for s, _ in calls])

    # parts, summed over the roll positions (median of repeats per roll position)
    t_total = t_coord = t_ritz = 0.0
    mats, asyms = [], []
    for segs, mdl in calls:
        t_total += timed(lambda s=segs, m=mdl: mesh_mod.mesh_compliance(case, s, model=m),
                         args.repeats)
        c, info = mesh_mod.mesh_compliance(case, segs, model=mdl)
        mats.append(c)
        asyms.append(info["asymmetry"])
        t_p, t_g = mesh_mod.case_transforms(case, segs.pinion_rotation, segs.gear_rotation)
        ends_flat = np.concatenate([segs.ends[:, 0], segs.ends[:, 1]])
        members = [(mdl.member(name), tr, sign)
                   for name, tr, sign in (("pinion", t_p, 1.0), ("gear", t_g, -1.0))]

        def coords(s=segs, ef=ends_flat, mem=members):
            return [tooth_mod._shell_points(data, s.midpoints, sign * s.normals, tr,
                                            tooth_mod.END_TOLERANCE, extra=ef)
                    for data, tr, sign in mem]

        t_coord += timed(coords, args.repeats)
        pts = coords()
        blocks = list(info["blocks"].values())

        def ritz(p=pts, mem=members, m=mdl, b=blocks):
            for (data, _, _), (sp, ep) in zip(mem, p, strict=True):
                tooth_mod.shell_matrices(data, sp, ep, m.theory, m.n_height, m.n_face, b)

        t_ritz += timed(ritz, args.repeats)

    n_roll = len(calls)
    rows = [
        ("mesh_compliance (all parts)", t_total, 1e3 * t_total / n_roll),
        ("  shell_coordinates (midpoints + ends, both members)", t_coord,
         1e3 * t_coord / n_roll),
        ("  Ritz compliance of the shell blocks (both members)", t_ritz, 1e3 * t_ritz / n_roll),
        ("  rest (foundation, Weber, assembly)", t_total - t_coord - t_ritz,
         1e3 * (t_total - t_coord - t_ritz) / n_roll),
    ]
    print(f"case {case.name}, T_p = {args.torque:g} N m, {n_roll} roll positions, "
          f"{sizes.min()}-{sizes.max()} segments (mean {sizes.mean():.0f}), modes "
          f"{model.n_height} x {model.n_face}, median of {args.repeats} calls")
    print(tabulate(rows, headers=["part", "all rolls [s]", "per roll [ms]"],
                   tablefmt="github", floatfmt=".4f"))
    print("target: <= 5 ms per roll position for the whole LTCA step (one core)")

    if args.save:
        store = {f"c{k}": m for k, m in enumerate(mats)}
        for k, (segs, _) in enumerate(calls):
            store.update(segments_to(segs, k))
        np.savez(args.save, asym=np.array(asyms), n_roll=len(calls), **store)
        print(f"saved {len(mats)} matrices to {args.save}")
    if args.check:
        rel = max(float(np.max(np.abs(m - ref[f"c{k}"])) / np.max(np.abs(ref[f"c{k}"])))
                  for k, m in enumerate(mats))
        asym_ref = ref["asym"]
        d_asym = float(np.max(np.abs(np.array(asyms) - asym_ref) / np.maximum(asym_ref, 1e-300)))
        print(f"check against {args.check}: max relative difference of C {rel:.2e} "
              f"(required <= 1e-10); asymmetry reports differ by {d_asym:.2e} (relative); "
              f"max asymmetry {max(asyms):.2e} (reference {float(asym_ref.max()):.2e})")


if __name__ == "__main__":
    main()
