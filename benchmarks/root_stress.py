"""Added cost of the tooth-root stress in one analysis, and of its FE coefficients.

Prints one table, measured in one run on the default case at its torques
(50/250/500 N·m) with the default LTCA and FE options:

* per member, the FE influence coefficients built once (time, unknowns, peak memory of
  the build as the coefficients record it) — the first run's cost of ``--root-stress``;
* the LTCA (``contact.ltca.loaded_tca``) and the root stress from the cached
  coefficients (``contact.ltca.root_stress.root_stress``: reading the cache and the
  superposition), and their ratio (the issue's target: ≤ 10 % after the cache);
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
        rows.append((f"coefficients {member}", f"{wall:.1f}",
                     f"{cost.get('n_unknowns', '')} unknowns, solver {cost.get('solver', '')}, "
                     f"peak RSS {cost.get('peak_rss_mb', float('nan')):.0f} MB"))
    torques = case.operating.torque
    t0 = time.perf_counter()
    lt = loaded_tca(case, torques, easeoff=eo)
    t_ltca = time.perf_counter() - t0
    t0 = time.perf_counter()
    rs = root_stress(case, eo, lt, cache_dir=cache)
    t_rs = time.perf_counter() - t0
    rows.append(("LTCA (default options)", f"{t_ltca:.1f}", f"{len(torques)} torques"))
    rows.append(("root stress, cached coefficients", f"{t_rs:.2f}",
                 f"ratio to the LTCA {t_rs / t_ltca:.3f} (superposition "
                 f"{rs.attrs['time_root_stress_s']:.2f} s)"))
    print(f"case {case.name}, cache {cache}")
    print(tabulate(rows, headers=["stage", "time [s]", "note"], tablefmt="github"))
    peak = rs["root_stress_max"]
    print(tabulate([(f"{t:g}", f"{float(peak.isel(torque=i).sel(member='pinion')):.0f}",
                     f"{float(peak.isel(torque=i).sel(member='gear')):.0f}")
                    for i, t in enumerate(peak["torque"].values)],
                   headers=["T_p [N m]", "pinion [MPa]", "gear [MPa]"], tablefmt="github"))


if __name__ == "__main__":
    main()
