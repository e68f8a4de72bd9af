"""Figures of design studies: sensitivity maps, tolerance histograms, the V-H check.

Each function takes a study's dataset and returns a matplotlib Figure (made without
``pyplot``: no backend set, nothing global changed);
:func:`save_study_figures` writes the figures of any study result into a directory.
Maps use perceptually uniform colour maps (``viridis``; ``cividis`` for positions),
every panel names its variable and units, and every title names the case and the
operating point.

Public functions
----------------
sensitivity_map_figure   maps of LTE p-p, peak pressure, edge share, pattern centre over
                         two swept inputs (one figure per torque)
tolerance_figure         histograms of LTE p-p, peak pressure, efficiency with percentiles
vh_check_figure          the loaded pattern at the toe, nominal and heel positions
save_study_figures       all figures of a study result as PNGs
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.patches import Rectangle
from matplotlib.ticker import MaxNLocator

from contact.study.monte_carlo import draw_values
from contact.study.points import POINT_INPUTS
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.text import plain_number
from geometry.plot import new_figure

__all__ = ["MAP_VARIABLES", "TOLERANCE_VARIABLES", "save_study_figures",
           "sensitivity_map_figure", "tolerance_figure", "vh_check_figure"]

#: Variables drawn in a sensitivity map, with their colour maps.
MAP_VARIABLES = (("lte_peak_to_peak", "viridis"), ("pressure_max_flank", "viridis"),
                 ("edge_load_share", "viridis"), ("pattern_centre_u", "cividis"))

#: Variables of the tolerance histograms (those present in the study).
TOLERANCE_VARIABLES = ("lte_peak_to_peak", "pressure_max_flank", "efficiency")

_SYMBOL = {"delta_E": "ΔE", "delta_P": "ΔP", "delta_G": "ΔG", "delta_Sigma": "ΔΣ",
           "deviation_scale": "deviation scale", "lte_peak_to_peak": "LTE peak-to-peak",
           "pressure_max_flank": "peak flank pressure", "pressure_max_edge":
           "peak edge pressure", "edge_load_share": "edge load share",
           "pattern_centre_u": "pattern centre, toe → heel",
           "pattern_centre_v": "pattern centre, root → tip"}


def _label(ds: xr.Dataset, name: str) -> str:
    units = ds[name].attrs.get("units", "")
    long_name = _SYMBOL.get(name, ds[name].attrs.get("long_name", name))
    return f"{long_name} [{units}]" if units else long_name


def sensitivity_map_figure(ds: xr.Dataset, torque: float | None = None, *,
                           x: str | None = None, y: str | None = None):
    """Maps of the main summaries over two swept inputs, at one torque.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`contact.study.sweep` result with at least two swept inputs (others
        must have one value).
    torque : float — [N·m], optional
        Default the first of the study.
    x, y : str, optional
        Inputs on the horizontal and vertical axes (default the first two swept).

    Returns
    -------
    matplotlib.figure.Figure
        One panel per :data:`MAP_VARIABLES` (filled contours, failed points blank and
        marked ×).

    Raises
    ------
    InputError
        Fewer than two swept inputs, or a third with more than one value.
    """
    swept = [d for d in ds.dims if d in POINT_INPUTS]
    if len(swept) < 2:
        raise InputError("map: a sensitivity map needs two swept inputs, the study has "
                         f"{swept}")
    x = x or swept[0]
    y = y or swept[1]
    sel = {d: 0 for d in swept if d not in (x, y) and ds.sizes[d] == 1}
    if any(ds.sizes[d] > 1 for d in swept if d not in (x, y)):
        raise InputError("map: the study sweeps more than two inputs; select one value of "
                         "the others first (ds.sel(...))")
    t = float(ds["torque"].values[0] if torque is None else torque)
    m = ds.isel(sel).sel(torque=t)
    fig = new_figure(figsize=(10, 8), layout="constrained")
    axes = fig.subplots(2, 2)
    X, Y = m[x].values, m[y].values
    failed = m["status"].transpose(x, y).values == 2
    for ax, (name, cmap) in zip(axes.ravel(), MAP_VARIABLES, strict=True):
        Z = m[name].transpose(x, y).values.astype(float)
        if np.isfinite(Z).sum() >= 4 and X.size > 1 and Y.size > 1:
            cs = ax.contourf(X, Y, Z.T, levels=12, cmap=cmap)
            ax.contour(X, Y, Z.T, levels=cs.levels, colors="k", linewidths=0.3)
            fig.colorbar(cs, ax=ax, label=_label(ds, name))
        ax.plot(*np.meshgrid(X, Y, indexing="ij"), ".", color="0.4", ms=2)
        if failed.any():
            gx, gy = np.meshgrid(X, Y, indexing="ij")
            ax.plot(gx[failed], gy[failed], "x", color="crimson", label="failed")
            ax.legend(loc="lower right", fontsize=7, framealpha=0.8)
        ax.set_xlabel(_label(ds, x))
        ax.set_ylabel(_label(ds, y))
        ax.set_title(_SYMBOL.get(name, name), fontsize=10)
    fig.suptitle(f"{ds.attrs.get('case', '')}: sensitivity at pinion torque {plain_number(t)} N m")
    return fig


def tolerance_figure(ds: xr.Dataset, torque: float | None = None):
    """Histograms of the Monte Carlo outputs, with the 5, 50 and 95 % percentiles.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`contact.study.sample` result.
    torque : float — [N·m], optional
        Default the first of the study.

    Returns
    -------
    matplotlib.figure.Figure
    """
    t = float(ds["torque"].values[0] if torque is None else torque)
    names = [n for n in TOLERANCE_VARIABLES if n in ds.data_vars]
    fig = new_figure(figsize=(4.2 * len(names), 3.6), layout="constrained")
    axes = fig.subplots(1, len(names), squeeze=False)
    ok = ds["status"].values != 2
    for ax, name in zip(axes[0], names, strict=True):
        values = draw_values(ds, name, t)
        if name == "efficiency":
            values = 100.0 * values
            label = "mesh efficiency [%]"
        else:
            label = _label(ds, name)
        if values.size:
            ax.hist(values, bins=min(40, max(5, values.size // 10)), color="#3b6fb6",
                    edgecolor="white", linewidth=0.5)
            # the percentiles as lines, their values in the panel's title: no label over
            # the bars
            ps = np.percentile(values, (5, 50, 95))
            for p, ls in zip(ps, (":", "-", ":"), strict=True):
                ax.axvline(p, color="k", ls=ls, lw=1)
            ax.set_title(f"P5 {ps[0]:.4g} | P50 {ps[1]:.4g} | P95 {ps[2]:.4g}", fontsize=8)
        ax.set_xlabel(label)
        ax.set_ylabel("draws [1]")
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))  # draws are counted
    n_fail = int((~ok).sum())
    fig.suptitle(f"{ds.attrs.get('case', '')}: {ok.sum()} draws ({ds.attrs.get('method', '')}"
                 f"{f', {n_fail} failed' if n_fail else ''}) at pinion torque "
                 f"{plain_number(t)} N·m; "
                 "dotted P5, P95, solid P50")
    return fig


def vh_check_figure(vh: xr.Dataset):
    """The loaded pattern at the toe, nominal and heel positions of a V-H check.

    Parameters
    ----------
    vh : xarray.Dataset
        A :func:`contact.study.vh_check` result.

    Returns
    -------
    matplotlib.figure.Figure
        Three panels on the normalised gear flank (toe → heel, root → tip), each with
        its V and H, the target and the pattern centre; one colour scale.
    """
    fig = new_figure(figsize=(13, 4), layout="constrained")
    axes = fig.subplots(1, 3, sharey=True)
    env = vh["pressure_envelope"]
    vmax = float(np.nanmax(env.values)) or 1.0
    u, v = vh["u"].values, vh["v"].values
    mesh = None
    for ax, pos in zip(axes, vh["position"].values, strict=True):
        p = env.sel(position=pos).values.T
        mesh = ax.pcolormesh(u, v, np.ma.masked_less_equal(p, 0.0), cmap="viridis",
                             vmin=0.0, vmax=vmax, shading="nearest")
        ax.add_patch(Rectangle((0, 0), 1, 1, fill=False, lw=1.2, color="k"))
        r = vh.sel(position=pos)
        ax.plot(float(r["pattern_centre_u"]), float(r["pattern_centre_v"]), "o", mfc="none",
                mec="crimson", ms=9, label="pattern centre")
        if np.isfinite(float(r["target_u"])):
            ax.axvline(float(r["target_u"]), color="crimson", ls="--", lw=1, label="target")
        ax.set_xlim(-0.02, 1.02)
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel("gear face width: toe → heel [1]")
        ax.set_title(f"{pos}: V = {float(r['V']):+.3f} mm, H = {float(r['H']):+.3f} mm",
                     fontsize=10)
    axes[0].set_ylabel("gear whole depth: root → tip [1]")
    axes[0].legend(loc="lower left", fontsize=7)
    fig.colorbar(mesh, ax=axes, label="maximum pressure [MPa]")
    fig.suptitle(f"{vh.attrs.get('case', '')}: V-H check at pinion torque "
                 f"{plain_number(vh.attrs.get('torque_N_m', float('nan')))} N m")
    return fig


def save_study_figures(ds: xr.Dataset, directory: str | os.PathLike[str]) -> list[Path]:
    """Write the figures of a study result (sweep, sample or V-H check) as PNGs.

    Parameters
    ----------
    ds : xarray.Dataset
        A result of :func:`contact.study.sweep`, :func:`contact.study.sample` or
        :func:`contact.study.vh_check`.
    directory : path-like
        Existing directory.

    Returns
    -------
    list of pathlib.Path
        The files written (``<case>_map_T<torque>.png``, ``<case>_tolerance_T….png`` or
        ``<case>_vh_check.png``).

    Raises
    ------
    InputError
        A directory that does not exist, or a dataset that is no study result.
    """
    out = Path(directory)
    if not out.is_dir():
        raise InputError(f"plots: directory {str(out)!r} does not exist")
    case = ds.attrs.get("case", "study")
    kind = ds.attrs.get("study")
    figs = []
    if kind == "vh-check":
        figs.append((vh_check_figure(ds), f"{case}_vh_check.png"))
    elif kind == "sample":
        figs += [(tolerance_figure(ds, t), f"{case}_tolerance_T{t:g}.png")
                 for t in ds["torque"].values]
    elif kind == "sweep":
        if sum(1 for d in ds.dims if d in POINT_INPUTS and ds.sizes[d] > 1) == 2:
            figs += [(sensitivity_map_figure(ds, t), f"{case}_map_T{t:g}.png")
                     for t in ds["torque"].values]
    else:
        raise InputError(f"plots: not a study result (study attribute {kind!r})")
    paths = []
    for fig, name in figs:
        path = out / name
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=110, format="png")
        paths.append(path)
    return paths
