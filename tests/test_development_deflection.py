"""The LTE at the design torque against the teeth's mean deflection
(contact.optimize.development_deflection; the verdict's clause; issue 71, the ratio-1
16x16 at Σ 60°)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from contact.optimize.development_deflection import (
    CURVATURE_RATIO_NOTE,
    DeflectionLTE,
    curvature_ratio,
    deflection_lte,
    deflection_text,
    within_torque,
)

# the 16x16 at Sigma 60 deg's written case (ltca synthesize with every default,
# 2026-11-27): LTE p-p and mean deflection at four torques from light to design
TORQUES_16 = (97.4, 281.4, 465.4, 649.4)
LTE_16 = (45.07, 46.99, 110.62, 121.61)
DEFLECTION_16 = (248.5, 516.1, 730.0, 922.2)


def test_within_torque_interpolates_the_first_crossing():
    # 47 -> 111 urad between 281.4 and 465.4 N m: 60 at 281.4 + 13/63.6 * 184
    t = within_torque(TORQUES_16, LTE_16, 60.0)
    assert t == pytest.approx(281.4 + (60.0 - 46.99) / (110.62 - 46.99) * 184.0, rel=1e-12)
    assert 281.4 < t < 465.4
    # the first crossing, not a later dip below the limit
    assert within_torque((1.0, 2.0, 3.0, 4.0), (10.0, 70.0, 50.0, 80.0), 60.0) == \
        pytest.approx(1.0 + 50.0 / 60.0)


def test_within_torque_ends():
    assert within_torque((10.0, 20.0), (30.0, 40.0), 60.0) == 20.0  # never above
    assert math.isnan(within_torque((10.0, 20.0), (70.0, 40.0), 60.0))  # above at once
    assert math.isnan(within_torque((10.0, 20.0), (30.0, math.nan), 60.0))
    with pytest.raises(ValueError, match="2 torques and 1 LTE"):
        within_torque((10.0, 20.0), (30.0,), 60.0)


def _ltca(torques, te_rows, ute):
    return xr.Dataset(
        {"transmission_error": (("torque", "roll"), np.asarray(te_rows, float)),
         "unloaded_transmission_error": (("roll",), np.asarray(ute, float)),
         "lte_peak_to_peak": (("torque",), np.ptp(np.asarray(te_rows, float), axis=1))},
        coords={"torque": list(torques)})


def test_deflection_lte_reads_the_mean_deflection_and_sorts_the_torques():
    ute = [10.0, 0.0, 10.0, 20.0]
    # torques given out of order: the light torque's row second
    ds = _ltca([500.0, 100.0], [[910.0, 900.0, 930.0, 940.0], [210.0, 200.0, 210.0, 240.0]],
               ute)
    d = deflection_lte(ds, limit=60.0)
    assert d.torques == (100.0, 500.0)
    # mean loaded TE less mean unloaded TE (10 urad)
    assert d.deflection == pytest.approx((215.0 - 10.0, 920.0 - 10.0))
    assert d.lte == pytest.approx((40.0, 40.0))
    assert d.share == pytest.approx(40.0 / 910.0)
    assert d.share_needed == pytest.approx(60.0 / 910.0)
    assert d.within == 500.0


def test_curvature_ratio_against_the_virtual_gears():
    # ratio 1 at Sigma 60 deg: r_v = r_m / cos 30 deg on both, rho_red = r_v / 2
    assert curvature_ratio(16, 16, math.radians(30), math.radians(30)) == \
        pytest.approx(0.5 / math.cos(math.radians(30)))
    # miter: 1 / (2 cos 45 deg) = 0.707; ratio 3 at Sigma 90 deg: 1 / (3 sqrt 10) * 3
    assert curvature_ratio(20, 20, math.pi / 4, math.pi / 4) == pytest.approx(math.sqrt(0.5))
    d1 = math.atan(1 / 3)
    assert curvature_ratio(13, 39, d1, math.pi / 2 - d1) == pytest.approx(1 / math.sqrt(10))
    assert curvature_ratio(13, 39, d1, math.pi / 2 - d1) < CURVATURE_RATIO_NOTE < \
        curvature_ratio(16, 16, math.radians(30), math.radians(30))
    with pytest.raises(ValueError, match="pitch angles"):
        curvature_ratio(16, 16, 0.0, 0.5)


def test_the_note_of_the_16x16_in_numbers():
    found = DeflectionLTE(TORQUES_16, LTE_16, DEFLECTION_16, 60.0)
    text = deflection_text(found, curvature_ratio(16, 16, math.radians(30),
                                                  math.radians(30)))
    assert "deflect 922 urad on average at 649.4 N m" in text
    assert "LTE p-p 122 urad is 13.2 % of it" in text
    assert "within 60 urad it would be 6.5 %" in text
    assert "relative curvature radius is 0.58 of the gear's mean radius" in text
    assert "up to about 319 N m (49 % of the design torque" in text
    assert "[synthesis] design_torque" in text
    assert "24x24, eps_va 1.22, eps_vb 1.40" in text
    assert "(measured: that 16x16 at 300 N m" in text  # named by the curvature clause
    # far from ratio 1, no curvature clause; within the limit at the design torque, no note
    assert "curvature" not in deflection_text(found, 0.32)
    assert deflection_text(DeflectionLTE((10.0, 20.0), (70.0, 50.0), (100.0, 200.0),
                                         60.0)) is None


def test_the_verdicts_lte_finding_states_the_deflection_share():
    from contact.study.verdicts import _lte

    ute = [10.0, 0.0, 10.0, 20.0]
    ds = _ltca([600.0], [[900.0, 1000.0, 910.0, 920.0]], ute)
    ds["pairs_in_contact"] = (("torque", "roll"), np.full((1, 4), 2.0))
    (finding,) = _lte(ds, None, 60.0)
    assert finding.severity == "attention"
    # mean TE 932.5, mean UTE 10: 922.5 urad; LTE p-p 100 urad
    assert "the teeth's mean deflection there 922 µrad" in finding.reason
    assert "the LTE 10.8 % of it, 6.5 % within the limit" in finding.reason


def test_the_verdicts_lte_finding_names_an_unloaded_te_above_the_limit():
    """Round 30 (the spiral bevel 14x21 at Sigma 125 deg): its written drive flank's
    unloaded TE p-p 129 urad exceeds the limit before any load; ltca synthesize's note said
    so, ltca run's lte finding named the deflection alone. The clause's number is the
    unloaded TE's max less min over the rolls (exact: no tolerance)."""
    from contact.study.verdicts import _lte

    ute = [0.0, 129.0, 40.0, 10.0]  # p-p 129 urad
    ds = _ltca([22.5], [[300.0, 420.0, 330.0, 310.0]], ute)  # LTE p-p 120 urad
    (finding,) = _lte(ds, None, 60.0)
    assert "the flank's unloaded TE p-p is 129 µrad, above the 60 µrad before any load" \
        in finding.reason
    # the deflection clause stays beside it
    assert "the teeth's mean deflection there" in finding.reason
    # an unloaded TE within the limit: no clause (the finding as before)
    ds = _ltca([22.5], [[300.0, 420.0, 330.0, 310.0]], [0.0, 45.0, 20.0, 10.0])
    (finding,) = _lte(ds, None, 60.0)
    assert "unloaded TE p-p" not in finding.reason
    # no unloaded TE in the tree: no clause, no error
    ds = _ltca([22.5], [[300.0, 420.0, 330.0, 310.0]], ute).drop_vars(
        "unloaded_transmission_error")
    (finding,) = _lte(ds, None, 60.0)
    assert "unloaded TE" not in finding.reason


def test_synthesize_note_only_where_the_check_did_not_judge_the_range_within(monkeypatch):
    """The lock changed (issue 71, "LTE p-p <= 60 urad at every torque"): the note was made
    only where the design torque's LTE was above 60 urad, so that the truck hypoid 8x41
    (38.5 / 38.6 urad at 254.3 / 1696 N m, 65.8 at 734.9 N m between) and the spiral bevel
    27x34 (35 / 52 at 127.8 / 852.2, 77.3 at 369.3 N m) were written without one. Now the
    written case is analysed also where the development's check judged its LTE above the
    limit between the torques (its record ``lte_range``), or did not judge it at the
    written torques (no record); never where it judged it within the limit there."""
    from types import SimpleNamespace

    import contact.optimize.development_deflection as dd
    from contact.optimize.written_notes import deflection_note

    def fail(*args, **kwargs):
        raise AssertionError("analysed where the LTE keeps the limit")

    monkeypatch.setattr(dd, "analysed", fail)
    metrics = {"lte_peak_to_peak": [70.0, 38.0]}
    within = SimpleNamespace(best=SimpleNamespace(metrics=metrics), torque=(36.9, 246.5),
                             lte_range={"peak": 59.9, "at": 140.1})
    assert deflection_note(object(), within) is None  # judged within: never analysed
    # the truck 8x41's numbers: judged above the limit between the torques by the check
    truck = DeflectionLTE((254.3, 734.9, 1215.5, 1696.0), (38.5, 65.8, 41.0, 38.6),
                          (300.0, 700.0, 1000.0, 1300.0), 60.0)
    asked = []

    def between(case, light, design):
        asked.append((light, design))
        return truck

    monkeypatch.setattr(dd, "analysed", between)
    judged = SimpleNamespace(best=SimpleNamespace(metrics={"lte_peak_to_peak": [38.5, 38.6]}),
                             torque=(254.3, 1696.0), lte_range={"peak": 65.8, "at": 734.9})
    text = deflection_note(object(), judged)
    assert asked == [(254.3, 1696.0)]
    assert text == dd.between_text(truck)
    assert "65.8 urad at 734.9 N m, between the light 254.3 and the design torque 1696" in text
    assert "above the limit 60 urad" in text
    # not judged at the written torques (changed after the check's steps): analysed
    unjudged = SimpleNamespace(best=judged.best, torque=(254.3, 1696.0), lte_range=None)
    assert deflection_note(object(), unjudged) == text
    assert len(asked) == 2
    found = DeflectionLTE(TORQUES_16, LTE_16, DEFLECTION_16, 60.0)
    seen = []

    def stand_in(case, light, design):
        seen.append((light, design))
        return found

    monkeypatch.setattr(dd, "analysed", stand_in)
    blank = SimpleNamespace(teeth=16, pitch_angle=math.radians(30))
    case = SimpleNamespace(pinion=SimpleNamespace(blank=blank), gear=SimpleNamespace(blank=blank))
    above = SimpleNamespace(best=SimpleNamespace(metrics={"lte_peak_to_peak": [45.0, 121.6]}),
                            torque=(97.4, 649.4))
    text = deflection_note(case, above)
    assert seen == [(97.4, 649.4)]
    assert text == deflection_text(found, curvature_ratio(16, 16, math.radians(30),
                                                          math.radians(30)))


def test_within_text_one_function_for_both_commands():
    from contact.study.lte_within import within_text

    # the 16x16's four torques: 60 urad at 281.4 + 13.01/63.63 * 184 = 319.0 N m, 49 %
    said = within_text(TORQUES_16, LTE_16, 60.0, 649.4)
    assert said == ("within 60 µrad up to about 319 N·m (49 % of the design torque; LTE p-p "
                    "45 / 47 / 111 / 122 µrad at 97.4 / 281.4 / 465.4 / 649.4 N·m)")
    assert within_text(TORQUES_16, LTE_16, 60.0, urad="urad", nm="N m").startswith(
        "within 60 urad up to about 319 N m (LTE p-p 45 / 47")  # no design torque: no share
    # nothing to name: one torque, within the limit at the last, above it at the first
    assert within_text((649.4,), (121.6,), 60.0, 649.4) is None
    assert within_text((97.4, 649.4), (39.2, 58.0), 60.0, 649.4) is None
    assert within_text((97.4, 649.4), (61.0, 118.0), 60.0, 649.4) is None


def test_the_verdicts_lte_finding_names_the_torque_within_the_limit():
    from contact.study.verdicts import _lte

    # stand-in numbers: LTE p-p 40 / 100 / 140 urad at 100 / 300 / 500 N m (each row's
    # spread), mean deflection positive
    ute = [0.0, 0.0, 0.0, 0.0]
    rows = [[200.0, 240.0, 210.0, 220.0], [500.0, 600.0, 520.0, 540.0],
            [800.0, 940.0, 820.0, 850.0]]
    ds = _ltca([300.0, 100.0, 500.0], [rows[1], rows[0], rows[2]], ute)  # out of order
    ds["pairs_in_contact"] = (("torque", "roll"), np.full((3, 4), 2.0))
    found = _lte(ds, None, 60.0)
    assert [f.severity for f in found] == ["attention", "fail"]  # 100 and 140 urad
    # 60 urad at 100 + (60 - 40) / (100 - 40) * 200 = 166.7 N m; said once, on the largest
    # torque's finding, with the run's torques and no design-torque share (no rating)
    clause = ("it stays within 60 µrad up to about 166.7 N·m (LTE p-p 40 / 100 / 140 µrad "
              "at 100 / 300 / 500 N·m), interpolated linearly between this run's torques")
    assert clause not in found[0].reason
    assert clause in found[1].reason
    # with a rating's design torque of 300 N m: judged up to it, the share of it said
    rating = xr.Dataset({"design_torque": ((), 300.0)})
    (at_design,) = _lte(ds, rating, 60.0)
    assert ("within 60 µrad up to about 166.7 N·m (56 % of the design torque; LTE p-p "
            "40 / 100 µrad at 100 / 300 N·m)") in at_design.reason
    # one torque (the single-torque run): nothing new said
    (single,) = _lte(ds.isel(torque=[0]), None, 60.0)
    assert "stays within" not in single.reason


def test_an_uncertified_solve_is_nan_never_a_number():
    """As ``ltca run``'s lte_range step (contact.ltca.lte_range: an uncertified solve NaN):
    a torque where a roll position has no certified contact solution has no LTE to judge."""
    ute = [0.0, 0.0, 0.0, 0.0]
    ds = _ltca([100.0, 300.0], [[200.0, 240.0, 210.0, 220.0], [500.0, 600.0, 520.0, 540.0]],
               ute)
    ds["found"] = (("torque", "roll"), np.asarray([[1, 1, 1, 1], [1, 0, 1, 1]], np.int8))
    d = deflection_lte(ds, limit=60.0)
    assert d.lte[0] == pytest.approx(40.0)
    assert math.isnan(d.lte[1])
    assert d.deflection[1] == pytest.approx(540.0)  # the deflection is still the mean
    # every roll certified: the numbers as before
    ds["found"] = (("torque", "roll"), np.ones((2, 4), np.int8))
    assert deflection_lte(ds, limit=60.0).lte == pytest.approx((40.0, 100.0))


def test_analysed_says_nan_where_a_torque_is_not_certified(monkeypatch):
    """:func:`analysed` (synthesize's note) judges the torques of ``ltca run``'s step with
    its NaN: the torque whose solve is not certified is NaN, the crossing not bisected past
    it (contact.ltca.lte_range.bisected: a value up to the crossing not finite)."""
    import contact.pipeline as pipeline
    from contact.optimize.development_deflection import analysed

    lte_of = {100.0: 40.0, 200.0: 50.0, 300.0: 100.0, 400.0: 45.0}
    calls = []

    def fake(case, torques, **kw):
        calls.append(list(torques))
        rows = [[t, t + lte_of[round(t, 6)], t, t] for t in torques]
        ds = _ltca(torques, rows, [0.0] * 4)
        ds["found"] = (("torque", "roll"),
                       np.asarray([[0 if round(t) == 200 else 1] * 4 for t in torques],
                                  np.int8))
        return xr.DataTree.from_dict({"/ltca": ds})

    monkeypatch.setattr(pipeline, "run_analysis", fake)
    found = analysed(object(), 100.0, 400.0)
    assert calls == [[100.0, 200.0, 300.0, 400.0]]  # no bisection past a NaN
    assert found.torques == (100.0, 200.0, 300.0, 400.0)
    assert found.lte[0] == pytest.approx(40.0) and math.isnan(found.lte[1])
    assert found.lte[2:] == pytest.approx((100.0, 45.0))


def test_the_between_note_in_numbers_and_where_it_is_silent():
    # the 27x34's numbers (benchmarks/data/unseen_designs, 2026-11-27): 77.3 urad at
    # 369.3 N m between 35 and 52 urad at 127.8 and 852.2 N m
    found = DeflectionLTE((127.8, 369.3, 610.7, 852.2), (35.0, 77.3, 58.0, 52.0),
                          (100.0, 300.0, 500.0, 700.0), 60.0)
    text = deflection_text(found)
    assert text is None  # the design torque within the limit: no deflection note
    from contact.optimize.development_deflection import between_text

    said = between_text(found)
    assert "77.3 urad at 369.3 N m, between the light 127.8 and the design torque 852.2" in said
    assert "LTE p-p 35 / 77 / 58 / 52 urad at 127.8 / 369.3 / 610.7 / 852.2 N m" in said
    # silent: within at every torque, above at the design torque (deflection_text's), or
    # at the light torque (its own finding), or two torques only
    assert between_text(found._replace(lte=(35.0, 59.0, 58.0, 52.0))) is None
    assert between_text(found._replace(lte=(35.0, 77.3, 58.0, 61.0))) is None
    assert between_text(found._replace(lte=(61.0, 77.3, 58.0, 52.0))) is None
    assert between_text(DeflectionLTE((1.0, 2.0), (30.0, 40.0), (1.0, 2.0), 60.0)) is None


def test_the_16x16_introduced_where_the_curvature_clause_is_not_said():
    """Round 22's spiral bevel 14x36 at Sigma 70 deg (ratio 2.57, no curvature clause): its
    note said "(measured: that 16x16 at 300 N m ...)" of a pair it had never named. Its
    written case's numbers (ltca synthesize with every default, 2026-11-27): LTE p-p 14 /
    36 / 48 / 60 / 82 / 78 urad at 55.6 / 108.2 / 134.5 / 160.8 / 266 / 371.2 N m; the
    mean deflections are stand-ins, only the design torque's (615 urad, as its note) is
    read."""
    found = DeflectionLTE((55.6, 108.2, 134.5, 160.8, 266.0, 371.2),
                          (14.2, 36.0, 47.6, 60.1, 81.6, 77.9),
                          (150.0, 250.0, 300.0, 350.0, 500.0, 615.0), 60.0)
    for curvature in (math.nan, 0.32):  # not given; far from ratio 1
        text = deflection_text(found, curvature)
        assert "curvature" not in text
        assert "that 16x16" not in text
        assert ("(measured: a ratio-1 spiral bevel 16x16 at a shaft angle of 60 deg, its "
                "ISO capacity 649.4 N m at 300 N m, LTE p-p 57/55 urad") in text
        # the 13x39 is named in full before "that 13x39" could be needed
        assert "a ratio-3 spiral bevel 13x39" in text
        assert "deflect 615 urad on average at 371.2 N m" in text
