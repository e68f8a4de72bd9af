"""Contact analysis of hypoid and spiral bevel gears: UTCA, compliance, the loaded-contact QP, LTCA.

Five layers, each a subpackage, each importing only those below it (tests/test_layers.py):

* :mod:`contact.qp` — the loaded-contact problem, its solver registry and studies (no gear);
* :mod:`contact.utca` — ease-off, contact curves, unloaded TE, deviations;
* :mod:`contact.compliance` — tooth bending and shear (shell), Weber contact, fillet
  foundation;
* :mod:`contact.ltca` — the loaded TCA over the mesh cycle (segments, screening, roll
  loop, dataset);
* the application on top: :mod:`contact.pipeline` (the whole analysis of a case),
  :mod:`geometry.core.io` (netCDF), :mod:`contact.plots`, :mod:`contact.cli` and
  :mod:`contact.commands` (the ``ltca`` command).

The loaded-contact problem and its solvers::

    from contact import ContactProblem, solve_contact, available_solvers

The whole analysis of a case (geometry → ease-off UTCA → LTCA) as one DataTree::

    from contact import run_analysis

Every per-process cache (memo) of the toolkit is emptied by one call::

    from contact import clear_caches
"""

from geometry import __version__
from geometry.core.lazy import lazy_exports

__all__ = [
    "DEFAULT_SOLVER",
    "DEFAULT_TOLERANCE",
    "ContactError",
    "ContactProblem",
    "ContactSolution",
    "NotPositiveDefiniteError",
    "ProblemInputError",
    "SolverNotFoundError",
    "__version__",
    "available_solvers",
    "clear_caches",
    "contact_residuals",
    "run_analysis",
    "solve_contact",
]

#: the public names and the module each comes from, imported when first used (PEP 562):
#: the QP layer pulls in SciPy and the pipeline the whole chain, which ``ltca --help`` and
#: ``ltca cases`` do not need (issue 32: start-up ≤ 0.5 s)
_LAZY = {
    **dict.fromkeys(("DEFAULT_SOLVER", "DEFAULT_TOLERANCE", "ContactProblem", "ContactSolution",
                     "available_solvers", "contact_residuals", "solve_contact"), "contact.qp"),
    **dict.fromkeys(("ContactError", "NotPositiveDefiniteError", "ProblemInputError",
                     "SolverNotFoundError"), "contact.errors"),
    "run_analysis": "contact.pipeline",
    "clear_caches": "geometry.core.caches",
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
