"""Maps of swept results: any variable over two swept dimensions, faceted over the rest.

:func:`map_figure` is the generic one: for a study over ΔE × ΔP (``ltca sweep``), speed ×
torque (``ltca efficiency-map``) or any other labelled grid, it draws filled contours of
one variable over two dimensions, one panel per value of the remaining swept
dimensions (all values shown, one colour scale), the sampled points marked (and
written on small grids), axes labelled from the coordinates' ``long_name`` and
``units``. Signed variables get a diverging map centred on zero, others ``viridis``.

Example (a ΔE × ΔP study with a ``torque`` dimension)::

    from contact.plots import map_figure, save_png
    fig = map_figure(study, "lte_peak_to_peak", x="delta_E", y="delta_P", facet="torque")
    save_png(fig, "lte_pp.png")

Public functions
----------------
map_figure                 a variable over (x, y), faceted over the other swept dimensions
efficiency_map_figure      efficiency (or power loss) over speed × torque, every
                           temperature and roughness a panel
efficiency_speed_figure    efficiency against speed per torque (seed Fig. 5.11), faceted
efficiency_roughness_figure  efficiency against roughness per oil temperature (seed
                           Fig. 5.12), one panel per torque and speed
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from contact.plots.style import (
    DIVERGING,
    SEQUENTIAL,
    axis_label,
    hide_unused,
    panel_grid,
    symmetric_norm,
    title,
    unit_text,
)
from geometry.core.errors import InputError
from geometry.core.text import plain_number

__all__ = [
    "efficiency_map_figure",
    "efficiency_roughness_figure",
    "efficiency_speed_figure",
    "facet_title",
    "map_figure",
]


def facet_title(ds: xr.Dataset | xr.DataArray, selection: dict) -> str:
    """``"temperature = 90 °C, roughness = 0.8 µm"`` of one facet's coordinates."""
    parts = []
    for dim, val in selection.items():
        c = ds[dim]
        unit = unit_text(c.attrs.get("units"))
        val_text = f"{val:g}" if isinstance(val, (int, float, np.number)) else str(val)
        unit = "" if unit in ("1", "") else f" {unit}"
        parts.append(f"{c.attrs.get('long_name', dim).split('(')[0].strip()} = {val_text}{unit}")
    return ", ".join(parts)


def _facets(da: xr.DataArray, x: str, y: str, facet) -> list[str]:
    others = [d for d in da.dims if d not in (x, y)]
    if facet is None:
        chosen = [d for d in others if da.sizes[d] > 1]
    else:
        chosen = [facet] if isinstance(facet, str) else list(facet)
    unknown = [d for d in chosen if d not in da.dims]
    if unknown:
        raise InputError(f"facet: {unknown} are not dimensions of {da.name!r} "
                         f"(it has {list(da.dims)})")
    if len(chosen) > 2:
        raise InputError(f"facet: at most two dimensions (rows, columns), got {chosen}; "
                         "select values of the others first (Dataset.sel)")
    loose = [d for d in others if d not in chosen and da.sizes[d] > 1]
    if loose:
        raise InputError(f"facet: {loose} of {da.name!r} have several values; facet over "
                         "them or select one (Dataset.sel)")
    return chosen


def _positions(c: xr.DataArray) -> tuple[np.ndarray, list[str] | None]:
    vals = c.values
    if vals.dtype.kind in "iuf":
        return vals.astype(float), None
    return np.arange(vals.size, dtype=float), [str(v) for v in vals]


def map_figure(
    ds: xr.Dataset,
    var: str,
    x: str,
    y: str,
    facet: str | Sequence[str] | None = None,
    *,
    diverging: bool | None = None,
    levels: int = 12,
    heading: str | None = None,
    label: str | None = None,
) -> Figure:
    """Filled contours of ``ds[var]`` over (x, y), one panel per value of the facet dims.

    Parameters
    ----------
    ds : xarray.Dataset
        A labelled study: ``var`` over ``x``, ``y`` and possibly other dimensions, its
        coordinates with ``long_name`` and ``units`` (used for the axes).
    var : str
        The variable drawn (any units; its ``long_name`` and ``units`` label the colour bar).
    x, y : str
        The dimensions on the horizontal and vertical axes (numeric or text coordinates).
    facet : str or sequence of up to two str, optional
        The dimensions with one panel per value (two: rows × columns). Default: every
        other dimension with more than one value. Every value is shown.
    diverging : bool, optional
        Diverging colour map centred on zero; default when the values change sign.
    levels : int
        Number of filled-contour levels (shared by all panels).
    heading : str, optional
        Figure title (default: the dataset's ``case`` and the variable's long name).
    label : str, optional
        Colour-bar label (default ``long_name [units]``).

    Returns
    -------
    matplotlib.figure.Figure
        Filled contours of ``var`` over ``x`` × ``y``, one panel per value of ``facet``,
        axes and colour bar labelled with the coordinates' ``long_name`` and ``units``.

    Raises
    ------
    InputError
        If ``var`` is missing, ``x``/``y`` are not its dimensions, or a dimension with
        several values is neither drawn nor faceted.
    """
    if var not in ds:
        raise InputError(f"var: {var!r} is not in the dataset (it has {list(ds.data_vars)})")
    da = ds[var]
    for name, d in (("x", x), ("y", y)):
        if d not in da.dims:
            raise InputError(f"{name}: {d!r} is not a dimension of {var!r} ({list(da.dims)})")
    if x == y:
        raise InputError(f"x, y: must differ, both are {x!r}")
    fdims = _facets(da, x, y, facet)
    squeeze = [d for d in da.dims if d not in (x, y, *fdims)]
    da = da.isel({d: 0 for d in squeeze})
    vals = np.asarray(da.values, float)
    finite = np.isfinite(vals)
    signed = bool(finite.any() and np.nanmin(vals) < 0 < np.nanmax(vals))
    if diverging if diverging is not None else signed:
        norm, cmap = symmetric_norm(vals), DIVERGING
    else:
        lo = float(np.nanmin(vals)) if finite.any() else 0.0
        hi = float(np.nanmax(vals)) if finite.any() else 1.0
        norm, cmap = Normalize(lo, hi if hi > lo else lo + max(abs(lo), 1.0) * 1e-6), SEQUENTIAL
    lev = np.linspace(norm.vmin, norm.vmax, levels + 1)
    xs, xt = _positions(ds[x])
    ys, yt = _positions(ds[y])
    rows_dim = fdims[0] if len(fdims) == 2 else None
    cols_dim = fdims[-1] if fdims else None
    if rows_dim is not None:
        nrows, ncols = ds.sizes[rows_dim], ds.sizes[cols_dim]
        cells = [{rows_dim: i, cols_dim: j} for i in range(nrows) for j in range(ncols)]
    elif cols_dim is not None:
        n = ds.sizes[cols_dim]
        ncols = min(n, 3)
        nrows = -(-n // ncols)
        cells = [{cols_dim: j} for j in range(n)]
    else:
        nrows = ncols = 1
        cells = [{}]
    # a lone panel is drawn larger: its title, axis labels and annotations fit
    fig, grid, (cax,) = panel_grid(nrows, ncols, panel=(3.0, 2.3) if ncols > 1 else (5.0, 3.2),
                                   colorbars=1, left=0.9)
    axes = grid.ravel()
    mappable = None
    annotate = xs.size * ys.size <= 40
    for ax, sel in zip(axes, cells, strict=False):
        z = da.isel(sel).transpose(y, x).values
        if xs.size >= 2 and ys.size >= 2 and np.isfinite(z).sum() >= 4:
            mappable = ax.contourf(xs, ys, np.ma.masked_invalid(z), levels=lev, cmap=cmap,
                                   norm=norm, extend="both")
            cl = ax.contour(xs, ys, np.ma.masked_invalid(z), levels=lev[::2], colors="k",
                            linewidths=0.4, alpha=0.6)
            ax.clabel(cl, fontsize=6, fmt="%.4g")
        else:
            mappable = ax.pcolormesh(xs, ys, z, cmap=cmap, norm=norm, shading="nearest")
        xx, yy = np.meshgrid(xs, ys)
        ax.plot(xx.ravel(), yy.ravel(), "k.", ms=2.5)
        if annotate:
            for xi, yi, zi in zip(xx.ravel(), yy.ravel(), z.ravel(), strict=True):
                if np.isfinite(zi):
                    ax.annotate(f"{zi:.4g}", (xi, yi), xytext=(0, 4), textcoords="offset points",
                                ha="center", va="bottom", fontsize=6)
        if xt is not None:
            ax.set_xticks(xs, xt)
        if yt is not None:
            ax.set_yticks(ys, yt)
        ax.set_xlabel(axis_label(ds[x]))
        ax.set_ylabel(axis_label(ds[y]))
        if sel:
            ax.set_title(facet_title(ds, {d: ds[d].values[i] for d, i in sel.items()}),
                         fontsize=8)
    hide_unused(grid, len(cells), axis_label(ds[x]))
    fig.colorbar(mappable, cax=cax, label=label or axis_label(da))
    if heading is None:
        case = ds.attrs.get("case", "")
        fixed = {d: ds[d].values[0] for d in squeeze if d in ds.coords}
        heading = (f"{case + ': ' if case else ''}{da.attrs.get('long_name', var)}"
                   + (f" ({facet_title(ds, fixed)})" if fixed else ""))
    chars = int(fig.get_figwidth() * 14)  # 9 pt: about 14 characters per inch
    title(fig, "\n".join(textwrap.wrap(heading, chars)))
    return fig


def _percent(emap: xr.Dataset) -> xr.Dataset:
    out = emap.copy()
    if "efficiency" in emap:
        out["efficiency"] = (emap["efficiency"] * 100).assign_attrs(
            units="%", long_name="mechanical efficiency")
    return out


def _emap_title(emap: xr.Dataset, what: str) -> str:
    a = emap.attrs
    return (f"{a.get('case', '')}: {what} ({a.get('lubricant', '')}, "
            f"{a.get('friction_model', '')} friction)")


def efficiency_map_figure(emap: xr.Dataset, var: str = "efficiency") -> Figure:
    """Efficiency (or another map variable) over pinion speed × torque, one panel per oil
    temperature and roughness (every swept value shown, one colour scale).

    Parameters
    ----------
    emap : xarray.Dataset
        The output of :func:`contact.study.efficiency.efficiency_map` (``efficiency`` [1],
        ``power_loss`` [W] over torque, speed, temperature, roughness).
    var : str
        ``efficiency`` (drawn in %) or ``power_loss`` …

    Returns
    -------
    matplotlib.figure.Figure
    """
    ds = _percent(emap)
    what = ds[var].attrs.get("long_name", var) if var in ds else var
    swept = swept_dims(emap)
    x, y = (swept + [d for d in EMAP_DIMS if d not in swept])[:2] if len(swept) >= 2 \
        else ("speed", "torque")
    return map_figure(ds, var, x=x, y=y, heading=_emap_title(emap, what))


#: the dimensions of an efficiency map, in the order they take the map's axes
EMAP_DIMS = ("speed", "torque", "temperature", "roughness")


def swept_dims(emap: xr.Dataset) -> list[str]:
    """The dimensions of an efficiency map with more than one value, in :data:`EMAP_DIMS`
    order (the map's x and y are the first two: a sweep of temperature × roughness at one
    speed and torque is drawn over temperature × roughness, not as one-dot panels)."""
    return [d for d in EMAP_DIMS if emap.sizes.get(d, 1) > 1]


def _line_facets(emap: xr.Dataset, dims: Sequence[str]):
    dims = [d for d in dims if d in emap.dims]
    shape = [emap.sizes[d] for d in dims]
    cells = [dict(zip(dims, idx, strict=True)) for idx in np.ndindex(*shape)] or [{}]
    ncols = shape[-1] if len(dims) == 2 else min(len(cells), 3)
    nrows = -(-len(cells) // ncols)
    return cells, nrows, ncols


def _efficiency_lines(emap: xr.Dataset, *, x: str, x_name: str, line: str, line_label,
                      facets: tuple[str, str], panel: tuple[float, float], ylabel: str,
                      title_size: float, what: str) -> Figure:
    """Efficiency [%] against ``x``, one line per value of ``line`` (labelled by
    ``line_label(value)``), one panel per combination of the ``facets`` values."""
    if "efficiency" not in emap:
        raise InputError("emap: dataset lacks 'efficiency' (not an efficiency map)")
    cells, nrows, ncols = _line_facets(emap, facets)
    # a single panel takes a page column's width, so its title is not clipped
    width = panel[0] if ncols > 1 else max(panel[0], 6.0)
    fig, grid, _ = panel_grid(nrows, ncols, panel=(width, panel[1]), left=0.8)
    axes = grid.ravel()
    xlabel = axis_label(emap[x], x_name)
    for ax, sel in zip(axes, cells, strict=False):
        eff = emap["efficiency"].isel(sel) * 100
        for v in emap[line].values:
            ax.plot(emap[x].values, eff.sel({line: v}).values, "o-", ms=3,
                    label=line_label(v))
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.set_title(facet_title(emap, {d: emap[d].values[i] for d, i in sel.items()}),
                     fontsize=title_size)
    hide_unused(grid, len(cells), xlabel)
    axes[0].legend(fontsize=7)
    chars = int(fig.get_figwidth() * 14)  # 9 pt: about 14 characters per inch
    title(fig, "\n".join(textwrap.wrap(_emap_title(emap, what), chars)))
    return fig


def efficiency_speed_figure(emap: xr.Dataset) -> Figure:
    """Efficiency against pinion speed, one line per torque (seed Fig. 5.11); one panel
    per oil temperature × roughness, so every swept value is shown.

    Parameters
    ----------
    emap : xarray.Dataset

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If ``emap`` lacks ``efficiency``.
    """
    return _efficiency_lines(emap, x="speed", x_name="pinion speed", line="torque",
                             line_label=lambda t: f"T_p = {plain_number(t)} N·m",
                             facets=("temperature", "roughness"), panel=(3.0, 2.2),
                             ylabel="mechanical efficiency [%]", title_size=8,
                             what="efficiency against speed")


def efficiency_roughness_figure(emap: xr.Dataset) -> Figure:
    """Efficiency against roughness, one line per oil temperature (seed Fig. 5.12); one
    panel per torque × speed.

    Parameters
    ----------
    emap : xarray.Dataset

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If ``emap`` lacks ``efficiency``.
    """
    return _efficiency_lines(emap, x="roughness", x_name="RMS roughness Rq",
                             line="temperature", line_label=lambda t: f"oil {t:g} °C",
                             facets=("torque", "speed"), panel=(2.7, 2.0),
                             ylabel="efficiency [%]", title_size=7,
                             what="efficiency against roughness")
