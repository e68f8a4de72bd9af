"""The command line's paper cuts (issue 56, item 6), each refused or printed as a user needs.

* a mistyped option gets the sub-command's usage and the closest option it has;
* a torque ≤ 0 is refused before any work, naming ``--flank coast`` where the command
  has a flank to choose;
* ``ltca report`` of another command's file says what the file is and what reads it;
* HiGHS's banner never lands in ``ltca compare-solvers``' table (a fresh process: the
  banner comes once per process, from C);
* the friction model's extrapolation WARNING wraps to ≤ 100 columns
  (tests/test_kolivand2009.py);
* one unit spelling per medium (docs/nomenclature.md, Units): the console's is the files'
  UDUNITS spelling in ASCII (N m, um, urad, degC) — the figures and the HTML report write
  N·m, µm, µrad, °C — so no string of the commands spells a unit the other way, and a run
  prints none;
* the optional-dependency hints say how to install from a clone too.
"""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr

from contact.cli import main
from geometry.core.io import write_netcdf

ROOT = Path(__file__).resolve().parents[1]


def _refused(argv, capsys) -> str:
    with pytest.raises(SystemExit) as info:
        main(argv)
    assert info.value.code == 2
    return capsys.readouterr().err


@pytest.mark.parametrize("argv, usage, hint", [
    (["run", "--torqe", "5"], "usage: ltca run", "did you mean --torque?"),
    (["sweep", "--dEE", "0"], "usage: ltca sweep", "did you mean --dE?"),
    (["efficiency-map", "--rougness", "0.4"], "usage: ltca efficiency-map",
     "did you mean --roughness?"),
])
def test_a_mistyped_option_gets_the_commands_usage_and_a_suggestion(argv, usage, hint,
                                                                    capsys):
    err = _refused(argv, capsys)
    assert err.startswith(usage)
    last = err.strip().splitlines()[-1]
    assert last.startswith(f"ltca {argv[0]}: error: unrecognized arguments: {argv[1]}")
    assert hint in last


def test_an_unknown_word_gets_no_made_up_suggestion(capsys):
    last = _refused(["run", "--frobnicate"], capsys).strip().splitlines()[-1]
    assert "unrecognized arguments: --frobnicate" in last and "did you mean" not in last


def test_a_negative_torque_names_the_coast_flank(capsys, tmp_path):
    last = _refused(["run", "--torque", "-50", "-o", str(tmp_path / "r.nc")],
                    capsys).strip().splitlines()[-1]
    assert last == ("ltca run: error: --torque: must be > 0 [N m], got -50; the coast flank "
                    "is --flank coast with a positive torque")
    assert not (tmp_path / "r.nc").exists()
    # ltca rate rates the coast side by --flank coast too (issue 72): the same hint
    last = _refused(["rate", "--torque", "0"], capsys).strip().splitlines()[-1]
    assert last == ("ltca rate: error: --torque: must be > 0 [N m], got 0; the coast flank "
                    "is --flank coast with a positive torque")


@pytest.mark.parametrize("attrs, what, command", [
    ({"study": "sweep", "title": "hypoid-ltca sweep of x"}, "a misalignment sweep file",
     "ltca sweep"),
    ({"study": "sample"}, "a tolerance study file", "ltca tolerance"),
    ({"study": "vh-check"}, "a V-H check file", "ltca vh-check"),
    ({"title": "hypoid-ltca friction study: mixed-EHL line contacts"}, "a friction study file",
     "ltca friction-study"),
    ({"title": "mechanical efficiency map"}, "an efficiency map file", "ltca efficiency-map"),
])
def test_report_of_another_commands_file_names_it(attrs, what, command, tmp_path, capsys):
    path = write_netcdf(xr.Dataset({"x": ("point", [1.0], {"units": "1", "long_name": "x"})},
                                   attrs=attrs), tmp_path / "other.nc")
    assert main(["report", str(path), "-o", str(tmp_path / "r.html")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0
    assert err.startswith(f"ltca report: error: {str(path)!r} is {what}, written by "
                          f"`{command}`, not an analysis")
    assert "`ltca report` reads the files of `ltca run` and `ltca duty-cycle`" in err
    assert not (tmp_path / "r.html").exists()


def test_highs_says_nothing_inside_the_solver_table():
    """A fresh process solves one problem with HiGHS and prints a line: only the line."""
    code = (
        "import numpy as np\n"
        "from contact.qp import ContactProblem\n"
        "from contact.qp.solvers import get_backend\n"
        "p = ContactProblem(1e-5 * np.eye(3), [0.0, 1e-3, 2e-3], [80.0, 80.0, 80.0], 1e4)\n"
        "r = get_backend('highs').solve(p)\n"
        "print('| highs | solved |', r.force is not None)\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300, cwd=ROOT)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == "| highs | solved | True\n"


#: the figures' and the page's spellings, which the console does not use
_PAGE_UNITS = re.compile(r"N·m|µm|µrad|°C")


def _command_strings():
    """(file, line, text) of every string literal (and f-string part) of the command line's
    modules, docstrings and comments aside."""
    files = [ROOT / "contact" / "cli.py", *sorted((ROOT / "contact" / "commands").glob("*.py"))]
    for path in files:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        docstrings = {id(n.body[0].value) for n in ast.walk(tree)
                      if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef))
                      and n.body and isinstance(n.body[0], ast.Expr)
                      and isinstance(n.body[0].value, ast.Constant)}
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                    and id(node) not in docstrings:
                yield path.name, node.lineno, node.value


def test_the_command_line_writes_one_spelling_of_each_unit():
    """The console's spelling (docs/nomenclature.md: N m, um, urad, degC, as the files'
    ``units``): no string of the commands spells a unit as the figures and the page do,
    and a text shared with the page is converted on its way to the console."""
    from contact.commands.run import CONSOLE_UNITS

    bad = [f"{name}:{line}: {text!r}" for name, line, text in _command_strings()
           if _PAGE_UNITS.search(text) and text not in CONSOLE_UNITS]  # the converting table
    assert not bad, "the page's unit spellings in the command line:\n" + "\n".join(bad)
    from contact.commands.run import console_text

    assert console_text("at 50 N·m: 2.5 µm, 3 µrad, 90 °C") == "at 50 N m: 2.5 um, 3 urad, 90 degC"


def test_a_run_prints_one_spelling(tmp_path, capsys):
    assert main(["run", "--torque", "50", "--rolls-per-cycle", "4", "--segments", "8",
                 "--no-root-stress", "--no-rating", "-o", str(tmp_path / "r.nc")]) == 0
    out = capsys.readouterr().out
    assert "T_p [N m]" in out and "[urad]" in out and " degC" in out and " um" in out
    assert not _PAGE_UNITS.search(out), _PAGE_UNITS.search(out)


def test_install_hints_work_from_a_clone():
    from contact.compliance.fe.elasticity import SOLVERS, factorise
    from geometry.core.errors import ModelUnavailableError

    missing = [name for name, installed in SOLVERS.items() if not installed()]
    if not missing:
        pytest.skip("every FE solver is installed here")
    import numpy as np
    import scipy.sparse as sp

    with pytest.raises(ModelUnavailableError) as info:
        factorise(sp.identity(3, format="csr"), np.array([0]), missing[0])
    assert "pip install 'hypoid-ltca[fe]', from a clone: pip install '.[fe]'" in str(info.value)


class _Stop(Exception):
    """Raised in place of a study's work: the test is what the command printed before it."""


def _stop(*args, **kwargs):
    raise _Stop


@pytest.mark.parametrize(("argv", "target", "expected"), [
    (["duty-cycle", "--no-root-stress"], "contact.study.duty_cycle.run_duty_cycle",
     ["duty cycle of kolivand2009_fm_11x41_reference", "7 bins: T [N m] 50, 125, 200"]),
    (["efficiency-map", "--torque", "100", "250", "--speed", "500", "1500"],
     "contact.study.efficiency.efficiency_map",
     ["efficiency map of kolivand2009_fm_11x41_reference: torque [N m] 100, 250; speed "
      "[rpm] 500, 1500", "(4 points)"]),
    (["friction-study", "-n", "4", "--seed", "3"],
     "contact.study.friction_study.run_friction_study",
     ["friction study: 4 conditions (sobol, seed 3)"]),
])
def test_every_study_prints_what_it_will_run_before_it_starts(argv, target, expected,
                                                               monkeypatch, tmp_path, capsys):
    """Issue 56: every study prints the values it will run before it starts (the sweeps and
    the tolerance analysis: tests/test_study_inputs.py); here the duty cycle, the efficiency
    map and the friction study, whose work is replaced by an exception: what they printed
    is what a user sees before the first point."""
    from contact.cli import main

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(target, _stop)
    with pytest.raises(_Stop):
        main([*argv, "-o", str(tmp_path / "out.nc"), "--no-progress"])
    out = " ".join(capsys.readouterr().out.split())  # the lines are wrapped at 100 columns
    for text in expected:
        assert text in out, (text, out)
