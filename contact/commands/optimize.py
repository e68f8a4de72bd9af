"""``ltca optimize``: pinion machine settings (and profile relief) for a loaded target.

Reads the case and its ``[optimize]`` table (command-line options replace its fields) —
or a basic design file (``cases/basic``), synthesised, whose flank prescriptions may then be
variables too (each design re-synthesised),
minimises the objective of :mod:`contact.optimize` over the chosen variables with every
design analysed by the loaded TCA (on Dask), writes the best design as a new case with an
``[optimize]`` provenance table and every evaluation into the netCDF group ``/optimize``
(both atomically). See ``docs/optimize.md``.
"""

from __future__ import annotations

import argparse
import math
import os
import shlex
import tomllib
from pathlib import Path

from contact.commands import options
from contact.commands.options import count
from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 36

_HEADER = ("# Written by `ltca optimize` (contact.optimize): {case} with optimised pinion "
           "settings;\n# see the [optimize] table and docs/optimize.md.\n")
_HEADER_BASIC = ("# Written by `ltca optimize` (contact.optimize): {case} re-synthesised from "
                 "its basic design with optimised\n# prescriptions and settings; see the "
                 "[optimize] table and docs/optimize.md.\n")


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    from contact.optimize.methods import METHODS

    p = sub.add_parser(
        "optimize",
        help="optimise the pinion's machine settings / profile relief for a loaded target; "
             "write the new case",
        description="Minimise LTE peak-to-peak, edge load share, flank peak pressure and "
        "the pattern's offset over torques and misalignments, subject to engineering "
        "limits, by varying pinion settings within bounds; every design is analysed by the "
        "loaded TCA. Options replace the fields of the case's [optimize] table "
        "(docs/optimize.md). Infeasible limits are reported with the best design found.",
    )
    options.case_argument(p, what="optimise")
    options.output_option(p, default="<case>_optimized.toml", what="optimised case file (TOML)")
    p.add_argument("--name", default=None,
                   help="name of the new case (default <case>_optimized)")
    p.add_argument("--log", default=None, metavar="FILE",
                   help="netCDF log of every evaluation, group /optimize (default: the "
                        "output with suffix .nc)")
    p.add_argument("--variable", nargs=3, action="append", default=None,
                   metavar=("NAME", "LOW", "HIGH"),
                   help="a variable and its bounds in its unit (deg, mm, um, 1/rad ...); "
                        "repeatable; replaces the table's variables")
    options.torque_option(p, default="the [optimize] table's, else the case's [operating]")
    options.misalignment_options(p, default="the [optimize] table's misalignments, else the "
                                 "case's; any given: this one assembly, the others 0")
    p.add_argument("--max-edge-share", type=float, nargs="+", default=None, metavar="SHARE",
                   help="largest edge load share per torque, a fraction of the torque in "
                        "[0, 1] (0.02 = 2 %%, the share the tables print in %%; one value or "
                        "one per torque)")
    p.add_argument("--max-flank-pressure", type=float, nargs="+", default=None,
                   metavar="MPA", help="largest flank peak pressure [MPa] per torque")
    p.add_argument("--lte-pp-range", type=float, nargs=2, default=None,
                   metavar=("LOW", "HIGH"), help="LTE peak-to-peak range [urad]")
    p.add_argument("--method", choices=list(METHODS), default=None,
                   help="optimiser (default differential_evolution)")
    p.add_argument("--max-evaluations", type=count(2, 1_000_000), default=None, metavar="N",
                   help="designs to analyse at most (default 200)")
    p.add_argument("--seed", type=count(0, 2**32 - 1), default=None, help="random seed (default 0)")
    p.add_argument("--confirm", type=count(0, 1000), default=3, metavar="N",
                   help="designs to confirm at most as `ltca run` analyses the written case "
                        "(its sampling, the rating's verdict, the FE mesh of the pinion "
                        "tooth), best first, until one meets every constraint (default 3; "
                        "0: report the optimiser's own ranking, unconfirmed)")
    options.solver_option(p)
    p.add_argument("--flank", choices=["drive", "coast"], default=None)
    options.rolls_per_cycle_option(p)
    options.segments_option(p)
    p.add_argument("--ritz-modes", type=int, nargs=2, default=None,
                   metavar=("N_HEIGHT", "N_FACE"),
                   help="Ritz modes of the tooth shells (default 6 21; fewer build faster)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler address; default a local cluster; 'synchronous' "
                        "runs in this process")
    p.add_argument("--workers", type=count(1, 1024), default=None, metavar="N",
                   help="processes of the local cluster (default one per core)")
    options.progress_option(p)
    p.set_defaults(func=run_optimize, many_analyses=True)


def _start(arg: str | None):
    """(case, basic design or None) of the command's CASE argument: a basic design file
    (it has a ``[design]`` table and no ``[pinion]``/``[gear]``) is synthesised; anything
    else is a case or a bundled name (:func:`contact.catalogue.resolve_case`, which names
    a bad file)."""
    from contact.catalogue import resolve_case

    path = Path(arg) if arg is not None else None
    if path is not None and path.is_file():
        from geometry.core.errors import InputError
        from geometry.core.toml_files import read_toml

        try:
            raw = read_toml(path, "case file")
        except InputError:
            raw = {}  # resolve_case reports it
        # basic data to synthesise: a [design] table and no members (a case carries its
        # [design] beside its [pinion]/[gear] tables for the ISO 10300 rating)
        if isinstance(raw.get("design"), dict) and not {"pinion", "gear"} & raw.keys():
            from geometry.synthesis.basic_design import load_basic
            from geometry.synthesis.case_synthesis import synthesize

            basic = load_basic(path)
            return synthesize(basic)[0], basic
    return resolve_case(arg), None


def _shown(path, case_file) -> str:
    """A path as the provenance records it: relative to the directory of the case file
    that records it (``case_file``), as the bundled cases name their basic file and log
    (a case and its inputs move together, installed or copied), else absolute (another
    drive)."""
    p = Path(path).resolve()
    try:
        return Path(os.path.relpath(p, Path(case_file).resolve().parent)).as_posix()
    except ValueError:
        return str(p)


def _table(case) -> dict:
    t = case.extra.get("optimize", {})
    if "source_case" in t:  # an optimised case: its problem is kept under "problem"
        t = t.get("problem", {})
    return dict(t)


def _outcome(result, confirm: int) -> str:
    """The headline of an optimisation: constraints met only where the confirmation at
    ``ltca run``'s sampling meets them (:mod:`contact.optimize.confirm`)."""
    conf = result.confirmation
    if not confirm:
        return ("all constraints met at the optimiser's sampling (not confirmed: --confirm 0)"
                if result.feasible else "INFEASIBLE: no design met every constraint; the "
                "best design found is written")
    if result.case is None:
        return "no design confirmed: the FE model cannot mesh their pinion teeth"
    if conf is not None and conf.met:
        head = (f"all constraints met, confirmed at ltca run's sampling (design "
                f"{conf.index + 1})")
        if conf.severity == "fail":
            head += f"; but ltca run's verdict is FAIL: {'; '.join(conf.findings)}"
        if conf.index == 0 and any(c.worse_than_start for c in result.confirmations):
            head += ("; the start case is written: every better-ranked design confirmed "
                     f"was judged worse than its {conf.severity.upper()} by ltca run's "
                     "verdict")
        elif conf.worse_than_start:
            head += (f"; but its verdict {conf.severity.upper()} is worse than the start's "
                     f"{conf.start_severity.upper()}")
        return head
    why = f" ({', '.join(conf.violated)})" if conf is not None and conf.violated else ""
    return (f"NOT every constraint met at ltca run's sampling{why}: of "
            f"{len(result.confirmations)} designs confirmed none met them; the best whose "
            "mesh builds is written")


def _variables_hint(synthesis: bool) -> str:
    """The names ``--variable`` takes, each with the unit of its LOW and HIGH: a synthesised
    case carries no ``[optimize.variables]`` table, and the refusal named no variable a
    user could give (round 18, the 9x38 hypoid at Σ 95° fresh from ``ltca synthesize``)."""
    from contact.optimize import RELIEF_VARIABLES, SYNTHESIS_VARIABLES
    from geometry.synthesis.correction import SETTING_VARIABLES

    def listed(units: dict[str, str]) -> str:
        return ", ".join(f"{n} [{u}]" for n, u in units.items())

    text = ("NAME a setting of the pinion flank's tools in its case-file unit ("
            + listed({n: v.unit for n, v in SETTING_VARIABLES.items()})
            + ") or its profile relief (" + listed(RELIEF_VARIABLES) + ")")
    if synthesis:
        text += ", or a synthesis prescription (" + listed(SYNTHESIS_VARIABLES) + ")"
    return text + ", e.g. --variable tip_relief 0 40 --variable 2C -0.05 0.05 (docs/optimize.md)"


def run_optimize(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.commands.synthesize import write_text_atomic
    from contact.optimize import (
        DesignVariable,
        optimize,
        optimized_case,
        problem_from_table,
    )
    from geometry.case import case_from_dict
    from geometry.core.errors import InputError
    from geometry.core.io import write_netcdf
    from geometry.pair.assembly import Misalignment

    out = check_output_file(options.default_output(args, "_optimized.toml"),
                            create_parents=True)
    log_path = check_output_file(args.log if args.log else out.with_suffix(".nc"),
                                 option="--log")
    case, basic = _start(args.case)
    table = dict(basic.optimize) if basic is not None else _table(case)
    # torques: the option, else the [optimize] table's, else the case's [operating] ones
    # (on the coast flank none above its coast design torque, as ltca run: flank_torques)
    from contact.pipeline import flank_torques

    torque = args.torque or (None if "torque" in table
                             else flank_torques(case, args.flank)[0])
    override: dict = {"torque": torque, "max_edge_share": args.max_edge_share,
                      "max_flank_pressure": args.max_flank_pressure,
                      "lte_peak_to_peak_range": args.lte_pp_range, "flank": args.flank}
    if any(v is not None for v in (args.dE, args.dP, args.dG, args.dSigma)):
        override["misalignments"] = (Misalignment(
            delta_E=args.dE or 0.0, delta_P=args.dP or 0.0, delta_G=args.dG or 0.0,
            delta_Sigma=math.radians(args.dSigma or 0.0)),)
    opt_kw = {k: v for k, v in (("rolls_per_cycle", args.rolls_per_cycle),
                                ("segments", args.segments), ("solver", args.solver))
              if v is not None}
    if args.ritz_modes:
        opt_kw |= dict(zip(("n_height", "n_face"), args.ritz_modes, strict=True))
    if opt_kw:  # laid over the table's sampling by problem_from_table
        override["options"] = opt_kw
    problem, run = problem_from_table(table, **override)
    bounds = run["variables"]
    if args.variable:
        bounds = {}
        for name, low, high in args.variable:
            try:
                bounds[name] = (float(low), float(high))
            except ValueError:
                raise InputError(f"--variable {name}: LOW and HIGH must be numbers, got "
                                 f"{low!r} {high!r}") from None
    if not bounds:
        raise InputError("variables: give --variable NAME LOW HIGH or an [optimize.variables] "
                         f"table in the case; {_variables_hint(basic is not None)}")
    start = run.get("start") or {}
    if args.variable:  # the table's start values belong to its variables: those kept that
        # are still varied within the bounds given, the others start from the case
        start = {n: v for n, v in start.items()
                 if n in bounds and bounds[n][0] <= float(v) <= bounds[n][1]}
    variables = [DesignVariable(n, lo, hi) for n, (lo, hi) in bounds.items()]
    result = optimize(
        case, variables, problem,
        method=args.method or run.get("method", "differential_evolution"),
        max_evaluations=(args.max_evaluations if args.max_evaluations is not None
                         else run.get("max_evaluations", 200)),
        popsize=run.get("popsize"), seed=args.seed if args.seed is not None
        else run.get("seed", 0), relief_start=run.get("relief_start"),
        scheduler=args.scheduler, n_workers=args.workers,
        progress=getattr(args, "progress", not args.no_progress), basic=basic, start=start,
        confirm=args.confirm)
    b, s = result.best_evaluation, result.start_evaluation
    print(f"{case.name}: {result.log.sizes['evaluation']} designs in {result.seconds:.1f} s "
          f"({result.method}); {_outcome(result, args.confirm)}")
    for conf in result.confirmations:
        print(f"  design {conf.index + 1} at ltca run's sampling: {conf.summary()}")
    print(tabulate([(n, u, f"{x0:.8g}", f"{x1:.8g}") for n, u, x0, x1 in
                    zip(result.names, result.units, result.start, result.best, strict=True)],
                   headers=["variable", "unit", "start", "result"], tablefmt="github"))
    rows = []
    conf = result.confirmation

    def worst(metrics, k, scale):
        return " / ".join(f"{v:.4g}" for v in scale * metrics[k].max(0))

    for k, unit, scale in (("lte_mean", "urad", 1), ("lte_peak_to_peak", "urad", 1),
                           ("edge_load_share", "%", 100), ("pressure_max_flank", "MPa", 1)):
        rows.append((k, unit, worst(s.metrics, k, scale), worst(b.metrics, k, scale))
                    + ((worst(conf.metrics, k, scale),) if conf is not None else ()))
    rows.append(("objective", "1", f"{s.objective:.5g}", f"{b.objective:.5g}")
                + (("",) if conf is not None else ()))
    print(tabulate(rows, headers=["worst over misalignments, per torque", "unit", "start",
                                  "result"] + (["result at ltca run's sampling"]
                                               if conf is not None else []),
                   tablefmt="github", disable_numparse=True))
    import xarray as xr

    if result.case is None:  # no confirmed design has a tooth the FE model can mesh
        write_netcdf(xr.DataTree.from_dict({"/optimize": result.log}), log_path,
                     inputs=case.to_toml())
        print(f"no case written: none of the {len(result.confirmations)} designs confirmed "
              f"has a pinion tooth the FE model can mesh (ltca run's root stress and ltca "
              f"duty-cycle would fail on it); every evaluation is in {log_path}")
        return 1
    provenance = {"source_file": _shown(args.case, out) if args.case
                  and Path(args.case).is_file() else (args.case or case.name),
                  "log_file": _shown(log_path, out)}
    if getattr(args, "argv", None):  # the command as typed: ltca run's next steps read it
        provenance["command"] = "ltca " + shlex.join(str(a) for a in args.argv)
    if basic is not None:
        provenance["basic_design"] = provenance.pop("source_file")
    new = optimized_case(result, provenance=provenance, name=args.name)
    header = _HEADER if basic is None else _HEADER_BASIC
    text = header.format(case=case.name) + new.to_toml()
    case_from_dict(tomllib.loads(text))  # the written text must load back

    write_netcdf(xr.DataTree.from_dict({"/optimize": result.log}), log_path,
                 inputs=case.to_toml())
    path = write_text_atomic(out, text)
    print(f"wrote {path} and {log_path}")
    return 0
