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

With ``--done-when`` each design also runs ``ltca run CASE --flank coast`` and ``ltca
duty-cycle CASE`` (the default spectrum up to the design torque, ``--scheduler
synchronous``) and a second table gives issue 71's "Done when" per design: every drive
target of the development met (and tolerant), ``ltca run`` and ``--flank coast`` not FAIL,
no plastic segment at any torque (either flank), no edge contact at the light torque (15 %
of the design torque; ``pressure_max_edge`` 0, as tests/test_development_designs.py),
LTE p-p ≤ 60 µrad at every torque (drive; the coast's beside it), the duty cycle not
FAIL, and the CPU of synthesize + the first ``ltca run``.

Usage: ``python benchmarks/development_designs.py [BASIC.toml ...] [--keep DIR]
[--done-when]``.
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


def _command(args: list[str], log: Path | None = None) -> tuple[int, float, str]:
    """Run one ``ltca`` command; its return code, CPU seconds and output (also written to
    ``log`` where given: what a user reads, the notes and errors, kept with the files)."""
    c0 = _cpu()
    p = subprocess.run([sys.executable, "-m", "contact", *args], capture_output=True,
                       text=True, check=False)
    if log is not None:
        log.write_text(p.stdout + p.stderr, encoding="utf-8")
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
    rc, cpu, text = _command(["synthesize", str(basic), "-o", str(case), "--no-progress"],
                             work / f"{basic.stem}_synthesize.log")
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
    rc, cpu, text = _command(["run", str(case), "-o", str(nc), "--no-progress"],
                             work / f"{basic.stem}_run.log")
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


def done_when(row: dict, work: Path) -> dict:
    """Issue 71's "Done when" of a design :func:`run_design` synthesised and ran: the coast
    run and the duty cycle added (subprocesses), each criterion as a boolean."""
    import numpy as np
    import xarray as xr

    from contact.study.verdicts import verdict

    stem = row["design"]
    case, nc = work / f"{stem}.toml", work / f"{stem}.nc"
    out: dict = {"design": stem, "cpu_new_design": row.get("synth_cpu", np.nan)
                 + row.get("run_cpu", np.nan)}
    if "error" in row:
        out["error"] = row["error"]
        return out

    def flank(path: Path) -> dict:
        tree = xr.open_datatree(path)
        lt = tree["/ltca"]
        plastic = (np.nan_to_num(lt["plastic_load_share"].values) if "plastic_load_share"
                   in lt else np.zeros(1))
        edge = np.nan_to_num(lt["pressure_max_edge"].values)
        return {"verdict": verdict(tree).severity, "plastic": float(np.max(plastic)),
                "light_edge": float(edge[0]), "lte": lt["lte_peak_to_peak"].values.tolist()}

    drive = flank(nc)
    nc_coast = work / f"{stem}_coast.nc"
    rc, _, _ = _command(["run", str(case), "--flank", "coast", "-o", str(nc_coast),
                         "--no-progress"], work / f"{stem}_coast.log")
    coast = flank(nc_coast) if rc == 0 else {"verdict": f"rc {rc}", "plastic": np.nan,
                                              "light_edge": np.nan, "lte": [np.nan]}
    nc_duty = work / f"{stem}_duty.nc"
    rc, _, _ = _command(["duty-cycle", str(case), "--scheduler", "synchronous", "-o",
                         str(nc_duty), "--no-progress"], work / f"{stem}_duty.log")
    duty = verdict(xr.open_datatree(nc_duty)).severity if rc == 0 else f"rc {rc}"
    out.update(
        targets=bool(row["met"]) and bool(row["tolerant"]), run=drive["verdict"],
        coast=coast["verdict"], duty=duty,
        plastic=max(drive["plastic"], coast["plastic"]),
        light_edge=drive["light_edge"], lte=max(drive["lte"]),
        coast_lte=float(np.nanmax(coast["lte"])))
    out["all"] = (out["targets"] and "fail" not in (out["run"], out["coast"], out["duty"])
                  and not str(out["coast"]).startswith("rc") and not str(duty).startswith("rc")
                  and out["plastic"] == 0.0 and out["light_edge"] == 0.0
                  and out["lte"] <= 60.0)
    return out


def _fmt_done(d: dict) -> str:
    if "error" in d:
        return f"{d['design']:<28} FAILED: {d['error']}"
    yes = {True: "yes", False: "NO"}
    return (f"{d['design']:<28} {yes[d['targets']]:<8}{d['run']:<10}{d['coast']:<10}"
            f"{d['duty']:<10}{100 * d['plastic']:>7.2f} {d['light_edge']:>9.0f} "
            f"{d['lte']:>7.0f} {d['coast_lte']:>7.0f} {d['cpu_new_design']:>7.0f}  "
            f"{yes[d['all']]}")


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
    ap.add_argument("--done-when", action="store_true",
                    help="also the coast run and the duty cycle: issue 71's criteria per design")
    args = ap.parse_args(argv)
    work = args.keep or Path(tempfile.mkdtemp(prefix="ltca-dev-"))
    work.mkdir(parents=True, exist_ok=True)
    print(f"{'design':<22} {'T light/design':<13} {'pattern u x v (light)':<22} "
          f"{'edge%':>5} {'LTE':>6}  {'met':<4}{'tol':<5}{'verdict':<10}"
          f"{'run edge % per T':<18}{'run LTE urad':<14}{'RS':<5}{'ISO':<4}"
          f"{'syn s':>6} {'run s':>6}")
    rows = []
    for basic in args.basic:
        rows.append(run_design(basic, work))
        print(_fmt(rows[-1]), flush=True)
    if args.done_when:
        print(f"\n{'design':<28} {'targets':<8}{'run':<10}{'coast':<10}{'duty':<10}"
              f"{'plastic%':>7} {'edge@15%':>9} {'LTE max':>7} {'coast':>7} {'CPU s':>7}  all")
        for row in rows:
            print(_fmt_done(done_when(row, work)), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
