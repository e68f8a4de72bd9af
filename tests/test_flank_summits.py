"""Asperity summits of ground flanks from their roughness (friction.flank_summits).

Independent references: the scaling identities of a profile scaled in height (m₀, m₂, m₄
all ∝ Rq², so McCool's summit density is unchanged, β ∝ 1/Rq, σ ∝ Rq: ηβσ constant and
σ/β ∝ Rq² — exact, so round-off tolerances); McCool's (1986) formulas written out by hand
from the moments; Greenwood & Williamson's plasticity index by hand; the range the
module's source quotes for a ground profile (RΔq ≈ 0.10 rad at Rq 0.5 µm,
friction.ehl.roughness.DEFAULT_SHORT_CUTOFF) and Greenwood & Williamson's 0.03–0.05 for
ηβσ (their Table 1 surfaces), with the tolerance of those ranges.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from friction.ehl.asperity import composite_moments
from friction.flank_summits import (
    _composite_heights,
    flank_summit_statistics,
    greenwood_tripp_parameters,
    height_tail_integral,
    plasticity_index,
    unit_profile_moments,
    unit_profile_skewness,
)
from friction.mixed_ehl import greenwood_tripp_integral
from geometry.core.errors import InputError


def test_scaled_profile_keeps_density_and_sharpens_summits() -> None:
    ebs1, sb1 = greenwood_tripp_parameters(0.5, 0.5)
    for rq in (0.068, 0.3, 0.884, 1.3):
        ebs, sb = greenwood_tripp_parameters(rq, rq)
        assert ebs == pytest.approx(ebs1, rel=1e-12)
        assert sb == pytest.approx(min(sb1 * (rq / 0.5) ** 2, 1.0), rel=1e-12)
        s = flank_summit_statistics(rq, rq)
        s1 = flank_summit_statistics(0.5, 0.5)
        assert s.density == pytest.approx(s1.density, rel=1e-12)
        assert s.radius * rq == pytest.approx(s1.radius * 0.5, rel=1e-12)


def test_running_in_blunts_the_summits_by_the_square_of_the_roughness_ratio() -> None:
    # running-in as a change of roughness (Rq × 0.68): σ/β falls by 0.68²
    _, sb_new = greenwood_tripp_parameters(0.8, 0.8)
    _, sb_run = greenwood_tripp_parameters(0.8 * 0.68, 0.8 * 0.68)
    assert sb_run / sb_new == pytest.approx(0.68**2, rel=1e-12)


def test_mccool_summits_from_the_moments_by_hand() -> None:
    (u1, u2) = unit_profile_moments("ground")
    m0, m2, m4 = composite_moments(tuple(m * 0.64 for m in u1), tuple(m * 0.25 for m in u2))
    s = flank_summit_statistics(0.8, 0.5)
    assert s.sigma == pytest.approx(math.sqrt(0.64 + 0.25), rel=1e-12)
    # McCool (1986) Eq. 3-7 (m₀ [µm²], m₂ [1], m₄ [1/mm²]): η = m₄/(6π√3 m₂),
    # β = 0.375 √(π/m₄), α = m₀m₄/m₂², σ_s = √(1 − 0.8968/α) σ
    alpha = m0 * 1e-6 * m4 / m2**2
    assert s.density == pytest.approx(m4 / (6 * math.pi * math.sqrt(3) * m2), rel=1e-12)
    assert s.radius == pytest.approx(0.375 * math.sqrt(math.pi / m4), rel=1e-12)
    assert s.bandwidth == pytest.approx(alpha, rel=1e-12)
    assert s.summit_sigma == pytest.approx(math.sqrt(1 - 0.8968 / alpha) * s.sigma, rel=1e-12)
    ebs, sb = greenwood_tripp_parameters(0.8, 0.5)
    assert ebs == pytest.approx(s.density * s.radius * s.sigma * 1e-3, rel=1e-12)
    assert sb == pytest.approx(s.sigma * 1e-3 / s.radius, rel=1e-12)


def test_ground_profile_inside_the_measured_ranges() -> None:
    (u1, _u2) = unit_profile_moments("ground")
    # RΔq of one flank at Rq 0.5 µm: √m₂ (the module's statement ≈ 0.10 rad)
    assert 0.5 * math.sqrt(u1[1]) == pytest.approx(0.10, abs=0.03)
    ebs, _ = greenwood_tripp_parameters(0.5, 0.5)
    assert 0.03 <= ebs <= 0.06  # Greenwood & Williamson 1966: 0.03–0.05; ours 0.056


def test_plasticity_index_by_hand() -> None:
    s = flank_summit_statistics(0.544, 0.544)
    psi = plasticity_index(s, 2.26e5, 6835.0)
    assert psi == pytest.approx(1.13e5 / 6835.0 * math.sqrt(s.summit_sigma * 1e-3 / s.radius),
                                rel=1e-12)
    assert psi > 1.0  # a ground flank's summits yield at first contact (GW 1966: ψ > 1)


def test_refusals_name_the_field() -> None:
    with pytest.raises(InputError, match="finish"):
        unit_profile_moments("lapped")
    with pytest.raises(InputError, match="roughness_1, roughness_2"):
        flank_summit_statistics(0.0, 0.0)
    with pytest.raises(InputError, match="roughness_1"):
        flank_summit_statistics(-1.0, 0.5)
    assert np.isfinite(greenwood_tripp_parameters(0.0, 0.5)[1])


def test_height_integral_of_gaussian_heights_is_greenwood_tripps() -> None:
    # zero skewness: the composite is Gaussian and F_{5/2} is the closed form (parabolic
    # cylinder function); the 0.002 σ binning of the quadrature bounds the error (< 1e-3
    # relative up to t = 5, where F is 3e-9 of its value at 0)
    x, p = _composite_heights(0.0, 0.0, 0.6)
    t = np.array([-3.0, -1.0, 0.0, 1.0, 2.0, 3.0, 5.0])
    f = np.array([np.sum(p * np.maximum(x - ti, 0.0) ** 2.5) for ti in t])
    np.testing.assert_allclose(f, greenwood_tripp_integral(2.5, t), rtol=1e-3)


def test_composite_heights_have_the_flanks_moments() -> None:
    # the sum of independent unit-variance heights weighted w₁, w₂ (w₁² + w₂² = 1) has mean
    # 0, variance 1 and skewness w₁³ s₁ + w₂³ s₂ (third cumulants add)
    s1, s2 = unit_profile_skewness("ground")
    assert -0.6 < s1 < -0.2 and -0.6 < s2 < -0.2  # generated at −0.5, lowered by λs
    for r1, r2 in ((0.5, 0.5), (0.8, 0.3)):
        w1 = r1 / math.hypot(r1, r2)
        w2 = r2 / math.hypot(r1, r2)
        x, p = _composite_heights(s1, s2, w1)
        assert np.sum(p * x) == pytest.approx(0.0, abs=1e-9)
        assert np.sum(p * x * x) == pytest.approx(1.0, rel=1e-9)
        assert np.sum(p * x**3) == pytest.approx(w1**3 * s1 + w2**3 * s2, abs=2e-3)


def test_skewed_heights_carry_less_at_positive_separation() -> None:
    # negative skewness thins the upper tail: F_{5/2} below the Gaussian's for t ≥ 0,
    # approaching it deep in contact (t → −∞: E[(z − t)^{5/2}] ≈ |t|^{5/2}, skew-free to
    # first order); continuous across the tabulated range's lower end (−8)
    t = np.array([0.0, 0.5, 1.0, 2.0])
    ratio = height_tail_integral(t, 0.5, 0.5) / greenwood_tripp_integral(2.5, t)
    assert np.all(np.diff(ratio) < 0) and np.all(ratio < 1.0)
    deep = height_tail_integral(np.array([-12.0]), 0.5, 0.5)
    assert deep[0] == pytest.approx(float(greenwood_tripp_integral(2.5, -12.0)), rel=2e-3)
    edge = height_tail_integral(np.array([-8.0 - 1e-9, -8.0 + 1e-9]), 0.5, 0.5)
    assert edge[0] == pytest.approx(edge[1], rel=1e-6)
