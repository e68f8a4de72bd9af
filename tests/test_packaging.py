"""Every Python package of the source tree is installed by ``pip install .``.

``pyproject.toml`` lists the packages by name (the bundled cases are mapped to
``contact.cases``), so a new subpackage that is not added there imports in a clone
(``pytest`` from the repository root) but not from an installed copy: CI once failed
on ``friction.ehl`` for that reason. This test compares the list with the tree.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _tree_packages() -> set[str]:
    out = set()
    for top in ("contact", "geometry", "friction"):
        for init in (ROOT / top).rglob("__init__.py"):
            rel = init.parent.relative_to(ROOT)
            if "__pycache__" not in rel.parts:
                out.add(".".join(rel.parts))
    return out


def test_every_package_of_the_tree_is_listed_in_pyproject():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    listed = set(config["tool"]["setuptools"]["packages"])
    missing = _tree_packages() - listed
    assert not missing, f"add to [tool.setuptools] packages in pyproject.toml: {sorted(missing)}"
    # every listed name is a package of the tree or a mapped directory (contact.cases)
    mapped = set(config["tool"]["setuptools"].get("package-dir", {}))
    assert listed - _tree_packages() <= mapped
