"""The local specific film thickness and the safety against micropitting.

Micropitting (grey staining) of case-hardened flanks is a fatigue of the asperities where
the oil film is thin beside the roughness. ISO/TS 6336-22 (Method B; ISO/TR 15144-1:2014
before it) judges it by the specific film thickness

    λ_GF = h / Ra,     Ra = (Ra₁ + Ra₂)/2                         (ISO/TR 15144-1 (2), (3))

at every point of the contact, its minimum over the flank and the mesh, and the safety

    S_λ = λ_GF,min / λ_GFP                                          (ISO/TR 15144-1 (1))

against the oil's permissible specific film thickness λ_GFP (from the oil's FVA 54
micropitting test, ISO/TS 6336-22 Method B, or as given by its maker).

Film temperature: ISO/TS 6336-22 takes the oil's viscosity and pressure–viscosity
coefficient at the bulk (tooth body) temperature θ_M, not at the oil inlet: the flanks
heat the oil that enters the contact. :func:`film_at_bulk_temperature` therefore evaluates
the toolkit's minimum film thickness h_min (Dowson–Higginson with Gupta's thermal factor,
:mod:`friction.film`) with the oil's η, α, β and k at θ_M at every loaded contact segment
of the LTCA — ISO's temperature with the toolkit's film formula. ISO's own h_Y (its
constant 1600, exponents and the sliding parameter S_GF that corrects for the local
contact temperature) is not reproduced: its text was not at hand to source the constants.
The friction stage keeps the film at the inlet temperature for the friction coefficient
(the seed's choice) and stores the inlet λ_GF,min beside the ISO one for comparison;
docs/scuffing_micropitting.md gives what the difference is worth.

Roughness: the toolkit's input is the RMS roughness Rq of each flank; ISO's is the
arithmetic mean roughness Ra. They are converted by the Gaussian relation Ra = √(2/π) Rq
(E|z| = σ √(2/π) for normally distributed heights z of standard deviation σ; Thomas,
*Rough Surfaces*, 2nd ed., Imperial College Press (1999) §5.2), 0.798 — ground and
honed flanks measure Ra/Rq of 0.75–0.85. So λ_GF = λ √π for the lambda ratio
λ = h/√(Rq₁² + Rq₂²) of two flanks of equal Rq.

Units: film thickness and roughness µm; λ dimensionless.

Public functions
----------------
arithmetic_roughness       Ra from Rq (Gaussian)
film_at_bulk_temperature   h_min with the oil's properties at θ_M (ISO/TS 6336-22's temperature)
specific_film_thickness    λ_GF = h / Ra
micropitting_safety        S_λ = λ_GF,min / λ_GFP

References
----------
ISO/TR 15144-1:2014, Calculation of micropitting load capacity of cylindrical spur and
helical gears — Part 1, Formulae (1)–(3) (replaced by ISO/TS 6336-22:2018, Method B,
which keeps them).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.film import minimum_film_thickness, thermal_loading, thermal_reduction_factor
from friction.lubricant import (
    Lubricant,
    pressure_viscosity_coefficient,
    temperature_viscosity_coefficient,
    thermal_conductivity,
    viscosity,
)
from geometry.core.errors import InputError
from geometry.core.validation import broadcast, one_of, positive, real_array

__all__ = ["GAUSSIAN_RA_PER_RQ", "arithmetic_roughness", "film_at_bulk_temperature",
           "micropitting_safety", "specific_film_thickness"]

Array = NDArray[np.float64]

#: Ra/Rq of a surface with Gaussian heights: √(2/π)
GAUSSIAN_RA_PER_RQ = math.sqrt(2.0 / math.pi)


def arithmetic_roughness(rq: ArrayLike) -> Array | float:
    """The arithmetic mean roughness of a surface with Gaussian heights.

    Parameters
    ----------
    rq : array_like — [µm]
        RMS roughness Rq, > 0.

    Returns
    -------
    float or array — [µm]
        Ra = √(2/π) Rq.

    Raises
    ------
    InputError
        A non-positive or non-finite Rq.

    Notes
    -----
    Gaussian heights (module docstring; Thomas 1999 §5.2).
    """
    r = real_array("rq", rq, unit="um", low=0.0, low_open=True)
    return _out(GAUSSIAN_RA_PER_RQ * r)


def film_at_bulk_temperature(
    lubricant: Lubricant, bulk_temperature: ArrayLike, rolling_velocity: ArrayLike,
    load_per_length: ArrayLike, radius: ArrayLike, hertz_pressure: ArrayLike,
    slide_to_roll: ArrayLike, e_prime: float,
) -> Array | float:
    """The minimum film thickness with the oil's properties at the bulk temperature θ_M.

    Parameters
    ----------
    lubricant : friction.lubricant.Lubricant
        The oil (its viscosity, pressure–viscosity coefficient, temperature–viscosity
        coefficient and thermal conductivity against temperature).
    bulk_temperature : array_like — [degC]
        θ_M at each contact (ISO/TS 6336-20's θ_oil + 0.47 X_S X_mp θ_flm,
        :func:`contact.load_capacity.flash_temperature.bulk_temperature`), finite.
    rolling_velocity : array_like — [m/s]
        Entraining velocity u = (V₁ + V₂)/2 along the rolling direction, > 0.
    load_per_length : array_like — [N/mm]
    radius : array_like — [mm]
        Equivalent radius of curvature across the contact line.
    hertz_pressure : array_like — [MPa]
    slide_to_roll : array_like — [1]
        abs(V_s)/V_r, for Gupta's thermal factor.
    e_prime : float — [MPa]
        Effective modulus E′.

    Returns
    -------
    float or array — [µm]
        h_min (Dowson–Higginson, Gupta's thermal factor;
        :func:`friction.film.minimum_film_thickness`) with η, α, β and k of the oil at θ_M
        (broadcast shape).

    Raises
    ------
    InputError
        A non-finite bulk temperature or one outside the oil's data (naming the field),
        or a bad kinematic input (from :mod:`friction.film`).

    Notes
    -----
    ISO/TS 6336-22:2018 (Method B; ISO/TR 15144-1:2014 before it) evaluates the film at
    the bulk temperature θ_M; the formula here is the toolkit's film (module docstring),
    not ISO's h_Y.
    """
    theta = real_array("bulk_temperature", bulk_temperature, unit="degC")
    eta = np.asarray(viscosity(lubricant, theta), float)
    alpha = np.asarray(pressure_viscosity_coefficient(lubricant, theta), float)
    beta = np.asarray(temperature_viscosity_coefficient(lubricant, theta), float)
    k_oil = np.asarray(thermal_conductivity(lubricant, theta), float)
    loading = thermal_loading(beta, eta, rolling_velocity, k_oil)
    phi_t = thermal_reduction_factor(loading, hertz_pressure, e_prime, slide_to_roll)
    return _out(np.asarray(minimum_film_thickness(rolling_velocity, eta, alpha, load_per_length,
                                                  radius, e_prime, thermal_factor=phi_t),
                           float))


def specific_film_thickness(film_thickness: ArrayLike, roughness_1: ArrayLike,
                            roughness_2: ArrayLike, *, roughness: str = "rq") -> Array | float:
    """The specific film thickness λ_GF of ISO/TS 6336-22.

    Parameters
    ----------
    film_thickness : array_like — [µm]
        h, the film thickness, ≥ 0 (NaN passes: an unloaded segment).
    roughness_1, roughness_2 : array_like — [µm]
        Roughness of each flank, > 0.
    roughness : {"rq", "ra"}
        What ``roughness_1`` and ``roughness_2`` are: RMS Rq (default, the toolkit's
        input, converted by :func:`arithmetic_roughness`) or arithmetic Ra.

    Returns
    -------
    float or array — [1]
        λ_GF = h / Ra with Ra = (Ra₁ + Ra₂)/2 (broadcast shape).

    Raises
    ------
    InputError
        A negative film, a non-positive roughness, an unknown ``roughness`` kind or
        shapes that do not broadcast (naming the field).

    Notes
    -----
    ISO/TR 15144-1:2014 Formulae (2), (3) (ISO/TS 6336-22:2018).
    """
    one_of("roughness", roughness, ("rq", "ra"))
    h = _film(film_thickness)
    r1 = real_array("roughness_1", roughness_1, unit="um", low=0.0, low_open=True)
    r2 = real_array("roughness_2", roughness_2, unit="um", low=0.0, low_open=True)
    h, r1, r2 = broadcast(film_thickness=h, roughness_1=r1, roughness_2=r2)
    scale = GAUSSIAN_RA_PER_RQ if roughness == "rq" else 1.0
    ra = 0.5 * scale * (r1 + r2)
    return _out(h / ra)


def micropitting_safety(specific_film_min: ArrayLike,
                        permissible_specific_film: float) -> Array | float:
    """The safety factor against micropitting.

    Parameters
    ----------
    specific_film_min : array_like — [1]
        λ_GF,min, the least specific film thickness over the flank and the mesh, ≥ 0
        (NaN passes).
    permissible_specific_film : float — [1]
        λ_GFP of the oil, > 0.

    Returns
    -------
    float or array — [1]
        S_λ = λ_GF,min / λ_GFP.

    Raises
    ------
    InputError
        A negative λ_GF,min or a non-positive λ_GFP (naming the field).

    Notes
    -----
    ISO/TR 15144-1:2014 Formula (1) (ISO/TS 6336-22:2018); ISO/TS 6336-22 asks for
    S_λ ≥ S_λmin (its recommended minimum is left to the user; 1 is the limit).
    """
    lam = np.asarray(specific_film_min, dtype=float)
    finite = lam[np.isfinite(lam)]
    if np.any(finite < 0.0) or np.any(np.isinf(lam)):
        raise InputError("specific_film_min: must be finite and >= 0 [1], got "
                         f"{float(np.min(lam)):g}")
    perm = positive("permissible_specific_film", permissible_specific_film, "1")
    return _out(lam / perm)


def _film(value: ArrayLike) -> np.ndarray:
    """The film thickness [µm]: numbers ≥ 0, or NaN (an unloaded segment)."""
    try:
        kind = np.asarray(value).dtype.kind
    except (TypeError, ValueError):
        kind = "O"
    if isinstance(value, (bool, np.bool_)) or kind not in "fiu":
        raise InputError("film_thickness: must be real numbers, finite and >= 0 [um] (NaN "
                         f"where unloaded), got {value!r}")
    h = np.array(value, dtype=float)
    bad = np.isinf(h) | (h < 0.0)
    if np.any(bad):
        raise InputError(f"film_thickness: must be finite and >= 0 [um] (NaN where unloaded), "
                         f"got {int(bad.sum())} value(s) outside, e.g. {float(h[bad].flat[0])!r}")
    return h


def _out(value: np.ndarray) -> Array | float:
    arr = np.array(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr
