"""The modified roll's 2C as step 5's second lever for the twist (issue 71, the 12x12 miter).

The face-milled spiral bevel miter 12x12 (benchmarks/data/unseen_designs/
spiral_bevel_12x12_miter_b35.toml) stops at step 6: its drive pinion's mismatch, made by
the ratio of roll alone (−22 % from the conjugate's), leaves a TE of +192 / −1050 µrad at
±pitch/4 against the parabola's 2.8 µrad. Step 5 given a 2C
(:func:`geometry.synthesis.pinion.pinion_generate_tools`'s ``roll_curvature``) meets the
same shape at M with another ratio of roll, and the 2C of
:func:`geometry.synthesis.roll_curvature.third_order_cancelling` removes the TE's cubic
at M. These tests check the flank made so against the equation of meshing written out
from docs/machine.md (not the library's machine transform), the secant on stand-ins, and
that step 6 keeps the 2C (docs/own_gear_set.md, "The 12-tooth miter and the modified
roll's 2C").
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from geometry.core.errors import InputError
from geometry.machine.flank_point import flank_points
from geometry.machine.relief import relief_places
from geometry.synthesis import case_synthesis as cs
from geometry.synthesis import modified_roll as mr
from geometry.synthesis.basic_design import load_basic
from geometry.synthesis.pinion import pinion_generate_tools
from geometry.synthesis.roll_curvature import (
    ROLL_CURVATURE_LIMIT,
    third_order_cancelling,
)

MITER12 = (Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"
           / "spiral_bevel_12x12_miter_b35.toml")


# --------------------------------------------------------------------------- stand-ins
def test_the_secant_finds_a_linear_cubic_s_root_in_one_step():
    """c3(2C) = 0.134 + 1.71·2C (the 12x12's drive flank's slope, rounded): the secant from
    0 and the first step lands on −0.134/1.71 to rounding (1e-15), with three tools made
    (0 given, the first step, the root)."""
    made = []

    def tools_at(c2):
        made.append(c2)
        return c2

    out = third_order_cancelling(tools_at, lambda c2: 0.134 + 1.71 * c2, c3_zero=0.134,
                                 tools_zero=0.0)
    assert out.c2 == pytest.approx(-0.134 / 1.71, abs=1e-15)
    assert out.tools == out.c2 and abs(out.c3) <= 1e-15
    assert out.c3_before == 0.134
    assert len(made) == 2


def test_the_secant_converges_on_a_mildly_curved_cubic():
    """c3 = 0.134 + 1.71 x + 3 x² (curvature 3 /rad⁴, larger than the 12x12's, whose odd
    part is linear within 1 % over 2C 0 to −0.1): the root of the quadratic, −0.0822…, to
    the tolerance 1e-3 of |c3(0)| (|c3| ≤ 1.34e-4, so 2C within 1e-4)."""
    f = lambda x: 0.134 + 1.71 * x + 3.0 * x * x  # noqa: E731
    root = (-1.71 + math.sqrt(1.71**2 - 4 * 3.0 * 0.134)) / 6.0
    out = third_order_cancelling(lambda c2: c2, f)
    assert abs(out.c3) <= 1e-3 * 0.134
    assert out.c2 == pytest.approx(root, abs=1e-4)


def test_a_cubic_2c_does_not_move_is_an_input_error_naming_2c():
    """A cubic 2C does not change (or changes so little that the secant leaves ±0.5 1/rad)
    is refused, naming the last 2C and both cubics."""
    with pytest.raises(InputError, match="no modified roll 2C within"):
        third_order_cancelling(lambda c2: c2, lambda c2: 1.0)
    with pytest.raises(InputError, match=r"cubic .* against 1.26 without it"):
        third_order_cancelling(lambda c2: c2, lambda c2: 1.26 + 0.1 * c2)
    assert ROLL_CURVATURE_LIMIT == 0.5


# --------------------------------------------------------------------------- the 12x12
def _drive_flank(monkeypatch, c2: float):
    """The 12x12's drive (concave) pinion flank of step 5 generated with 2C ``c2`` on the
    generated gear's crown gear (the process that applies to a ratio-1 pair), and step 6's
    inputs (spied: tools, tooth pair, start, rate, keywords)."""
    spied = []

    def spy(tools, pair, start, rate, **kw):
        spied.append((tools, pair, start, rate, kw))
        return tools

    def tools_2c(*a, **kw):
        return pinion_generate_tools(*a, roll_curvature=c2, **kw)

    monkeypatch.setattr(cs, "tune_roll", spy)
    monkeypatch.setattr(cs, "pinion_generate_tools", tools_2c)
    basic = load_basic(MITER12)
    geom = basic.blank()
    pair = cs._pair_data(basic, geom, "Generate", "gear", False)
    cs._unrelieved_flank(pair, "concave", basic.options.flank("concave"), None,
                         conjugate=False, say=lambda _s: None)
    return pair, spied[0]


def _rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def _ry(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1.0]])


def _rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1.0]])


def _t(x, y, z):
    m = np.eye(4)
    m[:3, 3] = x, y, z
    return m


def _chain(s, q, c2):
    """Cutter → blank of a face-milling Generate setting with the modified roll's 2C
    ``c2`` alone, written out from docs/machine.md: φ(q) = R_a (q − C q²), C = 2C/2;
    R_z(−φ) T(0,0,−X_p) R_y(γ_m − π/2) T(0,−E_m,X_b) R_z(q_c + q) T(S_r,0,0) R_z(j) R_x(i)."""
    assert not s.helical_motion and not s.vertical_motion
    phi = s.ratio_of_roll * (q - 0.5 * c2 * q * q)
    return (_rz(-phi) @ _t(0, 0, -s.machine_center_to_back)
            @ _ry(s.machine_root_angle - math.pi / 2) @ _t(0, -s.blank_offset, s.sliding_base)
            @ _rz(s.cradle_angle + q) @ _t(s.radial_setting, 0, 0) @ _rz(s.swivel)
            @ _rx(s.tilt))


def _velocity(s, q, r, c2, h=1e-6):
    """Velocity [mm/rad of cradle roll] of the cutter point at blank point r at roll q
    relative to the blank (central difference, error O(h²) ~ 1e-10 of |v|)."""
    local = np.linalg.solve(_chain(s, q, c2), np.append(r, 1.0))
    return ((_chain(s, q + h, c2) - _chain(s, q - h, c2)) @ local)[:3] / (2 * h)


def test_the_2c_flank_meets_the_equation_of_meshing_and_its_shape_at_m(monkeypatch):
    """Step 5 with 2C −0.08 on the 12x12's drive flank (1.4 s): the shape operator at M is
    met to 1e-8 1/mm and M to 1e-7 mm (pinion_generate_tools' own acceptance); at the mean
    section's M, tip end and root end (relief_places, rolls −0.36 to +0.15 rad) each point
    satisfies the equation of meshing with the independent chain, |n·v| ≤ 1e-7 |v| (the
    difference's error ~1e-10, the envelope solver's far below), and not without the 2C
    (|n·v| > 1e-4 |v| at the roll farthest from 0: the test sees the 2C); the ratio of roll
    moved (with the gear's cradle axis through its root apex, before branch shell85:
    towards the conjugate's 1.2485, 0.974 without 2C, 1.18 with it; through its pitch
    apex 1.399 with it: a regression anchor, the gear's tooth now ISO 23509's)."""
    c2 = -0.08
    pair, (tools, *_rest) = _drive_flank(monkeypatch, c2)
    s = tools.settings
    assert s.modified_roll == (c2,)
    assert tools.shape_error <= 1e-8 and tools.point_error <= 1e-7
    assert 1.35 < s.ratio_of_roll < 1.45
    places = relief_places(pair.pinion_blank, pair.gear_blank)
    fp = flank_points(tools.blade, s, pair.pinion_blank, "right", places[:, 0],
                      places[:, 1])
    assert fp.ok.all()
    qs, plain = [], []
    for k in range(len(places)):
        r, n, q = fp.r[k], fp.n[k], float(fp.params[k][2])
        v = _velocity(s, q, r, c2)
        assert abs(n @ v) <= 1e-7 * np.linalg.norm(v)
        v0 = _velocity(s, q, r, 0.0)
        qs.append(q)
        plain.append(abs(n @ v0) / np.linalg.norm(v0))
    far = int(np.argmax(np.abs(qs)))
    assert abs(qs[far]) > 0.2 and plain[far] > 1e-4


def test_the_2c_that_cancels_the_cubic_is_kept_by_step_6(monkeypatch):
    """The 12x12's drive flank (1.3 s): third_order_cancelling's 2C
    (+0.0121; −0.078 with the gear's cradle axis through its root apex, before branch
    shell85, whose gear tooth was 43 % thin at the mean pitch point) makes the TE's odd
    part at ±pitch/16, followed by the TCA's contact solve
    (seed Eq. 2.14, not the cubic's Richardson estimate the secant used), below 2 % of its
    value without 2C (4.84 µrad; +0.0 µrad to the 0.1 printed at the cancelling 2C,
    docs/own_gear_set.md); step 6 (tune_roll) keeps the 2C as given and puts the TE at ±pitch/4,
    followed again in 8 steps, on the parabola within 0.6 % (its tolerance 0.5 % and the
    roots' 1e-13 rad)."""
    _pair0, (tools0, tooth_pair0, start, rate, kw0) = _drive_flank(monkeypatch, 0.0)
    pitch, a21 = kw0["pitch"], kw0["a21"]
    rest = {k: v for k, v in kw0.items() if k not in ("pitch", "a21", "fraction", "warm")}
    kept = {}

    def tools_at(c2):
        if c2 == 0.0:
            return tools0
        _, (t, tp, _s, _r, kw) = _drive_flank(monkeypatch, c2)
        kept[id(t)] = (tp, {k: v for k, v in kw.items()
                            if k not in ("pitch", "a21", "fraction", "warm")})
        return t

    def pair_of(t):
        return (tooth_pair0, rest) if t is tools0 else kept[id(t)]

    def cubic(t):
        tp, r = pair_of(t)
        return mr.third_order_te(t, tp, start, rate, a21=a21, pitch=pitch, **r).c3

    out = third_order_cancelling(tools_at, cubic, tools_zero=tools0)
    assert 0.005 < out.c2 < 0.02
    h = pitch / 16

    def odd(t):
        tp, r = pair_of(t)
        te, _ = mr._te_at(tp, start, rate, rolls=(h, -h), **r)
        return 0.5 * (te[h] - te[-h])

    assert abs(odd(out.tools)) <= 0.02 * abs(odd(tools0))
    tp, r = pair_of(out.tools)
    tuned = mr.tune_roll(out.tools, tp, start, rate, a21=a21, pitch=pitch, **r)
    assert tuned.settings.modified_roll[0] == out.c2
    assert len(tuned.settings.modified_roll) == 3
    level = 0.5 * a21 * (pitch / 4) ** 2
    followed = mr.ToothPair(tp.pinion._replace(machine=tuned.settings), tp.gear,
                            tp.transforms)
    te, _ = mr._te_at(followed, start, rate, rolls=(pitch / 4, -pitch / 4), steps=8, **r)
    for v in te.values():
        assert v == pytest.approx(level, rel=6e-3)
