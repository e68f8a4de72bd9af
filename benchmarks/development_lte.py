"""What makes the LTE of a developed bearing: one prescription at a time about the design the
development chose (issue 60, "LTE p-p within a target"; docs/synthesis.md, "The LTE
against the relief").

For a basic file the development (:func:`contact.optimize.development.develop`, its
defaults) chooses a design; then, with the others as chosen, the relief is scaled
(tip and root relief × 0 … 1.5), ``te_level``, ``relief_start`` and ``ellipse_length``
are varied, and each design is synthesised (steps 3–6 from the development's memo where
only the relief changes) and analysed with the development's own coarse LTCA
(:data:`~contact.optimize.development.COARSE_LTCA`) at its light and design torque. The
table gives per design the LTE peak-to-peak at both torques, the unloaded TE
peak-to-peak, the mean number of tooth pairs in contact over the mesh cycle at light load,
the edge and plastic shares at the design torque, the light-load pattern (u toe-heel on the
gear flank) and the targets missed (:func:`~contact.optimize.development.development_score`).
``--check`` analyses at ``ltca run``'s sampling (CHECK_LTCA) with the tip planes placed.

Usage: ``python benchmarks/development_lte.py BASIC.toml [--values JSON] [--check]``
(``--values``: prescriptions that replace the developed ones as the base, e.g. the first
bearing's design ``'{"path_angle": -79.375, "ellipse_length": 0.475, "tip_relief": 20.06,
"root_relief": 36.65, "relief_start": 0.2762}'`` of the 10x43, docs/synthesis.md)
(default: the passenger-car hypoid 10x43 of tests/data/designs; ≈ 1 min CPU).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def _analyse(basic, flank, values, torques, memo, teeth, check):
    from contact.optimize import development as dev
    from contact.pipeline import run_analysis
    from geometry.synthesis.basic_design import with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    case = synthesize(with_flank_options(basic, flank, values), memo=memo,
                      tip_planes=check)[0]
    options = dataclasses.replace(dev.CHECK_LTCA if check else dev.COARSE_LTCA,
                                  compliance=teeth.compliance(dev.bearing_key(values)))
    tree = run_analysis(case, list(torques), flank="drive", options=options,
                        deviations=False, geometry=False, operating=False,
                        mesh_interface=False, root_stress=False,
                        steps={"load_capacity": None})
    m = dev.design_metrics(tree, case)
    _, short, _ = dev.development_score(m, dev.DevelopmentTargets(), dev.grid_bounds(tree),
                                        centre_v=dev.working_depth_centre(case),
                                        pressure_limit=dev.static_strength(tree))
    pairs = np.asarray(tree["/ltca"]["pairs_in_contact"].values, float).mean(axis=-1)
    ute = float(tree["/utca"]["peak_to_peak_transmission_error"])
    return m, short, pairs, ute


def main(argv: list[str] | None = None) -> None:
    from contact.optimize.development import KeptTeeth, develop
    from geometry.synthesis.basic_design import load_basic

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("basic", nargs="?",
                    default=str(ROOT / "tests" / "data" / "designs" / "pc_hypoid_10x43.toml"))
    ap.add_argument("--values", default="{}",
                    help="JSON of prescriptions replacing the developed ones as the base")
    ap.add_argument("--check", action="store_true",
                    help="analyse at ltca run's sampling, tip planes placed")
    args = ap.parse_args(argv)
    basic = load_basic(args.basic)
    result = develop(basic)
    chosen = dict(result.best.values) | json.loads(args.values)
    chosen.setdefault("te_level", 45.0)
    flank = basic.options.drive_flank
    torques = result.torque
    sweeps = [("developed", {})]
    sweeps += [(f"relief x {s:g}", {"tip_relief": s * chosen["tip_relief"],
                                    "root_relief": s * chosen["root_relief"]})
               for s in (0.0, 0.5, 0.75, 1.5)]
    sweeps += [(f"te_level {v:g}", {"te_level": v}) for v in (10.0, 25.0, 70.0, 140.0)]
    sweeps += [(f"relief_start {v:g}", {"relief_start": v}) for v in (0.2, 0.35, 0.5)]
    sweeps += [(f"ellipse {v:g}", {"ellipse_length": v}) for v in (0.35, 0.55, 0.65, 0.75)]
    memo, teeth = {}, KeptTeeth()
    print(f"{Path(args.basic).stem}: light/design torque {torques[0]:.4g}/{torques[1]:.4g} "
          f"N m; developed: " + ", ".join(f"{k} {v:.3g}" for k, v in chosen.items())
          + f" ({'check' if args.check else 'coarse'} LTCA)")
    print(f"{'design':18s} {'LTE l/d urad':>13s} {'UTE':>5s} {'pairs l':>7s} "
          f"{'edge %':>6s} {'plast %':>7s} {'pattern u':>10s}  missed")
    for label, change in sweeps:
        values = chosen | change
        try:
            m, short, pairs, ute = _analyse(basic, flank, values, torques, memo, teeth,
                                            args.check)
        except Exception as exc:  # a design that fails is a row, not the end
            print(f"{label:18s} failed: {exc}".splitlines()[0])
            continue
        lte = m["lte_peak_to_peak"]
        print(f"{label:18s} {lte[0]:6.0f}/{lte[1]:<6.0f} {ute:5.0f} {pairs[0]:7.2f} "
              f"{100 * m['edge_load_share'][1]:6.1f} {100 * np.max(m['plastic_share']):7.1f} "
              f"{m['pattern_toe_u'][0]:4.2f}-{m['pattern_heel_u'][0]:4.2f}  "
              + ", ".join(k for k, v in short.items() if v > 0))


if __name__ == "__main__":
    main()
