"""Analysis results into the slots REXS has: the ISO 10300 rating, the mesh stiffness per
mesh position, the ease-off as a point list with normals (docs/exchange.md).

An analysis file of ``ltca run`` (or ``ltca rate -o``) holds the ``/rating`` group: the
ISO 10300-1/-2/-3:2014 Method B1 rating per torque and member. Its factors and stresses go
into the REXS attributes ``*_iso_10300_2014`` of the ``bevel_stage`` (pair quantities) and
the two ``bevel_stage_gear_data`` (member quantities); quantities that vary with torque go
into the load case of their torque, and the load spectrum is then the analysis' torques.

Public
------
RATING_STAGE, RATING_MEMBER   the mapping tables (rating variable → REXS attribute)
mesh_stiffness                secant mesh stiffness per torque and roll of an /ltca group
add_results                   add an analysis file's results to a model
"""

from __future__ import annotations

import logging
import os
from typing import Any

import numpy as np

from contact.exchange.rexs.database import load_database
from contact.exchange.rexs.mapping import DATA_IDS, STAGE_ID
from contact.exchange.rexs.model import (
    Component,
    LoadCase,
    LoadSpectrum,
    Model,
    Ref,
    Relation,
)
from geometry.case import Case
from geometry.core.errors import InputError

__all__ = ["RATING_MEMBER", "RATING_STAGE", "add_results", "mesh_stiffness"]

log = logging.getLogger(__name__)

_S = "_iso_10300_2014"
#: /rating variable → bevel_stage attribute (pair quantities; a member-dimensioned value is
#: written where both members share it)
RATING_STAGE = {
    "K_A": "application_factor", "K_v": "dynamic_factor",
    "K_Hbeta": "face_load_factor_contact_stress", "K_Fbeta": "face_load_factor_root_stress",
    "K_Hbeta_be": "mounting_factor", "K_F0": "lengthwise_curvature_factor_tooth_root",
    "K_Halpha": "transverse_load_factor_pitting",
    "K_Falpha": "transverse_load_factor_tooth_root",
    "Z_E": "elasticity_factor_pitting", "Z_LS": "load_sharing_factor_pitting",
    "Z_MB": "mid_zone_factor_pitting", "Z_Hyp": "hypoid_factor_pitting",
    "Z_K": "bevel_gear_factor_pitting", "Z_L": "lubricant_factor_pitting",
    "Z_speed": "speed_factor_pitting", "Z_R": "roughness_factor_pitting",
    "Y_eps": "contact_ratio_factor_tooth_root", "Y_LS": "load_sharing_factor_tooth_root",
    "b_veff": "effective_face_width_virtual_cylindrical_gear",
    "b_v": "face_width_virtual_cylindrical_gear",
}
#: /rating variable → bevel_stage_gear_data attribute (member quantities; a pair value is
#: written on both members)
RATING_MEMBER = {
    "S_H": "safety_factor_pitting", "S_F": "safety_factor_tooth_root",
    "S_Hmin": "minimum_safety_factor_pitting", "S_Fmin": "minimum_safety_factor_tooth_root",
    "sigma_H0": "nominal_contact_stress", "sigma_H": "contact_stress",
    "sigma_HP": "permissible_contact_stress", "sigma_F0": "nominal_tooth_root_stress",
    "sigma_F": "tooth_root_stress", "sigma_FP": "permissible_tooth_root_stress",
    "Z_NT": "life_factor_pitting", "Y_NT": "life_factor_tooth_root",
    "Z_X": "size_factor_pitting", "Y_X": "size_factor_tooth_root",
    "Z_W": "work_hardening_factor_pitting", "Y_Sa": "stress_correction_factor_tooth_root",
    "Y_Fa": "form_factor_tooth_root", "Y_BS": "bevel_spiral_angle_factor_tooth_root",
    "Y_RrelT": "relative_surface_factor_tooth_root",
    "d_v": "reference_diameter_virtual_cylindrical_gear",
    "d_va": "tip_diameter_virtual_cylindrical_gear",
    "d_vb": "base_diameter_virtual_cylindrical_gear",
    "d_vn": "reference_diameter_normal_section_virtual_cylindrical_gear",
    "d_van": "tip_diameter_normal_section_virtual_cylindrical_gear",
    "d_vbn": "base_diameter_normal_section_virtual_cylindrical_gear",
}
_MEMBERS = ("pinion", "gear")


def _tree(path: str | os.PathLike[str], case: Case):
    import xarray as xr

    try:
        tree = xr.open_datatree(path)
    except (OSError, ValueError) as exc:
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: cannot be read as netCDF "
                         f"({exc})") from None
    groups = [g for g in ("rating", "ltca", "easeoff") if g in tree.children]
    if not groups:
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: has none of the groups /rating, "
                         "/ltca, /easeoff (ltca run writes them; ltca rate -o /rating)")
    for g in groups:
        named = tree[g].attrs.get("case")
        if named not in (None, case.name):
            raise InputError(f"ANALYSIS {os.fspath(path)!r}: is an analysis of case "
                             f"{named!r}, not of {case.name!r}")
    if "rating" in groups and tree["rating"].attrs.get("rating_method",
                                                        "iso10300") != "iso10300":
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: rated by "
                         f"{tree['rating'].attrs['rating_method']!r}; REXS's rating slots "
                         "are ISO 10300's")
    return {g: tree[g].to_dataset().load() for g in groups}


class _Cases:
    """The load cases of an export with results, one per torque: the case's torques first,
    then those of the analysis that the case does not list."""

    def __init__(self, spectrum: LoadSpectrum | None) -> None:
        """Start from the case's own load cases (one per ``[operating]`` torque)."""
        self.cases: list[LoadCase] = list(spectrum.load_cases) if spectrum else []
        self.torques: list[float] = [lc.components[0].value("torque") for lc in self.cases]

    def component(self, torque: float, cid: int, type_: str) -> Component:
        if torque not in self.torques:
            self.torques.append(torque)
            lc = LoadCase(len(self.cases) + 1, [Component(DATA_IDS["pinion"],
                                                          "bevel_stage_gear_data")])
            lc.components[0].add("torque", torque, "N m")
            self.cases.append(lc)
        lc = self.cases[self.torques.index(torque)]
        for c in lc.components:
            if c.id == cid:
                return c
        lc.components.append(Component(cid, type_))
        return lc.components[-1]


def _values(da, member: int | None, torque: int | None) -> float | None:
    """The value of a rating variable for a member and torque (None: not finite, or a
    member-dimensioned pair value whose members differ)."""
    sel: dict[str, Any] = {}
    if "torque" in da.dims:
        sel["torque"] = torque
    if "member" in da.dims:
        if member is None:
            vals = np.asarray(da.isel(**sel).values, dtype=float)
            return float(vals[0]) if np.all(vals == vals[0]) and np.isfinite(vals[0]) \
                else None
        sel["member"] = member
    v = float(np.asarray(da.isel(**sel).values, dtype=float))
    return v if np.isfinite(v) else None


def _add_rating(model: Model, ds, db, cases: _Cases) -> None:
    torques = [float(t) for t in ds["torque"].values] if "torque" in ds.coords else []
    stage = model.component(STAGE_ID)
    stage.add("calculation_method" + _S, "method_b1", "none", "enum")
    stage.add("custom_rating_side", str(ds.attrs.get("side", "drive")), "none", "string")
    data = {m: model.component(DATA_IDS[m]) for m in _MEMBERS}
    skipped = []
    for table, target in ((RATING_STAGE, "stage"), (RATING_MEMBER, "member")):
        for var, stem in table.items():
            if var not in ds:
                continue
            attr = stem + _S
            comp_type = "bevel_stage" if target == "stage" else "bevel_stage_gear_data"
            if not db.has(comp_type, attr):
                skipped.append(attr)
                continue
            da, spec = ds[var], db.attributes[attr]
            for k, member in enumerate([None] if target == "stage" else [0, 1]):
                cid = STAGE_ID if target == "stage" else DATA_IDS[_MEMBERS[k]]
                if "torque" in da.dims:
                    for i, t in enumerate(torques):
                        v = _values(da, member, i)
                        if v is not None and spec.in_range(v):
                            cases.component(t, cid, comp_type).add(attr, v, spec.unit)
                else:
                    v = _values(da, member, None)
                    comp = stage if target == "stage" else data[_MEMBERS[k]]
                    if v is not None and spec.in_range(v):
                        comp.add(attr, v, spec.unit)
    if skipped:
        log.info("rating values without a REXS %s attribute: %s", model.version,
                 ", ".join(skipped))


def mesh_stiffness(ltca) -> np.ndarray:
    """Secant mesh stiffness per torque and roll position [N/mm] of an ``/ltca`` dataset.

    k = ΣF / (Θ r_m): the total normal force of the segments over the deflection along the
    contact normal at their load-weighted mean moment arm r_m = Σ F a / Σ F about the gear
    axis, Θ the loaded rotation of the contact problem (the gear's elastic lag, the LTE
    less the UTE). NaN where no certified solution was found or Θ ≤ 0.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``force`` (torque, roll, pair, segment) [N], ``moment_arm`` (roll, pair, segment)
        [mm], ``loaded_rotation`` (torque, roll) [µrad], ``found`` (torque, roll).

    Returns
    -------
    numpy.ndarray, shape (torque, roll)

    Source: the definition of a mesh stiffness as load per deflection along the line of
    action (ISO 6336-1 cl. 9 for cylindrical gears), applied to the LTCA's contact problem.
    """
    force = np.nan_to_num(np.asarray(ltca["force"].values, dtype=float))
    arm = np.nan_to_num(np.asarray(ltca["moment_arm"].values, dtype=float))[None]
    total = force.sum(axis=(2, 3))
    moment = (force * np.abs(arm)).sum(axis=(2, 3))
    theta = np.asarray(ltca["loaded_rotation"].values, dtype=float) * 1e-6
    ok = (np.asarray(ltca["found"].values) == 1) & (theta > 0) & (total > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = total**2 / (theta * moment)
    return np.where(ok, k, np.nan)


def _add_stiffness(ltca, cases: _Cases) -> None:
    k = mesh_stiffness(ltca)
    roll = np.degrees(np.asarray(ltca["roll"].values, dtype=float))
    for i, t in enumerate(np.asarray(ltca["torque"].values, dtype=float)):
        good = np.isfinite(k[i])
        if not good.any():
            continue
        cases.component(float(t), STAGE_ID, "bevel_stage").add(
            "meshing_stiffness_characteristic", [float(v) for v in k[i][good]], "N / mm",
            "floating_point_array")
        cases.component(float(t), DATA_IDS["pinion"], "bevel_stage_gear_data").add(
            "rotational_meshing_position", [float(v) for v in roll[good]], "deg",
            "floating_point_array")


#: component ids of the ease-off's point list and gear flank data set
EASE_OFF_IDS = (30, 31)


def _add_ease_off(model: Model, easeoff) -> None:
    """The ease-off as a ``point_list`` of the gear flank it is measured on (gear frame,
    mm) and a ``gear_flank_data_set`` of its amounts [mm] along the flank normals."""
    mask = np.asarray(easeoff["mask"].values) == 1
    pos = np.asarray(easeoff["gear_position"].values, dtype=float)[mask]
    nrm = np.asarray(easeoff["gear_normal"].values, dtype=float)[mask]
    amount = np.asarray(easeoff["ease_off"].values, dtype=float)[mask] * 1e-3  # um → mm
    good = np.isfinite(pos).all(axis=1) & np.isfinite(nrm).all(axis=1) & np.isfinite(amount)
    pos, nrm, amount = pos[good], nrm[good], amount[good]
    if not len(amount):
        return
    flank = str(easeoff.attrs.get("gear_flank", "convex"))
    flank_id = 21 + ("concave", "convex").index(flank)
    pl_id, ds_id = EASE_OFF_IDS
    points = Component(pl_id, "point_list", f"ease-off points, gear {flank} flank")
    points.add("kind_of_point_list", "gear_flank_mesh", "none", "enum")
    points.add("point_ids", list(range(1, len(amount) + 1)), "none", "integer_array")
    if load_database(model.version).has("point_list", "point_coordinates_v_coord"):
        for axis, column in zip("uvw", pos.T, strict=True):  # REXS 2.0.0
            points.add(f"point_coordinates_{axis}_coord", [float(v) for v in column], "mm",
                       "floating_point_array")
    else:  # REXS 1.7: one matrix of (u, v, w) rows
        points.add("point_coordinates", [[float(v) for v in row] for row in pos], "mm",
                   "floating_point_matrix")
    points.add("custom_coordinate_frame", "gear frame of hypoid-ltca (docs/machine.md): "
               "w along the gear axis from the apex side into the body", "none", "string")
    data = Component(ds_id, "gear_flank_data_set", "ease-off")
    data.add("set_ids", [pl_id], "none", "integer_array")
    data.add("topographical_deviation_amounts_point_list", [float(v) for v in amount], "mm",
             "floating_point_array")
    data.add("topographical_deviation_normals", [[float(v) for v in row] for row in nrm],
             "none", "floating_point_matrix")
    data.add("custom_deviation_meaning", "ease-off: the real gear flank's normal distance "
             "from the conjugate of the real pinion flank (docs/exchange.md)", "none",
             "string")
    model.components += [points, data]
    next_id = max(r.id for r in model.relations) + 1
    model.relations += [
        Relation(next_id, "assembly", [Ref(flank_id, "assembly", "bevel_gear_flank"),
                                       Ref(pl_id, "part", "point_list")]),
        Relation(next_id + 1, "reference", [Ref(pl_id, "origin", "point_list"),
                                            Ref(ds_id, "referenced", "gear_flank_data_set")])]


def add_results(model: Model, case: Case, analysis: str | os.PathLike[str]) -> None:
    """Add an analysis file's results to a model (in place).

    Parameters
    ----------
    model : Model
        From :func:`contact.exchange.rexs.mapping.case_to_model` for ``case``.
    case : geometry.Case
    analysis : path-like
        netCDF file of ``ltca run`` (``/rating``, ``/ltca``, ``/easeoff``) or ``ltca rate
        -o`` (``/rating``).

    Raises
    ------
    InputError
        Unreadable file, none of the groups, another case's analysis, a rating by another
        method than ISO 10300.

    Source: ISO 10300-1/-2/-3:2014 Method B1 (the toolkit's rating, docs/rating.md) into
    the REXS attributes ``*_iso_10300_2014``; :func:`mesh_stiffness`; the ease-off of
    :mod:`contact.utca` (docs/exchange.md).
    """
    db = load_database(model.version)
    groups = _tree(analysis, case)
    cases = _Cases(model.load_spectrum)
    if "rating" in groups:
        _add_rating(model, groups["rating"], db, cases)
    if "ltca" in groups:
        _add_stiffness(groups["ltca"], cases)
    if "easeoff" in groups:
        _add_ease_off(model, groups["easeoff"])
    if cases.cases:
        model.load_spectrum = LoadSpectrum(1, cases.cases)
