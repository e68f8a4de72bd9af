"""The loaded-contact QP with force limits F ≤ F_max (elastic–perfectly-plastic segments).

Independent references and identities:
- without active limits the bounded problem is the unbounded one: the same answer to
  round-off (limits above every force change nothing: the KKT conditions are the same);
- at a limit the force equals it, the segment penetrates (Y ≤ 0, the plastic flow), the
  other segments carry the rest of the torque (equilibrium), and the box-constrained KKT
  conditions hold (upper complementarity among the certified residuals);
- the Hertz cylinder on a flat (Johnson 1985 Eq. 4.43–4.45, Love's strip influence
  coefficients): with a pressure limit on every strip the pressure is flat at the limit
  where Hertz's would exceed it and the contact widens to carry the load;
- quadprog and the other backends (tests/test_solvers.py) on the same problems.

Every problem here has at most 240 segments: each test takes well under a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from contact import ContactProblem, solve_contact
from contact.errors import ProblemInputError
from contact.qp.benchmark_problems import hertz_cylinder_problem, ltca_like_problem
from contact.qp.problem import RESIDUALS, contact_residuals
from contact.qp.problem_files import read_problem, write_problem
from contact.qp.solvers.active_set import (
    block_pivoting,
    initial_contact_sets,
    primal_active_set,
)


def _with_bound(p: ContactProblem, bound: np.ndarray) -> ContactProblem:
    return ContactProblem(p.compliance, p.separation, p.moment_arm, p.torque, name=p.name,
                          upper_bound=bound)


@pytest.mark.parametrize("n, seed", [(40, 0), (120, 1), (240, 2)])
def test_limits_above_every_force_change_nothing(n, seed):
    # Below the limit the bounded QP is today's: limits 1 % above the loaded segments'
    # forces (and on every unloaded one) leave the same answer to 1e-9 (round-off of the
    # same reduced KKT system: its contact set is the same).
    p = ltca_like_problem(n, seed=seed).problem
    ref = solve_contact(p)
    bound = np.where(ref.force > 0, 1.01 * ref.force, 10.0 * ref.force.max())
    sol = solve_contact(_with_bound(p, bound))
    assert sol.found, sol.status
    assert np.max(np.abs(sol.force - ref.force)) <= 1e-9 * ref.force.max()
    assert sol.rotation == pytest.approx(ref.rotation, rel=1e-9)
    assert not np.any(sol.at_limit(_with_bound(p, bound)))
    assert sol.residuals["upper_complementarity"] <= 1e-12


def test_no_limit_is_the_unbounded_problem_bit_for_bit():
    p = ltca_like_problem(90, seed=5).problem
    q = _with_bound(p, np.full(p.size, np.inf))
    assert not q.has_bounds
    a, b = solve_contact(p), solve_contact(q)
    assert np.array_equal(a.force, b.force) and a.rotation == b.rotation
    assert set(a.residuals) == set(RESIDUALS) and a.residuals["upper_complementarity"] == 0.0


@pytest.mark.parametrize("n, seed", [(60, 3), (160, 4), (240, 6)])
def test_at_the_limit_neighbours_carry_the_rest(n, seed):
    # Above the limit: the limited segments carry exactly F_max, penetrate (Y < 0: the
    # plastic flow the elastic model cannot follow), the others carry the rest of the
    # torque, and the box KKT conditions certify to round-off.
    p = ltca_like_problem(n, seed=seed).problem
    ref = solve_contact(p)
    top = np.argsort(-ref.force)[:4]
    bound = np.full(n, np.inf)
    bound[top] = 0.6 * ref.force[top]
    q = _with_bound(p, bound)
    sol = solve_contact(q)
    assert sol.found, sol.status
    plastic = sol.at_limit(q)
    assert np.array_equal(np.flatnonzero(plastic), np.sort(top))
    np.testing.assert_allclose(sol.force[top], bound[top], rtol=1e-12)
    assert np.all(sol.slack[top] < 0)
    # equilibrium: what the limited segments give up, the others carry
    R = p.moment_arm
    others = ~plastic
    assert R[others] @ sol.force[others] == pytest.approx(
        p.torque - R[top] @ bound[top], rel=1e-12)
    assert R[others] @ sol.force[others] > R[others] @ ref.force[others]
    # a softer contact: the gear turns further to carry the torque
    assert sol.rotation > ref.rotation
    res = contact_residuals(q, sol.force, sol.rotation)
    assert max(res.values()) <= 1e-12, res
    # the unbounded residuals of the same answer fail: the penetration is not elastic
    assert contact_residuals(p, sol.force, sol.rotation)["dual"] > 1e-6


def test_an_unloaded_segment_with_a_limit_below_the_tolerance_is_not_plastic():
    # A sliver of a contact line clipped at the face's boundary (8.4e-7 mm long) has a
    # force limit below the solver's tolerance (3.2e-4 N against 30 kN): unloaded, it was
    # counted at its limit, and `ltca run` printed "plastic 2 (0.0 %)" for a design
    # without a plastic contact (issue 71, round 16). Plastic segments carry their limit.
    p = ltca_like_problem(120, seed=12).problem
    ref = solve_contact(p)
    open_ = np.flatnonzero(ref.force == 0.0)
    assert open_.size
    bound = np.full(p.size, np.inf)
    tiny = 1e-3 * ref.tolerance * ref.force.max()
    bound[open_[:3]] = tiny
    q = _with_bound(p, bound)
    sol = solve_contact(q)
    assert sol.found, sol.status
    np.testing.assert_array_equal(sol.force[open_[:3]], 0.0)
    assert not np.any(sol.at_limit(q))
    # a limit that binds is still found: the largest force's segment at half its force
    top = int(np.argmax(ref.force))
    bound[top] = 0.5 * ref.force[top]
    q = _with_bound(p, bound)
    sol = solve_contact(q)
    assert sol.found, sol.status
    assert np.array_equal(np.flatnonzero(sol.at_limit(q)), [top])


def test_upper_complementarity_catches_penetration_below_the_limit():
    # A limited segment that penetrates while below its limit violates the upper
    # complementarity (and only it: its Y < 0 is not a dual violation, which would be
    # wrong at the limit).
    p = ltca_like_problem(60, seed=8).problem
    ref = solve_contact(p)
    k = int(np.argmax(ref.force))
    bound = np.full(p.size, np.inf)
    bound[k] = 0.5 * ref.force[k]
    q = _with_bound(p, bound)
    sol = solve_contact(q)
    F = sol.force.copy()
    F[k] *= 0.9  # off its limit, still penetrating
    res = contact_residuals(q, F, sol.rotation)
    assert res["upper_complementarity"] > 1e-3
    F[k] = 1.1 * bound[k]  # beyond the limit: primal infeasible
    assert contact_residuals(q, F, sol.rotation)["primal"] > 1e-3


def test_hertz_cylinder_with_a_pressure_limit():
    # Johnson Eq. 4.43–4.45 on 20 strips per half-width (discretisation error 0.01 % of
    # p0, tests/test_solvers.py); a pressure limit of 0.8 p0 on every strip: the middle
    # strips carry exactly the limit (a flat top), the contact widens beyond Hertz's b to
    # carry the same load, and the approach grows.
    tp = hertz_cylinder_problem(20)
    ref_sol = solve_contact(tp.problem)
    r = tp.reference
    p_lim = 0.8 * r["peak_pressure"]
    bound = np.full(tp.problem.size, p_lim * r["strip"])
    q = _with_bound(tp.problem, bound)
    sol = solve_contact(q)
    assert sol.found, sol.status
    p = sol.force / r["strip"]
    plastic = sol.at_limit(q)
    # Hertz's pressure exceeds 0.8 p0 within |x| < 0.6 b: those strips are at the limit
    # (one strip either way at the ends of the plateau: the plateau's edge moves as the
    # contact widens)
    hertz_above = np.abs(r["x"]) < 0.6 * r["half_width"] - r["strip"]
    assert np.all(plastic[hertz_above])
    np.testing.assert_allclose(p[plastic], p_lim, rtol=1e-12)
    assert p.max() <= p_lim * (1 + 1e-12)
    width = np.ptp(r["x"][sol.active_set | plastic]) + r["strip"]
    width_ref = np.ptp(r["x"][ref_sol.active_set]) + r["strip"]
    assert width > width_ref + r["strip"]
    assert sol.force.sum() == pytest.approx(tp.problem.torque, rel=1e-12)
    assert sol.rotation > ref_sol.rotation


def test_primal_active_set_and_block_pivoting_agree_under_limits():
    for seed in range(3):
        p = ltca_like_problem(150, seed=20 + seed).problem
        ref = solve_contact(p)
        bound = np.full(p.size, np.inf)
        top = np.argsort(-ref.force)[:10]
        bound[top] = 0.5 * ref.force[top]
        q = _with_bound(p, bound)
        F, theta, _, ok = primal_active_set(q)
        out = block_pivoting(q)
        assert ok and out["converged"] and not out["fallback"]
        np.testing.assert_allclose(F, out["force"], rtol=1e-9, atol=1e-9 * ref.force.max())
        assert theta == pytest.approx(out["rotation"], rel=1e-9)


def test_bad_warm_starts_reach_the_same_answer():
    p = ltca_like_problem(200, seed=9).problem
    ref = solve_contact(p)
    bound = np.full(p.size, np.inf)
    top = np.argsort(-ref.force)[:8]
    bound[top] = 0.7 * ref.force[top]
    q = _with_bound(p, bound)
    cold = solve_contact(q)
    rng = np.random.default_rng(0)
    for _ in range(5):
        active = rng.random(p.size) < 0.3
        upper = q.bounded & (rng.random(p.size) < 0.5)
        out = block_pivoting(q, initial_active_set=active, initial_upper_set=upper)
        assert out["converged"]
        np.testing.assert_allclose(out["force"], cold.force, rtol=1e-9,
                                   atol=1e-9 * cold.force.max())
    # the previous solution as a warm start: one iteration
    warm = solve_contact(q, initial=cold)
    assert warm.found and warm.iterations == 1


def test_cold_start_sets_of_the_lumped_problem():
    # The water filling with limits: the sets are disjoint, the at-limit set lies among
    # the limited segments, and with limits far above every force it is the unlimited
    # water filling's set.
    p = ltca_like_problem(120, seed=11).problem
    ref = solve_contact(p)
    far = _with_bound(p, np.full(p.size, 1e6 * ref.force.max()))
    loaded, at_limit = initial_contact_sets(far)
    loaded0, _ = initial_contact_sets(p)
    assert np.array_equal(loaded, loaded0) and not at_limit.any()
    bound = np.full(p.size, np.inf)
    bound[np.argsort(-ref.force)[:10]] = 1e-3 * ref.force.max()
    q = _with_bound(p, bound)
    loaded, at_limit = initial_contact_sets(q)
    assert not np.any(loaded & at_limit)
    assert np.all(q.bounded[at_limit]) and at_limit.any()


def test_infeasible_limits_are_refused():
    p = ltca_like_problem(30, seed=1).problem
    with pytest.raises(ProblemInputError, match="upper_bound"):
        _with_bound(p, np.full(p.size, 1e-6))  # cannot carry T
    with pytest.raises(ProblemInputError, match="upper_bound"):
        _with_bound(p, np.zeros(p.size))
    with pytest.raises(ProblemInputError, match="upper_bound"):
        _with_bound(p, np.full(p.size + 1, np.inf))
    with pytest.raises(ProblemInputError, match="upper_bound"):
        _with_bound(p, np.full(p.size, np.nan))


def test_problem_file_round_trip_keeps_the_limits(tmp_path):
    p = ltca_like_problem(50, seed=2).problem
    ref = solve_contact(p)
    bound = np.full(p.size, np.inf)
    bound[np.argmax(ref.force)] = 0.5 * ref.force.max()
    q = _with_bound(p, bound)
    back = read_problem(write_problem(tmp_path / "q", q))
    assert np.array_equal(back.upper_bound, q.upper_bound)
    plain = read_problem(write_problem(tmp_path / "p", p))
    assert not plain.has_bounds


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(min_value=6, max_value=120), st.integers(min_value=0, max_value=10_000),
       st.floats(min_value=0.05, max_value=0.95), st.integers(min_value=1, max_value=12))
def test_property_box_kkt_conditions(n, seed, fraction, n_limited):
    # Limits on up to half the segments (the others, all with R > 0 in these instances,
    # keep the problem feasible): 0 ≤ F ≤ F_max, Y ≥ 0 where F = 0, Y = 0
    # where 0 < F < F_max, Y ≤ 0 where F = F_max, RᵀF = T (the box-constrained KKT
    # conditions, each to round-off relative to the problem's scales).
    p = ltca_like_problem(n, seed=seed).problem
    ref = solve_contact(p)
    bound = np.full(n, np.inf)
    assert np.all(p.moment_arm > 0)
    top = np.argsort(-ref.force)[:min(n_limited, n // 2)]
    bound[top] = fraction * np.maximum(ref.force[top], ref.force.max() * 1e-3)
    q = _with_bound(p, bound)
    sol = solve_contact(q)
    assert sol.found, sol.status
    F, Y = sol.force, sol.slack
    f = max(F.max(), q.scale.force)
    d = max(float(np.max(np.abs(q.compliance @ F))), q.scale.length)
    assert np.all(F >= -1e-12 * f) and np.all(F <= bound + 1e-12 * f)
    below = F < bound - 1e-9 * f
    assert np.all(Y[below] >= -1e-10 * d)
    loaded = (F > 1e-9 * f) & below
    assert np.all(np.abs(Y[loaded]) <= 1e-10 * d)
    assert np.all(Y[~below] <= 1e-10 * d)
    assert abs(q.moment_arm @ F - q.torque) <= 1e-12 * q.torque
