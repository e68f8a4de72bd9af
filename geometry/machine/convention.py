"""Machine-setting summaries typed in another tool's convention, converted to ours.

The toolkit's chain (``docs/machine.md``, :mod:`geometry.machine.cradle`) is the classical cradle
model that open generators use too; only the signs, the hand rule and the reference of the
circular blade profile differ. This module holds the conversion tables and applies them.

Conventions
-----------
``"ours"``
    The toolkit's own: settings of the **right-hand** reference member, positive senses of
    ``docs/machine.md``; a circular blade profile tangent to the nominal line at the
    reference height h_ref. Case files written by the toolkit (``Case.to_toml``) are always
    in this convention.
``"spygo"``
    The summary as typed into SpyGO (E. Grabovic et al., open-source spiral bevel and
    hypoid generator, Python; module ``hypoid_kinematics``/``kinematics`` and the sign
    matrices of ``manageMachinePar``/``manage_machine_settings``): the settings of the
    member *of its own hand* (the system hand is the pinion's), multiplied by a sign per
    member and hand before its 9-joint cradle chain; the circular blade profile (radius
    ρ_b, "RHO") is referred to the blade **tip** (the arc passes through the point radius in
    the tip plane with the blade angle there) and ρ_b > 0 puts the arc's centre on the
    work-material side (a convex tooth profile).

Derivation (``docs/machine.md``, "Summaries from other tools"): SpyGO's chain is
R_z(−ψ) T(0,0,−D) R_y(γ) T(B,E,0) R_x(−q) T(0,0,S) R_x(ζ) R_z(σ) R_y(−π/2) acting on the same
cutter frame as ours; conjugating ours by P = R_y(−π/2) (our z_m is SpyGO's −x) gives term by
term ψ = φ, D = X_p, γ = γ_m, B = −X_b, E = −E_m, q = q_c + q, S = S_r, ζ = −j, σ = i.
Composing with SpyGO's signs for the member and hand, and with :func:`mirror_settings
<geometry.machine.cradle.mirror_settings>` for a left-hand member, gives :data:`SPYGO_MACHINE`.

Public functions
----------------
CONVENTIONS              the accepted convention names
SPYGO_MACHINE            the machine-setting table: ours = factor × SpyGO's, per member, hand
SPYGO_BLADE_FIELDS       blade fields a SpyGO summary gives (the others are ours only)
check_convention         validate a convention name (InputError naming the field)
machine_from_spygo       SpyGO-typed machine fields → ours
machine_to_spygo         ours → SpyGO-typed machine fields
blade_from_spygo         SpyGO-typed blade fields → ours (circular profile re-referenced)
blade_to_spygo           ours → SpyGO-typed blade fields
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from geometry.core.errors import InputError
from geometry.machine.cutter import BLADE_SIDES

__all__ = [
    "CONVENTIONS",
    "SPYGO_BLADE_FIELDS",
    "SPYGO_MACHINE",
    "blade_from_spygo",
    "blade_to_spygo",
    "check_convention",
    "machine_from_spygo",
    "machine_to_spygo",
]

#: accepted summary conventions of a case's ``[<member>.machine]`` / ``[<member>.cutter]``
CONVENTIONS: tuple[str, ...] = ("ours", "spygo")

_MEMBERS = ("pinion", "gear")
_HANDS = ("right", "left")

# SpyGO stores the 5th and 6th derivatives of the sliding base in thousandths (its
# coefficient matrix divides H5/120 and H6/720 by a further 1000)
_KILO = 1.0e-3
_SCALAR = ("radial_setting", "cradle_angle", "swivel", "tilt", "machine_root_angle",
           "machine_center_to_back", "sliding_base", "blank_offset", "ratio_of_roll")
_SEQUENCE = ("modified_roll", "helical_motion", "vertical_motion")


def _table(swivel: float, tilt: float, modified_roll, helical, vertical) -> Mapping:
    return MappingProxyType({
        "radial_setting": 1.0, "cradle_angle": 1.0, "swivel": swivel, "tilt": tilt,
        "machine_root_angle": 1.0, "machine_center_to_back": 1.0, "sliding_base": -1.0,
        "blank_offset": 1.0, "ratio_of_roll": 1.0,
        "modified_roll": tuple(modified_roll), "helical_motion": tuple(helical),
        "vertical_motion": tuple(vertical)})


#: ours = factor × SpyGO-typed value, per (member, hand) of the member; for the lists one
#: factor per coefficient: modified_roll (2C, 6D, 24E, 120F), helical_motion (H1…H6),
#: vertical_motion (V1…V6). Derived in docs/machine.md; checked against an independent
#: implementation of SpyGO's chain in tests/test_machine_convention.py.
SPYGO_MACHINE: Mapping[tuple[str, str], Mapping[str, Any]] = MappingProxyType({
    ("pinion", "right"): _table(-1.0, 1.0, (-1, 1, -1, 1),
                                (1, -1, 1, -1, _KILO, -_KILO), (1, 1, 1, 1, 1, 1)),
    ("pinion", "left"): _table(-1.0, 1.0, (-1, 1, -1, 1),
                               (1, -1, 1, -1, _KILO, -_KILO), (-1, 1, -1, 1, -1, 1)),
    ("gear", "right"): _table(-1.0, -1.0, (1, 1, 1, 1),
                              (-1, -1, -1, -1, -_KILO, -_KILO), (-1, -1, -1, -1, -1, -1)),
    ("gear", "left"): _table(1.0, -1.0, (1, 1, 1, 1),
                             (-1, -1, -1, -1, -_KILO, -_KILO), (-1, -1, -1, -1, -1, 1)),
})

#: blade fields of a SpyGO cutter summary (POINTRADIUS, BLADEANGLE, EDGERADIUS, TYPE, RHO)
SPYGO_BLADE_FIELDS: tuple[str, ...] = ("point_radius", "blade_angle", "edge_radius", "profile",
                                       "profile_radius")


def check_convention(where: str, value: Any) -> str:
    """Validate a summary convention name.

    Parameters
    ----------
    where : str
        Dotted path of the field, for the message (e.g. ``pinion.machine.convention``).
    value : object
        The value read from the file.

    Returns
    -------
    str
        ``value``, one of :data:`CONVENTIONS`.

    Raises
    ------
    InputError
        ``value`` is not one of :data:`CONVENTIONS` (the message names ``where`` and the
        accepted values).
    """
    if not isinstance(value, str) or value not in CONVENTIONS:
        raise InputError(f"{where}: must be one of {list(CONVENTIONS)}, got {value!r}")
    return value


def _rules(member: str, hand: str) -> Mapping[str, Any]:
    if member not in _MEMBERS:
        raise InputError(f"member: must be one of {list(_MEMBERS)}, got {member!r}")
    if hand not in _HANDS:
        raise InputError(f"hand: must be one of {list(_HANDS)}, got {hand!r}")
    return SPYGO_MACHINE[(member, hand)]


def _convert(fields: Mapping[str, Any], member: str, hand: str, forward: bool) -> dict:
    rules = _rules(member, hand)
    out = dict(fields)
    for name in _SCALAR:
        if name in out:
            out[name] = rules[name] * out[name] if forward else out[name] / rules[name]
    for name in _SEQUENCE:
        if name not in out:
            continue
        seq = tuple(out[name])
        factors = rules[name]
        if len(seq) > len(factors):
            raise InputError(
                f"{name}: the SpyGO conversion table has {len(factors)} coefficients, got "
                f"{len(seq)}")
        out[name] = tuple(f * v if forward else v / f for f, v in zip(factors, seq,
                                                                        strict=False))
    return out


def machine_from_spygo(fields: Mapping[str, Any], member: str, hand: str) -> dict[str, Any]:
    """Machine settings typed as in SpyGO → the same settings in our convention.

    Parameters
    ----------
    fields : mapping
        Any of the fields of :class:`geometry.machine.cradle.MachineSettings` (radial_setting,
        cradle_angle, swivel, tilt, machine_root_angle, machine_center_to_back,
        sliding_base, blank_offset, ratio_of_roll [mm, rad or deg, 1: the units are kept],
        modified_roll (2C, 6D, 24E, 120F), helical_motion (H1…H6, H5 and H6 in SpyGO's
        thousandths), vertical_motion (V1…V6)) with SpyGO's signs; other keys pass through.
    member : str
        ``"pinion"`` or ``"gear"``.
    hand : str
        Hand of this member, ``"right"`` or ``"left"`` (SpyGO's system hand is the pinion's).

    Returns
    -------
    dict
        The fields with our signs: the settings of the right-hand reference member
        (:data:`SPYGO_MACHINE`; ``docs/machine.md``).

    Raises
    ------
    InputError
        Bad member or hand, or a list longer than the table.

    Notes
    -----
    Source: SpyGO's cradle chain and sign matrices, conjugated by R_y(−π/2) into our frames
    and mirrored for a left-hand member (``docs/machine.md``). Every factor is ±1 except
    H5, H6 (1/1000), so the conversion is exact but for those two.
    """
    return _convert(fields, member, hand, forward=True)


def machine_to_spygo(fields: Mapping[str, Any], member: str, hand: str) -> dict[str, Any]:
    """Machine settings in our convention → the values to type into SpyGO.

    Parameters
    ----------
    fields : mapping
        Fields of :class:`geometry.machine.cradle.MachineSettings` in our convention (right-hand
        reference member), units kept; other keys pass through.
    member, hand : str
        As in :func:`machine_from_spygo` (hand: of this member).

    Returns
    -------
    dict
        The inverse of :func:`machine_from_spygo` (exact but for H5, H6, ×1000).

    Raises
    ------
    InputError
        Bad member or hand, or a list longer than the table.
    """
    return _convert(fields, member, hand, forward=False)


def _side(side: str) -> int:
    if side not in BLADE_SIDES:
        raise InputError(f"side: must be one of {sorted(BLADE_SIDES)}, got {side!r}")
    return BLADE_SIDES[side]


def _rereference(sigma: int, point_radius: float, blade_angle: float, radius: float,
                 h_from: float, h_to: float) -> tuple[float, float]:
    """(r, α) of the same circle referred to its tangent at height ``h_to`` instead of
    ``h_from`` [mm] (r: where that tangent meets the tip plane; see blade_to_spygo)."""
    sin_new = math.sin(blade_angle) + (h_from - h_to) / radius
    if not -1.0 < sin_new < 1.0:
        raise InputError(
            f"profile_radius: the circular profile of radius {radius:g} mm has no tangent at "
            f"height {h_to:g} mm (|sin| = {abs(sin_new):.6g} >= 1)")
    new_angle = math.asin(sin_new)
    # R (cos α' − cos α) written without the cancellation: −(h_from − h_to) tan((α + α')/2)
    shift = (h_from * math.tan(blade_angle) - h_to * math.tan(new_angle)
             - (h_from - h_to) * math.tan(0.5 * (blade_angle + new_angle)))
    return point_radius + sigma * shift, new_angle


def blade_to_spygo(fields: Mapping[str, Any], side: str) -> dict[str, Any]:
    """A blade in our convention → the blade fields to type into SpyGO.

    Parameters
    ----------
    fields : mapping
        Our blade fields (as :class:`geometry.machine.cutter.Blade`, angles in **rad**, lengths mm):
        point_radius, blade_angle, edge_radius, profile, profile_radius,
        profile_reference_height; the toprem, flankrem and placement fields must be 0 or
        absent (SpyGO's are other curves: not in the table).
    side : str
        ``"outside"`` (concave flank) or ``"inside"`` (convex flank).

    Returns
    -------
    dict
        :data:`SPYGO_BLADE_FIELDS`: the point radius R_p and blade angle α_t of the circle
        **at the tip plane**, edge radius, profile, ρ_b = −R_pr (straight: 0).

    Raises
    ------
    InputError
        A field outside the table is non-zero, or the circle does not reach the tip plane.

    Notes
    -----
    Our arc of radius R_pr (> 0: centre on the blade's side) is tangent at height h_ref to
    the line of blade angle α through (r_p, 0). Its centre is
    (r_p + σ h_ref tan α − σ R_pr cos α, h_ref + R_pr sin α) (σ = +1 outside, −1 inside), so
    at the tip plane its tangent makes α_t with the cutter axis and it passes at R_p:

        sin α_t = sin α + h_ref / R_pr,
        R_p = r_p + σ h_ref [tan α − tan((α + α_t)/2)],

    (R_pr (cos α_t − cos α) = −h_ref tan((α + α_t)/2), no cancellation for large R_pr).
    """
    sigma = _side(side)
    for name in ("toprem_angle", "flankrem_angle", "blade_phase", "blade_offset_angle",
                 "rake_angle", "hook_angle"):
        if fields.get(name, 0.0):
            raise InputError(f"{name}: not in the SpyGO conversion table (must be 0 to "
                             f"write a SpyGO summary), got {fields[name]!r}")
    out = {"point_radius": fields["point_radius"], "blade_angle": fields["blade_angle"],
           "edge_radius": fields.get("edge_radius", 0.0),
           "profile": fields.get("profile", "straight"), "profile_radius": 0.0}
    if out["profile"] == "circular":
        radius = fields["profile_radius"]
        height = fields.get("profile_reference_height", 0.0)
        out["point_radius"], out["blade_angle"] = _rereference(
            sigma, fields["point_radius"], fields["blade_angle"], radius, height, 0.0)
        out["profile_radius"] = -radius
    return out


def blade_from_spygo(fields: Mapping[str, Any], side: str,
                     reference_height: float = 0.0) -> dict[str, Any]:
    """SpyGO-typed blade fields → our blade fields.

    Parameters
    ----------
    fields : mapping
        :data:`SPYGO_BLADE_FIELDS` (angles in **rad**, lengths mm); the circle of a
        ``"circular"`` profile is referred to the tip plane, ρ_b > 0 centre on the work side.
    side : str
        ``"outside"`` (concave flank) or ``"inside"`` (convex flank).
    reference_height : float — [mm]
        h_ref ≥ 0 of the returned blade (where its circle is tangent to its nominal line);
        default 0, the tip: then r_p = R_p and α = α_t.

    Returns
    -------
    dict
        point_radius, blade_angle, edge_radius, profile, profile_radius (R_pr = −ρ_b),
        profile_reference_height in our convention; the same circle and edge radius.

    Raises
    ------
    InputError
        An unknown field, negative ``reference_height``, or a circle that has no tangent
        point at that height.

    Notes
    -----
    The inverse of :func:`blade_to_spygo`: sin α = sin α_t − h_ref/R_pr,
    r_p = R_p − σ h_ref [tan α − tan((α + α_t)/2)].
    """
    sigma = _side(side)
    unknown = sorted(set(fields) - set(SPYGO_BLADE_FIELDS))
    if unknown:
        raise InputError(f"{unknown[0]}: not a SpyGO blade field; accepted: "
                         f"{', '.join(SPYGO_BLADE_FIELDS)}")
    if not reference_height >= 0.0:
        raise InputError(f"profile_reference_height: must be >= 0 mm, got {reference_height}")
    out = {"point_radius": fields["point_radius"], "blade_angle": fields["blade_angle"],
           "edge_radius": fields.get("edge_radius", 0.0),
           "profile": fields.get("profile", "straight"), "profile_radius": 0.0,
           "profile_reference_height": 0.0}
    if out["profile"] == "circular":
        radius = -fields["profile_radius"]
        if radius == 0.0:
            raise InputError("profile_radius: a circular profile needs a non-zero radius")
        out["point_radius"], out["blade_angle"] = _rereference(
            sigma, fields["point_radius"], fields["blade_angle"], radius, 0.0,
            reference_height)
        out["profile_radius"] = radius
        out["profile_reference_height"] = reference_height
    return out
