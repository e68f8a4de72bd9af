"""The README's and the manual's Python examples pass ruff (issue 21 item 7; the API
reference is part of the documentation site now, tests/test_docs_site.py)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

from doc_pages import ALL_PAGES, ROOT, python_blocks


def test_readme_python_examples_pass_ruff(tmp_path):
    """Every ```python block of every page (the README and docs/*.md), written to its own
    file, passes ``ruff check`` with the project's configuration."""
    blocks = [code for page in ALL_PAGES for _, code, _ in python_blocks(page)]
    assert blocks, "no python examples"
    for i, block in enumerate(blocks):
        (tmp_path / f"readme_example_{i}.py").write_text(block)
    ruff = shutil.which("ruff") or str(Path(sys.executable).parent / "ruff")
    res = subprocess.run([ruff, "check", "--config", str(ROOT / "pyproject.toml"),
                          "--no-cache", str(tmp_path)], capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
