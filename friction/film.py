"""EHL film thickness of a line contact, thermal reduction, composite roughness and λ ratio.

Each contact segment of the seed's efficiency model (seed section 5.2) is a line
contact of equivalent radius R, load per length w′ and entraining (rolling) velocity
u = (u₁ + u₂)/2 (seed Eq. 5.6: V_r is the mean of the two surfaces' tangential
velocities across the contact line). The λ ratio of the seed (section 5.2.3: "ratio of
the smooth condition minimum film thickness to the RMS surface roughness value") selects
the friction regime.

Conventions (stated once, used by the whole ``friction`` package)
-----------------------------------------------------------------
* Effective modulus E′ = 2 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) = 2E*, the
  Dowson–Higginson / Hamrock convention in which the groups below are written; it is the
  seed's E_eq. E′ is used only here and in :mod:`friction.rolling`: compute it as
  ``2 * geometry.core.hertz.contact_modulus(E₁, ν₁, E₂, ν₂)`` (E* is the toolkit's one
  contact modulus, and the Hertz contact of a segment is
  :func:`geometry.core.hertz.hertz_line_contact` in E*).
* Dimensionless groups (Dowson & Higginson 1966; Hamrock 1991)::

      U = η₀ u / (E′ R)      speed parameter
      G = α E′               materials parameter
      W = w′ / (E′ R)        load parameter (per unit length)

  computed in SI at this module's boundary from the toolkit units: u [m/s],
  η₀ [Pa s], α [1/GPa], w′ [N/mm], R [mm], E′ [MPa].
* Film thickness and roughness are in µm (surface-finish scale): h = H · R.

Vectorised: every function broadcasts its array arguments (e.g. over segments).
"""

from __future__ import annotations

import logging
import warnings
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.validity import FrictionModelRangeWarning
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.validation import broadcast, real_array, scalar_or_array

__all__ = [
    "DOWSON_TOYODA_EXPONENTS",
    "FILM_THICKNESS_MODELS",
    "THERMAL_REDUCTION_MODELS",
    "EHLGroups",
    "composite_roughness",
    "dowson_higginson",
    "dowson_higginson_1966",
    "dowson_toyoda_central",
    "ehl_groups",
    "lambda_ratio",
    "minimum_film_thickness",
    "moes_central",
    "moes_film",
    "moes_load_parameter",
    "pan_hamrock",
    "thermal_loading",
    "thermal_reduction_factor",
]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]


class EHLGroups(NamedTuple):
    """Dimensionless EHL groups of a line contact (all [1]).

    Attributes
    ----------
    U : array — speed parameter η₀ u / (E′ R)
    G : array — materials parameter α E′
    W : array — load parameter w′ / (E′ R)
    """

    U: Array
    G: Array
    W: Array


def ehl_groups(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> EHLGroups:
    """Dimensionless speed, materials and load groups U, G, W of a line contact.

    Parameters
    ----------
    entraining_velocity : float or array — [m/s]
        Mean entraining (rolling) velocity u = (u₁ + u₂)/2 (seed V_r, Eq. 5.6), ≥ 0.
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity η₀ at ambient pressure, in (0, 100].
    pressure_viscosity : float or array — [1/GPa]
        Pressure–viscosity coefficient α, in [0.1, 100] (liquid lubricants lie far inside;
        the bounds catch α passed in 1/MPa or 1/Pa by mistake).
    load_per_length : float or array — [N/mm]
        Normal load per unit length w′, in (0, inf).
    radius : float or array — [mm]
        Equivalent radius R, in (0, inf).
    e_prime : float or array — [MPa]
        Effective modulus E′ = 2E* (module docstring convention), in (0, inf).

    Returns
    -------
    EHLGroups
        U, G, W arrays of the broadcast shape.

    Raises
    ------
    InputError
        An input outside its range (the message names it and the range).

    Notes
    -----
    Source: Dowson, D., Higginson, G. R., *Elasto-hydrodynamic Lubrication*, Pergamon
    (1966/1977); Hamrock (1991) NASA RP-1255, ch. 21. Seed Eq. 5.10 text uses the same
    U, G, W (U = η₀ V_r/(E_eq R_eq), G = α E_eq, W = f/(E_eq R_eq)). SI conversion:
    U = η₀ u / (E′·10⁶ · R·10⁻³), G = α·10⁻⁹ · E′·10⁶, W = w′/(E′ R) (N/mm over MPa·mm).
    """
    u = real_array("entraining_velocity", entraining_velocity, low=0.0, unit="m/s")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    alpha = real_array("pressure_viscosity", pressure_viscosity, low=0.1, high=100.0, unit="1/GPa")
    w = real_array("load_per_length", load_per_length, low=0.0, low_open=True, unit="N/mm")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    e = real_array("e_prime", e_prime, low=0.0, low_open=True, unit="MPa")
    u, eta, alpha, w, r, e = broadcast(
        entraining_velocity=u,
        viscosity=eta,
        pressure_viscosity=alpha,
        load_per_length=w,
        radius=r,
        e_prime=e,
    )
    speed = eta * u / (e * 1e6 * r * 1e-3)
    materials = alpha * 1e-9 * e * 1e6
    load = w / (e * r)
    return EHLGroups(speed, materials, load)


def _h_min(
    coef: float,
    exponents: tuple[float, float, float],
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """h_min = coef · U^pu · G^pg · W^pw · R, returned in µm."""
    g = ehl_groups(
        entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
    )
    pu, pg, pw = exponents
    r = np.broadcast_to(np.asarray(radius, dtype=float), g.U.shape)
    return scalar_or_array(coef * g.U**pu * g.G**pg * g.W**pw * r * 1e3)


def dowson_higginson(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Line-contact minimum film, Dowson & Higginson: h_min/R = 2.65 U^0.70 G^0.54 W^−0.13.

    Parameters
    ----------
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity u = (u₁ + u₂)/2, ≥ 0.
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity η₀, in (0, 100].
    pressure_viscosity : float or array — [1/GPa]
        Pressure–viscosity coefficient α, in [0.1, 100].
    load_per_length : float or array — [N/mm]
        Normal load per unit length w′, > 0.
    radius : float or array — [mm]
        Equivalent radius R, > 0.
    e_prime : float or array — [MPa]
        Effective modulus E′ = 2/Σ((1 − ν²)/E) = 2E*.

    Returns
    -------
    float or array — [µm]
        Isothermal minimum film thickness h_min (broadcast shape).

    Raises
    ------
    InputError
        An input outside its range (see :func:`ehl_groups`).

    Notes
    -----
    Source: Dowson, D., Higginson, G. R., *Elasto-hydrodynamic Lubrication*, SI ed.,
    Pergamon (1977); as quoted in seed/NOTES.md and Hamrock (1991) NASA RP-1255,
    ch. 21. Isothermal, smooth surfaces, fully flooded inlet.
    """
    return _h_min(
        2.65,
        (0.70, 0.54, -0.13),
        entraining_velocity,
        viscosity,
        pressure_viscosity,
        load_per_length,
        radius,
        e_prime,
    )


def dowson_higginson_1966(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Earlier Dowson–Higginson line-contact fit: h_min/R = 1.6 U^0.70 G^0.60 W^−0.13.

    Parameters
    ----------
    entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
        As :func:`dowson_higginson` ([m/s], [Pa s], [1/GPa], [N/mm], [mm], [MPa]).

    Returns
    -------
    float or array — [µm]
        Isothermal minimum film thickness h_min.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Dowson, D., Higginson, G. R., *Elasto-hydrodynamic Lubrication*, Pergamon
    (1966), the original minimum-film formula; the 1977 edition's 2.65 form
    (:func:`dowson_higginson`) supersedes it. Kept as an independent cross-check.
    """
    return _h_min(
        1.6,
        (0.70, 0.60, -0.13),
        entraining_velocity,
        viscosity,
        pressure_viscosity,
        load_per_length,
        radius,
        e_prime,
    )


def pan_hamrock(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Line-contact minimum film, Pan & Hamrock: h_min/R = 1.714 W^−0.128 U^0.694 G^0.568.

    Parameters
    ----------
    entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
        As :func:`dowson_higginson` ([m/s], [Pa s], [1/GPa], [N/mm], [mm], [MPa]).

    Returns
    -------
    float or array — [µm]
        Isothermal minimum film thickness h_min.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Pan, P., Hamrock, B. J., "Simple formulas for performance parameters used in
    elastohydrodynamically lubricated line contacts", J. Tribol. 111 (1989) 246–251,
    minimum film thickness formula (curve fit to numerical isothermal solutions), with
    the E′ convention of the module docstring.
    """
    return _h_min(
        1.714,
        (0.694, 0.568, -0.128),
        entraining_velocity,
        viscosity,
        pressure_viscosity,
        load_per_length,
        radius,
        e_prime,
    )


def dowson_toyoda_central(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Line-contact *central* film, Dowson & Toyoda: h_c/R = 3.06 U^0.69 G^0.56 W^−0.10.

    Parameters
    ----------
    entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
        As :func:`dowson_higginson` ([m/s], [Pa s], [1/GPa], [N/mm], [mm], [MPa]).

    Returns
    -------
    float or array — [µm]
        Isothermal central (plateau) film thickness h_c.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Dowson, D., Toyoda, S., "A central film thickness formula for
    elastohydrodynamic line contacts", Proc. 5th Leeds–Lyon Symposium on Tribology
    (1978, publ. 1979) 60–65; quoted with the groups of :func:`ehl_groups` (E′ = 2E*).
    The central film is the separation of the surfaces over the Hertz zone, the one the
    load-sharing model of :mod:`friction.mixed_ehl` compares with the roughness.
    """
    return _h_min(
        3.06,
        (0.69, 0.56, -0.10),
        entraining_velocity,
        viscosity,
        pressure_viscosity,
        load_per_length,
        radius,
        e_prime,
    )


def moes_central(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Line-contact *central* film of Moes, over the whole range of M and L.

    Parameters
    ----------
    entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
        As :func:`dowson_higginson` ([m/s], [Pa s], [1/GPa], [N/mm], [mm], [MPa]).

    Returns
    -------
    float or array — [µm]
        Isothermal central film thickness h_c.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Moes's dimensionless groups M = W(2U)^(−1/2), L = G(2U)^(1/4), H = (h_c/R)(2U)^(−1/2)
    (W, U, G of :func:`ehl_groups`, E′ = 2E*), and his interpolation between the four
    asymptotes (rigid–isoviscous, elastic–isoviscous, rigid–piezoviscous,
    elastic–piezoviscous):

        H = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s},
        s = 3/2 (1 + e^{−1.2 H_EI/H_RI}),
        H_RI = 3 M^{−1}, H_EI = 2.621 M^{−1/5}, H_RP = 1.287 L^{2/3},
        H_EP = 1.311 M^{−1/8} L^{3/4}.

    Source: Moes, H., "Optimum similarity analysis with applications to
    elastohydrodynamic lubrication", Wear 159 (1992) 57–66; as quoted by Venner, C. H.,
    Lubrecht, A. A., *Multilevel Methods in Lubrication*, Elsevier (2000), §2 (line
    contact). Checked against the toolkit's numerical smooth film (tests/test_ehl_stochastic.py).
    """
    g = ehl_groups(
        entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
    )
    r = np.broadcast_to(np.asarray(radius, dtype=float), g.U.shape)
    return scalar_or_array(moes_film(g.W, g.U, g.G) * r * 1e3)


def moes_film(load: ArrayLike, speed: ArrayLike, materials: ArrayLike) -> Array:
    """h_c/R of :func:`moes_central` from the groups W, U, G themselves [1] (no checks:
    the load-sharing model scales U and G beyond the ranges a physical input may take)."""
    two_u = 2.0 * np.asarray(speed, dtype=float)
    m = np.asarray(load, dtype=float) / np.sqrt(two_u)
    big_l = np.asarray(materials, dtype=float) * two_u**0.25
    h_ri = 3.0 / m
    h_ei = 2.621 * m ** (-0.2)
    h_rp = 1.287 * big_l ** (2.0 / 3.0)
    h_ep = 1.311 * m ** (-0.125) * big_l**0.75
    s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
    iso = (h_ri ** (7.0 / 3.0) + h_ei ** (7.0 / 3.0)) ** (3.0 * s / 7.0)
    piezo = (h_rp**-3.5 + h_ep**-3.5) ** (-2.0 * s / 7.0)
    return (iso + piezo) ** (1.0 / s) * np.sqrt(two_u)


def moes_load_parameter(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
) -> NDArray[np.float64] | float:
    """Moes's load parameter M = W(2U)^(−1/2) of a line contact [1] (inputs as
    :func:`ehl_groups`; α does not enter). Source: Moes (1992)."""
    g = ehl_groups(entraining_velocity, viscosity, 10.0, load_per_length, radius, e_prime)
    return scalar_or_array(g.W / np.sqrt(2.0 * g.U))


#: Exponents (p_U, p_G, p_W) of :func:`dowson_toyoda_central` (h_c ∝ U^p_U G^p_G W^p_W).
DOWSON_TOYODA_EXPONENTS: tuple[float, float, float] = (0.69, 0.56, -0.10)


#: Minimum film thickness formulas by name (all take the same physical inputs).
FILM_THICKNESS_MODELS: Mapping[str, Callable[..., NDArray[np.float64] | float]] = (
    MappingProxyType(
        {
            "dowson_higginson": dowson_higginson,
            "dowson_higginson_1966": dowson_higginson_1966,
            "pan_hamrock": pan_hamrock,
        }
    )
)


def minimum_film_thickness(
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    load_per_length: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
    *,
    model: str = "dowson_higginson",
    thermal_factor: ArrayLike = 1.0,
) -> NDArray[np.float64] | float:
    """Minimum film thickness by a named formula, times a thermal reduction factor.

    Parameters
    ----------
    entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime
        As :func:`dowson_higginson` ([m/s], [Pa s], [1/GPa], [N/mm], [mm], [MPa]).
    model : str
        A key of :data:`FILM_THICKNESS_MODELS`.
    thermal_factor : float or array — [1]
        φ_T in [0, 1] (see :func:`thermal_reduction_factor`); 1 is isothermal.

    Returns
    -------
    float or array — [µm]
        φ_T · h_min.

    Raises
    ------
    ModelUnavailableError
        Unknown ``model`` (the message lists the available ones).
    InputError
        An input outside its range.

    Notes
    -----
    Source: the chosen formula's reference; the thermal factor multiplies the isothermal
    film (Gupta et al. 1992; Murch & Wilson 1975).
    """
    try:
        fn = FILM_THICKNESS_MODELS[model]
    except KeyError:
        raise ModelUnavailableError(
            f"unknown film thickness model {model!r}; available: {sorted(FILM_THICKNESS_MODELS)}"
        ) from None
    phi = real_array("thermal_factor", thermal_factor, low=0.0, high=1.0, unit="1")
    h = np.asarray(
        fn(entraining_velocity, viscosity, pressure_viscosity, load_per_length, radius, e_prime)
    )
    h, phi = broadcast(film_thickness=h, thermal_factor=phi)
    return scalar_or_array(h * phi)


# ----------------------------------------------------------------------------- thermal
def thermal_loading(
    temperature_viscosity_coefficient: ArrayLike,
    viscosity: ArrayLike,
    entraining_velocity: ArrayLike,
    thermal_conductivity: ArrayLike,
) -> NDArray[np.float64] | float:
    """Thermal loading factor L = β η₀ u² / k of the inlet zone.

    Parameters
    ----------
    temperature_viscosity_coefficient : float or array — [1/K]
        β = −(1/η₀) dη₀/dT, ≥ 0 (e.g. :func:`friction.lubricant.temperature_viscosity_coefficient`).
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity η₀, in (0, 100].
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity u = (u₁ + u₂)/2, ≥ 0.
    thermal_conductivity : float or array — [W/(m K)]
        Lubricant thermal conductivity k, > 0.

    Returns
    -------
    float or array — [1]
        L (SI throughout: (1/K)(Pa s)(m²/s²)/(W/(m K)) is dimensionless).

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Murch & Wilson (1975); Gupta et al. (1992) write L = (−∂η/∂T) u²/k, which is
    β η₀ u²/k with β as above.
    """
    beta = real_array("temperature_viscosity_coefficient", temperature_viscosity_coefficient,
                    low=0.0, unit="1/K")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    u = real_array("entraining_velocity", entraining_velocity, low=0.0, unit="m/s")
    k = real_array("thermal_conductivity", thermal_conductivity, low=0.0, low_open=True,
                 unit="W/(m K)")
    beta, eta, u, k = broadcast(
        temperature_viscosity_coefficient=beta,
        viscosity=eta,
        entraining_velocity=u,
        thermal_conductivity=k,
    )
    return scalar_or_array(beta * eta * u**2 / k)


def _gupta1992(
    thermal_loading: Array,
    hertz_pressure: Array | None,
    e_prime: Array | None,
    slide_to_roll: Array | None,
) -> Array:
    missing = [
        name
        for name, val in (
            ("hertz_pressure", hertz_pressure),
            ("e_prime", e_prime),
            ("slide_to_roll", slide_to_roll),
        )
        if val is None
    ]
    if missing:
        raise InputError(f"thermal_reduction_factor model 'gupta1992' needs {missing}")
    numerator = 1.0 - 13.2 * (hertz_pressure / e_prime) * thermal_loading**0.42
    denominator = 1.0 + 0.213 * (1.0 + 2.23 * np.abs(slide_to_roll) ** 0.83) * thermal_loading**0.64
    if np.any(numerator <= 0.0):
        warnings.warn(
            "thermal_reduction_factor (gupta1992): 1 − 13.2 (p_h/E′) L^0.42 ≤ 0 at"
            f" {int(np.count_nonzero(numerator <= 0))} point(s) — the correlation is outside its"
            " range (extreme thermal loading); φ_T clipped to 0 there",
            FrictionModelRangeWarning,
            stacklevel=3,
        )
    return np.clip(numerator, 0.0, None) / denominator


def _murch_wilson1975(
    thermal_loading: Array,
    hertz_pressure: Array | None,
    e_prime: Array | None,
    slide_to_roll: Array | None,
) -> Array:
    del hertz_pressure, e_prime, slide_to_roll  # the 1975 correlation depends on L only
    return 3.94 / (3.94 + thermal_loading**0.62)


#: Thermal reduction factor correlations by name: (L, p_h, E′, SR) -> φ_T.
THERMAL_REDUCTION_MODELS: Mapping[str, Callable[..., Array]] = (
    MappingProxyType({"gupta1992": _gupta1992, "murch_wilson1975": _murch_wilson1975})
)


def thermal_reduction_factor(
    thermal_loading: ArrayLike,
    hertz_pressure: ArrayLike | None = None,
    e_prime: ArrayLike | None = None,
    slide_to_roll: ArrayLike | None = None,
    *,
    model: str = "gupta1992",
) -> NDArray[np.float64] | float:
    """Thermal reduction factor φ_T ∈ [0, 1] of film thickness (and rolling traction).

    ``"gupta1992"`` (default)::

        φ_T = (1 − 13.2 (p_h/E′) L^0.42) / (1 + 0.213 (1 + 2.23 |SR|^0.83) L^0.64)

    ``"murch_wilson1975"``::

        φ_T = 3.94 / (3.94 + L^0.62)

    Parameters
    ----------
    thermal_loading : float or array — [1]
        L of :func:`thermal_loading`, ≥ 0.
    hertz_pressure : float or array — [MPa], optional
        Peak Hertz pressure p_h, ≥ 0 (required by gupta1992, ignored by murch_wilson1975).
    e_prime : float or array — [MPa], optional
        Effective modulus E′ = 2E*, > 0 (required by gupta1992).
    slide_to_roll : float or array — [1], optional
        SR = (u₁ − u₂)/u with u the mean entraining velocity; its magnitude is used
        (required by gupta1992).
    model : {"gupta1992", "murch_wilson1975"}

    Returns
    -------
    float or array — [1]
        φ_T, broadcast shape.

    Raises
    ------
    InputError
        An input outside its range, or one the model needs is missing.
    ModelUnavailableError
        Unknown ``model``.

    Warns
    -----
    FrictionModelRangeWarning
        gupta1992 numerator ≤ 0 (thermal loading beyond the correlation); clipped to 0.

    Notes
    -----
    Sources: Gupta, P. K., Cheng, H. S., Zhu, D., Forster, N. H., Schrand, J. B.,
    "Viscoelastic effects in MIL-L-7808-type lubricant, Part I: analytical formulation",
    Tribol. Trans. 35 (1992) 269–274 (the form gear-efficiency models after Xu et al.
    2007 use with the Goksem–Hargreaves correlation); Murch,
    L. E., Wilson, W. R. D., "A thermal elastohydrodynamic inlet zone analysis",
    J. Lubr. Technol. 97 (1975) 212–216. Reconstruction: the seed cites a thermal
    correction factor for Eq. 5.10 (refs. [5.31], [5.35]) without printing it; which
    correlation those references used is not recoverable from the extraction, so the
    choice is exposed here by name. The E′ in p_h/E′ is taken as 2E* (module docstring).
    """
    try:
        fn = THERMAL_REDUCTION_MODELS[model]
    except KeyError:
        raise ModelUnavailableError(
            f"unknown thermal reduction model {model!r}; available:"
            f" {sorted(THERMAL_REDUCTION_MODELS)}"
        ) from None
    arrays = {"thermal_loading": real_array("thermal_loading", thermal_loading, low=0.0, unit="1")}
    if hertz_pressure is not None:
        arrays["hertz_pressure"] = real_array("hertz_pressure", hertz_pressure, low=0.0, unit="MPa")
    if e_prime is not None:
        arrays["e_prime"] = real_array("e_prime", e_prime, low=0.0, low_open=True, unit="MPa")
    if slide_to_roll is not None:
        arrays["slide_to_roll"] = real_array("slide_to_roll", slide_to_roll, unit="1")
    full = dict(zip(arrays, broadcast(**arrays), strict=True))
    return scalar_or_array(
        fn(
            full["thermal_loading"],
            full.get("hertz_pressure"),
            full.get("e_prime"),
            full.get("slide_to_roll"),
        )
    )


# ----------------------------------------------------------------------------- roughness
def composite_roughness(
    roughness_1: ArrayLike, roughness_2: ArrayLike
) -> NDArray[np.float64] | float:
    """Composite RMS roughness σ = √(Rq₁² + Rq₂²).

    Parameters
    ----------
    roughness_1, roughness_2 : float or array — [µm]
        RMS roughness Rq of each surface, ≥ 0.

    Returns
    -------
    float or array — [µm]

    Raises
    ------
    InputError
        Negative or non-finite roughness.

    Notes
    -----
    Source: seed section 5.2.3 (S_c = √(Rq₁² + Rq₂²)); Hamrock (1991) ch. 23.
    """
    r1 = real_array("roughness_1", roughness_1, low=0.0, unit="µm")
    r2 = real_array("roughness_2", roughness_2, low=0.0, unit="µm")
    r1, r2 = broadcast(roughness_1=r1, roughness_2=r2)
    return scalar_or_array(np.hypot(r1, r2))


def lambda_ratio(
    film_thickness: ArrayLike, composite_roughness: ArrayLike
) -> NDArray[np.float64] | float:
    """Film parameter λ = h_min / σ.

    Parameters
    ----------
    film_thickness : float or array — [µm]
        (Smooth-surface) minimum film thickness, ≥ 0.
    composite_roughness : float or array — [µm]
        σ of :func:`composite_roughness`, > 0.

    Returns
    -------
    float or array — [1]

    Raises
    ------
    InputError
        Negative film thickness or non-positive roughness (λ would be undefined).

    Notes
    -----
    Source: seed section 5.2.3 ("ratio of the smooth condition minimum film thickness
    to the RMS surface roughness value"); regimes λ < 1, 1–3, > 3 (seed Eq. 5.11a–c).
    """
    h = real_array("film_thickness", film_thickness, low=0.0, unit="µm")
    s = real_array("composite_roughness", composite_roughness, low=0.0, low_open=True, unit="µm")
    h, s = broadcast(film_thickness=h, composite_roughness=s)
    return scalar_or_array(h / s)

