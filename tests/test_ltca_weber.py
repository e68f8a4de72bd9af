"""The Weber iteration of one roll (contact.ltca.weber) against the identities it must meet.

A roll's contact problem with Weber's load-dependent contact compliance is solved by
Newton's method on the contact deformation (module docstring). Its converged loads must
satisfy the *nonlinear* problem itself — compatibility with the secant compliance at those
loads, complementarity and torque equilibrium — which no single linear solve does.
Checked here on a synthetic roll with the structure of a hypoid mesh (two tooth pairs,
bending coupling along each contact line, parabolic separations), independent of the
gear geometry.
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.compliance.weber import weber_compliance
from contact.errors import ProblemInputError
from contact.ltca import LTCAOptions
from contact.ltca.weber import RollSelection, even_share, weber_solve
from geometry.core.hertz import STEEL, contact_modulus

E, NU = STEEL
MODULUS = contact_modulus(E, NU, E, NU)


def _roll(n_per_pair: int = 12) -> RollSelection:
    """Two tooth pairs of n segments each: exponential bending coupling within a pair
    (ISO 6336-1's c′ ≈ 14 N/(mm µm) over a 2 mm segment), none across pairs; parabolic
    ease-off, the second pair 4 µm further off; arms of a ~80 mm gear."""
    x = np.linspace(-1.0, 1.0, n_per_pair)
    block = 2.0 / (14e3 * 2.0) * np.exp(-np.abs(x[:, None] - x[None, :]) / 0.4)
    n = 2 * n_per_pair
    structural = np.zeros((n, n))
    structural[:n_per_pair, :n_per_pair] = block
    structural[n_per_pair:, n_per_pair:] = block
    sep = np.r_[8e-3 * x**2, 4e-3 + 8e-3 * x**2]
    return RollSelection(
        roll=0, pairs=np.repeat([0, 1], n_per_pair), segments=np.tile(np.arange(n_per_pair), 2),
        structural=structural, depth=np.full((n, 2), 4.0), length=np.full(n, 2.0),
        r_eq=np.full(n, 25.0), moment_arm=np.full(n, 80.0), separation=sep)


@pytest.mark.parametrize("torque", [2e5, 1e6, 4e6])  # gear torque [N·mm]
def test_converged_loads_solve_the_nonlinear_problem(torque):
    """At the converged loads F: C_s(F) F + s − R Θ = Y ≥ 0, F ≥ 0, F·Y = 0 and
    Rᵀ F = T, with C_s the structural compliance plus Weber's *secant* compliance at F.

    Tolerances: the iteration stops when the LTE changes by less than 1e-3 µrad (or its
    Newton step foretells that), so the gaps of the loaded segments close to
    R · 1e-3 µrad ≈ 1e-7 mm (80 mm arms) — 1e-6 mm allows the last step's ten-fold
    margin; equilibrium is the solver's own (1e-7 relative)."""
    sel = _roll()
    options = LTCAOptions()
    first = even_share(torque, sel.moment_arm)
    ws = weber_solve(sel, torque, first, options, MODULUS)
    sol = ws.solution
    assert sol.found and 2 <= ws.iterations <= options.max_weber_iterations
    F = np.maximum(sol.force, 0.0)
    secant = weber_compliance(F, sel.length, sel.depth[:, 0], sel.depth[:, 1], e1=E, nu1=NU,
                              e2=E, nu2=NU, r_eq=sel.r_eq, kind="secant")
    gap = (sel.structural + np.diag(secant)) @ F + sel.separation \
        - sel.moment_arm * sol.rotation
    loaded = F > 1e-9 * F.max()
    assert np.all(np.abs(gap[loaded]) < 1e-6)  # closed where loaded
    assert np.all(gap[~loaded] > -1e-6)  # open elsewhere
    assert abs(sel.moment_arm @ F - torque) < 1e-7 * torque
    assert loaded.sum() >= 3


def test_first_loads_share_the_torque():
    """even_share: the first loads carry exactly the torque over the given arms."""
    arms = np.array([70.0, 80.0, 90.0])
    f = even_share(1e6, arms)
    assert arms @ np.full(3, f) == pytest.approx(1e6, rel=1e-15)
    assert even_share(1e6, np.zeros(0)) == pytest.approx(1e6 / 1e-12)


def test_a_roll_that_cannot_carry_the_torque_is_refused_naming_the_field():
    """No segment with a positive moment arm: the problem is refused before any solve,
    naming ``moment_arm`` (never a NaN solution)."""
    sel = _roll(4)
    bad = RollSelection(**{**sel.__dict__, "moment_arm": -sel.moment_arm})
    with pytest.raises(ProblemInputError, match="moment_arm"):
        weber_solve(bad, 1e6, 1.0, LTCAOptions(), MODULUS)


@pytest.mark.parametrize("torque", [2e5, 4e6])  # gear torque [N·mm]
def test_compiled_warm_solves_change_nothing(monkeypatch, torque):
    """Issue 75: where the block pivoting runs compiled, the iterations after the first
    solve each problem in one compiled call (contact.qp.solvers.pivoting_numba.warm_solve)
    and make the problem and solution for the last only. Against every solve by
    solve_contact (the compiled call switched off): the same iterations, forces, Θ,
    slack, residuals, status and final problem, to the bit — the same kernel on the same
    arrays, not an approximation of it."""
    import contact.ltca.weber as weber

    if weber._warm_kernels("active_set") is None:
        pytest.skip("the block pivoting runs in NumPy here (no numba or LTCA_KERNELS)")
    sel = _roll()
    options = LTCAOptions()
    first = even_share(torque, sel.moment_arm)
    prior = np.full(sel.length.size, first)
    fast = weber_solve(sel, torque, first, options, MODULUS, prior=prior)
    monkeypatch.setattr(weber, "_warm_kernels", lambda solver: None)
    plain = weber_solve(sel, torque, first, options, MODULUS, prior=prior)
    assert fast.iterations == plain.iterations >= 2
    a, b = fast.solution, plain.solution
    np.testing.assert_array_equal(a.force, b.force)
    np.testing.assert_array_equal(a.slack, b.slack)
    assert a.rotation == b.rotation and a.residuals == b.residuals
    assert (a.found, a.status, a.solver, a.iterations, dict(a.extras)) == \
        (b.found, b.status, b.solver, b.iterations, dict(b.extras))
    np.testing.assert_array_equal(fast.problem.compliance, plain.problem.compliance)
    np.testing.assert_array_equal(fast.problem.separation, plain.problem.separation)


def test_a_last_solve_the_certification_refuses_is_solved_again(monkeypatch):
    """Where solve_contact's own residuals refuse the compiled call's last solution (a
    residual within round-off of the tolerance: the two sum C F in different orders), the
    last problem is solved again by solve_contact, whose answer is the one returned."""
    import contact.ltca.weber as weber

    if weber._warm_kernels("active_set") is None:
        pytest.skip("the block pivoting runs in NumPy here (no numba or LTCA_KERNELS)")
    sel = _roll()
    torque = 1e6
    first = even_share(torque, sel.moment_arm)
    prior = np.full(sel.length.size, first)
    want = weber_solve(sel, torque, first, LTCAOptions(), MODULUS, prior=prior)
    calls = []
    solve, residuals = weber.solve_contact, weber.residuals_and_gaps

    def counted(*args, **kwargs):
        calls.append(args[0])
        return solve(*args, **kwargs)

    def refusing(problem, force, rotation):
        res, gaps = residuals(problem, force, rotation)
        return {**res, "dual": 1.0}, gaps

    monkeypatch.setattr(weber, "solve_contact", counted)
    monkeypatch.setattr(weber, "residuals_and_gaps", refusing)
    got = weber_solve(sel, torque, first, LTCAOptions(), MODULUS, prior=prior)
    assert calls and calls[-1] is got.problem  # the last problem, solved again
    np.testing.assert_array_equal(got.solution.force, want.solution.force)
    assert got.solution.rotation == want.solution.rotation and got.solution.found
