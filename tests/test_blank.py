"""Tests of the ISO 23509 blank geometry (geometry.iso23509.pitch_cone, geometry.iso23509.blank).

References
----------
* ISO 23509:2016 Annex F worked examples (tests/data/iso23509_annex_f_face_milling.toml):
  every printed value of both samples is a test case, within the relative tolerance given
  next to it in the file (the tolerance matches the printed precision: 3 decimals on values
  of a few units to a few hundred give 0.2–0.3 %; the hypoid sample's looser 1–5 % cover the
  standard's iterative Method 1, which stops at a tolerance).
* Identities the equations must satisfy (zero offset: δ1 + δ2 = Σ; a → 0 continuity of
  Method 1; thickness balance), and independent 3-D vector constructions of the tangent
  pitch cones, the sliding velocity, the limit radius and the face/root cone tangency.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from scipy.optimize import brentq

from geometry.core.errors import InputError, ModelUnavailableError
from geometry.iso23509.blank import (
    BlankGeometry,
    blank_dataset,
    blank_geometry,
    check_face_angles,
    in_degrees,
    pinion_spiral_angle_at,
    spiral_angle_at,
)
from geometry.iso23509.pitch_cone import (
    BevelGearDesign,
    hypoid_pitch_angles,
    limit_radius,
    pitch_cone,
)

DATA = Path(__file__).parent / "data" / "iso23509_annex_f_face_milling.toml"
ANNEX_F = tomllib.loads(DATA.read_text(encoding="utf-8"))

# TOML input keys -> BevelGearDesign fields (angles stay in degrees for from_degrees)
_BACKLASH_KIND = {"outer normal j_en": "j_en", "outer transverse j_et2": "j_et2"}


def design_from_annex(sample: str, **override: object) -> BevelGearDesign:
    """BevelGearDesign of an Annex F sample, optionally with fields overridden."""
    inp = ANNEX_F[sample]["input"]
    fields = {
        "method": inp["method"], "Sigma": inp["Sigma"], "a": inp["a"], "z1": inp["z1"],
        "z2": inp["z2"], "de2": inp["de2"], "b2": inp["b2"],
        "beta_m": inp.get("beta_m2", inp.get("beta_m1_desired")), "rc0": inp["rc0"],
        "alpha_dD": inp["alpha_dD"], "alpha_dC": inp["alpha_dC"], "f_alim": inp["f_alim"],
        "c_ham": inp["c_ham"], "k_d": inp["k_d"], "k_c": inp["k_c"], "k_t": inp["k_t"],
        "backlash": _BACKLASH_KIND[inp["backlash"]], "backlash_value": inp["backlash_value"],
        "theta_a2": inp["theta_a2"], "theta_f2": inp["theta_f2"],
    }
    fields.update(override)
    return BevelGearDesign.from_degrees(**fields)


@pytest.fixture(scope="module")
def geometries() -> dict[str, BlankGeometry]:
    return {s: blank_geometry(design_from_annex(s)) for s in ("sample1", "sample2")}


def _flat_symbols(geom: BlankGeometry) -> dict[str, float]:
    """The result under the standard's symbols (member suffix 1 = pinion, 2 = gear), in deg."""
    d = in_degrees(geom)
    flat = {k: v for k, v in d.items() if not isinstance(v, dict)}
    flat.update(d["pitch"])
    for member, suffix in (("pinion", "1"), ("gear", "2")):
        flat.update({f"{k}{suffix}": v for k, v in d[member].items()})
    flat["Rm"] = flat["Rm2"]  # sample 1 prints the common mean cone distance once
    flat["ap"] = flat["a_p"]
    return flat


def _annex_cases() -> list[object]:
    # every printed value, none skipped (the hypoid pinion's β_e1, β_i1 included: they come
    # from the gear's spiral angle at the pinion end's corresponding point plus the offset
    # angle there, geometry.iso23509.blank.pinion_spiral_angle_at)
    cases = []
    for sample in ("sample1", "sample2"):
        for symbol, (value, rtol) in ANNEX_F[sample]["expected"].items():
            cases.append(pytest.param(sample, symbol, value, rtol, id=f"{sample}-{symbol}"))
    return cases


@pytest.mark.parametrize(("sample", "symbol", "expected", "rtol"), _annex_cases())
def test_annex_f_value(geometries, sample, symbol, expected, rtol):
    # tolerance: the relative tolerance printed next to each value in Annex F data (see the
    # module docstring for why it is what it is)
    got = _flat_symbols(geometries[sample])[symbol]
    assert got == pytest.approx(expected, rel=rtol), f"{sample} {symbol}: {got} vs {expected}"


# --------------------------------------------------------------------------- invariants
@pytest.mark.parametrize("sigma_deg", [45.0, 75.0, 90.0, 100.0])
@pytest.mark.parametrize(("z1", "z2"), [(14, 39), (10, 10), (9, 47)])
def test_zero_offset_pitch_angles_sum_to_shaft_angle(sigma_deg, z1, z2):
    design = design_from_annex("sample1", Sigma=sigma_deg, z1=z1, z2=z2, de2=180.0)
    p = pitch_cone(design)
    # identity δ1 + δ2 = Σ and the ratio of pitch radii = u: exact up to rounding (1e-12)
    assert p.delta1 + p.delta2 == pytest.approx(math.radians(sigma_deg), abs=1e-12)
    assert p.dm2 / p.dm1 == pytest.approx(z2 / z1, rel=1e-12)
    g = blank_geometry(design)
    # bevel: constant clearance makes δ_a1 = δ1 + θ_f2, δ_f1 = δ1 − θ_a2, and b1 = b2 (1e-12)
    assert g.pinion.delta_a == pytest.approx(p.delta1 + design.theta_f2, abs=1e-12)
    assert g.pinion.delta_f == pytest.approx(p.delta1 - design.theta_a2, abs=1e-12)
    assert g.pinion.b == pytest.approx(design.b2, abs=1e-12)


def test_method1_at_zero_offset_reduces_to_method0():
    m0 = pitch_cone(design_from_annex("sample2", method=0, a=0.0))
    m1 = pitch_cone(design_from_annex("sample2", a=0.0))
    # the angles are those of Method 0 exactly (1e-12 rad: rounding only)
    for name in ("delta1", "delta2", "beta_m1", "beta_m2", "zeta_m", "zeta_mp", "alpha_lim",
                 "alpha_nD", "alpha_nC"):
        assert getattr(m1, name) == pytest.approx(getattr(m0, name), abs=1e-12), name
    assert m1.Re2 == pytest.approx(m0.Re2, rel=1e-12)
    assert m1.Rm1 == pytest.approx(m1.Rm2, rel=1e-12)  # the pitch apexes meet
    # Method 1 keeps its own calculation point r_mpt2 = (d_e2 − b2 sin δ_int2)/2,
    # δ_int2 = arctan(u / 1.2) at Σ = 90°, so R_m2 differs from Method 0's R_e2 − b2/2
    d = design_from_annex("sample2")
    r_mpt2 = 0.5 * (d.de2 - d.b2 * math.sin(math.atan(d.u / 1.2)))
    assert m1.Rm2 * math.sin(m1.delta2) == pytest.approx(r_mpt2, rel=1e-12)


def test_method1_is_continuous_as_offset_vanishes():
    # the a > 0 solver knows nothing of the a = 0 branch: its result must tend to it
    # linearly in a (the first-order terms of the offset geometry)
    ref = pitch_cone(design_from_annex("sample2", a=0.0))
    devs = []
    for a in (1e-2, 1e-3):
        p = pitch_cone(design_from_annex("sample2", a=a))
        devs.append(max(abs(p.delta1 - ref.delta1), abs(p.delta2 - ref.delta2),
                        abs(p.Rm1 - ref.Rm1) / ref.Rm1, abs(p.Rm2 - ref.Rm2) / ref.Rm2))
    # deviation ≤ 1e-2 rad (or relative) per mm of offset (sample 2 has ≈ 6e-3 per mm) and
    # shrinking ~10× for a 10× smaller offset (first order; 20 % slack on the ratio for the
    # second-order terms)
    assert devs[0] < 1e-2 * 1e-2
    assert devs[0] / devs[1] == pytest.approx(10.0, rel=0.2)


# --------------------------------------------------------------------------- 3-D checks
def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def _frame(sigma: float, a: float):
    """Gear axis z through O; pinion axis through (a, 0, 0) along (0, sin Σ, cos Σ)."""
    return np.array([0.0, 0.0, 1.0]), np.array([a, 0.0, 0.0]), np.array(
        [0.0, math.sin(sigma), math.cos(sigma)]
    )


def _angle(u: np.ndarray, v: np.ndarray) -> float:
    return math.atan2(np.linalg.norm(np.cross(u, v)), float(np.dot(u, v)))


@pytest.mark.parametrize("sigma_deg", [60.0, 90.0, 115.0])
@pytest.mark.parametrize(("zeta_deg", "eta_deg"), [(10.6, 4.2), (3.0, 12.0), (20.0, 20.0)])
def test_hypoid_pitch_angles_match_tangent_cones_in_3d(sigma_deg, zeta_deg, eta_deg):
    sigma, zeta, eta = map(math.radians, (sigma_deg, zeta_deg, eta_deg))
    delta1, delta2, zeta_mp = hypoid_pitch_angles(zeta, eta, sigma)
    e2, _, e1 = _frame(sigma, 0.0)
    # gear radial unit at azimuth ζ and pinion radial unit at angle η (module frame)
    rho2 = np.array([math.sin(zeta), math.cos(zeta), 0.0])
    x_hat, f_hat = np.array([1.0, 0.0, 0.0]), np.cross(np.array([1.0, 0.0, 0.0]), e1)
    rho1 = -math.sin(eta) * x_hat + math.cos(eta) * f_hat
    n2 = math.cos(delta2) * rho2 - math.sin(delta2) * e2  # outward normal of gear cone
    n1 = math.cos(delta1) * rho1 - math.sin(delta1) * e1  # outward normal of pinion cone
    # tangent cones: the outward normals are opposite (1e-12: rounding)
    np.testing.assert_allclose(n1, -n2, atol=1e-12)
    t2, t1 = np.cross(e2, rho2), np.cross(e1, rho1)
    assert zeta_mp == pytest.approx(min(_angle(t1, t2), _angle(t1, -t2)), abs=1e-12)
    if sigma_deg == 90.0:  # Gleason's Σ = 90° forms
        assert math.tan(delta1) == pytest.approx(math.sin(eta) / math.tan(zeta), rel=1e-12)
        assert math.tan(delta2) == pytest.approx(math.sin(zeta) / math.tan(eta), rel=1e-12)
        assert math.sin(zeta_mp) == pytest.approx(math.sin(zeta) / math.cos(delta1), rel=1e-12)


def _pitch_point(design, p):
    """P in the module frame from the gear side: azimuth ζ_m, radius r2, on the gear cone."""
    z_p = -p.t_z2 + p.Rm2 * math.cos(p.delta2)
    r2 = 0.5 * p.dm2
    return np.array([r2 * math.sin(p.zeta_m), r2 * math.cos(p.zeta_m), z_p])


@pytest.mark.parametrize("sigma_deg", [75.0, 90.0, 100.0])
def test_hypoid_pitch_cone_geometry_and_kinematics_in_3d(sigma_deg):
    design = design_from_annex("sample2", Sigma=sigma_deg)
    p = pitch_cone(design)
    e2, a1, e1 = _frame(design.Sigma, design.a)
    P = _pitch_point(design, p)
    # P is at the pinion pitch radius from the pinion axis, on the pinion pitch cone whose
    # apex lies t_z1 beyond the crossing point A1 (1e-9 mm / rad: solver tolerance)
    d = P - a1
    assert np.linalg.norm(d - np.dot(d, e1) * e1) == pytest.approx(0.5 * p.dm1, abs=1e-9)
    apex1 = a1 - p.t_z1 * e1
    assert np.linalg.norm(P - apex1) == pytest.approx(p.Rm1, abs=1e-9)
    assert _angle(P - apex1, e1) == pytest.approx(p.delta1, abs=1e-11)
    # kinematics: ω2 = e2, ω1 = ±u e1; the sliding velocity at P lies along the tooth, at
    # β_m1 from the pinion generatrix and β_m2 from the gear generatrix (for one sense of
    # rotation; 1e-9 rad: solver tolerance)
    apex2 = np.array([0.0, 0.0, -p.t_z2])
    g1, g2 = _unit(P - apex1), _unit(P - apex2)
    matches = []
    for sign in (1.0, -1.0):
        w = np.cross(sign * design.u * e1, P - a1) - np.cross(e2, P)
        b1 = min(_angle(w, g1), _angle(-w, g1))
        b2 = min(_angle(w, g2), _angle(-w, g2))
        matches.append(abs(b1 - p.beta_m1) < 1e-9 and abs(b2 - p.beta_m2) < 1e-9)
    assert any(matches)


def test_limit_radius_matches_contact_along_the_tooth():
    """ρ_lim closed form vs its definition by relative velocities at P (sample 2)."""
    design = design_from_annex("sample2")
    p = pitch_cone(design)
    e2, a1, e1 = _frame(design.Sigma, design.a)
    P = _pitch_point(design, p)
    apex1 = a1 - p.t_z1 * e1
    n_t = _unit(np.cross(_unit(P - apex1), _unit(P - np.array([0.0, 0.0, -p.t_z2]))))
    candidates = []
    for sign in (1.0, -1.0):
        om12 = sign * design.u * e1 - e2
        w = np.cross(sign * design.u * e1, P - a1) - np.cross(e2, P)
        ll = _unit(w)
        m = np.cross(n_t, ll)
        for psi in (p.alpha_lim, -p.alpha_lim):
            for mm in (m, -m):
                normal = math.sin(psi) * n_t + math.cos(psi) * mm
                # normal curvature cos ψ / ρ along the tooth = N·(ω12 × w)/|w|²
                k = float(np.dot(normal, np.cross(om12, w))) / float(np.dot(w, w))
                if k > 0:
                    candidates.append(math.cos(psi) / k)
    # the closed form gives r_c0 at the Method 1 solution; the vector definition must give the
    # same for one orientation of flank and rotation (1e-8 relative: solver tolerance); the
    # other orientations give values far away (> 1 mm), so the match is not accidental
    closed = limit_radius(p.delta1, p.delta2, p.Rm1, p.Rm2, p.beta_m1, p.beta_m2, p.alpha_lim)
    assert closed == pytest.approx(design.rc0, rel=1e-10)
    best = min(candidates, key=lambda r: abs(r - closed))
    assert best == pytest.approx(closed, rel=1e-8)
    assert sorted(abs(r - closed) for r in candidates)[1] > 1.0


@pytest.mark.parametrize("sigma_deg", [80.0, 90.0])
def test_pinion_face_and_root_cones_tangent_to_gear_cones_in_3d(sigma_deg):
    design = design_from_annex("sample2", Sigma=sigma_deg)
    g = blank_geometry(design)
    p, gear, pin = g.pitch, g.gear, g.pinion
    _, a1, e1 = _frame(design.Sigma, design.a)
    r_p, z_p = p.Rm2 * math.sin(p.delta2), -p.t_z2 + p.Rm2 * math.cos(p.delta2)
    for phi, d_gear, t_gear, d_pin, t_pin in (
        (g.zeta_R, gear.delta_f, gear.t_zR, pin.delta_a, pin.t_zF),  # gear root / pinion face
        (g.zeta_o, gear.delta_a, gear.t_zF, pin.delta_f, pin.t_zR),  # gear face / pinion root
    ):
        n = np.array([math.cos(d_gear) * math.sin(phi), math.cos(d_gear) * math.cos(phi),
                      -math.sin(d_gear)])
        m = np.array([r_p * math.sin(phi), r_p * math.cos(phi), z_p])
        # the normal line through the mean point's meridian position meets the pinion axis
        # (distance between the lines; 1e-9 mm: rounding)
        cross = np.cross(n, e1)
        assert abs(np.dot(m - a1, cross)) / np.linalg.norm(cross) < 1e-9
        # its foot Q on the gear cone, offset by the clearance c, lies on the pinion cone,
        # whose generatrix there is normal to n: the cones are tangent (1e-9: rounding)
        apex_gear = np.array([0.0, 0.0, -t_gear])
        t0 = float(np.dot(apex_gear - m, n))  # Q = m + t0 n satisfies (Q − apex)·n = 0
        q = m + (t0 + g.c) * n
        apex_pin = a1 - t_pin * e1
        assert _angle(q - apex_pin, e1) == pytest.approx(d_pin, abs=1e-9)
        assert abs(np.dot(_unit(q - apex_pin), n)) < 1e-9


# --------------------------------------------------------------------------- formulas
@pytest.mark.parametrize("R", [60.0, 81.27, 93.97])
def test_spiral_angle_follows_cutter_circle(R):
    # brute force: circle of radius r_c0 in the pitch plane through the mean point at cone
    # distance R_m with spiral angle β_m; find its point at distance R from the apex and
    # measure the angle between the circle tangent and the radius vector
    Rm, beta, rc0 = 81.27, math.radians(35.0), 114.3
    centre = np.array([Rm, 0.0]) + rc0 * np.array([-math.sin(beta), math.cos(beta)])
    t = np.linspace(-0.6, 0.6, 200001)
    pts = centre + rc0 * np.stack([np.sin(beta + t), -np.cos(beta + t)], axis=1)
    i = int(np.argmin(np.abs(np.linalg.norm(pts, axis=1) - R)))
    tangent = np.array([math.cos(beta + t[i]), math.sin(beta + t[i])])
    radial = pts[i] / np.linalg.norm(pts[i])
    brute = math.acos(abs(float(np.dot(tangent, radial))))
    # grid step 6e-6 rad of the circle parameter bounds the brute-force error near 1e-5 rad
    assert spiral_angle_at(R, Rm, beta, rc0) == pytest.approx(brute, abs=2e-5)


def _trace_point(Rm: float, beta: float, rc0: float, R: float) -> tuple[np.ndarray, np.ndarray]:
    """Point at distance R from the apex on the cutter circle through (R_m, 0) with spiral
    angle β there (pitch plane, apex at the origin), and the unit tooth tangent there."""
    centre = np.array([Rm, 0.0]) + rc0 * np.array([-math.sin(beta), math.cos(beta)])

    def point(t: float) -> np.ndarray:
        return centre + rc0 * np.array([math.sin(beta + t), -math.cos(beta + t)])

    t = brentq(lambda t: float(np.linalg.norm(point(t))) - R, -0.9, 0.9, xtol=1e-15)
    return point(t), np.array([math.cos(beta + t), math.sin(beta + t)])


@pytest.mark.parametrize("b_x1", [-18.0, -7.5, 0.0, 6.0, 16.09])
@pytest.mark.parametrize("zeta_mp_deg", [0.0, 11.39, 20.0])
def test_pinion_spiral_angle_by_construction_in_the_pitch_plane(b_x1, zeta_mp_deg):
    """Pinion heel/toe spiral angle vs a drawing of the pitch plane (sample-2-like data).

    Construction (the geometry behind ISO 23509's corresponding point): the gear apex O2 at
    the origin, the mean point P = (R_m2, 0), the tooth trace a circle of radius r_c0 through
    P at β_m2 to O2P; the pinion generatrix through P makes ζ_mp with O2P on the side that
    gives β_m1 = β_m2 + ζ_mp. The pinion face-width end is X = P + b_x1·d on it. Turning the
    pitch plane about O2 until X lies on the tooth trace (point T, |T| = |X|) carries the
    pinion generatrix with it; the pinion spiral angle is the angle between the tooth
    tangent at T and the turned generatrix.
    """
    Rm2, beta2, rc0 = 76.33, math.radians(38.61), 63.5
    zeta = math.radians(zeta_mp_deg)
    P = np.array([Rm2, 0.0])
    d = np.array([math.cos(zeta), -math.sin(zeta)])  # pinion generatrix direction at P
    X = P + b_x1 * d
    T, tangent = _trace_point(Rm2, beta2, rc0, float(np.linalg.norm(X)))
    phi = math.atan2(T[1], T[0]) - math.atan2(X[1], X[0])
    rot = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])
    brute = math.acos(float(np.dot(tangent, rot @ d)))
    # root-found construction, exact up to rounding: 1e-10 rad
    got = pinion_spiral_angle_at(b_x1, Rm2, beta2, zeta, rc0)
    assert got == pytest.approx(brute, abs=1e-10)


def test_pinion_spiral_angle_identities():
    Rm2, beta2, rc0, zeta = 76.33, math.radians(38.61), 63.5, math.radians(11.39)
    # at the calculation point the pinion angle is β_m1 = β_m2 + ζ_mp (rounding only, 1e-14)
    assert pinion_spiral_angle_at(0.0, Rm2, beta2, zeta, rc0) == pytest.approx(
        beta2 + zeta, abs=1e-14)
    # without offset the pinion end lies on the common cone: the gear's cutter-circle formula
    # at R_m + b_x1 (rounding only, 1e-14 rad)
    for b in (-15.0, 12.0):
        assert pinion_spiral_angle_at(b, Rm2, beta2, 0.0, rc0) == pytest.approx(
            spiral_angle_at(Rm2 + b, Rm2, beta2, rc0), abs=1e-14)


def test_hypoid_pinion_end_spiral_angles_differ_from_naive_cutter_formula(geometries):
    # the Annex F values (57.544°, 44.879°) are met by the corresponding-point construction;
    # the cutter formula at the pinion's own cone distances misses them by more than 1° —
    # guards against a regression to that naive form (margins ≫ the 2 % tolerance)
    g = geometries["sample2"]
    pin = g.pinion
    naive_e = math.degrees(spiral_angle_at(pin.Re, pin.Rm, pin.beta_m, g.design.rc0))
    naive_i = math.degrees(spiral_angle_at(pin.Ri, pin.Rm, pin.beta_m, g.design.rc0))
    assert abs(naive_e - 57.544) > 1.0 and abs(naive_i - 44.879) > 1.0
    # and the blank uses the corresponding point (printed precision 0.001°; the converged
    # Method 1 shifts R_m1 by 0.03 mm against the printed sample, worth < 0.01°)
    assert math.degrees(pin.beta_e) == pytest.approx(57.544, abs=0.01)
    assert math.degrees(pin.beta_i) == pytest.approx(44.879, abs=0.01)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [({"Rm2": 0.0}, "Rm2"), ({"zeta_mp": -0.1}, "zeta_mp"), ({"zeta_mp": 1.6}, "zeta_mp"),
     ({"b_x1": -80.0}, "b_x1"), ({"rc0": 5.0}, "rc0")],
)
def test_pinion_spiral_angle_bad_input(kwargs, field):
    args = {"b_x1": 10.0, "Rm2": 76.33, "beta_m2": math.radians(38.61),
            "zeta_mp": math.radians(11.39), "rc0": 63.5}
    args.update(kwargs)
    with pytest.raises(InputError, match=field):
        pinion_spiral_angle_at(**args)


@pytest.mark.parametrize("sample", ["sample1", "sample2"])
def test_thickness_balance(geometries, sample):
    g = geometries[sample]
    # s_mn1 + s_mn2 + j_mn = π m_mn: identity up to rounding (1e-12 mm)
    total = g.pinion.smn + g.gear.smn + g.j_mn
    assert total == pytest.approx(math.pi * g.m_mn, abs=1e-12)
    # depths: h_mw = h_am1 + h_am2, h_m = h_am + h_fm per member (1e-12 mm)
    assert g.pinion.ham + g.gear.ham == pytest.approx(g.hmw, abs=1e-12)
    for member in (g.pinion, g.gear):
        assert member.ham + member.hfm == pytest.approx(g.hm, abs=1e-12)


# --------------------------------------------------------------------------- bad input
_BAD = [
    ("method", 2, ModelUnavailableError),
    ("method", 1.5, InputError),
    ("Sigma", 0.0, InputError),
    ("a", -1.0, InputError),
    ("a", 100.0, InputError),
    ("z1", 4, InputError),
    ("z1", True, InputError),
    ("z2", 10, InputError),
    ("de2", -5.0, InputError),
    ("de2", float("nan"), InputError),
    ("b2", 0.0, InputError),
    ("b2", 90.0, InputError),
    ("beta_m", 80.0, InputError),
    ("rc0", 0.0, InputError),
    ("alpha_dD", 0.0, InputError),
    ("alpha_dC", 50.0, InputError),
    ("f_alim", 1.5, InputError),
    ("c_ham", 0.6, InputError),
    ("k_d", 0.0, InputError),
    ("k_c", -0.1, InputError),
    ("k_t", "thick", InputError),
    ("backlash", "j_xx", InputError),
    ("backlash_value", -0.1, InputError),
    ("theta_a2", 25.0, InputError),
    ("theta_f2", float("inf"), InputError),
    ("hand", "up", InputError),
]


@pytest.mark.parametrize(("field", "value", "error"), _BAD, ids=[f"{f}={v!r}" for f, v, _ in _BAD])
def test_bad_input_names_the_field(field, value, error):
    with pytest.raises(error, match=field):
        design_from_annex("sample2", **{field: value})


def test_a_shaft_angle_past_the_internal_gear_names_sigma():
    """Σ 170° on Annex F sample 2 (13x42): the spiral bevel (a = 0) is refused on
    construction, the hypoid (a = 15 mm) by its pitch cone, which does not close past the
    spiral bevel's bound (issue 71, round 39: a hypoid's own pitch cone decides, the FH 12x41
    at a = 31.5 mm has δ2 80.2° at Σ 110° past its 107.02°); both name Sigma and the bound
    arccos(−13/42) = 108.03° first (exact to the 2 decimals printed)."""
    limit = f"{math.degrees(math.acos(-13 / 42)):.2f}"
    assert limit == "108.03"
    with pytest.raises(InputError, match=rf"^Sigma: must be below {limit} for 13x42 "):
        design_from_annex("sample2", Sigma=170.0, a=0.0)
    hypoid = design_from_annex("sample2", Sigma=170.0)
    with pytest.raises(InputError, match=rf"^Sigma: must be below {limit} for 13x42 .*"
                                         r"unless the hypoid's own pitch cone closes past it"):
        blank_geometry(hypoid)


def test_offset_with_method0_is_rejected():
    with pytest.raises(InputError, match=r"a: must be 0 for method 0.*got 15"):
        design_from_annex("sample2", method=0)


def test_negative_offset_names_the_convention():
    # a user's hypoid "with the pinion above centre" typed as a = -32 mm (issue 71, unseen
    # designs): the range, and why a < 0 is not the mirror image the hand gives
    with pytest.raises(InputError, match=r"^a: must be in \[0, 85\) \[mm\], got -32: a "
                       r"negative offset \(the pinion spiral angle smaller.*`hand`"):
        design_from_annex("sample2", a=-32.0)


def test_unknown_field_is_rejected():
    """The unknown field named first, then the accepted ones, as every other table's
    unknown field reads (the basic file's ``design.`` before it: "design.shaft_angle:
    unknown field; accepted: Sigma, a, …"; before, "design.unknown design field(s)
    ['shaft_angle']: accepted [...]")."""
    with pytest.raises(InputError, match=r"^shaft_angle: unknown field; accepted: Sigma, a, "):
        design_from_annex("sample2", shaft_angle=90.0)
    with pytest.raises(InputError, match=r"^foo, shaft_angle: unknown fields; accepted: "):
        design_from_annex("sample2", shaft_angle=90.0, foo=1.0)


def test_cutter_radius_below_every_limit_radius_is_rejected():
    # for sample 2 the limit radius of Method 1 pitch cones never falls below ~17 mm
    with pytest.raises(InputError, match="rc0"):
        pitch_cone(design_from_annex("sample2", rc0=10.0))


def test_gear_spiral_angle_of_wrong_hand_is_rejected():
    # β_m2 = β_m1 − ζ_mp < 0 for β_m1 = 5° at sample 2's offset (ζ_mp ≈ 11.7°)
    with pytest.raises(InputError, match="beta_m"):
        pitch_cone(design_from_annex("sample2", beta_m=5.0))


def test_degenerate_toe_is_rejected():
    with pytest.raises(InputError, match="theta_a2"):
        blank_geometry(design_from_annex("sample1", theta_a2=19.0))


# --------------------------------------------------------------------------- output
def test_dataset_units_and_round_trip(geometries, tmp_path):
    ds = blank_dataset(geometries["sample2"])
    for name, var in ds.variables.items():
        if name == "member":
            continue
        assert var.attrs.get("units") and var.attrs.get("long_name"), name
    # angles are stored in rad: the gear pitch angle of sample 2 is ≈ 68.3° (printed values)
    assert float(ds["delta"].sel(member="gear")) == pytest.approx(math.radians(68.33), rel=2e-3)
    path = tmp_path / "blank.nc"
    ds.to_netcdf(path, engine="netcdf4")
    with xr.open_dataset(path, engine="netcdf4") as back:
        xr.testing.assert_identical(back.load(), ds)


def test_in_degrees_converts_only_angles(geometries):
    g = geometries["sample1"]
    d = in_degrees(g)
    assert d["gear"]["delta"] == pytest.approx(math.degrees(g.gear.delta), rel=1e-15)
    assert d["gear"]["Re"] == g.gear.Re
    assert d["design"]["Sigma"] == pytest.approx(90.0, rel=1e-15)
    with pytest.raises(InputError, match="obj"):
        in_degrees(3.0)


def test_gear_face_angle_beyond_90_names_the_addendum_angle():
    # a spiral bevel 12x35 at Σ 110° (issue 71, unseen (11)): δ2 89.95°, θ_a2 1° put the
    # gear's face angle at 90.95°, which stopped `ltca synthesize` with the case blank's
    # "face_angle: must be in (0, 90]"; the ISO blank itself is made (its formulas hold for
    # any pitch angle), and the check a case's blank needs names the basic field and range
    design = design_from_annex("sample1", method=0, a=0.0, Sigma=110.0, z1=12, z2=35,
                               theta_a2=1.0, theta_f2=4.0)
    g = blank_geometry(design)
    d2 = math.degrees(g.gear.delta)
    assert 89.9 < d2 < 90.0  # the pitch angle alone is within the plane
    assert math.degrees(g.gear.delta_a) == pytest.approx(d2 + 1.0, abs=1e-12)
    with pytest.raises(InputError, match=r"^theta_a2: must be in \[0, 90° − δ2\] = \[0, "
                       r"0\.0[0-9]*\] \[deg\].*got 1: δ2 89\.9[0-9]*° \(Σ 110°"):
        check_face_angles(g)
    ok = blank_geometry(design_from_annex("sample1", method=0, a=0.0, Sigma=110.0, z1=12,
                                          z2=35, theta_a2=0.0, theta_f2=4.0))
    assert check_face_angles(ok) is ok
    assert ok.gear.delta_a == pytest.approx(math.radians(d2), abs=1e-12)


def test_basic_design_blank_checks_face_angles():
    # the synthesis' blank (BasicDesign.blank) is the checked one: the same 12x35 basic
    # file as a user types it stops with the basic field, not the case blank's
    from geometry.synthesis.basic_design import basic_from_dict

    raw = {"name": "sb12x35", "source": "test: spiral bevel 12x35 at Sigma 110 deg", "design": {
        "method": 0, "Sigma": 110.0, "a": 0.0, "z1": 12, "z2": 35, "de2": 180.0, "b2": 27.0,
        "beta_m": 35.0, "rc0": 57.15, "alpha_dD": 20.0, "alpha_dC": 20.0, "f_alim": 1.0,
        "c_ham": 0.25, "k_d": 2.0, "k_c": 0.125, "k_t": 0.1, "backlash": "j_et2",
        "backlash_value": 0.12, "theta_a2": 1.0, "theta_f2": 4.0, "hand": "left"}}
    with pytest.raises(InputError, match=r"^theta_a2: must be in \[0, 90° − δ2\]"):
        basic_from_dict(raw).blank()
    raw["design"]["theta_a2"] = 0.0
    assert math.degrees(basic_from_dict(raw).blank().gear.delta_a) < 90.0
