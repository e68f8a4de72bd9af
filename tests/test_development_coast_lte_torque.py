"""The coast design torque no higher than where the written coast bearing keeps the
verdict's LTE limit (:mod:`contact.optimize.development_coast_lte_torque`, issue 71).

Stand-ins: the coast flank's LTE p-p a piecewise-linear law of the torque, its two ends
and the knot the FM spiral bevel 13x17 at Σ 50° of benchmarks/data/unseen_designs wrote
(``ltca synthesize`` on main, 2026-11-29: 56 / 90 µrad at 18.4 / 122.7 N m, 79.6 µrad at
87.93 N m between). The tests are the rule's choices — where it lowers, to which
torque, what it refuses — checked against the crossing computed by hand here, not numbers
of a gear; the capacity search and the range analysis are replaced by the law.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from contact.optimize import development_coast_lte_torque as lte_torque
from contact.optimize.development_coast import CoastCapacity, CoastCheck
from contact.optimize.development_targets import DevelopmentTargets

#: the 13x17's coast light torque and coast design torque [N·m]
LIGHT, DESIGN = 18.4, 122.7

#: its written coast LTE p-p [µrad] at torques [N·m] (the knot ltca run's range found)
KNOTS = ((18.4, 56.0), (87.93, 79.6), (122.7, 90.0))


def law(t: float, knots=KNOTS) -> float:
    """The stand-in LTE p-p [µrad] at ``t`` [N·m], linear between the knots."""
    ts, xs = zip(*knots, strict=True)
    return float(np.interp(t, ts, xs))


def _range(light: float, design: float, knots=KNOTS):
    """ltca run's range stand-in: the light, the middle and the design torque."""
    ts = (light, 0.5 * (light + design), design)
    return ts, tuple(law(t, knots) for t in ts)


def _coast(design=DESIGN, knots=KNOTS):
    best = SimpleNamespace(checked_full=True, values={"ellipse_length": 0.65},
                           metrics={"lte_peak_to_peak": [law(LIGHT, knots),
                                                         law(design, knots)]})
    return SimpleNamespace(best=best, torques=(LIGHT, design))


def _patched(monkeypatch, knots=KNOTS, holds=True, lower_to=None):
    """The range analysis and the capacity search replaced by the law; returns the
    capacity search's start torques."""
    calls: list[float] = []

    def fake_range(e, setup, teeth, *a, **k):
        light, design = setup["torques"]
        return _range(float(light), float(design), knots)

    def fake_capacity(case, basic, coast, targets, setup, start, root_stress, lower, say):
        calls.append(start)
        torque = start if lower_to is None else min(start, lower_to)
        best = SimpleNamespace(checked_full=True, values=dict(coast.best.values),
                               metrics={"lte_peak_to_peak": [
                                   law(LIGHT / DESIGN * torque, knots), law(torque, knots)]})
        check = CoastCheck(torque, 1400.0, 2400.0)
        reason = "" if torque == start else f"its peak at {start} N m"
        # the coast light torque the same share of the coast design torque as before
        return (SimpleNamespace(best=best, torques=(LIGHT / DESIGN * torque, torque)),
                CoastCapacity(torque, start, (check,), reason, holds))

    monkeypatch.setattr(lte_torque, "range_lte", fake_range)
    monkeypatch.setattr(lte_torque, "coast_flank_capacity", fake_capacity)
    return calls


_DRIVE = SimpleNamespace(values={"path_angle": -60.0})
_BASIC = SimpleNamespace(gives_design_torque=False, rating={})
_BEFORE = CoastCapacity(DESIGN, DESIGN, (CoastCheck(DESIGN, 1500.0, 2400.0),), "", True)


def _run(coast, cap=_BEFORE, basic=_BASIC, targets=None, drive_light=LIGHT):
    lines: list[str] = []
    setup = {"torques": [drive_light, DESIGN]}  # the drive's light and design torque
    got = lte_torque.coast_lte_torque(None, basic, coast, cap, _DRIVE,
                                      targets or DevelopmentTargets(), setup, None, True,
                                      lines.append)
    return got, lines


def test_the_coast_design_torque_is_lowered_to_where_its_lte_keeps_60_urad(monkeypatch):
    """56 / 79.6 / 90 µrad at 18.4 / 87.93 / 122.7 N m: the crossing of 60 µrad, linear
    between the light torque and the knot, is 18.4 + 4 / 23.6 × 69.53 = 30.18 N m, written
    rounded down to 0.1 N m (30.1); its own range (56 / 57.3 / 59.98 µrad) keeps the limit,
    so it is written, its light torque the same share of it (0.15: 4.51 N m), and the line
    and reason say the LTE before and after with the numbers. Below the drive's light
    torque nothing is lowered (a coast design torque under it is a failed outcome)."""
    calls = _patched(monkeypatch)
    coast = _coast()
    (outcome, cap), lines = _run(coast)
    crossing = 18.4 + (60.0 - 56.0) / (79.6 - 56.0) * (87.93 - 18.4)
    assert crossing == pytest.approx(30.18, abs=0.01)
    assert calls == [pytest.approx(30.1)]
    assert cap.torque == pytest.approx(30.1) and cap.lowered and cap.holds
    assert cap.start == DESIGN and len(cap.checks) == 2  # the capacity's checks kept
    assert outcome.torques == (pytest.approx(LIGHT / DESIGN * 30.1), pytest.approx(30.1))
    assert max(outcome.best.metrics["lte_peak_to_peak"]) <= 60.0
    assert lines[-1].startswith("development: coast design torque 122.7 -> 30.1 N m")
    # the range before (its middle 56 + 52.15 / 69.53 × 23.6 = 73.7 µrad) and at 30.1
    assert "56.0 / 73.7 / 90.0 urad at 18.4 / 70.55 / 122.7 N m" in cap.reason
    assert "60.0 urad at 4.514 / 17.31 / 30.1 N m at the coast design torque 30.1" in cap.reason
    assert "none of its bearing steps kept 60 urad there" in cap.reason
    # the drive's light torque above the crossing: nothing lowered
    calls.clear()
    (outcome, cap), lines = _run(coast, drive_light=35.0)
    assert outcome is coast and cap is _BEFORE and calls == []
    assert "no coast design torque below 122.7 N m found" in lines[-1]


def test_a_capacity_reason_before_is_kept_and_a_further_cut_said(monkeypatch):
    """A coast design torque set by its capacity already keeps that reason first; where
    the capacity search at the crossing lowers it further (a criterion fails there), the
    torque written is the search's and its reason follows."""
    _patched(monkeypatch, lower_to=25.0)
    before = CoastCapacity(DESIGN, 200.0, (CoastCheck(DESIGN, 1500.0, 2400.0),),
                           "S_H,loc 0.95 at 200 N m", True)
    (_outcome, cap), _ = _run(_coast(), cap=before)
    assert cap.torque == 25.0 and cap.start == 200.0
    assert cap.reason.startswith("S_H,loc 0.95 at 200 N m; the torque up to which")
    assert cap.reason.endswith("its peak at 30.1 N m")


def test_within_the_limit_at_every_torque_nothing_is_analysed(monkeypatch):
    """A coast flank within 60 µrad over its range (the default case's, the 10x43's) is
    returned as it is, no capacity search run."""
    flat = ((18.4, 40.0), (122.7, 55.0))
    calls = _patched(monkeypatch, knots=flat)
    coast = _coast(knots=flat)
    (outcome, cap), lines = _run(coast)
    assert outcome is coast and cap is _BEFORE and calls == [] and lines == []


def test_the_light_torques_lte_above_the_limit_lowers_nothing(monkeypatch):
    """The coast light torque is the drive's: a lower coast design torque does not move
    it, so where its LTE exceeds 60 µrad already no torque keeps the limit."""
    high = ((18.4, 61.0), (122.7, 104.0))
    calls = _patched(monkeypatch, knots=high)
    coast = _coast(knots=high)
    (outcome, cap), lines = _run(coast)
    assert outcome is coast and cap is _BEFORE and calls == []
    assert lines[-1].endswith("(its light torque's above it already)")


def test_a_given_torque_is_kept(monkeypatch):
    """A design torque or coast design torque the basic file gives is kept, said."""
    calls = _patched(monkeypatch)
    coast = _coast()
    for basic in (SimpleNamespace(gives_design_torque=True, rating={}),
                  SimpleNamespace(gives_design_torque=False,
                                  rating={"coast_design_torque": DESIGN})):
        (outcome, cap), lines = _run(coast, basic=basic)
        assert outcome is coast and cap is _BEFORE and calls == []
        assert lines[-1].endswith("the design torque the basic file gives is kept")


def test_no_torque_that_holds_or_keeps_the_limit_leaves_it_as_it_was(monkeypatch):
    """Where the capacity search holds nowhere, nothing is lowered; where each lowered
    torque's own range still exceeds the limit (a stand-in whose LTE jumps just above the
    light torque), at most LTE_TRIES torques are tried, each lower, then nothing."""
    calls = _patched(monkeypatch, holds=False)
    coast = _coast()
    (outcome, cap), _ = _run(coast)
    assert outcome is coast and cap is _BEFORE and len(calls) == 1
    # 56 µrad at the light torque, 100 µrad from just above it: every range fails
    steep = ((18.4, 56.0), (18.5, 100.0), (122.7, 100.0))
    calls = _patched(monkeypatch, knots=steep)
    coast = _coast(knots=steep)
    (outcome, cap), lines = _run(coast)
    assert outcome is coast and cap is _BEFORE
    assert 1 <= len(calls) <= lte_torque.LTE_TRIES
    assert all(b < a for a, b in zip([DESIGN, *calls], calls, strict=False))
    assert "no coast design torque below 122.7 N m found" in lines[-1]


def test_the_coast_development_off_changes_nothing(monkeypatch):
    """coast_max_evaluations 0 (the coast development off): nothing analysed."""
    calls = _patched(monkeypatch)
    coast = _coast()
    off = DevelopmentTargets(coast_max_evaluations=0)
    (outcome, cap), lines = _run(coast, targets=off)
    assert outcome is coast and cap is _BEFORE and calls == [] and lines == []
