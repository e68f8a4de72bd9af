"""``ltca report``: one self-contained HTML page of an analysis, from its netCDF file alone."""

from __future__ import annotations

import argparse

from contact.commands.options import (
    analysis_file_argument,
    output_option,
    progress_option,
    resolve_analysis_file,
)
from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 12


def register(sub) -> None:
    """Add the ``report`` sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "report",
        help="one HTML page of an analysis file: case, conditions, summary table, figures",
        description="Write a self-contained HTML page (figures embedded, no network) of a "
        "file written by `ltca run`: the case and its provenance, the operating conditions, "
        "the LTE/pressure/efficiency summary table (seed Table 3.1 layout), every figure, "
        "the solver's certification and the toolkit versions. A file written by `ltca "
        "duty-cycle` gives its duty-cycle page instead (damage, life and safety factors "
        "of both members, the bins, the figures). Only the file is read, so a file from "
        "another machine or an older run gives the same page.",
    )
    analysis_file_argument(p)
    output_option(p, default="FILE's name with .html, e.g. kolivand2009_fm_11x41_reference.html",
                  what="HTML file")
    progress_option(p)
    p.set_defaults(func=run)


#: files of other commands that ``ltca report`` does not read: (test on the file's root
#: attributes, what it is, the command that wrote it, what reads or draws it)
OTHER_FILES = (
    (lambda a: a.get("study") == "sweep", "a misalignment sweep", "ltca sweep",
     "its maps: `ltca sweep ... --plots DIR`, or contact.study.figures.save_study_figures"),
    (lambda a: a.get("study") == "sample", "a tolerance study", "ltca tolerance",
     "its figures: `ltca tolerance ... --plots DIR`, or contact.study.figures.save_study_figures"),
    (lambda a: a.get("study") == "vh-check", "a V-H check", "ltca vh-check",
     "its figure: `ltca vh-check ... --plots DIR`, or contact.study.figures.save_study_figures"),
    (lambda a: str(a.get("title", "")).startswith("hypoid-ltca friction study"),
     "a friction study", "ltca friction-study", "`ltca friction-fit FILE` fits mu to it"),
    (lambda a: a.get("title") == "mechanical efficiency map", "an efficiency map",
     "ltca efficiency-map", "its figures: `ltca efficiency-map ... --plots DIR`"),
    (lambda a: str(a.get("title", "")).startswith("hypoid-ltca simulated wear"),
     "a wear simulation", "ltca wear", "its worn flanks: `ltca run --deviations`"),
    (lambda a: str(a.get("title", "")).startswith("mixed-EHL line contact"),
     "a mixed-EHL line contact", "ltca ehl", "xarray reads its profiles"),
    (lambda a: a.get("title") == "tooth surfaces", "tooth surfaces", "ltca geometry",
     "their figures: `ltca plot-geometry CASE --plots DIR`"),
    (lambda a: str(a.get("title", "")).startswith("ISO 10300"), "an ISO 10300 rating",
     "ltca rate", "`ltca rate` prints its table"),
    # any method's rating file (ltca rate -o: a root and /rating, no analysis)
    (lambda a: bool(a.get("_rating_group")), "a load-capacity rating", "ltca rate",
     "`ltca rate CASE --method NAME` prints its tables"),
    (lambda a: a.get("title") == "hypoid-ltca solver comparison", "a solver comparison",
     "ltca compare-solvers", "`ltca compare-solvers` prints its table"),
    (lambda a: str(a.get("title", "")).startswith("hypoid-ltca optimisation"),
     "a machine-setting optimisation", "ltca optimize", "its settings: the case file it wrote"),
)


def other_file(tree, path) -> str | None:
    """Why ``ltca report`` does not read a file that another command wrote: what it is,
    which command wrote it and what reads it (:data:`OTHER_FILES`); None for a file that
    is none of them."""
    attrs = dict(tree.attrs)
    if "rating" in getattr(tree, "children", {}):  # a rating file: say whose method
        method = str(tree["rating"].attrs.get("rating_method", ""))
        attrs["_rating_group"] = method or "a method"
    for test, what, command, reader in OTHER_FILES:
        if test(attrs):
            return (f"{str(path)!r} is {what} file, written by `{command}`, not an analysis: "
                    "`ltca report` reads the files of `ltca run` and `ltca duty-cycle`; "
                    f"{reader}")
    return None


def run(args: argparse.Namespace) -> int:
    from contact.plots.report import write_report
    from geometry.core.errors import InputError
    from geometry.core.io import read_netcdf

    path = resolve_analysis_file(args.file)
    output = args.output or path.with_suffix(".html").name
    check_output_file(output)
    tree = read_netcdf(path, tree=True)
    if not {"easeoff", "duty_cycle"} & set(tree.children):
        message = other_file(tree, path)
        if message is not None:
            raise InputError(message)
        raise InputError(f"{str(path)!r} has no /easeoff or /duty_cycle group (groups: "
                         f"{', '.join('/' + g for g in tree.children) or 'none'}): "
                         "`ltca report` reads the files of `ltca run` and `ltca duty-cycle`")
    if "duty_cycle" in tree.children:
        from contact.plots.duty_report import write_duty_report

        print(f"wrote {write_duty_report(tree, output)}")
        return 0
    try:
        print(f"wrote {write_report(tree, output, figures=_figures(tree, args))}")
    except InputError as exc:  # a group or variable the page reads is absent: which file
        raise InputError(f"{str(path)!r}: {exc}") from None
    return 0


def _figures(tree, args: argparse.Namespace):
    """The report's figures drawn here with progress: a bar on a terminal, a plain line per
    figure anywhere else (``report: figure 3/14, contact_pattern (5 s)``); None (the
    report draws them) without progress or for a tree that is no analysis (the report
    refuses it before drawing)."""
    progress = getattr(args, "progress", False)
    if not progress or "ltca" not in tree.children:
        return None
    from contact.plots.analysis import RenderedFigure, analysis_specs, render_analysis
    from contact.plots.style import png_bytes

    if progress is True:
        return render_analysis(tree, progress=True)
    from contact.commands.step_lines import StepLines

    specs = list(analysis_specs(tree))
    say = StepLines("report", len(specs), unit="figure")
    out = []
    for spec in specs:
        say(spec.name)
        out.append(RenderedFigure(spec.name, spec.caption, png_bytes(spec.draw())))
    return out
