"""The opt-in thermal Eyring friction model (friction.thermal_eyring): limits and bounds.

Independent references: ``mixed_ehl``'s isothermal Eyring film (the model's limit as the
heating vanishes, with a tolerance bounded from the Eyring law: the stress is at most
linear in the viscosity, so heating by ΔT changes it by at most a fraction β ΔT);
Jaeger's moving band source integrated by :func:`friction.ehl.thermal.flash_temperature`
(the band mean (4/(3√π)) q √(2b)/(B √u) the model uses); the bound τ ≤ Λ p (the film's μ can
never exceed the limiting shear coefficient); the root equation itself.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from friction.coefficient import friction_coefficient
from friction.ehl.thermal import flash_temperature
from friction.flank_summits import greenwood_tripp_parameters, height_tail_integral
from friction.mixed_ehl import MIXED_EHL_DEFAULTS, mixed_ehl, mixed_ehl_solution
from friction.thermal_eyring import (
    _BAND_MEAN,
    STEEL_EFFUSIVITY,
    thermal_eyring,
    thermal_eyring_film_shear,
)
from geometry.core.errors import InputError

#: the flank segment of tests/test_mixed_ehl.py (Table 5.4 pairs, 1500 rpm, 90 °C, 75W90)
SEGMENT = dict(load_per_length=300.0, hertz_pressure=1000.0, radius=40.0, e_prime=2.26e5,
               entraining_velocity=2.5, sliding_velocity=1.5, viscosity=0.0135,
               pressure_viscosity=10.3, roughness_1=0.8, roughness_2=0.8)
BETA, K_OIL, BETA_ALPHA = 0.03, 0.135, 0.0065
LAMBDA = MIXED_EHL_DEFAULTS["limiting_shear_coefficient"][0]
MU_B = MIXED_EHL_DEFAULTS["boundary_friction"][0]
JGP, ZH = "johnson_greenwood_poon", "zhou_hoeprich"  # the two load sharings


def test_no_temperature_dependence_is_mixed_ehl() -> None:
    # β = 0: the viscosity does not feel the heat, the model is mixed_ehl to round-off
    u = np.array([0.5, 2.5, 10.0])
    kw = dict(SEGMENT, entraining_velocity=u)
    # (with mixed_ehl's load sharing, Johnson, Greenwood & Poon's)
    np.testing.assert_allclose(thermal_eyring(**kw, temperature_viscosity=0.0,
                                              summits="fixed", load_sharing=JGP),
                               mixed_ehl(**kw), rtol=1e-12)
    # with the ground flanks' summits: mixed_ehl with their ηβσ, σ/β and skewed heights
    ebs, sb = greenwood_tripp_parameters(0.8, 0.8)
    np.testing.assert_allclose(
        thermal_eyring(**kw, temperature_viscosity=0.0, load_sharing=JGP),
        mixed_ehl_solution(**kw, asperity_density_radius_sigma=ebs, sigma_over_beta=sb,
                           height_integral=lambda t: height_tail_integral(t, 0.8, 0.8)
                           ).friction_coefficient, rtol=1e-12)


def test_ground_summits_per_roughness_pair() -> None:
    # points of different Rq pairs are solved each with its own summits, as one by one
    rq1, rq2 = np.array([0.1, 0.8, 0.1, 1.3]), np.array([0.1, 0.8, 0.1, 0.4])
    kw = dict(SEGMENT, roughness_1=rq1, roughness_2=rq2)
    for sharing in (JGP, ZH):
        together = np.asarray(thermal_eyring(**kw, temperature_viscosity=BETA,
                                             load_sharing=sharing))
        alone = [thermal_eyring(**dict(SEGMENT, roughness_1=a, roughness_2=b),
                                temperature_viscosity=BETA, load_sharing=sharing)
                 for a, b in zip(rq1, rq2, strict=True)]
        np.testing.assert_allclose(together, alone, rtol=1e-12)
        assert together[0] == together[2]


@pytest.mark.parametrize("sliding", [1e-3, 3e-3])
def test_isothermal_low_sliding_limit(sliding: float) -> None:
    # As V_s → 0 the heat q = τ V_s vanishes. ΔT ≤ Λ p_h V_s (flash + h/(8k)) per unit τ,
    # and the Eyring stress is at most linear in η, so the film shear falls by at most a
    # fraction (β + β_α α p_h) ΔT_max (ln η falls by β ΔT + α p (1 − e^(−β_α ΔT))): that
    # bound (< 2e-3 here) is the stated tolerance.
    kw = dict(SEGMENT, sliding_velocity=sliding)
    iso = mixed_ehl_solution(**kw)
    b = 2.0 * SEGMENT["load_per_length"] / (math.pi * SEGMENT["hertz_pressure"]) * 1e-3
    u1, u2 = 2.5 + sliding / 2, 2.5 - sliding / 2
    flash = _BAND_MEAN * math.sqrt(2 * b) / (STEEL_EFFUSIVITY * (math.sqrt(u1) + math.sqrt(u2)))
    h = float(iso.film_thickness)
    # the largest isothermal stress in the zone (at p_h, γ₁ ≥ 1 only lowers it) [MPa]
    eta_max = SEGMENT["viscosity"] * math.exp(SEGMENT["pressure_viscosity"] * 1e-3
                                              * SEGMENT["hertz_pressure"])
    tau0 = MIXED_EHL_DEFAULTS["eyring_stress"][0]
    tau_max = min(LAMBDA * SEGMENT["hertz_pressure"],
                  tau0 * math.asinh(eta_max * sliding / (h * 1e-6) / (tau0 * 1e6)))
    dt_max = tau_max * 1e6 * sliding * (flash + h * 1e-6 / (8 * K_OIL))
    tol = (BETA + BETA_ALPHA * SEGMENT["pressure_viscosity"] * 1e-3
           * SEGMENT["hertz_pressure"]) * dt_max
    assert tol < 2e-3
    # the film's heat does not depend on how the asperities are described: the fixed
    # summits compare with mixed_ehl's solution as it is
    mu = thermal_eyring(**kw, temperature_viscosity=BETA, oil_thermal_conductivity=K_OIL,
                        pressure_viscosity_temperature=BETA_ALPHA, summits="fixed",
                        load_sharing=JGP)
    film_iso = float(iso.film_friction)
    film = mu - float(iso.boundary_friction)
    assert film <= film_iso * (1 + 1e-12)
    assert film >= film_iso * (1 - tol)


def test_bounded_by_limiting_shear_and_isothermal_and_finite() -> None:
    # over a grid far beyond gear conditions: finite, never above the isothermal model
    # (heating only thins the oil), and the film's part never above Λ (τ ≤ Λ p,
    # ∫p dx = w′/γ₁ ≤ w′), so μ ≤ max(μ_b, Λ)
    grid = list(itertools.product([100.0, 1000.0, 3000.0], [0.01, 1.0, 50.0],
                                  [0.0, 0.3, 2.0], [1e-3, 0.1, 1.0], [0.05, 1.5]))
    ph, u, sr, eta, rq = (np.array(v) for v in zip(*grid, strict=True))
    w = math.pi * 20.0 * ph**2 / 2.26e5 * 2
    kw = dict(load_per_length=w, hertz_pressure=ph, radius=20.0, e_prime=2.26e5,
              entraining_velocity=u, sliding_velocity=sr * u, viscosity=eta,
              pressure_viscosity=20.0, roughness_1=rq, roughness_2=rq)
    with pytest.warns(Warning):  # the validity range of mixed_ehl (p_h, u) is left
        iso = mixed_ehl_solution(**kw)
    for c_f in (0.0, 1.0):
        with pytest.warns(Warning):
            mu = np.asarray(thermal_eyring(**kw, temperature_viscosity=0.1,
                                           oil_thermal_conductivity=0.1, film_heating=c_f,
                                           pressure_viscosity_temperature=0.02,
                                           summits="fixed", load_sharing=JGP))
        with pytest.warns(Warning):  # Zhou & Hoeprich's share: the same bounds
            mu_zh = np.asarray(thermal_eyring(**kw, temperature_viscosity=0.1,
                                              oil_thermal_conductivity=0.1, film_heating=c_f,
                                              pressure_viscosity_temperature=0.02))
        assert np.all(np.isfinite(mu_zh)) and np.all(mu_zh <= max(MU_B, LAMBDA) + 1e-12)
        assert np.all(mu_zh >= 0.0)
        assert np.all(np.isfinite(mu))
        assert np.all(mu <= iso.friction_coefficient * (1 + 1e-9) + 1e-15)
        assert np.all(mu - iso.boundary_friction <= LAMBDA * (1 + 1e-9))
        assert np.all(mu <= max(MU_B, LAMBDA) + 1e-12)
        assert np.all(mu >= iso.boundary_friction - 1e-15)


def test_root_equation_and_temperature_rise() -> None:
    # one node by hand: τ = min(τ₀ asinh(η₀ e^{αp} e^{−βΔT} γ̇/τ₀), Λp) with
    # ΔT = τ V_s (flash + c_f h/(8k)) and α falling as e^(−β_α ΔT)
    p, eta0, alpha, vs, h, flash = 800.0, 0.02, 12.0, 3.0, 0.4, 2.0e-8
    rate = vs / (h * 1e-6)
    tau, dt = thermal_eyring_film_shear(
        pressure=p, viscosity=eta0, pressure_viscosity=alpha, shear_rate_film=rate,
        sliding_velocity=vs, film_thickness=h, flash_factor=flash, eyring_stress=5.0,
        limiting_shear_coefficient=LAMBDA, temperature_viscosity=BETA,
        oil_thermal_conductivity=K_OIL, film_heating=1.0, pressure_viscosity_temperature=BETA_ALPHA)
    tau, dt = float(tau), float(dt)
    expect_dt = tau * 1e6 * vs * (flash + h * 1e-6 / (8 * K_OIL))
    assert dt == pytest.approx(expect_dt, rel=1e-12)
    eta = eta0 * math.exp(alpha * 1e-3 * p * math.exp(-BETA_ALPHA * dt) - BETA * dt)
    rhs = min(5.0 * math.asinh(eta * rate / 5e6), LAMBDA * p)
    assert tau == pytest.approx(rhs, rel=1e-8)
    assert 0 < tau < LAMBDA * p  # heated below the cap (the point is chosen so)


def test_newton_root_matches_scipy_bracketing_solver() -> None:
    # the safeguarded Newton iteration (friction.thermal_eyring._thermal_root) against an
    # independent solver of the same equation: scipy's bracketing elementwise.find_root
    # (Chandrupatla) driven to 1e-15 relative, on 4000 random film nodes of gear flanks
    # (p 0–2 GPa, η₀ 2–200 mPa s, γ̇ 1e4–1e8 1/s, k 0.01–50 K/MPa), capped and heated ones
    # alike. Tolerance 1e-13 relative: both converge to the double-precision root (the
    # Newton solver stops within 16 ulp, 3.6e-15; the reference within its 1e-15 tolerance)
    from scipy.optimize import elementwise

    from friction.thermal_eyring import _thermal_root

    rng = np.random.default_rng(7)
    n, tau0 = 4000, 5.0
    p = rng.uniform(0.0, 2000.0, n)
    number = 10.0 ** rng.uniform(-3.0, 1.0, n)  # η₀γ̇/τ₀
    a_p = 12.0e-3 * p
    k = 10.0 ** rng.uniform(-2.0, 1.7, n)
    cap = LAMBDA * p
    with np.errstate(over="ignore"):
        tau_hi = np.minimum(tau0 * np.arcsinh(number * np.exp(a_p)), cap)

    def g(t, nn, ap, kk, c):
        dt = kk * t
        with np.errstate(over="ignore", under="ignore"):
            arg = nn * np.exp(ap * np.exp(-BETA_ALPHA * dt) - BETA * dt)
        return t - np.minimum(tau0 * np.arcsinh(arg), c)

    ref = elementwise.find_root(g, (np.zeros(n), tau_hi), args=(number, a_p, k, cap),
                                tolerances={"xatol": 1e-300, "xrtol": 1e-15}).x
    got = _thermal_root(tau_hi, number, a_p, k, cap, tau0, BETA, BETA_ALPHA)
    assert np.all(np.isfinite(got))
    np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-300)
    assert np.count_nonzero(got == cap) > 0 and np.count_nonzero(got < cap) > n // 2


def test_mirrored_nodes_equal_the_full_rule() -> None:
    # the model solves half the θ nodes and mirrors them: the same μ as solving all 24
    # (every input of a node depends on cos θ only); tolerance 1e-14 (summation order)
    from friction.mixed_ehl import COS_THETA, W_THETA

    kw = dict(SEGMENT, temperature_viscosity=BETA, oil_thermal_conductivity=K_OIL,
              pressure_viscosity_temperature=BETA_ALPHA, load_sharing=JGP, summits="fixed")
    mu = float(thermal_eyring(**kw))
    sol = mixed_ehl_solution(**SEGMENT)
    w, ph, u, vs = (SEGMENT[k] for k in ("load_per_length", "hertz_pressure",
                                         "entraining_velocity", "sliding_velocity"))
    b = 2 * w / (math.pi * ph)
    gamma1 = 1 / (1 - sol.asperity_load_share)
    flash = _BAND_MEAN * math.sqrt(2 * b * 1e-3) / (
        STEEL_EFFUSIVITY * (math.sqrt(u + vs / 2) + math.sqrt(u - vs / 2)))
    tau, _ = thermal_eyring_film_shear(
        pressure=ph / gamma1 * COS_THETA, viscosity=SEGMENT["viscosity"],
        pressure_viscosity=SEGMENT["pressure_viscosity"],
        shear_rate_film=vs / (sol.film_thickness * 1e-6), sliding_velocity=vs,
        film_thickness=sol.film_thickness, flash_factor=flash, eyring_stress=5.0,
        limiting_shear_coefficient=LAMBDA, temperature_viscosity=BETA,
        oil_thermal_conductivity=K_OIL, film_heating=1.0,
        pressure_viscosity_temperature=BETA_ALPHA)
    full = b * float(np.sum(tau * COS_THETA * W_THETA)) / w + float(sol.boundary_friction)
    assert mu == pytest.approx(full, rel=1e-14)


def test_band_mean_flash_factor_matches_jaeger_integral() -> None:
    # the model's band mean (4/(3√π)) q √(2b)/(B √u) against Jaeger's integral
    # (friction.ehl.thermal.flash_temperature, exact for a flux uniform over each cell)
    # averaged over the band: within 0.5 % (the cells' discretisation, 4000 cells)
    q, b, u, n = 1e8, 2e-4, 5.0, 4000
    dx = 2 * b / n
    dt = flash_temperature(np.full(n, q), dx, u, STEEL_EFFUSIVITY)
    mean = float(np.mean(dt))
    archard = _BAND_MEAN * q * math.sqrt(2 * b) / (STEEL_EFFUSIVITY * math.sqrt(u))
    assert mean == pytest.approx(archard, rel=5e-3)


def test_full_film_friction_falls_with_speed() -> None:
    # the heating the isothermal film lacks: in full film (Rq 0.05 µm, λ ≫ 3) at SR 0.3 the
    # isothermal μ rises from 5 to 20 m/s, the thermal one falls
    kw = dict(SEGMENT, roughness_1=0.05, roughness_2=0.05)
    u = np.array([5.0, 20.0])
    kw.update(entraining_velocity=u, sliding_velocity=0.3 * u)
    iso = np.asarray(mixed_ehl(**kw))
    th = np.asarray(thermal_eyring(**kw, temperature_viscosity=BETA,
                                   oil_thermal_conductivity=K_OIL))
    assert iso[1] > iso[0]
    assert th[1] < th[0]


def test_registered_and_refuses_bad_parameters() -> None:
    mu = friction_coefficient("thermal_eyring", **SEGMENT, temperature_viscosity=BETA,
                              oil_thermal_conductivity=K_OIL)
    assert mu == pytest.approx(thermal_eyring(**SEGMENT, temperature_viscosity=BETA,
                                              oil_thermal_conductivity=K_OIL), rel=1e-12)
    with pytest.raises(InputError, match="film_heating"):
        thermal_eyring(**SEGMENT, film_heating=1.5)
    with pytest.raises(InputError, match="oil_thermal_conductivity"):
        thermal_eyring(**SEGMENT, oil_thermal_conductivity=0.0)


def test_efficiency_stage_passes_the_oils_alpha_slope() -> None:
    # the bundled 75W90 (seed Table 5.2: α 11.4 at 75 °C, 9.7 GPa⁻¹ at 100 °C, log-linear
    # between): −d ln α/dT at 90 °C is ln(11.4/9.7)/25 K exactly
    from friction.efficiency import _alpha_temperature_coefficient
    from friction.lubricant import load_lubricant

    slope = _alpha_temperature_coefficient(load_lubricant("75W90"), 90.0)
    assert slope == pytest.approx(math.log(11.4 / 9.7) / 25.0, rel=1e-9)


# --- Zhou & Hoeprich's load share (load_sharing="zhou_hoeprich") ------------------------


def test_zhou_hoeprich_share_is_the_published_relation() -> None:
    from friction.thermal_eyring import ZHOU_HOEPRICH_CONSTANTS, zhou_hoeprich_share

    # Zhou & Hoeprich (1991) Eq. 29, N_a/N = exp(−B Λ^C), with the constants Wingertszahn
    # et al. (2023) print in their Table 4: B 1.90, C 0.99 (rib, σ 0.24 µm) and B 2.32,
    # C 0.97 (raceway, σ 0.16 µm); exact to round-off (the formula itself)
    assert ZHOU_HOEPRICH_CONSTANTS["rib"][:2] == (1.90, 0.99)
    assert ZHOU_HOEPRICH_CONSTANTS["raceway"][:2] == (2.32, 0.97)
    lam = np.array([0.0, 0.1, 0.5, 1.0, 2.0])
    np.testing.assert_allclose(zhou_hoeprich_share(lam), np.exp(-1.90 * lam**0.99),
                               rtol=1e-14)
    np.testing.assert_allclose(zhou_hoeprich_share(lam, "raceway"),
                               np.exp(-2.32 * lam**0.97), rtol=1e-14)
    assert zhou_hoeprich_share(1.0) == pytest.approx(math.exp(-1.90), rel=1e-14)
    np.testing.assert_allclose(zhou_hoeprich_share(lam, (1.90, 0.99)), zhou_hoeprich_share(lam),
                               rtol=0.0)
    # their Fig. 5 statement: the rougher surface carries asperity load over a wider range
    # of Λ — the rib's (σ 0.24 µm) share above the raceway's (0.16 µm) at every Λ > 0
    grid = np.geomspace(0.01, 3.0, 50)
    assert np.all(zhou_hoeprich_share(grid) > zhou_hoeprich_share(grid, "raceway"))


def test_zhou_hoeprich_share_inside_deterministic_mixed_ehl_range() -> None:
    from friction.thermal_eyring import zhou_hoeprich_share

    # Zhu & Wang, Proc. IMechE J 226 (2012) 1010 (deterministic mixed EHL, abstract): at
    # λ ≈ 0.05–0.1 the film still carries more than 10–15 % of the load, and the mixed
    # regime ends at λ ≈ 0.6–1.2 ("little or no asperity contact"). With both published
    # constant sets: the film carries ≥ 15 % at λ 0.1 and the asperities < 15 % at λ 1.2
    # (Johnson–Greenwood–Poon's share with the ground summits is ≥ 0.97 at λ 0.1 —
    # docs/friction.md — the disagreement this law removes)
    for c in ("rib", "raceway"):
        assert 1.0 - zhou_hoeprich_share(0.1, c) >= 0.15
        assert zhou_hoeprich_share(1.2, c) < 0.15


def test_zhou_hoeprich_option_in_the_model() -> None:
    from friction.thermal_eyring import zhou_hoeprich_share

    u = np.array([0.3, 1.0, 2.5, 10.0])
    kw = dict(SEGMENT, entraining_velocity=u, temperature_viscosity=BETA,
              pressure_viscosity_temperature=BETA_ALPHA)
    h_s = mixed_ehl_solution(**dict(SEGMENT, entraining_velocity=u)).smooth_film_thickness
    share = zhou_hoeprich_share(h_s / math.hypot(0.8, 0.8))
    # no sliding: no film shear, μ is the asperities' μ_b × the share exactly
    np.testing.assert_allclose(
        thermal_eyring(**dict(kw, sliding_velocity=0.0), load_sharing="zhou_hoeprich"),
        MU_B * share, rtol=1e-12)
    # sliding: the film carries 1 − share at p_h/γ₁, so its part is ≤ Λ (1 − share)
    mu = np.asarray(thermal_eyring(**kw, load_sharing="zhou_hoeprich"))
    film = mu - MU_B * share
    assert np.all(film > 0.0) and np.all(film <= LAMBDA * (1.0 - share) * (1 + 1e-12))
    # the share falls as the film grows with speed; summits do not enter
    assert np.all(np.diff(share) < 0.0)
    np.testing.assert_allclose(
        thermal_eyring(**kw, load_sharing="zhou_hoeprich", summits="fixed"), mu, rtol=0.0)
    # it is the model's default load sharing (issue 74: it meets the rows JGP's missed)
    np.testing.assert_allclose(thermal_eyring(**kw), mu, rtol=0.0)


def test_zhou_hoeprich_refuses_bad_parameters() -> None:
    from friction.thermal_eyring import zhou_hoeprich_share

    with pytest.raises(InputError, match="load_sharing"):
        thermal_eyring(**SEGMENT, load_sharing="persson")
    for bad in ("flank", (0.0, 1.0), (1.9, -1.0), (1.9,), "x", (float("nan"), 1.0)):
        with pytest.raises(InputError, match="asperity_load_constants"):
            thermal_eyring(**SEGMENT, load_sharing="zhou_hoeprich",
                           asperity_load_constants=bad)
    with pytest.raises(InputError, match="film_ratio"):
        zhou_hoeprich_share(-0.1)
    with pytest.raises(InputError, match="constants"):
        zhou_hoeprich_share(0.5, (2.0, 0.0))
