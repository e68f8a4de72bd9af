"""Weber contact deformation, Sainsot fillet-foundation compliance, and the total
single-tooth-pair stiffness of a spur-like limit case against ISO 6336-1."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact.compliance import (
    ShellTooth,
    ToothFoundation,
    build_shell_model,
    compliance_matrix,
    contact_modulus,
    foundation_compliance,
    foundation_matrix,
    hertz_half_width,
    load_angle_from_normals,
    load_line_height,
    sainsot_coefficients,
    weber_compliance,
    weber_deformation,
    weber_pair_deformation,
)
from geometry.core.errors import InputError, ModelUnavailableError

STEEL_E = 206000.0  # MPa
STEEL_NU = 0.3


# --------------------------------------------------------------------------- Weber
def test_weber_against_hand_evaluation():
    """w′ = 100 N/mm, R_eq = 10 mm, steel/steel, h₁ = 5 mm, h₂ = 6 mm.

    Hand evaluation (calculator, 5 significant digits) of the published formulas:
    E* = 1/(2·0.91/206000) = 113 187 MPa; b = sqrt(4·100·10/(π·113 187)) = 0.10606 mm;
    k = 2·100·0.91/(π·206000) = 2.8123e-4 mm; δ₁ = k (ln(10/0.10606) − 0.3/1.4)
    = 2.8123e-4 · (4.5463 − 0.21429) = 1.2183e-3 mm; δ₂ = k (ln(12/0.10606) − 0.21429)
    = 1.2696e-3 mm. Tolerance 5e-4 relative: the hand values carry 5 digits.
    """
    assert contact_modulus(STEEL_E, STEEL_NU, STEEL_E, STEEL_NU) == pytest.approx(113187, rel=5e-5)
    b = hertz_half_width(100.0, 10.0, STEEL_E, STEEL_NU, STEEL_E, STEEL_NU)
    assert b == pytest.approx(0.10606, rel=5e-4)
    d1 = weber_deformation(100.0, b, 5.0, STEEL_E, STEEL_NU)
    d2 = weber_deformation(100.0, b, 6.0, STEEL_E, STEEL_NU)
    assert d1 == pytest.approx(1.2183e-3, rel=5e-4)
    assert d2 == pytest.approx(1.2696e-3, rel=5e-4)
    pair = weber_pair_deformation(100.0, 10.0, 5.0, 6.0, STEEL_E, STEEL_NU, STEEL_E, STEEL_NU)
    assert pair == pytest.approx(d1 + d2, rel=1e-14)  # identity: the pair is the sum


def test_weber_dissimilar_materials_independent_arithmetic():
    """Steel on bronze-like (E₂ = 110 000 MPa, ν₂ = 0.34), formula re-typed here."""
    w, r, h1, h2 = 250.0, 7.5, 4.0, 9.0
    e2, nu2 = 110000.0, 0.34
    e_star = 1.0 / ((1 - STEEL_NU**2) / STEEL_E + (1 - nu2**2) / e2)
    b = math.sqrt(4 * w * r / (math.pi * e_star))
    exp1 = 2 * w * (1 - STEEL_NU**2) / (math.pi * STEEL_E) * (
        math.log(2 * h1 / b) - STEEL_NU / (2 * (1 - STEEL_NU))
    )
    exp2 = 2 * w * (1 - nu2**2) / (math.pi * e2) * (math.log(2 * h2 / b) - nu2 / (2 * (1 - nu2)))
    got = weber_pair_deformation(w, r, h1, h2, STEEL_E, STEEL_NU, e2, nu2)
    assert got == pytest.approx(exp1 + exp2, rel=1e-12)  # same formula, rounding only


def test_weber_secant_and_tangent_are_consistent_with_the_deformation():
    """Identities: secant·F = δ(F); tangent = dδ/dF (central difference, h = 1e-4 F,
    truncation error O(h²) ~ 1e-8 relative, tolerance 1e-6)."""
    F = np.array([50.0, 400.0, 3000.0])  # N
    L = np.array([0.5, 1.0, 2.0])  # mm
    kw = dict(e1=STEEL_E, nu1=STEEL_NU, e2=STEEL_E, nu2=STEEL_NU, r_eq=12.0)
    sec = weber_compliance(F, L, 4.0, 5.0, kind="secant", **kw)
    tan = weber_compliance(F, L, 4.0, 5.0, kind="tangent", **kw)

    def delta(f):
        return weber_pair_deformation(f / L, 12.0, 4.0, 5.0, STEEL_E, STEEL_NU, STEEL_E, STEEL_NU)

    np.testing.assert_allclose(sec * F, delta(F), rtol=1e-12)
    h = 1e-4 * F
    np.testing.assert_allclose(tan, (delta(F + h) - delta(F - h)) / (2 * h), rtol=1e-6)
    assert np.all(tan < sec)  # δ is concave in F (log term): tangent below secant
    # both kinds from one evaluation (the LTCA's Newton step): the same arrays to a few ulp
    # (1e-14: the log is numpy's SIMD kernel, whose unaligned head may round differently)
    both = weber_compliance(F, L, 4.0, 5.0, kind=("secant", "tangent"), **kw)
    np.testing.assert_allclose(both[0], sec, rtol=1e-14, atol=0)
    np.testing.assert_allclose(both[1], tan, rtol=1e-14, atol=0)


def test_weber_half_width_function_matches_hertz():
    """A user half-width function equal to Hertz gives the r_eq result (the log-slope
    by central difference is exact to O(step²) = 1e-8; tolerance 1e-7)."""
    e_star = 1.0 / (2 * (1 - STEEL_NU**2) / STEEL_E)
    F, L = np.array([100.0, 900.0]), np.array([1.0, 1.5])
    kw = dict(e1=STEEL_E, nu1=STEEL_NU, e2=STEEL_E, nu2=STEEL_NU)
    for kind in ("secant", "tangent"):
        ref = weber_compliance(F, L, 4.0, 4.0, r_eq=9.0, kind=kind, **kw)
        got = weber_compliance(
            F, L, 4.0, 4.0, kind=kind,
            half_width_fn=lambda w: np.sqrt(4 * w * 9.0 / (math.pi * e_star)), **kw,
        )
        np.testing.assert_allclose(got, ref, rtol=1e-7)


def test_weber_errors():
    kw = dict(e1=STEEL_E, nu1=STEEL_NU, e2=STEEL_E, nu2=STEEL_NU)
    with pytest.raises(InputError, match="load"):
        weber_compliance(-1.0, 1.0, 4.0, 4.0, r_eq=9.0, **kw)
    with pytest.raises(InputError, match="r_eq"):
        weber_compliance(1.0, 1.0, 4.0, 4.0, **kw)
    with pytest.raises(ModelUnavailableError, match="secant"):
        weber_compliance(1.0, 1.0, 4.0, 4.0, r_eq=9.0, kind="chord", **kw)
    with pytest.raises(InputError, match="depth"):
        weber_deformation(1e6, 1.0, 0.1, STEEL_E, STEEL_NU)
    with pytest.raises(InputError, match="nu1"):
        contact_modulus(STEEL_E, 0.6, STEEL_E, STEEL_NU)


# --------------------------------------------------------------------------- Sainsot
def test_sainsot_coefficients_against_hand_evaluation():
    """h_f = 2, θ_f = 0.08 rad. Hand sums of X* = A/θ² + B h² + C h/θ + D/θ + E h + F:
    L* = −0.0087094 − 0.0079944 − 0.0057538 + 0.059628 + 0.0542 + 6.8045 = 6.89587;
    M* = 0.093923 + 0.1124 − 0.20858 − 0.12407 + 0.3248 + 0.9086 = 1.10708.
    Tolerance 1e-5 relative (hand sums kept to 6 digits)."""
    c = sainsot_coefficients(2.0, 0.08)
    assert c["L"] == pytest.approx(6.89587, rel=1e-5)
    assert c["M"] == pytest.approx(1.10708, rel=1e-5)
    # P* and Q* re-typed from the published table (independent arithmetic)
    h, t = 2.0, 0.08
    p = -50.952e-5 / t**2 + 185.50e-3 * h**2 + 0.0538e-4 * h / t + 53.300e-3 / t + 0.2895 * h
    q = -6.2042e-5 / t**2 + 9.0889e-3 * h**2 - 4.0964e-4 * h / t + 7.8297e-3 / t - 0.1472 * h
    assert c["P"] == pytest.approx(p + 0.9236, rel=1e-12)
    assert c["Q"] == pytest.approx(q + 0.6904, rel=1e-12)


def test_sainsot_deflection_formula():
    """δ_f/F = cos²α/(E b) [L*(u/S)² + M*(u/S) + P*(1 + Q* tan²α)], re-typed."""
    fnd = ToothFoundation(root_radius=60.0, inner_radius=30.0, root_half_angle=0.08,
                          face_width=25.0, youngs_modulus=STEEL_E)
    u = np.array([2.0, 5.0, 9.0])
    a = np.radians([10.0, 20.0, 25.0])
    c = sainsot_coefficients(2.0, 0.08)
    s_f = 2 * 60.0 * 0.08
    exp = np.cos(a) ** 2 / (STEEL_E * 25.0) * (
        c["L"] * (u / s_f) ** 2 + c["M"] * u / s_f + c["P"] * (1 + c["Q"] * np.tan(a) ** 2)
    )
    np.testing.assert_allclose(foundation_compliance(fnd, u, a), exp, rtol=1e-12)


def test_foundation_matrix_is_reciprocal_low_rank_and_matches_sainsot():
    """Identities the coupling must satisfy: symmetric (Maxwell–Betti), diagonal =
    Sainsot's formula, rank ≤ 3, positive semi-definite (tolerances: rounding)."""
    fnd = ToothFoundation(60.0, 30.0, 0.08, 25.0, STEEL_E)
    rng = np.random.default_rng(1)
    u = rng.uniform(0.5, 10.0, 12)
    a = rng.uniform(0.05, 0.45, 12)
    C = foundation_matrix(fnd, u, a)
    np.testing.assert_allclose(C, C.T, rtol=0, atol=1e-15 * np.abs(C).max())
    np.testing.assert_allclose(np.diag(C), foundation_compliance(fnd, u, a), rtol=1e-12)
    ev = np.linalg.eigvalsh(C)
    assert ev.min() > -1e-12 * ev.max()
    assert np.sum(ev > 1e-10 * ev.max()) <= 3


def test_load_line_and_angle_helpers():
    # flank tilted 15° towards the tip: the load pushes towards the root, α = +15°
    n = np.array([[math.sin(0.2618), 0.0, math.cos(0.2618)],
                  [math.sin(0.2618), 0.0, -math.cos(0.2618)]])
    np.testing.assert_allclose(load_angle_from_normals(n), 0.2618, rtol=1e-12)
    assert load_line_height(6.0, 4.0, math.atan(0.5)) == pytest.approx(5.0, rel=1e-14)


def test_foundation_errors():
    with pytest.raises(InputError, match="inner_radius"):
        ToothFoundation(60.0, 70.0, 0.08, 25.0, STEEL_E)
    with pytest.raises(InputError, match="root_half_angle"):
        ToothFoundation(60.0, 30.0, 2.0, 25.0, STEEL_E)
    fnd = ToothFoundation(60.0, 30.0, 0.08, 25.0, STEEL_E)
    with pytest.raises(InputError, match="load_angle"):
        foundation_compliance(fnd, 3.0, 1.7)


# --------------------------------------------------------------- ISO 6336-1 spur limit
def test_spur_limit_single_stiffness_against_iso_6336():
    """Single-tooth-pair stiffness of two z = 30, m = 5 mm, α = 20° standard spur gears
    (flat limit of the shell: R = 1e5 mm) at the pitch point, w′ = 300 N/mm:
    bending + shear (shell, flank load along the line of action) + Weber + base
    (Sainsot) of both teeth, against ISO 6336-1:2006 method B single stiffness
    c′ = c′_th C_M C_R C_B cos β, c′_th = 1/q′, q′ = C1 + C2/z₁ + C3/z₂ (x = 0), C1 = 0.04723,
    C2 = 0.15551, C3 = 0.25791 [mm·µm/N], C_M = 0.8, C_R = C_B = cos β = 1
    → c′ = 13.1 N/(mm·µm) (ISO's usual rounded value for solid spur gears: 14).

    The tooth is idealised a priori (no tuning): linear thickness from the root arc
    thickness S_f (rack tip land rolled to the root circle) to the involute tip
    thickness s_a, height 2.25 m; the body has a 25 mm bore radius. Tolerance
    30 %: ISO's c′ is an empirical value for average solid spur gears, and our tooth
    is a trapezoid, not an involute with fillets (measured: c′ = 10.8, −17 %).
    """
    m, z, alpha = 5.0, 30, math.radians(20.0)
    r = m * z / 2
    rb, ra, rf = r * math.cos(alpha), r + m, r - 1.25 * m

    def inv(a):
        return math.tan(a) - a

    s = math.pi * m / 2
    s_a = 2 * ra * (s / (2 * r) + inv(alpha) - inv(math.acos(rb / ra)))  # 3.687 mm
    s_f = 2 * math.pi * rf / z - (s - 2 * 1.25 * m * math.tan(alpha)) * rf / r  # 11.37 mm
    b, big_r = 20.0, 1e5
    tooth = ShellTooth.from_face_width(
        thickness_toe_root=s_f, thickness_heel_root=s_f, thickness_tip=s_a,
        height_toe=2.25 * m, height_heel=2.25 * m, face_width=b, radius=big_r,
        youngs_modulus=STEEL_E, poisson_ratio=STEEL_NU,
    )
    x = r - rf  # pitch point above the root circle
    a_f = alpha - s / (2 * r)  # load line to the normal of the tooth centreline
    normal = np.array([[math.sin(a_f), 0.0, math.cos(a_f)]])
    model = build_shell_model(tooth, 6, 3)  # uniform across the face: 3 face modes
    c_shell = compliance_matrix(
        model, np.array([[[x, 0.0], [x, b / big_r]]]), normals=normal, n_segment_gauss=6
    ).matrix[0, 0]
    t_x = float(tooth.thickness(x, 0.0))
    depth = 0.5 * t_x / math.cos(a_f)  # contact to centreline along the load line
    r_eq = (r * math.sin(alpha)) / 2  # equal gears at the pitch point
    w = 300.0
    c_weber = float(weber_compliance(w * b, b, depth, depth, e1=STEEL_E, nu1=STEEL_NU,
                                     e2=STEEL_E, nu2=STEEL_NU, r_eq=r_eq))
    fnd = ToothFoundation(rf, 25.0, s_f / (2 * rf), b, STEEL_E)
    c_base = float(foundation_compliance(fnd, load_line_height(x, t_x, a_f), a_f)[0])
    c_total = 2 * c_shell + c_weber + 2 * c_base  # mm/N along the line of action
    c_prime = 1.0 / (c_total * b) / 1000.0  # N/(mm·µm)
    q = 0.04723 + 0.15551 / z + 0.25791 / z
    c_iso = 0.8 / q
    assert c_iso == pytest.approx(13.11, abs=0.01)
    assert c_prime == pytest.approx(c_iso, rel=0.30)


def _sainsot_g(c):
    return np.array([[c["L"], 0.5 * c["M"], 0.0], [0.5 * c["M"], c["P"], 0.0],
                     [0.0, 0.0, c["P"] * c["Q"]]])


def test_sainsot_bare_fit_goes_indefinite_below_its_range():
    """Why the coefficients are held (module docstring): the bare polynomial at a 19×62
    industrial gear's virtual tooth (h_f 2.009, θ_f 0.0071) gives P* < 0 and an
    indefinite coupling, and P* turns down below θ_f = −2A_P/D_P = 0.0191 (the fit's
    slope dP*/d ln(1/θ_f) changes sign there), while inside the range that slope is
    0.50–0.70, near the half-plane's 2(1 − ν²)/π = 0.579 (Flamant, ν = 0.3). Finite
    differences at a relative step 1e-6 (error ~1e-6 of the slope); bands as measured."""
    bare = sainsot_coefficients(2.009, 0.0071, extrapolate=True)
    assert bare["P"] < 0.0
    assert np.linalg.eigvalsh(_sainsot_g(bare)).min() < 0.0

    def slope(theta, h=2.0, eps=1e-6):
        p0 = sainsot_coefficients(h, theta, extrapolate=True)["P"]
        p1 = sainsot_coefficients(h, theta * (1 - eps), extrapolate=True)["P"]
        return (p1 - p0) / -math.log(1 - eps)

    half_plane = 2 * (1 - 0.3**2) / math.pi
    assert half_plane == pytest.approx(0.5793, abs=1e-4)
    for theta in (0.025, 0.03, 0.04, 0.06, 0.08):
        assert 0.45 < slope(theta) < 0.75
    assert slope(0.0185) < 0.0 < slope(0.0195)  # the maximum of P* at 0.0191
    assert slope(0.012) < -2.0


def test_sainsot_coefficients_beyond_the_fits_range():
    """Below θ_f 0.012: L* and M* those at the bound, P* and P* Q* those at the bound plus
    k ln(0.012/θ_f), k = 2(1 − ν²)/π (hand values); above h_f 7 the values at h_f 7;
    inside the range the bare fit (exact equality: the same arithmetic). At the bound the
    coefficients lie within the published coefficient ranges (L* 6.82–6.94, M* 1.08–3.29,
    P* 2.56–13.47, Q* 0.141–0.62: the ranges the fit was made over, as ROSS's
    GearElementTVMS types them), within 1 % (the bound is rounded to 0.012), at h_f 2 and
    3 (the default bore, half the root radius, gives h_f 2.0–2.3; at h_f 1.5, M* is 3.52,
    7 % above: a thin rim's data stopped at a larger θ_f)."""
    from contact.compliance.foundation import (
        SAINSOT_H_F_MAX,
        SAINSOT_LOG_SLOPE,
        SAINSOT_THETA_F_MIN,
    )

    assert SAINSOT_THETA_F_MIN == 0.012 and SAINSOT_H_F_MAX == 7.0
    assert SAINSOT_LOG_SLOPE == pytest.approx(2 * 0.91 / math.pi, rel=1e-15)
    b = sainsot_coefficients(2.009, 0.012)
    c = sainsot_coefficients(2.009, 0.0071)
    grow = 0.57932 * math.log(0.012 / 0.0071)  # 0.30408
    assert (c["L"], c["M"]) == (b["L"], b["M"])
    assert c["P"] == pytest.approx(b["P"] + grow, rel=1e-5)
    assert c["P"] * c["Q"] == pytest.approx(b["P"] * b["Q"] + grow, rel=1e-5)
    assert sainsot_coefficients(9.0, 0.05) == sainsot_coefficients(7.0, 0.05)
    assert sainsot_coefficients(2.0, 0.08) == sainsot_coefficients(2.0, 0.08, extrapolate=True)
    assert sainsot_coefficients(2.0, 0.012) == sainsot_coefficients(2.0, 0.012,
                                                                    extrapolate=True)
    published = {"L": (6.82, 6.94), "M": (1.08, 3.29), "P": (2.56, 13.47), "Q": (0.141, 0.62)}
    for h in (2.0, 3.0):
        at = sainsot_coefficients(h, 0.012)
        for k, (lo, hi) in published.items():
            assert lo * 0.99 <= at[k] <= hi * 1.01, (h, k, at[k])


def test_sainsot_coupling_positive_definite_and_continuous_everywhere():
    """Over h_f 1.001–60 and θ_f 0.001–1.5 rad (log grids) the held coupling G is
    positive definite (smallest eigenvalue > 0.5: measured 0.80, at h_f 7, θ_f ≥ 0.3;
    the bare fit's is −13 at θ_f 0.005), and the compliance of a tooth is continuous
    across the bound θ_f = 0.012: a step of ±1e-9 rad changes it by < 1e-6 relative
    (S_f = 2 r_f θ_f moves by 1e-7 relative, the log term by k·1e-7)."""
    worst = math.inf
    for h in np.geomspace(1.001, 60.0, 40):
        for theta in np.geomspace(0.001, 1.5, 60):
            worst = min(worst, np.linalg.eigvalsh(_sainsot_g(sainsot_coefficients(h, theta)))[0])
    assert worst > 0.5

    def tooth(theta, h=2.009):
        return ToothFoundation(root_radius=300.0, inner_radius=300.0 / h,
                               root_half_angle=theta, face_width=40.0,
                               youngs_modulus=STEEL_E)

    u, a = np.array([1.0, 5.0, 9.0]), np.array([0.1, 0.2, 0.35])
    below = foundation_compliance(tooth(0.012 - 1e-9), u, a)
    above = foundation_compliance(tooth(0.012 + 1e-9), u, a)
    np.testing.assert_allclose(below, above, rtol=1e-6)
    assert np.all(below > 0.0)
    rng = np.random.default_rng(3)
    c = foundation_matrix(tooth(0.0071), rng.uniform(0.5, 12.0, 10), rng.uniform(0.0, 0.5, 10))
    ev = np.linalg.eigvalsh(c)
    assert ev.min() > -1e-12 * ev.max()
