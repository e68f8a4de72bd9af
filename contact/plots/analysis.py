"""Every figure of an analysis, named and captioned, drawn from its DataTree alone.

:func:`analysis_figures` yields the figures of a tree read back from ``ltca run``'s
netCDF (or straight from :func:`contact.pipeline.run_analysis`) one at a time, each with
a file name and a caption; :func:`plot_analysis` writes them as PNGs and the HTML report
(:mod:`contact.plots.report`) embeds them. Groups a tree lacks (no ``/friction`` when the
efficiency stage was skipped, no ``/theoretical`` without deviations) give no figures.

Public functions
----------------
NamedFigure            a figure with its file name and caption
analysis_figures       the figures of an analysis tree
plot_analysis          write them as PNGs into a directory
plot_utca              the unloaded figures (``ltca utca --plots``)
efficiency_map_figures the figures of an efficiency map
plot_efficiency_map    write them as PNGs into a directory
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import xarray as xr
from matplotlib.figure import Figure

from contact.plots.curves import (
    efficiency_curve_figure,
    load_share_figure,
    te_comparison_figure,
    transmission_error_figure,
)
from contact.plots.flank import (
    FRICTION_FLANK_PLOTS,
    contact_pattern_figure,
    easeoff_contour_figure,
    easeoff_map_figure,
    easeoff_topography_figure,
    friction_flank_figure,
    pressure_figure,
    segment_panels_figure,
)
from contact.plots.maps import (
    efficiency_map_figure,
    efficiency_roughness_figure,
    efficiency_speed_figure,
)
from contact.plots.style import save_png, torque_text
from geometry.errors import InputError

__all__ = [
    "NamedFigure",
    "analysis_figures",
    "efficiency_map_figures",
    "plot_analysis",
    "plot_efficiency_map",
    "plot_utca",
]


@dataclass(frozen=True)
class NamedFigure:
    """A figure with the stem of its file name and a caption (for the report)."""

    name: str
    caption: str
    figure: Figure


def _group(tree: xr.DataTree, path: str) -> xr.Dataset | None:
    try:
        return tree[path].to_dataset()
    except KeyError:
        return None


def _deviation_figures(tree: xr.DataTree, eo, ut, lt) -> Iterator[NamedFigure]:
    th_eo, th_ut, th_lt = (_group(tree, f"theoretical/{g}") for g in ("easeoff", "utca", "ltca"))
    if th_eo is not None:
        yield NamedFigure(
            "deviations_easeoff",
            "Ease-off of the theoretical and the deviated surfaces on one scale "
            "(seed Figs. 4.6, 4.11).",
            easeoff_map_figure({"theoretical": th_eo, "deviated": eo}))
    if "ease_off_change" in eo:
        yield NamedFigure(
            "deviations_easeoff_change",
            "Change of the ease-off by the surface deviations, deviated − theoretical; "
            "the diverging colours are centred on zero (seed Figs. 4.6c, 4.11c).",
            easeoff_map_figure({"deviated − theoretical": eo}, "ease_off_change",
                               diverging=True))
    if th_eo is not None and th_ut is not None:
        yield NamedFigure(
            "deviations_contact_pattern_theoretical",
            "Contact patterns of the theoretical surfaces, beside the deviated ones above "
            "(seed Figs. 4.7, 4.12).",
            contact_pattern_figure(th_eo, th_ut, th_lt))
    if th_lt is not None and lt is not None and th_eo is not None:
        panels = []
        for i, t in enumerate(lt["torque"].values):
            for name, e, dl in (("theoretical", th_eo, th_lt), ("deviated", eo, lt)):
                panels.append((f"{name}, {torque_text(t)}", e, dl,
                               dl["pressure_max"].isel(torque=i).values))
        yield NamedFigure(
            "deviations_pressure",
            "Maximum contact pressure of the theoretical (left) and deviated (right) "
            "surfaces at each torque, one colour scale (seed Figs. 4.9, 4.14).",
            segment_panels_figure(panels, label="maximum Hertzian pressure [MPa]",
                                  edges_apart=True, columns=2,
                                  what="maximum contact pressure: theoretical and deviated"))
    if th_lt is not None and th_ut is not None and lt is not None and ut is not None:
        yield NamedFigure(
            "deviations_transmission_error",
            "UTE and LTE of the theoretical and deviated surfaces (seed Figs. 4.8, 4.13).",
            te_comparison_figure({"theoretical": (th_ut, th_lt), "deviated": (ut, lt)}))


def analysis_figures(tree: xr.DataTree) -> Iterator[NamedFigure]:
    """The figures of an analysis, one at a time (drawn when asked for).

    Parameters
    ----------
    tree : xarray.DataTree
        ``run_analysis``'s tree or ``read_netcdf(file, tree=True)``: ``/easeoff`` and
        any of ``/utca``, ``/ltca``, ``/friction``, ``/theoretical``.

    Yields
    ------
    NamedFigure
        ``easeoff_topography``, ``easeoff``, ``contact_pattern``,
        ``transmission_error``, ``pressure``, ``load_share``, ``friction_flank``,
        ``friction_efficiency`` and, for deviated runs, ``deviations_*`` — those whose
        groups the tree has.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff`` (not an analysis file).
    """
    eo = _group(tree, "easeoff")
    if eo is None:
        raise InputError("tree: has no /easeoff group (not a hypoid-ltca analysis file)")
    ut, lt, fr = (_group(tree, g) for g in ("utca", "ltca", "friction"))
    yield NamedFigure("easeoff_topography",
                      "Ease-off over the normalised gear tooth (seed Fig. 2.8).",
                      easeoff_topography_figure(eo))
    yield NamedFigure("easeoff",
                      "Ease-off on the gear's projection plane, with iso-lines of the roll "
                      "angle (seed Fig. 2.7).", easeoff_contour_figure(eo))
    if ut is not None:
        yield NamedFigure(
            "contact_pattern",
            "Unloaded pattern and, per torque, the loaded pattern on the same outline, "
            "with the paths of contact (seed Figs. 2.10, 3.7).",
            contact_pattern_figure(eo, ut, lt))
    if ut is not None or lt is not None:
        yield NamedFigure(
            "transmission_error",
            "UTE of the tooth pairs and their envelope; LTE per torque (seed Figs. 2.9, 3.6).",
            transmission_error_figure(ut, lt))
    if lt is not None:
        yield NamedFigure(
            "pressure",
            "Maximum contact pressure over two mesh cycles, one colour scale for all "
            "torques; the edge contact in its own scale outside the flank (seed Fig. 3.7).",
            pressure_figure(eo, lt))
        yield NamedFigure("load_share", "Load sharing of the tooth pairs.",
                          load_share_figure(lt))
    if fr is not None and lt is not None:
        if any(name in fr for name in FRICTION_FLANK_PLOTS):
            yield NamedFigure(
                "friction_flank",
                "Sliding and rolling velocity, slide-to-roll ratio, lambda ratio, friction "
                "coefficient and sliding loss on the gear flank at the largest torque "
                "(seed Figs. 5.5–5.10).",
                friction_flank_figure(eo, lt, fr))
        yield NamedFigure("friction_efficiency",
                          "Instantaneous mechanical efficiency over the mesh cycles.",
                          efficiency_curve_figure(fr, lt))
    if "theoretical" in tree.children:
        yield from _deviation_figures(tree, eo, ut, lt)


def _write(figures, directory: str | os.PathLike[str]) -> list[Path]:
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    return [save_png(nf.figure, d / f"{nf.name}.png") for nf in figures]


def plot_analysis(tree: xr.DataTree, directory: str | os.PathLike[str]) -> list[Path]:
    """Write every figure of an analysis (:func:`analysis_figures`) as PNG into ``directory``
    (created if missing) and return the paths.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff``.
    """
    return _write(analysis_figures(tree), directory)


def plot_utca(easeoff: xr.Dataset, utca: xr.Dataset,
              directory: str | os.PathLike[str]) -> list[Path]:
    """The unloaded figures (ease-off topography and contour, pattern, UTE) into
    ``directory`` (created if missing).

    Returns
    -------
    list of pathlib.Path
    """
    figs = [NamedFigure("easeoff_topography", "", easeoff_topography_figure(easeoff)),
            NamedFigure("easeoff", "", easeoff_contour_figure(easeoff)),
            NamedFigure("contact_pattern", "", contact_pattern_figure(easeoff, utca)),
            NamedFigure("transmission_error", "", transmission_error_figure(utca, None))]
    return _write(figs, directory)


def efficiency_map_figures(emap: xr.Dataset) -> Iterator[NamedFigure]:
    """The figures of an efficiency map (:func:`contact.pipeline.efficiency_map`).

    Yields
    ------
    NamedFigure
        ``efficiency_map`` (speed × torque contour, a panel per temperature and
        roughness), ``power_loss_map``, ``efficiency_vs_speed`` and, when roughness or
        temperature is swept, ``efficiency_vs_roughness``.
    """
    yield NamedFigure("efficiency_map", "Efficiency over pinion speed × torque.",
                      efficiency_map_figure(emap))
    if "power_loss" in emap:
        yield NamedFigure("power_loss_map", "Mesh power loss over pinion speed × torque.",
                          efficiency_map_figure(emap, "power_loss"))
    yield NamedFigure("efficiency_vs_speed", "Efficiency against speed (seed Fig. 5.11).",
                      efficiency_speed_figure(emap))
    if emap.sizes.get("roughness", 1) > 1 or emap.sizes.get("temperature", 1) > 1:
        yield NamedFigure("efficiency_vs_roughness",
                          "Efficiency against roughness per oil temperature (seed Fig. 5.12).",
                          efficiency_roughness_figure(emap))


def plot_efficiency_map(emap: xr.Dataset, directory: str | os.PathLike[str]) -> list[Path]:
    """Write the figures of an efficiency map as PNGs into ``directory`` (created if
    missing) and return the paths."""
    return _write(efficiency_map_figures(emap), directory)
