"""A drive development run again in its LTE window stopped after its drive steps where its
check's LTE record over ``ltca run``'s range breaks the verdict's limit
(:func:`contact.optimize.development_written_lte.window_missed`, issue 71, branch cpu90b).

The record's numbers are the FM spiral bevel 16x16 at Σ 60°'s re-development at 534.3 N m
(docs/synthesis.md, "The FM 16×16 at Σ 60°'s design torque raised back past its LTE
window": 116 / 108 µrad, not kept) and the 14x36 at Σ 70°'s kept one (47 / 50 µrad at
31.8 / 212.1 N m, 28.4 between); the tests are the rule's choices against the 60 µrad
limit, not numbers of a gear, so they compare exactly.
"""

from __future__ import annotations

import math

import pytest
from development_stand_ins import WindowResult, checked
from development_stand_ins import metrics as _metrics

from contact.optimize import development as dev
from contact.optimize import development_range_lte as drl
from contact.optimize.development import DevelopmentTargets
from contact.optimize.development_range_lte import RANGE_KEY
from contact.optimize.development_written_lte import (
    WindowMissed,
    redeveloped_in_window,
    window_missed,
)


@pytest.fixture(autouse=True)
def _aim_at_the_verdicts_limit(monkeypatch):
    """The rule's choices written at its aim of 60 µrad: the development's sampling margin
    below the verdict's limit (development_range_lte.development_lte_limit) set to 0 here;
    the margin is tests/test_development_lte_margin.py's."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)


_VALUES = {"path_angle": -45.0, "ellipse_length": 0.7}
_TORQUES = (80.1, 534.3)


def _best(values=_VALUES):
    return checked(dict(values), _metrics(lte_peak_to_peak=[116.0, 108.0]),
                   DevelopmentTargets(), 0.6)


def _setup(peak: float, values=_VALUES, torques=_TORQUES):
    """A development's setup with the check's record over the range at ``torques``."""
    record = {"torques": (torques[0], 300.0, torques[1]), "lte": (116.0, peak, 108.0),
              "peak": peak, "at": 300.0, "values": dict(values)}
    return {"torques": list(torques), "source": "x",
            RANGE_KEY: {tuple(float(t) for t in torques): record}}


def test_the_record_of_the_design_above_the_limit_is_the_miss():
    """Above 60 µrad on the design's own record: the record; at or below it: None. Where
    no record of the design has a finite peak (NaN, another design's, another torque's,
    none), its result's range will not be judged, which is not kept either: the miss is its
    LTE at its own torques where that breaks the limit too (116 / 108 µrad: the record of
    those, ``judged`` False), else None (the 17x23's re-development: 72.1 / 77.6 µrad)."""
    best = _best()
    assert window_missed(_setup(116.0), best)["peak"] == 116.0
    assert window_missed(_setup(60.0), best) is None  # the limit itself is kept
    other = _setup(116.0)
    other["torques"] = [80.0, 533.0]  # the record of other torques is not this design's
    for setup in (_setup(math.nan), _setup(116.0, values={**_VALUES, "path_angle": -50.0}),
                  other, {"torques": list(_TORQUES)}):
        got = window_missed(setup, best)
        assert got["judged"] is False and got["lte"] == (116.0, 108.0)
        assert got["peak"] == 116.0 and got["values"] == _VALUES
    # the ends within the limit, or not known: nothing known yet
    within = checked(dict(_VALUES), _metrics(lte_peak_to_peak=[47.0, 60.0]),
                     DevelopmentTargets(), 0.6)
    unknown = checked(dict(_VALUES), _metrics(lte_peak_to_peak=[math.nan, 108.0]),
                      DevelopmentTargets(), 0.6)
    for design in (within, unknown):
        assert window_missed(_setup(math.nan), design) is None
        assert window_missed({"torques": list(_TORQUES)}, design) is None


def test_the_stop_is_asked_for_alone():
    """develop's stop_over_lte: False never stops; True raises WindowMissed on a miss only,
    the line said."""
    lines: list[str] = []
    dev._stop_where_missed(_setup(116.0), _best(), False, lines.append)
    dev._stop_where_missed(_setup(50.0), _best(), True, lines.append)
    assert lines == []
    with pytest.raises(WindowMissed) as stop:
        dev._stop_where_missed(_setup(116.0), _best(), True, lines.append)
    assert stop.value.record["peak"] == 116.0
    assert "at most 116.0 urad over the range" in lines[-1]
    with pytest.raises(WindowMissed):  # no range judged, its ends above the limit
        dev._stop_where_missed({"torques": list(_TORQUES)}, _best(), True, lines.append)
    assert "at most 116.0 urad at its torques (the range not judged) after" in lines[-1]


def _window():
    """The setup written_lte_capacity leaves where no lower torque keeps the limit (the
    16x16's window 375.7-534.4 N m)."""
    return {"torques": [97.4, 649.4], "source": "the ISO 10300 capacity",
            "lte_window": (375.7, 534.4, "54 / 95 urad at 97.4 / 649.4 N m")}


def test_a_stopped_re_development_is_not_kept_as_one_run_in_full_is_not():
    """The stand-in development: run in full, its result above the limit over the range is
    not kept (None); stopped after its drive steps on the same record, the same None, its
    line naming the check's reading, not a failed run."""
    record = _setup(116.0)[RANGE_KEY][tuple(_TORQUES)]

    def in_full(torque):
        return WindowResult(_best(), record, (80.1, torque))

    def stopped(torque):
        raise WindowMissed(record)

    lines: list[str] = []
    assert redeveloped_in_window(in_full, _window(), "as given", lambda s: None) is None
    assert redeveloped_in_window(stopped, _window(), "as given", lines.append) is None
    assert "at most 116.0 over the range after its drive steps" in lines[-1]
    assert "design torque kept at 649.4 N m" in lines[-1] and "failed" not in lines[-1]


def test_the_re_development_is_asked_to_stop(monkeypatch):
    """_at_written_lte hands the re-development stop_over_lte=True (and the window's
    torque name), the first development's own run asks for nothing of the kind."""
    asked: list[dict] = []

    def lowered(best, targets, setup, teeth, say):  # no lower torque: the 16x16's window
        setup.update(_window())
        return best

    def rerun(torque, **kw):
        asked.append({"torque": torque, **kw})
        raise WindowMissed(_setup(116.0)[RANGE_KEY][tuple(_TORQUES)])

    monkeypatch.setattr(dev, "written_lte_capacity", lowered)
    basic = type("Basic", (), {"gives_design_torque": False})()
    setup = {"torques": [97.4, 649.4], "source": "x", "lowered": False}
    _best_kept, again = dev._at_written_lte(_best(), basic, DevelopmentTargets(), setup, None,
                                            lambda s: None, math.nan, rerun)
    assert again is None and asked[0]["stop_over_lte"] is True
    assert asked[0]["torque"] == pytest.approx(534.4, abs=1e-9)
    assert "LTE window" in asked[0]["torque_name"]
