"""``ltca compare-solvers``: every solver backend on a contact problem set, as a table."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from contact.commands.options import (
    count,
    misalignment_options,
    output_option,
    progress_option,
    rolls_per_cycle_option,
    torque_option,
)
from contact.commands.output_paths import check_output_file
from geometry import __version__

#: Place in ``ltca --help``.
ORDER = 90


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "compare-solvers",
        help="run every solver backend on a problem set and print a comparison",
        description="Run every available solver backend on the standard contact "
        "problem set (Hertz problems, random LTCA-like instances), on a case's real LTCA "
        "problems (CASE) or on an exported set (--problems DIR, from `ltca export-problems`) "
        "and print a qpbenchmark-style table; -o writes the results with the solver "
        "versions, CPU and BLAS.",
    )
    p.add_argument("case", nargs="?", default=None, metavar="CASE",
                   help="case file or bundled case name (`ltca cases`): run on its real LTCA "
                        "problems (default: the standard problem set)")
    p.add_argument("--problems", metavar="DIR",
                   help="run on a problem set written by `ltca export-problems -o DIR` "
                   "(with --with-standard also the standard set)")
    p.add_argument("--quick", action="store_true", help="a small problem set (N <= 250)")
    torque_option(p, default="with CASE: the case's [operating] torques")
    misalignment_options(p, default="with CASE: the case's [operating] values")
    rolls_per_cycle_option(p, default=20)
    p.add_argument("--with-standard", action="store_true",
                   help="with CASE or --problems: also run the standard problem set")
    p.add_argument(
        "--solvers",
        nargs="+",
        metavar="NAME",
        help="solver names (default: every installed one but the cvxpy:NAME variants; "
        "those not installed are listed with their install line)",
    )
    p.add_argument("--accuracy", choices=["high", "default", "low"], default="high")
    p.add_argument(
        "--no-polish",
        action="store_true",
        help="report backends' raw answers (no exact polishing on their contact set)",
    )
    p.add_argument(
        "--repeats",
        type=count(1, 100),
        default=None,
        help="runs per (solver, problem); the fastest counts (default 3 with --quick, else 1)",
    )
    progress_option(p)
    output_option(p, default="none: the table only", what="netCDF file of the full results")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.qp.benchmark_problems import standard_problem_set
    from contact.qp.solver_study import (
        compare_solvers,
        default_study_solvers,
        not_installed_text,
        summarize,
    )
    from geometry.core.io import write_netcdf

    if args.output:
        check_output_file(args.output)
    if args.case is not None and args.problems is not None:
        from geometry.core.errors import InputError

        raise InputError("--problems: give either a CASE or --problems DIR, not both")
    if args.problems is not None:
        from contact.qp.problem_files import read_problem_set

        problems = read_problem_set(args.problems)
        if args.with_standard:
            problems += standard_problem_set(quick=args.quick)
    elif args.case is not None:
        from contact.catalogue import resolve_case
        from contact.commands.export_problems import case_problems
        from contact.commands.options import misalignment_from_args
        from contact.ltca import LTCAOptions

        case = resolve_case(args.case)
        mis = misalignment_from_args(args, case.misalignment)
        torques = args.torque or list(case.operating.torque)
        opts = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle)
        print(f"collecting the LTCA problems of {case.name} at T_p = {torques} N m ...")
        problems = case_problems(args.case, torques, mis, opts)
        if args.with_standard:
            problems += standard_problem_set(quick=args.quick)
    else:
        problems = standard_problem_set(quick=args.quick)
    solvers = args.solvers or default_study_solvers()
    missing = not_installed_text()
    if missing:
        print(f"not installed here: {missing}")
    print(
        f"hypoid-ltca {__version__}: {len(solvers)} solvers x {len(problems)} problems "
        f"(N = {min(p.problem.size for p in problems)}...{max(p.problem.size for p in problems)}), "
        f"accuracy {args.accuracy}, polish {'on' if not args.no_polish else 'off'}"
    )
    results = compare_solvers(
        problems,
        solvers,
        accuracy=args.accuracy,
        polish=not args.no_polish,
        repeats=args.repeats if args.repeats is not None else (3 if args.quick else 1),
        progress=not args.no_progress,
    )
    summary = summarize(results)
    at = results.attrs
    print(f"on {at['cpu']} ({at['cpu_count']} CPUs), {at['platform']}, Python {at['python']}; "
          f"BLAS during the study: {at['blas']}")
    rows = [
        (
            str(s),
            str(summary.solver_family.sel(solver=s).item()),
            f"{summary.success_rate.sel(solver=s).item():.1f}",
            f"{summary.time_relative.sel(solver=s).item():.2f}",
            f"{summary.time_relative_qpbenchmark.sel(solver=s).item():.2f}",
            f"{summary.time_shgeom.sel(solver=s).item():.3g}",
            f"{summary.worst_residual.sel(solver=s).item():.1e}",
            f"{summary.worst_force_error.sel(solver=s).item():.1e}",
            f"{summary.polished_rate.sel(solver=s).item():.0f}",
        )
        for s in summary.solver.values
    ]
    print(
        tabulate(
            rows,
            headers=[
                "solver",
                "family",
                "success [%]",
                "time / best",
                "qpbenchmark shm",
                "shgeom time [ms]",
                "worst residual",
                "worst force err",
                "polished [%]",
            ],
            tablefmt="github",
        )
    )
    print(
        "\nsuccess: certified by the toolkit's residuals "
        f"(tolerance {results.attrs['tolerance']:.0e}); "
        f"time: shifted geometric mean over the best (shift {summary.attrs['shift_ms']} ms; "
        "qpbenchmark shm: qpbenchmark's shift of 10 s), failures charged "
        f"{summary.attrs['time_limit_s']} s; force error against the exact active-set solver."
    )
    if args.output:
        path = write_netcdf(results, Path(args.output), inputs=" ".join(sys.argv[1:]))
        print(f"wrote {path}")
    return 0
