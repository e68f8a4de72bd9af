"""Durability arithmetic (contact.load_capacity.durability): S–N curves, Miner's rule, damage
and life.

All cheap (no analysis: arrays of a few numbers). Every check is against an identity the
equations must satisfy or a hand calculation written out in the test.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact.load_capacity.durability import (
    SNCurve,
    cumulative_damage,
    life_at_first_failure,
    member_cycles,
    peak_fillet_stress,
    sn_curves,
)
from geometry.core.errors import InputError


def test_iso_6336_5_numbers_and_exponents():
    """The table's numbers are those of ISO 6336-5 (σ_Hlim MQ 1500, σ_FE MQ 850 MPa) and the
    exponents those of the life-factor lines (ln 500 / ln 1.6, ln 3000 / ln 2.5)."""
    c = sn_curves("case_carburised_steel", "MQ")
    assert c["contact"].allowable == 1500.0
    assert c["bending"].allowable == 850.0
    assert sn_curves("case_carburised_steel", "ML")["contact"].allowable == 1300.0
    assert sn_curves("case_carburised_steel", "ME")["bending"].allowable == 1050.0
    assert c["contact"].exponent == pytest.approx(math.log(500) / math.log(1.6), rel=1e-15)
    assert c["bending"].exponent == pytest.approx(math.log(3000) / math.log(2.5), rel=1e-15)


@pytest.mark.parametrize("kind", ["contact", "bending"])
@pytest.mark.parametrize("rule", ["elementary", "modified"])
def test_curve_passes_through_allowable_at_knee_and_static_end(kind, rule):
    """N(σ_lim) = N_knee and N(Z σ_lim) = N_static (ISO's life-factor line), to 1e-12
    (one power of a ratio, a few ulp)."""
    c = sn_curves("case_carburised_steel", "MQ")[kind]
    assert c.cycles_to_failure(c.allowable, rule) == pytest.approx(c.knee_cycles, rel=1e-12)
    assert c.cycles_to_failure(c.static_stress, rule) == pytest.approx(c.static_cycles,
                                                                       rel=1e-12)


def test_below_knee_rules():
    """Below the knee: elementary keeps slope m, modified (Haibach) 2m − 1, original none."""
    c = sn_curves("case_carburised_steel", "MQ")["contact"]
    s = 0.8 * c.allowable
    m = c.exponent
    assert c.cycles_to_failure(s, "elementary") == pytest.approx(c.knee_cycles * 0.8 ** -m,
                                                                 rel=1e-12)
    assert c.cycles_to_failure(s, "modified") == pytest.approx(
        c.knee_cycles * 0.8 ** -(2 * m - 1), rel=1e-12)
    assert np.isinf(c.cycles_to_failure(s, "original"))
    assert c.damage(0.0, 1e9) == 0.0


def test_damage_scales_with_duration_and_inverse_constant():
    """Damage ∝ cycles (duration) and ∝ 1 / (σ^m N constant): exact up to rounding (1e-13)."""
    c = sn_curves("case_carburised_steel", "MQ")["contact"]
    s = np.array([[0.0, 900.0], [1400.0, 1700.0]])
    n = np.array([1e7, 3e6])
    d = cumulative_damage(s, n, c)
    assert np.allclose(cumulative_damage(s, 2.5 * n, c), 2.5 * d, rtol=1e-13, atol=0)
    c3 = c.scaled(3.0)
    assert c3.exponent == pytest.approx(c.exponent, rel=1e-13)
    for rule in ("elementary", "modified"):
        assert np.allclose(cumulative_damage(s, n, c3, rule),
                           cumulative_damage(s, n, c, rule) / 3.0, rtol=1e-12, atol=0)


def test_miner_sum_three_bins_by_hand():
    """Miner's sum over 3 bins at one point, written out: Σ n_i / (N_k (σ_lim/σ_i)^k_i)."""
    c = SNCurve(1500.0, 5e7, 1e5, 1.6)
    m = math.log(500) / math.log(1.6)
    stress = np.array([1200.0, 1600.0, 2000.0])
    n = np.array([2e8, 1e7, 1e5])
    hand = (2e8 / (5e7 * (1500 / 1200) ** (2 * m - 1))  # below the knee: Haibach
            + 1e7 / (5e7 * (1500 / 1600) ** m) + 1e5 / (5e7 * (1500 / 2000) ** m))
    got = cumulative_damage(stress, n, c, "modified").sum()
    assert got == pytest.approx(hand, rel=1e-12)
    # life: the spectrum's hours over the largest damage; the point with it
    life, idx = life_at_first_failure(np.array([0.1 * got, got]), 250.0)
    assert life == pytest.approx(250.0 / got, rel=1e-15) and idx == (1,)


def test_bending_damage_from_a_root_stress_history():
    """The bending side on a stress history built here (roll, member, tooth, fillet point):
    the peak tensile stress per fillet point over rolls and teeth, compressive → 0, then
    Miner's sum by hand with one cycle per tooth mesh (pinion revolutions; gear z1/z2)."""
    rng = np.random.default_rng(1)
    hist = rng.uniform(-300, 600, size=(5, 2, 3, 4))
    hist[:, :, :, 3] = -50.0  # a fillet point in compression only
    hist[2, 1, 0, 0] = 900.0
    peak = peak_fillet_stress(hist)
    assert peak.shape == (2, 4)
    assert peak[1, 0] == 900.0 and np.all(peak[:, 3] == 0.0)
    assert peak[0, 1] == hist[:, 0, :, 1].max()
    c = sn_curves("case_carburised_steel", "MQ")["bending"]
    cyc = member_cycles(np.array([1e6, 4e6]), 11, 41)
    assert cyc["gear"][1] == pytest.approx(4e6 * 11 / 41, rel=1e-15)
    stress = np.stack([peak[1], 1.1 * peak[1]])  # gear fillet over 2 bins
    d = cumulative_damage(stress, cyc["gear"], c, "elementary").sum(0)
    m = c.exponent
    hand = sum(cyc["gear"][b] / (c.knee_cycles * (850.0 / stress[b, 0]) ** m) for b in (0, 1))
    assert d[0] == pytest.approx(hand, rel=1e-12)
    assert d[3] == 0.0


def test_bad_inputs_named():
    with pytest.raises(InputError, match="grade"):
        sn_curves("case_carburised_steel", "MX")
    with pytest.raises(InputError, match="miner_rule"):
        sn_curves("case_carburised_steel")["contact"].cycles_to_failure(1.0, "palmgren")
    with pytest.raises(InputError, match="cycles"):
        cumulative_damage(np.ones(2), np.array([1.0, -1.0]), SNCurve(1500, 5e7, 1e5, 1.6))
    with pytest.raises(InputError, match="knee_cycles"):
        SNCurve(1500, 1e4, 1e5, 1.6)
    with pytest.raises(InputError, match="stress"):
        SNCurve(1500, 5e7, 1e5, 1.6).damage(np.nan, 1.0)
    with pytest.raises(InputError, match="root_stress"):
        peak_fillet_stress(np.ones((2, 2)))


def test_rated_curve_and_one_curve_per_bin():
    """SNCurve.rated: the allowable times the rating's long-life factors at the knee, the
    static stress without those of them that are 1 there (ISO 6336-2: Z_L Z_v Z_R = 1 for
    the static stress) — both ends by hand; cumulative_damage takes one curve per bin and
    equals each bin's own damage (identity), and refuses a count that is not one per bin."""
    from contact.load_capacity.durability import SNCurve, cumulative_damage
    from geometry.core.errors import InputError

    bare = SNCurve(1500.0, 5e7, 1e5, 1.6)
    rated = bare.rated(1.2 * 0.9, 0.9)
    assert rated.allowable == pytest.approx(1620.0, rel=1e-15)
    assert rated.static_stress == pytest.approx(1500.0 * 1.2 * 1.6, rel=1e-15)
    assert rated.knee_cycles == bare.knee_cycles and rated.static_cycles == bare.static_cycles
    # on the sloped line at the static end and the knee: the cycles of the two ends
    n = rated.cycles_to_failure(np.array([rated.static_stress, rated.allowable]))
    np.testing.assert_allclose(n, [1e5, 5e7], rtol=1e-12)
    stress = np.array([[1700.0, 0.0], [1900.0, 1650.0]])
    per_bin = cumulative_damage(stress, np.array([1e6, 2e6]), [bare, rated])
    np.testing.assert_allclose(per_bin[0], bare.damage(stress[0], 1e6), rtol=1e-15)
    np.testing.assert_allclose(per_bin[1], rated.damage(stress[1], 2e6), rtol=1e-15)
    with pytest.raises(InputError, match="curve"):
        cumulative_damage(stress, np.array([1e6, 2e6]), [bare])
    with pytest.raises(InputError, match="static_influence"):
        bare.rated(1.0, 0.0)
