"""The face contact ratio of a basic design and the face width / spiral angle that raise
it to 1.25 (contact.load_capacity.iso10300.face_contact; issue 71, the low-overlap designs
whose LTE the bearing levers lower only in part), and where the commands say it.

Fast: a few ISO 23509 blanks per design (≈ 0.3 s)."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from contact.load_capacity.iso10300.face_contact import (
    FACE_CONTACT_RATIO_MIN,
    PROFILE_CONTACT_RATIO_MIN,
    loaded_ratio_text,
    low_ratio_text,
    overlap_remedy,
    overlap_text,
    profile_remedy,
)
from geometry.core.errors import InputError
from geometry.synthesis.basic_design import load_basic

ROOT = Path(__file__).resolve().parent.parent
DESIGNS = ROOT / "tests" / "data" / "designs"


def _eps_vb(design) -> float:
    """ε_vβ = b_v,eff sin β_v / (π m_mn) (ISO 10300-1 A.2) by hand from the virtual gears'
    own b_v,eff and β_v and the blank's m_mn: the formula, not the module's chain."""
    from contact.load_capacity.iso10300.inputs import gear_data_from_blank
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears
    from geometry.iso23509.blank import blank_geometry

    data = gear_data_from_blank(blank_geometry(design))
    vg = virtual_gears(data)
    return vg.b_veff * math.sin(vg.beta_v) / (math.pi * data.m_mn)


def test_the_iso_tr_sample_3_ratio_is_the_reports():
    """ISO/TR 10300-30:2024 sample 3 prints ε_vβ = 0.860 (virtual_gears' docstring); the
    remedy's ratio is that one, to the TR's last digit."""
    from contact.load_capacity.iso10300.rating import case_gear_data
    from geometry.case import load_case

    _, blank = case_gear_data(load_case(ROOT / "cases" / "iso10300_30_sample3.toml"))
    r = overlap_remedy(blank.design)
    assert r.eps_vb == pytest.approx(0.860, abs=5e-4)


def test_the_17x29s_face_width_and_spiral_angle_reach_the_target():
    """The spiral bevel 17x29 at Σ 100° (ε_vβ 0.96 at b2 24 mm, β_m 35°): at the face width
    and at the spiral angle returned, ε_vβ by hand is 1.25 to the root-find's tolerance
    (0.001 mm / 0.001° moves ε_vβ by < 1e-4); a face width of 30 mm is just short of it
    and 31 mm beyond (bracketing the root independently); the face width needed is above
    0.3 R_e2, which the sentence says."""
    design = load_basic(DESIGNS / "spiral_bevel_17x29_s100_m0.toml").design
    r = overlap_remedy(design)
    assert r.eps_vb == pytest.approx(_eps_vb(design), rel=1e-12)
    assert r.eps_vb == pytest.approx(0.956, abs=1e-3)
    assert 30.0 < r.b2_needed < 31.0
    assert _eps_vb(dataclasses.replace(design, b2=30.0)) < FACE_CONTACT_RATIO_MIN
    assert _eps_vb(dataclasses.replace(design, b2=31.0)) > FACE_CONTACT_RATIO_MIN
    assert _eps_vb(dataclasses.replace(design, b2=r.b2_needed)) == pytest.approx(1.25,
                                                                                 abs=1e-4)
    assert _eps_vb(dataclasses.replace(design, beta_m=math.radians(r.beta_m_needed))
                   ) == pytest.approx(1.25, abs=1e-4)
    assert 40.0 < r.beta_m_needed < 45.0 and r.b2_needed > r.b2_limit
    text = overlap_text(design)
    assert "eps_vb 0.96 is below 1.25" in text
    # "above the usual" qualifies the width asked for, not the design's own 24 mm (below
    # the 26.0 mm: the 6x37 of unseen (9) read "(now 28, above the usual ... 29.4 mm)")
    assert r.b2 < r.b2_limit
    assert (f"b2 of {math.ceil(r.b2_needed * 10) / 10:.1f} mm, above the usual 0.3 R_e2 = "
            f"{r.b2_limit:.1f} mm (now 24)") in text
    assert f"beta_m of {math.ceil(r.beta_m_needed * 10) / 10:.1f} deg (now 35)" in text


def _eps_va(design) -> float:
    from contact.load_capacity.iso10300.inputs import gear_data_from_blank
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears
    from geometry.iso23509.blank import blank_geometry

    return float(virtual_gears(gear_data_from_blank(blank_geometry(design))).eps_va)


def test_an_overlap_remedy_that_takes_the_profile_ratio_below_1_says_so():
    """Issue 71, round 16: the hypoid 15x31 (ε_vα 1.10, ε_vβ 1.00) was offered β_m 46.3°
    for ε_vβ 1.25; synthesised there (hypoid_15x31_a10_b46p3.toml) it printed ε_vα 0.98
    and a profile-ratio note. The remedy now says what the spiral angle does to ε_vα; the
    face width, which keeps ε_vα above 1, gets no such words; the 17x29, whose both ways
    keep it above 1, reads as before."""
    unseen = ROOT / "benchmarks" / "data" / "unseen_designs"
    design = load_basic(unseen / "hypoid_15x31_a10.toml").design
    text = overlap_text(design)
    assert _eps_va(design) > PROFILE_CONTACT_RATIO_MIN
    after = _eps_va(dataclasses.replace(design, beta_m=math.radians(46.3)))
    assert after == pytest.approx(0.98, abs=5e-3)  # synthesize's own line: 0.98
    assert "beta_m of 46.3 deg (now 40; eps_va then 0.98, below 1)" in text
    assert _eps_va(dataclasses.replace(design, b2=32.6)) >= PROFILE_CONTACT_RATIO_MIN
    assert "(now 27) or" in text
    remedy = load_basic(unseen / "hypoid_15x31_a10_b46p3.toml").design
    assert _eps_va(remedy) == pytest.approx(after, rel=1e-12)
    assert "eps_va then" not in overlap_text(
        load_basic(DESIGNS / "spiral_bevel_17x29_s100_m0.toml").design)


def test_a_ratio_just_below_its_limit_is_printed_below_it():
    """Issue 71, unseen (12): the face-hobbed 7x39 at Sigma 85 deg (ε_vβ 1.2465, its own
    value by the ISO 10300 virtual gears) read "eps_vb 1.25 is below 1.25"; the number
    gets the decimals that show it below the limit (1.247), and 2 where those do (the
    17x29's 0.96 above)."""
    design = load_basic(ROOT / "benchmarks" / "data" / "unseen_designs"
                        / "fh_hypoid_7x39_s85_a30.toml").design
    eps = overlap_remedy(design).eps_vb
    assert eps == pytest.approx(_eps_vb(design), rel=1e-12) and round(eps, 2) == 1.25
    # within RATIO_AT_TARGET (0.01) of 1.25 it is said at its target, with the same 3
    # decimals (branch remedy82: the change b2 29 -> 29.1 mm is below a meaningful step)
    assert overlap_text(design).startswith("face contact ratio eps_vb 1.247 is at its target "
                                           "1.25 (0.003 below it, within 0.01; not a remedy "
                                           "here: a gear face width b2 of 29.1 mm (now 29)")
    # below the tolerance, said below it, as before (a target 0.0135 higher, 1.26)
    assert overlap_text(design, 1.26).startswith("face contact ratio eps_vb 1.25 is below "
                                                 "1.26, ")


def test_a_design_with_overlap_enough_gets_no_sentence():
    """The passenger-car hypoid 10x43 (ε_vβ 1.44): its own values, no sentence."""
    design = load_basic(DESIGNS / "pc_hypoid_10x43.toml").design
    r = overlap_remedy(design)
    assert r.eps_vb > FACE_CONTACT_RATIO_MIN
    assert (r.b2_needed, r.beta_m_needed) == (r.b2, r.beta_m)
    assert overlap_text(design) is None


@pytest.mark.parametrize("target", [0.0, -1.0, 6.0, math.nan, "1.25"])
def test_a_bad_target_is_refused(target):
    design = load_basic(DESIGNS / "pc_hypoid_10x43.toml").design
    with pytest.raises(InputError, match="target"):
        overlap_remedy(design, target)


def test_synthesizes_note_threshold_is_the_modules():
    """``ltca synthesize`` keeps the number without importing the rating (its import
    light): the two must agree."""
    from contact.commands.synthesize import FACE_CONTACT_RATIO_NOTE, PROFILE_CONTACT_RATIO_NOTE

    assert FACE_CONTACT_RATIO_NOTE == FACE_CONTACT_RATIO_MIN
    assert PROFILE_CONTACT_RATIO_NOTE == PROFILE_CONTACT_RATIO_MIN


def _eps_va(design) -> float:
    """ε_vα = g_vα / p_vet (ISO 10300-1 A.2) by hand from the virtual gears' own path of
    contact and transverse base pitch: the formula, not the module's chain."""
    from contact.load_capacity.iso10300.inputs import gear_data_from_blank
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears
    from geometry.iso23509.blank import blank_geometry

    vg = virtual_gears(gear_data_from_blank(blank_geometry(design)))
    return vg.g_va / vg.p_vet


def test_the_19x23s_depth_factor_and_pressure_angle_reach_a_profile_ratio_of_1():
    """The spiral bevel 19x23 at β_m 46° of benchmarks/data/unseen_designs (ε_vα 0.976,
    ε_vβ 1.27: the spiral angle that raised its face contact ratio lowered its profile
    contact ratio below 1): at the depth factor and at the drive pressure angle returned,
    ε_vα by hand is 1 to the root-find's tolerance (1e-3 in k_d or α_dD moves ε_vα by
    < 5e-4); k_d 2.05 is just short and 2.06 beyond, α_dD 19.0° short and 18.9° beyond
    (bracketing the roots independently). The sentence gives both, k_d rounded up to
    0.01 and α_dD down to 0.1° (each then reaches 1), and no face-width remedy (ε_vβ
    meets 1.25)."""
    design = load_basic(ROOT / "benchmarks" / "data" / "unseen_designs"
                        / "spiral_bevel_19x23_b46.toml").design
    r = profile_remedy(design)
    assert r.eps_va == pytest.approx(_eps_va(design), rel=1e-12)
    assert r.eps_va == pytest.approx(0.976, abs=1e-3)
    assert (r.k_d, r.alpha_d) == (2.0, pytest.approx(20.0, abs=1e-12))
    assert 2.05 < r.k_d_needed < 2.06 and 18.9 < r.alpha_d_needed < 19.0
    assert _eps_va(dataclasses.replace(design, k_d=2.05)) < 1.0
    assert _eps_va(dataclasses.replace(design, k_d=2.06)) > 1.0
    assert _eps_va(dataclasses.replace(design, alpha_dD=math.radians(19.0))) < 1.0
    assert _eps_va(dataclasses.replace(design, alpha_dD=math.radians(18.9))) > 1.0
    assert _eps_va(dataclasses.replace(design, k_d=r.k_d_needed)) == pytest.approx(1.0,
                                                                                    abs=5e-4)
    text = low_ratio_text(design)
    assert text.startswith("profile contact ratio eps_va 0.98 is below 1")
    assert "a depth factor k_d of 2.06, above the usual 2 (now 2)" in text
    assert "a drive pressure angle alpha_dD of 18.9 deg (now 20)" in text
    assert "eps_vb" not in text


def test_both_low_ratios_are_said_and_neither_where_both_meet_their_limits():
    """The 17x29 at Σ 100° (ε_vβ 0.96, ε_vα 1.20): the face contact ratio's sentence
    alone (overlap_text's, word for word); the hypoid 10x43 (ε_vβ 1.44, ε_vα 1.03): its
    own values, no sentence."""
    design = load_basic(DESIGNS / "spiral_bevel_17x29_s100_m0.toml").design
    assert profile_remedy(design).eps_va > PROFILE_CONTACT_RATIO_MIN
    assert low_ratio_text(design) == overlap_text(design)
    design = load_basic(DESIGNS / "pc_hypoid_10x43.toml").design
    r = profile_remedy(design)
    assert (r.k_d_needed, r.alpha_d_needed) == (r.k_d, r.alpha_d)
    assert low_ratio_text(design) is None
    with pytest.raises(InputError, match="target"):
        profile_remedy(design, 0.0)


def test_the_loaded_contact_ratio_is_the_mean_of_the_pairs_in_contact():
    """loaded_ratio_text: the mean of the pairs over the cycle and the share of the rolls
    with one pair (hand-counted: 1, 1, 1, 2 → 1.25, 75 %), each ratio below its limit
    said so, NaN rolls left out; without a rating only the loaded ratio."""
    text = loaded_ratio_text(0.98, 1.27, [1, 1, 1, 2, np.nan])
    assert text == ("contact ratios eps_va 0.98 (below 1), eps_vb 1.27, total 2.25 (ISO "
                    "10300-1); loaded contact ratio 1.25 (the mean of the tooth pairs "
                    "carrying load, one pair alone over 75 % of the mesh cycle)")
    assert "eps_vb 1.14 (below 1.25)" in loaded_ratio_text(1.11, 1.14, [2, 3])
    assert loaded_ratio_text(math.nan, math.nan, [2, 2]).startswith("loaded contact ratio 2.00")
    # never one pair alone: said so, not "one pair alone over 0 %" (round 14's 10x31)
    assert loaded_ratio_text(math.nan, math.nan, [2, 3]).endswith(
        "two pairs or more at every roll of the mesh cycle)")


def test_an_lte_finding_names_the_contact_ratios_and_the_remedy():
    """``ltca run``'s ``lte`` finding gives the rating's ε_vα, ε_vβ and the LTCA's loaded
    contact ratio at its torque; under an ATTENTION verdict with an ``lte`` finding the
    next step is the basic-file remedy of the case's low ratios (ISO/TR sample 3, ε_vβ
    0.86), none for a case whose ratios meet their limits (sample 2)."""
    import xarray as xr

    from contact.commands.run import next_steps
    from contact.study.verdicts import verdict
    from geometry.case import load_case

    lt = xr.Dataset({"lte_peak_to_peak": ("torque", [100.0, 30.0]),
                     "pairs_in_contact": (("torque", "roll"), [[1, 1, 1, 2], [2, 2, 2, 2]])},
                    coords={"torque": [50.0, 500.0]})
    rating = xr.Dataset({"eps_va": ((), 1.2), "eps_vb": ((), 0.96)})
    tree = xr.DataTree.from_dict({"/ltca": lt, "/rating": rating})
    v = verdict(tree)
    lte = [f for f in v.findings if f.check == "lte"]
    assert v.severity == "attention" and len(lte) == 1
    assert lte[0].reason.endswith(
        "; contact ratios eps_va 1.20, eps_vb 0.96 (below 1.25), total 2.16 (ISO 10300-1); "
        "loaded contact ratio 1.25 (the mean of the tooth pairs carrying load, one pair "
        "alone over 75 % of the mesh cycle)")
    low = next_steps(tree, load_case(ROOT / "cases" / "iso10300_30_sample3.toml"), "c.toml",
                     None)
    assert len(low) == 1 and low[0].startswith("  next, the LTE may be the design's: face "
                                               "contact ratio eps_vb 0.86 is below 1.25")
    # a trial, not a remedy: no estimate from the basic data supports one; a case of
    # settings given by hand records no check of its remedies: said so
    assert "whether it lowers the LTE is not estimated from the basic data" in low[0]
    assert "(not checked by a synthesis: this case records no check" in low[0]
    assert low[0].endswith("a trial: ltca synthesize BASIC.toml --apply-remedy (the best "
                           "change that passes its check applied and developed; contact."
                           "optimize.development_remedy), then ltca run of the case it writes")
    assert next_steps(tree, load_case(ROOT / "cases" / "iso10300_30_sample2.toml"),
                      "c.toml", None) == []
    # beyond twice the limit the finding FAILs (verdicts.LTE_FAIL_FACTOR): the same remedy
    # is the next step, said once
    loud = xr.DataTree.from_dict({"/ltca": lt.assign(lte_peak_to_peak=("torque",
                                                                       [855.0, 30.0])),
                                  "/rating": rating})
    assert verdict(loud).severity == "fail"
    steps = next_steps(loud, load_case(ROOT / "cases" / "iso10300_30_sample3.toml"),
                       "c.toml", None)
    assert sum(x.startswith("  next, the LTE may be the design's: face contact ratio "
                            "eps_vb 0.86 is below 1.25") for x in steps) == 1


def test_the_next_step_of_an_lte_spread_names_the_overlap():
    """``ltca run``'s and ``ltca duty-cycle``'s next step under an LTE-spread FAIL: the
    sentence for a case whose ε_vβ is low (ISO/TR sample 3, 0.86), nothing for one whose
    is not (sample 2, 2.10)."""
    from contact.commands.next_steps import overlap_lines
    from geometry.case import load_case

    low = overlap_lines(load_case(ROOT / "cases" / "iso10300_30_sample3.toml"))
    assert len(low) == 1 and "eps_vb 0.86 is below 1.25" in low[0]
    assert "ltca synthesize" in low[0] and "not estimated" in low[0]
    assert overlap_lines(load_case(ROOT / "cases" / "iso10300_30_sample2.toml")) == []


def test_a_duty_cycle_failing_on_its_spread_prints_the_overlap_first(monkeypatch):
    """duty_cycle_lines with the case: the overlap line first where the verdict FAILs on
    an LTE spread; not where it FAILs on something else."""
    import numpy as np
    import xarray as xr

    from contact.commands import next_steps
    from contact.study.verdicts import Finding
    from geometry.case import load_case

    case = load_case(ROOT / "cases" / "iso10300_30_sample3.toml")
    ds = xr.Dataset({"torque": ("bin", np.array([40.0, 400.0]))})

    class V:
        def __init__(self, reason):
            self.findings = [Finding("fail", "implausible", reason)]

    monkeypatch.setattr("contact.study.verdicts.verdict",
                        lambda d: V("lte spread in bin 0 (the cause ltca run warns of)"))
    lines = next_steps.duty_cycle_lines(ds, "c.toml", None, ["implausible"], case)
    assert "eps_vb 0.86" in lines[0] and "ltca run c.toml --torque 400" in lines[2]
    monkeypatch.setattr("contact.study.verdicts.verdict",
                        lambda d: V("plastic contact in bin 1"))
    lines = next_steps.duty_cycle_lines(ds, "c.toml", None, ["implausible"], case)
    assert not any("eps_vb" in ln for ln in lines)


def test_the_duty_cycle_line_names_the_member_of_an_unlabelled_member_dimension():
    """A duty-cycle dataset whose ``member`` dimension has no labels (its index only)
    names the member as the toolkit numbers them (pinion 0, gear 1), not "0's"."""
    import numpy as np
    import xarray as xr

    from contact.commands import next_steps

    flank = np.zeros((2, 2, 3, 3))  # (bin, member, u, v)
    flank[1, 1, 2, 1] = 0.7  # the gear's worst point, done by the second bin
    flank[0, 1, 2, 1] = 0.3
    ds = xr.Dataset({"torque": ("bin", np.array([40.0, 400.0])),
                     "flank_damage": (("bin", "member", "u", "v"), flank),
                     "damage": ("member", np.array([0.1, 1.0]))})
    ds = ds.transpose("member", "bin", "u", "v")
    ds["flank_damage"] = ds["flank_damage"].transpose("bin", "member", "u", "v")
    lines = next_steps.duty_cycle_lines(ds, "c.toml", None, ["damage"])
    text = "\n".join(lines)
    assert "gear's flank damage" in text and "0's" not in text and "1's" not in text, text
    # the share printed is the second bin's 70 % of the point's damage
    assert "bin 1 (400 N m) does 70 %" in text, text


def test_synthesizes_note_gives_the_developed_lte_in_numbers():
    """``ltca synthesize``'s low-overlap note ends with the developed bearing's LTE p-p of
    both flanks at their light and design torques against the development's target, and
    says whether it was met (a stand-in result with the hypoid 8x41 b2 22's numbers,
    docs/own_gear_set.md "A face contact ratio below 1.25")."""
    import types

    import numpy as np

    from contact.commands.synthesize import low_overlap_lte
    from contact.optimize.development import DevelopmentTargets

    dev = types.SimpleNamespace(
        best=types.SimpleNamespace(metrics={"lte_peak_to_peak": np.array([28.1, 49.6])}),
        torque=(28.8, 192.0), coast={"lte_peak_to_peak": np.array([67.1, 61.7])},
        coast_design_torques=(28.8, 119.0), targets=DevelopmentTargets())
    text = low_overlap_lte(dev)
    assert text == ("the developed bearing's LTE p-p: drive 28/50 urad at 28.8/192 N m, "
                    "coast 67/62 urad at 28.8/119 N m (light/design), the development's "
                    "target 40 urad missed, above the verdict's 60 urad on the coast flank")
    # one flank within the target, the other not: said which (a face-hobbed 8x37 of
    # unseen round 10 read "drive 10/20, coast 42/50 ..., target 40 urad missed")
    dev.best.metrics["lte_peak_to_peak"] = np.array([10.0, 19.7])
    dev.coast = {"lte_peak_to_peak": np.array([42.0, 50.0])}
    assert low_overlap_lte(dev).endswith("coast 42/50 urad at 28.8/119 N m (light/design), "
                                         "the development's target 40 urad met on the "
                                         "drive flank, missed on the coast")
    dev.coast = None
    dev.best.metrics["lte_peak_to_peak"] = np.array([30.0, 38.0])
    assert low_overlap_lte(dev).endswith("drive 30/38 urad at 28.8/192 N m (light/design), "
                                         "the development's target 40 urad met")


def test_the_12x12_miters_note_names_the_teeth_where_no_width_nor_angle_reaches():
    """The spiral bevel 12x12 miter (d_e2 90, b2 19 mm = 0.3 R_e2, β_m 35°; issue 71,
    branch remeasure87): ε_vβ 0.564 (ISO 10300-1 A.2 with b_v,eff 0.85 b2; by hand with the
    whole b2, b2 sin β_m / (π m_mn) = 0.664). Neither the face width up to R_e2/2 nor the
    spiral angle up to 50° alone reaches 1.25; the note says what each reaches there and
    names the fewest teeth at the same d_e2, b2 and β_m that do: m_mn falls as 1/z, so
    ε_vβ grows in proportion to z (checked by hand to 1e-9: the same virtual face width
    and spiral angle), and 27x27 is the first (26x26 falls short, by hand)."""
    from contact.load_capacity.iso10300.face_contact import teeth_remedy
    from geometry.iso23509.blank import blank_geometry

    design = load_basic(ROOT / "tests" / "data" / "limits"
                        / "spiral_bevel_12x12_miter_b35.toml").design
    eps = _eps_vb(design)
    assert eps == pytest.approx(0.564, abs=1e-3)
    m_mn = float(blank_geometry(design).m_mn)
    assert 19.0 * math.sin(math.radians(35.0)) / (math.pi * m_mn) == pytest.approx(0.664,
                                                                                  abs=1e-3)
    r = overlap_remedy(design)
    assert math.isnan(r.b2_needed) and math.isnan(r.beta_m_needed)
    half = 0.5 * r.b2_limit / 0.3
    at_b = _eps_vb(dataclasses.replace(design, b2=half))
    at_beta = _eps_vb(dataclasses.replace(design, beta_m=math.radians(50.0)))
    assert at_b < FACE_CONTACT_RATIO_MIN and at_beta < FACE_CONTACT_RATIO_MIN
    assert teeth_remedy(design) == (27, 27)
    for z in (26, 27):
        assert _eps_vb(dataclasses.replace(design, z1=z, z2=z)) == pytest.approx(
            eps * z / 12, rel=1e-9)
    assert _eps_vb(dataclasses.replace(design, z1=26, z2=26)) < FACE_CONTACT_RATIO_MIN
    assert _eps_vb(dataclasses.replace(design, z1=27, z2=27)) >= FACE_CONTACT_RATIO_MIN
    text = overlap_text(design)
    assert "eps_vb 0.56 is below 1.25" in text
    assert (f"no face width up to R_e2/2 (eps_vb {at_b:.2f} at {half:.1f} mm) nor spiral "
            f"angle up to 50 deg ({at_beta:.2f}) alone reaches 1.25") in text
    assert "z1 27 and z2 27 (now 12 and 12; m_mn 2.32 mm, now 5.23) reach 1.25" in text
    assert "the ratio then" not in text


def test_the_module_remedy_is_checked_before_it_is_offered():
    """The 12x12 miter's module remedy (27x27, the least count reaching 1.25 by ISO
    10300-1 A.2) with a stand-in of the synthesis check (issue 71, round 96: the 15x15
    hypoid's 57x57 was offered "not checked by a synthesis" and has none): where the least
    count fails, the next count 5 pinion teeth up that passes is offered with what failed
    before it, and it reaches the target by hand; where every count tried fails, no count
    is offered as reaching it: what failed is said, and that the cutter radius limits it."""
    design = load_basic(ROOT / "tests" / "data" / "limits"
                        / "spiral_bevel_12x12_miter_b35.toml").design
    asked = []

    def check(z1, z2):
        asked.append((z1, z2))
        return None if z1 >= 32 else "machine settings: no envelope solution (stand-in)"

    text = overlap_text(design, teeth_check=check)
    assert asked == [(27, 27), (32, 32)]
    assert _eps_vb(dataclasses.replace(design, z1=32, z2=32)) >= FACE_CONTACT_RATIO_MIN
    assert "z1 32 and z2 32 (now 12 and 12; m_mn " in text
    assert ("reach 1.25, checked by a synthesis of the file with these counts "
            "(`--no-development`): its unloaded contact is computed; not 27x27: machine "
            "settings: no envelope solution (stand-in)") in text
    assert "not checked" not in text and "z1 27 and z2 27" not in text
    asked.clear()
    text = low_ratio_text(design, teeth_check=lambda z1, z2: asked.append(z1) or "lost")
    assert asked == [27, 32, 37, 42]
    assert ("z1 27 and z2 27 would reach 1.25, but no synthesis of the file with 4 counts "
            "from 27x27 up has an unloaded contact `ltca run` computes (27x27: lost; "
            "32x32: lost; 37x37: lost; 42x42: lost); at the cutter radius rc0") in text
    assert "reach 1.25, checked" not in text and "not checked" not in text
    # without a check (ltca run's next steps, which record none) the offer says so
    assert "reach 1.25 (not checked by a synthesis)" in overlap_text(design)


def test_the_teeth_remedy_keeps_the_ratio_as_near_as_whole_teeth_allow():
    """A non-miter below its target (the 17x29 at Σ 100°, ε_vβ 0.96 at b2 24 mm): the
    tooth numbers returned keep z2 = round(z1 u) and reach 1.25 by hand, the pinion one
    tooth fewer does not (at its own rounded z2); a design at its target gets None; the
    17x29's own note, whose face width and spiral angle reach the target, names no teeth."""
    from contact.load_capacity.iso10300.face_contact import teeth_remedy

    design = load_basic(DESIGNS / "spiral_bevel_17x29_s100_m0.toml").design
    z1, z2 = teeth_remedy(design)
    assert z2 == round(z1 * 29 / 17)
    assert _eps_vb(dataclasses.replace(design, z1=z1, z2=z2)) >= FACE_CONTACT_RATIO_MIN
    assert _eps_vb(dataclasses.replace(design, z1=z1 - 1, z2=round((z1 - 1) * 29 / 17))
                   ) < FACE_CONTACT_RATIO_MIN
    assert teeth_remedy(dataclasses.replace(design, z1=z1, z2=z2)) is None
    with pytest.raises(InputError, match=r"^target: .*\(0, 5\]"):
        teeth_remedy(design, math.nan)
    assert "the module is the lever left" not in overlap_text(design)


def test_synthesizes_note_names_the_flank_above_the_verdicts_limit():
    """Where one flank's written LTE p-p exceeds the verdict's 60 µrad and the other's does
    not, the note names the one (issue 71, round 26c, branch unseen87: the spiral bevel
    17x23's note read "drive 31/96 ..., coast 26/58 urad ... (light/design), ..., above
    the verdict's 60 urad", its coast flank within); where both do, or only one flank was
    checked, it says so unqualified; where none does, nothing. The limit compared is the
    verdict's own (contact.study.verdicts.LTE_LIMIT), the LTE values the 17x23's."""
    import types

    import numpy as np

    from contact.commands.synthesize import low_overlap_lte
    from contact.optimize.development import DevelopmentTargets
    from contact.optimize.development_remedy import above_limit_text
    from contact.study.verdicts import LTE_LIMIT

    dev = types.SimpleNamespace(
        best=types.SimpleNamespace(metrics={"lte_peak_to_peak": np.array([31.0, 96.0])}),
        torque=(230.5, 1537.0), coast={"lte_peak_to_peak": np.array([26.0, 58.0])},
        coast_design_torques=(110.8, 739.3), targets=DevelopmentTargets())
    assert LTE_LIMIT == 60.0
    assert low_overlap_lte(dev) == (
        "the developed bearing's LTE p-p: drive 31/96 urad at 230.5/1537 N m, coast 26/58 "
        "urad at 110.8/739.3 N m (light/design), the development's target 40 urad missed, "
        "above the verdict's 60 urad on the drive flank")
    dev.coast = {"lte_peak_to_peak": np.array([61.0, 58.0])}  # both above
    assert above_limit_text(dev, LTE_LIMIT) == ", above the verdict's 60 urad"
    dev.coast = None  # the drive flank alone checked
    assert above_limit_text(dev, LTE_LIMIT) == ", above the verdict's 60 urad"
    dev.best.metrics["lte_peak_to_peak"] = np.array([31.0, 60.0])  # at the limit: within
    assert above_limit_text(dev, LTE_LIMIT) == ""
