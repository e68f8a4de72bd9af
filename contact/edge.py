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

Public functions
----------------
EDGE_KINDS      names of the boundary pieces
FlankBoundary   the boundary, split into segments of three samples each
flank_boundary  build it from the ease-off splines
"""

from __future__ import annotations

import math
from typing import NamedTuple

import contourpy
import numpy as np

from geometry.errors import InputError

__all__ = ["EDGE_KINDS", "FlankBoundary", "flank_boundary"]

#: boundary pieces: the gear's tip edge (v = 1), heel and toe ends (u = 1, 0), and the
#: pinion's edges (tip and ends: where the pinion mate leaves the pinion blank)
EDGE_KINDS = ("gear_tip", "gear_heel", "gear_toe", "pinion_edge")

_FINE = 801  # samples locating a piece along the grid edges / the margin contour grid
_CONTOUR_GRID = (161, 81)  # (u, v) samples of the pinion-margin contour


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
    fields : contact.utca._Fields
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
    f = fields
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
            lines.append((kind, np.r_[ua, uu[a + 1:b], ub], np.r_[va, vv[a + 1:b], vb]))
    ug = np.linspace(u0, u1, _CONTOUR_GRID[0])
    vg = np.linspace(v0, v1, _CONTOUR_GRID[1])
    zg = f.margin(ug, vg).T  # (nv, nu)
    for line in contourpy.contour_generator(ug, vg, zg).lines(0.0):
        uu, vv = line[:, 0], line[:, 1]
        for a, b in _runs(f.good_cell(uu, vv)):
            if b > a:
                lines.append((3, uu[a:b + 1], vv[a:b + 1]))
    pieces = [_piece(f, kind, uu, vv, step) for kind, uu, vv in lines]
    pieces = [p for p in pieces if p is not None]
    if not pieces:
        empty = np.zeros((0, 3))
        return FlankBoundary(np.zeros(0, int), empty, empty, empty, empty, empty, empty,
                             empty, np.zeros((0, 3, 3)), np.zeros((0, 3, 3)))
    return FlankBoundary(*(np.concatenate(a) for a in zip(*pieces, strict=True)))


def _runs(ok: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of True."""
    edge = np.diff(np.r_[0, ok.astype(np.int8), 0])
    return list(zip(np.flatnonzero(edge == 1), np.flatnonzero(edge == -1) - 1, strict=True))


def _margin_crossing(uu, vv, m, i: int, j: int):
    """Place between sample i (inside) and its neighbour j where the margin crosses 0
    (sample i itself where j is out of range or the neighbour is out for another reason)."""
    if not (0 <= j < m.size) or m[j] >= 0.0:
        return uu[i], vv[i]
    w = m[i] / (m[i] - m[j])
    return uu[i] + w * (uu[j] - uu[i]), vv[i] + w * (vv[j] - vv[i])


def _piece(f, kind: int, uu: np.ndarray, vv: np.ndarray, step: float):
    """One boundary line (fine polyline) as segments of at most ``step`` mm."""
    pos = np.stack([p.ev(uu, vv) for p in f.pos], -1)
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(pos, axis=0), axis=-1))]
    if arc[-1] <= 1e-9:
        return None
    n = max(1, math.ceil(arc[-1] / step))
    at = np.linspace(0.0, arc[-1], 2 * n + 1)
    us, vs = np.interp(at, arc, uu), np.interp(at, arc, vv)
    q = f.q.ev(us, vs)
    if kind == 0:  # tip edge: inward is −v
        slope = -f.q.ev(us, vs, dy=1)
    elif kind == 1:  # heel: inward is −u
        slope = -f.q.ev(us, vs, dx=1)
    elif kind == 2:  # toe: inward is +u
        slope = f.q.ev(us, vs, dx=1)
    else:  # pinion edge: inward is up the margin
        slope = (f.q.ev(us, vs, dx=1) * f.margin.ev(us, vs, dx=1)
                 + f.q.ev(us, vs, dy=1) * f.margin.ev(us, vs, dy=1))
    nrm = np.stack([p.ev(us, vs) for p in f.nrm], -1)
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    xyz = np.stack([p.ev(us, vs) for p in f.pos], -1)
    idx = 2 * np.arange(n)[:, None] + np.arange(3)[None, :]  # (n, 3) samples per segment
    return (np.full(n, kind), us[idx], vs[idx], q[idx], f.eps.ev(us, vs)[idx],
            f.gap_at(us, vs)[idx], f.arm.ev(us, vs)[idx], slope[idx], xyz[idx], nrm[idx])
