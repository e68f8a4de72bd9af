"""Simulate the bundled wear example: the worn flanks of ``kolivand2009_fm_11x41``.

    python cases/deviations/make_wear_case.py

Writes ``wear_11x41_{pinion,gear}.csv`` (the worn grids of the last step) and
``../kolivand2009_fm_11x41_wear.toml`` (the base case plus a ``[deviations]`` table, by
``make_examples.write_case``), and prints the step table. Run it again whenever the base
case is re-synthesised.

The wear is simulated (:func:`contact.wear.simulate_wear`, Archard's law by single-point
observation, the worn surfaces analysed again after every step through the seed's ease-off
update, §4.3), standing in for the seed's Fig. 4.5 (worn flanks "predicted by a hypoid gear
wear model", Park & Kahraman, seed ref. [4.15], whose wear settings the seed does not give):

* pinion torque 200 N·m, the torque of the seed's Table 4.2 analysis of its worn pair;
* the base case's own assembly (no misalignment), drive flanks;
* wear coefficient k = 1e-17 m²/N (= 1e-17 m³ per N·m of sliding) and 2.5e6 load cycles
  (pinion revolutions; each gear tooth meshes 11/41 as often) in 10 equal steps: the
  toolkit's choice, which wears the pinion 8.1 µm and the gear 3.4 µm deep, the size of
  the seed's Fig. 4.5 (10 µm; its k and cycles are not published; at a given depth only
  their product matters, up to how the wear redistributes the load on the way);
* the default LTCA options and the wear grid :data:`contact.wear.WEAR_GRID` (41 × 21).
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
CASE = "kolivand2009_fm_11x41"
TORQUE = 200.0  # [N·m]
WEAR_COEFFICIENT = 1e-17  # [m^2/N]
CYCLES = 2.5e6  # pinion load cycles
STEPS = 10

log = logging.getLogger(__name__)


def write_grid(name: str, u: np.ndarray, v: np.ndarray, values: np.ndarray,
               comment: str) -> None:
    """One grid as the CSV of :func:`contact.utca.deviation_files.read_deviation_csv` (mm, 1 nm
    resolution)."""
    lines = [f"# {comment}", "# normal deviation [mm], positive = material added",
             "v\\u," + ",".join(f"{x:.4f}" for x in u)]
    for j, vj in enumerate(v):
        row = np.round(values[:, j], 6) + 0.0  # + 0.0: no "-0.000000"
        lines.append(f"{vj:.4f}," + ",".join(f"{x:.6f}" for x in row))
    (HERE / name).write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    from make_examples import write_case
    from tabulate import tabulate

    from contact.wear import simulate_wear

    ds = simulate_wear(CASE, TORQUE, wear_coefficient=WEAR_COEFFICIENT, cycles=CYCLES,
                       steps=STEPS, deviations=False)
    cols = ["cycles", "max_pinion_depth", "max_gear_depth", "ute_peak_to_peak",
            "lte_peak_to_peak", "pressure_max_flank"]
    print(tabulate(ds[cols].to_dataframe()[cols], headers=["step", *cols],
                   tablefmt="github", floatfmt=".4g"))
    what = (f"simulated wear, ltca wear: {CYCLES:g} cycles at {TORQUE:g} N m, "
            f"k = {WEAR_COEFFICIENT:g} m^2/N, {STEPS} steps")
    for member in ("pinion", "gear"):
        d = ds[f"{member}_deviation"].isel(step=-1).transpose(f"u_{member}", f"v_{member}")
        write_grid(f"wear_11x41_{member}.csv", ds[f"u_{member}"].values,
                   ds[f"v_{member}"].values, d.values,
                   f"{member} drive flank of {CASE}, {what} (written by make_wear_case.py)")
    write_case(CASE, "wear", "wear_11x41_pinion.csv", "wear_11x41_gear.csv",
               what, script="make_wear_case.py")


if __name__ == "__main__":
    logging.basicConfig(level=logging.INFO)
    for noisy in ("contact.utca", "contact.ltca", "geometry"):
        logging.getLogger(noisy).setLevel(logging.WARNING)
    main()
