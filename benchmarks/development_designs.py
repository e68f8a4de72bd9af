"""User designs from basic data through ``ltca synthesize`` (development bearing) and
``ltca run``: what each design achieved, as a table (issue 60, items 1 and 7).

For each basic file (default ``tests/data/designs/*.toml`` without the ``_unrelieved``
cases: a spiral bevel without offset, a passenger-car hypoid, a large-offset truck hypoid,
a face-hobbed hypoid), the two commands run as subprocesses with their defaults (the
development on; root stress and ISO 10300 rating on) and the table prints, per design:
the development's light and design torque, the light-load pattern (u toe-heel, v root-tip
on the gear flank, coarse LTCA), the edge share and LTE peak-to-peak at the design torque,
whether every target was met and the design tolerant at the ΔE/ΔP excursions, then from
``ltca run`` (default sampling) the verdict, the edge share at each torque and the CPU
seconds of each command (children's user + system time, ``resource.getrusage``).

Usage: ``python benchmarks/development_designs.py [BASIC.toml ...] [--keep DIR]``.
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DESIGNS = sorted(p for p in (ROOT / "tests" / "data" / "designs").glob("*.toml")
                 if not p.stem.endswith("_unrelieved"))


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _command(args: list[str]) -> tuple[int, float, str]:
    c0 = _cpu()
    p = subprocess.run([sys.executable, "-m", "contact", *args], capture_output=True,
                       text=True, check=False)
    return p.returncode, _cpu() - c0, p.stdout + p.stderr


def run_design(basic: Path, work: Path) -> dict:
    """Synthesise (with development) and run one design; the numbers of the table."""
    import numpy as np
    import xarray as xr

    from contact.ltca.summary import edge_load_share
    from contact.study.verdicts import verdict

    case = work / f"{basic.stem}.toml"
    nc = work / f"{basic.stem}.nc"
    row: dict = {"design": basic.stem}
    rc, cpu, text = _command(["synthesize", str(basic), "-o", str(case), "--no-progress"])
    row.update(synth_rc=rc, synth_cpu=cpu)
    if rc:
        row["error"] = text.strip().splitlines()[-1] if text.strip() else "?"
        return row
    dev = tomllib.loads(case.read_text(encoding="utf-8")).get("development", {})
    a = dev.get("achieved", {})
    row.update(torque=dev.get("torque_Nm"), met=dev.get("targets_met"),
               tolerant=dev.get("tolerant"),
               pattern=(a["pattern_toe_u"][0], a["pattern_heel_u"][0], a["pattern_root_v"][0],
                        a["pattern_tip_v"][0]) if a else None,
               dev_edge=a.get("edge_load_share", [np.nan, np.nan])[1],
               dev_lte=a.get("lte_peak_to_peak", [np.nan, np.nan])[1],
               prescriptions=dev.get("prescriptions"))
    rc, cpu, text = _command(["run", str(case), "-o", str(nc), "--no-progress"])
    row.update(run_rc=rc, run_cpu=cpu)
    if rc:
        row["error"] = text.strip().splitlines()[-1] if text.strip() else "?"
        return row
    tree = xr.open_datatree(nc)
    lt = tree["/ltca"].to_dataset()
    v = verdict(tree)
    root = lt["root_stress_max"].values if "root_stress_max" in lt else np.array([np.nan])
    row.update(verdict=v.severity, findings=len(v.findings),
               torques=lt["torque"].values.tolist(),
               lte=lt["lte_peak_to_peak"].values.tolist(),
               edge=edge_load_share(lt).tolist(),
               root_stress=bool(np.all(np.isfinite(root))),
               rating="rating" in tree.children)
    return row


def _fmt(row: dict) -> str:
    if "error" in row:
        return f"{row['design']:<22} FAILED: {row['error']}"
    p = row["pattern"]
    pat = f"{p[0]:.2f}-{p[1]:.2f} x {p[2]:.2f}-{p[3]:.2f}" if p else "-"
    t = row["torque"] or [float("nan")] * 2
    return (f"{row['design']:<22} {t[0]:>6.0f}/{t[1]:<6.0f} {pat:<22} "
            f"{100 * row['dev_edge']:>5.1f} {row['dev_lte']:>6.1f}  "
            f"{'yes' if row['met'] else 'no':<4}{'yes' if row['tolerant'] else 'no':<5}"
            f"{row['verdict']:<10}"
            f"{' '.join(f'{100 * e:.1f}' for e in row['edge']):<18}"
            f"{' '.join(f'{x:.0f}' for x in row['lte']):<14}"
            f"{'yes' if row['root_stress'] else 'no':<5}{'yes' if row['rating'] else 'no':<4}"
            f"{row['synth_cpu']:>6.0f} {row['run_cpu']:>6.0f}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("basic", nargs="*", type=Path, default=DESIGNS)
    ap.add_argument("--keep", type=Path, default=None, help="keep the cases and files here")
    args = ap.parse_args(argv)
    work = args.keep or Path(tempfile.mkdtemp(prefix="ltca-dev-"))
    work.mkdir(parents=True, exist_ok=True)
    print(f"{'design':<22} {'T light/design':<13} {'pattern u x v (light)':<22} "
          f"{'edge%':>5} {'LTE':>6}  {'met':<4}{'tol':<5}{'verdict':<10}"
          f"{'run edge % per T':<18}{'run LTE urad':<14}{'RS':<5}{'ISO':<4}"
          f"{'syn s':>6} {'run s':>6}")
    for basic in args.basic:
        print(_fmt(run_design(basic, work)), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
