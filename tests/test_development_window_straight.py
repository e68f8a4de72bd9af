"""The LTE window's re-development straight to the middle
(:func:`contact.optimize.development_written_lte.redeveloped_in_window`, ``straight``;
``WINDOW_STRAIGHT_TO_MIDDLE``; issue 71, branch middle100) and the rule that takes it by
default where the written bearing's light end missed (``light_end_missed``, branch cpu101).

The window is the FM spiral bevel 17x23 of benchmarks/data/unseen_designs as logged on main
(its written bearing within 60 µrad from about 440.5 to 926.9 N m; developed at the upper end
926.9 N m it missed, at the middle 638.9 it missed, at 530.5 it was kept: branch lowratio95).
The developments are stand-ins (tests/development_stand_ins.py). The tests are the rule's
choices: which torques are developed and in what order, how many, what each is named and
what the kept one's source says. The torques are exact arithmetic, floor_torque of the
geometric means √(440.5 × 926.9) = 638.98 → 638.9 and √(440.5 × 638.9) = 530.50 → 530.5,
so they compare to round-off (1e-9 N m).
"""

from __future__ import annotations

import pytest
from development_stand_ins import WindowResult, checked
from development_stand_ins import metrics as _metrics

from contact.optimize import development_written_lte as written
from contact.optimize.development import DevelopmentTargets
from contact.optimize.development_written_lte import WindowMissed, redeveloped_in_window

_VALUES = {"path_angle": -31.2, "ellipse_length": 0.7}
_MISSED = {"torques": (139.0, 926.9), "lte": (72.1, 77.6), "peak": 77.6, "at": 926.9,
           "values": dict(_VALUES), "judged": False}


def _window(low: float = 440.5, high: float = 926.9, light: float | None = None) -> dict:
    """The 17x23's setup after written_lte_capacity; ``light`` the written bearing's LTE
    p-p [µrad] at its light torque 230.5 N m (the 17x23's 94.8) where given, else no
    reading (a setup of before branch cpu101)."""
    setup = {"torques": [230.5, 1537.0], "source": "the ISO 10300 capacity",
             "lte_window": (low, high, "94.8 / 96.0 urad at 230.5 / 1537 N m")}
    if light is not None:
        setup["lte_window_light"] = (230.5, light)
    return setup


def _kept(torque: float) -> WindowResult:
    best = checked(dict(_VALUES), _metrics(lte_peak_to_peak=[39.0, 42.0]),
                   DevelopmentTargets(), 0.6)
    return WindowResult(best, {"peak": 28.0, "at": 229.8}, (0.15 * torque, torque))


def _run(asked: list[dict], kept_below: float):
    """A development that misses (stopped after its drive steps) at or above
    ``kept_below`` N m and is kept below it."""
    def run(torque, **kw):
        asked.append({"torque": torque, **kw})
        if torque >= kept_below:
            raise WindowMissed(dict(_MISSED, torques=(0.15 * torque, torque),
                                    lte=(48.0, 64.0), peak=64.0))
        return _kept(torque)
    return run


@pytest.fixture(autouse=True)
def _as_given(monkeypatch):
    monkeypatch.setattr(written, "given_torque_of", lambda developed, basic: developed)


def test_straight_skips_the_upper_end_and_ends_where_the_upper_end_first_ends():
    """The 17x23: with straight the upper end 926.9 N m is not developed; 638.9 missed,
    530.5 kept — the torque the upper end first reaches after three developments, in two.
    The first development is named the middle below the upper end (not developed)."""
    asked: list[dict] = []
    lines: list[str] = []
    got = redeveloped_in_window(_run(asked, 600.0), _window(), "as given", lines.append,
                                middle=True, straight=True)
    assert [a["torque"] for a in asked] == [pytest.approx(t, abs=1e-9)
                                            for t in (638.9, 530.5)]
    assert asked[0]["torque_name"].startswith(
        "the LTE window's geometric middle below its upper end 926.9 N m")
    assert "the upper end not developed" in asked[0]["torque_name"]
    assert "at 638.9 N m its drive LTE p-p 48.0 / 64.0" in asked[1]["torque_name"]
    assert got is not None and got.lte_torque == pytest.approx(530.5, abs=1e-9)
    assert "straight at the window's geometric middle below its upper end 926.9" in (
        got.torque_source)
    assert "developed at 530.5 N m: 39.0 / 42.0 urad" in got.torque_source
    assert "(the upper end not developed)" in lines[0]

    # the same window the upper end first: three developments to the same torque
    asked.clear()
    first = redeveloped_in_window(_run(asked, 600.0), _window(), "as given", lambda s: None,
                                  middle=True, straight=False)
    assert [a["torque"] for a in asked] == [pytest.approx(t, abs=1e-9)
                                            for t in (926.9, 638.9, 530.5)]
    assert first.lte_torque == got.lte_torque


def test_straight_develops_at_most_window_lower_steps_in_all():
    """Every development misses: straight stops after WINDOW_LOWER_STEPS developments
    (one fewer than the upper end first, which adds its upper end), the design torque
    kept, said."""
    asked: list[dict] = []
    lines: list[str] = []
    got = redeveloped_in_window(_run(asked, 0.0), _window(), "as given", lines.append,
                                middle=True, straight=True)
    assert got is None and len(asked) == written.WINDOW_LOWER_STEPS == 2
    assert "design torque kept at 1537 N m" in lines[-1]


def test_a_wide_window_s_upper_end_is_not_tried_when_its_middle_is_kept():
    """A window 28.7-191.7 N m (the FM 24x29 at Σ 105°'s) whose middle is kept: one
    development, at floor_torque(√(28.7 × 191.6)) = 74.1 N m, not at 191.6 — the rule's
    cost where the upper end would have been kept (the raise back from the middle,
    development._window_raised, is the run's, not this function's)."""
    asked: list[dict] = []
    got = redeveloped_in_window(_run(asked, 1e9), _window(28.7, 191.7), "as given",
                                lambda s: None, middle=True, straight=True)
    assert [a["torque"] for a in asked] == [pytest.approx(74.1, abs=1e-9)]
    assert got.lte_torque == pytest.approx(74.1, abs=1e-9)


def test_a_narrow_window_goes_to_its_upper_end_and_the_switch_overrides_the_rule(
        monkeypatch):
    """A window 800-926.9 N m: its middle 861.1 N m within 1.1 × of 926.9, so straight
    develops the upper end as without it. The default (straight None) reads
    WINDOW_STRAIGHT_TO_MIDDLE, None: the rule light_end_missed (a setup without the light
    end's reading: the upper end first); False: the upper end first even where the light
    end missed; True: the middle first. After a capacity cut (middle False) straight changes
    nothing."""
    asked: list[dict] = []
    redeveloped_in_window(_run(asked, 0.0), _window(800.0, 926.9), "as given",
                          lambda s: None, middle=True, straight=True)
    assert asked[0]["torque"] == pytest.approx(926.9, abs=1e-9)
    assert "torque_name" not in asked[0]

    assert written.WINDOW_STRAIGHT_TO_MIDDLE is None
    asked.clear()
    redeveloped_in_window(_run(asked, 1e9), _window(), "as given", lambda s: None,
                          middle=True)
    assert [a["torque"] for a in asked] == [pytest.approx(926.9, abs=1e-9)]
    monkeypatch.setattr(written, "WINDOW_STRAIGHT_TO_MIDDLE", False)
    asked.clear()
    redeveloped_in_window(_run(asked, 1e9), _window(light=94.8), "as given",
                          lambda s: None, middle=True)
    assert [a["torque"] for a in asked] == [pytest.approx(926.9, abs=1e-9)]
    monkeypatch.setattr(written, "WINDOW_STRAIGHT_TO_MIDDLE", True)
    asked.clear()
    redeveloped_in_window(_run(asked, 1e9), _window(), "as given", lambda s: None,
                          middle=True)
    assert [a["torque"] for a in asked] == [pytest.approx(638.9, abs=1e-9)]
    asked.clear()
    redeveloped_in_window(_run(asked, 1e9), _window(), "as given", lambda s: None)
    assert [a["torque"] for a in asked] == [pytest.approx(926.9, abs=1e-9)]


def test_the_rule_goes_straight_where_the_written_bearing_s_light_end_missed():
    """By default (straight None, WINDOW_STRAIGHT_TO_MIDDLE None) the written bearing's LTE
    at its own light torque decides: the 17x23's 94.8 µrad at 230.5 N m (above the verdict's
    60) goes straight to the middle 638.9 N m, then 530.5 — the torque the upper end first
    reaches, one development fewer; the 24x29's kind of window, its light end within the
    limit (17.1 µrad), goes to the upper end first as before; a reading at the limit itself
    (60.0) keeps the limit (the verdict's check is ``≤``), a NaN reading decides nothing
    (the upper end first)."""
    asked: list[dict] = []
    got = redeveloped_in_window(_run(asked, 600.0), _window(light=94.8), "as given",
                                lambda s: None, middle=True)
    assert [a["torque"] for a in asked] == [pytest.approx(t, abs=1e-9)
                                            for t in (638.9, 530.5)]
    assert got.lte_torque == pytest.approx(530.5, abs=1e-9)
    for light in (17.1, 60.0, float("nan")):
        asked.clear()
        redeveloped_in_window(_run(asked, 1e9), _window(light=light), "as given",
                              lambda s: None, middle=True)
        assert [a["torque"] for a in asked] == [pytest.approx(926.9, abs=1e-9)], light
    assert written.light_end_missed(_window(light=60.000001))
    assert not written.light_end_missed(_window())
