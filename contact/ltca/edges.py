"""The flank boundary as a contact line: edge contact beyond a contact curve's end.

The line model of the LTCA (seed §3.3) places the load on the instantaneous contact
curves, the valleys of the separation between the real pinion at roll q and the real gear,

    Φ_q(x) = ε(x) + ½ K(x) (Q(x) − q)²      [rad of gear lag]

(ε the angular ease-off, Q the surface of roll angle, K the pinion's gap curvature; see
:mod:`contact.utca`). Where that valley leaves the contact region, the least separation
across it lies on the region's boundary instead: the gear's tip edge or its toe or heel
end touches the pinion flank, or the pinion's tip edge or ends touch the gear flank (the
line where the pinion mate leaves its blank). This is the edge contact of an entering
pair at the corner of the flank, before its contact curve emerges, and of the stretch of
the boundary beyond any curve that ends on it.

A boundary point x is in edge contact at roll q when the curve of its pair, the iso-line
Q = q + t (t the curve's shift, :attr:`contact.utca.ContactCurves.shift`), passes
*outside* the region there: with m the inward direction of the boundary,
(q + t − Q(x)) (∇Q·m) < 0. Where it passes inside, the curve carries the contact and the
boundary point is left to it. The two meet where the curve ends on the boundary, and there
Φ_q equals the curve's own separation ε + ½ K t² (Q = q + t), so the load runs on
continuously from the curve onto the edge.

Across an edge the contact is between the edge's rounding (radius r_e) and the mating
flank: R_eq = 1/(1/r_e + κ_other) (Hertz line contact of a cylinder of radius r_e on the
other member's flank, seed Eq. 2.13 with the edge's curvature).

Where the load acts: a gear edge presses on the pinion flank at its own point x, with the
gear's normal there. A pinion edge point P is parametrised by its mate x on the gear
boundary, but at roll q it has turned on from the mate instant Q(x) and presses on the
gear flank at another point g — the foot of the gear flank's normal through P — with the
gear's normal at g (the rounding's normal there is the flank's). The force then acts along
n(g) through P (P lies on that line, at the gap's distance from g), and its moment arm
about the gear axis is the normal arm at g; x's normal and arm, a few tenths of a mm away
along the flank, would put the line of action off by up to 0.8 mm (issue 37) and break
the torque balance about both axes. g's place (u, v) and gear-frame point are stored for
the segment, and its moment arm is the normal's through P (the normal arm at g, to the
splines' interpolation error); R_eq keeps the gear curvature at x (its share of 1/R_eq
is ~1 % beside the edge's 1/r_e).

Public functions
----------------
EDGE_KINDS      names of the boundary pieces
FlankBoundary   the boundary, split into segments of three samples each
flank_boundary  build it from the ease-off splines
edge_segments   the edge segments of every (roll, pair) where a curve passes outside
edge_r_eq       R_eq across boundary segments: the edge rounding on the mating flank
gear_flank_under  the gear flank point under pair-frame points (a pinion edge's contact)
"""

from __future__ import annotations

import math
from typing import NamedTuple

import contourpy
import numpy as np

from contact.ltca.curvature import gear_curvature, pinion_curvature
from contact.ltca.discretisation import (
    MIN_CLIP,
    SegmentFields,
    SegmentQuadratic,
    blank_measure,
    gear_to_pair,
)
from contact.utca import EaseOff, EaseOffFields
from geometry.core.caches import Carried, Same, memoised
from geometry.core.errors import InputError
from geometry.machine.meshing import warm_seeds_active
from geometry.pair.assembly import rotate_about_axis

__all__ = ["EDGE_KINDS", "FlankBoundary", "edge_r_eq", "edge_segments", "flank_boundary",
           "gear_flank_under"]

#: boundary pieces: the gear's tip edge (v = 1), heel and toe ends (u = 1, 0), and the
#: pinion's edges (tip and ends: where the pinion mate leaves the pinion blank)
EDGE_KINDS = ("gear_tip", "gear_heel", "gear_toe", "pinion_edge")

_FINE = 801  # samples locating a piece along the grid edges / the margin contour grid
_CONTOUR_GRID = (161, 81)  # (u, v) samples of the pinion-margin contour
_FOOT_STEP = 1e-13  # [1] Gauss–Newton step (of the grid fractions) that ends a foot point


class FlankBoundary(NamedTuple):
    """The contact region's boundary as E segments sampled at their ends and middle.

    Sample arrays are (E, 3) (start, middle, end), vectors (E, 3, 3); gear frame,
    gear projection-plane fractions.
    """

    kind: np.ndarray  # (E,) int: index into EDGE_KINDS
    u: np.ndarray  # (E, 3) [1]
    v: np.ndarray  # (E, 3) [1]
    roll_angle: np.ndarray  # (E, 3) [rad] Q
    ease_off_angle: np.ndarray  # (E, 3) [rad] ε
    gap_curvature: np.ndarray  # (E, 3) [1/rad] K
    normal_arm: np.ndarray  # (E, 3) [mm]
    inward_slope: np.ndarray  # (E, 3) [rad] ∇Q·m, m the inward direction (sign only)
    position: np.ndarray  # (E, 3, 3) [mm]
    normal: np.ndarray  # (E, 3, 3) [1] gear normal

    @property
    def gear_edge(self) -> np.ndarray:
        """(E,) True where the edge is the gear's (else the pinion's)."""
        return self.kind < EDGE_KINDS.index("pinion_edge")


def flank_boundary(fields, step: float) -> FlankBoundary:
    """The boundary of the contact region on the gear flank, split into segments.

    Parameters
    ----------
    fields : contact.utca.EaseOffFields
        Splines of the ease-off fields (Q, ε, K, normal arm, flank point and normal,
        pinion margin) over the gear grid.
    step : float — [mm]
        Largest segment length along the boundary (> 0).

    Returns
    -------
    FlankBoundary
        The gear's tip edge, heel and toe ends where the pinion mate lies in its blank
        (margin ≥ 0), and the pinion's edges (margin = 0, by contouring the margin
        spline with ``contourpy``), within grid cells whose corners were computed.

    Raises
    ------
    InputError
        For a step that is not a finite positive length.

    Notes
    -----
    Source: the seed's contact region on the gear projection plane (§2.3.2.2, §3.3:
    bounded by the gear blank and the pinion mate's blank, Fig. 2.10); the boundary as a
    contact line of its own is this toolkit's extension (module docstring). Checked in
    tests/test_edge_contact.py: the samples lie on the region's edge (measure 0 to 2e-3)
    and the tip piece matches the gear's node polyline to 1 %.
    """
    if not (isinstance(step, (int, float)) and math.isfinite(step) and step > 0):
        raise InputError(f"edge_step: must be a length > 0 [mm], got {step!r}")
    bd = _pieces(fields, _boundary_lines(fields), step)
    if bd is None:
        empty = np.zeros((0, 3))
        return FlankBoundary(np.zeros(0, int), empty, empty, empty, empty, empty, empty,
                             empty, np.zeros((0, 3, 3)), np.zeros((0, 3, 3)))
    return bd


def _boundary_lines(f) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """The boundary's lines of :func:`flank_boundary` as (kind, u, v) fine polylines."""
    u0, u1, v0, v1 = (float(x) for x in (f.u[0], f.u[-1], f.v[0], f.v[-1]))
    lines: list[tuple[int, np.ndarray, np.ndarray]] = []
    s = np.linspace(0.0, 1.0, _FINE)
    for kind, uu, vv in (
        (0, u0 + (u1 - u0) * s, np.full(_FINE, v1)),
        (1, np.full(_FINE, u1), v0 + (v1 - v0) * s),
        (2, np.full(_FINE, u0), v0 + (v1 - v0) * s),
    ):
        m = f.margin.ev(uu, vv)
        for a, b in _runs(f.good_cell(uu, vv) & (m >= 0.0)):
            ua, va = _margin_crossing(uu, vv, m, a, a - 1)
            ub, vb = _margin_crossing(uu, vv, m, b, b + 1)
            lines.append((kind, np.concatenate(([ua], uu[a + 1:b], [ub])),
                          np.concatenate(([va], vv[a + 1:b], [vb]))))
    ug = np.linspace(u0, u1, _CONTOUR_GRID[0])
    vg = np.linspace(v0, v1, _CONTOUR_GRID[1])
    zg = f.margin(ug, vg).T  # (nv, nu)
    for line in contourpy.contour_generator(ug, vg, zg).lines(0.0):
        uu, vv = line[:, 0], line[:, 1]
        # a vertex lies on a line of the contour grid, and where that is a line of the
        # ease-off grid too (every 4th) contourpy's interpolation puts it a unit in the
        # last place to either side: its cell is judged on the line itself, else the
        # pinion edge starts one vertex earlier or later (one segment more or fewer) as
        # the round-off of the BLAS kernels falls (tests/test_sweep_guard.py)
        for a, b in _runs(f.good_cell(_onto_grid(uu, f.u), _onto_grid(vv, f.v))):
            if b > a:
                lines.append((3, uu[a:b + 1], vv[a:b + 1]))
    return lines


def _runs(ok: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of True."""
    # (np.concatenate: np.r_'s result, without its indexing machinery: ~0.1 ms a call)
    edge = np.diff(np.concatenate(([0], ok.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edge == 1), np.flatnonzero(edge == -1) - 1, strict=True))


def _onto_grid(x: np.ndarray, grid: np.ndarray, rtol: float = 1e-9) -> np.ndarray:
    """``x`` with each value within ``rtol`` of the spacing of a line of ``grid`` (ascending,
    ≥ 2 lines) put on that line: places on a grid line that round-off moved off it."""
    grid = np.asarray(grid, dtype=float)
    k = np.clip(np.searchsorted(grid, x), 1, grid.size - 1)
    lo, hi = grid[k - 1], grid[k]
    nearest = np.where(x - lo <= hi - x, lo, hi)
    return np.where(np.abs(x - nearest) <= rtol * (hi - lo), nearest, x)


def _margin_crossing(uu, vv, m, i: int, j: int):
    """Place between sample i (inside) and its neighbour j where the margin crosses 0
    (sample i itself where j is out of range or the neighbour is out for another reason)."""
    if not (0 <= j < m.size) or m[j] >= 0.0:
        return uu[i], vv[i]
    w = m[i] / (m[i] - m[j])
    return uu[i] + w * (uu[j] - uu[i]), vv[i] + w * (vv[j] - vv[i])


def _pieces(f, lines: list[tuple[int, np.ndarray, np.ndarray]],
            step: float) -> FlankBoundary | None:
    """The boundary lines (kind, fine polyline u, v) as segments of at most ``step`` mm,
    the lines' segments in their order (None where no line has a length).

    Each line's samples sit at 2n + 1 places equally spaced in arc length along its fine
    polyline (n = ⌈length / step⌉ segments of three samples each). The fields are
    evaluated for all lines together, one spline call per field group (issue 75 item 4:
    five lines a study point had ~7 calls each); the splines are evaluated point by point,
    so each sample's values are those of a call per line, bit for bit
    (``tests/test_flank_boundary_batched.py`` keeps the per-line loop as the reference).
    """
    if not lines:
        return None
    sizes = [uu.size for _, uu, _ in lines]
    pos_all = f.values(("pos",), np.concatenate([uu for _, uu, _ in lines]),
                       np.concatenate([vv for _, _, vv in lines]))
    kinds, us_l, vs_l, ns = [], [], [], []
    start = 0
    for (kind, uu, vv), size in zip(lines, sizes, strict=True):
        pos = pos_all[start:start + size]
        start += size
        arc = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(pos, axis=0),
                                                              axis=-1))))
        if arc[-1] <= 1e-9:
            continue
        n = max(1, math.ceil(arc[-1] / step))
        at = np.linspace(0.0, arc[-1], 2 * n + 1)
        kinds.append(kind)
        us_l.append(np.interp(at, arc, uu))
        vs_l.append(np.interp(at, arc, vv))
        ns.append(n)
    if not ns:
        return None
    us, vs = np.concatenate(us_l), np.concatenate(vs_l)
    kind_s = np.repeat(kinds, [2 * n + 1 for n in ns])  # each sample's line kind
    val = f.values(("q", "eps", "arm", "pos", "nrm"), us, vs)
    # the inward slope ∇Q·m, m the inward direction: tip edge −v, heel −u, toe +u, pinion
    # edge up the margin
    slope = np.empty(us.size)
    for kind, dx, dy, sign in ((0, 0, 1, -1.0), (1, 1, 0, -1.0), (2, 1, 0, 1.0)):
        sel = np.flatnonzero(kind_s == kind)
        if sel.size:
            slope[sel] = sign * f.values(("q",), us[sel], vs[sel], dx=dx, dy=dy)[:, 0]
    sel = np.flatnonzero(kind_s == 3)
    if sel.size:
        d_u = f.values(("q", "margin"), us[sel], vs[sel], dx=1)
        d_v = f.values(("q", "margin"), us[sel], vs[sel], dy=1)
        slope[sel] = d_u[:, 0] * d_u[:, 1] + d_v[:, 0] * d_v[:, 1]
    nrm = val[:, 6:9]
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    # (n, 3) samples of each line's segments, offset to the line's first sample
    first = np.concatenate(([0], np.cumsum([2 * n + 1 for n in ns])[:-1]))
    idx = np.concatenate([s0 + 2 * np.arange(n)[:, None] + np.arange(3)[None, :]
                          for s0, n in zip(first, ns, strict=True)])
    return FlankBoundary(np.repeat(kinds, ns), us[idx], vs[idx], val[:, 0][idx],
                         val[:, 1][idx], f.gap_at(us, vs)[idx], val[:, 2][idx], slope[idx],
                         val[:, 3:6][idx], nrm[idx])


def edge_segments(case, eo: EaseOff, bd: FlankBoundary, edge_radius: tuple[float, float],
                  target: np.ndarray, shift: np.ndarray, ute_env: np.ndarray,
                  limit: float | None = None, fields=None,
                  before: SegmentFields | None = None) -> SegmentFields:
    """Edge segments of every (roll, pair): the boundary where the pair's curve passes
    outside the contact region (module docstring), clipped where it passes inside.

    Parameters
    ----------
    case : geometry.case.Case
    eo : EaseOff
    bd : FlankBoundary (E segments)
    edge_radius : (float, float) — [mm] the pinion's and the gear's edge rounding radius
        (R_eq: :func:`edge_r_eq`)
    target, shift : arrays (J, K) — [rad] roll value q of each pair and its curve's shift t
    ute_env : array (J,) — [rad] each roll's UTE (the least over its pairs)
    limit : float, optional — [mm] see :func:`contact.ltca.segment_geometry`'s
        ``edge_limit``
    fields : contact.utca.EaseOffFields, optional
        The splines ``bd`` was built from (default: built here), for the gear flank point
        under each pinion edge (module docstring).
    before : SegmentFields, optional
        Segments (J, K, S) the edge segments follow along the segment axis (the curve
        segments, :func:`contact.ltca.segment_geometry`): returned with them, as
        ``before.concatenate(edge_segments(...))`` gives them, each field written once
        into its (J, K, S + E) array (no (J, K, E) arrays copied again: ≈ 5 MB, 1 ms of a
        study point of the default case, issue 75).

    Returns
    -------
    SegmentFields
        Arrays (J, K, E[, ...]) (with ``before``: (J, K, S + E[, ...]), its S first); the
        lag is the mean of Φ_q = ε + ½ K (Q − q)² over the part in edge contact. NaN
        (length 0) where the pair's curve passes inside the region all along the boundary
        segment, or its separation is surely above ``limit``.

    Notes
    -----
    A gear edge touches the pinion flank at the gear's edge point x itself; it is clipped
    where the real pinion at the pair's roll has no flank across x (beyond its blank), as
    the curves are. A pinion edge point P is the mate of the boundary point x at the
    instant Q(x); at roll q it has turned on by s_p (q − Q(x)) with the pinion, and the
    contact sits there (P's separation is Φ_q(x) to first order: the gap function on the
    pinion's surface has the same form), on the gear flank point g under P: the segment's
    normal, (u, v) and gear-frame point are g's (:func:`gear_flank_under`), its moment arm
    that of the normal through P.

    Source: the LTCA's line model (seed §3.3) continued onto the flank boundary, as the
    module docstring derives it.
    """
    kin = eo.kinematics
    quad = SegmentQuadratic(np.array([0.0, 0.5, 1.0]))
    J, K = target.shape
    E = bd.kind.size
    cand, outside, phi_s = _edge_candidates(bd, target, shift, ute_env, limit)
    jj, kk, ee = np.nonzero(cand)
    outside = outside[jj, kk, ee]  # (n, 3)
    pts, phi, psi, g = _edge_contact_points(eo, bd, target[jj, kk], ee)
    # each part in contact lies on the mating member's flank: within its blank
    for sel, member, turn in ((g, "pinion", phi), (~g, "gear", psi)):
        if np.any(sel):
            m = blank_measure(case, kin, member, pts[sel], turn[sel])
            outside[sel] = np.minimum(outside[sel], m)
    a, b = (x[..., 0] for x in quad.clip(outside))  # (n,)
    a1, b1, c1 = a[:, None], b[:, None], 0.5 * (a + b)[:, None]
    sep = phi_s[jj, kk, ee]  # (n, 3)
    inside = b - a > MIN_CLIP
    # R_eq of the boundary segments in edge contact somewhere
    used = np.unique(ee[inside])
    r_eq = np.full(E, np.nan)
    r_eq[used] = _edge_r_eq_of(case, eo, bd, edge_radius, used)
    nrm = quad.at(bd.normal[ee], c1, vector=True)[:, 0]
    nrm = nrm / np.linalg.norm(nrm, axis=-1, keepdims=True)
    u_c, v_c = quad.at(bd.u[ee], c1)[:, 0], quad.at(bd.v[ee], c1)[:, 0]
    mid_g = quad.at(bd.position[ee], c1, vector=True)[:, 0]
    arm = quad.at(bd.normal_arm[ee], c1)[:, 0]
    mid_pair = quad.at(pts, c1, vector=True)[:, 0]
    # a pinion edge presses on the gear flank point under it (module docstring)
    pe = ~g
    if np.any(pe):
        f = fields if fields is not None else EaseOffFields(eo)
        u_c[pe], v_c[pe], mid_g[pe], nrm[pe] = gear_flank_under(
            f, kin, psi[pe], mid_pair[pe], u_c[pe], v_c[pe])
    n_pair = -gear_to_pair(kin, psi, nrm, vec=True)
    if np.any(pe):
        # the moment arm of the force along n(g) through the edge point P (P lies on the
        # normal through g: the normal arm at g, to the spline's interpolation error),
        # signed as the flank's normal arm ρ|n·e_θ| is: (P − O) × n_pair · a_g = −ρ n_θ(g)
        # (n_pair the gear normal reversed) has the sign of −s_g, s_g = sign(n_g·e_θ) the
        # lag sense of this flank, so −s_g times it is the arm in the sense the gear torque
        # loads the flank: positive on either flank (drive: s_g = −1, unchanged; coast:
        # s_g = +1, where the unsigned cross product gave every pinion edge a negative arm,
        # hence a negative separation R (lag − UTE) and a negative moment)
        arm[pe] = -eo.lag_sense * np.einsum(
            "ni,i->n", np.cross(mid_pair[pe] - kin.gear_origin, n_pair[pe]), kin.gear_axis)
    end_a = quad.at(pts, a1, vector=True)[:, 0]
    end_b = quad.at(pts, b1, vector=True)[:, 0]
    chord = end_b - end_a
    length = np.where(inside, np.linalg.norm(chord, axis=-1), 0.0)
    chord = np.where(inside[:, None], chord, pts[:, 2] - pts[:, 0])
    values = {
        "u": np.where(inside, u_c, np.nan),
        "v": np.where(inside, v_c, np.nan),
        "midpoint": mid_g,
        "midpoint_pair": mid_pair,
        "ends_pair": np.stack([end_a, end_b], axis=-2),
        "normal_pair": n_pair,
        "tangent_pair": chord / np.linalg.norm(chord, axis=-1, keepdims=True),
        "length": length,
        "moment_arm": arm,
        "lag": quad.mean(sep, a1, b1)[:, 0],
        "r_eq": np.where(inside, r_eq[ee], np.nan),
    }
    s0 = 0 if before is None else before.length.shape[2]
    out = {}
    for key, val in values.items():
        full = np.full((J, K, s0 + E, *val.shape[1:]), 0.0 if key == "length" else np.nan)
        if before is not None:
            full[:, :, :s0] = getattr(before, key)
        full[jj, kk, s0 + ee] = val
        out[key] = full
    return SegmentFields(**out)


def gear_flank_under(fields, kin, psi: np.ndarray, points: np.ndarray, u: np.ndarray,
                     v: np.ndarray, iterations: int = 8):
    """The gear flank point under pair-frame points: the foot of the flank's normal.

    Parameters
    ----------
    fields : contact.utca.EaseOffFields
        Splines of the real gear flank (points, normals, normal arm) over (u, v).
    kin : the ease-off's kinematics (gear axis, origin and placement)
    psi : ndarray (n,) — [rad]
        The gear's rotation at each point's roll.
    points : ndarray (n, 3) — [mm]
        Points in the pair frame (e.g. pinion edge points at the pair's roll).
    u, v : ndarray (n,) — [1]
        Starting places (gear fractions), near the answer.
    iterations : int
        Gauss–Newton steps at most (default 8: from a few tenths of a mm away the step
        falls below 1e-12 of the grid in 4–5); a point stops after a step of at most
        :data:`_FOOT_STEP` of the grid.

    Returns
    -------
    u, v : ndarray (n,) — [1]
        The places g, held within the gear grid.
    position : ndarray (n, 3) — [mm]
        g in the gear frame.
    normal : ndarray (n, 3) — [1]
        The gear's unit normal at g, gear frame.

    Notes
    -----
    Gauss–Newton on (x(u, v) − p)·x_u = (x(u, v) − p)·x_v = 0, p the point in the gear
    frame (turned back by ψ); the splines' own derivatives. A point beyond the grid (a
    pinion edge past the gear flank's computed part, far from contact) gets the nearest
    grid edge's place. Each step's 2 × 2 normal equations are solved in closed form
    (Cramer's rule; where JᵀJ is singular LAPACK's solve raises, as it did for all).
    Checked in tests/test_plastic_edges.py: the force along the normal at g through the
    pinion edge point balances the gear torque with the others. These
    are the normal equations of min ‖x(u, v) − p‖² over the flank's parameters, a
    nonlinear least-squares problem (Gauss–Newton: Nocedal & Wright, Numerical
    Optimization, 2nd ed., Springer 2006, ch. 10).
    """
    f = fields
    p = rotate_about_axis(kin.gear_axis, -psi, points - kin.gear_origin) \
        @ kin.gear_place[:3, :3]
    uu = np.array(u, dtype=float)  # (the iterates: copies, written in place)
    vv = np.array(v, dtype=float)
    act = np.arange(uu.size)
    for _ in range(iterations):
        if act.size == 0:
            break
        ua, va = uu[act], vv[act]
        r = p[act] - f.values(("pos",), ua, va)  # (m, 3)
        xu = f.values(("pos",), ua, va, dx=1)
        xv = f.values(("pos",), ua, va, dy=1)
        # the normal equations JᵀJ Δ = Jᵀr (J = [x_u x_v], 2 × 2 symmetric) solved in
        # closed form, each entry one dot product over the three components (issue 75:
        # ≈ 2 ms of a study point in the batched einsum and LAPACK solve of 2 × 2 systems
        # it replaces; the same step to round-off, the converged places to ≈ 1e-15)
        a = np.einsum("ni,ni->n", xu, xu)
        b = np.einsum("ni,ni->n", xu, xv)
        c = np.einsum("ni,ni->n", xv, xv)
        det = a * c - b * b
        if not np.all(det > 0.0):  # a degenerate flank place: LAPACK's solve says so
            np.linalg.solve(np.stack([np.stack([a, b], -1), np.stack([b, c], -1)], -1),
                            np.zeros((a.size, 2, 1)))
        gu = np.einsum("ni,ni->n", xu, r)
        gv = np.einsum("ni,ni->n", xv, r)
        new_u = np.clip(ua + (c * gu - b * gv) / det, f.u[0], f.u[-1])
        new_v = np.clip(va + (a * gv - b * gu) / det, f.v[0], f.v[-1])
        step = np.maximum(np.abs(new_u - ua), np.abs(new_v - va))
        uu[act] = new_u
        vv[act] = new_v
        # a point whose step fell to _FOOT_STEP leaves the batch (the steps shrink ~100×
        # each: the rest would move it by ~1e-15)
        act = act[step > _FOOT_STEP]
    both = f.values(("pos", "nrm"), uu, vv)
    pos, nrm = both[:, :3], both[:, 3:]
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    return uu, vv, pos, nrm


def _edge_candidates(bd: FlankBoundary, target: np.ndarray, shift: np.ndarray,
                     ute_env: np.ndarray, limit: float | None):
    """The (roll, pair, boundary segment) worth working out, (J, K, E) bool; the signed
    measure (J, K, E, 3) ≥ 0 where the curve passes outside beyond each sample; and the
    separation Φ_q [rad] (J, K, E, 3) at the samples."""
    # ≥ 0 where the curve Q = q + t passes outside the region beyond the boundary point;
    # only the (roll, pair, boundary segment) where it does somewhere are worked out
    # (flattened to n candidates), the rest stay NaN (no edge contact)
    outside = ((bd.roll_angle[None, None] - (target + shift)[..., None, None])
               * bd.inward_slope)  # (J, K, E, 3)
    # (reductions over the three samples as element-wise ops on the three: the same
    # values, without numpy's slow reduction along a length-3 last axis)
    cand = (outside[..., 0] >= 0) | (outside[..., 1] >= 0) | (outside[..., 2] >= 0)
    # Φ_q = ε + ½ K (Q − q)² at the samples of every boundary segment [rad]
    phi_s = (bd.ease_off_angle + 0.5 * bd.gap_curvature
             * (bd.roll_angle - target[..., None, None]) ** 2)  # (J, K, E, 3)
    if limit is not None:
        # the separation's lower bound: Φ_q at the samples, less the quadratic's second
        # difference (its dip below the samples is at most a quarter of that), times
        # the least normal arm
        dip = np.abs(phi_s[..., 0] - 2.0 * phi_s[..., 1] + phi_s[..., 2])
        least = np.minimum(np.minimum(phi_s[..., 0], phi_s[..., 1]), phi_s[..., 2])
        low = least - dip - ute_env[:, None, None]
        cand &= ~(np.min(bd.normal_arm, axis=-1) * low > limit)
    return cand, outside, phi_s


def _edge_contact_points(eo: EaseOff, bd: FlankBoundary, q: np.ndarray, ee: np.ndarray):
    """Pair-frame contact points (n, 3, 3) [mm] of n candidates: boundary segments ``ee``
    (n,) of pairs at roll values ``q`` (n,) [rad]; with the pinion and gear rotations φ,
    ψ (n,) [rad] and whether each is a gear edge (n,) bool. A gear edge's contact is at its
    own points; a pinion edge's points are turned on with the pinion from their mate
    instant."""
    kin = eo.kinematics
    q = q[:, None]  # (n, 1) roll value of the candidate's pair
    phi = eo.roll_zero + eo.drive_sense * q[:, 0]  # (n,) pinion rotation
    psi = eo.gear_phase - phi / eo.ratio
    g = bd.gear_edge[ee]
    pts = np.empty((ee.size, 3, 3))  # (n, 3, 3)
    if np.any(g):
        pts[g] = gear_to_pair(kin, psi[g, None], bd.position[ee[g]])
    if not np.all(g):
        pe = ~g
        # a pinion edge's mate depends on its boundary segment alone: each distinct
        # segment's once (the candidates repeat them over rolls and pairs, issue 75)
        seg, back = np.unique(ee[pe], return_inverse=True)
        phi_m = eo.roll_zero + eo.drive_sense * bd.roll_angle[seg]  # (m, 3) mate instants
        mate = gear_to_pair(kin, eo.gear_phase - phi_m / eo.ratio, bd.position[seg])
        turn = eo.drive_sense * (q[pe] - bd.roll_angle[ee[pe]])
        pts[pe] = rotate_about_axis(kin.pinion_axis, turn,
                                    mate[back.ravel()] - kin.pinion_origin) + kin.pinion_origin
    return pts, phi, psi, g


def _edge_r_eq_of(case, eo: EaseOff, bd: FlankBoundary, edge_radius: tuple[float, float],
                  which: np.ndarray) -> np.ndarray:
    """:func:`edge_r_eq`, memoised per process by the ease-off and boundary objects, the
    teeth (``Case.teeth_key``: what the curvatures read of the case), the edge radii and
    the boundary segments ``which`` (M,): the same R_eq, computed once for the analyses
    of one case repeated or of a torque series whose edge contact uses the same boundary
    segments (issue 75: ~5 ms of curvatures a warm analysis). Not memoised inside a
    development's trial (its ease-off is not either:
    :func:`geometry.machine.meshing.warm_seeds_active`). A copy is returned."""
    if warm_seeds_active():
        return edge_r_eq(case, eo, bd, edge_radius, which)
    which = np.ascontiguousarray(which, dtype=np.intp)
    radii = (float(edge_radius[0]), float(edge_radius[1]))
    return _memo_edge_r_eq(Same(eo), Same(bd), case.teeth_key(), Carried(case), radii,
                           which.tobytes()).copy()


@memoised(maxsize=8)  # each entry holds its ease-off: as many as the ease-off memo keeps
def _memo_edge_r_eq(eo: Same, bd: Same, teeth, case: Carried, radii: tuple[float, float],
                    which: bytes) -> np.ndarray:
    """:func:`edge_r_eq` memoised (:func:`_edge_r_eq_of`), its array read-only."""
    out = edge_r_eq(case.value, eo.obj, bd.obj, radii, np.frombuffer(which, dtype=np.intp))
    out.flags.writeable = False
    return out


def edge_r_eq(case, eo: EaseOff, bd: FlankBoundary, edge_radius: tuple[float, float],
               which: np.ndarray) -> np.ndarray:
    """R_eq [mm] across the boundary segments ``which`` (indices (M,)): the edge's
    rounding (radius r_e: ``edge_radius`` (pinion, gear) [mm], the edge's own member's)
    on the other member's flank, 1/(1/r_e + κ_other) at the segment's middle (κ_other
    along n × t, t the edge tangent; the pinion taken at its mate's instant Q).

    Notes
    -----
    Source: Hertz line contact of a cylinder of the edge radius on the other member's flank,
    R_eq = 1/(1/r_e + κ_other) (seed Eq. 2.13 with the edge's curvature; Johnson 1985,
    ch. 4).
    """
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
        k_other[g] = pinion_curvature(case, eo, u[g], v[g], w[g], phi)
    if np.any(~g):
        k_other[~g] = gear_curvature(case, eo, pos[~g], w[~g])
    krel = 1.0 / np.where(g, edge_radius[1], edge_radius[0]) + k_other
    return np.where(np.isfinite(krel), 1.0 / np.maximum(krel, 1e-4), np.nan)
