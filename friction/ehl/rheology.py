"""Lubricant rheology of the mixed-EHL solver: viscosity and density under pressure, film shear.

Pure functions of pressure in SI units inside the solver ([Pa], [Pa s], [kg/m3]); the
lubricant's properties at the inlet temperature come from :mod:`friction.lubricant`
(η₀ by its Vogel fit, α by its table, ρ₀ by its straight-line fit).

* viscosity–pressure: Roelands (1966) with the pressure–viscosity index Z chosen so that
  its initial slope equals the table's α, or Barus η = η₀ e^(αp) (registry
  :data:`VISCOSITY_PRESSURE_MODELS`);
* density–pressure: Dowson & Higginson (1966), ρ/ρ₀ = 1 + 0.6 p/(1 + 1.7 p), p in GPa;
* film shear: Eyring, τ = τ₀ asinh(η γ̇/τ₀), capped by the limiting shear stress Λ p
  (Bair & Winer 1979).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "ROELANDS_P0",
    "VISCOSITY_PRESSURE_MODELS",
    "barus_viscosity",
    "dowson_higginson_density",
    "eyring_limited_shear",
    "roelands_viscosity",
    "roelands_z",
]

Array = NDArray[np.float64]

#: Roelands' reference pressure p₀ [Pa] (Roelands 1966).
ROELANDS_P0 = 1.96e8
#: ln(η∞) of Roelands' equation with η∞ = 6.31e-5 Pa s: ln η∞ = −9.67.
_LN_ETA_INF = math.log(6.31e-5)


def roelands_z(eta0: float | Array, alpha: float | Array) -> float | Array:
    """Roelands pressure–viscosity index Z matching a pressure–viscosity coefficient α.

    Parameters
    ----------
    eta0 : float or array — [Pa s]
        Viscosity at ambient pressure.
    alpha : float or array — [1/Pa]
        Pressure–viscosity coefficient (initial slope of ln η).

    Returns
    -------
    float — [1]
        Z = α p₀ / (ln η₀ + 9.67), so that d ln η/dp at p = 0 equals α.

    Notes
    -----
    Source: Roelands, C. J. A., "Correlational aspects of the viscosity–temperature–pressure
    relationship of lubricating oils", PhD thesis, TU Delft, 1966; the matching of Z to α
    is Hamrock, Schmid & Jacobson, *Fundamentals of Machine Elements*, §8.7 (and Venner &
    Lubrecht 2000, Eq. 2.7).
    """
    return alpha * ROELANDS_P0 / (np.log(eta0) - _LN_ETA_INF)


def roelands_viscosity(pressure: Array, eta0: float | Array,
                       alpha: float | Array) -> tuple[Array, Array]:
    """Roelands viscosity η(p) and its derivative d ln η/dp.

    Parameters
    ----------
    pressure : array (n,) — [Pa]
        Film pressure; negative values are treated as 0.
    eta0 : float or array (broadcast with pressure) — [Pa s]
    alpha : float or array — [1/Pa]

    Returns
    -------
    eta : array (n,) — [Pa s]
        η = η₀ exp{(ln η₀ + 9.67)[(1 + p/p₀)^Z − 1]}.
    dln_eta : array (n,) — [1/Pa]
        d ln η / dp (0 where p < 0).

    Notes
    -----
    Source: Roelands (1966); see :func:`roelands_z`.
    """
    p = np.maximum(pressure, 0.0)
    z = roelands_z(eta0, alpha)
    a = np.log(eta0) - _LN_ETA_INF
    s = 1.0 + p / ROELANDS_P0
    expo = a * (s**z - 1.0)
    eta = eta0 * np.exp(expo)
    d = a * z * s ** (z - 1.0) / ROELANDS_P0
    return eta, np.where(pressure > 0.0, d, 0.0)


def barus_viscosity(pressure: Array, eta0: float | Array,
                    alpha: float | Array) -> tuple[Array, Array]:
    """Barus viscosity η = η₀ e^(αp) and d ln η/dp.

    Parameters
    ----------
    pressure : array (n,) — [Pa]
        Negative values are treated as 0.
    eta0 : float or array (broadcast with pressure) — [Pa s]
    alpha : float or array — [1/Pa]

    Returns
    -------
    eta : array (n,) — [Pa s]
    dln_eta : array (n,) — [1/Pa]

    Notes
    -----
    Source: Barus, C., Am. J. Sci. 45 (1893) 87.
    """
    p = np.maximum(pressure, 0.0)
    eta = eta0 * np.exp(alpha * p)
    return eta, np.where(pressure > 0.0, alpha, 0.0) * np.ones_like(p)


#: Viscosity–pressure relations by name: (p [Pa], η₀ [Pa s], α [1/Pa]) → (η, d ln η/dp).
VISCOSITY_PRESSURE_MODELS: Mapping[str, Callable[[Array, float, float], tuple[Array, Array]]] = (
    MappingProxyType({"roelands": roelands_viscosity, "barus": barus_viscosity})
)


def dowson_higginson_density(pressure: Array) -> tuple[Array, Array]:
    """Dowson–Higginson density ratio ρ/ρ₀ and its derivative.

    Parameters
    ----------
    pressure : array (n,) — [Pa]
        Negative values are treated as 0.

    Returns
    -------
    rho_ratio : array (n,) — [1]
        ρ/ρ₀ = 1 + 0.6e-9 p / (1 + 1.7e-9 p).
    drho_ratio : array (n,) — [1/Pa]

    Notes
    -----
    Source: Dowson, D., Higginson, G. R., *Elasto-hydrodynamic Lubrication*, Pergamon 1966.
    """
    p = np.maximum(pressure, 0.0)
    den = 1.0 + 1.7e-9 * p
    rho = 1.0 + 0.6e-9 * p / den
    d = 0.6e-9 / den**2
    return rho, np.where(pressure > 0.0, d, 0.0)


def eyring_limited_shear(
    viscosity: Array, shear_rate: Array, pressure: Array, eyring_stress: float,
    limiting_shear_coefficient: float,
) -> Array:
    """Film shear stress: Eyring, capped by the limiting shear stress.

    Parameters
    ----------
    viscosity : array (n,) — [Pa s]
    shear_rate : array (n,) — [1/s]
        Sliding velocity over film thickness, u_s/h (signed).
    pressure : array (n,) — [Pa]
    eyring_stress : float — [Pa]
        τ₀ > 0.
    limiting_shear_coefficient : float — [1]
        Λ = τ_L/p ≥ 0; ``inf`` disables the cap.

    Returns
    -------
    array (n,) — [Pa]
        τ = sign(γ̇) min(τ₀ asinh(η|γ̇|/τ₀), Λ p).

    Notes
    -----
    Source: Eyring, H., J. Chem. Phys. 4 (1936) 283; Johnson & Tevaarwerk, Proc. R. Soc.
    A 356 (1977) 215 (the sinh law for EHL traction); Bair & Winer, J. Lubr. Technol. 101
    (1979) 258 (limiting shear stress proportional to pressure).
    """
    tau = eyring_stress * np.arcsinh(viscosity * np.abs(shear_rate) / eyring_stress)
    cap = limiting_shear_coefficient * np.maximum(pressure, 0.0)
    return np.sign(shear_rate) * np.minimum(tau, cap)
