"""Analysis results into the slots REXS has: the ISO 10300 rating (docs/exchange.md).

An analysis file of ``ltca run`` (or ``ltca rate -o``) holds the ``/rating`` group: the
ISO 10300-1/-2/-3:2014 Method B1 rating per torque and member. Its factors and stresses go
into the REXS attributes ``*_iso_10300_2014`` of the ``bevel_stage`` (pair quantities) and
the two ``bevel_stage_gear_data`` (member quantities); quantities that vary with torque go
into the load case of their torque, and the load spectrum is then the analysis' torques.

Public
------
RATING_STAGE, RATING_MEMBER   the mapping tables (rating variable → REXS attribute)
add_results                   add an analysis file's results to a model
"""

from __future__ import annotations

import logging
import os
from typing import Any

import numpy as np

from contact.exchange.rexs.database import load_database
from contact.exchange.rexs.mapping import DATA_IDS, STAGE_ID
from contact.exchange.rexs.model import Component, LoadCase, LoadSpectrum, Model
from geometry.case import Case
from geometry.core.errors import InputError

__all__ = ["RATING_MEMBER", "RATING_STAGE", "add_results"]

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


def _rating(path: str | os.PathLike[str], case: Case):
    import xarray as xr

    try:
        tree = xr.open_datatree(path)
    except (OSError, ValueError) as exc:
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: cannot be read as netCDF "
                         f"({exc})") from None
    if "rating" not in tree.children:
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: has no /rating group (ltca run "
                         "writes it unless --no-rating; ltca rate -o writes it alone)")
    ds = tree["rating"].to_dataset().load()
    if ds.attrs.get("case") not in (None, case.name):
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: is an analysis of case "
                         f"{ds.attrs.get('case')!r}, not of {case.name!r}")
    if ds.attrs.get("rating_method", "iso10300") != "iso10300":
        raise InputError(f"ANALYSIS {os.fspath(path)!r}: rated by "
                         f"{ds.attrs['rating_method']!r}; REXS's rating slots are ISO 10300's")
    return ds, ds.attrs


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


def add_results(model: Model, case: Case, analysis: str | os.PathLike[str]) -> None:
    """Add an analysis file's ISO 10300 rating to a model (in place).

    Parameters
    ----------
    model : Model
        From :func:`contact.exchange.rexs.mapping.case_to_model` for ``case``.
    case : geometry.Case
    analysis : path-like
        netCDF file with a ``/rating`` group (``ltca run``, ``ltca rate -o``).

    Raises
    ------
    InputError
        Unreadable file, no ``/rating`` group, another case's analysis, a rating by another
        method than ISO 10300.

    Source: ISO 10300-1/-2/-3:2014 Method B1 (the toolkit's rating, docs/rating.md) into
    the REXS attributes ``*_iso_10300_2014`` of the attribute database.
    """
    db = load_database(model.version)
    ds, attrs = _rating(analysis, case)
    torques = [float(t) for t in ds["torque"].values] if "torque" in ds.coords else []
    stage = model.component(STAGE_ID)
    stage.add("calculation_method" + _S, "method_b1", "none", "enum")
    stage.add("custom_rating_side", str(attrs.get("side", "drive")), "none", "string")
    cases = [LoadCase(i + 1, [Component(STAGE_ID, "bevel_stage"),
                              Component(DATA_IDS["pinion"], "bevel_stage_gear_data"),
                              Component(DATA_IDS["gear"], "bevel_stage_gear_data")])
             for i in range(len(torques))]
    for i, t in enumerate(torques):
        cases[i].components[1].add("torque", t, "N m")
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
            da = ds[var]
            members = [None] if target == "stage" else [0, 1]
            for k, member in enumerate(members):
                idx = 0 if target == "stage" else 1 + k
                if "torque" in da.dims:
                    for i in range(len(torques)):
                        v = _values(da, member, i)
                        if v is not None and db.attributes[attr].in_range(v):
                            cases[i].components[idx].add(attr, v, db.attributes[attr].unit)
                else:
                    v = _values(da, member, None)
                    comp = stage if target == "stage" else data[_MEMBERS[k]]
                    if v is not None and db.attributes[attr].in_range(v):
                        comp.add(attr, v, db.attributes[attr].unit)
    if skipped:
        log.info("rating values without a REXS %s attribute: %s", model.version,
                 ", ".join(skipped))
    if cases:
        for lc in cases:
            lc.components = [c for c in lc.components if c.attributes]
        model.load_spectrum = LoadSpectrum(1, cases)
