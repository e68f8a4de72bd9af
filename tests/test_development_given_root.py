"""The drive bearing at a given design torque the gear root binds (issue 71, round 21's
truck hypoid 8×47 at 0.95 × its ISO capacity; contact/optimize/development_given_root.py).

* :func:`root_variants`: the blade-angle changes that put the light-load centre v at the
  target and ``LOWER_CENTRE`` of its tolerance below, by hand from the slope, each with
  the tip relief × ``TIP_FACTORS`` (clipped to the bound); none where the pattern is not
  above the target; a non-finite centre refused by name.
* :func:`checked_given_root`'s rule on a bearing whose centre v, plastic share and gear
  root safety follow a law fitted to the 8×47's measurements (no LTCA, no FE): the
  written case's drive flank at ``ltca run``'s sampling, blade-angle change 0 / −0.2 /
  −0.35°: centre v 0.636 / 0.535 / 0.461 (0.5 per degree), the gear's S_F,FE at 1765 N·m
  1.246 / 1.331 / 1.369 (a fit S_F = 1.246 + 0.70 (0.636 − v) is within 0.01 of all
  three); the tip relief 21.4 → 32.2 µm at −0.2° took S_F,FE to 1.287 (−0.044).
"""

from __future__ import annotations

import dataclasses
import math
import types

import numpy as np
import pytest
from development_stand_ins import law_evaluation

from contact.optimize import development_given_root as dg
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import HEIGHT_NAME, DevelopmentTargets
from geometry.core.errors import InputError

TARGETS = DevelopmentTargets(pattern_centre_v=0.541)  # the 8×47's target centre v
SETUP = {"torques": [264.7, 1765.0], "centre_v": 0.541}
BOUNDS = {HEIGHT_NAME: (-3.0, 3.0), "tip_relief": (0.0, 60.0)}
V0, SLOPE = 0.636, 0.5  # the written design's centre v [1]; d(centre v)/d(blade) [1/deg]


def test_the_variants_aim_at_the_target_and_below_it_with_each_tip_relief():
    """Centre v 0.636, target 0.541 ± 0.08, slope 0.5 per degree: the blade angle
    (0.541 − 0.636)/0.5 = −0.19° and (0.541 − 0.75·0.08 − 0.636)/0.5 = −0.31°, each
    with the tip relief 21.4 µm as written, × 1.5 = 32.1 µm and × 2.1 = 44.94 µm."""
    values = {HEIGHT_NAME: 0.0, "tip_relief": 21.4}
    out = dg.root_variants(values, V0, 0.541, 0.08, BOUNDS, SLOPE)
    blades = [v[HEIGHT_NAME] for v, _ in out]
    tips = [v["tip_relief"] for v, _ in out]
    assert blades == pytest.approx([-0.19] * 3 + [-0.31] * 3, abs=1e-12)
    assert tips == pytest.approx([21.4, 32.1, 44.94] * 2, abs=1e-12)
    assert "aimed at v 0.54" in out[0][1] and "tip relief 32.1 um" in out[1][1]
    # the tip relief clipped to its bound: 50 × 1.5 -> 60
    out = dg.root_variants({HEIGHT_NAME: 0.0, "tip_relief": 50.0}, V0, 0.541, 0.08, BOUNDS,
                           SLOPE)
    assert [v["tip_relief"] for v, _ in out] == [50.0, 60.0] * 2  # x 2.1 the same
    # the blade angle's bound stops the change: -0.1 at most, both heights the same design
    out = dg.root_variants(values, V0, 0.541, 0.08, {**BOUNDS, HEIGHT_NAME: (-0.1, 3.0)},
                           SLOPE)
    assert [v[HEIGHT_NAME] for v, _ in out] == [-0.1] * 3
    # a pattern at or below both heights aimed at (0.541, 0.481): nothing; within the
    # tolerance but above 0.481, the lower height alone
    assert dg.root_variants(values, 0.45, 0.541, 0.08, BOUNDS, SLOPE) == []
    out = dg.root_variants(values, 0.5, 0.541, 0.08, BOUNDS, SLOPE)
    assert [v[HEIGHT_NAME] for v, _ in out] == pytest.approx([-0.038] * 3, abs=1e-12)
    # a slope below the floor HEIGHT_SLOPE_MIN (0.14 per degree) is floored
    low = dg.root_variants(values, V0, 0.541, 0.08, BOUNDS, 0.01)
    assert low[0][0][HEIGHT_NAME] == pytest.approx(-0.095 / 0.14, abs=1e-12)
    with pytest.raises(InputError, match="centre_v nan"):
        dg.root_variants(values, math.nan, 0.541, 0.08, BOUNDS)
    with pytest.raises(InputError, match="tolerance must be > 0"):
        dg.root_variants(values, V0, 0.541, 0.0, BOUNDS)


def _law(values, state):
    """(centre v, plastic share at the design torque, the gear's S_F,FE at 1765 N·m) of the
    8×47's fit: v = 0.636 + 0.5 Δα; S_F = 1.246 + 0.70 (0.636 − v) − 0.0041 per µm of tip
    relief above 21.4 (−0.044 for +10.7 µm); plastic 2.5 % where the centre v is below
    ``state["plastic_above_v"]`` and the tip relief below ``state["tip_clears"]`` µm (the
    pinion tip edge a lower pattern reaches), else none."""
    tip = values["tip_relief"]
    v = V0 + SLOPE * values[HEIGHT_NAME]
    sf = 1.246 + 0.70 * (V0 - v) - 0.044 / 10.7 * (tip - 21.4)
    plastic = 0.025 if (v < state["plastic_above_v"] and tip < state["tip_clears"]) else 0.0
    return v, plastic, sf


def _metrics(v: float, plastic: float) -> dict[str, np.ndarray]:
    return {"pattern_toe_u": np.array([0.23, 0.1]), "pattern_heel_u": np.array([0.8, 0.9]),
            "pattern_root_v": np.array([v - 0.2, v - 0.3]),
            "pattern_tip_v": np.array([v + 0.2, v + 0.3]),
            "pattern_centre_u": np.array([0.5, 0.5]),
            "pattern_centre_v": np.array([v, v]),
            "edge_load_share": np.array([0.0, 0.01]),
            "lte_peak_to_peak": np.array([18.0, 12.0]),
            "pressure_max_flank": np.array([889.0, 1616.0]),
            "plastic_share": np.array([0.0, plastic]), "lte_spread": np.zeros(2)}


def _evaluation(values, state) -> DevelopmentEvaluation:
    v, plastic, _ = _law(values, state)
    return law_evaluation(values, _metrics(v, plastic), TARGETS, SETUP["centre_v"])


@pytest.fixture
def stubbed(monkeypatch):
    """The check's analysis and the root stress replaced by :func:`_law`, every design
    tolerant; the designs analysed and those whose root stress was computed recorded."""
    state = {"plastic_above_v": 0.0, "tip_clears": 30.0, "analysed": [], "rooted": []}

    def said(best, values, stage, label, targets, setup, teeth, say, placed, **kw):
        state["analysed"].append(dict(values))
        return dataclasses.replace(_evaluation(values, state), stage=stage)

    def root_of(values):
        state["rooted"].append(dict(values))
        return _law(values, state)[2], "gear"

    monkeypatch.setattr(dg, "said_variant", said)
    monkeypatch.setattr(dg, "kept_why", lambda *a, **k: "")
    state["root_of"] = root_of
    state["monkeypatch"] = monkeypatch
    return state


WRITTEN = {HEIGHT_NAME: 0.0, "tip_relief": 21.4, "ellipse_length": 0.5}


def test_the_first_lower_pattern_that_holds_the_root_is_kept(stubbed):
    """No plastic edge anywhere: the pattern centred (−0.19°: v 0.541, the centre v target
    met) gives S_F,FE 1.246 + 0.70·0.095 = 1.3125 >= 1.3 — kept, and the step ends there
    (one design analysed, one root stress computed)."""
    best = _evaluation(WRITTEN, stubbed)
    assert best.full[1]["centre_v"] > 0.0  # the written design misses its centre v
    lines: list[str] = []
    kept, sf, trials = dg.checked_given_root(best, 1.246, 1.3, TARGETS, dict(SETUP), None,
                                             lines.append, lambda v: None,
                                             stubbed["root_of"], slope=SLOPE)
    assert len(stubbed["analysed"]) == 1 and len(stubbed["rooted"]) == 1
    assert kept.values[HEIGHT_NAME] == pytest.approx(-0.19)
    assert sf == pytest.approx(1.246 + 0.70 * 0.095, rel=1e-12) and sf >= 1.3
    assert kept.full[1]["centre_v"] == 0.0
    assert trials[0].member == "gear" and not trials[0].missed
    text = dg.tried_text(trials, sf, 1.3, True)
    assert "S_F,FE 1.31" in text and "highest root safety that loses no target kept" \
        in text


def test_a_lower_pattern_that_loses_a_met_target_is_not_kept_and_said(stubbed):
    """The 8×47 as measured: a pattern below v 0.6 puts the pinion tip edge in plastic
    contact (2.5 %; −0.124° at the default sampling: 1.8 %), a longer tip relief clears
    it at the cost of the root safety. Centred (−0.19°): S_F,FE 1.3125 but plastic — not
    kept, its root stress said; with the tip relief 32.1 µm no plastic and centre v met,
    S_F,FE 1.3125 − 0.0041·10.7 = 1.2685 (+0.0225 over the written 1.246) — kept as the
    highest root safety that loses nothing, though below 1.3; with 44.94 µm 1.2157 — lower,
    not kept; the lower height (−0.31°) plastic again (root stress not computed), with the
    tip relief 32.1 µm S_F,FE 1.246 + 0.70·0.155 − 0.044 = 1.3105 >= 1.3, every target
    met — kept, the step ends."""
    stubbed["plastic_above_v"] = 0.6
    best = _evaluation(WRITTEN, stubbed)
    lines: list[str] = []
    kept, sf, trials = dg.checked_given_root(best, 1.246, 1.3, TARGETS, dict(SETUP), None,
                                             lines.append, lambda v: None,
                                             stubbed["root_of"], slope=SLOPE)
    assert [t.missed for t in trials] == [("plastic",), (), (), ("plastic",), ()]
    assert math.isfinite(trials[0].safety) and math.isnan(trials[3].safety)
    assert len(stubbed["rooted"]) == 4  # the first, and the three that lose nothing
    assert trials[1].safety == pytest.approx(1.246 + 0.70 * 0.095 - 0.044)
    assert trials[2].safety == pytest.approx(1.246 + 0.70 * 0.095 - 0.044 / 10.7 * 23.54)
    assert kept.values == stubbed["analysed"][4] and kept.full[2]
    assert sf == pytest.approx(1.246 + 0.70 * 0.155 - 0.044, rel=1e-9) and sf >= 1.3
    assert any("not kept" in line and "plastic" in line for line in lines)


def test_none_kept_where_every_gain_loses_a_target(stubbed):
    """Plastic below v 0.6 whatever the tip relief: every lower pattern loses the plastic
    target; the written design stays, and the sentence gives the first variant's root
    safety (1.3125) and what each missed, the others' root stress not computed."""
    stubbed["plastic_above_v"], stubbed["tip_clears"] = 0.6, math.inf
    best = _evaluation(WRITTEN, stubbed)
    kept, sf, trials = dg.checked_given_root(best, 1.246, 1.3, TARGETS, dict(SETUP), None,
                                             lambda line: None, lambda v: None,
                                             stubbed["root_of"], slope=SLOPE)
    assert kept is best and sf == 1.246 and len(trials) == 6
    assert all(t.missed == ("plastic",) for t in trials)
    assert len(stubbed["rooted"]) == 1
    text = dg.tried_text(trials, sf, 1.3, False)
    assert "centre v 0.54, S_F,FE 1.31, misses plastic" in text and "none kept" in text
    assert text.count("S_F,FE not computed") == 5


def test_nothing_tried_where_the_pattern_is_not_above_its_target(stubbed):
    best = _evaluation({**WRITTEN, HEIGHT_NAME: -0.4}, stubbed)  # v 0.436 < 0.481
    kept, sf, trials = dg.checked_given_root(best, 1.2, 1.3, TARGETS, dict(SETUP), None,
                                             lambda line: None, lambda v: None,
                                             stubbed["root_of"], slope=SLOPE)
    assert kept is best and sf == 1.2 and trials == [] and stubbed["analysed"] == []
    assert dg.tried_text([], 1.2, 1.3, False) == ""


def test_a_drive_target_gained_at_the_same_root_safety_is_kept(stubbed):
    """The 8×47 at −0.2° with the tip relief 45 µm: centre v 0.585 (met), no plastic,
    S_F,FE 1.247 against the written 1.246 — within ROOT_GAIN and one target more met:
    better (:func:`_better`); 0.01 lower is not, nor a NaN root."""
    best = _evaluation(WRITTEN, stubbed)
    gained = _evaluation({**WRITTEN, HEIGHT_NAME: -0.102}, stubbed)  # v 0.585
    assert gained.full[1]["centre_v"] == 0.0 and best.full[1]["centre_v"] > 0.0
    assert dg._better(best, 1.246, gained, 1.247)
    assert not dg._better(best, 1.246, gained, 1.236)
    assert not dg._better(best, 1.246, gained, math.nan)
    assert not dg._better(gained, 1.246, best, 1.247)  # a target fewer: no
    assert dg._better(gained, 1.246, best, 1.252)  # ROOT_GAIN higher: yes (lost checked apart)


def test_the_first_variants_measured_slope_sets_the_others(stubbed):
    """No slope measured for the bearing: the first variant at the default 0.28 per degree
    (−0.095/0.28 = −0.339°, v 0.466 — the 8×47's synthesize went there, 0.46); it
    measures the law's 0.5 per degree, and the next variants aim with it: −0.19° (v 0.541)
    with the tip relief 32.1 µm."""
    stubbed["plastic_above_v"] = 0.6
    best = _evaluation(WRITTEN, stubbed)
    dg.checked_given_root(best, 1.246, 1.3, TARGETS, dict(SETUP), None, lambda line: None,
                          lambda v: None, stubbed["root_of"], slope=None)
    first, second = stubbed["analysed"][:2]
    assert first[HEIGHT_NAME] == pytest.approx(-0.095 / 0.28, abs=1e-12)
    assert second[HEIGHT_NAME] == pytest.approx(-0.19, abs=1e-9)
    assert second["tip_relief"] == pytest.approx(32.1, abs=1e-12)


def test_a_later_tip_relief_start_is_tried_at_each_height():
    """With ``tip_relief_start`` developed (0.608 as written): after the three tip reliefs,
    × 1.5 from 0.708 at each height; from 0.85 the start is clipped to its bound 0.9, at
    the bound nothing more."""
    values = {HEIGHT_NAME: 0.0, "tip_relief": 21.4, "tip_relief_start": 0.608}
    bounds = {**BOUNDS, "tip_relief_start": (0.5, 0.9)}
    out = dg.root_variants(values, V0, 0.541, 0.08, bounds, SLOPE)
    assert len(out) == 8
    later = [v for v, _ in out if v["tip_relief_start"] != 0.608]
    assert [v[HEIGHT_NAME] for v in later] == pytest.approx([-0.19, -0.31], abs=1e-12)
    assert all(v["tip_relief"] == pytest.approx(32.1) and v["tip_relief_start"]
               == pytest.approx(0.708, abs=1e-12) for v in later)
    assert "from 0.708" in out[3][1]
    out = dg.root_variants({**values, "tip_relief_start": 0.85}, V0, 0.541, 0.08, bounds,
                           SLOPE)
    assert out[3][0]["tip_relief_start"] == 0.9
    assert len(dg.root_variants({**values, "tip_relief_start": 0.9}, V0, 0.541, 0.08,
                                bounds, SLOPE)) == 6


def test_the_development_writes_the_kept_bearing_and_says_it(monkeypatch):
    """``develop``'s wiring (:func:`contact.optimize.development._given_root_bearing`), the
    step and the synthesis replaced: no failing root check (``setup`` without
    ``given_root``), nothing done; a variant kept that holds the given torque: written
    (the re-synthesis, its FE models built, the root checked again), the note gone and
    the design torque's source saying S_F,FE 1.246 -> 1.31; one kept short of S_Fmin: the
    new check's note with what was tried; none kept: the note extended."""
    from contact.optimize import development as dev

    best = _evaluation(WRITTEN, {"plastic_above_v": 0.0, "tip_clears": 30.0})
    kept = dataclasses.replace(best, values={**WRITTEN, HEIGHT_NAME: -0.19})
    written = (best, "basic", "case", "report")
    calls: list[str] = []
    monkeypatch.setattr(dev, "with_flank_options", lambda b, f, v: ("basic", dict(v)))

    def write(basic, **kw):
        calls.append("write")
        return "case2", "report2"

    def built(case):
        calls.append(f"built {case}")

    setup = {"torques": [264.7, 1765.0], "source": "[synthesis] design_torque"}
    out = dev._given_root_bearing(written, TARGETS, setup, None, lambda s: None, None,
                                  write, built, 1.246, "", "concave", True, None)
    assert out == (*written, 1.246, "") and calls == []

    trial = dg.RootTrial("centred lower", 1.31, "gear", (), 0.541)
    for result, again, text in (((kept, 1.31, [trial]), (1.31, ""), ""),
                                ((kept, 1.28, [trial]), (1.28, "still FAIL"), "still FAIL; "),
                                ((best, 1.246, [trial]), None, "FAIL at 1765; ")):
        calls.clear()
        monkeypatch.setattr(dg, "checked_given_root", lambda *a, r=result, **k: r)
        monkeypatch.setattr(dev, "given_torque_root", lambda c, s, say, a=again: a)
        s = dict(setup, given_root=(1.246, 1.3, "gear"))
        out = dev._given_root_bearing(written, TARGETS, s, None, lambda line: None, None,
                                      write, built, 1.246, "FAIL at 1765", "concave", True,
                                      None)
        if result[0] is best:  # none kept: the written case, the note extended
            assert out[:5] == (*written, 1.246) and calls == []
            assert out[5].startswith("FAIL at 1765; a pattern centred lower was tried")
            continue
        assert out[0] is kept and out[2:4] == ("case2", "report2")
        assert calls == ["write", "built case2"] and "given_root" not in s
        assert out[4] == again[0] and out[5].startswith(text)
        if not again[1]:
            assert out[5] == "" and "S_F,FE 1.25 -> 1.31 >= S_Fmin 1.3" in s["source"]


# --------------------------------------------------------------------------- the fillet
def test_the_largest_edge_radius_is_tried_where_the_basic_file_gives_none():
    """The rule of :func:`larger_edge_radius`: the 8×47's largest 2.36 mm against the
    written default 1.574 mm (0.25 m_mn) is tried; not where the basic file gives a
    radius (the user's tool), nor where the largest is within EDGE_GAIN (5 %) of the
    written one (1.65 mm against 1.574: 4.8 % larger); bad input named."""
    assert dg.larger_edge_radius(1.574, 2.36, False) == 2.36
    assert dg.larger_edge_radius(1.574, 2.36, True) is None
    assert dg.larger_edge_radius(1.574, 1.65, False) is None
    assert dg.larger_edge_radius(1.574, 1.6527, False) == 1.6527  # 1.05 x 1.574 = 1.6527
    with pytest.raises(InputError, match="written edge radius"):
        dg.larger_edge_radius(0.0, 2.36, False)
    with pytest.raises(InputError, match="largest edge radius"):
        dg.larger_edge_radius(1.574, math.nan, False)


def test_the_edge_radius_to_try_of_a_basic_design():
    """:func:`edge_radius_to_try` on the 8×47's basic file (no edge radius given): 2.36
    mm, the pinion's slot (tests/test_synthesis_edge_radius.py); with ``[synthesis]
    edge_radius`` given, or a face-hobbed design (z0 13), none."""
    from pathlib import Path

    from geometry.synthesis.basic_design import load_basic

    root = Path(__file__).resolve().parents[1]
    basic = load_basic(root / "benchmarks" / "data" / "unseen_designs"
                       / "truck_hypoid_8x47_a45.toml")
    assert dg.edge_radius_to_try(basic, 1.574) == 2.36
    given = dataclasses.replace(basic, options=dataclasses.replace(basic.options,
                                                                   edge_radius=1.574))
    assert dg.edge_radius_to_try(given, 1.574) is None
    fh = load_basic(root / "cases" / "basic" / "kolivand2009_fh_12x41.toml")
    assert dg.edge_radius_to_try(fh, 0.5) is None


def _edged(stubbed, sf, centre_v=None, plastic=0.0):
    """:func:`checked_edge_radius` with the analysis replaced: the written bearing at the
    larger radius with ``centre_v`` (default the written design's) and ``plastic``, its
    root safety ``sf``."""
    best = _evaluation(WRITTEN, stubbed)
    v = V0 if centre_v is None else centre_v

    def said(base, values, stage, label, targets, setup, teeth, say, placed, **kw):
        stubbed["analysed"].append((dict(values), kw.get("key_prefix")))
        ms = _metrics(v, plastic)
        ev = law_evaluation(values, ms, TARGETS, SETUP["centre_v"])
        return dataclasses.replace(ev, case=types.SimpleNamespace(name="edged"), stage=stage)

    stubbed["monkeypatch"].setattr(dg, "said_variant", said)
    lines: list[str] = []
    out = dg.checked_edge_radius(best, 1.246, 2.36, 1.574, TARGETS, dict(SETUP), None,
                                 lines.append, lambda v: None, lambda v: (sf, "gear"))
    return best, out, lines


def test_a_larger_fillet_that_loses_no_target_is_kept(stubbed):
    """The written bearing (its prescriptions, the pinion tooth keyed apart by the radius)
    with the edge radius 2.36 mm: S_F,FE 1.246 -> 1.45 (the 8×47's synthesize with 2.36
    mm read 1.45 on its own development), the same pattern: kept, and said."""
    best, (kept, sf, trial), lines = _edged(stubbed, 1.45)
    assert stubbed["analysed"] == [(WRITTEN, ("edge_radius", 2.36))]
    assert kept is not best and kept.values == WRITTEN and sf == 1.45
    assert trial.safety == 1.45 and trial.member == "gear" and not trial.missed
    assert any("edge radius 2.36 mm (was 1.574" in line and "S_F,FE 1.450" in line
               for line in lines)
    text = dg.edge_text(trial, True)
    assert text.startswith("a larger fillet was tried (the blade's edge radius 2.36 mm")
    assert "S_F,FE 1.45" in text and text.endswith("kept")


def test_a_larger_fillet_that_loses_a_target_or_no_root_is_not_kept(stubbed):
    """Plastic at the design torque (a target the written design met): not kept, its root
    safety said; a root safety no higher (1.248 < 1.246 + ROOT_GAIN, the same pattern):
    not kept; a root not computed (NaN): not kept."""
    best, (kept, sf, trial), _ = _edged(stubbed, 1.45, plastic=0.025)
    assert kept is best and sf == 1.246 and trial.missed == ("plastic",)
    assert "misses plastic" in dg.edge_text(trial, False)
    best, (kept, sf, _), _ = _edged(stubbed, 1.248)
    assert kept is best and sf == 1.246
    best, (kept, sf, trial), _ = _edged(stubbed, math.nan)
    assert kept is best and "S_F,FE not computed" in dg.edge_text(trial, False)
    assert dg.edge_text(None, False) == ""


def test_the_development_writes_the_larger_fillet_and_says_it(monkeypatch):
    """``develop``'s wiring of the fillet (:func:`contact.optimize.development.
    _given_root_bearing` with ``edged``), the steps and the synthesis replaced: the edge
    radius 2.36 mm kept at S_F,FE 1.45 >= 1.3, with every target met or with the centre v
    missed as written (the 8×47): the pattern's variants not tried (the root holds), the
    basic design written with ``[synthesis] edge_radius`` 2.36, the source saying so; kept
    at 1.28 (short of S_Fmin): the pattern's variants tried from it, with its synthesis
    (``edged(2.36)``); not kept: the variants from the written design, the note saying
    both."""
    from pathlib import Path

    from contact.optimize import development as dev
    from geometry.synthesis.basic_design import load_basic

    basic = load_basic(Path(__file__).resolve().parents[1] / "benchmarks" / "data"
                       / "unseen_designs" / "truck_hypoid_8x47_a45.toml")
    best = _evaluation(WRITTEN, {"plastic_above_v": 0.0, "tip_clears": 30.0})
    edged = dataclasses.replace(best, values=dict(WRITTEN), stage="given root")
    assert edged.full[2] is False  # the written design misses its centre v
    edged_met = dataclasses.replace(edged, full=(0.0, edged.full[1], True))
    written = (best, basic, "case", "report")
    calls: list = []
    monkeypatch.setattr(dev, "with_flank_options", lambda b, f, v: b)
    monkeypatch.setattr(dev, "_edge_radius_of", lambda case: 1.574)
    monkeypatch.setattr(dg, "edge_radius_to_try", lambda b, current: 2.36)
    monkeypatch.setattr(dev, "given_torque_root", lambda c, s, say: (1.45, ""))

    def write(b, **kw):
        calls.append(("write", b.options.edge_radius))
        return "case2", "report2"

    trial = dg.RootTrial("edge radius 2.36 mm (was 1.574; the largest the slots allow)",
                         1.45, "gear", (), 0.636)
    for edge_out, expect_variants in (((edged_met, 1.45, trial), False),
                                      ((edged, 1.45, trial), False),
                                      ((edged, 1.28, trial), True),
                                      ((best, 1.246, trial), True)):
        calls.clear()
        monkeypatch.setattr(dg, "checked_edge_radius", lambda *a, r=edge_out: r)

        def variants(start, s0, s_min, targets, setup, teeth, say, placed, root_of, slope):
            calls.append(("variants", start.stage, s0, placed))
            return start, s0, []

        monkeypatch.setattr(dg, "checked_given_root", variants)
        s = {"torques": [264.7, 1765.0], "source": "[synthesis] design_torque",
             "given_root": (1.246, 1.3, "gear"), "fe_level_why": "root stress limits"}
        out = dev._given_root_bearing(written, TARGETS, s, None, lambda line: None, "placed",
                                      write, lambda c: calls.append(("built", c)), 1.246,
                                      "FAIL at 1765", "concave", True, None,
                                      lambda r: f"placed {r}")
        if edge_out[0] is best:  # not kept: the variants from the written design
            assert calls == [("variants", "", 1.246, "placed")]
            assert out[:5] == (*written, 1.246)
            assert out[5].startswith("FAIL at 1765; a larger fillet was tried")
            assert out[5].endswith("not kept")
            continue
        assert out[1].options.edge_radius == 2.36 and out[2:4] == ("case2", "report2")
        assert calls[-2:] == [("write", 2.36), ("built", "case2")]
        assert (calls[0][0] == "variants") == expect_variants
        if expect_variants:
            assert calls[0][1:] == ("given root", 1.28, "placed 2.36")
        assert "the blade edge radius made the largest the slots allow" in s["source"]
        assert "S_F,FE 1.25 -> 1.45 >= S_Fmin 1.3" in s["source"]
        # (the variants' stand-in keeps none: the edge radius alone said)
        assert s["fe_level_why"] == (
            "root stress limits, of the design before the gear root's step; the blade "
            "edge radius made the largest the slots allow, S_F,FE 1.45 on it")
