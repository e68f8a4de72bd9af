"""Polynomial trial functions of the Rayleigh–Ritz shell model (seed Eq. 3.8–3.9).

The seed writes the trial functions as monomials: ``(x/a)^m`` (pinned–free),
``(x/a)^(m+1)`` (clamped–free) along the tooth height and ``(θ/Θ₀)^(n-1)``
(free–free) along the face width. Monomials of degree ≳ 8 make the Ritz stiffness
matrix ill-conditioned, so this module spans *the same spaces* with Legendre
polynomials in mapped coordinates:

* height: ``ξ^p · P_k(2ξ − 1)``, ``k = 0 … K−1``, ``ξ = x / a`` — spans
  ``{ξ^p, …, ξ^(p+K−1)}`` exactly, so the root condition of order ``p`` holds;
* face width: ``P_n(η)``, ``n = 0 … N−1``, ``η = 2θ/Θ₀ − 1`` — spans
  ``{1, θ, …, θ^(N−1)}``, i.e. the seed's free–free family.

Because the spans are identical, the Ritz solution is the same as with the
seed's monomials in exact arithmetic; only the rounding differs.
"""

from __future__ import annotations

import numpy as np
from numpy.polynomial import legendre as _leg

__all__ = ["face_basis", "height_basis"]


def _legendre_values(t: np.ndarray, count: int, order: int) -> list[np.ndarray]:
    """Values of P_0 … P_{count-1} and their first ``order`` derivatives at ``t``.

    Returns a list (length ``order + 1``) of arrays of shape ``(count, t.size)``.
    """
    eye = np.eye(count)
    out = [_leg.legval(t, eye)]
    coef = eye
    for _ in range(order):
        coef = _leg.legder(coef, axis=0) if coef.shape[0] > 1 else np.zeros((1, count))
        out.append(_leg.legval(t, coef))
    return [np.atleast_2d(v).reshape(count, t.size) for v in out]


def height_basis(xi: np.ndarray, power: int, count: int) -> tuple[np.ndarray, ...]:
    """Height-direction trial functions ``f_k(ξ) = ξ^power · P_k(2ξ − 1)``.

    Parameters
    ----------
    xi : ndarray, shape (Q,) — [1] normalised height ``x / a``
    power : int — [1] order of the root condition (1: value vanishes, 2: value
        and slope vanish)
    count : int — [1] number of functions K

    Returns
    -------
    f, df, ddf : ndarray, shape (K, Q) — [1] the functions and their first and
        second derivatives with respect to ξ
    """
    xi = np.asarray(xi, dtype=float)
    p, dp, ddp = _legendre_values(2.0 * xi - 1.0, count, 2)
    dp = 2.0 * dp  # d/dξ of P(2ξ−1)
    ddp = 4.0 * ddp
    xp = xi**power
    xp1 = power * xi ** (power - 1) if power >= 1 else np.zeros_like(xi)
    xp2 = power * (power - 1) * xi ** (power - 2) if power >= 2 else np.zeros_like(xi)
    f = xp * p
    df = xp1 * p + xp * dp
    ddf = xp2 * p + 2.0 * xp1 * dp + xp * ddp
    return f, df, ddf


def face_basis(eta: np.ndarray, count: int) -> tuple[np.ndarray, ...]:
    """Face-width trial functions ``g_n(η) = P_n(η)`` (free–free).

    Parameters
    ----------
    eta : ndarray, shape (Q,) — [1] mapped face coordinate in [−1, 1]
    count : int — [1] number of functions N

    Returns
    -------
    g, dg, ddg : ndarray, shape (N, Q) — [1] values and first and second
        derivatives with respect to η
    """
    eta = np.asarray(eta, dtype=float)
    g, dg, ddg = _legendre_values(eta, count, 2)
    return g, dg, ddg
