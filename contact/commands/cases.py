"""``ltca cases``: the bundled cases, one line each (name, process, teeth, source)."""

from __future__ import annotations

import argparse

#: Place in ``ltca --help``.
ORDER = 5


def register(sub) -> None:
    """Add the ``cases`` sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "cases",
        help="list the bundled cases (names every command accepts as CASE)",
        description="One line per bundled case: its name (what every command takes as "
        "CASE), the cutting method and processes, the numbers of teeth, the operating "
        "point of its [operating] table, and where the pair comes from. The default case "
        "is marked with *.",
    )
    p.set_defaults(func=run)


def case_line(case, default: bool = False) -> tuple[str, ...]:
    """The row of one case: name, method/processes, z1 x z2, torques, misalignment, source."""
    mis = case.misalignment.labelled()
    errs = ", ".join(f"d{k[6:-3]} {v:+g}" for k, v in mis.items() if v) or "aligned"
    source = case.source.split(" (")[0].split(". ")[0]
    if len(source) > 80:
        source = source[:77] + "..."
    return ("*" if default else "", case.name,
            f"{case.pair.method} {case.pinion.process}/{case.gear.process}",
            f"{case.pinion.blank.teeth}x{case.gear.blank.teeth}",
            " ".join(f"{t:g}" for t in case.operating.torque), errs, source)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.catalogue import DEFAULT_CASE, bundled_case_path, bundled_cases
    from geometry.case import load_case

    rows = [case_line(load_case(bundled_case_path(name)), name == DEFAULT_CASE)
            for name in bundled_cases()]
    print(tabulate(rows, headers=("", "case", "method", "teeth", "T_p [N m]",
                                  "misalignment [mm, deg]", "source"), tablefmt="simple"))
    print("* the default case (CASE omitted); dSigma in deg")
    return 0
