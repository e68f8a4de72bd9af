"""Compiled kernels of the iso-line searches on the ease-off splines (numba; issue 32).

The contact curves' searches (:mod:`contact.utca.contact_curves`) iterate Newton's method
and false position on a few hundred places at a time, so in NumPy most of their time is
the interpreter's, not the arithmetic's. These kernels run the same iterations point by
point in compiled loops, with **the same floating-point operations in the same order** as
the NumPy path of :class:`contact.utca.fields.EaseOffFields` (which stays the reference):

- the bicubic spline's value is FITPACK's ``fpbisp``/``fpbspl`` (Dierckx, *Curve and
  Surface Fitting with Splines*, 1993, §2.1: de Boor–Cox recurrence, then the tensor
  sum in FITPACK's order), which ``scipy.interpolate.RectBivariateSpline.ev`` calls point
  by point (``bispeu``); a partial derivative is the spline of ``pardeu``'s differenced
  coefficients (:func:`derivative_spline`, computed once instead of on every call);
- Newton's method on v*(u) (:meth:`EaseOffFields.newton_v`), the inside measure
  (:meth:`EaseOffFields.measure`), the ends' false position
  (:func:`contact.utca.contact_curves._false_position_ends`) and the columns' Newton
  steps (:meth:`EaseOffFields.solve_columns`) repeat their NumPy statements per point;
- the whole evaluation of a batch of iso-lines after the column solves
  (:func:`contact.utca.contact_curves._seed_places`: the coarse samples' largest inside
  runs, :func:`coarse_runs`; the ends, the samples, ε and the lowest point,
  :func:`seed_places`), so a transition search's call on 4 rolls is no longer mostly the
  interpreter's; the short curves' grid search stays in NumPy (it runs where a curve lies
  between two coarse samples, calling the kernels above);
- several fields at the same places (:meth:`EaseOffFields.values`: the flank's points
  and normals, Q, ε, the normal arm) share each point's basis (:func:`ev_many`), as all
  the fields' splines are on the grid's knots.

The two paths agree to the last bit on this machine (``tests/test_isoline_kernels.py``);
numba does not contract ``a * b + c`` into fused multiply-adds or reassociate sums unless
asked (``fastmath`` is off), so the agreement does not depend on the CPU.

This module imports numba; :mod:`contact.utca.fields` imports it only where numba is
installed (the ``fast`` extra) and the environment variable ``LTCA_KERNELS`` is not
``numpy``. The first call compiles the kernels (a few seconds), which numba caches on
disk (``NUMBA_CACHE_DIR``, or beside this file).
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = [
    "coarse_runs",
    "derivative_spline",
    "ev",
    "ev_many",
    "false_position_ends",
    "measure",
    "newton_v",
    "seed_places",
    "solve_columns",
]

_jit = numba.njit(cache=True, nogil=True)


def derivative_spline(tck: tuple, degrees: tuple[int, int], nux: int, nuy: int) -> tuple:
    """The partial derivative ∂^(nux+nuy) s/∂x^nux ∂y^nuy of a bivariate spline, as a
    spline of degrees (kx − nux, ky − nuy): FITPACK ``pardeu``'s coefficient arithmetic
    (Dierckx 1993, §2.1, eq. 2.14), ``((c[i+1] − c[i]) · k) / (t[i+k+1] − t[i+1])`` in its
    order.

    Parameters
    ----------
    tck : (tx, ty, c)
        Knots and flat coefficients of ``RectBivariateSpline.tck``.
    degrees : (int, int)
        (kx, ky).
    nux, nuy : int
        Orders of the derivative, 0 ≤ nux < kx, 0 ≤ nuy < ky.

    Returns
    -------
    (tx', ty', c', kx', ky') : the derivative's knots, flat coefficients and degrees.

    Raises
    ------
    ValueError
        An order outside [0, degree).
    """
    tx, ty, c = (np.asarray(a, dtype=float) for a in tck[:3])
    kx, ky = degrees
    if not (0 <= nux < kx and 0 <= nuy < ky):
        raise ValueError(f"nux, nuy: must lie in [0, {kx}) and [0, {ky}), got {nux}, {nuy}")
    w = c.reshape(tx.size - kx - 1, ty.size - ky - 1).copy()
    # along x on the rows, then along y on the columns (a view: in place); pardeu
    # differences only the rows it keeps along y, and each row's arithmetic is its own
    nxx, kkx = _difference(w, tx, kx, nux)
    nyy, kky = _difference(w.T, ty, ky, nuy)
    return (np.ascontiguousarray(tx[nux:tx.size - nux]),
            np.ascontiguousarray(ty[nuy:ty.size - nuy]),
            np.ascontiguousarray(w[:nxx, :nyy]).ravel(), kkx, kky)


def _difference(w: np.ndarray, t: np.ndarray, k: int, nu: int) -> tuple[int, int]:
    """``pardeu``'s ``nu`` differencing passes of the coefficient rows of ``w`` (in
    place) for knots ``t`` and degree ``k``; returns the rows left and their degree."""
    n = w.shape[0]
    for j in range(nu):
        ak = float(k)
        n -= 1
        for i in range(n):
            fac = t[i + 1 + j + k] - t[i + 1 + j]
            if fac > 0.0:
                w[i] = (w[i + 1] - w[i]) * ak / fac
        k -= 1
    return n, k


@_jit
def _basis(t, k, x, h, hh):
    """FITPACK ``fpbspl``: the k + 1 B-splines nonzero at x, clamped into the knots'
    range, into h; returns the knot interval l (t[l] ≤ x < t[l + 1], 0-based)."""
    nk1 = t.size - k - 1
    if x < t[k]:
        x = t[k]
    if x > t[nk1]:
        x = t[nk1]
    # the least l in [k, nk1 − 1] with x < t[l + 1]: fpbisp's linear search, bisected
    lo, hi = k, nk1 - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if x < t[mid + 1]:
            hi = mid
        else:
            lo = mid + 1
    if k == 3:
        _deboor3(t, lo, x, h)
        return lo
    if k == 2:
        _deboor2(t, lo, x, h)
        return lo
    h[0] = 1.0
    for j in range(1, k + 1):
        for i in range(j):
            hh[i] = h[i]
        h[0] = 0.0
        for i in range(1, j + 1):
            li = lo + i
            lj = li - j
            if t[li] == t[lj]:
                h[i] = 0.0
                continue
            f = hh[i - 1] / (t[li] - t[lj])
            h[i - 1] = h[i - 1] + f * (t[li] - x)
            h[i] = f * (x - t[lj])
    return lo


@_jit
def _step(t, li, lj, x, g, lower):
    """One term of the recurrence (``fpbspl``'s inner loop): the B-spline values (h[i − 1],
    h[i]) from h[i − 1] = ``lower`` and hh[i − 1] = ``g`` on the knots t[lj] < t[li]."""
    a = t[li]
    b = t[lj]
    if a == b:
        return lower, 0.0
    f = g / (a - b)
    return lower + f * (a - x), f * (x - b)


@_jit
def _deboor2(t, lo, x, h):
    """The recurrence of :func:`_basis` for k = 2, unrolled into scalars (the same
    operations in the same order: ~2× faster than the loops over small arrays)."""
    h0, h1 = _step(t, lo + 1, lo, x, 1.0, 0.0)
    g0, g1 = h0, h1
    h0, h1 = _step(t, lo + 1, lo - 1, x, g0, 0.0)
    h1, h2 = _step(t, lo + 2, lo, x, g1, h1)
    h[0] = h0
    h[1] = h1
    h[2] = h2


@_jit
def _deboor3(t, lo, x, h):
    """The recurrence of :func:`_basis` for k = 3, unrolled into scalars (as
    :func:`_deboor2`)."""
    h0, h1 = _step(t, lo + 1, lo, x, 1.0, 0.0)
    g0, g1 = h0, h1
    h0, h1 = _step(t, lo + 1, lo - 1, x, g0, 0.0)
    h1, h2 = _step(t, lo + 2, lo, x, g1, h1)
    g0, g1, g2 = h0, h1, h2
    h0, h1 = _step(t, lo + 1, lo - 2, x, g0, 0.0)
    h1, h2 = _step(t, lo + 2, lo - 1, x, g1, h1)
    h2, h3 = _step(t, lo + 3, lo, x, g2, h2)
    h[0] = h0
    h[1] = h1
    h[2] = h2
    h[3] = h3


@_jit
def _value(tx, ty, c, kx, ky, x, y, hx, hy, hh):
    """FITPACK ``fpbisp`` at one point (work arrays hx (kx + 1), hy (ky + 1), hh)."""
    lx = _basis(tx, kx, x, hx, hh)
    return _value_at(ty, c, kx, ky, lx, hx, y, hy, hh)


@_jit
def _value_at(ty, c, kx, ky, lx, hx, y, hy, hh):
    """:func:`_value` with the x-basis given (its interval lx and values hx): splines on
    the same x-knots at the same x share it (the same numbers as computing it again)."""
    ly = _basis(ty, ky, y, hy, hh)
    return _tensor_sum(c, 0, kx, ky, lx, ly, ty.size - ky - 1, hx, hy)


@_jit
def _tensor_sum(c, base, kx, ky, lx, ly, nky1, hx, hy):
    """FITPACK's sum Σᵢ Σⱼ c[base + (lx − kx + i)·nky1 + ly − ky + j] hx[i] hy[j], in its
    order, for flat coefficients (a spline's from ``base``) and the bases (intervals lx,
    ly; values hx, hy)."""
    l1 = base + (lx - kx) * nky1 + (ly - ky)
    sp = 0.0
    for i1 in range(kx + 1):
        l2 = l1
        for j1 in range(ky + 1):
            sp = sp + c[l2] * hx[i1] * hy[j1]
            l2 += 1
        l1 += nky1
    return sp


@_jit
def ev(tx, ty, c, kx, ky, x, y):
    """Spline values at the points (x[i], y[i]) (M,): ``RectBivariateSpline.ev``."""
    out = np.empty(x.size)
    hx = np.empty(kx + 1)
    hy = np.empty(ky + 1)
    hh = np.empty(max(kx, ky) + 1)
    for p in range(x.size):
        out[p] = _value(tx, ty, c, kx, ky, x[p], y[p], hx, hy, hh)
    return out


@_jit
def ev_many(tx, ty, c, kx, ky, x, y):
    """Values (M, K) of K splines on the same knots at the points (x[i], y[i]) (M,):
    ``RectBivariateSpline.ev`` of each (coefficients ``c`` (K, ·)), the points' bases
    computed once for all K (the same numbers as computing them for each)."""
    k = c.shape[0]
    out = np.empty((x.size, k))
    hx = np.empty(kx + 1)
    hy = np.empty(ky + 1)
    hh = np.empty(max(kx, ky) + 1)
    nky1 = ty.size - ky - 1
    flat = c.reshape(-1)  # (the splines' coefficients one after the other)
    size = c.shape[1]
    for p in range(x.size):
        lx = _basis(tx, kx, x[p], hx, hh)
        ly = _basis(ty, ky, y[p], hy, hh)
        for s in range(k):
            out[p, s] = _tensor_sum(flat, s * size, kx, ky, lx, ly, nky1, hx, hy)
    return out


@_jit
def _maximum(a, b):
    """np.maximum of two floats (NaN if either is NaN)."""
    if a != a or b != b:
        return np.nan
    return a if a >= b else b


@_jit
def _minimum(a, b):
    """np.minimum of two floats (NaN if either is NaN)."""
    if a != a or b != b:
        return np.nan
    return a if a <= b else b


@_jit
def _newton_one(q, qv, v0, v1, u, t, v, miss, w):
    """:meth:`EaseOffFields.newton_v` of one point: v* [1] or NaN. ``q``, ``qv``: the
    splines of Q and ∂Q/∂v; ``w``: work arrays (hx, hy, hh)."""
    hx, hy, hh = w
    # u stays fixed: Q and ∂Q/∂v (same x-knots and degree) share the x-basis at u
    lx = _basis(q[0], q[3], u, hx, hh)
    f = _value_at(q[1], q[2], q[3], q[4], lx, hx, v, hy, hh) - t
    if not (abs(f) < 1e-13) and not miss:
        for _ in range(6):
            d = _value_at(qv[1], qv[2], qv[3], qv[4], lx, hx, v, hy, hh)
            vn = _minimum(_maximum(v - f / (d if d != 0 else 1e-30), v0), v1)
            fa = _value_at(q[1], q[2], q[3], q[4], lx, hx, vn, hy, hh) - t
            va = v
            v, f = vn, fa
            if abs(fa) < 1e-13 or vn == va:
                break
    tol = 1e-9 * (v1 - v0)
    if v < v0 - tol or v > v1 + tol or abs(f) > 1e-9 or miss:
        return np.nan
    return _minimum(_maximum(v, v0), v1)


@_jit
def _work(q):
    return (np.empty(q[3] + 1), np.empty(q[4] + 1), np.empty(max(q[3], q[4]) + 1))


@_jit
def newton_v(q, qv, v0, v1, u, t, v, miss):
    """Newton's method on the iso-line Q(u, v*) = t (M,) from the finite starts v (M,),
    as :meth:`EaseOffFields.newton_v`: v* [1] or NaN. A spline is (tx, ty, c, kx, ky);
    ``q`` is Q's, ``qv`` its ∂/∂v (:func:`derivative_spline`)."""
    w = _work(q)
    out = np.empty(u.size)
    for p in range(u.size):
        out[p] = _newton_one(q, qv, v0, v1, u[p], t[p], v[p], miss[p], w)
    return out


@_jit
def _good_cell(ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.good_cell` of one place: its grid cell's corners were all
    computed (places beyond the grid count as its edge cells)."""
    iu = min(max(np.searchsorted(ug, u, side="right") - 1, 0), ug.size - 2)
    iv = min(max(np.searchsorted(vg, v, side="right") - 1, 0), vg.size - 2)
    return cell_ok[iu, iv]


@_jit
def _measure(margin, ug, vg, cell_ok, u, v, w):
    """:meth:`EaseOffFields.measure` of one place (v may be NaN)."""
    hx, hy, hh = w
    fin = math.isfinite(v)
    vs = v if fin else vg[0]
    c = _minimum(_value(margin[0], margin[1], margin[2], margin[3], margin[4], u, vs,
                        hx, hy, hh), vs - vg[0])
    c = _minimum(c, vg[-1] - vs)
    c = _minimum(c, u - ug[0])
    c = _minimum(c, ug[-1] - u)
    if not fin:
        return -1.0
    return c if _good_cell(ug, vg, cell_ok, u, vs) else -1.0


@_jit
def measure(margin, ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.measure` at the places (u, v) (M,) (v may be NaN)."""
    w = _work(margin)
    out = np.empty(u.size)
    for p in range(u.size):
        out[p] = _measure(margin, ug, vg, cell_ok, u[p], v[p], w)
    return out


@_jit
def false_position_ends(q, qv, margin, ug, vg, cell_ok, t, a, b, va, n_iter):
    """:func:`contact.utca.contact_curves._false_position_ends`: the last inside places of
    the iso-lines Q = t (M,) between inside places a (profile places va) and outside
    places b, ``n_iter`` Illinois / bisection steps (fewer only once every |b − a| <
    1e-9); ``a``, ``b``, ``va`` are updated in place."""
    w = _work(margin)
    v0, v1 = vg[0], vg[-1]
    m_pts = a.size
    ca = np.empty(m_pts)
    cb = np.empty(m_pts)
    for p in range(m_pts):
        ca[p] = _measure(margin, ug, vg, cell_ok, a[p], va[p], w)
        vs = va[p] if math.isfinite(va[p]) else 0.5 * (v0 + v1)
        vb = _newton_one(q, qv, v0, v1, b[p], t[p], vs, False, w)
        cb[p] = _measure(margin, ug, vg, cell_ok, b[p], vb, w)
    prev_in = np.zeros(m_pts, dtype=np.bool_)
    prev_out = np.zeros(m_pts, dtype=np.bool_)
    for _ in range(n_iter):
        done = True
        for p in range(m_pts):
            ap, bp, cap, cbp = a[p], b[p], ca[p], cb[p]
            smooth = (cbp > -0.5) and (cap < 0.5) and (cbp != cap)
            if smooth:
                m = bp - cbp * (bp - ap) / (cbp - cap)
            else:
                m = 0.5 * (ap + bp)
            lo_m, hi_m = _minimum(ap, bp), _maximum(ap, bp)
            wd = 1e-3 * (hi_m - lo_m)
            m = _minimum(_maximum(m, lo_m + wd), hi_m - wd)
            vm = _newton_one(q, qv, v0, v1, m, t[p], va[p], False, w)
            cm = _measure(margin, ug, vg, cell_ok, m, vm, w)
            good = cm >= 0
            if good and prev_in[p] and smooth:
                cb[p] = cbp * 0.5
            if (not good) and prev_out[p] and smooth:
                ca[p] = cap * 0.5
            if good:
                a[p], ca[p], va[p] = m, cm, vm
            else:
                b[p], cb[p] = m, cm
            prev_in[p], prev_out[p] = good, not good
            if not (abs(b[p] - a[p]) < 1e-9):
                done = False
        if done:
            break
    return a


@_jit
def solve_columns(qn, vn, q_sign, target, breaks, pieces, cell_piece, n_iter):
    """:meth:`EaseOffFields.solve_columns`: the profile places v* (nb, nc) [1] of the
    iso-lines Q = target (nb,) on the lengthwise places of the lattice ``qn`` (nc, nv)
    (Q at those places × the profile nodes ``vn``), NaN where Q misses the target or the
    safeguarded Newton steps on the column's cubic piece (``pieces`` (nc, n_int, 4) on
    the knot intervals ``breaks``; ``cell_piece`` (nv − 1,) the interval of each cell)
    leave |Q − q| above 1e-9 rad."""
    nc, nv = qn.shape
    nb = target.size
    out = np.full((nb, nc), np.nan)
    for ib in range(nb):
        tg = target[ib]
        for j in range(nc):
            # the bracketing cell: as many nodes at or below the target (Q is monotone)
            below = 0
            for i in range(nv):
                if q_sign * (qn[j, i] - tg) <= 0:
                    below += 1
            k = min(max(below - 1, 0), nv - 2)
            if q_sign * (qn[j, 0] - tg) > 0 or q_sign * (qn[j, nv - 1] - tg) < 0:
                continue
            qa, qb = qn[j, k], qn[j, k + 1]
            tt = (tg - qa) / (qb - qa if qb != qa else 1.0)
            tt = _minimum(_maximum(tt, 0.0), 1.0)
            v = vn[k] + tt * (vn[k + 1] - vn[k])
            pc = cell_piece[k]
            c0, c1, c2, c3 = pieces[j, pc, 0], pieces[j, pc, 1], pieces[j, pc, 2], pieces[j, pc, 3]
            x0 = breaks[pc]
            lo, hi = vn[k] - x0, vn[k + 1] - x0
            x = v - x0
            f = ((c3 * x + c2) * x + c1) * x + c0 - tg
            if not (abs(f) < 1e-13):
                for _ in range(n_iter):
                    xr = x
                    d = (3.0 * c3 * xr + 2.0 * c2) * xr + c1
                    xn = _minimum(_maximum(xr - f / (d if d != 0 else 1e-30), lo), hi)
                    f = ((c3 * xn + c2) * xn + c1) * xn + c0 - tg
                    x = xn
                    if abs(f) < 1e-13 or xn == xr:
                        break
            if not (abs(f) > 1e-9):
                out[ib, j] = x + x0
    return out


@_jit
def _inside_one(margin, ug, vg, cell_ok, u, v, w):
    """:meth:`EaseOffFields.inside` of one place: in the grid, in a cell whose corners
    were computed, and with the pinion mate in its blank (margin ≥ 0)."""
    if not (u >= ug[0] and u <= ug[-1] and v >= vg[0] and v <= vg[-1]
            and math.isfinite(v)):
        return False
    if not _good_cell(ug, vg, cell_ok, u, v):
        return False
    hx, hy, hh = w
    return _value(margin[0], margin[1], margin[2], margin[3], margin[4], u, v,
                  hx, hy, hh) >= 0.0


@_jit
def coarse_runs(margin, ug, vg, cell_ok, uc, vc):
    """The largest run of inside coarse samples of each iso-line (the first of equally
    long ones), as :func:`contact.utca.contact_curves._coarse_runs` after its column
    solves ``vc`` (nb, nc) at the places ``uc`` (nc,): have, start, stop (nb,) (−1 where
    no sample is inside)."""
    w = _work(margin)
    nb, nc = vc.shape
    have = np.zeros(nb, dtype=np.bool_)
    start = np.full(nb, -1, dtype=np.int64)
    stop = np.full(nb, -1, dtype=np.int64)
    for r in range(nb):
        best, best_at, run, run_at = 0, -1, 0, -1
        for j in range(nc):
            if _inside_one(margin, ug, vg, cell_ok, uc[j], vc[r, j], w):
                if run == 0:
                    run_at = j
                run += 1
                if run > best:  # (strictly longer: the first of equal runs is kept)
                    best, best_at = run, run_at
            else:
                run = 0
        if best > 0:
            have[r] = True
            start[r] = best_at
            stop[r] = best_at + best - 1
    return have, start, stop


@_jit
def _curve_ends(q, qv, margin, ug, vg, cell_ok, t, uc, vc, have, start, stop, s_rows, s_u,
                s_v, s_lo, s_hi, n_end):
    """``_curve_ends``: the ends (ua, ub) (nb,) of the curves, refined by
    :func:`false_position_ends` on the batch the NumPy path builds (the runs' low ends, their
    high ends, the short curves' low and high ends)."""
    nb, nc = vc.shape
    ua = np.full(nb, np.nan)
    ub = np.full(nb, np.nan)
    n_lo = 0
    n_hi = 0
    for r in range(nb):
        if have[r]:
            ua[r] = uc[min(max(start[r], 0), nc - 1)]
            ub[r] = uc[min(max(stop[r], 0), nc - 1)]
            if start[r] > 0:
                n_lo += 1
            if stop[r] < nc - 1:
                n_hi += 1
    n_s = s_rows.size
    m_ends = n_lo + n_hi + 2 * n_s
    if m_ends == 0:
        return ua, ub
    rows = np.empty(m_ends, dtype=np.int64)
    a = np.empty(m_ends)
    b = np.empty(m_ends)
    va = np.empty(m_ends)
    i = 0
    for r in range(nb):
        if have[r] and start[r] > 0:
            rows[i], a[i], b[i], va[i] = r, uc[start[r]], uc[start[r] - 1], vc[r, start[r]]
            i += 1
    for r in range(nb):
        if have[r] and stop[r] < nc - 1:
            rows[i], a[i], b[i], va[i] = r, uc[stop[r]], uc[stop[r] + 1], vc[r, stop[r]]
            i += 1
    for side in range(2):
        for s in range(n_s):
            rows[i], a[i], va[i] = s_rows[s], s_u[s], s_v[s]
            b[i] = s_lo[s] if side == 0 else s_hi[s]
            i += 1
    tr = np.empty(m_ends)
    for i in range(m_ends):
        tr[i] = t[rows[i]]
    a = false_position_ends(q, qv, margin, ug, vg, cell_ok, tr, a, b, va, n_end)
    for i in range(n_lo):
        ua[rows[i]] = a[i]
    for i in range(n_lo, n_lo + n_hi):
        ub[rows[i]] = a[i]
    for s in range(n_s):
        ua[s_rows[s]] = a[n_lo + n_hi + s]
        ub[s_rows[s]] = a[n_lo + n_hi + n_s + s]
    return ua, ub


@_jit
def _run_start(uc, vc, r, s0, s1, x):
    """``_run_interpolation`` of one place x of curve r: its run's coarse profile places
    (s0 … s1) interpolated linearly (ends held)."""
    j = min(max(np.searchsorted(uc, x, side="right") - 1, s0), s1)
    jn = min(j + 1, s1)
    yj = vc[r, j]
    yn = vc[r, jn]
    step = jn != j
    slope = (yn - yj) / (uc[jn] - uc[j] if step else 1.0)
    val = slope * (x - uc[j]) + yj if (step and uc[j] != x) else yj
    if x < uc[s0]:
        return vc[r, s0]
    if x >= uc[s1]:
        return vc[r, s1]
    return val


@_jit
def _lowest_point(q, qv, eps, vg, t, up, vp, e, w):
    """``_lowest_point`` with ``_parabola_vertex``: ute, cu, cv, index (nb,)."""
    nb, n = up.shape
    hx, hy, hh = w
    v0, v1 = vg[0], vg[-1]
    ute = np.full(nb, np.nan)
    cu = np.full(nb, np.nan)
    cv = np.full(nb, np.nan)
    index = np.full(nb, -1, dtype=np.int64)
    for r in range(nb):
        k = -1
        emin = np.inf
        for j in range(n):  # argmin of ε over the samples (the first of equal ones)
            if math.isfinite(vp[r, j]) and (k < 0 or e[r, j] < emin):
                k, emin = j, e[r, j]
        if k < 0:
            continue
        index[r] = k
        ute[r], cu[r], cv[r] = emin, up[r, k], vp[r, k]
        if not (0 < k < n - 1):
            continue
        em, ec, ep = e[r, k - 1], e[r, k], e[r, k + 1]
        h1 = up[r, k] - up[r, k - 1]
        h2 = up[r, k + 1] - up[r, k]
        a1, a2 = em - ec, ep - ec
        den = 2 * (h2 * a1 + h1 * a2)
        d = (h2 * h2 * a1 - h1 * h1 * a2) / den if (math.isfinite(den) and den > 0) else 0.0
        ur = up[r, k] + _minimum(_maximum(d, -0.5 * h1), 0.5 * h2)
        vr = _newton_one(q, qv, v0, v1, ur, t[r], vp[r, k], False, w)
        if math.isfinite(vr):
            er = _value(eps[0], eps[1], eps[2], eps[3], eps[4], ur, vr, hx, hy, hh)
            if er < ec:
                ute[r], cu[r], cv[r] = er, ur, vr
    return ute, cu, cv, index


@_jit
def seed_places(q, qv, margin, eps, ug, vg, cell_ok, t, frac, uc, vc, have, start, stop,
                s_rows, s_u, s_v, s_lo, s_hi, n_end):
    """The iso-lines' places, ε and contact points from their coarse runs, as
    :func:`contact.utca.contact_curves._seed_places` after :func:`coarse_runs` and the
    short curves (rows ``s_rows`` (M,), seeds ``s_u``, ``s_v``, brackets ``s_lo``,
    ``s_hi``): the ends (:func:`false_position_ends`, ``n_end`` steps, the same batch),
    the samples at ``frac`` (n,) by Newton's method from the runs' interpolation, ε there,
    the lowest sample and its parabola's vertex. Returns up, vp, ε (nb, n) and ute, cu,
    cv (nb,), index (nb,)."""
    w = _work(q)
    hx, hy, hh = w
    nb = vc.shape[0]
    n = frac.size
    u0 = ug[0]
    v0, v1 = vg[0], vg[-1]
    ua, ub = _curve_ends(q, qv, margin, ug, vg, cell_ok, t, uc, vc, have, start, stop,
                         s_rows, s_u, s_v, s_lo, s_hi, n_end)
    short_v = np.full(nb, np.nan)
    is_short = np.zeros(nb, dtype=np.bool_)
    for s in range(s_rows.size):
        is_short[s_rows[s]] = True
        short_v[s_rows[s]] = s_v[s]
    up = np.empty((nb, n))
    vp = np.full((nb, n), np.nan)
    e = np.full((nb, n), np.nan)
    for r in range(nb):
        for k in range(n):
            up[r, k] = ua[r] + (ub[r] - ua[r]) * frac[k]
        if not (have[r] or is_short[r]):
            continue
        for k in range(n):
            # Newton from the run's interpolation (a short curve: from its seed)
            x = up[r, k] if math.isfinite(up[r, k]) else u0
            vs = short_v[r] if is_short[r] else _run_start(uc, vc, r, start[r], stop[r], x)
            if not math.isfinite(vs):
                vs = 0.5 * (v0 + v1)
            vp[r, k] = _newton_one(q, qv, v0, v1, x, t[r], vs, False, w)
        for k in range(n):
            if math.isfinite(vp[r, k]):
                e[r, k] = _value(eps[0], eps[1], eps[2], eps[3], eps[4], up[r, k], vp[r, k],
                                 hx, hy, hh)
    for r in range(nb):
        for k in range(n):
            if not math.isfinite(vp[r, k]):
                up[r, k] = np.nan
    ute, cu, cv, index = _lowest_point(q, qv, eps, vg, t, up, vp, e, w)
    return up, vp, e, ute, cu, cv, index
