"""Sphinx configuration of the hypoid-ltca documentation site.

Build (from the repository root)::

    pip install '.[docs]'
    sphinx-build -W -b html docs docs/_build/html

The Markdown pages are read by MyST, the API reference is built from the numpydoc
docstrings of the public names (``docs/api.md``), and the example gallery
(``docs/examples/plot_*.py``) is executed at build time by sphinx-gallery.
``HYPOID_LTCA_DOCS_GALLERY`` chooses which examples run: a regular expression on their
file names (default: all of them; the test suite runs the quickest, tests/test_docs_site.py).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from geometry import __version__  # noqa: E402  (after the path, for a build from a clone)

project = "hypoid-ltca"
author = "the hypoid-ltca developers"
copyright = "the hypoid-ltca developers, BSD-3-Clause"
version = release = __version__

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "sphinx_gallery.gen_gallery",
]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
exclude_patterns = ["_build", "examples", "solvers/*", "figures/**/*.md",
                    "auto_examples/*.ipynb", "auto_examples/*.py", "auto_examples/*.zip",
                    "auto_examples/*.md5", "auto_examples/*.codeobj.json",
                    "sg_execution_times.rst"]
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 4
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_validation_checks: set[str] = set()

sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": os.environ.get("HYPOID_LTCA_DOCS_GALLERY", r"/plot_"),
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
}

html_theme = "alabaster"
html_title = f"hypoid-ltca {__version__}"
html_static_path: list[str] = []


def _public_api(package: str) -> str:
    """The autodoc entries of the package's public names (its ``__all__``): classes,
    functions, then constants, each under its name at the package top."""
    import importlib
    import inspect

    module = importlib.import_module(package)
    names = sorted((n for n in getattr(module, "__all__", []) if not n.startswith("_")),
                   key=str.lower)
    lines = ["```{eval-rst}", f".. currentmodule:: {package}", ""]
    for name in names:
        obj = getattr(module, name)
        if inspect.isclass(obj):
            lines += [f".. autoclass:: {name}", ""]
        elif callable(obj):
            lines += [f".. autofunction:: {name}", ""]
        else:
            lines += [f".. autodata:: {name}", "   :no-value:", ""]
    lines += ["```", ""]
    return "\n".join(lines)


def _fill_api(app, docname, source):
    """Replace each ``PUBLIC-API:<package>`` line of api.md by that package's names."""
    if docname != "api":
        return
    text = source[0]
    for package in ("contact", "friction", "geometry"):
        text = text.replace(f"PUBLIC-API:{package}", _public_api(package))
    source[0] = text


def setup(app):
    app.connect("source-read", _fill_api)
