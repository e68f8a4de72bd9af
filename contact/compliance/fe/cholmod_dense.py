"""CHOLMOD's solve of a whole dense block of right-hand sides, on cvxopt's factor.

cvxopt's ``cholmod.solve`` applies a factor to a dense matrix one column at a time and
``cholmod.spsolve`` hands CHOLMOD sparse right-hand sides, which CHOLMOD solves a few
columns per pass over the factor: both read the whole factor (≈ 0.6 GB on the default
pinion model) from memory for every one to four columns, ≈ 0.04 s per unit load on the
default pinion model (issue 75: 6.5 GFLOP/s against the factorisation's 30). CHOLMOD's own
``cholmod_l_solve`` of a dense block runs the supernodal triangular solves on all columns
at once (dense matrix-matrix kernels, BLAS-3): ≈ 0.012 s per unit load on the same model,
the same displacements to the last bit (measured, docs/performance.md).

cvxopt does not expose that call, so this module calls it through :mod:`ctypes` in the
very library cvxopt's ``cholmod`` module has loaded (found in the process's memory map,
``/proc/self/maps``: the factor's structure is that library's), with the factor taken
from cvxopt's capsule. Where that library cannot be found (not Linux, or another build of
cvxopt) :func:`dense_solver` gives None and the caller keeps cvxopt's sparse solves; a
solver that is found is checked once against cvxopt's own solve before it is used
(:func:`dense_solver`).

This module imports NumPy and cvxopt only: it is also what the FE build's solver worker
process loads (:mod:`contact.compliance.fe.solver_worker`, a lean interpreter).

Public names
------------
CHOLMOD_BLOCK  right-hand sides per sparse solve (the fallback)
cholmod_kernel CHOLMOD's factor of a matrix's lower triangle and its solve
csc_spmatrix   a cvxopt sparse matrix from CSC arrays, without cvxopt's triplet sort
dense_solver   a function solving dense blocks with a cvxopt CHOLMOD factor, or None
"""

from __future__ import annotations

import ctypes
import logging
import sys
from collections.abc import Callable

import numpy as np

__all__ = ["CHOLMOD_BLOCK", "cholmod_kernel", "csc_spmatrix", "dense_solver"]

log = logging.getLogger(__name__)

#: the name cvxopt gives the capsule of a real (double) LLᵀ / LDLᵀ factor
_CAPSULE = b"CHOLMOD FACTOR D L"
#: bytes reserved for a ``cholmod_common`` (≈ 3 KB in SuiteSparse 5–7; generously more)
_COMMON_BYTES = 1 << 16
#: [1] relative difference from cvxopt's own solve above which the dense solve is refused
CHECK_TOLERANCE = 1e-10
#: right-hand sides solved at once by cvxopt's sparse solves (the fallback): bounds the
#: dense blocks' memory (the loads and displacements, 8 bytes × unknowns × this)
CHOLMOD_BLOCK = 48
_REAL = 1  # CHOLMOD_REAL
_DOUBLE = 0  # CHOLMOD_DOUBLE


class _Dense(ctypes.Structure):
    """``cholmod_dense`` (SuiteSparse 4–7: the same layout)."""

    _fields_ = [("nrow", ctypes.c_size_t), ("ncol", ctypes.c_size_t),
                ("nzmax", ctypes.c_size_t), ("d", ctypes.c_size_t),
                ("x", ctypes.c_void_p), ("z", ctypes.c_void_p),
                ("xtype", ctypes.c_int), ("dtype", ctypes.c_int)]


class _CCS(ctypes.Structure):
    """cvxopt's ``ccs`` (cvxopt.h, 1.x): a sparse matrix's compressed columns, its arrays
    allocated with the C library's ``malloc`` and freed with its ``free``."""

    _fields_ = [("values", ctypes.c_void_p), ("colptr", ctypes.c_void_p),
                ("rowind", ctypes.c_void_p), ("nrows", ctypes.c_ssize_t),
                ("ncols", ctypes.c_ssize_t), ("id", ctypes.c_int)]


class _SpObject(ctypes.Structure):
    """cvxopt's ``spmatrix`` object: ``PyObject_HEAD`` and its ``ccs *``."""

    _fields_ = [("ob_refcnt", ctypes.c_ssize_t), ("ob_type", ctypes.c_void_p),
                ("obj", ctypes.POINTER(_CCS))]


def _ccs_of(mat) -> _CCS | None:
    """The ``ccs`` inside a cvxopt ``spmatrix``, or None where the object is not laid out
    as :class:`_SpObject` (checked on a small matrix of known columns first)."""
    from cvxopt import spmatrix

    probe = spmatrix([1.5, 2.5, 3.5], [0, 2, 1], [0, 0, 1], (3, 2))
    try:
        ccs = _SpObject.from_address(id(probe)).obj.contents
        ok = (ccs.nrows, ccs.ncols, ccs.id) == (3, 2, 1) and (
            np.ctypeslib.as_array(ctypes.cast(ccs.colptr, ctypes.POINTER(ctypes.c_ssize_t)),
                                  shape=(3,)).tolist() == [0, 2, 3]
            and np.ctypeslib.as_array(ctypes.cast(ccs.rowind,
                                                  ctypes.POINTER(ctypes.c_ssize_t)),
                                      shape=(3,)).tolist() == [0, 2, 1]
            and np.ctypeslib.as_array(ctypes.cast(ccs.values,
                                                  ctypes.POINTER(ctypes.c_double)),
                                      shape=(3,)).tolist() == [1.5, 2.5, 3.5])
    except (ValueError, TypeError, OSError):  # pragma: no cover - another layout
        ok = False
    if not ok:  # pragma: no cover - another cvxopt
        return None
    return _SpObject.from_address(id(mat)).obj.contents


def csc_spmatrix(data: np.ndarray, indices: np.ndarray, indptr: np.ndarray, n: int):
    """A cvxopt ``spmatrix`` (n, n) of compressed sparse columns, copied into it as they
    are.

    cvxopt builds a sparse matrix from triplets only, and sorts each column's triplets
    (``qsort``) even where they come sorted: ~1 s for the 6.6 M non-zeros of the default
    pinion model's lower triangle, in the FE build's worker, per member (issue 75). Here a
    matrix of the right size is made with one entry and its three arrays replaced by
    copies of the given ones, allocated with the C library's ``malloc`` as cvxopt's own
    (which frees them with ``free``): ~0.05 s.

    Parameters
    ----------
    data : ndarray (nnz,) [float64]
    indices : ndarray (nnz,) of int — row of each entry; sorted within each column, no
        duplicates (scipy's canonical CSC, e.g. from ``tocsc()``)
    indptr : ndarray (n + 1,) of int — start of each column in ``data``
    n : int — rows and columns

    Returns
    -------
    cvxopt.spmatrix
        The same matrix as ``spmatrix(data, indices, columns, (n, n))`` (entry for entry).

    Raises
    ------
    ValueError
        The arrays are not canonical CSC of an (n, n) matrix, or cvxopt's matrix or the C
        library's ``malloc`` cannot be reached as expected here (Windows; another cvxopt):
        the caller builds from triplets instead.
    """
    from cvxopt import spmatrix

    data = np.asarray(data, dtype=np.float64)
    indices, indptr = np.asarray(indices), np.asarray(indptr)
    nnz = int(indptr[-1]) if indptr.size else -1
    if (indptr.shape != (n + 1,) or indptr[0] != 0 or data.shape != (nnz,)
            or indices.shape != (nnz,) or np.any(np.diff(indptr) < 0)):
        raise ValueError("csc_spmatrix: not the compressed columns of an (n, n) matrix")
    if nnz:
        step = np.diff(indices)
        step[indptr[1:-1][(indptr[1:-1] > 0) & (indptr[1:-1] < nnz)] - 1] = 1
        if indices.min() < 0 or indices.max() >= n or np.any(step <= 0):
            raise ValueError("csc_spmatrix: rows out of range, unsorted or repeated in a "
                             "column")
    if sys.platform == "win32":  # cvxopt's allocator there need not be one we can reach
        raise ValueError("csc_spmatrix: not on Windows")
    try:
        libc = ctypes.CDLL(None)
        malloc = libc.malloc
    except (OSError, TypeError, AttributeError) as exc:  # pragma: no cover - no C library
        raise ValueError(f"csc_spmatrix: no C library's malloc here ({exc})") from None
    malloc.restype, malloc.argtypes = ctypes.c_void_p, [ctypes.c_size_t]
    mat = spmatrix([0.0], [0], [0], (n, n))
    ccs = _ccs_of(mat)
    if ccs is None:  # pragma: no cover - another cvxopt
        raise ValueError("csc_spmatrix: cvxopt's sparse matrix is laid out differently")
    values = malloc(8 * max(nnz, 1))
    rows = malloc(8 * max(nnz, 1))
    if not values or not rows:  # pragma: no cover - out of memory
        raise MemoryError("csc_spmatrix: malloc failed")

    def view(address, ctype, size):
        return np.ctypeslib.as_array(ctypes.cast(address, ctypes.POINTER(ctype)),
                                     shape=(size,))

    view(values, ctypes.c_double, max(nnz, 1))[:nnz] = data
    view(rows, ctypes.c_ssize_t, max(nnz, 1))[:nnz] = indices
    view(ccs.colptr, ctypes.c_ssize_t, n + 1)[:] = indptr  # cvxopt's own: n + 1 long
    # the one-entry arrays cvxopt made (8 bytes each) are left to it unfreed: freeing
    # them here would need its allocator's word; 16 bytes per matrix
    ccs.values, ccs.rowind = values, rows
    return mat


def _loaded_cholmod() -> str | None:
    """Path of the CHOLMOD library this process has loaded (cvxopt's), Linux only."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        with open("/proc/self/maps", encoding="utf-8", errors="replace") as maps:
            paths = {line.split()[-1] for line in maps if "libcholmod" in line}
    except OSError:
        return None
    paths = {p for p in paths if p.startswith("/")}
    return paths.pop() if len(paths) == 1 else None


def _factor_pointer(factor) -> int | None:
    """The ``cholmod_factor *`` inside cvxopt's capsule, or None if it is not a real one."""
    get_name = ctypes.pythonapi.PyCapsule_GetName
    get_name.restype, get_name.argtypes = ctypes.c_char_p, [ctypes.py_object]
    get = ctypes.pythonapi.PyCapsule_GetPointer
    get.restype, get.argtypes = ctypes.c_void_p, [ctypes.py_object, ctypes.c_char_p]
    try:
        if get_name(factor) != _CAPSULE:
            return None
        return get(factor, _CAPSULE)
    except (TypeError, ValueError):
        return None


def dense_solver(factor, reference: Callable[[np.ndarray], np.ndarray]
                 ) -> Callable[[np.ndarray], np.ndarray] | None:
    """A solve of dense blocks of right-hand sides with a CHOLMOD factor of cvxopt.

    Parameters
    ----------
    factor : PyCapsule
        ``cvxopt.cholmod`` factor (``cholmod.symbolic`` then ``cholmod.numeric``) of an
        (n, n) symmetric positive definite matrix A; it must outlive the returned function.
    reference : callable
        cvxopt's own solve of A x = b (ndarray (n, k) → (n, k)): the check of the first
        use (one column).

    Returns
    -------
    callable or None
        ``solve(b, out=None)``: x (n, k) [float64] of A x = b for b (n, k), written
        into ``out`` where given (float64, Fortran order) — CHOLMOD's
        ``cholmod_l_solve`` (``CHOLMOD_A``) on the whole block (supernodal, BLAS-3); or
        None where CHOLMOD's library cannot be reached here (not Linux, another cvxopt
        build, an unexpected capsule): the caller keeps cvxopt's solves.

    Raises
    ------
    RuntimeError
        From ``solve``: CHOLMOD reports a failure (out of memory), or the first solve
        differs from ``reference`` by more than :data:`CHECK_TOLERANCE` relative (an
        incompatible library: the solver is not to be trusted; the caller falls back).

    Notes
    -----
    Source: T. A. Davis, *CHOLMOD User Guide* (SuiteSparse), ``cholmod_solve``; Y. Chen,
    T. A. Davis, W. W. Hager, S. Rajamanickam 2008, "Algorithm 887: CHOLMOD, supernodal
    sparse Cholesky factorization and update/downdate", *ACM TOMS* 35(3) 22.
    """
    path = _loaded_cholmod()
    pointer = _factor_pointer(factor)
    if path is None or pointer is None:
        return None
    try:
        lib = ctypes.CDLL(path)
        start, solve_c, free = lib.cholmod_l_start, lib.cholmod_l_solve, lib.cholmod_l_free_dense
        finish = lib.cholmod_l_finish
    except (OSError, AttributeError):
        return None
    start.argtypes = finish.argtypes = [ctypes.c_void_p]
    solve_c.restype = ctypes.POINTER(_Dense)
    solve_c.argtypes = [ctypes.c_int, ctypes.c_void_p, ctypes.POINTER(_Dense), ctypes.c_void_p]
    free.argtypes = [ctypes.POINTER(ctypes.POINTER(_Dense)), ctypes.c_void_p]
    common = ctypes.create_string_buffer(_COMMON_BYTES)
    if not start(common):
        return None
    checked = []

    def solve(b: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        rhs = np.asfortranarray(b, dtype=np.float64)
        n, k = rhs.shape
        if out is not None and (out.shape != (n, k) or out.dtype != np.float64
                                or not out.flags.f_contiguous):
            raise ValueError("solve: out must be a float64 array of the block's shape in "
                             "Fortran order")
        if k == 0:
            return np.empty((n, 0)) if out is None else out
        block = _Dense(n, k, n * k, n, rhs.ctypes.data, None, _REAL, _DOUBLE)
        x = solve_c(0, pointer, ctypes.byref(block), common)  # 0: CHOLMOD_A, A x = b
        if not x:
            raise RuntimeError("CHOLMOD: cholmod_l_solve failed (out of memory?)")
        try:
            d = x.contents
            if (d.nrow, d.ncol) != (n, k) or d.xtype != _REAL:
                raise RuntimeError("CHOLMOD: cholmod_l_solve returned an unexpected block")
            flat = np.ctypeslib.as_array(ctypes.cast(d.x, ctypes.POINTER(ctypes.c_double)),
                                         shape=(k * d.d,))
            # copied column after column (Fortran order, as CHOLMOD lays it out): no
            # transposition (~0.05 s per block of 64 on the default pinion model), into
            # ``out`` where given (the solver worker's shared block, issue 75)
            if out is None:
                out = flat.reshape(k, d.d)[:, :n].copy().T
            else:
                np.copyto(out.T, flat.reshape(k, d.d)[:, :n])
        finally:
            free(ctypes.byref(x), common)
        if not checked:
            ref = reference(np.ascontiguousarray(rhs[:, :1]))
            scale = float(np.abs(ref).max()) or 1.0
            if float(np.abs(out[:, :1] - ref).max()) > CHECK_TOLERANCE * scale:
                raise RuntimeError("CHOLMOD's dense solve differs from cvxopt's (an "
                                   "incompatible library)")
            checked.append(True)
        return out

    solve.finish = lambda: finish(common)  # type: ignore[attr-defined]
    return solve


def cholmod_kernel(box: list) -> tuple[Callable[[np.ndarray], np.ndarray], int]:
    """CHOLMOD's Cholesky factor of a symmetric positive definite matrix and its solve.

    Parameters
    ----------
    box : list
        One item, taken out (its memory freed once copied into cvxopt's matrix): the
        tuple ``(data, indices, indptr, n, ordering)`` of the matrix's lower triangle in
        CSC (float64, integer, integer, int) [N/mm] and its fill-reducing permutation
        (ndarray (n,) of int: entry k the row eliminated k-th) or None (AMD).

    Returns
    -------
    (solve, nnz)
        ``solve(b, out=None)``: x (n, k) of A x = b for b (n, k) (into ``out``, an
        (n, k) float64 array in Fortran order, where given), dense blocks at once
        (:func:`dense_solver`) or, where that cannot be reached, cvxopt's sparse solves;
        ``nnz`` −1 (cvxopt does not report the factor's size).

    Raises
    ------
    RuntimeError
        The matrix is not positive definite (CHOLMOD's message).

    Notes
    -----
    Supernodal factor; the ordering given (the mesh lattice's nested dissection,
    :func:`contact.compliance.fe.elasticity.lattice_dissection`) or CHOLMOD's AMD (cvxopt's
    CHOLMOD has no METIS of its own). Source: Chen, Davis, Hager, Rajamanickam 2008
    (:func:`dense_solver`).
    """
    from cvxopt import cholmod, matrix, spmatrix

    data, indices, indptr, n, ordering = box.pop()
    try:  # the columns copied as they are (cvxopt's triplets sort them: ~1 s, issue 75)
        mat = csc_spmatrix(data, indices, indptr, n)
    except ValueError:
        columns = np.repeat(np.arange(n, dtype=np.int64), np.diff(indptr))
        mat = spmatrix(data, np.asarray(indices, dtype=np.int64), columns, size=(n, n))
        del columns
    del data, indices, indptr
    saved = dict(cholmod.options)
    try:
        cholmod.options["supernodal"] = 2          # supernodal (BLAS-3) numeric factor
        cholmod.options["postorder"] = True
        if ordering is None:
            factor = cholmod.symbolic(mat, uplo="L")
        else:  # the given ordering alone (nmethods 1: not compared with AMD's)
            cholmod.options["nmethods"] = 1
            factor = cholmod.symbolic(mat, p=matrix(np.asarray(ordering, dtype=np.int64)),
                                      uplo="L")
            del ordering
        cholmod.numeric(mat, factor)
    except ArithmeticError as exc:                 # not positive definite: singular K
        raise RuntimeError(f"CHOLMOD: {exc}") from None
    finally:
        cholmod.options.clear()
        cholmod.options.update(saved)
    del mat

    def sparse_solve(b: np.ndarray) -> np.ndarray:
        # cvxopt's cholmod.solve applies the factor one column at a time (its time is
        # linear in the columns: ~0.12 s each on the default pinion model, the factor read
        # from memory twice per column); cholmod.spsolve hands a block of sparse
        # right-hand sides to CHOLMOD's supernodal solve, which takes several columns per
        # pass over the factor: 2.3x faster on these unit loads (a few hundred nonzeros
        # each), the same displacements to 1e-14 relative (issue 60, the cold-run budget).
        # The fallback of the dense block solve below.
        out = np.empty_like(b)
        for start in range(0, b.shape[1], CHOLMOD_BLOCK):
            block = b[:, start:start + CHOLMOD_BLOCK]
            rows, cols = np.nonzero(block)
            if rows.size == 0:
                out[:, start:start + CHOLMOD_BLOCK] = 0.0
                continue
            rhs = spmatrix(block[rows, cols], rows.astype(np.int64), cols.astype(np.int64),
                           size=block.shape)
            x = cholmod.spsolve(factor, rhs, sys=0)
            out[:, start:start + CHOLMOD_BLOCK] = np.asarray(matrix(x))
        return out

    # CHOLMOD's solve of the whole dense block at once (BLAS-3): ~3.4x the sparse solves'
    # speed on the default models, the same displacements to the bit (issue 75); where
    # CHOLMOD's library cannot be reached, or its first solve disagrees, the sparse solves
    dense = [dense_solver(factor, sparse_solve)]

    def solve(b: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        if dense[0] is not None:
            try:
                return dense[0](b) if out is None else dense[0](b, out)
            except RuntimeError as exc:
                log.warning("FE solves: %s; CHOLMOD's sparse solves used instead", exc)
                dense[0] = None
        if out is None:
            return sparse_solve(b)
        out[...] = sparse_solve(b)
        return out

    # cvxopt does not report the factor's size without copying it out (getfactor: ~0.8 s
    # and the factor's memory again): -1, "not reported"
    return solve, -1
