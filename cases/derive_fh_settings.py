"""Write a face-hobbed example pair from basic relations (no local synthesis).

Run from the repository root::

    python cases/derive_fh_settings.py

It writes ``tests/data/fh_iso23509_s2_crown.toml``: the ISO 23509 Annex F sample 2 blank
(hypoid 13/42) cut by face hobbing with z0 = 5 blade groups and a cutter of r_c0 = 82.55 mm:

* gear Formate, the closed-form face-hobbing tools of
  :func:`geometry.synthesis.gear.gear_formate_tools` (``blade_groups = 5``): slot
  centre line
  the extended epicycloid through the mean root point with the gear's spiral angle, outside
  blade leading the inside blade by half a group pitch, rake planes at the lead angle;
* pinion Generate by its own face-hobbing crown gear in its root plane: the same closed form
  on the pinion blank, rolled with R_a = 1/sin δ_f1 (the crown gear of z1/sin δ_f1 teeth),
  the work indexing κ1 = R_a κ_crown = −z0/z1 (``docs/machine.md``, "Face hobbing").

The pair is an example of face-hobbed surfaces for the geometry commands and tests; it is
not a synthesised (matched) pair: that is ``ltca synthesize`` with ``method = "FH"``.
"""

from __future__ import annotations

import math
import sys
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from geometry.case import case_from_dict  # noqa: E402
from geometry.iso23509.blank import blank_geometry  # noqa: E402
from geometry.iso23509.pitch_cone import BevelGearDesign  # noqa: E402
from geometry.synthesis.case_synthesis import case_blank, gear_formate_tools  # noqa: E402

Z0 = 5
RC0 = 82.55  # [mm] 3.25 in

# ISO 23509:2016 Annex F, sample 2 basic data (tests/data/iso23509_annex_f_face_milling.toml)
DESIGN = dict(method=1, Sigma=90.0, a=15.0, z1=13, z2=42, de2=170.0, b2=30.0, beta_m=50.0,
              rc0=63.5, alpha_dD=20.0, alpha_dC=20.0, f_alim=0.0, c_ham=0.24, k_d=2.0,
              k_c=0.125, k_t=0.0, backlash="j_en", backlash_value=0.127, theta_a2=0.0,
              theta_f2=0.0)


def _deg(blade) -> dict:
    out = {}
    for k in ("point_radius", "blade_angle", "edge_radius", "blade_phase",
              "blade_offset_angle"):
        v = getattr(blade, k)
        out[k] = math.degrees(v) if k.endswith(("angle", "phase")) else v
    return out


def _machine(s) -> dict:
    return {"radial_setting": s.radial_setting, "cradle_angle": math.degrees(s.cradle_angle),
            "machine_root_angle": math.degrees(s.machine_root_angle),
            "machine_center_to_back": s.machine_center_to_back,
            "ratio_of_roll": s.ratio_of_roll}


def derive() -> dict:
    geom = blank_geometry(BevelGearDesign.from_degrees(**DESIGN))
    kw = dict(cutter_radius=RC0, blade_angle_drive=math.radians(20.0),
              blade_angle_coast=math.radians(20.0), point_width=None, edge_radius=None,
              blade_groups=Z0)
    gear = gear_formate_tools(geom, **kw)
    # the pinion's crown gear: the same closed form on the pinion blank (swap the members)
    swapped = replace(geom, gear=geom.pinion, pinion=geom.gear)
    crown = gear_formate_tools(swapped, **kw)
    ratio = 1.0 / math.sin(geom.pinion.delta_f)
    pin = replace(crown.settings, process="Generate", ratio_of_roll=ratio,
                  indexing_ratio=-Z0 / geom.pinion.z)
    doc = {
        "name": "fh_iso23509_s2_crown",
        "source": (
            "Written by cases/derive_fh_settings.py: ISO 23509:2016 Annex F sample 2 blank "
            "(hypoid 13x42, Method 1) face-hobbed with z0 = 5 blade groups, r_c0 = 82.55 mm. "
            "Gear Formate by the closed-form face-hobbing tools of "
            "geometry.synthesis.gear.gear_formate_tools (slot centre line the extended "
            "epicycloid "
            "through the mean root point, OB leading IB by half a group pitch, rake planes at "
            "the lead angle); pinion Generate by its own face-hobbing crown gear in its root "
            f"plane (ratio of roll 1/sin delta_f1 = {ratio:.6f}, indexing -z0/z1). Example "
            "surfaces, not a matched pair."),
        "synthesised": [],
        "pair": {"shaft_angle": 90.0, "offset": 15.0, "method": "FH", "pinion_hand": "left",
                 "gear_hand": "right", "drive_flank": "concave"},
    }
    for name, member, tools, settings, process in (
            ("pinion", geom.pinion, crown, pin, "Generate"),
            ("gear", geom.gear, gear, gear.settings, "Formate")):
        doc[name] = {
            "process": process, "blank": case_blank(member),
            "cutter": {"blade_groups": Z0, "cutter_radius": RC0,
                       **{f: _deg(b) for f, b in tools.blades.items()}},
            "machine": {f: _machine(settings) for f in ("concave", "convex")},
        }
    return doc


def main() -> None:
    case = case_from_dict(derive())
    out = ROOT / "tests" / "data" / "fh_iso23509_s2_crown.toml"
    header = ("# Written by `python cases/derive_fh_settings.py` (face-hobbed example pair; "
              "see `source`). Do not edit by hand.\n")
    tmp = out.with_suffix(".tmp")
    tmp.write_text(header + case.to_toml(), encoding="utf-8")
    tmp.replace(out)
    print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
