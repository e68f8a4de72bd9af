"""The check's step for a design torque's LTE above the target where the face contact ratio
is below 1 (:data:`contact.optimize.development_relief_lte.TIP_START`, issue 71): the tip
relief started later, at its bound.

Stand-in analyses whose law is the face-milled spiral bevel 15x28 at Σ 110° of
benchmarks/data/unseen_designs (ε_vα 1.19, ε_vβ 0.91) at 91.8 / 612.4 N m, as measured
with ``benchmarks/development_levers.py --check --at 10 200 300 400 500 --tolerance
--from-case`` on the case ``ltca synthesize`` wrote before the step (2026-11-27; the
numbers in the step's docstring and docs/synthesis.md, "LTE at every torque on a face
contact ratio below 1"): the tests are the step's choices, not numbers of a gear.
"""

from __future__ import annotations

import functools
import math

import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs as _seen
from development_stand_ins import stand_in

from contact.optimize import development_check as dcheck
from contact.optimize import development_relief_lte as dts
from contact.optimize.development import DevelopmentTargets

#: the step alone
check = functools.partial(dts.checked_relief_variants, reliefs=(dts.TIP_START,))

#: the 15x28's developed drive prescriptions as written before the step
WRITTEN = {"path_angle": -45.0, "ellipse_length": 0.7, "tip_relief": 15.0,
           "root_relief": 60.0, "relief_start": 0.2, "profile_crowning": 0.0,
           "tip_relief_start": 0.85, "blade_angle_change": 0.0, "te_level": 128.1}


def _fifteen_by_28(case, torques, misalignment=None, options=None, teeth=None,
                   pinion_key=(), flank="drive"):
    """The 15x28 at 91.8 / 612.4 N m through the measured tip-relief starts: 0.75 / 0.85 /
    0.9 → LTE 101 / 101, 90 / 103, 86 / 93 µrad (linear between them); the pattern and the
    edges as measured (length 0.55-0.60, centre v 0.60, edge 0.1-0.9 %), tolerant."""
    s = float(case["tip_relief_start"])
    if s <= 0.85:
        f = (s - 0.75) / 0.1
        light, design = 101.0 - 11.0 * f, 101.0 + 2.0 * f
    else:
        f = (s - 0.85) / 0.05
        light, design = 90.0 - 4.0 * f, 103.0 - 10.0 * f
    m = _metrics(pattern_toe_u=[0.23, 0.05], pattern_heel_u=[0.8, 1.0],
                 pattern_root_v=[0.29, 0.24], pattern_tip_v=[0.95, 1.0],
                 pattern_centre_u=[0.49, 0.5], pattern_centre_v=[0.60, 0.62],
                 edge_load_share=[0.0, 0.004], lte_peak_to_peak=[light, design],
                 lte_spread=[0.4, 0.15], pressure_max_flank=[879.0, 1313.0])
    return m, (0.0, 1.0, 0.0, 1.0, 2400.0)


def test_the_tip_relief_starts_at_its_bound_and_is_kept(monkeypatch):
    """ε_vβ 0.91, LTE 90 / 103 µrad at a tip-relief start 0.85: one design, the start at
    the bound of the development's variables (0.9), kept (ranks better, no target lost,
    tolerant); its LTE 86 / 93 µrad recorded for ltca synthesize's note."""
    seen, fake = _seen(_fifteen_by_28)
    targets, setup, chosen = stand_in(monkeypatch, fake, [91.8, 612.4])
    start = chosen(dict(WRITTEN))
    seen.clear()
    lines = []
    got = check(start, targets, setup, None, lines.append, lambda v: dict(v), eps=(1.19, 0.91))
    assert seen == [WRITTEN | {"tip_relief_start": 0.9}]
    assert got.stage == dts.TIP_START.stage and got.values == seen[0]
    light, design = (float(x) for x in got.metrics["lte_peak_to_peak"])
    assert (light, design) == pytest.approx((86.0, 93.0))
    assert got.objective < start.objective
    assert "tip_relief_start 0.9" in lines[0]
    assert not any("not kept" in s for s in lines)
    reach = setup["lte_reach"][(91.8, 612.4)]
    assert (reach["light"], reach["design"]) == pytest.approx((86.0, 93.0))
    assert reach["tried"] == (dts.TIP_START_LEVER,)


def test_a_later_start_that_scores_worse_is_not_kept(monkeypatch):
    """Where the later start raises the LTE (the law inverted), the design is said not
    kept and the start returned."""
    def worse(case, torques, misalignment=None, **kw):
        m, limits = _fifteen_by_28(case, torques, misalignment, **kw)
        if float(case["tip_relief_start"]) > 0.85:
            m = m | {"lte_peak_to_peak": m["lte_peak_to_peak"] + 30.0}
        return m, limits

    targets, setup, chosen = stand_in(monkeypatch, worse, [91.8, 612.4])
    start = chosen(dict(WRITTEN))
    lines = []
    got = check(start, targets, setup, None, lines.append, lambda v: dict(v), eps=(1.19, 0.91))
    assert got is start


@pytest.mark.parametrize("lte, eps, values", [
    ([30.0, 38.0], (1.19, 0.91), {}),  # the LTE target met at the design torque
    ([90.0, 103.0], (1.19, 1.00), {}),  # ε_vβ not below 1
    ([90.0, 103.0], (math.nan, math.nan), {}),  # unknown
    ([90.0, 103.0], (1.19, 0.91), {"tip_relief": 0.0}),  # no tip relief
    ([90.0, 103.0], (1.19, 0.91), {"tip_relief_start": 0.9}),  # at its bound already
])
def test_the_gate_costs_nothing(monkeypatch, lte, eps, values):
    """Where the design torque's LTE target is met, ε_vβ is not below 1 (or unknown), the
    design has no tip relief or its start is at the bound: the design returned as it is and
    nothing analysed; the ratios are not read unless every other condition holds."""
    read = []
    seen = []

    def fake(case, torques, misalignment=None, **kw):
        seen.append(dict(case))
        m, limits = _fifteen_by_28(case, torques, misalignment, **kw)
        return m | {"lte_peak_to_peak": m["lte_peak_to_peak"] * 0 + lte}, limits

    targets, setup, chosen = stand_in(monkeypatch, fake, [91.8, 612.4])
    start = chosen(dict(WRITTEN) | values)
    seen.clear()

    def ratios():
        read.append(1)
        return eps

    assert dts.tip_start_runs_on(start, targets, ratios) is False
    asked = lte[1] > targets.max_lte and not values
    assert read == ([1] if asked else [])
    monkeypatch.setattr(dts, "contact_ratios", lambda case: eps)
    assert check(start, targets, setup, None, print, lambda v: dict(v)) is start
    assert seen == []


def test_the_bound_is_the_users():
    """The start tried is the upper bound of ``tip_relief_start`` the targets carry (the
    default 0.9; a bound the user gave as given); none without a tip relief or a start."""
    assert dts.later_start(WRITTEN, DevelopmentTargets()) == 0.9
    narrow = DevelopmentTargets(variables=dict(DevelopmentTargets().variables)
                                | {"tip_relief_start": (0.5, 0.95)})
    assert dts.later_start(WRITTEN, narrow) == 0.95
    assert dts.later_start(WRITTEN | {"tip_relief_start": 0.897}, DevelopmentTargets()) is None
    assert dts.later_start({"tip_relief": 15.0}, DevelopmentTargets()) is None
    without = DevelopmentTargets(variables={k: v for k, v in DevelopmentTargets().variables
                                            .items() if k != "tip_relief_start"})
    assert dts.later_start(WRITTEN, without) is None


def test_the_step_runs_in_the_check_after_the_matched_te_step():
    """check_steps calls the relief variants (by name) after the matched-TE step and before
    the near-miss step, the later tip-relief start first."""
    import inspect

    src = inspect.getsource(dcheck.check_steps)
    assert (src.index("checked_matched_te(") < src.index("checked_relief_variants(")
            < src.index("checked_near_miss("))
    assert dts.RELIEFS == (dts.TIP_START, dts.LIGHTER, dts.TIP_LTE)
