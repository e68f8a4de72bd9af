"""Structured hexahedral meshes mapped from a parameter box: the mesh code of the FE models.

A mesh is laid out in a *parameter space* of integer-spaced vertices (a tensor box of
unit cells, some of them removed), turned into 27-node hexahedra (skfem.MeshHex2) whose
nodes — vertices, edge, face and cell midpoints — are then moved by a mapping from the
parameter space to the physical space. Because every node of the quadratic geometry is
placed by the mapping, curved boundaries are followed to second order (isoparametric
elements). The same code meshes the gear teeth (:mod:`contact.compliance.fe.solid`) and
the cantilever that checks it against beam theory (tests/test_fe_tooth.py).

Public names
------------
graded             node positions of a graded 1-D division, vertices and midpoints
size_exponents     the exponents of its element sizes (growth factor q: sizes q^e)
geometric_ratio    the growth factor that gives a geometric division a first element size
at_index           interpolate such a table at a parameter coordinate
MappedMesh         the parameter mesh, the physical mesh and the parameter coordinates
mapped_mesh        build one
FacetPoints        quadrature points on facets with basis values, gradients and normals
facet_points       compute them
BasisFields        basis values and gradients, the mapping's points and Jacobian there
basis_fields       compute them at reference points of the elements
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import skfem
from skfem.quadrature import get_quadrature

from geometry.core.errors import InputError, LTCAError

__all__ = ["BasisFields", "FacetPoints", "MappedMesh", "at_index", "basis_fields", "facet_points",
           "geometric_ratio", "graded", "mapped_mesh", "size_exponents"]


def size_exponents(n: int, fine: str) -> np.ndarray:
    """Exponents e_k (n,) of the element sizes q^e_k of a division into ``n`` elements
    graded from its start (e_k = k) or from both ends (``fine="both"``: min(k, n − 1 − k)),
    the smallest element's 0; [1]."""
    k = np.arange(n)
    return np.minimum(k, n - 1 - k) if fine == "both" else k


def graded(n: int, ratio: float = 1.0, fine: str = "start") -> np.ndarray:
    """Fractions in [0, 1] of a graded division into ``n`` elements, at 2n + 1 points.

    Parameters
    ----------
    n : int — [1] elements, ≥ 1
    ratio : float — [1] largest / smallest element (geometric progression), ≥ 1
    fine : str — where the smallest elements are: ``"start"``, ``"end"`` or ``"both"``
        (symmetric; for odd ``n`` the middle element is the largest)

    Returns
    -------
    ndarray (2n + 1,) — [1] the vertices at even indices, the element midpoints
        (arithmetic means, so that a quadratic element's midside node sits in its
        middle) at odd indices.
    """
    e = size_exponents(n, "both" if fine == "both" else "start")
    q = ratio ** (1.0 / e.max()) if e.max() > 0 else 1.0
    h = q ** e.astype(float)
    x = np.r_[0.0, np.cumsum(h)] / h.sum()
    if fine == "end":
        x = 1.0 - x[::-1]
    out = np.empty(2 * n + 1)
    out[0::2] = x
    out[1::2] = 0.5 * (x[1:] + x[:-1])
    return out


def geometric_ratio(n: int, total: float, first: float, *, limit: float = 2.5,
                    fine: str = "start") -> float:
    """Growth factor q of a geometric division of ``total`` into ``n`` elements whose
    smallest element is ``first`` long: first Σ_k q^e_k = total (e_k = k, or for
    ``fine="both"`` min(k, n − 1 − k): fine at both ends), q in [1, limit] (1 when n
    elements of ``first`` already cover ``total``; ``limit`` when even that growth does
    not reach it — the smallest element is then longer than asked). :func:`graded` takes
    the ratio q^max(e_k)."""
    e = size_exponents(n, fine).astype(float)
    if e.max() == 0 or n * first >= total:
        return 1.0

    def covered(q: float) -> float:
        return first * float(np.sum(q ** e))

    if covered(limit) <= total:
        return limit
    lo, hi = 1.0, limit
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if covered(mid) < total else (lo, mid)
    return 0.5 * (lo + hi)


def at_index(table: np.ndarray, index) -> np.ndarray:
    """Interpolate a :func:`graded` table at a parameter (element index) ``index`` ∈ [0, n]
    (linear between the 2n + 1 entries, which is exact at vertices and midpoints)."""
    return np.interp(2.0 * np.asarray(index, dtype=float), np.arange(table.size), table)


@dataclass(frozen=True, eq=False)
class MappedMesh:
    """A structured hexahedral mesh mapped from its parameter space.

    Attributes
    ----------
    param : skfem.MeshHex — the mesh in parameter space (unit cells)
    mesh : skfem.MeshHex2 — the physical mesh: the same elements and facets, every
        quadratic node moved by the mapping [mm]
    param_nodes : ndarray (3, N) — parameter coordinates of ``mesh.doflocs``
    min_jacobian : float — [1] smallest ratio over the elements of the Jacobian
        determinant at a cell quadrature point to the element's mean (1 for a
        parallelepiped; a value near 0 flags a badly shaped element)
    """

    param: skfem.MeshHex
    mesh: skfem.MeshHex2
    param_nodes: np.ndarray
    min_jacobian: float

    def nodes_where(self, test: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:
        """Indices of the mesh nodes whose parameter coordinates (3, N) pass ``test``."""
        return np.flatnonzero(test(self.param_nodes))

    def facets_where(self, test: Callable[[np.ndarray], np.ndarray],
                     boundary: bool = True) -> np.ndarray:
        """Indices of the (boundary) facets whose parameter midpoints pass ``test``."""
        facets = self.param.boundary_facets() if boundary else np.arange(
            self.param.facets.shape[1])
        mid = self.param.p[:, self.param.facets[:, facets]].mean(axis=1)
        return facets[test(mid)]

    def elements_where(self, test: Callable[[np.ndarray], np.ndarray]) -> np.ndarray:
        """Indices of the elements whose parameter centres pass ``test``."""
        return np.flatnonzero(test(self.param.p[:, self.param.t].mean(axis=1)))


def mapped_mesh(shape: tuple[int, int, int], mapping: Callable[[np.ndarray], np.ndarray],
                keep: Callable[[np.ndarray], np.ndarray] | None = None) -> MappedMesh:
    """Build a mapped structured hexahedral mesh.

    Parameters
    ----------
    shape : (int, int, int) — [1] unit cells of the parameter box along its three axes
    mapping : callable — parameter coordinates (3, M) → physical coordinates (3, M) [mm];
        called once with every node (vertices and midpoints, i.e. parameter coordinates
        that are multiples of ½)
    keep : callable, optional — cell centres (3, C) → bool (C,): which cells of the box
        form the mesh (default all)

    Returns
    -------
    MappedMesh

    Raises
    ------
    InputError — a shape entry below 1.
    LTCAError — the mapping inverts an element or collapses one (a Jacobian determinant
        changes sign or vanishes at a quadrature point): the geometry cannot be meshed
        this way, e.g. a division too coarse for a curved boundary.
    """
    if len(shape) != 3 or min(shape) < 1:
        raise InputError(f"shape: must be three cell counts >= 1, got {shape!r}")
    box = skfem.MeshHex.init_tensor(*(np.arange(n + 1.0) for n in shape))
    if keep is not None:
        centres = box.p[:, box.t].mean(axis=1)
        drop = np.flatnonzero(~np.asarray(keep(centres), dtype=bool))
        if drop.size:
            box = box.remove_elements(drop).remove_unused_nodes()
    quad = skfem.MeshHex2.from_mesh(box)
    nodes = quad.doflocs.copy()
    phys = np.asarray(mapping(nodes), dtype=float)
    if phys.shape != nodes.shape or not np.all(np.isfinite(phys)):
        raise LTCAError("mesh mapping: returned non-finite or misshaped coordinates")
    mesh = dataclasses.replace(quad, doflocs=phys)
    # the Jacobian at CellBasis(mesh, ElementHex1(), intorder=2)'s points of every
    # element, without the basis (its global dofs and values: ~0.2 s, issue 75)
    quad_x, _ = get_quadrature(mesh.refdom, 2)
    det = mesh.mapping().detDF(quad_x)
    sign = np.sign(np.median(det))
    ratio = sign * det / np.abs(det).mean(axis=1, keepdims=True)
    worst = float(ratio.min())
    if worst <= 0.0:
        e = int(np.argmin(ratio.min(axis=1)))
        centre = box.p[:, box.t[:, e]].mean(axis=1)
        raise LTCAError(f"mesh mapping: element {e} (parameter centre {np.round(centre, 2)}) "
                        "is inverted or collapsed; refine the mesh or check the geometry")
    return MappedMesh(box, mesh, nodes, worst)


class FacetPoints(NamedTuple):
    """Quadrature points on F facets, Q per facet, evaluated on the physical mesh.

    tind : (F,) the element each facet belongs to (its inside); param, x : (3, F, Q) the
    points in parameter and physical coordinates [mm]; normal : (3, F, Q) the outward
    unit normal; dx : (F, Q) [mm²] area weights (quadrature weight × surface Jacobian);
    values : (nb, F, Q) and grads : (nb, 3, F, Q) [1/mm] (None where not asked for) of
    the element's basis functions;
    element_dofs : (nb, F) their global indices (the scalar basis's nodes).
    """

    tind: np.ndarray
    param: np.ndarray
    x: np.ndarray
    normal: np.ndarray
    dx: np.ndarray
    values: np.ndarray
    grads: np.ndarray
    element_dofs: np.ndarray


def facet_points(mapped: MappedMesh, element: skfem.Element, facets: np.ndarray,
                 order: int, *, grads: bool = True) -> FacetPoints:
    """Gauss points on boundary facets of a mapped mesh, with everything a load or a
    stress needs there.

    The points are laid on the parameter mesh (whose elements are unit cubes, so their
    reference coordinates come out exactly) and evaluated on the physical mesh at the same
    reference coordinates; the normal and the area follow by Nanson's formula
    n da = |det Φ| Φ⁻ᵀ N dA for the parameter-to-physical map Φ (N the outward normal of
    the parameter facet). (scikit-fem's FacetBasis
    inverts the curved physical elements by Newton's method instead, which can stall on
    the long, thin elements along a gear's face width.)

    Parameters
    ----------
    mapped : MappedMesh
    element : skfem.Element — the scalar element of the basis (e.g. ``ElementHexS2()``)
    facets : ndarray of int — boundary facets
    order : int — quadrature order (3: 2 × 2 Gauss points, 6: 4 × 4)
    grads : bool — the basis' gradients too (default); False: ``grads`` is None (the
        hat loads read only the values)

    Returns
    -------
    FacetPoints
    """
    # what scikit-fem's FacetBasis(mapped.param, ElementHex1(), facets=facets,
    # intorder=order) computes of the parameter mesh and this needs (its points, element,
    # outward normal and area weights), by the same calls of its mapping: the same numbers
    # to the bit, without its global dof locations over the whole mesh, its basis and two
    # more Newton inversions of the points (~0.1 s per call, 14 calls per FE build of the
    # default case, issue 75)
    param = mapped.param
    find = np.asarray(facets)
    tind = param.f2t[0, find]
    quad_x, quad_w = get_quadrature(param.brefdom, order)
    pmap = param.mapping()
    xp = pmap.G(quad_x, find=find)
    # the parameter elements are unit cubes: their map is affine, so Newton's first step
    # from the cube's centre (scikit-fem's invF starts there) is its inverse, and its
    # Jacobian is one matrix per element — taken at the centre once instead of at every
    # point in each of invF's iterations and the normals' (issue 75; the points agree
    # with invF's to round-off)
    half = np.full((3, 1), 0.5)
    jp_inv = _inverse3(pmap.DF(half, tind=tind))[0]  # (3, 3, F, 1)
    ref = np.clip(half[:, :, None] + np.einsum("ijfq,jfq->ifq", jp_inv,
                                                xp - pmap.F(half, tind=tind)), 0.0, 1.0)
    param_normal = _cube_normals(pmap, jp_inv, tind, find, param.t2f, xp.shape[-1])
    param_dx = np.abs(pmap.detDG(quad_x, find=find)) * np.broadcast_to(
        quad_w, (len(find), quad_w.shape[-1]))
    # the points, d(physical)/d(reference) (3, 3, F, Q) and the basis there, at once
    fields = basis_fields(mapped.mesh, element, ref, tind, grads=grads)
    x, jac = fields.x, fields.jac
    # d(physical)/d(parameter): jac times d(reference)/d(parameter); the 3 × 3 inverses
    # and determinants in closed form (LAPACK per point through numpy.linalg: ~0.05 s
    # per call on a flank's 16 points per facet, issue 75)
    phi = np.einsum("ikfq,kjfq->ijfq", jac, np.broadcast_to(jp_inv, jac.shape))
    phi_inv, det = _inverse3(phi)
    phi_inv_t = phi_inv.transpose(1, 0, 2, 3)
    # N outward in parameter space; a normal is a covector, n ∝ Φ⁻ᵀ N, and stays outward
    # (n·dx = N·dX for dx = Φ dX), whatever the sign of det Φ
    a = np.einsum("ijfq,jfq->ifq", phi_inv_t, param_normal)
    norm = np.linalg.norm(a, axis=0)
    normal = a / norm
    dx = np.abs(det) * norm * param_dx
    dofs = skfem.assembly.Dofs(mapped.mesh, element).element_dofs[:, tind]
    return FacetPoints(tind, xp, x, normal, dx, fields.values, fields.grads, dofs)


def _cube_normals(pmap, jp_inv: np.ndarray, tind: np.ndarray, find: np.ndarray,
                  t2f: np.ndarray, points: int) -> np.ndarray:
    """Outward unit normals (3, F, Q) of facets ``find`` of the parameter mesh's elements
    ``tind``: scikit-fem's ``MappingIsoparametric.normals`` with the element's inverse
    Jacobian ``jp_inv`` (3, 3, F, 1) of its affine map (the same at every point)."""
    n_ref = pmap.mesh.elem.refdom.normals
    normal = np.empty((3, len(find)))
    for itr in range(n_ref.shape[0]):
        ix = np.nonzero(t2f[itr, tind] == find)[0]
        normal[:, ix] = n_ref[itr][:, None]
    n = np.einsum("ijkl,ik->jkl", jp_inv, normal)
    n = n / np.sqrt(np.sum(n ** 2, axis=0))
    return np.broadcast_to(n, (3, len(find), points))


def _inverse3(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inverses (3, 3, ...) and determinants (...) of 3 × 3 matrices m (3, 3, ...), by the
    adjugate (Cramer's rule); the determinants must not vanish."""
    c00 = m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1]
    c01 = m[1, 2] * m[2, 0] - m[1, 0] * m[2, 2]
    c02 = m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]
    det = m[0, 0] * c00 + m[0, 1] * c01 + m[0, 2] * c02
    inv = np.empty_like(m)
    inv[0, 0], inv[1, 0], inv[2, 0] = c00, c01, c02
    inv[0, 1] = m[0, 2] * m[2, 1] - m[0, 1] * m[2, 2]
    inv[1, 1] = m[0, 0] * m[2, 2] - m[0, 2] * m[2, 0]
    inv[2, 1] = m[0, 1] * m[2, 0] - m[0, 0] * m[2, 1]
    inv[0, 2] = m[0, 1] * m[1, 2] - m[0, 2] * m[1, 1]
    inv[1, 2] = m[0, 2] * m[1, 0] - m[0, 0] * m[1, 2]
    inv[2, 2] = m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0]
    inv /= det
    return inv, det


class BasisFields(NamedTuple):
    """An H¹ element's basis and the isoparametric mapping at reference points of E
    elements, Q per element (:func:`basis_fields`)."""

    values: np.ndarray | None  # (nb, E, Q) [1] (None: not asked for)
    grads: np.ndarray | None  # (nb, 3, E, Q) [1/mm] (None: not asked for)
    det: np.ndarray  # (E, Q) [mm³] det of d(physical)/d(reference)
    x: np.ndarray  # (3, E, Q) [mm] the points
    jac: np.ndarray  # (3, 3, E, Q) [mm] d(physical)/d(reference)


def basis_fields(mesh: skfem.Mesh, element: skfem.Element, X: np.ndarray,
                 tind: np.ndarray | None = None, *, values: bool = True,
                 grads: bool = True) -> BasisFields:
    """Values and physical gradients of an H¹ element's basis functions, and the mapping
    (points, Jacobian and its determinant), at reference points of the elements of an
    isoparametric mesh.

    scikit-fem's own arithmetic (``MappingIsoparametric.F``/``DF``/``detDF``/``invDF``
    and ``ElementH1.gbasis``, as ``CellBasis`` runs them: the same sums in the same
    order, so the same numbers to the bit), with the mapping element's reference values
    and gradients and the inverse Jacobian computed once instead of once per basis
    function, coordinate and Jacobian entry (27 × 9 evaluations of the quadratic
    hexahedron's 27 gradients on the default models: most of an FE build's basis
    set-up, issue 75).

    Parameters
    ----------
    mesh : skfem.Mesh — isoparametric (e.g. ``skfem.MeshHex2``) [mm]
    element : skfem.Element — an H¹ element (``ElementH1``: identity transformation)
    X : ndarray (3, Q) — the same reference points in every element (a quadrature rule),
        or (3, E, Q) — points per element
    tind : ndarray (E,) of int, optional — the elements; None: all of the mesh's
    values, grads : bool — compute the basis' values, its gradients (default both); a
        field not computed is None in the result (the stiffness reads no values, the hat
        loads no gradients: 82 and 245 MB not written on the default pinion model,
        issue 75)

    Returns
    -------
    BasisFields

    Raises
    ------
    ValueError — a zero Jacobian determinant (a collapsed element).
    """
    t = mesh.dofs.element_dofs  # the mapping's nodes of each element
    p = mesh.doflocs
    mapel = mesh.mapping().elem
    local = [mapel.lbasis(X, m) for m in range(t.shape[0])]  # (phi, dphi) of each node
    dphi = [d for _, d in local]
    ne = t.shape[1] if tind is None else len(tind)
    nodes = [t[m, :] if tind is None else t[m, tind] for m in range(t.shape[0])]
    x = np.empty((3, ne, X.shape[-1]))
    for i in range(3):
        out = np.zeros((ne, X.shape[-1]))
        for m in range(t.shape[0]):
            out += p[i, nodes[m]][:, None] * local[m][0]
        x[i] = out
    del local
    jac = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            out = np.zeros((ne, X.shape[-1]))
            for m in range(t.shape[0]):
                out += p[i, nodes[m]][:, None] * dphi[m][j]
            jac[i][j] = out
    J = jac
    det = (J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]))
    if np.any(det == 0):
        raise ValueError("zero Jacobian determinant")
    inv = np.empty((3, 3, *J[0][0].shape))
    inv[0, 0] = -J[1][2] * J[2][1] + J[1][1] * J[2][2]
    inv[1, 0] = J[1][2] * J[2][0] - J[1][0] * J[2][2]
    inv[2, 0] = -J[1][1] * J[2][0] + J[1][0] * J[2][1]
    inv[0, 1] = J[0][2] * J[2][1] - J[0][1] * J[2][2]
    inv[1, 1] = -J[0][2] * J[2][0] + J[0][0] * J[2][2]
    inv[2, 1] = J[0][1] * J[2][0] - J[0][0] * J[2][1]
    inv[0, 2] = -J[0][2] * J[1][1] + J[0][1] * J[1][2]
    inv[1, 2] = J[0][2] * J[1][0] - J[0][0] * J[1][2]
    inv[2, 2] = -J[0][1] * J[1][0] + J[0][0] * J[1][1]
    inv = inv / det
    jac = np.array(J)
    del J
    rule = "ijkl,il->jkl" if X.ndim == 2 else "ijkl,ikl->jkl"
    nb = len(element.doflocs)  # one basis function per node (scalar H¹ elements)
    value_out = np.empty((nb, ne, X.shape[-1])) if values else None
    grad_out = np.empty((nb, 3, ne, X.shape[-1])) if grads else None
    for j in range(nb if values or grads else 0):
        phi, dphi_j = element.lbasis(X, j)
        if values:
            value_out[j] = np.broadcast_to(phi, (ne, X.shape[-1]))
        if grads:
            grad_out[j] = np.einsum(rule, inv, dphi_j)
    return BasisFields(value_out, grad_out, det, x, jac)
