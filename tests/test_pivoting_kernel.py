"""The compiled block pivoting (contact.qp.solvers.pivoting_numba) against the NumPy path.

Both run the same iterations (start sets, KKT system per contact set, sign tests, pivots);
the compiled one factors C_AA by the Cholesky–Banachiewicz recurrence, the NumPy one by
LAPACK's blocked ``potrf``. Tolerance: the two factorisations agree to round-off, ~1e-15
relative per entry; the KKT solution's condition number on these problems (κ(C_AA) ≲ 1e4,
the compliance's diagonal dominating through its contact term) carries that to ≲ 1e-11 of
the largest force, and the certified residuals of both are below the solver's 1e-7.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from contact.qp import ContactProblem, solve_contact
from contact.qp.benchmark_problems import ltca_like_problem
from contact.qp.solvers.active_set import block_pivoting

kernels = pytest.importorskip("contact.qp.solvers.pivoting_numba",
                              reason="numba (the 'fast' extra) is not installed")

FORCE_RTOL = 1e-10


def _both(monkeypatch, problem, **kw):
    out = {}
    for name in ("numpy", "numba"):
        monkeypatch.setenv("LTCA_KERNELS", name)
        out[name] = block_pivoting(problem, **kw)
    return out["numba"], out["numpy"]


def _bounded(problem: ContactProblem, fraction: float) -> ContactProblem:
    """The problem with force limits at ``fraction`` of its unbounded solution's largest
    force on every segment (so several segments reach their limits)."""
    ref = solve_contact(problem)
    limit = fraction * float(ref.force.max())
    return dataclasses.replace(problem, upper_bound=np.full(problem.size, limit))


@pytest.mark.parametrize("n, seed", [(12, 0), (74, 1), (134, 2), (300, 3)])
@pytest.mark.parametrize("fraction", [None, 0.6])
def test_compiled_pivoting_is_the_numpy_path(monkeypatch, n, seed, fraction):
    """Cold starts, with and without force limits: the same iterations, outcome and
    contact sets, forces and Θ to round-off, and a certified solution."""
    problem = ltca_like_problem(n, seed=seed).problem
    if fraction is not None:
        problem = _bounded(problem, fraction)
    got, want = _both(monkeypatch, problem)
    assert got["converged"] and want["converged"]
    assert got["status"] == want["status"] == "solved"
    assert got["iterations"] == want["iterations"] and not got["fallback"]
    scale = float(np.max(np.abs(want["force"])))
    np.testing.assert_allclose(got["force"], want["force"], rtol=FORCE_RTOL,
                               atol=FORCE_RTOL * scale)
    np.testing.assert_allclose(got["rotation"], want["rotation"], rtol=FORCE_RTOL)
    np.testing.assert_array_equal(got["force"] > 0, want["force"] > 0)
    if fraction is not None:
        assert np.sum(got["force"] >= problem.upper_bound * (1 - 1e-12)) >= 1
    monkeypatch.setenv("LTCA_KERNELS", "numba")
    assert solve_contact(problem).found


def test_compiled_pivoting_from_warm_and_poor_starts(monkeypatch):
    """Warm starts from a neighbouring solution, a start set that cannot carry the torque
    (only segments with negative arms) and an iteration cap that trips: the same
    outcomes on both paths (the cap's fallback runs in NumPy)."""
    tp = ltca_like_problem(90, seed=5)
    problem = tp.problem
    prior = solve_contact(problem).force
    moved = dataclasses.replace(problem, separation=problem.separation * 1.05)
    got, want = _both(monkeypatch, moved, initial_active_set=prior > 0)
    assert got["iterations"] == want["iterations"] and got["converged"]
    np.testing.assert_allclose(got["force"], want["force"], rtol=FORCE_RTOL,
                               atol=FORCE_RTOL * want["force"].max())
    poor = np.zeros(problem.size, dtype=bool)
    poor[np.argmin(problem.moment_arm)] = True
    got, want = _both(monkeypatch, problem, initial_active_set=poor)
    assert got["converged"] and got["iterations"] == want["iterations"]
    got, want = _both(monkeypatch, problem, max_iterations=1, fallback=False)
    assert not got["converged"] and not want["converged"]
    assert got["status"] == want["status"]
    assert "iteration cap (1)" in got["status"]


def test_kernel_outcomes_name_the_failure():
    """A contact set that cannot carry the torque even with every loaded-side segment
    (a Schur floor above any complement) is reported, not returned as a solution."""
    problem = ltca_like_problem(20, seed=1).problem
    n = problem.size
    F, _, it, outcome = kernels.block_pivoting(
        problem.compliance, problem.separation, problem.moment_arm, float(problem.torque),
        problem.upper_bound, False, 1e-12, 1e-12, np.inf, np.ones(n, dtype=bool),
        np.zeros(n, dtype=bool), 10)
    assert outcome == kernels.CANNOT_CARRY and it == 1
    assert not np.any(F)  # no solution was found: the forces stay at their start (0)


def _warm(problem: ContactProblem, diagonal: np.ndarray, separation: np.ndarray,
          start: np.ndarray):
    """pivoting_numba.warm_solve of ``problem`` with another diagonal and separations,
    with the new problem's scale and thresholds as contact.ltca.weber hands them."""
    from contact.qp.problem import ProblemScale
    from contact.qp.solvers.active_set import pivoting_thresholds

    sc = problem.scale
    scale = ProblemScale(force=sc.force, length=sc.force * float(np.mean(diagonal)),
                         arm=sc.arm)
    return kernels.warm_solve(problem.compliance, diagonal, separation, problem.moment_arm,
                              float(problem.torque), problem.upper_bound, problem.bounded,
                              problem.has_bounds, *pivoting_thresholds(scale), start, 1e-7,
                              scale.force, scale.length, scale.arm, 50)


@pytest.mark.parametrize("n, seed", [(74, 1), (134, 2)])
@pytest.mark.parametrize("fraction", [None, 0.6])
def test_warm_solve_is_solve_contact_to_the_bit(n, seed, fraction):
    """The Weber iteration's compiled solve (issue 75) against solve_contact on the
    problem with_diagonal makes: the same start sets and block pivoting, so the same
    forces, Θ and iterations to the bit (not to round-off: the same kernel on the same
    arrays), certified where solve_contact certifies."""
    base = ltca_like_problem(n, seed=seed).problem
    if fraction is not None:
        base = _bounded(base, fraction)
    rng = np.random.default_rng(seed)
    diagonal = np.diagonal(base.compliance) * (1.0 + rng.uniform(0.0, 0.3, base.size))
    separation = base.separation + rng.uniform(0.0, 1e-3, base.size)
    prior = solve_contact(base)
    problem = base.with_diagonal(diagonal, separation)
    want = solve_contact(problem, initial=prior)
    F, theta, its, outcome, certified = _warm(base, diagonal, separation, prior.force)
    assert outcome == kernels.SOLVED and certified and want.found
    np.testing.assert_array_equal(F, want.force)
    assert theta == want.rotation and its == want.iterations


def test_warm_solve_leaves_a_cold_start_to_the_caller():
    """A warm start that loads no segment able to carry the torque: COLD_START, the
    caller's general path (contact.ltca.weber falls back to solve_contact)."""
    base = ltca_like_problem(40, seed=4).problem
    diagonal = np.diagonal(base.compliance).copy()
    *_, outcome, certified = _warm(base, diagonal, base.separation.copy(),
                                   np.zeros(base.size))
    assert outcome == kernels.COLD_START and not certified
