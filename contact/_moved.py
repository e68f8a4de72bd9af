"""Old module paths of ``contact`` that keep working for one release (issues 20 and 31).

``contact/`` was split into its layers (``qp``, ``utca``, ``compliance``, ``ltca`` and the
application on top), and the netCDF conventions moved to the toolkit's low layer
(``geometry.core.io``). An import of a module by its old path — ``import contact.easeoff``,
``from contact.problem import ContactProblem`` — still gives the module at its new place,
with a :class:`DeprecationWarning` naming it (:mod:`geometry.core.moved`). The table is
the whole list; nothing else is aliased. ``contact.utca``, ``contact.ltca`` and
``contact.wear`` kept their names (now packages that export what the modules did).
"""

from __future__ import annotations

from geometry.core import moved

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
    "contact.deviations": "contact.utca.deviation_files",
    "contact.deviation_files": "contact.utca.deviation_files",
    "contact.edge": "contact.ltca.edges",
    "contact.transmission_error": "contact.ltca.transmission_error",
    "contact.tca": "geometry.pair.conventional_tca",
    "contact.compliance.base": "contact.compliance.foundation",
    "contact.compliance.hertz": "contact.compliance.weber",
    "contact.io": "geometry.core.io",
    "contact.output_paths": "contact.commands.output_paths",
}


def install() -> None:
    """Put the finder of :data:`MOVED` on ``sys.meta_path`` (once)."""
    moved.install(MOVED)
