"""The ease-off fields' interpolant across a corner (issue 71, docs/synthesis.md "The
ease-off interpolant at a relief corner").

:func:`contact.utca.corner_spline.corner_spline` must be the interpolating bicubic spline
where the data are smooth (it replaced ``RectBivariateSpline`` in the ease-off's fields),
and must not ring next to a kink: a relief only removes material, so the interpolant of
data that are flat on one side of a relief's start may not dip below them.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import RectBivariateSpline

from contact.utca.corner_spline import corner_nodes, corner_spline, node_slopes
from contact.utca.piecewise import from_splines
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


def test_smooth_data_give_the_interpolating_spline_itself():
    """No corner on smooth data, and the interpolant is RectBivariateSpline(s = 0) to
    round-off (values 1e-14 of their O(1) scale, derivatives to 1e-10: the Hermite form's
    sums of node slopes against FITPACK's B-spline sums)."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    z = _smooth(uu, vv)
    assert not corner_nodes(U, z).any() and not corner_nodes(V, z.T).any()
    old, new = RectBivariateSpline(U, V, z), corner_spline(U, V, z)
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
    new = corner_spline(U, V, z)(0.5, v).ravel() - exact
    assert old.min() < -1.0
    assert np.abs(new).max() < 0.05
    assert corner_spline(U, V, z)(U, V) == pytest.approx(z, abs=1e-9)


def test_the_cell_holding_the_corner_stays_between_its_nodes():
    """Shape preservation in the cell the corner lies in (Fritsch & Butland's slopes): the
    interpolant between the two nodes stays within their values."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    z = _relief(uu, vv, start=0.47)  # near the node 0.4775: the sharpest case
    v = np.linspace(0.43, 0.4775, 200)
    s = corner_spline(U, V, z)(0.5, v).ravel()
    lo, hi = sorted(_relief(0.5, np.array([0.43, 0.4775]), start=0.47))
    assert s.min() >= lo - 1e-9 and s.max() <= hi + 1e-9


def test_a_corner_is_found_on_the_two_nodes_of_its_cell_only():
    """A kink between v 0.43 and 0.4775 and the held relief's between 0.335 and 0.3825
    mark the four nodes of their two cells on every profile line (each hides the other from
    a median at first); the parabola elsewhere marks none."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    marks = corner_nodes(V, _relief(uu, vv).T)
    assert set(np.flatnonzero(marks.any(axis=1))) == {6, 7, 8, 9}
    assert marks[6:10].all()


def test_a_bending_that_grows_towards_an_end_is_no_corner():
    """A gap curvature rising towards a fold (1/(1.05 − v): each second difference up to
    3.4 times the last, as K near the ISO sample 1's tip) is no corner."""
    assert not corner_nodes(V, (1.0 / (1.05 - V))[:, None]).any()


def test_node_slopes_harmonic_at_a_cut_and_zero_across_a_sign_change():
    """At a cut the slope is the harmonic mean of the two pieces' one-sided slopes (0 where
    they differ in sign); elsewhere each piece's own spline slopes (a straight piece: its
    slope exactly)."""
    x = np.linspace(0.0, 1.0, 11)
    y = np.where(x < 0.5, 2.0 * x, 1.0 + 50.0 * (x - 0.5))  # kink on the node 0.5
    s = node_slopes(x, y[:, None])[:, 0]
    assert s[:5] == pytest.approx(2.0, rel=1e-12)
    assert s[6:] == pytest.approx(50.0, rel=1e-12)
    assert s[5] == pytest.approx(2 * 2.0 * 50.0 / 52.0, rel=1e-12)
    y = np.abs(x - 0.5) * 40.0  # a V: slopes of opposite sign at the cut
    assert node_slopes(x, y[:, None])[5, 0] == 0.0


def test_it_converts_to_the_piecewise_form_of_the_kernels():
    """Double interior knots: the piecewise-polynomial form (empty knot intervals left out)
    evaluates as FITPACK does, to 1e-12 of the data's 800 µrad scale."""
    uu, vv = np.meshgrid(U, V, indexing="ij")
    s = corner_spline(U, V, _relief(uu, vv))
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
