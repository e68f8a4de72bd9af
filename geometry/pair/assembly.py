"""Pinion and gear in one global frame, with misalignments (seed §2.3.1, Eq. 2.14).

Global (pair) frame S_f
-----------------------
Origin at the gear's crossing point; z_f along the gear axis from its apex side into the
gear body (the gear's own z); the pinion axis lies in the plane y_f = y_E and points along
z_p = (sin Σ, 0, cos Σ) from its apex side into the pinion body; x_p = (−cos Σ, 0, sin Σ),
y_p = (0, −1, 0). With these axes the mesh zone lies on the +x side of both members (where
each member's reference tooth is cut, see :mod:`geometry.machine.cradle`) and the pinion crossing
point is at (0, y_E, 0).

Offset: y_E = h (E + ΔE) with h = +1 when the gear is right-hand, −1 when left-hand, so a
positive offset E is the ISO 23509 sign (the pinion's mean spiral angle exceeds the
gear's; "below centre" for a left-hand pinion). Mirroring the whole pair in y_f swaps
both hands and mirrors each member in its own frame (y → −y), consistent with
:mod:`geometry.machine.cradle`.

Misalignments, in the Gleason V–H check convention as we know it (Krenzer 1981,
"Understanding Tooth Contact Analysis", seed ref. 2.2; Stadtfeld 1993, "Handbook of Bevel
and Hypoid Gears"; not checked against the originals):
ΔE (V) increases the offset; ΔP (H) moves the pinion along its axis away from the mesh
(increasing its mounting distance), i.e. along +z_p; ΔG moves the gear along +z_f (away
from the mesh); ΔΣ increases the shaft angle by turning the pinion axis about the offset
line (y_f direction) through the pinion crossing point.

Rotations: a member turned by φ about its own +z axis (right-hand rule). Two meshing
members turn with opposite signs in these axes: φ_g = −(z_p/z_g) φ_p for pure rolling.

Public functions
----------------
Misalignment        frozen dataclass ΔE, ΔP, ΔG [mm], ΔΣ [rad]
member_transform    4×4 member → global transform (batched over rotation angles)
case_transforms     both transforms for a Case
transform_points    apply a 4×4 transform to points
transform_vectors   apply its rotation to vectors (normals, directions)
rotate_about_axis   Rodrigues rotation of vectors about a unit axis
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from geometry.core.errors import InputError
from geometry.core.validation import real
from geometry.core.vectors import cross

__all__ = [
    "HANDS",
    "MEMBERS",
    "Misalignment",
    "case_transforms",
    "member_transform",
    "rotate_about_axis",
    "transform_points",
    "transform_vectors",
]

HANDS: dict[str, int] = {"right": 1, "left": -1}
MEMBERS = ("pinion", "gear")


@dataclass(frozen=True)
class Misalignment:
    """Assembly misalignments (Gleason V–H check convention, see module docstring).

    Parameters
    ----------
    delta_E : float — [mm]
        Change of the hypoid offset (V); positive increases it.
    delta_P : float — [mm]
        Pinion axial displacement (H); positive away from the mesh.
    delta_G : float — [mm]
        Gear axial displacement; positive away from the mesh.
    delta_Sigma : float — [rad]
        Change of the shaft angle; positive increases it; abs(ΔΣ) < 10°.

    Raises
    ------
    InputError
        A value is not finite or ΔΣ is out of range.
    """

    delta_E: float = 0.0
    delta_P: float = 0.0
    delta_G: float = 0.0
    delta_Sigma: float = 0.0

    def __post_init__(self) -> None:
        for name in ("delta_E", "delta_P", "delta_G", "delta_Sigma"):
            object.__setattr__(self, name, real(name, getattr(self, name)))
        if abs(self.delta_Sigma) >= math.radians(10.0):
            raise InputError(
                f"delta_Sigma: must be in (-10, 10) deg, got {math.degrees(self.delta_Sigma):.6g}")

    def plus(self, other: Misalignment) -> Misalignment:
        """This mounting displaced by ``other``, component by component (an excursion or a
        deflection taken from an assembly's own misalignment, as the V-H check takes it).

        Parameters
        ----------
        other : Misalignment
            The displacement: ΔE, ΔP, ΔG [mm], ΔΣ [rad].

        Returns
        -------
        Misalignment
            The sums of the four components.

        Raises
        ------
        InputError
            The summed ΔΣ out of range (the constructor's check).
        """
        return Misalignment(delta_E=self.delta_E + other.delta_E,
                            delta_P=self.delta_P + other.delta_P,
                            delta_G=self.delta_G + other.delta_G,
                            delta_Sigma=self.delta_Sigma + other.delta_Sigma)

    def labelled(self) -> dict[str, float]:
        """The misalignment as stored in files and printed: names that carry their units.

        Returns
        -------
        dict
            ``delta_E_mm``, ``delta_P_mm``, ``delta_G_mm`` [mm] and ``delta_Sigma_deg``
            [deg] (degrees at every boundary: case files, the command line, result files;
            radians only inside, in this dataclass).
        """
        return {"delta_E_mm": float(self.delta_E), "delta_P_mm": float(self.delta_P),
                "delta_G_mm": float(self.delta_G),
                "delta_Sigma_deg": math.degrees(float(self.delta_Sigma))}


def _rot_z(phi) -> np.ndarray:
    phi = np.asarray(phi, dtype=float)
    m = np.zeros((*phi.shape, 4, 4))
    c, s = np.cos(phi), np.sin(phi)
    m[..., 0, 0] = c
    m[..., 0, 1] = -s
    m[..., 1, 0] = s
    m[..., 1, 1] = c
    m[..., 2, 2] = m[..., 3, 3] = 1.0
    return m


def member_transform(member: str, *, shaft_angle: float, offset: float, gear_hand: str,
                     rotation=0.0, misalignment: Misalignment | None = None) -> np.ndarray:
    """Homogeneous transform from a member's frame to the global pair frame.

    Parameters
    ----------
    member : str
        ``"pinion"`` or ``"gear"``.
    shaft_angle : float — [rad]
        Σ, in (0, π).
    offset : float — [mm]
        Hypoid offset E (ISO 23509 sign).
    gear_hand : str
        ``"right"`` or ``"left"``: fixes the side of the offset.
    rotation : float or array_like — [rad]
        Rotation of the member about its own +z axis.
    misalignment : Misalignment, optional

    Returns
    -------
    ndarray, shape rotation.shape + (4, 4)
        T with r_global = T · [r_member, 1].

    Raises
    ------
    InputError
        For an unknown member or hand, or a shaft angle outside (0, π).

    Notes
    -----
    Seed Eq. 2.14 places the rotated pinion and gear surfaces with the offset vector OE;
    the axes and signs are this toolkit's (module docstring).
    """
    if member not in MEMBERS:
        raise InputError(f"member: must be one of {list(MEMBERS)}, got {member!r}")
    if gear_hand not in HANDS:
        raise InputError(f"gear_hand: must be one of {sorted(HANDS)}, got {gear_hand!r}")
    if not 0.0 < shaft_angle < math.pi:
        raise InputError(
            f"shaft_angle: must be in (0, 180) deg, got {math.degrees(shaft_angle):.6g}")
    mis = misalignment if misalignment is not None else Misalignment()
    place = np.eye(4)
    if member == "gear":
        place[2, 3] = mis.delta_G
    else:
        sig = shaft_angle + mis.delta_Sigma
        c, s = math.cos(sig), math.sin(sig)
        place[:3, 0] = (-c, 0.0, s)
        place[:3, 1] = (0.0, -1.0, 0.0)
        place[:3, 2] = (s, 0.0, c)
        y_e = HANDS[gear_hand] * (offset + mis.delta_E)
        place[:3, 3] = np.array([0.0, y_e, 0.0]) + mis.delta_P * place[:3, 2]
    return place @ _rot_z(rotation)


def case_transforms(case, pinion_rotation=0.0, gear_rotation=0.0,
                    misalignment: Misalignment | None = None):
    """Member → global transforms of both members of a case.

    Parameters
    ----------
    case : geometry.case.Case
    pinion_rotation, gear_rotation : float or array_like — [rad]
    misalignment : Misalignment, optional
        Defaults to the case's own ``misalignment``.

    Returns
    -------
    (T_pinion, T_gear) : tuple of ndarray (..., 4, 4)
    """
    mis = case.misalignment if misalignment is None else misalignment
    kw = dict(shaft_angle=case.pair.shaft_angle, offset=case.pair.offset,
              gear_hand=case.gear.hand, misalignment=mis)
    return (member_transform("pinion", rotation=pinion_rotation, **kw),
            member_transform("gear", rotation=gear_rotation, **kw))


def transform_points(transform, points) -> np.ndarray:
    """Apply a homogeneous transform to points.

    Parameters
    ----------
    transform : array_like (..., 4, 4)
    points : array_like (..., 3) — [mm]

    Returns
    -------
    ndarray (..., 3) — [mm]
    """
    t = np.asarray(transform, dtype=float)
    p = np.asarray(points, dtype=float)
    return np.einsum("...ij,...j->...i", t[..., :3, :3], p) + t[..., :3, 3]


def transform_vectors(transform, vectors) -> np.ndarray:
    """Apply the rotation of a homogeneous transform to vectors (normals, directions).

    Parameters
    ----------
    transform : array_like (..., 4, 4)
    vectors : array_like (..., 3)

    Returns
    -------
    ndarray (..., 3)
    """
    t = np.asarray(transform, dtype=float)
    return np.einsum("...ij,...j->...i", t[..., :3, :3], np.asarray(vectors, dtype=float))


def rotate_about_axis(axis: np.ndarray, angle, v: np.ndarray) -> np.ndarray:
    """Rodrigues rotation of vectors about a unit axis through the origin.

    Parameters
    ----------
    axis : ndarray (3,) — [1]
        Unit rotation axis (not checked: callers pass a member's axis).
    angle : float or ndarray (...) — [rad]
        Right-handed rotation angle, broadcast against ``v``'s leading axes.
    v : ndarray (..., 3)
        Vectors (or points relative to a point of the axis).

    Returns
    -------
    ndarray (..., 3)
        v cos θ + (a × v) sin θ + a (a·v)(1 − cos θ).

    Notes
    -----
    Rodrigues' rotation formula; points about an axis through O: O + R(p − O).

    An ``angle`` of v's leading shape that is a broadcast view (``np.broadcast_to``: one
    angle per curve for all its points) has its cosine and sine taken once per distinct
    angle and kept broadcast through the products (the same numbers, element by element;
    ~4× faster on the LTCA's (rolls, pairs, points) arrays, issue 75).
    """
    angle = _compact(angle, np.shape(v)[:-1])
    c = np.cos(angle)[..., None]
    s = np.sin(angle)[..., None]
    return v * c + cross(axis, v) * s + axis * (v @ axis)[..., None] * (1.0 - c)


def _compact(angle, lead: tuple):
    """``angle`` with each axis it is broadcast along (stride 0) cut to length 1, where it
    has the shape ``lead`` (so it still broadcasts to the same result); else itself."""
    if (type(angle) is np.ndarray and angle.ndim and angle.shape == lead
            and 0 in angle.strides):
        return angle[tuple(slice(0, 1) if st == 0 else slice(None) for st in angle.strides)]
    return angle
