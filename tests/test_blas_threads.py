"""The BLAS thread limit of the toolkit's entry points (geometry.core.blas).

The limit exists because a second OpenBLAS thread spins on the toolkit's small matrices
(measured in the module docstring); what is tested here is the contract: one thread
inside, the caller's setting back outside, the environment's choice honoured, a bad
value refused with the variable's name. The suite itself runs with one thread
(conftest.py), so the tests raise the count first to see the limit act.
"""

import numpy as np
import pytest
import scipy.linalg
from threadpoolctl import threadpool_info, threadpool_limits

from geometry.core.blas import blas_threads
from geometry.core.errors import InputError

ENV = ("HYPOID_LTCA_BLAS_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
       "OMP_NUM_THREADS")


def _threads() -> list[int]:
    return [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]


@pytest.fixture
def clean_env(monkeypatch):
    for name in ENV:
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


def test_one_thread_inside_and_the_callers_setting_back(clean_env):
    with threadpool_limits(limits=2, user_api="blas"):
        outside = _threads()
        with blas_threads() as limit:
            assert limit == 1
            assert set(_threads()) == {1}
        assert _threads() == outside


def test_the_environment_chooses(clean_env):
    clean_env.setenv("OPENBLAS_NUM_THREADS", "2")
    with threadpool_limits(limits=1, user_api="blas"), blas_threads() as limit:
        assert limit == 2
    clean_env.setenv("HYPOID_LTCA_BLAS_THREADS", "0")  # read first: no limit
    with threadpool_limits(limits=2, user_api="blas"):
        before = _threads()
        with blas_threads() as limit:
            assert limit is None
            assert _threads() == before



def test_run_analysis_runs_with_one_thread(clean_env):
    """The analysis' own steps see the limit (issue 75: the decorator had slipped onto a
    helper inserted above ``run_analysis``, and a warm analysis ran its shell products on
    two spinning threads: 3.5x its CPU on the shared 2-core machine). A user's first step
    records the threads and stops the run."""
    from contact import run_analysis
    from geometry.core.errors import PluginError

    seen = []

    def look(state):
        seen.append(_threads())
        raise RuntimeError("stop here")

    with threadpool_limits(limits=2, user_api="blas"):
        outside = _threads()
        with pytest.raises(PluginError, match="stop here"):
            run_analysis(None, [250.0], steps={"geometry": look})
        assert _threads() == outside
    assert seen and set(seen[0]) == {1}

@pytest.mark.parametrize("value", ["two", "-1", "1.5"])
def test_a_bad_variable_is_named(clean_env, value):
    clean_env.setenv("HYPOID_LTCA_BLAS_THREADS", value)
    with pytest.raises(InputError, match="HYPOID_LTCA_BLAS_THREADS"), blas_threads():
        pass


def test_a_negative_limit_is_refused():
    with pytest.raises(InputError, match="limit: must be >= 0"), blas_threads(-2):
        pass


def test_results_do_not_depend_on_the_thread_count(clean_env):
    """A Cholesky factor (what the contact problem's check computes) is the same with one
    thread as with two to round-off: the limit changes the cost, not the answer (the
    blocked algorithm's summation order may differ, so 1e-12 relative, far above the
    ~1e-15 of one reordering and far below any physical tolerance)."""
    rng = np.random.default_rng(3)
    a = rng.standard_normal((300, 300))
    c = a @ a.T + 300.0 * np.eye(300)
    with threadpool_limits(limits=2, user_api="blas"):
        two = scipy.linalg.cholesky(c, lower=True)
    with blas_threads():
        one = scipy.linalg.cholesky(c, lower=True)
    np.testing.assert_allclose(one, two, rtol=1e-12, atol=1e-12 * np.abs(two).max())


def test_the_command_starts_its_blas_with_the_limit(clean_env):
    """limit_at_start (the ``ltca`` command, before NumPy loads) makes every BLAS the
    process loads afterwards start with one thread; a process that asked for none keeps
    the library's own count (checked in a fresh interpreter: the suite's own BLAS is
    already loaded and limited)."""
    import subprocess
    import sys

    code = ("from geometry.core.blas import limit_at_start; print(limit_at_start()); "
            "import numpy, scipy.linalg; from threadpoolctl import threadpool_info; "
            "print(sorted({i['num_threads'] for i in threadpool_info() "
            "if i['user_api'] == 'blas'}))")
    env = {k: v for k, v in __import__("os").environ.items() if k not in ENV}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=True).stdout.split("\n")
    assert out[0] == "1" and out[1] == "[1]"
    env["HYPOID_LTCA_BLAS_THREADS"] = "0"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=True).stdout.split("\n")
    assert out[0] == "None"
