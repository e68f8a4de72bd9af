"""The machine-settings sheet of a gear pair: what a machine operator sets, per member and flank.

From the case file as run (its TOML text in an analysis file's ``inputs``): per member the
process, then per flank (concave, convex) the cutter's blade and the cradle-type
generator's basic and higher-order settings, each with its symbol and unit as
``docs/cases.md`` gives them (angles in degrees, lengths in mm, as typed in case files;
signs in the toolkit's convention, ``docs/machine.md``). Fields a case leaves at their
default appear with it; lists (modified roll, helical and vertical motion) one row per
coefficient, only where a flank has it.

Public functions
----------------
machine_sheet   the sheet: per member, its process and (label, unit, concave, convex) rows
MACHINE_ROWS    the machine-setting rows: field → (label, unit, decimals)
BLADE_ROWS      the blade rows likewise
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

__all__ = ["BLADE_ROWS", "MACHINE_ROWS", "machine_sheet"]

#: ``[<member>.cutter.<flank>]`` fields: field → (label with symbol, unit, decimals);
#: units and symbols of docs/cases.md (``geometry.case`` reads them)
BLADE_ROWS: Mapping[str, tuple[str, str, int]] = {
    "point_radius": ("point radius r_p", "mm", 4),
    "blade_angle": ("blade (pressure) angle α", "deg", 4),
    "edge_radius": ("edge radius ρ_e", "mm", 3),
    "profile": ("blade profile", "", 0),
    "profile_radius": ("profile radius R_pr", "mm", 1),
    "profile_reference_height": ("profile reference height h_ref", "mm", 3),
    "toprem_angle": ("toprem angle Δα_T", "deg", 4),
    "toprem_height": ("toprem height", "mm", 3),
    "flankrem_angle": ("flankrem angle Δα_F", "deg", 4),
    "flankrem_height": ("flankrem height", "mm", 3),
    "blade_phase": ("blade phase θ_b", "deg", 4),
    "blade_offset_angle": ("blade offset angle δ_b", "deg", 4),
    "rake_angle": ("rake angle", "deg", 4),
    "hook_angle": ("hook angle γ_h", "deg", 4),
}

#: ``[<member>.machine.<flank>]`` scalar fields: field → (label with symbol, unit, decimals)
MACHINE_ROWS: Mapping[str, tuple[str, str, int]] = {
    "radial_setting": ("radial setting S_r", "mm", 4),
    "cradle_angle": ("cradle angle q_c", "deg", 4),
    "swivel": ("swivel j", "deg", 4),
    "tilt": ("tilt i", "deg", 4),
    "machine_root_angle": ("machine root angle γ_m", "deg", 4),
    "machine_center_to_back": ("machine centre to back X_p", "mm", 4),
    "sliding_base": ("sliding base X_b", "mm", 4),
    "blank_offset": ("blank offset E_m", "mm", 4),
    "ratio_of_roll": ("ratio of roll R_a", "1", 6),
}

#: list fields of the machine table: field → (coefficient names, unit of each)
_MOTIONS: Mapping[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "modified_roll": (("modified roll 2C", "modified roll 6D", "modified roll 24E",
                       "modified roll 120F"), ("1/rad", "1/rad²", "1/rad³", "1/rad⁴")),
    "helical_motion": (tuple(f"helical motion H{k}" for k in range(1, 7)),
                       tuple(f"mm/rad{'' if k == 1 else _sup}" for k, _sup in
                             zip(range(1, 7), ("", "²", "³", "⁴", "⁵", "⁶"), strict=True))),
    "vertical_motion": (tuple(f"vertical motion V{k}" for k in range(1, 7)),
                        tuple(f"mm/rad{'' if k == 1 else _sup}" for k, _sup in
                              zip(range(1, 7), ("", "²", "³", "⁴", "⁵", "⁶"), strict=True))),
}

#: the cutter head of a face-hobbing member: field → (label, unit, decimals)
_HEAD_ROWS = {"blade_groups": ("blade groups z_0", "1", 0),
              "cutter_radius": ("cutter radius r_c", "mm", 4)}

FLANKS = ("concave", "convex")


def _text(value: Any, decimals: int) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, bool) or value is None:
        return "–"
    x = float(value)
    if not math.isfinite(x):
        return "–"
    if decimals == 0:
        return f"{x:.0f}"
    if x != 0.0 and abs(x) < 10.0 ** (1 - decimals):  # small coefficients: 4 significant
        return f"{x:.4g}"
    return f"{x:.{decimals}f}"


def _rows(tables: Mapping[str, Mapping[str, Any]],
          fields: Mapping[str, tuple[str, str, int]]) -> list[tuple[str, str, str, str]]:
    rows = []
    for key, (label, unit, decimals) in fields.items():
        if not any(key in tables.get(f, {}) for f in FLANKS):
            continue
        rows.append((label, unit, *(_text(tables.get(f, {}).get(key), decimals)
                                    if key in tables.get(f, {}) else "–" for f in FLANKS)))
    return rows


def _motion_rows(tables: Mapping[str, Mapping[str, Any]]) -> list[tuple[str, str, str, str]]:
    rows = []
    for key, (names, units) in _MOTIONS.items():
        lists = [list(tables.get(f, {}).get(key, []) or []) for f in FLANKS]
        for k in range(min(max(len(x) for x in lists), len(names))):
            rows.append((names[k], units[k], *(_text(x[k], 6) if k < len(x) else "–"
                                               for x in lists)))
    return rows


def machine_sheet(case: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The machine-settings sheet of a case, per member.

    Parameters
    ----------
    case : mapping
        The case file as parsed by ``tomllib`` (an analysis file's ``inputs``): its
        ``[pinion]`` and ``[gear]`` tables with ``cutter.<flank>`` and
        ``machine.<flank>``.

    Returns
    -------
    list of dict
        One per member present: ``member``, ``process`` (Generate/Formate, "–" when not
        given), ``hand``, ``drive`` (the pinion flank in drive, from ``[pair]``
        ``drive_flank``; the gear's mate is the other), ``head`` (label, unit, value) rows
        of a face-hobbing cutter head, and ``rows`` (label, unit, concave, convex): blade,
        then machine settings, then the higher-order motions, as typed in the case file
        (deg, mm; "–" where a flank lacks the field).
    """
    out = []
    pair = case.get("pair", {}) if isinstance(case.get("pair"), Mapping) else {}
    drive = str(pair.get("drive_flank", "concave"))
    for member in ("pinion", "gear"):
        m = case.get(member)
        if not isinstance(m, Mapping):
            continue
        cutter = m.get("cutter", {}) if isinstance(m.get("cutter"), Mapping) else {}
        machine = m.get("machine", {}) if isinstance(m.get("machine"), Mapping) else {}
        blades = {f: cutter.get(f, {}) for f in FLANKS if isinstance(cutter.get(f), Mapping)}
        settings = {f: machine.get(f, {}) for f in FLANKS
                    if isinstance(machine.get(f), Mapping)}
        head = [(label, unit, _text(cutter[k], d)) for k, (label, unit, d) in
                _HEAD_ROWS.items() if cutter.get(k)]
        mate = drive if member == "pinion" else ("convex" if drive == "concave" else "concave")
        out.append({
            "member": member,
            "process": str(m.get("process", "–")),
            "hand": str(pair.get(f"{member}_hand", "–")),
            "drive": mate,
            "head": head,
            "rows": (_rows(blades, BLADE_ROWS) + _rows(settings, MACHINE_ROWS)
                     + _motion_rows(settings)),
        })
    return out
