"""The CPU of this process together with the FE solver workers it started.

``time.process_time()`` counts this process only. The FE build's CHOLMOD factor lives in a
worker process of its own (:class:`contact.compliance.fe.elasticity._LeanWorker`), which a
worker session keeps alive between factorisations; its CPU enters
``resource.RUSAGE_CHILDREN`` only once it has ended and been waited for. A clock that reads
``process_time`` alone printed ``ltca synthesize``'s development CPU as roughly half of what
the command costs where the development builds FE models (issue 71, Round 39: the FH hypoid
12×41 at Σ 110°, 36.1 s in the parent, 37.1 s in its worker, 33.9 s printed).

:func:`cpu_seconds` is this process's CPU, plus its ended and waited-for children's, plus
the CPU the live lean workers have spent so far (Linux: ``/proc/<pid>/stat``). A worker's
CPU moves from the third term to the second when it is reaped, so differences of the clock
count every second once.
"""

from __future__ import annotations

import os
import sys
import time
import weakref

__all__ = ["cpu_seconds", "live_workers_cpu_seconds", "register_worker"]

#: the lean workers started by this process and not yet collected (weak: the registry keeps
#: no worker alive)
_LIVE: weakref.WeakSet = weakref.WeakSet()


def register_worker(worker) -> None:
    """Count ``worker`` in :func:`live_workers_cpu_seconds` while it lives: an object with
    the process id ``pid`` and ``is_alive()`` (a :class:`multiprocessing.Process`, the lean
    worker's :class:`subprocess.Popen` handle), which reaps an ended process — its CPU then
    counts in ``RUSAGE_CHILDREN``."""
    _LIVE.add(worker)


def _proc_cpu(pid: int) -> float:
    """CPU seconds (user + system) of a live process ``pid`` from ``/proc/<pid>/stat``;
    0 where it cannot be read (ended, another system)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            text = f.read().decode("ascii", "replace")
    except OSError:
        return 0.0
    fields = text[text.rfind(")") + 2:].split()  # after "pid (comm) "
    try:
        ticks = int(fields[11]) + int(fields[12])  # utime, stime: stat fields 14 and 15
    except (IndexError, ValueError):
        return 0.0
    return ticks / os.sysconf("SC_CLK_TCK")


def live_workers_cpu_seconds() -> float:
    """CPU seconds [s] the registered workers still running (not yet waited for) have
    spent so far. Linux only (``/proc``); 0 elsewhere."""
    if not sys.platform.startswith("linux"):
        return 0.0
    total = 0.0
    for worker in list(_LIVE):
        pid = getattr(worker, "pid", None)
        if pid is not None and worker.is_alive():
            total += _proc_cpu(int(pid))
    return total


def cpu_seconds() -> float:
    """CPU seconds [s] (user + system) of this process, its ended children and the live
    FE solver workers (:func:`live_workers_cpu_seconds`); a clock for differences, as
    ``time.process_time`` (where ``resource`` is missing, Windows: this process only)."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        return time.process_time()
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (time.process_time() + children.ru_utime + children.ru_stime
            + live_workers_cpu_seconds())
