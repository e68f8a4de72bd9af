"""Film traction of a smooth EHL line contact: the Eyring shear over the Hertz zone.

:func:`smooth_film_traction` is the friction coefficient of the film alone, with the
contact's pressure taken as Hertz's and its film as the central film everywhere:

    μ_E = (1/w′) ∫_{−b}^{b} min(τ₀ asinh(η(p) u_s/(h_c τ₀)), Λ p) dx,
    p = p_h √(1 − (x/b)²),   w′ = π b p_h / 2,

with η(p) Barus' or Roelands' (:mod:`friction.ehl.rheology`, the solver's), h_c
Dowson & Toyoda's isothermal central film (:func:`friction.film.dowson_toyoda_central`),
τ₀ the Eyring stress and Λ the limiting shear coefficient (the cap τ_L = Λp of Bair &
Winer). It is the film part of the mixed-EHL solver's μ (:mod:`friction.ehl`) without
its inlet and exit, its pressure spike and roughness: the solver's smooth full-film μ
agrees with it to a few per cent (tests/test_traction.py), and it carries the traction
curve's shape in SR, pressure and temperature (Newtonian, Eyring, limiting) into the
``kolivand2009`` model's ``eyring`` structure (:mod:`friction.kolivand2009`), whose
regression then only corrects it for roughness and the asperities' share.

The integral is evaluated by Gauss–Legendre quadrature in θ with x = b sin θ (the
square-root ends of the Hertz pressure become smooth); ``nodes`` = 48 is converged to
1e-4 relative or better except at the kink where the cap starts (tests).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.ehl.rheology import VISCOSITY_PRESSURE_MODELS, eyring_limited_shear
from friction.film import dowson_toyoda_central
from geometry.core.errors import InputError
from geometry.core.validation import broadcast, integer, one_of, real_array, scalar_or_array

__all__ = ["smooth_film_traction"]

Array = NDArray[np.float64]


def smooth_film_traction(
    *,
    hertz_pressure: ArrayLike,
    slide_to_roll: ArrayLike,
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
    eyring_stress: float,
    limiting_shear_coefficient: float,
    viscosity_model: str = "barus",
    nodes: int = 48,
) -> NDArray[np.float64] | float:
    """Friction coefficient of the Eyring film shear over a smooth Hertz line contact.

    Parameters
    ----------
    hertz_pressure : float or array — [MPa]
        p_h > 0.
    slide_to_roll : float or array — [1]
        SR = u_s/u_e (sign ignored).
    entraining_velocity : float or array — [m/s]
        u_e = (u₁ + u₂)/2 > 0.
    viscosity : float or array — [Pa s]
        η₀ at the inlet temperature, > 0.
    pressure_viscosity : float or array — [1/GPa]
        α > 0.
    radius : float or array — [mm]
        R_eq > 0.
    e_prime : float or array — [MPa]
        E′ = 2E* (:mod:`friction.film`'s convention).
    eyring_stress : float — [MPa]
        τ₀ > 0.
    limiting_shear_coefficient : float — [1]
        Λ = τ_L/p > 0 (``inf``: no cap).
    viscosity_model : {"barus", "roelands"}
        η(p) (:data:`friction.ehl.rheology.VISCOSITY_PRESSURE_MODELS`).
    nodes : int
        Quadrature nodes in θ, 4 … 1024.

    Returns
    -------
    float or array — [1]
        μ_E ≥ 0, broadcast shape of the array inputs (0 where SR = 0).

    Raises
    ------
    InputError
        An input non-finite or out of its range (named).

    Notes
    -----
    Source: Johnson, K. L., Tevaarwerk, J. L., "Shear behaviour of elastohydrodynamic oil
    films", Proc. R. Soc. A 356 (1977) 215 (the Eyring film over the Hertz zone at the
    central film); Bair, S., Winer, W. O., J. Lubr. Technol. 101 (1979) 258 (Λp);
    Dowson & Toyoda (1979) for h_c. The seed's Eq. 5.8 film shear with the solver's
    rheology (:func:`friction.ehl.rheology.eyring_limited_shear`).
    """
    ph = real_array("hertz_pressure", hertz_pressure, low=0.0, low_open=True, unit="MPa")
    sr = np.abs(real_array("slide_to_roll", slide_to_roll, unit="1"))
    ue = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True,
                    unit="m/s")
    eta0 = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    alpha = real_array("pressure_viscosity", pressure_viscosity, low=0.0, low_open=True,
                       high=100.0, unit="1/GPa")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    ep = real_array("e_prime", e_prime, low=1e3, high=1e7, unit="MPa")
    if not (math.isfinite(eyring_stress) and eyring_stress > 0.0):
        raise InputError(f"eyring_stress: must be finite and > 0 [MPa], got {eyring_stress}")
    if not limiting_shear_coefficient > 0.0:
        raise InputError("limiting_shear_coefficient: must be > 0 [1] (inf: no cap), got "
                         f"{limiting_shear_coefficient}")
    one_of("viscosity_model", viscosity_model, tuple(VISCOSITY_PRESSURE_MODELS))
    integer("nodes", nodes, low=4, high=1024)
    ph, sr, ue, eta0, alpha, r, ep = broadcast(
        hertz_pressure=ph, slide_to_roll=sr, entraining_velocity=ue, viscosity=eta0,
        pressure_viscosity=alpha, radius=r, e_prime=ep)
    load = 2.0 * math.pi * r * ph**2 / ep                      # w′ [N/mm]
    hc = np.asarray(dowson_toyoda_central(ue, eta0, alpha, load, r, ep), float) * 1e-6  # [m]
    rate = sr * ue / hc                                        # u_s/h_c [1/s]
    theta, weight = np.polynomial.legendre.leggauss(nodes)
    cos = np.cos(0.5 * math.pi * theta)                        # √(1 − ξ²), ξ = sin θ
    p = ph[..., None] * 1e6 * cos                              # [Pa]
    tau0 = eyring_stress * 1e6
    eta, _ = VISCOSITY_PRESSURE_MODELS[viscosity_model](p, eta0[..., None],
                                                        alpha[..., None] * 1e-9)
    tau = eyring_limited_shear(eta, rate[..., None], p, tau0, limiting_shear_coefficient)
    # ∫_{−b}^{b} τ dx = b ∫_{−π/2}^{π/2} τ(θ) cos θ dθ, the rule's weights on θ ∈ [−1, 1]
    # scaled by π/2, and w′ = π b p_h/2: μ = Σ τ cos θ w / p_h
    return scalar_or_array(np.sum(tau * cos * weight, axis=-1) / (ph * 1e6))

