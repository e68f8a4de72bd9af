"""Profile relief (tip and root) of the pinion flank: the synthesis input and its conversion.

The conversion (:mod:`geometry.machine.relief`) turns a prescribed normal relief δ at the flank's
tip and root ends into the blade's flankrem and toprem by the closed form of two straight
lines through a corner. It is checked here on what the generator makes of the relieved
blade, not on the formula: the flank cut with the relieved blade is measured along the
unrelieved flank's normals as a CMM would (:func:`geometry.synthesis.correction.cmm_deviation`, an
envelope solution per point), at the two ends and at M.
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from geometry.case import case_from_dict, load_case
from geometry.core.errors import InputError
from geometry.machine.flank_point import flank_points
from geometry.machine.relief import blade_relief, relief_places, relieved_blade
from geometry.synthesis.basic_design import basic_from_dict
from geometry.synthesis.case_synthesis import synthesize
from geometry.synthesis.correction import cmm_deviation
from geometry.synthesis.tip_plane import move_tip_plane

ROOT = Path(__file__).resolve().parents[1]
BASIC = ROOT / "cases" / "basic" / "kolivand2009_fm_11x41.toml"
CASE = ROOT / "cases" / "kolivand2009_fm_11x41.toml"


@cache
def _committed():
    return load_case(CASE)


def _raw(**synthesis):
    raw = tomllib.loads(BASIC.read_text(encoding="utf-8"))
    raw["synthesis"].update(synthesis)
    return raw


def _measured(case, relieved, flank):
    """Deviation [µm] of the relieved pinion flank along the nominal normals at (M, tip
    end, root end); negative = material removed."""
    mem = case.pinion
    tool = mem.flank(flank)
    places = relief_places(mem.blank, case.gear.blank)
    pts = flank_points(tool.blade, tool.machine, mem.blank, mem.hand, places[:, 0],
                       places[:, 1])
    return 1e3 * cmm_deviation(relieved, "pinion", flank, pts.r, pts.n)[0]


def _with_blade(case, flank, blade):
    tool = dataclasses.replace(case.pinion.flank(flank), blade=blade)
    return dataclasses.replace(case, pinion=dataclasses.replace(case.pinion, **{flank: tool}))


@cache
def _relieved_synthesis():
    """The default basic file synthesised with 20 µm tip and 15 µm root relief (~4 s)."""
    return synthesize(basic_from_dict(_raw(tip_relief=20.0, root_relief=15.0)))[0]


@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_synthesised_relief_is_measured_at_the_flank_ends(flank):
    """A basic file with ``tip_relief = 20``, ``root_relief = 15`` µm gives the committed
    (unrelieved) machine settings and point radius up to the tip plane's place along the
    cutter axis (step 8; the relief's corners lie away from M,
    so steps 4–6 of the synthesis are unchanged, to the synthesis' 1e-9 reproducibility),
    and its pinion flank, measured against the unrelieved flank, is eased off by the
    prescription at the two ends and not at M.

    Tolerances: at M 1e-6 µm (the CMM solve is good to 1e-11 mm; M lies between the
    corners, where the flank is the unrelieved one); at the ends 5 %: the conversion is
    exact to first order in δ, the second-order term is about 3.7 mm · δ/L² of the relief
    (L the blade height from corner to end, 1.3–2.4 mm here), measured 0.3 % at the tip
    and 3–4 % at the root for these reliefs (the order is checked in
    :func:`test_relief_error_is_second_order`).
    """
    case, committed = _relieved_synthesis(), _committed()
    new, old = case.pinion.flank(flank), committed.pinion.flank(flank)
    # Step 8 places each cut's tip plane by the root line its edge radius generates; the
    # root relief (toprem) turns the profile the edge radius is tangent to, so the
    # relieved cut's tip plane lies elsewhere along the cutter axis (measured 2.0 µm
    # concave, 0.12 µm convex) and with it the radial setting, cradle angle, swivel,
    # sliding base and point radius (geometry.synthesis.tip_plane.move_tip_plane), the
    # cutting surface unchanged. Moved onto the committed cut's tip plane (Δ from the
    # sliding base, which takes Δ cos i), the settings must be the committed ones.
    moved = (old.machine.sliding_base - new.machine.sliding_base) / math.cos(new.machine.tilt)
    assert abs(moved) < 0.015  # a fraction of the 15 µm root relief, not a new placement
    blade, machine = move_tip_plane(new.blade, new.machine, moved)
    for field in ("radial_setting", "cradle_angle", "swivel", "ratio_of_roll",
                  "sliding_base", "blank_offset", "machine_root_angle"):
        assert getattr(machine, field) == pytest.approx(getattr(old.machine, field),
                                                        rel=1e-9, abs=1e-9)
    assert blade.point_radius == pytest.approx(old.blade.point_radius, rel=1e-9)
    assert new.blade.flankrem_angle > 0 > new.blade.toprem_angle
    measured = _measured(committed, case, flank)
    assert abs(measured[0]) < 1e-6
    np.testing.assert_allclose(-measured[1:], [20.0, 15.0], rtol=0.05)
    info = case.extra["synthesis"][flank]
    assert info["tip_relief_um"] == pytest.approx(20.0)
    assert info["root_relief_um"] == pytest.approx(15.0)


def test_relieved_case_round_trips_through_toml():
    """The relief is written to the case file (toprem/flankrem in deg and mm) and read back
    to the same blade (TOML floats: 1e-12 relative)."""
    case = _relieved_synthesis()
    back = case_from_dict(tomllib.loads(case.to_toml()))
    for flank in ("concave", "convex"):
        a, b = case.pinion.flank(flank).blade, back.pinion.flank(flank).blade
        for field in ("toprem_angle", "toprem_height", "flankrem_angle", "flankrem_height"):
            assert getattr(b, field) == pytest.approx(getattr(a, field), rel=1e-12)


def test_relief_error_is_second_order():
    """Halving δ halves the relative error of the measured relief (error ∝ δ², the
    conversion exact to first order), within 10 % of the factor 2 (third-order terms)."""
    case = _committed()
    tool = case.pinion.concave
    errors = []
    for delta in (0.02, 0.01):
        blade = relieved_blade(tool.blade, tool.machine, case.pinion.blank, case.pinion.hand,
                               case.gear.blank, tip_relief=delta, root_relief=delta)
        m = _measured(case, _with_blade(case, "concave", blade), "concave")
        errors.append(-m[1:] / (1e3 * delta) - 1.0)
    ratio = np.asarray(errors[0]) / np.asarray(errors[1])
    np.testing.assert_allclose(ratio, 2.0, rtol=0.1)


@pytest.mark.parametrize(("tip", "root", "start"), [(30.0, 10.0, 0.85), (12.0, 0.0, 0.5),
                                                    (0.0, 20.0, 0.3)])
def test_blade_relief_inverts_relieved_blade(tip, root, start):
    """:func:`blade_relief` of a relieved blade returns the relief it was made with — the
    two solve the same normal-distance equation at the same blade heights, so they agree
    to Brent's tolerance (xtol 1e-14 rad on the rem angle, ≈ 1e-9 µm here; 1e-6 µm
    stated). A start value of a relieved case (``contact.optimize.start_values``, the
    optimiser's start) is this measurement: it used to fail with "targets must be
    finite" when the relieved tip end left the generated flank."""
    from contact.optimize import start_values

    case = _committed()
    tool = case.pinion.concave
    blade = relieved_blade(tool.blade, tool.machine, case.pinion.blank, case.pinion.hand,
                           case.gear.blank, tip_relief=1e-3 * tip, root_relief=1e-3 * root,
                           start=start)
    got = blade_relief(blade, tool.machine, case.pinion.blank, case.pinion.hand,
                       case.gear.blank)
    np.testing.assert_allclose(1e3 * np.asarray(got), [tip, root], atol=1e-6)
    relieved = _with_blade(case, "concave", blade)
    np.testing.assert_allclose(start_values(relieved, "concave", ["tip_relief", "root_relief"]),
                               [tip, root], atol=1e-6)


def test_cmm_deviation_survives_points_leaving_the_flank():
    """A nominal point whose Newton step leaves the generated flank comes back NaN, and
    the other points are still measured (the iteration used to pass the NaN on to the
    envelope solver, which refused every point). Points: M and the two ends of the
    unrelieved flank, plus M moved 30 mm off the flank along its lengthwise tangent (no
    generated point there); the three on the flank give the same deviations as alone
    (1e-9 µm: the same Newton iterates)."""
    case = _committed()
    relieved = _relieved_synthesis()
    mem = case.pinion
    tool = mem.concave
    places = relief_places(mem.blank, case.gear.blank)
    pts = flank_points(tool.blade, tool.machine, mem.blank, mem.hand, places[:, 0],
                       places[:, 1])
    off = pts.r[0] + np.array([0.0, 0.0, 30.0])
    r = np.vstack([pts.r, off])
    n = np.vstack([pts.n, pts.n[0]])
    dev = cmm_deviation(relieved, "pinion", "concave", r, n)[0]
    alone = cmm_deviation(relieved, "pinion", "concave", pts.r, pts.n)[0]
    assert np.isnan(dev[3])
    np.testing.assert_allclose(dev[:3], alone, atol=1e-12)


def test_zero_relief_leaves_the_blade_alone():
    """No relief: the blade comes back without rems (and the flank is the committed one)."""
    case = _committed()
    tool = case.pinion.concave
    blade = relieved_blade(tool.blade, tool.machine, case.pinion.blank, case.pinion.hand,
                           case.gear.blank, tip_relief=0.0, root_relief=0.0)
    assert blade == tool.blade
    assert math.isclose(blade.toprem_angle, 0.0) and math.isclose(blade.flankrem_angle, 0.0)


@pytest.mark.parametrize("patch, match", [
    ({"tip_relief": -1.0}, "tip_relief"),
    ({"root_relief": 250.0}, "root_relief"),
    ({"relief_start": 1.0}, "relief_start"),
    ({"concave": {"tip_relief": "a"}}, "synthesis.concave.tip_relief"),
])
def test_bad_relief_names_the_field(patch, match):
    with pytest.raises(InputError, match=match):
        basic_from_dict(_raw(**patch), fit=False)


def test_a_tip_relief_of_its_own_start_moves_only_the_flankrem():
    """``tip_start`` (the basic file's ``tip_relief_start``) places the flankrem's corner at
    h_M + tip_start (h_tip − h_M) and leaves the toprem where ``start`` puts it; the relief
    at the ends is still the prescribed one (:func:`blade_relief`, the inverse, to Brent's
    tolerance as above); ``tip_start=None`` is ``start`` (the same blade, bit for bit)."""
    from geometry.machine.relief import relief_heights

    case = _committed()
    tool, mem = case.pinion.concave, case.pinion
    kw = dict(tip_relief=0.020, root_relief=0.015, start=0.3)
    both = relieved_blade(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank,
                          **kw)
    assert relieved_blade(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank,
                          tip_start=None, **kw) == both
    short = relieved_blade(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank,
                           tip_start=0.85, **kw)
    h = relief_heights(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    assert short.flankrem_height == pytest.approx(h.mean + 0.85 * (h.tip - h.mean), rel=1e-12)
    assert both.flankrem_height == pytest.approx(h.mean + 0.3 * (h.tip - h.mean), rel=1e-12)
    assert (short.toprem_height, short.toprem_angle) == (both.toprem_height, both.toprem_angle)
    # the same relief over a shorter ramp: a steeper rem
    assert short.flankrem_angle > both.flankrem_angle > 0.0
    got = blade_relief(short, tool.machine, mem.blank, mem.hand, case.gear.blank)
    np.testing.assert_allclose(1e3 * np.asarray(got), [20.0, 15.0], atol=1e-6)
    with pytest.raises(InputError, match="tip_relief_start"):
        relieved_blade(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank,
                       tip_start=1.0, **kw)


def test_the_basic_file_reads_tip_relief_start():
    """``[synthesis] tip_relief_start`` (per flank too) is read, validated with its name,
    and recorded in the case's ``[synthesis.<flank>]`` only where it differs from
    ``relief_start`` (the cases of files without it unchanged); without it the flank's
    prescriptions give ``relief_start`` as the tip relief's start."""
    from geometry.synthesis.basic_design import flank_option_values

    basic = basic_from_dict(_raw(tip_relief=20.0, relief_start=0.4, tip_relief_start=0.85))
    assert basic.options.concave.tip_relief_start == 0.85
    assert basic.options.concave.tip_start == 0.85
    plain = basic_from_dict(_raw(relief_start=0.4))
    assert plain.options.concave.tip_relief_start is None
    assert flank_option_values(plain.options.concave)["tip_relief_start"] == 0.4
    with pytest.raises(InputError, match=r"synthesis.*tip_relief_start"):
        basic_from_dict(_raw(tip_relief_start=1.5))
