"""Contact analysis of hypoid and spiral bevel gears: UTCA, compliance, the loaded-contact QP, LTCA.

The loaded-contact problem and its solvers::

    from contact import ContactProblem, solve_contact, available_solvers

The whole analysis of a case (geometry → ease-off UTCA → LTCA) as one DataTree::

    from contact import run_analysis
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
    "run_analysis",
    "solve_contact",
]


def __getattr__(name: str):
    # the pipeline pulls in geometry and plotting-free stages; import it only when used
    if name == "run_analysis":
        from contact.pipeline import run_analysis

        return run_analysis
    raise AttributeError(f"module 'contact' has no attribute {name!r}")
