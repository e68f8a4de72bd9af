"""``ltca sweep``, ``ltca tolerance`` and ``ltca vh-check``: design studies on Dask.

Ranges are typed ``START:STOP:N`` (N values, ends included) — the only form of a range —,
a single value, or values separated by commas (``-0.2,0.2,5`` is the three values −0.2,
0.2 and 5, not a range); distributions ``normal:MEAN:STD``, ``uniform:LOW:HIGH``,
``truncnormal:MEAN:STD:LOW:HIGH`` or ``triangular:LOW:MODE:HIGH``. Lengths in mm, ΔΣ in
degrees (as ``ltca run``). Every study prints the values it will run before it starts;
a misalignment beyond the plausible range of the pair's blanks
(:func:`contact.ltca.plausibility.misalignment_limits`) is refused unless ``--force``, and
each point's plausibility (the causes ``ltca run`` warns of) is flagged in the output's
``plausibility`` and counted in the summary. ``--scheduler tcp://host:8786`` runs on an
existing Dask cluster; by default a local cluster of ``--workers`` processes (one per core).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import TYPE_CHECKING

from contact.commands.options import (
    case_argument,
    compliance_option,
    count,
    default_output,
    flank_option,
    misalignment_options,
    output_option,
    plots_option,
    progress_option,
    rolls_per_cycle_option,
    root_stress_option,
    solver_option,
    torque_option,
)
from contact.commands.output_paths import check_output_dir, check_output_file
from contact.commands.run import print_verdict
from contact.study.sample_size import DEFAULT_SAMPLES, SAMPLES_RANGE
from geometry.core.errors import InputError
from geometry.core.text import plain_number

if TYPE_CHECKING:
    import numpy as np

#: Place in ``ltca --help``.
ORDER = 45

#: CLI option → the unit it is typed in
_TYPED_UNITS = {"dE": "mm", "dP": "mm", "dG": "mm", "dSigma": "deg", "deviation_scale": "1"}

#: CLI option → (study input, factor from the typed unit to the input's unit)
_INPUT_OPTIONS = {
    "dE": ("delta_E", 1.0),
    "dP": ("delta_P", 1.0),
    "dG": ("delta_G", 1.0),
    "dSigma": ("delta_Sigma", math.pi / 180.0),
    "deviation_scale": ("deviation_scale", 1.0),
}


def study_progress(args: argparse.Namespace) -> bool | str:
    """A study command's ``progress``: True (a bar: standard error is a terminal),
    ``"lines"`` (plain periodic lines: it is not) or False (``-q``, ``--no-progress``), as
    :func:`contact.cli.main` decided (:mod:`geometry.core.progress`); for arguments that
    did not pass through it, a bar unless ``--no-progress``."""
    return getattr(args, "progress", not getattr(args, "no_progress", False))


def parse_range(option: str, text: str) -> np.ndarray:
    """Values of ``START:STOP:N``, ``X`` or ``X,Y,…`` (InputError naming ``option``)."""
    import numpy as np

    try:
        if ":" in text:
            parts = text.split(":")
            if len(parts) != 3:
                raise ValueError
            start, stop, n = float(parts[0]), float(parts[1]), int(parts[2])
            if n < 1 or (n == 1 and start != stop):
                raise ValueError
            values = np.linspace(start, stop, n)
        else:
            values = np.array([float(x) for x in text.split(",")])
    except ValueError:
        raise InputError(f"{option}: expected START:STOP:N (N >= 2 values), a number or "
                         f"numbers separated by commas, got {text!r}") from None
    if not np.all(np.isfinite(values)):
        raise InputError(f"{option}: values must be finite, got {text!r}")
    return values


def values_line(option: str, text: str, values: np.ndarray, unit: str) -> str:
    """The line a study prints for one swept input before it starts: its values, and —
    for a comma list of three whose last is a whole number >= 2, such as ``-0.2,0.2,5`` —
    that a comma list is values and a range ``START:STOP:N``."""
    shown = ", ".join(f"{x:g}" for x in values[:12]) + (" ..." if values.size > 12 else "")
    line = f"  {option} [{unit}]: {values.size} value{'s' * (values.size != 1)}: {shown}"
    parts = text.split(",")
    if ":" not in text and len(parts) == 3:
        try:
            last = float(parts[2])
        except ValueError:
            return line
        if last >= 2 and last == int(last):
            line += (f"  (a comma list is values; the range of {int(last)} values from "
                     f"{parts[0]} to {parts[1]} is {parts[0]}:{parts[1]}:{int(last)})")
    return line


def _common(p: argparse.ArgumentParser, *, many_torques: bool = True) -> None:
    case_argument(p, what="study")
    if many_torques:
        torque_option(p)
        p.add_argument("--speed", type=float, nargs="+", default=None, metavar="RPM",
                       help="pinion speeds [rpm]: adds efficiency and power loss (oil, "
                            "temperature, roughness: the case's [operating] table)")
    solver_option(p)
    flank_option(p)
    rolls_per_cycle_option(p)
    compliance_option(p)
    output_option(p, default="<case>_<study>.nc (--flank coast: "
                             "<case>_coast_<study>.nc); finished points stream to FILE.parts/ and "
                  "a killed study started again resumes")
    plots_option(p)
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler of an existing cluster (e.g. tcp://host:8786); "
                        "default a local cluster; 'synchronous' runs in this process")
    p.add_argument("--workers", type=count(1, 1024), default=None, metavar="N",
                   help="processes of the local cluster (default one per core)")
    p.add_argument("--force", action="store_true",
                   help="run points whose misalignment is beyond the plausible range of the "
                        "blanks (5 %% of the face width; flagged in the output's "
                        "plausibility) instead of refusing them")
    progress_option(p)


def _root_stress_option(p: argparse.ArgumentParser) -> None:
    root_stress_option(p, "the peak tooth-root stress of both members at every point "
                          "(root_stress_max), the coefficients built once per design and "
                          "handed to every worker")


def register(sub) -> None:
    """Add the study sub-commands to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "sweep", help="misalignment map: LTCA over a grid of dE, dP, dG, dSigma (Dask)",
        description="Loaded TCA over a full grid of misalignments (and deviation scales), "
        "torques and speeds, on Dask; prints the range of each summary, writes one "
        "netCDF and, with --plots, maps over the first two swept inputs.")
    _common(p)
    misalignment_options(p, kind="range", default="the case's [operating] value; e.g. "
                         "-0.2:0.2:21")
    p.add_argument("--deviation-scale", metavar="RANGE",
                   help="factors on the case's [deviations] (0 theoretical, 1 measured)")
    _root_stress_option(p)
    p.set_defaults(func=sweep_command, many_analyses=True, study="sweep")

    t = sub.add_parser(
        "tolerance", help="Monte Carlo tolerance analysis of misalignments (Dask)",
        description="Loaded TCA at N draws of the misalignments from the given "
        "distributions (Sobol', Latin hypercube or random); prints percentiles of LTE p-p, "
        "peak pressure, edge share and efficiency and which input drives their spread.")
    _common(t)
    misalignment_options(t, kind="distribution", default="the case's [operating] value; "
                         "a distribution e.g. normal:0:0.05")
    t.add_argument("--deviation-scale", metavar="DIST",
                   help="distribution of the factor on the case's [deviations]")
    t.add_argument("-n", type=count(*SAMPLES_RANGE), default=DEFAULT_SAMPLES,
                   help="number of draws (default %(default)s)")
    t.add_argument("--method", choices=["sobol", "lhs", "random"], default="sobol",
                   help="how the draws are placed: scrambled Sobol or Latin-hypercube "
                        "quasi-random points (scipy.stats.qmc), or plain random (default "
                        "%(default)s)")
    t.add_argument("--seed", type=count(0, 2**32 - 1), default=0,
                   help="random seed (default %(default)s)")
    _root_stress_option(t)
    t.set_defaults(func=tolerance_command, many_analyses=True, study="tolerance")

    v = sub.add_parser(
        "vh-check", help="V-H check: offset (V) and pinion mounting (H) moving the pattern "
        "to toe and heel",
        description="Maps the loaded pattern centre over a V (= dE) x H (= dP) grid about the "
        "case's mounting (its [operating] dE, dP) on Dask and solves for the displacements "
        "that put it at the toe and heel targets at the nominal pattern's height; each "
        "solution is checked by a single analysis.")
    _common(v, many_torques=False)
    torque_option(v, many=False, default="the first of the case's [operating] torques, 50 "
                  "for the default case")
    v.add_argument("--toe", type=float, default=None,
                   help="toe target of the pattern centre, face-width fraction (default 0.25)")
    v.add_argument("--heel", type=float, default=None,
                   help="heel target, face-width fraction (default 0.75)")
    v.add_argument("--profile", type=float, default=None,
                   help="height the centre keeps, depth fraction (default the nominal's)")
    misalignment_options(v, kind="range", extra={
        "dE": "V grid, offset change dE [mm] (default the case's dE +/- 0.4 mm, 9 values)",
        "dP": "H grid, pinion axial dP [mm] (default the case's dP +/- 0.3 mm, 7 values)"})
    v.set_defaults(func=vh_check_command, many_analyses=True, study="vh_check")


def _prepare(args: argparse.Namespace) -> tuple:
    """Output paths checked first; the keyword arguments every study takes."""
    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study import StudyRun

    out = Path(default_output(args, f"_{args.study}.nc"))
    check_output_file(out)
    if args.plots:
        check_output_dir(args.plots)
    case = resolve_case(args.case)
    if args.workers is not None and args.workers < 1:
        raise InputError(f"--workers: must be >= 1, got {args.workers}")
    kw = {}
    if args.solver:
        kw["solver"] = args.solver
    if args.rolls_per_cycle is not None:
        kw["rolls_per_cycle"] = args.rolls_per_cycle
    if args.compliance is not None:
        kw["compliance"] = args.compliance
    run = StudyRun(options=LTCAOptions(**kw), flank=args.flank, output=out,
                   scheduler=args.scheduler, n_workers=args.workers,
                   progress=study_progress(args),
                   root_stress=bool(getattr(args, "root_stress", True)),
                   force=bool(getattr(args, "force", False)))
    return case, run


def _plots(ds, args) -> None:
    if args.plots:
        from contact.study.figures import save_study_figures

        for path in save_study_figures(ds, args.plots):
            print(f"wrote {path}")


def _torques(args: argparse.Namespace, case) -> list[float]:
    """``--torque``, else the case's ``[operating]`` torques (as ``ltca run`` takes them)."""
    return list(args.torque) if args.torque else list(case.operating.torque)


#: summaries the tables show in other units than the file: name → (factor, units), so
#: efficiency and edge share read in % as in every other table of the toolkit
_SHOWN = {"efficiency": (100.0, "%"), "edge_load_share": (100.0, "%")}


def _shown(name: str, x: np.ndarray, units: str) -> tuple[np.ndarray, str]:
    import numpy as np

    factor, shown = _SHOWN.get(name, (1.0, units))
    return np.asarray(x, float) * factor, shown


def _ranges_table(ds) -> str:
    import numpy as np
    from tabulate import tabulate

    names = [n for n in ("lte_mean", "lte_peak_to_peak", "pressure_max_flank",
                         "pressure_max_edge", "edge_load_share", "pattern_centre_u",
                         "pattern_centre_v", "efficiency") if n in ds]
    rows = []
    for t in ds["torque"].values:
        for n in names:
            x = ds[n].sel(torque=t).values.astype(float)
            x, units = _shown(n, x[np.isfinite(x)], ds[n].attrs.get("units", ""))
            if x.size:
                rows.append((plain_number(t), n, units, f"{x.min():.4g}",
                             f"{np.median(x):.4g}", f"{x.max():.4g}"))
        for m, x in _root_stress_values(ds, t):
            rows.append((plain_number(t), f"root_stress_max {m}", "MPa", f"{x.min():.4g}",
                         f"{np.median(x):.4g}", f"{x.max():.4g}"))
    return tabulate(rows, headers=("T_p [N m]", "summary", "units", "min", "median", "max"),
                    tablefmt="github")


def _root_stress_values(ds, torque: float) -> list:
    """(member, finite peak root stresses [MPa] of the points that did not fail) at one
    torque; none without ``root_stress_max``."""
    import numpy as np

    if "root_stress_max" not in ds:
        return []
    ok = ds["status"] != 2
    out = []
    for m in ds["member"].values:
        x = ds["root_stress_max"].sel(torque=torque, member=m).where(ok).values.ravel()
        x = x[np.isfinite(x)]
        if x.size:
            out.append((str(m), x))
    return out


def _status_line(ds) -> str:
    st = ds["status"].values.ravel()
    line = (f"{st.size} points: {(st == 0).sum()} certified, {(st == 1).sum()} partly "
            f"uncertified, {(st == 2).sum()} failed")
    if (st == 2).any():
        reasons = sorted(set(ds["reason"].values.ravel()[st == 2]))
        line += "\n  " + "\n  ".join(reasons[:5])
    line += "\n" + plausibility_line(ds)
    # what the summary printed but no limit judged, in the verdicts' words (issue 71)
    from contact.study.verdicts import not_checked_line, study_not_checked

    line += "".join("\n" + not_checked_line(checks, why).strip()
                    for checks, why in study_not_checked(ds))
    if ds.attrs.get("points_resumed"):
        line += f"\n(resumed: {ds.attrs['points_resumed']} points from an interrupted run)"
    return line


def plausibility_line(ds, name: str = "plausibility", what: str = "points") -> str:
    """How many points a study flagged implausible, and for which causes
    (:data:`contact.ltca.plausibility.CAUSES`: the bits of ``name``, any torque)."""
    import numpy as np

    from contact.ltca.plausibility import CAUSES

    if name not in ds:
        return f"plausibility: not recorded (a file written before {name!r})"
    flags = ds[name]
    other = [d for d in flags.dims if d == "torque"]
    bits = np.bitwise_or.reduce(flags.values.astype(np.int64), axis=flags.get_axis_num(
        other[0])) if other else flags.values.astype(np.int64)
    bits = np.ravel(bits)
    n = int(np.count_nonzero(bits))
    if n == 0:
        return (f"plausibility: all {bits.size} {what} plausible (none flagged for plastic "
                "contact, flank above the material's limit, LTE spread or a misalignment "
                "beyond the blank)")
    causes = ", ".join(f"{_CAUSE_WORDS.get(c, c)} {int(np.count_nonzero(bits & (1 << k)))}"
                       for k, c in enumerate(CAUSES) if np.any(bits & (1 << k)))
    per = ", per torque" if other else ""
    return (f"WARNING: plausibility: {n} of {bits.size} {what} flagged implausible "
            f"({causes}; the variable {name} says which{per}; the causes are those "
            "`ltca run` warns of)")


#: the causes of contact.ltca.plausibility.CAUSES as the summary line says them
_CAUSE_WORDS = {"plastic_contact": "plastic contact", "flank_above_limit": "flank above limit",
                "lte_spread": "LTE spread",
                "misalignment_beyond_blank": "misalignment beyond blank"}


def sweep_command(args: argparse.Namespace) -> int:
    from contact.study import sweep

    case, run = _prepare(args)
    axes, lines = {}, []
    for opt, (name, factor) in _INPUT_OPTIONS.items():
        text = getattr(args, opt)
        if text is not None:
            option = f"--{opt.replace('_', '-')}"
            typed = parse_range(option, text)
            lines.append(values_line(option, text, typed, _TYPED_UNITS[opt]))
            axes[name] = typed * factor
    if not axes:
        raise InputError("sweep: give at least one of --dE, --dP, --dG, --dSigma, "
                         "--deviation-scale")
    torques = _torques(args, case)
    n = math.prod(v.size for v in axes.values())
    print(f"sweep of {case.name}: {n} points (" + " x ".join(f"{k} {v.size}" for k, v in
                                                           axes.items())
          + f") at T_p {', '.join(f'{plain_number(t)}' for t in torques)} N m", flush=True)
    print("\n".join(lines), flush=True)
    ds = sweep(case, torque=torques, pinion_speed=args.speed, **axes, run=run)
    print(_ranges_table(ds))
    print(_status_line(ds))
    print(f"wrote {run.output}")
    _plots(ds, args)
    return 0


def tolerance_command(args: argparse.Namespace) -> int:
    import numpy as np
    from tabulate import tabulate

    from contact.study import draw_points, parse_distribution, sample, sensitivity
    from contact.study.monte_carlo import draw_values

    case, run = _prepare(args)
    dists = {}
    for opt, (name, factor) in _INPUT_OPTIONS.items():
        text = getattr(args, opt)
        if text is not None:
            dists[name] = parse_distribution(f"--{opt.replace('_', '-')}", text, factor)
    if not dists:
        raise InputError("tolerance: give the distribution of at least one of --dE, --dP, "
                         "--dG, --dSigma, --deviation-scale")
    torques = _torques(args, case)
    print(f"tolerance analysis of {case.name}: {args.n} draws ({args.method}, seed "
          f"{args.seed}) of " + ", ".join(dists)
          + f" at T_p {', '.join(f'{plain_number(t)}' for t in torques)} N m", flush=True)
    # the draws sample() will make (same distributions, method and seed): their range
    draws = draw_points(dists, args.n, method=args.method, seed=args.seed)
    for opt, (name, factor) in _INPUT_OPTIONS.items():
        if name in draws:
            x = draws[name] / factor
            p5, p50, p95 = np.percentile(x, (5, 50, 95))
            print(f"  --{opt.replace('_', '-')} [{_TYPED_UNITS[opt]}]: {getattr(args, opt)}: "
                  f"draws from {x.min():.4g} to {x.max():.4g} (P5 {p5:.4g}, P50 {p50:.4g}, "
                  f"P95 {p95:.4g})", flush=True)
    ds = sample(case, dists, args.n, method=args.method, seed=args.seed,
                torque=torques, pinion_speed=args.speed, run=run)
    ok = ds["status"].values != 2
    rows = []
    for t in ds["torque"].values:
        for n in ("lte_peak_to_peak", "pressure_max_flank", "pressure_max_edge",
                  "edge_load_share", "efficiency"):
            if n not in ds:
                continue
            x, units = _shown(n, draw_values(ds, n, t), ds[n].attrs.get("units", ""))
            if x.size:
                p5, p50, p95 = np.percentile(x, (5, 50, 95))
                rows.append((plain_number(t), n, units, f"{p5:.4g}",
                             f"{p50:.4g}", f"{p95:.4g}", f"{x.mean():.4g}", f"{x.std():.3g}"))
        for m, x in _root_stress_values(ds, t):
            p5, p50, p95 = np.percentile(x, (5, 50, 95))
            rows.append((plain_number(t), f"root_stress_max {m}", "MPa", f"{p5:.4g}", f"{p50:.4g}",
                         f"{p95:.4g}", f"{x.mean():.4g}", f"{x.std():.3g}"))
    print(tabulate(rows, headers=("T_p [N m]", "summary", "units", "P5", "P50", "P95", "mean",
                                  "std"), tablefmt="github"))
    if ok.sum() > len(dists) + 2:
        sens = sensitivity(ds, "lte_peak_to_peak")
        srows = []
        for t in ds["torque"].values:
            s = sens.sel(torque=t)
            for name in s["input"].values:
                srows.append((plain_number(t), name, f"{float(s['spearman'].sel(input=name)):+.2f}",
                              f"{float(s['src'].sel(input=name)):+.2f}",
                              f"{float(s['r_squared']):.2f}"))
        print("what drives the spread of LTE p-p (rank correlation, standardised "
              "regression coefficient, R^2 of the linear fit):")
        print(tabulate(srows, headers=("T_p [N m]", "input", "Spearman", "SRC", "R^2"),
                       tablefmt="github"))
    print(_status_line(ds))
    print(f"wrote {run.output}")
    _plots(ds, args)
    return 0


def _or_dash(x: float) -> str:
    """A target to three decimals, "-" where there is none (the nominal row)."""
    return f"{x:.3f}" if math.isfinite(x) else "-"


def vh_check_command(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.study import vh_check
    from contact.study.vh_check import VH_DEFAULT_GRID, VH_DEFAULT_LIMITS, default_vh_torque

    case, run = _prepare(args)
    kw = {}
    if args.dE is not None:
        kw["delta_E"] = parse_range("--dE", args.dE)
    if args.dP is not None:
        kw["delta_P"] = parse_range("--dP", args.dP)
    torque = args.torque or default_vh_torque(case)  # as contact.vh_check takes it
    nv = len(kw.get("delta_E", VH_DEFAULT_GRID[0]))
    nh = len(kw.get("delta_P", VH_DEFAULT_GRID[1]))
    print(f"V-H check of {case.name} at {plain_number(torque)} N m about its mounting dE "
          f"{case.misalignment.delta_E:g} mm, dP {case.misalignment.delta_P:g} mm: mapping "
          f"the pattern centre over {nv} x {nh} V-H points ({nv * nh} analyses), then 3 "
          "single analyses", flush=True)
    for option, key, default, shift in (
            ("--dE", "delta_E", VH_DEFAULT_GRID[0], case.misalignment.delta_E),
            ("--dP", "delta_P", VH_DEFAULT_GRID[1], case.misalignment.delta_P)):
        grid = kw[key] if key in kw else default + shift
        text = getattr(args, option[2:])
        print(values_line(f"{option} ({'V' if key == 'delta_E' else 'H'})",
                          text if text is not None else "", grid, "mm"), flush=True)
    ds = vh_check(case, torque=torque,
                  toe=VH_DEFAULT_LIMITS[0] if args.toe is None else args.toe,
                  heel=VH_DEFAULT_LIMITS[1] if args.heel is None else args.heel,
                  profile=args.profile, **kw, run=run)
    rows = [(str(p), f"{float(r['V']):+.3f}", f"{float(r['H']):+.3f}",
             _or_dash(float(r['target_u'])), f"{float(r['pattern_centre_u']):.3f}",
             f"{float(r['target_v']):.3f}", f"{float(r['pattern_centre_v']):.3f}",
             f"{float(r['grid_tolerance_u']):.3f}")
            for p, r in ((p, ds.sel(position=p)) for p in ds["position"].values)]
    print(f"V-H check of {case.name} at {plain_number(ds.attrs['torque_N_m'])} N m "
          "(V = dE, H = dP; centre as fractions of face width u and whole depth v)")
    print(tabulate(rows, headers=("position", "V [mm]", "H [mm]", "target u", "centre u",
                                  "target v", "centre v", "grid tol. u"), tablefmt="github"))
    print(plausibility_line(ds, "map_plausibility", "V-H points"))
    print_verdict(ds)
    print(f"wrote {run.output}")
    _plots(ds, args)
    return 0

