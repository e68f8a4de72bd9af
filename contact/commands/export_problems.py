"""``ltca export-problems``: the real LTCA contact problems of cases, written for solver studies.

For each case (default: every bundled case), aligned and misaligned, the analysis of
``ltca run`` (the case's own surface deviations applied, as :func:`contact.pipeline.run_analysis`
does) runs at the given torques; the final contact problem of every roll position of one
mesh cycle at every torque is written as one ``.npz`` file, with ``manifest.json`` listing
case, misalignment, torque, roll, N and file (:mod:`contact.qp.problem_files`).
"""

from __future__ import annotations

import argparse
import dataclasses
import datetime
import logging
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

from contact.commands.options import (
    case_argument,
    misalignment_from_args,
    misalignment_options,
    progress_option,
    rolls_per_cycle_option,
    torque_option,
)
from contact.commands.output_paths import check_output_dir
from geometry import __version__

__all__ = ["DEFAULT_TORQUES", "case_problems", "export_problems", "register", "run"]

log = logging.getLogger(__name__)

#: Place in ``ltca --help``.
ORDER = 92

#: Pinion torques of the export [N·m]: the seed's Table 3.1 (light, medium, full load).
DEFAULT_TORQUES = (50.0, 250.0, 500.0)


def case_problems(name: str, torques: Sequence[float], misalignment=None,
                  options=None) -> list:
    """The real contact problems of one case's LTCA over one mesh cycle, as ``ltca run``
    solves them (the ease-off of the case's own surface deviations, as
    :func:`contact.pipeline.run_analysis` builds it).

    Parameters
    ----------
    name : str
        Bundled case name or case file.
    torques : sequence of float — [N·m]
        Pinion torques.
    misalignment : geometry.pair.assembly.Misalignment, optional
        Replaces the case's own (default: the case's).
    options : contact.ltca.LTCAOptions, optional

    Returns
    -------
    list of contact.qp.benchmark_problems.TestProblem
        As :func:`contact.ltca.ltca_problems`.
    """
    from contact.catalogue import resolve_case
    from contact.ltca import ltca_problems
    from contact.utca import ease_off
    from contact.utca.deviation_files import read_deviations
    from contact.utca.deviations import apply_deviations

    case = resolve_case(name)
    if misalignment is not None:
        case = dataclasses.replace(case, misalignment=misalignment)
    eo = ease_off(case)
    files = case.deviations
    if files is not None and (files.pinion or files.gear):
        eo = apply_deviations(
            eo,
            pinion=read_deviations(files.pinion, "pinion") if files.pinion else None,
            gear=read_deviations(files.gear, "gear") if files.gear else None,
            case=case,
        )
    return ltca_problems(case, list(torques), options=options, easeoff=eo)


def export_problems(cases: Sequence[str], directory: str | Path, *,
                    torques: Sequence[float] = DEFAULT_TORQUES,
                    misalignments: Mapping[str, object] | None = None,
                    options=None, progress: bool = False,
                    command: str = "") -> Path:
    """Write the real contact problems of cases and their manifest into ``directory``.

    Parameters
    ----------
    cases : sequence of str
        Bundled case names or case files.
    directory : path-like
        Created if missing; files of the same names are replaced.
    torques : sequence of float — [N·m]
        Pinion torques (default :data:`DEFAULT_TORQUES`).
    misalignments : mapping of str to geometry.pair.assembly.Misalignment, optional
        Label → misalignment; default ``aligned`` (none) and ``misaligned`` (the seed's
        Table 3.1: ΔE = −0.15 mm, ΔP = +0.12 mm, :data:`contact.catalogue.SEED_TABLE_3_1`).
    options : contact.ltca.LTCAOptions, optional
        LTCA settings (default ``LTCAOptions()``: 20 roll positions per mesh cycle).
    progress : bool
        tqdm progress bar over (case, misalignment).
    command : str
        The command line, recorded in the manifest.

    Returns
    -------
    pathlib.Path
        The manifest written.

    Raises
    ------
    InputError
        Unknown case, bad torque or options.
    """
    from contact.catalogue import SEED_TABLE_3_1
    from contact.ltca import LTCAOptions
    from contact.ltca.options import json_options
    from contact.qp.problem_files import write_manifest, write_problem
    from geometry.pair.assembly import Misalignment

    opts = options or LTCAOptions()
    mis = dict(misalignments or {"aligned": Misalignment(),
                                 "misaligned": SEED_TABLE_3_1["misalignment"]})
    d = check_output_dir(directory, option="-o")
    jobs = [(c, label) for c in cases for label in mis]
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=len(jobs), desc="export-problems", unit="analysis")
    entries = []
    for case, label in jobs:
        m = mis[label]
        stem = Path(case).name.removesuffix(".toml")
        if bar is not None:
            bar.set_postfix_str(f"{stem} {label}", refresh=True)
        for tp in case_problems(case, torques, m, opts):
            ref = tp.reference
            name = f"{stem}-{label}-T{ref['torque']:g}-roll{ref['roll']:02d}"
            path = write_problem(d / f"{name}.npz", tp.problem)
            entries.append({
                "name": name, "file": path.name, "n": tp.problem.size, "kind": "ltca",
                "case": stem, "misalignment": label,
                "delta_E_mm": m.delta_E, "delta_P_mm": m.delta_P, "delta_G_mm": m.delta_G,
                "delta_Sigma_rad": m.delta_Sigma,
                "torque_Nm": ref["torque"], "gear_torque_Nmm": tp.problem.torque,
                "roll": ref["roll"], "roll_angle_rad": ref["roll_angle"],
            })
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    attrs = {
        "title": "real contact problems of hypoid-ltca loaded TCA",
        "toolkit_version": __version__,
        "date_created": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "command": command,
        "cases": [Path(c).name.removesuffix(".toml") for c in cases],
        "torques_Nm": [float(t) for t in torques],
        "misalignments": {k: dataclasses.asdict(v) for k, v in mis.items()},
        "ltca_options": json_options(opts),
        "units": {"compliance": "mm/N", "separation": "mm", "moment_arm": "mm",
                  "torque": "N mm (gear torque)"},
    }
    return write_manifest(d, entries, attrs)


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "export-problems",
        help="write the real LTCA contact problems of cases for solver studies",
        description="Run the loaded TCA of each case aligned and misaligned at each torque "
        "and write the contact problem of every roll position of one mesh cycle as .npz, "
        "with manifest.json (case, misalignment, torque, roll, N, file). The set feeds "
        "`ltca compare-solvers --problems DIR` and benchmarks/ltca_contact.py (qpbenchmark).",
    )
    case_argument(p, many=True, what="export")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="directory to write the problems and manifest.json into")
    torque_option(p, default="50 250 500, the seed's Table 3.1")
    misalignment_options(p, default="of the misaligned set: the seed's Table 3.1, "
                         "dE -0.15, dP +0.12")
    rolls_per_cycle_option(p, default=20)
    progress_option(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Export the problems and print where they went."""
    from contact.catalogue import SEED_TABLE_3_1, bundled_cases
    from contact.ltca import LTCAOptions
    from geometry.pair.assembly import Misalignment

    check_output_dir(args.output, option="-o")
    misaligned = misalignment_from_args(args, SEED_TABLE_3_1["misalignment"])
    torques = list(DEFAULT_TORQUES) if args.torque is None else args.torque
    cases = args.case or [c.removesuffix(".toml") for c in bundled_cases()]
    opts = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle)
    print(f"hypoid-ltca {__version__}: the LTCA problems of {len(cases)} cases, aligned and "
          f"misaligned, at T_p = {torques} N m, {opts.rolls_per_cycle} rolls per cycle")
    path = export_problems(cases, args.output, torques=torques,
                           misalignments={"aligned": Misalignment(), "misaligned": misaligned},
                           options=opts, progress=not args.no_progress,
                           command="ltca " + " ".join(sys.argv[1:]))
    from contact.qp.problem_files import read_manifest

    entries = read_manifest(path.parent)["problems"]
    sizes = [e["n"] for e in entries]
    print(f"wrote {len(entries)} problems (N = {min(sizes)}...{max(sizes)}) and {path}")
    return 0
