"""``ltca utca``: ease-off based unloaded tooth contact analysis of a case."""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

from contact.commands.options import (
    case_and_misalignment,
    case_argument,
    checked_outputs,
    count,
    flank_option,
    misalignment_options,
    output_option,
    plots_option,
    rolls_per_cycle_option,
)

#: Place in ``ltca --help``.
ORDER = 40


def register(sub) -> None:
    """Add the ``utca`` sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "utca",
        help="unloaded TCA from the ease-off and the surface of roll angle",
        description="Ease-off topography, surface of roll angle, contact curves, unloaded "
        "transmission error of adjacent tooth pairs and the contact pattern of a case "
        "(Kolivand 2009, sections 2.3.2 and 4.4). Misalignments given here replace the "
        "case's [operating] values.",
    )
    case_argument(p)
    misalignment_options(p)
    flank_option(p, default="drive")
    rolls_per_cycle_option(p, default=30, alias="--n-roll")
    output_option(p, default="<case>_utca.nc; --flank coast: "
                             "<case>_coast_utca.nc", what="netCDF file (groups /easeoff, /utca)")
    plots_option(p)
    p.add_argument("--separation", type=float, default=6.3,
                   help="separation bounding the contact lines [um] (default 6.3)")
    p.add_argument("--method", default="second_order",
                   help="UTE method: second_order (default) or seed")
    p.add_argument("--nu", type=count(3, 2001), default=41,
                   help="lengthwise grid points (default 41)")
    p.add_argument("--nv", type=count(3, 2001), default=21, help="profile grid points (default 21)")
    p.set_defaults(func=run_utca)


def run_utca(args: argparse.Namespace) -> int:
    """Run the UTCA, print a summary, write netCDF and plots as asked."""
    import xarray as xr

    from contact.pipeline import MISALIGNMENT_REFERENCE, misalignment_attrs
    from contact.utca import unloaded_tca
    from geometry.core.io import write_netcdf

    output = checked_outputs(args, "_utca.nc")
    case, mis = case_and_misalignment(args)
    easeoff, utca = unloaded_tca(case, misalignment=mis, flank=args.flank,
                                 rolls_per_cycle=args.rolls_per_cycle,
                                 separation=args.separation * 1e-3,
                                 grid={"nu": args.nu, "nv": args.nv}, method=args.method)
    m1, m2 = utca["transition_roll"].values
    print(f"{case.name}: {easeoff.attrs['pinion_flank']} pinion / "
          f"{easeoff.attrs['gear_flank']} gear flank, misalignment dE {mis.delta_E:g} mm, "
          f"dP {mis.delta_P:g} mm, dG {mis.delta_G:g} mm, "
          f"dSigma {math.degrees(mis.delta_Sigma):g} deg")
    print(f"  max ease-off {float(easeoff['ease_off'].max()):.2f} um; "
          f"UTE peak-to-peak {float(utca['peak_to_peak_transmission_error']):.3f} urad; "
          f"transitions M1 {m1:.5f} rad, M2 {m2:.5f} rad; "
          f"longest contact line {float(utca['contact_line_length'].max()):.2f} mm")
    inputs = dataclasses.replace(case, misalignment=mis).to_toml()
    tree = xr.DataTree.from_dict({
        "/": xr.Dataset(attrs={"case": case.name, "title": "unloaded TCA",
                               **misalignment_attrs(mis)}),
        "/easeoff": easeoff.assign_attrs(misalignment=MISALIGNMENT_REFERENCE),
        "/utca": utca.assign_attrs(misalignment=MISALIGNMENT_REFERENCE)})
    path = write_netcdf(tree, Path(output), inputs=inputs)
    print(f"wrote {path}")
    if args.plots:
        from contact.plots import plot_utca

        for w in plot_utca(easeoff, utca, args.plots):
            print(f"wrote {w}")
    return 0
