"""LTCA benchmark: the CPU time of each stage of an analysis and of a study point, per case.

    python benchmarks/ltca.py [CASE] [--case CASE ...] [--baseline [CASE]] [--torque 250]
                              [--rolls-per-cycle 20] [--repeat 5] [--compare-kernels]

Without cases: the bundled default (the reference design of the seed's 11×41 pair, at
its Table 3.1 mounting) and the long-bearing ``kolivand2009_fm_11x41`` side by side.

Two measurements per case, in this process, BLAS on one thread (one core):

* the **whole analysis** at one torque, as ``ltca run`` runs it (geometry, ease-off, UTCA,
  LTCA, efficiency at the case's speed), against the seed's reported 45 s (25 s
  compliance, about 1 s per roll position, on a 3.0 GHz PC; seed §3.4);
* a **study point**: what a worker of a study computes per point
  (:func:`contact.study.engine.analyse_point`: no geometry group, one torque), at
  ``--repeat`` misalignments around the case's own.

Each stage's CPU time (``time.process_time``, exclusive of the stages nested in it:
``benchmarks/stage_clock.py``) and its share of the whole are printed side by side for the
cases, with the ratio to the first case. CPU time, not wall time: the machines here are
shared, and other processes' load moves wall times by up to 70 % but CPU times far less.
The analyses run once as a warm-up (imports, the per-process memos of the tooth models and
the forward map, as on a study's worker), then ``--repeat`` times with the cases taking
turns (a change of the machine's load falls on all alike); medians are printed, and the
least and largest whole times. Targets (issue 32, one core): the default case's whole
analysis ≤ 0.25 s, a study point ≤ 0.25 s of CPU (≥ 6 points/s on 2 workers: see
``benchmarks/sweep.py``).

The work of one study point is also counted (load-independent, unlike the times): the
envelope solver's Newton loops and evaluations (with their points), the spline evaluations
(FITPACK, with their points), the contact curves' coarse samples solved on Q's column
pieces instead (``EaseOffFields.solve_columns``, with their points; 0 in code before it)
and the Python-level calls (``cProfile``'s count), each run once more at the first offset.
A change that makes a point cheaper without changing its arithmetic shows here as fewer
calls for the same points.

``--baseline`` (a reference case; without a value the bundled default) puts a case first,
e.g. face-hobbed cases beside the face-milled default (target: a face-hobbed analysis
≤ 1.5 × the face-milled one)::

    python benchmarks/ltca.py --case kolivand2009_fh_12x41 \
        --case kolivand2009_table54_A_fh --baseline

``--compare-kernels`` runs each case twice, taking turns: on the NumPy paths of the
envelope solver's Newton and the contact curves' iso-line searches
(``LTCA_KERNELS=numpy``) and on their compiled kernels (numba, the ``fast`` extra), the
ratio column giving the kernels' gain in one run::

    python benchmarks/ltca.py --case kolivand2009_fm_11x41_reference --compare-kernels
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import os
import statistics
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from stage_clock import StageClock  # noqa: E402
from tabulate import tabulate  # noqa: E402

from contact.catalogue import DEFAULT_CASE, resolve_case  # noqa: E402
from contact.ltca import LTCAOptions  # noqa: E402
from contact.pipeline import run_analysis  # noqa: E402
from contact.study.engine import analyse_point  # noqa: E402
from contact.study.points import StudyInputs  # noqa: E402

SEED_TOTAL_S = 45.0
LONG_BEARING = "kolivand2009_fm_11x41"
TARGET_ANALYSIS_S = 0.25  # the default case's whole analysis, one core
TARGET_POINT_S = 0.25  # a study point's CPU time
FH_TARGET_RATIO = 1.5  # a face-hobbed analysis at most this many times a face-milled one
#: the analysis these targets were set on: geometry to friction, without the root stress
#: and the rating that run_analysis runs by default since issue 63
STEPS = {"root_stress": False, "steps": {"load_capacity": None}}


def _kernels_in_use() -> str:
    """The implementation of the envelope Newton and the iso-line searches the timings ran
    (``LTCA_KERNELS``)."""
    from contact.utca.fields import kernels_module

    return ("numpy (LTCA_KERNELS=numpy, or numba not installed)" if kernels_module() is None
            else "numba (LTCA_KERNELS=numpy for the NumPy path)")


def _offsets(repeat: int) -> list[tuple[float, float]]:
    """(ΔE, ΔP) offsets [mm] of the study points from the case's mounting."""
    return [(0.02 * ((i % 5) - 2), 0.015 * ((i * 3) % 5 - 2)) for i in range(repeat)]


class _Passes(logging.Handler):
    """Counts the LTCA's repeated passes (``… again with …`` at INFO)."""

    def __init__(self) -> None:
        super().__init__(logging.INFO)
        self.count = 0

    def emit(self, record: logging.LogRecord) -> None:
        if "again with" in record.getMessage():
            self.count += 1


def _timed(clock: StageClock, fn, *args, **kwargs):
    """(result, CPU [s] of the call, stage CPU times [s]) of one call."""
    clock.reset()
    t0 = time.process_time()
    out = fn(*args, **kwargs)
    total = time.process_time() - t0
    stages = dict(clock.cpu)
    stages["rest (pipeline, datasets)"] = total - sum(stages.values())
    return out, total, stages


@contextlib.contextmanager
def _kernels(name: str | None):
    """``LTCA_KERNELS`` set to ``name`` (None: left as it is) for the block."""
    old = os.environ.get("LTCA_KERNELS")
    if name is not None:
        os.environ["LTCA_KERNELS"] = name
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("LTCA_KERNELS", None)
        else:
            os.environ["LTCA_KERNELS"] = old


def measure(cases, torque: float, opts: LTCAOptions, repeat: int,
            kernels: list[str | None] | None = None) -> list[dict]:
    """Per case: the stage CPU times [s] of ``repeat`` whole analyses and study points.

    ``kernels``: the kernels' implementation of each case (``LTCA_KERNELS``;
    None: as the environment has it), so one case can run twice, once on each path.

    Returns one dict per case: ``name``, ``method``, ``analysis`` and ``point`` (lists of
    (total, stages) per run), ``passes`` (the LTCA's passes in the last whole analysis),
    ``counts`` (:func:`work_counts` of a study point at the first offset).
    """
    kernels = kernels or [None] * len(cases)
    clock = StageClock().install()
    logger = logging.getLogger("contact.ltca.mesh_cycle")
    passes, level = _Passes(), logger.level
    logger.addHandler(passes)
    logger.setLevel(logging.INFO)
    try:
        shared = [StudyInputs(case=c, torque=(torque,), options=opts) for c in cases]
        for c, s, kn in zip(cases, shared, kernels, strict=True):  # warm-up: imports, memos
            with _kernels(kn):
                run_analysis(c, [torque], options=opts, **STEPS)
                analyse_point(s, 0, {"delta_E": c.misalignment.delta_E,
                                     "delta_P": c.misalignment.delta_P})
        out = [{"name": c.name + ("" if kn is None else f" [{kn}]"), "method": c.pair.method,
                "analysis": [], "point": [], "passes": 1}
               for c, kn in zip(cases, kernels, strict=True)]
        for dE, dP in _offsets(max(repeat, 1)):
            for k, (c, s) in enumerate(zip(cases, shared, strict=True)):
                passes.count = 0
                with _kernels(kernels[k]):
                    _, total, stages = _timed(clock, run_analysis, c, [torque], options=opts,
                                              **STEPS)
                out[k]["analysis"].append((total, stages))
                out[k]["passes"] = 1 + passes.count
                point = {"delta_E": c.misalignment.delta_E + dE,
                         "delta_P": c.misalignment.delta_P + dP}
                with _kernels(kernels[k]):
                    res, total, stages = _timed(clock, analyse_point, s, 0, point)
                if res.status == 2:
                    raise RuntimeError(f"study point {point} of {c.name} failed: {res.reason}")
                out[k]["point"].append((total, stages))
    finally:
        clock.remove()
        logger.removeHandler(passes)
        logger.setLevel(level)
    dE, dP = _offsets(1)[0]
    for k, (c, s) in enumerate(zip(cases, shared, strict=True)):
        out[k]["counts"] = work_counts(s, {"delta_E": c.misalignment.delta_E + dE,
                                           "delta_P": c.misalignment.delta_P + dP})
    return out


def work_counts(shared: StudyInputs, point: dict) -> dict[str, float]:
    """The work of one study point, counted: the envelope solver's Newton loops and
    evaluations (and their points), the spline evaluations (FITPACK, and their points),
    the contact curves' coarse samples solved on Q's column pieces (where the code has
    them: :meth:`contact.utca.EaseOffFields.solve_columns`, and their points) and the
    Python-level calls (``cProfile``'s count of function calls). Counted on the NumPy
    paths (``LTCA_KERNELS=numpy``): the compiled kernels do the same arithmetic, out of
    sight of these counters."""
    import cProfile
    import pstats

    import numpy as np
    from scipy.interpolate import _fitpack2

    import geometry.machine.meshing as meshing
    from contact.utca import fields

    n = dict.fromkeys(("Newton loops", "envelope evaluations", "envelope points",
                       "spline evaluations", "spline points", "column-piece solves",
                       "column-piece points"), 0)
    originals = (meshing._newton, meshing._evaluate, _fitpack2.BivariateSpline.ev)
    columns = getattr(fields.EaseOffFields, "solve_columns", None)

    def newton(*args):
        n["Newton loops"] += 1
        return originals[0](*args)

    def evaluate(ctx, x, *args):
        n["envelope evaluations"] += 1
        n["envelope points"] += len(x)
        return originals[1](ctx, x, *args)

    def ev(self, xi, yi, dx=0, dy=0):
        n["spline evaluations"] += 1
        n["spline points"] += int(np.size(xi))
        return originals[2](self, xi, yi, dx, dy)

    def solve_columns(self, uc, target):
        n["column-piece solves"] += 1
        n["column-piece points"] += int(np.size(uc) * np.size(target))
        return columns(self, uc, target)

    meshing._newton, meshing._evaluate, _fitpack2.BivariateSpline.ev = newton, evaluate, ev
    if columns is not None:
        fields.EaseOffFields.solve_columns = solve_columns
    profile = cProfile.Profile()
    try:
        with _kernels("numpy"):
            profile.enable()
            analyse_point(shared, 0, point)
            profile.disable()
    finally:
        meshing._newton, meshing._evaluate, _fitpack2.BivariateSpline.ev = originals
        if columns is not None:
            fields.EaseOffFields.solve_columns = columns
    n["Python-level calls"] = pstats.Stats(profile).total_calls
    return n


def _median_stages(runs: list[tuple[float, dict]]) -> tuple[float, dict[str, float]]:
    """Median whole time and median time of each stage over the runs."""
    names = sorted({n for _, st in runs for n in st})
    return (statistics.median(t for t, _ in runs),
            {n: statistics.median(st.get(n, 0.0) for _, st in runs) for n in names})


def print_table(results: list[dict], what: str, title: str) -> None:
    """Stage CPU times and shares of each case side by side, ratios to the first case."""
    meds = [_median_stages(r[what]) for r in results]
    names = sorted({n for _, st in meds for n in st if st[n] > 5e-4 or n.startswith("rest")},
                   key=lambda n: -meds[0][1].get(n, 0.0))
    headers = ["stage"]
    for k, r in enumerate(results):
        headers += [f"{r['name']} [s]", "share"] + (["ratio"] if k else [])
    rows = []
    for n in names:
        row = [n]
        for k, (total, st) in enumerate(meds):
            v = st.get(n, 0.0)
            row += [v, f"{100 * v / total:.0f} %"]
            if k:
                ref = meds[0][1].get(n, 0.0)
                row.append(f"{v / ref:.2f}x" if ref > 0 else "")
        rows.append(row)
    row = ["whole (median)"]
    for k, (total, _) in enumerate(meds):
        row += [total, "100 %"] + ([f"{total / meds[0][0]:.2f}x"] if k else [])
    rows.append(row)
    print(title)
    print(tabulate(rows, headers=headers, tablefmt="github", floatfmt=".4f"))
    for r in results:
        t = [x for x, _ in r[what]]
        print(f"  {r['name']}: {len(t)} runs, least {min(t):.3f} s, median "
              f"{statistics.median(t):.3f} s, largest {max(t):.3f} s of CPU")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case_arg", nargs="?", default=None, metavar="CASE",
                        help="case file or bundled case name")
    parser.add_argument("--case", action="append", default=[], metavar="CASE",
                        help="a case to time (repeatable; the first is the reference unless "
                             "--baseline is given)")
    # the bundled default by its name (resolve_case takes a bundled case by its name alone)
    default = DEFAULT_CASE.removesuffix(".toml")
    parser.add_argument("--baseline", nargs="?", const=default, default=None,
                        metavar="CASE", help="reference case printed first (without a "
                        f"value: the bundled default, {default})")
    parser.add_argument("--torque", type=float, default=250.0)
    parser.add_argument("--rolls-per-cycle", type=int, default=20)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--compare-kernels", action="store_true",
                        help="each case twice, on the NumPy paths and on the compiled "
                             "kernels (LTCA_KERNELS=numpy / numba), taking turns")
    args = parser.parse_args()
    names = ([args.case_arg] if args.case_arg is not None else []) + args.case
    if args.baseline is not None:
        names = [args.baseline, *names]
    if not names:
        names = [None, LONG_BEARING]
    opts = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle)
    cases = [resolve_case(n) for n in names]
    kernels = None
    if args.compare_kernels:
        cases = [c for c in cases for _ in range(2)]
        kernels = ["numpy", "numba"] * (len(cases) // 2)
    load = os.getloadavg()[0]
    results = measure(cases, args.torque, opts, args.repeat, kernels)
    print(f"T_p = {args.torque:g} N m, {opts.cycles} x {opts.rolls_per_cycle} roll positions, "
          f"solver {opts.solver}, one BLAS thread; CPU time (process_time), medians of "
          f"{args.repeat} runs; load average {load:.1f} -> {os.getloadavg()[0]:.1f} on "
          f"{os.cpu_count()} cores; kernels: "
          f"{'per column' if kernels else _kernels_in_use()}")
    for r in results:
        if r["passes"] > 1:
            print(f"  {r['name']}: LTCA in {r['passes']} passes (more pairs or a wider edge "
                  "limit)")
    print()
    print_table(results, "analysis", "whole analysis at one torque (as `ltca run`):")
    print()
    print_table(results, "point", "study point (contact.study.engine.analyse_point, no "
                "geometry), in this process:")
    print()
    print("work of one study point, counted (load-independent):")
    rows = [[name, *(f"{r['counts'][name]:,}" for r in results)]
            for name in results[0]["counts"]]
    print(tabulate(rows, headers=["", *(r["name"] for r in results)], tablefmt="github"))
    print()
    # the targets are judged on what a user runs: with --compare-kernels, the first case
    # on the compiled kernels (the tables' ratios stay relative to the NumPy path)
    ref = results[1] if kernels else results[0]
    t_an = statistics.median(t for t, _ in ref["analysis"])
    t_pt = statistics.median(t for t, _ in ref["point"])
    print(f"{ref['name']}: whole analysis {t_an:.3f} s = {SEED_TOTAL_S / t_an:.0f}x faster than "
          f"the seed's {SEED_TOTAL_S:g} s (target <= {TARGET_ANALYSIS_S:g} s: "
          f"{'met' if t_an <= TARGET_ANALYSIS_S else 'NOT met'}); study point {t_pt:.3f} s "
          f"of CPU (target <= {TARGET_POINT_S:g} s: "
          f"{'met' if t_pt <= TARGET_POINT_S else 'NOT met'}), i.e. at most "
          f"{2.0 / t_pt:.1f} points/s on 2 workers")
    for r in results[3::2] if kernels else results[1:]:  # (the same path as ``ref``)
        if r["method"] == "FH" and ref["method"] == "FM":
            t = statistics.median(x for x, _ in r["analysis"])
            verdict = "met" if t / t_an <= FH_TARGET_RATIO else "NOT met"
            print(f"target FH analysis <= {FH_TARGET_RATIO:g} x FM: {r['name']} / "
                  f"{ref['name']} = {t / t_an:.2f} ({verdict})")


if __name__ == "__main__":
    main()

