"""The warm analysis' checked fast paths (issue 75, warm75g) give what the general paths give.

Each fast path skips conversions or re-validation of inputs already in the form the
general path would make; the numbers must be the same to the bit (exact equality, no
tolerance: the same arithmetic on the same values), and bad input must still be refused
with the field named (the fast path is only taken where every check passes).
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.compliance.weber import WeberSegments
from contact.errors import ProblemInputError
from contact.qp import ContactProblem
from contact.qp.problem import mean_of
from geometry.core.errors import InputError

STEEL = dict(e1=206000.0, nu1=0.3, e2=206000.0, nu2=0.3)


def _segments(n: int = 7, seed: int = 0):
    rng = np.random.default_rng(seed)
    return (rng.uniform(0.5, 2.0, n), rng.uniform(2.0, 6.0, n), rng.uniform(2.0, 6.0, n),
            rng.uniform(5.0, 40.0, n))


def test_weber_segments_fast_path_equals_the_general_one():
    length, h1, h2, r = _segments()
    fast = WeberSegments.of(length, h1, h2, r_eq=r, **STEEL)
    # lists and an integer modulus take the general (converting) path
    slow = WeberSegments.of(list(length), list(h1), list(h2), r_eq=list(r),
                            e1=206000, nu1=0.3, e2=206000, nu2=0.3)
    for name in ("length", "depth_1", "depth_2", "r_eq", "e_star", "nu1", "nu2", "k1", "k2"):
        assert np.array_equal(getattr(fast, name), getattr(slow, name)), name
    assert fast.length is not length  # copied, as real_array copies
    load = np.linspace(0.0, 3000.0, length.size)
    general = fast.compliance(load, kind=("secant", "tangent"))
    for a, b in zip(fast.secant_tangent(load), general, strict=True):
        assert np.array_equal(a, b)
    # the Weber cap's secant (contact.ltca.weber) by secant_tangent: compliance's, bit for bit
    assert np.array_equal(fast.secant_tangent(load)[0], fast.compliance(load, kind="secant"))


@pytest.mark.parametrize("field", ["length", "depth_1", "depth_2", "r_eq"])
@pytest.mark.parametrize("bad", [0.0, -1.0, np.nan, np.inf])
def test_weber_segments_bad_array_still_named(field, bad):
    length, h1, h2, r = _segments()
    arrays = dict(length=length, depth_1=h1, depth_2=h2, r_eq=r)
    arrays[field] = arrays[field].copy()
    arrays[field][3] = bad
    with pytest.raises(InputError, match=field):
        WeberSegments.of(arrays["length"], arrays["depth_1"], arrays["depth_2"],
                         r_eq=arrays["r_eq"], **STEEL)


def test_weber_segments_bad_material_still_named():
    length, h1, h2, r = _segments()
    with pytest.raises(InputError, match="nu2"):
        WeberSegments.of(length, h1, h2, r_eq=r, e1=206000.0, nu1=0.3, e2=206000.0, nu2=0.7)


def _problem_inputs(n: int = 6, seed: int = 1):
    rng = np.random.default_rng(seed)
    a = rng.standard_normal((n, n))
    C = 1e-6 * (a @ a.T + n * np.eye(n))
    C[0, 1] += 1e-9  # a small asymmetry: symmetrised and reported
    return C, rng.uniform(0.0, 1e-3, n), rng.uniform(50.0, 80.0, n)


def test_contact_problem_fast_path_equals_the_general_one():
    C, s, R = _problem_inputs()
    fast = ContactProblem(C, s, R, 2.0e5)
    slow = ContactProblem(C.tolist(), s.tolist(), R.tolist(), 2.0e5)  # converted
    for name in ("compliance", "separation", "moment_arm", "upper_bound"):
        assert np.array_equal(getattr(fast, name), getattr(slow, name)), name
    assert fast.asymmetry == slow.asymmetry and fast.scale == slow.scale
    assert fast.separation is not s and fast.moment_arm is not R
    assert s.flags.writeable and R.flags.writeable  # the caller's arrays left alone


def test_contact_problem_exactly_symmetric_kept_as_given():
    """An exactly symmetric compliance (the LTCA's every roll) is kept as it is, copied,
    instead of symmetrised (issue 75, studypt80): the problem equals the one the
    symmetrising path makes from it, to the bit, and the caller's matrix stays its own."""
    C, s, R = _problem_inputs()
    sym = 0.5 * (C + C.T)
    assert np.array_equal(sym, sym.T)
    fast = ContactProblem(sym, s, R, 2.0e5)
    # the general path: the same matrix as nested lists (converted, then symmetrised)
    slow = ContactProblem(sym.tolist(), s.tolist(), R.tolist(), 2.0e5)
    for name in ("compliance", "separation", "moment_arm", "upper_bound"):
        assert np.array_equal(getattr(fast, name), getattr(slow, name)), name
    assert np.array_equal(fast.compliance, 0.5 * (sym + sym.T))  # ½(C + Cᵀ) is C
    assert fast.asymmetry == slow.asymmetry == 0.0 and fast.scale == slow.scale
    assert fast.compliance is not sym and sym.flags.writeable
    assert not fast.compliance.flags.writeable
    # a diagonal changed later (Weber's iterations) as from a symmetrised one
    d = np.diagonal(sym) * 1.5
    assert np.array_equal(fast.with_diagonal(d, s).compliance,
                          slow.with_diagonal(d, s).compliance)
    # an asymmetric matrix still takes the symmetrising path and reports its asymmetry
    asym = ContactProblem(C, s, R, 2.0e5)
    assert asym.asymmetry > 0.0 and np.array_equal(asym.compliance, 0.5 * (C + C.T))


@pytest.mark.parametrize("field", ["compliance", "separation", "moment_arm"])
def test_contact_problem_non_finite_still_named(field):
    C, s, R = _problem_inputs()
    arrays = dict(compliance=C, separation=s, moment_arm=R)
    arrays[field] = arrays[field].copy()
    arrays[field].flat[2] = np.nan
    with pytest.raises(ProblemInputError, match=field):
        ContactProblem(arrays["compliance"], arrays["separation"], arrays["moment_arm"], 2.0e5)


@pytest.mark.parametrize("n", [1, 2, 3, 7, 8, 9, 16, 17, 33, 129, 1000])
def test_mean_of_is_numpys_mean(n):
    rng = np.random.default_rng(n)
    for _ in range(50):
        x = rng.random(n) * 10.0 ** rng.uniform(-8, 3)
        assert mean_of(x) == float(np.mean(x))
        m = rng.random((n, n))
        assert mean_of(np.diagonal(m)) == float(np.mean(np.diagonal(m)))  # a strided view


def test_edge_r_eq_memo_gives_edge_r_eq():
    """The memoised R_eq of boundary segments is :func:`edge_r_eq` of the same segments,
    bit for bit, a copy each time (a caller may write into it), and a second set of
    segments is worked out for itself."""
    from pathlib import Path

    from contact.ltca.edges import _edge_r_eq_of, edge_r_eq, flank_boundary
    from contact.utca import EaseOffFields
    from contact.utca.easeoff import ease_off
    from geometry.case import load_case

    case = load_case(Path(__file__).resolve().parents[1] / "cases"
                     / "kolivand2009_fm_11x41.toml")
    eo = ease_off(case)
    bd = flank_boundary(EaseOffFields(eo), 0.5)
    radii = (0.5, 0.8)
    for which in (np.arange(0, bd.kind.size, 3), np.arange(1, bd.kind.size, 4)):
        want = edge_r_eq(case, eo, bd, radii, which)
        first = _edge_r_eq_of(case, eo, bd, radii, which)
        again = _edge_r_eq_of(case, eo, bd, radii, which)
        assert np.array_equal(first, want, equal_nan=True)
        assert np.array_equal(again, want, equal_nan=True)
        assert again is not first and again.flags.writeable
