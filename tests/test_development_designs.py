"""The designs of tests/data/designs from basic data to a rated analysis (issue 60, item 7;
issue 71): slow.

A spiral bevel without offset, a passenger-car hypoid, a large-offset truck hypoid and a
face-hobbed hypoid (``tests/data/designs/*.toml``, none bundled, each written from
docs/synthesis.md with every synthesis default) go through ``ltca synthesize`` (defaults:
the development bearing on, contact.optimize.development) and ``ltca run`` (root stress
and the ISO 10300 rating on, the defaults): rc 0, a verdict that is not FAIL, root stress
of both members at every torque, the rating present, and the developed case records what
its development achieved. The coast flank, developed at its own torques where it misses
a target as synthesised, is run too (``ltca run CASE --flank coast``, root stress and
rating on): a verdict that is not FAIL. The coast side is rated for long life up to the
case's ``[rating] coast_design_torque`` (its own ISO 10300 capacity, or lower its flank's
capacity at its developed bearing, which the synthesis writes where it is below the design
torque; ``ltca run --flank coast`` analyses no torque above it) and at a finite life above
it: at the drive
side's capacity the coast side's S_H and S_F of Method B1 — read from the basic data,
not from the flank's prescriptions — fall below their minima on some designs (measured:
passenger-car hypoid S_H 0.99, truck hypoid S_H 1.00 and gear S_F 1.18 against 1 and
1.3), which failed the coast run before the coast design torque.
``benchmarks/development_designs.py`` prints the same runs as a table (pattern, LTE, edge
share, verdict, CPU time).

Run with ``pytest -m slow tests/test_development_designs.py -n 0`` (≈ 3–5 min of CPU per
design with a cold FE cache, the coast run ≈ 1 min of it).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

DESIGNS = sorted(p for p in (Path(__file__).parent / "data" / "designs").glob("*.toml")
                 if not p.stem.endswith("_unrelieved"))

#: the issue-71 criteria ("done when") each design meets at ``ltca run``, measured
#: 2026-11-25 with the levers of docs/synthesis.md "What sets the pattern and the LTE"
#: (short tip relief, root-relief height design, TE stage; docs/own_gear_set.md, step 2):
#: "plastic" no plastic segment at any torque, "light_edge" no edge contact at the light
#: torque (15 % of the design torque), "lte60" LTE p-p <= 60 urad at every torque. Not
#: yet met: the LTE of the spiral bevel 14x35 at Σ 70° (134/71 urad) and of the 17x29 at
#: Σ 100° at its design torque (57/138 urad, docs/own_gear_set.md, "The LTE spread at light
#: load"). The four own
#: designs written for issue 71's "designs it has not seen" (spiral bevel 17x29 at Σ 100°,
#: hypoid 7x45 with a 45 mm offset, face-hobbed spiral bevel 12x37, hypoid 12x41 at
#: Σ 85°; docs/own_gear_set.md, "The drive flank on designs it has not seen") as measured
#: 2026-11-25 after the check's changes of that date.
_ALL = {"plastic", "light_edge", "lte60"}
DONE_WHEN = {
    "eaxle_hypoid_11x39_s80": _ALL,
    "fh_spiral_bevel_12x37_m3": _ALL,
    "hypoid_12x41_s85": _ALL,
    "hypoid_7x45_a45": _ALL,
    "spiral_bevel_17x29_s100_m0": {"plastic", "light_edge"},
    "fh_hypoid_10x37_m2": _ALL,
    "fh_hypoid_11x43": _ALL,
    "fh_hypoid_11x46_m3": _ALL,
    "hypoid_10x37_s75": _ALL,
    "hypoid_5x43": _ALL,
    "hypoid_6x41": _ALL,
    "pc_hypoid_10x43": _ALL,
    "spiral_bevel_13x39": _ALL,
    # the light torque's edge, lost since the generated gear's cradle goes through the pitch
    # apex (branch shell85, 2026-11-28: 1031 MPa on the gear tip at 46.6 N m, LTE 42.5 /
    # 75.7 urad, root relief 10.2 um from 0.341), developed away by the light-edge step
    # (contact.optimize.development_light_edge_relief, branch light86, 2026-11-28): root
    # relief 15.25 um from 0.2, p_max edge 0 at 46.6 N m, LTE 47.7 / 77.8 urad, tolerant.
    # Its LTE since the design torque is where the written drive keeps 60 urad (branch
    # lte87, 2026-11-28, contact.optimize.development_written_lte): the bearing written at
    # the ISO capacity 310.8 N m kept it from 24.4 to 162.7 N m only, so the drive was
    # developed again at 162.6 N m: LTE 35.0 / 44.5 urad at 24.3 / 162.6 N m, 26.2 / 24.8
    # between, no edge at the light torque, no plastic (the design torque honestly lower)
    "spiral_bevel_14x35_s70_m0": _ALL,
    "spiral_bevel_15x45_m0": _ALL,
    # the LTE between the run's torques (its lte_range step): 65.8 urad at 734.9 N m
    # between the light 254.3 and the design 1696 N m (38.5 / 38.6 urad at them) while the
    # development judged the two torques alone; since its check judges the torques between
    # as ltca run does (contact.optimize.development_range_lte, 2026-11-27): 23.5 / 50.8 /
    # 40.4 / 24.0 urad at 279.9 / 808.6 / 1337.3 / 1866 N m (docs/synthesis.md, "The LTE
    # between the development's torques")
    "truck_hypoid_8x41_a40": _ALL,
    "truck_hypoid_9x37": _ALL,
    # designs not seen before (issue 71's last clause), measured 2026-11-25 after the
    # edge-row shortfall (development_targets.EDGE_ROW_SHORTFALL): 727 MPa on the gear tip
    # edge at the light torque before it
    "hypoid_12x37_s105": _ALL,
    # and after the coast flank's redevelopment kept the chosen drive flank: LTE 99 / 115
    # urad and a FAIL (spread 0.55) before it, the drive flank written a stale design
    "truck_hypoid_8x39_a45": _ALL,
    # an unseen hypoid 7x37 (2.5-in cutter, b2 0.33 R_e2) at its user's 60 N m, measured
    # 2026-11-26 (LTE 21 / 30 urad; docs/own_gear_set.md, "unseen (3)")
    "hypoid_7x37_rc2p5": _ALL,
    # designs not seen before (3), measured 2026-11-26 (docs/own_gear_set.md, "Issue 71's
    # criteria on thirty-four designs"): the face-hobbed spiral bevel 11x33 after the coast
    # redevelopment's pressure bound
    "fh_spiral_bevel_11x33_m0": _ALL,
}


#: designs whose development meets every drive target of contact.optimize.development
#: (the first clause of its "development: design ..." line), measured 2026-11-25: the
#: spiral bevel 13x39 and the hypoid 12x41 at Σ 85° since the check's height steps
#: (a shorter tip relief at 0.8, 2/3, 1/2, the root relief with a longer ellipse;
#: docs/own_gear_set.md, "The pattern's height": centre v 0.64 and 0.63 before), the
#: others on main before them (docs/own_gear_set.md, "The drive flank on designs it has
#: not seen"), which those steps do not reach (they run only on a pattern above its
#: centre's tolerance at the check)
#: The 5x43, 6x41, the 10x37 at Σ 75° and the face-hobbed 10x37 measured so on the merged
#: tree (`benchmarks/development_designs.py --done-when`, docs/own_gear_set.md, "Issue 71's
#: criteria on seventeen designs").
DRIVE_TARGETS_MET = {"eaxle_hypoid_11x39_s80", "fh_hypoid_11x43", "fh_spiral_bevel_12x37_m3",
                     "hypoid_12x41_s85", "hypoid_7x45_a45", "pc_hypoid_10x43",
                     "spiral_bevel_13x39", "spiral_bevel_15x45_m0", "truck_hypoid_9x37",
                     "hypoid_5x43", "hypoid_6x41", "hypoid_10x37_s75", "fh_hypoid_10x37_m2",
                     "hypoid_12x37_s105", "truck_hypoid_8x39_a45", "hypoid_7x37_rc2p5",
                     "fh_spiral_bevel_11x33_m0"}

#: designs whose developed drive flank is tolerant at the mounting excursions (ΔE, ΔP ±
#: 0.05 mm; ``[development] tolerant``): the hypoid 12x37 at Σ 105°, since the check's
#: tolerance step (development_check.checked_tolerance, 2026-11-26 01:31: 2.8 % on the
#: edges at ΔE −0.05 mm before it, its tip relief 15 µm; 22.5 µm after). The Sainsot base
#: compliance held at its fit's range (merge 4edff8f, phys71, 2026-11-26 10:01) moved its
#: development (chosen: tip relief 15 µm, root relief 25 µm from 0.2, te_level 25; 2.4 %
#: at ΔE −0.05 mm, 2.03 % at ΔP −0.05 mm, limit 2 %), and the step's full raises each gave
#: up a met target (tip relief 22.5 µm the centre v, 0.63 against 0.545 ± 0.08; root relief
#: 37.5 µm the LTE, 29 / 48 µrad); since the raise is also tried at 2/3 and 1/3
#: (TOLERANCE_RAISE_FRACTIONS, branch tol71b) the tip relief 17.5 µm meets every target and
#: is tolerant again (edges 1.5 / 1.5 / 1.4 / 1.2 % at ΔE ± / ΔP ± 0.05 mm;
#: docs/own_gear_set.md, "The bundled designs on the tree of 2026-11-26").
TOLERANT: set[str] = {"hypoid_12x37_s105"}


#: designs whose ``ltca run`` FAILs, measured 2026-11-25, with what the one reason says:
#: the 14x35 at Σ 70° (undercut toe; its Formate gear at δ2 51.7°, below the ≈ 63° the
#: Formate gear reaches: docs/synthesis.md, "Limits") at the light torque of its local
#: pitting capacity, 26.6 N·m: LTE spread 0.61 — its pinion's blade angle −0.19° and the
#: root relief from 0.2 of the way raise the unloaded TE to 197 µrad p-p and one tooth
#: pair carries the light torque over 75 % of the mesh cycle (docs/own_gear_set.md, "The
#: LTE spread at light load"). The spiral bevel 17x29 at Σ 100° no longer FAILs (the
#: check's steps on each checked design, a spread beyond the verdict's limit ranked after
#: every design the verdict passes: LTE 57 / 138 µrad, spread 0.28, ATTENTION).
#: Since the LTE is weighed at each torque and a pattern on the edge row outweighs an LTE
#: miss (2026-11-25, lowcr71 and unseen71 merged), the 14x35's `ltca run` has no FAIL
#: finding either (the slow run of this test at the merged tree, 2026-11-25 23:50 UTC).
#: Since an LTE p-p beyond twice the verdict's 60 µrad is a FAIL (contact.study.verdicts.
#: LTE_FAIL_FACTOR, issue 71, 2026-11-26, branch lowcr71) the 17x29 at Σ 100° FAILs on
#: it alone: 133 µrad at its design torque 402.8 N·m, ε_vβ 0.96 (docs/own_gear_set.md,
#: "Low contact ratios: the profile crowning and the TE parabola").
RUN_FAILS: dict[str, str] = {
    "spiral_bevel_17x29_s100_m0": "times the 60 µrad of the loaded transmission error",
}

#: issue 71 item 2 (both flanks, one design torque that holds), measured 2026-11-25 with
#: each flank's design torque capped at its local pitting capacity and the coast flank
#: developed again at its own design torque (docs/own_gear_set.md, "One design torque that
#: holds"): "coast_lte60" LTE p-p <= 60 urad on the coast flank at its light and design
#: torque, "duty" the default duty cycle (`ltca duty-cycle CASE`, the illustrative
#: spectrum up to the design torque) not FAIL (any check). Designs not listed were not
#: re-measured.
COAST_DONE_WHEN: dict[str, set[str]] = {
    "eaxle_hypoid_11x39_s80": {"coast_lte60", "duty"},
    "hypoid_10x37_s75": {"coast_lte60", "duty"},
    "hypoid_5x43": {"coast_lte60", "duty"},
    # the duty cycle's top bin at the design torque 357 N m FAILs its gear root, S_F,FE 1.29 <
    # 1.3, under the bundled spectrum's made-up deflection (dE 0.05, dP -0.03, dG 0.03 mm;
    # ltca run at 357 N m without it: 1.32, not FAIL); measured 2026-11-27 at 5b52318 since
    # the duty cycle judges the FE root as ltca run does (dutyroot81): not met
    "pc_hypoid_10x43": {"coast_lte60"},
    "spiral_bevel_13x39": {"coast_lte60", "duty"},
    "truck_hypoid_9x37": {"coast_lte60", "duty"},
    "hypoid_6x41": {"coast_lte60", "duty"},
    "spiral_bevel_15x45_m0": {"coast_lte60", "duty"},
    "spiral_bevel_14x35_s70_m0": {"duty"},
    "fh_hypoid_10x37_m2": {"coast_lte60", "duty"},
    "fh_spiral_bevel_12x37_m3": {"coast_lte60", "duty"},
    "hypoid_12x41_s85": {"coast_lte60", "duty"},
    "hypoid_7x45_a45": {"coast_lte60", "duty"},
    # since the LTE is weighed at each torque (its light torque's LTE 100 -> 70 urad): the
    # duty cycle's lightest bin, 40.3 N m, spread 0.44 where it was 0.67 (FAIL); measured
    # 2026-11-25, docs/own_gear_set.md, "A face contact ratio below 1.25"
    "spiral_bevel_17x29_s100_m0": {"duty"},
    "hypoid_12x37_s105": {"coast_lte60", "duty"},
    "truck_hypoid_8x39_a45": {"coast_lte60", "duty"},
    "hypoid_7x37_rc2p5": {"coast_lte60", "duty"},
    # the 11x33's coast LTE p-p 64 urad at its coast design torque 180.8 N m (ε_vβ 1.12;
    # 61 urad at 119.2 N m before the pressure bound)
    "fh_spiral_bevel_11x33_m0": {"duty"},
}


@pytest.mark.slow
@pytest.mark.parametrize("basic", DESIGNS, ids=[p.stem for p in DESIGNS])
def test_user_design_synthesised_developed_run_and_rated(basic, tmp_path, capsys):
    from contact.cli import main
    from contact.optimize.development import COAST_STATUS
    from contact.study.verdicts import verdict

    case_path = tmp_path / f"{basic.stem}.toml"
    assert main(["synthesize", str(basic), "-o", str(case_path)]) == 0
    out = capsys.readouterr().out
    assert "development: design" in out
    # the outcome in numbers: each missed target's value and limit, both flanks' pressure
    assert "flank peak pressure at" in out and "coast" in out
    head = next(line for line in out.splitlines() if "development: design" in line)
    assert ", every target met;" in head or "(limit " in head or "(target " in head, head
    if basic.stem in DRIVE_TARGETS_MET:  # the drive flank's clause, before the coast's
        assert head.split(";")[0].endswith(", every target met"), head
    if basic.stem in TOLERANT:
        assert "; tolerant at dE" in head, head
    case = tomllib.loads(case_path.read_text(encoding="utf-8"))
    assert "Development bearing" in case["source"]
    dev = case["development"]
    assert len(dev["torque_Nm"]) == 2 and dev["torque_Nm"][0] < dev["torque_Nm"][1]

    nc = tmp_path / f"{basic.stem}.nc"
    assert main(["run", str(case_path), "-o", str(nc)]) == 0
    tree = xr.open_datatree(nc)
    v = verdict(tree)
    if basic.stem in RUN_FAILS:  # the measured state: where it fails, on that alone (its
        # 128-133 µrad sits near the 120 µrad FAIL line; a search that lands below it gives
        # an ATTENTION on the same finding, which is as right)
        fails = [f.reason for f in v.findings if f.severity == "fail"]
        assert all(RUN_FAILS[basic.stem] in r for r in fails), fails
    else:
        assert v.severity != "fail", [f.reason for f in v.findings]
    lt = tree["/ltca"]
    root = lt["root_stress_max"].transpose("torque", "member").values
    assert root.shape == (lt.sizes["torque"], 2)  # pinion and gear at every torque
    assert np.all(np.isfinite(root)) and np.all(root > 0)
    assert "rating" in tree.children and "S_H" in tree["/rating"]
    # issue 71's criteria, where this design meets them (DONE_WHEN)
    met = DONE_WHEN.get(basic.stem, set())
    if "plastic" in met:
        share = np.nan_to_num(lt["plastic_load_share"].values) if (
            "plastic_load_share" in lt) else np.zeros(1)
        assert np.all(share == 0.0), share
    if "light_edge" in met:  # the light torque is the first (the development's)
        assert float(np.nan_to_num(lt["pressure_max_edge"].values)[0]) == 0.0
    if "lte60" in met:  # at the run's torques and between them (its lte_range step)
        assert np.all(lt["lte_peak_to_peak"].values <= 60.0), lt["lte_peak_to_peak"].values
        between = np.asarray(lt["lte_range_peak_to_peak"].values)
        assert np.all(np.nan_to_num(between) <= 60.0), between

    # the coast flank (reverse gear: the full torque on the coast side)
    coast = case["development"]["coast"]
    assert coast["development"] != COAST_STATUS["not checked"]
    assert "Coast flank (" in case["source"]
    nc_coast = tmp_path / f"{basic.stem}_coast.nc"
    assert main(["run", str(case_path), "--flank", "coast", "-o", str(nc_coast)]) == 0
    tree = xr.open_datatree(nc_coast)
    fails = [f.reason for f in verdict(tree).findings if f.severity == "fail"]
    assert not fails, fails
    root = tree["/ltca"]["root_stress_max"].values
    assert np.all(np.isfinite(root)) and np.all(root > 0)
    coast_met = COAST_DONE_WHEN.get(basic.stem, set())
    if "coast_lte60" in coast_met:  # at the light and the coast design torque and between
        lte = tree["/ltca"]["lte_peak_to_peak"].values
        assert np.all(lte <= 60.0), lte
        between = np.asarray(tree["/ltca"]["lte_range_peak_to_peak"].values)
        assert np.all(np.nan_to_num(between) <= 60.0), between
    if "duty" in coast_met:  # the default spectrum up to the design torque
        nc_duty = tmp_path / f"{basic.stem}_duty.nc"
        main(["duty-cycle", str(case_path), "--scheduler", "synchronous", "-o", str(nc_duty)])
        duty = xr.open_datatree(nc_duty)
        # issue 71's Done when: "a duty cycle at the design torque not FAIL" — every
        # check of the duty cycle's verdict, not only the pitting damage (since static79
        # the duty cycle judges a bin's flank and edges against ltca run's static strength,
        # so a bin above it is a FAIL this assertion must see)
        fails = [f"{f.check}: {f.reason}" for f in verdict(duty).findings
                 if f.severity == "fail"]
        assert not fails, fails


#: basic designs of benchmarks/data/unseen_designs whose face contact ratio ε_vβ ≤ 1.00
#: reaches no LTE p-p <= 60 urad with any lever of the development, developed with the
#: contact-ratio remedy their note checks applied (``ltca synthesize --apply-remedy``,
#: contact.optimize.development_remedy; docs/synthesis.md, "The checked remedy applied"):
#: the field changed, its value in the file and applied, and the largest drive LTE p-p
#: [urad] measured between the run's torques (its lte_range step). The 15x28 at Σ 110°,
#: measured 2026-11-27 (branch facewidth79): b2 28 -> 36.5 mm, ε_vβ 0.91 -> 1.25, drive
#: LTE 19.8 / 45.1 urad at 123.6 / 824.3 N m and 62.4 urad between them at 357.2 N m
#: (ATTENTION; the design as given 86 / 93 urad at 91.8 / 612.4 N m), coast 48.4 / 53.4
#: urad and at most 55.8 between. The hypoid 15x31 at a = 0.056 d_e2, measured 2026-11-27
#: after the development judged the drive LTE between its torques (branch remedy79): b2 27
#: -> 32.6 mm, ε_vβ 1.00 -> 1.25, drive LTE 45.1 / 58.2 urad at 104.8 / 699.2 N m and 63.3
#: urad between them at 501.1 N m (ATTENTION; no design the development tried kept 60
#: there), coast 43.4 / 45.2 urad at 104.8 / 260.3 N m and at most 47.1 between. Since
#: the next checked remedy is developed where the first misses 60 urad between the torques
#: (contact.optimize.development_remedy_next; measured 2026-11-27, branch remedynext80):
#: the 15x31's beta_m 40 -> 46.3 deg is kept (ε_vα 0.98), drive LTE 41.6 / 57.8 urad at
#: 77.2 / 514.8 N m and 49.0 / 56.3 urad between them (ATTENTION 3); the 15x28's beta_m
#: 43.9 deg developed to 40.8 / 71.7 urad and was not kept (b2 written as before)
# The remedy each design keeps and the largest drive LTE p-p its synthesize measured over
# ltca run's torques (the bound between them). Measured 2026-11-27 at 5e12882: the
# hypoid's beta_m remedy now misses the pattern length the development keeps (len81), so
# its face width is kept; the spiral bevel's beta_m remedy keeps 60.9 urad between the
# torques against the face width's 62.5, with no target lost, so it is kept.
# Measured 2026-11-28 at 10690213 (spline89's ease-off cut at relief corners, regain89's
# raise that keeps the LTE window): the spiral bevel's first remedy, the face width b2
# 28 -> 36.5 mm, now keeps 59.3 urad between the torques (drive 14.6 / 44.1 urad at
# 123.6 / 824.3 N m, coast 47.7 / 53.9 and 55.7 between; ATTENTION 3, no FAIL), so the
# next remedy (beta_m) is not developed.
REMEDIED = {"spiral_bevel_15x28_s110": ("b2", 28.0, 36.5, 59.3),
            "hypoid_15x31_a10": ("b2", 27.0, 32.6, 63.3)}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(REMEDIED))
def test_remedied_design_applied_developed_and_run(name, tmp_path, capsys):
    """``ltca synthesize BASIC --apply-remedy``: the first line says the change, the case
    records it (its ``[applied_remedy]`` table, its source's first sentence), and the
    remedied design's runs: no FAIL, the drive LTE within 60 urad at the run's torques
    and within the measured bound between them, the coast LTE within 60 urad at every
    torque analysed."""
    from contact.cli import main
    from contact.study.verdicts import verdict

    field, before, after, between_bound = REMEDIED[name]
    basic = Path(__file__).resolve().parent.parent / "benchmarks" / "data" / \
        "unseen_designs" / f"{name}.toml"
    case_path = tmp_path / f"{name}.toml"
    assert main(["synthesize", str(basic), "--apply-remedy", "--no-progress", "-o",
                 str(case_path)]) == 0
    first = capsys.readouterr().out.splitlines()[0]
    assert first.startswith("applied remedy (--apply-remedy): ") and \
        f"{field} {before:g} -> {after:g}" in first, first
    case = tomllib.loads(case_path.read_text(encoding="utf-8"))
    table = case["applied_remedy"]
    assert (table["field"], table["before"], table["after"]) == (field, before, after)
    assert table["eps_vb_after"] >= 1.25 > table["eps_vb_before"]
    said = case["source"].split(". ")[0]  # the first sentence: the basic data's source
    assert "; remedied by ltca synthesize --apply-remedy: " in said and \
        f"{field} {before:g} -> {after:g}" in said, said

    nc = tmp_path / f"{name}.nc"
    assert main(["run", str(case_path), "-o", str(nc)]) == 0
    tree = xr.open_datatree(nc)
    assert verdict(tree).severity != "fail", [f.reason for f in verdict(tree).findings]
    lt = tree["/ltca"]
    assert np.all(lt["lte_peak_to_peak"].values <= 60.0), lt["lte_peak_to_peak"].values
    between = np.nan_to_num(np.asarray(lt["lte_range_peak_to_peak"].values))
    # the run-to-run spread of a development under load: 5 % on the measured bound
    assert np.all(between <= 1.05 * between_bound), between
    nc_coast = tmp_path / f"{name}_coast.nc"
    assert main(["run", str(case_path), "--flank", "coast", "-o", str(nc_coast)]) == 0
    tree = xr.open_datatree(nc_coast)
    assert verdict(tree).severity != "fail", [f.reason for f in verdict(tree).findings]
    lte = np.nan_to_num(np.asarray(tree["/ltca"]["lte_range_peak_to_peak"].values))
    assert np.all(lte <= 60.0), lte
