"""Exceptions of the contact package, all in the toolkit's family (:class:`geometry.LTCAError`)."""

from __future__ import annotations

from geometry.core.errors import InputError, LTCAError, PluginError, UnknownNameError

__all__ = [
    "ASYMMETRY_LIMIT",
    "AnalysisFailedError",
    "AsymmetricComplianceError",
    "ContactError",
    "NotPositiveDefiniteError",
    "PluginError",
    "ProblemInputError",
    "SolverNotFoundError",
]


class ContactError(LTCAError):
    """Root of the errors raised by the contact package."""


class AnalysisFailedError(ContactError, RuntimeError):
    """An analysis ran but has no certified contact solution at some torque or roll
    position (:func:`contact.ltca.summary.certification`): its file is written, with
    ``analysis_status`` and ``analysis_status_reason`` at the root, and ``ltca run`` exits
    with status 1 (a refused input exits with 2). The message is the reason."""


class ProblemInputError(ContactError, InputError):
    """A contact problem's data are of the wrong shape, not finite, or out of range."""


class NotPositiveDefiniteError(ProblemInputError):
    """The compliance matrix is not symmetric positive definite (its Cholesky fails).

    A physical compliance matrix is SPD by Maxwell–Betti reciprocity and positive
    strain energy; a matrix that is not means the compliance model is broken.
    """


class SolverNotFoundError(ContactError, UnknownNameError):
    """A solver name that is not registered or not installed here (an
    :class:`~geometry.core.errors.UnknownNameError`: an InputError naming ``solver`` and
    the available solvers, and a ModelUnavailableError)."""


#: Largest relative asymmetry ‖C − Cᵀ‖_F / ‖C‖_F of a compliance matrix that is
#: symmetrised, ½(C + Cᵀ), and used; above it the matrix is refused. By Maxwell–Betti
#: reciprocity a compliance matrix is symmetric; the toolkit's own (C = YᵀY, shell Ritz
#: model) is to round-off (≤ 1e-10, tests/test_compliance_tooth.py), and one read from
#: finite-element influence coefficients at interpolated points is asymmetric by its
#: discretisation error. Symmetrising changes C by at most its asymmetric part, so below
#: 5 % the change stays under the accuracy of the compliance model itself (shell vs 3-D
#: FE tip deflection 5.6–7.5 %, tests/test_compliance_shell.py); an asymmetry beyond that
#: is no discretisation error but a modelling one (a transposed block, a sign error, loads
#: and deflections read along different directions).
ASYMMETRY_LIMIT = 0.05


class AsymmetricComplianceError(ProblemInputError):
    """A compliance matrix breaks Maxwell–Betti reciprocity by more than
    :data:`ASYMMETRY_LIMIT` (relative Frobenius norm of C − Cᵀ)."""
