"""Figures over the mesh cycles: transmission error, load sharing, instantaneous efficiency.

Public functions
----------------
pair_ute_curves            each tooth pair's UTE over the mesh cycles (from /utca)
transmission_error_figure  UTE of the pairs and its lower envelope, then the LTE of each
                           torque, over two mesh cycles (seed Figs. 2.9, 3.6)
load_share_figure          share of the torque each pair carries, one panel per torque
efficiency_curve_figure    instantaneous mechanical efficiency per torque (seed Fig. 5.4)
te_comparison_figure       UTE and LTE of theoretical and deviated surfaces (Figs. 4.8, 4.13)
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contact.plots.style import (
    EXTRAPOLATED,
    case_text,
    legend_below,
    panel_grid,
    title,
    torque_text,
)
from contact.plots.tooth import require

__all__ = [
    "efficiency_curve_figure",
    "load_share_figure",
    "pair_ute_curves",
    "te_comparison_figure",
    "transmission_error_figure",
]

MESH_CYCLES_LABEL = "mesh cycles from M1 [1]"


def pair_ute_curves(utca: xr.Dataset, start: float | None = None,
                    cycles: float = 2.0) -> dict[int, tuple[np.ndarray, np.ndarray]]:
    """Each tooth pair's unloaded transmission error over ``cycles`` mesh cycles.

    Pair k's curve is the reference pair's shifted by k mesh cycles, UTE_k(r) =
    UTE_0(r − k·p) (seed §2.3.2.2); ``/utca`` holds it over about one cycle for pairs
    −1, 0, +1, from which every pair that meshes within the window is drawn.

    Parameters
    ----------
    utca : xarray.Dataset
        ``/utca`` (``pair_transmission_error`` (roll, pair) [µrad], ``mesh_period`` [rad]).
    start : float, optional
        First roll of the window [rad] (default the first roll of ``/utca``).
    cycles : float
        Length of the window [mesh cycles].

    Returns
    -------
    dict of int to (x, te)
        Pair offset → (mesh cycles from ``start`` [1], UTE [µrad]) where it meshes.
    """
    require(utca, ("pair_transmission_error",), "utca")
    roll = utca["roll"].values
    te = utca["pair_transmission_error"].values
    pairs = utca["pair"].values
    period = float(utca.attrs.get("mesh_period", roll[-1] - roll[0]))
    start = float(roll[0] if start is None else start)
    arg = (roll[:, None] - pairs[None, :] * period).ravel()  # arguments of UTE_0
    val = te.ravel()
    ok = np.isfinite(val)
    order = np.argsort(arg[ok])
    arg, val = arg[ok][order], val[ok][order]
    out = {}
    kmin = int(np.floor((start - arg[-1]) / period)) if arg.size else 0
    kmax = int(np.ceil((start + cycles * period - arg[0]) / period)) if arg.size else -1
    for k in range(kmin, kmax + 1):
        x = (arg + k * period - start) / period
        m = (x >= -1e-9) & (x <= cycles + 1e-9)
        if m.sum() > 1:
            out[k] = (x[m], val[m])
    return out


def transmission_error_figure(utca: xr.Dataset | None, ltca: xr.Dataset | None) -> Figure:
    """Unloaded and loaded transmission error over two mesh cycles (seed Figs. 2.9, 3.6).

    The top panel holds the UTE of every tooth pair (thin) and their lower envelope,
    the UTE (thick); below it, one panel per torque holds the LTE with its mean and
    peak-to-peak. The x axis is shared: mesh cycles from the transition M1.

    Parameters
    ----------
    utca : xarray.Dataset or None
        ``/utca``; None leaves the UTE panel out.
    ltca : xarray.Dataset or None
        ``/ltca`` (``transmission_error`` (torque, roll) [µrad], ``mesh_cycle``); None
        leaves the LTE panels out.

    Returns
    -------
    matplotlib.figure.Figure
        The transmission error [µrad] over the mesh cycles: unloaded per pair (UTE),
        loaded per torque (LTE).

    Raises
    ------
    InputError
        If both are None or a dataset lacks the variables drawn.
    """
    from geometry.core.errors import InputError

    if utca is None and ltca is None:
        raise InputError("utca, ltca: give at least one of /utca and /ltca")
    nt = 0 if ltca is None else ltca.sizes["torque"]
    n = nt + (utca is not None)
    fig, grid, _ = panel_grid(n, 1, panel=(6.2, 1.55), sharey=False, left=0.8)
    axes = grid[:, 0]
    cycles = 2.0
    start = None
    if ltca is not None:
        require(ltca, ("transmission_error", "mesh_cycle"), "ltca")
        start = float(ltca["roll"].values[0])
        mc = ltca["mesh_cycle"].values
        cycles = float(max(mc[-1] + (mc[1] - mc[0] if mc.size > 1 else 0), 1.0))
    k = 0
    if utca is not None:
        ax = axes[0]
        for pair, (x, te) in sorted(pair_ute_curves(utca, start, cycles).items()):
            ax.plot(x, te, lw=0.9, label=f"pair {pair:+d}")
        if ltca is not None and "unloaded_transmission_error" in ltca:
            env_x, env = ltca["mesh_cycle"].values, ltca["unloaded_transmission_error"].values
        else:
            period = float(utca.attrs.get("mesh_period", 1.0))
            env_x = (utca["roll"].values - (start or utca["roll"].values[0])) / period
            env = utca["unloaded_transmission_error"].values
        ax.plot(env_x, env, color="k", lw=2.0, alpha=0.6, label="UTE (lower envelope)")
        p2p = (float(utca["peak_to_peak_transmission_error"])
               if "peak_to_peak_transmission_error" in utca else np.nan)
        lo = float(np.nanmin(env)) if np.isfinite(env).any() else 0.0
        span = max(p2p if np.isfinite(p2p) else 1.0, 1.0)
        ax.set_ylim(lo - 0.3 * span, lo + 2.5 * span)
        ax.set_ylabel("UTE [µrad]")
        ax.set_title(f"unloaded: peak-to-peak {p2p:.1f} µrad", fontsize=8)
        ax.legend(fontsize=7, ncols=3, loc="upper center")
        k = 1
    for i in range(nt):
        ax = axes[k + i]
        te = ltca["transmission_error"].isel(torque=i).values
        x = ltca["mesh_cycle"].values
        ax.plot(x, te, "o-", ms=2.5, lw=1.2, color="C0", label="LTE")
        mean = float(ltca["lte_mean"].values[i]) if "lte_mean" in ltca else np.nanmean(te)
        pp = (float(ltca["lte_peak_to_peak"].values[i]) if "lte_peak_to_peak" in ltca
              else float(np.nanmax(te) - np.nanmin(te)))
        ax.axhline(mean, color="0.5", lw=0.8, ls=":")
        ax.set_ylabel("LTE [µrad]")
        ax.set_title(f"{torque_text(ltca['torque'].values[i])}: mean {mean:.1f} µrad, "
                     f"peak-to-peak {pp:.1f} µrad", fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(MESH_CYCLES_LABEL)
    axes[-1].set_xlim(0, cycles)
    src = ltca if ltca is not None else utca
    title(fig, f"{case_text(src)}\ntransmission error over two mesh cycles")
    return fig


def load_share_figure(ltca: xr.Dataset) -> Figure:
    """Share of the gear torque each tooth pair carries, one panel per torque.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` (``load_share`` (torque, roll, pair) [1], ``mesh_cycle``).

    Returns
    -------
    matplotlib.figure.Figure
        The share of the torque [1] each tooth pair carries over the mesh cycles,
        one panel per torque.

    Raises
    ------
    InputError
        If ``/ltca`` lacks ``load_share``.
    """
    require(ltca, ("load_share", "mesh_cycle"), "ltca")
    nt = ltca.sizes["torque"]
    fig, grid, _ = panel_grid(nt, 1, panel=(6.2, 1.35), legend_rows=1, left=0.8)
    axes = grid[:, 0]
    x = ltca["mesh_cycle"].values
    for i, ax in enumerate(axes):
        share = ltca["load_share"].isel(torque=i)
        for j, pair in enumerate(ltca["pair"].values):
            y = share.isel(pair=j).values
            if np.nanmax(np.nan_to_num(y)) > 0:
                ax.plot(x, y, "o-", ms=2.2, lw=1, color=f"C{j}",
                        label=f"pair {int(pair):+d}" if i == 0 else None)
        ax.set_ylim(-0.03, 1.03)
        ax.set_ylabel("load share [1]")
        ax.set_title(torque_text(ltca["torque"].values[i]), fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(MESH_CYCLES_LABEL)
    legend_below(fig, axes[0].get_lines(), ncols=6)
    title(fig, f"{case_text(ltca)}\nload sharing of the tooth pairs")
    return fig


#: markers of the torques' lines, in order (with their colours C0, C1 …, so that the
#: torques stay apart in grey print too)
TORQUE_MARKERS = ("o", "s", "^", "D", "v", "P", "X")


#: [1] the share of a roll's sliding loss from segments outside the friction model's
#: fitted range at which the efficiency figure marks the roll: the extrapolation was
#: checked against the solver to ≤ 20 % of the sliding loss on a flank's contacts and
#: 7.8 % on edges (docs/friction.md), so below 5 % it moves that roll's loss by ≤ 1 %
EXTRAPOLATED_LOSS_SHARE = 0.05


def _extrapolated_rolls(friction: xr.Dataset, torque_index: int) -> np.ndarray:
    """(roll,) bool: the rolls of one torque where segments flagged
    ``friction_model_extrapolated`` make ≥ :data:`EXTRAPOLATED_LOSS_SHARE` of the sliding
    loss (any flagged segment where the dataset has no ``sliding_loss``)."""
    flag = friction["friction_model_extrapolated"].isel(torque=torque_index) == 1
    if "sliding_loss" not in friction:
        return flag.any(("pair", "segment")).values
    loss = friction["sliding_loss"].isel(torque=torque_index).fillna(0.0)
    total = loss.sum(("pair", "segment")).values
    out = loss.where(flag, 0.0).sum(("pair", "segment")).values
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(total > 0, out / np.where(total > 0, total, 1.0), 0.0) \
            >= EXTRAPOLATED_LOSS_SHARE


def efficiency_curve_figure(friction: xr.Dataset,
                            ltca: xr.Dataset | None = None) -> Figure:
    """Instantaneous mechanical efficiency over the mesh cycles, one line per torque.

    Parameters
    ----------
    friction : xarray.Dataset
        ``/friction`` (``efficiency`` (torque, roll) [1], ``mesh_cycle``): one line per
        torque, each with its colour and marker (:data:`TORQUE_MARKERS`); roll positions
        where segments flagged ``friction_model_extrapolated`` make at least
        :data:`EXTRAPOLATED_LOSS_SHARE` of the roll's sliding loss show the torque's marker
        open with a magenta dot (:data:`contact.plots.style.EXTRAPOLATED`) inside.
    ltca : xarray.Dataset, optional
        ``/ltca``, for the case name and misalignment in the title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    require(friction, ("efficiency",), "friction")
    # the legend under the panel, where it covers no curve (one row per two entries)
    n_entries = friction.sizes["torque"] + ("friction_model_extrapolated" in friction)
    fig, grid, _ = panel_grid(1, 1, panel=(6.2, 2.4), panel_title_lines=0, left=0.8,
                              legend_rows=-(-n_entries // 2))
    ax = grid[0, 0]
    x = friction["mesh_cycle"].values
    marked = False
    for i, tq in enumerate(friction["torque"].values):
        eff = 100 * friction["efficiency"].isel(torque=i).values
        mean = (100 * float(friction["efficiency_mean"].values[i])
                if "efficiency_mean" in friction else float(np.nanmean(eff)))
        # each torque its own colour and marker (issue 56: one colour hid the torques)
        colour, marker = f"C{i % 10}", TORQUE_MARKERS[i % len(TORQUE_MARKERS)]
        ax.plot(x, eff, "-", color=colour, marker=marker, ms=3.5, lw=1.2,
                label=f"{torque_text(tq)} (mean {mean:.2f} %)")
        if "friction_model_extrapolated" in friction:
            # roll positions where the friction model left its fitted range: the torque's
            # marker drawn open in its colour with a magenta dot inside, so the torques
            # keep their colours and the extrapolation its mark
            out = _extrapolated_rolls(friction, i)
            if out.any():
                ax.plot(x[out], eff[out], ls="none", marker=marker, ms=5.5, mfc="white",
                        mec=colour, mew=1.1, zorder=3)
                ax.plot(x[out], eff[out], ls="none", marker="o", ms=1.8, color=EXTRAPOLATED,
                        zorder=4)
                marked = True
    handles = list(ax.get_lines())
    if marked:
        from matplotlib.lines import Line2D

        handles.append(Line2D([], [], ls="none", marker="o", ms=5.5, mfc=EXTRAPOLATED,
                              mec="0.3", mew=1.1,
                              label="open marker, magenta dot: ≥ "
                                    f"{EXTRAPOLATED_LOSS_SHARE:.0%} of that roll's sliding "
                                    "loss from segments outside the friction model's range"))
    ax.set_xlabel(MESH_CYCLES_LABEL)
    ax.set_ylabel("mechanical efficiency [%]")
    ax.grid(alpha=0.3)
    legend_below(fig, handles, ncols=2)
    a = friction.attrs
    op = (f"{a.get('pinion_speed_rpm', float('nan')):g} rpm, {a.get('lubricant', '')} at "
          f"{a.get('inlet_temperature_degC', float('nan')):g} °C, Rq "
          f"{a.get('roughness_rq_um', float('nan')):g} µm, {a.get('friction_model', '')}")
    title(fig, f"{case_text(ltca if ltca is not None else friction)}\n"
          f"instantaneous efficiency, {op}")
    return fig


def te_comparison_figure(groups: Mapping[str, tuple[xr.Dataset, xr.Dataset]]) -> Figure:
    """UTE and LTE of several analyses of one pair (theoretical and deviated surfaces)
    over the mesh cycles: the top panel the UTE envelopes, one panel per torque below
    (seed Figs. 4.8, 4.13).

    Parameters
    ----------
    groups : mapping of str to (utca, ltca)
        Label → (``/utca``, ``/ltca``), e.g. ``{"theoretical": ..., "deviated": ...}``;
        the ``/ltca`` datasets share their torques.

    Returns
    -------
    matplotlib.figure.Figure
    """
    _first_ut, first_lt = next(iter(groups.values()))
    nt = first_lt.sizes["torque"]
    fig, grid, _ = panel_grid(nt + 1, 1, panel=(6.2, 1.55), sharey=False, left=0.8)
    axes = grid[:, 0]
    styles = ("o-", "s-", "^-", "v-")
    for (name, (ut, lt)), st in zip(groups.items(), styles, strict=False):
        x = lt["mesh_cycle"].values
        p2p = float(ut["peak_to_peak_transmission_error"])
        axes[0].plot(x, lt["unloaded_transmission_error"].values, st, ms=2.5, lw=1,
                     label=f"{name}: p-p {p2p:.1f} µrad")
        for i in range(nt):
            pp = float(lt["lte_peak_to_peak"].values[i])
            axes[i + 1].plot(x, lt["transmission_error"].isel(torque=i).values, st, ms=2.5,
                             lw=1, label=f"{name}: p-p {pp:.1f} µrad")
    axes[0].set_ylabel("UTE [µrad]")
    axes[0].set_title("unloaded (lower envelope)", fontsize=8)
    for i in range(nt):
        axes[i + 1].set_ylabel("LTE [µrad]")
        axes[i + 1].set_title(torque_text(first_lt["torque"].values[i]), fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    axes[-1].set_xlabel(MESH_CYCLES_LABEL)
    title(fig, f"{case_text(first_lt)}\ntransmission error: " + " and ".join(groups))
    return fig

