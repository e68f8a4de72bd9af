"""The development's CPU clock counts the FE solver workers (issue 71, Round 39).

``ltca synthesize`` printed its development's CPU from ``time.process_time()``, which left
out the CHOLMOD worker process a worker session keeps alive (the FH hypoid 12×41 at Σ 110°:
36.1 s in the parent, 37.1 s in its worker, 33.9 s printed). The identity tested here: a
registered child's CPU, read from the kernel's own accounting, enters
:func:`contact.compliance.fe.worker_cpu.cpu_seconds` while it runs and stays counted once
it is reaped (moved to ``RUSAGE_CHILDREN``), never twice.
"""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

from contact.compliance.fe import worker_cpu
from contact.compliance.fe.elasticity import _Child

#: the child burns this much CPU [s] and then waits on its stdin
_BURN = 0.6

_SCRIPT = (f"import sys, time\nt = time.process_time()\n"
           f"while time.process_time() - t < {_BURN}: pass\n"
           "print('done', flush=True)\nsys.stdin.read()\n")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc is Linux's")
def test_a_live_worker_counts_and_a_reaped_one_is_not_counted_twice():
    before = worker_cpu.cpu_seconds()
    own_before = time.process_time()
    popen = subprocess.Popen([sys.executable, "-c", _SCRIPT], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, text=True)
    child = _Child(popen)  # registers itself, as the lean FE worker's handle does
    try:
        assert popen.stdout.readline().strip() == "done"
        # the child spent at least _BURN of CPU in its loop (its own process_time); the
        # kernel's tick accounting reads it to a tick (1/CLK_TCK, 10 ms): 0.05 s of slack
        assert worker_cpu.live_workers_cpu_seconds() >= _BURN - 0.05
        child_alive = worker_cpu.cpu_seconds() - before - (time.process_time() - own_before)
        assert child_alive >= _BURN - 0.05
    finally:
        popen.stdin.close()
        child.join(30)
    assert not child.is_alive()
    child_reaped = worker_cpu.cpu_seconds() - before - (time.process_time() - own_before)
    # reaped: its CPU comes from RUSAGE_CHILDREN now, once: what it spent after "done"
    # (reading an empty stdin, the interpreter's exit) is well under 0.3 s, while a count
    # in both terms would add the whole _BURN (0.6 s) again
    assert child_alive - 0.05 <= child_reaped <= child_alive + 0.3


def test_an_unregistered_or_ended_pid_reads_zero():
    class Gone:
        pid = 2 ** 22 + 12345  # above Linux's default pid_max: no such process

        def is_alive(self):
            return True

    gone = Gone()
    worker_cpu.register_worker(gone)
    assert worker_cpu._proc_cpu(gone.pid) == 0.0
