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

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np

from contact.ltca import LTCAOptions
from contact.ltca.weber import RollSelection, even_share, weber_solve
from contact.utca import EaseOffFields, contact_curves, transitions
from contact.utca.contact_curves import (
    _EDGE_TOL,
    CURVE_SPACINGS,
    _feasible_edge,
    _gap_at_contact,
    _probe_shift,
    _seed_places,
)
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.core.hertz import STEEL, contact_modulus

ROOT = Path(__file__).resolve().parents[1]
E, NU = STEEL
MODULUS = contact_modulus(E, NU, E, NU)


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


def test_near_miss_shifts_do_not_depend_on_where_the_grid_falls():
    """The kolivand 11x41's 22 iso-lines of a sweep (201 rolls over 2.5 pitches) that miss
    the region, probed with the grid's places moved by 0, 0.37 and 0.71 of its last step
    (where round-off of the ease-off puts a place on one side of a corner or the other is
    such a move): the probe's cost UTE_seed + ½ K t_b² at the shifts found agrees to
    5e-9 rad. Measured: nine of the rows have their minimum on the edge of the feasible
    set, their shifts now the same to the bit (they moved by 8.4 and 16.2 µrad, their cost
    by up to 1.5e-7 rad before the edge was bisected); one interior minimum moves by
    83 µrad and 1.5e-9 rad, the grid's own accuracy at a smooth minimum (½ c″ h²)."""
    eo = _easeoff()
    f = EaseOffFields(eo)
    m1, _ = transitions(eo)
    q = m1 + np.linspace(-1.0, 1.5, 201) * eo.pitch
    first = _seed_places(f, q, CURVE_SPACINGS["cosine"](21))
    lost = q[~np.isfinite(first.ute)]
    assert lost.size >= 10
    frac = CURVE_SPACINGS["uniform"](9)
    costs = []
    for phase in (0.0, 0.37, 0.71):
        rows, tb = _probe_shift(f, lost, phase=phase)
        pr = _seed_places(f, lost[rows] + tb, frac, coarse_per_cell=1)
        costs.append((rows, pr.ute + 0.5 * _gap_at_contact(f, pr) * tb**2))
    for rows, c in costs[1:]:
        assert np.array_equal(rows, costs[0][0])
        np.testing.assert_allclose(c, costs[0][1], rtol=0, atol=5e-9)


def _roll_with_short_segment(short: float) -> RollSelection:
    """A synthetic roll (one pair, 12 segments of 2 mm over x ∈ [-1, 1], exponential bending
    coupling as ISO 6336-1's c′ ≈ 14 N/(mm µm), parabolic separation) and a 13th segment of
    length ``short`` [mm] where the curve runs on (x = 1.05, the separation continued): its
    structural compliance that of a point load, independent of its length."""
    x = np.r_[np.linspace(-1.0, 1.0, 12), 1.05]
    structural = 2.0 / (14e3 * 2.0) * np.exp(-np.abs(x[:, None] - x[None, :]) / 0.4)
    n = x.size
    return RollSelection(
        roll=0, pairs=np.zeros(n, int), segments=np.arange(n), structural=structural,
        depth=np.full((n, 2), 4.0), length=np.r_[np.full(n - 1, 2.0), short],
        r_eq=np.full(n, 25.0), moment_arm=np.full(n, 80.0), separation=8e-3 * x**2)


def test_the_load_of_a_segment_shrinking_to_zero_length_tends_to_zero():
    """The seed's segment load is line load × length (Eq. 3.12–3.14 with Weber's compliance
    per unit length, ∝ 1/length for a segment): a segment of 1e-3 … 1e-7 mm beyond a
    curve's end carries a force ∝ its length — its line load the same to 1 % at every
    length (measured 4259.6 … 4271.6 N/mm; its structural deflection F·7e-5 mm/N is
    negligible beside Weber's), its force tending to 0 — and the other segments' forces
    move by at most its force plus the iteration's tolerance (1e-2 N).

    Weber's iteration is run to 1e-9 µrad here: at the default 1e-3 µrad it stops on the
    LTE, which a segment of ≤ 1e-5 mm does not move, with that segment's line load
    unconverged (measured 1389 N/mm, 3 iterations; 4260 N/mm, 6 iterations, at 1e-3 mm) —
    still ∝ its length, so its force still tends to 0 (checked too)."""
    tight = dataclasses.replace(LTCAOptions(), weber_tolerance=1e-9, max_weber_iterations=60)
    torque = 1e6  # [N·mm]
    for options in (tight, LTCAOptions()):
        forces = {}
        for short in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7):
            sel = _roll_with_short_segment(short)
            ws = weber_solve(sel, torque, even_share(torque, sel.moment_arm), options,
                             MODULUS)
            assert ws.solution.found
            forces[short] = np.maximum(ws.solution.force, 0.0)
        line = np.array([f[-1] / s for s, f in forces.items()])  # [N/mm]
        assert line.min() > 0
        assert forces[1e-7][-1] < 1e-3  # [N]
        rest = np.abs(forces[1e-7][:-1] - forces[1e-3][:-1]).max()
        assert rest <= forces[1e-3][-1] + 1e-2
        if options is tight:
            assert line.max() / line.min() - 1 < 0.01
        else:  # the unconverged short segments: the same line load below 1e-5 mm
            assert abs(line[-1] / line[-2] - 1) < 0.01
