"""Case files: one gear pair in TOML, loaded into frozen dataclasses (see ``docs/cases.md``).

A case holds the pair data (shaft angle, offset, method, hands, drive flank), and per member
its blank, and per member and flank the blade and the machine settings of the cradle-type
generator. Angles are degrees in files and radians in the dataclasses (converted once
here); lengths are mm. Every field is validated on load; an error names the field by its
dotted path and the accepted range, e.g.
``pinion.machine.concave.ratio_of_roll: must be > 0 for a generated member, got -1.0``.

Settings are read for a right-hand member (see :mod:`geometry.machine.cradle`); a left-hand member
is generated as the mirror image of the right-hand one. A member's ``[<member>.machine]``
and ``[<member>.cutter]`` tables may each declare the convention their summary is typed in,
``convention = "ours"`` (default) or ``"spygo"`` (a summary typed from SpyGO, converted on
load by :mod:`geometry.machine.convention`; ``docs/machine.md``). Case files written by the
toolkit (:meth:`Case.to_toml`) are always in our convention and carry no ``convention`` key.

Public functions
----------------
Blank, FlankTool, Member, Pair, Case     frozen dataclasses
OperatingPoint                            the ``[operating]`` table: torques, speed, oil
DeviationFiles                            the optional ``[deviations]`` table (resolved paths)
load_case                                 read and validate a TOML case file
case_from_dict                            the same from an already parsed mapping
read_toml                                 parse a TOML input file, a bad one refused by name
Case.to_toml                              the case as TOML text (round-trips through load)
"""

from __future__ import annotations

import dataclasses
import json
import logging
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from geometry.core.bounds import check_bound
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.materials import DEFAULT_MATERIAL, available_materials
from geometry.core.operating_defaults import OPERATING_DEFAULTS as _OPERATING_DEFAULTS
from geometry.core.toml_files import dump_toml, read_toml
from geometry.core.validation import integer, known_fields, positive, real
from geometry.machine.convention import (
    SPYGO_BLADE_FIELDS,
    blade_from_spygo,
    check_convention,
    machine_from_spygo,
)
from geometry.machine.cradle import PROCESSES, MachineSettings, indexing_ratio
from geometry.machine.cutter import PROFILE_TYPES, Blade
from geometry.pair.assembly import HANDS, Misalignment

__all__ = [
    "FLANKS",
    "METHODS",
    "OPERATING_DEFAULTS",
    "Blank",
    "Case",
    "DeviationFiles",
    "FlankTool",
    "Member",
    "OperatingPoint",
    "Pair",
    "TeethKey",
    "case_from_dict",
    "load_case",
    "read_toml",
]

log = logging.getLogger(__name__)

#: flank name → the blade that cuts it
FLANKS: dict[str, str] = {"concave": "outside", "convex": "inside"}
#: cutting methods: name → implemented (face milling, face hobbing)
METHODS: dict[str, bool] = {"FM": True, "FH": True}

_DEG = math.pi / 180.0


def _fmt(x: float) -> str:
    return f"{x:.6g}"


#: the toolkit's operating point where a case's ``[operating]`` table gives none
#: (:mod:`geometry.core.operating_defaults`, a module light enough for the commands' help)
OPERATING_DEFAULTS = _OPERATING_DEFAULTS


@dataclass(frozen=True)
class OperatingPoint:
    """The operating point of a case (its ``[operating]`` table; the misalignment, the
    fourth part of it, is :attr:`Case.misalignment`).

    Every entry point (``ltca`` commands, :func:`contact.pipeline.run_analysis`,
    :func:`contact.study.efficiency.efficiency_map`, the studies' base point) uses these values
    unless the caller overrides them.

    Parameters
    ----------
    torque : tuple of float — [N·m]
        Pinion torques of the analysis, each in (0, 1e6] (at least one; the table of
        physical bounds, :data:`geometry.core.bounds.PHYSICAL_BOUNDS`). Default the seed's
        Table 3.1 torques 50, 250, 500.
    pinion_speed : float — [rpm]
        Pinion speed of the efficiency stage, 0 or in (0, 5e4]; 0 runs no efficiency stage.
        Default 1500.
    lubricant : str
        Bundled oil name or the path of an oil TOML file (checked where the efficiency
        stage runs, :class:`friction.operating.OperatingConditions`). Default ``"75W90"``.
    temperature : float — [degC]
        Oil inlet temperature, in [-40, 200]. Default 90.
    roughness : float — [µm]
        RMS roughness Rq of each flank, in (0, 5]. Default 0.8.
    friction_model : str or None
        Friction coefficient model name (checked where the efficiency stage runs). Default
        None: the efficiency stage's default, the friction package's
        (:data:`friction.defaults.DEFAULT_FRICTION_MODEL`); a case file without the field
        writes none back.

    Raises
    ------
    InputError
        A field of the wrong type or out of its range (``<field>: must be … got …``).

    Notes
    -----
    Defaults: :data:`OPERATING_DEFAULTS` (seed Table 3.1 torques, seed Table 5.2 oil).
    """

    torque: tuple[float, ...] = OPERATING_DEFAULTS["torque"]
    pinion_speed: float = OPERATING_DEFAULTS["pinion_speed"]
    lubricant: str = OPERATING_DEFAULTS["lubricant"]
    temperature: float = OPERATING_DEFAULTS["temperature"]
    roughness: float = OPERATING_DEFAULTS["roughness"]
    friction_model: str | None = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        t = self.torque
        values = [t] if isinstance(t, (int, float)) and not isinstance(t, bool) else t
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or not values:
            raise InputError(f"torque: must be one or more pinion torques > 0 [N m], got {t!r}")
        # the one table of physical bounds (geometry.core.bounds; issue 64)
        set_(self, "torque", tuple(check_bound("torque", v) for v in values))
        speed = real("pinion_speed", self.pinion_speed, unit="rpm")
        set_(self, "pinion_speed", speed if speed == 0.0 else check_bound("pinion_speed", speed))
        set_(self, "temperature", check_bound("temperature", self.temperature))
        set_(self, "roughness", check_bound("roughness", self.roughness, positive=True))
        for name in ("lubricant", "friction_model"):
            val = getattr(self, name)
            if val is None and name == "friction_model":
                continue
            if isinstance(val, os.PathLike):
                val = os.fspath(val)
                set_(self, name, val)
            if not isinstance(val, str) or not val.strip():
                raise InputError(f"{name}: must be a non-empty name, got {val!r}")


@dataclass(frozen=True)
class Blank:
    """Blank of one member, as a case file gives it (ISO 23509 names; angles rad, lengths mm).

    Parameters
    ----------
    teeth : int
        Number of teeth z, in [3, 500].
    face_width : float — [mm]
        b, in (0, outer_cone_distance).
    outer_cone_distance : float — [mm]
        R_e > 0, along the pitch cone from the pitch apex to the heel.
    pitch_angle, face_angle, root_angle : float — [rad]
        δ, δ_a, δ_f in (0, 90°], with δ_f ≤ δ ≤ δ_a (all equal for uniform depth, the
        usual face-hobbed tooth: the cones are then parallel with different apexes).
    pitch_apex, face_apex, root_apex : float — [mm]
        Apex positions "beyond the crossing point" (ISO 23509 t_zm, t_zF, t_zR: positive when
        the apex lies beyond the crossing point, away from the member body); |t| < R_e.
    outer_addendum, outer_dedendum : float — [mm]
        h_ae ≥ 0, h_fe > 0 at R_e, measured perpendicular to the pitch cone; the face and
        root cones must pass through these points within max(0.02 mm, 1 % of h_ae + h_fe).
    edge_break_radius : float — [mm]
        Rounding radius of the tooth's edges (the tip edge, toe and heel ends: the edge
        break), in (0, h_ae + h_fe); default 0.5 mm, a light edge break. An edge in
        contact with the mating flank is a Hertz line contact of this radius
        (:mod:`contact.ltca.edges`).

    Raises
    ------
    InputError
        Naming the field and its range.
    """

    teeth: int
    face_width: float
    outer_cone_distance: float
    pitch_angle: float
    face_angle: float
    root_angle: float
    pitch_apex: float
    face_apex: float
    root_apex: float
    outer_addendum: float
    outer_dedendum: float
    edge_break_radius: float = 0.5

    def __post_init__(self) -> None:
        integer("teeth", self.teeth, 3, 500)
        for name in ("face_width", "outer_cone_distance", "pitch_angle", "face_angle",
                     "root_angle", "pitch_apex", "face_apex", "root_apex", "outer_addendum",
                     "outer_dedendum", "edge_break_radius"):
            unit = "rad" if name.endswith("_angle") else "mm"
            object.__setattr__(self, name, real(name, getattr(self, name), unit=unit))
        positive("outer_cone_distance", self.outer_cone_distance, "mm")
        if not 0 < self.face_width < self.outer_cone_distance:
            raise InputError(
                f"face_width: must be in (0, outer_cone_distance = {self.outer_cone_distance}) "
                f"[mm], got {self.face_width}")
        for name in ("pitch_angle", "face_angle", "root_angle"):
            real(name, getattr(self, name), unit="deg", low=0.0, high=0.5 * math.pi + 1e-12,
                 low_open=True, scale=_DEG)
        eps = 1e-12  # [rad] round-off of cone angles computed from each other
        if not self.root_angle - eps <= self.pitch_angle <= self.face_angle + eps:
            raise InputError(
                "pitch_angle: must satisfy root_angle <= pitch_angle <= face_angle (all equal: "
                f"uniform depth), got root {_fmt(self.root_angle / _DEG)}, pitch "
                f"{_fmt(self.pitch_angle / _DEG)}, face {_fmt(self.face_angle / _DEG)} deg")
        for name in ("pitch_apex", "face_apex", "root_apex"):
            if abs(getattr(self, name)) >= self.outer_cone_distance:
                raise InputError(
                    f"{name}: must be in (-R_e, R_e) = (-{self.outer_cone_distance}, "
                    f"{self.outer_cone_distance}) [mm], got {getattr(self, name)}")
        real("outer_addendum", self.outer_addendum, unit="mm", low=0.0)
        positive("outer_dedendum", self.outer_dedendum, "mm")
        depth = self.outer_addendum + self.outer_dedendum
        if not 0 < self.edge_break_radius < depth:
            raise InputError(
                f"edge_break_radius: must be in (0, outer_addendum + outer_dedendum = "
                f"{_fmt(depth)}) [mm], got {self.edge_break_radius}")
        # consistency: face and root cones through the outer addendum / dedendum points
        d = self.pitch_angle
        zp = -self.pitch_apex
        tol = max(0.02, 0.01 * (self.outer_addendum + self.outer_dedendum))
        for name, h, apex, angle in (
                ("face_apex", self.outer_addendum, self.face_apex, self.face_angle),
                ("root_apex", -self.outer_dedendum, self.root_apex, self.root_angle)):
            z = zp + self.outer_cone_distance * math.cos(d) - h * math.sin(d)
            rho = self.outer_cone_distance * math.sin(d) + h * math.cos(d)
            # distance of the point from the cone line through (-apex, 0) at ``angle``
            dist = abs((z + apex) * math.sin(angle) - rho * math.cos(angle))
            if dist > tol:
                raise InputError(
                    f"{name}: the cone through this apex misses the outer "
                    f"{'addendum' if h >= 0 else 'dedendum'} point by {dist:.4g} mm "
                    f"(accepted {tol:.3g} mm); check the apex sign (positive beyond the "
                    "crossing point) and the cone angle")


@dataclass(frozen=True)
class FlankTool:
    """Blade and machine settings that cut one flank."""

    blade: Blade
    machine: MachineSettings


@dataclass(frozen=True)
class Member:
    """One member (pinion or gear): blank and the tools of its two flanks.

    ``blade_groups`` is z0 of a face-hobbing cutter head (0 for face milling; its indexing
    ratio −z0/z is in both flanks' machine settings) and ``cutter_radius`` the nominal
    cutter radius r_c0 [mm] (informational, 0 when not given). ``material`` names the
    member's entry of the material table (:mod:`geometry.core.materials`; default
    case-carburised gear steel), which sets its contact-pressure limit.
    """

    name: str
    hand: str
    process: str
    blank: Blank
    concave: FlankTool
    convex: FlankTool
    blade_groups: int = 0
    cutter_radius: float = 0.0
    material: str = DEFAULT_MATERIAL

    def flank(self, name: str) -> FlankTool:
        """The tool of flank ``name`` (``"concave"`` or ``"convex"``)."""
        if name not in FLANKS:
            raise InputError(f"flank: must be one of {list(FLANKS)}, got {name!r}")
        return getattr(self, name)


@dataclass(frozen=True)
class Pair:
    """Pair data: Σ [rad], E [mm] (ISO 23509 sign), method, drive flank of the pinion."""

    shaft_angle: float
    offset: float
    method: str
    drive_flank: str


@dataclass(frozen=True)
class DeviationFiles:
    """The ``[deviations]`` table: files of measured / wear flank deviations (seed §4.3).

    Only the paths are kept (the geometry package does not read them: the files are read by
    :func:`contact.utca.deviation_files.read_deviations` when the analysis runs).

    Parameters
    ----------
    pinion, gear : str or None
        Absolute paths of the deviation files (CSV or netCDF) of the pinion and gear flanks
        in contact, resolved against the case file's directory when the file gives a
        relative path; None when the table omits the member.

    Raises
    ------
    InputError
        ``deviations.pinion`` / ``deviations.gear``: not a string, or no such file.
    """

    pinion: str | None = None
    gear: str | None = None

    def __post_init__(self) -> None:
        for name in ("pinion", "gear"):
            val = getattr(self, name)
            if val is None:
                continue
            if not isinstance(val, str) or not val.strip():
                raise InputError(f"{name}: must be a path string (CSV or netCDF deviation "
                                 f"file), got {val!r}")
            if not Path(val).is_file():
                raise InputError(f"{name}: no such deviation file {val!r}")


@dataclass(frozen=True)
class Case:
    """A whole case file. ``extra`` keeps other stages' tables (unvalidated here).

    ``deviations`` holds the optional ``[deviations]`` table (:class:`DeviationFiles`) or
    None. ``misalignment`` (ΔE, ΔP, ΔG [mm], ΔΣ [rad]) and ``operating``
    (:class:`OperatingPoint`: torques, speed, oil) are the case's operating point, read
    from its ``[operating]`` table.
    """

    name: str
    source: str
    pair: Pair
    pinion: Member
    gear: Member
    misalignment: Misalignment = field(default_factory=Misalignment)
    synthesised: tuple[str, ...] = ()
    extra: Mapping[str, Any] = field(default_factory=lambda: MappingProxyType({}))
    deviations: DeviationFiles | None = None
    operating: OperatingPoint = field(default_factory=OperatingPoint)

    def member(self, name: str) -> Member:
        """The member called ``name`` (``"pinion"`` or ``"gear"``)."""
        if name not in ("pinion", "gear"):
            raise InputError(f"member: must be 'pinion' or 'gear', got {name!r}")
        return getattr(self, name)

    def to_toml(self) -> str:
        """The case as TOML text; :func:`case_from_dict` of its parse equals the case.

        Returns
        -------
        str
            Angles in degrees, lengths in mm, as in a case file; machine settings and blades
            always in our convention (``docs/machine.md``), whatever convention the loaded
            file declared, so no ``convention`` key is written.

        Notes
        -----
        The text is made once per case object and kept on it (the case is frozen): an
        analysis writes it into several datasets' provenance (issue 32).
        """
        text = self.__dict__.get("_toml_text")
        if text is None:
            text = dump_toml(_case_to_dict(self))
            object.__setattr__(self, "_toml_text", text)
        return text

    def teeth_toml(self) -> str:
        """The case as TOML text without its misalignment and surface deviations.

        Neither changes a tooth in its member's frame (they change how the pair is
        assembled and which surfaces are compared), so this text keys the per-process memos
        of what the teeth alone decide: the tooth models
        (:func:`contact.compliance.pair_compliance_model`) and the pinion's points of the
        ease-off's forward map (:mod:`contact.utca.conjugate_map`); a misalignment sweep
        computes them once per process.

        Returns
        -------
        str
            :meth:`to_toml` of the case with ``Misalignment()`` and no deviations.
        """
        return dataclasses.replace(self, misalignment=Misalignment(), deviations=None).to_toml()

    def teeth_key(self) -> TeethKey:
        """The key of the per-process memos of what the teeth alone decide (the tooth
        models, the ease-off with its misalignment as a key of its own; the ease-off's
        forward-map points and gear nodes are keyed by their flank alone,
        :func:`contact.utca.conjugate_map.flank_key`): the case without its misalignment, deviations
        and operating point (torques, speed, oil: no tooth depends on them, and
        :func:`contact.run_analysis` writes the torques run into the case, so a torque
        series would otherwise miss every memo), compared by its full ``repr`` (every
        float to the last bit), carrying the case itself for the memo to compute from.

        Not :meth:`teeth_toml` rebuilt by :func:`case_from_dict`: a case changed in code
        can hold what its TOML does not say (a face-hobbing indexing ratio other than
        −z0/z, say), and the rebuilt case would be another pair's teeth.

        The operating point (``[operating]``: torques, speed, oil), the ``[rating]``
        table and the ``[root_stress]`` table (the FE level of the root stress) are left
        out too: none changes a tooth (what the memos compute reads the
        members, the pair and the name alone), and the development's checks analyse one
        case at several design torques, which each wrote into both (the coast flank's
        capacity search made the same ease-off and tooth models again at each torque).

        Returns
        -------
        TeethKey

        Notes
        -----
        Made once per case object and kept on it, as :meth:`to_toml`'s text (the case is
        frozen): an analysis asks for it at each memo it reads (the tooth models, the
        ease-off, the forward-map points and flanks), and the ``repr`` of a whole case is
        ~0.6 ms.
        """
        key = self.__dict__.get("_teeth_key")
        if key is None:
            extra = self.extra
            if not _NOT_TEETH_TABLES.isdisjoint(extra):
                extra = MappingProxyType({k: v for k, v in extra.items()
                                          if k not in _NOT_TEETH_TABLES})
            teeth = dataclasses.replace(self, misalignment=Misalignment(), deviations=None,
                                        operating=OperatingPoint(), extra=extra)
            key = TeethKey(teeth, repr(teeth))
            object.__setattr__(self, "_teeth_key", key)
        return key


    def replaced(self, **changes: Any) -> Case:
        """``dataclasses.replace(self, **changes)``, carrying this case's teeth key where
        the changes leave the teeth as they are.

        Parameters
        ----------
        **changes
            New values of the case's fields, as :func:`dataclasses.replace` takes them
            (``misalignment`` a :class:`~geometry.pair.assembly.Misalignment` [mm, rad],
            ``operating`` an :class:`OperatingPoint`, ``deviations`` a
            :class:`DeviationFiles` or None, …).

        Returns
        -------
        Case
            The changed case. Where only ``misalignment``, ``deviations`` and
            ``operating`` change (:meth:`teeth_key` leaves all three out: no tooth
            depends on them), the new case carries this case's teeth key (made now if
            not yet) instead of making it again from its ``repr`` (~0.5 ms: a study's
            every point replaces the misalignment of the study's case, and every
            analysis the operating point of the case it runs; both read the key).

        Raises
        ------
        TypeError
            A name that is no field of :class:`Case` (:func:`dataclasses.replace`'s).

        Notes
        -----
        Source: :meth:`teeth_key`'s definition (the case without its misalignment,
        deviations and operating point); the carried key equals the one the new case
        would make (tests/test_study_memos.py).
        """
        out = dataclasses.replace(self, **changes)
        if changes.keys() <= _NOT_TEETH:
            object.__setattr__(out, "_teeth_key", self.teeth_key())
        return out


#: the case's fields :meth:`Case.teeth_key` leaves out (no tooth depends on them)
_NOT_TEETH = frozenset({"misalignment", "deviations", "operating"})
#: tables of ``Case.extra`` no tooth depends on, left out of :meth:`Case.teeth_key`: the
#: rating's inputs and the FE level of the root stress (contact's ``[root_stress]``)
_NOT_TEETH_TABLES = frozenset({"rating", "root_stress"})


class TeethKey:
    """A case's teeth as a hashable memo key (:meth:`Case.teeth_key`): equal and hashed by
    ``text`` (the case's ``repr`` without misalignment, deviations and operating point;
    for one flank alone, the ``repr`` of what its solve reads:
    :func:`contact.utca.conjugate_map.flank_key`); ``case`` is that case, for the memo to
    compute from."""

    __slots__ = ("case", "text")

    def __init__(self, case: Case, text: str) -> None:
        self.case, self.text = case, text

    def __hash__(self) -> int:
        return hash(self.text)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TeethKey) and other.text == self.text


# ---------------------------------------------------------------------------- schema
# field → (unit, required, default); unit "deg" is converted to rad, "list" is a list of
# numbers, "str" a string, "mm"/"1" plain numbers
_BLANK_FIELDS = {
    "teeth": ("int", True, None),
    "face_width": ("mm", True, None),
    "outer_cone_distance": ("mm", True, None),
    "pitch_angle": ("deg", True, None),
    "face_angle": ("deg", True, None),
    "root_angle": ("deg", True, None),
    "pitch_apex": ("mm", False, 0.0),
    "face_apex": ("mm", False, 0.0),
    "root_apex": ("mm", False, 0.0),
    "outer_addendum": ("mm", True, None),
    "outer_dedendum": ("mm", True, None),
    "edge_break_radius": ("mm", False, 0.5),
}
_BLADE_FIELDS = {
    "point_radius": ("mm", True, None),
    "blade_angle": ("deg", True, None),
    "edge_radius": ("mm", False, 0.0),
    "point_width": ("mm", False, 0.0),
    "profile": ("str", False, "straight"),
    "profile_radius": ("mm", False, 0.0),
    "profile_reference_height": ("mm", False, 0.0),
    "toprem_angle": ("deg", False, 0.0),
    "toprem_height": ("mm", False, 0.0),
    "flankrem_angle": ("deg", False, 0.0),
    "flankrem_height": ("mm", False, 0.0),
}
#: blade placement in the head (face hobbing; written only where used)
_BLADE_PLACEMENT_FIELDS = {
    "blade_phase": ("deg", False, 0.0),
    "blade_offset_angle": ("deg", False, 0.0),
    "rake_angle": ("deg", False, 0.0),
    "hook_angle": ("deg", False, 0.0),
}
#: cutter-head fields of ``[<member>.cutter]`` beside its flank tables
_HEAD_FIELDS = {
    "blade_groups": ("int", False, 0),
    "cutter_radius": ("mm", False, 0.0),
}
_MACHINE_FIELDS = {
    "radial_setting": ("mm", True, None),
    "cradle_angle": ("deg", True, None),
    "swivel": ("deg", False, 0.0),
    "tilt": ("deg", False, 0.0),
    "machine_root_angle": ("deg", True, None),
    "machine_center_to_back": ("mm", False, 0.0),
    "sliding_base": ("mm", False, 0.0),
    "blank_offset": ("mm", False, 0.0),
    "ratio_of_roll": ("1", False, 0.0),
    "modified_roll": ("list", False, ()),
    "helical_motion": ("list", False, ()),
    "vertical_motion": ("list", False, ()),
}
_PAIR_FIELDS = {
    "shaft_angle": ("deg", True, None),
    "offset": ("mm", False, 0.0),
    "method": ("str", False, "FM"),
    "pinion_hand": ("str", True, None),
    "gear_hand": ("str", True, None),
    "drive_flank": ("str", False, "concave"),
}
_MISALIGNMENT_FIELDS = {
    "delta_E": ("mm", False, 0.0),
    "delta_P": ("mm", False, 0.0),
    "delta_G": ("mm", False, 0.0),
    "delta_Sigma": ("deg", False, 0.0),
}
#: the ``[operating]`` table: misalignment (into Case.misalignment) and OperatingPoint
_OPERATING_MISALIGNMENT_FIELDS = _MISALIGNMENT_FIELDS
_OPERATING_POINT_FIELDS = {
    "torque": ("list", False, OPERATING_DEFAULTS["torque"]),
    "pinion_speed": ("rpm", False, OPERATING_DEFAULTS["pinion_speed"]),
    "lubricant": ("str", False, OPERATING_DEFAULTS["lubricant"]),
    "temperature": ("degC", False, OPERATING_DEFAULTS["temperature"]),
    "roughness": ("um", False, OPERATING_DEFAULTS["roughness"]),
    "friction_model": ("str", False, None),
}
_DEVIATION_FIELDS = {
    "pinion": ("str", False, None),
    "gear": ("str", False, None),
}
#: blade fields of a cutter table typed in SpyGO's convention (``convention = "spygo"``)
_SPYGO_BLADE_SCHEMA = {k: _BLADE_FIELDS[k] for k in SPYGO_BLADE_FIELDS}
_MEMBER_KEYS = {"process", "blank", "cutter", "machine", "material"}
_TOP_KEYS = {"name", "source", "synthesised", "pair", "pinion", "gear", "misalignment",
             "operating", "deviations"}


def _table(parent: Mapping, key: str, path: str, required: bool = True) -> Mapping:
    if key not in parent:
        if required:
            raise InputError(f"{path}: missing table")
        return {}
    val = parent[key]
    if not isinstance(val, Mapping):
        raise InputError(f"{path}: must be a table, got {type(val).__name__}")
    return val


def _fields(table: Mapping, schema: dict, path: str) -> dict[str, Any]:
    known_fields(path, table, schema)
    out: dict[str, Any] = {}
    for key, (unit, required, default) in schema.items():
        where = f"{path}.{key}"
        if key not in table:
            if required:
                raise InputError(f"{where}: missing (required, unit {unit})")
            out[key] = default
            continue
        val = table[key]
        if unit == "str":
            if not isinstance(val, str):
                raise InputError(f"{where}: must be a string, got {val!r}")
            out[key] = val
        elif unit == "int":
            if isinstance(val, bool) or not isinstance(val, int):
                raise InputError(f"{where}: must be an integer, got {val!r}")
            out[key] = val
        elif unit == "list":
            if not isinstance(val, list) or any(
                    isinstance(v, bool) or not isinstance(v, (int, float)) for v in val):
                raise InputError(f"{where}: must be a list of numbers, got {val!r}")
            if not all(math.isfinite(v) for v in val):
                raise InputError(f"{where}: must be finite, got {val!r}")
            out[key] = tuple(float(v) for v in val)
        else:
            if isinstance(val, bool) or not isinstance(val, (int, float)):
                raise InputError(f"{where}: must be a number [{unit}], got {val!r}")
            if not math.isfinite(val):
                raise InputError(f"{where}: must be finite, got {val!r}")
            out[key] = float(val) * (_DEG if unit == "deg" else 1.0)
    return out


def _build(cls, kwargs: dict, path: str):
    try:
        return cls(**kwargs)
    except InputError as exc:
        raise InputError(f"{path}.{exc}") from None


def _member(raw: Mapping, name: str, hand: str) -> Member:
    known_fields(name, raw, sorted(_MEMBER_KEYS))
    process = raw.get("process")
    if process not in PROCESSES:
        raise InputError(f"{name}.process: must be one of {sorted(PROCESSES)}, got {process!r}")
    blank = _build(Blank, _fields(_table(raw, "blank", f"{name}.blank"), _BLANK_FIELDS,
                                  f"{name}.blank"), f"{name}.blank")
    cutter = _table(raw, "cutter", f"{name}.cutter")
    machine = _table(raw, "machine", f"{name}.machine")
    tools = {}
    for tab, where, extra in ((cutter, "cutter", set(_HEAD_FIELDS)), (machine, "machine", set())):
        known_fields(f"{name}.{where}", tab, [*FLANKS, *sorted(extra), "convention"])
    # the convention each summary is typed in (docs/machine.md); converted to ours below
    conv = {where: check_convention(f"{name}.{where}.convention",
                                    tab.get("convention", "ours"))
            for tab, where in ((cutter, "cutter"), (machine, "machine"))}
    head = _fields({k: v for k, v in cutter.items() if k in _HEAD_FIELDS}, _HEAD_FIELDS,
                   f"{name}.cutter")
    for where, value in conv.items():
        if value == "spygo" and head["blade_groups"] > 0:
            raise InputError(f"{name}.{where}.convention: 'spygo' summaries are face milling "
                             f"(blade_groups 0); give a face-hobbing member in 'ours'")
    try:
        kappa = indexing_ratio(head["blade_groups"], blank.teeth)
    except InputError as exc:
        raise InputError(f"{name}.cutter.{exc}") from None
    if head["cutter_radius"] < 0.0:
        raise InputError(f"{name}.cutter.cutter_radius: must be >= 0 mm (0: not given), got "
                         f"{head['cutter_radius']}")
    for flank, side in FLANKS.items():
        bpath = f"{name}.cutter.{flank}"
        spygo_blade = conv["cutter"] == "spygo"
        bschema = (_SPYGO_BLADE_SCHEMA if spygo_blade
                   else _BLADE_FIELDS | _BLADE_PLACEMENT_FIELDS)
        bkw = _fields(_table(cutter, flank, bpath), bschema, bpath)
        if bkw["profile"] not in PROFILE_TYPES:
            raise InputError(f"{bpath}.profile: must be one of {list(PROFILE_TYPES)}, got "
                             f"{bkw['profile']!r}")
        if spygo_blade:
            try:
                bkw = blade_from_spygo(bkw, side)
            except InputError as exc:
                raise InputError(f"{bpath}.{exc}") from None
        blade = _build(Blade, {"side": side, **bkw}, bpath)
        mpath = f"{name}.machine.{flank}"
        mkw = _fields(_table(machine, flank, mpath), _MACHINE_FIELDS, mpath)
        if conv["machine"] == "spygo":
            try:
                mkw = machine_from_spygo(mkw, name, hand)
            except InputError as exc:
                raise InputError(f"{mpath}.{exc}") from None
        settings = _build(MachineSettings,
                          {"process": process, **mkw, "indexing_ratio": kappa}, mpath)
        tools[flank] = FlankTool(blade, settings)
    mat = raw.get("material", DEFAULT_MATERIAL)
    if mat not in available_materials():
        raise InputError(f"{name}.material: must be one of {list(available_materials())} "
                         f"(geometry/core/data/materials.toml), got {mat!r}")
    return Member(name=name, hand=hand, process=process, blank=blank, **tools,
                  blade_groups=head["blade_groups"], cutter_radius=head["cutter_radius"],
                  material=mat)


def _check_method(method: str, pinion: Member, gear: Member) -> None:
    """Face hobbing needs a blade-group count on both members, face milling none."""
    for m in (pinion, gear):
        if method == "FH" and m.blade_groups < 1:
            raise InputError(f"{m.name}.cutter.blade_groups: must be an integer in [1, 50] "
                             f"for a face-hobbed pair (pair.method = 'FH'), got "
                             f"{m.blade_groups}")
        if method == "FM" and m.blade_groups != 0:
            raise InputError(f"{m.name}.cutter.blade_groups: must be 0 or absent for a "
                             f"face-milled pair (pair.method = 'FM'; set 'FH' for face "
                             f"hobbing), got {m.blade_groups}")
    if method == "FH" and pinion.blade_groups != gear.blade_groups:
        log.warning("FH pair with different blade groups (pinion %d, gear %d): the pinion is "
                    "conjugate to the gear only when both are cut with the same z0",
                    pinion.blade_groups, gear.blade_groups)


def _paths(obj: Any, prefix: str = "") -> set[str]:
    out = set()
    if isinstance(obj, Mapping):
        for k, v in obj.items():
            p = f"{prefix}.{k}" if prefix else str(k)
            out.add(p)
            out |= _paths(v, p)
    return out


def _deviation_files(raw: Mapping, base_dir: str | os.PathLike[str] | None,
                     ) -> DeviationFiles | None:
    if "deviations" not in raw:
        return None
    kw = _fields(_table(raw, "deviations", "deviations"), _DEVIATION_FIELDS, "deviations")
    base = Path.cwd() if base_dir is None else Path(base_dir)
    for key, val in kw.items():
        if val is not None:
            p = Path(val).expanduser()
            kw[key] = str((p if p.is_absolute() else base / p).resolve())
    return _build(DeviationFiles, kw, "deviations")


def _oil_file_beside_case(operating: OperatingPoint,
                          base_dir: str | os.PathLike[str] | None) -> OperatingPoint:
    """``operating.lubricant`` given as an oil file (a value with a directory separator or
    ending in ``.toml``) resolved against the case file's directory, as the ``[deviations]``
    files are: a case and its oil travel together, whatever the working directory. A bundled
    oil's name (``"75W90"``) is left as it is.

    Raises
    ------
    InputError
        ``operating.lubricant`` names an oil file that does not exist there.
    """
    oil = operating.lubricant
    if not isinstance(oil, str) or not (
            "/" in oil or "\\" in oil or oil.lower().endswith(".toml")):
        return operating
    p = Path(oil).expanduser()
    if not p.is_absolute():
        p = (Path.cwd() if base_dir is None else Path(base_dir)) / p
    if not p.is_file():
        raise InputError(f"operating.lubricant: no oil file at {str(p)!r} (a relative oil "
                         "path is read from the case file's directory); give a bundled oil "
                         "name or an existing oil TOML file")
    return dataclasses.replace(operating, lubricant=str(p.resolve()))


def case_from_dict(raw: Mapping[str, Any], *,
                   base_dir: str | os.PathLike[str] | None = None) -> Case:
    """Validate a parsed case mapping and build the :class:`Case`.

    Parameters
    ----------
    raw : mapping
        The parsed TOML document (degrees and mm, as in files).
    base_dir : path-like, optional
        Directory against which relative paths of the ``[deviations]`` table and an oil
        file given as ``[operating] lubricant`` are resolved (:func:`load_case` passes the
        case file's directory); default the current directory.

    Returns
    -------
    Case

    Raises
    ------
    InputError
        For a missing, unknown, mistyped or out-of-range field (the message names it by its
        dotted path, e.g. ``gear.blank.teeth``), inconsistent fields, or a ``[deviations]``
        file that does not exist (``deviations.pinion``, ``deviations.gear``).
    ModelUnavailableError
        For a ``pair.method`` that is reserved but not implemented (none today).
    """
    if not isinstance(raw, Mapping):
        raise InputError(f"case: must be a table, got {type(raw).__name__}")
    for key in ("name", "source"):
        if not isinstance(raw.get(key), str) or not raw.get(key).strip():
            raise InputError(f"{key}: required non-empty string, got {raw.get(key)!r}")
    synth = raw.get("synthesised", [])
    if not isinstance(synth, list) or not all(isinstance(s, str) for s in synth):
        raise InputError(f"synthesised: must be a list of field paths, got {synth!r}")
    known = _paths(raw)
    for s in synth:
        if s not in known:
            raise InputError(f"synthesised: {s!r} names no field of this case")
    pr = _fields(_table(raw, "pair", "pair"), _PAIR_FIELDS, "pair")
    if pr["method"] not in METHODS:
        raise InputError(f"pair.method: must be one of {sorted(METHODS)}, got {pr['method']!r}")
    if not METHODS[pr["method"]]:
        raise ModelUnavailableError(
            f"pair.method: {pr['method']!r} is reserved and not implemented; "
            f"available: {[m for m, ok in METHODS.items() if ok]}")
    if not 0 < pr["shaft_angle"] < math.pi:
        raise InputError(
            f"pair.shaft_angle: must be in (0, 180) deg, got {_fmt(pr['shaft_angle'] / _DEG)}")
    for key in ("pinion_hand", "gear_hand"):
        if pr[key] not in HANDS:
            raise InputError(f"pair.{key}: must be one of {sorted(HANDS)}, got {pr[key]!r}")
    if pr["pinion_hand"] == pr["gear_hand"]:
        raise InputError(
            f"pair.gear_hand: must be the opposite of pair.pinion_hand ({pr['pinion_hand']}) "
            "for an external bevel or hypoid pair")
    if pr["drive_flank"] not in FLANKS:
        raise InputError(
            f"pair.drive_flank: must be one of {list(FLANKS)} (the pinion flank that drives), "
            f"got {pr['drive_flank']!r}")
    pair = Pair(pr["shaft_angle"], pr["offset"], pr["method"], pr["drive_flank"])
    pinion = _member(_table(raw, "pinion", "pinion"), "pinion", pr["pinion_hand"])
    gear = _member(_table(raw, "gear", "gear"), "gear", pr["gear_hand"])
    if pinion.blank.teeth > gear.blank.teeth:
        raise InputError(
            f"pinion.blank.teeth: the pinion has more teeth ({pinion.blank.teeth}) than the "
            f"gear ({gear.blank.teeth}); the pinion is the member with fewer teeth — are the "
            "[pinion] and [gear] tables swapped?")
    _check_method(pr["method"], pinion, gear)
    mis, operating = operating_from_dict(raw)
    operating = _oil_file_beside_case(operating, base_dir)
    devs = _deviation_files(raw, base_dir)
    extra = {k: v for k, v in raw.items() if k not in _TOP_KEYS}
    if extra:
        log.info("case %s: tables %s kept unvalidated for other stages", raw["name"],
                 sorted(extra))
    return Case(name=raw["name"], source=raw["source"], pair=pair, pinion=pinion, gear=gear,
                misalignment=mis, synthesised=tuple(synth),
                extra=MappingProxyType(json.loads(json.dumps(extra, default=str))),
                deviations=devs, operating=operating)


def operating_from_dict(raw: Mapping[str, Any]) -> tuple[Misalignment, OperatingPoint]:
    """The misalignment and operating point of a parsed case (its ``[operating]`` table).

    Parameters
    ----------
    raw : mapping
        The parsed case (or any mapping with an ``operating`` table): ``torque`` [N·m],
        ``delta_E``, ``delta_P``, ``delta_G`` [mm], ``delta_Sigma`` [deg], ``pinion_speed``
        [rpm], ``lubricant``, ``temperature`` [degC], ``roughness`` [µm],
        ``friction_model``; every field optional (:data:`OPERATING_DEFAULTS`, aligned). The
        older top-level ``[misalignment]`` table (the same four ``delta_*`` fields) is still
        read when ``[operating]`` gives no misalignment.

    Returns
    -------
    (geometry.pair.assembly.Misalignment, OperatingPoint)
        ΔΣ converted to rad.

    Raises
    ------
    InputError
        An unknown, mistyped or out-of-range field (named ``operating.<field>``), or a
        misalignment given both in ``[operating]`` and in ``[misalignment]``.
    """
    table = dict(_table(raw, "operating", "operating", False))
    mis_keys = [k for k in _OPERATING_MISALIGNMENT_FIELDS if k in table]
    mis_raw = {k: table.pop(k) for k in mis_keys}
    where = "operating"
    if "misalignment" in raw:
        if mis_keys:
            raise InputError(f"misalignment: give the misalignment once, in [operating] "
                             f"({', '.join(mis_keys)} there); [misalignment] is its old "
                             "place")
        mis_raw = dict(_table(raw, "misalignment", "misalignment", False))
        where = "misalignment"
    unknown = sorted(set(table) - set(_OPERATING_POINT_FIELDS))
    if unknown:
        accepted = [*_OPERATING_POINT_FIELDS, *_OPERATING_MISALIGNMENT_FIELDS]
        raise InputError(f"operating.{unknown[0]}: unknown field; accepted: "
                         f"{', '.join(accepted)}")
    mis = _build(Misalignment, _fields(mis_raw, _OPERATING_MISALIGNMENT_FIELDS, where), where)
    if "torque" in table and isinstance(table["torque"], (int, float)):
        table["torque"] = [table["torque"]]
    kw = _fields(table, _OPERATING_POINT_FIELDS, "operating")
    return mis, _build(OperatingPoint, kw, "operating")


def load_case(path: str | os.PathLike[str]) -> Case:
    """Read and validate a TOML case file.

    Parameters
    ----------
    path : path-like
        A ``cases/*.toml`` file (schema in ``docs/cases.md``).

    Returns
    -------
    Case
        Angles converted to rad, lengths in mm; the paths of a ``[deviations]`` table
        resolved against the file's directory.

    Raises
    ------
    InputError
        If ``path`` is no path, the file is missing, unreadable, not UTF-8 text, not valid
        TOML, a basic design file (which ``ltca synthesize`` makes a case of), or a field is
        invalid (named by its path).
    ModelUnavailableError
        For a ``pair.method`` that is reserved but not implemented (none today).
    """
    if isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise InputError("path: must be the path of a case file (str or os.PathLike), got "
                         f"{type(path).__name__} {path!r}")
    p = Path(path)
    data = read_toml(p, "case file")
    if "pair" not in data and "design" in data and "pinion" not in data:
        # basic design data (ISO 23509 input, targets): no machine settings to analyse yet
        raise InputError(f"case file {str(p)!r} is a basic design file ([design] without "
                         "[pair], [pinion], [gear]); make a case of it first: ltca "
                         f"synthesize {str(p)!r} -o CASE.toml (or geometry.synthesis."
                         "synthesize(load_basic(path))), then use that case")
    return case_from_dict(data, base_dir=p.resolve().parent)


# ---------------------------------------------------------------------------- writing
def _values(obj, schema: dict) -> dict[str, Any]:
    out = {}
    for key, (unit, _required, _default) in schema.items():
        val = getattr(obj, key)
        if unit == "deg":
            val = val / _DEG
        elif unit == "list":
            val = list(val)
        out[key] = val
    return out


def _case_to_dict(case: Case) -> dict[str, Any]:
    pair = case.pair
    doc: dict[str, Any] = {"name": case.name, "source": case.source,
                           "synthesised": list(case.synthesised)}
    doc["pair"] = {"shaft_angle": pair.shaft_angle / _DEG, "offset": pair.offset,
                   "method": pair.method, "pinion_hand": case.pinion.hand,
                   "gear_hand": case.gear.hand, "drive_flank": pair.drive_flank}
    for m in (case.pinion, case.gear):
        placed = m.blade_groups > 0 or any(m.flank(f).blade.placed for f in FLANKS)
        blade_schema = _BLADE_FIELDS | (_BLADE_PLACEMENT_FIELDS if placed else {})
        cutter: dict[str, Any] = {}
        if m.blade_groups > 0:
            cutter["blade_groups"] = m.blade_groups
        if m.cutter_radius > 0.0:
            cutter["cutter_radius"] = m.cutter_radius
        cutter |= {f: _values(m.flank(f).blade, blade_schema) for f in FLANKS}
        doc[m.name] = {
            "process": m.process,
            **({"material": m.material} if m.material != DEFAULT_MATERIAL else {}),
            "blank": _values(m.blank, _BLANK_FIELDS),
            "cutter": cutter,
            "machine": {f: _values(m.flank(f).machine, _MACHINE_FIELDS) for f in FLANKS},
        }
    doc["operating"] = operating_to_dict(case.misalignment, case.operating)
    for k, v in case.extra.items():
        doc[k] = v
    if case.deviations is not None:
        doc["deviations"] = {k: getattr(case.deviations, k) for k in _DEVIATION_FIELDS
                             if getattr(case.deviations, k) is not None}
    return doc


def operating_to_dict(misalignment: Misalignment, operating: OperatingPoint,
                      ) -> dict[str, Any]:
    """The ``[operating]`` table of a case (units of a case file: ΔΣ in deg); inverse of
    :func:`operating_from_dict`."""
    op = _values(operating, _OPERATING_POINT_FIELDS)
    if op["friction_model"] is None:  # the efficiency stage's default: nothing to write
        del op["friction_model"]
    return {"torque": op.pop("torque"), **_values(misalignment, _MISALIGNMENT_FIELDS), **op}
