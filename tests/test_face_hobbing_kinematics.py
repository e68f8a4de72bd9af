"""Face-hobbing (FH) kinematics: the machine chain with work indexing and placed blades.

Every check is against something the code under test does not compute itself: the chain
written out here with scipy rotations and explicit 4×4 matrices (design note "Face
hobbing", §2.3), central finite differences, the closed forms of the extended epicycloid
(§2.10, ISO 23509 FH quantities ν, ρ_P0, ρ_b, η1, ρ_mβ), plane geometry of the rake plane
(§2.4), an independent search of the surface swept by the edge (§3.1), group periodicity
and mirror identities (§2.5, §2.8), a quadric fitted to solved points, and the face-milling
(FM) path of the toolkit itself (§3.4, the FM limit).

Sign conventions (design note §2.2): θ is the cutter spin on the spindle, the work turns
by φ = φ_roll(q) + κθ with κ = −z0/z, and the spiral angle is the angle between the tooth
trace and the radius vector (the cone generatrix) in the crown-gear plane.
"""

from __future__ import annotations

import dataclasses
import math
import sys
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.spatial.transform import Rotation

from geometry.case import Blank, FlankTool, load_case
from geometry.core.errors import InputError
from geometry.iso23509.blank import blank_geometry
from geometry.machine.cradle import (
    MachineSettings,
    indexing_ratio,
    machine_transform,
    mirror_settings,
)
from geometry.machine.cutter import Blade, mirror_blade, profile_sections
from geometry.machine.family import generated_family, meshing_function
from geometry.machine.flank import flank_surface, projection_grid
from geometry.machine.flank_point import flank_points
from geometry.machine.meshing import solve_envelope
from geometry.synthesis.case_synthesis import case_blank, gear_formate_tools

sys.path.insert(0, str(Path(__file__).parent))
from test_blank import design_from_annex  # the ISO 23509 Annex F sample designs

ROOT = Path(__file__).resolve().parents[1]
D = math.radians
DIAG = np.array([1.0, -1.0, 1.0])  # the mirror y → −y
VECTORS = ("r", "r_s", "r_theta", "r_q", "r_ss", "r_stheta", "r_thetatheta", "r_sq",
           "r_thetaq", "r_qq")


# --------------------------------------------------------------------------- reference chain
def _rot(axis: str, angle) -> np.ndarray:
    """Stack (n, 4, 4) of active right-handed rotations (scipy)."""
    a = np.atleast_1d(np.asarray(angle, dtype=float))
    m = np.zeros((a.size, 4, 4))
    m[:, :3, :3] = Rotation.from_euler(axis, a[:, None]).as_matrix()
    m[:, 3, 3] = 1.0
    return m


def _trans(x, y, z) -> np.ndarray:
    """Stack (n, 4, 4) of translations."""
    x, y, z = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=float)) for v in (x, y, z)))
    m = np.zeros((x.size, 4, 4))
    m[:, [0, 1, 2, 3], [0, 1, 2, 3]] = 1.0
    m[:, 0, 3], m[:, 1, 3], m[:, 2, 3] = x, y, z
    return m


def _product(*factors) -> np.ndarray:
    out = factors[0]
    for f in factors[1:]:
        out = out @ f
    return out


def _taylor(value0, derivatives, q):
    """value0 + Σ d_k q^k / k! written out."""
    return value0 + sum(d * q**k / math.factorial(k) for k, d in enumerate(derivatives, 1))


def _ref_head_to_blank(st: MachineSettings, theta, q) -> np.ndarray:
    """The documented chain (design note §2.3) up to and including the spin R_z(θ):

    R_z(−φ) T(0,0,−X_p) R_y(γ_m − π/2) T(0,−E_m(q),X_b(q)) R_z(q_c+q) T(S_r,0,0) R_z(j) R_x(i)
    R_z(θ), φ = R_a (q − C q² − D q³ − E q⁴ − F q⁵) + κθ (Generate), κθ (Formate, q ≡ 0).
    """
    theta, q = np.broadcast_arrays(np.atleast_1d(np.asarray(theta, dtype=float)),
                                   np.atleast_1d(np.asarray(q, dtype=float)))
    if st.process == "Formate":
        q = np.zeros_like(q)
        phi = st.indexing_ratio * theta
    else:
        c2, d6, e24, f120 = (*st.modified_roll, 0.0, 0.0, 0.0, 0.0)[:4]
        phi = st.ratio_of_roll * (q - c2 / 2 * q**2 - d6 / 6 * q**3 - e24 / 24 * q**4
                                  - f120 / 120 * q**5) + st.indexing_ratio * theta
    xb = _taylor(st.sliding_base, st.helical_motion, q)
    em = _taylor(st.blank_offset, st.vertical_motion, q)
    return _product(_rot("z", -phi), _trans(0.0, 0.0, -st.machine_center_to_back),
                    _rot("y", st.machine_root_angle - math.pi / 2), _trans(0.0, -em, xb),
                    _rot("z", st.cradle_angle + q), _trans(st.radial_setting, 0.0, 0.0),
                    _rot("z", st.swivel), _rot("x", st.tilt), _rot("z", theta))


def _ref_placement(bl: Blade) -> np.ndarray:
    """B = R_z(θ_b) T(r_p, 0, 0) R_z(γ_a) R_x(γ_h), γ_a = blade offset + rake (§2.3)."""
    return _product(_rot("z", bl.blade_phase), _trans(bl.point_radius, 0.0, 0.0),
                    _rot("z", bl.blade_offset_angle + bl.rake_angle),
                    _rot("x", bl.hook_angle))[0]


def _ref_profile(bl: Blade, s):
    """(ρ, h) of a straight blade with edge radius r_e, by plane geometry: an arc of radius
    r_e tangent to the tip plane at s = 0 (centre at ρ_c = r_p − σ r_e (1 − sin α)/cos α,
    height r_e), then the line of blade angle α through (r_p, 0) from s1 = r_e (π/2 − α)."""
    assert bl.profile == "straight" and not (bl.toprem_angle or bl.flankrem_angle)
    s = np.asarray(s, dtype=float)
    a, sg, re = bl.blade_angle, bl.sigma, bl.edge_radius
    rho_c = bl.point_radius - sg * re * (1.0 - math.sin(a)) / math.cos(a)
    s1 = re * (math.pi / 2 - a)
    psi = np.minimum(s, s1) / re if re > 0 else np.zeros_like(s)
    rho = rho_c + sg * re * np.sin(psi)
    h = re * (1.0 - np.cos(psi))
    t = np.maximum(s - s1, 0.0)
    return rho + sg * t * math.sin(a), h + t * math.cos(a)


def _ref_edge(bl: Blade, s) -> np.ndarray:
    """Homogeneous edge points (n, 4) in the head frame: B · [ρ − r_p, 0, −h, 1]."""
    rho, h = _ref_profile(bl, np.atleast_1d(s))
    eb = np.stack([rho - bl.point_radius, np.zeros_like(rho), -h, np.ones_like(rho)], -1)
    return eb @ _ref_placement(bl).T


def _ref_points(bl: Blade, st: MachineSettings, s, theta, q=0.0) -> np.ndarray:
    """Blank-frame points of the documented chain, (n, 3)."""
    s, theta, q = (a.ravel() for a in np.broadcast_arrays(
        *(np.atleast_1d(np.asarray(v, dtype=float)) for v in (s, theta, q))))
    m = _ref_head_to_blank(st, theta, q)
    return np.einsum("nij,nj->ni", m, _ref_edge(bl, s))[:, :3]


# --------------------------------------------------------------------------- test data
Z0, Z = 13, 41  # blade groups, teeth of a generic member (no common factor)
GENERIC_FH = MachineSettings(
    process="Generate", radial_setting=70.0, cradle_angle=0.9, swivel=0.3, tilt=0.2,
    machine_root_angle=0.35, machine_center_to_back=3.0, sliding_base=1.5, blank_offset=12.0,
    ratio_of_roll=2.7, modified_roll=(0.05, -0.1, 0.2, 0.3), helical_motion=(1.0, 2.0, -3.0),
    vertical_motion=(0.5, -1.0, 2.0), indexing_ratio=indexing_ratio(Z0, Z))
FORMATE_FH = MachineSettings(
    process="Formate", radial_setting=75.0, cradle_angle=0.8, swivel=-0.4, tilt=0.15,
    machine_root_angle=1.1, machine_center_to_back=2.5, sliding_base=-0.7, blank_offset=3.0,
    indexing_ratio=indexing_ratio(Z0, Z))


def _placed_blades():
    """Straight blades with edge radius and all four placement angles non-zero."""
    kw = dict(point_radius=60.0, blade_angle=D(20.0), edge_radius=1.0)
    return [Blade(side="outside", blade_phase=0.7, blade_offset_angle=0.2, rake_angle=0.1,
                  hook_angle=0.15, **kw),
            Blade(side="inside", blade_phase=-2.1, blade_offset_angle=-0.3, rake_angle=0.12,
                  hook_angle=-0.1, **kw)]


# s on the edge radius (s1 = 1.22 mm) and on the profile; spins across a cutting pass
S_PTS = np.array([0.3, 1.0, 4.0, 9.0])
TH_PTS = np.array([0.2, -0.4, 0.05, 0.6])
Q_PTS = np.array([-0.2, 0.0, 0.13, 0.07])


def _sections(bl: Blade, s):
    return np.searchsorted(profile_sections(bl).s_hi, s)


# --------------------------------------------------------------------------- 1 chain
@pytest.mark.parametrize("st", [GENERIC_FH, FORMATE_FH], ids=["Generate", "Formate"])
@pytest.mark.parametrize("bl", _placed_blades(), ids=["outside", "inside"])
def test_chain_is_the_documented_formula(bl, st):
    """generated_family and machine_transform reproduce the chain of the design note §2.3,
    composed here from scipy rotations and 4×4 translations with the blade placement B and
    the work indexing κθ (tilt, swivel, offset, modified roll, helical and vertical motion,
    κ = −13/41, all four placement angles ≠ 0): 1e-12 mm on coordinates of ~100 mm
    (round-off of ten 4×4 products is ~1e-14 mm)."""
    fam = generated_family(bl, st, S_PTS, TH_PTS, Q_PTS, _sections(bl, S_PTS))
    ref = _ref_points(bl, st, S_PTS, TH_PTS, Q_PTS)
    assert np.abs(ref).max() > 30.0  # the points are really away from the origin
    np.testing.assert_allclose(fam.r, ref, rtol=0, atol=1e-12)
    # machine_transform: M(q, θ) excludes the spin; M · R_z(θ) · B · e_b
    m, _, _ = machine_transform(st, Q_PTS, TH_PTS)
    head = np.einsum("nij,nj->ni", _rot("z", TH_PTS), _ref_edge(bl, S_PTS))
    np.testing.assert_allclose(np.einsum("nij,nj->ni", m, head)[:, :3], ref, rtol=0, atol=1e-12)


# --------------------------------------------------------------------------- 2 derivatives
@pytest.mark.parametrize("st", [GENERIC_FH, FORMATE_FH], ids=["Generate", "Formate"])
@pytest.mark.parametrize("bl", _placed_blades(), ids=["outside", "inside"])
def test_family_derivatives_against_finite_differences(bl, st):
    """All first and second derivatives of r(s, θ, q) (Formate: those in s and θ only; q is
    not a motion there) against central differences of r and of the first derivatives, the
    mixed ones both ways (r_sθ from r_s and from r_θ). Step h = 1e-6: truncation
    h²|r'''|/6 ~ 1e-10 and rounding 1e-16·|r|/h ~ 1e-8 for |r| ~ 100 mm, both well below
    the tolerance 1e-6 × max(1, |derivative|). The meshing-function gradient likewise."""
    sec = _sections(bl, S_PTS)
    generate = st.process == "Generate"
    f0 = generated_family(bl, st, S_PTS, TH_PTS, Q_PTS, sec)
    h = 1e-6
    pairs = {0: (("r", "r_s"), ("r_s", "r_ss"), ("r_theta", "r_stheta"), ("r_q", "r_sq")),
             1: (("r", "r_theta"), ("r_s", "r_stheta"), ("r_theta", "r_thetatheta"),
                 ("r_q", "r_thetaq")),
             2: (("r", "r_q"), ("r_s", "r_sq"), ("r_theta", "r_thetaq"), ("r_q", "r_qq"))}
    checked = set()
    for k, names in pairs.items():
        if k == 2 and not generate:
            continue
        dv = np.zeros(3)
        dv[k] = h
        fp = generated_family(bl, st, S_PTS + dv[0], TH_PTS + dv[1], Q_PTS + dv[2], sec)
        fm = generated_family(bl, st, S_PTS - dv[0], TH_PTS - dv[1], Q_PTS - dv[2], sec)
        for base, an in names:
            if not generate and "q" in base + an.replace("theta", ""):
                continue
            fd = (getattr(fp, base) - getattr(fm, base)) / (2 * h)
            scale = max(1.0, np.abs(getattr(f0, an)).max())
            np.testing.assert_allclose(fd, getattr(f0, an), rtol=0, atol=1e-6 * scale,
                                       err_msg=f"d{base}/d{'s θ q'.split()[k]} vs {an}")
            checked.add(an)
        if generate:
            gp, _ = meshing_function(fp, 100.0)
            gm, _ = meshing_function(fm, 100.0)
            _, grad = meshing_function(f0, 100.0)
            np.testing.assert_allclose((gp - gm) / (2 * h), grad[:, k], rtol=0, atol=1e-6)
    expected = set(VECTORS[1:]) if generate else {"r_s", "r_theta", "r_ss", "r_stheta",
                                                  "r_thetatheta"}
    assert checked == expected


# --------------------------------------------------------------------------- crown gear
# design note §2.4/§2.10 example: crown gear of z = 45 teeth, z0 = 13, r_c0 = 88.9 mm,
# mean point at R = 100 mm with spiral angle β = 32°
CZ, CZ0, RC0, RM, BETA = 45, 13, 88.9, 100.0, D(32.0)


class Epicycloid:
    """Closed forms of the FH tooth trace (design note §2.10; ISO 23509 FH quantities)."""

    def __init__(self, zp: float, z0: int = CZ0, rc0: float = RC0, rm: float = RM,
                 beta: float = BETA):
        self.zp, self.z0, self.rc0, self.rm, self.beta = zp, z0, rc0, rm, beta
        self.nu = math.asin(rm * z0 * math.cos(beta) / (rc0 * zp))  # lead angle
        lam = math.pi / 2 - beta + self.nu  # angle OPC
        self.rho_p0 = math.sqrt(rm**2 + rc0**2 - 2 * rm * rc0 * math.cos(lam))
        self.rho_b = self.rho_p0 / (1 + z0 / zp)  # base radius
        eta1 = math.acos(rm * math.cos(beta) / self.rho_b)
        tb, te, tn = math.tan(beta), math.tan(eta1), math.tan(self.nu)
        self.rho_mbeta = rm * math.cos(beta) * (tb + te / (1 + tn * (tb + te)))
        # machine placement of the trace (Appendix A / synthesis §5.2): cutter centre and
        # the blade phase that puts the reference point at (R, 0) at θ = 0
        self.qc = math.atan2(rc0 * math.cos(beta - self.nu), rm - rc0 * math.sin(beta - self.nu))
        self.theta0 = beta - self.nu - math.pi / 2 - self.qc

    def spiral_angle(self, radius):
        """β(R) = atan((R − ρ_b cos q)/(ρ_b sin q)), q(R) the angle POC."""
        r = np.asarray(radius, dtype=float)
        q = np.arccos((r**2 + self.rho_p0**2 - self.rc0**2) / (2 * r * self.rho_p0))
        return np.arctan((r - self.rho_b * np.cos(q)) / (self.rho_b * np.sin(q)))


def _crown_settings(ep: Epicycloid, kappa: float) -> MachineSettings:
    """Formate crown gear: γ_m = 90°, i = j = 0, X_p = X_b = E_m = 0.

    MachineSettings accepts only |γ_m| < 90° (a crown gear is not a member the toolkit
    cuts); the chain is defined for γ_m = 90°, so the field is set past the validation.
    """
    st = MachineSettings(process="Formate", radial_setting=ep.rho_p0, cradle_angle=ep.qc,
                         machine_root_angle=0.0, indexing_ratio=kappa)
    object.__setattr__(st, "machine_root_angle", math.pi / 2)
    return st


def _spiral_angle(tangent, radius_vector):
    """Angle in [0, 90°] between a trace tangent and the radius vector."""
    t = np.asarray(tangent)
    r = np.asarray(radius_vector)
    cross = np.abs(t[..., 0] * r[..., 1] - t[..., 1] * r[..., 0])
    return np.arctan2(cross, np.abs((t[..., :2] * r[..., :2]).sum(-1)))


def _plane_curvature(d1, d2):
    """Curvature |x' × x''| / |x'|³ of a plane curve from its first two derivatives."""
    return abs(d1[0] * d2[1] - d1[1] * d2[0]) / math.hypot(d1[0], d1[1]) ** 3


def test_crown_gear_trace_is_the_extended_epicycloid():
    """The blade-tip trace θ ↦ r(s = 0, θ) of a Formate FH crown gear (design note
    Appendix A, §2.10) from generated_family's analytic r_θ, r_θθ: at θ = 0 it passes
    through the mean point at R = 100 mm with the spiral angle 32° and the lengthwise
    radius of curvature ρ_mβ of ISO 23509's FH closed form (72.91527 mm, the note's value);
    along the trace (R = 78 … 121 mm) the spiral angle is β(R) of the closed form. Exact
    identities (the relative motion is a rolling of the cutter circle on the base circle
    ρ_b), so 1e-9 (relative, and rad) leaves room only for round-off."""
    ep = Epicycloid(zp=CZ)
    st = _crown_settings(ep, indexing_ratio(CZ0, CZ))
    bl = Blade("outside", RC0, D(20.0), blade_phase=ep.theta0)  # edge radius 0: s = 0 is M
    f = generated_family(bl, st, 0.0, 0.0, 0.0)
    assert np.linalg.norm(f.r) == pytest.approx(RM, rel=1e-12)
    assert abs(f.r[2]) < 1e-12 and abs(f.r_theta[2]) < 1e-12  # the trace lies in z = 0
    assert float(_spiral_angle(f.r_theta, f.r)) == pytest.approx(BETA, abs=1e-9)
    rho = 1.0 / _plane_curvature(f.r_theta, f.r_thetatheta)
    assert rho == pytest.approx(ep.rho_mbeta, rel=1e-9)
    assert ep.rho_mbeta == pytest.approx(72.91527, abs=1e-5)  # design note Appendix A
    th = np.linspace(-0.25, 0.25, 9)
    ft = generated_family(bl, st, 0.0, th, 0.0)
    radius = np.linalg.norm(ft.r, axis=-1)
    assert radius.min() < 80.0 and radius.max() > 120.0
    np.testing.assert_allclose(_spiral_angle(ft.r_theta, ft.r), ep.spiral_angle(radius),
                               rtol=0, atol=1e-9)


def test_crown_gear_wrong_indexing_sign_is_caught():
    """Negative control (design note §2.7, oracle #6): with κ = +z0/z the blade traces a
    hypotrochoid whose spiral angle at the mean point is 2.934° (the note's value), far
    from 32°: the sign of κ is observable."""
    ep = Epicycloid(zp=CZ)
    st = _crown_settings(ep, +CZ0 / CZ)
    bl = Blade("outside", RC0, D(20.0), blade_phase=ep.theta0)
    f = generated_family(bl, st, 0.0, 0.0, 0.0)
    beta = math.degrees(float(_spiral_angle(f.r_theta, f.r)))
    assert abs(beta - 32.0) > 10.0
    assert beta == pytest.approx(2.934, abs=1e-3)


@pytest.mark.parametrize("gamma_deg", [50.0, 65.0, 75.0])
def test_inclined_formate_gear_trace(gamma_deg):
    """Formate FH gear with γ_m < 90°, zero tilt, root apex at the machine centre (X_b = 0
    puts the machine centre on the work axis, at z = −X_p; X_p = 2.5 mm): at the mean root
    point (R = 100 mm on x_m at θ = 0) the tip trace projected on the tip plane (the root
    cone's tangent plane) has the spiral angle 32° and the lengthwise radius ρ_mβ of the
    closed forms with z_p = z / sin γ_m (design note §2.10 (iii)). Exact: projected on the
    tip plane, a rotation about the work axis at rate κ moves points of that plane as a
    rotation about z_m at rate κ sin γ_m (first derivative); the second derivative differs
    by −κ² cos²γ_m (y_m·c) y_m, which vanishes on the x_m axis. Hence 1e-9 (rad, relative),
    evaluated with the family's analytic r_θ, r_θθ."""
    gm = D(gamma_deg)
    ep = Epicycloid(zp=CZ / math.sin(gm))
    st = MachineSettings(process="Formate", radial_setting=ep.rho_p0, cradle_angle=ep.qc,
                         machine_root_angle=gm, machine_center_to_back=2.5,
                         indexing_ratio=indexing_ratio(CZ0, CZ))
    bl = Blade("outside", RC0, D(20.0), blade_phase=ep.theta0)
    f = generated_family(bl, st, 0.0, 0.0, 0.0)
    frame = Rotation.from_euler("y", gm - math.pi / 2).as_matrix()  # x_m, y_m, z_m columns
    centre = np.array([0.0, 0.0, -2.5])
    p = frame.T @ (f.r - centre)
    np.testing.assert_allclose(p, [RM, 0.0, 0.0], rtol=0, atol=1e-12)
    d1, d2 = frame.T @ f.r_theta, frame.T @ f.r_thetatheta  # components (x_m, y_m, z_m)
    assert float(_spiral_angle(d1, p)) == pytest.approx(BETA, abs=1e-9)
    assert 1.0 / _plane_curvature(d1, d2) == pytest.approx(ep.rho_mbeta, rel=1e-9)


# --------------------------------------------------------------------------- rake plane
@pytest.mark.parametrize("side", ["outside", "inside"])
def test_rake_plane_normal_to_the_trace(side):
    """Crown gear of the §2.4 example, straight blade of blade angle α = 20° at the mean
    point. Plane geometry at M: the trace tangent t is horizontal, the rake plane's
    horizontal line a1 makes the angle γ_a − ν with the trace normal (the blade phase puts
    a1 at β − π/2 + γ_a − ν), and the edge is σ sin α a1 − cos α z. So with γ_a = ν the edge
    is ⟂ t (|cos| ≤ 1e-9) and the flank's normal-section pressure angle is α; in general
    tan α_n = tan α cos(γ_a − ν). The note's values (§2.4, its prototype) are 19.284° for
    γ_a = 0 and 17.155° for γ_a = −ν, checked to 1e-3°; the closed form to 1e-9°."""
    ep = Epicycloid(zp=CZ)
    st = _crown_settings(ep, indexing_ratio(CZ0, CZ))
    alpha = D(20.0)
    note = {0.0: 19.284, -1.0: 17.155}
    for factor in (1.0, 0.0, -1.0):
        ga = factor * ep.nu
        bl = Blade(side, RC0, alpha, blade_phase=ep.theta0, blade_offset_angle=ga)
        f = generated_family(bl, st, 0.0, 0.0, 0.0)
        t = f.r_theta / np.linalg.norm(f.r_theta)
        edge = f.r_s / np.linalg.norm(f.r_s)
        n = np.cross(f.r_s, f.r_theta)
        n /= np.linalg.norm(n)
        profile = np.cross(t, n)  # the profile tangent in the normal section (⟂ t)
        alpha_n = math.degrees(math.acos(abs(profile[2])))
        expected = math.degrees(math.atan(math.tan(alpha) * math.cos(ga - ep.nu)))
        assert alpha_n == pytest.approx(expected, abs=1e-9)
        if factor == 1.0:
            assert abs(edge @ t) <= 1e-9
            assert alpha_n == pytest.approx(20.0, abs=1e-6)
        else:
            assert abs(edge @ t) > 0.05
            assert alpha_n == pytest.approx(note[factor], abs=1e-3)


# --------------------------------------------------------------------------- group periodicity
@pytest.mark.parametrize("st", [GENERIC_FH, FORMATE_FH], ids=["Generate", "Formate"])
def test_group_periodicity(st):
    """The blade of the next group (phase θ_b + 2π/z0) sweeps the one-pitch-turned copy:
    r(s, θ; θ_b + 2π/z0) = R_z(−2π/z) r(s, θ + 2π/z0; θ_b), because κ · 2π/z0 = −2π/z
    (design note §2.5). All vectors of the family turn alike (the derivatives in s and q
    by the same rotation, those in θ too). 1e-12 mm / per unit."""
    bl = _placed_blades()[0]
    nxt = dataclasses.replace(bl, blade_phase=bl.blade_phase + 2 * math.pi / Z0)
    sec = _sections(bl, S_PTS)
    a = generated_family(nxt, st, S_PTS, TH_PTS, Q_PTS, sec)
    b = generated_family(bl, st, S_PTS, TH_PTS + 2 * math.pi / Z0, Q_PTS, sec)
    rot = Rotation.from_euler("z", -2 * math.pi / Z).as_matrix()
    for name in VECTORS:
        np.testing.assert_allclose(getattr(a, name), getattr(b, name) @ rot.T, rtol=0,
                                   atol=1e-12, err_msg=name)
    np.testing.assert_allclose(a.normal, b.normal @ rot.T, rtol=0, atol=1e-14)


# --------------------------------------------------------------------------- mirror
@pytest.mark.parametrize("st", [GENERIC_FH, FORMATE_FH], ids=["Generate", "Formate"])
@pytest.mark.parametrize("bl", _placed_blades(), ids=["outside", "inside"])
def test_mirror_rule_generates_the_mirror_image(bl, st):
    """Design note §2.8: mirror_settings (κ unchanged) with mirror_blade (θ_b, δ_b, rake and
    hook negated), θ → −θ, q → −q generate D r, D = diag(1, −1, 1). The derivatives follow
    by the chain rule: a θ or q derivative flips sign once per order. 1e-12 mm."""
    mb = mirror_blade(bl)
    for name in ("blade_phase", "blade_offset_angle", "rake_angle", "hook_angle"):
        assert getattr(mb, name) == -getattr(bl, name)
    ms = mirror_settings(st)
    assert ms.indexing_ratio == st.indexing_ratio
    sec = _sections(bl, S_PTS)
    a = generated_family(bl, st, S_PTS, TH_PTS, Q_PTS, sec)
    b = generated_family(mb, ms, S_PTS, -TH_PTS, -Q_PTS, sec)
    odd = {"r_theta", "r_q", "r_stheta", "r_sq"}  # one θ/q derivative: sign flips
    for name in VECTORS:
        sign = -1.0 if name in odd else 1.0
        np.testing.assert_allclose(getattr(b, name), sign * getattr(a, name) * DIAG, rtol=0,
                                   atol=1e-12, err_msg=name)
    np.testing.assert_allclose(b.normal, a.normal * DIAG, rtol=0, atol=1e-14)
    # the reference chain agrees: the mirrored tool's points are D times the original's
    np.testing.assert_allclose(_ref_points(mb, ms, S_PTS, -TH_PTS, -Q_PTS),
                               _ref_points(bl, st, S_PTS, TH_PTS, Q_PTS) * DIAG, rtol=0,
                               atol=1e-12)


# --------------------------------------------------------------------------- FH gear on a blank
FH_Z0 = 13  # blade groups for the sample-2 gear (z2 = 42: no common factor)


@cache
def _fh_gear():
    """ISO 23509 Annex F sample 2 (hypoid, z2 = 42) gear blank and its closed-form Formate
    FH tools (synthesis §5.2; r_c0 = 63.5 mm, 20° blades, z0 = 13)."""
    geom = blank_geometry(design_from_annex("sample2"))
    blank = Blank(**{k: (math.radians(v) if k.endswith("angle") else v)
                     for k, v in case_blank(geom.gear).items()})
    tools = gear_formate_tools(geom, cutter_radius=63.5, blade_angle_drive=D(20.0),
                               blade_angle_coast=D(20.0), point_width=None, edge_radius=None,
                               blade_groups=FH_Z0)
    return blank, tools


def _fh_settings(process: str) -> MachineSettings:
    """The Formate FH gear's settings, or the same machine rolling (Generate): R_a = 1/sin γ_m
    with κ = −z0/z2 unchanged is the generating crown gear of z_G = R_a z2 teeth and
    κ_G = κ/R_a = −z0/z_G (design note §3.3), so the gear is generated by a rigid FH crown
    gear, a Generate FH member whose flank lies inside the blank."""
    st = _fh_gear()[1].settings
    if process == "Formate":
        return st
    return dataclasses.replace(st, process="Generate",
                               ratio_of_roll=1.0 / math.sin(st.machine_root_angle))


def _solve(bl: Blade, st: MachineSettings, axial, radius, **kw):
    blank = _fh_gear()[0]
    return solve_envelope(bl, st, axial, radius, length_scale=blank.outer_cone_distance,
                          depth=blank.outer_addendum + blank.outer_dedendum, **kw)


def _grid(nu=5, nv=4, v_limits=(0.1, 1.0)):
    return projection_grid(_fh_gear()[0], nu, nv, v_limits=v_limits)


@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_formate_flank_is_the_swept_edge(flank):
    """Formate FH gear (design note §3.1, oracle #11): (a) each solved (s, θ) put through the
    reference chain of this file (spin, blade placement and indexing from scipy rotations,
    the straight edge with its edge radius by plane geometry) gives the solver's point to
    1e-9 mm (the solver converges to 1e-10 mm); (b) the flank is the surface swept by the
    edge: for each target circle (z = Z, ρ = P) the edge of the reference simulation is
    sampled over a full turn of the head (0.25° × 0.1 mm), every near-miss (distance
    < 0.5 mm, local minimum in θ) is refined by least squares on (s, θ) to the exact
    crossing, and the solver's point must be one of these crossings to 1e-9 mm (least
    squares stops at 1e-15 in x; different crossings are other slots, mm apart)."""
    tools = _fh_gear()[1]
    bl, st = tools.blades[flank], tools.settings
    assert bl.placed and st.indexing_ratio == pytest.approx(-FH_Z0 / 42, rel=1e-15)
    grid = _grid()
    sol = _solve(bl, st, grid.axial, grid.radius)
    ok = sol.reason == 0
    assert ok.all()
    np.testing.assert_allclose(sol.position[ok], _ref_points(bl, st, sol.s[ok], sol.theta[ok]),
                               rtol=0, atol=1e-9)
    # (b) the swept edge, searched over the whole turn of the head
    theta_grid = np.linspace(-math.pi, math.pi, 1441)
    s_grid = np.linspace(0.0, 12.0, 121)
    pts = np.einsum("tij,sj->tsi", _ref_head_to_blank(st, theta_grid, 0.0),
                    _ref_edge(bl, s_grid))[..., :3]
    z_g, rho_g = pts[..., 2], np.hypot(pts[..., 0], pts[..., 1])
    for zt, pt, p_solver in zip(grid.axial.ravel(), grid.radius.ravel(),
                                sol.position.reshape(-1, 3), strict=True):
        dist = np.hypot(z_g - zt, rho_g - pt)
        dmin, jmin = dist.min(1), dist.argmin(1)
        near = np.flatnonzero((dmin < 0.5) & (dmin <= np.roll(dmin, 1))
                              & (dmin <= np.roll(dmin, -1)))

        def miss(x, zt=zt, pt=pt):
            p = _ref_points(bl, st, x[0], x[1])[0]
            return [p[2] - zt, math.hypot(p[0], p[1]) - pt]

        crossings = []
        for i in near:
            fit = least_squares(miss, [s_grid[jmin[i]], theta_grid[i]], method="lm",
                                xtol=1e-15, ftol=1e-15, gtol=1e-15)
            if np.abs(fit.fun).max() < 1e-11 and fit.x[0] >= 0.0:
                crossings.append(_ref_points(bl, st, fit.x[0], fit.x[1])[0])
        assert crossings, f"the swept edge does not reach the target ({zt}, {pt})"
        gap = min(np.linalg.norm(c - p_solver) for c in crossings)
        assert gap < 1e-9
        # one crossing per head turn (all near-misses refine to it): the blade meets a
        # target circle once per turn, the fact test_next_group_cuts_the_next_slot uses
        assert max(np.linalg.norm(c - p_solver) for c in crossings) < 1e-9


def _tool_side(bl: Blade, st: MachineSettings, x, theta, q):
    """> 0 where blank-frame points x lie on the tool's side of the surface of revolution
    the edge sweeps in the head (outside blade: inside it; inside blade: outside), at the
    pose (θ, q); the reference chain inverted, the straight edge's hyperboloid in closed
    form (hook 0: height h along −z_t; ρ − r_p = h tan α along a1 from M)."""
    assert bl.hook_angle == 0.0
    m = np.linalg.inv(_ref_head_to_blank(st, theta, q))
    xh = np.einsum("nij,nj->ni", m, np.c_[x, np.ones(len(x))])[:, :3]
    h = -xh[:, 2]
    ph, ga = bl.blade_phase, bl.blade_offset_angle + bl.rake_angle
    along = bl.sigma * h * math.tan(bl.blade_angle)
    ex = bl.point_radius * math.cos(ph) + along * math.cos(ph + ga)
    ey = bl.point_radius * math.sin(ph) + along * math.sin(ph + ga)
    return bl.sigma * (np.hypot(ex, ey) - np.hypot(xh[:, 0], xh[:, 1]))


@pytest.mark.parametrize("process", ["Formate", "Generate"])
@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_fh_meshing_residual_and_normals(process, flank):
    """FH members on the sample-2 gear blank: every grid point is generated, lies at its
    target (1e-9 mm) and satisfies the equation of meshing |f| ≤ 1e-9 (the solver stops at
    1e-12). The normals are unit and normal to the flank: ⟂ to the central differences of
    solved points 1e-3 mm away along Z and along P (|cos| < 1e-6: truncation ~δ²κ', the
    solver's 1e-10 mm over 2δ is 5e-8). They point out of the material by the rule of the
    FM tests (tests/test_meshing.py): 0.01 mm along the normal is on the tool's side of the
    surface the edge sweeps in the head, 0.01 mm against it on the work side (the flank
    and that surface share the edge and differ by a turn about it of order ν, so the side
    is unambiguous, but the flank's normal is not the head surface's normal)."""
    bl = _fh_gear()[1].blades[flank]
    st = _fh_settings(process)
    grid = _grid(7, 5)
    sol = _solve(bl, st, grid.axial, grid.radius)
    ok = sol.reason == 0
    assert ok.all()
    pos = sol.position[ok]
    np.testing.assert_allclose(pos[:, 2], grid.axial[ok], rtol=0, atol=1e-9)
    np.testing.assert_allclose(np.hypot(pos[:, 0], pos[:, 1]), grid.radius[ok], rtol=0,
                               atol=1e-9)
    assert np.abs(sol.meshing_residual[ok]).max() <= 1e-9
    if process == "Generate":
        assert np.ptp(sol.q[ok]) > 0.1  # really generated: the cradle rolls
    n = sol.normal[ok]
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, rtol=0, atol=1e-14)
    delta = 1e-3
    dz = np.array([delta, -delta, 0.0, 0.0])
    dp = np.array([0.0, 0.0, delta, -delta])
    guess = tuple(np.broadcast_to(np.asarray(a)[ok][:, None], (ok.sum(), 4))
                  for a in (sol.s, sol.theta, sol.q, sol.section))
    near = _solve(bl, st, grid.axial[ok][:, None] + dz, grid.radius[ok][:, None] + dp,
                  guess=guess)
    assert np.all(near.reason == 0)
    for a, b in ((0, 1), (2, 3)):
        chord = near.position[:, a] - near.position[:, b]
        assert np.linalg.norm(chord, axis=-1).min() > delta
        cos = (chord * n).sum(-1) / np.linalg.norm(chord, axis=-1)
        assert np.abs(cos).max() < 1e-6, f"normal off the flank by {np.abs(cos).max():.3g}"
    prof = sol.section[ok] == profile_sections(bl).main
    assert prof.sum() >= 20
    args = (sol.theta[ok][prof], sol.q[ok][prof])
    assert np.all(_tool_side(bl, st, pos[prof] + 0.01 * n[prof], *args) > 0)
    assert np.all(_tool_side(bl, st, pos[prof] - 0.01 * n[prof], *args) < 0)


def _quadric_fit(p0, n, e1, e2, pts):
    """Principal curvatures of the graph w(x, y) fitted by least squares (cubic terms kept),
    as tests/test_curvature.py; κ = −w'' with n out of the material."""
    d = pts - p0
    x, y, w = d @ e1, d @ e2, d @ n
    a = np.stack([np.ones_like(x), x, y, x * x / 2, x * y, y * y / 2,
                  x**3, x * x * y, x * y * y, y**3], -1)
    c = np.linalg.lstsq(a, w, rcond=None)[0]
    return np.linalg.eigvalsh(-np.array([[c[3], c[4]], [c[4], c[5]]]))[::-1]


@pytest.mark.parametrize("process", ["Formate", "Generate"])
@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_fh_curvatures_match_finite_differences(process, flank):
    """Principal curvatures of the shape operator of flank_points (implicit differentiation
    with the κ terms of the family) against a quadric fitted to 5×5 solved points around
    the middle of the flank, 0.1, 0.05 and 0.025 mm apart in the projection plane (started
    from the middle point's parameters so that the patch stays on its slot): agreement to
    1e-3 of the largest |κ| at 0.025 mm, and the fit's error falls ~h² (ratio > 3 from
    0.1 to 0.05 mm), so the remaining difference is the fit's truncation (as
    tests/test_curvature.py for FM)."""
    blank, tools = _fh_gear()
    bl, st = tools.blades[flank], _fh_settings(process)
    grid = _grid(7, 5)
    zc, pc = grid.axial[3, 2], grid.radius[3, 2]
    fp = flank_points(bl, st, blank, "right", np.array([zc]), np.array([pc]))
    assert fp.ok[0] and fp.params[0, 3] == profile_sections(bl).main
    p0, n, w = fp.r[0], fp.n[0], fp.shape[0]
    e1 = fp.r_s[0] - (fp.r_s[0] @ n) * n
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    basis = np.stack([e1, e2])
    k_an = np.linalg.eigvalsh(basis @ w @ basis.T)[::-1]
    assert np.abs(k_an).max() > 1e-3
    errors = []
    for h in (0.1, 0.05, 0.025):
        a = np.arange(-2, 3) * h
        zz, pp = np.meshgrid(zc + a, pc + a, indexing="ij")
        sol = _solve(bl, st, zz, pp, guess=tuple(fp.params[0]))
        assert np.all(sol.reason == 0)
        pts = sol.position.reshape(-1, 3)
        assert np.linalg.norm(pts - p0, axis=-1).max() < 1.0  # the same slot
        errors.append(np.abs(_quadric_fit(p0, n, e1, e2, pts) - k_an).max()
                      / np.abs(k_an).max())
    assert errors[-1] < 1e-3
    assert errors[0] / errors[1] > 3.0


@pytest.mark.parametrize("process", ["Formate", "Generate"])
@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_next_group_cuts_the_next_slot(process, flank):
    """One pitch on solved flanks (design note §2.5): the blade of the next group (phase
    θ_b + 2π/z0) solved from scratch on the same targets (root row included, so that the
    Formate grid has masked points) gives the same mask, the same edge points (s), and
    the first blade's points turned by one pitch, R_z(−2π/z) p, at the spin θ − 2π/z0.
    Why exactly that copy: by group periodicity r(s, θ'; θ_b + 2π/z0) = R_z(−2π/z)
    r(s, θ' + 2π/z0; θ_b), and the first blade meets the target circle only once per head
    turn (after a full turn the work has indexed z0 pitches), so within |θ'| < π the
    solution is θ' = θ − 2π/z0. Points 1e-9 mm, spins 1e-9 rad (solver tolerance)."""
    bl = _fh_gear()[1].blades[flank]
    st = _fh_settings(process)
    nxt = dataclasses.replace(bl, blade_phase=bl.blade_phase + 2 * math.pi / FH_Z0)
    grid = _grid(7, 5, v_limits=(0.0, 1.0))
    a = _solve(bl, st, grid.axial, grid.radius)
    b = _solve(nxt, st, grid.axial, grid.radius)
    np.testing.assert_array_equal(b.reason, a.reason)
    ok = a.reason == 0
    assert ok.sum() >= 28
    if process == "Formate":
        assert (~ok).any()
    np.testing.assert_array_equal(b.section[ok], a.section[ok])
    np.testing.assert_allclose(b.s[ok], a.s[ok], rtol=0, atol=1e-9)
    np.testing.assert_allclose(b.theta[ok], a.theta[ok] - 2 * math.pi / FH_Z0, rtol=0,
                               atol=1e-9)
    np.testing.assert_allclose(b.q[ok], a.q[ok], rtol=0, atol=1e-9)
    rot = Rotation.from_euler("z", -2 * math.pi / 42).as_matrix()
    np.testing.assert_allclose(b.position[ok], a.position[ok] @ rot.T, rtol=0, atol=1e-9)
    np.testing.assert_allclose(b.normal[ok], a.normal[ok] @ rot.T, rtol=0, atol=1e-9)


# --------------------------------------------------------------------------- FM limit
def _face_milled(path: Path) -> bool:
    """The case file's ``pair.method`` is FM (the default): the FM limit is a property of
    face-milled tools; the face-hobbed cases in ``cases/`` have placed blades and κ ≠ 0."""
    with path.open("rb") as f:
        return tomllib.load(f).get("pair", {}).get("method", "FM") == "FM"


CASE_FILES = [p for p in sorted((ROOT / "cases").glob("*.toml")) + sorted(
    (ROOT / "tests" / "data").glob("*conjugate*.toml")) if _face_milled(p)]


@pytest.mark.parametrize("path", CASE_FILES, ids=lambda p: p.stem)
def test_face_milling_limit(path):
    """Oracle #1: for every bundled face-milled case, member and flank, the general (placed-blade)
    path of the chain with κ = 0 and a blade phase of 2π — the same geometry, but
    Blade.placed is True — reproduces the FM path: the family's vectors at the solved flank
    parameters (1e-9 mm; observed ~1e-13, the round-off of sin 2π ≠ 0), and the flank
    solved through that path (same mask, points 1e-9 mm: the solver's tolerance). κ → 0 is
    continuous: κ = −1e-12 moves the points by < 1e-9 mm."""
    case = load_case(path)
    assert len(CASE_FILES) >= 8  # 6 bundled face-milled cases and the 2 conjugate examples
    for member in ("pinion", "gear"):
        mem = case.member(member)
        for flank in ("concave", "convex"):
            tool = mem.flank(flank)
            assert not tool.blade.placed and tool.machine.indexing_ratio == 0.0
            placed = dataclasses.replace(tool.blade, blade_phase=2 * math.pi)
            assert placed.placed
            fs = flank_surface(case, member, flank, nu=11, nv=7)
            ok = fs.valid
            # enough solved points to compare; the reference design's relieved, helically
            # moved pinion drive flank leaves its root row (below the working depth) to the
            # blade's edge radius: 68 of 77 nodes
            assert ok.mean() > 0.85
            args = (fs.s[ok], fs.theta[ok], fs.q[ok], fs.section[ok])
            a = generated_family(tool.blade, tool.machine, *args)
            b = generated_family(placed, tool.machine, *args)
            for name in VECTORS:
                np.testing.assert_allclose(getattr(b, name), getattr(a, name), rtol=0,
                                           atol=1e-9, err_msg=f"{member} {flank} {name}")
            np.testing.assert_allclose(b.normal, a.normal, rtol=0, atol=1e-12)
            near = generated_family(tool.blade, dataclasses.replace(
                tool.machine, indexing_ratio=-1e-12), *args)
            assert np.abs(near.r - a.r).max() < 1e-9
            other = dataclasses.replace(case, **{member: dataclasses.replace(
                mem, **{flank: FlankTool(placed, tool.machine)})})
            fs2 = flank_surface(other, member, flank, nu=11, nv=7)
            np.testing.assert_array_equal(fs2.reason, fs.reason)
            np.testing.assert_allclose(fs2.position[ok], fs.position[ok], rtol=0, atol=1e-9)
            np.testing.assert_allclose(fs2.normal[ok], fs.normal[ok], rtol=0, atol=1e-9)


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("call, field", [
    (lambda: indexing_ratio(0.5, 12), "blade_groups"),
    (lambda: indexing_ratio(-1, 12), "blade_groups"),
    (lambda: indexing_ratio(6, 12), "blade_groups"),
    (lambda: indexing_ratio(13, 2), "teeth"),
    (lambda: Blade("outside", 60.0, D(20.0), blade_offset_angle=D(50.0)),
     "blade_offset_angle"),
    (lambda: Blade("outside", 60.0, D(20.0), hook_angle=D(25.0)), "hook_angle"),
    (lambda: Blade("outside", 60.0, D(20.0), rake_angle=D(35.0)), "rake_angle"),
    (lambda: Blade("outside", 60.0, D(20.0), blade_phase=D(361.0)), "blade_phase"),
    (lambda: MachineSettings(process="Formate", radial_setting=70.0, cradle_angle=0.5,
                             indexing_ratio=100.0), "indexing_ratio"),
], ids=["groups-fraction", "groups-negative", "common-factor", "teeth", "offset", "hook",
        "rake", "phase", "kappa"])
def test_bad_face_hobbing_input(call, field):
    """Bad FH input raises InputError whose message starts with the field's name."""
    with pytest.raises(InputError, match=rf"^{field}:"):
        call()
