"""Give the bundled cases the tables of the ISO 10300 rating: ``[design]`` and ``[rating]``.

Run from the repository root::

    python cases/derive_rating_tables.py

``ltca run`` rates every case beside its loaded contact (contact.load_capacity.iso10300,
docs/rating.md);
the rating needs the pair's ISO 23509 basic design data (``[design]``, from which it
computes the blank) and its rating inputs (``[rating]``). This script appends both
tables, after a marker comment, to each bundled case below (replacing what an earlier run
appended; a case that has its own tables, the ISO/TR 10300-30 samples, is not touched):

* ``[design]`` — the design the case's blank was computed from: its basic file's design
  fitted to its targets (``cases/basic/<base>.toml``, :func:`geometry.synthesis.
  basic_design.load_basic`), or ISO 23509 Annex F's basic data for the two Annex F cases
  (their blanks are the Annex F tables; the blank of this design matches them within
  0.03 mm and 0.01 deg, checked below);
* ``[rating]`` — for the Annex F samples, ISO/TR 10300-30:2024's inputs of the same
  pairs (samples 1 and 2); for the seed's pairs (Kolivand 2009, which gives none) the
  stated defaults of :data:`SEED_RATING`, each with its source.

Every appended design is checked: its ISO 23509 blank must give the case's blank (outer
cone distance, face width, pitch angle, addendum and dedendum of both members) within
:data:`TOLERANCE`. The measured and worn variants (``*_measured``, ``*_wear``) take their
base case's tables (their blanks are the base's); ``cases/deviations/make_examples.py``
copies them on its next run.
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from derive_iso10300_samples import COMMON, SAMPLES  # noqa: E402

from geometry.core.atomic_files import atomic_path  # noqa: E402
from geometry.core.toml_files import dump_toml  # noqa: E402
from geometry.iso23509.blank import blank_geometry  # noqa: E402
from geometry.iso23509.design_data import BevelGearDesign  # noqa: E402
from geometry.synthesis.basic_design import load_basic  # noqa: E402
from geometry.synthesis.gear import case_blank  # noqa: E402

MARKER = ("# ISO 10300 rating tables, appended by `python cases/derive_rating_tables.py` "
          "(docs/rating.md); rerun it after regenerating this case.")

#: the rating inputs of the seed's pairs (Kolivand 2009 gives none): each value stated
#: with its source; the fields left out take RatingInputs' defaults
#: (contact.load_capacity.iso10300.inputs:
#: pattern checked under a light test load, flank/root Rz 8/16 um as the TR's lapped
#: samples, material quality MQ, long life, S_Hmin 1.0, S_Fmin 1.3, nu40 and the edge radii
#: from the case's oil and blades)
SEED_RATING = {
    "application_factor": 1.0,
    "mounting": "one",
    "accuracy_grade": [6, 8],
    "source": (
        "Stated defaults (the seed gives no rating data): K_A = 1.0, ISO 10300-1:2014's "
        "application factor of a uniform driving and driven machine, so that the rating "
        "and the LTCA carry the same nominal torque; mounting 'one' (one member "
        "cantilever-mounted), the automotive rear axle's overhung pinion with a "
        "straddle-mounted ring gear, as ISO/TR 10300-30:2024's samples; ISO 17485 accuracy "
        "grades 6 (pinion) and 8 (gear), the grades of the TR's f_pt (sample 1: 12 and "
        "26 um at its sizes); the other fields RatingInputs' defaults (docs/rating.md)."),
}

#: the design torque of the seed's 11x41 face-milled pairs [N m, pinion] (its Table 3.1
#: loads them at 50, 250 and 500 N m; it gives no design torque): 250 N m, the middle load,
#: rated at long life; 500 N m is then an overload of finite life whose permissible load
#: cycles the rating states (its long-life capacity at S_H = S_Hmin is ~445 N m)
SEED_DESIGN_TORQUE = {"kolivand2009_fm_11x41": 250.0, "kolivand2009_fm_11x41_reference": 250.0}
SEED_DESIGN_TORQUE_SOURCE = (
    " Design torque 250 N m (pinion): the middle load of the seed's Table 3.1 (50, 250, "
    "500 N m), rated at long life; the seed gives no design torque, and the rating's "
    "long-life capacity of this pair at S_H = S_Hmin is about 445 N m "
    "(contact.load_capacity.iso10300.capacity), so 500 N m is rated as an overload of "
    "finite life (the permissible load cycles in /rating, ISO 10300-2/-3 cl. 8).")

#: the Annex F cases: (case, TR sample whose [rating] inputs they take)
ANNEX_F = {"spiral_bevel_iso23509_s1": 1, "hypoid_iso23509_s2": 2}
#: cases from a basic file of the same name, and the variants of a base case
FROM_BASIC = ("iso23509_sample2_fm", "kolivand2009_fm_11x41", "kolivand2009_fm_11x41_reference",
              "kolivand2009_fh_12x41", "kolivand2009_fh_12x41_reference",
              "kolivand2009_table54_A_fh", "kolivand2009_table54_A_fh_reference",
              "kolivand2009_table54_B_fh", "kolivand2009_table54_B_fh_reference")
VARIANTS = {"iso23509_sample2_fm_measured": "iso23509_sample2_fm",
            "kolivand2009_fh_12x41_measured": "kolivand2009_fh_12x41",
            "kolivand2009_fm_11x41_wear": "kolivand2009_fm_11x41"}
#: the largest difference allowed between the case's blank and that of its [design]
#: [mm, deg]: the synthesised cases' blanks are their design's (1e-9); the Annex F cases'
#: blanks are Annex F's printed tables, which the toolkit's ISO 23509 blank of the same
#: basic data meets within 0.0014 (sample 1) and 0.03 (sample 2: R_e1 89.638 against the
#: printed 89.608 mm, delta1 21.279 against 21.289 deg; tests/test_blank.py)
TOLERANCE = {"synthesised": 1e-6, "annex_f": 0.05}


def _tables(name: str) -> tuple[dict, dict, str]:
    """([design], [rating], kind of check) of a bundled case."""
    base = VARIANTS.get(name, name)
    if base in ANNEX_F:
        n = ANNEX_F[base]
        design = dict(SAMPLES[n]["design"])
        rating = {**COMMON, **SAMPLES[n]["rating"], "source": (
            f"ISO/TR 10300-30:2024 sample {n}: the TR's rating inputs of this ISO 23509 "
            "Annex F pair (cases/derive_iso10300_samples.py)")}
        return design, rating, "annex_f"
    basic = load_basic(ROOT / "cases" / "basic" / f"{base}.toml")
    rating = dict(SEED_RATING)
    if base in SEED_DESIGN_TORQUE:
        rating["design_torque"] = SEED_DESIGN_TORQUE[base]
        rating["source"] += SEED_DESIGN_TORQUE_SOURCE
    return basic.design.to_degrees(), rating, "synthesised"


def _check(name: str, text: str, design: dict, kind: str) -> float:
    """The largest difference between the case's blank and its design's [mm, deg]."""
    raw = tomllib.loads(text)
    geom = blank_geometry(BevelGearDesign.from_degrees(**design))
    worst = 0.0
    for member, iso in (("pinion", geom.pinion), ("gear", geom.gear)):
        ours, theirs = raw[member]["blank"], case_blank(iso)
        for key in ("outer_cone_distance", "face_width", "pitch_angle", "outer_addendum",
                    "outer_dedendum"):
            worst = max(worst, abs(ours[key] - theirs[key]))
    if worst > TOLERANCE[kind]:
        raise RuntimeError(f"{name}: the blank of its [design] differs from its own by "
                           f"{worst:.3g} (> {TOLERANCE[kind]:g})")
    return worst


def derive(name: str) -> str:
    """The text of case ``name`` with the rating tables appended (or replaced)."""
    path = ROOT / "cases" / f"{name}.toml"
    text = path.read_text(encoding="utf-8").split("\n" + MARKER)[0].rstrip("\n") + "\n"
    if "\n[rating]" in text or "\n[design]" in text:
        raise RuntimeError(f"{name}: has its own [design] or [rating] table")
    design, rating, kind = _tables(name)
    out = text + "\n" + MARKER + "\n" + dump_toml({"design": design, "rating": rating})
    worst = _check(name, out, design, kind)
    print(f"{name}: blank of [design] within {worst:.2g} of the case's")
    return out


def main() -> None:
    for name in (*FROM_BASIC, *ANNEX_F, *VARIANTS):
        text = derive(name)
        target = ROOT / "cases" / f"{name}.toml"
        with atomic_path(target) as tmp:
            tmp.write_text(text, encoding="utf-8")
        print(f"wrote {target.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
