"""Where each member's FE root stress peaks, and FE peak / ISO σ_F (issue 62 item 1).

Prints two tables, measured in one run of the default analysis of a case (its torques,
root stress and ISO 10300 rating on; the FE coefficients from the cache, built on a first
run):

* per torque and member: ``root_stress_max`` [MPa], the face station u of the peak, the
  rating's ``sigma_F`` [MPa], their ratio, and the share of the load on the heel tenth of
  the face (segments at gear u ≥ 0.9);
* per member: the largest tensile root stress of the loaded tooth per unit load [MPa/N],
  a unit load at mid-depth (v 0.525) at the toe end, at the least-stressing face station
  and at the heel end — where each member's weak end is (docs/fe.md, "Root and slot
  bottom").

Run: ``python benchmarks/fe_root_peak.py [--case NAME]``; ~1 min on a warm FE cache,
~5 min cold (the builds of both members) on the 2-core machine.
"""

from __future__ import annotations

import argparse

import numpy as np

from contact.catalogue import DEFAULT_CASE, resolve_case
from contact.compliance.fe import influence_coefficients
from contact.pipeline import run_analysis


def unit_load_peaks(coef, load_v: float = 0.525) -> np.ndarray:
    """(load_u,) [MPa/N]: the loaded tooth's largest tensile root stress per unit load at
    each lengthwise place of the load row nearest ``load_v`` [1]."""
    fm = coef["fillet_max_principal"].sel(tooth=0).sel(load_v=load_v, method="nearest")
    return fm.where(coef["fillet_in_root"].sel(tooth=0) > 0).max(
        ("side", "station", "arc")).values


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", default=DEFAULT_CASE.removesuffix(".toml"))
    args = parser.parse_args(argv)
    tree = run_analysis(args.case)
    lt, rating = tree["/ltca"].to_dataset(), tree["/rating"].to_dataset()
    su = lt["segment_u"].values
    print(f"{args.case}: FE root stress against ISO 10300 sigma_F")
    print(f"{'T [N m]':>8} {'member':>7} {'FE [MPa]':>9} {'at u':>5} {'sigma_F':>8} "
          f"{'FE/sF':>6} {'heel 10 %':>9}")
    for it, torque in enumerate(lt["torque"].values):
        force = lt["force"].isel(torque=it).values
        ok = np.isfinite(force) & np.isfinite(su)
        heel = force[ok & (su >= 0.9)].sum() / force[ok].sum()
        for im, member in enumerate(("pinion", "gear")):
            fe = float(lt["root_stress_max"].isel(torque=it, member=im))
            along = lt["root_stress"].isel(torque=it, member=im).max(("roll", "tooth")).values
            u = float(lt["fillet_u"].isel(member=im).values[int(np.nanargmax(along))])
            sf = float(rating["sigma_F"].isel(torque=it, member=im))
            print(f"{torque:8.0f} {member:>7} {fe:9.1f} {u:5.2f} {sf:8.1f} {fe / sf:6.3f} "
                  f"{heel:9.3f}")
    case = resolve_case(args.case)
    print("\nroot stress per unit load at mid-depth [MPa/N]")
    print(f"{'member':>7} {'toe end':>8} {'least':>8} {'at u':>5} {'heel end':>8}")
    for member in ("pinion", "gear"):
        coef = influence_coefficients(case, member, progress=False)
        peaks = unit_load_peaks(coef)
        k = int(np.argmin(peaks))
        print(f"{member:>7} {peaks[0]:8.3f} {peaks[k]:8.3f} "
              f"{float(coef['load_u'].values[k]):5.2f} {peaks[-1]:8.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
