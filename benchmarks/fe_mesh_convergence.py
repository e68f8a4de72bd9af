"""Convergence of the FE peak root stress over mesh levels, on several designs (issue 75).

    python benchmarks/fe_mesh_convergence.py CASE.toml [CASE.toml ...]
        [--levels reference default face8 ...] [--cache DIR] [--flanks drive coast]
        [--json FILE.jsonl]
    python benchmarks/fe_mesh_convergence.py --table FILE.jsonl [...]   # the docs' table

For each case and each mesh level: the FE build of both members (both flanks from one
factorisation, ``influence_coefficients(..., other_flank=True)``, as ``ltca synthesize``
builds them) in a child process with an empty cache of its own — its CPU (``ru_utime +
ru_stime`` of the child and the solver worker it waited for, ``os.wait4``) and peak
resident memory (the largest of them). Then, in this process, the LTCA of each flank runs
once at ``ltca run``'s sampling at the flank's torques (:func:`contact.pipeline.
flank_torques`: the drive flank at the case's ``[operating]`` torques, the coast flank
limited to its ``coast_design_torque``) and its segment forces are superposed on each
level's coefficients (:func:`contact.ltca.root_stress.root_stress`): the FE mesh is the
only difference between the rows. Printed per case, flank and level: the peak root stress
``root_stress_max`` [MPa] of pinion and gear at the flank's design torque (the largest)
and its relative difference to the ``default`` level and to the ``reference`` level, the
largest |difference| to the default over all the flank's torques, and the build's CPU and
memory; at the end the table of all cases (the largest |difference| per level).

Levels (:func:`levels`; the options of each are printed): ``reference`` — twice the
default's divisions along the face and 1.5 times in the depth (fillet, flank, half slot,
rim; the elements across the tooth follow, :func:`contact.compliance.fe.solid.mesh_layout`);
``reference2`` twice in both (~8 times the unknowns, > 6 GB and many minutes per member);
``default`` — :class:`contact.compliance.fe.FEOptions` as ``ltca run`` builds it; coarser:
``face10``, ``face8``, ``face6`` (elements along the face), ``depth/1.5`` (fillet, flank, half-slot
and rim divisions / 1.5), ``loads11`` / ``loads15`` (11 or 15 columns of unit loads along
the face instead of 21, the 11 rows kept: the coefficients between the columns
interpolated by the hat functions as everywhere between load points), ``rows8`` /
``rows6`` / ``rows5`` (8, 6 or 5 rows of unit loads along the profile instead of 11, the
21 columns kept: wider hats), ``step2`` (rows 0, 1, 2, 4, 6, 8, 10 of the 11 solved, the full grid's
hats: ``FEOptions(load_row_step=2)``), and combinations; ``coarse`` —
``FEOptions.at_level("coarse")``, the same model as ``face8+depth/1.5+step2``;
``coarse10`` — ``FEOptions.at_level("coarse10")`` (``ltca synthesize``'s level), and on
it ``coarse9`` (9 along the face), ``coarse10+loads15`` (15 columns of unit loads) and
``coarse10+across4`` (4 across the tooth: the same model, the root size sets them;
docs/performance.md, "A new design to its verdict: the FE level and the check's sampling
measured as levers").
Measured 2026-11-26 on six designs: docs/fe.md, "Mesh levels on six designs" (the runs of
a design at several times share its cache directory: a level already built is read back,
its CPU then the read's, and ``--table`` keeps the cold build's).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import subprocess
import sys
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def levels() -> dict:
    """Mesh level name → FEOptions."""
    from contact.compliance.fe import FEOptions

    d = FEOptions()

    def depth(o, f):
        return dataclasses.replace(
            o, fillet_divisions=max(1, round(o.fillet_divisions * f)),
            flank_divisions=max(2, round(o.flank_divisions * f)),
            slot_divisions=max(1, round(o.slot_divisions * f)),
            rim_divisions=max(1, round(o.rim_divisions * f)))

    rep = dataclasses.replace
    return {
        "reference": depth(rep(d, face_divisions=2 * d.face_divisions), 1.5),
        "reference2": depth(rep(d, face_divisions=2 * d.face_divisions), 2.0),
        "default": d,
        "face8": rep(d, face_divisions=8),
        "face6": rep(d, face_divisions=6),
        "depth/1.5": depth(d, 1 / 1.5),
        "loads15": rep(d, load_nu=15),
        "loads11": rep(d, load_nu=11),
        "face8+loads15": rep(d, face_divisions=8, load_nu=15),
        "face8+loads11": rep(d, face_divisions=8, load_nu=11),
        "face8+depth/1.5": depth(rep(d, face_divisions=8), 1 / 1.5),
        "face10": rep(d, face_divisions=10),
        "rows8": rep(d, load_nv=8),
        "rows6": rep(d, load_nv=6),
        "rows5": rep(d, load_nv=5),
        "step2": rep(d, load_row_step=2),
        "depth/1.5+step2": depth(rep(d, load_row_step=2), 1 / 1.5),
        "face10+depth/1.5+step2": depth(rep(d, face_divisions=10, load_row_step=2), 1 / 1.5),
        "face8+depth/1.5+step2": depth(rep(d, face_divisions=8, load_row_step=2), 1 / 1.5),
        "face8+step2": rep(d, face_divisions=8, load_row_step=2),
        # FEOptions.at_level("coarse"): face8+depth/1.5+step2 under its name
        "coarse": FEOptions.at_level("coarse"),
        "coarse10": FEOptions.at_level("coarse10"),
        "coarse9": FEOptions.at_level("coarse", face_divisions=9),
        "coarse10+loads15": FEOptions.at_level("coarse10", load_nu=15),
        "coarse10+across4": FEOptions.at_level("coarse10", across_divisions=4),
    }


#: the child process: both members' coefficients of both flanks built into a cache
_CHILD = r"""
import sys, json
sys.path.insert(0, sys.argv[1])
import benchmarks.fe_mesh_convergence as m
from contact.compliance.fe import influence_coefficients
from geometry.case import load_case
case = load_case(sys.argv[2])
opt = m.levels()[sys.argv[3]]
out = {}
for member in ("pinion", "gear"):
    ds = influence_coefficients(case, member, "drive", opt, cache_dir=sys.argv[4],
                                progress=False, other_flank=True)
    out[member] = {k: ds.attrs[f"cost_{k}"] for k in ("n_unknowns", "n_elements",
                                                         "n_loads", "time_total_s")}
print("COST " + json.dumps(out, default=float))
"""


def build_measured(case_path: Path, level: str, cache: Path) -> tuple[float, float, dict]:
    """As :func:`build`, with the child's CPU and peak RSS from ``os.wait4``."""
    proc = subprocess.Popen([sys.executable, "-c", _CHILD, str(ROOT), str(case_path), level,
                             str(cache)], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            text=True, env={**os.environ, "PYTHONPATH": str(ROOT)})
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode:
        raise RuntimeError(f"build {case_path.name} {level} failed ({proc.returncode})")
    line = next(x for x in out.splitlines() if x.startswith("COST "))
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 2**20, json.loads(line[5:])


def main(argv: list[str] | None = None) -> None:
    from contact.ltca import LTCAOptions, loaded_tca
    from contact.ltca.root_stress import root_stress
    from contact.pipeline import flank_torques
    from contact.utca.easeoff import ease_off
    from geometry.case import load_case
    from geometry.core.blas import blas_threads

    table = levels()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("cases", nargs="*", type=Path)
    ap.add_argument("--table", nargs="+", type=Path, metavar="JSONL",
                    help="print the markdown table of earlier runs' --json files and stop")
    ap.add_argument("--cache", type=Path, default=Path("/tmp/fe_mesh_convergence"))
    ap.add_argument("--levels", nargs="+", default=list(table), choices=list(table))
    ap.add_argument("--flanks", nargs="+", default=["drive", "coast"],
                    choices=("drive", "coast"))
    ap.add_argument("--json", type=Path, help="append each case's numbers to this file")
    args = ap.parse_args(argv)
    if args.table:
        print(markdown_table(args.table))
        return
    names = list(dict.fromkeys(["default", *args.levels]))
    print("levels: " + "; ".join(f"{n}: {table[n]}" for n in names), flush=True)
    worst: dict[str, float] = {n: 0.0 for n in names}
    for path in args.cases:
        case = load_case(path)
        cost = {}
        for name in names:
            cache = args.cache / path.stem / name.replace("/", "_")
            c, rss, info = build_measured(path, name, cache)
            cost[name] = (c, rss, info)
            print(f"{path.stem} {name:16s} build CPU {c:6.1f} s, peak RSS {rss:.2f} GB, "
                  f"unknowns {info['pinion']['n_unknowns']}/{info['gear']['n_unknowns']}, "
                  f"loads {info['pinion']['n_loads']}", flush=True)
        record = {"case": path.stem, "cost": cost, "peaks": {}, "torques": {}}
        for flank in args.flanks:
            torques = list(flank_torques(case, flank)[0])
            with blas_threads(1):
                eo = ease_off(case, flank=flank)
                lt = loaded_tca(case, torques, easeoff=eo, options=LTCAOptions())
            peaks = {}
            for name in names:
                cache = args.cache / path.stem / name.replace("/", "_")
                rs = root_stress(case, eo, lt, table[name], cache_dir=cache)
                peaks[name] = rs["root_stress_max"].transpose("torque", "member").values
            record["peaks"][flank] = {n: v.tolist() for n, v in peaks.items()}
            record["torques"][flank] = torques
            d, r = peaks["default"], peaks.get("reference")
            print(f"\n{path.stem}, {flank}: torques {torques} N·m; design torque "
                  f"{torques[-1] if torques == sorted(torques) else max(torques)}", flush=True)
            k = int(max(range(len(torques)), key=lambda i: torques[i]))
            for name in names:
                p = peaks[name]
                rel = p / d - 1.0
                worst[name] = max(worst[name], float(abs(rel).max()))
                vs_ref = "" if r is None else (
                    f" vs reference {rel_txt(p[k] / r[k] - 1.0)}")
                print(f"  {name:16s} pinion/gear {p[k, 0]:7.1f} / {p[k, 1]:7.1f} MPa  vs "
                      f"default {rel_txt(rel[k])}{vs_ref}  max|vs default| over torques "
                      f"{abs(rel).max():.2%}", flush=True)
        if args.json:
            with open(args.json, "a") as f:
                f.write(json.dumps(record, default=float) + "\n")
    print("\nlargest |difference to the default| over all cases, flanks, members, torques:")
    for name in names:
        print(f"  {name:16s} {worst[name]:.2%}")


def markdown_table(paths: list[Path]) -> str:
    """The markdown table of the records (``--json`` files): per level, each design's
    build CPU relative to its default level's, and the peak root stress at each flank's
    design torque (the largest) relative to the default level's, pinion/gear drive,
    pinion/gear coast; the default level's row gives its CPU [s], peak RSS and MPa."""
    recs: dict[str, dict] = {}
    for path in paths:
        for line in Path(path).read_text().splitlines():
            r = json.loads(line)
            old = recs.setdefault(r["case"], {"cost": {}, "peaks": {}, "torques": {}})
            # (records before the torques were kept: the flanks' torques ascending)
            old["torques"].update(r.get("torques") or {
                fl: list(range(len(next(iter(p.values()))))) for fl, p in r["peaks"].items()})
            for name, cost in r["cost"].items():  # a level read from the cache by a later
                # run (its CPU the read's) keeps the cold build's costs
                if name not in old["cost"] or cost[0] > old["cost"][name][0]:
                    old["cost"][name] = cost
            for fl, p in r["peaks"].items():
                old["peaks"].setdefault(fl, {}).update(p)
    names = list(dict.fromkeys(n for r in recs.values() for n in r["cost"]))
    cases = list(recs)
    out = ["| level | " + " | ".join(cases) + " | largest \\|Δ\\| |",
           "|---" * (len(cases) + 2) + "|"]
    for name in names:
        cells, worst = [], 0.0
        for c in cases:
            r = recs[c]
            if name not in r["cost"]:
                cells.append("")
                continue
            cpu, rss, _ = r["cost"][name]
            d_cpu = r["cost"]["default"][0]
            bits = []
            for fl in ("drive", "coast"):
                p = r["peaks"].get(fl, {})
                if name not in p:
                    continue
                worst = max(worst, max(abs(x / y - 1.0) for a, b in zip(
                    p[name], p["default"], strict=True) for x, y in zip(a, b, strict=True)))
                k = max(range(len(p[name])), key=lambda i, fl=fl: r["torques"][fl][i])
                v, d = p[name][k], p["default"][k]
                if name == "default":
                    bits.append(f"{v[0]:.0f}/{v[1]:.0f}")
                else:
                    bits.append("/".join(f"{x / y - 1.0:+.1%}" for x, y in zip(v, d,
                                                                                strict=True)))
            head = (f"{cpu:.1f} s, {rss:.2f} GB" if name == "default"
                    else f"CPU ×{cpu / d_cpu:.2f}")
            cells.append(f"{head}; " + ", ".join(bits))
        out.append(f"| {name} | " + " | ".join(cells) + f" | {worst:.1%} |")
    return "\n".join(out)


def rel_txt(x) -> str:
    return "/".join(f"{v:+.2%}" for v in x)


if __name__ == "__main__":
    main()
