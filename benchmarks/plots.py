"""Drawing the figures of the default run against the analysis that produced them.

Target (issue 22): drawing every figure of ``ltca run --plots`` on the default case
takes no longer than the analysis. Measured in one process, one after the other, so
both see the same machine load:

1. the analysis (``run_analysis`` of the default case at the seed's Table 3.1 conditions
   with the efficiency stage, as ``ltca run``), wall and CPU time;
2. every figure of :func:`contact.plots.analysis_figures` drawn and written as PNG in
   one process, per figure and in total;
3. the same by :func:`contact.plots.render_analysis` in two processes, as ``ltca run
   --plots`` and ``ltca plot`` draw them (CPU time: the parent's only);
4. the HTML report (:func:`contact.plots.report.render_report`) from those PNGs.

The figures are laid out on a fixed grid in inches (``contact.plots.style.panel_grid``):
with matplotlib's constrained layout the three-panel pressure figure took 1.0–1.3 s CPU
to draw and save, on the fixed grid 0.6–0.65 s (measured while developing it, same load).

Each repeat is a fresh process (the analysis caches nothing across runs there, as in
``ltca run``; the first figure pays matplotlib's start-up, as there too). Run:
``python benchmarks/plots.py [--out DIR] [--repeat N]``. BLAS is limited to one thread
unless ``OPENBLAS_NUM_THREADS``/``OMP_NUM_THREADS`` are set. Prints a table; the verdict
compares the best of N processes of each step.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

from tabulate import tabulate  # noqa: E402

from contact.catalogue import SEED_TABLE_3_1, resolve_case  # noqa: E402
from contact.pipeline import run_analysis  # noqa: E402
from contact.plots import analysis_figures, render_analysis, save_png  # noqa: E402
from contact.plots.report import render_report  # noqa: E402
from friction.operating import OperatingConditions  # noqa: E402
from geometry.core.io import read_netcdf, write_netcdf  # noqa: E402


def _timed(fn):
    w, c = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - w, time.process_time() - c


def _draw(tree, out: Path):
    """Draw and write every figure; (name, wall, CPU) per figure and the figures."""
    rows, figures = [], []
    gen = analysis_figures(tree)  # each figure is drawn when the generator reaches it
    while True:
        w, c = time.perf_counter(), time.process_time()
        try:
            nf = next(gen)
        except StopIteration:
            return rows, figures
        save_png(nf.figure, out / f"{nf.name}.png")
        rows.append((nf.name, time.perf_counter() - w, time.process_time() - c))
        figures.append(nf)


def _once(out: Path) -> dict:
    """One cold measurement (a fresh process: nothing cached, as ``ltca run``)."""
    case = resolve_case(None)
    tree, w, c = _timed(lambda: run_analysis(
        case, SEED_TABLE_3_1["torque"], misalignment=SEED_TABLE_3_1["misalignment"],
        operating=OperatingConditions()))
    res = {"analysis": (w, c)}
    nc = write_netcdf(tree, out / "default.nc", inputs=tree.attrs["inputs"])
    back = read_netcdf(nc, tree=True)
    t0 = (time.perf_counter(), time.process_time())
    rows, _ = _draw(back, out)
    res["figures, one process"] = (time.perf_counter() - t0[0], time.process_time() - t0[1])
    rendered, w, c = _timed(lambda: render_analysis(back, n_workers=2))
    res["figures, two processes (--plots)"] = (w, c)
    _, w, c = _timed(lambda: render_report(back, rendered))
    res["report HTML from the PNGs (--report)"] = (w, c)
    res["per_figure"] = {name: (fw, fc) for name, fw, fc in rows}
    return res


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None, help="directory for the PNGs (default a temp dir)")
    ap.add_argument("--repeat", type=int, default=2, help="fresh processes (best of)")
    ap.add_argument("--once", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    out = Path(args.out or tempfile.mkdtemp(prefix="ltca_plots_"))
    out.mkdir(parents=True, exist_ok=True)
    if args.once:
        print(json.dumps(_once(out)))
        return 0
    runs = []
    for _ in range(max(args.repeat, 1)):
        done = subprocess.run([sys.executable, __file__, "--once", "--out", str(out)],
                              check=True, capture_output=True, text=True)
        runs.append(json.loads(done.stdout.strip().splitlines()[-1]))
    steps = [k for k in runs[0] if k != "per_figure"]
    best = {k: min(tuple(r[k]) for r in runs) for k in steps}
    per_figure = {k: min(tuple(r["per_figure"][k]) for r in runs) for k in runs[0]["per_figure"]}
    print(f"default case, Table 3.1 conditions, best of {len(runs)} fresh processes; "
          f"PNGs in {out}\n")
    print(tabulate([(k, f"{w:.2f}", f"{c:.2f}") for k, (w, c) in per_figure.items()],
                   headers=["figure", "wall [s]", "CPU [s]"], tablefmt="github"))
    print()
    print(tabulate([(k, f"{w:.2f}", f"{c:.2f}") for k, (w, c) in best.items()],
                   headers=["step", "wall [s]", "CPU [s]"], tablefmt="github"))
    ratio = best["figures, two processes (--plots)"][0] / best["analysis"][0]
    print(f"\nfigures / analysis (wall): {ratio:.2f} — target ≤ 1: "
          f"{'met' if ratio <= 1 else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
