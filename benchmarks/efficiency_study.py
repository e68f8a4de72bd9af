"""The seed's chapter 5 efficiency study (§5.3, Figs. 5.11–5.12) with two friction models.

Runs the loaded TCA of the seed's Table 5.4 designs A and B (face-hobbed cases
``kolivand2009_table54_A_fh`` / ``_B_fh``, 20 rolls per cycle) once per torque, then the
efficiency stage (:func:`friction.efficiency.efficiency_analysis`) over

* speed 100–3000 rpm × torque 100/500/1000 N·m at 90 °C, Rq 0.8 µm (seed Fig. 5.11), and
* oil temperature 50/75/100 °C × roughness Rq 0.1–1.3 µm at 1500 rpm, 500 N·m (Fig. 5.12),

for the friction models named on the command line (default ``kolivand2009``, ``xu2007`` and
``mixed_ehl``), and prints the efficiency tables [%], the load-weighted mean λ and μ, the
trends the seed reports, each measured, and the A − B gap at the seed's operating point
(1500 rpm, 500 N·m) split into the flanks' sliding per transmitted power (the offset's
kinematics), their μ, and the edges (docs/friction.md, "A against B").

Slow (about 10–20 min on one core: six LTCA runs). Usage::

    python benchmarks/efficiency_study.py [--models kolivand2009 xu2007 mixed_ehl] [--rolls 20]
        [--cache DIR]   # reuse LTCA results written there
        [--reference]   # the optimised reference designs of A and B (issue 37)
"""

from __future__ import annotations

import argparse
import json
import warnings
from pathlib import Path

import numpy as np
import xarray as xr
from tabulate import tabulate

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from friction.coefficient import FrictionModelRangeWarning
from friction.efficiency import efficiency_analysis
from friction.operating import OperatingConditions

CASES = {"A": "kolivand2009_table54_A_fh", "B": "kolivand2009_table54_B_fh"}
TORQUES = (100.0, 500.0, 1000.0)
SPEEDS = (100.0, 250.0, 500.0, 1000.0, 1500.0, 2000.0, 2500.0, 3000.0)
TEMPERATURES = (50.0, 75.0, 100.0)
ROUGHNESS = (0.1, 0.3, 0.5, 0.7, 0.9, 1.1, 1.3)


def _ltca(design: str, rolls: int, cache: Path | None, suffix: str = "") -> xr.Dataset:
    path = None if cache is None else cache / f"ltca_{design}{suffix}_{rolls}.nc"
    if path is not None and path.is_file():
        return xr.load_dataset(path)
    lt = loaded_tca(resolve_case(CASES[design] + suffix), list(TORQUES),
                    options=LTCAOptions(rolls_per_cycle=rolls))
    if path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        lt.to_netcdf(path)
    return lt


def _weighted(fr: xr.Dataset, name: str, force: xr.DataArray) -> np.ndarray:
    dims = ("roll", "pair", "segment")
    return ((fr[name].fillna(0) * force).sum(dims) / force.sum(dims)).values


def _point(lt: xr.Dataset, model: str, speed: float, temp: float, rq: float) -> dict:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        fr = efficiency_analysis(lt, OperatingConditions(
            pinion_speed=speed, temperature=temp, roughness=rq, friction_model=model))
    force = lt["force"].fillna(0.0)
    return {
        "eff": fr["efficiency_mean"].values * 100,
        "lam": _weighted(fr, "lambda_ratio", force),
        "mu": _weighted(fr, "friction_coefficient", force),
        "flag": float(fr["friction_model_extrapolated"].where(lt["force"] > 0).mean()),
        "why": json.loads(fr.attrs.get("model_range_warnings", "[]")),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--models", nargs="+", default=["kolivand2009", "xu2007", "mixed_ehl"])
    ap.add_argument("--rolls", type=int, default=20)
    ap.add_argument("--cache", type=Path, default=None)
    ap.add_argument("--reference", action="store_true",
                    help="the optimised reference designs (kolivand2009_table54_*_fh_reference, "
                    "issue 37) instead of the long-bearing pairs")
    args = ap.parse_args(argv)
    suffix = "_reference" if args.reference else ""
    print(f"designs: {', '.join(CASES[d] + suffix for d in CASES)}")
    lts = {d: _ltca(d, args.rolls, args.cache, suffix) for d in CASES}
    for model in args.models:
        print(f"\n## friction model {model}\n")
        speed = {d: [_point(lts[d], model, n, 90.0, 0.8) for n in SPEEDS] for d in CASES}
        rows = []
        for i, t in enumerate(TORQUES):
            pair = (f"{speed['A'][j]['eff'][i]:.2f} / {speed['B'][j]['eff'][i]:.2f}"
                    for j in range(len(SPEEDS)))
            rows.append([f"{t:g}", *pair])
        print("Efficiency [%] at 90 C, Rq 0.8 um, A / B")
        print(tabulate(rows, headers=["T_p [N m]", *(f"{n:g} rpm" for n in SPEEDS)],
                       tablefmt="github"))
        lam = [[f"{speed[d][j]['lam'][1]:.2f}" for j in range(len(SPEEDS))] for d in CASES]
        mu = [[f"{speed[d][j]['mu'][1]:.4f}" for j in range(len(SPEEDS))] for d in CASES]
        print("\nLoad-weighted mean lambda (h_min/sigma) and mu at 500 N m, A and B")
        print(tabulate([["lambda A", *lam[0]], ["lambda B", *lam[1]], ["mu A", *mu[0]],
                        ["mu B", *mu[1]]],
                       headers=["", *(f"{n:g}" for n in SPEEDS)], tablefmt="github"))
        grid = {d: [[_point(lts[d], model, 1500.0, tc, rq)["eff"][1] for rq in ROUGHNESS]
                    for tc in TEMPERATURES] for d in CASES}
        rows = [[f"{tc:g} C", *(f"{grid['A'][k][m]:.2f} / {grid['B'][k][m]:.2f}"
                                for m in range(len(ROUGHNESS)))]
                for k, tc in enumerate(TEMPERATURES)]
        print("\nEfficiency [%] at 1500 rpm, 500 N m, A / B")
        print(tabulate(rows, headers=["oil", *(f"Rq {r:g}" for r in ROUGHNESS)],
                       tablefmt="github"))
        flags = {d: [p["flag"] for p in speed[d]] for d in CASES}
        print("\nLoaded segments outside the model's range (friction_model_extrapolated), "
              "share per speed (90 C, Rq 0.8 um, all torques), A / B: "
              + ", ".join(f"{flags['A'][j]:.0%} / {flags['B'][j]:.0%}"
                          for j in range(len(SPEEDS))))
        at = SPEEDS.index(1500.0)
        for d in CASES:
            print(f"  {d} at 1500 rpm, why: {'; '.join(speed[d][at]['why']) or 'none'}")
        _trends(model, speed, grid)
        _gap(model, lts)
    return 0


def _gap(model: str, lts: dict) -> None:
    """Print the A − B efficiency gap at 1500 rpm, 500 N·m, 90 °C, Rq 0.8 µm split into
    the flanks' and the edges' sliding loss, each into kinematics K = Σ F|V_s| / P_in
    (the sliding per unit of transmitted power, set by the offset) and the load-and-sliding
    weighted μ̄ = Σ μ F|V_s| / Σ F|V_s| (loss = μ̄ K; ΔK at the mean μ̄, Δμ̄ at the mean K),
    and the rolling loss."""
    parts = {}
    for d in CASES:
        lt = lts[d].sel(torque=[500.0])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            fr = efficiency_analysis(lt, OperatingConditions(friction_model=model))
        force = lt["force"].values
        loaded = np.isfinite(force) & (force > 0)
        edge = np.broadcast_to((lt["segment_kind"] != "curve").values, force.shape)
        p_in = 500.0 * 2.0 * np.pi * 1500.0 / 60.0 * force.shape[1]  # summed over rolls
        fv = np.where(loaded, force * fr["sliding_velocity"].values, 0.0)
        mu = np.where(loaded, fr["friction_coefficient"].values, 0.0)
        parts[d] = {name: (fv[m].sum() / p_in, (mu * fv)[m].sum() / fv[m].sum())
                    for name, m in (("flank", loaded & ~edge), ("edge", loaded & edge))}
        parts[d]["rolling"] = float(np.nansum(fr["rolling_loss"].values)) / p_in
        parts[d]["efficiency"] = float(fr["efficiency_mean"][0])
    total = 100 * (parts["A"]["efficiency"] - parts["B"]["efficiency"])
    print(f"\nA - B at 1500 rpm, 500 N m ({model}): {total:.2f} points")
    for name in ("flank", "edge"):
        (ka, ma), (kb, mb) = parts["A"][name], parts["B"][name]
        print(f" - {name}s: K {ka:.3f} / {kb:.3f}, mu {ma:.4f} / {mb:.4f}: "
              f"{100 * (mb * kb - ma * ka):.2f} points = kinematics "
              f"{100 * 0.5 * (ma + mb) * (kb - ka):.2f} + mu "
              f"{100 * 0.5 * (ka + kb) * (mb - ma):.2f}")
    print(f" - rolling loss: {100 * (parts['B']['rolling'] - parts['A']['rolling']):.3f} points")


def _trends(model: str, speed: dict, grid: dict) -> None:
    """Print the seed's §5.3 trends, each measured on this model's results."""
    eff = {d: np.array([p["eff"] for p in speed[d]]) for d in CASES}  # (speed, torque)
    lam = {d: np.array([p["lam"] for p in speed[d]]) for d in CASES}
    lines = []
    for d in CASES:
        e = eff[d]
        worst = [SPEEDS[k] for k in np.argmin(e, axis=0)]
        best = [SPEEDS[k] for k in np.argmax(e, axis=0)]
        lines.append(f"{d}: per torque {list(TORQUES)} the least efficient speed is {worst} rpm,"
                     f" the most efficient {best} rpm (seed: a dip at low speed, then a rise);"
                     f" lambda at {SPEEDS[0]:g} rpm {np.round(lam[d][0], 2).tolist()}")
        lines.append(f"{d}: torque order at {SPEEDS[0]:g} rpm {np.argsort(-e[0]).tolist()}, "
                     f"at 3000 rpm {np.argsort(-e[-1]).tolist()} (indices of {list(TORQUES)}, "
                     "best first)")
        g = np.array(grid[d])  # (temperature, roughness)
        hot_better = (g[-1] > g[0]).tolist()
        lines.append(f"{d}: 100 C better than 50 C at Rq {list(ROUGHNESS)}: {hot_better}")
    gap = eff["A"] - eff["B"]
    lines.append(f"A - B efficiency gap [points]: {gap.min():.2f} to {gap.max():.2f} "
                 f"(mean {gap.mean():.2f}; seed about 1.5)")
    print(f"\nTrends ({model}):")
    for ln in lines:
        print(" -", ln)


if __name__ == "__main__":
    raise SystemExit(main())
