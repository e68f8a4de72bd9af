"""The files a user of a scientific package expects beside the code, consistent with
pyproject.toml: LICENSE, CHANGELOG, CITATION.cff and the PEP 561 marker ``py.typed``."""

from __future__ import annotations

import importlib.resources
import re
import tomllib
from pathlib import Path

import pytest

from geometry.core.version import __version__

ROOT = Path(__file__).resolve().parents[1]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
CONFIG = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]


def test_license_file_is_the_declared_license():
    """pyproject declares BSD-3-Clause; LICENSE holds that licence's text (its three
    numbered conditions and the disclaimer)."""
    assert PROJECT["license"]["text"] == "BSD-3-Clause"
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("BSD 3-Clause License")
    assert all(f"\n{k}. " in text for k in (1, 2, 3))
    assert 'PROVIDED BY THE COPYRIGHT HOLDERS AND CONTRIBUTORS "AS IS"' in text


def test_citation_file_matches_the_package():
    """CITATION.cff (Citation File Format 1.2.0) names the package's version and licence
    and cites the method's source, Kolivand's 2009 dissertation."""
    text = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    fields = dict(re.findall(r"^([a-z-]+): *\"?([^\"\n]*)\"?$", text, flags=re.MULTILINE))
    assert fields["cff-version"] == "1.2.0"
    assert fields["version"] == __version__
    assert fields["license"] == PROJECT["license"]["text"]
    assert "Kolivand" in text and "Ohio State" in text


def test_the_version_is_written_in_one_place():
    """pyproject.toml reads the version from geometry/core/version.py (its only literal);
    the toolkit reports that one (no installed metadata is consulted)."""
    assert "version" not in PROJECT and "version" in PROJECT["dynamic"]
    assert CONFIG["setuptools"]["dynamic"]["version"] == {
        "attr": "geometry.core.version.__version__"}
    import geometry

    assert geometry.__version__ == __version__
    assert re.fullmatch(r"\d+\.\d+\.\d+(\.dev\d+|rc\d+)?", __version__)


def test_changelog_has_the_current_version():
    """Keep a Changelog: the first entry is the version being made (``[Unreleased] —
    X.Y.Z`` until it is released, then ``[X.Y.Z] - YYYY-MM-DD`` below an empty
    ``[Unreleased]``), with no subsection twice."""
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    entries = text.split("\n## ")[1:]
    if entries[0].strip() == "[Unreleased]":  # an empty Unreleased above a release
        entries = entries[1:]
    first = entries[0]
    heading = first.split("\n")[0]
    assert re.fullmatch(rf"\[Unreleased\] — {re.escape(__version__)}"
                        rf"|\[{re.escape(__version__)}\] - \d{{4}}-\d{{2}}-\d{{2}}", heading)
    subsections = re.findall(r"^### (.+)$", first, flags=re.MULTILINE)
    assert subsections and len(subsections) == len(set(subsections)), subsections
    assert set(subsections) <= {"Added", "Changed", "Deprecated", "Removed", "Fixed",
                                "Security"}


@pytest.mark.parametrize("package", ["contact", "geometry", "friction"])
def test_packages_are_marked_typed(package):
    """PEP 561: each top-level package ships ``py.typed`` (declared as package data, so it
    is in an installed copy too)."""
    assert importlib.resources.files(package).joinpath("py.typed").is_file()
    data = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "py.typed" in data["tool"]["setuptools"]["package-data"][package]


#: distributions that qpsolvers can use as a QP backend (qpsolvers 4.x's solver list)
QP_BACKEND_DISTRIBUTIONS = {
    "clarabel", "cvxopt", "daqp", "ecos", "gurobipy", "highspy", "hpipm", "jaxopt",
    "kvxopt", "mosek", "osqp", "piqp", "proxsuite", "pyqpmad", "qpalm", "qpax",
    "qpoases", "qpswift", "quadprog", "scs", "sip-python"}


def _name(requirement: str) -> str:
    return re.split(r"[\s<>=!~;\[]", requirement, maxsplit=1)[0].lower()


def test_the_core_pulls_only_the_design_cards_qp_backends():
    """``pip install .`` requires, of the QP backends, only the design card's (clarabel,
    osqp; cvxpy and qpsolvers are front ends) and cvxopt, whose CHOLMOD is the FE models'
    direct solver for the root stress of the main job (docs/fe.md); scs and highspy come
    only with cvxpy's own requirements. The other backends are the ``[solvers]`` extra."""
    required = {_name(r) for r in PROJECT["dependencies"]}
    assert required & QP_BACKEND_DISTRIBUTIONS == {"clarabel", "osqp", "cvxopt"}
    extra = {_name(r) for r in PROJECT["optional-dependencies"]["solvers"]}
    assert {"daqp", "quadprog", "proxsuite", "piqp", "qpalm"} <= extra


def test_no_test_imports_the_source_trees_cases_folder():
    """``cases`` is a module only where the clone itself is on ``sys.path`` (an editable
    install); an installed copy names the bundled cases ``contact.cases``. A test that
    imports ``cases`` passes here and fails in CI's ``pip install '.[test]'`` (it did:
    four tests), so tests reach case files through ``contact.catalogue`` or by path."""
    pattern = re.compile(r"""files\(\s*["']cases["']|^\s*(import|from)\s+cases\b""",
                         flags=re.MULTILINE)
    offenders = [p.name for p in sorted((ROOT / "tests").glob("*.py"))
                 if pattern.search(p.read_text(encoding="utf-8"))
                 and p.name != "test_project_files.py"]
    assert offenders == []
