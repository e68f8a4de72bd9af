"""Hertz line contact: the one contact modulus and the one half-width and peak pressure.

Every stage that needs the Hertz contact of a line (the LTCA's pressures and Weber's
contact compliance in ``contact``, the EHL film and rolling loss in ``friction``, the
half-space references of the solver study) takes it from here, in one modulus
convention:

* **contact modulus** E* of Johnson (*Contact Mechanics*, 1985, Eq. 4.22):
  1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂. Steel on steel (206 000 MPa, ν = 0.3) gives
  E* = 113 187 MPa. (The EHL literature's E′ = 2E*, Dowson & Higginson's "effective
  modulus", appears only inside :mod:`friction.film` and :mod:`friction.rolling`, where
  their dimensionless groups are written in it.)
* **line contact** of load per length w′ between cylinders of equivalent radius
  R = R₁R₂/(R₁ + R₂) (seed Eq. 2.13's R_eq): half-width b = √(4 w′ R / (π E*)) and peak
  pressure p₀ = 2 w′ / (π b) (Johnson Eq. 4.43–4.45), p₀ = 0 at no load.

Units: mm, N, N/mm, MPa.

Public functions
----------------
STEEL               (E [MPa], ν [1]) of the steel both members are made of by default
contact_modulus     E* of two bodies [MPa]
HertzLineContact    half-width and peak pressure of a line contact
hertz_line_contact  compute them
hertz_line_load     the load per length at which a line contact reaches a peak pressure

References
----------
K. L. Johnson (1985). *Contact Mechanics.* Cambridge University Press, §4.2 and Eq. 4.22.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from geometry.core.validation import broadcast, real, real_array

__all__ = ["STEEL", "HertzLineContact", "contact_modulus", "hertz_line_contact",
           "hertz_line_contact_of_checked", "hertz_line_load"]

#: Young's modulus [MPa] and Poisson's ratio [1] of case-hardened gear steel: the default
#: material of both members everywhere in the toolkit
STEEL: tuple[float, float] = (206_000.0, 0.3)


def contact_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Contact modulus E* = 1 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) of two elastic bodies.

    Parameters
    ----------
    e1, e2 : float — [MPa]
        Young's moduli, finite and > 0.
    nu1, nu2 : float — [1]
        Poisson's ratios, in [0, 0.5).

    Returns
    -------
    float — [MPa]

    Raises
    ------
    InputError
        A modulus not finite and positive or a Poisson's ratio outside [0, 0.5) (the
        message names ``e1``, ``nu1``, ``e2`` or ``nu2``).

    Notes
    -----
    Johnson (1985) Eq. 4.22.
    """
    e1 = real("e1", e1, unit="MPa", low=0.0, low_open=True)
    nu1 = real("nu1", nu1, unit="1", low=0.0, high=0.5, high_open=True)
    e2 = real("e2", e2, unit="MPa", low=0.0, low_open=True)
    nu2 = real("nu2", nu2, unit="1", low=0.0, high=0.5, high_open=True)
    return 1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)


class HertzLineContact(NamedTuple):
    """Hertz contact of a line (arrays broadcast from the inputs)."""

    half_width: np.ndarray  # [mm] b
    peak_pressure: np.ndarray  # [MPa] p₀ (0 where the load is 0)


def hertz_line_contact(load_per_length, radius, modulus) -> HertzLineContact:
    """Half-width and peak pressure of a Hertz line contact (Johnson Eq. 4.43–4.45).

    Parameters
    ----------
    load_per_length : float or ndarray — [N/mm]
        w′ ≥ 0.
    radius : float or ndarray — [mm]
        Equivalent radius R = R₁R₂/(R₁ + R₂) > 0 (seed Eq. 2.13).
    modulus : float or ndarray — [MPa]
        Contact modulus E* (:func:`contact_modulus`), > 0 (usually one value).

    Returns
    -------
    HertzLineContact
        ``half_width`` b = √(4 w′ R / (π E*)) [mm] and ``peak_pressure``
        p₀ = 2 w′ / (π b) = √(w′ E* / (π R)) [MPa], p₀ = 0 where w′ = 0; arrays of the
        broadcast shape of the inputs.

    Raises
    ------
    InputError
        A negative or non-finite load, a radius or modulus not finite and positive, or
        shapes that do not broadcast (the message names the fields).

    Notes
    -----
    Johnson (1985) Eq. 4.43 (b) and 4.44–4.45 (p₀ = 2P/(πb)); the peak pressure is
    computed from b so that b and p₀ carry the load w′ = π b p₀ / 2 to rounding.
    """
    w = real_array("load_per_length", load_per_length, unit="N/mm", low=0.0)
    r = real_array("radius", radius, unit="mm", low=0.0, low_open=True)
    e_star = real_array("modulus", modulus, unit="MPa", low=0.0, low_open=True)
    w, r, e_star = broadcast(load_per_length=w, radius=r, modulus=e_star)
    return hertz_line_contact_of_checked(w, r, e_star)


def hertz_line_contact_of_checked(load_per_length: np.ndarray, radius: np.ndarray,
                                  modulus) -> HertzLineContact:
    """:func:`hertz_line_contact` of inputs the caller has checked: the same arithmetic
    (the same numbers to the bit), without checking them again — for the LTCA, which
    records the Hertz contact of every roll's solved loads (a load per length ≥ 0 and
    radii > 0 of its own; issue 75).

    Parameters
    ----------
    load_per_length : ndarray — [N/mm] w′ ≥ 0, finite
    radius : ndarray — [mm] R > 0, finite, the shape of ``load_per_length``
    modulus : float or ndarray — [MPa] E* > 0, finite (one value, or that shape)

    Returns
    -------
    HertzLineContact — as :func:`hertz_line_contact` (Johnson 1985, Eq. 4.43–4.45)
    """
    b = np.sqrt(4.0 * load_per_length * radius / (math.pi * modulus))
    with np.errstate(divide="ignore", invalid="ignore"):
        p0 = np.where(b > 0.0, 2.0 * load_per_length / (math.pi * np.where(b > 0.0, b, 1.0)),
                      0.0)
    return HertzLineContact(b, p0)


def hertz_line_load(peak_pressure, radius, modulus) -> np.ndarray:
    """Load per length at which a Hertz line contact reaches a given peak pressure.

    The inverse of :func:`hertz_line_contact`'s p₀(w′): w′ = π R p₀² / E*.

    Parameters
    ----------
    peak_pressure : float or ndarray — [MPa]
        p₀ ≥ 0.
    radius : float or ndarray — [mm]
        Equivalent radius R > 0 (seed Eq. 2.13).
    modulus : float or ndarray — [MPa]
        Contact modulus E* > 0 (:func:`contact_modulus`).

    Returns
    -------
    ndarray — [N/mm]
        w′ of the broadcast shape of the inputs.

    Raises
    ------
    InputError
        A negative or non-finite pressure, a radius or modulus not finite and positive, or
        shapes that do not broadcast (the message names the fields).

    Notes
    -----
    Johnson (1985) Eq. 4.43–4.45: p₀ = √(w′ E*/(π R)).
    """
    p0 = real_array("peak_pressure", peak_pressure, unit="MPa", low=0.0)
    r = real_array("radius", radius, unit="mm", low=0.0, low_open=True)
    e_star = real_array("modulus", modulus, unit="MPa", low=0.0, low_open=True)
    p0, r, e_star = broadcast(peak_pressure=p0, radius=r, modulus=e_star)
    return math.pi * r * p0 * p0 / e_star
