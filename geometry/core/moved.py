"""Old module paths that keep working for one release, with a deprecation warning.

When a package's modules move (``contact/`` split into its layers, issue 20; ``geometry/``
into subpackages, issue 31), an import by the old path — ``import geometry.errors``,
``from contact.problem import ContactProblem`` — still gives the module at its new place,
with a :class:`DeprecationWarning` naming it. Each package keeps its own table (old module
path → new module path; a package's submodules follow it) and installs it here:
:data:`geometry.MOVED` and :data:`contact.MOVED`. Nothing else is aliased.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import warnings
from collections.abc import Mapping

__all__ = ["install", "new_name"]


def new_name(name: str, table: Mapping[str, str]) -> str | None:
    """The new path of the module ``name`` under ``table`` (None: it did not move)."""
    for old, new in table.items():
        if name == old or name.startswith(old + "."):
            return new + name[len(old):]
    return None


class _MovedFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old path of its table and loads the module of its new path."""

    def __init__(self, table: Mapping[str, str]) -> None:
        self.table = table

    def find_spec(self, fullname, path=None, target=None):
        if new_name(fullname, self.table) is None:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        new = new_name(spec.name, self.table)
        warnings.warn(f"{spec.name} moved to {new}; the old path goes in the next release",
                      DeprecationWarning, stacklevel=2)
        return importlib.import_module(new)

    def exec_module(self, module) -> None:
        """Nothing to run: the module was imported at its new path."""


def install(table: Mapping[str, str]) -> None:
    """Put a finder of ``table``'s old paths on ``sys.meta_path`` (once per table)."""
    if not any(isinstance(f, _MovedFinder) and f.table is table for f in sys.meta_path):
        sys.meta_path.insert(0, _MovedFinder(table))
