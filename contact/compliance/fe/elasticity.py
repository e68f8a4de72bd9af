"""Linear elasticity on a mapped hexahedral mesh: stiffness, loads, stresses, direct solvers.

The stiffness matrix K of isotropic linear elasticity, a(u, w) = ∫ σ(u) : ε(w) dV with
σ = λ tr(ε) I + 2 μ ε, is assembled element by element from scikit-fem's quadratic
hexahedral bases (shape-function gradients and quadrature weights on the mapped
elements, 3 × 3 × 3 Gauss points: exact for the parallelepiped and the standard full
integration of quadratic hexahedra) and one vectorised contraction per block of elements
(the general scikit-fem assembler loops over the 81 × 81 basis pairs in Python and is
some ten times slower for these elements). Degree of freedom 3 n + c is the component c
(x, y, z) of the displacement at node n of the scalar basis.

The solution K u = f is by a sparse direct factorisation, factorised once and applied to
many right-hand sides, chosen from :data:`SOLVERS`: CHOLMOD's supernodal Cholesky
(SuiteSparse, through cvxopt, a required dependency with wheels for every platform: the
default, issue 53), Intel MKL PARDISO through pypardiso where installed (the optional
extra ``fe``, x86-64 only), or SuperLU through scipy (a general LU, ~15× CHOLMOD's time on
these matrices; kept as the reference).

Public names
------------
ElasticModel        the basis, the stiffness matrix and the material of a mesh
elastic_model       assemble it
SOLVERS             solver name → whether it is installed here
Factorisation       a factorised matrix: solve many right-hand sides
factorise           factorise the stiffness matrix with its constrained dofs removed
resolve_solver      the solver "auto" (or a name) stands for here
lattice_dissection  nested dissection of a structured mesh's node lattice for CHOLMOD (the
                    influence build's ordering)
                    (not used by the build since the lattice's: as good, no dependency)
stress_operator     sparse map from displacements to stress components at points
worker_session      keep CHOLMOD's solver worker between factorisations (a pair's members)
"""

from __future__ import annotations

import contextlib
import gc
import importlib.util
import logging
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
import skfem
from skfem.quadrature import get_quadrature

from contact.compliance.fe.cholmod_dense import cholmod_kernel
from contact.compliance.fe.mapped_mesh import basis_fields
from contact.compliance.fe.options import ELEMENTS
from contact.compliance.fe.worker_cpu import register_worker
from geometry.core.errors import InputError, LTCAError, ModelUnavailableError
from geometry.core.validation import one_of, positive, real

__all__ = [
    "SOLVERS",
    "DofMap",
    "ElasticModel",
    "Factorisation",
    "elastic_model",
    "factorise",
    "isolation_available",
    "lame",
    "lattice_dissection",
    "resolve_solver",
    "stress_operator",
    "worker_session",
]

log = logging.getLogger(__name__)

_BLOCK = 32  # elements per block of the stiffness contraction (in the CPU's cache: 32 × 81² × 8 B)
#: elements whose basis gradients are evaluated at once for the stiffness (31 MB on the
#: quadratic hexahedra; all of them at once took 181 MB on the default pinion model)
_FIELDS_BLOCK = 32 * _BLOCK
_VOIGT = ((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))  # xx, yy, zz, yz, xz, xy


def lame(youngs_modulus: float, poisson_ratio: float) -> tuple[float, float]:
    """Lamé constants λ, μ [MPa] of E [MPa] and ν [1] (isotropic linear elasticity)."""
    e = positive("youngs_modulus", youngs_modulus, "MPa")
    nu = real("poisson_ratio", poisson_ratio, unit="1", low=0.0, high=0.5, high_open=True)
    return e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))


class DofMap(NamedTuple):
    """The dof numbering of a scalar basis, without its quadrature data.

    N : int — scalar dofs (the nodes); element_dofs : ndarray (nb, E) — each element's
    scalar dofs (as ``skfem.CellBasis.element_dofs``)
    """

    N: int
    element_dofs: np.ndarray


@dataclass(frozen=True, eq=False)
class ElasticModel:
    """Stiffness of a mesh.

    Attributes
    ----------
    basis : DofMap — the scalar quadratic basis's numbering (its dofs are the nodes); the
        basis's values and gradients at every quadrature point are released once K is
        assembled (~100 MB on the default pinion model, measured; issue 62 item 6)
    stiffness : scipy.sparse.csr_matrix (3N, 3N) or None — K [N/mm], or its lower
        triangle where assembled with ``lower=True`` (what CHOLMOD reads); None in a model
        whose stiffness was handed to its factorisation and released (the influence
        coefficients' build: its memory is the factor's, issue 53)
    youngs_modulus, poisson_ratio : float — [MPa], [1]
    assemble_time : float — [s]
    """

    basis: DofMap
    stiffness: sp.csr_matrix | None
    youngs_modulus: float
    poisson_ratio: float
    assemble_time: float

    @property
    def n_dofs(self) -> int:
        """Unknowns of the unconstrained problem, 3 × nodes."""
        return 3 * int(self.basis.N)

    def element_dofs(self, elements: np.ndarray) -> np.ndarray:
        """(E, 3 nb) vector dofs of ``elements``, node-major (3 n + c)."""
        nodes = self.basis.element_dofs[:, elements].T
        return (3 * nodes[:, :, None] + np.arange(3)).reshape(len(elements), -1)


def elastic_model(mesh: skfem.MeshHex2, element: str, youngs_modulus: float,
                  poisson_ratio: float, *, lower: bool = False) -> ElasticModel:
    """Assemble the stiffness matrix of isotropic linear elasticity.

    Parameters
    ----------
    mesh : skfem.MeshHex2 — the mapped mesh [mm]
    element : str — a key of :data:`contact.compliance.fe.options.ELEMENTS`
    youngs_modulus : float — [MPa]
    poisson_ratio : float — [1]
    lower : bool — assemble K's lower triangle only (row ≥ column), all CHOLMOD reads:
        half the memory of K (issue 75). The whole K (``lower=False``) is that lower
        triangle completed by its transpose: exactly symmetric, and its lower triangle
        is the ``lower=True`` matrix to the bit.

    Returns
    -------
    ElasticModel

    Raises
    ------
    InputError — an unknown element or material constants out of range.

    Notes
    -----
    K_e[a i, b j] = Σ_q w_q (λ ∂_i N_a ∂_j N_b + μ ∂_j N_a ∂_i N_b + μ δ_ij ∇N_a·∇N_b)
    (the Galerkin form of Navier's equations, e.g. Hughes, The Finite Element Method,
    2000, §2.7): per pair of element nodes a, b the 3 × 3 block λ G + μ Gᵀ + μ tr(G) I
    with G_ij = Σ_q w_q ∂_i N_a ∂_j N_b. K is summed by node pairs (issue 75, fourth
    round): the mesh's pairs of coupled nodes with node(a) ≥ node(b) are numbered once
    (K's pattern of 3 × 3 blocks, each block's place in the CSR arrays known), and each
    element's blocks of those pairs are added at their places (``numpy.add.at``, block
    by block of elements) — no sparse matrix per block of elements, no pairwise sums
    (2.5 → ~1 s on the default pinion model; K within round-off of the element-block
    sums, 2e-16 of its largest entry). Tested against scikit-fem's own assembly of the
    same form (tests/test_fe_dense_solve.py) and beam theory (tests/test_fe_tooth.py).
    """
    one_of("element", element, ELEMENTS)
    lam, mu = lame(youngs_modulus, poisson_ratio)
    t0 = time.perf_counter()
    elem = ELEMENTS[element][0]()
    # CellBasis(mesh, elem, intorder=4)'s gradients and area weights, each evaluated
    # once (mapped_mesh.basis_fields: the same numbers, a fraction of the time, issue 75)
    X, W = get_quadrature(mesh.refdom, 4)
    dofs = skfem.assembly.Dofs(mesh, elem)
    dofmap = DofMap(int(dofs.N), dofs.element_dofs)
    pattern = _node_pairs(dofmap)
    n = 3 * dofmap.N
    ne, nq = mesh.nelements, X.shape[-1]
    data = np.zeros(pattern.nnz + 1)  # the last: where the diagonal blocks' upper go
    grads = dx = None
    for lo in range(0, ne, _BLOCK):
        hi = min(lo + _BLOCK, ne)
        if lo % _FIELDS_BLOCK == 0:  # the gradients of the next elements (no values)
            top = min(lo + _FIELDS_BLOCK, ne)
            fields = basis_fields(mesh, elem, X, np.arange(lo, top), values=False)
            grads, dx = fields.grads, np.abs(fields.det) * W  # (nb, 3, e, Q), (e, Q)
            nb, first = grads.shape[0], lo
            del fields
        g = grads[:, :, lo - first:hi - first].transpose(2, 0, 1, 3).reshape(
            hi - lo, 3 * nb, nq)
        gg = np.matmul(g * dx[lo - first:hi - first, None, :],
                       g.transpose(0, 2, 1))  # (e, a i, b j)
        # the blocks G of the element's node pairs kept (node(a) ≥ node(b)), (M, 3, 3)
        big_g = gg.reshape(hi - lo, nb, 3, nb, 3).transpose(0, 1, 3, 2, 4)[
            pattern.kept[lo:hi]]
        del gg, g
        ke = lam * big_g
        ke += mu * big_g.transpose(0, 2, 1)
        trace = mu * (big_g[:, 0, 0] + big_g[:, 1, 1] + big_g[:, 2, 2])
        for i in range(3):
            ke[:, i, i] += trace
        del big_g
        # added at their places in K's CSR data, in the order of the elements (NumPy's
        # unbuffered add: a deterministic sum, no array of K's size per block)
        np.add.at(data, pattern.place[pattern.pair[pattern.start[lo]:pattern.start[hi]]
                                      ].ravel(), ke.ravel())
        del ke
    del grads, dx  # the quadrature data: only the numbering is needed from here on
    k = sp.csr_matrix((data[:-1], pattern.indices, pattern.indptr), shape=(n, n))
    k.has_sorted_indices = True
    del data
    if not k.data.all():  # entries summed to exactly zero: not stored (as sparse sums do)
        k.eliminate_zeros()
    if not lower:  # the strict lower triangle mirrored: exactly symmetric
        k = (k + sp.tril(k, -1, format="csr").T).tocsr()
        k.sort_indices()
    elapsed = time.perf_counter() - t0
    log.info("stiffness: %d elements (%s), %d dofs, %d non-zeros, %.1f s", ne, element, n,
             k.nnz, elapsed)
    return ElasticModel(dofmap, k, float(youngs_modulus), float(poisson_ratio), elapsed)


class _NodePairs(NamedTuple):
    """K's lower triangle as 3 × 3 blocks of node pairs (:func:`_node_pairs`)."""

    kept: np.ndarray  # (E, nb, nb) bool: the element's node pairs a, b with node(a) ≥ node(b)
    start: np.ndarray  # (E + 1,) int: each element's first kept pair in ``pair``
    pair: np.ndarray  # (M,) int: the block (of K's pattern) of each kept pair, element-major
    place: np.ndarray  # (blocks, 9) int: the CSR place of each block's entry (i, j); the
    #                    diagonal blocks' upper entries (j > i) at ``nnz`` (discarded)
    indptr: np.ndarray  # (3N + 1,) the lower triangle's CSR arrays
    indices: np.ndarray  # (nnz,)
    nnz: int


def _node_pairs(dofmap: DofMap) -> _NodePairs:
    """The pattern of K's lower triangle by node pairs: which pairs of each element's nodes
    it holds, the block of each, and where each block's 9 entries lie in the CSR arrays
    (rows 3 A + i, columns 3 B + j ≤ row: the blocks of node A's pairs B ≤ A in the order
    of B, the diagonal block's lower part last)."""
    en = dofmap.element_dofs.T.astype(np.int64)  # (E, nb)
    n_nodes = int(dofmap.N)
    kept = en[:, :, None] >= en[:, None, :]
    start = np.zeros(en.shape[0] + 1, dtype=np.int64)
    np.cumsum(kept.reshape(en.shape[0], -1).sum(axis=1), out=start[1:])
    keys = (en[:, :, None] * n_nodes + en[:, None, :])[kept]
    blocks, pair = np.unique(keys, return_inverse=True)
    del keys
    row = blocks // n_nodes
    col = blocks - row * n_nodes
    first = np.searchsorted(row, np.arange(n_nodes + 1))  # each node row's first block
    count = np.diff(first)
    # row 3 A + i holds 3 (count_A − 1) + i + 1 entries: the off-diagonal blocks' three
    # columns each, then the diagonal block's j ≤ i
    lengths = 3 * (count[:, None] - 1) + np.arange(1, 4)[None, :]
    indptr = np.zeros(3 * n_nodes + 1, dtype=np.int64)
    np.cumsum(lengths.ravel(), out=indptr[1:])
    nnz = int(indptr[-1])
    # the places and columns in 32 bits where they fit (half the memory written: the
    # pinion's 742 k blocks × 9 and 6.6 M columns, issue 75)
    index = np.int32 if 3 * n_nodes < 2**31 and nnz < 2**31 else np.int64
    rank = (np.arange(blocks.size) - first[row]).astype(index)  # rank in its node row
    place = (indptr[:-1].astype(index).reshape(n_nodes, 3)[row] + 3 * rank[:, None])[
        :, :, None] + np.arange(3, dtype=index)[None, None, :]  # (blocks, i, j)
    upper = np.triu(np.ones((3, 3), dtype=bool), 1)
    diagonal = row == col
    place[diagonal] = np.where(upper, nnz, place[diagonal])
    place = place.reshape(-1, 9)
    indices = np.empty(nnz + 1, dtype=index)
    indices[place.ravel()] = (3 * col.astype(index)[:, None]
                              + np.tile(np.arange(3, dtype=index), 3)[None, :]).ravel()
    return _NodePairs(kept, start, pair, place, indptr.astype(index), indices[:nnz], nnz)


def stress_operator(model: ElasticModel, grads: np.ndarray, elements: np.ndarray) -> sp.csr_matrix:
    """Sparse map S (6P, 3N) from the displacements to stresses at P points.

    Parameters
    ----------
    model : ElasticModel
    grads : ndarray (nb, 3, P) — [1/mm] physical gradients of the element's basis
        functions at each point
    elements : ndarray (P,) — the element holding each point

    Returns
    -------
    scipy.sparse.csr_matrix — row 6 p + k is stress component k (Voigt order xx, yy,
        zz, yz, xz, xy) [MPa per mm of displacement] at point p.

    Notes
    -----
    σ_ij = λ δ_ij ε_kk + 2 μ ε_ij with ε = ½(∇u + ∇uᵀ), u = Σ_a N_a u_a.
    """
    lam, mu = lame(model.youngs_modulus, model.poisson_ratio)
    nb, _, npt = grads.shape
    dofs = model.element_dofs(np.asarray(elements))  # (P, 3 nb), node-major
    # coefficient of u_{a c} in σ_ij: λ δ_ij ∂_c N_a + μ (δ_ic ∂_j N_a + δ_jc ∂_i N_a)
    coef = np.zeros((npt, 6, nb, 3))
    g = grads.transpose(2, 0, 1)  # (P, nb, 3)
    for k, (i, j) in enumerate(_VOIGT):
        if i == j:
            coef[:, k] += lam * g
        coef[:, k, :, i] += mu * g[:, :, j]
        coef[:, k, :, j] += mu * g[:, :, i]
    coef = coef.reshape(npt, 6, 3 * nb)
    rows = (6 * np.arange(npt)[:, None, None] + np.arange(6)[None, :, None]) \
        + np.zeros((1, 1, 3 * nb), dtype=int)
    cols = np.broadcast_to(dofs[:, None, :], coef.shape)
    return sp.csr_matrix((coef.ravel(), (rows.ravel(), cols.ravel())),
                         shape=(6 * npt, model.n_dofs))


# --------------------------------------------------------------------------- solvers
def _pardiso_installed() -> bool:
    return importlib.util.find_spec("pypardiso") is not None


def _cholmod_installed() -> bool:
    return importlib.util.find_spec("cvxopt") is not None


#: solver name → a test whether it is installed here ("auto": the first installed of
#: CHOLMOD, PARDISO, SuperLU)
SOLVERS: dict[str, Callable[[], bool]] = {
    "cholmod": _cholmod_installed,
    "pardiso": _pardiso_installed,
    "superlu": lambda: True,
}

@dataclass(eq=False)
class Factorisation:
    """A factorised constrained stiffness matrix K_ff.

    Attributes
    ----------
    solver : str — which solver factorised it
    free : ndarray (F,) — the unconstrained dofs, in the order of K_ff
    n_dofs : int — all dofs (3 × nodes)
    factor_nnz : int — non-zeros of the factors (memory ≈ 12 bytes each); -1 where the
        solver does not report them (CHOLMOD through cvxopt)
    factor_time : float — [s]
    isolated : bool — the factor lives in a worker process (:func:`factorise`)
    """

    solver: str
    free: np.ndarray
    n_dofs: int
    factor_nnz: int
    factor_time: float
    _solve: Callable[[np.ndarray], np.ndarray]
    isolated: bool = False
    _close: Callable[[], None] | None = None
    _shared: _LeanWorker | None = None  # the worker, where its blocks are shared memory

    def close(self) -> None:
        """End the worker process that holds an isolated factor (nothing otherwise); the
        factorisation cannot solve afterwards."""
        if self._close is not None:
            self._close()
            self._close = None
        self._shared = None

    def rhs_block(self, k: int) -> np.ndarray:
        """An array (F, k) [float64, Fortran order] for ``k`` right-hand sides on the
        free dofs, to be solved by :meth:`solve_free`: the solver worker's shared block
        where it has one and ``k`` ≤ :data:`PIPE_BLOCK` (the loads are then neither
        copied nor sent, issue 75), else a new array."""
        block = self._shared.rhs_block(k) if self._shared is not None else None
        return block if block is not None else np.empty((self.free.size, k), order="F")

    def solve_free(self, b: np.ndarray) -> np.ndarray:
        """Displacements of the free dofs (F, k) [mm] for loads ``b`` (F, k) [N] on the
        free dofs (in the order of :attr:`free`). Where ``b`` is the :meth:`rhs_block`
        of the worker's shared memory, it is solved in place and the result is a view of
        the shared solutions (Fortran order), valid until the next solve: use or copy it
        before."""
        if self._shared is not None and self._shared.shared is not None:
            rhs = self._shared.shared.rhs
            if (b.ndim == 2 and b.shape[0] == rhs.shape[0] and b.shape[1] <= rhs.shape[1]
                    and b.__array_interface__["data"][0] == rhs.__array_interface__["data"][0]
                    and b.flags.f_contiguous):
                return self._shared.solve_shared(b.shape[1])
        return self._solve(np.asfortranarray(b, dtype=float) if b.ndim == 2 and b.shape[1] > 1
                           else np.asarray(b, dtype=float))

    def solve(self, rhs: np.ndarray | sp.spmatrix) -> np.ndarray:
        """Displacements (3N, k) [mm] for loads ``rhs`` (3N, k) or (3N,) [N], dense or
        sparse (3N, k) (the unit loads: their free rows made dense at once, in the
        Fortran order the solver takes, issue 75); the constrained dofs are zero and
        their loads ignored (reactions)."""
        if sp.issparse(rhs):
            b_free = sp.csr_matrix(rhs)[self.free].toarray(order="F").astype(float,
                                                                             copy=False)
            out = np.zeros((self.n_dofs, b_free.shape[1]))
            out[self.free] = self._solve(b_free if b_free.shape[1] > 1 else
                                         np.ascontiguousarray(b_free))
            return out
        b = np.asarray(rhs, dtype=float)
        vec = b.ndim == 1
        b2 = b[:, None] if vec else b
        out = np.zeros((self.n_dofs, b2.shape[1]))
        # the free rows in Fortran order (CHOLMOD's dense blocks: column after column),
        # one copy (the worker neither transposes them nor its solutions back, issue 75)
        out[self.free] = self._solve(np.asfortranarray(b2[self.free]) if b2.shape[1] > 1
                                     else b2[self.free])
        return out[:, 0] if vec else out


def _superlu(box: list):
    a = box.pop()
    lu = spla.splu(a, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                   options={"SymmetricMode": True})
    return lu.solve, int(lu.L.nnz + lu.U.nnz)


def _cholmod(box: list):
    """CHOLMOD's factor of the lower triangle given (CSC, with its ordering or None: the
    one item of ``box``, taken out so that its memory is freed once copied):
    :func:`contact.compliance.fe.cholmod_dense.cholmod_kernel` on its arrays."""
    low, ordering = box.pop()
    arrays = [(low.data, low.indices, low.indptr, low.shape[0], ordering)]
    del low
    return cholmod_kernel(arrays)


def _pardiso(box: list):
    import pypardiso

    a = box.pop()
    solver = pypardiso.PyPardisoSolver(mtype=2)  # real symmetric positive definite
    upper = sp.triu(a, format="csr")
    upper.sort_indices()
    solver.factorize(upper)
    nnz = int(solver.get_iparm(18)) if hasattr(solver, "get_iparm") else upper.nnz

    def solve(b: np.ndarray) -> np.ndarray:
        return np.asarray(solver.solve(upper, b)).reshape(b.shape)

    return solve, nnz


# ------------------------------------------------------------ the factor in a worker process
#: [s] how often a process waiting for its solver worker looks at it (and lets a signal
#: handler run: a SIGTERM or Ctrl-C is honoured within this, not after the native call)
WORKER_POLL = 0.1

#: right-hand sides sent to a solver worker at once (0.63 MB each on the default pinion
#: model; the copies of a piece on its way through the pipe are the worker's transient
#: memory): CHOLMOD's dense block solve takes them all in one pass over the factor
PIPE_BLOCK = 64

_PENDING: list = []  # the matrix handed to a forked worker (read by it, cleared here)
_SIGNALS = {signal.SIGINT, signal.SIGTERM}


def _serve(kernel: Callable[[list], tuple], conn) -> None:
    """The forked worker: factorise the pending matrix with ``kernel``, report ``("ready",
    nnz, seconds)`` or ``("error", exception)``, then solve each block of right-hand sides
    it receives until ``None`` or the end of the pipe
    (:func:`contact.compliance.fe.solver_worker.serve`, the lean worker's loop too)."""
    from contact.compliance.fe.solver_worker import serve, set_parent_death_signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)   # the parent decides; it kills this
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # at once, even inside native code
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _SIGNALS)  # blocked by the parent's fork
    set_parent_death_signal()
    # a collection would touch every object inherited from the parent and copy their
    # pages (copy-on-write); the worker makes few objects of its own
    gc.disable()
    serve(conn, kernel, [_PENDING.pop()])


class _Worker:
    """A forked process holding a factor: :meth:`call` waits for its answers in short
    polls, so that a signal handler of the waiting (main) thread runs within
    :data:`WORKER_POLL`; any exception while waiting (KeyboardInterrupt from SIGINT or the
    CLI's SIGTERM handler among them) kills the worker first."""

    def __init__(self, kernel: Callable[[list], tuple], box: list) -> None:
        import multiprocessing

        ctx = multiprocessing.get_context("fork")
        self.conn, child = ctx.Pipe()
        self.busy = False
        _PENDING.append(box.pop())
        # no signal handler may run between the fork and knowing the worker (it would be
        # left factorising with this process's handlers): both blocked until then
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, _SIGNALS)
        try:
            self.proc = ctx.Process(target=_serve, args=(kernel, child), daemon=True,
                                    name="fe-factor")
            self.proc.start()
            register_worker(self.proc)
        finally:
            _PENDING.clear()  # this process's reference: the worker holds its own copy
            child.close()
            try:
                signal.pthread_sigmask(signal.SIG_SETMASK, mask)  # a pending one runs now
            except BaseException:
                self.kill()
                raise

    def receive(self):
        """The worker's next message; raises what it reports, LTCAError if it died."""
        self.busy = True
        try:
            while not self.conn.poll(WORKER_POLL):
                if not self.proc.is_alive():
                    raise LTCAError(f"FE solver worker ended unexpectedly (exit code "
                                    f"{self.proc.exitcode})")
            msg = self.conn.recv()
        except BaseException:
            self.kill()
            raise
        self.busy = False
        if msg[0] == "error":
            self.kill()
            raise msg[1]
        return msg

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Solutions of right-hand sides ``b`` (F, k), sent in pieces of at most
        :data:`PIPE_BLOCK` columns, each as a header and its raw bytes both ways
        (:func:`contact.compliance.fe.solver_worker.send_array`: no pickle copies)."""
        from contact.compliance.fe.solver_worker import recv_array, send_array

        out = np.empty(b.shape, dtype=np.float64, order="F")
        for start in range(0, b.shape[1], PIPE_BLOCK):
            piece = b[:, start:start + PIPE_BLOCK]
            self.busy = True
            try:  # a header and the raw bytes, not pickled (solver_worker.send_array)
                send_array(self.conn, "block", piece)
            except BaseException:
                self.kill()
                raise
            del piece
            header = self.receive()
            self.busy = True
            try:
                part = out[:, start:start + PIPE_BLOCK]
                if len(header) > 3 and header[3] == "F" and part.flags.f_contiguous:
                    recv_array(self.conn, header, out=part)  # straight into its columns
                else:
                    part[...] = recv_array(self.conn, header)
            except BaseException:
                self.kill()
                raise
            self.busy = False
        return out

    def close(self) -> None:
        """Ask an idle worker to end, then make sure it did (one still at work, e.g. when
        an exception ends the build, is killed at once)."""
        if self.proc.is_alive() and not self.busy:
            try:
                self.conn.send(None)
            except OSError:
                pass
            self.proc.join(5.0)
        self.kill()

    def kill(self) -> None:
        if self.proc.is_alive():
            self.proc.kill()
        self.proc.join()
        self.conn.close()


class _Child:
    """A :class:`subprocess.Popen` seen as the :class:`multiprocessing.Process` that
    :class:`_Worker` waits for."""

    def __init__(self, popen: subprocess.Popen) -> None:
        self.popen = popen
        self.pid = popen.pid
        register_worker(self)  # its CPU in the development's clock (worker_cpu)

    def is_alive(self) -> bool:
        return self.popen.poll() is None

    @property
    def exitcode(self) -> int | None:
        return self.popen.returncode

    def kill(self) -> None:
        self.popen.kill()

    def join(self, timeout: float | None = None) -> None:
        try:
            self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            pass


class _LeanWorker(_Worker):
    """CHOLMOD's factor in a new interpreter that imports NumPy and cvxopt only
    (:mod:`contact.compliance.fe.solver_worker`): a forked worker's resident set would
    start with all of this process's pages (~300 MB at the default model's
    factorisation), to which the factor adds its own (issue 75). The matrix goes through
    the connection (its lower triangle, ~70 MB on the default pinion model); waiting,
    signals and the end are :class:`_Worker`'s."""

    def __init__(self, box: list) -> None:
        import socket
        from multiprocessing.connection import Connection

        ours, theirs = socket.socketpair()
        self.conn = Connection(ours.detach())
        self.busy = False
        fd = theirs.detach()
        low, ordering = box.pop()
        self.shared = _shared_blocks(low.shape[0])
        script = str(Path(__file__).resolve().with_name("solver_worker.py"))
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, _SIGNALS)  # as _Worker: known
        try:                                                       # before any handler
            self.proc = _Child(subprocess.Popen(
                [sys.executable, script, str(fd), *sys.argv],
                pass_fds=(fd,) if self.shared is None else (fd, self.shared.fd),
                stdin=subprocess.DEVNULL,
                # its NumPy arrays on ordinary pages (influence._small_pages: no compaction
                # for huge pages at each fault)
                env={**os.environ, "NUMPY_MADVISE_HUGEPAGE": "0"}))
        finally:
            os.close(fd)
            try:
                signal.pthread_sigmask(signal.SIG_SETMASK, mask)
            except BaseException:
                self.kill()
                raise
        self._send_matrix(low, ordering)

    def _send_matrix(self, low: sp.csc_matrix, ordering: np.ndarray | None) -> None:
        """Hand the worker a matrix to factorise (its answer: :meth:`receive`)."""
        self.busy = True
        try:  # the arrays as raw bytes, not pickled: no copy of the matrix on either side
            from contact.compliance.fe.solver_worker import send_array

            self.conn.send(("cholmod-raw", low.shape[0], ordering is not None) + (
                () if self.shared is None else (self.shared.fd, self.shared.columns)))
            for array in (low.data, low.indices, low.indptr) + (
                    (ordering,) if ordering is not None else ()):
                send_array(self.conn, "array", array)
        except BaseException:
            self.kill()
            raise

    def load(self, box: list) -> None:
        """Hand this worker, released (:meth:`release`), the next matrix of ``box`` (taken
        out): the shared blocks resized to its rows (the worker maps them again)."""
        low, ordering = box.pop()
        if self.shared is not None and self.shared.rows != low.shape[0]:
            from contact.compliance.fe.solver_worker import SharedBlocks

            fd = self.shared.fd
            self.shared.close()
            self.shared = SharedBlocks(fd, low.shape[0], PIPE_BLOCK, create=True)
        self._send_matrix(low, ordering)

    def release(self) -> bool:
        """Free the worker's factor and keep the process for another matrix
        (:meth:`load`): True where it answered so, else (busy, ended, an error) it is
        ended and False."""
        if not self.proc.is_alive() or self.busy:
            self.close()
            return False
        try:
            self.conn.send(("release",))
            answer = self.receive()
        except Exception:  # ended by receive
            return False
        if answer[:1] != ("released",):
            self.kill()
            return False
        return True

    def rhs_block(self, k: int) -> np.ndarray | None:
        """The shared block for ``k`` ≤ :data:`PIPE_BLOCK` right-hand sides, (F, k) in
        Fortran order (write them there, then :meth:`solve_shared`), or None without
        shared blocks."""
        if self.shared is None or k > self.shared.columns:
            return None
        return self.shared.rhs[:, :k]

    def solve_shared(self, k: int) -> np.ndarray:
        """Solutions (F, k), Fortran order, of the right-hand sides written to
        :meth:`rhs_block` ``(k)``: a view of the shared solutions' block, valid until the
        next solve."""
        self.busy = True
        try:
            self.conn.send(("shared", k))
        except BaseException:
            self.kill()
            raise
        header = self.receive()
        if header[:2] != ("shared-ok", k):
            self.kill()
            raise LTCAError(f"FE solver worker: unexpected answer {header[:2]!r}")
        return self.shared.solution[:, :k]

    def solve(self, b: np.ndarray) -> np.ndarray:
        """As :meth:`_Worker.solve`; through the shared blocks where there are."""
        if self.shared is None:
            return super().solve(b)
        out = np.empty(b.shape, dtype=np.float64, order="F")
        for start in range(0, b.shape[1], self.shared.columns):
            k = min(self.shared.columns, b.shape[1] - start)
            self.shared.rhs[:, :k] = b[:, start:start + k]
            out[:, start:start + k] = self.solve_shared(k)
        return out

    def kill(self) -> None:
        super().kill()
        if getattr(self, "shared", None) is not None:
            self.shared.close()
            os.close(self.shared.fd)
            self.shared = None


def _shared_blocks(rows: int):
    """Two shared blocks of ``rows`` × :data:`PIPE_BLOCK` float64 for the lean worker
    (:class:`contact.compliance.fe.solver_worker.SharedBlocks` on a ``memfd_create``
    file), or None where the platform has no such file or it cannot be made (then the
    blocks go through the connection, as before)."""
    if not hasattr(os, "memfd_create"):
        return None
    from contact.compliance.fe.solver_worker import SharedBlocks

    try:
        fd = os.memfd_create("hypoid-ltca-fe-blocks", os.MFD_CLOEXEC)
    except OSError:
        return None
    try:
        return SharedBlocks(fd, rows, PIPE_BLOCK, create=True)
    except (OSError, ValueError):
        os.close(fd)
        return None


def lean_worker_available() -> bool:
    """Whether CHOLMOD's factor can live in a new lean interpreter here (POSIX: the
    connection's descriptor is passed to it), :class:`_LeanWorker`."""
    return os.name == "posix"


#: the open sessions of :func:`worker_session`, innermost last: each a list holding its
#: idle lean worker (or nothing)
_SESSIONS: list[list] = []


@contextlib.contextmanager
def worker_session():
    """Within the block, CHOLMOD's lean solver worker is kept between factorisations: a
    :class:`Factorisation` closed hands its worker back (its factor freed) and the next
    isolated factorisation uses it — the FE builds of a pair's two members in one worker
    process, without a second interpreter start and its imports (~0.35 s of CPU) and
    with the second factor on the pages the first one had (issue 75). The worker left
    idle at the end of the block is ended. Nested sessions share the outermost's worker.
    Nothing changes for the forked workers of the other solvers."""
    holder: list = []
    _SESSIONS.append(holder)
    try:
        yield
    finally:
        _SESSIONS.remove(holder)
        while holder:
            worker = holder.pop()
            if _SESSIONS:  # an outer session takes it over
                _SESSIONS[0].append(worker)
            else:
                worker.close()


def _session_worker(box: list) -> _LeanWorker:
    """A lean worker given the matrix of ``box``: the session's idle one where there is
    one alive (:func:`worker_session`), else a new one."""
    holder = _SESSIONS[0] if _SESSIONS else []
    while holder:
        worker = holder.pop()
        if worker.proc.is_alive():
            worker.load(box)
            return worker
        worker.kill()
    return _LeanWorker(box)


def _closer(worker: _Worker) -> Callable[[], None]:
    """What closes a factorisation's worker: hand it back to the session open then (the
    factor freed, :meth:`_LeanWorker.release`), or end it."""
    def close() -> None:
        if isinstance(worker, _LeanWorker) and _SESSIONS and worker.release():
            _SESSIONS[0].append(worker)
        else:
            worker.close()

    return close


def _isolated(kernel: Callable[[list], tuple], box: list):
    """``kernel``'s factorisation and solves in a worker process — CHOLMOD's in a
    :class:`_LeanWorker` (a session's where one is open: :func:`worker_session`), the
    others in a forked :class:`_Worker`: (solve, nnz, close)."""
    if kernel is _cholmod and lean_worker_available():
        worker = _session_worker(box)
    else:
        worker = _Worker(kernel, box)
    _, nnz, _ = worker.receive()
    return worker.solve, nnz, _closer(worker), (worker if isinstance(worker, _LeanWorker)
                                                 and worker.shared is not None else None)


def isolation_available() -> bool:
    """Whether the factor can live in a forked worker process here: POSIX ``fork``, and
    this process may have children (not a daemonic process, e.g. a process pool's)."""
    import multiprocessing

    return ("fork" in multiprocessing.get_all_start_methods()
            and not multiprocessing.current_process().daemon)


#: [1] nodes of a part of the lattice ordered without a further cut (:func:`lattice_dissection`)
LATTICE_LEAF = 32
#: [1] smallest share of a part's nodes on either side of a cut (:func:`lattice_dissection`)
LATTICE_BALANCE = 0.15


def _free_ordering(order: np.ndarray, n_nodes: int, free: np.ndarray) -> np.ndarray:
    """The positions in ``free`` of the free dofs of the nodes in ``order``, each node's
    three dofs together (the constrained ones dropped)."""
    if free.size and (free.min() < 0 or free.max() >= 3 * n_nodes):
        raise LTCAError("nested dissection: not a permutation of the free dofs (a free "
                        f"dof beyond the {n_nodes} nodes ordered)")
    dofs = (3 * np.asarray(order, dtype=np.int64)[:, None] + np.arange(3)).ravel()
    position = np.full(3 * n_nodes, -1, dtype=np.int64)
    position[free] = np.arange(free.size)
    ordering = position[dofs]
    ordering = ordering[ordering >= 0]
    if ordering.size != free.size:
        raise LTCAError("nested dissection: not a permutation of the free dofs")
    return ordering


def _best_cut(c: np.ndarray, balance: float) -> tuple[float, int, int] | None:
    """The cut of a part of the lattice (its nodes' coordinates ``c``, (3, m)) by a plane
    of nodes at an even coordinate (element boundaries) that minimises the separator's
    size over the product of the two sides' shares, each side holding at least
    ``balance`` of the nodes: (score, direction, plane), or None where none does."""
    m = c.shape[1]
    best = None
    for d in range(3):
        lo = int(c[d].min())
        counts = np.bincount(c[d] - lo)
        below = np.cumsum(counts) - counts  # nodes below each plane
        plane = np.arange(counts.size)
        sep, left = counts, below
        right = m - below - counts
        ok = ((plane + lo) % 2 == 0) & (np.minimum(left, right) >= balance * m) & (sep > 0)
        if not ok.any():
            continue
        score = np.where(ok, sep * float(m) * m / np.maximum(left * right, 1), np.inf)
        k = int(np.argmin(score))
        if best is None or score[k] < best[0]:
            best = (float(score[k]), d, k + lo)
    return best


def lattice_dissection(lattice: np.ndarray, free: np.ndarray, *, leaf: int = LATTICE_LEAF,
                       balance: float = LATTICE_BALANCE) -> np.ndarray:
    """A fill-reducing ordering of the free dofs for CHOLMOD: nested dissection of a
    structured hexahedral mesh by planes of its node lattice, each node's three dofs
    together.

    Parameters
    ----------
    lattice : ndarray (3, N) of int
        Each node's place on the lattice of its mapped mesh: twice its parameter
        coordinates (:attr:`contact.compliance.fe.mapped_mesh.MappedMesh.param_nodes`),
        so that vertices lie at even and midside nodes at odd coordinates. A plane of
        nodes at an even coordinate separates the elements on its two sides (a quadratic
        element couples only nodes of its own cell).
    free : ndarray (F,) of int — the unconstrained vector dofs (3 n + c), increasing
    leaf : int — [1] parts of at most this many nodes are not cut further (ordered along
        the lattice)
    balance : float — [1] smallest share of a part's nodes on either side of a cut

    Returns
    -------
    ndarray (F,) of int64
        Entry k: the position in ``free`` of the dof eliminated k-th (:func:`factorise`'s
        ``ordering``): each part's two sides first (recursively), its separating plane
        last.

    Raises
    ------
    LTCAError — ``lattice`` does not describe the free dofs' nodes (not a permutation).

    Notes
    -----
    A. George 1973, "Nested dissection of a regular finite element mesh", *SIAM J.
    Numer. Anal.* 10(2) 345–363: each part is cut by the plane that minimises the
    separator over the product of the sides (a ratio cut, each side at least ``balance``
    of the part), across whichever of the three directions gives the smallest. The
    solid's lattice (teeth on a rim, :mod:`contact.compliance.fe.solid`) is cut through the
    rim under the slots, then along the face and across the teeth. On the default models
    (issue 75) the factor's non-zeros 67.5 → 50.3 M (pinion) and 66.2 → 47.5 M (gear) and
    its floating-point work 96 → 51 and 104 → 48 GFLOP against CHOLMOD's AMD — METIS's
    nested dissection (pymetis): 52.2 M / 52.5 GFLOP and 48.6 M / 48.2 GFLOP —, in
    ~0.05 s (docs/performance.md).
    """
    lattice = np.asarray(lattice, dtype=np.int64)
    n_nodes = lattice.shape[1]
    order = np.empty(n_nodes, dtype=np.int64)
    stack = [(np.arange(n_nodes), 0, n_nodes)]  # (nodes, first slot, end) to be ordered
    while stack:
        nodes, lo, hi = stack.pop()
        c = lattice[:, nodes]
        cut = _best_cut(c, balance) if nodes.size > leaf else None
        if cut is None:  # a leaf: along the lattice
            order[lo:hi] = nodes[np.lexsort((c[0], c[1], c[2]))]
            continue
        _, d, plane = cut
        below, on = c[d] < plane, c[d] == plane
        first, sep = nodes[below], nodes[on]
        second = nodes[~below & ~on]
        cs = lattice[:, sep]
        order[hi - sep.size:hi] = sep[np.lexsort((cs[0], cs[1], cs[2]))]
        stack.append((first, lo, lo + first.size))
        stack.append((second, lo + first.size, hi - sep.size))
    return _free_ordering(order, n_nodes, free)


def resolve_solver(solver: str = "auto") -> str:
    """The solver :func:`factorise` uses for ``solver``: a key of :data:`SOLVERS` (for
    ``"auto"`` the first installed of CHOLMOD, PARDISO, SuperLU).

    Raises
    ------
    InputError — an unknown solver name.
    ModelUnavailableError — the solver asked for is not installed (with the hint).
    """
    one_of("solver", solver, ("auto", *SOLVERS))
    if solver == "auto":
        return next(name for name, installed in SOLVERS.items() if installed())
    if not SOLVERS[solver]():
        raise ModelUnavailableError(f"solver: {solver!r} is not installed here (pip install "
                                    "'hypoid-ltca[fe]', from a clone: pip install '.[fe]'); "
                                    "available: "
                                    f"{[k for k, ok in SOLVERS.items() if ok()]}")
    return solver


def _free_lower(stiffness: sp.spmatrix, free: np.ndarray) -> sp.csc_matrix:
    """The lower triangle of K's free rows and columns, (F, F) CSC (what CHOLMOD reads):
    ``sp.tril(K)[free][:, free].tocsc()`` entry for entry, in one pass over K's
    non-zeros (renumbered, filtered, counted per row) instead of a copy for the triangle
    and one for each slice (~0.6 s less per member of the default case, issue 75)."""
    k = sp.csr_matrix(stiffness)
    n = k.shape[0]
    index = np.int32 if n < 2**31 else np.int64
    renum = np.full(n, -1, dtype=index)
    renum[free] = np.arange(free.size, dtype=index)
    rows = np.repeat(renum, np.diff(k.indptr))  # each entry's free row (−1: fixed)
    cols = renum[k.indices]
    keep = (cols >= 0) & (rows >= cols)  # a free column on or below the diagonal
    del cols
    counts = np.bincount(rows[keep], minlength=free.size)
    del rows
    indptr = np.r_[0, np.cumsum(counts)]
    low = sp.csr_matrix((k.data[keep], renum[k.indices[keep]], indptr),
                        shape=(free.size, free.size))
    low.has_sorted_indices = k.has_sorted_indices  # renumbering keeps the order
    return low.tocsc()


def factorise(stiffness: sp.spmatrix, fixed_dofs: np.ndarray, solver: str = "auto", *,
              isolated: bool = False, ordering: np.ndarray | None = None) -> Factorisation:
    """Factorise K with the ``fixed_dofs`` removed (homogeneous Dirichlet conditions).

    Parameters
    ----------
    stiffness : sparse (3N, 3N) — K [N/mm]; for CHOLMOD its lower triangle is enough
        (:func:`elastic_model` with ``lower=True``), the others need the whole K
    fixed_dofs : ndarray of int — constrained dofs
    solver : str — ``"auto"``, or a key of :data:`SOLVERS`
    isolated : bool — factorise and solve in a worker process (where ``fork`` exists,
        :func:`isolation_available`; else in this process): the native factorisation and
        solves hold the interpreter for seconds to minutes, in which a signal handler
        cannot run; waiting for a worker, a SIGTERM or Ctrl-C is honoured within
        :data:`WORKER_POLL` and the worker killed (issue 64). CHOLMOD's worker is a new
        lean interpreter (:mod:`contact.compliance.fe.solver_worker`, issue 75), the
        other solvers' a fork of this process. The matrix, the right-hand sides and the
        solutions go through a pipe (~40 MB per block of 64, tens of ms).
    ordering : ndarray (F,) of int, optional — CHOLMOD's fill-reducing permutation of the
        free dofs (:func:`lattice_dissection`; entry k: the free dof eliminated k-th);
        None: CHOLMOD's own (AMD). Ignored by the other solvers. Call
        :meth:`Factorisation.close` when done (the worker also ends with this process).

    Returns
    -------
    Factorisation

    Raises
    ------
    InputError — an unknown solver name or no constrained dof (a free body).
    ModelUnavailableError — the solver asked for is not installed (with the hint).
    LTCAError — the factorisation fails (a singular matrix: a part of the mesh not
        connected to the support).
    """
    solver = resolve_solver(solver)
    fixed = np.unique(np.asarray(fixed_dofs, dtype=int))
    if fixed.size == 0:
        raise InputError("fixed_dofs: at least one dof must be constrained (a free body "
                         "has no unique displacement)")
    n = stiffness.shape[0]
    free = np.setdiff1d(np.arange(n), fixed)
    if solver == "cholmod":  # its lower triangle only: half the memory of K_ff
        a = _free_lower(stiffness, free)
    else:
        a = sp.csr_matrix(stiffness)[free][:, free].tocsc()
    # K itself is no longer needed here: a caller that handed over its only reference
    # (build_influence_model) gets its memory back before the factor takes its own
    del stiffness
    t0 = time.perf_counter()
    kernel = {"cholmod": _cholmod, "pardiso": _pardiso, "superlu": _superlu}[solver]
    isolated = isolated and isolation_available()
    close = shared = None
    log.info("factorising %d unknowns with %s%s", free.size, solver,
             " in a worker process" if isolated else "")
    try:
        # the solver takes the matrix out: freed once it holds its own copy
        box = [(a, ordering)] if solver == "cholmod" else [a]
        del a
        if isolated:
            solve, nnz, close, shared = _isolated(kernel, box)
        else:
            solve, nnz = kernel(box)
    except RuntimeError as exc:  # SuperLU: "Factor is exactly singular"
        raise LTCAError(f"stiffness matrix: factorisation failed ({exc}); part of the mesh "
                        "is not held by the constraint") from None
    elapsed = time.perf_counter() - t0
    log.info("factorised %d unknowns with %s: %d non-zeros in the factors, %.1f s", free.size,
             solver, nnz, elapsed)
    return Factorisation(solver, free, n, nnz, elapsed, solve, isolated, close, shared)
