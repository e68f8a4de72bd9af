"""Compiled kernels of the iso-line searches on the ease-off splines (numba; issue 32).

The contact curves' searches (:mod:`contact.utca.contact_curves`) iterate Newton's method
and false position on a few hundred places at a time, so in NumPy most of their time is
the interpreter's, not the arithmetic's. These kernels run the same iterations point by
point in compiled loops, with the same steps and tests as the NumPy path of
:class:`contact.utca.fields.EaseOffFields` (which stays the reference):

- a bicubic spline is taken in piecewise-polynomial form
  (:mod:`contact.utca.piecewise`: per knot cell, the polynomial's coefficients), so a
  value is two interval look-ups and a Horner scheme instead of FITPACK's de Boor–Cox
  recurrence and tensor sum (``fpbisp``/``fpbspl``, Dierckx 1993, §2.1; ~1/3 of the time),
  and ∂Q/∂v comes with Q from the same polynomial;
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
  and normals, Q, ε, the normal arm) share each place's cell look-up (:func:`ev`).

The two paths differ by the spline's round-off: the polynomial form and FITPACK's
recurrence agree to a few units in the last place of the spline's scale (measured
≤ 1e-15 relative; checked to 1e-13). The iterations stop at |ΔQ| < 1e-13 rad, so the
places agree to that over the slope of Q (≤ 1.8e-11 on the cases tested; measured
≤ 2e-12), and a study point's summaries to the 5×5 guard's 1e-9
(``tests/test_isoline_kernels.py``); numba does not contract ``a * b + c`` into
fused multiply-adds or reassociate sums unless asked (``fastmath`` is off), so the
kernels' numbers do not depend on the CPU.

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
    "ev",
    "false_position_ends",
    "measure",
    "newton_v",
    "pieces",
    "seed_places",
    "solve_columns",
]

_jit = numba.njit(cache=True, nogil=True)

#: helpers called from compiled code only: no CPython or C wrapper to compile
_helper = numba.njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)


@_helper
def _locate(b, x):
    """The cell of breakpoints ``b`` holding x and x's offset in it: x clamped into
    [b[0], b[-1]] (FITPACK's clamp), the largest i ≤ len(b) − 2 with b[i] ≤ x (FITPACK's
    interval: an interior knot opens the cell to its right)."""
    if x < b[0]:
        x = b[0]
    if x > b[-1]:
        x = b[-1]
    lo, hi = 0, b.size - 2
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if x >= b[mid]:
            lo = mid
        else:
            hi = mid - 1
    return lo, x - b[lo]


@_helper
def _poly(coef, i, j, s, dx, dy):
    """Spline s's polynomial on cell (i, j) at the offsets (dx, dy): Horner's scheme in y
    within Horner's scheme in x."""
    acc = 0.0
    for p in range(coef.shape[3] - 1, -1, -1):
        r = 0.0
        for q in range(coef.shape[4] - 1, -1, -1):
            r = r * dy + coef[i, j, s, p, q]
        acc = acc * dx + r
    return acc


@_helper
def _value(sp, x, y):
    """The value at (x, y) of the first spline of ``sp`` = (bx, by, coefficients)
    (:class:`contact.utca.piecewise.PiecewiseSpline`)."""
    i, dx = _locate(sp[0], x)
    j, dy = _locate(sp[1], y)
    return _poly(sp[2], i, j, np.int64(0), dx, dy)


@_helper
def _value_and_slope(sp, i, dx, y):
    """The first spline of ``sp`` and its ∂/∂y at (x, y), x given by its cell i and offset
    dx: the polynomial in y at that x, by Horner's scheme with its derivative's."""
    coef = sp[2]
    j, dy = _locate(sp[1], y)
    val = 0.0
    der = 0.0
    for q in range(coef.shape[4] - 1, -1, -1):
        a = 0.0
        for p in range(coef.shape[3] - 1, -1, -1):
            a = a * dx + coef[i, j, 0, p, q]
        der = der * dy + val
        val = val * dy + a
    return val, der


@_jit
def ev(bx, by, coef, x, y):
    """Values (M, K) of K splines in piecewise-polynomial form (breakpoints bx, by;
    coefficients (nx, ny, K, kx + 1, ky + 1), :class:`contact.utca.piecewise.PiecewiseSpline`)
    at the places (x[m], y[m]) (M,): ``RectBivariateSpline.ev`` of each, to round-off; each
    place's cell is found once for the K splines."""
    k = coef.shape[2]
    out = np.empty((x.size, k))
    for m in range(x.size):
        i, dx = _locate(bx, x[m])
        j, dy = _locate(by, y[m])
        for s in range(k):
            out[m, s] = _poly(coef, i, j, s, dx, dy)
    return out


@_jit
def pieces(c, basis_x, basis_y):
    """The per-cell polynomial coefficients (ncx, ncy, K, kx + 1, ky + 1) of K splines on
    the same knots, from their B-spline coefficients ``c`` (K, nx, ny) and the knots'
    B-splines as polynomials on each interval (``basis_x`` (ncx, kx + 1, kx + 1),
    ``basis_y``; :func:`contact.utca.piecewise.piece_basis`): Σ_a Σ_b Bx[i, a, p]
    c[s, i + a, j + b] By[j, b, q], along x and then along y
    (:func:`contact.utca.piecewise.from_splines`, compiled)."""
    k = c.shape[0]
    ncx, kx1 = basis_x.shape[0], basis_x.shape[1]
    ncy, ky1 = basis_y.shape[0], basis_y.shape[1]
    ny = c.shape[2]
    out = np.empty((ncx, ncy, k, kx1, ky1))
    along_x = np.empty((ny, kx1))
    for s in range(k):
        for i in range(ncx):
            for jj in range(ny):
                for p in range(kx1):
                    acc = 0.0
                    for a in range(kx1):
                        acc += basis_x[i, a, p] * c[s, i + a, jj]
                    along_x[jj, p] = acc
            for j in range(ncy):
                for p in range(kx1):
                    for q in range(ky1):
                        acc = 0.0
                        for b in range(ky1):
                            acc += along_x[j + b, p] * basis_y[j, b, q]
                        out[i, j, s, p, q] = acc
    return out


@_helper
def _maximum(a, b):
    """np.maximum of two floats (NaN if either is NaN)."""
    if a != a or b != b:
        return np.nan
    return a if a >= b else b


@_helper
def _minimum(a, b):
    """np.minimum of two floats (NaN if either is NaN)."""
    if a != a or b != b:
        return np.nan
    return a if a <= b else b


@_helper
def _newton_one(q, v0, v1, u, t, v, miss):
    """:meth:`EaseOffFields.newton_v` of one point: v* [1] or NaN. ``q``: the spline of Q
    (bx, by, coefficients), whose value and ∂Q/∂v come from one polynomial per step."""
    # u stays fixed: its cell and offset serve every step
    i, du = _locate(q[0], u)
    f, d = _value_and_slope(q, i, du, v)
    f = f - t
    if not (abs(f) < 1e-13) and not miss:
        for _ in range(6):
            vn = _minimum(_maximum(v - f / (d if d != 0 else 1e-30), v0), v1)
            fa, dn = _value_and_slope(q, i, du, vn)
            fa = fa - t
            va = v
            v, f, d = vn, fa, dn
            if abs(fa) < 1e-13 or vn == va:
                break
    tol = 1e-9 * (v1 - v0)
    if v < v0 - tol or v > v1 + tol or abs(f) > 1e-9 or miss:
        return np.nan
    return _minimum(_maximum(v, v0), v1)


@_jit
def newton_v(q, v0, v1, u, t, v, miss):
    """Newton's method on the iso-line Q(u, v*) = t (M,) from the finite starts v (M,),
    as :meth:`EaseOffFields.newton_v`: v* [1] or NaN. ``q`` is Q's spline in
    piecewise-polynomial form (bx, by, coefficients)."""
    out = np.empty(u.size)
    for p in range(u.size):
        out[p] = _newton_one(q, v0, v1, u[p], t[p], v[p], miss[p])
    return out


@_helper
def _good_cell(ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.good_cell` of one place: its grid cell's corners were all
    computed (places beyond the grid count as its edge cells)."""
    iu = min(max(np.searchsorted(ug, u, side="right") - 1, 0), ug.size - 2)
    iv = min(max(np.searchsorted(vg, v, side="right") - 1, 0), vg.size - 2)
    return cell_ok[iu, iv]


@_helper
def _measure(margin, ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.measure` of one place (v may be NaN)."""
    fin = math.isfinite(v)
    vs = v if fin else vg[0]
    c = _minimum(_value(margin, u, vs), vs - vg[0])
    c = _minimum(c, vg[-1] - vs)
    c = _minimum(c, u - ug[0])
    c = _minimum(c, ug[-1] - u)
    if not fin:
        return -1.0
    return c if _good_cell(ug, vg, cell_ok, u, vs) else -1.0


@_jit
def measure(margin, ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.measure` at the places (u, v) (M,) (v may be NaN)."""
    out = np.empty(u.size)
    for p in range(u.size):
        out[p] = _measure(margin, ug, vg, cell_ok, u[p], v[p])
    return out


@_jit
def false_position_ends(q, margin, ug, vg, cell_ok, t, a, b, va, n_iter):
    """:func:`contact.utca.contact_curves._false_position_ends`: the last inside places of
    the iso-lines Q = t (M,) between inside places a (profile places va) and outside
    places b, ``n_iter`` Illinois / bisection steps (fewer only once every |b − a| <
    1e-9); ``a``, ``b``, ``va`` are updated in place."""
    v0, v1 = vg[0], vg[-1]
    m_pts = a.size
    ca = np.empty(m_pts)
    cb = np.empty(m_pts)
    for p in range(m_pts):
        ca[p] = _measure(margin, ug, vg, cell_ok, a[p], va[p])
        vs = va[p] if math.isfinite(va[p]) else 0.5 * (v0 + v1)
        vb = _newton_one(q, v0, v1, b[p], t[p], vs, np.bool_(False))
        cb[p] = _measure(margin, ug, vg, cell_ok, b[p], vb)
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
            vm = _newton_one(q, v0, v1, m, t[p], va[p], np.bool_(False))
            cm = _measure(margin, ug, vg, cell_ok, m, vm)
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


@_helper
def _inside_one(margin, ug, vg, cell_ok, u, v):
    """:meth:`EaseOffFields.inside` of one place: in the grid, in a cell whose corners
    were computed, and with the pinion mate in its blank (margin ≥ 0)."""
    if not (u >= ug[0] and u <= ug[-1] and v >= vg[0] and v <= vg[-1]
            and math.isfinite(v)):
        return False
    if not _good_cell(ug, vg, cell_ok, u, v):
        return False
    return _value(margin, u, v) >= 0.0


@_jit
def coarse_runs(margin, ug, vg, cell_ok, uc, vc):
    """The largest run of inside coarse samples of each iso-line (the first of equally
    long ones), as :func:`contact.utca.contact_curves._coarse_runs` after its column
    solves ``vc`` (nb, nc) at the places ``uc`` (nc,): have, start, stop (nb,) (−1 where
    no sample is inside)."""
    nb, nc = vc.shape
    have = np.zeros(nb, dtype=np.bool_)
    start = np.full(nb, -1, dtype=np.int64)
    stop = np.full(nb, -1, dtype=np.int64)
    for r in range(nb):
        best, best_at, run, run_at = 0, -1, 0, -1
        for j in range(nc):
            if _inside_one(margin, ug, vg, cell_ok, uc[j], vc[r, j]):
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


@_helper
def _curve_ends(q, margin, ug, vg, cell_ok, t, uc, vc, have, start, stop, s_rows, s_u,
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
    a = false_position_ends(q, margin, ug, vg, cell_ok, tr, a, b, va, n_end)
    for i in range(n_lo):
        ua[rows[i]] = a[i]
    for i in range(n_lo, n_lo + n_hi):
        ub[rows[i]] = a[i]
    for s in range(n_s):
        ua[s_rows[s]] = a[n_lo + n_hi + s]
        ub[s_rows[s]] = a[n_lo + n_hi + n_s + s]
    return ua, ub


@_helper
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


@_helper
def _lowest_point(q, eps, vg, t, up, vp, e):
    """``_lowest_point`` with ``_parabola_vertex``: ute, cu, cv, index (nb,)."""
    nb, n = up.shape
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
        vr = _newton_one(q, v0, v1, ur, t[r], vp[r, k], np.bool_(False))
        if math.isfinite(vr):
            er = _value(eps, ur, vr)
            if er < ec:
                ute[r], cu[r], cv[r] = er, ur, vr
    return ute, cu, cv, index


@_jit
def seed_places(q, margin, eps, ug, vg, cell_ok, t, frac, uc, vc, have, start, stop,
                s_rows, s_u, s_v, s_lo, s_hi, n_end):
    """The iso-lines' places, ε and contact points from their coarse runs, as
    :func:`contact.utca.contact_curves._seed_places` after :func:`coarse_runs` and the
    short curves (rows ``s_rows`` (M,), seeds ``s_u``, ``s_v``, brackets ``s_lo``,
    ``s_hi``): the ends (:func:`false_position_ends`, ``n_end`` steps, the same batch),
    the samples at ``frac`` (n,) by Newton's method from the runs' interpolation, ε there,
    the lowest sample and its parabola's vertex. Returns up, vp, ε (nb, n) and ute, cu,
    cv (nb,), index (nb,)."""
    nb = vc.shape[0]
    n = frac.size
    u0 = ug[0]
    v0, v1 = vg[0], vg[-1]
    ua, ub = _curve_ends(q, margin, ug, vg, cell_ok, t, uc, vc, have, start, stop,
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
            vp[r, k] = _newton_one(q, v0, v1, x, t[r], vs, np.bool_(False))
        for k in range(n):
            if math.isfinite(vp[r, k]):
                e[r, k] = _value(eps, up[r, k], vp[r, k])
    for r in range(nb):
        for k in range(n):
            if not math.isfinite(vp[r, k]):
                up[r, k] = np.nan
    ute, cu, cv, index = _lowest_point(q, eps, vg, t, up, vp, e)
    return up, vp, e, ute, cu, cv, index
