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
(``LTCAOptions(rolls_per_cycle=8, segments=8)``). One point, ΔE = −0.10 mm, ΔP = 0.12 mm,
was run again when the pinion edge stopped depending on the last bit of a contour vertex
(``contact.ltca.edges``: the writer's OpenBLAS kernels had put a vertex on a grid line one
ulp into the computed cell, giving the edge one segment more than every other kernel did;
LTE mean +3.6e-4 µrad, pattern centre 0.01 mm). All 25 points were written again when
the pinion's blade tip planes were placed on the root cone (c716685, a reviewed change of
results; the file's ``rewritten`` attribute): the flank is unchanged (to 1e-13 mm), but
(1) the pinion FE tooth is built on the raised root lines (slot bottom 0.51 mm higher under
the concave cut, 0.03 mm under the convex one), which at every point moved the LTE mean by
−0.26 to −0.41 µrad, the flank pressure by −1.3 to −2.2 MPa and the pattern centre by
+0.01 mm, the UTE unchanged; and (2) the ease-off's mapping maps other gear nodes next to
the pinion blade's flankrem corner (the extended pinion grid is built on the blade's main
section, whose heights count from the tip plane: 0–3 nodes per point, the common nodes
equal to 1e-11 rad), which changed the UTE p-p at ΔE, ΔP = (−0.15, 0.095) mm by −3.0 µrad,
and with the edge contact at that corner the LTE p-p (−7.9 µrad at (−0.175, 0.095)), the
edge pressure (−207 to +130 MPa) and the pattern's root row (one grid step) at six points.
All 25 points were written again when the ease-off's fields Q, ε and K were cut at the
pinion's flankrem corner (issue 71, branch spline89: the default case's tip relief crosses
every lengthwise column of its ease-off, where the global spline rang; a reviewed change
of results): UTE p-p by up to 2.0 µrad (range 12.04–91.03 → 10.68–91.18), LTE p-p up to
1.6 µrad (10.89–22.42 → 12.51–23.42), LTE mean up to 0.7 µrad, flank pressure up to
72 MPa, edge pressure up to 283 MPa (the limit 5262 MPa unchanged), edge share up to
0.09 %, pattern centre up to 0.25 mm and the toe row at two points (one grid step).

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

``test_the_guard_on_other_blas_kernels`` runs the comparison again in a process whose
OpenBLAS uses another CPU's kernels (``OPENBLAS_CORETYPE``, as tests/test_golden_run.py
does), so a result that follows a machine's last digit fails on any machine, not only on
a new user's.
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr
from blas_kernels import PRINT_KERNEL, run_on_other_kernel
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


_OTHER_KERNEL_RUN = PRINT_KERNEL + """
import os, sys
os.environ["LTCA_KERNELS"] = "numpy"
sys.path.insert(0, {tests!r})
import xarray as xr
from sweep_guard import GUARD, differences, run_guard
diff = differences(run_guard(), xr.load_dataset(GUARD), rtol={rtol!r})
print("\\n".join(["DIFFERENCES"] + diff) if diff else "AGREES")
"""


def test_the_guard_on_other_blas_kernels():
    """The sweep agrees with the stored one (same tolerance) when OpenBLAS runs another
    CPU's kernels: the pinion edge of two points followed the kernels' round-off of the
    margin (one segment more or fewer, LTE mean 1e-6 relative), which the machine that
    wrote the file never saw. About 25 s: the sweep again, in a subprocess.

    That run also takes the iso-line searches' NumPy path (``LTCA_KERNELS=numpy``), where
    the test above takes the compiled kernels wherever numba is installed (the ``fast``
    extra, part of ``test``): both paths are held to the stored sweep."""
    out = run_on_other_kernel(_OTHER_KERNEL_RUN.format(tests=str(Path(__file__).parent),
                                                       rtol=RTOL))
    assert "AGREES" in out, out[-5000:]
