"""The ``ltca`` command line: a thin layer that parses, calls library functions, prints, writes.

No physics here: every command calls functions users can call from Python. Each
sub-command lives in its own module of :mod:`contact.commands` with a
``register(subparsers)`` function and an integer ``ORDER`` (its place in
``ltca --help``); the modules are found by :func:`command_modules`.
"""

from __future__ import annotations

import argparse
import contextlib
import difflib
import importlib
import logging
import os
import pkgutil
import re
import signal
import sys
import threading
from collections.abc import Iterator, Sequence
from types import ModuleType

from contact.commands.options import verbosity_options
from contact.errors import AnalysisFailedError
from geometry import __version__
from geometry.core.blas import limit_at_start
from geometry.core.errors import LTCAError

log = logging.getLogger("ltca")


def command_modules() -> list[ModuleType]:
    """Every command module of :mod:`contact.commands` (those with a ``register``; the
    shared options of :mod:`contact.commands.options` are none), sorted by its ``ORDER``."""
    import contact.commands as pkg

    mods = [
        importlib.import_module(f"{pkg.__name__}.{info.name}")
        for info in pkgutil.iter_modules(pkg.__path__)
        if not info.name.startswith("_")
    ]
    mods = [m for m in mods if hasattr(m, "register")]
    return sorted(mods, key=lambda m: (getattr(m, "ORDER", 100), m.__name__))


class _HelpFormatter(argparse.HelpFormatter):
    """argparse's formatter, but an ``examples:`` epilog keeps its lines (one command
    each) instead of being filled into a paragraph."""

    def _fill_text(self, text: str, width: int, indent: str) -> str:
        if text.startswith("examples:"):
            return "\n".join(indent + line for line in text.splitlines())
        return super()._fill_text(text, width, indent)


def _epilog(lines) -> str:
    return "examples:\n" + "\n".join(f"  {line}" for line in lines)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``ltca`` (one sub-command group per command module); each
    command's help ends with its examples (:mod:`contact.commands.examples`)."""
    from contact.commands.examples import EXAMPLES, TOP_EXAMPLES

    parser = argparse.ArgumentParser(
        prog="ltca",
        description="Loaded tooth contact analysis of hypoid and spiral bevel gears. Every "
        "command takes a case file or a bundled case name (default the bundled default "
        "case) at its [operating] conditions unless options override them.",
        epilog=_epilog(TOP_EXAMPLES), formatter_class=_HelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"hypoid-ltca {__version__}")
    verbosity_options(parser, top=True)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for module in command_modules():
        module.register(sub)
    for name, command in sub.choices.items():  # -v/-q also after the command
        verbosity_options(command)
        command.formatter_class = _HelpFormatter
        if name in EXAMPLES and not command.epilog:
            command.epilog = _epilog(EXAMPLES[name])
    return parser


_NEGATIVE_VALUE = re.compile(r"^-\.?\d")
#: what argparse itself reads as a negative number, not an option (its own pattern)
_PLAIN_NEGATIVE = re.compile(r"^-\d+$|^-\d*\.\d+$")


def attach_negative_values(argv: Sequence[str]) -> list[str]:
    """``--opt -0.2:0.2:21`` → ``--opt=-0.2:0.2:21``: argparse reads a value that starts
    with ``-`` but is not a plain number (a range such as ``-0.2:0.2:21``, a list
    ``-0.1,0.1`` or ``-1e-3``) as an option; attached with ``=`` it is the option's value.
    A plain negative number (``-0.3``) is left for argparse, which takes it as a value —
    also as the first of an option's several values (``--roughness -0.3 0.3``), which an
    attached ``=`` would cut off."""
    out: list[str] = []
    for token in argv:
        prev = out[-1] if out else ""
        if (_NEGATIVE_VALUE.match(token) and not _PLAIN_NEGATIVE.match(token)
                and prev.startswith("--") and "=" not in prev and len(prev) > 2):
            out[-1] = f"{prev}={token}"
        else:
            out.append(token)
    return out


def _subcommand(parser: argparse.ArgumentParser, name: str | None):
    """The sub-command parser ``name`` of ``parser`` (None: no such command)."""
    for action in parser._actions:  # argparse keeps its sub-parsers on this action
        if isinstance(action, argparse._SubParsersAction):
            return action.choices.get(name)
    return None


def suggest_options(parser: argparse.ArgumentParser, tokens: Sequence[str]) -> list[str]:
    """``"did you mean --torque?"`` for each mistyped option among ``tokens`` that is close
    to one of ``parser``'s (difflib's similarity ≥ 0.75: a slip of a letter or two, not
    another word); none for the others."""
    options = [o for a in parser._actions for o in a.option_strings if o.startswith("--")]
    hints = []
    for token in tokens:
        if token.startswith("--"):
            close = difflib.get_close_matches(token.split("=", 1)[0], options, n=1,
                                              cutoff=0.75)
            if close:
                hints.append(f"did you mean {close[0]}?")
    return hints


def parse_arguments(parser: argparse.ArgumentParser, argv: Sequence[str]) -> argparse.Namespace:
    """Parse ``argv`` (after :func:`attach_negative_values`); refuse, with the sub-command's
    usage (exit 2), an option it does not know — suggesting the closest one it does
    (``ltca run --torqe 5``: "did you mean --torque?") — and a torque ≤ 0 (the coast flank
    is ``--flank coast`` with a positive torque, where the command has ``--flank``)."""
    args, extras = parser.parse_known_args(attach_negative_values(argv))
    command = _subcommand(parser, getattr(args, "command", None)) or parser
    if extras:
        hints = suggest_options(command, extras)
        command.error(f"unrecognized arguments: {' '.join(extras)}"
                      + (f" ({'; '.join(hints)})" if hints else ""))
    torque = getattr(args, "torque", None)
    if torque is not None:
        values = torque if isinstance(torque, list) else [torque]
        bad = [t for t in values if not t > 0.0]
        if bad:
            coast = any("--flank" in a.option_strings for a in command._actions)
            command.error(f"--torque: must be > 0 [N m], got {bad[0]:g}"
                          + ("; the coast flank is --flank coast with a positive torque"
                             if coast else ""))
    return args


#: option (argparse dest) → its bound in :data:`geometry.core.bounds.PHYSICAL_BOUNDS`, for
#: every command but those of :data:`OWN_BOUNDS`
OPTION_BOUNDS = {"torque": "torque", "speed": "pinion_speed", "temperature": "temperature",
                 "roughness": "roughness"}
#: commands whose options of those names mean other quantities, checked by the command
#: (``ltca ehl``: --speed the entraining velocity [m/s], --roughness two flanks' Rq)
OWN_BOUNDS = ("ehl",)


def check_option_bounds(args: argparse.Namespace) -> None:
    """Refuse (InputError: exit 2, one line) an operating option outside the one table of
    physical bounds (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`: ``--torque`` (0, 1e6]
    N m, ``--speed`` (0, 5e4] rpm — 0 where a command takes it for "no efficiency stage" —,
    ``--temperature`` [-40, 200] degC, ``--roughness`` (0, 5] um) before any work, for
    every command that has them (issue 64: ``ltca rate --speed 1e12`` printed full tables).
    """
    if getattr(args, "command", None) in OWN_BOUNDS:
        return
    from geometry.core.bounds import check_bound

    for dest, bound in OPTION_BOUNDS.items():
        value = getattr(args, dest, None)
        for v in value if isinstance(value, (list, tuple)) else [value]:
            if v is None or (dest == "speed" and v == 0):
                continue
            check_bound(bound, v, field=f"--{dest}", positive=dest == "roughness")


def compile_note() -> str | None:
    """The line a command that runs the compiled kernels prints before numba compiles them
    (its cache holds no kernels for this machine yet: a fresh install or source tree), or
    None (the NumPy path, or the kernels cached).

    The first ``ltca synthesize`` of a fresh tree said nothing for 98 s of wall time at a
    load of 14 (the compiling, ≈ 20 s of CPU on an idle machine) and then 150 s more before
    its first trial (issue 71, round 13; docs/performance.md, "Compiled kernels"). The
    note then said "about 20 s of CPU before the first lines", but numba compiles each
    kernel at its first call: the geometry's before the first line, the contact
    analysis's (UTCA, compliance, QP) within the first analysis — round 16's first two
    runs printed the development's first line after 87–103 s and then nothing for 147–163
    s (load 15), its first design reading 32 s of CPU where the others read 1 s. The note
    says both waits.

    Returns
    -------
    str or None
    """
    from geometry.core.kernels import KERNEL_MODULES, cache_ready, compiled_modules

    names = compiled_modules()
    if not names or all(cache_ready(name) for name in names):
        return None
    if names != KERNEL_MODULES:  # ltca synthesize on a fresh cache: the envelope's only
        return ("note: compiling the geometry's numba kernels for this machine, once "
                "(about 10 s of CPU, before the first lines); the contact analysis runs "
                "NumPy until numba's cache holds its kernels too: `ltca compile` compiles "
                "them all (about 30 s of CPU), docs/environment.md")
    return ("note: compiling the numba kernels for this machine, once: the geometry's "
            "before the first lines, the contact analysis's within the first analysis (a "
            "development's first design then takes about 30 s of CPU where the others take "
            "about 1 s), minutes of wall time on a loaded machine; later runs read them "
            "from numba's cache; `ltca compile` compiles them ahead (about 30 s of CPU), "
            "docs/environment.md")


class _CompileNote(logging.Handler):
    """Prints the compile note to stderr at the first record it receives, once."""

    def __init__(self, note: str) -> None:
        super().__init__(logging.INFO)
        self.note = note
        self.printed = False

    def emit(self, record: logging.LogRecord) -> None:
        if not self.printed:
            self.printed = True
            print(self.note, file=sys.stderr, flush=True)


@contextlib.contextmanager
def compile_note_when_compiling(note: str | None) -> Iterator[_CompileNote | None]:
    """Print ``note`` (:func:`compile_note`) when numba starts compiling, not before.

    Within the context, the first record of :data:`geometry.core.kernels.COMPILING_LOGGER`
    (:func:`geometry.core.kernels.announce_compiling`: a compiled module handed to a hot
    loop or to a study's workers while numba's cache holds none of its kernels) prints the
    note to stderr, once; the records themselves are not shown. A command refused on its
    inputs or outputs before any kernel runs prints its refusal alone: before, the note
    came first on every fresh cache (issue 71; tests/test_cli.py's ``_refusal`` stripped it).

    Parameters
    ----------
    note : str or None
        The line to print; None: nothing to print (the context does nothing).

    Yields
    ------
    handler or None
        The handler (its ``printed`` says whether the note was printed), None without a note.
    """
    if note is None:
        yield None
        return
    from geometry.core.kernels import COMPILING_LOGGER

    logger = logging.getLogger(COMPILING_LOGGER)
    handler = _CompileNote(note)
    level, propagate = logger.level, logger.propagate
    logger.setLevel(logging.INFO)
    logger.propagate = False
    logger.addHandler(handler)
    try:
        yield handler
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)
        logger.propagate = propagate


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``ltca`` console script and ``python -m contact``."""
    parser = build_parser()
    as_process = argv is None  # the console script or python -m contact: the command is the process
    argv = list(sys.argv[1:] if argv is None else argv)
    args = parse_arguments(parser, argv)
    args.argv = argv  # as typed, for the provenance of files a command writes
    args.verbose = args.verbose + getattr(args, "verbose_sub", 0)
    args.quiet = args.quiet or getattr(args, "quiet_sub", False)
    if args.quiet and args.verbose:
        parser.error("-q/--quiet and -v/--verbose exclude each other")
    if hasattr(args, "no_progress"):
        # the studies' progress (geometry.core.progress): a bar on a terminal, plain
        # periodic lines anywhere else (a file, a pipe), none with -q or --no-progress;
        # every other progress bar only on a terminal
        terminal = sys.stderr.isatty()
        args.no_progress = args.no_progress or args.quiet
        args.progress = False if args.no_progress else (True if terminal else "lines")
        args.no_progress = args.no_progress or not terminal
    level = ([logging.WARNING, logging.INFO, logging.DEBUG][min(args.verbose, 2)]
             if not args.quiet else logging.ERROR)
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s")
    # Dask's scheduler and workers log every start and stop at INFO: only with -vv.
    # distributed sets its loggers' levels from dask's config when it is imported (in
    # this process and in every worker process), so the config says it, not a setLevel.
    distributed_level = "debug" if args.verbose >= 2 else "warning"
    # dask reads the variable when first imported; only a dask already imported (not the
    # case for most commands, which should not pay for importing it) needs telling
    os.environ["DASK_LOGGING__DISTRIBUTED"] = distributed_level
    if "dask" in sys.modules:
        sys.modules["dask"].config.set({"logging.distributed": distributed_level})
    logging.getLogger("distributed").setLevel(distributed_level.upper())
    main_thread = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGTERM, _terminate) if main_thread else None
    stack = contextlib.ExitStack()
    try:
        check_option_bounds(args)  # before any work
        # one BLAS thread for the command's computations (its matrices are small,
        # geometry.core.blas), set before NumPy loads: `ltca cases` stays light
        limit_at_start()
        if getattr(args, "many_analyses", False):
            # the compiled kernels earn their first-use compile back over many analyses
            # (geometry.core.kernels: a single analysis runs the NumPy path until cached)
            from geometry.core.kernels import prefer_compiled

            # a command of its own process may name the kernels that earn their compile
            # back in it (``compiled_kernels``: ltca synthesize, the envelope's; issue 75)
            prefer_compiled(getattr(args, "compiled_kernels", None) if as_process else None)
            # said when numba starts compiling: a refusal of the command's inputs or
            # outputs comes before, alone (issue 71)
            stack.enter_context(compile_note_when_compiling(
                None if args.quiet else compile_note()))
        elif as_process and getattr(args, "one_analysis", False):
            # one analysis never earns the compile back, nor on a full cache numba's
            # import and kernel loading: the NumPy path (geometry.core.kernels.
            # prefer_numpy, issue 75), the same numbers whatever numba's cache holds
            from geometry.core.heap import keep_heap_pages
            from geometry.core.kernels import prefer_numpy

            prefer_numpy()
            # its large arrays (the FE build's assembly, loads and solutions) reuse the
            # process's pages: the cold first run's system time 4.2 -> 1.8 s (issue 75)
            keep_heap_pages()
        return int(args.func(args) or 0)
    except AnalysisFailedError as exc:  # ran, wrote its file, found no certified contact
        print(f"ltca {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except LTCAError as exc:
        print(f"ltca {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        # Ctrl-C or SIGTERM: one line, no traceback; files being written were left as they
        # were (geometry.core.atomic_files); the shell's code 128 + signal number
        signum = exc.signum if isinstance(exc, Terminated) else signal.SIGINT
        print(f"ltca {args.command}: interrupted ({signal.Signals(signum).name}); "
              "files being written were left as they were", file=sys.stderr)
        return 128 + int(signum)
    finally:
        stack.close()
        if main_thread:
            signal.signal(signal.SIGTERM, previous)


class Terminated(KeyboardInterrupt):
    """SIGTERM received: stop as Ctrl-C does (files under write keep their old content)."""

    def __init__(self, signum: int) -> None:
        super().__init__(f"signal {signum}")
        self.signum = signum


def _terminate(signum: int, frame: object) -> None:
    raise Terminated(signum)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
