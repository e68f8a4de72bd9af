"""The standard's flash-temperature method on the virtual cylindrical gears of a bevel pair.

The LTCA's flash temperature (:mod:`contact.load_capacity.flash_temperature`) is Blok's,
evaluated on every loaded contact segment with the segment's own load, curvature, speeds and μ. The
standard's flash-temperature method of scuffing (ISO/TS 6336-20:2017, formerly ISO/TR
13989-1:2000) is Blok's too, but on an idealised mesh: the involute path of contact of a
cylindrical gear pair, the nominal load shared between the pairs in contact by a load
sharing factor, and one mean friction coefficient for the whole mesh. ISO/TS 10300-20
(bevel and hypoid gears) applies it through virtual cylindrical gears; its own
definitions could not be sourced, so this module applies ISO/TS 6336-20's method to the
virtual cylindrical gears of ISO 10300-1 Annex A (the ``/rating`` group,
:mod:`contact.load_capacity.iso10300`), as issue 52 allows, and says so on every output. The
comparison
of the two on the same case is in docs/scuffing_micropitting.md.

Along the path of contact of the virtual pair (transverse section; positions g from the
pinion's base tangent point, from A, the gear's tip, to E, the pinion's tip):

    ρ_t1 = g,   ρ_t2 = a_v sin α_vet − g,   ρ_n = ρ_t1 ρ_t2 / ((ρ_t1 + ρ_t2) cos β_vb)
    v_1 = ω_v1 ρ_t1,   v_2 = ω_v2 ρ_t2   (each flank's speed along its profile)
    |V_s| = √((v_1 − v_2)² + v_g²)     (v_g the hypoid's lengthwise sliding, 0 for bevel)
    w_n = X_Γ w_Bt / cos α_vet,   w_Bt = K_A K_v K_Bβ K_Bα F_vmt / b_v,eff
    b_H = √(4 w_n ρ_n / (π E*)),   p_H = 2 w_n / (π b_H)          (Hertz, line contact)
    θ_fl = Blok(μ_m, p_H, b_H, |V_s|, v_1 cos β_vb, v_2 cos β_vb)   (Hertzian band)

with a_v = (d_v1 + d_v2)/2, ω_vi = 2 v_vt/d_vi the virtual gears' speeds for the common
normal speed v_mn = v_mt1 cos β_m1 (v_vt = v_mn/cos β_v), the flanks passing through the
band at their speed across the contact line (the line lies at β_vb to the face), and
K_Bβ = K_Hβ, K_Bα = K_Hα of the rating (ISO/TS 6336-20 takes the pitting factors).
Blok's constant of the Hertzian band is the same as the LTCA's (1.11 in his form; ISO's
compact flash-temperature formula, θ_fl = μ_m X_M X_J X_G (X_Γ w_Bt)^0.75 v^0.5/a^0.25,
is this expression with the involute geometry folded into its factors).

The standard's inputs:

* the mean friction coefficient (ISO/TR 13989-1:2000 Eq. (25)–(27)),
  μ_m = 0.045 (w_Bt K_Bγ / (v_ΣC ρ_redC))^0.2 η_oil^−0.05 X_R X_L with
  v_ΣC = 2 v_vt sin α_vet [m/s], ρ_redC = ρ_n at the pitch point [mm],
  X_R = 2.2 (Ra/ρ_redC)^0.25 (Ra [µm] the mean of both flanks), η_oil [mPa s] at the oil
  temperature, X_L the base oil's lubricant factor
  (:func:`contact.load_capacity.flash_temperature.base_oil_factor`) and the helical
  load factor K_Bγ = 1 (ε_γ ≤ 2), 1 + 0.2 √((ε_γ − 2)(5 − ε_γ)) (2 < ε_γ < 3.5), 1.3
  (ε_γ ≥ 3.5);
* the load sharing factor X_Γ: 1/ε_α for ε_β ≥ 1 (helical: the load spread evenly over
  the contact lines); for spur gears with unmodified profiles the trapezoid 1/3 → 2/3 over
  the double-contact zones, 1 in the single-contact zone; linear in ε_β between
  (ISO/TR 13989-1 clause 5.3, our reading; no buttressing, no tip relief);
* no approach factor (X_J = 1) and no tip-relief factor: the flanks are unmodified;
* the bulk temperature θ_M = θ_oil + 0.47 X_S X_mp θ_flm with θ_flm the mean of θ_fl
  along the path of contact (ISO/TR 13989-1 Eq. (22)–(23),
  :func:`contact.load_capacity.flash_temperature.bulk_temperature`), the scuffing
  temperature and the safety S_B of :mod:`contact.load_capacity.flash_temperature`.

Two variants, both stored and labelled (:func:`iso_flash_temperature_variants`):

* ``standard`` — ISO/TS 6336-20's method as written, on the virtual cylindrical gears
  (:data:`METHOD_STANDARD`): the sliding of the involute profiles only. The bevel/hypoid
  standard ISO/TS 10300-20:2021 exists, but its text could not be sourced here: this is
  not it, and is named so.
* ``lengthwise_sliding`` — not the standard's (:data:`METHOD_LENGTHWISE`): the hypoid's
  lengthwise sliding v_g (ISO 10300-2 cl. 6, the rating's ``v_g``) added to the profile
  sliding as an orthogonal component. A cylindrical gear has none; without it the flash
  temperature of a hypoid vanishes at the pitch point, where the hypoid slides most
  along the tooth. For a spiral bevel pair (v_g = 0) both variants are the same.

The spread of S_B its uncertain constants give (``scuffing_safety_low``/``_high``): the
mean friction coefficient in ISO's form above or in DIN 3990-4:1987's,
μ_m = 0.060 (w_Bt K_Bγ/(v_ΣC ρ_redC))^0.2 η_oil^−0.05 Ra^0.25 X_L (the same regression
before ISO made the roughness term dimensionless: 0.045 · 2.2 ρ_redC^−0.25 = 0.060 at
ρ_redC = 7.2 mm), and the scuffing temperature θ_S with X_L alone (the standard's, adopted)
or with X_L η_oil^−0.05 (this toolkit's earlier reading): four combinations, their least
and largest S_B.

Units: lengths mm, speeds m/s, loads N/mm, pressure MPa, temperatures degC, temperature
differences K.

Public functions
----------------
helical_load_factor            K_Bγ
roughness_factor               X_R = 2.2 (Ra/ρ_redC)^0.25
mean_friction_coefficient      μ_m (ISO/TR 13989-1 Eq. (25); DIN 3990-4's form as an option)
load_sharing_factor            X_Γ along the path of contact
path_of_contact                positions, radii of curvature of the involute path
iso_flash_temperature_method   the whole method from a ``/rating`` dataset, as a Dataset
iso_flash_temperature_variants the standard and the lengthwise-sliding variant, with the
                               spread of S_B (the ``/rating/flash_temperature`` group)

References
----------
ISO/TR 13989-1:2000 (replaced by ISO/TS 6336-20:2017), Calculation of scuffing load
capacity of cylindrical, bevel and hypoid gears — Part 1: Flash temperature method.
ISO 10300-1:2014 Annex A (the virtual cylindrical gears).
DIN 3990-4:1987, Tragfähigkeitsberechnung von Stirnrädern — Berechnung der
Freßtragfähigkeit (the flash temperature criterion; its mean friction coefficient).
Blok, H., "The flash temperature concept", Wear 6 (1963) 483–494.
Johnson, K. L., *Contact Mechanics*, Cambridge (1985) §4.2 (the Hertz line contact).
"""

from __future__ import annotations

import json
import logging
import math

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike, NDArray

from contact.load_capacity.flash_temperature import (
    ScuffingConditions,
    base_oil_factor,
    blok_flash_temperature,
    bulk_temperature,
    lubricant_factor,
    scuffing_safety,
    scuffing_temperature,
)
from contact.load_capacity.micropitting import GAUSSIAN_RA_PER_RQ
from friction.lubricant import load_lubricant, viscosity
from geometry import __version__
from geometry.core.conventions import data_var, dataset
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.materials import material
from geometry.core.renamed import renamed_keywords
from geometry.core.validation import integer, one_of, positive, real, real_array

__all__ = [
    "FRICTION_FORMS",
    "METHOD",
    "METHOD_LENGTHWISE",
    "METHOD_STANDARD",
    "VARIANTS",
    "helical_load_factor",
    "iso_flash_temperature_method",
    "iso_flash_temperature_variants",
    "load_sharing_factor",
    "mean_friction_coefficient",
    "path_of_contact",
    "roughness_factor",
]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]

#: what each variant is, said on every output
METHOD_STANDARD = ("ISO/TS 6336-20 flash temperature method (ISO/TR 13989-1) on the virtual "
                   "cylindrical gears of ISO 10300-1 Annex A, as written (profile sliding "
                   "only); not ISO/TS 10300-20, whose text was not sourced")
METHOD_LENGTHWISE = ("not a standard: ISO/TS 6336-20's flash temperature method on the "
                     "virtual cylindrical gears of ISO 10300-1 Annex A with the hypoid's "
                     "lengthwise sliding v_g added to the profile sliding")
#: the variants of :func:`iso_flash_temperature_variants`: name → lengthwise sliding added
VARIANTS = {"standard": False, "lengthwise_sliding": True}
#: the forms of the mean friction coefficient: ISO/TR 13989-1's and DIN 3990-4's
FRICTION_FORMS = ("iso", "din")
#: kept for files and code that name the method in one string: the lengthwise variant
METHOD = METHOD_LENGTHWISE


def helical_load_factor(eps_gamma: float) -> float:
    """The helical load factor K_Bγ of the mean friction coefficient.

    Parameters
    ----------
    eps_gamma : float — [1]
        Total contact ratio ε_γ = ε_α + ε_β, > 0.

    Returns
    -------
    float — [1]
        1 for ε_γ ≤ 2; 1 + 0.2 √((ε_γ − 2)(5 − ε_γ)) for 2 < ε_γ < 3.5; 1.3 from 3.5 on.

    Raises
    ------
    InputError
        ε_γ not a finite number > 0.

    Notes
    -----
    ISO/TR 13989-1:2000 (ISO/TS 6336-20:2017), the helical load factor of Eq. (25).
    Continuous at both joints (1 at 2, 1 + 0.2·1.5 = 1.3 at 3.5).
    """
    e = positive("eps_gamma", eps_gamma, "1")
    if e <= 2.0:
        return 1.0
    if e >= 3.5:
        return 1.3
    return 1.0 + 0.2 * math.sqrt((e - 2.0) * (5.0 - e))


def roughness_factor(roughness_ra: float, relative_radius: float) -> float:
    """The roughness factor X_R of the mean friction coefficient.

    Parameters
    ----------
    roughness_ra : float — [µm]
        Ra = (Ra₁ + Ra₂)/2, the mean arithmetic roughness of the flanks, > 0.
    relative_radius : float — [mm]
        ρ_redC, the relative radius of curvature at the pitch point, > 0.

    Returns
    -------
    float — [1]
        X_R = 2.2 (Ra/ρ_redC)^0.25.

    Raises
    ------
    InputError
        A non-positive or non-finite input (naming the field).

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (26) (ISO/TS 6336-20:2017).
    """
    ra = positive("roughness_ra", roughness_ra, "um")
    rho = positive("relative_radius", relative_radius, "mm")
    return 2.2 * (ra / rho) ** 0.25


def mean_friction_coefficient(
    load_per_width: ArrayLike,
    sum_velocity: float,
    relative_radius: float,
    oil_viscosity: float,
    roughness_ra: float,
    base_oil: str,
    helical_factor: float = 1.0,
    form: str = "iso",
) -> Array | float:
    """ISO's mean friction coefficient of the mesh (or DIN 3990-4's form of it).

    Parameters
    ----------
    load_per_width : array_like — [N/mm]
        w_Bt, the transverse unit load with the load factors, > 0.
    sum_velocity : float — [m/s]
        v_ΣC, the sum of the flanks' profile speeds at the pitch point, > 0.
    relative_radius : float — [mm]
        ρ_redC, the normal relative radius of curvature at the pitch point, > 0.
    oil_viscosity : float — [Pa s]
        η_oil, the dynamic viscosity at the oil temperature, > 0.
    roughness_ra : float — [µm]
        Ra, the mean arithmetic roughness of both flanks, > 0.
    base_oil : str
        One of :data:`contact.load_capacity.flash_temperature.BASE_OIL_FACTORS` (X_lub).
    helical_factor : float — [1]
        K_Bγ (:func:`helical_load_factor`), ≥ 1; default 1.
    form : {"iso", "din"}
        ``"iso"`` (default): ISO/TR 13989-1's; ``"din"``: DIN 3990-4:1987's, with Ra^0.25
        (Ra in µm) in place of X_R and 0.060 in place of 0.045.

    Returns
    -------
    float or array — [1]
        ISO: μ_m = 0.045 (w_Bt K_Bγ/(v_ΣC ρ_redC))^0.2 η_oil^−0.05 X_R X_L; DIN:
        μ_m = 0.060 (w_Bt K_Bγ/(v_ΣC ρ_redC))^0.2 η_oil^−0.05 Ra^0.25 X_L (η_oil in mPa s,
        X_L the base oil's, :func:`contact.load_capacity.flash_temperature.lubricant_factor`;
        the shape of ``load_per_width``).

    Raises
    ------
    InputError
        A non-positive or non-finite input, an unknown base oil or form (naming the
        field).

    Notes
    -----
    ISO/TR 13989-1:2000 Eq. (25)–(27) (ISO/TS 6336-20:2017), units as in the standard:
    N/mm, m/s, mm, mPa s, µm. E.g. w_Bt = 300 N/mm, v_ΣC = 3 m/s, ρ_redC = 10 mm,
    η_oil = 13.6 mPa s, Ra = 0.64 µm, mineral oil: μ_m = 0.069 (ISO), 0.075 (DIN).
    """
    w = real_array("load_per_width", load_per_width, unit="N/mm", low=0.0, low_open=True)
    v = positive("sum_velocity", sum_velocity, "m/s")
    rho = positive("relative_radius", relative_radius, "mm")
    eta = positive("oil_viscosity", oil_viscosity, "Pa s")
    one_of("form", form, FRICTION_FORMS)
    x_l = lubricant_factor(eta, base_oil)  # η_oil^−0.05 X_L, η_oil in mPa s
    k = real("helical_factor", helical_factor, unit="1", low=1.0)
    if form == "iso":
        mu = 0.045 * (w * k / (v * rho)) ** 0.2 * x_l * roughness_factor(roughness_ra, rho)
    else:
        ra = positive("roughness_ra", roughness_ra, "um")
        mu = 0.060 * (w * k / (v * rho)) ** 0.2 * x_l * ra ** 0.25
    return float(mu) if mu.ndim == 0 else mu


def load_sharing_factor(position: ArrayLike, path_length: float, base_pitch: float,
                        eps_alpha: float, eps_beta: float) -> Array:
    """ISO's load sharing factor X_Γ along the path of contact (unmodified profiles).

    Parameters
    ----------
    position : array_like — [mm]
        Distance from A (the start of the path, the gear's tip) along the path, in
        [0, path_length].
    path_length : float — [mm]
        g_α, > 0.
    base_pitch : float — [mm]
        p_et, the transverse base pitch, > 0.
    eps_alpha, eps_beta : float — [1]
        Transverse (in [1, 2] for the spur branch) and face contact ratio.

    Returns
    -------
    ndarray — [1]
        X_Γ: 1/ε_α for ε_β ≥ 1; for ε_β = 0 the spur trapezoid (1/3 at A rising to 2/3 at
        B = E − p_et, 1 from B to D = A + p_et, 2/3 at D falling to 1/3 at E); linear in
        ε_β between.

    Raises
    ------
    InputError
        A position off the path, a non-positive length or pitch, ε_α < 1, or the spur
        branch needed (ε_β < 1) with ε_α > 2 (naming the field).

    Notes
    -----
    ISO/TR 13989-1:2000 clause 5.3 (ISO/TS 6336-20:2017) for gears without profile
    modification and without buttressing; the blend for 0 < ε_β < 1 is our reading of the
    standard's interpolation between spur and helical gears.
    """
    g = positive("path_length", path_length, "mm")
    p = positive("base_pitch", base_pitch, "mm")
    ea = real("eps_alpha", eps_alpha, unit="1")
    if ea < 1.0:  # say why, not only the range (issue 71, round 25b: a 6x41 at 0.9916)
        raise InputError(f"eps_alpha: must be >= 1 [1], got {ea:.4g}: the transverse "
                         "contact ratio of the virtual cylindrical gears is below 1, "
                         "outside ISO/TR 13989-1's load sharing X_Gamma (clause 5.3), "
                         "which assumes at least one pair in contact at every instant")
    eb = real("eps_beta", eps_beta, unit="1", low=0.0)
    s = real_array("position", position, unit="mm", low=-1e-9 * g, high=g * (1 + 1e-9))
    helical = np.full(s.shape, 1.0 / ea)
    if eb >= 1.0:
        return helical
    if ea > 2.0:
        raise InputError(f"eps_alpha: must be <= 2 [1] for the spur load sharing (eps_beta "
                         f"{eb:g} < 1), got {ea:g}")
    b_point, d_point = g - p, p  # B and D from A
    spur = np.ones(s.shape)
    if b_point > 0.0:
        rise = s < b_point
        spur[rise] = 1.0 / 3.0 + s[rise] / (3.0 * b_point)
        fall = s > d_point
        spur[fall] = 1.0 / 3.0 + (g - s[fall]) / (3.0 * (g - d_point))
    return (1.0 - eb) * spur + eb * helical


def path_of_contact(tip_diameter: ArrayLike, base_diameter: ArrayLike,
                    reference_diameter: ArrayLike, pressure_angle: float,
                    points: int = 41) -> dict[str, Array]:
    """Points and radii of curvature along the involute path of contact of a gear pair.

    Parameters
    ----------
    tip_diameter, base_diameter, reference_diameter : array_like, shape (2,) — [mm]
        d_a, d_b, d of the pinion and the gear (the pair at its reference centre distance
        a = (d₁ + d₂)/2, as the virtual gears of ISO 10300-1 are).
    pressure_angle : float — [rad]
        Transverse pressure angle α_t, in (0, π/2).
    points : int
        Number of points from A to E, ≥ 3.

    Returns
    -------
    dict of ndarray
        ``position`` (points,) [mm] from A; ``radius`` (2, points) [mm], the transverse
        radii of curvature ρ_t1 = g, ρ_t2 = a sin α_t − g of the flanks at each point
        (g from the pinion's base tangent point); ``pitch`` [mm], the pitch point's
        position from A; ``length`` [mm], g_α.

    Raises
    ------
    InputError
        Shapes other than (2,), non-positive diameters, tips inside the base circles, a
        path that reaches behind a base tangent point (interference), or too few points.

    Notes
    -----
    Involute geometry (ISO 21771:2007 §5): g_E = √(r_a1² − r_b1²), g_A = a sin α_t −
    √(r_a2² − r_b2²).
    """
    da = real_array("tip_diameter", tip_diameter, unit="mm", low=0.0, low_open=True)
    db = real_array("base_diameter", base_diameter, unit="mm", low=0.0, low_open=True)
    d = real_array("reference_diameter", reference_diameter, unit="mm", low=0.0,
                   low_open=True)
    for name, arr in (("tip_diameter", da), ("base_diameter", db),
                      ("reference_diameter", d)):
        if arr.shape != (2,):
            raise InputError(f"{name}: must have shape (2,) (pinion, gear), got {arr.shape}")
    alpha = real("pressure_angle", pressure_angle, unit="rad", low=0.0, high=math.pi / 2,
                 low_open=True, high_open=True)
    n = integer("points", points, low=3)
    if np.any(da <= db):
        raise InputError(f"tip_diameter: must exceed the base diameter {db.tolist()} [mm], "
                         f"got {da.tolist()}")
    line = 0.5 * float(d.sum()) * math.sin(alpha)  # T1T2
    g_e = 0.5 * math.sqrt(da[0] ** 2 - db[0] ** 2)
    g_a = line - 0.5 * math.sqrt(da[1] ** 2 - db[1] ** 2)
    if g_a <= 0.0 or g_e >= line:
        raise InputError("tip_diameter: the path of contact reaches behind a base tangent "
                         f"point (interference): A at {g_a:.4g} mm, E at {g_e:.4g} mm of "
                         f"T1T2 = {line:.4g} mm")
    g = np.linspace(g_a, g_e, n)
    return {"position": g - g_a, "radius": np.stack([g, line - g]),
            "pitch": 0.5 * float(d[0]) * math.sin(alpha) - g_a, "length": g_e - g_a}


def _rating_value(rating: xr.Dataset, name: str) -> np.ndarray:
    if name not in rating:
        raise InputError(f"rating: the dataset has no {name!r} (an ISO 10300 /rating group, "
                         "contact.load_capacity.iso10300, is needed)")
    return np.asarray(rating.variables[name].values, dtype=float)


@renamed_keywords(oil_temperature="temperature")
def iso_flash_temperature_method(
    rating: xr.Dataset,
    *,
    lubricant: str = "75W90",
    temperature: float,
    roughness: float,
    conditions: ScuffingConditions | None = None,
    points: int = 41,
    lengthwise_sliding: bool = False,
    friction_form: str = "iso",
    viscosity_in_scuffing_temperature: bool = False,
) -> xr.Dataset:
    """The standard's flash-temperature method on the virtual cylindrical gears of a pair.

    Parameters
    ----------
    rating : xarray.Dataset
        An ISO 10300 ``/rating`` dataset (:func:`contact.load_capacity.iso10300.iso10300_rating`):
        the
        virtual gears ``d_v``, ``d_va``, ``d_vb``, ``alpha_vet``, ``beta_v``, ``beta_vb``,
        ``p_vet``, ``eps_va``, ``eps_vb``, ``b_veff``, the speeds ``v_mt``, ``v_g``, the
        loads ``F_vmt`` and factors ``K_A``, ``K_v``, ``K_Hbeta``, ``K_Halpha`` over
        ``torque``, ``youngs_modulus`` and ``poisson_ratio``; its attributes
        ``materials`` (the members' materials, for the thermal effusivity) and
        ``gear_data`` (β_m1, for the normal speed).
    lubricant : str
        Oil name or file (:func:`friction.lubricant.load_lubricant`); it needs
        ``base_oil`` (X_L), and ``fzg_load_stage`` for the scuffing safety.
    temperature : float — [degC]
        θ_oil, the oil's inlet temperature (the ``temperature`` of
        :class:`friction.OperatingConditions`; old name ``oil_temperature``, deprecated).
    roughness : float — [µm]
        RMS roughness Rq of each flank (the case's), > 0; Ra = √(2/π) Rq.
    conditions : ScuffingConditions, optional
        Lubrication and meshing gears (bulk temperature) and X_W (scuffing temperature).
    points : int
        Points along the path of contact, ≥ 3; default 41.
    lengthwise_sliding : bool
        Add the hypoid's lengthwise sliding v_g to the profile sliding (not the standard's,
        :data:`METHOD_LENGTHWISE`); default False, the standard as written
        (:data:`METHOD_STANDARD`).
    friction_form : {"iso", "din"}
        The form of the mean friction coefficient (:func:`mean_friction_coefficient`);
        default ISO's.
    viscosity_in_scuffing_temperature : bool
        Multiply θ_S's X_L by η_oil^−0.05 (not the standard's; one end of the spread of
        S_B, module docstring); default False.

    Returns
    -------
    xarray.Dataset
        Over ``path`` (the position from A [mm]): ``load_sharing_factor`` [1],
        ``relative_radius`` [mm], ``sliding_velocity`` [m/s], ``surface_speed`` (member,
        path) [m/s] across the contact line; over (``torque``, ``path``):
        ``pressure_max`` [MPa], ``half_width`` [mm], ``flash_temperature`` [K],
        ``contact_temperature`` [degC]; over ``torque``: ``load_per_width`` (w_Bt)
        [N/mm], ``mean_friction_coefficient`` [1], ``flash_temperature_mean``,
        ``flash_temperature_max`` [K], ``bulk_temperature``, ``contact_temperature_max``
        [degC], ``scuffing_safety`` [1]; 0-d ``scuffing_temperature`` [degC]. The method
        (:data:`METHOD_STANDARD` or :data:`METHOD_LENGTHWISE`) in the attribute ``method``,
        the options in the attributes ``lengthwise_sliding`` (0/1), ``friction_form`` and
        ``viscosity_in_scuffing_temperature`` (0/1).

    Raises
    ------
    InputError
        A dataset without the variables named above, an oil without ``base_oil``, a bad
        temperature, roughness or point count (naming the field).

    Notes
    -----
    Module docstring (ISO/TR 13989-1:2000 / ISO/TS 6336-20:2017 on ISO 10300-1 Annex A's
    virtual gears; Blok 1963).
    """
    return _dataset(*_method(
        rating, lubricant=lubricant, temperature=temperature, roughness=roughness,
        conditions=conditions, points=points, lengthwise_sliding=lengthwise_sliding,
        friction_form=friction_form,
        viscosity_in_scuffing_temperature=viscosity_in_scuffing_temperature))


#: position of S_B in :func:`_method`'s result (the arguments of :func:`_dataset`)
_S_B = 17


def _method(rating: xr.Dataset, *, lubricant: str, temperature: float, roughness: float,
            conditions: ScuffingConditions | None, points: int, lengthwise_sliding: bool,
            friction_form: str, viscosity_in_scuffing_temperature: bool,
            memo: dict | None = None) -> tuple:
    """:func:`iso_flash_temperature_method`'s arithmetic: the arguments of
    :func:`_dataset` (S_B [1] per torque at :data:`_S_B`), no dataset built (the spread
    of :func:`iso_flash_temperature_variants` reads S_B alone, issue 75); ``memo`` keeps
    what no variant changes between the calls of one set of variants (the same oil
    temperature and points): the rating's values, the path of contact and its load
    sharing, the oil, its viscosity and the materials' effusivities."""
    memo = {} if memo is None else memo
    cond = ScuffingConditions() if conditions is None else conditions
    if not isinstance(cond, ScuffingConditions):
        raise InputError("conditions: must be a contact.load_capacity.flash_temperature."
                         f"ScuffingConditions or None, got {conditions!r}")
    t_oil = real("temperature", temperature, unit="degC", low=-273.15, low_open=True)
    rq = positive("roughness", roughness, "um")
    if not isinstance(rating, xr.Dataset):
        raise InputError(f"rating: must be an xarray.Dataset (/rating), got {type(rating)!r}")
    if "v" not in memo:  # the rating's values, read once for all the variants
        memo["v"] = {k: _rating_value(rating, k) for k in (
            "d_v", "d_va", "d_vb", "alpha_vet", "beta_v", "beta_vb", "p_vet", "eps_va",
            "eps_vb", "b_veff", "v_mt", "v_g", "F_vmt", "K_A", "K_v", "K_Hbeta", "K_Halpha",
            "youngs_modulus", "poisson_ratio")}
        memo["torque"] = np.atleast_1d(_rating_value(rating, "torque"))
    v, torque = memo["v"], memo["torque"]
    alpha, beta_vb = float(v["alpha_vet"]), float(v["beta_vb"])
    if "path" not in memo:  # the path of contact and its load sharing: every variant's
        path = path_of_contact(v["d_va"], v["d_vb"], v["d_v"], alpha, points)
        memo["path"] = path, load_sharing_factor(
            path["position"], path["length"], float(v["p_vet"]), float(v["eps_va"]),
            float(v["eps_vb"]))
    path, x_gamma = memo["path"]
    rho_t = path["radius"]
    rho_n = rho_t[0] * rho_t[1] / ((rho_t[0] + rho_t[1]) * math.cos(beta_vb))
    # speeds: the common normal speed v_mn = v_mt1 cos β_m1, in the virtual gears'
    # transverse section v_vt = v_mn / cos β_v; ω_vi = 2 v_vt / d_vi [1/s with mm → m]
    beta_m1 = _beta_m1(rating)
    v_vt = float(v["v_mt"][0]) * math.cos(beta_m1) / math.cos(float(v["beta_v"]))
    omega = 2.0 * v_vt / (v["d_v"] * 1e-3)
    speed = omega[:, None] * rho_t * 1e-3  # (2, path) along the profiles
    v_g = float(v["v_g"]) if lengthwise_sliding else 0.0
    sliding = np.hypot(speed[0] - speed[1], v_g)
    across = speed * math.cos(beta_vb)
    # loads and contact
    w_bt = (float(v["K_A"]) * np.atleast_1d(v["K_v"]) * float(v["K_Hbeta"])
            * np.atleast_1d(v["K_Halpha"]) * np.atleast_1d(v["F_vmt"]) / float(v["b_veff"]))
    w_n = x_gamma[None, :] * w_bt[:, None] / math.cos(alpha)  # (T, path)
    e, nu = v["youngs_modulus"], v["poisson_ratio"]
    e_star = 1.0 / float(np.sum((1.0 - nu ** 2) / e))
    half_width = np.sqrt(4.0 * w_n * rho_n[None, :] / (math.pi * e_star))
    p_h = 2.0 * w_n / (math.pi * half_width)
    # the oil, ISO's friction coefficient, the materials' effusivities
    if "oil" not in memo:
        memo["oil"] = load_lubricant(lubricant)
    oil = memo["oil"]
    if oil.base_oil is None:
        raise InputError(f"lubricant: the oil {oil.name} gives no base_oil (X_L of ISO's mean "
                         "friction coefficient; an optional oil-file field of "
                         "friction.lubricant)")
    if "eta" not in memo:  # (the same oil temperature for every variant)
        memo["eta"] = float(viscosity(oil, t_oil))
    eta = memo["eta"]
    pitch_t = np.array([0.5 * v["d_v"][0], 0.5 * v["d_v"][1]]) * math.sin(alpha)
    rho_c = float(pitch_t[0] * pitch_t[1] / (pitch_t.sum() * math.cos(beta_vb)))
    ra = GAUSSIAN_RA_PER_RQ * rq
    k_bg = helical_load_factor(float(v["eps_va"] + v["eps_vb"]))
    mu = np.asarray(mean_friction_coefficient(
        w_bt, 2.0 * v_vt * math.sin(alpha), rho_c, eta, ra, oil.base_oil, k_bg,
        form=friction_form), float)
    if "b_m" not in memo:  # the materials' effusivities, read once for all the variants
        names = [n.strip() for n in str(rating.attrs.get("materials", "")).split(",")]
        if len(names) != 2 or not all(names):
            raise InputError("rating: the dataset's attribute 'materials' must name the "
                             "pinion's and the gear's material, got "
                             f"{rating.attrs.get('materials')!r}")
        try:
            memo["b_m"] = [material(n).thermal_effusivity for n in names]
        except ModelUnavailableError as exc:
            raise InputError(f"rating.materials: no thermal properties ({exc})") from None
    b_m = memo["b_m"]
    flash = np.asarray(blok_flash_temperature(
        mu[:, None], p_h, half_width, sliding[None, :], across[0][None, :],
        across[1][None, :], b_m[0], b_m[1]), float)
    # uniform mean along the path (trapezoidal rule over the equally spaced points)
    flm = np.trapezoid(flash, path["position"], axis=1) / path["length"]
    bulk = np.asarray(bulk_temperature(t_oil, flm, cond), float).reshape(flm.shape)
    contact = bulk[:, None] + flash
    theta_max = contact.max(axis=1)
    theta_s, s_b, comment = _iso_scuffing(oil, eta, t_oil, cond, theta_max,
                                          viscosity_in_scuffing_temperature)
    method = METHOD_LENGTHWISE if lengthwise_sliding else METHOD_STANDARD
    return (rating, torque, path, x_gamma, rho_n, sliding, across, p_h, half_width,
            flash, contact, w_bt, mu, flm, bulk, theta_max, theta_s, s_b, comment,
            dict(method=method, lengthwise_sliding=int(bool(lengthwise_sliding)),
                         friction_form=friction_form,
                         viscosity_in_scuffing_temperature=int(
                             bool(viscosity_in_scuffing_temperature)),
                         lubricant=oil.name, oil_temperature_degC=t_oil, roughness_rq_um=rq,
                         helical_load_factor=k_bg, inlet_viscosity_Pa_s=eta,
                         scuffing_lubrication=cond.lubrication,
                         scuffing_meshing_gears=cond.meshing_gears,
                         scuffing_structural_factor=cond.structural_factor))


def _beta_m1(rating: xr.Dataset) -> float:
    """β_m1 [rad] from the rating's ``gear_data`` attribute (JSON of its GearData)."""
    try:
        return float(json.loads(rating.attrs["gear_data"])["beta_m1"])
    except (KeyError, TypeError, ValueError) as exc:
        raise InputError("rating: the dataset's attribute 'gear_data' must hold the pair's "
                         f"beta_m1 [rad] (contact.load_capacity.iso10300), got an error: "
                         f"{exc}") from None


def _iso_scuffing(oil, eta: float, t_oil: float, cond: ScuffingConditions,
                  theta_max: np.ndarray, viscosity_term: bool = False
                  ) -> tuple[float, np.ndarray, str]:
    """θ_S [degC] and S_B [1] per torque, NaN with the reason where the oil lacks its FZG
    load stage or θ_S is not above the oil; θ_S's X_L is the base oil's, times
    η_oil^−0.05 with ``viscosity_term`` (not the standard's)."""
    if oil.fzg_load_stage is None:
        return (math.nan, np.full(theta_max.shape, np.nan),
                f"NaN: the oil {oil.name} gives no fzg_load_stage")
    x_l = lubricant_factor(eta, oil.base_oil) if viscosity_term else base_oil_factor(
        oil.base_oil)
    theta_s = scuffing_temperature(oil.fzg_load_stage, x_l, cond.structural_factor)
    if theta_s <= t_oil:
        return (theta_s, np.full(theta_max.shape, np.nan),
                f"NaN: the scuffing temperature {theta_s:.0f} degC is not above the oil's")
    s_b = np.full(theta_max.shape, np.inf)
    hot = theta_max > t_oil
    if hot.any():
        s_b[hot] = scuffing_safety(theta_s, theta_max[hot], t_oil)
    return theta_s, s_b, "S_B = (theta_S - theta_oil) / (theta_Bmax - theta_oil)"


def _dataset(*args) -> xr.Dataset:
    """The dataset of one :func:`_method` result (its arguments)."""
    data, coords, attrs = _parts(*args)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _parts(rating, torque, path, x_gamma, rho_n, sliding, across, p_h, half_width, flash,
           contact, w_bt, mu, flm, bulk, theta_max, theta_s, s_b, comment,
           attrs) -> tuple[dict, dict, dict]:
    """(data variables, coordinates, attributes) of one :func:`_method` result, as
    ``(dims, values, attrs)`` tuples."""
    tp, t = ("torque", "path"), ("torque",)
    data = {
        "load_sharing_factor": data_var("path", x_gamma, "1", "load sharing factor X_Gamma"),
        "relative_radius": data_var("path", rho_n, "mm",
                                    "normal relative radius of curvature along the path"),
        "sliding_velocity": data_var("path", sliding, "m/s",
                                     "sliding speed (profile and hypoid lengthwise)"),
        "surface_speed": data_var(("member", "path"), across, "m/s",
                                  "flank speed across the contact line"),
        "pressure_max": data_var(tp, p_h, "MPa", "Hertzian peak pressure along the path"),
        "half_width": data_var(tp, half_width, "mm", "Hertzian half-width along the path"),
        "flash_temperature": data_var(tp, flash, "K",
                                      "flash temperature along the path of contact"),
        "contact_temperature": data_var(tp, contact, "degC",
                                        "contact temperature along the path of contact"),
        "load_per_width": data_var(t, w_bt, "N/mm",
                                   "transverse unit load w_Bt with the load factors"),
        "mean_friction_coefficient": data_var(t, mu, "1",
                                              "mean friction coefficient mu_m (ISO)"),
        "flash_temperature_mean": data_var(t, flm, "K",
                                           "mean flash temperature along the path"),
        "flash_temperature_max": data_var(t, flash.max(axis=1), "K",
                                          "peak flash temperature along the path"),
        "bulk_temperature": data_var(t, bulk, "degC", "bulk temperature theta_M"),
        "contact_temperature_max": data_var(t, theta_max, "degC",
                                            "peak contact temperature theta_Bmax"),
        "scuffing_temperature": data_var((), theta_s, "degC",
                                         "scuffing temperature of the oil theta_S"),
        "scuffing_safety": data_var(t, s_b, "1", "scuffing safety factor S_B",
                                    comment=comment),
    }
    coords = {"torque": ("torque", torque, rating["torque"].attrs),
              "path": ("path", path["position"],
                       {"units": "mm", "long_name": "position along the path of contact "
                        "from A (the gear's tip)"}),
              "member": ("member", ["pinion", "gear"], {"long_name": "gear pair member"})}
    return data, coords, {
        "title": "scuffing by the standard's flash temperature method",
        "case": str(rating.attrs.get("case", "")),
        "pitch_point_mm": float(path["pitch"]), "toolkit_version": __version__, **attrs}


#: the variables the lengthwise sliding changes (over ``variant``); the others are shared
_BY_VARIANT = ("sliding_velocity", "flash_temperature", "contact_temperature",
               "flash_temperature_mean", "flash_temperature_max", "bulk_temperature",
               "contact_temperature_max", "scuffing_safety")
#: the combinations of the uncertain constants whose S_B spread is reported:
#: (friction_form, viscosity_in_scuffing_temperature)
_SPREAD = (("iso", False), ("iso", True), ("din", False), ("din", True))


@renamed_keywords(oil_temperature="temperature")
def iso_flash_temperature_variants(
    rating: xr.Dataset,
    *,
    lubricant: str = "75W90",
    temperature: float,
    roughness: float,
    conditions: ScuffingConditions | None = None,
    points: int = 41,
) -> xr.Dataset:
    """The standard's flash-temperature method and its lengthwise-sliding variant, with the
    spread of S_B its uncertain constants give: the ``/rating/flash_temperature`` group.

    Parameters
    ----------
    rating, lubricant, temperature, roughness, conditions, points
        As :func:`iso_flash_temperature_method`.

    Returns
    -------
    xarray.Dataset
        The variables of :func:`iso_flash_temperature_method` (ISO's μ_m, θ_S with X_L
        alone) over a leading dimension ``variant`` = :data:`VARIANTS` (``standard``:
        ISO/TS 6336-20 as written on the virtual gears; ``lengthwise_sliding``: with the
        hypoid's lengthwise sliding, not a standard), the variant's description in the
        coordinate variable ``method`` (variant), plus ``scuffing_safety_low`` and
        ``scuffing_safety_high`` (variant, torque) [1]: the least and largest S_B over
        μ_m in ISO's or DIN 3990-4's form and θ_S with or without η_oil^−0.05 (module
        docstring).

    Raises
    ------
    InputError
        As :func:`iso_flash_temperature_method`.

    Notes
    -----
    Module docstring (ISO/TR 13989-1:2000 / ISO/TS 6336-20:2017 on ISO 10300-1 Annex A's
    virtual gears; DIN 3990-4:1987 for the other form of μ_m).
    """
    kw = dict(lubricant=lubricant, temperature=temperature, roughness=roughness,
              conditions=conditions, points=points, memo={})
    parts, low, high = [], [], []
    for lengthwise in VARIANTS.values():
        parts.append(_parts(*_method(rating, lengthwise_sliding=lengthwise,
                                     friction_form="iso",
                                     viscosity_in_scuffing_temperature=False, **kw)))
        spread = np.stack([np.asarray(_method(
            rating, lengthwise_sliding=lengthwise, friction_form=form,
            viscosity_in_scuffing_temperature=visc, **kw)[_S_B], float)
            for form, visc in _SPREAD])
        with np.errstate(invalid="ignore"):
            low.append(np.min(spread, axis=0))
            high.append(np.max(spread, axis=0))
    # one dataset of the variants' variables, as xr.concat over ``variant`` of each
    # variant's dataset would give (the variables of _BY_VARIANT stacked, the others and
    # the coordinates the first variant's), without building and aligning those datasets
    # (issue 75: they were a third of this step's CPU)
    methods = [str(attrs["method"]) for _, _, attrs in parts]
    (first, coords, attrs0), others = parts[0], [p[0] for p in parts[1:]]
    data = {}
    for name, (dims, values, var_attrs) in first.items():
        if name in _BY_VARIANT:
            dims = ("variant", *((dims,) if isinstance(dims, str) else dims))
            values = np.stack([np.asarray(values)]
                              + [np.asarray(o[name][1]) for o in others])
        data[name] = (dims, values, var_attrs)
    note = ("over the mean friction coefficient in ISO/TR 13989-1's form and in DIN "
            "3990-4's (0.060 (w_Bt K_Bgamma/(v_SigmaC rho_redC))^0.2 eta_oil^-0.05 Ra^0.25 "
            "X_L), and the scuffing temperature with X_L alone (the standard's) or X_L "
            "eta_oil^-0.05")
    data["scuffing_safety_low"] = (("variant", "torque"), np.stack(low),
                                   {"units": "1", "long_name": "least scuffing safety "
                                    "factor S_B of the uncertain constants", "comment": note})
    data["scuffing_safety_high"] = (("variant", "torque"), np.stack(high),
                                    {"units": "1", "long_name": "largest scuffing safety "
                                     "factor S_B of the uncertain constants", "comment": note})
    attrs = {k: v for k, v in attrs0.items() if k not in ("method", "lengthwise_sliding")}
    return dataset(data, {
        **coords,
        "variant": ("variant", list(VARIANTS), {"long_name": "variant of the flash "
                                                "temperature method"}),
        "method": ("variant", methods, {"long_name": "what the variant is"})}, {
        **attrs,
        "method": "; ".join(f"{k}: {m}" for k, m in zip(VARIANTS, methods, strict=True)),
        "friction_form": "iso", "viscosity_in_scuffing_temperature": 0})
