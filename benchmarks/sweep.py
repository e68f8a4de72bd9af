"""Benchmark of the study engine: a ΔE × ΔP map at one torque on 1 and 2 local workers.

Prints points per second, the speed-up from 1 to 2 workers, the time per point against
one ``run_analysis`` in the same run, and the peak memory (RSS) of the client and of the
workers at 100 and at all (default 441) points — memory should be flat in the number of
points. Targets on the 2-core machine (issue 18): ≥ 3 points/s with 2 workers, speed-up
≥ 1.7, memory flat.

    python benchmarks/sweep.py              # 21 x 21 map (about 10 min on 2 cores)
    python benchmarks/sweep.py --grid 11    # 11 x 11, quicker
"""

from __future__ import annotations

import argparse
import resource
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import psutil
from tabulate import tabulate

from contact.catalogue import resolve_case
from contact.pipeline import run_analysis
from contact.study import StudyRun, sweep
from geometry.pair.assembly import Misalignment

TORQUE = 250.0


class PeakRSS:
    """Peak resident memory of this process, sampled every 50 ms while in the block."""

    def __init__(self) -> None:
        self.peak = 0
        self._stop = threading.Event()

    def _sample(self) -> None:
        proc = psutil.Process()
        while not self._stop.is_set():
            self.peak = max(self.peak, proc.memory_info().rss)
            time.sleep(0.05)

    def __enter__(self) -> PeakRSS:
        self._thread = threading.Thread(target=self._sample, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        self._thread.join()


def _worker_peak() -> int:
    """Peak RSS [bytes] of a worker process over its life (Linux: ru_maxrss in KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def run_map(n: int, workers: int, out_dir: Path) -> dict:
    """A n × n map on a fresh LocalCluster of ``workers`` processes."""
    from distributed import Client, LocalCluster

    dE = np.linspace(-0.2, 0.2, n)
    dP = np.linspace(-0.2, 0.2, n)
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client, \
            PeakRSS() as client_mem:
        t0 = time.perf_counter()
        ds = sweep(None, delta_E=dE, delta_P=dP, torque=TORQUE,
                   run=StudyRun(scheduler=client, output=out_dir / f"map_{n}_{workers}.nc"))
        wall = time.perf_counter() - t0
        worker_mem = max(client.run(_worker_peak).values())
    st = ds["status"].values
    return {"points": n * n, "workers": workers, "wall": wall, "rate": n * n / wall,
            "client_MB": client_mem.peak / 2**20, "worker_MB": worker_mem / 2**20,
            "failed": int((st == 2).sum())}


def single_time(repeats: int = 5) -> float:
    """Mean time [s] of one run_analysis (one torque, no geometry) at distinct ΔE."""
    case = resolve_case(None)
    run_analysis(case, [TORQUE], geometry=False)  # imports, tooth models
    times = []
    for e in np.linspace(-0.1, 0.1, repeats):
        t0 = time.perf_counter()
        run_analysis(case, [TORQUE], misalignment=Misalignment(delta_E=float(e)),
                     geometry=False)
        times.append(time.perf_counter() - t0)
    return float(np.mean(times))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=21, help="values per axis (default 21)")
    ap.add_argument("--small", type=int, default=10,
                    help="values per axis of the small map of the memory check (default 10)")
    args = ap.parse_args()
    t_single = single_time()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        r1 = run_map(args.grid, 1, tmp)
        r2 = run_map(args.grid, 2, tmp)
        small = run_map(args.small, 2, tmp)
    for r in (small, r1, r2):
        rows.append((r["points"], r["workers"], f"{r['wall']:.1f}", f"{r['rate']:.2f}",
                     f"{r['workers'] / r['rate']:.3f}", f"{r['client_MB']:.0f}",
                     f"{r['worker_MB']:.0f}", r["failed"]))
    print(tabulate(rows, headers=("points", "workers", "wall [s]", "points/s",
                                  "s/point/worker", "client peak [MB]",
                                  "worker peak [MB]", "failed"), tablefmt="github"))
    print(f"one run_analysis (same torque, in this process): {t_single:.3f} s")
    print(f"speed-up 1 -> 2 workers: {r2['rate'] / r1['rate']:.2f} (target >= 1.7)")
    print(f"2 workers: {r2['rate']:.2f} points/s (target >= 3); "
          f"1000 points in {1000 / r2['rate'] / 60:.1f} min")
    print(f"memory from {small['points']} to {r2['points']} points: client "
          f"{r2['client_MB'] / small['client_MB']:.2f}x, workers "
          f"{r2['worker_MB'] / small['worker_MB']:.2f}x (flat: about 1)")


if __name__ == "__main__":
    main()
