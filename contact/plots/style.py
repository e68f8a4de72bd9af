"""The common look of the toolkit's figures: colour maps, labels, titles, saving.

Every figure is a :class:`matplotlib.figure.Figure` made without ``pyplot`` (no global
figure registry, nothing to close; saving uses the Agg canvas). Panels are laid out on a
fixed grid in inches (:func:`panel_grid`): no layout engine runs at save time, which
halves the cost of a figure against constrained layout (``benchmarks/plots.py``).

Colour maps: perceptually uniform sequential ``viridis`` for magnitudes, diverging
``RdBu_r`` centred on zero for signed quantities (slide-to-roll, ease-off change), a
separate sequential ``Reds`` for the edge contact (its pressures, several times the
flank's, would otherwise swamp the flank's scale).

Public functions
----------------
new_figure        an empty Figure of a given size [in], no layout engine
panel_grid        a Figure with a grid of panels, colour-bar axes and room for a legend
hide_unused       hide the grid's unused panels, keep the tick labels of those above
legend_below      one legend for the figure, under the panels
save_png          write a figure as PNG (directory checked) and return the path
png_bytes         a figure as PNG bytes (for the HTML report)
axis_label        "long name [unit]" of a DataArray, units written as a reader expects
case_text         the case name and misalignment of a dataset, for titles
misalignment_text the recorded ΔE, ΔP, ΔG, ΔΣ of a group's attributes as text
torque_text       "T_p = 500 N·m"
symmetric_norm    a colour normalisation centred on zero
title             the figure title in the room the grid left for it
"""

from __future__ import annotations

import io
import json
import os
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from geometry.core.text import plain_number
from geometry.plot import png_target

__all__ = [
    "DIVERGING",
    "DPI",
    "EDGE",
    "EXTRAPOLATED",
    "SEQUENTIAL",
    "axis_label",
    "case_text",
    "hide_unused",
    "legend_below",
    "misalignment_text",
    "new_figure",
    "panel_grid",
    "png_bytes",
    "save_png",
    "symmetric_norm",
    "title",
    "torque_text",
]

#: perceptually uniform sequential colour map (magnitudes)
SEQUENTIAL = "viridis"
#: diverging colour map for signed quantities, always used with :func:`symmetric_norm`
DIVERGING = "RdBu_r"
#: sequential colour map of the edge contact, apart from the flank's
EDGE = "Reds"
#: the mark of results a model extrapolated (friction model outside its fitted range): a
#: colour none of the colour maps above uses, so it never reads as a value
EXTRAPOLATED = "#ff00ff"
#: resolution of the written PNGs [dots per inch]: 150, so that the figures' 7-10 pt text
#: (legends, ticks) keeps 15-21 px of height (at 100 dpi it had 10-14, hard to read once a
#: multi-panel figure is scaled down; issue 56); the report shows each figure at its own
#: size (96 CSS px per inch), sharp on high-density screens and in print
DPI = 150

#: how netCDF (UDUNITS) unit strings are written on axes
_UNIT_TEXT = {"urad": "µrad", "um": "µm", "degC": "°C", "N m": "N·m", "m/s": "m/s",
              "1": "1", "": "1", "rpm": "rpm", "Pa s": "Pa·s"}


def new_figure(width: float, height: float) -> Figure:
    """An empty Figure [in × in], not registered with ``pyplot``, no layout engine."""
    return Figure(figsize=(width, height))


def panel_grid(
    nrows: int,
    ncols: int,
    *,
    panel: tuple[float, float] = (3.0, 2.4),
    colorbars: int = 0,
    legend_rows: int = 0,
    title_lines: int = 2,
    panel_title_lines: int = 1,
    sharex: bool = True,
    sharey: bool = True,
    left: float = 0.75,
    colorbar_width: float = 1.05,
    wspace: float | None = None,
    right: float = 0.2,
) -> tuple[Figure, np.ndarray, list]:
    """A Figure with an (nrows, ncols) grid of panels laid out in inches.

    Parameters
    ----------
    nrows, ncols : int
    panel : (float, float) — [in]
        Width and height of one panel.
    colorbars : int
        Colour-bar axes to the right of the grid, spanning its height.
    legend_rows : int
        Rows of legend entries to leave room for under the panels (:func:`legend_below`).
    title_lines, panel_title_lines : int
        Lines of the figure title and of each panel's title.
    sharex, sharey : bool
        Shared axes (inner tick labels hidden).
    left : float — [in]
        Room for the y label and tick labels.
    colorbar_width : float — [in]
        Room for each colour bar with its ticks and label.
    wspace : float, optional — [in]
        Room between panels (default 0.3 shared y, 0.8 otherwise).
    right : float — [in]
        Room right of the panels (and left of the colour bars).

    Returns
    -------
    fig : matplotlib.figure.Figure
    axes : ndarray (nrows, ncols) of Axes
    colorbar_axes : list of Axes
    """
    pw, ph = panel
    ws = wspace if wspace is not None else (0.3 if sharey else 0.8)
    hs = 0.15 + 0.2 * panel_title_lines + (0.0 if sharex else 0.45)
    top = 0.12 + 0.19 * title_lines + 0.19 * panel_title_lines
    bottom = 0.55 + 0.2 * legend_rows
    right = right + colorbars * colorbar_width
    width = left + ncols * pw + (ncols - 1) * ws + right
    height = top + nrows * ph + (nrows - 1) * hs + bottom
    fig = new_figure(width, height)
    gs = fig.add_gridspec(nrows, ncols, left=left / width, right=(width - right) / width,
                          bottom=bottom / height, top=(height - top) / height,
                          wspace=ws / pw, hspace=hs / ph)
    axes = np.asarray(gs.subplots(sharex=sharex, sharey=sharey, squeeze=False))
    span = (height - top - bottom) * 0.92
    y0 = (bottom + 0.04 * (height - top - bottom)) / height
    cax = [fig.add_axes(((width - right + 0.15 + k * colorbar_width) / width, y0,
                         0.14 / width, span / height)) for k in range(colorbars)]
    return fig, axes, cax


def title(fig: Figure, text: str) -> None:
    """The figure title, at the top of the room :func:`panel_grid` left for it."""
    fig.suptitle(text, y=1 - 0.08 / fig.get_figheight(), va="top", fontsize=9)


def hide_unused(axes: np.ndarray, n: int, xlabel: str = "") -> None:
    """Hide panels n… of a grid; the panels above them get their x tick labels and
    ``xlabel`` back."""
    cols = axes.shape[1]
    flat = axes.ravel()
    for k in range(n, flat.size):
        flat[k].set_visible(False)
        above = k - cols
        if 0 <= above < n:
            flat[above].xaxis.set_tick_params(labelbottom=True)
            flat[above].set_xlabel(xlabel)


def legend_below(fig: Figure, handles, ncols: int = 3) -> None:
    """One legend of the figure under the panels (labels starting with ``_`` left out,
    duplicates merged)."""
    uniq = {}
    for h in handles:
        lab = h.get_label()
        if lab and not lab.startswith("_"):
            uniq.setdefault(lab, h)
    if uniq:
        fig.legend(list(uniq.values()), list(uniq), loc="lower center",
                   bbox_to_anchor=(0.5, 0.0), ncols=min(len(uniq), ncols), fontsize=7,
                   frameon=False)


def save_png(fig: Figure, path: str | os.PathLike[str], dpi: int = DPI) -> Path:
    """Write ``fig`` as PNG and return the path.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure (any ``*_figure`` function's).
    path : str or os.PathLike
        The PNG file to write (as given); its directory must exist.
    dpi : int
        Resolution [1/inch] (default :data:`DPI`).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    InputError
        If the directory does not exist.
    """
    target = png_target(path)
    fig.savefig(target, dpi=dpi)
    return target


def png_bytes(fig: Figure, dpi: int = DPI) -> bytes:
    """``fig`` encoded as PNG."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    return buf.getvalue()


def unit_text(units: str | None) -> str:
    """A UDUNITS string as written on an axis (``urad`` → ``µrad``)."""
    u = "" if units is None else str(units)
    return _UNIT_TEXT.get(u, u)


def axis_label(da: xr.DataArray, name: str | None = None) -> str:
    """``"long name [unit]"`` of ``da`` (``name`` replaces the long name)."""
    text = name or da.attrs.get("long_name") or str(da.name)
    return f"{text} [{unit_text(da.attrs.get('units'))}]"


def _misalignment(attrs) -> dict[str, float] | None:
    """ΔE, ΔP, ΔG [mm], ΔΣ [deg] from the root's ``misalignment_delta_*`` attributes (where
    an analysis file stores it once), a standalone group's ``misalignment`` JSON, or the
    attributes of files written before (None if the dataset records none)."""
    if "misalignment_delta_E_mm" in attrs:
        return {k: float(attrs.get(f"misalignment_delta_{k}_{u}", 0.0))
                for k, u in (("E", "mm"), ("P", "mm"), ("G", "mm"), ("Sigma", "deg"))}
    raw = attrs.get("misalignment")
    if isinstance(raw, str):
        try:
            m = json.loads(raw)
        except ValueError:
            m = None
        if isinstance(m, dict):
            def get(*keys):
                return next((float(m[k]) for k in keys if k in m), 0.0)
            sigma = (get("delta_Sigma_deg") if "delta_Sigma_deg" in m
                     else np.degrees(get("delta_Sigma")))
            return {"E": get("delta_E_mm", "delta_E"), "P": get("delta_P_mm", "delta_P"),
                    "G": get("delta_G_mm", "delta_G"), "Sigma": float(sigma)}
    if "misalignment_dE_mm" in attrs:  # files of hypoid-ltca before issue 21
        return {"E": float(attrs["misalignment_dE_mm"]),
                "P": float(attrs.get("misalignment_dP_mm", 0.0)),
                "G": float(attrs.get("misalignment_dG_mm", 0.0)),
                "Sigma": float(np.degrees(float(attrs.get("misalignment_dSigma_rad", 0.0))))}
    return None


def misalignment_text(attrs) -> str:
    """``"ΔE −0.15, ΔP +0.12 mm, ΔΣ +0.05°"`` (the non-zero errors; ``"aligned"`` if none;
    ΔΣ in degrees, as typed on the command line and in case files)."""
    m = _misalignment(attrs)
    if m is None:
        return ""
    parts = [f"Δ{k} {m[k]:+.3g}" for k in ("E", "P", "G") if m[k]]
    text = ", ".join(parts) + (" mm" if parts else "")
    if m["Sigma"]:
        text += f"{', ' if parts else ''}ΔΣ {m['Sigma']:+.3g}°"
    return (text or "aligned").replace("-", "−")


def case_text(ds: xr.Dataset | xr.DataTree) -> str:
    """The case name, the gear flank and the misalignment of a dataset, for a title."""
    attrs = ds.attrs
    name = attrs.get("case") or "unnamed case"
    flank = attrs.get("gear_flank")
    mis = misalignment_text(attrs)
    return ", ".join(p for p in (name, f"gear {flank} flank" if flank else "", mis) if p)


def torque_text(torque: float) -> str:
    """``"T_p = 500 N·m"`` for a pinion torque [N·m]."""
    return f"T_p = {plain_number(torque)} N·m"


def symmetric_norm(values, floor: float = 1e-12) -> Normalize:
    """A linear normalisation from −m to +m, m the largest finite |value|: zero at the
    centre of a diverging colour map whatever the data's range."""
    v = np.asarray(values, float)
    m = float(np.nanmax(np.abs(v))) if np.isfinite(v).any() else 1.0
    m = max(m, floor)
    return Normalize(vmin=-m, vmax=m)
