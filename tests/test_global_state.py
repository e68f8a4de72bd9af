"""Library calls leave the process as they found it (issue 54 item 6).

* a plot call leaves matplotlib's backend alone (a notebook's inline figures keep
  working): checked by running the toolkit's figure writers in a process whose backend
  is set to one the toolkit would never choose, and by reading the source for
  ``matplotlib.use`` and ``pyplot`` outside the command line;
* every per-process cache is one of :mod:`geometry.core.caches` (no other ``lru_cache``
  in the source), is emptied by one :func:`contact.clear_caches`, and is listed in
  docs/environment.md;
* every environment variable the library reads is listed in docs/environment.md.

The references are the toolkit's own source (read with ``ast``) and matplotlib's
``get_backend``: exact checks, no tolerance.
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "friction", "geometry")
ENVIRONMENT_DOC = ROOT / "docs" / "environment.md"
#: the one module that may choose a matplotlib backend or use pyplot: the command line
#: (it needs neither today)
CLI_MODULES = {"contact/cli.py", "contact/__main__.py"}


def _sources() -> list[Path]:
    return sorted(p for pkg in PACKAGES for p in (ROOT / pkg).rglob("*.py"))


#: every source file's syntax tree, parsed once for the module's tests (each of the
#: seven source scans parsed the whole toolkit again, ~3 s of CPU each; the trees are
#: only read)
_TREES: dict[Path, ast.Module] = {}


def _tree(path: Path) -> ast.Module:
    """The syntax tree of a source file (parsed on first use)."""
    if path not in _TREES:
        _TREES[path] = ast.parse(path.read_text(encoding="utf-8"))
    return _TREES[path]


def _rel(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


def _dotted(node: ast.AST) -> str:
    """``a.b.c`` of an attribute chain (empty for anything else)."""
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
        return ".".join(reversed(parts))
    return ""


_PLOTTING = """
import sys
from pathlib import Path

import matplotlib

matplotlib.use("template")  # a backend no toolkit call would choose

import xarray as xr

from contact.catalogue import resolve_case
from contact.plots import analysis_figures, save_png
from contact.study.figures import save_study_figures
from geometry.machine.flank import flank_surface
from geometry.plot import plot_flanks_in_mesh, plot_projection_grid

out = Path(sys.argv[1])
data = Path(sys.argv[2])
case = resolve_case(None)
surface = flank_surface(case, "pinion", "concave", nu=9, nv=7)
plot_projection_grid(surface, case.pinion.blank, out / "grid.png")
plot_flanks_in_mesh(case, [surface], out / "mesh.png")
tree = xr.open_datatree(sys.argv[3])  # the default run (tests/conftest.py)
first = next(iter(analysis_figures(tree)))
save_png(first.figure, out / "analysis.png")
save_study_figures(xr.open_dataset(data / "sweep_guard_5x5.nc"), out)
print(matplotlib.get_backend(), "matplotlib.pyplot" in sys.modules)
"""


def test_plot_calls_leave_the_matplotlib_backend_alone(tmp_path, default_run_file):
    """geometry.plot's writers, an analysis figure (contact.plots, of the default run the
    session shares) and a study's figures (contact.study.figures), drawn in a process
    whose backend is ``template``: the backend is still ``template`` afterwards and pyplot
    was never imported (pyplot would pick a backend of its own on import)."""
    run = subprocess.run(
        [sys.executable, "-c", _PLOTTING, str(tmp_path), str(ROOT / "tests" / "data"),
         str(default_run_file)],
        capture_output=True, text=True, cwd=tmp_path,
        env={**{k: v for k, v in os.environ.items() if k != "MPLBACKEND"},
             "PYTHONPATH": str(ROOT)})
    assert run.returncode == 0, run.stderr
    backend, pyplot_imported = run.stdout.split()
    assert backend == "template"
    assert pyplot_imported == "False"
    written = sorted(p.name for p in tmp_path.glob("*.png"))
    assert {"grid.png", "mesh.png", "analysis.png"} <= set(written) and len(written) > 3


def test_library_code_never_chooses_a_backend_nor_imports_pyplot():
    bad = []
    for path in _sources():
        if _rel(path) in CLI_MODULES:
            continue
        for node in ast.walk(_tree(path)):
            if isinstance(node, ast.Call) and _dotted(node.func) == "matplotlib.use":
                bad.append(f"{_rel(path)}:{node.lineno}: matplotlib.use")
            elif isinstance(node, ast.Import) and any(
                    a.name == "matplotlib.pyplot" for a in node.names):
                bad.append(f"{_rel(path)}:{node.lineno}: import matplotlib.pyplot")
            elif isinstance(node, ast.ImportFrom) and (
                    node.module == "matplotlib.pyplot"
                    or (node.module == "matplotlib"
                        and any(a.name == "pyplot" for a in node.names))):
                bad.append(f"{_rel(path)}:{node.lineno}: imports pyplot")
    assert not bad, "library code changes matplotlib's global state:\n" + "\n".join(bad)


def _memoised_functions() -> list[tuple[str, str]]:
    """(module path, function name) of every ``@memoised`` function in the source."""
    out = []
    for path in _sources():
        for node in ast.walk(_tree(path)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                for dec in node.decorator_list:
                    target = dec.func if isinstance(dec, ast.Call) else dec
                    if _dotted(target).endswith("memoised"):
                        out.append((_rel(path), node.name))
    return out


def test_every_cache_goes_through_the_one_registry():
    """No ``functools.lru_cache``/``cache`` outside geometry.core.caches: each memo is a
    :func:`geometry.core.caches.memoised`, so :func:`clear_caches` reaches it."""
    bad = []
    for path in _sources():
        if _rel(path) == "geometry/core/caches.py":
            continue
        for node in ast.walk(_tree(path)):
            if isinstance(node, ast.ImportFrom) and node.module == "functools":
                names = {a.name for a in node.names} & {"lru_cache", "cache"}
                if names:
                    bad.append(f"{_rel(path)}:{node.lineno}: from functools import "
                               f"{', '.join(sorted(names))}")
            elif isinstance(node, ast.Attribute) and _dotted(node) in (
                    "functools.lru_cache", "functools.cache"):
                bad.append(f"{_rel(path)}:{node.lineno}: {_dotted(node)}")
    assert not bad, ("caches that clear_caches() does not reach (use "
                     "geometry.core.caches.memoised):\n" + "\n".join(bad))
    assert len(_memoised_functions()) >= 12  # the memos listed in docs/environment.md


def test_every_cache_is_documented():
    text = ENVIRONMENT_DOC.read_text(encoding="utf-8")
    missing = [f"{module}: {name}" for module, name in _memoised_functions()
               if f"`{name}`" not in text and f".{name}`" not in text]
    assert not missing, "caches missing from docs/environment.md:\n" + "\n".join(missing)


def test_clear_caches_empties_every_cache():
    """Fill several memos with cheap calls, then one :func:`contact.clear_caches` empties
    all registered caches and names them."""
    import numpy as np

    from contact import available_solvers, clear_caches
    from contact.compliance.shell import _segment_gauss
    from contact.utca.piecewise import piece_basis
    from friction.kolivand2009 import load_kolivand2009_fit
    from geometry.core.caches import cache_sizes
    from geometry.core.materials import available_materials
    from geometry.machine.cradle import taylor_coefficients

    available_materials()
    available_solvers()
    taylor_coefficients(0.0, (1.0, 0.5))
    _segment_gauss(5)
    piece_basis(np.array([0, 0, 0, 0, 0.5, 1, 1, 1, 1.0]), 3)
    load_kolivand2009_fit("75W90")
    before = cache_sizes()
    filled = {k for k, v in before.items() if v}
    assert {"geometry.core.materials._bundled", "geometry.machine.cradle.taylor_coefficients",
            "contact.compliance.shell._segment_gauss", "contact.utca.piecewise._piece_basis",
            "friction.kolivand2009._bundled"} <= filled
    names = clear_caches()
    assert set(names) == set(before)
    assert all(v == 0 for v in cache_sizes().values())


_READS: dict[Path, list[tuple[str, int]]] = {}


def _environment_reads(path: Path) -> list[tuple[str, int]]:
    """(variable, line) of every environment variable a module reads or sets: the
    argument of ``os.environ.get``, ``os.getenv``, ``os.environ[...]``, resolved through
    the module's constants (found once per file for the module's four tests)."""
    if path not in _READS:
        _READS[path] = _find_environment_reads(path)
    return list(_READS[path])


def _find_environment_reads(path: Path) -> list[tuple[str, int]]:
    tree = _tree(path)
    constants = {t.id: node.value.value for node in tree.body if isinstance(node, ast.Assign)
                 and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)
                 for t in node.targets if isinstance(t, ast.Name)}

    def name(arg: ast.AST) -> str | None:
        if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
            return arg.value
        if isinstance(arg, ast.Name):
            return constants.get(arg.id, f"<unresolved {arg.id}>")
        return "<unresolved expression>"

    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and _dotted(node.func) in (
                "os.environ.get", "os.getenv", "environ.get", "getenv",
                "os.environ.setdefault", "os.environ.pop") and node.args:
            out.append((name(node.args[0]), node.lineno))
        elif isinstance(node, ast.Subscript) and _dotted(node.value) in ("os.environ",
                                                                         "environ"):
            out.append((name(node.slice), node.lineno))
    return out


def test_every_environment_variable_is_documented():
    text = ENVIRONMENT_DOC.read_text(encoding="utf-8")
    found = {(var, f"{_rel(p)}:{line}") for p in _sources()
             for var, line in _environment_reads(p)}
    assert {"HYPOID_LTCA_CACHE", "LTCA_KERNELS"} <= {v for v, _ in found}
    missing = sorted(f"{where}: {var}" for var, where in found if f"`{var}`" not in text)
    assert not missing, ("environment variables missing from docs/environment.md:\n"
                         + "\n".join(missing))


@pytest.mark.parametrize("variable", ["HYPOID_LTCA_CACHE", "LTCA_KERNELS",
                                      "HYPOID_LTCA_PROBLEMS"])
def test_documented_variables_are_read(variable):
    """The table lists nothing the source does not read (a renamed switch is caught)."""
    reads = {v for p in _sources() for v, _ in _environment_reads(p)}
    assert variable in reads
