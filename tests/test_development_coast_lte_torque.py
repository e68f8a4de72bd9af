"""The coast design torque no higher than where the written coast bearing keeps the
verdict's LTE limit (:mod:`contact.optimize.development_coast_lte_torque`, issue 71).

Stand-ins: the coast flank's LTE p-p a piecewise-linear law of the torque through the
values two designs of benchmarks/data/unseen_designs were written with (``ltca
synthesize`` on main, 2026-11-29): the FH spiral bevel 12x27 narrow face (coast 39 / 74
µrad at 3.3 / 22.6 N m, 61.7 µrad at 16.17 N m between; its coast design torque set by
S_H,loc, the drive's 36.7 N m, light 5.5 N m) and the FM spiral bevel 13x17 at Σ 50° (56 /
90 µrad at 18.4 / 122.7 N m, 79.6 µrad at 87.93 N m; coast design torque the drive's). The
tests are the rule's choices — where it lowers, to which torque, what it refuses — against
the crossing computed by hand here, not numbers of a gear; the capacity search and the
range analysis are replaced by the law (clamped below its first knot).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from contact.optimize import development_coast_lte_torque as lte_torque
from contact.optimize import development_range_lte as drl
from contact.optimize.development_coast import CoastCapacity, CoastCheck
from contact.optimize.development_targets import DevelopmentTargets


@pytest.fixture(autouse=True)
def _aim_at_the_verdicts_limit(monkeypatch):
    """The rule's choices written at its aim of 60 µrad: the development's sampling margin
    below the verdict's limit (development_range_lte.development_lte_limit) set to 0 here;
    the margin is tests/test_development_lte_margin.py's."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)


#: the 12x27's coast (light, design) torque [N·m], the drive's light torque, its LTE law
TWELVE = {"light": 3.3, "design": 22.6, "drive_light": 5.5,
          "knots": ((3.3, 39.5), (16.17, 61.7), (22.6, 74.2))}

#: the 13x17's (its coast design torque the drive's)
THIRTEEN = {"light": 18.4, "design": 122.7, "drive_light": 18.4,
            "knots": ((18.4, 56.0), (87.93, 79.6), (122.7, 90.0))}

STATIC = 2400.0


def law(t: float, knots) -> float:
    """The stand-in LTE p-p [µrad] at ``t`` [N·m], linear between the knots."""
    ts, xs = zip(*knots, strict=True)
    return float(np.interp(t, ts, xs))


def _coast(d):
    best = SimpleNamespace(checked_full=True, values={"ellipse_length": 0.65},
                           metrics={"lte_peak_to_peak": [law(d["light"], d["knots"]),
                                                         law(d["design"], d["knots"])]})
    return SimpleNamespace(best=best, torques=(d["light"], d["design"]))


def _before(d, edge=float("nan")):
    check = CoastCheck(d["design"], 1500.0, STATIC, edge_peak=edge)
    return CoastCapacity(d["design"], d["design"], (check,), "", True)


def _patched(monkeypatch, d, holds=True, lower_to=None, edge=float("nan")):
    """The range analysis (light, middle, design torque) and the capacity search
    replaced by the law; returns the capacity search's start torques."""
    calls: list[float] = []
    share = d["light"] / d["design"]  # the coast light torque's share (flank_torques)

    def fake_range(e, setup, teeth, *a, **k):
        light, design = (float(t) for t in setup["torques"])
        ts = (light, 0.5 * (light + design), design)
        return ts, tuple(law(t, d["knots"]) for t in ts)

    def fake_capacity(case, basic, coast, targets, setup, start, root_stress, lower, say):
        calls.append(start)
        torque = start if lower_to is None else min(start, lower_to)
        best = SimpleNamespace(checked_full=True, values=dict(coast.best.values),
                               metrics={"lte_peak_to_peak": [law(share * torque, d["knots"]),
                                                             law(torque, d["knots"])]})
        check = CoastCheck(torque, 1400.0, STATIC, edge_peak=edge)
        reason = "" if torque == start else f"its peak at {start} N m"
        return (SimpleNamespace(best=best, torques=(share * torque, torque)),
                CoastCapacity(torque, start, (check,), reason, holds))

    monkeypatch.setattr(lte_torque, "range_lte", fake_range)
    monkeypatch.setattr(lte_torque, "coast_flank_capacity", fake_capacity)
    return calls


_DRIVE = SimpleNamespace(values={"path_angle": -60.0})
_BASIC = SimpleNamespace(gives_design_torque=False, rating={})


def _run(d, coast=None, cap=None, basic=_BASIC, targets=None):
    lines: list[str] = []
    coast = coast or _coast(d)
    cap = cap or _before(d)
    setup = {"torques": [d["drive_light"], 36.7]}  # the drive's light and design torque
    got = lte_torque.coast_lte_torque(None, basic, coast, cap, _DRIVE,
                                      targets or DevelopmentTargets(), setup, None, True,
                                      lines.append)
    return got, lines, coast, cap


def test_the_coast_design_torque_is_lowered_to_where_its_lte_keeps_60_urad(monkeypatch):
    """The 12x27: 39.5 / 56.15 / 74.2 µrad at 3.3 / 12.95 / 22.6 N m (the middle by the
    law, 39.5 + 9.65 / 12.87 × 22.2); the crossing of 60 µrad, linear between 12.95
    (56.15) and 22.6 (74.2), is 12.95 + 3.85 / 18.05 × 9.65 = 15.01 N m, written rounded
    down to 0.1 (15.0): above half the coast design torque (11.3) and the drive's light
    torque (5.5). Its own range (light 0.146 × 15.0 = 2.19 N m) keeps the limit, so it is
    written; line and reason say the LTE before and after."""
    calls = _patched(monkeypatch, TWELVE)
    (outcome, cap), lines, _, _ = _run(TWELVE)
    middle = 39.5 + (12.95 - 3.3) / (16.17 - 3.3) * 22.2
    assert middle == pytest.approx(56.15, abs=0.01)
    crossing = 12.95 + (60.0 - middle) / (74.2 - middle) * (22.6 - 12.95)
    assert crossing == pytest.approx(15.01, abs=0.01)
    assert calls == [pytest.approx(15.0)]
    assert cap.torque == pytest.approx(15.0) and cap.lowered and cap.holds
    assert cap.start == 22.6 and len(cap.checks) == 2  # the capacity's checks kept
    assert outcome.torques[1] == pytest.approx(15.0)
    assert max(outcome.best.metrics["lte_peak_to_peak"]) <= 60.0
    assert lines[-1].startswith("development: coast design torque 22.6 -> 15 N m")
    assert "39.5 / 56.1 / 74.2 urad at 3.3 / 12.95 / 22.6 N m" in cap.reason
    assert "none of its bearing steps kept 60 urad there" in cap.reason
    assert "at the coast design torque 15 N m" in cap.reason


def test_no_cut_below_half_the_coast_design_torque(monkeypatch):
    """The 13x17: 56 / 73.7 / 90 µrad at 18.4 / 70.55 / 122.7 N m (the middle 56 + 52.15
    / 69.53 × 23.6); the crossing 18.4 + 4 / 17.7 × 52.15 = 30.18 → 30.1 N m, 25 % of
    122.7: below half of it (61.35), so nothing is analysed or lowered (the lead's gate:
    an attention-level LTE does not cut a coast design torque below half), and the line
    says the crossing and its share (``ltca synthesize``'s finer range, 58.0 / 65.7 µrad
    at 44.48 / 53.17 N m, puts the 13x17's at 46.7 N m, 38 %: below the bound too)."""
    calls = _patched(monkeypatch, THIRTEEN)
    (outcome, cap), lines, coast, before = _run(THIRTEEN)
    assert outcome is coast and cap is before and calls == []
    assert "it keeps 60 urad up to 30.1 N m only, 25% of 122.7 N m" in lines[-1]
    assert "at or above 61.35 N m" in lines[-1]


def test_a_capacity_reason_before_is_kept_and_a_further_cut_said(monkeypatch):
    """A coast design torque set by its capacity keeps that reason first; where the
    capacity search at the crossing lowers it further (a criterion fails there), the
    torque written is the search's (above the floor) and its reason follows."""
    _patched(monkeypatch, TWELVE, lower_to=13.0)
    before = CoastCapacity(22.6, 36.7, (CoastCheck(22.6, 1572.0, STATIC),),
                           "S_H,loc 0.70 at 36.7 N m", True)
    (_outcome, cap), _, _, _ = _run(TWELVE, cap=before)
    assert cap.torque == 13.0 and cap.start == 36.7
    assert cap.reason.startswith("S_H,loc 0.70 at 36.7 N m; the torque up to which")
    assert cap.reason.endswith("its peak at 15.0 N m")


def test_edges_above_the_static_strength_at_the_lowered_torque(monkeypatch):
    """The lowered torque's counted edges above the static strength and higher than at
    the coast design torque before (the 20x24's 2488 MPa at 169.4 N m): not kept; where
    no higher than before (an edge the lower torque does not make worse), kept."""
    calls = _patched(monkeypatch, TWELVE, edge=2488.0)
    (outcome, cap), lines, coast, before = _run(TWELVE)
    assert outcome is coast and cap is before and len(calls) == 1
    assert "its edges peak 2488 MPa, above the static strength 2400 MPa" in lines[-1]
    (_outcome, cap), _, _, _ = _run(TWELVE, cap=_before(TWELVE, edge=2600.0))
    assert cap.torque == pytest.approx(15.0)


def test_within_the_limit_at_every_torque_nothing_is_analysed(monkeypatch):
    """A coast flank within 60 µrad over its range (the default case's, the 10x43's) is
    returned as it is, no capacity search run, nothing said."""
    flat = dict(TWELVE, knots=((3.3, 40.0), (22.6, 55.0)))
    calls = _patched(monkeypatch, flat)
    (outcome, cap), lines, coast, before = _run(flat)
    assert outcome is coast and cap is before and calls == [] and lines == []


def test_the_light_torques_lte_above_the_limit_lowers_nothing(monkeypatch):
    """Where the light torque's LTE exceeds 60 µrad already (the 20x24's 61 / 104 µrad)
    no lower torque keeps it: nothing analysed, said."""
    high = dict(TWELVE, knots=((3.3, 61.0), (22.6, 104.0)))
    calls = _patched(monkeypatch, high)
    (outcome, cap), lines, coast, before = _run(high)
    assert outcome is coast and cap is before and calls == []
    assert lines[-1].endswith("(its light torque's above it already)")


def test_a_given_torque_is_kept(monkeypatch):
    """A design torque or coast design torque the basic file gives is kept, said."""
    calls = _patched(monkeypatch, TWELVE)
    for basic in (SimpleNamespace(gives_design_torque=True, rating={}),
                  SimpleNamespace(gives_design_torque=False,
                                  rating={"coast_design_torque": 22.6})):
        (outcome, cap), lines, coast, before = _run(TWELVE, basic=basic)
        assert outcome is coast and cap is before and calls == []
        assert lines[-1].endswith("the design torque the basic file gives is kept")
    # the drive developed again in its LTE window gives its own torque: not a given one
    lines: list[str] = []
    got = lte_torque.coast_lte_torque(
        None, SimpleNamespace(gives_design_torque=True, rating={}), _coast(TWELVE),
        _before(TWELVE), _DRIVE, DevelopmentTargets(), {"torques": [5.5, 36.7]}, None, True,
        lines.append, own_torque=True)
    assert got[1].torque == pytest.approx(15.0) and calls == [pytest.approx(15.0)]


def test_no_torque_that_holds_leaves_it_and_a_failed_range_is_tried_again(monkeypatch):
    """Where the capacity search holds nowhere, nothing is lowered. Where the first
    lowered torque's own range still exceeds the limit (a stand-in whose LTE jumps from 58
    to 100 µrad between 12.95 and 13.0 N m: crossing 12.95 + 2 / 42 × 9.65 = 13.4 N m,
    100 µrad there), its torques join those the crossing is taken between (12.95 + 2 / 42 ×
    0.45 → 12.9 N m, within), each try lower, at most LTE_TRIES."""
    calls = _patched(monkeypatch, TWELVE, holds=False)
    (outcome, cap), _, coast, before = _run(TWELVE)
    assert outcome is coast and cap is before and len(calls) == 1
    # a coast root check refined at a torque not kept leaves no record in the setup
    monkeypatch.setattr(lte_torque, "coast_flank_capacity", lambda c, b, o, t, setup, *a:
                        (setup.update(fe_level_why="refined at 15.0 N m"), (o, None))[1])
    setup = {"torques": [5.5, 36.7], "fe_level_why": "the drive's"}
    lte_torque.coast_lte_torque(None, _BASIC, _coast(TWELVE), _before(TWELVE), _DRIVE,
                                DevelopmentTargets(), setup, None, True, print)
    assert setup["fe_level_why"] == "the drive's"
    steep = dict(TWELVE, knots=((3.3, 50.0), (12.95, 58.0), (13.0, 100.0), (22.6, 100.0)))
    calls = _patched(monkeypatch, steep)
    (outcome, cap), _, _, _ = _run(steep)
    assert calls == [pytest.approx(13.4), pytest.approx(12.9)]
    assert len(calls) <= lte_torque.LTE_TRIES
    assert cap.torque == pytest.approx(12.9)
    assert max(outcome.best.metrics["lte_peak_to_peak"]) <= 60.0


def test_the_coast_development_off_changes_nothing(monkeypatch):
    """coast_max_evaluations 0 (the coast development off): nothing analysed."""
    calls = _patched(monkeypatch, TWELVE)
    off = DevelopmentTargets(coast_max_evaluations=0)
    (outcome, cap), lines, coast, before = _run(TWELVE, targets=off)
    assert outcome is coast and cap is before and calls == [] and lines == []
