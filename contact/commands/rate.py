"""``ltca rate``: the load capacity rating of a case by a method of the registry
(:mod:`contact.load_capacity`; default ISO 10300 Method B1)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from contact.commands.options import case_argument, output_option, torque_option

#: Place in ``ltca --help``.
ORDER = 45


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "rate",
        help="load capacity rating (default ISO 10300 Method B1): contact and root "
        "stresses, permissible stresses and safety factors",
        description="Rate the case's pair by a load-capacity method of the registry "
        "(--method; default iso10300, ISO 10300-1/-2/-3 Method B1, docs/rating.md). For "
        "ISO 10300: the virtual cylindrical gears of its ISO 23509 blank (the case's "
        "[design] table), the load factors, the contact stress against pitting and the "
        "tooth root stress of both members, with the permissible stresses and safety "
        "factors, printed in the layout of ISO/TR 10300-30's result tables. The rating "
        "inputs (application factor, pitch deviation, mounting, oil, roughness, material "
        "quality, life, minimum safety factors) are the case's [rating] table; the "
        "bundled iso10300_30_sample1..3 are the TR's samples.",
    )
    case_argument(p, what="rate")
    torque_option(p, default="the case's [operating] torques")
    p.add_argument("--speed", type=float, default=None, metavar="RPM",
                   help="pinion speed [rpm] (default the case's [operating] pinion_speed)")
    p.add_argument("--method", default=None, metavar="NAME",
                   help="load-capacity rating method of the registry (default the case's "
                   "[rating] method, else iso10300: ISO 10300-1/-2/-3:2014 Method B1; "
                   "agma2003: ANSI/AGMA 2003-D19, the case's [agma2003] table; an unknown "
                   "name lists those available; docs/extending.md adds one)")
    p.add_argument("--flank", default=None, choices=("drive", "coast", "concave", "convex"),
                   help="the pinion flank rated, as `ltca run --flank` loads it (default the "
                   "[rating] table's side, else the drive flank)")
    output_option(p, default="none: the tables only",
                  what="netCDF file of the /rating dataset")
    p.set_defaults(func=run)


def variable_lines(ds) -> str:
    """A rating dataset as text, for a method without tables of its own: per variable its
    name, units and values (per torque and member where it has those dimensions)."""
    from tabulate import tabulate

    rows = []
    for name, var in ds.data_vars.items():
        values = var.values
        text = (f"{float(values):.6g}" if values.ndim == 0 and values.dtype.kind in "fiu"
                else " ".join(f"{float(v):.6g}" if values.dtype.kind in "fiu" else str(v)
                              for v in values.ravel()))
        rows.append((name, var.attrs.get("units", ""), ", ".join(var.dims), text))
    head = (f"{ds.attrs.get('title', 'load capacity rating')}: {ds.attrs.get('case', '')} "
            f"(method {ds.attrs.get('rating_method', '')})")
    return "\n".join([head, tabulate(rows, headers=["variable", "units", "dims", "values"],
                                     tablefmt="simple", disable_numparse=True)])


def run(args: argparse.Namespace) -> int:
    import xarray as xr

    from contact.catalogue import resolve_case
    from contact.commands.output_paths import check_output_file
    from contact.load_capacity.methods import DEFAULT_METHOD, METHODS, case_method, rate
    from geometry.core.io import write_netcdf

    if args.output:
        check_output_file(args.output)
    case = resolve_case(args.case)
    method = args.method or case_method(case) or DEFAULT_METHOD
    # unknown method: lists the names
    ds = rate(case, args.torque, args.speed, method=method, flank=args.flank)
    show = METHODS[method].tables or variable_lines
    print(show(ds))
    if ds.attrs.get("rating_method") == "iso10300" and "rating_inputs" in ds.attrs:
        # ISO 10300: the flank roughness it took
        rz = json.loads(ds.attrs["rating_inputs"])["flank_roughness"]
        if "flank_roughness" not in (case.extra.get("rating") or {}):
            print(f"flank roughness Rz {rz[0]:g} / {rz[1]:g} um: the case's [operating] "
                  f"roughness Rq {case.operating.roughness:g} um (the flanks the analysis "
                  "runs) as Rz = 6 Ra = 6 sqrt(2/pi) Rq (docs/rating.md)")
    if args.output:
        tree = xr.DataTree.from_dict({
            "/": xr.Dataset(attrs={"case": case.name,
                                   "title": str(ds.attrs.get("title", "load capacity "
                                                                       "rating"))}),
            "/rating": ds})
        path = write_netcdf(tree, Path(args.output), inputs=case.to_toml())
        print(f"wrote {path}")
    return 0
