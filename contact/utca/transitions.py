"""The transition points of the unloaded mesh: where the next tooth pair takes over.

Between two consecutive pairs the unloaded transmission error passes from one pair's TE
curve to the next's where they cross (seed §4.4, the UTE is the minimum over the pairs):
the roll of each crossing is bracketed on a scan of the pair difference over one mesh
cycle and refined by a bracketing search on batches of rolls, each batch one
contact-curve evaluation (:func:`transitions`). The LTCA's mesh cycle starts at these
rolls (:mod:`contact.ltca.mesh_cycle`).

M1 (pair −1 hands over to pair 0) and M2 (pair 0 to pair +1) are one handover a pitch
apart: the difference of pair 0 and pair +1 at roll x is minus that of pair −1 and pair 0
at x − pitch, so M2's bracket is M1's shifted by the pitch.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from contact.utca.contact_curves import pair_transmission_error
from contact.utca.easeoff import EaseOff
from contact.utca.fields import EaseOffFields, fields_of
from geometry.core.caches import Same, memoised
from geometry.core.validation import integer

__all__ = [
    "cycle_transitions",
    "transitions",
]

log = logging.getLogger(__name__)


def transitions(eo: EaseOff, *, method: str = "second_order", fields: EaseOffFields | None = None,
                n_point: int = 41, samples: int = 8) -> tuple[float, float]:
    """Rolls M1, M2 bounding the reference pair's share of the lower envelope (seed Fig. 2.9).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    method : str
        See :func:`contact_curves`.
    n_point : int
        Samples per contact curve.
    samples : int
        Roll samples per mesh cycle used to bracket each transition (≥ 4).

    Returns
    -------
    (M1, M2) : (float, float) — [rad]
        M1: pair −1 hands over to pair 0; M2: pair 0 hands over to pair +1. Starting from
        the roll of the lowest ease-off node, the first sample where the neighbour is lower
        (or pair 0 leaves the contact region) brackets each transition, which is then solved
        to 1e-12 rad at a crossing of the two UTE curves or a jump of their difference (a
        batched bracketing search, :func:`_batched_search`), or, where a pair leaves the
        contact region first (the lower envelope then jumps) or the difference changes sign
        more than once in the bracket, by false position (Illinois) and bisection to
        1e-8 rad as before the batched search (:func:`_sequential_search`). If the
        lowest node's pair does not carry the motion at its roll (a misalignment can move
        the contact away), the scan starts again from the nearest sampled roll where it
        does. NaN if pair 0 never carries the motion or is still the lowest two cycles
        away.

    Raises
    ------
    InputError
        For ``samples`` < 4 (and as :func:`contact_curves`).
    """
    samples = integer("samples", samples, low=4)
    h = _PairDifference(eo, fields if fields is not None else EaseOffFields(eo), method,
                        n_point)
    p = eo.pitch
    # start where the ease-off is lowest: the reference pair carries the motion there
    i0 = np.nanargmin(np.where(eo.valid, eo.ease_off_angle, np.nan))
    r_star = float(eo.roll_angle.ravel()[i0])
    u_all = _roll_scan(h, r_star, samples)
    x, hx = _scan_brackets(u_all, r_star, p, samples)
    if np.any(hx[:, 0] > 0):
        # the lowest node's pair does not carry the motion there (a misalignment can move
        # the contact off it): start again from the nearest scanned roll where it does
        m = _nearest_carrying(u_all, samples)
        if m is None:
            log.warning("transitions: the reference pair does not carry the motion near "
                        "the lowest ease-off point")
            return math.nan, math.nan
        r_star += float(m) * p / samples
        u_all = _roll_scan(h, r_star, samples)
        x, hx = _scan_brackets(u_all, r_star, p, samples)
        if np.any(hx[:, 0] > 0):
            log.warning("transitions: the reference pair does not carry the motion at the "
                        "lowest ease-off point")
            return math.nan, math.nan
    return _solve_transitions(h, x, hx)


def cycle_transitions(eo: EaseOff) -> tuple[float, float]:
    """The transitions M1, M2 [rad] the loaded TCA's mesh cycle starts from
    (:func:`contact.ltca.loaded_tca` where it is given none): :func:`transitions` of ``eo``
    with its defaults on the ease-off's shared splines (:func:`contact.utca.fields.fields_of`,
    the splines the LTCA's segment geometry then reads, as the unloaded cycle shares them
    in :func:`contact.pipeline.run_analysis`), memoised per process by the ease-off object.

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
        Compared by identity (as :func:`contact.utca.fields.fields_of`): the analyses of
        one ease-off object at several torques (the development's trials of one design
        analysed again at another torque, the ease-off kept by
        :class:`contact.optimize.development_evaluate.KeptTeeth`; its check at two
        torques from the ease-off memo) search the transitions once (issue 75: ≈ 14 ms
        of a coarse development LTCA, on the passenger-car hypoid 10x43).

    Returns
    -------
    (M1, M2) : (float, float) — [rad]
        As :func:`transitions`.

    Raises
    ------
    InputError, ModelUnavailableError
        As :func:`transitions` and :class:`contact.utca.fields.EaseOffFields`.

    Notes
    -----
    Source: seed §2.3.2.2, Fig. 2.9 (:func:`transitions`). The memo and the shared splines
    change no number: the transitions are a function of the ease-off alone (its splines,
    no envelope solve), and the splines' lazily formed parts are the same arithmetic
    whoever asks first (:func:`contact.utca.fields.fields_of`); tested bit for bit against
    :func:`transitions` on its own splines (tests/test_transitions.py).
    """
    return _memo_cycle_transitions(Same(eo))


@memoised(maxsize=32)
def _memo_cycle_transitions(eo: Same) -> tuple[float, float]:
    """:func:`transitions` of ``eo.obj`` on its shared splines, memoised per process by
    the ease-off object (:func:`cycle_transitions`): 32 entries, so that the designs of
    a development's coast flank (at most ``coast_max_evaluations``, 20 by default) are
    all still there when it is developed again (each entry holds its ease-off,
    ≈ 0.2 MB)."""
    return transitions(eo.obj, fields=fields_of(eo.obj))


#: value of the UTE difference of two pairs where one is out of mesh (:class:`_PairDifference`)
_OUT_OF_MESH = 1.0


_TRANSITION_ITER = 80  # false-position steps on a transition


@dataclass(frozen=True)
class _PairDifference:
    """UTE₀(x) − UTE_k(x) of the reference pair and its neighbour k at rolls x [rad]: ≤ 0
    while pair 0 is the lower; ±:data:`_OUT_OF_MESH` where one is out of mesh (+ where
    pair 0 is)."""

    eo: EaseOff
    fields: EaseOffFields
    method: str
    n_point: int

    def ute(self, roll) -> np.ndarray:
        """UTE [rad] of the reference pair at rolls ``roll`` (NaN: out of mesh)."""
        return pair_transmission_error(self.eo, roll, method=self.method, fields=self.fields,
                                       n_point=self.n_point)

    def __call__(self, x, k) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        k = np.asarray(k, dtype=float)
        u = self.ute(np.stack([x, x - k * self.eo.pitch]))
        out = u[0] - u[1]
        out = np.where(np.isnan(u[1]), -_OUT_OF_MESH, out)
        return np.where(np.isnan(u[0]), _OUT_OF_MESH, out)


def _roll_scan(h: _PairDifference, r_star: float, samples: int) -> np.ndarray:
    """UTE₀ [rad] at r* + m·p/samples, m = −2·samples … 2·samples: one scan serves both
    directions and both neighbours (pair k at r is UTE₀(r − k·p), a shift by samples)."""
    m_all = np.arange(-2 * samples, 2 * samples + 1)
    return h.ute(r_star + m_all * h.eo.pitch / samples)


def _scan_brackets(u_all: np.ndarray, r_star: float, p: float, samples: int):
    """Rolls x (2, 2·samples + 1) [rad] from r* towards M1 (row 0) and M2 (row 1), one
    cycle each way, and the UTE difference of pair 0 and its neighbour there (as
    :class:`_PairDifference`), from the scan :func:`_roll_scan`."""

    def h_scan(k):
        j = np.arange(2 * samples + 1)
        own = u_all[2 * samples + k * j]
        other = u_all[2 * samples + k * j - k * samples]
        out = np.where(np.isnan(other), -_OUT_OF_MESH, own - other)
        return r_star + k * j * p / samples, np.where(np.isnan(own), _OUT_OF_MESH, out)

    x, hx = (np.stack(a) for a in zip(*(h_scan(k) for k in (-1, 1)), strict=True))
    return x, hx


def _nearest_carrying(u_all: np.ndarray, samples: int):
    """The scan offset m (|m| ≤ samples) nearest to 0 at which pair 0 is below both
    neighbours (a neighbour out of mesh counts as higher), or None."""
    m = np.arange(-samples, samples + 1)
    own = u_all[2 * samples + m]
    carried = (np.isfinite(own) & ~(own > u_all[2 * samples + m + samples])
               & ~(own > u_all[2 * samples + m - samples]))
    if not carried.any():
        return None
    return m[carried][np.argmin(np.abs(m[carried]))]


def _solve_transitions(h: _PairDifference, x: np.ndarray, hx: np.ndarray):
    """(M1, M2) [rad]: the first sample of each scan row where the neighbour is lower
    brackets the transition (NaN where the row has none).

    Where the brackets' ends are smooth (both pairs in mesh), the batched search
    (:func:`_batched_search`) solves M1 to 1e-12 rad, and M2 is the same handover one
    pitch later (module docstring), taken from M1's bracket where the scan bracketed the
    same handover (else solved alike). Where a bracket has an end out of mesh, or the
    batched search finds the difference changing sign more than once in a bracket (an
    irregular UTE, at extreme misalignments), both are solved as before the batched search
    (:func:`_sequential_search`), whose choice (among several crossings; within 1e-8 rad of
    where a pair leaves the mesh) this toolkit has always given.
    """
    big = _OUT_OF_MESH
    found = np.any(hx > 0, axis=1)
    j = np.where(found, np.argmax(hx > 0, axis=1), 1)
    rows = np.arange(2)
    a, fa = x[rows, j - 1], hx[rows, j - 1]
    b, fb = x[rows, j], hx[rows, j]
    smooth = (np.abs(fa) < big) & (np.abs(fb) < big)
    if np.all(smooth | ~found):
        res = np.full(2, np.nan)
        todo = found.copy()
        for r, k in ((0, -1.0), (1, 1.0)):
            if not todo[r]:
                continue
            ends = _batched_search(h, a[r], fa[r], b[r], fb[r], k)
            if ends is None:  # several crossings: the sequential search's choice
                break
            res[r] = ends[0]
            # pair 0 takes over from pair −1 where pair +1 takes over from pair 0 one
            # pitch later: h(x, +1) = −h(x − p, −1), so M2's bracket is M1's shifted by
            # the pitch (its pair-0 side M1's other end), where the scan bracketed the
            # same handover
            shifted = ends[1] + h.eo.pitch
            if r == 0 and todo[1] and min(a[1], b[1]) <= shifted <= max(a[1], b[1]):
                res[1] = shifted
                todo[1] = False
        else:
            return float(res[0]), float(res[1])
    res = np.where(found, _sequential_search(h, a, fa, b, fb, found), np.nan)
    return float(res[0]), float(res[1])


_BATCH = 12  # rolls per round of the batched search
_GUARDS = 3  # of which spread over the whole bracket when the others close in on the root
_TRANSITION_TOL = 1e-12  # [rad] the batched search's bracket
#: [rad] sign changes of the difference that all lie within this of each other are
#: round-off, not a second crossing (|h| ~ 1e-19 to 1e-17 rad within ~1e-14 rad of a
#: crossing, measured; the rolls closing in on an estimated root can sit there while the
#: bracket is still wider: the default case at ΔE = ΔP = −0.12 mm on the ease-off's
#: corner-aware interpolant, issue 71)
_NOISE_WIDTH = 1e-10


def _batched_search(h: _PairDifference, a: float, fa: float, b: float, fb: float,
                    k: float) -> tuple[float, float]:
    """The transition of one scan row by a bracketing search on batches of rolls.

    Parameters
    ----------
    h : _PairDifference
    a, fa : float — [rad], [rad]
        The bracket's end on the reference pair's side (fa ≤ 0: pair 0 the lower) …
    b, fb : float
        … and on the neighbour's (fb > 0).
    k : float
        The neighbour (−1 or +1).

    Returns
    -------
    (a, b) : (float, float) — [rad], or None
        The final bracket, |b − a| < 1e-12 rad: ``a`` the last roll on the reference
        pair's side (M1 or M2), ``b`` the first on the neighbour's. None where a round
        finds the difference changing sign more than once in the bracket, the changes
        farther apart than :data:`_NOISE_WIDTH` (closer: round-off): the transition
        is then left to :func:`_sequential_search`, whose choice among the crossings
        (the one its false position runs into) is this toolkit's.

    Notes
    -----
    Each round evaluates the UTE difference at :data:`_BATCH` rolls inside the bracket in
    one batch (one contact-curve evaluation of 2 × :data:`_BATCH` curves costs little more
    than one of two: its cost is mostly per call) and keeps the first sub-interval, from
    the reference pair's side, where the sign changes (the scan's rule). Where the
    difference is smooth across the bracket (both ends of both pairs in mesh, and the
    slope across the bracket within four times that of the neighbouring sub-intervals),
    the rolls close in on the root estimated by inverse quadratic interpolation, in a
    window four times the distance between that estimate and the secant's, with
    :data:`_GUARDS` rolls spread over the bracket; otherwise (the difference jumps where
    the second-order curve of a pair leaves the contact region, or a pair leaves the
    mesh) the rolls divide the bracket evenly. A jump is thus bracketed to 1e-12 rad in
    about ten rounds, a smooth crossing in three; false position (Illinois), one roll pair
    per call, took 30–40 calls at a jump.
    """
    big = _OUT_OF_MESH
    even = np.arange(1, _BATCH + 1) / (_BATCH + 1)
    guards = np.arange(1, _GUARDS + 1) / (_GUARDS + 1)
    near: tuple[tuple[float, float], tuple[float, float]] | None = None  # outer neighbours
    for _ in range(_TRANSITION_ITER):
        w = b - a
        if abs(w) < _TRANSITION_TOL:
            break
        s = even
        est = _root_estimate(a, fa, b, fb, near, big)
        if est is not None:
            x_star, half = est
            c = (x_star - a) / w  # fractions of the bracket from a
            hw = abs(half / w)
            if hw < 0.25:
                lo, hi = max(c - hw, 0.0), min(c + hw, 1.0)
                n = _BATCH - _GUARDS
                s = np.concatenate([lo + (hi - lo) * np.arange(1, n + 1) / (n + 1), guards])
        s = np.unique(s[(s > 0.0) & (s < 1.0)])
        m = a + s * w
        fm = h(m, np.full(m.size, k))
        xs = np.r_[a, m, b]
        fs = np.r_[fa, fm, fb]
        flips = np.flatnonzero(np.diff(fs > 0))
        if flips.size > 1 and abs(xs[flips[-1] + 1] - xs[flips[0]]) > _NOISE_WIDTH:
            return None  # several crossings: which one is a matter of the path taken
        i = int(np.argmax(fs > 0))  # the first roll on the neighbour's side (≥ 1)
        a, fa, b, fb = xs[i - 1], fs[i - 1], xs[i], fs[i]
        near = ((xs[i - 2], fs[i - 2]) if i >= 2 else None,
                (xs[i + 1], fs[i + 1]) if i + 1 < xs.size else None)
        if fa == 0.0:
            break
    return float(a), float(b)


def _root_estimate(a: float, fa: float, b: float, fb: float, near, big: float):
    """Where the difference crosses zero in the bracket (a, b) and how far the estimate
    may be off — (x*, half-width) [rad] — from the bracket's ends and their outer
    neighbours ``near`` (((x, f) or None) beside a, then beside b); None where the
    difference does not look smooth there (an end out of mesh, no neighbour, or a jump:
    the slope across the bracket more than four times the slopes beside it)."""
    if near is None or abs(fa) >= big or abs(fb) >= big or fa == fb:
        return None
    beside = [(p, end, f_end) for p, end, f_end in zip(near, (a, b), (fa, fb), strict=True)
              if p is not None and abs(p[1]) < big and p[0] != end and p[1] not in (fa, fb)]
    if not beside:
        return None
    across = abs((fb - fa) / (b - a))
    slope = max(abs((f_end - p[1]) / (end - p[0])) for p, end, f_end in beside)
    if across > 4.0 * slope:
        return None
    x_lin = a - fa * (b - a) / (fb - fa)
    xc, fc = beside[0][0]
    # inverse quadratic interpolation through (a, fa), (b, fb), (xc, fc)
    x_quad = (a * fb * fc / ((fa - fb) * (fa - fc)) + b * fa * fc / ((fb - fa) * (fb - fc))
              + xc * fa * fb / ((fc - fa) * (fc - fb)))
    if not (min(a, b) < x_quad < max(a, b)):
        return None
    return x_quad, 4.0 * abs(x_quad - x_lin) + 4.0 * np.finfo(float).eps * abs(x_quad)


def _sequential_search(h: _PairDifference, a: np.ndarray, fa: np.ndarray, b: np.ndarray,
                       fb: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """The transitions (2,) [rad] of both scan rows from their brackets (a, b) (2,), one
    roll of each row per step (the rows ``rows`` (2,) of bool; the others keep ``a``): false
    position (Illinois) to 1e-12 rad where the difference is smooth, bisection to 1e-8 rad
    where a pair leaves the contact region (the lower envelope then jumps). The search of
    this toolkit before the batched one (:func:`_batched_search`), kept as it was."""
    big = _OUT_OF_MESH
    ks = np.array([-1.0, 1.0])
    a, fa, b, fb = (np.array(v, dtype=float) for v in (a, fa, b, fb))
    side = np.zeros(2)
    done = ~np.asarray(rows, dtype=bool)
    for _ in range(_TRANSITION_ITER):
        smooth = (np.abs(fa) < big) & (np.abs(fb) < big)
        m = np.where(smooth & (fa != fb), (b * fa - a * fb) / np.where(fa != fb, fa - fb, 1.0),
                     0.5 * (a + b))
        lo_m, hi_m = np.minimum(a, b), np.maximum(a, b)
        m = np.minimum(np.maximum(m, lo_m + 1e-6 * (hi_m - lo_m)), hi_m - 1e-6 * (hi_m - lo_m))
        m = np.where(done, a, m)
        fm = h(m, ks)
        out = fm > 0
        upd = ~done
        # Illinois: halve the value kept at the end that did not move twice running
        fa = np.where(upd & out & (side == -1) & smooth, 0.5 * fa, fa)
        fb = np.where(upd & ~out & (side == 1) & smooth, 0.5 * fb, fb)
        a, fa = np.where(upd & ~out, m, a), np.where(upd & ~out, fm, fa)
        b, fb = np.where(upd & out, m, b), np.where(upd & out, fm, fb)
        side = np.where(out, -1, 1)
        tol = np.where(smooth, 1e-12, 1e-8)
        done |= (np.abs(b - a) < tol) | (fm == 0.0)
        if done.all():
            break
    return a
