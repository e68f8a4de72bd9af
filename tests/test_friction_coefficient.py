"""Tests of friction.coefficient: the registry, Xu et al. 2007, Benedict & Kelley, ISO/TR
14179-2, constant."""

from __future__ import annotations

import csv
import itertools
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from friction.coefficient import (
    STANDARD_INPUTS,
    UNAVAILABLE_MODELS,
    FrictionModelRangeWarning,
    available_friction_models,
    benedict_kelley,
    friction_coefficient,
    friction_model_validity,
    get_friction_model,
    iso_tr_14179_2,
    unavailable_friction_models,
    xu2007,
)
from friction.lubricant import load_lubricant, viscosity
from geometry.core.errors import InputError, ModelUnavailableError

DATA = Path(__file__).parent / "data"

# Xu et al. (2007) check point (seed/NOTES.md): P_h = 1 GPa, SR = 0.5, V_e = 10 m/s,
# ν₀ = 16.3 cP, R = 0.02 m, S = 0.8 µm → μ ≈ 0.029; here in the toolkit's units.
XU_CHECK = dict(
    hertz_pressure=1000.0,
    slide_to_roll=0.5,
    entraining_velocity=10.0,
    viscosity=0.0163,
    radius=20.0,
    roughness_1=0.8,
    roughness_2=0.8,
)

BK_POINT = dict(
    load_per_length=300.0,
    sliding_velocity=2.0,
    entraining_velocity=5.0,
    viscosity=0.02,
    roughness_1=0.4,
    roughness_2=0.4,
)


def _no_warnings():
    ctx = warnings.catch_warnings()
    ctx.__enter__()
    warnings.simplefilter("error")
    return ctx


# ----------------------------------------------------------------------------- registry
def test_registry_lists_models() -> None:
    assert available_friction_models() == ("benedict_kelley", "constant", "iso_tr_14179_2",
                                           "kolivand2009", "mixed_ehl", "thermal_eyring",
                                           "xu2007")
    assert "kolivand2009_table_5_3" in unavailable_friction_models()


def test_unknown_model_lists_available() -> None:
    with pytest.raises(ModelUnavailableError, match="xu2007"):
        friction_coefficient("coulomb", **XU_CHECK)


def test_kolivand2009_table_5_3_unavailable_with_reason() -> None:
    with pytest.raises(ModelUnavailableError, match="not recoverable") as info:
        get_friction_model("kolivand2009_table_5_3")
    assert UNAVAILABLE_MODELS["kolivand2009_table_5_3"] in str(info.value)


def test_unknown_input_name_refused() -> None:
    with pytest.raises(InputError, match="hertz_presure"):
        friction_coefficient("xu2007", **XU_CHECK, hertz_presure=1.0)


def test_missing_input_named() -> None:
    inputs = {k: v for k, v in XU_CHECK.items() if k != "radius"}
    with pytest.raises(InputError, match="radius"):
        friction_coefficient("xu2007", **inputs)


def test_extra_standard_inputs_ignored_and_shape_broadcast() -> None:
    # A pipeline passes every segment quantity to whichever model is named.
    n = 5
    segs = {k: np.full(n, v) for k, v in XU_CHECK.items()}
    segs.update(sliding_velocity=np.full(n, 5.0), load_per_length=np.full(n, 300.0))
    assert set(segs) <= set(STANDARD_INPUTS)
    mu = friction_coefficient("constant", **segs, value=0.07)
    np.testing.assert_array_equal(mu, np.full(n, 0.07))
    mu_xu = friction_coefficient("xu2007", **segs)
    assert np.shape(mu_xu) == (n,)


def test_model_object_reports_inputs() -> None:
    m = get_friction_model("benedict_kelley")
    assert "sliding_velocity" in m.required
    assert m(**BK_POINT) == pytest.approx(benedict_kelley(**BK_POINT))


# ----------------------------------------------------------------------------- xu2007
def test_xu2007_check_value() -> None:
    # NOTES.md quotes μ ≈ 0.029 (2 significant digits): tolerance ±0.0005, half a unit
    # in the last quoted digit.
    mu = friction_coefficient("xu2007", **XU_CHECK)
    assert abs(mu - 0.029) <= 0.0005


def test_xu2007_rises_with_slide_to_roll_at_low_sr() -> None:
    # Xu et al. (2007): in the low-SR (near-linear traction) region μ grows with |SR|.
    sr = np.linspace(0.025, 0.3, 12)
    mu = np.asarray(xu2007(**{**XU_CHECK, "slide_to_roll": sr}))
    assert np.all(np.diff(mu) > 0)
    # sign of SR does not matter
    assert xu2007(**{**XU_CHECK, "slide_to_roll": -0.2}) == xu2007(
        **{**XU_CHECK, "slide_to_roll": 0.2}
    )


def test_xu2007_falls_with_entraining_speed() -> None:
    # Full-film EHL: a faster entraining speed thickens the film and lowers μ (Xu 2007,
    # exponent b6 < 0).
    ve = np.linspace(1.0, 20.0, 12)
    mu = np.asarray(xu2007(**{**XU_CHECK, "entraining_velocity": ve}))
    assert np.all(np.diff(mu) < 0)


# The seed's R_eq (35–50 mm) reaches past the fitted 5–40 mm: the range warning is expected.
@pytest.mark.filterwarnings("ignore::friction.coefficient.FrictionModelRangeWarning")
def test_xu2007_magnitude_at_seed_operating_point() -> None:
    # Seed Fig. 5.10 (Design A, 1500 rpm, 500 N m, 90 °C, S = 0.8 µm): μ = 0.01–0.06,
    # from a regression built by Xu et al.'s method for 75W90. At the mid-face
    # conditions of Figs. 5.4–5.8 (p_h 800 MPa, V_r 2 m/s, SR 0.45, R_eq 42.5 mm) Xu's
    # own regression must land in that range; over the interior of the figures' ranges
    # it may deviate by the factor 2 that separates independent regressions.
    with open(DATA / "kolivand2009_fig5_design_A_ranges.csv", encoding="utf-8") as fh:
        rows = csv.DictReader(line for line in fh if not line.startswith("#"))
        ranges = {r["quantity"]: (float(r["low"]), float(r["high"])) for r in rows}
    mu_lo, mu_hi = ranges["friction_coefficient"]
    eta = viscosity(load_lubricant("75W90"), 90.0)
    base = dict(viscosity=eta, roughness_1=0.8, roughness_2=0.8)
    mid = xu2007(
        hertz_pressure=800.0, slide_to_roll=0.45, entraining_velocity=2.0, radius=42.5, **base
    )
    assert mu_lo <= mid <= mu_hi
    for ph, sr, vr, r in itertools.product([600.0, 1000.0], [0.1, 0.8], [1.0, 3.5], [35.0, 50.0]):
        mu = xu2007(hertz_pressure=ph, slide_to_roll=sr, entraining_velocity=vr, radius=r, **base)
        assert mu_lo / 2 <= mu <= mu_hi * 2


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("hertz_pressure", 3000.0),
        ("slide_to_roll", 1.5),
        ("entraining_velocity", 30.0),
        ("viscosity", 0.5),
        ("radius", 2.0),
        ("roughness_1", 2.0),
    ],
)
def test_xu2007_warns_outside_range(field: str, value: float) -> None:
    name = "roughness" if field.startswith("roughness") else field
    with pytest.warns(FrictionModelRangeWarning, match=name):
        mu = xu2007(**{**XU_CHECK, field: value})
    assert math.isfinite(mu)


def test_xu2007_silent_inside_range() -> None:
    ctx = _no_warnings()
    try:
        xu2007(**XU_CHECK)
    finally:
        ctx.__exit__(None, None, None)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("hertz_pressure", -1.0),
        ("entraining_velocity", 0.0),
        ("viscosity", float("nan")),
        ("radius", -20.0),
        ("roughness_2", -0.1),
        ("slide_to_roll", float("inf")),
    ],
)
def test_xu2007_bad_input_names_field(field: str, value: float) -> None:
    with pytest.raises(InputError, match=field):
        xu2007(**{**XU_CHECK, field: value})


# ----------------------------------------------------------------------------- B&K
def test_benedict_kelley_in_published_units() -> None:
    # Independent route: the formula evaluated by hand in its published US customary units
    # (W′ lbf/in, ν₀ cP, V in in/s, S µin), then the same point converted to the toolkit
    # units with the exact definitions 1 in = 25.4 mm, 1 lbf = 4.4482216152605 N.
    w_lbf_in, nu_cp, vs_in, vt_in, s_uin = 2000.0, 15.0, 60.0, 400.0, 16.0
    expected = 0.0127 * 50.0 / (50.0 - s_uin) * math.log10(
        3.17e8 * w_lbf_in / (nu_cp * vs_in * vt_in**2)
    )
    rq_um = s_uin * 0.0254 / math.sqrt(2.0 / math.pi)  # Ra → Rq (Gaussian), both surfaces
    mu = benedict_kelley(
        load_per_length=w_lbf_in * 4.4482216152605 / 25.4,
        sliding_velocity=vs_in * 0.0254,
        entraining_velocity=vt_in * 0.0254 / 2.0,
        viscosity=nu_cp * 1e-3,
        roughness_1=rq_um,
        roughness_2=rq_um,
    )
    assert mu == pytest.approx(expected, rel=1e-12)


def test_benedict_kelley_trends() -> None:
    # Benedict & Kelley (1961) abstract: μ increases with load and decreases with sum
    # velocity, sliding velocity and oil viscosity.
    base = benedict_kelley(**BK_POINT)
    assert benedict_kelley(**{**BK_POINT, "load_per_length": 600.0}) > base
    assert benedict_kelley(**{**BK_POINT, "entraining_velocity": 10.0}) < base
    assert benedict_kelley(**{**BK_POINT, "sliding_velocity": 4.0}) < base
    assert benedict_kelley(**{**BK_POINT, "viscosity": 0.04}) < base
    assert benedict_kelley(**{**BK_POINT, "roughness_1": 0.8, "roughness_2": 0.8}) > base


def test_benedict_kelley_pure_rolling_warns_and_is_zero() -> None:
    with pytest.warns(FrictionModelRangeWarning, match="pure rolling"):
        mu = benedict_kelley(**{**BK_POINT, "sliding_velocity": np.array([0.0, 2.0])})
    assert mu[0] == 0.0
    assert mu[1] == pytest.approx(benedict_kelley(**BK_POINT))


def test_benedict_kelley_low_argument_clipped() -> None:
    with pytest.warns(FrictionModelRangeWarning, match="clipped"):
        mu = benedict_kelley(
            **{**BK_POINT, "sliding_velocity": 50.0, "entraining_velocity": 80.0, "viscosity": 5.0}
        )
    assert mu == 0.0


def test_benedict_kelley_roughness_limit() -> None:
    with pytest.raises(InputError, match="roughness_1, roughness_2"):
        benedict_kelley(**{**BK_POINT, "roughness_1": 2.0, "roughness_2": 2.0})


# ----------------------------------------------------------------------------- constant
# ----------------------------------------------------------------------------- ISO/TR 14179-2
_RQ_OF_RA_05 = 0.5 / math.sqrt(2.0 / math.pi)  # the Rq whose Gaussian Ra is 0.5 µm


def test_iso_tr_14179_2_worked_value() -> None:
    # the standard's formula in its own units, written out by hand: w 300 N/mm,
    # v_Σ 3 m/s, ρ 10 mm, η 13.6 mPa s, Ra 0.5 µm, mineral oil; the only tolerance is
    # round-off (the model converts u_e → v_Σ, Pa s → mPa s and Rq → Ra exactly)
    expected = 0.048 * (300.0 / (3.0 * 10.0)) ** 0.2 * 13.6**-0.05 * 0.5**0.25
    assert expected == pytest.approx(0.05614, abs=1e-5)
    mu = friction_coefficient("iso_tr_14179_2", load_per_length=300.0, entraining_velocity=1.5,
                              radius=10.0, viscosity=0.0136, roughness_1=_RQ_OF_RA_05,
                              roughness_2=_RQ_OF_RA_05)
    assert mu == pytest.approx(expected, rel=1e-12)


def test_iso_tr_14179_2_exponents_and_oil_factor() -> None:
    # the published exponents as ratios: load ×2 → ×2^0.2, speed ×2 → ×2^−0.2, Ra ×4 → ×√2,
    # viscosity ×2 → ×2^−0.05; X_L multiplies (0.8 for a polyalphaolefin)
    base = dict(load_per_length=300.0, entraining_velocity=1.5, radius=10.0, viscosity=0.0136,
                roughness_1=0.2, roughness_2=0.2)
    mu0 = iso_tr_14179_2(**base)
    assert iso_tr_14179_2(**{**base, "load_per_length": 600.0}) / mu0 == pytest.approx(2**0.2)
    assert iso_tr_14179_2(**{**base, "entraining_velocity": 3.0}) / mu0 == pytest.approx(2**-0.2)
    assert iso_tr_14179_2(**{**base, "roughness_1": 0.8, "roughness_2": 0.8}) / mu0 == \
        pytest.approx(4**0.25)
    assert iso_tr_14179_2(**{**base, "viscosity": 0.0272}) / mu0 == pytest.approx(2**-0.05)
    assert iso_tr_14179_2(**base, base_oil_factor=0.8) / mu0 == pytest.approx(0.8)


def test_iso_tr_14179_2_warns_outside_range_and_names_bad_input() -> None:
    base = dict(load_per_length=300.0, radius=10.0, viscosity=0.0136, roughness_1=0.5,
                roughness_2=0.5)
    with pytest.warns(FrictionModelRangeWarning, match="sum_velocity"):
        iso_tr_14179_2(entraining_velocity=0.05, **base)
    with pytest.raises(InputError, match="load_per_length"):
        iso_tr_14179_2(entraining_velocity=1.5, **{**base, "load_per_length": -1.0})
    assert not friction_model_validity("iso_tr_14179_2", entraining_velocity=0.05, **base)
    assert friction_model_validity("iso_tr_14179_2", entraining_velocity=1.5, **base)


def test_constant_default_is_coleman_value() -> None:
    assert friction_coefficient("constant") == 0.05
    with pytest.raises(InputError, match="value"):
        friction_coefficient("constant", value=1.5)


# ----------------------------------------------------------------------------- never NaN
@settings(max_examples=150, deadline=None)
@given(
    ph=st.floats(0.0, 5000.0),
    sr=st.floats(-3.0, 3.0),
    ve=st.floats(1e-3, 100.0),
    eta=st.floats(1e-4, 10.0),
    r=st.floats(0.5, 500.0),
    s=st.floats(0.0, 3.0),
    vs=st.floats(0.0, 50.0),
    w=st.floats(1e-2, 1e4),
)
def test_models_never_return_nan(ph, sr, ve, eta, r, s, vs, w) -> None:
    # Property: any accepted input gives a finite μ ≥ 0 (warnings allowed, NaN never).
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        mu = xu2007(
            hertz_pressure=ph,
            slide_to_roll=sr,
            entraining_velocity=ve,
            viscosity=eta,
            radius=r,
            roughness_1=s,
            roughness_2=s,
        )
        assert math.isfinite(mu) and mu >= 0
        s_bk = min(s, 1.0)  # B&K refuses mean Ra ≥ 50 µin (tested above)
        mu = benedict_kelley(
            load_per_length=w,
            sliding_velocity=vs,
            entraining_velocity=ve,
            viscosity=eta,
            roughness_1=s_bk,
            roughness_2=s_bk,
        )
        assert math.isfinite(mu) and mu >= 0
