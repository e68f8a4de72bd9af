"""Draw the machine-setting convention figure of docs/machine.md.

Run from the repository root::

    python docs/figures/machine_frames.py

writes ``docs/figures/machine_frames.png``: (a) the cradle plane seen from the work (along
−z_m) with the cutter of the example spiral-bevel gear, (b) the section y_m = 0 with the work
axis, the blank's root cone and the blade tips, (c) the pair frame of the hypoid example.
All geometry is computed by the toolkit from the example case files.
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

from geometry.case import load_case  # noqa: E402
from geometry.machine.flank import flank_surface  # noqa: E402
from geometry.pair.assembly import case_transforms, transform_points  # noqa: E402


def main() -> None:
    case = load_case(ROOT / "cases" / "spiral_bevel_iso23509_s1.toml")
    st = case.gear.concave.machine
    r_ob = case.gear.concave.blade.point_radius
    r_ib = case.gear.convex.blade.point_radius
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.4))

    # (a) cradle plane, seen from the work: x_m to the right, y_m up
    ax = axes[0]
    qc, sr = st.cradle_angle, st.radial_setting
    c = np.array([sr * math.cos(qc), sr * math.sin(qc)])
    t = np.linspace(0, 2 * math.pi, 400)
    for r, lab in ((r_ob, "outside blades (concave flank)"),
                   (r_ib, "inside blades (convex flank)")):
        ax.plot(c[0] + r * np.cos(t), c[1] + r * np.sin(t), lw=1, label=lab)
    ax.plot([0, c[0]], [0, c[1]], "k-", lw=1)
    ax.annotate("", xy=c, xytext=(0, 0), arrowprops=dict(arrowstyle="->"))
    ax.text(*(0.55 * c + [5, 0]), "$S_r$")
    arc = np.linspace(0, qc, 50)
    ax.plot(25 * np.cos(arc), 25 * np.sin(arc), "k-", lw=0.8)
    ax.text(28 * math.cos(qc / 2), 28 * math.sin(qc / 2), "$q_c$")
    rm = 83.16  # mean root cone distance of the example gear
    ax.plot([0, 120], [0, 0], "k--", lw=0.8)
    ax.plot(rm, 0, "ko")
    ax.text(rm - 10, 8, "mean point", fontsize=8)
    ax.annotate("", xy=(40, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", lw=2))
    ax.annotate("", xy=(0, 40), xytext=(0, 0), arrowprops=dict(arrowstyle="->", lw=2))
    ax.text(42, 3, "$x_m$")
    ax.text(-12, 42, "$y_m$")
    ax.plot(0, 0, "ko")
    ax.text(-95, 175, "cradle axis $z_m$ at the origin,\npointing at the viewer (the work)",
            fontsize=8)
    ax.set_aspect("equal")
    ax.set_title("(a) cradle plane $z_m = 0$ (right-hand member, $q_c > 0$)")
    ax.legend(fontsize=8, loc="lower left")
    ax.set_xlabel("$x_m$ [mm]")
    ax.set_ylabel("$y_m$ [mm]")

    # (b) section y_m = 0: work axis at the machine root angle, root cone, blade tips
    ax = axes[1]
    g = st.machine_root_angle
    a = np.array([math.cos(g), math.sin(g)])
    apex = np.array([0.0, -st.sliding_base]) + st.machine_center_to_back * a
    root_apex = apex - case.gear.blank.root_apex * a
    ax.plot([-20, 130], [0, 0], "k-", lw=1)
    ax.text(-20, -7, "blade-tip plane $z_m = 0$", fontsize=8)
    ax.fill_between([55, 110], [0, 0], [-9, -9], color="0.85")
    ax.text(60, -14, "cutter blades (body at $z_m < 0$)", fontsize=8)
    s = np.linspace(0, 140, 2)
    ax.plot(root_apex[0] + s * a[0], root_apex[1] + s * a[1], "b-", lw=1.5)
    ax.text(*(root_apex + 110 * a + [3, 0]), "work axis $z_g$", color="b")
    d_f = case.gear.blank.root_angle
    gen = np.array([math.cos(g - d_f), math.sin(g - d_f)])
    ax.plot(root_apex[0] + s * gen[0], root_apex[1] + s * gen[1], "b--", lw=1)
    ax.text(88, 3, "root generatrix", color="b", fontsize=8)
    arc = np.linspace(0, g, 40)
    ax.plot(30 * np.cos(arc), 30 * np.sin(arc), "k-", lw=0.8)
    ax.text(32 * math.cos(g / 2), 32 * math.sin(g / 2), r"$\gamma_m$")
    ax.annotate("", xy=(0, 45), xytext=(0, 0), arrowprops=dict(arrowstyle="->", lw=2))
    ax.annotate("", xy=(45, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", lw=2))
    ax.text(2, 47, "$z_m$ (cradle axis)")
    ax.text(46, 2, "$x_m$")
    ax.text(62, 55, "member body at $z_m > 0$\n$X_p$: crossing point along $z_g$\n"
            "$X_b$: work moved along $-z_m$ (deeper)\n$E_m$: work axis at $y_m = E_m$",
            fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlim(-25, 135)
    ax.set_ylim(-25, 135)
    ax.set_title("(b) section $y_m = 0$ (example gear, Formate)")
    ax.set_xlabel("$x_m$ [mm]")
    ax.set_ylabel("$z_m$ [mm]")

    # (c) pair frame of the hypoid example: flanks placed with case_transforms
    ax = axes[2]
    hyp = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    tp, tg = case_transforms(hyp, 0.0, math.radians(hyp.extra["derivation"][
        "gear_rotation_deg"]))
    for member, t, col in (("pinion", tp, "tab:blue"), ("gear", tg, "tab:red")):
        for flank in ("concave", "convex"):
            fs = flank_surface(hyp, member, flank, nu=11, nv=5)
            p = transform_points(t, fs.position)
            ax.plot(p[..., 0].ravel(), p[..., 2].ravel(), ".", ms=1.5, color=col)
        o, z = t[:3, 3], t[:3, 2]
        ax.plot([o[0], o[0] + 110 * z[0]], [o[2], o[2] + 110 * z[2]], "-", color=col, lw=1)
        ax.text(o[0] + 80 * z[0] + 2, o[2] + 80 * z[2] + 2, f"{member} axis $z$", color=col)
    ax.text(20, 95, "origin: gear crossing point\npinion axis at $y_f = +E$ (right-hand gear,"
            " $E > 0$)\nmesh zone on the $+x$ side of both members", fontsize=8)
    ax.set_aspect("equal")
    ax.set_title("(c) pair frame, hypoid example (projection on $x_f$–$z_f$)")
    ax.set_xlabel("$x_f$ [mm]")
    ax.set_ylabel("$z_f$ [mm]")
    fig.tight_layout()
    out = Path(__file__).with_suffix(".png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
