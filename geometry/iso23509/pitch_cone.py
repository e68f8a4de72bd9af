"""Pitch cones of spiral bevel and hypoid gear pairs after ISO 23509:2016, clause 5.

The basic design data of a face-milled or face-hobbed bevel or hypoid pair (ISO 23509
input data type I or II) are held in :class:`BevelGearDesign`; :func:`pitch_cone` turns them
into the pitch cone parameters at the calculation point P (the mean point) with one of the
standard's methods, chosen by number from :data:`PITCH_CONE_METHODS`:

* Method 0 — spiral bevel gears without offset (ISO 23509 cl. 5, "Method 0"), face milling
  or face hobbing (the pitch cone does not depend on the process),
* Method 1 — hypoid gears, Gleason method (ISO 23509 cl. 5, "Method 1"), face milling
  (closure ρ_lim = r_c0) or face hobbing (closure ρ_lim = ρ_mβ),
* Method 2 — hypoid gears, Oerlikon method (ISO 23509 cl. 5, "Method 2"), face hobbing,
  from the gear mean pitch diameter d_m2,
* Method 3 — hypoid gears, Klingelnberg method (ISO 23509 cl. 5, "Method 3"), face hobbing.

The process follows from the number of blade groups z0 of the cutter: z0 = 0 is face
milling, z0 ≥ 1 face hobbing (then r_c0 is the nominal face-hobbing cutter radius and the
lengthwise tooth curve an extended epicycloid, :func:`face_hobbing_trace`).

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

Face hobbing (checked against ``tests/data/iso23509_annex_f_face_hobbing.toml``, Annex F
samples 3 and 4):

* the tooth trace at P (:func:`face_hobbing_trace`): lead angle ν, first auxiliary angle λ,
  crown-gear-centre to cutter-centre distance ρ_P0, base radius ρ_b, second auxiliary angle
  η1 and lengthwise radius of curvature ρ_mβ of the extended epicycloid, rebuilt from the
  rolling of the cutter on the crown gear (tests: an independently time-stepped epicycloid);
* Method 2 (Oerlikon) closes on the condition that the pinion pitch apex lies on the line
  from the gear pitch apex through the cutter centre in the pitch plane (the standard's
  check R_m1 = R_m,check = R_m2 sin φ6 / sin(180° − ζ_mp − φ6), φ6 the angle at the gear
  apex between P and the cutter centre). The standard reaches it by an approximation chain
  that stops once the check agrees within a tolerance: the printed values of sample 3 give
  R_m,check = 60.99 mm against R_m1 = 61.19 mm, 0.3 % short of the condition. Solved
  exactly here, δ2 is 0.07° and R_m1 0.26 % off the printed values (within the tolerances
  of the data file);
* Method 3 (Klingelnberg) closes on ρ_lim = ρ_mβ (the limit radius equals the lengthwise
  radius of the epicycloid at P), with the gear mean point at the middle of the face width
  (c_be2 = 0.5, d_m2 = d_e2 − b2 sin δ2). The standard writes the closure as an explicit
  approximation R_m,int = R_m1 inside a fixed-point iteration. That identification was
  made by re-running that iteration as transcribed in third-party public code (nothing of
  it is used here): its converged sample 4 (which reproduces every value the data file
  prints) satisfies ρ_lim = ρ_mβ to 0.1 %, and the exact solution here lies within 0.04 %
  (R_m1) and 0.01° (δ1, δ2) of it. Method 1 for face hobbing uses the same closure with the
  desired pinion spiral angle.

Frame used for the hypoid relations (right-handed): the gear axis is the z axis through
the crossing point O and points from the gear pitch apex into the gear (towards its back);
the common perpendicular of the axes is the x axis; the pinion axis passes through
(a, 0, 0) with unit vector e1 = (0, sin Σ, cos Σ), again pointing into the pinion.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields, replace

from scipy.optimize import brentq

from geometry.core.bisection import largest_found
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.validation import positive, real
from geometry.iso23509.design_data import (
    BACKLASH_KINDS,
    DEPTH_FIELDS,
    HANDS,
    INPUT_DATA_TYPES,
    BevelGearDesign,
)

__all__ = [
    "BACKLASH_KINDS",
    "DEPTH_FIELDS",
    "HANDS",
    "INPUT_DATA_TYPES",
    "PITCH_CONE_METHODS",
    "FaceHobbingTrace",
    "PitchCone",
    "face_hobbing_trace",
    "hypoid_pitch_angles",
    "limit_pressure_angle",
    "limit_radius",
    "pitch_cone",
]

_DEG = math.pi / 180.0


#: factor 1.2 of the approximate gear pitch angle of Method 1 (ISO 23509 cl. 5, Method 1)
_DELTA_INT_FACTOR = 1.2


# --------------------------------------------------------------------------- result
@dataclass(frozen=True)
class PitchCone:
    """Pitch cone parameters at the calculation point P (ISO 23509 cl. 5 results).

    Attributes
    ----------
    method : int
        Method used (0 to 3).
    u : float
        Gear ratio u = z2/z1 [1].
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
        Limit radius of lengthwise curvature ρ_lim [mm] (by construction r_c0 for Method 1
        face milling, ρ_mβ for Method 1 face hobbing and Method 3; ``inf`` for Method 0 and
        at zero offset, where it is undefined).
    alpha_nD, alpha_nC : float
        Generated normal pressure angles of drive and coast flank [rad],
        α_nD = α_dD + f_αlim α_lim, α_nC = α_dC − f_αlim α_lim.
    alpha_eD, alpha_eC : float
        Effective pressure angles of drive and coast flank [rad] (ISO 23509, the pressure
        angles the flanks have in mesh once the limit pressure angle is taken off the
        generated ones): α_eD = α_nD − α_lim, α_eC = α_nC + α_lim; with f_αlim = 1 they
        are the design pressure angles.
    c_be2 : float
        Face width factor c_be2 = (R_e2 − R_m2)/b2 [1] (0.5 in Methods 0, 2 and 3).
    Re2 : float
        Outer cone distance of the gear R_e2 = d_e2 / (2 sin δ2) [mm] (R_m2 + b2/2 in
        Method 2).
    nu, lambda_, rho_P0, rho_b, eta1, rho_mbeta : float
        The gear's tooth trace at P (:class:`FaceHobbingTrace`, on the gear's crown gear of
        z_p = z2/sin δ2 teeth): lead angle ν [rad], first auxiliary angle λ [rad] (ISO
        symbol λ; ``lambda`` is a Python keyword), crown-gear-centre to cutter-centre
        distance ρ_P0 [mm], base radius ρ_b [mm], second auxiliary angle η1 [rad],
        lengthwise radius of curvature ρ_mβ [mm]. For face milling (z0 = 0) their limits:
        ν = 0, ρ_b = ρ_P0, ρ_mβ = r_c0.
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
    alpha_eD: float
    alpha_eC: float
    c_be2: float
    Re2: float
    nu: float
    lambda_: float
    rho_P0: float
    rho_b: float
    eta1: float
    rho_mbeta: float


@dataclass(frozen=True)
class FaceHobbingTrace:
    """The lengthwise tooth curve of a face-hobbed member at a point (ISO 23509 symbols).

    Attributes
    ----------
    nu : float
        Lead angle of the cutter ν [rad]: sin ν = z0 m_n / (2 r_c0).
    lambda_ : float
        First auxiliary angle λ = 90° − β + ν [rad]: the angle at P between the directions
        to the crown gear centre and to the cutter centre.
    rho_P0 : float
        Distance from the crown gear centre to the cutter centre ρ_P0 [mm].
    rho_b : float
        Base radius ρ_b = ρ_P0 / (1 + z0/z_p) [mm]: distance from the crown gear centre to
        the pitch point of cutter and crown gear, through which the trace normal at P runs.
    eta1 : float
        Second auxiliary angle η1 [rad]: angle between the tooth trace at P and the line from
        the crown gear centre through the cutter centre (cos η1 = R cos β / ρ_b).
    rho_mbeta : float
        Lengthwise radius of curvature of the tooth trace at P ρ_mβ [mm].
    """

    nu: float
    lambda_: float
    rho_P0: float
    rho_b: float
    eta1: float
    rho_mbeta: float


# --------------------------------------------------------------------------- formulas
def face_hobbing_trace(
    R: float, beta: float, rc0: float, z0: float, z_p: float
) -> FaceHobbingTrace:
    """Tooth trace of a face-hobbed (or, for z0 = 0, face-milled) member at one point.

    Parameters
    ----------
    R : float
        Cone distance of the point (distance from the crown gear centre) [mm], > 0.
    beta : float
        Spiral angle at the point [rad], in (−90°, 90°).
    rc0 : float
        Nominal cutter radius r_c0 [mm], > 0: distance from the cutter centre to the blade
        as it passes the point.
    z0 : float
        Number of blade groups [1], ≥ 0 (real, so that the face-milling limit z0 → 0 can be
        approached; a design holds an integer). 0 gives the face-milling circle.
    z_p : float
        Number of teeth of the crown gear [1], > 0: z/sin δ for a member of pitch angle δ.

    Returns
    -------
    FaceHobbingTrace
        ν, λ, ρ_P0, ρ_b, η1, ρ_mβ (angles [rad], lengths [mm]).

    Raises
    ------
    InputError
        For an input out of range, or a cutter too small for the lead angle
        (z0 m_n ≥ 2 r_c0).

    Notes
    -----
    In the plane of the crown gear (centre O), the cutter (centre C) and the crown gear turn
    like two external gears of z0 and z_p teeth: relative to the crown gear the cutter
    rolls on the base circle ρ_b about O, and a blade at r_c0 from C traces an extended
    epicycloid. With the normal module m_n = 2 R cos β / z_p at the point P:

        sin ν = z0 m_n / (2 r_c0),  λ = 90° − β + ν,
        ρ_P0² = R² + r_c0² − 2 R r_c0 cos λ,  ρ_b = ρ_P0 / (1 + z0/z_p),
        η1 = atan2(r_c0 cos ν − R sin β, r_c0 sin ν + R cos β),
        ρ_mβ = R cos β [tan β + tan η1 / (1 + tan ν (tan β + tan η1))].

    The trace normal at P passes through the pitch point I (|OI| = ρ_b on OC), not through
    C: CP is turned by ν from it. η1 is written in the signed form (equal to
    arccos(R cos β / ρ_b) where that is positive), so that for z0 = 0 the formulas give the
    circle of radius r_c0 exactly: ν = 0, ρ_b = ρ_P0, ρ_mβ = r_c0.

    Source: ISO 23509:2016 cl. 5 (Method 1, face hobbing: lead angle, first and second
    auxiliary angle, lengthwise mean radius of curvature; Method 2: ν, λ, η1) and cl. 6
    (ρ_P0, ρ_b of the spiral angles at the face-width ends). Rebuilt from the rolling
    geometry above and checked in the tests against a time-stepped epicycloid.
    """
    R = positive("R", R, "mm")
    beta = real("beta", beta, unit="rad", low=-0.5 * math.pi, high=0.5 * math.pi,
                low_open=True, high_open=True)
    rc0 = positive("rc0", rc0, "mm")
    z0 = real("z0", z0, unit="1", low=0.0)
    z_p = positive("z_p", z_p, "1")
    c_b, s_b = math.cos(beta), math.sin(beta)
    s_nu = R * z0 * c_b / (rc0 * z_p)
    if not s_nu < 1.0:
        raise InputError(
            f"rc0: must be > z0 m_n / 2 = {R * z0 * c_b / z_p:.4g} (lead angle ν below 90°, "
            f"z0 = {z0:g}) [mm], got {rc0:g}"
        )
    nu = math.asin(s_nu)
    lam = 0.5 * math.pi - beta + nu
    rho_p0 = math.sqrt(R * R + rc0 * rc0 - 2.0 * R * rc0 * math.cos(lam))
    rho_b = rho_p0 / (1.0 + z0 / z_p)
    c_nu = math.cos(nu)
    eta1 = math.atan2(rc0 * c_nu - R * s_b, rc0 * s_nu + R * c_b)
    t_b, t_e, t_nu = s_b / c_b, math.tan(eta1), s_nu / c_nu
    den = 1.0 + t_nu * (t_b + t_e)
    rho = math.inf if den == 0.0 else R * c_b * (t_b + t_e / den)
    return FaceHobbingTrace(nu=nu, lambda_=lam, rho_P0=rho_p0, rho_b=rho_b, eta1=eta1,
                            rho_mbeta=rho)


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
def _bevel_angles(design: BevelGearDesign) -> tuple[float, float]:
    """Pitch angles δ1, δ2 of a bevel pair without offset (Method 0)."""
    sigma = design.Sigma
    delta1 = math.atan2(math.sin(sigma), math.cos(sigma) + design.u)
    return delta1, sigma - delta1


def _method_0(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 0: spiral bevel gears without offset."""
    delta1, delta2 = _bevel_angles(design)
    Re2 = design.de2 / (2.0 * math.sin(delta2))
    _check_face_width(design, Re2)
    Rm = Re2 - design.b2 / 2.0
    beta = design.beta_m
    return _bevel_result(design, delta1, delta2, Rm, beta, Re2)


def _trace(design: BevelGearDesign, Rm2: float, beta2: float, delta2: float) -> FaceHobbingTrace:
    """The gear's tooth trace at P (its crown gear has z2/sin δ2 teeth)."""
    return face_hobbing_trace(Rm2, beta2, design.rc0, design.z0, design.z2 / math.sin(delta2))


def _trace_fields(trace: FaceHobbingTrace) -> dict[str, float]:
    return {f.name: getattr(trace, f.name) for f in fields(trace)}


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
        alpha_eD=design.alpha_dD, alpha_eC=design.alpha_dC,
        c_be2=(Re2 - Rm) / design.b2, Re2=Re2,
        **_trace_fields(_trace(design, Rm, beta, delta2)),
    )


def _check_face_width(design: BevelGearDesign, Re2: float) -> None:
    if design.b2 >= Re2:
        raise InputError(
            f"b2: must be in (0, R_e2) = (0, {Re2:.4g}) for this pitch cone [mm], got "
            f"{design.b2:g}"
        )


def _check_offset(design: BevelGearDesign, r2: float) -> None:
    if design.a >= r2:
        raise InputError(f"a: must be in [0, r_m2) = [0, {r2:.4g}) (offset below the gear "
                         f"mean pitch radius) [mm], got {design.a:g}")


def _hypoid_state(
    x: float, a: float, r2: float, u: float, beta: float, sigma: float, *,
    gear_beta: bool = False,
) -> dict[str, float] | None:
    """Pitch-cone state for the shape parameter x = η/(η + ζ_m), or None if infeasible.

    Solves a = r2 sin ζ_m + r1 sin η together with the ratio condition
    u r1 cos β_m1 = r2 cos β_m2, β_m2 = β_m1 − ζ_mp, for the scale s = η + ζ_m; ``beta`` is
    the pinion's β_m1 (Method 1) or, with ``gear_beta``, the gear's β_m2 (Methods 2, 3).
    """
    s_max = math.asin(a / r2) / (1.0 - x)
    s_max = min(s_max, 0.5 * math.pi / x)

    def residual(s: float) -> float:
        eta, zeta = x * s, (1.0 - x) * s
        _, _, zeta_mp = hypoid_pitch_angles(zeta, eta, sigma)
        r1 = (a - r2 * math.sin(zeta)) / math.sin(eta)
        if gear_beta:
            return u * r1 * math.cos(beta + zeta_mp) - r2 * math.cos(beta)
        return u * r1 * math.cos(beta) - r2 * math.cos(beta - zeta_mp)

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
    beta1, beta2 = (beta + zeta_mp, beta) if gear_beta else (beta, beta - zeta_mp)
    return {
        "eta": eta, "zeta_m": zeta, "zeta_mp": zeta_mp, "delta1": delta1, "delta2": delta2,
        "r1": r1, "Rm1": r1 / math.sin(delta1), "Rm2": r2 / math.sin(delta2),
        "beta_m1": beta1, "beta_m2": beta2,
    }


def _lengthwise_radius(design: BevelGearDesign, state: dict[str, float]) -> float:
    """The radius the limit radius must equal: r_c0 (face milling) or ρ_mβ (face hobbing)."""
    if design.z0 == 0:
        return design.rc0
    return _trace(design, state["Rm2"], state["beta_m2"], state["delta2"]).rho_mbeta


def _rho_residual(state: dict[str, float], rho: float) -> float:
    """ρ·den − num of ρ_lim: zero where ρ_lim = ρ, continuous through den = 0."""
    args = (state["delta1"], state["delta2"], state["Rm1"], state["Rm2"],
            state["beta_m1"], state["beta_m2"])
    alpha_lim = limit_pressure_angle(*args, state["zeta_mp"])
    num, den = _limit_radius_terms(*args, alpha_lim)
    return rho * den - num


def _apex_residual(design: BevelGearDesign, state: dict[str, float]) -> float:
    """R_m1 sin(φ6 + ζ_mp) − R_m2 sin φ6: zero where the pinion apex lies on the line from
    the gear apex through the cutter centre (Method 2), continuous where φ6 + ζ_mp → 180°."""
    Rm2, trace = state["Rm2"], _trace(design, state["Rm2"], state["beta_m2"], state["delta2"])
    rc0, lam = design.rc0, trace.lambda_
    phi6 = math.atan2(rc0 * math.sin(lam), Rm2 - rc0 * math.cos(lam))
    return state["Rm1"] * math.sin(phi6 + state["zeta_mp"]) - Rm2 * math.sin(phi6)


#: number of trial shapes η/(η + ζ_m) scanned for the closing condition of Methods 1-3
_N_SHAPES = 240


def _solve_shape(
    closure: Callable[[dict[str, float]], float], a: float, r2: float, u: float, beta: float,
    sigma: float, *, gear_beta: bool, rising: bool,
    near: float | None = None,
) -> tuple[float, dict[str, float]] | None:
    """Shape x = η/(η + ζ_m) where ``closure`` of the hypoid state changes sign, and the state.

    Scans the shapes for the first crossing (− → + if ``rising``, else + → −) and refines it
    by Brent's method; with ``near`` a narrow bracket around that shape is tried first.
    None if there is no crossing.
    """
    def g(x: float) -> float:
        state = _hypoid_state(x, a, r2, u, beta, sigma, gear_beta=gear_beta)
        if state is None:
            return math.nan
        try:
            return closure(state)
        except InputError:  # e.g. a lead angle beyond 90° for this trial shape
            return math.nan

    def crosses(lo: float, hi: float) -> bool:
        return lo < 0.0 < hi if rising else lo > 0.0 > hi

    bracket = None
    if near is not None:
        lo, hi = max(near - 1e-3, 1e-3), min(near + 1e-3, 1.0 - 1e-3)
        if crosses(g(lo), g(hi)):
            bracket = (lo, hi)
    if bracket is None:
        # the shapes in order, up to the first crossing (the shapes beyond it are not
        # needed: each costs a Brent solve of the hypoid state)
        xs = [1e-3 + (1.0 - 2e-3) * i / (_N_SHAPES - 1) for i in range(_N_SHAPES)]
        g_prev = g(xs[0])
        for i in range(_N_SHAPES - 1):
            g_next = g(xs[i + 1])
            if crosses(g_prev, g_next):
                bracket = (xs[i], xs[i + 1])
                break
            g_prev = g_next
        if bracket is None:
            return None
    x = brentq(g, *bracket, xtol=1e-15, rtol=1e-15, maxiter=200)
    state = _hypoid_state(x, a, r2, u, beta, sigma, gear_beta=gear_beta)
    if state is None:  # pragma: no cover - g(x) was finite at both ends of the bracket
        raise InputError("the hypoid pitch cone became infeasible at the solution")
    return x, state


def _hypoid_result(design: BevelGearDesign, st: dict[str, float], r2: float, Re2: float
                   ) -> PitchCone:
    """PitchCone of a solved hypoid state (Methods 1-3)."""
    sigma = design.Sigma
    delta1, delta2, Rm1, Rm2 = st["delta1"], st["delta2"], st["Rm1"], st["Rm2"]
    beta1, beta2, zeta_mp = st["beta_m1"], st["beta_m2"], st["zeta_mp"]
    alpha_lim = limit_pressure_angle(delta1, delta2, Rm1, Rm2, beta1, beta2, zeta_mp)
    rho = limit_radius(delta1, delta2, Rm1, Rm2, beta1, beta2, alpha_lim)
    # pitch apexes: P = A1 + y1 e1 + r1 p̂ = (r2 sin ζ, r2 cos ζ, z_P) (module frame)
    r1, eta, zeta = st["r1"], st["eta"], st["zeta_m"]
    y1 = (r2 * math.cos(zeta) + r1 * math.cos(eta) * math.cos(sigma)) / math.sin(sigma)
    z_p = y1 * math.cos(sigma) + r1 * math.cos(eta) * math.sin(sigma)
    f = design.f_alim
    return PitchCone(
        method=design.method, u=design.u, delta1=delta1, delta2=delta2, Rm1=Rm1, Rm2=Rm2,
        dm1=2.0 * r1, dm2=2.0 * r2, beta_m1=beta1, beta_m2=beta2,
        zeta_m=zeta, eta=eta, zeta_mp=zeta_mp, a_p=Rm2 * math.sin(zeta_mp),
        t_z1=Rm1 * math.cos(delta1) - y1, t_z2=Rm2 * math.cos(delta2) - z_p,
        m_mn=2.0 * r2 * math.cos(beta2) / design.z2, alpha_lim=alpha_lim, rho_lim=rho,
        alpha_nD=design.alpha_dD + f * alpha_lim, alpha_nC=design.alpha_dC - f * alpha_lim,
        alpha_eD=design.alpha_dD + (f - 1.0) * alpha_lim,
        alpha_eC=design.alpha_dC - (f - 1.0) * alpha_lim,
        c_be2=(Re2 - Rm2) / design.b2, Re2=Re2,
        **_trace_fields(_trace(design, Rm2, beta2, delta2)),
    )


def _method_1(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 1 (Gleason) for hypoid gears; see :func:`pitch_cone`."""
    u, sigma, a = design.u, design.Sigma, design.a
    beta1 = design.beta_m
    delta_int2 = math.atan2(u * math.sin(sigma), _DELTA_INT_FACTOR * (1.0 + u * math.cos(sigma)))
    r2 = 0.5 * (design.de2 - design.b2 * math.sin(delta_int2))
    _check_offset(design, r2)
    if a == 0.0:
        # limit a → 0 of the Gleason conditions: ρ_lim stays finite only if the two pitch
        # apexes meet, i.e. the bevel pitch cone, with Method 1's calculation point r_mpt2
        delta1, delta2 = _bevel_angles(design)
        Re2 = design.de2 / (2.0 * math.sin(delta2))
        _check_face_width(design, Re2)
        return _bevel_result(design, delta1, delta2, r2 / math.sin(delta2), beta1, Re2)

    # the first crossing − → + of ρ·den − num over the shapes (ρ_lim falling through the
    # lengthwise radius on its positive branch)
    found = _solve_shape(lambda st: _rho_residual(st, _lengthwise_radius(design, st)),
                         a, r2, u, beta1, sigma, gear_beta=False, rising=True)
    if found is None:
        raise InputError(
            "rc0: must be large enough for a Method 1 pitch cone whose limit radius equals "
            f"the lengthwise radius of the tooth at a = {a:g} mm, beta_m = {beta1 / _DEG:g} deg "
            f"(or use a smaller offset) [mm], got {design.rc0:g}"
        )
    st = found[1]
    beta2, zeta_mp = st["beta_m2"], st["zeta_mp"]
    if beta2 <= 0.0:
        raise InputError(
            f"beta_m: must be > ζ_mp = {zeta_mp / _DEG:.4g} for method 1 (the gear spiral "
            f"angle would be {beta2 / _DEG:.4g} deg, of the wrong hand) [deg], got "
            f"{beta1 / _DEG:g}"
        )
    Re2 = design.de2 / (2.0 * math.sin(st["delta2"]))
    _check_face_width(design, Re2)
    return _hypoid_result(design, st, r2, Re2)


def _method_2(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 2 (Oerlikon), face hobbing; see :func:`pitch_cone`."""
    u, sigma, a, beta2 = design.u, design.Sigma, design.a, design.beta_m
    r2 = 0.5 * design.dm2
    _check_offset(design, r2)
    if a == 0.0:
        delta1, delta2 = _bevel_angles(design)
        Rm = r2 / math.sin(delta2)
        Re2 = Rm + 0.5 * design.b2
        return _bevel_result(design, delta1, delta2, Rm, beta2, Re2)
    # the lead angle depends on d_m2 and β_m2 only: check it before the search
    _trace(design, r2, beta2, 0.5 * math.pi)
    # R_m1 sin(φ6 + ζ_mp) − R_m2 sin φ6 falls through zero as the pinion apex crosses the
    # line gear apex → cutter centre
    found = _solve_shape(lambda st: _apex_residual(design, st), a, r2, u, beta2, sigma,
                         gear_beta=True, rising=False)
    if found is None:
        raise InputError(
            "rc0: must allow a Method 2 pitch cone whose pinion apex lies on the line from the "
            f"gear apex through the cutter centre at a = {a:g} mm, beta_m = "
            f"{beta2 / _DEG:g} deg, z0 = {design.z0} (or change the offset) [mm], got "
            f"{design.rc0:g}"
        )
    st = found[1]
    if design.delta2 is not None:
        st = _published_state(design, st, r2)
    Re2 = st["Rm2"] + 0.5 * design.b2
    return _hypoid_result(design, st, r2, Re2)


#: [rad] how far a given gear pitch angle of Method 2 may lie from the exact closing
#: condition: a stopped iteration (Annex F sample 3: 0.067°), not another design
_DELTA2_GIVEN_SPAN = math.radians(1.0)


def _published_state(design: BevelGearDesign, exact: dict[str, float], r2: float
                     ) -> dict[str, float]:
    """The hypoid state of Method 2 whose gear pitch angle is the given ``design.delta2``
    (the offset and ratio conditions hold; the apex closure is left where the standard's
    iteration stopped), within :data:`_DELTA2_GIVEN_SPAN` of the exact state ``exact``."""
    lo, hi = exact["delta2"] - _DELTA2_GIVEN_SPAN, exact["delta2"] + _DELTA2_GIVEN_SPAN
    if not lo <= design.delta2 <= hi:
        raise InputError(
            f"delta2: must lie within 1 deg of the exact Method 2 closure, in "
            f"[{lo / _DEG:.3f}, {hi / _DEG:.3f}] (the gear pitch angle at which a published "
            f"iteration stopped) [deg], got {design.delta2 / _DEG:g}")
    found = None
    for rising in (True, False):
        found = _solve_shape(lambda st: st["delta2"] - design.delta2, design.a, r2, design.u,
                             design.beta_m, design.Sigma, gear_beta=True, rising=rising)
        if found is not None:
            break
    if found is None:  # pragma: no cover - δ2 is continuous in the shape near the closure
        raise InputError(f"delta2: no Method 2 hypoid pitch cone has this gear pitch angle "
                         f"[deg], got {design.delta2 / _DEG:g}")
    return found[1]


#: iterations allowed for the gear mean pitch radius of Method 3 (converges in about 5)
_MAX_RADIUS_ITERATIONS = 100


def _method_3(design: BevelGearDesign) -> PitchCone:
    """ISO 23509:2016 cl. 5, Method 3 (Klingelnberg), face hobbing; see :func:`pitch_cone`."""
    u, sigma, a, beta2 = design.u, design.Sigma, design.a, design.beta_m
    de2, b2 = design.de2, design.b2
    _, delta2 = _bevel_angles(design)
    if a == 0.0:
        return _method_0(design)
    # the mean point is in the middle of the face width: r_m2 = (d_e2 − b2 sin δ2)/2 depends
    # on the solution; fixed point on δ2 (a contraction: r_m2 moves by b2 cos δ2 / 2 per
    # radian of δ2, and δ2 follows r_m2 only through a/r_m2)
    x_prev: float | None = None
    for _ in range(_MAX_RADIUS_ITERATIONS):
        r2 = 0.5 * (de2 - b2 * math.sin(delta2))
        _check_offset(design, r2)
        found = _solve_shape(
            lambda st: _rho_residual(st, _lengthwise_radius(design, st)), a, r2, u, beta2,
            sigma, gear_beta=True, rising=True, near=x_prev,
        )
        if found is None:
            raise InputError(
                "rc0: must allow a Method 3 pitch cone whose limit radius equals the "
                f"lengthwise radius of the tooth at a = {a:g} mm, beta_m = {beta2 / _DEG:g} deg, "
                f"z0 = {design.z0} (or change the offset) [mm], got {design.rc0:g}"
            )
        x_prev, st = found
        converged = abs(st["delta2"] - delta2) <= 1e-13
        delta2 = st["delta2"]
        if converged:
            break
    else:  # pragma: no cover - the map is a strong contraction
        raise InputError("b2: Method 3 found no consistent mean point (iteration on the gear "
                         f"pitch angle did not converge) [mm], got {b2:g}")
    Re2 = de2 / (2.0 * math.sin(st["delta2"]))
    _check_face_width(design, Re2)
    return _hypoid_result(design, st, r2, Re2)


#: ISO 23509 pitch-cone methods by number
PITCH_CONE_METHODS: Mapping[int, Callable[[BevelGearDesign], PitchCone]] = {
    0: _method_0,
    1: _method_1,
    2: _method_2,
    3: _method_3,
}


def _largest_closing_sigma(method, design: BevelGearDesign,
                           steps: int = 40) -> tuple[float, float] | None:
    """The largest shaft angle [rad] in [90°, ``design.Sigma``] at which ``method`` closes
    the pitch cone of ``design`` (its other data kept), with the gear pitch angle δ2 [rad]
    there, by bisection to (Σ − 90°)/2**``steps``; None where it does not close at 90°."""
    def closes(s: float) -> PitchCone | None:
        try:
            return method(replace(design, Sigma=s))
        except InputError:
            return None

    lo, hi = math.pi / 2, design.Sigma
    cone = closes(lo)
    if cone is None:
        return None
    lo, cone = largest_found(closes, lo, hi, steps, cone)
    return lo, cone.delta2


def pitch_cone(design: BevelGearDesign) -> PitchCone:
    """Pitch cone parameters at the calculation point (ISO 23509:2016 clause 5).

    Parameters
    ----------
    design : BevelGearDesign
        Basic design data; ``design.method`` picks the method from
        :data:`PITCH_CONE_METHODS`, ``design.z0`` the process (0 face milling, ≥ 1 face
        hobbing).

    Returns
    -------
    PitchCone
        Pitch angles, mean cone distances and diameters, spiral angles, offset angles,
        apex positions, mean normal module, limit pressure angle, generated pressure angles
        and the gear's tooth trace at P (angles in rad, lengths in mm).

    Raises
    ------
    InputError
        If the design has no valid pitch cone (face width beyond the outer cone distance,
        offset not below the gear mean pitch radius, no pitch cone meeting the method's
        closing condition for this cutter radius, desired pinion spiral angle not above the
        offset angle ζ_mp, a face-hobbing cutter too small for its lead angle); for a
        hypoid whose shaft angle is past a spiral bevel's bound arccos(−z1/z2), naming
        ``Sigma`` and that bound first, the method's own reason after it.
    ModelUnavailableError
        If ``design.method`` is not implemented.

    Notes
    -----
    Method 0 (ISO 23509 cl. 5): u = z2/z1, δ1 = arctan[sin Σ/(cos Σ + u)], δ2 = Σ − δ1,
    R_e2 = d_e2/(2 sin δ2), R_m1 = R_m2 = R_e2 − b2/2, β_m1 = β_m2, α_lim = 0.

    The hypoid methods share the pitch cones tangent at P (:func:`hypoid_pitch_angles`)
    with a = r_m2 sin ζ_m + r_m1 sin η, the ratio condition u = r_m2 cos β_m2/(r_m1 cos β_m1)
    and β_m1 = β_m2 + ζ_mp. That leaves one freedom, which each method closes its own way;
    the standard's iterations are replaced by a bracketed root search on the shape
    η/(η + ζ_m), converged to machine precision. At a = 0 each reduces to the bevel pitch
    cone at its own calculation point (the limit a → 0). In all of them α_lim follows
    :func:`limit_pressure_angle`, α_nD = α_dD + f_αlim α_lim, α_nC = α_dC − f_αlim α_lim.

    Method 1 (ISO 23509 cl. 5, Gleason): δ_int2 = arctan[u sin Σ / (1.2 (1 + u cos Σ))],
    r_mpt2 = (d_e2 − b2 sin δ_int2)/2 is the gear mean pitch radius, β_m1 the desired pinion
    spiral angle; closed by ρ_lim = r_c0 for face milling and ρ_lim = ρ_mβ for face hobbing
    (:func:`limit_radius`, :func:`face_hobbing_trace` of the gear at P).

    Method 2 (ISO 23509 cl. 5, Oerlikon; face hobbing): r_m2 = d_m2/2 is given, β_m2 the gear
    spiral angle, c_be2 = 0.5 (R_e2 = R_m2 + b2/2). Closed by the pinion pitch apex lying on
    the line from the gear pitch apex through the cutter centre in the pitch plane:
    R_m1 = R_m2 sin φ6 / sin(φ6 + ζ_mp), φ6 = angle at the gear apex between P and the
    cutter centre in the triangle of sides R_m2, r_c0 and angle λ at P.

    Method 3 (ISO 23509 cl. 5, Klingelnberg; face hobbing): β_m2 the gear spiral angle,
    c_be2 = 0.5, i.e. r_m2 = (d_e2 − b2 sin δ2)/2 (a fixed point on δ2), closed by
    ρ_lim = ρ_mβ.
    """
    try:
        method = PITCH_CONE_METHODS[design.method]
    except KeyError:
        raise ModelUnavailableError(
            f"pitch-cone method {design.method!r} is not available: choose one of "
            f"{sorted(PITCH_CONE_METHODS)}"
        ) from None
    z1, z2, sigma = design.z1, design.z2, design.Sigma
    if design.a == 0.0 or (math.cos(sigma) > -z1 / z2 and sigma <= math.pi / 2):
        return method(design)
    if math.cos(sigma) > -z1 / z2:
        # a hypoid above 90° but within the spiral bevel's bound: where its own pitch cone
        # does not close there but does at 90°, the shaft angle is the reason, not the
        # method's closing sentence (issue 71, round 40: the FM 11x37 at a = 56 mm by
        # Method 1, δ2 88.2° at Σ 105°, refused at Σ 107° with "rc0: must be large
        # enough …, got 88.9", which no rc0 up to 228.6 mm closed)
        try:
            return method(design)
        except InputError as exc:
            largest = _largest_closing_sigma(method, design)
            if largest is None:
                raise
            raise InputError(
                f"Sigma: must be at most {math.degrees(largest[0]):.2f} for this hypoid "
                f"{z1}x{z2} at a = {design.a:g} mm by method {design.method} (its own pitch "
                f"cone closes from 90° up to there, the gear pitch angle then "
                f"{math.degrees(largest[1]):.2f}°) [deg], got {math.degrees(sigma):g}: the "
                f"method's pitch cone does not close there ({exc})"
            ) from None
    # A hypoid past the spiral bevel's bound (refused for a = 0 by BevelGearDesign): its
    # own pitch cone has a smaller gear pitch angle (issue 71, round 39: the FH 12x41 at
    # a = 31.5 mm and Σ 110°, past 107.02°, has δ2 80.2°); where it does not close, the
    # shaft angle is said first, the method's own reason after it
    try:
        return method(design)
    except InputError as exc:
        raise InputError(
            f"Sigma: must be below {math.degrees(math.acos(-z1 / z2)):.2f} for {z1}x{z2} "
            f"(cos Σ > −z1/z2 = {-z1 / z2:.4f}: a spiral bevel's gear pitch angle below "
            f"90°; internal bevel gears are not modelled) unless the hypoid's own pitch "
            f"cone closes past it [deg], got {math.degrees(sigma):g}: at a = {design.a:g} mm "
            f"the method {design.method} pitch cone does not ({exc})"
        ) from None
