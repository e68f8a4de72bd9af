"""Time per condition of the mixed-EHL line-contact solver, as ratios to one FFT convolution.

    python benchmarks/ehl.py [--repeats 3]
    python benchmarks/ehl.py --map [--nodes 256] [--steady] [--viscosity-model barus]
    python benchmarks/ehl.py --convergence

One core (BLAS limited to one thread). The unit is one 4096-point DC-FFT deflection
(``friction.ehl.kernel.ElasticKernel.deflection``), timed in the same run, so the ratios
say how many convolutions' worth of work a condition costs on this machine. Cases (p_h 1
GPa, R 20 mm, 75–90 °C): smooth steady (512 and 1024 nodes, u_e 5 m/s); rough steady
near-dry (384 nodes, Rq 0.3 µm each, u_e 1e-4 m/s); rough transient (ground profiles of Rq
0.3 µm each, u_e 5 m/s, SR 0.3, λ ≈ 0.65, the default time grid: 5 b/u_e) at 256 and 512
nodes with the dense Newton solver, and at 1024 nodes with the dense and the Krylov one
(issue 33 target: ≤ 10 s per rough transient condition). The fastest of ``--repeats``
counts (one run for the transient cases).

``--map`` prints the convergence map over p_h 1 and 2 GPa, u_e 1, 5, 20 m/s, Rq 0.1, 0.3,
1 µm on each surface (ground profiles, seeds 1 and 2), R 20 mm, 90 °C, SR 0.3 — λ,
converged or why not, asperity load ratio, μ, time — transient by default (``--steady``:
the frozen-roughness solver; docs/ehl.md, Validity).

``--convergence`` prints the rough transient condition's μ, asperity load ratio and
central film for halved time steps (Courant 2, 1, 0.5) and halved node spacings (256,
512, 1024 nodes, λs 24 µm so that every grid sees the same profile), with the changes'
ratios (the rates of docs/ehl.md).
"""

from __future__ import annotations

import argparse
import itertools
import math
import time

import numpy as np
from tabulate import tabulate
from threadpoolctl import threadpool_limits

from friction.ehl.complementarity import NewtonOptions
from friction.ehl.kernel import ElasticKernel
from friction.ehl.line_contact import (
    STEEL_E_PRIME,
    ConvergenceError,
    Grid,
    LineContactCondition,
    hertz_line_contact,
    line_contact_summary,
)
from friction.ehl.roughness import GroundSurface, ground_profile
from friction.ehl.transient import TimeGrid, default_transient_grid, transient_summary

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


def _transient_condition(ph_gpa: float = 1.0, speed: float = 5.0, temperature: float = 90.0,
                         viscosity_model: str = "roelands") -> LineContactCondition:
    load = 2.0 * math.pi * RADIUS * (ph_gpa * 1e3) ** 2 / STEEL_E_PRIME
    return LineContactCondition(load_per_length=load, radius=RADIUS, entraining_velocity=speed,
                                slide_to_roll=0.3, temperature=temperature,
                                viscosity_model=viscosity_model)


def convergence_map(nodes: int, steady: bool, viscosity_model: str) -> None:
    """Print the solver's convergence over a small (p_h, u_e, Rq) grid."""
    rows, converged = [], 0
    for ph, speed, rq in itertools.product((1.0, 2.0), (1.0, 5.0, 20.0), (0.1, 0.3, 1.0)):
        t = time.perf_counter()
        try:
            if steady:
                load = 2.0 * math.pi * RADIUS * (ph * 1e3) ** 2 / STEEL_E_PRIME
                grid = Grid(nodes=nodes, step_limit=3.0)
                b, _ = hertz_line_contact(load, RADIUS, STEEL_E_PRIME)
                x = grid.coordinates() * b
                cond = LineContactCondition(
                    load_per_length=load, radius=RADIUS, entraining_velocity=speed,
                    slide_to_roll=0.3, temperature=90.0, viscosity_model=viscosity_model,
                    roughness_1=ground_profile(x, rq, seed=1),
                    roughness_2=ground_profile(x, rq, seed=2))
                s = line_contact_summary(cond, grid)
            else:
                cond = _transient_condition(ph, speed, 90.0, viscosity_model)
                s = transient_summary(cond, (GroundSurface(rq, seed=1), GroundSurface(rq, seed=2)),
                                      default_transient_grid(cond, nodes))
            converged += 1
            result = ("converged", f"{s.lambda_ratio:.2f}", f"{s.asperity_load_ratio:.3f}",
                      f"{s.friction_coefficient:.4f}")
        except ConvergenceError as exc:
            kind = "sets cycle" if "cycle" in str(exc) else "no convergence"
            result = (f"failed ({kind})", "", "", "")
        rows.append((ph, speed, rq, *result, f"{time.perf_counter() - t:.1f} s"))
    print(tabulate(rows, headers=["p_h [GPa]", "u_e [m/s]", "Rq [um]", "status", "lambda",
                                  "ALR", "mu", "time"], tablefmt="github"))
    print(f"\nconverged {converged} of {len(rows)} ({nodes} nodes, "
          f"{'steady' if steady else 'transient'}, {viscosity_model})")


def convergence_rates() -> None:
    """Print μ, the asperity load ratio and h_c under halved time steps and spacings."""
    cond = _transient_condition()
    surfaces = (GroundSurface(0.3, seed=1, short_cutoff=0.024),
                GroundSurface(0.3, seed=2, short_cutoff=0.024))
    rows = []
    for label, grid, courant in (("C 2, 256", 256, 2.0), ("C 1, 256", 256, 1.0),
                                 ("C 0.5, 256", 256, 0.5), ("C 1, 512", 512, 1.0),
                                 ("C 1, 1024", 1024, 1.0)):
        t = time.perf_counter()
        s = transient_summary(cond, surfaces, default_transient_grid(cond, grid),
                              TimeGrid(courant=courant))
        rows.append((label, s.friction_coefficient, s.friction_coefficient_error,
                     s.asperity_load_ratio, s.film_central, time.perf_counter() - t))
    print(tabulate([(r[0], f"{r[1]:.5f}", f"{r[2]:.5f}", f"{r[3]:.4f}", f"{r[4]:.4f}",
                     f"{r[5]:.0f} s") for r in rows],
                   headers=["time step, nodes", "mu", "s.e. of mu", "ALR", "h_c [um]", "time"],
                   tablefmt="github"))
    for name, k in (("mu", 1), ("ALR", 3), ("h_c", 4)):
        dt = (abs(rows[1][k] - rows[0][k]), abs(rows[2][k] - rows[1][k]))
        dx = (abs(rows[3][k] - rows[1][k]), abs(rows[4][k] - rows[3][k]))
        print(f"{name}: time-step changes {dt[0]:.2e} -> {dt[1]:.2e}, "
              f"grid changes {dx[0]:.2e} -> {dx[1]:.2e}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--map", action="store_true", help="print the convergence map instead")
    ap.add_argument("--steady", action="store_true", help="--map of the steady solver")
    ap.add_argument("--viscosity-model", default="roelands", choices=("roelands", "barus"))
    ap.add_argument("--nodes", type=int, default=256, help="grid of --map")
    ap.add_argument("--convergence", action="store_true",
                    help="print the time-step and grid convergence instead")
    args = ap.parse_args()
    with threadpool_limits(1):
        if args.map:
            convergence_map(args.nodes, args.steady, args.viscosity_model)
            return
        if args.convergence:
            convergence_rates()
            return
        k = ElasticKernel(4096, 1e-3)
        p = np.random.default_rng(0).random(4096)
        unit, _ = _best(lambda: [k.deflection(p) for _ in range(100)], args.repeats)
        unit /= 100
        smooth = LineContactCondition(load_per_length=LOAD, radius=RADIUS,
                                      entraining_velocity=5.0, slide_to_roll=0.3,
                                      temperature=75.0)
        g_dry = Grid(nodes=384, inlet=-2.0, step_limit=1e9)
        cond = _transient_condition()
        rough = (GroundSurface(0.3, seed=1), GroundSurface(0.3, seed=2))

        def transient(nodes: int, solver: str):
            return lambda: transient_summary(
                cond, rough, default_transient_grid(cond, nodes),
                TimeGrid(newton=NewtonOptions(linear_solver=solver)))

        cases = [
            ("smooth steady, 512 nodes", lambda: line_contact_summary(smooth, Grid(nodes=512)),
             args.repeats),
            ("smooth steady, 1024 nodes", lambda: line_contact_summary(smooth, Grid(nodes=1024)),
             args.repeats),
            ("rough steady near-dry, 384 nodes", lambda: line_contact_summary(
                _rough(1e-4, g_dry), g_dry), args.repeats),
            ("rough transient (λ 0.65), 256 nodes, dense", transient(256, "dense"), 1),
            ("rough transient (λ 0.65), 512 nodes, dense", transient(512, "dense"), 1),
            ("rough transient (λ 0.65), 1024 nodes, dense", transient(1024, "dense"), 1),
            ("rough transient (λ 0.65), 1024 nodes, krylov", transient(1024, "krylov"), 1),
        ]
        rows = [("one 4096-point FFT convolution", f"{unit * 1e3:.3f} ms", "1", "")]
        for name, fn, repeats in cases:
            t, s = _best(fn, repeats)
            extra = (f", {s.steps} steps, {s.newton_iterations / s.steps:.1f} Newton/step"
                     if hasattr(s, "steps") else "")
            rows.append((name, f"{t:.2f} s", f"{t / unit:.0f}",
                         f"h_c {s.film_central:.3f} um, ALR {s.asperity_load_ratio:.3f}, "
                         f"mu {s.friction_coefficient:.4f}{extra}"))
    print(tabulate(rows, headers=["condition", "time", "ratio to one FFT", "result"],
                   tablefmt="github"))


if __name__ == "__main__":
    main()
