"""Blades, cutter surfaces and the cradle-type machine chain (seed Eq. 2.5–2.7).

Each numeric check is against a closed form, a finite difference, an independent
re-implementation of the documented chain (scipy Rotation, ``docs/machine.md``), or an
identity the equations must satisfy.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.cradle import (
    MachineSettings,
    cutter_pose,
    machine_transform,
    mirror_settings,
    roll_angle,
    settings_from_poses,
)
from geometry.machine.cutter import (
    Blade,
    blade_profile,
    cutter_curvatures,
    cutter_surface,
    profile_sections,
)
from geometry.machine.family import generated_family, meshing_function
from geometry.machine.flank import flank_surface

CASES = Path(__file__).resolve().parents[1] / "cases"
D = math.radians


def _blades():
    kw = dict(point_radius=60.0, blade_angle=D(20.0))
    return [
        Blade(side="outside", **kw),
        Blade(side="inside", edge_radius=1.0, **kw),
        Blade(side="outside", edge_radius=1.0, profile="circular", profile_radius=250.0,
              profile_reference_height=4.0, **kw),
        Blade(side="inside", edge_radius=0.8, profile="circular", profile_radius=-300.0,
              profile_reference_height=3.0, **kw),
        Blade(side="outside", edge_radius=0.8, toprem_angle=D(4.0), toprem_height=2.0,
              flankrem_angle=D(-5.0), flankrem_height=8.0, **kw),
        Blade(side="inside", edge_radius=0.8, profile="circular", profile_radius=200.0,
              profile_reference_height=5.0, toprem_angle=D(4.0), toprem_height=2.0,
              flankrem_angle=D(-5.0), flankrem_height=8.0, **kw),
    ]


GENERIC = MachineSettings(
    process="Generate", radial_setting=70.0, cradle_angle=0.9, swivel=0.3, tilt=0.2,
    machine_root_angle=0.35, machine_center_to_back=3.0, sliding_base=1.5, blank_offset=12.0,
    ratio_of_roll=2.7, modified_roll=(0.05, -0.1, 0.2, 0.3), helical_motion=(1.0, 2.0, -3.0),
    vertical_motion=(0.5, -1.0, 2.0))


@pytest.mark.parametrize("blade", _blades(), ids=lambda b: f"{b.side}-{b.profile}")
def test_blade_sections_join(blade):
    """Sections meet in position everywhere; the tangent is continuous except at the toprem
    and flankrem corners, where those straight sections have the blade angle α + Δα
    (closed form: angle of the tangent from the cutter axis)."""
    sec = profile_sections(blade)
    sg = blade.sigma
    for k in range(len(sec.names) - 1):
        a = blade_profile(sec, sec.s_hi[k], k)
        b = blade_profile(sec, sec.s_hi[k], k + 1)
        # positions: 1e-12 mm is rounding of 60 mm coordinates
        assert math.hypot(a.rho - b.rho, a.h - b.h) < 1e-12
        turn = abs(math.atan2(a.drho * b.dh - a.dh * b.drho, a.drho * b.drho + a.dh * b.dh))
        assert (turn > 1e-3) if sec.corner_above[k] else (turn < 1e-12)
    for k, name in enumerate(sec.names):
        if name in ("toprem", "flankrem"):
            p = blade_profile(sec, 0.5 * (sec.s_lo[k] + min(sec.s_hi[k], sec.s_lo[k] + 2)), k)
            angle = math.atan2(sg * float(p.drho), float(p.dh))
            assert angle == pytest.approx(
                blade.blade_angle + getattr(blade, f"{name}_angle"), abs=1e-13)


def test_straight_blade_closed_form():
    """Straight profile ρ = r_p + σ h tan α; edge arc tangent to the tip plane at s = 0 and
    r_e (π/2 − α) long (plane geometry)."""
    for side, sg in (("outside", 1), ("inside", -1)):
        b = Blade(side=side, point_radius=60.0, blade_angle=D(20.0), edge_radius=1.0)
        sec = profile_sections(b)
        s = np.linspace(sec.s_hi[0], 10.0, 7)
        p = blade_profile(b, s)
        np.testing.assert_allclose(p.rho, 60.0 + sg * p.h * math.tan(D(20.0)), atol=1e-12)
        p0 = blade_profile(b, 0.0)
        assert float(p0.h) == pytest.approx(0.0, abs=1e-15)
        assert float(p0.dh) == pytest.approx(0.0, abs=1e-15)
        assert sec.s_hi[0] == pytest.approx(1.0 * (math.pi / 2 - D(20.0)), rel=1e-14)


def test_circular_profile_closed_form():
    """A circular profile is at distance |R| from its centre and tangent to the nominal line
    at the reference height (circle through Q with tangent d: centre Q − R n_out)."""
    for side, sg in (("outside", 1), ("inside", -1)):
        for radius in (250.0, -300.0):
            b = Blade(side=side, point_radius=60.0, blade_angle=D(20.0), edge_radius=0.5,
                      profile="circular", profile_radius=radius, profile_reference_height=4.0)
            a = D(20.0)
            q = np.array([60.0 + sg * 4.0 * math.tan(a), 4.0])
            n_out = np.array([sg * math.cos(a), -math.sin(a)])
            centre = q - radius * n_out
            sec = profile_sections(b)
            s = np.linspace(sec.s_lo[sec.main], sec.s_lo[sec.main] + 12.0, 9)
            p = blade_profile(b, s)
            dist = np.hypot(p.rho - centre[0], p.h - centre[1])
            np.testing.assert_allclose(dist, abs(radius), rtol=1e-13)
            # at the reference height the edge passes through Q along the nominal direction
            s_q = sec.s_ref[sec.main]
            pq = blade_profile(b, s_q)
            assert float(pq.rho) == pytest.approx(q[0], abs=1e-12)
            assert float(pq.drho) == pytest.approx(sg * math.sin(a), abs=1e-13)


@pytest.mark.parametrize("blade", _blades(), ids=lambda b: f"{b.side}-{b.profile}")
def test_cutter_surface_derivatives(blade):
    """Analytic derivatives of r_t(s, θ) against central differences (step 1e-5: truncation
    ~1e-10, rounding ~1e-11 for 60 mm coordinates; tolerance 1e-8)."""
    sec = profile_sections(blade)
    s = np.array([0.3, 2.5, 5.0, 9.0])
    k = np.searchsorted(sec.s_hi, s)
    th = np.array([0.2, -0.4, 1.1, 3.0])
    h = 1e-5
    c = cutter_surface(blade, s, th, k)
    cps, cms = cutter_surface(blade, s + h, th, k), cutter_surface(blade, s - h, th, k)
    cpt, cmt = cutter_surface(blade, s, th + h, k), cutter_surface(blade, s, th - h, k)
    for fd, an in (((cps.r - cms.r) / (2 * h), c.r_s), ((cpt.r - cmt.r) / (2 * h), c.r_theta),
                   ((cps.r_s - cms.r_s) / (2 * h), c.r_ss),
                   ((cpt.r_s - cmt.r_s) / (2 * h), c.r_stheta),
                   ((cpt.r_theta - cmt.r_theta) / (2 * h), c.r_thetatheta)):
        np.testing.assert_allclose(fd, an, atol=1e-8)


@pytest.mark.parametrize("blade", _blades(), ids=lambda b: f"{b.side}-{b.profile}")
def test_cutter_normal_unit_and_side(blade):
    """Unit normal ⟂ both tangents; it points out of the work, i.e. into the tool: towards
    the cutter axis for an outside blade, away from it for an inside blade."""
    s = np.linspace(0.1, 9.0, 12)
    th = np.linspace(-1, 1, 12)
    c = cutter_surface(blade, s, th)
    np.testing.assert_allclose(np.linalg.norm(c.normal, axis=-1), 1.0, atol=1e-15)
    np.testing.assert_allclose((c.normal * c.r_s).sum(-1), 0.0, atol=1e-14)
    np.testing.assert_allclose((c.normal * c.r_theta).sum(-1), 0.0, atol=1e-13)
    radial = c.r[..., :2] / np.linalg.norm(c.r[..., :2], axis=-1, keepdims=True)
    outward = (c.normal[..., :2] * radial).sum(-1)
    prof = s > profile_sections(blade).s_hi[0]
    assert np.all(-blade.sigma * outward[prof] > 0)


def test_cutter_curvatures_closed_form():
    """Straight cone: κ_meridian = 0, κ_parallel = −σ cos α / ρ (concave for the outside
    blade); edge radius: κ_meridian = −1/r_e (a fillet is concave)."""
    for side, sg in (("outside", 1), ("inside", -1)):
        b = Blade(side=side, point_radius=60.0, blade_angle=D(20.0), edge_radius=0.8)
        s = np.array([3.0, 6.0])
        km, kp = cutter_curvatures(b, s)
        rho = blade_profile(b, s).rho
        np.testing.assert_allclose(km, 0.0, atol=1e-15)
        np.testing.assert_allclose(kp, -sg * math.cos(D(20.0)) / rho, rtol=1e-14)
        km0, _ = cutter_curvatures(b, np.array([0.2]))
        np.testing.assert_allclose(km0, -1.0 / 0.8, rtol=1e-14)


def test_machine_transform_rigid_and_derivatives():
    """M(q) is a proper rigid motion; dM/dq and d²M/dq² match central differences
    (step 1e-5, tolerance 1e-7 on entries of order 100 mm)."""
    q = np.array([-0.3, 0.0, 0.17])
    m, dm, d2m = machine_transform(GENERIC, q)
    r = m[..., :3, :3]
    np.testing.assert_allclose(r @ np.swapaxes(r, -1, -2), np.broadcast_to(np.eye(3), r.shape),
                               atol=1e-15)
    np.testing.assert_allclose(np.linalg.det(r), 1.0, atol=1e-14)
    h = 1e-5
    mp, dmp, _ = machine_transform(GENERIC, q + h)
    mm, dmm, _ = machine_transform(GENERIC, q - h)
    np.testing.assert_allclose((mp - mm) / (2 * h), dm, atol=1e-7)
    np.testing.assert_allclose((dmp - dmm) / (2 * h), d2m, atol=1e-7)


def _reference_chain(st: MachineSettings, q: float, phi: float, xb: float, em: float):
    """The chain of docs/machine.md written independently with scipy rotations."""
    def rot(axis, a):
        return Rotation.from_euler(axis, a).as_matrix()

    def apply(p):
        p = rot("x", st.tilt) @ p
        p = rot("z", st.swivel) @ p
        p = p + np.array([st.radial_setting, 0.0, 0.0])
        p = rot("z", st.cradle_angle + q) @ p
        p = p + np.array([0.0, -em, xb])
        p = rot("y", st.machine_root_angle - math.pi / 2) @ p
        p = p - np.array([0.0, 0.0, st.machine_center_to_back])
        return rot("z", -phi) @ p

    return apply


def test_generated_family_matches_documented_chain():
    """generated_family (fast vector path) and machine_transform (4×4) both reproduce the
    documented chain evaluated with scipy rotations, including modified roll, helical and
    vertical motions (closed-form polynomials); tolerance 1e-12 mm."""
    blade = _blades()[2]
    s, th, q = 4.0, 0.3, 0.12
    fam = generated_family(blade, GENERIC, s, th, q)
    ra = GENERIC.ratio_of_roll
    c2, d6, e24, f120 = GENERIC.modified_roll
    phi = ra * (q - c2 / 2 * q**2 - d6 / 6 * q**3 - e24 / 24 * q**4 - f120 / 120 * q**5)
    h1, h2, h3 = GENERIC.helical_motion
    v1, v2, v3 = GENERIC.vertical_motion
    xb = GENERIC.sliding_base + h1 * q + h2 * q**2 / 2 + h3 * q**3 / 6
    em = GENERIC.blank_offset + v1 * q + v2 * q**2 / 2 + v3 * q**3 / 6
    ref = _reference_chain(GENERIC, q, phi, xb, em)
    rt = cutter_surface(blade, s, th).r
    np.testing.assert_allclose(fam.r, ref(rt), atol=1e-12)
    m, _, _ = machine_transform(GENERIC, q)
    np.testing.assert_allclose(m[:3, :3] @ rt + m[:3, 3], ref(rt), atol=1e-12)
    assert float(roll_angle(GENERIC, q)[0]) == pytest.approx(phi, rel=1e-15)


def test_family_derivatives_and_meshing_gradient():
    """All derivatives of r_g(s, θ, q) and the gradient of the meshing function against
    central differences (step 1e-6; tolerance 1e-6 relative to the derivative scale)."""
    blade = _blades()[3]
    s, th, q = np.array([0.5, 3.0, 7.0]), np.array([0.1, -0.2, 0.3]), np.array([-0.2, 0.0, 0.13])
    f0 = generated_family(blade, GENERIC, s, th, q)
    mf, grad = meshing_function(f0, 100.0)
    h = 1e-6
    pairs = {0: ("r_s", "r_ss", "r_stheta", "r_sq"), 1: ("r_theta", "r_stheta", "r_thetatheta",
                                                          "r_thetaq"),
             2: ("r_q", "r_sq", "r_thetaq", "r_qq")}
    for k, names in pairs.items():
        dv = np.zeros(3)
        dv[k] = h
        fp = generated_family(blade, GENERIC, s + dv[0], th + dv[1], q + dv[2])
        fm = generated_family(blade, GENERIC, s - dv[0], th - dv[1], q - dv[2])
        for base, an in zip(("r", "r_s", "r_theta", "r_q"), names, strict=True):
            fd = (getattr(fp, base) - getattr(fm, base)) / (2 * h)
            scale = max(1.0, np.abs(getattr(f0, an)).max())
            np.testing.assert_allclose(fd, getattr(f0, an), atol=1e-6 * scale)
        gp, _ = meshing_function(fp, 100.0)
        gm, _ = meshing_function(fm, 100.0)
        np.testing.assert_allclose((gp - gm) / (2 * h), grad[:, k], atol=1e-6)
    assert mf.shape == (3,)


def test_mirror_settings_generate_the_mirror_image():
    """Conjugating the chain by D = diag(1, −1, 1) and q → −q: the mirrored settings generate
    D r_g(s, θ, q) at (s, −θ, −q) (identity; 1e-12 mm)."""
    blade = _blades()[4]
    s, th, q = np.array([1.0, 4.0, 9.0]), np.array([0.2, -0.1, 0.4]), np.array([0.1, -0.2, 0.3])
    a = generated_family(blade, GENERIC, s, th, q)
    b = generated_family(blade, mirror_settings(GENERIC), s, -th, -q)
    dmat = np.array([1.0, -1.0, 1.0])
    np.testing.assert_allclose(b.r, a.r * dmat, atol=1e-12)
    np.testing.assert_allclose(b.normal, a.normal * dmat, atol=1e-15)
    twice = mirror_settings(mirror_settings(GENERIC))
    assert twice == GENERIC


def test_settings_from_poses_round_trip():
    """Inverse kinematics: the poses produced by a set of settings give those settings back
    (1e-12), for zero and non-zero blank offset, tilt and swivel."""
    for st in (GENERIC, MachineSettings(process="Formate", radial_setting=95.0,
                                        cradle_angle=1.3, machine_root_angle=1.1,
                                        machine_center_to_back=4.0)):
        c, u = cutter_pose(st, 0.0)
        # machine frame in the blank frame at q = 0 (cradle axis and a point on it)
        m, _, _ = machine_transform(
            MachineSettings(process="Formate", radial_setting=0.0, cradle_angle=0.0,
                            machine_root_angle=st.machine_root_angle,
                            machine_center_to_back=st.machine_center_to_back,
                            sliding_base=st.sliding_base, blank_offset=st.blank_offset), 0.0)
        ps = settings_from_poses(cradle_point=m[:3, 3] + 7.0 * m[:3, 2], cradle_axis=m[:3, 2],
                                 cutter_centre=c, cutter_axis=u, process=st.process,
                                 ratio_of_roll=st.ratio_of_roll)
        for name in ("radial_setting", "cradle_angle", "swivel", "tilt", "machine_root_angle",
                     "machine_center_to_back", "sliding_base", "blank_offset"):
            assert getattr(ps.settings, name) == pytest.approx(getattr(st, name), abs=1e-12)
        assert ps.blank_phase == pytest.approx(0.0, abs=1e-15)


def test_straight_formate_gear_is_the_cutter_cone():
    """A straight-bladed Formate gear is the imprint of the cutter: every profile point lies
    on the analytic cone (axis and apex from the documented chain, scipy rotations) with the
    cone's normal (1e-9 mm; the solver converges to 1e-10 mm)."""
    case = load_case(CASES / "spiral_bevel_iso23509_s1.toml")
    for flank in ("concave", "convex"):
        # above the fillet: v from 20 % of the depth (the edge radius is ~0.5 mm high)
        fs = flank_surface(case, "gear", flank, nu=11, nv=7, v_limits=(0.2, 1.0))
        tool = case.gear.flank(flank)
        st, bl = tool.machine, tool.blade
        ref = _reference_chain(st, 0.0, 0.0, st.sliding_base, st.blank_offset)
        centre = ref(np.zeros(3))
        axis = ref(np.array([0.0, 0.0, 1.0])) - centre
        sel = (fs.reason == 0) & (fs.section == profile_sections(bl).main)
        assert sel.all()
        d = fs.position[sel] - centre
        height = -(d @ axis)  # above the tip plane, towards the cutter body
        radial = d + height[:, None] * axis
        rho = np.linalg.norm(radial, axis=-1)
        expected = bl.point_radius + bl.sigma * height * math.tan(bl.blade_angle)
        np.testing.assert_allclose(rho, expected, atol=1e-9)
        e_rho = radial / rho[:, None]
        # work normal = −(tool outward normal) = −σ cos α e_ρ − sin α z_t
        n_cone = (-bl.sigma * math.cos(bl.blade_angle) * e_rho
                  - math.sin(bl.blade_angle) * axis)
        np.testing.assert_allclose(fs.normal[sel], n_cone, atol=1e-12)


@pytest.mark.parametrize("kwargs, field", [
    (dict(side="outside", point_radius=-5.0, blade_angle=0.3), "point_radius"),
    (dict(side="outside", point_radius=60.0, blade_angle=D(50.0)), "blade_angle"),
    (dict(side="outside", point_radius=60.0, blade_angle=D(-1.0)), "blade_angle"),
    (dict(side="middle", point_radius=60.0, blade_angle=0.3), "side"),
    (dict(side="inside", point_radius=60.0, blade_angle=0.3, edge_radius=40.0), "edge_radius"),
    (dict(side="inside", point_radius=60.0, blade_angle=0.3, profile="circular",
          profile_radius=0.0), "profile_radius"),
    (dict(side="inside", point_radius=60.0, blade_angle=0.3, toprem_angle=D(3.0),
          toprem_height=0.0), "toprem_height"),
    (dict(side="inside", point_radius=float("nan"), blade_angle=0.3), "point_radius"),
])
def test_bad_blade(kwargs, field):
    """Bad blades raise InputError naming the field."""
    with pytest.raises(InputError, match=rf"^{field}:"):
        Blade(**kwargs)


@pytest.mark.parametrize("kwargs, field", [
    (dict(process="Generate", radial_setting=70.0, cradle_angle=0.5, ratio_of_roll=-1.0),
     "ratio_of_roll"),
    (dict(process="Formate", radial_setting=70.0, cradle_angle=0.5, ratio_of_roll=2.0),
     "ratio_of_roll"),
    (dict(process="Generate", radial_setting=-1.0, cradle_angle=0.5, ratio_of_roll=2.0),
     "radial_setting"),
    (dict(process="Generate", radial_setting=70.0, cradle_angle=0.5, ratio_of_roll=2.0,
          tilt=D(95.0)), "tilt"),
    (dict(process="Roll", radial_setting=70.0, cradle_angle=0.5), "process"),
    (dict(process="Generate", radial_setting=70.0, cradle_angle=0.5, ratio_of_roll=2.0,
          modified_roll=(1.0, 2.0, 3.0, 4.0, 5.0)), "modified_roll"),
])
def test_bad_settings(kwargs, field):
    """Bad settings raise InputError naming the field."""
    with pytest.raises(InputError, match=rf"^{field}:"):
        MachineSettings(**kwargs)
