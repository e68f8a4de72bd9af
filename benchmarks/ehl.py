"""Time per condition of the mixed-EHL line-contact solver, as ratios to one FFT convolution.

    python benchmarks/ehl.py [--repeats 3]

One core (BLAS limited to one thread). The unit is one 4096-point DC-FFT deflection
(``friction.ehl.kernel.ElasticKernel.deflection``), timed in the same run, so the ratios
say how many convolutions' worth of work a condition costs on this machine. Cases: smooth
steady (512 and 1024 nodes, p_h 1 GPa, R 20 mm, u_e 5 m/s, 75 °C), rough steady near-dry
(384 nodes, Rq 0.3 µm each, u_e 1e-4 m/s), rough steady mixed (1024 nodes, λ ≈ 0.9, u_e
5 m/s, through the roughness homotopy); rough transient is not implemented yet (issue 33
target: ≤ 10 s per rough transient condition). The fastest of ``--repeats`` counts.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from tabulate import tabulate
from threadpoolctl import threadpool_limits

from friction.ehl.kernel import ElasticKernel
from friction.ehl.line_contact import (
    STEEL_E_PRIME,
    Grid,
    LineContactCondition,
    hertz_line_contact,
    line_contact_summary,
)
from friction.ehl.roughness import ground_profile

LOAD, RADIUS = 556.0, 20.0


def _best(fn, repeats: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeats):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def _rough(speed: float, grid: Grid) -> LineContactCondition:
    b, _ = hertz_line_contact(LOAD, RADIUS, STEEL_E_PRIME)
    x = grid.coordinates() * b
    return LineContactCondition(load_per_length=LOAD, radius=RADIUS, entraining_velocity=speed,
                                slide_to_roll=0.3, temperature=75.0,
                                roughness_1=ground_profile(x, 0.3, seed=1),
                                roughness_2=ground_profile(x, 0.3, seed=2))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    with threadpool_limits(1):
        k = ElasticKernel(4096, 1e-3)
        p = np.random.default_rng(0).random(4096)
        unit, _ = _best(lambda: [k.deflection(p) for _ in range(100)], args.repeats)
        unit /= 100
        smooth = LineContactCondition(load_per_length=LOAD, radius=RADIUS,
                                      entraining_velocity=5.0, slide_to_roll=0.3,
                                      temperature=75.0)
        g_dry = Grid(nodes=384, inlet=-2.0, step_limit=1e9)
        g_mixed = Grid(nodes=1024, inlet=-3.0, step_limit=3.0, max_iterations=100)
        cases = [
            ("smooth steady, 512 nodes", lambda: line_contact_summary(smooth, Grid(nodes=512))),
            ("smooth steady, 1024 nodes", lambda: line_contact_summary(smooth, Grid(nodes=1024))),
            ("rough steady near-dry, 384 nodes", lambda: line_contact_summary(
                _rough(1e-4, g_dry), g_dry)),
            ("rough steady mixed (λ≈0.9), 1024 nodes", lambda: line_contact_summary(
                _rough(5.0, g_mixed), g_mixed)),
        ]
        rows = [("one 4096-point FFT convolution", f"{unit * 1e3:.3f} ms", "1", "")]
        for name, fn in cases:
            t, s = _best(fn, args.repeats)
            rows.append((name, f"{t:.2f} s", f"{t / unit:.0f}",
                         f"h_c {s.film_central:.3f} um, ALR {s.asperity_load_ratio:.3f}, "
                         f"mu {s.friction_coefficient:.4f}"))
        rows.append(("rough transient", "not implemented", "", "issue 33 target ≤ 10 s"))
    print(tabulate(rows, headers=["condition", "time", "ratio to one FFT", "result"],
                   tablefmt="github"))


if __name__ == "__main__":
    main()
