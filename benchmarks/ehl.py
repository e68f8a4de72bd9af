"""Time per condition of the mixed-EHL line-contact solver, as ratios to one FFT convolution.

    python benchmarks/ehl.py [--repeats 3]
    python benchmarks/ehl.py --map [--nodes 256]


One core (BLAS limited to one thread). The unit is one 4096-point DC-FFT deflection
(``friction.ehl.kernel.ElasticKernel.deflection``), timed in the same run, so the ratios
say how many convolutions' worth of work a condition costs on this machine. Cases: smooth
steady (512 and 1024 nodes, p_h 1 GPa, R 20 mm, u_e 5 m/s, 75 °C), rough steady near-dry
(384 nodes, Rq 0.3 µm each, u_e 1e-4 m/s), rough steady mixed (1024 nodes, λ ≈ 0.9, u_e
5 m/s, through the roughness homotopy); rough transient is not implemented yet (issue 33
target: ≤ 10 s per rough transient condition). The fastest of ``--repeats`` counts.

``--map`` prints instead the convergence map of the rough steady solver: p_h 1 and 2 GPa,
u_e 1, 5, 20 m/s, Rq 0.1, 0.3, 1 µm on each surface (ground profiles, seeds 1 and 2),
R 20 mm, 90 °C, SR 0.3 — λ, converged or the ConvergenceError's kind, asperity load
ratio, μ, time — and the fraction converged (docs/ehl.md, Validity).
"""

from __future__ import annotations

import argparse
import itertools
import math
import time

import numpy as np
from tabulate import tabulate
from threadpoolctl import threadpool_limits

from friction.ehl.kernel import ElasticKernel
from friction.ehl.line_contact import (
    STEEL_E_PRIME,
    ConvergenceError,
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


def convergence_map(nodes: int) -> None:
    """Print the rough steady solver's convergence over a small (p_h, u_e, Rq) grid."""
    radius, rows, converged = 20.0, [], 0
    for ph, speed, rq in itertools.product((1.0, 2.0), (1.0, 5.0, 20.0), (0.1, 0.3, 1.0)):
        load = 2.0 * math.pi * radius * (ph * 1e3) ** 2 / STEEL_E_PRIME   # w′ of this p_h
        grid = Grid(nodes=nodes, step_limit=3.0)
        b, _ = hertz_line_contact(load, radius, STEEL_E_PRIME)
        x = grid.coordinates() * b
        cond = LineContactCondition(load_per_length=load, radius=radius,
                                    entraining_velocity=speed, slide_to_roll=0.3,
                                    temperature=90.0, roughness_1=ground_profile(x, rq, seed=1),
                                    roughness_2=ground_profile(x, rq, seed=2))
        t = time.perf_counter()
        try:
            s = line_contact_summary(cond, grid)
            converged += 1
            result = ("converged", f"{s.lambda_ratio:.2f}", f"{s.asperity_load_ratio:.3f}",
                      f"{s.friction_coefficient:.4f}")
        except ConvergenceError as exc:
            kind = "sets cycle" if "cycle" in str(exc) else "max iterations"
            result = (f"failed ({kind})", "", "", "")
        rows.append((ph, speed, rq, *result, f"{time.perf_counter() - t:.1f} s"))
    print(tabulate(rows, headers=["p_h [GPa]", "u_e [m/s]", "Rq [um]", "status", "lambda",
                                  "ALR", "mu", "time"], tablefmt="github"))
    print(f"\nconverged {converged} of {len(rows)} ({nodes} nodes)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--map", action="store_true", help="print the convergence map instead")
    ap.add_argument("--nodes", type=int, default=256, help="grid of --map")
    args = ap.parse_args()
    if args.map:
        with threadpool_limits(1):
            convergence_map(args.nodes)
        return
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
