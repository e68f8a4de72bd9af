"""FE influence coefficients on a cluster whose workers share no cache (issue 53).

A study builds (or reads) the coefficients once in its client and hands them to every
worker with the shared inputs (``Client.scatter(broadcast=True)``); each worker writes
them into its own cache before its first point (``contact.compliance.fe.prime_cache``).
Here a ``LocalCluster``'s two workers each get a different, empty cache directory (the
environment variable per worker, as on separate machines) and a build of FE coefficients
on a worker fails the point: every point must be solved, and each worker's cache must
hold the client's entries, checksum intact.

~20 s: two worker processes and the small LTCA at two mountings on the coarse FE model.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

# the coarse FE model and small LTCA of tests/test_fe_ltca.py: the subject here is where
# the coefficients come from, not their accuracy
from test_fe_ltca import COARSE, SMALL

from contact.catalogue import resolve_case
from contact.compliance.fe import (
    CACHE_ENV,
    cache_key,
    cache_path,
    influence_coefficients,
)
from contact.compliance.fe.cache import CHECKSUM_ATTR, read_cache_entry
from contact.utca.easeoff import working_flanks

distributed = pytest.importorskip("distributed")


def _isolate_worker(root: str, dask_worker=None) -> str:
    """Run on each worker: its own empty cache directory (named for the worker), and any
    build of FE coefficients raises."""
    import contact.compliance.fe.influence as influence

    name = dask_worker.name if dask_worker is not None else "worker"
    path = Path(root) / f"worker-{name}"
    path.mkdir(parents=True, exist_ok=True)
    os.environ[CACHE_ENV] = str(path)

    def no_build(*args, **kwargs):
        raise RuntimeError("a worker built FE influence coefficients")

    influence.build_influence_model = no_build
    return str(path)


def test_workers_with_empty_caches_build_no_fe(tmp_path, monkeypatch):
    from distributed import Client, LocalCluster

    from contact.study import StudyRun, sweep

    monkeypatch.setenv(CACHE_ENV, str(tmp_path / "client"))
    case = resolve_case(None)
    flanks = dict(zip(("pinion", "gear"), working_flanks(case, None), strict=True))
    keys = {m: cache_key(case.member(m), flanks[m], COARSE) for m in flanks}
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        dirs = client.run(_isolate_worker, str(tmp_path / "workers"))
        assert len(set(dirs.values())) == 2
        assert all(not any(Path(d).iterdir()) for d in dirs.values())
        de = case.misalignment.delta_E
        grid = sweep(case, delta_E=[de - 0.02, de + 0.02], torque=250.0,
                     run=StudyRun(options=SMALL, root_stress=COARSE,
                                  scheduler=cluster.scheduler_address, progress=False))
    # every point solved on a worker that could not build: the coefficients came with the
    # shared inputs
    assert np.all(grid["status"].values == 0), grid["reason"].values
    assert np.all(np.isfinite(grid["root_stress_max"].values))
    assert np.all(grid["root_stress_max"].values > 0)
    # the worker that ran a point holds the client's entries under their keys, intact
    # (checksum and key checked by the reader); the client built them once in its own cache
    primed = [d for d in dirs.values() if any(Path(d).iterdir())]
    assert primed
    for d in primed:
        for member, key in keys.items():
            assert read_cache_entry(cache_path(key, d), key) is not None, (d, member)
    for key in keys.values():
        assert cache_path(key, tmp_path / "client").exists()
    # and they are the client's coefficients, not an equivalent rebuilt elsewhere
    client_pinion = influence_coefficients(case, "pinion", flanks["pinion"], COARSE,
                                           cache_dir=tmp_path / "client", progress=False)
    worker_pinion = read_cache_entry(cache_path(keys["pinion"], primed[0]), keys["pinion"])
    assert worker_pinion.attrs[CHECKSUM_ATTR] == client_pinion.attrs[CHECKSUM_ATTR]
