"""Deprecated: the friction stage's Hertz line contact in E′, now :mod:`geometry.core.hertz`.

The toolkit has one Hertz line contact in one modulus convention,
:func:`geometry.core.hertz.hertz_line_contact` with Johnson's contact modulus
E* (:func:`geometry.core.hertz.contact_modulus`). The three functions here took the EHL
literature's effective modulus E′ = 2E* (Dowson & Higginson; Hamrock) instead; they are
kept for one release as thin wrappers over :mod:`geometry.core.hertz` and warn with a
:class:`DeprecationWarning` naming the replacement:

=====================================  ==================================================
deprecated                             replacement
=====================================  ==================================================
``combined_modulus(E1, ν1, E2, ν2)``   ``2 * geometry.core.hertz.contact_modulus(E1, ν1, E2, ν2)``
``half_width(w′, R, E′)``              ``hertz_line_contact(w′, R, E′ / 2).half_width``
``peak_pressure(w′, R, E′)``           ``hertz_line_contact(w′, R, E′ / 2).peak_pressure``
=====================================  ==================================================

E′ remains only where the EHL formulas are written in it (:mod:`friction.film`,
:mod:`friction.rolling`). Units: mm, N, N/mm, MPa. The input checks that used to live
here are :mod:`geometry.core.validation`'s.
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from geometry.core.hertz import contact_modulus, hertz_line_contact
from geometry.core.validation import broadcast, real_array, scalar_or_array

__all__ = ["combined_modulus", "half_width", "peak_pressure"]


def _deprecated(old: str, new: str, stacklevel: int = 3) -> None:
    """Warn that ``old`` goes, naming ``new``, at the caller of the public function."""
    warnings.warn(f"friction.hertz.{old} is deprecated and will be removed in the next "
                  f"release; use {new}", DeprecationWarning, stacklevel=stacklevel)


def combined_modulus(
    youngs_modulus_1: ArrayLike,
    poisson_ratio_1: ArrayLike,
    youngs_modulus_2: ArrayLike,
    poisson_ratio_2: ArrayLike,
) -> NDArray[np.float64] | float:
    """Deprecated: E′ = 2 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) = 2 E*; use ``2 * contact_modulus``.

    Parameters
    ----------
    youngs_modulus_1, youngs_modulus_2 : float or array — [MPa]
        Young's moduli of the two bodies, finite and > 0.
    poisson_ratio_1, poisson_ratio_2 : float or array — [1]
        Poisson's ratios, in [0, 0.5).

    Returns
    -------
    float or array — [MPa]
        E′ = 2 :func:`geometry.core.hertz.contact_modulus` (arrays broadcast).

    Raises
    ------
    InputError
        A modulus not finite and positive or a Poisson's ratio outside [0, 0.5) (the
        message names the argument).

    Warns
    -----
    DeprecationWarning
        Always: use ``2 * geometry.core.hertz.contact_modulus(e1, nu1, e2, nu2)``.

    Notes
    -----
    Source: Hamrock, B. J., *Fundamentals of Fluid Film Lubrication*, NASA RP-1255
    (1991), "effective elastic modulus"; Johnson (1985) Eq. 4.22 for E*.
    """
    _deprecated("combined_modulus", "2 * geometry.core.hertz.contact_modulus(e1, nu1, e2, nu2)")
    e1 = real_array("youngs_modulus_1", youngs_modulus_1, unit="MPa", low=0.0, low_open=True)
    n1 = real_array("poisson_ratio_1", poisson_ratio_1, unit="1", low=0.0, high=0.5,
                    high_open=True)
    e2 = real_array("youngs_modulus_2", youngs_modulus_2, unit="MPa", low=0.0, low_open=True)
    n2 = real_array("poisson_ratio_2", poisson_ratio_2, unit="1", low=0.0, high=0.5,
                    high_open=True)
    e1, n1, e2, n2 = broadcast(youngs_modulus_1=e1, poisson_ratio_1=n1,
                               youngs_modulus_2=e2, poisson_ratio_2=n2)
    if e1.ndim == 0:
        return 2.0 * contact_modulus(float(e1), float(n1), float(e2), float(n2))
    return np.vectorize(contact_modulus, otypes=[float])(e1, n1, e2, n2) * 2.0


def _line_contact(name: str, load_per_length, radius, e_prime):
    _deprecated(name, f"geometry.core.hertz.hertz_line_contact(w, R, E*).{name} with "
                      "E* = E′/2 = geometry.core.hertz.contact_modulus(...)", stacklevel=4)
    e = real_array("e_prime", e_prime, unit="MPa", low=0.0, low_open=True)
    return hertz_line_contact(load_per_length, radius, e / 2.0)


def half_width(
    load_per_length: ArrayLike, radius: ArrayLike, e_prime: ArrayLike
) -> NDArray[np.float64] | float:
    """Deprecated: Hertz half-width b = √(8 w′ R / (π E′)); use ``hertz_line_contact``.

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        Normal load per unit contact length w′, ≥ 0.
    radius : float or array — [mm]
        Equivalent radius of curvature R (seed R_eq), > 0.
    e_prime : float or array — [MPa]
        Effective modulus E′ = 2E*, > 0.

    Returns
    -------
    float or array — [mm]
        ``geometry.core.hertz.hertz_line_contact(w′, R, E′/2).half_width``.

    Raises
    ------
    InputError
        A negative load, a radius or modulus not finite and positive (named).

    Warns
    -----
    DeprecationWarning
        Always.

    Notes
    -----
    Source: Johnson (1985) Eq. 4.43, b² = 4 w′ R/(π E*).
    """
    return scalar_or_array(_line_contact("half_width", load_per_length, radius,
                                         e_prime).half_width)


def peak_pressure(
    load_per_length: ArrayLike, radius: ArrayLike, e_prime: ArrayLike
) -> NDArray[np.float64] | float:
    """Deprecated: peak Hertz pressure p_h = 2 w′/(π b); use ``hertz_line_contact``.

    Parameters
    ----------
    load_per_length, radius, e_prime
        As :func:`half_width` ([N/mm], [mm], [MPa], E′ = 2E*).

    Returns
    -------
    float or array — [MPa]
        ``geometry.core.hertz.hertz_line_contact(w′, R, E′/2).peak_pressure`` (0 at no load).

    Raises
    ------
    InputError
        As :func:`half_width`.

    Warns
    -----
    DeprecationWarning
        Always.

    Notes
    -----
    Source: Johnson (1985) Eqs. 4.44–4.45, p₀ = 2P/(πb) = √(w′E′/(2πR)).
    """
    return scalar_or_array(_line_contact("peak_pressure", load_per_length, radius,
                                         e_prime).peak_pressure)
