"""Drawing the figures of the default run against the analysis that produced them.

Target (issue 22): drawing every figure of ``ltca run --plots`` on the default case
takes no longer than the analysis. Measured in one process, one after the other, so
both see the same machine load:

1. the analysis (``run_analysis`` of the default case at the seed's Table 3.1 conditions
   with the efficiency stage, as ``ltca run``), wall and CPU time;
2. every figure of :func:`contact.plots.analysis_figures` drawn and written as PNG
   (the ``--plots`` step), per figure and in total;
3. the HTML report (:func:`contact.plots.report.render_report`) from the same figures,
   with the PNG encoding for embedding;
4. for comparison, the same figures with matplotlib's constrained layout switched on
   (what the fixed inch grid of ``contact.plots.style.panel_grid`` replaces).

Run: ``python benchmarks/plots.py [--out DIR] [--repeat N]``. BLAS is limited to one
thread unless ``OPENBLAS_NUM_THREADS``/``OMP_NUM_THREADS`` are set. Prints a table;
the verdict compares the best of N repeats of each.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

_HERE = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != _HERE]

from tabulate import tabulate  # noqa: E402

from contact.io import read_netcdf, write_netcdf  # noqa: E402
from contact.pipeline import SEED_TABLE_3_1, resolve_case, run_analysis  # noqa: E402
from contact.plots import analysis_figures, save_png  # noqa: E402
from contact.plots.report import render_report  # noqa: E402
from friction.operating import OperatingConditions  # noqa: E402


def _timed(fn):
    w, c = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - w, time.process_time() - c


def _draw(tree, out: Path, constrained: bool = False):
    """Draw and write every figure; (name, wall, CPU) per figure and the figures."""
    rows, figures = [], []
    gen = analysis_figures(tree)  # each figure is drawn when the generator reaches it
    while True:
        w, c = time.perf_counter(), time.process_time()
        try:
            nf = next(gen)
        except StopIteration:
            return rows, figures
        if constrained:
            nf.figure.set_layout_engine("constrained")
        save_png(nf.figure, out / f"{nf.name}.png")
        rows.append((nf.name, time.perf_counter() - w, time.process_time() - c))
        figures.append(nf)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None, help="directory for the PNGs (default a temp dir)")
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    out = Path(args.out or tempfile.mkdtemp(prefix="ltca_plots_"))
    out.mkdir(parents=True, exist_ok=True)
    case = resolve_case(None)
    best = {}
    per_figure = {}
    for _ in range(max(args.repeat, 1)):
        tree, w, c = _timed(lambda: run_analysis(
            case, SEED_TABLE_3_1["torque"], misalignment=SEED_TABLE_3_1["misalignment"],
            operating=OperatingConditions()))
        best["analysis"] = min(best.get("analysis", (w, c)), (w, c))
        nc = write_netcdf(tree, out / "default.nc", inputs=tree.attrs["inputs"])
        back = read_netcdf(nc, tree=True)
        t0 = (time.perf_counter(), time.process_time())
        rows, figures = _draw(back, out)
        w, c = time.perf_counter() - t0[0], time.process_time() - t0[1]
        best["figures (--plots)"] = min(best.get("figures (--plots)", (w, c)), (w, c))
        for name, fw, fc in rows:
            per_figure[name] = min(per_figure.get(name, (fw, fc)), (fw, fc))
        _, w, c = _timed(lambda back=back, figures=figures: render_report(back, figures))
        best["report (PNG encode + HTML)"] = min(best.get("report (PNG encode + HTML)", (w, c)),
                                                 (w, c))
        cdir = out / "constrained"
        cdir.mkdir(exist_ok=True)
        t0 = (time.perf_counter(), time.process_time())
        _draw(back, cdir, constrained=True)
        w, c = time.perf_counter() - t0[0], time.process_time() - t0[1]
        best["figures, constrained layout"] = min(
            best.get("figures, constrained layout", (w, c)), (w, c))
    print(f"default case, Table 3.1 conditions, best of {args.repeat}; PNGs in {out}\n")
    print(tabulate([(k, f"{w:.2f}", f"{c:.2f}") for k, (w, c) in per_figure.items()],
                   headers=["figure", "wall [s]", "CPU [s]"], tablefmt="github"))
    print()
    print(tabulate([(k, f"{w:.2f}", f"{c:.2f}") for k, (w, c) in best.items()],
                   headers=["step", "wall [s]", "CPU [s]"], tablefmt="github"))
    ratio = best["figures (--plots)"][0] / best["analysis"][0]
    print(f"\nfigures / analysis (wall): {ratio:.2f} — target ≤ 1: "
          f"{'met' if ratio <= 1 else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
