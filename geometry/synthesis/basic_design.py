"""Basic design data of a face-milled or face-hobbed pair: the input of the machine-setting
synthesis.

A basic file (``cases/basic/*.toml``, schema in ``docs/synthesis.md``) holds

* ``name``, ``source`` — the case to write and where the data come from;
* ``[design]`` — the ISO 23509 inputs of :class:`geometry.iso23509.pitch_cone.BevelGearDesign`
  (angles in degrees, lengths in mm), from which the blanks follow
  (:func:`geometry.iso23509.blank.blank_geometry`);
* ``[targets]`` (optional) — published values the blank must reproduce (mean spiral angle of
  the gear, outer cone distances …) and the design fields ``adjust`` that are varied to hit
  them (least squares; the achieved values are reported in the case ``source``);
* ``[synthesis]`` — the synthesis options with documented defaults (:class:`SynthesisOptions`),
  optionally overridden per pinion flank in ``[synthesis.concave]`` / ``[synthesis.convex]``;
* ``[optimize]`` (optional) — the problem ``ltca optimize`` solves when it re-synthesises
  the design (``docs/optimize.md``); not read by the synthesis;
* ``[rating]`` (optional) — the ISO 10300 rating inputs of the pair (``docs/rating.md``),
  copied into the synthesised case; without it the case gets the stated defaults of
  ``ltca synthesize`` (``docs/synthesis.md``, "The written case").

Public functions
----------------
FlankOptions, SynthesisOptions, BasicDesign   frozen dataclasses
TARGETS                                       target name → how it is read from a blank
load_basic                                    read and validate a basic file
basic_from_dict                               the same from a parsed mapping
fit_design                                    adjust design fields to hit the targets
flank_option_values, FLANK_OPTION_UNITS       a flank's prescriptions in file units
with_flank_options                            the design with a flank's prescriptions replaced
size_scale, REFERENCE_MODULE                  the factor the µm-sized defaults follow the
                                              tooth size by (small modules)
SIZE_SCALED_OPTIONS                           the flank prescriptions it scales
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from types import MappingProxyType
from typing import Any

from scipy.optimize import least_squares

from geometry.case import Blank, operating_from_dict
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.toml_files import read_toml
from geometry.core.validation import real
from geometry.iso23509.blank import BlankGeometry, blank_geometry, check_face_angles
from geometry.iso23509.pitch_cone import BevelGearDesign

__all__ = [
    "DEFAULT_RATING",
    "EDGE_BREAK_RADIUS",
    "FLANK_OPTION_UNITS",
    "PROCESSES",
    "REFERENCE_MODULE",
    "SIZE_SCALED_OPTIONS",
    "TARGETS",
    "BasicDesign",
    "FlankOptions",
    "SynthesisOptions",
    "basic_from_dict",
    "fit_design",
    "flank_option_values",
    "load_basic",
    "size_scale",
    "with_flank_options",
]

#: (gear, pinion) processes the synthesis implements; a gear process ``"auto"`` (the
#: default) is Formate where the gear pitch angle allows it and Generate below
#: :data:`geometry.synthesis.case_synthesis.FORMATE_PITCH_ANGLE_LIMIT`
PROCESSES: dict[tuple[str, str], bool] = {("Formate", "Generate"): True,
                                          ("Generate", "Generate"): True,
                                          ("auto", "Generate"): True}

#: target name → (unit, value read from a blank geometry); angles in degrees
TARGETS: dict[str, tuple[str, Callable[[BlankGeometry], float]]] = {
    "beta_m1": ("deg", lambda g: math.degrees(g.pinion.beta_m)),
    "beta_m2": ("deg", lambda g: math.degrees(g.gear.beta_m)),
    "Re1": ("mm", lambda g: g.pinion.Re),
    "Re2": ("mm", lambda g: g.gear.Re),
    "de2": ("mm", lambda g: g.gear.de),
    "dm2": ("mm", lambda g: g.gear.dm),
}
#: the ``[rating]`` table of a synthesised case whose basic file gives none (ISO 10300
#: inputs, :class:`contact.load_capacity.iso10300.inputs.RatingInputs`; its ``source`` states each
#: value)
DEFAULT_RATING: Mapping[str, Any] = MappingProxyType({
    "application_factor": 1.0,
    "mounting": "one",
    "accuracy_grade": [6, 8],
    "source": (
        "Stated defaults of ltca synthesize (the basic file gives no [rating] table; "
        "docs/synthesis.md, 'The written case'): K_A = 1.0, ISO 10300-1:2014's application "
        "factor of a uniform driving and driven machine, so that the rating and the LTCA "
        "carry the same nominal torque; mounting 'one' (one member cantilever-mounted), "
        "the automotive axle's overhung pinion with a straddle-mounted ring gear, as "
        "ISO/TR 10300-30:2024's samples; ISO 17485 accuracy grades 6 (pinion) and 8 "
        "(gear), the grades of the TR's f_pt (sample 1: 12 and 26 um at its sizes); load "
        "cycles: long life (Z_NT = Y_NT = 1, the TR's samples); materials: both members "
        "the case's material (case-carburised steel, geometry/core/data/materials.toml) at "
        "ISO 6336-5 quality MQ; flank Rz: the case's [operating] roughness Rq as Rz = "
        "6 sqrt(2/pi) Rq (3.83 um at Rq 0.8 um; the rating's Z_R and the LTCA's film see "
        "one roughness); pattern checked under a light test load, root Rz 16 um, "
        "S_H,min 1.0, S_F,min 1.3 (RatingInputs' defaults, docs/rating.md)."),
})

_ADJUSTABLE = ("de2", "dm2", "b2", "rc0", "beta_m", "theta_a2", "theta_f2", "c_ham")
_DESIGN_ANGLES = {"Sigma", "beta_m", "alpha_dD", "alpha_dC", "theta_a2", "theta_f2"}

#: [mm] the mean normal module m_mn below which the µm-sized defaults of the synthesis and
#: the development follow the tooth size (:func:`size_scale`): just below the smallest
#: m_mn of the designs they were chosen and checked on (3.12 mm, the spiral bevel 15x45 of
#: tests/data/designs; 3.1-7.4 mm over the table of docs/own_gear_set.md), so that every
#: one of those designs keeps them bit for bit
REFERENCE_MODULE = 3.0

#: the flank prescriptions whose defaults :func:`size_scale` scales (lengths of µm: the
#: elastic approach at which the ellipse is prescribed, the tip and root relief); a value
#: the basic file gives is used as given
SIZE_SCALED_OPTIONS = ("approach", "tip_relief", "root_relief")

#: [mm] the case blank's edge break radius (:class:`geometry.case.Blank`, default 0.5 mm)
#: that a case written from basic data gets × :func:`size_scale` where ``[synthesis]
#: edge_break_radius`` is not given (issue 71: on a tooth of m_mn 1.18 mm the 0.5 mm of a
#: 3 mm tooth is an edge 2.5 times blunter relative to it, and its edge pressure is
#: optimistic)
EDGE_BREAK_RADIUS = next(f.default for f in fields(Blank) if f.name == "edge_break_radius")


def size_scale(m_mn: float) -> float:
    """The factor the µm-sized defaults follow the tooth size by: min(1, m_mn / m_ref).

    Parameters
    ----------
    m_mn : float — [mm]
        Mean normal module of the pair (ISO 23509, :attr:`BlankGeometry.m_mn`), > 0.

    Returns
    -------
    float — [1]
        m_mn / :data:`REFERENCE_MODULE` below it, else 1. It multiplies the defaults of
        :data:`SIZE_SCALED_OPTIONS` (:func:`basic_from_dict`) and the development's µm
        bounds and steps (``[development] size_scale``,
        :class:`contact.optimize.development.DevelopmentTargets`).

    Raises
    ------
    InputError
        ``m_mn`` not a positive finite number.

    Notes
    -----
    Why the amounts scale with the module. The defaults — the elastic approach δ = 6.3 µm
    at which the contact ellipse is prescribed (Litvin & Fuentes, *Gear Geometry and
    Applied Theory*, 2nd ed., §9.4: the curvature gap 2δ/a²), the 15 µm tip and root
    relief and the development's 0-60 µm relief and 0-30 µm profile-crowning bounds
    (:data:`contact.optimize.development.VARIABLES`) — are absolute lengths, set and
    checked on automotive and industrial pairs of m_mn 3.1-7.4 mm. Two pairs alike in
    every proportion but size (ISO 23509's depths are multiples of m_mn; b2 is 6-10
    m_mn on the designs of tests/data/designs) loaded to the same contact pressure (the
    design torque is the ISO 10300 capacity, S_H = 1, which grows as the size cubed)
    deform alike: the Hertzian semi-axis a and the approach δ = a²/R grow with the size
    (Johnson, *Contact Mechanics*, 1985, §4.2), and so does a tooth's bending and
    shear deflection under the same stress. A bearing localised as much relative to its
    tooth therefore needs an approach and reliefs in proportion to the module: held at
    6.3 µm on a tooth of m_mn 1.6 mm, the same ellipse fraction is the curvature gap of
    12 µm on one of 3 mm, a bearing twice as localised, and 15-60 µm of relief a relief
    twice as deep. Measured on the spiral bevel 11x27 at β_m 43° of
    tests/data/limits (m_mn 1.62 mm, docs/own_gear_set.md "unseen (3)"): with 6.3 µm the
    developed bearing's local pitting capacity cut the design torque 11.55 → 1.7 N·m and
    its light-load pattern was 0.22 of the face; with 3.2 µm (6.3 × 2.6/5) it stayed
    11.55 N·m with a pattern of 0.47. Above :data:`REFERENCE_MODULE` the factor stays
    1: the similarity argument would raise the amounts on a truck hypoid (m_mn 6.9),
    but the designs of that size meet every criterion with the amounts as they are, and
    a larger amount is not measured. A sourced rule of Gleason or Stadtfeld for the
    amounts against the module was looked for and not found; the rule here is the
    similarity above, stated as such.
    """
    m = real("m_mn", m_mn, unit="mm", low=0.0, low_open=True)
    return min(1.0, m / REFERENCE_MODULE)


def _size_scaled_defaults(scale: float) -> dict[str, float]:
    """The defaults of :data:`SIZE_SCALED_OPTIONS` × ``scale`` [FlankOptions units]; none
    at a scale of 1 (the dataclass' own defaults)."""
    if scale == 1.0:
        return {}
    return {n: scale * f.default for f in fields(FlankOptions) if (n := f.name)
            in SIZE_SCALED_OPTIONS}


def _scaled_edge_break(scale: float) -> dict[str, float]:
    """``edge_break_radius`` = :data:`EDGE_BREAK_RADIUS` × ``scale`` [mm], rounded to 0.1 µm
    as the development's scaled mounting excursions; none at a scale of 1 (the case blank's
    own default)."""
    if scale == 1.0:
        return {}
    return {"edge_break_radius": round(scale * EDGE_BREAK_RADIUS, 4)}


def _design_scale(design: BevelGearDesign) -> float:
    """:func:`size_scale` of a design's blank; 1 where the blank cannot be made (its own
    error is raised where the blank is first needed, as without the scaling)."""
    try:
        return size_scale(blank_geometry(design).m_mn)
    except InputError:
        return 1.0


@dataclass(frozen=True)
class FlankOptions:
    """Local-synthesis prescriptions for one pinion flank at the mean point M.

    Parameters
    ----------
    path_angle : float — [rad]
        Direction of the contact path on the gear flank at M: angle from the gear's
        lengthwise direction (toe → heel) towards its profile direction (root → tip), in
        (−90°, 90°). Default −45°: a diagonal path that falls towards the root going to the
        heel. It must stay clear of the conjugate contact line at M (for a face-milled
        Formate pair nearly lengthwise, about −10° to +25°), along which the contact point
        would have to move infinitely fast (``docs/synthesis.md``).
    te_level : float — [rad]
        Unloaded TE of one tooth pair at ±1 pitch of pinion roll from M (the gear lag of
        :mod:`geometry.pair.conventional_tca`): TE(roll) = a21/2 · roll², a21 = 2 te_level/(2π/z1)².
        Default 45 µrad, in (0, 1000 µrad].
    ellipse_length : float — [1]
        Major axis 2a of the contact ellipse at M as a fraction of the gear face width, at
        the elastic approach ``approach``. Default 0.275, in (0.02, 0.9).
    approach : float — [mm]
        Elastic approach δ (the separation that bounds the unloaded pattern), default
        0.0063 mm, in (0, 0.1]. A basic file that does not give it gets 0.0063 mm ×
        :func:`size_scale` (m_mn below :data:`REFERENCE_MODULE`: in proportion to the
        module).
    tip_relief, root_relief : float — [mm]
        Profile relief of the pinion flank (:mod:`geometry.machine.relief`): normal ease-off added
        at the flank's tip end and at its root end (the lowest point the gear tip reaches),
        at the mean section, by the blade's flankrem and toprem. Default 0.015 mm each (the
        10–30 µm of automotive practice), in [0, 0.2); the file gives them in µm. A basic
        file that does not give them gets 0.015 mm × :func:`size_scale`.
    relief_start : float — [1]
        Where the relief starts, as the fraction of the way from M to each end (blade
        heights); default 0.5, in [0, 1).
    tip_relief_start : float or None — [1]
        Where the tip relief alone starts (the flankrem's corner), the fraction of the way
        from M to the tip end, in [0, 1); default None: ``relief_start``. A corner near the
        tip (0.8–0.9, as the seed's reference designs: ``relief_start`` 0.86) makes a short
        tip relief that takes the pinion's tip edge out of contact under load and leaves
        the light-load transfer between tooth pairs on the unrelieved profile
        (docs/synthesis.md, "The LTE against the relief": on the passenger-car hypoid 10×43
        of tests/data/designs a 20 µm tip relief from 0.28 / 0.85 of the way gave an
        unloaded TE of 94 / 38 µrad and LTE 37 / 25 µrad at light load, edge share 2.3 /
        0.1 % at the design torque).
    blade_angle_change : float — [rad]
        Pressure-angle (blade-angle) change of the pinion blade about M's blade height,
        applied after steps 4–6 (:func:`geometry.synthesis.blade_change.blade_angle_changed`):
        the lever that moves the bearing up or down the tooth. Default 0, in (−5°, 5°);
        the file gives it in degrees.
    profile_crowning : float — [mm]
        Profile crowning added by the pinion blade's profile curvature about M's blade
        height (:func:`geometry.synthesis.blade_change.blade_profile_crowned`): the normal
        ease-off at ±m_mn of blade height from M, > 0 crowned; applied after steps 4–6,
        the lever that shortens the bearing in depth. Default 0, in (−100, 100) µm; the
        file gives it in µm.
    mean_point_shift : float — [1]
        The mean point M placed off the gear's mean cone distance by this fraction of the
        gear face width, > 0 towards the heel (:func:`geometry.pair.design_point.design_point`,
        step 3): the local synthesis then makes the bearing about M there, the lever that
        moves the pattern along the face (toe–heel). Default 0, in (−0.25, 0.25).
    """

    path_angle: float = math.radians(-45.0)
    te_level: float = 45e-6
    ellipse_length: float = 0.275
    approach: float = 0.0063
    tip_relief: float = 0.015
    root_relief: float = 0.015
    relief_start: float = 0.5
    blade_angle_change: float = 0.0
    profile_crowning: float = 0.0
    tip_relief_start: float | None = None
    mean_point_shift: float = 0.0

    @property
    def tip_start(self) -> float:
        """Where the tip relief starts [1]: ``tip_relief_start``, else ``relief_start``."""
        return self.relief_start if self.tip_relief_start is None else self.tip_relief_start

    def __post_init__(self) -> None:
        object.__setattr__(self, "path_angle", math.radians(real(
            "path_angle", math.degrees(real("path_angle", self.path_angle, unit="rad")),
            unit="deg", low=-90.0, high=90.0, low_open=True, high_open=True)))
        object.__setattr__(self, "te_level", 1e-6 * real(
            "te_level", 1e6 * real("te_level", self.te_level, unit="rad"), unit="urad",
            low=0.0, high=1000.0, low_open=True))
        object.__setattr__(self, "ellipse_length", real(
            "ellipse_length", self.ellipse_length, unit="1, fraction of the face width",
            low=0.02, high=0.9, low_open=True, high_open=True))
        object.__setattr__(self, "approach", real("approach", self.approach, unit="mm",
                                                  low=0.0, high=0.1, low_open=True))
        for name in ("tip_relief", "root_relief"):
            object.__setattr__(self, name, 1e-3 * real(
                name, 1e3 * real(name, getattr(self, name), unit="mm"), unit="um", low=0.0,
                high=200.0, high_open=True))
        object.__setattr__(self, "relief_start", real(
            "relief_start", self.relief_start, unit="1, fraction of the way from M to the "
            "flank end", low=0.0, high=1.0, high_open=True))
        if self.tip_relief_start is not None:
            object.__setattr__(self, "tip_relief_start", real(
                "tip_relief_start", self.tip_relief_start, unit="1, fraction of the way "
                "from M to the tip end", low=0.0, high=1.0, high_open=True))
        object.__setattr__(self, "blade_angle_change", math.radians(real(
            "blade_angle_change", math.degrees(real("blade_angle_change",
                                                    self.blade_angle_change, unit="rad")),
            unit="deg", low=-5.0, high=5.0, low_open=True, high_open=True)))
        object.__setattr__(self, "profile_crowning", 1e-3 * real(
            "profile_crowning", 1e3 * real("profile_crowning", self.profile_crowning,
                                           unit="mm"),
            unit="um", low=-100.0, high=100.0, low_open=True, high_open=True))
        object.__setattr__(self, "mean_point_shift", real(
            "mean_point_shift", self.mean_point_shift, unit="1, fraction of the face width",
            low=-0.25, high=0.25, low_open=True, high_open=True))


@dataclass(frozen=True)
class SynthesisOptions:
    """Synthesis options (``[synthesis]`` of a basic file; defaults in ``docs/synthesis.md``).

    Parameters
    ----------
    drive_flank : str
        Pinion flank that drives, ``"concave"`` (default) or ``"convex"``.
    gear_process, pinion_process : str
        Gear ``"Formate"``, ``"Generate"`` or ``"auto"`` (default: Formate where the gear
        pitch angle δ2 is at least
        :data:`geometry.synthesis.case_synthesis.FORMATE_PITCH_ANGLE_LIMIT` or the gear is
        face hobbed, Generate below it where the Formate synthesis has no solution, and,
        under the development, where the Formate gear's developed design fails or misses
        a drive pattern target:
        :func:`contact.optimize.development_process.with_generated_gear`); pinion
        ``"Generate"``.
    cutter_radius : float or None — [mm]
        Nominal gear cutter radius r_c0; default the design's ``rc0``.
    blade_angle_drive, blade_angle_coast : float or None — [rad]
        Gear blade angles of the flanks meshing the pinion's drive / coast flank; default the
        generated normal pressure angles α_nD, α_nC of ISO 23509 (= design pressure angles
        ± f_αlim α_lim).
    point_width : float or None — [mm]
        Gear cutter point width; default from the gear slot width at the mean point:
        W = π m_mn − s_mn2 − h_fm2 (tan α_D + tan α_C).
    edge_radius : float or None — [mm]
        Blade edge radius of both members; default min(0.25 m_mn, 0.4 W).
    edge_break_radius : float or None — [mm]
        Edge break (rounding) radius of both members' tooth edges, written into the case's
        ``[<member>.blank] edge_break_radius`` (:class:`geometry.case.Blank`; the radius of
        the Hertz line contact of an edge, :mod:`contact.ltca.edges`), in (0, 20]. Default
        None: the case blank's own 0.5 mm (:data:`EDGE_BREAK_RADIUS`); a basic file that
        does not give it gets 0.5 mm × :func:`size_scale` (m_mn below
        :data:`REFERENCE_MODULE`: in proportion to the module, written into the case).
    design_torque : float or None — [N·m]
        Pinion torque at which the development bearing is checked under load (no edge
        contact beyond a small share, no plastic edge; ``docs/synthesis.md``), in
        (0, 1e6]. Default None: the pinion torque at which the ISO 10300 pitting safety
        factor S_H of the synthesised case's ``[rating]`` inputs equals 1
        (:func:`contact.load_capacity.iso10300.capacity.design_torque`) — the largest torque the
        flank
        carries at long life, so the torque the bearing must hold without edge contact.
    concave, convex : FlankOptions
        Local-synthesis prescriptions per pinion flank.
    """

    drive_flank: str = "concave"
    gear_process: str = "auto"
    pinion_process: str = "Generate"
    cutter_radius: float | None = None
    blade_angle_drive: float | None = None
    blade_angle_coast: float | None = None
    point_width: float | None = None
    edge_radius: float | None = None
    design_torque: float | None = None
    edge_break_radius: float | None = None
    concave: FlankOptions = field(default_factory=FlankOptions)
    convex: FlankOptions = field(default_factory=FlankOptions)

    def __post_init__(self) -> None:
        if self.drive_flank not in ("concave", "convex"):
            raise InputError(f"synthesis.drive_flank: must be 'concave' or 'convex', got "
                             f"{self.drive_flank!r}")
        procs = (self.gear_process, self.pinion_process)
        if procs not in PROCESSES:
            raise InputError(f"synthesis.gear_process, pinion_process: must be one of "
                             f"{sorted(PROCESSES)}, got {procs!r}")
        if not PROCESSES[procs]:
            raise ModelUnavailableError(
                f"synthesis.gear_process, pinion_process: {procs!r} is not implemented; "
                f"available: {[p for p, ok in PROCESSES.items() if ok]}")
        for name, lo, hi, unit in (("cutter_radius", 0.0, 1e4, "mm"),
                                   ("point_width", 0.0, 100.0, "mm"),
                                   ("edge_radius", 0.0, 20.0, "mm"),
                                   ("edge_break_radius", 0.0, 20.0, "mm"),
                                   ("design_torque", 0.0, 1e6, "N m")):
            v = getattr(self, name)
            if v is not None:
                object.__setattr__(self, name, real(f"synthesis.{name}", v, unit=unit, low=lo,
                                                    high=hi, low_open=name != "edge_radius"))
        for name in ("blade_angle_drive", "blade_angle_coast"):
            v = getattr(self, name)
            if v is not None:
                object.__setattr__(self, name, math.radians(real(
                    f"synthesis.{name}", math.degrees(real(f"synthesis.{name}", v, unit="rad")),
                    unit="deg", low=0.0, high=45.0, low_open=True, high_open=True)))

    def flank(self, name: str) -> FlankOptions:
        """Prescriptions of pinion flank ``name``."""
        return getattr(self, name)


@dataclass(frozen=True)
class BasicDesign:
    """A parsed basic file: design data, targets and synthesis options.

    Attributes
    ----------
    name, source : str
    design : BevelGearDesign
        After the fit to ``targets`` (if any).
    targets : dict
        Target name (:data:`TARGETS`) → value [deg or mm].
    adjust : tuple of str
        Design fields varied to hit the targets.
    options : SynthesisOptions
    comments : dict
        Free-text notes kept from the file's ``[notes]`` table (copied into the case source).
    operating : dict
        The file's ``[operating]`` table (the case's operating point: torques,
        misalignment, speed, oil; schema of :func:`geometry.case.operating_from_dict`),
        copied into the synthesised case; empty for the toolkit's defaults.
    optimize : dict
        The file's ``[optimize]`` table (read by ``ltca optimize`` when it re-synthesises
        this design; schema of :func:`contact.optimize.problem_from_table`), unvalidated
        here; empty if absent.
    path : str
        The basic file as the user named it (set by :func:`load_basic`; ``ltca
        synthesize`` passes the name it shows), cited first in the case ``source``; empty
        for a design built from a mapping.
    rating : dict
        The file's ``[rating]`` table (ISO 10300 inputs, schema of
        :class:`contact.load_capacity.iso10300.inputs.RatingInputs`), copied into the synthesised
        case
        (else :data:`DEFAULT_RATING`);
        validated by ``ltca synthesize``, not here; empty if absent.
    development : dict
        The file's ``[development]`` table: the development-bearing targets of
        ``ltca synthesize`` (schema of :class:`contact.optimize.development.DevelopmentTargets`,
        ``docs/synthesis.md``), unvalidated here; empty for the stated defaults.
    root_stress : dict
        The file's ``[root_stress]`` table (``fe_level``: the FE model of the root stress,
        :func:`contact.compliance.fe.options.fe_level_of`), copied into the synthesised
        case; unvalidated here (``ltca synthesize`` writes the level it used: its
        ``--fe-level``, else this table's, else ``"coarse10"``); empty if absent.
    """

    name: str
    source: str
    design: BevelGearDesign
    targets: Mapping[str, float]
    adjust: tuple[str, ...]
    options: SynthesisOptions
    comments: Mapping[str, str] = field(default_factory=dict)
    operating: Mapping[str, Any] = field(default_factory=dict)
    optimize: Mapping[str, Any] = field(default_factory=dict)
    rating: Mapping[str, Any] = field(default_factory=dict)
    path: str = ""
    development: Mapping[str, Any] = field(default_factory=dict)
    root_stress: Mapping[str, Any] = field(default_factory=dict)

    def blank(self) -> BlankGeometry:
        """ISO 23509 blank geometry of the design (pitch cone and both members), its face
        angles within 90° (:func:`~geometry.iso23509.blank.check_face_angles`: a case's
        blank; InputError naming the basic field where not)."""
        return check_face_angles(blank_geometry(self.design))

    def size_scale(self) -> float:
        """:func:`size_scale` of the design's mean normal module [1]: the factor its
        µm-sized defaults were scaled by (InputError where the blank cannot be made)."""
        return size_scale(self.blank().m_mn)

    @property
    def gives_design_torque(self) -> bool:
        """The basic file gives the design torque (``[synthesis] design_torque`` or
        ``[rating] design_torque``): the development keeps it, lowering none of its own."""
        return (self.options.design_torque is not None
                or self.rating.get("design_torque") is not None)


def fit_design(design: BevelGearDesign, targets: Mapping[str, float],
               adjust: tuple[str, ...]) -> BevelGearDesign:
    """Adjust design fields so that the ISO 23509 blank hits published target values.

    Parameters
    ----------
    design : BevelGearDesign
        Start values (angles rad, lengths mm).
    targets : mapping
        Target name (a key of :data:`TARGETS`) → value [deg for angles, mm for lengths].
    adjust : tuple of str
        Design fields varied (a subset of ``de2, dm2, b2, rc0, beta_m, theta_a2, theta_f2,
        c_ham``, each given in ``design``); at most as many as there are targets.

    Returns
    -------
    BevelGearDesign
        The fitted design (least squares; exact when the targets are reachable).

    Raises
    ------
    InputError
        For an unknown target or adjustable field, a field the design leaves out, more
        fields than targets, or when no valid design is found near the start.

    Notes
    -----
    ``scipy.optimize.least_squares`` on the residuals value − target, each divided by 1 mm or
    1°, with every evaluation a full ISO 23509 blank (:func:`blank_geometry`).
    Designs rejected by the standard's checks count as a large residual.
    """
    unknown = sorted(set(targets) - set(TARGETS))
    if unknown:
        raise InputError(f"targets.{unknown[0]}: unknown target; accepted: {sorted(TARGETS)}")
    bad = sorted(set(adjust) - set(_ADJUSTABLE))
    if bad:
        raise InputError(f"targets.adjust: {bad[0]!r} cannot be adjusted; accepted: "
                         f"{list(_ADJUSTABLE)}")
    unset = [a for a in adjust if getattr(design, a) is None]
    if unset:
        raise InputError(f"targets.adjust: {unset[0]!r} is not given in this design (method "
                         f"{design.method}, input data type {design.input_data_type}); "
                         "adjust a field it has")
    if len(adjust) > len(targets):
        raise InputError(f"targets.adjust: {len(adjust)} fields for {len(targets)} targets; "
                         "give at most as many fields as targets")
    if not adjust:
        return design
    names = list(targets)
    x0 = [getattr(design, a) for a in adjust]
    scale = [1.0 if a not in _DESIGN_ANGLES else math.radians(1.0) for a in adjust]

    def make(x):
        return replace(design, **dict(zip(adjust, (v * s for v, s in zip(x, scale,
                                                                          strict=True)),
                                          strict=True)))

    def residual(x):
        try:
            geom = blank_geometry(make(x))
        except InputError:
            return [1e3] * len(names)
        return [TARGETS[n][1](geom) - targets[n] for n in names]

    sol = least_squares(residual, [v / s for v, s in zip(x0, scale, strict=True)],
                        xtol=1e-14, ftol=1e-14, gtol=1e-14)
    if max(abs(r) for r in sol.fun) >= 1e2:
        raise InputError(f"targets: no valid ISO 23509 design found by adjusting {adjust}")
    return make(sol.x)


_OPTION_FIELDS = {"drive_flank", "gear_process", "pinion_process", "cutter_radius",
                  "blade_angle_drive", "blade_angle_coast", "point_width", "edge_radius",
                  "design_torque", "edge_break_radius"}
_FLANK_FIELDS = {f.name for f in fields(FlankOptions)}
_TOP = {"name", "source", "design", "targets", "synthesis", "notes", "operating", "optimize",
        "rating", "development", "root_stress"}


def _same(v):
    return v


#: flank prescription → (file unit, file → FlankOptions value, FlankOptions value → file):
#: the one place the ``[synthesis]`` units are converted, both ways
_FILE_UNITS: dict[str, tuple[str, Callable[[Any], Any], Callable[[Any], Any]]] = {
    "path_angle": ("deg", math.radians, math.degrees),
    "te_level": ("urad", lambda v: v * 1e-6, lambda v: 1e6 * v),
    "ellipse_length": ("1", _same, _same),
    "approach": ("mm", _same, _same),
    "tip_relief": ("um", lambda v: v * 1e-3, lambda v: 1e3 * v),
    "root_relief": ("um", lambda v: v * 1e-3, lambda v: 1e3 * v),
    "relief_start": ("1", _same, _same),
    "blade_angle_change": ("deg", math.radians, math.degrees),
    "profile_crowning": ("um", lambda v: v * 1e-3, lambda v: 1e3 * v),
    "tip_relief_start": ("1", _same, _same),
    "mean_point_shift": ("1", _same, _same),
}
#: file units of the flank prescriptions (``[synthesis]`` of a basic file)
FLANK_OPTION_UNITS: Mapping[str, str] = {k: u for k, (u, _, _) in _FILE_UNITS.items()}


def _flank_options(raw: Mapping, where: str, base: FlankOptions | None = None,
                   defaults: Mapping[str, float] | None = None) -> FlankOptions:
    unknown = sorted(set(raw) - _FLANK_FIELDS)
    if unknown:
        raise InputError(f"{where}.{unknown[0]}: unknown field; accepted: "
                         f"{sorted(_FLANK_FIELDS)}")
    kw: dict[str, Any] = dict(defaults or {})  # the values given replace these
    for k, v in raw.items():
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise InputError(f"{where}.{k}: must be a number, got {v!r}")
        kw[k] = _FILE_UNITS[k][1](v)
    try:
        return replace(base, **kw) if base is not None else FlankOptions(**kw)
    except InputError as exc:
        raise InputError(f"{where}.{exc}") from None


def flank_option_values(options: FlankOptions) -> dict[str, float]:
    """A flank's prescriptions in file units (:data:`FLANK_OPTION_UNITS`: deg, µrad, µm …).

    Parameters
    ----------
    options : FlankOptions

    Returns
    -------
    dict of str to float
        Field → value in the unit a basic file gives it (schema: docs/synthesis.md);
        ``tip_relief_start`` the start the tip relief has (``relief_start`` where the
        flank gives none).
    """
    out = {}
    for k, (_, _, to_file) in _FILE_UNITS.items():
        v = options.tip_start if k == "tip_relief_start" else getattr(options, k)
        out[k] = float(to_file(v))
    return out


def hunting_z0(z0: int, z1: int, z2: int, largest: int = 19) -> tuple[int, ...]:
    """The numbers of blade groups nearest ``z0`` that hunt both members.

    Parameters
    ----------
    z0 : int
        The number of blade groups given [1].
    z1, z2 : int
        The pinion's and the gear's numbers of teeth [1].
    largest : int, optional
        The largest number of blade groups offered (face-hobbing cutters carry 1 to about
        19 groups; Stadtfeld, *Gleason Bevel Gear Technology*, 2014, ch. on face hobbing).
        Default 19.

    Returns
    -------
    tuple of int
        The nearest number below ``z0`` and the nearest above (each where one exists in
        1 … ``largest``) with no common factor with ``z1`` and ``z2``, below first.
    """
    def hunts(n: int) -> bool:
        return math.gcd(n, z1) == 1 and math.gcd(n, z2) == 1

    below = next((n for n in range(z0 - 1, 0, -1) if hunts(n)), None)
    above = next((n for n in range(z0 + 1, largest + 1) if hunts(n)), None)
    return tuple(n for n in (below, above) if n is not None)


def _hunting_z0_text(z0: int, z1: int, z2: int) -> str:
    """"; the nearest that hunt both: z0 3 or 7" (:func:`hunting_z0`), "" where none."""
    near = hunting_z0(z0, z1, z2)
    return ("; the nearest that hunt both: z0 " + " or ".join(str(n) for n in near)
            if near else "")


def with_flank_options(basic: BasicDesign, flank: str,
                       values: Mapping[str, float]) -> BasicDesign:
    """The basic design with some prescriptions of one pinion flank replaced.

    Parameters
    ----------
    basic : BasicDesign
    flank : str
        Pinion flank ``"concave"`` or ``"convex"``.
    values : mapping of str to float
        Field of :class:`FlankOptions` → value in file units (:data:`FLANK_OPTION_UNITS`).

    Returns
    -------
    BasicDesign
        Only ``options.<flank>`` differs.

    Raises
    ------
    InputError
        Unknown flank or field, or a value outside the field's range, named as
        ``synthesis.<flank>.<field>``.

    Notes
    -----
    The prescriptions of Litvin's local synthesis (Litvin & Fuentes, *Gear Geometry and
    Applied Theory*, 2nd ed., ch. 9), in the ``[synthesis]`` schema of docs/synthesis.md.
    """
    if flank not in ("concave", "convex"):
        raise InputError(f"flank: must be 'concave' or 'convex', got {flank!r}")
    fo = _flank_options(dict(values), f"synthesis.{flank}", basic.options.flank(flank))
    return replace(basic, options=replace(basic.options, **{flank: fo}))


def _check_cutting_method(method: Any, z0: int) -> None:
    """``[synthesis] method``, optional: "FM" (face milling) or "FH" (face hobbing), the
    case file's ``pair.method``; it must agree with the blade groups ``design.z0``."""
    if method is None:
        return
    if method not in ("FM", "FH"):
        raise InputError(f"synthesis.method: must be 'FM' or 'FH', got {method!r}")
    if (method == "FH") != (z0 >= 1):
        need = "design.z0 >= 1 blade groups" if method == "FH" else "design.z0 = 0"
        raise InputError(f"synthesis.method: {method!r} needs {need}, got z0 = {z0}")


def basic_from_dict(raw: Mapping[str, Any], *, fit: bool = True) -> BasicDesign:
    """Validate a parsed basic file and build the :class:`BasicDesign`.

    Parameters
    ----------
    raw : mapping
        Parsed TOML (angles in degrees, lengths in mm, ``te_level`` in µrad).
    fit : bool
        Fit the design to ``[targets]`` (default True).

    Returns
    -------
    BasicDesign

    Raises
    ------
    InputError
        A missing, unknown or out-of-range field, named by its dotted path.
    ModelUnavailableError
        A process pair or ISO method that is not implemented.
    """
    if not isinstance(raw, Mapping):
        raise InputError(f"basic file: must be a table, got {type(raw).__name__}")
    unknown = sorted(set(raw) - _TOP)
    if unknown:
        raise InputError(f"{unknown[0]}: unknown table or field; accepted: {sorted(_TOP)}")
    for key in ("name", "source"):
        if not isinstance(raw.get(key), str) or not raw[key].strip():
            raise InputError(f"{key}: required non-empty string, got {raw.get(key)!r}")
    des = raw.get("design")
    if not isinstance(des, Mapping):
        raise InputError("design: missing table (the ISO 23509 inputs)")
    try:
        design = BevelGearDesign.from_degrees(**des)
    except InputError as exc:
        raise InputError(f"design.{exc}") from None
    except ModelUnavailableError as exc:  # an ISO method not available (for this process)
        raise ModelUnavailableError(f"design.{exc}") from None
    for z in (design.z1, design.z2):
        if design.z0 and math.gcd(design.z0, z) != 1:
            raise InputError(
                f"design.z0: {design.z0} blade groups share the factor "
                f"{math.gcd(design.z0, z)} with {z} teeth; a face-hobbing cutter must hunt "
                "both members (no common factor with z1 and z2)"
                + _hunting_z0_text(design.z0, design.z1, design.z2))
    tg = dict(raw.get("targets", {}))
    adjust = tg.pop("adjust", [])
    if not isinstance(adjust, list) or not all(isinstance(a, str) for a in adjust):
        raise InputError(f"targets.adjust: must be a list of design field names, got "
                         f"{adjust!r}")
    targets: dict[str, float] = {}
    for k, v in tg.items():
        if k not in TARGETS:
            raise InputError(f"targets.{k}: unknown target; accepted: {sorted(TARGETS)}")
        targets[k] = real(f"targets.{k}", v, unit=TARGETS[k][0], low=-1e5, high=1e5)
    if fit:
        design = fit_design(design, targets, tuple(adjust))
    syn = dict(raw.get("synthesis", {}))
    _check_cutting_method(syn.pop("method", None), design.z0)
    flank_raw = {f: syn.pop(f, {}) for f in ("concave", "convex")}
    flank_common = {k: syn.pop(k) for k in list(syn) if k in _FLANK_FIELDS}
    unknown = sorted(set(syn) - _OPTION_FIELDS)
    if unknown:
        accepted = _OPTION_FIELDS | _FLANK_FIELDS | {"concave", "convex", "method"}
        raise InputError(f"synthesis.{unknown[0]}: unknown field; accepted: "
                         f"{sorted(accepted)}")
    # the µm-sized defaults and the edge break follow the tooth size (size_scale); a value
    # given wins
    scale = _design_scale(design)
    common = _flank_options(flank_common, "synthesis",
                            defaults=_size_scaled_defaults(scale))
    per_flank = {f: _flank_options(flank_raw[f], f"synthesis.{f}", common)
                 for f in ("concave", "convex")}
    kw = dict(syn)
    for name in ("blade_angle_drive", "blade_angle_coast"):
        if name in kw:
            v = kw[name]
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise InputError(f"synthesis.{name}: must be a number [deg], got {v!r}")
            kw[name] = math.radians(v)
    options = SynthesisOptions(**(_scaled_edge_break(scale) | kw), **per_flank)
    notes = raw.get("notes", {})
    if not isinstance(notes, Mapping) or not all(isinstance(v, str) for v in notes.values()):
        raise InputError(f"notes: must be a table of strings, got {notes!r}")
    operating_from_dict(raw)  # the [operating] table validated here (operating.<field>)
    operating = dict(raw.get("operating", {}))
    rating = raw.get("rating", {})
    if not isinstance(rating, Mapping):
        raise InputError(f"rating: must be a table (the ISO 10300 inputs, docs/rating.md), "
                         f"got {rating!r}")
    return BasicDesign(name=raw["name"], source=raw["source"], design=design,
                       targets=targets, adjust=tuple(adjust), options=options,
                       comments=dict(notes), operating=operating,
                       optimize=dict(raw.get("optimize", {})),
                       rating=dict(rating), development=_table(raw, "development"),
                       root_stress=_table(raw, "root_stress"))


def _table(raw: Mapping[str, Any], name: str) -> dict[str, Any]:
    """The optional table ``name`` of a basic file (empty if absent); InputError if it is
    not a table."""
    tab = raw.get(name, {})
    if not isinstance(tab, Mapping):
        raise InputError(f"{name}: must be a table, got {tab!r}")
    return dict(tab)


def load_basic(path: str | os.PathLike[str], *, fit: bool = True) -> BasicDesign:
    """Read and validate a basic design file (``cases/basic/*.toml``).

    Parameters
    ----------
    path : path-like
    fit : bool
        Fit the design to ``[targets]`` (default True).

    Returns
    -------
    BasicDesign
        The validated file: design data, ``[targets]``, synthesis options and its other
        tables (``[operating]``, ``[rating]``, ``[development]``, ``[optimize]``), the
        design fitted to the targets when ``fit``; ``path`` as given
        (``cases/basic/<name>`` for a bundled file).

    Raises
    ------
    InputError
        Missing or unreadable file, not UTF-8 text, invalid TOML, or an invalid field (named
        by its dotted path).
    ModelUnavailableError
        As :func:`basic_from_dict`.
    """
    p = Path(path)
    # a bundled file by its place in the repository, not this machine's install path
    shown = (f"cases/basic/{p.name}" if p.resolve().parent.parts[-2:] == ("cases", "basic")
             else os.fspath(path))
    return replace(basic_from_dict(read_toml(path, "basic file"), fit=fit), path=shown)
