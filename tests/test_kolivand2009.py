"""The fitted ``kolivand2009`` friction model against the committed friction study.

The data are the committed study files (``friction/data/friction_study_75W90*.nc``: a
Sobol design of Table 5.1's box and held-out Latin-hypercube points of another seed,
solved by :mod:`friction.ehl`) and the coefficient file fitted to them
(``friction/data/kolivand2009_75W90.toml``). Every test reads these small files and
evaluates closed-form expressions (the refit: one ``least_squares`` of ~40 unknowns over a
few hundred points, ~1–2 s): cheap enough for CI.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.stats import spearmanr

from friction.coefficient import friction_coefficient, friction_model_validity
from friction.kolivand2009 import (
    DATA_DIR,
    Kolivand2009Fit,
    contact_groups,
    kolivand2009,
    load_kolivand2009_fit,
)
from friction.study.fit import (
    fit_kolivand2009,
    fit_statistics,
    study_inputs,
    write_fit,
)
from friction.validity import FrictionModelRangeWarning
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf

TRAIN = DATA_DIR / "friction_study_75W90.nc"
HELD = DATA_DIR / "friction_study_75W90_heldout.nc"

#: a gear-like contact inside the fitted box (1500 rpm, ~300 N·m class segment at 75 °C)
REF = dict(hertz_pressure=1200.0, slide_to_roll=0.3, entraining_velocity=5.0,
           viscosity=0.0208, pressure_viscosity=11.4, radius=20.0, roughness_1=0.5,
           roughness_2=0.5)


@pytest.fixture(scope="module")
def train():
    return read_netcdf(TRAIN, tree=False)


@pytest.fixture(scope="module")
def held():
    return read_netcdf(HELD, tree=False)


@pytest.fixture(scope="module")
def fit():
    return load_kolivand2009_fit("75W90")


def _inputs(d):
    keys = ("hertz_pressure", "slide_to_roll", "entraining_velocity", "viscosity",
            "pressure_viscosity", "radius", "roughness_1", "roughness_2")
    return {k: d[k] for k in keys}


# ----------------------------------------------------------------------------- the fit
def test_fit_against_held_out_solver_points(fit, held):
    """Held-out points (LHS, seed 34, never in the fit): RMS relative error and worst case
    as measured when the file was fitted (stated in docs/friction.md), and the file's
    statistics are those of the committed data (to 1e-9).

    The issue's target (RMS ≤ 10 %) is NOT met: the steady solver's μ in the mixed regime
    depends on the roughness realisation by about as much (two profile pairs: 53 % RMS at
    λ 1–3), which no regression of the seed's groups can follow. The bounds pin the
    measured values (a worse fit fails)."""
    s = fit_statistics(fit, held)
    assert s["points"] >= 50
    assert s["rms_relative_error"] <= 0.36
    assert s["max_relative_error"] <= 1.3
    for k in ("points", "rms_relative_error", "max_relative_error"):
        assert s[k] == pytest.approx(fit.statistics[f"heldout_{k}"], rel=1e-9), k


def test_full_film_regime_fits_better_than_the_noise_of_the_mixed_one(fit, train, held):
    """Where the realisation does not matter (λ ≥ 3: no asperity contact; 4 % RMS between
    profile pairs) the fit is closer to the solver: RMS ≤ 16 % over the training points
    (measured 13.9 %) and median |error| ≤ 15 % over the held-out ones (measured
    10.0 %; their worst, +123 %, is a low-pressure, low-slip point of the Newtonian
    corner, μ ≈ 0.002, where the power law is least apt)."""
    for study, stat, bound in ((train, "rms", 0.16), (held, "median", 0.15)):
        d = study_inputs(study)
        full = d["lambda_ratio"] >= 3.0
        assert full.sum() >= 5
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            mu = kolivand2009(**{k: v[full] for k, v in _inputs(d).items()},
                              coefficients=fit)
        rel = mu / d["friction_coefficient"][full] - 1.0
        value = np.sqrt(np.mean(rel**2)) if stat == "rms" else np.median(np.abs(rel))
        assert value <= bound, (stat, value)


def test_refit_reproduces_the_bundled_coefficients(fit, train, held):
    """The committed coefficients are the fit of the committed data (least squares is
    deterministic: 1e-6 relative covers the optimiser's stopping tolerance)."""
    again = fit_kolivand2009(train, heldout=held)
    np.testing.assert_allclose(np.asarray(again.coefficients), np.asarray(fit.coefficients),
                               rtol=1e-6, atol=1e-8)
    np.testing.assert_allclose(again.boundary, fit.boundary, rtol=1e-6, atol=1e-8)


def test_continuous_at_lambda_1_and_3(fit):
    """μ just below and at λ = 1 and 3 over 500 random points of the box differ by less
    than 0.5 % (the continuity rows; the file states the training points' maximum)."""
    rng = np.random.default_rng(1)
    g = {"SR": rng.uniform(0.025, 1.0, 500), "U": np.exp(rng.uniform(-28, -22, 500)),
         "G": rng.uniform(2200, 4100, 500), "H": rng.uniform(0.0022, 0.011, 500),
         "Seq/Sc": rng.uniform(0.1, 0.35, 500), "Sc/R": rng.uniform(1e-5, 1e-4, 500)}
    for at in fit.lambda_bounds:
        below = fit.mu({**g, "lambda": np.full(500, np.nextafter(at, 0.0))})
        above = fit.mu({**g, "lambda": np.full(500, at)})
        assert np.max(np.abs(above / below - 1.0)) < 5e-3
    assert max(fit.statistics["continuity_jump_lambda_1"],
               fit.statistics["continuity_jump_lambda_3"]) < 5e-3


def test_lambda_is_the_solvers(train):
    """The model's λ (Pan–Hamrock h_min/σ from the inputs) equals the solver's λ at every
    committed point (the same formula: 1e-12)."""
    d = study_inputs(train)
    lam = contact_groups(**_inputs(d))["lambda"]
    np.testing.assert_allclose(lam, d["lambda_ratio"], rtol=1e-12)


def test_limits_boundary_and_film(fit):
    """The split's asperity share follows the solver: ψ > 0.9 at the smallest fitted λ
    (μ → μ_b), ψ < 1 % at λ ≥ 3 (film shear only)."""
    low = dict(REF, entraining_velocity=4.0, viscosity=0.0107, pressure_viscosity=9.7,
               roughness_1=1.0, roughness_2=1.0, hertz_pressure=2000.0, radius=10.0)
    g = contact_groups(**low)
    assert fit.ranges["lambda"][0] < g["lambda"] < 0.15
    assert fit.asperity_share(g) > 0.9
    # μ_b plus a thin film's shear on the few fluid nodes (the solver: 0.0999–0.1000)
    assert kolivand2009(**low) == pytest.approx(fit.boundary_friction, rel=0.05)
    high = dict(REF, entraining_velocity=15.0, roughness_1=0.1, roughness_2=0.1)
    g = contact_groups(**high)
    assert g["lambda"] > 3.0 and fit.asperity_share(g) < 0.01


# ----------------------------------------------------------------------------- trends
def test_trends_of_the_solver_data(train):
    """From the committed solver points (converged), with their size: ln μ regressed on
    ln p_h, ln R, ln u_e, ln SR, T and ln σ (σ = √(Rq₁² + Rq₂²)) — μ rises with roughness
    (exponent 0.81 measured; ≥ 0.5) and falls with speed at fixed load (−0.54; ≤ −0.3);
    the asperity load share grows as λ falls (Spearman ρ −0.89; ≤ −0.8): median ≥ 0.9 below
    λ = 0.3, none above λ = 1."""
    ok = train["status"].values == 0
    d = train.isel(point=ok)
    mu = d["friction_coefficient"].values
    sigma = np.hypot(d["roughness_1"].values, d["roughness_2"].values)
    x = np.column_stack([np.ones(mu.size), np.log(d["hertz_pressure"].values),
                         np.log(d["radius"].values), np.log(d["entraining_velocity"].values),
                         np.log(d["slide_to_roll"].values), d["temperature"].values / 100.0,
                         np.log(sigma)])
    b, *_ = np.linalg.lstsq(x, np.log(mu), rcond=None)
    assert b[6] >= 0.5          # roughness
    assert b[3] <= -0.3         # speed
    alr, lam = d["asperity_load_ratio"].values, d["lambda_ratio"].values
    assert spearmanr(alr, lam).statistic <= -0.8
    assert np.median(alr[lam < 0.3]) >= 0.9
    assert np.median(alr[lam > 1.0]) == 0.0


def test_trends_of_the_fitted_model(fit):
    """The model at a gear-like contact: μ rises with roughness (Rq 0.2 → 0.8 µm each: at
    least +50 %) and falls with speed at fixed load (u_e 2 → 15 m/s: at least −30 %)."""
    rq = kolivand2009(**{**REF, "roughness_1": np.array([0.2, 0.8]),
                         "roughness_2": np.array([0.2, 0.8])})
    assert rq[1] >= 1.5 * rq[0]
    ue = kolivand2009(**{**REF, "entraining_velocity": np.array([2.0, 15.0])})
    assert ue[1] <= 0.7 * ue[0]


# ----------------------------------------------------------------------------- registry
def test_registered_with_validity_and_range_warning(fit):
    mu = friction_coefficient("kolivand2009", **REF, e_prime=226373.6, load_per_length=500.0)
    assert mu == pytest.approx(kolivand2009(**REF))
    assert 0.005 < mu < 0.1
    assert friction_model_validity("kolivand2009", **REF).all()
    out = dict(REF, hertz_pressure=np.array([1200.0, 3000.0]))
    with pytest.warns(FrictionModelRangeWarning, match="hertz_pressure outside the fitted"):
        mu2 = friction_coefficient("kolivand2009", **out)
    assert friction_model_validity("kolivand2009", **out).tolist() == [True, False]
    hi = fit.ranges["hertz_pressure"][1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        assert mu2[1] == pytest.approx(kolivand2009(**dict(REF, hertz_pressure=hi)))


def test_coefficient_file_round_trip(fit, tmp_path):
    path = write_fit(fit, tmp_path / "k.toml")
    again = load_kolivand2009_fit(path)
    assert again.coefficients == fit.coefficients and again.boundary == fit.boundary
    assert again.ranges == fit.ranges and again.structure == fit.structure
    assert kolivand2009(**REF, coefficients=str(path)) == kolivand2009(**REF)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"hertz_pressure": -1.0}, r"^hertz_pressure: must be finite and > 0"),
    ({"roughness_1": 0.0}, r"^roughness_1: must be"),
    ({"viscosity": np.nan}, r"^viscosity: must be"),
    ({"coefficients": "ISO-VG-9999"}, r"^coefficients: no bundled kolivand2009 fit"),
    ({"coefficients": "/no/such/file.toml"}, r"no such file"),
])
def test_bad_input_named(kwargs, match):
    with pytest.raises(InputError, match=match):
        kolivand2009(**{**REF, **kwargs})


def test_malformed_coefficients_named(fit, tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text('schema = "hypoid-ltca kolivand2009 fit 1"\nlubricant = "x"\n',
                 encoding="utf-8")
    with pytest.raises(InputError, match="missing or malformed field"):
        load_kolivand2009_fit(p)
    with pytest.raises(InputError, match=r"^coefficients: must be 3 regimes"):
        Kolivand2009Fit(fit.lubricant, fit.features, fit.lambda_bounds,
                        fit.coefficients[:2], fit.ranges, {}, {})  # type: ignore[arg-type]
    with pytest.raises(InputError, match=r"^structure: must be one of"):
        Kolivand2009Fit(fit.lubricant, fit.features, fit.lambda_bounds, fit.coefficients,
                        fit.ranges, {}, {}, structure="cubic")
