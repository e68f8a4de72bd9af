"""``ltca run`` reproduces the golden file written before the restructuring of ``contact/``.

The golden file (``tests/data/golden_default_run.nc``, made by ``tests/golden.py``) is the
whole default analysis: every group (/geometry, /easeoff, /utca, /ltca, /friction), every
variable and every attribute. A refactoring must reproduce it all but the timings and the
file's creation stamp.

Tolerance: integers, text (solver status, the case as TOML, JSON options) and
attributes must be identical; float variables agree to 1e-9 of each variable's largest
magnitude (the contact residuals, round-off that varies from run to run, to 1e-12:
``golden.RESIDUAL_ATOL``; the reviewed changes of ``golden.REVIEWED`` to their bound).
On the machine that wrote the file the run reproduces it bit for bit
(``differences(..., rtol=0)`` is empty; checked when the file was written and after the
restructuring); the 1e-9 allows for another CPU's or BLAS build's round-off (the LTCA's
Newton and active-set iterations stop at 1e-9 of their scales, so round-off cannot move
a result by more than that without moving a contact set, which would show as an
integer ``contact`` flag difference).
"""

from __future__ import annotations

import numpy as np
import pytest
from golden import GOLDEN, differences, run_default

from contact.io import read_netcdf

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
