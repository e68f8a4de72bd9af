"""Conventional tooth contact analysis (TCA) of one tooth pair (seed §2.3.1, Eq. 2.14).

The independent reference of the toolkit's unloaded TCA: for a prescribed pinion roll the
pinion and gear flanks touch at a point where their positions coincide and their normals are
collinear (seed Eq. 2.14a–b),

    M_p(φ_p) r_p(Z_p, P_p) = M_g(φ_g) r_g(Z_g, P_g),
    M_p(φ_p) n_p(Z_p, P_p) = −M_g(φ_g) n_g(Z_g, P_g),

with M the member → pair transforms of :func:`geometry.pair.assembly.case_transforms` (which carry
the misalignments ΔE, ΔP, ΔG, ΔΣ). Each flank is parametrised by its projection-plane place
(axial position Z, radius P) and evaluated by :func:`geometry.machine.flank_point.flank_points`
(:func:`geometry.machine.meshing.solve_envelope`, seed Eq. 2.7–2.8), so the unknowns are
(Z_p, P_p, Z_g, P_g, φ_g): five unknowns for the five independent equations (the unit
normals add two; all six components are used in a least-squares sense). The Jacobian is
analytic: the surface tangents ∂r/∂Z, ∂r/∂P from the envelope and the normal derivatives
∂n = W ∂r from the shape operator W = κ₁e₁e₁ᵀ + κ₂e₂e₂ᵀ of
:func:`geometry.machine.curvature.surface_curvatures`. Roll positions are solved in blocks of
neighbours by continuation along the roll angle outward from the reference: a batched damped
Gauss–Newton (Levenberg–Marquardt) iteration, one surface evaluation per member and
iteration for the whole block; positions that fail are retried by continuation in small roll
steps, with ``scipy.optimize.least_squares`` (MINPACK Levenberg–Marquardt) as the last
resort. The damping also copes with the rank-deficient Jacobian of a conjugate
(line-contact) pair, where the contact point may lie anywhere on the contact line. A solution
counts only where the relative curvature W_p + W_g is positive semi-definite (a contact, not
a saddle of the separation where the surfaces already cross). The system is
:class:`ToothPair`, which the synthesis (:mod:`geometry.synthesis.case_synthesis`) also uses to
tune the modified roll; it takes any two flanks and any member → pair transforms.

Conventions
-----------
Members turn right-handed about their own +z axis (:mod:`geometry.pair.assembly`). The **pinion
roll** is the pinion rotation measured in its *sense of motion* — the sense in which the
analysed pinion flank pushes the gear (opposite for the drive and the coast flank) — from the
**reference**: the position at which, in the nominal (aligned) assembly, the pinion touches
the gear flank at its mean contact point M (:func:`geometry.pair.design_point.design_point_of_case`:
at the gear's mean cone distance, centred in roll within the working depth — the design
point of a synthesised pair). The reference gear rotation is the TCA gear rotation there, so
the nominal transmission error is exactly 0 at roll 0.

**Transmission error** (TE) is the **gear lag**: the ideal kinematic gear rotation
(z_p/z_g)·roll minus the actual gear rotation from the reference, both measured in the gear's
sense of motion,

    TE(roll) = (z_p/z_g)·roll − s_g (φ_g − φ_g,ref),

so TE ≥ 0 wherever the pair still has a gap to close compared with the ideal motion. For a
pair with a localised bearing the TE of one pair is a ∪-shaped parabola, 0 at its mean
contact point (for a synthesised pair, roll 0), and in mesh the gear follows the *lower
envelope* of the TE curves of adjacent pairs (shifted by one pitch 2π/z_p of roll); the
maxima of that envelope are the transition points M1, M2 (the seed's Fig. 2.9 convention).
A misaligned assembly keeps the nominal reference, so its TE also shows the constant shift
of the gear caused by the misalignment.

Public functions
----------------
ToothPair          seed Eq. 2.14 of two flanks: residual, Jacobian, solvers, contact check
TCAResult          frozen dataclass of the contact path, gear rotation and TE
MeanContact        the reference (mean contact) of a pair and flank
mean_contact       compute the reference
conventional_tca   contact points, gear rotation and TE over pinion roll positions
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import LinearNDInterpolator
from scipy.optimize import least_squares

from geometry.case import FLANKS, Case
from geometry.core.errors import InputError
from geometry.machine.flank import blank_outline, flank_surface
from geometry.machine.flank_point import MemberFlank
from geometry.pair.assembly import Misalignment, case_transforms
from geometry.pair.design_point import design_point_of_case

__all__ = [
    "CONVERGED_RESIDUAL",
    "MeanContact",
    "TCAResult",
    "ToothPair",
    "conventional_tca",
    "mean_contact",
]

log = logging.getLogger(__name__)

#: a roll position counts as converged when max(|r_p − r_g| [mm], |n_p + n_g| [1]) is below
#: this (the solver itself drives the residual to ~1e-12)
CONVERGED_RESIDUAL = 1e-8
_BLOCK = 8  # roll positions solved together
_PENALTY = 1e3  # residual of a point whose surface cannot be evaluated (outside the envelope)
_OTHER = {"concave": "convex", "convex": "concave"}
_STOP = 1e-11  # [mm, 1] a position is solved once Eq. 2.14 holds to this
_FLOOR = 1e-9  # [mm, 1] below this a position that stops improving is at the noise floor
_PSD = 1e-6  # [1/mm] tolerance of the positive semi-definite relative curvature at a contact
_SUBSTEP = 0.025  # [1] largest roll step of the fallback continuation, in pinion pitches
_DAMP = 1e-3  # Levenberg–Marquardt damping of the step, relative to the largest singular value
_STEP_LIMIT = np.array([3.0, 3.0, 3.0, 3.0, 3.0])  # [mm] largest step (φ_g × R_g in mm)


# --------------------------------------------------------------------------- results
@dataclass(frozen=True, eq=False)
class MeanContact:
    """Reference position of a tooth pair: contact at the gear flank's mean contact point M.

    Attributes
    ----------
    flank : str
        Pinion flank (``"concave"`` or ``"convex"``); the gear flank is the other one.
    pinion_rotation, gear_rotation : float — [rad]
        Absolute member rotations (right-handed about each member's own +z, as
        :func:`geometry.pair.assembly.case_transforms` takes them) of the reference, in the
        nominal assembly. ``gear_rotation`` is the TCA gear rotation at ``pinion_rotation``.
    pinion_sense, gear_sense : int
        +1 or −1: the sense of motion of each member when the pinion flank drives
        (pinion: the flank advances along its outward normal; gear: its flank recedes).
    pinion_projection, gear_projection : ndarray (2,) — [mm]
        (axial position, radius) of the contact point at the reference.
    mismatch : float — [1]
        |n_p + n_g| of the best match with the gear point held at M (0 when the contact
        path passes through M, as for a synthesised pair).
    """

    flank: str
    pinion_rotation: float
    gear_rotation: float
    pinion_sense: int
    gear_sense: int
    pinion_projection: np.ndarray
    gear_projection: np.ndarray
    mismatch: float


@dataclass(frozen=True, eq=False)
class TCAResult:
    """Conventional TCA of one tooth pair over pinion roll positions (K of them).

    Attributes
    ----------
    flank : str
        Analysed pinion flank; the gear flank is the other one.
    pinion_roll : ndarray (K,) — [rad]
        Pinion roll in its sense of motion from the reference (module docstring).
    pinion_rotation : ndarray (K,) — [rad]
        Absolute pinion rotation (right-handed about its own +z; for
        :func:`geometry.pair.assembly.case_transforms`): ``reference[0] + sense[0]·pinion_roll``.
    gear_rotation : ndarray (K,) — [rad]
        Absolute gear rotation (right-handed about its own +z) solved by the TCA.
    transmission_error : ndarray (K,) — [rad]
        Gear lag: (z_p/z_g)·roll − sense[1]·(gear_rotation − reference[1]) (≥ 0 where the
        pair has a gap to close; module docstring).
    pinion_point, gear_point : ndarray (K, 3) — [mm]
        Contact point on each flank in the pair frame (equal at a converged position).
    pinion_projection, gear_projection : ndarray (K, 2) — [mm]
        (axial position, radius) of the contact point in each member's projection plane.
    normal : ndarray (K, 3) — [1]
        Unit normal of the pinion flank at the contact point, out of the pinion material,
        in the pair frame.
    residual : ndarray (K,)
        max(|pinion_point − gear_point| [mm], |n_p + n_g| [1]): the residual of seed
        Eq. 2.14.
    converged : ndarray (K,) bool
        residual < :data:`CONVERGED_RESIDUAL`, opposite normals and a positive semi-definite
        relative curvature (a contact, not a saddle). Where False, every solved quantity
        (rotations, TE, points, projections, normal) is NaN.
    on_flank : ndarray (K,) bool
        Both contact points lie inside their blank outlines (between root, face, toe and
        heel cones); outside, the contact is on the flank's analytic extension.
    reference : ndarray (2,) — [rad]
        Absolute (pinion, gear) rotations at roll 0 (:class:`MeanContact`).
    sense : ndarray (2,) int
        (pinion, gear) senses of motion.
    misalignment : Misalignment
        The assembly analysed.
    """

    flank: str
    pinion_roll: np.ndarray
    pinion_rotation: np.ndarray
    gear_rotation: np.ndarray
    transmission_error: np.ndarray
    pinion_point: np.ndarray
    gear_point: np.ndarray
    pinion_projection: np.ndarray
    gear_projection: np.ndarray
    normal: np.ndarray
    residual: np.ndarray
    converged: np.ndarray
    on_flank: np.ndarray
    reference: np.ndarray
    sense: np.ndarray
    misalignment: Misalignment


# --------------------------------------------------------------------------- helpers
def _inside(blank, z: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Whether projection-plane points lie in the blank outline (toe, heel, root, face)."""
    c = blank_outline(blank).corners
    quad = [c[0, 0], c[1, 0], c[1, 1], c[0, 1]]  # toe-root, heel-root, heel-tip, toe-tip
    pts = np.stack([z, p], -1)
    signs = []
    for a, b in zip(quad, quad[1:] + quad[:1], strict=True):
        e = b - a
        rel = pts - a
        signs.append(e[0] * rel[..., 1] - e[1] * rel[..., 0])
    s = np.stack(signs, -1)
    return np.all(s >= -1e-9, -1) | np.all(s <= 1e-9, -1)


# --------------------------------------------------------------------------- the system
class ToothPair:
    """Seed Eq. 2.14 for one pinion flank and the gear flank it meshes, batched over rolls.

    The system of the conventional TCA: for pinion rotations φ_p (K,) and unknowns
    x = (Z_p, P_p, Z_g, P_g, φ_g) (K, 5) — the projection-plane places of the contact point
    on each flank [mm] and the gear rotation [rad] — the residuals

        F = [M_p r_p − M_g r_g,  L_n (M_p n_p + M_g n_g)]   (K, 6) [mm]

    (seed Eq. 2.14a–b; L_n the gear mean cone distance makes the normal residuals lengths),
    their analytic Jacobian, a batched damped Gauss–Newton solver, a scipy fallback for one
    roll and the contact check. Used by :func:`conventional_tca`, :func:`mean_contact` and
    the synthesis's tuning of the modified roll (:mod:`geometry.synthesis.case_synthesis`).

    Parameters
    ----------
    pinion, gear : geometry.machine.flank_point.MemberFlank
        The pinion flank and the gear flank it meshes (tool, blank, hand).
    transforms : callable
        ``transforms(phi_p, phi_g) -> (T_p, T_g)``: member → pair-frame homogeneous
        transforms (…, 4, 4) at member rotations φ_p, φ_g [rad] (right-handed about each
        member's own +z), batched over arrays of rotations (one may be a scalar), e.g.
        :func:`geometry.pair.assembly.case_transforms` of a case.

    Attributes
    ----------
    pinion, gear : MemberFlank
    mean_cone_distance : float — [mm]
        L_n = R_e2 − b2/2 of the gear blank: the scale of the normal residuals.
    mean_pitch_radius : float — [mm]
        L_n sin δ2: the scale of the gear rotation (φ_g × this is a length).

    See Also
    --------
    ToothPair.from_case : the system of a case, pinion flank and assembly.
    """

    def __init__(self, pinion: MemberFlank, gear: MemberFlank, transforms) -> None:
        self.pinion = pinion
        self.gear = gear
        self._transforms = transforms
        bl = gear.blank
        # length scales: normal residuals × L_n, gear rotation × R_g ~ mm
        self.mean_cone_distance = bl.outer_cone_distance - 0.5 * bl.face_width
        self.mean_pitch_radius = self.mean_cone_distance * math.sin(bl.pitch_angle)

    @classmethod
    def from_case(cls, case: Case, flank: str,
                  misalignment: Misalignment | None = None) -> ToothPair:
        """The system of a case: pinion flank ``flank``, the other gear flank, an assembly.

        Parameters
        ----------
        case : geometry.case.Case
        flank : str
            Pinion flank, ``"concave"`` or ``"convex"``; the gear flank is the other one.
        misalignment : geometry.pair.assembly.Misalignment, optional
            Assembly; default the case's own ``misalignment``.

        Returns
        -------
        ToothPair
            With the transforms of :func:`geometry.pair.assembly.case_transforms`.

        Raises
        ------
        InputError
            For a bad flank name.
        """
        if flank not in _OTHER:
            raise InputError(f"flank: must be one of {list(_OTHER)} (the pinion flank), got "
                             f"{flank!r}")
        mis = case.misalignment if misalignment is None else misalignment

        def transforms(phi_p, phi_g):
            return case_transforms(case, phi_p, phi_g, mis)

        return cls(MemberFlank.of_case(case, "pinion", flank),
                   MemberFlank.of_case(case, "gear", _OTHER[flank]), transforms)

    def transforms(self, phi_p, phi_g):
        """Member → pair transforms (T_p, T_g), each (…, 4, 4), at rotations φ_p, φ_g [rad]."""
        return self._transforms(phi_p, phi_g)

    def residual(self, phi_p, x, guess=None):
        """Residuals of seed Eq. 2.14 and their Jacobian at K roll positions.

        Parameters
        ----------
        phi_p : ndarray (K,) — [rad]
            Pinion rotations.
        x : ndarray (K, 5) — [mm, mm, mm, mm, rad]
            (Z_p, P_p, Z_g, P_g, φ_g).
        guess : ndarray (K, 8), optional
            Envelope parameters of nearby points (pinion then gear, as the ``params`` of
            :meth:`newton_params`): the surface solver's start instead of its seed search.

        Returns
        -------
        f : ndarray (K, 6) — [mm]
            r_p − r_g and L_n (n_p + n_g) in the pair frame (class docstring).
        jac : ndarray (K, 6, 5)
            ∂f/∂x (∂r/∂(Z, P) from :func:`geometry.machine.flank_point.flank_points`, ∂n = W ∂r,
            ∂/∂φ_g = −a_g × (r_g − o_g), a_g × n_g).
        ok : ndarray (K,) bool
            Both flanks generated at their places (elsewhere ``f`` and ``jac`` hold NaN).
        placed : tuple
            (r_p, r_g, n_p, n_g) (K, 3) in the pair frame and the relative shape operator
            W_p + W_g (K, 3, 3) [1/mm] in the pair frame.
        """
        return self._residual(phi_p, x, guess)[:4]

    def _residual(self, phi_p, x, guess=None):
        """As :meth:`residual`, plus the envelope parameters (K, 8) of both flanks.

        ``guess`` (K, 8): pinion then gear (s, θ, q, section) from nearby points.
        """
        gp, gg = (None, None) if guess is None else (guess[:, :4], guess[:, 4:])
        fp = self.pinion.points(x[:, 0], x[:, 1], guess=gp)
        fg = self.gear.points(x[:, 2], x[:, 3], guess=gg)
        rp, n_p, dp, wp, okp, pp_par = fp.r, fp.n, fp.tangents, fp.shape, fp.ok, fp.params
        rg, n_g, dg, wg, okg, pg_par = fg.r, fg.n, fg.tangents, fg.shape, fg.ok, fg.params
        tp, tg = self.transforms(phi_p, x[:, 4])
        a_p, a_g = tp[..., :3, :3], tg[..., :3, :3]
        pp = np.einsum("kij,kj->ki", a_p, rp) + tp[..., :3, 3]
        pg = np.einsum("kij,kj->ki", a_g, rg) + tg[..., :3, 3]
        np_ = np.einsum("kij,kj->ki", a_p, n_p)
        ng = np.einsum("kij,kj->ki", a_g, n_g)
        ln = self.mean_cone_distance
        f = np.concatenate([pp - pg, ln * (np_ + ng)], -1)
        jac = np.zeros((len(x), 6, 5))
        jac[:, :3, 0:2] = a_p @ dp
        jac[:, :3, 2:4] = -(a_g @ dg)
        jac[:, 3:, 0:2] = ln * (a_p @ (wp @ dp))
        jac[:, 3:, 2:4] = ln * (a_g @ (wg @ dg))
        axis_g, orig_g = tg[..., :3, 2], tg[..., :3, 3]
        jac[:, :3, 4] = -np.cross(axis_g, pg - orig_g)
        jac[:, 3:, 4] = ln * np.cross(axis_g, ng)
        ok = okp & okg
        rel = (a_p @ wp @ np.swapaxes(a_p, -1, -2)) + (a_g @ wg @ np.swapaxes(a_g, -1, -2))
        return f, jac, ok, (pp, pg, np_, ng, rel), np.concatenate([pp_par, pg_par], -1)

    def newton(self, phi_p, x0, max_iter: int = 15):
        """Batched damped Gauss–Newton: :meth:`newton_params` without the surface parameters.

        Returns
        -------
        x : ndarray (K, 5)
        done : ndarray (K,) bool
        """
        return self.newton_params(phi_p, x0, max_iter)[:2]

    def newton_params(self, phi_p, x0, max_iter: int = 15, guess=None,
                      damping: float = _DAMP):
        """Solve seed Eq. 2.14 at K roll positions together by damped Gauss–Newton.

        Parameters
        ----------
        phi_p : ndarray (K,) — [rad]
            Pinion rotations.
        x0 : array_like (K, 5) — [mm, mm, mm, mm, rad]
            Start (Z_p, P_p, Z_g, P_g, φ_g) of each position.
        max_iter : int
            Largest number of iterations.
        guess : ndarray (K, 8), optional
            Envelope parameters (pinion then gear) of points near the starts, e.g. the
            ``params`` of an earlier solution: the surface solver's first start instead of
            its seed search (the same solution, found with fewer evaluations).
        damping : float — [1]
            μ relative to the largest singular value of J (default ``_DAMP``, 1e-3); 0
            for Gauss–Newton steps, which converge quadratically where J has full rank (a
            localised contact) and slide along the contact line where it has not.

        Returns
        -------
        x : ndarray (K, 5)
            The last accepted iterate of each position (not checked: use :meth:`measure`).
        done : ndarray (K,) bool
            Eq. 2.14 holds to ``_STOP`` (1e-11 mm) or the position stopped improving below
            ``_FLOOR`` (1e-9 mm, the noise floor of the surface evaluation).
        params : ndarray (K, 8)
            Envelope parameters (s, θ, q, section) of the pinion then the gear flank at
            ``x`` (to start :meth:`measure`).

        Notes
        -----
        Levenberg–Marquardt steps. Each roll position is its own 6 × 5 least-squares
        system; all are stepped together (one surface evaluation per member and iteration).
        The step solves (JᵀJ + μ²I) Δx = −JᵀF (scaled unknowns) with μ = ``_DAMP`` (1e-3) ×
        the largest singular value of J: on a localised-contact pair this only slows the
        weakest direction slightly, while on a conjugate pair (J rank-deficient on the
        solution set: the contact point may lie anywhere on the contact line; nearly so just
        off it) it keeps the step from sliding far along the contact line. Steps are limited
        and halved while they leave the generated surface or more than double the residual.
        A position is done when Eq. 2.14 holds to ``_STOP``. Each surface evaluation starts
        the envelope solver from the previous iterate's surface parameters.
        """
        x = np.array(x0, dtype=float)
        k = len(x)
        scale = np.array([1.0, 1.0, 1.0, 1.0, 1.0 / self.mean_pitch_radius])
        done = np.zeros(k, bool)
        dead = np.zeros(k, bool)
        f, jac, ok, _, par = self._residual(phi_p, x, guess)
        dead |= ~ok
        prev = np.full(k, np.inf)
        for _ in range(max_iter):
            size = np.maximum(np.abs(f[:, :3]).max(-1),
                              np.abs(f[:, 3:]).max(-1) / self.mean_cone_distance)
            # solved, or at the noise floor of the surface evaluation (no more progress)
            done |= ((size < _STOP) | ((size > 0.3 * prev) & (size < _FLOOR))) & ~dead
            prev = size
            act = np.flatnonzero(~(done | dead))
            if len(act) == 0:
                break
            js = jac[act] * scale
            u, sv, vt = np.linalg.svd(js, full_matrices=False)
            mu = damping * sv[:, :1]
            inv = sv / (sv * sv + mu * mu)
            du = -np.einsum("kji,kj,klj,kl->ki", vt, inv, u, f[act])
            dx = du * scale
            lim = np.min(_STEP_LIMIT / np.maximum(np.abs(du), 1e-300), axis=-1)
            dx *= np.minimum(1.0, lim)[:, None]
            norm0 = np.linalg.norm(f[act], axis=-1)
            trial = act
            step = dx
            for _half in range(5):
                xn = x[trial] + step
                fn, jn, okn, _, pn = self._residual(phi_p[trial], xn, par[trial])
                good = okn & (np.linalg.norm(np.where(okn[:, None], fn, 0.0), axis=-1)
                              <= norm0 + _STOP)
                x[trial[good]], f[trial[good]], jac[trial[good]] = xn[good], fn[good], jn[good]
                par[trial[good]] = pn[good]
                if good.all():
                    break
                bad = ~good
                trial, step, norm0 = trial[bad], 0.5 * step[bad], norm0[bad]
            else:
                dead[trial] = True
        return x, done, par

    def solve_one(self, phi_p: float, x0, *, max_nfev: int = 12, guess=None) -> np.ndarray:
        """Solve seed Eq. 2.14 at one roll position with scipy's Levenberg–Marquardt.

        Parameters
        ----------
        phi_p : float — [rad]
            Pinion rotation.
        x0 : array_like (5,) — [mm, mm, mm, mm, rad]
            Start (Z_p, P_p, Z_g, P_g, φ_g).
        max_nfev : int
            Largest number of residual evaluations (12: the TCA's last resort after
            :meth:`newton_params`; the synthesis allows more).
        guess : ndarray (1, 8), optional
            Envelope parameters (pinion then gear) of a point near the start: the surface
            solver's first start instead of its seed search.

        Returns
        -------
        ndarray (5,)
            The solution found (not checked: use :meth:`residual` or :meth:`measure`).

        Notes
        -----
        ``scipy.optimize.least_squares`` (MINPACK ``lm``) on the six residuals with the
        analytic Jacobian, φ_g scaled by the gear mean pitch radius, tolerances 1e-14; a
        place where a flank is not generated has the residual 1e3 mm. Each evaluation starts
        the envelope solver from the last generated one.
        """
        phi = np.array([phi_p])
        last = [guess]  # surface parameters of the last generated evaluation: the next guess

        def fun(xf):
            f, jac, ok, _, par = self._residual(phi, xf[None], last[0])
            if not ok[0]:
                return np.full(6, _PENALTY), np.zeros((6, 5))
            last[0] = par
            return f[0], jac[0]

        cache: dict[bytes, tuple] = {}

        def get(xf):
            key = xf.tobytes()
            if key not in cache:
                cache.clear()
                cache[key] = fun(xf)
            return cache[key]

        sol = least_squares(lambda xf: get(xf)[0], np.asarray(x0, float),
                            jac=lambda xf: get(xf)[1], method="lm",
                            x_scale=np.array([1.0, 1.0, 1.0, 1.0,
                                              1.0 / self.mean_pitch_radius]),
                            xtol=1e-14, ftol=1e-14, gtol=1e-14, max_nfev=max_nfev)
        return sol.x

    def measure(self, phi_p, x, guess=None):
        """Residual of Eq. 2.14, the contact check and the placed points of solutions.

        Parameters
        ----------
        phi_p : ndarray (K,) — [rad]
            Pinion rotations.
        x : ndarray (K, 5) — [mm, mm, mm, mm, rad]
            Solutions (Z_p, P_p, Z_g, P_g, φ_g).
        guess : ndarray (K, 8), optional
            Envelope parameters from :meth:`newton_params` (start of the surface solver).

        Returns
        -------
        residual : ndarray (K,)
            max(|r_p − r_g| [mm], |n_p + n_g| [1]); inf where a flank is not generated.
        converged : ndarray (K,) bool
            residual < :data:`CONVERGED_RESIDUAL`, opposite normals and a contact (below).
        pinion_point, gear_point, normal : ndarray (K, 3)
            r_p, r_g [mm] and the pinion unit normal n_p in the pair frame.

        Notes
        -----
        A solution counts only if the relative curvature W_p + W_g is positive
        semi-definite in the tangent plane (to ``_PSD`` = 1e-6 1/mm): a local minimum of the
        separation, i.e. a contact point, not a saddle where the surfaces already cross.
        """
        _, _, ok, (pp, pg, np_, ng, rel), _ = self._residual(phi_p, x, guess)
        res = np.maximum(np.linalg.norm(pp - pg, axis=-1), np.linalg.norm(np_ + ng, axis=-1))
        res = np.where(ok, res, np.inf)
        nz = np.where(ok[:, None], np_, 0.0)
        proj = np.eye(3) - nz[:, :, None] * nz[:, None, :]
        rel_t = proj @ np.where(ok[:, None, None], rel, 0.0) @ proj
        # eigenvalues of the tangent-plane part: the 3 × 3 projection has one extra 0
        lam = np.linalg.eigvalsh(rel_t + 1e3 * nz[:, :, None] * nz[:, None, :])
        contact = lam[:, 0] > -_PSD
        conv = ok & (res < CONVERGED_RESIDUAL) & ((np_ * ng).sum(-1) < 0) & contact
        return res, conv, pp, pg, np_


# --------------------------------------------------------------------------- reference
def _cyl(points: np.ndarray, vectors: np.ndarray):
    """Cylindrical (z, ρ, ψ) of points and (v_z, v_ρ, v_ψ) of vectors about the z axis."""
    rho = np.hypot(points[..., 0], points[..., 1])
    psi = np.arctan2(points[..., 1], points[..., 0])
    c, s = np.cos(psi), np.sin(psi)
    v = np.stack([vectors[..., 2], c * vectors[..., 0] + s * vectors[..., 1],
                  -s * vectors[..., 0] + c * vectors[..., 1]], -1)
    return points[..., 2], rho, psi, v


def _check_flank(case: Case, flank: str | None) -> str:
    if not isinstance(case, Case):
        raise InputError(f"case: must be a geometry.case.Case, got {type(case).__name__}")
    flank = case.pair.drive_flank if flank is None else flank
    if flank not in FLANKS:
        raise InputError(f"flank: must be one of {list(FLANKS)} (the pinion flank), got "
                         f"{flank!r}")
    return flank


def mean_contact(case: Case, flank: str | None = None) -> MeanContact:
    """Reference position of a pair: the pinion touching the gear flank's mean point M.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str, optional
        Pinion flank, ``"concave"`` or ``"convex"``; default the pair's drive flank.

    Returns
    -------
    MeanContact
        Computed in the nominal assembly (no misalignment).

    Raises
    ------
    InputError
        For a bad flank name, or if no pinion position touches the gear mean point.

    Notes
    -----
    The gear point is held at M (:func:`geometry.pair.design_point.design_point_of_case`) and
    (Z_p, P_p, φ_p, φ_g) are fitted to
    seed Eq. 2.14 by ``scipy.optimize.least_squares``. The start comes from a scan of the
    gear rotation over the mesh zone (+x side of the pair frame): for each gear rotation the
    gear point's place in the pinion projection plane is independent of φ_p, so the pinion
    flank (solved once on a 15 × 9 grid and interpolated) gives the normal mismatch in
    cylindrical components, which is independent of φ_p too; the best one, with φ_p turning
    the pinion flank onto the point, starts the fit. The gear rotation of the reference is
    then the TCA gear rotation at that pinion rotation.
    """
    flank = _check_flank(case, flank)
    pair = ToothPair.from_case(case, flank, Misalignment())
    zg, pg_ = design_point_of_case(case, flank)
    gpt = pair.gear.points(np.array([zg]), np.array([pg_]))
    rg, ng, okg = gpt.r, gpt.n, gpt.ok
    if not okg[0]:
        raise InputError(f"case {case.name}: the gear {_OTHER[flank]} flank is not generated "
                         "at its mean point")
    # pinion flank on a coarse grid, interpolated in its projection plane
    fs = flank_surface(case, "pinion", flank, nu=15, nv=9, v_limits=(0.0, 1.0))
    good = fs.valid
    zc, rc, psic, nc = _cyl(fs.position[good], fs.normal[good])
    interp = LinearNDInterpolator(np.stack([zc, rc], -1),
                                  np.column_stack([np.unwrap(psic), nc]))
    # scan the gear rotation over the mesh zone
    phi_g = np.linspace(-math.pi, math.pi, 721)
    tp0, tg = pair.transforms(0.0, phi_g)
    pts = np.einsum("kij,j->ki", tg[..., :3, :3], rg[0]) + tg[..., :3, 3]
    nrm = np.einsum("kij,j->ki", tg[..., :3, :3], ng[0])
    inv = tp0[:3, :3].T
    loc = (pts - tp0[:3, 3]) @ inv.T
    nloc = nrm @ inv.T
    z1, r1, psi1, v1 = _cyl(loc, nloc)
    val = interp(np.stack([z1, r1], -1))
    mism = np.linalg.norm(val[:, 1:] + v1, axis=-1)
    mism = np.where(pts[:, 0] > 0, mism, np.nan)
    if not np.any(np.isfinite(mism)):
        raise InputError(f"case {case.name}: the gear mean point never enters the pinion "
                         f"{flank} flank region; check the pair placement")
    best = int(np.nanargmin(mism))
    pitch = 2 * math.pi / case.pinion.blank.teeth
    phi_p0 = math.remainder(psi1[best] - val[best, 0], pitch)

    def fun(y):
        x = np.array([[y[0], y[1], zg, pg_, y[3]]])
        f, jac, ok, (pp, _, np_, _, _) = pair.residual(np.array([y[2]]), x)
        if not ok[0]:
            return np.full(6, _PENALTY), np.zeros((6, 4))
        tp, _ = pair.transforms(y[2], 0.0)
        axis_p, orig_p = tp[:3, 2], tp[:3, 3]
        jp = np.concatenate([np.cross(axis_p, pp[0] - orig_p),
                             pair.mean_cone_distance * np.cross(axis_p, np_[0])])
        return f[0], np.column_stack([jac[0][:, 0], jac[0][:, 1], jp, jac[0][:, 4]])

    memo: dict[bytes, tuple] = {}

    def get(y):
        key = y.tobytes()
        if key not in memo:
            memo.clear()
            memo[key] = fun(y)
        return memo[key]

    y0 = np.array([z1[best], r1[best], phi_p0, phi_g[best]])
    sol = least_squares(lambda y: get(y)[0], y0, jac=lambda y: get(y)[1], method="lm",
                        x_scale=np.array([1.0, 1.0, 1.0 / pair.mean_pitch_radius,
                                          1.0 / pair.mean_pitch_radius]),
                        xtol=1e-13, ftol=1e-13, gtol=1e-13, max_nfev=200)
    y = sol.x
    x = np.array([[y[0], y[1], zg, pg_, y[3]]])
    _, _, ok, (pp, _, np_, ngp, _) = pair.residual(np.array([y[2]]), x)
    if not ok[0]:
        raise InputError(f"case {case.name}: no pinion position touches the gear mean point "
                         f"on the pinion {flank} flank")
    mismatch = float(np.linalg.norm(np_[0] + ngp[0]))
    # the TCA at that pinion rotation fixes the reference gear rotation
    xs, _ = pair.newton(np.array([y[2]]), x, max_iter=80)
    res, conv, pp, pg, np_ = pair.measure(np.array([y[2]]), xs)
    if not conv[0]:
        xs = pair.solve_one(float(y[2]), xs[0] if np.all(np.isfinite(xs)) else x[0])[None]
        res, conv, pp, pg, np_ = pair.measure(np.array([y[2]]), xs)
    if not conv[0]:
        raise InputError(f"case {case.name}: the TCA at the mean contact did not converge "
                         f"(residual {res[0]:.3g})")
    tp, tg = pair.transforms(y[2], xs[0, 4])
    s_p = int(np.sign(np.cross(tp[:3, 2], pp[0] - tp[:3, 3]) @ np_[0]))
    s_g = int(np.sign(np.cross(tg[:3, 2], pg[0] - tg[:3, 3]) @ np_[0]))
    return MeanContact(flank=flank, pinion_rotation=float(y[2]),
                       gear_rotation=float(xs[0, 4]), pinion_sense=s_p, gear_sense=s_g,
                       pinion_projection=xs[0, :2].copy(), gear_projection=xs[0, 2:4].copy(),
                       mismatch=mismatch)


# --------------------------------------------------------------------------- TCA
def _extrapolate(known: dict[float, np.ndarray], r: float) -> np.ndarray:
    """Linear extrapolation of the path from the two nearest solved roll positions.

    Linear rather than quadratic: on a conjugate (line-contact) pair the solved points may
    slide along the contact lines, and a higher-order extrapolation amplifies that.
    """
    kr = np.fromiter(known, float)
    order = np.argsort(np.abs(kr - r))[:2]
    rr = kr[order]
    xx = np.stack([known[float(v)] for v in rr])
    if len(rr) == 1:
        return xx[0].copy()
    t = (r - rr[0]) / (rr[1] - rr[0])
    return xx[0] + t * (xx[1] - xx[0])


def _substeps(pair: ToothPair, ref: MeanContact, known: dict[float, np.ndarray], r: float,
              step: float) -> tuple[np.ndarray, bool]:
    """Solve roll r by continuation from the nearest solved roll in steps ≤ ``step``.

    Intermediate solutions are added to ``known``; the last resort at r is scipy's
    Levenberg–Marquardt (:meth:`ToothPair.solve_one`).
    """
    kr = np.fromiter(known, float)
    r0 = float(kr[np.argmin(np.abs(kr - r))])
    n = max(1, math.ceil(abs(r - r0) / step))
    x = known[r0]
    for m in range(1, n + 1):
        rm = r0 + (r - r0) * m / n
        phi = np.array([ref.pinion_rotation + ref.pinion_sense * rm])
        xs, _, par = pair.newton_params(phi, _extrapolate(known, rm)[None])
        _, conv, _, _, _ = pair.measure(phi, xs, par)
        if not conv[0]:
            x1 = pair.solve_one(float(phi[0]), _extrapolate(known, rm))
            _, conv, _, _, _ = pair.measure(phi, x1[None])
            if not conv[0]:
                return x, False
            xs = x1[None]
        x = xs[0]
        known[rm] = x.copy()
    return x, True


def conventional_tca(case: Case, pinion_roll, *, flank: str | None = None,
                     misalignment: Misalignment | None = None,
                     initial: TCAResult | MeanContact | None = None) -> TCAResult:
    """Conventional TCA (seed Eq. 2.14): contact point, gear rotation and TE per pinion roll.

    Parameters
    ----------
    case : geometry.case.Case
    pinion_roll : float or array_like (K,) — [rad]
        Pinion roll in its sense of motion from the reference (mean contact, see the module
        docstring); e.g. ``np.linspace(-1, 1, 21) * 2 * np.pi / z_p`` spans ±1 pitch.
    flank : str, optional
        Pinion flank ``"concave"`` or ``"convex"``; default the pair's drive flank. The gear
        flank is the other one.
    misalignment : geometry.pair.assembly.Misalignment, optional
        Assembly analysed; default the case's own ``misalignment``. The reference (roll 0)
        is always taken from the nominal assembly.
    initial : TCAResult or MeanContact, optional
        A reference computed before for the same case and flank (:func:`mean_contact`, or
        the ``reference`` of an earlier result, whose contact path, interpolated at
        ``pinion_roll``, also starts the solution). Saves the reference search.

    Returns
    -------
    TCAResult
        Arrays in the order of ``pinion_roll``.

    Raises
    ------
    InputError
        For a non-finite roll, a bad flank name, an ``initial`` of another flank, or a pair
        without a mean contact (see :func:`mean_contact`).

    Notes
    -----
    Seed Eq. 2.14a–b (five equations; unknowns Z_p, P_p, Z_g, P_g, φ_g at given φ_p),
    solved in blocks of up to 8 roll positions outward from roll 0 by continuation (each
    block starts from a linear extrapolation of the already solved path) with the batched
    damped Gauss–Newton iteration of the module docstring; positions that fail are retried
    by continuation in steps of 1/40 pitch with ``scipy.optimize.least_squares`` as the
    last resort. Those that still fail (e.g. where the contact would leave the generated
    surface) are returned with ``converged = False`` and NaN in every solved quantity.
    """
    flank = _check_flank(case, flank)
    roll = np.atleast_1d(np.asarray(pinion_roll, dtype=float))
    if roll.ndim != 1 or not np.all(np.isfinite(roll)):
        raise InputError("pinion_roll: must be a finite scalar or 1-D array [rad]")
    prev: TCAResult | None = None
    if initial is None:
        ref = mean_contact(case, flank)
    elif isinstance(initial, TCAResult):
        prev = initial
        if initial.flank != flank:
            raise InputError(f"initial: a result for the {initial.flank} flank, not {flank}")
        if not initial.converged.any():
            raise InputError("initial: the earlier result has no converged roll position")
        k0 = int(np.argmin(np.where(initial.converged, np.abs(initial.pinion_roll), np.inf)))
        ref = MeanContact(flank, float(initial.reference[0]), float(initial.reference[1]),
                          int(initial.sense[0]), int(initial.sense[1]),
                          initial.pinion_projection[k0], initial.gear_projection[k0], 0.0)
    elif isinstance(initial, MeanContact):
        if initial.flank != flank:
            raise InputError(f"initial: a reference for the {initial.flank} flank, not {flank}")
        ref = initial
    else:
        raise InputError(f"initial: must be a TCAResult or MeanContact, got "
                         f"{type(initial).__name__}")
    pair = ToothPair.from_case(case, flank, misalignment)
    mis = case.misalignment if misalignment is None else misalignment
    ratio = case.pinion.blank.teeth / case.gear.blank.teeth
    phi_p = ref.pinion_rotation + ref.pinion_sense * roll

    # solved path: roll → (Z_p, P_p, Z_g, P_g, φ_g)
    known = {0.0: np.array([*ref.pinion_projection, *ref.gear_projection, ref.gear_rotation])}
    if prev is not None and prev.converged.any():
        ok = prev.converged
        known = {float(r): np.array([*a, *b, c]) for r, a, b, c in zip(
            prev.pinion_roll[ok], prev.pinion_projection[ok], prev.gear_projection[ok],
            prev.gear_rotation[ok], strict=True)}
    k = len(roll)
    step = _SUBSTEP * 2.0 * math.pi / case.pinion.blank.teeth
    x = np.full((k, 5), np.nan)
    # two sweeps outward from the roll nearest 0, in blocks
    order = np.argsort(roll)
    start = int(np.searchsorted(roll[order], 0.0))
    sweeps = [order[start:], order[:start][::-1]]
    for sweep in sweeps:
        frontier = False  # a fallback failed in this sweep: farther rolls get no fallback
        for b in range(0, len(sweep), _BLOCK):
            idx = sweep[b:b + _BLOCK]
            x0 = np.stack([_extrapolate(known, roll[i]) for i in idx])
            xs, _, par = pair.newton_params(phi_p[idx], x0)
            _, conv, _, _, _ = pair.measure(phi_p[idx], xs, par)
            for j, i in enumerate(idx):
                if not conv[j] and not frontier:
                    # fallback: continuation in small steps from the nearest solved position
                    x1, c1 = _substeps(pair, ref, known, float(roll[i]), step)
                    if c1:
                        xs[j], conv[j] = x1, True
                    else:
                        frontier = True
                x[i] = xs[j]
                if conv[j]:
                    known[float(roll[i])] = xs[j].copy()
    res, conv, pp, pg, np_ = pair.measure(phi_p, x)
    n_bad = int((~conv).sum())
    if n_bad:
        log.info("conventional_tca: %d of %d roll positions did not converge", n_bad, k)
    # positions that did not converge carry NaN (their residual says how far they got)
    x = np.where(conv[:, None], x, np.nan)
    pp, pg, np_ = (np.where(conv[:, None], a, np.nan) for a in (pp, pg, np_))
    te = ratio * roll - ref.gear_sense * (x[:, 4] - ref.gear_rotation)
    with np.errstate(invalid="ignore"):
        on_flank = (_inside(case.pinion.blank, x[:, 0], x[:, 1])
                    & _inside(case.gear.blank, x[:, 2], x[:, 3]) & conv)
    return TCAResult(
        flank=flank, pinion_roll=roll, pinion_rotation=phi_p, gear_rotation=x[:, 4].copy(),
        transmission_error=te, pinion_point=pp, gear_point=pg,
        pinion_projection=x[:, :2].copy(), gear_projection=x[:, 2:4].copy(), normal=np_,
        residual=res, converged=conv, on_flank=on_flank,
        reference=np.array([ref.pinion_rotation, ref.gear_rotation]),
        sense=np.array([ref.pinion_sense, ref.gear_sense]), misalignment=mis)
