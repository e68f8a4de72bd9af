"""The fitted ``kolivand2009`` friction model against the committed friction study.

The data are the committed study files (``friction/data/friction_study_75W90*.nc``: 2048
Sobol points, seed 2009, in two files of 1024 (``--skip 1024``), of the gear-contact box
(``GEAR_CONTACT_RANGE``: p_h 0.3–3 GPa, R 5–150 mm, u_e 0.05–20 m/s, |SR| 0.01–2, 25–110 °C,
Rq 0.05–1.5 µm each), and 200 held-out Latin-hypercube points, seed 7, solved by the
stochastic mixed-EHL solver of :mod:`friction.ehl.stochastic` at 512 nodes with Barus
viscosity and the flash temperature) and the coefficient file fitted to them
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
from friction.lubricant import load_lubricant, pressure_viscosity_coefficient, viscosity
from friction.study.design import GEAR_CONTACT_RANGE, TABLE_5_1_RANGE
from friction.study.fit import (
    combine_studies,
    fit_kolivand2009,
    fit_statistics,
    study_inputs,
    write_fit,
)
from friction.validity import FrictionModelRangeWarning
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf

#: the Sobol design's points 0-1023 and its continuation 1024-2047 (``--skip 1024``)
TRAIN = (DATA_DIR / "friction_study_75W90.nc", DATA_DIR / "friction_study_75W90_skip1024.nc")
HELD = DATA_DIR / "friction_study_75W90_heldout.nc"

#: a gear-like contact inside the fitted box (1500 rpm, ~300 N·m class segment at 75 °C)
REF = dict(hertz_pressure=1200.0, slide_to_roll=0.3, entraining_velocity=5.0,
           viscosity=0.0208, pressure_viscosity=11.4, radius=20.0, roughness_1=0.5,
           roughness_2=0.5)


@pytest.fixture(scope="module")
def train():
    return combine_studies([read_netcdf(f, tree=False) for f in TRAIN])


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
    """Held-out points (LHS, seed 7, never in the fit): the issue's target, RMS relative
    error ≤ 10 %, met over the whole widened gear box — measured 9.0 % (median |error|
    4.2 %), worst +86 % (p_h 1.5 GPa, |SR| 1.83, u_e 11.8 m/s, λ 1.74: the box's hot
    corner, where the flash temperature of the film's shear heat is largest and the
    regression's flash group ``ln_1+flash`` follows the solver's thermal film only in the
    mean). The file's statistics are those of the committed data (to 1e-9). Bounds: the
    target, and the worst case with ~10 % slack for the optimiser's platform round-off."""
    s = fit_statistics(fit, held)
    assert s["points"] == 200
    assert s["rms_relative_error"] <= 0.10
    assert s["max_relative_error"] <= 0.95
    for k in ("points", "rms_relative_error", "max_relative_error"):
        assert s[k] == pytest.approx(fit.statistics[f"heldout_{k}"], rel=1e-9), k


def _inside_table_5_1(d):
    inside = np.ones(d["friction_coefficient"].size, bool)
    for name, (lo, hi, _) in TABLE_5_1_RANGE.items():
        if name in d:
            inside &= (d[name] >= lo) & (d[name] <= hi)
    return inside


def test_fit_inside_the_seeds_box_is_closer(fit, train, held):
    """Inside Table 5.1's box (the seed's: p_h ≥ 500 MPa, R ≤ 40 mm, u_e ≥ 1 m/s, SR ≥
    0.025) the fit is closer to the solver than over the gear box: RMS 7.1 % over the 115
    training points there and 6.6 % over the 10 held-out ones (bounds 8 and 8 %; 9.4 and
    9.0 % over the whole box); the large errors are the gear box's hot, high-slip corner."""
    for study, bound, least in ((train, 0.08, 100), (held, 0.08, 8)):
        d = study_inputs(study)
        inside = _inside_table_5_1(d)
        assert inside.sum() >= least
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            mu = kolivand2009(**{k: v[inside] for k, v in _inputs(d).items()},
                              coefficients=fit)
        rel = mu / d["friction_coefficient"][inside] - 1.0
        assert np.sqrt(np.mean(rel**2)) <= bound


def test_eyring_structure_beats_the_power_laws(fit, train, held):
    """The shipped ``eyring`` structure (the smooth film's Eyring traction corrected by the
    regression) against the ``split`` and ``regimes`` power laws refitted on the same
    points: held-out RMS 9.0 % against 17.1 % and 22.3 % (measured; asserted: ≤ 0.6 × each)."""
    ours = fit_statistics(fit, held)["rms_relative_error"]
    for structure in ("split", "regimes"):
        other = fit_kolivand2009(train, structure=structure, box=GEAR_CONTACT_RANGE)
        assert ours <= 0.6 * fit_statistics(other, held)["rms_relative_error"], structure


def test_refit_reproduces_the_bundled_coefficients(fit, train, held):
    """The committed coefficients are the fit of the committed data over the design's box.
    Compared by what they predict: the optimum is flat along some directions, so another
    platform's round-off moves coefficients more than μ (measured: the data perturbed by
    1e-11 relative moved coefficients by 3e-6 and μ by 9e-8). Tolerances: μ at every
    training and held-out point 1e-6 relative; coefficients 1e-4; the ranges of the
    inputs 1e-9 relative (min and max of derived inputs — λ, viscosity — computed through
    NumPy's vectorised exp/log, whose SIMD paths differ by a few ulp between CPUs: an
    AVX-512 machine moved them by ~2e-13)."""
    again = fit_kolivand2009(train, heldout=held, box=GEAR_CONTACT_RANGE)
    for study in (train, held):
        d = study_inputs(study)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            np.testing.assert_allclose(kolivand2009(**_inputs(d), coefficients=again),
                                       kolivand2009(**_inputs(d), coefficients=fit),
                                       rtol=1e-6)
    np.testing.assert_allclose(np.asarray(again.coefficients), np.asarray(fit.coefficients),
                               rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(again.boundary, fit.boundary, rtol=1e-4, atol=1e-6)
    assert again.ranges.keys() == fit.ranges.keys()
    for key, bounds in fit.ranges.items():
        np.testing.assert_allclose(again.ranges[key], bounds, rtol=1e-9, err_msg=key)


def test_continuous_at_lambda_1_and_3(fit):
    """μ just below and at λ = 1 and 3 over 500 random points of the box differ by less
    than 0.5 % (the continuity rows; the file states the training points' maximum)."""
    rng = np.random.default_rng(1)
    oil = load_lubricant("75W90")
    t = rng.uniform(25.0, 110.0, 500)
    g = contact_groups(hertz_pressure=rng.uniform(300.0, 3000.0, 500),
                       slide_to_roll=np.exp(rng.uniform(np.log(0.01), np.log(2.0), 500)),
                       entraining_velocity=np.exp(rng.uniform(np.log(0.05), np.log(20.0), 500)),
                       viscosity=viscosity(oil, t),
                       pressure_viscosity=pressure_viscosity_coefficient(oil, t),
                       radius=np.exp(rng.uniform(np.log(5.0), np.log(150.0), 500)),
                       roughness_1=rng.uniform(0.05, 1.5, 500),
                       roughness_2=rng.uniform(0.05, 1.5, 500))
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


def test_limits_boundary_and_film(fit, train):
    """The asperity share ψ follows the solver's asperity load ratio: it falls with λ
    (Spearman ρ with the solver's ratio over the training points 0.99 measured; ≥ 0.95),
    reaches the boundary regime where the solver does (ψ up to 0.995, the solver's ratio
    up to 0.9999 at the box's thinnest films) and is < 1 % above λ = 3, where the
    solver's asperities carry < 0.03 % of the load: 0.68 at λ 0.09, 3e-5 at λ 5.6."""
    d = study_inputs(train)
    psi = fit.asperity_share(contact_groups(**_inputs(d)))
    assert spearmanr(psi, d["asperity_load_ratio"]).statistic >= 0.95
    assert np.max(psi) >= 0.95
    low = dict(REF, entraining_velocity=4.0, viscosity=0.0107, pressure_viscosity=9.7,
               roughness_1=1.0, roughness_2=1.0, hertz_pressure=2000.0, radius=10.0)
    high = dict(REF, entraining_velocity=15.0, roughness_1=0.1, roughness_2=0.1)
    g_low, g_high = contact_groups(**low), contact_groups(**high)
    assert fit.ranges["lambda"][0] < g_low["lambda"] < 0.15 and g_high["lambda"] > 3.0
    assert fit.asperity_share(g_low) > 0.5 > 100 * fit.asperity_share(g_high)
    assert fit.asperity_share(g_high) < 0.01


# ----------------------------------------------------------------------------- trends
def test_trends_of_the_solver_data(train):
    """From the committed solver points (converged), with their size: ln μ regressed on
    ln p_h, ln R, ln u_e, ln SR, T and ln σ (σ = √(Rq₁² + Rq₂²)). Measured over the gear
    box: rougher flanks raise μ (σ^0.30), a faster contact lowers it (u_e^−0.15), a hotter
    oil raises it (ln μ +0.42 per 100 °C: the thinner film hands load to the asperities'
    μ_b), and μ falls weakly with p_h (p_h^−0.24: the asperities' share of the load at a
    given λ falls as the Hertz pressure grows) and SR (SR^−0.04: the flash temperature
    thins the film's shear) — the seed's trends in kind (chapter 5: μ rising with
    roughness and oil temperature, falling with speed): most of the box is mixed, where
    the asperities carry the friction (docs/friction.md). The bounds pin these sizes. The
    asperity load share grows as λ falls (Spearman ρ −0.72; ≤ −0.6): median 0.75 below
    λ = 0.3, 0.38 at 0.3–1, < 0.1 % above λ = 3."""
    ok = train["status"].values == 0
    d = train.isel(point=ok)
    mu = d["friction_coefficient"].values
    sigma = np.hypot(d["roughness_1"].values, d["roughness_2"].values)
    x = np.column_stack([np.ones(mu.size), np.log(d["hertz_pressure"].values),
                         np.log(d["radius"].values), np.log(d["entraining_velocity"].values),
                         np.log(d["slide_to_roll"].values), d["temperature"].values / 100.0,
                         np.log(sigma)])
    b, *_ = np.linalg.lstsq(x, np.log(mu), rcond=None)
    assert -0.35 <= b[1] <= -0.15       # Hertz pressure
    assert -0.1 <= b[4] <= 0.0          # slide-to-roll ratio
    assert 0.3 <= b[5] <= 0.55          # temperature: hotter oil, higher μ
    assert 0.2 <= b[6] <= 0.4           # roughness: rougher, higher μ
    assert -0.25 <= b[3] <= -0.1        # speed: faster, lower μ
    alr, lam = d["asperity_load_ratio"].values, d["lambda_ratio"].values
    assert spearmanr(alr, lam).statistic <= -0.6
    assert np.median(alr[lam < 0.3]) > 0.6 > np.median(alr[(lam >= 0.3) & (lam < 1.0)]) > 0.2
    assert np.max(alr[lam > 3.0]) < 1e-3


def test_trends_of_the_fitted_model(fit):
    """The model at a gear-like contact (REF, λ 0.53) follows the solver's trends: Rq
    0.2 → 0.8 µm each raises μ 2.3× (0.030 → 0.069; bounds 1.8–2.8×), u_e 2 → 15 m/s
    lowers it by 57 % (0.072 → 0.031; bounds 0.35–0.55×) and it falls monotonically over
    0.1–15 m/s; a hotter oil (η₀ and α of 75W90 at 40 → 90 °C) raises it at Rq 0.5 µm
    (0.037 → 0.064) and 1.0 µm (0.050 → 0.080) — the asperities take the thinner film's
    load — and leaves it within 2 % at 0.2 µm, where the film still carries most of it
    (λ 3.8 → 0.9): the seed's Fig. 5.12 in kind."""
    rq = kolivand2009(**{**REF, "roughness_1": np.array([0.2, 0.8]),
                         "roughness_2": np.array([0.2, 0.8])})
    assert 1.8 < rq[1] / rq[0] < 2.8
    ue = kolivand2009(**{**REF, "entraining_velocity": np.array([0.1, 0.5, 1.0, 2.0, 5.0,
                                                                   15.0])})
    assert 0.35 < ue[-1] / ue[3] < 0.55
    assert np.all(np.diff(ue) < 0.0)
    oil = load_lubricant("75W90")
    for rq, rise in ((0.2, (0.98, 1.02)), (0.5, (1.4, 2.0)), (1.0, (1.3, 1.9))):
        cold, hot = (kolivand2009(**dict(REF, viscosity=viscosity(oil, t), roughness_1=rq,
                                         roughness_2=rq,
                                         pressure_viscosity=pressure_viscosity_coefficient(
                                             oil, t)))
                     for t in (40.0, 90.0))
        assert rise[0] < hot / cold < rise[1], rq


# ----------------------------------------------------------------------------- registry
def test_registered_with_validity_and_range_warning(fit):
    mu = friction_coefficient("kolivand2009", **REF, e_prime=226373.6, load_per_length=500.0)
    assert mu == pytest.approx(kolivand2009(**REF))
    assert 0.005 < mu < 0.1
    assert friction_model_validity("kolivand2009", **REF).all()
    out = dict(REF, hertz_pressure=np.array([1200.0, 3500.0]))  # the box ends at 3 GPa
    with pytest.warns(FrictionModelRangeWarning, match="hertz_pressure outside the fitted"):
        mu2 = friction_coefficient("kolivand2009", **out)
    assert friction_model_validity("kolivand2009", **out).tolist() == [True, False]
    # outside the box the regression is held at the box's edge, ψ and μ_E follow the
    # inputs: (μ − μ_bψ)/((1 − ψ)μ_E) at 3.5 GPa, with ψ and μ_E there, equals that at
    # the edge, 3 GPa (round-off)
    hi = fit.ranges["hertz_pressure"][1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        edge = dict(REF, hertz_pressure=hi)
        mu_edge = kolivand2009(**edge)
    g_edge, g_out = contact_groups(**edge), contact_groups(**dict(REF, hertz_pressure=3500.0))
    psi_edge, psi_out = fit.asperity_share(g_edge), fit.asperity_share(g_out)
    assert psi_out != pytest.approx(psi_edge, rel=1e-6)
    film_edge = ((mu_edge - fit.boundary_friction * psi_edge)
                 / ((1.0 - psi_edge) * fit.film_traction(g_edge)))
    film_out = ((mu2[1] - fit.boundary_friction * psi_out)
                / ((1.0 - psi_out) * fit.film_traction(g_out)))
    assert film_out == pytest.approx(film_edge, rel=1e-12)
    assert fit.film_traction(g_out) > fit.film_traction(g_edge)


def test_extrapolation_checked_against_the_solver(fit):
    """64 solver conditions just outside the box (``friction_study_75W90_outside.nc``,
    ``benchmarks/friction_extrapolation.py``: 16 per slab, p_h 3–4.5 GPa, SR 0.001–0.01,
    u_e 0.01–0.05 m/s, R 150–500 mm, the rest in the gear box): every one is flagged, and
    the model's RMS relative error per slab is 10.5 / 5.9 / 11.7 / 10.3 % (worst +21 / +11
    / +33 / −23 %; all 64 converged) — bounds 13 / 8 / 14 / 13 %."""
    study = read_netcdf(DATA_DIR / "friction_study_75W90_outside.nc", tree=False)
    d = study_inputs(study)
    points = study["point"].values[(study["status"].values == 0)
                                   & (study["friction_coefficient"].values > 0)]
    assert points.size == 64
    assert not friction_model_validity("kolivand2009", **_inputs(d)).any()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        rel = kolivand2009(**_inputs(d), coefficients=fit) / d["friction_coefficient"] - 1.0
    for k, bound in enumerate((0.13, 0.08, 0.14, 0.13)):
        m = (points >= 16 * k) & (points < 16 * (k + 1))
        assert np.sqrt(np.mean(rel[m] ** 2)) <= bound, k


def _sliding_loss_error(mu, study, d, mask=None):
    """Σ|μ − μ_solver|·w / Σμ_solver·w over a study's converged points (``d``:
    :func:`study_inputs`; ``mask`` a subset of them), w = w′·|SR|·u_e the sliding power per
    unit μ: the relative error of the sliding loss those contacts would make."""
    ok = (study["status"].values == 0) & (study["friction_coefficient"].values > 0)
    w = (study["load_per_length"].values[ok] * np.abs(d["slide_to_roll"])
         * d["entraining_velocity"])
    m = np.ones(w.size, bool) if mask is None else mask
    solver = d["friction_coefficient"]
    return np.sum(np.abs(mu - solver)[m] * w[m]) / np.sum(solver[m] * w[m])


def test_flank_shell_checked_against_the_solver(fit):
    """The gear flanks' contacts outside the box — the contact curves' light-load ends (p_h
    100–300 MPa) and the pitch line (|SR| 1e-4–0.01), R_eq down to 4 mm — solved by the
    study's solver (``friction_study_75W90_flank.nc``: 200 Sobol conditions, seed 2010, of
    the shell between the gear box and ``GEAR_FLANK_RANGE``, all converged; never in the
    fit): every one is flagged, and μ's error weighted by the sliding power per unit μ,
    w′·|SR|·u_e (the error of the sliding loss these contacts would make) is 20 % over
    all, 36 % at the light-load ends, 6.3 % at the pitch line; the median relative errors
    are 2.0 % and 4.5 %. The light-load ends' weighted error is one full-film condition's
    (p_h 297 MPa, |SR| 1.89, u_e 18 m/s, λ 5.3: +57 %, 12 of the 20 points — the hot
    corner of the held-out test). Bounds 25 / 45 / 8 %; xu2007 on the same conditions:
    90 % (it ignores the film's physics at low slip): asserted ≤ half of it."""
    study = read_netcdf(DATA_DIR / "friction_study_75W90_flank.nc", tree=False)
    ok = (study["status"].values == 0) & (study["friction_coefficient"].values > 0)
    assert ok.sum() == 200
    d = study_inputs(study)
    assert not friction_model_validity("kolivand2009", **_inputs(d)).any()
    sr, ph, ue = (np.abs(d["slide_to_roll"]), d["hertz_pressure"],
                  d["entraining_velocity"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        mu = kolivand2009(**_inputs(d), coefficients=fit)
        xu = friction_coefficient(
            "xu2007", **_inputs(d), sliding_velocity=sr * ue,
            load_per_length=study["load_per_length"].values[ok], e_prime=226373.6)
    assert _sliding_loss_error(mu, study, d) <= 0.25
    assert _sliding_loss_error(mu, study, d) <= 0.5 * _sliding_loss_error(xu, study, d)
    assert _sliding_loss_error(mu, study, d, (ph < 300.0) & (sr >= 0.01)) <= 0.45
    assert _sliding_loss_error(mu, study, d, (sr < 0.01) & (ph >= 300.0)) <= 0.08


def test_edge_contacts_checked_against_the_solver(fit):
    """A rounded tooth edge on the mating flank — the LTCA's edge segments: R_eq ≈ the edge
    radius, p_h to the 5.3 GPa shakedown limit, λ down to 0.01 — solved by the study's
    solver (``friction_study_75W90_edge.nc``: 100 LHS conditions, seed 11, of
    ``GEAR_EDGE_RANGE``, R 0.3–1 mm, p_h 0.5–5.3 GPa, u_e 0.3–5 m/s, SR 0.2–2; never in
    the fit): every one is flagged, and the error of the sliding loss (weighted by
    w′·|SR|·u_e) is 7.8 %, median relative error 7.0 % (the solver's asperities carry
    23–99.98 % of an edge's load, the fitted share follows them); xu2007 on the same
    conditions: 62 %; all 100 converged. Bounds 12 % and a fifth of xu2007's."""
    study = read_netcdf(DATA_DIR / "friction_study_75W90_edge.nc", tree=False)
    ok = (study["status"].values == 0) & (study["friction_coefficient"].values > 0)
    assert ok.sum() == 100
    d = study_inputs(study)
    assert not friction_model_validity("kolivand2009", **_inputs(d)).any()
    sr, ue = np.abs(d["slide_to_roll"]), d["entraining_velocity"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        mu = kolivand2009(**_inputs(d), coefficients=fit)
        xu = friction_coefficient(
            "xu2007", **_inputs(d), sliding_velocity=sr * ue,
            load_per_length=study["load_per_length"].values[ok], e_prime=226373.6)
    assert _sliding_loss_error(mu, study, d) <= 0.12
    assert _sliding_loss_error(mu, study, d) <= 0.2 * _sliding_loss_error(xu, study, d)


@pytest.mark.parametrize("name", ["default", "kolivand2009_table54_A_fh",
                                  "kolivand2009_table54_B_fh"])
def test_gear_contacts_inside_the_range_or_flagged_with_why(name, request):
    """The default model on the default case's run (``ltca run``'s LTCA: 50/250/500 N·m,
    Table 3.1 mounting) and on Table 5.4's A and B at the seed's operating point (500 N·m;
    the suite's 6-roll LTCA), all at 1500 rpm, 90 °C, Rq 0.8 µm: every loaded segment is
    inside the fitted box or flagged, and the flag says why — a flank segment only at the
    contact curve's light-load end (p_h < 300 MPa), at the pitch line (|SR| < 0.01) or at
    R_eq 4–5 mm (the shell checked against the solver above), the edge segments (a rounded
    tooth edge on the mating flank, R_eq ≈ the edge radius, p_h to 5.3 GPa) as edges; the
    run's summary names both with their share of the load. Measured: flagged flank segments
    carry 1.29 % (default), 1.39 % (A) and 1.52 % (B) of the load; xu2007 flags 5.2–11.0 %
    of it. Bound 2 %."""
    import json

    from test_face_hobbing_chain import _run as _fh_run

    from friction.efficiency import efficiency_analysis, extrapolation_summary

    if name == "default":
        # the session's one default run (tests/conftest.py), only when this case asks
        lt = read_netcdf(request.getfixturevalue("default_run_file"), tree=True)["ltca"]
        lt = lt.to_dataset()
    else:
        lt = _fh_run(name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        fr = efficiency_analysis(lt, pinion_speed=1500.0, temperature=90.0, roughness=0.8,
                                 friction_model="kolivand2009")  # not the default since issue 61
    assert fr.attrs["friction_model"] == "kolivand2009"
    force = lt["force"].values
    loaded = np.isfinite(force) & (force > 0)
    edge = np.broadcast_to((lt["segment_kind"] != "curve").values, force.shape)
    flag = fr["friction_model_extrapolated"].values == 1
    assert np.isfinite(fr["friction_coefficient"].values[loaded]).all()
    flank = flag & loaded & ~edge
    ph = lt["pressure_max"].values
    sr = fr["slide_to_roll_total"].values
    radius = np.broadcast_to(lt["equivalent_radius"].values, force.shape)
    assert ((ph < 300.0) | (sr < 0.01) | (radius < 5.0))[flank].all()
    assert force[flank].sum() / force[loaded].sum() <= 0.02
    parts = json.loads(fr.attrs["model_range_by_contact"])
    assert parts["flank"]["extrapolated"] == int(flank.sum())
    assert parts["edge"]["extrapolated"] == int((flag & loaded & edge).sum())
    assert parts["edge"]["spans"]["radius"][1] < 1.0
    text = extrapolation_summary(fr)
    assert "on the flanks" in text and "on the edges" in text


def test_outside_the_box_the_film_traction_extrapolates(fit):
    """μ is continuous where the inputs leave the fitted box (p_h 3 GPa, R 150 mm, u_e
    0.05 m/s, SR 0.01; jump < 1e-3 across ±0.01 %), and toward pure rolling the film's
    part vanishes with μ_E, leaving the asperities' boundary share: μ(SR = 0) = μ_b ψ
    (1e-9), below μ at the box's SR 0.01 (measured 0.040 against 0.052 at REF, λ 0.53,
    where the asperities carry 40 % of the load) — where holding μ at the box's edge, as
    the power-law structures do, would keep the film's shear of SR = 0.01 at any slip."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        for name, edge in (("hertz_pressure", 3000.0), ("radius", 150.0),
                           ("entraining_velocity", 0.05), ("slide_to_roll", 0.01)):
            mu = kolivand2009(**dict(REF, **{name: edge * np.array([0.9999, 1.0001])}))
            assert abs(mu[1] / mu[0] - 1.0) < 1e-3, name
        slip = kolivand2009(**dict(REF, slide_to_roll=np.array([0.0, 0.01])))
    g = contact_groups(**dict(REF, slide_to_roll=0.01))
    assert slip[0] == pytest.approx(fit.boundary_friction * fit.asperity_share(g), rel=1e-9)
    assert slip[0] < 0.85 * slip[1]


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


# ----------------------------------------------------------------------------- a gear's contacts
def test_gear_segments_inside_the_range_or_flagged_with_the_reason():
    """The efficiency stage on the suite's default-case LTCA (60 and 240 N·m, 1500 rpm,
    90 °C, Rq 0.8 µm, new flanks): every loaded segment has a finite μ, the flagged ones are those
    outside the fitted box, the ``model_range_warnings`` attribute names every input
    concerned, and the gear box covers more of this gear's contacts than xu2007's range.
    Measured: 39 % flagged (R below 5 mm at 290 of 836 loaded segments, p_h above 3 GPa
    at 208 — edge contacts —, the total slide-to-roll ratio |V_s|/V_r outside 0.01–2 at
    232, λ below 0.0038 at 10); xu2007 over the same segments: 59 %. The bound pins the
    measured share."""
    import json

    from test_ltca import _run  # the suite's default-case LTCA (cached per session)

    from friction.efficiency import efficiency_analysis
    from friction.operating import OperatingConditions

    lt = _run()
    flagged = {}
    for model in ("kolivand2009", "xu2007"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            # new flanks (issue 61: run in, Rq × 0.68, the λ of these segments stays above
            # the range's 0.0038 and only the other three inputs are named)
            fr = efficiency_analysis(lt, OperatingConditions(surface_state="new"),
                                     friction_model=model)
        force = lt["force"].values
        loaded = np.isfinite(force) & (force > 0)
        flag = fr["friction_model_extrapolated"].values
        flagged[model] = flag[loaded].mean()
        if model == "kolivand2009":
            why = " ".join(json.loads(fr.attrs["model_range_warnings"]))
            for name in ("lambda", "radius", "hertz_pressure", "slide_to_roll"):
                assert f"kolivand2009: {name} outside" in why, name
            assert np.isfinite(fr["friction_coefficient"].values[loaded]).all()
    assert 0.3 <= flagged["kolivand2009"] <= 0.45
    assert flagged["kolivand2009"] < flagged["xu2007"]


def test_run_warning_says_where_the_model_extrapolated(capsys):
    """``ltca run``'s warning (``contact.commands.run.print_extrapolation_warning``) on the
    suite's hypoid-example LTCA: one line of at most 100 characters (issue 61) with the
    flagged flank segments and their share of the load, the edge contacts after them (the
    counts of ``model_range_by_contact``, which add up to the ``/friction`` flag's); a
    dataset without flags, or with only edge contacts carrying < 1 % of the load, prints
    nothing."""
    import json

    from test_ltca import _run

    from contact.commands.run import print_extrapolation_warning
    from friction.efficiency import efficiency_analysis, extrapolated_segments

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        fr = efficiency_analysis(_run())
    flagged, loaded = extrapolated_segments(fr)
    assert 0 < flagged < loaded
    parts = json.loads(fr.attrs["model_range_by_contact"])
    n_flank, n_edge = parts["flank"]["extrapolated"], parts["edge"]["extrapolated"]
    assert n_flank + n_edge == flagged
    print_extrapolation_warning(fr)
    printed = capsys.readouterr().out
    assert len(printed.splitlines()) == 1 and len(printed.rstrip("\n")) <= 100
    # the default model's name (thermal_eyring since issue 74), as the dataset records it
    model = fr.attrs["friction_model"]
    assert printed.startswith(f"WARNING: {model} extrapolated: {n_flank} flank segments")
    assert f"{parts['flank']['load_share']:.2%} of load" in printed
    assert f"{n_edge} edge contacts" in printed
    print_extrapolation_warning(fr.assign(friction_model_extrapolated=0
                                          * fr["friction_model_extrapolated"]))
    assert capsys.readouterr().out == ""
    edges_only = {"flank": {**parts["flank"], "extrapolated": 0},
                  "edge": {**parts["edge"], "load_share": 0.005}}
    print_extrapolation_warning(fr.assign_attrs(model_range_by_contact=json.dumps(edges_only)))
    assert capsys.readouterr().out == ""
