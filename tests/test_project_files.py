"""The files a user of a scientific package expects beside the code, consistent with
pyproject.toml: LICENSE, CHANGELOG, CITATION.cff and the PEP 561 marker ``py.typed``."""

from __future__ import annotations

import importlib.resources
import re
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]


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
    assert fields["version"] == PROJECT["version"]
    assert fields["license"] == PROJECT["license"]["text"]
    assert "Kolivand" in text and "Ohio State" in text


def test_changelog_has_the_current_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert f"{PROJECT['version']}" in text.split("\n## ")[1].split("\n")[0]


@pytest.mark.parametrize("package", ["contact", "geometry", "friction"])
def test_packages_are_marked_typed(package):
    """PEP 561: each top-level package ships ``py.typed`` (declared as package data, so it
    is in an installed copy too)."""
    assert importlib.resources.files(package).joinpath("py.typed").is_file()
    data = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "py.typed" in data["tool"]["setuptools"]["package-data"][package]
