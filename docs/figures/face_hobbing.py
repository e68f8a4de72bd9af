"""Draw the face-hobbing figure of docs/machine.md.

Run from the repository root::

    python docs/figures/face_hobbing.py

writes ``docs/figures/face_hobbing.png``: (a) the cutter head in its tip plane, seen from the
work (along −z_t): z0 blade groups, each an outside blade (OB) leading an inside blade (IB)
by half a group pitch, the reference points M at the point radii and the rake planes turned
by the blade offset angle δ_b; (b) the tip plane of a crown gear (γ_m = 90°, Formate): the
trace of one blade tip relative to the work while the head spins and the work indexes by
κ = −z0/z (an extended epicycloid through the mean point P with the spiral angle β), beside
the circle a face-milling cutter of the same radius traces (κ = 0). All points are computed
with the toolkit's chain (geometry.machine.family.generated_family).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from geometry.machine.cradle import MachineSettings, generated_family  # noqa: E402
from geometry.machine.cutter import Blade, placement_vectors  # noqa: E402

# crown-gear example of the design note (docs/machine.md, "Face hobbing")
Z, Z0, RC0, R, BETA = 45, 13, 88.9, 100.0, math.radians(32.0)


def crown_tools(kappa: float):
    nu = math.asin(R * Z0 * math.cos(BETA) / (RC0 * Z)) if kappa else 0.0
    sr = math.sqrt(R**2 + RC0**2 - 2 * R * RC0 * math.sin(BETA - nu))
    qc = math.atan2(RC0 * math.cos(BETA - nu), R - RC0 * math.sin(BETA - nu))
    phase = BETA - nu - 0.5 * math.pi - qc
    blade = Blade("outside", RC0, 0.0, blade_phase=phase, blade_offset_angle=nu)
    settings = MachineSettings("Formate", sr, qc, machine_root_angle=0.5 * math.pi - 1e-9,
                               indexing_ratio=kappa)
    return blade, settings, nu


def main() -> None:
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5.6))
    # (a) the head
    _, _, nu = crown_tools(-Z0 / Z)
    ax1.add_patch(plt.Circle((0, 0), RC0, fill=False, ls=":", color="0.5"))
    for k in range(Z0):
        base = 2 * math.pi * k / Z0
        for side, shift, colour in (("outside", 0.5, "C3"), ("inside", -0.5, "C0")):
            rp = RC0 + (2.5 if side == "outside" else -2.5)
            b = Blade(side, rp, 0.0, blade_phase=base + shift * math.pi / Z0,
                      blade_offset_angle=nu)
            m, a1, _ = placement_vectors(b)
            ax1.plot(*m[:2], "o", color=colour, ms=4)
            # the rake plane's trace in the tip plane: the line through M along a1
            seg = np.array([m - 9 * a1, m + 9 * a1])
            ax1.plot(seg[:, 0], seg[:, 1], "-", color=colour, lw=1.2)
            if k == 0:
                ax1.annotate(f"{'OB' if side == 'outside' else 'IB'}", m[:2],
                             xytext=(6, 4 if side == "outside" else -12),
                             textcoords="offset points", color=colour)
    ax1.set_title(f"(a) head: z0 = {Z0} groups, OB leads IB by π/z0,\n"
                  f"rake planes turned by δ_b = ν = {math.degrees(nu):.1f}° "
                  "(seen from the work)", fontsize=10)
    ax1.set_aspect("equal")
    ax1.set_xlabel("x_t [mm]")
    ax1.set_ylabel("y_t [mm]")
    # (b) the trace in the crown-gear plane
    theta = np.linspace(-0.45, 0.45, 181)
    for kappa, label, style in ((-Z0 / Z, f"face hobbing, κ = −{Z0}/{Z}: extended epicycloid",
                                 "C3"), (0.0, "face milling, κ = 0: circle of r_c0", "0.5")):
        b, st, _ = crown_tools(kappa)
        r = generated_family(b, st, 0.0, theta, 0.0).r
        ax2.plot(r[:, 0], r[:, 1], color=style, ls="-" if kappa else "--", label=label)
    t = np.linspace(-0.35, 0.35, 50)
    ax2.plot(R * np.cos(t), R * np.sin(t), ":", color="0.6", lw=0.8)
    ax2.plot([0, R], [0, 0], "k-", lw=0.6)
    ax2.plot([R], [0], "ko", ms=4)
    ax2.annotate(f"P (R = {R:g} mm, β = {math.degrees(BETA):g}°)", (R, 0), xytext=(6, -14),
                 textcoords="offset points")
    ax2.plot([0], [0], "k+")
    ax2.annotate("crown centre O", (0, 0), xytext=(4, 4), textcoords="offset points")
    ax2.set_aspect("equal")
    ax2.legend(loc="upper left", fontsize=8)
    ax2.set_xlabel("x_g [mm]")
    ax2.set_ylabel("y_g [mm]")
    ax2.set_title(f"(b) blade-tip trace on a crown gear of z = {Z}, r_c0 = {RC0} mm",
                  fontsize=10)
    fig.tight_layout()
    out = ROOT / "docs" / "figures" / "face_hobbing.png"
    tmp = out.with_name(out.stem + ".tmp.png")
    fig.savefig(tmp, dpi=110)
    tmp.replace(out)
    print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
