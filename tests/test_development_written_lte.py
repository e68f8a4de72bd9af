"""The design torque no higher than where the written drive design keeps the verdict's LTE
limit at every torque (:mod:`contact.optimize.development_written_lte`, issue 71).

The stand-in's LTE p-p against the torque is the FM spiral bevel 14x36 at Σ 70° of
benchmarks/data/unseen_designs as ``ltca run`` judged its written case (docs/
own_gear_set.md, "Two FM generated-gear designs re-measured on the corrected gear": 49.1 /
60.3 / 71.2 / 83.5 µrad at 55.6 / 161 / 266 / 371.2 N m), a light-load value below it,
linear between: the tests are the rule's choices, not numbers of a gear.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from development_stand_ins import WindowResult, checked, lte_law_start
from development_stand_ins import metrics as _metrics

from contact.optimize import development_range_lte as drl
from contact.optimize.development_written_lte import lowered_torque, written_lte_capacity


@pytest.fixture(autouse=True)
def _aim_at_the_verdicts_limit(monkeypatch):
    """The rule's choices written at its aim of 60 µrad: the development's sampling margin
    below the verdict's limit (development_range_lte.development_lte_limit) set to 0 here;
    the margin is tests/test_development_lte_margin.py's."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)


#: (torque [N m], LTE p-p [µrad]) of the 14x36's written bearing
_LAW = ((20.0, 45.0), (55.6, 49.1), (161.0, 60.3), (266.0, 71.2), (371.2, 83.5))
_VALUES = {"path_angle": -45.0, "ellipse_length": 0.7}
#: a basic file of the repository (the stand-in development's basic data)
_BASIC = (Path(__file__).resolve().parent.parent / "benchmarks" / "data" / "unseen_designs"
          / "spiral_bevel_15x28_s110.toml")


def _start(monkeypatch, law=_LAW, torques=(55.6, 371.2)):
    return lte_law_start(monkeypatch, law, torques, _VALUES)


def test_lowered_torque_is_the_crossing_rounded_down():
    """60 µrad crossed between 55.6 (49.1) and 161 N m (60.3): 55.6 + 10.9/11.2 × 105.4 =
    158.18 N m, rounded down to 0.1 N m (floor_torque): 158.1. Exact arithmetic, so the
    tolerance is round-off alone."""
    got = lowered_torque([55.6, 161.0, 266.0, 371.2], [49.1, 60.3, 71.2, 83.5], 60.0, 371.2)
    assert got == pytest.approx(158.1, abs=1e-9)
    assert math.isnan(lowered_torque([55.6, 371.2], [49.1, 58.0], 60.0, 371.2))  # keeps it
    assert math.isnan(lowered_torque([55.6, 371.2], [61.0, 80.0], 60.0, 371.2))  # light above
    # a torque above the design torque is not judged (ltca run's range ends at it)
    assert math.isnan(lowered_torque([55.6, 371.2, 400.0], [49.1, 58.0, 90.0], 60.0, 371.2))
    with pytest.raises(ValueError):
        lowered_torque([1.0, 2.0], [1.0], 60.0, 2.0)


def test_an_attention_level_lte_lowers_the_design_torque_to_where_it_keeps_60(monkeypatch):
    """The 14x36: 83.5 µrad at 371.2 N m (the verdict's attention, below its FAIL level
    lte_capacity acts on). Over ltca run's range (four torques, the crossing bisected twice)
    the stand-in's law crosses 60 µrad at 55.6 + 10.9/11.2 × 105.4 = 158.18 N m; the
    lowered torque's own range (light 0.15 × it) keeps 60 at every torque: kept, the light
    torque the targets' share of it, said with the numbers."""
    targets, setup, best, seen = _start(monkeypatch)
    lines: list[str] = []
    got = written_lte_capacity(best, targets, setup, None, lines.append)
    assert seen[0] == pytest.approx((160.8, 266.0), abs=1e-9)  # linspace(55.6, 371.2, 4)
    assert setup["lowered"] is True
    t1 = setup["torques"][1]
    assert 150.0 < t1 <= 158.2  # at or below the crossing of the linear law (bisected grid)
    assert setup["torques"][0] == pytest.approx(targets.light_load * t1, abs=0.1)
    assert np.all(got.metrics["lte_peak_to_peak"] <= 60.0)
    assert got.values == best.values  # the bearing as written: no step again
    assert lines and "371.2 -> " in lines[0] and "keeps the drive LTE within 60 urad" in lines[0]
    assert "83.5" in setup["source"] and "the ISO 10300 capacity 371.2 N m" in setup["source"]


def test_no_cut_where_the_lte_keeps_the_limit_or_no_torque_does(monkeypatch):
    """An LTE within 60 µrad over the whole range: the design and setup unchanged, nothing
    said; an LTE above 60 µrad at the light torque already: unchanged, said."""
    keeping = ((20.0, 40.0), (55.6, 45.0), (371.2, 59.0))
    targets, setup, best, _seen = _start(monkeypatch, keeping)
    lines: list[str] = []
    assert written_lte_capacity(best, targets, setup, None, lines.append) is best
    assert "lowered" not in setup and lines == []
    high = ((20.0, 70.0), (55.6, 65.0), (371.2, 90.0))
    targets, setup, best, _seen = _start(monkeypatch, high)
    assert written_lte_capacity(best, targets, setup, None, lines.append) is best
    assert "lowered" not in setup and "no design torque below 371.2" in lines[-1]
    assert "lte_window" not in setup  # no torque keeps it: no window to develop in


#: the 14x36's written bearing as `ltca run --torque` measured it (2026-11-28, branch
#: lte87: 15-55.6 N m) and as the development's range read it (160.8-371.2 N m): the LTE
#: falls from the unloaded TE's 70 µrad at light load and rises again above 160 N m
_MEASURED = ((15.0, 70.3), (20.0, 68.2), (25.0, 65.9), (31.8, 62.4), (40.0, 58.1),
             (48.0, 53.2), (55.6, 49.1), (160.8, 32.3), (187.1, 46.0), (213.4, 60.7),
             (266.0, 71.5), (371.2, 83.9))


def test_lte_window_is_the_first_run_within_the_limit():
    """The measured 14x36: 60 µrad crossed at 31.8 + 2.4/4.3 × 8.2 = 36.377 and 187.1 +
    14/14.7 × 26.3 = 212.147 N m (linear interpolation: exact to round-off)."""
    from contact.optimize.development_written_lte import lte_window

    t, y = np.array(_MEASURED).T
    low, high = lte_window(t, y, 60.0)
    assert low == pytest.approx(31.8 + 2.4 / 4.3 * 8.2, abs=1e-9)
    assert high == pytest.approx(187.1 + 14.0 / 14.7 * 26.3, abs=1e-9)
    assert lte_window([1.0, 2.0], [50.0, 55.0], 60.0) == (1.0, 2.0)
    assert all(math.isnan(x) for x in lte_window([1.0, 2.0], [61.0, 65.0], 60.0))
    with pytest.raises(ValueError):
        lte_window([1.0], [], 60.0)


def test_a_lowered_light_torque_above_the_limit_keeps_the_design(monkeypatch):
    """The measured 14x36: within 60 µrad only from 36.4 to 212.1 N m, narrower than the
    light torque's 0.15 of the design torque (0.15 × 212.1 = 31.8 N m, 62.4 µrad there): no
    lowered torque keeps the limit at every torque, the design as it was, the window said
    in the line and the design torque's source."""
    targets, setup, best, seen = _start(monkeypatch, _MEASURED)
    lines: list[str] = []
    got = written_lte_capacity(best, targets, setup, None, lines.append)
    assert got is best and "lowered" not in setup
    assert len(seen) >= 2  # the range at the design torque, then one lowered torque tried
    assert "no design torque below 371.2" in lines[-1] and "tried at 212" in lines[-1]
    assert "only, and a design torque's light torque is 0.15 of it" in lines[-1]
    assert setup["source"].startswith("the ISO 10300 capacity")
    assert "at no lower design torque" in setup["source"]
    # the window the drive is developed again in: linear between the torques the rule
    # analysed (not the law's own points), so within the law's brackets of 60 µrad only
    low, high, _text = setup["lte_window"]
    assert 31.8 < low < 40.0 and 187.1 < high < 213.4
    # and the bearing's reading at its own light torque 55.6 N m, which decides whether the
    # re-development goes straight to the window's middle (light_end_missed): the law's
    # 49.1 µrad there, within 60, so the upper end first (lte87's 14x36: kept there)
    light, lte = setup["lte_window_light"]
    assert light == pytest.approx(55.6, abs=1e-9) and lte == pytest.approx(49.1, abs=1e-6)
    from contact.optimize.development_written_lte import light_end_missed
    assert not light_end_missed(setup)


def _window_setup():
    """The setup written_lte_capacity leaves on the measured 14x36 (window 36.4-212.1)."""
    return {"torques": [55.6, 371.2], "source": "the ISO 10300 capacity, the pinion ...",
            "lte_window": (36.377, 212.147, "48.9 / 83.9 urad at 55.6 / 371.2 N m")}


def test_the_drive_developed_again_at_the_window_s_upper_end_is_kept_where_it_keeps_60():
    """The 14x36 given 212.1 N m (measured: 47 / 50 µrad at 31.8 / 212.1 N m, 28.4 between):
    the run asked at floor_torque(212.147) = 212.1, its result kept with its written
    prescriptions at the design torque as given (given_torque_of), the torque the
    development's own and its source in numbers."""
    import dataclasses

    from contact.optimize.development import DevelopmentTargets
    from contact.optimize.development_written_lte import redeveloped_in_window
    from geometry.synthesis.basic_design import load_basic, with_flank_options

    given = load_basic(_BASIC)
    asked: list[float] = []
    best = checked(dict(_VALUES), _metrics(lte_peak_to_peak=[47.0, 50.4]),
                   DevelopmentTargets(), 0.6)
    drive = given.options.drive_flank

    def run(torque):
        asked.append(torque)
        at = dataclasses.replace(given, options=dataclasses.replace(
            given.options, design_torque=torque))
        return WindowResult(best, {"peak": 28.4, "at": 91.9}, (31.8, torque),
                            basic=with_flank_options(at, drive, _VALUES))

    lines: list[str] = []
    got = redeveloped_in_window(run, _window_setup(), given, lines.append)
    assert asked == [pytest.approx(212.1, abs=1e-9)]
    assert got.torque_lowered is True
    # the written prescriptions kept (the remedies are checked at them), the design torque
    # the file's (ltca synthesize's case reads it as given: written_case)
    assert got.basic.options.design_torque == given.options.design_torque
    assert got.basic.options.flank(drive) == with_flank_options(
        given, drive, _VALUES).options.flank(drive) != given.options.flank(drive)
    # the torque the LTE window set: a cut to it is no failed outcome (development_process)
    assert got.lte_torque == pytest.approx(212.1, abs=1e-9)
    assert "371.2 N m" in got.torque_source and "47.0 / 50.4 urad at 31.8 / 212.1 N m" in (
        got.torque_source) and "at most 28.4 urad over ltca run's range" in got.torque_source
    assert any("371.2 -> 212.1 N m" in line for line in lines)


def test_no_redevelopment_without_a_window_and_none_kept_above_the_limit():
    """No window recorded: nothing run. A run whose LTE between the torques (61 µrad) or
    at a torque exceeds 60 µrad, or that fails: None (the first development stands)."""
    from contact.optimize.development import DevelopmentTargets
    from contact.optimize.development_written_lte import redeveloped_in_window

    def never(torque):
        raise AssertionError("run without a window")

    assert redeveloped_in_window(never, {"torques": [55.6, 371.2], "source": "x"}, None,
                                 lambda s: None) is None
    best = checked(dict(_VALUES), _metrics(lte_peak_to_peak=[47.0, 50.4]),
                   DevelopmentTargets(), 0.6)
    between = lambda t: WindowResult(best, {"peak": 61.0, "at": 91.9}, (31.8, t))  # noqa: E731
    assert redeveloped_in_window(between, _window_setup(), None, lambda s: None) is None
    unjudged = lambda t: WindowResult(best, None, (31.8, t))  # noqa: E731
    assert redeveloped_in_window(unjudged, _window_setup(), None, lambda s: None) is None

    def fails(torque):
        raise ValueError("no case")

    lines: list[str] = []
    assert redeveloped_in_window(fails, _window_setup(), None, lines.append) is None
    assert "failed (no case)" in lines[-1]


def test_the_window_rule_runs_again_after_a_capacity_cut(monkeypatch):
    """``development._lte_after_cut``: the LTE window rule ran before the local pitting
    cut only; round 31's 13×17 remedied to b2 37 mm kept 45/59 µrad at its ISO capacity
    379.8 N m and was written at the cut torque 333.4 N m at 44/62 µrad (ATTENTION,
    docs/synthesis.md "The 13×17's remedied design above 60 µrad"). After a cut the rule
    runs again: where it lowers the torque (to 267.9 N m, where that bearing keeps 60 µrad
    by ltca synthesize's note) the setup carries it, the torque phrase chains the cut's and
    the rule's, and the root safety is read again there; where it keeps the torque (or no
    cut was made) nothing of the setup changes, the rule's record of a window with no
    torque in it included. Stand-ins for the rule and the FE check (no LTCA: the test is
    the wiring)."""
    from contact.optimize import development as dev

    cut = {"torques": [50.0, 333.4], "source": "the local pitting capacity ...",
           "centre_v": 0.55}
    said, calls = [], []

    def rule(lowers):
        def fake(best, targets, setup, teeth, say):
            calls.append(list(setup["torques"]))
            if lowers:
                setup.update(torques=[40.1, 267.9], source="the torque up to which ...",
                             lowered=True, lte_torque=267.9)
                return "lowered design"
            setup["source"] += "; ... at no lower design torque"
            setup["lte_window"] = (100.0, 267.9, "44 / 62 urad")
            return best
        monkeypatch.setattr(dev, "written_lte_capacity", fake)

    def root(case, best, targets, setup, say):
        calls.append(("root", list(setup["torques"])))
        return f"{best}, rescored", 2.9, ""

    monkeypatch.setattr(dev, "checked_root_capacity", root)
    rule(True)
    setup = dict(cut)
    got = dev._lte_after_cut(None, "design", None, setup, None, "the local pitting ...",
                             2.51, said.append)
    assert calls == [[50.0, 333.4], ("root", [40.1, 267.9])]
    assert got == ("lowered design, rescored",
                   "the local pitting ...; then the torque up to which ...", 2.9)
    assert setup["torques"] == [40.1, 267.9] and setup["lte_torque"] == 267.9
    assert setup["lowered"] and setup["source"] == got[1]
    # no lower torque keeps it: the design, its phrase, safety and setup as they were
    rule(False)
    calls.clear()
    setup = dict(cut)
    assert dev._lte_after_cut(None, "design", None, setup, None, "phrase", 2.51,
                              said.append) == ("design", "phrase", 2.51)
    assert setup == cut and calls == [[50.0, 333.4]]
    # no cut: the rule is not run again
    calls.clear()
    assert dev._lte_after_cut(None, "design", None, setup, None, "", 2.51,
                              said.append) == ("design", "", 2.51)
    assert not calls


#: the FM spiral bevel miter 18x18 of benchmarks/data/unseen_designs (round 33) as `ltca run`
#: judged its written case at its ISO capacity: 60.1 / 97.7 / 121.7 / 112.7 µrad at 97.8 /
#: 282.5 / 467.3 / 652 N m, a light-load value above the limit below it
_MITER = ((10.0, 75.0), (97.8, 60.1), (282.5, 97.7), (467.3, 121.7), (652.0, 112.7))


def test_an_lte_above_the_fail_level_with_no_torque_keeping_60_lowers_to_the_fail_level(
        monkeypatch):
    """The miter: its light-load LTE (60.1 µrad) above 60 already, so no lower design torque
    keeps 60 µrad and no window exists; between the torques 121.7 µrad, above ltca run's FAIL
    level 2 × 60. The design torque is lowered to where the written bearing keeps 120 µrad:
    the law crosses it at 282.5 + 22.3/24 × 184.8 = 454.2 N m (linear; the bisected range
    only adds points of the same law, so the crossing lies in (282.5, 454.2]); its own range
    keeps 120 at every torque. Before the fix the design was kept at 652 N m, where
    `ltca run` FAILs."""
    targets, setup, best, _seen = _start(monkeypatch, _MITER, torques=(97.8, 652.0))
    lines: list[str] = []
    got = written_lte_capacity(best, targets, setup, None, lines.append)
    assert setup.get("lowered") is True
    t1 = setup["torques"][1]
    assert 282.5 < t1 <= 454.2 + 0.1
    assert setup["torques"][0] == pytest.approx(targets.light_load * t1, abs=0.1)
    assert np.all(got.metrics["lte_peak_to_peak"] <= 120.0)
    assert got.values == best.values  # the bearing as written
    assert "652 -> " in lines[-1] and "FAIL level 120 urad" in lines[-1]
    assert "no lower design torque keeps 60 urad" in setup["source"]


def test_an_lte_below_the_fail_level_with_no_torque_keeping_60_keeps_the_design(monkeypatch):
    """The same law scaled to 0.9 (at most 109.5 µrad, below 120): the verdict's attention,
    not its FAIL — the design torque kept as before, the line says no torque keeps 60."""
    law = tuple((t, 0.9 * y if t > 97.8 else y) for t, y in _MITER)
    targets, setup, best, _seen = _start(monkeypatch, law, torques=(97.8, 652.0))
    lines: list[str] = []
    assert written_lte_capacity(best, targets, setup, None, lines.append) is best
    assert "lowered" not in setup and "no design torque below 652" in lines[-1]


def test_the_fail_level_cut_tries_again_where_the_lte_is_no_straight_line(monkeypatch):
    """The miter's law as `ltca run --torque 67.7 451` measured it (116.2 µrad at 323.2 N m,
    122.2 at 451): the first crossing, interpolated over the design torque's range, lands
    at about 454 N m, where the law is still above 120 µrad; the second, with that range's
    torques added and aimed at 0.95 × 120 = 114 µrad, between 282.5 and 323.2 N m (the
    law's own bracket of 114: linear between its points), where it keeps 120 at every
    torque: kept there."""
    law = ((10.0, 75.0), (97.8, 60.1), (282.5, 97.7), (323.2, 116.2), (404.0, 119.0),
           (451.0, 122.2), (467.3, 121.7), (652.0, 112.7))
    targets, setup, best, seen = _start(monkeypatch, law, torques=(97.8, 652.0))
    lines: list[str] = []
    got = written_lte_capacity(best, targets, setup, None, lines.append)
    assert setup.get("lowered") is True
    assert 282.5 < setup["torques"][1] <= 323.2
    assert np.all(got.metrics["lte_peak_to_peak"] <= 120.0)
    assert len(seen) >= 3  # the design torque's range, the first lowered try, the second


def test_an_lte_just_above_the_limit_is_not_written_as_the_limit():
    """Issue 71, round 37 (the FM 24x29 at Σ 105°): the lowered torques tried were refused
    for an LTE p-p above 60 µrad by less than 0.05 µrad, and the line read "60.0 urad" —
    the limit itself, as if kept. A value above the limit is given to the decimal that
    shows it above (exact string formatting, no tolerance); one at or below the limit, or
    clear of it, keeps 0.1 µrad."""
    from contact.optimize.development_written_lte import _curve

    text = _curve(((28.7, 137.4, 191.7), (15.6, 41.5, 60.004)))
    assert text == "15.6 / 41.5 / 60.004 urad at 28.7 / 137.4 / 191.7 N m"
    assert _curve(((191.8,), (60.04,))) == "60.04 urad at 191.8 N m"
    assert _curve(((194.2,), (60.8,))) == "60.8 urad at 194.2 N m"
    assert _curve(((150.0,), (59.97,))) == "60.0 urad at 150 N m"  # within: at the limit
    assert _curve(((150.0,), (60.0,))) == "60.0 urad at 150 N m"


def test_a_window_records_the_written_bearing_s_light_end(monkeypatch):
    """The 17x23's written bearing (its range as logged: 94.8 / 22.6 / 85.0 / 96.0 µrad at
    230.5 / 666 / 1102 / 1537 N m, linear between; a steeper rise below its light torque,
    the unloaded TE's): no lowered torque keeps 60 µrad, a window between the two
    crossings is recorded, and with it the reading at the development's own light torque
    230.5 N m, 94.8 µrad — above the limit, so the re-development goes straight to the
    window's middle (development_written_lte.light_end_missed; branch cpu101). The law's
    points are the log's, so the reading compares to round-off (1e-6 µrad)."""
    from contact.optimize.development_written_lte import light_end_missed

    law = ((20.0, 300.0), (230.5, 94.8), (666.0, 22.6), (1102.0, 85.0), (1537.0, 96.0))
    targets, setup, best, _ = _start(monkeypatch, law, torques=(230.5, 1537.0))
    got = written_lte_capacity(best, targets, setup, None, lambda s: None)
    assert got is best and "lowered" not in setup
    low, high, _text = setup["lte_window"]
    assert 230.5 < low < 666.0 < high < 1102.0
    light, lte = setup["lte_window_light"]
    assert light == pytest.approx(230.5, abs=1e-9) and lte == pytest.approx(94.8, abs=1e-6)
    assert light_end_missed(setup)
