"""Sainsot's base compliance against an independent plane-strain FE of the gear body,
inside the fit's range and below it (contact.compliance.foundation, module docstring).

The FE (scikit-fem, biquadratic quadrilaterals) is the body Sainsot, Velex & Duverger
(2004) fitted: an annulus r_int = r_f/h_f … r_f fixed at its bore, loaded on the root arc
of half-angle θ_f (width S_f = 2 r_f θ_f) by a uniform tangential traction (the root
section's shear: P*), a uniform radial one (its normal force: P* Q*), each of unit force
per unit face width; the work-conjugate displacement (load vector · solution) times E is
the coefficient (Sainsot's δ_f = F/(E b) × coefficient at u_f = 0). Plane strain, ν 0.3.
The tooth itself is not meshed: its rotation coefficient L* depends on the fillet Sainsot
modelled and is not compared (the FE gives 5.19, the half-plane's 18(1 − ν²)/π = 5.21).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contact.compliance.foundation import SAINSOT_LOG_SLOPE, sainsot_coefficients


def _graded(length: float, first: float, n: int) -> np.ndarray:
    """n intervals over [0, length], the first ``first`` long, growing geometrically."""
    from scipy.optimize import brentq

    if first * n >= length:
        return np.linspace(0.0, length, n + 1)
    q = brentq(lambda q: first * (q**n - 1) / (q - 1) - length, 1.0 + 1e-9, 10.0)
    return np.concatenate([[0.0], np.cumsum(first * q ** np.arange(n))])


def _body_fe(theta: float, h: float) -> tuple[float, float]:
    """(P*, P* Q*) of the annulus by FE (module docstring); r_f = 1, E = 1."""
    from skfem import (
        Basis,
        ElementQuad2,
        ElementVector,
        FacetBasis,
        LinearForm,
        MeshQuad,
        asm,
        condense,
        solve,
    )
    from skfem.helpers import dot
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    r_int, s_f, n_arc = 1.0 / h, 2.0 * theta, 8
    out = theta + _graded(0.98 * math.pi - theta, s_f / n_arc, 48)
    phi = np.concatenate([-out[::-1], np.linspace(-theta, theta, n_arc + 1)[1:-1], out])
    r = 1.0 - _graded(1.0 - r_int, s_f / n_arc, 36)[::-1]
    m = MeshQuad.init_tensor(r, phi)
    m = MeshQuad(np.vstack([m.p[0] * np.cos(m.p[1]), m.p[0] * np.sin(m.p[1])]), m.t)
    e = ElementVector(ElementQuad2())
    lam, mu = lame_parameters(1.0, 0.3)  # plane strain
    k = asm(linear_elasticity(lam, mu), Basis(m, e, intorder=4))
    bore = Basis(m, e).get_dofs(
        m.facets_satisfying(lambda p: np.hypot(p[0], p[1]) < r_int * (1 + 1e-9))).all()
    arc = m.facets_satisfying(lambda p: (np.hypot(p[0], p[1]) > 1 - 0.25 * s_f / n_arc)
                              & (np.abs(np.arctan2(p[1], p[0])) < theta * (1 + 1e-9)))
    fb = FacetBasis(m, e, facets=arc, intorder=6)

    def coefficient(direction: str) -> float:
        @LinearForm
        def load(v, w):
            a = np.arctan2(w.x[1], w.x[0])
            t = (np.array([-np.sin(a), np.cos(a)]) if direction == "tangential"
                 else np.array([np.cos(a), np.sin(a)]))
            return dot(t / s_f, v)

        f = asm(load, fb)
        return float(f @ solve(*condense(k, f, D=bore)))

    return coefficient("tangential"), coefficient("radial")


@pytest.fixture(scope="module")
def fe():
    return {t: _body_fe(t, 2.0) for t in (0.05, 0.012, 0.007)}


def test_the_fe_body_reproduces_the_fit_inside_its_range(fe):
    """At h_f 2, θ_f 0.05 (inside the range): FE P* 2.95, P* Q* 1.59 against the fit's
    3.11 and 1.70 — within 10 % (the fit's own scatter about Sainsot's FE is not published;
    measured 5 % and 7 %; a mesh of 1.8 times the elements gives the same to 0.1 %)."""
    p, pq = fe[0.05]
    c = sainsot_coefficients(2.0, 0.05)
    assert p == pytest.approx(c["P"], rel=0.10)
    assert pq == pytest.approx(c["P"] * c["Q"], rel=0.10)


def test_below_the_range_the_fe_grows_as_the_half_plane_and_the_model_follows(fe):
    """From θ_f 0.012 to 0.007 the FE's P* and P* Q* grow by 2(1 − ν²)/π ln(0.012/0.007) =
    0.312 (within 5 %: Flamant's half-plane, what the model continues with), where the bare
    fit's fall (P* 3.15 → −0.54: indefinite). The model's ratio to the FE stays what it
    is at the bound (P*: 1.20 there, 1.18 at 0.007, within 3 %; P* Q*: 1.31, 1.26, within
    5 %), so below the range it carries the fit's
    own offset, not a new error."""
    growth = SAINSOT_LOG_SLOPE * math.log(0.012 / 0.007)
    for k in (0, 1):
        assert fe[0.007][k] - fe[0.012][k] == pytest.approx(growth, rel=0.05)
    assert sainsot_coefficients(2.0, 0.007, extrapolate=True)["P"] < 0.0
    model = {t: sainsot_coefficients(2.0, t) for t in (0.012, 0.007)}
    ratio = {t: fe[t][0] / model[t]["P"] for t in model}
    assert ratio[0.007] == pytest.approx(ratio[0.012], rel=0.03)
    ratio_pq = {t: fe[t][1] / (model[t]["P"] * model[t]["Q"]) for t in model}
    assert ratio_pq[0.007] == pytest.approx(ratio_pq[0.012], rel=0.05)
