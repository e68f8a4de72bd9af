"""Shell against FE compliance in the LTCA: the seed's Fig. 3.4/3.7 comparison (issue 35).

For the default case (``kolivand2009_fm_11x41_reference``) and the face-hobbed pair
``kolivand2009_fh_12x41`` at 50/250/500 N·m and the seed's Fig. 3.7 misalignments
(Table 3.1's ΔE = −0.15, ΔP = +0.12 mm; Fig. 3.7d's −0.08, +0.05; Fig. 3.7e's −0.26, +0.13:
``contact.catalogue.SEED_TABLE_3_1`` argues the signs), one LTCA with each compliance
(``LTCAOptions(compliance="shell")`` and ``"fe"``, otherwise the defaults) and the default
FE model (docs/fe.md: the mesh whose refinement changes the mid-surface compliance by
< 3 %). Printed per (case, misalignment, torque): LTE mean and peak-to-peak [µrad], the
largest share of the gear torque one tooth pair carries over the cycle [%], the peak
flank pressure [MPa], the loaded pattern's extent (lengthwise × profile) [mm] and its
centre [1], and the peak tooth-root stress of both members [MPa] (the default FE model's
fillet stress of each LTCA's loads: the loads differ, the stress coefficients do not) for
both compliances; then the time of each analysis (ease-off, UTCA, the LTCA of the three
torques and the root stress; wall and process CPU, in one process, one after the other:
the ratio FE/shell is the number to read).

The FE coefficients are read from the disk cache (built the first time: ~0.5–1.5 min per
member; their build is timed apart and not in the LTCA's time).

Run::

    OMP_NUM_THREADS=1 python benchmarks/fe_ltca.py [--quick]

``--quick``: the default case, Table 3.1's misalignment only. ``--ablation``: also, at
Table 3.1's misalignment, the FE LTCA with the FE coupling between neighbouring teeth
dropped (the inter-tooth blocks of each member's compliance set to zero, by replacing
:func:`contact.compliance.fe.contact_compliance.interpolated_compliance` in this process
only): what the rim's coupling of the teeth does to the LTE and the load sharing.
"""

from __future__ import annotations

import argparse
import dataclasses
import time

import numpy as np
from tabulate import tabulate

from contact.catalogue import resolve_case
from contact.compliance.fe import influence_coefficients
from contact.ltca import LTCAOptions
from contact.pipeline import run_analysis
from contact.study.summary import point_summary
from contact.utca.easeoff import ease_off
from geometry.pair.assembly import Misalignment

CASES = ("kolivand2009_fm_11x41_reference", "kolivand2009_fh_12x41")
#: the seed's Fig. 3.7 misalignments (ΔE, ΔP) [mm]: a–c (Table 3.1), d, e
MISALIGNMENTS = {"3.7a-c": (-0.15, 0.12), "3.7d": (-0.08, 0.05), "3.7e": (-0.26, 0.13)}
TORQUES = (50.0, 250.0, 500.0)


def _summary(case, tree):
    """LTE, pair share, pressure, pattern of an analysis, per torque."""
    lt = tree["ltca"].to_dataset()
    s = point_summary(tree, case)
    share = np.nanmax(np.nan_to_num(lt["load_share"].values), axis=(1, 2))  # (torque,)
    return {"lte_mean": lt["lte_mean"].values, "lte_pp": lt["lte_peak_to_peak"].values,
            "share": 100.0 * share, "p_flank": lt["pressure_max_flank"].values,
            "length": s["pattern_length"], "height": s["pattern_height"],
            "cu": s["pattern_centre_u"], "cv": s["pattern_centre_v"],
            "sigma_p": lt["root_stress_max"].sel(member="pinion").values,
            "sigma_g": lt["root_stress_max"].sel(member="gear").values}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--ablation", action="store_true")
    args = ap.parse_args()
    cases = CASES[:1] if args.quick else CASES
    mis = dict(list(MISALIGNMENTS.items())[:1]) if args.quick else MISALIGNMENTS
    rows, times = [], []
    for name in cases:
        base = resolve_case(name)
        eo0 = ease_off(base)
        t0 = time.perf_counter()
        for member, flank in (("pinion", eo0.pinion_flank), ("gear", eo0.gear_flank)):
            influence_coefficients(base, member, flank, progress=False)
        t_coef = time.perf_counter() - t0
        for label, (de, dp) in mis.items():
            mis_ = Misalignment(delta_E=de, delta_P=dp)
            case = dataclasses.replace(base, misalignment=mis_)
            res, tm = {}, {}
            for comp in ("shell", "fe"):
                w0, c0 = time.perf_counter(), time.process_time()
                tree = run_analysis(base, list(TORQUES), misalignment=mis_,
                                    options=LTCAOptions(compliance=comp), operating=False,
                                    geometry=False, mesh_interface=False, root_stress=True)
                tm[comp] = (time.perf_counter() - w0, time.process_time() - c0)
                res[comp] = _summary(case, tree)
                res[comp]["certified"] = bool(np.all(tree["ltca"]["found"].values))
            for it, torque in enumerate(TORQUES):
                r = [name.replace("kolivand2009_", ""), label, f"{torque:g}"]
                for key, fmt in (("lte_mean", "{:.0f}"), ("lte_pp", "{:.1f}"),
                                 ("share", "{:.0f}"), ("p_flank", "{:.0f}")):
                    r.append(" / ".join(fmt.format(res[c][key][it]) for c in ("shell", "fe")))
                r.append(" / ".join(f"{res[c]['length'][it]:.1f}×{res[c]['height'][it]:.1f}"
                                    for c in ("shell", "fe")))
                r.append(" / ".join(f"({res[c]['cu'][it]:.2f}, {res[c]['cv'][it]:.2f})"
                                    for c in ("shell", "fe")))
                for key in ("sigma_p", "sigma_g"):
                    r.append(" / ".join(f"{res[c][key][it]:.0f}" for c in ("shell", "fe")))
                rows.append(r)
            times.append([name.replace("kolivand2009_", ""), label, f"{tm['shell'][0]:.1f}",
                          f"{tm['fe'][0]:.1f}", f"{tm['shell'][1]:.1f}", f"{tm['fe'][1]:.1f}",
                          f"{tm['fe'][1] / tm['shell'][1]:.2f}",
                          "yes" if res["fe"]["certified"] and res["shell"]["certified"]
                          else "no"])
        print(f"{name}: FE coefficients (cache or first build) {t_coef:.1f} s", flush=True)
    print(tabulate(rows, headers=["case", "Fig.", "T_p [N·m]", "LTE mean [µrad]",
                                  "LTE p-p [µrad]", "max pair share [%]",
                                  "peak flank p [MPa]", "pattern L×H [mm]",
                                  "pattern centre (u, v)", "σ_F pinion [MPa]",
                                  "σ_F gear [MPa]"], tablefmt="github"))
    print("\n(shell / FE in every cell)\n")
    print(tabulate(times, headers=["case", "Fig.", "shell wall [s]", "FE wall [s]",
                                   "shell CPU [s]", "FE CPU [s]", "FE/shell (CPU)",
                                   "certified"], tablefmt="github"))
    if args.ablation:
        print()
        print(tabulate(_ablation(cases), headers=[
            "case", "FE coupling", "LTE mean [µrad]", "LTE p-p [µrad]", "max pair share [%]",
            "peak flank p [MPa]"], tablefmt="github"))


def _ablation(cases) -> list[list[str]]:
    """The FE LTCA at Table 3.1's misalignment with and without the inter-tooth blocks."""
    import contact.compliance.fe.contact_compliance as cc

    full = cc.interpolated_compliance

    def own_tooth(coefficients, weights, tooth, variable="centreline"):
        c = full(coefficients, weights, tooth, variable)
        k = np.asarray(tooth)
        return np.where(k[:, None] == k[None, :], c, 0.0)

    de, dp = MISALIGNMENTS["3.7a-c"]
    rows = []
    try:
        for name in cases:
            for label, fn in (("with", full), ("without", own_tooth)):
                cc.interpolated_compliance = fn
                tree = run_analysis(name, list(TORQUES),
                                    misalignment=Misalignment(delta_E=de, delta_P=dp),
                                    options=LTCAOptions(compliance="fe"), operating=False,
                                    geometry=False, mesh_interface=False, root_stress=False)
                lt = tree["ltca"].to_dataset()
                share = 100 * np.nanmax(np.nan_to_num(lt["load_share"].values), axis=(1, 2))
                rows.append([name.replace("kolivand2009_", ""), label,
                             " / ".join(f"{x:.0f}" for x in lt["lte_mean"].values),
                             " / ".join(f"{x:.1f}" for x in lt["lte_peak_to_peak"].values),
                             " / ".join(f"{x:.0f}" for x in share),
                             " / ".join(f"{x:.0f}" for x in lt["pressure_max_flank"].values)])
    finally:
        cc.interpolated_compliance = full
    return rows


if __name__ == "__main__":
    main()
