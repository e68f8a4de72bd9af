"""The check's profile crowning matched to the load (issue 71, branch crown88;
docs/synthesis.md, "The profile crowning's TE on a profile path").

A profile crowning c adds the TE parabola k·c (tests/test_crowning_te.py): the unloaded TE
at light load, the deflection's transfer absorbed at the design torque. Where the check's
flatter profiles (``checked_crowning_lte``'s fractions) widen the design torque's lead over
the light torque's LTE, the crowning is raised to where the two cross
(``matched_crowning``, linear through the design and its half-crowned variant). Stand-in
analyses from the spiral bevel 16×16 at Σ 60° as written (``benchmarks/
development_levers.py --from-case --check``, ``ltca run``'s sampling at 58.6 / 390.7 N m,
path −88°, measured 2026-11-28): crowning 0 / 2.33 / 4.67 / 7 / 9.3 µm: LTE 21 / 107, 38 /
108, 54 / 95, 64 / 81, 78 / 72.5 µrad.
"""

from __future__ import annotations

import pytest
from development_stand_ins import checked as _checked
from development_stand_ins import metrics as _metrics
from development_stand_ins import stand_in

from contact.optimize import development_lte_steps as steps

#: LTE p-p (light, design) [µrad] by profile crowning [µm, 2 decimals], measured on the
#: written 16×16 (module docstring) but 7.97 µm: between the measured 7 and 9.3 µm
#: (linear: 68.1 / 78.3, the stand-in rounds to 68 / 78)
LTE = {4.67: [54.0, 95.0], 2.33: [38.0, 108.0], 0.0: [21.0, 107.0], 7.97: [68.0, 78.0]}


def _fake(calls):
    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        key = round(float(case["profile_crowning"]), 2)
        calls.append((key, float(case["te_level"]), misalignment is not None))
        # te_level's 45 µrad beside a crowning's ~270 µrad parabola: the written LTE
        lte = LTE[key] if case["te_level"] == 10.0 else [56.0, 95.0]
        return (_metrics(lte_peak_to_peak=lte, edge_load_share=[0.0, 0.007]),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


def test_matched_crowning_is_the_light_and_design_lte_crossing():
    """Through (4.67 µm: 54 / 95) and (2.33: 38 / 108): the gap design − light 41 and 70
    µrad, zero at 4.67 + 2.34 · 41/29 = 7.98 µm (the measured LTE crosses between 7 and
    9.3 µm: 64 / 81 and 78 / 72.5); at most twice the crowning; None where the flatter
    profile does not widen the gap, the design's LTE is the light torque's, or no flatter
    design was seen."""
    got = steps.matched_crowning([(4.67, (54.0, 95.0)), (2.335, (38.0, 108.0)),
                                  (0.0, (21.0, 107.0))])
    assert got == pytest.approx(4.67 + 2.335 * 41.0 / 29.0, rel=1e-12)
    assert 7.0 < got < 9.3
    assert steps.matched_crowning([(4.67, (54.0, 95.0)), (2.335, (54.0, 96.0))]) == \
        pytest.approx(2 * 4.67)
    assert steps.matched_crowning([(4.67, (54.0, 95.0)), (2.335, (50.0, 80.0))]) is None
    assert steps.matched_crowning([(4.67, (95.0, 54.0)), (2.335, (38.0, 108.0))]) is None
    assert steps.matched_crowning([(4.67, (54.0, 95.0))]) is None


def test_check_raises_the_crowning_to_the_load_where_flatter_profiles_lose(monkeypatch):
    """The 16×16's written drive design at 58.6 / 390.7 N m (54 / 95 µrad): the flatter
    profiles (2.33 and 0 µm) lower the light LTE but raise the design torque's, and are
    not kept; te_level 45 µrad moves nothing (stand-in 56 / 95 µrad: the crowning is ~96 %
    of the parabola); the crowning at the crossing, 7.97 µm, is analysed and kept (68 / 78 µrad)."""
    calls = []
    targets, setup, chosen = stand_in(monkeypatch, _fake(calls), [58.6, 390.7])
    values = {"path_angle": -88.0, "ellipse_length": 0.63, "tip_relief": 16.2,
              "root_relief": 10.2, "relief_start": 0.34, "profile_crowning": 4.67,
              "tip_relief_start": 0.9, "te_level": 10.0}
    start = chosen(values)
    calls.clear()
    lines = []
    got = steps.checked_crowning_lte(start, targets, setup, None, lines.append,
                                     lambda v: dict(v))
    designs = [c[:2] for c in calls if not c[2]]
    assert designs == [(2.33, 10.0), (0.0, 10.0), (4.67, 45.0), (7.97, 10.0)]
    assert got.values["profile_crowning"] == pytest.approx(4.67 + 2.335 * 41 / 29, abs=1e-9)
    assert list(got.metrics["lte_peak_to_peak"]) == [68.0, 78.0]
    assert any("its TE matched to the load" in x for x in lines)
    assert "the profile crowning matched to the load" in \
        setup["lte_reach"][(58.6, 390.7)]["tried"]


def test_no_crowning_no_match(monkeypatch):
    """A design without profile crowning (the ratio-3 designs the issue keeps: the
    passenger-car hypoid 10×43 and the FH 12×37's drive flanks) gets no crowning step."""
    calls = []
    targets, setup, _ = stand_in(monkeypatch, _fake(calls), [58.6, 390.7])
    values = {"path_angle": -88.0, "ellipse_length": 0.63, "profile_crowning": 0.0,
              "te_level": 45.0}
    start = _checked(values, _metrics(lte_peak_to_peak=[21.0, 107.0]), targets, 0.6)
    got = steps.checked_crowning_lte(start, targets, setup, None, lambda s: None,
                                     lambda v: dict(v))
    assert got is start and calls == []
