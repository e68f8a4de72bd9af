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
sys.path.insert(0, str(Path(__file__).resolve().parent))  # docs/gallery_scraper.py

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
exclude_patterns = ["_build", "examples", "figures/**/*.md",
                    "auto_examples/*.ipynb", "auto_examples/*.py", "auto_examples/*.zip",
                    "auto_examples/*.md5", "auto_examples/*.codeobj.json",
                    "sg_execution_times.rst"]
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 4
autodoc_typehints = "none"
numpydoc_show_class_members = False
#: numpydoc's validation of every public docstring (the names of docs/api.md), warnings
#: that ``-W`` makes errors. The checks that carry CONTRIBUTING.md's promise: GL08 a
#: docstring, SS01 a summary line; PR01 every parameter documented (its entry holds the
#: type, shape and unit), PR02 none documented that the signature lacks, PR04 every
#: parameter typed (the type line carries the shape: ``array_like (N, 3)``); RT01 a Returns
#: section where the function returns, RT03 the returned value described (dims, units).
#: Units, sources and Raises sections are the project's own checks
#: (tests/test_api_docs.py), which numpydoc has none for. Not checked: numpydoc's style
#: rules (GL01-GL03, SS02-SS06, PR06-PR10, RT02, RT04, RT05: our entries put "— [unit]" on
#: the type line), extended summaries (ES01), See Also (SA01) and Examples (EX01).
numpydoc_validation_checks = {"GL08", "SS01", "PR01", "PR02", "PR04", "RT01", "RT03"}
#: the public names whose docstrings do not pass yet, each with why; a short, named list
#: (tests/test_api_docs.py fails on a name listed here that passes, so it only shrinks)
NUMPYDOC_PENDING = {
    # results and containers read by attribute: their fields are documented under
    # "Attributes" (PR01 reads the constructor's parameters)
    "contact.ContactSolution": "a result; fields under Attributes",
    "geometry.Case": "a loaded case file; fields under Attributes",
}
numpydoc_validation_exclude = {rf"^{name.replace('.', '[.]')}$" for name in NUMPYDOC_PENDING}

sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": os.environ.get("HYPOID_LTCA_DOCS_GALLERY", r"/plot_"),
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib", "gallery_scraper"),  # docs/gallery_scraper.py
}


html_theme = "alabaster"
html_title = f"hypoid-ltca {__version__}"
html_static_path = ["_static"]
html_css_files = ["code.css"]  # code blocks wrap instead of running off the page


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
