"""What a progress line's "targets met" says (:func:`~contact.optimize.development_evaluate.
met_text`; round 29: the 13x50's bearing stage said "(all targets met)" of a design 1.7 %
plastic, the bearing stage scoring no edge or plastic share; issue 71, branch tol89)."""

from __future__ import annotations

import dataclasses

from development_stand_ins import checked as _checked
from development_stand_ins import metrics as _metrics

from contact.optimize.development import DevelopmentTargets
from contact.optimize.development_evaluate import evaluation_line, met_text
from contact.optimize.development_targets import STAGE_TERMS


def test_the_bearing_stage_says_its_own_targets():
    e = _checked({"x": 0.0}, _metrics(plastic_share=[0.0, 0.017]), DevelopmentTargets(), 0.6)
    bearing = dataclasses.replace(e, met=True, stage="bearing")
    left = [k for k in STAGE_TERMS["relief"] if k not in STAGE_TERMS["bearing"]]
    assert "plastic" in left and "edge" in left  # the stage the line is about scores neither
    text = met_text(bearing)
    assert text.startswith(" (the bearing stage's targets met;") and "plastic" in text
    assert "all targets met" not in evaluation_line(bearing, 36, "bearing")
    for stage in ("relief", "height", "te", "tolerance"):  # every target, or a check step's
        assert met_text(dataclasses.replace(bearing, stage=stage)) == " (all targets met)"
    assert met_text(dataclasses.replace(bearing, met=False)) == ""
