"""Sliding friction coefficient models, chosen by name from a registry.

The seed (section 5.2.2–5.2.3) computes the sliding friction coefficient μ of each
contact segment from a regression to mixed-EHL simulations (seed Eq. 5.11). This module
offers that family of models behind one interface::

    >>> from friction.coefficient import available_friction_models, friction_coefficient
    >>> available_friction_models()
    ('benedict_kelley', 'constant', 'iso_tr_14179_2', 'kolivand2009', 'mixed_ehl', 'xu2007')
    >>> mu = friction_coefficient("xu2007", hertz_pressure=1000.0, slide_to_roll=0.5,
    ...                           entraining_velocity=10.0, viscosity=0.0163, radius=20.0,
    ...                           roughness_1=0.8, roughness_2=0.8)
    >>> round(mu, 3)
    0.029

Every model takes keyword inputs from one vocabulary (:data:`STANDARD_INPUTS`, in the
toolkit's units), so a pipeline can hand all segment quantities to whichever model the
user names; :func:`friction_coefficient` passes each model the inputs it uses, refuses a
name outside the vocabulary (a typo), and broadcasts the result to the inputs' shape.

Each model validates its inputs (:class:`InputError` naming the field), warns with
:class:`FrictionModelRangeWarning` where inputs leave the range the model was fitted on,
and never returns NaN: where a formula breaks down the value is clipped and the warning
says so.

The registry is open: :func:`register_friction_model` adds a user's model under a name
(checked as the bundled models are: keyword inputs, required ones from the vocabulary),
installed plug-ins add theirs through the entry-point group :data:`ENTRY_POINT_GROUP`, and
wherever a model is chosen by name a :class:`FrictionModel` or a plain model function is
accepted too (docs/extending.md). The default model's name is
:data:`friction.defaults.DEFAULT_FRICTION_MODEL`.

``kolivand2009`` is the seed's Eq. 5.11 *derived again*: its structure fitted to the
toolkit's mixed-EHL solver over Table 5.1's conditions (:mod:`friction.kolivand2009`,
:mod:`friction.study`). The seed's own Table 5.3 reading of Eq. 5.11,
``kolivand2009_table_5_3``, is registered as *unavailable*: asking for it raises
:class:`ModelUnavailableError` quoting :data:`UNAVAILABLE_MODELS`.
"""

from __future__ import annotations

import logging
import math
import re
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.defaults import DEFAULT_FRICTION_MODEL
from friction.kolivand2009 import kolivand2009, kolivand2009_validity
from friction.mixed_ehl import mixed_ehl, mixed_ehl_validity
from friction.thermal_eyring import thermal_eyring
from friction.validity import FrictionModelRangeWarning
from geometry.core.caches import memoised
from geometry.core.errors import (
    InputError,
    LTCAError,
    PluginError,
    UnknownNameError,
)
from geometry.core.registries import (
    callable_name,
    check_model_name,
    entry_point_objects,
    keyword_parameters,
)
from geometry.core.validation import broadcast, real_array, scalar_or_array

__all__ = [
    "DEFAULT_FRICTION_MODEL",
    "ENTRY_POINT_GROUP",
    "ISO_TR_14179_2_RANGE",
    "MU_CAP",
    "MU_MAX",
    "STANDARD_INPUTS",
    "UNAVAILABLE_MODELS",
    "XU2007_COEFFICIENTS",
    "FrictionModel",
    "FrictionModelLike",
    "FrictionModelRangeWarning",
    "as_friction_model",
    "available_friction_models",
    "benedict_kelley",
    "constant",
    "friction_coefficient",
    "friction_model_name",
    "friction_model_validity",
    "get_friction_model",
    "is_mu_above_cap",
    "iso_tr_14179_2",
    "register_friction_model",
    "unavailable_friction_models",
    "unregister_friction_model",
    "xu2007",
]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]


#: The input vocabulary shared by all friction models: name → "[units] meaning".
STANDARD_INPUTS: Mapping[str, str] = MappingProxyType(
    {
        "hertz_pressure": "[MPa] peak Hertz pressure p_h of the segment"
                          " (geometry.core.hertz.hertz_line_contact)",
        "slide_to_roll": "[1] SR = V_s / V_e (sign ignored by the models)",
        "entraining_velocity": "[m/s] mean entraining (rolling) velocity V_e = (u1 + u2)/2",
        "sliding_velocity": "[m/s] sliding velocity V_s = |u1 - u2|",
        "load_per_length": "[N/mm] normal load per unit length w'",
        "viscosity": "[Pa s] inlet dynamic viscosity at ambient pressure",
        "radius": "[mm] equivalent radius of curvature R",
        "roughness_1": "[µm] RMS roughness Rq of surface 1",
        "roughness_2": "[µm] RMS roughness Rq of surface 2",
        "lambda_ratio": "[1] film parameter h_min / sigma",
        "pressure_viscosity": "[1/GPa] pressure-viscosity coefficient",
        "e_prime": "[MPa] effective modulus E' = 2 E* (EHL convention; E* of"
                   " geometry.core.hertz.contact_modulus)",
        "temperature": "[degC] inlet oil temperature",
        "thermal_factor": "[1] thermal reduction factor φ_T of the film thickness"
                          " (friction.film.thermal_reduction_factor)",
        "temperature_viscosity": "[1/K] the oil's temperature-viscosity coefficient β at"
                                 " the inlet temperature"
                                 " (friction.lubricant.temperature_viscosity_coefficient)",
        "oil_thermal_conductivity": "[W/(m K)] the oil's thermal conductivity at the inlet"
                                    " temperature",
        "pressure_viscosity_temperature": "[1/K] −d ln α/dT of the oil at the inlet"
                                          " temperature (α's fall with temperature)",
    }
)


def _warn_outside(model: str, name: str, values: Array, low: float, high: float, units: str):
    outside = (values < low) | (values > high)
    n = int(np.count_nonzero(outside))
    if n:
        warnings.warn(
            f"{model}: {name} outside the fitted range [{low:g}, {high:g}] [{units}] at {n} of"
            f" {values.size} point(s) (e.g. {values[outside].flat[0]:g}); result extrapolated",
            FrictionModelRangeWarning,
            stacklevel=3,
        )


#: Upper clip of every regression: no lubricated steel contact reaches it, so a larger
#: value means the formula is far outside its fitted range (a warning says so).
MU_CAP = 0.3


#: Hard upper bound of any model's μ, bundled or a user's (:func:`friction_coefficient`
#: refuses above it, warns above :data:`MU_CAP`): above the static coefficient of clean,
#: dry steel on steel, ~0.74-0.8, and its kinetic ~0.42-0.57 (Bowden & Tabor, *The
#: Friction and Lubrication of Solids*, 1950; Rabinowicz, *Friction and Wear of
#: Materials*, 2nd ed. 1995, ch. 4); lubricated gear contacts run at 0.01-0.1 and in
#: boundary lubrication at 0.1-0.15 (ISO/TR 14179-2:2001; Xu et al. 2007). A μ above 1 is
#: a unit or definition error (a percentage, a friction force), never a gear contact's.
#: The same bound as the ``constant`` model's ``value``.
MU_MAX = 1.0


def _cap(model: str, mu: Array) -> Array:
    over = ~(mu <= MU_CAP)  # also catches inf
    if np.any(over):
        warnings.warn(
            f"{model}: μ above {MU_CAP} (or overflowing) at {int(np.count_nonzero(over))}"
            " point(s) — inputs far outside the fitted range; μ clipped to"
            f" {MU_CAP} there",
            FrictionModelRangeWarning,
            stacklevel=3,
        )
    return np.where(over, MU_CAP, mu)


# ----------------------------------------------------------------------------- xu2007
#: b1 … b9 of Xu, Kahraman, Anderson & Maddock (2007), Eq. for μ (seed/NOTES.md).
XU2007_COEFFICIENTS: tuple[float, ...] = (
    -8.916465,
    1.03303,
    1.036077,
    -0.354068,
    2.812084,
    -0.100601,
    0.752755,
    -0.390958,
    0.620305,
)

#: Fitted ranges used for the xu2007 warnings: (low, high, units) in toolkit units.
XU2007_RANGE: Mapping[str, tuple[float, float, str]] = MappingProxyType(
    {
        "hertz_pressure": (500.0, 2500.0, "MPa"),
        "slide_to_roll": (0.025, 1.0, "1"),
        "entraining_velocity": (1.0, 20.0, "m/s"),
        "viscosity": (0.0106, 0.1626, "Pa s"),
        "radius": (5.0, 40.0, "mm"),
        "roughness": (0.1, 1.0, "µm"),
    }
)


def xu2007(
    *,
    hertz_pressure: ArrayLike,
    slide_to_roll: ArrayLike,
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    radius: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
    coefficients: tuple[float, ...] = XU2007_COEFFICIENTS,
) -> NDArray[np.float64] | float:
    """Mixed-EHL regression friction coefficient of Xu, Kahraman, Anderson & Maddock (2007).

    μ = e^f · P_h^b2 · |SR|^b3 · V_e^b6 · ν₀^b7 · R^b8, with
    f = b1 + b4 |SR| P_h log₁₀ν₀ + b5 exp(−|SR| P_h log₁₀ν₀) + b9 e^S,

    evaluated in the paper's units: P_h [GPa], ν₀ [cP] (= mPa s, dynamic), V_e [m/s],
    R [m], S [µm]. Inputs are converted from the toolkit units at this boundary.

    Parameters
    ----------
    hertz_pressure : float or array — [MPa]
        Peak Hertz pressure p_h, ≥ 0.
    slide_to_roll : float or array — [1]
        SR = V_s / V_e; only |SR| is used.
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity V_e = (u₁ + u₂)/2, > 0.
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity η₀ at ambient pressure, > 0.
    radius : float or array — [mm]
        Equivalent radius of curvature R, > 0.
    roughness_1, roughness_2 : float or array — [µm]
        RMS roughness of each surface, ≥ 0; S = (Rq₁ + Rq₂)/2.
    coefficients : tuple of 9 floats
        b1 … b9; default :data:`XU2007_COEFFICIENTS` (fitted for a 75W90 axle oil).

    Returns
    -------
    float or array — [1]
        μ, broadcast shape of the inputs.

    Raises
    ------
    InputError
        An input outside its accepted range (the message names it).

    Warns
    -----
    FrictionModelRangeWarning
        Inputs outside the fitted ranges of :data:`XU2007_RANGE`: p_h 500–2500 MPa,
        |SR| 0.025–1, V_e 1–20 m/s, η₀ 0.0106–0.1626 Pa s (75W90 at 100–25 °C),
        R 5–40 mm, S 0.1–1 µm.

    Notes
    -----
    Source: Xu, H., Kahraman, A., Anderson, N. E., Maddock, D. G., "Prediction of
    mechanical efficiency of parallel-axis gear pairs", J. Mech. Des. 129 (2007) 58–68,
    friction formula and its coefficient table (quoted in seed/NOTES.md with the check
    μ ≈ 0.029 at p_h = 1 GPa, SR = 0.5, V_e = 10 m/s, ν₀ = 16.3 cP, R = 0.02 m,
    S = 0.8 µm). Assumptions to verify against the paper: (i) V_e is the mean
    entraining velocity (if the paper's V_e were u₁ + u₂ the result would change by
    2^−0.1, i.e. −7 %); (ii) S is the mean of the two surfaces' RMS roughness (the check
    case has equal surfaces); (iii) the fitted ranges are those of the seed's Table 5.1,
    which follows Xu et al.'s parametric methodology for a 75W90 oil. SR = 0 gives μ = 0
    (|SR|^b3), the pure-rolling limit.
    """
    if len(coefficients) != 9:
        raise InputError(f"coefficients: must be 9 values b1..b9, got {len(coefficients)}")
    ph = real_array("hertz_pressure", hertz_pressure, low=0.0, unit="MPa")
    sr = np.abs(real_array("slide_to_roll", slide_to_roll, unit="1"))
    ve = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True, unit="m/s")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    s1 = real_array("roughness_1", roughness_1, low=0.0, high=100.0, unit="µm")
    s2 = real_array("roughness_2", roughness_2, low=0.0, high=100.0, unit="µm")
    ph, sr, ve, eta, r, s1, s2 = broadcast(
        hertz_pressure=ph,
        slide_to_roll=sr,
        entraining_velocity=ve,
        viscosity=eta,
        radius=r,
        roughness_1=s1,
        roughness_2=s2,
    )
    s = 0.5 * (s1 + s2)
    for name, vals in (
        ("hertz_pressure", ph),
        ("slide_to_roll", sr),
        ("entraining_velocity", ve),
        ("viscosity", eta),
        ("radius", r),
        ("roughness", s),
    ):
        lo, hi, units = XU2007_RANGE[name]
        _warn_outside("xu2007", name, vals, lo, hi, units)
    b1, b2, b3, b4, b5, b6, b7, b8, b9 = coefficients
    p_gpa = ph * 1e-3
    nu_cp = eta * 1e3
    r_m = r * 1e-3
    zero = (sr == 0.0) | (p_gpa == 0.0)  # μ → 0 in pure rolling or without load
    sr_, p_ = np.where(zero, 1.0, sr), np.where(zero, 1.0, p_gpa)
    group = sr_ * p_ * np.log10(nu_cp)
    with np.errstate(over="ignore"):
        # evaluated as ln μ so no intermediate product overflows; inf is capped below
        ln_mu = (
            b1
            + b4 * group
            + b5 * np.exp(-group)
            + b9 * np.exp(s)
            + b2 * np.log(p_)
            + b3 * np.log(sr_)
            + b6 * np.log(ve)
            + b7 * np.log(nu_cp)
            + b8 * np.log(r_m)
        )
        mu = np.exp(np.minimum(ln_mu, 700.0))
    mu = _cap("xu2007", mu)
    return scalar_or_array(np.where(zero, 0.0, mu))


# ----------------------------------------------------------------------------- B&K
_N_PER_MM_TO_LBF_PER_IN = 25.4 / 4.4482216152605  # 1 N/mm in lbf/in
_M_PER_S_TO_IN_PER_S = 1.0 / 0.0254
_RA_OVER_RQ = math.sqrt(2.0 / math.pi)  # Gaussian height distribution
_UM_TO_UIN = 1.0 / 0.0254


def benedict_kelley(
    *,
    load_per_length: ArrayLike,
    sliding_velocity: ArrayLike,
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
) -> NDArray[np.float64] | float:
    """Empirical gear-tooth friction coefficient of Benedict & Kelley (1960).

    μ = 0.0127 C_R log₁₀(3.17·10⁸ W′ / (ν₀ V_s V_t²)),  C_R = 50 / (50 − S_avg),

    in the published (US customary) units: W′ load per unit face width [lbf/in],
    ν₀ dynamic viscosity at the oil inlet temperature [cP], V_s sliding velocity
    [in/s], V_t sum (entraining) velocity u₁ + u₂ [in/s], S_avg average roughness
    [µin]. Inputs are converted from the toolkit units at this boundary.

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        Normal load per unit length w′, > 0.
    sliding_velocity : float or array — [m/s]
        V_s = |u₁ − u₂|, ≥ 0.
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity (u₁ + u₂)/2, > 0; V_t = 2 × this.
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity, > 0.
    roughness_1, roughness_2 : float or array — [µm]
        RMS roughness Rq of each surface, ≥ 0. Converted to arithmetic-mean roughness
        by Ra = √(2/π) Rq (Gaussian surfaces) and averaged: S_avg = (Ra₁ + Ra₂)/2.

    Returns
    -------
    float or array — [1]
        μ ≥ 0, broadcast shape.

    Raises
    ------
    InputError
        An input outside its accepted range, or S_avg ≥ 50 µin (≈ 1.27 µm Ra), where
        C_R is undefined.

    Warns
    -----
    FrictionModelRangeWarning
        Where V_s = 0 (pure rolling; the formula diverges) μ is set to 0 — the sliding
        loss μ f V_s is zero there anyway; where the log argument is ≤ 1 (μ ≤ 0, very
        high speed/viscosity for the load) μ is clipped to 0.

    Notes
    -----
    Source: Benedict, G. H., Kelley, B. W., "Instantaneous coefficients of gear tooth
    friction", ASLE Trans. 4 (1961) 59–70 (presented 1960; seed ref. [5.8]), from
    roller tests; the form with the roughness factor C_R as it is usually quoted in
    the gear-efficiency literature (the constants 0.0127, 3.17·10⁸ and 50 µin were not
    re-checked against the original here). The original measured CLA (Ra) roughness:
    the Rq → Ra conversion is an assumption of this implementation.
    """
    w = real_array("load_per_length", load_per_length, low=0.0, low_open=True, unit="N/mm")
    vs = real_array("sliding_velocity", sliding_velocity, low=0.0, unit="m/s")
    ve = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True, unit="m/s")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    s1 = real_array("roughness_1", roughness_1, low=0.0, high=100.0, unit="µm")
    s2 = real_array("roughness_2", roughness_2, low=0.0, high=100.0, unit="µm")
    w, vs, ve, eta, s1, s2 = broadcast(
        load_per_length=w,
        sliding_velocity=vs,
        entraining_velocity=ve,
        viscosity=eta,
        roughness_1=s1,
        roughness_2=s2,
    )
    s_avg = 0.5 * (s1 + s2) * _RA_OVER_RQ * _UM_TO_UIN
    if np.any(s_avg >= 50.0):
        raise InputError(
            "roughness_1, roughness_2: benedict_kelley needs the mean Ra = √(2/π)·mean(Rq) below"
            f" 50 µin (mean Rq < {50.0 * 0.0254 / _RA_OVER_RQ:.3f} µm) for C_R = 50/(50 − S);"
            f" got {s_avg.max():.1f} µin"
        )
    c_r = 50.0 / (50.0 - s_avg)
    w_lbf = w * _N_PER_MM_TO_LBF_PER_IN
    nu_cp = eta * 1e3
    vs_in = vs * _M_PER_S_TO_IN_PER_S
    vt_in = 2.0 * ve * _M_PER_S_TO_IN_PER_S
    rolling = vs_in == 0.0
    with np.errstate(divide="ignore", over="ignore"):
        arg = 3.17e8 * w_lbf / (nu_cp * np.where(rolling, 1.0, vs_in) * vt_in**2)
    mu = 0.0127 * c_r * np.log10(arg)
    if np.any(rolling):
        warnings.warn(
            f"benedict_kelley: sliding_velocity = 0 at {int(np.count_nonzero(rolling))} point(s);"
            " the formula diverges in pure rolling — μ set to 0 there (no sliding loss)",
            FrictionModelRangeWarning,
            stacklevel=2,
        )
    low = (arg <= 1.0) & ~rolling
    if np.any(low):
        warnings.warn(
            f"benedict_kelley: log argument 3.17e8 W/(ν V_s V_t²) ≤ 1 at"
            f" {int(np.count_nonzero(low))} point(s) (outside the roller-test range); μ clipped"
            " to 0 there",
            FrictionModelRangeWarning,
            stacklevel=2,
        )
    mu = np.where(rolling | low, 0.0, mu)
    return scalar_or_array(_cap("benedict_kelley", mu))


# ----------------------------------------------------------------------------- ISO/TR 14179-2
#: Declared range of ``iso_tr_14179_2`` as applied per contact segment: (low, high, units).
#: The standard states no numeric range for the formula; these are the conditions of the FZG
#: test gears it was fitted on as far as the sources quoted in the docstring give them
#: (pitch-line velocity 0.5–20 m/s on centre distance 91.5 mm gears, i.e. v_Σ ≈ 0.3–14 m/s;
#: ground or shaved flanks, Ra 0.1–1 µm), and mineral-oil viscosities of ISO VG 32–220 at
#: 40–120 °C (≈ 3–300 mPa s). Outside it the formula is evaluated as it stands and flagged.
ISO_TR_14179_2_RANGE: Mapping[str, tuple[float, float, str]] = MappingProxyType(
    {
        "sum_velocity": (0.3, 14.0, "m/s"),
        "roughness_ra": (0.1, 1.0, "µm"),
        "viscosity": (0.003, 0.3, "Pa s"),
    }
)


def iso_tr_14179_2(
    *,
    load_per_length: ArrayLike,
    entraining_velocity: ArrayLike,
    radius: ArrayLike,
    viscosity: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
    base_oil_factor: float = 1.0,
) -> NDArray[np.float64] | float:
    """Mean tooth friction coefficient of ISO/TR 14179-2 (Schlenk's FZG correlation).

    μ_mz = 0.048 (F_bt/b / (v_ΣC ρ_C))^0.2 · η_oil^−0.05 · Ra^0.25 · X_L,

    in the standard's units: F_bt/b [N/mm], v_ΣC = u₁ + u₂ [m/s], ρ_C [mm], η_oil
    [mPa s], Ra = (Ra₁ + Ra₂)/2 [µm]. A *measured* correlation (FZG back-to-back tests on
    spur and helical gears, mean μ over the mesh), offered as an independent anchor to compare
    the physics models with — not as the default. Applied here per contact segment: F_bt/b
    is the segment's normal load per length w′, v_ΣC twice its entraining velocity and ρ_C
    its equivalent radius R.

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        w′ > 0.
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity u_e = (u₁ + u₂)/2 > 0; v_ΣC = 2 u_e.
    radius : float or array — [mm]
        Equivalent radius of curvature R > 0.
    viscosity : float or array — [Pa s]
        Dynamic viscosity at the oil (inlet) temperature, > 0.
    roughness_1, roughness_2 : float or array — [µm]
        RMS roughness Rq of each flank, ≥ 0; Ra = √(2/π) Rq (Gaussian heights), averaged.
    base_oil_factor : float — [1]
        X_L: 1.0 mineral oil (default), 0.8 polyalphaolefin, 0.7 non-water-soluble polyglycol,
        0.6 water-soluble polyglycol (the values of
        :data:`friction.lubricant.BASE_OIL_FACTORS`), in (0, 2].

    Returns
    -------
    float or array — [1]
        μ_mz, broadcast shape of the inputs (0 where the flanks are ideally smooth, Ra = 0,
        the formula's own limit).

    Raises
    ------
    InputError
        An input outside its accepted range (the message names it).

    Warns
    -----
    FrictionModelRangeWarning
        v_ΣC, Ra or η outside :data:`ISO_TR_14179_2_RANGE`.

    Notes
    -----
    Source: ISO/TR 14179-2:2001, *Gears — Thermal capacity — Part 2: Thermal load-carrying
    capacity*, the load-dependent gear loss with the mean friction coefficient of Schlenk,
    L., *Untersuchungen zur Fresstragfähigkeit von Großzahnrädern*, Diss. TU München (1994).
    The constant 0.048 and the exponents 0.2 / −0.05 / 0.25 were checked against an
    independent implementation of the standard's formula (a public gearbox-loss script,
    "Average friction coefficient according to Schlenk", in the same units); the standard
    itself is not open. Worked value (the test): w′ 300 N/mm, v_Σ 3 m/s, ρ 10 mm,
    η 13.6 mPa s, Ra 0.5 µm, mineral oil → μ = 0.048 · 10^0.2 · 13.6^−0.05 · 0.5^0.25
    = 0.0561. The standard applies it to the nominal load of a whole mesh at the pitch
    point; evaluated per segment it follows the local load, speed and curvature with the
    same exponents (so a mesh-mean of it is not exactly the standard's value).
    """
    w = real_array("load_per_length", load_per_length, low=0.0, low_open=True, unit="N/mm")
    ve = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True,
                    unit="m/s")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    s1 = real_array("roughness_1", roughness_1, low=0.0, high=100.0, unit="µm")
    s2 = real_array("roughness_2", roughness_2, low=0.0, high=100.0, unit="µm")
    x_l = float(real_array("base_oil_factor", base_oil_factor, low=0.0, low_open=True,
                           high=2.0, unit="1"))
    w, ve, r, eta, s1, s2 = broadcast(load_per_length=w, entraining_velocity=ve, radius=r,
                                      viscosity=eta, roughness_1=s1, roughness_2=s2)
    v_sum = 2.0 * ve
    ra = 0.5 * (s1 + s2) * _RA_OVER_RQ
    for name, vals in (("sum_velocity", v_sum), ("roughness_ra", ra), ("viscosity", eta)):
        lo, hi, units = ISO_TR_14179_2_RANGE[name]
        _warn_outside("iso_tr_14179_2", name, vals, lo, hi, units)
    mu = 0.048 * (w / (v_sum * r)) ** 0.2 * (eta * 1e3) ** -0.05 * ra**0.25 * x_l
    return scalar_or_array(_cap("iso_tr_14179_2", mu))


def _iso_tr_14179_2_validity(*, entraining_velocity: ArrayLike, viscosity: ArrayLike,
                             roughness_1: ArrayLike, roughness_2: ArrayLike,
                             **_: Any) -> NDArray[np.bool_]:
    """True where v_Σ, Ra and η lie inside :data:`ISO_TR_14179_2_RANGE`."""
    values = {
        "sum_velocity": 2.0 * np.asarray(entraining_velocity, float),
        "roughness_ra": 0.5 * (np.asarray(roughness_1, float)
                               + np.asarray(roughness_2, float)) * _RA_OVER_RQ,
        "viscosity": np.asarray(viscosity, float),
    }
    ok = np.asarray(True)
    for name, vals in values.items():
        lo, hi, _units = ISO_TR_14179_2_RANGE[name]
        ok = ok & (vals >= lo) & (vals <= hi)
    return np.asarray(ok, dtype=bool)


# ----------------------------------------------------------------------------- constant
def constant(*, value: float = 0.05) -> float:
    """A constant friction coefficient (Coleman's assumption for bevel and hypoid gears).

    Parameters
    ----------
    value : float — [1]
        μ, in [0, 1]; default 0.05.

    Returns
    -------
    float — [1]
        ``value`` (:func:`friction_coefficient` broadcasts it to the inputs' shape).

    Raises
    ------
    InputError
        ``value`` outside [0, 1] or not finite.

    Notes
    -----
    Source: Coleman, W., "Computing efficiency for bevel and hypoid gears", Machine
    Design 47 (1975) 64–65 (seed ref. [5.1]: "a constant friction coefficient of 0.05 at
    every contact point").
    No validity range, hence no warnings.
    """
    v = real_array("value", value, low=0.0, high=1.0, unit="1")
    if v.ndim:
        raise InputError(f"value: must be a scalar friction coefficient [1], got shape {v.shape}")
    return float(v)


# ----------------------------------------------------------------------------- registry
@dataclass(frozen=True)
class FrictionModel:
    """A registered friction model.

    Attributes
    ----------
    name : str
    function : callable
        Keyword-only model function returning μ [1].
    required : tuple of str
        Inputs the model needs (names of :data:`STANDARD_INPUTS`).
    optional : tuple of str
        Inputs or model parameters with defaults.
    source : str
        The reference the model implements.
    validity : callable
        Keyword function of the same inputs returning a bool array, True where the inputs
        lie inside the model's declared validity (fitted) range.
    """

    name: str
    function: Callable[..., Any]
    required: tuple[str, ...]
    optional: tuple[str, ...]
    source: str
    validity: Callable[..., Any]

    def __call__(self, **inputs: Any) -> NDArray[np.float64] | float:
        """Evaluate the model (see :func:`friction_coefficient`)."""
        return _evaluate(self, inputs)


def _register(name: str, function: Callable[..., Any], source: str,
              validity: Callable[..., Any]) -> FrictionModel:
    """A :class:`FrictionModel` of a function, after the checks every model passes, bundled
    or not: a callable whose inputs are passed by keyword (no ``*args``, ``**kwargs`` or
    positional-only parameters), whose required inputs are names of
    :data:`STANDARD_INPUTS` (the only ones the efficiency stage can give), and a validity
    function taking the same inputs by keyword."""
    required, optional, _ = keyword_parameters("function", function, var_keyword=False)
    outside = sorted(set(required) - set(STANDARD_INPUTS))
    if outside:
        raise InputError(
            f"function: {callable_name(function)} requires {outside}, which are not inputs "
            f"of the vocabulary {sorted(STANDARD_INPUTS)}; give them defaults (model "
            "parameters) or use the vocabulary's names")
    v_required, _, v_any = keyword_parameters("validity", validity)
    if not v_any and set(v_required) - set(required) - set(optional):
        raise InputError(f"validity: {callable_name(validity)} requires "
                         f"{sorted(set(v_required) - set(required) - set(optional))}, which "
                         "the model does not take")
    return FrictionModel(name, function, required, optional, source, validity)


def _xu2007_validity(*, hertz_pressure: ArrayLike, slide_to_roll: ArrayLike,
                     entraining_velocity: ArrayLike, viscosity: ArrayLike, radius: ArrayLike,
                     roughness_1: ArrayLike, roughness_2: ArrayLike, **_: Any) -> NDArray[np.bool_]:
    """True where every xu2007 input lies inside :data:`XU2007_RANGE` (units there)."""
    s = 0.5 * (np.asarray(roughness_1, float) + np.asarray(roughness_2, float))
    values = {
        "hertz_pressure": np.asarray(hertz_pressure, float),
        "slide_to_roll": np.abs(np.asarray(slide_to_roll, float)),
        "entraining_velocity": np.asarray(entraining_velocity, float),
        "viscosity": np.asarray(viscosity, float),
        "radius": np.asarray(radius, float),
        "roughness": s,
    }
    ok = np.asarray(True)
    for name, vals in values.items():
        lo, hi, _units = XU2007_RANGE[name]
        ok = ok & (vals >= lo) & (vals <= hi)
    return np.asarray(ok, dtype=bool)


def _benedict_kelley_validity(*, sliding_velocity: ArrayLike, **_: Any) -> NDArray[np.bool_]:
    """True where V_s > 0 (the formula diverges in pure rolling; its fitted ranges of load,
    speed and viscosity are not stated in the form the toolkit quotes)."""
    return np.asarray(np.asarray(sliding_velocity, float) > 0.0)


def _always_valid(**_: Any) -> NDArray[np.bool_]:
    """True: the constant model has no validity range."""
    return np.asarray(True)


_MODELS: Mapping[str, FrictionModel] = MappingProxyType(
    {
        "xu2007": _register(
            "xu2007", xu2007, "Xu, Kahraman, Anderson & Maddock, J. Mech. Des. 129 (2007) 58",
            _xu2007_validity,
        ),
        "benedict_kelley": _register(
            "benedict_kelley", benedict_kelley, "Benedict & Kelley, ASLE Trans. 4 (1961) 59",
            _benedict_kelley_validity,
        ),
        "constant": _register("constant", constant, "Coleman (1975); constant μ",
                              _always_valid),
        "iso_tr_14179_2": _register(
            "iso_tr_14179_2", iso_tr_14179_2,
            "ISO/TR 14179-2:2001 mean tooth friction (Schlenk 1994, FZG tests); a measured"
            " anchor, applied per segment", _iso_tr_14179_2_validity,
        ),
        "kolivand2009": _register(
            "kolivand2009", kolivand2009,
            "seed Eq. 5.11 structure (Kolivand 2009, §5.2.3) fitted to friction.ehl over"
            " Table 5.1 (friction.kolivand2009, friction/data/kolivand2009_75W90.toml)",
            kolivand2009_validity,
        ),
        "mixed_ehl": _register(
            "mixed_ehl", mixed_ehl,
            "Johnson, Greenwood & Poon, Wear 19 (1972) 91 load sharing; Greenwood & Tripp"
            " (1970) asperities; Eyring film shear; boundary friction (friction.mixed_ehl)",
            mixed_ehl_validity,
        ),
        "thermal_eyring": _register(
            "thermal_eyring", thermal_eyring,
            "Zhou & Hoeprich, J. Tribol. 113 (1991) 590 asperity load share with a thermal"
            " Eyring film shear: Johnson & Greenwood, Wear 61 (1980) 353; Jaeger (1942)"
            " flash temperature (friction.thermal_eyring);"
            " the default since issue 74", mixed_ehl_validity,
        ),
    }
)

#: Models of the literature that are known but not offered, with the reason.
UNAVAILABLE_MODELS: Mapping[str, str] = MappingProxyType(
    {
        "kolivand2009_table_5_3": (
            "the seed's own coefficients (Table 5.3) cannot be used: the seed's regression"
            " (Kolivand 2009, Eq. 5.11a-c with Table 5.3) is not recoverable from the text"
            " extraction: the λ symbol, the exponents, the"
            " operators and the grouping of the three regime formulas were lost, so which"
            " of the 35 Table 5.3 coefficients multiplies which group (λ, SR, U, G, H, S_c,"
            " S_eq), and whether inside a log, an exponent or a power, is undetermined; a"
            " term structure picked so that μ lands in 0.01-0.06 and is continuous at"
            " λ = 1 and 3 would be fitted to those acceptance checks rather than recovered"
            " from the source. Use 'kolivand2009' (the same structure fitted again to the"
            " toolkit's solver) or 'xu2007' instead."
        ),
    }
)


#: what may stand where a friction model is chosen: a name, a FrictionModel, a function
FrictionModelLike = str | FrictionModel | Callable[..., Any]

#: the entry-point group in which an installed distribution advertises friction models:
#: each entry is a :class:`FrictionModel` or a model function (registered under the entry's
#: name), so that ``ltca run --friction-model NAME`` finds it
ENTRY_POINT_GROUP = "hypoid_ltca.friction_models"

#: models registered in this process by :func:`register_friction_model` (not a cache:
#: ``clear_caches`` keeps them)
_USER: dict[str, FrictionModel] = {}


@memoised(maxsize=None)
def _plugins() -> dict[str, FrictionModel]:
    """The models of the installed plug-ins (:data:`ENTRY_POINT_GROUP`)."""
    out = {}
    for name, obj in entry_point_objects(ENTRY_POINT_GROUP).items():
        if name in _MODELS or name in UNAVAILABLE_MODELS:
            log.warning("entry point %s of group %s shadows a bundled friction model: left "
                        "out", name, ENTRY_POINT_GROUP)
            continue
        try:
            out[name] = (obj if isinstance(obj, FrictionModel)
                         else _register(name, obj, f"plug-in {name}", _always_valid))
        except InputError as exc:
            log.warning("entry point %s of group %s is not a friction model: %s", name,
                        ENTRY_POINT_GROUP, exc)
    return out


def available_friction_models() -> tuple[str, ...]:
    """Names of the friction models that can be evaluated.

    Returns
    -------
    tuple of str
        Sorted names: the bundled models (``"benedict_kelley"``, ``"constant"``,
        ``"iso_tr_14179_2"``, ``"kolivand2009"``, ``"mixed_ehl"``, ``"xu2007"``), the
        installed plug-ins' and those registered with :func:`register_friction_model`.

    Notes
    -----
    Source: the registry of this module; each model's docstring gives its reference.
    """
    return tuple(sorted({*_MODELS, *_plugins(), *_USER}))


def unavailable_friction_models() -> Mapping[str, str]:
    """Known models that are not offered, with the reason for each.

    Returns
    -------
    mapping of str to str
        Name → reason (read-only).

    Notes
    -----
    Source: seed/NOTES.md on seed Eq. 5.11 (kolivand2009_table_5_3).
    """
    return UNAVAILABLE_MODELS


def as_friction_model(function: Callable[..., Any], *, name: str | None = None,
                      validity: Callable[..., Any] | None = None, source: str = ""
                      ) -> FrictionModel:
    """A :class:`FrictionModel` of a model function, checked as the bundled models are.

    Parameters
    ----------
    function : callable
        ``mu = function(*, <inputs>)``: keyword inputs from :data:`STANDARD_INPUTS` (units
        there; those without a default are required) and model parameters with defaults;
        returns μ [1], float or an array broadcasting with the inputs, finite, in
        [0, :data:`MU_MAX`] (warned above :data:`MU_CAP`; checked at each call).
    name : str, optional
        The name the model is recorded by (default the function's ``__name__``).
    validity : callable, optional
        Keyword function of the same inputs returning True where they lie in the model's
        range (default: everywhere).
    source : str
        The reference the model implements.

    Returns
    -------
    FrictionModel

    Raises
    ------
    InputError
        Not callable, ``*args``/``**kwargs``/positional-only parameters, a required input
        outside the vocabulary, or a validity function needing inputs the model does not
        take (the message names them).
    """
    label = check_model_name("name", name if name is not None else callable_name(function))
    return _register(label, function, source or f"user function {label}",
                     _always_valid if validity is None else validity)


def register_friction_model(name: str, function: Callable[..., Any] | FrictionModel, *,
                            validity: Callable[..., Any] | None = None, source: str = "",
                            replace: bool = False) -> FrictionModel:
    """Register a user's friction-coefficient model under ``name`` for this process.

    After it, ``name`` is a model like the bundled ones: ``OperatingConditions(
    friction_model=name)``, :func:`friction_coefficient`, ``run_analysis`` and the studies
    of this process. For ``ltca run --friction-model NAME`` and a cluster's workers,
    advertise it in the entry-point group :data:`ENTRY_POINT_GROUP` of an installed
    package instead (docs/extending.md).

    Parameters
    ----------
    name : str
        Registry name (no spaces); not a bundled or known-unavailable model's.
    function : callable or FrictionModel
        The model function (:func:`as_friction_model` gives the checks), or a ready
        :class:`FrictionModel` (registered under ``name``).
    validity : callable, optional
        As :func:`as_friction_model`.
    source : str
        The reference the model implements (listed with the model).
    replace : bool
        Allow replacing a model registered earlier under ``name`` (default False).

    Returns
    -------
    FrictionModel
        The registered model (its name, function, validity check and source).

    Raises
    ------
    InputError
        A bad name or function (:func:`as_friction_model`), a bundled name, or a name
        taken without ``replace``.
    """
    check_model_name("name", name)
    if name in _MODELS or name in UNAVAILABLE_MODELS:
        raise InputError(f"name: {name!r} is a bundled friction model; register under "
                         "another name")
    if (name in _USER or name in _plugins()) and not replace:
        raise InputError(f"name: a friction model {name!r} is registered already; pass "
                         "replace=True to replace it or choose another name")
    if isinstance(function, FrictionModel):
        model = _register(name, function.function, source or function.source,
                          function.validity if validity is None else validity)
    else:
        model = as_friction_model(function, name=name, validity=validity, source=source)
    _USER[name] = model
    return model


def unregister_friction_model(name: str) -> None:
    """Remove a model registered with :func:`register_friction_model`.

    Parameters
    ----------
    name : str
        The name it was registered under.

    Raises
    ------
    InputError
        ``name`` was not registered with :func:`register_friction_model`.
    """
    if name not in _USER:
        raise InputError(f"name: {name!r} was not registered with register_friction_model "
                         f"(registered: {sorted(_USER)})")
    del _USER[name]


def friction_model_name(model: FrictionModelLike) -> str:
    """The name a model is recorded by (the ``friction_model`` attribute of results): the
    name itself, the FrictionModel's, or the function's ``__name__``."""
    if isinstance(model, str):
        return model
    if isinstance(model, FrictionModel):
        return model.name
    return callable_name(model)


def get_friction_model(name: FrictionModelLike) -> FrictionModel:
    """Return the registered friction model ``name``.

    Parameters
    ----------
    name : str, FrictionModel or callable
        One of :func:`available_friction_models`; a FrictionModel is returned as it is and
        a model function is checked and wrapped (:func:`as_friction_model`).

    Returns
    -------
    FrictionModel
        Callable with keyword inputs; ``required`` and ``optional`` list them.

    Raises
    ------
    geometry.core.errors.UnknownNameError
        ``name`` is unavailable (the message quotes the reason) or unknown (the message
        lists the available names): an InputError and a ModelUnavailableError.
    InputError
        A model function that fails the checks of :func:`as_friction_model`.

    Notes
    -----
    Source: registry pattern of the toolkit's STYLE (qpsolvers-like).
    """
    if isinstance(name, FrictionModel):
        return name
    if not isinstance(name, str):
        return as_friction_model(name)
    for registry in (_MODELS, _USER):
        if name in registry:
            return registry[name]
    if name in UNAVAILABLE_MODELS:
        raise UnknownNameError(
            f"friction model {name!r} is unavailable: {UNAVAILABLE_MODELS[name]}"
            f" (available: {available_friction_models()})"
        )
    plugins = _plugins()
    if name in plugins:
        return plugins[name]
    raise UnknownNameError(
        f"unknown friction model {name!r}; available: {available_friction_models()};"
        f" known but unavailable: {tuple(sorted(UNAVAILABLE_MODELS))}"
    )


def _evaluate(model: FrictionModel, inputs: Mapping[str, Any]) -> NDArray[np.float64] | float:
    accepted = set(model.required) | set(model.optional)
    unknown = sorted(set(inputs) - set(STANDARD_INPUTS) - accepted)
    if unknown:
        raise InputError(
            f"unknown input(s) {unknown} for friction model {model.name!r}; the vocabulary is"
            f" {sorted(STANDARD_INPUTS)} plus the model's parameters {sorted(model.optional)}"
        )
    missing = [k for k in model.required if k not in inputs]
    if missing:
        meaning = "; ".join(f"{k} {STANDARD_INPUTS.get(k, '')}" for k in missing)
        raise InputError(f"friction model {model.name!r} needs input(s) {missing} ({meaning})")
    shapes = [np.shape(v) for k, v in inputs.items() if k in STANDARD_INPUTS]
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError as exc:
        raise InputError(f"input shapes do not broadcast together: {shapes}") from exc
    mu = _called(model, "μ", model.function,
                 **{k: v for k, v in inputs.items() if k in accepted})
    try:
        mu = np.asarray(mu, dtype=float)
        out = np.broadcast_to(mu, np.broadcast_shapes(mu.shape, shape))
    except (TypeError, ValueError):
        out = None
    if out is None or out.shape != shape:  # a μ per input point, or one for all
        raise PluginError(f"friction model {model.name!r} returned {_returned(mu)} for inputs "
                          f"of shape {shape}; a model returns μ [1] as a number or an array "
                          "of the inputs' shape (docs/extending.md)")
    if not np.all(np.isfinite(out)):  # a guard: every model is written to stay finite
        raise PluginError(f"friction model {model.name!r} returned a non-finite μ "
                          f"({int(np.sum(~np.isfinite(out)))} of {out.size} values) for these "
                          "inputs; μ must be finite and >= 0")
    if np.any(out < 0.0):
        raise PluginError(f"friction model {model.name!r} returned a negative μ (least "
                          f"{float(out.min()):.3g}); a sliding friction coefficient is >= 0 "
                          "(its direction is the sliding velocity's)")
    return scalar_or_array(_bounded(model, out).astype(float))


def _bounded(model: FrictionModel, mu: Array) -> Array:
    """``mu`` of ``model`` after the physical bounds every model's μ is held to: refused
    above :data:`MU_MAX`, warned above :data:`MU_CAP` (issue 71)."""
    if np.any(mu > MU_MAX):
        raise PluginError(
            f"friction model {model.name!r} returned friction_coefficient μ = "
            f"{float(mu.max()):.3g} at {int(np.count_nonzero(mu > MU_MAX))} of {mu.size} "
            f"point(s); accepted 0 <= μ <= {MU_MAX:g} (dry steel on steel stays below ~0.8, "
            f"lubricated gear contacts 0.01-0.15; μ in % or a friction force instead of a "
            "coefficient?) (docs/extending.md)")
    above = mu > MU_CAP
    if np.any(above):
        warnings.warn(
            f"{model.name}: friction_coefficient μ up to {float(mu.max()):.3g} above "
            f"{MU_CAP:g} at {int(np.count_nonzero(above))} of {mu.size} point(s): beyond "
            "any lubricated steel gear contact (boundary friction 0.1-0.15), the range of "
            "dry steel; the efficiency and the flash temperature rest on it",
            FrictionModelRangeWarning,
            stacklevel=4,
        )
    return mu


def is_mu_above_cap(note: str) -> bool:
    """Whether ``note`` (a :class:`FrictionModelRangeWarning`'s message, as the efficiency
    stage lists them in ``model_range_warnings``) is the warning of a μ above
    :data:`MU_CAP`: a bundled model's clip (``"<model>: μ above 0.3 …"``) or any model's
    μ kept in (MU_CAP, MU_MAX] (``"<model>: friction_coefficient μ up to 0.45 above 0.3
    …"``), not a fitted range's.

    Parameters
    ----------
    note : str
        One warning message.

    Returns
    -------
    bool
        True for those two warnings (issue 71: ``ltca run`` prints them).

    Notes
    -----
    Source: the texts of :func:`_cap` and :func:`_bounded` (this module); the bound
    :data:`MU_CAP` as their messages print it (``:g``).
    """
    return re.search(rf"μ (up to \S+ )?above {re.escape(f'{MU_CAP:g}')}\b", note) is not None


def _returned(value: Any) -> str:
    """What a plug-in returned, short: type, shape and the first characters."""
    text = " ".join(repr(value).split())  # one line: a 2-D array's repr has newlines
    text = text if len(text) <= 50 else text[:49] + "…"
    shape = np.shape(value) if isinstance(value, np.ndarray) else None
    return f"{type(value).__name__}{'' if shape is None else f' of shape {shape}'} {text}"


def _called(model: FrictionModel, what: str, function: Callable[..., Any], **inputs: Any) -> Any:
    """``function(**inputs)`` of a friction model: an exception of the toolkit's family
    passes (a bundled model's range check), any other becomes a :class:`PluginError` that
    names the model, what it was computing and what it raised."""
    try:
        return function(**inputs)
    except LTCAError:
        raise
    except Exception as exc:
        raise PluginError(f"friction model {model.name!r} raised {type(exc).__name__} "
                          f"computing {what}: {str(exc).splitlines()[0] if str(exc) else ''}"
                          " (docs/extending.md)") from exc


def friction_coefficient(name: FrictionModelLike, **inputs: Any) -> NDArray[np.float64] | float:
    """Friction coefficient μ of the model ``name`` for the given segment inputs.

    Parameters
    ----------
    name : str, FrictionModel or callable
        One of :func:`available_friction_models`, or a model (:func:`get_friction_model`).
    **inputs : float or array
        Keyword inputs from :data:`STANDARD_INPUTS`, broadcastable to one shape:
        ``hertz_pressure`` [MPa], ``slide_to_roll`` [1], ``entraining_velocity`` and
        ``sliding_velocity`` [m/s], ``load_per_length`` [N/mm], ``viscosity`` [Pa s],
        ``radius`` [mm], ``roughness_1`` and ``roughness_2`` [µm], ``lambda_ratio`` [1],
        ``pressure_viscosity`` [1/GPa], ``e_prime`` [MPa], ``temperature`` [degC],
        ``thermal_factor`` [1]; plus the model's own parameters (e.g. ``value`` [1] for
        ``constant``). Inputs a model does not use are ignored; names outside the
        vocabulary are refused.

    Returns
    -------
    float or array — [1]
        μ, broadcast to the shape of all the standard inputs passed.

    Raises
    ------
    ModelUnavailableError
        Unknown or unavailable model.
    InputError
        A missing, unknown or out-of-range input.
    PluginError
        The model raised, or returned μ of the wrong shape, non-finite, negative or above
        :data:`MU_MAX` (1; the message names the model and ``friction_coefficient``).

    Warns
    -----
    FrictionModelRangeWarning
        Inputs outside the model's fitted range; a μ above :data:`MU_CAP` (0.3, beyond
        lubricated steel contacts).

    Notes
    -----
    Source: each model's reference (see the model functions); the registry pattern and
    the seed's per-segment use are seed section 5.2.2–5.2.4.
    """
    return _evaluate(get_friction_model(name), inputs)


def friction_model_validity(name: FrictionModelLike, **inputs: Any) -> NDArray[np.bool_]:
    """Which points lie inside the declared validity range of the friction model ``name``.

    Parameters
    ----------
    name : str, FrictionModel or callable
        One of :func:`available_friction_models`, or a model (:func:`get_friction_model`).
    **inputs : float or array
        As :func:`friction_coefficient` (the same call's keyword inputs).

    Returns
    -------
    array of bool
        True inside the model's range (fitted range of a regression, declared validity of
        a physical model), broadcast to the shape of the standard inputs passed.

    Raises
    ------
    ModelUnavailableError
        Unknown or unavailable model.
    InputError
        A missing input or shapes that do not broadcast.

    Notes
    -----
    Source: each model's range (``XU2007_RANGE``, ``friction.mixed_ehl.MIXED_EHL_VALIDITY``;
    benedict_kelley: V_s > 0; constant: everywhere).
    """
    model = get_friction_model(name)
    missing = [k for k in model.required if k not in inputs]
    if missing:
        raise InputError(f"friction model {model.name!r} needs input(s) {missing}")
    ok = np.asarray(_called(model, "its validity", model.validity, **inputs), dtype=bool)
    shapes = [np.shape(v) for k, v in inputs.items() if k in STANDARD_INPUTS]
    try:
        shape = np.broadcast_shapes(ok.shape, *shapes)
    except ValueError as exc:
        raise InputError(f"input shapes do not broadcast together: {shapes}") from exc
    return np.broadcast_to(ok, shape).copy()
