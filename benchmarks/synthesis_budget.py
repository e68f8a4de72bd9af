"""CPU budget of a user's design from basic data: ``ltca synthesize`` (development bearing
on) then ``ltca run`` with a cold FE cache, per design, as a table (issue 60, "Done when":
under 2 min of CPU for both).

For each basic file (default ``tests/data/designs/*.toml`` without the ``_unrelieved``
cases: a spiral bevel without offset, a passenger-car hypoid, a large-offset truck hypoid,
a face-hobbed hypoid) the two commands run one after the other as subprocesses with their
defaults; ``ltca run`` gets an empty FE cache of its own (``HYPOID_LTCA_CACHE`` set to a
temporary directory, so the FE influence coefficients of both members are built as on a
first run; ``--warm`` uses the user's cache instead). CPU is the children's user + system
time (``resource.getrusage(RUSAGE_CHILDREN)``, the FE worker process included), so a
loaded machine inflates it less than wall time; the development's own split (bearing
stage, relief stage, final check and tolerance, coast flank, from the case's
``[development]`` table) shows where the synthesis spends it. The table also gives what
the run found: verdict, LTE peak-to-peak and flank peak pressure at the light and design
torque, and the light-load pattern (u toe-heel on the gear flank); then the coast flank:
what its development did (``dev``, ``met``: every target met as synthesised, ``off``,
``kept``: nothing better found), its plastic share as synthesised → as written (the
development's check, the larger of both torques), and ``ltca run CASE --flank coast``
(root stress and rating on, the same FE cache; its CPU is not in the budget, a check the
user runs besides): its verdict and plastic share. ``--no-coast`` leaves that run out.

``--baseline DIR`` also runs ``ltca synthesize`` of another source tree first on each
design (column ``base``): the ratio of the two is measured under the same machine load.

Usage: ``python benchmarks/synthesis_budget.py [BASIC.toml ...] [--warm] [--keep DIR]
[--baseline DIR] [--no-coast]``.
Run one design at a time on a shared machine (each cold FE build is ~1.5 min of CPU).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DESIGNS = sorted(p for p in (ROOT / "tests" / "data" / "designs").glob("*.toml")
                 if not p.stem.endswith("_unrelieved"))
#: the issue's budget for synthesize + a cold-cache run [s CPU]
BUDGET = 120.0


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _command(args: list[str], env: dict[str, str] | None = None,
             source: Path = ROOT) -> tuple[int, float, str]:
    c0 = _cpu()
    p = subprocess.run([sys.executable, "-m", "contact", *args], capture_output=True,
                       text=True, check=False, cwd=source, env=env)
    return p.returncode, _cpu() - c0, p.stdout + p.stderr


def run_design(basic: Path, work: Path, warm: bool, baseline: Path | None = None,
               coast: bool = True) -> dict:
    """Synthesise and run one design; the numbers of the table."""
    import numpy as np
    import xarray as xr

    from contact.study.verdicts import verdict

    case, nc = work / f"{basic.stem}.toml", work / f"{basic.stem}.nc"
    row: dict = {"design": basic.stem}
    if baseline is not None:  # the same command from another source tree, same load
        rc, cpu, _ = _command(["synthesize", str(basic.resolve()), "-o",
                               str((work / f"{basic.stem}_baseline.toml").resolve()),
                               "--no-progress"], source=baseline)
        row["baseline_cpu"] = cpu if rc == 0 else float("nan")
    rc, cpu, text = _command(["synthesize", str(basic), "-o", str(case), "--no-progress"])
    row["synth_cpu"] = cpu
    if rc:
        row["error"] = "synthesize: " + (text.strip().splitlines() or ["?"])[-1]
        return row
    dev = tomllib.loads(case.read_text(encoding="utf-8")).get("development", {})
    row["stages"] = dev.get("cpu_seconds_stages", {})
    row["evaluations"] = dev.get("evaluations")
    row["coast_dev"] = _coast_status(dev)
    env = dict(os.environ)
    with tempfile.TemporaryDirectory(prefix="ltca-fe-") as cache:
        if not warm:
            env["HYPOID_LTCA_CACHE"] = cache
        rc, cpu, text = _command(["run", str(case), "-o", str(nc), "--no-progress"], env)
        row["run_cpu"] = cpu
        if rc:
            row["error"] = "run: " + (text.strip().splitlines() or ["?"])[-1]
            return row
        if coast:
            cnc = work / f"{basic.stem}_coast.nc"
            rc, cpu, text = _command(["run", str(case), "--flank", "coast", "-o", str(cnc),
                                      "--no-progress"], env)
            row["coast_run_cpu"] = cpu
            if rc:
                row["coast_run"] = "error: " + (text.strip().splitlines() or ["?"])[-1]
            else:
                ct = xr.open_datatree(cnc)
                lt = ct["/ltca"].to_dataset()
                share = (float(np.nanmax(lt["plastic_load_share"].values))
                         if "plastic_load_share" in lt else 0.0)
                row["coast_run"] = f"{verdict(ct).severity} {100 * share:.1f} %"
    tree = xr.open_datatree(nc)
    lt = tree["/ltca"].to_dataset()
    from contact.study.summary import pattern_dimensions
    from geometry.case import load_case

    row.update(verdict=verdict(tree).severity,
               torque=lt["torque"].values.tolist(),
               lte=lt["lte_peak_to_peak"].values.tolist(),
               pressure=lt["pressure_max_flank"].values.tolist(),
               pattern=_pattern(pattern_dimensions(lt, load_case(case))),
               root_stress=bool("root_stress_max" in lt
                                and np.all(np.isfinite(lt["root_stress_max"].values))))
    return row


def _coast_status(dev: dict) -> str:
    """The coast flank's development from the case's ``[development]`` table: what it did
    and its plastic share as synthesised → as written [%]."""
    c = dev.get("coast", {})
    what = c.get("development", "")
    short = ("dev" if what == "developed" else "met" if "met every" in what
             else "off" if "off" in what else "kept" if "did better" in what else "-")
    after = dev.get("coast_achieved", {}).get("plastic_share")
    before = c.get("as_synthesised", {}).get("plastic_share", after)
    if not after:
        return short
    return f"{short} {100 * max(before):.1f}->{100 * max(after):.1f}"


def _pattern(dims) -> str:
    try:
        return f"{float(dims['pattern_toe_u'][0]):.2f}-{float(dims['pattern_heel_u'][0]):.2f}"
    except (TypeError, KeyError, IndexError, ValueError):
        return "-"


def _fmt(row: dict) -> str:
    st = row.get("stages", {})
    split = "/".join(f"{st.get(k, float('nan')):.0f}"
                     for k in ("bearing", "height", "relief", "check", "coast"))
    base = row.get("baseline_cpu")
    head = (f"{row['design']:<20} " + (f"{base:>6.0f} " if base is not None else "")
            + f"{row['synth_cpu']:>6.0f} {split:<11}")
    if "error" in row:
        return head + f" FAILED: {row['error']}"
    total = row["synth_cpu"] + row["run_cpu"]
    t = row["torque"]
    return (head + f" {row['run_cpu']:>6.0f} {total:>6.0f} "
            f"{'yes' if total <= BUDGET else 'no':<4} {row['verdict']:<10}"
            f"{t[0]:>6.1f}/{t[-1]:<7.1f}"
            f"{'/'.join(f'{x:.0f}' for x in row['lte']):<10}"
            f"{'/'.join(f'{x:.0f}' for x in row['pressure']):<11}"
            f"{row['pattern']:<10}{'yes' if row['root_stress'] else 'no':<4}"
            f"{row.get('coast_dev', '-'):<15}{row.get('coast_run', '-'):<16}"
            f"{row.get('coast_run_cpu', float('nan')):>5.0f}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("basic", nargs="*", type=Path, default=DESIGNS)
    ap.add_argument("--warm", action="store_true",
                    help="ltca run with the user's FE cache (default: an empty one)")
    ap.add_argument("--keep", type=Path, default=None, help="keep the cases and files here")
    ap.add_argument("--no-coast", dest="coast", action="store_false",
                    help="leave out ltca run --flank coast")
    ap.add_argument("--baseline", type=Path, default=None,
                    help="a source tree of another version (e.g. `git archive REV | tar -x "
                         "-C DIR`): its ltca synthesize runs first on each design, so the "
                         "two CPU times are measured under the same machine load")
    args = ap.parse_args(argv)
    work = args.keep or Path(tempfile.mkdtemp(prefix="ltca-budget-"))
    work.mkdir(parents=True, exist_ok=True)
    print(f"CPU [s] of ltca synthesize (development split bearing/relief/check/coast) and "
          f"ltca run ({'warm' if args.warm else 'cold'} FE cache); budget {BUDGET:.0f} s; "
          "coast: its development (plastic % as synthesised->written) and ltca run --flank "
          "coast (verdict, plastic %, CPU)")
    print(f"{'design':<20} " + (f"{'base':>6} " if args.baseline else "")
          + f"{'synth':>6} {'b/h/r/c/k':<11} {'run':>6} {'total':>6} {'ok':<4} "
          f"{'verdict':<10}{'T light/design':<14}{'LTE urad':<10}{'p_max MPa':<11}"
          f"{'pattern':<10}{'RS':<4}{'coast dev':<15}{'coast run':<16}{'cpu':>5}")
    for basic in args.basic:
        print(_fmt(run_design(basic, work, args.warm, args.baseline, args.coast)),
              flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
