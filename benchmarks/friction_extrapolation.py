"""The ``kolivand2009`` model outside its fitted box, against the mixed-EHL solver.

A gear's loaded segments leave the friction study's box (docs/friction.md, "Range against
a gear's contacts"): p_h above 3 GPa at the edges, SR below 0.01 near the pitch line,
u_e below 0.05 m/s at the lowest speeds, R_eq above 150 mm along a hypoid's contact lines.
There the ``eyring`` model holds its regression at the box's edge and takes the smooth
film's traction μ_E and the asperity share ψ at the inputs. This script solves 64
conditions just outside the box — 16 per slab, each a Latin hypercube (seeds 100–103) of
the gear box with one input replaced: p_h 3–4.5 GPa, SR 0.001–0.01 (log), u_e 0.01–0.05
m/s (log), R 150–500 mm (log) — with the study's solver settings (the stochastic model,
512 nodes, Barus, the flash temperature), and prints the model's RMS and worst relative
error per slab beside the ``split`` power laws held at the box's edge. The committed
result is ``friction/data/friction_study_75W90_outside.nc`` (``tests/test_kolivand2009.py``
checks the numbers).

~30 s on 2 workers. Usage::

    python benchmarks/friction_extrapolation.py [-o friction_study_75W90_outside.nc]
        [--scheduler synchronous | ADDRESS] [--workers N]
    python benchmarks/friction_extrapolation.py --evaluate friction_study_75W90_outside.nc
"""

from __future__ import annotations

import argparse
import warnings
from pathlib import Path

import numpy as np
import xarray as xr
from tabulate import tabulate

from contact.study.friction_study import run_friction_study
from contact.study.store import ResultStore
from friction.kolivand2009 import DATA_DIR, kolivand2009, load_kolivand2009_fit
from friction.study.design import GEAR_CONTACT_RANGE, space_filling_design
from friction.study.fit import combine_studies, fit_kolivand2009, study_inputs
from friction.study.points import SolveSettings
from friction.validity import FrictionModelRangeWarning
from geometry.core.io import read_netcdf, write_netcdf

#: one input outside the gear box per slab: (name, (low, high, log)), LHS seed
SLABS = (("hertz_pressure", (3000.0, 4500.0, False), 100),
         ("slide_to_roll", (0.001, 0.01, True), 101),
         ("entraining_velocity", (0.01, 0.05, True), 102),
         ("radius", (150.0, 500.0, True), 103))
PER_SLAB = 16
MODEL_INPUTS = ("hertz_pressure", "slide_to_roll", "entraining_velocity", "viscosity",
                "pressure_viscosity", "radius", "roughness_1", "roughness_2")


def design() -> dict[str, np.ndarray]:
    """The 64 conditions, slab by slab."""
    parts = []
    for name, span, seed in SLABS:
        box = dict(GEAR_CONTACT_RANGE)
        box[name] = span
        parts.append(space_filling_design(PER_SLAB, method="lhs", seed=seed, box=box))
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


def evaluate(study: xr.Dataset) -> list[list[object]]:
    """Rows (slab, converged, RMS and worst of eyring, of split held at the edge)."""
    d = study_inputs(study)
    points = study["point"].values[(study["status"].values == 0)
                                   & (study["friction_coefficient"].values > 0)]
    train = combine_studies([read_netcdf(DATA_DIR / f"friction_study_75W90{s}.nc", tree=False)
                             for s in ("", "_skip1024")])
    models = {"eyring": load_kolivand2009_fit("75W90"),
              "split": fit_kolivand2009(train, structure="split", box=GEAR_CONTACT_RANGE)}
    rel = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        for name, fit in models.items():
            mu = kolivand2009(**{k: d[k] for k in MODEL_INPUTS}, coefficients=fit)
            rel[name] = mu / d["friction_coefficient"] - 1.0
    rows = []
    for k, (name, (lo, hi, _), _) in enumerate(SLABS):
        m = (points >= k * PER_SLAB) & (points < (k + 1) * PER_SLAB)
        row: list[object] = [f"{name} {lo:g}-{hi:g}", f"{int(m.sum())} of {PER_SLAB}"]
        for r in rel.values():
            row += [f"{np.sqrt(np.mean(r[m] ** 2)):.1%}", f"{r[m][np.argmax(np.abs(r[m]))]:+.0%}"]
        rows.append(row)
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", default="friction_study_75W90_outside.nc")
    ap.add_argument("--evaluate", default=None, metavar="FILE.nc",
                    help="print the table of an existing file instead of solving")
    ap.add_argument("--scheduler", default=None)
    ap.add_argument("--workers", type=int, default=None)
    args = ap.parse_args()
    if args.evaluate:
        study = read_netcdf(args.evaluate, tree=False)
    else:
        settings = SolveSettings()
        attrs = {"method": "lhs", "seed": "100-103", "points": len(SLABS) * PER_SLAB,
                 "box": "gear box with one input outside: p_h 3-4.5 GPa, SR 0.001-0.01, "
                        "u_e 0.01-0.05 m/s, R 150-500 mm (16 points each; "
                        "benchmarks/friction_extrapolation.py)"}
        study = run_friction_study(design(), settings, design_attrs=attrs, output=args.output,
                                   scheduler=args.scheduler, n_workers=args.workers)
        write_netcdf(study, Path(args.output))
        ResultStore.remove_parts(args.output)
    print(tabulate(evaluate(study), headers=["slab", "converged", "eyring RMS", "worst",
                                             "split at the edge RMS", "worst"],
                   tablefmt="github"))


if __name__ == "__main__":
    main()
