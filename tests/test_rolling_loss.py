"""Tests of friction.rolling: Goksem–Hargreaves rolling traction (seed Eq. 5.10) and its loss."""

from __future__ import annotations

import math

import numpy as np
import pytest

from friction.coefficient import FrictionModelRangeWarning
from friction.film import thermal_loading, thermal_reduction_factor
from friction.lubricant import (
    load_lubricant,
    pressure_viscosity_coefficient,
    temperature_viscosity_coefficient,
    thermal_conductivity,
    viscosity,
)
from friction.rolling import rolling_power_loss, rolling_traction, rolling_traction_isothermal
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.hertz import hertz_line_contact

E_PRIME = 206000.0 / (1 - 0.3**2)  # steel/steel, E′ = E/(1 − ν²) [MPa] (assumed material)

POINT = dict(
    entraining_velocity=5.0,
    viscosity=0.0136,
    pressure_viscosity=10.3,
    load_per_length=500.0,
    radius=20.0,
    e_prime=E_PRIME,
)


def test_scales_as_u_to_0_658() -> None:
    # Goksem & Hargreaves: F_R ∝ (G U)^0.658 with U ∝ u, so F_R(k u)/F_R(u) = k^0.658
    # exactly (isothermal); checked over a decade of speed, rtol 1e-12 (rounding only).
    u = np.array([1.0, 2.0, 5.0, 10.0, 20.0])
    f = np.asarray(rolling_traction_isothermal(**{**POINT, "entraining_velocity": u}))
    np.testing.assert_allclose(f / f[0], (u / u[0]) ** 0.658, rtol=1e-12)
    # log-log slope, the form the brief states it in
    slope = np.polyfit(np.log(u), np.log(f), 1)[0]
    assert slope == pytest.approx(0.658, abs=1e-12)


def test_viscosity_and_load_exponents() -> None:
    # Same power law in η₀ (through U) and the weak W^0.0126 load dependence.
    base = rolling_traction_isothermal(**POINT)
    assert rolling_traction_isothermal(**{**POINT, "viscosity": 0.0272}) / base == pytest.approx(
        2**0.658, rel=1e-12
    )
    assert rolling_traction_isothermal(
        **{**POINT, "load_per_length": 1000.0}
    ) / base == pytest.approx(2**0.0126, rel=1e-12)


def test_si_evaluation_independent_route() -> None:
    # The published formula evaluated in SI (N/m) straight from its definition
    # (seed Eq. 5.10 text: U = η₀V_r/(E R), G = α E, W = w/(E R), F/l = 4.318 (GU)^0.658
    # W^0.0126 R/α) must equal the module's N/mm result × 1000; rtol 1e-12.
    u, eta, alpha, w, r, e = 5.0, 0.0136, 10.3e-9, 500.0e3, 0.020, E_PRIME * 1e6
    big_u, big_g, big_w = eta * u / (e * r), alpha * e, w / (e * r)
    f_si = 4.318 * (big_g * big_u) ** 0.658 * big_w**0.0126 * r / alpha
    assert rolling_traction_isothermal(**POINT) * 1e3 == pytest.approx(f_si, rel=1e-12)


def test_magnitude_small_against_sliding() -> None:
    # A units guard, not a reference value: the seed treats rolling traction as a loss
    # secondary to sliding (μ ≈ 0.01–0.06, seed Fig. 5.10), so F_R/w′ must sit well below
    # 0.01; a factor-1000 slip in the α or R units would move it out of [1e-5, 5e-3].
    ratio = rolling_traction_isothermal(**POINT) / POINT["load_per_length"]
    assert 1e-5 < ratio < 5e-3


def test_thermal_correction_is_factor_times_isothermal() -> None:
    # Seed Eq. 5.10 read as φ_T × the isothermal correlation: identity with φ_T computed
    # separately from friction.film at the same L and p_h; rtol 1e-12.
    oil = load_lubricant("75W90")
    t = 90.0
    eta = viscosity(oil, t)
    alpha = pressure_viscosity_coefficient(oil, t)
    beta = temperature_viscosity_coefficient(oil, t)
    k = thermal_conductivity(oil, t)
    u = np.array([1.0, 3.0, 10.0, 20.0])
    sr = 0.4
    args = dict(POINT, viscosity=eta, pressure_viscosity=alpha, entraining_velocity=u)
    hot = np.asarray(
        rolling_traction(
            slide_to_roll=sr,
            temperature_viscosity_coefficient=beta,
            thermal_conductivity=k,
            **args,
        )
    )
    cold = np.asarray(rolling_traction_isothermal(**args))
    phi = thermal_reduction_factor(
        thermal_loading(beta, eta, u, k),
        hertz_line_contact(POINT["load_per_length"], POINT["radius"], E_PRIME / 2).peak_pressure,
        E_PRIME,
        sr,
    )
    np.testing.assert_allclose(hot, phi * cold, rtol=1e-12)
    assert np.all(hot < cold)  # shear heating only reduces the traction
    # the thermal correction grows with speed (L ∝ u²)
    assert np.all(np.diff(hot / cold) < 0)


def test_thermal_model_choice() -> None:
    kw = dict(
        POINT,
        slide_to_roll=0.3,
        temperature_viscosity_coefficient=0.026,
        thermal_conductivity=0.135,
    )
    a = rolling_traction(**kw, thermal_model="murch_wilson1975")
    b = rolling_traction(**kw)
    assert a != b and 0 < a < rolling_traction_isothermal(**POINT)
    with pytest.raises(ModelUnavailableError, match="gupta1992"):
        rolling_traction(**kw, thermal_model="none")


def test_thermal_clip_warns() -> None:
    kw = dict(
        POINT,
        entraining_velocity=80.0,
        viscosity=5.0,
        load_per_length=20000.0,
        slide_to_roll=0.3,
        temperature_viscosity_coefficient=0.1,
        thermal_conductivity=0.1,
    )
    with pytest.warns(FrictionModelRangeWarning):
        f = rolling_traction(**kw)
    assert f == 0.0


def test_power_loss_units() -> None:
    # P = (F_R/l)·L·V_r: 0.1 N/mm × 10 mm × 5 m/s = 1 N × 5 m/s = 5 W (unit identity).
    assert rolling_power_loss(0.1, 10.0, 5.0) == pytest.approx(5.0, rel=1e-15)
    p = rolling_power_loss(np.array([0.1, 0.2]), 10.0, np.array([5.0, 1.0]))
    np.testing.assert_allclose(p, [5.0, 2.0], rtol=1e-15)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("entraining_velocity", -1.0),
        ("viscosity", -0.01),
        ("pressure_viscosity", 0.0103),  # given in 1/MPa by mistake
        ("load_per_length", float("nan")),
        ("radius", 0.0),
    ],
)
def test_bad_input_names_field(field: str, value: float) -> None:
    with pytest.raises(InputError, match=field):
        rolling_traction_isothermal(**{**POINT, field: value})


def test_power_loss_bad_input() -> None:
    with pytest.raises(InputError, match="length"):
        rolling_power_loss(0.1, -1.0, 5.0)


def test_zero_speed_gives_zero_traction() -> None:
    # Limit u → 0: U = 0, no film, no rolling traction (finite, not NaN).
    f = rolling_traction_isothermal(**{**POINT, "entraining_velocity": 0.0})
    assert f == 0.0 and math.isfinite(f)
