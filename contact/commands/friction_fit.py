"""``ltca friction-fit``: fit the ``kolivand2009`` friction model to a friction study."""

from __future__ import annotations

import argparse

#: Place in ``ltca --help``.
ORDER = 62


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "friction-fit",
        help="fit the kolivand2009 friction model (seed Eq. 5.11 structure) to the results "
        "of ltca friction-study; any oil",
        description="Fits ln mu of the converged points of a friction study (written by ltca "
        "friction-study, with any oil) in three lambda regimes (< 1, 1-3, > 3; seed Eq. "
        "5.11) with continuity at lambda = 1 and 3, and writes the coefficient file with "
        "the fitted range, the fit's statistics (and those on held-out points) and the "
        "study's provenance. Use it as the model's coefficients: "
        "friction.kolivand2009.kolivand2009(..., coefficients=FILE) (docs/friction.md).",
    )
    p.add_argument("study", metavar="STUDY.nc", nargs="+",
                   help="friction study (or studies of one oil and solver setting, e.g. a "
                   "Sobol design and its --skip continuation) to fit")
    p.add_argument("--held-out", default=None, nargs="+", metavar="FILE.nc",
                   help="friction studies (other design seeds) used only to measure the "
                   "fit's error")
    p.add_argument("--structure", choices=("eyring", "split", "regimes"), default="eyring",
                   help="eyring: mu = (1 - asperity share) * smooth-film Eyring traction * "
                   "regression + mu_b * asperity share; split: mu = film regression + mu_b * "
                   "asperity share; regimes: ln mu regressed directly (default %(default)s)")
    p.add_argument("--box", choices=("auto", "table_5_1", "gear", "gear_flank", "gear_edge"),
                   default="auto",
                   help="the fitted range of the inputs: the box the study was designed in "
                   "(auto: read from the studies' design_box attributes, the widest named), "
                   "or a named one (default %(default)s)")
    p.add_argument("-o", "--output", default="kolivand2009_fit.toml", metavar="FILE",
                   help="coefficient file to write (default %(default)s)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from contact.commands.output_paths import check_output_file
    from friction.study.design import DESIGN_BOXES, design_box_of
    from friction.study.fit import combine_studies, fit_kolivand2009, write_fit
    from geometry.core.errors import InputError
    from geometry.core.io import read_netcdf

    check_output_file(args.output)
    if not str(args.output).endswith(".toml"):
        raise InputError(f"-o: the coefficient file must end in .toml, got {args.output!r}")
    study = combine_studies([read_netcdf(f, tree=False) for f in args.study])
    held = (combine_studies([read_netcdf(f, tree=False) for f in args.held_out])
            if args.held_out else None)
    box = args.box
    if box == "auto":
        box = design_box_of(str(study.attrs.get("design_box", "")))
    fit = fit_kolivand2009(study, heldout=held, structure=args.structure,
                           box=DESIGN_BOXES[box])
    path = write_fit(fit, args.output)
    s = fit.statistics
    line = (f"{fit.lubricant}: {s['training_points']} points, RMS relative error "
            f"{s['training_rms_relative_error']:.1%} "
            f"(worst {s['training_max_relative_error']:.0%})")
    if held is not None:
        line += (f"; held out {s['heldout_points']}: {s['heldout_rms_relative_error']:.1%} "
                 f"(worst {s['heldout_max_relative_error']:.0%})")
    jump = max(s["continuity_jump_lambda_1"], s["continuity_jump_lambda_3"])
    print(f"{line}; continuity jump {jump:.1e} -> {path}")
    return 0
