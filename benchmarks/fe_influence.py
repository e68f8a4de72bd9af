"""Cost of a member's FE influence coefficients and of one superposition call.

Prints two tables, measured in one run:

1. per member of the case, the influence coefficients at the default mesh
   (contact.compliance.fe.FEOptions()): unknowns, elements, loads, the time of each phase
   (sections and mesh, stiffness, factorisation, unit-load solves), the factor's
   non-zeros and the process's peak resident memory — each member built in a fresh
   process, so that its peak is its own — for every direct solver installed (CHOLMOD
   through cvxopt and SuperLU always, PARDISO with the optional extra ``fe``), with the
   ratio of the solvers' times;
2. one superposition call on the built coefficients (as the LTCA's root stress will make
   at each roll position): the compliance matrix of N contact points and the fillet
   stress of their forces, with its time as a ratio of the build's;
3. (``--first-run``) the whole ``ltca run`` of the case three ways, each in a fresh
   process: without root stress (``--no-root-stress``), with it into an empty FE cache
   (the first run of a design) and with it again (the cache read): wall and CPU time,
   peak memory, the peak root stress of each member, and the ratios to the run without
   root stress (issue 53's target: the first build ≤ 20 s of CPU per member, ≤ 1.5 GB).

Run: ``python benchmarks/fe_influence.py [--case NAME] [--members pinion gear]
[--solvers cholmod superlu pardiso] [--first-run]``. Defaults: the default case, both
members, every installed solver, no third table. Tables 1-2 read and write no cache; table
3 uses a temporary one.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np
from tabulate import tabulate

from contact.compliance.fe import SOLVERS

_CHILD = """
import json, sys, time
from contact.catalogue import resolve_case
from contact.compliance.fe import influence_coefficients
case = resolve_case(sys.argv[1])
t0 = time.perf_counter()
ds = influence_coefficients(case, sys.argv[2], cache=False, progress=False, solver=sys.argv[3])
ds.to_netcdf(sys.argv[4])
print(json.dumps({"wall_s": time.perf_counter() - t0, **json.loads(ds.attrs["cost"])}))
"""


def build(case: str, member: str, solver: str, path: str) -> dict:
    """Influence coefficients of one member in a fresh process; its cost record."""
    out = subprocess.run([sys.executable, "-c", _CHILD, case, member, solver, path],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def superposition_cost(path: str, n_points: int = 120, repeat: int = 5) -> dict:
    """Median time of fe_compliance_matrix and fillet_stress for n points on the flank."""
    import xarray as xr

    from contact.compliance.fe import fe_compliance_matrix, fillet_stress, hat_weights

    ds = xr.load_dataset(path)
    rng = np.random.default_rng(3)
    u, v = rng.uniform(0.0, 1.0, n_points), rng.uniform(0.06, 1.0, n_points)
    pos = ds["flank_position"].values.reshape(-1, 3)
    pts = hat_weights(ds.u.values, ds.v.values, u, v) @ pos  # near the flank (grid chords)
    forces = rng.uniform(1.0, 100.0, n_points)
    times = {"compliance": [], "stress": []}
    for _ in range(repeat):
        t0 = time.perf_counter()
        fe_compliance_matrix(ds, pts)
        t1 = time.perf_counter()
        fillet_stress(ds, pts, forces)
        times["compliance"].append(t1 - t0)
        times["stress"].append(time.perf_counter() - t1)
    return {k: float(np.median(v)) for k, v in times.items()}


_RUN_CHILD = """
import json, resource, runpy, sys
out = sys.argv.pop(1)
sys.argv[0] = "ltca"
try:
    runpy.run_module("contact", run_name="__main__")
finally:
    r = resource.getrusage(resource.RUSAGE_SELF)
    with open(out, "w") as f:  # ru_maxrss in kB on Linux
        json.dump({"cpu_s": r.ru_utime + r.ru_stime, "rss_mb": r.ru_maxrss / 1024}, f)
"""


def ltca_run(case: str, out: str, cache: str, *extra: str) -> dict:
    """One ``ltca run`` of the case in a fresh process: wall and CPU time [s], the
    process's own peak resident memory [MB] and the peak root stress per member [MPa]."""
    import xarray as xr

    env = {**os.environ, "HYPOID_LTCA_CACHE": cache}
    record = out + ".json"
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", _RUN_CHILD, record, "run", case, "--no-progress",
                    "-q", "-o", out, *extra], env=env, check=True, capture_output=True)
    wall = time.perf_counter() - t0
    with open(record) as f:
        usage = json.load(f)
    lt = xr.load_dataset(out, group="ltca")
    peak = (lt["root_stress_max"].max("torque").values.tolist()
            if "root_stress_max" in lt else [float("nan")] * 2)
    return {"wall_s": wall, **usage, "pinion": peak[0], "gear": peak[1]}


def first_run_table(case: str, tmp: str) -> None:
    """Table 3: ``ltca run`` without root stress, with it (empty cache), with it (cached)."""
    cache = f"{tmp}/cache"
    runs = [("--no-root-stress", ltca_run(case, f"{tmp}/a.nc", cache, "--no-root-stress")),
            ("root stress, empty cache", ltca_run(case, f"{tmp}/b.nc", cache)),
            ("root stress, cached", ltca_run(case, f"{tmp}/c.nc", cache))]
    base = runs[0][1]
    rows = [[name, r["wall_s"], r["cpu_s"], r["rss_mb"], r["pinion"], r["gear"],
             r["wall_s"] / base["wall_s"], r["cpu_s"] / base["cpu_s"]] for name, r in runs]
    print(f"\n3. ltca run {case}, each in a fresh process")
    print(tabulate(rows, headers=["run", "wall [s]", "CPU [s]", "peak RSS [MB]",
                                  "σ_F max pinion [MPa]", "σ_F max gear [MPa]",
                                  "wall / without", "CPU / without"],
                   floatfmt=("", ".2f", ".2f", ".0f", ".0f", ".0f", ".2f", ".2f")))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="kolivand2009_fm_11x41_reference")
    ap.add_argument("--members", nargs="+", default=["pinion", "gear"])
    ap.add_argument("--solvers", nargs="+", default=[s for s, ok in SOLVERS.items() if ok()])
    ap.add_argument("--first-run", action="store_true",
                    help="also table 3: ltca run without root stress, first run, cached")
    args = ap.parse_args(argv)
    import tempfile

    rows, costs = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        for member in args.members:
            for solver in args.solvers:
                path = f"{tmp}/{member}_{solver}.nc"
                c = build(args.case, member, solver, path)
                costs[member, solver] = (c, path)
                rows.append([member, solver, c["n_unknowns"], c["n_elements"], c["n_loads"],
                             c["time_solid_s"], c["time_assembly_s"],
                             c["time_factorisation_s"], c["time_solves_s"], c["wall_s"],
                             # CHOLMOD through cvxopt does not report its factor's size (-1)
                             c["factor_nonzeros"] / 1e6 if c["factor_nonzeros"] >= 0
                             else float("nan"), c.get("peak_rss_mb", float("nan"))])
        print(f"\n1. FE influence coefficients of {args.case}, default mesh, one member per "
              "process")
        print(tabulate(rows, headers=["member", "solver", "unknowns", "elements", "loads",
                                      "mesh [s]", "stiffness [s]", "factor [s]",
                                      "solves [s]", "total [s]", "factor nnz [1e6]",
                                      "peak RSS [MB]"], floatfmt=".1f"))
        if len(args.solvers) > 1:
            ref = args.solvers[0]
            print("\ntime ratio to " + ref + ": " + ", ".join(
                f"{m} {s} {costs[m, s][0]['wall_s'] / costs[m, ref][0]['wall_s']:.2f}"
                for m in args.members for s in args.solvers[1:]))
        rows = []
        for member in args.members:
            c, path = costs[member, args.solvers[-1]]
            t = superposition_cost(path)
            rows.append([member, 120, 1e3 * t["compliance"], 1e3 * t["stress"],
                         (t["compliance"] + t["stress"]) / c["wall_s"]])
        print("\n2. One superposition call (120 contact points): compliance matrix and "
              "fillet stress")
        print(tabulate(rows, headers=["member", "points", "compliance [ms]", "stress [ms]",
                                      "ratio to build"], floatfmt=".4g"))
        if args.first_run:
            first_run_table(args.case, tmp)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
