"""ISO 10300 Method B1 as a method of the load-capacity registry (``"iso10300"``).

:func:`rate` is the registry's protocol (:class:`contact.load_capacity.methods.RatingMethod`)
around :func:`contact.load_capacity.iso10300.rating.iso10300_rating`: the case's ``[design]``
and ``[rating]`` tables, the pinion torques and speed, and the flank the analysis loads
(which sets the rated side where the ``[rating]`` table does not).
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import xarray as xr

from contact.load_capacity.contract import contract_variables
from contact.load_capacity.iso10300.inputs import RatingInputs
from contact.load_capacity.iso10300.rating import iso10300_rating
from geometry.core.errors import InputError
from geometry.core.text import plain_number

__all__ = ["missing_tables", "rate", "rated_side", "tables"]


def rated_side(case, flank: str | None) -> str | None:
    """The ISO 23509 side (``"drive"`` or ``"coast"``) a loaded pinion flank is rated on.

    Parameters
    ----------
    case : geometry.case.Case
    flank : {"concave", "convex", "drive", "coast"} or None
        The pinion flank, by name or as the case's drive or coast flank.

    Returns
    -------
    str or None
        ``"drive"`` when the pinion's concave flank drives (ISO 23509's drive side),
        ``"coast"`` otherwise; None for ``flank`` None (the ``[rating]`` table's own side).
    """
    if flank is None:
        return None
    drive = case.pair.drive_flank
    pinion_flank = {"drive": drive,
                    "coast": "convex" if drive == "concave" else "concave"}.get(flank, flank)
    return "drive" if pinion_flank == "concave" else "coast"


def missing_tables(case) -> str:
    """Why ISO 10300 Method B1 cannot rate ``case`` although nothing in it is wrong, or
    ``""``: it has no ``[design]`` table (the ISO 23509 basic data the virtual cylindrical
    gears are computed from) or no ``[rating]`` table (application factor, mounting, pitch
    deviation; docs/rating.md).

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    str
        One line naming the absent table, or ``""``.

    Notes
    -----
    ISO 10300-1:2014 cl. 4 (the data the method needs).
    """
    if not isinstance(case.extra.get("design"), Mapping):
        return ("ISO 10300 rating not computed: the case has no [design] table (its "
                "ISO 23509 basic design data, docs/rating.md)")
    if case.extra.get("rating") is None:
        return ("ISO 10300 rating not computed: the case has no [rating] table "
                "(application factor, mounting, pitch deviation; docs/rating.md)")
    return ""


def rate(case, torque: np.ndarray, speed: float, *, flank: str | None = None,
         datasets: Mapping[str, xr.Dataset] | None = None,
         rating: RatingInputs | Mapping[str, Any] | None = None) -> xr.Dataset:
    """The ISO 10300-1/-2/-3:2014 Method B1 ``/rating`` dataset of a case (the registry's
    ``"iso10300"`` method).

    Parameters
    ----------
    case : geometry.case.Case
        With a ``[design]`` table (ISO 23509 basic data) and a ``[rating]`` table
        (docs/rating.md).
    torque : numpy.ndarray, shape (n,) — [N·m]
        Pinion torques.
    speed : float — [rpm]
        Pinion speed (> 0).
    flank : {"concave", "convex", "drive", "coast"}, optional
        The pinion flank the analysis loads; sets the rated side where the rating inputs
        leave it open (:func:`rated_side`). Default: the inputs' side (the drive side).
    datasets : mapping of str to xarray.Dataset, optional
        The analysis' groups; unused (Method B1 rates the nominal geometry of the virtual
        cylindrical gears, not the loaded contact).
    rating : RatingInputs or mapping, optional
        Replaces the case's ``[rating]`` table.

    Returns
    -------
    xarray.Dataset
        :func:`contact.load_capacity.iso10300.rating.iso10300_rating`'s dataset with the
        result contract (:mod:`contact.load_capacity.contract`: ``pitting_safety`` = S_H,
        ``bending_safety`` = S_F, their minima S_Hmin, S_Fmin, ``contact_stress`` σ_H,
        ``root_stress`` σ_F).

    Raises
    ------
    InputError
        No ``[rating]`` table (and no ``rating``), or a bad table, torque or speed (named).

    Notes
    -----
    ISO 10300-1/-2/-3:2014 Method B1; checked against ISO/TR 10300-30:2024 samples 1–3.
    """
    table = case.extra.get("rating") if rating is None else rating
    if table is None:
        raise InputError("rating: the case has no [rating] table (application factor, "
                         "mounting, pitch deviation; docs/rating.md), and none was given")
    side = rated_side(case, flank)
    if side is not None:
        inputs = table if isinstance(table, RatingInputs) else RatingInputs.from_mapping(table)
        if inputs.side is None:
            table = (dataclasses.replace(table, side=side) if isinstance(table, RatingInputs)
                     else {**table, "side": side})
    return contract_variables(iso10300_rating(case, torque, speed, rating=table),
                              pitting=("S_H", "S_Hmin", "S_H", "S_Hmin"),
                              bending=("S_F", "S_Fmin", "S_F", "S_Fmin"),
                              stresses=("sigma_H", "sigma_F"), life=("Z_NT", "Y_NT"))


#: (variable, label, digits) of the rows of each table; a variable without the member
#: dimension is shown once, in the column of the pair
_GEOMETRY = (("d_v", "d_v [mm]", 3), ("z_v", "z_v", 3), ("z_vn", "z_vn", 3),
             ("d_van", "d_van [mm]", 3), ("g_va", "g_va [mm]", 3), ("eps_va", "eps_va", 3),
             ("eps_vb", "eps_vb", 3), ("eps_vg", "eps_vg", 3), ("b_veff", "b_v,eff [mm]", 3),
             ("l_bm", "l_bm [mm]", 3), ("rho_rel", "rho_rel [mm]", 3))
#: every factor of the stresses and permissible stresses, in the order of their equations
#: (sigma_H0 = ... Z_M-B Z_LS Z_E; sigma_HP = sigma_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp;
#: sigma_F0 = ... Y_Fa Y_Sa Y_eps Y_BS Y_LS; sigma_FP = sigma_Flim Y_ST Y_NT Y_delta,relT
#: Y_R,relT Y_X), so that a reader sees why sigma_HP is what it is
_PITTING = (("Z_MB", "Z_M-B", 3), ("Z_LS", "Z_LS", 3), ("Z_E", "Z_E [MPa^0.5]", 3),
            ("sigma_H0", "sigma_H0 [MPa]", 1), ("sigma_H", "sigma_H [MPa]", 1),
            ("sigma_Hlim", "sigma_Hlim [MPa]", 1), ("Z_NT", "Z_NT", 3), ("Z_X", "Z_X", 3),
            ("Z_L", "Z_L", 3), ("Z_speed", "Z_v", 3), ("Z_R", "Z_R", 3), ("Z_W", "Z_W", 3),
            ("Z_K", "Z_K", 3), ("Z_Hyp", "Z_Hyp", 3), ("sigma_HP", "sigma_HP [MPa]", 1),
            ("S_H", "S_H", 3), ("S_Hmin", "S_H,min", 3))
_BENDING = (("s_Fn", "s_Fn [mm]", 3), ("h_Fa", "h_Fa [mm]", 3), ("rho_F", "rho_F [mm]", 3),
            ("Y_Fa", "Y_Fa", 3), ("Y_Sa", "Y_Sa", 3), ("Y_eps", "Y_eps", 3),
            ("Y_BS", "Y_BS", 3), ("Y_LS", "Y_LS", 3), ("sigma_F0", "sigma_F0 [MPa]", 1),
            ("sigma_F", "sigma_F [MPa]", 1), ("sigma_Flim", "sigma_Flim [MPa]", 1),
            ("Y_ST", "Y_ST", 3), ("Y_NT", "Y_NT", 3), ("Y_deltarelT", "Y_delta,relT", 3),
            ("Y_RrelT", "Y_R,relT", 3), ("Y_X", "Y_X", 3), ("sigma_FP", "sigma_FP [MPa]", 1),
            ("S_F", "S_F", 3), ("S_Fmin", "S_F,min", 3))


def _rows(ds, spec) -> list[tuple[str, str, str, str]]:
    """(label, pair, pinion, gear): a value of the pair once, a member's in its column."""
    rows = []
    for name, label, digits in spec:
        if name not in ds:  # a file of an older version
            continue
        x = ds[name]
        if "member" in x.dims:
            rows.append((label, "", *(f"{float(v):.{digits}f}" for v in x.values)))
        else:
            rows.append((label, f"{float(x):.{digits}f}", "", ""))
    return rows


def _given_lines(given: Mapping[str, Any], i: int) -> list[str]:
    """The line on the load factors the ``[rating]`` table gives (``given_load_factors``
    of the dataset), each beside the value the method computes, at torque index ``i``; no
    line where none is given."""
    if not given:
        return []

    def at(x) -> float:
        return float(x[min(i, len(x) - 1)] if isinstance(x, list) else x)

    parts = []
    for name, g in given.items():
        if "field" in g:
            parts.append(f"{name} {g['given']:.3f} ([rating] {g['field']}; "
                         f"{g['computed_by']} gives {at(g['computed']):.3f})")
        else:
            parts.append(f"{name} {at(g['value']):.3f} (follows: {g['follows']}; "
                         f"{g['computed_by']} gives {at(g['computed']):.3f})")
    return ["given load factors: " + "; ".join(parts)]


def tables(ds: xr.Dataset) -> str:
    """The rating as text: the virtual gears, then per torque the load factors and the
    pitting and bending tables (the layout of ISO/TR 10300-30's result tables), what
    ``ltca rate`` prints.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``/rating`` dataset of :func:`rate`.

    Returns
    -------
    str
        The tables, lines separated by newlines (angles in degrees, stresses in N/mm²).
    """
    from tabulate import tabulate

    head = ("", "pair", "pinion", "gear")
    deg = 180.0 / math.pi
    out = [f"ISO 10300 Method B1: {ds.attrs.get('case', '')} ({ds.attrs['side']} side), "
           f"n1 {float(ds['pinion_speed']):g} rpm, K_A {float(ds['K_A']):.3f}, "
           f"beta_v {float(ds['beta_v']) * deg:.3f} deg, alpha_vet "
           f"{float(ds['alpha_vet']) * deg:.3f} deg",
           "",
           "virtual cylindrical gears (ISO 10300-1 Annex A)",
           tabulate(_rows(ds, _GEOMETRY), headers=head, tablefmt="simple",
                    disable_numparse=True)]
    given = json.loads(ds.attrs.get("given_load_factors", "{}"))
    for i, t in enumerate(ds["torque"].values):
        one = ds.sel(torque=t)
        out += ["", f"T1 = {plain_number(t)} N m: F_mt1 {float(one['F_mt1']):.1f} N, F_vmt "
                    f"{float(one['F_vmt']):.1f} N, F_n {float(one['F_n']):.1f} N",
                "load factors: " + "  ".join(
                    f"{label} {float(one[name]):.3f}" for name, label in (
                        ("K_A", "K_A"), ("K_v", "K_v"), ("K_Hbeta_be", "K_Hbeta-be"),
                        ("K_Hbeta", "K_Hbeta"), ("K_F0", "K_F0"), ("K_Fbeta", "K_Fbeta"),
                        ("K_Halpha", "K_Halpha"), ("K_Falpha", "K_Falpha"))
                    if name in one)
                + (f"  (K_v Method B: resonance ratio N {float(one['N']):.3f})"
                   if "N" in one and "K_v" not in given else ""),
                *_given_lines(given, i),
                "", "pitting (ISO 10300-2)",
                tabulate(_rows(one, _PITTING), headers=head, tablefmt="simple",
                         disable_numparse=True),
                "", "tooth root (ISO 10300-3)",
                tabulate(_rows(one, _BENDING), headers=head, tablefmt="simple",
                         disable_numparse=True)]
        if "non_generated" in ds and float(ds["non_generated"].sum()) > 0:
            formate = [m for m, v in zip(ds["member"].values, ds["non_generated"].values,
                                         strict=True) if v > 0]
            out.append(f"tooth form of the {' and the '.join(formate)}: non-generated "
                       "(Formate), its root fillet the cutter's edge radius (ISO 10300-3)")
        for s, smin, what in (("S_H", "S_Hmin", "pitting"), ("S_F", "S_Fmin", "bending")):
            low = [m for m, v in zip(ds["member"].values, one[s].values, strict=True)
                   if v < float(ds[smin])]
            if low:
                out.append(f"{what}: {s} below {s},min {float(ds[smin]):g} for the "
                           f"{' and the '.join(low)}")
    return "\n".join(out)
