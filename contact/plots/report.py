"""One self-contained HTML page of an analysis, drawn from its netCDF file alone.

The page holds the case and its provenance (source, synthesised fields, the case file),
the operating conditions, the summary table in the layout of the seed's Table 3.1 (LTE
mean, peak-to-peak, the first three mesh harmonics and their root-sum-square per torque
and misalignment, with the peak pressures and the efficiency), the figures of
:func:`contact.plots.analysis.analysis_figures` embedded as PNG data URIs (no network),
the solver's certification and the toolkit versions. Nothing is taken from the machine
or the clock: the same file gives the same page anywhere. Groups the file lacks are
named on the page with what they would have given. The page is rendered by Jinja2 from
the package template ``contact/templates/report.html.j2`` (autoescaped).

Public functions
----------------
report_context   the values the page shows, from a DataTree
render_report    the HTML page as text
write_report     write it atomically to a file
"""

from __future__ import annotations

import base64
import json
import os
import tomllib
from collections import Counter
from collections.abc import Iterable
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from contact.plots.analysis import RenderedFigure, analysis_figures, render_figures
from contact.plots.style import misalignment_text
from geometry import __version__
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError

__all__ = ["SUMMARY_COLUMNS", "render_report", "report_context", "write_report"]

#: columns of the summary table: (key, heading, unit, decimals)
SUMMARY_COLUMNS = (
    ("torque", "T_p", "N·m", 0),
    ("lte_mean", "LTE mean", "µrad", 1),
    ("lte_peak_to_peak", "p-p", "µrad", 1),
    ("harmonic_1", "1st", "µrad", 1),
    ("harmonic_2", "2nd", "µrad", 1),
    ("harmonic_3", "3rd", "µrad", 1),
    ("lte_harmonic_rss", "RMS*", "µrad", 1),
    ("pressure_max_flank", "p_max flank", "MPa", 0),
    ("pressure_max_edge", "p_max edge", "MPa", 0),
    ("efficiency_mean", "efficiency", "%", 2),
    ("power_loss_mean", "power loss", "W", 1),
)

#: what each optional group gives, said on the page when the file lacks it
ABSENT = {
    "utca": "unloaded TCA (UTE, unloaded pattern)",
    "ltca": "loaded TCA (LTE, pressure, load sharing, the summary table)",
    "friction": "efficiency stage (efficiency, power loss, friction on the flank): "
                "run without it (ltca run --speed 0) or written before it existed",
}


def _group(tree: xr.DataTree, path: str) -> xr.Dataset | None:
    try:
        return tree[path].to_dataset()
    except KeyError:
        return None


def _num(value: Any) -> float:
    return float(np.asarray(value, float))


def _cell(value: float, decimals: int) -> dict:
    v = _num(value)
    return {"text": f"{v:.{decimals}f}" if np.isfinite(v) else "–",
            "value": repr(v) if np.isfinite(v) else ""}


def _inputs(tree: xr.DataTree) -> tuple[dict, str]:
    text = str(tree.attrs.get("inputs", ""))
    if not text:
        eo = _group(tree, "easeoff")
        text = str(eo.attrs.get("inputs", "")) if eo is not None else ""
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError:
        return {}, text


def _summary(tree: xr.DataTree, lt: xr.Dataset, fr: xr.Dataset | None) -> list[dict]:
    errors = misalignment_text(tree.attrs) or misalignment_text(lt.attrs)
    rows = []
    for i, t in enumerate(lt["torque"].values):
        vals = {"torque": t}
        for k in ("lte_mean", "lte_peak_to_peak", "lte_harmonic_rss", "pressure_max_flank",
                  "pressure_max_edge"):
            vals[k] = lt[k].values[i] if k in lt else np.nan
        h = lt["lte_harmonics"].values[i] if "lte_harmonics" in lt else np.full(3, np.nan)
        for n in range(3):
            vals[f"harmonic_{n + 1}"] = h[n] if n < len(h) else np.nan
        vals["efficiency_mean"] = (100 * fr["efficiency_mean"].values[i]
                                   if fr is not None and "efficiency_mean" in fr else np.nan)
        vals["power_loss_mean"] = (fr["power_loss_mean"].values[i]
                                   if fr is not None and "power_loss_mean" in fr else np.nan)
        found = lt["found"].isel(torque=i).values if "found" in lt else np.array([])
        rows.append({
            "errors": errors,
            "cells": [{"key": k, **_cell(vals[k], d)} for k, _, _, d in SUMMARY_COLUMNS],
            "certified": f"{int(np.sum(found))}/{found.size}",
        })
    return rows


def _solver(lt: xr.Dataset) -> dict:
    opts = lt.attrs.get("options", "{}")
    try:
        options = json.loads(opts) if isinstance(opts, str) else {}
    except ValueError:
        options = {}
    rows = []
    for i, t in enumerate(lt["torque"].values):
        status = Counter(str(s) for s in np.ravel(lt["status"].isel(torque=i).values)) \
            if "status" in lt else Counter()
        res = {k: _num(np.nanmax(lt[f"residual_{k}"].isel(torque=i).values))
               for k in ("primal", "dual", "complementarity", "equilibrium",
                         "upper_complementarity")
               if f"residual_{k}" in lt}
        found = lt["found"].isel(torque=i).values if "found" in lt else np.array([])
        rows.append({
            "torque": f"{t:g}",
            "certified": f"{int(np.sum(found))}/{found.size}",
            "status": ", ".join(f"{k} ×{v}" for k, v in sorted(status.items())),
            "residuals": {k: f"{v:.1e}" for k, v in res.items()},
            "weber": (int(np.nanmax(lt["weber_iterations"].isel(torque=i).values))
                      if "weber_iterations" in lt else "–"),
        })
    all_found = "found" in lt and bool(np.all(lt["found"].values == 1))
    return {"name": lt.attrs.get("solver", "?"), "rows": rows, "all_certified": all_found,
            "options": options}


def _te_table(tree: xr.DataTree) -> list[dict]:
    """Rows of the theoretical/deviated TE table (seed Tables 4.2, 4.4)."""
    th_lt, th_ut = _group(tree, "theoretical/ltca"), _group(tree, "theoretical/utca")
    lt, ut = _group(tree, "ltca"), _group(tree, "utca")
    if th_lt is None or th_ut is None or lt is None or ut is None:
        return []
    rows = []
    for i, t in enumerate(lt["torque"].values):
        for name, a, u in (("theoretical", th_lt, th_ut), ("deviated", lt, ut)):
            h = a["lte_harmonics"].values[i]
            rows.append({"torque": f"{t:g}", "surfaces": name, "cells": [
                _cell(a["lte_mean"].values[i], 2), _cell(a["lte_peak_to_peak"].values[i], 2),
                _cell(h[0], 2), _cell(h[1], 2), _cell(h[2], 2),
                _cell(a["lte_harmonic_rss"].values[i], 2),
                _cell(u["peak_to_peak_transmission_error"].values, 2)]})
    return rows


def _operating(tree: xr.DataTree, lt, fr, eo) -> list[tuple[str, str]]:
    rows = []
    if lt is not None:
        rows.append(("pinion torque T_p", ", ".join(f"{t:g}" for t in lt["torque"].values)
                     + " N·m"))
        if "gear_torque" in lt.coords:
            rows.append(("gear torque", ", ".join(f"{t:.4g}" for t in lt["gear_torque"].values)
                         + " N·m (lossless)"))
    rows.append(("misalignment (ΔE, ΔP, ΔG, ΔΣ)",
                 misalignment_text(tree.attrs) or misalignment_text(eo.attrs) or "not recorded"))
    src = lt if lt is not None else eo
    if "pinion_flank" in src.attrs:
        rows.append(("flanks in contact", f"pinion {src.attrs['pinion_flank']}, gear "
                                          f"{src.attrs.get('gear_flank', '?')}"))
    if lt is not None:
        try:
            opts = json.loads(lt.attrs.get("options", "{}"))
        except ValueError:
            opts = {}
        if opts:
            rows.append(("discretisation", f"{opts.get('rolls_per_cycle', '?')} rolls per mesh "
                         f"cycle over {opts.get('cycles', '?')} cycles, {opts.get('segments', '?')}"
                         f" segments per contact line, pairs {opts.get('pairs', '?')}, "
                         f"edge contact {'on' if opts.get('edge_contact') else 'off'}"))
    if fr is not None:
        a = fr.attrs
        rows += [
            ("pinion speed", f"{_num(a.get('pinion_speed_rpm', np.nan)):g} rpm"),
            ("lubricant", f"{a.get('lubricant', '?')} at "
                          f"{_num(a.get('inlet_temperature_degC', np.nan)):g} °C inlet"),
            ("RMS roughness Rq", f"{_num(a.get('roughness_rq_um', np.nan)):g} µm"),
            ("friction model", str(a.get("friction_model", "?"))),
        ]
    if eo is not None and "deviations" in eo.attrs:
        rows.append(("surface deviations", str(eo.attrs["deviations"])))
    return rows


def report_context(tree: xr.DataTree,
                   figures: Iterable[RenderedFigure] | None = None) -> dict:
    """Everything the report shows, from the analysis tree alone.

    Parameters
    ----------
    tree : xarray.DataTree
        ``read_netcdf(file, tree=True)`` of a file written by ``ltca run`` (or the tree
        of :func:`contact.pipeline.run_analysis`).
    figures : iterable of RenderedFigure, optional
        The figures to embed, as PNG (default :func:`analysis_figures` of the tree).

    Returns
    -------
    dict
        Keys ``case``, ``provenance``, ``operating``, ``columns``, ``summary``,
        ``te_table``, ``solver``, ``absent``, ``figures``, ``warnings``, ``versions``.

    Raises
    ------
    InputError
        If the tree has no ``/easeoff`` group (not an analysis file).
    """
    eo = _group(tree, "easeoff")
    if eo is None:
        raise InputError("tree: has no /easeoff group (not a hypoid-ltca analysis file)")
    lt, fr, ut = _group(tree, "ltca"), _group(tree, "friction"), _group(tree, "utca")
    case, inputs_text = _inputs(tree)
    name = tree.attrs.get("case") or eo.attrs.get("case") or case.get("name", "unnamed case")
    present = {"utca": ut is not None, "ltca": lt is not None, "friction": fr is not None}
    absent = [{"group": f"/{g}", "gives": ABSENT[g]} for g, ok in present.items() if not ok]
    if figures is None:
        figures = render_figures(analysis_figures(tree))
    figs = [{"name": rf.name, "caption": rf.caption,
             "data": base64.b64encode(rf.png).decode("ascii")} for rf in figures]
    warnings = []
    if fr is not None and "model_range_warnings" in fr.attrs:
        try:
            warnings = list(json.loads(fr.attrs["model_range_warnings"]))
        except ValueError:
            warnings = [str(fr.attrs["model_range_warnings"])]
    return {
        "case": {"name": name,
                 "source": tree.attrs.get("case_source") or case.get("source", ""),
                 "synthesised": list(case.get("synthesised", [])),
                 "inputs": inputs_text},
        "provenance": [(k, str(tree.attrs[k])) for k in
                       ("title", "date_created", "history", "source", "Conventions",
                        "references") if k in tree.attrs],
        "operating": _operating(tree, lt, fr, eo),
        "columns": [(h, u) for _, h, u, _ in SUMMARY_COLUMNS],
        "summary": _summary(tree, lt, fr) if lt is not None else [],
        "te_table": _te_table(tree),
        "solver": _solver(lt) if lt is not None else None,
        "absent": absent,
        "figures": figs,
        "warnings": warnings,
        "versions": {"file": str(tree.attrs.get("toolkit_version", "not recorded")),
                     "report": __version__},
    }


def render_report(tree: xr.DataTree, figures: Iterable[RenderedFigure] | None = None) -> str:
    """The report of an analysis as one self-contained HTML page (figures embedded).

    Parameters
    ----------
    tree : xarray.DataTree
    figures : iterable of RenderedFigure, optional
        Figures already encoded (e.g. by ``ltca run --plots``); default drawn here.

    Returns
    -------
    str
        The HTML text (UTF-8, no external resources).
    """
    from jinja2 import Environment, select_autoescape

    template = (resources.files("contact") / "templates" / "report.html.j2").read_text(
        encoding="utf-8")
    env = Environment(autoescape=select_autoescape(default=True, default_for_string=True),
                      trim_blocks=True, lstrip_blocks=True)
    return env.from_string(template).render(**report_context(tree, figures))


def write_report(tree: xr.DataTree, path: str | os.PathLike[str],
                 figures: Iterable[RenderedFigure] | None = None) -> Path:
    """Write :func:`render_report` to ``path`` atomically (a temporary file, then a rename).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        If the directory of ``path`` does not exist.
    """
    target = Path(path)
    if not target.parent.exists():
        raise InputError(f"path: directory {str(target.parent)!r} does not exist")
    html = render_report(tree, figures)
    with atomic_path(target, mode=0o644) as tmp:
        tmp.write_text(html, encoding="utf-8")
    return target
