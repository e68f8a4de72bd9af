"""Case ↔ REXS bevel stage: which case field goes into which REXS attribute, both ways.

The tables below are the mapping (docs/exchange.md prints them): each row is a case field
(its key in the case file's table), the REXS attribute (as the attribute database spells
it), its unit and value type. Fields REXS has no attribute for are written as ``custom_``
attributes (REXS's place for them), so that case → REXS → case gives the same case to the
last bit (floating-point values are written with their shortest round-trip form).

Component layout of a written stage (ids): 1 ``bevel_stage``; 2, 3 ``bevel_gear`` pinion
and gear; 4, 5 their ``bevel_stage_gear_data``; per member (base 10 pinion, 20 gear) the
concave and convex ``bevel_gear_flank`` (+1, +2), their ``bevel_gear_tool`` (+3, +4) and
``bevel_gear_manufacturing_settings`` (+5, +6). Relations ``stage``, ``stage_gear_data``,
``flank`` (roles left/right, :func:`flank_side`) and one ``manufacturing_step`` (order 1)
per flank. The torques of ``[operating]`` form a ``load_spectrum``, one load case per
torque carrying the pinion's ``bevel_stage_gear_data`` ``torque``.

Public
------
case_to_model            a case (as its parsed case-file mapping) → REXS Model
model_to_case_dict       a REXS Model with manufacturing settings → case-file mapping
model_to_basic_dict      a REXS Model with blank data only → basic design file mapping
has_manufacturing        whether a model's stage carries manufacturing settings
flank_side               "left"/"right" of a member's concave/convex flank
"""

from __future__ import annotations

import json
import logging
import tomllib
from datetime import UTC, datetime
from typing import Any

from contact.exchange.rexs.database import load_database
from contact.exchange.rexs.model import Component, LoadCase, LoadSpectrum, Model, Ref, Relation
from geometry import __version__
from geometry.core.errors import InputError
from geometry.core.toml_files import dump_toml

__all__ = ["case_to_model", "flank_side", "has_manufacturing", "model_to_basic_dict",
           "model_to_case_dict"]

log = logging.getLogger(__name__)

APPLICATION_ID = "hypoid-ltca"
FLANKS = ("concave", "convex")
MEMBERS = ("pinion", "gear")
#: component ids of the written layout
STAGE_ID, GEAR_IDS, DATA_IDS = 1, {"pinion": 2, "gear": 3}, {"pinion": 4, "gear": 5}
MEMBER_BASE = {"pinion": 10, "gear": 20}

# (case key, REXS attribute, unit, value type); value type "floating_point" unless given
#: [<member>.blank] → bevel_gear
BLANK = (
    ("teeth", "number_of_teeth", "none", "integer"),
    ("face_width", "face_width", "mm", "floating_point"),
    ("outer_cone_distance", "outer_cone_distance", "mm", "floating_point"),
    ("pitch_angle", "pitch_angle", "deg", "floating_point"),
    ("face_angle", "face_angle", "deg", "floating_point"),
    ("root_angle", "root_angle", "deg", "floating_point"),
    ("pitch_apex", "pitch_apex_beyond_crossing_point", "mm", "floating_point"),
    ("face_apex", "face_apex_beyond_crossing_point", "mm", "floating_point"),
    ("root_apex", "root_apex_beyond_crossing_point", "mm", "floating_point"),
    ("outer_addendum", "outer_addendum", "mm", "floating_point"),
    ("outer_dedendum", "outer_dedendum", "mm", "floating_point"),
    ("edge_break_radius", "custom_edge_break_radius", "mm", "floating_point"),
)
#: [<member>.cutter.<flank>] → bevel_gear_tool
BLADE = (
    ("point_radius", "blade_point_radius", "mm", "floating_point"),
    ("blade_angle", "blade_pressure_angle", "deg", "floating_point"),
    ("edge_radius", "tool_edge_radius_bevel_gear_tool", "mm", "floating_point"),
    ("point_width", "custom_point_width", "mm", "floating_point"),
    ("profile", "custom_blade_profile", "none", "string"),
    ("profile_radius", "custom_profile_radius", "mm", "floating_point"),
    ("profile_reference_height", "custom_profile_reference_height", "mm", "floating_point"),
    ("toprem_angle", "custom_toprem_angle", "deg", "floating_point"),
    ("toprem_height", "custom_toprem_height", "mm", "floating_point"),
    ("flankrem_angle", "custom_flankrem_angle", "deg", "floating_point"),
    ("flankrem_height", "custom_flankrem_height", "mm", "floating_point"),
    ("blade_phase", "custom_blade_phase", "deg", "floating_point"),
    ("blade_offset_angle", "custom_blade_offset_angle", "deg", "floating_point"),
    ("rake_angle", "custom_rake_angle", "deg", "floating_point"),
    ("hook_angle", "custom_hook_angle", "deg", "floating_point"),
)
#: [<member>.machine.<flank>] → bevel_gear_manufacturing_settings
MACHINE = (
    ("radial_setting", "radial_distance", "mm", "floating_point"),
    ("cradle_angle", "center_roll_position", "deg", "floating_point"),
    ("swivel", "cutter_swivel", "deg", "floating_point"),
    ("tilt", "cutter_tilt", "deg", "floating_point"),
    ("machine_root_angle", "machine_root_angle", "deg", "floating_point"),
    ("machine_center_to_back", "machine_center_to_crossing_point", "mm", "floating_point"),
    ("sliding_base", "sliding_base", "mm", "floating_point"),
    ("blank_offset", "work_offset", "mm", "floating_point"),
    ("ratio_of_roll", "ratio_of_roll", "none", "floating_point"),
    ("modified_roll", "modified_roll_coefficients", "none", "floating_point_array"),
    ("helical_motion", "helical_motion_coefficients", "none", "floating_point_array"),
    ("vertical_motion", "vertical_motion_coefficients", "none", "floating_point_array"),
)
#: [operating] misalignment → bevel_stage (assembly deviations ΔV, ΔH, ΔJ, ΔΣ)
MISALIGNMENT = (
    ("delta_E", "deviation_of_offset", "mm", "floating_point"),
    ("delta_P", "axial_displacement_pinion", "mm", "floating_point"),
    ("delta_G", "axial_displacement_gear", "mm", "floating_point"),
    ("delta_Sigma", "deviation_of_shaft_angle", "deg", "floating_point"),
)
#: [operating] fields REXS has no attribute for → bevel_stage
OPERATING_CUSTOM = (
    ("lubricant", "custom_lubricant", "none", "string"),
    ("roughness", "custom_roughness", "mum", "floating_point"),
    ("friction_model", "custom_friction_model", "none", "string"),
)
#: [design] (ISO 23509 inputs) → bevel_stage / bevel_gear, where the version has them:
#: (design key, component: "stage" / "pinion" / "gear", attribute per version, unit, type)
DESIGN = (
    ("Sigma", "stage", {"1.7": "shaft_angle", "2.0.0": "shaft_angle"}, "deg"),
    ("a", "stage", {"1.7": "hypoid_offset", "2.0.0": "hypoid_offset"}, "mm"),
    ("rc0", "stage", {"1.7": "cutter_radius", "2.0.0": "cutter_radius"}, "mm"),
    ("alpha_dD", "stage", {"1.7": "nominal_design_pressure_angle_drive",
                           "2.0.0": "nominal_design_pressure_angle_on_drive_side"}, "deg"),
    ("alpha_dC", "stage", {"1.7": "nominal_design_pressure_angle_coast",
                           "2.0.0": "nominal_design_pressure_angle_on_coast_side"}, "deg"),
    ("f_alim", "stage", {"2.0.0": "influence_factor_of_limit_pressure_angle"}, "none"),
    ("c_ham", "stage", {"2.0.0": "mean_addendum_factor_of_wheel"}, "none"),
    ("k_d", "stage", {"2.0.0": "depth_factor"}, "none"),
    ("k_c", "stage", {"2.0.0": "clearance_factor"}, "none"),
    ("k_t", "stage", {"2.0.0": "circular_thickness_factor"}, "none"),
    ("de2", "gear", {"1.7": "outer_pitch_diameter", "2.0.0": "outer_pitch_diameter"}, "mm"),
    ("b2", "gear", {"1.7": "face_width", "2.0.0": "face_width"}, "mm"),
    ("theta_a2", "gear", {"2.0.0": "addendum_angle"}, "deg"),
    ("theta_f2", "gear", {"2.0.0": "dedendum_angle"}, "deg"),
)
#: design.backlash (its kind) → where its value goes: (component, attribute per version)
BACKLASH = {
    "j_en": ("stage", {"2.0.0": "outer_normal_backlash"}),
    "j_mn": ("stage", {"2.0.0": "mean_normal_backlash"}),
    "j_et2": ("gear", {"2.0.0": "outer_transverse_backlash"}),
}
#: the basic design's fields an import needs: (design key, component, attribute)
BASIC_NEEDS = (("Sigma", "stage", "shaft_angle"), ("a", "stage", "hypoid_offset"),
               ("de2", "gear", "outer_pitch_diameter"), ("b2", "gear", "face_width"),
               ("beta_m", "spiral", "mean_spiral_angle"), ("rc0", "stage", "cutter_radius"),
               ("f_alim", "stage", "influence_factor_of_limit_pressure_angle"),
               ("theta_a2", "gear", "addendum_angle"), ("theta_f2", "gear", "dedendum_angle"),
               ("backlash_value", "gear", "outer_transverse_backlash"))
#: custom attributes of the stage for what the case holds beyond REXS
STAGE_CUSTOM = ("custom_cutting_method", "custom_drive_flank", "custom_case_name",
                "custom_source", "custom_synthesised", "custom_ltca_tables",
                "custom_deviation_file_pinion", "custom_deviation_file_gear",
                "custom_lubricant", "custom_roughness", "custom_friction_model")


def flank_side(hand: str, flank: str) -> str:
    """The REXS ``flank`` relation role (``"left"``/``"right"``) of a member's flank.

    Left and right as for cylindrical gears (ISO 21771), seen by an observer at the heel
    looking towards the apex with the tooth tip up. In the machine frames of
    docs/machine.md the cutter centre of a right-hand member lies on the left of the tooth
    trace seen so, and the concave flank faces it: a right-hand member's concave flank is
    its left flank, a left-hand member's its right flank. The written flanks also name
    themselves (``custom_flank_curvature``), which the importer takes over this rule.

    Parameters
    ----------
    hand : {"left", "right"}
    flank : {"concave", "convex"}
    """
    concave_left = hand == "right"
    return "left" if (flank == "concave") == concave_left else "right"


def _now() -> str:
    return datetime.now(UTC).replace(microsecond=0).isoformat()


def _put(comp: Component, attr: str, value: Any, unit: str, vtype: str, db) -> None:
    """Add an attribute, leaving out a value outside the database's range that equals the
    case's default (0 blade groups, a zero edge radius: "not given" in REXS)."""
    if vtype == "floating_point_array" and not value:
        return
    if not attr.startswith("custom_") and vtype in ("floating_point", "integer"):
        spec = db.attributes[attr]
        if not spec.in_range(float(value)) and float(value) == 0.0:
            return
    comp.add(attr, value, unit, vtype)


def case_to_model(doc: dict[str, Any], version: str = "2.0.0") -> Model:
    """The REXS model of a case's bevel stage.

    Parameters
    ----------
    doc : mapping
        The case as its parsed case file (``tomllib.loads(case.to_toml())``): degrees, mm.
    version : {"1.7", "2.0.0"}
        REXS version; names follow its attribute database.

    Returns
    -------
    Model
        Stage, blanks, flanks, tools and manufacturing settings of both members and both
        flanks, the operating point (one load case per torque), and what REXS lacks in
        ``custom_`` attributes (docs/exchange.md).

    Raises
    ------
    InputError
        An unsupported version.

    Source: FVA REXS attribute database of ``version`` (data/README.md).
    """
    db = load_database(version)
    pair, op = doc["pair"], doc.get("operating", {})
    model = Model(version=version, application_id=APPLICATION_ID,
                  application_version=__version__, date=_now())
    stage = Component(STAGE_ID, "bevel_stage", doc["name"])
    _put(stage, "shaft_angle", pair["shaft_angle"], "deg", "floating_point", db)
    stage.add("hypoid_offset", pair["offset"], "mm")
    gear_cutter = doc["gear"]["cutter"]
    _put(stage, "cutter_radius", gear_cutter.get("cutter_radius", 0.0), "mm",
         "floating_point", db)
    _put(stage, "number_of_blade_groups", gear_cutter.get("blade_groups", 0), "none",
         "integer", db)
    for key, attr, unit, vt in MISALIGNMENT:
        stage.add(attr, op.get(key, 0.0), unit, vt)
    if "temperature" in op:
        stage.add("temperature_lubricant", op["temperature"], "C")
    for key, attr, unit, vt in OPERATING_CUSTOM:
        if key in op:
            stage.add(attr, op[key], unit, vt)
    stage.add("custom_cutting_method", pair["method"], "none", "string")
    stage.add("custom_drive_flank", pair["drive_flank"], "none", "string")
    stage.add("custom_case_name", doc["name"], "none", "string")
    stage.add("custom_source", doc["source"], "none", "string")
    stage.add("custom_synthesised", json.dumps(doc.get("synthesised", [])), "none", "string")
    known = {"name", "source", "synthesised", "pair", "pinion", "gear", "operating",
             "deviations"}
    extra = {k: v for k, v in doc.items() if k not in known}
    if extra:
        stage.add("custom_ltca_tables", dump_toml(extra), "none", "string")
    for member, path in (doc.get("deviations") or {}).items():
        stage.add(f"custom_deviation_file_{member}", path, "none", "string")
    design = doc.get("design") if isinstance(doc.get("design"), dict) else {}
    for key, where, names, unit in DESIGN:
        if where == "stage" and key in design and version in names \
                and stage.get(names[version]) is None:
            spec = db.attributes[names[version]]
            if spec.in_range(float(design[key])):
                stage.add(names[version], design[key], unit)
            else:  # f_alim = 0 or 1 (ISO 23509's usual values) lie outside the
                # database's open range (0, 1): the value travels in custom_ltca_tables
                log.info("design.%s = %g: outside the REXS %s range %s of %s, not written "
                         "as that attribute", key, design[key], version, spec.range_text(),
                         spec.id)
    kind = BACKLASH.get(design.get("backlash", ""))
    if kind is not None and kind[0] == "stage" and version in kind[1] \
            and "backlash_value" in design:
        stage.add(kind[1][version], design["backlash_value"], "mm")
    if "method" in design and db.has("bevel_stage", "calculation_method_iso_23509_2025"):
        stage.add("calculation_method_iso_23509_2025", str(design["method"]), "none", "enum")
    model.components.append(stage)
    model.relations.append(Relation(1, "stage", [
        Ref(STAGE_ID, "stage", "bevel_stage"), Ref(GEAR_IDS["pinion"], "gear_1", "bevel_gear"),
        Ref(GEAR_IDS["gear"], "gear_2", "bevel_gear")]))
    rel_id = 2
    for name in MEMBERS:
        rel_id = _member(model, doc, name, db, design, rel_id)
    model.load_spectrum = LoadSpectrum(1, [
        LoadCase(i + 1, [_torque_data(t)]) for i, t in enumerate(op.get("torque", []))])
    if not model.load_spectrum.load_cases:
        model.load_spectrum = None
    return model


def _torque_data(torque: float) -> Component:
    comp = Component(DATA_IDS["pinion"], "bevel_stage_gear_data")
    comp.add("torque", float(torque), "N m")
    return comp


def _member(model: Model, doc: dict, name: str, db, design: dict, rel_id: int) -> int:
    m, pair, op = doc[name], doc["pair"], doc.get("operating", {})
    hand = pair[f"{name}_hand"]
    gear = Component(GEAR_IDS[name], "bevel_gear", name)
    for key, attr, unit, vt in BLANK:
        _put(gear, attr, m["blank"][key], unit, vt, db)
    gear.add("spiral_angle_pitch_direction", hand, "none", "enum")
    gear.add("custom_process", m["process"], "none", "string")
    # completing (both flanks cut in one setting: the same machine settings) or single
    # side; the case says it by its settings, REXS not at all: informational, not read
    same = m["machine"]["concave"] == m["machine"]["convex"]
    gear.add("custom_cutting_cycle", "completing" if same else "single_side", "none",
             "string")
    if "material" in m:
        gear.add("custom_material", m["material"], "none", "string")
    if name == "pinion":
        if "pinion_speed" in op:
            gear.add("rotational_speed", op["pinion_speed"], "1 / min")
        if "beta_m" in design and design.get("method") == 1:
            gear.add("mean_spiral_angle", design["beta_m"], "deg")
    elif "beta_m" in design and design.get("method") == 0:
        gear.add("mean_spiral_angle", design["beta_m"], "deg")
    if name == "gear" and "de2" in design:
        gear.add("outer_pitch_diameter", design["de2"], "mm")
    if db.has("bevel_gear", "addendum_angle"):  # REXS 2.0.0: the blank's θ_a, θ_f
        b = m["blank"]
        own = name == "gear" and "theta_a2" in design and "theta_f2" in design
        gear.add("addendum_angle", design["theta_a2"] if own
                 else b["face_angle"] - b["pitch_angle"], "deg")
        gear.add("dedendum_angle", design["theta_f2"] if own
                 else b["pitch_angle"] - b["root_angle"], "deg")
    kind = BACKLASH.get(design.get("backlash", ""))
    if name == "gear" and kind is not None and kind[0] == "gear" \
            and db.version in kind[1] and "backlash_value" in design:
        gear.add(kind[1][db.version], design["backlash_value"], "mm")
    model.components.append(gear)
    data = Component(DATA_IDS[name], "bevel_stage_gear_data", f"{name} stage data")
    data.add("is_driving_gear", name == "pinion", "none", "boolean")
    drive = pair["drive_flank"] if name == "pinion" else \
        FLANKS[1 - FLANKS.index(pair["drive_flank"])]
    data.add("loaded_tooth_flank", flank_side(hand, drive), "none", "enum")
    model.components.append(data)
    model.relations.append(Relation(rel_id, "stage_gear_data", [
        Ref(STAGE_ID, "stage", "bevel_stage"), Ref(gear.id, "gear", "bevel_gear"),
        Ref(data.id, "stage_gear_data", "bevel_stage_gear_data")]))
    rel_id += 1
    base = MEMBER_BASE[name]
    flank_ids = {}
    for i, flank in enumerate(FLANKS):
        fid, tid, sid = base + 1 + i, base + 3 + i, base + 5 + i
        flank_ids[flank] = fid
        fl = Component(fid, "bevel_gear_flank", f"{name} {flank}")
        fl.add("custom_flank_curvature", flank, "none", "string")
        tool = Component(tid, "bevel_gear_tool", f"{name} {flank} blade")
        blade = m["cutter"][flank]
        for key, attr, unit, vt in BLADE:
            if key in blade:
                _put(tool, attr, blade[key], unit, vt, db)
        _put(tool, "number_of_blade_groups_bevel_gear_tool", m["cutter"].get(
            "blade_groups", 0), "none", "integer", db)
        if m["cutter"].get("cutter_radius", 0.0) > 0.0:
            tool.add("custom_cutter_radius", m["cutter"]["cutter_radius"], "mm")
        settings = Component(sid, "bevel_gear_manufacturing_settings",
                             f"{name} {flank} machine")
        for key, attr, unit, vt in MACHINE:
            _put(settings, attr, m["machine"][flank][key], unit, vt, db)
        model.components += [fl, tool, settings]
    model.relations.append(Relation(rel_id, "flank", [
        Ref(gear.id, "gear", "bevel_gear"),
        *sorted((Ref(fid, flank_side(hand, f), "bevel_gear_flank")
                 for f, fid in flank_ids.items()), key=lambda r: r.role)]))
    rel_id += 1
    for i in range(len(FLANKS)):
        model.relations.append(Relation(rel_id, "manufacturing_step", [
            Ref(base + 1 + i, "workpiece", "bevel_gear_flank"),
            Ref(base + 3 + i, "tool", "bevel_gear_tool"),
            Ref(base + 5 + i, "manufacturing_settings", "bevel_gear_manufacturing_settings")],
            order=1))
        rel_id += 1
    return rel_id


# ------------------------------------------------------------------------------ import
class _Reader:
    """Typed access to a model's components, every refusal naming component, attribute and
    id; ``origin`` records which REXS attribute each case field came from."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.origin: dict[str, str] = {}

    def get(self, comp: Component, attr: str, kind: str, field: str | None = None,
            default: Any = ..., names: tuple[str, ...] = ()) -> Any:
        for a in (attr, *names):
            found = comp.get(a)
            if found is not None:
                attr = a
                break
        else:
            if default is ...:
                raise InputError(f"REXS {comp.where()}: missing attribute {attr}, needed "
                                 f"for the case field {field or attr}")
            if field is not None:
                self.origin.setdefault(field, f"{comp.where()}, attribute {attr} (not given)")
            return default
        if field is not None:
            self.origin[field] = f"{comp.where()}, attribute {attr}"
        value = found.value
        where = f"REXS {comp.where()}, attribute {attr}"
        try:
            if kind == "float":
                if isinstance(value, bool):
                    raise ValueError
                return float(value)
            if kind == "int":
                if isinstance(value, bool) or float(value) != int(float(value)):
                    raise ValueError
                return int(float(value))
            if kind == "list":
                if not isinstance(value, list):
                    raise ValueError
                return [float(v) for v in value]
            return str(value)
        except (TypeError, ValueError):
            raise InputError(f"{where}: {value!r} is not a {kind}") from None

    def related(self, type_: str, role: str, cid: int) -> list[Relation]:
        return [r for r in self.model.relations_of(type_) if r.component(role) == cid]


def _stage(model: Model) -> tuple[Component, Component, Component]:
    """The one bevel stage and its two gears (pinion: the fewer teeth)."""
    stages = model.of_type("bevel_stage")
    if len(stages) != 1:
        raise InputError(f"REXS file: holds {len(stages)} bevel_stage components "
                         f"{[s.id for s in stages]}; import takes a file with exactly one")
    stage = stages[0]
    rel = [r for r in model.relations_of("stage") if r.component("stage") == stage.id]
    if len(rel) != 1:
        raise InputError(f"REXS {stage.where()}: needs exactly one 'stage' relation naming "
                         f"its gear_1 and gear_2, found {len(rel)}")
    for role in ("gear_1", "gear_2"):
        if rel[0].component(role) is None:
            raise InputError(f"REXS relation stage id {rel[0].id}: no {role} of "
                             f"{stage.where()}")
    g1, g2 = (model.component(rel[0].component(r)) for r in ("gear_1", "gear_2"))
    for g in (g1, g2):
        if g.type != "bevel_gear":
            raise InputError(f"REXS {g.where()}: the stage's gear must be a bevel_gear")
    z = [_Reader(model).get(g, "number_of_teeth", "int") for g in (g1, g2)]
    return (stage, g1, g2) if z[0] <= z[1] else (stage, g2, g1)


def has_manufacturing(model: Model) -> bool:
    """Whether the model's bevel stage has manufacturing steps (a case can be made of it);
    else only blank data (a basic design file can)."""
    return bool(model.relations_of("manufacturing_step"))


def _flanks(rd: _Reader, gear: Component, hand: str) -> dict[str, tuple[Component, ...]]:
    """flank name → (flank, tool, settings) components of a member."""
    rels = rd.related("flank", "gear", gear.id)
    if len(rels) != 1:
        raise InputError(f"REXS {gear.where()}: needs one 'flank' relation with its left and "
                         f"right bevel_gear_flank, found {len(rels)}")
    out = {}
    for role in ("left", "right"):
        fid = rels[0].component(role)
        if fid is None:
            raise InputError(f"REXS relation flank id {rels[0].id}: no {role} flank of "
                             f"{gear.where()}")
        fl = rd.model.component(fid)
        named = rd.get(fl, "custom_flank_curvature", "str", default=None)
        flank = named if named is not None else next(
            f for f in FLANKS if flank_side(hand, f) == role)
        if flank not in FLANKS or flank in out:
            raise InputError(f"REXS {fl.where()}, attribute custom_flank_curvature: "
                             f"{named!r} must name the concave or the convex flank once")
        steps = rd.related("manufacturing_step", "workpiece", fid)
        if len(steps) != 1:
            raise InputError(f"REXS {fl.where()}: needs exactly one manufacturing_step "
                             f"(bevel_gear_tool and manufacturing settings), found "
                             f"{len(steps)}")
        tool = rd.model.component(steps[0].component("tool") or -1)
        settings = rd.model.component(steps[0].component("manufacturing_settings") or -1)
        out[flank] = (fl, tool, settings)
    return out


def _hand(rd: _Reader, gear: Component) -> str:
    hand = rd.get(gear, "spiral_angle_pitch_direction", "str")
    if hand not in ("left", "right"):
        raise InputError(f"REXS {gear.where()}, attribute spiral_angle_pitch_direction: "
                         f"must be 'left' or 'right', got {hand!r}")
    return hand


def _member_dict(rd: _Reader, gear: Component, name: str, hand: str,
                 stage_z0: int = 0) -> tuple[dict, int, float]:
    blank = {key: rd.get(gear, attr, "int" if vt == "integer" else "float",
                         f"{name}.blank.{key}", default=(... if key in (
                             "teeth", "face_width", "outer_cone_distance", "pitch_angle",
                             "face_angle", "root_angle", "outer_addendum",
                             "outer_dedendum") else None))
             for key, attr, unit, vt in BLANK}
    blank = {k: v for k, v in blank.items() if v is not None}
    process = rd.get(gear, "custom_process", "str", f"{name}.process", default=None)
    flanks = _flanks(rd, gear, hand)
    cutter: dict[str, Any] = {}
    machine: dict[str, Any] = {}
    z0s, radii = set(), set()
    for flank, (_fl, tool, settings) in flanks.items():
        blade = {}
        for key, attr, _unit, vt in BLADE:
            kind = {"string": "str"}.get(vt, "float")
            v = rd.get(tool, attr, kind, f"{name}.cutter.{flank}.{key}",
                       default=... if key in ("point_radius", "blade_angle") else None)
            if v is not None:
                blade[key] = v
        cutter[flank] = blade
        z0s.add(rd.get(tool, "number_of_blade_groups_bevel_gear_tool", "int",
                       f"{name}.cutter.blade_groups", default=stage_z0))
        radii.add(rd.get(tool, "custom_cutter_radius", "float",
                         f"{name}.cutter.cutter_radius", default=0.0))
        ms = {}
        for key, attr, _unit, vt in MACHINE:
            kind = "list" if vt == "floating_point_array" else "float"
            required = key in ("radial_setting", "cradle_angle", "machine_root_angle")
            v = rd.get(settings, attr, kind, f"{name}.machine.{flank}.{key}",
                       default=... if required else ([] if kind == "list" else 0.0))
            ms[key] = v
        machine[flank] = ms
    if len(z0s) != 1:
        t = flanks["convex"][1]
        raise InputError(f"REXS {t.where()}, attribute number_of_blade_groups_bevel_gear_tool:"
                         f" the two flanks' tools of the {name} give different blade groups "
                         f"{sorted(z0s)}")
    if len(radii) != 1:
        t = flanks["convex"][1]
        raise InputError(f"REXS {t.where()}, attribute custom_cutter_radius: the two flanks' "
                         f"tools of the {name} give different cutter radii {sorted(radii)}")
    z0, rc = z0s.pop(), radii.pop()
    if z0 > 0:
        cutter["blade_groups"] = z0
    if rc > 0.0:
        cutter["cutter_radius"] = rc
    if process is None:  # REXS has no Generate/Formate switch: a ratio of roll generates
        process = "Generate" if any(machine[f]["ratio_of_roll"] > 0 for f in FLANKS) \
            else "Formate"
    out = {"process": process, "blank": blank,
           "cutter": {**{k: v for k, v in cutter.items() if k not in FLANKS},
                      **{f: cutter[f] for f in FLANKS}},
           "machine": machine}
    material = rd.get(gear, "custom_material", "str", f"{name}.material", default=None)
    if material is not None:
        out["material"] = material
    return out, z0, rc


def model_to_case_dict(model: Model) -> tuple[dict[str, Any], dict[str, str]]:
    """The case-file mapping of a REXS bevel stage with manufacturing settings.

    Parameters
    ----------
    model : Model
        Read and validated (:func:`contact.exchange.rexs.validate.check_text`).

    Returns
    -------
    (dict, dict)
        The case as a parsed case file (degrees, mm; :func:`geometry.case.case_from_dict`
        validates it), and for each case field path the REXS component, id and attribute
        it came from (for messages).

    Raises
    ------
    InputError
        A missing or inconsistent item, named by component type, id and attribute.
    """
    rd = _Reader(model)
    stage, pinion, gear = _stage(model)
    hands = {"pinion": _hand(rd, pinion), "gear": _hand(rd, gear)}
    members, z0 = {}, {}
    # a tool without its own blade groups takes the stage's (z0 ≥ 1: face hobbing)
    stage_z0 = rd.get(stage, "number_of_blade_groups", "int", default=0)
    for name, comp in (("pinion", pinion), ("gear", gear)):
        members[name], z0[name], _rc = _member_dict(rd, comp, name, hands[name], stage_z0)
    method = rd.get(stage, "custom_cutting_method", "str", "pair.method", default=None)
    if stage_z0 and stage_z0 != z0["gear"]:
        raise InputError(f"REXS {stage.where()}, attribute number_of_blade_groups: "
                         f"{stage_z0} disagrees with the gear's tools ({z0['gear']})")
    if method is None:  # REXS: z0 ≥ 1 is face hobbing
        method = "FH" if z0["gear"] > 0 else "FM"
    name = rd.get(stage, "custom_case_name", "str", "name", default=stage.name or "rexs")
    doc: dict[str, Any] = {
        "name": name,
        "source": rd.get(stage, "custom_source", "str", "source",
                         default=f"Imported from REXS {model.version} "
                                 f"({model.application_id} {model.application_version})"),
        "synthesised": json.loads(rd.get(stage, "custom_synthesised", "str", default="[]")),
        "pair": {"shaft_angle": rd.get(stage, "shaft_angle", "float", "pair.shaft_angle"),
                 "offset": rd.get(stage, "hypoid_offset", "float", "pair.offset",
                                  default=0.0),
                 "method": method, "pinion_hand": hands["pinion"], "gear_hand": hands["gear"],
                 "drive_flank": _drive_flank(rd, stage, pinion, hands["pinion"])},
        "pinion": members["pinion"], "gear": members["gear"],
        "operating": _operating(rd, stage, pinion),
    }
    tables = rd.get(stage, "custom_ltca_tables", "str", default=None)
    if tables:
        try:
            doc |= tomllib.loads(tables)
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"REXS {stage.where()}, attribute custom_ltca_tables: not TOML "
                             f"({exc})") from None
    devs = {m: rd.get(stage, f"custom_deviation_file_{m}", "str", f"deviations.{m}",
                      default=None) for m in MEMBERS}
    if any(devs.values()):
        doc["deviations"] = {k: v for k, v in devs.items() if v}
    unused = sorted({f"{c.type}.{a.id}" for c in model.components for a in c.attributes}
                    - _used(rd))
    if unused:
        log.info("REXS attributes not used by the case: %s", ", ".join(unused))
    return doc, rd.origin


def _used(rd: _Reader) -> set[str]:
    """component type.attribute of every attribute the importer reads (for the log)."""
    out = {f"bevel_gear.{a}" for _, a, _, _ in BLANK}
    out |= {f"bevel_gear_tool.{a}" for _, a, _, _ in BLADE}
    out |= {f"bevel_gear_manufacturing_settings.{a}" for _, a, _, _ in MACHINE}
    out |= {f"bevel_stage.{a}" for _, a, _, _ in (*MISALIGNMENT, *OPERATING_CUSTOM)}
    out |= {f"bevel_stage.{a}" for a in (*STAGE_CUSTOM, "shaft_angle", "hypoid_offset",
                                         "number_of_blade_groups", "temperature_lubricant")}
    out |= {"bevel_gear.spiral_angle_pitch_direction", "bevel_gear.custom_process",
            "bevel_gear.custom_cutting_cycle",
            "bevel_gear.custom_material", "bevel_gear.rotational_speed",
            "bevel_gear_tool.number_of_blade_groups_bevel_gear_tool",
            "bevel_gear_tool.custom_cutter_radius", "bevel_gear_flank.custom_flank_curvature",
            "bevel_stage_gear_data.loaded_tooth_flank", "bevel_stage_gear_data.torque",
            "bevel_stage_gear_data.is_driving_gear"}
    return out


def _drive_flank(rd: _Reader, stage: Component, pinion: Component, hand: str) -> str:
    named = rd.get(stage, "custom_drive_flank", "str", "pair.drive_flank", default=None)
    data = [rd.model.component(r.component("stage_gear_data") or -1)
            for r in rd.related("stage_gear_data", "gear", pinion.id)]
    side = next((rd.get(d, "loaded_tooth_flank", "str", default=None) for d in data), None)
    by_side = next((f for f in FLANKS if flank_side(hand, f) == side), None)
    if named is not None and by_side is not None and named != by_side:
        raise InputError(f"REXS {data[0].where()}, attribute loaded_tooth_flank: {side!r} is "
                         f"the pinion's {by_side} flank, but {stage.where()} attribute "
                         f"custom_drive_flank says {named!r}")
    return named or by_side or "concave"


def _operating(rd: _Reader, stage: Component, pinion: Component) -> dict[str, Any]:
    op: dict[str, Any] = {}
    ls = rd.model.load_spectrum
    torques = []
    if ls is not None:
        for lc in ls.load_cases:
            for c in lc.components:
                if c.type == "bevel_stage_gear_data" and c.get("torque") is not None:
                    sgd = rd.related("stage_gear_data", "stage_gear_data", c.id)
                    if sgd and sgd[0].component("gear") == pinion.id:
                        torques.append(rd.get(c, "torque", "float", "operating.torque"))
    if torques:
        op["torque"] = torques
    for key, attr, _unit, _vt in MISALIGNMENT:
        op[key] = rd.get(stage, attr, "float", f"operating.{key}", default=0.0)
    speed = rd.get(pinion, "rotational_speed", "float", "operating.pinion_speed", default=None)
    if speed is not None:
        op["pinion_speed"] = speed
    temp = rd.get(stage, "temperature_lubricant", "float", "operating.temperature",
                  default=None)
    if temp is not None:
        op["temperature"] = temp
    for key, attr, _unit, vt in OPERATING_CUSTOM:
        v = rd.get(stage, attr, "str" if vt == "string" else "float", f"operating.{key}",
                   default=None)
        if v is not None:
            op[key] = v
    return op


def model_to_basic_dict(model: Model) -> dict[str, Any]:
    """A basic design file mapping (``ltca synthesize``'s input, docs/synthesis.md) from a
    REXS bevel stage that has blank data but no manufacturing settings.

    The ``[design]`` table takes the ISO 23509 inputs REXS carries: Σ, a (stage), z1, z2,
    d_e2, b2 (gears), β_m (the pinion's for an offset pair, ISO 23509 Method 1; the gear's
    for Method 0), r_c0, z0, the design pressure angles and, from REXS 2.0.0, f_αlim, c_ham,
    k_d, k_c, k_t; a ``custom_ltca_tables`` written by this toolkit supplies the rest
    (targets, synthesis options, rating), the standard attributes taking precedence.

    Raises
    ------
    InputError
        A needed attribute missing, named by component, id and attribute.
    """
    rd = _Reader(model)
    stage, pinion, gear = _stage(model)
    tables: dict[str, Any] = {}
    text = rd.get(stage, "custom_ltca_tables", "str", default=None)
    if text:
        tables = tomllib.loads(text)
    design = dict(tables.get("design", {}))
    ver = model.version
    for key, where, names, _unit in DESIGN:
        comp = {"stage": stage, "pinion": pinion, "gear": gear}[where]
        if ver in names:
            v = rd.get(comp, names[ver], "float", default=None)
            if v is not None:
                design[key] = v
    method = rd.get(stage, "calculation_method_iso_23509_2025", "int", default=None)
    offset = design.get("a", rd.get(stage, "hypoid_offset", "float", default=0.0))
    design["method"] = method if method is not None else design.get(
        "method", 1 if offset else 0)
    design["z1"] = rd.get(pinion, "number_of_teeth", "int")
    design["z2"] = rd.get(gear, "number_of_teeth", "int")
    spiral = pinion if design["method"] == 1 else gear
    beta = rd.get(spiral, "mean_spiral_angle", "float", default=None)
    if beta is not None:
        design["beta_m"] = beta
    z0 = rd.get(stage, "number_of_blade_groups", "int", default=None)
    if z0 is not None:
        design["z0"] = z0
    design["hand"] = _hand(rd, pinion)
    for kind, (where, names) in BACKLASH.items():
        comp = stage if where == "stage" else gear
        v = rd.get(comp, names.get(ver, ""), "float", default=None)
        if v is not None:
            design["backlash"], design["backlash_value"] = kind, v
    parts = {"stage": stage, "gear": gear, "spiral": spiral}
    for key, where, attr in BASIC_NEEDS:
        if key not in design:
            raise InputError(f"REXS {parts[where].where()}: missing attribute {attr}, needed "
                             f"for the basic design's design.{key}")
    name = rd.get(stage, "custom_case_name", "str", default=stage.name or "rexs")
    source = rd.get(stage, "custom_source", "str", default=(
        f"Imported from REXS {ver} ({model.application_id} {model.application_version})"))
    doc: dict[str, Any] = {"name": name, "source": source, "design": design}
    for key in ("targets", "notes", "rating", "development"):
        if key in tables:
            doc[key] = tables[key]
    return doc
