"""The LTE peak-to-peak against torque, and what shapes it (issue 37, item 4).

    python benchmarks/lte_trend.py [CASE ...] [--torque 50 100 ...] [--rolls-per-cycle 20]

The seed's Table 3.1 (Fig. 3.6) LTE peak-to-peak of its 11×41 pair rises with torque,
12.8 / 15.9 / 21.9 µrad at 50 / 250 / 500 N·m; the reference design's is 16.1 / 22.6 /
22.4 µrad at ``ltca run``'s 20 roll positions per cycle. This script runs controlled
loaded analyses (:func:`contact.pipeline.run_analysis`, the case's own misalignment) of
each case over a torque sweep in three edge models — the default (edges on, their
pressure bounded by the shakedown limit), elastic edges (``edge_pressure_limit=None``)
and no edges (``edge_contact=False``) — and prints per torque:

* the LTE mean and peak-to-peak, its first mesh harmonic's amplitude, the LTE's maximum
  and minimum [µrad] with the mesh cycle fraction where they occur,
* the loaded contact curves (pairs with a loaded segment) per roll: the mean over the
  cycle, and at the LTE's maximum and minimum rolls (the contact ratio under load),
* the edge load share and the share of the torque on segments at their plastic limit.

The answer is in the README's side-by-side ("LTE against torque"). The unloaded TE
(``/ltca/unloaded_transmission_error``) is printed once per case: where the single- and
two-pair rolls sit.
"""

from __future__ import annotations

import argparse

import numpy as np
from tabulate import tabulate

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions
from contact.ltca.summary import edge_load_share
from contact.pipeline import run_analysis

#: edge models compared: label → LTCAOptions fields
EDGE_MODELS = {
    "edges, shakedown limit (default)": {},
    "edges, elastic": {"edge_pressure_limit": None},
    "no edges": {"edge_contact": False},
}
#: seed Table 3.1 LTE peak-to-peak [µrad] at 50 / 250 / 500 N·m
SEED_TABLE_3_1_PP = {50.0: 12.8, 250.0: 15.9, 500.0: 21.9}


def trend_rows(ltca) -> list[list]:
    """One table row per torque of an ``/ltca`` dataset (module docstring)."""
    te = ltca["transmission_error"].values                      # (torque, roll) [µrad]
    first = ltca["lte_harmonics"].sel(harmonic=1).values        # (torque,) [µrad]
    cycle = ltca["mesh_cycle"].values
    loaded = (ltca["force"] > 0.0).any("segment").sum("pair").values   # (torque, roll)
    edge = np.atleast_1d(edge_load_share(ltca))
    plastic = ltca["plastic_load_share"]
    plastic = plastic.max([d for d in plastic.dims if d != "torque"]).values \
        if plastic.ndim > 1 else np.atleast_1d(plastic.values)
    rows = []
    for k, torque in enumerate(ltca["torque"].values):
        i_max, i_min = int(np.argmax(te[k])), int(np.argmin(te[k]))
        rows.append([float(torque), float(te[k].mean()), float(np.ptp(te[k])),
                     SEED_TABLE_3_1_PP.get(float(torque), ""), float(first[k]),
                     f"{te[k, i_max]:.1f} @ {cycle[i_max] % 1:.2f}",
                     f"{te[k, i_min]:.1f} @ {cycle[i_min] % 1:.2f}",
                     float(loaded[k].mean()), int(loaded[k, i_max]), int(loaded[k, i_min]),
                     100.0 * float(edge[k]), 100.0 * float(plastic[k])])
    return rows


HEADERS = ["T_p [N·m]", "LTE mean [µrad]", "LTE p-p [µrad]", "seed p-p", "1st harm. [µrad]",
           "LTE max @ cycle",
           "LTE min @ cycle", "loaded curves (mean)", "at max", "at min", "edge %",
           "plastic % (max roll)"]


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="*", default=["kolivand2009_fm_11x41_reference",
                                                     "kolivand2009_fm_11x41"])
    parser.add_argument("--torque", type=float, nargs="+",
                        default=[50.0, 100.0, 200.0, 250.0, 300.0, 400.0, 500.0, 600.0,
                                 700.0])
    parser.add_argument("--rolls-per-cycle", type=int, default=20)
    parser.add_argument("--models", nargs="+", default=list(EDGE_MODELS),
                        choices=list(EDGE_MODELS))
    args = parser.parse_args(argv)
    for name in args.cases:
        case = resolve_case(name)
        for model in args.models:
            options = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle, **EDGE_MODELS[model])
            tree = run_analysis(case, args.torque, options=options, deviations=False,
                                geometry=False, operating=False, mesh_interface=False,
                                root_stress=False, steps={"load_capacity": None})
            ltca = tree["/ltca"].to_dataset()
            print(f"\n{case.name}, {model}, {args.rolls_per_cycle} rolls per cycle "
                  f"(UTE p-p {np.ptp(ltca['unloaded_transmission_error'].values):.1f} µrad)")
            print(tabulate(trend_rows(ltca), headers=HEADERS, floatfmt=".1f"))


if __name__ == "__main__":
    main()
