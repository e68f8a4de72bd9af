"""ContactProblem validation and the toolkit's error family."""

from __future__ import annotations

import numpy as np
import pytest

from contact import (
    ContactError,
    ContactProblem,
    NotPositiveDefiniteError,
    ProblemInputError,
    SolverNotFoundError,
    available_solvers,
    solve_contact,
)
from geometry.core.errors import InputError, LTCAError


def _good(n=4):
    rng = np.random.default_rng(1)
    A = rng.normal(size=(n, n))
    C = A @ A.T + n * np.eye(n)
    return C * 1e-5, np.linspace(0, 0.01, n), np.full(n, 80.0), 2e5


def test_valid_problem_records_symmetrisation():
    C, s, R, T = _good()
    Cn = C.copy()
    Cn[0, 1] += 1e-7
    p = ContactProblem(Cn, s, R, T)
    np.testing.assert_allclose(p.compliance, p.compliance.T, rtol=0, atol=0)
    expected = np.linalg.norm(Cn - Cn.T) / np.linalg.norm(Cn)
    assert p.asymmetry == pytest.approx(expected, rel=1e-12)
    assert ContactProblem(C, s, R, T).asymmetry == 0.0


def test_asymmetry_beyond_the_limit_is_refused():
    """Off-diagonals of opposite sign (the issue-21 matrix): ‖C − Cᵀ‖/‖C‖ = 0.6√2/√2.18 =
    0.575 breaks Maxwell–Betti reciprocity; refused, naming the field and the limit."""
    from contact.errors import ASYMMETRY_LIMIT, AsymmetricComplianceError

    C = 1e-5 * np.array([[1.0, 0.3], [-0.3, 1.0]])
    expected = 0.6 * np.sqrt(2) / np.sqrt(2.18)
    with pytest.raises(AsymmetricComplianceError, match=r"compliance: .*0\.575.*0\.05"):
        ContactProblem(C, [0.0, 0.0], [80.0, 80.0], 1e5)
    assert expected == pytest.approx(0.575, abs=5e-4) and expected > ASYMMETRY_LIMIT
    with pytest.raises(ProblemInputError):  # one family: caught as bad input
        ContactProblem(C, [0.0, 0.0], [80.0, 80.0], 1e5)


def test_asymmetry_below_the_limit_is_symmetrised_and_reported():
    """Just under the limit the problem is built on ½(C + Cᵀ) and records the asymmetry
    (relative Frobenius norm, computed here independently)."""
    from contact.errors import ASYMMETRY_LIMIT

    a = 0.02
    C = 1e-5 * np.array([[1.0, 0.1 + a], [0.1 - a, 1.0]])
    p = ContactProblem(C, [0.0, 0.0], [80.0, 80.0], 1e5)
    expected = np.hypot(2 * a, 2 * a) / np.linalg.norm(C / 1e-5)
    assert p.asymmetry == pytest.approx(expected, rel=1e-12)
    assert p.asymmetry < ASYMMETRY_LIMIT
    np.testing.assert_array_equal(p.compliance, p.compliance.T)
    assert p.compliance[0, 1] == pytest.approx(1e-6, rel=1e-12)


def test_problem_arrays_are_read_only():
    p = ContactProblem(*_good())
    with pytest.raises(ValueError):
        p.separation[0] = 1.0


@pytest.mark.parametrize(
    ("mutate", "field"),
    [
        (lambda C, s, R, T: (C[:, :-1], s, R, T), "compliance"),
        (lambda C, s, R, T: (C[0], s, R, T), "compliance"),
        (lambda C, s, R, T: (C, s[:-1], R, T), "compliance"),
        (lambda C, s, R, T: (C, s, R[:-1], T), "moment_arm"),
        (lambda C, s, R, T: (C, np.array([]), np.array([]), T), "separation"),
        (lambda C, s, R, T: (np.where(np.eye(len(s)) > 0, np.nan, C), s, R, T), "compliance"),
        (lambda C, s, R, T: (C, np.r_[s[:-1], np.inf], R, T), "separation"),
        (lambda C, s, R, T: (C, s, -R, T), "moment_arm"),
        (lambda C, s, R, T: (C, s, np.zeros_like(R), T), "moment_arm"),
        (lambda C, s, R, T: (C, s, R, 0.0), "torque"),
        (lambda C, s, R, T: (C, s, R, -5.0), "torque"),
        (lambda C, s, R, T: (C, s, R, float("nan")), "torque"),
        (lambda C, s, R, T: (C, s, R, "lots"), "torque"),
        (lambda C, s, R, T: ("abc", s, R, T), "compliance"),
    ],
)
def test_bad_input_names_the_field(mutate, field):
    with pytest.raises(ProblemInputError, match=field):
        ContactProblem(*mutate(*_good()))


def test_not_positive_definite_is_refused():
    C, s, R, T = _good()
    C = C.copy()
    C[0, 0] = -1e-3
    with pytest.raises(NotPositiveDefiniteError, match="not positive definite"):
        ContactProblem(C, s, R, T)
    with pytest.raises(NotPositiveDefiniteError):
        ContactProblem(np.zeros_like(C), s, R, T)


def test_with_diagonal_is_the_constructors_problem():
    """Weber's next problem of a roll (only C's diagonal and s change) equals the one the
    constructor builds, to the bit, asymmetric off-diagonals and force limits included;
    its new C is still checked positive definite, its arrays finite."""
    C, s, R, T = _good(6)
    C = C.copy()
    C[0, 1] += 1e-7  # symmetrised by both
    U = np.full(6, 1e6)
    first = ContactProblem(C + np.diag(np.full(6, 2e-5)), s, R, T, name="roll 3",
                           upper_bound=U)
    d = np.linspace(1e-5, 3e-5, 6)
    s2 = s + 1e-4
    want = ContactProblem(C + np.diag(d), s2, R, T, name="roll 3", upper_bound=U)
    got = first.with_diagonal(np.diag(C) + d, s2)
    for name in ("compliance", "separation", "moment_arm", "upper_bound", "bounded"):
        np.testing.assert_array_equal(getattr(got, name), getattr(want, name))
    assert (got.torque, got.name, got.scale) == (want.torque, want.name, want.scale)
    # ‖C‖ of the symmetric C: the same but for the asymmetry's own square
    assert got.asymmetry == pytest.approx(want.asymmetry, rel=want.asymmetry**2)
    C4, s4, R4, T4 = _good()
    assert ContactProblem(C4, s4, R4, T4).with_diagonal(np.diag(C4), s4).asymmetry == 0.0
    with pytest.raises(ValueError):
        got.compliance[0, 0] = 1.0
    with pytest.raises(NotPositiveDefiniteError):
        first.with_diagonal(np.r_[-1e-3, d[1:]], s2)
    with pytest.raises(ProblemInputError, match="finite"):
        first.with_diagonal(d, np.r_[s2[:-1], np.nan])
    with pytest.raises(ProblemInputError, match="shape"):
        first.with_diagonal(d[:-1], s2)



def test_renamed_is_the_same_problem_unchecked(monkeypatch):
    """A repeated roll's problem under its own name: every array and derived value the
    same (the arrays shared, read-only), no second Cholesky."""
    import contact.qp.problem as problem_module

    C, s, R, T = _good(6)
    first = ContactProblem(C, s, R, T, name="roll 3", upper_bound=np.full(6, 1e6))
    monkeypatch.setattr(problem_module, "_check_positive_definite",
                        lambda C: pytest.fail("checked again"))
    got = first.renamed("roll 23")
    assert (got.name, first.name) == ("roll 23", "roll 3")
    for name in ("compliance", "separation", "moment_arm", "upper_bound", "bounded"):
        assert getattr(got, name) is getattr(first, name)
    assert (got.torque, got.scale, got.asymmetry, got.has_bounds) == (
        first.torque, first.scale, first.asymmetry, first.has_bounds)
    with pytest.raises(ValueError):
        got.compliance[0, 0] = 1.0

def test_with_diagonal_skips_the_cholesky_only_where_weyl_proves_it(monkeypatch):
    """A diagonal nowhere below the (checked) problem's keeps C positive definite (Weyl's
    inequality: λ_min(A + D) ≥ λ_min(A) for D ≥ 0), so no Cholesky is paid; one entry below
    it is checked again. Checked here by the smallest eigenvalue of every C made, over
    random symmetric positive definite problems whose smallest eigenvalue is tiny (the
    case where a wrong skip would show)."""
    import contact.qp.problem as problem_module

    calls = []
    real = problem_module._check_positive_definite
    monkeypatch.setattr(problem_module, "_check_positive_definite",
                        lambda C: (calls.append(1), real(C)))
    rng = np.random.default_rng(11)
    for _ in range(20):
        n = 8
        q, _r = np.linalg.qr(rng.standard_normal((n, n)))
        eig = np.r_[1e-9, rng.uniform(1e-6, 1e-4, n - 1)]
        C = (q * eig) @ q.T
        C = 0.5 * (C + C.T)
        _, s, R, T = _good(n)
        base = ContactProblem(C, s, R, T)
        calls.clear()
        up = base.with_diagonal(np.diag(C) + rng.uniform(0.0, 1e-5, n), s)
        assert not calls
        assert np.linalg.eigvalsh(up.compliance)[0] > 0.0
        down = np.diag(C).copy()
        down[rng.integers(n)] *= 0.999
        try:
            base.with_diagonal(down, s)
        except NotPositiveDefiniteError:
            pass
        assert calls  # checked: a lower diagonal may lose positive definiteness


def test_weber_iterations_stay_above_their_checked_base():
    """Weber's iteration checks one base problem per roll, whose diagonal is the structural
    compliance plus half the secant contact compliance at the load cap; the identity its
    skip rests on: the secant compliance falls with the load (so it is least at the cap)
    and the iteration's compliance (the tangent where above half the secant, else the
    secant) is never below that floor, over loads from the floor to the cap."""
    from contact.compliance.weber import WeberSegments

    seg = WeberSegments.of(np.array([0.5, 1.0, 2.0]), np.array([2.0, 3.0, 4.0]),
                           np.array([2.5, 2.0, 5.0]), e1=206000.0, nu1=0.3, e2=206000.0,
                           nu2=0.3, r_eq=np.array([5.0, 20.0, 60.0]))
    e_star = 206000.0 / (2 * (1 - 0.3**2))
    depth = np.minimum([2.0, 3.0, 4.0], [2.5, 2.0, 5.0])
    cap = np.pi * e_star * depth**2 / (4 * np.array([5.0, 20.0, 60.0])) * np.array(
        [0.5, 1.0, 2.0])
    floor = 0.5 * seg.compliance(cap, kind="secant")
    loads = np.linspace(0.0, 1.0, 400)[:, None] * cap
    cs, ct = seg.compliance(loads, kind=("secant", "tangent"))
    assert np.all(np.diff(cs, axis=0) <= 0.0)
    newton = (ct > 0.5 * cs) & (loads < cap)
    assert np.all(np.where(newton, ct, cs) >= floor)


def test_errors_are_one_family():
    assert issubclass(ProblemInputError, ContactError)
    assert issubclass(ContactError, LTCAError)
    assert issubclass(ProblemInputError, InputError)
    assert issubclass(ProblemInputError, ValueError)  # users catching ValueError still work
    assert issubclass(NotPositiveDefiniteError, ProblemInputError)
    assert issubclass(SolverNotFoundError, LTCAError)


def test_unknown_solver_lists_available():
    p = ContactProblem(*_good())
    with pytest.raises(SolverNotFoundError) as info:
        solve_contact(p, "no-such-solver")
    for name in available_solvers():
        assert name in str(info.value)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"accuracy": "extreme"}, "accuracy"),
        ({"tolerance": 0.0}, "tolerance"),
        ({"tolerance": 2.0}, "tolerance"),
    ],
)
def test_bad_solve_options(kwargs, field):
    p = ContactProblem(*_good())
    with pytest.raises(ProblemInputError, match=field):
        solve_contact(p, **kwargs)


def test_bad_problem_type():
    with pytest.raises(ProblemInputError, match="problem"):
        solve_contact({"compliance": 1})


def test_at_least_ten_backends_and_ours_first():
    names = available_solvers()
    assert names[0] == "active_set"
    assert len(names) >= 10
