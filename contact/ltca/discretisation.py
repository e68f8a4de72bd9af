"""Building blocks of the LTCA's discretisation (seed §3.3, Fig. 3.3).

Each contact curve is sampled at 2S + 1 places and split into S segments whose fields
follow the quadratic through their ends and middle (:class:`SegmentQuadratic`); a segment
is clipped to the part whose real mate lies inside the mating blank
(:func:`blank_measure`); points of the reference gear tooth are carried into the pair
frame at a roll position by :func:`gear_to_pair`.

Public functions
----------------
SegmentFields     the fields of the segments of every (roll, pair), typed
MIN_CLIP          least clipped fraction of a segment that is kept
SegmentQuadratic  quadratic interpolation, mean and clipping within each segment
blank_measure     inside measure of pair-frame points in a member's blank
gear_to_pair      gear-frame points or vectors into the pair frame, gear turned
fill_rows         fill invalid entries of each row by linear interpolation
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from geometry.machine.flank import blank_outline, projection_fractions
from geometry.pair.assembly import rotate_about_axis

__all__ = ["MIN_CLIP", "SegmentFields", "SegmentQuadratic", "blank_measure", "fill_rows",
           "gear_to_pair"]


@dataclass(frozen=True, eq=False)
class SegmentFields:
    """The fields of the contact segments of every (roll, pair): arrays (J, K, S[, ...]).

    J roll positions, K tooth pairs, S segments (curve segments, then edge segments).
    NaN where a pair has no segment there (``length`` 0).

    Attributes
    ----------
    u, v : ndarray (J, K, S) — [1]
        Gear projection-plane fractions of the segment's collocation point.
    midpoint : ndarray (J, K, S, 3) — [mm]
        The collocation point on the reference gear tooth, gear frame.
    midpoint_pair : ndarray (J, K, S, 3) — [mm]
        The same in the pair frame at the roll position.
    ends_pair : ndarray (J, K, S, 2, 3) — [mm]
        Ends of the part in contact (inside the mating blank), pair frame.
    normal_pair, tangent_pair : ndarray (J, K, S, 3) — [1]
        Contact normal (out of the pinion) and unit tangent of the contact line, pair frame.
    length : ndarray (J, K, S) — [mm]
        Length of the part in contact (0 where none).
    moment_arm : ndarray (J, K, S) — [mm]
        Moment arm R of the contact normal about the gear axis.
    lag : ndarray (J, K, S) — [rad]
        Mean angular separation ε + gap over the part in contact (gear lag).
    r_eq : ndarray (J, K, S) — [mm]
        Equivalent radius across the contact line (seed Eq. 2.13).
    """

    u: np.ndarray
    v: np.ndarray
    midpoint: np.ndarray
    midpoint_pair: np.ndarray
    ends_pair: np.ndarray
    normal_pair: np.ndarray
    tangent_pair: np.ndarray
    length: np.ndarray
    moment_arm: np.ndarray
    lag: np.ndarray
    r_eq: np.ndarray

    @classmethod
    def field_names(cls) -> tuple[str, ...]:
        """The names of the per-segment fields, in order."""
        return tuple(f.name for f in dataclasses.fields(SegmentFields))

    def per_segment(self) -> dict[str, np.ndarray]:
        """The per-segment fields by name."""
        return {k: getattr(self, k) for k in SegmentFields.field_names()}

    def concatenate(self, other: SegmentFields) -> SegmentFields:
        """These segments followed by ``other``'s along the segment axis."""
        return SegmentFields(**{k: np.concatenate([v, getattr(other, k)], axis=2)
                                for k, v in self.per_segment().items()})


#: [1] a segment clipped by the pinion blank to less than this fraction of its length is
#: left out (its load would be below the solution's resolution)
MIN_CLIP = 1e-6


class SegmentQuadratic:
    """Quadratic interpolation within each segment of a curve sampled at 2S + 1 points.

    Segment k spans the samples 2k (τ = 0), 2k + 1 (τ = τ_m) and 2k + 2 (τ = 1), τ the
    fraction of the segment's parameter span; the Lagrange quadratic through the three
    gives a field at any τ (error O(h³)) and its mean over [a, b] (exact for quadratics).

    Parameters
    ----------
    fractions : array (2S + 1,) — [1]
        The sample fractions along the curve (:data:`contact.utca.CURVE_SPACINGS`).

    Notes
    -----
    Source: the contact curves divided into N_c segments, each carrying its own load, are the
    seed's (§3.2, Figure 3.3, Eq. 3.11). The mean of the three-point Lagrange quadratic over
    the whole segment with τ_m = 1/2 is Simpson's rule (f₀ + 4 f_m + f₁)/6.
    """

    def __init__(self, fractions: np.ndarray):
        x = np.asarray(fractions, float)
        self.tau_m = (x[1:-1:2] - x[0:-2:2]) / (x[2::2] - x[0:-2:2])  # (S,)

    @staticmethod
    def _split(x: np.ndarray, vector: bool):
        if vector:  # vectors (..., 2S+1, 3)
            return x[..., 0:-1:2, :], x[..., 1::2, :], x[..., 2::2, :]
        return x[..., 0:-1:2], x[..., 1::2], x[..., 2::2]

    def _basis(self, tau):
        """Lagrange weights (w0, wm, w1) at τ (..., S)."""
        tm = self.tau_m
        w0 = (tau - tm) * (tau - 1.0) / tm
        wm = tau * (tau - 1.0) / (tm * (tm - 1.0))
        w1 = tau * (tau - tm) / (1.0 - tm)
        return w0, wm, w1

    def _combine(self, x, w, vector: bool = False):
        x0, xm, x1 = self._split(x, vector)
        if vector:
            w = tuple(wi[..., None] for wi in w)
        return w[0] * x0 + w[1] * xm + w[2] * x1

    def at(self, x: np.ndarray, tau: np.ndarray, vector: bool = False) -> np.ndarray:
        """Field x (..., 2S+1), or vectors (..., 2S+1, 3) with ``vector``, at the fractions
        τ (..., S) of each segment."""
        return self._combine(x, self._basis(tau), vector)

    def mean(self, x: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Mean of field x (..., 2S+1) over [a, b] ⊂ [0, 1] of each segment (..., S)."""
        a, b = np.broadcast_arrays(a, b)
        tm = self.tau_m
        m1 = 0.5 * (a + b)  # mean of τ over [a, b]
        m2 = (a * a + a * b + b * b) / 3.0  # mean of τ²
        w0 = (m2 - (tm + 1.0) * m1 + tm) / tm
        wm = (m2 - m1) / (tm * (tm - 1.0))
        w1 = (m2 - tm * m1) / (1.0 - tm)
        return self._combine(x, (w0, wm, w1))

    def clip(self, m: np.ndarray):
        """Part [a, b] of each segment where a measure m (..., 2S+1) is ≥ 0.

        m is taken as linear between the samples (crossings to second order in h); a
        segment wholly outside gets a = b = 0, as does one without a curve (NaN). Where m
        changes sign twice within a segment the part between the outer crossings is kept.
        """
        m0, mm, m1 = self._split(m, False)
        tm = self.tau_m
        in0, inm, in1 = m0 >= 0, mm >= 0, m1 >= 0
        with np.errstate(invalid="ignore", divide="ignore"):
            c0m = tm * m0 / (m0 - mm)  # crossing within [0, τm]
            cm1 = tm + (1.0 - tm) * mm / (mm - m1)  # crossing within [τm, 1]
        a = np.where(in0, 0.0, np.where(inm, c0m, np.where(in1, cm1, 0.0)))
        b = np.where(in1, 1.0, np.where(inm, cm1, np.where(in0, c0m, 0.0)))
        return a, b


def blank_measure(case, kin, member: str, points_pair: np.ndarray,
                   turn: np.ndarray) -> np.ndarray:
    """Inside measure of pair-frame points in one member's blank, the member turned.

    Parameters
    ----------
    member : str
        ``"pinion"`` or ``"gear"``.
    points_pair : array (..., P, 3) — [mm]
        Points in the pair frame (e.g. the samples of the curves of every (roll, pair);
        NaN where no curve).
    turn : array (...) — [rad]
        The member's rotation about its axis for each group of P points (pinion φ,
        gear ψ).

    Returns
    -------
    array (..., P) — [1]
        m = min(u, 1 − u, 1 − v) in the member's projection-plane fractions (toe, heel,
        tip): ≥ 0 inside the blank (NaN where no point).
    """
    axis, origin = getattr(kin, f"{member}_axis"), getattr(kin, f"{member}_origin")
    place = getattr(kin, f"{member}_place")[:3, :3]
    x = rotate_about_axis(axis, np.broadcast_to(-turn[..., None], points_pair.shape[:-1]),
                points_pair - origin) @ place
    fu, fv = projection_fractions(blank_outline(case.member(member).blank).corners, x[..., 2],
                        np.hypot(x[..., 0], x[..., 1]))
    return np.minimum(np.minimum(fu, 1.0 - fu), 1.0 - fv)


def gear_to_pair(kin, psi, x: np.ndarray, vec: bool = False) -> np.ndarray:
    """Gear-frame points (or vectors) x (..., 3) [mm] into the pair frame with the gear
    turned by ψ [rad] (broadcast against x's leading axes)."""
    shape = np.broadcast_shapes(np.shape(psi), x.shape[:-1])
    x = np.broadcast_to(x @ kin.gear_place[:3, :3].T, (*shape, 3))
    q = rotate_about_axis(kin.gear_axis, np.broadcast_to(psi, shape), x)
    return q if vec else q + kin.gear_origin


def fill_rows(a: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Replace the invalid entries of each row by linear interpolation between its valid
    neighbours, and beyond a row's first or last valid entry by that entry.

    Parameters
    ----------
    a : array (R, S) — [any unit]
        The rows (e.g. a field along each contact curve's S segments).
    valid : array (R, S) of bool
        The entries to keep (a non-finite entry is invalid whatever ``valid`` says).

    Returns
    -------
    ndarray (R, S) — [as ``a``]
        Row by row what :func:`numpy.interp` of the row's valid entries (at their column
        indices) gives at every column, to the bit: the valid entries themselves, between
        two valid entries p < c < q the value (a_q − a_p)/(q − p) · (c − p) + a_p, before
        the first and after the last the first's and the last's; for all rows in whole-
        array passes (a roll's curves, every roll at once: issue 75 item 4).

    Raises
    ------
    ValueError
        A row with an invalid entry and no valid one (as :func:`numpy.interp` of no
        points).
    """
    out = np.array(a, dtype=float)
    good = np.asarray(valid, dtype=bool) & np.isfinite(out)
    if good.all():
        return out
    n = out.shape[1]
    col = np.arange(n)
    # each entry's nearest valid column at or before it (−1: none) and at or after it (n)
    prev = np.maximum.accumulate(np.where(good, col, -1), axis=1)
    nxt = np.minimum.accumulate(np.where(good, col, n)[:, ::-1], axis=1)[:, ::-1]
    r, c = np.nonzero(~good)
    p, q = prev[r, c], nxt[r, c]
    if np.any((p < 0) & (q >= n)):
        raise ValueError("fill_rows: a row has no valid entry to fill from")
    before, after = p < 0, q >= n
    inner = ~(before | after)
    fill = np.empty(r.size)
    fill[before] = out[r[before], q[before]]
    fill[after] = out[r[after], p[after]]
    ri, ci, pi, qi = r[inner], c[inner], p[inner], q[inner]
    # numpy.interp's arithmetic: slope (f_q − f_p)/(x_q − x_p), then slope·(x − x_p) + f_p
    lo = out[ri, pi]
    slope = (out[ri, qi] - lo) / (qi.astype(float) - pi.astype(float))
    fill[inner] = slope * (ci.astype(float) - pi.astype(float)) + lo
    out[r, c] = fill
    return out
