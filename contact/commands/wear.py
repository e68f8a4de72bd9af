"""``ltca wear``: simulated wear of the flanks in contact over load cycles (Archard)."""

from __future__ import annotations

import argparse
import dataclasses
from pathlib import Path

from contact.commands.options import (
    case_and_misalignment,
    case_argument,
    checked_outputs,
    count,
    misalignment_options,
    output_option,
    progress_option,
    rolls_per_cycle_option,
    segments_option,
    solver_option,
    torque_option,
)
from geometry.core.text import plain_number

#: pinion torque of ``ltca wear`` without ``--torque`` [N·m] (the seed's Table 4.2)
WEAR_TORQUE = 200.0

#: Place in ``ltca --help``.
ORDER = 17


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "wear",
        help="simulate flank wear (Archard) over load cycles; write the evolving deviations, "
        "TE and pattern per step",
        description="Archard wear of the pinion and gear flanks in contact (contact.wear): each "
        "step analyses the current surfaces (ease-off updated by the wear deviations, UTCA, "
        "LTCA), computes the wear depth of one mesh from the loads and the sliding, and "
        "removes it, times the step's load cycles, from the deviation grids. Writes a netCDF "
        "over the steps (deviation grids, TE, peak pressure, pattern).",
    )
    case_argument(p, what="wear")
    p.add_argument("--cycles", type=float, required=True,
                   help="load cycles in all (pinion revolutions)")
    p.add_argument("--wear-coefficient", type=float, required=True, metavar="K",
                   help="dimensional Archard wear coefficient k [m^2/N] (= m^3/(N m))")
    p.add_argument("--steps", type=count(1, 10000), default=5,
                   help="wear steps (default %(default)s)")
    torque_option(p, many=False, default="200, the seed's Table 4.2")
    misalignment_options(p)
    solver_option(p)
    p.add_argument("--no-deviations", action="store_true",
                   help="start from the theoretical surfaces, not the case's [deviations]")
    rolls_per_cycle_option(p)
    segments_option(p)
    output_option(p, default="<case>_wear.nc", what="netCDF file of the steps")
    p.add_argument("--deviations-out", default=None, metavar="FILE",
                   help="also write the worn (pinion, gear) grids of the last step as a "
                   "deviation netCDF (for `ltca run --deviations FILE FILE`)")
    progress_option(p)
    p.set_defaults(func=run, many_analyses=True)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.commands.run import ltca_options
    from contact.utca.deviation_files import write_deviation_netcdf
    from contact.wear import final_deviations, simulate_wear
    from geometry.core.io import write_netcdf

    output = checked_outputs(args, "_wear.nc", more={"--deviations-out": args.deviations_out})
    case, mis = case_and_misalignment(args)
    case = dataclasses.replace(case, misalignment=mis)
    torque = WEAR_TORQUE if args.torque is None else args.torque
    ds = simulate_wear(
        case,
        torque,
        wear_coefficient=args.wear_coefficient,
        cycles=args.cycles,
        steps=args.steps,
        options=ltca_options(args),
        deviations=False if args.no_deviations else None,
        progress=not args.no_progress,
    )
    rows = [
        (int(s), f"{ds['cycles'].values[i]:.4g}", f"{1e3 * ds['max_pinion_depth'].values[i]:.3f}",
         f"{1e3 * ds['max_gear_depth'].values[i]:.3f}", f"{ds['ute_peak_to_peak'].values[i]:.2f}",
         f"{ds['lte_peak_to_peak'].values[i]:.2f}", f"{ds['pressure_max_flank'].values[i]:.0f}")
        for i, s in enumerate(ds["step"].values)
    ]
    print(f"case {case.name}: wear at {plain_number(torque)} N m, "
          f"k = {args.wear_coefficient:g} m^2/N, "
          f"{args.cycles:g} cycles in {args.steps} steps")
    print(tabulate(rows, headers=["step", "cycles", "pinion depth [um]", "gear depth [um]",
                                  "UTE p-p [urad]", "LTE p-p [urad]", "p_max [MPa]"],
                   tablefmt="github"))
    path = write_netcdf(ds, Path(output), inputs=case.to_toml())
    print(f"wrote {path}")
    if args.deviations_out:
        pin, gear = final_deviations(ds)
        out = write_deviation_netcdf(
            args.deviations_out, pinion=pin, gear=gear,
            description=f"simulated wear of {case.name}: {args.cycles:g} cycles at "
            f"{torque:g} N m, k = {args.wear_coefficient:g} m^2/N (ltca wear)")
        print(f"wrote {out}")
    return 0
