"""``ltca correct``: corrective machine settings from measured flank deviations.

Reads the case and the measured normal deviations of the pinion and gear flanks in contact
(CSV or netCDF, as ``ltca run --deviations``), computes per member the setting changes that
cancel them (:func:`geometry.synthesis.correction.corrective_settings`), prints a table per flank
and writes the corrected case (atomically, with a ``[correction]`` table saying where it came
from). See ``docs/correction.md``.
"""

from __future__ import annotations

import argparse
import math
import os
import tomllib
from pathlib import Path

from contact.commands.options import (
    case_argument,
    default_output,
    flank_option,
    output_option,
)
from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 35

_HEADER = ("# Written by `ltca correct` (geometry.synthesis.correction): {case} with "
           "corrective machine settings\n# from the measured deviations {files}; see the "
           "[correction] table and "
           "docs/correction.md.\n")


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    from geometry.synthesis.setting_variables import (
        COND_MAX,
        DEFAULT_VARIABLES,
        SETTING_VARIABLES,
    )

    defaults = "; ".join(f"{proc}: {' '.join(names)}" for proc, names in
                         DEFAULT_VARIABLES.items())
    p = sub.add_parser(
        "correct",
        help="corrective machine settings from measured flank deviations (CMM grid); write "
             "the corrected case",
        description="Least-squares identification of the settings errors that explain the "
        "measured normal deviations of the flanks in contact (sensitivities from the "
        "generator; settings the measurement does not determine are held fixed and "
        "reported), and the corrected case: the nominal settings plus the correction, the "
        "change to dial into the machine to cancel the deviation (minus the identified "
        "error). Prints, per flank, each setting's correction, whether it is determined, "
        "its standard error per um of measurement noise and the residual deviation.",
    )
    case_argument(p, what="correct")
    p.add_argument("--deviations", nargs=2, metavar=("PINION", "GEAR"), default=None,
                   help="measured normal deviations of the pinion and gear flanks in contact "
                        "(CSV or netCDF, positive = material added; '-' for a member not to "
                        "correct); default: the case's [deviations] table")
    flank_option(p, default="drive")
    p.add_argument("--settings", nargs="+", default=None, metavar="NAME",
                   help=f"settings to correct (default per process, {defaults}); accepted: "
                        f"{' '.join(SETTING_VARIABLES)}")
    p.add_argument("--bound", nargs=3, action="append", default=[],
                   metavar=("NAME", "LOW", "HIGH"),
                   help="bounds of a corrected setting in case-file units (deg, mm); "
                        "repeatable; must lie in the setting's valid range")
    p.add_argument("--cond-max", type=float, default=COND_MAX, metavar="KAPPA",
                   help="largest condition number of the settings kept free (default "
                        "%(default)g); the others are held fixed")
    output_option(p, default="<case>_corrected.toml; --flank coast: "
                             "<case>_coast_corrected.toml", what="corrected case file (TOML)")
    p.set_defaults(func=run_correct, many_analyses=True)


def _bounds(raw: list[list[str]]) -> dict[str, tuple[float, float]]:
    from geometry.core.errors import InputError
    from geometry.synthesis.setting_variables import SETTING_VARIABLES

    out = {}
    for name, low, high in raw:
        if name not in SETTING_VARIABLES:
            raise InputError(f"--bound: unknown setting {name!r}; accepted: "
                             f"{', '.join(SETTING_VARIABLES)}")
        try:
            lo, hi = float(low), float(high)
        except ValueError:
            raise InputError(f"--bound {name}: LOW and HIGH must be numbers, got {low!r} "
                             f"{high!r}") from None
        scale = SETTING_VARIABLES[name].scale
        out[name] = (lo * scale, hi * scale)
    return out


def _table(c) -> str:
    from tabulate import tabulate

    rows = []
    for i, name in enumerate(c.names):
        s = c.scale[i]
        status = ("yes" if c.determined[i] else
                  "no effect" if not c.effect[i] else "held fixed")
        if c.at_bound[i]:
            status += " (at bound)"
        se = c.standard_error_per_um[i] / s
        corr = c.correction[i] / s
        rows.append((name, c.units[i], f"{c.nominal[i] / s + 0.0:.8g}",
                     "0" if corr == 0.0 else f"{corr:+.6g}", f"{c.corrected[i] / s + 0.0:.8g}",
                     status,
                     "" if math.isnan(se) else f"{se:.3g}",
                     "inf" if math.isinf(c.vif[i]) else f"{c.vif[i]:.3g}"))
    return tabulate(rows, headers=["setting", "unit", "nominal", "correction", "corrected",
                                   "determined", "std err / um noise", "VIF"],
                    tablefmt="github", disable_numparse=True)


def run_correct(args: argparse.Namespace) -> int:
    from contact.catalogue import resolve_case
    from contact.commands.synthesize import write_text_atomic
    from contact.utca.deviation_files import read_deviations
    from contact.utca.easeoff import FLANK_ROLES, MATING_FLANK
    from geometry.case import case_from_dict
    from geometry.core.errors import InputError
    from geometry.synthesis.correction import corrected_case, corrective_settings

    output = default_output(args, "_corrected.toml")
    check_output_file(output, create_parents=True)
    case = resolve_case(args.case)
    if args.deviations is not None:
        files = [None if f == "-" else f for f in args.deviations]
    elif case.deviations is not None:
        files = [case.deviations.pinion, case.deviations.gear]
    else:
        raise InputError("--deviations: the case has no [deviations] table; give the "
                         "PINION and GEAR deviation files ('-' for none)")
    if all(f is None for f in files):
        raise InputError("--deviations: at least one of PINION, GEAR must be a file")
    bounds = _bounds(args.bound) or None
    pinion_flank = (FLANK_ROLES[args.flank](case) if args.flank in FLANK_ROLES
                    else args.flank)
    flanks = {"pinion": pinion_flank, "gear": MATING_FLANK[pinion_flank]}
    corrections = []
    for member, path in zip(("pinion", "gear"), files, strict=True):
        if path is None:
            continue
        dev = read_deviations(path, member)
        c = corrective_settings(case, member, flanks[member], dev.u, dev.v, dev.deviation,
                                settings=args.settings, bounds=bounds,
                                cond_max=args.cond_max)
        corrections.append(c)
        held = [n for n, d in zip(c.names, c.determined, strict=True) if not d]
        print(f"{member} {c.flank} ({case.member(member).process}), {Path(path).name}: "
              f"{c.n_points} points, measured RMS {1e3 * c.measured_rms:.3f} um / max "
              f"{1e3 * c.measured_max:.3f} um -> residual RMS {1e3 * c.residual_rms:.3f} um / "
              f"max {1e3 * c.residual_max:.3f} um")
        print(f"  condition number {c.condition_number:.3g} (candidates), "
              f"{c.condition_number_determined:.3g} (determined, limit {c.cond_max:g}); held "
              f"fixed: {', '.join(held) if held else 'none'}")
        print(_table(c))
    names = ", ".join(os.fspath(f) for f in files if f is not None)
    provenance = {
        "source_file": str(Path(args.case).resolve()) if args.case and Path(args.case).is_file()
        else (args.case or case.name),
        "deviation_files": [os.path.abspath(f) if f is not None else "-" for f in files],
    }
    out = corrected_case(case, corrections, provenance=provenance)
    text = _HEADER.format(case=case.name, files=names) + out.to_toml()
    case_from_dict(tomllib.loads(text))  # the written text must load back
    path = write_text_atomic(Path(output), text)
    print(f"wrote {path}")
    return 0
