"""``ltca report``: one self-contained HTML page of an analysis, from its netCDF file alone."""

from __future__ import annotations

import argparse

from contact.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 12


def register(sub) -> None:
    """Add the ``report`` sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "report",
        help="one HTML page of an analysis file: case, conditions, summary table, figures",
        description="Write a self-contained HTML page (figures embedded, no network) of a "
        "file written by `ltca run`: the case and its provenance, the operating conditions, "
        "the LTE/pressure/efficiency summary table (seed Table 3.1 layout), every figure, "
        "the solver's certification and the toolkit versions. Only the file is read, so a "
        "file from another machine or an older run gives the same page.",
    )
    p.add_argument("file", help="netCDF file written by `ltca run`")
    p.add_argument("-o", "--output", default="report.html",
                   help="HTML file (default report.html)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from contact.io import read_netcdf
    from contact.plots.report import write_report

    check_output_file(args.output)
    tree = read_netcdf(args.file, tree=True)
    print(f"wrote {write_report(tree, args.output)}")
    return 0
