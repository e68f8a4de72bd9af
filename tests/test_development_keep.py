"""The check steps' one keep rule (:func:`contact.optimize.development_check.kept_why`) and
the path step's bar (a height step's design turned towards the profile is asked for its
tolerance only where it could replace the design kept; issue 71, the synthesize CPU).

Stand-in designs and analyses: the tests are the rule's decisions, not numbers of a gear.
"""

from __future__ import annotations

import math

from development_stand_ins import checked as _checked
from development_stand_ins import metrics as _metrics

from contact.optimize import development_check as dcheck
from contact.optimize.development import DevelopmentTargets


def _design(values, metrics, targets=None):
    """A checked design scored on ``metrics`` (:func:`development_score`, centre v 0.6)."""
    return _checked(dict(values), metrics, targets or DevelopmentTargets(), 0.6)


def test_the_keep_rule_asks_better_then_lost_then_tolerant(monkeypatch):
    """A design scoring no better is refused without asking for its tolerance; one that
    loses a met target is refused and said; one better, losing nothing and tolerant is
    kept (empty reason); the tolerance is asked only then, and ``tolerant=False`` skips it.
    With ``lost_first`` (the near-miss step) the lost target is said even where the design
    is no better."""
    asked = []

    def tolerant(e, targets, setup, teeth, say):
        asked.append(e.values["x"])
        return e.values["x"] != 9.0

    # kept_why asks its own module (development_keep) for the tolerance
    monkeypatch.setattr("contact.optimize.development_keep._tolerant_variant", tolerant)
    best = _design({"x": 0.0}, _metrics(lte_peak_to_peak=[45.0, 50.0]))  # misses the LTE
    assert not best.met
    worse = _design({"x": 1.0}, _metrics(lte_peak_to_peak=[60.0, 70.0]))
    better = _design({"x": 2.0}, _metrics())
    # better on the LTE, but its light-load centre v leaves the band best met
    lost = _design({"x": 3.0}, _metrics(lte_peak_to_peak=[20.0, 30.0],
                                        pattern_centre_v=[0.75, 0.7]))
    untolerant = _design({"x": 9.0}, _metrics())
    lines = []

    def why(e, **kw):
        return dcheck.kept_why(best, e, DevelopmentTargets(), {}, None, lines.append,
                               "the step", **kw)

    assert why(None) == "it could not be analysed"
    assert why(worse, lost=dcheck.lost_targets) == "it scores no better"
    assert asked == [] and lines == []
    assert why(lost, lost=dcheck.lost_targets) == "it misses centre_v"
    assert lines == ["  not kept: the step misses centre_v"] and asked == []
    assert why(better, lost=dcheck.lost_targets) == "" and asked == [2.0]
    assert why(untolerant).startswith("not tolerant") and asked == [2.0, 9.0]
    assert why(untolerant, tolerant=False) == "" and asked == [2.0, 9.0]
    # lost first: said although the design is no better (the near-miss step's order)
    lines.clear()
    no_better = _design({"x": 4.0}, _metrics(lte_peak_to_peak=[60.0, 70.0],
                                             pattern_centre_v=[0.75, 0.7]))
    assert why(no_better, lost=dcheck.lost_targets, lost_first=True).startswith("it misses")
    assert len(lines) == 1
    assert why(no_better, lost=dcheck.lost_targets).startswith("it scores no better")
    assert len(lines) == 1


def test_the_path_step_of_a_height_design_asks_no_tolerance_it_cannot_use(monkeypatch):
    """Under a height step (:func:`kept_height_step`), a path design that ranks better than the
    height design but not better than the design kept (``bar``) cannot be the outcome: it
    is not asked for its tolerance (no excursion analysis), and the outcome is the one
    without the bar. Stand-in analyses: the LTE falls as the path turns, never below the
    kept design's."""
    from contact.optimize import development as dev

    excursions = []

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        if misalignment is not None:  # a tolerance check: counted, elastic and clear
            excursions.append(case["path_angle"])
            return _metrics(), (0.0, 1.0, 0.0, 1.0, 2400.0)
        assert options is dev.CHECK_LTCA
        lte = 80.0 + 0.5 * (case["path_angle"] + 60.0)  # -60: 80, -75: 72.5, -80: 70
        return (_metrics(lte_peak_to_peak=[lte, lte]), (0.0, 1.0, 0.0, 1.0, 2400.0))

    monkeypatch.setattr("contact.optimize.development_evaluate.analyse_design", fake)
    targets, setup = DevelopmentTargets(), {"torques": [50.0, 330.0], "centre_v": 0.6}
    height = _design({"path_angle": -60.0, "ellipse_length": 0.55},
                     _metrics(lte_peak_to_peak=[80.0, 80.0]))
    kept = _design({"path_angle": -50.0, "ellipse_length": 0.6},
                   _metrics(lte_peak_to_peak=[45.0, 45.0]))
    lines = []
    # without the bar: the path design is kept over the height design (asked its tolerance)
    alone = dcheck.checked_path(height, targets, setup, None, lines.append,
                                lambda v: dict(v))
    assert alone is not height and excursions
    assert math.isclose(float(alone.metrics["lte_peak_to_peak"][1]), 70.0)
    # the height step: the outcome is the kept design either way, no excursion asked
    excursions.clear()
    setup = {"torques": [50.0, 330.0], "centre_v": 0.6}  # no memo of the run above
    got = dcheck.kept_height_step(height, kept, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    assert got is kept and excursions == []
