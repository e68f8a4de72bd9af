"""The ease-off's map: each gear node to the pinion point that meets it (seed §2.3.2, Eq. 2.19).

For a gear grid node (axial position z, radius ρ in the gear's projection plane) the
conjugate point is the pinion flank point that the pinion's rotation about its axis
brings onto the node's circle about the gear axis with collinear normals (the action
surface, seed Eq. 2.19; Stadtfeld's ease-off construction): its roll angle is the node's
value of the surface of roll angle, its angular position on that circle gives the
ease-off. The pinion point of each node is found in its projection-plane fractions (u, v)
by a Newton iteration on the exact map (each step solves the equation of meshing at the
trial points, :func:`geometry.machine.meshing.solve_envelope`), started from a spline of
the forward map on a pinion grid, with Broyden updates of the per-node Jacobians, and
accepted when the image lies within 1e-7 mm of the node.

Public names
------------
fill_missing       fill the NaN nodes of a grid from the computed ones (linear continuation)
map_gear_nodes     every gear node's conjugate pinion point (used by :func:`ease_off`)
flank_nodes        a real flank on a projection-plane grid (memoised per process)
gear_nodes         the real gear flank on the ease-off's grid (``flank_nodes`` of the gear)
memo_info, clear_memos
                   the per-process memos of the forward map's pinion points and the flanks
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from scipy.interpolate import RectBivariateSpline
from scipy.spatial import cKDTree

from contact.utca.action_surface import (
    MeshKinematics,
    action_roll_angle,
    conjugate_points,
)
from contact.utca.spline_group import SplineGroup
from geometry.case import TeethKey
from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.kernels import kernels_module
from geometry.machine.curvature import surface_curvatures
from geometry.machine.cutter import working_sections
from geometry.machine.flank import FlankSurface, blank_outline, flank_surface
from geometry.machine.meshing import (
    ENVELOPE_STEP_LIMIT,
    envelope_family,
    meshing_q_sign,
    solve_envelope,
    warm_seeds_active,
)

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "clear_memos",
    "fill_missing",
    "flank_nodes",
    "gear_nodes",
    "memo_info",
]

log = logging.getLogger(__name__)


_MAP_TOL = 1e-7  # [mm] node-placement tolerance of the conjugate points


_MAP_ITER = 10  # exact placement iterations


_BROYDEN_ITER = 4  # of which with Broyden updates (then finite differences)


_SPLINE_ITER = 10  # Newton steps on the spline of the forward map (start values)


_STEP_LIMIT = 0.1  # largest Newton step in each pinion fraction


_LATE_STEP_LIMIT = 0.02  # … in the finite-difference iterations


_FD_STEP = 1e-6  # finite-difference step of the exact map's Jacobian [1]


_PINION_U = (-0.15, 1.15)  # extended pinion grid (fractions of face width / depth)


_PINION_V = (-0.05, 1.2)


_FORWARD_GRID = (41, 21)  # pinion grid of the forward-map spline (start values only)


_MIRROR = np.array([1.0, -1.0, 1.0])


#: cases (flanks) whose forward-map pinion points a process keeps (as the tooth models'
#: memo, :mod:`contact.compliance.mesh`)
_MEMO_SIZE = 4


def _bilinear(corners: np.ndarray, u, v):
    u = np.asarray(u, dtype=float)[..., None]
    v = np.asarray(v, dtype=float)[..., None]
    p = ((1 - u) * (1 - v) * corners[0, 0] + u * (1 - v) * corners[1, 0]
         + (1 - u) * v * corners[0, 1] + u * v * corners[1, 1])
    return p[..., 0], p[..., 1]


class Mates(NamedTuple):
    """Pinion points at projection-plane places and their images through the action surface."""

    z: np.ndarray  # [mm] pinion projection-plane place
    rho: np.ndarray
    position: np.ndarray  # pinion frame
    normal: np.ndarray
    roll: np.ndarray  # [rad] action roll angle φ_a
    good: np.ndarray  # generated and on the surface of action
    conjugate: np.ndarray  # conjugate-gear point (gear frame, ψ₀ = 0)
    image: np.ndarray  # (..., 2) its (z, ρ) on the gear projection plane
    # [1/mm] pinion principal curvatures and direction (pinion frame); None in the
    # placement's trial mates (:func:`_with_curvatures` adds them to the placed ones)
    kappa1: np.ndarray | None
    kappa2: np.ndarray | None
    dir1: np.ndarray | None
    section: np.ndarray  # blade section that generates the pinion point
    params: np.ndarray  # (..., 3) its envelope parameters (s, θ, q) [mm, rad, rad]


def _pinion_points(case: Case, flank: str, z, rho, guess=None, curvatures: bool = True,
                   undercut_sign: float | None = None, seed_index: tuple | None = None):
    """Real pinion surface at projection-plane places: position, normal, reason, curvatures.

    ``guess`` (params (..., 3), section) from nearby earlier points starts the envelope solver
    (:func:`geometry.machine.meshing.solve_envelope`) there instead of at its seed search.
    ``curvatures=False``: κ₁, κ₂ and e₁ are None (the placement's trial places: only the
    placed mates' are read, :func:`_with_curvatures`). ``undercut_sign``: the flank's
    regular sign of ∂f/∂q (:attr:`_ForwardMap.q_sign`) for the solver's undercut test;
    None: the solve's seed target's. ``seed_index``: the solver's seed target (None: the
    middle one).
    """
    mem = case.pinion
    tool = mem.flank(flank)
    bl = mem.blank
    if guess is not None:
        params, sec0 = guess
        guess = (params[..., 0], params[..., 1], params[..., 2], sec0)
    sol = solve_envelope(tool.blade, tool.machine, z, rho, length_scale=bl.outer_cone_distance,
                         depth=bl.outer_addendum + bl.outer_dedendum, guess=guess,
                         undercut_sign=undercut_sign, seed_index=seed_index)
    mirror = _MIRROR if mem.hand == "left" else np.ones(3)
    k1 = k2 = e1 = None
    if curvatures:
        k1, k2, e1 = _curvatures_of(case, flank, sol.family)
    return (sol.position * mirror, sol.normal * mirror, sol.reason, k1, k2, e1, sol.section,
            np.stack([sol.s, sol.theta, sol.q], -1))


def _curvatures_of(case: Case, flank: str, family):
    """κ₁, κ₂ [1/mm] and e₁ (mirrored into the pinion frame) of the pinion's generated
    surface (:func:`geometry.machine.curvature.surface_curvatures`) of ``family``."""
    mem = case.pinion
    tool = mem.flank(flank)
    with np.errstate(invalid="ignore", divide="ignore"):
        pc = surface_curvatures(family, tool.machine.process == "Generate",
                                mem.blank.outer_cone_distance)
    mirror = _MIRROR if mem.hand == "left" else np.ones(3)
    return pc.kappa1, pc.kappa2, pc.dir1 * mirror


def _with_curvatures(case: Case, flank: str, mates: Mates) -> Mates:
    """``mates`` (flat (n,)) with the pinion curvatures at their places.

    The family is evaluated at the mates' envelope parameters and blade sections
    (:func:`geometry.machine.meshing.envelope_family`: the buffer the envelope solve gave
    at them, bit for bit), so the curvatures are those a solve with curvatures gives its
    valid points; where a mate has no solution (NaN parameters) they are NaN. The
    placement's trial places (~4 a node) need none: only the placed mates' are read
    (issue 75: ~4 ms a study point)."""
    mem = case.pinion
    tool = mem.flank(flank)
    par = mates.params
    fin = np.isfinite(par).all(axis=-1)
    k1, k2 = np.full(fin.shape, np.nan), np.full(fin.shape, np.nan)
    e1 = np.full(par.shape, np.nan)
    if fin.any():
        p = par[fin]
        fam = envelope_family(tool.blade, tool.machine, p[:, 0], p[:, 1], p[:, 2],
                              mates.section[fin], length_scale=mem.blank.outer_cone_distance)
        k1[fin], k2[fin], e1[fin] = _curvatures_of(case, flank, fam)
    return mates._replace(kappa1=k1, kappa2=k2, dir1=e1)


def _take(mates: Mates, sel) -> Mates:
    """The mates ``sel`` (an index or mask of the first axis; fields without curvatures
    stay None)."""
    return Mates(*(None if a is None else np.asarray(a)[sel] for a in mates))


def _mates(case: Case, flank: str, kin: MeshKinematics, corners, u, v, *, branch=None,
           reference=None, guess=None, points=None, curvatures: bool = True,
           undercut_sign: float | None = None, seed_index: tuple | None = None
           ) -> tuple[Mates, int]:
    """Evaluate the real pinion at fractions (u, v) and map it through the action surface.

    ``guess``: (params, section) of nearby pinion points, see :func:`_pinion_points`;
    ``points``: those pinion points already computed (:func:`_pinion_points` at (u, v));
    ``curvatures``, ``undercut_sign``, ``seed_index``: as :func:`_pinion_points`'.
    """
    z, rho = _bilinear(corners, u, v)
    if points is None:
        points = _pinion_points(case, flank, z, rho, guess, curvatures, undercut_sign,
                                seed_index)
    pos, nrm, reason, k1, k2, e1, sec, par = points
    roll, branch = action_roll_angle(kin, pos, nrm, branch=branch, reference=reference)
    good = (reason == 0) & np.isfinite(roll)
    conj, _ = conjugate_points(kin, pos, nrm, np.where(good, roll, 0.0))
    img = np.stack([conj[..., 2], np.hypot(conj[..., 0], conj[..., 1])], -1)
    return Mates(z, rho, pos, nrm, roll, good, conj, img, k1, k2, e1, sec, par), branch


def gear_reference(case: Case, kin: MeshKinematics) -> np.ndarray:
    """The gear's mean pitch point turned into the mesh zone (+x side) in the pair frame."""
    z, rho = blank_outline(case.gear.blank).mean_point
    return kin.gear_place[:3, :3] @ np.array([rho, 0.0, z]) + kin.gear_origin


class GearMates(NamedTuple):
    """The pinion mates of the gear nodes (nu, nv), as :func:`map_gear_nodes` places them."""

    u: np.ndarray  # [1] pinion fractions of the mates (extended grid: beyond 0..1 possible)
    v: np.ndarray
    mates: Mates  # the mates evaluated there and their images
    error: np.ndarray  # [mm] placement error max |Δz|, |Δρ| (inf where no mate)
    pinned: np.ndarray  # bool: the Newton iterate ran to the edge of the extended grid


@dataclass(frozen=True)
class _ForwardMap:
    """The real pinion mapped through the action surface: pinion fractions (u, v) → the
    (z, ρ) of the conjugate point on the gear projection plane, evaluated exactly
    (:meth:`mates`) and as a bicubic spline over the extended pinion grid (start values and
    first Jacobians only)."""

    case: Case
    flank: str  # pinion flank
    kin: MeshKinematics
    corners: np.ndarray  # (2, 2, 2) [mm] pinion blank corners (bilinear map of u, v)
    branch: int  # branch of the action roll angle (the mesh zone)
    u: np.ndarray  # (41,) extended pinion grid
    v: np.ndarray  # (21,)
    nodes: Mates  # the mates on the extended grid
    #: [mm] the image's axial position and radius over (u, v), splines evaluated together
    image: SplineGroup
    #: the sign of ∂f/∂q on the pinion flank's regular envelope, from the forward grid's
    #: solve (its seed the grid's middle); None: not generated, or no valid point
    q_sign: float | None = None

    def mates(self, u, v, guess) -> Mates:
        """Mates at the fractions (u, v), the envelope solver started at ``guess``; without
        curvatures (the placement's trial places, :func:`_with_curvatures`).

        The solver's undercut test takes the forward grid's sign (:attr:`q_sign`), and
        where the batch's middle place, the solver's seed, has no good mate or one whose
        envelope parameters lie farther from its guess than one limited Newton step of the
        solver (:data:`_SEED_JUMP`: another root), the batch is solved again seeded at the
        place nearest the forward grid's middle node (:func:`_seed_place`): the middle of a
        subset of places (the nodes not yet placed) can lie at the blank's edge, where its
        root is on another section or beyond the singular line, and the seed's section
        and sign then decided for the whole batch (issue 71, the FM 20×31 at Σ 70°: 514
        of 560 regular places called undercut, and trial places a Newton step of 9e-6
        away solved on the tip section, 3.3 mm off; docs/synthesis.md). A batch whose
        middle seed is good near its guess is solved once, as before."""
        m, _ = _mates(self.case, self.flank, self.kin, self.corners, u, v, branch=self.branch,
                      guess=guess, curvatures=False, undercut_sign=self.q_sign)
        shape = np.shape(m.good)
        if not shape or self.q_sign is None or guess is None:
            return m
        mid = tuple(d // 2 for d in shape)
        if m.good[mid] and np.all(np.abs(m.params[mid] - np.asarray(guess[0])[mid])
                                  <= _SEED_JUMP):
            return m
        seed = _seed_place(self, u, v)
        if seed is None or seed == mid:
            return m
        m, _ = _mates(self.case, self.flank, self.kin, self.corners, u, v, branch=self.branch,
                      guess=guess, curvatures=False, undercut_sign=self.q_sign,
                      seed_index=seed)
        return m

    def jacobian(self, u, v) -> np.ndarray:
        """(..., 2, 2) [mm] ∂(z, ρ)/∂(u, v) of the spline."""
        return np.stack([self.image(u, v, dx=1), self.image(u, v, dy=1)], -1)

    def newton_step(self, j, u, v, e, limit=_STEP_LIMIT):
        """Places (u, v) moved by the Newton step J⁻¹ e (held to ``limit`` in each fraction;
        none where J is singular), clipped to the extended grid."""
        det = j[..., 0, 0] * j[..., 1, 1] - j[..., 0, 1] * j[..., 1, 0]
        safe = np.abs(det) > 1e-12
        det = np.where(safe, det, 1.0)
        du = np.where(safe, (j[..., 1, 1] * e[..., 0] - j[..., 0, 1] * e[..., 1]) / det, 0.0)
        dv = np.where(safe, (j[..., 0, 0] * e[..., 1] - j[..., 1, 0] * e[..., 0]) / det, 0.0)
        scale = np.maximum(1.0, np.maximum(np.abs(du), np.abs(dv)) / limit)
        return (np.clip(u + du / scale, self.u[0], self.u[-1]),
                np.clip(v + dv / scale, self.v[0], self.v[-1]))


@dataclass
class _Placement:
    """State of the exact placement, flat over the gear nodes (n,); updated in place."""

    mates: Mates  # (n, ...) the mates at the current places
    u: np.ndarray  # (n,) [1] current pinion fractions
    v: np.ndarray
    target: np.ndarray  # (n, 2) [mm] the nodes' (z, ρ)
    jacobian: np.ndarray  # (n, 2, 2) [mm] per-node ∂(z, ρ)/∂(u, v)
    error: np.ndarray  # (n,) [mm] max |Δz|, |Δρ| (inf: no mate)

    def accept(self, idx: np.ndarray, mates: Mates, u: np.ndarray, v: np.ndarray) -> None:
        """Move the nodes ``idx`` to the places (u, v) of their new ``mates``."""
        for full, part in zip(self.mates, mates, strict=True):
            if full is not None:
                full[idx] = part
        self.error[idx] = _placement_error(self.target[idx], mates)
        self.u[idx], self.v[idx] = u, v


def _placement_error(target: np.ndarray, mates: Mates) -> np.ndarray:
    """[mm] max |Δz|, |Δρ| of the mates' images from the targets (inf where no mate)."""
    return np.where(np.asarray(mates.good), np.abs(target - mates.image).max(axis=-1), np.inf)


def _forward_grid(case: Case):
    """The extended pinion grid of the forward map: its fractions (41,), (21,), the blank
    corners (2, 2, 2) [mm] and the grid's places (41, 21) in fractions and [mm]."""
    cp = blank_outline(case.pinion.blank).corners
    up = np.linspace(*_PINION_U, _FORWARD_GRID[0])
    vp = np.linspace(*_PINION_V, _FORWARD_GRID[1])
    uu, vv = np.meshgrid(up, vp, indexing="ij")
    z, rho = _bilinear(cp, uu, vv)
    return up, vp, cp, uu, vv, z, rho


def flank_key(case: Case, member: str, flank: str) -> TeethKey:
    """The key of the per-process memos of one flank alone (:func:`flank_nodes`, the
    forward map's pinion points): what :func:`geometry.machine.flank.flank_surface` and
    :func:`_pinion_points` read of the case — the member's name, hand and blank and the
    flank's tool (blade, machine settings) — and nothing of the other member, the other
    flank or the pair. So a development's trial that changes the pinion alone keeps the
    gear's nodes, and a gear changed alone keeps the pinion's forward-map points (issue
    75: the gear flank of every pinion trial was solved again, 278 of the 286 solves of
    the spiral bevel 17x23's synthesis repeats). Exact (``repr``), never a tolerance.

    Parameters
    ----------
    case : geometry.case.Case
    member : str — ``"pinion"`` or ``"gear"``
    flank : str — ``"concave"`` or ``"convex"``

    Returns
    -------
    geometry.case.TeethKey
        Equal and hashed by the ``repr`` above (every float to the last bit, -0.0 apart
        from 0.0, as :meth:`~geometry.case.Case.teeth_key`), carrying ``case`` for the
        memo to compute from.

    Raises
    ------
    InputError
        For a bad member or flank name.
    """
    mem = case.member(member)
    tool = mem.flank(flank)
    return TeethKey(case, repr((member, flank, mem.hand, mem.blank, tool)))


@memoised(maxsize=_MEMO_SIZE)
def _memo_forward_points(key: TeethKey, flank: str) -> tuple[np.ndarray, ...]:
    """The real pinion on the forward map's grid (:func:`_pinion_points`) of the pinion
    flank of ``key`` (:func:`flank_key`; read-only arrays)."""
    case = key.case
    *_, z, rho = _forward_grid(case)
    out = _pinion_points(case, flank, z, rho)
    for a in out:
        a.flags.writeable = False
    return out


@memoised(maxsize=4 * _MEMO_SIZE)  # four flanks per case
def _memo_flank_nodes(key: TeethKey, member: str, flank: str, grid: tuple) -> FlankSurface:
    """The real flank of ``member`` on a projection-plane grid (``grid``: its options as
    sorted (key, value) pairs) of the flank of ``key`` (:func:`flank_key`; read-only
    arrays)."""
    fs = flank_surface(key.case, member, flank, **dict(grid))
    for a in (*fs, *fs.grid):
        if isinstance(a, np.ndarray):
            a.flags.writeable = False
    return fs


def flank_nodes(case: Case, member: str, flank: str, grid: dict) -> FlankSurface:
    """A real flank on a projection-plane grid, memoised per process by the flank alone.

    Parameters
    ----------
    case : geometry.case.Case
    member : str
        ``"pinion"`` or ``"gear"``.
    flank : str
        ``"concave"`` or ``"convex"``.
    grid : dict
        ``nu``, ``nv``, ``u_limits``, ``v_limits`` of
        :func:`geometry.machine.flank.flank_surface`.

    Returns
    -------
    geometry.machine.flank.FlankSurface
        :func:`geometry.machine.flank.flank_surface` of the flank (arrays read-only): a
        flank does not depend on the misalignment, so the analyses of a process that share
        the teeth (a misalignment or torque series, a study with ``/geometry``) solve its
        861 nodes once, keyed by the flank alone (:func:`flank_key`: a case whose other
        member or other flank differs shares it).

    Raises
    ------
    InputError
        As :func:`geometry.machine.flank.flank_surface`.

    Notes
    -----
    Source: seed §2.2 (Eq. 2.7a, 2.8, 2.9–2.13), through
    :func:`geometry.machine.flank.flank_surface`; the memo changes no number (tested
    bit for bit against a fresh solve, ``tests/test_study_memos.py``).
    """
    key = tuple(sorted((k, tuple(v) if isinstance(v, list | tuple) else v)
                       for k, v in grid.items()))
    return _memo_flank_nodes(flank_key(case, member, flank), member, flank, key)


def gear_nodes(case: Case, flank: str, grid: dict) -> FlankSurface:
    """The real gear flank on the ease-off's grid, memoised per process
    (:func:`flank_nodes` of the gear): the ease-off and the ``/geometry`` group of an
    analysis share it, and a misalignment study solves it once per process.

    Parameters, returns and errors as :func:`flank_nodes`.
    """
    return flank_nodes(case, "gear", flank, grid)


def memo_info() -> dict[str, tuple]:
    """Hits, misses, size and capacity (``functools`` cache info) of this process's memos
    of what an analysis needs of the teeth alone: ``"forward_points"`` (the pinion points
    of the forward map) and ``"flank_nodes"`` (real flanks on a grid: the ease-off's gear
    flank, the ``/geometry`` group's four); a misalignment sweep solves each once per
    process."""
    return {"forward_points": _memo_forward_points.cache_info(),
            "flank_nodes": _memo_flank_nodes.cache_info()}


def clear_memos() -> None:
    """Forget the memoised forward-map points and flank nodes, and the ease-offs computed
    from them with their unloaded cycles and fields (:func:`contact.utca.easeoff.ease_off`'s,
    :func:`contact.utca.unloaded_tca`'s and :func:`contact.utca.fields.fields_of`'s memos;
    frees memory)."""
    from contact.utca.datasets import clear_cycle_memo
    from contact.utca.easeoff import clear_ease_off_memo
    from contact.utca.fields import clear_fields_memo

    _memo_forward_points.cache_clear()
    _memo_flank_nodes.cache_clear()
    clear_ease_off_memo()
    clear_cycle_memo()
    clear_fields_memo()


def _forward_map(case: Case, pf: str, kin: MeshKinematics, ref: np.ndarray) -> _ForwardMap:
    """The forward map on the extended pinion grid and its spline.

    The spline is built on the pinion blade's working sections only (the profile and its
    relief lines, :func:`_working_sections`) and continued linearly beyond them
    (:func:`fill_missing`): the kink at the fillet would make a cubic spline ring over the
    whole flank.

    The pinion points on the grid (861 solutions of the equation of meshing) do not depend
    on the misalignment, only their images do: they are memoised per process
    (:func:`_memo_forward_points`, keyed by the pinion flank alone, :func:`flank_key`),
    so the points of a misalignment study, or of gears tried against one pinion, are solved
    once.
    """
    up, vp, cp, uu, vv, z, rho = _forward_grid(case)
    # inside a development's trial (seeds continued from earlier trials', WarmSeeds) the
    # points are solved and not memoised: an analysis outside one is computed cold
    points = (_pinion_points(case, pf, z, rho) if warm_seeds_active()
              else _memo_forward_points(flank_key(case, "pinion", pf), pf))
    fwd, branch = _mates(case, pf, kin, cp, uu, vv, reference=ref, points=points)
    ok = fwd.good
    if ok.sum() < 16:
        raise InputError(
            f"case: the {pf} pinion flank has no points on the surface of action of these "
            "axes (check the misalignment and the machine settings)")
    smooth = ok & np.isin(fwd.section, working_sections(case.pinion.flank(pf).blade))
    if smooth.sum() < 16:
        smooth = ok
    image = fill_missing(fwd.image, smooth)
    splines = [RectBivariateSpline(up, vp, image[..., k]) for k in range(2)]
    return _ForwardMap(case, pf, kin, cp, branch, up, vp, fwd,
                       SplineGroup(splines, kernels_module("contact.utca.isoline_numba")),
                       _regular_q_sign(case, pf, points))


def _seed_place(fm: _ForwardMap, u, v) -> tuple | None:
    """The index (of the shape of ``u``) of the place (u, v) nearest, in pinion fractions,
    the forward grid's middle node (its solve's seed; the first on ties); None where there
    is no place or none is finite (the batch then keeps its own seed)."""
    u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
    if u.size == 0:
        return None
    d = (u - fm.u[len(fm.u) // 2]) ** 2 + (v - fm.v[len(fm.v) // 2]) ** 2
    if not np.isfinite(d).any():
        return None
    return tuple(int(i) for i in np.unravel_index(int(np.nanargmin(d)), u.shape))


def _regular_q_sign(case: Case, pf: str, points) -> float | None:
    """The sign of ∂f/∂q on the pinion flank's regular envelope, read at the forward grid's
    valid point nearest its middle (the grid's solve compared every point with its seed,
    the middle target, so every valid point has that sign); None where the pinion is not
    generated or no point is valid (the later solves then take their own seed's).

    Why: the placement's later solves (:meth:`_ForwardMap.mates`) are of subsets of places
    whose middle target, the solver's seed, can converge beyond the singular line or on
    another root; its sign then called every regular point of the subset undercut and
    the ease-off lost those nodes (issue 71, the FM 20×31 at Σ 70°: 197 of 861 nodes
    valid, 664 with the flank's sign; docs/synthesis.md).
    """
    tool = case.pinion.flank(pf)
    if tool.machine.process != "Generate":
        return None
    reason, section, params = points[2], points[6], points[7]
    ok = np.argwhere(reason == 0)
    if ok.size == 0:
        return None
    mid = (np.asarray(reason.shape) - 1) / 2.0
    i = tuple(ok[np.argmin(((ok - mid) ** 2).sum(axis=1))])
    sign = meshing_q_sign(tool.blade, tool.machine, params[i][0:1], params[i][1:2],
                          params[i][2:3], np.asarray(section[i]).reshape(1),
                          length_scale=case.pinion.blank.outer_cone_distance)
    return float(sign[0]) if sign[0] != 0 else None


#: [mm, rad, rad] the largest move of (s, θ, q) from its guess that a trial batch's middle
#: seed may make and still seed the batch (:meth:`_ForwardMap.mates`): one limited Newton
#: step of the envelope solver (:data:`geometry.machine.meshing.ENVELOPE_STEP_LIMIT`; a
#: root farther is "possibly another branch" there too). A seed that crosses a
#: blade-section junction to its neighbour moves far less (the default run's: none
#: re-seeded); the 20×31 at Σ 70°'s jumped to the tip section at q −0.46 rad, its
#: neighbours at q ≈ −0.08.
_SEED_JUMP = ENVELOPE_STEP_LIMIT


_NEAREST_CANDIDATES = 4  # k-d tree neighbours re-ranked by _nearest_node's own distance


def _nearest_node(zt: np.ndarray, rt: np.ndarray, zn: np.ndarray, rn: np.ndarray) -> np.ndarray:
    """Index (M,) of the node (zn, rn) (N,) [mm] nearest each target (zt, rt) (M,) [mm]:
    ``argmin((zt − zn)² + (rt − rn)²)`` over the nodes, the first on ties.

    A k-d tree (``scipy.spatial.cKDTree``) gives each target's
    :data:`_NEAREST_CANDIDATES` nearest nodes, which are ranked again by that expression
    (the lowest index among equal distances), so the choice is the full search's; where
    all the candidates tie within round-off (a repeated node) the target takes the full
    search, which formed the M × N distances of all targets (~9 ms for the 861 × 861 of
    the default grids). A target that is not finite gets node 0 (the full search's
    argmin of a row of NaN).
    """
    n = zn.size
    out = np.zeros(zt.size, dtype=np.intp)
    fin = np.isfinite(zt) & np.isfinite(rt)
    if n == 0 or not fin.any():
        return out
    k = min(_NEAREST_CANDIDATES, n)
    _, cand = cKDTree(np.stack([zn, rn], -1)).query(np.stack([zt[fin], rt[fin]], -1), k=k)
    cand = np.reshape(cand, (-1, k))
    d2 = (zt[fin, None] - zn[cand]) ** 2 + (rt[fin, None] - rn[cand]) ** 2
    best = d2.min(axis=1, keepdims=True)
    pick = np.where(d2 == best, cand, n).min(axis=1)
    # every candidate within round-off of the least: more nodes may tie beyond them (a
    # node repeated), so those targets take the full search
    tied = np.flatnonzero(d2.max(axis=1) <= best[:, 0] * (1.0 + 1e-12))
    if tied.size:
        rows = np.flatnonzero(fin)[tied]
        pick[tied] = np.argmin((zt[rows, None] - zn) ** 2 + (rt[rows, None] - rn) ** 2,
                               axis=1)
    out[fin] = pick
    return out


def _spline_start(fm: _ForwardMap, zt: np.ndarray, rt: np.ndarray):
    """Start places (u, v) of the mates of the gear nodes (zt, rt): the nearest node of the
    forward map, then :data:`_SPLINE_ITER` Newton steps on its spline.

    A node whose step leaves its place exactly as it was has reached a fixed point of the
    iteration (the spline and the step are evaluated point by point), so its further
    steps would leave it there: it steps no more (the same places bit for bit; about
    two thirds of the 861 nodes settle by the fifth step, the rest alternate in the last
    bit and run all steps).
    """
    ok = fm.nodes.good
    img = fm.nodes.image
    uu, vv = np.meshgrid(fm.u, fm.v, indexing="ij")
    target = np.stack([zt, rt], -1).reshape(-1, 2)
    k = _nearest_node(zt.ravel(), rt.ravel(), img[..., 0][ok], img[..., 1][ok])
    u = uu[ok][k]
    v = vv[ok][k]
    act = np.arange(u.size)
    for _ in range(_SPLINE_ITER):
        ua, va = u[act], v[act]
        un, vn = fm.newton_step(fm.jacobian(ua, va), ua, va, target[act] - fm.image(ua, va))
        u[act], v[act] = un, vn
        act = act[(un != ua) | (vn != va)]
        if act.size == 0:
            break
    return u.reshape(zt.shape), v.reshape(zt.shape)


def _exact_start(fm: _ForwardMap, u: np.ndarray, v: np.ndarray, zt: np.ndarray,
                 rt: np.ndarray) -> _Placement:
    """The real pinion at the start places, mapped exactly (the envelope solver starts from
    the forward node nearest to each place), with the spline's Jacobians there."""
    n = zt.size
    iu = np.clip(np.rint((u - fm.u[0]) / (fm.u[1] - fm.u[0])), 0, len(fm.u) - 1).astype(int)
    iv = np.clip(np.rint((v - fm.v[0]) / (fm.v[1] - fm.v[0])), 0, len(fm.v) - 1).astype(int)
    m0 = fm.mates(u, v, guess=(fm.nodes.params[iu, iv], fm.nodes.section[iu, iv]))
    flat = Mates(*(None if a is None else np.array(a).reshape(n, *np.shape(a)[zt.ndim:])
                   for a in m0))
    uf, vf = u.ravel().copy(), v.ravel().copy()
    target = np.stack([zt, rt], -1).reshape(n, 2)
    return _Placement(flat, uf, vf, target, fm.jacobian(uf, vf),
                      _placement_error(target, flat))


def _mates_with_jacobian(fm: _ForwardMap, u: np.ndarray, v: np.ndarray, guess):
    """Mates at (u, v) (M,) and the finite-difference Jacobian (M, 2, 2) of the exact map
    there, the point and its two stencil points in one batch; ok (M,): all three good."""
    k = u.size
    h = _FD_STEP
    params, section = guess
    m3 = fm.mates(np.r_[u, u + h, u], np.r_[v, v, v + h],
                  guess=(np.tile(params, (3, 1)), np.tile(section, 3)))
    at, du, dv = (_take(m3, slice(i * k, (i + 1) * k)) for i in range(3))
    ok = at.good & du.good & dv.good
    return at, np.stack([(du.image - at.image) / h, (dv.image - at.image) / h], -1), ok


def _broyden(jac: np.ndarray, dx: np.ndarray, dy: np.ndarray, good: np.ndarray) -> np.ndarray:
    """Broyden (secant) update of per-node Jacobians (M, 2, 2) with the steps dx (M, 2) of
    the places and dy (M, 2) of the images, where ``good`` and the step is not null."""
    nx = np.einsum("...i,...i", dx, dx)
    upd = good & (nx > 1e-24)
    corr = (dy - np.einsum("...ij,...j->...i", jac, dx)) / np.where(upd, nx, 1.0)[:, None]
    return np.where(upd[:, None, None], jac + corr[:, :, None] * dx[:, None, :], jac)


def _place_exactly(fm: _ForwardMap, st: _Placement) -> None:
    """Exact placement iterations on the nodes not yet placed (updates ``st``).

    Each evaluates the real pinion at the Newton step and maps it exactly; the per-node
    Jacobian gets Broyden updates, and from iteration :data:`_BROYDEN_ITER` on, for the
    stragglers where the map is strongly stretched (near the pinion's fillet junction),
    the finite-difference Jacobian at each accepted new place. A step that does not reduce
    the error is not taken (the node retries with the secant-updated Jacobian); a node
    whose mate leaves the generated surface is dropped.
    """
    for it in range(_MAP_ITER):
        idx = np.flatnonzero(np.isfinite(st.error) & (st.error >= _MAP_TOL))
        if idx.size == 0:
            break
        late = it >= _BROYDEN_ITER
        u0, v0, img0 = st.u[idx], st.v[idx], st.mates.image[idx]
        un, vn = fm.newton_step(st.jacobian[idx], u0, v0, st.target[idx] - img0,
                                limit=_LATE_STEP_LIMIT if late else _STEP_LIMIT)
        guess = (st.mates.params[idx], st.mates.section[idx])
        if late or it == _BROYDEN_ITER - 1:
            mm, j_fd, ok_fd = _mates_with_jacobian(fm, un, vn, guess)
        else:
            mm, j_fd, ok_fd = fm.mates(un, vn, guess), None, None
        dy = np.where(mm.good[:, None], mm.image - img0, 0.0)
        jac = _broyden(st.jacobian[idx], np.stack([un - u0, vn - v0], -1), dy, mm.good)
        better = mm.good & (np.abs(st.target[idx] - mm.image).max(axis=-1) < st.error[idx])
        if j_fd is not None:
            jac = np.where((better & ok_fd)[:, None, None], j_fd, jac)
        st.jacobian[idx] = jac
        st.accept(idx[better], _take(mm, better), un[better], vn[better])
        st.error[idx[~mm.good]] = np.inf
        log.debug("map iteration: %d of %d nodes placed", int((st.error < _MAP_TOL).sum()),
                  st.error.size)


def map_gear_nodes(case: Case, pf: str, kin: MeshKinematics, ref: np.ndarray,
                    zt: np.ndarray, rt: np.ndarray) -> GearMates:
    """Pinion mates of the gear nodes (module docstring, "Gear projection-plane grid").

    Start values from the spline of the forward map (:func:`_spline_start`), then exact
    iterations on the real pinion (:func:`_place_exactly`). ``pinned``: the nodes whose
    iterate ran to the edge of the extended pinion grid (their mate lies beyond the pinion
    blank).
    """
    fm = _forward_map(case, pf, kin, ref)
    u, v = _spline_start(fm, zt, rt)
    st = _exact_start(fm, u, v, zt, rt)
    _place_exactly(fm, st)
    shape = zt.shape
    mates = _with_curvatures(case, pf, st.mates)
    u, v = st.u.reshape(shape), st.v.reshape(shape)
    pinned = (np.isclose(u, fm.u[0]) | np.isclose(u, fm.u[-1]) | np.isclose(v, fm.v[0])
              | np.isclose(v, fm.v[-1]))
    return GearMates(u, v, Mates(*(a.reshape(shape + a.shape[1:]) for a in mates)),
                      st.error.reshape(shape), pinned)


def fill_missing(values: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Fill invalid nodes of a 2-D field by linear extrapolation from valid neighbours.

    Used only to give the interpolating splines a smooth field: filled nodes stay masked.
    Each pass fills the invalid nodes next to valid ones, with the mean over the four grid
    directions of the linear continuation of the two nearest valid nodes (2 a₁ − a₂), or
    of the nearest one where only it is valid; passes repeat until every node is filled
    or none can be. A pass reads each direction's neighbours through shifted views of the
    grid, the fields first (the same sums, bit for bit, as the rolled copies of the grid
    it read before: ~2× faster on the ease-off's 41 × 21 grids, issue 75).

    Parameters
    ----------
    values : array_like (nu, nv, ...)
        The field; trailing axes carry several fields on the same mask, filled at once
        (each element's arithmetic is that of a single field).
    valid : array_like of bool (nu, nv)
        Nodes that hold values.

    Returns
    -------
    ndarray of float (nu, nv, ...)
        A copy with the invalid nodes filled (left as they were where no valid node
        reaches them).

    Raises
    ------
    InputError
        If no node is valid.
    """
    out = np.array(values, dtype=float)
    have = np.array(valid, dtype=bool)
    if not have.any():
        raise InputError("valid: must hold at least one valid node, got none")
    if have.ndim != 2 or out.shape[:2] != have.shape:
        return _fill_missing_rolled(out, have)
    nu, nv = have.shape
    # the fields first, the grid last (T, nu, nv): the masks broadcast over the fields
    # and each product runs along the grid's rows
    grid = np.moveaxis(out.reshape(nu, nv, -1), 2, 0).copy()
    # each direction's continuation reaches the nodes two beyond the grid's edge on its
    # side: the node, its nearest neighbour a₁ and the next a₂, as three shifted views
    # (the nodes nearer the edge take nothing from that side)
    views = []
    for axis, n in ((0, nu), (1, nv)):
        for step in (1, -1):
            if n < 3:
                continue
            at, n1, n2 = ((slice(2, None), slice(1, -1), slice(0, -2)) if step == 1
                          else (slice(0, -2), slice(1, -1), slice(2, None)))
            views.append(tuple((slice(None),) * axis + (k,) for k in (at, n1, n2)))
    with np.errstate(invalid="ignore", over="ignore"):
        while not have.all():
            acc = np.zeros(grid.shape)
            cnt = np.zeros(have.shape)
            for at, n1, n2 in views:
                lack, h1, h2 = ~have[at], have[n1], have[n2]
                two = lack & h1 & h2
                one = lack & h1 & ~h2
                a1, a2 = grid[(slice(None), *n1)], grid[(slice(None), *n2)]
                acc_at = acc[(slice(None), *at)]
                # (the sums of the selected nodes alone, in the same order: as boolean
                # indexing wrote them; an unfilled node's value is never read)
                np.add(acc_at, 2 * a1 - a2, out=acc_at, where=two)
                np.add(acc_at, a1, out=acc_at, where=one)
                cnt_at = cnt[at]
                np.add(cnt_at, 1.0, out=cnt_at, where=two | one)
            new = ~have & (cnt > 0)
            if not new.any():
                break
            grid[:, new] = acc[:, new] / cnt[new]
            have = have | new
    return np.ascontiguousarray(np.moveaxis(grid, 0, 2)).reshape(out.shape)


def _fill_missing_rolled(out: np.ndarray, have: np.ndarray) -> np.ndarray:
    """:func:`fill_missing`'s passes by rolled copies of the grid (the general path: a
    mask that is not the field's first two axes)."""
    trail = (1,) * (out.ndim - have.ndim)
    while not have.all():
        acc = np.zeros(out.shape)
        cnt = np.zeros(have.shape)
        for axis in (0, 1):
            for step in (1, -1):
                a1 = np.roll(out, step, axis)
                a2 = np.roll(out, 2 * step, axis)
                h1 = np.roll(have, step, axis)
                h2 = np.roll(have, 2 * step, axis)
                # forbid wrap-around
                edge = [slice(None)] * 2
                edge[axis] = slice(0, 2) if step == 1 else slice(-2, None)
                h1 = h1.copy()
                h2 = h2.copy()
                h1[tuple(edge)] = False
                h2[tuple(edge)] = False
                two = ~have & h1 & h2
                one = ~have & h1 & ~h2
                acc[two] += 2 * a1[two] - a2[two]
                cnt[two] += 1
                acc[one] += a1[one]
                cnt[one] += 1
        new = ~have & (cnt > 0)
        if not new.any():
            break
        out[new] = acc[new] / cnt[new].reshape(-1, *trail)
        have = have | new
    return out
