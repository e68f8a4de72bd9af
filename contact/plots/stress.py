"""Figure of the tooth-root stress: fillet stress over face width × mesh, and its envelope.

Public functions
----------------
tooth_history        one tooth's root stress over its passage through mesh
root_stress_figure   per member: the map at the largest torque and the envelope per torque
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contact.plots.style import case_text, legend_below, panel_grid, title, torque_text
from contact.plots.tooth import require

__all__ = ["root_stress_figure", "tooth_history"]


def tooth_history(ltca: xr.Dataset, torque_index: int, member: str
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """One tooth's root stress as it passes through mesh.

    At a roll a fraction m of the way through its mesh cycle, the tooth of pair k is the
    one that was (will be) the reference pair's tooth k cycles later (earlier): the pair
    offsets count from the pair that takes over at each cycle's start
    (:func:`contact.ltca.segments.segment_geometry`). So the stress of pair k at m is the
    one tooth's at x = m − k mesh cycles; the first mesh cycle's rolls give it all.

    Parameters
    ----------
    ltca : xarray.Dataset — ``/ltca`` with ``root_stress`` (torque, roll, member, tooth,
        fillet_point) [MPa], ``mesh_cycle`` (roll) [1], ``fillet_u`` (member, fillet_point)
    torque_index : int
    member : str — ``"pinion"`` or ``"gear"``

    Returns
    -------
    (x, u, stress) — x (M,) [mesh cycles] sorted, u (F,) [1] the face stations'
        lengthwise fractions, stress (M, F) [MPa]

    Raises
    ------
    InputError — ``ltca`` lacks a variable.
    """
    require(ltca, ("root_stress", "mesh_cycle", "fillet_u"), "ltca")
    rs = ltca["root_stress"].isel(torque=torque_index).sel(member=member)
    m = np.asarray(ltca["mesh_cycle"].values, float)
    first = m < 1.0 - 1e-9
    pairs = np.asarray(ltca["tooth"].values, float)
    x = (m[first][None, :] - pairs[:, None]).ravel()  # (tooth, roll)
    s = rs.transpose("tooth", "roll", "fillet_point").values[:, first].reshape(x.size, -1)
    order = np.argsort(x)
    return x[order], ltca["fillet_u"].sel(member=member).values, s[order]


def root_stress_figure(ltca: xr.Dataset) -> Figure:
    """Tooth-root stress of both members: over face width × mesh, and its envelope.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` with ``root_stress`` [MPa] and ``root_stress_max`` [MPa]
        (:func:`contact.ltca.root_stress.root_stress`), ``mesh_cycle``.

    Returns
    -------
    matplotlib.figure.Figure
        Left, per member: one tooth's fillet stress (largest max principal over both
        fillets) over its passage through mesh (x) and the face width (y) at the largest
        torque. Right: its envelope along the face width (max over the passage), per
        torque.

    Raises
    ------
    InputError
        If ``/ltca`` lacks the root stress.
    """
    require(ltca, ("root_stress", "root_stress_max", "mesh_cycle", "fillet_u"), "ltca")
    members = [str(m) for m in ltca["member"].values]
    nt = ltca.sizes["torque"]
    fig, grid, cax = panel_grid(len(members), 2, panel=(3.3, 2.2), colorbars=1,
                              legend_rows=1, sharex=False, sharey=False)
    vmax = float(np.nanmax(ltca["root_stress"].isel(torque=nt - 1).values)) or 1.0
    mesh = None
    for r, member in enumerate(members):
        ax_map, ax_env = grid[r, 0], grid[r, 1]
        x, u, s = tooth_history(ltca, nt - 1, member)
        mesh = ax_map.pcolormesh(x, u, s.T, shading="nearest", cmap="viridis", vmin=0.0,
                                 vmax=vmax)
        ax_map.set_ylabel(f"{member}: face fraction [1]")
        ax_map.set_title(f"{member}, {torque_text(ltca['torque'].values[-1])}", fontsize=8)
        for i in range(nt):
            _, uu, si = tooth_history(ltca, i, member)
            ax_env.plot(uu, np.nanmax(si, axis=0), "o-", ms=2, lw=1, color=f"C{i}",
                        label=torque_text(ltca["torque"].values[i]))
        ax_env.set_title(f"{member}: envelope along the face", fontsize=8)
        ax_env.set_ylabel("root stress [MPa]")
        ax_env.grid(alpha=0.3)
    grid[-1, 0].set_xlabel("passage through mesh [mesh cycles]")
    grid[-1, 1].set_xlabel("face fraction (toe 0, heel 1) [1]")
    if mesh is not None:
        fig.colorbar(mesh, cax=cax[0], label="root stress [MPa]")
    legend_below(fig, grid[0, 1].get_lines(), ncols=4)
    title(fig, f"{case_text(ltca)}\ntooth-root stress (max principal, FE superposition)")
    return fig
