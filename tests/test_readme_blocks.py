"""Every ``bash`` block of the README and of the pages that were its sections
(tests/doc_pages.py) runs as written from a scratch directory, or says where it runs
(issue 38: "every README block should run from any directory or say where it runs").

The install-and-run block (install and run, install and test) is CI's own command
(``tests/test_readme.py``); the walk-through has its own test
(``tests/test_readme_walkthrough.py``). Every other block is parsed here: its ``ltca``
commands (continuation lines joined) are run in order, block by block, through
:func:`contact.cli.main` from an empty temporary directory, at the reduced resolution of
``test_readme_walkthrough.REDUCED`` (only the resolution changes: fewer rolls, torques,
speeds, steps, evaluations — never a case, a file or another option). A command that is
not ``ltca`` (``pip``, ``python benchmarks/…``, ``qpbenchmark``) needs a clone: its block
must say so ("from the root of a clone") and the files it names must exist in the
repository. No command reads a ``cases/…`` path.

CI runs the blocks whose commands are cheap reduced (< 10 s each); the ``slow`` test runs
them all (the synthesis, the optimisation).
"""

from __future__ import annotations

import re
import shlex
import tomllib
from pathlib import Path

import pytest
from doc_pages import blocks
from test_readme_walkthrough import REDUCED

from contact.cli import attach_negative_values, build_parser, main

ROOT = Path(__file__).resolve().parent.parent

#: further reductions for commands of these blocks (same meaning as REDUCED)
MORE: dict[str, list[str]] = {
    "correct": [],
    "optimize": ["--max-evaluations", "2", "--rolls-per-cycle", "4", "--torque", "50"],
    "export-problems": ["--rolls-per-cycle", "4", "--torque", "50"],
    "mesh-interface": ["--rolls-per-cycle", "4", "--segments", "8", "--torque", "50"],
    "duty-cycle": ["--rolls-per-cycle", "4", "--segments", "8", "--scheduler", "synchronous"],
}
#: commands too costly for CI even reduced (each > 10 s on one loaded core; duty-cycle:
#: seven analyses)
SLOW = ("synthesize", "optimize", "export-problems", "duty-cycle")
CLONE = "from the root of a clone"


def _blocks() -> list[tuple[str, str]]:
    return blocks("bash")


def _commands(block: str) -> list[list[str]]:
    joined = re.sub(r"\\\n\s*", " ", block)
    return [w for w in (shlex.split(ln, comments=True) for ln in joined.splitlines()) if w]


#: the install-and-run block (CI's), on the README and the getting-started page
INSTALL = "pip install . && ltca run\npip install '.[test]' && pytest"
#: (page:line, commands) of every block but the install-and-run and the walk-through's
BLOCKS = [(line, _commands(b)) for line, b in _blocks()
          if b.strip() != INSTALL and not b.lstrip().startswith("ltca cases")]


#: options that take one value or one per torque: when the reduction keeps fewer torques
#: than the block gives, these keep the values of the torques kept (else the command
#: would be refused for a count mismatch the block as written does not have)
PER_TORQUE = ("--max-edge-share", "--max-flank-pressure")


def _values(argv: list[str], option: str) -> tuple[int, int]:
    """Where ``option``'s values start in ``argv`` and where they end (exclusive)."""
    start = argv.index(option) + 1
    end = start
    while end < len(argv) and not (argv[end].startswith("--") or argv[end] == "-o"):
        end += 1
    return start, end


def _reduced(argv: list[str]) -> list[str]:
    extra = [*REDUCED.get(argv[0], []), *MORE.get(argv[0], [])]
    argv = list(argv)
    if "--torque" in argv and "--torque" in extra:
        start, end = _values(argv, "--torque")
        given = [float(w) for w in argv[start:end]]
        ks, ke = _values(extra, "--torque")
        kept = [given.index(float(w)) if float(w) in given else 0 for w in extra[ks:ke]]
        for option in PER_TORQUE:
            if option not in argv:
                continue
            start, end = _values(argv, option)
            values = argv[start:end]
            if len(values) == len(given) > 1:
                argv[start:end] = [values[i] for i in kept]
    return [*argv, *extra]


def test_blocks_found():
    assert len(BLOCKS) >= 3  # face hobbing, correction/optimisation, qpbenchmark


@pytest.mark.parametrize(("line", "commands"), BLOCKS, ids=[n for n, _ in BLOCKS])
def test_block_reads_no_repository_path_and_parses(line, commands):
    block = dict(_blocks())[line]
    parser = build_parser()
    for words in commands:
        assert not any(w.startswith("cases/") for w in words), words
        if words[0] == "ltca":
            args = parser.parse_args(attach_negative_values(_reduced(words[1:])))
            assert args.command == words[1]
            continue
        # not ltca: it needs the clone, and the block says so
        assert CLONE in block, f"{line}: `{' '.join(words)}` needs a clone"
        for w in words:
            if w.startswith("benchmarks/") and w.endswith(".py"):
                assert (ROOT / w).is_file(), w
        if words[:2] == ["pip", "install"]:
            extra = re.search(r"\[(\w+)\]", words[2]).group(1)
            project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
            assert extra in project["optional-dependencies"], extra


def _output(words: list[str]) -> str | None:
    return words[words.index("-o") + 1] if "-o" in words else None


def _run_block(commands, tmp_path, monkeypatch, capsys, skip=()) -> tuple[int, int]:
    """Run the block's ``ltca`` commands in order; those in ``skip``, and any that reads a
    file a skipped one writes, are left out. Returns how many ran and how many were left
    out only because they read a skipped command's file."""
    monkeypatch.chdir(tmp_path)
    ran, dependent, missing = 0, 0, set()
    for words in commands:
        if words[0] != "ltca":
            continue
        if words[1] in skip or missing & set(words):
            dependent += words[1] not in skip
            missing.add(_output(words))
            continue
        code = main([*_reduced(words[1:]), "-q"])
        out = capsys.readouterr()
        assert code == 0, f"ltca {' '.join(words[1:])}: {out.err}"
        ran += 1
    return ran, dependent


@pytest.mark.parametrize(("line", "commands"), BLOCKS, ids=[n for n, _ in BLOCKS])
def test_block_runs_from_a_scratch_directory(line, commands, tmp_path, monkeypatch, capsys):
    """CI's share: the slow commands (and what reads their files) left out."""
    cheap = [w for w in commands if w[0] == "ltca" and w[1] not in SLOW]
    ran, dependent = _run_block(commands, tmp_path, monkeypatch, capsys, skip=SLOW)
    assert ran >= min(1, len(cheap) - dependent)


@pytest.mark.slow
@pytest.mark.parametrize(("line", "commands"), BLOCKS, ids=[n for n, _ in BLOCKS])
def test_whole_block_runs_from_a_scratch_directory(line, commands, tmp_path, monkeypatch,
                                                   capsys):
    _run_block(commands, tmp_path, monkeypatch, capsys)
