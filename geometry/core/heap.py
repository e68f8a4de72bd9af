"""glibc's heap kept for a process's large arrays (standard library only).

Public names
------------
keep_heap_pages  no memory mapped per allocation and none given back to the system

This module imports nothing but the standard library: the FE build's lean solver worker
(:mod:`contact.compliance.fe.solver_worker`) loads it from its file.
"""

from __future__ import annotations

import sys

__all__ = ["keep_heap_pages"]


def keep_heap_pages() -> bool:
    """glibc only: from now on, no memory mapped per allocation and none given back to the
    system (``mallopt(M_MMAP_MAX, 0)``, ``mallopt(M_TRIM_THRESHOLD, 2**31 - 1)``).

    Blocks of the same size allocated and freed again and again (the FE solves'
    right-hand sides and solutions, 42 MB each on the default pinion model; the stiffness
    assembly's element blocks; an analysis's grids) then reuse the pages the process has
    instead of mapping and faulting in fresh zeroed ones each time: glibc maps every
    block above its mmap threshold (at most 32 MB) on its own and unmaps it when freed.

    Returns
    -------
    bool
        True where set (Linux with glibc), False elsewhere (nothing changed).

    Notes
    -----
    Measured (issue 75, docs/performance.md): the FE solver worker calls it once its
    factor is made (the factorisation's transient memory mapped and given back as
    before: its peak unchanged); ``ltca synthesize`` at its start (the 9x41 hypoid: 26 →
    6 s of system time with the worker's, the peak the same 1.12 GB); ``ltca run`` run
    as its own process at its start (the cold first run of the default case: the
    parent's system time 4.2 → 1.8 s, its peak 688 → 714 MB, below the worker's).
    Source: the GNU C Library manual, "Malloc Tunable Parameters".
    """
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None)
        mallopt = libc.mallopt
    except (OSError, AttributeError):  # pragma: no cover - not glibc
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    m_trim_threshold, m_mmap_max = -1, -4
    return bool(mallopt(m_mmap_max, 0)) and bool(mallopt(m_trim_threshold, 2**31 - 1))
