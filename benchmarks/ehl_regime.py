"""The stochastic solver's regime map, its grid convergence and its cost, in one run.

    python benchmarks/ehl_regime.py [--figure docs/figures/ehl/regime_map.png]
    python benchmarks/ehl_regime.py --timing [--repeats 3]

The regime map (issue 51): the asperity load ratio, the real contact area ratio and μ with
its film and boundary parts against λ from 5 to 0.01 — speed sweeps at three roughnesses
(Rq 0.1, 0.3, 1.0 µm on each surface, the ground profiles of seeds 1 and 2) and three
pressures (p_h 0.5, 1 and 2 GPa), R 20 mm, SR 0.3, 75W90 at 90 °C, the speeds chosen from
Pan–Hamrock's λ ∝ u^0.694 — plus the dry limit (u_e = 1e-5 m/s) and Johnson–Greenwood–Poon's
asperity share of the same conditions (the independent check). Prints one table per
series and the minimum of μ (the Stribeck minimum), and draws the figure.

``--timing``: seconds per rough condition on one core (BLAS one thread) at 256, 512 and
1024 nodes with the changes of μ and of the asperity load ratio between them (512 is the
grid the convergence study asks: halving its spacing moves both < 10 %), next to the
resolved transient model at its default 256 nodes; the fastest of ``--repeats``.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np
from tabulate import tabulate
from threadpoolctl import threadpool_limits

from friction.ehl.line_contact import STEEL_E_PRIME, LineContactCondition
from friction.ehl.load_sharing import jgp_load_sharing
from friction.ehl.roughness import GroundSurface
from friction.ehl.stochastic import (
    roughness_statistics,
    stochastic_grid,
    stochastic_summary,
)
from friction.ehl.transient import default_transient_grid, transient_summary

RADIUS, SR, TEMPERATURE = 20.0, 0.3, 90.0
LAMBDAS = (5.0, 3.0, 2.0, 1.5, 1.0, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05, 0.03, 0.02, 0.01)
DRY_SPEED = 1e-5
PRESSURES = (0.5, 1.0, 2.0)


def _condition(ph_gpa: float, speed: float) -> LineContactCondition:
    load = 2.0 * math.pi * RADIUS * (ph_gpa * 1e3) ** 2 / STEEL_E_PRIME
    return LineContactCondition(load_per_length=load, radius=RADIUS, entraining_velocity=speed,
                                slide_to_roll=SR, temperature=TEMPERATURE)


def _surfaces(rq: float) -> tuple[GroundSurface, GroundSurface]:
    return GroundSurface(rq, seed=1), GroundSurface(rq, seed=2)


def _speeds(ph: float, rq: float) -> list[float]:
    """Speeds that give the λ targets (Pan–Hamrock: λ ∝ u_e^0.694), up to 100 m/s."""
    ref = stochastic_summary(_condition(ph, 1.0), _surfaces(rq))
    speeds = [(lam / ref.lambda_ratio) ** (1.0 / 0.694) for lam in LAMBDAS]
    return [u for u in speeds if u <= 100.0]


def regime_map(figure: Path | None) -> None:
    series = {}
    for ph in PRESSURES:
        for rq in (0.1, 0.3, 1.0):
            stats = roughness_statistics(_surfaces(rq))
            rows = []
            for u in [*_speeds(ph, rq), DRY_SPEED]:
                cond = _condition(ph, u)
                r = stochastic_summary(cond, _surfaces(rq))
                jgp = jgp_load_sharing(cond, stats).asperity_load_ratio
                rows.append((u, r.lambda_ratio, r.asperity_load_ratio, jgp,
                             r.contact_area_ratio, r.friction_coefficient, r.fluid_friction,
                             r.boundary_part, r.flash_temperature_max))
            series[(ph, rq)] = np.array(rows)
            print(f"\np_h {ph} GPa, Rq {rq} um each")
            print(tabulate([(f"{a:.4g}", f"{b:.3g}", f"{c:.3f}", f"{d:.3f}", f"{e:.3f}",
                             f"{f:.4f}", f"{g:.4f}", f"{h:.4f}", f"{i:.1f}")
                            for a, b, c, d, e, f, g, h, i in rows],
                           headers=["u_e [m/s]", "lambda", "ALR", "ALR (JGP)", "area",
                                    "mu", "mu film", "mu boundary", "flash [K]"],
                           tablefmt="github"))
            mu = series[(ph, rq)][:-1, 5]
            k = int(np.argmin(mu))
            print(f"least mu {mu[k]:.4f} at lambda {series[(ph, rq)][k, 1]:.3g}"
                  + (" (the sweep's end: no minimum inside it)" if k in (0, mu.size - 1)
                     else " (Stribeck minimum)"))
    if figure is not None:
        _draw(series, figure)


def _draw(series, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 4, figsize=(19, 4.8), constrained_layout=True)
    colours = {0.1: "tab:blue", 0.3: "tab:orange", 1.0: "tab:green"}
    styles = dict(zip(PRESSURES, ("-.", "-", "--"), strict=True))
    for (ph, rq), a in series.items():
        style = styles[ph]
        lam, c = a[:-1, 1], colours[rq]
        label = f"{ph:g} GPa, Rq {rq:g} µm"
        axes[0].plot(lam, a[:-1, 2], style, color=c, label=label)
        axes[0].plot(lam, a[:-1, 3], ":", color=c, lw=1)
        axes[1].plot(lam, a[:-1, 4], style, color=c, label=label)
        axes[2].plot(lam, a[:-1, 5], style, color=c, label=label)
        axes[3].plot(lam, np.maximum(a[:-1, 6], 1e-5), style, color=c, label=label)
        axes[3].plot(lam, np.maximum(a[:-1, 7], 1e-5), style, color=c, lw=0.8, alpha=0.5)
        # the dry limit (u_e 1e-5 m/s: the rough contact the QP solves), at the axis' end
        for k, j in ((0, 2), (1, 4), (2, 5)):
            axes[k].plot([0.006], [a[-1, j]], "o", color=c, ms=3)
    titles = ("asperity load ratio (dotted: JGP)", "real contact area / 2b",
              "friction coefficient µ", "µ's film part (thin: boundary part)")
    for ax, title in zip(axes, titles, strict=True):
        ax.set_xscale("log")
        ax.set_xlabel("λ (Pan–Hamrock h_min / composite Rq)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.axvspan(1.0, 3.0, color="0.9", zorder=0)
        ax.set_xlim(6.0, 0.005)
    axes[3].set_yscale("log")
    axes[3].set_ylim(1e-4, 0.12)
    axes[2].axhline(0.1, color="k", lw=0.8, ls=":")
    axes[2].text(4.0, 0.102, "µ_b", fontsize=9)
    axes[1].legend(fontsize=8, loc="upper left")
    fig.suptitle("Stochastic mixed-EHL line contact: R 20 mm, SR 0.3, 75W90 at 90 °C "
                 "(shaded: 1 < λ < 3; dots at λ = 0.006: the dry limit, u_e = 1e-5 m/s)")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=150)
    print(f"\nfigure -> {path}")


def timing(repeats: int) -> None:
    rows = []
    for ph, u, rq in ((1.0, 1.0, 0.3), (2.0, 0.3, 0.8), (1.0, 10.0, 0.1)):
        cond = _condition(ph, u)
        surfaces = _surfaces(rq)
        stats = roughness_statistics(surfaces)
        out = {}
        for nodes in (256, 512, 1024):
            best = math.inf
            for _ in range(repeats):
                t = time.perf_counter()
                r = stochastic_summary(cond, surfaces, stochastic_grid(cond, stats, nodes))
                best = min(best, time.perf_counter() - t)
            out[nodes] = (best, r)
        t = time.perf_counter()
        tr = transient_summary(cond, surfaces, default_transient_grid(cond, 256))
        t_tr = time.perf_counter() - t
        for nodes, (sec, r) in out.items():
            ref = out[2 * nodes][1] if 2 * nodes in out else None
            change = (f"{ref.friction_coefficient / r.friction_coefficient - 1:+.1%} / "
                      f"{ref.asperity_load_ratio - r.asperity_load_ratio:+.3f}"
                      if ref else "")
            rows.append((f"{ph:g} GPa, {u:g} m/s, Rq {rq:g} (λ {r.lambda_ratio:.2f})",
                         f"stochastic {nodes}", f"{sec:.2f} s",
                         f"{r.friction_coefficient:.4f}", f"{r.asperity_load_ratio:.3f}", change))
        rows.append(("", "resolved transient 256", f"{t_tr:.1f} s",
                     f"{tr.friction_coefficient:.4f}", f"{tr.asperity_load_ratio:.3f}", ""))
    print(tabulate(rows, headers=["condition", "solver, nodes", "time", "mu", "ALR",
                                  "to twice the nodes: mu / ALR"], tablefmt="github"))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--figure", type=Path, default=None, help="draw the regime map here")
    ap.add_argument("--timing", action="store_true", help="time per condition instead")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    with threadpool_limits(1):
        if args.timing:
            timing(args.repeats)
        else:
            regime_map(args.figure)


if __name__ == "__main__":
    main()
