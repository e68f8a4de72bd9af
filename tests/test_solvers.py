"""Solvers of the loaded-contact problem: Hertz, cross-backend agreement, identities, guards.

Independent references:
- Hertz's closed-form contact of a sphere and of a cylinder on a flat (Johnson,
  *Contact Mechanics*, Eq. 4.22–4.23, 4.43–4.45), discretised with the exact
  influence coefficients of Love (1929) / Johnson Eq. 3.25 and 2.25;
- quadprog (Goldfarb–Idnani dual active set), an implementation independent of ours;
- identities the contact conditions must satisfy (complementarity, equilibrium,
  homogeneity in (s, T), invariance under a rigid rotation of the separations).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from contact import ContactProblem, available_solvers, solve_contact
from contact.qp.benchmark_problems import (
    hertz_cylinder_problem,
    hertz_sphere_problem,
    ltca_like_problem,
)
from contact.qp.solvers import register_backend, unregister_backend
from contact.qp.solvers.active_set import block_pivoting, primal_active_set
from contact.qp.solvers.backend import Backend, RawResult

SOLVERS = available_solvers()

# Agreement with our exact solver, relative to the largest force (and to |Θ|).
# Certification bounds every residual by 1e-7; a force error is that residual times
# the conditioning of the loaded block, measured here at up to ~6e-7 (cvxopt, highs:
# interior-point and simplex-type stopping tests) and ≤ 1e-9 for the rest. Exact
# active-set methods (quadprog, daqp) agree to round-off.
FORCE_TOL = {"active_set": 1e-12, "quadprog": 1e-10, "daqp": 1e-10, "cvxpy:DAQP": 1e-10}
DEFAULT_FORCE_TOL = 5e-6


@pytest.fixture(scope="module")
def sphere():
    return hertz_sphere_problem(8)


@pytest.fixture(scope="module")
def cylinder():
    return hertz_cylinder_problem(20)


def _fit_radius(coord_sq: np.ndarray, pressure: np.ndarray, m: np.ndarray) -> float:
    """Contact radius from the Hertz profile p² = p₀² (1 − r²/a²), linear in r², over set m."""
    A = np.column_stack((np.ones(m.sum()), coord_sq[m]))
    c0, c1 = np.linalg.lstsq(A, pressure[m] ** 2, rcond=None)[0]
    return math.sqrt(-c0 / c1)


@pytest.mark.parametrize("solver", SOLVERS)
def test_hertz_sphere(solver, sphere):
    # 8 cells per contact radius: the discretisation error is 0.1 % (p₀), 0.3 % (a),
    # 0.03 % (δ) with the exact solver, so 1 % tests each backend, not the grid.
    sol = solve_contact(sphere.problem, solver)
    assert sol.found, sol.status
    ref = sphere.reference
    p = sol.force / ref["cell_area"]
    assert p.max() == pytest.approx(ref["peak_pressure"], rel=0.01)
    assert _fit_radius(ref["x"] ** 2 + ref["y"] ** 2, p, sol.active_set) == pytest.approx(
        ref["radius"], rel=0.01
    )
    assert sol.rotation == pytest.approx(ref["approach"], rel=0.01)


@pytest.mark.parametrize("solver", SOLVERS)
def test_hertz_cylinder(solver, cylinder):
    # 20 strips per half-width: discretisation error 0.01 % (p₀), 0.1 % (b), 1e-5 (δ).
    sol = solve_contact(cylinder.problem, solver)
    assert sol.found, sol.status
    ref = cylinder.reference
    p = sol.force / ref["strip"]
    assert p.max() == pytest.approx(ref["peak_pressure"], rel=0.01)
    assert _fit_radius(ref["x"] ** 2, p, sol.active_set) == pytest.approx(
        ref["half_width"], rel=0.01
    )
    assert sol.rotation == pytest.approx(ref["approach"], rel=0.01)


def test_hertz_converges_with_refinement():
    # The contact radius error of the discretised sphere must fall as cells shrink.
    errs = []
    for k in (4, 8, 16):
        tp = hertz_sphere_problem(k)
        sol = solve_contact(tp.problem)
        r = tp.reference
        a = _fit_radius(r["x"] ** 2 + r["y"] ** 2, sol.force / r["cell_area"], sol.active_set)
        errs.append(abs(a / r["radius"] - 1))
    assert errs[0] > errs[1] > errs[2]


@pytest.fixture(scope="module")
def random_problems():
    probs = [ltca_like_problem(n, seed=s) for s, n in enumerate((40, 90, 160, 240))]
    return [(tp.problem, solve_contact(tp.problem)) for tp in probs]


@pytest.mark.parametrize("solver", SOLVERS)
def test_backends_agree_with_exact_solver(solver, random_problems):
    tol = FORCE_TOL.get(solver, DEFAULT_FORCE_TOL)
    for problem, ref in random_problems:
        sol = solve_contact(problem, solver)
        assert sol.found, f"{problem.name}: {sol.status}"
        scale = np.max(ref.force)
        assert np.max(np.abs(sol.force - ref.force)) <= tol * scale, problem.name
        assert abs(sol.rotation - ref.rotation) <= tol * abs(ref.rotation), problem.name
        assert sol.max_residual <= sol.tolerance


def _limited(problem: ContactProblem, force: np.ndarray, fraction: float = 0.7,
             every: int = 20) -> ContactProblem:
    """The problem with force limits on its most loaded segments (one in ``every``, at
    least three): ``fraction`` of their unlimited force; no limit elsewhere."""
    bound = np.full(problem.size, np.inf)
    top = np.argsort(-force)[: max(3, problem.size // every)]
    bound[top] = fraction * force[top]
    return ContactProblem(problem.compliance, problem.separation, problem.moment_arm,
                          problem.torque, name=f"{problem.name}_limited", upper_bound=bound)


@pytest.fixture(scope="module")
def limited_problems(random_problems):
    out = []
    for problem, ref in random_problems:
        q = _limited(problem, ref.force)
        out.append((q, solve_contact(q)))
    return out


@pytest.mark.parametrize("solver", SOLVERS)
def test_backends_agree_with_exact_solver_under_force_limits(solver, limited_problems):
    # The QP with box constraints 0 ≤ F ≤ F_max (the elastic–perfectly-plastic segments):
    # every registered backend takes the limits and agrees with our exact solver to the
    # same tolerance map as without limits (the answers are certified by the same
    # residuals, the upper bound's complementarity among them).
    tol = FORCE_TOL.get(solver, DEFAULT_FORCE_TOL)
    for problem, ref in limited_problems:
        assert ref.found and ref.at_limit(problem).sum() >= 3, ref.status
        sol = solve_contact(problem, solver)
        assert sol.found, f"{problem.name}: {sol.status}"
        scale = np.max(ref.force)
        assert np.max(np.abs(sol.force - ref.force)) <= tol * scale, problem.name
        assert abs(sol.rotation - ref.rotation) <= tol * abs(ref.rotation), problem.name
        assert np.all(sol.force <= problem.upper_bound * (1 + sol.tolerance))
        assert sol.max_residual <= sol.tolerance


def test_exact_solver_matches_quadprog_to_1e8():
    # quadprog (Goldfarb & Idnani 1983) is an exact dual active-set method written
    # independently of ours: the two must agree to round-off, 1e-8 relative at least.
    pytest.importorskip("quadprog",
                        reason="an optional backend: pip install 'hypoid-ltca[solvers]'")
    for seed, n in enumerate((50, 120, 300, 500)):
        problem = ltca_like_problem(n, seed=100 + seed).problem
        ours = solve_contact(problem)
        theirs = solve_contact(problem, "quadprog", polish_solution=False)
        assert ours.found and theirs.found
        assert np.max(np.abs(ours.force - theirs.force)) <= 1e-8 * np.max(ours.force)
        assert abs(ours.rotation - theirs.rotation) <= 1e-8 * abs(ours.rotation)
        assert max(ours.residuals.values()) < 1e-12


problem_params = st.tuples(
    st.integers(min_value=6, max_value=120),
    st.integers(min_value=0, max_value=10_000),
    st.floats(min_value=1e3, max_value=2e6),
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problem_params)
def test_property_complementarity_and_equilibrium(params):
    n, seed, torque = params
    problem = ltca_like_problem(n, seed=seed, torque=torque).problem
    sol = solve_contact(problem)
    assert sol.found, sol.status
    F, Y = sol.force, sol.slack
    sc = problem.scale
    assert np.all(F >= -1e-12 * sc.force)
    assert np.all(Y >= -1e-10 * max(sc.length, float(np.max(np.abs(problem.compliance @ F)))))
    assert np.max(np.minimum(F / np.max(F), Y / np.max(np.abs(Y) + sc.length))) <= 1e-10
    assert abs(problem.moment_arm @ F - torque) <= 1e-12 * torque
    assert (np.any(F > 0) and sol.rotation > 0) or np.min(problem.separation) > 0


@settings(max_examples=30, deadline=None)
@given(problem_params, st.floats(min_value=0.05, max_value=20.0))
def test_property_homogeneity(params, alpha):
    # (s, T) → α (s, T) scales F and Θ by α exactly: the conditions are homogeneous.
    n, seed, torque = params
    p = ltca_like_problem(n, seed=seed, torque=torque).problem
    q = ContactProblem(p.compliance, alpha * p.separation, p.moment_arm, alpha * p.torque)
    a, b = solve_contact(p), solve_contact(q)
    assert np.array_equal(a.active_set, b.active_set)
    np.testing.assert_allclose(b.force, alpha * a.force, rtol=1e-8, atol=1e-10 * np.max(b.force))
    assert b.rotation == pytest.approx(alpha * a.rotation, rel=1e-8)


@settings(max_examples=30, deadline=None)
@given(problem_params, st.floats(min_value=0.1, max_value=10.0))
def test_property_torque_scaling_without_separation(params, alpha):
    # With zero initial separation the contact set does not depend on T: F ∝ T.
    n, seed, torque = params
    p = ltca_like_problem(n, seed=seed, torque=torque).problem
    p0 = ContactProblem(p.compliance, np.zeros(n), p.moment_arm, torque)
    a, b = solve_contact(p0), solve_contact(p0.with_torque(alpha * torque))
    assert np.array_equal(a.active_set, b.active_set)
    np.testing.assert_allclose(b.force, alpha * a.force, rtol=1e-8, atol=1e-10 * np.max(b.force))


@settings(max_examples=30, deadline=None)
@given(problem_params, st.floats(min_value=-1e-3, max_value=1e-3))
def test_property_rigid_rotation_of_separations(params, phi):
    # s → s + R φ is a rigid rotation of the gear: F unchanged, Θ → Θ + φ.
    n, seed, torque = params
    p = ltca_like_problem(n, seed=seed, torque=torque).problem
    q = ContactProblem(p.compliance, p.separation + p.moment_arm * phi, p.moment_arm, torque)
    a, b = solve_contact(p), solve_contact(q)
    np.testing.assert_allclose(b.force, a.force, rtol=1e-7, atol=1e-9 * np.max(a.force))
    assert b.rotation == pytest.approx(a.rotation + phi, rel=1e-9, abs=1e-12)


def test_iteration_cap_triggers_fallback_and_same_answer():
    problem = ltca_like_problem(300, seed=7).problem
    ref = solve_contact(problem)
    assert ref.iterations > 1
    capped = solve_contact(problem, max_iterations=1)
    assert capped.found
    assert capped.extras["fallback"] is True
    assert "fallback" in capped.status
    np.testing.assert_allclose(capped.force, ref.force, rtol=1e-9, atol=1e-9 * ref.force.max())
    assert capped.rotation == pytest.approx(ref.rotation, rel=1e-10)


def test_cycle_detection_triggers_fallback(monkeypatch):
    # Force a two-set cycle: from the full set, a fake KKT solve says segment 0 pulls
    # (F < 0); from the set without it, a fake huge Θ makes segment 0 penetrate.
    import contact.qp.solvers.active_set as mod

    monkeypatch.setenv("LTCA_KERNELS", "numpy")  # the fake KKT solve is the NumPy path's
    problem = ltca_like_problem(80, seed=3).problem
    n = problem.size
    real = mod.reduced_kkt

    def cycling(C, s, R, T, idx, floor):
        if idx.size == n:
            F_A = np.ones(n)
            F_A[0] = -1.0
            return F_A, 0.0
        if idx.size == n - 1 and idx[0] != 0:
            return np.ones(n - 1), 1e6
        return real(C, s, R, T, idx, floor)

    monkeypatch.setattr(mod, "reduced_kkt", cycling)
    out = block_pivoting(problem, initial_active_set=np.ones(n, dtype=bool))
    assert out["fallback"] and out["converged"]
    assert "cycled" in out["status"]
    monkeypatch.setattr(mod, "reduced_kkt", real)
    ref = solve_contact(problem)
    np.testing.assert_allclose(out["force"], ref.force, rtol=1e-9, atol=1e-9 * ref.force.max())


def test_fallback_disabled_reports_failure():
    problem = ltca_like_problem(300, seed=7).problem
    sol = solve_contact(problem, max_iterations=1, fallback=False, polish_solution=False)
    assert not sol.found
    assert "fallback disabled" in sol.status


def test_primal_active_set_alone_is_exact():
    for seed in range(3):
        problem = ltca_like_problem(150, seed=seed).problem
        F, _theta, _, ok = primal_active_set(problem)
        ref = solve_contact(problem)
        assert ok
        np.testing.assert_allclose(F, ref.force, rtol=1e-9, atol=1e-9 * ref.force.max())


def test_warm_start_from_previous_solution_is_cheaper():
    problem = ltca_like_problem(240, seed=2).problem
    cold = solve_contact(problem)
    warm = solve_contact(problem, initial=cold)
    assert warm.found and warm.iterations == 1
    assert cold.iterations > 1
    np.testing.assert_allclose(warm.force, cold.force, rtol=1e-12, atol=1e-12 * cold.force.max())


@pytest.fixture
def register():
    """Register test doubles through the public registry; unregistered after the test."""
    names = []

    def _register(name, fn):
        register_backend(name, Backend(name, "test", fn, False, "test double"))
        names.append(name)

    yield _register
    for name in names:
        unregister_backend(name)


def test_backend_exception_is_reported_not_raised(register):
    def broken(problem, **_):
        raise RuntimeError("solver crashed")

    register("broken", broken)
    sol = solve_contact(ltca_like_problem(30).problem, "broken")
    assert not sol.found
    assert "solver crashed" in sol.status
    assert all(math.isinf(v) for v in sol.residuals.values())


def test_false_success_claim_is_not_passed_on(register):
    # A backend that claims success with a poor answer (uniform forces) is reported unfound.
    def liar(problem, **_):
        F = np.full(problem.size, problem.torque / problem.moment_arm.sum())
        return RawResult(F, 0.0, True, "optimal", 0.0, 0.0)

    register("liar", liar)
    sol = solve_contact(ltca_like_problem(60, seed=1).problem, "liar", polish_solution=False)
    assert not sol.found
    assert "not certified" in sol.status


def test_polish_rescues_a_nearly_right_answer(register):
    problem = ltca_like_problem(120, seed=4).problem
    exact = solve_contact(problem)

    def sloppy(problem, **_):
        F = exact.force * (1 + 1e-3 * np.sin(np.arange(problem.size)))
        return RawResult(F, exact.rotation * (1 + 1e-4), True, "optimal", 0.0, 0.0)

    register("sloppy", sloppy)
    raw = solve_contact(problem, "sloppy", polish_solution=False)
    polished = solve_contact(problem, "sloppy")
    assert not raw.found
    assert polished.found and polished.status == "solved (polished)"
    np.testing.assert_allclose(
        polished.force, exact.force, rtol=1e-9, atol=1e-9 * exact.force.max()
    )
    assert "raw_residuals" in polished.extras


def test_a_missing_optional_backend_is_named_with_its_install_line(monkeypatch):
    """A known backend the registry lacks (a name no one installs stands for one) is listed
    by missing_backends and named, with the line that installs it, when asked for."""
    from contact.errors import SolverNotFoundError
    from contact.qp import solvers

    monkeypatch.setitem(solvers.KNOWN_BACKENDS, "nosuchqp", "nosuchqp-dist")
    missing = solvers.missing_backends()
    assert missing["nosuchqp"] == f"pip install nosuchqp-dist (or {solvers.SOLVERS_EXTRA})"
    assert set(missing) == {n for n in solvers.KNOWN_BACKENDS if n not in available_solvers()}
    with pytest.raises(SolverNotFoundError, match=r"'nosuchqp' is an optional backend: pip "
                                                  r"install nosuchqp-dist"):
        solve_contact(ltca_like_problem(10).problem, "nosuchqp")
