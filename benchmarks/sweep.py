"""Benchmark of the study engine: ΔE × ΔP maps at one torque on 1 and 2 local workers.

    python benchmarks/sweep.py              # 21 x 21 maps (about 15 min on 2 quiet cores)
    python benchmarks/sweep.py --grid 11    # 11 x 11, quicker
    python benchmarks/sweep.py --case kolivand2009_fm_11x41   # one case only

The bundled default case (the reference design) and the long-bearing
``kolivand2009_fm_11x41`` side by side, each swept over ΔE, ΔP ∈ [−0.2, 0.2] mm at
250 N·m. Per case it prints:

* **CPU seconds per study point** — in this process (``analyse_point``, BLAS on one thread,
  median over points of the map) and per worker (the workers' process CPU time over the
  map, from Dask, divided by the points: what a point costs a worker, Dask's own work and
  each worker's one-off tooth models and forward map included);
* **points per second** on a LocalCluster of 1 and of 2 single-threaded workers (started by
  the study engine, :func:`contact.study.engine.open_client`, as ``sweep`` starts it), and
  the speed-up from 1 to 2;
* **each stage's share** of the workers' CPU time (``benchmarks/stage_clock.py`` installed
  in the workers);
* the peak memory (RSS) of client and workers at ``--small``² and at all points (the
  default case): memory should be flat in the number of points.

Points per second are wall-clock rates and depend on the machine's load (the load average
is printed); CPU seconds per point do much less. Targets on the 2-core machine (issue 32):
≥ 6 points/s with 2 workers when the machine is quiet (a point ≤ 0.25 s of CPU), speed-up
≥ 1.8, memory flat.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import tempfile
import threading
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
import psutil  # noqa: E402
import stage_clock  # noqa: E402
from tabulate import tabulate  # noqa: E402

from contact.catalogue import resolve_case  # noqa: E402
from contact.study import StudyRun, sweep  # noqa: E402
from contact.study.engine import analyse_point, open_client  # noqa: E402
from contact.study.points import StudyInputs  # noqa: E402
from contact.utca.fields import kernels_module  # noqa: E402

TORQUE = 250.0
#: the stage clock's source, uploaded to the workers (read here: an upload replaces the
#: module in the scheduler's process, which a LocalCluster shares with this one)
CLOCK_FILE = str(Path(stage_clock.__file__).resolve())
LONG_BEARING = "kolivand2009_fm_11x41"
TARGET_RATE = 6.0  # points/s on 2 workers, quiet machine
TARGET_SPEEDUP = 1.8


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


def _axes(n: int) -> tuple[np.ndarray, np.ndarray]:
    return np.linspace(-0.2, 0.2, n), np.linspace(-0.2, 0.2, n)


def run_map(case, n: int, workers: int, out_dir: Path) -> dict:
    """A n × n map of ``case`` on a fresh LocalCluster of ``workers`` processes."""
    dE, dP = _axes(n)
    with open_client(None, workers) as client, PeakRSS() as client_mem:
        client.upload_file(CLOCK_FILE, load=False)
        before = client.run(stage_clock.worker_clock, "install")
        t0 = time.perf_counter()
        ds = sweep(case, delta_E=dE, delta_P=dP, torque=TORQUE,
                   run=StudyRun(scheduler=client,
                                output=out_dir / f"map_{case.name}_{n}_{workers}.nc"))
        wall = time.perf_counter() - t0
        after = client.run(stage_clock.worker_clock, "remove")
        worker_mem = max(client.run(_worker_peak).values())
    cpu = sum(after[w]["process"] - before[w]["process"] for w in after)
    stages: dict[str, float] = {}
    for w in after:
        for name, sec in after[w].items():
            if name != "process":
                stages[name] = stages.get(name, 0.0) + sec
    stages["Dask and the rest"] = cpu - sum(stages.values())
    st = ds["status"].values
    return {"points": n * n, "workers": workers, "wall": wall, "rate": n * n / wall,
            "cpu_per_point": cpu / (n * n), "stages": stages, "cpu": cpu,
            "client_MB": client_mem.peak / 2**20, "worker_MB": worker_mem / 2**20,
            "failed": int((st == 2).sum())}


def in_process_cpu(case, n: int, count: int = 9) -> list[float]:
    """CPU time [s] of ``count`` study points of the map, in this process (after one
    warm-up point: imports, the tooth models, the forward map)."""
    shared = StudyInputs(case=case, torque=(TORQUE,))
    dE, dP = _axes(n)
    analyse_point(shared, 0, {"delta_E": 0.0, "delta_P": 0.0})
    out = []
    rng = np.random.default_rng(1)
    for i, j in rng.integers(0, n, size=(count, 2)):
        t0 = time.process_time()
        analyse_point(shared, 0, {"delta_E": float(dE[i]), "delta_P": float(dP[j])})
        out.append(time.process_time() - t0)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=21, help="values per axis (default 21)")
    ap.add_argument("--small", type=int, default=10,
                    help="values per axis of the small map of the memory check (default 10; "
                         "0: no memory check)")
    ap.add_argument("--case", action="append", default=None, metavar="CASE",
                    help="case(s) to sweep (default: the bundled default and "
                         f"{LONG_BEARING})")
    args = ap.parse_args()
    # (None: the bundled default; DEFAULT_CASE is its file name, which resolve_case reads
    # as a path)
    names = args.case or [None, LONG_BEARING]
    cases = [resolve_case(n) for n in names]
    load0 = os.getloadavg()[0]
    res = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for case in cases:
            r = {"name": case.name, "in_process": in_process_cpu(case, args.grid)}
            r[1] = run_map(case, args.grid, 1, tmp)
            r[2] = run_map(case, args.grid, 2, tmp)
            res.append(r)
        small = (run_map(cases[0], args.small, 2, tmp) if args.small > 0 else None)
    print(f"{args.grid} x {args.grid} dE x dP maps at {TORQUE:g} N m; load average "
          f"{load0:.1f} -> {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; "
          f"kernels: {'numpy' if kernels_module() is None else 'numba'} (LTCA_KERNELS)")
    headers = ["", *(r["name"] for r in res)]
    rows = [
        ["CPU s per point, in this process (median)",
         *(f"{statistics.median(r['in_process']):.3f}" for r in res)],
        ["CPU s per point per worker, 1 worker", *(f"{r[1]['cpu_per_point']:.3f}" for r in res)],
        ["CPU s per point per worker, 2 workers",
         *(f"{r[2]['cpu_per_point']:.3f}" for r in res)],
        ["points/s, 1 worker", *(f"{r[1]['rate']:.2f}" for r in res)],
        ["points/s, 2 workers", *(f"{r[2]['rate']:.2f}" for r in res)],
        ["speed-up 1 -> 2 workers", *(f"{r[2]['rate'] / r[1]['rate']:.2f}" for r in res)],
        ["wall s, 2 workers", *(f"{r[2]['wall']:.1f}" for r in res)],
        ["failed points", *(str(r[2]["failed"]) for r in res)],
    ]
    print(tabulate(rows, headers=headers, tablefmt="github"))
    print()
    print("each stage's share of the workers' CPU time (2 workers):")
    names_st = sorted({n for r in res for n in r[2]["stages"]},
                      key=lambda n: -res[0][2]["stages"].get(n, 0.0))
    rows = [[n, *(f"{1e3 * r[2]['stages'].get(n, 0.0) / r[2]['points']:.1f} ms "
                  f"({100 * r[2]['stages'].get(n, 0.0) / r[2]['cpu']:.0f} %)" for r in res)]
            for n in names_st]
    print(tabulate(rows, headers=["stage (per point)", *(r["name"] for r in res)],
                   tablefmt="github"))
    ref = res[0]
    print()
    print(f"{ref['name']}: 2 workers {ref[2]['rate']:.2f} points/s (target >= {TARGET_RATE:g} "
          f"on a quiet machine), speed-up {ref[2]['rate'] / ref[1]['rate']:.2f} (target >= "
          f"{TARGET_SPEEDUP:g}); 1000 points in {1000 / ref[2]['rate'] / 60:.1f} min; "
          f"{ref[2]['cpu_per_point']:.3f} CPU s per point per worker = at most "
          f"{2.0 / ref[2]['cpu_per_point']:.1f} points/s on 2 idle cores")
    if small is not None:
        big = ref[2]
        print(f"memory from {small['points']} to {big['points']} points ({ref['name']}, 2 "
              f"workers): client {small['client_MB']:.0f} -> {big['client_MB']:.0f} MB "
              f"({big['client_MB'] / small['client_MB']:.2f}x), workers "
              f"{small['worker_MB']:.0f} -> {big['worker_MB']:.0f} MB "
              f"({big['worker_MB'] / small['worker_MB']:.2f}x; flat: about 1)")


if __name__ == "__main__":
    main()
