"""``ltca --help`` and ``ltca cases`` import only what they need (issue 32: start-up).

Each command module imports its own dependencies inside its run function, the packages'
public names are imported when first used (``geometry.core.lazy``), and the help's data
(the optimisers, the correctable settings) live in light modules. What is checked here is
the import set, not a time (speed targets are benchmarks' business): ``ltca --help``
imports neither NumPy nor SciPy, xarray, pandas, dask, matplotlib or scikit-fem; ``ltca cases``
(which loads every bundled case file, so NumPy) imports none of the others. On a quiet
core ``ltca --help`` then takes about 0.1 s of CPU, ``ltca cases`` about 0.2 s
(``benchmarks/startup.py``); before, 1.3–1.5 s.

Cheap enough for CI: two fresh interpreters, each well under a second.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

HEAVY = ("scipy", "xarray", "pandas", "dask", "distributed", "matplotlib", "netCDF4",
         "qpsolvers", "skfem", "tqdm", "jinja2")

_RUN = """
import contextlib, io, json, sys
from contact.cli import main
out = io.StringIO()
with contextlib.redirect_stdout(out):
    try:
        code = main({argv!r})
    except SystemExit as exc:  # argparse's --help exits
        code = exc.code
print(json.dumps({{"code": code, "modules": sorted(sys.modules), "out": out.getvalue()}}))
"""


def _imports(argv: list[str]) -> dict:
    done = subprocess.run([sys.executable, "-c", _RUN.format(argv=argv)], capture_output=True,
                          text=True, timeout=120, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def _top(modules: list[str]) -> set[str]:
    return {m.split(".")[0] for m in modules}


def test_help_imports_no_numerical_library():
    res = _imports(["--help"])
    assert res["code"] == 0
    assert "cases" in res["out"] and "sweep" in res["out"]  # every command is listed
    loaded = _top(res["modules"])
    assert not loaded & {"numpy", *HEAVY}, sorted(loaded & {"numpy", *HEAVY})


@pytest.mark.parametrize("command", ["correct", "optimize", "synthesize"])
def test_command_help_that_lists_data_imports_no_numerical_library(command):
    """The helps that list names from the library (correctable settings and their
    defaults, optimisers, bundled basic designs) take them from light modules."""
    res = _imports([command, "--help"])
    assert res["code"] == 0
    assert not _top(res["modules"]) & {"numpy", *HEAVY}


def test_cases_imports_only_the_case_files():
    res = _imports(["cases"])
    assert res["code"] == 0
    assert "kolivand2009_fm_11x41_reference" in res["out"]
    assert not _top(res["modules"]) & set(HEAVY), sorted(_top(res["modules"]) & set(HEAVY))
