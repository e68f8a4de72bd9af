"""Power loss and efficiency of a loaded mesh (friction.efficiency): bookkeeping and ranges.

Identities: each segment's sliding loss is μ·F·V_s (recomputed here from the stored
fields), the power loss of a roll position is the sum over its segments, efficiency is
1 − loss/(T_p ω_p). Ranges: the seed reports μ 0.01–0.06, λ 0.1–0.3 and mesh
efficiencies of 96–99.5 % for automotive hypoid pairs at 1500 rpm (seed ch. 5); the
test pair (crowned hypoid example of tests/test_ltca.py) must fall in the efficiency
band, and its median μ in the μ band.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_ltca import _run  # the same LTCA result (cached per session)

from friction.efficiency import efficiency_analysis
from geometry.errors import InputError


@pytest.fixture(scope="module")
def ltca():
    return _run()


@pytest.fixture(scope="module")
def fr(ltca):
    return efficiency_analysis(ltca)


def test_bookkeeping(ltca, fr):
    F = ltca["force"].values
    mu, vs = fr["friction_coefficient"].values, fr["sliding_velocity"].values
    loaded = np.isfinite(F) & (F > 0)
    np.testing.assert_allclose(fr["sliding_loss"].values[loaded], (mu * F * vs)[loaded], rtol=1e-12)
    total = (fr["sliding_loss"].fillna(0) + fr["rolling_loss"].fillna(0)).sum(("pair", "segment"))
    np.testing.assert_allclose(fr["power_loss"].values, total.values, rtol=1e-12)
    p_in = ltca["torque"].values[:, None] * 2 * math.pi * 1500.0 / 60.0
    np.testing.assert_allclose(
        fr["efficiency"].values, 1 - fr["power_loss"].values / p_in, rtol=1e-12
    )


def test_seed_ranges(fr):
    eff = fr["efficiency_mean"].values
    assert np.all((eff > 0.96) & (eff < 0.995))
    assert 0.01 < float(fr["friction_coefficient"].median()) < 0.06
    assert np.all(fr["rolling_loss"].fillna(0).values >= 0)


def test_constant_friction_scales_the_sliding_loss(ltca, fr):
    c = efficiency_analysis(ltca, friction_model="constant")
    np.testing.assert_allclose(c["friction_coefficient"].dropna("segment", how="all").max(), 0.05)
    ratio = c["sliding_loss"] / (fr["sliding_loss"] / fr["friction_coefficient"] * 0.05)
    np.testing.assert_allclose(ratio.values[np.isfinite(ratio.values)], 1.0, rtol=1e-12)


def test_bad_input(ltca):
    with pytest.raises(InputError, match="pinion_speed"):
        efficiency_analysis(ltca, pinion_speed=0.0)
    with pytest.raises(InputError, match="roughness"):
        efficiency_analysis(ltca, roughness=-1.0)
    with pytest.raises(InputError, match="ltca"):
        efficiency_analysis(ltca.drop_vars("contact_point"))
