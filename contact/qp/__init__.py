"""The loaded-contact problem as a convex QP, its solvers and its studies — no gear in it.

At one roll position, N contact segments with compliance C [mm/N], initial separations s
[mm] and moment arms R [mm] carry the gear torque T [N·mm]:

    C F + s − R Θ = Y ≥ 0,   F ≥ 0,   F·Y = 0,   Rᵀ F = T

the KKT conditions of *minimise ½ FᵀCF + sᵀF subject to F ≥ 0, RᵀF = T* (seed
Eq. 3.12–3.14). This layer knows nothing of gears:

* :mod:`contact.qp.problem` — :class:`ContactProblem`, :class:`ContactSolution` and the
  residuals of the four conditions, computed here, never taken from a solver;
* :mod:`contact.qp.solvers` — the one registry of interchangeable backends (our exact
  ``active_set``, every installed ``qpsolvers`` backend, ``cvxpy``, plug-ins); a bundled
  backend goes in a module of its own there, a user's registers from outside
  (:func:`register_backend`, docs/extending.md);
* :mod:`contact.qp.halfspace` — Love's half-space influence coefficients and Hertz's
  solutions, the independent references;
* :mod:`contact.qp.benchmark_problems` — the test problems of the solver study (Hertz
  sphere and cylinder, random instances with a hypoid mesh's structure);
* :mod:`contact.qp.solver_study` — every backend on a problem set, as a labelled dataset;
* :mod:`contact.qp.qpbenchmark_export` — the same problems as a qpbenchmark test set.
"""

from contact.qp.problem import (
    DEFAULT_TOLERANCE,
    ContactProblem,
    ContactSolution,
    contact_residuals,
)
from contact.qp.solvers import (
    DEFAULT_SOLVER,
    available_solvers,
    get_backend,
    register_backend,
    solve_contact,
    unregister_backend,
)

__all__ = [
    "DEFAULT_SOLVER",
    "DEFAULT_TOLERANCE",
    "ContactProblem",
    "ContactSolution",
    "available_solvers",
    "contact_residuals",
    "get_backend",
    "register_backend",
    "solve_contact",
    "unregister_backend",
]
