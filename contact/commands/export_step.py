"""``ltca export-step``: both members of a case as closed B-rep solids in a STEP file."""

from __future__ import annotations

import argparse

from contact.commands.options import (
    case_argument,
    default_output,
    misalignment_from_args,
    misalignment_options,
    output_option,
)
from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 93


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "export-step",
        help="write both members as closed B-rep solids (STEP AP214, an assembly at the "
        "case's misalignment) for CAD, CAM and CMM programs",
        description="Write both members of a case as closed B-rep solids in one STEP AP214 "
        "file: the blank of revolution (ISO 23509 cones, a rim under the slots) with its "
        "slots cut by B-spline faces through the generated flanks, fillets and slot "
        "bottoms; each member a part in its own frame (the frame of `ltca geometry`'s flank "
        "positions), the pair an assembly at the case's misalignment. Needs the optional "
        "extra: pip install \"hypoid-ltca[step]\" (docs/exchange.md).",
    )
    case_argument(p, what="export")
    output_option(p, default="<case>.step", what="STEP file (.step or .stp)",
                  metavar="FILE.step")
    p.add_argument("--rim-depth", type=float, default=None, metavar="MM",
                   help="depth of the rim under the deepest slot bottom [mm] (default 1.2 x "
                   "the outer whole depth, as the FE solid's)")
    misalignment_options(p, default="the case's [operating] values")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import dataclasses

    from contact.catalogue import resolve_case
    from contact.exchange.step import member_solid, ocp_available, write_step
    from geometry.core.errors import InputError, ModelUnavailableError

    output = default_output(args, ".step")
    if not str(output).lower().endswith((".step", ".stp")):
        raise InputError(f"-o/--output: must end in .step or .stp, got {str(output)!r}")
    check_output_file(output)
    if not ocp_available():
        raise ModelUnavailableError(
            "ltca export-step needs OpenCASCADE's Python bindings, not installed here: "
            "pip install \"hypoid-ltca[step]\" (cadquery-ocp-novtk)")
    case = resolve_case(args.case)
    mis = misalignment_from_args(args, case.misalignment)
    if mis is not None:
        case = dataclasses.replace(case, misalignment=mis)
    solids = {m: member_solid(case, m, rim_depth=args.rim_depth) for m in ("pinion", "gear")}
    path = write_step(case, output, solids=solids)
    for m, s in solids.items():
        print(f"{m:7s} one closed solid, {s.faces} faces, volume {s.volume:.6g} mm^3, "
              f"rim {s.rim_depth:.3g} mm under the root cone")
    print(f"wrote {path}")
    return 0
