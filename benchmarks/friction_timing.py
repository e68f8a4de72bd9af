"""Time per condition of the two μ models, and an efficiency study's conditions per second.

Prints, measured in one run (issue 61):

1. the efficiency stage (:func:`friction.efficiency.efficiency_analysis`) on the default
   case's LTCA (50 / 250 / 500 N·m, the LTCA computed once and cached as in
   ``benchmarks/friction_anchors.py``) with ``mixed_ehl`` (the default of issues 61–74),
   ``thermal_eyring`` (the default since issue 74) and ``kolivand2009`` (of issues 34–61):
   seconds per operating condition (one speed, temperature and roughness over all torques,
   rolls and segments) and the μ model's own evaluation per loaded segment;
2. the stochastic mixed-EHL line-contact solver that ``kolivand2009`` is fitted to, on one
   flank-like condition (1 GPa, R 20 mm, 2.2 m/s, SR 0.66, 90 °C, Rq 0.544 µm each): seconds
   per condition;
3. each μ model alone on 20 000 random gear-like flank segments (p_h 0.3–1.6 GPa, R
   5–40 mm, u 0.5–20 m/s, SR 0–1, 75W90 at 90 °C, Rq 0.544 µm each): CPU seconds, best of
   ``--repeats`` (the ``thermal_eyring`` cost of docs/friction.md, issue 74);
4. a small efficiency map (:func:`contact.study.efficiency.efficiency_map`: 2 torques ×
   2 speeds × 2 oil temperatures × 2 roughnesses of the default case, one mesh cycle of
   6 rolls) on a Dask LocalCluster of 2 single-threaded workers, per μ model: conditions
   per second, the LTCAs included (one task per torque).

Usage::

    python benchmarks/friction_timing.py [--ltca-cache DIR] [--repeats 3] [--no-cluster]
    python benchmarks/friction_timing.py --segments-only   # item 3 alone, no LTCA
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from tabulate import tabulate

sys.path.insert(0, str(Path(__file__).resolve().parent))
# this tree, not an installed copy (a non-editable `pip install .` leaves one in site-packages)
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from friction_anchors import CASES, _ltca

from friction.coefficient import FrictionModelRangeWarning, friction_coefficient
from friction.efficiency import efficiency_analysis
from friction.lubricant import load_lubricant, pressure_viscosity_coefficient, viscosity
from friction.operating import OperatingConditions

MODELS = ("mixed_ehl", "thermal_eyring", "kolivand2009")

#: E′ = 2E* [MPa] of steel on steel (206 GPa, ν 0.3), as benchmarks/friction_anchors.py
E_PRIME = 206000.0 / (1.0 - 0.3**2)


def _best(fn, repeats: int, clock=time.perf_counter) -> float:
    """The least of ``repeats`` timings of ``fn()`` by ``clock`` (wall by default)."""
    best = np.inf
    for _ in range(repeats):
        t = clock()
        fn()
        best = min(best, clock() - t)
    return float(best)


def stage_rows(cache: Path, repeats: int) -> list[list]:
    """Seconds per efficiency-stage condition and per segment of each μ model."""
    _label, case, torques, rolls = CASES[0]
    lt = _ltca(case, torques, rolls, cache)
    force = lt["force"].values
    n_seg = int(np.count_nonzero(np.isfinite(force) & (force > 0)))
    oil = load_lubricant("75W90")
    rows = []
    for model in MODELS:
        op = OperatingConditions(friction_model=model)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            fr = efficiency_analysis(lt, op)  # warm-up (imports, coefficient files)
            stage = _best(lambda op=op: efficiency_analysis(lt, op), repeats)
            loaded = np.isfinite(force) & (force > 0)
            pick = {k: fr[k].values[loaded] for k in ("rolling_velocity", "sliding_velocity",
                                                      "slide_to_roll_total", "lambda_ratio")}
            inputs = dict(
                hertz_pressure=lt["pressure_max"].values[loaded],
                load_per_length=lt["load_per_length"].values[loaded],
                radius=np.broadcast_to(lt["equivalent_radius"].values, force.shape)[loaded],
                entraining_velocity=pick["rolling_velocity"],
                sliding_velocity=pick["sliding_velocity"],
                slide_to_roll=pick["slide_to_roll_total"], lambda_ratio=pick["lambda_ratio"],
                viscosity=float(viscosity(oil, op.temperature)),
                pressure_viscosity=float(pressure_viscosity_coefficient(oil, op.temperature)),
                e_prime=E_PRIME, roughness_1=op.effective_roughness,
                roughness_2=op.effective_roughness, temperature=op.temperature)
            mu_time = _best(lambda m=model, kw=inputs: friction_coefficient(m, **kw), repeats)
        rows.append([model, f"{stage:.3f}", n_seg, f"{1e6 * mu_time / n_seg:.2f}"])
    return rows


def segment_rows(repeats: int, n: int = 20000) -> list[list]:
    """CPU seconds of each μ model alone on ``n`` random gear-like flank segments."""
    from friction.efficiency import _alpha_temperature_coefficient
    from friction.lubricant import temperature_viscosity_coefficient, thermal_conductivity

    rng = np.random.default_rng(0)
    ph = rng.uniform(300.0, 1600.0, n)
    radius = rng.uniform(5.0, 40.0, n)
    u = rng.uniform(0.5, 20.0, n)
    sr = rng.uniform(0.0, 1.0, n)
    oil = load_lubricant("75W90")
    inputs = dict(
        hertz_pressure=ph, radius=radius, load_per_length=2.0 * np.pi * radius * ph**2 / E_PRIME,
        entraining_velocity=u, sliding_velocity=sr * u, slide_to_roll=sr,
        viscosity=float(viscosity(oil, 90.0)),
        pressure_viscosity=float(pressure_viscosity_coefficient(oil, 90.0)), e_prime=E_PRIME,
        roughness_1=0.544, roughness_2=0.544, temperature=90.0)
    rows = []
    for model in MODELS:
        kw = dict(inputs)
        if model == "thermal_eyring":
            kw.update(temperature_viscosity=float(temperature_viscosity_coefficient(oil, 90.0)),
                      oil_thermal_conductivity=float(thermal_conductivity(oil, 90.0)),
                      pressure_viscosity_temperature=_alpha_temperature_coefficient(oil, 90.0))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            friction_coefficient(model, **kw)  # warm-up
            t = _best(lambda m=model, kw=kw: friction_coefficient(m, **kw), repeats,
                      clock=time.process_time)
        rows.append([model, n, f"{t:.3f}"])
    return rows


def solver_row(repeats: int) -> list:
    """Seconds per condition of the stochastic solver (the study's and the fit's)."""
    import math

    from threadpoolctl import threadpool_limits

    from friction.ehl.line_contact import LineContactCondition
    from friction.ehl.roughness import GroundSurface
    from friction.ehl.stochastic import stochastic_summary

    w = 2.0 * math.pi * 20.0 * 1000.0**2 / E_PRIME
    cond = LineContactCondition(load_per_length=w, radius=20.0, entraining_velocity=2.2,
                                slide_to_roll=0.66, temperature=90.0)
    surfaces = (GroundSurface(0.544, seed=1), GroundSurface(0.544, seed=2))
    with threadpool_limits(limits=1):
        stochastic_summary(cond, surfaces)
        t = _best(lambda: stochastic_summary(cond, surfaces), repeats)
    return ["stochastic solver (512 nodes), one condition", f"{t:.3f}"]


def cluster_rows() -> list[list]:
    """Conditions per second of a small efficiency map on 2 LocalCluster workers."""
    from contact.ltca import LTCAOptions
    from contact.study.efficiency import efficiency_map

    rows = []
    for model in MODELS:
        op = OperatingConditions(friction_model=model)
        t = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            ds = efficiency_map(CASES[0][1], torque=(100.0, 500.0), speed=(500.0, 4000.0),
                                temperature=(50.0, 100.0), roughness=(0.1, 0.8),
                                operating=op,
                                options=LTCAOptions(cycles=1, rolls_per_cycle=6, segments=12),
                                scheduler=None, n_workers=2)
        wall = time.perf_counter() - t
        n = int(ds["efficiency"].size)
        rows.append([model, n, f"{wall:.1f}", f"{n / wall:.2f}"])
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ltca-cache", type=Path,
                    default=Path.home() / ".cache" / "hypoid-ltca" / "benchmarks")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--no-cluster", action="store_true", help="leave out the 2-worker map")
    ap.add_argument("--segments-only", action="store_true",
                    help="only the μ models on random segments (item 3)")
    args = ap.parse_args(argv)
    seg_table = tabulate(segment_rows(args.repeats),
                         headers=["μ model", "segments", "CPU s, best of repeats"])
    if args.segments_only:
        print(seg_table)
        return 0
    print("Efficiency stage on the default case's LTCA (50/250/500 N·m; best of "
          f"{args.repeats})")
    print(tabulate(stage_rows(args.ltca_cache, args.repeats),
                   headers=["μ model", "s per condition", "loaded segments",
                            "μ model alone [µs per segment]"]))
    print()
    print(tabulate([solver_row(args.repeats)], headers=["", "s per condition"]))
    print("\nEach μ model alone, 20 000 random gear-like flank segments")
    print(seg_table)
    if not args.no_cluster:
        print("\nEfficiency map, default case, 2 torques × 2 speeds × 2 °C × 2 Rq, 6 rolls, "
              "LocalCluster of 2 workers (LTCAs included)")
        print(tabulate(cluster_rows(), headers=["μ model", "conditions", "wall [s]",
                                                "conditions/s"]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
