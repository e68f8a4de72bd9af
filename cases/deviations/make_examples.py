"""Write the example deviation grids of cases/deviations/ (seed Figs. 4.5 and 4.10 in kind).

    python cases/deviations/make_examples.py

Grids: 9 lengthwise (u, toe → heel) × 5 profile (v, root → tip) points, the common CMM
practice (seed §4.5.2); normal deviations in mm, positive = material added.

* ``wear_11x41_{pinion,gear}.csv`` — a local, wear-like deviation of the default case: a
  smooth hollow (material removed) around the pattern centre, up to 10 µm on the pinion and
  5 µm on the gear (seed Fig. 4.5 magnitudes).
* ``measured_iso2_{pinion,gear}.csv`` — a global, measured-like deviation of
  ``iso23509_sample2_fm``: a pressure-angle error (linear in v), a spiral-angle error
  (linear in u) and a twist (u·v), up to 50 µm on the pinion and 25 µm on the gear (seed
  Fig. 4.10 magnitudes).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

U = np.linspace(0.0, 1.0, 9)
V = np.linspace(0.05, 1.0, 5)
HERE = Path(__file__).resolve().parent


def write(name: str, values: np.ndarray, comment: str) -> None:
    lines = [f"# {comment}", "# normal deviation [mm], positive = material added",
             "v\\u," + ",".join(f"{u:.4f}" for u in U)]
    for j, v in enumerate(V):
        lines.append(f"{v:.4f}," + ",".join(f"{values[i, j]:.6f}" for i in range(U.size)))
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    uu, vv = np.meshgrid(U, V, indexing="ij")
    hollow = np.exp(-(((uu - 0.5) / 0.22) ** 2 + ((vv - 0.55) / 0.25) ** 2))
    write("wear_11x41_pinion.csv", -0.010 * hollow,
          "wear-like local deviation, pinion drive flank of kolivand2009_fm_11x41 (10 um)")
    write("wear_11x41_gear.csv", -0.005 * hollow,
          "wear-like local deviation, gear drive flank of kolivand2009_fm_11x41 (5 um)")
    su, sv = 2 * uu - 1, 2 * vv - 1
    write("measured_iso2_pinion.csv", 0.025 * sv + 0.015 * su + 0.010 * su * sv,
          "measured-like global deviation, pinion drive flank of iso23509_sample2_fm (50 um)")
    write("measured_iso2_gear.csv", -0.0125 * sv + 0.0075 * su - 0.005 * su * sv,
          "measured-like global deviation, gear drive flank of iso23509_sample2_fm (25 um)")


if __name__ == "__main__":
    main()
