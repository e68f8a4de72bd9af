"""Pitch cones of spiral bevel and hypoid gear pairs after ISO 23509:2016, clause 5.

The basic design data of a face-milled bevel or hypoid pair (ISO 23509 "data type II",
Gleason style) are held in :class:`BevelGearDesign`; :func:`pitch_cone` turns them into the
pitch cone parameters at the calculation point P (the mean point) with one of the
standard's methods, chosen by number from :data:`PITCH_CONE_METHODS`:

* Method 0 — spiral bevel gears without offset (ISO 23509 cl. 5, "Method 0"),
* Method 1 — hypoid gears, Gleason method (ISO 23509 cl. 5, "Method 1").

Methods 2 (Oerlikon) and 3 (Klingelnberg) are not implemented.

What was reconstructed
----------------------
The standard itself was not at hand. The formulas below were rebuilt from the geometry of
two cones tangent at P and checked step by step against the published Annex F examples
(``tests/data/iso23509_annex_f_face_milling.toml``); equation numbers of the standard are
therefore not quoted. In particular:

* the approximate gear pitch angle δ_int2 with the factor 1.2 and the gear mean pitch
  radius r_mpt2 = (d_e2 − b2 sin δ_int2)/2, held fixed in Method 1, reproduce Annex F
  sample 2 exactly (R_e2 − R_m2 = 15.131 mm);
* the tangency relations of the hypoid pitch cones (:func:`hypoid_pitch_angles`) are
  exact geometry, derived here and checked against a 3-D construction in the tests;
* the limit pressure angle α_lim is the standard's (Wildhaber's) formula;
* the closing condition of Method 1 is the Gleason/Wildhaber design rule that the limit
  radius of lengthwise curvature ρ_lim equals the cutter radius r_c0
  (:func:`limit_radius`, derived from the condition that the contact line at P runs along
  the tooth). The standard iterates to a tolerance (its sample ends at β_m1 = 49.998° for a
  desired 50°); this module solves the same conditions to machine precision, which moves
  δ1, δ2 by about 0.01° against Annex F sample 2.

Frame used for the hypoid relations (right-handed): the gear axis is the z axis through
the crossing point O and points from the gear pitch apex into the gear (towards its back);
the common perpendicular of the axes is the x axis; the pinion axis passes through
(a, 0, 0) with unit vector e1 = (0, sin Σ, cos Σ), again pointing into the pinion.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from typing import Any

from scipy.optimize import brentq

from geometry.errors import InputError, ModelUnavailableError
from geometry.validation import integer, one_of, real

__all__ = [
    "BACKLASH_KINDS",
    "HANDS",
    "PITCH_CONE_METHODS",
    "BevelGearDesign",
    "PitchCone",
    "hypoid_pitch_angles",
    "limit_pressure_angle",
    "limit_radius",
    "pitch_cone",
]

#: hand of spiral of the pinion (the gear has the opposite hand)
HANDS = ("left", "right")
#: how the backlash is specified: outer normal j_en, outer transverse j_et2, mean normal j_mn
BACKLASH_KINDS = ("j_en", "j_et2", "j_mn")

_DEG = math.pi / 180.0
#: factor 1.2 of the approximate gear pitch angle of Method 1 (ISO 23509 cl. 5, Method 1)
_DELTA_INT_FACTOR = 1.2


# --------------------------------------------------------------------------- input data
@dataclass(frozen=True)
class BevelGearDesign:
    """Basic design data of a face-milled bevel/hypoid gear pair (ISO 23509 data type II).

    Angles are in radians and lengths in millimetres; :meth:`from_degrees` builds the
    object from angles in degrees (as in case files). Every field is validated on
    construction; a bad value raises :class:`~geometry.errors.InputError` naming the field
    and its accepted range.

    Parameters
    ----------
    method : int
        ISO 23509 pitch-cone method, a key of :data:`PITCH_CONE_METHODS`: 0 (spiral bevel,
        zero offset) or 1 (hypoid, Gleason).
    Sigma : float
        Shaft angle Σ [rad], 0 < Σ < π, with cos Σ > −z1/z2 (gear pitch angle below 90°).
    a : float
        Hypoid offset a [mm], 0 ≤ a < d_e2/2; must be 0 for Method 0. Only the offset that
        makes the pinion spiral angle larger than the gear's (the usual hypoid) is modelled.
    z1, z2 : int
        Numbers of teeth of pinion and gear [-], 5 ≤ z1 ≤ z2 ≤ 500.
    de2 : float
        Outer pitch diameter of the gear d_e2 [mm], > 0.
    b2 : float
        Face width of the gear b_2 [mm], 0 < b2 < d_e2/2 (checked against R_e2 later).
    beta_m : float
        Mean spiral angle [rad], 0 ≤ β ≤ 70°: the gear's β_m2 (= β_m1) for Method 0, the
        desired pinion β_m1 for Method 1.
    rc0 : float
        Nominal cutter radius r_c0 [mm], 0 < r_c0 ≤ 10 d_e2.
    alpha_dD, alpha_dC : float
        Design pressure angles of the drive and coast flanks α_dD, α_dC [rad], (0°, 45°).
    f_alim : float
        Influence factor of the limit pressure angle f_αlim [-], [0, 1].
    c_ham : float
        Mean addendum factor of the gear c_ham [-], [0, 0.5].
    k_d : float
        Depth factor k_d [-], (0, 4]: mean working depth h_mw = k_d m_mn.
    k_c : float
        Clearance factor k_c [-], [0, 0.5]: clearance c = k_c h_mw.
    k_t : float
        Thickness factor k_t [-], [−0.5, 0.5].
    backlash : str
        How the backlash is given, one of :data:`BACKLASH_KINDS`: ``"j_en"`` outer normal
        backlash (measured perpendicular to the flanks), ``"j_et2"`` outer transverse
        backlash of the gear, ``"j_mn"`` mean normal backlash.
    backlash_value : float
        The backlash [mm], [0, 2].
    theta_a2, theta_f2 : float
        Addendum and dedendum angles of the gear θ_a2, θ_f2 [rad], [0°, 20°] (data type II
        gives them directly; the pinion angles follow from the gear's).
    hand : str
        Hand of spiral of the pinion, ``"left"`` or ``"right"`` (does not change the blank).

    Notes
    -----
    Source: ISO 23509:2016 cl. 5.1 (initial data) and cl. 6.1 (data type II); field names
    are the standard's symbols.
    """

    method: int
    Sigma: float
    a: float
    z1: int
    z2: int
    de2: float
    b2: float
    beta_m: float
    rc0: float
    alpha_dD: float
    alpha_dC: float
    f_alim: float
    c_ham: float
    k_d: float
    k_c: float
    k_t: float
    backlash: str
    backlash_value: float
    theta_a2: float
    theta_f2: float
    hand: str = "left"

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        method = integer("method", self.method, 0, 9, allow_float=True)
        if method not in PITCH_CONE_METHODS:
            raise ModelUnavailableError(
                f"method = {method} is not available: implemented ISO 23509 pitch-cone methods "
                f"are {sorted(PITCH_CONE_METHODS)} (2 Oerlikon and 3 Klingelnberg are not)"
            )
        set_(self, "method", method)
        z1 = integer("z1", self.z1, 5, 500, allow_float=True)
        z2 = integer("z2", self.z2, z1, 500, allow_float=True)
        set_(self, "z1", z1)
        set_(self, "z2", z2)
        sigma = real("Sigma", self.Sigma, unit="deg", low=0.0, high=math.pi,
                     low_open=True, high_open=True, scale=_DEG)
        if math.cos(sigma) <= -z1 / z2:
            raise InputError(
                f"Sigma: must have cos Σ > −z1/z2 = {-z1 / z2:.4f} (gear pitch angle below "
                f"90°; internal bevel gears are not modelled) [deg], got {sigma / _DEG:g}"
            )
        set_(self, "Sigma", sigma)
        de2 = real("de2", self.de2, unit="mm", low=0.0, high=1e5, low_open=True)
        set_(self, "de2", de2)
        set_(self, "b2", real("b2", self.b2, unit="mm", low=0.0, high=de2 / 2,
                              low_open=True, high_open=True))
        a = real("a", self.a, unit="mm", low=0.0, high=de2 / 2, high_open=True)
        if method == 0 and a != 0.0:
            raise InputError(f"a: must be 0 for method 0 (use method 1 for hypoid gears) [mm], "
                             f"got {a:g}")
        set_(self, "a", a)
        set_(self, "beta_m", real("beta_m", self.beta_m, unit="deg", low=0.0,
                                  high=70 * _DEG, scale=_DEG))
        set_(self, "rc0", real("rc0", self.rc0, unit="mm", low=0.0, high=10 * de2,
                               low_open=True))
        for name in ("alpha_dD", "alpha_dC"):
            set_(self, name, real(name, getattr(self, name), unit="deg", low=0.0,
                                  high=45 * _DEG, low_open=True, high_open=True, scale=_DEG))
        set_(self, "f_alim", real("f_alim", self.f_alim, unit="1", low=0.0, high=1.0))
        set_(self, "c_ham", real("c_ham", self.c_ham, unit="1", low=0.0, high=0.5))
        set_(self, "k_d", real("k_d", self.k_d, unit="1", low=0.0, high=4.0, low_open=True))
        set_(self, "k_c", real("k_c", self.k_c, unit="1", low=0.0, high=0.5))
        set_(self, "k_t", real("k_t", self.k_t, unit="1", low=-0.5, high=0.5))
        one_of("backlash", self.backlash, BACKLASH_KINDS)
        set_(self, "backlash_value", real("backlash_value", self.backlash_value, unit="mm",
                                          low=0.0, high=2.0))
        for name in ("theta_a2", "theta_f2"):
            set_(self, name, real(name, getattr(self, name), unit="deg", low=0.0,
                                  high=20 * _DEG, scale=_DEG))
        one_of("hand", self.hand, HANDS)

    @property
    def u(self) -> float:
        """Gear ratio u = z2/z1 [-] (ISO 23509 cl. 5)."""
        return self.z2 / self.z1

    @classmethod
    def from_degrees(cls, **values: Any) -> BevelGearDesign:
        """Build the design from the same fields with angles in degrees.

        Parameters
        ----------
        **values
            The fields of :class:`BevelGearDesign`; ``Sigma``, ``beta_m``, ``alpha_dD``,
            ``alpha_dC``, ``theta_a2``, ``theta_f2`` in [deg], the rest as documented there.

        Returns
        -------
        BevelGearDesign

        Raises
        ------
        InputError
            On an unknown or missing field or a value out of range.
        """
        names = {f.name for f in fields(cls)}
        unknown = sorted(set(values) - names)
        if unknown:
            raise InputError(f"unknown design field(s) {unknown}: accepted {sorted(names)}")
        converted: dict[str, Any] = dict(values)
        for name in _ANGLE_INPUTS & set(values):
            converted[name] = real(name, values[name], unit="deg") * _DEG
        try:
            return cls(**converted)
        except TypeError as exc:  # missing required fields
            raise InputError(f"incomplete design data: {exc}") from None


_ANGLE_INPUTS = frozenset({"Sigma", "beta_m", "alpha_dD", "alpha_dC", "theta_a2", "theta_f2"})


# --------------------------------------------------------------------------- result
@dataclass(frozen=True)
class PitchCone:
    """Pitch cone parameters at the calculation point P (ISO 23509 cl. 5 results).

    Attributes
    ----------
    method : int
        Method used (0 or 1).
    u : float
        Gear ratio u = z2/z1 [-].
    delta1, delta2 : float
        Pitch angles δ1, δ2 [rad].
    Rm1, Rm2 : float
        Mean cone distances R_m1, R_m2 [mm].
    dm1, dm2 : float
        Mean pitch diameters d_m1, d_m2 [mm].
    beta_m1, beta_m2 : float
        Mean spiral angles β_m1, β_m2 [rad].
    zeta_m : float
        Pinion offset angle in the axial plane ζ_m [rad] (angle at the gear axis, in the
        gear's transverse projection, between the gear radius to P and the direction of
        the pinion axis).
    eta : float
        Gear offset angle in the pinion axial plane η [rad] (the same seen from the pinion).
    zeta_mp : float
        Offset angle in the pitch plane ζ_mp = β_m1 − β_m2 [rad].
    a_p : float
        Offset in the pitch plane a_p = R_m2 sin ζ_mp [mm].
    t_z1, t_z2 : float
        Pitch apex beyond the crossing point t_z1, t_z2 [mm], along each member's axis,
        positive when the apex lies on the far side of the crossing point seen from the
        member's back.
    m_mn : float
        Mean normal module m_mn = 2 R_m2 sin δ2 cos β_m2 / z2 [mm].
    alpha_lim : float
        Limit pressure angle α_lim [rad] (0 for Method 0).
    rho_lim : float
        Limit radius of lengthwise curvature ρ_lim [mm] (r_c0 for Method 1 by construction;
        ``inf`` for Method 0, where it is undefined).
    alpha_nD, alpha_nC : float
        Generated normal pressure angles of drive and coast flank [rad],
        α_nD = α_dD + f_αlim α_lim, α_nC = α_dC − f_αlim α_lim.
    c_be2 : float
        Face width factor c_be2 = (R_e2 − R_m2)/b2 [-] (0.5 in Method 0).
    Re2 : float
        Outer cone distance of the gear R_e2 = d_e2 / (2 sin δ2) [mm].
    """

    method: int
    u: float
    delta1: float
    delta2: float
    Rm1: float
    Rm2: float
    dm1: float
    dm2: float
    beta_m1: float
    beta_m2: float
    zeta_m: float
    eta: float
    zeta_mp: float
    a_p: float
    t_z1: float
    t_z2: float
    m_mn: float
    alpha_lim: float
    rho_lim: float
    alpha_nD: float
    alpha_nC: float
    c_be2: float
    Re2: float


# --------------------------------------------------------------------------- formulas
def hypoid_pitch_angles(zeta_m: float, eta: float, Sigma: float) -> tuple[float, float, float]:
    """Pitch angles and pitch-plane offset angle of two cones tangent at P.

    Parameters
    ----------
    zeta_m : float
        Pinion offset angle in the axial plane ζ_m [rad], > 0.
    eta : float
        Gear offset angle in the pinion axial plane η [rad], > 0.
    Sigma : float
        Shaft angle Σ [rad].

    Returns
    -------
    delta1, delta2, zeta_mp : float
        Pitch angles δ1, δ2 [rad] (possibly ≤ 0 or ≥ π/2 for infeasible input: the caller
        checks) and the offset angle in the pitch plane ζ_mp [rad].

    Raises
    ------
    InputError
        If ζ_m or η is not positive.

    Notes
    -----
    With P = (r2 sin ζ_m, r2 cos ζ_m, z_P) in the frame of the module docstring, the
    circumferential directions of the two cones at P are t2 = (−cos ζ_m, sin ζ_m, 0) and
    t1 = cos η x̂ + sin η (0, −cos Σ, sin Σ); the cone normals must both be normal to t1
    and t2, which gives (derived here, reduces for Σ = 90° to the Gleason relations
    tan δ1 = sin η / tan ζ_m, tan δ2 = sin ζ_m / tan η, sin ζ_mp = sin ζ_m / cos δ1):

        tan δ2 = (cos η sin ζ_m − sin η cos ζ_m cos Σ) / (sin η sin Σ)
        tan δ1 = (sin η cos ζ_m − cos η sin ζ_m cos Σ) / (sin ζ_m sin Σ)
        cos ζ_mp = cos η cos ζ_m + sin η sin ζ_m cos Σ

    Source: ISO 23509:2016 cl. 5 (hypoid pitch-cone relations); general-Σ form
    reconstructed from the geometry of tangent cones.
    """
    if not (zeta_m > 0.0 and eta > 0.0):
        raise InputError(f"zeta_m, eta: must be > 0 [rad], got {zeta_m!r}, {eta!r}")
    s_sig, c_sig = math.sin(Sigma), math.cos(Sigma)
    s_z, c_z = math.sin(zeta_m), math.cos(zeta_m)
    s_e, c_e = math.sin(eta), math.cos(eta)
    delta2 = math.atan2(c_e * s_z - s_e * c_z * c_sig, s_e * s_sig)
    delta1 = math.atan2(s_e * c_z - c_e * s_z * c_sig, s_z * s_sig)
    c_zp = c_e * c_z + s_e * s_z * c_sig
    # |t1 × t2| = sin ζ_mp, computed directly to keep precision for small angles
    t1 = (c_e, -s_e * c_sig, s_e * s_sig)
    t2 = (-c_z, s_z, 0.0)
    cross = (
        t1[1] * t2[2] - t1[2] * t2[1],
        t1[2] * t2[0] - t1[0] * t2[2],
        t1[0] * t2[1] - t1[1] * t2[0],
    )
    s_zp = math.sqrt(sum(c * c for c in cross))
    return delta1, delta2, math.atan2(s_zp, c_zp)


def limit_pressure_angle(
    delta1: float,
    delta2: float,
    Rm1: float,
    Rm2: float,
    beta_m1: float,
    beta_m2: float,
    zeta_mp: float,
) -> float:
    """Limit pressure angle α_lim of a hypoid pitch-cone pair.

    Parameters
    ----------
    delta1, delta2 : float
        Pitch angles [rad].
    Rm1, Rm2 : float
        Mean cone distances [mm].
    beta_m1, beta_m2 : float
        Mean spiral angles [rad].
    zeta_mp : float
        Offset angle in the pitch plane [rad].

    Returns
    -------
    float
        α_lim [rad] = −arctan[ tan δ1 tan δ2 / cos ζ_mp · (R_m1 sin β_m1 − R_m2 sin β_m2)
        / (R_m1 tan δ1 + R_m2 tan δ2) ]; 0 for a spiral bevel pair.

    Notes
    -----
    Source: ISO 23509:2016 cl. 5 (limit pressure angle, common to the hypoid methods;
    Wildhaber's limit normal). Reproduces Annex F sample 2 (−2.253°) from the sample's own
    pitch-cone values to 1e-4°.
    """
    t1, t2 = math.tan(delta1), math.tan(delta2)
    num = t1 * t2 / math.cos(zeta_mp) * (Rm1 * math.sin(beta_m1) - Rm2 * math.sin(beta_m2))
    return -math.atan(num / (Rm1 * t1 + Rm2 * t2))


def _limit_radius_terms(
    delta1: float, delta2: float, Rm1: float, Rm2: float,
    beta_m1: float, beta_m2: float, alpha_lim: float,
) -> tuple[float, float]:
    num = math.tan(beta_m1) - math.tan(beta_m2)
    den = (
        1.0 / (Rm1 * math.cos(beta_m1))
        - 1.0 / (Rm2 * math.cos(beta_m2))
        - math.tan(alpha_lim) * (
            math.tan(beta_m1) / (Rm1 * math.tan(delta1))
            + math.tan(beta_m2) / (Rm2 * math.tan(delta2))
        )
    )
    return num, den


def limit_radius(
    delta1: float,
    delta2: float,
    Rm1: float,
    Rm2: float,
    beta_m1: float,
    beta_m2: float,
    alpha_lim: float,
) -> float:
    """Limit radius of lengthwise tooth curvature ρ_lim at the calculation point.

    Parameters
    ----------
    delta1, delta2 : float
        Pitch angles [rad].
    Rm1, Rm2 : float
        Mean cone distances [mm].
    beta_m1, beta_m2 : float
        Mean spiral angles [rad].
    alpha_lim : float
        Limit pressure angle [rad] (:func:`limit_pressure_angle`).

    Returns
    -------
    float
        ρ_lim [mm] = (tan β_m1 − tan β_m2) / [1/(R_m1 cos β_m1) − 1/(R_m2 cos β_m2)
        − tan α_lim (tan β_m1/(R_m1 tan δ1) + tan β_m2/(R_m2 tan δ2))]; ``inf`` where the
        denominator vanishes (spiral bevel gears).

    Notes
    -----
    Reconstructed (the standard's own form was not available): a tooth whose lengthwise
    curve in the pitch plane is a circle of radius ρ and whose normal at P is inclined by
    α_lim to the pitch plane makes contact along the tooth direction at P when its normal
    curvature along the tooth, cos α_lim / ρ, equals N·(ω12 × w)/|w|², w the sliding
    velocity and ω12 the relative angular velocity. Writing the velocities with the pitch
    cone data gives the formula above; the tests check it against that vector form. The
    Gleason method chooses the pitch cones so that ρ_lim equals the cutter radius r_c0
    (ISO 23509 cl. 5, Method 1).
    """
    num, den = _limit_radius_terms(delta1, delta2, Rm1, Rm2, beta_m1, beta_m2, alpha_lim)
    if den == 0.0:
        return math.inf
    return num / den


# --------------------------------------------------------------------------- methods
def _method_0(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 0: spiral bevel gears without offset."""
    u, sigma = design.u, design.Sigma
    delta1 = math.atan2(math.sin(sigma), math.cos(sigma) + u)
    delta2 = sigma - delta1
    Re2 = design.de2 / (2.0 * math.sin(delta2))
    _check_face_width(design, Re2)
    Rm = Re2 - design.b2 / 2.0
    beta = design.beta_m
    return _bevel_result(design, delta1, delta2, Rm, beta, Re2)


def _bevel_result(
    design: BevelGearDesign, delta1: float, delta2: float, Rm: float, beta: float, Re2: float
) -> PitchCone:
    dm2 = 2.0 * Rm * math.sin(delta2)
    return PitchCone(
        method=design.method, u=design.u, delta1=delta1, delta2=delta2, Rm1=Rm, Rm2=Rm,
        dm1=2.0 * Rm * math.sin(delta1), dm2=dm2, beta_m1=beta, beta_m2=beta,
        zeta_m=0.0, eta=0.0, zeta_mp=0.0, a_p=0.0, t_z1=0.0, t_z2=0.0,
        m_mn=dm2 * math.cos(beta) / design.z2, alpha_lim=0.0, rho_lim=math.inf,
        alpha_nD=design.alpha_dD, alpha_nC=design.alpha_dC,
        c_be2=(Re2 - Rm) / design.b2, Re2=Re2,
    )


def _check_face_width(design: BevelGearDesign, Re2: float) -> None:
    if design.b2 >= Re2:
        raise InputError(
            f"b2: must be in (0, R_e2) = (0, {Re2:.4g}) for this pitch cone [mm], got "
            f"{design.b2:g}"
        )


def _hypoid_state(
    x: float, a: float, r2: float, u: float, beta1: float, sigma: float
) -> dict[str, float] | None:
    """Pitch-cone state for the shape parameter x = η/(η + ζ_m), or None if infeasible.

    Solves a = r2 sin ζ_m + r1 sin η together with the ratio condition
    u r1 cos β_m1 = r2 cos β_m2, β_m2 = β_m1 − ζ_mp, for the scale s = η + ζ_m.
    """
    s_max = math.asin(a / r2) / (1.0 - x)
    s_max = min(s_max, 0.5 * math.pi / x)

    def residual(s: float) -> float:
        eta, zeta = x * s, (1.0 - x) * s
        _, _, zeta_mp = hypoid_pitch_angles(zeta, eta, sigma)
        r1 = (a - r2 * math.sin(zeta)) / math.sin(eta)
        return u * r1 * math.cos(beta1) - r2 * math.cos(beta1 - zeta_mp)

    lo, hi = s_max * 1e-9, s_max * (1.0 - 1e-12)
    f_lo, f_hi = residual(lo), residual(hi)
    if not (f_lo > 0.0 > f_hi):
        return None
    s = brentq(residual, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=200)
    eta, zeta = x * s, (1.0 - x) * s
    delta1, delta2, zeta_mp = hypoid_pitch_angles(zeta, eta, sigma)
    if not (0.0 < delta1 < 0.5 * math.pi and 0.0 < delta2 < 0.5 * math.pi):
        return None
    r1 = (a - r2 * math.sin(zeta)) / math.sin(eta)
    return {
        "eta": eta, "zeta_m": zeta, "zeta_mp": zeta_mp, "delta1": delta1, "delta2": delta2,
        "r1": r1, "Rm1": r1 / math.sin(delta1), "Rm2": r2 / math.sin(delta2),
        "beta_m1": beta1, "beta_m2": beta1 - zeta_mp,
    }


def _rho_residual(state: dict[str, float], rc0: float) -> float:
    """r_c0·den − num of ρ_lim: zero where ρ_lim = r_c0, continuous through den = 0."""
    args = (state["delta1"], state["delta2"], state["Rm1"], state["Rm2"],
            state["beta_m1"], state["beta_m2"])
    alpha_lim = limit_pressure_angle(*args, state["zeta_mp"])
    num, den = _limit_radius_terms(*args, alpha_lim)
    return rc0 * den - num


def _method_1(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 1 (Gleason) for hypoid gears; see :func:`pitch_cone`."""
    u, sigma, a = design.u, design.Sigma, design.a
    beta1, rc0 = design.beta_m, design.rc0
    delta_int2 = math.atan2(u * math.sin(sigma), _DELTA_INT_FACTOR * (1.0 + u * math.cos(sigma)))
    r2 = 0.5 * (design.de2 - design.b2 * math.sin(delta_int2))
    if a >= r2:
        raise InputError(f"a: must be in [0, r_mpt2) = [0, {r2:.4g}) (offset below the gear "
                         f"mean pitch radius) [mm], got {a:g}")
    if a == 0.0:
        # limit a → 0 of the Gleason conditions: ρ_lim stays finite only if the two pitch
        # apexes meet, i.e. the bevel pitch cone, with Method 1's calculation point r_mpt2
        delta1 = math.atan2(math.sin(sigma), math.cos(sigma) + u)
        delta2 = sigma - delta1
        Re2 = design.de2 / (2.0 * math.sin(delta2))
        _check_face_width(design, Re2)
        return _bevel_result(design, delta1, delta2, r2 / math.sin(delta2), beta1, Re2)

    def g(x: float) -> float:
        state = _hypoid_state(x, a, r2, u, beta1, sigma)
        return math.nan if state is None else _rho_residual(state, rc0)

    # scan the shape parameter for the first crossing g: − → + (ρ_lim falling through r_c0
    # on its positive branch), then refine
    n = 240
    xs = [1e-3 + (1.0 - 2e-3) * i / (n - 1) for i in range(n)]
    gs = [g(x) for x in xs]
    bracket = next(
        ((xs[i], xs[i + 1]) for i in range(n - 1) if gs[i] < 0.0 < gs[i + 1]), None
    )
    if bracket is None:
        finite = [v for v in gs if math.isfinite(v)]
        raise InputError(
            "rc0: must be large enough for a Method 1 pitch cone whose limit radius equals "
            f"the cutter radius at a = {a:g} mm, beta_m = {beta1 / _DEG:g} deg (or use a "
            f"smaller offset) [mm], got {rc0:g} ({len(finite)} of {n} trial shapes feasible)"
        )
    x = brentq(g, *bracket, xtol=1e-15, rtol=1e-15, maxiter=200)
    st = _hypoid_state(x, a, r2, u, beta1, sigma)
    if st is None:  # pragma: no cover - g(x) was finite at both ends of the bracket
        raise InputError("Method 1 pitch cone became infeasible at the solution")
    delta1, delta2, Rm1, Rm2 = st["delta1"], st["delta2"], st["Rm1"], st["Rm2"]
    beta2, zeta_mp = st["beta_m2"], st["zeta_mp"]
    if beta2 <= 0.0:
        raise InputError(
            f"beta_m: must be > ζ_mp = {zeta_mp / _DEG:.4g} for method 1 (the gear spiral "
            f"angle would be {beta2 / _DEG:.4g} deg, of the wrong hand) [deg], got "
            f"{beta1 / _DEG:g}"
        )
    alpha_lim = limit_pressure_angle(delta1, delta2, Rm1, Rm2, beta1, beta2, zeta_mp)
    rho = limit_radius(delta1, delta2, Rm1, Rm2, beta1, beta2, alpha_lim)
    Re2 = design.de2 / (2.0 * math.sin(delta2))
    _check_face_width(design, Re2)
    # pitch apexes: P = A1 + y1 e1 + r1 p̂ = (r2 sin ζ, r2 cos ζ, z_P) (module frame)
    r1, eta, zeta = st["r1"], st["eta"], st["zeta_m"]
    y1 = (r2 * math.cos(zeta) + r1 * math.cos(eta) * math.cos(sigma)) / math.sin(sigma)
    z_p = y1 * math.cos(sigma) + r1 * math.cos(eta) * math.sin(sigma)
    f = design.f_alim
    return PitchCone(
        method=1, u=u, delta1=delta1, delta2=delta2, Rm1=Rm1, Rm2=Rm2,
        dm1=2.0 * r1, dm2=2.0 * r2, beta_m1=beta1, beta_m2=beta2,
        zeta_m=zeta, eta=eta, zeta_mp=zeta_mp, a_p=Rm2 * math.sin(zeta_mp),
        t_z1=Rm1 * math.cos(delta1) - y1, t_z2=Rm2 * math.cos(delta2) - z_p,
        m_mn=2.0 * r2 * math.cos(beta2) / design.z2, alpha_lim=alpha_lim, rho_lim=rho,
        alpha_nD=design.alpha_dD + f * alpha_lim, alpha_nC=design.alpha_dC - f * alpha_lim,
        c_be2=(Re2 - Rm2) / design.b2, Re2=Re2,
    )


#: ISO 23509 pitch-cone methods by number
PITCH_CONE_METHODS: Mapping[int, Callable[[BevelGearDesign], PitchCone]] = {
    0: _method_0,
    1: _method_1,
}


def pitch_cone(design: BevelGearDesign) -> PitchCone:
    """Pitch cone parameters at the calculation point (ISO 23509:2016 clause 5).

    Parameters
    ----------
    design : BevelGearDesign
        Basic design data; ``design.method`` picks the method from
        :data:`PITCH_CONE_METHODS`.

    Returns
    -------
    PitchCone
        Pitch angles, mean cone distances and diameters, spiral angles, offset angles,
        apex positions, mean normal module, limit pressure angle and generated pressure
        angles (angles in rad, lengths in mm).

    Raises
    ------
    InputError
        If the design has no valid pitch cone (face width beyond the outer cone distance,
        offset not below the gear mean pitch radius, cutter radius below every attainable
        limit radius, desired pinion spiral angle not above the offset angle ζ_mp).
    ModelUnavailableError
        If ``design.method`` is not implemented.

    Notes
    -----
    Method 0 (ISO 23509 cl. 5): u = z2/z1, δ1 = arctan[sin Σ/(cos Σ + u)], δ2 = Σ − δ1,
    R_e2 = d_e2/(2 sin δ2), R_m1 = R_m2 = R_e2 − b2/2, β_m1 = β_m2, α_lim = 0.

    Method 1 (ISO 23509 cl. 5, Gleason): δ_int2 = arctan[u sin Σ / (1.2 (1 + u cos Σ))],
    r_mpt2 = (d_e2 − b2 sin δ_int2)/2 is the gear mean pitch radius, β_m1 the desired pinion
    spiral angle; the pitch cones are tangent at P (:func:`hypoid_pitch_angles`) with
    a = r_mpt2 sin ζ_m + r_mn1 sin η and u = r_mpt2 cos β_m2/(r_mn1 cos β_m1),
    β_m2 = β_m1 − ζ_mp, and the last freedom is closed by ρ_lim = r_c0
    (:func:`limit_radius`). The standard's iteration on η, ζ_m is replaced by a bracketed
    root search on the shape η/(η + ζ_m), which converges to machine precision. At a = 0
    the conditions reduce to the bevel pitch cone at r_mpt2 (the limit of a → 0).
    α_nD = α_dD + f_αlim α_lim, α_nC = α_dC − f_αlim α_lim.
    """
    try:
        method = PITCH_CONE_METHODS[design.method]
    except KeyError:
        raise ModelUnavailableError(
            f"pitch-cone method {design.method!r} is not available: choose one of "
            f"{sorted(PITCH_CONE_METHODS)}"
        ) from None
    return method(design)
