"""Step 7a of the synthesis: a pressure-angle (blade-angle) change of a pinion flank at M.

The local synthesis (steps 3–6) makes the pinion flank touch the gear at M with the gear's
pressure angle there; the height of the bearing on the tooth is what a gear engineer then
moves by a **blade-angle change** of the pinion blade (Stadtfeld, *Gleason Bevel Gear
Technology*, 2014, ch. on the development of a bearing: "a pressure angle change moves the
contact towards the top or the root"; Litvin & Fuentes, *Gear Geometry and Applied
Theory*, 2nd ed., 2004, §9.4: a mismatch of the profile inclination is a first-order
ease-off across the profile). The blade is turned about its point at M's height, so the
blade still passes through the circle that generates M and only the inclination of the
flank at M changes: in ease-off terms a linear profile term through M, the tooth thickness
at M unchanged (a turn about the blade tip would also thin or thicken the tooth by
h_M Δα, ≈ 0.14 mm per degree on an 8 mm high blade, and eat the backlash).

Public names
------------
blade_angle_changed   the blade with its angle changed about a height
blade_profile_crowned the blade with profile crowning added about a height
"""

from __future__ import annotations

import math
from dataclasses import replace

from geometry.core.errors import InputError
from geometry.core.validation import real
from geometry.machine.cutter import Blade

__all__ = ["blade_angle_changed", "blade_profile_crowned"]


def blade_angle_changed(blade: Blade, change: float, pivot_height: float) -> Blade:
    """The blade with its angle changed by ``change`` about its point at ``pivot_height``.

    Parameters
    ----------
    blade : geometry.machine.cutter.Blade
        A pinion blade before its relief (toprem and flankrem are kept as they are; the
        synthesis applies this before :func:`geometry.machine.relief.relieved_blade`).
    change : float — [rad]
        Δα added to the blade angle α, in (−5°, 5°); > 0 a larger blade angle.
    pivot_height : float — [mm]
        Height h above the blade tip about which the nominal profile line turns (M's blade
        height, the circular profile's reference height), ≥ 0.

    Returns
    -------
    Blade
        α' = α + Δα and r_p' = r_p + σ h (tan α − tan α'), σ = +1 for an outside blade and
        −1 for an inside blade, so that the nominal line's radius at h,
        r_p + σ h tan α, is unchanged; a circular profile keeps its radius and stays
        tangent to the (turned) nominal line at its reference height. ``change`` = 0
        returns ``blade`` itself.

    Raises
    ------
    InputError
        ``change`` or ``pivot_height`` out of range, or a changed blade the cutter model
        refuses (blade angle outside [0, 45°), point radius ≤ 0), naming
        ``blade_angle_change``.

    Notes
    -----
    The radius of the nominal line at height h is ρ(h) = r_p + σ h tan α (the convention
    of :func:`geometry.synthesis.pinion.pinion_generate_tools`); holding ρ(h_M) fixed gives
    r_p'. Source: Stadtfeld 2014 (above); the ease-off of a profile-inclination mismatch,
    Litvin & Fuentes 2004 §9.4.
    """
    change = real("blade_angle_change", change, unit="rad", low=-math.radians(5.0),
                  high=math.radians(5.0), low_open=True, high_open=True)
    pivot_height = real("pivot_height", pivot_height, unit="mm", low=0.0)
    if change == 0.0:
        return blade
    sigma = 1.0 if blade.side == "outside" else -1.0
    alpha = blade.blade_angle + change
    r_p = blade.point_radius + sigma * pivot_height * (math.tan(blade.blade_angle)
                                                       - math.tan(alpha))
    try:
        return replace(blade, blade_angle=alpha, point_radius=r_p)
    except InputError as exc:
        raise InputError(f"blade_angle_change: {math.degrees(change):+.4g} deg gives a blade "
                         f"the cutter model refuses ({exc}); change it less") from None


def blade_profile_crowned(blade: Blade, crowning: float, pivot_height: float,
                          reach: float) -> Blade:
    """The blade with profile crowning added: its profile curvature changed so that the
    flank it cuts is eased off by ``crowning`` at ``reach`` above and below M's height.

    Parameters
    ----------
    blade : geometry.machine.cutter.Blade
        A pinion blade before its relief.
    crowning : float — [mm]
        Normal ease-off c at ±``reach`` of blade height from the pivot, in (−0.1, 0.1) mm;
        > 0 crowns the flank (less contact at both ends of the profile).
    pivot_height : float — [mm]
        M's blade height, where the added curvature is tangent to the profile.
    reach : float — [mm]
        The blade height from the pivot at which ``crowning`` is measured, > 0 (the
        synthesis gives the normal module m_mn, about half the working depth).

    Returns
    -------
    Blade
        A circular profile of curvature κ' = κ + Δκ, Δκ = 2 c / reach² (the circle's
        sagitta), tangent to the nominal line at ``pivot_height``; the existing circular
        profile's κ = 1/R_pr (0 for a straight one). ``crowning`` = 0 returns ``blade``.

    Raises
    ------
    InputError
        Out-of-range input, or a profile radius the cutter model refuses (|R_pr| at most
        the edge radius), naming ``profile_crowning``.

    Notes
    -----
    Profile crowning by the blade's profile curvature (Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: "profile crowning ... by a curved blade profile"; Litvin & Fuentes
    2004 ch. 20: the parabolic blade profile of the pinion's generating tool). The sign of
    the blade curvature that crowns the flank follows the cutter model's convention (a
    convex cutting edge, R_pr > 0, is a concave tool surface seen from the flank it cuts):
    Δκ = −2 c / reach² on the profile curvature of :class:`~geometry.machine.cutter.Blade`.
    """
    crowning = real("profile_crowning", crowning, unit="mm", low=-0.1, high=0.1,
                    low_open=True, high_open=True)
    pivot_height = real("pivot_height", pivot_height, unit="mm", low=0.0)
    reach = real("reach", reach, unit="mm", low=0.0, low_open=True)
    if crowning == 0.0:
        return blade
    kappa = (1.0 / blade.profile_radius if blade.profile == "circular"
             and blade.profile_radius else 0.0)
    kappa += _CROWN_SIGN * 2.0 * crowning / reach**2
    try:
        if kappa == 0.0:
            return replace(blade, profile="straight")
        return replace(blade, profile="circular", profile_radius=1.0 / kappa,
                       profile_reference_height=pivot_height)
    except InputError as exc:
        raise InputError(f"profile_crowning: {1e3 * crowning:+.4g} um gives a blade the "
                         f"cutter model refuses ({exc}); change it less") from None


#: sign of the blade's profile curvature that crowns the flank it cuts
_CROWN_SIGN = -1.0
