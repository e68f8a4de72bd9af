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


def test_synthesize_note_only_above_the_limit_at_the_design_torque(monkeypatch):
    from types import SimpleNamespace

    import contact.optimize.development_deflection as dd
    from contact.commands.synthesize import _deflection_note

    def fail(*args, **kwargs):
        raise AssertionError("analysed where the LTE keeps the limit")

    monkeypatch.setattr(dd, "analysed", fail)
    within = SimpleNamespace(best=SimpleNamespace(metrics={"lte_peak_to_peak": [70.0, 38.0]}),
                             torque=(36.9, 246.5))
    assert _deflection_note(object(), within) is None  # the 13x39's case: never analysed
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
    text = _deflection_note(case, above)
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
