"""``ltca efficiency-map``: mechanical efficiency over speed, torque, temperature, roughness."""

from __future__ import annotations

import argparse
from pathlib import Path

from contact.commands.options import (
    case_argument,
    checked_outputs,
    count,
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
    torque_option(p, default="100 250 500")
    misalignment_options(p)
    operating_options(p, many=True, speed_help="pinion speeds [rpm] (default 500 1000 1500 "
                      "2500 4000)")
    solver_option(p)
    flank_option(p)
    rolls_per_cycle_option(p, default=10)
    segments_option(p)
    output_option(p, default="<case>_efficiency_map_<swept inputs>.nc, e.g. "
                  "kolivand2009_fm_11x41_reference_efficiency_map_speed_torque.nc")
    plots_option(p)
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the torques on the Dask cluster at ADDRESS (tcp://host:8786)")
    p.add_argument("--workers", type=count(1, 1024), default=None, metavar="N",
                   help="run the torques on a local Dask cluster of N processes "
                        "(default: in this process)")
    progress_option(p)
    p.set_defaults(func=run, many_analyses=True)


#: how each dimension of an efficiency map is written in the table
_DIM_TEXT = {"torque": ("T_p", "N m"), "speed": ("speed", "rpm"),
             "temperature": ("oil", "degC"), "roughness": ("Rq", "um")}


def efficiency_table(emap) -> str:
    """One table of every operating point of an efficiency map [%]: its columns the first
    swept input of speed, roughness, temperature, torque; a row per combination of the
    other swept inputs; inputs of one value said above the table (was one table per oil
    temperature and roughness, 21 one-cell tables for the README's temperature × roughness
    map)."""
    import itertools

    from tabulate import tabulate

    swept = [d for d in ("speed", "roughness", "temperature", "torque")
             if emap.sizes.get(d, 1) > 1]
    col = swept[0] if swept else "speed"
    rows_dims = [d for d in ("torque", "temperature", "roughness", "speed")
                 if d != col and emap.sizes.get(d, 1) > 1]
    fixed = [d for d in ("torque", "speed", "temperature", "roughness")
             if d != col and d not in rows_dims]
    eff = emap["efficiency"] * 100
    for d in fixed:
        eff = eff.isel({d: 0})
    head = ", ".join(f"{_DIM_TEXT[d][0]} {float(emap[d].values[0]):g} {_DIM_TEXT[d][1]}"
                     for d in fixed)
    rows = []
    for values in itertools.product(*(emap[d].values for d in rows_dims)):
        sel = eff.sel(dict(zip(rows_dims, values, strict=True)))
        rows.append([*(f"{v:g}" for v in values),
                     *(f"{float(x):.2f}" for x in sel.transpose(col).values)])
    name, unit = _DIM_TEXT[col]
    headers = [f"{_DIM_TEXT[d][0]} [{_DIM_TEXT[d][1]}]" for d in rows_dims] + [
        f"{name} {float(v):g} {unit}" for v in emap[col].values]
    table = tabulate(rows, headers=headers, tablefmt="github")
    return f"at {head}:\n{table}" if head else table


def swept_values(args: argparse.Namespace) -> dict[str, list[float] | None]:
    """The values of each input of an ``efficiency-map`` command, known before the work:
    speed [rpm] and torque [N·m] as given or the map's defaults, temperature [degC] and
    roughness Rq [µm] as given or None (the case's)."""
    from contact.study.efficiency import EFFICIENCY_MAP_SPEEDS, EFFICIENCY_MAP_TORQUES

    def listed(v):
        return None if v is None else list(v)

    return {"speed": list(args.speed or EFFICIENCY_MAP_SPEEDS),
            "torque": list(args.torque or EFFICIENCY_MAP_TORQUES),
            "temperature": listed(args.temperature), "roughness": listed(args.roughness)}


def sweep_tag(args: argparse.Namespace) -> str:
    """The inputs an ``efficiency-map`` command sweeps (more than one value) joined by
    ``_`` (``speed_torque``, ``temperature_roughness``), known before the work: the
    default output and figure names carry it, so maps of one case over different inputs
    do not overwrite each other."""
    sizes = {d: len(v) if v else 1 for d, v in swept_values(args).items()}
    return "_".join(d for d, n in sizes.items() if n > 1) or "point"


def efficiency_map_plan(name: str, args: argparse.Namespace) -> str:
    """The line ``ltca efficiency-map`` prints before it starts: the values of every swept
    input and how many analyses they make (issue 56: every study says what it will run)."""
    values = swept_values(args)
    labels = {"torque": "torque [N m]", "speed": "speed [rpm]",
              "temperature": "temperature [degC]", "roughness": "roughness Rq [um]"}
    parts, n = [], 1
    for dim, label in labels.items():
        if values[dim] is None:
            parts.append(f"{label.split(' [')[0]} the case's")
            continue
        n *= len(values[dim])
        parts.append(f"{label} {', '.join(f'{x:g}' for x in values[dim])}")
    return (f"efficiency map of {name}: " + "; ".join(parts)
            + f" ({n} point{'s' if n != 1 else ''})")


def run(args: argparse.Namespace) -> int:
    from contact.catalogue import resolve_case
    from contact.commands.run import ltca_options, print_wrapped
    from contact.plots import plot_efficiency_map
    from contact.plots.style import misalignment_text
    from contact.study.efficiency import efficiency_map
    from friction.operating import OperatingConditions
    from geometry.core.io import write_netcdf

    tag = sweep_tag(args)
    output = checked_outputs(args, f"_efficiency_map_{tag}.nc")
    case = resolve_case(args.case)
    op = OperatingConditions.from_point(
        case.operating, pinion_speed=case.operating.pinion_speed or None,
        lubricant=args.lubricant, friction_model=args.friction_model,
        surface_state=args.surface_state)
    scheduler = args.scheduler
    if scheduler is None:
        scheduler = "synchronous" if args.workers is None else None
    print_wrapped(efficiency_map_plan(case.name, args))  # what will run, before it starts
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
    print(f"case {case.name}: efficiency [%] ({op.lubricant}, {op.friction_model}; "
          f"{misalignment_text(emap.attrs)})")
    print(efficiency_table(emap))
    share = emap["friction_model_extrapolated_share"]
    if float(share.max()) > 0:
        print_wrapped(f"WARNING: friction model {emap.attrs.get('friction_model', '')} "
                      f"extrapolated outside its fitted range at "
                      f"{100 * float(share.max()):.0f} % of the loaded segments at worst "
                      f"({int((share > 0).sum())} of {share.size} operating points; "
                      "friction_model_extrapolated_share): those efficiencies are "
                      "extrapolations")
    path = write_netcdf(emap, Path(output), inputs=case.to_toml())
    print(f"wrote {path}")
    if args.plots:
        for p in plot_efficiency_map(emap, args.plots, progress=not args.no_progress,
                                     prefix=f"{case.name}_{tag}_"):
            print(f"wrote {p}")
    if int(emap["analysis_status"].max()) > 0:  # a torque without certified contact
        from contact.errors import AnalysisFailedError

        raise AnalysisFailedError(f"efficiency map {path}: {emap.attrs['analysis_status_reason']}"
                                  " (its efficiencies are NaN there; analysis_status)")
    return 0
