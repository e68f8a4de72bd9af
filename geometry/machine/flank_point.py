"""Generated flank points with their tangents and curvature at projection-plane places.

One evaluator of a generated (or Formate) flank for the solvers that need first and second
order surface data at prescribed places (axial position Z, radius P) of the member's
projection plane: the conventional TCA (:mod:`geometry.pair.conventional_tca`, seed Eq. 2.14) and
the synthesis (:mod:`geometry.synthesis.case_synthesis`, :mod:`geometry.pair.design_point`). Each
point is solved
by :func:`geometry.machine.meshing.solve_envelope` (seed Eq. 2.7–2.8); the shape operator comes from
the principal curvatures of :func:`geometry.machine.curvature.surface_curvatures` (seed Eq.
2.9–2.13), W = κ₁e₁e₁ᵀ + κ₂e₂e₂ᵀ with dn = W dr; the tangents ∂r/∂Z, ∂r/∂P follow from the
surface tangents along the blade (s) and about the cutter axis (θ), with the roll q
eliminated through the equation of meshing for a generated flank, by inverting the 2 × 2 map
(∂/∂s, ∂/∂θ) → (∂Z, ∂P). A left-hand member is the mirror image y → −y of the right-hand
one generated from its (right-hand reference) settings.

Public functions
----------------
FlankPoint     points, normals, shape operators, tangents and envelope parameters (batched)
MemberFlank    the tool, blank and hand of one member's flank (what :func:`flank_points` needs)
flank_points   evaluate a flank at projection-plane places
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from geometry.core.errors import InputError
from geometry.machine.cradle import MachineSettings
from geometry.machine.curvature import surface_curvatures
from geometry.machine.cutter import Blade
from geometry.machine.family import meshing_function
from geometry.machine.meshing import solve_envelope

if TYPE_CHECKING:
    from geometry.case import Blank, Case

__all__ = ["FlankPoint", "MemberFlank", "flank_points"]

_MIRROR = np.array([1.0, -1.0, 1.0])


class FlankPoint(NamedTuple):
    """Flank points in their member frame (mirrored for a left-hand member), batched.

    Arrays have the shape of the targets (…) plus the trailing shapes below; where ``ok``
    is False every field holds NaN.
    """

    r: np.ndarray  # (..., 3) [mm] point
    n: np.ndarray  # (..., 3) [1] unit normal, out of the material
    shape: np.ndarray  # (..., 3, 3) [1/mm] shape operator W (dn = W dr), convex positive
    r_s: np.ndarray  # (..., 3) [1] unit tangent along the blade (root → tip)
    tangents: np.ndarray  # (..., 3, 2) [mm/mm] ∂r/∂Z, ∂r/∂P in the projection plane
    ok: np.ndarray  # (...,) bool: generated (geometry.machine.meshing reason 0), finite derivatives
    params: np.ndarray  # (..., 4) envelope parameters s [mm], θ [rad], q [rad], section


class MemberFlank(NamedTuple):
    """The tool, blank and hand of one member's flank: what :func:`flank_points` evaluates."""

    blade: Blade
    machine: MachineSettings  # right-hand reference settings
    blank: Blank
    hand: str  # "right" or "left"

    @classmethod
    def of_case(cls, case: Case, member: str, flank: str) -> MemberFlank:
        """Flank ``flank`` (``"concave"``/``"convex"``) of ``member`` (``"pinion"``/``"gear"``)
        of a :class:`geometry.case.Case`; InputError for a bad name."""
        mem = case.member(member)
        tool = mem.flank(flank)
        return cls(tool.blade, tool.machine, mem.blank, mem.hand)

    def points(self, axial, radius, *, guess=None) -> FlankPoint:
        """:func:`flank_points` of this flank."""
        return flank_points(*self, axial, radius, guess=guess)


def _solve(blade: Blade, machine: MachineSettings, blank: Blank, z: np.ndarray,
           p: np.ndarray, guess):
    """The envelope at 1-D targets, seeded at the middle target or, failing that, the next
    one; None if neither seeds."""
    kw = dict(length_scale=blank.outer_cone_distance,
              depth=blank.outer_addendum + blank.outer_dedendum, guess=guess)
    mid = len(z) // 2
    order = sorted(range(len(z)), key=lambda i: abs(i - mid))[:2]
    for k in order:
        try:
            return solve_envelope(blade, machine, z, p, seed_index=(k,), **kw)
        except InputError:
            continue
    return None


def flank_points(blade: Blade, machine: MachineSettings, blank: Blank, hand: str, axial,
                 radius, *, guess=None) -> FlankPoint:
    """Points, normals, shape operators and tangents of a flank at projection-plane places.

    Parameters
    ----------
    blade : geometry.machine.cutter.Blade
        The blade that cuts the flank.
    machine : geometry.machine.cradle.MachineSettings
        Its right-hand reference settings (Generate or Formate).
    blank : geometry.case.Blank
        The member blank (its outer cone distance scales the meshing residual, its whole
        depth bounds the search along the blade).
    hand : str
        ``"right"`` or ``"left"``; a left-hand flank is mirrored y → −y.
    axial, radius : array_like, same shape (…) — [mm]
        Axial position Z and radius P in the member's projection plane.
    guess : array_like (…, 4), optional
        Envelope parameters (s [mm], θ [rad], q [rad], section) of nearby earlier points
        (the ``params`` of an earlier result) to start the envelope solver from; rows with a
        non-finite value have no guess and are solved as without one.

    Returns
    -------
    FlankPoint
        In the member frame, arrays of the targets' shape plus trailing dimensions. Targets
        that are not finite, not off the axis (P ≤ 0), not generated (reason ≠ 0 of
        :func:`geometry.machine.meshing.solve_envelope`) or whose derivatives are not finite have
        ``ok`` False and NaN in every other field; if no target seeds the envelope solver,
        all are.

    Raises
    ------
    InputError
        If ``axial`` and ``radius`` differ in shape, for an unknown hand, or if the guess
        does not broadcast to the targets or has a section index out of range.

    Notes
    -----
    Seed Eq. 2.7–2.8 (envelope) and 2.9–2.13 (curvatures). The envelope is seeded at the
    middle target and, if no solution exists there, at its neighbour. With r_s, r_θ the
    surface tangents along the blade and about the cutter axis (for a generated flank
    r_s + r_q q_s, r_θ + r_q q_θ with q_s, q_θ from the gradient of the equation of meshing,
    :func:`geometry.machine.family.meshing_function`), the tangents are [∂r/∂Z, ∂r/∂P] =
    [r_s, r_θ] A⁻¹, A the rows (e_z·, e_ρ·) of [r_s, r_θ].
    """
    z = np.asarray(axial, dtype=float)
    p = np.asarray(radius, dtype=float)
    if z.shape != p.shape:
        raise InputError(f"axial, radius: shapes differ, {z.shape} vs {p.shape}")
    if hand not in ("right", "left"):
        raise InputError(f"hand: must be 'right' or 'left', got {hand!r}")
    shape_ = z.shape
    z, p = z.ravel(), p.ravel()
    k = len(z)
    r = np.full((k, 3), np.nan)
    n = np.full((k, 3), np.nan)
    rsu = np.full((k, 3), np.nan)
    d = np.full((k, 3, 2), np.nan)
    w = np.full((k, 3, 3), np.nan)
    par = np.full((k, 4), np.nan)
    ok = np.isfinite(z) & np.isfinite(p) & (p > 0)

    def out(ok_):
        return FlankPoint(r.reshape(*shape_, 3), n.reshape(*shape_, 3),
                          w.reshape(*shape_, 3, 3), rsu.reshape(*shape_, 3),
                          d.reshape(*shape_, 3, 2), ok_.reshape(shape_),
                          par.reshape(*shape_, 4))

    if not ok.any():
        return out(ok)
    idx = np.flatnonzero(ok)
    g = None
    if guess is not None:
        gi = np.broadcast_to(np.asarray(guess, dtype=float), (*shape_, 4)).reshape(k, 4)[idx]
        have = np.all(np.isfinite(gi), axis=-1)
        if have.any():
            gi = np.where(have[:, None], gi, np.nan)
            g = (gi[:, 0], gi[:, 1], gi[:, 2], np.where(have, gi[:, 3], 0.0))
    sol = _solve(blade, machine, blank, z[idx], p[idx], g)
    if sol is None:
        return out(np.zeros(k, bool))
    generate = machine.process == "Generate"
    length = blank.outer_cone_distance
    valid = sol.reason == 0
    fam = sol.family
    pc = surface_curvatures(fam, generate, length)
    if generate:
        _, grad = meshing_function(fam, length)
        with np.errstate(divide="ignore", invalid="ignore"):
            qs = (-grad[:, 0] / grad[:, 2])[:, None]
            qt = (-grad[:, 1] / grad[:, 2])[:, None]
        rs = fam.r_s + fam.r_q * qs
        rt = fam.r_theta + fam.r_q * qt
    else:
        rs, rt = fam.r_s, fam.r_theta
    pos = sol.position
    rho = np.hypot(pos[:, 0], pos[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        e_rho = np.stack([pos[:, 0] / rho, pos[:, 1] / rho, np.zeros_like(rho)], -1)
        a = np.empty((len(idx), 2, 2))
        a[:, 0, 0], a[:, 0, 1] = rs[:, 2], rt[:, 2]
        a[:, 1, 0] = (rs * e_rho).sum(-1)
        a[:, 1, 1] = (rt * e_rho).sum(-1)
        det = a[:, 0, 0] * a[:, 1, 1] - a[:, 0, 1] * a[:, 1, 0]
        inv = np.stack([np.stack([a[:, 1, 1], -a[:, 0, 1]], -1),
                        np.stack([-a[:, 1, 0], a[:, 0, 0]], -1)], -2) / det[:, None, None]
        blade_dir = fam.r_s / np.linalg.norm(fam.r_s, axis=-1, keepdims=True)
    tang = np.stack([rs, rt], -1) @ inv  # (n, 3, 2): ∂r/∂Z, ∂r/∂P
    shape = (pc.kappa1[:, None, None] * pc.dir1[:, :, None] * pc.dir1[:, None, :]
             + pc.kappa2[:, None, None] * pc.dir2[:, :, None] * pc.dir2[:, None, :])
    nrm = sol.normal
    if hand == "left":
        pos, nrm, blade_dir = pos * _MIRROR, nrm * _MIRROR, blade_dir * _MIRROR
        tang = tang * _MIRROR[:, None]
        shape = shape * _MIRROR[:, None] * _MIRROR[None, :]
    good = valid & np.all(np.isfinite(tang), axis=(1, 2)) & np.all(
        np.isfinite(shape), axis=(1, 2))
    r[idx], n[idx], d[idx], w[idx], rsu[idx] = pos, nrm, tang, shape, blade_dir
    par[idx] = np.stack([sol.s, sol.theta, sol.q, sol.section], -1)
    ok[idx] = good
    bad = ~ok
    r[bad], n[bad], d[bad], w[bad], rsu[bad], par[bad] = (np.nan,) * 6
    return out(ok)
