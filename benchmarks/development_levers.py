"""What each development lever does to the light-load pattern and the LTE (issue 71;
docs/synthesis.md, "What sets the pattern and the LTE").

About a bearing given by its prescriptions (``--base``, ``[synthesis]`` file units), each
design of ``--vary`` (a JSON list of prescription changes) is synthesised (steps 3-6 from a
memo where only step 7 changes) and analysed with the development's coarse LTCA
(:data:`~contact.optimize.development.COARSE_LTCA`; ``--check``: ``ltca run``'s sampling,
tip planes placed) at the light and design torque. One row per design: light-load pattern
length and ends (u, v), footprint centre v, LTE p-p at both torques, the unloaded TE p-p
(``/utca``), the mean tooth pairs in contact at both torques, the edge and plastic shares
at the design torque and the targets missed (:func:`~contact.optimize.development.
development_score`, default targets); ``--tolerance``: under each row, the tolerance
targets (toe, heel, edge, plastic) missed at each mounting excursion ΔE/ΔP ± 0.05 mm
(:func:`~contact.optimize.development_check.tolerance_checks`, the development's coarse
LTCA; ≈ 4 more analyses per design); ``--floor N``: under each row, the LTE floor of the
design's load sharing from the mesh stiffness at N torques from the light to the design
torque (:func:`floor_line`; docs/synthesis.md, "The LTE floor of a face contact ratio
near 1"); ``--at T ...``: under each row, the LTE p-p at more torques [N m] (from one
analysis at those and the two), the mean tooth pairs carrying load at each, the share of
the mesh cycle one pair carries alone at the design torque and the deflection's floor from
the least torque to the design torque (:func:`at_line`; docs/synthesis.md, "LTE at every
torque on a face contact ratio below 1"); ``--edges``: under each row, each edge kind's peak
pressure at the design torque as ``ltca run``'s ``edge_pressure`` check reads it (0 below its
0.05 % share floor) and the largest LTE p-p at ``ltca run``'s evenly spaced ``lte_range``
torques between the two (:func:`range_line`; docs/synthesis.md, "The spiral bevel 12×31 at
Σ 112.5°: its edges and missed targets diagnosed"; on its written case the row reads 3051 /
4171 MPa and 47 µrad at 149.5 N m, ``ltca run``'s own numbers).

Usage::

    python benchmarks/development_levers.py tests/data/designs/spiral_bevel_13x39.toml \\
        --torques 40.62 270.8 \\
        --base '{"path_angle": -58.8, "ellipse_length": 0.55, "tip_relief": 0,
                 "root_relief": 0, "relief_start": 0.5, "profile_crowning": 0,
                 "blade_angle_change": 0, "te_level": 45}' \\
        --vary '[{}, {"blade_angle_change": -0.1}, {"root_relief": 60, "relief_start": 0.2},
                 {"tip_relief": 15, "tip_relief_start": 0.85}, {"te_level": 10}]'

(≈ 2 s CPU per design with a new steps 3-6, 0.3 s where only the relief, the blade angle
or the crowning change.)

``--flank coast --from-case CASE`` varies the **coast** flank of a case ``ltca synthesize``
wrote from ``BASIC``: both flanks' developed prescriptions are read from the case's
``[development]`` tables (the drive flank's kept, the coast flank's the base of
``--vary``; a generated gear as the case's synthesis says), and the coast flank analysed
at the torques given (its light and coast design torque), e.g.::

    python benchmarks/development_levers.py tests/data/limits/hypoid_8x41_b22.toml \
        --torques 28.8 119 --flank coast --from-case hypoid_8x41_b22_case.toml --check \
        --vary '[{}, {"ellipse_length": 0.5}, {"path_angle": -43.75}]'

(the flank peak pressure at the design torque [MPa] and the development's objective are
printed too; ``--tolerance`` checks the drive flank.)

A row reads a design as the development's check does (``checked_analysis``: the same
numbers, tests/test_development_hollow_target.py), but ``--from-case`` varies the design
*as written*, after every step: a step inside the check varies the design before the later
steps (the edge-peak step's relief) change it. On the FH hypoid 9x39 at Σ 95° that made
the same recipe 1.4 % edge here and 2.4 % in the check's hollow step (root relief 15 vs
9.55 µm; docs/synthesis.md, "The development and development_levers 1 % apart on the
9×39's edge"): give the earlier design's values in ``--base`` to read what a check step saw.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time


def main(argv: list[str] | None = None) -> None:
    import numpy as np

    from contact.chain import AnalysisChain
    from contact.ltca.edges import EDGE_KINDS
    from contact.optimize import development as dev
    from contact.optimize.development_check import tolerance_checks
    from contact.optimize.development_result import TOLERANCE_KEYS
    from contact.pipeline import run_analysis
    from geometry.synthesis.basic_design import load_basic, with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("basic")
    ap.add_argument("--torques", nargs=2, type=float, required=True,
                    metavar=("LIGHT", "DESIGN"), help="pinion torques [N m]")
    ap.add_argument("--base", default="{}", help="JSON: the bearing's prescriptions")
    ap.add_argument("--vary", default="[{}]", help="JSON list of changes to the base")
    ap.add_argument("--check", action="store_true", help="ltca run's sampling")
    ap.add_argument("--flank", choices=("drive", "coast"), default="drive",
                    help="the flank varied and analysed (default the drive flank)")
    ap.add_argument("--from-case", default=None, metavar="CASE",
                    help="a case `ltca synthesize` wrote from BASIC: both flanks' developed "
                         "prescriptions (its [development] tables) under --base")
    ap.add_argument("--floor", type=int, default=0, metavar="N",
                    help="also the LTE floor of each design's load sharing: N >= 2 torques "
                         "from LIGHT to DESIGN with the mesh stiffness, half the p-p of "
                         "the deflection between them (docs/synthesis.md, 'The LTE floor')")
    ap.add_argument("--at", type=float, nargs="+", default=None, metavar="T",
                    help="also the LTE p-p at these pinion torques [N m], the mean pairs "
                         "carrying load at each and the deflection's floor from the least "
                         "of them to DESIGN")
    ap.add_argument("--edges", action="store_true",
                    help="also each edge kind's peak pressure [MPa] at DESIGN as ltca run's "
                         "edge_pressure check reads it (0: below the 0.05 %% share floor), "
                         "and the LTE p-p between the torques (its lte_range); the edge "
                         "contact at LIGHT (p_max edge, its share, each kind's peak)")
    ap.add_argument("--tolerance", action="store_true",
                    help="also the development's tolerance check (coarse LTCA at "
                         "dE/dP +/- 0.05 mm): the tolerance targets missed, per excursion")
    args = ap.parse_args(argv)
    basic = load_basic(args.basic)
    drive = basic.options.drive_flank
    coast = "convex" if drive == "concave" else "concave"
    flank = drive if args.flank == "drive" else coast
    base = {}
    if args.from_case:
        import tomllib
        with open(args.from_case, "rb") as f:
            written = tomllib.load(f).get("development", {})
        drive_values = written.get("prescriptions", {})
        coast_values = written.get("coast", {}).get("prescriptions", {})
        basic = with_flank_options(basic, drive, drive_values)
        if coast_values:
            basic = with_flank_options(basic, coast, coast_values)
        base = dict(drive_values if args.flank == "drive" else coast_values)
        if "generated gear" in str(tomllib.loads(open(args.from_case).read())
                                   .get("synthesis", {}).get("method", "")):
            basic = dataclasses.replace(
                basic, options=dataclasses.replace(basic.options, gear_process="Generate"))
    base |= json.loads(args.base)
    memo, teeth = {}, dev.KeptTeeth()
    options = dev.CHECK_LTCA if args.check else dev.COARSE_LTCA
    print(f"{'change':44s} {'len':>4s} {'u':>9s} {'v':>9s} {'cv':>4s} {'LTE l/d':>8s} "
          f"{'UTE':>4s} {'pairs':>9s} {'edge% l/d':>9s} {'pl%':>4s} {'p_max':>5s}  missed [CPU s]")
    for change in json.loads(args.vary):
        values = base | change
        t0 = time.process_time()
        try:
            case = synthesize(with_flank_options(basic, flank, values), memo=memo,
                              tip_planes=args.check)[0]
            opts = dataclasses.replace(
                options, compliance=teeth.compliance(dev.bearing_key(values)))
            tree = run_analysis(case, list(args.torques), flank=args.flank, options=opts,
                                deviations=False, steps=AnalysisChain.contact_only())
        except Exception as exc:  # a design that fails is a row, not the end
            print(f"{json.dumps(change):44s} failed: {exc}".splitlines()[0])
            continue
        m = dev.design_metrics(tree, case)
        objective, short, _ = dev.development_score(
            m, dev.DevelopmentTargets(), dev.grid_bounds(tree),
            centre_v=dev.working_depth_centre(case), pressure_limit=dev.static_strength(tree))
        pairs = np.asarray(tree["/ltca"]["pairs_in_contact"].values, float).mean(axis=-1)
        ute = float(tree["/utca"]["peak_to_peak_transmission_error"])
        lte = m["lte_peak_to_peak"]
        print(f"{json.dumps(change):44s} {m['pattern_heel_u'][0] - m['pattern_toe_u'][0]:4.2f} "
              f"{m['pattern_toe_u'][0]:4.2f}-{m['pattern_heel_u'][0]:4.2f} "
              f"{m['pattern_root_v'][0]:4.2f}-{m['pattern_tip_v'][0]:4.2f} "
              f"{m['pattern_centre_v'][0]:4.2f} {lte[0]:4.1f}/{lte[1]:<5.1f}{ute:4.0f} "
              f"{pairs[0]:4.2f}/{pairs[1]:4.2f} {100 * m['edge_load_share'][0]:4.1f}/"
              f"{100 * m['edge_load_share'][1]:<4.1f} "
              f"{100 * np.max(m['plastic_share']):4.1f} "
              f"{m['pressure_max_flank'][1]:5.0f}  "
              + ",".join(k for k, v in short.items() if v > 0)
              + f" obj {objective:.3g} [{time.process_time() - t0:.1f}]")
        if args.edges:
            print("    edges at DESIGN: " + ", ".join(
                f"{k} {m[f'edge_peak_{k}'][-1]:.0f}" for k in EDGE_KINDS
                if f"edge_peak_{k}" in m)
                + f" MPa; {range_line(case, args.torques, opts, args.flank)}")
            print("    " + light_line(m))
        if args.floor >= 2:
            print("    " + floor_line(case, np.linspace(*args.torques, args.floor), opts,
                                      args.flank))
        if args.at:
            print("    " + at_line(case, list(args.at) + list(args.torques), args.torques[1],
                                   opts, args.flank))
        if args.tolerance:
            setup = {"torques": list(args.torques), "centre_v": dev.working_depth_centre(case)}
            tol = tolerance_checks(case, dev.DevelopmentTargets(), setup, teeth, values)
            missed = {lab: [k for k in TOLERANCE_KEYS if short[k] > 0.0]
                      for lab, (_, short) in tol.items()}
            print("    tolerance: " + "; ".join(
                f"{lab} {','.join(ks) or 'ok'}" + (
                    f" (edge {100 * tol[lab][0]['edge_load_share'][1]:.1f} %, plastic "
                    f"{100 * np.max(tol[lab][0]['plastic_share']):.1f} %)" if ks else "")
                for lab, ks in missed.items()))


def light_line(m) -> str:
    """The edge contact at the light torque as ``ltca run`` prints it: ``p_max edge``
    [MPa], the ``edge_contact`` check's share [%] and each edge kind's peak [MPa] whatever
    its share (:func:`~contact.optimize.development_evaluate.light_edge_metrics`; the coast
    light-edge step's readings)."""
    from contact.ltca.edges import EDGE_KINDS

    if "pressure_max_edge" not in m:
        return "edges at LIGHT: not read"
    share = m.get("edge_contact_share")
    kinds = ", ".join(f"{k} {m[f'edge_pressure_{k}'][0]:.0f}" for k in EDGE_KINDS
                      if f"edge_pressure_{k}" in m)
    return (f"edges at LIGHT: p_max edge {m['pressure_max_edge'][0]:.0f} MPa"
            + (f", share {100 * share[0]:.2g} %" if share is not None else "")
            + (f" ({kinds} MPa)" if kinds else ""))


def range_line(case, torques, options, flank: str) -> str:
    """The LTE p-p at ``ltca run``'s ``lte_range`` torques between ``torques`` (light,
    design) [N m] (its evenly spaced ones, not its bisections), in words: the largest and
    where."""
    import numpy as np

    from contact.chain import AnalysisChain
    from contact.ltca.lte_range import lte_range_torques
    from contact.pipeline import run_analysis

    ts = [float(t) for t in lte_range_torques(torques)]
    tree = run_analysis(case, ts, flank=flank, options=options, deviations=False,
                        steps=AnalysisChain.contact_only())
    lte = np.asarray(tree["/ltca"]["lte_peak_to_peak"].values, float)
    return (f"between: {np.max(lte):.0f} urad at {ts[int(np.argmax(lte))]:g} N m")


def floor_line(case, torques, options, flank: str) -> str:
    """The LTE floor of a design's load sharing between the first and the last of
    ``torques`` [N m, pinion], in words.

    The LTE at a torque is the p-p over the roll φ of UTE(φ) + δ(φ, T), the unloaded TE
    plus the mesh deflection δ = ∫ dT_g / k_Θ(φ, T_g) (k_Θ the torsional mesh stiffness of
    :mod:`contact.ltca.mesh_interface`, T_g the gear torque); the unloaded TE is the same at
    both ends, so p-p(δ_last − δ_first) ≤ LTE_first + LTE_last and max(LTE_first,
    LTE_last) ≥ ½ p-p(δ_last − δ_first), whatever the TE parabola or the relief (as long as
    they leave the load sharing as it is). The integral by the trapezoid rule over
    ``torques``; beside it the same bound from the LTCA's own TE at the two ends (the
    integral exactly, the unloaded TE cancelling)."""
    import numpy as np

    from contact.chain import AnalysisChain
    from contact.optimize.development_lte_floor import te_floor
    from contact.pipeline import run_analysis

    tree = run_analysis(case, [float(t) for t in torques], flank=flank, options=options,
                        deviations=False,
                        steps=AnalysisChain.contact_only().with_steps(
                            mesh_interface="linearised"))
    lt = tree["/ltca"]
    k = np.asarray(tree["/mesh_interface"]["torsional_mesh_stiffness"].values, float)
    g = np.asarray(lt["gear_torque"].values, float)
    deflection = np.trapezoid(1e6 / k, g, axis=0)  # [µrad]: N m / (N m/rad)
    lte = np.asarray(lt["lte_peak_to_peak"].values, float)
    return (f"floor: 1/2 p-p of the deflection {torques[0]:.1f} -> {torques[-1]:.1f} N m "
            f"{0.5 * np.ptp(deflection):.1f} urad from k_theta (mean {np.mean(k[0]) / 1e6:.2f}"
            f" / {np.mean(k[-1]) / 1e6:.2f} MN m/rad), {te_floor(lt.to_dataset()):.1f} "
            f"urad from the TE; LTE p-p at each torque "
            + " / ".join(f"{x:.0f}" for x in lte))


def at_line(case, torques, design: float, options, flank: str) -> str:
    """A design's LTE p-p at each of ``torques`` [N m, pinion], in words, with the mean
    tooth pairs carrying load at each, the share of the mesh cycle one pair carries alone at
    ``design`` [N m] (the loaded contact ratio's hand-over) and the floor ½ p-p(δ_design −
    δ_least) of the mesh deflection δ = ∫ dT_g / k_Θ between the least torque and
    ``design`` (as :func:`floor_line`: no unloaded TE gets both below it while the load
    sharing stays; with the least torque near zero the LTE there is the unloaded TE, so the
    bound holds for every torque up to ``design``)."""
    import numpy as np

    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis

    ts = sorted({round(float(t), 6) for t in torques})
    tree = run_analysis(case, ts, flank=flank, options=options, deviations=False,
                        steps=AnalysisChain.contact_only().with_steps(
                            mesh_interface="linearised"))
    lt = tree["/ltca"]
    lte = np.asarray(lt["lte_peak_to_peak"].values, float)
    pairs = np.asarray(lt["pairs_in_contact"].values, float)
    k = np.asarray(tree["/mesh_interface"]["torsional_mesh_stiffness"].values, float)
    g = np.asarray(lt["gear_torque"].values, float)
    step = 0.5 * (1e6 / k[1:] + 1e6 / k[:-1]) * np.diff(g)[:, None]  # [µrad] trapezoid
    deflection = np.concatenate([np.zeros((1, k.shape[1])), np.cumsum(step, axis=0)])
    d = int(np.argmin(np.abs(np.asarray(ts) - float(design))))
    return ("LTE p-p at " + " / ".join(f"{t:g}" for t in ts) + " N m: "
            + " / ".join(f"{x:.0f}" for x in lte) + f" urad (largest {np.max(lte):.0f} at "
            f"{ts[int(np.argmax(lte))]:g}); pairs " + " / ".join(
                f"{x:.2f}" for x in pairs.mean(axis=1))
            + f"; one pair alone over {100 * np.mean(pairs[d] < 1.5):.0f} % of the cycle at "
            f"{ts[d]:g}; floor {ts[0]:g} -> {ts[d]:g} N m: "
            f"{0.5 * np.ptp(deflection[d] - deflection[0]):.0f} urad")


if __name__ == "__main__":
    main()
