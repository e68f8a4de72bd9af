"""The walk-through (docs/walkthrough.md, once the README's) runs as printed, from a
directory that is not the repository.

Every command of the walk-through's ``bash`` block is parsed from its page and run, in
order, through :func:`contact.cli.main` from an empty temporary directory, so a bundled
name or a ``cases/…`` path that only resolves inside a clone fails here, and so does a
command that reads a file an earlier one did not write under that name (``ltca plot
kolivand2009_fm_11x41_reference.nc`` after ``ltca run``).

Reduced resolution (the CI budget): options appended to a command replace the printed
ones (argparse keeps the last), and only the resolution changes — fewer roll positions,
torques, speeds, grid points, draws and steps, studies in this process, ``ltca run``
without its efficiency stage or its root stress (``--no-root-stress``: the FE build of each
case is tested in tests/test_root_stress.py and tests/test_fe_*.py) — never the command's
case, files or other options.
:data:`REDUCED` lists them. The commands whose cost no option reduces enough (the
synthesis, the Dask studies) run in the ``slow`` test; the CI test runs the others, in
order, and checks that the slow ones parse.
"""

from __future__ import annotations

import hashlib
import re
import shlex

import pytest
from doc_pages import WALKTHROUGH

from contact.cli import attach_negative_values, build_parser, main

#: command → options appended to it (the same options at a lower resolution)
REDUCED: dict[str, list[str]] = {
    "run": ["--rolls-per-cycle", "4", "--segments", "8", "--torque", "50", "--speed", "0",
            "--no-root-stress"],
    "plot": [],
    "report": [],
    "cases": [],
    "utca": ["--rolls-per-cycle", "8", "--nu", "15", "--nv", "9"],
    "geometry": ["--nu", "9", "--nv", "5"],
    "synthesize": [],
    "compare-solvers": ["--rolls-per-cycle", "4", "--torque", "50", "--solvers", "active_set"],
    "efficiency-map": ["--rolls-per-cycle", "4", "--segments", "8", "--torque", "100",
                       "--speed", "1500", "--roughness", "0.8"],
    "wear": ["--rolls-per-cycle", "4", "--segments", "8", "--steps", "1"],
    "sweep": ["--rolls-per-cycle", "4", "--dE", "-0.1,0.1", "--dP", "0",
              "--scheduler", "synchronous"],
    "tolerance": ["--rolls-per-cycle", "4", "-n", "4", "--scheduler", "synchronous"],
    "vh-check": ["--rolls-per-cycle", "4", "--dE", "-0.55:0.25:3", "--dP", "-0.18:0.42:3",
                 "--scheduler", "synchronous"],
    "mesh-interface": ["--rolls-per-cycle", "4", "--segments", "8", "--torque", "50"],
    "ehl": ["--nodes", "256"],
}


def walkthrough_commands() -> list[list[str]]:
    """The ``ltca`` commands of the walk-through's first block, as argument lists."""
    text = WALKTHROUGH.read_text(encoding="utf-8")
    section = text[text.index("# Walk-through"):]
    block = re.search(r"```bash\n(.*?)```", section, flags=re.S).group(1)
    out = []
    for line in block.splitlines():
        words = shlex.split(line, comments=True)
        if words:
            assert words[0] == "ltca", line
            out.append(words[1:])
    return out


COMMANDS = walkthrough_commands()
#: commands run only by the slow test (each > 10 s even reduced, on one loaded core)
SLOW = ("synthesize", "sweep", "tolerance", "vh-check")


def test_walkthrough_reads_no_repository_path():
    """No ``cases/…`` path: bundled names work from any directory."""
    for argv in COMMANDS:
        assert not any(w.startswith("cases/") for w in argv), argv


def test_every_command_is_reduced_and_parses():
    parser = build_parser()
    for argv in COMMANDS:
        assert argv[0] in REDUCED, f"no reduced resolution for `ltca {argv[0]}`"
        args = parser.parse_args(attach_negative_values([*argv, *REDUCED[argv[0]]]))
        assert args.command == argv[0]


def _contents(directory) -> dict:
    """Every file under ``directory`` → the SHA-256 of its bytes."""
    return {p.relative_to(directory): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in directory.rglob("*") if p.is_file()}


def _run_all(commands, tmp_path, monkeypatch, capsys):
    """Run ``commands`` in order in ``tmp_path``; no command may replace a file an earlier
    one wrote with different content (issue 56: figure names carry what they show, so
    e.g. `ltca utca --plots figs` keeps the loaded figures of `ltca plot … --plots figs`)."""
    monkeypatch.chdir(tmp_path)
    written: dict = {}  # file → (its content, the command that wrote it)
    for argv in commands:
        code = main([*argv, *REDUCED[argv[0]], "-q"])
        out = capsys.readouterr()
        assert code == 0, f"ltca {' '.join(argv)}: {out.err}"
        for path, digest in _contents(tmp_path).items():
            before = written.get(path)
            assert before is None or before[0] == digest, (
                f"`ltca {' '.join(argv)}` overwrote {path}, written by `ltca {before[1]}`, "
                "with different content")
            if before is None:
                written[path] = (digest, " ".join(argv))
    return written


def test_walkthrough_runs_from_a_scratch_directory(tmp_path, monkeypatch, capsys):
    written = _run_all([a for a in COMMANDS if a[0] not in SLOW], tmp_path, monkeypatch,
                       capsys)
    # the loaded figures of the default run and the unloaded ones of `ltca utca` side by
    # side, each command's under its own name
    figures = {p.name for p in written if p.parent.name == "figs"}
    case = "kolivand2009_fm_11x41_reference"
    for name in ("contact_pattern", "transmission_error"):
        assert f"{case}_T50_{name}.png" in figures and f"{case}_unloaded_{name}.png" in figures
    assert f"{case}_mesh_interface_T50.png" in figures  # the command's, beside plot's
    # outputs named after the case, so `ltca plot` redrew the default run
    assert (tmp_path / "kolivand2009_fm_11x41_reference.nc").is_file()
    assert (tmp_path / "kolivand2009_table54_B_fh.nc").is_file()
    assert (tmp_path / "kolivand2009_fm_11x41_reference_utca.nc").is_file()
    assert (tmp_path / "report.html").is_file()
    assert any((tmp_path / "figs").glob("*.png"))


@pytest.mark.slow
def test_whole_walkthrough_runs_from_a_scratch_directory(tmp_path, monkeypatch, capsys):
    _run_all(COMMANDS, tmp_path, monkeypatch, capsys)
    assert (tmp_path / "my_case.toml").is_file() and (tmp_path / "map.nc").is_file()
