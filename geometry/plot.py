"""Plots of tooth flanks: both members in mesh, and each flank's projection-plane grid.

matplotlib figures made without ``pyplot`` (:func:`new_figure`: no backend set, no global
state); every function writes a PNG (atomically) and returns its path. Lengths are drawn in mm.

Public functions
----------------
plot_flanks_in_mesh      3-D view of pinion and gear flanks placed in the pair frame
plot_projection_grid     a flank's grid in its projection plane, coloured by mask reason,
                         with the blank outline (root, face, toe and heel cones)
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.machine.flank import FlankSurface, blank_outline
from geometry.pair.assembly import case_transforms, transform_points

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_flanks_in_mesh", "plot_projection_grid"]


def new_figure(**kwargs: Any) -> Figure:
    """An empty :class:`matplotlib.figure.Figure`, made without ``pyplot``; shared by the
    toolkit's plots.

    No backend is chosen and nothing global changes (``matplotlib.use`` is never called,
    the figure is not registered with ``pyplot``, so no ``close`` is needed): a notebook's
    inline figures keep working. ``Figure.savefig`` renders PNG with Agg by itself.

    Parameters
    ----------
    **kwargs
        Passed to :class:`matplotlib.figure.Figure` (``figsize`` [in], ``layout`` …).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    return Figure(**kwargs)


def png_target(path) -> Path:
    """The PNG path to write, after checking its directory exists (InputError otherwise)."""
    p = Path(path)
    if not p.parent.exists():
        raise InputError(f"path: directory {str(p.parent)!r} does not exist")
    return p


def plot_flanks_in_mesh(case, surfaces: Iterable[FlankSurface], path: str | os.PathLike[str],
                        *, pinion_rotation: float = 0.0, gear_rotation: float = 0.0,
                        teeth: int = 1) -> Path:
    """Draw flanks of both members in the global pair frame and save a PNG.

    Parameters
    ----------
    case : geometry.case.Case
    surfaces : iterable of FlankSurface
        Flanks to draw (any members and flanks), e.g. from
        :func:`geometry.machine.flank.flank_surface`.
    path : path-like
        PNG file to write; its directory must exist.
    pinion_rotation, gear_rotation : float — [rad]
        Rotations of the members about their axes (see :mod:`geometry.pair.assembly`).
    teeth : int
        How many neighbouring teeth (slot copies rotated by one pitch) to draw, ≥ 1.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory does not exist or ``teeth`` < 1.
    """
    if int(teeth) < 1:
        raise InputError(f"teeth: must be >= 1, got {teeth!r}")
    target = png_target(path)
    fig = new_figure(figsize=(8, 7))
    ax = fig.add_subplot(projection="3d")
    colours = {("pinion", "concave"): "tab:blue", ("pinion", "convex"): "tab:cyan",
               ("gear", "concave"): "tab:red", ("gear", "convex"): "tab:orange"}
    for fs in surfaces:
        n = case.member(fs.member).blank.teeth
        for k in range(int(teeth)):
            pitch = 2.0 * np.pi * k / n
            rot_p = pinion_rotation + (pitch if fs.member == "pinion" else 0.0)
            rot_g = gear_rotation + (pitch if fs.member == "gear" else 0.0)
            tp, tg = case_transforms(case, rot_p, rot_g)
            pts = transform_points(tp if fs.member == "pinion" else tg, fs.position)
            ax.plot_wireframe(pts[..., 0], pts[..., 1], pts[..., 2], rstride=4, cstride=4,
                              color=colours.get((fs.member, fs.flank), "k"), linewidth=0.5,
                              label=f"{fs.member} {fs.flank}" if k == 0 else None)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.set_title(f"{case.name}: flanks in the pair frame")
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    with atomic_path(target) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    return target


def plot_projection_grid(surface: FlankSurface, blank, path: str | os.PathLike[str]) -> Path:
    """Draw a flank's projection-plane grid with its mask, and the blank outline; save a PNG.

    Parameters
    ----------
    surface : FlankSurface
    blank : geometry.case.Blank
        The member's blank (for the outline).
    path : path-like
        PNG file to write; its directory must exist.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory does not exist.
    """
    from geometry.machine.meshing import REASONS

    target = png_target(path)
    out = blank_outline(blank)
    c = out.corners
    fig = new_figure(figsize=(7, 5))
    ax = fig.subplots()
    ring = np.array([c[0, 0], c[1, 0], c[1, 1], c[0, 1], c[0, 0]])
    ax.plot(ring[:, 0], ring[:, 1], "k-", lw=1, label="blank outline")
    g = surface.grid
    ax.plot(g.axial, g.radius, color="0.75", lw=0.4)
    ax.plot(g.axial.T, g.radius.T, color="0.75", lw=0.4)
    for code, name in REASONS.items():
        sel = surface.reason == code
        if sel.any():
            ax.plot(g.axial[sel], g.radius[sel], ".", ms=3 if code == 0 else 6,
                    label=f"{name} ({int(sel.sum())})")
    ax.plot(*out.mean_point, "k+", ms=10, label="mean pitch point")
    ax.set_aspect("equal")
    ax.set_xlabel("axial position z [mm]")
    ax.set_ylabel("radius [mm]")
    ax.set_title(f"{surface.member} {surface.flank}: projection-plane grid")
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    with atomic_path(target) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    return target
