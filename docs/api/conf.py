"""Sphinx configuration of the API reference (built from the numpydoc docstrings).

    sphinx-build -b html docs/api docs/api/_build
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

project = "hypoid-ltca"
author = "the hypoid-ltca developers"
copyright = "the hypoid-ltca developers, BSD-3-Clause"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.autosummary", "numpydoc"]
autosummary_generate = True
numpydoc_show_class_members = False
numpydoc_validation_checks: set[str] = set()
autodoc_typehints = "none"
exclude_patterns = ["_build"]
html_theme = "alabaster"
