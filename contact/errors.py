"""Exceptions of the contact package, all in the toolkit's family (:class:`geometry.LTCAError`)."""

from __future__ import annotations

from geometry.errors import InputError, LTCAError, ModelUnavailableError

__all__ = [
    "ContactError",
    "NotPositiveDefiniteError",
    "ProblemInputError",
    "SolverNotFoundError",
]


class ContactError(LTCAError):
    """Root of the errors raised by the contact package."""


class ProblemInputError(ContactError, InputError):
    """A contact problem's data are of the wrong shape, not finite, or out of range."""


class NotPositiveDefiniteError(ProblemInputError):
    """The compliance matrix is not symmetric positive definite (its Cholesky fails).

    A physical compliance matrix is SPD by Maxwell–Betti reciprocity and positive
    strain energy; a matrix that is not means the compliance model is broken.
    """


class SolverNotFoundError(ContactError, ModelUnavailableError):
    """A solver name that is not registered or not installed here."""
