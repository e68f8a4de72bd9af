"""``ltca run`` reproduces the golden file written before the restructuring of ``contact/``.

The golden file (``tests/data/golden_default_run.nc``, made by ``tests/golden.py``) is the
whole default analysis: every group (/geometry, /easeoff, /utca, /ltca, /friction), every
variable and every attribute. A refactoring must reproduce it all but the timings and the
file's creation stamp.

Tolerance: integers and text (solver status, the case as TOML, JSON options) must be
identical; float variables agree to 1e-9 of each variable's largest magnitude and float
attributes to 1e-9 of their value, but for the few whose comparison across machines is
stated in ``golden.ACROSS_MACHINES`` with its reason (convergence diagnostics to an
absolute tolerance, the friction coefficient of lightly loaded segments to 1e-7) and the
contact residuals (round-off that varies from run to run, to 1e-12:
``golden.RESIDUAL_ATOL``). On the machine that wrote the file the run reproduces it bit
for bit (``python tests/golden.py --check``); the 1e-9 allows for another CPU's or BLAS
build's round-off (the LTCA's Newton and active-set iterations stop at 1e-9 of their
scales, so round-off cannot move a result by more than that without moving a contact set,
which would show as an integer ``contact`` flag difference). Principal directions are
signed by a stated convention (``geometry.machine.curvature.principal_from_directional``), so
they too compare as floats; before it, round-off of a torsion's sign flipped them between
CPUs (issue 31).

``test_golden_file_on_other_blas_kernels`` runs the comparison again in a process whose
OpenBLAS uses another CPU's kernels (``OPENBLAS_CORETYPE``), so a result that depends on
a machine's last digit fails on any machine, not only on a new user's.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from blas_kernels import PRINT_KERNEL, run_on_other_kernel
from golden import GOLDEN, differences, run_default

from geometry.core.io import read_netcdf

#: float variables, relative to each variable's largest magnitude (module docstring)
RTOL = 1e-9


@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    return read_netcdf(run_default(tmp_path_factory.mktemp("golden")), tree=True)


def test_default_run_reproduces_the_golden_file(default_run):
    golden = read_netcdf(GOLDEN, tree=True)
    diff = differences(default_run, golden, rtol=RTOL)
    assert not diff, "\n".join(diff)


def test_the_comparison_sees_a_change(default_run):
    """The comparison is not vacuous: the largest force changed by 1e-6 is reported."""
    golden = read_netcdf(GOLDEN, tree=True)
    changed = default_run.copy(deep=True)
    ds = changed["ltca"].to_dataset(inherit=False)
    force = ds["force"].values.copy()
    force[np.unravel_index(np.nanargmax(force), force.shape)] *= 1.0 + 1e-6
    ds["force"] = ds["force"].copy(data=force)
    changed["ltca"].dataset = ds
    assert any(line.startswith("/ltca/force") for line in
               differences(changed, golden, rtol=RTOL))


_OTHER_KERNEL_RUN = PRINT_KERNEL + """
import sys
from pathlib import Path
import tempfile
from threadpoolctl import threadpool_limits
sys.path.insert(0, {tests!r})
from golden import GOLDEN, differences, run_default
from geometry.core.io import read_netcdf
with threadpool_limits(limits=1, user_api="blas"), tempfile.TemporaryDirectory() as tmp:
    new = read_netcdf(run_default(Path(tmp)), tree=True)
diff = differences(new, read_netcdf(GOLDEN, tree=True), rtol={rtol!r})
print("\\n".join(["DIFFERENCES"] + diff) if diff else "AGREES")
"""


def test_golden_file_on_other_blas_kernels():
    """The default run agrees with the golden file (same tolerances) when OpenBLAS runs
    another CPU's kernels: a fresh AMD machine's kernels differed in the last digit and
    flipped principal directions, which the machine that wrote the file never saw
    (issue 31). About 10 s: one more default run, in a subprocess."""
    out = run_on_other_kernel(_OTHER_KERNEL_RUN.format(tests=str(Path(__file__).parent),
                                                       rtol=RTOL))
    assert "AGREES" in out, out[-5000:]


def test_the_standards_scuffing_method_is_stored_beside_the_rating(default_run):
    """``/rating/flash_temperature`` is the standard's flash temperature method recomputed
    from the file's own ``/rating`` and ``/friction`` (same inputs, so to round-off:
    rtol 1e-12), and it gives a finite scuffing safety at every torque."""
    from contact.commands.run import standard_scuffing

    stored = default_run["rating/flash_temperature"].to_dataset()  # with the inherited coords
    again = standard_scuffing(default_run, default_run["friction"].to_dataset())
    assert again is not None
    assert set(stored.data_vars) == set(again.data_vars)
    for name, var in again.data_vars.items():
        xr.testing.assert_allclose(stored[name], var, rtol=1e-12)
    assert np.all(np.isfinite(stored["scuffing_safety"].values))
    assert stored.attrs["method"] == again.attrs["method"]
