"""Surface velocities (friction.kinematics) against closed forms of crossed-axis kinematics.

Independent reference: the relative velocity of two members turning about crossed axes
is affine in the point, v₁₂(r) = Ω × r + c, so its smallest magnitude over all points is
|Ω·c|/|Ω|, reached on the axis of the relative screw motion (Litvin & Fuentes 2004,
§6.1): zero for intersecting axes (spiral bevel: pure rolling on the pitch-cone
generatrix) and growing linearly with the hypoid offset.

Process-agnostic (design note FACE_HOBBING.md §6): on the face-hobbed example pair
(tests/data/fh_iso23509_s2_crown.toml) the friction stage's sliding and rolling velocities
and slide-to-roll ratios equal the velocities of material points moved by the assembly's
own member transforms (geometry.pair.assembly.case_transforms, central differences), its
equivalent radii the flank curvatures at the contact points (geometry.machine.flank.flank_at), and
its outputs depend on nothing but the contact geometry it is given.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from friction.efficiency import efficiency_analysis
from friction.kinematics import surface_velocities
from geometry.core.errors import InputError

FH_EXAMPLE = Path(__file__).resolve().parent / "data" / "fh_iso23509_s2_crown.toml"

N_P = 1500.0  # rpm
RATIO = 41 / 11


def _axes(offset):
    # gear axis z through the origin; pinion axis x through (0, -offset, 0); Σ = 90°
    return dict(
        pinion_axis=np.array([1.0, 0.0, 0.0]),
        pinion_origin=np.array([0.0, -offset, 0.0]),
        gear_axis=np.array([0.0, 0.0, 1.0]),
        gear_origin=np.zeros(3),
    )


def _screw(offset):
    """Ω, c of v₁₂(r) = Ω × r + c [per mm → m/s], computed from the axes directly."""
    ax = _axes(offset)
    wp = 2 * math.pi * N_P / 60
    wg = -wp / RATIO
    omega = (wp * ax["pinion_axis"] - wg * ax["gear_axis"]) * 1e-3
    c = (
        -wp * np.cross(ax["pinion_axis"], ax["pinion_origin"])
        + wg * np.cross(ax["gear_axis"], ax["gear_origin"])
    ) * 1e-3
    return omega, c


def _frame_normal_to(v):
    n = np.cross(v, [0.3, 0.5, 0.8]) if np.linalg.norm(v) > 0 else np.array([0.0, 0.0, 1.0])
    n /= np.linalg.norm(n)
    t = np.cross(n, [0.1, 0.9, 0.2])
    return n, t / np.linalg.norm(t)


@pytest.mark.parametrize("offset", [0.0, 10.0, 20.0, 40.0])
def test_minimum_sliding_equals_the_screw_closed_form(offset):
    omega, c = _screw(offset)
    r_star = np.cross(omega, c) / (omega @ omega)  # point on the relative screw axis
    v_rel = np.cross(omega, r_star) + c
    n, t = _frame_normal_to(v_rel)  # a contact normal must be ⊥ v₁₂ (meshing)
    out = surface_velocities(r_star, n, t, pinion_speed=N_P, ratio=RATIO, **_axes(offset))
    expected = abs(omega @ c) / np.linalg.norm(omega)
    assert out["sliding_velocity"] == pytest.approx(expected, rel=1e-9, abs=1e-12)
    if offset == 0:
        assert out["sliding_velocity"] < 1e-12  # pure rolling on the pitch generatrix


def test_sliding_grows_linearly_with_offset():
    mins = []
    for e in (5.0, 10.0, 20.0):
        omega, c = _screw(e)
        mins.append(abs(omega @ c) / np.linalg.norm(omega))
    assert mins[0] < mins[1] < mins[2]
    assert mins[2] / mins[1] == pytest.approx(2.0, rel=1e-9)


def test_velocities_and_slide_to_roll_identities():
    # at an arbitrary meshing point: v_p − v_g is tangential, SR = sliding across / rolling
    omega, c = _screw(20.0)
    r = np.array([30.0, 15.0, 70.0])
    v_rel = np.cross(omega, r) + c
    n, t = _frame_normal_to(v_rel)
    out = surface_velocities(r, n, t, pinion_speed=N_P, ratio=RATIO, **_axes(20.0))
    vs = out["pinion_tangential"] - out["gear_tangential"]
    np.testing.assert_allclose(vs, v_rel, rtol=1e-12, atol=1e-15)
    assert out["sliding_velocity"] == pytest.approx(
        math.hypot(out["sliding_along"], out["sliding_across"]), rel=1e-12
    )
    assert out["slide_to_roll"] == pytest.approx(out["sliding_across"] / out["rolling_velocity"])
    # surface speed of the pinion = ω_p × distance from its axis
    d = np.linalg.norm(np.cross(_axes(20.0)["pinion_axis"], r - _axes(20.0)["pinion_origin"]))
    assert np.linalg.norm(out["pinion_velocity"]) == pytest.approx(
        2 * math.pi * N_P / 60 * d * 1e-3, rel=1e-12
    )


def test_bad_input():
    ax = _axes(10.0)
    with pytest.raises(InputError, match="normals"):
        surface_velocities(
            [1.0, 2.0, 3.0], [0, 0, 2.0], [1.0, 0, 0], pinion_speed=N_P, ratio=RATIO, **ax
        )
    with pytest.raises(InputError, match="pinion_speed"):
        surface_velocities(
            [1.0, 2.0, 3.0], [0, 0, 1.0], [1.0, 0, 0], pinion_speed=-1.0, ratio=RATIO, **ax
        )
    with pytest.raises(InputError, match="not contact points"):
        # a normal along the relative velocity cannot be a contact normal
        omega, c = _screw(10.0)
        r = np.array([30.0, 15.0, 70.0])
        v = np.cross(omega, r) + c
        n = v / np.linalg.norm(v)
        t = np.cross(n, [0, 0, 1.0])
        surface_velocities(r, n, t / np.linalg.norm(t), pinion_speed=N_P, ratio=RATIO, **ax)


@pytest.mark.parametrize(
    "name", ["kolivand2009_fm_11x41", "iso23509_sample2_fm", "kolivand2009_table54_B_fh"]
)
def test_mean_pitch_point_against_the_pitch_cone_hand_calculation(name):
    # The mean pitch point P of the ISO 23509 pitch cones (radius d_m/2 and axial place
    # −t_z + R_m cos δ on both members) is located in the toolkit's pair frame; there the
    # pitch-cone relations of hypoid gearing hold: v₁ cos β₁ = v₂ cos β₂ across the tooth
    # trace (rolling), V_s = v₁ sin β₁ − v₂ sin β₂ along it (sliding), with v = ω d_m/2
    # (ISO 23509 §5; Litvin & Fuentes 2004, ch. 21). Issue tolerance 2 %; the vector
    # kinematics reproduce the hand values to round-off.
    from pathlib import Path

    from scipy.optimize import least_squares

    from contact.utca.action_surface import mesh_kinematics
    from geometry.case import load_case
    from geometry.iso23509.pitch_cone import pitch_cone
    from geometry.pair.assembly import Misalignment
    from geometry.synthesis.basic_design import load_basic

    root = Path(__file__).resolve().parents[1] / "cases"
    pc = pitch_cone(load_basic(root / "basic" / f"{name}.toml").design)
    case = load_case(root / f"{name}.toml")
    kin = mesh_kinematics(case, Misalignment())  # aligned (the pitch-cone identities)
    members = (
        (kin.pinion_axis, kin.pinion_origin, pc.t_z1, pc.Rm1, pc.delta1, pc.dm1),
        (kin.gear_axis, kin.gear_origin, pc.t_z2, pc.Rm2, pc.delta2, pc.dm2),
    )

    def residual(p):
        out = []
        for a, o, tz, rm, delta, dm in members:
            r = p - o
            axial = r @ a
            out += [axial - (-tz + rm * math.cos(delta)), np.linalg.norm(r - axial * a) - dm / 2]
        return out

    start = kin.gear_origin + np.array([pc.dm2 / 2, 0.0, -pc.t_z2 + pc.Rm2 * math.cos(pc.delta2)])
    sol = least_squares(residual, start, xtol=1e-15, ftol=1e-15)
    assert np.max(np.abs(sol.fun)) < 1e-6  # the pitch cones touch at P in our frame
    p = sol.x
    ratio = case.gear.blank.teeth / case.pinion.blank.teeth
    w1 = 2 * math.pi * N_P / 60
    v1, v2 = w1 * pc.dm1 / 2e3, w1 / ratio * pc.dm2 / 2e3
    vp = w1 * np.cross(kin.pinion_axis, p - kin.pinion_origin)
    vg = -w1 / ratio * np.cross(kin.gear_axis, p - kin.gear_origin)
    n = np.cross(vp, vg)  # the pitch-plane normal
    n /= np.linalg.norm(n)
    trace = (vp - vg) / np.linalg.norm(vp - vg)  # relative velocity runs along the trace
    out = surface_velocities(
        p,
        n,
        trace,
        pinion_speed=N_P,
        ratio=ratio,
        pinion_axis=kin.pinion_axis,
        pinion_origin=kin.pinion_origin,
        gear_axis=kin.gear_axis,
        gear_origin=kin.gear_origin,
    )
    hand_sliding = v1 * math.sin(pc.beta_m1) - v2 * math.sin(pc.beta_m2)
    hand_rolling = v1 * math.cos(pc.beta_m1)
    assert v1 * math.cos(pc.beta_m1) == pytest.approx(v2 * math.cos(pc.beta_m2), rel=1e-9)
    assert float(out["sliding_velocity"]) == pytest.approx(hand_sliding, rel=0.02)
    assert float(out["rolling_velocity"]) == pytest.approx(hand_rolling, rel=0.02)


# ------------------------------------------------------------------ face hobbing
@functools.cache
def _fh_ltca():
    """The face-hobbed example pair loaded at T_p = 250 N m (a coarse LTCA: one mesh cycle,
    6 roll positions, 12 segments per contact curve) and its friction stage at N_P."""
    from contact.ltca import LTCAOptions, loaded_tca
    from geometry.case import load_case

    case = load_case(FH_EXAMPLE)
    assert case.pair.method == "FH" and case.pinion.blade_groups == case.gear.blade_groups == 5
    ltca = loaded_tca(case, [250.0], options=LTCAOptions(cycles=1, rolls_per_cycle=6,
                                                         segments=12))
    return case, ltca, efficiency_analysis(ltca, pinion_speed=N_P)


def _rigid_velocity(case, member, points, omega, step=1e-6):
    """Velocity [m/s] of the material points of ``member`` now at ``points`` (pair frame,
    mm) turning at ``omega`` [rad/s] about its own +z axis: central differences of the
    assembly's member → pair transforms at rotations ±step [rad]."""
    from geometry.pair.assembly import case_transforms, transform_points

    k = 0 if member == "pinion" else 1
    in_member = transform_points(np.linalg.inv(case_transforms(case)[k]), points)
    ahead = transform_points(case_transforms(case, step, step)[k], in_member)
    behind = transform_points(case_transforms(case, -step, -step)[k], in_member)
    return omega * (ahead - behind) / (2.0 * step) * 1e-3


def _curvature_at(case, member, flank, points, direction):
    """Normal curvature [1/mm] (convex positive) of ``member``'s generated ``flank`` at pair-
    frame ``points`` along pair-frame ``direction`` (projected on its tangent plane): the
    flank point at the same axial position and radius (geometry.machine.flank.flank_at), turned
    about the member axis onto the point."""
    from geometry.machine.curvature import normal_curvature
    from geometry.machine.flank import flank_at
    from geometry.pair.assembly import case_transforms, transform_points, transform_vectors

    to_pair = case_transforms(case)[0 if member == "pinion" else 1]
    pm = transform_points(np.linalg.inv(to_pair), points)
    fs = flank_at(case, member, flank, pm[:, 2], np.hypot(pm[:, 0], pm[:, 1]))
    turn = np.arctan2(pm[:, 1], pm[:, 0]) - np.arctan2(fs.position[:, 1], fs.position[:, 0])
    c, s = np.cos(turn)[:, None], np.sin(turn)[:, None]

    def turned(v):
        return np.column_stack([c[:, 0] * v[:, 0] - s[:, 0] * v[:, 1],
                                s[:, 0] * v[:, 0] + c[:, 0] * v[:, 1], v[:, 2]])

    assert np.allclose(turned(fs.position), pm, atol=1e-6)
    normal = transform_vectors(to_pair, turned(fs.normal))
    tangent = direction - np.sum(direction * normal, axis=1)[:, None] * normal
    return normal_curvature(fs.kappa1, fs.kappa2, transform_vectors(to_pair, turned(fs.dir1)),
                            tangent)


def test_face_hobbed_contacts_kinematics_from_rigid_rotations_and_flank_curvatures():
    """Every loaded segment of the FH example's LTCA: the friction stage's sliding speed,
    entraining speed and slide-to-roll ratio (seed Eq. 5.1–5.6) equal those built here from
    the velocities of the material points under the assembly's own rotations (ω_p = 2π n/60
    about the pinion's +z, ω_g = −ω_p z1/z2 about the gear's; not the axes stored in the
    dataset) within 1e-7 (central differences, step 1e-6 rad: truncation ~1e-12, rounding
    ~1e-9; measured 7e-10). On the contact curves (edge contacts take the edge rounding),
    R_eq = 1/(κ_p + κ_g) across the contact line from the flank curvatures at the contact
    point, within 2 %: the example is not a conjugate pair (its unloaded TE reaches 6 mrad),
    and the LTCA takes the pinion's curvature at the mate of the gear point under the
    ideal motion, a few tenths of a mm from the loaded contact (6 mrad at ~70 mm; measured
    ≤ 1.6 %, median 0.9 %; the gear's flank normal at the point is the contact normal to
    1e-15). Nothing here knows the process."""
    case, ltca, fr = _fh_ltca()
    force = ltca["force"].values[0]
    loaded = np.isfinite(force) & (force > 0)
    assert loaded.sum() > 20
    r = ltca["contact_point"].values[loaded]
    n = ltca["contact_normal"].values[loaded]
    t = ltca["contact_tangent"].values[loaded]
    w_p = 2 * math.pi * N_P / 60
    ratio = case.gear.blank.teeth / case.pinion.blank.teeth
    v_p = _rigid_velocity(case, "pinion", r, w_p)
    v_g = _rigid_velocity(case, "gear", r, -w_p / ratio)
    vpt = v_p - np.sum(v_p * n, axis=1)[:, None] * n
    vgt = v_g - np.sum(v_g * n, axis=1)[:, None] * n
    across = np.cross(n, t)
    v_s = vpt - vgt
    rolling = np.abs(0.5 * np.sum((vpt + vgt) * across, axis=1))
    expected = {"sliding_velocity": np.linalg.norm(v_s, axis=1), "rolling_velocity": rolling,
                "slide_to_roll": np.sum(v_s * across, axis=1) / rolling}
    for key, value in expected.items():
        np.testing.assert_allclose(fr[key].values[0][loaded], value, rtol=1e-7, atol=1e-9)
    curve = loaded & (np.broadcast_to(ltca["segment_kind"].values, force.shape) == "curve")
    assert curve.sum() > 10
    r, n, t = (ltca[k].values[curve] for k in ("contact_point", "contact_normal",
                                               "contact_tangent"))
    across = np.cross(n, t)
    k_rel = (_curvature_at(case, "pinion", ltca.attrs["pinion_flank"], r, across)
             + _curvature_at(case, "gear", ltca.attrs["gear_flank"], r, across))
    np.testing.assert_allclose(ltca["equivalent_radius"].values[curve], 1.0 / k_rel,
                               rtol=0.02)


def test_friction_stage_reads_only_the_contact_geometry():
    """The friction stage of the FH example gets the same results from a dataset holding
    only the loads and the contact geometry (points, normals, tangents, R_eq, segment
    lengths; the axes, ratio and material) under a face-milled case's name: nothing in it
    depends on the cutting process (the LTCA dataset does not even record it)."""
    _, ltca, fr = _fh_ltca()
    # (and ``found``, the certification of each roll: a roll without a certified contact
    # solution has no efficiency, issue 64 — this coarse FH example's first roll collapses
    # plastically at 250 N m)
    needed = ("force", "load_per_length", "pressure_max", "segment_length",
              "equivalent_radius", "contact_point", "contact_normal", "contact_tangent",
              "found")
    keep = ("pinion_axis", "pinion_origin_mm", "gear_axis", "gear_origin_mm", "ratio",
            "options")
    bare = xr.Dataset({k: ltca[k] for k in needed},
                      attrs={**{k: ltca.attrs[k] for k in keep},
                             "case": "kolivand2009_fm_11x41"})
    out = efficiency_analysis(bare, pinion_speed=N_P)
    for key in fr.data_vars:
        # the same computation on the same numbers: equal to round-off (1e-12 relative),
        # attributes identical
        a, b = out[key].reset_coords(drop=True), fr[key].reset_coords(drop=True)
        xr.testing.assert_allclose(a, b, rtol=1e-12, atol=0)
        assert a.attrs.keys() == b.attrs.keys(), key
        for name, value in a.attrs.items():
            np.testing.assert_array_equal(value, b.attrs[name], err_msg=f"{key}.{name}")
