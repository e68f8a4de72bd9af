"""Corrective machine settings: from measured flank deviations back to setting changes.

Closed-loop production (seed §4.3 measures flanks on a CMM grid and feeds the deviations
forward into the contact analysis; this module goes the other way): given the normal
deviations δ of one flank measured on its projection-plane grid, find the changes of the
flank's machine and blade settings that explain them, and the changes that cancel them.

Measured deviation of a flank cut with other settings
-----------------------------------------------------
As a CMM measures: at every nominal grid point p (projection-plane fractions (u, v) of
:func:`geometry.machine.flank.projection_grid`) with outward unit normal n, the deviation is the t
at which the line p + t n pierces the flank cut with the changed settings; positive =
material added (:mod:`contact.utca.deviations`' convention). :func:`cmm_deviation` finds t by
a tangent-plane Newton iteration on the generator: the changed flank's point at the axial
section (z, ρ) of the current point x = p + t n (:func:`geometry.machine.flank.flank_at`) differs
from x only along the circle of that section, so t ← t + (r − x)·n′ / (n·n′) with r, n′
its point and normal; two or three steps reach 1e-11 mm.

Identification and correction
-----------------------------
With s the chosen settings (a variable list per process, :data:`DEFAULT_VARIABLES`,
overridable), J the (points × settings) Jacobian of δ by central differences (steps scaled
so that each moves the flank by about 2 µm) and δ_m the measured deviations, the settings
error Δ minimises ‖δ(s₀ + Δ) − δ_m‖ (Gauss–Newton with J fixed at s₀, each step a
bounded linear least squares, :func:`scipy.optimize.lsq_linear`). The machine that cut the
measured flank behaves as if its settings were s₀ + Δ; dialling the **correction
c = −Δ** into it cancels the deviation (to first order the flank then deviates by the
fit residual δ_m − δ(s₀ + Δ)). :class:`SettingCorrection` returns both Δ
(``identified``) and c (``correction``); the corrected case holds s₀ + c.

Conditioning (which settings the measurement determines)
---------------------------------------------------------
A 5 × 9 grid sees a handful of independent flank shapes (offset, pressure and spiral
angle, twist, crowning, bias …) while a cradle-type generator has more settings, many of
which move the flank almost alike. With J̃ the Jacobian with unit columns, its singular
values σ₁ ≥ … and the condition number σ₁/σₖ say how well the set is determined; the
settings are chosen by subset selection (Golub, Klema & Stewart 1976; Golub & Van Loan,
*Matrix Computations*, 4th ed., §5.5.7): the numerical rank r counts σᵢ ≥ σ₁/κ_max
(:data:`COND_MAX`), and QR with column pivoting of the first r right singular vectors
picks the r settings that span them best. The others are held fixed (correction 0) and
reported as not determined, with their variance inflation factor VIF_j = [(J̃ᵀJ̃)⁻¹]_jj
in the candidate set (1 for a setting independent of the others, → ∞ for one the others
reproduce). A setting that moves the flank by less than :data:`NO_EFFECT` at its trial
step is reported as having no effect. The standard error of each determined setting per
µm of measurement noise is 1e-3 mm · √[(JᵀJ)⁻¹]_jj over the determined set.

Public functions
----------------
SettingVariable         one correctable setting: where it lives, its unit, its trial step
SETTING_VARIABLES       registry name → SettingVariable
DEFAULT_VARIABLES       process → default variable names
setting_value           a setting's value in a flank's tools
tool_with_values        the flank's tools with settings replaced (validated)
case_with_values        a case with one flank's settings replaced
measurement_places      (z, ρ) of projection-plane fractions (u, v)
cmm_deviation           deviation of a changed flank along the nominal normals (as a CMM)
settings_deviation      the deviation grid of a flank cut with changed settings
setting_sensitivities   Jacobian of the deviation with respect to settings
identifiable_subset     subset selection on a Jacobian (SVD + pivoted QR)
SettingCorrection       the result of corrective_settings
corrective_settings     settings error and correction from measured deviations
corrected_case          the case with the corrections applied, with provenance
"""

from __future__ import annotations

import logging
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np
import scipy.linalg
from scipy.optimize import lsq_linear

from geometry.core.errors import InputError
from geometry.core.validation import positive, real_array
from geometry.machine.flank import FlankSurface, blank_outline, flank_at
from geometry.synthesis.setting_variables import (
    COND_MAX,
    DEFAULT_VARIABLES,
    SETTING_VARIABLES,
    SettingVariable,
    case_with_values,
    setting_value,
    tool_with_values,
    variables_of,
)

__all__ = [
    "COND_MAX",
    "DEFAULT_VARIABLES",
    "NO_EFFECT",
    "SETTING_VARIABLES",
    "SettingCorrection",
    "SettingVariable",
    "case_with_values",
    "cmm_deviation",
    "corrected_case",
    "corrective_settings",
    "identifiable_subset",
    "measurement_places",
    "setting_sensitivities",
    "setting_value",
    "settings_deviation",
    "tool_with_values",
]

log = logging.getLogger(__name__)


if TYPE_CHECKING:
    from geometry.case import Blank, Case, FlankTool


#: [mm] a setting whose trial step moves no grid point by more than this has no effect
#: (100 × the generator's point accuracy of 1e-10 mm)
NO_EFFECT = 1e-8


#: [mm] the finite-difference steps are scaled to move the flank by about this much
_FD_TARGET = 2e-3


#: [mm] accuracy of a CMM deviation (the generator solves points to 1e-10 mm)
_CMM_TOL = 1e-11


#: [mm] Gauss–Newton stops when a step changes the fitted deviations by less than this
_GN_TOL = 1e-9


def measurement_places(blank: Blank, u, v) -> tuple[np.ndarray, np.ndarray]:
    """Projection-plane places (z, ρ) of a measurement grid's fractions.

    Parameters
    ----------
    blank : geometry.case.Blank
    u : array_like (nu,) — [1]
        Lengthwise fractions, toe 0 → heel 1.
    v : array_like (nv,) — [1]
        Profile fractions, root 0 → tip 1.

    Returns
    -------
    axial, radius : ndarray (nu, nv) — [mm]
        The bilinear map of :func:`geometry.machine.flank.projection_grid` (same layout, arbitrary
        fractions).
    """
    c = blank_outline(blank).corners
    uu, vv = np.meshgrid(np.asarray(u, dtype=float), np.asarray(v, dtype=float),
                         indexing="ij")
    uu, vv = uu[..., None], vv[..., None]
    pts = ((1 - uu) * (1 - vv) * c[0, 0] + uu * (1 - vv) * c[1, 0]
           + (1 - uu) * vv * c[0, 1] + uu * vv * c[1, 1])
    return pts[..., 0], pts[..., 1]


def cmm_deviation(case: Case, member: str, flank: str, position, normal, *,
                  guess: FlankSurface | None = None, max_iter: int = 12,
                  ) -> tuple[np.ndarray, FlankSurface]:
    """Normal deviation of a case's flank from nominal points, measured as a CMM does.

    Parameters
    ----------
    case : geometry.case.Case
        The case whose flank is "measured" (e.g. the nominal case with changed settings).
    member, flank : str
    position : array (..., 3) — [mm]
        Nominal points p in the member frame.
    normal : array (..., 3) — [1]
        Their outward unit normals n.
    guess : FlankSurface, optional
        Envelope parameters of nearby solutions (e.g. the nominal flank at these points),
        passed to :func:`geometry.machine.flank.flank_at`.
    max_iter : int
        Newton steps at most.

    Returns
    -------
    deviation : ndarray (...) — [mm]
        t with p + t n on the case's flank: positive = material added; NaN where the
        nominal point is NaN or the flank has no generated point there.
    surface : FlankSurface or None
        The flank's points p + t n (last iterate) with their envelope parameters; None when
        no nominal point is finite.

    Notes
    -----
    Tangent-plane Newton iteration t ← t + (r − x)·n′/(n·n′) with x = p + t n and r, n′ the
    flank's point and normal at the axial section (z, ρ) of x (module docstring); stops
    when every |Δt| < 1e-11 mm. Source: the CMM measurement of seed §4.5.2 (normal
    deviations at the nominal grid points).
    """
    p = np.asarray(position, dtype=float)
    n = np.asarray(normal, dtype=float)
    ok = np.all(np.isfinite(p), -1) & np.all(np.isfinite(n), -1)
    t = np.where(ok, 0.0, np.nan)
    if not ok.any():
        return t, None
    pv, nv = p[ok], n[ok]
    tv = np.zeros(pv.shape[0])
    g = None if guess is None else tuple(np.asarray(a)[ok]
                                         for a in (guess.s, guess.theta, guess.q,
                                                   guess.section))
    dt = np.full(tv.shape, np.inf)
    surf = None
    for _ in range(max_iter):
        # a point whose step left the generated flank (NaN) drops out; the others go on
        live = np.isfinite(tv)
        if not live.any():
            break
        x = pv + np.where(live, tv, 0.0)[:, None] * nv
        gl = None if g is None else tuple(np.where(live, a, a[live][0]) for a in g)
        surf = flank_at(case, member, flank, x[:, 2], np.hypot(x[:, 0], x[:, 1]), guess=gl)
        dt = (((surf.position - x) * surf.normal).sum(-1) / (nv * surf.normal).sum(-1))
        dt[~live] = np.nan
        tv = tv + dt
        g = (surf.s, surf.theta, surf.q, surf.section)
        if np.all(np.abs(dt[np.isfinite(dt)]) < _CMM_TOL):
            break
    bad = ~np.isfinite(dt) | (np.abs(dt) >= _CMM_TOL)
    if np.any(np.isfinite(dt) & bad):
        log.warning("cmm_deviation: %d point(s) not converged (|dt| up to %.3g mm)",
                    int((np.isfinite(dt) & bad).sum()), float(np.nanmax(np.abs(dt))))
    tv[bad] = np.nan
    t[ok] = tv
    full = _scatter(surf, ok, p.shape[:-1]) if surf is not None else None
    return t, full


def _scatter(surf: FlankSurface, ok: np.ndarray, shape: tuple) -> FlankSurface:
    """A FlankSurface of the full shape from one solved on the points ``ok``."""
    out = {}
    for name in ("position", "normal", "dir1", "dir2"):
        a = np.full((*shape, 3), np.nan)
        a[ok] = getattr(surf, name)
        out[name] = a
    for name in ("kappa1", "kappa2", "meshing_residual", "s", "theta", "q"):
        a = np.full(shape, np.nan)
        a[ok] = getattr(surf, name)
        out[name] = a
    sec = np.zeros(shape, dtype=np.asarray(surf.section).dtype)
    sec[ok] = surf.section
    reason = np.ones(shape, dtype=np.int8)
    reason[ok] = surf.reason
    return surf._replace(section=sec, reason=reason, **out)


def _nominal(case: Case, member: str, flank: str, u, v) -> FlankSurface:
    z, rho = measurement_places(case.member(member).blank, u, v)
    return flank_at(case, member, flank, z, rho)


def settings_deviation(case: Case, member: str, flank: str, values: Mapping[str, float],
                       u, v) -> np.ndarray:
    """Deviation grid of a flank cut with changed settings, measured against the nominal.

    Parameters
    ----------
    case : geometry.case.Case
        The nominal case.
    member, flank : str
    values : mapping name → float
        Settings of the "measured" flank in internal units (rad, mm) (the others nominal).
    u, v : array_like (nu,), (nv,) — [1]
        Measurement grid fractions (e.g. 9 lengthwise × 5 profile points,
        ``contact.utca.deviations.DEFAULT_MEASUREMENT_GRID``).

    Returns
    -------
    ndarray (nu, nv) — [mm]
        Normal deviation, positive = material added (:func:`cmm_deviation`); NaN where the
        nominal flank has no generated point.

    Raises
    ------
    InputError
        As :func:`tool_with_values` and :func:`geometry.machine.flank.flank_at`.
    """
    nom = _nominal(case, member, flank, u, v)
    changed = case_with_values(case, member, flank, values)
    return cmm_deviation(changed, member, flank, nom.position, nom.normal, guess=nom)[0]


def setting_sensitivities(case: Case, member: str, flank: str, names: Sequence[str],
                          nominal: FlankSurface, *, tool: FlankTool | None = None,
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Jacobian of the CMM deviation of a flank with respect to its settings.

    Parameters
    ----------
    case : geometry.case.Case
    member, flank : str
    names : sequence of str
        Keys of :data:`SETTING_VARIABLES`.
    nominal : FlankSurface
        The nominal flank at the measurement points (its generated points are used).
    tool : geometry.case.FlankTool, optional
        The tools about which to differentiate (default the case's).

    Returns
    -------
    jacobian : ndarray (points, settings) — [mm per internal unit]
        ∂δ/∂s_j over the nominal's generated points (flattened, C order), by central
        differences; a column of zeros where the setting has no effect.
    steps : ndarray (settings,)
        The steps h_j used (internal units), scaled so that each moves the flank by about
        2 µm (second-order error ~ (h/scale)² of the derivative).
    effect : ndarray (settings,) of bool
        False where the trial step moved no point by more than :data:`NO_EFFECT`.

    Raises
    ------
    InputError
        For unknown names, a step that leaves a setting's valid range, or one whose flank
        no longer covers every grid point.
    """
    base = case.member(member).flank(flank) if tool is None else tool
    ok = nominal.valid
    p, n = nominal.position[ok], nominal.normal[ok]

    sub = nominal._replace(s=nominal.s[ok], theta=nominal.theta[ok], q=nominal.q[ok],
                           section=nominal.section[ok])

    def dev(name, value):
        c = case_with_values(case, member, flank, {name: value}, tool=base)
        d = cmm_deviation(c, member, flank, p, n, guess=sub)[0]
        if not np.all(np.isfinite(d)):
            raise InputError(f"settings: a finite-difference step of {name!r} loses grid "
                             "points of the flank; the measurement grid reaches beyond the "
                             "generated flank")
        return d

    jac = np.zeros((p.shape[0], len(names)))
    steps = np.zeros(len(names))
    effect = np.zeros(len(names), dtype=bool)
    for j, name in enumerate(names):
        var = SETTING_VARIABLES[name]
        s0 = setting_value(base, name)
        trial = np.max(np.abs(dev(name, s0 + var.step)))
        if not trial > NO_EFFECT:
            steps[j] = var.step
            continue
        h = var.step * _FD_TARGET / trial
        jac[:, j] = (dev(name, s0 + h) - dev(name, s0 - h)) / (2.0 * h)
        steps[j] = h
        effect[j] = True
    return jac, steps, effect


def identifiable_subset(jacobian, cond_max: float = COND_MAX):
    """Which columns of a Jacobian are determined: subset selection by SVD and pivoted QR.

    Parameters
    ----------
    jacobian : array (points, settings)
        Sensitivities (columns of zeros: settings without effect).
    cond_max : float
        Largest accepted condition number of the unit-column Jacobian of the selection, > 1.

    Returns
    -------
    selected : ndarray (settings,) of bool
        The r columns kept, r the number of singular values σᵢ ≥ σ₁/cond_max.
    singular_values : ndarray
        Of the unit-column Jacobian of the columns with an effect, descending.
    vif : ndarray (settings,)
        Variance inflation factor 1/(1 − R_j²) of each column with an effect against the
        *selected* columns, R_j² the (uncentred) fraction of the unit column that the other
        selected columns reproduce by least squares: for a selected column [(J̃_sᵀJ̃_s)⁻¹]_jj
        of the selection J̃_s (bounded by its condition number, ≤ cond_max²), for one left
        out what it would be if it alone were added; inf for a column without effect or one
        the selection reproduces to 1e-15.

    Raises
    ------
    InputError
        For a non-finite Jacobian or cond_max ≤ 1.

    Notes
    -----
    Golub, Klema & Stewart, "Rank degeneracy and least squares problems", Stanford
    STAN-CS-76-559 (1976); Golub & Van Loan, Matrix Computations, 4th ed., §5.5.7: with
    J̃ = U Σ Vᵀ and r the numerical rank, QR with column pivoting of V[:, :r]ᵀ orders the
    columns by how independently they span the dominant right singular subspace; the first r
    pivots are kept. The selection's condition number is then close to σ₁/σᵣ.
    """
    a = real_array("jacobian", jacobian, ndim=2)
    positive("cond_max", cond_max)
    if cond_max <= 1.0:
        raise InputError(f"cond_max: must be > 1, got {cond_max}")
    norms = np.linalg.norm(a, axis=0)
    live = np.flatnonzero(norms > 0.0)
    selected = np.zeros(a.shape[1], dtype=bool)
    vif = np.full(a.shape[1], np.inf)
    if live.size == 0:
        return selected, np.zeros(0), vif
    an = a[:, live] / norms[live]
    _, sv, vt = np.linalg.svd(an, full_matrices=False)
    rank = int(np.sum(sv >= sv[0] / cond_max))
    _, _, piv = scipy.linalg.qr(vt[:rank], pivoting=True, mode="economic")
    selected[live[piv[:rank]]] = True
    kept = selected[live]
    for k, j in enumerate(live):
        # VIF = 1 / (1 − R²), R² of the unit column regressed on the determined others (least
        # squares): for a determined setting, how much the fit that varies it inflates its
        # variance; for one held fixed, how much it would if it were freed as well
        others = an[:, kept & (np.arange(live.size) != k)]
        rest = an[:, k]
        if others.shape[1]:
            rest = rest - others @ np.linalg.lstsq(others, rest, rcond=None)[0]
        unexplained = float(rest @ rest)
        vif[j] = 1.0 / unexplained if unexplained > 1e-15 else np.inf
    return selected, sv, vif


@dataclass(frozen=True)
class SettingCorrection:
    """Result of :func:`corrective_settings` for one member's flank.

    Arrays over the settings are in the order of ``names``; values in internal units
    (rad, mm; ``scale`` converts: file value = value / scale).

    Attributes
    ----------
    member, flank : str
    names, units : tuple of str
        Setting names and their units in files and tables.
    scale : ndarray
        Internal value per file unit.
    nominal : ndarray
        The settings of the case (s₀).
    identified : ndarray
        Δ: the settings change that reproduces the measured flank (the machine cut as if
        set to s₀ + Δ).
    correction : ndarray
        c = −Δ: the change to dial into the machine to cancel the deviation.
    corrected : ndarray
        s₀ + c, the values written to the corrected case.
    determined : ndarray of bool
        Settings the measurement determines (corrected); the others are held fixed (c = 0).
    effect : ndarray of bool
        False for settings that do not move the flank at all.
    at_bound : ndarray of bool
        Corrected value on a bound.
    vif : ndarray
        Variance inflation factor against the determined settings (of a determined one:
        within the fit, ≤ cond_max²; of one held fixed: were it freed too; inf: exactly
        dependent or without effect; :func:`identifiable_subset`).
    standard_error_per_um : ndarray
        Standard error of Δ per µm of measurement noise (NaN for held settings).
    standard_error : ndarray
        Standard error of Δ from the fit residual (σ̂ = ‖r‖/√(n − r); NaN when n = r).
    singular_values : ndarray
        Of the unit-column Jacobian of the candidates with an effect.
    condition_number, condition_number_determined : float
        σ₁/σ_min of the candidates with an effect, and of the determined ones.
    cond_max : float
        The threshold used.
    steps : ndarray
        Finite-difference steps.
    jacobian : ndarray (n_points, settings) — [mm per internal unit]
        ∂δ/∂s at s₀ over the points used (C order of the (u, v) grid).
    u, v : ndarray
        Measurement grid fractions.
    measured : ndarray (nu, nv) — [mm]
        The measured deviations (NaN: not used).
    residual : ndarray (nu, nv) — [mm]
        δ_m − δ(s₀ + Δ): what the correction leaves (to first order the deviation of the
        flank the corrected machine cuts), positive = material added.
    measured_rms, measured_max, residual_rms, residual_max : float — [mm]
        RMS and largest |·| over the points used.
    n_points : int
        Points used.
    iterations : int
        Gauss–Newton steps.
    """

    member: str
    flank: str
    names: tuple[str, ...]
    units: tuple[str, ...]
    scale: np.ndarray
    nominal: np.ndarray
    identified: np.ndarray
    correction: np.ndarray
    corrected: np.ndarray
    determined: np.ndarray
    effect: np.ndarray
    at_bound: np.ndarray
    vif: np.ndarray
    standard_error_per_um: np.ndarray
    standard_error: np.ndarray
    singular_values: np.ndarray
    condition_number: float
    condition_number_determined: float
    cond_max: float
    steps: np.ndarray
    jacobian: np.ndarray
    u: np.ndarray
    v: np.ndarray
    measured: np.ndarray
    residual: np.ndarray
    measured_rms: float
    measured_max: float
    residual_rms: float
    residual_max: float
    n_points: int
    iterations: int

    @property
    def values(self) -> dict[str, float]:
        """The corrected values of the determined settings, name → internal units."""
        return {n: float(c) for n, c, d in zip(self.names, self.corrected, self.determined,
                                               strict=True) if d}


def _bounds(names, tool, bounds) -> tuple[np.ndarray, np.ndarray]:
    """Bounds of the corrected values, each checked against the setting's valid range."""
    lo = np.full(len(names), -np.inf)
    hi = np.full(len(names), np.inf)
    if bounds is None:
        return lo, hi
    if not isinstance(bounds, Mapping):
        raise InputError(f"bounds: must be a mapping name -> (low, high), got {bounds!r}")
    for name, pair in bounds.items():
        if name not in SETTING_VARIABLES:
            raise InputError(f"bounds: unknown setting {name!r}; accepted: "
                             f"{', '.join(SETTING_VARIABLES)}")
        if name not in names:
            raise InputError(f"bounds: {name!r} is not among the settings corrected "
                             f"({', '.join(names)})")
        var = SETTING_VARIABLES[name]
        j = names.index(name)
        try:
            low, high = pair
        except (TypeError, ValueError):
            raise InputError(f"bounds.{name}: must be a (low, high) pair, got {pair!r}") from None
        low = -np.inf if low is None else float(low)
        high = np.inf if high is None else float(high)
        if math.isnan(low) or math.isnan(high) or not low < high:
            raise InputError(f"bounds.{name}: must satisfy low < high, got ({low / var.scale:g},"
                             f" {high / var.scale:g}) {var.unit}")
        for b in (low, high):
            if math.isfinite(b):
                try:
                    tool_with_values(tool, {name: b})
                except InputError as exc:
                    raise InputError(
                        f"bounds.{name}: {b / var.scale:g} {var.unit} lies outside the "
                        f"setting's valid range ({exc})") from None
        lo[j], hi[j] = low, high
    return lo, hi


def corrective_settings(case: Case, member: str, flank: str, u, v, deviation, *,
                        settings: Sequence[str] | None = None,
                        bounds: Mapping[str, tuple[float | None, float | None]] | None = None,
                        cond_max: float = COND_MAX, max_iter: int = 10) -> SettingCorrection:
    """Setting changes that cancel measured normal deviations of one flank.

    Parameters
    ----------
    case : geometry.case.Case
        The nominal case (the settings the flank was cut with).
    member, flank : str
        ``"pinion"``/``"gear"``, ``"concave"``/``"convex"``.
    u : array_like (nu,) — [1]
        Lengthwise fractions of the measurement grid, toe 0 → heel 1.
    v : array_like (nv,) — [1]
        Profile fractions, root 0 → tip 1.
    deviation : array_like (nu, nv) — [mm]
        Measured normal deviations, positive = material added (NaN: point not measured).
    settings : sequence of str, optional
        Candidate settings (:data:`SETTING_VARIABLES`); default
        :data:`DEFAULT_VARIABLES` of the member's process.
    bounds : mapping name → (low, high), optional
        Bounds of the corrected values in internal units (rad, mm), None for open; each
        must lie in the setting's valid range.
    cond_max : float — [1]
        Condition-number threshold of the subset selection, σ₁/σ of the unit-column
        Jacobian's singular values (dimensionless); default :data:`COND_MAX` (100).
    max_iter : int
        Gauss–Newton steps at most (≥ 1).

    Returns
    -------
    SettingCorrection
        Δ (``identified``), c = −Δ (``correction``), the determined settings, the
        conditioning and the residual.

    Raises
    ------
    InputError
        For unknown names, a setting not available to the process, bad grids, deviations
        of the wrong shape, fewer than 3 usable points, bounds that are reversed or outside
        a setting's valid range, or a correction whose settings generate no flank.

    Notes
    -----
    Module docstring: CMM deviation along the nominal normals, central-difference
    sensitivities, subset selection (Golub, Klema & Stewart 1976) and Gauss–Newton with
    the Jacobian at s₀ and bounded linear steps (:func:`scipy.optimize.lsq_linear`, BVLS).
    Source of the measured quantity: seed §4.3 and §4.5.2 (normal deviations on a 5 × 9
    grid).
    """
    mem = case.member(member)
    tool = mem.flank(flank)
    variables = variables_of(mem.process, settings)
    names = [var.name for var in variables]
    uu = real_array("u", u, unit="1", ndim=1)
    vv = real_array("v", v, unit="1", ndim=1)
    dm = np.array(deviation, dtype=float)
    if dm.shape != (uu.size, vv.size):
        raise InputError(f"deviation: must have shape (len(u), len(v)) = ({uu.size}, "
                         f"{vv.size}), got {dm.shape}")
    if np.any(np.isinf(dm)):
        raise InputError("deviation: must be finite or NaN (not measured), got inf")
    if int(max_iter) != max_iter or max_iter < 1:
        raise InputError(f"max_iter: must be an integer >= 1, got {max_iter!r}")
    lo, hi = _bounds(names, tool, bounds)
    nominal = _nominal(case, member, flank, uu, vv)
    use = nominal.valid & np.isfinite(dm)
    if use.sum() < 3:
        raise InputError(f"deviation: needs at least 3 measured points on the generated "
                         f"flank, got {int(use.sum())}")
    nom_use = nominal._replace(reason=np.where(use, nominal.reason, 1))
    jac, steps, effect = setting_sensitivities(case, member, flank, names, nom_use, tool=tool)
    selected, sv, vif = identifiable_subset(jac, cond_max)
    s0 = np.array([setting_value(tool, n) for n in names])
    meas = dm[use]
    act = np.flatnonzero(selected)
    a = jac[:, act]
    norms = np.linalg.norm(a, axis=0)
    an = a / norms
    # Δ bounds from bounds of the corrected value s0 − Δ
    lb = (s0 - hi)[act] * norms
    ub = (s0 - lo)[act] * norms
    x = np.zeros(act.size)
    resid = -meas  # model(Δ = 0) − measured: the nominal flank has δ = 0
    p, n = nominal.position[use], nominal.normal[use]
    guess = nominal._replace(s=nominal.s[use], theta=nominal.theta[use], q=nominal.q[use],
                             section=nominal.section[use])
    delta = np.zeros(len(names))
    it = 0
    for _ in range(int(max_iter)):
        it += 1
        sol = lsq_linear(an, an @ x - resid, bounds=(lb, ub), method="bvls")
        step = sol.x - x
        x = sol.x
        delta[act] = x / norms
        trial = case_with_values(case, member, flank, dict(zip(names, s0 + delta, strict=True)))
        model = cmm_deviation(trial, member, flank, p, n, guess=guess)[0]
        if not np.all(np.isfinite(model)):
            raise InputError("settings: the identified settings generate no flank at some "
                             "measured points; restrict the settings or add bounds")
        resid = model - meas
        if np.max(np.abs(an @ step)) < _GN_TOL:
            break
    else:
        log.warning("corrective_settings: Gauss-Newton not converged in %d steps", max_iter)
    corr = -delta
    corrected = s0 + corr
    at_bound = np.zeros(len(names), dtype=bool)
    at_bound[act] = (np.isclose(corrected[act], lo[act], rtol=0, atol=1e-12)
                     | np.isclose(corrected[act], hi[act], rtol=0, atol=1e-12))
    se_um = np.full(len(names), np.nan)
    se = np.full(len(names), np.nan)
    if act.size:
        cov = np.linalg.inv(an.T @ an)
        se_um[act] = 1e-3 * np.sqrt(np.diag(cov)) / norms
        dof = meas.size - act.size
        if dof > 0:
            sigma = float(np.linalg.norm(resid) / math.sqrt(dof))
            se[act] = se_um[act] * sigma / 1e-3
    live_sv = sv if sv.size else np.array([np.nan])
    sv_act = (np.linalg.svd(an, compute_uv=False) if act.size else np.array([np.nan]))
    residual = np.full(dm.shape, np.nan)
    residual[use] = -resid
    return SettingCorrection(
        member=member, flank=flank, names=tuple(names),
        units=tuple(var.unit for var in variables),
        scale=np.array([var.scale for var in variables]), nominal=s0, identified=delta,
        correction=corr, corrected=corrected, determined=selected, effect=effect,
        at_bound=at_bound, vif=vif, standard_error_per_um=se_um, standard_error=se,
        singular_values=sv, condition_number=float(live_sv[0] / live_sv[-1]),
        condition_number_determined=float(sv_act[0] / sv_act[-1]), cond_max=float(cond_max),
        steps=steps, jacobian=jac, u=uu, v=vv, measured=np.where(use, dm, np.nan),
        residual=residual,
        measured_rms=float(np.sqrt(np.mean(meas**2))), measured_max=float(np.max(np.abs(meas))),
        residual_rms=float(np.sqrt(np.mean(resid**2))),
        residual_max=float(np.max(np.abs(resid))), n_points=int(meas.size), iterations=it)


def corrected_case(case: Case, corrections: Sequence[SettingCorrection], *,
                   provenance: Mapping[str, object] | None = None,
                   name: str | None = None) -> Case:
    """The case with corrections applied, recording what was done in a ``[correction]`` table.

    Parameters
    ----------
    case : geometry.case.Case
        The nominal case the corrections were computed for.
    corrections : sequence of SettingCorrection
        At most one per member and flank.
    provenance : mapping, optional
        Extra entries of the table (e.g. the deviation files), keyed as given; values
        TOML-writable (str, numbers, lists of them).
    name : str, optional
        Name of the corrected case (default ``<name>_corrected``).

    Returns
    -------
    geometry.case.Case
        The determined settings set to their corrected values (``SettingCorrection.values``),
        ``deviations`` dropped (the measured files describe the uncorrected flanks), and
        ``extra["correction"]`` holding the source case, per member and flank the
        corrections (file units), the settings held fixed, and the RMS/max deviation
        before and residual after [µm].

    Raises
    ------
    InputError
        For two corrections of one flank, or corrected values outside a setting's range.
    """
    seen = set()
    table: dict = {"source_case": case.name, "method":
    "geometry.synthesis.correction.corrective_settings"
                   " (least squares on CMM-deviation sensitivities, subset selection)",
                   "sign": "correction = setting change to apply to the machine to cancel the "
                           "measured deviation (= minus the identified settings error)"}
    table |= dict(provenance or {})
    out = case
    for c in corrections:
        key = (c.member, c.flank)
        if key in seen:
            raise InputError(f"corrections: two corrections of {c.member} {c.flank}")
        seen.add(key)
        out = case_with_values(out, c.member, c.flank, c.values)
        det = [i for i, d in enumerate(c.determined) if d]
        table.setdefault(c.member, {})[c.flank] = {
            "corrections": {c.names[i]: float(c.correction[i] / c.scale[i]) for i in det},
            "units": {c.names[i]: c.units[i] for i in det},
            "held_fixed": [nm for nm, d in zip(c.names, c.determined, strict=True) if not d],
            "condition_number": c.condition_number,
            "cond_max": c.cond_max,
            "points": c.n_points,
            "measured_rms_um": 1e3 * c.measured_rms,
            "measured_max_um": 1e3 * c.measured_max,
            "residual_rms_um": 1e3 * c.residual_rms,
            "residual_max_um": 1e3 * c.residual_max,
        }
    extra = {**out.extra, "correction": table}
    return replace(out, name=name or f"{case.name}_corrected", deviations=None,
                   extra=MappingProxyType(extra))
