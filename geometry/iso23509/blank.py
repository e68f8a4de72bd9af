"""Blank geometry of spiral bevel and hypoid gears after ISO 23509:2016, clause 6.

:func:`gear_dimensions` takes the basic design data (:class:`~geometry.iso23509.pitch_cone.
BevelGearDesign`) and the pitch cone (:func:`~geometry.iso23509.pitch_cone.pitch_cone`) and returns
the blank of both members: cone distances, spiral angles at heel, mean point and toe,
pitch/face/root angles and apexes, addenda and dedenda, tooth depth, mean normal tooth
thickness, diameters and crown-to-crossing-point distances, as frozen dataclasses
(:class:`MemberBlank` per member, :class:`BlankGeometry` for the pair). Angles are stored
in radians; :func:`in_degrees` reports them in degrees and :func:`blank_dataset` packs
everything into an ``xarray.Dataset`` with ``units`` and ``long_name`` on every variable.

What was reconstructed
----------------------
The standard was not at hand; each formula below was rebuilt from the blank geometry and
checked against the Annex F examples (``tests/data/iso23509_annex_f_face_milling.toml``):

* tooth depths from data type II (h_mw = k_d m_mn, h_am2 = c_ham h_mw, c = k_c h_mw) and
  the outer/inner addenda and dedenda along the face angles reproduce both samples;
* the pinion face and root angles of a hypoid pair follow from tangency of the pinion
  face (root) cone with the gear root (face) cone offset by the clearance c; ζ_R and ζ_o
  are the azimuths at which the normal line from the mean point P to the gear root (face)
  cone meets the pinion axis (sample 2: ζ_R, ζ_o within 0.01 % of the printed values);
* the pinion face width b1 = b2 / cos ζ_mp + 2 Δb_x1 with Δb_x1 = h_mw sin ζ_R (1 − 1/u)
  reproduces sample 2 to 0.01 mm at both ends;
* backlash j_en is taken as measured perpendicular to the flanks (j_mn = j_en R_m2 /
  (R_e2 cos α_n)); with that the thicknesses of sample 1 agree to 0.002 mm;
* tooth depths from data type I (h_mw = 2 k_hap m_mn, h_am2 = (k_hap − x_hm1) m_mn,
  c = (k_hfp − k_hap) m_mn, thickness 2 x_smn m_mn) are the type II relations under the
  standard's conversion; they reproduce h_mw of sample 4
  (``tests/data/iso23509_annex_f_face_hobbing.toml``);
* uniform depth (θ_a2 = θ_f2 = 0, the face-hobbing samples 3 and 4) needs no branch: the
  pinion face and root angles still follow from the tangency with the clearance, and come
  out uniform too (δ_a1 = δ_f1 = δ1: the gear root and face cones, parallel to its pitch
  cone, touch the pinion cones along the common normal of the pitch cones at P, which
  meets both axes); sample 3's δ_a1 is within 0.3 % of the printed value, the difference of
  the pitch angle δ1;
* the pinion face width is the method's: Methods 0 and 1 as below; Method 2
  b1 = b2 (1 + tan² ζ_mp) with the calculation point in the middle (sample 3: 0.01 %);
  Method 3 the pinion's stretch of the pitch plane between the gear's toe and heel circles,
  b_p1 = √(R_e2² − a_p²) − √(R_i2² − a_p²), widened by 3 m_mn |tan ζ_mp| + 1 mm and
  rounded down to a whole millimetre, the extra width shared equally by both ends (this
  rule was taken from a transcription of the standard; no printed value checks it);
* spiral angles at heel and toe follow the tooth trace in the pitch plane
  (:func:`spiral_angle_at`): the cutter circle of radius r_c0 for face milling, the
  extended epicycloid of :func:`~geometry.iso23509.pitch_cone.face_hobbing_trace` for face hobbing
  (β(R) = arctan[(R − ρ_b cos q)/(ρ_b sin q)], q the angle at the crown gear centre between
  the point and the cutter centre; sample 3: β_e1 within 0.01 %), for the gear at its own
  face-width ends. For the pinion of a
  hypoid pair the cutter formula is evaluated at the gear cone distance R_e21 (R_i21) of
  the pinion's face-width end, reached along the pinion generatrix through P in the pitch
  plane, and the pitch-plane offset angle there, arcsin(a_p/R_x21), is added
  (:func:`pinion_spiral_angle_at`). This reproduces sample 2 (β_e1 57.546° vs 57.544°,
  β_i1 44.884° vs 44.879°) and reduces to the bevel result for a = 0 (sample 1 exact).

Signs: apex distances t_z, t_zF, t_zR are "beyond the crossing point": measured along the
member's axis from the crossing point away from the member's back (positive when the apex
lies beyond the crossing point). The crown-to-crossing-point distances t_xo, t_xi are
measured from the crossing point to the heel and toe crowns, towards the member's back.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping
from dataclasses import asdict, dataclass, fields, is_dataclass
from typing import Any, ClassVar

import numpy as np
import xarray as xr

from geometry.core.errors import InputError
from geometry.core.validation import positive, real
from geometry.core.version import __version__
from geometry.iso23509.pitch_cone import BevelGearDesign, PitchCone, face_hobbing_trace, pitch_cone

__all__ = [
    "BACKLASH_TO_MEAN_NORMAL",
    "BlankGeometry",
    "MemberBlank",
    "blank_dataset",
    "blank_geometry",
    "check_face_angles",
    "gear_dimensions",
    "in_degrees",
    "pinion_spiral_angle_at",
    "spiral_angle_at",
]


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class MemberBlank:
    """Blank of one member (pinion or gear), ISO 23509 clause 6 symbols.

    Attributes
    ----------
    z : int
        Number of teeth [1].
    delta, delta_a, delta_f : float
        Pitch angle δ, face angle δ_a, root angle δ_f [rad].
    theta_a, theta_f : float
        Addendum angle θ_a = δ_a − δ and dedendum angle θ_f = δ − δ_f [rad].
    Re, Rm, Ri : float
        Outer, mean and inner cone distance R_e, R_m, R_i [mm] (along the pitch cone).
    b : float
        Face width b = R_e − R_i [mm].
    beta_e, beta_m, beta_i : float
        Spiral angle at heel (outer), mean point and toe (inner) β_e, β_m, β_i [rad].
    ham, hfm : float
        Mean addendum h_am and mean dedendum h_fm [mm] (normal to the pitch cone).
    hae, hfe, hai, hfi : float
        Outer addendum h_ae, outer dedendum h_fe, inner addendum h_ai, inner dedendum
        h_fi [mm].
    de, dm, di : float
        Outer, mean and inner pitch diameter d_e, d_m, d_i [mm].
    dae, dfe, dai, dfi : float
        Outer and inner tip (face) and root diameters d_ae, d_fe, d_ai, d_fi [mm].
    t_z, t_zF, t_zR : float
        Pitch, face and root apex beyond the crossing point t_z, t_zF, t_zR [mm].
    txo, txi : float
        Outer (heel) and inner (toe) crown to crossing point t_xo, t_xi [mm].
    smn : float
        Mean normal circular tooth thickness s_mn [mm] (backlash allowance included).
    """

    z: int
    delta: float
    delta_a: float
    delta_f: float
    theta_a: float
    theta_f: float
    Re: float
    Rm: float
    Ri: float
    b: float
    beta_e: float
    beta_m: float
    beta_i: float
    ham: float
    hfm: float
    hae: float
    hfe: float
    hai: float
    hfi: float
    de: float
    dm: float
    di: float
    dae: float
    dfe: float
    dai: float
    dfi: float
    t_z: float
    t_zF: float
    t_zR: float
    txo: float
    txi: float
    smn: float

    ANGLES: ClassVar[frozenset[str]] = frozenset(
        {"delta", "delta_a", "delta_f", "theta_a", "theta_f", "beta_e", "beta_m", "beta_i"}
    )


@dataclass(frozen=True)
class BlankGeometry:
    """Blank geometry of a bevel/hypoid pair (ISO 23509 clause 6).

    Attributes
    ----------
    design : BevelGearDesign
        The basic design data the blank was computed from.
    pitch : PitchCone
        Pitch cone parameters at the calculation point (clause 5).
    pinion, gear : MemberBlank
        The two members.
    met2 : float
        Outer transverse module of the gear m_et2 = d_e2/z2 [mm].
    m_mn : float
        Mean normal module m_mn [mm].
    hmw : float
        Mean working depth h_mw = k_d m_mn [mm].
    c : float
        Clearance c = k_c h_mw [mm].
    hm : float
        Mean whole depth h_m = h_mw + c [mm].
    j_mn : float
        Mean normal backlash j_mn [mm].
    zeta_R : float
        Pinion offset angle in the root plane ζ_R [rad] (gear root cone ↔ pinion face cone).
    zeta_o : float
        Pinion offset angle in the face plane ζ_o [rad] (gear face cone ↔ pinion root cone).
    Delta_bx1 : float
        Pinion face width increment Δb_x1 at each end [mm] (Methods 0 and 1; ``nan`` for
        Methods 2 and 3, whose pinion face width rules have no such term).
    """

    design: BevelGearDesign
    pitch: PitchCone
    pinion: MemberBlank
    gear: MemberBlank
    met2: float
    m_mn: float
    hmw: float
    c: float
    hm: float
    j_mn: float
    zeta_R: float
    zeta_o: float
    Delta_bx1: float

    ANGLES: ClassVar[frozenset[str]] = frozenset({"zeta_R", "zeta_o"})

    @property
    def u(self) -> float:
        """Gear ratio u = z2/z1 [1]."""
        return self.design.u


_PITCH_ANGLES = frozenset(
    {"delta1", "delta2", "beta_m1", "beta_m2", "zeta_m", "eta", "zeta_mp", "alpha_lim",
     "alpha_nD", "alpha_nC", "alpha_eD", "alpha_eC", "nu", "lambda_", "eta1"}
)
_DESIGN_ANGLES = frozenset({"Sigma", "beta_m", "alpha_dD", "alpha_dC", "theta_a2", "theta_f2"})


# --------------------------------------------------------------------------- backlash
def _jmn_from_outer_normal(design: BevelGearDesign, pitch: PitchCone) -> float:
    alpha_n = 0.5 * (pitch.alpha_nD + pitch.alpha_nC)
    return design.backlash_value * pitch.Rm2 / (pitch.Re2 * math.cos(alpha_n))


def _jmn_from_outer_transverse(design: BevelGearDesign, pitch: PitchCone) -> float:
    return design.backlash_value * pitch.Rm2 / pitch.Re2 * math.cos(pitch.beta_m2)


def _jmn_given(design: BevelGearDesign, pitch: PitchCone) -> float:
    return design.backlash_value


#: mean normal backlash j_mn [mm] from the backlash as specified (``design.backlash``):
#: j_en outer normal, measured perpendicular to the flanks → j_en R_m2 / (R_e2 cos α_n),
#: α_n = (α_nD + α_nC)/2; j_et2 outer transverse of the gear → j_et2 (R_m2/R_e2) cos β_m2;
#: j_mn given directly. Reconstructed, checked on ISO 23509 Annex F samples 1 and 2.
BACKLASH_TO_MEAN_NORMAL: Mapping[str, Callable[[BevelGearDesign, PitchCone], float]] = {
    "j_en": _jmn_from_outer_normal,
    "j_et2": _jmn_from_outer_transverse,
    "j_mn": _jmn_given,
}


# --------------------------------------------------------------------------- formulas
def spiral_angle_at(
    R: float, Rm: float, beta_m: float, rc0: float, z0: float = 0.0, z_p: float = math.inf
) -> float:
    """Spiral angle at cone distance R of a face-milled or face-hobbed tooth.

    Parameters
    ----------
    R : float
        Cone distance where the angle is wanted [mm], > 0.
    Rm : float
        Mean cone distance [mm].
    beta_m : float
        Mean spiral angle [rad].
    rc0 : float
        Cutter radius r_c0 [mm]: radius of the tooth trace in the pitch plane (face
        milling), distance from the cutter centre to the blade (face hobbing).
    z0 : float
        Number of blade groups [1], ≥ 0: 0 (default) for face milling. Real, so that the
        face-milling limit can be approached.
    z_p : float
        Number of crown gear teeth [1], z/sin δ of the member; used for face hobbing only.

    Returns
    -------
    float
        β(R) [rad]. Face milling: arcsin[(R² − R_m² + 2 R_m r_c0 sin β_m) / (2 R r_c0)].
        Face hobbing: arctan[(R − ρ_b cos q) / (ρ_b sin q)] with
        q = arccos[(R² + ρ_P0² − r_c0²) / (2 R ρ_P0)], ρ_P0 and ρ_b of the tooth trace at the
        mean point (:func:`~geometry.iso23509.pitch_cone.face_hobbing_trace`).

    Raises
    ------
    InputError
        If the cutter does not reach cone distance R (argument outside [−1, 1]), or a
        face-hobbing input is out of range.

    Notes
    -----
    Source: ISO 23509:2016 cl. 6 (spiral angles at outer and inner end). Face milling: the
    tooth trace is a circle of radius r_c0 through the mean point with spiral angle β_m; the
    law of cosines in the pitch plane gives the formula. Face hobbing: the trace is the
    extended epicycloid of the blade as the cutter rolls on the base circle ρ_b; at the
    point of the trace at distance R from the crown gear centre O the blade is r_c0 from the
    cutter centre C at that instant (seen from the crown gear C runs on the circle of radius
    ρ_P0 about O), q is the angle at O in that triangle, and the trace
    normal runs through the pitch point I on OC at ρ_b from O, which gives the arctangent
    (the tests compare it with a time-stepped epicycloid). For z0 → 0, ρ_b → ρ_P0 and the
    face-hobbing formula tends to the face-milling one.
    """
    z0 = real("z0", z0, unit="1", low=0.0)
    if z0 == 0.0:
        arg = (R * R - Rm * Rm + 2.0 * Rm * rc0 * math.sin(beta_m)) / (2.0 * R * rc0)
        if not -1.0 <= arg <= 1.0:
            raise InputError(
                "rc0: must be large enough for the cutter circle through the mean point to "
                f"reach cone distance {R:.4g} mm (or reduce b2) [mm], got {rc0:g}"
            )
        return math.asin(arg)
    R = positive("R", R, "mm")
    trace = face_hobbing_trace(Rm, beta_m, rc0, z0, z_p)
    rho_p0, rho_b = trace.rho_P0, trace.rho_b
    arg = (R * R + rho_p0 * rho_p0 - rc0 * rc0) / (2.0 * R * rho_p0)
    if not -1.0 <= arg <= 1.0:
        raise InputError(
            "rc0: must be large enough for the face-hobbing tooth trace through the mean point "
            f"to reach cone distance {R:.4g} mm (or reduce b2) [mm], got {rc0:g}"
        )
    q = math.acos(arg)
    return math.atan2(R - rho_b * math.cos(q), rho_b * math.sin(q))


def pinion_spiral_angle_at(
    b_x1: float, Rm2: float, beta_m2: float, zeta_mp: float, rc0: float,
    z0: float = 0.0, z_p2: float = math.inf,
) -> float:
    """Pinion spiral angle at a point of the pinion face width (hypoid or bevel pair).

    Parameters
    ----------
    b_x1 : float
        Signed distance [mm] from the calculation point P along the pinion pitch generatrix:
        b_e1 = R_e1 − R_m1 > 0 towards the heel, −b_i1 = R_i1 − R_m1 < 0 towards the toe.
    Rm2 : float
        Mean cone distance of the gear R_m2 [mm], > 0.
    beta_m2 : float
        Mean spiral angle of the gear β_m2 [rad].
    zeta_mp : float
        Offset angle in the pitch plane ζ_mp = β_m1 − β_m2 [rad], [0, π/2).
    rc0 : float
        Cutter radius r_c0 [mm], > 0.
    z0 : float
        Number of blade groups [1]: 0 (default) for face milling, ≥ 1 for face hobbing.
    z_p2 : float
        Number of teeth of the gear's crown gear z2/sin δ2 [1] (face hobbing only).

    Returns
    -------
    float
        β_x1 [rad] = β_x21 + ζ_xp21, where (law of cosines in the pitch plane)

        R_x21 = sqrt(R_m2² + b_x1² + 2 R_m2 b_x1 cos ζ_mp)

        is the gear cone distance of the pinion point, β_x21 the gear spiral angle at R_x21
        (:func:`spiral_angle_at` with R_m2, β_m2, r_c0, z0, z_p2: the gear's tooth trace),
        and ζ_xp21 = arcsin(a_p / R_x21), a_p = R_m2 sin ζ_mp, the offset angle in the pitch
        plane at that point.

    Raises
    ------
    InputError
        If R_m2 is not positive, ζ_mp is outside [0, π/2), the point reaches the foot of the
        perpendicular from the gear apex (R_x21 ≤ a_p), or the cutter circle does not reach
        R_x21.

    Notes
    -----
    Source: ISO 23509:2016 cl. 6 (face widths and spiral angles at the outer and inner end
    of the pinion, face milling), as in ANSI/AGMA 2005-D03 and Gleason's hypoid dimension
    sheets: the pinion spiral angle at its heel (toe) is the gear's spiral angle at the
    corresponding point plus the offset angle in the pitch plane there. Reconstructed (the
    standard's text was not at hand): in the pitch plane the pinion generatrix through P
    passes the gear apex at the distance a_p; the pinion face-width end lies on it at
    b_x1 from P, i.e. at gear cone distance R_x21, where the offset angle is
    arcsin(a_p/R_x21) — at P (b_x1 = 0) this is ζ_mp and β_x1 = β_m2 + ζ_mp = β_m1. For
    a = 0 (ζ_mp = 0) it is :func:`spiral_angle_at` at R_m1 + b_x1. Reproduces ISO 23509
    Annex F sample 2 (β_e1 = 57.544°, β_i1 = 44.879°) to 0.005°; the naive cutter formula
    at the pinion's own cone distances misses by 1.7° and 1.0°.
    """
    Rm2 = positive("Rm2", Rm2, "mm")
    zeta_mp = real("zeta_mp", zeta_mp, unit="rad", low=0.0, high=0.5 * math.pi, high_open=True)
    a_p = Rm2 * math.sin(zeta_mp)
    # along the pinion generatrix: distance from the foot of the perpendicular from the gear
    # apex is R_m2 cos ζ_mp + b_x1, at distance a_p from the apex
    s_x = Rm2 * math.cos(zeta_mp) + b_x1
    if not s_x > 0.0:
        raise InputError(
            f"b_x1: must be > −R_m2 cos ζ_mp = {-Rm2 * math.cos(zeta_mp):.4g} (toe beyond the "
            f"offset foot point) [mm], got {b_x1:.4g}"
        )
    R_x21 = math.hypot(s_x, a_p)
    return spiral_angle_at(R_x21, Rm2, beta_m2, rc0, z0, z_p2) + math.asin(a_p / R_x21)


def _offset_azimuth(
    a: float, sigma: float, delta_cone: float, r_q: float, z_q: float
) -> float:
    """Azimuth φ at which a normal line of a gear cone meets the pinion axis.

    The normal line of the cone (axis z, half angle δ) passes through the meridian point
    (r_q, z_q) at azimuth φ, z from the crossing point towards the gear back. Coplanarity
    of that line with the pinion axis gives A sin φ − B cos φ = C with
    A = (r_q sin δ + z_q cos δ) sin Σ, B = a cos δ cos Σ, C = a sin δ sin Σ; for (r_q, z_q)
    the mean point P, r_q sin δ + z_q cos δ = R_m2 cos(δ2 − δ) − t_z2 cos δ.
    """
    s_d, c_d = math.sin(delta_cone), math.cos(delta_cone)
    A = (r_q * s_d + z_q * c_d) * math.sin(sigma)
    B = a * c_d * math.cos(sigma)
    C = a * s_d * math.sin(sigma)
    R = math.hypot(A, B)
    if R == 0.0 or abs(C) > R:
        raise InputError(
            "a: must be small enough for the pinion face/root cone to be made tangent to the "
            f"gear root/face cone (offset too large for the blank) [mm], got {a:g}"
        )
    return math.atan2(B, A) + math.asin(C / R)


def _depth_factors(design: BevelGearDesign, m_mn: float) -> tuple[float, float, float, float]:
    """Mean working depth h_mw, gear mean addendum h_am2, clearance c and the thickness
    term (k_t m_mn = 2 x_smn m_mn) [mm] from input data type II or I."""
    if design.input_data_type == "II":
        hmw = design.k_d * m_mn
        return hmw, design.c_ham * hmw, design.k_c * hmw, design.k_t * m_mn
    return (2.0 * design.k_hap * m_mn, (design.k_hap - design.x_hm1) * m_mn,
            (design.k_hfp - design.k_hap) * m_mn, 2.0 * design.x_smn * m_mn)


def _pinion_face_width(
    design: BevelGearDesign, p: PitchCone, Ri2: float, hmw: float, zeta_R: float
) -> tuple[float, float, float]:
    """R_e1, R_i1 [mm] and Δb_x1 [mm] (nan where the method has none) of the pinion."""
    Re2, Rm2, zeta_mp = p.Re2, p.Rm2, p.zeta_mp
    if design.method == 2:
        b1 = design.b2 * (1.0 + math.tan(zeta_mp) ** 2)
        return p.Rm1 + p.c_be2 * b1, p.Rm1 - (1.0 - p.c_be2) * b1, math.nan
    if design.method == 3:
        a_p = p.a_p
        foot_i = math.sqrt(Ri2 * Ri2 - a_p * a_p)
        b_p1 = math.sqrt(Re2 * Re2 - a_p * a_p) - foot_i
        b1 = math.floor(b_p1 + 3.0 * p.m_mn * abs(math.tan(zeta_mp)) + 1.0)
        b_i1 = math.sqrt(Rm2 * Rm2 - a_p * a_p) - foot_i + 0.5 * (b1 - b_p1)
        return p.Rm1 + b1 - b_i1, p.Rm1 - b_i1, math.nan
    delta_bx1 = hmw * math.sin(zeta_R) * (1.0 - 1.0 / design.u)
    cz = math.cos(zeta_mp)
    Re1 = p.Rm1 + (Re2 - Rm2) / cz + delta_bx1
    Ri1 = p.Rm1 - (Rm2 - Ri2) / cz - delta_bx1
    return Re1, Ri1, delta_bx1


def gear_dimensions(design: BevelGearDesign, pitch: PitchCone | None = None) -> BlankGeometry:
    """Blank dimensions of both members (ISO 23509:2016 clause 6).

    Parameters
    ----------
    design : BevelGearDesign
        Basic design data.
    pitch : PitchCone, optional
        Pitch cone of ``design``; computed with :func:`~geometry.iso23509.pitch_cone.pitch_cone`
        when omitted.

    Returns
    -------
    BlankGeometry
        Pinion and gear blanks (:class:`MemberBlank`) and the pair quantities; angles [rad],
        lengths [mm].

    Raises
    ------
    InputError
        If the blank degenerates: non-positive inner addendum/dedendum (θ or b2 too large),
        non-positive tooth thickness, a cutter circle that does not reach the face ends, or
        an offset too large for the face/root cone tangency.

    Notes
    -----
    Formulas, per member i with its own δ, R_m, θ, h (clause 6 of ISO 23509:2016):

    * m_et2 = d_e2/z2; data type II: h_mw = k_d m_mn, h_am2 = c_ham h_mw, c = k_c h_mw;
      data type I: h_mw = 2 k_hap m_mn, h_am2 = (k_hap − x_hm1) m_mn,
      c = (k_hfp − k_hap) m_mn; then h_am1 = h_mw − h_am2, h_m = h_mw + c,
      h_fm,i = h_m − h_am,i.
    * gear: R_e2 = d_e2/(2 sin δ2) (R_m2 + b2/2 for Method 2, whose d_e2 = 2 R_e2 sin δ2 is a
      result), R_i2 = R_e2 − b2, δ_a2 = δ2 + θ_a2, δ_f2 = δ2 − θ_f2 (uniform depth:
      θ_a2 = θ_f2 = 0),
      t_zF2 = t_z2 − (R_m2 sin θ_a2 − h_am2 cos θ_a2)/sin δ_a2,
      t_zR2 = t_z2 + (R_m2 sin θ_f2 − h_fm2 cos θ_f2)/sin δ_f2.
    * ζ_R, ζ_o: the normal line from P to the gear root (face) cone meets the pinion axis;
      for Σ = 90°: sin ζ_R = a sin δ_f2 / (R_m2 cos θ_f2 − t_z2 cos δ_f2),
      sin ζ_o = a sin δ_a2 / (R_m2 cos θ_a2 − t_z2 cos δ_a2) (general Σ: see the code).
    * pinion angles: sin δ_a1 = sin Σ cos δ_f2 cos ζ_R − cos Σ sin δ_f2,
      sin δ_f1 = sin Σ cos δ_a2 cos ζ_o − cos Σ sin δ_a2 (tangency with clearance c),
      t_zF1 = (a sin ζ_R cos δ_f2 − t_zR2 sin δ_f2 − c)/sin δ_a1,
      t_zR1 = (a sin ζ_o cos δ_a2 − t_zF2 sin δ_a2 − c)/sin δ_f1.
      For a = 0 these reduce to δ_a1 = δ1 + θ_f2, δ_f1 = δ1 − θ_a2.
    * pinion face width, Methods 0 and 1: Δb_x1 = h_mw sin ζ_R (1 − 1/u);
      R_e1 = R_m1 + (R_e2 − R_m2)/cos ζ_mp + Δb_x1, R_i1 = R_m1 − (R_m2 − R_i2)/cos ζ_mp − Δb_x1.
      Method 2: b1 = b2 (1 + tan² ζ_mp), R_e1 = R_m1 + c_be2 b1, R_i1 = R_e1 − b1.
      Method 3: b_p1 = √(R_e2² − a_p²) − √(R_i2² − a_p²),
      b1 = ⌊b_p1 + 3 m_mn |tan ζ_mp| + 1 mm⌋, b_i1 = √(R_m2² − a_p²) − √(R_i2² − a_p²)
      + (b1 − b_p1)/2, R_i1 = R_m1 − b_i1, R_e1 = R_i1 + b1.
    * h_ae = h_am + (R_e − R_m) tan θ_a, h_fe = h_fm + (R_e − R_m) tan θ_f,
      h_ai = h_am − (R_m − R_i) tan θ_a, h_fi = h_fm − (R_m − R_i) tan θ_f.
    * d_e = 2 R_e sin δ, d_i = 2 R_i sin δ, d_ae = d_e + 2 h_ae cos δ, d_fe = d_e − 2 h_fe cos δ,
      d_ai = d_i + 2 h_ai cos δ, d_fi = d_i − 2 h_fi cos δ.
    * t_xo = R_e cos δ − h_ae sin δ − t_z, t_xi = R_i cos δ − h_ai sin δ − t_z.
    * gear β_e2, β_i2 from :func:`spiral_angle_at` at R_e2, R_i2 with r_c0 (and z0, z2/sin δ2
      for face hobbing); pinion β_e1, β_i1 from :func:`pinion_spiral_angle_at` at
      b_e1 = R_e1 − R_m1, −b_i1 = R_i1 − R_m1 (gear spiral angle at the pinion end's gear
      cone distance plus the offset angle in the pitch plane there; for a = 0 the same as
      the gear formula).
    * s_mn1 = π m_mn/2 + (h_am1 − h_am2)(tan α_nD + tan α_nC)/2 + k_t m_mn − j_mn/2
      (k_t m_mn = 2 x_smn m_mn for data type I), s_mn2 = π m_mn − s_mn1 − j_mn, j_mn from
      :data:`BACKLASH_TO_MEAN_NORMAL`.

    What was reconstructed and how well it reproduces Annex F is listed in the module
    docstring.
    """
    p = pitch_cone(design) if pitch is None else pitch
    sigma, a = design.Sigma, design.a
    m_mn = p.m_mn
    hmw, ham2, c, thickness = _depth_factors(design, m_mn)
    ham1 = hmw - ham2
    hm = hmw + c
    hfm1, hfm2 = hm - ham1, hm - ham2

    # gear cones and apexes
    Re2, Rm2 = p.Re2, p.Rm2
    Ri2 = Re2 - design.b2
    th_a2, th_f2 = design.theta_a2, design.theta_f2
    d2 = p.delta2
    da2, df2 = d2 + th_a2, d2 - th_f2
    if df2 <= 0.0:
        raise InputError(
            f"theta_f2: must be in [0, δ2) = [0, {math.degrees(d2):.4g}) [deg], got "
            f"{math.degrees(th_f2):g}"
        )
    t_zF2 = p.t_z2 - (Rm2 * math.sin(th_a2) - ham2 * math.cos(th_a2)) / math.sin(da2)
    t_zR2 = p.t_z2 + (Rm2 * math.sin(th_f2) - hfm2 * math.cos(th_f2)) / math.sin(df2)

    # pinion face/root angles from tangency with the gear root/face cones: the tangency
    # point is the foot of the perpendicular from the mean point P on the gear cone, so the
    # normal line passes through P's meridian position (r from the gear axis, z from the
    # crossing point towards the gear back)
    z_p = -p.t_z2 + Rm2 * math.cos(d2)
    r_p = Rm2 * math.sin(d2)
    zeta_R = _offset_azimuth(a, sigma, df2, r_p, z_p)
    zeta_o = _offset_azimuth(a, sigma, da2, r_p, z_p)
    s_sig, c_sig = math.sin(sigma), math.cos(sigma)
    da1 = math.asin(s_sig * math.cos(df2) * math.cos(zeta_R) - c_sig * math.sin(df2))
    df1 = math.asin(s_sig * math.cos(da2) * math.cos(zeta_o) - c_sig * math.sin(da2))
    t_zF1 = (a * math.sin(zeta_R) * math.cos(df2) - t_zR2 * math.sin(df2) - c) / math.sin(da1)
    t_zR1 = (a * math.sin(zeta_o) * math.cos(da2) - t_zF2 * math.sin(da2) - c) / math.sin(df1)

    # pinion face width
    Re1, Ri1, delta_bx1 = _pinion_face_width(design, p, Ri2, hmw, zeta_R)

    # thickness
    try:
        to_jmn = BACKLASH_TO_MEAN_NORMAL[design.backlash]
    except KeyError:  # pragma: no cover - validated in BevelGearDesign
        raise InputError(f"backlash: must be one of {sorted(BACKLASH_TO_MEAN_NORMAL)}, got "
                         f"{design.backlash!r}") from None
    j_mn = to_jmn(design, p)
    tan_alpha = 0.5 * (math.tan(p.alpha_nD) + math.tan(p.alpha_nC))
    smn1 = 0.5 * math.pi * m_mn + (ham1 - ham2) * tan_alpha + thickness - 0.5 * j_mn
    smn2 = math.pi * m_mn - smn1 - j_mn
    if smn2 <= 0.0 or smn1 <= 0.0:
        name = "k_t" if design.input_data_type == "II" else "x_smn"
        raise InputError(
            f"{name}: must leave both teeth a thickness s_mn > 0 (with h_am1 − h_am2 = "
            f"{ham1 - ham2:.4g} mm, backlash {design.backlash_value:g} mm) [1], got "
            f"{getattr(design, name):g}: s_mn1 = {smn1:.4g} mm, s_mn2 = {smn2:.4g} mm"
        )

    # spiral angles at heel and toe: gear on its own tooth trace, pinion via the gear's
    # angle at the corresponding point plus the pitch-plane offset angle there
    rc0, z0, z_p2 = design.rc0, design.z0, design.z2 / math.sin(d2)
    beta_e2 = spiral_angle_at(Re2, Rm2, p.beta_m2, rc0, z0, z_p2)
    beta_i2 = spiral_angle_at(Ri2, Rm2, p.beta_m2, rc0, z0, z_p2)
    beta_e1 = pinion_spiral_angle_at(Re1 - p.Rm1, Rm2, p.beta_m2, p.zeta_mp, rc0, z0, z_p2)
    beta_i1 = pinion_spiral_angle_at(Ri1 - p.Rm1, Rm2, p.beta_m2, p.zeta_mp, rc0, z0, z_p2)

    pinion = _member(
        z=design.z1, delta=p.delta1, delta_a=da1, delta_f=df1, Re=Re1, Rm=p.Rm1, Ri=Ri1,
        beta_e=beta_e1, beta_m=p.beta_m1, beta_i=beta_i1, ham=ham1, hfm=hfm1, t_z=p.t_z1,
        t_zF=t_zF1, t_zR=t_zR1, smn=smn1,
    )
    gear = _member(
        z=design.z2, delta=d2, delta_a=da2, delta_f=df2, Re=Re2, Rm=Rm2, Ri=Ri2,
        beta_e=beta_e2, beta_m=p.beta_m2, beta_i=beta_i2, ham=ham2, hfm=hfm2, t_z=p.t_z2,
        t_zF=t_zF2, t_zR=t_zR2, smn=smn2,
    )
    de2 = design.de2 if design.de2 is not None else gear.de  # Method 2: a result
    return BlankGeometry(
        design=design, pitch=p, pinion=pinion, gear=gear, met2=de2 / design.z2,
        m_mn=m_mn, hmw=hmw, c=c, hm=hm, j_mn=j_mn, zeta_R=zeta_R, zeta_o=zeta_o,
        Delta_bx1=delta_bx1,
    )


def _member(
    *, z: int, delta: float, delta_a: float, delta_f: float, Re: float, Rm: float, Ri: float,
    beta_e: float, beta_m: float, beta_i: float, ham: float, hfm: float, t_z: float,
    t_zF: float, t_zR: float, smn: float,
) -> MemberBlank:
    theta_a, theta_f = delta_a - delta, delta - delta_f
    hae = ham + (Re - Rm) * math.tan(theta_a)
    hfe = hfm + (Re - Rm) * math.tan(theta_f)
    hai = ham - (Rm - Ri) * math.tan(theta_a)
    hfi = hfm - (Rm - Ri) * math.tan(theta_f)
    if hai <= 0.0 or hfi <= 0.0:
        # the mean addendum itself may be what leaves nothing (c_ham 0: a gear without
        # an addendum); say so beside the angles
        mean = (f"; its mean addendum h_am = {ham:.4g} mm (c_ham: the gear's share of "
                "the working depth, 0.5 for equal addenda)" if hai <= 0.0 and ham < 0.5 * hfm
                else "")
        raise InputError(
            "theta_a2, theta_f2 (or b2): must leave the tooth a depth at the toe, h_ai and h_fi "
            f"> 0 [mm], got h_ai = {hai:.4g}, h_fi = {hfi:.4g} at the member with {z} "
            f"teeth{mean}"
        )
    s_d, c_d = math.sin(delta), math.cos(delta)
    de, di = 2.0 * Re * s_d, 2.0 * Ri * s_d
    return MemberBlank(
        z=z, delta=delta, delta_a=delta_a, delta_f=delta_f, theta_a=theta_a, theta_f=theta_f,
        Re=Re, Rm=Rm, Ri=Ri, b=Re - Ri,
        beta_e=beta_e, beta_m=beta_m, beta_i=beta_i,
        ham=ham, hfm=hfm, hae=hae, hfe=hfe, hai=hai, hfi=hfi,
        de=de, dm=2.0 * Rm * s_d, di=di, dae=de + 2.0 * hae * c_d, dfe=de - 2.0 * hfe * c_d,
        dai=di + 2.0 * hai * c_d, dfi=di - 2.0 * hfi * c_d,
        t_z=t_z, t_zF=t_zF, t_zR=t_zR,
        txo=Re * c_d - hae * s_d - t_z, txi=Ri * c_d - hai * s_d - t_z, smn=smn,
    )


def check_face_angles(geom: BlankGeometry) -> BlankGeometry:
    """A blank whose members' face angles stay within 90°, as a case's blank must.

    Parameters
    ----------
    geom : BlankGeometry
        Both members' ISO 23509 blanks (:func:`blank_geometry`); angles [rad].

    Returns
    -------
    BlankGeometry
        ``geom`` itself.

    Raises
    ------
    InputError
        Naming ``theta_a2`` and its range [0, 90° − δ2] [deg] where the gear's face angle
        δ_a2 = δ2 + θ_a2 passes 90° (the pinion's, an arcsine of the gear's cones
        (:func:`gear_dimensions`), cannot).

    Notes
    -----
    ISO 23509:2016 cl. 6 gives δ_a2 = δ2 + θ_a2 for any pitch angle; a face cone beyond
    the plane of the member's back is an internal bevel gear's, which the case blank
    (:class:`geometry.case.Blank`, face angle in (0, 90] deg) does not describe. Said here
    in the basic data's terms (issue 71, unseen (11): a spiral bevel 12x35 at Σ 110°, δ2
    89.95°, θ_a2 1° stopped ``ltca synthesize`` with "face_angle: must be in (0, 90]").
    """
    design, limit = geom.design, 0.5 * math.pi + 1e-12
    d2, th_a2 = geom.gear.delta, geom.gear.theta_a
    if geom.gear.delta_a > limit:
        raise InputError(
            f"theta_a2: must be in [0, 90° − δ2] = [0, {max(90.0 - math.degrees(d2), 0.0):.4g}]"
            f" [deg] for the gear's face angle δ_a2 = δ2 + θ_a2 to stay within 90° (a face "
            "cone beyond the plane is an internal bevel gear's, not modelled), got "
            f"{math.degrees(th_a2):.4g}: δ2 {math.degrees(d2):.4g}° (Σ "
            f"{math.degrees(design.Sigma):g}°, z2/z1 {design.z2}/{design.z1}) makes the gear "
            "nearly a crown gear; give theta_a2 within that range (uniform depth: theta_a2 = "
            "theta_f2 = 0), or a smaller Sigma"
        )
    return geom


def blank_geometry(design: BevelGearDesign) -> BlankGeometry:
    """Pitch cone and blank dimensions in one call (ISO 23509:2016 clauses 5 and 6).

    Parameters
    ----------
    design : BevelGearDesign
        Basic design data.

    Returns
    -------
    BlankGeometry
        As :func:`gear_dimensions`.

    Raises
    ------
    InputError, ModelUnavailableError
        As :func:`~geometry.iso23509.pitch_cone.pitch_cone` and :func:`gear_dimensions`.
    """
    return gear_dimensions(design, pitch_cone(design))


# --------------------------------------------------------------------------- reporting
def _angle_names(obj: Any) -> frozenset[str]:
    if isinstance(obj, PitchCone):
        return _PITCH_ANGLES
    if isinstance(obj, BevelGearDesign):
        return _DESIGN_ANGLES
    return getattr(obj, "ANGLES", frozenset())


def in_degrees(obj: Any) -> dict[str, Any]:
    """Fields of a blank result as a dict, angles converted to degrees.

    Parameters
    ----------
    obj : BlankGeometry, MemberBlank, PitchCone or BevelGearDesign
        A result (or input) of this module.

    Returns
    -------
    dict
        Field name → value; angle fields in [deg], lengths in [mm]; nested results (design,
        pitch, pinion, gear of a :class:`BlankGeometry`) become nested dicts.

    Raises
    ------
    InputError
        If ``obj`` is not one of the dataclasses above.
    """
    if not (is_dataclass(obj) and not isinstance(obj, type)):
        raise InputError(f"obj: must be a blank-geometry dataclass, got {type(obj).__name__}")
    angles = _angle_names(obj)
    out: dict[str, Any] = {}
    for f in fields(obj):
        v = getattr(obj, f.name)
        if is_dataclass(v):
            out[f.name] = in_degrees(v)
        elif f.name in angles:
            out[f.name] = math.degrees(v)
        else:
            out[f.name] = v
    return out


#: units and long names of every stored variable of :func:`blank_dataset`
_MEMBER_META: dict[str, tuple[str, str]] = {
    "z": ("1", "number of teeth"),
    "delta": ("rad", "pitch angle"),
    "delta_a": ("rad", "face angle"),
    "delta_f": ("rad", "root angle"),
    "theta_a": ("rad", "addendum angle"),
    "theta_f": ("rad", "dedendum angle"),
    "Re": ("mm", "outer cone distance"),
    "Rm": ("mm", "mean cone distance"),
    "Ri": ("mm", "inner cone distance"),
    "b": ("mm", "face width"),
    "beta_e": ("rad", "outer (heel) spiral angle"),
    "beta_m": ("rad", "mean spiral angle"),
    "beta_i": ("rad", "inner (toe) spiral angle"),
    "ham": ("mm", "mean addendum"),
    "hfm": ("mm", "mean dedendum"),
    "hae": ("mm", "outer addendum"),
    "hfe": ("mm", "outer dedendum"),
    "hai": ("mm", "inner addendum"),
    "hfi": ("mm", "inner dedendum"),
    "de": ("mm", "outer pitch diameter"),
    "dm": ("mm", "mean pitch diameter"),
    "di": ("mm", "inner pitch diameter"),
    "dae": ("mm", "outer tip diameter"),
    "dfe": ("mm", "outer root diameter"),
    "dai": ("mm", "inner tip diameter"),
    "dfi": ("mm", "inner root diameter"),
    "t_z": ("mm", "pitch apex beyond crossing point"),
    "t_zF": ("mm", "face apex beyond crossing point"),
    "t_zR": ("mm", "root apex beyond crossing point"),
    "txo": ("mm", "outer crown to crossing point"),
    "txi": ("mm", "inner crown to crossing point"),
    "smn": ("mm", "mean normal circular tooth thickness"),
}
_PAIR_META: dict[str, tuple[str, str]] = {
    "met2": ("mm", "outer transverse module of the gear"),
    "m_mn": ("mm", "mean normal module"),
    "hmw": ("mm", "mean working depth"),
    "c": ("mm", "clearance"),
    "hm": ("mm", "mean whole depth"),
    "j_mn": ("mm", "mean normal backlash"),
    "zeta_R": ("rad", "pinion offset angle in root plane"),
    "zeta_o": ("rad", "pinion offset angle in face plane"),
    "Delta_bx1": ("mm", "pinion face width increment at each end"),
    "zeta_m": ("rad", "pinion offset angle in axial plane"),
    "eta": ("rad", "gear offset angle in pinion axial plane"),
    "zeta_mp": ("rad", "offset angle in pitch plane"),
    "a_p": ("mm", "offset in pitch plane"),
    "alpha_lim": ("rad", "limit pressure angle"),
    "rho_lim": ("mm", "limit radius of lengthwise curvature"),
    "alpha_nD": ("rad", "generated normal pressure angle, drive flank"),
    "alpha_nC": ("rad", "generated normal pressure angle, coast flank"),
    "alpha_eD": ("rad", "effective pressure angle, drive flank"),
    "alpha_eC": ("rad", "effective pressure angle, coast flank"),
    "c_be2": ("1", "face width factor of the gear"),
}
#: the gear's face-hobbing tooth trace at P, stored for face hobbing only: dataset name →
#: (attribute of the PitchCone, units, long name)
_TRACE_META: dict[str, tuple[str, str, str]] = {
    "nu": ("nu", "rad", "lead angle of the cutter"),
    "lambda": ("lambda_", "rad", "first auxiliary angle (crown gear centre to cutter centre at P)"),
    "rho_P0": ("rho_P0", "mm", "crown gear centre to cutter centre distance"),
    "rho_b": ("rho_b", "mm", "base radius of the epicycloid"),
    "eta1": ("eta1", "rad", "second auxiliary angle"),
    "rho_mbeta": ("rho_mbeta", "mm", "lengthwise radius of curvature of the tooth at P"),
}


def blank_dataset(geom: BlankGeometry) -> xr.Dataset:
    """The blank as an ``xarray.Dataset`` (dimension ``member`` = pinion, gear).

    Parameters
    ----------
    geom : BlankGeometry
        Result of :func:`gear_dimensions`.

    Returns
    -------
    xarray.Dataset
        One variable per :class:`MemberBlank` field along ``member`` and one scalar per pair
        quantity, each with ``units`` (UDUNITS: ``mm``, ``rad``, ``1``) and ``long_name``
        attributes; angles in rad. ``rho_lim`` is omitted for Method 0, where the limit
        radius is undefined, ``Delta_bx1`` for Methods 2 and 3; for face hobbing the gear's
        tooth trace at P is added (``nu``, ``lambda``, ``rho_P0``, ``rho_b``, ``eta1``,
        ``rho_mbeta``). Attributes: the ISO method, the process, the design data as JSON
        text (angles in rad), the toolkit version.

    Raises
    ------
    InputError
        If ``geom`` is not a :class:`BlankGeometry`.
    """
    if not isinstance(geom, BlankGeometry):
        raise InputError(f"geom: must be a BlankGeometry, got {type(geom).__name__}")
    members = (geom.pinion, geom.gear)
    data_vars: dict[str, Any] = {}
    for name, (units, long_name) in _MEMBER_META.items():
        values = np.array([getattr(m, name) for m in members])
        data_vars[name] = ("member", values, {"units": units, "long_name": long_name})
    for name, (units, long_name) in _PAIR_META.items():
        value = getattr(geom, name) if hasattr(geom, name) else getattr(geom.pitch, name)
        if not math.isfinite(value):
            continue
        data_vars[name] = ((), float(value), {"units": units, "long_name": long_name})
    if geom.design.process == "face hobbing":
        for name, (attr, units, long_name) in _TRACE_META.items():
            data_vars[name] = ((), float(getattr(geom.pitch, attr)),
                               {"units": units, "long_name": long_name})
    return xr.Dataset(
        data_vars,
        coords={"member": ("member", ["pinion", "gear"], {"long_name": "gear pair member"})},
        attrs={
            "title": "bevel/hypoid blank geometry (ISO 23509:2016 clauses 5 and 6)",
            "iso23509_method": int(geom.pitch.method),
            "process": geom.design.process,
            "design": json.dumps(asdict(geom.design)),
            "toolkit_version": __version__,
        },
    )
