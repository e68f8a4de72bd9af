"""The mesh interface for dynamic models, drawn: stiffness, excitation, line and point.

Public functions
----------------
mesh_interface_figure   mesh stiffness, transmission-error excitation and their
                        harmonics, and the rotation radii over the mesh cycles
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contact.plots.curves import MESH_CYCLES_LABEL
from contact.plots.style import case_text, legend_below, panel_grid, title, torque_text
from contact.plots.tooth import require

__all__ = ["mesh_interface_figure"]

def mesh_interface_figure(mesh: xr.Dataset, ltca: xr.Dataset | None = None) -> Figure:
    """The mesh interface over the mesh cycles, one line per torque (four panels).

    Parameters
    ----------
    mesh : xarray.Dataset
        ``/mesh_interface`` (:func:`contact.ltca.mesh_interface.mesh_interface`):
        ``mesh_stiffness`` [N/µm], ``te_excitation`` [µm] and their harmonic amplitudes,
        ``gear_rotation_radius``, ``pinion_rotation_radius`` [mm] over (torque, roll).
    ltca : xarray.Dataset, optional
        ``/ltca``, for the case name and misalignment in the title.

    Returns
    -------
    matplotlib.figure.Figure
        Panels: effective mesh stiffness along the line of action; the transmission-error
        excitation about its mean; the peak amplitudes of their mesh harmonics; the
        directional rotation radii about the gear and pinion axes.

    Raises
    ------
    InputError
        If ``mesh`` lacks a variable drawn.
    """
    require(mesh, ("mesh_stiffness", "te_excitation", "te_excitation_amplitude",
                   "mesh_stiffness_amplitude", "gear_rotation_radius",
                   "pinion_rotation_radius"), "mesh_interface")
    fig, axes, _ = panel_grid(2, 2, panel=(3.6, 2.3), legend_rows=1, sharex=False,
                              sharey=False, left=0.85, wspace=0.95)
    x = mesh["mesh_cycle"].values
    handles = []
    h = mesh["harmonic"].values
    nt = mesh.sizes["torque"]
    width = 0.8 / max(nt, 1)
    for i, tq in enumerate(mesh["torque"].values):
        colour = f"C{i}"
        k = mesh["mesh_stiffness"].isel(torque=i).values
        e = mesh["te_excitation"].isel(torque=i).values
        (line,) = axes[0, 0].plot(x, k, "o-", ms=2.2, lw=1, color=colour,
                                  label=torque_text(tq))
        handles.append(line)
        axes[0, 1].plot(x, e - np.nanmean(e), "o-", ms=2.2, lw=1, color=colour)
        axes[1, 0].bar(h + (i - (nt - 1) / 2) * width,
                       mesh["te_excitation_amplitude"].isel(torque=i).values, width,
                       color=colour)
        axes[1, 1].plot(x, mesh["gear_rotation_radius"].isel(torque=i).values, "o-", ms=2,
                        lw=1, color=colour)
        axes[1, 1].plot(x, np.abs(mesh["pinion_rotation_radius"].isel(torque=i).values),
                        "s--", ms=2, lw=1, color=colour)
    axes[0, 0].set_ylabel("mesh stiffness k_m [N/µm]")
    axes[0, 0].set_title("effective mesh stiffness along the line of action", fontsize=8)
    axes[0, 1].set_ylabel("excitation e − mean [µm]")
    axes[0, 1].set_title("transmission-error excitation along the line of action",
                         fontsize=8)
    axes[1, 0].set_ylabel("peak amplitude [µm]")
    axes[1, 0].set_xlabel("mesh harmonic [1]")
    axes[1, 0].set_xticks(h)
    axes[1, 0].set_title("harmonics of the excitation", fontsize=8)
    axes[1, 1].set_ylabel("rotation radius [mm]")
    axes[1, 1].set_title("λ_g (gear, solid) and |λ_p| (pinion, dashed)", fontsize=8)
    for ax in (axes[0, 0], axes[0, 1], axes[1, 1]):
        ax.set_xlabel(MESH_CYCLES_LABEL)
    for ax in axes.ravel():
        ax.grid(alpha=0.3)
    legend_below(fig, handles, ncols=6)
    src = ltca if ltca is not None else mesh
    title(fig, f"{case_text(src)}\nmesh interface for dynamic models "
          "(mesh stiffness, transmission-error excitation)")
    return fig
