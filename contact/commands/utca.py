"""``ltca utca``: ease-off based unloaded tooth contact analysis of a case."""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

from contact.output_paths import check_output_dir, check_output_file

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
        "case's own.",
    )
    p.add_argument("case", help="case file (TOML)")
    p.add_argument("-o", "--output", help="netCDF file to write (groups /easeoff, /utca)")
    p.add_argument("--plots", metavar="DIR", help="directory for the PNG plots")
    p.add_argument("--dE", type=float, help="offset change Delta E [mm]")
    p.add_argument("--dP", type=float, help="pinion axial displacement Delta P [mm]")
    p.add_argument("--dG", type=float, help="gear axial displacement Delta G [mm]")
    p.add_argument("--dSigma", type=float, help="shaft-angle change Delta Sigma [deg]")
    p.add_argument("--flank", default="drive",
                   help="drive, coast, or the pinion flank concave/convex (default drive)")
    p.add_argument("--n-roll", type=int, default=30, help="roll positions per mesh cycle")
    p.add_argument("--separation", type=float, default=6.3,
                   help="separation bounding the contact lines [um] (default 6.3)")
    p.add_argument("--method", default="second_order",
                   help="UTE method: second_order (default) or seed")
    p.add_argument("--nu", type=int, default=41, help="lengthwise grid points (default 41)")
    p.add_argument("--nv", type=int, default=21, help="profile grid points (default 21)")
    p.set_defaults(func=run_utca)


def run_utca(args: argparse.Namespace) -> int:
    """Run the UTCA, print a summary, write netCDF and plots as asked."""
    import xarray as xr

    from contact.io import write_netcdf
    from contact.utca import unloaded_tca
    from geometry.case import load_case

    if args.output:
        check_output_file(args.output)
    if args.plots:
        check_output_dir(args.plots)
    case = load_case(args.case)
    mis = case.misalignment
    given = {"delta_E": args.dE, "delta_P": args.dP, "delta_G": args.dG,
             "delta_Sigma": None if args.dSigma is None else math.radians(args.dSigma)}
    mis = dataclasses.replace(mis, **{k: v for k, v in given.items() if v is not None})
    easeoff, utca = unloaded_tca(case, misalignment=mis, flank=args.flank, n_roll=args.n_roll,
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
    inputs = case.to_toml()
    if args.output:
        tree = xr.DataTree.from_dict({
            "/": xr.Dataset(attrs={"case": case.name, "title": "unloaded TCA"}),
            "/easeoff": easeoff, "/utca": utca})
        path = write_netcdf(tree, Path(args.output), inputs=inputs)
        print(f"wrote {path}")
    if args.plots:
        from contact.plots import plot_utca

        for w in plot_utca(easeoff, utca, args.plots):
            print(f"wrote {w}")
    return 0
