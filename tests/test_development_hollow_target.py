"""The drive development's last step: the hollow profile with the tip relief deeper for the
development's own LTE target, tried on the design as it is written, after the edge-peak
step (contact.optimize.development_hollow_target, issue 71).

Stand-in analyses whose law is the face-hobbed hypoid 9x39 at Sigma 95 deg of
benchmarks/data/unseen_designs as ``benchmarks/development_levers.py --from-case --check
--at 100.7 166.6`` measured its written bearing (root relief 15 um after the edge-peak
step) and the development's analysis of the design before that step (root relief 9.55 um),
both at ltca run's sampling (2026-11-28, branches lte84 and edge85; docs/synthesis.md,
"The development and development_levers 1 % apart on the 9x39's edge"); and the identity
behind the step's place: the bench's analysis of a design and the development's check of
the same design are the same numbers (the passenger-car hypoid 10x43 of tests/data/designs).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.optimize import development_hollow_target as dt
from contact.optimize import development_range_lte as drl
from contact.optimize.development_targets import scaled_variables

TORQUES = (42.9, 286.0)
#: the torques of the bench's rows [N m] (the development's two and --at's two)
BENCH = (42.9, 100.7, 166.6, 286.0)

#: the written drive bearing of the 9x39 (case written by ltca synthesize, branch lte84)
WRITTEN = {"path_angle": -71.25, "ellipse_length": 0.65, "tip_relief": 13.93,
           "root_relief": 15.0, "relief_start": 0.5, "profile_crowning": 2.3344,
           "tip_relief_start": 0.8487, "blade_angle_change": 0.0, "te_level": 10.0}
#: the root relief the check's steps left before the edge-peak step deepened it [um]
BEFORE_EDGE_PEAK = 9.5467

#: (root relief [um], profile crowning [um]) -> (edge share at the design torque [1],
#: LTE p-p [urad] at BENCH, tolerant); measured: the written design 0.98 %, 38 / 25 / 50 /
#: 44; crowning -5 / -3 um with the tip relief 20.9 um 1.40 / 1.15 %, 34 / 23 / 40 / 37 and
#: 36 / 23 / 42 / 38, tolerant; before the edge-peak step 1.66 %, LTE 37.3 / 42.3 at the
#: two torques, and its hollow designs 2.40 / 2.06 %, 30.7 / 34.6 and 34.0 / 36.4; with the
#: root relief 10 um deeper (the development's check, branch edge85): 25 um 0.22 / 0.11 %,
#: 34.8 / 38.6 and 37.7 / 39.5; 19.55 um 0.76 / 0.56 %, 34.2 / 37.6 and 37.2 / 39.0 (at
#: 100.7 / 166.6 N m, where only the two torques were measured, the 15 um rows' values,
#: within 60 urad as the LTE over the range the bench measured on those)
ROWS = {(15.0, 2.3344): (0.0098, (38.5, 25.0, 50.0, 43.8), True),
        (15.0, -5.0): (0.0140, (33.6, 23.0, 40.0, 36.5), True),
        (15.0, -3.0): (0.0115, (36.3, 23.0, 42.0, 37.9), True),
        (BEFORE_EDGE_PEAK, 2.3344): (0.0166, (37.3, 25.0, 48.0, 42.3), True),
        (BEFORE_EDGE_PEAK, -5.0): (0.0240, (30.7, 22.0, 39.0, 34.6), True),
        (BEFORE_EDGE_PEAK, -3.0): (0.0206, (34.0, 22.0, 41.0, 36.4), True),
        (25.0, -5.0): (0.0022, (34.8, 23.0, 41.0, 38.6), True),
        (25.0, -3.0): (0.0011, (37.7, 23.0, 43.0, 39.5), True),
        (BEFORE_EDGE_PEAK + 10.0, -5.0): (0.0076, (34.2, 23.0, 40.0, 37.6), True),
        (BEFORE_EDGE_PEAK + 10.0, -3.0): (0.0056, (37.2, 23.0, 42.0, 39.0), True)}
#: (root relief [um], profile crowning [um]) -> the edge peaks at the design torque [MPa]
#: (gear tip, pinion edge), measured by the development's check (branch edge85); the
#: static strength 2400 MPa
PEAKS = {(15.0, 2.3344): (3467.0, 2475.0), (15.0, -5.0): (4480.0, 0.0),
         (15.0, -3.0): (4247.0, 0.0), (25.0, -5.0): (2577.0, 0.0),
         (25.0, -3.0): (2149.0, 0.0), (BEFORE_EDGE_PEAK, 2.3344): (4380.0, 2455.0),
         (BEFORE_EDGE_PEAK, -5.0): (5226.0, 0.0), (BEFORE_EDGE_PEAK, -3.0): (5019.0, 0.0),
         (BEFORE_EDGE_PEAK + 10.0, -5.0): (3740.0, 0.0),
         (BEFORE_EDGE_PEAK + 10.0, -3.0): (3472.0, 0.0)}


def _law(rows=ROWS, peaks=None):
    def law(case, torques, misalignment=None, **kw):
        ts = tuple(float(t) for t in torques) or TORQUES
        key = (round(float(case["root_relief"]), 4), round(float(case["profile_crowning"]), 4))
        edge, curve, tolerant = rows[key]
        m = {k: np.resize(v, len(ts)) for k, v in _metrics().items()}
        m["edge_load_share"] = np.resize([0.0, edge], len(ts))
        m["lte_peak_to_peak"] = np.asarray(np.interp(ts, BENCH, curve), float)
        if misalignment is not None and not tolerant:
            m["plastic_share"] = np.resize([0.0, 0.001], len(ts))
        if peaks:
            tip, pinion = peaks.get(key, (0.0, 0.0))
            m["edge_static_strength"] = np.full(len(ts), 2400.0)
            m["edge_peak_gear_tip"] = np.resize([0.0, tip], len(ts))
            m["edge_peak_pinion_edge"] = np.resize([0.0, pinion], len(ts))
            for kind in ("gear_heel", "gear_toe"):
                m[f"edge_peak_{kind}"] = np.zeros(len(ts))
            m["edge_peak"] = np.resize([0.0, max(tip, pinion)], len(ts))
        return m, (0.0, 1.0, 0.0, 1.0, 2400.0)

    return law


def _start(chosen, values=WRITTEN):
    start = chosen(dict(values))
    return dataclasses.replace(start, case=dict(start.values))


def test_the_designs_are_the_hollow_profiles_with_the_tip_relief_deeper():
    targets = dt.DevelopmentTargets()
    got = dt.target_designs(WRITTEN, targets)
    # tip relief 13.93 x 1.5 = 20.895 um; nothing else but the crowning changed
    # then the same with the root relief 10 um deeper (15 -> 25 um)
    assert [(d["profile_crowning"], d["root_relief"]) for d in got] == [
        (-5.0, 15.0), (-3.0, 15.0), (-5.0, 25.0), (-3.0, 25.0)]
    assert all(d == WRITTEN | {"tip_relief": 20.895, "profile_crowning": d["profile_crowning"],
                               "root_relief": d["root_relief"]} for d in got)
    # a small module's bounds (size scale 0.5): the crowning and the root relief's step
    # halved, the tip relief clipped to its halved upper bound (60 x 0.5)
    small = dataclasses.replace(targets, variables=scaled_variables(0.5))
    half = dt.target_designs(WRITTEN | {"tip_relief": 25.0}, small)
    assert [(d["profile_crowning"], d["root_relief"]) for d in half] == [
        (-2.5, 15.0), (-1.5, 15.0), (-2.5, 20.0), (-1.5, 20.0)]
    assert {d["tip_relief"] for d in half} == {30.0}
    assert dt.target_designs({"path_angle": -71.25}, targets) == []


def test_kept_on_the_written_design_without_edge_peaks(monkeypatch):
    """The written bearing (LTE 43.8 urad against 40, nothing else missed, 50 urad at most
    over the torques), no edge peak read: crowning -5 um with the tip relief 20.9 um meets
    every target (36.5 urad, edge 1.4 %) and ends the step (nothing else tried)."""
    seen, fake = seen_designs(_law())
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    assert [k for k, v in start.full[1].items() if v > 0.0] == ["lte"]
    assert dt.target_runs_on(start, targets, setup, None)
    seen.clear()
    lines: list[str] = []
    got = dt.checked_hollow_target(start, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    assert [(s["profile_crowning"], s["root_relief"]) for s in seen] == [(-5.0, 15.0)] * len(
        seen)
    assert got.stage == dt.STAGE and got.full[2]
    assert got.values == WRITTEN | {"tip_relief": 20.895, "profile_crowning": -5.0}
    # 36.5 urad at the design torque, the law's own number (no rounding on the way)
    assert float(got.metrics["lte_peak_to_peak"][-1]) == pytest.approx(36.5, abs=1e-9)
    record = drl.range_record(setup)
    assert record["values"] == got.values and record["peak"] <= 60.0
    assert "kept with the hollow profile for the LTE target" in lines[-1]
    assert any("its LTE 44 urad at the design torque against 40" in s for s in lines)


def test_the_edge_peak_steps_gain_kept(monkeypatch):
    """As measured on the 9x39: the hollow profile lifts the gear tip's edge peak the
    edge-peak step had lowered (3467 -> 4480 / 4247 MPa against 2400): both refused; with
    the root relief 10 um deeper, -5 um (gear tip 2577 MPa, pinion edge none above 2400,
    LTE 38.6 urad, edge 0.22 %) is kept and ends the step."""
    seen, fake = seen_designs(_law(peaks=PEAKS))
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    seen.clear()
    lines: list[str] = []
    got = dt.checked_hollow_target(start, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    tried = list(dict.fromkeys((s["profile_crowning"], s["root_relief"]) for s in seen
                               if s["profile_crowning"] < 0.0))  # the design's own range apart
    assert tried == [(-5.0, 15.0), (-3.0, 15.0), (-5.0, 25.0)]
    assert sum(s.endswith("misses the edge peak") for s in lines) == 2
    assert got.full[2] and got.values == WRITTEN | {
        "tip_relief": 20.895, "profile_crowning": -5.0, "root_relief": 25.0}
    assert float(got.metrics["lte_peak_to_peak"][-1]) == pytest.approx(38.6, abs=1e-9)


def test_before_the_edge_peak_step_the_edge_target_is_lost(monkeypatch):
    """What lte84's recipe inside the check's step saw: the root relief 9.55 um (before the
    edge-peak step deepened it), where the two hollow designs carry 2.40 / 2.06 % on the
    edges (limit 2 %): -5 um ranks below the design (its objective 0.99 against the 0.38
    of the design's LTE shortfall), -3 um loses the edge target; the bench reads the same
    numbers of the same design (test_the_bench_and_the_development_read_a_design_alike)."""
    seen, fake = seen_designs(_law())
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen, WRITTEN | {"root_relief": BEFORE_EDGE_PEAK})
    seen.clear()
    lines: list[str] = []
    got = dt.checked_hollow_target(start, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    assert any(s.endswith("misses edge") for s in lines)
    # the root relief 10 um deeper (19.55 um: edge 0.76 %, LTE 37.6 urad) is kept
    assert got.values["root_relief"] == pytest.approx(BEFORE_EDGE_PEAK + 10.0, abs=1e-9)
    assert got.values["profile_crowning"] == -5.0 and got.full[2]


def test_the_gate(monkeypatch):
    """Already hollow; another target missed (the edge share 2.1 %); the LTE above the
    verdict's 60 urad between the torques (the check's hollow-profile step's case): the
    design is returned as it is, no hollow design tried."""
    seen, fake = seen_designs(_law())
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    hollow = _start(chosen, WRITTEN | {"profile_crowning": -5.0})
    assert not dt.target_runs_on(hollow, targets, setup, None)
    for row in ((0.021, (38.5, 25.0, 50.0, 43.8), True), (0.0098, (38.5, 70.0, 70.0, 43.8),
                                                          True)):
        rows = dict(ROWS) | {(15.0, 2.3344): row}
        seen, fake = seen_designs(_law(rows))
        targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
        start = _start(chosen)
        seen.clear()
        got = dt.checked_hollow_target(start, targets, setup, None, lambda s: None,
                                       lambda v: dict(v))
        assert got is start
        assert all(s["profile_crowning"] == 2.3344 for s in seen)


def test_the_bench_and_the_development_read_a_design_alike():
    """The identity the 1 % on the 9x39 was not a defect of: a design's drive flank as
    ``benchmarks/development_levers.py --check`` analyses it (the synthesis with the tip
    planes placed, ``run_analysis``'s contact chain at ``ltca run``'s sampling with the kept
    shell teeth, ``design_metrics``) and as the development's check does
    (:func:`~contact.optimize.development_variant.checked_analysis`: ``placed_case``,
    ``analyse_design`` at CHECK_LTCA) are the same numbers, on the passenger-car hypoid
    10x43 with a hollow profile and the tip relief deeper. Tolerance 1e-9 relative: the
    same ease-off, compliance and LTCA solve on both paths (measured equal bit for bit on
    the 9x39; 1e-9 leaves the summation order of the tree's datasets free)."""
    import functools

    from contact.chain import AnalysisChain
    from contact.optimize import development as dev
    from contact.optimize.development_check import placed_case
    from contact.optimize.development_variant import checked_analysis
    from contact.pipeline import run_analysis
    from geometry.synthesis.basic_design import (
        flank_option_values,
        load_basic,
        with_flank_options,
    )
    from geometry.synthesis.case_synthesis import synthesize

    path = Path(__file__).resolve().parents[1] / "tests" / "data" / "designs"
    basic = load_basic(path / "pc_hypoid_10x43.toml")
    flank = basic.options.drive_flank
    values = dict(flank_option_values(basic.options.flank(flank)))
    values |= {"profile_crowning": -3.0,
               "tip_relief": 1.5 * max(float(values.get("tip_relief", 0.0)), 10.0)}
    torques = [40.0, 250.0]
    memo: dict = {}
    # the bench's row
    teeth = dev.KeptTeeth()
    case = synthesize(with_flank_options(basic, flank, values), memo=memo,
                      tip_planes=True)[0]
    opts = dataclasses.replace(dev.CHECK_LTCA,
                               compliance=teeth.compliance(dev.bearing_key(values)))
    tree = run_analysis(case, torques, flank="drive", options=opts, deviations=False,
                        steps=AnalysisChain.contact_only())
    bench = dev.design_metrics(tree, case)
    # the development's check
    placed = functools.partial(placed_case, basic, flank, memo)
    _, checked, _ = checked_analysis({"torques": torques}, placed, values, dev.KeptTeeth(),
                                     dev.bearing_key(values))
    for k in ("edge_load_share", "lte_peak_to_peak", "pattern_tip_v", "plastic_share",
              "pressure_max_flank"):
        np.testing.assert_allclose(np.asarray(checked[k], float),
                                   np.asarray(bench[k], float), rtol=1e-9, atol=1e-12,
                                   err_msg=k)
