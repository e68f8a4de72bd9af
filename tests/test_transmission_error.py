"""TE summary statistics against signals with known harmonics (exact identities)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from contact.ltca.transmission_error import mesh_harmonics, transmission_error_summary
from geometry.core.errors import InputError

T = 2 * np.pi / 11  # mesh period of an 11-tooth pinion [rad]


def _signal(n_per_cycle=40, cycles=2, amps=(6.3, 0.6, 0.1), phases=(0.3, 1.1, -0.4), mean=110.0):
    phi = np.arange(n_per_cycle * cycles) * T / n_per_cycle
    y = mean + sum(a * np.cos(2 * np.pi * (k + 1) * phi / T + p)
                   for k, (a, p) in enumerate(zip(amps, phases, strict=True)))
    return phi, y


def test_known_harmonics_recovered_to_round_off():
    phi, y = _signal()
    s = transmission_error_summary(phi, y, T)
    np.testing.assert_allclose(s["harmonics"], [6.3, 0.6, 0.1], rtol=1e-10)
    assert s["mean"] == pytest.approx(110.0, rel=1e-12)
    # RMS of a sum of orthogonal sines: √(ΣA²/2); the seed's "RMS" is √ΣA²
    assert s["rms"] == pytest.approx(np.sqrt((6.3**2 + 0.6**2 + 0.1**2) / 2), rel=1e-10)
    assert s["harmonic_rss"] == pytest.approx(np.sqrt(6.3**2 + 0.6**2 + 0.1**2), rel=1e-10)


def test_seed_table_3_1_rms_reading():
    # The seed's printed rows (Table 3.1): 1st/2nd/3rd and RMS — RMS = √ΣAₖ² within the
    # printed precision of 0.1 µrad.
    for a1, a2, a3, rms in ((6.3, 0.6, 0.1, 6.3), (7.9, 0.3, 0.4, 7.9), (9.9, 2.3, 0.5, 10.1)):
        phi, y = _signal(amps=(a1, a2, a3))
        assert transmission_error_summary(phi, y, T)["harmonic_rss"] == pytest.approx(rms, abs=0.15)


def test_higher_harmonics_do_not_alias_into_the_first_three():
    phi, y = _signal(amps=(1.0, 0.0, 0.0))
    y = y + 5.0 * np.cos(2 * np.pi * 7 * phi / T)
    np.testing.assert_allclose(mesh_harmonics(phi, y, T), [1.0, 0.0, 0.0], atol=1e-10)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.1, 50), st.floats(-np.pi, np.pi), st.integers(1, 3), st.integers(16, 64))
def test_pure_sine_peak_to_peak(amp, phase, cycles, n):
    phi = np.arange(n * cycles) * T / n
    y = amp * np.sin(2 * np.pi * phi / T + phase)
    s = transmission_error_summary(phi, y, T)
    assert s["harmonics"][0] == pytest.approx(amp, rel=1e-9)
    assert s["peak_to_peak"] <= 2 * amp * (1 + 1e-12)
    assert s["peak_to_peak"] >= 2 * amp * np.cos(np.pi / n) - 1e-9  # sampled extremes


@pytest.mark.parametrize(
    ("roll", "te", "field"),
    [
        (np.arange(10) * T / 7, np.zeros(10), "whole number"),
        (np.arange(40) * T / 40, np.zeros(39), "equal length"),
        (np.r_[np.arange(39) * T / 40, np.nan], np.zeros(40), "finite"),
        (np.arange(3) * T / 3, np.zeros(3), "at least 4"),
        (np.arange(40)[::-1] * T / 40, np.zeros(40), "increasing"),
    ],
)
def test_bad_input(roll, te, field):
    with pytest.raises(InputError, match=field):
        transmission_error_summary(roll, te, T)
