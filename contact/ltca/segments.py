"""Contact segments of every (roll, pair): the LTCA discretisation (seed §3.3, Fig. 3.3).

Public functions
----------------
segment_geometry   the segments of the contact curves (and flank edges) of every roll, pair
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from contact.ltca.curvature import gear_curvature, pinion_curvature
from contact.ltca.discretisation import (
    MIN_CLIP,
    SegmentQuadratic,
    blank_measure,
    fill_rows,
    gear_to_pair,
)
from contact.ltca.edges import edge_segments, flank_boundary
from contact.utca import CURVE_SPACINGS, EaseOff, EaseOffFields, contact_curves

__all__ = ["segment_geometry"]


def segment_geometry(case, eo: EaseOff, roll: np.ndarray, pairs: Sequence[int], segments: int,
                     spacing: str = "cosine", edges: tuple[float, float] | None = None,
                     edge_limit: float | None = None):
    """Contact segments of every (roll, pair): the LTCA discretisation (seed §3.3, Fig. 3.3).

    Parameters
    ----------
    case : geometry.case.Case
    eo : contact.utca.easeoff.EaseOff
    roll : array (J,) — [rad]
        Pinion roll positions (Q units, driving sense).
    pairs : sequence of int (K,)
        Pair offsets relative to each roll's own mesh cycle: at roll r in cycle
        c = ⌊(r − r₀)/pitch⌋ (r₀ the first roll), pair k is the tooth pair whose contact
        curve is Q = r − (c + k)·pitch. The results are then periodic in the mesh cycle.
    segments : int
        Segments per contact curve.
    spacing : str
        Placing of the segment ends (:data:`contact.utca.CURVE_SPACINGS`; see
        :class:`LTCAOptions`).
    edges : (float, float or (float, float)), optional — [mm]
        (step, edge radius): also the edge segments of every pair (:mod:`contact.edge`),
        the flank boundary split into segments of at most ``step``, each with R_eq from
        the edge radius — one for both members, or (pinion, gear), each member's for its
        own edges; they follow the S curve segments along the segment axis.
        Default None: the curves only (the seed's line model).
    edge_limit : float, optional — [mm]
        Edge segments whose separation from the roll's UTE is surely above this (its
        lower bound from the three samples) are not worked out (left NaN): they cannot
        touch while R Θ stays below it. Default None: all.

    Returns
    -------
    dict of arrays, shapes (J, K, S + E) (+ (3,) for vectors), E the boundary segments
    (0 without ``edges``); NaN where a pair has no curve or a boundary segment is not in
    edge contact: ``kind`` (S + E,) 0 for a curve segment, 1 + the index into
    :data:`contact.ltca.edges.EDGE_KINDS` for an edge segment; ``midpoint`` (gear frame) and
    ``midpoint_pair`` (pair frame) [mm],
    ``ends_pair`` (J, K, S, 2, 3) [mm] (of the part inside the pinion blank),
    ``normal_pair`` [1] (out of the pinion), ``length`` [mm] (0 where the segment lies
    wholly beyond the pinion blank), ``moment_arm`` [mm], ``lag`` [rad] (mean ε + gap
    over the segment),
    ``u``, ``v`` [1] gear projection-plane fractions, ``r_eq`` [mm]; (J, K): ``ute`` [rad];
    (J,): ``pinion_rotation``, ``gear_rotation`` [rad] (of the cycle's reference pair, to
    which each pair's points are consistent: pairs sit whole pitches apart),
    ``edge_arm_max`` float [mm] the greatest normal arm on the flank boundary, ``source``
    [1] the first roll with the same curves (rolls whole mesh cycles apart: their targets
    agree to 1e-12 pitch; they are computed once and their entries are identical).
    """
    roll = np.asarray(roll, float)
    pairs = np.asarray(pairs, int)
    cycle = np.floor((roll - roll[0]) / eo.pitch + 1e-9)
    target = roll[:, None] - (cycle[:, None] + pairs[None, :]) * eo.pitch
    rp = eo.roll_zero + eo.drive_sense * (roll - cycle * eo.pitch)
    # rolls whole mesh cycles apart have the same curves (their targets differ by
    # round-off): they are computed once, from the first such roll ("source")
    source = _same_rolls(target, eo.pitch)
    first = np.flatnonzero(source == np.arange(roll.size))
    geo = _segment_geometry(case, eo, target[first], rp[first], segments, spacing, edges,
                            edge_limit)
    back = np.searchsorted(first, source)
    out = {k: (val[back] if isinstance(val, np.ndarray) and k != "kind" else val)
           for k, val in geo.items()}
    out["shape"] = (roll.size, pairs.size, geo["kind"].size)
    out["source"] = source
    return out


def _same_rolls(target: np.ndarray, pitch: float) -> np.ndarray:
    """(J,) index of the first roll whose targets (J, K) agree to 1e-12 pitch [rad]."""
    key = np.round(target / (1e-12 * pitch))
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return first[np.ravel(inverse)]


def _segment_geometry(case, eo: EaseOff, target: np.ndarray, rp: np.ndarray, segments: int,
                      spacing: str, edges: tuple[float, float] | None = None,
                      edge_limit: float | None = None):
    """:func:`segment_geometry` of roll targets (J, K) [rad] with pinion rotations rp (J,)."""
    # each segment is sampled at its ends and its middle (2S + 1 points along a curve);
    # its fields follow the quadratic through the three (SegmentQuadratic)
    fields = EaseOffFields(eo)
    cc = contact_curves(eo, target, n_point=2 * segments + 1, spacing=spacing,
                        near_misses=True, fields=fields)
    (J, K), S = target.shape, segments
    quad = SegmentQuadratic(CURVE_SPACINGS[spacing](2 * S + 1))
    kin = eo.kinematics
    # member rotations of each curve: pinion φ = roll_zero + s_p q, gear at the ideal ψ;
    # pair k's points then lie on the teeth k pitches away at the roll's own rotations
    phi = eo.roll_zero + eo.drive_sense * target  # (J, K)
    psi = eo.gear_phase - phi / eo.ratio

    def to_pair(x, vec=False):
        return gear_to_pair(kin, psi[..., None], x, vec)

    # the real pinion touches a gear point at the pair's own instant, which near the
    # pinion's tip or ends can lie beyond its blank (the curve ends where the *conjugate*
    # mate leaves it): each segment is clipped to the part [a, b] whose real mate lies
    # inside the pinion blank, at the crossing of the blank measure, so the contact line
    # ends on the blank edge whatever the segment count
    a, b = quad.clip(blank_measure(case, kin, "pinion", to_pair(cc.position), phi))
    # a curve shrunk to a point (a pair just meeting a corner of the flank) has no
    # segment either
    whole = cc.position[..., 2::2, :] - cc.position[..., 0:-1:2, :]  # whole-segment chords
    inside = (b - a > MIN_CLIP) & (np.linalg.norm(whole, axis=-1) > 0)
    c = 0.5 * (a + b)  # collocation point: the middle of the segment's part in contact
    u = np.where(inside, quad.at(cc.u, c), np.nan)
    v = np.where(inside, quad.at(cc.v, c), np.nan)
    pos_g = quad.at(cc.position, c, vector=True)
    nrm_g = quad.at(cc.normal, c, vector=True)
    nrm_g /= np.linalg.norm(nrm_g, axis=-1, keepdims=True)
    end_a, end_b = quad.at(cc.position, a, vector=True), quad.at(cc.position, b, vector=True)
    chord = end_b - end_a
    length = np.where(inside, np.linalg.norm(chord, axis=-1), 0.0)
    # the separation enters as the segment's mean (a uniform load over the segment does
    # work against the mean gap; the midpoint value would be off by −s″ h²/24)
    lag = quad.mean(cc.ease_off_angle + cc.gap, a, b)
    arm = quad.at(cc.normal_arm, c)
    mid_pair = to_pair(pos_g)
    ends_pair = np.stack([to_pair(end_a), to_pair(end_b)], axis=-2)
    # the gear normal points out of the gear; the contact normal out of the pinion is −n_g
    n_pair = -to_pair(nrm_g, vec=True)
    # unit tangent of the chord (of the whole segment where it is clipped away)
    chord = np.where(inside[..., None], chord, whole)
    norm = np.linalg.norm(chord, axis=-1, keepdims=True)
    tangent = chord / np.where(norm > 0, norm, np.nan)
    t_pair = to_pair(tangent, vec=True)
    # R_eq across the contact line from both real surfaces at the midpoints
    ok = np.isfinite(u) & np.isfinite(v)
    r_eq = np.full(u.shape, np.nan)
    if np.any(ok):
        # the envelope solver continues from neighbouring targets, so the midpoints are
        # handed over as a 2-D array of curves ordered (pair, roll): neighbours are close
        order = np.transpose(np.arange(J * K).reshape(J, K))  # (K, J) → curve index
        rows = order.reshape(-1)
        okc = ok.reshape(J * K, S)[rows]
        keep = np.any(okc, axis=1)
        rows, okc = rows[keep], okc[keep]
        uu = fill_rows(u.reshape(J * K, S)[rows], okc)
        vv = fill_rows(v.reshape(J * K, S)[rows], okc)
        pg = pos_g.reshape(J * K, S, 3)[rows]
        pg = np.stack([fill_rows(pg[..., i], okc) for i in range(3)], axis=-1)
        # across-line direction w = n × t in the gear frame (carried to the pinion frame
        # at each curve's pinion rotation)
        w_g = np.nan_to_num(np.cross(nrm_g, tangent)).reshape(J * K, S, 3)[rows]
        phi_r = np.broadcast_to(phi[..., None], u.shape).reshape(J * K, S)[rows]
        kg = gear_curvature(case, eo, pg, w_g)
        kp = pinion_curvature(case, eo, uu, vv, w_g, phi_r)
        krel = np.where(okc, kp + kg, np.nan)
        # nearly conformal (κ_rel ≤ 1e-4 /mm): R_eq capped at 10 m; where a surface has
        # no generated point (NaN curvature) the segment is left out (R_eq NaN)
        flat = np.full((J * K, S), np.nan)
        flat[rows] = np.where(np.isfinite(krel), 1.0 / np.maximum(krel, 1e-4), np.nan)
        r_eq = flat.reshape(J, K, S)
    out = {
        "u": u, "v": v, "midpoint": pos_g, "midpoint_pair": mid_pair, "ends_pair": ends_pair,
        "normal_pair": n_pair, "tangent_pair": t_pair, "length": length, "moment_arm": arm,
        "lag": lag, "r_eq": r_eq,
    }
    kind = np.zeros(S, dtype=np.int8)
    edge_arm_max = 0.0
    if edges is not None:
        bd = flank_boundary(fields, edges[0])
        shift = np.where(np.isfinite(cc.shift), cc.shift, 0.0).reshape(J, K)
        ute = cc.ute.reshape(J, K)
        ute_env = np.min(np.where(np.isfinite(ute), ute, np.inf), axis=1)
        radii = tuple(np.broadcast_to(np.asarray(edges[1], dtype=float), (2,)))
        edge = edge_segments(case, eo, bd, radii, target, shift, ute_env, edge_limit)
        edge_arm_max = float(np.max(bd.normal_arm, initial=0.0))
        out = {k: np.concatenate([out[k], edge[k]], axis=2) for k in out}
        kind = np.r_[kind, 1 + bd.kind].astype(np.int8)
    return {
        **out, "kind": kind,
        "ute": cc.ute.reshape(J, K), "pinion_rotation": rp,
        "gear_rotation": eo.gear_phase - rp / eo.ratio, "shape": (J, K, kind.size),
        "edge_arm_max": edge_arm_max,
    }


def keep_segments(seg: dict, keep: np.ndarray) -> dict:
    """``segment_geometry``'s fields with only the segments ``keep`` (bool (S + E,))."""
    J, K, n = seg["shape"]
    out = {}
    for k, val in seg.items():
        if k == "kind":
            out[k] = val[keep]
        elif isinstance(val, np.ndarray) and val.ndim >= 3 and val.shape[:3] == (J, K, n):
            out[k] = val[:, :, keep]
        else:
            out[k] = val
    out["shape"] = (J, K, int(keep.sum()))
    return out
