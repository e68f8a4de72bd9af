"""Every figure of an analysis, named and captioned, drawn from its DataTree alone.

:func:`analysis_figures` yields the figures of a tree read back from ``ltca run``'s
netCDF (or straight from :func:`contact.pipeline.run_analysis`) one at a time, each with
a file name and a caption; :func:`plot_analysis` writes them as PNGs and the HTML report
(:mod:`contact.plots.report`) embeds them. Groups a tree lacks (no ``/friction`` when the
efficiency stage was skipped, no ``/theoretical`` without deviations) give no figures.

Public functions
----------------
NamedFigure            a figure with its file name and caption
RenderedFigure         the same encoded as PNG; render_figures encodes them
FigureSpec             a figure not yet drawn (the call that draws it)
analysis_specs         the figures of an analysis tree, as calls
analysis_figures       the same, drawn
render_analysis        the same, encoded as PNG by one or more processes
plot_analysis          write them as PNGs into a directory
plot_utca              the unloaded figures (``ltca utca --plots``)
efficiency_map_figures the figures of an efficiency map
plot_efficiency_map    write them as PNGs into a directory
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from functools import partial
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contact.plots.curves import (
    efficiency_curve_figure,
    load_share_figure,
    te_comparison_figure,
    transmission_error_figure,
)
from contact.plots.dynamics import mesh_interface_figure
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
from contact.plots.stress import root_stress_figure
from contact.plots.style import DPI, png_bytes, save_png, torque_text
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords

__all__ = [
    "FigureSpec",
    "NamedFigure",
    "RenderedFigure",
    "analysis_figures",
    "analysis_specs",
    "efficiency_map_figures",
    "figure_prefix",
    "plot_analysis",
    "plot_efficiency_map",
    "plot_utca",
    "render_analysis",
    "render_figures",
    "torque_tag",
]


@dataclass(frozen=True)
class NamedFigure:
    """A figure with the stem of its file name and a caption (for the report)."""

    name: str
    caption: str
    figure: Figure


@dataclass(frozen=True)
class FigureSpec:
    """A figure not yet drawn: its name, caption and the call that draws it (picklable,
    so another process can draw it)."""

    name: str
    caption: str
    draw: partial


@dataclass(frozen=True)
class RenderedFigure:
    """A figure encoded once as PNG, for the files and the report alike."""

    name: str
    caption: str
    png: bytes


def render_figures(figures: Iterable[NamedFigure], dpi: int = DPI) -> Iterator[RenderedFigure]:
    """Each figure encoded as PNG (drawn once; the Figure is not kept)."""
    for nf in figures:
        yield RenderedFigure(nf.name, nf.caption, png_bytes(nf.figure, dpi))


def _group(tree: xr.DataTree, path: str) -> xr.Dataset | None:
    """A group as a Dataset, with the root's misalignment attributes (stored once at the
    root of an analysis file) for the figures' titles."""
    try:
        ds = tree[path].to_dataset()
    except KeyError:
        return None
    root = {k: v for k, v in tree.attrs.items() if k.startswith("misalignment_")}
    return ds.assign_attrs(root) if root else ds


def _deviation_specs(tree: xr.DataTree, eo, ut, lt) -> Iterator[FigureSpec]:
    th_eo, th_ut, th_lt = (_group(tree, f"theoretical/{g}") for g in ("easeoff", "utca", "ltca"))
    if th_eo is not None:
        yield FigureSpec(
            "deviations_easeoff",
            "Ease-off of the theoretical and the deviated surfaces on one scale "
            "(seed Figs. 4.6, 4.11).",
            partial(easeoff_map_figure, {"theoretical": th_eo, "deviated": eo}))
    if "ease_off_change" in eo:
        yield FigureSpec(
            "deviations_easeoff_change",
            "Change of the ease-off by the surface deviations, deviated − theoretical; "
            "the diverging colours are centred on zero (seed Figs. 4.6c, 4.11c).",
            partial(easeoff_map_figure, {"deviated − theoretical": eo}, "ease_off_change",
                    diverging=True))
    if th_eo is not None and th_ut is not None:
        yield FigureSpec(
            "deviations_contact_pattern_theoretical",
            "Contact patterns of the theoretical surfaces, beside the deviated ones above "
            "(seed Figs. 4.7, 4.12).",
            partial(contact_pattern_figure, th_eo, th_ut, th_lt))
    if th_lt is not None and lt is not None and th_eo is not None:
        panels = []
        for i, t in enumerate(lt["torque"].values):
            for name, e, dl in (("theoretical", th_eo, th_lt), ("deviated", eo, lt)):
                panels.append((f"{name}, {torque_text(t)}", e, dl,
                               dl["pressure_max"].isel(torque=i).values))
        yield FigureSpec(
            "deviations_pressure",
            "Maximum contact pressure of the theoretical (left) and deviated (right) "
            "surfaces at each torque, one colour scale (seed Figs. 4.9, 4.14).",
            partial(segment_panels_figure, panels, label="maximum Hertzian pressure [MPa]",
                                  edges_apart=True, columns=2,
                                  what="maximum contact pressure: theoretical and deviated"))
    if th_lt is not None and th_ut is not None and lt is not None and ut is not None:
        yield FigureSpec(
            "deviations_transmission_error",
            "UTE and LTE of the theoretical and deviated surfaces (seed Figs. 4.8, 4.13).",
            partial(te_comparison_figure, {"theoretical": (th_ut, th_lt), "deviated": (ut, lt)}))


def analysis_specs(tree: xr.DataTree) -> Iterator[FigureSpec]:
    """The figures of an analysis, each as the function call that draws it.

    Parameters
    ----------
    tree : xarray.DataTree
        ``run_analysis``'s tree or ``read_netcdf(file, tree=True)``: ``/easeoff`` and
        any of ``/utca``, ``/ltca``, ``/friction``, ``/theoretical``.

    Yields
    ------
    FigureSpec
        ``easeoff_topography``, ``easeoff``, ``contact_pattern``,
        ``transmission_error``, ``pressure``, ``load_share``, ``root_stress`` (when
        ``/ltca`` has it), ``friction_flank``,
        ``friction_efficiency``, ``mesh_interface`` and, for deviated runs,
        ``deviations_*`` — those whose groups the tree has.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff`` (not an analysis file).
    """
    eo = _group(tree, "easeoff")
    if eo is None:
        raise InputError("tree: has no /easeoff group (not a hypoid-ltca analysis file)")
    ut, lt, fr = (_group(tree, g) for g in ("utca", "ltca", "friction"))
    yield FigureSpec("easeoff_topography",
                      "Ease-off over the normalised gear tooth (seed Fig. 2.8).",
                      partial(easeoff_topography_figure, eo))
    yield FigureSpec("easeoff",
                      "Ease-off on the gear's projection plane, with iso-lines of the roll "
                      "angle (seed Fig. 2.7).", partial(easeoff_contour_figure, eo))
    if ut is not None:
        yield FigureSpec(
            "contact_pattern",
            "Unloaded pattern and, per torque, the loaded pattern on the same outline, "
            "with the paths of contact (seed Figs. 2.10, 3.7).",
            partial(contact_pattern_figure, eo, ut, lt))
    if ut is not None or lt is not None:
        yield FigureSpec(
            "transmission_error",
            "UTE of the tooth pairs and their envelope; LTE per torque (seed Figs. 2.9, 3.6).",
            partial(transmission_error_figure, ut, lt))
    if lt is not None:
        yield FigureSpec(
            "pressure",
            "Maximum contact pressure over two mesh cycles, one colour scale for all "
            "torques; the edge contact in its own scale outside the flank (seed Fig. 3.7).",
            partial(pressure_figure, eo, lt))
        yield FigureSpec("load_share", "Load sharing of the tooth pairs.",
                          partial(load_share_figure, lt))
        if "root_stress" in lt:
            yield FigureSpec(
                "root_stress",
                "Tooth-root stress of both members (largest maximum principal stress over "
                "the fillets, FE influence coefficients): one tooth's passage through mesh "
                "over the face width at the largest torque, and its envelope along the "
                "face per torque.", partial(root_stress_figure, lt))
    if fr is not None and lt is not None:
        # the flash temperature and λ_GF on the flank: the load-capacity step's
        # /scuffing_micropitting (in /friction in a file written before issue 63)
        sm = _group(tree, "scuffing_micropitting")
        if sm is not None:
            fr = fr.assign({n: sm[n] for n in FRICTION_FLANK_PLOTS if n in sm and n not in fr})
        if any(name in fr for name in FRICTION_FLANK_PLOTS):
            yield FigureSpec(
                "friction_flank",
                "Sliding and rolling velocity, slide-to-roll ratio, lambda ratio, friction "
                "coefficient, sliding loss, flash temperature (Blok) and specific film "
                "thickness λ_GF = h_min/Ra on the gear flank at the largest torque "
                "(seed Figs. 5.5–5.10; docs/scuffing_micropitting.md).",
                partial(friction_flank_figure, eo, lt, fr))
        yield FigureSpec("friction_efficiency",
                          "Instantaneous mechanical efficiency over the mesh cycles.",
                          partial(efficiency_curve_figure, fr, lt))
    mi = _group(tree, "mesh_interface")
    if mi is not None:
        yield FigureSpec(
            "mesh_interface",
            "Mesh interface for dynamic models: effective mesh stiffness along the line of "
            "action, transmission-error excitation and its mesh harmonics, directional "
            "rotation radii (Cheng & Lim 2001).",
            partial(mesh_interface_figure, mi, lt))
    if "theoretical" in tree.children:
        yield from _deviation_specs(tree, eo, ut, lt)


def analysis_figures(tree: xr.DataTree) -> Iterator[NamedFigure]:
    """The figures of an analysis (:func:`analysis_specs`), each drawn when reached.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff`` (not an analysis file).
    """
    for spec in analysis_specs(tree):
        yield NamedFigure(spec.name, spec.caption, spec.draw())


def _render(spec: FigureSpec, dpi: int) -> RenderedFigure:
    return RenderedFigure(spec.name, spec.caption, png_bytes(spec.draw(), dpi))


def _bar(total: int, progress: bool, desc: str = "figures"):
    """A tqdm bar over the figures (None without ``progress``)."""
    if not progress:
        return None
    from tqdm.auto import tqdm

    return tqdm(total=total, desc=desc, unit="figure", leave=False)


@renamed_keywords(workers="n_workers")
def render_analysis(tree: xr.DataTree, n_workers: int = 1, dpi: int = DPI,
                    progress: bool = False) -> list[RenderedFigure]:
    """Every figure of an analysis encoded as PNG, drawn by ``n_workers`` processes.

    Parameters
    ----------
    tree : xarray.DataTree
    n_workers : int
        Processes drawing at once (≥ 1; 1 draws here; old name ``workers``, deprecated).
        The figures are independent, so on a machine with that many free cores the wall
        time falls with them.
    dpi : int
    progress : bool
        A tqdm progress bar over the figures.

    Returns
    -------
    list of RenderedFigure
        In the order of :func:`analysis_specs`.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff`` or ``n_workers`` < 1.
    """
    workers = n_workers
    if int(workers) < 1:
        raise InputError(f"n_workers: must be >= 1, got {workers!r}")
    specs = list(analysis_specs(tree))
    bar = _bar(len(specs), progress)
    try:
        if workers == 1 or len(specs) < 2:
            out = []
            for s in specs:
                out.append(_render(s, dpi))
                if bar is not None:
                    bar.update()
            return out
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed

        ctx = multiprocessing.get_context("fork" if "fork" in
                                          multiprocessing.get_all_start_methods() else None)
        with ProcessPoolExecutor(max_workers=int(workers), mp_context=ctx) as pool:
            # the costliest first, so the last figure does not run alone
            order = sorted(range(len(specs)), key=lambda i: -_COST.get(specs[i].name, 1.0))
            futures = {i: pool.submit(_render, specs[i], dpi) for i in order}
            for _ in as_completed(futures.values()):
                if bar is not None:
                    bar.update()
            return [futures[i].result() for i in range(len(specs))]
    finally:
        if bar is not None:
            bar.close()


#: relative drawing cost of the figures (benchmarks/plots.py), to start the costly first
_COST = {"friction_flank": 4.0, "contact_pattern": 2.0, "pressure": 2.0,
         "transmission_error": 2.0, "deviations_pressure": 3.0}


def _write(figures, directory: str | os.PathLike[str], prefix: str = "") -> list[Path]:
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    return [save_png(nf.figure, d / f"{prefix}{nf.name}.png") for nf in figures]


#: the most torques a figure name lists one by one (more: first-last and the count)
_TAGGED_TORQUES = 4


def torque_tag(torques) -> str:
    """``"T50-250-500"``: the torque set [N·m] in a figure's name (``"T50-500x8"`` for more
    than four torques: first, last and their number); empty for no torques."""
    t = [float(x) for x in np.atleast_1d(np.asarray(torques, dtype=float))]
    if not t:
        return ""
    if len(t) > _TAGGED_TORQUES:
        return f"T{t[0]:g}-{t[-1]:g}x{len(t)}"
    return "T" + "-".join(f"{x:g}" for x in t)


def _coast(tree: xr.DataTree) -> bool:
    """Whether an analysis ran on the flank opposite the case's drive flank (the case as
    run is the tree's ``inputs`` attribute; ``[pair] drive_flank``, concave by default)."""
    import tomllib

    pinion = None
    for group in ("ltca", "easeoff"):
        if group in tree.children:
            pinion = tree[group].attrs.get("pinion_flank")
            break
    try:
        pair = tomllib.loads(str(tree.attrs.get("inputs", ""))).get("pair", {})
    except tomllib.TOMLDecodeError:
        return False
    drive = pair.get("drive_flank", "concave") if isinstance(pair, dict) else "concave"
    return pinion is not None and pinion != drive


def figure_prefix(tree_or_ds: xr.DataTree | xr.Dataset, kind: str | None = None) -> str:
    """The start of every figure file of a result: what the figures show, so that the
    figures of several commands written into one directory (the walk-through,
    docs/walkthrough.md) never share a name with different content.

    Parameters
    ----------
    tree_or_ds : xarray.DataTree or xarray.Dataset
        An analysis tree (``ltca run``, ``ltca plot``), or a dataset with a ``case``
        attribute (an efficiency map, a UTCA).
    kind : str, optional
        What the figures are, placed after the case (``"unloaded"`` for the UTCA's).

    Returns
    -------
    str
        ``"<case>_T<torques>_"`` for a loaded analysis (:func:`torque_tag` of its
        ``/ltca`` torques; ``"<case>_T…_coast_"`` on the coast flank),
        ``"<case>_<kind>_"`` with ``kind``, ``"<case>_T<torques>_"`` for a dataset with a
        ``torque`` coordinate, ``"<case>_"`` otherwise; empty where the data name no case.
    """
    case = tree_or_ds.attrs.get("case", "")
    if not case:
        return ""
    parts = [case]
    if kind:
        parts.append(kind)
    elif isinstance(tree_or_ds, xr.DataTree) and "ltca" in tree_or_ds.children:
        parts.append(torque_tag(tree_or_ds["ltca"]["torque"].values))
        if _coast(tree_or_ds):
            parts.append("coast")
    elif "torque" in tree_or_ds.coords:
        parts.append(torque_tag(tree_or_ds["torque"].values))
    return "_".join(p for p in parts if p) + "_"


@renamed_keywords(workers="n_workers")
def plot_analysis(tree: xr.DataTree, directory: str | os.PathLike[str],
                  n_workers: int = 1, progress: bool = False) -> list[Path]:
    """Write every figure of an analysis (:func:`analysis_figures`) as PNG into ``directory``
    (created if missing), each named ``<case>_T<torques>_<figure>.png``
    (:func:`figure_prefix`), and
    return the paths; ``n_workers`` processes draw them (``progress``: a tqdm bar over the
    figures).

    Parameters
    ----------
    tree : xarray.DataTree
        An analysis (:func:`contact.run_analysis`, or its file read back).
    directory : str or os.PathLike
        Where the PNG files go (created if missing).
    n_workers : int
        Processes drawing the figures (default 1: this process; old name ``workers``,
        deprecated; Dask's and :class:`contact.study.StudyRun`'s name).
    progress : bool
        A tqdm bar over the figures.

    Returns
    -------
    list of pathlib.Path
        The files written, one per figure, each written atomically.

    Raises
    ------
    InputError
        If the tree lacks ``/easeoff``.
    """
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    out = []
    prefix = figure_prefix(tree)
    for rf in render_analysis(tree, n_workers, progress=progress):
        with atomic_path(d / f"{prefix}{rf.name}.png") as tmp:
            tmp.write_bytes(rf.png)
        out.append(d / f"{prefix}{rf.name}.png")
    return out


def plot_utca(easeoff: xr.Dataset, utca: xr.Dataset,
              directory: str | os.PathLike[str]) -> list[Path]:
    """The unloaded figures (ease-off topography and contour, pattern, UTE) into
    ``directory`` (created if missing), each named ``<case>_unloaded_<figure>.png``
    (:func:`figure_prefix`: apart from the loaded analysis's figures).

    Returns
    -------
    list of pathlib.Path
    """
    figs = [NamedFigure("easeoff_topography", "", easeoff_topography_figure(easeoff)),
            NamedFigure("easeoff", "", easeoff_contour_figure(easeoff)),
            NamedFigure("contact_pattern", "", contact_pattern_figure(easeoff, utca)),
            NamedFigure("transmission_error", "", transmission_error_figure(utca, None))]
    data = utca if utca.attrs.get("case") else easeoff
    return _write(figs, directory, figure_prefix(data, "unloaded"))


def efficiency_map_figures(emap: xr.Dataset) -> Iterator[NamedFigure]:
    """The figures of an efficiency map (:func:`contact.study.efficiency.efficiency_map`).

    Yields
    ------
    NamedFigure
        ``efficiency_map`` (contours over the first two swept inputs of speed, torque,
        temperature, roughness; a panel per value of the others) and ``power_loss_map``
        where two or more are swept, ``efficiency_vs_speed`` where speed is swept (or
        nothing is), ``efficiency_vs_roughness`` where roughness or temperature is.
    """
    from contact.plots.maps import swept_dims

    swept = swept_dims(emap)
    if len(swept) >= 2:  # a map needs two swept inputs; one is a line (below)
        axes = " × ".join(swept[:2])
        yield NamedFigure("efficiency_map", f"Efficiency over {axes}.",
                          efficiency_map_figure(emap))
        if "power_loss" in emap:
            yield NamedFigure("power_loss_map", f"Mesh power loss over {axes}.",
                              efficiency_map_figure(emap, "power_loss"))
    if emap.sizes.get("speed", 1) > 1 or not swept:
        yield NamedFigure("efficiency_vs_speed", "Efficiency against speed (seed Fig. 5.11).",
                          efficiency_speed_figure(emap))
    if emap.sizes.get("roughness", 1) > 1 or emap.sizes.get("temperature", 1) > 1:
        yield NamedFigure("efficiency_vs_roughness",
                          "Efficiency against roughness per oil temperature (seed Fig. 5.12).",
                          efficiency_roughness_figure(emap))


def plot_efficiency_map(emap: xr.Dataset, directory: str | os.PathLike[str],
                        progress: bool = False, prefix: str | None = None) -> list[Path]:
    """Write the figures of an efficiency map as PNGs into ``directory`` (created if
    missing) and return the paths (``progress``: a tqdm bar over the figures); each file
    starts with ``prefix`` (default ``"<case>_"``)."""
    figures = efficiency_map_figures(emap)
    if progress:
        from tqdm.auto import tqdm

        figures = tqdm(figures, desc="figures", unit="figure", leave=False)
    return _write(figures, directory, figure_prefix(emap) if prefix is None else prefix)
