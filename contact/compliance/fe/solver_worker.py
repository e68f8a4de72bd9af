"""The FE build's CHOLMOD worker, a lean process of its own (run as a script).

``python solver_worker.py FD [LABEL ...]``: a connection on file descriptor FD
(:class:`multiprocessing.connection.Connection`) brings the lower triangle of the matrix
(``("cholmod-raw", n, ordered)`` followed by data, indices, indptr and, where ordered,
the ordering, each as :func:`send_array` sends it; or pickled, ``("cholmod", data,
indices, indptr, n, ordering)``, CSC); the worker factorises it
(:func:`contact.compliance.fe.cholmod_dense.cholmod_kernel`), answers ``("ready", nnz,
seconds)`` or ``("error", exception)``, then answers each block of right-hand sides it
receives (a header ``("block", shape, dtype[, "F"])`` and the raw bytes, :func:`send_array`) with
``("ok", shape, dtype)`` and the solution's raw bytes until ``None`` or the end of the
connection; or, after ``("release",)``, frees the factor, answers ``("released",)`` and
waits for the next matrix (a parent's session of builds). Where the request's header
carries a shared memory file (``("cholmod-raw", n,
ordered, fd, columns)``: a descriptor passed to this process, two blocks of n × columns
float64 in Fortran order, :class:`SharedBlocks`), a block is solved in place: the
message ``("shared", k)`` says that the first k columns of the right-hand sides' block
are written, the answer ``("shared-ok", k)`` that the solutions' block holds theirs —
no block through the connection (issue 75, fourth round). LABEL is
not read: the words of the parent's command line, so that the worker is recognisable as
the build's in a process list.

Why a new interpreter and not a fork of the build (issue 75): a forked worker's resident
set starts with every page of its parent (~300 MB: the imported toolkit, the mesh), to
which the factor (~0.6 GB on the default pinion model) is added; this process imports
NumPy and cvxopt only (~30 MB), so the largest process of a cold ``ltca run`` stays near
the factor's own size. The signal handling is the forked worker's
(:func:`contact.compliance.fe.elasticity.factorise`, issue 64): SIGINT ignored (the parent
decides), SIGTERM ends it at once, and it dies with its parent (Linux).
"""

from __future__ import annotations

import gc
import importlib.util
import os
import signal
import sys
import time
from pathlib import Path


def _kernel_module():
    """:mod:`contact.compliance.fe.cholmod_dense` loaded from its file (not through the
    ``contact`` package, whose import pulls in the whole toolkit)."""
    return _module_from(Path(__file__).resolve().with_name("cholmod_dense.py"),
                        "_fe_cholmod_dense")


def set_parent_death_signal() -> None:
    """Linux: the worker is killed when the process that started it dies (a SIGKILL of
    ``ltca run`` leaves no orphan factorising on); elsewhere nothing."""
    if sys.platform != "linux":
        return
    try:
        import ctypes

        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - no libc
        pass


def send_array(conn, tag: str, array) -> None:
    """Send a float array as a small pickled header ``(tag, shape, dtype)`` and its bytes
    raw (:meth:`Connection.send_bytes`): not pickled, so neither side copies it into a
    pickle buffer (a 42 MB block of 64 right-hand sides on the default pinion model;
    pickling and unpickling them took ~3 s of CPU and its page faults per development,
    issue 75). A Fortran-ordered array (CHOLMOD's dense blocks: column after column) is
    sent as it lies, its header ``(tag, shape, dtype, "F")``, instead of transposed into
    C order (~0.05 s per such block). The receiver reads it with :func:`recv_array`."""
    import numpy as np

    a = np.asarray(array)
    if a.ndim > 1 and a.flags.f_contiguous and not a.flags.c_contiguous:
        conn.send((tag, a.shape, a.dtype.str, "F"))
        conn.send_bytes(memoryview(a.T.reshape(-1)).cast("B"))  # a.T: C order, a view
        return
    a = np.ascontiguousarray(a)
    conn.send((tag, a.shape, a.dtype.str))
    conn.send_bytes(memoryview(a.reshape(-1)).cast("B"))


def recv_array(conn, header, out=None):
    """The array whose ``header`` (``(tag, shape, dtype)`` or ``(tag, shape, dtype,
    "F")``, :func:`send_array`) was just received: its bytes read from ``conn`` straight
    into a new array of that order, or into ``out`` (an array of that shape, dtype and
    order, e.g. a block of columns of a Fortran-ordered array)."""
    import numpy as np

    fortran = len(header) > 3 and header[3] == "F"
    if out is None:
        out = np.empty(header[1], dtype=np.dtype(header[2]), order="F" if fortran else "C")
    elif (out.shape != tuple(header[1]) or out.dtype != np.dtype(header[2])
          or not (out.T if fortran else out).flags.c_contiguous):
        raise ValueError("recv_array: the array given does not fit the header "
                         f"{header[1:]}")
    flat = out.T if fortran else out  # C order either way: the bytes' order
    if out.size:
        conn.recv_bytes_into(memoryview(flat.reshape(-1)).cast("B"))
    else:
        conn.recv_bytes()
    return out


class SharedBlocks:
    """Two blocks of ``rows`` × ``columns`` float64 in Fortran order on a shared memory
    file (Linux's ``memfd_create``), mapped by the FE build and its solver worker: the
    right-hand sides (``rhs``) and the solutions (``solution``) of a block of unit loads,
    written and read in place by both processes instead of sent through the connection
    (two copies through the kernel per block and direction; issue 75, fourth round).

    Parameters
    ----------
    fd : int — the file's descriptor (the file sized here where ``create``)
    rows, columns : int — [1] the blocks' shape
    create : bool — size the file (the build's side)
    """

    def __init__(self, fd: int, rows: int, columns: int, *, create: bool = False) -> None:
        import mmap

        import numpy as np

        size = 2 * rows * columns * 8
        if create:
            import os

            os.ftruncate(fd, size)
        self.fd, self.rows, self.columns = fd, rows, columns
        self._map = mmap.mmap(fd, size) if size else None
        blocks = (np.frombuffer(self._map, dtype=np.float64).reshape(2, columns, rows)
                  if size else np.empty((2, columns, rows)))
        self.rhs = blocks[0].T  # (rows, columns), Fortran order
        self.solution = blocks[1].T

    def close(self) -> None:
        """Unmap the file (the arrays must no longer be used)."""
        self.rhs = self.solution = None
        if self._map is not None:
            try:
                self._map.close()
            except BufferError:  # a view still exported: freed with the process
                pass
            self._map = None


def _module_from(path: Path, name: str):
    """A module loaded from its file (not through its package, whose import pulls in the
    whole toolkit)."""
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def keep_heap_pages() -> bool:
    """:func:`geometry.core.heap.keep_heap_pages`, loaded from its file (this worker
    imports no package of the toolkit): the solves' blocks reuse the process's pages.
    The worker calls it once its factor is made; ``ltca synthesize`` and ``ltca run``
    call it at their start."""
    path = Path(__file__).resolve().parents[3] / "geometry" / "core" / "heap.py"
    return _module_from(path, "_fe_heap").keep_heap_pages()


def heap_pages_back() -> bool:
    """glibc only: undo :func:`keep_heap_pages` — large blocks mapped per allocation again,
    freed memory given back to the system (glibc's defaults: ``M_MMAP_MAX`` 65536,
    ``M_TRIM_THRESHOLD`` 128 KiB) and the free pages held now returned
    (``malloc_trim(0)``). The worker calls it once a factor is released: the next
    factorisation's transient memory is mapped and given back as in a new worker, so
    that its peak is a new worker's (kept, the pages of the factor before fragmented the
    heap: 0.83 → 0.97 GB on the default case's gear, issue 75). False where not glibc."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None)
        mallopt, trim = libc.mallopt, libc.malloc_trim
    except (OSError, AttributeError):  # pragma: no cover - not glibc
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    trim.argtypes, trim.restype = [ctypes.c_size_t], ctypes.c_int
    m_trim_threshold, m_mmap_max = -1, -4
    done = bool(mallopt(m_mmap_max, 65536)) and bool(mallopt(m_trim_threshold, 128 * 1024))
    trim(0)
    return done


def serve(conn, kernel, box: list, shared: SharedBlocks | None = None) -> str:
    """Factorise the matrix in ``box`` with ``kernel`` (its solve and the factor's nonzeros),
    report ``("ready", nnz, seconds)`` or ``("error", exception)``, then answer each block
    of right-hand sides received on ``conn`` (:func:`send_array`'s header and bytes, or a
    pickled array) with the solution (:func:`send_array`, tag ``"ok"``) or ``("error",
    exception)`` until ``None`` or the end of the connection; with ``shared`` blocks,
    ``("shared", k)`` is answered by solving the first k columns of ``shared.rhs`` into
    ``shared.solution`` and ``("shared-ok", k)``. The loop of this lean worker and of
    the forked one (:func:`contact.compliance.fe.elasticity.factorise`).

    Returns ``"release"`` where ``("release",)`` ended the loop (the factor is freed on
    return and the lean worker waits for another matrix: :func:`main`), else ``"end"``."""
    try:
        t0 = time.perf_counter()
        solve, nnz = kernel(box)
        keep_heap_pages()  # the solves' blocks reuse their pages (the factor is made)
        conn.send(("ready", nnz, time.perf_counter() - t0))
    except Exception as exc:  # handed to the parent, which raises it
        conn.send(("error", exc))
        return "end"
    while True:
        try:
            block = conn.recv()
        except (EOFError, OSError):
            return "end"
        if block is None:
            return "end"
        if isinstance(block, tuple) and block == ("release",):  # the factor freed;
            # another matrix may follow (main)
            return "release"
        if shared is not None and isinstance(block, tuple) and block[:1] == ("shared",):
            k = int(block[1])
            try:
                solve(shared.rhs[:, :k], out=shared.solution[:, :k])
            except Exception as exc:  # the parent raises it
                conn.send(("error", exc))
                continue
            conn.send(("shared-ok", k))
            continue
        try:
            if isinstance(block, tuple) and block and block[0] == "block":
                block = recv_array(conn, block)  # the right-hand sides' raw bytes
            x = solve(block)
        except Exception as exc:  # the parent raises it
            conn.send(("error", exc))
            continue
        del block
        send_array(conn, "ok", x)


def one_blas_thread() -> str | None:
    """NumPy's BLAS in this worker with the toolkit's thread count, set before NumPy is
    imported: CHOLMOD's own BLAS (cvxopt's OpenBLAS) is single-threaded, and NumPy's
    serves the forward solves' products here
    (:class:`contact.compliance.fe.cholmod_dense.SupernodalForward`), which a second
    thread would only spin on (docs/performance.md, "One BLAS thread").
    ``HYPOID_LTCA_BLAS_THREADS`` first (``0``: as the library has it), else one thread
    where neither ``OPENBLAS_NUM_THREADS``, ``OMP_NUM_THREADS`` nor ``MKL_NUM_THREADS``
    is set (the parent's ``ltca`` command has set them already). Returns the count set,
    or None where the environment's stands."""
    given = (os.environ.get("HYPOID_LTCA_BLAS_THREADS") or "").strip()
    if given:
        if given == "0" or not given.isdigit():
            return None
        os.environ["OPENBLAS_NUM_THREADS"] = given
        return given
    if ((os.environ.get("OPENBLAS_NUM_THREADS") or "").strip()
            or (os.environ.get("OMP_NUM_THREADS") or "").strip()
            or (os.environ.get("MKL_NUM_THREADS") or "").strip()):
        return None
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    return "1"


def main(argv: list[str]) -> None:
    """Serve the connection on file descriptor ``argv[0]`` (module docstring)."""
    from multiprocessing.connection import Connection

    one_blas_thread()  # before NumPy is imported
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})
    set_parent_death_signal()
    gc.disable()  # few objects of its own; the arrays are freed by reference counts
    conn = Connection(int(argv[0]))
    shared = None
    # one matrix after another: a build of both members (a session of the parent,
    # contact.compliance.fe.elasticity.worker_session) releases a factor and sends the
    # next matrix to this same process — no second interpreter and its imports, and the
    # next factor on the pages the last one had (issue 75)
    while True:
        try:
            request = conn.recv()
        except (EOFError, OSError):
            return
        if request is None:
            return
        if request[0] == "cholmod-raw":  # ("cholmod-raw", n, ordered[, fd, columns]), then
            arrays = [recv_array(conn, conn.recv()) for _ in range(4 if request[2] else 3)]
            box = [(*arrays[:3], request[1], arrays[3] if request[2] else None)]
            del arrays
            if len(request) > 3:  # the blocks on a shared memory file (SharedBlocks),
                if shared is not None:  # resized by the parent for this matrix
                    shared.close()
                shared = SharedBlocks(int(request[3]), int(request[1]), int(request[4]))
        else:  # ("cholmod", data, indices, indptr, n, ordering), pickled
            box = [tuple(request[1:])]
        del request
        if serve(conn, lambda b: _kernel_module().cholmod_kernel(b), box, shared) != "release":
            return
        heap_pages_back()  # the factor is freed: the next one starts as in a new worker
        conn.send(("released",))


if __name__ == "__main__":
    sys.path.pop(0)  # this file's directory: its modules must not shadow any other
    main(sys.argv[1:])
