"""Blok's flash temperature, the contact temperature and the scuffing safety of a loaded mesh.

Friction heats a sliding contact. In a lubricated line contact of Hertzian half-width b
the heat of friction is generated as a band source of flux q(x) = μ p(x) abs(V_s) across
the contact line (μ the friction coefficient, p(x) the contact pressure, abs(V_s) the
sliding speed), and the two surfaces carry it away as they pass through the band, each
at its own speed v₁, v₂ across the line. At the Péclet numbers of gear contacts
(Pe = v b/(2κ) ≳ 5 on the flanks) heat is conducted into each surface only normal to it
(Jaeger's moving source at high Péclet number, :mod:`friction.ehl.thermal`), and a
surface taking the share q_i of the flux warms by

    ΔT_i(x) = 1/(√π B_i √v_i) ∫_{−b}^{x} q_i(ξ)/√(x − ξ) dξ,     B_i = √(k_i ρ_i c_i),

B_i the surface's thermal effusivity. Blok's postulate (1937) is that the two surfaces
reach the same temperature in the contact: with the same shape of flux into both, that
holds at every x when the heat is shared in proportion to B_i √v_i,

    φ₁ = B₁√v₁ / (B₁√v₁ + B₂√v₂),   φ₂ = 1 − φ₁                        (heat partition)

and the flash temperature, the maximum of the surfaces' common rise over the band, is

    θ_fl = C · μ p_max abs(V_s) √b / (B₁√v₁ + B₂√v₂)                        (Blok)

with C = 2√2/√π = 1.5958 for a uniform band (p_max the uniform pressure; the maximum is at
the band's trailing edge) and C = max_X I(X)/√π = 1.2346 for the semi-elliptic (Hertzian)
band p(x) = p_max √(1 − x²/b²), I(X) = ∫_{−1}^{X} √(1 − s²)/√(X − s) ds, whose maximum is
at x = 0.652 b (x from the band's centre, the surfaces entering at x = −b). In Blok's own
form, with the load per length w (2b p_max of the uniform band, π b p_max/2 of the
semi-elliptic one) and the band's width 2b, they are θ_fl = 1.128 and
1.11 μ w abs(V_s) / ((B₁√v₁ + B₂√v₂) √(2b)) — his "1.13" (uniform) and "1.11"
(semi-elliptic) (Blok 1937, 1963). :data:`BLOK_HERTZIAN` was
computed by adaptive quadrature of I(X) and a bounded scalar maximisation to 1e-10;
``tests/test_scuffing_micropitting.py`` checks both constants against Jaeger's integral
done independently. ISO/TR 15144-1:2014 Eq. (80) (ISO/TS 6336-22's flash temperature)
writes the Hertzian case with √(π/2) = 1.2533 in place of C, 1.5 % above the exact
maximum.

The contact temperature is the bulk (tooth body) temperature plus the flash temperature,
θ_B = θ_M + θ_fl. The bulk temperature is ISO/TS 6336-20's (ISO/TR 13989-1:2000 Eq. (22)–
(23)): θ_M = θ_oil + 0.47 X_S X_mp θ_flm, with θ_flm the mean flash temperature along the
path of contact, X_S the lubrication factor (1.2 spray, 1.0 dip, 0.2 submerged) and
X_mp = (1 + n_p)/2 for a gear meshing with n_p gears (1 for a pair).

Scuffing is judged against the oil's scuffing temperature from its FZG scuffing test
(A/8.3/90, ISO 14635-1) failure load stage S_FZG (ISO/TR 13989-1:2000 Eq. (99), carried
into ISO/TS 6336-20:2017):

    θ_S = 80 + (0.85 + 1.4 X_W) X_L S_FZG²   [degC]

with X_W the structural factor of the material (1.0 for case-hardened steel of average
retained austenite, ISO/TR 13989-1 Table 2) and X_L the lubricant factor of the base oil
(1.0 mineral oils, 0.8 polyalphaolefins, 0.7 non-water-soluble and 0.6 water-soluble
polyglycols, 1.3 phosphate esters, 1.5 traction fluids; ISO/TR 13989-1 Eq. (27), DIN
3990-4:1987 the same table). The oil's viscosity has no term of its own in θ_S: the
factor η_oil^(−0.05) (η_oil in mPa s) belongs to the mean friction coefficient of the
standard's method, μ_m = 0.045 (w_Bt K_Bγ/(v_ΣC ρ_redC))^0.2 η_oil^(−0.05) X_R X_L
(ISO/TR 13989-1 Eq. (25); :mod:`contact.load_capacity.iso_flash_temperature`), where it stands
beside X_L. (Earlier versions multiplied it into θ_S's X_L too: 364 °C instead of 404 °C
for a mineral oil of S_FZG 12 at 13.6 mPa s; the standard's method keeps that reading
as one end of the spread of its S_B.) The safety factor is
S_B = (θ_S − θ_oil)/(θ_Bmax − θ_oil) (ISO/TR 13989-1 Eq. (100)); the standard advises
stating the margin θ_S − θ_Bmax beside it.

Units: pressure MPa, half-width mm, speeds m/s, effusivity W s^0.5/(m2 K), temperatures
degC, temperature differences K.

Public functions
----------------
heat_partition          Blok's share of the heat taken by surface 1
blok_flash_temperature  the flash temperature of a uniform or Hertzian band source
hertz_half_width        b = 2w/(π p_max) of a Hertzian line contact
bulk_temperature        θ_M = θ_oil + 0.47 X_S X_mp θ_flm
base_oil_factor         X_L of the base oil (θ_S and μ_m)
lubricant_factor        η_oil^(−0.05) X_L, the lubricant term of ISO's μ_m
scuffing_temperature    θ_S from the FZG load stage
scuffing_safety         S_B = (θ_S − θ_oil)/(θ_Bmax − θ_oil)
ScuffingConditions      the inputs of the assessment beyond the contact and the oil

References
----------
Blok, H., "Theoretical study of temperature rise at surfaces of actual contact under
oiliness lubricating conditions", Proc. General Discussion on Lubrication and
Lubricants, IMechE, London, 2 (1937) 222–235; Blok, H., "The flash temperature concept",
Wear 6 (1963) 483–494.
Jaeger, J. C., "Moving sources of heat and the temperature at sliding contacts",
J. Proc. R. Soc. N.S.W. 76 (1942) 203–224.
ISO/TR 13989-1:2000, Calculation of scuffing load capacity of cylindrical, bevel and
hypoid gears — Part 1: Flash temperature method, Eq. (22), (23), (27), (99), (100), Table 2
(replaced by ISO/TS 6336-20:2017, which keeps the method).
ISO/TR 15144-1:2014, Calculation of micropitting load capacity of cylindrical spur and
helical gears — Part 1: Introduction and basic principles, Eq. (80) (replaced by ISO/TS
6336-22:2018).
The constants of Eq. (22), (27), (99) were read from an independent open implementation
of ISO/TR 13989-1 whose notes report its scuffing temperatures within 0.2 % of two
commercial ISO 6336 rating reports (the standard itself is not open); docs/
scuffing_micropitting.md says what was checked and how.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.lubricant import BASE_OIL_FACTORS  # a property of the oil's base stock
from geometry.core.errors import InputError
from geometry.core.validation import broadcast, integer, one_of, positive, real, real_array

__all__ = [
    "BASE_OIL_FACTORS",
    "BLOK_HERTZIAN",
    "BLOK_UNIFORM",
    "HEAT_DISTRIBUTIONS",
    "LUBRICATION_FACTORS",
    "ScuffingConditions",
    "base_oil_factor",
    "blok_flash_temperature",
    "bulk_temperature",
    "heat_partition",
    "hertz_half_width",
    "lubricant_factor",
    "scuffing_safety",
    "scuffing_temperature",
]

Array = NDArray[np.float64]

#: C of θ_fl = C μ p_max abs(V_s) √b / Σ B√v for a uniform band of pressure p_max:
#: 2√2/√π (the maximum, at the trailing edge x = b, of 2 q √(x + b)/√π)
BLOK_UNIFORM = 2.0 * math.sqrt(2.0 / math.pi)
#: C for the semi-elliptic (Hertzian) band: max over X of
#: I(X) = ∫_{−1}^{X} √(1 − s²)/√(X − s) ds, divided by √π (the maximum 2.188307 at
#: X = 0.65223); adaptive quadrature and a bounded maximisation to 1e-10 (module docstring)
BLOK_HERTZIAN = 1.2346198310
#: the band's pressure distribution → C (see the module docstring)
HEAT_DISTRIBUTIONS: Mapping[str, float] = MappingProxyType(
    {"hertzian": BLOK_HERTZIAN, "uniform": BLOK_UNIFORM})

#: lubrication factor X_S of the bulk temperature (ISO/TR 13989-1:2000 Eq. (22))
LUBRICATION_FACTORS: Mapping[str, float] = MappingProxyType(
    {"spray": 1.2, "dip": 1.0, "submerged": 0.2})


#: the FZG A/8.3/90 test's load stages (ISO 14635-1: 1 to 12; stages 13 and 14 of the
#: extended test are accepted)
_FZG_STAGES = (1.0, 14.0)


@dataclass(frozen=True)
class ScuffingConditions:
    """The inputs of the scuffing assessment beyond the loaded contact and the oil.

    Parameters
    ----------
    lubrication : {"dip", "spray", "submerged"}
        How the oil reaches the mesh: X_S of the bulk temperature
        (:data:`LUBRICATION_FACTORS`). Default ``"dip"``: an axle's splash lubrication.
    meshing_gears : int
        n_p, the gears the member meshes with (X_mp = (1 + n_p)/2); default 1 (a pair).
    structural_factor : float — [1]
        X_W of the scuffing temperature, > 0; default 1.0, ISO/TR 13989-1 Table 2's
        for case-hardened steel of average retained austenite (10–20 %), the toolkit's
        default material (the table gives other values for other heat treatments, e.g.
        1.5 for nitrided steels).

    Raises
    ------
    InputError
        An unknown lubrication, a gear count below 1 or a structural factor ≤ 0.
    """

    lubrication: str = "dip"
    meshing_gears: int = 1
    structural_factor: float = 1.0

    def __post_init__(self) -> None:
        one_of("lubrication", self.lubrication, LUBRICATION_FACTORS)
        object.__setattr__(self, "meshing_gears",
                           integer("meshing_gears", self.meshing_gears, low=1))
        object.__setattr__(self, "structural_factor",
                           positive("structural_factor", self.structural_factor, "1"))

    @property
    def lubrication_factor(self) -> float:
        """X_S (:data:`LUBRICATION_FACTORS`) — [1]."""
        return LUBRICATION_FACTORS[self.lubrication]

    @property
    def multiple_mesh_factor(self) -> float:
        """X_mp = (1 + n_p)/2 — [1]."""
        return 0.5 * (1.0 + self.meshing_gears)


def heat_partition(speed_1: ArrayLike, speed_2: ArrayLike, effusivity_1: ArrayLike,
                   effusivity_2: ArrayLike) -> Array | float:
    """Blok's share of the friction heat that surface 1 takes.

    Parameters
    ----------
    speed_1, speed_2 : array_like — [m/s]
        Each surface's speed through the contact (across the contact line), ≥ 0.
    effusivity_1, effusivity_2 : array_like — [W s^0.5/(m2 K)]
        B = √(kρc) of each surface, > 0.

    Returns
    -------
    float or array — [1]
        φ₁ = B₁√v₁/(B₁√v₁ + B₂√v₂) (broadcast shape); NaN where neither surface moves.

    Raises
    ------
    InputError
        A negative or non-finite speed, a non-positive effusivity, or shapes that do not
        broadcast.

    Notes
    -----
    Blok (1937): the heat is shared so that both surfaces reach the same temperature in
    the contact; for the same flux shape into both this equalises the whole temperature
    profile (module docstring). Equal materials at equal speeds share it half and half.
    """
    s1, s2, b1, b2 = _thermal_inputs(speed_1, speed_2, effusivity_1, effusivity_2)
    a1, a2 = b1 * np.sqrt(s1), b2 * np.sqrt(s2)
    total = a1 + a2
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(total > 0.0, a1 / np.where(total > 0.0, total, 1.0), np.nan)
    return _out(share)


def blok_flash_temperature(
    friction_coefficient: ArrayLike,
    pressure: ArrayLike,
    half_width: ArrayLike,
    sliding_speed: ArrayLike,
    speed_1: ArrayLike,
    speed_2: ArrayLike,
    effusivity_1: ArrayLike,
    effusivity_2: ArrayLike,
    *,
    distribution: str = "hertzian",
) -> Array | float:
    """Blok's flash temperature of a band heat source μ p(x) abs(V_s) on two moving surfaces.

    Parameters
    ----------
    friction_coefficient : array_like — [1]
        μ, ≥ 0.
    pressure : array_like — [MPa]
        Peak (Hertzian) or uniform pressure p_max of the band, ≥ 0.
    half_width : array_like — [mm]
        Half-width b of the band across the contact line, ≥ 0.
    sliding_speed : array_like — [m/s]
        abs(V_s), the magnitude of the sliding velocity (the heat's source), ≥ 0.
    speed_1, speed_2 : array_like — [m/s]
        Each surface's speed through the band (its velocity across the contact line,
        magnitude), ≥ 0.
    effusivity_1, effusivity_2 : array_like — [W s^0.5/(m2 K)]
        B = √(kρc) of each surface, > 0
        (:attr:`geometry.core.materials.Material.thermal_effusivity`).
    distribution : {"hertzian", "uniform"}
        The pressure across the band: semi-elliptic p_max √(1 − x²/b²) (default) or
        uniform p_max (:data:`HEAT_DISTRIBUTIONS`).

    Returns
    -------
    float or array — [K]
        θ_fl = C μ p_max abs(V_s) √b / (B₁√v₁ + B₂√v₂), the maximum over the band of both
        surfaces' common temperature rise (broadcast shape of the inputs); 0 where no heat
        is generated; NaN where heat is generated but neither surface moves across the
        line (the moving-source model has no answer: nothing carries the heat through
        the band).

    Raises
    ------
    InputError
        A negative or non-finite input, a non-positive effusivity, an unknown
        distribution (naming the field), or shapes that do not broadcast.

    Notes
    -----
    Blok (1937, 1963) with Jaeger's moving band source at high Péclet number (1942);
    module docstring. Valid for Pe = v b/(2κ) ≳ 5 of the surface that takes most of the
    heat (κ = k/(ρc) ≈ 1.2e-5 m²/s for steel: v b ≳ 1.2e-4 m²/s, e.g. 2 m/s at
    b = 0.06 mm); below it the formula overestimates the rise of that surface.
    """
    c = HEAT_DISTRIBUTIONS[one_of("distribution", distribution, HEAT_DISTRIBUTIONS)]
    mu = real_array("friction_coefficient", friction_coefficient, unit="1", low=0.0)
    p = real_array("pressure", pressure, unit="MPa", low=0.0)
    b = real_array("half_width", half_width, unit="mm", low=0.0)
    vs = real_array("sliding_speed", sliding_speed, unit="m/s", low=0.0)
    s1, s2, e1, e2 = _thermal_inputs(speed_1, speed_2, effusivity_1, effusivity_2)
    mu, p, b, vs, s1, s2, e1, e2 = broadcast(
        friction_coefficient=mu, pressure=p, half_width=b, sliding_speed=vs, speed_1=s1,
        speed_2=s2, effusivity_1=e1, effusivity_2=e2)
    # q_max [W/m2] = μ p [MPa → Pa] abs(V_s); √b [√m]
    heat = mu * p * 1e6 * vs * np.sqrt(b * 1e-3)
    total = e1 * np.sqrt(s1) + e2 * np.sqrt(s2)
    with np.errstate(invalid="ignore", divide="ignore"):
        theta = np.where(heat > 0.0, c * heat / np.where(total > 0.0, total, np.nan), 0.0)
    return _out(theta)


def hertz_half_width(load_per_length: ArrayLike, pressure_max: ArrayLike) -> Array | float:
    """Half-width of a Hertzian line contact from its load and peak pressure.

    Parameters
    ----------
    load_per_length : array_like — [N/mm]
        w ≥ 0.
    pressure_max : array_like — [MPa]
        p_max ≥ 0.

    Returns
    -------
    float or array — [mm]
        b = 2w/(π p_max) (w = π b p_max/2 of the semi-elliptic pressure); 0 where w = 0.

    Raises
    ------
    InputError
        A negative or non-finite input, or p_max = 0 under a load.

    Notes
    -----
    Johnson, K. L., *Contact Mechanics*, Cambridge (1985) §4.2, Eq. (4.45). It equals the
    LTCA's ``half_width`` (the same relation, ``contact.ltca``).
    """
    w = real_array("load_per_length", load_per_length, unit="N/mm", low=0.0)
    p = real_array("pressure_max", pressure_max, unit="MPa", low=0.0)
    w, p = broadcast(load_per_length=w, pressure_max=p)
    if np.any((w > 0.0) & (p <= 0.0)):
        raise InputError("pressure_max: must be > 0 [MPa] where load_per_length > 0, got 0")
    with np.errstate(invalid="ignore", divide="ignore"):
        return _out(np.where(w > 0.0, 2.0 * w / (math.pi * np.where(p > 0.0, p, 1.0)), 0.0))


def bulk_temperature(oil_temperature: float, mean_flash_temperature: ArrayLike,
                     conditions: ScuffingConditions | None = None) -> Array | float:
    """The bulk (tooth body) temperature of ISO/TS 6336-20's flash-temperature method.

    Parameters
    ----------
    oil_temperature : float — [degC]
        θ_oil, above absolute zero.
    mean_flash_temperature : array_like — [K]
        θ_flm, the mean flash temperature along the path of contact, ≥ 0.
    conditions : ScuffingConditions, optional
        Lubrication (X_S) and meshing gears (X_mp); default ``ScuffingConditions()``.

    Returns
    -------
    float or array — [degC]
        θ_M = θ_oil + 0.47 X_S X_mp θ_flm.

    Raises
    ------
    InputError
        A temperature below absolute zero or a negative or non-finite mean flash
        temperature.

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (22)–(23) (ISO/TS 6336-20:2017): a fit to FZG measurements
    of the bulk temperature of gears, 0.47 of the mean flash temperature above the oil's.
    """
    cond = ScuffingConditions() if conditions is None else conditions
    t_oil = real("oil_temperature", oil_temperature, unit="degC", low=-273.15, low_open=True)
    flm = real_array("mean_flash_temperature", mean_flash_temperature, unit="K", low=0.0)
    return _out(t_oil + 0.47 * cond.lubrication_factor * cond.multiple_mesh_factor * flm)


def base_oil_factor(base_oil: str) -> float:
    """The lubricant factor X_L of a base oil.

    Parameters
    ----------
    base_oil : str
        One of :data:`BASE_OIL_FACTORS` (``"mineral"``, ``"polyalphaolefin"`` …).

    Returns
    -------
    float — [1]
        X_L: 1.0 mineral, 0.8 polyalphaolefin, 0.7 / 0.6 non-water-soluble / water-soluble
        polyglycol, 1.3 phosphate ester, 1.5 traction fluid.

    Raises
    ------
    InputError
        An unknown base oil (the message lists the known ones).

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (27) (ISO/TS 6336-20:2017; DIN 3990-4:1987): the factor of
    the scuffing temperature θ_S (:func:`scuffing_temperature`) and of the mean friction
    coefficient μ_m, which has the oil's viscosity as a term of its own
    (:func:`lubricant_factor`).
    """
    return BASE_OIL_FACTORS[one_of("base_oil", base_oil, BASE_OIL_FACTORS)]


def lubricant_factor(viscosity: float, base_oil: str) -> float:
    """The lubricant term η_oil^(−0.05) X_L of ISO's mean friction coefficient.

    Parameters
    ----------
    viscosity : float — [Pa s]
        Dynamic viscosity η_oil at the oil temperature, > 0.
    base_oil : str
        One of :data:`BASE_OIL_FACTORS` (``"mineral"``, ``"polyalphaolefin"`` …).

    Returns
    -------
    float — [1]
        X_L (1000 η_oil)^(−0.05) (η_oil in mPa s; X_L :func:`base_oil_factor`).

    Raises
    ------
    InputError
        A non-positive viscosity or an unknown base oil.

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (25), (27) (ISO/TS 6336-20:2017): the viscosity term and the
    base oil's X_L of the mean friction coefficient μ_m. Not the scuffing temperature's
    factor, which is X_L alone (module docstring).
    """
    eta = positive("viscosity", viscosity, "Pa s")
    return base_oil_factor(base_oil) * (1e3 * eta) ** -0.05


def scuffing_temperature(fzg_load_stage: float, lubricant_factor: float,
                         structural_factor: float = 1.0) -> float:
    """The oil's scuffing temperature from its FZG scuffing-test failure load stage.

    Parameters
    ----------
    fzg_load_stage : float — [1]
        S_FZG, the failure load stage of the FZG A/8.3/90 test (ISO 14635-1), in [1, 14].
    lubricant_factor : float — [1]
        X_L > 0, the base oil's (:func:`base_oil_factor`).
    structural_factor : float — [1]
        X_W > 0 (:class:`ScuffingConditions`); default 1.0.

    Returns
    -------
    float — [degC]
        θ_S = 80 + (0.85 + 1.4 X_W) X_L S_FZG².

    Raises
    ------
    InputError
        A load stage outside [1, 14] or a non-positive factor (naming the field).

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (99) (ISO/TS 6336-20:2017). The relation is calibrated on
    the A/8.3/90 test; stages of other FZG tests (A/16.6/90, S-A10/16.6R/90) are not
    interchangeable with it. E.g. S_FZG = 12, X_W = X_L = 1: θ_S = 404 °C.
    """
    s = real("fzg_load_stage", fzg_load_stage, unit="1", low=_FZG_STAGES[0],
             high=_FZG_STAGES[1])
    x_l = positive("lubricant_factor", lubricant_factor, "1")
    x_w = positive("structural_factor", structural_factor, "1")
    return 80.0 + (0.85 + 1.4 * x_w) * x_l * s * s


def scuffing_safety(scuffing_temperature: float, contact_temperature: ArrayLike,
                    oil_temperature: float) -> Array | float:
    """The scuffing safety factor of the flash-temperature method.

    Parameters
    ----------
    scuffing_temperature : float — [degC]
        θ_S (:func:`scuffing_temperature`), above the oil temperature.
    contact_temperature : array_like — [degC]
        θ_Bmax, the peak contact temperature, above the oil temperature (NaN passes).
    oil_temperature : float — [degC]
        θ_oil.

    Returns
    -------
    float or array — [1]
        S_B = (θ_S − θ_oil)/(θ_Bmax − θ_oil) (NaN where θ_Bmax is NaN).

    Raises
    ------
    InputError
        θ_S or a finite θ_Bmax not above θ_oil.

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (100) (ISO/TS 6336-20:2017). A quotient of temperature rises:
    the standard advises stating the margin θ_S − θ_Bmax too.
    """
    t_oil = real("oil_temperature", oil_temperature, unit="degC", low=-273.15, low_open=True)
    t_s = real("scuffing_temperature", scuffing_temperature, unit="degC", low=t_oil,
               low_open=True)
    t_b = np.asarray(contact_temperature, dtype=float)
    finite = t_b[np.isfinite(t_b)]
    if np.any(finite <= t_oil) or np.any(np.isinf(t_b)):
        raise InputError(f"contact_temperature: must be finite and > {t_oil:g} [degC] (the "
                         f"oil temperature), got {float(np.min(t_b)):g}")
    with np.errstate(invalid="ignore"):
        return _out((t_s - t_oil) / (t_b - t_oil))


def _thermal_inputs(speed_1, speed_2, effusivity_1, effusivity_2) -> tuple[np.ndarray, ...]:
    """The speeds [m/s] (≥ 0) and effusivities [W s^0.5/(m2 K)] (> 0), validated and
    broadcast."""
    s1 = real_array("speed_1", speed_1, unit="m/s", low=0.0)
    s2 = real_array("speed_2", speed_2, unit="m/s", low=0.0)
    b1 = real_array("effusivity_1", effusivity_1, unit="W s0.5/(m2 K)", low=0.0, low_open=True)
    b2 = real_array("effusivity_2", effusivity_2, unit="W s0.5/(m2 K)", low=0.0, low_open=True)
    return broadcast(speed_1=s1, speed_2=s2, effusivity_1=b1, effusivity_2=b2)


def _out(value: np.ndarray) -> Array | float:
    """A float for a 0-d result, a new array otherwise."""
    arr = np.array(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr
