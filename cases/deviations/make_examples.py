"""Write the example deviation grids of cases/deviations/ and their two example cases.

    python cases/deviations/make_examples.py

Run it again whenever a base case is re-synthesised: the example case files are the base
case files plus a ``[deviations]`` table. The wear example (``wear_11x41_*.csv``,
``../kolivand2009_fm_11x41_wear.toml``) is simulated by ``make_wear_case.py`` instead.

Grids: 9 lengthwise (u, toe → heel) × 5 profile (v, root → tip) points, the common CMM
practice (seed §4.5.2), in projection-plane fractions of each member; normal deviations in
mm, positive = material added (contact.utca.deviations).

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
* ``../iso23509_sample2_fm_measured.toml`` and ``../kolivand2009_fh_12x41_measured.toml``
  — the base cases with a ``[deviations]`` table pointing at those grids.
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
log = logging.getLogger(__name__)


def write(name: str, values: np.ndarray, comment: str) -> None:
    lines = [f"# {comment}", "# normal deviation [mm], positive = material added",
             "v\\u," + ",".join(f"{u:.4f}" for u in U)]
    for j, v in enumerate(V):
        row = np.round(values[:, j], 6) + 0.0  # + 0.0: no "-0.000000"
        lines.append(f"{v:.4f}," + ",".join(f"{x:.6f}" for x in row))
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def write_case(base: str, suffix: str, pinion_csv: str, gear_csv: str, what: str,
               script: str = "make_examples.py") -> Path:
    """The base case file plus a ``[deviations]`` table (paths relative to the case file)."""
    text = (CASES / f"{base}.toml").read_text(encoding="utf-8")
    body = "\n".join(ln for ln in text.splitlines() if not ln.startswith("#")).lstrip("\n")
    body, n = re.subn(r'^name = "[^"]*"', f'name = "{base}_{suffix}"', body, count=1,
                      flags=re.M)
    if n != 1:
        raise RuntimeError(f"{base}.toml has no top-level name")
    header = (f"# Written by `python cases/deviations/{script}`: {base}.toml plus a\n"
              f"# [deviations] table ({what}).\n"
              "# Regenerated whenever the base case is re-synthesised; do not edit by hand.\n")
    table = (f'\n[deviations]\npinion = "deviations/{pinion_csv}"\n'
             f'gear = "deviations/{gear_csv}"\n')
    out = CASES / f"{base}_{suffix}.toml"
    out.write_text(header + body.rstrip("\n") + "\n" + table, encoding="utf-8")
    return out


def _global_shape(su: np.ndarray, sv: np.ndarray) -> np.ndarray:
    """Pressure-angle error (∝ v), spiral-angle error (∝ u) and twist (∝ u·v), scaled to
    [0, 1] over the grid with the maximum at su = sv = 1 (the seed's Fig. 4.10 deviations
    are shifted to one sign and peak at one corner: pinion heel-top, gear toe-root)."""
    s = 0.5 * sv + 0.3 * su + 0.2 * su * sv
    return (s - s.min()) / (s.max() - s.min())


def main() -> None:
    uu, vv = np.meshgrid(U, V, indexing="ij")
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
    write_case("iso23509_sample2_fm", "measured", "measured_iso2_pinion.csv",
               "measured_iso2_gear.csv", "global measured-like deviations, seed Fig. 4.10")
    write_case("kolivand2009_fh_12x41", "measured", "measured_fh_12x41_pinion.csv",
               "measured_fh_12x41_gear.csv",
               "global measured-like deviations of the seed's Table 4.3 pair, seed 4.5.2")


if __name__ == "__main__":
    logging.basicConfig(level=logging.INFO)
    main()
