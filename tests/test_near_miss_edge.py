"""A near miss's shift on the edge of its feasible set (contact.utca.contact_curves).

A pair whose iso-line Q = q misses the contact region is shifted to the iso-line
Q = q + t_b that minimises UTE_seed + ½ K t_b²; the cost is infinite where the iso-line
misses, and its minimum often sits where the iso-line starts to meet a corner. The probe's
grid found the first feasible place beyond that edge (up to a grid step, 1.8e-5 rad) or
the edge itself, with the round-off of the ease-off: on the miter 20x20's written coast
flank a 1 µm curve at the gear tip appeared or not, the edge segments moved by µm and the
tip edge peak by 5.26 MPa (issue 71). Independent checks: a cost whose minimum is an edge
known in closed form, and the continuity of the shifts under a 1e-13 rad perturbation.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np

from contact.utca import EaseOffFields, contact_curves, transitions
from contact.utca.contact_curves import _EDGE_TOL, _feasible_edge
from contact.utca.easeoff import ease_off
from geometry.case import load_case

ROOT = Path(__file__).resolve().parents[1]


def _edge_cost(edges: np.ndarray):
    """Cost (rows, x) of rows whose feasible set is x ≥ edge, rising from it (slope 1 and
    curvature 1e3, as UTE_seed + ½ K t² rises from a corner's edge)."""
    def grid_cost(rows, x):
        d = x - edges[rows][:, None]
        return np.where(d >= 0, d + 1e3 * d**2, np.inf)
    return grid_cost


def test_the_grid_minimum_moves_onto_the_edge_whichever_side_the_grid_falls():
    """Grid places k·h (h = 1.8e-5 rad, the probe's last step on the miter): an edge on a
    place (found there) and edges 1e-14 … 0.999 h beyond one (the grid stops a step past
    it) all end within the bisection's tolerance of their edge (1e-12 rad, plus round-off
    of the places ~1e-17); before, the second group ended up to h away."""
    h = 1.8e-5
    k = 1000
    edges = k * h + np.array([0.0, 1e-14, 1e-9, 0.5 * h, 0.999 * h])
    grid = np.ceil(edges / h - 1e-9) * h  # the first grid place at or beyond each edge
    grid = np.where(grid < edges, grid + h, grid)
    out = _feasible_edge(_edge_cost(edges), grid, np.ones(edges.size, bool), h)
    assert np.all(out >= edges)  # feasible
    np.testing.assert_allclose(out, edges, rtol=0, atol=_EDGE_TOL + 1e-15)
    # the two first edges (1e-14 apart) now give shifts 1e-14 apart, not a step h
    assert abs(out[1] - out[0]) < 2 * _EDGE_TOL


def test_interior_minima_and_rows_not_found_are_kept():
    """A minimum inside the feasible set (both neighbours finite) and a row the grid did
    not find are returned as given, bit for bit."""
    def cost(rows, x):
        return (x - 1.0) ** 2
    x = np.array([1.0, 2.0])
    out = _feasible_edge(cost, x, np.array([True, False]), 1e-3)
    assert np.array_equal(out, x)


@cache
def _easeoff():
    return ease_off(load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml"))


def test_near_miss_shifts_are_continuous_under_a_perturbation():
    """The curves of a sweep over a mesh cycle and a half (near misses included: the
    pairs entering and leaving at the region's corners), and of the same rolls moved by
    1e-13 rad: every shift and UTE moves by ≤ 1e-9 rad (a jump of the probe's grid is a
    step, ≥ 1e-5 rad, and 1e-7 rad of UTE; smooth dependence gives ~1e-13)."""
    eo = _easeoff()
    f = EaseOffFields(eo)
    m1, _ = transitions(eo)
    q = m1 + np.linspace(-1.0, 1.5, 41) * eo.pitch
    a = contact_curves(eo, q, n_point=21, spacing="cosine", near_misses=True, fields=f)
    b = contact_curves(eo, q + 1e-13, n_point=21, spacing="cosine", near_misses=True,
                       fields=f)
    assert np.array_equal(np.isfinite(a.ute), np.isfinite(b.ute))
    fin = np.isfinite(a.shift) & np.isfinite(b.shift)
    assert np.any(fin & (a.shift != 0))  # some near misses shifted
    np.testing.assert_allclose(a.shift[fin], b.shift[fin], rtol=0, atol=1e-9)
    ok = np.isfinite(a.ute)
    np.testing.assert_allclose(a.ute[ok], b.ute[ok], rtol=0, atol=1e-9)
