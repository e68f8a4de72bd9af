"""Test-suite configuration.

BLAS is limited to one thread: the suite's matrices are small, and on a shared
2-core machine a multi-threaded BLAS oversubscribes the cores (a shell-model build
measured 0.02 s single-threaded and 0.3–0.7 s threaded under load).

The FE influence coefficients' cache (root stress, on by default in ``ltca run``, issue 53)
is one directory for the whole session and every xdist worker, beside pytest's own cache
(``.pytest_cache/hypoid-ltca-fe``), unless ``HYPOID_LTCA_CACHE`` is set: a design's
coefficients are built once per session (once ever on a developer's machine), never in the
user's own cache. Tests that need an empty cache set their own (monkeypatch).

The default ``ltca run`` (``default_run_file``) is run once per session, by the first
xdist worker that needs it (the golden-file test, the plots' global-state test and the
friction model's range check read it): ``tests/golden.py``'s ``shared_default_run``.

A shell that starts pytest as a background job without job control (``pytest &`` in a
script, ``(cmd &)``) starts it with SIGINT ignored, and an ignored SIGINT is inherited
through ``exec`` by every ``ltca`` the tests start: the tests of Ctrl-C (the held signal of
an atomic write, a build interrupted in the FE cache, a signal during ``ltca run``'s write)
then wait for a run that never stops. Python's own handler is put back here, as an
interactive shell would have it (seen in a fresh-clone CI run started with ``&``: three
signal tests failed, one after its 300 s safety bound).
"""

import os
import signal
from pathlib import Path

import numpy  # noqa: F401 - loads NumPy's BLAS, so that the limit below reaches it
import pytest
import scipy.linalg  # noqa: F401 - loads SciPy's own BLAS (LAPACK's potrf, the QPs)
from threadpoolctl import threadpool_limits

# One BLAS thread per process: xdist runs a worker per core, and a second BLAS thread per
# worker only spins on the small dense matrices of the contact problems (measured on 2
# cores: tests/test_ltca*.py + test_study.py 112 -> 50 s wall, 125 -> 51 s CPU, when
# SciPy's BLAS, loaded after this file, kept its 2 threads). threadpoolctl limits only the
# libraries already loaded, hence the imports above; the subprocesses of the CLI tests
# start their BLAS with the variable.
threadpool_limits(limits=1, user_api="blas")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

os.environ.setdefault(
    "HYPOID_LTCA_CACHE",
    str(Path(__file__).resolve().parents[1] / ".pytest_cache" / "hypoid-ltca-fe"))


@pytest.fixture(scope="session")
def default_run_file(tmp_path_factory) -> Path:
    """The netCDF file of the default ``ltca run`` (no arguments), shared by the session's
    xdist workers (their base temporary directories have one parent)."""
    from golden import shared_default_run

    base = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        base = base.parent
    return shared_default_run(base / "default-run")


@pytest.fixture(autouse=True)
def _kernels_choice_restored():
    """A command run in-process (``ltca synthesize``, a study …) sets ``LTCA_KERNELS=numba``
    for its process (``geometry.core.kernels.prefer_compiled``): restored after each test,
    so that no test passes its choice on to the next."""
    before = os.environ.get("LTCA_KERNELS")
    yield
    if before is None:
        os.environ.pop("LTCA_KERNELS", None)
    else:
        os.environ["LTCA_KERNELS"] = before
