"""``ltca friction-study``: the seed's friction study (§5.2.3) — the mixed-EHL line-contact
solver over Table 5.1's conditions on Dask, streamed and resumable."""

from __future__ import annotations

import argparse

from contact.commands.options import count, film_model_options, progress_option
from contact.commands.study import study_progress

#: Place in ``ltca --help``.
ORDER = 61


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "friction-study",
        help="solve the mixed-EHL line contact over the seed's Table 5.1 conditions "
        "(Sobol/LHS sample or the full factorial grid) on Dask",
        description="The seed's friction study (section 5.2.3): every condition of a design "
        "over Table 5.1's box (p_h 0.5-2.5 GPa, R 5-40 mm, u_e 1-20 m/s, SR 0.025-1, oil "
        "25-100 degC, Rq of each surface 0.1-1 um from the ground profile scaled) solved by "
        "friction.ehl; a point the solver does not converge on is kept as failed with its "
        "reason. Finished points stream to OUTPUT.parts/ and the same command started "
        "again resumes. Writes a netCDF of scalars with its provenance (docs/friction.md).",
    )
    p.add_argument("--design", choices=("sobol", "lhs", "factorial"), default="sobol",
                   help="space-filling sample of the box, or Table 5.1's full factorial grid "
                   "(31,500 conditions: a cluster's job) (default %(default)s)")
    p.add_argument("-n", "--points", type=count(1, 10_000_000), default=128, metavar="N",
                   help="conditions of a sobol/lhs design (default %(default)s)")
    p.add_argument("--seed", type=count(0, 2**32 - 1), default=2009,
                   help="seed of the sampler (default %(default)s; held-out points: another "
                   "seed and --design lhs)")
    p.add_argument("--box", choices=("table_5_1", "gear", "gear_flank", "gear_edge"),
                   default="table_5_1",
                   help="sobol/lhs: the seed's Table 5.1 box, or a wider one covering a hypoid "
                   "gear's contacts (gear: p_h 0.3-3 GPa, R 5-150 mm, u_e 0.05-20 m/s, SR "
                   "0.01-2, 25-110 degC, Rq 0.05-1.5 um; gear_flank: p_h from 0.1 GPa, R from "
                   "4 mm, SR from 1e-4), or a rounded tooth edge on a flank (gear_edge: R "
                   "0.3-1 mm, p_h 0.5-5.3 GPa, u_e 0.3-5 m/s, SR 0.2-2) (default %(default)s)")
    p.add_argument("--exclude-box", choices=("table_5_1", "gear"), default=None,
                   metavar="BOX",
                   help="sobol/lhs: pass over the points inside this box (a study that "
                   "extends one already run in it, e.g. --box gear_flank --exclude-box gear)")
    p.add_argument("--skip", type=count(0, 10**9), default=0, metavar="K",
                   help="sobol: continue the sequence after its first K points")
    p.add_argument("--nodes", type=count(64, 16384), default=512,
                   help="solver grid nodes over the rough contact's spread (the stochastic "
                   "solver; the resolved transient and steady models are not offered: "
                   "docs/ehl.md) (default %(default)s)")
    film_model_options(p)
    p.add_argument("--max-iterations", type=count(1, 10000), default=60, metavar="N",
                   help="Newton iterations before a point counts as not converged "
                   "(default %(default)s)")
    p.add_argument("--realisations", type=count(1, 32), default=1, metavar="K",
                   help="roughness realisations per condition, their converged results "
                   "averaged (default %(default)s)")
    p.add_argument("--lubricant", default="75W90", metavar="NAME",
                   help="bundled oil name (default %(default)s)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler of an existing cluster (e.g. tcp://host:8786), or "
                   "'synchronous' (this process); default a local cluster")
    p.add_argument("--workers", type=count(1, 1024), default=None, metavar="N",
                   help="workers of the local cluster (default one per core)")
    p.add_argument("-o", "--output", default="friction_study.nc", metavar="FILE",
                   help="netCDF file to write (default %(default)s)")
    progress_option(p)
    p.set_defaults(func=run, many_analyses=True)


def run(args: argparse.Namespace) -> int:
    import numpy as np

    from contact.commands.output_paths import check_output_file
    from contact.study.friction_study import run_friction_study
    from contact.study.store import ResultStore
    from friction.study.design import (
        DESIGN_BOX_TEXT,
        DESIGN_BOXES,
        check_design,
        factorial_design,
        space_filling_design,
    )
    from friction.study.points import SolveSettings
    from geometry.core.errors import InputError, StudyFailedError
    from geometry.core.io import write_netcdf

    check_output_file(args.output)
    if args.workers is not None and args.workers < 1:
        raise InputError(f"--workers: must be >= 1, got {args.workers}")
    if args.design == "factorial":
        design = factorial_design()
        attrs = {"method": "factorial", "source": "seed Table 5.1 (unordered Rq pairs)"}
    else:
        exclude = DESIGN_BOXES[args.exclude_box] if args.exclude_box else None
        design = space_filling_design(args.points, method=args.design, seed=args.seed,
                                      skip=args.skip, box=DESIGN_BOXES[args.box],
                                      exclude=exclude)
        attrs = {"method": args.design, "seed": args.seed, "skip": args.skip,
                 "box": DESIGN_BOX_TEXT[args.box]}
        if exclude is not None:
            attrs["box"] += f"; outside {DESIGN_BOX_TEXT[args.exclude_box]}"
    attrs["points"] = int(next(iter(design.values())).size)
    try:
        settings = SolveSettings(nodes=args.nodes, max_iterations=args.max_iterations,
                                 lubricant=args.lubricant, realisations=args.realisations,
                                 viscosity_model=args.viscosity_model,
                                 thermal=not args.isothermal)
    except InputError as exc:
        raise InputError(_option(str(exc))) from None
    check_design(design, lubricant=settings.lubricant)  # every condition in the oil's range
    # what will run, before it starts (issue 56): the conditions and their ranges
    ranges = ", ".join(f"{k} {np.min(v):.4g}..{np.max(v):.4g}" for k, v in design.items())
    from contact.commands.run import print_wrapped

    print_wrapped(f"friction study: {attrs['points']} conditions ({attrs['method']}"
                  + (f", seed {attrs['seed']}" if "seed" in attrs else "") + f"), {ranges}; "
                  f"{settings.lubricant}, {settings.nodes} nodes")
    ds = run_friction_study(design, settings, design_attrs=attrs, output=args.output,
                            scheduler=args.scheduler, n_workers=args.workers,
                            progress=study_progress(args))
    inputs = " ".join(f"{k}={v}" for k, v in sorted(vars(args).items()) if k != "func")
    path = write_netcdf(ds, args.output, inputs=inputs)
    ResultStore.remove_parts(args.output)
    ok = ds["status"].values == 0
    mu = ds["friction_coefficient"].values[ok]
    span = f", mu {np.min(mu):.4f}-{np.max(mu):.4f}" if mu.size else ""
    print(f"{ds.sizes['point']} conditions, {int(ok.sum())} converged{span}, "
          f"wall time {ds.attrs['wall_time']:.0f} s -> {path}")
    if not ok.any():
        # a condition that does not converge is a result; a study of which none converges
        # is an error (its file keeps every point's reason)
        reasons = [str(r) for r in ds["reason"].values]
        raise StudyFailedError(
            f"none of the {ds.sizes['point']} conditions converged; the first (point "
            f"{int(ds['point'].values[0])}): {reasons[0] or 'no reason recorded'} "
            f"(every point's reason: the 'reason' variable of {str(path)!r})")
    return 0


#: SolveSettings' fields that are this command's options (the message names the option)
_OPTIONS = {"lubricant": "--lubricant", "nodes": "--nodes", "max_iterations": "--max-iterations",
            "realisations": "--realisations"}


def _option(message: str) -> str:
    """A :class:`SolveSettings` refusal with its field named as the command's option
    (``max_iterations: ...`` → ``--max-iterations: ...``); other messages as they are."""
    field, sep, rest = message.partition(":")
    return f"{_OPTIONS[field]}{sep}{rest}" if sep and field in _OPTIONS else message
