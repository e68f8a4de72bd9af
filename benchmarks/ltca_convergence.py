"""LTCA convergence study: LTE and peak pressure as the segments and roll positions double.

    python benchmarks/ltca_convergence.py [CASE] [--torque 50 250 500] [--aligned]

For the case (default: the bundled 11×41 pair at the seed's Table 3.1 misalignment) it
runs the LTCA over one mesh cycle with 12/24/48/96 segments per contact line (20 roll
positions) and with 10/20/40 roll positions (24 segments), and prints for each doubling
the largest change of the LTE at the shared roll positions, of the cycle's mean and
peak-to-peak LTE [µrad] and of the peak pressure [%]. The issue's bounds for a doubling
from the default discretisation (24 segments, 20 roll positions per cycle): < 0.5 µrad
and < 2 %. The unit tests check the same bounds on two doublings
(tests/test_ltca_discretisation.py); this script shows the whole sequence.
"""

from __future__ import annotations

import argparse
import dataclasses
import itertools

import numpy as np
from tabulate import tabulate

from contact.catalogue import SEED_TABLE_3_1, resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from contact.utca.easeoff import ease_off
from geometry.pair.assembly import Misalignment


def _run(case, eo, torques, rolls, segments):
    opts = LTCAOptions(cycles=1, rolls_per_cycle=rolls, segments=segments)
    return loaded_tca(case, torques, options=opts, easeoff=eo)


def _rows(runs, label, shared_step):
    rows = []
    for (na, a), (nb, b) in itertools.pairwise(runs):
        step = shared_step(na, nb)
        te_a = a["transmission_error"].values
        te_b = b["transmission_error"].values[:, ::step]
        pa = a["pressure_max"].max(("roll", "pair", "segment")).values
        pb = b["pressure_max"].max(("roll", "pair", "segment")).values
        for it, torque in enumerate(a["torque"].values):
            rows.append((
                f"{label} {na} → {nb}", f"{torque:g}",
                float(np.max(np.abs(te_b[it] - te_a[it]))),
                float(abs(b["lte_mean"].values[it] - a["lte_mean"].values[it])),
                float(abs(b["lte_peak_to_peak"].values[it] - a["lte_peak_to_peak"].values[it])),
                100.0 * float(abs(pb[it] / pa[it] - 1.0)),
            ))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case", nargs="?", default=None)
    parser.add_argument("--torque", type=float, nargs="+", default=[50.0, 250.0, 500.0])
    parser.add_argument("--aligned", action="store_true",
                        help="no misalignment (default: the seed's Table 3.1 for the "
                             "bundled case, the case's own otherwise)")
    args = parser.parse_args()
    case = resolve_case(args.case)
    if args.aligned:
        mis = Misalignment()
    elif args.case is None:
        mis = SEED_TABLE_3_1["misalignment"]
    else:
        mis = case.misalignment
    case = dataclasses.replace(case, misalignment=mis)
    eo = ease_off(case)
    seg_runs = [(s, _run(case, eo, args.torque, 20, s)) for s in (12, 24, 48, 96)]
    roll_runs = [(r, _run(case, eo, args.torque, r, 24)) for r in (10, 20, 40)]
    rows = _rows(seg_runs, "segments", lambda na, nb: 1)
    rows += _rows(roll_runs, "rolls", lambda na, nb: nb // na)
    print(f"case {case.name}, misalignment {mis}")
    print(tabulate(rows, headers=["doubling", "T_p [N m]", "max ΔLTE [urad]",
                                  "Δ mean [urad]", "Δ p-p [urad]", "Δ p_max [%]"],
                   tablefmt="github", floatfmt=".3f"))
    print("bounds (from the default 24 segments, 20 rolls): ΔLTE < 0.5 urad, Δp_max < 2 %")


if __name__ == "__main__":
    main()
