"""Step 2 of the synthesis: the gear's Formate tools, and the shared tool helpers.

The cutter surface is the gear's tooth slot (face milling: one spread-blade cutter; face
hobbing: the closed-form face-hobbing tools, the slot centre line the extended epicycloid
through the mean root point). Machine root angle γ_m = root angle δ_f2, root apex at the
machine centre, cutter centre from the mean root cone distance R_mf, the mean spiral angle
β_m2 and the cutter radius r_c0 (S_r² = R_mf² + r_c0² − 2 R_mf r_c0 sin β_m2,
q_c = atan2(r_c0 cos β_m2, R_mf − r_c0 sin β_m2)). See :mod:`geometry.synthesis` and
``docs/synthesis.md``.

Public functions
----------------
case_blank          ISO 23509 member blank → case blank
GearTools           the gear's blades, settings and cutter
gear_formate_tools  Formate gear blades and settings (FM and FH)
gear_generate_tools generated gear: the Formate gear's cutter and settings with cradle roll
generating_ratio_of_roll  the generated gear's ratio of roll (pitch cone on the crown gear)
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import NamedTuple

import numpy as np

from geometry.case import Blank
from geometry.core.errors import InputError
from geometry.iso23509.blank import BlankGeometry, MemberBlank
from geometry.iso23509.pitch_cone import FaceHobbingTrace, face_hobbing_trace
from geometry.machine.cradle import (
    MachineSettings,
    cradle_pose,
    cutter_pose,
    indexing_ratio,
    settings_from_poses,
)
from geometry.machine.cutter import Blade
from geometry.machine.flank import blank_outline
from geometry.machine.flank_point import FlankPoint, flank_points

__all__ = [
    "GearTools",
    "case_blank",
    "gear_formate_tools",
    "gear_generate_tools",
    "generating_ratio_of_roll",
    "mean_root_point",
    "slot_width_at_root",
]

_OTHER = {"concave": "convex", "convex": "concave"}


# --------------------------------------------------------------------------- helpers
def unit(v: np.ndarray) -> np.ndarray:
    """``v`` (3,) scaled to unit length [1]."""
    return v / np.linalg.norm(v)


def tangent_basis(n: np.ndarray) -> np.ndarray:
    """3 × 2 orthonormal basis of the plane normal to n (columns t1, t2 = n × t1)."""
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    t1 = unit(a - (a @ n) * n)
    return np.column_stack([t1, np.cross(n, t1)])


def flank_point(blade: Blade, settings: MachineSettings, blank: Blank, hand: str,
                 z: float, p: float) -> FlankPoint:
    """One flank point (unbatched); InputError if the flank is not generated there."""
    pt = flank_points(blade, settings, blank, hand, [z], [p])
    if not pt.ok[0]:
        raise InputError(f"synthesis: the flank is not generated at (z, rho) = ({z:.4g}, "
                         f"{p:.4g}) mm")
    return FlankPoint(*(a[0] for a in pt))


# --------------------------------------------------------------------------- blanks
def case_blank(member: MemberBlank) -> dict[str, float]:
    """Case-file blank table (degrees, mm) of an ISO 23509 member blank.

    Parameters
    ----------
    member : geometry.iso23509.blank.MemberBlank

    Returns
    -------
    dict
        Fields of ``[<member>.blank]`` (docs/cases.md): teeth, face width, outer cone
        distance, pitch/face/root angles [deg], apexes beyond the crossing point [mm], outer
        addendum and dedendum [mm].

    Notes
    -----
    ISO 23509:2016 cl. 6 symbols: z, b, R_e, δ, δ_a, δ_f, t_z, t_zF, t_zR, h_ae, h_fe; the
    case file's apex sign is the standard's ("beyond the crossing point").
    """
    return {
        "teeth": int(member.z), "face_width": float(member.b),
        "outer_cone_distance": float(member.Re), "pitch_angle": math.degrees(member.delta),
        "face_angle": math.degrees(member.delta_a),
        "root_angle": math.degrees(member.delta_f), "pitch_apex": float(member.t_z),
        "face_apex": float(member.t_zF), "root_apex": float(member.t_zR),
        "outer_addendum": float(member.hae), "outer_dedendum": float(member.hfe),
    }


def blank(member: MemberBlank) -> Blank:
    """The case blank (angles [rad], lengths [mm]) of an ISO 23509 member blank."""
    d = case_blank(member)
    return Blank(**{k: (math.radians(v) if k.endswith("angle") else v) for k, v in d.items()})


def mean_root_point(member: MemberBlank) -> tuple[float, float]:
    """Root cone distance R_mf and dedendum h_fm of a member's mean point.

    Parameters
    ----------
    member : geometry.iso23509.blank.MemberBlank — one member of an ISO 23509 blank

    Returns
    -------
    (R_mf, h_fm) : [mm], [mm]
        The mean root point is where the root line meets the normal to the pitch cone
        through the mean point P_m of the axial section; R_mf its distance from the root
        apex along the root line, h_fm its distance from P_m (ISO 23509:2016 §6, the mean
        dedendum measured normal to the pitch cone).
    """
    out = blank_outline(blank(member))
    d, df = member.delta, member.delta_f
    pm = out.mean_point
    root_dir = np.array([math.cos(df), math.sin(df)])
    perp = np.array([-math.sin(d), math.cos(d)])
    a = np.array([[root_dir[0], -perp[0]], [root_dir[1], -perp[1]]])
    t = np.linalg.solve(a, pm - np.array([out.root_apex, 0.0]))
    return float(t[0]), float(abs(t[1]))


def slot_width_at_root(member: MemberBlank, m_mn: float, blade_angle_inside: float,
                       blade_angle_outside: float) -> float:
    """Slot width at the mean root, W = π m_mn − s_mn − h_fm (tan α_IB + tan α_OB).

    Parameters
    ----------
    member : geometry.iso23509.blank.MemberBlank — its ``smn`` is s_mn [mm]
    m_mn : float — [mm] mean normal module
    blade_angle_inside, blade_angle_outside : float — [rad] α_IB, α_OB (the convex and
        the concave flank's blade angle)

    Returns
    -------
    float — [mm] the width, in the mean normal section, between the two flanks' straight
    nominal profiles at the root line: the point width of a spread-blade cutter whose tip
    plane holds the mean root line (Stadtfeld 1993, Handbook of bevel and hypoid gears,
    §2; Litvin & Fuentes 2004 §20.3), and the width that the tip of a blade cutting one
    flank alone can span without reaching the other flank at the mean point.

    Raises
    ------
    InputError — a width ≤ 0 (the slot closes above the root for these blade angles).
    """
    h_fm = mean_root_point(member)[1]
    w = (math.pi * m_mn - member.smn
         - h_fm * (math.tan(blade_angle_inside) + math.tan(blade_angle_outside)))
    if w <= 0:
        raise InputError(f"point_width: must be > 0 mm, got {w:.4g} (slot too narrow at the "
                         "root for these blade angles)")
    return w


# --------------------------------------------------------------------------- gear
class GearTools(NamedTuple):
    """Formate gear: blade per gear flank, one machine setting for both, derivation data."""

    blades: dict[str, Blade]
    settings: MachineSettings
    mean_root_cone_distance: float  # [mm]
    point_width: float  # [mm]
    cutter_radius: float  # [mm]
    blade_groups: int = 0  # z0 (0: face milling)


def gear_formate_tools(geom: BlankGeometry, *, cutter_radius: float,
                       blade_angle_drive: float, blade_angle_coast: float,
                       point_width: float | None, edge_radius: float | None,
                       drive_flank: str = "concave", blade_groups: int = 0) -> GearTools:
    """Blades and machine settings of a Formate gear cut by one spread-blade cutter.

    Parameters
    ----------
    geom : geometry.iso23509.blank.BlankGeometry
        ISO 23509 blank of the pair.
    cutter_radius : float — [mm]
        Nominal cutter radius r_c0 (radius of the slot centre line at the tip plane).
    blade_angle_drive, blade_angle_coast : float — [rad]
        Blade angles of the gear flanks meshing the pinion's drive and coast flanks.
    point_width : float or None — [mm]
        Cutter point width W; None: from the slot width at the mean point,
        W = π m_mn − s_mn2 − h_fm2 (tan α_IB + tan α_OB).
    edge_radius : float or None — [mm]
        Blade edge radius; None: min(0.25 m_mn, 0.4 W), rounded to 1 µm.
    drive_flank : str
        Pinion drive flank (its mate on the gear is the other flank type).
    blade_groups : int
        z0 of a face-hobbing cutter head (≥ 1, no common factor with z2); 0 (default): face
        milling.

    Returns
    -------
    GearTools
        ``blades`` keyed by gear flank (``"concave"`` outside blade, point radius r_c0 + W/2;
        ``"convex"`` inside blade, r_c0 − W/2) and the settings (γ_m = δ_f2, X_p = t_zR2,
        X_b = E_m = 0, no tilt, S_r and q_c from R_mf, β_m2, r_c0).

    Raises
    ------
    InputError
        If the point width is not positive or the cutter does not reach the mean point.

    Notes
    -----
    Face-milling basic relations (e.g. Litvin & Fuentes 2004 §20.3; Stadtfeld 1993): the
    cutter tip plane contains the root generatrix of the mean point (γ_m = δ_f2, root apex at
    the machine centre) and the slot centre line, a circle of radius r_c0 about the cutter
    centre, passes through the mean root point with the spiral angle β_m2:
    S_r² = R_mf² + r_c0² − 2 R_mf r_c0 sin β_m2, q_c = atan2(r_c0 cos β_m2,
    R_mf − r_c0 sin β_m2), R_mf the root cone distance of the mean point.

    Face hobbing (``blade_groups`` z0 ≥ 1; ``docs/machine.md``, "Face hobbing"): the slot
    centre line is the extended epicycloid traced by the blades' reference points while
    the work indexes by κ = −z0/z2 per radian of spin (seed Eq. 2.1). In the tip plane (the
    root plane of the crown gear of z_pf = z2/sin δ_f2 teeth) the lead angle at the mean
    root point is sin ν_f = z0 R_mf cos β_m2/(r_c0 z_pf); the cutter centre is placed by
    the same triangle with β_m2 − ν_f in place of β_m2 (the trace normal at the mean point
    passes through the pitch point of the cutter and crown circles, not through the cutter
    centre), and the spin phase θ_0 = β_m2 − ν_f − π/2 − q_c puts the slot centre at the
    mean root point at θ = 0. The outside blade leads the inside blade by half a group
    pitch (phases θ_0 ± π/(2 z0)), which adds p_n/2 to the slot width: the point radii are
    r_c0 ± W_r/2 with W_r = (W − π m_mn/2)/cos ν_f, and each blade's rake plane is turned
    by its own lead angle (blade offset angle δ_b = ν at r_p) so that it cuts normal to
    the trace. Exact at the mean root point for the spiral angle; the slot width is closed
    in the tip plane.
    """
    g = geom.gear
    # mean root point: the root line met by the normal to the pitch cone through P_m
    rmf = mean_root_point(g)[0]
    beta = g.beta_m
    sr2 = rmf**2 + cutter_radius**2 - 2 * rmf * cutter_radius * math.sin(beta)
    if sr2 <= 0:
        raise InputError(f"cutter_radius: {cutter_radius:g} mm does not reach the mean point")
    other = _OTHER[drive_flank]
    # gear flank → blade angle: the gear flank meshing the pinion drive flank has the drive
    # pressure angle
    alpha = {other: blade_angle_drive, drive_flank: blade_angle_coast}
    a_ib, a_ob = alpha["convex"], alpha["concave"]
    if point_width is None:
        point_width = slot_width_at_root(g, geom.m_mn, a_ib, a_ob)
    if point_width <= 0:
        raise InputError(f"point_width: must be > 0 mm, got {point_width:.4g} (slot too narrow "
                         "at the root for these blade angles)")
    if edge_radius is None:
        edge_radius = round(min(0.25 * geom.m_mn, 0.4 * point_width), 3)
    if blade_groups:
        return _face_hobbing_gear_tools(g, rmf, cutter_radius, a_ob, a_ib, point_width,
                                        edge_radius, geom.m_mn, blade_groups)
    blades = {
        "concave": Blade("outside", cutter_radius + 0.5 * point_width, a_ob,
                         edge_radius=edge_radius, point_width=point_width),
        "convex": Blade("inside", cutter_radius - 0.5 * point_width, a_ib,
                        edge_radius=edge_radius, point_width=point_width),
    }
    settings = MachineSettings(
        process="Formate", radial_setting=math.sqrt(sr2),
        cradle_angle=math.atan2(cutter_radius * math.cos(beta),
                                rmf - cutter_radius * math.sin(beta)),
        machine_root_angle=g.delta_f, machine_center_to_back=g.t_zR)
    return GearTools(blades, settings, rmf, point_width, cutter_radius)


def generating_ratio_of_roll(member: MemberBlank) -> float:
    """Ratio of roll R_a of a member generated at the machine root angle γ_m = δ_f.

    Parameters
    ----------
    member : geometry.iso23509.blank.MemberBlank — pitch angle δ, root angle δ_f [rad]

    Returns
    -------
    float — [1] R_a = cos θ_f / sin δ (work rotation per cradle rotation), θ_f = δ − δ_f the
    dedendum angle.

    Notes
    -----
    With the cutter's tip plane on the root cone (γ_m = δ_f, root apex at the machine centre)
    the generating crown gear's pitch cone has the half angle 90° − θ_f about the cradle
    axis and touches the member's pitch cone along its pitch generatrix; the two cones roll
    without slip when ω_work sin δ = ω_cradle cos θ_f (Litvin & Fuentes 2004, ch. 20, the
    generating gear's pitch cone; Stadtfeld, *Gleason Bevel Gear Technology*, 2014, the
    ratio of roll of a generated member, sin δ / cos θ_f as cradle per work rotation). The
    generated flank then has the blade angle as its pressure angle at the pitch cone, as a
    rack-generated spur gear has at its pitch circle.
    """
    return math.cos(member.delta - member.delta_f) / math.sin(member.delta)


def gear_generate_tools(geom: BlankGeometry, *, cutter_radius: float,
                        blade_angle_drive: float, blade_angle_coast: float,
                        point_width: float | None, edge_radius: float | None,
                        drive_flank: str = "concave", blade_groups: int = 0) -> GearTools:
    """Blades and machine settings of a generated gear (face milling or face hobbing).

    Parameters
    ----------
    geom, cutter_radius, blade_angle_drive, blade_angle_coast, point_width, edge_radius,
    drive_flank :
        As :func:`gear_formate_tools`.
    blade_groups : int
        z0 of a face-hobbing cutter head (≥ 1); 0 (default): face milling.

    Returns
    -------
    GearTools
        The Formate gear's blades (one spread-blade cutter, point width from the slot width
        at the mean root) and settings (γ_m = δ_f2, X_p = t_zR2, S_r, q_c placing the slot
        centre line through the mean root point with the spiral angle β_m2), with
        ``process = "Generate"`` and the ratio of roll :func:`generating_ratio_of_roll`
        (no modified roll, helical or vertical motion), the cradle axis moved from the
        root apex to the gear's pitch apex (:func:`_cradle_through_pitch_apex`; X_p =
        −t_z2 along the axis, the sliding base X_b and S_r, q_c keeping the cutter where it
        was). Face hobbing: also the indexing κ2 = −z0/z2 at q = θ = 0.

    Raises
    ------
    InputError
        As :func:`gear_formate_tools`.

    Notes
    -----
    Below a gear pitch angle of about 63° a Formate gear's straight flank does not meet the
    surface of action over the deep part of its working depth (``docs/synthesis.md``,
    "Known limits"); practice generates both members of such pairs (Stadtfeld, *Gleason
    Bevel Gear Technology*, 2014; Litvin & Fuentes 2004, ch. 20, the generated gear of a
    spiral bevel pair). At roll q = 0 the cutter stands where the Formate gear's does (its
    tip plane on the root cone, the slot centre line through the mean root point with the
    spiral angle β_m2); the crown gear it represents rolls on the gear's pitch cone (its
    cradle axis through the pitch apex), so the slot width at the pitch cone is the crown
    gear's tooth thickness there, W + h_fm (tan α_IB + tan α_OB) = π m_mn − s_mn2, and the
    gear's normal pressure angle at the pitch cone is the blade angle. With the cradle
    axis through the root apex (face milling before issue 71, branch shell85) the line
    that rolled was the parallel to the pitch generatrix through the root apex, Δ sin δ2
    from it (Δ = t_z2 − t_zR2): on the 12x12 miter (Δ 8.15 mm) the gear's transverse arc
    thickness at the mean pitch point was 3.99 mm instead of ISO 23509's 7.02 mm, its
    teeth pointed at the tip, and the shell and FE tooth models refused every case
    written (``tests/test_synthesis_generated_gear.py``).
    """
    tools = gear_formate_tools(geom, cutter_radius=cutter_radius,
                               blade_angle_drive=blade_angle_drive,
                               blade_angle_coast=blade_angle_coast, point_width=point_width,
                               edge_radius=edge_radius, drive_flank=drive_flank,
                               blade_groups=blade_groups)
    settings = replace(tools.settings, process="Generate",
                       ratio_of_roll=generating_ratio_of_roll(geom.gear))
    settings = _cradle_through_pitch_apex(settings, geom.gear)
    return tools._replace(settings=settings)


def _cradle_through_pitch_apex(settings: MachineSettings,
                               member: MemberBlank) -> MachineSettings:
    """A generated gear's settings (:func:`gear_generate_tools`): the Formate
    gear's cutter pose kept at q = θ = 0, the cradle axis (its direction normal to the
    root plane) moved along the gear axis from the root apex to the pitch apex.

    Why: the pinion of a generated gear rolls on the gear's crown gear (step 5); the
    crown gear's pitch cone (half angle 90° − θ_f about the cradle axis) rolls without slip
    on the gear's pitch cone at R_a = cos θ_f / sin δ only where its apex is the pitch apex,
    and the gear and pinion generated by it are conjugate (Camus) where the cradle, gear
    and pinion axes meet in one point — the pitch apex of a spiral bevel. Through the root
    apex (the Formate gear's machine centre, ``t_zR``) the uniform depth of face hobbing
    puts the cradle axis h_f / sin δ from the pitch apex (16 mm on the 16x16 at Σ 60°),
    and the "conjugate" pinion of the 16x16 carried 253 µm of ease-off; through the pitch
    apex 0.0 µm (``tests/test_synthesis_fh_generated_gear.py``). Face milling's tapered
    depth puts the root apex Δ = t_z − t_zR from the pitch apex too where ISO 23509 gives
    the dedendum angle apart from the apexes (8.15 mm on the 12x12 miter, whose gear tooth
    came out 43 % thin at the mean pitch point through the root apex)."""
    centre, axis = cutter_pose(settings, 0.0, 0.0)
    _, cradle_axis = cradle_pose(settings, 0.0)
    apex = np.array([0.0, 0.0, -member.t_z])
    ps = settings_from_poses(cradle_point=apex, cradle_axis=cradle_axis,
                             cutter_centre=centre, cutter_axis=axis, process="Generate",
                             ratio_of_roll=settings.ratio_of_roll)
    if abs(ps.blank_phase) > 1e-9:
        raise InputError("synthesis.gear_process: the generated gear's cradle "
                         f"cannot be placed at its pitch apex (blank phase {ps.blank_phase:.3g} "
                         "rad)")
    return replace(ps.settings, indexing_ratio=settings.indexing_ratio)


def _face_hobbing_gear_tools(g: MemberBlank, rmf: float, rc0: float, a_ob: float,
                             a_ib: float, slot_width: float, edge_radius: float, m_mn: float,
                             z0: int) -> GearTools:
    """The face-hobbing branch of :func:`gear_formate_tools` (see its Notes)."""
    kappa = indexing_ratio(z0, g.z)
    zp = g.z / math.sin(g.delta_f)
    beta = g.beta_m

    def trace(r: float) -> FaceHobbingTrace:
        # the tip plane is the root plane of a crown gear of z_pf teeth
        try:
            return face_hobbing_trace(rmf, beta, r, z0, zp)
        except InputError as exc:
            raise InputError(f"cutter_radius: {rc0:g} mm is too small for {z0} blade groups "
                             f"({exc})") from None

    mean = trace(rc0)
    nu = mean.nu
    wr = (slot_width - 0.5 * math.pi * m_mn) / math.cos(nu)
    qc = math.atan2(rc0 * math.cos(beta - nu), rmf - rc0 * math.sin(beta - nu))
    theta0 = beta - nu - 0.5 * math.pi - qc
    blades = {}
    for flank, side, sign, alpha in (("concave", "outside", 1, a_ob),
                                     ("convex", "inside", -1, a_ib)):
        rp = rc0 + sign * 0.5 * wr
        blades[flank] = Blade(side, rp, alpha, edge_radius=edge_radius,
                              point_width=slot_width,
                              blade_phase=theta0 + sign * 0.5 * math.pi / z0,
                              blade_offset_angle=trace(rp).nu)
    settings = MachineSettings(
        process="Formate", radial_setting=mean.rho_P0, cradle_angle=qc,
        machine_root_angle=g.delta_f, machine_center_to_back=g.t_zR, indexing_ratio=kappa)
    return GearTools(blades, settings, rmf, wr, rc0, z0)
