"""Starting guesses of the envelope solver (geometry.machine.meshing.solve_envelope(..., guess=)).

A guess only changes where Newton starts: the solution must be the one found without a
guess (same root, same mask reasons) to the solver's own tolerances, and a bad or missing
guess must fall back to the seed search and continuation. Speed is measured, not asserted,
in ``benchmarks/meshing_guess.py``.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pytest

from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.flank import projection_grid
from geometry.machine.meshing import solve_envelope

CASES = Path(__file__).resolve().parents[1] / "cases"
CASE_FILES = ("spiral_bevel_iso23509_s1.toml", "hypoid_iso23509_s2.toml")
FLANKS = [(m, f) for m in ("pinion", "gear") for f in ("concave", "convex")]
# the solver stops at |Δz|, |Δρ| < 1e-10 mm: two solutions of the same target agree to
# 2e-10 mm in z and ρ
TOL_POS = 2e-10


@cache
def _setup(name, member, flank):
    mem = load_case(CASES / name).member(member)
    tool = mem.flank(flank)
    bl = mem.blank
    grid = projection_grid(bl, 17, 9, (0.0, 1.0), (0.0, 1.0))
    kw = dict(length_scale=bl.outer_cone_distance, depth=bl.outer_addendum + bl.outer_dedendum)
    return tool, grid, kw


@cache
def _solve(name, member, flank, dz=0.0, dr=0.0):
    tool, grid, kw = _setup(name, member, flank)
    return solve_envelope(tool.blade, tool.machine, grid.axial + dz, grid.radius + dr, **kw)


def _assert_same(a, b):
    """Same mask reasons; valid points at the same place on the same root of the surface."""
    np.testing.assert_array_equal(a.reason, b.reason)
    ok = a.reason == 0
    np.testing.assert_array_equal(a.section[ok], b.section[ok])
    pa, pb = a.position[ok], b.position[ok]
    assert np.all(np.abs(pa[:, 2] - pb[:, 2]) <= TOL_POS)
    assert np.all(np.abs(np.hypot(pa[:, 0], pa[:, 1]) - np.hypot(pb[:, 0], pb[:, 1])) <= TOL_POS)
    # along the circle (z, ρ fixed) both lie on the same surface, so their distance is the
    # z, ρ mismatch carried by the surface slope: ≤ TOL_POS (|n_z| + |n_ρ|) / |n_θ|
    n = a.normal[ok]
    rho = np.hypot(pa[:, 0], pa[:, 1])
    e_t = np.stack([-pa[:, 1], pa[:, 0], np.zeros_like(rho)], -1) / rho[:, None]
    e_r = np.stack([pa[:, 0], pa[:, 1], np.zeros_like(rho)], -1) / rho[:, None]
    nt = np.abs((n * e_t).sum(-1))
    slope = (np.abs(n[:, 2]) + np.abs((n * e_r).sum(-1))) / nt
    circ = np.abs(((pa - pb) * e_t).sum(-1))
    assert np.all(circ <= TOL_POS * slope + 1e-11)  # + 1e-11 mm: round-off of the frames


@pytest.mark.parametrize("name", CASE_FILES)
@pytest.mark.parametrize("member, flank", FLANKS)
def test_guess_at_own_solution_is_identical(name, member, flank):
    """Guessing the solution itself returns it: Newton stops at the first evaluation, so
    the results agree to 1e-10 mm (the solver's position tolerance) and keep their reasons;
    masked points (NaN guess) take the path without a guess."""
    tool, grid, kw = _setup(name, member, flank)
    ref = _solve(name, member, flank)
    sol = solve_envelope(tool.blade, tool.machine, grid.axial, grid.radius, guess=ref, **kw)
    np.testing.assert_array_equal(sol.reason, ref.reason)
    ok = ref.reason == 0
    assert np.all(np.abs(sol.position[ok] - ref.position[ok]) <= 1e-10)
    # the tuple form without sections (derived from s) gives the same
    tup = solve_envelope(tool.blade, tool.machine, grid.axial, grid.radius,
                         guess=(ref.s, ref.theta, ref.q), **kw)
    _assert_same(tup, ref)


@pytest.mark.parametrize("name", CASE_FILES)
@pytest.mark.parametrize("member, flank", FLANKS)
def test_guess_from_nearby_targets(name, member, flank):
    """Targets moved by (0.05, 0.03) mm solved from the solution at the old targets equal
    the solution without a guess (same reasons, same root, to the solver tolerance)."""
    tool, grid, kw = _setup(name, member, flank)
    old = _solve(name, member, flank)
    ref = _solve(name, member, flank, 0.05, 0.03)
    sol = solve_envelope(tool.blade, tool.machine, grid.axial + 0.05, grid.radius + 0.03,
                         guess=old, **kw)
    _assert_same(sol, ref)


@pytest.mark.parametrize("member, flank", FLANKS)
def test_bad_guess_falls_back(member, flank):
    """Deliberately bad guesses (far off in s, θ, q; or all NaN; or one broadcast point of
    the wrong section) converge to the solution without a guess or are masked with the
    same reason: points that fail from their guess take the seed-and-continuation path."""
    name = "hypoid_iso23509_s2.toml"
    tool, grid, kw = _setup(name, member, flank)
    ref = _solve(name, member, flank)
    mid = tuple(d // 2 for d in grid.axial.shape)
    bad = [
        (ref.s + 3.0, ref.theta + 0.4, ref.q - 0.3, ref.section),
        (np.nan, np.nan, np.nan),
        (ref.s[mid] + 1.0, ref.theta[mid], ref.q[mid], 0),
    ]
    for guess in bad:
        sol = solve_envelope(tool.blade, tool.machine, grid.axial, grid.radius, guess=guess,
                             **kw)
        _assert_same(sol, ref)


def test_guess_bad_input():
    """Guesses that do not broadcast, have a section out of range or are not (s, θ, q)
    raise InputError naming the guess."""
    tool, grid, kw = _setup("hypoid_iso23509_s2.toml", "pinion", "concave")
    ref = _solve("hypoid_iso23509_s2.toml", "pinion", "concave")
    z, p = grid.axial, grid.radius
    for guess in [(ref.s[:3], ref.theta, ref.q), (ref.s, ref.theta, ref.q, 7),
                  (ref.s, ref.theta, ref.q, 0.5), (ref.s, ref.theta), 3.0]:
        with pytest.raises(InputError, match="guess"):
            solve_envelope(tool.blade, tool.machine, z, p, guess=guess, **kw)
