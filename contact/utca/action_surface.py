"""The surface of action of the ideal motion and the conjugate points (seed Eq. 2.19–2.20).

The kinematics of a mounted pair (axes, crossing points, ratio; misalignments included)
and, for points of the real pinion flank with their normals, the pinion rotation at which
each lies on the surface of action (its roll angle), its place there and its image on the
pinion's conjugate gear. :mod:`contact.utca.easeoff` builds the surface of roll angle and
the ease-off on them.

Conjugacy condition (our reading of Eq. 2.19)
----------------------------------------------
In the pair frame of :mod:`geometry.pair.assembly` the members turn with opposite signs,
φ_g = −φ_p / R with R = z_g / z_p. The relative velocity of the pinion with respect to the
gear at a point r per unit pinion rotation is
v₁₂ = a_p × (r − O_p) + (1/R) a_g × (r − O_g), and the equation of meshing n·v₁₂ = 0
(Litvin & Fuentes 2004, §6.1, crossed axes) reads

    R · a_p·((r − O_p) × n) + a_g·((r − O_g) × n) = 0.

The extracted seed prints R (a_p·r×n) = (a_g·r×n): the same relation with both position
vectors taken from the respective crossing points and the gear rotation counted in the
opposite sense. The first term is invariant under rotation about the pinion axis; the
second is A + B cos φ + C sin φ (Rodrigues' formula), so the roll angle of every point is
found **in closed form**: φ = α ± arccos(−(R c₁ + A)/√(B² + C²)), α = atan2(C, B). The
sign of the arccos selects the branch on which ∂(n·v₁₂)/∂φ has one sign; the branch whose
action points lie nearest to the gear flank is the mesh zone (the other one is half a turn
away).

Public functions
----------------
MeshKinematics         axes, crossing points, ratio and placements of the two members
mesh_kinematics        build them for a case (with misalignments, optional phases)
to_pair_frame          pinion-frame points and normals into the pair frame
meshing_coefficients   coefficients of the equation of meshing in the pinion rotation
action_roll_angle      closed-form roll angle of pinion points (Eq. 2.19)
action_surface         roll angle, action-surface points and normals in the pair frame
conjugate_points       conjugate-gear points in the gear frame (Eq. 2.20)

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009 (the seed), §2.3.2, §4.2.
F. L. Litvin, A. Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §6.1.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from geometry.core.errors import InputError
from geometry.core.validation import one_of, real
from geometry.core.vectors import cross
from geometry.pair.assembly import Misalignment, case_transforms, rotate_about_axis

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "MeshKinematics",
    "action_roll_angle",
    "action_surface",
    "conjugate_points",
    "mesh_kinematics",
    "meshing_coefficients",
    "to_pair_frame",
]


# --------------------------------------------------------------------------- kinematics
@dataclass(frozen=True)
class MeshKinematics:
    """Axes of the two members in the pair frame (see :mod:`geometry.pair.assembly`).

    Parameters
    ----------
    pinion_place, gear_place : ndarray (4, 4)
        Member → pair transforms at zero rotation (misalignments and phases included).
    ratio : float — [1]
        R = z_g / z_p.
    """

    pinion_place: np.ndarray
    gear_place: np.ndarray
    ratio: float

    @property
    def pinion_axis(self) -> np.ndarray:
        """Unit pinion axis a_p in the pair frame [1]."""
        return self.pinion_place[:3, 2]

    @property
    def pinion_origin(self) -> np.ndarray:
        """Pinion crossing point O_p in the pair frame [mm]."""
        return self.pinion_place[:3, 3]

    @property
    def gear_axis(self) -> np.ndarray:
        """Unit gear axis a_g in the pair frame [1]."""
        return self.gear_place[:3, 2]

    @property
    def gear_origin(self) -> np.ndarray:
        """Gear crossing point O_g in the pair frame [mm]."""
        return self.gear_place[:3, 3]


def mesh_kinematics(case: Case, misalignment: Misalignment | None = None, *,
                    pinion_phase: float = 0.0, gear_phase: float = 0.0) -> MeshKinematics:
    """Axes, crossing points and ratio of a case in the pair frame.

    Parameters
    ----------
    case : geometry.case.Case
    misalignment : geometry.pair.assembly.Misalignment, optional
        ΔE, ΔP, ΔG [mm], ΔΣ [rad]; defaults to the case's own.
    pinion_phase, gear_phase : float — [rad]
        Rigid rotation of each member's teeth about its own axis before assembly (tooth
        indexing); the ease-off and the shape of Q do not depend on them.

    Returns
    -------
    MeshKinematics

    Raises
    ------
    InputError
        For non-finite phases (and as :func:`geometry.pair.assembly.case_transforms`).

    Notes
    -----
    Seed Eq. 2.14 (placement with the offset vector OE); frames of
    :mod:`geometry.pair.assembly`.
    """
    pinion_phase = real("pinion_phase", pinion_phase, unit="rad")
    gear_phase = real("gear_phase", gear_phase, unit="rad")
    tp, tg = case_transforms(case, pinion_phase, gear_phase, misalignment)
    return MeshKinematics(np.array(tp), np.array(tg),
                          case.gear.blank.teeth / case.pinion.blank.teeth)


def to_pair_frame(kin: MeshKinematics, position, normal):
    """Pinion-frame points and normals into the pair frame at zero pinion rotation.

    Parameters
    ----------
    kin : MeshKinematics
    position, normal : array_like (..., 3) — [mm], [1]
        Pinion points and unit normals in the pinion frame.

    Returns
    -------
    r0, n0 : ndarray (..., 3) — [mm], [1]
        In the pair frame (:mod:`geometry.pair.assembly`).

    Raises
    ------
    InputError
        Unless both have the same shape (..., 3).
    """
    p = np.asarray(position, dtype=float)
    n = np.asarray(normal, dtype=float)
    if p.shape != n.shape or p.shape[-1:] != (3,):
        raise InputError(f"position, normal: must have equal shapes (..., 3), got {p.shape} "
                         f"and {n.shape}")
    rot = kin.pinion_place[:3, :3]
    return p @ rot.T + kin.pinion_origin, n @ rot.T


def meshing_coefficients(kin: MeshKinematics, r0: np.ndarray, n0: np.ndarray):
    """Coefficients of the equation of meshing in the pinion rotation φ (seed Eq. 2.19).

    Parameters
    ----------
    kin : MeshKinematics
    r0, n0 : ndarray (..., 3) — [mm], [1]
        Pinion points and unit normals in the pair frame at zero pinion rotation
        (:func:`to_pair_frame`).

    Returns
    -------
    c1, a, b, c : ndarray (...) — [mm]
        R c₁ + A + B cos φ + C sin φ = 0 is the conjugacy condition of the point turned by
        φ about the pinion axis; c₁ = a_p·((r − O_p) × n) does not change with φ.

    Notes
    -----
    Module docstring ("Conjugacy condition"): the gear term a_g·((r − O_g) × n) of the
    turned point by Rodrigues' formula; Litvin & Fuentes 2004, §6.1.
    """
    a = kin.pinion_axis
    ag = kin.gear_axis
    w0 = r0 - kin.pinion_origin
    m0 = cross(w0, n0)
    c1 = m0 @ a
    k = cross(ag, kin.pinion_origin - kin.gear_origin)
    ka, aga = float(k @ a), float(ag @ a)
    na, ma = n0 @ a, m0 @ a
    b = (n0 @ k - ka * na) + (m0 @ ag - aga * ma)
    c = cross(a, n0) @ k + cross(a, m0) @ ag
    a0 = ka * na + aga * ma
    return c1, a0, b, c


def action_roll_angle(kin: MeshKinematics, position, normal, *, branch: int | None = None,
                      reference=None):
    """Pinion rotation that brings each pinion point onto the surface of action (Eq. 2.19).

    Parameters
    ----------
    kin : MeshKinematics
    position : array_like (..., 3) — [mm]
        Pinion surface points in the pinion frame (NaN allowed).
    normal : array_like (..., 3) — [1]
        Their unit normals (out of the pinion material).
    branch : {+1, −1}, optional
        Sign of the arccos root; by default the branch whose action points lie nearest
        (median distance) to ``reference`` in the gear's axial section, i.e. in axial
        position along and distance from the gear axis (the place on the gear projection
        plane where their conjugate gear points lie; a rotation about the gear axis does not
        change it). A distance in space would also weigh where around the gear axis the
        point lies and picks the wrong root for large offsets (e.g. the coast flank of the
        seed's 45 mm offset pair of Table 4.3).
    reference : array_like (3,), optional — [mm]
        A point of the gear flank in the pair frame that marks the mesh zone; required
        when ``branch`` is not given.

    Returns
    -------
    roll : ndarray (...) — [rad]
        Pinion rotation φ_p about +a_p in (−π, π]; NaN where the point never meets the
        surface of action.
    branch : int
        The branch used.

    Raises
    ------
    InputError
        For mismatched shapes, or neither ``branch`` nor ``reference``.

    Notes
    -----
    Seed Eq. 2.19 / 4.1 in the form R a_p·((r − O_p) × n) + a_g·((r − O_g) × n) = 0
    (module docstring: the opposite rotation senses of the pair frame give the plus sign;
    Litvin & Fuentes 2004, §6.1), solved in closed form.
    """
    r0, n0 = to_pair_frame(kin, position, normal)
    c1, a0, b, c = meshing_coefficients(kin, r0, n0)
    amp = np.hypot(b, c)
    with np.errstate(invalid="ignore", divide="ignore"):
        arg = -(kin.ratio * c1 + a0) / amp
    ok = np.isfinite(arg) & (np.abs(arg) <= 1.0)
    beta = np.arccos(np.clip(np.where(ok, arg, 0.0), -1.0, 1.0))
    alpha = np.arctan2(c, b)

    def roots(sign):
        phi = np.remainder(alpha + sign * beta + np.pi, 2.0 * np.pi) - np.pi
        return np.where(ok, phi, np.nan)

    if branch is None:
        if reference is None:
            raise InputError("reference: must be a gear-flank point (3,) [mm] when branch is "
                             "not given, got None")
        ag, og = kin.gear_axis, kin.gear_origin

        def section(r):  # (axial position, radius) about the gear axis
            rel = np.asarray(r, dtype=float) - og
            z = rel @ ag
            return np.stack([z, np.linalg.norm(rel - z[..., None] * ag, axis=-1)], -1)

        ref = section(reference)
        dist = {}
        for sign in (1, -1):
            phi = roots(sign)
            ra = kin.pinion_origin + rotate_about_axis(kin.pinion_axis, phi, r0 - kin.pinion_origin)
            d = np.linalg.norm(section(ra) - ref, axis=-1)
            dist[sign] = np.nanmedian(d) if np.isfinite(d).any() else np.inf
        branch = 1 if dist[1] <= dist[-1] else -1
    else:
        one_of("branch", branch, (1, -1))
    return roots(branch), int(branch)


def action_surface(kin: MeshKinematics, position, normal, roll):
    """Action-surface points and normals: pinion points turned by their roll angle.

    Parameters
    ----------
    kin : MeshKinematics
    position, normal : array_like (..., 3) — [mm], [1]
        Pinion points and unit normals in the pinion frame.
    roll : array_like (...) — [rad]
        Pinion rotation of each point (e.g. from :func:`action_roll_angle`).

    Returns
    -------
    points, normals : ndarray (..., 3) — [mm], [1]
        In the pair frame.

    Raises
    ------
    InputError
        For mismatched shapes.

    Notes
    -----
    Seed Eq. 2.19: the action surface r_a is the locus of the turned points.
    """
    r0, n0 = to_pair_frame(kin, position, normal)
    phi = np.asarray(roll, dtype=float)
    ra = kin.pinion_origin + rotate_about_axis(kin.pinion_axis, phi, r0 - kin.pinion_origin)
    return ra, rotate_about_axis(kin.pinion_axis, phi, n0)


def conjugate_points(kin: MeshKinematics, position, normal, roll, gear_phase: float = 0.0):
    """Conjugate-gear points: action points turned back with the gear (Eq. 2.20, 4.2a).

    Parameters
    ----------
    kin : MeshKinematics
    position, normal : array_like (..., 3) — [mm], [1]
        Pinion points and normals in the pinion frame.
    roll : array_like (...) — [rad]
        Their roll angles φ_p.
    gear_phase : float — [rad]
        Gear rotation ψ₀ at φ_p = 0; the kinematic gear rotation is ψ = ψ₀ − φ_p / R.

    Returns
    -------
    points, normals : ndarray (..., 3) — [mm], [1]
        In the gear frame (gear at zero rotation).
    """
    ra, na = action_surface(kin, position, normal, roll)
    psi = gear_phase - np.asarray(roll, dtype=float) / kin.ratio
    ag, og = kin.gear_axis, kin.gear_origin
    back = rotate_about_axis(ag, -psi, ra - og)
    nb = rotate_about_axis(ag, -psi, na)
    rot = kin.gear_place[:3, :3]
    return back @ rot, nb @ rot
