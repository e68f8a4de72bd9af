"""Loaded tooth contact analysis over the mesh cycle (seed §3.3–3.4, Eq. 3.12–3.14).

At each pinion roll position the instantaneous contact curves of every tooth pair that
may share the load (from the ease-off UTCA, :mod:`contact.utca`) are split into
segments; each segment carries its midpoint, normal, length, initial separation
s = (ease-off − UTE) along the normal, moment arm R about the gear axis and the
equivalent radius R_eq across the contact line. The compliance of the segments
(:func:`contact.compliance.mesh_compliance`: both members' shells, Sainsot foundation,
Weber contact) and these data form a :class:`contact.ContactProblem`, solved by any
registered solver; the multiplier Θ is the loaded rotation, and the loaded transmission
error is LTE = UTE + Θ (gear lag, the seed's Fig. 3.6 convention).

Weber's contact compliance depends on the load (logarithmically). It is solved by
Newton's method on the contact deformation δ(F): about the current loads F₀,
δ ≈ c_s F₀ + c_t (F − F₀) (c_s the secant, c_t the tangent compliance), i.e. the
problem takes the diagonal c_t and the separation s + (c_s − c_t) F₀; solve, linearise
again at the new loads, solve again, until the LTE changes by less than
``weber_tolerance`` (default 1e-3 µrad), or its quadratically shrinking steps foretell a
next step ten times smaller; 3–5 solves are typical. The first loads share the torque
evenly over the roll's curve segments (so a roll's result depends on that roll alone). Where
c_t is not well positive (Hertz half-width near the depth) or a load is at the cap, the
secant is used there (the fixed-point iteration).

Segment selection (screening): a segment left out of a roll's problem whose gap
C F + s − R Θ stays open (≥ 0) at the solution changes nothing: the solution on the
other segments is that of all of them. Each problem takes the segments with
s < 1.1 R Θ̂ + 1 µm, Θ̂ the rotation of the last computed roll at that torque carried
over by the UTE difference; after the solve the gaps of the segments left out are
checked — exactly for those whose compliance is assembled, by s ≥ R Θ for the others
(enough, as the compliance matrix has no negative entries: the gap is ≥ s − R Θ) — and
any that would close is added and the roll solved again.
The structural compliance is assembled once per roll for a pool of segments chosen the
same way from the first roll's rotation at the largest torque (tests/test_ltca.py
compares the screened solution with that of all segments).

Moment arm: a gear rotation δ closes the gap at a point by ρ |n·e_θ| δ — the distance of
the normal's line of action from the gear axis — which is the ``normal_arm`` of the
ease-off; so R = normal_arm, and s = R (ε + gap − UTE) with ε the angular ease-off.

Discretisation (seed §3.3, Fig. 3.3, made convergent here): each curve is sampled at
2S + 1 places (cosine spacing by default: the segments are graded towards the curve's
ends, where the load of the entering and leaving pairs rises into the flank edge); each
segment follows the quadratic through its ends and middle, is clipped where the real
pinion's mate leaves the pinion blank (so the line ends on the blank edge whatever S is),
and carries the mean separation over its clipped part at the middle of that part. Pairs
whose iso-line has just left the contact region keep a curve through the pinion's own gap
(:func:`contact.utca.contact_curves` with ``near_misses``), so a leaving pair's load fades
instead of vanishing. Doubling S or the roll positions changes the LTE by well under
0.5 µrad (tests/test_ltca_discretisation.py).

Edge contact (:mod:`contact.edge`, on by default): where a pair's curve passes outside the
contact region, the region's boundary (gear tip, heel, toe; the pinion's tip edge and
ends) carries edge segments with the separation ε + ½ K (Q − q)² of the pinion at roll q,
which continues the curve's own at its end, and R_eq = 1/(1/r_e + κ_other) from the
edges' rounding radius r_e; they follow the curve segments along the ``segment`` axis
(``segment_kind``), and the flank and edge peak pressures are reported apart.

R_eq across the contact line: κ_rel(w) = κ_p(w) + κ_g(w) along w = n × t (t the
contact-line tangent), each member's normal curvature from its principal curvatures
(Euler), evaluated on the real surfaces at the segment midpoints
(:func:`geometry.flank.flank_at`); R_eq = 1/κ_rel (seed Eq. 2.13).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import xarray as xr
from scipy.interpolate import RectBivariateSpline

from contact.compliance.hertz import hertz_half_width, weber_compliance
from contact.compliance.mesh import ContactSegments, mesh_compliance_many, pair_compliance_model
from contact.easeoff import EaseOff, _rotate, ease_off
from contact.edge import EDGE_KINDS, FlankBoundary, flank_boundary
from contact.io import data_var as _var
from contact.problem import ContactProblem
from contact.solvers import DEFAULT_SOLVER, get_backend, solve_contact
from contact.transmission_error import transmission_error_summary
from contact.utca import CURVE_SPACINGS, _Fields, contact_curves
from contact.utca import transitions as _transitions
from geometry._version import __version__
from geometry.assembly import Misalignment
from geometry.curvature import normal_curvature
from geometry.errors import InputError
from geometry.flank import blank_outline, flank_at, projection_fractions

__all__ = ["LTCAOptions", "loaded_tca", "ltca_problems", "segment_geometry"]

log = logging.getLogger(__name__)

_RESIDUALS = ("primal", "dual", "complementarity", "equilibrium")

#: [1] a segment clipped by the pinion blank to less than this fraction of its length is
#: left out (its load would be below the solution's resolution)
_MIN_CLIP = 1e-6

#: segment screening (LTCAOptions.separation_limit None): a roll's problem takes the
#: segments with s < margin · R Θ̂ + pad, Θ̂ the loaded rotation expected there; after the
#: solve every segment left out must keep its gap open (else it is added and the roll
#: solved again, at most _SCREEN_ROUNDS times). [1], [mm]
_SCREEN_MARGIN = 1.1
_SCREEN_PAD = 1e-3
_SCREEN_ROUNDS = 6

#: the pair window grows (LTCAOptions.pairs) up to this many pairs
_MAX_PAIRS = 8


def _generous_limit(torque: float, ratio: float) -> float:
    """[mm] A separation limit growing with the gear torque (pinion ``torque`` [N·m]
    times ``ratio``) that holds every loaded segment of the seed's cases with room to
    spare: 0.05 mm + 0.15 mm per 1000 N·m of gear torque. It bounds the edge segments
    worked out and the first roll's pool before any rotation is known."""
    return 0.05 + 0.15 * torque * ratio / 1000.0


@dataclass(frozen=True)
class LTCAOptions:
    """Discretisation and solution settings of the LTCA.

    Attributes
    ----------
    cycles : int
        Mesh cycles analysed (≥ 1; default 2).
    rolls_per_cycle : int
        Roll positions per mesh cycle (≥ 4; default 20).
    pairs : tuple of int
        Tooth-pair offsets considered, relative to the pair that takes over at the
        start of each mesh cycle (default −1, 0, 1, 2; see :func:`segment_geometry`).
        Widened by one on a side whose outermost pair is loaded at its end of the window
        (the lowest at a cycle's last roll, the highest at its first), where the next
        pair may be loaded too, up to 8 pairs.
    segments : int
        Segments per contact curve (≥ 4; default 24).
    spacing : str
        Placing of the segment ends along a curve (:data:`contact.utca.CURVE_SPACINGS`):
        ``"cosine"`` (default) grades them towards the curve ends, where the load rises
        into a flank edge (the entering pair at the gear tip, the leaving pair at the
        pinion tip): the end segments are ~π²/(4 S²) of the curve, so the load at the
        edge converges at second order in 1/S (uniform spacing: first order);
        ``"uniform"``: equal steps in the lengthwise fraction.
    separation_limit : float or None — [mm]
        A fixed limit: segments separated by more are left out (a warning is logged if
        one of them would touch). Default None: the screening of the module docstring,
        which leaves out only segments whose gap stays open (s ≥ R Θ).
    solver : str
        Registered solver name (default our exact ``active_set``).
    weber_tolerance : float — [urad]
        Stop the Weber load iteration when the LTE changes by less, or its next Newton
        step is foretold to be ten times smaller (default 1e-3).
    max_weber_iterations : int
        Cap on the Weber iteration (default 12).
    edge_contact : bool
        Also the contact of the flank boundary beyond the curves' ends (default True;
        :mod:`contact.edge`): the gear's tip edge and ends and the pinion's tip edge and
        ends where a pair's curve passes outside the contact region (an entering pair at
        the flank's corner before its curve emerges). False: the seed's line model, load
        on the curves only.
    edge_radius : float or None — [mm]
        Rounding radius of the tooth edges, across which an edge segment is in Hertz
        line contact with the mating flank. Default None: each member's own, the case's
        ``[<member>.blank] edge_break_radius`` (default 0.5 mm, a light edge break); a
        value in (0, 50] overrides both (e.g. a sensitivity study).
    edge_step : float — [mm]
        Largest edge segment along the boundary (> 0; default 0.25 mm: halving it moves
        the LTE by < 0.1 µrad and the edge pressure by < 1 % on the seed case).
    youngs_modulus, poisson_ratio : float — [MPa], [1]
        Steel for both members (default 206 000 MPa, 0.3).
    theory, n_height, n_face
        Shell-model settings (:func:`contact.compliance.pair_compliance_model`).
    """

    cycles: int = 2
    rolls_per_cycle: int = 20
    pairs: tuple[int, ...] = (-1, 0, 1, 2)
    segments: int = 24
    spacing: str = "cosine"
    separation_limit: float | None = None
    solver: str = DEFAULT_SOLVER
    weber_tolerance: float = 1e-3
    max_weber_iterations: int = 12
    edge_contact: bool = True
    edge_radius: float | None = None
    edge_step: float = 0.25
    youngs_modulus: float = 206_000.0
    poisson_ratio: float = 0.3
    theory: str = "seed"
    n_height: int = 6
    n_face: int = 21

    def __post_init__(self) -> None:
        checks = (
            ("cycles", self.cycles, 1, 20),
            ("rolls_per_cycle", self.rolls_per_cycle, 4, 400),
            ("segments", self.segments, 4, 400),
            ("max_weber_iterations", self.max_weber_iterations, 1, 100),
        )
        for name, val, lo, hi in checks:
            if not (isinstance(val, int) and lo <= val <= hi):
                raise InputError(f"{name}: must be an integer in [{lo}, {hi}], got {val!r}")
        if self.spacing not in CURVE_SPACINGS:
            raise InputError(f"spacing: must be one of {sorted(CURVE_SPACINGS)}, got "
                             f"{self.spacing!r}")
        if not self.pairs or 0 not in self.pairs:
            raise InputError(f"pairs: must contain the reference pair 0, got {self.pairs!r}")
        if self.separation_limit is not None and not self.separation_limit > 0:
            raise InputError(
                f"separation_limit: must be > 0 [mm] or None, got {self.separation_limit!r}"
            )
        for name in ("edge_radius", "edge_step"):
            val = getattr(self, name)
            if name == "edge_radius" and val is None:
                continue
            if not (isinstance(val, (int, float)) and not isinstance(val, bool)
                    and math.isfinite(val) and 0 < val <= 50):
                extra = " or None" if name == "edge_radius" else ""
                raise InputError(f"{name}: must be a length in (0, 50] [mm]{extra}, got "
                                 f"{val!r}")
        if not isinstance(self.edge_contact, bool):
            raise InputError(f"edge_contact: must be True or False, got {self.edge_contact!r}")
        if not self.weber_tolerance > 0:
            raise InputError(f"weber_tolerance: must be > 0 [urad], got {self.weber_tolerance}")
        get_backend(self.solver)


def _spline(eo: EaseOff, field: np.ndarray) -> RectBivariateSpline:
    vals = np.array(field, dtype=float)
    ok = np.isfinite(vals)
    if not np.all(ok):  # fill masked nodes from the nearest valid node along the profile
        for i in range(vals.shape[0]):
            row = vals[i]
            good = np.flatnonzero(np.isfinite(row))
            if good.size:
                vals[i] = np.interp(np.arange(row.size), good, row[good])
        for j in range(vals.shape[1]):
            col = vals[:, j]
            good = np.flatnonzero(np.isfinite(col))
            if good.size:
                vals[:, j] = np.interp(np.arange(col.size), good, col[good])
    return RectBivariateSpline(eo.u, eo.v, np.nan_to_num(vals), kx=3, ky=3, s=0)


def segment_geometry(case, eo: EaseOff, roll: np.ndarray, pairs: Sequence[int], segments: int,
                     spacing: str = "cosine", edges: tuple[float, float] | None = None,
                     edge_limit: float | None = None):
    """Contact segments of every (roll, pair): the LTCA discretisation (seed §3.3, Fig. 3.3).

    Parameters
    ----------
    case : geometry.case.Case
    eo : contact.easeoff.EaseOff
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
    :data:`contact.edge.EDGE_KINDS` for an edge segment; ``midpoint`` (gear frame) and
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
    # its fields follow the quadratic through the three (_SegmentQuadratic)
    fields = _Fields(eo)
    cc = contact_curves(eo, target, n_point=2 * segments + 1, spacing=spacing,
                        near_misses=True, fields=fields)
    (J, K), S = target.shape, segments
    quad = _SegmentQuadratic(CURVE_SPACINGS[spacing](2 * S + 1))
    kin = eo.kinematics
    # member rotations of each curve: pinion φ = roll_zero + s_p q, gear at the ideal ψ;
    # pair k's points then lie on the teeth k pitches away at the roll's own rotations
    phi = eo.roll_zero + eo.drive_sense * target  # (J, K)
    psi = eo.gear_phase - phi / eo.ratio

    def gear_to_pair(x, vec=False):
        return _gear_to_pair(kin, psi[..., None], x, vec)

    # the real pinion touches a gear point at the pair's own instant, which near the
    # pinion's tip or ends can lie beyond its blank (the curve ends where the *conjugate*
    # mate leaves it): each segment is clipped to the part [a, b] whose real mate lies
    # inside the pinion blank, at the crossing of the blank measure, so the contact line
    # ends on the blank edge whatever the segment count
    a, b = quad.clip(_blank_measure(case, kin, "pinion", gear_to_pair(cc.position), phi))
    # a curve shrunk to a point (a pair just meeting a corner of the flank) has no
    # segment either
    whole = cc.position[..., 2::2, :] - cc.position[..., 0:-1:2, :]  # whole-segment chords
    inside = (b - a > _MIN_CLIP) & (np.linalg.norm(whole, axis=-1) > 0)
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
    mid_pair = gear_to_pair(pos_g)
    ends_pair = np.stack([gear_to_pair(end_a), gear_to_pair(end_b)], axis=-2)
    # the gear normal points out of the gear; the contact normal out of the pinion is −n_g
    n_pair = -gear_to_pair(nrm_g, vec=True)
    # unit tangent of the chord (of the whole segment where it is clipped away)
    chord = np.where(inside[..., None], chord, whole)
    norm = np.linalg.norm(chord, axis=-1, keepdims=True)
    tangent = chord / np.where(norm > 0, norm, np.nan)
    t_pair = gear_to_pair(tangent, vec=True)
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
        uu = _fill_rows(u.reshape(J * K, S)[rows], okc)
        vv = _fill_rows(v.reshape(J * K, S)[rows], okc)
        pg = pos_g.reshape(J * K, S, 3)[rows]
        pg = np.stack([_fill_rows(pg[..., i], okc) for i in range(3)], axis=-1)
        # across-line direction w = n × t in the gear frame (carried to the pinion frame
        # at each curve's pinion rotation)
        w_g = np.nan_to_num(np.cross(nrm_g, tangent)).reshape(J * K, S, 3)[rows]
        phi_r = np.broadcast_to(phi[..., None], u.shape).reshape(J * K, S)[rows]
        kg = _gear_curvature(case, eo, pg, w_g)
        kp = _pinion_curvature(case, eo, uu, vv, w_g, phi_r)
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
        edge = _edge_segments(case, eo, bd, radii, target, shift, ute_env, edge_limit)
        edge_arm_max = float(np.max(bd.normal_arm, initial=0.0))
        out = {k: np.concatenate([out[k], edge[k]], axis=2) for k in out}
        kind = np.r_[kind, 1 + bd.kind].astype(np.int8)
    return {
        **out, "kind": kind,
        "ute": cc.ute.reshape(J, K), "pinion_rotation": rp,
        "gear_rotation": eo.gear_phase - rp / eo.ratio, "shape": (J, K, kind.size),
        "edge_arm_max": edge_arm_max,
    }


def _edge_segments(case, eo: EaseOff, bd: FlankBoundary, edge_radius: tuple[float, float],
                   target: np.ndarray, shift: np.ndarray, ute_env: np.ndarray,
                   limit: float | None = None) -> dict:
    """Edge segments of every (roll, pair): the boundary where the pair's curve passes
    outside the contact region (:mod:`contact.edge`), clipped where it passes inside.

    Parameters
    ----------
    case : geometry.case.Case
    eo : EaseOff
    bd : FlankBoundary (E segments)
    edge_radius : (float, float) — [mm] the pinion's and the gear's edge rounding radius
        (R_eq: :func:`_edge_r_eq`)
    target, shift : arrays (J, K) — [rad] roll value q of each pair and its curve's shift t
    ute_env : array (J,) — [rad] each roll's UTE (the least over its pairs)
    limit : float, optional — [mm] see :func:`segment_geometry`'s ``edge_limit``

    Returns
    -------
    dict of arrays (J, K, E[, ...]), the keys of :func:`segment_geometry`'s segment
    fields; the lag is the mean of Φ_q = ε + ½ K (Q − q)² over the part in edge contact.
    NaN (length 0) where the pair's curve passes inside the region all along the
    boundary segment, or its separation is surely above ``limit``.

    Notes
    -----
    A gear edge touches the pinion flank at the gear's edge point x itself; it is clipped
    where the real pinion at the pair's roll has no flank across x (beyond its blank), as
    the curves are. A pinion edge point P is the mate of the boundary point x at the
    instant Q(x); at roll q it has turned on by s_p (q − Q(x)) with the pinion, and the
    contact sits there (P's separation is Φ_q(x) to first order: the gap function on the
    pinion's surface has the same form).
    """
    kin = eo.kinematics
    quad = _SegmentQuadratic(np.array([0.0, 0.5, 1.0]))
    J, K = target.shape
    E = bd.kind.size
    # ≥ 0 where the curve Q = q + t passes outside the region beyond the boundary point;
    # only the (roll, pair, boundary segment) where it does somewhere are worked out
    # (flattened to n candidates), the rest stay NaN (no edge contact)
    outside = ((bd.roll_angle[None, None] - (target + shift)[..., None, None])
               * bd.inward_slope)  # (J, K, E, 3)
    cand = np.any(outside >= 0, axis=-1)
    # Φ_q = ε + ½ K (Q − q)² at the samples of every boundary segment [rad]
    phi_s = (bd.ease_off_angle + 0.5 * bd.gap_curvature
             * (bd.roll_angle - target[..., None, None]) ** 2)  # (J, K, E, 3)
    if limit is not None:
        # the separation's lower bound: Φ_q at the samples, less the quadratic's second
        # difference (its dip below the samples is at most a quarter of that), times
        # the least normal arm
        dip = np.abs(phi_s[..., 0] - 2.0 * phi_s[..., 1] + phi_s[..., 2])
        low = np.min(phi_s, axis=-1) - dip - ute_env[:, None, None]
        cand &= ~(np.min(bd.normal_arm, axis=-1) * low > limit)
    jj, kk, ee = np.nonzero(cand)
    outside = outside[jj, kk, ee]  # (n, 3)
    q = target[jj, kk][:, None]  # (n, 1) roll value of the candidate's pair
    phi = eo.roll_zero + eo.drive_sense * target[jj, kk]  # (n,) pinion rotation
    psi = eo.gear_phase - phi / eo.ratio
    # the contact points in the pair frame: a gear edge's own points; a pinion edge's
    # points turned on with the pinion from their mate instant
    pts = _gear_to_pair(kin, psi[:, None], bd.position[ee])  # (n, 3, 3)
    g = bd.gear_edge[ee]
    if np.any(~g):
        q_m = bd.roll_angle[ee[~g]]  # (np, 3) mate instants
        phi_m = eo.roll_zero + eo.drive_sense * q_m
        mate = _gear_to_pair(kin, eo.gear_phase - phi_m / eo.ratio, bd.position[ee[~g]])
        turn = eo.drive_sense * (q[~g] - q_m)
        pts[~g] = _rotate(kin.pinion_axis, turn, mate - kin.pinion_origin) + \
            kin.pinion_origin
    # each part in contact lies on the mating member's flank: within its blank
    for sel, member, turn in ((g, "pinion", phi), (~g, "gear", psi)):
        if np.any(sel):
            m = _blank_measure(case, kin, member, pts[sel], turn[sel])
            outside[sel] = np.minimum(outside[sel], m)
    a, b = (x[..., 0] for x in quad.clip(outside))  # (n,)
    a1, b1, c1 = a[:, None], b[:, None], 0.5 * (a + b)[:, None]
    sep = phi_s[jj, kk, ee]  # (n, 3)
    inside = b - a > _MIN_CLIP
    # R_eq of the boundary segments in edge contact somewhere
    used = np.unique(ee[inside])
    r_eq = np.full(E, np.nan)
    r_eq[used] = _edge_r_eq(case, eo, bd, edge_radius, used)
    nrm = quad.at(bd.normal[ee], c1, vector=True)[:, 0]
    nrm = nrm / np.linalg.norm(nrm, axis=-1, keepdims=True)
    end_a = quad.at(pts, a1, vector=True)[:, 0]
    end_b = quad.at(pts, b1, vector=True)[:, 0]
    chord = end_b - end_a
    length = np.where(inside, np.linalg.norm(chord, axis=-1), 0.0)
    chord = np.where(inside[:, None], chord, pts[:, 2] - pts[:, 0])
    fields = {
        "u": np.where(inside, quad.at(bd.u[ee], c1)[:, 0], np.nan),
        "v": np.where(inside, quad.at(bd.v[ee], c1)[:, 0], np.nan),
        "midpoint": quad.at(bd.position[ee], c1, vector=True)[:, 0],
        "midpoint_pair": quad.at(pts, c1, vector=True)[:, 0],
        "ends_pair": np.stack([end_a, end_b], axis=-2),
        "normal_pair": -_gear_to_pair(kin, psi, nrm, vec=True),
        "tangent_pair": chord / np.linalg.norm(chord, axis=-1, keepdims=True),
        "length": length,
        "moment_arm": quad.at(bd.normal_arm[ee], c1)[:, 0],
        "lag": quad.mean(sep, a1, b1)[:, 0],
        "r_eq": np.where(inside, r_eq[ee], np.nan),
    }
    out = {}
    for key, val in fields.items():
        full = np.full((J, K, E, *val.shape[1:]), 0.0 if key == "length" else np.nan)
        full[jj, kk, ee] = val
        out[key] = full
    return out


def _gear_to_pair(kin, psi, x: np.ndarray, vec: bool = False) -> np.ndarray:
    """Gear-frame points (or vectors) x (..., 3) [mm] into the pair frame with the gear
    turned by ψ [rad] (broadcast against x's leading axes)."""
    shape = np.broadcast_shapes(np.shape(psi), x.shape[:-1])
    x = np.broadcast_to(x @ kin.gear_place[:3, :3].T, (*shape, 3))
    q = _rotate(kin.gear_axis, np.broadcast_to(psi, shape), x)
    return q if vec else q + kin.gear_origin


def _pinion_curvature(case, eo: EaseOff, u, v, w_gear, phi):
    """Normal curvature [1/mm] of the real pinion, at the mates of gear places (u, v),
    along gear-frame directions ``w_gear`` (..., 3), the pinion turned by φ [rad] and the
    gear at its ideal rotation (the directions are carried to the pinion frame)."""
    kin = eo.kinematics
    ps = flank_at(case, "pinion", eo.pinion_flank, _spline(eo, eo.pinion_axial).ev(u, v),
                  _spline(eo, eo.pinion_radius).ev(u, v),
                  guess=_node_guess(eo, eo.pinion_parameters, eo.pinion_section, u, v))
    w_pair = _gear_to_pair(kin, eo.gear_phase - phi / eo.ratio, w_gear, vec=True)
    w_p = _rotate(kin.pinion_axis, -np.broadcast_to(phi, u.shape), w_pair) @ \
        kin.pinion_place[:3, :3]
    return normal_curvature(ps.kappa1, ps.kappa2, ps.dir1, w_p)


def _node_guess(eo: EaseOff, params, section, u, v):
    """Envelope-parameter guesses (s, θ, q, section) at gear places (u, v): those of the
    nearest gear grid node (``params`` (nu, nv, 3), ``section`` (nu, nv) of the ease-off;
    None where the ease-off has none)."""
    if params is None or section is None:
        return None
    iu = np.rint(np.interp(u, eo.u, np.arange(eo.u.size))).astype(int)
    iv = np.rint(np.interp(v, eo.v, np.arange(eo.v.size))).astype(int)
    par = params[iu, iv]
    return par[..., 0], par[..., 1], par[..., 2], section[iu, iv]


def _gear_curvature(case, eo: EaseOff, position, w_gear):
    """Normal curvature [1/mm] of the real gear at gear-frame points along ``w_gear``."""
    z, rho = position[..., 2], np.hypot(position[..., 0], position[..., 1])
    u, v = projection_fractions(blank_outline(case.gear.blank).corners, z, rho)
    guess = _node_guess(eo, eo.gear_parameters, eo.gear_section, np.clip(u, 0.0, 1.0),
                        np.clip(v, eo.v[0], eo.v[-1]))
    gs = flank_at(case, "gear", eo.gear_flank, z, rho, guess=guess)
    return normal_curvature(gs.kappa1, gs.kappa2, gs.dir1, w_gear)


def _edge_r_eq(case, eo: EaseOff, bd: FlankBoundary, edge_radius: tuple[float, float],
               which: np.ndarray) -> np.ndarray:
    """R_eq [mm] across the boundary segments ``which`` (indices (M,)): the edge's
    rounding (radius r_e: ``edge_radius`` (pinion, gear) [mm], the edge's own member's)
    on the other member's flank, 1/(1/r_e + κ_other) at the segment's middle (κ_other
    along n × t, t the edge tangent; the pinion taken at its mate's instant Q)."""
    if which.size == 0:
        return np.zeros(0)
    u, v = bd.u[which, 1], bd.v[which, 1]
    pos, nrm = bd.position[which, 1], bd.normal[which, 1]
    t = bd.position[which, 2] - bd.position[which, 0]
    w = np.cross(nrm, t / np.linalg.norm(t, axis=-1, keepdims=True))
    k_other = np.empty(u.size)
    g = bd.gear_edge[which]
    if np.any(g):
        phi = eo.roll_zero + eo.drive_sense * bd.roll_angle[which[g], 1]
        k_other[g] = _pinion_curvature(case, eo, u[g], v[g], w[g], phi)
    if np.any(~g):
        k_other[~g] = _gear_curvature(case, eo, pos[~g], w[~g])
    krel = 1.0 / np.where(g, edge_radius[1], edge_radius[0]) + k_other
    return np.where(np.isfinite(krel), 1.0 / np.maximum(krel, 1e-4), np.nan)


class _SegmentQuadratic:
    """Quadratic interpolation within each segment of a curve sampled at 2S + 1 points.

    Segment k spans the samples 2k (τ = 0), 2k + 1 (τ = τ_m) and 2k + 2 (τ = 1), τ the
    fraction of the segment's parameter span; the Lagrange quadratic through the three
    gives a field at any τ (error O(h³)) and its mean over [a, b] (exact for quadratics).

    Parameters
    ----------
    fractions : array (2S + 1,) — [1]
        The sample fractions along the curve (:data:`contact.utca.CURVE_SPACINGS`).
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


def _blank_measure(case, kin, member: str, points_pair: np.ndarray,
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
    x = _rotate(axis, -np.broadcast_to(turn[..., None], points_pair.shape[:-1]),
                points_pair - origin) @ place
    fu, fv = projection_fractions(blank_outline(case.member(member).blank).corners, x[..., 2],
                        np.hypot(x[..., 0], x[..., 1]))
    return np.minimum(np.minimum(fu, 1.0 - fu), 1.0 - fv)


def _fill_rows(a: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """Replace invalid entries of each row by linear interpolation/extension of the valid."""
    out = np.array(a, dtype=float)
    idx = np.arange(out.shape[1])
    for i in range(out.shape[0]):
        good = valid[i] & np.isfinite(out[i])
        out[i] = np.interp(idx, idx[good], out[i, good])
    return out


def loaded_tca(
    case,
    torque: Sequence[float] | float,
    *,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    easeoff: EaseOff | None = None,
    progress: bool = False,
    problem_sink: Callable[[ContactProblem], None] | None = None,
    transitions: tuple[float, float] | None = None,
) -> xr.Dataset:
    """Loaded TCA of a case at one or more torques over whole mesh cycles (seed §3.3–3.4).

    Parameters
    ----------
    case : geometry.case.Case
    torque : float or sequence of float — [N·m]
        Pinion torques T_p (> 0), the seed's operating variable (Fig. 3.6, Table 3.1).
        The contact problem carries the gear torque T_g = T_p z_g/z_p (static and
        lossless: friction enters only in the efficiency stage).
    misalignment : geometry.assembly.Misalignment, optional
        ΔE, ΔP, ΔG [mm], ΔΣ [rad]; defaults to the case's own.
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    options : LTCAOptions, optional
    easeoff : contact.easeoff.EaseOff, optional
        A precomputed ease-off of the same case, flank and misalignment.
    progress : bool
        Show a progress bar over roll positions.
    problem_sink : callable, optional
        Called with the final :class:`contact.ContactProblem` of every (torque, roll)
        (after the Weber iteration), e.g. to collect real problems for a solver study.
    transitions : (float, float), optional — [rad]
        The transition rolls (M1, M2) of the same ease-off, as
        :func:`contact.utca.transitions` gives them with its defaults (e.g. the
        ``transition_roll`` of :func:`contact.utca.unloaded_tca`, which the pipeline has
        already computed); default: computed here. The roll positions start at M1.

    Returns
    -------
    xarray.Dataset
        The ``/ltca`` dataset (exchange names: ``transmission_error`` [urad] over
        (``torque``, ``roll``); ``force`` [N] and ``pressure_max`` [MPa] over
        (``torque``, ``roll``, ``pair``, ``segment``); ``load_share`` [1] over
        (``torque``, ``roll``, ``pair``); ``torque`` coordinate [N m]), plus load per
        length, half-width, contact and edge flags, separations, residuals, solver
        status and times, and the LTE summary over the mesh cycles.

    Raises
    ------
    InputError
        For bad torques or options (the message names the field).
    """
    opts = options or LTCAOptions()
    torques = np.atleast_1d(np.asarray(torque, dtype=float))
    if torques.ndim != 1 or torques.size == 0 or not np.all(np.isfinite(torques)) or np.any(
        torques <= 0
    ):
        raise InputError(f"torque: must be finite values > 0 [N m], got {torque!r}")
    if misalignment is not None:
        case = dataclasses.replace(case, misalignment=misalignment)
    t0 = time.perf_counter()
    eo = easeoff if easeoff is not None else ease_off(case, flank=flank)
    t_easeoff = time.perf_counter() - t0
    if transitions is None:
        m1, m2 = _transitions(eo)
    else:
        try:
            m1, m2 = (float(m) for m in transitions)
        except (TypeError, ValueError) as exc:
            raise InputError("transitions: must be (M1, M2) [rad] (NaN where none), got "
                             f"{transitions!r}") from exc
    start = m1 if math.isfinite(m1) else 0.0
    n_roll = opts.cycles * opts.rolls_per_cycle
    roll = start + np.arange(n_roll) * eo.pitch / opts.rolls_per_cycle
    # edge segments surely separated by more than a generous limit are not worked out
    # (segment_geometry's edge_limit); the limit is checked against the solution's
    # R Θ and the analysis repeated with a wider one if it was too tight
    edge_limit = None
    if opts.edge_contact:
        edge_limit = opts.separation_limit or _generous_limit(float(torques.max()),
                                                              eo.ratio)
    while True:
        sink: list[ContactProblem] | None = [] if problem_sink is not None else None
        t1 = time.perf_counter()
        seg = segment_geometry(case, eo, roll, opts.pairs, opts.segments, opts.spacing,
                               (opts.edge_step, _edge_radii(case, opts)) if opts.edge_contact
                               else None, edge_limit=edge_limit)
        t_segments = time.perf_counter() - t1
        ds, reach = _solve_rolls(case, eo, opts, torques, roll, seg, m1, m2, progress, sink,
                                 timing={"easeoff": t_easeoff, "segments": t_segments})
        # the pairs must span every tooth pair in mesh: the window of roll values they
        # cover ends at the last roll for the lowest pair and at the first roll for the
        # highest; a pair loaded there has a neighbour beyond it that may be loaded too
        share = np.nan_to_num(ds["load_share"].values)  # (torque, roll, pair)
        last = np.arange(opts.cycles) * opts.rolls_per_cycle + opts.rolls_per_cycle - 1
        lo, hi = int(np.argmin(opts.pairs)), int(np.argmax(opts.pairs))
        more = (min(opts.pairs) - 1 if np.any(share[:, last, lo] > 1e-6) else None,
                max(opts.pairs) + 1 if np.any(share[:, last - opts.rolls_per_cycle + 1, hi]
                                             > 1e-6) else None)
        widen = edge_limit is not None and opts.separation_limit is None and reach > edge_limit
        if (more == (None, None) or len(opts.pairs) >= _MAX_PAIRS) and not widen:
            break
        if more != (None, None) and len(opts.pairs) < _MAX_PAIRS:
            pairs = tuple(sorted({*opts.pairs, *(k for k in more if k is not None)}))
            log.info("pairs %s: an outermost pair is loaded at the end of the window; "
                     "again with %s", opts.pairs, pairs)
            opts = dataclasses.replace(opts, pairs=pairs)
        if widen:
            log.info("edge segments: R Θ reached %.3g mm beyond the limit %.3g mm; again "
                     "with %.3g mm", reach, edge_limit, 2.0 * reach)
            edge_limit = 2.0 * reach
    if problem_sink is not None:
        for problem in sink:
            problem_sink(problem)
    return ds


def _edge_radii(case, opts: LTCAOptions) -> tuple[float, float]:
    """(pinion, gear) rounding radii of the tooth edges [mm]: ``opts.edge_radius`` if set,
    else each member's blank ``edge_break_radius``."""
    if opts.edge_radius is not None:
        return float(opts.edge_radius), float(opts.edge_radius)
    return (float(case.pinion.blank.edge_break_radius),
            float(case.gear.blank.edge_break_radius))


def _solve_rolls(case, eo: EaseOff, opts: LTCAOptions, torques: np.ndarray, roll: np.ndarray,
                 seg: dict, m1: float, m2: float, progress: bool,
                 sink: list | None, timing: dict) -> tuple[xr.Dataset, float]:
    """The contact problems of every (torque, roll) of :func:`loaded_tca` on the segments
    ``seg`` (:func:`segment_geometry`); returns the ``/ltca`` dataset and the largest
    R Θ [mm] the edge segments could reach (greatest boundary arm × greatest Θ), which
    must not exceed the ``edge_limit`` the segments were worked out with. The final
    problems are appended to ``sink`` (if given) in order."""
    ute_env = np.nanmin(seg["ute"], axis=1)  # (J,)
    if not np.all(np.isfinite(ute_env)):
        raise InputError("no tooth pair is in contact at some roll position (check the case)")

    # separation s = R (lag − UTE) [mm] of every segment; ``ok``: the segments with the
    # data of a contact problem (finite s and R_eq, a part inside the blanks)
    arm = seg["moment_arm"]
    sep_all = arm * (seg["lag"] - ute_env[:, None, None])
    ok_all = np.isfinite(sep_all) & np.isfinite(seg["r_eq"]) & (seg["length"] > 0)
    J, K, S = seg["shape"]
    fixed = opts.separation_limit
    limit_max = _generous_limit(float(torques.max()), eo.ratio)

    def generous(j: int) -> np.ndarray:
        # the first pool, before any rotation is known
        return ok_all[j] & (sep_all[j] <= limit_max)

    def near(j: int, theta: float) -> np.ndarray:
        # the segments a loaded rotation θ [rad] may close: s < R θ with a margin
        return ok_all[j] & (sep_all[j] < _SCREEN_MARGIN * arm[j] * max(theta, 0.0)
                            + _SCREEN_PAD)

    model = pair_compliance_model(
        case, theory=opts.theory, n_height=opts.n_height, n_face=opts.n_face,
        pinion_material=(opts.youngs_modulus, opts.poisson_ratio),
        gear_material=(opts.youngs_modulus, opts.poisson_ratio),
    )
    E, nu = opts.youngs_modulus, opts.poisson_ratio
    NT = torques.size
    shape4 = (NT, J, K, S)
    out = {k: np.full(shape4, np.nan) for k in ("force", "load_per_length", "pressure_max",
                                                "half_width")}
    contact = np.zeros(shape4, np.int8)
    in_problem = np.zeros(shape4, np.int8)
    rotation = np.full((NT, J), np.nan)
    resid = {r: np.full((NT, J), np.nan) for r in _RESIDUALS}
    found = np.zeros((NT, J), np.int8)
    status = np.full((NT, J), "", dtype=object)
    solve_time = np.zeros((NT, J))
    compliance_time = np.zeros(J)
    weber_iters = np.zeros((NT, J), np.int64)
    n_seg = np.zeros(J, np.int64)
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=J, desc="LTCA", unit="roll")
    # the structural compliance (shells and foundations) of a pool of segments per
    # computed roll, all rolls' segments mapped onto the shells in one batch
    # (mesh_compliance_many); a torque's problem takes the sub-matrix of its selection
    pool: dict[int, np.ndarray] = {}  # (K, S) the segments of the assembled compliance
    structural: dict[int, tuple[np.ndarray, np.ndarray]] = {}

    def assemble(jobs: list[tuple[int, np.ndarray]]) -> None:
        batch = []
        for j, mask in jobs:
            wk, ws = np.nonzero(mask)
            batch.append(ContactSegments(
                midpoints=seg["midpoint_pair"][j, wk, ws],
                ends=seg["ends_pair"][j, wk, ws],
                normals=seg["normal_pair"][j, wk, ws],
                length=seg["length"][j, wk, ws],
                r_eq=seg["r_eq"][j, wk, ws],
                pair_index=np.asarray(opts.pairs)[wk],
                # (Weber's part is replaced below; a unit line load keeps it defined)
                load=seg["length"][j, wk, ws],
                pinion_rotation=float(seg["pinion_rotation"][j]),
                gear_rotation=float(seg["gear_rotation"][j]),
            ))
        try:
            mats = mesh_compliance_many(case, batch, model=model)
        except InputError as exc:
            if fixed is None:
                raise
            raise InputError(
                f"separation_limit: {fixed:g} mm takes in segments so far from contact that "
                "their points lie off the mating tooth (far pairs' edges); use a smaller "
                f"limit or the default screening (None): {exc}") from exc
        for (j, mask), (C_full, info) in zip(jobs, mats, strict=True):
            pool[j] = mask
            structural[j] = (C_full - info["weber"], info["weber_depth"])
            compliance_time[j] += info["time"]

    def weber_solve(j: int, T: float, sel: np.ndarray, prior: np.ndarray | None):
        """The contact problem of roll j at torque T on the segments ``sel``, with the
        Weber compliance iterated to the solution's loads; ``prior`` (N,) [N] (NaN where
        unknown) the forces of a neighbouring solution, a warm start for the solver."""
        idx = np.argwhere(sel)  # (N, 2): pair index, segment index
        kk, ss = idx[:, 0], idx[:, 1]
        sub = np.flatnonzero(sel[pool[j]])  # positions of the selection in the pool
        C_pool, depth_pool = structural[j]
        C_struct = C_pool[np.ix_(sub, sub)]
        depth = depth_pool[sub]
        L = seg["length"][j, kk, ss]
        Req = seg["r_eq"][j, kk, ss]
        R = arm[j, kk, ss]
        s = sep_all[j, kk, ss]
        Tn = T * eo.ratio * 1e3  # gear torque [N·mm]
        # Weber's formula holds while the Hertz half-width b is well below the depth h
        # (ln(2h/b) − ν/(2(1−ν)) > 0); loads are capped where b would reach h, i.e.
        # w′ ≤ π E* h²/(4 R_eq) — beyond that a segment is in gross edge contact and
        # the secant compliance is frozen at the cap (logged)
        e_star = E / (2 * (1 - nu**2))
        cap = np.pi * e_star * np.min(depth, axis=1) ** 2 / (4 * Req) * L  # [N]
        # first Weber loads: the torque shared evenly over the roll's curve segments (not
        # the neighbour's loads, nor the selection's: the roll's result then depends on
        # the roll alone, not on the path to it or on which edge segments were worked out)
        on_curve = ok_all[j] & (seg["kind"] == 0)
        share = Tn / max(float(np.sum(arm[j][on_curve if on_curve.any() else ok_all[j]])),
                         1e-12)
        load = np.minimum(np.full(kk.size, share), cap)
        start = None if prior is None else np.nan_to_num(prior)
        lte_prev = step_prev = None
        sol = problem = None
        n_it = time_used = 0
        for w_it in range(1, opts.max_weber_iterations + 1):
            # Newton on Weber's δ(F): δ ≈ c_s F₀ + c_t (F − F₀), c_s the secant and c_t
            # the tangent compliance at the loads F₀, i.e. compliance c_t and separation
            # s + (c_s − c_t) F₀; the secant alone where c_t is not well positive (b near
            # the depth h) or the load is at the cap (frozen there)
            cs, ct = weber_compliance(load, L, depth[:, 0], depth[:, 1], e1=E, nu1=nu, e2=E,
                                      nu2=nu, r_eq=Req, kind=("secant", "tangent"))
            newton = (ct > 0.5 * cs) & (load < cap)
            cw = np.where(newton, ct, cs)
            problem = ContactProblem(C_struct + np.diag(cw),
                                     s + np.where(newton, (cs - ct) * load, 0.0), R, Tn,
                                     name=f"{case.name} roll {j} T {T:g}")
            sol = solve_contact(problem, opts.solver,
                                initial=sol if sol is not None else start)
            time_used += sol.solve_time + sol.build_time
            if not sol.found:
                break
            load = np.minimum(np.maximum(sol.force, 0.0), cap)
            if np.any(sol.force > cap):
                log.info("roll %d: Weber load cap reached on %d segments", j,
                         int(np.sum(sol.force > cap)))
            lte = sol.rotation * 1e6
            n_it = w_it
            if lte_prev is not None:
                step = abs(lte - lte_prev)
                # Newton's steps shrink quadratically once close (the last step below
                # 1000 tolerances) where every loaded segment took it: the next step is
                # then about step²/(last step), asked to be ten times below the tolerance
                quadratic = (step_prev is not None
                             and step_prev < 1000.0 * opts.weber_tolerance
                             and bool(np.all(newton[load > 0])))
                if step < opts.weber_tolerance or (
                        quadratic and step * step < 0.1 * opts.weber_tolerance * step_prev):
                    break
                step_prev = step
            lte_prev = lte
        return sol, problem, kk, ss, n_it, time_used

    problems: dict[tuple[int, int], ContactProblem] = {}
    last_force: list[np.ndarray | None] = [None] * NT  # forces of the last computed roll [N]
    last_theta: list[float | None] = [None] * NT  # its LTE Θ + UTE [rad]
    computed = [j for j in range(J) if int(seg["source"][j]) == j and ok_all[j].any()]
    if fixed is not None:
        assemble([(j, ok_all[j] & (sep_all[j] <= fixed)) for j in computed])
    elif computed:
        assemble([(computed[0], generous(computed[0]))])
    for j in range(J):
        src = int(seg["source"][j])
        if src != j:
            # a roll whole mesh cycles after ``src``: its segments, separations and hence
            # its contact problems are identical (segment_geometry), so are the results
            for arr in (*out.values(), contact, in_problem, *resid.values(), rotation, found,
                        status, weber_iters):
                arr[:, j] = arr[:, src]
            for it in range(NT):
                if sink is not None and (it, src) in problems:
                    sink.append(dataclasses.replace(
                        problems[it, src], name=f"{case.name} roll {j} T {torques[it]:g}"))
            n_seg[j] = n_seg[src]
            if bar is not None:
                bar.update()
            continue
        for it, T in enumerate(torques):
            if j not in pool or not pool[j].any():
                status[it, j] = "no segment within the separation limit"
                continue
            # the segments that may touch: the whole pool, or (screening) those the
            # LTE of the last computed roll at this torque would close here
            if fixed is not None or last_theta[it] is None:
                sel = pool[j]
            else:
                sel = near(j, last_theta[it] - ute_env[j]) & pool[j]
                if not sel.any():
                    sel = pool[j]
            # the last computed roll's forces on the same (pair, segment) start the
            # Weber iteration and (backends that take one) the solver
            prior = None if last_force[it] is None else last_force[it][sel]
            for _round in range(_SCREEN_ROUNDS):
                if np.any(sel & ~pool[j]):
                    assemble([(j, pool[j] | sel)])
                sol, problem, kk, ss, n_it, t_used = weber_solve(j, T, sel, prior)
                solve_time[it, j] += t_used
                if not sol.found:
                    break
                # a segment left out keeps its gap open if s + C F − R Θ ≥ 0: checked
                # exactly within the assembled pool, and beyond it by s ≥ R Θ (the
                # compliances are ≥ 0); then the solution is that of all segments
                rest = pool[j] & ~sel
                missed = ok_all[j] & ~sel & ~pool[j] & (sep_all[j] < arm[j] * sol.rotation)
                if rest.any():
                    C_pool = structural[j][0]
                    gap = (sep_all[j][rest] - arm[j][rest] * sol.rotation
                           + C_pool[np.ix_(np.flatnonzero(rest[pool[j]]),
                                           np.flatnonzero(sel[pool[j]]))] @ sol.force)
                    missed[rest] = gap < 0.0
                if not missed.any():
                    break
                if fixed is not None:
                    log.warning("roll %d, torque %g N m: %d segments beyond the separation "
                                "limit %g mm would touch", j, T, int(missed.sum()), fixed)
                    break
                # the missed ones and, within the assembled pool, those nearly missed
                sel = sel | missed | (near(j, sol.rotation) & pool[j])
                full = np.full((K, S), np.nan)
                full[kk, ss] = np.maximum(sol.force, 0.0)
                prior = full[sel]
            else:
                log.warning("roll %d, torque %g N m: the screening of the segments did not "
                            "settle in %d rounds", j, T, _SCREEN_ROUNDS)
                sol = dataclasses.replace(sol, found=False,
                                          status="segment screening did not settle")
            weber_iters[it, j] = n_it
            n_seg[j] = max(n_seg[j], kk.size)
            if sink is not None:
                sink.append(problem)
                problems[it, j] = problem
            found[it, j] = int(sol.found)
            status[it, j] = sol.status
            for r in _RESIDUALS:
                resid[r][it, j] = sol.residuals[r]
            if not sol.found:
                log.warning("roll %d, torque %g N m: %s", j, T, sol.status)
                continue
            F = sol.force
            rotation[it, j] = sol.rotation
            last_theta[it] = sol.rotation + ute_env[j]
            last_force[it] = np.full((K, S), np.nan)
            last_force[it][kk, ss] = F
            L = seg["length"][j, kk, ss]
            Req = seg["r_eq"][j, kk, ss]
            w = F / L
            b = hertz_half_width(np.maximum(w, 1e-12), Req, E, nu, E, nu)
            pmax = np.where(F > 0, 2 * w / (np.pi * b), 0.0)
            out["force"][it, j, kk, ss] = F
            out["load_per_length"][it, j, kk, ss] = w
            out["half_width"][it, j, kk, ss] = np.where(F > 0, b, 0.0)
            out["pressure_max"][it, j, kk, ss] = pmax
            contact[it, j, kk, ss] = sol.active_set.astype(np.int8)
            in_problem[it, j, kk, ss] = 1
        if fixed is None and computed and j == computed[0]:
            # the pools of the other rolls: the segments this roll's LTE at the largest
            # torque would close there (the LTE varies little over the cycle; a segment
            # missed is added when its roll is solved)
            it_max = int(np.argmax(torques))
            jobs = []
            for i in computed[1:]:
                mask = (near(i, ute_env[j] + rotation[it_max, j] - ute_env[i])
                        if found[it_max, j] else generous(i))
                jobs.append((i, mask if mask.any() else generous(i)))
            if jobs:
                assemble(jobs)
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    # the segment axis keeps the curve segments and the edge segments in some problem
    keep = (seg["kind"] == 0) | np.any(in_problem > 0, axis=(0, 1, 2))
    seg = _keep_segments(seg, keep)
    sep_all, contact, in_problem = sep_all[..., keep], contact[..., keep], in_problem[..., keep]
    out = {k: v[..., keep] for k, v in out.items()}
    reach = float(seg["edge_arm_max"]) * float(np.nanmax(rotation, initial=0.0))
    return _ltca_dataset(case, eo, opts, torques, roll, seg, sep_all, ute_env, out, contact,
                         in_problem, rotation, resid, found, status, solve_time, weber_iters,
                         compliance_time, n_seg, m1, m2, timing=timing), reach


def _ltca_dataset(case, eo, opts, torques, roll, seg, sep_all, ute_env, out, contact,
                  in_problem, rotation, resid, found, status, solve_time, weber_iters,
                  compliance_time, n_seg, m1, m2, timing) -> xr.Dataset:
    NT, _J, _K, S = out["force"].shape
    F = np.nan_to_num(out["force"])
    R = np.nan_to_num(seg["moment_arm"])[None]
    pair_torque = np.sum(F * R, axis=-1)  # (NT, J, K) N·mm
    share = pair_torque / np.maximum(pair_torque.sum(axis=-1, keepdims=True), 1e-300)
    share = np.where(found[..., None] > 0, share, np.nan)
    lte = (ute_env[None, :] + rotation) * 1e6  # urad
    # edge contact: the first or last segment of a curve (on the flank boundary: the gear
    # blank's edge where the curve ends, the pinion blank's edge where it is clipped) or an
    # edge segment loaded
    loaded = contact > 0
    curve = seg["kind"] == 0
    valid = np.isfinite(seg["r_eq"]) & (seg["length"] > 0)
    edge = (_edge_loaded(loaded[..., curve], valid[..., curve])
            | np.any(loaded[..., ~curve], axis=-1)).astype(np.int8)
    pairs_in_contact = np.sum(np.any(loaded, axis=-1), axis=-1)
    # LTE summary over the mesh cycles
    harm = np.full((NT, 3), np.nan)
    summ = {k: np.full(NT, np.nan) for k in ("mean", "peak_to_peak", "rms", "harmonic_rss")}
    # harmonics the roll sampling resolves: 2n + 1 ≤ samples per cycle (else NaN)
    n_h = min(3, (roll.size // max(opts.cycles, 1) - 1) // 2)
    for it in range(NT):
        if np.all(np.isfinite(lte[it])) and n_h >= 1:
            s = transmission_error_summary(roll, lte[it], eo.pitch, n_h)
            harm[it, :n_h] = s["harmonics"]
            for k in summ:
                summ[k][it] = s[k]
    # loaded contact pattern: envelope of the maximum pressure on the gear grid nodes
    nu, nv = eo.u.size, eo.v.size
    env = np.zeros((NT, nu, nv))
    # the ease-off grid fractions are uniform in [u0, u1] × [v0, v1]: nearest node
    u0, u1 = float(eo.u[0]), float(eo.u[-1])
    v0, v1 = float(eo.v[0]), float(eo.v[-1])
    ui = np.rint((seg["u"] - u0) / (u1 - u0) * (nu - 1))
    vi = np.rint((seg["v"] - v0) / (v1 - v0) * (nv - 1))
    good = np.isfinite(ui) & np.isfinite(vi)
    uu = np.clip(np.where(good, ui, 0), 0, nu - 1).astype(int)
    vv = np.clip(np.where(good, vi, 0), 0, nv - 1).astype(int)
    for it in range(NT):
        p = np.nan_to_num(out["pressure_max"][it])
        np.maximum.at(env[it], (uu[good], vv[good]), p[good])
    pairs = np.asarray(opts.pairs)
    dims4 = ("torque", "roll", "pair", "segment")
    dims3 = ("torque", "roll", "pair")
    dims2 = ("torque", "roll")
    data = {
        "transmission_error": _var(dims2, lte, "urad",
                                   "loaded transmission error (gear lag, UTE + loaded rotation)"),
        "loaded_rotation": _var(dims2, rotation * 1e6, "urad",
                                "loaded rotation Theta of the contact problem"),
        "unloaded_transmission_error": _var(("roll",), ute_env * 1e6, "urad",
                                            "unloaded transmission error (lower envelope)"),
        "force": _var(dims4, out["force"], "N", "segment force"),
        "load_per_length": _var(dims4, out["load_per_length"], "N/mm", "load per unit length"),
        "pressure_max": _var(dims4, out["pressure_max"], "MPa",
                             "maximum Hertzian pressure (line contact)"),
        "half_width": _var(dims4, out["half_width"], "mm", "Hertzian half-width"),
        "contact": _var(dims4, contact, "1", "segment in contact (1) or open (0)"),
        "in_problem": _var(dims4, in_problem, "1",
                           "segment in the contact problem (1) or left out, its gap open "
                           "(0)"),
        "separation": _var(("roll", "pair", "segment"), sep_all, "mm",
                           "initial separation (ease-off relative to the UTE)"),
        "moment_arm": _var(("roll", "pair", "segment"), seg["moment_arm"], "mm",
                           "moment arm of the contact normal about the gear axis"),
        "segment_length": _var(("roll", "pair", "segment"), seg["length"], "mm",
                               "segment length"),
        "equivalent_radius": _var(("roll", "pair", "segment"), seg["r_eq"], "mm",
                                  "equivalent radius across the contact line"),
        "segment_u": _var(("roll", "pair", "segment"), seg["u"], "1",
                          "gear lengthwise fraction of the segment midpoint (toe 0, heel 1)"),
        "segment_v": _var(("roll", "pair", "segment"), seg["v"], "1",
                          "gear profile fraction of the segment midpoint (root 0, tip 1)"),
        "segment_position": _var(("roll", "pair", "segment", "xyz"), seg["midpoint"], "mm",
                                 "segment midpoint on the reference gear tooth, gear frame"),
        "contact_point": _var(("roll", "pair", "segment", "xyz"), seg["midpoint_pair"], "mm",
                              "segment midpoint in the pair frame at the roll position"),
        "contact_normal": _var(("roll", "pair", "segment", "xyz"), seg["normal_pair"], "1",
                               "contact normal (out of the pinion) in the pair frame"),
        "contact_tangent": _var(("roll", "pair", "segment", "xyz"), seg["tangent_pair"], "1",
                                "unit tangent of the contact line in the pair frame"),
        "load_share": _var(dims3, share, "1", "share of the gear torque carried by the pair"),
        "edge_contact": _var(dims3, edge, "1",
                             "load reaches the end of the pair's contact curve (flank edge)"),
        "pairs_in_contact": _var(dims2, pairs_in_contact, "1", "number of pairs in contact"),
        "found": _var(dims2, found, "1", "certified solution found (1) or not (0)"),
        "status": _var(dims2, status.astype(str), None, "solver status"),
        "solve_time": _var(dims2, solve_time, "s", "solver time over the Weber iterations"),
        "weber_iterations": _var(dims2, weber_iters, "1", "Weber linearisation iterations"),
        "compliance_time": _var(("roll",), compliance_time, "s", "compliance assembly time"),
        "n_segments": _var(("roll",), n_seg, "1", "segments in the contact problem"),
        **{f"residual_{r}": _var(dims2, resid[r], "1", f"relative {r} residual")
           for r in _RESIDUALS},
        "lte_mean": _var(("torque",), summ["mean"], "urad", "mean loaded transmission error"),
        "lte_peak_to_peak": _var(("torque",), summ["peak_to_peak"], "urad",
                                 "peak-to-peak loaded transmission error"),
        "lte_harmonics": _var(("torque", "harmonic"), harm, "urad",
                              "amplitude of the mesh harmonics of the LTE"),
        "lte_rms": _var(("torque",), summ["rms"], "urad", "RMS of the LTE about its mean"),
        "lte_harmonic_rss": _var(("torque",), summ["harmonic_rss"], "urad",
                                 "root-sum-square of the first three harmonic amplitudes "
                                 "(the seed's Table 3.1 RMS)"),
        "pressure_max_flank": _var(("torque",), _peak(out["pressure_max"], curve), "MPa",
                                   "peak Hertzian pressure on the contact curves (line "
                                   "contact of the flanks)"),
        "pressure_max_edge": _var(("torque",), _peak(out["pressure_max"], ~curve), "MPa",
                                  "peak Hertzian pressure of the edge contact (edge rounding "
                                  "on the mating flank; 0 where none)"),
        "pressure_envelope": _var(("torque", "u", "v"), env, "MPa",
                                  "loaded contact pattern: envelope of the maximum pressure "
                                  "over the roll positions, on the gear grid"),
    }
    coords = {
        "torque": ("torque", torques, {"units": "N m", "long_name": "pinion torque"}),
        "gear_torque": ("torque", torques * eo.ratio,
                        {"units": "N m", "long_name": "gear torque (lossless)"}),
        "roll": ("roll", roll, {"units": "rad",
                                "long_name": "pinion roll angle (Q units, driving sense)"}),
        "pair": ("pair", pairs, {"units": "1", "long_name": "tooth-pair offset"}),
        "segment": ("segment", np.arange(S), {"units": "1", "long_name": "segment index"}),
        "segment_kind": ("segment", np.array(("curve", *EDGE_KINDS))[seg["kind"]],
                         {"long_name": "contact curve segment, or the flank edge of an edge "
                                       "segment (contact.edge.EDGE_KINDS)"}),
        "harmonic": ("harmonic", np.arange(1, 4), {"units": "1",
                                                   "long_name": "mesh harmonic order"}),
        "u": ("u", np.asarray(eo.u), {"units": "1", "long_name": "gear lengthwise fraction"}),
        "v": ("v", np.asarray(eo.v), {"units": "1", "long_name": "gear profile fraction"}),
        "xyz": ("xyz", ["x", "y", "z"], {"long_name": "Cartesian component"}),
        "mesh_cycle": ("roll", (roll - roll[0]) / eo.pitch,
                       {"units": "1", "long_name": "mesh cycles from the first roll position"}),
    }
    attrs = {
        "title": "loaded tooth contact analysis",
        "case": case.name,
        "toolkit_version": __version__,
        "pinion_flank": eo.pinion_flank,
        "gear_flank": eo.gear_flank,
        "solver": opts.solver,
        "mesh_period_rad": eo.pitch,
        "transition_M1_rad": float(m1),
        "transition_M2_rad": float(m2),
        "options": json_options(opts),
        "time_easeoff_s": timing["easeoff"],
        "time_segments_s": timing["segments"],
        "misalignment": json_misalignment(case.misalignment),
        "ratio": float(eo.ratio),
        "edge_radius_pinion_mm": _edge_radii(case, opts)[0] if opts.edge_contact else np.nan,
        "edge_radius_gear_mm": _edge_radii(case, opts)[1] if opts.edge_contact else np.nan,
        "pinion_axis": np.asarray(eo.kinematics.pinion_axis, float),
        "pinion_origin_mm": np.asarray(eo.kinematics.pinion_origin, float),
        "gear_axis": np.asarray(eo.kinematics.gear_axis, float),
        "gear_origin_mm": np.asarray(eo.kinematics.gear_origin, float),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _peak(p: np.ndarray, which: np.ndarray) -> np.ndarray:
    """(NT,) largest of p (NT, J, K, S) over the segments ``which`` (0 where none)."""
    sel = np.nan_to_num(p[..., which])
    return sel.max(axis=(1, 2, 3)) if sel.size else np.zeros(p.shape[0])


def _keep_segments(seg: dict, keep: np.ndarray) -> dict:
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


def _edge_loaded(loaded: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """(..., K) whether the first or last valid segment of each curve is loaded.

    ``loaded`` (NT, J, K, S) contact flags; ``valid`` (J, K, S) the segments of each
    curve (its ends lie on the flank boundary).
    """
    S = valid.shape[-1]
    have = valid.any(axis=-1)
    first = np.argmax(valid, axis=-1)
    last = S - 1 - np.argmax(valid[..., ::-1], axis=-1)
    at_first = np.take_along_axis(loaded, np.broadcast_to(first[None, ..., None],
                                                          (*loaded.shape[:-1], 1)), -1)
    at_last = np.take_along_axis(loaded, np.broadcast_to(last[None, ..., None],
                                                         (*loaded.shape[:-1], 1)), -1)
    return (at_first[..., 0] | at_last[..., 0]) & have[None]


def json_options(opts: LTCAOptions) -> str:
    """The options as JSON text (netCDF-safe)."""
    import json

    return json.dumps(dataclasses.asdict(opts), sort_keys=True)


def json_misalignment(m) -> str:
    """A Misalignment as JSON text (ΔE, ΔP, ΔG [mm], ΔΣ [rad])."""
    import json

    return json.dumps(dataclasses.asdict(m), sort_keys=True, default=float)


def ltca_problems(case, torque, *, misalignment: Misalignment | None = None,
                  options: LTCAOptions | None = None) -> list:
    """The real contact problems of a case's LTCA, as a solver study's test set.

    Parameters
    ----------
    case : geometry.case.Case
    torque : float or sequence — [N·m] pinion torques
    misalignment : Misalignment, optional
    options : LTCAOptions, optional

    Returns
    -------
    list of contact.problem_set.TestProblem
        One per (torque, roll position), kind ``ltca``, named
        ``"<case> T<torque> roll<j>"``.
    """
    from contact.problem_set import TestProblem

    collected: list[ContactProblem] = []
    loaded_tca(case, torque, misalignment=misalignment, options=options,
               problem_sink=collected.append)
    out = []
    for i, p in enumerate(collected):
        name = p.name.replace(" ", "_") or f"{case.name}_{i}"
        out.append(TestProblem(f"{name}_{i}", "ltca", p))
    return out
