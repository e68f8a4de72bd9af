"""CHOLMOD's dense block solve (issue 75): the same displacements as cvxopt's own solves.

The FE build's unit loads are solved by ``cholmod_l_solve`` on whole dense blocks
(:mod:`contact.compliance.fe.cholmod_dense`, BLAS-3) instead of cvxopt's sparse solves of
a few columns per pass over the factor. Both apply the same factor; the references here
are cvxopt's own solve and SciPy's SuperLU, on a meshed cantilever (hex20, 4 × 2 × 2).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse as sp

from contact.compliance.fe import cholmod_dense
from contact.compliance.fe.cholmod_dense import dense_solver
from contact.compliance.fe.elasticity import elastic_model, factorise
from contact.compliance.fe.mapped_mesh import mapped_mesh


def _cantilever():
    mm = mapped_mesh((4, 2, 2), lambda p: np.vstack([10.0 * p[0], 2.0 * p[1], 2.0 * p[2]]))
    model = elastic_model(mm.mesh, "hex20", 206000.0, 0.3)
    clamp = mm.nodes_where(lambda p: p[0] < 1e-9)
    clamp = clamp[clamp < model.basis.N]
    return model, (3 * clamp[:, None] + np.arange(3)).ravel()


def _factor(model, fixed):
    """cvxopt's factor of K_ff (lower triangle) and its own column-by-column solve."""
    import scipy.sparse as sp
    from cvxopt import cholmod, matrix, spmatrix

    free = np.setdiff1d(np.arange(model.n_dofs), fixed)
    low = sp.tril(model.stiffness, format="csr")[free][:, free].tocsc()
    cols = np.repeat(np.arange(low.shape[1], dtype=np.int64), np.diff(low.indptr))
    mat = spmatrix(low.data, low.indices.astype(np.int64), cols, size=low.shape)
    factor = cholmod.symbolic(mat, uplo="L")
    cholmod.numeric(mat, factor)

    def own(b):
        x = matrix(np.asfortranarray(b, dtype=float))
        cholmod.solve(factor, x, sys=0)
        return np.asarray(x)

    return factor, own, free


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="found on Linux only")
def test_dense_block_solve_equals_cvxopt_solve():
    """On Linux the dense solver is found in cvxopt's CHOLMOD library; a block of 70
    right-hand sides (dense and unit-load-like sparse columns, a zero column) is solved to
    1e-12 of cvxopt's column-by-column solve (the same factor, the same triangular
    solves; measured equal to the bit on the default pinion model) and to 1e-9 of SuperLU
    (another factorisation: round-off of a matrix of condition ~1e6)."""
    model, fixed = _cantilever()
    factor, own, free = _factor(model, fixed)
    solve = dense_solver(factor, own)
    assert solve is not None
    rng = np.random.default_rng(11)
    b = rng.standard_normal((free.size, 70))
    b[:, 40:] = 0.0
    b[rng.integers(0, free.size, 30), np.arange(40, 70)] = 1.0
    b[:, 55] = 0.0
    got = solve(b)
    ref = own(b)
    scale = np.abs(ref).max()
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * scale)
    assert not got[:, 55].any()
    lu = factorise(model.stiffness, fixed, "superlu")
    full = np.zeros((model.n_dofs, b.shape[1]))
    full[free] = b
    np.testing.assert_allclose(got, lu.solve(full)[free], rtol=0, atol=1e-9 * scale)
    assert solve(np.empty((free.size, 0))).shape == (free.size, 0)


def test_dense_solver_refuses_what_is_not_a_factor():
    """Anything but cvxopt's real factor capsule gives None (the caller keeps cvxopt's
    solves), never a crash."""
    assert dense_solver(object(), lambda b: b) is None


def test_sparse_fallback_where_the_dense_solve_is_missing(monkeypatch):
    """Where the dense solve cannot be reached (not Linux, another cvxopt build), the
    factorisation solves with cvxopt's sparse solves: the same displacements (1e-12)."""
    model, fixed = _cantilever()
    rhs = np.random.default_rng(12).standard_normal((model.n_dofs, 50))
    ref = factorise(model.stiffness, fixed, "cholmod").solve(rhs)
    monkeypatch.setattr(cholmod_dense, "dense_solver", lambda factor, reference: None)
    got = factorise(model.stiffness, fixed, "cholmod").solve(rhs)
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * np.abs(ref).max())


def test_a_dense_solve_that_disagrees_falls_back(monkeypatch, caplog):
    """A dense solve that fails its first check (an incompatible library) is dropped with
    one warning, and the sparse solves give the displacements."""
    model, fixed = _cantilever()
    rhs = np.random.default_rng(13).standard_normal((model.n_dofs, 20))
    ref = factorise(model.stiffness, fixed, "cholmod").solve(rhs)

    def broken(factor, reference):
        def solve(b):
            raise RuntimeError("CHOLMOD's dense solve differs from cvxopt's")
        return solve

    monkeypatch.setattr(cholmod_dense, "dense_solver", broken)
    fac = factorise(model.stiffness, fixed, "cholmod")
    with caplog.at_level("WARNING", logger="contact.compliance.fe.cholmod_dense"):
        got = fac.solve(rhs)
        again = fac.solve(rhs)
    assert sum("sparse solves used instead" in r.getMessage() for r in caplog.records) == 1
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * np.abs(ref).max())
    np.testing.assert_array_equal(again, got)


def test_lower_triangle_assembly_equals_the_whole_ks_to_the_bit(monkeypatch):
    """``elastic_model(..., lower=True)`` (what a CHOLMOD build assembles, issue 75) stores
    exactly the lower triangle of the whole K: the same pattern and the same values to the
    bit (the whole K is the lower triangle completed by its transpose), over many blocks
    (7 elements each) of a distorted mesh."""
    import scipy.sparse as sp

    from contact.compliance.fe import elasticity

    monkeypatch.setattr(elasticity, "_BLOCK", 7)
    mm = mapped_mesh((6, 4, 3), lambda p: np.vstack([10.0 * p[0] + p[1] ** 2, 2.0 * p[1],
                                                     2.0 * p[2] + 0.3 * p[0]]))
    full = elastic_model(mm.mesh, "hex20", 206000.0, 0.3)
    low = elastic_model(mm.mesh, "hex20", 206000.0, 0.3, lower=True)
    want = sp.tril(full.stiffness, format="csr")
    got = low.stiffness
    want.sort_indices()
    got.sort_indices()
    assert got.nnz == want.nnz
    np.testing.assert_array_equal(got.indptr, want.indptr)
    np.testing.assert_array_equal(got.indices, want.indices)
    np.testing.assert_array_equal(got.data, want.data)


def _assert_ordering_solves_alike(model, fixed, order, seed: int, columns: int) -> None:
    """CHOLMOD factorising in ``order`` solves random right-hand sides as its own AMD
    ordering does to 1e-10 of the largest displacement (another elimination order of the
    same matrix, condition ~1e6), and the lean worker's factor bit for bit as in process."""
    rhs = np.random.default_rng(seed).standard_normal((model.n_dofs, columns))
    ref = factorise(model.stiffness, fixed, "cholmod").solve(rhs)
    got = factorise(model.stiffness, fixed, "cholmod", ordering=order).solve(rhs)
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-10 * np.abs(ref).max())
    iso = factorise(model.stiffness, fixed, "cholmod", ordering=order, isolated=True)
    np.testing.assert_array_equal(iso.solve(rhs), got)
    iso.close()


def _factor_nonzeros(model, fixed, ordering):
    """Non-zeros of CHOLMOD's factor of K_ff in ``ordering`` (None: its AMD)."""
    import scipy.sparse as sp
    from cvxopt import cholmod, matrix, spmatrix

    free = np.setdiff1d(np.arange(model.n_dofs), fixed)
    low = sp.tril(model.stiffness, format="csr")[free][:, free].tocsc()
    cols = np.repeat(np.arange(low.shape[1], dtype=np.int64), np.diff(low.indptr))
    mat = spmatrix(low.data, low.indices.astype(np.int64), cols, size=low.shape)
    saved = dict(cholmod.options)
    try:
        if ordering is None:
            factor = cholmod.symbolic(mat, uplo="L")
        else:
            cholmod.options["nmethods"] = 1
            factor = cholmod.symbolic(mat, p=matrix(ordering), uplo="L")
        cholmod.numeric(mat, factor)
    finally:
        cholmod.options.clear()
        cholmod.options.update(saved)
    return len(cholmod.getfactor(factor).V)


def test_lattice_dissection_orders_the_free_dofs_with_less_fill_and_solves_alike():
    """The nested dissection of the mesh's node lattice (issue 75) is a permutation of the
    free dofs; its separators are planes of nodes at even lattice coordinates, so the
    last-eliminated dofs are one such plane's; on a block of 16 × 4 × 8 quadratic
    elements held at one end CHOLMOD's factor in that order has fewer non-zeros than in
    its own AMD order (nested dissection's fill, George 1973: O(n^(4/3)) in 3-D against
    minimum degree's larger on regular grids), and the displacements equal AMD's to
    round-off (1e-10 of the largest: another elimination order of the same matrix), in
    process and in the lean worker alike."""
    from contact.compliance.fe.elasticity import lattice_dissection

    mm = mapped_mesh((16, 4, 8), lambda p: np.vstack([2.0 * p[0], 1.5 * p[1], p[2]]))
    model = elastic_model(mm.mesh, "hex20", 206000.0, 0.3)
    n = model.basis.N
    clamp = mm.nodes_where(lambda p: p[0] < 1e-9)
    clamp = clamp[clamp < n]
    fixed = (3 * clamp[:, None] + np.arange(3)).ravel()
    free = np.setdiff1d(np.arange(model.n_dofs), fixed)
    lattice = np.rint(2.0 * mm.param_nodes[:, :n]).astype(np.int64)
    order = lattice_dissection(lattice, free)
    assert order.dtype == np.int64
    np.testing.assert_array_equal(np.sort(order), np.arange(free.size))
    # the last dofs eliminated: the first cut, one plane at an even coordinate
    last = lattice[:, free[order[-24:]] // 3]
    assert any(np.all(last[d] == last[d, 0]) and last[d, 0] % 2 == 0 for d in range(3))
    assert _factor_nonzeros(model, fixed, order) < _factor_nonzeros(model, fixed, None)
    _assert_ordering_solves_alike(model, fixed, order, seed=15, columns=12)


def _block_factor():
    """A block of 16 × 4 × 8 quadratic elements held at one end, its lattice ordering and
    CHOLMOD's supernodal factor of it as the FE build makes it (``cholmod_kernel``)."""
    from contact.compliance.fe.elasticity import _free_lower, lattice_dissection

    mm = mapped_mesh((16, 4, 8), lambda p: np.vstack([2.0 * p[0], 1.5 * p[1], p[2]]))
    model = elastic_model(mm.mesh, "hex20", 206000.0, 0.3, lower=True)
    n = model.basis.N
    clamp = mm.nodes_where(lambda p: p[0] < 1e-9)
    clamp = clamp[clamp < n]
    fixed = (3 * clamp[:, None] + np.arange(3)).ravel()
    free = np.setdiff1d(np.arange(model.n_dofs), fixed)
    order = lattice_dissection(np.rint(2.0 * mm.param_nodes[:, :n]).astype(np.int64), free)
    low = _free_lower(model.stiffness, free)
    solve, _ = cholmod_dense.cholmod_kernel([(low.data, low.indices, low.indptr, free.size,
                                              order)])
    full = (low + sp.tril(low, -1).T).tocsc()
    # loads on a patch of the top face near the free end: nodes at z = 8, x >= 26
    top = mm.nodes_where(lambda p: (p[2] > 8 - 1e-9) & (p[0] > 13 - 1e-9))
    top = top[top < n]
    return solve, full, free, top


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="found on Linux only")
def test_forward_solve_over_the_loaded_supernodes_equals_the_whole_solve(monkeypatch):
    """Right-hand sides on a few rows (unit loads on a patch of one face, issue 75) are
    solved forward over the supernodes they reach only (``SupernodalForward``: the
    ancestors of their rows' supernodes in the elimination tree, Gilbert 1994) and
    backward by CHOLMOD: the displacements equal SuperLU's of the same matrix to 1e-10 of
    the largest (another factorisation: round-off of a matrix of condition ~1e6) and
    CHOLMOD's whole solve of the same factor to 1e-12 (the same triangular factors, the
    forward sums in another order); dense right-hand sides, which reach more than
    ``FORWARD_SHARE`` of the factor, take CHOLMOD's whole solve."""
    import scipy.sparse.linalg as sla

    calls = []
    real = cholmod_dense.SupernodalForward.__call__

    def counted(self, b, rows, supernodes):
        calls.append(self.share(supernodes))
        return real(self, b, rows, supernodes)

    monkeypatch.setattr(cholmod_dense.SupernodalForward, "__call__", counted)
    solve, full, free, top = _block_factor()
    position = np.full(3 * (free.max() // 3 + 1), -1)
    position[free] = np.arange(free.size)
    rows = position[(3 * top[:, None] + np.arange(3)).ravel()]
    rows = rows[rows >= 0]
    rng = np.random.default_rng(17)
    b = np.zeros((free.size, 24))
    b[rows] = rng.standard_normal((rows.size, 24))
    b[:, 5] = 0.0
    got = solve(b)
    assert len(calls) == 1 and 0.0 < calls[0] < cholmod_dense.FORWARD_SHARE
    lu = sla.splu(full)
    ref = lu.solve(b)
    scale = np.abs(ref).max()
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-10 * scale)
    assert not got[:, 5].any()
    monkeypatch.setattr(cholmod_dense, "FORWARD_SHARE", -1.0)  # the whole solve
    whole = solve(b)
    assert len(calls) == 1
    np.testing.assert_allclose(got, whole, rtol=0, atol=1e-12 * scale)
    monkeypatch.setattr(cholmod_dense, "FORWARD_SHARE", 0.5)
    dense = rng.standard_normal((free.size, 3))
    np.testing.assert_allclose(solve(dense), lu.solve(dense), rtol=0,
                               atol=1e-10 * np.abs(lu.solve(dense)).max())
    assert len(calls) == 1  # dense right-hand sides reach every supernode


def test_supernodal_arrays_refuse_a_simplicial_factor():
    """A factor that is not supernodal LLᵀ (cvxopt's simplicial default on a small matrix)
    is not read as one: no forward solve of ours, CHOLMOD's whole solve only."""
    from cvxopt import cholmod

    model, fixed = _cantilever()
    saved = dict(cholmod.options)
    cholmod.options["supernodal"] = 0
    try:
        factor, own, free = _factor(model, fixed)
    finally:
        cholmod.options.clear()
        cholmod.options.update(saved)
    pointer = cholmod_dense._factor_pointer(factor)
    assert pointer is not None
    assert cholmod_dense._supernodal_arrays(pointer) is None
    b = np.zeros((free.size, 2))
    b[:6] = 1.0
    np.testing.assert_allclose(dense_solver(factor, own)(b), own(b), rtol=0,
                               atol=1e-12 * np.abs(own(b)).max())


def test_lattice_dissection_refuses_a_lattice_of_other_nodes():
    """A lattice of fewer nodes than the free dofs name is refused (not a permutation)."""
    from contact.compliance.fe.elasticity import lattice_dissection
    from geometry.core.errors import LTCAError

    lattice = np.array([[0, 2], [0, 0], [0, 0]])
    with pytest.raises(LTCAError, match="not a permutation"):
        lattice_dissection(lattice, np.arange(9))


def test_keep_heap_pages_from_the_package_and_from_the_lean_worker():
    """``geometry.core.heap.keep_heap_pages`` and the lean solver worker's copy of it
    (loaded from the file, the worker imports no package of the toolkit) set glibc's
    malloc options where there is glibc (True on Linux) and do nothing elsewhere (False):
    run in a child process, whose heap alone it changes."""
    import subprocess

    child = ("import sys\n"
             "from geometry.core.heap import keep_heap_pages\n"
             "from contact.compliance.fe import solver_worker\n"
             "print(keep_heap_pages(), solver_worker.keep_heap_pages(), sys.platform)\n")
    out = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True,
                         cwd=Path(__file__).resolve().parents[1], check=True).stdout.split()
    assert out[0] == out[1] == str(out[2].startswith("linux"))


def test_csc_spmatrix_equals_the_triplets():
    """``csc_spmatrix`` (the compressed columns copied into cvxopt's matrix as they are,
    issue 75) gives the matrix cvxopt builds from the same entries as triplets, entry for
    entry (values, rows, columns exactly), empty columns included; arrays that are not
    canonical CSC are refused (the worker then builds from triplets)."""
    import scipy.sparse as sp
    from cvxopt import spmatrix

    from contact.compliance.fe.cholmod_dense import csc_spmatrix

    a = sp.random(40, 40, density=0.1, random_state=np.random.default_rng(3), format="csc")
    a = sp.tril(a + sp.eye(40), format="csc")
    keep = np.ones(40)
    keep[7] = 0.0  # an empty column
    a = (a @ sp.diags(keep)).tocsc()
    a.eliminate_zeros()
    a.sort_indices()
    cols = np.repeat(np.arange(40, dtype=np.int64), np.diff(a.indptr))
    ref = spmatrix(a.data, a.indices.astype(np.int64), cols, size=(40, 40))
    got = csc_spmatrix(a.data, a.indices.astype(np.int32), a.indptr, 40)
    assert got.size == ref.size == (40, 40)
    for x, y in ((got.V, ref.V), (got.I, ref.I), (got.J, ref.J)):
        assert np.array_equal(np.asarray(x), np.asarray(y))
    del got  # its arrays freed by cvxopt (malloc'd as its own)
    swapped = a.indices.copy()
    start = a.indptr[0]
    swapped[start], swapped[start + 1] = swapped[start + 1], swapped[start]
    with pytest.raises(ValueError, match="unsorted"):
        csc_spmatrix(a.data, swapped, a.indptr, 40)
    with pytest.raises(ValueError, match="compressed columns"):
        csc_spmatrix(a.data, a.indices, a.indptr, 41)


def test_free_lower_triangle_equals_scipys_slices():
    """The matrix CHOLMOD is handed (K's free rows and columns, lower triangle, CSC) is
    built in one pass (issue 75): entry for entry ``sp.tril(K)[free][:, free].tocsc()``,
    from the whole K and from its lower triangle alike."""
    import scipy.sparse as sp

    from contact.compliance.fe.elasticity import _free_lower

    mm = mapped_mesh((3, 2, 2), lambda p: np.vstack([10.0 * p[0], 2.0 * p[1] + p[0] * 0.1,
                                                     2.0 * p[2]]))
    full = elastic_model(mm.mesh, "hex20", 206000.0, 0.3).stiffness
    low = elastic_model(mm.mesh, "hex20", 206000.0, 0.3, lower=True).stiffness
    fixed = np.random.default_rng(5).choice(full.shape[0], 40, replace=False)
    free = np.setdiff1d(np.arange(full.shape[0]), fixed)
    want = sp.tril(full, format="csr")[free][:, free].tocsc()
    for k in (full, low):
        got = _free_lower(k, free)
        assert got.shape == want.shape and got.format == "csc"
        np.testing.assert_array_equal(got.indptr, want.indptr)
        np.testing.assert_array_equal(got.indices, want.indices)
        np.testing.assert_array_equal(got.data, want.data)


def test_stiffness_equals_scikit_fems_assembly(monkeypatch):
    """K summed by node pairs (issue 75, fourth round) against scikit-fem's own assembly
    of the same bilinear form (``skfem.models.elasticity.linear_elasticity`` on the same
    basis and quadrature: independent code, the element matrices summed by scikit-fem's
    COO): equal within 1e-13 of K's largest entry (summation order only; the sums' round-
    off is ~1e-16 relative per term, a few tens of terms per entry), exactly symmetric,
    the lower triangle's ``lower=True``. Blocks of 3 elements (several blocks adding to
    the same entries) on a distorted mesh."""
    import scipy.sparse as sp
    import skfem
    from skfem.models.elasticity import linear_elasticity

    from contact.compliance.fe import elasticity

    monkeypatch.setattr(elasticity, "_BLOCK", 3)
    mm = mapped_mesh((4, 3, 2), lambda p: np.vstack([10.0 * p[0] + p[1] ** 2, 2.0 * p[1],
                                                     2.0 * p[2] + 0.3 * p[0] * p[2]]))
    lam, mu = elasticity.lame(206000.0, 0.3)
    basis = skfem.CellBasis(mm.mesh, skfem.ElementVector(skfem.ElementHexS2()), intorder=4)
    want = skfem.asm(linear_elasticity(lam, mu), basis).tocsr()
    got = elastic_model(mm.mesh, "hex20", 206000.0, 0.3).stiffness
    scale = abs(want).max()
    assert abs(got - want).max() <= 1e-13 * scale
    assert (got - got.T).count_nonzero() == 0
    low = elastic_model(mm.mesh, "hex20", 206000.0, 0.3, lower=True).stiffness
    assert (low - sp.tril(got)).count_nonzero() == 0


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="memfd_create: Linux")
@pytest.mark.parametrize("shared", [True, False])
def test_the_workers_shared_blocks_solve_as_the_connection(monkeypatch, shared):
    """The lean worker's blocks on shared memory (issue 75, fourth round): a block written
    into :meth:`Factorisation.rhs_block` and solved in place by :meth:`solve_free`, and
    more columns than one block through :meth:`Factorisation.solve`, give the in-process
    factor's displacements (the same factor and ordering in another process: equal to
    round-off, 1e-12 of the largest); without shared memory (``_shared_blocks`` None)
    the same through the connection."""
    from contact.compliance.fe import elasticity

    if not shared:
        monkeypatch.setattr(elasticity, "_shared_blocks", lambda rows: None)
    model, fixed = _cantilever()
    rhs = np.random.default_rng(21).standard_normal((model.n_dofs, 150))
    ref = factorise(model.stiffness, fixed, "cholmod").solve(rhs)
    iso = factorise(model.stiffness, fixed, "cholmod", isolated=True)
    try:
        assert (iso._shared is not None) == shared
        scale = np.abs(ref).max()
        got = iso.solve(rhs)  # 150 columns: three blocks
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * scale)
        block = iso.rhs_block(40)
        assert block.shape == (iso.free.size, 40) and block.flags.f_contiguous
        block[...] = rhs[iso.free, :40]
        x = iso.solve_free(block)
        np.testing.assert_allclose(x, ref[iso.free, :40], rtol=0, atol=1e-12 * scale)
        # an array of its own (not the shared block) is solved too
        y = iso.solve_free(np.ascontiguousarray(rhs[iso.free, 40:45]))
        np.testing.assert_allclose(y, ref[iso.free, 40:45], rtol=0, atol=1e-12 * scale)
    finally:
        iso.close()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="memfd_create: Linux")
@pytest.mark.parametrize("shared", [True, False])
def test_a_worker_session_factorises_one_matrix_after_another(monkeypatch, shared):
    """Within ``worker_session`` (issue 75: a pair's two FE builds) a closed factorisation
    hands its lean worker back and the next one uses the same process — a matrix of other
    rows too (the shared blocks resized) — and each solves as the in-process factor (equal
    to round-off, 1e-12 of the largest: the same factor in another process); the worker
    ends with the session, and without one each factorisation has its own."""
    from contact.compliance.fe import elasticity

    if not shared:
        monkeypatch.setattr(elasticity, "_shared_blocks", lambda rows: None)
    model, fixed = _cantilever()
    small_fixed = np.r_[fixed, np.arange(model.n_dofs - 30, model.n_dofs)]  # other rows
    rhs = np.random.default_rng(5).standard_normal((model.n_dofs, 70))
    pids = []
    with elasticity.worker_session():
        for dofs in (fixed, small_fixed, fixed):
            ref = factorise(model.stiffness, dofs, "cholmod").solve(rhs)
            iso = factorise(model.stiffness, dofs, "cholmod", isolated=True)
            try:
                pids.append(iso._close.__closure__[0].cell_contents.proc.popen.pid)
                np.testing.assert_allclose(iso.solve(rhs), ref, rtol=0,
                                           atol=1e-12 * np.abs(ref).max())
            finally:
                iso.close()
        held = elasticity._SESSIONS[0][0]
        assert held.proc.is_alive()
    assert len(set(pids)) == 1
    held.proc.join(5.0)
    assert not held.proc.is_alive() and not elasticity._SESSIONS
    outside = [factorise(model.stiffness, fixed, "cholmod", isolated=True) for _ in range(2)]
    try:
        assert len({f._close.__closure__[0].cell_contents.proc.popen.pid
                    for f in outside}) == 2
    finally:
        for f in outside:
            f.close()


@pytest.mark.parametrize(("env", "expected", "after"), [
    ({}, "1", "1"),
    ({"OMP_NUM_THREADS": "4"}, None, None),
    ({"OPENBLAS_NUM_THREADS": "2"}, None, "2"),
    ({"HYPOID_LTCA_BLAS_THREADS": "3"}, "3", "3"),
    ({"HYPOID_LTCA_BLAS_THREADS": "0"}, None, None),
])
def test_the_worker_takes_one_blas_thread_unless_told(monkeypatch, env, expected, after):
    """The solver worker's NumPy BLAS (the forward solves' products) gets the toolkit's
    thread count before NumPy loads: one thread where the environment names none, the
    toolkit's own variable first, the user's OpenBLAS/OpenMP/MKL setting left alone."""
    from contact.compliance.fe.solver_worker import one_blas_thread

    for name in ("HYPOID_LTCA_BLAS_THREADS", "OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                 "MKL_NUM_THREADS"):
        monkeypatch.delenv(name, raising=False)
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    assert one_blas_thread() == expected
    import os
    assert os.environ.get("OPENBLAS_NUM_THREADS") == after
