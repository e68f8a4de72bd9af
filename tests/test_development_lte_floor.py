"""The load sharing's floor of the LTE between two torques and what ``ltca synthesize``
says of the development's LTE target against it
(:mod:`contact.optimize.development_lte_floor`, issue 71).

The floor is ½ p-p(TE_design − TE_light); the identity it rests on is p-p(a − b) ≤
p-p(a) + p-p(b), so max(LTE_light, LTE_design) ≥ floor whatever the unloaded TE (which
cancels). Tested on a stated TE law (exact) and on a real analysis of the bundled default
case (the bound, to round-off).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.optimize import development_lte_floor as dlf
from contact.optimize.development_lte_lines import flank_lte_line

ROOT = Path(__file__).resolve().parents[1]


def _dataset(te: np.ndarray, torques) -> xr.Dataset:
    return xr.Dataset({"transmission_error": (("torque", "roll"), te)},
                      coords={"torque": np.asarray(torques, float)})


def test_the_floor_is_half_the_deflections_change_whatever_the_unloaded_te():
    """TE(φ, T) = UTE(φ) + δ(φ, T): the floor is ½ p-p(δ_design − δ_light) exactly (the
    unloaded TE cancels: a parabola of any depth added leaves it), and both torques' LTE
    is at least the floor (the identity), for every depth of the parabola."""
    phi = np.linspace(-0.5, 0.5, 41)  # one mesh cycle, in pitches
    light = 300.0 + 20.0 * (np.abs(phi) > 0.3)  # a hand-over at light load [µrad]
    design = 1500.0 + 80.0 * (np.abs(phi) > 0.3) + 10.0 * np.cos(2 * np.pi * phi)
    expected = 0.5 * np.ptp(design - light)
    for depth in (0.0, 30.0, 120.0, 400.0):
        ute = depth * phi**2
        te = np.stack([ute + design, ute + light])  # the design torque first: sorted
        ds = _dataset(te, [400.0, 60.0])
        floor = dlf.te_floor(ds)
        assert floor == pytest.approx(expected, rel=1e-12)
        lte = [np.ptp(ute + light), np.ptp(ute + design)]
        assert max(lte) >= floor - 1e-9


def test_nan_rolls_are_left_out_and_one_torque_has_no_floor():
    te = np.array([[0.0, 1.0, np.nan, 3.0], [0.0, 5.0, 7.0, 1.0]])
    # the difference 0, 4, (NaN), −2: p-p 6 over the three rolls with both values
    assert dlf.te_floor(_dataset(te, [10.0, 20.0])) == pytest.approx(0.5 * 6.0)
    assert math.isnan(dlf.te_floor(_dataset(te[:1], [10.0])))
    with pytest.raises(ValueError, match="0 < light < design"):
        dlf.load_sharing_floor(None, 50.0, 50.0)


def test_the_bound_on_a_real_analysis_of_the_default_case():
    """The bundled default case at 50 / 500 N m (``ltca run``'s sampling): the floor is
    positive and below the larger of the two torques' LTE p-p, to round-off (1e-9 µrad:
    the LTE p-p is the p-p of the same TE samples, contact.ltca.transmission_error)."""
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis
    from geometry.case import load_case

    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    tree = run_analysis(case, [50.0, 500.0], flank="drive", deviations=False,
                        steps=AnalysisChain.contact_only())
    ltca = tree["/ltca"].to_dataset()
    floor = dlf.te_floor(ltca)
    lte = np.asarray(ltca["lte_peak_to_peak"].values, float)
    assert 0.0 < floor <= float(np.max(lte)) + 1e-9
    assert dlf.load_sharing_floor(case, 50.0, 500.0) == pytest.approx(floor, rel=1e-12)


def test_the_words_on_either_side_of_the_target():
    """Below the target: the bearing misses it; at or above: out of the bearing's reach,
    the levers that lower the floor named; NaN: nothing said."""
    above = dlf.floor_text(27.0, 40.0)
    assert "floor 1/2 p-p(TE_design - TE_light) 27 urad" in above
    assert "the target 40 urad is above it" in above and "bearing's LTE" in above
    at = dlf.floor_text(41.0, 40.0)
    assert "at or below it, out of this bearing's reach" in at
    assert "higher contact ratios" in at
    assert dlf.floor_text(math.nan, 40.0) == ""


def test_the_drive_line_says_the_floor_where_the_target_is_missed():
    """``ltca synthesize``'s drive LTE line (the 13x33 at Σ 85°'s numbers, 2026-11-29):
    the floor appended where the target is missed within the verdict's limit; the line as
    before without a floor, and none where the target is met."""
    args = ("drive", (59.0, 393.5), (16.0, 53.0), {"peak": 54.5, "at": 282.0}, 60.0, 40.0)
    before = flank_lte_line(*args)
    assert before.endswith("the development's target 40 urad missed")
    with_floor = flank_lte_line(*args, floor=26.7)
    assert with_floor.startswith(before) and "floor 1/2 p-p" in with_floor
    assert flank_lte_line("drive", (59.0, 393.5), (16.0, 38.0), None, 60.0, 40.0,
                          floor=26.7) is None
