"""The ease-off fields' interpolant across a corner (issue 71, docs/synthesis.md "The
ease-off interpolant at a relief corner").

:func:`contact.utca.corner_spline.corner_spline` must be the interpolating bicubic spline
where no line is cut (the ease-off's fields without a relief), and must not ring next to
a kink it is told of: a relief only removes material, so the interpolant of data that are
flat on one side of a relief's start may not dip below them. The cuts come from the design
(:func:`contact.utca.relief_corners.relief_corners`: the blades' sections of the nodes),
never from the data.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.interpolate import RectBivariateSpline

from contact.utca.corner_spline import corner_spline, node_slopes
from contact.utca.piecewise import from_splines
from contact.utca.relief_corners import relief_corners
from geometry.core.errors import InputError

#: the default ease-off grid: 41 lengthwise × 21 profile nodes
U = np.linspace(0.0, 1.0, 41)
V = np.linspace(0.05, 1.0, 21)


def _smooth(u, v):
    return np.sin(3 * u) * np.exp(v) + u * v**3


def _relief(u, v, start=0.44, slope=16000.0):
    """A flank's ease-off [µrad] with a tip relief of slope [µrad per unit v] from
    ``start`` towards v = 0 (the 16×16's: 786 µrad over 0.0475 of v), held beyond 0.06
    of v from the start (the ease-off's fill continues the last node of the sheet), on a
    parabola of 30 µrad per unit v² about v 0.57 (a smooth, unrelieved ease-off)."""
    return np.clip(start - v, 0.0, 0.06) * slope + 30.0 * (v - 0.57) ** 2 + 0.0 * u


def _relief_cuts(start=0.44):
    """The cuts the design gives for :func:`_relief` (the nodes of the cells holding its
    two kinks, at ``start`` and 0.06 before it, on every line along v)."""
    cut_v = np.zeros((U.size, V.size), dtype=bool)
    for kink in (start, start - 0.06):
        j = np.searchsorted(V, kink) - 1
        cut_v[:, j:j + 2] = True
    return cut_v


def test_smooth_data_give_the_interpolating_spline_itself():
    """No cut: the interpolant is RectBivariateSpline(s = 0) to round-off (values 1e-14 of
    their O(1) scale, derivatives to 1e-10: the Hermite form's sums of node slopes against
    FITPACK's B-spline sums), and cut masks without a cut are none."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    z = _smooth(uu, vv)
    none = np.zeros(z.shape, dtype=bool)
    old, new = RectBivariateSpline(U, V, z), corner_spline(U, V, z, none, none)
    rng = np.random.default_rng(7)
    u, v = rng.uniform(0, 1, 500), rng.uniform(0.05, 1, 500)
    for dx, dy, tol in ((0, 0, 1e-14), (1, 0, 1e-11), (0, 1, 1e-11), (1, 1, 1e-10)):
        assert np.abs(new.ev(u, v, dx=dx, dy=dy) - old.ev(u, v, dx=dx, dy=dy)).max() < tol
    assert new(U, V) == pytest.approx(z, abs=1e-14)


def test_no_dip_below_flat_data_next_to_a_relief_corner():
    """The relief's flat side (v ≥ 0.4775, the first node past the corner at 0.44) stays
    within 0.05 µrad of the parabola it interpolates (the parabola's own cubic
    interpolation error is ~1e-4 µrad; what is left is the harmonic slope at the cut:
    measured 0.036), where the global spline dips 1.45 µrad below it (ringing); the
    interpolant reproduces every node."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    z = _relief(uu, vv)
    v = np.linspace(0.4775, 1.0, 400)
    exact = _relief(0.5, v)
    old = RectBivariateSpline(U, V, z)(0.5, v).ravel() - exact
    new = corner_spline(U, V, z, cut_y=_relief_cuts())(0.5, v).ravel() - exact
    assert old.min() < -1.0
    assert np.abs(new).max() < 0.05
    assert corner_spline(U, V, z, cut_y=_relief_cuts())(U, V) == pytest.approx(z, abs=1e-9)


def test_the_cell_holding_the_corner_stays_between_its_nodes():
    """Shape preservation in the cell the corner lies in (Fritsch & Butland's slopes): the
    interpolant between the two nodes stays within their values."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    z = _relief(uu, vv, start=0.47)  # near the node 0.4775: the sharpest case
    v = np.linspace(0.43, 0.4775, 200)
    s = corner_spline(U, V, z, cut_y=_relief_cuts(0.47))(0.5, v).ravel()
    lo, hi = sorted(_relief(0.5, np.array([0.43, 0.4775]), start=0.47))
    assert s.min() >= lo - 1e-9 and s.max() <= hi + 1e-9


def _ease_off_sections(ps, gs, reason, smooth):
    """The four arrays :func:`relief_corners` reads, as an ease-off would carry them."""
    return SimpleNamespace(pinion_section=np.asarray(ps), gear_section=np.asarray(gs),
                           reason=np.asarray(reason, dtype=np.int8),
                           smooth=np.asarray(smooth, dtype=bool))


def test_the_design_cuts_lines_crossing_a_relief_start_at_its_cells_only():
    """The 16×16's column u 0.5 (tests/test_ratio_one_unloaded_te.py's case, read off its
    ease-off): filled nodes 0–6 (gear fillet), node 7 on the pinion's flankrem (section
    2), node 8 a hole at the corner, nodes 9–20 on the profile (section 1). The line is cut
    at the nodes of the cells where the label changes (6, 7, 8, 9), nowhere else; a line
    whose sheet lies on the profile only, with the same fill, is not cut; a blade without
    relief gives no cut at all (None: the fields keep the interpolating splines)."""
    n = 21
    ps = np.array([2] * 8 + [1] * 13)
    gs = np.array([0] * 7 + [1] * 14)
    reason = np.array([3] * 8 + [2] + [0] * 12)
    smooth = np.array([0] * 7 + [1, 0] + [1] * 12, dtype=bool)
    plain = np.ones(n, dtype=int)
    eo = _ease_off_sections(np.stack([ps, plain] * 2), np.stack([gs] * 4),
                            np.stack([reason] * 4), np.stack([smooth] * 4))
    cut_u, cut_v = relief_corners(eo)
    assert set(np.flatnonzero(cut_v[0])) == {6, 7, 8, 9}
    assert not cut_v[1].any()
    # along u the sections alternate (2, 1, 2, 1) on node 7: every line through it cut
    assert cut_u[:, 7].all() and not cut_u[:, 10:].any()
    none = _ease_off_sections(np.ones((4, n), int), np.stack([gs] * 4),
                              np.stack([reason] * 4), np.stack([smooth] * 4))
    assert relief_corners(none) is None


def test_a_corner_strip_node_cuts_its_line():
    """A node of a corner's strip (``smooth`` without a mate: the pinion blade's corner
    touches it) cuts its line at its two cells even where the mates' sections read the
    same on both sides; a section array of another shape is refused."""
    n = 12
    reason = np.zeros((4, n), int)
    reason[1, 5] = 2
    eo = _ease_off_sections(np.ones((4, n), int), np.ones((4, n), int), reason,
                            np.ones((4, n), bool))
    _, cut_v = relief_corners(eo)
    assert set(np.flatnonzero(cut_v[1])) == {4, 5, 6} and not cut_v[[0, 2, 3]].any()
    with pytest.raises(InputError, match="pinion_section and gear_section"):
        relief_corners(_ease_off_sections(np.ones((3, n), int), np.ones((4, n), int),
                                          reason, np.ones((4, n), bool)))


def test_node_slopes_harmonic_at_a_cut_and_zero_across_a_sign_change():
    """At a cut the slope is the harmonic mean of the two pieces' one-sided slopes (0 where
    they differ in sign); elsewhere each piece's own spline slopes (a straight piece: its
    slope exactly)."""
    x = np.linspace(0.0, 1.0, 11)
    y = np.where(x < 0.5, 2.0 * x, 1.0 + 50.0 * (x - 0.5))  # kink on the node 0.5
    cut = np.zeros((11, 1), dtype=bool)
    cut[5] = True
    s = node_slopes(x, y[:, None], cut)[:, 0]
    assert s[:5] == pytest.approx(2.0, rel=1e-12)
    assert s[6:] == pytest.approx(50.0, rel=1e-12)
    assert s[5] == pytest.approx(2 * 2.0 * 50.0 / 52.0, rel=1e-12)
    y = np.abs(x - 0.5) * 40.0  # a V: slopes of opposite sign at the cut
    assert node_slopes(x, y[:, None], cut)[5, 0] == 0.0


def test_it_converts_to_the_piecewise_form_of_the_kernels():
    """Double interior knots: the piecewise-polynomial form (empty knot intervals left out)
    evaluates as FITPACK does, to 1e-12 of the data's 800 µrad scale."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    s = corner_spline(U, V, _relief(uu, vv), cut_y=_relief_cuts())
    pp = from_splines([s])
    assert pp.bx == pytest.approx(U) and pp.by == pytest.approx(V)
    rng = np.random.default_rng(3)
    u, v = rng.uniform(0, 1, 300), rng.uniform(0.05, 1, 300)
    i = np.minimum(np.searchsorted(pp.bx, u, side="right") - 1, len(pp.bx) - 2)
    j = np.minimum(np.searchsorted(pp.by, v, side="right") - 1, len(pp.by) - 2)
    du, dv = u - pp.bx[i], v - pp.by[j]
    c = pp.coefficients[i, j, 0]
    val = np.einsum("mpq,mp,mq->m", c, du[:, None] ** np.arange(4), dv[:, None] ** np.arange(4))
    assert val == pytest.approx(s.ev(u, v), abs=1e-12 * 800)


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="x: must be at least 4"):
        corner_spline([0.0, 1.0, 2.0], V, np.zeros((3, V.size)))
    with pytest.raises(InputError, match="z: must be"):
        corner_spline(U, V, np.zeros((3, 3)))
    with pytest.raises(InputError, match="y: must be finite"):
        node_slopes(V, np.full((V.size, 1), np.nan))
    with pytest.raises(InputError, match="cut_y: must be a bool array"):
        corner_spline(U, V, np.zeros((U.size, V.size)), cut_y=np.zeros((3, 3), bool))


def test_a_measured_deviation_adds_no_cut():
    """A gear deviation with a sharp bend of its own (a worn band 4 µm deep with straight
    flanks between u 0.4 and 0.6, as a wear step's border) leaves the cuts where the design
    put them: the default case's (its pinion tip relief) exactly, and none on a case
    without relief, whose fields stay the interpolating splines (``RectBivariateSpline``
    itself, not the Hermite form) — the worn ease-off's bends are never cut (spline88's
    data-found corners cut them and broke tests/test_wear.py)."""
    from pathlib import Path

    from contact.catalogue import resolve_case
    from contact.utca.deviations import SurfaceDeviation, apply_deviations
    from contact.utca.easeoff import ease_off
    from contact.utca.fields import EaseOffFields
    from geometry.case import load_case

    gu, gv = np.linspace(-0.2, 1.2, 29), np.linspace(-0.2, 1.2, 15)
    band = -0.004 * np.clip(1.0 - np.abs(gu - 0.5) / 0.1, 0.0, 1.0)[:, None] * np.ones(gv.size)
    worn = SurfaceDeviation(gu, gv, band)
    eo = ease_off(resolve_case(None), flank="drive")
    designed = relief_corners(eo)
    assert designed is not None
    got = relief_corners(apply_deviations(eo, gear=worn))
    assert np.array_equal(got[0], designed[0]) and np.array_equal(got[1], designed[1])
    plain = ease_off(load_case(Path(__file__).resolve().parents[1] / "cases"
                               / "kolivand2009_fm_11x41.toml"), flank="drive")
    deviated = apply_deviations(plain, gear=worn)
    assert relief_corners(deviated) is None
    f = EaseOffFields(deviated)
    assert f.cuts is None and type(f.eps) is RectBivariateSpline
