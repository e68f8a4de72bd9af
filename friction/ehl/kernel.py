"""Elastic deflection of a line contact: the half-space kernel and its DC-FFT convolution.

Combined normal surface displacement of two elastic half-planes under a pressure p(x)
per unit length (plane strain), with E′ = 2E* (the toolkit's convention,
:mod:`friction.film`):

    v(x) = −(4/(π E′)) ∫ p(s) ln|x − s| ds   (+ a constant absorbed in the rigid approach)

In the solver's dimensionless variables (X = x/b, P = p/p_h, H = hR/b², with b and p_h of
Hertz) this is V(X) = −(1/π) ∫ P(S) ln|X − S| dS. For P piecewise constant over elements
of width Δ centred on the nodes, the influence coefficient of element j at node i depends
on i − j only (a Toeplitz matrix), so the deflection of N nodes is a linear convolution,
evaluated by zero-padded FFT without wrap-around error (DC-FFT).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.fft
from numpy.typing import NDArray

__all__ = ["ElasticKernel", "influence_coefficients"]

Array = NDArray[np.float64]


def influence_coefficients(n: int, spacing: float) -> Array:
    """Dimensionless influence coefficients D_k for offsets k = −(n−1) … n−1.

    Parameters
    ----------
    n : int
        Number of nodes (≥ 2).
    spacing : float — [1]
        Node spacing Δ in units of the Hertz half-width.

    Returns
    -------
    array (2n − 1,) — [1]
        D_k = −(1/π)[a ln|a| − c ln|c| − Δ], a = kΔ + Δ/2, c = kΔ − Δ/2, the deflection at a
        node k spacings from a unit-pressure element (entry n − 1 + k).

    Notes
    -----
    Source: integral of the half-plane Green function ln|x − s| over a uniform strip
    (Johnson, *Contact Mechanics*, 1985, Eq. 2.25 and §2.8); the same coefficients as
    Hamrock & Jacobson, ASLE Trans. 27 (1984) 275 for line contacts.
    """
    k = np.arange(-(n - 1), n, dtype=float)
    a = k * spacing + 0.5 * spacing
    c = k * spacing - 0.5 * spacing

    def xlogx(t: Array) -> Array:
        at = np.abs(t)
        return np.where(at > 0.0, t * np.log(np.where(at > 0.0, at, 1.0)), 0.0)

    return -(xlogx(a) - xlogx(c) - spacing) / math.pi


class ElasticKernel:
    """Line-contact deflection of N equally spaced nodes by DC-FFT.

    Parameters
    ----------
    n : int
        Number of nodes.
    spacing : float — [1]
        Dimensionless node spacing Δ.

    Notes
    -----
    Source: Liu, S., Wang, Q., Liu, G., "A versatile method of discrete convolution and
    FFT (DC-FFT) for contact analyses", Wear 243 (2000) 101–111: the kernel of 2N − 1
    offsets is wrapped into a period of length 2N (the zero-padded pressure makes the
    circular convolution equal to the linear one on the first N outputs).
    """

    def __init__(self, n: int, spacing: float) -> None:
        self.n = n
        self.spacing = spacing
        self.coefficients = influence_coefficients(n, spacing)
        m = 2 * n
        wrapped = np.zeros(m)
        wrapped[:n] = self.coefficients[n - 1:]          # offsets 0 … n−1
        wrapped[n + 1:] = self.coefficients[: n - 1]     # offsets −(n−1) … −1
        self._spectrum = scipy.fft.rfft(wrapped)
        self._m = m
        self._matrix: Array | None = None

    def deflection(self, pressure: Array) -> Array:
        """V_i = Σ_j D_(i−j) P_j for one pressure vector (n,) [1] → (n,) [1]."""
        spec = scipy.fft.rfft(pressure, n=self._m)
        return scipy.fft.irfft(spec * self._spectrum, n=self._m)[: self.n]

    def matrix(self) -> Array:
        """The dense Toeplitz matrix D (n, n) [1] of the same coefficients (for Newton).

        Formed once per kernel and shared (read-only): callers must not modify it.
        """
        if self._matrix is None:
            n = self.n
            idx = np.arange(n)
            self._matrix = self.coefficients[(idx[:, None] - idx[None, :]) + n - 1]
            self._matrix.flags.writeable = False
        return self._matrix
