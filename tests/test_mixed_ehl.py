"""The mixed-EHL friction model (friction.mixed_ehl): published values, limits, continuity.

Independent references: the published curve fit F_{5/2}(h) ≈ 4.4086e-5 (4 − h)^6.804 of
Hu et al. (1994) to the Greenwood–Tripp integral; the closed forms F_0 = 1 − Φ(h),
F_1 = φ(h) − h(1 − Φ(h)) of the Gaussian; the Eyring law's Newtonian and logarithmic
asymptotes; the JGP film scaling h ∝ γ₁^0.13 from the Dowson–Toyoda exponents; the
limits μ → μ_b (λ → 0) and μ → film shear (λ ≫ 3) that the load-sharing construction
implies; the monotonic trends of Johnson, Greenwood & Poon (1972) (the asperity share
falls with the film parameter and rises with roughness).
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
import warnings
from importlib import resources

import numpy as np
import pytest
from scipy import integrate, stats
from test_ltca import _run  # the same LTCA result (cached per session)

from friction.coefficient import (
    FrictionModelRangeWarning,
    friction_coefficient,
    friction_model_validity,
)
from friction.efficiency import efficiency_analysis, extrapolated_segments
from friction.film import dowson_toyoda_central
from friction.mixed_ehl import (
    MIXED_EHL_DEFAULTS,
    asperity_pressure,
    eyring_shear_stress,
    greenwood_tripp_integral,
    mixed_ehl,
    mixed_ehl_solution,
)
from geometry.core.errors import InputError

#: A flank segment of the seed's Table 5.4 pairs at 1500 rpm, 500 N·m, 90 °C (75W90).
SEGMENT = dict(
    load_per_length=300.0,
    hertz_pressure=1000.0,
    radius=40.0,
    e_prime=2.26e5,
    entraining_velocity=2.5,
    sliding_velocity=1.5,
    viscosity=0.0135,
    pressure_viscosity=10.3,
    roughness_1=0.8,
    roughness_2=0.8,
)
#: A lightly loaded contact (p̄ = 118 MPa) whose asperities can carry the whole load
#: (K E′ F_{5/2}(0) ≈ 170 MPa with the default roughness parameters).
# mean pressure π/4 · 60 = 47 MPa, below the scheme's asperity capacity K′E′F_{5/2}(0) ≈ 83 MPa
LIGHT = dict(SEGMENT, load_per_length=10.0, hertz_pressure=60.0)
MU_B = MIXED_EHL_DEFAULTS["boundary_friction"][0]


# ----------------------------------------------------------------------------- F_n
def test_greenwood_tripp_matches_hu_fit() -> None:
    # Hu et al. (1994)'s fit 4.4086e-5 (4 − h)^6.804 approximates the integral where the
    # asperities carry load (0 ≤ h ≲ 2): there it is within 12.1 % of the exact value
    # (12.0 % at h = 0, 10.1 % at h = 2, ~1 % near h = 1) — the fit's own accuracy
    h = np.linspace(0.0, 2.0, 21)
    fit = 4.4086e-5 * (4.0 - h) ** 6.804
    np.testing.assert_allclose(greenwood_tripp_integral(2.5, h), fit, rtol=0.121)


def test_greenwood_tripp_gaussian_identities() -> None:
    h = np.linspace(-3.0, 6.0, 37)
    tail = stats.norm.sf(h)
    np.testing.assert_allclose(greenwood_tripp_integral(0.0, h), tail, rtol=1e-10)
    np.testing.assert_allclose(greenwood_tripp_integral(1.0, h), stats.norm.pdf(h) - h * tail,
                               rtol=1e-9)
    # F_n(0) = 2^((n−1)/2) Γ((n+1)/2) / √(2π) and quadrature at a few points
    for n in (1.5, 2.5):
        closed = 2 ** ((n - 1) / 2) * math.gamma((n + 1) / 2) / math.sqrt(2 * math.pi)
        assert greenwood_tripp_integral(n, 0.0) == pytest.approx(closed, rel=1e-12)
        for x in (-1.0, 0.7, 2.3):
            quad, _ = integrate.quad(lambda s, x=x, n=n: (s - x) ** n * stats.norm.pdf(s), x,
                                     np.inf)
            assert greenwood_tripp_integral(n, x) == pytest.approx(quad, rel=1e-8)


def test_asperity_pressure_scales() -> None:
    # p_a = (8√2/15) π (ηβσ)² √(σ/β) E′ F_{5/2} with E′ = 2E* (the summit-pair sum is
    # derived in tests/test_ehl_solver.py::test_greenwood_tripp_constant_from_summit_pairs)
    k = 8 * math.sqrt(2) / 15 * math.pi * 0.05**2 * math.sqrt(0.01)
    assert asperity_pressure(1.0, 2.26e5, asperity_density_radius_sigma=0.05,
                             sigma_over_beta=0.01) == pytest.approx(
        k * 2.26e5 * greenwood_tripp_integral(2.5, 1.0), rel=1e-12)


# ----------------------------------------------------------------------------- Eyring
def test_eyring_asymptotes() -> None:
    # Newtonian for η γ̇ ≪ τ₀ (error ~ (ηγ̇/τ₀)²/6 = 2e-9 here)
    assert eyring_shear_stress(0.01, 100.0, 5.0) == pytest.approx(0.01 * 100.0 * 1e-6, rel=1e-8)
    # τ₀ ln(2x) for x = η γ̇/τ₀ ≫ 1: asinh x − ln 2x = 1/(4x²) + O(x⁻⁴); x = 2e4 here, so
    # the relative difference is 6.25e-10 / ln(4e4) ≈ 5.9e-11
    eta, rate, tau0 = 1e4, 1e7, 5.0
    x = eta * rate / (tau0 * 1e6)
    assert eyring_shear_stress(eta, rate, tau0) == pytest.approx(tau0 * math.log(2 * x),
                                                                 rel=1e-10)


# ----------------------------------------------------------------------------- film
def test_jgp_film_scaling() -> None:
    # JGP: the film carries w′/γ₁ at modulus E′/γ₁, so h_c ∝ γ₁^(0.69 − 0.56) (Dowson–Toyoda)
    args = (2.5, 0.0135, 10.3)
    h1 = dowson_toyoda_central(*args, 300.0, 40.0, 2.26e5)
    for g in (1.5, 4.0, 30.0):
        hg = dowson_toyoda_central(*args, 300.0 / g, 40.0, 2.26e5 / g)
        assert hg == pytest.approx(h1 * g**0.13, rel=1e-12)


# ----------------------------------------------------------------------------- limits
def test_boundary_limit_lambda_to_zero() -> None:
    # λ → 0 by slowing the entraining motion (h ∝ u^0.69): the asperities take the load
    # (1/γ₂ → 1) and μ → μ_b; below λ ≈ 0.01 the film's share of the load is < 1e-4
    u = np.array([10.0, 1.0, 0.1, 1e-2, 1e-4, 1e-6])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)  # u < 0.1 m/s flagged
        sol = mixed_ehl_solution(**dict(LIGHT, entraining_velocity=u))
    lam_s = sol.smooth_film_thickness / math.hypot(0.8, 0.8)  # the smooth-surface λ
    assert np.all(np.diff(lam_s) < 0) and lam_s[-1] < 1e-4
    assert np.all(np.diff(np.abs(sol.friction_coefficient - MU_B)) <= 0)
    assert np.all(np.diff(sol.asperity_load_share) >= 0)
    assert sol.asperity_load_share[0] < 0.2 and sol.asperity_load_share[-1] > 1 - 1e-4
    assert sol.friction_coefficient[-1] == pytest.approx(MU_B, abs=1e-4 * MU_B + 1e-5)


def test_heavy_load_asperities_take_the_load_as_the_film_closes() -> None:
    # issue 61: at gear pressures the share was capped at p_a(0)/p̄ (the mean-plane
    # separation held at the film's h_c ≥ 0); with the separation of the film's mean gap
    # (Patir & Cheng) it goes negative as the film closes, and the asperities take the load:
    # μ → μ_b, far above the old cap
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        sol = mixed_ehl_solution(**dict(SEGMENT, entraining_velocity=1e-6))
        mu = mixed_ehl(**dict(SEGMENT, entraining_velocity=1e-6))
    cap = float(asperity_pressure(0.0, SEGMENT["e_prime"])) / (math.pi / 4 * 1000.0)
    assert float(sol.asperity_load_share) > 0.999 > 5 * cap
    assert float(mu) == pytest.approx(0.1, rel=1e-3)   # μ_b of the 75W90 file


def test_separation_of_mean_gap_inverts_the_gaussian_mean_gap() -> None:
    # identity: t Φ(t) + φ(t) (flow_factors.mean_gap) at the returned t gives the mean gap
    # back to round-off, from a closing film (1e-8 σ: t ≈ −5.3) to a thick one (t ≈ h_T/σ)
    from friction.ehl.flow_factors import mean_gap
    from friction.mixed_ehl import separation_of_mean_gap

    g = np.array([1e-8, 1e-3, 0.05, 0.2, 0.399, 0.5, 1.0, 3.0, 10.0])
    t = separation_of_mean_gap(g)
    np.testing.assert_allclose(mean_gap(t)[0], g, rtol=1e-12)
    assert t[0] < -5.0 and t[-1] == pytest.approx(10.0, rel=1e-12)
    assert np.all(np.diff(t) > 0)


def test_full_film_limit() -> None:
    # λ ≫ 3: F_{5/2}(λ) < 1e-12, no asperity load, μ is the film shear alone
    fast = dict(SEGMENT, entraining_velocity=40.0, roughness_1=0.05, roughness_2=0.05)
    sol = mixed_ehl_solution(**fast)
    assert float(sol.lambda_central) > 20
    assert float(sol.asperity_load_share) == 0.0
    mu0 = mixed_ehl(**fast, boundary_friction=0.0)
    assert float(sol.friction_coefficient) == pytest.approx(float(mu0), rel=1e-14)
    # and the film shear is the Eyring integral over the Hertz profile (adaptive quadrature)
    w, ph = fast["load_per_length"], fast["hertz_pressure"]
    b = 2 * w / (math.pi * ph)
    h = float(sol.film_thickness) * 1e-6
    tau0, lam = 5.0, 0.08

    def tau(x: float) -> float:
        p = ph * math.sqrt(max(0.0, 1 - (x / b) ** 2))
        eta = fast["viscosity"] * math.exp(fast["pressure_viscosity"] * 1e-3 * p)
        return min(tau0 * math.asinh(eta * fast["sliding_velocity"] / h / (tau0 * 1e6)),
                   lam * p)

    ref, _ = integrate.quad(tau, -b, b, limit=200, epsabs=0, epsrel=1e-9)
    # the model's 24-node Gauss rule meets a kink where the limiting shear takes over:
    # agreement to 2e-5 relative (a 0.002 % error on μ)
    assert float(sol.friction_coefficient) == pytest.approx(ref / w, rel=2e-5)


def test_continuous_in_lambda() -> None:
    # sweep the smooth-surface λ through boundary, mixed and full film (< 0.01 … > 10) in
    # fine steps of ln u:
    # μ has no jump anywhere (in particular not at λ = 1 or 3, where the seed's
    # regression switches formula); |Δμ| per step ≤ 5e-4 with steps of 0.5 % in u
    u = np.geomspace(1e-6, 300.0, 4000)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        sol = mixed_ehl_solution(**dict(LIGHT, entraining_velocity=u))
    lam = sol.smooth_film_thickness / math.hypot(0.8, 0.8)  # the smooth-surface λ
    assert lam.min() < 0.01 and lam.max() > 10
    assert np.all(np.isfinite(sol.friction_coefficient))
    assert np.max(np.abs(np.diff(sol.friction_coefficient))) < 5e-4
    assert np.max(np.abs(np.diff(sol.asperity_load_share))) < 5e-3


def test_monotonic_as_the_source_says() -> None:
    # JGP: the asperity share falls as the film parameter grows (faster rolling) and
    # rises with roughness; Eyring: film shear rises with sliding speed
    u = np.geomspace(0.05, 50.0, 60)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        by_speed = mixed_ehl_solution(**dict(SEGMENT, entraining_velocity=u))
    share = by_speed.asperity_load_share
    assert np.all(np.diff(share[share > 0]) < 0)
    rq = np.linspace(0.1, 1.5, 30)
    by_rough = mixed_ehl_solution(**dict(SEGMENT, roughness_1=rq, roughness_2=rq))
    assert np.all(np.diff(by_rough.asperity_load_share) >= 0)
    assert np.all(np.diff(by_rough.friction_coefficient) > 0)
    vs = np.linspace(0.05, 5.0, 30)
    by_slide = mixed_ehl_solution(**dict(SEGMENT, sliding_velocity=vs))
    assert np.all(np.diff(by_slide.film_friction) > 0)


# ----------------------------------------------------------------------------- registry
def test_registry_and_validity_flag() -> None:
    mu = friction_coefficient("mixed_ehl", **SEGMENT, slide_to_roll=0.6, temperature=90.0)
    assert mu == pytest.approx(float(mixed_ehl(**SEGMENT)), rel=1e-14)
    assert 0.01 < mu < 0.06  # the seed's μ band on the flanks (Fig. 5.10)
    ph = np.array([800.0, 3000.0])
    with pytest.warns(FrictionModelRangeWarning, match="hertz_pressure outside"):
        friction_coefficient("mixed_ehl", **dict(SEGMENT, hertz_pressure=ph))
    ok = friction_model_validity("mixed_ehl", **dict(SEGMENT, hertz_pressure=ph))
    np.testing.assert_array_equal(ok, [True, False])
    with pytest.raises(InputError, match="roughness_1, roughness_2"):
        mixed_ehl(**dict(SEGMENT, roughness_1=0.0, roughness_2=0.0))
    with pytest.raises(InputError, match="boundary_friction"):
        mixed_ehl(**SEGMENT, boundary_friction=1.5)


def test_efficiency_stage_with_mixed_ehl() -> None:
    lt = _run()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        fr = efficiency_analysis(lt, friction_model="mixed_ehl")
    F = lt["force"].values
    loaded = np.isfinite(F) & (F > 0)
    mu, vs = fr["friction_coefficient"].values, fr["sliding_velocity"].values
    np.testing.assert_allclose(fr["sliding_loss"].values[loaded], (mu * F * vs)[loaded],
                               rtol=1e-12)
    eff = fr["efficiency_mean"].values
    assert np.all((eff > 0.96) & (eff < 0.995))  # seed ch. 5 band
    flag = fr["friction_model_extrapolated"]
    assert flag.dtype == np.int8 and flag.attrs["flag_meanings"] == "no yes"
    assert flag.attrs["units"] == "1" and "validity" in flag.attrs["long_name"]
    assert set(np.unique(flag.values[~loaded])) <= {0}
    # the flag marks exactly the loaded segments the model's range check rejects
    ph = lt["pressure_max"].values[loaded]
    np.testing.assert_array_equal(flag.values[loaded] == 1,
                                  (ph > 2500.0) | (fr["rolling_velocity"].values[loaded] < 0.1))


# ----------------------------------------------------------------------------- μ_b of the oil
def _oil_file(tmp_path, name: str, boundary_friction: str) -> str:
    """The bundled 75W90 oil file with its ``boundary_friction = 0.1`` line replaced (a
    number or a ``[boundary_friction]`` table, written at the end)."""
    text = resources.files("friction").joinpath("data", "75W90.toml").read_text("utf-8")
    text, n = re.subn(r"(?m)^boundary_friction = 0\.1$", "", text)
    assert n == 1
    if boundary_friction.startswith("["):
        text += "\n" + boundary_friction
    else:
        text = f"boundary_friction = {boundary_friction}\n" + text
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return str(path)


#: A measured table (docs/friction.md's example) and its value at the run's 90 °C inlet.
MU_B_TABLE = ("[boundary_friction]\ntemperature = [40.0, 80.0, 120.0]\n"
              "value = [0.11, 0.12, 0.13]\nsource = \"MTM, a test\"\n")
MU_B_AT_90 = float(np.interp(90.0, [40.0, 80.0, 120.0], [0.11, 0.12, 0.13]))


@pytest.fixture(scope="module")
def small_ltca():
    return _run()


def test_oil_table_gives_the_constant_oil_result_at_its_inlet_value(small_ltca, tmp_path):
    """Identity: an oil whose μ_b table reads x at the inlet temperature (0.1225 at 90 °C,
    by hand a quarter of the way from 0.12 to 0.13) gives exactly the μ, losses and
    efficiency of the same oil with the constant x — μ_b is evaluated at the inlet
    temperature, nothing else changes — and the dataset records the μ_b used."""
    assert MU_B_AT_90 == pytest.approx(0.1225, rel=1e-14)
    table = _oil_file(tmp_path, "table", MU_B_TABLE)
    const = _oil_file(tmp_path, "const", repr(MU_B_AT_90))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        a = efficiency_analysis(small_ltca, lubricant=table, friction_model="mixed_ehl")
        b = efficiency_analysis(small_ltca, lubricant=const, friction_model="mixed_ehl")
        base = efficiency_analysis(small_ltca, friction_model="mixed_ehl")
    for name in ("friction_coefficient", "sliding_loss", "efficiency", "efficiency_mean",
                 "friction_model_extrapolated"):
        np.testing.assert_array_equal(a[name].values, b[name].values)
    assert a.attrs["model_range_warnings"] == b.attrs["model_range_warnings"]
    assert a.attrs["boundary_friction"] == MU_B_AT_90 == b.attrs["boundary_friction"]
    assert "table" in a.attrs["boundary_friction_source"]
    assert "MTM, a test" in a.attrs["boundary_friction_source"]
    assert "constant" in b.attrs["boundary_friction_source"]
    # the bundled oil: its constant 0.1 and its source recorded; a larger μ_b costs efficiency
    assert base.attrs["boundary_friction"] == 0.1
    assert "0.08-0.13" in base.attrs["boundary_friction_source"]
    assert np.all(a["efficiency_mean"].values < base["efficiency_mean"].values)


def test_oil_temperature_outside_the_table_is_flagged(small_ltca, tmp_path):
    """Inlet 130 °C, above the table's 120 °C: μ_b held at 0.13 (the constant-0.13 oil's
    μ exactly), every loaded segment flagged, the range warning saying why; a model that
    takes no μ_b (kolivand2009) is neither flagged for it nor records one."""
    table = _oil_file(tmp_path, "table", MU_B_TABLE)
    const = _oil_file(tmp_path, "const", "0.13")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        hot = efficiency_analysis(small_ltca, lubricant=table, temperature=130.0,
                                  friction_model="mixed_ehl")
        ref = efficiency_analysis(small_ltca, lubricant=const, temperature=130.0,
                                  friction_model="mixed_ehl")
        k09 = efficiency_analysis(small_ltca, lubricant=table, temperature=130.0,
                                  friction_model="kolivand2009")
        k09_const = efficiency_analysis(small_ltca, lubricant=const, temperature=130.0,
                                        friction_model="kolivand2009")
    np.testing.assert_array_equal(hot["friction_coefficient"].values,
                                  ref["friction_coefficient"].values)
    assert hot.attrs["boundary_friction"] == 0.13
    loaded = hot["friction_coefficient"].notnull().values
    assert np.all(hot["friction_model_extrapolated"].values[loaded] == 1)
    assert not np.all(ref["friction_model_extrapolated"].values[loaded] == 1)
    notes = json.loads(hot.attrs["model_range_warnings"])
    assert any("boundary_friction measured at 40-120 degC" in n and "130 degC" in n
               for n in notes)
    assert extrapolated_segments(hot)[0] == int(loaded.sum())
    np.testing.assert_array_equal(k09["friction_model_extrapolated"].values,
                                  k09_const["friction_model_extrapolated"].values)
    assert "boundary_friction" not in k09.attrs
    assert not any("boundary_friction" in n for n in json.loads(k09.attrs["model_range_warnings"]))


def test_line_contact_takes_the_oil_table_at_its_inlet_temperature(tmp_path):
    """The line-contact solvers' μ_b (``ltca ehl``, the friction study): the oil's at the
    condition's inlet temperature, the condition's own where given; recorded in the
    solution's attributes."""
    from friction.ehl.line_contact import (
        Grid,
        LineContactCondition,
        condition_attrs,
        condition_boundary_friction,
        contact_setup,
    )

    table = _oil_file(tmp_path, "table", MU_B_TABLE)
    cond = LineContactCondition(load_per_length=300.0, radius=20.0, entraining_velocity=2.0,
                                slide_to_roll=0.3, temperature=60.0, lubricant=table)
    assert condition_boundary_friction(cond) == pytest.approx(0.115, rel=1e-14)
    assert contact_setup(cond, Grid()).mu_b == condition_boundary_friction(cond)
    assert condition_attrs(cond)["boundary_friction"] == condition_boundary_friction(cond)
    own = dataclasses.replace(cond, boundary_friction=0.05)
    assert condition_boundary_friction(own) == 0.05
    with pytest.warns(FrictionModelRangeWarning, match="held at the end value"):
        assert condition_boundary_friction(dataclasses.replace(cond, temperature=20.0)) == 0.11
    with pytest.raises(InputError, match="boundary_friction"):
        condition_boundary_friction(dataclasses.replace(cond, boundary_friction=2.0))
