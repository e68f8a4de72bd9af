"""Surface velocities (friction.kinematics) against closed forms of crossed-axis kinematics.

Independent reference: the relative velocity of two members turning about crossed axes
is affine in the point, v₁₂(r) = Ω × r + c, so its smallest magnitude over all points is
|Ω·c|/|Ω|, reached on the axis of the relative screw motion (Litvin & Fuentes 2004,
§6.1): zero for intersecting axes (spiral bevel: pure rolling on the pitch-cone
generatrix) and growing linearly with the hypoid offset.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from friction.kinematics import surface_velocities
from geometry.errors import InputError

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
    "name", ["kolivand2009_fm_11x41", "iso23509_sample2_fm", "kolivand2009_table54_B_fm"]
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
    from geometry.basic_design import load_basic
    from geometry.case import load_case
    from geometry.pitch_cone import pitch_cone

    root = Path(__file__).resolve().parents[1] / "cases"
    pc = pitch_cone(load_basic(root / "basic" / f"{name}.toml").design)
    case = load_case(root / f"{name}.toml")
    kin = mesh_kinematics(case)
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
