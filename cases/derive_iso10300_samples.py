"""Write the bundled cases of ISO/TR 10300-30:2024's three rating samples.

Run from the repository root::

    python cases/derive_iso10300_samples.py

It writes ``cases/iso10300_30_sample1.toml``, ``…sample2.toml`` and ``…sample3.toml``: the
gear sets of ISO 23509:2016 Annex F that the TR rates by ISO 10300 Method B1, each with

* ``[design]`` — the ISO 23509 basic design data (the blank the rating computes,
  :func:`geometry.iso23509.blank.blank_geometry`);
* ``[rating]`` — the TR's rating inputs (K_A, f_pt, mounting, oil, roughness, allowable
  stress numbers, E, cutter edge radii, minimum safety factors; docs/rating.md);
* ``[operating]`` — the TR's operating point (pinion torque and speed);
* blanks, cutters and machine settings so that every command runs the case:
  sample 1 from ``cases/spiral_bevel_iso23509_s1.toml`` (basic relations, the blank of
  Annex F), sample 2 from ``cases/iso23509_sample2_fm.toml`` (synthesised from the same
  basic data), sample 3 synthesised here (face hobbing, ISO 23509 Method 2, z0 = 13; no
  profile relief: the default 15 µm needs a blade rem angle beyond the synthesis' limit
  on this small 9-tooth pinion; the pitch cone at the TR's gear pitch angle δ2 = 63.212°,
  where the standard's Method 2 iteration stopped, ``[design].delta2``).
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from geometry.case import case_from_dict  # noqa: E402
from geometry.synthesis.basic_design import basic_from_dict  # noqa: E402
from geometry.synthesis.case_synthesis import synthesize  # noqa: E402

#: ISO/TR 10300-30:2024, the inputs common to its three samples (Tables A.4, B.4, C.4):
#: application factor, mounting (one member cantilever-mounted, pattern checked under a
#: light test load), steel/steel E, the cutter edge radii of pinion and gear, the minimum
#: safety factors, the effective face width 0.85 b and e_LS = 3
COMMON = {
    "application_factor": 1.1,
    "mounting": "one",
    "contact_pattern": "light_load",
    "youngs_modulus": 210000.0,
    "poisson_ratio": 0.3,
    "edge_radius": [0.8, 1.2],
    "min_safety_pitting": 1.0,
    "min_safety_bending": 1.3,
    "effective_width_ratio": 0.85,
    "load_sharing_exponent": 3.0,
}

#: how the TR rates the members, given in the sample cases only (not in COMMON, which
#: cases/derive_rating_tables.py also gives the Annex F cases of the same pairs, rated by
#: their own members' process): both by the generated tooth form — its printed gear q_s
#: 2.166, 2.073, 2.118 are the generated fillet's (the non-generated one, the edge radius,
#: gives 3.008, 2.427, 3.796; tests/test_rating_iso10300.py), while the cases' gears are
#: cut Formate for the contact analysis
TR_PROCESS = {"process": "Generate"}

#: what each sample's [rating] source says of its process (not the case's own)
_PROCESS_SOURCE = ("process Generate for both members as the TR rates them (its printed gear "
                   "q_s is the generated fillet's), although the case's gear is cut Formate "
                   "for the contact analysis")

SAMPLES = {
    1: {
        "from": "spiral_bevel_iso23509_s1.toml",
        "title": "spiral bevel 14/39 (ISO 23509 Annex F sample 1, face milling)",
        "design": dict(method=0, Sigma=90.0, a=0.0, z1=14, z2=39, de2=176.893, b2=25.4,
                       beta_m=35.0, rc0=114.3, alpha_dD=20.0, alpha_dC=20.0, f_alim=0.0,
                       c_ham=0.24737, k_d=2.0, k_c=0.125, k_t=0.0915, backlash="j_en",
                       backlash_value=0.127, theta_a2=2.1342, theta_f2=6.4934, hand="left"),
        "operating": {"torque": [300.0], "pinion_speed": 1200.0},
        "rating": {"single_pitch_deviation": [12.0, 26.0], "nu40": 150.0,
                   "flank_roughness": 8.0, "root_roughness": 16.0, "sigma_Hlim": 1500.0,
                   "sigma_Flim": 480.0,
                   "source": f"ISO/TR 10300-30:2024 sample 1 (Annex A): {_PROCESS_SOURCE}"},
    },
    2: {
        "from": "iso23509_sample2_fm.toml",
        "title": "hypoid 13/42, offset 15 mm (ISO 23509 Annex F sample 2, face milling)",
        "design": dict(method=1, Sigma=90.0, a=15.0, z1=13, z2=42, de2=170.0, b2=30.0,
                       beta_m=50.0, rc0=63.5, alpha_dD=20.0, alpha_dC=20.0, f_alim=1.0,
                       c_ham=0.35, k_d=2.0, k_c=0.125, k_t=0.1, backlash="j_et2",
                       backlash_value=0.2, theta_a2=1.0, theta_f2=4.0, hand="left"),
        "operating": {"torque": [250.0], "pinion_speed": 1200.0},
        "rating": {"single_pitch_deviation": [11.6, 23.5], "nu40": 150.0,
                   "flank_roughness": 8.0, "root_roughness": 16.0, "sigma_Hlim": 1500.0,
                   "sigma_Flim": 480.0,
                   "source": f"ISO/TR 10300-30:2024 sample 2 (Annex B): {_PROCESS_SOURCE}"},
    },
    3: {
        "from": None,
        "title": "hypoid 9/34, offset 31.75 mm (ISO 23509 Annex F sample 3, face hobbing, "
                 "Method 2, z0 = 13)",
        # the Annex F file gives no backlash kind: j_et2 0.2 mm reproduces its thicknesses
        # (tests/test_blank_face_hobbing.py). delta2: the gear pitch angle at which the
        # standard's Method 2 iteration stopped in Annex F (63.212 deg, 0.3 % short of its
        # closing condition; exact closure 63.145 deg) and which the TR rates: with it the
        # blank reproduces Annex F's R_m2 82.168, R_e2 95.168, delta_a1 24.765 and the TR's
        # d_v2 325.506 (tests/test_rating_iso10300.py)
        "design": dict(method=2, Sigma=90.0, a=31.75, z1=9, z2=34, dm2=146.7, b2=26.0,
                       beta_m=21.009, rc0=76.0, z0=13, alpha_dD=20.0, alpha_dC=20.0,
                       f_alim=1.0, c_ham=0.275, k_d=2.0, k_c=0.125, k_t=0.1,
                       backlash="j_et2", backlash_value=0.2, theta_a2=0.0, theta_f2=0.0,
                       hand="left", delta2=63.212),
        "operating": {"torque": [250.0], "pinion_speed": 4500.0},
        # K_v: the TR's printed 1.000, with which it computed F_mtH, K_Halpha and the
        # stresses; ISO 10300-1 Method B gives N K + 1 = 1.049 at its printed N 0.084 and
        # K 0.589 (tests/test_rating_iso10300.py, test_sample3_dynamic_factor_misprint)
        "rating": {"single_pitch_deviation": [12.0, 25.0], "nu40": 100.0,
                   "flank_roughness": 3.0, "root_roughness": 10.0, "sigma_Hlim": 1510.0,
                   "sigma_Flim": 500.0, "dynamic_factor": 1.0,
                   "source": "ISO/TR 10300-30:2024 sample 3 (Annex C): dynamic_factor is the "
                             "TR's printed K_v = 1.000, with which it computes F_mtH, "
                             "K_Halpha and the stresses (ISO 10300-1 Method B gives N K + 1 "
                             "= 1.049 at the TR's N 0.084, K 0.589); " + _PROCESS_SOURCE},
    },
}

_SOURCE = (
    "ISO/TR 10300-30:2024 (calculation of load capacity of bevel gears, worked examples of "
    "ISO 10300 Method B1), sample {n}: {title}. [design]: ISO 23509:2016 Annex F basic "
    "data, from which the rating computes the blank (geometry.iso23509.blank); [rating] "
    "and [operating]: the TR's inputs (K_A 1.1, f_pt {fpt} um, one member "
    "cantilever-mounted, pattern checked under a light test load, nu40 {nu40} mm2/s, Rz "
    "flank {rzf} / root {rzr} um, sigma_Hlim {shl} / sigma_Flim {sfl} N/mm2, E 210000 "
    "N/mm2, cutter edge radii 0.8 / 1.2 mm, S_Hmin 1.0, S_Fmin 1.3; T1 {t:g} N m at {n1:g} "
    "rpm). Blanks, cutters and machine settings for the contact analysis: {origin}. "
    "Written by cases/derive_iso10300_samples.py.")


def _synthesised_sample3(design: dict) -> dict:
    basic = basic_from_dict({
        "name": "iso10300_30_sample3",
        "source": "ISO 23509:2016 Annex F sample 3 (face-hobbed hypoid 9x34, Method 2)",
        "design": design,
        "synthesis": {"method": "FH", "drive_flank": "concave", "tip_relief": 0.0,
                      "root_relief": 0.0},
    })
    case, _ = synthesize(basic)
    return tomllib.loads(case.to_toml())


def derive(n: int) -> str:
    """The TOML text of sample ``n``'s case."""
    spec = SAMPLES[n]
    if spec["from"] is None:
        doc = _synthesised_sample3(spec["design"])
        origin = ("synthesised from the [design] data by geometry.synthesis.case_synthesis "
                  "(face hobbing, z0 = 13, no profile relief), its source: "
                  + doc["source"])
    else:
        doc = tomllib.loads((ROOT / "cases" / spec["from"]).read_text(encoding="utf-8"))
        origin = f"those of cases/{spec['from']}, whose source: " + doc["source"]
    rating = {**COMMON, **spec["rating"], **TR_PROCESS}
    op = {**doc.get("operating", {}), **spec["operating"]}
    rz = rating["flank_roughness"], rating["root_roughness"]
    doc.update(
        name=f"iso10300_30_sample{n}",
        source=_SOURCE.format(n=n, title=spec["title"], fpt=" / ".join(
            f"{x:g}" for x in rating["single_pitch_deviation"]), nu40=f"{rating['nu40']:g}",
            rzf=f"{rz[0]:g}", rzr=f"{rz[1]:g}", shl=f"{rating['sigma_Hlim']:g}",
            sfl=f"{rating['sigma_Flim']:g}", t=op["torque"][0], n1=op["pinion_speed"],
            origin=origin),
        operating=op, design=spec["design"], rating=rating)
    case = case_from_dict(doc)
    header = ("# Written by `python cases/derive_iso10300_samples.py` (ISO/TR 10300-30:2024 "
              f"sample {n}; see `source`). Do not edit by hand.\n")
    return header + case.to_toml()


def main() -> None:
    for n in SAMPLES:
        out = ROOT / "cases" / f"iso10300_30_sample{n}.toml"
        tmp = out.with_suffix(".tmp")
        tmp.write_text(derive(n), encoding="utf-8")
        tmp.replace(out)
        print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
