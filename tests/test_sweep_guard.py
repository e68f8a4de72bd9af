"""A study computes what it computed before the speed work of issue 32 ("every result
unchanged"): a fresh 5×5 ΔE × ΔP sweep of the default case equals the stored one.

The stored summaries (``tests/data/sweep_guard_5x5.nc``) were written by
``tests/sweep_guard.py --write`` before the first change of issue 32, and written again
when the elastic–perfectly-plastic edges of issue 37 were merged (a reviewed change of
results: the stored sweep's edge peak 5910 MPa became the shakedown limit 5262 MPa, and
the load the limit passes on moved the LTE, the pattern and the edge share), with the same
options the test runs: the default case about its Table 3.1 mounting (ΔE = −0.15 ± 0.05 mm,
ΔP = 0.12 ± 0.05 mm, 25 points), 250 N·m, the study engine with
``scheduler="synchronous"``, one BLAS thread, and a coarse LTCA
(``LTCAOptions(rolls_per_cycle=8, segments=8)``).

Why it is cheap enough for CI: the coarse LTCA (8 rolls per cycle, 8 segments per curve)
leaves the ease-off, UTCA and the tooth models as they are in a full analysis (so every
algorithm of a study point is on the path) but makes each point a fraction of a full one;
25 points in one process, the tooth models built once.

Tolerance: 1e-9 relative, elementwise (and 1e-9 of the variable's largest magnitude for
the values at or near 0, e.g. an edge pressure of 0). The speed work may change the order
of floating-point sums and the route of iterations that stop at 1e-9 of their scales
(tests/test_golden_run.py's argument: round-off moves a result by no more than that
without moving a contact set, which would show as a larger difference or an integer
change), but nothing more: a change of a result is a change of the algorithm's answer, not
its speed.
"""

from __future__ import annotations

import xarray as xr
from sweep_guard import GUARD, differences, run_guard

RTOL = 1e-9


def test_a_fresh_sweep_equals_the_stored_one():
    stored = xr.load_dataset(GUARD)
    new = run_guard()
    assert stored.sizes["delta_E"] == stored.sizes["delta_P"] == 5
    assert (stored["status"].values == 0).all()
    diff = differences(new, stored, rtol=RTOL)
    assert not diff, "\n".join(diff)


def test_the_comparison_sees_a_change():
    """Not vacuous: one LTE peak-to-peak moved by 1e-8 relative is reported."""
    stored = xr.load_dataset(GUARD)
    changed = stored.copy(deep=True)
    changed["lte_peak_to_peak"].values[2, 2, 0] *= 1.0 + 1e-8
    assert any(line.startswith("lte_peak_to_peak") for line in
               differences(changed, stored, rtol=RTOL))
    assert not differences(stored, stored, rtol=RTOL)
