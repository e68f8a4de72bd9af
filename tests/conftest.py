"""Test-suite configuration.

BLAS is limited to one thread: the suite's matrices are small, and on a shared
2-core machine a multi-threaded BLAS oversubscribes the cores (a shell-model build
measured 0.02 s single-threaded and 0.3–0.7 s threaded under load).

The FE influence coefficients' cache (root stress, on by default in ``ltca run``, issue 53)
is one directory for the whole session and every xdist worker, beside pytest's own cache
(``.pytest_cache/hypoid-ltca-fe``), unless ``HYPOID_LTCA_CACHE`` is set: a design's
coefficients are built once per session (once ever on a developer's machine), never in the
user's own cache. Tests that need an empty cache set their own (monkeypatch).
"""

import os
from pathlib import Path

from threadpoolctl import threadpool_limits

threadpool_limits(limits=1, user_api="blas")

os.environ.setdefault(
    "HYPOID_LTCA_CACHE",
    str(Path(__file__).resolve().parents[1] / ".pytest_cache" / "hypoid-ltca-fe"))
