"""Unloaded TCA from the ease-off and the surface of roll angle (seed §2.3.2.2, §4.4).

For a pinion roll position (value q of the roll-angle surface Q, see
:mod:`contact.utca.easeoff`) all gear projection-plane points with Q = q are in contact with
the pinion's conjugate at the same time: the iso-line Q = q is the instantaneous contact
curve, and projected onto the ease-off its lowest point H gives the unloaded transmission
error (UTE) of that tooth pair — the gear lag at which the real gear first touches the
pinion (seed Fig. 2.8, 4.3). Adjacent tooth pairs are the same curves one angular pitch
2π/z_p of pinion roll apart; the pair that carries the motion is the one with the smallest
lag, so the actual UTE is the lower envelope of the pairs' curves, and their intersections
are the transition points M1, M2 (seed Fig. 2.9). Along each contact curve the stretch
where the ease-off exceeds the UTE by no more than a separation (6.3 µm by default,
"0.006 mm" in the seed) is the unloaded contact line; its ends trace the left and right
point paths LPP, RPP on either side of the contact point path CPP (seed Fig. 2.10).

Contouring
----------
Q, the angular ease-off ε, the gap curvature K, the normal arm and the gear flank are
represented by bicubic interpolating splines over the gear grid (u, v)
(``scipy.interpolate.RectBivariateSpline``, s = 0), which reproduce the exact node values.
ε, Q and K are built from the valid nodes and the computed nodes on the same smooth sheet
beyond them (both points on their blades' main sections), continued linearly past those:
a blade-section junction kinks the fields and a cubic spline would carry the kink back.
Q is strictly monotone along the profile direction on bevel and hypoid flanks (checked;
otherwise ``ModelUnavailableError``), so a contact curve is parameterised by the
lengthwise fraction u and its profile place v*(u) solved by Newton's method on the spline
(to |ΔQ| < 1e-13 rad). A curve ends where it leaves the contact region: where the mating
pinion point leaves the pinion blank (a smooth level set of the pinion's projection-plane
fractions), the grid's root or tip line, or a grid cell with an uncomputed corner; the ends
are found by false position on that continuous measure (bisection where it jumps) to 1e-9
of the face width, and the curve is resampled uniformly in u between them. The minimum
along the curve is refined by a parabola through the three lowest samples.

Interpolation error: built on every other node, the spline reproduces the skipped nodes'
exact ε within 0.2–0.3 µrad away from the region's edges (``tests/test_utca.py``); the
error falls as h⁴, so on the full 41 × 21 grid it is ≈ 0.01–0.02 µrad. Within a cell of a
section junction (near the pinion tip or the gear's fillet) it reaches ~1 µrad.

The UTE: seed's first-order method and its second-order correction
-------------------------------------------------------------------
The seed's contact curves are those between the real pinion and the conjugate gear (seed
§2.3.2.2: "the contact curves are between real pinion and conjugate gear"), and its UTE is
the minimum of ε along the iso-line Q = q (``method="seed"``). The real pinion at roll q
is itself separated from its conjugate by ½ K (Q − q)² (``EaseOff.gap_curvature``), so the
real first contact is min over t of UTE_seed(q + t) + ½ K t²; the default
``method="second_order"`` takes t₀ = −(dUTE_seed/dq)/K and evaluates the shifted iso-line
(error O((t − t₀)²)). Against the conventional TCA (seed Eq. 2.14) on a crowned hypoid the
seed's method is off by up to ~3 µrad within the mesh cycle (16 µrad at 200 µrad of UTE),
the second-order one by ≤ 0.03 µrad (0.35 µrad at 200 µrad); contact points within
0.03 mm.

Public functions
----------------
DEFAULT_SEPARATION       6.3 µm (0.0063 mm)
UTE_METHODS              "seed", "second_order"
CURVE_SPACINGS           "uniform", "cosine" samples along a contact curve
ContactCurves            curves of a batch of roll targets: places, ease-off, UTE, H
contact_curves           compute them from an EaseOff for roll values (Q units)
pair_transmission_error  UTE of the reference tooth pair at roll values
transitions              rolls M1, M2 bounding the reference pair's share of the envelope

The UTCA of a whole case as datasets (:func:`contact.utca.unloaded_tca`) is in
:mod:`contact.utca.datasets`.

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009, §2.3.2.2, §2.4, §4.4.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from contact.utca.easeoff import EaseOff
from contact.utca.fields import EaseOffFields
from geometry.core.errors import InputError
from geometry.core.validation import integer, one_of, real_array

__all__ = [
    "CURVE_SPACINGS",
    "DEFAULT_SEPARATION",
    "UTE_METHODS",
    "ContactCurves",
    "contact_curves",
    "pair_transmission_error",
]

#: separation that bounds the unloaded contact line [mm] (6.3 µm, industry practice; the
#: seed's example uses 0.006 mm)
DEFAULT_SEPARATION = 0.0063


_COARSE_PER_CELL = 2  # coarse samples per grid cell along a curve


#: false-position steps on a curve end: all of them run unless every end of the batch is
#: within 1e-9 of the face width; a jump end (bisection) ends within 2⁻¹¹–2⁻¹² of its
#: coarse step, 3–6e-6 of the face width on the default grid (:func:`_false_position_ends`)
_END_ITER = 12


class ContactCurves(NamedTuple):
    """Contact curves of a batch of roll targets (shape ``batch``), ``n_point`` samples each.

    Places are gear projection-plane fractions (u, v); a curve that misses the contact
    region holds NaN. Angles in rad, lengths in mm. The separation from the gear at lag λ
    along the curve is ``normal_arm`` × (``ease_off_angle`` + ``gap`` − λ).
    """

    target: np.ndarray  # batch [rad] roll value of the pair (Q units)
    shift: np.ndarray  # batch [rad] t: the curve drawn is the iso-line Q = target + t
    u: np.ndarray  # batch + (n_point,)
    v: np.ndarray
    ease_off_angle: np.ndarray  # [rad] ε along the curve
    gap: np.ndarray  # [rad] ½ K t² (the pinion's own gap to its conjugate); 0 for "seed"
    normal_arm: np.ndarray  # [mm]
    position: np.ndarray  # batch + (n_point, 3) [mm] gear frame
    normal: np.ndarray  # batch + (n_point, 3) [1]
    ute: np.ndarray  # batch [rad] unloaded transmission error of the pair (gear lag)
    contact_u: np.ndarray  # batch: place of the contact point H
    contact_v: np.ndarray
    index: np.ndarray  # batch: sample index nearest to H (-1 where no curve)


class _Coarse(NamedTuple):
    """Iso-lines located on coarse samples along u (flat batch nb).

    ``start``, ``stop``: sample indices of each curve's largest contiguous run of samples
    inside the contact region (-1 where it has none, ``have`` False).
    """

    u: np.ndarray  # (nc,) [1] coarse places along u
    v: np.ndarray  # (nb, nc) [1] profile places of the iso-lines there (NaN: missed)
    have: np.ndarray  # (nb,) bool
    start: np.ndarray  # (nb,) int
    stop: np.ndarray  # (nb,) int


class _ShortCurves(NamedTuple):
    """Curves that lie wholly between two coarse samples (see :func:`_short_curves`)."""

    rows: np.ndarray  # (M,) int: indices into the batch
    u: np.ndarray  # (M,) [1] a place inside each (the maximum of the inside measure)
    v: np.ndarray  # (M,)
    lo: np.ndarray  # (M,) neighbouring coarse places (outside) bracketing each curve's ends
    hi: np.ndarray


def _seed_places(f: EaseOffFields, t: np.ndarray, frac: np.ndarray,
                 coarse_per_cell: int = _COARSE_PER_CELL) -> ContactCurves:
    """Places, ε and UTE of the iso-lines Q = t (flat batch), without the flank fields
    (``normal_arm``, ``position``, ``normal`` are None; see :func:`_curve_fields`), sampled
    at the fractions ``frac`` (increasing from 0 to 1) of u between each curve's ends; the
    curves are first located on ``coarse_per_cell`` samples per grid cell along u
    (:func:`_coarse_runs`), their ends refined (:func:`_curve_ends`), the samples solved by
    Newton's method from the coarse curve and the minimum of ε refined
    (:func:`_lowest_point`)."""
    nb = t.size
    u0 = float(f.u[0])
    co = _coarse_runs(f, t, coarse_per_cell)
    # a curve shorter than the coarse step can fall between two samples: where the measure
    # peaks inside between them, that peak seeds it (a pair entering or leaving at a corner
    # of the region keeps its curve until the curve shrinks to nothing)
    short = _short_curves(f, t, co.u, co.v, co.have)
    if f.kernels is not None:  # the same steps below, compiled
        ks = f.kernel_splines
        up, vp, eps, ute, cu, cv, index = f.kernels.seed_places(
            ks.q, ks.margin, ks.eps, f.u, f.v, f.cell_ok,
            np.ascontiguousarray(t, dtype=float), np.ascontiguousarray(frac, dtype=float),
            co.u, co.v, co.have, co.start, co.stop,
            short.rows.astype(np.int64), short.u, short.v, short.lo, short.hi, _END_ITER)
        return ContactCurves(
            target=t, shift=np.zeros(nb), u=up, v=vp, ease_off_angle=eps,
            gap=np.where(np.isfinite(vp), 0.0, np.nan), normal_arm=None, position=None,
            normal=None, ute=ute, contact_u=cu, contact_v=cv, index=index)
    ua, ub = _curve_ends(f, t, co, short)
    up = ua[:, None] + (ub - ua)[:, None] * frac
    up_safe = np.where(np.isfinite(up), up, u0)
    vstart = np.full(up.shape, np.nan)
    hb = np.flatnonzero(co.have)
    if hb.size:
        vstart[hb] = _run_interpolation(co, hb, up_safe[hb])
    if short.rows.size:  # a short curve: Newton from its seed
        vstart[short.rows] = short.v[:, None]
        hb = np.r_[hb, short.rows]
    # only the curves that exist (Newton runs each point independently)
    vp = np.full(up.shape, np.nan)
    if hb.size:
        vp[hb] = f.solve_v(up_safe[hb], t[hb, None], v_start=vstart[hb])
    up = np.where(np.isfinite(vp), up, np.nan)
    fin = np.isfinite(vp)
    us, vs = np.where(fin, up, u0), np.where(fin, vp, f.v[0])
    eps = np.where(fin, f.eps.ev(us, vs), np.nan)
    ute, cu, cv, index = _lowest_point(f, t, up, vp, eps)
    return ContactCurves(
        target=t, shift=np.zeros(nb), u=up, v=vp, ease_off_angle=eps,
        gap=np.where(fin, 0.0, np.nan), normal_arm=None, position=None, normal=None, ute=ute,
        contact_u=cu, contact_v=cv, index=index)


def _coarse_runs(f: EaseOffFields, t: np.ndarray, coarse_per_cell: int) -> _Coarse:
    """The iso-lines Q = t on ``coarse_per_cell`` samples per grid cell along u, and the
    largest contiguous run of inside samples of each."""
    nb = t.size
    nc = coarse_per_cell * (len(f.u) - 1) + 1
    uc = np.linspace(float(f.u[0]), float(f.u[-1]), nc)
    vc = f.solve_columns(uc, t)
    if f.kernels is not None:  # the same runs, compiled
        have, start, stop = f.kernels.coarse_runs(f.kernel_splines.margin, f.u, f.v,
                                                  f.cell_ok, uc, vc)
        return _Coarse(uc, vc, have, start, stop)
    ok = f.inside(np.broadcast_to(uc, vc.shape), vc)
    # vectorised over the curves: a run starts where ok rises and ends before it falls;
    # argmax takes the first of equally long runs
    edge = np.diff(np.pad(ok, ((0, 0), (1, 1))).astype(np.int8), axis=1)
    col = np.arange(nc + 1)
    falls = np.where(edge == -1, col, nc + 1)
    run_end = np.minimum.accumulate(falls[:, ::-1], axis=1)[:, ::-1]  # first fall ≥ j
    length = np.where(edge == 1, run_end - col, 0)[:, :nc]
    have = length.max(axis=1, initial=0) > 0
    first = np.argmax(length, axis=1)
    start = np.where(have, first, -1)
    stop = np.where(have, first + length[np.arange(nb), first] - 1, -1)
    return _Coarse(uc, vc, have, start, stop)


def _curve_ends(f: EaseOffFields, t: np.ndarray, co: _Coarse, short: _ShortCurves):
    """Lengthwise places (ua, ub) (nb,) of the curves' ends (NaN where no curve).

    An end inside the grid lies between the last inside and the first outside coarse
    sample of its run, a short curve's between its seed and either bracket; each is found
    there on the continuous inside measure (:func:`_false_position_ends`).
    """
    uc, vc, have, start, stop = co
    nc = uc.size
    ua = np.where(have, uc[np.clip(start, 0, nc - 1)], np.nan)
    ub = np.where(have, uc[np.clip(stop, 0, nc - 1)], np.nan)
    lo_end = have & (start > 0)
    hi_end = have & (stop < nc - 1)
    s_rows = short.rows
    rows = np.r_[np.flatnonzero(lo_end), np.flatnonzero(hi_end), s_rows, s_rows]
    if rows.size:
        j_in = np.r_[start[lo_end], stop[hi_end]]
        j_out = np.r_[start[lo_end] - 1, stop[hi_end] + 1]
        a = np.r_[uc[j_in], short.u, short.u]
        b = np.r_[uc[j_out], short.lo, short.hi]
        va = np.r_[vc[rows[: j_in.size], j_in], short.v, short.v]
        a = _false_position_ends(f, t[rows], a, b, va)
        n_lo, n_hi, n_s = int(lo_end.sum()), int(hi_end.sum()), s_rows.size
        ua[rows[:n_lo]] = a[:n_lo]
        ub[rows[n_lo:n_lo + n_hi]] = a[n_lo:n_lo + n_hi]
        ua[s_rows] = a[n_lo + n_hi:n_lo + n_hi + n_s]
        ub[s_rows] = a[n_lo + n_hi + n_s:]
    return ua, ub


def _false_position_ends(f: EaseOffFields, t: np.ndarray, a: np.ndarray, b: np.ndarray,
                         va: np.ndarray) -> np.ndarray:
    """Ends of the iso-lines Q = t (M,) between an inside place a (profile place va) and an
    outside place b: false position (Illinois) on the continuous inside measure, bisection
    where the measure jumps (an outside place without an iso-line point or in a cell with
    an uncomputed corner: −1), :data:`_END_ITER` steps, fewer only if every end of the
    batch is then within 1e-9 of the face width. Jump ends are left within 2⁻¹¹–2⁻¹² of
    the coarse step, 3–6e-6 of the face width on the default grid (~0.1–0.2 µm); measured,
    45 % of a study point's ends at the default case's mounting are such (the rest within
    1e-9), 98 % of the transition search's at ΔE = −0.12, ΔP = −0.08 mm. Returns the last
    inside place of each (``a``, ``b``, ``va`` are updated in place). The NumPy path's;
    the compiled one is :func:`contact.utca.isoline_numba.false_position_ends`, called by
    :func:`contact.utca.isoline_numba.seed_places`."""
    ca = f.measure(a, va)
    cb = f.measure(b, f.solve_v(b, t, v_start=va))
    # the last step moved a (prev_in) or b (prev_out); updates in place (own arrays)
    prev_in = np.zeros(a.size, dtype=bool)
    prev_out = np.zeros(a.size, dtype=bool)
    for _ in range(_END_ITER):
        smooth = (cb > -0.5) & (ca < 0.5) & (cb != ca)
        m = np.where(smooth, b - cb * (b - a) / np.where(smooth, cb - ca, 1.0), 0.5 * (a + b))
        lo_m, hi_m = np.minimum(a, b), np.maximum(a, b)
        w = 1e-3 * (hi_m - lo_m)
        m = np.minimum(np.maximum(m, lo_m + w), hi_m - w)
        vm = f.newton_v(m, t, va.copy())
        cm = f.measure(m, vm)
        good = cm >= 0
        bad = ~good
        # Illinois: halve the value kept at the end that did not move twice running
        np.multiply(cb, 0.5, out=cb, where=good & prev_in & smooth)
        np.multiply(ca, 0.5, out=ca, where=bad & prev_out & smooth)
        np.copyto(a, m, where=good)
        np.copyto(ca, cm, where=good)
        np.copyto(va, vm, where=good)
        np.copyto(b, m, where=bad)
        np.copyto(cb, cm, where=bad)
        prev_in, prev_out = good, bad
        if np.all(np.abs(b - a) < 1e-9):
            break
    return a


def _run_interpolation(co: _Coarse, rows: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Profile places (M, n) at the places x of the curves ``rows`` (M,), interpolated
    linearly along each curve's run of coarse samples (ends held): ``np.interp`` of each
    run, vectorised over the curves (the same arithmetic: slope (y[j+1] − y[j]) /
    (x[j+1] − x[j]))."""
    uc = co.u
    s0, s1 = co.start[rows][:, None], co.stop[rows][:, None]
    j = np.clip(np.searchsorted(uc, x, side="right") - 1, s0, s1)
    jn = np.minimum(j + 1, s1)
    vrun = co.v[rows]
    yj = np.take_along_axis(vrun, j, 1)
    yn = np.take_along_axis(vrun, jn, 1)
    step = jn != j
    slope = (yn - yj) / np.where(step, uc[jn] - uc[j], 1.0)
    val = np.where(step & (uc[j] != x), slope * (x - uc[j]) + yj, yj)
    lo_v = np.take_along_axis(vrun, s0, 1)
    hi_v = np.take_along_axis(vrun, s1, 1)
    return np.where(x < uc[s0], lo_v, np.where(x >= uc[s1], hi_v, val))


def _lowest_point(f: EaseOffFields, t: np.ndarray, up: np.ndarray, vp: np.ndarray,
                  eps: np.ndarray):
    """The contact point H of each curve: the lowest ε along it (nb, n) [rad], refined by
    the vertex of the parabola through the lowest sample and its neighbours (held within
    half a step of the lowest, and kept only where ε is lower there).

    Returns (ute, contact_u, contact_v, index) (nb,): the UTE [rad], H's place, and the
    index of the lowest sample (-1 and NaN where there is no curve).
    """
    nb, n_point = up.shape
    fin = np.isfinite(vp)
    ute = np.full(nb, np.nan)
    cu = np.full(nb, np.nan)
    cv = np.full(nb, np.nan)
    index = np.full(nb, -1)
    rows = np.flatnonzero(fin.any(axis=1))
    if rows.size:
        e = np.where(fin[rows], eps[rows], np.inf)
        k = np.argmin(e, axis=1)
        index[rows] = k
        ute[rows] = e[np.arange(rows.size), k]
        cu[rows] = up[rows, k]
        cv[rows] = vp[rows, k]
        inner = (k > 0) & (k < n_point - 1)
        if inner.any():
            r, ki = rows[inner], k[inner]
            ur, vr, er = _parabola_vertex(f, t, up, vp, eps, r, ki)
            ec = eps[r, ki]
            better = np.isfinite(vr) & (er < ec)
            ute[r] = np.where(better, er, ec)
            cu[r] = np.where(better, ur, cu[r])
            cv[r] = np.where(better, vr, cv[r])
    return ute, cu, cv, index


def _parabola_vertex(f: EaseOffFields, t: np.ndarray, up: np.ndarray, vp: np.ndarray,
                     eps: np.ndarray, r: np.ndarray, k: np.ndarray):
    """Vertex of the parabola of ε through the samples k − 1, k, k + 1 (M,) of the curves
    r (M,) (steps h1, h2, equal or not), held within half a step of sample k.

    Returns its place (u, v) on the iso-line (v NaN where it misses) and ε there (inf
    where it misses).
    """
    em, ec, ep = eps[r, k - 1], eps[r, k], eps[r, k + 1]
    h1 = up[r, k] - up[r, k - 1]
    h2 = up[r, k + 1] - up[r, k]
    a1, a2 = em - ec, ep - ec
    den = 2 * (h2 * a1 + h1 * a2)
    okp = np.isfinite(den) & (den > 0)
    d = np.where(okp, (h2**2 * a1 - h1**2 * a2) / np.where(okp, den, 1.0), 0.0)
    ur = up[r, k] + np.clip(d, -0.5 * h1, 0.5 * h2)
    vr = f.solve_v(ur, t[r], v_start=vp[r, k])
    good = np.isfinite(vr)
    return ur, vr, np.where(good, f.eps.ev(ur, np.where(good, vr, f.v[0])), np.inf)


def _short_curves(f: EaseOffFields, t: np.ndarray, uc: np.ndarray, vc: np.ndarray,
                  have: np.ndarray) -> _ShortCurves:
    """Seeds of the curves that lie wholly between two coarse samples.

    For each curve without an inside coarse sample whose iso-line crosses the grid, the
    inside measure is maximised (successive grids, to ~2e-4 of the coarse step) between the
    neighbours of its best coarse sample; where the maximum is ≥ 0 the curve exists.

    Returns
    -------
    _ShortCurves
        ``rows`` (M,): the curves found; ``u``, ``v`` (M,): a place inside each (the
        maximum of the measure); ``lo``, ``hi`` (M,): the neighbouring coarse places
        (outside) bracketing each curve's ends.
    """
    empty = np.zeros(0)
    none = _ShortCurves(np.zeros(0, dtype=int), empty, empty, empty, empty)
    cand = np.flatnonzero(~have & np.any(np.isfinite(vc), axis=1))
    if cand.size == 0:
        return none
    nc = uc.size
    vcc = vc[cand]
    meas = f.measure(np.broadcast_to(uc, vcc.shape), vcc)
    best = np.argmax(meas, axis=1)
    near = np.max(meas, axis=1) > -0.5  # −1: undefined (no iso-line point in a good cell)
    cand, best, vcc = cand[near], best[near], vcc[near]
    if cand.size == 0:
        return none
    lo = uc[np.maximum(best - 1, 0)]
    hi = uc[np.minimum(best + 1, nc - 1)]
    tt = t[cand]
    v_best = vcc[np.arange(cand.size), best]
    v_best = np.where(np.isfinite(v_best), v_best, 0.5 * (f.v[0] + f.v[-1]))

    def minus_measure(rows, x):  # (M, n) places → −measure (the grid search minimises)
        n = x.shape[1]
        vx = f.newton_v(x.ravel(), np.repeat(tt[rows], n), np.repeat(v_best[rows], n))
        return -f.measure(x.ravel(), vx).reshape(-1, n)

    u_star, _ = _grid_minimum(minus_measure, lo, hi, uc[best], _SHORT_ITER)
    v_star = f.newton_v(u_star, tt, v_best.copy())
    m_star = f.measure(u_star, v_star)
    ok = m_star >= 0
    return _ShortCurves(cand[ok], u_star[ok], v_star[ok], lo[ok], hi[ok])


def _curve_fields(f: EaseOffFields, cc: ContactCurves) -> ContactCurves:
    """Normal arm, gear flank point and unit normal along the curves of ``cc``."""
    fin = np.isfinite(cc.v)
    us, vs = np.where(fin, cc.u, f.u[0]), np.where(fin, cc.v, f.v[0])
    val = f.values(("arm", "pos", "nrm"), us, vs)
    arm = np.where(fin, val[..., 0], np.nan)
    pos = np.where(fin[..., None], val[..., 1:4], np.nan)
    nrm = val[..., 4:7]
    nrm = np.where(fin[..., None], nrm / np.linalg.norm(nrm, axis=-1, keepdims=True), np.nan)
    return cc._replace(normal_arm=arm, position=pos, normal=nrm)


def _curves_seed(f: EaseOffFields, t: np.ndarray, frac: np.ndarray, *,
                 flank_fields: bool = True, near_misses: bool = False) -> ContactCurves:
    """Iso-lines Q = t (flat batch) and the minimum of ε along them (seed §2.3.2.2)."""
    if near_misses:
        raise InputError("near_misses: must be False with method 'seed' (it needs the "
                         "pinion's gap), got True")
    cc = _seed_places(f, t, frac)
    return _curve_fields(f, cc) if flank_fields else cc


def _curves_second_order(f: EaseOffFields, t: np.ndarray, frac: np.ndarray, *,
                         flank_fields: bool = True, near_misses: bool = False) -> ContactCurves:
    """The seed's curves corrected for the pinion's own gap to its conjugate.

    The pinion at roll q is separated from its conjugate at a gear place x by
    S ≈ ½ K(x) (Q(x) − q)² (K: ``EaseOff.gap_curvature``), so the real first contact is
    min over t of UTE_seed(q + t) + ½ K t²: with g = dUTE_seed/dq and t₀ = −g/K the
    iso-line Q = q + t₀ carries the contact point and UTE = UTE_seed(q + t₀) + ½ K t₀²
    (error O((t − t₀)²) since the function is stationary at its minimum). g is the ease-off
    derivative across the iso-line at H (envelope theorem), or the finite difference of
    UTE_seed where H is an end of the curve (edge contact). ``flank_fields=False`` skips
    the normal arm, flank point and normal (None), which the UTE does not need.
    ``near_misses=True`` also returns the curves of iso-lines Q = q that miss the contact
    region but whose shifted iso-line meets it (see :func:`_near_miss_curves`).
    """
    first = _seed_places(f, t, frac)
    base = np.zeros(t.size)
    if near_misses:
        first, base = _near_miss_curves(f, t, frac, first)
    have = np.isfinite(first.ute)
    cu = np.where(have, first.contact_u, f.u[0])
    cv = np.where(have, first.contact_v, f.v[0])
    g = _seed_slope(f, first, have, t + base, frac, cu, cv)
    k = f.gap_at(cu, cv)
    shift = np.where(have & (k > 0), -g / np.where(k > 0, k, 1.0), base)
    # (only where there is a curve to correct: elsewhere the shift is the base's and the
    # curve the first's)
    redo = np.flatnonzero(have)
    second = first
    if redo.size:
        second = _with_rows(first, redo, _seed_places(f, (t + shift)[redo], frac))
        second, shift = _safeguarded_step(f, t, frac, first, base, second, shift, redo)
    ok2 = np.isfinite(second.ute)
    # keep the first-order curve where the shifted one leaves the contact region
    use = ok2 | ~have
    shift = np.where(use, shift, base)
    cc = ContactCurves(
        *(None if a is None else np.where(use.reshape((-1,) + (1,) * (np.ndim(a) - 1)), a, b)
          for a, b in zip(second, first, strict=True)))
    if flank_fields:
        cc = _curve_fields(f, cc)
    fin = np.isfinite(cc.u)
    us = np.where(fin, cc.u, f.u[0])
    vs = np.where(fin, cc.v, f.v[0])
    gap = np.where(fin, 0.5 * f.gap_at(us, vs) * shift[:, None] ** 2, np.nan)
    return cc._replace(target=t, shift=shift, gap=gap, ute=_second_order_ute(f, cc, shift))


#: halvings of a second-order step that would raise the pair's UTE (_safeguarded_step)
_STEP_HALVINGS = 4


def _safeguarded_step(f: EaseOffFields, t: np.ndarray, frac: np.ndarray,
                      first: ContactCurves, base: np.ndarray, second: ContactCurves,
                      shift: np.ndarray, rows: np.ndarray):
    """The second-order curves of ``rows`` with every step that raises the cost halved.

    The step t₀ = −g/K of :func:`_curves_second_order` is one Newton step on
    c(t) = UTE_seed(q + t) + ½ K t² from the first-order curve (shift ``base``), with g
    the slope of UTE_seed at H. Where UTE_seed is not smooth — H at the start of a relief,
    where ε's profile slope jumps — the quadratic model fails and the step may land where
    c is higher than at its start: on the default case's 81 × 61 grid one leaving pair's
    step went to t = −35 mrad, c 126 µrad, where c was 104 at t = 0 and ≈ 98 near
    −6 mrad, a spike of 53 µrad in the 500 N·m LTE at one roll (issue 71, grid
    convergence). The real first contact is the minimum of c, so a step that raises it
    is no better estimate than its start: it is halved toward ``base`` (up to
    :data:`_STEP_HALVINGS` times) until c is not above the start's, else the first-order
    curve is kept (the step-halving safeguard of a Newton iteration; Nocedal & Wright,
    *Numerical Optimization*, 2nd ed., §3.1, sufficient decrease with a zero constant).

    Parameters
    ----------
    f : EaseOffFields
    t : ndarray (nb,) — [rad]
        The pairs' roll values.
    frac : ndarray (n_point,)
        Sample fractions along the curves.
    first : ContactCurves
        The first-order curves (iso-lines Q = t + ``base``).
    base : ndarray (nb,) — [rad]
        Their shifts.
    second : ContactCurves
        The curves of the full steps (iso-lines Q = t + ``shift``) at ``rows``.
    shift : ndarray (nb,) — [rad]
        The full steps' shifts.
    rows : int array
        The rows that have a first-order curve.

    Returns
    -------
    second : ContactCurves
        With the rows whose full step raised c replaced by a halved step's curve, or the
        first-order curve where no halving lowers c to the start's.
    shift : ndarray (nb,) — [rad]
        The shifts of those curves.

    Notes
    -----
    Rows whose full step does not raise c are returned unchanged (bit for bit).
    """
    c_first = _second_order_ute(f, first, base)
    c1 = _second_order_ute(f, second, shift)[rows]
    worse = rows[np.isfinite(c1) & (c1 > c_first[rows])]
    if worse.size == 0:
        return second, shift
    shift = shift.copy()
    step = shift[worse] - base[worse]
    todo = worse
    for _ in range(_STEP_HALVINGS):
        step = 0.5 * step
        trial_shift = base[todo] + step
        trial = _seed_places(f, t[todo] + trial_shift, frac)
        c = _second_order_ute(f, trial, trial_shift)
        ok = np.isfinite(c) & (c <= c_first[todo])
        if ok.any():
            second = _with_rows(second, todo[ok], _take(trial, np.flatnonzero(ok)))
            shift[todo[ok]] = trial_shift[ok]
        todo, step = todo[~ok], step[~ok]
        if todo.size == 0:
            break
    if todo.size:
        second = _with_rows(second, todo, _take(first, todo))
        shift[todo] = base[todo]
    return second, shift


def _second_order_ute(f: EaseOffFields, cc: ContactCurves, shift: np.ndarray) -> np.ndarray:
    """c(t) = UTE_seed(q + t) + ½ K t² [rad] of the curves ``cc`` drawn at the shifts
    ``shift`` (nb,) [rad]: the pair's second-order UTE (K at each curve's contact point,
    :func:`_gap_at_contact`), the cost :func:`_safeguarded_step` compares."""
    return cc.ute + 0.5 * _gap_at_contact(f, cc) * shift ** 2


def _take(cc: ContactCurves, rows: np.ndarray) -> ContactCurves:
    """The curves ``rows`` of the batch ``cc`` (every field's first axis)."""
    return ContactCurves(*(None if a is None else np.asarray(a)[rows] for a in cc))


def _near_miss_curves(f: EaseOffFields, t: np.ndarray, frac: np.ndarray,
                      first: ContactCurves):
    """The first-order curves with those of the near misses, and the base shifts (nb,).

    Where the iso-line Q = q misses the contact region (a pair just leaving or entering at
    a corner), the real pinion may still touch it through its gap: the iso-line
    Q = q + t_b nearest in that sense (min of UTE_seed + ½ K t_b², by probing,
    :func:`_probe_shift`) is the first-order curve from which the correction starts.
    """
    base = np.zeros(t.size)
    lost = np.flatnonzero(~np.isfinite(first.ute))
    if lost.size:
        rows, t_b = _probe_shift(f, t[lost])
        if rows.size:
            rows = lost[rows]
            base[rows] = t_b
            first = _with_rows(first, rows, _seed_places(f, t[rows] + t_b, frac))
    return first, base


def _seed_slope(f: EaseOffFields, first: ContactCurves, have: np.ndarray, t: np.ndarray,
                frac: np.ndarray, cu: np.ndarray, cv: np.ndarray) -> np.ndarray:
    """g = dUTE_seed/dq [1] of the first-order curves ``first`` of the iso-lines Q = t at
    their contact points H (cu, cv) (nb,).

    The ease-off derivative across the iso-line at H, (∇ε·∇Q)/|∇Q|² (envelope theorem);
    where H is an end of its curve, the slope along the region's boundary
    (:func:`_end_slope`), or at a corner of the region or a masked cell's edge the central
    difference of UTE_seed (step 1e-5 rad).
    """
    n_point = frac.size
    qu, qv = f.q.ev(cu, cv, dx=1), f.q.ev(cu, cv, dy=1)
    eu, ev = f.eps.ev(cu, cv, dx=1), f.eps.ev(cu, cv, dy=1)
    g = (eu * qu + ev * qv) / (qu * qu + qv * qv)
    edge = np.flatnonzero(have & ((first.index == 0) | (first.index == n_point - 1)))
    if edge.size:
        # H at an end of its curve: UTE_seed = ε at the end, which slides along the
        # region's boundary as q changes: g = (∇ε·b)/(∇Q·b), b the boundary's direction
        at_lo = first.index[edge] == 0
        g_end, smooth = _end_slope(f, np.where(at_lo, first.u[edge, 0], first.u[edge, -1]),
                                   np.where(at_lo, first.v[edge, 0], first.v[edge, -1]))
        g[edge[smooth]] = g_end[smooth]
        rest = edge[~smooth]
        if rest.size:
            # at a corner of the region or a masked cell's edge: by finite differences
            h = 1e-5
            te = t[rest]
            pair = _seed_places(f, np.r_[te + h, te - h], frac).ute
            fd = (pair[: te.size] - pair[te.size:]) / (2 * h)
            g[rest] = np.where(np.isfinite(fd), fd, g[rest])
    return g


def _end_slope(f: EaseOffFields, u: np.ndarray, v: np.ndarray):
    """dUTE_seed/dq [1] where the contact point H is the curve's end (u, v) (M,).

    The end lies on the region's boundary, the zero set of the active term of
    :meth:`EaseOffFields.measure` (the pinion-blank margin, or a grid limit in u or v); as q
    changes it slides along that boundary, direction b (the margin's level line, or the
    grid line), so dε/dq = (∇ε·b)/(∇Q·b): the exact derivative of the model, where a
    finite difference of UTE_seed would divide the end search's resolution (bisection to
    ~3e-6 in u where the iso-line runs off the grid's tip or root) by the step.
    Returns (g, smooth): ``smooth`` False where the end is not on one smooth boundary
    piece (a corner: the second term within 1e-3; a masked cell's edge: the measure not
    within 1e-4 of zero; or the iso-line nearly tangent to the boundary), for the
    caller's finite differences.
    """
    vs = np.clip(v, f.v[0], f.v[-1])
    terms = f.measure_terms(u, vs)  # (5, M)
    order = np.argsort(terms, axis=0)
    k, k2 = order[0], order[1]
    idx = np.arange(u.size)
    c, c2 = terms[k, idx], terms[k2, idx]
    mu, mv = f.margin.ev(u, vs, dx=1), f.margin.ev(u, vs, dy=1)
    bu = np.where(k == 0, -mv, np.where(k <= 2, 1.0, 0.0))  # along the active boundary
    bv = np.where(k == 0, mu, np.where(k <= 2, 0.0, 1.0))
    qu, qv = f.q.ev(u, vs, dx=1), f.q.ev(u, vs, dy=1)
    eu, ev = f.eps.ev(u, vs, dx=1), f.eps.ev(u, vs, dy=1)
    den = qu * bu + qv * bv
    smooth = (np.isfinite(v) & f.good_cell(u, vs) & (np.abs(c) < 1e-4) & (c2 > 1e-3)
              & (np.abs(den) > 1e-3 * np.hypot(qu, qv) * np.hypot(bu, bv)))
    return (eu * bu + ev * bv) / np.where(smooth, den, 1.0), smooth


#: [pitch] largest iso-line shift sought for a pair whose iso-line misses the contact
#: region: beyond it the pinion's own gap ½ K t² is some hundred µrad (no load reaches it)
_MAX_SHIFT = 1.0 / 8.0


_SHORT_ITER = 4  # grids locating a short curve: 8^-4 ≈ 2e-4 of two coarse steps


_REFINE_POINTS, _REFINE_ITER = 17, 4  # grids refining the shift: 8^-4 ≈ 2e-4 of the first


def _probe_shift(f: EaseOffFields, t: np.ndarray, phase: float = 0.0):
    """Iso-line shifts t_b for roll values whose iso-line Q = t misses the contact region.

    The shift minimises UTE_seed(t + t_b) + ½ K t_b² (K > 0 at the contact point). It is
    first located on the ease-off nodes of the region, min over nodes of ε + ½ K (Q − t)²,
    kept where |t_b| ≤ :data:`_MAX_SHIFT` pitches, then refined on the curves themselves
    by successive grids (the cost is infinite where the iso-line misses: the minimum often
    sits where it starts to meet a corner of the region), so that t_b varies continuously
    with t. ``phase`` [1] moves the grids' places by that share of the last grid's step
    (default 0; the shifts found do not depend on it to 1e-12 rad, :func:`_feasible_edge`).

    Returns
    -------
    rows : int array (M,)
        Indices into ``t`` for which the shifted iso-line meets the region.
    t_b : array (M,) — [rad]
        The shift of each.
    """
    eo = f.eo
    p = eo.pitch
    node = eo.valid & np.isfinite(eo.gap_curvature) & (eo.gap_curvature > 0)
    if not np.any(node):
        return np.zeros(0, dtype=int), np.zeros(0)
    q_n = eo.raw_roll_angle[node]
    e_n = eo.raw_ease_off_angle[node]
    k_n = eo.gap_curvature[node]
    node_cost = e_n[None, :] + 0.5 * k_n[None, :] * (q_n[None, :] - t[:, None]) ** 2
    best = np.argmin(node_cost, axis=1)
    d0 = q_n[best] - t
    cand = np.flatnonzero(np.abs(d0) <= _MAX_SHIFT * p)
    if cand.size == 0:
        return cand, np.zeros(0)
    # first bracket: two steps of Q between neighbouring nodes either side
    q = np.where(eo.valid, eo.raw_roll_angle, np.nan)
    dq = np.nanmax(np.abs(np.r_[np.diff(q, axis=0).ravel(), np.diff(q, axis=1).ravel()]))
    frac = CURVE_SPACINGS["uniform"](9)

    def cost(tc, dd):
        """UTE_seed(t + d) + ½ K d² (inf where the iso-line misses the region or K ≤ 0)."""
        # (located on one coarse sample per cell: the shifted curve found is computed
        # again at full resolution). Each distinct iso-line once: the grids of rows whose
        # node is the same share many (a third of them on the default case); every curve
        # is computed independently of the others in its batch, so its values are the same
        tt, back = np.unique(tc + dd, return_inverse=True)
        pr = _seed_places(f, tt, frac, coarse_per_cell=1)
        back = back.ravel()
        k = _gap_at_contact(f, pr)[back]
        c = np.where(k > 0, pr.ute[back] + 0.5 * k * dd**2, np.nan)
        return np.where(np.isfinite(c), c, np.inf)

    tb = t[cand]

    def grid_cost(rows, x):
        return cost(np.repeat(tb[rows], x.shape[1]), x.ravel()).reshape(x.shape)

    # the last grid's step (the bracket 4 dq narrowed by 2/(n - 1) at each pass)
    step = 4 * dq * (2 / (_REFINE_POINTS - 1)) ** (_REFINE_ITER - 1) / (_REFINE_POINTS - 1)
    mid = d0[cand] + phase * step
    d_star, found = _grid_minimum(grid_cost, mid - 2 * dq, mid + 2 * dq, mid, _REFINE_ITER)
    d_star = _feasible_edge(grid_cost, d_star, found, step)
    return cand[found], d_star[found]


#: [rad] the feasibility edge of a shift is located to this (_feasible_edge)
_EDGE_TOL = 1e-12


def _feasible_edge(grid_cost, x: np.ndarray, found: np.ndarray, step: float) -> np.ndarray:
    """The grid minima ``x`` (M,) [rad] moved onto the edge of their feasible set where
    that edge lies within one grid ``step`` [rad] of them and is cheaper.

    The cost of a shift is infinite where its iso-line misses the contact region, and its
    minimum often sits where the iso-line starts to meet a corner (:func:`_probe_shift`).
    A grid then finds the first feasible place beyond that edge, up to a step away, or the
    edge itself where a node lies on it (an iso-line through the corner, met at one point
    or not with the round-off of the ease-off): the shift jumped by up to a step (1.8e-5
    rad, a 1 µm curve at the miter 20x20's gear tip, 2.7e-7 rad of its pair's UTE, the
    edge segments moved by µm; issue 71). Where the neighbour a step away is infeasible
    the edge between them is located to :data:`_EDGE_TOL` by sections of
    :data:`_REFINE_POINTS` places and kept where its cost is not above the grid's: the
    shift then follows the edge continuously, whichever side of it the grid's places fall.

    Parameters
    ----------
    grid_cost : callable (rows (M,), x (M, n) [rad]) -> (M, n)
        The cost UTE_seed + ½ K x² [rad] of each row's shifts, ``inf`` where infeasible.
    x : ndarray (M,) — [rad]
        The grid minima.
    found : ndarray (M,) of bool
        Whether each row's grid saw a finite cost (the others are returned as given).
    step : float — [rad]
        The last grid's step.

    Returns
    -------
    ndarray (M,) — [rad]
        The shifts: on the feasible edge where it lies within a step and is cheaper.

    Notes
    -----
    Source: the shift's minimisation, :func:`_probe_shift` (the seed's second-order
    contact through the pinion's gap ½ K t², continued to pairs entering at a corner).
    """
    rows = np.flatnonzero(found)
    if rows.size == 0 or not step > 0:
        return x
    xs = x[rows]
    c = grid_cost(rows, np.stack([xs - step, xs, xs + step], axis=1))
    out_lo, out_hi = ~np.isfinite(c[:, 0]), ~np.isfinite(c[:, 2])
    edge = np.isfinite(c[:, 1]) & (out_lo != out_hi)
    if not edge.any():
        return x
    r = rows[edge]
    inside = xs[edge]
    outside = np.where(out_lo[edge], inside - step, inside + step)
    # by sections of _REFINE_POINTS places (one batch of curves each: 7 passes for a step
    # of 1.8e-5 rad, where halving took 25 batches, 20 % dearer in all)
    frac = np.linspace(0.0, 1.0, _REFINE_POINTS)[None, 1:-1]
    n = _REFINE_POINTS - 1
    for _ in range(int(np.ceil(np.log(step / _EDGE_TOL) / np.log(n)))):
        x_mid = outside[:, None] + (inside - outside)[:, None] * frac  # outside → inside
        ok = np.isfinite(grid_cost(r, x_mid))
        # the first feasible place from the outside (the set is one-sided within a step)
        j = np.where(ok.any(axis=1), np.argmax(ok, axis=1), n - 1)
        hit = ok.any(axis=1)
        new_in = np.where(hit, x_mid[np.arange(r.size), np.minimum(j, n - 2)], inside)
        # (no hit: j = n - 1, so the new outside is the last place, x_mid[:, -1])
        new_out = np.where(j > 0, x_mid[np.arange(r.size), np.maximum(j - 1, 0)], outside)
        inside, outside = new_in, new_out
    better = grid_cost(r, inside[:, None])[:, 0] <= c[edge, 1]
    x = x.copy()
    x[r[better]] = inside[better]
    return x


def _grid_minimum(func, lo: np.ndarray, hi: np.ndarray, start: np.ndarray, iterations: int):
    """Minimum of a function of one variable per row by successive grids.

    Each pass evaluates ``func(rows, x)`` on :data:`_REFINE_POINTS` equally spaced places
    x (M, n) of every row's bracket [lo, hi] and narrows the bracket to the best place ±
    one step, i.e. to 2/(n − 1) of itself (robust where the function is infinite over
    parts of the bracket, as where an iso-line misses the contact region). Rows whose
    values are all infinite keep their bracket and ``start``.

    Returns
    -------
    x : array (M,)
        The best place of each row.
    found : bool array (M,)
        Whether a finite value was seen.
    """
    n = _REFINE_POINTS
    x_star = np.array(start, dtype=float)
    found = np.zeros(x_star.size, dtype=bool)
    rows = np.arange(x_star.size)
    for _ in range(iterations):
        x = lo[:, None] + (hi - lo)[:, None] * np.linspace(0.0, 1.0, n)[None, :]
        c = func(rows, x)
        i = np.argmin(c, axis=1)
        fin = np.isfinite(c[rows, i])
        found |= fin
        x_star = np.where(fin, x[rows, i], x_star)
        step = (hi - lo) / (n - 1)
        lo, hi = np.where(fin, x_star - step, lo), np.where(fin, x_star + step, hi)
    return x_star, found


def _gap_at_contact(f: EaseOffFields, cc: ContactCurves) -> np.ndarray:
    """The pinion's gap curvature K [1/rad] at each curve's contact point H (at the
    grid's first node where a curve has none; its UTE is NaN there anyway)."""
    hu = np.where(np.isfinite(cc.contact_u), cc.contact_u, f.u[0])
    hv = np.where(np.isfinite(cc.contact_v), cc.contact_v, f.v[0])
    return f.gap_at(hu, hv)


def _with_rows(cc: ContactCurves, rows: np.ndarray, sub: ContactCurves) -> ContactCurves:
    """A copy of the curves ``cc`` with the curves ``sub`` in the places ``rows``."""

    def put(a, b):
        if a is None:
            return None
        out = np.array(a, copy=True)
        out[rows] = b
        return out

    return ContactCurves(*(put(a, b) for a, b in zip(cc, sub, strict=True)))


#: spacings of the samples along a contact curve: name → fractions (n,) of the u-span
#: between the curve's ends, from 0 to 1
CURVE_SPACINGS: dict[str, Callable[[int], np.ndarray]] = {
    "uniform": lambda n: np.linspace(0.0, 1.0, n),
    "cosine": lambda n: 0.5 * (1.0 - np.cos(np.pi * np.arange(n) / (n - 1))),
}


#: UTE methods: name → contact curves of a flat batch of roll targets (sampled at the
#: fractions of a :data:`CURVE_SPACINGS` entry)
UTE_METHODS: dict[str, Callable[..., ContactCurves]] = {
    "seed": _curves_seed,
    "second_order": _curves_second_order,
}


def contact_curves(eo: EaseOff, target, *, method: str = "second_order", n_point: int = 41,
                   fields: EaseOffFields | None = None, spacing: str = "uniform",
                   near_misses: bool = False) -> ContactCurves:
    """Instantaneous contact curves and the UTE of tooth pairs (seed §2.3.2.2, §4.4).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    target : array_like — [rad]
        Roll values q (Q units, driving sense; any shape ``batch``); the pair k at roll r
        has q = r − k·pitch.
    method : str
        ``"seed"``: the iso-line Q = q and the minimum of ε along it (the seed's method,
        first order); ``"second_order"`` (default): corrected for the pinion's own
        separation from its conjugate (see :data:`UTE_METHODS`).
    n_point : int
        Samples along each curve (≥ 3), between the curve's ends.
    fields : optional
        Pre-built splines (internal reuse).
    spacing : str
        Placing of the samples in u between the ends (see :data:`CURVE_SPACINGS`):
        ``"uniform"`` (default) or ``"cosine"`` (Chebyshev–Lobatto: steps ~ π²/(4 n²) of
        the span at the ends, π/(2n) in the middle), which resolves load rising into a
        flank edge (the LTCA's segments).
    near_misses : bool
        Also the curves of pairs whose iso-line Q = q misses the contact region while the
        real pinion, through its own gap ½ K t², still comes within some hundred µrad of
        it (a pair entering or leaving at a corner of the flank; ``"second_order"`` only):
        their iso-line is shifted by the t that minimises UTE_seed(q + t) + ½ K t², so
        their curve, separation and UTE vary continuously with q. Default False: such a
        pair is out of mesh (NaN), the seed's convention for the UTCA; the LTCA sets it,
        so that the load of a leaving pair fades instead of vanishing.

    Returns
    -------
    ContactCurves

    Raises
    ------
    InputError
        For ``n_point`` < 3, non-finite targets, an unknown method or spacing (the
        message lists the accepted ones).
    ModelUnavailableError
        If Q is not monotone along the profile direction.

    Notes
    -----
    Seed §2.3.2.2: intersection of the plane z = q with Q, projected onto the projection
    plane and then onto the ease-off; its lowest point H gives the UTE.
    """
    tgt, f = _checked(eo, target, method, n_point, fields)
    one_of("spacing", spacing, CURVE_SPACINGS)
    batch = tgt.shape
    cc = UTE_METHODS[method](f, tgt.reshape(-1), CURVE_SPACINGS[spacing](int(n_point)),
                             near_misses=near_misses)
    return ContactCurves(*(np.reshape(a, batch + np.shape(a)[1:]) for a in cc))


def _checked(eo: EaseOff, target, method: str, n_point: int, fields: EaseOffFields | None):
    """Validated roll targets (float array) and the splines, for :func:`contact_curves`."""
    one_of("method", method, UTE_METHODS)
    integer("n_point", n_point, low=3)
    tgt = real_array("target", target, unit="rad")
    return tgt, (fields if fields is not None else EaseOffFields(eo))


def pair_transmission_error(eo: EaseOff, roll, *, method: str = "second_order",
                            fields: EaseOffFields | None = None, n_point: int = 41) -> np.ndarray:
    """UTE of the reference tooth pair at roll values.

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    roll : array_like — [rad]
        Roll values (Q units, driving sense).
    method : str
        See :func:`contact_curves`.
    n_point : int
        Samples per curve.

    Returns
    -------
    ndarray — [rad]
        Gear lag (NaN where the pair is out of mesh).

    Raises
    ------
    InputError
        As :func:`contact_curves`.
    """
    tgt, f = _checked(eo, roll, method, n_point, fields)
    # the UTE only: the flank point, normal and arm along the curves are not evaluated
    cc = UTE_METHODS[method](f, tgt.reshape(-1), CURVE_SPACINGS["uniform"](int(n_point)),
                             flank_fields=False)
    return cc.ute.reshape(tgt.shape)
