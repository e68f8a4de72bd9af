"""How many threads the BLAS libraries of NumPy and SciPy use while the toolkit computes.

The toolkit's dense linear algebra is small: a contact problem's compliance matrix has a
few hundred rows (LAPACK's Cholesky check, the QP backends' factorisations), the synthesis'
least-squares Jacobians are 3 × 3 to 5 × 5. On such matrices a second OpenBLAS thread
only waits for work, spinning: it doubles the CPU time without shortening the wall time,
and where other processes share the cores (a study's Dask workers, pytest-xdist, a loaded
machine) it lengthens the wall time as well. Measured on a shared 2-core machine: the
development of the passenger-car hypoid 10×43 (``ltca synthesize``) 45 → 16 s of CPU, of
which LAPACK's ``potrf`` on the contact matrices (N < 200) 10.5 → 0.02 s; LTCA and study
tests 112 → 50 s wall; a cold ``ltca run`` (its FE build's CHOLMOD uses its own,
single-threaded BLAS) unchanged. So while the toolkit's entry points run
(:func:`contact.pipeline.run_analysis`, the development, the ``ltca`` command), both
libraries use one thread, and get their own setting back afterwards.

The user's choice wins: where ``OPENBLAS_NUM_THREADS``, ``OMP_NUM_THREADS``,
``MKL_NUM_THREADS`` or ``HYPOID_LTCA_BLAS_THREADS`` is set in the environment, the limit is
that number (``HYPOID_LTCA_BLAS_THREADS`` first; ``0`` leaves the libraries as they are).
Dask's workers are started with one BLAS thread by ``distributed`` already.

Public names
------------
blas_threads   context manager: the BLAS thread limit of the toolkit's computations
limit_at_start the same limit as start-up variables, for the ``ltca`` command
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Iterator

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["blas_threads", "limit_at_start"]

def _limit_from_environment() -> int | None:
    """The limit the environment asks for: 1 where it says nothing, None for ``0``."""
    # (each read by its name, as docs/environment.md lists them: tests/test_global_state.py)
    given = (("HYPOID_LTCA_BLAS_THREADS", os.environ.get("HYPOID_LTCA_BLAS_THREADS")),
             ("OPENBLAS_NUM_THREADS", os.environ.get("OPENBLAS_NUM_THREADS")),
             ("MKL_NUM_THREADS", os.environ.get("MKL_NUM_THREADS")),
             ("OMP_NUM_THREADS", os.environ.get("OMP_NUM_THREADS")))
    for name, value in given:
        text = (value or "").strip()
        if not text:
            continue
        try:
            value = int(text)
        except ValueError:
            raise InputError(f"{name}: must be a whole number of threads (0 = as the "
                             f"library has it), got {text!r}") from None
        if value < 0:
            raise InputError(f"{name}: must be >= 0 (0 = as the library has it), got {value}")
        return value or None
    return 1


def limit_at_start() -> int | None:
    """At an application's start (the ``ltca`` command, before NumPy is imported): the
    limit of :func:`blas_threads` as OpenBLAS's and MKL's start-up variables, so that
    every BLAS the process loads starts with it, without importing one here (a command
    that needs no NumPy stays light).

    Returns
    -------
    int or None
        The limit set, or None where the environment asks for none or NumPy or SciPy is
        already loaded (then :func:`blas_threads` limits the loaded libraries).

    Raises
    ------
    InputError
        As :func:`blas_threads`, for a variable that is not a whole number >= 0.
    """
    limit = _limit_from_environment()
    if limit is None or {"numpy", "scipy"} & sys.modules.keys():
        return None
    os.environ["OPENBLAS_NUM_THREADS"] = str(limit)
    os.environ["MKL_NUM_THREADS"] = str(limit)
    return limit


@contextlib.contextmanager
def blas_threads(limit: int | None = None) -> Iterator[int | None]:
    """Limit the threads of NumPy's and SciPy's BLAS while the block runs.

    Parameters
    ----------
    limit : int, optional
        Threads [1]; default the environment's choice (module docstring: 1 where nothing
        is set). ``0`` or a limit the environment turns into None: no limit.

    Yields
    ------
    int or None
        The limit in force (None: the libraries as they were).

    Raises
    ------
    InputError
        A negative ``limit``, or an environment variable of the module docstring that is not a
        whole number >= 0.

    Notes
    -----
    threadpoolctl (``threadpool_limits(user_api="blas")``) sets the libraries loaded when
    the block starts, so SciPy's linear algebra, which brings its own OpenBLAS, is
    imported first; the previous settings are restored on leaving (no global state).
    """
    if limit is None:
        limit = _limit_from_environment()
    elif int(limit) < 0:
        raise InputError(f"limit: must be >= 0 BLAS threads (0 = as the library has it), "
                         f"got {limit}")
    limit = int(limit) or None if limit is not None else None
    if limit is None:
        yield None
        return
    import numpy  # noqa: F401 - loads NumPy's BLAS, so that threadpoolctl sees it
    import scipy.linalg  # noqa: F401 - loads SciPy's own BLAS

    with _controller(len(sys.modules)).limit(limits=limit, user_api="blas"):
        yield limit


@memoised(maxsize=1)
def _controller(n_modules: int):
    """threadpoolctl's view of the BLAS libraries loaded (a ``ThreadpoolController``), made
    again only when modules were imported since (``n_modules``: ``len(sys.modules)``, the
    key; a library comes with the module that loads it).

    Making one lists and inspects every shared library of the process: ~3 ms, each time
    ``threadpool_limits`` is entered, i.e. at every analysis (0.7 % of a study point);
    the limit set on a kept controller is 0.03 ms, the same libraries set the same way.
    """
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()
