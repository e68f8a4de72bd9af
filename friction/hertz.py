"""Line-contact Hertz theory for the friction stage: combined modulus, half-width, peak pressure.

Each contact segment of the seed's efficiency model (seed section 5.2, "contacting
surfaces are approximated as two cylinders") is a Hertzian line contact of load per
unit length w′ between cylinders of equivalent radius R (seed: R_eq = R_p R_g/(R_p + R_g)).

Modulus convention (used by the whole ``friction`` package)
------------------------------------------------------------
The combined ("effective") modulus is

    E′ = 2 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂)

the convention of Dowson & Higginson and of Hamrock, in which the dimensionless EHL
groups U, G, W of :mod:`friction.film` and :mod:`friction.rolling` are written. It
is twice the contact modulus E* = 1/((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) of Johnson's
*Contact Mechanics*. Steel on steel (E = 206 GPa, ν = 0.3) gives E′ ≈ 226 GPa.

Units: lengths in mm, forces in N, load per length in N/mm, pressures and moduli in
MPa (N/mm²).

The compliance engineer's Weber deformation model lives in ``contact`` and is a
separate module; this one serves the friction models only.

This module also holds the small input-checking helpers used across the ``friction``
package (so a bad input is caught at the boundary with an :class:`InputError` naming
the field, never deep inside numpy).
"""

from __future__ import annotations

import logging
import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from geometry.errors import InputError

__all__ = ["combined_modulus", "half_width", "peak_pressure"]

log = logging.getLogger(__name__)


# ----------------------------------------------------------------------------- input checks
def as_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Return ``value`` as a float array; raise :class:`InputError` if it is not numeric."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(
            f"{name} must be a real number or array of real numbers; got {value!r}"
        ) from exc
    return arr


def checked(
    name: str,
    value: ArrayLike,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    high_open: bool = False,
    units: str = "",
) -> NDArray[np.float64]:
    """Return ``value`` as a float array after checking it is finite and inside a range.

    Raises
    ------
    InputError
        Naming ``name``, the accepted range (with ``units``) and the first offending value.
    """
    arr = as_array(name, value)
    lo = "-inf" if low is None else f"{low:g}"
    hi = "inf" if high is None else f"{high:g}"
    left = "(" if low is None or low_open else "["
    right = ")" if high is None or high_open else "]"
    rng = f"{left}{lo}, {hi}{right}"
    unit_txt = f" [{units}]" if units else ""
    bad = ~np.isfinite(arr)
    if low is not None:
        bad |= (arr <= low) if low_open else (arr < low)
    if high is not None:
        bad |= (arr >= high) if high_open else (arr > high)
    if np.any(bad):
        first = arr[bad].flat[0] if arr.ndim else float(arr)
        raise InputError(
            f"{name} must be finite and in {rng}{unit_txt}; got {first!r}"
            f" ({int(np.count_nonzero(bad))} of {arr.size} value(s) outside)"
        )
    return arr


def broadcast(**arrays: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
    """Broadcast named arrays together; raise :class:`InputError` listing shapes that clash."""
    try:
        return tuple(np.broadcast_arrays(*arrays.values()))
    except ValueError as exc:
        shapes = ", ".join(f"{k}{np.shape(v)}" for k, v in arrays.items())
        raise InputError(f"input shapes do not broadcast together: {shapes}") from exc


def result(arr: NDArray[np.float64]) -> NDArray[np.float64] | float:
    """Return a Python float for 0-d results, the array otherwise."""
    return float(arr) if np.ndim(arr) == 0 else arr


# ----------------------------------------------------------------------------- Hertz
def combined_modulus(
    youngs_modulus_1: ArrayLike,
    poisson_ratio_1: ArrayLike,
    youngs_modulus_2: ArrayLike,
    poisson_ratio_2: ArrayLike,
) -> NDArray[np.float64] | float:
    """Combined modulus E′ = 2 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) of two contacting bodies.

    Parameters
    ----------
    youngs_modulus_1, youngs_modulus_2 : float or array — [MPa]
        Young's moduli of the two bodies, in (0, inf).
    poisson_ratio_1, poisson_ratio_2 : float or array — [1]
        Poisson's ratios, in [0, 0.5).

    Returns
    -------
    float or array — [MPa]
        E′, the seed's E_eq ("equivalent module of elasticity", seed Eq. 5.10 text) in
        the Dowson–Higginson/Hamrock convention (twice Johnson's E*).

    Raises
    ------
    InputError
        If a modulus is not positive and finite or a Poisson's ratio is outside [0, 0.5).

    Notes
    -----
    Source: Hamrock, B. J., *Fundamentals of Fluid Film Lubrication*, NASA RP-1255
    (1991), "effective elastic modulus"; Dowson & Higginson (1966). Arrays broadcast.
    """
    e1 = checked("youngs_modulus_1", youngs_modulus_1, low=0.0, low_open=True, units="MPa")
    e2 = checked("youngs_modulus_2", youngs_modulus_2, low=0.0, low_open=True, units="MPa")
    n1 = checked("poisson_ratio_1", poisson_ratio_1, low=0.0, high=0.5, high_open=True, units="1")
    n2 = checked("poisson_ratio_2", poisson_ratio_2, low=0.0, high=0.5, high_open=True, units="1")
    e1, n1, e2, n2 = broadcast(
        youngs_modulus_1=e1, poisson_ratio_1=n1, youngs_modulus_2=e2, poisson_ratio_2=n2
    )
    return result(2.0 / ((1.0 - n1**2) / e1 + (1.0 - n2**2) / e2))


def _line_contact_inputs(
    load_per_length: ArrayLike, radius: ArrayLike, e_prime: ArrayLike
) -> tuple[NDArray[np.float64], ...]:
    w = checked("load_per_length", load_per_length, low=0.0, units="N/mm")
    r = checked("radius", radius, low=0.0, low_open=True, units="mm")
    e = checked("e_prime", e_prime, low=0.0, low_open=True, units="MPa")
    return broadcast(load_per_length=w, radius=r, e_prime=e)


def half_width(
    load_per_length: ArrayLike, radius: ArrayLike, e_prime: ArrayLike
) -> NDArray[np.float64] | float:
    """Hertz semi-width b = √(8 w′ R / (π E′)) of a line contact.

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        Normal load per unit contact length w′, in [0, inf).
    radius : float or array — [mm]
        Equivalent radius of curvature R (seed R_eq), in (0, inf).
    e_prime : float or array — [MPa]
        Combined modulus E′ (see :func:`combined_modulus` for the convention).

    Returns
    -------
    float or array — [mm]
        Half-width b of the contact band (broadcast shape of the inputs).

    Raises
    ------
    InputError
        If an input is negative (load) or non-positive (radius, modulus) or not finite.

    Notes
    -----
    Source: Johnson, K. L., *Contact Mechanics* (1985), §4.2 (Eq. 4.43 in the 1985
    edition): b² = 4 w′ R/(π E*), rewritten with E′ = 2E*. Hamrock (1991) gives the
    same form with E′.
    """
    w, r, e = _line_contact_inputs(load_per_length, radius, e_prime)
    return result(np.sqrt(8.0 * w * r / (math.pi * e)))


def peak_pressure(
    load_per_length: ArrayLike, radius: ArrayLike, e_prime: ArrayLike
) -> NDArray[np.float64] | float:
    """Maximum Hertz pressure p_h = 2 w′ / (π b) = √(w′ E′ / (2π R)) of a line contact.

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        Normal load per unit contact length w′, in [0, inf).
    radius : float or array — [mm]
        Equivalent radius of curvature R, in (0, inf).
    e_prime : float or array — [MPa]
        Combined modulus E′ (convention of :func:`combined_modulus`).

    Returns
    -------
    float or array — [MPa]
        Peak (centre) pressure of the elliptical Hertz distribution
        p(x) = p_h √(1 − x²/b²).

    Raises
    ------
    InputError
        As :func:`half_width`.

    Notes
    -----
    Source: Johnson (1985), §4.2 (Eqs. 4.44–4.45 in the 1985 edition): p₀ = 2P/(π a);
    the closed form avoids the 0/0 of 2 w′/(π b) at zero load (p_h = 0 there).
    """
    w, r, e = _line_contact_inputs(load_per_length, radius, e_prime)
    return result(np.sqrt(w * e / (2.0 * math.pi * r)))
