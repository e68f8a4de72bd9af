"""LTCA benchmark: time of each stage of ``ltca run`` on a case, against the seed's timing.

    python benchmarks/ltca.py [CASE] [--case CASE ...] [--baseline [CASE]] [--torque 250]
                              [--rolls-per-cycle 20] [--repeat 5]

Prints the wall time of each stage (geometry, ease-off, UTCA, LTCA with its compliance
assembly and contact solves per roll position) for one torque, and the ratios to the
seed's reported 45 s for a whole analysis (25 s compliance, about 1 s per roll position
on a 3.0 GHz PC, seed §3.4). BLAS is limited to one thread (one core, as the targets
are stated: whole analysis ≤ 1 s, ≤ 5 ms per roll position). The LTCA is timed as
:func:`contact.pipeline.run_analysis` runs it (reusing the UTCA's transitions M1, M2).
Rolls whole mesh cycles apart repeat an earlier roll and are copied, not recomputed: the
table gives the time per roll position (LTCA / all rolls) and per computed roll. The
analysis runs ``--repeat`` times after a warm-up and the fastest run is reported (the
machines here are shared: the minimum is the least disturbed measurement). When the LTCA
is repeated (an outer tooth pair loaded at the end of the window, or edge segments
reaching beyond their separation limit: :func:`contact.ltca.loaded_tca`), ``LTCA total``
and the per-roll rows count every pass, the compliance and solve rows the last pass only
(the returned dataset); the header gives the number of passes.

Cases: a file path or a bundled case name, given as the positional CASE and/or with
``--case`` (repeatable); none: the bundled default. With two or more cases, or with
``--baseline`` (a reference case; without a value the bundled default, the seed's
face-milled 11×41 pair), the stages of each case are printed side by side with their
ratio to the reference, e.g. a face-hobbed case beside the face-milled default::

    python benchmarks/ltca.py --case tests/data/fh_iso23509_s2_crown.toml --baseline

(target: a face-hobbed analysis ≤ 1.5 × the face-milled one; face hobbing changes only
the machine chain of the flank evaluations, design note FACE_HOBBING.md §6).
"""

from __future__ import annotations

import argparse
import logging
import os
import statistics

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from tabulate import tabulate  # noqa: E402

from contact.catalogue import DEFAULT_CASE, resolve_case  # noqa: E402
from contact.ltca import LTCAOptions  # noqa: E402
from contact.pipeline import run_analysis  # noqa: E402

SEED_TOTAL_S = 45.0
SEED_COMPLIANCE_S = 25.0
SEED_PER_ROLL_S = 1.0
FH_TARGET_RATIO = 1.5  # a face-hobbed analysis at most this many times a face-milled one


class _Repeats(logging.Handler):
    """Counts the LTCA's repeated passes: :func:`contact.ltca.loaded_tca` logs "… again
    with …" (INFO) when it runs the analysis again with more tooth pairs or a wider
    edge-segment limit."""

    def __init__(self) -> None:
        super().__init__(logging.INFO)
        self.count = 0

    def emit(self, record: logging.LogRecord) -> None:
        if "again with" in record.getMessage():
            self.count += 1


def _analysis(case, torque: float, opts: LTCAOptions):
    """One analysis and the number of passes its LTCA took."""
    logger = logging.getLogger("contact.ltca.mesh_cycle")
    counter, level = _Repeats(), logger.level
    logger.addHandler(counter)
    logger.setLevel(logging.INFO)
    try:
        run = run_analysis(case, [torque], options=opts)
    finally:
        logger.removeHandler(counter)
        logger.setLevel(level)
    return run, 1 + counter.count


def measure(cases, torque: float, opts: LTCAOptions, repeat: int) -> list[dict]:
    """Stage times [s] of the fastest of ``repeat`` analyses of each case.

    Each case is analysed once as a warm-up, then the cases take turns (round robin), so
    that a change of the shared machine's load falls on all of them alike.

    Returns one dict per case: ``name``, ``method`` (FM/FH), ``solver``, ``n_roll``,
    ``n_computed`` (rolls not copied from an earlier mesh cycle), ``passes`` (the LTCA's
    passes: more than 1 when it was repeated with more pairs or a wider edge limit),
    ``rows`` — list of (stage, seconds) — ``ltca_times`` and ``totals`` (LTCA and whole
    analysis time of every run, in round order) and ``total`` (of the fastest run).
    """
    for case in cases:
        _analysis(case, torque, opts)  # warm-up: imports, caches
    runs: list[list] = [[] for _ in cases]
    for _ in range(max(repeat, 1)):
        for k, case in enumerate(cases):
            run, passes = _analysis(case, torque, opts)
            times = {key[5:-2]: float(v) for key, v in run.attrs.items()
                     if key.startswith("time_")}
            runs[k].append((run, times, passes))
    return [_summary(case, r) for case, r in zip(cases, runs, strict=True)]


def _summary(case, runs: list) -> dict:
    """The dict of :func:`measure` for one case from its (run, stage times, passes)."""
    tree, t, passes = min(runs, key=lambda r: sum(r[1].values()))
    lt = tree["ltca"].dataset
    n_roll = lt.sizes["roll"]
    compliance = float(lt["compliance_time"].sum())
    # rolls whole mesh cycles apart repeat an earlier roll's problem and are not recomputed
    n_computed = max(int((lt["compliance_time"] > 0).sum()), 1)
    solve = float(lt["solve_time"].sum())
    total = sum(t.values())
    rows = [
        ("geometry (4 flanks, 41x21)", t["geometry"]),
        ("ease-off + roll-angle surface", t["easeoff"]),
        ("UTCA (one mesh cycle)", t["utca"]),
        ("LTCA total", t["ltca"]),
        ("  LTCA per pass", t["ltca"] / passes),
        ("  compliance assembly", compliance),
        ("  contact solves (all Weber iterations)", solve),
        ("  per roll position", t["ltca"] / n_roll),
        ("  contact solves per roll position", solve / n_roll),
        ("  LTCA per computed roll", t["ltca"] / n_computed),
        ("  compliance per computed roll", compliance / n_computed),
        ("whole analysis", total),
    ]
    return {"name": case.name, "method": case.pair.method, "solver": lt.attrs["solver"],
            "n_roll": n_roll, "n_computed": n_computed, "passes": passes, "rows": rows,
            "ltca_times": [r[1]["ltca"] for r in runs],
            "totals": [sum(r[1].values()) for r in runs], "total": total}


def _seed_ratio(label: str, seconds: float) -> str:
    if label == "  compliance assembly":
        return f"{SEED_COMPLIANCE_S / max(seconds, 1e-9):.0f}x"
    if label == "  per roll position":
        return f"{SEED_PER_ROLL_S / max(seconds, 1e-9):.0f}x"
    if label == "whole analysis":
        return f"{SEED_TOTAL_S / max(seconds, 1e-9):.0f}x"
    return ""


def _header(m: dict, torque: float, repeat: int) -> str:
    again = "" if m["passes"] == 1 else " (repeated: more pairs or a wider edge limit)"
    return (f"case {m['name']} ({m['method']}), T_p = {torque:g} N m, {m['n_roll']} roll "
            f"positions ({m['n_computed']} computed), LTCA in {m['passes']} pass(es){again}, "
            f"solver {m['solver']}, fastest of {max(repeat, 1)} runs")


def _spread(m: dict) -> str:
    lt = m["ltca_times"]
    return (f"{m['name']}: LTCA per roll position over the {len(lt)} runs: median "
            f"{1e3 * statistics.median(lt) / m['n_roll']:.2f} ms, slowest "
            f"{1e3 * max(lt) / m['n_roll']:.2f} ms (the machine's load varies)")


def print_one(m: dict, torque: float, repeat: int) -> None:
    """The stage table of one case with the speed-up over the seed."""
    print(_header(m, torque, repeat))
    rows = [(label, sec, _seed_ratio(label, sec)) for label, sec in m["rows"]]
    print(tabulate(rows, headers=["stage", "time [s]", "faster than the seed"],
                   tablefmt="github", floatfmt=".4f"))
    print(_spread(m))
    print("targets: whole analysis <= 1 s, <= 5 ms per roll position (one core)")


def print_side_by_side(ref: dict, others: list[dict], torque: float, repeat: int) -> None:
    """The stages of each case beside the reference case's, with the ratios."""
    for m in (ref, *others):
        print(_header(m, torque, repeat))
    headers = ["stage", f"{ref['name']} [s]"]
    for m in others:
        headers += [f"{m['name']} [s]", "ratio"]
    rows = []
    for i, (label, sec) in enumerate(ref["rows"]):
        row = [label, sec]
        for m in others:
            other = m["rows"][i][1]
            row += [other, other / sec if sec > 0 else float("nan")]
        rows.append(row)
    print(tabulate(rows, headers=headers, tablefmt="github",
                   floatfmt=(".4f", ".4f", *([".4f", ".2f"] * len(others)))))
    for m in (ref, *others):
        print(_spread(m))
    for m in others:
        if m["method"] == "FH" and ref["method"] == "FM":
            ratio = m["total"] / ref["total"]
            rounds = statistics.median(a / b for a, b in zip(m["totals"], ref["totals"],
                                                              strict=True))
            verdict = "met" if ratio <= FH_TARGET_RATIO else "NOT met"
            print(f"target FH analysis <= {FH_TARGET_RATIO:g} x FM: {m['name']} / {ref['name']} "
                  f"= {ratio:.2f} fastest runs, {rounds:.2f} median of the rounds ({verdict})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case_arg", nargs="?", default=None, metavar="CASE",
                        help="case file or bundled case name (default: the bundled default)")
    parser.add_argument("--case", action="append", default=[], metavar="CASE",
                        help="a case to time (repeatable; the first is the reference unless "
                             "--baseline is given)")
    parser.add_argument("--baseline", nargs="?", const=DEFAULT_CASE, default=None,
                        metavar="CASE", help="reference case printed beside the others "
                        f"(without a value: the bundled default, {DEFAULT_CASE})")
    parser.add_argument("--torque", type=float, default=250.0)
    parser.add_argument("--rolls-per-cycle", type=int, default=20)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    names = ([args.case_arg] if args.case_arg is not None else []) + args.case
    if args.baseline is not None:
        names = [args.baseline, *names]
    if not names:
        names = [None]
    opts = LTCAOptions(rolls_per_cycle=args.rolls_per_cycle)
    results = measure([resolve_case(n) for n in names], args.torque, opts, args.repeat)
    if len(results) == 1:
        print_one(results[0], args.torque, args.repeat)
    else:
        print_side_by_side(results[0], results[1:], args.torque, args.repeat)


if __name__ == "__main__":
    main()
