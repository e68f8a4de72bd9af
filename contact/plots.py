"""Plots of the unloaded TCA: ease-off topography, contact pattern, transmission error.

matplotlib with the Agg backend (no display needed); every function takes the ``/easeoff``
and ``/utca`` Datasets of :func:`contact.utca.unloaded_tca` (or read back from netCDF),
writes one PNG and returns its path. The gear flank is drawn in its projection plane:
axial position (toe → heel) horizontally, radius (root → tip) vertically, in mm.

Public functions
----------------
plot_easeoff             ease-off topography with iso-lines of the roll angle (seed Fig. 2.7)
plot_contact_pattern     contact lines, pattern, LPP/CPP/RPP and the M1, M2 bounds (Fig. 2.10)
plot_transmission_error  UTE of adjacent pairs, lower envelope, M1, M2, peak-to-peak (Fig. 2.9)
plot_utca                all three into a directory
plot_loaded_transmission_error  LTE over the mesh cycles for each torque (seed Fig. 3.6)
plot_pressure            maximum pressure of every segment over the mesh cycles on the gear
                         flank, and the loaded contact pattern (seed Fig. 3.7)
plot_load_share          load share of each tooth pair over the mesh cycles
plot_ltca                the LTCA plots into a directory
plot_analysis            every plot of a whole analysis (DataTree), e.g. read back from netCDF
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import xarray as xr

from geometry.errors import InputError
from geometry.plot import png_target as _target
from geometry.plot import pyplot as _pyplot

__all__ = [
    "plot_analysis",
    "plot_contact_pattern",
    "plot_deviations",
    "plot_easeoff",
    "plot_efficiency_map",
    "plot_friction",
    "plot_load_share",
    "plot_loaded_transmission_error",
    "plot_ltca",
    "plot_pressure",
    "plot_transmission_error",
    "plot_utca",
]


def _require(ds: xr.Dataset, names, what: str) -> None:
    missing = [n for n in names if n not in ds.variables]
    if missing:
        raise InputError(
            f"{what}: dataset lacks {missing} (expected the output of contact.utca.unloaded_tca)"
        )


def _outline(ax, easeoff: xr.Dataset) -> None:
    """Grid boundary of the gear flank and the toe/heel/root/tip labels."""
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    ring = np.concatenate(
        [
            np.c_[z[:, 0], r[:, 0]],
            np.c_[z[-1, :], r[-1, :]],
            np.c_[z[::-1, -1], r[::-1, -1]],
            np.c_[z[0, ::-1], r[0, ::-1]],
        ]
    )
    ax.plot(ring[:, 0], ring[:, 1], color="0.3", lw=0.8)
    mid_u, mid_v = z.shape[0] // 2, z.shape[1] // 2
    style = dict(fontsize=8, color="0.25", ha="center", va="center")
    ax.annotate(
        "toe", (z[0, mid_v], r[0, mid_v]), xytext=(-14, 0), textcoords="offset points", **style
    )
    ax.annotate(
        "heel", (z[-1, mid_v], r[-1, mid_v]), xytext=(16, 0), textcoords="offset points", **style
    )
    ax.annotate(
        "root", (z[mid_u, 0], r[mid_u, 0]), xytext=(0, -10), textcoords="offset points", **style
    )
    ax.annotate(
        "tip", (z[mid_u, -1], r[mid_u, -1]), xytext=(0, 10), textcoords="offset points", **style
    )
    ax.set_xlabel("gear axial position [mm]")
    ax.set_ylabel("gear radius [mm]")
    ax.set_aspect("equal")


def plot_easeoff(easeoff: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Ease-off topography over the gear flank, with iso-lines of the roll angle Q.

    Parameters
    ----------
    easeoff : xarray.Dataset
        The ``/easeoff`` group (``ease_off`` [um], ``roll_angle`` [rad], positions [mm]).
    path : path-like
        PNG to write; its directory must exist.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory does not exist or the dataset lacks the variables.
    """
    _require(easeoff, ("ease_off", "roll_angle", "axial_position", "radial_position"), "easeoff")
    plt = _pyplot()
    target = _target(path)
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    e = easeoff["ease_off"].values
    q = easeoff["roll_angle"].values
    fig, ax = plt.subplots(figsize=(8, 5))
    levels = np.linspace(0.0, max(float(np.nanmax(e)), 1e-3), 16)
    cs = ax.contourf(z, r, np.ma.masked_invalid(e), levels=levels, cmap="viridis")
    fig.colorbar(cs, ax=ax, label="ease-off along the gear normal [µm]")
    if np.isfinite(q).sum() > 4:
        qd = np.degrees(q)
        ql = ax.contour(
            z, r, np.ma.masked_invalid(qd), levels=10, colors="w", linewidths=0.6, linestyles="--"
        )
        ax.clabel(ql, fmt="%.0f°", fontsize=6)
    _outline(ax, easeoff)
    name, flank = easeoff.attrs.get("case", ""), easeoff.attrs.get("gear_flank", "")
    ax.set_title(f"{name}: ease-off (gear {flank} flank) and roll angle Q (dashed)", fontsize=9)
    fig.tight_layout()
    fig.savefig(target, dpi=130)
    plt.close(fig)
    return target


def plot_contact_pattern(
    easeoff: xr.Dataset, utca: xr.Dataset, path: str | os.PathLike[str]
) -> Path:
    """Unloaded contact pattern on the gear flank (seed Fig. 2.10).

    Contact lines (stretches within the separation) of every pair at every roll position
    are drawn on one flank (all teeth are alike), the active ones solid; the paths
    LPP/CPP/RPP over the active rolls, and the reference pair's contact curves at the
    transitions M1 and M2 that bound its pattern.

    Parameters
    ----------
    easeoff, utca : xarray.Dataset
        The ``/easeoff`` and ``/utca`` groups.
    path : path-like
        PNG to write.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory does not exist or the datasets lack the variables.
    """
    _require(
        utca,
        (
            "curve_axial_position",
            "curve_radial_position",
            "contact_pattern",
            "path_axial_position",
            "path_radial_position",
            "active",
        ),
        "utca",
    )
    plt = _pyplot()
    target = _target(path)
    cz = utca["curve_axial_position"].values
    cr = utca["curve_radial_position"].values
    pat = utca["contact_pattern"].values.astype(bool)
    act = utca["active"].values.astype(bool)
    pz = utca["path_axial_position"].values
    pr = utca["path_radial_position"].values
    pairs = utca["pair"].values
    fig, ax = plt.subplots(figsize=(8, 5))
    _outline(ax, easeoff)
    colours = plt.get_cmap("tab10")
    for j, k in enumerate(pairs):
        c = colours(j % 10)
        for i in range(cz.shape[0]):
            ax.plot(cz[i, j], cr[i, j], color=c, lw=0.3, alpha=0.35)
            if pat[i, j].any():
                seg = np.where(pat[i, j], 1.0, np.nan)
                ax.plot(cz[i, j] * seg, cr[i, j] * seg, color=c, lw=1.6, alpha=0.8)
        a = act[:, j]
        for m, (name, style) in enumerate((("LPP", ":"), ("CPP", "-"), ("RPP", ":"))):
            x = np.where(a, pz[:, j, m], np.nan)
            y = np.where(a, pr[:, j, m], np.nan)
            ax.plot(x, y, color="k", ls=style, lw=1.0, label=name if j == 0 else None)
        ax.plot([], [], color=c, lw=1.6, label=f"pair {int(k):+d}")
    # the reference pair's bounds: its curves at M1 (first roll) and at M2 (pair −1 then)
    if "transition_roll" in utca and np.isfinite(utca["transition_roll"].values).all():
        k0 = int(np.flatnonzero(pairs == 0)[0])
        ax.plot(cz[0, k0], cr[0, k0], color="r", lw=1.2, ls="--", label="M1, M2")
        if -1 in pairs:
            km = int(np.flatnonzero(pairs == -1)[0])
            ax.plot(cz[0, km], cr[0, km], color="r", lw=1.2, ls="--")
    ax.legend(fontsize=7, loc="upper left", ncol=2)
    sep = float(utca["separation_threshold"]) if "separation_threshold" in utca else np.nan
    ax.set_title(
        f"{utca.attrs.get('case', '')}: unloaded contact pattern (separation {sep:.1f} µm)",
        fontsize=9,
    )
    fig.tight_layout()
    fig.savefig(target, dpi=130)
    plt.close(fig)
    return target


def plot_transmission_error(utca: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """UTE curves of adjacent tooth pairs over three mesh cycles (seed Fig. 2.9).

    Pair k's curve is the reference pair's UTE shifted by k mesh cycles, UTE_k(r) =
    UTE_0(r − k·pitch); the dataset holds UTE_0 over three cycles (as pairs −1, 0, +1 over
    one), from which every pair's curve is drawn over the three cycles.

    Parameters
    ----------
    utca : xarray.Dataset
        The ``/utca`` group.
    path : path-like
        PNG to write.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory does not exist or the dataset lacks the variables.
    """
    _require(utca, ("pair_transmission_error", "unloaded_transmission_error"), "utca")
    plt = _pyplot()
    target = _target(path)
    roll = utca["roll"].values
    te = utca["pair_transmission_error"].values
    pairs = utca["pair"].values
    period = float(utca.attrs.get("mesh_period", roll[-1] - roll[0]))
    start = roll[0]
    # samples of UTE_0 at arguments r − k p
    arg = (roll[:, None] - pairs[None, :] * period).ravel()
    val = te.ravel()
    order = np.argsort(arg)
    arg, val = arg[order], val[order]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for k in pairs:
        x = (arg + k * period - start) / period
        ax.plot(x, val, lw=1.0, label=f"pair {int(k):+d}")
    x_all = np.unique(np.concatenate([arg + k * period for k in pairs]))
    env = np.full(x_all.shape, np.inf)
    for k in pairs:
        y = np.interp(x_all, arg + k * period, val, left=np.nan, right=np.nan)
        env = np.fmin(env, np.where(np.isfinite(y), y, np.inf))
    env[~np.isfinite(env)] = np.nan
    ax.plot((x_all - start) / period, env, color="k", lw=2.2, alpha=0.5, label="lower envelope")
    if "transition_roll" in utca:
        m = utca["transition_roll"].values
        tv = utca["transition_transmission_error"].values
        for name, mr, mv in zip(("M1", "M2"), m, tv, strict=True):
            if np.isfinite(mr):
                x = (mr - start) / period
                ax.plot([x], [mv], "ro", ms=4)
                ax.annotate(
                    name,
                    (x, mv),
                    xytext=(0, 6),
                    textcoords="offset points",
                    ha="center",
                    fontsize=8,
                )
    p2p = (
        float(utca["peak_to_peak_transmission_error"])
        if ("peak_to_peak_transmission_error" in utca)
        else np.nan
    )
    lo = np.nanmin(utca["unloaded_transmission_error"].values)
    ax.set_ylim(lo - 0.3 * max(p2p, 1.0), lo + 2.5 * max(p2p, 1.0))
    ax.set_xlim(-1.0, 2.0)
    ax.set_xlabel("mesh cycles from M1")
    ax.set_ylabel("unloaded transmission error [µrad]")
    ax.set_title(f"{utca.attrs.get('case', '')}: UTE, peak-to-peak {p2p:.2f} µrad", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(target, dpi=130)
    plt.close(fig)
    return target


def plot_utca(
    easeoff: xr.Dataset, utca: xr.Dataset, directory: str | os.PathLike[str]
) -> list[Path]:
    """All three UTCA plots into a directory (created if missing).

    Parameters
    ----------
    easeoff, utca : xarray.Dataset
    directory : path-like

    Returns
    -------
    list of pathlib.Path
        ``easeoff.png``, ``contact_pattern.png``, ``transmission_error.png``.
    """
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    return [
        plot_easeoff(easeoff, d / "easeoff.png"),
        plot_contact_pattern(easeoff, utca, d / "contact_pattern.png"),
        plot_transmission_error(utca, d / "transmission_error.png"),
    ]


def plot_loaded_transmission_error(ltca: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Loaded transmission error over the mesh cycles, one curve per torque (seed Fig. 3.6).

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset of :func:`contact.ltca.loaded_tca`.
    path : path-like
        PNG to write (its directory must exist).

    Returns
    -------
    pathlib.Path
    """
    _require(ltca, ["transmission_error", "mesh_cycle"], "ltca")
    plt = _pyplot()
    out = _target(path)
    nt = ltca.sizes["torque"]
    fig, axes = plt.subplots(nt, 1, figsize=(6.5, 2.2 * nt + 0.6), sharex=True, squeeze=False)
    x = ltca["mesh_cycle"].values
    for i, ax in enumerate(axes[:, 0]):
        te = ltca["transmission_error"].isel(torque=i).values
        T = float(ltca["torque"].values[i])
        ax.plot(x, te, "o-", ms=3, lw=1.2, color="C0")
        pp = float(np.nanmax(te) - np.nanmin(te)) if np.any(np.isfinite(te)) else float("nan")
        ax.set_title(
            f"T_p = {T:g} N m: mean {np.nanmean(te):.1f} urad, p-p {pp:.1f} urad", fontsize=9
        )
        ax.set_ylabel("LTE [urad]")
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("mesh cycles")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def _flank_xy(easeoff: xr.Dataset, u, v):
    from scipy.interpolate import RegularGridInterpolator

    uu, vv = easeoff["u"].values, easeoff["v"].values
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    pts = np.column_stack(
        [np.clip(np.ravel(u), uu[0], uu[-1]), np.clip(np.ravel(v), vv[0], vv[-1])]
    )
    fz = RegularGridInterpolator((uu, vv), np.nan_to_num(z))
    fr = RegularGridInterpolator((uu, vv), np.nan_to_num(r))
    return fz(pts).reshape(np.shape(u)), fr(pts).reshape(np.shape(u))


def _flank_scatter(
    easeoff: xr.Dataset, ltca: xr.Dataset, values: np.ndarray, path, title: str, label: str,
    edge: np.ndarray | None = None, edge_label: str = "edge contact",
) -> Path:
    """Segment values (roll, pair, segment) drawn at their places on the gear flank;
    ``edge`` (segment,) marks edge segments, drawn as black crosses over the colours of
    the others (their values, e.g. an edge's pressure, would swamp the colour scale)."""
    plt = _pyplot()
    out = _target(path)
    u = np.broadcast_to(ltca["segment_u"].values, values.shape)
    v = np.broadcast_to(ltca["segment_v"].values, values.shape)
    m = np.isfinite(values) & np.isfinite(u) & np.isfinite(v)
    e = np.zeros(values.shape, bool) if edge is None else np.broadcast_to(edge, values.shape)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    _outline(ax, easeoff)
    if np.any(m & ~e):
        x, y = _flank_xy(easeoff, u[m & ~e], v[m & ~e])
        order = np.argsort(values[m & ~e])
        sc = ax.scatter(x[order], y[order], c=values[m & ~e][order], s=6, cmap="jet")
        fig.colorbar(sc, ax=ax, label=label)
    if np.any(m & e):
        x, y = _flank_xy(easeoff, u[m & e], v[m & e])
        ax.scatter(x, y, marker="x", s=14, c="k", linewidths=0.8, label=edge_label)
        ax.legend(loc="lower right", fontsize=7)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("axial position [mm]")
    ax.set_ylabel("radius [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return out


def plot_pressure(
    easeoff: xr.Dataset, ltca: xr.Dataset, path: str | os.PathLike[str], torque_index: int = -1
) -> Path:
    """Pressure distribution on the gear flank over the mesh cycles (seed Fig. 3.7).

    Every loaded segment of every roll position and pair is drawn at its place on the gear
    flank (projection plane), coloured by its maximum Hertzian pressure; the outline and
    toe/heel/root/tip labels as in :func:`plot_easeoff`.

    Parameters
    ----------
    easeoff, ltca : xarray.Dataset
    path : path-like
    torque_index : int
        Which torque to draw (default the largest, the last).

    Returns
    -------
    pathlib.Path
    """
    _require(ltca, ["pressure_max", "segment_u", "segment_v"], "ltca")
    p = ltca["pressure_max"].isel(torque=torque_index).values
    p = np.where(p > 0, p, np.nan)
    T = float(ltca["torque"].values[torque_index])
    # edge segments (files from before the edge-contact model have none)
    edge = (ltca["segment_kind"].values != "curve" if "segment_kind" in ltca.coords
            else np.zeros(p.shape[-1], bool))
    flank = p[..., ~edge]
    pmax = float(np.nanmax(flank)) if np.any(np.isfinite(flank)) else float("nan")
    pe = p[..., edge]
    edge_label = (f"edge contact (peak {np.nanmax(pe):.0f} MPa)" if np.any(np.isfinite(pe))
                  else "edge contact")
    return _flank_scatter(
        easeoff,
        ltca,
        p,
        path,
        f"gear flank pressure, T_p = {T:g} N m (peak on the flank {pmax:.0f} MPa)",
        "max. pressure [MPa]",
        edge=edge,
        edge_label=edge_label,
    )


#: /friction variables drawn over the gear flank by :func:`plot_friction` (seed Figs. 5.5–5.10)
FRICTION_FLANK_PLOTS = {
    "sliding_velocity": "sliding velocity [m/s]",
    "rolling_velocity": "rolling velocity [m/s]",
    "slide_to_roll": "slide-to-roll ratio [1]",
    "lambda_ratio": "lambda ratio [1]",
    "friction_coefficient": "friction coefficient [1]",
    "sliding_loss": "sliding power loss [W]",
}


def plot_friction(
    easeoff: xr.Dataset,
    ltca: xr.Dataset,
    friction: xr.Dataset,
    directory: str | os.PathLike[str],
    torque_index: int = -1,
) -> list[Path]:
    """Distributions of the efficiency quantities over the gear flank (seed Figs. 5.5–5.10).

    One PNG per variable of :data:`FRICTION_FLANK_PLOTS` at one torque, plus the
    instantaneous efficiency over the mesh cycles.
    """
    _require(friction, list(FRICTION_FLANK_PLOTS), "friction")
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    T = float(friction["torque"].values[torque_index])
    out = []
    for name, label in FRICTION_FLANK_PLOTS.items():
        vals = friction[name].isel(torque=torque_index).values
        out.append(
            _flank_scatter(
                easeoff,
                ltca,
                vals,
                d / f"friction_{name}_{T:g}Nm.png",
                f"{label.split(' [')[0]}, T_p = {T:g} N m, "
                f"{friction.attrs.get('pinion_speed_rpm', 0):g} rpm",
                label,
            )
        )
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 3.2))
    x = ltca["mesh_cycle"].values
    for i, tq in enumerate(friction["torque"].values):
        ax.plot(
            x,
            100 * friction["efficiency"].isel(torque=i).values,
            "o-",
            ms=2.5,
            label=f"T_p = {tq:g} N m",
        )
    ax.set_xlabel("mesh cycles")
    ax.set_ylabel("efficiency [%]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(d / "friction_efficiency.png", dpi=120)
    plt.close(fig)
    out.append(d / "friction_efficiency.png")
    return out


def plot_load_share(ltca: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Load share of each tooth pair over the mesh cycles, one panel per torque."""
    _require(ltca, ["load_share", "mesh_cycle"], "ltca")
    plt = _pyplot()
    out = _target(path)
    nt = ltca.sizes["torque"]
    fig, axes = plt.subplots(nt, 1, figsize=(6.5, 2.0 * nt + 0.6), sharex=True, squeeze=False)
    x = ltca["mesh_cycle"].values
    for i, ax in enumerate(axes[:, 0]):
        share = ltca["load_share"].isel(torque=i)
        for k, pair in enumerate(ltca["pair"].values):
            y = share.isel(pair=k).values
            if np.nanmax(np.nan_to_num(y)) > 0:
                ax.plot(x, y, "o-", ms=2.5, lw=1, label=f"pair {int(pair):+d}")
        ax.set_ylim(-0.02, 1.02)
        ax.set_ylabel("load share")
        ax.set_title(f"T_p = {float(ltca['torque'].values[i]):g} N m", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=4)
    axes[-1, 0].set_xlabel("mesh cycles")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def plot_ltca(
    easeoff: xr.Dataset, ltca: xr.Dataset, directory: str | os.PathLike[str]
) -> list[Path]:
    """The LTCA plots (LTE, pressure at each torque, load share) into ``directory``."""
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    out = [
        plot_loaded_transmission_error(ltca, d / "ltca_transmission_error.png"),
        plot_load_share(ltca, d / "ltca_load_share.png"),
    ]
    for i, T in enumerate(ltca["torque"].values):
        out.append(plot_pressure(easeoff, ltca, d / f"ltca_pressure_{float(T):g}Nm.png", i))
    return out


def plot_analysis(tree: xr.DataTree, directory: str | os.PathLike[str]) -> list[Path]:
    """Every plot of an analysis from its DataTree alone (e.g. ``read_netcdf(file)``).

    Raises
    ------
    InputError
        If the tree lacks the ``/easeoff`` group.
    """
    if "easeoff" not in tree.children:
        raise InputError("tree: has no /easeoff group (not a hypoid-ltca analysis file)")
    eo = tree["easeoff"].to_dataset()
    out: list[Path] = []
    if "utca" in tree.children:
        out += plot_utca(eo, tree["utca"].to_dataset(), directory)
    if "ltca" in tree.children:
        out += plot_ltca(eo, tree["ltca"].to_dataset(), directory)
        if "theoretical" in tree.children:
            th = tree["theoretical"]
            out += plot_deviations(
                eo,
                tree["ltca"].to_dataset(),
                th["ltca"].to_dataset(),
                directory,
                utca=tree["utca"].to_dataset() if "utca" in tree.children else None,
                theoretical_easeoff=th["easeoff"].to_dataset(),
                theoretical_utca=th["utca"].to_dataset(),
            )
        if "friction" in tree.children:
            out += plot_friction(
                eo, tree["ltca"].to_dataset(), tree["friction"].to_dataset(), directory
            )
    return out


def plot_efficiency_map(emap: xr.Dataset, directory: str | os.PathLike[str]) -> list[Path]:
    """Efficiency against speed for each torque, and against roughness for each temperature.

    Parameters
    ----------
    emap : xarray.Dataset
        The output of :func:`contact.pipeline.efficiency_map`.
    directory : path-like
        Created if missing.

    Returns
    -------
    list of pathlib.Path
        ``efficiency_vs_speed.png``, ``power_loss_vs_speed.png``,
        ``efficiency_vs_roughness.png`` (as the seed's Figs. 5.11–5.12).
    """
    _require(emap, ["efficiency", "power_loss"], "emap")
    plt = _pyplot()
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    out = []
    first = {"temperature": 0, "roughness": 0}
    for var, label, name in (
        ("efficiency", "efficiency [%]", "efficiency_vs_speed.png"),
        ("power_loss", "power loss [W]", "power_loss_vs_speed.png"),
    ):
        fig, ax = plt.subplots(figsize=(6, 4))
        sel = emap[var].isel(**first)
        for T in emap["torque"].values:
            y = sel.sel(torque=T).values * (100 if var == "efficiency" else 1)
            ax.plot(emap["speed"].values, y, "o-", label=f"T_p = {T:g} N m")
        ax.set_xlabel("pinion speed [rpm]")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(d / name, dpi=120)
        plt.close(fig)
        out.append(d / name)
    fig, ax = plt.subplots(figsize=(6, 4))
    sel = emap["efficiency"].isel(torque=-1, speed=-1)
    for t in emap["temperature"].values:
        ax.plot(
            emap["roughness"].values, 100 * sel.sel(temperature=t).values, "o-", label=f"{t:g} degC"
        )
    ax.set_xlabel("RMS roughness Rq [um]")
    ax.set_ylabel("efficiency [%]")
    ax.set_title(
        f"T_p = {float(emap['torque'].values[-1]):g} N m, {float(emap['speed'].values[-1]):g} rpm",
        fontsize=9,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(d / "efficiency_vs_roughness.png", dpi=120)
    plt.close(fig)
    out.append(d / "efficiency_vs_roughness.png")
    return out


def plot_deviations(
    easeoff: xr.Dataset,
    ltca: xr.Dataset,
    theoretical_ltca: xr.Dataset,
    directory: str | os.PathLike[str],
    *,
    utca: xr.Dataset | None = None,
    theoretical_easeoff: xr.Dataset | None = None,
    theoretical_utca: xr.Dataset | None = None,
) -> list[Path]:
    """Theoretical against deviated surfaces (seed Figs. 4.6–4.9 and 4.11–4.14).

    Parameters
    ----------
    easeoff, ltca : xarray.Dataset
        ``/easeoff`` (with ``ease_off_change`` [um]) and ``/ltca`` of the deviated surfaces.
    theoretical_ltca : xarray.Dataset
        ``/theoretical/ltca``.
    directory : path-like
        Created if missing.
    utca, theoretical_easeoff, theoretical_utca : xarray.Dataset, optional
        ``/utca``, ``/theoretical/easeoff`` and ``/theoretical/utca``; with them the
        unloaded patterns, UTE curves and pressure of both surfaces are drawn too.

    Returns
    -------
    list of pathlib.Path
        ``deviations_easeoff_change.png`` (Figs. 4.6(c), 4.11(c): change of the ease-off
        topography), ``deviations_transmission_error.png`` (Figs. 4.8(b), 4.13(b): LTE of
        both surfaces per torque) and, with the optional groups,
        ``deviations_easeoff_{theoretical,deviated}.png`` (Figs. 4.6, 4.11),
        ``deviations_contact_pattern_{theoretical,deviated}.png`` (Figs. 4.7, 4.12),
        ``deviations_unloaded_transmission_error.png`` (Figs. 4.8(a), 4.13(a)) and
        ``deviations_pressure_{theoretical,deviated}.png`` at the largest torque (Figs.
        4.9, 4.14).

    Raises
    ------
    InputError
        If a dataset lacks the variables drawn.
    """
    _require(easeoff, ["ease_off_change"], "easeoff")
    plt = _pyplot()
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    _outline(ax, easeoff)
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    ch = easeoff["ease_off_change"].values
    cs = ax.contourf(z, r, ch, levels=15, cmap="coolwarm")
    fig.colorbar(cs, ax=ax, label="ease-off change [um]")
    ax.set_title("ease-off change by the surface deviations", fontsize=9)
    ax.set_xlabel("axial position [mm]")
    ax.set_ylabel("radius [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    fig.tight_layout()
    out = [d / "deviations_easeoff_change.png"]
    fig.savefig(out[0], dpi=130)
    plt.close(fig)
    nt = ltca.sizes["torque"]
    fig, axes = plt.subplots(nt, 1, figsize=(6.5, 2.2 * nt + 0.6), sharex=True, squeeze=False)
    x = ltca["mesh_cycle"].values
    for i, ax in enumerate(axes[:, 0]):
        ax.plot(
            x,
            theoretical_ltca["transmission_error"].isel(torque=i),
            "o-",
            ms=2.5,
            label="theoretical",
        )
        ax.plot(x, ltca["transmission_error"].isel(torque=i), "s-", ms=2.5, label="deviated")
        ax.set_title(f"T_p = {float(ltca['torque'].values[i]):g} N m", fontsize=9)
        ax.set_ylabel("LTE [urad]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[-1, 0].set_xlabel("mesh cycles")
    fig.tight_layout()
    out.append(d / "deviations_transmission_error.png")
    fig.savefig(out[-1], dpi=120)
    plt.close(fig)
    if utca is None or theoretical_easeoff is None or theoretical_utca is None:
        return out
    both = {"theoretical": (theoretical_easeoff, theoretical_utca, theoretical_ltca),
            "deviated": (easeoff, utca, ltca)}
    for name, (e, u, lt) in both.items():
        out.append(plot_easeoff(e, d / f"deviations_easeoff_{name}.png"))
        out.append(plot_contact_pattern(e, u, d / f"deviations_contact_pattern_{name}.png"))
        out.append(plot_pressure(e, lt, d / f"deviations_pressure_{name}.png"))
    _require(utca, ["unloaded_transmission_error"], "utca")
    _require(theoretical_utca, ["unloaded_transmission_error"], "theoretical_utca")
    fig, ax = plt.subplots(figsize=(6.5, 3.6))
    for (name, (_, u, _)), style in zip(both.items(), ("o-", "s-"), strict=True):
        period = float(u.attrs.get("mesh_period", 1.0))
        roll = u["roll"].values
        ax.plot(
            (roll - roll[0]) / period,
            u["unloaded_transmission_error"].values,
            style,
            ms=2.5,
            label=f"{name}: p-p {float(u['peak_to_peak_transmission_error']):.1f} urad",
        )
    ax.set_xlabel("mesh cycles")
    ax.set_ylabel("UTE [urad]")
    ax.set_title("unloaded transmission error (lower envelope)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out.append(d / "deviations_unloaded_transmission_error.png")
    fig.savefig(out[-1], dpi=120)
    plt.close(fig)
    return out
