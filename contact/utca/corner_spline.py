"""A bicubic interpolant of grid data that does not ring across a corner (issue 71).

The ease-off's fields were bicubic interpolating splines (``RectBivariateSpline``, s = 0,
not-a-knot ends). Such a spline is global: a kink in the data between two nodes — the
corner where a profile relief starts, the junction of two blade sections — spreads into
its node slopes with a factor of about −(2 − √3) ≈ −0.27 per node, so the spline dips
below flat node data next to the corner (on the FM 16×16 at Σ 60° with a tip relief 15 µm
from 0.9: the relieved flank's ε 30 µrad below the unrelieved one's at u 0.5, v 0.50,
where the nodes are equal; docs/synthesis.md, "The FM 16×16 at Σ 60°'s unloaded TE").

:func:`corner_spline` is the same spline where no grid line is cut and a shape-preserving
one across the cuts it is given. The cuts are the caller's: the ease-off's come from the
design (the relief start lines of the blades and the edge of the generated sheet,
:func:`contact.utca.relief_corners.relief_corners`), never from the data, so that a
measured deviation's own bends (wear, a CMM grid) stay smooth. Each piece of a line
between cuts gets the not-a-knot interpolating spline's node slopes of its own nodes, and
a cut node the harmonic mean of its two pieces' one-sided slopes (zero where they differ
in sign: Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5, 1984, a monotone choice). The
surface is the bicubic Hermite interpolant of the node values, the slopes along u and v
and the cross slopes (the u-slopes of the v-slopes), on every grid cell: C¹, and written
as a tensor-product B-spline with double interior knots (so it evaluates like any
``RectBivariateSpline`` and converts to the compiled kernels' piecewise form).

Where no line is cut the node slopes are the tensor spline's own (its node slopes along u
are the not-a-knot spline of each row's values, and so on), and a bicubic spline is on
each grid cell the Hermite patch of its node values and slopes: the interpolant is the
old spline to round-off (checked in ``tests/test_corner_spline.py``).

Public functions
----------------
node_slopes     node slopes along one axis: the pieces' splines, harmonic at the cuts
corner_spline   the bicubic Hermite interpolant of gridded data with those slopes
corner_splines  the same of several fields on one grid and cuts, at once
"""

from __future__ import annotations

import itertools

import numpy as np
from scipy.interpolate import RectBivariateSpline, make_interp_spline

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["corner_spline", "corner_splines", "node_slopes"]

def _grid(x: np.ndarray, name: str) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    if x.ndim != 1 or x.size < 4 or not np.all(np.diff(x) > 0):
        raise InputError(f"{name}: must be at least 4 strictly increasing nodes, got "
                         f"{x.size if x.ndim == 1 else x.shape}")
    return x


@memoised(maxsize=64)
def _spline_slopes(knots: bytes) -> np.ndarray:
    """(n, n) the node slopes of the not-a-knot interpolating spline of the nodes' bytes,
    as a matrix applied to the values (a piece's nodes are given from its first, so that
    the pieces of a uniform grid share one per length)."""
    x = np.frombuffer(knots, dtype=float)
    k = min(3, x.size - 1)
    out = make_interp_spline(x, np.eye(x.size), k=k).derivative()(x)
    out.flags.writeable = False
    return out


def _piece_slopes(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Node slopes (n, m) of one piece's not-a-knot spline of each column of y (n, m) (a
    quadratic on 3 nodes, the secant on 2)."""
    if x.size == 2:
        s = (y[1] - y[0]) / (x[1] - x[0])
        return np.stack([s, s])
    return _spline_slopes(np.ascontiguousarray(x - x[0]).tobytes()) @ y


def _cuts(cut, shape: tuple[int, int], name: str) -> np.ndarray | None:
    """The cut mask as bool (n, m), None where there is none or it cuts nothing."""
    if cut is None:
        return None
    c = np.asarray(cut)
    if c.shape != shape or c.dtype != bool:
        raise InputError(f"{name}: must be a bool array of shape {shape}, got "
                         f"{c.dtype} {c.shape}")
    return c if c.any() else None


def node_slopes(x, y, cut=None) -> np.ndarray:
    """Node slopes along the first axis: each piece's spline, harmonic at the cuts.

    Parameters
    ----------
    x : array_like (n,) — [x]
        Nodes, strictly increasing, n ≥ 4.
    y : array_like (n, m) — [y]
        Data, one line per column (finite).
    cut : array_like of bool (n, m), optional
        The nodes at which each line is cut (the two nodes of the cell a corner lies in,
        or the node it lies on); the first and last node of a line are its ends anyway.
        None or all False: no line cut.

    Returns
    -------
    ndarray (n, m) — [y/x]
        Lines without a cut: the not-a-knot interpolating spline's node slopes (the
        tensor spline's). Lines with one: cut at each cut node into pieces, each piece's
        own not-a-knot spline's slopes (a quadratic on three nodes, the secant on two),
        and at a cut node the harmonic mean 2 a b / (a + b) of the two pieces' one-sided
        slopes a, b where they share a sign, else 0 (Fritsch & Butland 1984).

    Raises
    ------
    InputError
        Fewer than 4 nodes, nodes not increasing, data not finite, or a cut mask of
        another shape or not bool.

    Notes
    -----
    Source: the module docstring (Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5, 1984).
    """
    x = _grid(x, "x")
    y = np.asarray(y, dtype=float)
    if y.ndim != 2 or y.shape[0] != x.size:
        raise InputError(f"y: must be ({x.size}, m), got {y.shape}")
    if not np.all(np.isfinite(y)):
        raise InputError("y: must be finite (fill masked nodes first)")
    out = _spline_slopes(x.tobytes()) @ y
    cut = _cuts(cut, y.shape, "cut")
    if cut is None:
        return out
    inner = cut.copy()
    inner[[0, -1]] = False  # a line's ends are its ends anyway
    lines = np.flatnonzero(inner.any(axis=0))
    if lines.size == 0:
        return out
    # the lines that share a pattern of cuts at once (a relief's start often cuts many
    # lines at the same nodes)
    patterns, group = np.unique(inner[:, lines].T, axis=0, return_inverse=True)
    for k, pattern in enumerate(patterns):
        cols = lines[np.ravel(group) == k]
        cuts = [0, *np.flatnonzero(pattern), x.size - 1]
        left = np.full((x.size, cols.size), np.nan)  # one-sided slopes, piece to the left
        right = np.full((x.size, cols.size), np.nan)
        for a, b in itertools.pairwise(cuts):
            sl = _piece_slopes(x[a:b + 1], y[a:b + 1][:, cols])
            right[a] = sl[0]
            left[b] = sl[-1]
            out[a + 1:b, cols] = sl[1:-1]
        out[0, cols], out[-1, cols] = right[0], left[-1]
        j = np.array(cuts[1:-1])
        pl, q = left[j], right[j]
        with np.errstate(divide="ignore", invalid="ignore"):
            out[j[:, None], cols] = np.where(pl * q > 0, 2.0 * pl * q / (pl + q), 0.0)
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


def corner_spline(x, y, z, cut_x=None, cut_y=None) -> RectBivariateSpline:
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
    cut_x : array_like of bool (nx, ny), optional
        The nodes at which the lines along x (one per y node) are cut
        (:func:`node_slopes`); None: none.
    cut_y : array_like of bool (nx, ny), optional
        The nodes at which the lines along y (one per x node) are cut; None: none. Both
        None: the interpolating spline itself in this form (on the same knots as the
        others of a grid, so that they convert to one piecewise form).

    Returns
    -------
    scipy.interpolate.RectBivariateSpline
        A bicubic tensor-product B-spline with double interior knots (``tck``,
        ``degrees`` (3, 3), ``ev``, ``__call__`` as any): on each grid cell the Hermite
        patch of the node values, the slopes ∂z/∂x (:func:`node_slopes` along x),
        ∂z/∂y (along y) and ∂²z/∂x∂y (:func:`node_slopes` along x of ∂z/∂y). It
        reproduces the node values; where no line is cut it is
        ``RectBivariateSpline(x, y, z)`` to round-off.

    Raises
    ------
    InputError
        Grids of fewer than 4 nodes or not increasing, z of another shape or not finite,
        cut masks of another shape or not bool.

    Notes
    -----
    Source: the module docstring (bicubic Hermite patches: de Boor, *A Practical Guide to
    Splines*, 1978, ch. XVII; slopes: Fritsch & Butland 1984 at the cuts).
    """
    return corner_splines(x, y, [z], cut_x, cut_y)[0]


def corner_splines(x, y, zs, cut_x=None, cut_y=None) -> list[RectBivariateSpline]:
    """:func:`corner_spline` of several fields on one grid with the same cuts, at once.

    Parameters
    ----------
    x, y, cut_x, cut_y
        As :func:`corner_spline`.
    zs : sequence of K array_like (nx, ny)
        The fields' values (finite).

    Returns
    -------
    list of K scipy.interpolate.RectBivariateSpline
        :func:`corner_spline` of each field (the same arithmetic per field: the lines of
        all fields go through :func:`node_slopes` together).

    Raises
    ------
    InputError
        As :func:`corner_spline`, or no field.

    Notes
    -----
    Source: the module docstring.
    """
    x, y = _grid(x, "x"), _grid(y, "y")
    z = np.asarray(zs, dtype=float)
    if z.ndim != 3 or z.shape[0] == 0 or z.shape[1:] != (x.size, y.size):
        raise InputError(f"z: must be ({x.size}, {y.size}) for each of at least one "
                         f"field, got {z.shape[1:] if z.ndim == 3 else z.shape}")
    k = z.shape[0]
    cut_x = _cuts(cut_x, z.shape[1:], "cut_x")
    cut_y = _cuts(cut_y, z.shape[1:], "cut_y")
    # the fields side by side along the lines' axis: (nx, K ny) and (ny, K nx)
    zx_lines = z.transpose(1, 0, 2).reshape(x.size, -1)
    zx = node_slopes(x, zx_lines, None if cut_x is None else np.tile(cut_x, k))
    zy_lines = z.transpose(2, 0, 1).reshape(y.size, -1)
    zy = node_slopes(y, zy_lines, None if cut_y is None else np.tile(cut_y.T, k))
    zy = zy.reshape(y.size, k, x.size).transpose(2, 1, 0).reshape(x.size, -1)  # (nx, K ny)
    zxy = node_slopes(x, zy, None if cut_x is None else np.tile(cut_x, k))
    tx, ax, bx = _hermite_coefficients(x)
    ty, ay, by = _hermite_coefficients(y)
    out = []
    for i in range(k):
        cols = slice(i * y.size, (i + 1) * y.size)
        c = (ax @ z[i] @ ay.T + bx @ zx[:, cols] @ ay.T + ax @ zy[:, cols] @ by.T
             + bx @ zxy[:, cols] @ by.T)
        out.append(RectBivariateSpline._from_tck((tx, ty, c.ravel(), 3, 3)))
    return out
