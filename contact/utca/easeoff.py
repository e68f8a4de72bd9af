"""Surface of action, surface of roll angle (Q) and ease-off (seed §2.3.2.1, §4.2).

The seed replaces the five-equation contact search of the conventional TCA (Eq. 2.14) by
two surfaces on the gear projection plane (the gear's axial section: axial position z ×
radius ρ):

* **Roll angle.** Every point of the real pinion flank, with its unit normal, is turned
  about the pinion axis until it satisfies the conjugacy condition of the two axes
  (seed Eq. 2.19 / 4.1, :mod:`contact.utca.action_surface`): there it lies on the
  *surface of action* and is a contact point of the pinion with its own conjugate gear.
  The pinion rotation needed is the point's roll angle; plotted on the gear projection
  plane it is the surface Q, shifted so that its smallest value is zero (Eq. 4.2 text).
* **Ease-off.** The action-surface points turned back about the gear axis by the gear's
  kinematic rotation form the conjugate of the pinion in the gear frame (Eq. 2.20, 4.2a).
  The ease-off is the distance from the real gear flank to this conjugate, after the
  conjugate is turned about the gear axis until it touches the real gear at one point
  (seed §4.2): as an angle about the gear axis (directly a transmission error) and as a
  distance along the gear normal.

Gear projection-plane grid (instead of resampling)
--------------------------------------------------
The real gear flank is generated on its projection-plane grid
(:func:`geometry.machine.flank.flank_surface`). Rather than resampling scattered conjugate points
onto that grid, for every gear node the pinion point whose action-surface image has the
node's (z, ρ) is found by Newton's method: a bicubic spline of the forward map (pinion
projection plane → gear projection plane, on an extended 41 × 21 pinion grid, built on the
pinion blade's main section) gives the start and the first Jacobian; each iteration then
evaluates the real pinion exactly (:func:`geometry.machine.meshing.solve_envelope`) and maps it
exactly, with Broyden updates of the Jacobian and, for the nodes left after four
iterations, finite-difference Jacobians of the exact map (the map is strongly stretched
next to the pinion's fillet junction). Nodes are placed to |Δz|, |Δρ| < 1e-7 mm and the
conjugate's polar angle is carried the remaining distance with the gear surface's slope,
so the residual placement enters at second order: the ease-off and Q are **exact at the
nodes** (no interpolation error; the conjugate examples give |ε| < 1e-5 µrad). Nodes with
no mate (beyond a fold of the map, where the pinion's flank meets its fillet) are masked
as ``no_conjugate_mate``; nodes whose mate lies beyond the pinion blank are computed but
masked as ``outside_pinion_blank`` (contact impossible there). Nodes in the strip a corner
of the pinion blade (the toprem or flankrem junction) touches have no mate on either
section either; they stay ``no_conjugate_mate`` but carry ε, Q and the mate's fractions
continued from the two faces (ε: the larger of the faces' linear continuations, the gap
to a convex corner) and are marked ``smooth``, so the fields' splines and the contact
curves pass the strip instead of cutting its cells out of the flank.

Signs
-----
* ``drive_sense`` s_p = sign(a_p·((r − O_p) × n_p)): the sign of the pinion rotation that
  drives (moves its flank along its outward normal). Q grows in the driving direction:
  pinion rotation φ_p = ``roll_zero`` + s_p Q.
* ``lag_sense`` s_g = sign(n_g·e_θ): a gear rotation s_g δ moves the gear flank towards the
  pinion, i.e. makes the gear **lag** by δ. The angular ease-off ε = s_g (θ_conjugate −
  θ_real) ≥ 0 is the lag the gear needs for its real flank to reach the conjugate point —
  the transmission-error convention of the seed's Fig. 2.9 (gear lag behind the ideal
  kinematic position, ≥ 0). The ideal kinematic gear rotation is
  ψ = ``gear_phase`` − φ_p / R, with ``gear_phase`` fixed so that min ε = 0.
* The normal ease-off is the distance from the real gear surface to the touching conjugate
  point along the gear normal, (c − r_g)·n_g = ρ[sin(s_g ε)(e_θ·n_g) + (cos ε − 1)(e_ρ·n_g)]
  ≥ 0 (chord of the rotation; its distance to the curved surface differs by ½κ d_t² with
  d_t the chord's tangential part: below 0.05 µm for ease-off up to 100 µm).

Second-order data
-----------------
``gap_curvature`` K (per node): the pinion turned away from its contact roll by t is
separated from its conjugate at the node by ½ K t² (angle about the gear axis), from the
relative velocity and acceleration of the members and the pinion's normal curvature along
the relative velocity (:func:`_gap_curvature`). :mod:`contact.utca.contact_curves` uses it
to correct the seed's first-order UTE.

Public functions
----------------
FLANK_ROLES            flank role name → pinion flank of a case (drive, coast)
MATING_FLANK           pinion flank → the gear flank it meshes with
roll_angle_surface     roll angle of every grid point of the real pinion flank
EaseOff                ease-off and Q on the gear projection-plane grid
ease_off               build it for a case (Eq. 2.19–2.20, 4.1–4.2)
normal_ease_off        the normal ease-off of an angular one (chord of the rotation)
fill_missing           fill masked grid nodes by linear continuation of the valid ones

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009 (the seed), §2.3.2, §4.2.
F. L. Litvin, A. Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §6.1.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from contact.utca.action_surface import (
    MeshKinematics,
    action_roll_angle,
    action_surface,
    mesh_kinematics,
    meshing_coefficients,
    to_pair_frame,
)
from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.validation import one_of
from geometry.machine.curvature import normal_curvature
from geometry.machine.cutter import working_sections
from geometry.machine.flank import DEFAULT_GRID, flank_surface
from geometry.machine.meshing import warm_seeds_active
from geometry.pair.assembly import Misalignment, rotate_about_axis
from geometry.pair.pitch_contact import check_pitch_contact

if TYPE_CHECKING:
    from geometry.case import Case, TeethKey
from contact.utca.conjugate_map import (
    GearMates,
    Mates,
    fill_missing,
    gear_nodes,
    gear_reference,
    map_gear_nodes,
)

__all__ = [
    "EASEOFF_REASONS",
    "FLANK_ROLES",
    "MATING_FLANK",
    "MIN_VALID_NODES",
    "MISALIGNMENT_UNITS",
    "EaseOff",
    "ease_off",
    "fill_missing",
    "misalignment_range",
    "normal_ease_off",
    "roll_angle_surface",
    "working_flanks",
]

log = logging.getLogger(__name__)


_MAP_TOL = 1e-7  # [mm] node-placement tolerance of the conjugate points


#: pinion flank → the gear flank it meshes with (concave pinion flanks mesh convex gear flanks)
MATING_FLANK: dict[str, str] = {"concave": "convex", "convex": "concave"}


#: flank role → the pinion flank of a case that plays it
FLANK_ROLES: dict[str, Callable[[Case], str]] = {
    "drive": lambda case: case.pair.drive_flank,
    "coast": lambda case: MATING_FLANK[case.pair.drive_flank],
}


#: mask reason codes of an ease-off grid node
EASEOFF_REASONS: dict[int, str] = {
    0: "valid",
    1: "gear_not_generated",  # the real gear flank has no point here (geometry mask)
    2: "no_conjugate_mate",  # no pinion point maps here through the surface of action
    3: "outside_pinion_blank",  # the mating pinion point lies beyond the pinion's blank
    4: "beyond_fold",  # the roll angle turns back along the profile: a fold of the mapping
}


# --------------------------------------------------------------------------- helpers
def working_flanks(case: Case, flank: str | None) -> tuple[str, str]:
    """The pinion's and the gear's working flank names for a flank role or name.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str or None
        ``"drive"`` (None), ``"coast"``, or a pinion flank name (``"concave"``/``"convex"``).

    Returns
    -------
    (str, str)
        The pinion flank name and its mating gear flank name (:data:`MATING_FLANK`).

    Raises
    ------
    InputError
        An unknown flank (the accepted names listed).
    """
    if flank is None:
        flank = "drive"
    one_of("flank", flank, [*FLANK_ROLES, *MATING_FLANK])
    pf = FLANK_ROLES[flank](case) if flank in FLANK_ROLES else flank
    return pf, MATING_FLANK[pf]


def _mask_folds(reason: np.ndarray, roll: np.ndarray) -> None:
    """Mask gear nodes beyond a fold of the roll-angle surface along the profile (in place).

    On a bevel or hypoid flank the roll angle of the conjugate mates changes monotonically
    from root to tip; where it turns back at the end of a profile line (the mapping pinion
    → gear folds, e.g. where the pinion's flank meets its fillet or tip), the nodes beyond
    the fold have a second-sheet mate that cannot carry contact. They are given reason 4
    (``beyond_fold``), counted from the fold towards the nearer end of the line.
    """
    valid = reason == 0
    q = np.where(valid, roll, np.nan)
    d = np.diff(q, axis=1)
    ok = np.isfinite(d)
    if not np.any(ok):
        return
    sense = 1.0 if np.median(np.sign(d[ok])) >= 0 else -1.0
    nv = q.shape[1]
    for i, j in np.argwhere(ok & (np.sign(d) * sense < 0)):
        if j + 1 >= nv / 2:  # fold near the tip end: mask from j + 1 to the tip
            reason[i, j + 1:][reason[i, j + 1:] == 0] = 4
        else:  # near the root end: mask from the root up to j
            reason[i, : j + 1][reason[i, : j + 1] == 0] = 4


def roll_angle_surface(case: Case, *, flank: str | None = None,
                       misalignment: Misalignment | None = None, nu: int = 41, nv: int = 21,
                       u_limits=(0.0, 1.0), v_limits=(0.0, 1.0)):
    """Roll angle of every grid point of the real pinion flank (seed Eq. 2.19, 4.1).

    Parameters
    ----------
    case : geometry.case.Case
    flank : str, optional
        ``"drive"`` (default), ``"coast"``, or the pinion flank ``"concave"``/``"convex"``.
    misalignment : geometry.pair.assembly.Misalignment, optional
        Defaults to the case's own.
    nu, nv, u_limits, v_limits
        Pinion projection-plane grid (see :func:`geometry.machine.flank.projection_grid`).

    Returns
    -------
    surface : geometry.machine.flank.FlankSurface
        The pinion flank.
    roll : ndarray (nu, nv) — [rad]
        Absolute pinion rotation φ_p at which each point lies on the surface of action
        (NaN where it never does or the point is not generated).
    action_points : ndarray (nu, nv, 3) — [mm]
        The points on the surface of action, in the pair frame.

    Raises
    ------
    InputError
        For a bad flank name or grid (and as :func:`geometry.machine.flank.flank_surface`).
    """
    pf, _ = working_flanks(case, flank)
    kin = mesh_kinematics(case, misalignment)
    ps = flank_surface(case, "pinion", pf, nu=nu, nv=nv, u_limits=u_limits, v_limits=v_limits)
    roll, _ = action_roll_angle(kin, ps.position, ps.normal, reference=gear_reference(case, kin))
    ra, _ = action_surface(kin, ps.position, ps.normal, np.nan_to_num(roll))
    ra[~np.isfinite(roll)] = np.nan
    return ps, roll, ra


def _gap_curvature(kin: MeshKinematics, position, normal, roll, kappa1, kappa2, dir1):
    """K_n: normal gap between the pinion at roll φ_a + t and its conjugate ≈ ½ K_n t² [mm].

    At the contact configuration (pinion turned by its roll angle φ_a) a point X fixed to
    the gear moves relative to the pinion with velocity y' = X' − ω_p × (X − O_p) and
    acceleration y'' = X'' − 2 ω_p × X' + ω_p × (ω_p × (X − O_p)) per unit pinion rotation
    (ω_p = a_p, ω_g = −a_g/R, X' = ω_g × (X − O_g), X'' = ω_g × X'); y'·n = 0 is the
    equation of meshing, so its distance from the pinion surface grows as
    ½ (n·y'' + κ_p(y') |y'|²) t² (κ_p: the pinion's normal curvature along y', convex
    positive; Euler's formula).
    """
    ra, na = action_surface(kin, position, normal, roll)
    r0 = kin.pinion_place[:3, :3]
    e1 = rotate_about_axis(kin.pinion_axis, roll, np.asarray(dir1) @ r0.T)
    wp = kin.pinion_axis
    wg = -kin.gear_axis / kin.ratio
    xd = np.cross(wg, ra - kin.gear_origin)
    xdd = np.cross(wg, xd)
    w = ra - kin.pinion_origin
    y1 = xd - np.cross(wp, w)
    y2 = xdd - 2.0 * np.cross(wp, xd) + np.cross(wp, np.cross(wp, w))
    speed2 = np.einsum("...i,...i", y1, y1)
    kap = normal_curvature(kappa1, kappa2, e1, y1 + 1e-300)
    return np.einsum("...i,...i", na, y2) + kap * speed2


# --------------------------------------------------------------------------- ease-off
class EaseOff(NamedTuple):
    """Ease-off and roll-angle surface on the gear projection-plane grid (nu, nv).

    Angles in rad, lengths in mm; invalid nodes hold NaN in ``ease_off``, ``ease_off_angle``
    and ``roll_angle`` (the ``raw_*`` fields keep the computed values wherever a conjugate
    mate exists, for interpolation).
    """

    pinion_flank: str
    gear_flank: str
    u: np.ndarray  # (nu,) gear lengthwise fraction
    v: np.ndarray  # (nv,) gear profile fraction
    axial: np.ndarray  # (nu, nv) [mm] gear projection plane z
    radius: np.ndarray  # (nu, nv) [mm] gear projection plane ρ
    ease_off: np.ndarray  # [mm] along the gear normal, ≥ 0
    ease_off_angle: np.ndarray  # [rad] gear lag, ≥ 0
    roll_angle: np.ndarray  # [rad] Q, drive sense, ≥ 0
    raw_ease_off_angle: np.ndarray  # [rad] as ease_off_angle where a mate exists
    raw_roll_angle: np.ndarray  # [rad]
    normal_arm: np.ndarray  # [mm] d(normal ease-off)/d(angle) = ρ |n·e_θ|
    gap_curvature: np.ndarray  # [1/rad] K: pinion's angular gap at roll Q + t ≈ ½ K t²
    gear_position: np.ndarray  # (nu, nv, 3) [mm] real gear flank, gear frame
    gear_normal: np.ndarray  # (nu, nv, 3) [1]
    pinion_axial: np.ndarray  # [mm] projection-plane place of the mating pinion point
    pinion_radius: np.ndarray  # [mm]
    pinion_u: np.ndarray  # [1] its fractions on the pinion blank (inside: 0..1)
    pinion_v: np.ndarray  # [1]
    placement_error: np.ndarray  # [mm] max |Δz|, |Δρ| of the conjugate point at the node
    smooth: np.ndarray  # bool: computed, and both points on their blades' working sections
    reason: np.ndarray  # int8, EASEOFF_REASONS
    drive_sense: int  # s_p
    lag_sense: int  # s_g
    roll_zero: float  # [rad] pinion rotation at Q = 0 (on top of the pinion phase)
    gear_phase: float  # [rad] gear rotation ψ₀ at pinion rotation 0 (ε min = 0; on top of
    #                    the gear phase)
    ratio: float  # z_g / z_p
    pitch: float  # [rad] pinion angular pitch 2π/z_p = one mesh cycle of roll
    kinematics: MeshKinematics
    # (nu, nv, 3) envelope parameters (s [mm], θ, q [rad]) of the pinion mate of each gear
    # node and of the gear node itself, and (nu, nv) their blade sections: starting
    # guesses for solving either surface nearby
    pinion_parameters: np.ndarray | None = None
    pinion_section: np.ndarray | None = None
    gear_parameters: np.ndarray | None = None
    gear_section: np.ndarray | None = None

    @property
    def valid(self) -> np.ndarray:
        """Nodes where the pinion can touch the real gear (reason 0)."""
        return self.reason == 0

    @property
    def margin(self) -> np.ndarray:
        """Signed distance (in blank fractions) of the mating pinion point inside its blank."""
        return np.minimum(np.minimum(self.pinion_u, 1.0 - self.pinion_u),
                          np.minimum(self.pinion_v, 1.0 - self.pinion_v))


def ease_off(case: Case, *, flank: str | None = None, misalignment: Misalignment | None = None,
             grid: dict | None = None, pinion_phase: float = 0.0,
             gear_phase: float = 0.0) -> EaseOff:
    """Ease-off topography and surface of roll angle on the gear projection plane.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str, optional
        ``"drive"`` (default: the case's ``pair.drive_flank``), ``"coast"``, or the pinion
        flank ``"concave"``/``"convex"``; the gear flank is the mating one.
    misalignment : geometry.pair.assembly.Misalignment, optional
        ΔE, ΔP, ΔG [mm], ΔΣ [rad]; defaults to the case's own ``[misalignment]``.
    grid : dict, optional
        Gear grid ``nu``, ``nv``, ``u_limits``, ``v_limits`` (default
        :data:`geometry.machine.flank.DEFAULT_GRID`: 41 × 21).
    pinion_phase, gear_phase : float — [rad]
        Rigid rotation of each member about its axis before assembly (indexing); only
        ``roll_zero`` and ``gear_phase`` of the result change.

    Returns
    -------
    EaseOff
        ε ≥ 0 [rad] (gear lag), normal ease-off ≥ 0 [mm], Q ≥ 0 [rad] on the (nu, nv) gear
        grid, all shifted to touch zero over the valid nodes; see the module docstring for
        signs.

    Raises
    ------
    InputError
        ``pair.offset`` inconsistent with the blanks
        (:func:`geometry.pair.pitch_contact.check_pitch_contact`). For a bad flank name or
        grid, if the pinion never meets the surface of action, or
        no gear node can be touched by the pinion; for a misalignment that separates the
        flanks (fewer than :data:`MIN_VALID_NODES` grid nodes where the pinion meets the
        gear inside both blanks) the message names the misalignment and the range of it
        that works for the case (bisection on the ease-off with the other misalignments
        as given, :func:`misalignment_range`).

    Notes
    -----
    Seed Eq. 2.19–2.20 and 4.1–4.2: action surface (closed form, module docstring),
    conjugate gear (Eq. 4.2a: rotation about the gear axis by −φ_p/R), ease-off = real
    gear − conjugate, shifted by a rigid rotation of the conjugate so that one node touches
    (§4.2). The seed's "radial distance" between grid points is read as the distance along
    the gear normal; the angular ease-off is exact (both points share (z, ρ)).
    """
    check_pitch_contact(case)  # pair.offset consistent with the blanks
    try:
        eo = _memo_ease_off(case, flank, misalignment, grid, pinion_phase, gear_phase)
        valid = int(np.count_nonzero(eo.valid))
        why = f"{valid} valid ease-off nodes, at least {MIN_VALID_NODES} needed"
    except InputError as exc:
        eo, valid, why = None, 0, str(exc)
    if valid >= MIN_VALID_NODES:
        return eo
    mis = case.misalignment if misalignment is None else misalignment
    given = {k: getattr(mis, k) for k in MISALIGNMENT_UNITS if getattr(mis, k) != 0.0}
    if not given:
        if eo is None:
            raise InputError(why)
        if case.synthesised:  # settings the user never set: say whose they are
            raise InputError(
                f"case: the flanks meet at only {why} with no misalignment: this case's "
                "machine settings were synthesised from basic data (its 'synthesised' "
                "fields); not edited since, the synthesised flanks do not mesh: where "
                "its 'source' says the pinion fell back to its own crown gear (a "
                "generated gear whose crown-gear synthesis had no solution, "
                "docs/synthesis.md 'The generated gear's pinion on the gear's crown "
                "gear'), the flanks match at the mean point only; the other gear process "
                "(`gear_process`), or a face contact ratio of 1.25 (beta_m, b2: `ltca "
                "synthesize`'s note), are the changes to try; edited, check the pair "
                "offset, the mounting distances and the blanks")
        raise InputError(f"case: the flanks meet at only {why} with no misalignment (check "
                         "the pair offset, the mounting distances and the blanks)")
    ranges = []
    for name, value in given.items():
        limit = misalignment_range(case, name, mis, flank=flank, grid=grid)
        if limit is None:  # zero does not help: another misalignment is the cause
            continue
        unit = MISALIGNMENT_UNITS[name]
        scale = math.degrees(1.0) if unit == "deg" else 1.0
        option = MISALIGNMENT_OPTIONS[name]
        ranges.append(f"{name} = {value * scale:g} {unit} ({option}) is out of range: beyond "
                      f"about {limit * scale:.3g} {unit} the flanks no longer meet inside both "
                      "blanks at all, and the contact pattern leaves the flank well before "
                      "that (`ltca vh-check` finds how far it stays on the flank)")
    if not ranges:
        ranges = ["no single one of " + ", ".join(given) + " is the cause: reduce them "
                  "together"]
    raise InputError(
        "misalignment: separates the flanks (the pinion meets the gear inside both blanks "
        f"at too few points: {why}); with the other misalignments as given, "
        + "; ".join(ranges))


#: fewest ease-off grid nodes where the pinion meets the gear inside both blanks for the
#: contact to be analysed (the contouring of the fields needs them, contact.utca.fields)
MIN_VALID_NODES = 16


#: the misalignment fields and the units they are reported in (ΔΣ is held in rad)
MISALIGNMENT_UNITS = {"delta_E": "mm", "delta_P": "mm", "delta_G": "mm", "delta_Sigma": "deg"}
#: the command-line options and case-file fields that set them, for messages
MISALIGNMENT_OPTIONS = {k: f"--d{k[6:]}, [operating] {k}" for k in MISALIGNMENT_UNITS}


def misalignment_range(case: Case, name: str, misalignment: Misalignment, *,
                       flank: str | None = None, grid: dict | None = None,
                       rel_tol: float = 0.02) -> float | None:
    """The largest value of one misalignment, in the direction of its given value, for which
    the flanks still meet inside both blanks (at least :data:`MIN_VALID_NODES` valid
    ease-off nodes), the other misalignments as given.

    Parameters
    ----------
    case : geometry.case.Case
    name : {"delta_E", "delta_P", "delta_G", "delta_Sigma"}
    misalignment : geometry.pair.assembly.Misalignment
        The misalignment whose ``name`` separates the flanks; [mm], ΔΣ [rad].
    flank, grid
        As :func:`ease_off`.
    rel_tol : float — [1]
        Bisection stops when the bracket is below this fraction of the bound (or 1 µm,
        1 µrad).

    Returns
    -------
    float or None
        The bound [mm] (ΔΣ [rad]) with the sign of the given value; None if even zero
        separates the flanks (the others are the cause).

    Notes
    -----
    A bisection on :func:`ease_off` (≈ 0.3 s each, ~10 evaluations): the count of valid
    nodes falls as the misalignment grows (the contact pattern leaves the blanks).
    """
    import dataclasses

    def meets(x: float) -> bool:
        m = dataclasses.replace(misalignment, **{name: x})
        try:
            eo = _ease_off(case, flank, m, grid, 0.0, 0.0)
        except InputError:
            return False
        return int(np.count_nonzero(eo.valid)) >= MIN_VALID_NODES

    value = float(getattr(misalignment, name))
    if not meets(0.0):
        return None
    lo, hi = 0.0, value
    while abs(hi - lo) > max(rel_tol * abs(lo), 1e-3 if name != "delta_Sigma" else 1e-6):
        mid = 0.5 * (lo + hi)
        if meets(mid):
            lo = mid
        else:
            hi = mid
    return lo


def _memo_ease_off(case: Case, flank: str | None, misalignment: Misalignment | None,
                   grid: dict | None, pinion_phase: float, gear_phase: float) -> EaseOff:
    """:func:`_ease_off`, memoised per process (:func:`_memoised_ease_off`, arrays
    read-only): the analyses of one process at the same teeth, misalignment and flank (a
    torque series, an analysis repeated in a notebook) compute the ease-off once; it is a
    function of these alone (seed Eq. 2.19–2.20, 4.1–4.2), not of the torque. Inside a
    :class:`geometry.machine.meshing.WarmSeeds` block (a development's trial, its seeds
    continued from the earlier trials') computed and not memoised."""
    if warm_seeds_active():  # a development's trial (seeds continued): not memoised
        return _ease_off(case, flank, misalignment, grid, pinion_phase, gear_phase)
    mis = case.misalignment if misalignment is None else misalignment
    g = _grid_options(grid)
    grid_key = tuple(sorted((k, tuple(v) if isinstance(v, list | tuple) else v)
                            for k, v in g.items()))
    # repr: every float to the last bit, -0.0 apart from 0.0 (as Case.teeth_key)
    return _memoised_ease_off(case.teeth_key(), repr(mis), mis, flank, grid_key,
                              float(pinion_phase), float(gear_phase))


@memoised(maxsize=8)
def _memoised_ease_off(teeth: TeethKey, mis_text: str, mis: Misalignment, flank: str | None,
                       grid: tuple, pinion_phase: float, gear_phase: float) -> EaseOff:
    """:func:`_ease_off` of the case of ``teeth`` (:meth:`~geometry.case.Case.teeth_key`:
    the ease-off reads neither the case's misalignment, given here, nor its deviations,
    applied after it) at ``mis`` (``mis_text`` its ``repr``, the key), its arrays
    read-only. Tested bit for bit against a fresh computation
    (``tests/test_study_memos.py``)."""
    eo = _ease_off(teeth.case, flank, mis, dict(grid), pinion_phase, gear_phase)
    for a in (*eo, *eo.kinematics.__dict__.values()):
        if isinstance(a, np.ndarray):
            a.flags.writeable = False
    return eo


def clear_ease_off_memo() -> None:
    """Forget the ease-offs memoised per process by :func:`ease_off` (frees memory; the
    next call computes afresh)."""
    _memoised_ease_off.cache_clear()


def _ease_off(case: Case, flank: str | None, misalignment: Misalignment | None,
              grid: dict | None, pinion_phase: float, gear_phase: float) -> EaseOff:
    """:func:`ease_off` without the check of the flanks meeting."""
    pf, gf = working_flanks(case, flank)
    g = _grid_options(grid)
    kin = mesh_kinematics(case, misalignment, pinion_phase=pinion_phase, gear_phase=gear_phase)
    gs = gear_nodes(case, gf, g)  # the gear alone: memoised per process
    zt, rt = gs.grid.axial, gs.grid.radius
    gm = map_gear_nodes(case, pf, kin, gear_reference(case, kin), zt, rt)
    mt = gm.mates
    kn = _gap_curvature(kin, mt.position, mt.normal, np.where(mt.good, mt.roll, 0.0),
                        mt.kappa1, mt.kappa2, mt.dir1)
    mate = np.isfinite(gm.error) & (gm.error < _MAP_TOL)
    reason = _node_reasons(gm, mate, gs.valid)
    drive = _drive_sense(kin, mt, mate)
    rho, nt, nr = _polar_normal(gs.position, gs.normal)
    lag = 1 if np.nanmedian(nt[reason == 0]) > 0 else -1
    _mask_folds(reason, np.where(mate, mt.roll, np.nan))
    eps_raw, psi0 = _angular_ease_off(gs, mt.conjugate, mate, reason, lag, nt, nr, rho)
    q_raw, roll_zero = _shifted_roll(mt.roll, mate, reason, drive)
    arm = rho * np.abs(nt)
    normal_raw = normal_ease_off(eps_raw, lag, rho, nt, nr)
    valid = reason == 0
    pinion_working = working_sections(case.pinion.flank(pf).blade)
    smooth = (mate & gs.valid & np.isin(gs.section, working_sections(case.gear.flank(gf).blade))
              & np.isin(mt.section, pinion_working))
    pu, pv = np.where(mate, gm.u, np.nan), np.where(mate, gm.v, np.nan)
    kn = np.where(mate & gs.valid, kn / arm, np.nan)
    corner = _corner_nodes(reason, smooth, mt.section, pinion_working)
    eps_raw, q_raw, kn, pu, pv = _fill_corner_nodes(
        corner, gs.grid.v, eps_raw, q_raw, kn, pu, pv, section=mt.section,
        sheet=(reason == 0) | smooth)
    smooth |= corner
    return EaseOff(
        pinion_flank=pf, gear_flank=gf, u=gs.grid.u, v=gs.grid.v, axial=zt, radius=rt,
        ease_off=np.where(valid, normal_raw, np.nan),
        ease_off_angle=np.where(valid, eps_raw, np.nan),
        roll_angle=np.where(valid, q_raw, np.nan),
        raw_ease_off_angle=eps_raw, raw_roll_angle=q_raw, normal_arm=arm,
        gap_curvature=kn,
        gear_position=gs.position, gear_normal=gs.normal, pinion_axial=mt.z,
        pinion_radius=mt.rho, pinion_u=pu,
        pinion_v=pv, placement_error=np.where(mate, gm.error, np.nan),
        smooth=smooth, reason=reason, drive_sense=drive, lag_sense=lag, roll_zero=roll_zero,
        gear_phase=psi0, ratio=kin.ratio, pitch=2.0 * math.pi / case.pinion.blank.teeth,
        kinematics=kin, pinion_parameters=np.where(mate[..., None], mt.params, np.nan),
        pinion_section=mt.section,
        gear_parameters=np.stack([gs.s, gs.theta, gs.q], -1), gear_section=gs.section)


#: the most gear nodes in a row (along the profile) that a pinion blade corner's strip holds
#: (:func:`_corner_nodes`): two on the FM 16×16 at Σ 60° on 81 × 81, one on 41 × 21
MAX_CORNER_RUN = 3


def _corner_nodes(reason: np.ndarray, smooth: np.ndarray, pinion_section: np.ndarray,
                  working: list[int]) -> np.ndarray:
    """Gear nodes (nu, nv) without a mate whose conjugate lies on a corner of the pinion
    blade (the toprem or flankrem junction): runs of up to :data:`MAX_CORNER_RUN`
    ``no_conjugate_mate`` nodes along the profile direction between two nodes of the
    smooth sheet whose mates lie on two different working sections, with a second sheet
    node on the same section beyond at least one of them (:func:`_fill_corner_nodes`
    continues that side into the run).

    The corner's normal turns by the relief angle, so the gear points it touches (a strip
    along the corner line) have no mate on either section; which nodes fall in the strip
    depends on where the strip crosses the grid, so along the lengthwise direction a
    corner column alternates between mapped nodes and holes, and a fine grid holds more
    than one node of it in a row. A relief narrower than two profile steps holds a
    single sheet node between the corner and the pinion's tip (the FM 16×16 at Σ 60° on
    41 × 21: the tip relief's 10 % of the pinion profile between gear nodes 7 and 9).
    A hole left unfilled cut the contact region at the grid line beyond it (on that
    16×16 41 × 21 19 % of the pinion's profile short of its tip, 81 × 81 the relief's
    strip; issue 71).
    """
    out = np.zeros(reason.shape, dtype=bool)
    sheet = (reason == 0) | smooth
    sec = np.where(sheet, pinion_section, -1)
    nv = reason.shape[1]
    hole = reason == 2
    first = hole & ~np.pad(hole, ((0, 0), (1, 0)))[:, :-1]  # a run's first node
    for i, j0 in np.argwhere(first):
        j1 = j0
        while j1 + 1 < nv and hole[i, j1 + 1]:
            j1 += 1
        lo, hi = j0 - 1, j1 + 1
        if j1 - j0 + 1 > MAX_CORNER_RUN or lo < 0 or hi >= nv:
            continue
        if not (sheet[i, lo] and sheet[i, hi] and sec[i, lo] != sec[i, hi]
                and sec[i, lo] in working and sec[i, hi] in working):
            continue
        far_lo = lo >= 1 and sheet[i, lo - 1] and sec[i, lo - 1] == sec[i, lo]
        far_hi = hi + 1 < nv and sheet[i, hi + 1] and sec[i, hi + 1] == sec[i, hi]
        if far_lo or far_hi:
            out[i, j0:j1 + 1] = True
    return out


def _fill_corner_nodes(corner: np.ndarray, v: np.ndarray, eps: np.ndarray, q: np.ndarray,
                       *fields: np.ndarray, section: np.ndarray,
                       sheet: np.ndarray) -> tuple[np.ndarray, ...]:
    """The angular ease-off ε [rad], roll Q [rad] and ``fields`` at the corner nodes of
    :func:`_corner_nodes`, from the sheet nodes bounding each run along the profile
    direction.

    ε: the larger of the two sections' ε continued linearly from their two nodes — the
    separation from a convex corner is the larger of the separations from its faces'
    tangent planes (first order in the grid step); where one side holds a single sheet
    node (``sheet``, ``section``, (nu, nv): the nodes of the smooth sheet and their mates'
    pinion sections), the other side's continuation alone (a lower bound of the two
    faces' larger separation, first order in the grid step as well). The other fields (Q,
    the gap curvature, the pinion fractions), continuous across the corner, are
    interpolated linearly between the two bounding nodes. Without this the spline of ε
    filled the hole from the sheet's far side (up to 65 µrad above the corner's ε on the
    default case at ΔE = ΔP = −0.12 mm) next to mapped corner nodes, and the UTE
    zig-zagged.
    """
    eps, q = eps.copy(), q.copy()
    fields = tuple(f.copy() for f in fields)
    for i, j in np.argwhere(corner):
        lo, hi = j - 1, j + 1
        while corner[i, lo]:
            lo -= 1
        while corner[i, hi]:
            hi += 1

        def along(f, k0, k1, i=i, j=j):
            return f[i, k1] + (f[i, k1] - f[i, k0]) * (v[j] - v[k1]) / (v[k1] - v[k0])
        sides = [along(eps, k0, k1) for k0, k1 in ((lo - 1, lo), (hi + 1, hi))
                 if 0 <= k0 < len(v) and sheet[i, k0] and section[i, k0] == section[i, k1]]
        eps[i, j] = max(sides)
        for f in (q, *fields):
            f[i, j] = along(f, lo, hi)
    return (eps, q, *fields)


def _grid_options(grid: dict | None) -> dict:
    """The gear grid of :func:`ease_off`: :data:`geometry.machine.flank.DEFAULT_GRID` updated by
    ``grid`` (InputError for an unknown key)."""
    g = dict(DEFAULT_GRID)
    if grid:
        unknown = sorted(set(grid) - set(g))
        if unknown:
            raise InputError(f"grid: must have keys from {sorted(g)}, got unknown keys "
                             f"{unknown}")
        g.update(grid)
    return g


def _node_reasons(gm: GearMates, mate: np.ndarray, gear_valid: np.ndarray) -> np.ndarray:
    """(nu, nv) int8 reason codes (:data:`EASEOFF_REASONS`) of the gear nodes, folds not yet
    masked; InputError if no node is valid."""
    reason = np.zeros(mate.shape, dtype=np.int8)
    reason[~mate] = 2
    reason[~mate & gm.pinned] = 3  # Newton ran to the edge of the extended pinion grid
    reason[~gear_valid] = 1
    inside = (gm.u >= 0) & (gm.u <= 1) & (gm.v >= 0) & (gm.v <= 1)
    reason[(reason == 0) & ~inside] = 3
    if not np.any(reason == 0):
        raise InputError("case: no gear grid node can be touched by the pinion (the blanks do "
                         "not overlap on the surface of action; check the misalignment)")
    n_bad = {EASEOFF_REASONS[c]: int((reason == c).sum()) for c in (1, 2, 3)}
    log.info("ease_off: %d of %d gear nodes valid (%s)", int((reason == 0).sum()), reason.size,
             ", ".join(f"{k}: {v}" for k, v in n_bad.items() if v))
    return reason


def _drive_sense(kin: MeshKinematics, mt: Mates, mate: np.ndarray) -> int:
    """s_p: the sign of the pinion rotation that drives its flank (module docstring, "Signs"),
    the median over the placed mates of the meshing coefficient c₁ = a_p·((r − O_p) × n)."""
    r0, n0 = to_pair_frame(kin, mt.position[mate], mt.normal[mate])
    c1, *_ = meshing_coefficients(kin, r0, n0)
    return 1 if np.median(c1) > 0 else -1


def _polar_normal(position: np.ndarray, normal: np.ndarray):
    """ρ [mm] of gear-frame points (..., 3) and their normals' components n·e_θ, n·e_ρ [1]
    along the polar directions about the gear axis."""
    pg, ng = position, normal
    rho = np.hypot(pg[..., 0], pg[..., 1])
    e_t = np.stack([-pg[..., 1], pg[..., 0], np.zeros_like(rho)], -1) / rho[..., None]
    e_r = np.stack([pg[..., 0], pg[..., 1], np.zeros_like(rho)], -1) / rho[..., None]
    return rho, np.einsum("...i,...i", ng, e_t), np.einsum("...i,...i", ng, e_r)


def _angular_ease_off(gs, conj: np.ndarray, mate: np.ndarray, reason: np.ndarray, lag: int,
                      nt: np.ndarray, nr: np.ndarray, rho: np.ndarray):
    """ε ≥ 0 [rad] on the valid nodes (NaN where no mate) and the gear phase ψ₀ [rad].

    ε is the lag the real gear needs to reach the conjugate point at its node's (z, ρ),
    shifted so that its least over the valid nodes is zero; the real gear turned by s_g ψ₀
    touches the conjugate (built with ψ₀ = 0) there. The conjugate's polar angle is carried
    from its place to the node with the slope of the (tangent) gear surface,
    dθ = −(n_z dz + n_ρ dρ)/(ρ n_θ): the residual placement (< 1e-7 mm) then enters only at
    second order.
    """
    pg, ng = gs.position, gs.normal
    nz = ng[..., 2]
    dz = gs.grid.axial - conj[..., 2]
    drho = gs.grid.radius - np.hypot(conj[..., 0], conj[..., 1])
    theta_c = np.arctan2(conj[..., 1], conj[..., 0]) - (nz * dz + nr * drho) / (rho * nt)
    theta_r = np.arctan2(pg[..., 1], pg[..., 0])
    diff = np.where(mate & gs.valid, lag * (theta_c - theta_r), np.nan)
    ref_diff = np.nanmedian(diff[reason == 0])
    diff = ref_diff + np.remainder(diff - ref_diff + np.pi, 2 * np.pi) - np.pi
    shift = np.nanmin(diff[reason == 0])
    return diff - shift, float(lag * shift)


def _shifted_roll(roll: np.ndarray, mate: np.ndarray, reason: np.ndarray, drive: int):
    """Q ≥ 0 [rad] (driving sense, least over the valid nodes zero; NaN where no mate) and
    the pinion rotation ``roll_zero`` [rad] at Q = 0."""
    q_raw = np.where(mate, drive * roll, np.nan)
    q_min = np.nanmin(q_raw[reason == 0])
    return q_raw - q_min, float(drive * q_min)


def normal_ease_off(angle, lag_sense: int, radius, normal_theta, normal_rho):
    """Normal ease-off: distance from the real gear to the touching conjugate point.

    Parameters
    ----------
    angle : array_like — [rad]
        Angular ease-off ε ≥ 0 (gear lag).
    lag_sense : {+1, −1}
        s_g (module docstring, "Signs").
    radius : array_like — [mm]
        ρ of the real gear point.
    normal_theta, normal_rho : array_like — [1]
        Components n·e_θ, n·e_ρ of the gear's unit normal along the polar directions.

    Returns
    -------
    ndarray — [mm]
        ρ [sin(s_g ε)(n·e_θ) + (cos ε − 1)(n·e_ρ)] ≥ 0 (broadcast shape): the chord of the
        rotation along the gear normal.

    Notes
    -----
    Seed §4.2 ("radial distance" between the real gear and its conjugate, read as the
    distance along the gear normal); the chord's distance to the curved surface differs by
    ½κ d_t² (module docstring).
    """
    eps_s = lag_sense * angle
    return radius * (np.sin(eps_s) * normal_theta + (np.cos(eps_s) - 1.0) * normal_rho)
