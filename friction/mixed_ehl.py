"""Physics-based mixed-EHL friction coefficient of a line-contact segment.

The seed (§5.2.2, Eq. 5.7–5.9) writes the friction of a contact segment as the viscous
shear of the fluid film plus a dry (boundary) friction on the asperity contacts, and
obtains it from a transient mixed-EHL solver (Li & Kahraman) that is not available here.
This module computes the same split with a published *load-sharing* scheme instead of a
solver, so that μ depends on the film parameter λ continuously from boundary to full film:

1. **Load sharing** (Johnson, Greenwood & Poon 1972): the load w′ is split between the
   fluid film and the asperities, w′ = w′/γ₁ + w′/γ₂ with 1/γ₁ + 1/γ₂ = 1. The film
   carries w′/γ₁ as a smooth EHL contact of modulus E′/γ₁; its central film thickness
   (Dowson & Toyoda, :func:`friction.film.dowson_toyoda_central`, times the thermal
   factor φ_T of :func:`friction.film.thermal_reduction_factor`) becomes
   h_c(γ₁) = h_c,s · γ₁^(p_U − p_G) = h_c,s · γ₁^0.13.
2. **Asperity pressure** (Greenwood & Tripp 1970): at the mean-plane separation h the
   asperities carry the nominal pressure p_a = K′ E′ F_{5/2}(h/σ), where h is the
   separation whose mean gap over the Gaussian heights is the film's h_c: h_T(h) =
   σ[tΦ(t) + φ(t)] = h_c, t = h/σ (Patir & Cheng 1978: the entrained flux, which the EHL
   film formula fixes, is carried by the mean gap; :func:`friction.ehl.flow_factors.mean_gap`,
   the stochastic solver's). As the film closes (h_c/σ → 0) t → −∞ and p_a grows without
   bound, so the asperities can take the whole load (issue 61: with h = h_c, p_a was
   capped at K′E′F_{5/2}(0) ≈ 83 MPa and μ never reached μ_b at gear pressures);
   K′ = (8√2/15) π (ηβσ)² √(σ/β) with E′ = 2E* (two rough surfaces; Greenwood & Tripp's
   (16√2/15)π… multiplies E*), which must equal the asperity share w′/(γ₂ · 2b) of
   the Hertz mean pressure p̄ = w′/(2b). One equation in γ₁, solved per segment.
3. **Film shear** (Eyring; Johnson & Tevaarwerk 1977; Evans & Johnson 1986): over the
   Hertz zone the film pressure is p(x)/γ₁ (the Hertz profile scaled to the film's load),
   the viscosity η = η₀ exp(α p/γ₁) (Barus, with the α of :mod:`friction.lubricant`), the
   shear rate V_s/h_c and the shear stress τ = τ₀ asinh(η V_s/(h_c τ₀)), capped by the
   limiting shear stress Λ p/γ₁ (Bair & Winer 1979).
4. **Boundary friction** μ_b on the asperity share (seed Eq. 5.8).

Hence μ = (μ_b w′/γ₂ + ∫τ dx) / w′. With λ → 0 (h_c,s → 0, where the asperities can carry
the load) γ₂ → 1 and the film's pressure, hence its limiting shear, vanish: μ → μ_b. With
λ ≫ 3, F_{5/2} → 0, γ₁ → 1 and μ is the film shear alone. μ is continuous in between.

Units: the toolkit's (MPa, mm, N/mm, m/s, Pa s, 1/GPa, µm); SI inside.

The model is registered as ``"mixed_ehl"`` in :mod:`friction.coefficient`.
"""

from __future__ import annotations

import logging
import math
import warnings
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import CubicSpline
from scipy.optimize import elementwise
from scipy.special import gamma, ndtr, pbdv

from friction.film import DOWSON_TOYODA_EXPONENTS, dowson_toyoda_central
from friction.validity import FrictionModelRangeWarning
from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.validation import broadcast, real_array, scalar_or_array

__all__ = [
    "FILM_GAMMA_EXPONENT",
    "MIXED_EHL_DEFAULTS",
    "MIXED_EHL_VALIDITY",
    "MixedEHL",
    "asperity_pressure",
    "eyring_shear_stress",
    "greenwood_tripp_integral",
    "mixed_ehl",
    "mixed_ehl_solution",
    "mixed_ehl_validity",
    "smooth_film",
]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]

#: Default model parameters: name → (value, "[units] meaning; source").
MIXED_EHL_DEFAULTS: Mapping[str, tuple[float, str]] = MappingProxyType(
    {
        "eyring_stress": (
            5.0,
            "[MPa] Eyring stress τ₀ of the film; mineral gear oils in EHL traction tests lie"
            " at about 2–10 MPa (Evans & Johnson 1986; Johnson & Tevaarwerk 1977) — 5 MPa"
            " is an assumed mid value (the seed gives none for its 75W90)",
        ),
        "limiting_shear_coefficient": (
            0.08,
            "[1] Λ = τ_L/p, the pressure coefficient of the limiting shear stress;"
            " 0.07–0.1 for mineral oils (Bair & Winer 1979; Höglund 1999) — assumed 0.08",
        ),
        "boundary_friction": (
            0.1,
            "[1] μ_b, friction of the asperity contacts under boundary films (seed Eq. 5.8"
            " 'dry contact friction coefficient'); 0.08–0.13 is the usual range for steel"
            " with additive-containing oils — assumed 0.1, the same value as the stochastic"
            " solver and the kolivand2009 fit (the oil file's boundary_friction)",
        ),
        "asperity_density_radius_sigma": (
            0.05,
            "[1] ηβσ, summit density × summit radius × RMS roughness; 0.03–0.05 on the"
            " engineering surfaces measured by Greenwood & Williamson (1966) — upper value;"
            " McCool's (1986) summit statistics of the toolkit's ground profile (the"
            " stochastic solver's, friction.ehl.roughness.GroundSurface seeds 1 and 2 through"
            " λs 8 µm) give 0.056 at any Rq (issue 61)",
        ),
        "sigma_over_beta": (
            0.01,
            "[1] σ/β, composite RMS roughness over summit radius, held fixed (the summits'"
            " radius grows with Rq); 0.01 gives β ≈ 110 µm at σ = 1.13 µm (Rq 0.8 µm per"
            " flank) — assumed, the order of ground steel. The toolkit's ground profile"
            " scaled in height (β ∝ 1/σ) gives σ/β = 0.154 σ² [σ in µm] instead (0.09 at the"
            " run-in Rq 0.544 µm): with it the flank μ falls with torque and is 1.95× ISO/TR"
            " 14179-2 at 50 N·m (docs/friction.md, 'Which model is the default'), which the"
            " measured correlation contradicts — so the fixed ratio is kept",
        ),
    }
)

#: Declared validity of the model: name → (low, high, units, reason).
MIXED_EHL_VALIDITY: Mapping[str, tuple[float, float, str, str]] = MappingProxyType(
    {
        "hertz_pressure": (
            0.0, 2500.0, "MPa",
            "Barus viscosity beyond α p ≈ 25 exceeds Roelands' by orders of magnitude, so"
            " the film shear rests on the limiting-shear cap alone",
        ),
        "entraining_velocity": (
            0.1, math.inf, "m/s",
            "the EHL film formula needs entraining motion; below 0.1 m/s the inlet is"
            " starved of the rolling that builds the film",
        ),
    }
)

# Gauss–Legendre nodes over θ ∈ (−π/2, π/2), x = b sin θ: the Hertz profile
# p = p_h cos θ and dx = b cos θ dθ are smooth in θ, so 24 nodes integrate the film
# shear to ~1e-5 relative (the kink where the limiting shear takes over limits the
# order; tested against an adaptive quadrature).
_N_QUAD = 24
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(_N_QUAD)
#: Gauss–Legendre nodes (cosines) and weights over the contact half-width θ ∈ [0, π/2],
#: shared with friction.thermal_eyring
COS_THETA = np.cos(0.5 * math.pi * _NODES)
W_THETA = 0.5 * math.pi * _WEIGHTS

#: h_c ∝ γ₁^(p_U − p_G) under the JGP scaling w′ → w′/γ₁, E′ → E′/γ₁ (U → γ₁U, G → G/γ₁).
FILM_GAMMA_EXPONENT = DOWSON_TOYODA_EXPONENTS[0] - DOWSON_TOYODA_EXPONENTS[1]
_FILM_GAMMA_EXPONENT = FILM_GAMMA_EXPONENT

#: Greenwood–Tripp constant for E′ = 2E*: (16√2/15)π multiplies E* for two rough
#: surfaces, hence (8√2/15)π with E′ (derived in tests/test_ehl_solver.py from the sum over
#: summit pairs). Until issue 33 this was 16√2/15 π with E′, 2× too large.
_GT_CONSTANT = 8.0 * math.sqrt(2.0) / 15.0 * math.pi


def greenwood_tripp_integral(order: float, separation: ArrayLike) -> NDArray[np.float64] | float:
    """F_n(h) = (1/√(2π)) ∫_h^∞ (s − h)^n e^(−s²/2) ds for a Gaussian height distribution.

    Parameters
    ----------
    order : float
        n ≥ 0 (5/2 for the Greenwood–Tripp asperity pressure).
    separation : float or array — [1]
        Mean-plane separation over the composite RMS roughness, h/σ (any real value).

    Returns
    -------
    float or array — [1]
        F_n(h) > 0, decreasing in h.

    Raises
    ------
    InputError
        A non-finite separation or a negative order.

    Notes
    -----
    Source: Greenwood, J. A., Tripp, J. H., "The contact of two nominally flat rough
    surfaces", Proc. Instn Mech. Engrs 185 (1970) 625–633 (the F_n integrals;
    Greenwood & Williamson 1966 for n = 0, 1, 3/2). Evaluated in closed form:
    ∫₀^∞ t^n e^(−(t+h)²/2) dt = Γ(n+1) e^(−h²/4) D_(−n−1)(h), D the parabolic cylinder
    function (Abramowitz & Stegun 19.5.3 / Gradshteyn & Ryzhik 3.462.1), so
    F_n(h) = Γ(n+1) e^(−h²/4) D_(−n−1)(h)/√(2π).
    """
    n = float(real_array("order", order, low=0.0, unit="1"))
    h = real_array("separation", separation, unit="1")
    d, _ = pbdv(-n - 1.0, h)
    return scalar_or_array(gamma(n + 1.0) / math.sqrt(2 * math.pi) * np.exp(-h * h / 4.0) * d)


def asperity_pressure(
    separation: ArrayLike,
    e_prime: ArrayLike,
    *,
    asperity_density_radius_sigma: float = MIXED_EHL_DEFAULTS["asperity_density_radius_sigma"][0],
    sigma_over_beta: float = MIXED_EHL_DEFAULTS["sigma_over_beta"][0],
) -> NDArray[np.float64] | float:
    """Greenwood–Tripp nominal asperity pressure p_a = K′ E′ F_{5/2}(h/σ).

    K′ = (8√2/15) π (ηβσ)² √(σ/β) with E′ = 2E*, i.e. (16√2/15) π (ηβσ)² √(σ/β) E* for two
    rough surfaces of summit density η, summit radius β and composite summit-height RMS σ.

    Parameters
    ----------
    separation : float or array — [1]
        Mean-plane separation over composite roughness, h/σ.
    e_prime : float or array — [MPa]
        Effective modulus E′ = 2E* (:mod:`friction.film` convention), > 0.
    asperity_density_radius_sigma : float — [1]
        ηβσ, in (0, 1].
    sigma_over_beta : float — [1]
        σ/β, in (0, 1].

    Returns
    -------
    float or array — [MPa]
        Nominal (area-averaged) pressure carried by the asperities.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Greenwood & Tripp (1970), in the form used for mixed lubrication by Hu, Y.,
    Cheng, H. S., Arai, T., Kobayashi, Y., Aoyama, S., "Numerical simulation of piston
    ring in mixed lubrication", J. Tribol. 116 (1994) 470–478, and Arcoumanis, C.,
    Ostovar, P., Mortier, R., "Mixed lubrication modelling of Newtonian and shear thinning
    liquids in a piston-ring configuration", SAE 972924 (1997). The constant is quoted
    as 8√2/15 or 16√2/15 by different authors, with E′ = E* or 2E*; summing the Hertz
    loads of all summit pairs of two rough surfaces gives (16√2/15)π with E* (Greenwood &
    Tripp 1970), hence (8√2/15)π with the toolkit's E′ = 2E* (the test derives it).

    :func:`mixed_ehl_solution` evaluates it at the separation whose mean gap is the film's
    (:func:`separation_of_mean_gap`), negative as the film closes, so it is not capped at
    K′E′F_{5/2}(0) (≈ 83 MPa with the defaults; it was before issue 61).
    """
    h = real_array("separation", separation, unit="1")
    e = real_array("e_prime", e_prime, low=0.0, low_open=True, unit="MPa")
    ebs, sb = _roughness_parameters(asperity_density_radius_sigma, sigma_over_beta)
    h, e = broadcast(separation=h, e_prime=e)
    k = _roughness_constant(ebs, sb)
    return scalar_or_array(k * e * np.asarray(greenwood_tripp_integral(2.5, h)))


def _roughness_parameters(density_radius_sigma: float, sigma_over_beta: float
                          ) -> tuple[float, float]:
    """ηβσ and σ/β [1] validated: each a scalar in (0, 1]."""
    ebs = float(real_array("asperity_density_radius_sigma", density_radius_sigma,
                           low=0.0, low_open=True, high=1.0, unit="1"))
    sb = float(real_array("sigma_over_beta", sigma_over_beta, low=0.0, low_open=True, high=1.0,
                          unit="1"))
    return ebs, sb


def _roughness_constant(density_radius_sigma: float, sigma_over_beta: float) -> float:
    """Greenwood–Tripp K′ = (8√2/15) π (ηβσ)² √(σ/β) [1] for E′ = 2E*.

    See :func:`asperity_pressure`.
    """
    return _GT_CONSTANT * density_radius_sigma**2 * math.sqrt(sigma_over_beta)


def eyring_shear_stress(
    viscosity: ArrayLike, shear_rate: ArrayLike, eyring_stress: ArrayLike
) -> NDArray[np.float64] | float:
    """Eyring (sinh-law) shear stress τ = τ₀ asinh(η γ̇ / τ₀).

    Parameters
    ----------
    viscosity : float or array — [Pa s]
        Local (pressure-raised) viscosity η, > 0.
    shear_rate : float or array — [1/s]
        γ̇ ≥ 0.
    eyring_stress : float or array — [MPa]
        τ₀ > 0.

    Returns
    -------
    float or array — [MPa]
        τ; Newtonian η γ̇ for η γ̇ ≪ τ₀, τ₀ ln(2 η γ̇/τ₀) for η γ̇ ≫ τ₀.

    Raises
    ------
    InputError
        An input outside its range.

    Notes
    -----
    Source: Eyring, H., "Viscosity, plasticity and diffusion as examples of absolute
    reaction rates", J. Chem. Phys. 4 (1936) 283; for EHL traction Johnson, K. L.,
    Tevaarwerk, J. L., "Shear behaviour of elastohydrodynamic oil films", Proc. R. Soc.
    Lond. A 356 (1977) 215–236 and Evans, C. R., Johnson, K. L., "The rheological
    properties of elastohydrodynamic lubricants", Proc. Instn Mech. Engrs C 200 (1986)
    303–312 (the viscous/non-linear regimes of the traction curve).
    """
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, unit="Pa s")
    rate = real_array("shear_rate", shear_rate, low=0.0, unit="1/s")
    tau0 = real_array("eyring_stress", eyring_stress, low=0.0, low_open=True, unit="MPa")
    eta, rate, tau0 = broadcast(viscosity=eta, shear_rate=rate, eyring_stress=tau0)
    with np.errstate(over="ignore"):
        arg = eta * rate / (tau0 * 1e6)
    return scalar_or_array(tau0 * np.arcsinh(arg))


class MixedEHL(NamedTuple):
    """Per-point solution of the mixed-EHL friction model (arrays of the broadcast shape).

    Attributes
    ----------
    friction_coefficient : array — [1] μ
    film_friction : array — [1] the film's share of μ, ∫τ dx / w′
    boundary_friction : array — [1] the asperities' share of μ, μ_b/γ₂
    asperity_load_share : array — [1] 1/γ₂ ∈ [0, 1)
    film_thickness : array — [µm] central film h_c with load sharing (thermal factor applied)
    smooth_film_thickness : array — [µm] h_c,s, the smooth-surface central film (γ₁ = 1)
    lambda_central : array — [1] h_c/σ
    valid : array of bool — inside :data:`MIXED_EHL_VALIDITY`
    """

    friction_coefficient: Array
    film_friction: Array
    boundary_friction: Array
    asperity_load_share: Array
    film_thickness: Array
    smooth_film_thickness: Array
    lambda_central: Array
    valid: NDArray[np.bool_]


@memoised(maxsize=None)
def _ln_f52_spline() -> CubicSpline:
    """Cubic spline of ln F_{5/2}(h) on h ∈ [−6, 14] (2001 nodes, |relative error| < 1e-8
    against :func:`greenwood_tripp_integral`, tested) — built once, on first use."""
    h = np.linspace(_F52_LOW, _F52_HIGH, 2001)
    return CubicSpline(h, np.log(np.asarray(greenwood_tripp_integral(2.5, h))))


_F52_LOW, _F52_HIGH = -6.0, 14.0


def _f52(h: Array) -> Array:
    """F_{5/2}(h) [1] fast: the spline inside [−6, 14], 0 above (F < 1e-45), exact below."""
    h = np.asarray(h, float)
    out = np.exp(_ln_f52_spline()(np.clip(h, _F52_LOW, _F52_HIGH)))
    out = np.where(h > _F52_HIGH, 0.0, out)
    low = h < _F52_LOW
    if np.any(low):
        out[low] = np.asarray(greenwood_tripp_integral(2.5, h[low]))
    return out


def separation_of_mean_gap(mean_gap_ratio: ArrayLike) -> Array:
    """t = h/σ [1] whose Gaussian mean gap t Φ(t) + φ(t) equals ``mean_gap_ratio`` = h_T/σ.

    Parameters
    ----------
    mean_gap_ratio : array — [1]
        h_T/σ > 0.

    Returns
    -------
    array — [1]
        t, the same shape: ≈ h_T/σ for thick films (h_T/σ ≳ 3), negative below
        h_T/σ = φ(0) ≈ 0.399 (the mean planes overlap; the oil in the valleys), → −∞ as
        h_T/σ → 0.

    Notes
    -----
    Patir & Cheng (1978), the average gap of Gaussian heights (as
    :func:`friction.ehl.flow_factors.mean_gap`). Newton's method on ln g(t), g = tΦ + φ,
    whose derivative Φ/g is positive (g is increasing and log-concave), from
    t = max(g, −√(−2 ln(√(2π) g))) (the asymptotes of both ends); 60 steps, each bounded
    to 4, reach round-off.
    """
    g = np.asarray(mean_gap_ratio, dtype=float)
    with np.errstate(divide="ignore"):
        t = np.where(g > 0.4, g, -np.sqrt(np.maximum(-2.0 * np.log(
            np.sqrt(2.0 * math.pi) * np.maximum(g, 1e-300)), 0.0)))
    for _ in range(60):
        cdf = ndtr(t)
        val = t * cdf + np.exp(-0.5 * t * t) / math.sqrt(2.0 * math.pi)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = (np.log(val) - np.log(g)) * val / cdf
        step = np.clip(np.nan_to_num(step, nan=0.0), -4.0, 4.0)
        t = t - step
        if np.all(np.abs(step) < 1e-13 * np.maximum(1.0, np.abs(t))):
            break
    return t


def _share_equation(x: Array, h_s: Array, p_mean: Array, k_e: Array,
                    f52: Callable[[Array], Array] = _f52) -> Array:
    """JGP load balance in x = ln γ₁ [1]: p_a(h(γ₁)) − p̄ (1 − 1/γ₁) [MPa] with h the
    separation of the film's mean gap h_c(γ₁) (:func:`separation_of_mean_gap`); decreasing
    in x (h_s = h_c,s/σ [1], p̄ [MPa], k_e = K E′ [MPa], ``f52`` the heights' F_{5/2})."""
    lam = h_s * np.exp(_FILM_GAMMA_EXPONENT * x)
    return k_e * f52(separation_of_mean_gap(lam)) - p_mean * (-np.expm1(-x))


def smooth_film(*, load_per_length: ArrayLike, hertz_pressure: ArrayLike, radius: ArrayLike,
                e_prime: ArrayLike, entraining_velocity: ArrayLike,
                sliding_velocity: ArrayLike, viscosity: ArrayLike,
                pressure_viscosity: ArrayLike, roughness_1: ArrayLike,
                roughness_2: ArrayLike, thermal_factor: ArrayLike, eyring_stress: float,
                limiting_shear_coefficient: float, boundary_friction: float) -> tuple:
    """The inputs of :func:`mixed_ehl_solution` checked and broadcast, with the composite
    roughness, the validity flags and the smooth-surface central film.

    Parameters
    ----------
    load_per_length … thermal_factor : float or array
        As :func:`mixed_ehl_solution` ([N/mm], [MPa], [mm], [MPa], [m/s], [m/s], [Pa s],
        [1/GPa], [µm], [µm], [1]).
    eyring_stress, limiting_shear_coefficient, boundary_friction : float
        As :func:`mixed_ehl_solution` ([MPa], [1], [1]).

    Returns
    -------
    tuple
        (w′ [N/mm], p_h [MPa], R [mm], E′ [MPa], u [m/s], V_s [m/s], η₀ [Pa s], α [1/GPa],
        Rq₁ [µm], Rq₂ [µm], φ_T [1], τ₀ [MPa], Λ [1], μ_b [1], σ [µm], valid [bool],
        h_c,s [µm]), the arrays broadcast to one shape; h_c,s = φ_T h_DT the
        smooth-surface central film of Dowson & Toyoda (1979).

    Raises
    ------
    InputError
        An input outside its accepted range (the message names it).

    Warns
    -----
    FrictionModelRangeWarning
        Points outside :data:`MIXED_EHL_VALIDITY`.

    Notes
    -----
    Source: Dowson, D., Toyoda, S., "A central film thickness formula for elastohydrodynamic
    line contacts", Proc. 5th Leeds–Lyon Symposium (1979) 60–65. Shared with
    ``thermal_eyring``'s Zhou & Hoeprich sharing, which needs the film but not the JGP
    balance.
    """
    w = real_array("load_per_length", load_per_length, low=0.0, low_open=True, unit="N/mm")
    ph = real_array("hertz_pressure", hertz_pressure, low=0.0, low_open=True, unit="MPa")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    e = real_array("e_prime", e_prime, low=0.0, low_open=True, unit="MPa")
    u = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True,
                   unit="m/s")
    vs = real_array("sliding_velocity", sliding_velocity, low=0.0, unit="m/s")
    eta0 = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    alpha = real_array("pressure_viscosity", pressure_viscosity, low=0.1, high=100.0,
                       unit="1/GPa")
    s1 = real_array("roughness_1", roughness_1, low=0.0, high=100.0, unit="µm")
    s2 = real_array("roughness_2", roughness_2, low=0.0, high=100.0, unit="µm")
    phi = real_array("thermal_factor", thermal_factor, low=0.0, low_open=True, high=1.0,
                     unit="1")
    tau0 = float(real_array("eyring_stress", eyring_stress, low=0.0, low_open=True, unit="MPa"))
    lam_l = float(real_array("limiting_shear_coefficient", limiting_shear_coefficient,
                             low=0.0, low_open=True, high=1.0, unit="1"))
    mu_b = float(real_array("boundary_friction", boundary_friction, low=0.0, high=1.0, unit="1"))
    w, ph, r, e, u, vs, eta0, alpha, s1, s2, phi = broadcast(
        load_per_length=w, hertz_pressure=ph, radius=r, e_prime=e, entraining_velocity=u,
        sliding_velocity=vs, viscosity=eta0, pressure_viscosity=alpha, roughness_1=s1,
        roughness_2=s2, thermal_factor=phi,
    )
    sigma = np.hypot(s1, s2)
    if np.any(sigma <= 0.0):
        raise InputError("roughness_1, roughness_2: the composite roughness √(Rq₁² + Rq₂²)"
                         " must be > 0 [µm] (λ = h/σ is undefined for smooth surfaces)")
    valid = np.ones(w.shape, dtype=bool)
    for name, vals in (("hertz_pressure", ph), ("entraining_velocity", u)):
        lo, hi, units, why = MIXED_EHL_VALIDITY[name]
        out = (vals < lo) | (vals > hi)
        if np.any(out):
            valid &= ~out
            warnings.warn(
                f"mixed_ehl: {name} outside [{lo:g}, {hi:g}] [{units}] at"
                f" {int(np.count_nonzero(out))} of {vals.size} point(s) (e.g."
                f" {vals[out].flat[0]:g}): {why}; result extrapolated",
                FrictionModelRangeWarning,
                stacklevel=3,
            )
    h_s = np.asarray(dowson_toyoda_central(u, eta0, alpha, w, r, e), float) * phi  # µm
    return (w, ph, r, e, u, vs, eta0, alpha, s1, s2, phi, tau0, lam_l, mu_b, sigma, valid,
            h_s)


def mixed_ehl_solution(
    *,
    load_per_length: ArrayLike,
    hertz_pressure: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
    entraining_velocity: ArrayLike,
    sliding_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
    thermal_factor: ArrayLike = 1.0,
    eyring_stress: float = MIXED_EHL_DEFAULTS["eyring_stress"][0],
    limiting_shear_coefficient: float = MIXED_EHL_DEFAULTS["limiting_shear_coefficient"][0],
    boundary_friction: float = MIXED_EHL_DEFAULTS["boundary_friction"][0],
    asperity_density_radius_sigma: float = MIXED_EHL_DEFAULTS["asperity_density_radius_sigma"][0],
    sigma_over_beta: float = MIXED_EHL_DEFAULTS["sigma_over_beta"][0],
    height_integral: Callable[[Array], Array] | None = None,
) -> MixedEHL:
    """Load sharing, film and friction of the mixed-EHL model (see the module docstring).

    Parameters
    ----------
    load_per_length : float or array — [N/mm]
        Normal load per unit length w′, > 0.
    hertz_pressure : float or array — [MPa]
        Peak Hertz pressure p_h of the segment, > 0; the Hertz half-width is
        b = 2w′/(π p_h) and the mean pressure p̄ = π p_h/4.
    radius : float or array — [mm]
        Equivalent radius R, > 0.
    e_prime : float or array — [MPa]
        Effective modulus E′ = 2E*, > 0.
    entraining_velocity : float or array — [m/s]
        Mean entraining velocity u = (u₁ + u₂)/2, > 0.
    sliding_velocity : float or array — [m/s]
        V_s = |u₁ − u₂| ≥ 0.
    viscosity : float or array — [Pa s]
        Inlet dynamic viscosity η₀.
    pressure_viscosity : float or array — [1/GPa]
        Barus pressure–viscosity coefficient α at the inlet temperature.
    roughness_1, roughness_2 : float or array — [µm]
        RMS roughness of each surface; σ = √(Rq₁² + Rq₂²) > 0.
    thermal_factor : float or array — [1]
        φ_T ∈ (0, 1] multiplying the isothermal film (:func:`friction.film.
        thermal_reduction_factor`); 1 is isothermal.
    eyring_stress, limiting_shear_coefficient, boundary_friction,
    asperity_density_radius_sigma, sigma_over_beta : float
        Model parameters; defaults and sources in :data:`MIXED_EHL_DEFAULTS`
        ([MPa], [1], [1], [1], [1]).
    height_integral : callable, optional
        F_{5/2}(t) [1] of the composite surface's height distribution at t = h/σ, i.e.
        E[(z − t)₊^{5/2}] for heights z of unit variance (e.g. the ground flanks' skewed
        heights, :func:`friction.flank_summits.height_tail_integral`); default the
        Gaussian's, :func:`greenwood_tripp_integral`. Positive, decreasing.

    Returns
    -------
    MixedEHL

    Raises
    ------
    InputError
        An input outside its accepted range (the message names it).

    Warns
    -----
    FrictionModelRangeWarning
        Points outside :data:`MIXED_EHL_VALIDITY` (flagged ``valid = False``).

    Notes
    -----
    Sources: Johnson, K. L., Greenwood, J. A., Poon, S. Y., "A simple theory of asperity
    contact in elastohydrodynamic lubrication", Wear 19 (1972) 91–108 (load sharing and
    the scaling of the film with γ₁); Greenwood & Tripp (1970) (asperity pressure, see
    :func:`asperity_pressure`); Dowson & Toyoda (1979) (central film); Gupta et al. (1992)
    (thermal factor, via the caller); Eyring/Johnson & Tevaarwerk (1977) (film shear,
    :func:`eyring_shear_stress`); Bair, S., Winer, W. O., "A rheological model for
    elastohydrodynamic contacts based on primary laboratory data", J. Lubr. Technol. 101
    (1979) 258–265 (limiting shear stress ∝ pressure); seed Eq. 5.7–5.9 (film shear plus
    boundary friction on the asperity contacts). The same scheme computes Stribeck curves
    in Gelinck, E. R. M., Schipper, D. J., "Calculation of Stribeck curves for line
    contacts", Tribol. Int. 33 (2000) 175–181 (there with Moes' film formula and a
    Greenwood–Williamson asperity model). Assumptions: uniform film h_c over the Hertz
    zone; the film's pressure is the Hertz profile scaled by 1/γ₁ (JGP); isothermal
    shear in the film (no flash-temperature correction of η).
    """
    (w, ph, _r, e, _u, vs, eta0, alpha, _s1, _s2, _phi, tau0, lam_l, mu_b, sigma, valid,
     h_s) = smooth_film(
        load_per_length=load_per_length, hertz_pressure=hertz_pressure, radius=radius,
        e_prime=e_prime, entraining_velocity=entraining_velocity,
        sliding_velocity=sliding_velocity, viscosity=viscosity,
        pressure_viscosity=pressure_viscosity, roughness_1=roughness_1,
        roughness_2=roughness_2, thermal_factor=thermal_factor, eyring_stress=eyring_stress,
        limiting_shear_coefficient=limiting_shear_coefficient,
        boundary_friction=boundary_friction)
    k_e = _roughness_constant(*_roughness_parameters(asperity_density_radius_sigma,
                                                     sigma_over_beta)) * e  # K E′ [MPa]
    p_mean = 0.25 * math.pi * ph
    lam_s = h_s / sigma
    # ln γ₁ from the load balance; γ₁ = 1 (no asperity load) where F_{5/2} underflows
    x = _solve_share(lam_s, p_mean, k_e, _f52 if height_integral is None else height_integral)
    gamma1 = np.exp(x)
    share_a = -np.expm1(-x)  # 1/γ₂ = 1 − 1/γ₁
    h_c = h_s * gamma1**_FILM_GAMMA_EXPONENT
    # film shear over the Hertz zone (θ quadrature, module constants)
    b = 2.0 * w / (math.pi * ph)  # mm
    p_film = (ph / gamma1)[..., None] * COS_THETA  # MPa
    with np.errstate(over="ignore"):
        eta = eta0[..., None] * np.exp(alpha[..., None] * 1e-3 * p_film)
    rate = (vs / (h_c * 1e-6))[..., None]  # 1/s
    tau = np.minimum(np.asarray(eyring_shear_stress(eta, rate, tau0)),
                     lam_l * p_film)  # MPa
    film_force = b * np.sum(tau * COS_THETA * W_THETA, axis=-1)  # MPa·mm = N/mm
    mu_film = film_force / w
    mu_bound = mu_b * share_a
    return MixedEHL(
        friction_coefficient=mu_film + mu_bound,
        film_friction=mu_film,
        boundary_friction=mu_bound,
        asperity_load_share=share_a,
        film_thickness=h_c,
        smooth_film_thickness=h_s,
        lambda_central=h_c / sigma,
        valid=valid,
    )


def _solve_share(lam_s: Array, p_mean: Array, k_e: Array,
                 f52: Callable[[Array], Array] = _f52) -> Array:
    """x = ln γ₁ ≥ 0 of the JGP load balance for each point (λ_s = h_c,s/σ [1], p̄ and
    K E′ [MPa]): 0 where the asperities carry nothing, else the root bracketed in
    [0, x_hi] by scipy's elementwise bracketing root finder (the balance is monotonic)."""
    x = np.zeros(lam_s.shape)
    need = f52(separation_of_mean_gap(lam_s)) * k_e > 1e-12 * p_mean
    if not np.any(need):
        return x
    ls, pm, ke = lam_s[need], p_mean[need], k_e[need]
    hi = np.full(ls.shape, 1.0)
    for _ in range(200):  # widen the bracket until the balance changes sign
        pos = _share_equation(hi, ls, pm, ke, f52) > 0
        if not np.any(pos):
            break
        hi = np.where(pos, 2.0 * hi, hi)
    res = elementwise.find_root(lambda x, a, b, c: _share_equation(x, a, b, c, f52),
                                (np.zeros_like(ls), hi), args=(ls, pm, ke),
                                tolerances={"xatol": 1e-12, "xrtol": 1e-12})
    x[need] = res.x
    return x


def mixed_ehl(
    *,
    load_per_length: ArrayLike,
    hertz_pressure: ArrayLike,
    radius: ArrayLike,
    e_prime: ArrayLike,
    entraining_velocity: ArrayLike,
    sliding_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
    thermal_factor: ArrayLike = 1.0,
    eyring_stress: float = MIXED_EHL_DEFAULTS["eyring_stress"][0],
    limiting_shear_coefficient: float = MIXED_EHL_DEFAULTS["limiting_shear_coefficient"][0],
    boundary_friction: float = MIXED_EHL_DEFAULTS["boundary_friction"][0],
    asperity_density_radius_sigma: float = MIXED_EHL_DEFAULTS["asperity_density_radius_sigma"][0],
    sigma_over_beta: float = MIXED_EHL_DEFAULTS["sigma_over_beta"][0],
) -> NDArray[np.float64] | float:
    """Mixed-EHL friction coefficient μ (load sharing + Eyring film + boundary friction).

    Parameters
    ----------
    As :func:`mixed_ehl_solution`.

    Returns
    -------
    float or array — [1]
        μ of the broadcast shape.

    Raises
    ------
    InputError
        An input outside its accepted range.

    Warns
    -----
    FrictionModelRangeWarning
        Points outside :data:`MIXED_EHL_VALIDITY`.

    Notes
    -----
    Sources: see :func:`mixed_ehl_solution` (Johnson, Greenwood & Poon 1972; Greenwood &
    Tripp 1970; Dowson & Toyoda 1979; Eyring/Johnson & Tevaarwerk 1977; Bair & Winer
    1979; seed Eq. 5.7–5.9).
    """
    sol = mixed_ehl_solution(
        load_per_length=load_per_length, hertz_pressure=hertz_pressure, radius=radius,
        e_prime=e_prime, entraining_velocity=entraining_velocity,
        sliding_velocity=sliding_velocity, viscosity=viscosity,
        pressure_viscosity=pressure_viscosity, roughness_1=roughness_1,
        roughness_2=roughness_2, thermal_factor=thermal_factor, eyring_stress=eyring_stress,
        limiting_shear_coefficient=limiting_shear_coefficient,
        boundary_friction=boundary_friction,
        asperity_density_radius_sigma=asperity_density_radius_sigma,
        sigma_over_beta=sigma_over_beta,
    )
    return scalar_or_array(sol.friction_coefficient)


def mixed_ehl_validity(
    *, hertz_pressure: ArrayLike, entraining_velocity: ArrayLike, **_: object
) -> NDArray[np.bool_]:
    """Which points lie inside the mixed-EHL model's declared validity.

    Parameters
    ----------
    hertz_pressure : float or array — [MPa]
    entraining_velocity : float or array — [m/s]
    **_ :
        Other model inputs (ignored).

    Returns
    -------
    array of bool
        True inside :data:`MIXED_EHL_VALIDITY`, broadcast shape.

    Notes
    -----
    Source: :data:`MIXED_EHL_VALIDITY` (reasons there).
    """
    ph = np.asarray(hertz_pressure, float)
    u = np.asarray(entraining_velocity, float)
    ph, u = np.broadcast_arrays(ph, u)
    ok = np.ones(ph.shape, dtype=bool)
    for name, vals in (("hertz_pressure", ph), ("entraining_velocity", u)):
        lo, hi, _units, _why = MIXED_EHL_VALIDITY[name]
        ok &= (vals >= lo) & (vals <= hi)
    return ok
