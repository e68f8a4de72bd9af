"""Contact analysis of hypoid and spiral bevel gears: UTCA, compliance, the loaded-contact QP, LTCA.

The loaded-contact problem and its solvers::

    from contact import ContactProblem, solve_contact, available_solvers
"""

from contact.errors import (
    ContactError,
    NotPositiveDefiniteError,
    ProblemInputError,
    SolverNotFoundError,
)
from contact.problem import DEFAULT_TOLERANCE, ContactProblem, ContactSolution, contact_residuals
from contact.solvers import DEFAULT_SOLVER, available_solvers, solve_contact
from geometry._version import __version__

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
    "contact_residuals",
    "solve_contact",
]
