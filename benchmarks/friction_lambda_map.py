"""The default friction model against the film parameter λ and the flanks' roughness.

The design-range survey (docs/validation.md, "The outputs users trust over the range of
designs") found the flank μ of the default model 1.19–1.61 × ISO/TR 14179-2 at λ 0.12–0.36
and inside the band above. This script maps where that comes from on the default case
(``kolivand2009_fm_11x41_reference``, 50 / 250 / 500 N·m, 75W90 at 90 °C, run-in flanks),
on the LTCA's own loaded flank segments (edge contacts apart, load-weighted):

* **λ by speed** — the pinion speed from 25 to 24 000 rpm (the film over the run-in Rq 0.8
  µm flanks, λ_c ≈ 0.02–1.1: the inlet's thermal reduction caps it): μ of
  ``thermal_eyring`` split into its asperity part μ_b N_a/N and its film part, Zhou &
  Hoeprich's asperity load share N_a/N, the smooth-surface central λ_c (the one the
  share takes) and the stored λ = h_min/σ, beside ISO/TR 14179-2 (Schlenk's FZG gear
  correlation), Benedict & Kelley (roller tests), ``xu2007`` (a regression of an EHL
  model) and ``mixed_ehl`` (Johnson, Greenwood & Poon's sharing) on the same segments;
* **λ by roughness** — the flanks' Ra from 0.05 to 1.0 µm at 1500 rpm (the given Rq =
  Ra/√(2/π) of each flank, run in to 0.68 × as every run; the columns' Ra is the run-in
  one the film and the correlations see), λ_c ≈ 0.1–3.2;
* **surface finishes** — the mesh efficiency and flank μ at the three torques for ground
  (Ra 0.8 µm), fine-ground (0.4), lapped/honed (0.2) and superfinished (0.1) flanks with
  each model, and the change from Ra 0.8 to 0.2 against the correlations' and the
  literature's (Britton et al., J. Tribol. 122 (2000) 354: superfinishing ground gear teeth
  from Ra ≈ 0.4 to ≈ 0.05 µm cut the friction by typically 30 %).

Usage::

    python benchmarks/friction_lambda_map.py [--file RUN.nc] [--ltca-cache DIR]

``--file``: an analysis file of ``ltca run`` (its /ltca group) instead of the default case's
LTCA (built once into the cache, as ``friction_anchors.py``'s). A few seconds per table.
"""

from __future__ import annotations

import argparse
import math
import sys
import warnings
from pathlib import Path

import numpy as np
import xarray as xr
from tabulate import tabulate

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(1, str(Path(__file__).resolve().parents[1]))

from friction_anchors import _ltca
from thermal_eyring_level import efficiency_inputs

from friction.coefficient import (
    STANDARD_INPUTS,
    FrictionModelRangeWarning,
    friction_coefficient,
)
from friction.efficiency import efficiency_analysis, loaded_segments
from friction.operating import OperatingConditions
from friction.thermal_eyring import _model_sharing

CASE, TORQUES = "kolivand2009_fm_11x41_reference", (50.0, 250.0, 500.0)
#: the models mapped beside the default (their registry names)
ANCHORS = ("iso_tr_14179_2", "benedict_kelley", "xu2007", "mixed_ehl")
SPEEDS = (25.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 1500.0, 3000.0, 6000.0, 12000.0, 24000.0)
RA_RUN_IN = (0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0)  # µm, the run-in flanks' Ra
FINISHES = (("ground", 0.8), ("fine ground", 0.4), ("lapped / honed", 0.2),
            ("superfinished", 0.1))  # the given (as-made) Ra [µm]
_RA_OVER_RQ = math.sqrt(2.0 / math.pi)
_RUN_IN = 0.68  # OperatingConditions' run-in factor (AGMA 925-A03, docs/friction.md)


def _sharing(inp: dict):
    """Zhou & Hoeprich's sharing of these inputs (the default model's): share, h_c,s."""
    kw = {k: inp[k] for k in ("load_per_length", "hertz_pressure", "radius", "e_prime",
                              "entraining_velocity", "sliding_velocity", "viscosity",
                              "pressure_viscosity", "roughness_1", "roughness_2",
                              "thermal_factor")}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        return _model_sharing(load_sharing="zhou_hoeprich", asperity_load_constants="rib",
                              summits="ground", eyring_stress=inp["eyring_stress"],
                              limiting_shear_coefficient=inp["limiting_shear_coefficient"],
                              boundary_friction=inp["boundary_friction"],
                              asperity_density_radius_sigma=0.05, sigma_over_beta=0.01, **kw)


def evaluate(lt: xr.Dataset, op: OperatingConditions, efficiency: bool = False) -> list[dict]:
    """Per torque, flank load-weighted: λ_c, λ, share, the default's μ and its parts, each
    anchor's μ on the same segments (and with ``efficiency`` each model's mesh efficiency)."""
    seg = loaded_segments(lt)
    inp, fr = efficiency_inputs(lt, op)
    sol = _sharing(inp)
    std = {k: v for k, v in inp.items() if k in STANDARD_INPUTS}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        mus = {m: np.broadcast_to(np.asarray(friction_coefficient(m, **std), float),
                                  seg.force.shape) for m in ANCHORS}
        eff = {}
        if efficiency:
            for m in ("thermal_eyring", *ANCHORS):
                o = OperatingConditions(pinion_speed=op.pinion_speed, temperature=op.temperature,
                                        roughness=op.roughness, friction_model=m)
                eff[m] = efficiency_analysis(lt, o)["efficiency_mean"].values * 100.0
    # the default model's μ per loaded segment (the efficiency stage's own evaluation)
    mu = fr["friction_coefficient"].transpose(*lt["force"].dims).values[seg.loaded]
    sigma = np.hypot(inp["roughness_1"], inp["roughness_2"])
    lam_c = sol.smooth_film_thickness / sigma
    asp = sol.boundary_friction
    torque = np.nonzero(seg.loaded)[0]
    weight = np.where(seg.edge, 0.0, seg.force)
    out = []
    for i in range(lt.sizes["torque"]):
        m = torque == i
        w = weight[m] / np.sum(weight[m])

        def mean(x, m=m, w=w):
            return float(np.sum(np.broadcast_to(x, m.shape)[m] * w))

        row = {"lam_c": mean(lam_c), "lam": mean(np.asarray(inp["lambda_ratio"], float)),
               "share": mean(sol.asperity_load_share), "mu": mean(mu), "asp": mean(asp),
               "ue": mean(np.asarray(inp["entraining_velocity"], float)),
               **{a: mean(mus[a]) for a in ANCHORS}}
        row["film"] = row["mu"] - row["asp"]
        row["eff"] = {k: float(v[i]) for k, v in eff.items()}
        out.append(row)
    return out


def _row(label, r: dict) -> list:
    return [label, f"{r['lam_c']:.3f}", f"{r['lam']:.3f}", f"{r['share']:.3f}",
            f"{r['asp']:.4f}", f"{r['film']:.4f}", f"{r['mu']:.4f}",
            f"{r['iso_tr_14179_2']:.4f}", f"{r['mu'] / r['iso_tr_14179_2']:.2f}",
            f"{r['benedict_kelley']:.4f}", f"{r['xu2007']:.4f}", f"{r['mixed_ehl']:.4f}"]


_HEAD = ["λ_c", "λ=h_min/σ", "N_a/N", "μ_b N_a/N", "film", "μ", "ISO μ", "μ/ISO",
         "B&K", "xu2007", "mixed_ehl"]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--file", type=Path, help="analysis file of `ltca run` (its /ltca)")
    ap.add_argument("--ltca-cache", type=Path,
                    default=Path.home() / ".cache" / "hypoid-ltca" / "benchmarks")
    ap.add_argument("--temperature", type=float, default=90.0)
    args = ap.parse_args(argv)
    lt = (xr.open_dataset(args.file, group="ltca").load() if args.file
          else _ltca(CASE, TORQUES, None, args.ltca_cache))
    torques = [float(t) for t in lt["torque"].values]
    rq_default = 0.8
    print(f"flank load-weighted means; 75W90 at {args.temperature:g} °C, run-in flanks "
          f"(Rq × {_RUN_IN}); thermal_eyring (the default) beside the anchors\n")
    for i, t in enumerate(torques):
        rows = []
        for n in SPEEDS:
            r = evaluate(lt, OperatingConditions(pinion_speed=n, temperature=args.temperature,
                                                 roughness=rq_default))[i]
            rows.append(_row(f"{n:g} ({r['ue']:.2f})", r))
        print(f"λ by speed, {t:g} N·m, given Rq {rq_default} µm (run-in Ra "
              f"{rq_default * _RUN_IN * _RA_OVER_RQ:.3f} µm)")
        print(tabulate(rows, headers=["rpm (u_e m/s)", *_HEAD]) + "\n")
    for i, t in enumerate(torques):
        rows = []
        for ra in RA_RUN_IN:
            rq = ra / _RA_OVER_RQ / _RUN_IN
            r = evaluate(lt, OperatingConditions(temperature=args.temperature, roughness=rq))[i]
            rows.append(_row(f"{ra:g}", r))
        print(f"λ by roughness, {t:g} N·m, 1500 rpm")
        print(tabulate(rows, headers=["run-in Ra µm", *_HEAD]) + "\n")
    res = {}
    for name, ra in FINISHES:
        res[name] = evaluate(lt, OperatingConditions(temperature=args.temperature,
                                                     roughness=ra / _RA_OVER_RQ),
                             efficiency=True)
    rows = []
    models = ("thermal_eyring", *ANCHORS)
    for name, ra in FINISHES:
        for i, t in enumerate(torques):
            r = res[name][i]
            rows.append([f"{name} (Ra {ra:g})", f"{t:g}", f"{r['lam_c']:.2f}",
                         *(f"{r['eff'][m]:.2f}" for m in models),
                         f"{r['mu']:.4f}", f"{r['iso_tr_14179_2']:.4f}"])
    print("surface finishes at 1500 rpm (given Ra, run in): mesh efficiency [%] by model, flank μ")
    print(tabulate(rows, headers=["finish", "N·m", "λ_c", *models, "μ", "ISO μ"]) + "\n")
    rows = []
    a, b = res["ground"], res["lapped / honed"]
    for i, t in enumerate(torques):
        rows.append([f"{t:g}", *(f"{b[i]['eff'][m] - a[i]['eff'][m]:+.2f}" for m in models),
                     f"{b[i]['mu'] / a[i]['mu'] - 1:+.0%}",
                     f"{b[i]['iso_tr_14179_2'] / a[i]['iso_tr_14179_2'] - 1:+.0%}",
                     f"{b[i]['xu2007'] / a[i]['xu2007'] - 1:+.0%}",
                     f"{b[i]['benedict_kelley'] / a[i]['benedict_kelley'] - 1:+.0%}"])
    print("Ra 0.8 → 0.2 µm (ground → lapped/honed): efficiency gain [points] by model; "
          "flank μ change: default, ISO, xu2007, B&K")
    print(tabulate(rows, headers=["N·m", *models, "μ", "ISO μ", "xu2007 μ", "B&K μ"]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
