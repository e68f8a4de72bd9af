"""The generated root of the FE teeth: blade point widths, the blade tip's path, the root
line against the blank's root cone (issue 62, item 1; docs/fe.md "Root and slot bottom").

A few seconds each (transverse sections only, no FE solve)."""

from __future__ import annotations

import dataclasses
import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from contact.compliance.fe.section import (
    _bilinear,
    _flank_samples,
    _reference_tooth,
    tooth_sections,
)
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.iso23509.blank import blank_geometry
from geometry.iso23509.design_data import BevelGearDesign
from geometry.machine.cutter import Blade
from geometry.machine.flank import blank_outline
from geometry.synthesis.gear import slot_width_at_root

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = "kolivand2009_fm_11x41_reference"
#: face-milled Formate gears (spread-blade cutters) of two bundled designs
FM_GEARS = [DEFAULT, "hypoid_iso23509_s2"]
#: one-cut gears, face milling and face hobbing
ONE_CUT_GEARS = [DEFAULT, "hypoid_iso23509_s2", "kolivand2009_fh_12x41_reference"]


def _case(name: str):
    return load_case(ROOT / "cases" / f"{name}.toml")


def _derivation():
    spec = importlib.util.spec_from_file_location(
        "derive_point_widths", ROOT / "cases" / "derive_point_widths.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_bundled_cases_carry_the_derived_point_widths(capsys):
    """Every bundled case with a [design] table holds the point widths that
    cases/derive_point_widths.py derives (its --check writes nothing and finds no file to
    change), and every blade of those cases has one (> 0)."""
    assert _derivation().main(["--check"]) == 0
    assert "would change 0 case(s)" in capsys.readouterr().out
    for path in sorted((ROOT / "cases").glob("*.toml")):
        case = load_case(path)
        if "design" in case.extra:
            for mem in (case.pinion, case.gear):
                for flank in ("concave", "convex"):
                    assert mem.flank(flank).blade.point_width > 0.0, (path.name, mem.name)


def test_the_check_tells_round_off_from_a_change():
    """--check compares the derived widths with a relative tolerance (ROUND_OFF, 1e-12): the
    last digit of a width moves with the NumPy build (1.2412878285717923 against ...914 on
    numpy 2.4, which failed the exact comparison in a fresh CI venv), a change of 1e-9
    relative is a change, and so is any other line."""
    mod = _derivation()
    text = "[gear.cutter.concave]\nedge_radius = 0.813\npoint_width = 1.2412878285717923\n"
    assert mod._same(text.replace("923", "914"), text)
    assert not mod._same(text.replace("1.2412878285717923", "1.2412878298130801"), text)
    assert not mod._same(text.replace("0.813", "0.814"), text)
    assert not mod._same(text + "x = 1\n", text)


@pytest.mark.parametrize("name, tol", [(DEFAULT, 1e-6), ("hypoid_iso23509_s2", 1e-3)])
def test_spread_blade_point_width_is_the_slot_width_at_the_mean_root(name, tol):
    """A face-milled Formate gear's point width is its cutter's spread, r_OB − r_IB, and
    equals the slot width at the mean root, π m_mn − s_mn2 − h_fm2 (tan α_IB + tan α_OB),
    computed afresh by ISO 23509 from the case's [design] table: the blades and the
    design data agree. Tolerance [mm]: 1e-6 for a synthesised case (round-off of the
    blank's fits); 1e-3 for the ISO 23509 Annex F sample, whose settings
    (cases/derive_basic_settings.py) start from the standard's published values, printed
    to 3–4 decimals (measured 0.55 µm)."""
    case = _case(name)
    outside, inside = case.gear.flank("concave").blade, case.gear.flank("convex").blade
    assert outside.point_width == pytest.approx(outside.point_radius - inside.point_radius,
                                                abs=1e-9)
    geom = blank_geometry(BevelGearDesign.from_degrees(**case.extra["design"]))
    w = slot_width_at_root(geom.gear, geom.m_mn, inside.blade_angle, outside.blade_angle)
    assert w == pytest.approx(outside.point_width, abs=tol)


@pytest.mark.parametrize("name", FM_GEARS)
def test_generated_slot_width_at_the_root_is_the_point_width(name):
    """The slot that the FE model's gear sections hold, measured at the mean section
    between the two flanks' generated root-line points (where each blade's edge radius
    leaves the tip plane) normal to the root line, equals the point width less the two
    edge radii's insets r_e tan(45° − α/2) (a circle tangent to the tip line and to a
    profile line of blade angle α). Tolerance 0.01 mm (1 % of the ~1 mm width): the width
    is taken from a chord across the slot in a transverse section, which meets the
    concentric root circles of radius ~r_c0 ≈ 100 mm a few tenths of a mm apart along the
    slot (d²/2r_c0 of a few µm; measured 1.4 and 6.3 µm)."""
    case = _case(name)
    ts = tooth_sections(case, "gear", np.array([0.45, 0.5, 0.55]))
    right = "concave" if ts.left_flank == "convex" else "convex"
    pr = [ts.root_point(right, k) for k in range(3)]
    pl = ts.root_point(ts.left_flank, 1, ts.pitch)  # the slot's other side: next tooth
    t = (pr[2] - pr[0]) / np.linalg.norm(pr[2] - pr[0])
    d = pl - pr[1]
    width = float(np.linalg.norm(d - (d @ t) * t))
    outside, inside = case.gear.flank("concave").blade, case.gear.flank("convex").blade

    def inset(b: Blade) -> float:
        return b.edge_radius * math.tan(0.25 * math.pi - 0.5 * b.blade_angle)

    assert width == pytest.approx(outside.point_width - inset(outside) - inset(inside),
                                  abs=0.01)


@pytest.mark.parametrize("name", ONE_CUT_GEARS)
def test_root_line_of_a_formate_gear_touches_its_root_cone(name):
    """A Formate gear's tip plane holds a generatrix of its root cone (machine root angle =
    root angle, root apex at the machine centre: gear_formate_tools), so the root lines
    its blades cut lie on or above the root cone and touch it: depth below the cone ≤ 1 µm
    in every section (the Newton tolerance of the generated points is 1e-10 mm; 1 µm
    allows the bilinear projection-plane map) and within 0.02 mm of it somewhere, for
    both flanks (face milling and face hobbing)."""
    case = _case(name)
    ts = tooth_sections(case, "gear", np.linspace(0.0, 1.0, 11))
    assert ts.one_cut
    for flank in ("convex", "concave"):
        depth = ts.root_depth(flank)
        assert np.all(np.isfinite(depth))
        assert depth.max() <= 1e-3, (flank, depth)
        assert np.abs(depth).min() < 0.02, (flank, depth)


def test_blade_tip_path_of_a_formate_cut_lies_in_the_tip_plane():
    """The flat tip added below the edge radius (s < 0) is generated by the same equations
    as the flank: on a Formate gear, which copies its cutter, every generated tip point
    and every root-line point of all sections lies on one plane, the tip plane
    (least-squares plane; residual < 1e-6 mm against the Newton tolerance 1e-10 mm), and
    the tip runs as far as asked (1.5 mm below s = 0 in each section)."""
    case = _case(DEFAULT)
    u = np.linspace(0.1, 0.9, 5)
    shift, ref, pitch, _ = _reference_tooth(case, "gear")
    samples = _flank_samples(case, "gear", "concave", u, shift * pitch, ref, tip=1.5)
    corners = blank_outline(case.gear.blank).corners
    pts = []
    for k, uk in enumerate(u):
        s = samples.s[k]
        assert s.min() == pytest.approx(-1.5, abs=1e-9)
        sel = s <= 0.0
        (z, rho) = _bilinear(corners, uk, samples.v[k][sel])[0].T
        phi = samples.phi[k][sel]
        pts.append(np.column_stack([rho * np.cos(phi), rho * np.sin(phi), z]))
    pts = np.vstack(pts)
    centred = pts - pts.mean(axis=0)
    normal = np.linalg.svd(centred)[2][-1]
    assert np.abs(centred @ normal).max() < 1e-6


def test_point_width_out_of_range_is_refused(tmp_path):
    """A negative point width, or one not below the point radius, is refused naming the
    field and its range, by the blade and by the case loader."""
    with pytest.raises(InputError, match=r"point_width: must be in \[0, point_radius\)"):
        Blade("outside", 100.0, 0.4, edge_radius=0.8, point_width=-1.0)
    with pytest.raises(InputError, match="point_width"):
        Blade("inside", 2.0, 0.4, edge_radius=0.5, point_width=2.0)
    text = (ROOT / "cases" / f"{DEFAULT}.toml").read_text(encoding="utf-8")
    bad = text.replace("point_width = ", "point_width = -", 1)
    path = tmp_path / "bad.toml"
    path.write_text(bad, encoding="utf-8")
    with pytest.raises(InputError, match=r"pinion\.cutter\.concave.*point_width"):
        load_case(path)


# ----------------------------------------------------------------- the pinion's tip planes
#: bundled face-milled cases with a Generate pinion (cases/derive_tip_planes.py placed their
#: tip planes; ltca synthesize does it as its step 8)
FM_PINIONS = [DEFAULT, "kolivand2009_fm_11x41", "hypoid_iso23509_s2",
              "spiral_bevel_iso23509_s1", "iso23509_sample2_fm"]
#: bundled face-hobbed cases (placed blades, separate settings per pinion flank; the
#: `_measured` variant of the 12×41 pair has its base case's pinion)
FH_PINIONS = ["kolivand2009_fh_12x41_reference", "kolivand2009_fh_12x41",
              "kolivand2009_table54_A_fh_reference", "kolivand2009_table54_A_fh",
              "kolivand2009_table54_B_fh_reference", "kolivand2009_table54_B_fh",
              "iso10300_30_sample3"]


def test_moving_the_tip_plane_keeps_the_flank_and_moves_the_root_line():
    """:func:`move_tip_plane` is a change of datum, not of the cut: the machine chain of the
    new settings is the old one followed by T(0, 0, Δ) at every roll (modified roll and
    helical motion included; 1e-12 mm, round-off of ~100 mm transforms), the working flank
    (points generated by the profile, toprem and flankrem sections) is the same surface
    (1e-9 mm against the Newton tolerance 1e-10 mm), and the root line moves deeper by Δ
    within 5 %: its point moves along its transverse section's line, not along the
    cutter axis, and the envelope point slides along the tip (measured 1.002–1.025 Δ from
    toe to heel)."""
    from geometry.machine.cradle import machine_transform, trans
    from geometry.machine.cutter import profile_sections
    from geometry.machine.meshing import solve_envelope
    from geometry.machine.root_line import projection_point
    from geometry.synthesis.tip_plane import generated_root_line, move_tip_plane

    case = _case(DEFAULT)
    mem = case.pinion
    tool = mem.flank("concave")  # the flank with modified roll and helical motion
    assert tool.machine.helical_motion and tool.machine.modified_roll
    delta = 0.4
    blade, settings = move_tip_plane(tool.blade, tool.machine, delta)
    q = np.linspace(-0.5, 0.5, 11)
    old = machine_transform(tool.machine, q)[0] @ trans([0.0, 0.0, delta])
    assert np.abs(machine_transform(settings, q)[0] - old).max() < 1e-12
    corners = blank_outline(mem.blank).corners
    uu, vv = np.meshgrid(np.linspace(0.0, 1.0, 7), np.linspace(0.1, 1.0, 7), indexing="ij")
    p, _ = projection_point(corners, uu, vv)
    kw = {"length_scale": mem.blank.outer_cone_distance,
          "depth": mem.blank.outer_addendum + mem.blank.outer_dedendum}
    a = solve_envelope(tool.blade, tool.machine, p[..., 0], p[..., 1], **kw)
    b = solve_envelope(blade, settings, p[..., 0], p[..., 1], **kw)
    working = ((a.reason == 0) & (b.reason == 0)
               & (np.array(profile_sections(tool.blade).names)[a.section] != "edge")
               & (np.array(profile_sections(blade).names)[b.section] != "edge"))
    assert working.sum() >= 40
    assert np.abs(a.position - b.position)[working].max() < 1e-9
    u = np.array([0.0, 0.5, 1.0])
    d0 = generated_root_line(tool.blade, tool.machine, mem.blank, mem.hand, u).depth
    d1 = generated_root_line(blade, settings, mem.blank, mem.hand, u).depth
    np.testing.assert_allclose(d1 - d0, delta, rtol=0.05)


@pytest.mark.parametrize("flank", ["concave", "convex"])
@pytest.mark.parametrize("hook", [0.0, 6.0])
def test_moving_a_face_hobbing_tip_plane_keeps_the_flank(flank, hook):
    """The same change of datum for a placed (face-hobbing) blade: the new reference point
    is the old nominal edge line's point at the new tip plane, the phase and the blade
    offset angle turn so that the rake plane stays the same plane (its directions a1, a2
    equal to 1e-12), the machine chain is the old one followed by T(0, 0, Δ) at every roll
    and cutter spin (the indexing κθ included; 1e-12 mm), the working flank is the same
    surface (1e-9 mm against the Newton tolerance 1e-10 mm; measured 4e-11 mm) and the
    root line moves deeper by Δ within 5 % (measured 0.998–1.009 Δ). The bundled blades
    have no hook; a 6° hook (heights along the rake plane's leaning vertical line, moved
    by Δ / cos γ_h) is checked on the same cut."""
    from geometry.machine.cradle import machine_transform, trans
    from geometry.machine.cutter import placement_vectors, profile_sections
    from geometry.machine.meshing import solve_envelope
    from geometry.machine.root_line import projection_point
    from geometry.synthesis.tip_plane import generated_root_line, move_tip_plane

    mem = _case("kolivand2009_fh_12x41_reference").pinion
    tool = mem.flank(flank)
    blade0 = dataclasses.replace(tool.blade, hook_angle=math.radians(hook))
    assert blade0.placed and tool.machine.indexing_ratio != 0.0
    delta = 0.3
    blade, settings = move_tip_plane(blade0, tool.machine, delta)
    assert blade.point_radius != blade0.point_radius
    assert blade.blade_phase != blade0.blade_phase
    for a, b in zip(placement_vectors(blade0)[1:], placement_vectors(blade)[1:], strict=True):
        np.testing.assert_allclose(a, b, atol=1e-12)
    q, theta = np.meshgrid(np.linspace(-0.5, 0.5, 5), np.linspace(-0.3, 0.3, 5))
    old = machine_transform(tool.machine, q, theta)[0] @ trans([0.0, 0.0, delta])
    assert np.abs(machine_transform(settings, q, theta)[0] - old).max() < 1e-12
    corners = blank_outline(mem.blank).corners
    uu, vv = np.meshgrid(np.linspace(0.0, 1.0, 7), np.linspace(0.1, 1.0, 7), indexing="ij")
    p, _ = projection_point(corners, uu, vv)
    kw = {"length_scale": mem.blank.outer_cone_distance,
          "depth": mem.blank.outer_addendum + mem.blank.outer_dedendum}
    a = solve_envelope(blade0, tool.machine, p[..., 0], p[..., 1], **kw)
    b = solve_envelope(blade, settings, p[..., 0], p[..., 1], **kw)
    working = ((a.reason == 0) & (b.reason == 0)
               & (np.array(profile_sections(blade0).names)[a.section] != "edge")
               & (np.array(profile_sections(blade).names)[b.section] != "edge"))
    assert working.sum() >= 40
    assert np.abs(a.position - b.position)[working].max() < 1e-9
    u = np.array([0.0, 0.5, 1.0])
    d0 = generated_root_line(blade0, tool.machine, mem.blank, mem.hand, u).depth
    d1 = generated_root_line(blade, settings, mem.blank, mem.hand, u).depth
    np.testing.assert_allclose(d1 - d0, delta, rtol=0.05)


@pytest.mark.parametrize("name", ["kolivand2009_fh_12x41_reference",
                                  "kolivand2009_table54_A_fh_reference",
                                  "kolivand2009_table54_B_fh_reference",
                                  "iso10300_30_sample3"])
def test_face_hobbed_pinion_slot_width_at_the_root(name):
    """The slot between the two separately cut flanks' generated root-line points at mid
    face (measured as for the Formate gears above) against the blades' point width W,
    the slot width at the mean root between the nominal profile lines (ISO 23509's
    s_mn1, cases/derive_point_widths.py): W less the two edge radii's insets
    r_e tan(45° − α/2), less d tan α for each cut whose root line lies d below the root
    cone there (the nominal line has come in by that much), is the generated width up to
    the difference of the generated tooth from ISO's nominal thickness. The synthesis
    takes the mean normal backlash j_mn (0.110–0.161 mm) off the pinion's tooth at M;
    tolerance j_mn + 0.02 mm (the mid-face section is not the hypoid pinion's mean point,
    and the chord measure's few µm). Measured: +0.125, −0.029, +0.018, −0.038 mm (before
    the tip planes were placed +0.129, −0.011, +0.028, −0.013 mm: the relation holds at
    any tip plane; the placement changed the widths themselves from 0.897, 0.724, 0.791,
    0.810 to 0.884, 0.843, 0.853, 0.735 mm, where W − insets is 0.919, 0.883, 0.880,
    0.905 mm)."""
    case = _case(name)
    ts = tooth_sections(case, "pinion", np.array([0.45, 0.5, 0.55]))
    assert not ts.one_cut
    right = "concave" if ts.left_flank == "convex" else "convex"
    pr = [ts.root_point(right, k) for k in range(3)]
    pl = ts.root_point(ts.left_flank, 1, ts.pitch)
    t = (pr[2] - pr[0]) / np.linalg.norm(pr[2] - pr[0])
    d = pl - pr[1]
    width = float(np.linalg.norm(d - (d @ t) * t))
    expected = case.pinion.concave.blade.point_width
    for flank in ("concave", "convex"):
        b = case.pinion.flank(flank).blade
        expected -= b.edge_radius * math.tan(0.25 * math.pi - 0.5 * b.blade_angle)
        expected -= float(ts.root_depth(flank)[1]) * math.tan(b.blade_angle)
    j_mn = case.extra["synthesis"]["mean_normal_backlash_mm"]
    assert abs(width - expected) <= j_mn + 0.02, (width, expected, j_mn)


@pytest.mark.parametrize("name", FM_PINIONS + FH_PINIONS)
def test_pinion_root_lines_touch_the_root_cone(name):
    """Each separately cut pinion flank's generated root line lies nowhere above the
    blank's root cone and touches it (the gear's face cone keeps its clearance along the
    whole face, and no cut goes deeper than that needs), face milling and face hobbing
    (before the face-hobbed pinions were placed, their cuts' highest points lay from
    0.263 mm above the root cone (ISO/TR 10300-30 sample 3, concave, at the heel) to
    0.234 mm below it (Table 5.4 A, convex)): at 21 sections no point lies
    above the root cone by more than 1e-6 mm, and the highest point, found by a bounded
    search between the neighbours of the highest section (an interior highest point is
    a flat minimum of the depth: 21 sections alone miss it by 0.3 µm on the ISO 23509
    samples), lies within 1e-6 mm of it (placed to 1e-9 mm; the search's
    step 1e-5 in u leaves < 1e-7 mm on these curvatures). The FE tooth's root lines
    (``ToothSections.root_line``) are the same points (1e-9 in v)."""
    from geometry.synthesis.tip_plane import generated_root_line

    case = _case(name)
    mem = case.pinion
    u = np.linspace(0.0, 1.0, 21)
    for flank in ("concave", "convex"):
        tool = mem.flank(flank)
        line = generated_root_line(tool.blade, tool.machine, mem.blank, mem.hand, u)
        assert np.all(np.isfinite(line.depth)), (flank, line.depth)
        assert line.depth.min() >= -1e-6, (flank, line.depth)
        k = int(np.argmin(line.depth))
        top = minimize_scalar(
            lambda x, t=tool: float(generated_root_line(t.blade, t.machine, mem.blank,
                                                        mem.hand, [x]).depth[0]),
            bounds=(u[max(k - 1, 0)], u[min(k + 1, u.size - 1)]), method="bounded",
            options={"xatol": 1e-5}).fun
        assert abs(min(top, line.depth[k])) <= 1e-6, (flank, top, line.depth)
    if name == DEFAULT:
        ts = tooth_sections(case, "pinion", u)
        for flank in ("concave", "convex"):
            tool = mem.flank(flank)
            line = generated_root_line(tool.blade, tool.machine, mem.blank, mem.hand, u)
            np.testing.assert_allclose(ts.root_line[flank][:, 0], line.v, atol=1e-9)


def test_highest_between_finds_a_flat_maximum_with_few_marches():
    """The placement's refinement of a root line's highest point
    (``tip_plane._highest_between``, grids of fractions then a parabola; issue 75) against
    the bounded scalar search it replaced: on a smooth depth with its least value between
    grid points (a quartic about u = 0.4371, curvature of the 10x37 Sigma 75's interior
    peak, ~1 mm per unit fraction squared) it lands within 1e-6 of the minimiser and
    1e-12 mm of the least depth, better than ``minimize_scalar`` with xatol 1e-4; with
    three marches (calls) in all; NaN where the line is not generated is passed over; a
    maximum at the bracket's end is the end."""
    from geometry.synthesis.tip_plane import _highest_between

    calls = []

    def depth(u):
        calls.append(len(u))
        u = np.asarray(u, float)
        d = 0.5 * (u - 0.4371) ** 2 + 3.0 * (u - 0.4371) ** 4 + 1e-3
        return np.where(u > 0.49, np.nan, d)

    u, d = _highest_between(depth, 0.3, 0.5)
    assert [len(c) for c in [calls]] == [3] and calls[:2] == [17, 17]
    ref = minimize_scalar(lambda x: float(depth([x])[0]), bounds=(0.3, 0.5),
                          method="bounded", options={"xatol": 1e-4})
    assert abs(u - 0.4371) <= 1e-6 and abs(d - 1e-3) <= 1e-12
    assert d <= ref.fun
    u, d = _highest_between(lambda x: np.asarray(x, float), 0.2, 0.4)
    assert (u, d) == (0.2, 0.2)


def test_a_placement_from_a_near_start_is_the_same_tip_plane():
    """``tip_plane_on_root_cone(start=...)`` (the secant from a near cut's placement, as a
    development's variants of one flank are placed; issue 75) gives the tip plane of the
    search without it within the placement's tolerance (1e-9 mm; measured 1e-14-3e-12 mm
    on the 10x37 Sigma 75's variants), with fewer root lines; a start the blade cannot
    take (the toprem corner below the edge radius) is ignored. The default pinion's
    concave cut with its tip plane 0.05 mm too deep, started 0.002 mm off the answer."""
    from geometry.synthesis import tip_plane as tp

    case = _case(DEFAULT)
    mem = case.pinion
    tool = mem.flank("concave")
    blade, settings = tp.move_tip_plane(tool.blade, tool.machine, 0.05)
    counted = []
    line = tp.root_line_points

    def counting(*args, **kwargs):
        counted.append(1)
        return line(*args, **kwargs)

    cold = tp.tip_plane_on_root_cone(blade, settings, mem.blank, mem.hand)
    assert abs(cold.moved + 0.05) <= 1e-6
    try:
        tp.root_line_points = counting
        warm = tp.tip_plane_on_root_cone(blade, settings, mem.blank, mem.hand,
                                         start=(cold.moved + 0.002, cold.u_touch))
        n_warm = len(counted)
        counted.clear()
        again = tp.tip_plane_on_root_cone(blade, settings, mem.blank, mem.hand)
        n_cold = len(counted)
    finally:
        tp.root_line_points = line
    assert abs(warm.moved - cold.moved) <= 1e-9 and again.moved == cold.moved
    assert abs(float(warm.root_line.depth.min())) <= 1e-6
    assert n_warm < n_cold, (n_warm, n_cold)
    bad = tp.tip_plane_on_root_cone(blade, settings, mem.blank, mem.hand,
                                    start=(-blade.toprem_height - 1.0, 0.5))
    assert bad.moved == cold.moved



@pytest.mark.parametrize("name", [DEFAULT, "kolivand2009_fh_12x41_reference"])
def test_root_line_solved_at_the_tip_from_a_near_cut_is_the_marched_one(name):
    """``root_line_points(at_tip=...)`` (Newton's method at s = 0 alone from a nearby
    cut's root-line points, interpolated between its sections, as the tip-plane placement
    solves its later root lines; issue 75) gives the points the fillet march gives from
    the cut's own starts: the cut's tip plane moved 0.3 mm deeper, started from the
    unmoved cut's points at every other of 11 sections, the 21 sections' v within 1e-9
    (both solved to the Newton tolerance 1e-10 mm; measured ≤ 5e-12) and φ within 1e-9
    rad (measured ≤ 2e-13), face milling and face hobbing."""
    from geometry.machine.root_line import root_line_points
    from geometry.synthesis.tip_plane import move_tip_plane

    mem = _case(name).pinion
    for flank in ("concave", "convex"):
        tool = mem.flank(flank)
        coarse = np.linspace(0.0, 1.0, 11)
        _, x0 = root_line_points(tool.blade, tool.machine, mem.blank, mem.hand, coarse,
                                 solution=True)
        assert np.all(np.isfinite(x0))
        blade, settings = move_tip_plane(tool.blade, tool.machine, 0.3)
        u = np.linspace(0.0, 1.0, 21)
        start = np.column_stack([np.interp(u, coarse, c) for c in x0.T])
        marched = root_line_points(blade, settings, mem.blank, mem.hand, u)
        solved, x = root_line_points(blade, settings, mem.blank, mem.hand, u,
                                     at_tip=start, solution=True)
        assert np.all(np.isfinite(marched)) and np.all(np.isfinite(x))
        np.testing.assert_allclose(solved, marched, rtol=0, atol=1e-9)
        np.testing.assert_allclose(x[:, 2], solved[:, 0], rtol=0, atol=0)

def test_tip_plane_refusals():
    """A move that takes the toprem corner below the edge radius, a depth that is not
    finite and a Formate cut (face milling and face hobbing) are refused by name."""
    from geometry.synthesis.tip_plane import move_tip_plane, tip_plane_on_root_cone

    case = _case(DEFAULT)
    tool = case.pinion.flank("concave")
    with pytest.raises(InputError, match=r"depth: moving the tip plane.*toprem_height"):
        move_tip_plane(tool.blade, tool.machine, -tool.blade.toprem_height)
    with pytest.raises(InputError, match="depth: must be a finite length"):
        move_tip_plane(tool.blade, tool.machine, float("nan"))
    gear = case.gear.flank("concave")
    with pytest.raises(InputError, match="Generate"):
        tip_plane_on_root_cone(gear.blade, gear.machine, case.gear.blank, case.gear.hand)
    fh = _case("kolivand2009_fh_12x41_reference").gear
    with pytest.raises(InputError, match="Generate"):
        tip_plane_on_root_cone(fh.concave.blade, fh.concave.machine, fh.blank, fh.hand)


@pytest.mark.slow  # 25 s: every bundled case's placement again; the touch tests above
# check the same property on every distinct FM and FH pinion in the default suite
def test_bundled_tip_planes_are_the_derivation_s(capsys):
    """cases/derive_tip_planes.py --check finds no bundled case to change: every bundled
    pinion's tip planes (face milling and face hobbing) are on its root cone as ``ltca
    synthesize`` places them."""
    spec = importlib.util.spec_from_file_location(
        "derive_tip_planes", ROOT / "cases" / "derive_tip_planes.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert mod.main(["--check"]) == 0
    assert "would change 0 case(s)" in capsys.readouterr().out


def test_section_targets_stop_short_of_the_member_axis(monkeypatch):
    """A whole depth under the root cone passes the member axis at the toe of a 5-tooth
    face-hobbed hypoid at a 50 mm offset (benchmarks/data/unseen_designs/
    fh_hypoid_5x45_a50.toml: ``ltca synthesize`` stopped with "radius: targets must be
    > 0 mm"). The section envelope's targets there are moved up to a twentieth of the
    root cone's radius; every other target is the one of :data:`V_TARGETS` as before."""
    from types import SimpleNamespace

    from geometry.machine import root_line

    # (z, ρ) [mm] of [toe, heel] x [root, tip]: the toe's root radius 4 mm, a depth of 8
    corners = np.array([[[10.0, 4.0], [10.0, 12.0]], [[40.0, 20.0], [40.0, 28.0]]])
    monkeypatch.setattr(root_line, "blank_outline", lambda _b: SimpleNamespace(
        corners=corners))
    seen = {}

    def solve(_blade, _settings, z, rho, **_kw):
        seen["z"], seen["rho"] = z, rho
        one = np.zeros(z.shape)
        return SimpleNamespace(reason=np.zeros(z.shape, int), s=one, theta=one, q=one)

    monkeypatch.setattr(root_line, "solve_envelope", solve)
    blank = SimpleNamespace(outer_cone_distance=50.0, outer_addendum=3.0,
                            outer_dedendum=5.0)
    u = np.array([0.0, 0.5, 1.0])
    _, vv, _ = root_line.section_envelope(None, SimpleNamespace(process="Generate"), blank,
                                          u)
    rho = seen["rho"]
    assert np.all(rho > 0.0)
    # the toe section: ρ = 4 + 8 v reaches 0 at v = -0.5; its targets below that at
    # ρ = 0.05 x 4 mm (v = -0.475); the other sections (ρ ≥ 20 - 8 = 12 mm at the
    # mid-face's v = -1) keep V_TARGETS exactly
    through = root_line.V_TARGETS <= -0.5
    np.testing.assert_allclose(rho[0, through], 0.2, rtol=1e-12)
    np.testing.assert_allclose(vv[0, through], -0.475, rtol=1e-12)
    np.testing.assert_array_equal(vv[0, ~through], root_line.V_TARGETS[~through])
    np.testing.assert_array_equal(vv[1:], np.tile(root_line.V_TARGETS, (2, 1)))
