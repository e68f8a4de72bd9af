"""``ltca duty-cycle``: a load spectrum's efficiency, damage and life (issue 36)."""

from __future__ import annotations

import argparse
import math

from contact.commands.options import (
    case_argument,
    count,
    default_output,
    flank_option,
    output_option,
    plots_option,
    progress_option,
    rolls_per_cycle_option,
    root_stress_option,
    segments_option,
    solver_option,
)
from contact.commands.output_paths import check_output_file
from contact.commands.study import study_progress

#: Place in ``ltca --help``.
ORDER = 16


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "duty-cycle",
        help="analyse a load spectrum (torque bins with speeds, durations and a deflection "
        "table): per-bin LTE, pressure, efficiency; cycle efficiency; flank and root damage "
        "and life (Miner, ISO 6336 S-N curves)",
        description="Each bin of the duty cycle is one analysis at its pinion torque and the "
        "misalignment of the deflection table at that torque (PCHIP, plus the case's own), "
        "with the efficiency at its speed and oil temperature, on the study engine (Dask; "
        "streams to OUTPUT.parts and resumes). Damage by Miner's rule on the ISO 6336-2/-3 "
        "S-N curves of the members' material, one load cycle per tooth mesh. Without "
        "--duty the case's [duty_cycle] table is used, and for a case without one the "
        "bundled ILLUSTRATIVE axle spectrum (7 bins, 10-100 % of the case's top torque; "
        "on the coast flank no more than its coast design torque, as ltca run).",
    )
    case_argument(p, what="analyse")
    p.add_argument("--duty", default=None, metavar="FILE",
                   help="TOML file with a [duty_cycle] table (docs/cases.md)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler of an existing cluster (e.g. tcp://host:8786), or "
                   "'synchronous' (this process); default a local cluster")
    p.add_argument("--workers", type=count(1, 1024), default=None, metavar="N",
                   help="workers of the local cluster (default one per core)")
    flank_option(p)
    solver_option(p)
    rolls_per_cycle_option(p)
    segments_option(p)
    output_option(p, default="<case>_duty_cycle.nc; --flank coast: "
                             "<case>_coast_duty_cycle.nc", what="netCDF file with /duty_cycle")
    plots_option(p)
    p.add_argument("--report", default=None, metavar="HTML",
                   help="also write the duty-cycle report page (as `ltca report` of the "
                   "output file) to HTML")
    root_stress_option(p, "the tooth-root stress of every bin and with it the bending side "
                          "(root damage, life, bending safety factor; ISO 6336-3)")
    progress_option(p)
    p.set_defaults(func=run)


def where_line(scheduler: str | None, workers: int | None, n_bins: int) -> str | None:
    """The line ``ltca duty-cycle`` prints before its bins run where they run on a new
    local Dask cluster (``scheduler`` None): where, on how many worker processes, and that
    starting them comes before the first bin (round 14: 53 s without a line between the
    spectrum and the first bin on a loaded machine); None for an existing cluster or
    ``"synchronous"``.

    Parameters
    ----------
    scheduler : str or None
        ``--scheduler`` as given.
    workers : int or None
        ``--workers`` as given (None: one per core, :func:`os.cpu_count`).
    n_bins : int
        The spectrum's bins [1].

    Returns
    -------
    str or None

    Raises
    ------
    None.

    Notes
    -----
    Source: the project guide ("a silent wait … is not done"); the cluster is
    :func:`contact.study.engine.open_client`'s.
    """
    if scheduler is not None:
        return None
    import os

    n = (os.cpu_count() or 1) if workers is None else int(workers)
    return (f"running the {n_bins} bins on a local Dask cluster of {n} worker "
            f"process{'es' if n != 1 else ''} (--workers, --scheduler); starting them and "
            "their first analysis come before the first bin")


def _fmt(x: float, spec: str) -> str:
    return "inf" if math.isinf(x) else format(x, spec)


def safety_lines(ds) -> list[str]:
    """The lines ``ltca duty-cycle`` prints on its safety factors per bin: the local ones
    (σ_Hlim over the bin's peak flank pressure, σ_FE over its peak fillet stress) beside
    the ISO 10300 rating's S_H, S_F at the bin's torque and speed, pinion / gear; or the
    line saying why the rating is absent; and the bins above the flank's static strength
    (:func:`contact.study.verdicts.duty_static_bins`), whose safeties are of no finite
    life.

    Parameters
    ----------
    ds : xarray.Dataset
        The ``/duty_cycle`` dataset (:func:`contact.study.duty_cycle.run_duty_cycle`).

    Returns
    -------
    list of str
    """
    from tabulate import tabulate

    if "local_contact_safety" not in ds:
        return []
    iso = "iso_contact_safety" in ds
    bending = "local_bending_safety" in ds

    def pair(name: str, i: int) -> str:
        if name not in ds:
            return "-"
        return " / ".join(_fmt(float(v), ".2f") for v in ds[name].values[i])

    rows = [(i, f"{float(ds['torque'].values[i]):g}", f"{float(ds['speed'].values[i]):g}",
             pair("local_contact_safety", i), pair("iso_contact_safety", i),
             pair("local_bending_safety", i), pair("iso_bending_safety", i))
            for i in range(ds.sizes["bin"])]
    allow = ("sigma_HP/Z_NT, sigma_FP/Y_NT of the bin's rating" if iso
             else "sigma_Hlim, sigma_FE")
    lines = [f"safety factors per bin, pinion / gear: local ({allow} over the peak flank "
             "pressure and the peak fillet stress) beside the ISO 10300 rating's"
             + ("" if bending else " (no local S_F: --no-root-stress)") + ":",
             tabulate(rows, headers=["bin", "T [N m]", "n [rpm]", "S_H local", "S_H ISO",
                                     "S_F local", "S_F ISO"], tablefmt="github")]
    lines.append(f"ISO rating: {ds.attrs.get('iso_rating', '')}" if iso
                 else str(ds.attrs.get("iso_rating", "")))
    from contact.study.verdicts import duty_static_bins

    static = duty_static_bins(ds)  # no finite life there: told apart (issue 71, remedy84)
    if static:
        lines.append("bins above the flank's static strength (no life there, the static "
                     "check): " + "; ".join(
                         f"bin {i} ({float(ds['torque'].values[i]):g} N m) flank peak "
                         f"{p:.0f} MPa above {s:.0f} MPa" for i, (p, s) in static.items()))
    return lines


def run(args: argparse.Namespace) -> int:
    import xarray as xr
    from tabulate import tabulate

    from contact.catalogue import resolve_case
    from contact.commands.run import ltca_options
    from contact.study.duty_cycle import bin_table, edge_note, run_duty_cycle
    from contact.study.duty_cycle_inputs import (
        example_duty_cycle,
        illustrative_speed_note,
        read_duty_cycle,
    )
    from contact.study.run import StudyRun
    from geometry.core.errors import InputError
    from geometry.core.io import write_netcdf
    from geometry.core.text import plain_number

    if args.workers is not None and args.workers < 1:
        raise InputError(f"--workers: must be >= 1, got {args.workers}")
    output = default_output(args, "_duty_cycle.nc")
    check_output_file(output)
    if args.report is not None:
        check_output_file(args.report, option="--report")
    case = resolve_case(args.case)
    if args.duty is not None:
        duty = read_duty_cycle(args.duty)
    elif "duty_cycle" in case.extra:
        duty = read_duty_cycle(case)
    else:  # to the flank's own top torque (the coast side's design torque), as the API's
        duty = example_duty_cycle(case=case, flank=args.flank)
    # what will run, before it starts (issue 56): the bins' torques, speeds and hours
    from contact.commands.run import print_wrapped

    print_wrapped(f"duty cycle of {case.name}: {duty.name}, {duty.n_bins} bins: T [N m] "
                  + ", ".join(f"{t:g}" for t in duty.torque) + "; n [rpm] "
                  + ", ".join(f"{n:g}" for n in duty.pinion_speed) + "; t [h] "
                  + ", ".join(plain_number(h) for h in duty.hours))
    where = where_line(args.scheduler, args.workers, duty.n_bins)
    if where:
        print(where, flush=True)
    ds = run_duty_cycle(case, duty, StudyRun(
        options=ltca_options(args), flank=args.flank, output=output,
        scheduler=args.scheduler, n_workers=args.workers, progress=study_progress(args)),
        root_stress=args.root_stress)
    print(f"case {case.name}: {duty.name}, {duty.n_bins} bins, {duty.hours.sum():g} h, "
          f"grade {duty.grade}, Miner {duty.miner_rule}")
    if duty.illustrative:
        print("NOTE: the bundled spectrum and deflection table are ILLUSTRATIVE (made-up "
              "proportions), not a measured drive cycle")
        speed_note = illustrative_speed_note(duty, case.operating.pinion_speed)
        if speed_note:
            print_wrapped(f"NOTE: {speed_note}")
    rows = [(i, f"{r['torque']:g}", f"{r['speed']:g}", plain_number(r['hours']),
             f"{r['lte_mean']:.1f}", f"{r['lte_peak_to_peak']:.2f}",
             f"{r['pressure_max_flank']:.0f}", f"{100 * r['edge_load_share']:.1f}",
             _fmt(r['pressure_max_edge'], '.0f') if r['edge_load_share'] > 0 else "-",
             f"{100 * r['efficiency']:.3f}", f"{r['power_loss']:.1f}")
            for i, r in enumerate(bin_table(ds))]
    print(tabulate(rows, headers=["bin", "T [N m]", "n [rpm]", "t [h]", "LTE [urad]",
                                  "LTE p-p [urad]", "p_max flank [MPa]", "edge [%]",
                                  "p_max edge [MPa]", "eff [%]", "loss [W]"],
                   tablefmt="github"))
    note = edge_note(ds)
    if note:
        print(note)
    print(f"cycle: energy in {float(ds['cycle_energy_in']):.1f} kW h, lost "
          f"{float(ds['cycle_energy_lost']):.3f} kW h, efficiency "
          f"{100 * float(ds['cycle_efficiency']):.3f} %")
    for k, m in enumerate(ds["member"].values):
        line = (f"{m}: flank damage {float(ds['damage'][k]):.3g}, pitting life "
                f"{_fmt(float(ds['life'][k]), '.4g')} h at u = {float(ds['life_u'][k]):.2f}, "
                f"v = {float(ds['life_v'][k]):.2f}, S_H = "
                f"{float(ds['contact_safety_factor'][k]):.2f}")
        if "root_life" in ds:
            line += (f"; root damage {float(ds['root_damage_max'][k]):.3g}, bending life "
                     f"{_fmt(float(ds['root_life'][k]), '.4g')} h, S_F = "
                     f"{float(ds['bending_safety_factor'][k]):.2f} (life factor 1, "
                     "against 1)")
        if "root_stress_safety" in ds:  # ltca run's quantity and minimum (issue 71)
            line += (f"; S_F,FE {float(ds['root_stress_safety'][:, k].min()):.2f} against "
                     f"S_Fmin {float(ds['bending_safety_min']):g} as ltca run judges it")
        print(line)
    if "root_life" not in ds:
        print(f"bending side {ds.attrs['bending']}")
    if ds.attrs.get("allowables"):
        print_wrapped(f"allowables: {ds.attrs['allowables']}")
    for line in safety_lines(ds):
        print(line)
    from contact.commands.run import print_verdict

    print_verdict(ds)
    import textwrap

    from contact.commands.next_steps import duty_cycle_lines
    from contact.study.verdicts import verdict

    fails = [f.check for f in verdict(ds).findings if f.severity == "fail"]
    for line in duty_cycle_lines(ds, args.case or case.name, args.flank, fails, case):
        # under the verdict's findings, as ltca run's; the commands unwrapped, to paste
        print(line if line.startswith("    ltca ") else
              textwrap.fill(line, 100, subsequent_indent="      "))
    tree = xr.DataTree.from_dict({"/duty_cycle": ds})
    path = write_netcdf(tree, output, inputs=case.to_toml())
    from contact.study.store import ResultStore

    ResultStore.remove_parts(output)
    print(f"wrote {path}")
    if args.plots:
        from pathlib import Path

        from contact.study.duty_cycle_figures import save_duty_cycle_figures

        Path(args.plots).mkdir(parents=True, exist_ok=True)
        for fig in save_duty_cycle_figures(ds, args.plots):
            print(f"wrote {fig}")
    if args.report is not None:
        from contact.plots.duty_report import write_duty_report

        print(f"wrote {write_duty_report(ds, args.report)}")
    return 0
