"""Equation of meshing: generated points, normals, and the envelope of a crown gear.

The envelope test solves the conventional TCA conditions (seed Eq. 2.14: coincident points,
collinear normals) between each generated point and an independently written generating
crown gear, with scipy.optimize.least_squares.
"""

from __future__ import annotations

import dataclasses
import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from geometry.case import FlankTool, load_case
from geometry.core.errors import InputError
from geometry.machine.cradle import MachineSettings, cutter_pose
from geometry.machine.cutter import Blade, profile_sections
from geometry.machine.flank import flank_surface
from geometry.machine.meshing import REASONS, solve_envelope

CASES = Path(__file__).resolve().parents[1] / "cases"
CASE_FILES = ("spiral_bevel_iso23509_s1.toml", "hypoid_iso23509_s2.toml")
FLANKS = [(m, f) for m in ("pinion", "gear") for f in ("concave", "convex")]
MIRROR = np.array([1.0, -1.0, 1.0])


@cache
def _case(name):
    return load_case(CASES / name)


@cache
def _surface(name, member, flank, nu=21, nv=11):
    return flank_surface(_case(name), member, flank, nu=nu, nv=nv)


@pytest.mark.parametrize("name", CASE_FILES)
@pytest.mark.parametrize("member, flank", FLANKS)
def test_meshing_residual_and_position(name, member, flank):
    """Every generated point satisfies the equation of meshing to < 1e-9 and lies at its
    projection-plane target to < 1e-9 mm (the solver stops at 1e-12 and 1e-10 mm); at least
    97 % of the grid is generated (only Formate root corners at toe/heel lie below the
    cutter's tip plane)."""
    fs = _surface(name, member, flank)
    ok = fs.valid
    assert ok.mean() > 0.97
    assert np.all(np.abs(fs.meshing_residual[ok]) < 1e-9)
    z = fs.position[..., 2]
    rho = np.hypot(fs.position[..., 0], fs.position[..., 1])
    assert np.all(np.abs(z[ok] - fs.grid.axial[ok]) < 1e-9)
    assert np.all(np.abs(rho[ok] - fs.grid.radius[ok]) < 1e-9)
    assert set(np.unique(fs.reason).tolist()) <= set(REASONS)
    assert np.all(np.isnan(fs.position[~ok]))


@pytest.mark.parametrize("name", CASE_FILES)
@pytest.mark.parametrize("member, flank", FLANKS)
def test_unit_normals_and_tangency(name, member, flank):
    """Normals are unit vectors and perpendicular to the surface: chords between grid
    neighbours off the edge radius are ⟂ to the mean normal of their ends (the chord of a
    circle is exactly ⟂ to it; the error is O(step² × curvature change), tolerance 2e-2 on
    the cosine for ~1 mm steps)."""
    fs = _surface(name, member, flank)
    ok = fs.valid
    np.testing.assert_allclose(np.linalg.norm(fs.normal[ok], axis=-1), 1.0, atol=1e-14)
    for axis in (0, 1):
        d = np.diff(fs.position, axis=axis)
        nmean = 0.5 * (np.take(fs.normal, range(fs.normal.shape[axis] - 1), axis=axis)
                       + np.take(fs.normal, range(1, fs.normal.shape[axis]), axis=axis))
        cos = (d * nmean).sum(-1) / np.linalg.norm(d, axis=-1)
        n = fs.section.shape[axis]
        good = (np.isfinite(cos) & (np.take(fs.section, range(n - 1), axis=axis) != 0)
                & (np.take(fs.section, range(1, n), axis=axis) != 0))
        assert np.all(np.abs(cos[good]) < 2e-2)


@pytest.mark.parametrize("name", CASE_FILES)
@pytest.mark.parametrize("member, flank", FLANKS)
def test_normals_point_out_of_the_material(name, member, flank):
    """At the roll that generates it, a point is on the cutter surface; 0.01 mm along the
    normal lies on the tool's side of the blade cone (the cut-away side), 0.01 mm against
    it on the work side (cone geometry in the cutter frame)."""
    case = _case(name)
    mem = case.member(member)
    tool = mem.flank(flank)
    fs = _surface(name, member, flank, 7, 5)
    bl = tool.blade
    sel = fs.valid & (fs.section == profile_sections(bl).main)
    assert sel.sum() > 20
    pts, nrm, q = fs.position[sel], fs.normal[sel], fs.q[sel]
    if mem.hand == "left":  # settings are for the right-hand reference member
        pts, nrm = pts * MIRROR, nrm * MIRROR
    centre, axis = cutter_pose(tool.machine, q)
    for sign, tool_side in ((1.0, True), (-1.0, False)):
        p = pts + sign * 0.01 * nrm - centre
        h = -(p * axis).sum(-1)
        rho = np.linalg.norm(p + h[:, None] * axis, axis=-1)
        cone = _blade_radius(bl, h)
        # outside blade: the tool is inside its cone; inside blade: outside its cone
        inside_tool = (bl.sigma * (cone - rho)) > 0
        assert np.all(inside_tool == tool_side)


def _blade_radius(bl: Blade, h):
    """Closed-form radius of the blade's profile section at height h: the nominal line, or
    the circle of radius R tangent to it at h_ref with centre Q − R n_out."""
    a, sg = bl.blade_angle, bl.sigma
    if bl.profile == "straight":
        return bl.point_radius + sg * h * math.tan(a)
    q = np.array([bl.point_radius + sg * bl.profile_reference_height * math.tan(a),
                  bl.profile_reference_height])
    centre = q - bl.profile_radius * np.array([sg * math.cos(a), -math.sin(a)])
    branch = math.copysign(1.0, q[0] - centre[0])
    return centre[0] + branch * np.sqrt(bl.profile_radius**2 - (h - centre[1]) ** 2)


MOTIONS = {"basic": {},
           "higher_order": dict(modified_roll=(0.05, 0.1, -0.3), helical_motion=(2.0, -3.0),
                                vertical_motion=(1.0, 0.5))}


def _crown_case(hand: str, side_flank: str, motions: str = "basic"):
    """Spiral-bevel pinion blank generated by a crown gear: machine root angle = pitch
    angle, pitch apex at the machine centre, tips at the mean dedendum below the pitch
    plane, ratio of roll 1/sin δ (crown gear of z/sin δ teeth)."""
    case = _case(CASE_FILES[0])
    bl = case.pinion.blank
    d = bl.pitch_angle
    rm = bl.outer_cone_distance - 0.5 * bl.face_width
    rc, beta = 76.2, math.radians(35.0)  # a 6-inch cutter, ISO sample 1 spiral angle
    sr = math.sqrt(rm**2 + rc**2 - 2 * rm * rc * math.sin(beta))
    qc = math.atan2(rc * math.cos(beta), rm - rc * math.sin(beta))
    hfm = 2.394  # ISO 23509 Annex F sample 1, mean dedendum of the pinion h_fm1
    st = MachineSettings(process="Generate", radial_setting=sr, cradle_angle=qc,
                         machine_root_angle=d, machine_center_to_back=bl.pitch_apex,
                         sliding_base=hfm, ratio_of_roll=1.0 / math.sin(d),
                         **MOTIONS[motions])
    side = {"concave": "outside", "convex": "inside"}[side_flank]
    width = 2.5
    blade = Blade(side=side, point_radius=rc + (width if side == "outside" else -width) / 2,
                  blade_angle=math.radians(20.0), edge_radius=0.6)
    pin = dataclasses.replace(case.pinion, hand=hand,
                              **{side_flank: FlankTool(blade, st)})
    return dataclasses.replace(case, pinion=pin), st, blade


@pytest.mark.parametrize("motions", sorted(MOTIONS))
@pytest.mark.parametrize("hand", ["right", "left"])
@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_generated_member_is_envelope_of_crown_gear(hand, flank, motions):
    """Seed Eq. 2.14 between each generated point and the generating crown gear, written
    here independently: crown-gear tooth = the cutter cone on the cradle (centre at
    (S_r cos q_c, ±S_r sin q_c), axis z_m); crown gear turned by ψ about z_m, member by
    φ(ψ) = R_a (ψ − C ψ² − D ψ³) about its axis with R_a = 1/sin δ (machine root angle δ,
    apex at the machine centre), the work moved by the helical motion X_b(ψ) along −z_m and
    the vertical motion E_m(ψ) along y_m. A left-hand member must be the envelope of the
    mirror-image machine: crown gear mirrored in y_m, and with ψ' = −ψ the motions
    φ'(ψ') = −φ(−ψ'), X_b'(ψ') = X_b(−ψ'), E_m'(ψ') = −E_m(−ψ'). Residual of the 6 equations
    after least squares < 1e-9 (mm and unit-normal components)."""
    case, st, blade = _crown_case(hand, flank, motions)
    fs = flank_surface(case, "pinion", flank, nu=5, nv=5, v_limits=(0.3, 1.0))
    sel = fs.valid & (fs.section == profile_sections(blade).main)
    assert sel.sum() >= 20
    gamma = st.machine_root_angle
    a_axis = np.array([math.cos(gamma), 0.0, math.sin(gamma)])
    frame = Rotation.from_euler("y", math.pi / 2 - gamma).as_matrix()  # member → machine
    mirror = -1.0 if hand == "left" else 1.0
    centre = np.array([st.radial_setting * math.cos(st.cradle_angle),
                       mirror * st.radial_setting * math.sin(st.cradle_angle), 0.0])
    sg, al = blade.sigma, blade.blade_angle
    ez = np.array([0.0, 0.0, 1.0])

    def poly(c0, derivs, x):
        return c0 + sum(dk * x**k / math.factorial(k) for k, dk in enumerate(derivs, 1))

    def motions_at(psi):
        """Work rotation, sliding base and blank offset at cradle roll psi (this hand)."""
        x = mirror * psi  # the right-hand machine's roll
        c = [0.0, 1.0] + [-v for v in st.modified_roll]  # φ/R_a as Taylor derivatives
        phi = st.ratio_of_roll * poly(0.0, c[1:], x)
        xb = poly(st.sliding_base, st.helical_motion, x)
        em = poly(st.blank_offset, st.vertical_motion, x)
        return mirror * phi, xb, mirror * em

    def crown(h, th, psi):
        er = np.array([math.cos(th), math.sin(th), 0.0])
        x = centre + (blade.point_radius + sg * h * math.tan(al)) * er - h * ez
        n = -sg * math.cos(al) * er - math.sin(al) * ez  # out of the work, into the tool
        rot = Rotation.from_rotvec(psi * ez).as_matrix()
        return rot @ x, rot @ n

    def member(p, n, psi):
        phi, xb, em = motions_at(psi)
        origin = np.array([0.0, em, -xb]) + st.machine_center_to_back * a_axis
        rot = frame @ Rotation.from_rotvec(phi * ez).as_matrix()
        return origin + rot @ p, rot @ n

    worst = 0.0
    for p, n, q in zip(fs.position[sel], fs.normal[sel], fs.q[sel], strict=True):
        psi0 = mirror * q
        xm, _ = member(p, n, psi0)
        d = xm - Rotation.from_rotvec(psi0 * ez).as_matrix() @ centre
        th0 = math.atan2(d[1], d[0]) - psi0

        def res(x, p=p, n=n):
            xc, nc = crown(*x)
            xw, nw = member(p, n, x[2])
            return np.concatenate([xw - xc, nw - nc])

        sol = least_squares(res, [-d[2], th0, psi0], xtol=1e-15, ftol=1e-15, gtol=1e-15)
        worst = max(worst, float(np.abs(sol.fun).max()))
    assert worst < 1e-9


def test_no_envelope_inside_the_blank_raises():
    """Settings that put the cutter far from the blank give a clear InputError."""
    case = _case(CASE_FILES[1])
    tool = case.gear.concave
    far = dataclasses.replace(tool.machine, radial_setting=tool.machine.radial_setting + 400.0)
    bl = case.gear.blank
    with pytest.raises(InputError, match="no envelope solution"):
        solve_envelope(tool.blade, far, np.array([[60.0]]), np.array([[70.0]]),
                       length_scale=bl.outer_cone_distance, depth=7.0)


def test_bad_targets_raise():
    """Non-finite or mismatched targets are rejected before any numerics."""
    tool = _case(CASE_FILES[0]).gear.concave
    with pytest.raises(InputError, match="axial, radius"):
        solve_envelope(tool.blade, tool.machine, np.zeros(3), np.ones(2), length_scale=90.0,
                       depth=7.0)
    with pytest.raises(InputError, match="finite"):
        solve_envelope(tool.blade, tool.machine, np.array([np.nan]), np.ones(1),
                       length_scale=90.0, depth=7.0)


def test_toprem_and_flankrem_sections_generate_their_cones():
    """A Formate gear cut by a blade with toprem and flankrem: points generated by each
    straight section lie on that section's own cone (closed form ρ = ρ_J + σ (h − h_J)
    tan(α + Δα)); the three sections all appear on the grid."""
    case = _case(CASE_FILES[0])
    tool = case.gear.concave
    bl = dataclasses.replace(tool.blade, toprem_angle=math.radians(6.0), toprem_height=2.5,
                             flankrem_angle=math.radians(-6.0), flankrem_height=6.0)
    gear = dataclasses.replace(case.gear, concave=FlankTool(bl, tool.machine))
    fs = flank_surface(dataclasses.replace(case, gear=gear), "gear", "concave", nu=9, nv=15)
    sec = profile_sections(bl)
    used = {sec.names[k] for k in np.unique(fs.section[fs.valid])}
    assert {"toprem", "profile", "flankrem"} <= used
    centre, axis = cutter_pose(tool.machine, 0.0)
    for name, angle, h_j in (("toprem", bl.blade_angle + bl.toprem_angle, bl.toprem_height),
                             ("flankrem", bl.blade_angle + bl.flankrem_angle,
                              bl.flankrem_height)):
        k = sec.names.index(name)
        sel = fs.valid & (fs.section == k)
        p = fs.position[sel] - centre
        h = -(p @ axis)
        rho = np.linalg.norm(p + h[:, None] * axis, axis=-1)
        rho_j = bl.point_radius + bl.sigma * h_j * math.tan(bl.blade_angle)
        np.testing.assert_allclose(rho, rho_j + bl.sigma * (h - h_j) * math.tan(angle),
                                   atol=1e-9)
