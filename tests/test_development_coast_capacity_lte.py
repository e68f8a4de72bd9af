"""The coast flank's LTE bought with its local pitting margin, within its capacity
(:mod:`contact.optimize.development_coast_capacity_lte`, issue 71).

Stand-in analyses whose laws are the coast flank of the face-hobbed spiral bevel 10x31
z0 3 of benchmarks/data/unseen_designs as measured with ``benchmarks/development_levers.py
--flank coast --from-case --check`` (docs/synthesis.md, "The face-hobbed spiral bevel
10×31, z0 3 … no coast step here" and "The coast LTE within the flank's capacity"): the
tests are the rule's choices, not numbers of a gear. The slow test synthesises the design
and checks its written coast flank as ``ltca run --flank coast`` does.
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.ltca.lte_range import lte_range_torques
from contact.optimize import development_coast_capacity_lte as cap
from contact.optimize.development_keep import pressure_raised
from contact.optimize.development_targets import DevelopmentTargets

#: the 10x31 z0 3's coast designs (ellipse, M's place, tip relief, root relief [µm]):
#: light-load pattern ends (toe, heel), LTE p-p (light, design) [µrad], flank peak at the
#: coast design torque [MPa], edge share at it [1] (as measured at 17.3 / 90.5 N m with
#: ``benchmarks/development_levers.py --flank coast --from-case --check``, 2026-11-27)
_TR, _RR = 10.0, 26.666666666666664
_DESIGNS = {
    (0.55, 0.0, _TR, _RR): ((0.12, 0.78), (49.4, 74.8), 1522.0, 0.016),
    (0.75, 0.0, _TR, _RR): ((0.03, 0.85), (44.4, 62.1), 1654.0, 0.011),
    (0.75, 0.0368, _TR, _RR): ((0.08, 0.90), (45.5, 61.2), 1564.0, 0.011),
    (0.75, 0.0368, _TR, 2 * _RR / 3): ((0.08, 0.90), (43.2, 55.1), 1852.0, 0.011),
    (0.75, 0.0368, 2 * _TR / 3, _RR): ((0.08, 0.88), (31.2, 55.2), 1529.0, 0.022),
    (0.75, 0.0368, 2 * _TR / 3, 2 * _RR / 3): ((0.08, 0.88), (29.9, 49.0), 1532.0, 0.021),
}
#: the coast design torque's local pitting bound (S_H,loc 1.01 at 1522 MPa, S_Hmin 1) and
#: the static strength [MPa]
_PITTING, _STATIC = 1537.0, 2400.0
_VALUES = {"path_angle": -45.0, "ellipse_length": 0.55, "tip_relief": _TR,
           "root_relief": _RR, "te_level": 10.0}


def _key(v):
    return tuple(round(float(v.get(k, 0.0)), 4) for k in
                 ("ellipse_length", "mean_point_shift", "tip_relief", "root_relief"))


#: the 10x31's coast torques [N m]
_TORQUES = (17.3, 90.5)


def _ten_by_31(designs=_DESIGNS, torques=_TORQUES, between=None):
    """The stand-in's law through ``designs``; its LTE p-p at torques other than its own
    two (``ltca run --flank coast``'s lte_range torques between them) linear between
    those two, or through ``between``'s values at the two torques between (by the
    design's key, as ``designs``')."""
    names = ("ellipse_length", "mean_point_shift", "tip_relief", "root_relief")
    table = {_key(dict(zip(names, k, strict=True))): v for k, v in designs.items()}
    inside = {_key(dict(zip(names, k, strict=True))): v for k, v in (between or {}).items()}
    grid = lte_range_torques(torques, torques[1])

    def fake(case, torques_asked, misalignment=None, options=None, teeth=None,
             pinion_key=(), flank="drive"):
        (toe, heel), lte, peak, edge, *edge_peak = table[_key(case)]
        m = _metrics(lte_peak_to_peak=list(lte), pressure_max_flank=[900.0, peak],
                     edge_load_share=[0.0, edge], pattern_toe_u=[toe, 0.0],
                     pattern_heel_u=[heel, 0.95], pattern_centre_u=[0.5 * (toe + heel)] * 2,
                     **({"edge_peak": [0.0, edge_peak[0]],
                         "edge_static_strength": [_STATIC, _STATIC]} if edge_peak else {}))
        ts = tuple(float(t) for t in torques_asked) or tuple(torques)
        if ts != tuple(torques):  # between the two torques
            curve = (lte[0], *inside[_key(case)], lte[1]) if _key(case) in inside else (
                np.interp(grid, torques, lte))
            m = {k: np.resize(v, len(ts)) for k, v in m.items()}
            m["lte_peak_to_peak"] = np.interp(ts, grid, curve)
        return m, (0.0, 1.0, 0.0, 1.0, _STATIC)
    return fake


def _start(monkeypatch, designs=_DESIGNS, torques=_TORQUES, between=None, values=_VALUES):
    """(targets, setup, the design as the check chose it, the designs analysed since:
    their keys, :func:`_key`, in a list :func:`~development_stand_ins.seen_designs`
    fills)."""
    seen, fake = seen_designs(_ten_by_31(designs, torques, between))
    targets = DevelopmentTargets(max_flank_pressure=_PITTING)
    targets, setup, chosen = stand_in(monkeypatch, fake, list(torques), targets=targets)
    start = dataclasses.replace(chosen(values), case=dict(values))
    seen.clear()
    return targets, setup, start, seen


def test_the_designs_prescriptions():
    """The longest ellipse (0.75, the bound); M's place giving the short end its clearance
    (0.04) and a node column: the 10x31's 0.03-0.85 moved 0.035 of the face to the heel;
    no further than centring it; a pattern with both clearances, or missing both, keeps its
    M; the lighter reliefs root × ⅔, tip × ⅔, both."""
    t = DevelopmentTargets()
    assert cap.longest_ellipse(_VALUES, t) == _VALUES | {"ellipse_length": 0.75}
    assert cap.longest_ellipse({"path_angle": -45.0}, t) is None

    def at(toe, heel, shift=0.0):
        return dataclasses.replace(
            _stand_in_eval(toe, heel), values=_VALUES | {"mean_point_shift": shift})

    assert cap.clearance_shift(at(0.03, 0.85), t) == pytest.approx(0.035 / 0.95)
    # the heel short: no further than centring (0.02 of the face), or its clearance back
    assert cap.clearance_shift(at(0.05, 0.99), t) == pytest.approx(-0.02 / 0.95)
    assert cap.clearance_shift(at(0.15, 0.98, 0.02), t) == pytest.approx(
        0.02 - 0.045 / 0.95)
    assert cap.clearance_shift(at(0.10, 0.90, 0.02), t) == 0.02
    assert cap.clearance_shift(at(0.03, 0.99), t) == 0.0
    got = cap.lighter_reliefs(_VALUES, t)
    assert [(d["tip_relief"], d["root_relief"]) for d in got] == [
        (_TR, pytest.approx(2 * _RR / 3)), (pytest.approx(2 * _TR / 3), _RR),
        (pytest.approx(2 * _TR / 3), pytest.approx(2 * _RR / 3))]
    assert cap.lighter_reliefs(_VALUES | {"tip_relief": 0.0, "root_relief": 0.0}, t) == []


def _stand_in_eval(toe, heel):
    from development_stand_ins import checked
    return checked(dict(_VALUES), _metrics(pattern_toe_u=[toe, 0.0],
                                           pattern_heel_u=[heel, 0.95]),
                   DevelopmentTargets(), 0.6)


def test_the_rule_keeps_a_peak_rise_within_the_static_strength(monkeypatch):
    """The 10x31: the ellipse 0.75 (62 µrad) and with M +0.037 (61 µrad) stay above 60;
    the lighter tip reliefs reach 55 / 49 µrad but put 2.2 / 2.1 % on the edges (a target
    met before: refused); the root relief × ⅔ reaches 55 µrad at 1852 MPa (+22 %) —
    above the pitting bound 1537 MPa, which the coast LTE steps' pressure rule refuses,
    within the static strength 2400 MPa: kept. Five designs analysed, each said; the one
    kept analysed between its torques too (ltca run --flank coast's lte_range: within 60
    µrad there)."""
    targets, setup, start, seen = _start(monkeypatch)
    lines = []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC)
    assert _key(got.values) == _key({"ellipse_length": 0.75, "mean_point_shift": 0.0368,
                                     "tip_relief": _TR, "root_relief": 2 * _RR / 3})
    assert got.stage == cap.STAGE
    keys = [_key(d) for d in seen]
    assert len(keys) == 6 and keys[2] == keys[3] == _key(got.values)
    assert pressure_raised(start, got, targets).startswith("pressure (1852 MPa above 1537")
    assert cap.capacity_kept(start, got, targets, 60.0, _STATIC) == ""
    refused = [s for s in lines if "not kept" in s]
    assert refused == ["  not kept: its LTE p-p 62 urad above 60",
                       "  not kept: its LTE p-p 61 urad above 60",
                       "  not kept: it misses edge", "  not kept: it misses edge"]


def test_the_rule_refuses_static_plastic_lte_and_lost_targets(monkeypatch):
    """Refused: a peak above the static strength, a plastic segment, an LTE still above
    the limit, a met target lost (the toe's clearance); nothing analysed where the design
    is within the limit at every torque or the static strength is unknown."""
    targets, setup, start, seen = _start(monkeypatch)
    refuse = cap.capacity_kept

    def variant(**over):
        from contact.optimize.development_targets import development_score
        m = _metrics(**({"lte_peak_to_peak": [39.0, 58.0], "pattern_toe_u": [0.12, 0.0],
                         "pattern_heel_u": [0.78, 0.95],
                         "pattern_centre_u": [0.45, 0.45]} | over))
        full = development_score(m, targets, centre_v=setup["centre_v"])
        return dataclasses.replace(start, metrics=m, full=full)

    assert refuse(start, variant(), targets, 60.0, _STATIC) == ""
    above = variant(pressure_max_flank=[900.0, 2450.0])
    assert "above the static strength 2400" in refuse(start, above, targets, 60.0, _STATIC)
    plastic = variant(plastic_share=[0.0, 0.004])
    assert "plastic segments carry 0.4 %" in refuse(start, plastic, targets, 60.0, _STATIC)
    loud = variant(lte_peak_to_peak=[39.0, 61.0])
    assert "LTE p-p 61 urad above 60" in refuse(start, loud, targets, 60.0, _STATIC)
    toe = variant(pattern_toe_u=[0.02, 0.0])
    assert refuse(start, toe, targets, 60.0, _STATIC) == "it misses toe"
    assert refuse(start, None, targets, 60.0, _STATIC) == "it could not be analysed"
    step = cap.checked_coast_capacity_lte
    assert step(start, targets, setup, None, print, lambda v: dict(v),
                static=float("nan")) is start
    assert seen == []
    # within the limit at its torques and between them: its range alone analysed
    quiet = {(0.55, 0.0, _TR, _RR): ((0.12, 0.78), (40.0, 55.0), 1522.0, 0.016)}
    targets, setup, start, seen = _start(monkeypatch, dict(_DESIGNS) | quiet,
                                         between={(0.55, 0.0, _TR, _RR): (50.0, 57.0)})
    assert step(start, targets, setup, None, print, lambda v: dict(v),
                static=_STATIC) is start
    assert seen and all(_key(s) == _key(_VALUES) for s in seen)


def test_no_design_within_the_limit_keeps_the_design(monkeypatch):
    """Where every design stays above 60 µrad, above the static strength or loses a
    target, the design is returned as it is."""
    worse = dict(_DESIGNS) | {(0.75, 0.0368, _TR, 2 * _RR / 3):
                              ((0.08, 0.90), (43.2, 55.1), 2500.0, 0.011)}
    targets, setup, start, seen = _start(monkeypatch, worse)
    lines, near = [], []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC, near=near)
    assert got is start
    assert len(seen) == 5
    assert "above the static strength 2400 MPa" in lines[5]
    # the designs refused for their LTE alone (M moved: 61 µrad), not the longest ellipse
    # (62 µrad, the toe's clearance lost), one above the static strength or off a met
    # target (the edges): the candidates of a lowered coast design torque
    assert [max(e.metrics["lte_peak_to_peak"]) for e in near] == [61.2]


def test_the_coast_design_torque_is_searched_again_on_the_bearing_kept(monkeypatch):
    """coast_torque_that_holds: on the bearing the step kept (peak 1778 MPa, S_H,loc 0.91
    at the coast design torque 90.5 N m), the coast capacity search runs again from 90.5
    N m with lowering allowed (the local pitting safety among its criteria) and its torque
    is written where the LTE p-p is within 60 urad there (the 10x31 z0 3: 81.7 N m, S_H,loc
    1.10, 43.6 / 54.8 urad), its reason naming the search and the bound; where the LTE
    there is above 60 urad, or no torque holds, None (the design before the step is
    written); where nothing fails at 90.5 N m, its torque and reason as they were.
    Stand-ins for the search (no LTCA), numbers as measured (``ltca run --flank coast``'s
    analysis of the written case, 2026-11-27)."""
    from types import SimpleNamespace

    from contact.optimize.development_coast import CoastCapacity, CoastCheck

    before = CoastCapacity(90.5, 115.4, (CoastCheck(115.4, 1700.0, _STATIC),),
                           "at 115.4 N m local pitting safety ...", True)
    kept = SimpleNamespace(torques=(17.3, 90.5), best=object())
    calls = []

    def search(lte, found):
        def fake(case, basic, coast, targets, setup, start, root_stress, lower, say):
            calls.append((start, root_stress, lower))
            best = SimpleNamespace(metrics={"lte_peak_to_peak": lte})
            return SimpleNamespace(torques=(17.3, found.torque if found else 90.5),
                                   best=best), found
        monkeypatch.setattr(cap, "coast_flank_capacity", fake)

    bad = CoastCheck(90.5, 1778.0, _STATIC, pitting_safety=0.912, s_h_min=1.0)
    ok = CoastCheck(81.7, 1477.0, _STATIC, pitting_safety=1.097, s_h_min=1.0)
    lowered = CoastCapacity(81.7, 90.5, (bad, ok), "at 90.5 N m local pitting safety "
                            "S_H,loc 0.91 (pinion) below S_Hmin 1; ... the largest that "
                            "holds 81.7 N m", True)
    search([43.6, 54.8], lowered)
    lines = []
    got = cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                      True, lines.append)
    assert calls == [(90.5, True, True)]
    outcome, written = got
    assert outcome.torques == (17.3, 81.7)
    assert written.torque == 81.7 and written.start == 115.4 and written.lowered
    assert written.holds and written.checks == (*before.checks, bad, ok)
    assert written.reason.startswith(before.reason + "; then a coast bearing whose LTE")
    assert ("searched again on it, set by its local pitting safety: at 90.5"
            in written.reason and written.reason.endswith("; LTE p-p 55 urad there"))
    assert lines == ["development: coast design torque 90.5 -> 81.7 N m on the bearing "
                     "whose LTE p-p is 55 urad there, set by its local pitting safety"]
    # its LTE above the limit at the torque that holds: the step's design not written
    search([43.6, 61.0], lowered)
    lines.clear()
    assert cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None
    assert "its LTE p-p 61 urad is above 60 urad" in lines[-1]
    # no torque holds, or the search failed
    search([43.6, 54.8], dataclasses.replace(lowered, holds=False))
    assert cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None
    search([43.6, 54.8], None)
    assert cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None
    # nothing fails at 90.5 N m: the torque and the reason as they were
    search([43.6, 54.8], CoastCapacity(90.5, 90.5, (ok,), "", True))
    outcome, written = cap.coast_torque_that_holds(None, None, kept, before,
                                                   DevelopmentTargets(), {}, True, print)
    assert written is before and outcome.torques == (17.3, 90.5)


def test_the_coast_design_torque_is_lowered_to_where_its_lte_holds(monkeypatch):
    """coast_torque_that_holds on a bearing that holds at the coast design torque but
    stays above 60 µrad there (the face-hobbed spiral bevel 20x24 at Σ 100°'s nearest
    coast bearing: 38 / 71 µrad at 90.4 / 603.3 N m, the coast torque the drive's): the
    coast design torque lowered to the crossing of 60 µrad, linear between the torques
    analysed (90.4 + 22/33 × 512.9 = 432.3 N m), the capacity searched from there and
    written where its LTE keeps the limit; its reason says so. A stand-in LTE linear in
    the torque (the test is the rule, not the gear). Before the fix: None."""
    from types import SimpleNamespace

    from contact.optimize.development_coast import CoastCapacity, CoastCheck

    def lte_at(t):
        return 38.0 + 33.0 * (t - 90.4) / (603.3 - 90.4)

    calls = []

    def fake(case, basic, coast, targets, setup, start, root_stress, lower, say):
        calls.append(start)
        light = 0.15 * start
        best = SimpleNamespace(metrics={"lte_peak_to_peak": [lte_at(90.4), lte_at(start)]})
        found = CoastCapacity(start, start, (CoastCheck(start, 1400.0, _STATIC),), "", True)
        return SimpleNamespace(torques=(light, start), best=best), found

    monkeypatch.setattr(cap, "coast_flank_capacity", fake)
    before = CoastCapacity(603.3, 603.3, (CoastCheck(603.3, 1370.0, _STATIC),), "", True)
    kept = SimpleNamespace(torques=(90.4, 603.3), best=object())
    lines = []
    got = cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                      True, lines.append)
    assert got is not None
    outcome, written = got
    assert calls == [603.3, 432.3]
    assert written.torque == pytest.approx(432.3) and written.lowered and written.holds
    assert max(outcome.best.metrics["lte_peak_to_peak"]) <= 60.0
    assert "within 60 urad up to 432.3 N m" in written.reason
    assert lines[-1].endswith("set by its LTE p-p within 60 urad")
    # above the limit at the light torque already: no torque keeps it, None
    calls.clear()
    monkeypatch.setattr(cap, "coast_flank_capacity", lambda *a: (SimpleNamespace(
        torques=(90.4, 603.3), best=SimpleNamespace(
            metrics={"lte_peak_to_peak": [61.0, 104.0]})), before))
    assert cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None
    # a coast design torque the basic file gives is kept (as the drive's lte_capacity)
    monkeypatch.setattr(cap, "coast_flank_capacity", fake)
    given = SimpleNamespace(gives_design_torque=False,
                            rating={"coast_design_torque": 603.3})
    assert cap.coast_torque_that_holds(None, given, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None


def test_the_lighter_reliefs_on_the_design_where_the_longest_ellipse_loses_a_target(
        monkeypatch):
    """Where the longest ellipse's pattern runs to both ends (0.00-0.98 of the face, the
    20x24 at Σ 100°: no M's place gives both clearances back), the lighter reliefs are
    tried on the design itself, not on the ellipse that lost the toe and heel; those
    refused for their LTE alone are the candidates of a lowered coast design torque."""
    designs = {
        (0.55, 0.0, _TR, _RR): ((0.12, 0.78), (61.3, 104.5), 1370.0, 0.016),
        (0.75, 0.0, _TR, _RR): ((0.00, 0.98), (53.0, 87.0), 1500.0, 0.016),
        (0.55, 0.0, _TR, 2 * _RR / 3): ((0.12, 0.78), (58.0, 93.0), 1450.0, 0.016),
        (0.55, 0.0, 2 * _TR / 3, _RR): ((0.12, 0.78), (33.0, 109.0), 1500.0, 0.016),
        (0.55, 0.0, 2 * _TR / 3, 2 * _RR / 3): ((0.12, 0.78), (32.0, 91.0), 1620.0, 0.016),
    }
    targets, setup, start, seen = _start(monkeypatch, designs)
    near = []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, print,
                                         lambda v: dict(v), static=_STATIC, near=near)
    assert got is start
    assert [_key(d)[0] for d in seen] == [0.75, 0.55, 0.55, 0.55]
    assert sorted(max(e.metrics["lte_peak_to_peak"]) for e in near) == [91.0, 93.0, 109.0]


#: the face-hobbed spiral bevel 20x24 at Σ 100° remedied (b2 24 -> 33.6 mm, ``ltca
#: synthesize --apply-remedy``, 2026-11-27): its coast flank at 135.2 / 834.6 N m before
#: the step (ellipse 0.55, tip / root relief 15 / 40 µm; 64 µrad at the light torque),
#: the longest ellipse (46 / 36 µrad, its pattern 0.00-0.98 of the face: toe and heel
#: lost), the lighter tip relief 10 µm the step kept (44.1 / 54.4 µrad at its torques and
#: 80.8 / 67.5 at 368.3 / 601.5 N m between them, as ``ltca run --flank coast`` judged the
#: written case); the lighter root relief and both reliefs as the law's (the test is the
#: rule's choice)
_TR20, _RR20 = 15.0, 40.0
_TWENTY = {
    (0.55, 0.0, _TR20, _RR20): ((0.12, 0.78), (64.0, 59.0), 1370.0, 0.016),
    (0.75, 0.0, _TR20, _RR20): ((0.00, 0.98), (46.0, 36.0), 1500.0, 0.016),
    (0.55, 0.0, _TR20, 2 * _RR20 / 3): ((0.12, 0.78), (61.0, 57.0), 1450.0, 0.016),
    (0.55, 0.0, 2 * _TR20 / 3, _RR20): ((0.12, 0.78), (44.1, 54.4), 1563.0, 0.016),
    (0.55, 0.0, 2 * _TR20 / 3, 2 * _RR20 / 3): ((0.12, 0.78), (42.0, 52.0), 1650.0, 0.016),
}
_TWENTY_BETWEEN = {(0.55, 0.0, 2 * _TR20 / 3, _RR20): (80.8, 67.5),
                   (0.55, 0.0, 2 * _TR20 / 3, 2 * _RR20 / 3): (58.0, 55.0)}
_TWENTY_VALUES = _VALUES | {"tip_relief": _TR20, "root_relief": _RR20}


def test_a_design_above_the_limit_between_its_torques_is_not_kept(monkeypatch):
    """The 20x24's coast: the lighter tip relief, 44 / 54 µrad at its torques, keeps the
    rule there (the least peak of those that do, 1563 MPa: the design written before) but
    peaks at 80.8 µrad at 368.3 N m between them, as ``ltca run --flank coast`` judges it:
    refused (said), and a candidate of a lowered coast design torque (its LTE alone);
    both lighter reliefs, 58 µrad at most over the range, are kept at their higher peak
    (1650 MPa). Without them, nothing is kept."""
    targets, setup, start, seen = _start(monkeypatch, _TWENTY, (135.2, 834.6),
                                         _TWENTY_BETWEEN, _TWENTY_VALUES)
    lines, near = [], []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC, near=near)
    tip = _key(_TWENTY_VALUES | {"tip_relief": 2 * _TR20 / 3})
    both = _key(_TWENTY_VALUES | {"tip_relief": 2 * _TR20 / 3, "root_relief": 2 * _RR20 / 3})
    assert _key(got.values) == both
    assert "  not kept: its LTE p-p 80.8 urad at 368.3 N m, between the torques, above 60" \
        in lines
    assert tip in [_key(e.values) for e in near]
    # the designs at their torques; the two within the limit there between them too
    # (the tip relief's crossing of 60 µrad bisected twice, as ltca run's lte_range)
    keys = [_key(d) for d in seen]
    assert keys.count(tip) == 4 and keys.count(both) == 2
    # the LTE over the range said with what the kept design gave up
    from types import SimpleNamespace

    from contact.optimize.development_coast import CoastCheck
    final = CoastCheck(834.6, 1370.0, _STATIC, pitting_safety=1.0, s_h_min=1.0)
    text = cap.capacity_text(got, SimpleNamespace(final=final), 834.6,
                             between=cap.coast_range_peak(got, setup, None))
    assert text.startswith("LTE p-p 58 urad at its torques and between them within 60 urad")
    # no design within the limit over the range: the design as it was
    targets, setup, start, seen = _start(
        monkeypatch, _TWENTY, (135.2, 834.6),
        _TWENTY_BETWEEN | {(0.55, 0.0, 2 * _TR20 / 3, 2 * _RR20 / 3): (75.0, 66.0)},
        _TWENTY_VALUES)
    assert cap.checked_coast_capacity_lte(start, targets, setup, None, print,
                                          lambda v: dict(v), static=_STATIC) is start


#: the face-hobbed spiral bevel 13x31 z0 7 (benchmarks/data/unseen_designs, round 21, every
#: default; docs/own_gear_set.md "Round 21"): its coast flank at 44.1 / 294 N m before the
#: step (path -45°, ellipse 0.55, tip / root relief 15 / 40 µm), the longest ellipse and
#: its lighter reliefs (toe, heel; LTE light / design [µrad]; flank peak [MPa]; edge share
#: at 294 N m; edge peak there [MPa]), as the development's check measured them and
#: ``benchmarks/development_levers.py --flank coast --from-case --check --at`` at the
#: torques between (the flank peak of the longest ellipse alone, refused on its LTE, the
#: law's: not measured)
_TR13, _RR13 = 15.0, 40.0
_THIRTEEN = {
    (0.55, 0.0, _TR13, _RR13): ((0.12, 0.85), (63.7, 76.7), 1642.0, 0.018, 4455.0),
    (0.75, 0.0, _TR13, _RR13): ((0.05, 0.95), (45.0, 65.0), 1640.0, 0.017, 5029.0),
    (0.75, 0.0, _TR13, 2 * _RR13 / 3): ((0.05, 0.95), (43.0, 57.3), 1618.0, 0.017, 4690.0),
    (0.75, 0.0, 2 * _TR13 / 3, _RR13): ((0.05, 0.93), (38.7, 56.7), 1740.0, 0.030, 4908.0),
    (0.75, 0.0, 2 * _TR13 / 3, 2 * _RR13 / 3): ((0.08, 0.93), (37.0, 49.2), 1582.0, 0.029,
                                                 4421.0),
}
_THIRTEEN_BETWEEN = {(0.75, 0.0, _TR13, 2 * _RR13 / 3): (65.0, 62.0),
                     (0.75, 0.0, 2 * _TR13 / 3, _RR13): (54.0, 58.0),
                     (0.75, 0.0, 2 * _TR13 / 3, 2 * _RR13 / 3): (53.0, 53.0)}
_THIRTEEN_VALUES = _VALUES | {"tip_relief": _TR13, "root_relief": _RR13}


def test_the_edge_share_given_up_where_the_edges_are_no_harder_loaded(monkeypatch):
    """The 13x31's coast: the longest ellipse with both lighter reliefs keeps 37 / 49 µrad
    at its torques and 53 µrad between them (the design 64 / 77, 80 between) but puts 2.9
    % of the design torque on the edges, above the 2 % target the design met (1.8 %), at
    an edge peak of 4421 MPa against the design's 4455: its edges no harder loaded, kept
    (its flank peak 1582 MPa, lower too). The lighter tip relief alone (3.0 %) peaks at
    4908 MPa on its edges: refused, its edge numbers said. Without the edge peaks (no
    material named) the edge share target is kept as before: nothing kept."""
    targets, setup, start, _seen = _start(monkeypatch, _THIRTEEN, (44.1, 294.0),
                                          _THIRTEEN_BETWEEN, _THIRTEEN_VALUES)
    targets = dataclasses.replace(targets, max_flank_pressure=1649.0)
    lines = []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC)
    both = _key(_THIRTEEN_VALUES | {"ellipse_length": 0.75, "tip_relief": 2 * _TR13 / 3,
                                    "root_relief": 2 * _RR13 / 3})
    assert _key(got.values) == both
    assert got.metrics["edge_load_share"][-1] > targets.max_edge_share >= \
        start.metrics["edge_load_share"][-1]
    assert "edge" in cap.lost_targets(start, got)
    assert not cap.edges_harder(start, got)
    assert cap.capacity_kept(start, got, targets, 60.0, _STATIC) == ""
    refused = [s for s in lines if "not kept" in s]
    assert refused == [
        "  not kept: its LTE p-p 65 urad above 60",
        "  not kept: its LTE p-p 65.0 urad at 127.4 N m, between the torques, above 60",
        "  not kept: it misses edge (3.0 % of the torque on the edges, its edge peak 4908 "
        "MPa above the design's 4455)"]
    # the same designs without their edge peaks: the edge share target kept
    plain = {k: v[:4] for k, v in _THIRTEEN.items()}
    targets, setup, start, _seen = _start(monkeypatch, plain, (44.1, 294.0),
                                          _THIRTEEN_BETWEEN, _THIRTEEN_VALUES)
    assert cap.edges_harder(start, start)
    assert cap.checked_coast_capacity_lte(start, targets, setup, None, print,
                                          lambda v: dict(v), static=_STATIC) is start


@pytest.mark.slow
def test_fh_spiral_bevel_10x31_coast_lte_within_60_urad():
    """The face-hobbed spiral bevel 10x31 z0 3 (benchmarks/data/unseen_designs) from its
    basic file with every default: the written case's coast flank, analysed as ``ltca run
    --flank coast`` does at its light and coast design torque (the development's last
    coast check), has LTE p-p within 60 µrad at both, no plastic segment, its flank peak
    within the static strength, and its coast design torque is the capacity the last
    search found on the bearing written (the text's last "the largest that holds").

    Measured 2026-11-29 on main ``aa9b8ac0`` (88.7 s CPU, FE cache warm): the drive
    lowered to its local pitting capacity 102.2 N m; the coast capacity at the first coast
    bearing 88.4 N m (S_H,loc 0.94 at 102.2), the coast developed again at 88.4 N m (its
    long bearing, LTE 52/75 µrad there) reads S_H,loc 0.76 → 66.4 N m, where the lighter
    tip relief keeps 47/59 µrad (flank peak 1412 MPa, edges 0.5 %). Keeping the first
    coast bearing instead holds 88.4 N m but at LTE 73/91 µrad (tried in session 31):
    the criterion "LTE p-p ≤ 60 µrad at every torque" (issue 71) is what lowers it. The
    earlier anchor of this test, 90.7 N m at a drive of 139.5 N m (2026-11-27, branch
    unseenb81), predates the drive's pitting cut (local pitting capacity, issue 71 item 2)."""
    from pathlib import Path

    from contact.optimize.development import develop
    from geometry.synthesis.basic_design import load_basic

    root = Path(__file__).resolve().parents[1]
    basic = load_basic(root / "benchmarks" / "data" / "unseen_designs"
                       / "fh_spiral_bevel_10x31_z03.toml")
    result = develop(basic)
    coast = result.coast
    assert coast is not None and result.coast_best.stage == cap.STAGE
    assert max(coast["lte_peak_to_peak"]) <= 60.0
    assert max(coast["plastic_share"]) == 0.0
    assert coast["pressure_max_flank"][-1] <= result.pressure_limit
    # the coast design torque is the last capacity search's "largest that holds" (to the
    # text's 0.1 N m rounding), and the coast flank carries no more than the drive's
    assert result.coast_capacity == result.coast_torques[1]
    held = re.findall(r"the largest that holds ([0-9.]+) N m", result.coast_capacity_text)
    assert held and float(held[-1]) == pytest.approx(result.coast_torques[1], abs=0.05)
    assert result.coast_torques[1] <= result.torque[1]


def test_a_coast_lte_above_the_limit_between_its_torques_alone_is_acted_on(monkeypatch):
    """Within 60 urad at its two torques, above it between them (the FH spiral bevel 25x31
    of m_et 9.52 mm of benchmarks/data/unseen_designs: 59 / 53 urad at 567 / 3780 N m, 64 /
    69 urad between, round 21b): the step runs on the range's peak and keeps the design
    within the limit over the range (the root relief x 2/3 on the longest ellipse, 43.2 /
    55.1 urad, linear between in the stand-in); the numbers are the stand-in's, exact."""
    quiet = {(0.55, 0.0, _TR, _RR): ((0.12, 0.78), (45.0, 55.0), 1522.0, 0.016)}
    targets, setup, start, _seen = _start(monkeypatch, dict(_DESIGNS) | quiet,
                                          between={(0.55, 0.0, _TR, _RR): (64.0, 69.0)})
    assert cap.coast_largest(start, setup, None) == pytest.approx(69.0)
    assert cap.coast_largest(start, setup, None, limit=50.0) == pytest.approx(55.0)
    lines: list[str] = []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC)
    assert _key(got.values) == _key(_VALUES | {"ellipse_length": 0.75,
                                               "mean_point_shift": 0.0368,
                                               "root_relief": 2 * _RR / 3})
    assert cap.coast_range_peak(got, setup, None)[0] == pytest.approx(55.1)
    assert any("not kept: its LTE p-p 62 urad above 60" in s for s in lines)


def test_the_nearest_coast_bearing_is_not_said_lowered_before_its_search(monkeypatch):
    """Where no coast bearing keeps 60 µrad at the coast design torque, the nearest's line
    says its torque is searched again, not that it was lowered: on the 14x21 of
    docs/own_gear_set.md the nearest (123 µrad at 150.5 N m, 110 µrad at its light
    torque already) was said "lowered, keeps the limit", yet no lower torque keeps 60 µrad
    there and the design before the step was written. Stand-ins for the capacity search
    (no LTCA): its three outcomes each say what was done after the nearest's line."""
    from types import SimpleNamespace

    from contact.optimize.development_coast import CoastCapacity, CoastCheck

    text = cap.nearest_text(150.5, 123.2, 60.0)
    assert text.startswith("development: coast flank: no bearing within 60 urad at "
                           "150.5 N m; the nearest (LTE p-p 123 urad) written")
    assert "lowered, keeps" not in text
    assert "else the coast design before this step kept" in text
    before = CoastCapacity(150.5, 150.5, (CoastCheck(150.5, 1500.0, _STATIC),), "", True)
    kept = SimpleNamespace(torques=(22.6, 150.5), best=object())

    def holds_at(lte, found):
        monkeypatch.setattr(cap, "coast_flank_capacity", lambda *a: (SimpleNamespace(
            torques=(22.6, found.torque), best=SimpleNamespace(
                metrics={"lte_peak_to_peak": lte})), found))

    # the 14x21: above the limit at the light torque, no lower torque keeps it: None
    # (development.develop writes the coast design before the step), said so
    holds_at([110.0, 123.2], before)
    lines = []
    assert cap.coast_torque_that_holds(None, None, kept, before, DevelopmentTargets(), {},
                                       True, lines.append) is None
    assert lines[-1].endswith("its LTE p-p 123 urad is above 60 urad; the coast design "
                              "before the step written")
    # within the limit at the torque it was checked at (re-read as written): kept, said so
    holds_at([44.0, 58.0], before)
    lines.clear()
    outcome, written = cap.coast_torque_that_holds(None, None, kept, before,
                                                   DevelopmentTargets(), {}, True,
                                                   lines.append)
    assert written is before and outcome.torques == (22.6, 150.5)
    assert lines == ["development: coast design torque 150.5 N m kept on the bearing whose "
                     "LTE p-p is 58 urad there (within 60 urad)"]
