"""``ltca efficiency-map``: mechanical efficiency over speed, torque, temperature, roughness."""

from __future__ import annotations

import argparse
from pathlib import Path

from contact.commands.options import (
    case_argument,
    default_output,
    flank_option,
    misalignment_from_args,
    misalignment_options,
    operating_options,
    output_option,
    plots_option,
    progress_option,
    rolls_per_cycle_option,
    segments_option,
    solver_option,
    torque_option,
)
from contact.commands.output_paths import check_output_dir, check_output_file

#: Place in ``ltca --help``.
ORDER = 15


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "efficiency-map",
        help="sweep speed, torque, oil temperature and roughness; write efficiency as netCDF",
        description="Loaded TCA once per torque, then the efficiency stage at every operating "
        "point; writes a netCDF over (torque, speed, temperature, roughness) and plots. The "
        "misalignment, oil, temperature and roughness are the case's [operating] table "
        "unless given here.",
    )
    case_argument(p)
    torque_option(p, default="100 250 500, contact.study.efficiency.EFFICIENCY_MAP_TORQUES")
    misalignment_options(p)
    operating_options(p, many=True, speed_help="pinion speeds [rpm] (default 500 1000 1500 "
                      "2500 4000, contact.study.efficiency.EFFICIENCY_MAP_SPEEDS)")
    solver_option(p)
    flank_option(p)
    rolls_per_cycle_option(p, default=10)
    segments_option(p)
    output_option(p, default="<case>_efficiency_map.nc")
    plots_option(p)
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the torques on the Dask cluster at ADDRESS (tcp://host:8786)")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="run the torques on a local Dask cluster of N processes "
                        "(default: in this process)")
    progress_option(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.catalogue import resolve_case
    from contact.commands.run import ltca_options
    from contact.plots import plot_efficiency_map
    from contact.plots.style import misalignment_text
    from contact.study.efficiency import efficiency_map
    from friction.operating import OperatingConditions
    from geometry.core.io import write_netcdf

    output = default_output(args, "_efficiency_map.nc")
    check_output_file(output)
    if args.plots:
        check_output_dir(args.plots)
    case = resolve_case(args.case)
    op = OperatingConditions.from_point(
        case.operating, pinion_speed=case.operating.pinion_speed or None,
        lubricant=args.lubricant, friction_model=args.friction_model)
    scheduler = args.scheduler
    if scheduler is None:
        scheduler = "synchronous" if args.workers is None else None
    emap = efficiency_map(
        case,
        args.torque,
        args.speed,
        temperature=args.temperature,
        roughness=args.roughness,
        operating=op,
        misalignment=misalignment_from_args(args, case.misalignment),
        flank=args.flank,
        options=ltca_options(args),
        progress=not args.no_progress,
        scheduler=scheduler,
        n_workers=args.workers,
    )
    # one table per oil temperature and roughness: every swept value is printed
    for temp in emap["temperature"].values:
        for rq in emap["roughness"].values:
            sel = emap["efficiency"].sel(temperature=temp, roughness=rq) * 100
            rows = [[f"{T:g}", *(f"{v:.2f}" for v in sel.sel(torque=T).values)]
                    for T in emap["torque"].values]
            print(f"case {case.name}: efficiency [%] at {temp:g} degC, Rq {rq:g} um "
                  f"({op.lubricant}, {op.friction_model}; {misalignment_text(emap.attrs)})")
            print(tabulate(rows, headers=["T_p [N m]",
                                          *(f"{n:g} rpm" for n in emap["speed"].values)],
                           tablefmt="github"))
    share = emap["friction_model_extrapolated_share"]
    if float(share.max()) > 0:
        print(f"WARNING: friction model {emap.attrs.get('friction_model', '')} extrapolated "
              f"outside its fitted range at {100 * float(share.max()):.0f} % of the loaded "
              "segments at worst "
              f"({int((share > 0).sum())} of {share.size} operating points; "
              "friction_model_extrapolated_share): those efficiencies are extrapolations")
    path = write_netcdf(emap, Path(output), inputs=case.to_toml())
    print(f"wrote {path}")
    if args.plots:
        for p in plot_efficiency_map(emap, args.plots, progress=not args.no_progress):
            print(f"wrote {p}")
    return 0
