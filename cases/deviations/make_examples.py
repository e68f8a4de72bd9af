"""Write the example deviation grids of cases/deviations/ and their two example cases.

    python cases/deviations/make_examples.py

Run it again whenever a base case is re-synthesised: the wear hollow is placed on the
pinion's active flank of the current base case, and the example case files are the base
case files plus a ``[deviations]`` table.

Grids: 9 lengthwise (u, toe → heel) × 5 profile (v, root → tip) points, the common CMM
practice (seed §4.5.2), in projection-plane fractions of each member; normal deviations in
mm, positive = material added (contact.utca.deviations).

* ``wear_11x41_{pinion,gear}.csv`` — a local, wear-like deviation of the default case: a
  smooth hollow (material removed), up to 10 µm on the pinion and 5 µm on the gear (seed
  Fig. 4.5 magnitudes). Lengthwise it is centred on the unloaded pattern (the median, over
  the gear nodes of least ease-off, of the node and of its pinion mate:
  contact.utca.easeoff.ease_off); in profile half-way between the lowest profile fraction that
  meshes (the lowest pinion mate, resp. the lowest gear node with a mate) and the pattern
  centre, i.e. in the dedendum where sliding wear is deepest; it is tapered to exactly zero
  below that lowest meshing fraction, so the fillet and root below the contact region stay
  unworn.
* ``measured_iso2_{pinion,gear}.csv`` — a global, measured-like deviation of
  ``iso23509_sample2_fm``: a pressure-angle error (linear in v), a spiral-angle error
  (linear in u) and a twist (u·v), shifted to one sign as the seed's Fig. 4.10 (material
  removed) and ranging 0–50 µm on the pinion (most at heel-top) and 0–25 µm on the gear
  (most at toe-root).
* ``measured_fh_12x41_{pinion,gear}.csv`` — the same global, measured-like shape on the
  face-hobbed pair the seed measured (Table 4.3, ``kolivand2009_fh_12x41``; §4.5.2: CMM
  on a 5×9 grid, up to 50 µm on the pinion at heel-top and 25 µm on the gear at toe-root,
  Fig. 4.10). The seed's measured values are not published, only these magnitudes and
  corners, so the shape is the one above and not a reading of Fig. 4.10's contours.
* ``../kolivand2009_fm_11x41_wear.toml``, ``../iso23509_sample2_fm_measured.toml`` and
  ``../kolivand2009_fh_12x41_measured.toml`` — the base cases with a ``[deviations]``
  table pointing at those grids.
"""

from __future__ import annotations

import logging
import re
from pathlib import Path

import numpy as np

U = np.linspace(0.0, 1.0, 9)
V = np.linspace(0.05, 1.0, 5)
HERE = Path(__file__).resolve().parent
CASES = HERE.parent
#: share of the valid gear nodes with the least ease-off taken as the unloaded pattern
PATTERN_SHARE = 0.3
#: profile-fraction width of the wear's rise from zero at the lowest meshing point
WEAR_TAPER = 0.1

log = logging.getLogger(__name__)


def write(name: str, values: np.ndarray, comment: str) -> None:
    lines = [f"# {comment}", "# normal deviation [mm], positive = material added",
             "v\\u," + ",".join(f"{u:.4f}" for u in U)]
    for j, v in enumerate(V):
        row = np.round(values[:, j], 6) + 0.0  # + 0.0: no "-0.000000"
        lines.append(f"{v:.4f}," + ",".join(f"{x:.6f}" for x in row))
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def write_case(base: str, suffix: str, pinion_csv: str, gear_csv: str, what: str) -> Path:
    """The base case file plus a ``[deviations]`` table (paths relative to the case file)."""
    text = (CASES / f"{base}.toml").read_text(encoding="utf-8")
    body = "\n".join(ln for ln in text.splitlines() if not ln.startswith("#")).lstrip("\n")
    body, n = re.subn(r'^name = "[^"]*"', f'name = "{base}_{suffix}"', body, count=1,
                      flags=re.M)
    if n != 1:
        raise RuntimeError(f"{base}.toml has no top-level name")
    header = (f"# Written by `python cases/deviations/make_examples.py`: {base}.toml plus a\n"
              f"# [deviations] table ({what}).\n"
              "# Regenerated whenever the base case is re-synthesised; do not edit by hand.\n")
    table = (f'\n[deviations]\npinion = "deviations/{pinion_csv}"\n'
             f'gear = "deviations/{gear_csv}"\n')
    out = CASES / f"{base}_{suffix}.toml"
    out.write_text(header + body.rstrip("\n") + "\n" + table, encoding="utf-8")
    return out


def _taper(v: np.ndarray, v0: float, width: float = 0.2) -> np.ndarray:
    """0 for v ≤ v0, smooth (C¹ smoothstep) rise to 1 at v0 + width."""
    t = np.clip((v - v0) / width, 0.0, 1.0)
    return t * t * (3 - 2 * t)


def _global_shape(su: np.ndarray, sv: np.ndarray) -> np.ndarray:
    """Pressure-angle error (∝ v), spiral-angle error (∝ u) and twist (∝ u·v), scaled to
    [0, 1] over the grid with the maximum at su = sv = 1 (the seed's Fig. 4.10 deviations
    are shifted to one sign and peak at one corner: pinion heel-top, gear toe-root)."""
    s = 0.5 * sv + 0.3 * su + 0.2 * su * sv
    return (s - s.min()) / (s.max() - s.min())


def active_region(case_name: str) -> dict[str, float]:
    """Pattern centre and lowest meshing profile fraction of both members of a case."""
    from contact.utca.easeoff import ease_off
    from geometry.case import load_case

    eo = ease_off(load_case(CASES / f"{case_name}.toml"))
    gu, gv = np.meshgrid(eo.u, eo.v, indexing="ij")
    ok = eo.valid & np.isfinite(eo.pinion_u) & np.isfinite(eo.pinion_v)
    e = eo.ease_off_angle[ok]
    near = e <= np.quantile(e, PATTERN_SHARE)
    return {
        "pinion_u": float(np.median(eo.pinion_u[ok][near])),
        "pinion_v": float(np.median(eo.pinion_v[ok][near])),
        "pinion_v_low": float(np.min(eo.pinion_v[ok])),
        "gear_u": float(np.median(gu[ok][near])),
        "gear_v": float(np.median(gv[ok][near])),
        "gear_v_low": float(np.min(gv[ok])),
    }


def main() -> None:
    uu, vv = np.meshgrid(U, V, indexing="ij")
    a = active_region("kolivand2009_fm_11x41")
    log.info("active region of kolivand2009_fm_11x41: %s", a)
    for m, amp in (("pinion", 0.010), ("gear", 0.005)):
        # sliding wear (Archard: depth ∝ pressure × sliding distance) is deepest in the
        # dedendum, between the lowest meshing point and the pattern centre (near the pitch
        # line, where sliding vanishes)
        vc = 0.5 * (a[f"{m}_v_low"] + a[f"{m}_v"])
        hollow = np.exp(-(((uu - a[f"{m}_u"]) / 0.22) ** 2 + ((vv - vc) / 0.2) ** 2))
        d = -amp * hollow * _taper(vv, a[f"{m}_v_low"], WEAR_TAPER)
        d *= amp / np.abs(d).max()  # peak exactly amp
        write(f"wear_11x41_{m}.csv", d,
              f"wear-like local deviation, {m} drive flank of kolivand2009_fm_11x41 "
              f"({amp * 1e3:g} um), centred at u {a[f'{m}_u']:.3f}, v {vc:.3f}, "
              f"zero below v {a[f'{m}_v_low']:.3f} (written by make_examples.py)")
    su, sv = 2 * uu - 1, 2 * vv - 1
    # the same measured-like global deviation (seed §4.5.2's sizes) on two pairs
    for tag, case, note in (("iso2", "iso23509_sample2_fm", ""),
                            ("fh_12x41", "kolivand2009_fh_12x41", ", seed 4.5.2")):
        write(f"measured_{tag}_pinion.csv", -0.050 * _global_shape(su, sv),
              f"measured-like global deviation, pinion drive flank of {case}: "
              f"0 to 50 um removed, most at heel-top{note} (written by make_examples.py)")
        write(f"measured_{tag}_gear.csv", -0.025 * _global_shape(-su, -sv),
              f"measured-like global deviation, gear drive flank of {case}: "
              f"0 to 25 um removed, most at toe-root{note} (written by make_examples.py)")
    write_case("kolivand2009_fm_11x41", "wear", "wear_11x41_pinion.csv",
               "wear_11x41_gear.csv", "local wear-like deviations, seed Fig. 4.5")
    write_case("iso23509_sample2_fm", "measured", "measured_iso2_pinion.csv",
               "measured_iso2_gear.csv", "global measured-like deviations, seed Fig. 4.10")
    write_case("kolivand2009_fh_12x41", "measured", "measured_fh_12x41_pinion.csv",
               "measured_fh_12x41_gear.csv",
               "global measured-like deviations of the seed's Table 4.3 pair, seed 4.5.2")


if __name__ == "__main__":
    logging.basicConfig(level=logging.INFO)
    main()
