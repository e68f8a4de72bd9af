"""The largest blade edge radius a design's slots and clearance allow (issue 71: the
fillet as the lever of a root that binds at a given torque).

The blade's edge radius r_e (the cutter's tip radius ρ_a0) is the radius of the fillet a
Formate gear's slot bottom keeps and the one a generated pinion's fillet is rolled from;
ISO 10300-3 reads it as the tool's ρ_a0 of the root's notch (a larger fillet radius ρ_F,
a smaller stress correction Y_S). The synthesis' default, ``min(0.25 m_mn, 0.4 W)``
(:func:`geometry.synthesis.gear.gear_formate_tools`), does not take the largest radius the
tool allows. Two limits bound it (the form of AGMA 929-A06, *Calculation of Bevel Gear
Top Land and Guidance on Cutter Edge Radius*; Stadtfeld, *Gleason Bevel Gear Technology*,
2014, the cutter's blade tip):

* **the point width**: a blade point W wide with its two edges rounded, each edge's arc
  tangent to the tip plane and to its flank (blade angle α from the tip plane's normal)
  starts r_e tan(45° − α/2) from its flank's foot, so both arcs fit the point where
  r_e (tan(45° − α_D/2) + tan(45° − α_C/2)) ≤ W (equality: a full-radius tip). The
  synthesis gives both members one edge radius, so the narrower slot binds (on a hypoid
  of a large ratio the pinion's: its teeth are the thicker);
* **the clearance**: the edge's arc meets the straight flank r_e (1 − sin α) above the
  tip plane, the top of the fillet it cuts; the mate's tip reaches down to the clearance
  c above the root, so the fillet stays below the working depth where
  r_e (1 − sin α) ≤ c, for the smaller of the two pressure angles.

Public names
------------
EdgeRadiusLimit      the largest edge radius and each limit
edge_radius_limit    from the point widths, the clearance and the pressure angles
largest_edge_radius  of a blank geometry (its slot widths at the mean root, its clearance)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from geometry.core.errors import InputError
from geometry.core.validation import real
from geometry.iso23509.blank import BlankGeometry
from geometry.synthesis.gear import slot_width_at_root

__all__ = ["EdgeRadiusLimit", "edge_radius_limit", "largest_edge_radius"]

#: [mm] the step the largest edge radius is rounded down to (a blade's edge radius is
#: ground to a hundredth of a millimetre)
EDGE_RADIUS_STEP = 0.01


@dataclass(frozen=True)
class EdgeRadiusLimit:
    """The largest edge radius both members' blades allow, and each limit.

    Attributes
    ----------
    radius : float — [mm] the smallest of the three limits, rounded down to
        :data:`EDGE_RADIUS_STEP`
    gear_width : float — [mm] the full-radius tip of the gear's point width
    pinion_width : float — [mm] the full-radius tip of the pinion's point width
    clearance : float — [mm] the fillet's top at the clearance
    binding : str — which limit is the smallest: ``"gear point width"``, ``"pinion point
        width"`` or ``"clearance"``
    """

    radius: float
    gear_width: float
    pinion_width: float
    clearance: float
    binding: str


def edge_radius_limit(gear_point_width: float, pinion_point_width: float, clearance: float,
                      alpha_d: float, alpha_c: float) -> EdgeRadiusLimit:
    """The largest blade edge radius of both members from their point widths and the
    clearance (module docstring).

    Parameters
    ----------
    gear_point_width, pinion_point_width : float — [mm] each member's slot width at the
        mean root (its blade's point width), > 0
    clearance : float — [mm] the clearance c between a tip and the mate's root, > 0
    alpha_d, alpha_c : float — [rad] the drive and coast blade (pressure) angles, each in
        (0, 45°)

    Returns
    -------
    EdgeRadiusLimit
        Point width: r_e ≤ W / (tan(45° − α_D/2) + tan(45° − α_C/2)) per member;
        clearance: r_e ≤ c / (1 − sin min(α_D, α_C)).

    Raises
    ------
    InputError
        A width or clearance ≤ 0 or not finite, or a pressure angle outside (0, 45°),
        named by the parameter.

    Notes
    -----
    Source: the blade tip's geometry (module docstring; the form of the limits of AGMA
    929-A06, guidance on cutter edge radius).
    """
    for name, v in (("gear_point_width", gear_point_width),
                    ("pinion_point_width", pinion_point_width), ("clearance", clearance)):
        real(f"edge radius limit: {name}", v, unit="mm", low=0.0, high=1e3, low_open=True)
    for name, v in (("alpha_d", alpha_d), ("alpha_c", alpha_c)):
        real(f"edge radius limit: {name}", v, unit="rad", low=0.0, high=0.25 * math.pi,
             low_open=True, high_open=True)
    insets = math.tan(0.25 * math.pi - 0.5 * alpha_d) + math.tan(0.25 * math.pi - 0.5 * alpha_c)
    limits = {"gear point width": gear_point_width / insets,
              "pinion point width": pinion_point_width / insets,
              "clearance": clearance / (1.0 - math.sin(min(alpha_d, alpha_c)))}
    binding = min(limits, key=limits.__getitem__)
    radius = math.floor(limits[binding] / EDGE_RADIUS_STEP + 1e-9) * EDGE_RADIUS_STEP
    return EdgeRadiusLimit(round(radius, 6), limits["gear point width"],
                           limits["pinion point width"], limits["clearance"], binding)


def largest_edge_radius(geom: BlankGeometry, alpha_d: float | None = None,
                        alpha_c: float | None = None) -> EdgeRadiusLimit:
    """:func:`edge_radius_limit` of a face-milled design's blank: each member's slot
    width at the mean root (:func:`~geometry.synthesis.gear.slot_width_at_root`, the
    point width the synthesis gives its blades) and the blank's clearance c = k_c h_mw.

    Parameters
    ----------
    geom : geometry.iso23509.blank.BlankGeometry
    alpha_d, alpha_c : float, optional — [rad] the gear's blade angles (``[synthesis]
        blade_angle_drive`` / ``_coast``); default the generated normal pressure angles
        α_nD, α_nC (the synthesis' default)

    Returns
    -------
    EdgeRadiusLimit

    Raises
    ------
    InputError
        A slot that closes above the root (:func:`slot_width_at_root`), or a face-hobbed
        design (its slot width at the root is the epicycloid's, not this relation; named
        ``design.z0``).

    Notes
    -----
    Source: module docstring; the slot width W = π m_mn − s_mn − h_fm (tan α_D + tan α_C)
    (Stadtfeld 1993, §2).
    """
    if geom.design.z0 != 0:
        raise InputError(f"design.z0: the largest edge radius is that of a face-milled "
                         f"design (z0 = 0), got z0 = {geom.design.z0}")
    a_d = geom.pitch.alpha_nD if alpha_d is None else alpha_d
    a_c = geom.pitch.alpha_nC if alpha_c is None else alpha_c
    return edge_radius_limit(slot_width_at_root(geom.gear, geom.m_mn, a_c, a_d),
                             slot_width_at_root(geom.pinion, geom.m_mn, a_c, a_d),
                             geom.c, a_d, a_c)
