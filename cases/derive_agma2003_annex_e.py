"""Write the bundled case of ANSI/AGMA 2003-D19's Annex E worked example.

Run from the repository root::

    python cases/derive_agma2003_annex_e.py

It writes ``cases/agma2003_d19_annex_e.toml``. Annex E rates a 14/39 spiral bevel pair
without offset: diametral pitch 5.6 (m_et = 25.4/5.6 mm), face width 1.0 in (25.4 mm),
outer cone distance 3.70 in, normal pressure angle 20°, mean spiral angle 35°, cutter
radius 4.5 in (114.3 mm), shaft angle 90°. That is the gear set of ISO 23509:2016 Annex F
sample 1 (d_e2 = 176.893 mm = 39 × 25.4/5.6, R_e 93.973 mm = 3.6997 in), which the
toolkit bundles as ``iso10300_30_sample1``; this case takes its ``[design]`` table, blanks,
cutters and machine settings from that file, and adds

* ``[agma2003]`` — Annex E's inputs (I 0.109, J 0.222 / 0.217 read off the Annex D
  charts, K_o 1.0, Q_v 11, one member straddle-mounted, properly crowned, N_L 1e9 /
  3.59e8, reliability 0.99, 20 °C, E 207 000 MPa, ν 0.3, carburised grade 1, S_H = S_F =
  1), as a public implementation's self-test against Annex E gives them (the standard's
  text was not at hand);
* ``[operating]`` — Annex E's operating point, T1 = 1440 lb·in (162.70 N·m) at 1750 rpm
  (the oil and roughness of the ISO sample, for the contact analysis);
* ``[rating]`` — an ISO 10300 table so that both methods rate the pair: ISO/TR
  10300-30:2024 sample 1's inputs of the same gear set, with Annex E's K_o 1.0 as K_A and
  its E 207 000 MPa (not part of Annex E).
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from geometry.case import case_from_dict  # noqa: E402
from geometry.core.atomic_files import atomic_path  # noqa: E402

#: lb·in → N·m, exactly (0.45359237 kg × 9.80665 m/s² × 0.0254 m)
LBF_IN = 0.45359237 * 9.80665 * 0.0254

AGMA2003 = {
    "geometry_factor_I": 0.109,
    "geometry_factor_J": [0.222, 0.217],
    "overload_factor": 1.0,
    "accuracy_number": 11,
    "mounting": "one",
    "crowned": True,
    "load_cycles": [1.0e9, 3.59e8],
    "critical_service": False,
    "reliability": 0.99,
    "temperature": 20.0,
    "grade": [1, 1],
    "youngs_modulus": [207000.0, 207000.0],
    "poisson_ratio": [0.3, 0.3],
    "safety_factor_pitting": 1.0,
    "safety_factor_bending": 1.0,
    "source": ("ANSI/AGMA 2003-D19 Annex E (worked example, US units), as a public "
               "implementation's self-test of the standard gives its inputs: I, J read off "
               "the Annex D charts (Figures D.13/D.14), K_o 1.0, Q_v 11, one member "
               "straddle-mounted, properly crowned, N_L 1e9 / 3.59e8, 1 failure in 100, "
               "20 degC, equal hardness, E 207000 MPa, nu 0.3, carburised case-hardened "
               "grade 1 (s_ac, s_at of the SI table), S_H = S_F = 1"),
}

SOURCE = (
    "ANSI/AGMA 2003-D19 Annex E (worked example of the rating of a 14/39 spiral bevel "
    "pair without offset: 5.6 diametral pitch, face width 1.0 in, outer cone distance "
    "3.70 in, alpha_n 20 deg, beta_m 35 deg, cutter radius 4.5 in, shaft angle 90 deg; "
    "T1 1440 lb in = 162.70 N m at 1750 rpm), as read from a public implementation's "
    "self-test of the standard (the standard's text was not at hand; docs/rating.md). "
    "[agma2003]: Annex E's inputs. [design], blanks, cutters and machine settings: those "
    "of cases/iso10300_30_sample1.toml, the same gear set (ISO 23509:2016 Annex F sample "
    "1, d_e2 = 39 x 25.4/5.6 mm), whose source: {origin} [rating]: ISO/TR 10300-30:2024 "
    "sample 1's ISO 10300 inputs with Annex E's K_o 1.0 as K_A and its E 207000 MPa, so "
    "that ISO 10300 rates the pair too (not part of Annex E). Written by "
    "cases/derive_agma2003_annex_e.py.")


def derive() -> str:
    """The TOML text of the case."""
    text = (ROOT / "cases" / "iso10300_30_sample1.toml").read_text(encoding="utf-8")
    doc = tomllib.loads(text)
    # the notes of cases/derive_point_widths.py and derive_tip_planes.py, whose values
    # the tables below carry over (their --check finds this file as they left sample 1)
    notes = [ln for ln in text.splitlines()[1:] if ln.startswith("#")]
    origin = doc["source"]
    rating = {**doc["rating"], "application_factor": 1.0, "youngs_modulus": 207000.0}
    operating = {**doc["operating"], "torque": [round(1440.0 * LBF_IN, 2)],
                 "pinion_speed": 1750.0}
    doc.update(name="agma2003_d19_annex_e", source=SOURCE.format(origin=origin),
               operating=operating, rating=rating, agma2003=AGMA2003)
    case = case_from_dict(doc)
    header = ("# Written by `python cases/derive_agma2003_annex_e.py` (ANSI/AGMA 2003-D19 "
              "Annex E; see `source`). Do not edit by hand.\n")
    return header + "".join(f"{ln}\n" for ln in notes) + case.to_toml()


def main() -> None:
    out = ROOT / "cases" / "agma2003_d19_annex_e.toml"
    with atomic_path(out) as tmp:
        Path(tmp).write_text(derive(), encoding="utf-8")
    print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
