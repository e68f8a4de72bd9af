"""Contact segments of every (roll, pair): the LTCA discretisation (seed §3.3, Fig. 3.3).

Each contact curve of a pair (:func:`contact.utca.contact_curves`, near misses included) is
sampled at 2S + 1 places and split into S segments, each following the quadratic through
its ends and middle (:class:`contact.ltca.discretisation.SegmentQuadratic`), clipped where
the real pinion's mate leaves the pinion blank, carrying the mean separation of its part
in contact, its moment arm and R_eq across the line (:mod:`contact.ltca.curvature`); the
flank boundary's edge segments (:mod:`contact.ltca.edges`) follow the curve segments
along the segment axis. Rolls whole mesh cycles apart have the same segments and are
computed once.

Public functions
----------------
Segments           the segments of an analysis: per-segment fields, kinds, UTE, rotations
segment_geometry   compute them for roll positions and tooth pairs
roll_phases        each roll's pairs' curve targets, rotations and first roll of its phase
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from contact.ltca.curvature import gear_curvature, pinion_curvature
from contact.ltca.discretisation import (
    MIN_CLIP,
    SegmentFields,
    SegmentQuadratic,
    blank_measure,
    fill_rows,
    gear_to_pair,
)
from contact.ltca.edges import FlankBoundary, edge_segments, flank_boundary
from contact.utca import CURVE_SPACINGS, ContactCurves, EaseOff, contact_curves
from contact.utca.fields import Same, fields_of
from geometry.core.caches import Carried, memoised
from geometry.machine.meshing import warm_seeds_active

__all__ = ["Segments", "clear_segment_memo", "roll_phases", "segment_geometry"]


@dataclass(frozen=True, eq=False)
class Segments(SegmentFields):
    """The contact segments of an analysis: J rolls × K pairs × S segments.

    The per-segment fields of :class:`contact.ltca.discretisation.SegmentFields`, and:

    Attributes
    ----------
    kind : ndarray (S,) of int8
        0 for a contact-curve segment, 1 + the index into :data:`contact.ltca.EDGE_KINDS`
        for an edge segment.
    ute : ndarray (J, K) — [rad]
        Unloaded transmission error of each pair (NaN out of mesh).
    pinion_rotation, gear_rotation : ndarray (J,) — [rad]
        Member rotations of the cycle's reference pair, to which each pair's points are
        consistent (pairs sit whole pitches apart).
    edge_arm_max : float — [mm]
        Greatest normal arm on the flank boundary (0 without edge segments).
    source : ndarray (J,) of int
        The first roll with the same segments (rolls whole mesh cycles apart: their
        targets agree to 1e-12 pitch; they are computed once and their entries are
        identical).

    Notes
    -----
    Source: seed §3.3 — the potential contact curves of all the tooth pairs that may share
    the torque, divided into segments, each with its length, separation and the surface
    curvatures of both members: the LTCA's input. The edge segments continue that line model
    onto the flank boundary (:mod:`contact.ltca.edges`).
    """

    kind: np.ndarray
    ute: np.ndarray
    pinion_rotation: np.ndarray
    gear_rotation: np.ndarray
    edge_arm_max: float
    source: np.ndarray

    @property
    def shape(self) -> tuple[int, int, int]:
        """(J, K, S): rolls, pairs, segments."""
        return self.length.shape

    def keep(self, keep: np.ndarray) -> Segments:
        """The same rolls and pairs with only the segments ``keep`` (bool (S,))."""
        # (np.take of the kept indices: the same elements as boolean indexing of the
        # third axis, copied ~3× faster)
        idx = np.flatnonzero(keep)
        fields = {k: np.take(v, idx, axis=2) for k, v in self.per_segment().items()}
        return Segments(**fields, kind=self.kind[keep], ute=self.ute,
                        pinion_rotation=self.pinion_rotation, gear_rotation=self.gear_rotation,
                        edge_arm_max=self.edge_arm_max, source=self.source)

    def rolls(self, index: np.ndarray, source: np.ndarray) -> Segments:
        """The rolls ``index`` (J′,) of these segments, with ``source`` (J′,)."""
        fields = {k: v[index] for k, v in self.per_segment().items()}
        return Segments(**fields, kind=self.kind, ute=self.ute[index],
                        pinion_rotation=self.pinion_rotation[index],
                        gear_rotation=self.gear_rotation[index],
                        edge_arm_max=self.edge_arm_max, source=source)

    def __getitem__(self, name: str):
        """``segments[name]``: the mapping access of the dict this type replaced
        (deprecated; use the attribute)."""
        warnings.warn("Segments[name] is deprecated: use the attribute Segments.name",
                      DeprecationWarning, stacklevel=2)
        return getattr(self, name)


def segment_geometry(case, eo: EaseOff, roll: np.ndarray, pairs: Sequence[int], segments: int,
                     spacing: str = "cosine", edges: tuple[float, float] | None = None,
                     edge_limit: float | None = None) -> Segments:
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
    Segments
        Per-segment fields (J, K, S + E), E the boundary segments (0 without ``edges``);
        NaN where a pair has no curve or a boundary segment is not in edge contact.
    """
    target, rp, source = roll_phases(eo, roll, pairs)
    # rolls whole mesh cycles apart have the same curves (their targets differ by
    # round-off): they are computed once, from the first such roll ("source")
    first = np.flatnonzero(source == np.arange(target.shape[0]))
    geo = _kept_segment_geometry(case, eo, target[first], rp[first], segments, spacing,
                                 edges, edge_limit)
    if first.size == target.shape[0]:
        # every roll its own (one mesh cycle, as a study point runs it): the segments
        # as computed, their arrays read-only (the memo's), instead of a copy of all
        # of them (≈ 5 MB at 20 rolls); the analysis only reads them
        return geo
    return geo.rolls(np.searchsorted(first, source), source)


def roll_phases(eo: EaseOff, roll: np.ndarray, pairs: Sequence[int]
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each roll's place in its mesh cycle, as :func:`segment_geometry` takes it.

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    roll : array (J,) — [rad] pinion roll positions (Q units, driving sense)
    pairs : sequence of int (K,) — pair offsets relative to each roll's own mesh cycle

    Returns
    -------
    target : ndarray (J, K) — [rad] the roll of pair k's contact curve, Q = r − (c + k)·pitch
        in cycle c = ⌊(r − r₀)/pitch⌋
    pinion_rotation : ndarray (J,) — [rad] the pinion's rotation of the cycle's reference
        pair, roll_zero + s_p (r − c·pitch)
    source : ndarray (J,) of int — the first roll with the same targets (to 1e-12 pitch):
        rolls whole mesh cycles apart, whose segments (and rotations) are the source's

    Notes
    -----
    Source: the LTCA's discretisation (seed §3.3, Fig. 3.3).
    """
    roll = np.asarray(roll, float)
    pairs = np.asarray(pairs, int)
    cycle = np.floor((roll - roll[0]) / eo.pitch + 1e-9)
    target = roll[:, None] - (cycle[:, None] + pairs[None, :]) * eo.pitch
    rp = eo.roll_zero + eo.drive_sense * (roll - cycle * eo.pitch)
    return target, rp, _same_rolls(target, eo.pitch)


def _same_rolls(target: np.ndarray, pitch: float) -> np.ndarray:
    """(J,) index of the first roll whose targets (J, K) agree to 1e-12 pitch [rad]."""
    key = np.round(target / (1e-12 * pitch))
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return first[np.ravel(inverse)]


def _segment_geometry(case, eo: EaseOff, target: np.ndarray, rp: np.ndarray, segments: int,
                      spacing: str, edges: tuple[float, float] | None = None,
                      edge_limit: float | None = None) -> Segments:
    """:func:`segment_geometry` of roll targets (J, K) [rad] with pinion rotations rp (J,)
    (every roll computed: ``source`` is 0 … J − 1)."""
    J = target.shape[0]
    part = _curve_part(case, eo, target, segments, spacing,
                       None if edges is None else edges[0])
    found = part.found
    kind = np.zeros(segments, dtype=np.int8)
    edge_arm_max = 0.0
    if edges is not None:
        bd = part.boundary
        ute = part.ute
        ute_env = np.min(np.where(np.isfinite(ute), ute, np.inf), axis=1)
        radii = tuple(np.broadcast_to(np.asarray(edges[1], dtype=float), (2,)))
        # the curve segments, then the edge segments: written once into each field's array
        found = edge_segments(case, eo, bd, radii, target, part.shift, ute_env, edge_limit,
                              fields=fields_of(eo), before=found)
        edge_arm_max = float(np.max(bd.normal_arm, initial=0.0))
        kind = np.r_[kind, 1 + bd.kind].astype(np.int8)
    return Segments(**found.per_segment(), kind=kind, ute=part.ute.copy(),
                    pinion_rotation=rp, gear_rotation=eo.gear_phase - rp / eo.ratio,
                    edge_arm_max=edge_arm_max, source=np.arange(J))


class _CurvePart(NamedTuple):
    """What the segment geometry of roll targets takes from the ease-off alone, not from
    the torque: the curve segments (J, K, S), each pair's UTE and curve shift (J, K)
    [rad] (the shift 0 where a pair has no curve) and the flank boundary (None without
    edge segments)."""

    found: SegmentFields
    ute: np.ndarray
    shift: np.ndarray
    boundary: FlankBoundary | None


def _curve_part(case, eo: EaseOff, target: np.ndarray, segments: int, spacing: str,
                step: float | None) -> _CurvePart:
    """:func:`_curve_part_of`, memoised per process by the ease-off object, the teeth
    (``Case.teeth_key``: what the blank measure and the curvatures read of the case), the
    targets to the last bit, the segment count, spacing and boundary step. The analyses of
    a torque series (or one repeated) at one misalignment share the memoised ease-off
    (:func:`contact.utca.ease_off`) and so these, as its unloaded cycle; the edge
    segments, which depend on the torque's separation limit, are worked out at each
    call. Inside a development's trial (:func:`geometry.machine.meshing.warm_seeds_active`:
    its ease-off is not in the process memo) memoised apart
    (:func:`_memo_trial_curve_part`), so that no cold analysis reads a trial's: a design
    the development analyses again (the coast flank developed again at its own design
    torque, its ease-off kept per development by
    :class:`contact.optimize.development_evaluate.KeptTeeth`, the same object) reads its
    curve segments from there (issue 75: ≈ 25 ms of a coarse trial's LTCA on the
    passenger-car hypoid 10x43)."""
    target = np.ascontiguousarray(target, dtype=float)
    memo = _memo_trial_curve_part if warm_seeds_active() else _memo_curve_part
    return memo(Same(eo), case.teeth_key(), Carried(case), target.shape, target.tobytes(),
                int(segments), str(spacing), None if step is None else float(step))


@memoised(maxsize=4)
def _memo_curve_part(eo: Same, teeth, case: Carried, shape: tuple[int, int], target: bytes,
                     segments: int, spacing: str, step: float | None) -> _CurvePart:
    """:func:`_curve_part_of` memoised (:func:`_curve_part`), its arrays read-only."""
    return _frozen_curve_part(eo, case, shape, target, segments, spacing, step)


@memoised(maxsize=32)
def _memo_trial_curve_part(eo: Same, teeth, case: Carried, shape: tuple[int, int],
                           target: bytes, segments: int, spacing: str,
                           step: float | None) -> _CurvePart:
    """:func:`_curve_part_of` of a development's trial memoised (:func:`_curve_part`), its
    arrays read-only. 32 entries (≈ 0.3 MB each with the ease-off it holds, on the
    passenger-car hypoid 10x43): the coast flank's designs (at most
    ``coast_max_evaluations``, 20 by default) are all still there when the coast flank is
    developed again (19 designs apart on the spiral bevel 13x39)."""
    return _frozen_curve_part(eo, case, shape, target, segments, spacing, step)


def _frozen_curve_part(eo: Same, case: Carried, shape: tuple[int, int], target: bytes,
                       segments: int, spacing: str, step: float | None) -> _CurvePart:
    """:func:`_curve_part_of` of a memo's key, its arrays made read-only."""
    part = _curve_part_of(case.value, eo.obj, np.frombuffer(target).reshape(shape),
                          segments, spacing, step)
    arrays = [*part.found.per_segment().values(), part.ute, part.shift]
    if part.boundary is not None:
        arrays += [a for a in part.boundary if isinstance(a, np.ndarray)]
    for a in arrays:
        a.flags.writeable = False
    return part


def _kept_segment_geometry(case, eo: EaseOff, target: np.ndarray, rp: np.ndarray,
                           segments: int, spacing: str, edges, edge_limit) -> Segments:
    """:func:`_segment_geometry`, memoised per process (:func:`_memo_segment_geometry`) by
    the ease-off object, the teeth, the targets and pinion rotations to the last bit, the
    segment count, spacing, edge step and radii and the edge limit: an analysis repeated
    at one misalignment and torque (whose edge limit is the same) works out its edge
    segments once (~13 ms of a warm analysis, issue 75), as its curve segments
    (:func:`_curve_part`). Its arrays read-only: :meth:`Segments.rolls` copies what the
    analysis takes. Not memoised inside a development's trial (as :func:`_curve_part`)."""
    if warm_seeds_active():
        return _segment_geometry(case, eo, target, rp, segments, spacing, edges, edge_limit)
    target = np.ascontiguousarray(target, dtype=float)
    rp = np.ascontiguousarray(rp, dtype=float)
    edge_key = None if edges is None else (
        float(edges[0]), tuple(np.asarray(edges[1], dtype=float).ravel().tolist()))
    return _memo_segment_geometry(
        Same(eo), case.teeth_key(), Carried((case, target, rp, edges)), target.shape,
        target.tobytes(), rp.tobytes(), int(segments), str(spacing), edge_key,
        None if edge_limit is None else float(edge_limit))


@memoised(maxsize=4)
def _memo_segment_geometry(eo: Same, teeth, given: Carried, shape: tuple[int, int],
                           target: bytes, rp: bytes, segments: int, spacing: str, edges,
                           edge_limit: float | None) -> Segments:
    """:func:`_segment_geometry` memoised (:func:`_kept_segment_geometry`), its arrays
    read-only."""
    case, t, r, e = given.value
    geo = _segment_geometry(case, eo.obj, t.copy(), r.copy(), segments, spacing, e,
                            edge_limit)
    for a in (*geo.per_segment().values(), geo.kind, geo.ute, geo.pinion_rotation,
              geo.gear_rotation, geo.source):
        a.flags.writeable = False
    return geo


def clear_segment_memo() -> None:
    """Forget the curve segments memoised per process by :func:`segment_geometry` (frees
    memory; the next analysis computes them afresh)."""
    _memo_curve_part.cache_clear()
    _memo_trial_curve_part.cache_clear()
    _memo_segment_geometry.cache_clear()


def _curve_part_of(case, eo: EaseOff, target: np.ndarray, segments: int, spacing: str,
                   step: float | None) -> _CurvePart:
    """The torque-independent part of :func:`_segment_geometry` (:class:`_CurvePart`)."""
    # each segment is sampled at its ends and its middle (2S + 1 points along a curve);
    # its fields follow the quadratic through the three (SegmentQuadratic)
    fields = fields_of(eo)  # the unloaded cycle's, where the analysis built it
    cc = contact_curves(eo, target, n_point=2 * segments + 1, spacing=spacing,
                        near_misses=True, fields=fields)
    J, K = target.shape
    found = _curve_segments(case, eo, cc, target, segments, spacing)
    shift = np.where(np.isfinite(cc.shift), cc.shift, 0.0).reshape(J, K)
    bd = None if step is None else flank_boundary(fields, step)
    return _CurvePart(found, cc.ute.reshape(J, K), shift, bd)


def _curve_segments(case, eo: EaseOff, cc: ContactCurves, target: np.ndarray, S: int,
                    spacing: str) -> SegmentFields:
    """The S segments of every contact curve ``cc`` of roll targets (J, K) [rad]."""
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
    r_eq = _curve_r_eq(case, eo, u, v, pos_g, nrm_g, tangent, phi)
    return SegmentFields(u=u, v=v, midpoint=pos_g, midpoint_pair=mid_pair, ends_pair=ends_pair,
                         normal_pair=n_pair, tangent_pair=t_pair, length=length,
                         moment_arm=arm, lag=lag, r_eq=r_eq)


def _curve_r_eq(case, eo: EaseOff, u, v, pos_g, nrm_g, tangent, phi) -> np.ndarray:
    """R_eq [mm] across the contact line at the segments' collocation points (J, K, S):
    places (u, v) [1], gear-frame points and normals, line tangents, pinion rotations
    φ (J, K) [rad]; NaN where a surface has no generated point."""
    J, K, S = u.shape
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
        # u, v and the three coordinates of every curve filled in one pass (each row on
        # its own: the rows of the five fields stacked)
        m = rows.size
        pg = pos_g.reshape(J * K, S, 3)[rows]
        filled = fill_rows(np.concatenate([u.reshape(J * K, S)[rows],
                                           v.reshape(J * K, S)[rows],
                                           *np.moveaxis(pg, -1, 0)]), np.tile(okc, (5, 1)))
        uu, vv = filled[:m], filled[m:2 * m]
        pg = np.ascontiguousarray(np.moveaxis(filled[2 * m:].reshape(3, m, S), 0, -1))
        # across-line direction w = n × t in the gear frame (carried to the pinion frame
        # at each curve's pinion rotation)
        w_g = np.nan_to_num(np.cross(nrm_g, tangent)).reshape(J * K, S, 3)[rows]
        # (one rotation a curve, broadcast along its segments: its trigonometry taken
        # once, geometry.pair.assembly.rotate_about_axis)
        phi_r = phi.reshape(J * K)[rows][:, None]
        kg = gear_curvature(case, eo, pg, w_g)
        kp = pinion_curvature(case, eo, uu, vv, w_g, phi_r)
        krel = np.where(okc, kp + kg, np.nan)
        # nearly conformal (κ_rel ≤ 1e-4 /mm): R_eq capped at 10 m; where a surface has
        # no generated point (NaN curvature) the segment is left out (R_eq NaN)
        flat = np.full((J * K, S), np.nan)
        flat[rows] = np.where(np.isfinite(krel), 1.0 / np.maximum(krel, 1e-4), np.nan)
        r_eq = flat.reshape(J, K, S)
    return r_eq
