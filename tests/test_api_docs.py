"""The API reference (docs/api, Sphinx + numpydoc from the docstrings) builds, and the
README's Python examples pass ruff (issue 21 item 7)."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_api_reference_configuration_loads():
    """Quick check: the configuration names the extensions that are installed (sphinx and
    numpydoc are in the test extra) and the index lists the three packages."""
    pytest.importorskip("sphinx")
    import numpydoc  # noqa: F401

    ns: dict = {"__file__": str(ROOT / "docs" / "api" / "conf.py")}
    exec((ROOT / "docs" / "api" / "conf.py").read_text(), ns)
    assert "numpydoc" in ns["extensions"] and "sphinx.ext.autosummary" in ns["extensions"]
    index = (ROOT / "docs" / "api" / "index.rst").read_text()
    assert all(p in index for p in ("geometry", "contact", "friction"))


@pytest.mark.slow
def test_api_reference_builds(tmp_path):
    """The whole reference builds (about a minute): sphinx-build exits 0 and writes the
    pages of the three packages."""
    pytest.importorskip("sphinx")
    out = tmp_path / "html"
    src = tmp_path / "src"
    shutil.copytree(ROOT / "docs" / "api", src, ignore=shutil.ignore_patterns("generated"))
    res = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-b", "html", str(src),
                          str(out)], capture_output=True, text=True, cwd=ROOT)
    assert res.returncode == 0, res.stderr[-2000:]
    for pkg in ("geometry", "contact", "friction"):
        assert (out / "generated" / f"{pkg}.html").is_file()


def test_readme_python_examples_pass_ruff(tmp_path):
    """Every ```python block of README.md, written to its own file, passes ``ruff check``
    with the project's configuration."""
    blocks = re.findall(r"```python\n(.*?)```", (ROOT / "README.md").read_text(), re.S)
    assert blocks, "README has no python examples"
    for i, block in enumerate(blocks):
        (tmp_path / f"readme_example_{i}.py").write_text(block)
    ruff = shutil.which("ruff") or str(Path(sys.executable).parent / "ruff")
    res = subprocess.run([ruff, "check", "--config", str(ROOT / "pyproject.toml"),
                          "--no-cache", str(tmp_path)], capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
