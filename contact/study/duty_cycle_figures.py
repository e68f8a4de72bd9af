"""Figures of a duty cycle: flank damage maps and bar charts per bin.

Public functions
----------------
damage_map_figure       cumulative flank damage of both members on the gear's contact grid
root_damage_figure      cumulative root (bending) damage along the fillet of both members
bins_figure             per bin: hours, share of the damage, energy lost, efficiency
save_duty_cycle_figures both as PNGs
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import xarray as xr

from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.text import plain_number
from geometry.plot import new_figure

__all__ = ["bins_figure", "damage_map_figure", "root_damage_figure",
           "save_duty_cycle_figures"]


def _check(ds: xr.Dataset) -> None:
    for name in ("flank_damage", "torque", "energy_lost"):
        if name not in ds:
            raise InputError(f"duty cycle: the dataset has no {name!r} (not a "
                             "run_duty_cycle result)")


def damage_map_figure(ds: xr.Dataset):
    """Cumulative flank (pitting) damage [1] over the cycle on the gear's contact grid.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`contact.study.duty_cycle.run_duty_cycle` result.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per member, log₁₀ of the damage (points without damage blank), the first
        point to reach damage 1 marked.

    Raises
    ------
    InputError
        Not a duty-cycle result.
    """
    _check(ds)
    fig = new_figure(figsize=(10, 4), layout="constrained")
    axes = fig.subplots(1, 2)
    u, v = ds["u"].values, ds["v"].values
    for k, ax in enumerate(axes):
        member = str(ds["member"].values[k])
        d = ds["flank_damage_total"].values[k]
        with np.errstate(divide="ignore"):
            logd = np.where(d > 0, np.log10(np.where(d > 0, d, 1.0)), np.nan)
        top = float(np.nanmax(logd)) if np.any(np.isfinite(logd)) else 0.0
        # six decades below the largest: smaller damage does not matter to the life
        im = ax.pcolormesh(u, v, logd.T, shading="nearest", cmap="viridis", vmin=top - 6,
                           vmax=top)
        ax.plot(float(ds["life_u"][k]), float(ds["life_v"][k]), "rx", ms=10,
                label=f"first to fail: life {plain_number(ds['life'][k], 3)} h")
        ax.set_xlabel("gear lengthwise fraction u [1] (toe 0, heel 1)")
        ax.set_ylabel("gear profile fraction v [1]")
        ax.set_title(f"{member} flank damage (Miner {ds.attrs.get('miner_rule', '')})")
        ax.legend(loc="upper left", fontsize=8)
        fig.colorbar(im, ax=ax, label="log10 cumulative damage [1]", extend="min")
    note = " (ILLUSTRATIVE)" if ds.attrs.get("illustrative") else ""
    fig.suptitle(f"{ds.attrs.get('case', '')}: {ds.attrs.get('duty_cycle', '')}{note}",
                 fontsize=9)
    return fig


def root_damage_figure(ds: xr.Dataset):
    """Cumulative root (bending) damage [1] along the fillet over the cycle, and the peak
    tensile fillet stress [MPa] of each bin, for both members.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`contact.study.duty_cycle.run_duty_cycle` result with the bending side
        (``root_damage``, ``root_stress_peak``, coordinate ``fillet_u``).

    Returns
    -------
    matplotlib.figure.Figure
        Top row: log₁₀ of the cumulative damage against the lengthwise fraction of the
        fillet station, the first station to reach damage 1 marked; bottom row: the bins'
        peak fillet stress along the face width with the S–N curve's allowable.

    Raises
    ------
    InputError
        Not a duty-cycle result, or one without the bending side.
    """
    _check(ds)
    if "root_damage" not in ds:
        raise InputError("duty cycle: the dataset has no 'root_damage' (run with "
                         "root_stress, `ltca duty-cycle --root-stress`)")
    fig = new_figure(figsize=(10, 6), layout="constrained")
    axes = fig.subplots(2, 2, sharex=True)
    for k in range(ds.sizes["member"]):
        member = str(ds["member"].values[k])
        x = (ds["fillet_u"].values[k] if "fillet_u" in ds.coords
             else np.linspace(0.0, 1.0, ds.sizes["fillet_point"]))
        total = ds["root_damage"].values[:, k, :].sum(0)
        ax = axes[0, k]
        ax.semilogy(x, np.where(total > 0, total, np.nan), "o-", ms=3)
        ax.axhline(1.0, color="0.5", lw=0.8, ls="--")
        i = int(ds["root_life_point"].values[k])
        ax.semilogy([x[i]], [max(total[i], 1e-300)], "rx", ms=10,
                    label=f"first to fail: life {plain_number(ds['root_life'][k], 3)} h")
        ax.set_ylabel("cumulative root damage [1]")
        ax.set_title(f"{member} root (bending) damage (Miner {ds.attrs.get('miner_rule', '')})")
        ax.legend(loc="best", fontsize=8)
        ax = axes[1, k]
        stress = ds["root_stress_peak"].values[:, k, :]
        for b in range(stress.shape[0]):
            ax.plot(x, stress[b], lw=1, label=f"{plain_number(ds['torque'].values[b])} N m")
        ax.set_xlabel("lengthwise fraction of the fillet station [1] (toe 0, heel 1)")
        ax.set_ylabel("peak tensile fillet stress [MPa]")
        ax.legend(fontsize=7, ncol=2, title="bin torque", title_fontsize=7)
    note = " (ILLUSTRATIVE)" if ds.attrs.get("illustrative") else ""
    fig.suptitle(f"{ds.attrs.get('case', '')}: {ds.attrs.get('duty_cycle', '')}{note}",
                 fontsize=9)
    return fig


def bins_figure(ds: xr.Dataset):
    """Bar charts per bin: duration [h], share of the damage at the flank point that fails
    first [%], energy lost [kW h],
    efficiency [%].

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`contact.study.duty_cycle.run_duty_cycle` result.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        Not a duty-cycle result.
    """
    _check(ds)
    fig = new_figure(figsize=(10, 6), layout="constrained")
    axes = fig.subplots(2, 2)
    labels = [plain_number(t) for t in ds["torque"].values]
    x = np.arange(len(labels))
    # each bin's share of the damage at the point that fails first (per member)
    at = np.stack([ds["flank_damage"].sel(member=m, u=float(ds["life_u"][k]),
                                          v=float(ds["life_v"][k])).values
                   for k, m in enumerate(ds["member"].values)], -1)  # (bin, member)
    share = 100 * at / np.where(at.sum(0) > 0, at.sum(0), 1.0)
    panels = (
        (axes[0, 0], [ds["hours"].values], ["duration"], "duration [h]"),
        (axes[0, 1], [share[:, 0], share[:, 1]], ["pinion", "gear"],
         "share of the damage at the first point to fail [%]"),
        (axes[1, 0], [ds["energy_lost"].values], ["energy lost"], "energy lost [kW h]"),
        (axes[1, 1], [100 * ds["efficiency"].values], ["efficiency"], "mesh efficiency [%]"),
    )
    for ax, series, names, ylabel in panels:
        w = 0.8 / len(series)
        for j, (y, name) in enumerate(zip(series, names, strict=True)):
            ax.bar(x + (j - (len(series) - 1) / 2) * w, y, w, label=name)
        ax.set_xticks(x, labels)
        ax.set_xlabel("pinion torque of the bin [N m]")
        ax.set_ylabel(ylabel)
        if len(series) > 1:
            ax.legend(fontsize=8)
    eff = axes[1, 1]
    lo = float(np.nanmin(100 * ds["efficiency"].values))
    eff.set_ylim(max(0.0, lo - 0.5), 100.0)
    fig.suptitle(f"{ds.attrs.get('case', '')}: cycle efficiency "
                 f"{100 * float(ds['cycle_efficiency']):.3f} %", fontsize=9)
    return fig


def save_duty_cycle_figures(ds: xr.Dataset, directory: str | os.PathLike[str]) -> list[Path]:
    """Write the damage map and the bar charts as PNGs.

    Parameters
    ----------
    ds : xarray.Dataset
        A duty-cycle result.
    directory : path-like
        Existing directory.

    Returns
    -------
    list of pathlib.Path
        ``<case>_duty_damage.png``, ``<case>_duty_bins.png`` and, with the bending side,
        ``<case>_duty_root_damage.png``.

    Raises
    ------
    InputError
        A missing directory or not a duty-cycle result.
    """
    out = Path(directory)
    if not out.is_dir():
        raise InputError(f"plots: directory {str(out)!r} does not exist")
    case = ds.attrs.get("case", "duty_cycle")
    paths = []
    figures = [(damage_map_figure, f"{case}_duty_damage.png"),
               (bins_figure, f"{case}_duty_bins.png")]
    if "root_damage" in ds:
        figures.append((root_damage_figure, f"{case}_duty_root_damage.png"))
    for draw, name in figures:
        fig = draw(ds)
        path = out / name
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=110, format="png")
        paths.append(path)
    return paths
