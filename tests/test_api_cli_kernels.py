"""``contact.run_analysis`` and ``ltca run`` take one kernel path and write the same file
(issue 71, branch remedy84; :mod:`geometry.core.kernels`).

``ltca run`` run as its own process runs ``auto`` (NumPy until numba's cache holds every
kernel module, :func:`geometry.core.kernels.prefer_cached`); the Python API ran numba
wherever installed. On a numba cache not yet filled (a fresh install, a fresh worktree)
the two files of the default case then differed: measured 665 entries of the golden
summary, up to 3.8e-9 relative (``/friction/film_thickness``), the ease-off's placement
1.2e-6 of its 1e-7 mm. Unset ``LTCA_KERNELS`` now means ``auto`` for both.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from golden import differences

from geometry.core.io import read_netcdf

ROOT = Path(__file__).resolve().parents[1]

API = ("import sys, contact\n"
       "from geometry.core.io import write_netcdf\n"
       "tree = contact.run_analysis(None)\n"
       "write_netcdf(tree, sys.argv[1], inputs=tree.attrs['inputs'])\n")


@pytest.mark.slow  # two default runs in their own processes, ~10 s each (FE cache warm)
def test_the_api_writes_the_file_ltca_run_writes_on_a_cold_numba_cache(tmp_path):
    """Both in processes of their own, on an empty numba cache (the state in which the
    paths parted) and ``LTCA_KERNELS`` unset: every entry of the golden summary equal bit
    for bit (``differences`` with rtol 0: timings and stamps left out, the contact
    residuals — round-off of ~1e-16 that moves with the arrays' alignment — to 1e-12)."""
    env = {k: v for k, v in os.environ.items() if k != "LTCA_KERNELS"}
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "numba")  # empty: nothing compiled yet
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    (tmp_path / "numba").mkdir()
    cli, api = tmp_path / "cli.nc", tmp_path / "api.nc"
    for argv in ([sys.executable, "-m", "contact.cli", "run", "--no-progress", "-o", str(cli)],
                 [sys.executable, "-c", API, str(api)]):
        done = subprocess.run(argv, cwd=tmp_path, env=env, capture_output=True, text=True,
                              timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
    assert differences(read_netcdf(api), read_netcdf(cli)) == []
