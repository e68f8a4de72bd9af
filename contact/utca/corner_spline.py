"""A bicubic interpolant of grid data that does not ring across a corner (issue 71).

The ease-off's fields were bicubic interpolating splines (``RectBivariateSpline``, s = 0,
not-a-knot ends). Such a spline is global: a kink in the data between two nodes — the
corner where a profile relief starts, the junction of two blade sections — spreads into
its node slopes with a factor of about −(2 − √3) ≈ −0.27 per node, so the spline dips
below flat node data next to the corner (on the FM 16×16 at Σ 60° with a tip relief 15 µm
from 0.9: the relieved flank's ε 30 µrad below the unrelieved one's at u 0.5, v 0.50,
where the nodes are equal; docs/synthesis.md, "The FM 16×16 at Σ 60°'s unloaded TE").

:func:`corner_spline` is the same spline where the data are smooth and a shape-preserving
one across a corner. Each grid line is cut at the nodes where the data bend much more
sharply than two nodes to either side (:func:`corner_nodes`); each piece between cuts
gets the not-a-knot interpolating spline's node slopes of its own nodes, and a cut node
the harmonic mean of its two pieces' one-sided slopes (zero where they differ in sign:
Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5, 1984, a monotone choice). The surface is
the bicubic Hermite interpolant of the node values, the slopes along u and v and the
cross slopes (the u-slopes of the v-slopes), on every grid cell: C¹, and written as a
tensor-product B-spline with double interior knots (so it evaluates like any
``RectBivariateSpline`` and converts to the compiled kernels' piecewise form).

Where no line has a cut the node slopes are the tensor spline's own (its node slopes
along u are the not-a-knot spline of each row's values, and so on), and a bicubic spline
is on each grid cell the Hermite patch of its node values and slopes: the interpolant is
the old spline to round-off (checked in ``tests/test_corner_spline.py``).

Public functions
----------------
corner_nodes    the nodes of grid lines where the data bend sharply (a corner)
node_slopes     node slopes along one axis: the pieces' splines, harmonic at the cuts
corner_spline   the bicubic Hermite interpolant of gridded data with those slopes
"""

from __future__ import annotations

import itertools

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from scipy.interpolate import RectBivariateSpline, make_interp_spline

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["CORNER_RATIO", "CORNER_WINDOW", "corner_nodes", "corner_spline", "node_slopes"]

#: a node is a corner where the change of the secant slope there exceeds this many times
#: the median change at the interior nodes within :data:`CORNER_WINDOW` on either side of
#: it (a smooth f: about h f'' at each, the ratio near 1; a kink: the kink's slope change
#: over h f'', hundreds on the 16×16's relief)
CORNER_RATIO = 4.0
#: nodes to either side whose slope changes form a node's background (a median of up to 4
#: each side: a second corner in it, as a relief's start two nodes from a filled node's,
#: still leaves it smooth)
CORNER_WINDOW = 4


def _grid(x: np.ndarray, name: str) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    if x.ndim != 1 or x.size < 4 or not np.all(np.diff(x) > 0):
        raise InputError(f"{name}: must be at least 4 strictly increasing nodes, got "
                         f"{x.size if x.ndim == 1 else x.shape}")
    return x


def corner_nodes(x, y, ratio: float = CORNER_RATIO) -> np.ndarray:
    """The nodes of grid lines where the data bend sharply.

    Parameters
    ----------
    x : array_like (n,) — any unit
        Nodes of the lines, strictly increasing, n ≥ 4.
    y : array_like (n, m)
        Data, one line per column (finite).
    ratio : float
        :data:`CORNER_RATIO`.

    Returns
    -------
    ndarray of bool (n, m)
        Interior node j of line l where the change of the secant slope |D_j| = |δ_j −
        δ_{j−1}| exceeds ``ratio`` times the median |D| of the interior nodes within
        :data:`CORNER_WINDOW` before j and ``ratio`` times that of those after it (each
        side at least one node: the first and last two nodes are none), and 1e-9 of the
        line's largest |δ| (round-off): the two nodes of the cell a kink lies in, or the
        node it lies on. Corners found leave the medians and the search is repeated until
        it finds no more (two kinks a node or two apart, as a relief's start next to the
        fill's constant continuation, each hide the other from a median otherwise). A
        smooth line (D_j about h f'') has none, nor one whose bending grows steadily
        towards an end (a gap curvature rising towards a fold: D_j below the median of
        the side it grows to).

    Notes
    -----
    Source: this module (an ENO-like smoothness indicator on second differences; Harten
    et al., J. Comput. Phys. 71, 1987).
    """
    x = _grid(x, "x")
    y = np.asarray(y, dtype=float)
    n = x.size
    delta = np.diff(y, axis=0) / np.diff(x)[:, None]
    d = np.full(y.shape, np.nan)
    d[1:-1] = np.abs(np.diff(delta, axis=0))
    # a slope change at round-off of the line's slopes is no corner (straight data)
    floor = 1e-9 * np.max(np.abs(delta), axis=0)
    w = CORNER_WINDOW
    inner = np.zeros(n, dtype=bool)
    inner[2:n - 2] = True  # a side of at least one interior node each
    out = np.zeros(y.shape, dtype=bool)
    for _ in range(n):  # corners found leave the background until no more are found
        padded = np.full((n + 2 * w, y.shape[1]), np.nan)
        padded[w:w + n] = np.where(out, np.nan, d)  # d is NaN on the end nodes
        windows = sliding_window_view(padded, w, axis=0)  # (n + w + 1, m, w)
        left = _nanmedian(windows[:n])  # nodes j − w … j − 1
        right = _nanmedian(windows[w + 1:w + 1 + n])  # nodes j + 1 … j + w
        with np.errstate(invalid="ignore"):  # a side all corners: NaN, no corner
            found = ((d > ratio * left) & (d > ratio * right) & (d > floor)
                     & inner[:, None])
        if not (found & ~out).any():
            break
        out |= found
    return out


def _nanmedian(b: np.ndarray) -> np.ndarray:
    """The median over the last axis of b's finite entries (NaN where none)."""
    ok = np.isfinite(b)
    srt = np.sort(np.where(ok, b, np.inf), axis=-1)
    k = ok.sum(axis=-1)
    lo = np.take_along_axis(srt, np.maximum((k - 1) // 2, 0)[..., None], axis=-1)[..., 0]
    hi = np.take_along_axis(srt, np.maximum(k // 2, 0)[..., None], axis=-1)[..., 0]
    return np.where(k > 0, 0.5 * (lo + hi), np.nan)


@memoised(maxsize=16)
def _spline_slopes(knots: bytes) -> np.ndarray:
    """(n, n) the node slopes of the not-a-knot interpolating spline of the nodes' bytes,
    as a matrix applied to the values."""
    x = np.frombuffer(knots, dtype=float)
    k = min(3, x.size - 1)
    out = make_interp_spline(x, np.eye(x.size), k=k).derivative()(x)
    out.flags.writeable = False
    return out


def _piece_slopes(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Node slopes of one piece's not-a-knot spline (a quadratic on 3 nodes, the secant
    on 2)."""
    if x.size == 2:
        s = (y[1] - y[0]) / (x[1] - x[0])
        return np.array([s, s])
    return _spline_slopes(np.ascontiguousarray(x).tobytes()) @ y


def node_slopes(x, y, ratio: float = CORNER_RATIO, corners: bool = True) -> np.ndarray:
    """Node slopes along the first axis: each piece's spline, harmonic at the cuts.

    Parameters
    ----------
    x : array_like (n,) — [x]
        Nodes, strictly increasing, n ≥ 4.
    y : array_like (n, m) — [y]
        Data, one line per column (finite).
    ratio : float
        :func:`corner_nodes`'s ratio.
    corners : bool
        False: every line's not-a-knot spline slopes (no line cut).

    Returns
    -------
    ndarray (n, m) — [y/x]
        Lines without a corner node: the not-a-knot interpolating spline's node slopes
        (the tensor spline's). Lines with one: cut at each corner node into pieces, each
        piece's own not-a-knot spline's slopes (a quadratic on three nodes, the secant on
        two), and at a cut node the harmonic mean 2 a b / (a + b) of the two pieces'
        one-sided slopes a, b where they share a sign, else 0 (Fritsch & Butland 1984).

    Raises
    ------
    InputError
        Fewer than 4 nodes, nodes not increasing, or data not finite.
    """
    x = _grid(x, "x")
    y = np.asarray(y, dtype=float)
    if y.ndim != 2 or y.shape[0] != x.size:
        raise InputError(f"y: must be ({x.size}, m), got {y.shape}")
    if not np.all(np.isfinite(y)):
        raise InputError("y: must be finite (fill masked nodes first)")
    out = _spline_slopes(x.tobytes()) @ y
    if not corners:
        return out
    cut = corner_nodes(x, y, ratio)
    for line in np.flatnonzero(cut.any(axis=0)):
        cuts = [0, *np.flatnonzero(cut[:, line]), x.size - 1]
        left = np.full(x.size, np.nan)  # one-sided slopes from the piece to the left
        right = np.full(x.size, np.nan)
        for a, b in itertools.pairwise(cuts):
            s = _piece_slopes(x[a:b + 1], y[a:b + 1, line])
            right[a] = s[0]
            left[b] = s[-1]
            out[a + 1:b, line] = s[1:-1]
        out[0, line], out[-1, line] = right[0], left[-1]
        for j in cuts[1:-1]:
            p, q = left[j], right[j]
            out[j, line] = 2.0 * p * q / (p + q) if p * q > 0 else 0.0
    return out


def _hermite_coefficients(x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Knots (2n + 4,) of a C¹ cubic with double interior knots and the matrices A, B
    (2n, n) of its B-spline coefficients c = A f + B f' from node values and slopes (the
    Bézier points of each cell: f_i, f_i + h f'_i / 3, f_{i+1} − h f'_{i+1} / 3)."""
    n = x.size
    h = np.diff(x)
    knots = np.concatenate([[x[0]] * 4, np.repeat(x[1:-1], 2), [x[-1]] * 4])
    a = np.zeros((2 * n, n))
    b = np.zeros((2 * n, n))
    a[0, 0] = a[-1, -1] = 1.0
    i = np.arange(n - 1)
    a[2 * i + 1, i] = 1.0
    b[2 * i + 1, i] = h / 3.0
    a[2 * i + 2, i + 1] = 1.0
    b[2 * i + 2, i + 1] = -h / 3.0
    return knots, a, b


def corner_spline(x, y, z, ratio: float = CORNER_RATIO,
                  corners: bool = True) -> RectBivariateSpline:
    """The bicubic Hermite interpolant of gridded data whose node slopes do not ring
    across a corner.

    Parameters
    ----------
    x : array_like (nx,) — [x]
        First-axis nodes (the ease-off's lengthwise fractions u), strictly increasing,
        nx ≥ 4.
    y : array_like (ny,) — [y]
        Second-axis nodes (profile fractions v), strictly increasing, ny ≥ 4.
    z : array_like (nx, ny)
        Values (finite; fill masked nodes first).
    ratio : float
        :func:`corner_nodes`'s ratio.
    corners : bool
        False: no line cut, the interpolating spline itself in this form (on the same
        knots as the others of a grid, so that they convert to one piecewise form).

    Returns
    -------
    scipy.interpolate.RectBivariateSpline
        A bicubic tensor-product B-spline with double interior knots (``tck``,
        ``degrees`` (3, 3), ``ev``, ``__call__`` as any): on each grid cell the Hermite
        patch of the node values, the slopes ∂z/∂x (:func:`node_slopes` along x),
        ∂z/∂y (along y) and ∂²z/∂x∂y (:func:`node_slopes` along x of ∂z/∂y). It
        reproduces the node values; where no line has a corner it is
        ``RectBivariateSpline(x, y, z)`` to round-off.

    Raises
    ------
    InputError
        Grids of fewer than 4 nodes or not increasing, z of another shape or not finite.

    Notes
    -----
    Source: the module docstring (bicubic Hermite patches: de Boor, *A Practical Guide to
    Splines*, 1978, ch. XVII; slopes: Fritsch & Butland 1984 at the cuts).
    """
    x, y = _grid(x, "x"), _grid(y, "y")
    z = np.asarray(z, dtype=float)
    if z.shape != (x.size, y.size):
        raise InputError(f"z: must be ({x.size}, {y.size}), got {z.shape}")
    zx = node_slopes(x, z, ratio, corners)
    zy = node_slopes(y, z.T, ratio, corners).T
    zxy = node_slopes(x, zy, ratio, corners)
    tx, ax, bx = _hermite_coefficients(x)
    ty, ay, by = _hermite_coefficients(y)
    c = ax @ z @ ay.T + bx @ zx @ ay.T + ax @ zy @ by.T + bx @ zxy @ by.T
    return RectBivariateSpline._from_tck((tx, ty, c.ravel(), 3, 3))
