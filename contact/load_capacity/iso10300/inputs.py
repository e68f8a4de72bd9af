"""Inputs of the ISO 10300 rating: the pair's geometry and the case's ``[rating]`` table.

Two frozen dataclasses, each validated on construction (a bad value raises
:class:`~geometry.core.errors.InputError` naming the field and the accepted range):

* :class:`GearData` — the gear data ISO 10300 takes from the ISO 23509 blank (mean
  diameters, pitch and spiral angles, module, addenda, profile shift and thickness
  modification, pressure angles, offset angles, face width, cutter radius, tool
  addendum); :func:`gear_data_from_blank` reads them off the blank the toolkit computes
  (:func:`geometry.iso23509.blank.blank_geometry`);
* :class:`RatingInputs` — what the rating needs beyond the geometry: application factor,
  pitch deviation or accuracy grade, mounting, lubricant, roughness, material quality,
  life and minimum safety factors, each default stated with its source below;
  :meth:`RatingInputs.from_mapping` reads a case's ``[rating]`` table (errors named
  ``rating.<field>``).

Units: lengths [mm], angles [rad] in :class:`GearData`; the ``[rating]`` table's units
are in :data:`RATING_FIELDS` (µm for deviations and roughness, mm²/s for ν40, MPa for
stresses).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import Any

from geometry.core.errors import InputError
from geometry.core.validation import integer, known_fields, one_of, real

__all__ = [
    "CONTACT_PATTERNS",
    "GIVEN_FACTORS",
    "MOUNTINGS",
    "PROCESSES",
    "RATING_FIELDS",
    "SIDES",
    "GearData",
    "RatingInputs",
    "gear_data_from_blank",
]

#: K_Hβ-be mounting: which members are straddle-mounted (bearings on both sides)
MOUNTINGS = ("both", "one", "neither")
#: how the contact pattern was verified (the rows of the mounting-factor table)
CONTACT_PATTERNS = ("full_load", "light_load", "estimated")
#: the rated flank, ISO 23509's naming (drive: the pinion's concave flank drives)
SIDES = ("drive", "coast")
#: how a member is cut: generated (rolled) or non-generated (the cutter's imprint), the
#: names of a case's ``[pinion]``/``[gear]`` ``process``
PROCESSES = ("Generate", "Formate")

_DEG = math.pi / 180.0

#: the load factors a ``[rating]`` table may give in place of the computed ones: field →
#: (the ``/rating`` variable, what computes it otherwise)
GIVEN_FACTORS: dict[str, tuple[str, str]] = {
    "dynamic_factor": ("K_v", "ISO 10300-1:2014 cl. 7 (Method B)"),
    "face_load_factor_contact": ("K_Hbeta", "ISO 10300-1:2014 cl. 8 (Method C)"),
    "face_load_factor_bending": ("K_Fbeta", "ISO 10300-1:2014 cl. 8 (K_Hbeta / K_F0)"),
    "transverse_load_factor_contact": ("K_Halpha", "ISO 10300-1:2014 cl. 9 (Method B)"),
    "transverse_load_factor_bending": ("K_Falpha", "ISO 10300-1:2014 cl. 9 (Method B)"),
}


def _pair(name: str, value: Any, *, unit: str, **bounds: Any) -> tuple[float, float]:
    """One number (both members) or [pinion, gear], each within [low, high]."""
    if isinstance(value, (list, tuple)):
        if len(value) != 2:
            raise InputError(f"{name}: must be one number or [pinion, gear] [{unit}], got "
                             f"{list(value)!r}")
        vals = value
    else:
        vals = (value, value)
    return tuple(real(name, v, unit=unit, **bounds) for v in vals)


@dataclass(frozen=True, kw_only=True)
class GearData:
    """The gear data of ISO 10300 (Method B1) for one pair, from its ISO 23509 blank.

    Parameters
    ----------
    z1, z2 : int
        Numbers of teeth, 5 ≤ z1 ≤ z2.
    a : float — [mm]
        Hypoid offset, ≥ 0.
    d_m1, d_m2 : float — [mm]
        Mean pitch diameters, > 0.
    delta1, delta2 : float — [rad]
        Pitch angles, in (0, π/2].
    beta_m1, beta_m2 : float — [rad]
        Mean spiral angles, in [0, 70°] (0: straight or zerol).
    m_mn : float — [mm]
        Mean normal module, > 0.
    h_am1, h_am2, h_fm1, h_fm2 : float — [mm]
        Mean addenda and dedenda, > 0.
    x_hm1, x_hm2 : float — [1]
        Profile shift coefficients at the mean point, in [−1, 1].
    x_sm1, x_sm2 : float — [1]
        Thickness modification coefficients at the mean point (backlash included), in
        [−0.5, 0.5].
    alpha_nD, alpha_nC : float — [rad]
        Generated normal pressure angles of drive and coast side, in (0, 45°).
    alpha_eD, alpha_eC : float — [rad]
        Effective pressure angles of drive and coast side, in (0, 45°).
    alpha_lim : float — [rad]
        Limit pressure angle (0 without offset), in [−20°, 20°].
    zeta_mp, zeta_m : float — [rad]
        Offset angles in the pitch plane and the axial plane (0 without offset), in
        [0, 60°].
    b2 : float — [mm]
        Face width of the gear, > 0.
    r_c0 : float — [mm]
        Nominal cutter radius (face milling: the tooth trace radius), > 0.
    h_a0 : float — [mm]
        Addendum of the tool, the basic crown gear's dedendum k_hfp m_mn, > 0.

    Raises
    ------
    InputError
        A value out of its range (named).

    Notes
    -----
    Source: ISO 10300-1:2014 (gear data of Method B1, taken from ISO 23509).
    """

    z1: int
    z2: int
    a: float
    d_m1: float
    d_m2: float
    delta1: float
    delta2: float
    beta_m1: float
    beta_m2: float
    m_mn: float
    h_am1: float
    h_am2: float
    h_fm1: float
    h_fm2: float
    x_hm1: float
    x_hm2: float
    x_sm1: float
    x_sm2: float
    alpha_nD: float
    alpha_nC: float
    alpha_eD: float
    alpha_eC: float
    alpha_lim: float
    zeta_mp: float
    zeta_m: float
    b2: float
    r_c0: float
    h_a0: float

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "z1", integer("z1", self.z1, 5, 500, allow_float=True))
        set_(self, "z2", integer("z2", self.z2, self.z1, 500, allow_float=True))
        checks = {
            "a": dict(unit="mm", low=0.0),
            **{k: dict(unit="mm", low=0.0, low_open=True)
               for k in ("d_m1", "d_m2", "m_mn", "h_am1", "h_am2", "h_fm1", "h_fm2", "b2",
                         "r_c0", "h_a0")},
            **{k: dict(unit="deg", low=0.0, high=90 * _DEG, low_open=True, scale=_DEG)
               for k in ("delta1", "delta2")},
            **{k: dict(unit="deg", low=0.0, high=70 * _DEG, scale=_DEG)
               for k in ("beta_m1", "beta_m2")},
            **{k: dict(unit="1", low=-1.0, high=1.0) for k in ("x_hm1", "x_hm2")},
            **{k: dict(unit="1", low=-0.5, high=0.5) for k in ("x_sm1", "x_sm2")},
            **{k: dict(unit="deg", low=0.0, high=45 * _DEG, low_open=True, high_open=True,
                       scale=_DEG) for k in ("alpha_nD", "alpha_nC", "alpha_eD", "alpha_eC")},
            "alpha_lim": dict(unit="deg", low=-20 * _DEG, high=20 * _DEG, scale=_DEG),
            **{k: dict(unit="deg", low=0.0, high=60 * _DEG, scale=_DEG)
               for k in ("zeta_mp", "zeta_m")},
        }
        for name, kw in checks.items():
            set_(self, name, real(name, getattr(self, name), **kw))

    @property
    def u(self) -> float:
        """Gear ratio u = z2/z1 [1]."""
        return self.z2 / self.z1

    def flank_angles(self, side: str) -> tuple[float, float, float]:
        """(α_n, α_e, α_lim signed) of the rated side [rad]: drive (α_nD, α_eD, α_lim) or
        coast (α_nC, α_eC, −α_lim)."""
        one_of("side", side, SIDES)
        if side == "drive":
            return self.alpha_nD, self.alpha_eD, self.alpha_lim
        return self.alpha_nC, self.alpha_eC, -self.alpha_lim

    @classmethod
    def from_degrees(cls, **kw: Any) -> GearData:
        """A GearData from angles in degrees (the other fields as in the class)."""
        angles = {"delta1", "delta2", "beta_m1", "beta_m2", "alpha_nD", "alpha_nC",
                  "alpha_eD", "alpha_eC", "alpha_lim", "zeta_mp", "zeta_m"}
        return cls(**{k: (math.radians(v) if k in angles else v) for k, v in kw.items()})


def gear_data_from_blank(blank) -> GearData:
    """The ISO 10300 gear data of an ISO 23509 blank.

    Parameters
    ----------
    blank : geometry.iso23509.blank.BlankGeometry
        The blank of :func:`geometry.iso23509.blank.blank_geometry`.

    Returns
    -------
    GearData
        With x_hm1 = (h_am1 − h_am2)/(2 m_mn) = −x_hm2 (ISO 23509: h_am1,2 =
        (k_hap ± x_hm1) m_mn); x_sm from the mean normal thicknesses,
        s_mn = m_mn (π/2 + 2 x_hm tan α_n + 2 x_sm) with α_n = (α_nD + α_nC)/2 (backlash
        included, as in ISO/TR 10300-30); the tool addendum h_a0 = h_mw/2 + c (the basic
        crown gear dedendum k_hfp m_mn).

    Notes
    -----
    Source: ISO 23509:2016 (the blank), ISO 10300-1:2014 (which data Method B1 takes).
    """
    p, d = blank.pitch, blank.design
    m = blank.m_mn
    x_hm1 = (blank.pinion.ham - blank.gear.ham) / (2.0 * m)
    alpha_n = 0.5 * (p.alpha_nD + p.alpha_nC)

    def x_sm(s_mn: float, x_hm: float) -> float:
        return s_mn / (2.0 * m) - 0.25 * math.pi - x_hm * math.tan(alpha_n)

    return GearData(
        z1=d.z1, z2=d.z2, a=d.a, d_m1=blank.pinion.dm, d_m2=blank.gear.dm,
        delta1=p.delta1, delta2=p.delta2, beta_m1=p.beta_m1, beta_m2=p.beta_m2, m_mn=m,
        h_am1=blank.pinion.ham, h_am2=blank.gear.ham, h_fm1=blank.pinion.hfm,
        h_fm2=blank.gear.hfm, x_hm1=x_hm1, x_hm2=-x_hm1,
        x_sm1=x_sm(blank.pinion.smn, x_hm1), x_sm2=x_sm(blank.gear.smn, -x_hm1),
        alpha_nD=p.alpha_nD, alpha_nC=p.alpha_nC, alpha_eD=p.alpha_eD, alpha_eC=p.alpha_eC,
        alpha_lim=p.alpha_lim, zeta_mp=p.zeta_mp, zeta_m=p.zeta_m, b2=blank.gear.b,
        r_c0=d.rc0, h_a0=0.5 * blank.hmw + blank.c)


#: the ``[rating]`` table: field → (unit, what it is and its default). Pairs are one
#: number (both members) or [pinion, gear].
RATING_FIELDS: dict[str, tuple[str, str]] = {
    "application_factor": ("1", "K_A, required, in [1, 5]"),
    "mounting": ("", "K_Hβ-be: members straddle-mounted, 'both', 'one' or 'neither'; "
                     "required"),
    "single_pitch_deviation": ("um", "f_pt [pinion, gear], in (0, 500]; or give "
                                     "accuracy_grade"),
    "accuracy_grade": ("", "ISO 17485 accuracy grade [pinion, gear], integers in [2, 11]"),
    "contact_pattern": ("", "how the pattern was checked: 'full_load', 'light_load' "
                            "(default) or 'estimated'"),
    "nu40": ("mm2/s", "oil viscosity at 40 degC, in [2, 5000]; default: the case's oil"),
    "flank_roughness": ("um", "Rz of the flanks [pinion, gear], in (0, 100]; default the "
                        "case's [operating] roughness Rq as Rz = 6 sqrt(2/pi) Rq (8 without "
                        "a case)"),
    "root_roughness": ("um", "Rz of the roots [pinion, gear], in (0, 100], default 16"),
    "quality_grade": ("", "ISO 6336-5 material quality 'ML', 'MQ' (default) or 'ME'"),
    "sigma_Hlim": ("MPa", "allowable contact stress number [pinion, gear], (0, 3000]; "
                          "default: the material table at quality_grade"),
    "sigma_Flim": ("MPa", "nominal bending stress number [pinion, gear], (0, 1500]; "
                          "default: the material table at quality_grade"),
    "load_cycles": ("1", "load cycles of the pinion N_L1 (the gear's N_L1 z1/z2), >= 1; "
                         "default: long life (Z_NT = Y_NT = 1)"),
    "design_torque": ("N m", "pinion torque the pair is rated for at long life, in (0, 1e6]; "
                             "torques above it are rated at a finite life (the verdict "
                             "states the permissible load cycles); default: none (every "
                             "torque at long life)"),
    "coast_design_torque": ("N m", "pinion torque the coast side is rated for at long life, "
                                   "in (0, 1e6]; default: design_torque (both sides)"),
    "min_safety_pitting": ("1", "S_H,min, in (0, 10], default 1.0"),
    "min_safety_bending": ("1", "S_F,min, in (0, 10], default 1.3"),
    "effective_width_ratio": ("1", "b2,eff / b2, in (0, 1], default 0.85"),
    "edge_radius": ("mm", "cutter edge radius rho_a0 [pinion, gear], in [0, 10]; default: "
                          "the case's blades"),
    "protuberance": ("mm", "s_pr [pinion, gear], in [0, 1], default 0"),
    "process": ("", "how the members are cut [pinion, gear], 'Generate' (generated tooth "
                    "form) or 'Formate' (non-generated: the fillet is the blade's edge "
                    "radius); default: the case's members' process"),
    "load_sharing_exponent": ("1", "e_LS, in [1, 5], default 3"),
    "dynamic_factor": ("1", "K_v given (e.g. from Method A), in [1, 3]; default Method B"),
    "face_load_factor_contact": ("1", "K_Hbeta given (e.g. from a measured contact pattern, "
                                      "Method A), in [1, 3]; default Method C, 1.5 "
                                      "K_Hbeta-be"),
    "face_load_factor_bending": ("1", "K_Fbeta given, in [1, 3]; default K_Hbeta / K_F0 "
                                      "(of the given K_Hbeta where that is given)"),
    "transverse_load_factor_contact": ("1", "K_Halpha given, in [1, 3]; default Method B"),
    "transverse_load_factor_bending": ("1", "K_Falpha given, in [1, 3]; default K_Halpha "
                                            "(the given one where that is given), else "
                                            "Method B"),
    "youngs_modulus": ("MPa", "E [pinion, gear], (0, 1e6]; default: the members' "
                              "material"),
    "poisson_ratio": ("1", "nu [pinion, gear], [0, 0.5); default: the members' material"),
    "side": ("", "rated flank 'drive' or 'coast' (ISO 23509); default: the case's "
                 "drive flank"),
    "source": ("", "where the values come from (text), optional"),
    "method": ("", "the load-capacity rating method ltca run and ltca rate use for this "
                   "case, a name of contact.load_capacity.available_methods(); default "
                   "iso10300"),
}


@dataclass(frozen=True, kw_only=True)
class RatingInputs:
    """What the ISO 10300 rating needs beyond the geometry (a case's ``[rating]`` table).

    Parameters
    ----------
    application_factor : float — [1]
        K_A, in [1, 5] (ISO 10300-1:2014 cl. 6 and its table of K_A: 1.0 for a uniform
        driving and driven machine, up to 2.25 and more for heavy shocks). Required.
    mounting : str
        Which members are straddle-mounted, for the mounting factor K_Hβ-be (ISO
        10300-1:2014 cl. 8): ``"both"``, ``"one"`` or ``"neither"``. Required.
    single_pitch_deviation : (float, float) — [µm], optional
        f_pt of pinion and gear, in (0, 500]. One of it and ``accuracy_grade`` is required.
    accuracy_grade : (int, int), optional
        ISO 17485 accuracy grades of pinion and gear, in [2, 11]: f_pt is then the
        single pitch tolerance of the grade (:func:`contact.load_capacity.iso10300.factors.
        single_pitch_tolerance`).
    contact_pattern : str
        How the contact pattern was verified: ``"full_load"`` (each set in its housing
        under full load), ``"light_load"`` (under a light test load) or ``"estimated"``
        (not checked). Default ``"light_load"``, ISO/TR 10300-30:2024's samples.
    nu40 : float — [mm²/s], optional
        Kinematic viscosity of the oil at 40 °C, in [2, 5000]; default: the case's oil
        (``[operating] lubricant``) at 40 °C.
    flank_roughness, root_roughness : (float, float) — [µm]
        Rz of the flanks and of the roots, in (0, 100]. Defaults 8 and 16 µm: ISO/TR
        10300-30:2024's samples 1 and 2 (lapped case-hardened gears).
    quality_grade : str
        ISO 6336-5 material quality ``"ML"``, ``"MQ"`` or ``"ME"``; default ``"MQ"``, the
        quality of production gears of known materials and heat treatment.
    sigma_Hlim, sigma_Flim : (float, float) — [MPa], optional
        Allowable stress numbers for contact and bending (ISO 6336-5); default: the
        material table (``geometry/core/data/materials.toml``) at ``quality_grade``,
        σ_Flim = σ_FE / Y_ST.
    load_cycles : float — [1], optional
        Load cycles of the pinion N_L1, ≥ 1 (the gear's are N_L1 z1/z2). Default: long
        life, at or beyond the knees of the S–N curves (Z_NT = Y_NT = 1, the reference
        values), as the TR's samples.
    design_torque : float — [N·m], optional
        The pinion torque the pair is rated for at long life, in (0, 1e6]. Torques above it
        are loads of limited duration (overloads of a load spectrum, e.g. an axle's low
        gears): where their long-life safety is below the minimum, the rating states the
        load cycles they may run (``permissible_cycles_pitting``/``_bending``) and the
        verdict wants attention rather than failing, as ISO 10300-2/-3 cl. 8 rate a load
        of finite life by its life factor. Default: none, every torque at long life.
    coast_design_torque : float — [N·m], optional
        The pinion torque the coast side is rated for at long life, in (0, 1e6]: used in
        place of ``design_torque`` where the rated side is the coast side. A hypoid's coast
        side carries less than its drive side at long life (other pressure angle, other
        spiral angle of the virtual gears); the torque it carries in reverse gear is a
        load of limited duration, rated at a finite life above this torque. Default:
        ``design_torque`` for both sides.
    min_safety_pitting, min_safety_bending : float — [1]
        S_H,min and S_F,min, in (0, 10]. Defaults 1.0 and 1.3: ISO/TR 10300-30:2024's
        samples (ISO 10300 leaves them to agreement).
    effective_width_ratio : float — [1]
        b2,eff / b2, the loaded contact pattern's share of the face width, in (0, 1].
        Default 0.85, ISO 10300-1's value when the pattern is not known (an LTCA gives it).
    edge_radius : (float, float) — [mm], optional
        Cutter edge radius ρ_a0 that cuts the roots of pinion and gear, in [0, 10];
        default: the edge radius of the blades that cut the rated flanks in the case.
    protuberance : (float, float) — [mm]
        Protuberance s_pr of the tools, in [0, 1]; default 0.
    process : (str, str), optional
        How pinion and gear are cut, ``"Generate"`` or ``"Formate"`` (one text for both):
        the tooth form of ISO 10300-3 for a generated member or for a non-generated one,
        whose root fillet is the cutter's edge radius
        (:func:`contact.load_capacity.iso10300.bending.non_generated_tooth_form`).
        Default: the case's members' ``process``; both generated where no case is rated.
    load_sharing_exponent : float — [1]
        e_LS of the peak-load distribution over the contact lines (Z_LS), in [1, 5];
        default 3, the TR's samples (moderate profile crowning).
    dynamic_factor : float — [1], optional
        K_v given (Method A, a measurement, or a value a worked example prints), in
        [1, 3]; default: Method B (ISO 10300-1:2014 cl. 7).
    face_load_factor_contact, face_load_factor_bending : float — [1], optional
        K_Hβ and K_Fβ given, in [1, 3]; default: Method C, K_Hβ = 1.5 K_Hβ-be and
        K_Fβ = K_Hβ/K_F0 (ISO 10300-1:2014 cl. 8). A given K_Hβ without a given K_Fβ
        gives K_Fβ = K_Hβ/K_F0 of it (the clause's relation).
    transverse_load_factor_contact, transverse_load_factor_bending : float — [1], optional
        K_Hα and K_Fα given, in [1, 3]; default: Method B (ISO 10300-1:2014 cl. 9). A given
        K_Hα without a given K_Fα is taken for both (Method B gives one value for both).
        A given factor is used as given, its range above the standard's limits not
        enforced; the ``/rating`` dataset records it beside the value the method computes
        (attribute ``given_load_factors``).
    youngs_modulus, poisson_ratio : (float, float), optional
        E [MPa] in (0, 1e6] and ν in [0, 0.5) of pinion and gear; default: the members'
        material.
    side : str, optional
        The rated flank ``"drive"`` or ``"coast"`` (ISO 23509); default: the case's
        drive flank (its pinion concave flank is ISO's drive side).
    source : str, optional
        Where the values come from (free text, kept in the ``/rating`` dataset's
        ``rating_inputs`` attribute).
    method : str, optional
        The load-capacity rating method the case is rated by in ``ltca run`` and ``ltca
        rate`` (:func:`contact.load_capacity.methods.case_method`); None: ISO 10300.

    Raises
    ------
    InputError
        A value out of its range, an unknown choice, or neither/both of
        ``single_pitch_deviation`` and ``accuracy_grade`` (the field named).
    """

    application_factor: float
    mounting: str
    single_pitch_deviation: tuple[float, float] | None = None
    accuracy_grade: tuple[int, int] | None = None
    contact_pattern: str = "light_load"
    nu40: float | None = None
    flank_roughness: tuple[float, float] = (8.0, 8.0)
    root_roughness: tuple[float, float] = (16.0, 16.0)
    quality_grade: str = "MQ"
    sigma_Hlim: tuple[float, float] | None = None
    sigma_Flim: tuple[float, float] | None = None
    load_cycles: float | None = None
    design_torque: float | None = None
    coast_design_torque: float | None = None
    min_safety_pitting: float = 1.0
    min_safety_bending: float = 1.3
    effective_width_ratio: float = 0.85
    edge_radius: tuple[float, float] | None = None
    protuberance: tuple[float, float] = (0.0, 0.0)
    process: tuple[str, str] | None = None
    load_sharing_exponent: float = 3.0
    dynamic_factor: float | None = None
    face_load_factor_contact: float | None = None
    face_load_factor_bending: float | None = None
    transverse_load_factor_contact: float | None = None
    transverse_load_factor_bending: float | None = None
    youngs_modulus: tuple[float, float] | None = None
    poisson_ratio: tuple[float, float] | None = None
    side: str | None = None
    source: str | None = None
    method: str | None = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        if self.source is not None and not isinstance(self.source, str):
            raise InputError(f"source: must be text, got {type(self.source).__name__}")
        if self.method is not None and not (isinstance(self.method, str) and self.method):
            raise InputError(f"method: must be the name of a load-capacity rating method, "
                             f"got {self.method!r}")
        set_(self, "application_factor", real("application_factor", self.application_factor,
                                              unit="1", low=1.0, high=5.0))
        one_of("mounting", self.mounting, MOUNTINGS)
        one_of("contact_pattern", self.contact_pattern, CONTACT_PATTERNS)
        one_of("quality_grade", self.quality_grade, ("ML", "MQ", "ME"))
        if self.side is not None:
            one_of("side", self.side, SIDES)
        if (self.single_pitch_deviation is None) == (self.accuracy_grade is None):
            raise InputError(
                "single_pitch_deviation: give the single pitch deviation f_pt [um] or the "
                "ISO 17485 accuracy_grade (one of the two), got "
                + ("both" if self.single_pitch_deviation is not None else "neither"))
        pairs = {
            "single_pitch_deviation": dict(unit="um", low=0.0, high=500.0, low_open=True),
            "flank_roughness": dict(unit="um", low=0.0, high=100.0, low_open=True),
            "root_roughness": dict(unit="um", low=0.0, high=100.0, low_open=True),
            "sigma_Hlim": dict(unit="MPa", low=0.0, high=3000.0, low_open=True),
            "sigma_Flim": dict(unit="MPa", low=0.0, high=1500.0, low_open=True),
            "edge_radius": dict(unit="mm", low=0.0, high=10.0),
            "protuberance": dict(unit="mm", low=0.0, high=1.0),
            "youngs_modulus": dict(unit="MPa", low=0.0, high=1e6, low_open=True),
            "poisson_ratio": dict(unit="1", low=0.0, high=0.5, high_open=True),
        }
        for name, kw in pairs.items():
            value = getattr(self, name)
            if value is not None:
                set_(self, name, _pair(name, value, **kw))
        if self.process is not None:
            given = self.process
            procs = tuple(given) if isinstance(given, (list, tuple)) else (given, given)
            if len(procs) != 2:
                raise InputError(f"process: must be one of {list(PROCESSES)} or [pinion, "
                                 f"gear], got {list(procs)!r}")
            for v in procs:
                one_of("process", v, PROCESSES)
            set_(self, "process", procs)
        if self.accuracy_grade is not None:
            g = self.accuracy_grade
            g = tuple(g) if isinstance(g, (list, tuple)) else (g, g)
            if len(g) != 2:
                raise InputError(f"accuracy_grade: must be one integer or [pinion, gear], "
                                 f"got {list(g)!r}")
            set_(self, "accuracy_grade",
                 tuple(integer("accuracy_grade", v, 2, 11, allow_float=True) for v in g))
        scalars = {
            "nu40": dict(unit="mm2/s", low=2.0, high=5000.0),
            "load_cycles": dict(unit="1", low=1.0, high=1e13),
            "design_torque": dict(unit="N m", low=0.0, high=1e6, low_open=True),
            "coast_design_torque": dict(unit="N m", low=0.0, high=1e6, low_open=True),
            "min_safety_pitting": dict(unit="1", low=0.0, high=10.0, low_open=True),
            "min_safety_bending": dict(unit="1", low=0.0, high=10.0, low_open=True),
            "effective_width_ratio": dict(unit="1", low=0.0, high=1.0, low_open=True),
            "load_sharing_exponent": dict(unit="1", low=1.0, high=5.0),
            **{k: dict(unit="1", low=1.0, high=3.0) for k in GIVEN_FACTORS},
        }
        for name, kw in scalars.items():
            value = getattr(self, name)
            if value is not None:
                set_(self, name, real(name, value, **kw))

    @classmethod
    def from_mapping(cls, table: Mapping[str, Any], where: str = "rating") -> RatingInputs:
        """A RatingInputs from a ``[rating]`` table (units of :data:`RATING_FIELDS`).

        Parameters
        ----------
        table : mapping
            The parsed table.
        where : str
            Prefix of the field names in errors (``rating`` → ``rating.mounting: …``).

        Returns
        -------
        RatingInputs

        Raises
        ------
        InputError
            Not a table, an unknown or missing field, or a bad value (``<where>.<field>:
            must be …``).
        """
        if not isinstance(table, Mapping):
            raise InputError(f"{where}: must be a table, got {type(table).__name__}")
        known_fields(where, table, RATING_FIELDS)
        for name in ("application_factor", "mounting"):
            if name not in table:
                raise InputError(f"{where}.{name}: missing ({RATING_FIELDS[name][1]})")
        try:
            return cls(**dict(table))
        except InputError as exc:
            raise InputError(f"{where}.{exc}") from None

    def to_mapping(self) -> dict[str, Any]:
        """The ``[rating]`` table of these inputs (None fields left out); inverse of
        :meth:`from_mapping`."""
        out: dict[str, Any] = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if v is not None:
                out[f.name] = list(v) if isinstance(v, tuple) else v
        return out
