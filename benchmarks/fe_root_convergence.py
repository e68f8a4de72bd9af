"""Peak root stress of cheaper FE models against the default one (issue 75 item 1).

    python benchmarks/fe_root_convergence.py [CASE.toml ...] [--cache DIR]
                                             [--variants default mesh/1.5 ...]

For each case (default: the bundled default case) the LTCA runs once at ``ltca run``'s
sampling (:class:`contact.ltca.LTCAOptions` defaults) at the case's ``[operating]``
torques (a synthesised case's light and design torque; ``--flank coast``: the coast
flank at the torques ``ltca run --flank coast`` takes); the same segment forces are then
superposed on the influence coefficients of each FE model variant
(:func:`contact.ltca.root_stress`), so the only difference between the rows is the FE
model. Printed per variant: the unknowns and unit loads of each member's model, the CPU
of building both (this process and its solver worker, ``getrusage``; an empty cache of
the variant's own), and the peak root stress ``root_stress_max`` [MPa] per member and
torque with its relative difference to the default model's. S_F,FE = σ_FP/(σ_F·K_A·K_v)
is inverse in σ_F, so its relative difference is the same (of the opposite sign).

Variants (``--variants``; the FE options of each are printed):

* ``default`` — :class:`contact.compliance.fe.FEOptions` as ``ltca run`` builds it;
* ``mesh/1.5`` — every division / 1.5 (:meth:`FEOptions.refined` with 1/1.5);
* ``loads11x6`` — the default mesh, unit loads on an 11 × 6 grid (66 instead of 231);
* ``loads11x6+mesh/1.5`` — both;
* ``loads15x8``, ``loads15x8+mesh/1.5``, ``face8+loads11x6`` (8 along the face),
  ``mesh/1.5,root+loads11x6`` (the fillet and half-slot divisions kept) — the other
  combinations measured;
* ``loads31x16`` — the default mesh under a finer load grid (496 unit loads): the load
  grid's own convergence;
* ``ci`` — the CI tests' coarse model (tests/test_root_stress.py ``COARSE``).
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import resource
import sys
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def variants() -> dict:
    from contact.compliance.fe import FEOptions

    d = FEOptions()
    return {
        "default": d,
        "mesh/1.5": d.refined(1 / 1.5),
        "loads11x6": dataclasses.replace(d, load_nu=11, load_nv=6),
        "loads11x6+mesh/1.5": dataclasses.replace(d.refined(1 / 1.5), load_nu=11, load_nv=6),
        "loads15x8": dataclasses.replace(d, load_nu=15, load_nv=8),
        "loads15x8+mesh/1.5": dataclasses.replace(d.refined(1 / 1.5), load_nu=15, load_nv=8),
        "face8+loads11x6": dataclasses.replace(d, face_divisions=8, load_nu=11, load_nv=6),
        "mesh/1.5,root+loads11x6": dataclasses.replace(
            d.refined(1 / 1.5), fillet_divisions=d.fillet_divisions,
            slot_divisions=d.slot_divisions, load_nu=11, load_nv=6),
        "loads31x16": dataclasses.replace(d, load_nu=31, load_nv=16),
        "ci": FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3,
                        slot_divisions=1, rim_divisions=2, fillet_divisions=2, load_nu=5,
                        load_nv=4),
    }


def cpu() -> float:
    s, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(
        resource.RUSAGE_CHILDREN)
    return s.ru_utime + s.ru_stime + c.ru_utime + c.ru_stime


def main(argv: list[str] | None = None) -> None:
    from contact.catalogue import bundled_case_path
    from contact.ltca import LTCAOptions, loaded_tca
    from contact.ltca.root_stress import root_stress
    from contact.pipeline import flank_torques
    from contact.utca.easeoff import ease_off
    from geometry.case import load_case
    from geometry.core.blas import blas_threads

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("cases", nargs="*", type=Path)
    ap.add_argument("--cache", type=Path, default=Path("/tmp/fe_root_convergence"))
    ap.add_argument("--flank", default="drive", choices=("drive", "coast"))
    ap.add_argument("--variants", nargs="+", default=["default", "mesh/1.5", "loads11x6",
                                                      "loads11x6+mesh/1.5"])
    args = ap.parse_args(argv)
    table = variants()
    paths = args.cases or [bundled_case_path()]
    with blas_threads(1):
        for path in paths:
            case = load_case(path)
            torques = list(flank_torques(case, args.flank)[0])
            eo = ease_off(case, flank=args.flank)
            lt = loaded_tca(case, torques, easeoff=eo, options=LTCAOptions())
            print(f"\n{case.name} ({Path(path).name}), {args.flank} flank: torques "
                  f"{torques} N·m", flush=True)
            ref = None
            for name in args.variants:
                opt = table[name]
                c0, t0 = cpu(), time.perf_counter()
                rs = root_stress(case, eo, lt, opt, cache_dir=args.cache / name)
                c1 = cpu() - c0
                peak = rs["root_stress_max"].transpose("torque", "member")
                vals = peak.values
                if ref is None and name == "default":
                    ref = vals
                rel = "" if ref is None else " ".join(
                    f"{x:+.2%}" for x in (vals / ref - 1.0).ravel())
                print(f"  {name:20s} CPU {c1:6.1f} s (wall {time.perf_counter() - t0:5.1f}) "
                      f"peak [MPa] (torque x {list(peak['member'].values)}): "
                      f"{' '.join(f'{x:.1f}' for x in vals.ravel())}  vs default: {rel}",
                      flush=True)
                from contact.compliance.fe import influence_coefficients
                for member in ("pinion", "gear"):
                    ds = influence_coefficients(case, member, eo.pinion_flank
                                                if member == "pinion" else eo.gear_flank,
                                                opt, cache_dir=args.cache / name,
                                                progress=False)
                    print(f"    {member}: {ds.attrs['cost_n_unknowns']} unknowns, "
                          f"{ds.attrs['cost_n_elements']} elements, "
                          f"{ds.attrs['cost_n_loads']} loads, build "
                          f"{ds.attrs['cost_time_total_s']:.1f} s wall "
                          f"(solves {ds.attrs['cost_time_solves_s']:.1f})", flush=True)
            print(f"  options: {{{', '.join(f'{n}: {table[n]}' for n in args.variants)}}}")


if __name__ == "__main__":
    main()
