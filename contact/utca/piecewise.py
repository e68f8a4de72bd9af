"""Tensor-product splines in piecewise-polynomial form (issue 32).

The ease-off's fields and the forward map are interpolating bicubic splines
(``scipy.interpolate.RectBivariateSpline``). FITPACK evaluates one at a place by the
de Boor–Cox recurrence of its B-splines, then a 4 × 4 tensor sum; the compiled kernels
(:mod:`contact.utca.isoline_numba`) evaluate them a few hundred thousand times per
analysis, so they take them in piecewise-polynomial form instead: on each cell of the
knot grid [bx[i], bx[i + 1]] × [by[j], by[j + 1]] the spline is the polynomial

    s(x, y) = Σ_p Σ_q P[i, j, p, q] (x − bx[i])^p (y − by[j])^q,

whose coefficients are the B-spline coefficients times each interval's B-splines written
as polynomials (de Boor, *A Practical Guide to Splines*, 1978, ch. VII–X; the same
conversion as ``scipy.interpolate.PPoly.from_spline``, in two variables). A value is then
two interval look-ups and a Horner scheme (~1/3 of the recurrence's cost, measured), and a
partial derivative is the polynomial's derivative, with no separate spline.

It is the same spline: the conversion's round-off is a few units in the last place of the
spline's scale (``tests/test_isoline_kernels.py`` checks 1e-13 against FITPACK, inside
the knots, on them and beyond). Places beyond the knots are clamped to their range, as
FITPACK does, and a place on an interior knot takes the cell to its right (FITPACK's
interval choice).

Public functions
----------------
PiecewiseSpline  breakpoints and per-cell coefficients of K splines on the same knots
piece_basis      a knot vector's B-splines as polynomials on each knot interval
from_splines     RectBivariateSplines on the same knots in piecewise-polynomial form
derivative       a partial derivative of a piecewise-polynomial spline
"""

from __future__ import annotations

import math
from types import ModuleType
from typing import NamedTuple

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from scipy.interpolate import BSpline

from geometry.core.caches import memoised

__all__ = ["PiecewiseSpline", "derivative", "from_splines", "piece_basis"]


class PiecewiseSpline(NamedTuple):
    """K tensor-product splines on the same knots, in piecewise-polynomial form.

    Attributes
    ----------
    bx : ndarray (nx + 1,)
        Breakpoints along x (the distinct knots of the interior and the two ends).
    by : ndarray (ny + 1,)
        Breakpoints along y.
    coefficients : ndarray (nx, ny, K, kx + 1, ky + 1), C-contiguous
        ``[i, j, s, p, q]``: spline s's coefficient of (x − bx[i])^p (y − by[j])^q on cell
        (i, j), in the splines' units per unit of x^p y^q.
    """

    bx: np.ndarray
    by: np.ndarray
    coefficients: np.ndarray


def piece_basis(t: np.ndarray, k: int = 3) -> np.ndarray:
    """The B-splines of a knot vector as polynomials on each knot interval.

    Parameters
    ----------
    t : ndarray (n + k + 1,)
        Knots (non-decreasing).
    k : int
        Degree.

    Returns
    -------
    ndarray (n − k, k + 1, k + 1), read-only
        ``[i, a, p]``: the coefficient of s^p, s = x − t[k + i], of the B-spline B_{i+a},
        one of the k + 1 that are nonzero on the interval [t[k + i], t[k + i + 1]] (their
        right-hand derivatives at its left knot over p!; de Boor 1978). Memoised per
        process by the knots (a study's ease-offs share their grid's).
    """
    t = np.asarray(t, dtype=float)
    return _piece_basis(t.tobytes(), int(k))


@memoised(maxsize=64)
def _piece_basis(knots: bytes, k: int) -> np.ndarray:
    """:func:`piece_basis` of the knots' bytes."""
    t = np.frombuffer(knots, dtype=float)
    n = len(t) - k - 1
    left = t[k:n]  # the intervals' left knots (n - k intervals)
    basis = BSpline(t, np.eye(n), k)
    rows = np.arange(left.size)
    out = np.empty((left.size, k + 1, k + 1))
    fact = 1.0
    for p in range(k + 1):
        fact *= max(p, 1)
        d = basis(left, nu=p)  # (n_int, n): the right-hand derivatives at the left knots
        for a in range(k + 1):
            out[:, a, p] = d[rows, rows + a] / fact
    out.flags.writeable = False
    return out


def _breakpoints(t: np.ndarray, k: int, name: str) -> tuple[np.ndarray, np.ndarray]:
    """The distinct knots t[k] … t[n] that bound the intervals, and which of the knot
    intervals have a length (a knot of multiplicity m opens m − 1 empty ones)."""
    b = np.asarray(t[k:len(t) - k], dtype=float)
    step = np.diff(b)
    if b.size < 2 or np.any(step < 0) or not np.any(step > 0):
        raise ValueError(f"splines: the {name}-knots between the end knots must be "
                         "non-decreasing and span an interval")
    full = step > 0
    return np.concatenate([b[:1], b[1:][full]]), full


def from_splines(splines: list, kernels: ModuleType | None = None) -> PiecewiseSpline:
    """Splines on the same knots in piecewise-polynomial form.

    Parameters
    ----------
    splines : list of K scipy.interpolate.RectBivariateSpline
        Splines with the same knots and degrees (e.g. interpolating splines on one grid,
        or :func:`contact.utca.corner_spline.corner_spline`'s, whose interior knots are
        double: their empty knot intervals are left out).
    kernels : module, optional
        :mod:`contact.utca.isoline_numba` to form the coefficients in its compiled loop
        (:func:`~contact.utca.isoline_numba.pieces`: the same sums, without NumPy's
        per-call overhead on these small arrays), or None (NumPy).

    Returns
    -------
    PiecewiseSpline
        The K splines' breakpoints and per-cell coefficients (:class:`PiecewiseSpline`).

    Raises
    ------
    ValueError
        No splines, splines on different knots or degrees, or knots that decrease.
    """
    if not splines:
        raise ValueError("splines: must hold at least one spline, got none")
    tx, ty, _ = splines[0].tck
    kx, ky = splines[0].degrees
    for s in splines[1:]:
        if (s.degrees != (kx, ky) or not np.array_equal(s.tck[0], tx)
                or not np.array_equal(s.tck[1], ty)):
            raise ValueError("splines: must all have the same knots and degrees")
    (bx, full_x), (by, full_y) = _breakpoints(tx, kx, "x"), _breakpoints(ty, ky, "y")
    nx, ny = len(tx) - kx - 1, len(ty) - ky - 1
    c = np.stack([np.asarray(s.tck[2], dtype=float).reshape(nx, ny) for s in splines])
    basis_x, basis_y = piece_basis(tx, kx), piece_basis(ty, ky)  # (ncx, kx+1, kx+1), …
    if kernels is not None:
        coef = kernels.pieces(c, basis_x, basis_y)
    else:
        # along x, then along y: Σ_a Σ_b Bx[i, a, p] c[s, i + a, j + b] By[j, b, q], the
        # (kx + 1) × (ky + 1) coefficients that act on each cell as sliding windows
        along_x = np.matmul(sliding_window_view(c, kx + 1, axis=1), basis_x[None])
        coef = np.matmul(sliding_window_view(along_x, ky + 1, axis=2), basis_y[None, None])
        coef = coef.transpose(1, 2, 0, 3, 4)  # (ncx, ncy, K, kx + 1, ky + 1)
    if not (full_x.all() and full_y.all()):  # repeated knots: their empty intervals out
        coef = coef[full_x][:, full_y]
    return PiecewiseSpline(bx, by, np.ascontiguousarray(coef))


def derivative(pp: PiecewiseSpline, nux: int, nuy: int) -> PiecewiseSpline:
    """The partial derivative ∂^(nux+nuy) s/∂x^nux ∂y^nuy of piecewise-polynomial splines.

    Parameters
    ----------
    pp : PiecewiseSpline
        Splines of degrees (kx, ky) (the shape of their coefficients).
    nux, nuy : int
        Orders of the derivative, 0 ≤ nux ≤ kx, 0 ≤ nuy ≤ ky.

    Returns
    -------
    PiecewiseSpline
        The derivatives on the same cells, of degrees (kx − nux, ky − nuy): each term's
        coefficient times p!/(p − nux)! · q!/(q − nuy)!.

    Raises
    ------
    ValueError
        An order outside [0, degree].
    """
    coef = pp.coefficients
    kx, ky = coef.shape[-2] - 1, coef.shape[-1] - 1
    if not (0 <= nux <= kx and 0 <= nuy <= ky):
        raise ValueError(f"nux, nuy: must lie in [0, {kx}] and [0, {ky}], got {nux}, {nuy}")
    if nux == nuy == 0:
        return pp
    fx = [math.perm(p + nux, nux) for p in range(kx + 1 - nux)]  # (p + nux)! / p!
    fy = [math.perm(q + nuy, nuy) for q in range(ky + 1 - nuy)]
    out = coef[..., nux:, nuy:] * np.multiply.outer(fx, fy)
    return PiecewiseSpline(pp.bx, pp.by, np.ascontiguousarray(out))
