"""The documentation site builds with warnings as errors (issue 54), so no page can rot:
every Markdown page parses (MyST), every public name's docstring renders (numpydoc), every
toctree entry exists, and the example gallery's quickest script is executed.

The build runs on a copy of ``docs/`` (sphinx-gallery writes its pages into the source
directory) with the rest of the repository linked beside it (the pages include
``CHANGELOG.md`` and ``CONTRIBUTING.md`` and link to sources, cases and benchmarks).
``HYPOID_LTCA_DOCS_GALLERY`` selects the gallery's quickest example (the whole gallery
runs when the site is built for publication: ``sphinx-build -W -b html docs …``). ~30 s.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys

import pytest
from doc_pages import DOCS, ROOT

pytest.importorskip("sphinx")
pytest.importorskip("myst_parser")
pytest.importorskip("sphinx_gallery")
pytest.importorskip("numpydoc")


def test_site_builds_with_warnings_as_errors(tmp_path):
    src = tmp_path / "repo" / "docs"
    shutil.copytree(DOCS, src, ignore=shutil.ignore_patterns("_build", "auto_examples",
                                                             "sg_execution_times.rst"))
    for entry in ROOT.iterdir():  # the rest of the repository, which pages link to
        if entry.name not in ("docs", ".git") and not entry.name.startswith("."):
            (tmp_path / "repo" / entry.name).symlink_to(entry)
    out = tmp_path / "html"
    env = {**os.environ, "HYPOID_LTCA_DOCS_GALLERY": "/plot_stribeck", "MPLBACKEND": "Agg"}
    res = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b",
                          "html", str(src), str(out)], capture_output=True, text=True,
                         cwd=tmp_path, env=env)
    assert res.returncode == 0, res.stderr[-4000:]
    for page in ("index", "getting_started", "walkthrough", "api", "validation",
                 "performance", "changelog", "auto_examples/index",
                 "auto_examples/plot_stribeck"):
        assert (out / f"{page}.html").is_file(), page
    api = (out / "api.html").read_text(encoding="utf-8")
    import contact
    import friction
    import geometry

    for package in (contact, friction, geometry):
        for name in getattr(package, "__all__", []):
            if not name.startswith("_"):
                assert f"{package.__name__}.{name}" in api, f"{package.__name__}.{name}"
    # the executed example's figure is on its page
    assert (out / "_images").is_dir() and any((out / "_images").glob("sphx_glr_plot_stribeck*"))


def test_examples_import_only_the_public_api():
    """The gallery's scripts and every page's Python blocks import from the package tops
    (``import contact``, ``from friction import …``), never from a submodule: what a user
    copies keeps working across releases (issue 54 item 3)."""
    import re

    from doc_pages import ALL_PAGES, python_blocks

    sources = [(p.name, p.read_text(encoding="utf-8"))
               for p in sorted((DOCS / "examples").glob("*.py"))]
    sources += [(f"{page.name}:{line}", code) for page in ALL_PAGES
                for line, code, _ in python_blocks(page)]
    assert len(sources) > 10
    for where, code in sources:
        deep = re.findall(r"^\s*(?:from|import)\s+((?:contact|friction|geometry)\.\S+)",
                          code, flags=re.M)
        assert not deep, (where, deep)


def test_no_public_name_hides_a_subpackage():
    """A public name equal to a submodule's (``contact.optimize``, ``friction.kolivand2009``)
    would be replaced by the module as soon as anything imports it: the package tops
    export none (issue 54 item 3)."""
    import importlib
    import pkgutil

    for name in ("contact", "friction", "geometry"):
        package = importlib.import_module(name)
        submodules = {m.name for m in pkgutil.iter_modules(package.__path__)}
        assert not submodules & set(package.__all__), name


def test_bundled_cases_name_files_that_install():
    """The provenance of a bundled case (its ``[optimize]`` table's optimiser log and basic
    design, its ``[deviations]``) names files beside it, relative to the case, that install
    with it as the package data ``contact.cases`` (pyproject.toml) — never a path of the
    repository such as ``docs/`` that an installed toolkit lacks (issue 63 item 3)."""
    import fnmatch
    import tomllib

    from contact import bundled_case_path, bundled_cases

    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    installed = pyproject["tool"]["setuptools"]["package-data"]["contact.cases"]
    named = 0
    for name in bundled_cases():
        path = bundled_case_path(name)
        table = tomllib.loads(path.read_text(encoding="utf-8"))
        files = [table.get("optimize", {}).get(k) for k in ("log_file", "basic_design")]
        files += list(table.get("deviations", {}).values())
        for file in filter(None, files):
            named += 1
            assert (path.parent / file).is_file(), (name, file)
            assert any(fnmatch.fnmatch(file, pattern) for pattern in installed), (name, file)
    assert named >= 8
