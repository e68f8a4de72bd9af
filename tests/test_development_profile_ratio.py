"""The check's step for a profile contact ratio below 1 (:func:`contact.optimize.
development_profile_ratio.checked_profile_ratio`, issue 71): the path at its profile
bound with the long bearing and no profile crowning, then a lighter tip relief.

Stand-in analyses whose law is the face-hobbed hypoid 13x29 by ISO 23509 Method 2 of
benchmarks/data/unseen_designs (ε_vα 0.91, ε_vβ 1.27) at 45.9 / 306.3 N m, as measured
with ``benchmarks/development_levers.py --check --tolerance --from-case`` on the case
``ltca synthesize`` wrote before the step (2026-11-27; the numbers in the step's
docstring): the tests are the step's choices, not numbers of a gear.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import stand_in

from contact.optimize import development_check as dcheck
from contact.optimize import development_profile_ratio as dpr

ROOT = Path(__file__).resolve().parents[1]

#: the 13x29's developed drive prescriptions as written before the step
WRITTEN = {"path_angle": -58.75, "ellipse_length": 0.4, "tip_relief": 24.65,
           "root_relief": 24.07, "relief_start": 0.2512, "profile_crowning": 2.58,
           "tip_relief_start": 0.8932, "blade_angle_change": 0.0, "te_level": 10.0}


def _thirteen_by_29(case, torques, misalignment=None, options=None, teeth=None,
                    pinion_key=(), flank="drive"):
    """The 13x29 at 45.9 / 306.3 N m: the written bearing 0.33 long on the gear's tip row,
    LTE 518 / 448 µrad (its spread 0: the mean below the unloaded TE's p-p); the path at
    −80° with the long bearing and no crowning 0.53 long, 61 / 62 µrad; its tip relief
    halved 59 / 60 µrad; every other bearing (the path or the ellipse alone) one pair alone
    over the light torque's cycle: 237 / 113 µrad, spread 0.8. Edges at the mounting
    excursions only below a 6 µm tip relief (5 µm: 2.1-3.3 %)."""
    long_ = case["path_angle"] <= -80.0 and case["ellipse_length"] >= 0.75
    if misalignment is not None and case["tip_relief"] < 6.0:
        edge = [0.0, 0.03]
    else:
        edge = [0.0, 0.003 if long_ else 0.007]
    if not long_:
        if case["path_angle"] == WRITTEN["path_angle"]:
            m = _metrics(pattern_toe_u=[0.35, 0.225], pattern_heel_u=[0.675, 0.8],
                         pattern_root_v=[0.24, 0.19], pattern_tip_v=[1.0, 1.0],
                         pattern_centre_v=[0.6, 0.62], lte_peak_to_peak=[517.7, 448.4],
                         lte_spread=[0.0, 0.43], edge_load_share=edge)
        else:
            m = _metrics(pattern_toe_u=[0.33, 0.2], pattern_heel_u=[0.7, 0.8],
                         pattern_root_v=[0.24, 0.2], pattern_tip_v=[0.91, 0.95],
                         pattern_centre_v=[0.56, 0.56], lte_peak_to_peak=[236.9, 112.9],
                         lte_spread=[0.8, 0.3], edge_load_share=edge)
    else:
        lte = ([60.6, 62.0] if case["tip_relief"] > 20.0 else [59.1, 59.6])
        m = _metrics(pattern_toe_u=[0.25, 0.2], pattern_heel_u=[0.78, 0.8],
                     pattern_root_v=[0.24, 0.2], pattern_tip_v=[0.95, 0.95],
                     pattern_centre_v=[0.58, 0.58], lte_peak_to_peak=lte,
                     lte_spread=[0.4, 0.2], edge_load_share=edge)
    return m, (0.0, 1.0, 0.0, 1.0, 2400.0)


def test_a_low_profile_ratio_gets_the_long_bearing_on_the_profile_path(monkeypatch):
    """ε_vα 0.91, LTE 518 µrad: one design at path −80° (the bound), the ellipse 0.75, the
    root relief from 0.5 with its slope kept and no crowning (kept, tolerant), then its tip
    relief halved, entering at 0.9 (the bound; kept: within 60 µrad at both torques)."""
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        if misalignment is None:
            seen.append(dict(case))
        return _thirteen_by_29(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, fake, [45.9, 306.3])
    start = chosen(dict(WRITTEN))
    assert start.full[1]["spread"] == 0.0 and start.full[1]["lte"] > 0.0
    seen.clear()
    lines = []
    got = dpr.checked_profile_ratio(start, targets, setup, None, lines.append,
                                    lambda v: dict(v), eps_va=0.91)
    root = 24.07 * (1.0 - 0.5) / (1.0 - 0.2512)
    first = WRITTEN | {"path_angle": -80.0, "ellipse_length": 0.75, "relief_start": 0.5,
                       "root_relief": pytest.approx(root, rel=1e-9),
                       "profile_crowning": 0.0}
    assert len(seen) == 2
    assert seen[0] == first
    assert seen[1] == first | {"tip_relief": pytest.approx(0.5 * 24.65),
                               "tip_relief_start": 0.9}
    assert got.stage == dpr.STAGE and got.values == seen[1]
    assert max(got.metrics["lte_peak_to_peak"]) <= 60.0
    assert "profile contact ratio 0.91 below 1.05" in lines[0]
    assert not any("not kept" in s for s in lines)


def test_a_profile_ratio_just_above_one_gets_the_long_bearing_too(monkeypatch):
    """ε_vα 1.01, the face-hobbed spiral bevel 10x31 at β_m 41.2° of
    benchmarks/data/unseen_designs (the remedy ``ltca synthesize``'s ε_vβ note printed),
    written before with the LTE of a path of −45° (268 / 309 µrad): its relief takes the
    flank away where the pairs hand over as below 1, and the step's bearing is tried (it
    was not: the step ran below 1 only)."""
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        if misalignment is None:
            seen.append(dict(case))
        return _thirteen_by_29(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, fake, [45.9, 306.3])
    start = chosen(dict(WRITTEN))
    seen.clear()
    lines = []
    got = dpr.checked_profile_ratio(start, targets, setup, None, lines.append,
                                    lambda v: dict(v), eps_va=1.01)
    assert seen and seen[0]["path_angle"] == -80.0 and seen[0]["ellipse_length"] == 0.75
    assert got.stage == dpr.STAGE
    assert "profile contact ratio 1.01 below 1.05" in lines[0]


@pytest.mark.parametrize("eps_va", [1.05, 1.12, math.nan])
def test_nothing_is_tried_at_a_profile_ratio_of_one_or_more(monkeypatch, eps_va):
    """ε_vα at 1.05 or above (or unknown): the design returned as it is, nothing analysed,
    however high its LTE — the designs that meet their targets (ε_vα 1.12 of
    tests/data/designs' fh_hypoid_11x46_m3; pc_hypoid_10x43's 1.03 is within the LTE
    limit, which the step reads first) are written as before."""
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        seen.append(dict(case))
        return _thirteen_by_29(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, fake, [45.9, 306.3])
    start = chosen(dict(WRITTEN))
    seen.clear()
    assert dpr.checked_profile_ratio(start, targets, setup, None, print,
                                     lambda v: dict(v), eps_va=eps_va) is start
    assert seen == []


def test_nothing_is_tried_within_the_limit_or_on_that_bearing_already(monkeypatch):
    """A design within the verdict's 60 µrad at both torques, or at the profile-ratio
    bearing already with its LTE within the limit after the tip step: no analysis; the
    ε_vα of the case is not even read (a stand-in case has none)."""
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        seen.append(dict(case))
        return _thirteen_by_29(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, fake, [45.9, 306.3])
    quiet = chosen(dpr.lighter_tip_relief(dpr.profile_ratio_bearing(WRITTEN, targets),
                                          targets))
    seen.clear()
    assert dpr.checked_profile_ratio(quiet, targets, setup, None, print,
                                     lambda v: dict(v)) is quiet
    assert seen == []
    assert dpr.profile_ratio_bearing(quiet.values, targets) is None
    assert quiet.values["tip_relief_start"] == 0.9


def test_the_lighter_tip_relief_keeps_its_bounds():
    """Half the tip relief within its variable's bounds, its start at the upper bound
    unless it is later already; none where the design has no tip relief or its half is
    below the lower bound."""
    from contact.optimize.development import DevelopmentTargets

    targets = DevelopmentTargets()
    lo, _ = targets.variables["tip_relief"]
    got = dpr.lighter_tip_relief(WRITTEN, targets)
    assert got == WRITTEN | {"tip_relief": 0.5 * 24.65, "tip_relief_start": 0.9}
    assert dpr.lighter_tip_relief(WRITTEN | {"tip_relief": 0.0}, targets) is None
    if lo > 0.0:
        assert dpr.lighter_tip_relief(WRITTEN | {"tip_relief": lo}, targets) is None


def test_a_bearing_that_gives_up_a_met_target_is_not_kept(monkeypatch):
    """The profile-ratio bearing with edges beyond the limit at the design torque (a target
    the design met): not kept, and no tip step on it (one analysis)."""
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        seen.append(dict(case))
        m, limits = _thirteen_by_29(case, torques, misalignment, **kw)
        if case["path_angle"] <= -80.0:
            m = m | {"edge_load_share": m["edge_load_share"] * 0 + [0.0, 0.03]}
        return m, limits

    targets, setup, chosen = stand_in(monkeypatch, fake, [45.9, 306.3])
    start = chosen(dict(WRITTEN))
    seen.clear()
    lines = []
    assert dpr.checked_profile_ratio(start, targets, setup, None, lines.append,
                                     lambda v: dict(v), eps_va=0.91) is start
    assert len(seen) == 1
    assert any("not kept: the profile-ratio bearing misses edge" in s for s in lines)


def test_the_step_runs_in_the_check_after_the_long_bearing():
    """check_steps calls the step (by name) between the long bearing and the length
    search."""
    import inspect

    src = inspect.getsource(dcheck.check_steps)
    assert (src.index("checked_long(") < src.index("checked_profile_ratio(")
            < src.index("checked_length("))


def test_the_profile_ratio_of_a_case_is_its_basic_designs():
    """:func:`profile_ratio` of a bundled case (its ``[design]`` table) equals the profile
    contact ratio ``ltca synthesize``'s note reads from the basic file it was written from
    (contact.load_capacity.iso10300.face_contact.profile_remedy); NaN for no case."""
    from contact.load_capacity.iso10300.face_contact import profile_remedy
    from geometry.case import load_case
    from geometry.synthesis.basic_design import load_basic

    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    basic = load_basic(ROOT / "cases" / "basic" / "kolivand2009_fm_11x41.toml")
    got = dpr.profile_ratio(case)
    assert got == pytest.approx(profile_remedy(basic.design).eps_va, rel=1e-9)
    assert 1.0 < got < 1.2  # 1.06 (docs/synthesis.md, "The LTE floor ...")
    assert math.isnan(dpr.profile_ratio(None))
