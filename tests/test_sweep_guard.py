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
All 25 points were written again when the ease-off filled the runs of up to three
relief-corner holes (issue 71, branch lte90, re-applied on lead91; a reviewed change of
results): at 7 points of the low-ΔP rows (ΔP 0.07 and 0.095 mm, ΔE −0.20 … −0.10 mm) the
pinion's tip relief crossed a hole at the gear's profile node next to it, whose cells had
dropped out of the contact region. Filled, the region reaches the relief tip and the load
the relief strip carries moves off the edge: LTE p-p by −0.03 to −6.0 µrad (23.42 → 17.43
at (−0.125, 0.07)), LTE mean −1.1 to −1.9 µrad, flank pressure −6 to −202 MPa, edge
pressure 0 to −727 MPa (4900 → 4173 at (−0.10, 0.07)), edge share −0.12 … −0.30 %, the
pattern centre's v −0.001 … −0.014, the gear's root stress −1.4 MPa at one point, the
UTE unchanged (the UTE is read on the contact curves, not on the region). Accepted: the
same points on finer ease-off grids (41 × 41, 81 × 41, 81 × 81, with and without the
fill; the guard's coarse LTCA and the default one) spread over 15–46 µrad in LTE p-p and
1048–1290 MPa in flank peak, with or without the fill: both the stored and the new values
lie inside that spread (the LTE's grid convergence at these excursions is an open point of
its own), and only the fill removes the holes, a defect of the region, not of the grid.
Reviewed again on lte91 (docs/synthesis.md "The sweep guard's moved points reviewed"): the
fill adds exactly one gear node at each of the 7 points (41 × 21 node (32, 19), u 0.80, v
0.953) and none at the other 18; the 41 × 21 flank peak, old and new, lies in that node's
cell (the old value was the hole's own pressure concentration), the finer grids' at
mid-flank; the filled edge peak agrees with the filled 81 × 81's within 43 MPa where it
moved (before: up to 233 MPa off the unfilled 81 × 81). The file's ``rewritten``
attribute records the rewrite.

All 25 points were written again when the second-order contact curve's Newton step
was halved where it raised the pair's cost UTE_seed + ½ K t² (issue 71, branch newton91;
a reviewed change of results: the second-order UTE can never exceed the seed's, and on
finer ease-off grids it did by up to 53.7 µrad): the UTE p-p by up to 0.067 µrad at 21
points, the LTE p-p by up to 1.53 µrad at 4, the LTE mean up to 0.16 µrad, the flank peak
up to 0.75 MPa, the edge peak up to 2.1 MPa, the edge share up to 0.037 %, the pattern
centre up to 0.03 mm and the pinion's root stress 2.6 MPa at one point.

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
