"""``ltca report``: one self-contained HTML page of an analysis, from its netCDF file alone."""

from __future__ import annotations

import argparse

from contact.commands.options import (
    analysis_file_argument,
    output_option,
    resolve_analysis_file,
)
from contact.commands.output_paths import check_output_file

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
        "the solver's certification and the toolkit versions. A file written by `ltca "
        "duty-cycle` gives its duty-cycle page instead (damage, life and safety factors "
        "of both members, the bins, the figures). Only the file is read, so a file from "
        "another machine or an older run gives the same page.",
    )
    analysis_file_argument(p)
    output_option(p, default="FILE's name with .html, e.g. kolivand2009_fm_11x41_reference.html",
                  what="HTML file")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from contact.plots.report import write_report
    from geometry.core.io import read_netcdf

    path = resolve_analysis_file(args.file)
    output = args.output or path.with_suffix(".html").name
    check_output_file(output)
    tree = read_netcdf(path, tree=True)
    if "duty_cycle" in tree.children:
        from contact.plots.duty_report import write_duty_report

        print(f"wrote {write_duty_report(tree, output)}")
        return 0
    print(f"wrote {write_report(tree, output)}")
    return 0
