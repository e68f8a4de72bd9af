"""Influence coefficients of a member's teeth: compliance of the flank, stress in the fillets.

For a grid of potential contact points on the working flank of the loaded tooth (the
ease-off grid's layout, :func:`geometry.flank.projection_grid`: ``load_nu × load_nv``
points in the lengthwise and profile fractions (u, v)), a unit normal load at each grid
point is solved on the FE model of :mod:`contact.compliance.fe.solid`, and recorded are

* the **compliance**: the normal displacement, into the tooth, at every grid point of the
  working flank of the loaded tooth and of each neighbour [mm/N];
* the **fillet stress**: the stress tensor at points along both root fillets (and the
  slot bottoms) of every modelled tooth, along the face width [MPa/N], with its maximum
  and minimum principal values per unit load (the tension and the compression side).

A "unit load at grid point a" is a pressure over the flank proportional to the bilinear
hat function N_a(u, v) of the grid, normalised to 1 N, acting along the inward normal;
the displacement "at grid point b" is the normal displacement averaged with the weight
N_b (the same functional). So the compliance G_ab = f_bᵀ K⁻¹ f_a is symmetric
(Maxwell–Betti) and converges with the mesh (a point force has no finite displacement in
an elastic solid), and a load at any point p of the flank is the hat loads with the
bilinear interpolation weights N_a(p) — the interpolation
:mod:`contact.compliance.fe.superposition` uses. The local contact deformation over the
hat's support (about two grid cells) is part of G; the LTCA's contact term (Weber) is
for the Hertzian zone, much narrower (docs/fe.md).

The coefficients are computed once per member, design and FE model and cached on disk
(:mod:`contact.compliance.fe.cache`); the cost (time, unknowns, memory) is logged and
stored in the dataset's attributes.

Public names
------------
InfluenceModel         the FE model with its load vectors and stress points
build_influence_model  build it (solid, stiffness, factorisation, loads, fillet points)
flank_grid_positions   member-frame points of a load grid on a flank of the sections
load_v_limits          the profile fractions the load grid covers (follows the flank)
influence_dataset      solve the unit loads and gather the coefficients
influence_coefficients the cached entry point: dataset of one member
hat_weights            bilinear hat functions of a grid at points
principal_stresses     extreme principal values of stress tensors
"""

from __future__ import annotations

import contextlib
import dataclasses
import importlib
import json
import logging
import math
import os
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import xarray as xr
from tqdm.auto import tqdm

from contact.compliance.fe.cache import (
    BlockCheckpoint,
    cache_key,
    cache_path,
    not_written,
    read_cache_entry,
    write_cache_entry,
)
from contact.compliance.fe.elasticity import (
    ElasticModel,
    Factorisation,
    elastic_model,
    factorise,
    lattice_dissection,
    resolve_solver,
    stress_operator,
)
from contact.compliance.fe.mapped_mesh import FacetPoints, facet_points
from contact.compliance.fe.options import ELEMENTS, FEOptions, member_flank
from contact.compliance.fe.solid import ToothSolid, kept_tooth_solid
from geometry import __version__
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, LTCAError
from geometry.machine.flank import projection_fractions

__all__ = [
    "COMPONENTS",
    "InfluenceModel",
    "build_influence_model",
    "flank_grid_positions",
    "hat_weights",
    "influence_coefficients",
    "influence_dataset",
    "load_v_limits",
    "principal_stresses",
]

log = logging.getLogger(__name__)

#: stress components in Voigt order (member frame)
COMPONENTS = ("xx", "yy", "zz", "yz", "xz", "xy")
_SIDES = ("left", "right")
_CHUNK = 64  # right-hand sides per solve (one dense block of CHOLMOD's: elasticity)
_LOAD_ORDER = 6  # facet quadrature order of the hat loads (4 × 4 Gauss points per facet) ...
_POINTS_PER_CELL = 2  # ... or more: Gauss points per load-grid cell across the largest facet


def hat_weights(grid_u: np.ndarray, grid_v: np.ndarray, u, v, *,
                outside: str = "zero") -> sp.csr_matrix:
    """Bilinear hat functions N_a(u, v) of a tensor grid at points, sparse (P, nu·nv).

    Parameters
    ----------
    grid_u, grid_v : ndarray (nu,), (nv,) — [1] increasing grid fractions
    u, v : array_like (P,) — [1] the points' fractions
    outside : str — ``"zero"``: a point outside the grid has no weight (loads beyond
        the grid); ``"clip"``: it takes the weights of the nearest grid point on the
        boundary (interpolation)

    Returns
    -------
    scipy.sparse.csr_matrix (P, nu nv) — column a = i nv + j is N at grid point
        (grid_u[i], grid_v[j]); each row sums to 1 inside the grid.
    """
    u = np.asarray(u, dtype=float).ravel()
    v = np.asarray(v, dtype=float).ravel()
    nu, nv = len(grid_u), len(grid_v)
    iu = np.clip(np.searchsorted(grid_u, u, side="right") - 1, 0, nu - 2)
    iv = np.clip(np.searchsorted(grid_v, v, side="right") - 1, 0, nv - 2)
    tu = (u - grid_u[iu]) / (grid_u[iu + 1] - grid_u[iu])
    tv = (v - grid_v[iv]) / (grid_v[iv + 1] - grid_v[iv])
    eps = 1e-12
    inside = (tu >= -eps) & (tu <= 1 + eps) & (tv >= -eps) & (tv <= 1 + eps)
    tu, tv = np.clip(tu, 0.0, 1.0), np.clip(tv, 0.0, 1.0)
    w = np.stack([(1 - tu) * (1 - tv), tu * (1 - tv), (1 - tu) * tv, tu * tv], axis=1)
    if outside == "zero":
        w[~inside] = 0.0
    # each row's four columns (distinct: nu, nv ≥ 2) in increasing order, i.e. the
    # canonical CSR that the COO constructor makes of them (its sort and duplicate sum,
    # ~2/3 of this function, left out): the same arrays, entries and products
    a = iu * nv + iv
    cols = np.stack([a, a + 1, a + nv, a + nv + 1], axis=1)
    w = w[:, [0, 2, 1, 3]]
    m = sp.csr_matrix((w.ravel(), cols.ravel(), np.arange(0, 4 * u.size + 1, 4)),
                      shape=(u.size, nu * nv))
    m.has_canonical_format = True  # sorted, no duplicates (above)
    return m


@dataclass(frozen=True, eq=False)
class _FilletPoints:
    """Stress points along the roots: P points, their stress operator and layout."""

    operator: sp.csr_matrix  # (6P, 3N)
    position: np.ndarray  # (P, 3) [mm] member frame
    u: np.ndarray  # (P,) [1]
    v: np.ndarray  # (P,) [1]
    index: np.ndarray  # (teeth, 2 sides, stations, arc points) → point
    station: np.ndarray  # (stations,) [1] lengthwise parameter fraction
    in_root: np.ndarray  # (P,) bool: on the half slot or the rows up to the junction


@dataclass(eq=False)
class InfluenceModel:
    """A member's FE model ready to be loaded on its working flank.

    Attributes
    ----------
    solid : ToothSolid
    elastic : ElasticModel
    factor : Factorisation — K with the support's dofs removed, factorised
    flank : str — the working flank (``"concave"``/``"convex"``)
    side : str — where it lies on the tooth (``"left"``/``"right"``)
    grid_u, grid_v : ndarray — [1] the load grid's fractions
    loads : dict[int, csr_matrix (3N, nu nv)] — unit hat loads [N] on the working flank
        of the tooth at each offset (the responses use the same functionals)
    centre : dict[int, csr_matrix (3N, nu nv)] — functionals of the displacement of each
        tooth's mid-surface along the hats' mean inward flank normals (hat averages)
    hat_area : ndarray (nu nv,) — [mm²] ∫ N_a dA on the loaded tooth
    fillet : _FilletPoints
    times : dict — [s] build phases
    """

    solid: ToothSolid
    elastic: ElasticModel
    factor: Factorisation
    flank: str
    side: str
    grid_u: np.ndarray
    grid_v: np.ndarray
    loads: dict
    centre: dict
    hat_area: np.ndarray
    fillet: _FilletPoints
    times: dict

    @property
    def offsets(self) -> list[int]:
        """Tooth offsets from the loaded tooth, −K … K."""
        k = self.solid.layout.neighbours
        return list(range(-k, k + 1))

    def solve(self, rhs) -> np.ndarray:
        """Displacements [mm] of loads ``rhs`` (3N, k) [N], dense or sparse."""
        return self.factor.solve(rhs)

    def compliance_of(self, disp: np.ndarray) -> np.ndarray:
        """Normal displacement [mm] in each hat functional of each tooth's working flank:
        (teeth, nu nv, k) from displacements (3N, k)."""
        return np.stack([self.loads[t].T @ disp for t in self.offsets])

    def centreline_of(self, disp: np.ndarray) -> np.ndarray:
        """Displacement [mm] of each tooth's mid-surface under each hat along the hat's
        inward flank normal: (teeth, nu nv, k) from displacements (3N, k)."""
        return np.stack([self.centre[t].T @ disp for t in self.offsets])

    def stress_of(self, disp: np.ndarray) -> np.ndarray:
        """Stress components [MPa] at the fillet points, (P, 6, k), of displacements."""
        s = self.fillet.operator @ disp
        return s.reshape(-1, 6, disp.shape[1])


def _facet_points(solid: ToothSolid, facets: np.ndarray, order: int, *,
                  grads: bool = True) -> FacetPoints:
    """Gauss points of ``facets`` with basis values, gradients (where ``grads``), normals
    and areas."""
    return facet_points(solid.mesh, ELEMENTS[solid.options.element][0](), facets, order,
                        grads=grads)


def _trace(fb: FacetPoints, n_dofs: int, weight: np.ndarray) -> sp.csr_matrix:
    """Sparse (3N, 3FQ) map: column 3 q + c picks the c-component of the displacement at
    facet point q times ``weight`` (F, Q) (the area weight, for integrals)."""
    nodes = fb.element_dofs  # (nb, F)
    nf, nq = weight.shape
    phi = fb.values * weight[None]  # (nb, F, Q)
    col = np.broadcast_to(np.arange(nf * nq).reshape(nf, nq)[None], phi.shape).ravel()
    rows = np.concatenate([np.broadcast_to(3 * nodes[:, :, None] + c, phi.shape).ravel()
                           for c in range(3)])
    cols = np.concatenate([3 * col + c for c in range(3)])
    return sp.csr_matrix((np.tile(phi.ravel(), 3), (rows, cols)), shape=(n_dofs, 3 * nf * nq))


def _hats(solid: ToothSolid, fb: FacetPoints, grid_u, grid_v):
    """Hat weights (FQ, nL) at facet points and the hats' areas ∫ N_a dA (nL,) [mm²]."""
    u, v = projection_fractions(solid.sections.corners, fb.x[2].ravel(),
                                np.hypot(fb.x[0], fb.x[1]).ravel())
    hats = hat_weights(grid_u, grid_v, u, v)
    area = np.asarray(hats.multiply(fb.dx.ravel()[:, None]).sum(axis=0)).ravel()
    if np.any(area <= 0.0):
        raise LTCAError(f"{solid.member}: a load grid point has no surface around it (the "
                        "load grid reaches beyond the meshed flank"
                        + _uncovered(grid_u, grid_v, area, u, v) + ")")
    return hats.tocsc(), area


def _uncovered(grid_u: np.ndarray, grid_v: np.ndarray, area: np.ndarray, u: np.ndarray,
               v: np.ndarray) -> str:
    """Where the meshed surface ends below the load grid, in words: the grid's lengthwise
    fractions with a point of no surface, and how high in v [1] the surface reaches there
    (the facet points ``u``, ``v`` within half a grid step). Found on the generated-gear
    spiral bevel 19x23 at β_m 46° (issue 71): its pinion's concave flank is generated only
    up to v 0.55 at the toe, the grid's points above it had no surface."""
    nv = len(grid_v)
    bad = np.flatnonzero(area <= 0.0)
    rows = np.unique(bad // nv)
    half = 0.5 * float(np.diff(grid_u).min())
    parts = []
    for i in rows[:4]:
        near = np.abs(u - grid_u[i]) <= half
        top = f"{float(v[near].max()):.2f}" if np.any(near) else "nowhere"
        parts.append(f"u {grid_u[i]:.2f}: surface up to v {top}, grid to "
                     f"{grid_v[bad[bad // nv == i] % nv].max():.2f}")
    more = ", …" if rows.size > 4 else ""
    return ("; " + ", ".join(parts) + more + ": the flank's generated surface does not "
            "cover the blank's working depth there, and the pair's contact is not modelled "
            "by the FE model beyond it")


def _load_order(solid: ToothSolid, facets: np.ndarray, grid_u: np.ndarray,
                grid_v: np.ndarray) -> int:
    """Facet quadrature order of the hat loads: :data:`_LOAD_ORDER`, or higher where a
    facet spans several load-grid cells (a large element up the flank under a fine grid),
    so that every hat meets :data:`_POINTS_PER_CELL` Gauss points per cell across it and
    none of them falls between the points."""
    mapped = solid.mesh
    corners = mapped.mesh.doflocs[:, mapped.param.facets[:, facets]]  # (3, 4, F) vertices
    u, v = projection_fractions(solid.sections.corners, corners[2].ravel(),
                                np.hypot(corners[0], corners[1]).ravel())
    cells = max(float(np.ptp(u.reshape(4, -1), axis=0).max() / np.diff(grid_u).min()),
                float(np.ptp(v.reshape(4, -1), axis=0).max() / np.diff(grid_v).min()))
    points = math.ceil(_POINTS_PER_CELL * cells)  # per direction; order 2n − 2 gives n
    return max(_LOAD_ORDER, 2 * points - 2)


def _flank_loads(solid: ToothSolid, elastic: ElasticModel, offset: int, side: str,
                 grid_u: np.ndarray, grid_v: np.ndarray):
    """On one tooth: the unit hat loads (3N, nL) [N] on its flank side (the flank's
    displacement functionals too), the hats' flank areas (nL,) [mm²], and the functionals
    of its mid-surface's displacement along each hat's mean inward flank normal
    (3N, nL) [1]."""
    facets = solid.flank_facets(offset, side)
    fb = _facet_points(solid, facets, _load_order(solid, facets, grid_u, grid_v),
                       grads=False)
    hats, area = _hats(solid, fb, grid_u, grid_v)
    scaled = hats.multiply(1.0 / area[None, :]).tocsc()  # (FQ, nL): N_a / A_a
    inward = -fb.normal.reshape(3, -1).T  # (FQ, 3)
    # the load: Σ_q φ_i(q) dA_q (−n(q)) N_a(q)/A_a, as (3FQ, nL) weights of the trace
    weights = sp.vstack([scaled.multiply(inward[:, [c]]) for c in range(3)]).tocsr()
    order = np.arange(3 * inward.shape[0]).reshape(3, -1).T.ravel()  # (c, q) → 3 q + c
    loads = (_trace(fb, elastic.n_dofs, fb.dx) @ weights[order]).tocsr()
    normal = np.asarray(scaled.T @ (inward * fb.dx.reshape(-1, 1)))
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)  # (nL, 3) mean inward normals
    # the tooth's mid-surface (the middle column of its block)
    lay = solid.layout
    a_mid = lay.side_a(offset, "left") + 0.5 * lay.across
    mid = solid.mesh.facets_where(lambda p: (np.abs(p[0] - a_mid) < 1e-9) & (p[1] > lay.rim),
                                  boundary=False)
    fm = _facet_points(solid, mid, _load_order(solid, mid, grid_u, grid_v), grads=False)
    hm, am = _hats(solid, fm, grid_u, grid_v)
    sm = hm.multiply(1.0 / am[None, :]).tocsc()
    w_mid = sp.vstack([sm.multiply(normal[:, c][None, :]) for c in range(3)]).tocsr()
    order_m = np.arange(3 * fm.dx.size).reshape(3, -1).T.ravel()
    centre = (_trace(fm, elastic.n_dofs, fm.dx) @ w_mid[order_m]).tocsr()
    return loads, area, centre


def _turned_rows(solid: ToothSolid, n_nodes: int, offset: int, nodes: np.ndarray
                 ) -> sp.csr_matrix | None:
    """The (3N, 3N) map that carries a field on the dofs of ``nodes`` (loaded-tooth nodes)
    to the tooth at ``offset``: each node to the one ``offset`` cells along the parameter
    A, its three components turned by ``offset`` pitches about the member axis. None
    where a node has no counterpart or the counterpart is not where the turn puts it
    (within 1e-9 of the solid's size): the caller computes that tooth's field itself.

    The solid's teeth are one tooth's nodes turned by whole pitches
    (:func:`contact.compliance.fe.solid.build_tooth_solid`: every node at its section's
    (v, φ + offset × pitch)), so a neighbour's flank loads and mid-surface functionals are
    the loaded tooth's turned (issue 75)."""
    lattice = np.rint(2.0 * solid.mesh.param_nodes[:, :n_nodes]).astype(np.int64)
    span = lattice.max(axis=1) + 1
    code = (lattice[0] * span[1] + lattice[1]) * span[2] + lattice[2]
    order = np.argsort(code)
    shift = round(2.0 * offset * solid.layout.cell)
    want = ((lattice[0, nodes] + shift) * span[1] + lattice[1, nodes]) * span[2] \
        + lattice[2, nodes]
    at = np.minimum(np.searchsorted(code, want, sorter=order), code.size - 1)
    target = order[at]
    if not np.array_equal(code[target], want):
        return None
    angle = offset * solid.pitch
    turn = np.array([[math.cos(angle), -math.sin(angle), 0.0],
                     [math.sin(angle), math.cos(angle), 0.0], [0.0, 0.0, 1.0]])
    x = solid.mesh.mesh.doflocs
    if np.abs(x[:, target] - turn @ x[:, nodes]).max() > 1e-9 * np.abs(x).max():
        return None
    rows = (3 * target[:, None, None] + np.arange(3)[None, :, None]).repeat(3, axis=2)
    cols = (3 * nodes[:, None, None] + np.arange(3)[None, None, :]).repeat(3, axis=1)
    vals = np.broadcast_to(turn, (nodes.size, 3, 3))
    return sp.csr_matrix((vals.ravel(), (rows.ravel(), cols.ravel())),
                         shape=(3 * n_nodes, 3 * n_nodes))


def _teeth_flank_loads(solid: ToothSolid, elastic: ElasticModel, offsets, side: str,
                       grid_u: np.ndarray, grid_v: np.ndarray):
    """:func:`_flank_loads` of every tooth at ``offsets``: the loaded tooth's (offset 0)
    computed, its neighbours' the loaded tooth's turned by their pitches
    (:func:`_turned_rows`; computed where the mesh is not one tooth turned). The turned
    functionals equal the computed ones to round-off (≤ 1e-13 of their largest entry,
    tests/test_fe_tooth.py) and cost a sparse product instead of the facet points, hats
    and traces of two more teeth (issue 75). Returns the dicts offset → loads and offset
    → mid-surface functionals, and the loaded tooth's hat areas."""
    loads, a0, c0 = _flank_loads(solid, elastic, 0, side, grid_u, grid_v)
    out_loads, out_centre = {0: loads}, {0: c0}
    n_nodes = elastic.n_dofs // 3
    rows = np.union1d(np.flatnonzero(np.diff(loads.indptr)),
                      np.flatnonzero(np.diff(c0.indptr)))
    nodes = np.unique(rows // 3)
    for t in offsets:
        if t == 0:
            continue
        turn = _turned_rows(solid, n_nodes, t, nodes)
        if turn is None:
            out_loads[t], _, out_centre[t] = _flank_loads(solid, elastic, t, side, grid_u,
                                                          grid_v)
            continue
        out_loads[t] = (turn @ loads).tocsr()
        out_centre[t] = (turn @ c0).tocsr()
    return ({t: out_loads[t] for t in sorted(out_loads)},
            {t: out_centre[t] for t in sorted(out_centre)}, a0)


def _solved_rows(loads: dict, centre: dict, area: np.ndarray, grid_u: np.ndarray,
                 grid_v: np.ndarray, options: FEOptions):
    """The hat loads, mid-surface functionals, hat areas and profile grid of the rows
    whose unit loads are solved (``options.load_row_step``, :attr:`FEOptions.solved_rows`):
    the full grid's hat functions at those rows, the others left out — the same loads
    and functionals as the full model's there, so the coefficients are its own at those
    rows (issue 75: every other row solved, the rest interpolated). All of them at the
    default step 1."""
    rows = options.solved_rows
    if len(rows) == grid_v.size:
        return loads, centre, area, grid_v
    keep = (np.arange(grid_u.size)[:, None] * grid_v.size + np.asarray(rows)[None, :]).ravel()
    return ({t: m[:, keep].tocsr() for t, m in loads.items()},
            {t: m[:, keep].tocsr() for t, m in centre.items()}, area[keep], grid_v[rows])


def _fillet_points(solid: ToothSolid, elastic: ElasticModel, offsets: list[int]) -> _FilletPoints:
    """Stress points (2 × 2 Gauss points of each facet) along both roots of every tooth."""
    lay = solid.layout
    blocks = []
    for t in offsets:
        for s, side in enumerate(_SIDES):
            slot, up = solid.fillet_facets(t, side)
            blocks.append((t, s, side, np.r_[slot, up], slot.size))
    facets = np.concatenate([b[3] for b in blocks])
    fb = _facet_points(solid, facets, 3)
    par, x, grads = fb.param, fb.x, fb.grads  # (3, F, Q), (3, F, Q), (nb, 3, F, Q)
    nb, nq = grads.shape[0], grads.shape[3]
    op = stress_operator(elastic, grads.reshape(nb, 3, -1), np.repeat(fb.tind, nq))
    stations = None
    index_blocks, at = [], 0
    in_root = np.ones(par.shape[1] * nq, dtype=bool)
    for t, s, side, fac, n_slot in blocks:
        p = par[:, at:at + fac.size].reshape(3, -1)  # this block's points, facet-major
        in_root[at * nq + n_slot * nq:(at + fac.size) * nq] = solid.in_root(
            side, p[:, n_slot * nq:])
        a0 = lay.side_a(t, side)
        key = np.where(np.arange(fac.size * nq) < n_slot * nq,
                       (p[0] - (a0 - lay.slot)) if side == "left" else (a0 + lay.slot - p[0]),
                       lay.slot + p[1] - lay.rim)
        w = np.round(p[2], 9)
        st = np.unique(w)
        arcs = np.unique(np.round(key, 9))
        if stations is None:
            stations = st
        idx = np.full((st.size, arcs.size), -1)
        idx[np.searchsorted(st, w), np.searchsorted(arcs, np.round(key, 9))] = \
            at * nq + np.arange(fac.size * nq)
        if np.any(idx < 0):
            raise LTCAError("fillet points: the facets do not form a regular grid")
        index_blocks.append((t, s, idx))
        at += fac.size
    k = lay.neighbours
    index = np.zeros((len(offsets), 2, *index_blocks[0][2].shape), dtype=int)
    for t, s, idx in index_blocks:
        index[t + k, s] = idx
    pos = x.reshape(3, -1).T
    u, v = projection_fractions(solid.sections.corners, pos[:, 2], np.hypot(pos[:, 0],
                                                                            pos[:, 1]))
    return _FilletPoints(op, pos, u, v, index, stations / lay.face, in_root)


#: [1] the load grid's lowest profile fraction by default (the ease-off grid's) and its
#: margin above where the generated working flank begins (:func:`load_v_limits`)
LOAD_V_LOW = 0.05
LOAD_V_MARGIN = 0.01


def load_v_limits(sections, flank: str, options: FEOptions) -> tuple[float, float]:
    """The profile fractions [1] the load grid covers on ``flank`` (a flank name).

    ``options.load_v_limits`` if given; else (max(:data:`LOAD_V_LOW`, v₀ +
    :data:`LOAD_V_MARGIN`), 1), v₀ where the generated flank begins in every section
    (:meth:`contact.compliance.fe.section.ToothSections.flank_start`): the grid follows
    the flank's extent, so that every bundled case's members take the default model.

    Raises
    ------
    InputError — given limits below where the flank begins (naming ``load_v_limits``).
    """
    start = sections.flank_start(flank)
    if options.load_v_limits is None:
        return (max(LOAD_V_LOW, start + LOAD_V_MARGIN), 1.0)
    low, high = options.load_v_limits
    if low < start - 1e-9:
        raise InputError(f"load_v_limits: the {sections.member}'s {flank} flank is generated "
                         f"from v = {start:.3f} up in every section; the load grid must start "
                         f"there or higher (or give None to follow the flank), got {low:g}")
    return (low, high)


def build_influence_model(case, member: str, flank: str = "drive",
                          options: FEOptions | None = None, *,
                          solver: str = "auto", isolated: bool = False) -> InfluenceModel:
    """Build a member's FE model: solid, stiffness, factorisation, loads, fillet points.

    Parameters
    ----------
    case : geometry.case.Case
    member : str — ``"pinion"`` or ``"gear"``
    flank : str — the working flank: ``"drive"`` (default), ``"coast"`` or a flank name
        (:func:`contact.compliance.fe.options.member_flank`)
    options : FEOptions, optional
    solver : str — ``"auto"`` or a key of :data:`contact.compliance.fe.elasticity.SOLVERS`
    isolated : bool — factorise and solve in a worker process, so that a signal is
        honoured within a tenth of a second (:func:`contact.compliance.fe.elasticity.
        factorise`); then close the model's factorisation (``model.factor.close()``)
        when done

    Returns
    -------
    InfluenceModel

    Raises
    ------
    InputError, LTCAError, ModelUnavailableError
        As :func:`contact.compliance.fe.solid.build_tooth_solid` and
        :func:`contact.compliance.fe.elasticity.factorise`.
    """
    opt = options if options is not None else FEOptions()
    name = member_flank(case, member, flank)
    times = {}
    t0 = time.perf_counter()
    # kept for a re-synthesis's reuse check, which compares the next design's solid with
    # this one (contact.compliance.fe.reuse.point_deviation)
    solid = kept_tooth_solid(case, member, opt)
    grid_u = np.linspace(0.0, 1.0, opt.load_nu)
    grid_v = np.linspace(*load_v_limits(solid.sections, name, opt), opt.load_nv)
    times["solid"] = time.perf_counter() - t0
    solver = resolve_solver(solver)
    # CHOLMOD reads K's lower triangle: only that is assembled (half the memory, issue 75)
    elastic = elastic_model(solid.mesh.mesh, opt.element, opt.youngs_modulus,
                            opt.poisson_ratio, lower=solver == "cholmod")
    times["assembly"] = elastic.assemble_time
    n_nodes = elastic.basis.N
    fixed_nodes = solid.constrained_nodes()
    fixed_nodes = fixed_nodes[fixed_nodes < n_nodes]
    # the stiffness handed to its factorisation and released from the model: K's memory
    # is free before the factor takes its own (the build's peak, issue 53)
    box = [elastic.stiffness]
    elastic = dataclasses.replace(elastic, stiffness=None)
    fixed = (3 * fixed_nodes[:, None] + np.arange(3)).ravel()
    # the mesh's lattice cut by planes of nodes (nested dissection, issue 75): half the
    # floating-point work of CHOLMOD's own AMD ordering, as METIS's, without pymetis
    ordering = None if solver != "cholmod" else lattice_dissection(
        np.rint(2.0 * solid.mesh.param_nodes[:, :n_nodes]).astype(np.int64),
        np.setdiff1d(np.arange(3 * n_nodes), fixed))
    factor = factorise(box.pop(), fixed, solver, isolated=isolated, ordering=ordering)
    del ordering
    times["factorisation"] = factor.factor_time
    t1 = time.perf_counter()
    side = solid.sections.side_name(name)
    loads, centre, area = _teeth_flank_loads(
        solid, elastic, range(-solid.layout.neighbours, solid.layout.neighbours + 1), side,
        grid_u, grid_v)
    loads, centre, area, grid_v = _solved_rows(loads, centre, area, grid_u, grid_v, opt)
    fillet = _fillet_points(solid, elastic, sorted(loads))
    times["loads_and_points"] = time.perf_counter() - t1
    return InfluenceModel(solid, elastic, factor, name, side, grid_u, grid_v, loads, centre,
                          area, fillet, times)


@contextlib.contextmanager
def _small_pages():
    """NumPy's large arrays on ordinary pages while the block runs, the caller's setting
    restored afterwards.

    NumPy asks the kernel for transparent huge pages (``madvise(MADV_HUGEPAGE)``) on every
    array of 4 MB or more; where the kernel's ``transparent_hugepage/defrag`` is
    ``madvise`` (the common default) each such fault may compact memory synchronously
    to find 2 MB, which the FE build pays as system time on its many short-lived arrays
    of tens of MB (the stiffness's element blocks, the solves' blocks): measured on the
    default pinion model (issue 75, fourth round), the build's parent 2.40 → 1.46 s of
    system time, the assembly 1.74 → 1.10 s of CPU. Nothing changes where NumPy has no
    such switch (``_set_madvise_hugepage``, a private function of NumPy ≥ 1.20).
    Source: the Linux kernel's admin guide, "Transparent Hugepage Support".
    """
    switch = None
    for name in ("numpy._core.multiarray", "numpy.core.multiarray"):
        try:
            switch = importlib.import_module(name)._set_madvise_hugepage
            break
        except (ImportError, AttributeError):
            continue
    if switch is None:
        yield
        return
    before = switch(False)
    try:
        yield
    finally:
        switch(before)


def _peak_rss_mb() -> float | None:
    """Peak resident memory of this process [MB], where the platform reports it."""
    try:
        import resource

        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        return peak / (1024.0 * 1024.0) if sys.platform == "darwin" else peak / 1024.0
    except (ImportError, OSError):
        return None


#: tensors per block of :func:`principal_stresses` (its temporaries stay in the CPU's cache)
_EIGEN_BLOCK = 1 << 15
#: where ``|r| > 1 − _NEAR_DOUBLE`` (two principal values nearly equal) the trigonometric
#: formula's arccos loses digits (an error δ in r moves the pair's values by ~√δ); those
#: tensors take :func:`_pair_by_projection`
_NEAR_DOUBLE = 1e-3


def principal_stresses(tensor: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest principal values of stresses in Voigt order (the extreme
    eigenvalues of the symmetric 3 × 3 tensors), by the closed form.

    The trigonometric solution of the characteristic cubic (Smith, Comm. ACM 4 (1961)
    168): with q = tr σ / 3, p² = |σ − q I|² / 6 and r = det((σ − q I) / p) / 2, the
    principal values are q + 2 p cos(φ + 2πk/3), φ = arccos(r) / 3. Where two of them
    nearly coincide (|r| near 1) the pair is found from the third (the separated one,
    which the formula gives accurately), its eigenvector and the 2 × 2 tensor on the plane
    normal to it (:func:`_pair_by_projection`). Vectorised in blocks; ~10× faster than
    ``numpy.linalg.eigvalsh`` on the FE build's millions of tensors and equal to it within
    1e-10 of the tensor's norm (tests/test_root_stress.py).

    Parameters
    ----------
    tensor : ndarray (..., 6) — [MPa] (or MPa/N) components xx, yy, zz, yz, xz, xy

    Returns
    -------
    smax, smin : ndarray (...) — the largest and smallest principal values, in the
        tensor's unit
    """
    t = np.asarray(tensor, dtype=float)
    flat = t.reshape(-1, 6)
    smax, smin = np.empty(flat.shape[0]), np.empty(flat.shape[0])
    for lo in range(0, flat.shape[0], _EIGEN_BLOCK):
        block = flat[lo:lo + _EIGEN_BLOCK]
        smax[lo:lo + block.shape[0]], smin[lo:lo + block.shape[0]] = _principal_block(block)
    return smax.reshape(t.shape[:-1]), smin.reshape(t.shape[:-1])


def _principal_block(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`principal_stresses` of a block of tensors (n, 6)."""
    xx, yy, zz, yz, xz, xy = (t[:, i] for i in range(6))
    q = (xx + yy + zz) * (1.0 / 3.0)
    bx, by, bz = xx - q, yy - q, zz - q
    p2 = bx * bx + by * by + bz * bz + 2.0 * (yz * yz + xz * xz + xy * xy)
    p2 *= 1.0 / 6.0
    p = np.sqrt(p2)
    det = (bx * (by * bz - yz * yz) - xy * (xy * bz - yz * xz) + xz * (xy * yz - by * xz))
    p3 = p2 * p
    r = np.divide(0.5 * det, p3, out=np.zeros_like(det), where=p3 > 0.0)
    np.clip(r, -1.0, 1.0, out=r)
    phi = np.arccos(r) * (1.0 / 3.0)
    smax = q + 2.0 * p * np.cos(phi)
    smin = q + 2.0 * p * np.cos(phi + 2.0 * np.pi / 3.0)
    near = np.flatnonzero(np.abs(r) > 1.0 - _NEAR_DOUBLE)
    if near.size:
        smax[near], smin[near] = _pair_by_projection(t[near], q[near], p[near], r[near])
    return smax, smin


def _pair_by_projection(t: np.ndarray, q: np.ndarray, p: np.ndarray, r: np.ndarray
                        ) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest principal values of tensors (n, 6) two of whose values nearly
    coincide, from their invariants of :func:`_principal_block` (q = tr σ / 3, p, r): the
    separated value μ by the trigonometric formula (the largest where r ≥ 0, else the
    smallest: accurate there), its eigenvector v (the longest cross product of two rows of
    σ − μ I) and the other two as the eigenvalues of the 2 × 2 tensor on the plane normal
    to v (stable where they coincide)."""
    xx, yy, zz, yz, xz, xy = (t[:, i] for i in range(6))
    inv = 1.0 / np.where(p > 0.0, p, 1.0)
    bx, by, bz = (xx - q) * inv, (yy - q) * inv, (zz - q) * inv
    byz, bxz, bxy = yz * inv, xz * inv, xy * inv
    phi = np.arccos(r) / 3.0
    mu = 2.0 * np.cos(np.where(r >= 0.0, phi, phi + 2.0 * np.pi / 3.0))
    rows = (np.stack([bx - mu, bxy, bxz]), np.stack([bxy, by - mu, byz]),
            np.stack([bxz, byz, bz - mu]))
    cands = np.stack([np.cross(rows[0], rows[1], axis=0), np.cross(rows[0], rows[2], axis=0),
                      np.cross(rows[1], rows[2], axis=0)])  # (3, 3, n)
    length = np.linalg.norm(cands, axis=1)  # (3, n)
    k = np.argmax(length, axis=0)
    n = np.arange(t.shape[0])
    v = cands[k, :, n].T / np.where(length[k, n] > 0.0, length[k, n], 1.0)  # (3, n)
    axis = np.zeros_like(v)
    axis[np.argmin(np.abs(v), axis=0), n] = 1.0  # the axis least along v
    e1 = np.cross(v, axis, axis=0)
    e1 /= np.linalg.norm(e1, axis=0)
    e2 = np.cross(v, e1, axis=0)
    b = np.stack([np.stack([bx, bxy, bxz]), np.stack([bxy, by, byz]),
                  np.stack([bxz, byz, bz])])  # (3, 3, n)
    be1, be2 = np.einsum("ijn,jn->in", b, e1), np.einsum("ijn,jn->in", b, e2)
    a11, a22, a12 = (e1 * be1).sum(0), (e2 * be2).sum(0), (e1 * be2).sum(0)
    mid, half = 0.5 * (a11 + a22), np.hypot(0.5 * (a11 - a22), a12)
    return q + p * np.maximum(mu, mid + half), q + p * np.minimum(mu, mid - half)


def _load_progress(progress, total: int, initial: int, desc: str):
    """The reporter of the unit loads solved: a tqdm bar (``True``), plain lines with the
    rate and the remaining time (``"lines"``: :class:`geometry.core.progress.
    ProgressLines`, as the studies print them when not on a terminal) or None."""
    if progress == "lines":
        from geometry.core.progress import ProgressLines

        return ProgressLines(total, initial, desc, "load")
    if progress:
        return tqdm(total=total, initial=initial, desc=desc, unit="load")
    return None


def progress_line(progress, text: str) -> None:
    """A plain progress line of an FE build on standard error, in the ``"lines"`` mode of
    ``progress`` only (a bar or nothing otherwise)."""
    if progress == "lines":
        print(text, file=sys.stderr, flush=True)


def _other_flank_model(model: InfluenceModel) -> InfluenceModel:
    """The same member's model loaded on its other flank: the solid, stiffness,
    factorisation and fillet points of ``model`` shared, the load grid (its profile
    limits follow that flank, :func:`load_v_limits`), the hat loads and the mid-surface
    functionals of that flank's side made as :func:`build_influence_model` makes them —
    so its coefficients are those of a build of their own, without a second solid,
    assembly and factorisation (issue 75: ``ltca synthesize`` checks both flanks).

    Parameters
    ----------
    model : InfluenceModel — built, its factorisation open

    Returns
    -------
    InfluenceModel — ``times`` holds the shared phases' times as ``model`` has them and
        the new loads' own
    """
    solid, opt = model.solid, model.solid.options
    t1 = time.perf_counter()
    flank = _other(model.flank)
    grid_v = np.linspace(*load_v_limits(solid.sections, flank, opt), opt.load_nv)
    side = solid.sections.side_name(flank)
    loads, centre, area = _teeth_flank_loads(solid, model.elastic, model.offsets, side,
                                             model.grid_u, grid_v)
    loads, centre, area, grid_v = _solved_rows(loads, centre, area, model.grid_u, grid_v,
                                               opt)
    times = dict(model.times, loads_and_points=time.perf_counter() - t1)
    return dataclasses.replace(model, flank=flank, side=side, grid_v=grid_v, loads=loads,
                               centre=centre, hat_area=area, times=times)


class _BlockSolve:
    """The unit loads solved block by block on the free dofs and their responses (issue
    75, fourth round): ``(lo, hi)`` → the compliance (teeth, nL, k), the centreline
    displacement (teeth, nL, k) and the fillet stress (P, 6, k) of loads ``lo:hi``.

    The loads' free rows are taken once (CSC) and each block written straight into the
    solver's right-hand side block (the worker's shared memory where it has one:
    :meth:`Factorisation.rhs_block`); the solutions stay on the free dofs (the
    constrained ones are zero, so the functionals' rows there add nothing) and meet one
    stacked functional matrix — the flank and mid-surface functionals of every tooth and
    the stress operator — in one sparse product, instead of a displacement vector of all
    dofs scattered from the free ones and seven products. The same sums as
    :meth:`InfluenceModel.compliance_of`, :meth:`~InfluenceModel.centreline_of` and
    :meth:`~InfluenceModel.stress_of` of :meth:`InfluenceModel.solve`'s displacements,
    less the constrained dofs' zero terms."""

    def __init__(self, model: InfluenceModel) -> None:
        free = model.factor.free
        self.model, self.teeth = model, len(model.offsets)
        self.loads = model.loads[0][free].tocsc()  # (F, nL)
        self.nl = self.loads.shape[1]
        self.functionals = sp.vstack(
            [model.loads[t][free].T for t in model.offsets]
            + [model.centre[t][free].T for t in model.offsets]
            + [model.fillet.operator[:, free]], format="csr")  # (2 T nL + 6P, F)
        self._c = np.empty(free.size * min(_CHUNK, self.nl))  # the solutions, C order

    def __call__(self, lo: int, hi: int) -> dict:
        k = hi - lo
        factor = self.model.factor
        rhs = factor.rhs_block(k)
        self.loads[:, lo:hi].toarray(out=rhs)
        disp = factor.solve_free(rhs)  # (F, k), Fortran order (CHOLMOD's columns)
        c = self._c[:disp.size].reshape(disp.shape)  # C order for the sparse product
        np.copyto(c, disp)
        del disp
        out = self.functionals @ c
        n = self.teeth * self.nl
        return {"compliance": out[:n].reshape(self.teeth, self.nl, k),
                "centreline": out[n:2 * n].reshape(self.teeth, self.nl, k),
                "stress": out[2 * n:].reshape(-1, 6, k)}


def influence_dataset(model: InfluenceModel, case, *, progress: bool | str = True,
                      key: str = "", checkpoint=None) -> xr.Dataset:
    """Solve the unit loads of a model and gather the influence coefficients.

    Parameters
    ----------
    model : InfluenceModel
    case : geometry.case.Case — for the case name and the member's blank data
    progress : bool or "lines" — a progress bar over the loads solved (tqdm), plain lines
        with the rate and the remaining time (``"lines"``), or none (False)
    key : str — the cache key, stored as an attribute
    checkpoint : contact.compliance.fe.cache.BlockCheckpoint, optional — where the
        solved blocks of loads are kept as they are solved (all but the last one solved,
        which the entry's write follows), and read from before (an interrupted build's:
        only the other blocks are solved)

    Returns
    -------
    xarray.Dataset
        ``compliance`` and ``centreline_compliance`` (load_u, load_v, tooth, u, v)
        [mm/N] (flank points; the tooth's mid-surface under them); ``fillet_stress``
        (load_u, load_v, tooth, side, station, arc, component) [MPa/N];
        ``fillet_max_principal``, ``fillet_min_principal`` (load_u, load_v, tooth, side,
        station, arc) [MPa/N]; positions and fractions of the fillet points and of the
        load grid on the loaded tooth's flank; the blank corners; the cost as attributes.
    """
    t0 = time.perf_counter()
    nl = model.loads[0].shape[1]
    offsets = model.offsets
    member = model.solid.member
    arrays = {"compliance": np.empty((len(offsets), nl, nl)),
              "centreline": np.empty((len(offsets), nl, nl)),
              "stress": np.empty((model.fillet.position.shape[0], 6, nl))}
    blocks = [(lo, min(lo + _CHUNK, nl)) for lo in range(0, nl, _CHUNK)]
    todo = []
    for lo, hi in blocks:  # the blocks an interrupted build kept
        part = checkpoint.read(lo, hi) if checkpoint is not None else None
        if part is not None and all(part.get(n, np.empty(0)).shape == a[..., lo:hi].shape
                                    for n, a in arrays.items()):
            for name, a in arrays.items():
                a[..., lo:hi] = part[name]
        else:
            todo.append((lo, hi))
    kept = nl - sum(hi - lo for lo, hi in todo)
    if kept:
        log.info("%s %s unit loads: resuming, %d of %d already solved (kept by an interrupted "
                 "build)", case.name, member, kept, nl)
    bar = _load_progress(progress, nl, kept, f"FE {member} unit loads")
    solve = _BlockSolve(model) if todo else None
    for lo, hi in todo:
        solved = solve(lo, hi)
        for name, a in arrays.items():
            a[..., lo:hi] = solved[name]
        if checkpoint is not None and (lo, hi) != todo[-1]:
            # the last block solved is not kept: the entry is written next (~0.1 s of CPU
            # per part on the default models, issue 75)
            checkpoint.write(lo, hi, solved)
        log.info("%s %s unit loads %d-%d of %d solved", case.name, member, lo, hi, nl)
        if bar is not None:
            bar.update(hi - lo)
    if bar is not None:
        bar.close()
    del solve
    comp, centre, stress = arrays["compliance"], arrays["centreline"], arrays["stress"]
    solve_time = time.perf_counter() - t0
    nu, nv = len(model.grid_u), len(model.grid_v)
    idx = model.fillet.index  # (T, 2, S, A)
    # compliance[a, t, b]: load a on the loaded tooth, functional b on tooth t
    g = comp.transpose(2, 0, 1).reshape(nu, nv, len(offsets), nu, nv)
    gc = centre.transpose(2, 0, 1).reshape(nu, nv, len(offsets), nu, nv)
    sig = stress.transpose(2, 0, 1)[:, idx]  # (nl, T, 2, S, A, 6)
    smax, smin = principal_stresses(sig)
    sig = sig.reshape(nu, nv, *sig.shape[1:])
    smax, smin = smax.reshape(nu, nv, *smax.shape[1:]), smin.reshape(nu, nv, *smin.shape[1:])
    sol = model.solid
    flank_names = [sol.sections.left_flank, _other(sol.sections.left_flank)]
    # the load grid's points on the loaded tooth's flank: solve them on the mesh surface
    x0 = _grid_positions(model)
    blank = case.member(sol.member).blank
    cost = {
        "n_dofs": int(model.elastic.n_dofs),
        "n_unknowns": int(model.factor.free.size),
        "n_elements": int(sol.mesh.mesh.nelements),
        "n_loads": int(nl),
        "solver": model.factor.solver,
        "factor_nonzeros": int(model.factor.factor_nnz),
        "time_solid_s": round(model.times["solid"], 3),
        "time_assembly_s": round(model.times["assembly"], 3),
        "time_factorisation_s": round(model.times["factorisation"], 3),
        "time_loads_s": round(model.times["loads_and_points"], 3),
        "time_solves_s": round(solve_time, 3),
        "time_total_s": round(sum(model.times.values()) + solve_time, 3),
        "min_jacobian_ratio": round(sol.mesh.min_jacobian, 4),
    }
    peak = _peak_rss_mb()
    if peak is not None:
        cost["peak_rss_mb"] = round(peak, 1)
    log.info("%s %s influence coefficients: %s", case.name, sol.member, cost)
    coords = {
        "load_u": ("load_u", model.grid_u, {
            "units": "1", "long_name": "lengthwise fraction of the unit load, toe 0 to heel 1"}),
        "load_v": ("load_v", model.grid_v, {
            "units": "1", "long_name": "profile fraction of the unit load, root 0 to tip 1"}),
        "tooth": ("tooth", np.array(offsets, dtype=np.int32), {
            "units": "1", "long_name": "tooth offset from the loaded tooth"}),
        "u": ("u", model.grid_u, {"units": "1", "long_name":
                                  "lengthwise fraction of the response point"}),
        "v": ("v", model.grid_v, {"units": "1", "long_name":
                                  "profile fraction of the response point"}),
        "side": ("side", np.array(flank_names), {"long_name":
                                                 "flank on whose side the root fillet lies"}),
        "station": ("station", model.fillet.station, {
            "units": "1", "long_name": "lengthwise parameter of the fillet point (face "
                                       "fraction of its element plane), toe 0 to heel 1"}),
        "arc": ("arc", np.arange(idx.shape[3], dtype=np.int32), {
            "units": "1", "long_name": "fillet point index from the slot middle up to the "
                                       "flank"}),
        "component": ("component", np.array(COMPONENTS), {
            "long_name": "stress component in the member frame (Voigt order)"}),
        "xyz": ("xyz", np.array(["x", "y", "z"]), {"long_name": "member-frame component"}),
        "corner_u": ("corner_u", np.array([0, 1], dtype=np.int32), {
            "units": "1", "long_name": "toe 0 / heel 1"}),
        "corner_v": ("corner_v", np.array([0, 1], dtype=np.int32), {
            "units": "1", "long_name": "root 0 / tip 1"}),
        "zr": ("zr", np.array(["z", "rho"]), {"long_name": "projection-plane component"}),
    }
    fpos = model.fillet.position[idx]  # (T, 2, S, A, 3)
    data = {
        "compliance": data_var(("load_u", "load_v", "tooth", "u", "v"), g, "mm/N",
                               "normal displacement into the tooth at the response point of "
                               "the working flank of the tooth, per unit normal load on the "
                               "loaded tooth's working flank"),
        "centreline_compliance": data_var(
            ("load_u", "load_v", "tooth", "u", "v"), gc, "mm/N",
            "displacement of the tooth's mid-surface under the response point along its "
            "inward flank normal, per unit normal load on the loaded tooth's working flank "
            "(bending, shear and rim: the compliance without the local compression between "
            "flank and mid-surface)"),
        "fillet_stress": data_var(
            ("load_u", "load_v", "tooth", "side", "station", "arc", "component"), sig,
            "MPa/N", "stress at the root fillet point per unit normal load"),
        "fillet_max_principal": data_var(
            ("load_u", "load_v", "tooth", "side", "station", "arc"), smax, "MPa/N",
            "maximum principal stress at the root fillet point per unit normal load "
            "(tension side)"),
        "fillet_min_principal": data_var(
            ("load_u", "load_v", "tooth", "side", "station", "arc"), smin, "MPa/N",
            "minimum principal stress at the root fillet point per unit normal load "
            "(compression side)"),
        "fillet_position": data_var(("tooth", "side", "station", "arc", "xyz"), fpos, "mm",
                                    "root fillet point in the member frame"),
        "fillet_u": data_var(("tooth", "side", "station", "arc"), model.fillet.u[idx], "1",
                             "lengthwise fraction of the root fillet point"),
        "fillet_v": data_var(("tooth", "side", "station", "arc"), model.fillet.v[idx], "1",
                             "profile fraction of the root fillet point (negative: under "
                             "the root cone)"),
        "fillet_in_root": data_var(
            ("tooth", "side", "station", "arc"), model.fillet.in_root[idx].astype(np.int8),
            "1", "1 where the point lies in the root (the half slot and the element rows "
                 "up to the fillet's junction with the flank), 0 on the flank above it: "
                 "the root stress is the largest over the points with 1"),
        "flank_position": data_var(("u", "v", "xyz"), x0, "mm",
                                   "load grid point on the loaded tooth's working flank "
                                   "(FE surface), member frame"),
        "hat_area": data_var(("u", "v"), model.hat_area.reshape(nu, nv), "mm2",
                             "flank area of the unit load's hat function"),
        "blank_corners": data_var(("corner_u", "corner_v", "zr"), sol.sections.corners, "mm",
                                  "the blank's projection-plane corners (z, rho)"),
    }
    opt = sol.options
    attrs = {
        "title": f"{case.name}: {sol.member} FE influence coefficients",
        "case": case.name,
        "member": sol.member,
        "flank": model.flank,
        "flank_side": model.side,
        "teeth": int(blank.teeth),
        "hand": case.member(sol.member).hand,
        "pitch": float(sol.pitch),
        "concave_shift": int(sol.sections.concave_shift),
        "rim_depth_mm": float(sol.rim_depth),
        "slot_depth_mm": float(sol.sections.slot_depth),
        "constraint": opt.constraint,
        "element": opt.element,
        "options": opt.to_json(),
        "cache_key": key,
        "toolkit_version": __version__,
        "frame": "member frame: origin at the crossing point, z along the member axis "
                 "towards its back; the loaded tooth is the reference tooth of "
                 "geometry.flank (tooth offsets turn it by whole pitches)",
        "load": "unit normal force distributed over the flank as the bilinear hat "
                "function of the load grid point (influence coefficients, docs/fe.md)",
        "source": "contact.compliance.fe.influence (3-D linear elasticity, quadratic "
                  "hexahedra, scikit-fem)",
        "cost": json.dumps(cost, sort_keys=True),
        **{f"cost_{k}": v for k, v in cost.items()},
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _other(flank: str) -> str:
    return "concave" if flank == "convex" else "convex"


def _grid_positions(model: InfluenceModel) -> np.ndarray:
    """Member-frame points of the load grid on the loaded tooth's working flank (nu, nv, 3)
    [mm]: the generated flank of the sections (:meth:`ToothSections.flank_angle`)."""
    return flank_grid_positions(model.solid.sections, model.flank, model.grid_u,
                                model.grid_v)


def flank_grid_positions(sections, flank: str, grid_u: np.ndarray,
                         grid_v: np.ndarray) -> np.ndarray:
    """Member-frame points (nu, nv, 3) [mm] of a load grid (fractions ``grid_u`` (nu,),
    ``grid_v`` (nv,) [1]) on the reference tooth's ``flank`` (a flank name) of
    ``sections`` (:class:`contact.compliance.fe.section.ToothSections`): the flank angle
    of the sections (:meth:`~contact.compliance.fe.section.ToothSections.flank_angle`) at
    the blank's bilinear projection-plane point of each fraction pair.

    Raises
    ------
    InputError — a fraction outside the flank's extent (as ``flank_angle``).
    """
    uu, vv = np.meshgrid(grid_u, grid_v, indexing="ij")
    phi = sections.flank_angle(flank, uu, vv)
    c = sections.corners
    z = (1 - uu) * (1 - vv) * c[0, 0, 0] + uu * (1 - vv) * c[1, 0, 0] \
        + (1 - uu) * vv * c[0, 1, 0] + uu * vv * c[1, 1, 0]
    rho = (1 - uu) * (1 - vv) * c[0, 0, 1] + uu * (1 - vv) * c[1, 0, 1] \
        + (1 - uu) * vv * c[0, 1, 1] + uu * vv * c[1, 1, 1]
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=-1)


def influence_coefficients(case, member: str, flank: str = "drive",
                           options: FEOptions | None = None, *, cache: bool = True,
                           cache_dir: str | os.PathLike[str] | None = None,
                           progress: bool | str = True, solver: str = "auto",
                           other_flank: bool = False,
                           written: Callable[[Path, str, xr.Dataset], None] | None = None
                           ) -> xr.Dataset:
    """A member's FE influence coefficients, from the cache or built and cached.

    Parameters
    ----------
    case : geometry.case.Case — face milling or face hobbing
    member : str — ``"pinion"`` or ``"gear"``
    flank : str — the working flank: ``"drive"`` (default), ``"coast"`` or a flank name
    options : FEOptions, optional — the FE model (default ``FEOptions()``)
    cache : bool — read and write the cache (default True)
    cache_dir : path, optional — the cache directory (default
        :func:`contact.compliance.fe.cache.cache_directory`)
    progress : bool or "lines" — a progress bar while the unit loads are solved, or
        plain lines on standard error (``"lines"``: a line per build phase with the
        estimate of the last builds in this cache, then the loads solved with the rate
        and the remaining time, as the studies print when not on a terminal)
    solver : str — ``"auto"`` (CHOLMOD, else PARDISO, else SuperLU) or a solver name
    other_flank : bool — where this flank's coefficients are built (not read from the
        cache) and ``cache`` is on, also build and cache the member's other flank's from
        the same solid and factorisation (:func:`_other_flank_model`) unless that entry
        is cached: the drive and coast flanks of a design for ~1.4 times one flank's
        build instead of twice (``ltca synthesize`` checks both; docs/fe.md, Cost). A
        failure of the other flank's build is logged (a warning), not raised: this
        flank's coefficients are returned as without it
    written : callable, optional — called as ``written(path, key, ds)`` with each entry
        this call builds and writes to the cache (this flank's and, with
        ``other_flank``, the other's): the dataset :func:`contact.compliance.fe.cache.
        read_cache_entry` would read back from ``path`` (the same values, key and
        checksum), so that a caller's memo of the files read holds it without reading it
        (:func:`contact.compliance.fe.contact_compliance.shared_coefficients`; issue 75)

    Returns
    -------
    xarray.Dataset — see :func:`influence_dataset`; the attribute ``cache_key`` names it,
        ``data_sha256`` is its data's checksum (when cached).

    Raises
    ------
    InputError, LTCAError, ModelUnavailableError
        As :func:`build_influence_model`; LTCAError also if the built coefficients hold
        non-finite values (not cached). A cache entry that is unreadable, foreign,
        corrupt or not finite is never used: it is set aside, one warning logged, and the
        coefficients rebuilt (:func:`contact.compliance.fe.cache.read_cache_entry`). A
        cache that cannot be written (a read-only or full file system) is no error: the
        built coefficients are returned with the attribute ``cache_not_written`` (why;
        :func:`contact.compliance.fe.cache.not_written`) and one warning logged.

    Notes
    -----
    The influence-coefficient (unit-load superposition) method: tooth compliance is "the
    amount of deflection at any contact point due to a unit load applied at various
    points on the same tooth surface" (seed §3.2, after Vaidyanathan, Houser & Busby
    1993, seed ref. [3.5]; the matrix of seed Eq. 3.11). The seed computes it with a
    Rayleigh–Ritz shell and validates the shell against an FE model (seed Fig. 3.4);
    here each unit load is solved on a 3-D FE model of the member's teeth (quadratic
    hexahedra, isotropic linear elasticity; scikit-fem: T. Gustafsson, G. D. McBain
    2020, "scikit-fem: A Python package for finite element assembly", *JOSS* 5(52),
    2369), as in the FE tooth models the seed cites (Wilcox, Chimner & Nowell 1997, seed
    ref. [3.1]); the fillet stresses per unit load are recorded with them, and the
    maximum principal stress at the fillet is the root stress
    (:func:`contact.compliance.fe.superposition.fillet_stress`). Load and response are the same hat
    functional, so G is symmetric (Maxwell–Betti; module docstring, docs/fe.md).

    The factorisation and the solves run in a worker process (where ``fork`` exists; for
    CHOLMOD a new lean interpreter, :mod:`contact.compliance.fe.solver_worker`), so
    that SIGTERM or Ctrl-C ends a build within a tenth of a second rather than after the
    native factorisation (issue 64); each solved block of unit loads is kept beside the
    entry (:class:`contact.compliance.fe.cache.BlockCheckpoint`), so that a build
    interrupted after some blocks resumes from them.

    Written atomically (geometry.atomic_files): a file in the cache is always complete,
    and carries a checksum of its data
    (:func:`contact.compliance.fe.cache.write_cache_entry`). The key covers the member's
    generating inputs, the working flank, the options and the toolkit version
    (:func:`contact.compliance.fe.cache.cache_key`).
    """
    opt = options if options is not None else FEOptions()
    if not isinstance(opt, FEOptions):
        raise InputError(f"options: must be an FEOptions, got {type(opt).__name__}")
    name = member_flank(case, member, flank)
    key = cache_key(case.member(member), name, opt)
    path = cache_path(key, cache_dir)
    if cache:
        ds = read_cache_entry(path, key)
        if ds is not None:
            log.info("%s %s influence coefficients read from %s", case.name, member, path)
            return ds
    t0 = time.perf_counter()
    progress_line(progress, f"FE {member} influence coefficients of {case.name} ({name} "
                            f"flank): not in the cache, building them"
                            # the estimate opens cache entries: only where it is printed
                            + (_estimate_text(cache_dir) if cache and progress == "lines"
                               else ""))
    with _small_pages():
        ds = _build_and_cache(case, member, name, opt, solver, progress, cache, cache_dir,
                              other_flank, path, key, t0, written)
    progress_line(progress, f"FE {member} influence coefficients built in "
                            f"{time.perf_counter() - t0:.0f} s")
    return ds


def _build_and_cache(case, member: str, name: str, opt: FEOptions, solver: str, progress,
                     cache: bool, cache_dir, other_flank: bool, path, key: str,
                     t0: float, written=None) -> xr.Dataset:
    """The build of :func:`influence_coefficients` once the cache missed: the model, its
    dataset, the cache entry and, where asked, the other flank's."""
    # the factor in a worker process: a signal is honoured at once (issue 64)
    model = build_influence_model(case, member, name, opt, solver=solver, isolated=True)
    try:
        if progress == "lines":
            progress_line(progress, f"FE {member}: model of {model.factor.free.size} unknowns "
                                    f"built and factorised ({model.factor.solver}) in "
                                    f"{time.perf_counter() - t0:.0f} s; solving "
                                    f"{model.loads[0].shape[1]} unit loads")
        checkpoint = BlockCheckpoint(path, key) if cache else None
        ds = influence_dataset(model, case, progress=progress, key=key,
                               checkpoint=checkpoint)
        if cache:
            ds = _cached(ds, case, member, path, key, checkpoint, written)
        if cache and other_flank:
            try:
                _other_flank_entry(model, case, member, opt, cache_dir, progress, written)
            except Exception as exc:  # this flank's result stands; the other's own build
                # (when asked for) raises its error where it belongs
                log.warning("%s %s: the other flank's influence coefficients not built "
                            "on this factorisation: %s", case.name, member, exc)
    finally:
        model.factor.close()
    return ds


def _cached(ds: xr.Dataset, case, member: str, path, key: str,
            checkpoint: BlockCheckpoint, written=None) -> xr.Dataset:
    """``ds`` written to the cache as ``path`` (its block checkpoints removed) and handed
    to ``written`` (where given), or marked as not written where the file system refuses
    (issue 72)."""
    try:
        ds = write_cache_entry(ds, path, key)
    except OSError as exc:  # read-only or full: used from memory, said (issue 72)
        return not_written(ds, path, exc)
    checkpoint.clear()
    log.info("%s %s influence coefficients cached in %s", case.name, member, path)
    if written is not None:
        written(Path(path), key, ds)
    return ds


def _other_flank_entry(model: InfluenceModel, case, member: str, opt: FEOptions,
                       cache_dir, progress, written=None) -> None:
    """The other flank's coefficients of ``model``'s member built on its factorisation and
    cached, unless an entry of them is cached already."""
    name = _other(model.flank)
    key = cache_key(case.member(member), name, opt)
    path = cache_path(key, cache_dir)
    if read_cache_entry(path, key) is not None:
        return
    progress_line(progress, f"FE {member} influence coefficients of {case.name} ({name} "
                            f"flank) on the same factorisation")
    other = _other_flank_model(model)
    checkpoint = BlockCheckpoint(path, key)
    _cached(influence_dataset(other, case, progress=progress, key=key,
                              checkpoint=checkpoint), case, member, path, key, checkpoint,
            written)


def _estimate_text(cache_dir) -> str:
    """``" (~40 s by the last builds here)"``: the median build time of the entries of the
    cache directory (their ``cost_time_total_s``, the ten newest), or "" without any."""
    from contact.compliance.fe.cache import cache_directory

    try:
        files = sorted(cache_directory(cache_dir).glob("fe-*.nc"),
                       key=lambda f: f.stat().st_mtime)[-10:]
    except OSError:
        return ""
    times = []
    for f in files:
        try:
            with xr.open_dataset(f, engine="netcdf4") as ds:
                times.append(float(ds.attrs["cost_time_total_s"]))
        except (OSError, KeyError, ValueError, TypeError):
            continue
    if not times:
        return ""
    return f" (~{float(np.median(times)):.0f} s by the last builds in this cache)"

