"""Old module paths of ``contact`` that keep working for one release (issue 20).

``contact/`` was split into its layers (``qp``, ``utca``, ``compliance``, ``ltca`` and the
application on top). An import of a module by its old path — ``import contact.easeoff``,
``from contact.problem import ContactProblem`` — still gives the module at its new place,
with a :class:`DeprecationWarning` naming it. The table is the whole list; nothing else
is aliased. ``contact.utca`` and ``contact.ltca`` kept their names (now packages that
export what the modules did).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import warnings

__all__ = ["MOVED", "install"]

#: old module path → new module path (a package's submodules follow it)
MOVED: dict[str, str] = {
    "contact.problem": "contact.qp.problem",
    "contact.solvers": "contact.qp.solvers",
    "contact.problem_set": "contact.qp.benchmark_problems",
    "contact.halfspace": "contact.qp.halfspace",
    "contact.solver_study": "contact.qp.solver_study",
    "contact.qpbenchmark_set": "contact.qp.qpbenchmark_export",
    "contact.easeoff": "contact.utca.easeoff",
    "contact.deviations": "contact.deviation_files",
    "contact.edge": "contact.ltca.edges",
    "contact.transmission_error": "contact.ltca.transmission_error",
    "contact.tca": "geometry.conventional_tca",
    "contact.compliance.base": "contact.compliance.foundation",
    "contact.compliance.hertz": "contact.compliance.weber",
}


def _new_name(name: str) -> str | None:
    for old, new in MOVED.items():
        if name == old or name.startswith(old + "."):
            return new + name[len(old):]
    return None


class _MovedFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old path in :data:`MOVED` and loads the module of its new path."""

    def find_spec(self, fullname, path=None, target=None):
        new = _new_name(fullname)
        if new is None:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        new = _new_name(spec.name)
        warnings.warn(f"{spec.name} moved to {new}; the old path goes in the next release",
                      DeprecationWarning, stacklevel=2)
        return importlib.import_module(new)

    def exec_module(self, module) -> None:
        """Nothing to run: the module was imported at its new path."""


def install() -> None:
    """Put the finder on ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _MovedFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _MovedFinder())
