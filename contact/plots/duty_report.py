"""The duty-cycle report: one self-contained HTML page of a ``/duty_cycle`` result.

Drawn from the result file alone (:func:`contact.study.duty_cycle.run_duty_cycle`'s
dataset): damage, life, locations and safety factors of both members (flank and, with root
stress, fillet), the per-bin table with the cycle's energy and efficiency, and the figures
of :mod:`contact.study.duty_cycle_figures` embedded as PNG.

Public functions
----------------
duty_report_context   the values the page shows
render_duty_report    the page as HTML text
write_duty_report     the page written atomically
"""

from __future__ import annotations

import base64
import io
import math
import os
from pathlib import Path
from typing import Any

import xarray as xr

from geometry import __version__
from geometry.core.errors import InputError

__all__ = ["duty_report_context", "render_duty_report", "write_duty_report"]

#: headings of the per-bin table
BIN_COLUMNS = ("bin", "T [N·m]", "n [rpm]", "t [h]", "LTE [µrad]", "LTE p-p [µrad]",
               "p_max flank [MPa]", "p_max edge [MPa]", "edge share [%]", "efficiency [%]",
               "power loss [W]", "energy lost [kW h]")


def _fmt(x: float, spec: str) -> str:
    return "∞" if math.isinf(x) else ("—" if math.isnan(x) else format(x, spec))


def _dataset(result: xr.DataTree | xr.Dataset) -> xr.Dataset:
    if isinstance(result, xr.DataTree):
        if "duty_cycle" not in result.children:
            raise InputError("tree: has no /duty_cycle group (not an `ltca duty-cycle` "
                             "result)")
        return result["duty_cycle"].to_dataset()
    if "flank_damage" not in result:
        raise InputError("dataset: has no flank_damage (not a duty-cycle result)")
    return result


def _figures(ds: xr.Dataset) -> list[dict[str, str]]:
    from contact.study.duty_cycle_figures import (
        bins_figure,
        damage_map_figure,
        root_damage_figure,
    )

    draw = [(damage_map_figure, "cumulative flank (pitting) damage on the gear's contact "
             "grid, the first point to fail marked"),
            (bins_figure, "per bin: duration, share of the damage at the first point to "
             "fail, energy lost, efficiency")]
    if "root_damage" in ds:
        draw.append((root_damage_figure, "root (bending) damage along the fillet and the "
                     "bins' peak fillet stress"))
    out = []
    for function, caption in draw:
        fig = function(ds)
        buf = io.BytesIO()
        fig.savefig(buf, dpi=100, format="png")
        out.append({"caption": caption,
                    "data": base64.b64encode(buf.getvalue()).decode("ascii")})
    return out


def edge_note(ds: xr.Dataset) -> str | None:
    """:func:`contact.study.duty_cycle.edge_note` (the printed summary's sentence)."""
    from contact.study.duty_cycle import edge_note as note

    return note(ds)


def duty_report_context(result: xr.DataTree | xr.Dataset, *, figures: bool = True
                        ) -> dict[str, Any]:
    """The values of the duty-cycle page.

    Parameters
    ----------
    result : xarray.DataTree or xarray.Dataset
        A file written by ``ltca duty-cycle`` (its ``/duty_cycle`` group) or the dataset
        of :func:`contact.study.duty_cycle.run_duty_cycle`.
    figures : bool
        Draw and embed the figures (default True).

    Returns
    -------
    dict
        ``case``, ``duty_cycle``, ``grade``, ``miner_rule``, ``hours``, ``illustrative``,
        ``durability`` (rows per member: flank damage [1], pitting life [h] and its (u, v),
        S_H; with root stress root damage [1], bending life [h], its fillet station's u,
        S_F), ``durability_columns``, ``bins`` (rows of :data:`BIN_COLUMNS`),
        ``bin_columns``, ``cycle`` (energy in and lost [kW h], efficiency [%]),
        ``bending``, ``bending_text``, ``edge_contact``, ``figures``, ``verdict`` (the
        verdict box: :func:`contact.study.verdicts.verdict`), ``versions``.

    Raises
    ------
    InputError
        Not a duty-cycle result.
    """
    ds = _dataset(result)
    bending = "root_damage" in ds
    cols = ["flank damage [1]", "pitting life [h]", "at u [1]", "at v [1]", "S_H [1]"]
    if bending:
        cols += ["root damage [1]", "bending life [h]", "at fillet u [1]", "S_F [1]"]
    rows = []
    for k, member in enumerate(ds["member"].values):
        cells = [_fmt(float(ds["damage"][k]), ".3g"), _fmt(float(ds["life"][k]), ".4g"),
                 _fmt(float(ds["life_u"][k]), ".2f"), _fmt(float(ds["life_v"][k]), ".2f"),
                 _fmt(float(ds["contact_safety_factor"][k]), ".2f")]
        if bending:
            i = int(ds["root_life_point"][k])
            u = (float(ds["fillet_u"].values[k, i]) if "fillet_u" in ds.coords
                 else float("nan"))
            cells += [_fmt(float(ds["root_damage_max"][k]), ".3g"),
                      _fmt(float(ds["root_life"][k]), ".4g"), _fmt(u, ".2f"),
                      _fmt(float(ds["bending_safety_factor"][k]), ".2f")]
        rows.append({"member": str(member), "cells": cells})
    bins = []
    for i in range(ds.sizes["bin"]):
        v = {name: float(ds[name].values[i]) for name in (
            "torque", "speed", "hours", "lte_mean", "lte_peak_to_peak", "pressure_max_flank",
            "pressure_max_edge", "edge_load_share", "efficiency", "power_loss",
            "energy_lost")}
        bins.append([str(i), _fmt(v["torque"], "g"), _fmt(v["speed"], "g"),
                     _fmt(v["hours"], ".4g"), _fmt(v["lte_mean"], ".1f"),
                     _fmt(v["lte_peak_to_peak"], ".2f"), _fmt(v["pressure_max_flank"], ".0f"),
                     _fmt(v["pressure_max_edge"], ".0f"),
                     _fmt(100 * v["edge_load_share"], ".1f"),
                     _fmt(100 * v["efficiency"], ".3f"), _fmt(v["power_loss"], ".1f"),
                     _fmt(v["energy_lost"], ".2f")])
    return {
        "case": str(ds.attrs.get("case", "")),
        "duty_cycle": str(ds.attrs.get("duty_cycle", "duty cycle")),
        "grade": str(ds.attrs.get("grade", "")),
        "miner_rule": str(ds.attrs.get("miner_rule", "")),
        "hours": _fmt(float(ds["hours"].sum()), "g"),
        "illustrative": bool(int(ds.attrs.get("illustrative", 0))),
        "durability": rows,
        "durability_columns": cols,
        "bins": bins,
        "bin_columns": BIN_COLUMNS,
        "cycle": {"energy_in": _fmt(float(ds["cycle_energy_in"]), ".1f"),
                  "energy_lost": _fmt(float(ds["cycle_energy_lost"]), ".3f"),
                  "efficiency": _fmt(100 * float(ds["cycle_efficiency"]), ".3f")},
        "bending": bending,
        "bending_text": str(ds.attrs.get("bending", "")),
        "edge_contact": str(ds.attrs.get("edge_contact", "")),
        "edge_note": edge_note(ds) or "",
        "figures": _figures(ds) if figures else [],
        "verdict": _verdict(ds),
        "versions": {"file": str(ds.attrs.get("toolkit_version", "not recorded")),
                     "report": __version__},
    }


def _verdict(ds: xr.Dataset) -> dict[str, Any]:
    """The verdict box of the page (:func:`contact.study.verdicts.verdict` of the duty
    cycle): severity, findings, checks, notes."""
    from contact.study.verdicts import verdict

    v = verdict(ds)
    return {"severity": v.severity,
            "findings": [{"severity": f.severity, "check": f.check, "reason": f.reason}
                         for f in v.findings],
            "checks": [c.replace("_", " ") for c in v.checks],
            "notes": list(v.notes),  # what a check left out (a flank corner's curve)
            # the checks it could not make and why, as `ltca run` prints them: a page
            # that left them out read as if they had passed (issue 71, api83)
            "not_checked": [{"checks": ", ".join(c.replace("_", " ") for c in checks),
                             "why": why} for checks, why in v.not_checked()]}


def render_duty_report(result: xr.DataTree | xr.Dataset, *, figures: bool = True) -> str:
    """The duty-cycle page as one self-contained HTML text (figures embedded).

    Parameters
    ----------
    result : xarray.DataTree or xarray.Dataset
        As :func:`duty_report_context`.
    figures : bool
        Draw and embed the figures (default True).

    Returns
    -------
    str

    Raises
    ------
    InputError
        Not a duty-cycle result.
    """
    from contact.plots.report import render_page

    return render_page("duty_report.html.j2", duty_report_context(result, figures=figures))


def write_duty_report(result: xr.DataTree | xr.Dataset, path: str | os.PathLike[str]
                      ) -> Path:
    """Write :func:`render_duty_report` to ``path`` atomically.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        Not a duty-cycle result; the directory of ``path`` does not exist.
    """
    from contact.plots.report import write_page

    if not Path(path).parent.exists():  # before the figures are drawn
        raise InputError(f"path: directory {str(Path(path).parent)!r} does not exist")
    return write_page(render_duty_report(result), path)
