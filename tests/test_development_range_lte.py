"""The check's last step: the drive LTE judged between the development's torques as ``ltca
run``'s ``lte_range`` step judges it (contact.optimize.development_range_lte, issue 71:
"LTE p-p <= 60 urad at every torque").

Stand-in analyses whose law is the truck hypoid 8x41 of tests/data/designs as ``ltca run``
judged its written case (2026-11-27): LTE p-p 38.5 / 38.6 urad at its light and design
torque 254.3 / 1696 N m and 65.8 urad at 734.9 N m between them, every development target
met. The turned paths' numbers are the law's (the tests are the step's choices, not numbers
of a gear): one turn lowers the LTE at both torques and raises the peak between them, the
other brings the peak within the limit.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.ltca.lte_range import lte_range_torques
from contact.optimize import development_check as dcheck
from contact.optimize import development_lte_capacity as dlc
from contact.optimize import development_path_lte as dpl
from contact.optimize import development_range_lte as drl

TORQUES = (254.3, 1696.0)
#: ltca run's lte_range torques of a case run at them: 254.3 / 734.87 / 1215.4 / 1696 N m
GRID = lte_range_torques(TORQUES, TORQUES[1])

WRITTEN = {"path_angle": -60.0, "ellipse_length": 0.6, "tip_relief": 20.0,
           "root_relief": 10.0, "relief_start": 0.5, "profile_crowning": 0.0,
           "tip_relief_start": 0.9, "blade_angle_change": 0.0, "te_level": 10.0}

#: LTE p-p [urad] at GRID by path angle [deg]: as written; turned by -6.25 deg (lower at
#: both torques, the peak between higher: it ranks better at the two torques alone);
#: turned by -12.5 deg (the peak between within 60)
CURVES = {-60.0: (38.5, 65.8, 45.0, 38.6), -66.25: (30.0, 70.0, 50.0, 31.0),
          -72.5: (39.0, 52.0, 44.0, 39.5)}


def _truck(curves=CURVES):
    """(the torques each analysis asked, the stand-in's law): the LTE interpolated over
    GRID in the path's row of ``curves``; every other metric meets its default target."""
    asked: list[tuple[float, ...]] = []

    def law(case, torques, misalignment=None, **kw):
        ts = tuple(float(t) for t in torques) or TORQUES
        if misalignment is None:
            asked.append(ts)
        lte = np.interp(ts, GRID, curves[float(case["path_angle"])])
        m = {k: np.resize(v, len(ts)) for k, v in _metrics().items()}
        m["lte_peak_to_peak"] = np.asarray(lte, float)
        return m, (0.0, 1.0, 0.0, 1.0, 2400.0)

    return asked, law


def _start(chosen):
    start = chosen(dict(WRITTEN))
    return dataclasses.replace(start, case=dict(start.values))


def test_a_peak_between_the_torques_is_seen_and_acted_on(monkeypatch):
    """38.5 / 38.6 urad at the two torques, 65.8 at 734.9 N m between: the path turned as
    the design torque's path step turns it; the turn that lowers both torques' LTE but
    raises the peak (70 urad) is not kept although it ranks better at the two torques,
    the one whose peak is 52 urad is."""
    asked, law = _truck()
    seen, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    assert start.full[2]  # every development target met at the two torques
    asked.clear()
    seen.clear()
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    # the two torques between analysed, then the interval of the crossing bisected twice
    assert asked[0] == pytest.approx(GRID[1:3])
    assert asked[1] == pytest.approx((0.5 * (GRID[0] + GRID[1]),))
    assert "65.8 urad at 734.9 N m, between the light and the design torque" in lines[0]
    # each turn analysed at the two torques and between them (its peak judged)
    turned = [s["path_angle"] for s in seen if s != dict(WRITTEN)]
    assert list(dict.fromkeys(turned)) == [-66.25, -72.5]
    assert [a for a in asked if a != TORQUES].count(pytest.approx(GRID[1:3])) == 3
    assert got.stage == dpl.STAGE
    assert got.values["path_angle"] == -72.5
    record = drl.range_record(setup)
    assert record["values"] == got.values
    assert record["peak"] == pytest.approx(52.0) and record["at"] == pytest.approx(GRID[1])
    assert any("(its LTE 38/39 urad, 66 urad at 734.9 N m between the torques above 60)" in s
               for s in lines)


def test_a_variant_is_judged_on_its_largest_lte_over_the_range(monkeypatch):
    """The keep rule's ``better`` on a peak between the torques: the largest LTE over the
    range, not the rank at the two torques."""
    _asked, law = _truck()
    _, fake = seen_designs(law)
    _targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    better = drl.range_better(setup, None)
    lower_both = dataclasses.replace(chosen(dict(WRITTEN) | {"path_angle": -66.25}),
                                     case=dict(WRITTEN) | {"path_angle": -66.25})
    within = dataclasses.replace(chosen(dict(WRITTEN) | {"path_angle": -72.5}),
                                 case=dict(WRITTEN) | {"path_angle": -72.5})
    assert dcheck.ranks_better(start, lower_both)  # better at the two torques alone
    assert not better(start, lower_both)  # 70 urad between: worse over the range
    assert better(start, within)  # 52 urad
    assert not better(within, start)  # 65.8 above the limit, 52 within it
    # both within the limit: the check's rank at the two torques
    other = dict(WRITTEN) | {"path_angle": -72.5, "ellipse_length": 0.55}
    assert better(within, dataclasses.replace(within, values=other, case=other,
                                              objective=within.objective - 1.0,
                                              full=(within.full[0] - 1.0,
                                                    *within.full[1:])))
    assert all(np.isnan(drl.range_peak(None)))
    assert all(np.isnan(drl.range_peak(((1.0, 2.0), (float("nan"), float("nan"))))))


def test_within_the_limit_between_no_design_is_tried(monkeypatch):
    """The LTE over the range within 60 urad: one analysis of the two torques between,
    recorded, no design tried, no line said."""
    asked, law = _truck({-60.0: (38.5, 55.0, 45.0, 38.6)})
    _seen, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    asked.clear()
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    assert got is start and not lines
    assert asked == [pytest.approx(GRID[1:3])]
    assert drl.range_record(setup)["peak"] == pytest.approx(55.0)
    # judged again (steps_on_each, a path step after a height step): not analysed again
    drl.checked_range_lte(start, targets, setup, None, lines.append, lambda v: dict(v))
    assert len(asked) == 1


def test_a_peak_at_the_design_torque_is_left_to_the_design_torque_steps(monkeypatch):
    """61 urad at the design torque, 55 at most between: the largest LTE is the design
    torque's, which the design torque's steps (the path LTE step among them) acted on; this
    step records the range and tries nothing."""
    _asked, law = _truck({-60.0: (38.5, 55.0, 45.0, 61.0)})
    seen, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    seen.clear()
    got = drl.checked_range_lte(start, targets, setup, None, lambda s: None,
                                lambda v: dict(v))
    assert got is start
    assert all(s == dict(WRITTEN) for s in seen)  # only the design itself, between
    assert drl.range_record(setup)["peak"] == pytest.approx(61.0)


def test_a_peak_between_above_a_missed_design_torque_is_acted_on(monkeypatch):
    """61 urad at the design torque and 65.8 between (the 17x38 by Method 0 of
    benchmarks/data/unseen_designs: 21 / 62 urad at its torques, 71 / 73 between): the
    design torque's steps judged the 61 alone, so this step acts on the 65.8 as on a peak
    between torques that keep the limit; the turn whose largest LTE over the range is 52
    urad is kept, the one at 70 is not."""
    curves = dict(CURVES) | {-60.0: (38.5, 65.8, 45.0, 61.0)}
    _asked, law = _truck(curves)
    seen, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    seen.clear()
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    assert "65.8 urad at 734.9 N m, between the light and the design torque" in lines[0]
    assert got.values["path_angle"] == -72.5
    assert drl.range_record(setup)["peak"] == pytest.approx(52.0)


@pytest.mark.parametrize(("peak", "ends", "acts"), [
    (65.8, (38.5, 38.6), True),  # within at both, above between
    (55.0, (38.5, 38.6), False),  # within everywhere
    (61.0, (38.5, 61.0), False),  # the peak is the design torque's
    (61.04, (38.5, 61.0), False),  # the same peak within SAME_PEAK (0.05 urad)
    (73.0, (21.0, 62.0), True),  # the 17x38: higher between than at its torques
    (float("nan"), (38.5, 38.6), False),  # not analysed
    (65.0, (float("nan"), 38.6), True),  # an end not analysed: the other within
])
def test_acts_between_reads_where_the_largest_lte_is(peak, ends, acts):
    """The rule alone: exact comparisons of given numbers (no tolerance but SAME_PEAK,
    the step's own)."""
    assert drl.acts_between(peak, ends, 60.0) is acts


def test_an_analysis_that_fails_is_not_judged(monkeypatch):
    _asked, law = _truck()

    def failing(case, torques, misalignment=None, **kw):
        if len(torques) and tuple(torques) != TORQUES:
            raise RuntimeError("no certified solution")
        return law(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, failing, TORQUES)
    start = _start(chosen)
    assert drl.range_lte(start, setup, None) is None
    assert drl.checked_range_lte(start, targets, setup, None, lambda s: None,
                                 lambda v: dict(v)) is start
    assert drl.range_record(setup) is None


def test_the_check_judges_the_range_last(monkeypatch):
    """check_steps ends on the step (the design its steps kept judged between the
    torques): its record is the design returned."""
    _asked, law = _truck()
    _, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    got = dcheck.check_steps(start, targets=targets, setup=setup, teeth=None,
                             say=lambda s: None, placed=lambda v: dict(v), level=10.0)
    record = drl.range_record(setup)
    assert record is not None and record["values"] == got.values
    assert record["peak"] <= 60.0


def test_the_lte_capacity_acts_on_a_fail_level_peak_between(monkeypatch):
    """A FAIL-level LTE (above 2 x 60 urad) between the torques alone: the design torque is
    lowered as for one at the design torque (development_lte_capacity); a record of
    another design is not read."""
    curve = (38.0, 130.0, 140.0, 55.0)
    asked, law = _truck({-60.0: curve})
    _, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    setup |= {"source": "the ISO 10300 capacity", "lowered": False}
    setup[drl.RANGE_KEY] = {TORQUES: {"values": dict(WRITTEN) | {"path_angle": -72.5},
                                      "peak": 140.0, "at": GRID[2]}}
    asked.clear()
    assert dlc.lte_capacity(start, targets, setup, None, lambda s: None) is start
    assert not asked  # another design's record: not run
    setup[drl.RANGE_KEY][TORQUES]["values"] = dict(WRITTEN)
    lines: list[str] = []
    got = dlc.lte_capacity(start, targets, setup, None, lines.append)
    assert setup["lowered"] and got is not start
    assert float(setup["torques"][1]) < GRID[1]
    assert "its LTE p-p was 140 urad" in lines[0]


#: the ellipse's rows at the path's bound (-80 deg): light-load pattern length [1] and the
#: LTE p-p at GRID [urad] (the shape of the truck 8x41's measured rows, docs/synthesis.md
#: "The LTE between the development's torques": 0.4135 / 0.445 / 0.46 -> 66 / 61 / 57)
ELLIPSES = {0.6: (0.58, (38.5, 65.8, 45.0, 38.6)), 0.65: (0.62, (30.0, 61.0, 47.0, 26.0)),
            0.7: (0.65, (26.0, 57.0, 41.0, 21.0)), 0.75: (0.68, (21.0, 55.0, 35.0, 16.0))}


def _at_bound(rows=ELLIPSES):
    """The stand-in's law through ``rows`` (by the design's ellipse)."""
    def law(case, torques, misalignment=None, **kw):
        ts = tuple(float(t) for t in torques) or TORQUES
        length, curve = rows[round(float(case["ellipse_length"]), 2)]
        m = {k: np.resize(v, len(ts)) for k, v in _metrics().items()}
        m["pattern_toe_u"] = np.resize([0.5 - length / 2, 0.1], len(ts))
        m["pattern_heel_u"] = np.resize([0.5 + length / 2, 0.9], len(ts))
        m["lte_peak_to_peak"] = np.asarray(np.interp(ts, GRID, curve), float)
        return m, (0.0, 1.0, 0.0, 1.0, 2400.0)

    return law


def test_at_the_path_bound_a_longer_ellipse_buys_the_range_with_the_length(monkeypatch):
    """The path at its bound (-80 deg: the path step tries nothing): the ellipse 0.05 longer
    lowers the peak to 61 urad but gives up the pattern's length (0.62 > 0.6) and stays
    above the limit: not kept; 0.1 longer, 57 urad within the limit, the length given up
    alone (as the long bearing buys the LTE with it): kept, and the step stops there."""
    seen, fake = seen_designs(_at_bound())
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = chosen(dict(WRITTEN) | {"path_angle": -80.0})
    start = dataclasses.replace(start, case=dict(start.values))
    assert start.full[2]
    seen.clear()
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    tried = list(dict.fromkeys(s["ellipse_length"] for s in seen))
    assert tried == [0.6, 0.65, 0.7]  # the design itself between, then two; not 0.75
    assert "  not kept: the longer ellipse misses length" in lines
    assert got.stage == drl.STAGE and got.values["ellipse_length"] == 0.7
    assert [k for k, v in got.full[1].items() if v > 0.0] == ["length"]
    assert drl.range_record(setup)["peak"] == pytest.approx(57.0)
    assert "kept on its LTE between the torques" in lines[-1]


def test_no_ellipse_within_the_limit_keeps_the_design(monkeypatch):
    """Where no longer ellipse keeps the limit over the range, none that gives up a met
    target is kept: the design stays as it was, its peak recorded for synthesize's note."""
    rows = {k: (0.62 if k > 0.6 else 0.58, (38.5, 65.8, 45.0, 38.6) if k == 0.6 else
                (30.0, 62.0 - 10 * (k - 0.6), 47.0, 26.0)) for k in ELLIPSES}
    _, fake = seen_designs(_at_bound(rows))
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = chosen(dict(WRITTEN) | {"path_angle": -80.0})
    start = dataclasses.replace(start, case=dict(start.values))
    got = drl.checked_range_lte(start, targets, setup, None, lambda s: None,
                                lambda v: dict(v))
    assert got is start
    assert drl.range_record(setup)["peak"] == pytest.approx(65.8)


#: the ellipse's rows at both default bounds (path -80 deg, ellipse 0.75): the shape of
#: the FM spiral bevel 24x29 at Sigma 105 deg's written bearing at its ISO capacity 503 N m
#: (benchmarks/data/unseen_designs; development_levers.py --check --at --from-case,
#: branch window99): ellipse 0.75 / 0.8 / 0.85 -> pattern 0.58 / 0.62 / 0.62 long, largest
#: LTE p-p 67 / 60 / 53 urad between the torques; here the 0.8's row just above the limit
#: and the design torque's LTE within the target 40 (its 51 / 46 / 41 missed it: the test
#: is the step's choices, not numbers of a gear)
BOUND_ELLIPSES = {0.75: (0.58, (17.2, 66.5, 61.1, 39.0)),
                  0.8: (0.62, (17.5, 60.4, 54.0, 38.0)),
                  0.85: (0.62, (17.9, 53.0, 48.0, 37.0))}


def test_past_the_default_ellipse_bound_the_range_is_kept_with_the_length(monkeypatch):
    """The path and the ellipse at their default bounds (-80 deg, 0.75): the step goes on to
    0.85 (range_ellipse_bounds, LENGTH_ELLIPSE_MAX) as the length step does: 0.8 gives up
    the length and stays above 60 urad (not kept), 0.85 keeps the limit, the length given
    up alone: kept. Where 0.75 is the bound the user gave (not the defaults) nothing is
    tried and the design stays as it was."""
    seen, fake = seen_designs(_at_bound(BOUND_ELLIPSES))
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    assert drl.range_ellipse_bounds(targets) == (0.15, 0.85)
    start = chosen(dict(WRITTEN) | {"path_angle": -80.0, "ellipse_length": 0.75})
    start = dataclasses.replace(start, case=dict(start.values))
    assert start.full[2]
    seen.clear()
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    tried = list(dict.fromkeys(s["ellipse_length"] for s in seen))
    assert tried == [0.75, 0.8, 0.85]
    assert got.stage == drl.STAGE and got.values["ellipse_length"] == 0.85
    assert [k for k, v in got.full[1].items() if v > 0.0] == ["length"]
    assert drl.range_record(setup)["peak"] == pytest.approx(53.0)
    # the bound given (another lower bound: not the defaults) is used as given
    given = dataclasses.replace(targets, variables=dict(targets.variables)
                                | {"ellipse_length": (0.2, 0.75)})
    assert drl.range_ellipse_bounds(given) == (0.2, 0.75)
    setup.pop(drl.RANGE_KEY, None)
    seen.clear()
    kept = drl.checked_range_lte(start, given, setup, None, lambda s: None,
                                 lambda v: dict(v))
    assert kept is start
    assert {s["ellipse_length"] for s in seen} <= {0.75}


def test_the_result_carries_the_record_of_the_design_written_alone(monkeypatch):
    """The development's result carries the check's record only where it is of the drive
    design written at the final torques: a step after the check's (the mounting tolerance,
    the pitting step) that changed the design leaves synthesize's note to analyse the
    written case itself."""
    from contact.optimize.development import _judged

    _, law = _truck({-60.0: (38.5, 55.0, 45.0, 38.6)})
    targets, setup, chosen = stand_in(monkeypatch, law, TORQUES)
    start = _start(chosen)
    drl.checked_range_lte(start, targets, setup, None, lambda s: None, lambda v: dict(v))
    assert _judged(setup, start)["peak"] == pytest.approx(55.0)
    later = dataclasses.replace(start, values=dict(WRITTEN) | {"tip_relief": 30.0})
    assert _judged(setup, later) is None
    assert _judged(dict(setup, torques=[250.0, 1668.0]), start) is None


#: the coast flank's development torques and ltca run's lte_range torques of a coast run
#: at them: 135.2 / 368.33 / 601.47 / 834.6 N m (the face-hobbed spiral bevel 20x24 at
#: Σ 100° of benchmarks/data/unseen_designs, b2 24 -> 33.6 mm by ltca synthesize
#: --apply-remedy, its coast flank as ltca run --flank coast judged it, 2026-11-27: LTE p-p
#: 44.1 / 54.4 urad at 135.2 / 834.6 N m, 80.8 urad at 368.3 N m between them)
COAST_TORQUES = (135.2, 834.6)
COAST_GRID = lte_range_torques(COAST_TORQUES, COAST_TORQUES[1])

COAST_WRITTEN = {"path_angle": -45.0, "ellipse_length": 0.5, "tip_relief": 0.0,
                 "tip_relief_start": 0.9}

#: LTE p-p [urad] at COAST_GRID by (path angle, ellipse): as written; the ellipse 0.1
#: longer (lower at both torques, the peak between higher: it ranks better at the two
#: torques alone); the path turned 15 deg lengthwise (the peak between within 60). The
#: variants' numbers are the law's (the test is the step's choices)
COAST_CURVES = {(-45.0, 0.5): (44.1, 80.8, 67.5, 54.4), (-45.0, 0.6): (35.0, 85.0, 60.0, 45.0),
                (-30.0, 0.5): (42.0, 57.0, 52.0, 50.0)}


def test_the_coast_lte_steps_act_on_a_peak_between_the_torques(monkeypatch):
    """A coast design within 60 urad at its light and design torque and above it between
    them (ltca run --flank coast's lte_range) is given the coast LTE steps
    (development_coast_steps.checked_coast_lte), each judged on its largest LTE over the
    range on the coast flank: the longer ellipse, better at the two torques alone but 85
    urad between, is not kept; the path turned lengthwise (57 urad) is. A design within the
    limit between the torques too is returned as it is."""
    from contact.optimize import development_coast_steps as dcs

    asked: list[tuple] = []

    def law(case, torques, misalignment=None, flank="drive", pinion_key=(), **kw):
        ts = tuple(float(t) for t in torques) or COAST_TORQUES
        asked.append((flank, pinion_key[:2], ts))
        curve = COAST_CURVES[(float(case["path_angle"]), round(float(case["ellipse_length"]),
                                                               9))]
        m = {k: np.resize(v, len(ts)) for k, v in _metrics(edge_load_share=[0.0, 0.0]).items()}
        m["lte_peak_to_peak"] = np.interp(ts, COAST_GRID, curve)
        return m, (0.0, 1.0, 0.0, 1.0, 2400.0)

    seen, fake = seen_designs(law)
    targets, setup, chosen = stand_in(monkeypatch, fake, COAST_TORQUES)
    start = chosen(dict(COAST_WRITTEN))
    start = dataclasses.replace(start, case=dict(start.values))
    assert max(start.metrics["lte_peak_to_peak"]) <= 60.0  # within at both torques
    asked.clear()
    seen.clear()
    lines: list[str] = []
    prefix = ("drive bearing", "coast")
    got = dcs.checked_coast_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v), key_prefix=prefix)
    # every analysis on the coast flank, under the coast design's kept pinion tooth
    assert {(f, k) for f, k, _ in asked} == {("coast", prefix)}
    # the two torques between analysed, then the crossing's interval bisected
    assert asked[0][2] == pytest.approx(COAST_GRID[1:3])
    assert "its LTE p-p 80.8 urad at 368.3 N m, between the light and the design torque" \
        in lines[0]
    tried = [(s["path_angle"], s["ellipse_length"]) for s in seen if s != COAST_WRITTEN]
    assert list(dict.fromkeys(tried)) == [(-45.0, 0.6), (-30.0, 0.5)]
    assert got.values == COAST_WRITTEN | {"path_angle": -30.0}
    assert drl.range_peak(drl.range_lte(got, setup, None, flank="coast",
                                        key_prefix=prefix))[0] == pytest.approx(57.0)
    # within the limit between the torques too: returned as it is
    seen.clear()
    assert dcs.checked_coast_lte(got, targets, setup, None, [].append, lambda v: dict(v),
                                 key_prefix=prefix) is got
    assert seen == []  # its analyses between the torques kept (the setup's memo)


def test_an_lte_above_the_limit_never_reads_at_it():
    """Round 32 of issue 71: the FH hypoid 13x40's development printed "with the ellipse
    0.75 (its LTE 60 urad at 126.7 N m between the torques above 60)" for a peak of 60.x
    urad, which read as within the limit. Whole µrad where they read above the limit,
    more decimals where rounding would hide it (the identity: the printed number exceeds the
    limit whenever the value does)."""
    from contact.optimize.development_range_lte import above_limit_text

    assert above_limit_text(67.4, 60.0) == "67"
    assert above_limit_text(60.3, 60.0) == "60.3"
    assert above_limit_text(60.49, 60.0) == "60.5"
    assert above_limit_text(60.01, 60.0) == "60.01"
    for peak in (60.01, 60.2, 60.5, 60.51, 61.0, 75.0):
        assert float(above_limit_text(peak, 60.0)) > 60.0, peak
