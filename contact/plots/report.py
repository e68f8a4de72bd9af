"""One self-contained HTML page of an analysis, drawn from its netCDF file alone.

The page holds the case and its provenance (source, synthesised fields, the case file),
the operating conditions, the summary table in the layout of the seed's Table 3.1 (LTE
mean, peak-to-peak, the first three mesh harmonics and their root-sum-square per torque
and misalignment, with the peak pressures and the efficiency), the figures of
:func:`contact.plots.analysis.analysis_figures` embedded as PNG data URIs (no network),
the scuffing and micropitting table (peak flash and contact temperature, scuffing safety,
least specific film thickness and micropitting safety per torque), the solver's
certification and the toolkit versions. It opens with the verdict
(:func:`contact.study.verdicts.verdict`: pass, attention or fail and the reasons), holds
the machine-settings sheet per member and flank (:mod:`contact.plots.machine_sheet`) and
the loaded pattern's dimensions in mm with the contact ratio per torque; its figures
enlarge on a click, its tables reflow on a narrow screen, and it prints on A4 or Letter
with each section on its own pages (plain HTML, CSS and a few lines of JavaScript, no
network). Nothing is taken from the machine
or the clock: the same file gives the same page anywhere. Groups the file lacks are
named on the page with what they would have given. The page is rendered by Jinja2 from
the package template ``contact/templates/report.html.j2`` (autoescaped).

Public functions
----------------
report_context   the values the page shows, from a DataTree
render_report    the HTML page as text
render_page      any of the toolkit's HTML templates filled (the report, the duty cycle's)
write_page       an HTML page written atomically
write_report     write it atomically to a file
"""

from __future__ import annotations

import base64
import json
import math
import os
import re
import tomllib
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from contact.ltca.summary import edge_load_share
from contact.plots.analysis import RenderedFigure, analysis_figures, render_figures
from contact.plots.machine_sheet import machine_sheet
from contact.plots.style import DPI, misalignment_text
from geometry import __version__
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError, LTCAError
from geometry.core.text import plain_number

__all__ = ["DURABILITY_COLUMNS", "SUMMARY_COLUMNS", "SummaryColumn", "render_page",
           "render_report", "report_context", "write_page", "write_report"]

@dataclass(frozen=True)
class SummaryColumn:
    """One column of the report's summary table.

    Attributes
    ----------
    key : str
        Identifier (the cell's ``data-key`` on the page).
    heading, unit : str
        Column heading and unit as shown ([µrad], [MPa] …).
    decimals : int or None
        Decimals shown; None: the number as the page's text writes it
        (:func:`geometry.core.text.plain_number`, the torque).
    value : callable
        ``value(groups, i)`` → the number at torque index ``i`` (NaN where the file lacks
        it: shown as "–"); ``groups`` maps ``"ltca"``, ``"friction"``,
        ``"mesh_interface"`` … to the file's datasets (None where absent).
    """

    key: str
    heading: str
    unit: str
    decimals: int | None
    value: Callable[[Mapping[str, xr.Dataset | None], int], float]


def _var(group: str, name: str, scale: float = 1.0, index: int | None = None):
    """A column value: ``name`` of ``group`` at the torque index (× ``scale``; element
    ``index`` of a trailing dimension such as ``harmonic``)."""
    def value(groups: Mapping[str, xr.Dataset | None], i: int) -> float:
        ds = groups.get(group)
        if ds is None or name not in ds:
            return math.nan
        v = np.asarray(ds[name].values)[i]
        if index is not None:
            v = np.ravel(v)
            return float(v[index]) * scale if index < v.size else math.nan
        return float(v) * scale
    return value


def _root_stress(member: str):
    """A column value: the peak root stress [MPa] of ``member`` at the torque index (NaN
    where the file has no root stress)."""
    def value(groups: Mapping[str, xr.Dataset | None], i: int) -> float:
        ds = groups.get("ltca")
        if ds is None or "root_stress_max" not in ds:
            return math.nan
        return float(ds["root_stress_max"].isel(torque=i).sel(member=member))
    return value


def _edge_share(groups: Mapping[str, xr.Dataset | None], i: int) -> float:
    lt = groups.get("ltca")
    if lt is None or not {"force", "moment_arm", "segment_kind"} <= set(lt.variables):
        return math.nan
    return 100.0 * float(edge_load_share(lt)[i])


#: The summary table's columns, in order: one entry per column, and a column added here
#: (e.g. the tooth-root stress of a stress stage, ``_var("stress", "root_stress_max")``)
#: appears on every report; its ``value`` returns NaN for files that lack it.
SUMMARY_COLUMNS: tuple[SummaryColumn, ...] = (
    # the torque as every other table and the verdict write it (127.1, not 127: api83)
    SummaryColumn("torque", "T_p", "N·m", None,
                  lambda g, i: float(g["ltca"]["torque"].values[i])),
    SummaryColumn("lte_mean", "LTE mean", "µrad", 1, _var("ltca", "lte_mean")),
    SummaryColumn("lte_peak_to_peak", "p-p", "µrad", 1, _var("ltca", "lte_peak_to_peak")),
    SummaryColumn("harmonic_1", "1st", "µrad", 1, _var("ltca", "lte_harmonics", index=0)),
    SummaryColumn("harmonic_2", "2nd", "µrad", 1, _var("ltca", "lte_harmonics", index=1)),
    SummaryColumn("harmonic_3", "3rd", "µrad", 1, _var("ltca", "lte_harmonics", index=2)),
    SummaryColumn("lte_harmonic_rss", "RMS*", "µrad", 1, _var("ltca", "lte_harmonic_rss")),
    SummaryColumn("pressure_max_flank", "p_max flank", "MPa", 0,
                  _var("ltca", "pressure_max_flank")),
    SummaryColumn("pressure_max_edge", "p_max edge", "MPa", 0,
                  _var("ltca", "pressure_max_edge")),
    SummaryColumn("edge_load_share", "edge share", "%", 1, _edge_share),
    SummaryColumn("root_stress_max_pinion", "σ_F pinion", "MPa", 0, _root_stress("pinion")),
    SummaryColumn("root_stress_max_gear", "σ_F gear", "MPa", 0, _root_stress("gear")),
    SummaryColumn("mesh_stiffness_mean", "mesh stiffness", "N/µm", 0,
                  _var("mesh_interface", "mesh_stiffness_mean")),
    SummaryColumn("efficiency_mean", "efficiency", "%", 2,
                  _var("friction", "efficiency_mean", 100.0)),
    SummaryColumn("power_loss_mean", "power loss", "W", 1, _var("friction", "power_loss_mean")),
)


def _standard(name: str, variant: str = "standard"):
    """A column value: ``name`` of the standard's flash temperature method
    (``/rating/flash_temperature``), its ``variant`` (``standard`` or
    ``lengthwise_sliding``), at the torque of the scuffing table's index (NaN where the
    file has no such group or variant, or the method did not run at that torque; a file
    written before the variants has the lengthwise one alone)."""
    def value(groups: Mapping[str, xr.Dataset | None], i: int) -> float:
        ds, fr = groups.get("standard_scuffing"), groups.get("scuffing_micropitting")
        if ds is None or fr is None or name not in ds:
            return math.nan
        if "variant" in ds.dims:
            if variant not in ds["variant"].values:
                return math.nan
            ds = ds.sel(variant=variant)
        elif variant != "lengthwise_sliding":
            return math.nan
        match = np.flatnonzero(ds["torque"].values == fr["torque"].values[i])
        return float(ds[name].values[match[0]]) if match.size else math.nan
    return value


#: The scuffing and micropitting table's columns after T_p: /scuffing_micropitting
#: variables over torque (docs/scuffing_micropitting.md; /friction in files written before
#: issue 63), then the standard's flash temperature method on the rating's virtual
#: cylindrical gears (/rating/flash_temperature); a file that lacks one shows "–".
DURABILITY_COLUMNS: tuple[SummaryColumn, ...] = (
    SummaryColumn("flash_temperature_max", "peak flash temperature θ_fl", "K", 0,
                  _var("scuffing_micropitting", "flash_temperature_max")),
    SummaryColumn("bulk_temperature", "bulk temperature θ_M", "°C", 0,
                  _var("scuffing_micropitting", "bulk_temperature")),
    SummaryColumn("contact_temperature_max", "peak contact temperature θ_B", "°C", 0,
                  _var("scuffing_micropitting", "contact_temperature_max")),
    SummaryColumn("scuffing_safety", "scuffing safety S_B", "1", 2,
                  _var("scuffing_micropitting", "scuffing_safety")),
    SummaryColumn("specific_film_thickness_min", "least λ_GF (film at θ_M)", "1", 3,
                  _var("scuffing_micropitting", "specific_film_thickness_min")),
    SummaryColumn("micropitting_safety", "micropitting safety S_λ", "1", 2,
                  _var("scuffing_micropitting", "micropitting_safety")),
    SummaryColumn("iso_contact_temperature_max", "ISO/TS 6336-20, virtual gears: peak θ_B",
                  "°C", 0, _standard("contact_temperature_max")),
    SummaryColumn("iso_scuffing_safety", "ISO/TS 6336-20, virtual gears: S_B", "1", 2,
                  _standard("scuffing_safety")),
    SummaryColumn("iso_lengthwise_contact_temperature_max",
                  "with lengthwise sliding (not a standard): peak θ_B", "°C", 0,
                  _standard("contact_temperature_max", "lengthwise_sliding")),
    SummaryColumn("iso_lengthwise_scuffing_safety",
                  "with lengthwise sliding (not a standard): S_B", "1", 2,
                  _standard("scuffing_safety", "lengthwise_sliding")),
)

#: how the page names the variants of the standard's method in the spread of S_B
_VARIANT_NAMES = {"standard": "ISO/TS 6336-20 on the virtual gears",
                  "lengthwise_sliding": "with lengthwise sliding"}


def _scuffing_spread(standard: xr.Dataset | None) -> list[str]:
    """Per variant the spread of the standard's S_B over its uncertain constants
    (``scuffing_safety_low``/``_high``), one line each; [] where the file has none."""
    if standard is None or "scuffing_safety_low" not in standard:
        return []
    out = []
    for v in standard["variant"].values:
        one = standard.sel(variant=v)
        cells = ", ".join(
            f"{plain_number(t)} N·m {_num(one['scuffing_safety_low'].values[i]):.2f}–"
            f"{_num(one['scuffing_safety_high'].values[i]):.2f}"
            for i, t in enumerate(standard["torque"].values))
        out.append(f"{_VARIANT_NAMES.get(str(v), str(v))}: S_B {cells}")
    return out

#: what each optional group gives, said on the page when the file lacks it
ABSENT = {
    "utca": "unloaded TCA (UTE, unloaded pattern)",
    "ltca": "loaded TCA (LTE, pressure, load sharing, the summary table)",
    "friction": "efficiency stage (efficiency, power loss, friction on the flank): "
                "run without it (ltca run --speed 0) or written before it existed",
    "rating": "ISO 10300 Method B1 rating beside the LTCA (σ_H, σ_F, safety factors): "
              "the case has no [design] or [rating] table, the run had --no-rating or no "
              "speed, or the file was written before it existed (docs/rating.md)",
}


def _group(tree: xr.DataTree, path: str) -> xr.Dataset | None:
    try:
        return tree[path].to_dataset()
    except KeyError:
        return None


def _num(value: Any) -> float:
    return float(np.asarray(value, float))


def _cell(value: float, decimals: int | None) -> dict:
    v = _num(value)
    text = plain_number(v) if decimals is None else f"{v:.{decimals}f}"
    return {"text": text if np.isfinite(v) else "–",
            "value": repr(v) if np.isfinite(v) else ""}


#: how the page labels the file's provenance attributes: the file's ``references`` cite
#: the toolkit's method (Kolivand 2009), not the design, whose source is the case's own
_PROVENANCE_LABELS = {"source": "written by", "references": "method (the toolkit's references)"}


def _provenance(tree: xr.DataTree, case_source: str) -> list[tuple[str, str]]:
    """The page's provenance rows: the design's source first (the case's ``source`` up to
    its first sentence's end, e.g. the user's basic file of a synthesised case), then the
    file's attributes, the method references labelled as the toolkit's."""
    text = str(case_source).strip()
    first = re.split(r"(?<=\.)\s+(?=[A-Z][a-z])", text, maxsplit=1)[0] if text else ""
    rows = [("design source", first or "not recorded in the file")]
    rows += [(_PROVENANCE_LABELS.get(k, k), str(tree.attrs[k])) for k in
             ("title", "date_created", "history", "source", "Conventions", "references")
             if k in tree.attrs]
    return rows


def _inputs(tree: xr.DataTree) -> tuple[dict, str]:
    text = str(tree.attrs.get("inputs", ""))
    if not text:
        eo = _group(tree, "easeoff")
        text = str(eo.attrs.get("inputs", "")) if eo is not None else ""
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError:
        return {}, text


def _summary(tree: xr.DataTree, lt: xr.Dataset) -> list[dict]:
    groups = {g: _group(tree, g) for g in ("ltca", "friction", "mesh_interface", "utca")}
    groups["ltca"] = lt
    rows = []
    for i in range(lt.sizes["torque"]):
        found = lt["found"].isel(torque=i).values if "found" in lt else np.array([])
        rows.append({
            "cells": [{"key": c.key, **_cell(c.value(groups, i), c.decimals)}
                      for c in SUMMARY_COLUMNS],
            "certified": f"{int(np.sum(found))}/{found.size}",
        })
    return rows


def _lte_between(lt: xr.Dataset | None) -> list[dict]:
    """The LTE p-p [µrad] the ``lte_range`` step analysed between the run's torques (the
    contact alone, ``/ltca/lte_range_peak_to_peak`` where ``lte_range_source`` is 1), each
    with its torque [N·m] — what ``ltca run`` prints under its table and the verdict's
    ``lte`` check judges beside the table's; empty where the file has none.

    Round 23 (issue 71): the 13x39's report showed 18.7 / 48.5 µrad at its two torques and
    not the 51.6 µrad at 368.6 N·m between them, its largest LTE, which ``ltca run``
    printed.
    """
    if lt is None or "lte_range_source" not in lt or "lte_range_peak_to_peak" not in lt:
        return []
    alone = np.asarray(lt["lte_range_source"].values) == 1
    torque = np.asarray(lt["lte_torque"].values, float)[alone]
    value = np.asarray(lt["lte_range_peak_to_peak"].values, float)[alone]
    # the torque as `ltca run`'s line writes it (plain_number)
    return [{"torque": float(t), "value": float(v), "text": _cell(float(v), 1)["text"],
             "torque_text": plain_number(float(t))}
            for t, v in zip(torque, value, strict=True)]


def _durability(lt: xr.Dataset | None, fr: xr.Dataset | None,
                standard: xr.Dataset | None = None) -> dict | None:
    """The scuffing and micropitting table (:data:`DURABILITY_COLUMNS` per torque; the
    standard's method from ``standard``, ``/rating/flash_temperature``), the oil's scuffing
    temperature and permissible λ_GF, and why a safety is missing; ``fr`` the
    ``/scuffing_micropitting`` group (``/friction`` in a file written before issue 63);
    None where the file has neither with the variables."""
    if lt is None or fr is None or "contact_temperature_max" not in fr:
        return None
    groups = {"ltca": lt, "scuffing_micropitting": fr, "standard_scuffing": standard}
    rows = [{"torque": plain_number(t),
             "cells": [{"key": c.key, **_cell(c.value(groups, i), c.decimals)}
                       for c in DURABILITY_COLUMNS]}
            for i, t in enumerate(fr["torque"].values)]
    theta_s = _num(fr["scuffing_temperature"].values)
    perm = _num(fr["permissible_specific_film"].values)
    oil = (f"oil {fr.attrs.get('lubricant', '?')}: scuffing temperature θ_S "
           + (f"{theta_s:.0f} °C (FZG load stage {_num(fr.attrs.get('fzg_load_stage')):g}, "
              f"{fr.attrs.get('base_oil', '')} base oil)" if np.isfinite(theta_s)
              else "unknown")
           + ", permissible λ_GFP " + (f"{perm:g}" if np.isfinite(perm) else "unknown"))
    notes = [f"{name.replace('_', ' ')}: {fr[name].attrs['comment']}"
             for name in ("scuffing_safety", "micropitting_safety")
             if str(fr[name].attrs.get("comment", "")).startswith("NaN")]
    return {"columns": [(c.heading, c.unit) for c in DURABILITY_COLUMNS], "rows": rows,
            "oil": oil, "notes": notes, "spread": _scuffing_spread(standard),
            "source": str(fr.attrs.get("durability_source", ""))}


def _scuffing_micropitting(tree: xr.DataTree, fr: xr.Dataset | None) -> xr.Dataset | None:
    """The scuffing and micropitting dataset: ``/scuffing_micropitting`` (the load-capacity
    step's), else ``fr`` (``/friction``, which held the variables before issue 63)."""
    sm = _group(tree, "scuffing_micropitting")
    return fr if sm is None else sm


def _rating(tree: xr.DataTree, lt: xr.Dataset | None) -> dict | None:
    """The table "Standard rating beside the LTCA", from the load-capacity methods' result
    contract (:mod:`contact.load_capacity.contract`): per torque and member the standard's
    contact stress beside the LTCA's peak flank pressure, its root stress beside the FE
    peak root stress (where the method gives the stresses), with their ratios, and the
    safeties against pitting and bending; None where the file has no ``/rating``, and a
    table of none but the reason (``missing``) where its ``/rating`` lacks the contract."""
    ra = _group(tree, "rating")
    if ra is None or lt is None:
        return None
    from contact.load_capacity.contract import safeties

    method = str(ra.attrs.get("rating_method", ""))
    ds, lacks = safeties(ra)
    if ds is None:
        return {"rows": [], "headers": [], "missing": f"not checked: {lacks}",
                "method": method, "root_stress": False, "ratios": []}
    stresses = {"contact_stress", "root_stress"} <= set(ds.data_vars)
    sym = {v: str(ds[v].attrs.get("symbol", "")) for v in ds.data_vars}
    names = ds["member_label"].values if "member_label" in ds.coords else ds["member"].values
    torques = np.asarray(lt["torque"].values, float) if "torque" in lt.coords else np.array([])

    def at(name: str, t: float, j: int) -> float:
        hit = np.flatnonzero(np.isclose(torques, t, rtol=1e-9, atol=0.0))
        if name not in lt or hit.size == 0:
            return float("nan")
        x = lt[name].isel(torque=int(hit[0]))
        return float((x.isel(member=j) if "member" in x.dims else x).values)

    rows = []
    for i, t in enumerate(ds["torque"].values):
        for j, member in enumerate(names):
            cells = []
            if stresses:
                c = float(ds["contact_stress"].transpose("torque", "member").values[i, j])
                r = float(ds["root_stress"].transpose("torque", "member").values[i, j])
                p, fe = at("pressure_max_flank", float(t), j), at("root_stress_max", float(t), j)
                cells += [{"key": k, **_cell(v, d)} for k, v, d in (
                    ("contact_stress", c, 0), ("pressure_max_flank", p, 0),
                    ("pressure_to_contact_stress", p / c, 2), ("root_stress", r, 0),
                    ("root_stress_max", fe, 0), ("root_stress_to_root_stress", fe / r, 2))]
            cells += [{"key": k, **_cell(ds[k].transpose("torque", "member").values[i, j], 2)}
                      for k in ("pitting_safety", "bending_safety")]
            rows.append({"torque": plain_number(t), "member": str(member), "cells": cells})
    standard = str(ds.attrs.get("rating_standard") or method)
    headers = ["T_p [N·m]", "member"]
    if stresses:
        ch, rh = sym["contact_stress"] or "contact stress", sym["root_stress"] or "root stress"
        headers += [f"{standard} {ch} [MPa]", "LTCA peak flank pressure [MPa]",
                    f"pressure / {ch}", f"{standard} {rh} [MPa]",
                    "FE peak root stress [MPa]", f"root stress / {rh}"]
    headers += [f"{standard} {sym['pitting_safety'] or 'pitting safety'}",
                f"{standard} {sym['bending_safety'] or 'bending safety'}"]
    mins = ", ".join(
        f"{sym[v] or v} " + " / ".join(f"{x:g}" for x in np.unique(np.asarray(ds[v].values,
                                                                             float)))
        for v in ("pitting_safety_min", "bending_safety_min"))
    title = str(ds.attrs.get("rating_method_title") or ds.attrs.get("method") or standard)
    side = f", {ds.attrs['side']} side" if ds.attrs.get("side") else ""
    speed = (f", n1 {_num(ds['pinion_speed'].values):g} rpm" if "pinion_speed" in ds
             and np.ndim(ds["pinion_speed"].values) == 0 else "")
    return {"rows": rows, "headers": [page_units(h).replace("sigma_", "σ_") for h in headers],
            "missing": "",
            "method": f"{title} (method {method}){side}{speed}; minima {mins}",
            "root_stress": "root_stress_max" in lt,
            "ratios": ([page_units(r).replace("sigma_", "σ_") for r in (
                f"pressure / {ch}: the LTCA's peak Hertzian pressure on the flank over the "
                "standard's contact stress with its load factors",
                f"root stress / {rh}: the FE peak maximum principal tooth-root stress over "
                "the standard's root stress with its load factors")] if stresses else [])}


def _basic_data(inputs_text: str) -> dict | None:
    """The pair's basic data (:func:`contact.plots.basic_data.basic_data_rows`) of the
    case as run, or None where the file's case does not load."""
    from contact.plots.basic_data import basic_data_rows
    from geometry.case import case_from_dict

    try:
        case = case_from_dict(tomllib.loads(inputs_text))
    except (LTCAError, tomllib.TOMLDecodeError, TypeError, KeyError, ValueError):
        return None
    return basic_data_rows(case)


#: "urad" (UDUNITS, as files and the console write it) → "µrad" on the page: one spelling
_URAD = re.compile(r"(?<![A-Za-z])urad\b")
_UM = re.compile(r"(?<=[\d\s(])um\b")
#: "N m" after a number (the console's torque) → "N·m", as the page's headings write it
_NM = re.compile(r"(?<=\d) N m\b")


def page_units(text: str) -> str:
    """ASCII unit spellings of files and the console as the page writes them: ``urad`` →
    ``µrad``, ``um`` after a number → ``µm``, ``N m`` after a number → ``N·m``."""
    return _NM.sub(" N·m", _UM.sub("µm", _URAD.sub("µrad", str(text))))


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
            "torque": plain_number(t),
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
            rows.append({"torque": plain_number(t), "surfaces": name, "cells": [
                _cell(a["lte_mean"].values[i], 2), _cell(a["lte_peak_to_peak"].values[i], 2),
                _cell(h[0], 2), _cell(h[1], 2), _cell(h[2], 2),
                _cell(a["lte_harmonic_rss"].values[i], 2),
                _cell(u["peak_to_peak_transmission_error"].values, 2)]})
    return rows


def _operating(tree: xr.DataTree, lt, fr, eo) -> list[tuple[str, str]]:
    rows = []
    if lt is not None:
        # four significant digits, never an exponent: an industrial pair's 15660 N·m
        # read "1.566e+04" beside the pinion's 10440 (issue 71, round 19)
        rows.append(("pinion torque T_p", ", ".join(plain_number(t) for t in lt["torque"].values)
                     + " N·m"))
        if "gear_torque" in lt.coords:
            rows.append(("gear torque", ", ".join(
                plain_number(t) for t in lt["gear_torque"].values) + " N·m (lossless)"))
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


def _verdict(tree: xr.DataTree) -> dict:
    """The verdict box: severity, findings (severity, check, reason), the checks run and
    the notes (:func:`contact.study.verdicts.verdict`)."""
    from contact.study.verdicts import verdict

    v = verdict(tree)
    return {"severity": v.severity,
            "findings": [{"severity": f.severity, "check": f.check, "reason": f.reason}
                         for f in v.findings],
            "checks": [c.replace("_", " ") for c in v.checks],
            "notes": list(v.notes),  # what a check left out (a flank corner's curve)
            # the checks it could not make and why, as `ltca run` prints them: a page
            # that left them out read as if they had passed (issue 71, api83)
            "not_checked": [{"checks": ", ".join(c.replace("_", " ") for c in checks),
                             "why": why} for checks, why in v.not_checked()]}


def _pattern(lt: xr.Dataset | None, inputs_text: str) -> list[dict] | None:
    """Per torque: the loaded pattern's centre and extent on the gear flank in mm
    (:func:`contact.study.summary.pattern_dimensions`) and the contact ratio, the mean
    number of tooth pairs carrying load over the mesh cycles (``pairs_in_contact``; its
    least and largest); None where the file lacks ``/ltca`` or its case does not load."""
    if lt is None or "pressure_envelope" not in lt:
        return None
    from contact.study.summary import pattern_dimensions
    from geometry.case import case_from_dict

    try:
        case = case_from_dict(tomllib.loads(inputs_text))
    except (LTCAError, tomllib.TOMLDecodeError, TypeError, KeyError, ValueError):
        return None
    dims = pattern_dimensions(lt, case)
    pairs = (np.asarray(lt["pairs_in_contact"].values, float) if "pairs_in_contact" in lt
             else np.full((lt.sizes["torque"], 1), np.nan))
    rows = []
    for i, t in enumerate(lt["torque"].values):
        cells = [_cell(dims[k][i], d) for k, d in (
            ("pattern_length", 1), ("pattern_height", 1), ("pattern_centre_lengthwise", 1),
            ("pattern_centre_profile", 1), ("pattern_toe_u", 2), ("pattern_heel_u", 2),
            ("pattern_root_v", 2), ("pattern_tip_v", 2))]
        p = pairs[i][np.isfinite(pairs[i])]
        cells += [_cell(p.mean() if p.size else np.nan, 2),
                  {"text": f"{p.min():.0f}–{p.max():.0f}" if p.size else "–",
                   "value": ""}]
        rows.append({"torque": plain_number(t), "cells": cells})
    return rows


def _png_size(png: bytes) -> tuple[int, int]:
    """(width, height) [px] of a PNG from its IHDR chunk (0, 0 if it is none)."""
    if png[:8] != b"\x89PNG\r\n\x1a\n" or len(png) < 24:
        return 0, 0
    return int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")


#: [in] a figure wider than this spans the page's whole width (a multi-panel figure,
#: whose panels would be too small in one of the grid's columns)
WIDE_FIGURE = 7.5


def _figure(rf: RenderedFigure, dpi: int = DPI) -> dict:
    """A figure as the page embeds it: name, caption, base64 PNG, its size in CSS pixels
    (96 per inch: the figure's own size, drawn at ``dpi``) and whether it spans the page."""
    w, h = _png_size(rf.png)
    return {"name": rf.name, "caption": rf.caption,
            "data": base64.b64encode(rf.png).decode("ascii"),
            "width": round(w * 96 / dpi), "height": round(h * 96 / dpi),
            "wide": w / dpi > WIDE_FIGURE}


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
        Keys ``verdict`` (:func:`contact.study.verdicts.verdict`: ``severity``,
        ``findings``, ``checks``), ``case``, ``basic_data``
        (:func:`contact.plots.basic_data.basic_data_rows`), ``machine_sheet``
        (:func:`contact.plots.machine_sheet.machine_sheet`), ``pattern`` (per torque the
        loaded pattern in mm and the contact ratio; None without ``/ltca``), ``figures``
        (each with its size in CSS pixels and ``wide``),
        ``provenance``, ``operating``, ``misalignment``, ``columns`` and ``summary`` (the
        table of :data:`SUMMARY_COLUMNS`), ``lte_between`` (the LTE p-p between the
        run's torques, :func:`_lte_between`), ``te_table``, ``solver``, ``absent``,
        ``durability`` (the scuffing and micropitting table, None for a file without
        it), ``rating`` (the ISO 10300 rating beside the LTCA, None for a file without
        ``/rating``), ``figures``, ``warnings`` (the efficiency stage's model-range warnings),
        ``plausibility`` (:func:`contact.ltca.plausibility.plausibility_warnings`: the
        causes for which the loaded contact should not be trusted), ``versions``.

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
    present = {"utca": ut is not None, "ltca": lt is not None, "friction": fr is not None,
               "rating": "rating" in tree.children}
    absent = [{"group": f"/{g}", "gives": ABSENT[g]} for g, ok in present.items() if not ok]
    if figures is None:
        figures = render_figures(analysis_figures(tree))
    figs = [_figure(rf) for rf in figures]
    warnings = []
    if fr is not None and "model_range_warnings" in fr.attrs:
        try:
            warnings = list(json.loads(fr.attrs["model_range_warnings"]))
        except ValueError:
            warnings = [str(fr.attrs["model_range_warnings"])]
    plausibility = []
    if lt is not None:
        from contact.ltca.plausibility import plausibility_warnings

        plausibility = plausibility_warnings(lt, edge_free_spread=False)
    return {
        "case": {"name": name,
                 "source": tree.attrs.get("case_source") or case.get("source", ""),
                 "synthesised": list(case.get("synthesised", [])),
                 "inputs": inputs_text},
        "provenance": _provenance(tree, tree.attrs.get("case_source")
                                  or case.get("source", "")),
        "operating": _operating(tree, lt, fr, eo),
        "columns": [(c.heading, c.unit) for c in SUMMARY_COLUMNS],
        "summary": _summary(tree, lt) if lt is not None else [],
        "lte_between": _lte_between(lt),
        "misalignment": (misalignment_text(tree.attrs) or misalignment_text(eo.attrs)
                         or "not recorded"),
        "basic_data": _basic_data(inputs_text),
        "machine_sheet": machine_sheet(case),
        "pattern": _pattern(lt, inputs_text),
        "verdict": _verdict(tree),
        "te_table": _te_table(tree),
        "durability": _durability(lt, _scuffing_micropitting(tree, fr),
                                  _group(tree, "rating/flash_temperature")),
        "rating": _rating(tree, lt),
        "solver": _solver(lt) if lt is not None else None,
        "absent": absent,
        "figures": figs,
        "warnings": warnings,
        "plausibility": plausibility,
        "versions": {"file": str(tree.attrs.get("toolkit_version", "not recorded")),
                     "report": __version__},
    }


def render_page(template: str, context: Mapping[str, Any]) -> str:
    """One of the toolkit's HTML templates (``contact/templates/``) filled with a context.

    Parameters
    ----------
    template : str
        The template's file name, e.g. ``"report.html.j2"``.
    context : mapping
        The template's values.

    Returns
    -------
    str
        The HTML text (autoescaped; the ``units`` filter is :func:`page_units`).
    """
    from jinja2 import Environment, select_autoescape

    text = (resources.files("contact") / "templates" / template).read_text(encoding="utf-8")
    env = Environment(autoescape=select_autoescape(default=True, default_for_string=True),
                      trim_blocks=True, lstrip_blocks=True)
    env.filters["units"] = page_units
    return env.from_string(text).render(**context)


def write_page(html: str, path: str | os.PathLike[str]) -> Path:
    """Write an HTML page to ``path`` atomically (a temporary file, then a rename).

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
    with atomic_path(target, mode=0o644) as tmp:
        tmp.write_text(html, encoding="utf-8")
    return target


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

    Raises
    ------
    InputError
        ``tree`` is no analysis (not a DataTree, no ``/ltca``) or its ``/ltca`` lacks a
        variable the report reads (named: a tree cut down or made by other means than
        :func:`contact.run_analysis`).
    """
    _check_analysis_tree(tree)
    try:
        return render_page("report.html.j2", report_context(tree, figures))
    except KeyError as exc:  # a variable deeper in the page that the tree lacks
        name = exc.args[0] if exc.args else exc
        raise InputError(f"tree: lacks {name} that the report reads (an analysis as "
                         "contact.run_analysis or ltca run writes it)") from None


#: the /ltca variables every report reads (its summary table and first figures)
REPORT_LTCA_VARIABLES = ("force", "found", "transmission_error", "lte_mean",
                         "lte_peak_to_peak", "pressure_max_flank", "pressure_max_edge")


def _check_analysis_tree(tree) -> None:
    """Refuse what is no analysis tree, before any figure is drawn: not a DataTree, no
    ``/ltca`` group, or an ``/ltca`` without :data:`REPORT_LTCA_VARIABLES`."""
    if not isinstance(tree, xr.DataTree):
        raise InputError("tree: must be the xarray.DataTree of an analysis "
                         f"(contact.run_analysis, or an ltca run file read with "
                         f"geometry.core.io.read_netcdf(path, tree=True)), got "
                         f"{type(tree).__name__}")
    if "ltca" not in tree.children:
        raise InputError("tree: has no /ltca group (groups: "
                         f"{', '.join(tree.children) or 'none'}); the report is of an "
                         "analysis, the /easeoff, /utca, /ltca … groups contact.run_analysis "
                         "or ltca run write")
    missing = [v for v in REPORT_LTCA_VARIABLES if v not in tree["ltca"].variables]
    if missing:
        raise InputError(f"tree: /ltca lacks {', '.join(missing)}, which the report reads "
                         "(an analysis as contact.run_analysis or ltca run writes it)")


def write_report(tree: xr.DataTree, path: str | os.PathLike[str],
                 figures: Iterable[RenderedFigure] | None = None) -> Path:
    """Write :func:`render_report` to ``path`` atomically (a temporary file, then a rename).

    Parameters
    ----------
    tree : xarray.DataTree
        An analysis (:func:`contact.run_analysis`, or its file read back).
    path : str or os.PathLike
        The HTML file; its directory must exist.
    figures : iterable of RenderedFigure, optional
        Figures already encoded (e.g. by ``ltca run --plots``); default drawn here.

    Returns
    -------
    pathlib.Path
        The page written: self-contained HTML (figures embedded, no external resources).

    Raises
    ------
    InputError
        If the directory of ``path`` does not exist, or ``tree`` is no analysis
        (:func:`render_report`), both before the figures are drawn.
    """
    _check_analysis_tree(tree)
    if not Path(path).parent.exists():  # before the figures are drawn
        raise InputError(f"path: directory {str(Path(path).parent)!r} does not exist")
    return write_page(render_report(tree, figures), path)
