"""The coast flank's own design torque (issue 71 item 2): the search that lowers it to what
the developed bearing carries, on synthetic coast flanks whose laws are known (no LTCA),
and the torques ``ltca run --flank coast`` analyses a case at."""

from __future__ import annotations

import dataclasses
import math
from types import MappingProxyType

import pytest

from contact.optimize.development_coast import (
    CLOSENESS,
    PLASTIC_STEP,
    CoastCheck,
    coast_capacity,
    coast_torque_step,
)

LIMIT = 2400.0  # MPa, the static strength of case-carburised steel at MQ (as the verdict's)


def _flank(p_at_300: float, a: float = 1.0 / 3.0, plastic_above: float = math.inf,
           root_at_300: float = math.nan, b: float = 1.0, light: float = 0.15):
    """A synthetic coast flank: flank peak p = p_at_300 (T/300)^a, plastic segments above
    ``plastic_above``, S_F,FE = root_at_300 (300/T)^b; the analysis records the torques."""
    seen = []

    def analyse(t: float) -> CoastCheck:
        seen.append(t)
        return CoastCheck(t, p_at_300 * (t / 300.0) ** a, LIMIT,
                          0.01 if t > plastic_above else 0.0,
                          root_at_300 * (300.0 / t) ** b, 1.3, "pinion",
                          root_at_300 * (300.0 / (light * t)) ** b, light * t)
    return analyse, seen


def test_a_hertzian_coast_flank_is_capped_in_one_step_at_its_static_capacity():
    """p ∝ T^(1/3) (Hertz's point contact, Johnson 1985 eq. 4.23): 3000 MPa at 300 N·m
    against 2400 MPa; one step T (0.99 p_lim/p)³ = 300 × 0.792³ = 149.0 N·m, where the
    same law gives 0.99 × 2400 MPa (an identity of the law, to the 0.1 N·m round-down:
    rel 1e-3), and the check there holds: two analyses, the reason in numbers."""
    analyse, seen = _flank(3000.0)
    cap = coast_capacity(analyse, 300.0)
    assert seen == [300.0, cap.torque]
    assert cap.torque == pytest.approx(300.0 * (0.99 * 2400.0 / 3000.0) ** 3, abs=0.1)
    assert 3000.0 * (cap.torque / 300.0) ** (1.0 / 3.0) == pytest.approx(0.99 * LIMIT,
                                                                          rel=1e-3)
    assert cap.holds and cap.lowered and cap.final.torque == cap.torque
    assert "3000 MPa above the static strength 2400 MPa" in cap.reason
    assert f"the largest that holds {cap.torque:.4g} N m, where flank peak pressure" in cap.reason


def test_a_slower_growing_peak_is_reached_by_the_measured_exponent():
    """p ∝ T^0.2 (a pattern that grows under load): the first, Hertzian step stops above
    the capacity; the second uses the exponent measured between the two checks (0.2,
    exact for this law) and lands at T (0.99 p_lim/p)^5 of the start, which holds; the
    estimate from the bracket is that torque again, so the search ends there."""
    analyse, seen = _flank(3000.0, a=0.2)
    cap = coast_capacity(analyse, 300.0)
    exact = 300.0 * (0.99 * LIMIT / 3000.0) ** 5
    assert len(seen) == 3 and cap.holds
    assert cap.torque == pytest.approx(exact, rel=2e-3)  # the round-down of each step
    assert cap.final.pressure <= LIMIT


def test_the_root_stress_capacity_uses_the_exponent_of_the_light_and_design_torque():
    """S_F,FE = 1.0 (300/T)^0.6 against S_Fmin 1.3: b = 0.6 measured between the light and
    the design torque of the first check (exact for this law), one step to
    300 (0.99/1.3)^(1/0.6), where S_F,FE = 1.3/0.99 >= 1.3."""
    analyse, seen = _flank(1500.0, root_at_300=1.0, b=0.6)
    cap = coast_capacity(analyse, 300.0)
    assert len(seen) == 2 and cap.holds
    assert cap.torque == pytest.approx(300.0 * (0.99 / 1.3) ** (1.0 / 0.6), abs=0.1)
    assert "S_F,FE 1.00 (pinion) below S_Fmin 1.3" in cap.reason


def test_plastic_segments_lower_the_torque_by_steps_then_back_up_to_the_edge():
    """Plastic above 200 N·m: down 300 → 255 → 216.7 → 184.1 N·m (× 0.85 each, rounded down
    to 0.1 N·m), the last without a plastic segment; then up by the bracket's geometric
    mean, 199.7 (holds) and 208.0 (fails): the torque written is within the bracket's
    closeness (1.05) of the true 200 N·m, below it."""
    analyse, seen = _flank(1500.0, plastic_above=200.0)
    cap = coast_capacity(analyse, 300.0)
    assert seen == [300.0, 255.0, 216.7, 184.1, 199.7, 208.0]
    assert cap.torque == 199.7 and cap.holds and PLASTIC_STEP == 0.85
    assert 200.0 / CLOSENESS < cap.torque <= 200.0
    assert "(at 208 N m: plastic segments" in cap.reason


def test_a_far_first_step_is_brought_back_up_to_the_capacity():
    """p ∝ T^0.9 (a peak on an edge, growing nearly with the load): the Hertzian first step
    lands at 149 N·m, far below; the bracket's exponent (0.9, exact) brings it up to
    T (0.99 p_lim/p)^(1/0.9) = 231.4 N·m, which holds: the torque written is what the
    bearing carries, not any torque below it."""
    analyse, seen = _flank(3000.0, a=0.9)
    cap = coast_capacity(analyse, 300.0)
    assert seen[:2] == [300.0, 149.0] and cap.holds
    # to the round-down of 0.1 N m and the exponent measured on the rounded 149.0
    assert cap.torque == pytest.approx(300.0 * (0.99 * LIMIT / 3000.0) ** (1 / 0.9), abs=0.2)


def test_a_coast_flank_that_holds_keeps_its_torque_and_a_failing_analysis_is_said():
    analyse, seen = _flank(2000.0, root_at_300=2.0)
    cap = coast_capacity(analyse, 300.0)
    assert seen == [300.0] and cap.torque == 300.0 and not cap.lowered and cap.reason == ""
    said = []

    def broken(t: float) -> CoastCheck:
        raise RuntimeError("mesh inverted")

    cap = coast_capacity(broken, 300.0, said.append)
    assert not cap.holds and cap.torque == 300.0 and "mesh inverted" in said[0]


def test_still_failing_after_the_last_step_is_said_as_such():
    """A flank beyond reach of the steps allowed keeps the last torque analysed and says
    "still"."""
    analyse, _ = _flank(3000.0, plastic_above=10.0)
    cap = coast_capacity(analyse, 300.0, n_steps=2)
    assert not cap.holds and "where still plastic segments" in cap.reason


def test_the_step_is_the_least_of_the_failing_criteria():
    c = CoastCheck(300.0, 3000.0, LIMIT, 0.02, 1.0, 1.3, "gear", 5.0, 45.0)
    t, why = coast_torque_step(c)
    assert why == "flank" and t == pytest.approx(149.0, abs=0.1)
    with pytest.raises(ValueError, match="start torque"):
        coast_capacity(lambda t: c, math.nan)


def test_ltca_run_analyses_the_coast_flank_at_its_own_design_torque():
    """A case whose [rating] coast_design_torque (150 N·m) is below its design torque
    (300 N·m): the coast flank (by role or by its pinion flank's name) runs at the
    [operating] torques with those above 150 N·m limited to it (repeats dropped), the drive
    flank at them; without a coast design torque below the design torque both run at the
    case's own."""
    from contact.catalogue import bundled_case_path
    from contact.pipeline import flank_torques
    from geometry.case import load_case

    case = load_case(bundled_case_path())
    case = dataclasses.replace(
        case, operating=dataclasses.replace(case.operating, torque=(45.0, 300.0)),
        extra=MappingProxyType(dict(case.extra) | {
            "rating": {"design_torque": 300.0, "coast_design_torque": 150.0}}))
    coast_flank = "convex" if case.pair.drive_flank == "concave" else "concave"
    assert flank_torques(case, "coast")[0] == (45.0, 150.0)
    assert flank_torques(case, coast_flank)[0] == (45.0, 150.0)
    assert "300 N m limited to its [rating] coast_design_torque 150 N m" in flank_torques(
        case, "coast")[1]
    three = dataclasses.replace(case, operating=dataclasses.replace(
        case.operating, torque=(50.0, 200.0, 250.0)))
    assert flank_torques(three, "coast")[0] == (50.0, 150.0)
    assert flank_torques(case, "drive") == ((45.0, 300.0), "")
    assert flank_torques(case, case.pair.drive_flank) == ((45.0, 300.0), "")
    same = dataclasses.replace(case, extra=MappingProxyType(
        dict(case.extra) | {"rating": {"design_torque": 300.0}}))
    assert flank_torques(same, "coast") == ((45.0, 300.0), "")


def test_ltca_run_says_it_limits_the_coast_torques(tmp_path, capsys):
    """``ltca run CASE --flank coast`` of a case with a coast design torque (the 5x43 hypoid
    of tests/data: [operating] 50/250/500 N·m, design 83.86, coast 80.45 N·m) analyses
    50 and 80.45 N·m and prints why."""
    from pathlib import Path

    import xarray as xr

    from contact.cli import main

    case = Path(__file__).parent / "data" / "hypoid_5x43_case.toml"
    out = tmp_path / "coast.nc"
    assert main(["run", str(case), "--flank", "coast", "--no-root-stress", "--no-progress",
                 "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert ("coast flank: the case's [operating] torques 250, 500 N m limited to its "
            "[rating] coast_design_torque 80.45 N m") in text
    tree = xr.open_datatree(out)
    assert list(tree["/ltca"]["torque"].values) == [50.0, 80.45]


def test_a_coast_design_torque_at_or_below_the_light_torque_is_scored_at_its_one_torque():
    """Where the coast flank holds only at or below the light torque, ``ltca run --flank
    coast`` (:func:`contact.pipeline.flank_torques`) analyses that one torque, and the
    development's coast check scores it as both its light and its design torque (a spiral
    bevel 19x23 whose Formate coast flank held only below the light torque ended `ltca
    synthesize` with ``IndexError: index 1 is out of bounds``, issue 71's unseen designs).
    The bundled case's coast flank at 30 N·m under a light torque of 45 N·m."""
    from types import SimpleNamespace

    import numpy as np

    from contact.catalogue import bundled_case_path
    from contact.optimize.development_coast_flank import _coast_check
    from contact.optimize.development_targets import DevelopmentTargets, development_score
    from geometry.case import load_case

    case = load_case(bundled_case_path())
    check = _coast_check(case, SimpleNamespace(operating={}), {"torques": (45.0, 300.0)},
                         30.0, root_stress=False)
    metrics, grid, torques = check.result
    assert torques == (30.0,) and check.torque == 30.0
    for name, value in metrics.items():  # the one analysis, as light and as design torque
        assert len(value) == 2, name
        np.testing.assert_array_equal(value[0], value[1])
    objective, shortfalls, _ = development_score(metrics, DevelopmentTargets(), grid[:4],
                                                 pressure_limit=grid[4])
    assert np.isfinite(objective) and "edge" in shortfalls
