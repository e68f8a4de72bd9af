"""One spelling of each unit in the docstrings (docs/nomenclature.md, Units; issue 63).

Docstrings and comments write ``[N·m]``, ``[µm]``, ``[µrad]`` and ``[degC]``; the files'
UDUNITS spellings (``N m``, ``um``, ``urad``) belong to the netCDF ``units`` attributes,
the CSV headers and the console, and ``°C`` to the figures. Read with ``ast`` from the
source of the three packages (nothing imported).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: a bracketed unit as the files or the figures spell it → the docstrings' spelling
REFUSED = {"[um]": "[µm]", "[N m]": "[N·m]", "[urad]": "[µrad]", "[°C]": "[degC]",
           "[N m/rad]": "[N·m/rad]",
           "[N/um]": "[N/µm]", "[N mm]": "[N·mm]"}
_PATTERN = re.compile("|".join(re.escape(k) for k in REFUSED))


#: (path, line, docstring) of the toolkit, walked once for both tests (a parse of every
#: source file is ~2 s of CPU)
_FOUND: list[tuple[Path, int, str]] = []


def _docstrings() -> list[tuple[Path, int, str]]:
    if not _FOUND:
        _FOUND.extend(_walk())
    return list(_FOUND)


def _walk():
    for pkg in ("contact", "geometry", "friction"):
        for path in sorted((ROOT / pkg).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in ast.walk(tree):
                if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                                     ast.AsyncFunctionDef)):
                    doc = ast.get_docstring(node, clean=False)
                    if doc:
                        yield path.relative_to(ROOT), getattr(node, "lineno", 1), doc


#: an inline literal (``mesh_stiffness [N/um]``: a CSV header quoted as written)
_LITERAL = re.compile(r"``.*?``", re.S)


def test_docstrings_spell_each_unit_one_way():
    bad = [f"{path}:{line}: {m.group(0)} (write {REFUSED[m.group(0)]})"
           for path, line, doc in _docstrings()
           for m in _PATTERN.finditer(_LITERAL.sub("``…``", doc))]
    assert not bad, "units spelt as the files or figures spell them:\n" + "\n".join(bad)


def test_the_walk_reads_the_docstrings():
    """The walk finds the docstrings' own spellings (a walk that read nothing would pass
    the test above vacuously)."""
    text = "\n".join(doc for _, _, doc in _docstrings())
    assert text.count("[N·m]") > 20 and text.count("[µm]") > 20 and "[µrad]" in text
