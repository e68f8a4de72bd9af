"""The design torque raised back after a capacity cut keeps the drive LTE limit it kept
at the cut torque (issue 71, branch regain89; contact/optimize/development_regain_lte.py,
``development._regained``; docs/synthesis.md, "The FM 16×16 at Σ 60°'s design torque
raised back past its LTE window").

The stand-in's LTE p-p against the torque is the FM spiral bevel 16×16 at Σ 60°'s written
drive bearing as ``ltca run --torque`` measured it (2026-11-28, the case main writes:
developed at the local pitting cut's 278.3 N m, raised back to 390.7 N m), linear between
the torques measured: the tests are the rule's choices, not numbers of a gear.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from development_stand_ins import checked, lte_law_start

from contact.optimize import development as dev
from contact.optimize import development_range_lte as drl
from contact.optimize import development_regain as dreg
from contact.optimize import development_root as droot
from contact.optimize.development_regain_lte import lte_kept_raise
from contact.optimize.development_result import case_torques


@pytest.fixture(autouse=True)
def _aim_at_the_verdicts_limit(monkeypatch):
    """The rule's choices written at its aim of 60 µrad: the development's sampling margin
    below the verdict's limit (development_range_lte.development_lte_limit) set to 0 here;
    the margin is tests/test_development_lte_margin.py's."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)


#: (torque [N m], LTE p-p [µrad]) of the 16×16's written drive bearing (ltca run)
_LAW = ((41.7, 53.3), (45.0, 52.5), (58.6, 53.6), (127.8, 41.0), (150.0, 35.0),
        (213.9, 40.9), (250.0, 44.0), (278.3, 50.6), (280.0, 51.3), (293.9, 56.9),
        (300.0, 59.4), (307.7, 62.6), (335.4, 73.3), (390.7, 94.8))
#: the law's own crossing of 60 µrad: 300 + 0.6 / 3.2 × 7.7 N m
_CROSSING = 300.0 + 0.6 / 3.2 * 7.7
CUT, RAISED, CEILING = 278.3, 390.7, 649.4
_VALUES = {"path_angle": -88.0, "ellipse_length": 0.63, "profile_crowning": 4.67}


def _start(monkeypatch, law=_LAW):
    """(targets, setup, the design at the cut torques, the design re-scored at the raised
    ones, seen)."""
    targets, setup, best, seen = lte_law_start(monkeypatch, law, case_torques(0.15, CUT),
                                               _VALUES)
    raised_torques = case_torques(0.15, RAISED)
    lte = np.interp(raised_torques, *np.array(law, float).T)
    raised = dataclasses.replace(best, metrics=dict(best.metrics, lte_peak_to_peak=lte))
    return targets, setup, best, raised, seen


def _lte(law, torques):
    return np.interp(torques, *np.array(law, float).T)


def test_the_raise_ends_where_the_written_bearing_keeps_60(monkeypatch):
    """The 16×16: 53 / 51 µrad at 41.7 / 278.3 N m (within 60 µrad over the range), 54 /
    95 µrad at 58.6 / 390.7: the raise ends at the crossing the rule finds on the raised
    range (linear between the torques it analysed: at or below the law's own crossing
    301.44 N m, above the cut torque), whose own range keeps 60 µrad; the setup not
    changed; the two ranges said."""
    targets, setup, best, raised, _seen = _start(monkeypatch)
    before = dict(setup)
    got = lte_kept_raise(best, raised, targets, setup, None, case_torques(0.15, RAISED),
                         lambda line: None)
    assert CUT * 1.01 < got.torque <= _CROSSING
    # its own light and design torque and the law between them keep 60 µrad
    light = 0.15 * got.torque
    assert np.all(_lte(_LAW, np.linspace(light, got.torque, 50)) <= 60.0)
    assert "at the cut torques" in got.why and "95 urad" in got.why
    assert {k: setup[k] for k in before} == before and "lte_torque" not in setup


def test_no_cap_where_the_raise_keeps_the_limit_or_the_cut_torque_did_not(monkeypatch):
    """A raised range within 60 µrad: the raised torque, nothing analysed but its range; a
    range above 60 µrad at the cut torques already (no limit kept to lose): the raised
    torque too."""
    keeping = ((40.0, 50.0), (400.0, 59.0))
    targets, setup, best, raised, seen = _start(monkeypatch, keeping)
    got = lte_kept_raise(best, raised, targets, setup, None, case_torques(0.15, RAISED),
                         lambda line: None)
    assert got.torque == RAISED and got.why == ""
    assert all(max(t) <= RAISED for t in seen)
    above = ((40.0, 65.0), (300.0, 62.0), (400.0, 90.0))
    targets, setup, best, raised, seen = _start(monkeypatch, above)
    got = lte_kept_raise(best, raised, targets, setup, None, case_torques(0.15, RAISED),
                         lambda line: None)
    assert got.torque == RAISED and got.why == ""


def test_the_cut_torque_where_no_torque_above_it_keeps_60(monkeypatch):
    """60 µrad crossed at 280 N m, less than 1 % above the cut 278.3: the cut torque, said."""
    tight = ((40.0, 50.0), (278.3, 59.0), (281.0, 61.0), (400.0, 95.0))
    targets, setup, best, raised, _seen = _start(monkeypatch, tight)
    lines: list[str] = []
    got = lte_kept_raise(best, raised, targets, setup, None, case_torques(0.15, RAISED),
                         lines.append)
    assert got.torque == CUT and got.why
    assert lines and "no design torque above 278.3" in lines[-1]


@pytest.mark.parametrize("tolerant_to", [RAISED, 350.0])
def test_regained_writes_the_lte_window_s_torque(monkeypatch, tolerant_to):
    """``development._regained`` on the 16×16's numbers: the capacity holds to 390.7 N m
    (the stand-in of ``regained_capacity``), the tolerance too (or to 350 N m only: its
    torque's capacity asked first); the LTE limit kept at the cut torque ends the raise at
    the LTE's torque, its capacity asked again there, the design re-scored there; the
    source, the line and ``lte_torque`` say it."""
    targets, setup, best, _raised, _seen = _start(monkeypatch)
    setup["source"] = "the local pitting capacity"
    asked: list[float] = []

    def regained(case, setup, light_load, ceiling, say):
        asked.append(ceiling)
        t = min(RAISED, ceiling)
        return ("tree", t), case_torques(light_load, t), t, 2.93

    def rescored(e, tree, case, targets, setup):
        lte = _lte(_LAW, case_torques(0.15, tree[1]))
        return dataclasses.replace(checked(e.values, dict(e.metrics, lte_peak_to_peak=lte),
                                           targets, 0.6), case=e.case)

    monkeypatch.setattr(droot, "regained_capacity", regained)
    monkeypatch.setattr(dev, "rescored", rescored)
    held = (dreg.TolerantRaise(RAISED) if tolerant_to == RAISED else
            dreg.TolerantRaise(tolerant_to, 360.0, ("dE+0.05: plastic",)))
    monkeypatch.setattr(dreg, "tolerant_raise", lambda *a, **k: held)
    best = dataclasses.replace(best, case=dict(_VALUES))
    rescored_at_cut = rescored(best, ("tree", CUT), None, targets, setup)
    best = dataclasses.replace(rescored_at_cut, case=best.case)
    lines: list[str] = []
    got, text, safety = dev._regained(best.case, best, targets, setup, None, CEILING, "cut",
                                      math.nan, lines.append)
    t = setup["torques"][1]
    assert CUT * 1.01 < t <= _CROSSING
    assert asked == ([CEILING, t] if tolerant_to == RAISED else [CEILING, tolerant_to, t])
    assert setup["lte_torque"] == t and setup["torques"] == case_torques(0.15, t)
    assert np.all(got.metrics["lte_peak_to_peak"] <= 60.0) and safety == 2.93
    assert text == setup["source"] and f"raised back to {t:.4g} N m (of 649.4)" in text
    if tolerant_to == RAISED:
        assert ("its capacity 390.7 N m, the drive LTE within 60 urad at every torque up to"
                in text)
    else:  # the tolerance's clause names the capacity; the LTE's follows it
        assert "held up to 350 N m (not at 360" in text
        assert "; the drive LTE within 60 urad at every torque up to" in text
    assert f"design torque 278.3 -> {t:.4g} N m" in lines[-1]


def test_regained_not_raised_where_the_lte_keeps_no_torque_above_the_cut(monkeypatch):
    """The LTE crossing within 1 % of the cut torque: no raise (design, torques, source as
    they were), said."""
    tight = ((40.0, 50.0), (278.3, 59.0), (281.0, 61.0), (400.0, 95.0))
    targets, setup, best, _raised, _seen = _start(monkeypatch, tight)
    setup["source"] = "the local pitting capacity"

    def regained(case, setup, light_load, ceiling, say):
        t = min(RAISED, ceiling)
        return ("tree", t), case_torques(light_load, t), t, 2.93

    def rescored(e, tree, case, targets, setup):
        lte = _lte(tight, case_torques(0.15, tree[1]))
        return dataclasses.replace(checked(e.values, dict(e.metrics, lte_peak_to_peak=lte),
                                           targets, 0.6), case=e.case)

    monkeypatch.setattr(droot, "regained_capacity", regained)
    monkeypatch.setattr(dev, "rescored", rescored)
    monkeypatch.setattr(dreg, "tolerant_raise",
                        lambda *a, **k: dreg.TolerantRaise(RAISED))
    best = dataclasses.replace(best, case=dict(_VALUES))
    lines: list[str] = []
    got, text, safety = dev._regained(best.case, best, targets, setup, None, CEILING, "cut",
                                      math.nan, lines.append)
    assert got is best and text == "cut" and math.isnan(safety)
    assert setup["torques"] == case_torques(0.15, CUT) and "lte_torque" not in setup
    assert "it would lose the drive LTE limit it keeps" in lines[-1]


if __name__ == "__main__":  # pragma: no cover
    pytest.main([__file__])
