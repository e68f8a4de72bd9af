"""Johnson–Greenwood–Poon load sharing: the independent check of the stochastic solver.

Johnson, Greenwood & Poon (1972) split a lubricated rough contact's load w′ between the
film and the asperities, w′ = w′/γ₁ + w′/γ₂ with 1/γ₁ + 1/γ₂ = 1, without solving the
Reynolds equation: the film carries w′/γ₁ as a smooth EHL contact of modulus E′/γ₁ (the
same Hertz width), whose central film — here Moes's formula
(:func:`friction.film.moes_central`, with U → γ₁U, G → G/γ₁, W unchanged) — is the
separation of the mean planes; at that separation the asperities must carry the rest,
p_a(h_c) = p̄/γ₂ with p̄ = πp_h/4 the mean Hertz pressure. One monotonic equation in γ₁
(Gelinck & Schipper 2000 solve the same system with Moes's formula).

It shares with :mod:`friction.ehl.stochastic` only the asperity law (the same summit
statistics and elastic–plastic summits, :func:`friction.ehl.asperity.asperity_contact`,
as the check must be "built from the same profile's summit statistics"); the film comes
from a formula instead of the average-flow Reynolds equation, the asperity pressure is a
single mean instead of a distribution over the contact, and the separation is uniform.

References
----------
Johnson, K. L., Greenwood, J. A., Poon, S. Y., "A simple theory of asperity contact in
elastohydrodynamic lubrication", Wear 19 (1972) 91–108.
Gelinck, E. R. M., Schipper, D. J., "Calculation of Stribeck curves for line contacts",
Tribol. Int. 33 (2000) 175–181.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from friction.ehl.asperity import asperity_contact
from friction.ehl.line_contact import LineContactCondition, hertz_line_contact, lubricant_of
from friction.ehl.stochastic import RoughnessStatistics
from friction.film import ehl_groups, moes_film
from friction.lubricant import pressure_viscosity_coefficient, viscosity
from geometry.core.materials import DEFAULT_MATERIAL, material

__all__ = ["LoadSharing", "jgp_load_sharing"]


class LoadSharing(NamedTuple):
    """The JGP split of one condition."""

    asperity_load_ratio: float    #: 1/γ₂ [1]
    film_central: float           #: the film's central thickness = mean-plane separation [µm]
    film_load_factor: float       #: γ₁ [1]


def jgp_load_sharing(condition: LineContactCondition, stats: RoughnessStatistics,
                     material_name: str = DEFAULT_MATERIAL) -> LoadSharing:
    """Asperity load ratio of a rough line contact by Johnson–Greenwood–Poon.

    Parameters
    ----------
    condition : LineContactCondition
        Load, radius, speed, temperature, oil, E′ (its roughness arrays are not used).
    stats : RoughnessStatistics
        Of the two surfaces (:func:`friction.ehl.stochastic.roughness_statistics`).
    material_name : str
        For the summits' hardness.

    Returns
    -------
    LoadSharing

    Notes
    -----
    Source: module docstring. γ₁ is found by bisection on ln γ₁ ∈ [0, 25]
    (p_a(h_c(γ₁)) − p̄(1 − 1/γ₁) changes sign once); where the asperities at the smooth
    film's separation already carry more than the whole mean pressure, the share is 1.
    """
    oil = lubricant_of(condition.lubricant)
    mat = material(material_name)
    eta0 = float(viscosity(oil, condition.temperature))
    alpha = float(pressure_viscosity_coefficient(oil, condition.temperature))
    _b, ph = hertz_line_contact(condition.load_per_length, condition.radius, condition.e_prime)
    p_mean = 0.25 * math.pi * ph

    groups = ehl_groups(condition.entraining_velocity, eta0, alpha, condition.load_per_length,
                        condition.radius, condition.e_prime)

    def film(g1: float) -> float:
        """Central film [µm] of the smooth contact carrying w′/γ₁ at modulus E′/γ₁."""
        return float(moes_film(groups.W, groups.U * g1, groups.G / g1)) * condition.radius * 1e3

    def excess(ln_g1: float) -> float:
        g1 = math.exp(ln_g1)
        pa = asperity_contact(np.array([film(g1)]), stats.summits, condition.e_prime,
                              mat.hardness, mat.poisson_ratio).pressure[0]
        return float(pa) - p_mean * (1.0 - 1.0 / g1)

    lo, hi = 0.0, 25.0
    if excess(hi) > 0.0:
        return LoadSharing(1.0, film(math.exp(hi)), math.inf)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if excess(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    g1 = math.exp(0.5 * (lo + hi))
    return LoadSharing(1.0 - 1.0 / g1, film(g1), g1)
