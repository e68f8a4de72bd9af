"""The transition points of the unloaded mesh: where the next tooth pair takes over.

Between two consecutive pairs the unloaded transmission error passes from one pair's TE
curve to the next's where they cross (seed §4.4, the UTE is the minimum over the pairs):
the roll of each crossing is bracketed on a scan of the pair difference over one mesh
cycle and refined by false position (:func:`transitions`). The LTCA's mesh cycle starts
at these rolls (:mod:`contact.ltca.mesh_cycle`).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from contact.utca.contact_curves import pair_transmission_error
from contact.utca.easeoff import EaseOff
from contact.utca.fields import EaseOffFields
from geometry.core.validation import integer

__all__ = [
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
        by false position (Illinois) to 1e-12 rad at a crossing of the two UTE curves, or
        by bisection to 1e-8 rad where a pair leaves the contact region first (the lower
        envelope then jumps). If the lowest node's pair does not carry the motion at its
        roll (a misalignment can move the contact away), the scan starts again from the
        nearest sampled roll where it does. NaN if pair 0 never carries the motion or is
        still the lowest two cycles away.

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
    brackets the transition, solved by false position (Illinois) to 1e-12 rad where the
    difference is smooth, by bisection to 1e-8 rad where a pair leaves the contact region
    (NaN where the row has no such sample)."""
    big = _OUT_OF_MESH
    ks = np.array([-1.0, 1.0])
    found = np.any(hx > 0, axis=1)
    j = np.where(found, np.argmax(hx > 0, axis=1), 1)
    rows = np.arange(2)
    a, fa = x[rows, j - 1], hx[rows, j - 1]
    b, fb = x[rows, j], hx[rows, j]
    side = np.zeros(2)
    done = ~found
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
    res = np.where(found, a, np.nan)
    return float(res[0]), float(res[1])
