"""``ltca export-rexs`` and ``ltca import-rexs``: bevel stages in REXS files (docs/exchange.md)."""

from __future__ import annotations

import argparse
from pathlib import Path

from contact.commands.options import case_argument, case_stem, output_option
from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 32


def register(sub) -> None:
    """Add the ``export-rexs`` and ``import-rexs`` sub-commands."""
    p = sub.add_parser(
        "export-rexs",
        help="write a case's bevel stage as a REXS file (.rexs XML, .rexsj JSON)",
        description="Write the bevel stage of a case - blanks, tools and machine settings of "
        "both members and flanks, the operating point as a load spectrum, and with an "
        "analysis file its results - as a REXS file (FVA Reducer EXchange Specification) "
        "that KISSsoft, MASTA or FVA-Workbench read. The file is checked against the "
        "published schema and the REXS attribute database before it is written; what REXS "
        "has no attribute for goes into custom_ attributes (docs/exchange.md).",
    )
    case_argument(p, what="export")
    p.add_argument("analysis", nargs="?", default=None, metavar="ANALYSIS",
                   help="netCDF file `ltca run CASE` wrote: its ISO 10300 rating, mesh "
                        "stiffness per mesh position and ease-off go into REXS's slots")
    output_option(p, default="<case>.rexs", what="REXS file (.rexs XML or .rexsj JSON)")
    p.add_argument("--version", dest="rexs_version", default="2.0.0",
                   choices=("1.7", "2.0.0"), help="REXS version (default 2.0.0)")
    p.set_defaults(func=run_export)
    q = sub.add_parser(
        "import-rexs",
        help="make a case (or a basic design file) of a REXS bevel stage",
        description="Read a REXS file (.rexs or .rexsj, REXS 1.7 or 2.0.0) with one bevel "
        "stage, check it against the published schema and the attribute database, and "
        "write a case file when the stage has manufacturing settings (tools and machine "
        "settings per member and flank), else a basic design file for `ltca synthesize`. "
        "Unknown or inconsistent data are refused, naming the component, its id and the "
        "attribute.",
    )
    q.add_argument("file", metavar="FILE", help="REXS file (.rexs XML or .rexsj JSON)")
    output_option(q, default="<FILE stem>.toml", what="case or basic design file (TOML)")
    q.set_defaults(func=run_import)


def run_export(args: argparse.Namespace) -> int:
    from contact.catalogue import resolve_case
    from contact.commands.options import resolve_analysis_file
    from contact.exchange.rexs import export_rexs
    from contact.exchange.rexs.files import file_format

    output = args.output or f"{case_stem(args.case)}.rexs"
    fmt = file_format(output)
    check_output_file(output, create_parents=True)
    case = resolve_case(args.case)
    analysis = resolve_analysis_file(args.analysis) if args.analysis else None
    model = export_rexs(case, output, version=args.rexs_version, analysis=analysis)
    cases = len(model.load_spectrum.load_cases) if model.load_spectrum else 0
    schema = "rexs-file.xsd" if fmt == "xml" else "rexs-file.json"
    print(f"wrote {output} (REXS {model.version}, {fmt.upper()}: {len(model.components)} "
          f"components, {len(model.relations)} relations, {cases} load cases); checked "
          f"against {schema} and the REXS {model.version} attribute database")
    return 0


def run_import(args: argparse.Namespace) -> int:
    from contact.commands.synthesize import write_text_atomic
    from contact.exchange.rexs import import_rexs

    output = args.output or f"{Path(args.file).stem}.toml"
    check_output_file(output, create_parents=True)
    stage = import_rexs(args.file)
    header = (f"# Written by `ltca import-rexs {args.file}` from REXS {stage.model.version} "
              f"({stage.model.application_id} {stage.model.application_version}); "
              "docs/exchange.md.\n")
    write_text_atomic(Path(output), header + stage.to_toml())
    if stage.kind == "case":
        print(f"wrote case {output} ({stage.case.pair.method}, "
              f"{stage.case.pinion.blank.teeth}x{stage.case.gear.blank.teeth}); analyse it: "
              f"ltca run {output}")
    else:
        print(f"wrote basic design file {output} (the stage has blank data but no "
              f"manufacturing settings); make a case of it: ltca synthesize {output} -o "
              "CASE.toml")
    return 0
