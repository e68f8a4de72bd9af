"""Added cost of the tooth-root stress in one analysis, and of its FE coefficients.

Prints one table, measured in one run on the default case at its torques
(50/250/500 N·m) with the default LTCA and FE options:

* per member, the FE influence coefficients built once (time, unknowns, peak memory of
  the build as the coefficients record it) — the first run's cost of ``--root-stress``;
* the LTCA (``contact.ltca.loaded_tca``), reading the cached coefficients and the root
  stress's superposition (``contact.ltca.root_stress.root_stress``, median of 3), wall and
  CPU time (the process's: on a shared machine the wall time of BLAS-threaded work
  varies several-fold), and their ratios (the issue's target: ≤ 10 % after the cache);
* the peak root stress of both members per torque.

Run: ``python benchmarks/root_stress.py [--case NAME] [--cache-dir DIR]``. The cache
directory defaults to a fresh temporary one (so the build is measured); give the user's
cache to time only the read.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time

import numpy as np
from tabulate import tabulate

from contact.catalogue import resolve_case
from contact.compliance.fe import influence_coefficients
from contact.ltca import loaded_tca
from contact.ltca.root_stress import root_stress
from contact.utca.easeoff import ease_off


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=None)
    ap.add_argument("--cache-dir", default=None)
    args = ap.parse_args()
    cache = args.cache_dir or tempfile.mkdtemp(prefix="fe-cache-")
    case = resolve_case(args.case)
    eo = ease_off(case)
    rows = []
    for member, flank in (("pinion", eo.pinion_flank), ("gear", eo.gear_flank)):
        t0 = time.perf_counter()
        ds = influence_coefficients(case, member, flank, cache_dir=cache, progress=False)
        wall = time.perf_counter() - t0
        cost = json.loads(ds.attrs.get("cost", "{}"))
        rows.append((f"coefficients {member} (build)", f"{wall:.1f}", "",
                     f"{cost.get('n_unknowns', '')} unknowns, solver {cost.get('solver', '')}, "
                     f"peak RSS {cost.get('peak_rss_mb', float('nan')):.0f} MB"))
    torques = case.operating.torque
    w0, c0 = time.perf_counter(), time.process_time()
    lt = loaded_tca(case, torques, easeoff=eo)
    t_ltca, c_ltca = time.perf_counter() - w0, time.process_time() - c0
    w0, c0 = time.perf_counter(), time.process_time()
    coef = {m: influence_coefficients(case, m, f, cache_dir=cache, progress=False)
            for m, f in (("pinion", eo.pinion_flank), ("gear", eo.gear_flank))}
    t_read, c_read = time.perf_counter() - w0, time.process_time() - c0
    walls, cpus = [], []
    for _ in range(3):
        w0, c0 = time.perf_counter(), time.process_time()
        rs = root_stress(case, eo, lt, coefficients=coef)
        walls.append(time.perf_counter() - w0)
        cpus.append(time.process_time() - c0)
    t_rs, c_rs = float(np.median(walls)), float(np.median(cpus))
    rows.append(("LTCA (default options)", f"{t_ltca:.2f}", f"{c_ltca:.2f}",
                 f"{len(torques)} torques"))
    rows.append(("read both members' coefficients (cache)", f"{t_read:.2f}", f"{c_read:.2f}",
                 f"ratio to the LTCA {t_read / t_ltca:.3f} wall, {c_read / c_ltca:.3f} CPU"))
    rows.append(("root stress superposition (median of 3)", f"{t_rs:.2f}", f"{c_rs:.2f}",
                 f"ratio to the LTCA {t_rs / t_ltca:.3f} wall, {c_rs / c_ltca:.3f} CPU"))
    rows.append(("root stress in all (read + superposition)", f"{t_read + t_rs:.2f}",
                 f"{c_read + c_rs:.2f}",
                 f"ratio to the LTCA {(t_read + t_rs) / t_ltca:.3f} wall, "
                 f"{(c_read + c_rs) / c_ltca:.3f} CPU"))
    print(f"case {case.name}, cache {cache}")
    print(tabulate(rows, headers=["stage", "wall [s]", "CPU [s]", "note"], tablefmt="github"))
    peak = rs["root_stress_max"]
    print(tabulate([(f"{t:g}", f"{float(peak.isel(torque=i).sel(member='pinion')):.0f}",
                     f"{float(peak.isel(torque=i).sel(member='gear')):.0f}")
                    for i, t in enumerate(peak["torque"].values)],
                   headers=["T_p [N m]", "pinion [MPa]", "gear [MPa]"], tablefmt="github"))


if __name__ == "__main__":
    main()
