"""Step 3 of the synthesis: the mesh position of the gear's mean point M.

The mean point M of each pinion flank (:func:`geometry.pair.design_point.design_point`) on
the gear flank at the mean cone distance, centred in roll within the working depth, turned
with the gear to where it lies on the surface of action of the ideal motion
(n·v⁽¹²⁾ = 0 at the ratio z1/z2). For the coast flank the pinion is turned so that the
normal backlash at M is the ISO mean normal backlash j_mn.

Public functions
----------------
MeanPoint    M, its normal and the gear's shape operator there, in the pair frame
mean_point   mesh position of the gear mean point (surface of action)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from geometry.case import Blank
from geometry.core.errors import InputError
from geometry.machine.flank_point import FlankPoint
from geometry.pair.assembly import member_transform
from geometry.pair.design_point import (
    action_rotation,
)
from geometry.synthesis.gear import unit

__all__ = [
    "MeanPoint",
    "mean_point",
]

# --------------------------------------------------------------------------- mean point
@dataclass(frozen=True, eq=False)
class MeanPoint:
    """Design point M of one pinion flank in the pair frame (nominal assembly).

    Attributes
    ----------
    pinion_flank : str
    point : ndarray (3,) — [mm]
        M in the pair frame.
    normal : ndarray (3,) — [1]
        Pinion normal at M (out of the pinion material) = −gear normal.
    gear_shape : ndarray (3, 3) — [1/mm]
        Shape operator of the gear flank at M in the pair frame (w.r.t. its own outward
        normal −normal).
    profile, lengthwise : ndarray (3,) — [1]
        Gear flank directions at M: along the blade (root → tip) and n_g × profile oriented
        toe → heel.
    pinion_rotation, gear_rotation : float — [rad]
        Member rotations (right-handed about their own +z) of the design position.
    pinion_sense, gear_sense : int
        Senses of motion when this pinion flank drives.
    gear_projection : ndarray (2,) — [mm]
        (z, ρ) of M in the gear projection plane.
    """

    pinion_flank: str
    point: np.ndarray
    normal: np.ndarray
    gear_shape: np.ndarray
    profile: np.ndarray
    lengthwise: np.ndarray
    pinion_rotation: float
    gear_rotation: float
    pinion_sense: int
    gear_sense: int
    gear_projection: np.ndarray


def pair_kw(shaft_angle: float, offset: float, gear_hand: str) -> dict[str, Any]:
    """The pair keywords of :func:`geometry.pair.assembly.member_transform` (Σ [rad], E [mm],
    the gear's hand)."""
    return dict(shaft_angle=shaft_angle, offset=offset, gear_hand=gear_hand)


def mean_point(gear_point: FlankPoint, gear_blank: Blank, pinion_blank: Blank, *,
               pinion_flank: str, shaft_angle: float, offset: float, gear_hand: str,
               pinion_rotation: float = 0.0, backlash: float = 0.0,
               reference_gear_rotation: float | None = None) -> MeanPoint:
    """Mesh position of the mean contact point M: on the surface of action of the pair.

    Parameters
    ----------
    gear_point : FlankPoint
        The gear flank at M (gear frame, unbatched;
        :func:`geometry.machine.flank_point.flank_points` of the gear tool at :func:`design_point`).
    gear_blank, pinion_blank : geometry.case.Blank
    pinion_flank : str
        The pinion flank that meshes this gear flank.
    shaft_angle : float — [rad]
    offset : float — [mm]
    gear_hand : str
    pinion_rotation : float — [rad]
        Pinion rotation of the design position (0 for the first flank synthesised).
    backlash : float — [mm]
        Normal backlash at M (second flank only; 0 otherwise).
    reference_gear_rotation : float, optional — [rad]
        Gear rotation of the first flank's design position at pinion rotation 0. Given, the
        pinion rotation of this flank's design position follows from the ideal motion
        φ_g = φ_g,ref − (z1/z2) φ_p and the backlash (``pinion_rotation`` is ignored).

    Returns
    -------
    MeanPoint

    Raises
    ------
    InputError
        If the gear point never crosses the surface of action in the mesh zone.

    Notes
    -----
    Surface of action of the ideal motion (Litvin & Fuentes 2004, ch. 6; seed Eq. 2.19 with
    R = z2/z1): n · v⁽¹²⁾ = 0, v⁽¹²⁾ = ω₁ × (r − o₁) − ω₂ × (r − o₂) with the members turning
    in opposite senses about their own axes at the ratio z1/z2. The gear rotation is found by
    a scan over the mesh zone (x_f > 0) and Brent's method; of several crossings the one
    whose pinion projection is nearest the pinion's mean point is taken.
    """
    kw = pair_kw(shaft_angle, offset, gear_hand)
    ratio = pinion_blank.teeth / gear_blank.teeth
    phi_g = float(action_rotation(gear_point.r[None], gear_point.n[None], pinion_blank,
                                  gear_blank, **kw)[0])
    if not math.isfinite(phi_g):
        raise InputError("synthesis: the gear mean point never meets the surface of action in "
                         "the mesh zone; check the blanks and the offset")
    tp = member_transform("pinion", **kw)
    a_p, o_p = tp[:3, 2], tp[:3, 3]
    tg = member_transform("gear", rotation=phi_g, **kw)
    r = tg[:3, :3] @ gear_point.r + tg[:3, 3]
    n = -(tg[:3, :3] @ gear_point.n)
    s_p = int(np.sign(np.cross(a_p, r - o_p) @ n))
    s_g = int(np.sign(np.cross(tg[:3, 2], r - tg[:3, 3]) @ n))
    if reference_gear_rotation is not None:
        # ideal motion with the first flank: φ_g − φ_g,ref = −(z1/z2) φ_p; the backlash turns
        # the pinion further in this flank's sense of motion (the surface of action does not
        # depend on the pinion rotation, so φ_g stays)
        lever = abs(np.cross(a_p, r - o_p) @ n)
        pinion_rotation = -(phi_g - reference_gear_rotation) / ratio + s_p * backlash / lever
    rot = tg[:3, :3]
    prof = rot @ gear_point.r_s
    length = unit(np.cross(-n, prof))
    # toe → heel: along the gear pitch generatrix away from the apex
    psi = math.atan2(gear_point.r[1], gear_point.r[0])
    gd = gear_blank.pitch_angle
    gen = rot @ np.array([math.sin(gd) * math.cos(psi), math.sin(gd) * math.sin(psi),
                          math.cos(gd)])
    if length @ gen < 0:
        length = -length
    return MeanPoint(pinion_flank=pinion_flank, point=r, normal=n,
                     gear_shape=rot @ gear_point.shape @ rot.T, profile=prof,
                     lengthwise=length, pinion_rotation=pinion_rotation, gear_rotation=phi_g,
                     pinion_sense=s_p, gear_sense=s_g,
                     gear_projection=np.array([gear_point.r[2],
                                               math.hypot(gear_point.r[0], gear_point.r[1])]))
