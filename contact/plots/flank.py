"""Figures over the gear flank: ease-off, contact patterns, pressure, friction quantities.

Each function takes the result datasets (the groups of ``ltca run``'s file) and returns a
:class:`matplotlib.figure.Figure`; :mod:`contact.plots.analysis` names and saves them.
Where torques are compared the panels share one colour scale; signed quantities use a
diverging map centred on zero; the masked nodes of the flank are hatched and keyed.

Public functions
----------------
easeoff_topography_figure  ease-off as a surface over the normalised tooth (seed Fig. 2.8)
easeoff_contour_figure     ease-off on the projection plane with roll-angle iso-lines
                           (seed Fig. 2.7)
easeoff_map_figure         a (u, v) variable of /easeoff on the normalised tooth, one panel
                           per dataset (theoretical and deviated side by side)
contact_pattern_figure     unloaded and loaded patterns on one outline, one panel per torque,
                           with the paths of contact (seed Figs. 2.10, 3.7)
pressure_figure            maximum contact pressure over the mesh cycles, one panel per
                           torque and one colour scale; edge contact apart (seed Fig. 3.7)
segment_map_figure         any segment variable (torque, roll, pair, segment) on the flank
segment_panels_figure      segment values of several analyses side by side, one scale
friction_flank_figure      the efficiency quantities, the flash temperature and the
                           specific film thickness on the flank at one torque, a panel each
                           (seed Figs. 5.5–5.10)
colour_index               the colour-map entry of each value (the segments are drawn as
                           one path per entry)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import xarray as xr
from matplotlib import colormaps
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap, Normalize
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import MaxNLocator

from contact.plots.style import (
    DIVERGING,
    EDGE,
    EXTRAPOLATED,
    SEQUENTIAL,
    axis_label,
    case_text,
    hide_unused,
    legend_below,
    new_figure,
    panel_grid,
    symmetric_norm,
    title,
    torque_text,
)
from contact.plots.tooth import (
    PROFILE_LABEL,
    TOE_HEEL_LABEL,
    draw_projection_outline,
    draw_tooth,
    edge_points,
    masked_reasons,
    require,
    segment_pieces,
)
from geometry.core.errors import InputError

__all__ = [
    "FRICTION_FLANK_PLOTS",
    "colour_index",
    "contact_pattern_figure",
    "easeoff_contour_figure",
    "easeoff_map_figure",
    "easeoff_topography_figure",
    "friction_flank_figure",
    "pressure_figure",
    "segment_map_figure",
    "segment_panels_figure",
]

#: /friction variables drawn over the gear flank (seed Figs. 5.5–5.10), and the flash
#: temperature and specific film thickness of scuffing and micropitting
#: (/scuffing_micropitting, merged in by the analysis figures); signed ones diverge
FRICTION_FLANK_PLOTS = {
    "sliding_velocity": "sliding velocity",
    "rolling_velocity": "rolling velocity",
    "slide_to_roll": "slide-to-roll ratio",
    "lambda_ratio": "lambda ratio",
    "friction_coefficient": "friction coefficient",
    "sliding_loss": "sliding power loss",
    "flash_temperature": "flash temperature",
    "specific_film_thickness": "specific film thickness λ_GF",
}


def _grid(n: int) -> tuple[int, int]:
    """(rows, columns) of n panels: up to three a row."""
    n = max(n, 1)
    cols = 2 if n == 4 else min(n, 3)
    return -(-n // cols), cols


def easeoff_topography_figure(easeoff: xr.Dataset) -> Figure:
    """Ease-off as a topography over the normalised tooth (seed Figs. 2.8, 4.6).

    The surface is the gap [µm] between the real gear flank and the conjugate of the
    pinion along the gear normal, over face width (toe → heel) × profile (root → tip);
    masked nodes (no contact possible) are left out of the surface.

    Parameters
    ----------
    easeoff : xarray.Dataset
        ``/easeoff``: ``ease_off`` (u, v) [µm] with coordinates ``u``, ``v`` [1].

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If the dataset lacks ``ease_off``.
    """
    require(easeoff, ("ease_off", "u", "v"), "easeoff")
    u, v = easeoff["u"].values, easeoff["v"].values
    e = easeoff["ease_off"].values
    uu, vv = np.meshgrid(u, v, indexing="ij")
    fig = new_figure(6.6, 5.0)
    ax = fig.add_axes((0.0, 0.02, 0.8, 0.86), projection="3d")
    cax = fig.add_axes((0.84, 0.2, 0.025, 0.55))
    finite = np.isfinite(e)
    top = float(np.nanmax(e)) if finite.any() else 1.0
    norm = Normalize(vmin=min(0.0, float(np.nanmin(e))) if finite.any() else 0.0,
                     vmax=max(top, 1e-3))
    surf = ax.plot_surface(uu, vv, np.ma.masked_invalid(e), cmap=SEQUENTIAL, norm=norm,
                           rstride=1, cstride=1, linewidth=0.15, edgecolor="0.35",
                           antialiased=False)
    # the tooth's outline at zero ease-off, for the eye
    u0, u1, v0, v1 = u[0], u[-1], v[0], v[-1]
    ax.plot([u0, u1, u1, u0, u0], [v0, v0, v1, v1, v0], [0, 0, 0, 0, 0], color="0.3", lw=0.8)
    ax.set_xlabel(TOE_HEEL_LABEL, fontsize=8)
    ax.set_ylabel(PROFILE_LABEL, fontsize=8)
    ax.set_zlabel(axis_label(easeoff["ease_off"], "ease-off"), fontsize=8)
    ax.tick_params(labelsize=7)
    ax.view_init(elev=28, azim=-62)
    fig.colorbar(surf, cax=cax,
                 label=axis_label(easeoff["ease_off"], "ease-off along the gear normal"))
    masked = int((~finite).sum())
    note = f"; {masked} masked nodes left out ({masked_reasons(easeoff)})" if masked else ""
    title(fig, f"{case_text(easeoff)}\nease-off topography{note}")
    return fig


def easeoff_contour_figure(easeoff: xr.Dataset) -> Figure:
    """Ease-off on the gear's projection plane with iso-lines of the roll angle (seed Fig. 2.7).

    Parameters
    ----------
    easeoff : xarray.Dataset
        ``/easeoff``: ``ease_off`` [µm], ``roll_angle`` [rad], ``axial_position`` and
        ``radial_position`` [mm] over (u, v).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If the dataset lacks the variables.
    """
    require(easeoff, ("ease_off", "axial_position", "radial_position"), "easeoff")
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    e = easeoff["ease_off"].values
    aspect = float(np.clip(np.ptp(r) / max(np.ptp(z), 1e-9), 0.4, 2.5))
    fig, axes, (cax,) = panel_grid(1, 1, panel=(3.8, float(np.clip(3.8 * aspect, 2.5, 7.0))),
                                   colorbars=1, legend_rows=1, panel_title_lines=0)
    ax = axes[0, 0]
    handles = draw_projection_outline(ax, easeoff)
    top = max(float(np.nanmax(e)) if np.isfinite(e).any() else 0.0, 1e-3)
    cs = ax.contourf(z, r, np.ma.masked_invalid(e),
                     levels=MaxNLocator(14).tick_values(0.0, top), cmap=SEQUENTIAL,
                     extend="both")
    fig.colorbar(cs, cax=cax, label=axis_label(easeoff["ease_off"], "ease-off"))
    if "roll_angle" in easeoff and np.isfinite(easeoff["roll_angle"].values).sum() > 4:
        qd = np.degrees(easeoff["roll_angle"].values)
        ql = ax.contour(z, r, np.ma.masked_invalid(qd), levels=8, colors="w",
                        linewidths=0.6, linestyles="--")
        ax.clabel(ql, fmt="%.0f°", fontsize=6)
        handles.append(Line2D([], [], color="0.4", ls="--", lw=0.8,
                              label="roll angle Q [deg] (white, dashed)"))
    title(fig, f"{case_text(easeoff)}\nease-off on the projection plane")
    legend_below(fig, handles)
    return fig


def easeoff_map_figure(
    datasets: Mapping[str, xr.Dataset], var: str = "ease_off", *, diverging: bool = False,
) -> Figure:
    """A (u, v) variable of ``/easeoff`` on the normalised tooth, one panel per dataset.

    Parameters
    ----------
    datasets : mapping of str to xarray.Dataset
        Panel title → ``/easeoff`` (e.g. ``{"theoretical": ..., "deviated": ...}``); the
        panels share one colour scale.
    var : str
        The variable drawn (``ease_off`` [µm], ``ease_off_change`` [µm] …).
    diverging : bool
        Draw with the diverging map centred on zero (for signed quantities).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If a dataset lacks ``var``.
    """
    if not datasets:
        raise InputError("datasets: give at least one /easeoff dataset")
    for name, ds in datasets.items():
        require(ds, (var, "u", "v"), f"easeoff ({name})")
    allv = np.concatenate([ds[var].values.ravel() for ds in datasets.values()])
    if diverging:
        norm = symmetric_norm(allv)
        levels = np.linspace(norm.vmin, norm.vmax, 17)
        cmap = DIVERGING
    else:
        top = max(float(np.nanmax(allv)) if np.isfinite(allv).any() else 0.0, 1e-3)
        bottom = min(float(np.nanmin(allv)) if np.isfinite(allv).any() else 0.0, 0.0)
        norm, levels, cmap = Normalize(bottom, top), np.linspace(bottom, top, 15), SEQUENTIAL
    n = len(datasets)
    fig, grid, (cax,) = panel_grid(1, n, panel=(3.4, 2.6), colorbars=1, legend_rows=1)
    axes = grid[0]
    handles: list = []
    cs = None
    first = next(iter(datasets.values()))
    for ax, (name, ds) in zip(axes, datasets.items(), strict=True):
        handles += draw_tooth(ax, ds)
        cs = ax.contourf(ds["u"].values, ds["v"].values, np.ma.masked_invalid(ds[var].values.T),
                         levels=levels, cmap=cmap, norm=norm, extend="both")
        ax.set_title(name, fontsize=9)
    fig.colorbar(cs, cax=cax, label=axis_label(first[var], var.replace("_", "-")))
    what = first[var].attrs.get("long_name", var).split(":")[0].split("(")[0].strip()
    title(fig, f"{case_text(first)}\n{what}")
    legend_below(fig, handles)
    return fig


def _draw_segments(ax, ltca: xr.Dataset, values: np.ndarray, norm, cmap: str,
                   lw: float = 1.8) -> LineCollection:
    """Draw the segments' pieces in the colours ``cmap(norm(values))``; return the
    collection (the mappable of their colour bar).

    A colour map holds ``N`` (256) colours, so the pieces are grouped by the colour they
    get and each group is one NaN-separated path carrying the group's mean value (same
    colour-map entry): the same pixels as one path per piece, but a panel of several
    thousand pieces draws in a fraction of the time (matplotlib's cost is per path).
    Groups are drawn in ascending value, so the largest values stay on top, as before.
    """
    pieces, colours = segment_pieces(ltca, values)
    cm = colormaps[cmap] if isinstance(cmap, str) else cmap
    index = colour_index(colours, norm, cm)
    groups = np.unique(index)
    lines = np.concatenate([pieces, np.full((len(pieces), 1, 2), np.nan)], axis=1)
    lc = LineCollection([lines[index == k].reshape(-1, 2) for k in groups], cmap=cm,
                        norm=norm, linewidths=lw, capstyle="butt", zorder=2)
    lc.set_array(np.array([colours[index == k].mean() for k in groups]))
    ax.add_collection(lc, autolim=False)
    return lc


def colour_index(values: np.ndarray, norm, cmap) -> np.ndarray:
    """(N,) int: the entry of ``cmap``'s look-up table that ``cmap(norm(values))`` uses
    (values beyond the norm's range: the end entries, matplotlib's default under/over
    colours)."""
    scaled = np.ma.getdata(norm(np.asarray(values, float)))
    return np.clip(np.floor(scaled * cmap.N), 0, cmap.N - 1).astype(int)


def _draw_edges(ax, ltca: xr.Dataset, values: np.ndarray, norm, cmap: str):
    pts, colours = edge_points(ltca, values)
    if not len(pts):
        return None
    return ax.scatter(pts[:, 0], pts[:, 1], c=colours, cmap=cmap, norm=norm, s=7,
                      marker="s", linewidths=0, zorder=1.5)


def _edge_mask(ltca: xr.Dataset) -> np.ndarray:
    if "segment_kind" in ltca.coords or "segment_kind" in ltca:
        return np.asarray(ltca["segment_kind"].values) != "curve"
    return np.zeros(ltca.sizes["segment"], bool)


def _norms(panels, edges_apart: bool, diverging: bool):
    """The flank's (and the edge's) colour normalisation shared by all panels."""
    flank, edges = [], []
    for _, _, lt, v in panels:
        e = _edge_mask(lt)
        fv = np.where(e, np.nan, v) if edges_apart else v
        flank.append(np.where(fv != 0, fv, np.nan).ravel())
        if edges_apart:
            edges.append(np.where(e, v, np.nan).ravel())
    fv = np.concatenate(flank)
    if diverging:
        norm, cmap = symmetric_norm(fv), DIVERGING
    else:
        good = np.isfinite(fv)
        lo = float(np.nanmin(fv)) if good.any() else 0.0
        hi = float(np.nanmax(fv)) if good.any() else 1.0
        norm, cmap = Normalize(min(lo, 0.0), max(hi, lo + 1e-12)), SEQUENTIAL
    edge_norm = None
    if edges:
        ev = np.concatenate(edges)
        if np.isfinite(ev).any() and np.nanmax(ev) > 0:
            edge_norm = Normalize(0.0, float(np.nanmax(ev)))
    return norm, cmap, edge_norm


def _plain(x: float) -> str:
    """A peak as a reader writes it: no exponent (1792, 48.3, 0.0412)."""
    ax = abs(x)
    return f"{x:.0f}" if ax >= 100 else f"{x:.3g}" if ax >= 1e-3 else f"{x:.2e}"


def _peaks(lt: xr.Dataset, v: np.ndarray, edges_apart: bool, unit: str = "") -> str:
    """``flank peak 1792 MPa, edge peak 6298 MPa`` of a panel's values."""
    e = _edge_mask(lt)
    u = f" {unit}" if unit else ""
    fv = np.where(e, np.nan, v)
    text = f"flank peak {_plain(np.nanmax(np.abs(fv)))}{u}" if np.isfinite(fv).any() else ""
    ev = np.where(e, v, np.nan)
    if edges_apart and np.isfinite(ev).any() and np.nanmax(ev) > 0:
        text += f", edge peak {_plain(np.nanmax(ev))}{u}"
    return text


def _unit_of(label: str) -> str:
    """The unit in brackets at the end of an axis label (``"pressure [MPa]"`` → MPa)."""
    if label.endswith("]") and "[" in label:
        unit = label[label.rindex("[") + 1:-1]
        return "" if unit == "1" else unit
    return ""


def segment_panels_figure(
    panels: Sequence[tuple[str, xr.Dataset, xr.Dataset, np.ndarray]],
    *,
    label: str,
    diverging: bool = False,
    edges_apart: bool = False,
    what: str = "",
    columns: int | None = None,
) -> Figure:
    """Segment values on the normalised gear flank, one panel each, one colour scale.

    Parameters
    ----------
    panels : sequence of (title, easeoff, ltca, values)
        Each panel's title, ``/easeoff`` (outline, mask), ``/ltca`` (``segment_u``,
        ``segment_v`` [1], ``segment_kind``) and values (roll, pair, segment) in the
        units of ``label``; NaN or 0 is not drawn.
    label : str
        Colour-bar label, with units.
    diverging : bool
        Diverging colour map centred on zero (signed quantities).
    edges_apart : bool
        Draw the edge segments in their own colour scale (``Reds``) and colour bar;
        otherwise in the flank's scale. Either way just outside the flank edge.
    what : str
        What is drawn, for the title (the case is added).
    columns : int, optional
        Panels per row (default up to three).

    Returns
    -------
    matplotlib.figure.Figure
    """
    if not panels:
        raise InputError("panels: nothing to draw")
    for _, _, lt, _ in panels:
        require(lt, ("segment_u", "segment_v"), "ltca")
    norm, cmap, edge_norm = _norms(panels, edges_apart, diverging)
    n = len(panels)
    cols = columns or _grid(n)[1]
    rows = -(-n // cols)
    fig, grid, caxes = panel_grid(rows, cols, panel=(3.0, 2.3),
                                  colorbars=1 + (edge_norm is not None), legend_rows=1,
                                  panel_title_lines=2)
    axes = grid.ravel()
    handles: list = []
    lc = sc = None
    for k, ax in enumerate(axes[:n]):
        name, eo, lt, v = panels[k]
        v = np.asarray(v, float)
        edge = _edge_mask(lt)
        handles += draw_tooth(ax, eo)
        lc = _draw_segments(ax, lt, np.where(edge, 0.0, v) if edges_apart else v, norm, cmap)
        ev = np.where(edge, np.nan_to_num(v), 0.0)
        if edges_apart and edge_norm is not None:
            sc = _draw_edges(ax, lt, ev, edge_norm, EDGE) or sc
        elif not edges_apart:
            _draw_edges(ax, lt, ev, norm, cmap)
        peaks = _peaks(lt, v, edges_apart, _unit_of(label))
        ax.set_title(f"{name}{chr(10) if name and peaks else ''}{peaks}", fontsize=8)
        if k % cols:
            ax.set_ylabel("")
        if k < n - cols:
            ax.set_xlabel("")
    hide_unused(grid, n, TOE_HEEL_LABEL)
    fig.colorbar(lc, cax=caxes[0], label=label)
    if sc is not None:
        fig.colorbar(sc, cax=caxes[1], label=f"edge contact: {label}")
        handles.append(Line2D([], [], ls="", marker="s", ms=4, color="#cb181d",
                              label="edge contact (drawn just outside the flank edge)"))
    title(fig, f"{case_text(panels[0][2])}\n{what}")
    legend_below(fig, handles)
    return fig


def segment_map_figure(
    easeoff: xr.Dataset,
    ltca: xr.Dataset,
    values: xr.DataArray,
    *,
    label: str | None = None,
    diverging: bool = False,
    edges_apart: bool = False,
    what: str = "",
    torques: Sequence[int] | None = None,
) -> Figure:
    """A segment variable on the normalised gear flank, one panel per torque.

    Parameters
    ----------
    easeoff, ltca : xarray.Dataset
        ``/easeoff`` (outline, mask) and ``/ltca`` (``segment_u``, ``segment_v`` [1],
        ``segment_kind``).
    values : xarray.DataArray (torque, roll, pair, segment)
        The value of every segment (``pressure_max`` [MPa], ``/friction``'s quantities …);
        NaN or 0 is not drawn.
    label : str, optional
        Colour-bar label (default: long name and units of ``values``).
    diverging : bool
        Diverging colour map centred on zero (signed quantities).
    edges_apart : bool
        Edge segments in their own colour scale and colour bar.
    what : str
        What is drawn, for the title (the case is added).
    torques : sequence of int, optional
        Indices of the torques to draw (default all).

    Returns
    -------
    matplotlib.figure.Figure
        All panels share one colour scale (and one edge scale).
    """
    if "torque" not in values.dims:
        raise InputError(f"values: {values.name!r} has no torque dimension ({values.dims})")
    idx = list(range(values.sizes["torque"])) if torques is None else list(torques)
    tq = values["torque"].values
    panels = [(torque_text(tq[i]), easeoff, ltca, values.isel(torque=i).values) for i in idx]
    return segment_panels_figure(panels, label=label or axis_label(values),
                                 diverging=diverging, edges_apart=edges_apart, what=what)


def pressure_figure(easeoff: xr.Dataset, ltca: xr.Dataset,
                    torques: Sequence[int] | None = None) -> Figure:
    """Maximum contact pressure on the gear flank over the mesh cycles (seed Fig. 3.7).

    One panel per torque on one colour scale; every loaded segment of every roll
    position and pair is drawn as its piece of the contact line. The edge contact
    (several times the flank's pressure) is drawn just outside the flank edge in its own
    scale, so the flank's pattern stays readable.

    Parameters
    ----------
    easeoff, ltca : xarray.Dataset
        ``/easeoff`` and ``/ltca`` (``pressure_max`` [MPa] over torque, roll, pair,
        segment).
    torques : sequence of int, optional
        Indices of the torques drawn (default all).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If ``/ltca`` lacks the variables.
    """
    require(ltca, ("pressure_max", "segment_u", "segment_v"), "ltca")
    p = ltca["pressure_max"]
    return segment_map_figure(
        easeoff, ltca, p.where(p > 0), label="maximum Hertzian pressure [MPa]",
        edges_apart=True, what="maximum contact pressure over two mesh cycles [MPa]",
        torques=torques,
    )


def friction_flank_figure(
    easeoff: xr.Dataset,
    ltca: xr.Dataset,
    friction: xr.Dataset,
    names: Sequence[str] | None = None,
    torque_index: int = -1,
) -> Figure:
    """The efficiency quantities on the gear flank at one torque (seed Figs. 5.5–5.10), with
    the flash temperature and the specific film thickness of scuffing and micropitting.

    One panel per quantity, each with its own colour bar; signed quantities (the
    slide-to-roll ratio) diverge about zero, the others are sequential; the scale is the
    flank's, the edge segments are drawn just outside the flank edge in it (clipped).

    Parameters
    ----------
    easeoff, ltca, friction : xarray.Dataset
        ``/easeoff``, ``/ltca`` and ``/friction`` (quantities over torque, roll, pair,
        segment).
    names : sequence of str, optional
        The ``/friction`` variables drawn (default those of :data:`FRICTION_FLANK_PLOTS`
        the group has).
    torque_index : int
        Which torque (default the largest, the last).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        If ``/friction`` lacks a named variable or has none to draw.
    """
    names = [n for n in FRICTION_FLANK_PLOTS if n in friction] if names is None else list(names)
    require(friction, names, "friction")
    if not names:
        raise InputError("friction: none of the flank quantities to draw")
    rows, cols = _grid(len(names))
    fig, grid, _ = panel_grid(rows, cols, panel=(3.5, 2.3), legend_rows=1, wspace=0.55,
                              right=0.55)
    axes = grid.ravel()
    handles: list = []
    edge = _edge_mask(ltca)
    for k, ax in enumerate(axes[:len(names)]):
        da = friction[names[k]].isel(torque=torque_index)
        v = np.asarray(da.values, float)
        fv = np.where(edge, np.nan, v)  # the scale is the flank's; edges beyond it clip
        good = np.isfinite(fv).any()
        signed = bool(good and np.nanmin(fv) < 0 < np.nanmax(fv))
        if signed:
            norm, cmap = symmetric_norm(fv), DIVERGING
        else:
            hi = float(np.nanmax(fv)) if good else 1.0
            norm, cmap = Normalize(0.0, hi if hi > 0 else 1.0), SEQUENTIAL
        handles += draw_tooth(ax, easeoff)
        lc = _draw_segments(ax, ltca, np.where(edge, 0.0, v), norm, cmap, lw=1.5)
        _draw_edges(ax, ltca, np.where(edge, np.nan_to_num(v), 0.0), norm, cmap)
        fig.colorbar(lc, ax=ax, fraction=0.06, pad=0.02, extend="both")
        ax.set_title(axis_label(da, FRICTION_FLANK_PLOTS.get(names[k], None)), fontsize=8)
        if k % cols:
            ax.set_ylabel("")
        if k < len(names) - cols:
            ax.set_xlabel("")
    a = friction.attrs
    op = (f"{torque_text(friction['torque'].values[torque_index])}, "
          f"{a.get('pinion_speed_rpm', float('nan')):g} rpm, {a.get('lubricant', '')} at "
          f"{a.get('inlet_temperature_degC', float('nan')):g} °C, "
          f"Rq {a.get('roughness_rq_um', float('nan')):g} µm, {a.get('friction_model', '')}")
    hide_unused(grid, len(names), TOE_HEEL_LABEL)
    title(fig, f"{case_text(ltca)}\nsurface velocities, film, friction and flash temperature "
          f"on the gear flank: {op}")
    legend_below(fig, handles)
    if "friction_model_extrapolated" in friction:
        # the segments where the friction model left its fitted range: crossed, and said
        flag = np.asarray(friction["friction_model_extrapolated"].isel(
            torque=torque_index).values) == 1
        if flag.any():
            for ax in axes[:len(names)]:
                _draw_segments(ax, ltca, np.where(flag & ~edge, 1.0, np.nan),
                               Normalize(0.0, 1.0), ListedColormap([EXTRAPOLATED]), lw=0.6)
            fig.text(0.01, 0.005, f"magenta: friction model extrapolated ({int(flag.sum())} "
                     "segments outside its fitted range)", fontsize=7, color=EXTRAPOLATED)
    return fig


def _pattern_lines(utca: xr.Dataset) -> np.ndarray:
    """(N, 2) polylines (NaN-separated) of the unloaded pattern in (u, v)."""
    pat = utca["contact_pattern"].values.astype(bool)
    cu = np.where(pat, utca["curve_u"].values, np.nan)
    cv = np.where(pat, utca["curve_v"].values, np.nan)
    rows = np.concatenate([np.stack([cu, cv], -1),
                           np.full((*cu.shape[:2], 1, 2), np.nan)], axis=2)
    return rows.reshape(-1, 2)


def _tooth_phase(roll: np.ndarray, pairs: np.ndarray, period: float) -> np.ndarray:
    """(roll, pair) the place of each pair's contact on the reference tooth, as a roll."""
    return roll[:, None] - pairs[None, :] * period


def _unloaded_path(utca: xr.Dataset) -> np.ndarray:
    """(N, 2) the unloaded path of contact (CPP, active rolls) on the reference tooth."""
    if "path_u" not in utca:
        return np.empty((0, 2))
    act = utca["active"].values.astype(bool)
    cpp = list(utca["path"].values).index("CPP") if "path" in utca.coords else 1
    pu = utca["path_u"].values[..., cpp]
    pv = utca["path_v"].values[..., cpp]
    period = float(utca.attrs.get("mesh_period", 1.0))
    ph = _tooth_phase(utca["roll"].values, utca["pair"].values, period)
    m = act & np.isfinite(pu) & np.isfinite(pv)
    order = np.argsort(ph[m])
    return np.c_[pu[m][order], pv[m][order]]


def _loaded_path(ltca: xr.Dataset, it: int) -> np.ndarray:
    """(N, 2) the loaded path of contact: force-weighted centre of each pair's flank
    segments at each roll, ordered along the reference tooth."""
    curve = ~_edge_mask(ltca)
    f = np.nan_to_num(ltca["force"].isel(torque=it).values[..., curve])
    u = np.nan_to_num(ltca["segment_u"].values[..., curve])
    v = np.nan_to_num(ltca["segment_v"].values[..., curve])
    w = f.sum(-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        cu, cv = (f * u).sum(-1) / w, (f * v).sum(-1) / w
    period = float(ltca.attrs.get("mesh_period_rad", np.nan))
    roll = ltca["roll"].values
    if not np.isfinite(period):
        mc = ltca["mesh_cycle"].values
        period = float((roll[-1] - roll[0]) / max(mc[-1] - mc[0], 1e-12))
    ph = _tooth_phase(roll, ltca["pair"].values, period)
    m = w > 0
    order = np.argsort(ph[m])
    return np.c_[cu[m][order], cv[m][order]]


def contact_pattern_figure(easeoff: xr.Dataset, utca: xr.Dataset,
                           ltca: xr.Dataset | None = None) -> Figure:
    """Unloaded and loaded contact patterns on one normalised outline (seed Figs. 2.10, 3.7).

    The first panel is the unloaded pattern (the contact lines within the separation
    threshold) with its path of contact (CPP) and bounds; each further panel one
    torque's loaded pattern (the flank segments in contact over the mesh cycles), the
    unloaded pattern behind it in grey, its loaded path of contact (force-weighted centre
    of each contact line) and the loaded edge contact.

    Parameters
    ----------
    easeoff, utca : xarray.Dataset
        ``/easeoff`` and ``/utca``.
    ltca : xarray.Dataset, optional
        ``/ltca``; without it only the unloaded panel.

    Returns
    -------
    matplotlib.figure.Figure
        The unloaded pattern, then one panel per torque of ``ltca``, on the normalised gear
        flank (face width toe → heel × profile root → tip [1]).

    Raises
    ------
    InputError
        If ``/utca`` lacks the pattern variables.
    """
    require(utca, ("contact_pattern", "curve_u", "curve_v", "active"), "utca")
    nt = 0 if ltca is None else ltca.sizes["torque"]
    rows, cols = _grid(1 + nt)
    fig, grid, _ = panel_grid(rows, cols, panel=(3.0, 2.3), legend_rows=3)
    axes = grid.ravel()
    lines = _pattern_lines(utca)
    upath = _unloaded_path(utca)
    sep = float(utca["separation_threshold"]) if "separation_threshold" in utca else np.nan
    handles: list = []
    for n, ax in enumerate(axes[:nt + 1]):
        handles += draw_tooth(ax, easeoff)
        if n == 0:
            ax.plot(lines[:, 0], lines[:, 1], color="tab:orange", lw=0.9, alpha=0.8,
                    label=f"unloaded pattern (gap ≤ {sep:g} µm)")
            ax.plot(upath[:, 0], upath[:, 1], color="k", lw=1.3,
                    label="unloaded path of contact (CPP)")
            ax.set_title("unloaded", fontsize=8)
        else:
            it = n - 1
            ax.plot(lines[:, 0], lines[:, 1], color="0.72", lw=0.8, zorder=1,
                    label="unloaded pattern, behind (grey)")
            contact = ltca["contact"].isel(torque=it).values if "contact" in ltca else (
                np.nan_to_num(ltca["force"].isel(torque=it).values) > 0)
            pieces, _ = segment_pieces(ltca, np.where(contact > 0, 1.0, np.nan))
            # one colour: one NaN-separated path draws the same pixels as a path per piece
            gap = np.full((len(pieces), 1, 2), np.nan)
            ax.plot(*np.concatenate([pieces, gap], axis=1).reshape(-1, 2).T,
                    color="tab:blue", lw=1.6, solid_capstyle="butt", zorder=2,
                    label="loaded pattern")
            edge_load = np.nan_to_num(ltca["force"].isel(torque=it).values)
            edge_load = np.where(_edge_mask(ltca)[None, None, :], edge_load, 0.0)
            pts, _ = edge_points(ltca, edge_load)
            if len(pts):
                ax.plot(pts[:, 0], pts[:, 1], ls="", marker="s", ms=2.2, color="#cb181d",
                        zorder=1.5, label="loaded edge contact (outside the edge)")
            lp = _loaded_path(ltca, it)
            ax.plot(lp[:, 0], lp[:, 1], ls="", marker="o", ms=1.8, color="k", zorder=4,
                    label="loaded path (load centre of each line)")
            ax.set_title(torque_text(ltca["torque"].values[it]), fontsize=8)
        if n % cols:
            ax.set_ylabel("")
        if n < nt + 1 - cols:
            ax.set_xlabel("")
    hide_unused(grid, nt + 1, TOE_HEEL_LABEL)
    for ax in axes[:nt + 1]:
        handles += [*ax.get_lines(), *ax.collections]
    title(fig, f"{case_text(ltca if ltca is not None else utca)}\n"
          "unloaded and loaded contact patterns on the gear flank")
    legend_below(fig, handles, ncols=2)
    return fig
