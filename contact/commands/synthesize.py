"""``ltca synthesize``: a complete case file from basic design data (local synthesis)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from contact.commands.options import (
    checked_fe_level,
    fe_level_option,
    output_option,
    progress_option,
)
from contact.commands.output_paths import check_output_file
from contact.optimize.written_notes import (  # noqa: F401  (the names tests and docs import)
    FACE_CONTACT_RATIO_NOTE,
    PROFILE_CONTACT_RATIO_NOTE,
    checked_basic_rating,
    fe_level_notes,
    first_lines,
    gear_process_note,
    header_text,
    low_overlap_lte,
    reach_text,
    synthesis_fe_level,
)
from geometry.core.atomic_files import atomic_path

#: Place in ``ltca --help``.
ORDER = 30





def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "synthesize",
        help="machine settings of a face-milled or face-hobbed pair from basic design data "
             "(case TOML)",
        description="Read a basic design file (cases/basic/*.toml: ISO 23509 inputs, "
        "targets, synthesis options), compute the blanks, the Formate gear settings (a "
        "generated gear where a low-ratio pair's Formate gear has no solution or its "
        "developed design fails or misses its drive pattern, [synthesis] gear_process) "
        "and the generated pinion by local synthesis, and write a "
        "complete case file. The process follows the design's blade groups z0: 0 face "
        "milling, >= 1 face hobbing.",
    )
    p.add_argument("basic", nargs="?", default=None, metavar="BASIC",
                   help="basic design file (TOML, schema in docs/synthesis.md) or the name of "
                        "a bundled one (cases/basic/: "
                        + ", ".join(bundled_basic_names()) + "); default the default case's, "
                        "kolivand2009_fm_11x41_reference")
    output_option(p, default="<stem>.toml of BASIC in this directory; <stem>_case.toml "
                  "where that is BASIC itself", what="case file (TOML)")
    progress_option(p)
    fe_level_option(p, "default the basic file's [root_stress] fe_level, else coarse10 "
                       "(a new design's root-stress checks, written into the case: `ltca "
                       "run` of it reads the same models)")
    p.add_argument("--no-development", dest="development", action="store_false",
                   help="write the local synthesis of the [synthesis] prescriptions as they "
                        "are, without developing the bearing under load (default: the "
                        "drive flank's path angle, ellipse and relief are developed to the "
                        "[development] targets, contact.optimize.development)")
    p.add_argument("--apply-remedy", dest="apply_remedy", action="store_true",
                   help="where a contact ratio is below its limit (face eps_vb < 1.25, "
                        "profile eps_va < 1), apply the remedy the note checks (a gear face "
                        "width b2 or mean spiral angle beta_m; a depth factor k_d or "
                        "pressure angle alpha_dD) to the basic data and write the remedied "
                        "design's development, the change recorded in its source (default: "
                        "the basic data as given, the remedy only offered; about twice the "
                        "CPU, three times where the first remedy's drive LTE exceeds 60 "
                        "urad between the torques and the next checked remedy is developed "
                        "too; contact.optimize.development_remedy)")
    # on a fresh numba cache only the envelope's kernels earn their compile back within
    # one synthesis (~10 s of compiling against ~14 s saved); the iso-lines', the shell's
    # and the block pivoting's (~17 s) do not: NumPy until cached (issue 75)
    p.set_defaults(func=run_synthesize, many_analyses=True,
                   compiled_kernels=("geometry.machine.envelope_numba",))


def bundled_basic_names() -> list[str]:
    """Names of the bundled basic design files (``cases/basic/*.toml``)."""
    from contact.catalogue import bundled_case_path

    root = bundled_case_path().parent / "basic"
    return sorted(p.stem for p in root.glob("*.toml")) if root.is_dir() else []


def synthesize_output(source: Path, output: str | None) -> Path:
    """The case file ``ltca synthesize`` writes: ``-o`` as given, else ``<stem>.toml`` of
    the basic file in the working directory, or ``<stem>_case.toml`` where that is the
    basic file itself (run beside its basic file, the command wrote the case over it:
    issue 71, unseen (12)).

    Parameters
    ----------
    source : pathlib.Path
        The basic design file read (:func:`resolve_basic`).
    output : str or None
        ``-o``, or None for the default.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        ``-o`` names the basic design file being read.
    """
    from geometry.core.errors import InputError

    def same(path: Path) -> bool:
        return path.resolve() == source.resolve()

    if output is not None:
        if same(Path(output)):
            raise InputError(f"-o: {output!r} is the basic design file being read; the "
                             "case would replace it: give another file (e.g. "
                             f"{source.stem}_case.toml)")
        return Path(output)
    default = Path(f"{source.stem}.toml")
    return Path(f"{source.stem}_case.toml") if same(default) else default


def resolve_basic(arg: str | None) -> Path:
    """A basic design file: a path, or a bundled name (``cases/basic/<name>.toml``); None
    the default case's.

    Raises
    ------
    InputError
        Neither a file nor a bundled name (the message lists the bundled ones).
    """
    from contact.catalogue import DEFAULT_CASE, bundled_case_path, closest_names
    from geometry.core.errors import InputError

    name = DEFAULT_CASE if arg is None else arg
    if Path(name).is_dir():
        raise InputError(f"BASIC: {name!r} is a directory, not a basic design file (TOML)")
    if Path(name).is_file():
        return Path(name)
    stem = Path(name).name.removesuffix(".toml")
    path = bundled_case_path().parent / "basic" / f"{stem}.toml"
    as_path = arg is not None and (len(Path(name).parts) > 1 or name.endswith(".toml"))
    if path.is_file() and not as_path:
        return path
    if as_path:  # a path that is not there: never read a bundled file in its place
        hint = (f"; the bundled basic design of that name is selected by its name alone: "
                f"{stem}" if path.is_file() else "")
        raise InputError(f"BASIC: no such file {name!r}{hint}")
    close = closest_names(stem, bundled_basic_names())
    hint = (f"did you mean {' or '.join(close)}?" if close else
            f"bundled: {', '.join(bundled_basic_names())}")
    raise InputError(f"BASIC: no such file and no bundled basic design {name!r}; {hint}")


def _say(line: str) -> None:
    """A development progress line on standard error, at once (plain text, as the
    synthesis' step lines: a log file reads it too)."""
    print(line, file=sys.stderr, flush=True)


def write_text_atomic(path: Path, text: str) -> Path:
    """Write ``text`` to ``path`` through a temporary file in the same directory + rename."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path




















































def run_synthesize(args: argparse.Namespace) -> int:
    """``ltca synthesize``: the case of a basic design file, developed and checked; dask
    kept out of the process (:func:`contact.commands.run.dask_hidden`).

    The command uses no dask: what imported it was the FE build of a new design's
    root-stress checks, whose datasets and cache entries xarray builds and writes with
    a look for dask's arrays and scheduler (dask.array and distributed imported, ~0.6 s
    of CPU per new design on the 2-core machine, issue 75; a design whose FE models are
    cached imported neither)."""
    from contact.commands.run import dask_hidden
    from geometry.core.errors import InputError
    from geometry.synthesis.case_synthesis import tried_text

    with dask_hidden():
        try:
            return _run_synthesize(args)
        except InputError as exc:
            # a synthesis that no gear process made: each process's reason, not the
            # last one's alone (geometry.synthesis.case_synthesis.tried_text)
            extra = tried_text(exc)
            if extra and extra not in str(exc):
                exc.args = (f"{exc}{extra}", *exc.args[1:])
            raise




def _print_lines(lines: list[str]) -> None:
    """Each line on standard output."""
    for line in lines:
        print(line)


def _run_synthesize(args: argparse.Namespace) -> int:
    """The command's body: the basic file resolved and the output checked, the case made
    by :func:`contact.optimize.synthesized_case.synthesize_case` (the Python API's one
    sequence), written and its lines printed."""
    from contact.commands.step_lines import StepLines
    from contact.optimize.synthesized_case import synthesize_case
    from geometry.core.heap import keep_heap_pages
    from geometry.synthesis.case_synthesis import SYNTHESIS_STEPS

    # the development's trials and checks allocate and free the same large arrays again
    # and again: glibc keeps their pages instead of mapping fresh ones each time (the
    # 9x41 hypoid's synthesize: 26 -> 6 s of system time with the FE worker's, the peak
    # memory the same; docs/performance.md)
    keep_heap_pages()
    source = resolve_basic(args.basic)
    output = synthesize_output(source, args.output)
    check_output_file(output, create_parents=True)
    shown = (f"cases/basic/{source.name}" if args.basic is None or not Path(args.basic).is_file()
             else Path(args.basic).as_posix())
    wanted = getattr(args, "progress", False)
    made = synthesize_case(
        source, fe_level=checked_fe_level(getattr(args, "fe_level", None)),
        development=getattr(args, "development", True),
        apply_remedy=getattr(args, "apply_remedy", False),
        progress=_say if wanted else None,
        synthesis_progress=StepLines("synthesize", SYNTHESIS_STEPS) if wanted else None,
        shown=shown)
    path = write_text_atomic(Path(output), made.text)
    _print_lines(made.lines(path))
    return 0
