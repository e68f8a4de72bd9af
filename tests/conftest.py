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


#: the test files of the most CPU, most first (measured one file at a time on a cold FE
#: cache, ``-n 0``, after the cuts of the suite75 branch: seconds of CPU in the comments).
#: pytest-xdist's ``--dist loadfile`` hands the files to its workers in collection order
#: (``--no-loadscope-reorder`` in addopts: xdist's own order, by number of tests, handed out
#: last the files of one or two long tests, e.g. test_fe_cluster.py and test_fe_reuse.py, so
#: that one worker ran them while the other had finished). Simulated on 2 workers from the
#: measured times of every file (1155 s of CPU): xdist's order ends at 588 s, this one at
#: 580 s, an even split at 578 s. The long files first, the short ones fill in at the end;
#: a file not listed runs after these in name order. A stale entry costs balance only,
#: never a result.
LONG_FILES_FIRST = (
    "test_generated_root.py",    # 45
    "test_ehl_stochastic.py",    # 32
    "test_fe_cache.py",          # 31
    "test_golden_run.py",        # 30
    "test_synthesis.py",         # 30
    "test_development.py",       # 29
    "test_fe_cluster.py",        # 29
    "test_fe_tooth.py",          # 27
    "test_study.py",             # 27
    "test_docs_site.py",         # 24
    "test_report.py",            # 24
    "test_friction_study.py",    # 24
    "test_compliance_tooth.py",  # 24
    "test_sweep_guard.py",       # 21 (27 s in a CI run)
    "test_root_stress.py",       # 21
    "test_fe_ltca.py",           # 21
    "test_fe_reuse.py",          # 20
    "test_global_state.py",      # 20
    "test_study_progress.py",    # 19
    "test_readme_walkthrough.py",  # 19
    "test_ehl_solver.py",        # 18
    "test_ltca.py",              # 17
    "test_optimize_truth.py",    # 17
    "test_docs_blocks.py",       # 15
)


def pytest_collection_modifyitems(config, items):
    """Put the files of :data:`LONG_FILES_FIRST` first, in its order (a stable sort: the
    tests of a file stay together and in their own order)."""
    rank = {name: i for i, name in enumerate(LONG_FILES_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))


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
