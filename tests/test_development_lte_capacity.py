"""The design torque lowered where the chosen design's drive LTE FAILs ``ltca run``'s
verdict (:mod:`contact.optimize.development_lte_capacity`, issue 71).

The stand-in's LTE p-p against the torque is the ratio-1 spiral bevel 16x16 at Σ 60° of
benchmarks/data/unseen_designs as written before the step (docs/synthesis.md, "The LTE at
the design torque: the teeth's deflection": 45 / 47 / 111 / 122 µrad at 97.4 / 281.4 /
465.4 / 649.4 N m, 57 µrad at 45 N m), linear between: the tests are the rule's choices,
not numbers of a gear.
"""

from __future__ import annotations

import numpy as np
import pytest
from development_stand_ins import lte_law_start

from contact.optimize.development_lte_capacity import lte_capacity
from contact.optimize.development_variant import lte_fails

#: (torque [N m], LTE p-p [µrad]) of the 16x16's written bearing
_LAW = ((45.0, 57.0), (97.4, 45.0), (281.4, 47.0), (465.4, 111.0), (649.4, 122.0))
_VALUES = {"path_angle": -80.0, "ellipse_length": 0.675}


def _start(monkeypatch, law=_LAW, torques=(97.4, 649.4)):
    return lte_law_start(monkeypatch, law, torques, _VALUES)


def test_a_fail_level_lte_lowers_the_design_torque_to_where_it_keeps_60(monkeypatch):
    """The 16x16: 122 µrad at 649.4 N m (FAIL beyond 120); its LTE at four torques from
    the light to the design torque crosses 60 µrad at 281.4 + 13/64 × 184 = 318.78 N m:
    the design torque lowered there, 318.7 rounded down (the light torque 0.15 × it),
    the LTE within 60 µrad at both, said with the numbers."""
    targets, setup, best, seen = _start(monkeypatch)
    assert lte_fails(best)
    lines: list[str] = []
    got = lte_capacity(best, targets, setup, None, lines.append)
    assert seen[0] == pytest.approx((97.4, 281.4, 465.4, 649.4))
    assert setup["lowered"] is True
    assert setup["torques"][1] == pytest.approx(318.7, abs=1e-9)
    assert setup["torques"][0] == pytest.approx(targets.light_load * 318.7, abs=0.1)
    assert not lte_fails(got)
    assert np.all(got.metrics["lte_peak_to_peak"] <= 60.0)
    assert len(seen) == 2  # the four torques, then the lowered pair
    assert lines and "649.4 -> 318.7 N m" in lines[0] and "45 / 47 / 111 / 122" in lines[0]
    assert "keeps the drive LTE within 60 urad" in setup["source"]


def test_a_lowered_torque_still_above_the_limit_is_analysed_again(monkeypatch):
    """A law whose LTE rises steeper between the torques analysed than linear (60 µrad
    crossed at 300, 100 µrad at 330 N m): the first cut (≈ 341 N m, 121 µrad there: still
    FAIL) is added to the torques the crossing is found between, the second keeps 60."""
    law = ((45.0, 50.0), (97.4, 45.0), (281.4, 47.0), (300.0, 60.0), (330.0, 100.0),
           (340.0, 121.0), (465.4, 111.0), (649.4, 122.0))
    targets, setup, best, seen = _start(monkeypatch, law)
    got = lte_capacity(best, targets, setup, None, lambda s: None)
    assert len(seen) >= 3
    assert setup["torques"][1] < 341.0
    assert not lte_fails(got)


def test_no_cut_where_the_lte_passes_or_no_torque_keeps_the_limit(monkeypatch):
    """An LTE within the FAIL level (the same law, 110 µrad at the design torque): no
    analysis, the design and setup unchanged; an LTE above 60 µrad at the light torque
    already (no torque below keeps it): unchanged after the one analysis."""
    passing = ((45.0, 57.0), (97.4, 45.0), (465.4, 100.0), (649.4, 110.0))
    targets, setup, best, seen = _start(monkeypatch, passing)
    assert lte_capacity(best, targets, setup, None, lambda s: None) is best
    assert seen == [] and "lowered" not in setup
    high = ((45.0, 90.0), (97.4, 80.0), (649.4, 130.0))
    targets, setup, best, seen = _start(monkeypatch, high)
    assert lte_capacity(best, targets, setup, None, lambda s: None) is best
    assert len(seen) == 1 and "lowered" not in setup


def test_the_lowering_numbers_are_named_as_before_the_development(monkeypatch):
    """The FM 13x17 at Σ 50° (round 31, docs/own_gear_set.md): its design-torque line read
    "keeps the drive LTE within 60 urad ... 61 / 58 urad at 18.4 / 122.7 N m" while the
    written design ran 48 / 54 µrad: the numbers are the bearing at the lowering, before
    the development at the new torque. A law 62 µrad at 45 N m, linear to 45 at 97.4: at
    the lowered 318.7 N m's light torque 0.15 × 318.7 = 47.8 N m it reads
    62 − 17 × 2.8 / 52.4 ≈ 61.1 µrad (> 60), the design torque 60 µrad (the crossing):
    the line says both that these are the bearing before its development and that the
    light torque's is above the limit; with _LAW's 56 µrad there it says no such thing."""
    law = ((45.0, 62.0), *_LAW[1:])
    targets, setup, best, _ = _start(monkeypatch, law)
    lte_capacity(best, targets, setup, None, lambda s: None)
    assert setup["torques"][1] == pytest.approx(318.7, abs=1e-9)
    assert "at the lowering 61 / 60 urad at" in setup["source"]
    assert "the light torque's above 60 urad" in setup["source"]
    assert "the bearing before its development at this torque" in setup["source"]
    targets, setup, best, _ = _start(monkeypatch)
    lte_capacity(best, targets, setup, None, lambda s: None)
    assert "above 60 urad (the bearing" not in setup["source"]
    assert "the bearing before its development at this torque" in setup["source"]
