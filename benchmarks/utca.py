"""Unloaded TCA benchmark: ease-off method vs the conventional TCA (seed Eq. 2.14).

The seed's claim (§2.3.2): the ease-off method "requires significantly less computational
effort" than the five-equation contact search. Measured in one run on one core:

1. ``unloaded_tca`` — ease-off and roll-angle surface on the 41 × 21 gear grid, the
   transitions M1, M2 and 30 roll positions × 3 tooth pairs of one mesh cycle (contact
   curves, UTE, pattern); target ≤ 0.2 s; with its two stages timed separately;
2. ``conventional_tca`` (geometry/pair/conventional_tca.py) at the same 90 (roll, pair)
   positions — the reference pair's TE at r − k·pitch —, started from the mean contact;
3. the ratio, and the agreement of the two methods' transmission errors at the positions
   where the conventional TCA converged on the flanks (up to a constant), for the seed's
   first-order UTE and the second-order one.

Case: ``cases/kolivand2009_fm_11x41.toml`` if present, else the hypoid example with
concave-edged circular pinion blades (R_pr = −400 mm: crowned; the example's own
convex-edged blades hollow the profile). Run: ``python benchmarks/utca.py [--repeat N]``.
BLAS is limited to one thread unless ``OPENBLAS_NUM_THREADS``/``OMP_NUM_THREADS`` are set.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

from contact.utca import (  # noqa: E402
    EaseOffFields,
    contact_curves,
    transitions,
    unloaded_tca,
)
from contact.utca.easeoff import ease_off  # noqa: E402
from geometry.case import load_case  # noqa: E402
from geometry.pair.conventional_tca import conventional_tca, mean_contact  # noqa: E402

ROOT = _HERE.parent


def bench_case():
    default = ROOT / "cases" / "kolivand2009_fm_11x41.toml"
    if default.exists():
        return load_case(default), default.name
    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")

    def concave_edge(tool):
        return dataclasses.replace(tool, blade=dataclasses.replace(tool.blade,
                                                                   profile_radius=-400.0))

    pinion = dataclasses.replace(case.pinion, concave=concave_edge(case.pinion.concave),
                                 convex=concave_edge(case.pinion.convex))
    return dataclasses.replace(case, pinion=pinion), "hypoid_iso23509_s2 with R_pr = -400 mm"


def best_of(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, help="repeats (the best is reported)")
    args = ap.parse_args(argv)
    case, label = bench_case()
    n_roll, pairs = 30, np.array([-1, 0, 1])
    print(f"case: {label}; grid 41 x 21, {n_roll} rolls x {len(pairs)} pairs, one core\n")

    t_total, (_, ds) = best_of(lambda: unloaded_tca(case, rolls_per_cycle=n_roll), args.repeat)
    t_eo, eo = best_of(lambda: ease_off(case), args.repeat)
    fields = EaseOffFields(eo)
    q = ds["roll"].values[:, None] - pairs[None, :] * eo.pitch
    t_tr, _ = best_of(lambda: transitions(eo, fields=fields), args.repeat)
    t_cc, cc2 = best_of(lambda: contact_curves(eo, q, fields=fields), args.repeat)
    cc1 = contact_curves(eo, q, fields=fields, method="seed")

    mc = mean_contact(case)
    phi = eo.roll_zero + eo.drive_sense * q.ravel()
    roll = mc.pinion_sense * (phi - mc.pinion_rotation)
    t_conv, res = best_of(lambda: conventional_tca(case, roll, initial=mc),
                          max(1, args.repeat - 2))
    ok = res.converged & res.on_flank & np.isfinite(cc2.ute.ravel())

    def spread(ute):
        d = (res.transmission_error - ute.ravel())[ok]
        return np.abs(d - d.mean()).max() * 1e6 if d.size else float("nan")

    rows = [
        ("ease-off + Q surfaces (41 x 21)", t_eo),
        ("transitions M1, M2", t_tr),
        ("contact curves, 30 rolls x 3 pairs", t_cc),
        ("unloaded_tca total (target <= 0.2 s)", t_total),
        ("conventional_tca, same 90 positions", t_conv),
    ]
    print(f"{'stage':42s} {'time [s]':>9s}")
    for name, t in rows:
        print(f"{name:42s} {t:9.3f}")
    print(f"\nspeed ratio conventional / ease-off UTCA: {t_conv / t_total:.1f}x "
          f"(per position: {t_conv / q.size * 1e3:.1f} ms vs {t_total / q.size * 1e3:.2f} ms)")
    print(f"\nagreement with the conventional TCA at {int(ok.sum())} of {q.size} positions "
          "(converged, contact on both flanks), TE up to a constant:")
    print(f"  {'method':14s} {'max |dTE| [urad]':>17s}")
    for name, c in (("seed", cc1), ("second_order", cc2)):
        print(f"  {name:14s} {spread(c.ute):17.3f}")
    print(f"\nUTE peak-to-peak {float(ds['peak_to_peak_transmission_error']):.2f} urad, "
          f"transitions M1, M2 = {ds['transition_roll'].values} rad")
    return 0


if __name__ == "__main__":
    sys.exit(main())
