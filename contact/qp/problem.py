"""The loaded-contact problem of a gear mesh and its certified solution.

At one pinion roll position the N contact segments of all tooth pairs that may
share the load satisfy (seed Eq. 3.12–3.14, after Conry & Seireg 1972)::

    compatibility   C F + s − R Θ = Y,   Y ≥ 0
    complementarity F ≥ 0,  F·Y = 0
    equilibrium     Rᵀ F = T

with C the total compliance [mm/N], s the initial separations [mm], R the moment
arms about the gear axis [mm], T the gear torque [N·mm], F the segment forces [N],
Y the gaps after loading [mm] and Θ the gear's rigid-body rotation [rad] — the
loaded transmission error. For symmetric positive definite C these are the KKT
conditions of the convex QP

    minimise ½ Fᵀ C F + sᵀ F   subject to  F ≥ 0,  Rᵀ F = T

whose equality multiplier is Θ. The seed's Eq. 3.12–3.14 are garbled in the
text extraction; the form above is the reading adopted in ``DESIGN.md``.

A segment whose force is limited (an elastic–perfectly-plastic edge, or flank, that
carries at most F_max: :mod:`geometry.core.materials`) adds the bound F ≤ F_max: the QP with
box constraints 0 ≤ F ≤ F_max, still convex. Its KKT conditions split the gap into the
multipliers of the two bounds, Y = λ − μ with λ, μ ≥ 0: a segment below its limit keeps
the conditions above, a segment at its limit may penetrate (Y ≤ 0: the plastic flow that
the elastic model cannot follow), and the upper bound's complementarity
(F_max − F)·min(Y, 0) = 0 joins the residuals.

Residuals are always computed here from the returned F and Θ, never taken from
a backend (:func:`contact_residuals`).
"""

from __future__ import annotations

import copy
import dataclasses
import logging
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.linalg
import scipy.linalg.lapack

from contact.errors import (
    ASYMMETRY_LIMIT,
    AsymmetricComplianceError,
    NotPositiveDefiniteError,
    ProblemInputError,
)
from geometry.core.errors import InputError
from geometry.core.validation import positive, real_array

log = logging.getLogger(__name__)

__all__ = [
    "DEFAULT_TOLERANCE",
    "RESIDUALS",
    "ContactProblem",
    "ContactSolution",
    "ProblemScale",
    "contact_residuals",
    "reduced_kkt",
    "residuals_and_gaps",
    "schur_floor",
    "solve_on_contact_set",
]

#: Relative tolerance on each of the four residuals for a solution to count as found.
#: 1e-7 is far below what any physical input is known to (compliances to ~1 %,
#: separations to ~0.1 µm of a ~10 µm scale) and above what double precision
#: reaches on the reduced KKT system for condition numbers up to ~1e8.
DEFAULT_TOLERANCE = 1e-7

#: The conditions whose relative residuals certify a solution (module docstring):
#: 0 ≤ F ≤ F_max (primal), Y ≥ 0 where F is unbounded (dual), F·Y = 0 (complementarity),
#: RᵀF = T (equilibrium), and the upper bound's complementarity (F_max − F)·min(Y, 0) = 0
#: (0 where no segment has a bound).
RESIDUALS = ("primal", "dual", "complementarity", "equilibrium", "upper_complementarity")


def _problem_input(check: Callable[..., Any], *args: Any, **kwargs: Any) -> Any:
    """A :mod:`geometry.core.validation` check whose refusal is a :class:`ProblemInputError`."""
    try:
        return check(*args, **kwargs)
    except InputError as exc:
        raise ProblemInputError(str(exc)) from None


@dataclass(frozen=True)
class ProblemScale:
    """Reference magnitudes that make a contact problem dimensionless.

    Attributes
    ----------
    force : float — [N]
        f₀ = T / Σ R⁺, the segment force if every segment with a positive moment
        arm carried an equal share.
    length : float — [mm]
        δ₀ = f₀ · mean(diag C), the deflection of one segment under f₀.
    arm : float — [mm]
        r₀ = max |R|.
    """

    force: float
    length: float
    arm: float

    @property
    def rotation(self) -> float:
        """Θ₀ = δ₀ / r₀ — [rad]."""
        return self.length / self.arm

    @property
    def schur_floor(self) -> float:
        """[mm·N] The smallest Schur complement R_Aᵀ C_AA⁻¹ R_A :func:`reduced_kkt` takes
        as positive: 1e-14 of its reference r₀² f₀/δ₀ (:func:`schur_floor`)."""
        return 1e-14 * self.arm**2 / (self.length / self.force)


@dataclass(frozen=True, eq=False)
class ContactProblem:
    """The loaded-contact problem at one roll position (seed Eq. 3.12–3.14).

    Parameters
    ----------
    compliance : array_like, shape (N, N) — [mm/N]
        Total compliance C: deflection along the contact normal at segment i due to
        a unit force at segment j (pinion + gear bending/shear + contact + base).
        Symmetrised on construction, ½(C + Cᵀ); the relative asymmetry
        ‖C − Cᵀ‖_F / ‖C‖_F is kept in :attr:`asymmetry` and must not exceed
        :data:`contact.errors.ASYMMETRY_LIMIT` (0.05; Maxwell–Betti reciprocity).
    separation : array_like, shape (N,) — [mm]
        Initial separations s (ease-off relative to the unloaded transmission error).
    moment_arm : array_like, shape (N,) — [mm]
        Moment arms R of the segment normals about the gear axis; at least one > 0.
    torque : float — [N·mm]
        Gear torque T > 0.
    name : str, optional
        Label used in reports.
    upper_bound : array_like, shape (N,), optional — [N]
        Force limits F_max > 0 of the segments (``inf`` where a segment has none);
        default None: no limit anywhere (stored as all ``inf``).

    Raises
    ------
    ProblemInputError
        Wrong shapes, non-finite entries, no positive moment arm, T ≤ 0 or N = 0; an
        upper bound that is NaN or ≤ 0, or bounds under which the segments cannot carry
        T (Σ R⁺ F_max < T: no feasible force).
    AsymmetricComplianceError
        C's relative asymmetry exceeds :data:`contact.errors.ASYMMETRY_LIMIT`.
    NotPositiveDefiniteError
        C (after symmetrisation) is not positive definite: its Cholesky fails.
    """

    compliance: np.ndarray
    separation: np.ndarray
    moment_arm: np.ndarray
    torque: float
    name: str = ""
    upper_bound: np.ndarray | None = None
    asymmetry: float = field(init=False)
    scale: ProblemScale = field(init=False)

    def __post_init__(self) -> None:
        C, s, R = self.compliance, self.separation, self.moment_arm
        if (_float_array(C, 2) and C.flags.c_contiguous and _float_array(s, 1)
                and _float_array(R, 1) and np.isfinite(C).all() and np.isfinite(s).all()
                and np.isfinite(R).all()):
            # finite float arrays of the right rank (the LTCA's each roll, issue 75): what
            # real_array checks, without its conversions; s and R copied as it copies
            # (C is not kept: its symmetric part below is a new array)
            s, R = s.copy(), R.copy()
        else:
            C = _problem_input(real_array, "compliance", C, unit="mm/N", ndim=2)
            s = _problem_input(real_array, "separation", s, unit="mm", ndim=1)
            R = _problem_input(real_array, "moment_arm", R, unit="mm", ndim=1)
        n = s.size
        if n == 0:
            raise ProblemInputError("separation: needs at least one segment, got 0")
        if C.shape != (n, n):
            raise ProblemInputError(
                f"compliance: must be square N×N with N = len(separation) = {n}, got {C.shape}"
            )
        if R.shape != (n,):
            raise ProblemInputError(f"moment_arm: must have shape ({n},), got {R.shape}")
        if not np.any(R > 0):
            raise ProblemInputError(
                "moment_arm: at least one entry must be > 0 (no segment can carry the torque)"
            )
        T = _problem_input(positive, "torque", self.torque, "N·mm")
        norm = np.linalg.norm(C)
        if norm == 0:
            raise NotPositiveDefiniteError("compliance: is the zero matrix, not positive definite")
        if math.isfinite(norm) and (C == C.T).all():
            # symmetric to the bit (the LTCA's every roll: its pools are symmetrised when
            # assembled, issue 75): ‖C − Cᵀ‖ is 0 and ½(C + Cᵀ) is C itself (x + x and
            # its half are exact below the overflow a finite ‖C‖ excludes), copied as the
            # symmetric part is a new array: the same problem in one pass instead of four
            skew, asym = 0.0, 0.0
            C = C.copy()
        else:
            skew = np.linalg.norm(C - C.T)
            asym = float(skew / norm)
            if asym > ASYMMETRY_LIMIT:
                raise AsymmetricComplianceError(
                    f"compliance: relative asymmetry ‖C − Cᵀ‖/‖C‖ = {asym:.3g} exceeds "
                    f"{ASYMMETRY_LIMIT:g}; a compliance matrix is symmetric by "
                    "Maxwell–Betti reciprocity, so this is a modelling error (transposed "
                    "block, sign, loads and deflections along different directions), not "
                    "round-off")
            if asym > 0.0:
                log.debug("compliance: relative asymmetry %.3g, symmetrised", asym)
            C = 0.5 * (C + C.T)
        _check_positive_definite(C)
        U = _upper_bound(self.upper_bound, R, T, n)
        bounded = np.isfinite(U)
        for arr in (C, s, R, U, bounded):
            arr.setflags(write=False)
        self._set_checked(C, s, R, T, U, bounded, asym, float(skew))

    def _set_checked(self, C: np.ndarray, s: np.ndarray, R: np.ndarray, T: float,
                     U: np.ndarray, bounded: np.ndarray, asym: float, skew: float,
                     like: ContactProblem | None = None) -> None:
        """Store checked, read-only inputs and what is derived from them: the scale, the
        segments with a limit (asked for at every solve and pivot) and ‖C − Cᵀ‖ [mm/N]
        of the compliance as given (for :meth:`with_diagonal`). ``like``: a problem with
        the same moment arms and torque, whose reference force and arm are these."""
        if like is None:
            f0 = T / float(R[R > 0].sum())
            r0 = float(np.max(np.abs(R)))
        else:
            f0, r0 = like.scale.force, like.scale.arm
        d0 = f0 * mean_of(np.diagonal(C))
        object.__setattr__(self, "compliance", C)
        object.__setattr__(self, "separation", s)
        object.__setattr__(self, "moment_arm", R)
        object.__setattr__(self, "torque", T)
        object.__setattr__(self, "upper_bound", U)
        object.__setattr__(self, "asymmetry", asym)
        object.__setattr__(self, "scale", ProblemScale(force=f0, length=d0, arm=r0))
        object.__setattr__(self, "_bounded", bounded)
        object.__setattr__(self, "_has_bounds", bool(bounded.any()))
        object.__setattr__(self, "_skew", skew)

    def with_diagonal(self, diagonal: np.ndarray, separation: np.ndarray) -> ContactProblem:
        """The same contact with another diagonal of C and other separations.

        Weber's iteration (:mod:`contact.ltca.weber`) changes only these between its
        problems of one roll: its contact compliance is diagonal. The result equals
        ``ContactProblem(C', separation, …)`` for a C' that differs from this problem's
        given compliance only on its diagonal, which is ``diagonal`` (½(C + Cᵀ) keeps a
        diagonal exactly), without checking again what it shares with this problem (the
        moment arms, torque, force limits and off-diagonal entries, and ‖C − Cᵀ‖, which no
        diagonal changes); C' is checked positive definite (its Cholesky) unless its diagonal
        is nowhere below this problem's, where it is so by Weyl's inequality (this problem
        is positive definite: checked when it was made). Weber's iteration makes its
        problems from one base with the smallest diagonal the iteration can reach, checked
        once per roll.

        Parameters
        ----------
        diagonal : ndarray (N,) — [mm/N]
            The new diagonal of C (finite).
        separation : ndarray (N,) — [mm]
            The new initial separations s (finite).

        Returns
        -------
        ContactProblem
            ``name`` kept; :attr:`asymmetry` ‖C − Cᵀ‖/‖C‖ with ‖C‖ of the new symmetric C
            (equal to the constructor's but for the off-diagonal asymmetry's own square,
            i.e. exactly where C₀ is symmetric).

        Raises
        ------
        ProblemInputError
            Wrong shapes or non-finite entries.
        NotPositiveDefiniteError
            The new C is not positive definite (its Cholesky fails).
        """
        n = self.size
        d = np.asarray(diagonal, dtype=float)
        s = np.array(separation, dtype=float, copy=True)
        if d.shape != (n,) or s.shape != (n,):
            raise ProblemInputError(
                f"diagonal, separation: must have shape ({n},), got {d.shape}, {s.shape}")
        if not (np.isfinite(d).all() and np.isfinite(s).all()):
            raise ProblemInputError("diagonal, separation: must be finite")
        C = self.compliance.copy()
        np.fill_diagonal(C, d)
        if not np.all(d >= np.diagonal(self.compliance)):
            # a diagonal nowhere below this (checked) problem's adds a positive
            # semi-definite matrix to a positive definite one: positive definite by Weyl's
            # inequality (λ_min(A + D) ≥ λ_min(A) + min D), with no Cholesky to pay
            _check_positive_definite(C)
        skew = self._skew
        asym = float(skew / np.linalg.norm(C)) if skew else 0.0
        C.setflags(write=False)
        s.setflags(write=False)
        new = object.__new__(ContactProblem)
        object.__setattr__(new, "name", self.name)
        new._set_checked(C, s, self.moment_arm, self.torque, self.upper_bound, self._bounded,
                         asym, skew, like=self)
        return new

    def renamed(self, name: str) -> ContactProblem:
        """The same problem under another ``name``, without checking it again.

        ``dataclasses.replace(problem, name=…)`` would symmetrise, measure and factorise C
        once more (a Cholesky per call: the LTCA's rolls whole mesh cycles apart share
        their problems, issue 75); the checked arrays are read-only and are shared.

        Parameters
        ----------
        name : str
            The new name.

        Returns
        -------
        ContactProblem
            Every field but ``name`` this problem's (:attr:`asymmetry` too: that of the
            compliance as first given).
        """
        new = copy.copy(self)
        object.__setattr__(new, "name", str(name))
        return new

    @property
    def size(self) -> int:
        """Number of segments N."""
        return int(self.separation.size)

    @property
    def bounded(self) -> np.ndarray:
        """(N,) bool: the segments with a force limit (finite ``upper_bound``; read-only)."""
        return self._bounded

    @property
    def has_bounds(self) -> bool:
        """Whether any segment has a force limit."""
        return self._has_bounds

    def scaled_upper_bound(self) -> np.ndarray:
        """The force limits of the dimensionless QP, F_max/f₀ (``inf`` where none), shape
        (N,); see :meth:`scaled`."""
        return self.upper_bound / self.scale.force

    def gap(self, force: np.ndarray, rotation: float) -> np.ndarray:
        """Gaps after loading Y = C F + s − R Θ — [mm], shape (N,) (seed Eq. 3.13)."""
        return self.compliance @ force + self.separation - self.moment_arm * rotation

    def scaled(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """The dimensionless QP handed to backends.

        With f₀, δ₀, r₀ from :attr:`scale`: C̃ = C f₀/δ₀, s̃ = s/δ₀, R̃ = R/r₀,
        T̃ = T/(r₀ f₀); then F = f₀ F̃ and Θ = (δ₀/r₀) Θ̃. Absolute tolerances of a
        backend then mean the same for every case.

        Returns
        -------
        (C̃ (N, N), s̃ (N,), R̃ (N,), T̃)
        """
        sc = self.scale
        return (
            self.compliance * (sc.force / sc.length),
            self.separation / sc.length,
            self.moment_arm / sc.arm,
            self.torque / (sc.arm * sc.force),
        )

    def with_torque(self, torque: float) -> ContactProblem:
        """The same contact with another torque [N·mm]."""
        return dataclasses.replace(self, torque=torque)


def mean_of(values: np.ndarray) -> float:
    """``float(np.mean(values))`` of a float64 array, the same arithmetic (numpy's sum
    divided by the count) without ``np.mean``'s overhead on a small array (called at
    every Weber iteration's solve, issue 75)."""
    return float(np.add.reduce(values, axis=None) / values.size)


def _float_array(a, ndim: int) -> bool:
    """Whether ``a`` is a float64 ndarray (not a subclass) of ``ndim`` dimensions."""
    return type(a) is np.ndarray and a.dtype == np.float64 and a.ndim == ndim


def _check_positive_definite(C: np.ndarray) -> None:
    """Refuse a symmetric compliance C (N, N) [mm/N] that is not positive definite: its
    Cholesky factorisation (LAPACK ``potrf``) fails."""
    _, info = scipy.linalg.lapack.dpotrf(C, lower=1, clean=0)
    if info != 0:
        eig_min = float(np.linalg.eigvalsh(C)[0])
        raise NotPositiveDefiniteError(
            "compliance: is not positive definite (Cholesky failed; smallest eigenvalue "
            f"{eig_min:.3e} mm/N); a physical compliance matrix must be SPD")


def _upper_bound(bound, R: np.ndarray, T: float, n: int) -> np.ndarray:
    """The checked force limits (N,) [N], ``inf`` where none (module docstring)."""
    if bound is None:
        return np.full(n, np.inf)
    U = np.array(bound, dtype=float, copy=True)
    if U.shape != (n,):
        raise ProblemInputError(f"upper_bound: must have shape ({n},) [N], got {U.shape}")
    if np.any(np.isnan(U)) or np.any(U <= 0.0):
        raise ProblemInputError("upper_bound: must be > 0 [N] (inf where a segment has no "
                                "limit), got NaN or a value <= 0")
    pos = R > 0
    reach = float(np.sum(R[pos] * U[pos]))
    if reach < T:
        raise ProblemInputError(
            f"upper_bound: the segments carry at most Σ R⁺ F_max = {reach:.6g} N·mm at "
            f"their limits, less than the torque T = {T:.6g} N·mm (no feasible force)")
    return U


def contact_residuals(
    problem: ContactProblem, force: np.ndarray, rotation: float
) -> dict[str, float]:
    """Relative residuals of the contact conditions, computed from F and Θ.

    With Y = C F + s − R Θ, reference force f = max(‖F‖∞, f₀), reference length
    d = max(‖C F‖∞, abs(Θ) ‖R‖∞, δ₀) and F_max the force limits (``inf`` where none):

    - ``primal``: ‖max(−F, F − F_max, 0)‖∞ / f — forces are compressive and within
      their limits (0 ≤ F ≤ F_max);
    - ``dual``: ‖min(Y, 0)‖∞ / d over the segments without a limit — no penetration
      after loading (Y ≥ 0; a segment with a limit may penetrate at it, which the
      upper complementarity checks);
    - ``complementarity``: maxᵢ min(Fᵢ⁺/f, Yᵢ⁺/d) — no segment both loaded and open;
    - ``equilibrium``: abs(Rᵀ F − T) / T (seed Eq. 3.14);
    - ``upper_complementarity``: maxᵢ min((F_max,ᵢ − Fᵢ)⁺/f, Yᵢ⁻/d) over the segments
      with a limit — a segment penetrates only at its limit (0 without limits).

    Parameters
    ----------
    problem : ContactProblem
    force : array, shape (N,) — [N]
    rotation : float — [rad]

    Returns
    -------
    dict of str to float
        Keyed by :data:`RESIDUALS`. Non-finite inputs give ``inf`` residuals, never NaN.
    """
    return residuals_and_gaps(problem, force, rotation)[0]


def residuals_and_gaps(problem: ContactProblem, force: np.ndarray, rotation: float
                       ) -> tuple[dict[str, float], np.ndarray | None]:
    """:func:`contact_residuals` and the gaps they were computed from.

    A solve's certification and its solution's slack from one product C F.

    Parameters
    ----------
    problem : ContactProblem
    force : array, shape (N,) — [N]
    rotation : float — [rad]

    Returns
    -------
    residuals : dict of str to float
        As :func:`contact_residuals` (keyed by :data:`RESIDUALS`; ``inf`` for non-finite
        inputs).
    gaps : ndarray, shape (N,), or None
        Y = C F + s − R Θ [mm] (:meth:`ContactProblem.gap`'s arithmetic, to the bit); None
        where F or Θ is not finite or F has the wrong shape.

    Notes
    -----
    Source: the gaps of the compatibility condition, seed Eq. 3.13; the residuals of
    :func:`contact_residuals` (equilibrium, seed Eq. 3.14).
    """
    F = np.asarray(force, dtype=float)
    if F.shape != (problem.size,) or not math.isfinite(rotation):
        return dict.fromkeys(RESIDUALS, math.inf), None
    # ‖F‖∞ is NaN or inf exactly where some force is not finite (N ≥ 1): one pass for
    # both (issue 75: this runs at every solve of every Weber iteration)
    f_abs = float(np.abs(F).max())
    if not math.isfinite(f_abs):
        return dict.fromkeys(RESIDUALS, math.inf), None
    sc = problem.scale
    CF = problem.compliance @ F
    Y = CF + problem.separation - problem.moment_arm * rotation
    # (the arrays' max method: np.max's reduction without its dispatch layers; ‖R‖∞ is
    # the scale's arm r₀, ContactProblem._set_checked)
    f_ref = max(f_abs, sc.force)
    d_ref = max(float(np.abs(CF).max()), abs(rotation) * sc.arm, sc.length)
    # the largest of max(a, b) is the larger of the two largest (max is exact), and
    # max(−F) is −min(F): the same numbers in fewer array passes
    if problem.has_bounds:
        # F − F_max is −inf without a limit (adds zeros to the max), and the segments with
        # a limit are left out of the dual test and kept in the upper complementarity
        b = problem.bounded
        U = problem.upper_bound
        negY = np.maximum(-Y, 0.0)  # penetration
        primal = max(0.0, -float(F.min()), float((F - U).max())) / f_ref
        dual = float(np.where(b, 0.0, negY).max()) / d_ref
        upper = float(np.where(
            b, np.minimum(np.maximum(U - F, 0.0) / f_ref, negY / d_ref), 0.0).max())
    else:
        primal = max(0.0, -float(F.min())) / f_ref
        dual = max(0.0, -float(Y.min())) / d_ref  # the largest penetration
        upper = 0.0
    return {
        "primal": primal,
        "dual": dual,
        "complementarity": float(
            np.minimum(np.maximum(F, 0.0) / f_ref, np.maximum(Y, 0.0) / d_ref).max()
        ),
        "equilibrium": abs(float(problem.moment_arm @ F) - problem.torque) / problem.torque,
        "upper_complementarity": upper,
    }, Y


#: LAPACK's Cholesky factorisation and solve in double precision, called directly: the
#: reduced KKT system of an LTCA problem (N ≲ 300) is small enough that the checking
#: layers of scipy.linalg.cho_factor/cho_solve cost as much as the factorisation.
_POTRF, _POTRS = scipy.linalg.lapack.get_lapack_funcs(("potrf", "potrs"), dtype=np.float64)

#: contact sets up to this size are gathered from C by two ``take`` calls, larger ones by
#: a ``take`` and a fancy-indexed slice (measured: each the faster on its side)
_TAKE_LIMIT = 96


def reduced_kkt(
    compliance: np.ndarray,
    separation: np.ndarray,
    moment_arm: np.ndarray,
    torque: float,
    idx: np.ndarray,
    schur_floor: float,
) -> tuple[np.ndarray, float] | None:
    """The KKT system of the contact problem on the contact set ``idx``, solved exactly.

    On the set A: C_AA F_A − R_A Θ = −s_A and R_Aᵀ F_A = T. One Cholesky factorisation
    of C_AA (LAPACK ``potrf``), two right-hand sides x_s = C_AA⁻¹ s_A, x_r = C_AA⁻¹ R_A
    (``potrs``); the scalar Schur complement R_Aᵀ x_r gives
    Θ = (T + R_Aᵀ x_s)/(R_Aᵀ x_r) and F_A = Θ x_r − x_s (seed Eq. 3.12–3.14 on A).

    Parameters
    ----------
    compliance : ndarray (N, N) — [mm/N], symmetric
    separation, moment_arm : ndarray (N,) — [mm]
    torque : float — [N·mm]
    idx : int ndarray (k,), k ≥ 1
        Indices of the contact set A.
    schur_floor : float — [mm·N]
        The smallest Schur complement R_Aᵀ C_AA⁻¹ R_A taken as positive.

    Returns
    -------
    (F_A [N] shape (k,), Θ [rad]) or None
        None when C_AA is not positive definite or the Schur complement ≤ ``schur_floor``
        (A cannot carry the torque).
    """
    # C is symmetric: the transposed (Fortran-ordered) view of the C-ordered submatrix is
    # the same matrix, which LAPACK factors in place without a copy; the two gathers
    # are the fastest way to it for small sets, one gather and a slice for larger ones
    rows = compliance.take(idx, 0)
    C_AA = (rows.take(idx, 1) if idx.size < _TAKE_LIMIT else rows[:, idx]).T
    factor, info = _POTRF(C_AA, lower=1, clean=0, overwrite_a=1)
    if info != 0:
        return None
    R_A = moment_arm.take(idx)
    rhs = np.array((separation.take(idx), R_A)).T  # (k, 2), Fortran-ordered
    x, info = _POTRS(factor, rhs, lower=1, overwrite_b=1)
    if info != 0:
        return None
    x_s, x_r = x[:, 0], x[:, 1]
    schur = float(R_A.dot(x_r))
    if not schur > schur_floor:
        return None
    theta = (torque + float(R_A.dot(x_s))) / schur
    return theta * x_r - x_s, theta


def schur_floor(problem: ContactProblem) -> float:
    """[mm·N] The smallest Schur complement R_Aᵀ C_AA⁻¹ R_A :func:`reduced_kkt` takes as
    positive: 1e-14 of its reference r₀² f₀/δ₀ (:class:`ProblemScale`)."""
    return problem.scale.schur_floor


def solve_on_contact_set(
    problem: ContactProblem, active: np.ndarray, upper: np.ndarray | None = None
) -> tuple[np.ndarray, float] | None:
    """Solve the equality-constrained KKT system on a given contact set exactly.

    On the set A of loaded segments below their limits, with the set B at their limits
    (F_B = F_max,B): C_AA F_A − R_A Θ = −(s_A + C_AB F_max,B) and
    R_Aᵀ F_A = T − R_Bᵀ F_max,B, by :func:`reduced_kkt` (one Cholesky factorisation of
    C_AA and the scalar Schur complement); F is zero off A and B.

    Parameters
    ----------
    problem : ContactProblem
    active : bool array, shape (N,)
        The contact set A (segments loaded below their limits).
    upper : bool array, shape (N,), optional
        The set B of segments at their limits (disjoint from A, finite limits only);
        default none.

    Returns
    -------
    (F [N] shape (N,), Θ [rad]) or None
        None when A is empty or R_Aᵀ C_AA⁻¹ R_A ≤ 0 (A cannot carry the torque).
    """
    idx = np.flatnonzero(active)
    if idx.size == 0:
        return None
    s, T = problem.separation, problem.torque
    F = np.zeros(problem.size)
    if upper is not None and np.any(upper):
        jdx = np.flatnonzero(upper)
        F[jdx] = problem.upper_bound[jdx]
        s = s + problem.compliance[:, jdx] @ F[jdx]
        T = T - float(problem.moment_arm[jdx] @ F[jdx])
    sol = reduced_kkt(problem.compliance, s, problem.moment_arm, T, idx,
                      schur_floor(problem))
    if sol is None:
        return None
    F[idx] = sol[0]
    return F, sol[1]


@dataclass(frozen=True, eq=False)
class ContactSolution:
    """A solution of :class:`ContactProblem`, certified by our own residuals.

    Attributes
    ----------
    force : ndarray, shape (N,) — [N]
        Segment forces F.
    rotation : float — [rad]
        Gear rigid-body rotation Θ: the loaded transmission error.
    slack : ndarray, shape (N,) — [mm]
        Gaps after loading Y = C F + s − R Θ.
    found : bool
        True only if every residual ≤ ``tolerance`` (checked here, not by the backend).
    status : str
        ``"solved"``, ``"solved (polished)"``, or why not.
    solver : str
        Registry name of the backend.
    build_time, solve_time : float — [s]
        Problem conversion (scaling, dense → sparse) and backend wall time.
    residuals : dict of str to float
        ``primal``, ``dual``, ``complementarity``, ``equilibrium``,
        ``upper_complementarity`` (see :func:`contact_residuals`).
    tolerance : float
        The tolerance ``found`` was judged against.
    iterations : int
        Backend iterations where reported (-1 otherwise).
    extras : dict
        Backend-specific information (e.g. raw residuals before polishing).
    """

    force: np.ndarray
    rotation: float
    slack: np.ndarray
    found: bool
    status: str
    solver: str
    build_time: float
    solve_time: float
    residuals: Mapping[str, float]
    tolerance: float = DEFAULT_TOLERANCE
    iterations: int = -1
    extras: Mapping[str, Any] = field(default_factory=dict)

    @property
    def active_set(self) -> np.ndarray:
        """Segments in contact, shape (N,) bool: a warm start for the next roll position.

        A segment is in contact when its force exceeds ``tolerance`` times the
        largest force: interior-point and first-order backends leave forces of
        round-off size on open segments, which certification bounds by the same
        tolerance (complementarity residual).
        """
        F = self.force
        if not np.all(np.isfinite(F)):
            return np.zeros(F.shape, dtype=bool)
        return F > self.tolerance * max(float(np.max(F)), 0.0)

    def at_limit(self, problem: ContactProblem) -> np.ndarray:
        """Segments at their force limit, shape (N,) bool: the plastic segments.

        A segment is at its limit when it is in contact (:attr:`active_set`) and its force
        is within ``tolerance`` times the largest force of its finite limit F_max (the
        certification bounds the distance of a penetrating segment from its limit by the
        same tolerance: upper complementarity residual). A segment that carries no force
        is never at its limit, however small its limit: a sliver of a contact line
        clipped at the face's boundary (8.4e-7 mm long, F_max 3.2e-4 N, below the
        tolerance) counted as plastic at zero force, and ``ltca run`` printed "plastic 2
        (0.0 %)" for a design without a plastic contact (issue 71, round 16: the
        industrial spiral bevel 17x53 at 5970 N m).

        Parameters
        ----------
        problem : ContactProblem
            The problem this solves (its ``upper_bound``).
        """
        F = self.force
        if not np.all(np.isfinite(F)) or F.shape != (problem.size,):
            return np.zeros(problem.size, dtype=bool)
        tol = self.tolerance * max(float(np.max(F)), problem.scale.force)
        return problem.bounded & self.active_set & (F >= problem.upper_bound - tol)

    @property
    def max_residual(self) -> float:
        """The largest of the relative residuals."""
        return max(self.residuals.values())
