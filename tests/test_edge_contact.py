"""Edge contact of the flank boundary (contact.ltca.edges, contact.ltca).

Independent checks: the boundary lies on the contact region's edge and its tip piece has
the length of the gear's tip line between the grid nodes; at a curve's end on the
boundary the edge separation Φ_q = ε + ½ K (Q − q)² equals the curve's own (an identity of
the two formulations); the edge segments converge with their step; the entering pair
loads its corner before its curve emerges (the physics the line model missed), and the
analysis still satisfies equilibrium and complementarity (tests/test_ltca.py runs with
edge contact on by default).
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.catalogue import SEED_TABLE_3_1
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.edges import EDGE_KINDS, flank_boundary
from contact.utca import EaseOffFields, contact_curves, transitions
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.core.errors import InputError

ROOT = Path(__file__).resolve().parents[1]


@cache
def _case():
    # the long-bearing synthesis without relief, whose edges carry load at Table 3.1
    # (7 % of the torque at 50 N m): these tests exercise the edge model, so they need a
    # design that loads its edges (the default, reference design keeps them nearly idle)
    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    return dataclasses.replace(case, misalignment=SEED_TABLE_3_1["misalignment"])


@cache
def _easeoff():
    return ease_off(_case())


def test_boundary_lies_on_the_region_edge_and_spans_the_tip_line():
    """Every sample lies on the contact region's boundary (inside measure 0 to 2e-3 of the
    grid: the pinion edge is a contour of the margin spline on a 161 × 81 grid), and the
    tip piece is as long as the polyline through the gear's own grid nodes on its tip line
    where the pinion mate lies in its blank (within 1 %: chords vs the spline's arc)."""
    eo = _easeoff()
    f = EaseOffFields(eo)
    bd = flank_boundary(f, 0.5)
    assert set(np.unique(bd.kind)) == set(range(len(EDGE_KINDS)))
    m = f.measure(bd.u.ravel(), bd.v.ravel())
    assert np.max(np.abs(m)) < 2e-3
    tip = bd.kind == EDGE_KINDS.index("gear_tip")
    length = np.linalg.norm(bd.position[tip, 2] - bd.position[tip, 0], axis=-1).sum()
    nodes = eo.gear_position[:, -1]
    inside = eo.margin[:, -1] >= 0
    chords = np.linalg.norm(np.diff(nodes, axis=0), axis=-1)
    reference = chords[inside[1:] & inside[:-1]].sum()
    assert abs(length / reference - 1) < 0.01
    with pytest.raises(InputError, match="edge_step"):
        flank_boundary(f, 0.0)


def test_edge_separation_continues_the_curve_at_its_end():
    """Where a curve ends on the boundary, Φ_q(x) = ε + ½ K (Q − q)² of the edge equals
    the curve's separation ε + gap (its iso-line is Q = q + t there, so both read ½ K t²),
    to 1e-9 rad (Q is met to 1e-13 rad on the curve)."""
    eo = _easeoff()
    f = EaseOffFields(eo)
    m1, _ = transitions(eo)
    q = m1 + np.linspace(-0.6, 1.2, 25) * eo.pitch
    cc = contact_curves(eo, q, n_point=21, spacing="cosine", near_misses=True, fields=f)
    have = np.isfinite(cc.ute)
    assert have.sum() > 15
    for end in (0, -1):
        u, v = cc.u[have, end], cc.v[have, end]
        phi = f.eps.ev(u, v) + 0.5 * f.gap.ev(u, v) * (f.q.ev(u, v) - q[have]) ** 2
        curve = cc.ease_off_angle[have, end] + cc.gap[have, end]
        np.testing.assert_allclose(phi, curve, rtol=0, atol=1e-9)


def test_entering_pair_loads_its_corner_before_its_curve_emerges():
    """At 500 N·m (Table 3.1, 80 rolls per cycle) the entering pair's heel-tip corner is
    in interference for several roll positions before its contact curve emerges there:
    it carries load on its edges alone, growing roll by roll (measured 0.1 → 4.6 % of the
    torque over 8 rolls), so the LTE no longer steps at the entry (largest step between
    neighbouring rolls, 16 segments: 1.4 µrad, 8.0 µrad with the line model alone)."""
    opts = LTCAOptions(cycles=1, rolls_per_cycle=80, segments=16)
    ds = loaded_tca(_case(), [500.0], options=opts, easeoff=_easeoff())
    curve = ds["segment_kind"].values == "curve"
    force = ds["force"].isel(torque=0).fillna(0.0).values
    on_curve, on_edge = force[..., curve].sum(-1), force[..., ~curve].sum(-1)
    k = list(ds["pair"].values).index(1)
    only = np.flatnonzero((on_edge[:, k] > 0) & (on_curve[:, k] == 0))
    assert only.size >= 3
    share = ds["load_share"].isel(torque=0, pair=k).values[only]
    assert np.all(np.diff(share) > 0)
    lines = loaded_tca(_case(), [500.0], options=dataclasses.replace(opts, edge_contact=False),
                       easeoff=_easeoff())
    step = np.abs(np.diff(ds["transmission_error"].values[0])).max()
    step_lines = np.abs(np.diff(lines["transmission_error"].values[0])).max()
    assert step < step_lines


def test_edge_segments_converge_with_their_step():
    """Halving the edge step (0.25 → 0.125 mm) moves the LTE by < 0.5 µrad and the peak
    edge pressure by < 2 % at 500 N·m (the issue's refinement bounds; measured 0.04 µrad
    and 0.8 %; from 0.5 to 0.25 mm: 0.7 µrad, hence the default 0.25 mm). The edges are
    elastic here (``edge_pressure_limit=None``): this is the convergence of the edge
    model's discretisation; with the plastic limit on, the peak would be the limit in both
    runs (tests/test_plastic_edges.py)."""
    eo = _easeoff()
    opts = LTCAOptions(cycles=1, rolls_per_cycle=10, edge_pressure_limit=None)
    a = loaded_tca(_case(), [500.0], options=opts, easeoff=eo)
    b = loaded_tca(_case(), [500.0], options=dataclasses.replace(opts, edge_step=0.125),
                   easeoff=eo)
    assert np.abs(a["transmission_error"] - b["transmission_error"]).max().item() < 0.5
    ratio = b["pressure_max_edge"].values / a["pressure_max_edge"].values
    assert np.all(np.abs(ratio - 1) < 0.02)


def test_edge_radius_sets_the_edge_pressure_as_hertz_says():
    """The edge's R_eq is 1/(1/r_e + κ_other): between two runs the mating flank's
    curvature cancels, 1/R_eq(2 mm) − 1/R_eq(0.5 mm) = 1/2 − 2 /mm on every edge segment
    (to 1e-9), and at r_e = 0.5 mm R_eq is within 10 % of r_e (|κ_other| ≤ ~0.1 /mm).
    Quadrupling r_e halves the edge's Hertz pressure at the same line load, and changes the
    LTE little (Weber's compliance depends on R_eq only through a logarithm)."""
    eo = _easeoff()
    base = LTCAOptions(cycles=1, rolls_per_cycle=6)
    a = loaded_tca(_case(), [250.0], options=base, easeoff=eo)
    b = loaded_tca(_case(), [250.0], options=dataclasses.replace(base, edge_radius=2.0),
                   easeoff=eo)
    edge = a["segment_kind"] != "curve"
    np.testing.assert_array_equal(b["segment_kind"].values, a["segment_kind"].values)
    ra = a["equivalent_radius"].where(edge).values
    rb = b["equivalent_radius"].where(edge).values
    ok = np.isfinite(ra)
    assert ok.sum() > 100
    np.testing.assert_allclose(1 / rb[ok] - 1 / ra[ok], 0.5 - 2.0, rtol=0, atol=1e-9)
    assert np.all(np.abs(ra[ok] / 0.5 - 1) < 0.1)
    # p = 2w/(π b), b ∝ √(w R): at equal w, p ∝ R^-1/2
    w_a = a["load_per_length"].where(a["segment_kind"] != "curve")
    pa = (a["pressure_max"] / np.sqrt(w_a)).where(w_a > 0)
    w_b = b["load_per_length"].where(b["segment_kind"] != "curve")
    pb = (b["pressure_max"] / np.sqrt(w_b)).where(w_b > 0)
    assert 0.45 < float(pb.median()) / float(pa.median()) < 0.55
    assert np.abs(a["transmission_error"] - b["transmission_error"]).max().item() < 5.0


def test_each_member_edge_takes_its_blank_edge_break_radius():
    """Without ``LTCAOptions.edge_radius`` each member's edges take its blank's
    ``edge_break_radius``: a gear rounded to 2 mm changes 1/R_eq of the gear's edge
    segments by 1/2 − 2 /mm (the mating curvature cancels; to 1e-9) and leaves the
    pinion's edges as they were (0 to 1e-9); the radii used are stored as attributes.
    A radius outside (0, whole depth) is refused, naming the field."""
    eo = _easeoff()
    opts = LTCAOptions(cycles=1, rolls_per_cycle=6)
    case = _case()
    gear = dataclasses.replace(case.gear, blank=dataclasses.replace(
        case.gear.blank, edge_break_radius=2.0))
    a = loaded_tca(case, [250.0], options=opts, easeoff=eo)
    b = loaded_tca(dataclasses.replace(case, gear=gear), [250.0], options=opts, easeoff=eo)
    assert (a.attrs["edge_radius_pinion_mm"], a.attrs["edge_radius_gear_mm"]) == (0.5, 0.5)
    assert (b.attrs["edge_radius_pinion_mm"], b.attrs["edge_radius_gear_mm"]) == (0.5, 2.0)
    for kinds, change in ((("gear_tip", "gear_heel", "gear_toe"), 0.5 - 2.0),
                          (("pinion_edge",), 0.0)):
        # the same boundary segments (the axis keeps those in some problem: compare the
        # segments present in both runs by position on the flank)
        ka = a["segment_kind"].isin(list(kinds)).values
        kb = b["segment_kind"].isin(list(kinds)).values
        pa = a["segment_position"].isel(segment=ka)
        pb = b["segment_position"].isel(segment=kb)
        ra = a["equivalent_radius"].isel(segment=ka).values
        rb = b["equivalent_radius"].isel(segment=kb).values
        # match by the (roll, pair) midpoint: equal positions are the same segment
        n = 0
        for j in range(a.sizes["roll"]):
            for k in range(a.sizes["pair"]):
                xa = pa.values[j, k]
                xb = pb.values[j, k]
                for ia in np.flatnonzero(np.isfinite(ra[j, k])):
                    d = np.linalg.norm(xb - xa[ia], axis=-1)
                    ib = int(np.nanargmin(d)) if np.any(np.isfinite(d)) else -1
                    if ib >= 0 and d[ib] < 1e-9 and np.isfinite(rb[j, k, ib]):
                        assert abs(1 / rb[j, k, ib] - 1 / ra[j, k, ia] - change) < 1e-9
                        n += 1
        assert n > 20, kinds
    with pytest.raises(InputError, match="edge_break_radius"):
        dataclasses.replace(case.gear.blank, edge_break_radius=0.0)
    with pytest.raises(InputError, match="edge_break_radius"):
        dataclasses.replace(case.gear.blank, edge_break_radius=50.0)


def test_line_model_alone_is_kept_and_options_are_checked():
    """``edge_contact=False`` is the seed's line model: curve segments only."""
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8, edge_contact=False)
    ds = loaded_tca(_case(), [100.0], options=opts, easeoff=_easeoff())
    assert ds.sizes["segment"] == 8
    assert set(ds["segment_kind"].values) == {"curve"}
    assert float(ds["pressure_max_edge"].values[0]) == 0.0
    for bad in ({"edge_radius": 0.0}, {"edge_step": -1.0}, {"edge_radius": float("nan")},
                {"edge_contact": "yes"}):
        with pytest.raises(InputError, match=next(iter(bad))):
            LTCAOptions(**bad)


def test_edge_gap_curvature_stays_within_the_nodes_range():
    """On ISO sample 2 (FM) the spline of the pinion's gap curvature K, filled past a
    fold at the gear tip, dips to K ≈ −0.027 /rad on the boundary while every node holds
    K ≥ 0.055: the edges' separation ε + ½ K (Q − q)² then fell by hundreds of µm far from
    Q, and the LTE at 50 N·m ran to −3900 µrad. K is held within the nodes' range, so no
    segment's separation is below the UTE (≥ −1e-6 mm, the lag's quadrature) and the LTE
    stays positive."""
    case = load_case(ROOT / "cases" / "iso23509_sample2_fm.toml")
    eo = ease_off(case)
    f = EaseOffFields(eo)
    bd = flank_boundary(f, 0.25)
    lo, hi = f.gap_range
    assert lo > 0
    assert float(f.gap.ev(bd.u.ravel(), bd.v.ravel()).min()) < 0  # what the clamp removes
    assert lo <= bd.gap_curvature.min() and bd.gap_curvature.max() <= hi
    ds = loaded_tca(case, [50.0], options=LTCAOptions(cycles=1, rolls_per_cycle=8),
                    easeoff=eo)
    assert float(ds["separation"].min()) > -1e-6
    assert float(ds["transmission_error"].min()) > 0


def test_pinion_edge_does_not_hang_on_the_last_bit_of_a_contour_vertex(monkeypatch):
    """Where the pinion-margin contour crosses an ease-off grid line between a computed
    cell and one with an uncomputed corner, its vertex lies on that line (the contour
    grid's lines include the ease-off grid's), and contourpy's interpolation puts it on
    it or a unit in the last place to either side, as the margin's round-off falls: the
    pinion edge must not start one vertex earlier or later for that. The default case at
    the sweep guard's point ΔE = −0.10 mm, ΔP = 0.12 mm has such a vertex at v = 0.335;
    its pinion edge had 140 segments with one machine's BLAS kernels and 139 with
    another's (tests/test_sweep_guard.py). Here the vertex is moved to each side of the
    line: the boundary is the same to round-off."""
    import contourpy

    from contact.catalogue import DEFAULT_CASE, bundled_case_path

    case = load_case(bundled_case_path(DEFAULT_CASE))
    case = dataclasses.replace(case, misalignment=dataclasses.replace(
        case.misalignment, delta_E=-0.10, delta_P=0.12))
    f = EaseOffFields(ease_off(case))
    generator = contourpy.contour_generator
    lines = {"u": np.asarray(f.u), "v": np.asarray(f.v)}
    found = []

    def moved(side):
        def contour_generator(*args, **kwargs):
            gen = generator(*args, **kwargs)

            class Moved:
                def lines(self, level):
                    out = []
                    for line in gen.lines(level):
                        line = line.copy()
                        for axis, grid in enumerate(lines.values()):
                            x = line[:, axis]
                            k = np.argmin(np.abs(x[:, None] - grid[None]), axis=1)
                            on = np.abs(x - grid[k]) < 1e-12
                            found.append(int(on.sum()))
                            x[on] = np.nextafter(grid[k[on]], side * np.inf)
                        out.append(line)
                    return out

            return Moved()
        return contour_generator

    boundaries = []
    for side in (-1, 1):
        monkeypatch.setattr(contourpy, "contour_generator", moved(side))
        boundaries.append(flank_boundary(f, 0.25))
    low, high = boundaries
    # the contour crosses grid lines (vertices were moved) on a flank with uncomputed
    # cells beside computed ones; which cell it is follows the geometry (the pinion's tip
    # planes on the root cone moved it from row 0 to rows 11-12), so it is not pinned here
    cells = f.cell_ok
    assert sum(found) > 0 and (~cells).any() and cells.any()
    assert np.array_equal(low.kind, high.kind)
    for name in ("u", "v", "position"):
        np.testing.assert_allclose(getattr(low, name), getattr(high, name), rtol=0,
                                   atol=1e-12)


def test_edge_segments_written_after_the_curve_segments_equal_their_concatenation():
    """``edge_segments(..., before=curves)`` writes the curve segments and the edge
    segments into one array per field (issue 75: no (J, K, E) arrays copied again); the
    result is ``curves.concatenate(edge_segments(...))`` bit for bit (the same values
    copied, the same fill: NaN, length 0), so no analysis number changes."""
    from contact.ltca.edges import edge_segments
    from contact.ltca.segments import _curve_part_of, roll_phases

    eo = _easeoff()
    m1, _ = transitions(eo)
    target, _, _ = roll_phases(eo, m1 + np.arange(6) * eo.pitch / 6, (-1, 0, 1, 2))
    part = _curve_part_of(_case(), eo, target, 8, "cosine", 0.25)
    ute_env = np.min(np.where(np.isfinite(part.ute), part.ute, np.inf), axis=1)
    args = (_case(), eo, part.boundary, (0.5, 0.5), target, part.shift, ute_env)
    edge = edge_segments(*args)
    both = edge_segments(*args, before=part.found)
    old = part.found.concatenate(edge)
    assert np.count_nonzero(edge.length > 0) > 0  # edge segments in contact to write
    for name, value in old.per_segment().items():
        np.testing.assert_array_equal(getattr(both, name), value, err_msg=name)
        assert getattr(both, name).dtype == value.dtype
