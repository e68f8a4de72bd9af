"""The roll window of one pair's contact on the unrelieved pinion flank
(:func:`geometry.pair.path_window.path_window`, issue 71; docs/synthesis.md, "The miter
20×20's contact path off the unrelieved flank").

The face-milled spiral bevel miter 20×20 of benchmarks/data/unseen_designs on its generated
gear, synthesised (no tip planes) at the drive prescriptions its development wrote: path
−45°, ellipse 0.70, te_level 10 µrad, tip relief 15 µm from 0.85 and root relief 15 µm from
0.5 of the way from M. The window is checked against an independent reading: the
conventional TCA of the *relieved* flank, which is the unrelieved one between the corners
(its TE the same there) and leaves it past them.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment
from geometry.pair.conventional_tca import conventional_tca
from geometry.pair.path_window import path_window
from geometry.synthesis.basic_design import load_basic
from geometry.synthesis.case_synthesis import synthesize

BASIC = (Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"
         / "spiral_bevel_20x20_miter.toml")


@cache
def _case(path_angle: float = -45.0, tip_relief: float = 0.015,
          root_relief: float = 0.015):
    """The miter at the written drive prescriptions but ``path_angle`` [deg] and the
    reliefs [mm] (~5-10 s CPU each, cached)."""
    basic = load_basic(BASIC)
    opt = basic.options
    drive = opt.drive_flank
    fo = replace(opt.flank(drive), path_angle=math.radians(path_angle), ellipse_length=0.70,
                 te_level=10e-6, tip_relief=tip_relief, root_relief=root_relief,
                 relief_start=0.5, tip_relief_start=0.85)
    case, _ = synthesize(replace(basic, options=replace(opt, gear_process="Generate",
                                                        **{drive: fo})), tip_planes=False)
    return replace(case, misalignment=Misalignment())


def test_the_written_miter_path_leaves_the_unrelieved_flank_within_a_pitch():
    """Path −45°: the window −0.35 … +0.25 pitch (measured; steps of 0.05), left at the
    tip relief's corner on the heel side of roll and the root relief's on the other, so
    neither transfer at ±0.5 pitch is on the designed parabola. Inside, the relieved
    flank's conventional TCA has the unrelieved flank's TE within 1e-4 µrad (a relief
    removes nothing between its corners); one step past the tip corner it no longer
    does (no contact found there: measured NaN at +0.30)."""
    case = _case()
    w = path_window(case)
    assert (w.low, w.high) == pytest.approx((-0.35, 0.25), abs=1e-9)
    assert not w.holds_pitch and w.span == pytest.approx(0.6)
    assert w.leaves_by() == "tip relief at +0.25 pitch"
    k = int(np.argmin(np.abs(w.roll - 0.30)))
    assert w.height[k] > w.tip_corner
    k = int(np.argmin(np.abs(w.roll + 0.40)))
    assert w.height[k] < w.root_corner
    pitch = 2 * math.pi / case.pinion.blank.teeth
    bare = conventional_tca(_case(-45.0, 0.0, 0.0), w.roll * pitch)
    relieved = conventional_tca(case, w.roll * pitch, initial=bare)
    inside = w.on_unrelieved
    assert np.all(np.abs(relieved.transmission_error[inside]
                         - bare.transmission_error[inside]) < 1e-10)
    past = int(np.argmin(np.abs(w.roll - (w.high + 0.05))))
    te_past = relieved.transmission_error[past]
    assert not np.isfinite(te_past) or abs(te_past - bare.transmission_error[past]) > 1e-7


def test_a_path_along_the_face_holds_a_pitch_on_the_unrelieved_flank():
    """Path 0° (past the contact line, along the face): the window −0.80 … +0.75 pitch
    holds ±0.5, each contact between the corners, left at the face's end (u < 0) —
    the face contact ratio 1.34 covers one pitch where the profile does not."""
    w = path_window(_case(0.0))
    assert w.holds_pitch and w.low == pytest.approx(-0.8) and w.high == pytest.approx(0.75)
    assert w.leaves_by() == "face end at +0.75 pitch"
    inside = w.on_unrelieved
    assert np.all((w.height[inside] > w.root_corner) & (w.height[inside] < w.tip_corner))
    assert w.face[-1] < 0.0


def test_a_path_across_the_contact_line_holds_a_pitch_too():
    """Path +30° (the angle the development's path-window step keeps first): the window
    −0.55 … +0.55 pitch, left at the root relief's corner; +45° no longer holds it
    (−0.50 … +0.45, the tip relief)."""
    w = path_window(_case(30.0))
    assert w.holds_pitch and (w.low, w.high) == pytest.approx((-0.55, 0.55))
    assert w.leaves_by() == "root relief at -0.55 pitch"
    w = path_window(_case(45.0))
    assert not w.holds_pitch and (w.low, w.high) == pytest.approx((-0.5, 0.45))


def test_a_bad_roll_list_is_an_input_error():
    with pytest.raises(InputError, match="rolls"):
        path_window(_case(), rolls=[0.1, 0.2])
    with pytest.raises(InputError, match="rolls"):
        path_window(_case(), rolls=[0.0, -0.1])
