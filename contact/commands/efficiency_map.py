"""``ltca efficiency-map``: mechanical efficiency over speed, torque, temperature, roughness."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from contact.output_paths import check_output_dir, check_output_file

#: Place in ``ltca --help``.
ORDER = 15


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    from friction.operating import OperatingConditions

    op = OperatingConditions()  # the defaults of the efficiency stage
    p = sub.add_parser(
        "efficiency-map",
        help="sweep speed, torque, oil temperature and roughness; write efficiency as netCDF",
        description="Loaded TCA once per torque, then the efficiency stage at every operating "
        "point; writes a netCDF over (torque, speed, temperature, roughness) and plots.",
    )
    p.add_argument("case", nargs="?", default=None, help="case file or bundled name")
    p.add_argument(
        "--speed",
        type=float,
        nargs="+",
        default=None,
        metavar="RPM",
        help="pinion speeds [rpm] (default 500 1000 1500 2500 4000, "
        "contact.pipeline.EFFICIENCY_MAP_SPEEDS)",
    )
    p.add_argument(
        "--torque",
        type=float,
        nargs="+",
        default=None,
        metavar="N_M",
        help="pinion torques [N m] (default 100 250 500, contact.pipeline.EFFICIENCY_MAP_TORQUES)",
    )
    p.add_argument(
        "--temperature",
        type=float,
        nargs="+",
        default=[op.temperature],
        metavar="C",
        help=f"oil inlet temperatures [C] (default {op.temperature:g})",
    )
    p.add_argument(
        "--roughness",
        type=float,
        nargs="+",
        default=[op.roughness],
        metavar="UM",
        help=f"RMS roughness Rq of each surface [um] (default {op.roughness:g})",
    )
    p.add_argument("--lubricant", default=op.lubricant,
                   help="bundled oil name or TOML file (default %(default)s)")
    p.add_argument("--friction-model", default=op.friction_model,
                   help="friction coefficient model (default %(default)s)")
    p.add_argument("--rolls-per-cycle", type=int, default=10)
    p.add_argument("-o", "--output", default="efficiency_map.nc")
    p.add_argument("--plots", default=None, metavar="DIR")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the torques on the Dask cluster at ADDRESS (tcp://host:8786)")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="run the torques on a local Dask cluster of N processes "
                        "(default: in this process)")
    p.add_argument("--no-progress", action="store_true")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.io import write_netcdf
    from contact.ltca import LTCAOptions
    from contact.pipeline import efficiency_map, resolve_case
    from contact.plots import plot_efficiency_map
    from friction.operating import OperatingConditions

    check_output_file(args.output)
    if args.plots:
        check_output_dir(args.plots)
    case = resolve_case(args.case)
    scheduler = args.scheduler
    if scheduler is None:
        scheduler = "synchronous" if args.workers is None else None
    emap = efficiency_map(
        case,
        args.torque,
        args.speed,
        temperature=args.temperature,
        roughness=args.roughness,
        operating=OperatingConditions(lubricant=args.lubricant,
                                      friction_model=args.friction_model),
        options=LTCAOptions(rolls_per_cycle=args.rolls_per_cycle),
        progress=not args.no_progress and sys.stderr.isatty(),
        scheduler=scheduler,
        n_workers=args.workers,
    )
    # one table per oil temperature and roughness: every swept value is printed
    for temp in emap["temperature"].values:
        for rq in emap["roughness"].values:
            sel = emap["efficiency"].sel(temperature=temp, roughness=rq) * 100
            rows = [[f"{T:g}", *(f"{v:.2f}" for v in sel.sel(torque=T).values)]
                    for T in emap["torque"].values]
            print(f"case {case.name}: efficiency [%] at {temp:g} C, Rq {rq:g} um "
                  f"({args.lubricant}, {args.friction_model})")
            print(tabulate(rows, headers=["T_p [N m]",
                                          *(f"{n:g} rpm" for n in emap["speed"].values)],
                           tablefmt="github"))
    share = emap["friction_model_extrapolated_share"]
    if float(share.max()) > 0:
        print(f"WARNING: friction model {args.friction_model} extrapolated outside its fitted "
              f"range at {100 * float(share.max()):.0f} % of the loaded segments at worst "
              f"({int((share > 0).sum())} of {share.size} operating points; "
              "friction_model_extrapolated_share): those efficiencies are extrapolations")
    path = write_netcdf(emap, Path(args.output), inputs=case.to_toml())
    print(f"wrote {path}")
    if args.plots:
        for p in plot_efficiency_map(emap, args.plots):
            print(f"wrote {p}")
    return 0
