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
FORWARD_SHARE  the factor's share a sparse block's forward solve may reach to be ours
SupernodalForward  the forward solve over the supernodes a sparse block reaches
"""

from __future__ import annotations

import ctypes
import logging
import sys
from collections.abc import Callable

import numpy as np

__all__ = ["CHOLMOD_BLOCK", "FORWARD_SHARE", "SupernodalForward", "cholmod_kernel",
           "csc_spmatrix", "dense_solver"]

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


class _Factor(ctypes.Structure):
    """``cholmod_factor`` (SuiteSparse 4–7, CHOLMOD 2–5: the same layout), read only by
    :class:`SupernodalForward` after the checks of :func:`_supernodal_arrays`."""

    _fields_ = ([(name, ctypes.c_size_t) for name in ("n", "minor")]
                + [(name, ctypes.c_void_p) for name in ("Perm", "ColCount", "IPerm")]
                + [("nzmax", ctypes.c_size_t)]
                + [(name, ctypes.c_void_p) for name in ("p", "i", "x", "z", "nz", "next",
                                                        "prev")]
                + [(name, ctypes.c_size_t) for name in ("nsuper", "ssize", "xsize",
                                                        "maxcsize", "maxesize")]
                + [(name, ctypes.c_void_p) for name in ("super", "pi", "px", "s")]
                + [(name, ctypes.c_int) for name in ("ordering", "is_ll", "is_super",
                                                     "is_monotonic", "itype", "xtype",
                                                     "dtype", "useGPU")])


_LONG = 2  # CHOLMOD_LONG: the factor's integers are int64 (cholmod_l_*)
_SOLVE_LT = 5  # CHOLMOD_Lt: x = L' \ b, no permutation
#: [1] share of the factor's entries above which a block's forward solve is left to
#: CHOLMOD's own (``cholmod_l_solve`` of A): ours gains only where it skips most of it
FORWARD_SHARE = 0.5


def _int64_view(address: int, size: int) -> np.ndarray:
    return np.ctypeslib.as_array(ctypes.cast(address, ctypes.POINTER(ctypes.c_int64)),
                                 shape=(size,))


def _supernodal_arrays(pointer: int) -> dict | None:
    """The supernodal LLᵀ factor at ``pointer`` as NumPy views (``Perm``, ``super``,
    ``pi``, ``px``, ``s``, the values' address), or None where it is not one this module
    can read: not supernodal LLᵀ of doubles with 64-bit integers, or arrays that do not
    hold together (a permutation, increasing supernodes, rows and values within their
    sizes, each supernode's rows starting with its own columns)."""
    try:
        f = _Factor.from_address(pointer)
        n, ns = int(f.n), int(f.nsuper)
        if not (f.is_super == 1 and f.is_ll == 1 and f.itype == _LONG
                and f.xtype == _REAL and f.dtype == _DOUBLE and n > 0 and 0 < ns <= n
                and f.Perm and f.super and f.pi and f.px and f.s and f.x):
            return None
        perm = _int64_view(f.Perm, n).copy()
        sup = _int64_view(f.super, ns + 1).copy()
        pi = _int64_view(f.pi, ns + 1).copy()
        px = _int64_view(f.px, ns + 1).copy()
        ncol, nrow = np.diff(sup), np.diff(pi)
        if (sup[0] != 0 or sup[-1] != n or np.any(ncol <= 0) or pi[0] != 0
                or pi[-1] > int(f.ssize) or np.any(nrow < ncol) or px[0] != 0
                or np.any(np.diff(px) != nrow * ncol) or px[-1] > int(f.xsize)
                or np.bincount(perm, minlength=n).max(initial=0) != 1
                or perm.min() < 0 or perm.max() >= n):
            return None
        rows = _int64_view(f.s, int(pi[-1])).copy()
        # each supernode's first rows are its own columns (the diagonal block)
        own = np.repeat(pi[:-1], ncol) + (np.arange(n) - np.repeat(sup[:-1], ncol))
        if not np.array_equal(rows[own], np.arange(n)):
            return None
        return {"perm": perm, "super": sup, "pi": pi, "px": px, "rows": rows,
                "x": int(f.x), "xsize": int(f.xsize)}
    except (ValueError, TypeError, OSError, OverflowError):  # pragma: no cover
        return None


class SupernodalForward:
    """The forward solve L y = P b of a supernodal CHOLMOD factor for right-hand sides
    that are zero on most rows, visiting only the supernodes on whose columns y is not
    zero: the ancestors, in the factor's elimination tree, of the supernodes holding the
    rows where b is not zero (Gilbert 1994: the non-zeros of L⁻¹b are the closure of b's
    under the tree's parent relation).

    The FE build's unit loads sit on one flank of one tooth, and on the default models the
    supernodes they reach hold ~18 % of the factor's entries (issue 75): the forward
    half of each solve costs a fifth of CHOLMOD's own (which runs every supernode
    whatever the right-hand side), the backward half stays CHOLMOD's (``CHOLMOD_Lt``).
    The diagonal blocks are solved by the BLAS CHOLMOD itself calls (``dtrsm_`` of the
    library it was linked with), the rows below them updated by NumPy's (a matrix
    product), both in the factor's own memory (no copy).

    Parameters
    ----------
    lib : ctypes.CDLL — the CHOLMOD library the factor belongs to
    arrays : dict — :func:`_supernodal_arrays` of the factor

    Raises
    ------
    AttributeError — ``dtrsm_`` cannot be reached through ``lib``.

    Notes
    -----
    Source: J. R. Gilbert 1994, "Predicting structure in sparse matrix computations",
    *SIAM J. Matrix Anal. Appl.* 15(1) 62–79; the supernodal layout of T. A. Davis,
    *CHOLMOD User Guide* (``cholmod_factor``: ``super``, ``pi``, ``px``, ``s``, ``x``).
    """

    def __init__(self, lib, arrays: dict) -> None:
        self.trsm = lib.dtrsm_
        char, ref = ctypes.c_char_p, ctypes.c_void_p
        self.trsm.restype = None
        self.trsm.argtypes = [char, char, char, char, ref, ref, ref, ref, ref, ref, ref]
        self.perm = arrays["perm"]
        self.n = self.perm.size
        self.iperm = np.empty_like(self.perm)
        self.iperm[self.perm] = np.arange(self.n)
        self.sup, self.pi, self.px = arrays["super"], arrays["pi"], arrays["px"]
        self.rows, self.x = arrays["rows"], arrays["x"]
        self.values = np.ctypeslib.as_array(  # the factor's values, in place
            ctypes.cast(self.x, ctypes.POINTER(ctypes.c_double)), shape=(int(self.px[-1]),))
        ncol, nrow = np.diff(self.sup), np.diff(self.pi)
        self.ncol, self.nrow = ncol, nrow
        self.col_super = np.repeat(np.arange(ncol.size), ncol)
        first_below = self.rows[np.minimum(self.pi[:-1] + ncol, self.pi[-1] - 1)]
        self.parent = np.where(nrow > ncol, self.col_super[first_below], -1)
        self.work = (nrow * ncol).astype(np.float64)  # the entries each supernode holds
        self.total = float(self.work.sum())

    def reached(self, nonzero_rows: np.ndarray) -> np.ndarray:
        """The supernodes (increasing) on whose columns L⁻¹Pb is not zero, for b not
        zero on ``nonzero_rows`` (rows of A)."""
        mark = np.zeros(self.ncol.size, dtype=bool)
        parent = self.parent
        for s in np.unique(self.col_super[self.iperm[nonzero_rows]]).tolist():
            while s >= 0 and not mark[s]:
                mark[s] = True
                s = int(parent[s])
        return np.flatnonzero(mark)

    def share(self, supernodes: np.ndarray) -> float:
        """The share [1] of the factor's entries held by ``supernodes``."""
        return float(self.work[supernodes].sum()) / self.total

    def __call__(self, b: np.ndarray, nonzero_rows: np.ndarray,
                 supernodes: np.ndarray) -> np.ndarray:
        """y = L⁻¹ P b (n, k) [float64, Fortran order] for b (n, k), not zero on
        ``nonzero_rows`` only, over ``supernodes`` (:meth:`reached`)."""
        n, k = b.shape
        y = np.zeros((n, k), order="F")
        y[self.iperm[nonzero_rows]] = b[nonzero_rows]
        c_int = ctypes.c_int
        one, ld_y, k_c = ctypes.c_double(1.0), c_int(n), c_int(k)
        base = y.ctypes.data
        for s in supernodes.tolist():
            first, nc, nr = int(self.sup[s]), int(self.ncol[s]), int(self.nrow[s])
            at = int(self.px[s])  # the supernode's (nr, nc) block, by columns
            ys = y[first:first + nc]  # its rows of y: (nc, k), leading dimension n
            self.trsm(b"L", b"L", b"N", b"N", ctypes.byref(c_int(nc)), ctypes.byref(k_c),
                      ctypes.byref(one), self.x + 8 * at, ctypes.byref(c_int(nr)),
                      base + 8 * first, ctypes.byref(ld_y))
            if nr > nc:  # the rows below: NumPy's BLAS (~3x the speed of cvxopt's
                # bundled one on the 2-core machine, issue 75), both operands in place
                below = self.values[at:at + nr * nc].reshape(nc, nr)[:, nc:].T
                rows = self.rows[int(self.pi[s]) + nc:int(self.pi[s + 1])]
                y[rows] -= below @ ys
        return y


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
        ``cholmod_l_solve`` (``CHOLMOD_A``) on the whole block (supernodal, BLAS-3); or,
        where b is zero on rows whose supernodes hold all but at most
        :data:`FORWARD_SHARE` of the factor (the FE build's unit loads: ~18 %), the
        forward solve over those supernodes only (:class:`SupernodalForward`) and
        CHOLMOD's backward solve (``CHOLMOD_Lt``), checked once against ``reference``
        like the whole solve (a disagreement drops it with a warning); or None where
        CHOLMOD's library cannot be reached here (not Linux, another cvxopt build, an
        unexpected capsule): the caller keeps cvxopt's solves.

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
    arrays = _supernodal_arrays(pointer)
    try:
        forward = [SupernodalForward(lib, arrays) if arrays is not None else None]
    except AttributeError:  # pragma: no cover - no BLAS reachable through CHOLMOD's library
        forward = [None]
    del arrays
    checked: dict[str, bool] = {}

    def cholmod_solve(system: int, rhs: np.ndarray, n: int, k: int) -> np.ndarray:
        """CHOLMOD's solve of ``system`` on the Fortran block ``rhs``: its result's (k,
        n) view by columns and the block to free (:func:`cholmod_l_free_dense`)."""
        block = _Dense(n, k, n * k, n, rhs.ctypes.data, None, _REAL, _DOUBLE)
        x = solve_c(system, pointer, ctypes.byref(block), common)
        if not x:
            raise RuntimeError("CHOLMOD: cholmod_l_solve failed (out of memory?)")
        d = x.contents
        if (d.nrow, d.ncol) != (n, k) or d.xtype != _REAL:
            free(ctypes.byref(x), common)
            raise RuntimeError("CHOLMOD: cholmod_l_solve returned an unexpected block")
        flat = np.ctypeslib.as_array(ctypes.cast(d.x, ctypes.POINTER(ctypes.c_double)),
                                     shape=(k * d.d,))
        return flat.reshape(k, d.d)[:, :n], x

    def check(what: str, rhs: np.ndarray, out: np.ndarray) -> bool:
        """Whether ``out``'s first column agrees with cvxopt's own solve (once per way)."""
        if what in checked:
            return checked[what]
        ref = reference(np.ascontiguousarray(rhs[:, :1]))
        scale = float(np.abs(ref).max()) or 1.0
        checked[what] = float(np.abs(out[:, :1] - ref).max()) <= CHECK_TOLERANCE * scale
        return checked[what]

    def solve(b: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        rhs = np.asfortranarray(b, dtype=np.float64)
        n, k = rhs.shape
        if out is not None and (out.shape != (n, k) or out.dtype != np.float64
                                or not out.flags.f_contiguous):
            raise ValueError("solve: out must be a float64 array of the block's shape in "
                             "Fortran order")
        if k == 0:
            return np.empty((n, 0)) if out is None else out
        if out is None:
            out = np.empty((n, k), order="F")
        if forward[0] is not None:
            # right-hand sides on a few rows (the unit loads on one flank, issue 75): the
            # forward solve over the supernodes they reach, then CHOLMOD's backward solve
            fw = forward[0]
            nonzero = np.flatnonzero(np.any(rhs != 0.0, axis=1))
            reached = fw.reached(nonzero)
            if fw.share(reached) <= FORWARD_SHARE:
                y = fw(rhs, nonzero, reached)
                z, x = cholmod_solve(_SOLVE_LT, y, n, k)
                try:
                    del y
                    out.T[:, fw.perm] = z  # x = Pᵀ z (by columns: contiguous)
                finally:
                    free(ctypes.byref(x), common)
                if check("forward", rhs, out):
                    return out
                log.warning("FE solves: the forward solve over the loaded supernodes "
                            "differs from cvxopt's; CHOLMOD's whole solve used instead")
                forward[0] = None
        z, x = cholmod_solve(0, rhs, n, k)  # 0: CHOLMOD_A, A x = b
        try:
            # copied column after column (Fortran order, as CHOLMOD lays it out): no
            # transposition (~0.05 s per block of 64 on the default pinion model), into
            # ``out`` (the solver worker's shared block, issue 75)
            np.copyto(out.T, z)
        finally:
            free(ctypes.byref(x), common)
        if not check("whole", rhs, out):
            raise RuntimeError("CHOLMOD's dense solve differs from cvxopt's (an "
                               "incompatible library)")
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
