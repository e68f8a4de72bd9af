"""The toolkit's version, written in this one place.

``pyproject.toml`` reads it from here (``[tool.setuptools.dynamic]``: the installed
distribution's metadata is made from it), the toolkit records it in every file it writes
(``toolkit_version``), and ``CITATION.cff`` and the first heading of ``CHANGELOG.md`` name
it (tests/test_project_files.py checks both). A clone run without installing has the same
version as an installed copy.
"""

from __future__ import annotations

__all__ = ["__version__"]

#: the version (PEP 440) of hypoid-ltca; to release, change it here, in CITATION.cff and in
#: CHANGELOG.md's heading (CONTRIBUTING.md, "Releasing")
__version__ = "0.3.0"
