"""The near-miss step's band-edge designs (contact.optimize.development_band_edge): where
every blade step of checked_near_miss gives up the LTE alone, the smallest blade step into
the centre band, then that step with the path turned, each kept by the check's one rule."""

from __future__ import annotations

import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import stand_in

from contact.optimize import development_band_edge as dband
from contact.optimize import development_check as dcheck
from contact.optimize.development_stages import HEIGHT_SLOPE


def _fake(calls, length_per_deg=0.0, edge_per_deg=0.0):
    """Stand-in analyses after the FM hypoid 11x39 at α 24° / 16° (56.7 / 378.4 N m,
    docs/synthesis.md "The length step's LTE bought back ..."): light-load centre v 0.635
    + 0.59 per degree of blade-angle change (0.60 at −0.0595°, 0.62 at −0.03°: measured
    0.60 / 0.62); LTE light 32.7 − 70 µrad per degree, design 39.5 − 90 per degree (42.5
    at −0.03°, measured 42.5) and 1.2 µrad less per degree the path turns below −65.6°
    (36.5 at −70.6°; measured 36.5 at −70°); ``length_per_deg``: the pattern's heel end
    moved per degree (a lost length); ``edge_per_deg``: the edge share at the design
    torque added per degree (a lost edge target)."""

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        x, p = case["blade_angle_change"], case["path_angle"]
        calls.append((x, p, misalignment is not None))
        return (_metrics(pattern_centre_v=[0.635 + 0.59 * x, 0.6],
                         pattern_heel_u=[0.7 - length_per_deg * x, 0.8],
                         edge_load_share=[0.0, 0.01 - edge_per_deg * x],
                         lte_peak_to_peak=[32.7 - 70.0 * x,
                                           39.5 - 90.0 * x + 1.2 * (p + 65.6)]),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


VALUES = {"path_angle": -65.6, "ellipse_length": 0.625, "blade_angle_change": 0.0,
          "te_level": 10.0}


def test_blade_steps_refused_for_the_lte_get_the_band_edge_then_the_path(monkeypatch):
    """The near-miss aims (v 0.603) give up the LTE (x −0.114°, −0.054°): refused; the
    band-edge step on the secant to the nearer one aims 0.9 of the tolerance from the
    target (0.615): −0.0339°, v 0.615, LTE 35.1 / 42.6 µrad, refused for the LTE alone;
    the same with the path −70.6°: 36.6 µrad at the design torque, every target met and
    tolerant (its four excursions): kept."""
    calls = []
    targets, setup, chosen = stand_in(monkeypatch, _fake(calls), [56.7, 378.4],
                                      centre_v=0.543)
    start = chosen(VALUES)
    assert [k for k, v in start.full[1].items() if v > 0] == ["centre_v"]
    calls.clear()
    lines = []
    got = dcheck.checked_near_miss(start, targets, setup, None, lines.append,
                                   lambda v: dict(v), 10.0)
    x1 = -(0.635 - 0.603) / HEIGHT_SLOPE
    x2 = x1 - (0.635 + 0.59 * x1 - 0.603) / 0.59
    edge = -(0.635 - 0.543 - dband.BAND_EDGE_AIM * 0.08) / 0.59
    assert edge == pytest.approx(-0.0339, abs=1e-4)
    path = -65.6 + dband.BAND_EDGE_PATH_TURN
    assert [c[:2] for c in calls if not c[2]] == [
        (pytest.approx(x1), -65.6), (pytest.approx(x2), -65.6),
        (pytest.approx(edge), -65.6), (pytest.approx(edge), path)]
    assert len(calls) == 4 + 4  # the kept design's excursions
    assert got.met and got.stage == "near miss"
    assert got.values == VALUES | {"blade_angle_change": pytest.approx(edge),
                                   "path_angle": path}
    assert "not kept: the band-edge blade step misses lte" in lines[5]


def test_no_band_edge_where_a_blade_step_gave_up_more_than_the_lte_and_length(monkeypatch):
    """A blade step that also gives up a target other than the LTE and the length (the
    edge share at the design torque, 0.01 + 1.0 per degree of blade step: 0.064 at the
    near-miss step nearest the design, limit 0.02) leaves the design as it was after the
    near-miss designs alone: no band-edge pair."""
    calls = []
    targets, setup, chosen = stand_in(monkeypatch, _fake(calls, edge_per_deg=1.0),
                                      [56.7, 378.4], centre_v=0.543)
    start = chosen(VALUES)
    calls.clear()
    got = dcheck.checked_near_miss(start, targets, setup, None, [].append,
                                   lambda v: dict(v), 10.0)
    assert got is start
    assert 0 < len(calls) <= dcheck.NEAR_MISS_DESIGNS and not any(c[2] for c in calls)


def _fake_9x38(calls):
    """Stand-in analyses after the FM hypoid 9x38 at Σ 95° of benchmarks/data/
    unseen_designs (``ltca run``'s sampling at 62.6 / 417.6 N m, path −65.6°, ellipse
    0.625; ``benchmarks/development_levers.py --check --tolerance``, 2026-11-27): centre v
    0.630 + 0.47 per degree of blade-angle change (0.61 at −0.0425°, measured 0.61); the
    pattern's toe at 0.225 of the face, 0.20 beyond −0.04° and its heel at 0.80, 0.82
    beyond −0.028° (measured 0.23 / 0.20 and 0.80 / 0.83 on the check's nodes of 0.025:
    0.58, 0.60 and 0.62 long at 0, −0.03° and −0.0425°); LTE at the design torque 39.4 −
    0.335 µrad per µrad of ``te_level`` below 45 − 163 µrad per degree (measured 39.4 as
    developed, 36.9 / 37.6 / 38.5 / 39.6 at −0.025 / −0.03 / −0.035 / −0.0425° with
    ``te_level`` 25: 36.8 / 37.6 / 38.4 / 39.6 here), 37.3 µrad at the light torque."""

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        x, te = case["blade_angle_change"], case["te_level"]
        calls.append((x, te, misalignment is not None))
        return (_metrics(pattern_centre_v=[0.630 + 0.47 * x, 0.63],
                         pattern_toe_u=[0.2 if x < -0.04 else 0.225, 0.0],
                         pattern_heel_u=[0.82 if x < -0.028 else 0.8, 1.0],
                         lte_peak_to_peak=[37.3, 39.4 - 0.335 * (45.0 - te) - 163.0 * x]),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


def test_a_blade_step_that_gave_up_the_length_gets_the_smaller_band_edge_step(monkeypatch):
    """The 9x38's near-miss aim (v 0.602 on the height stage's slope, 0.0280 / 0.0425 per
    degree) −0.0425°: v 0.610 but the pattern 0.62 long (0.5 ± 0.1): refused for the
    length alone; the secant's step −0.0595°: 0.645 long, LTE 42.4 µrad, refused; the
    band-edge step (0.9 of the tolerance from the target, v 0.614) −0.034°: 0.595 long,
    LTE 38.2 µrad, every target met and tolerant (its four excursions): kept, without the
    path turned. Before, a smallest step that lost the length ended the step with the
    design's centre v 0.630 off its band."""
    calls = []
    targets, setup, chosen = stand_in(monkeypatch, _fake_9x38(calls), [62.6, 417.6],
                                      centre_v=0.542)
    start = chosen(VALUES | {"te_level": 45.0})
    assert [k for k, v in start.full[1].items() if v > 0] == ["centre_v"]
    calls.clear()
    lines = []
    got = dcheck.checked_near_miss(start, targets, setup, None, lines.append,
                                   lambda v: dict(v), 45.0, slope=0.028 / 0.0425)
    x1 = -0.0425
    x2 = x1 - (0.630 + 0.47 * x1 - 0.602) / 0.47
    edge = -(0.630 - 0.542 - dband.BAND_EDGE_AIM * 0.08) / 0.47
    assert edge == pytest.approx(-0.0340, abs=1e-4)
    assert [c[:2] for c in calls if not c[2]] == [
        (pytest.approx(x1), 25.0), (pytest.approx(x2), 25.0), (pytest.approx(edge), 25.0)]
    assert len(calls) == 3 + 4  # the kept design's excursions
    assert any(line == "  not kept: the blade-angle step misses length" for line in lines)
    assert got.met and got.stage == "near miss"
    assert got.values == VALUES | {"blade_angle_change": pytest.approx(edge),
                                   "te_level": 25.0}
