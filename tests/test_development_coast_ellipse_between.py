"""The coast flank's ellipse between its design's and the longest, its pattern's height kept
(:mod:`contact.optimize.development_coast_ellipse_between`, issue 71), and the coast
capacity LTE step trying it (:func:`contact.optimize.development_coast_capacity_lte.
checked_coast_capacity_lte`).

The stand-in's law is the coast flank of the face-hobbed spiral bevel 25x31 of m_et 9.52 mm
(benchmarks/data/unseen_designs/fh_spiral_bevel_25x31_m9p5.toml, its coast design torque
the given 3780 N m) as ``ltca synthesize`` wrote it and as measured with
``benchmarks/development_levers.py --flank coast --from-case --check --at`` (2026-11-28;
docs/synthesis.md, "The coast ellipse between, its height kept"): the tests check the
rule's choices, not numbers of a gear.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.ltca.lte_range import lte_range_torques
from contact.optimize import development_coast_capacity_lte as cap
from contact.optimize import development_coast_ellipse_between as eb
from contact.optimize.development_stages import HEIGHT_SLOPE, HEIGHT_SLOPE_MIN
from contact.optimize.development_targets import DevelopmentTargets

#: the 25x31's coast torques [N m] and the static strength [MPa]
_TORQUES, _STATIC = (567.0, 3780.0), 2400.0
_TR, _RR = 20.0, 26.666666666666664
_VALUES = {"path_angle": -58.75, "ellipse_length": 0.4, "tip_relief": _TR,
           "root_relief": _RR, "blade_angle_change": 0.0, "te_level": 10.0}
#: the depth band's centre the written case's coast flank was judged at (0.556 ± 0.08)
_CENTRE = 0.556

#: (ellipse, tip relief, root relief [µm]) at the blade angle 0: light-load pattern ends
#: (toe, heel), LTE p-p (light, design) [µrad], its largest at the two lte_range torques
#: between (1638, 2709 N m) [µrad], light-load centre v, flank peak at 3780 N m [MPa], edge
#: and plastic share there [1]. Measured: the design, the ellipses 0.45 / 0.5 / 0.55 (their
#: LTE between at 1370-1638 N m, the larger of the two, and at 2709), the longest ellipse
#: and the lighter reliefs as the development's check said them (their LTE between not
#: analysed: the law's)
_LAW = {
    (0.4, _TR, _RR): ((0.20, 0.83), (59.3, 52.6), (69.0, 61.0), 0.630, 1158.0, 0.020, 0.0),
    (0.45, _TR, _RR): ((0.18, 0.88), (54.6, 45.9), (64.0, 53.0), 0.640, 1149.0, 0.017, 0.0),
    (0.5, _TR, _RR): ((0.15, 0.90), (47.2, 41.2), (59.0, 48.0), 0.640, 1153.0, 0.016, 0.0),
    (0.55, _TR, _RR): ((0.12, 0.93), (37.7, 37.6), (54.0, 45.0), 0.650, 1152.0, 0.016, 0.0),
    (0.75, _TR, _RR): ((0.00, 1.00), (23.0, 31.0), (40.0, 35.0), 0.650, 1300.0, 0.017,
                       0.0051),
    (0.4, _TR, 2 * _RR / 3): ((0.20, 0.83), (57.0, 52.0), (60.0, 55.0), 0.650, 1200.0,
                              0.025, 0.012),
    (0.4, 2 * _TR / 3, _RR): ((0.20, 0.80), (46.0, 47.0), (50.0, 48.0), 0.590, 1250.0,
                              0.026, 0.030),
    (0.4, 2 * _TR / 3, 2 * _RR / 3): ((0.20, 0.80), (44.0, 46.0), (48.0, 47.0), 0.610,
                                      1260.0, 0.032, 0.030),
}
#: d(centre v)/d(blade-angle change) [1/deg] of the law: the ellipse 0.5 at 0 / −0.02 /
#: −0.04° measured v 0.64 / 0.63 / 0.61
_SLOPE = 0.75


def _key(v):
    return (round(float(v["ellipse_length"]), 4), round(float(v["tip_relief"]), 4),
            round(float(v["root_relief"]), 4))


def _law(designs=_LAW):
    table = {_key({"ellipse_length": k[0], "tip_relief": k[1], "root_relief": k[2]}): v
             for k, v in designs.items()}
    grid = lte_range_torques(_TORQUES, _TORQUES[1])

    def fake(case, torques_asked, misalignment=None, options=None, teeth=None,
             pinion_key=(), flank="drive"):
        (toe, heel), lte, inside, v0, peak, edge, plastic = table[_key(case)]
        v = v0 + _SLOPE * float(case.get("blade_angle_change", 0.0))
        m = _metrics(lte_peak_to_peak=list(lte), pressure_max_flank=[900.0, peak],
                     edge_load_share=[0.0, edge], plastic_share=[0.0, plastic],
                     pattern_toe_u=[toe, 0.0], pattern_heel_u=[heel, 0.95],
                     pattern_centre_u=[0.5 * (toe + heel)] * 2, pattern_centre_v=[v, v])
        ts = tuple(float(t) for t in torques_asked) or tuple(_TORQUES)
        if ts != tuple(_TORQUES):  # ltca run --flank coast's lte_range torques between
            m = {k: np.resize(x, len(ts)) for k, x in m.items()}
            m["lte_peak_to_peak"] = np.interp(ts, grid, (lte[0], *inside, lte[1]))
        return m, (0.0, 1.0, 0.0, 1.0, _STATIC)
    return fake


def _start(monkeypatch, designs=_LAW):
    seen, fake = seen_designs(_law(designs))
    targets, setup, chosen = stand_in(monkeypatch, fake, list(_TORQUES), centre_v=_CENTRE)
    start = dataclasses.replace(chosen(_VALUES), case=dict(_VALUES))
    seen.clear()
    return targets, setup, start, seen


def test_the_ellipses_between():
    """0.05 of the face at a time from the design's, strictly below the longest (the bound
    0.75, the step's first design): 0.4 → 0.45 / 0.5 / 0.55; 0.65 → 0.7 alone; none where
    the ellipse is not varied."""
    t = DevelopmentTargets()
    got = [d["ellipse_length"] for d in eb.ellipses_between(_VALUES, t)]
    assert got == [0.45, 0.5, 0.55]
    assert [d["ellipse_length"] for d in eb.ellipses_between(
        _VALUES | {"ellipse_length": 0.65}, t)] == [0.7]
    assert eb.ellipses_between(_VALUES | {"ellipse_length": 0.75}, t) == []
    assert eb.ellipses_between({"path_angle": -45.0}, t) == []
    # every other prescription kept
    assert all(d | {"ellipse_length": 0.4} == _VALUES for d in eb.ellipses_between(_VALUES, t))


def test_the_height_slope_and_the_blade_angle_that_recentres():
    """The secant of the last two points of different blade angle (0.64 → 0.63 over
    −0.02°: 0.5 /deg), floored at HEIGHT_SLOPE_MIN; HEIGHT_SLOPE with one point. The
    blade angle moves by (aim − v) / slope within its bounds: v 0.64 to 0.63 at 0.28 /deg,
    −0.0357°; none where the blade angle is not varied or the bound stops it."""
    assert eb.height_slope([(0.0, 0.64)]) == HEIGHT_SLOPE
    assert eb.height_slope([(0.0, 0.64), (-0.02, 0.63)]) == pytest.approx(0.5)
    assert eb.height_slope([(0.0, 0.64), (-0.02, 0.66)]) == HEIGHT_SLOPE_MIN
    assert eb.height_slope([(0.0, 0.64), (0.0, 0.63)]) == HEIGHT_SLOPE
    t = DevelopmentTargets()
    got = eb.recentred(_VALUES, 0.64, 0.63, 0.28, t)
    assert got["blade_angle_change"] == pytest.approx(-0.01 / 0.28, abs=1e-4)
    assert got | {"blade_angle_change": 0.0} == _VALUES
    lo, hi = t.variables["blade_angle_change"]
    assert eb.recentred(_VALUES, 0.64, 0.64 - 0.28 * (1.0 - lo), 0.28, t)[
        "blade_angle_change"] == lo
    assert eb.recentred(_VALUES | {"blade_angle_change": hi}, 0.5, 0.6, 0.28, t) is None
    assert eb.recentred({"ellipse_length": 0.4}, 0.64, 0.63, 0.28, t) is None
    assert eb.recentred(_VALUES, float("nan"), 0.63, 0.28, t) is None


def test_the_25x31_coast_keeps_the_ellipse_between_recentred(monkeypatch):
    """The 25x31's coast (59 / 53 µrad at 567 / 3780 N m, 69 between): the longest ellipse
    (23 / 31 µrad, 0.5 % plastic) and the lighter reliefs (1.2-3.0 % plastic) refused as
    before; then the ellipse 0.45 (64 µrad between; its centre v 0.64 off the band the
    design met, re-centred: still 64), the ellipse 0.5 (59 µrad between, v 0.64 lost) and
    re-centred by the blade angle at the default slope (−0.0357°, v 0.613 in the law) —
    kept: within 60 µrad over the range, no target the design met lost, its peak lower."""
    targets, setup, start, seen = _start(monkeypatch)
    assert cap.coast_largest(start, setup, None) == pytest.approx(69.0)
    lines: list[str] = []
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, lines.append,
                                         lambda v: dict(v), static=_STATIC)
    assert _key(got.values) == _key(_VALUES | {"ellipse_length": 0.5})
    assert got.values["blade_angle_change"] == pytest.approx(-0.01 / HEIGHT_SLOPE, abs=1e-4)
    assert cap.coast_range_peak(got, setup, None)[0] == pytest.approx(59.0)
    assert cap.capacity_kept(start, got, targets, 60.0, _STATIC) == ""
    # each design once at its torques (the range analyses apart), in order
    tried = list(dict.fromkeys((*_key(d), round(float(d["blade_angle_change"]), 4))
                               for d in seen))
    recentred = round(-0.01 / HEIGHT_SLOPE, 4)
    assert tried == [(*_key(_VALUES), 0.0)] + [
        (*_key(_VALUES | change), blade) for change, blade in (
            ({"ellipse_length": 0.75}, 0.0), ({"root_relief": 2 * _RR / 3}, 0.0),
            ({"tip_relief": 2 * _TR / 3}, 0.0),
            ({"tip_relief": 2 * _TR / 3, "root_relief": 2 * _RR / 3}, 0.0),
            ({"ellipse_length": 0.45}, 0.0), ({"ellipse_length": 0.45}, recentred),
            ({"ellipse_length": 0.5}, 0.0), ({"ellipse_length": 0.5}, recentred))]
    assert "  not kept: plastic segments carry 0.51 % of the torque" in lines
    assert any("its LTE p-p 64.0 urad at 1638 N m, between the torques, above 60" in s
               for s in lines)
    assert any("the ellipse 0.5 with its light-load pattern's height back at v 0.63" in s
               for s in lines)


def test_the_ellipses_between_only_where_the_longest_kept_the_limit(monkeypatch):
    """Where the longest ellipse is above the limit at a torque (the LTE falls as the
    ellipse lengthens), or was not refused, no ellipse between is tried; the step's
    designs are then those of before."""
    loud = dict(_LAW) | {(0.75, _TR, _RR): ((0.00, 1.00), (45.0, 62.0), (60.0, 61.0), 0.65,
                                            1300.0, 0.017, 0.0051)}
    targets, setup, start, seen = _start(monkeypatch, loud)
    got = cap.checked_coast_capacity_lte(start, targets, setup, None, print,
                                         lambda v: dict(v), static=_STATIC)
    assert got is start
    assert {_key(d)[0] for d in seen} == {0.75, 0.4}
    assert not cap.between_wanted(start, None, targets, 60.0, _STATIC)
    # a longest ellipse the rule would not refuse but for its LTE (here the design itself,
    # 59 / 53 urad): nothing to try between
    assert not cap.between_wanted(start, start, targets, 60.0, _STATIC)
