"""Tip and root relief on every blade profile the synthesis makes (issue 60, item 1).

The relief solve (:func:`geometry.machine.relief.rem_angle`) used to bracket the rem angle
on one side of zero only and within ±19° regardless of the blade angle, so on circular
profiles of either curvature sign it failed with "needs a rem angle beyond 19 deg" for
15 µm where the closed form gives ~0.5°. Checked here, independently of the solve:

* on the blade: the relieved edge's normal distance from the unrelieved circular profile
  at the end height, measured as the distance to the circle through three points of the
  unrelieved edge (plane geometry, not the solve's own measure);
* on the generated flank: the relieved flank measured along the unrelieved flank's
  normals at the flank's tip and root ends as a CMM does
  (:func:`geometry.synthesis.correction.cmm_deviation`), on the pinion blades of every
  bundled case made from a basic file and of the four user designs of
  ``tests/data/designs/`` (both flanks, face milling and face hobbing, convex and concave
  circular profiles, one root end on the edge radius).

The whole synthesis with the default 15 µm relief on those basic files is the slow test
at the end (15–40 s a design).
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from geometry.case import load_case
from geometry.machine.cutter import Blade, blade_profile, profile_sections
from geometry.machine.flank import FlankSurface
from geometry.machine.flank_point import flank_points
from geometry.machine.relief import (
    ReliefError,
    _march,
    relief_heights,
    relief_places,
    relieved_blade,
    rem_angle,
)
from geometry.synthesis.correction import cmm_deviation

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "tests" / "data" / "designs"
#: bundled cases synthesised from a basic file of the same name (cases/basic/)
BUNDLED = sorted(p.stem for p in (ROOT / "cases" / "basic").glob("*.toml"))
#: the user designs' synthesis without relief (tests/data/designs/*_unrelieved.toml)
USER = sorted(p.name for p in DESIGNS.glob("*_unrelieved.toml"))
CASES = [ROOT / "cases" / f"{n}.toml" for n in BUNDLED] + [DESIGNS / n for n in USER]


def _plain(blade: Blade) -> Blade:
    return dataclasses.replace(blade, toprem_angle=0.0, toprem_height=0.0,
                               flankrem_angle=0.0, flankrem_height=0.0)


@cache
def _case(path: Path):
    """The case with its pinion rems removed (the *_reference cases carry an optimised
    relief: the relief is measured from the rem-less flank)."""
    case = load_case(path)
    mem = case.pinion
    tools = {f: dataclasses.replace(mem.flank(f), blade=_plain(mem.flank(f).blade))
             for f in ("concave", "convex")}
    return dataclasses.replace(case, pinion=dataclasses.replace(mem, **tools))


def _with_blade(case, flank, blade):
    tool = dataclasses.replace(case.pinion.flank(flank), blade=blade)
    return dataclasses.replace(case, pinion=dataclasses.replace(case.pinion, **{flank: tool}))


def _measured(case, flank, tip, root):
    """Normal deviation [µm] of the flank cut with the relieved blade at (M, tip end, root
    end) of the unrelieved flank (negative: material removed). The envelope solver is
    seeded by the unrelieved points, followed from M (a root end on the fillet is missed
    from a cold start)."""
    mem = case.pinion
    tool = mem.flank(flank)
    places = relief_places(mem.blank, case.gear.blank)
    par = np.array([_march(tool.blade, tool.machine, mem.blank, mem.hand, places[0],
                           places[k], None) for k in range(3)])
    pts = flank_points(tool.blade, tool.machine, mem.blank, mem.hand, places[:, 0],
                       places[:, 1], guess=par)
    assert pts.ok.all()
    blade = relieved_blade(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank,
                           tip_relief=tip, root_relief=root)
    guess = FlankSurface(*([None] * 11), s=par[:, 0], theta=par[:, 1], q=par[:, 2],
                         section=par[:, 3].astype(int), reason=None)
    dev = cmm_deviation(_with_blade(case, flank, blade), "pinion", flank, pts.r, pts.n,
                        guess=guess)[0]
    return 1e3 * dev, blade


@pytest.mark.parametrize("flank", ["concave", "convex"])
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_relief_is_measured_on_the_generated_flank(path, flank):
    """15 µm of tip and root relief on every synthesised pinion blade: the generated flank
    is eased off by 15 µm at both ends and not at M.

    Tolerances: M 1e-6 µm (between the corners the flank is the unrelieved one; the CMM
    solve converges to 1e-11 mm). Ends 6 %: the conversion is exact to first order in δ
    on the blade; generating adds a second-order term (∝ δ/L², L the blade length from
    corner to end; the halving test below checks the order), measured at most 5.0 % (root
    end of pc_hypoid_10x43's concave flank, L = 1.25 mm) and 0.9 % at the tip ends.
    """
    delta = 15.0
    dev, blade = _measured(_case(path), flank, 1e-3 * delta, 1e-3 * delta)
    assert abs(dev[0]) < 1e-6
    np.testing.assert_allclose(-dev[1:], [delta, delta], rtol=0.06)
    assert blade.flankrem_angle != 0.0 and blade.toprem_angle != 0.0


def test_relief_error_on_the_flank_is_second_order():
    """Richardson: with m(δ) = δ (1 + c δ), 2 m(δ/2)/(δ/2) − m(δ)/δ = 1 + O(δ²). On the
    worst end of the sweep above (pc_hypoid_10x43 concave, root: 5.0 % at 15 µm) the
    extrapolated ratio is 1 within 1 % (measured 0.3 %: third-order terms), so the
    conversion is exact to first order also on a circular profile."""
    case = _case(DESIGNS / "pc_hypoid_10x43_unrelieved.toml")
    ratios = []
    for delta in (15.0, 7.5):
        dev, _ = _measured(case, "concave", 1e-3 * delta, 1e-3 * delta)
        ratios.append(-dev[1:] / delta)
    np.testing.assert_allclose(2.0 * ratios[1] - ratios[0], 1.0, atol=0.01)


def _circle(points: np.ndarray) -> tuple[np.ndarray, float]:
    """Centre and radius of the circle through three (ρ, h) points."""
    (x1, y1), (x2, y2), (x3, y3) = points
    a = np.array([[x2 - x1, y2 - y1], [x3 - x1, y3 - y1]])
    b = 0.5 * np.array([x2**2 - x1**2 + y2**2 - y1**2, x3**2 - x1**2 + y3**2 - y1**2])
    c = np.linalg.solve(a, b)
    return c, float(np.hypot(*(points[0] - c)))


def _edge_at(blade: Blade, h: float) -> np.ndarray:
    sec = profile_sections(blade)
    s = np.linspace(0.0, 40.0, 400001)
    p = blade_profile(sec, s)
    k = int(np.argmin(np.abs(p.h - h)))
    # linear interpolation between the two samples around h (1e-4 mm apart)
    k0, k1 = (k - 1, k) if p.h[k] > h else (k, k + 1)
    w = (h - p.h[k0]) / (p.h[k1] - p.h[k0])
    return np.array([p.rho[k0] + w * (p.rho[k1] - p.rho[k0]), h])


@pytest.mark.parametrize("side", ["outside", "inside"])
@pytest.mark.parametrize("radius", [-60.0, -800.0, 800.0, 150.0, None])
def test_rem_line_leaves_the_profile_by_the_relief(side, radius):
    """On straight and circular profiles of either curvature (|R_pr| 60–800 mm; the
    synthesis makes 900–1e5 mm; R −60 mm bends the edge by ~30 µm over the span, twice
    the relief; R 150 mm by 13 µm towards the relief side, just short of it), both blade
    sides: the relieved edge at the end height lies δ = 15 µm from the
    unrelieved profile, measured as the distance to the circle through three points of the
    unrelieved edge (exact for the circle; the line: the distance to it), on the material
    side. Tolerance 2e-5 mm: the edge is sampled every 1e-4 mm of arc and interpolated
    linearly (error ≤ h²κ/8 ≈ 1e-11 mm) — the 1e-5 mm is the solve's horizontal-distance
    measure against the true normal distance, O(δ²/R) ≤ 4e-9 mm, well inside."""
    kw = (dict(profile="circular", profile_radius=radius, profile_reference_height=4.0)
          if radius is not None else {})
    blade = Blade(side=side, point_radius=60.0, blade_angle=math.radians(20.0),
                  edge_radius=0.8, **kw)
    h_mean, tip, root, delta = 4.0, 8.0, 1.6, 0.015
    for corner, end in ((0.5 * (h_mean + tip), tip), (0.5 * (h_mean + root), root)):
        d_alpha = rem_angle(blade, corner, end, delta)
        up = end > corner
        rem = (dict(flankrem_angle=d_alpha, flankrem_height=corner) if up else
               dict(toprem_angle=d_alpha, toprem_height=corner))
        relieved = dataclasses.replace(blade, **rem)
        q = _edge_at(relieved, end)
        pts = np.array([_edge_at(blade, h) for h in (end, 0.5 * (corner + end), corner)])
        if radius is None:
            t = (pts[2] - pts[0]) / np.linalg.norm(pts[2] - pts[0])
            dist = abs((q - pts[0])[0] * t[1] - (q - pts[0])[1] * t[0])
        else:
            c, r = _circle(pts)
            assert r == pytest.approx(abs(radius), rel=1e-4)
            dist = abs(np.linalg.norm(q - c) - r)
        assert dist == pytest.approx(delta, abs=2e-5)
        # material side: the relieved cutter lies further out (σ) than the profile
        assert blade.sigma * (q[0] - pts[0][0]) > 0.0


def test_straight_profile_is_the_closed_form():
    """A straight profile: tan(α + Δα) = tan α ± δ/(|h_e − h_c| cos α) (module docstring),
    to round-off."""
    a = math.radians(22.0)
    blade = Blade(side="inside", point_radius=50.0, blade_angle=a, edge_radius=0.5)
    for hc, he, sign in ((5.0, 8.0, 1.0), (3.0, 1.0, -1.0)):
        want = math.atan(math.tan(a) + sign * 0.02 / (abs(he - hc) * math.cos(a))) - a
        assert rem_angle(blade, hc, he, 0.02) == pytest.approx(want, abs=1e-13)


def test_impossible_relief_names_the_input_and_what_works():
    """150 µm over 0.05 mm of blade needs a flankrem of ~70°: the error names
    ``tip_relief``, says how much this span takes and the blade length the relief needs —
    and a corner that leaves that length does make it."""
    blade = Blade(side="outside", point_radius=60.0, blade_angle=math.radians(20.0),
                  edge_radius=0.8, profile="circular", profile_radius=900.0,
                  profile_reference_height=4.0)
    with pytest.raises(ReliefError, match=r"^tip_relief: .*needs at least") as info:
        rem_angle(blade, 7.95, 8.0, 0.15)
    assert info.value.field == "tip_relief"
    need = info.value.span[0]
    assert f"needs at least {need:.3g} mm of blade" in str(info.value)
    d_alpha = rem_angle(blade, 8.0 - 1.01 * need, 8.0, 0.15)
    assert 0.0 < d_alpha < math.radians(19.0)


def test_profile_turning_away_faster_than_the_relief_says_what_works():
    """A convex profile of R 60 mm turns ~33 µm away from its tangent over the 2 mm from
    corner to end: a 15 µm rem line would first add material (a bump). The error names
    ``tip_relief``, gives the relief that works and the longest span that works; a corner
    leaving that span then gives the relief."""
    blade = Blade(side="outside", point_radius=60.0, blade_angle=math.radians(20.0),
                  edge_radius=0.8, profile="circular", profile_radius=60.0,
                  profile_reference_height=4.0)
    with pytest.raises(ReliefError, match=r"^tip_relief: .*would first add material; "
                                          r"give tip_relief >= 3\d\.\d um") as info:
        rem_angle(blade, 6.0, 8.0, 0.015)
    longest = info.value.span[1]
    assert 0.0 < longest < 2.0
    # the relief it names, as a number: the profile's own turn over the span
    least = info.value.least
    assert f"give tip_relief >= {math.ceil(least * 1e4) / 10:.4g} um" in str(info.value)
    assert abs(rem_angle(blade, 6.0, 8.0, 1.01 * least)) < math.radians(19.0)
    # a flankrem below the nominal blade angle, but beyond the profile's own turn
    assert abs(rem_angle(blade, 8.0 - 0.99 * longest, 8.0, 0.015)) < math.radians(19.0)


def test_relieved_blade_turns_the_span_into_a_relief_start():
    """Through :func:`relieved_blade` the advice is a ``relief_start``: 60 µm of tip relief
    from 0.999 of the way to the tip needs a 16° flankrem over 5 µm of blade... beyond the
    model; the start it names works."""
    case = _case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    tool, mem = case.pinion.concave, case.pinion
    args = (tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    with pytest.raises(ReliefError, match=r"relief_start <= (0\.\d\d) would work") as info:
        relieved_blade(*args, tip_relief=0.06, root_relief=0.0, start=0.999)
    assert info.value.field == "tip_relief"
    start = float(info.value.args[0].split("relief_start <= ")[1].split(" ")[0])
    relieved_blade(*args, tip_relief=0.06, root_relief=0.0, start=start)


def test_root_relief_corner_in_the_edge_radius_names_relief_start():
    """A toprem corner inside the edge radius (spiral_bevel_13x39 concave, whose root end
    lies on the fillet): ReliefError on ``relief_start`` with the largest start that
    works — which then works."""
    case = _case(DESIGNS / "spiral_bevel_13x39_unrelieved.toml")
    tool, mem = case.pinion.concave, case.pinion
    args = (tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    with pytest.raises(ReliefError, match=r"relief_start: .* <= ") as info:
        relieved_blade(*args, tip_relief=0.0, root_relief=0.015, start=0.999)
    assert info.value.field == "relief_start"
    most = float(info.value.args[0].split("relief_start <= ")[1].split(" ")[0])
    relieved_blade(*args, tip_relief=0.0, root_relief=0.015, start=most)


def test_tip_plane_leaving_the_root_relief_in_the_edge_radius_names_relief_start():
    """``ltca synthesize --no-development`` of the spiral bevel 13x37 at Σ 60° of
    benchmarks/data/unseen_designs: step 8 moves the pinion's tip plane shallower, which
    leaves the root relief's corner within the blade's edge radius 0.894 mm. The error
    names the basic file's ``relief_start`` and the largest start that places it, which then
    synthesises (issue 71; before, "depth: moving the tip plane ... toprem_height" named no
    field). With its default relief_start 0.5 the corner sat at 0.881 mm until the generated
    gear's pinion was cut on the gear's own crown gear (session 14): that pinion's corner
    clears the blade's edge radius up to relief_start 0.89 and step 8's placed tip plane up
    to 0.85 (measured), so 0.95 (beyond both) and 0.87 (beyond step 8's alone) are asked
    here. The bound printed is the one that synthesises, at the first try: at 0.95 step 7
    printed the blade's own 0.89 before, which step 8 then refused with 0.85 (two rounds
    for a user who follows it); step 7's message now takes step 8's move into account
    (``case_synthesis._relief_start_placed``), and both name the same start."""
    from geometry.synthesis.basic_design import load_basic, with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    given = load_basic(ROOT / "benchmarks" / "data" / "unseen_designs"
                       / "spiral_bevel_13x37_s60.toml")
    printed = []
    for start, words in ((0.95, "lies within the blade's edge radius .* moves it by "),
                         (0.87, "the pinion's tip plane, placed so that its root line "
                                "touches the root cone, leaves")):
        basic = given
        for flank in ("concave", "convex"):
            basic = with_flank_options(basic, flank, {"relief_start": start})
        with pytest.raises(ReliefError, match=r"synthesis\.concave\.relief_start: .*"
                           + words + r".* give relief_start <= ") as info:
            synthesize(basic)
        assert info.value.field == "relief_start"
        most = float(info.value.args[0].split("relief_start <= ")[1].split(" ")[0])
        assert 0.0 < most < start
        printed.append(most)
    assert printed[0] == printed[1]  # step 7's bound is step 8's: the one that places
    for flank in ("concave", "convex"):
        basic = with_flank_options(basic, flank, {"relief_start": printed[0]})
    case, _ = synthesize(basic)  # the printed relief_start synthesises, first try
    assert case.pinion.concave.blade.toprem_height > case.pinion.concave.blade.edge_radius


def test_root_end_on_the_fillet_is_followed_from_m():
    """spiral_bevel_13x39's concave flank: the depth the gear tip reaches is cut by the
    pinion blade's edge radius (the envelope solver misses it from a cold start); the
    relief heights follow it from M and put it below the edge arc's top."""
    case = _case(DESIGNS / "spiral_bevel_13x39_unrelieved.toml")
    tool, mem = case.pinion.concave, case.pinion
    h = relief_heights(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    sec = profile_sections(tool.blade)
    top_of_arc = float(blade_profile(sec, sec.s_hi[0]).h)
    assert h.root < top_of_arc < h.mean < h.tip


@pytest.mark.slow  # 15-40 s a design, 13 designs
@pytest.mark.parametrize("path", [ROOT / "cases" / "basic" / f"{n}.toml" for n in BUNDLED]
                         + sorted(p for p in DESIGNS.glob("*.toml")
                                  if not p.stem.endswith("_unrelieved")),
                         ids=lambda p: p.stem)
def test_synthesis_with_the_default_relief(path):
    """Every bundled basic file and user design synthesises with the documented relief
    defaults (15 µm tip and root relief from 0.5 of the way to the ends; the bundled files
    give 0, or the reference designs' optimised tip relief from 0.86, for their committed
    cases — from 0.86 a toprem corner of kolivand2009_table54_A_fh_reference would lie in
    the edge radius, which the error says), and the written case carries the rems on both
    pinion flanks."""
    from geometry.synthesis.basic_design import basic_from_dict
    from geometry.synthesis.case_synthesis import synthesize

    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    syn = raw.setdefault("synthesis", {})
    for key, value in (("tip_relief", 15.0), ("root_relief", 15.0), ("relief_start", 0.5)):
        syn[key] = value
        for flank in ("concave", "convex"):
            syn.get(flank, {}).pop(key, None)
    case, _ = synthesize(basic_from_dict(raw))
    for flank in ("concave", "convex"):
        blade = case.pinion.flank(flank).blade
        assert blade.flankrem_angle > 0.0 > blade.toprem_angle
        info = case.extra["synthesis"][flank]
        assert info["tip_relief_um"] == info["root_relief_um"] == pytest.approx(15.0)


def test_a_default_relief_the_profile_refuses_is_raised_to_what_it_needs():
    """The spiral bevel 18x27 of benchmarks/data/unseen_designs: the drive (concave)
    flank's circular profile turns 18.7 µm from its tangent over the default 15 µm tip
    relief's span, and ``ltca synthesize`` stopped. :func:`relief_for_profile` raises that
    flank's default relief to 1.05 x the need (0.1 µm up), the other flank and every value
    the file gives kept; an error without the need is not its to mend."""
    from geometry.synthesis.basic_design import load_basic
    from geometry.synthesis.case_synthesis import relief_for_profile

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    assert basic.options.concave.tip_relief == 0.015  # the default (m_mn above 3 mm)
    exc = ReliefError("tip_relief: ...", "tip_relief", (None, 2.0), least=0.0187,
                      flank="concave")
    raised = relief_for_profile(basic, exc)
    assert raised.options.concave.tip_relief == pytest.approx(0.0197, abs=1e-12)
    assert raised.options.convex == basic.options.convex
    assert raised.options.concave.root_relief == basic.options.concave.root_relief
    given = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, concave=dataclasses.replace(basic.options.concave,
                                                   tip_relief=0.012)))
    assert relief_for_profile(given, exc) is None
    assert relief_for_profile(basic, ReliefError("tip_relief: ...", "tip_relief",
                                                 flank="concave")) is None
