"""Thermal Eyring film shear on the mixed-EHL load sharing: the default friction model.

``mixed_ehl`` (:mod:`friction.mixed_ehl`) shears its film isothermally at the inlet oil
temperature, so its full-film friction settles near the Eyring plateau and *rises* with
speed (issue 74: +24 % from 100 to 6000 rpm where ISO/TR 14179-2 falls 56 %). This model
shares the load between the asperities and the film by default with Zhou & Hoeprich's
(1991) asperity load ratio N_a/N = exp(−B Λ^C) (``load_sharing="zhou_hoeprich"``,
:func:`zhou_hoeprich_share`: a fit to deterministic contact simulations of run-in ground
profiles, where the film is the average gap and the mean planes may overlap; B 1.90, C
0.99 as printed for a ground surface of σ 0.24 µm), the film carrying the rest with
Johnson, Greenwood & Poon's (1972) scaling (γ₁ = 1/(1 − N_a/N), film pressure p_h/γ₁,
central film h_c,s γ₁^0.13). ``load_sharing="johnson_greenwood_poon"`` keeps
``mixed_ehl``'s sharing instead (γ₁, h_c and the share from
:func:`friction.mixed_ehl.mixed_ehl_solution`, Greenwood & Tripp 1970), with the
asperities' ηβσ and σ/β derived from the flanks' roughness (``summits="ground"``:
McCool's summits of the ground profile scaled to Rq, :mod:`friction.flank_summits`) or
``mixed_ehl``'s fixed constants; that sharing turns boundary (share ≥ 0.98) from λ ≈
0.09–0.15 where deterministic mixed-EHL solutions (Zhu & Wang 2012) keep 10–15 % of the
load on the film down to λ ≈ 0.05–0.1 (docs/friction.md, issue 74). Either way it keeps
``mixed_ehl``'s boundary friction μ_b on the asperities' share and replaces the film
shear with a *thermal* Eyring shear:
at every quadrature node of the Hertz zone the shear stress τ satisfies

    τ = min(τ₀ asinh(η(p, T_f) V_s / (h_c τ₀)), Λ p),
    η(p, T_f) = η₀ exp(α₀ e^(−β_α (T_f − T₀)) p − β (T_f − T₀)),
    T_f − T₀ = ΔT_s + c_f ΔT_c,
    ΔT_s = (4/(3√π)) q √(2b) / (B (√u₁ + √u₂)),   ΔT_c = q h_c / (8 k),   q = τ V_s,

with p = p_h cos θ / γ₁ (the film's share of the Hertz pressure), T₀ the inlet (bulk)
oil temperature, β the oil's temperature–viscosity coefficient at T₀, β_α = −d ln α/dT
the fall of its pressure–viscosity coefficient with temperature at T₀ (from the oil's α
table; ISO/TR 15144-1's α(θ) relation for a data-sheet oil), k its thermal conductivity,
and

* ΔT_s the surfaces' mean flash temperature under the heat flux q of the film's shear:
  Jaeger's band source at high Péclet number, ΔT(x) = 2q√(x + b)/(√π B √u) for one
  surface moving at u (Carslaw & Jaeger 1959 §10.7), averaged over the band, split
  between the two surfaces so that their temperatures are equal
  (Blok 1937), B = √(K ρ c) the steel's effusivity. The flux is the node's own q, taken
  as if uniform over the band (a local approximation of the convolution in
  :func:`friction.ehl.thermal.flash_temperature`);
* ΔT_c the rise of the film's mid-plane above its walls by conduction of a uniform
  dissipation q/h_c across the film (Couette; Johnson & Greenwood 1980), weighted by
  ``film_heating`` c_f ∈ [0, 1]: 1 is Johnson & Greenwood's uniform shear, 0 the surfaces'
  temperature alone (the stochastic solver's choice, :mod:`friction.ehl.thermal`, which
  argues from shear localisation, Bair, Qureshi & Winer 1993).

The right side decreases with τ (more shear, more heat, thinner oil), so the equation has
one root in [0, τ_iso] (τ_iso the isothermal stress), found per node by a bracketing
root finder (a safeguarded Newton iteration, :func:`_thermal_root`; half the nodes,
the others their mirror images). As V_s → 0 the heating vanishes and the model is ``mixed_ehl``; the
temperature enters through β, β_α and k, which are properties of the oil (its file), so
oils differ only through their data. Mapped against ISO/TR 14179-2 and Xu et al. (2007)
in docs/friction.md ("Mapped against the measured correlations", "Zhou & Hoeprich's load
share"): on the seed's Table 5.4 A and B it meets the 19 rows of issue 74's done-when
(with Johnson, Greenwood & Poon's sharing 17: the roughness cost at 90 °C was 2.4–2.6 ×
ISO's and B's VG 220 at 90 °C −18 %), and on the default case its flank μ is within 0.6–1.4
× ISO/TR 14179-2 at 50 / 250 / 500 N·m and does not fall with torque at 50, 75 and 90 °C
(at 100 °C 1.54 × at 50 N·m).

Assumptions stated (not fitted): τ₀ and Λ independent of temperature; the exponential
η(T) and α(T) with their slopes at the inlet temperature (over large ΔT they overstate
the fall that Vogel's form and the α table give); Barus' η(p); steel surfaces
(K 46 W/(m K), ρ 7850 kg/m³, c 470 J/(kg K)); Zhou & Hoeprich's constants of a bearing's
ground surface of composite σ 0.24 µm for gear flanks of composite run-in σ 0.1–1.25 µm
(an extrapolation in roughness: their surface of σ 0.16 µm, B 2.32, C 0.97, moves the
rows of docs/friction.md by at most 0.2 of the ratio to ISO; neither set is fitted here).

Sources: Zhou, R. S., Hoeprich, M. R., "Torque of tapered roller bearings", J. Tribol. 113
(1991) 590–597, Eq. 29–30 (load share); Wingertszahn, P., Koch, O., Maccioni, L., Concli,
F., Sauer, B., Lubricants 11 (2023) 369, Table 4 (its constants); Johnson, K. L.,
Greenwood, J. A., Poon, S. Y., Wear 19 (1972) 91 (film scaling); Eyring (1936); Johnson,
K. L., Tevaarwerk, J. L., Proc. R. Soc. Lond. A 356
(1977) 215; Johnson, K. L., Greenwood, J. A., "Thermal analysis of an Eyring fluid in
elastohydrodynamic traction", Wear 61 (1980) 353–374; Jaeger, J. C., J. Proc. R. Soc.
N.S.W. 76 (1942) 203; Carslaw, H. S., Jaeger, J. C., *Conduction of Heat in Solids*,
2nd ed. (1959) §10.7; Blok, H., Proc. Gen. Disc.
Lubrication, IMechE 2 (1937) 222; Bair, S., Winer, W. O., J. Lubr. Technol. 101 (1979)
258 (limiting shear stress).

Registered as ``"thermal_eyring"`` in :mod:`friction.coefficient`; the toolkit's default
model since issue 74 (:data:`friction.defaults.DEFAULT_FRICTION_MODEL`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.flank_summits import greenwood_tripp_parameters, height_tail_integral
from friction.mixed_ehl import (
    COS_THETA,
    FILM_GAMMA_EXPONENT,
    MIXED_EHL_DEFAULTS,
    W_THETA,
    MixedEHL,
    eyring_shear_stress,
    mixed_ehl_solution,
    smooth_film,
)
from geometry.core.errors import InputError
from geometry.core.validation import real_array, scalar_or_array

__all__ = ["LOAD_SHARING_LAWS", "STEEL_EFFUSIVITY", "THERMAL_EYRING_DEFAULTS",
           "ZHOU_HOEPRICH_CONSTANTS", "thermal_eyring", "thermal_eyring_film_shear",
           "zhou_hoeprich_share"]

Array = NDArray[np.float64]

#: √(K ρ c) of steel [W s^½/(m² K)]: K 46 W/(m K), ρ 7850 kg/m³, c 470 J/(kg K) (typical
#: case-hardening steel; the effusivity ISO/TS 6336-20 calls the thermal contact
#: coefficient, ≈ 13 000 there too)
STEEL_EFFUSIVITY = math.sqrt(46.0 * 7850.0 * 470.0)
#: mean over the band of Jaeger's high-Péclet rise ΔT(x) = 2q√(x + b)/(√π B √u) under a
#: uniform flux: (4/(3√π)) q √(2b)/(B √u) (the closed form that
#: :func:`friction.ehl.thermal.flash_temperature` is tested against, averaged)
_BAND_MEAN = 4.0 / (3.0 * math.sqrt(math.pi))

#: the quadrature's nodes come in mirrored pairs (an even Gauss–Legendre rule)
_HALF = COS_THETA.size // 2
if COS_THETA.size % 2 or not np.array_equal(COS_THETA[:_HALF], COS_THETA[_HALF:][::-1]):
    raise ImportError("friction.thermal_eyring needs mixed_ehl's θ nodes in mirrored pairs")

#: Default parameters beyond mixed_ehl's: name → (value, "[units] meaning; source").
THERMAL_EYRING_DEFAULTS = {
    "temperature_viscosity": (
        0.03, "[1/K] β of η ∝ exp(−β ΔT) at the inlet temperature; the efficiency stage "
        "passes the oil's (friction.lubricant.temperature_viscosity_coefficient)"),
    "oil_thermal_conductivity": (
        0.135, "[W/(m K)] the oil's; the efficiency stage passes the oil file's"),
    "pressure_viscosity_temperature": (
        0.0, "[1/K] β_α = −d ln α/dT at the inlet temperature (0: α held at the inlet's); "
        "the efficiency stage passes the oil's, from its α table (75W90, Table 5.2: "
        "0.0065 at 90 °C)"),
    "film_heating": (
        1.0, "[1] c_f, weight of the film's Couette mid-plane rise q h/(8k) (Johnson & "
        "Greenwood 1980): 1 uniform shear across the film, 0 the surfaces' flash "
        "temperature alone"),
}


#: The asperity load share laws ``thermal_eyring`` takes (``load_sharing``): name → source.
LOAD_SHARING_LAWS = {
    "johnson_greenwood_poon": (
        "Johnson, Greenwood & Poon, Wear 19 (1972) 91: the film and Greenwood & Tripp's "
        "asperities (the summits of ``summits``) at one mean-plane separation "
        "(friction.mixed_ehl.mixed_ehl_solution)"),
    "zhou_hoeprich": (
        "Zhou, R. S., Hoeprich, M. R., \"Torque of tapered roller bearings\", J. Tribol. 113 "
        "(1991) 590-597, Eq. 29: N_a/N = exp(-B Λ^C), fitted to deterministic contact "
        "simulations of measured run-in ground profiles (elastic-perfectly plastic, "
        "their Fig. 5)"),
}

#: Zhou & Hoeprich's constants (B, C) of N_a/N = exp(−B Λ^C) for ground steel surfaces, as
#: printed in Wingertszahn, Koch, Maccioni, Concli & Sauer, "Predicting friction of tapered
#: roller bearings with detailed multi-body simulation models", Lubricants 11 (2023) 369,
#: Table 4 ("mixed friction parameters ... according to Zhou and Hoeprich", their refs.
#: Teutsch, PhD thesis, TU Kaiserslautern 2005, and Zhou & Hoeprich 1991): name →
#: (B, C, composite σ [µm] of the surfaces they belong to).
ZHOU_HOEPRICH_CONSTANTS = {
    "rib": (1.90, 0.99, 0.24),
    "raceway": (2.32, 0.97, 0.16),
}


def zhou_hoeprich_share(film_ratio: ArrayLike, constants: str | tuple[float, float] = "rib"
                        ) -> NDArray[np.float64] | float:
    """Zhou & Hoeprich's asperity load share N_a/N = exp(−B Λ^C).

    Parameters
    ----------
    film_ratio : float or array — [1]
        Λ ≥ 0, the smooth-surface central film (thermal reduction applied) over the
        composite RMS roughness σ = √(Rq₁² + Rq₂²) (Zhou & Hoeprich's Eq. 30).
    constants : str or (float, float)
        A key of :data:`ZHOU_HOEPRICH_CONSTANTS` (default ``"rib"``: the rougher of the two
        published ground surfaces, σ 0.24 µm) or (B, C), each > 0 [1].

    Returns
    -------
    float or array — [1]
        The share of the load on the asperities, in [0, 1]; 1 at Λ = 0, decreasing.

    Raises
    ------
    InputError
        Λ < 0 or not finite; an unknown name or B, C ≤ 0.

    Notes
    -----
    Source: Zhou & Hoeprich (1991) Eq. 29 (:data:`LOAD_SHARING_LAWS`), a fit to the
    load–average-gap relation of deterministic contact simulations of run-in, filtered
    ground profiles (Lee & Cheng's elastic–perfectly plastic longitudinal-roughness
    model), so the film is the average gap and the mean planes may overlap; the constants
    as printed by Wingertszahn et al. (2023) (:data:`ZHOU_HOEPRICH_CONSTANTS`).
    """
    b, c = _zhou_hoeprich_constants(constants, "constants")
    lam = real_array("film_ratio", film_ratio, low=0.0, unit="1")
    return scalar_or_array(np.exp(-b * np.power(lam, c)))


def _zhou_hoeprich_constants(constants: str | tuple[float, float],
                             field: str = "asperity_load_constants") -> tuple[float, float]:
    """(B, C) of a name of :data:`ZHOU_HOEPRICH_CONSTANTS` or of a pair, checked (errors
    name ``field``)."""
    if isinstance(constants, str):
        if constants not in ZHOU_HOEPRICH_CONSTANTS:
            raise InputError(f"{field}: {constants!r} is not one of "
                             f"{sorted(ZHOU_HOEPRICH_CONSTANTS)} or a pair (B, C)")
        return ZHOU_HOEPRICH_CONSTANTS[constants][:2]
    try:
        b, c = (float(v) for v in constants)
    except (TypeError, ValueError):
        raise InputError(f"{field}: give a name of ZHOU_HOEPRICH_CONSTANTS or a pair (B, C) "
                         f"of positive numbers, not {constants!r}") from None
    if not (b > 0.0 and c > 0.0 and math.isfinite(b) and math.isfinite(c)):
        raise InputError(f"{field}: B and C must be finite and > 0 [1], got ({b:g}, {c:g})")
    return b, c


def thermal_eyring_film_shear(
    *, pressure: ArrayLike, viscosity: ArrayLike, pressure_viscosity: ArrayLike,
    shear_rate_film: ArrayLike, sliding_velocity: ArrayLike, film_thickness: ArrayLike,
    flash_factor: ArrayLike, eyring_stress: float, limiting_shear_coefficient: float,
    temperature_viscosity: float, oil_thermal_conductivity: float, film_heating: float,
    pressure_viscosity_temperature: float = 0.0,
) -> tuple[Array, Array]:
    """The thermal Eyring shear stress τ [MPa] and the film's temperature rise [K] at
    given film pressures (all arrays broadcast together).

    Parameters
    ----------
    pressure : array — [MPa] film pressure p ≥ 0
    viscosity : array — [Pa s] η₀ at the inlet temperature
    pressure_viscosity : array — [1/GPa] α
    shear_rate_film : array — [1/s] V_s/h_c
    sliding_velocity : array — [m/s] V_s
    film_thickness : array — [µm] h_c
    flash_factor : array — [K/(W/m²)] ΔT_s per unit heat flux, (4/(3√π)) √(2b)/(B(√u₁+√u₂))
    eyring_stress : float — [MPa] τ₀
    limiting_shear_coefficient : float — [1] Λ
    temperature_viscosity : float — [1/K] β
    oil_thermal_conductivity : float — [W/(m K)] k
    film_heating : float — [1] c_f
    pressure_viscosity_temperature : float — [1/K] β_α ≥ 0

    Returns
    -------
    (τ, ΔT) : arrays — [MPa], [K]
        The root of τ = min(τ₀ asinh(η(p, T₀ + ΔT(τ)) γ̇/τ₀), Λ p) and its temperature rise;
        η(p, T₀ + ΔT) = η₀ exp(α e^(−β_α ΔT) p − β ΔT).

    Notes
    -----
    Source: see the module docstring (Johnson & Greenwood 1980; Jaeger 1942; Blok 1937).
    """
    p, eta0, alpha, rate, vs, h, flash = np.broadcast_arrays(
        *(np.asarray(a, float) for a in (pressure, viscosity, pressure_viscosity,
                                         shear_rate_film, sliding_velocity, film_thickness,
                                         flash_factor)))
    # ΔT per MPa of τ: q = τ·1e6·V_s [W/m²]
    dt_per_tau = 1e6 * vs * (flash + film_heating * h * 1e-6 / (8.0 * oil_thermal_conductivity))
    cap = limiting_shear_coefficient * p
    ap = alpha * 1e-3 * p  # α₀ p [1]
    with np.errstate(over="ignore"):
        eta_iso = eta0 * np.exp(ap)
    b_a = pressure_viscosity_temperature
    tau_iso = np.minimum(np.asarray(eyring_shear_stress(eta_iso, rate, eyring_stress)), cap)
    tau = np.array(tau_iso, dtype=float)
    need = (tau_iso > 0.0) & (dt_per_tau * tau_iso * (temperature_viscosity + b_a * ap)
                              > 1e-12)
    if np.any(need):
        tau[need] = _thermal_root(
            tau_iso[need], eta0[need] * rate[need] / (eyring_stress * 1e6), ap[need],
            dt_per_tau[need], cap[need], eyring_stress, temperature_viscosity, b_a)
    return tau, dt_per_tau * tau


def thermal_eyring(
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
    temperature_viscosity: float = THERMAL_EYRING_DEFAULTS["temperature_viscosity"][0],
    pressure_viscosity_temperature: float = THERMAL_EYRING_DEFAULTS[
        "pressure_viscosity_temperature"][0],
    oil_thermal_conductivity: float = THERMAL_EYRING_DEFAULTS["oil_thermal_conductivity"][0],
    film_heating: float = THERMAL_EYRING_DEFAULTS["film_heating"][0],
    eyring_stress: float = MIXED_EHL_DEFAULTS["eyring_stress"][0],
    limiting_shear_coefficient: float = MIXED_EHL_DEFAULTS["limiting_shear_coefficient"][0],
    boundary_friction: float = MIXED_EHL_DEFAULTS["boundary_friction"][0],
    asperity_density_radius_sigma: float = MIXED_EHL_DEFAULTS["asperity_density_radius_sigma"][0],
    sigma_over_beta: float = MIXED_EHL_DEFAULTS["sigma_over_beta"][0],
    summits: str = "ground",
    load_sharing: str = "zhou_hoeprich",
    asperity_load_constants: str | tuple[float, float] = "rib",
) -> NDArray[np.float64] | float:
    """Mixed-EHL μ with a thermal Eyring film shear (module docstring).

    Parameters
    ----------
    load_per_length … thermal_factor :
        As :func:`friction.mixed_ehl.mixed_ehl_solution` (toolkit units: N/mm, MPa, mm,
        MPa, m/s, m/s, Pa s, 1/GPa, µm, µm, 1).
    temperature_viscosity : float — [1/K]
        β ≥ 0 of the oil at the inlet temperature (0 with β_α = 0: isothermal, μ =
        ``mixed_ehl``'s).
    pressure_viscosity_temperature : float — [1/K]
        β_α = −d ln α/dT ≥ 0 of the oil at the inlet temperature.
    oil_thermal_conductivity : float — [W/(m K)]
        k > 0 of the oil.
    film_heating : float — [1]
        c_f ∈ [0, 1], weight of the film's Couette rise (:data:`THERMAL_EYRING_DEFAULTS`).
    eyring_stress, limiting_shear_coefficient, boundary_friction : float
        As ``mixed_ehl`` (:data:`friction.mixed_ehl.MIXED_EHL_DEFAULTS`).
    summits : str
        How the asperities follow the roughness: ``"ground"`` (default) Greenwood &
        Tripp's law with ηβσ and σ/β of ground flanks at the given Rq
        (:mod:`friction.flank_summits`: McCool 1986 summits of the scaled ground profile's
        spectral moments); ``"fixed"`` with the constants ``asperity_density_radius_sigma``
        and ``sigma_over_beta`` (``mixed_ehl``'s, issue 74's first version).
    asperity_density_radius_sigma, sigma_over_beta : float
        ηβσ and σ/β [1] of ``summits="fixed"`` (unused otherwise).
    load_sharing : str
        The asperities' share of the load (:data:`LOAD_SHARING_LAWS`): ``"zhou_hoeprich"``
        (default) Zhou & Hoeprich's (1991) N_a/N = exp(−B Λ^C) at the smooth-surface
        central Λ (:func:`zhou_hoeprich_share`; ``summits`` then unused);
        ``"johnson_greenwood_poon"`` the film and Greenwood & Tripp's asperities of
        ``summits`` at one separation (``mixed_ehl``'s). With ``"zhou_hoeprich"`` the film
        carries the rest with JGP's γ₁ = 1/(1 − N_a/N) (film pressure p_h/γ₁, film
        h_c,s γ₁^0.13).
    asperity_load_constants : str or (float, float)
        (B, C) of ``"zhou_hoeprich"``: a key of :data:`ZHOU_HOEPRICH_CONSTANTS` (default
        ``"rib"``) or the pair.

    Returns
    -------
    float or array — [1]
        μ = (μ_b w′/γ₂ + ∫τ dx)/w′, broadcast shape; finite, ≤ μ_b/γ₂ + Λ/γ₁.

    Raises
    ------
    InputError
        An input outside its accepted range (the message names it).

    Warns
    -----
    FrictionModelRangeWarning
        As ``mixed_ehl`` (its validity range).

    Notes
    -----
    Sources: module docstring (Johnson & Greenwood 1980 thermal Eyring traction; Jaeger
    1942 / Carslaw & Jaeger 1959 flash temperature; Blok 1937 partition; Zhou & Hoeprich
    1991 and Johnson, Greenwood & Poon 1972 load sharing).
    """
    beta = float(real_array("temperature_viscosity", temperature_viscosity, low=0.0,
                            high=1.0, unit="1/K"))
    k_oil = float(real_array("oil_thermal_conductivity", oil_thermal_conductivity, low=0.0,
                             low_open=True, high=10.0, unit="W/(m K)"))
    c_f = float(real_array("film_heating", film_heating, low=0.0, high=1.0, unit="1"))
    b_a = float(real_array("pressure_viscosity_temperature", pressure_viscosity_temperature,
                           low=0.0, high=1.0, unit="1/K"))
    if summits not in ("ground", "fixed"):
        raise InputError(f"summits: {summits!r} is not 'ground' or 'fixed'")
    sol = _model_sharing(
        load_sharing=load_sharing, asperity_load_constants=asperity_load_constants,
        summits=summits,
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
    shape = sol.friction_coefficient.shape
    w, ph, u, vs, eta0, alpha = (np.broadcast_to(np.asarray(a, float), shape) for a in (
        load_per_length, hertz_pressure, entraining_velocity, sliding_velocity, viscosity,
        pressure_viscosity))
    gamma1 = 1.0 / (1.0 - sol.asperity_load_share)
    h_c = sol.film_thickness
    b = 2.0 * w / (math.pi * ph)  # mm
    u1 = np.maximum(u + 0.5 * vs, 0.0)
    u2 = np.maximum(u - 0.5 * vs, 0.0)
    flash = _BAND_MEAN * np.sqrt(2.0 * b * 1e-3) / (STEEL_EFFUSIVITY
                                                   * (np.sqrt(u1) + np.sqrt(u2)))
    # the nodes are symmetric about the contact's centre (COS_THETA[i] == COS_THETA[-1 - i]
    # exactly) and so is every input of a node's root: solve the first half, mirror it
    p_film = (ph / gamma1)[..., None] * COS_THETA[:_HALF]
    tau, _ = thermal_eyring_film_shear(
        pressure=p_film, viscosity=eta0[..., None], pressure_viscosity=alpha[..., None],
        shear_rate_film=(vs / (h_c * 1e-6))[..., None], sliding_velocity=vs[..., None],
        film_thickness=h_c[..., None], flash_factor=flash[..., None],
        eyring_stress=eyring_stress, limiting_shear_coefficient=limiting_shear_coefficient,
        temperature_viscosity=beta, oil_thermal_conductivity=k_oil, film_heating=c_f,
        pressure_viscosity_temperature=b_a)
    tau = np.concatenate([tau, tau[..., ::-1]], axis=-1)
    mu_film = b * np.sum(tau * COS_THETA * W_THETA, axis=-1) / w
    return scalar_or_array(mu_film + sol.boundary_friction)


def _model_sharing(*, load_sharing: str, asperity_load_constants: str | tuple[float, float],
                   summits: str, **inputs) -> MixedEHL:
    """The load sharing ``thermal_eyring`` uses (its ``load_sharing``, ``summits`` and
    ``asperity_load_constants``; ``inputs`` as :func:`friction.mixed_ehl.
    mixed_ehl_solution`'s): γ₁ through the share, the film h_c and μ_b × the share."""
    if load_sharing not in LOAD_SHARING_LAWS:
        raise InputError(f"load_sharing: {load_sharing!r} is not one of "
                         f"{sorted(LOAD_SHARING_LAWS)}")
    if load_sharing == "johnson_greenwood_poon":
        return _load_sharing(summits=summits, **inputs)
    constants = _zhou_hoeprich_constants(asperity_load_constants)
    # the smooth-surface film and the validity flags only: the JGP balance (mixed_ehl's
    # share, replaced here) is not solved
    *_, valid, h_s = smooth_film(**{k: v for k, v in inputs.items()
                                     if k not in ("asperity_density_radius_sigma",
                                                  "sigma_over_beta")})
    nan = np.full(h_s.shape, np.nan)
    sol = MixedEHL(friction_coefficient=nan, film_friction=nan, boundary_friction=nan,
                   asperity_load_share=nan, film_thickness=nan, smooth_film_thickness=h_s,
                   lambda_central=nan, valid=valid)
    return _zhou_hoeprich_sharing(sol, inputs["roughness_1"], inputs["roughness_2"],
                                  constants, inputs["boundary_friction"])


def _zhou_hoeprich_sharing(sol: MixedEHL, roughness_1: ArrayLike, roughness_2: ArrayLike,
                           constants: tuple[float, float], boundary_friction: float
                           ) -> MixedEHL:
    """``sol`` (a load-sharing solution, for its smooth-surface film) with Zhou & Hoeprich's
    asperity share at Λ = h_c,s/σ instead of its own: γ₁ = 1/(1 − N_a/N), the film
    h_c,s γ₁^0.13 (JGP's scaling of the film with its load), μ_b N_a/N on the asperities.
    ``friction_coefficient`` and ``film_friction`` are left as the film shear is computed
    by the caller (set to NaN here so that no one reads ``mixed_ehl``'s)."""
    shape = sol.smooth_film_thickness.shape
    sigma = np.broadcast_to(np.hypot(np.asarray(roughness_1, float),
                                     np.asarray(roughness_2, float)), shape)
    share = np.asarray(zhou_hoeprich_share(sol.smooth_film_thickness / sigma, constants),
                       float).reshape(shape)
    # a share of 1 (Λ = 0) would leave no film: the film's γ₁ is capped as mixed_ehl's
    share = np.minimum(share, 1.0 - 1e-12)
    gamma1 = 1.0 / (1.0 - share)
    h_c = sol.smooth_film_thickness * gamma1**FILM_GAMMA_EXPONENT
    nan = np.full(shape, np.nan)
    return MixedEHL(friction_coefficient=nan, film_friction=nan,
                    boundary_friction=boundary_friction * share,
                    asperity_load_share=share, film_thickness=h_c,
                    smooth_film_thickness=sol.smooth_film_thickness,
                    lambda_central=h_c / sigma, valid=sol.valid)


def _load_sharing(*, summits: str, **inputs) -> MixedEHL:
    """``mixed_ehl``'s load sharing with the asperities of ``summits``: for ``"ground"``
    one solution per distinct (Rq₁, Rq₂) of the inputs, each with its own ηβσ and σ/β
    (:func:`friction.flank_summits.greenwood_tripp_parameters`; the efficiency stage has
    one pair), reassembled in the inputs' broadcast shape."""
    if summits == "fixed":
        return mixed_ehl_solution(**inputs)
    inputs = {k: v for k, v in inputs.items()
              if k not in ("asperity_density_radius_sigma", "sigma_over_beta")}
    arrays = {k: np.asarray(v, float) for k, v in inputs.items() if k not in _SCALAR_INPUTS}
    shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    full = {k: np.broadcast_to(a, shape) for k, a in arrays.items()}
    key = np.stack([np.ravel(full["roughness_1"]), np.ravel(full["roughness_2"])])
    combos, which = np.unique(key, axis=1, return_inverse=True)
    if combos.shape[1] == 1:
        return mixed_ehl_solution(**inputs, **_ground_summits(*combos[:, 0]))
    scalars = {k: v for k, v in inputs.items() if k in _SCALAR_INPUTS}
    fields = {n: np.empty(key.shape[1], dtype=bool if n == "valid" else float)
              for n in MixedEHL._fields}
    for c in range(combos.shape[1]):
        mask = np.ravel(which) == c
        sol = mixed_ehl_solution(**{k: np.ravel(v)[mask] for k, v in full.items()},
                                 **scalars, **_ground_summits(*combos[:, c]))
        for n in MixedEHL._fields:
            fields[n][mask] = getattr(sol, n)
    return MixedEHL(**{n: v.reshape(shape) for n, v in fields.items()})


def _ground_summits(roughness_1: float, roughness_2: float) -> dict:
    """mixed_ehl_solution's asperity inputs for two ground flanks of these Rq [µm]: ηβσ,
    σ/β and the skewed heights' F_{5/2} (:mod:`friction.flank_summits`)."""
    r1, r2 = float(roughness_1), float(roughness_2)
    ebs, sb = greenwood_tripp_parameters(r1, r2)

    def heights(t: Array) -> Array:
        return height_tail_integral(t, r1, r2)

    return {"asperity_density_radius_sigma": ebs, "sigma_over_beta": sb,
            "height_integral": heights}


#: mixed_ehl_solution's keyword inputs that are scalars (not broadcast with the points)
_SCALAR_INPUTS = frozenset({"eyring_stress", "limiting_shear_coefficient",
                            "boundary_friction"})


#: Newton iterations of :func:`_thermal_root` before it gives up (it converges in 3–8 on
#: gear flanks; the bracket's bisection fallback bounds the worst case)
_ROOT_ITERATIONS = 200
#: :func:`_thermal_root`'s convergence: 16 ulp of τ (3.6e-15 relative)
_ROOT_ULPS = 16.0 * np.finfo(float).eps


def _thermal_root(tau_hi: Array, shear_number: Array, alpha_p: Array, dt_per_tau: Array,
                  cap: Array, eyring_stress: float, beta: float, beta_alpha: float) -> Array:
    """The root τ ∈ [0, τ_hi] [MPa] of τ = min(E(τ), Λp), E(τ) = τ₀ asinh(N exp(α₀p
    e^(−β_α k τ) − β k τ)) (``shear_number`` N = η₀γ̇/τ₀ [1], ``alpha_p`` α₀p [1],
    ``dt_per_tau`` k [K/MPa], ``cap`` Λp [MPa], 1-D arrays of one length; τ_hi the
    isothermal stress).

    τ = Λp where E(Λp) ≥ Λp. Elsewhere the root is that of g(τ) = τ − E(τ): E is
    decreasing and convex in τ (asinh(e^L) is convex and increasing in L, L convex in τ),
    so g is increasing (g′ ≥ 1) and concave, and Newton's iteration from τ_hi (g ≥ 0)
    lands in [0, root] after one step and then rises monotonically to the root; it is
    stopped when a step or the bracket is below 16 ulp, i.e. at the double-precision root
    (a bracket kept on the way falls back to bisection where E overflows). Replaces
    scipy's elementwise bracketing solver (the same root, to its 1e-10 relative tolerance)
    at a fraction of its overhead (docs/friction.md, "`thermal_eyring`: the model")."""
    tau = np.array(tau_hi, dtype=float)

    def stress(t: Array, n: Array, a_p: Array, k: Array) -> tuple[Array, Array]:
        dt = k * t
        with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
            fall = np.exp(-beta_alpha * dt)
            arg = n * np.exp(a_p * fall - beta * dt)
            e = eyring_stress * np.arcsinh(arg)
            # dE/dτ = τ₀ arg′/√(1 + arg²), arg′ = −arg (α₀p β_α k e^(−β_α k τ) + β k)
            de = -eyring_stress * (a_p * beta_alpha * fall + beta) * k \
                / np.sqrt(1.0 + 1.0 / (arg * arg))
        return e, de

    e_cap, _ = stress(cap, shear_number, alpha_p, dt_per_tau)
    todo = np.flatnonzero(~(e_cap >= cap))
    x = tau[todo]
    lo, hi = np.zeros_like(x), x.copy()
    n, a_p, k = shear_number[todo], alpha_p[todo], dt_per_tau[todo]
    for _ in range(_ROOT_ITERATIONS):
        if todo.size == 0:
            return tau
        e, de = stress(x, n, a_p, k)
        g = x - e
        below = g < 0.0
        lo = np.where(below, x, lo)
        hi = np.where(below, hi, x)
        with np.errstate(invalid="ignore", divide="ignore"):
            step = x - g / (1.0 - de)
        inside = (step >= lo) & (step <= hi)
        step = np.where(inside, step, 0.5 * (lo + hi))
        # converged: a step or the bracket within 16 ulp (g's rounding noise, ~1e-15 of τ,
        # makes the last steps alternate about the root)
        tol = _ROOT_ULPS * np.abs(step)
        done = (np.abs(step - x) <= tol) | (hi - lo <= tol) | (g == 0.0)
        x = step
        if np.any(done):
            tau[todo[done]] = x[done]
            keep = ~done
            todo, x, lo, hi, n, a_p, k = (a[keep] for a in (todo, x, lo, hi, n, a_p, k))
    raise RuntimeError(f"thermal_eyring: the film's shear stress did not converge at "
                       f"{todo.size} node(s) in {_ROOT_ITERATIONS} iterations")
