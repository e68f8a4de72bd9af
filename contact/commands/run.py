"""``ltca run`` and ``ltca plot``: the whole analysis of a case, and its plots from a file."""

from __future__ import annotations

import argparse
import math
import os
import sys
from pathlib import Path

from contact.output_paths import check_output_dir, check_output_file

#: Place in ``ltca --help``.
ORDER = 10


def _misalignment_args(p) -> None:
    p.add_argument("--dE", type=float, default=None, help="offset error ΔE [mm]")
    p.add_argument("--dP", type=float, default=None, help="pinion mounting error ΔP [mm]")
    p.add_argument("--dG", type=float, default=None, help="gear mounting error ΔG [mm]")
    p.add_argument("--dSigma", type=float, default=None, help="shaft angle error ΔΣ [deg]")


def misalignment_from_args(args, base):
    """A Misalignment from ``--dE --dP --dG --dSigma`` over ``base`` (None: all unset)."""
    from geometry.assembly import Misalignment

    given = {k: getattr(args, k) for k in ("dE", "dP", "dG", "dSigma")}
    if all(v is None for v in given.values()):
        return base
    b = base or Misalignment()
    return Misalignment(
        delta_E=b.delta_E if given["dE"] is None else given["dE"],
        delta_P=b.delta_P if given["dP"] is None else given["dP"],
        delta_G=b.delta_G if given["dG"] is None else given["dG"],
        delta_Sigma=b.delta_Sigma if given["dSigma"] is None else math.radians(given["dSigma"]),
    )


def register(sub) -> None:
    """Add the sub-commands to an ``argparse`` sub-parser collection."""
    from friction.operating import OperatingConditions

    op = OperatingConditions()  # the defaults of the efficiency stage
    p = sub.add_parser(
        "run",
        help="loaded TCA of a case (default: the bundled 11x41 pair at the seed's Table 3.1)",
        description="Geometry, ease-off UTCA and loaded TCA of a case at one or more torques; "
        "prints a summary, writes one netCDF (/geometry, /easeoff, /utca, /ltca) and plots. "
        "Without CASE: the bundled default case at the seed's Table 3.1 conditions "
        "(pinion torque 50/250/500 N m, ΔE = −0.15 mm, ΔP = +0.12 mm; the seed lost the signs, "
        "see contact.pipeline.SEED_TABLE_3_1).",
    )
    p.add_argument(
        "case",
        nargs="?",
        default=None,
        help="case file (TOML) or bundled case name (default: the 11x41 pair)",
    )
    p.add_argument(
        "--torque",
        type=float,
        nargs="+",
        default=None,
        metavar="N_M",
        help="pinion torques [N m] (default 50 250 500)",
    )
    _misalignment_args(p)
    p.add_argument("--solver", default=None, help="solver name (see `ltca compare-solvers`)")
    dev = p.add_mutually_exclusive_group()
    dev.add_argument(
        "--deviations",
        nargs=2,
        metavar=("PINION", "GEAR"),
        default=None,
        help="measured/wear normal deviations of the pinion and gear flanks in "
        "contact (CSV or netCDF, see contact.utca.deviations; '-' for none); overrides the "
        "case's [deviations] table; the theoretical results are kept under /theoretical",
    )
    dev.add_argument(
        "--no-deviations",
        action="store_true",
        help="ignore the case's [deviations] table (theoretical surfaces only)",
    )
    p.add_argument(
        "--speed",
        type=float,
        default=op.pinion_speed,
        metavar="RPM",
        help="pinion speed for the efficiency stage (default %(default)g; 0 skips it)",
    )
    p.add_argument("--lubricant", default=op.lubricant,
                   help="bundled oil name or TOML file (default %(default)s)")
    p.add_argument("--temperature", type=float, default=op.temperature,
                   help="oil inlet temperature [C] (default %(default)g)")
    p.add_argument("--roughness", type=float, default=op.roughness,
                   help="RMS roughness Rq [um] (default %(default)g)")
    p.add_argument("--friction-model", default=op.friction_model,
                   help="friction coefficient model (default %(default)s)")
    p.add_argument("--flank", choices=["drive", "coast"], default=None)
    p.add_argument("--rolls-per-cycle", type=int, default=20)
    p.add_argument("--segments", type=int, default=24, help="segments per contact curve")
    p.add_argument("-o", "--output", default="ltca.nc", help="netCDF file (default ltca.nc)")
    p.add_argument("--plots", default=None, metavar="DIR", help="write PNG plots into DIR")
    p.add_argument("--report", default=None, metavar="HTML",
                   help="write the one-page HTML report (as `ltca report`) to HTML")
    p.add_argument("--no-progress", action="store_true")
    p.set_defaults(func=run)

    q = sub.add_parser("plot", help="redraw every plot of an analysis from its netCDF file")
    q.add_argument("file", help="netCDF file written by `ltca run`")
    q.add_argument("--plots", default="plots", metavar="DIR", help="directory (default plots)")
    q.set_defaults(func=plot)


#: columns of the theoretical/deviated TE table (seed Tables 4.2, 4.4), all [urad] but T_p
TE_TABLE_HEADERS = (
    "T_p [N m]",
    "surfaces",
    "LTE mean",
    "LTE p-p",
    "1st",
    "2nd",
    "3rd",
    "RMS*",
    "UTE p-p",
)


def deviation_te_rows(tree) -> list[tuple[str, ...]]:
    """Rows of the TE table of an analysis with deviations (seed Tables 4.2, 4.4).

    Parameters
    ----------
    tree : xarray.DataTree
        Output of :func:`contact.pipeline.run_analysis` with deviations: ``/ltca``,
        ``/utca`` (deviated) and ``/theoretical/{ltca,utca}``.

    Returns
    -------
    list of tuple of str
        Per torque, a ``theoretical`` then a ``deviated`` row: T_p [N·m], LTE mean,
        peak-to-peak, amplitudes of the first three mesh harmonics, the seed's RMS
        (root-sum-square of those amplitudes, ``lte_harmonic_rss``) and the UTE
        peak-to-peak, all [µrad] with two decimals, as stored in the datasets (columns
        :data:`TE_TABLE_HEADERS`).
    """
    rows = []
    groups = {
        "theoretical": (tree["theoretical/ltca"].to_dataset(), tree["theoretical/utca"]),
        "deviated": (tree["ltca"].to_dataset(), tree["utca"]),
    }
    for i, T in enumerate(tree["ltca"]["torque"].values):
        for name, (lt, ut) in groups.items():
            h = lt["lte_harmonics"].values[i]
            rows.append(
                (
                    f"{T:g}",
                    name,
                    f"{lt['lte_mean'].values[i]:.2f}",
                    f"{lt['lte_peak_to_peak'].values[i]:.2f}",
                    f"{h[0]:.2f}",
                    f"{h[1]:.2f}",
                    f"{h[2]:.2f}",
                    f"{lt['lte_harmonic_rss'].values[i]:.2f}",
                    f"{float(ut['peak_to_peak_transmission_error']):.2f}",
                )
            )
    return rows


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.io import write_netcdf
    from contact.ltca import LTCAOptions
    from contact.pipeline import SEED_TABLE_3_1, resolve_case, run_analysis
    from friction.operating import OperatingConditions

    check_output_file(args.output)
    if args.plots:
        check_output_dir(args.plots)
    if args.report:
        check_output_file(args.report, option="--report")
    case = resolve_case(args.case)
    base = SEED_TABLE_3_1["misalignment"] if args.case is None else case.misalignment
    mis = misalignment_from_args(args, base)
    opts = LTCAOptions(
        rolls_per_cycle=args.rolls_per_cycle,
        segments=args.segments,
        **({"solver": args.solver} if args.solver else {}),
    )
    devs = None  # the case's [deviations] table, if any
    if args.no_deviations:
        devs = False
    elif args.deviations:
        # file paths: run_analysis reads them (contact.deviation_files.read_deviations)
        devs = tuple(None if f == "-" else f for f in args.deviations)
    operating = None  # --speed 0: no efficiency stage
    if args.speed:
        operating = OperatingConditions(
            pinion_speed=args.speed,
            lubricant=args.lubricant,
            temperature=args.temperature,
            roughness=args.roughness,
            friction_model=args.friction_model,
        )
    tree = run_analysis(
        case,
        args.torque,
        misalignment=mis,
        flank=args.flank,
        options=opts,
        deviations=devs,
        operating=operating,
        progress=not args.no_progress and sys.stderr.isatty(),
    )
    lt = tree["ltca"].to_dataset()
    print(
        f"case {case.name}: ΔE {mis.delta_E:g} mm, ΔP {mis.delta_P:g} mm, "
        f"ΔG {mis.delta_G:g} mm, ΔΣ {math.degrees(mis.delta_Sigma) * 60:g}′; "
        f"solver {lt.attrs['solver']}"
    )
    fr = tree["friction"].to_dataset() if "friction" in tree.children else None
    rows = []
    for i, T in enumerate(lt["torque"].values):
        h = lt["lte_harmonics"].values[i]
        rows.append(
            (
                f"{T:g}",
                f"{lt['lte_mean'].values[i]:.1f}",
                f"{lt['lte_peak_to_peak'].values[i]:.1f}",
                f"{h[0]:.1f}",
                f"{h[1]:.1f}",
                f"{h[2]:.1f}",
                f"{lt['lte_harmonic_rss'].values[i]:.1f}",
                f"{float(lt['pressure_max_flank'].values[i]):.0f}",
                f"{float(lt['pressure_max_edge'].values[i]):.0f}",
                f"{int(lt['found'].isel(torque=i).sum())}/{lt.sizes['roll']}",
                f"{100 * fr['efficiency_mean'].values[i]:.2f}" if fr is not None else "-",
            )
        )
    print(
        tabulate(
            rows,
            headers=[
                "T_p [N m]",
                "LTE mean [urad]",
                "p-p",
                "1st",
                "2nd",
                "3rd",
                "RMS*",
                "p_max flank [MPa]",
                "p_max edge",
                "certified",
                "efficiency [%]",
            ],
            tablefmt="github",
        )
    )
    if fr is not None:
        print(
            f"efficiency at {fr.attrs['pinion_speed_rpm']:g} rpm, {fr.attrs['lubricant']} at "
            f"{fr.attrs['inlet_temperature_degC']:g} C, Rq {fr.attrs['roughness_rq_um']:g} um, "
            f"friction model {fr.attrs['friction_model']}"
        )
        print_extrapolation_warning(fr)
    print("RMS*: root-sum-square of the first three harmonics, as the seed's Table 3.1.")
    if "theoretical" in tree.children:
        print(
            "transmission error of the theoretical and deviated surfaces "
            f"({tree['easeoff'].attrs.get('deviations', '')}; seed Tables 4.2, 4.4) [urad]:"
        )
        print(tabulate(deviation_te_rows(tree), headers=TE_TABLE_HEADERS, tablefmt="github"))
    times = {k[5:-2]: v for k, v in tree.attrs.items() if k.startswith("time_")}
    print("time [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in times.items()))
    path = write_netcdf(tree, Path(args.output), inputs=tree.attrs["inputs"])
    print(f"wrote {path}")
    write_figures(path, args.plots, args.report)
    return 0


def print_extrapolation_warning(friction) -> None:
    """A WARNING line when the friction model ran outside its fitted range (flagged per
    segment in ``/friction/friction_model_extrapolated``)."""
    from friction.efficiency import extrapolated_segments

    flagged, loaded = extrapolated_segments(friction)
    if flagged:
        print(f"WARNING: friction model {friction.attrs.get('friction_model', '')} "
              f"extrapolated outside its fitted range at {flagged} of {loaded} loaded "
              "segments (flag /friction/friction_model_extrapolated; marked on the plots): "
              "the efficiency there is an extrapolation")


def write_figures(path: Path, plots: str | None, report: str | None) -> None:
    """The PNGs (``--plots``) and the HTML report (``--report``) of the file just written,
    drawn from the file alone (what ``ltca plot`` and ``ltca report`` would draw), each
    figure once."""
    if not plots and not report:
        return
    from contact.io import read_netcdf
    from contact.plots import render_analysis
    from contact.plots.report import write_report
    from geometry.atomic_files import atomic_path

    tree = read_netcdf(path, tree=True)
    figures = []
    # two processes draw the figures (independent of each other): on two free cores the
    # drawing takes half the wall time (benchmarks/plots.py)
    for rf in render_analysis(tree, workers=min(2, os.cpu_count() or 1)):
        if plots:
            target = Path(plots) / f"{rf.name}.png"
            with atomic_path(target) as tmp:
                tmp.write_bytes(rf.png)
            print(f"wrote {target}")
        if report:
            figures.append(rf)
    if report:
        print(f"wrote {write_report(tree, report, figures)}")


def plot(args: argparse.Namespace) -> int:
    from contact.io import read_netcdf
    from contact.plots import plot_analysis

    tree = read_netcdf(args.file, tree=True)
    for p in plot_analysis(tree, args.plots, workers=min(2, os.cpu_count() or 1)):
        print(f"wrote {p}")
    return 0
