"""The console's lines on a load-capacity rating beside the LTCA, from the result contract.

``ltca run`` prints them; they read only the contract of the load-capacity methods
(:mod:`contact.load_capacity.contract`: the safeties and their minima, and where the
method gives them the standard's contact and root stresses), so that every method of the
registry — ISO 10300, ANSI/AGMA 2003, a plug-in's — is printed the same way, and a
``/rating`` without the contract says so ("not checked") instead of being read as passed.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the command modules load for `ltca --help` without numerical libraries
    import xarray as xr

__all__ = ["rating_lines"]


def _number(value: float, decimals: int = 0) -> str:
    return f"{value:.{decimals}f}" if math.isfinite(value) else "-"


def _ltca_at(lt: xr.Dataset | None, name: str, torque: float, member: int) -> float:
    import numpy as np

    """``/ltca``'s ``name`` at ``torque`` (and member index where it has one), NaN where
    the analysis lacks it."""
    if lt is None or name not in lt or "torque" not in lt.coords:
        return math.nan
    t = np.asarray(lt["torque"].values, float)
    hit = np.flatnonzero(np.isclose(t, torque, rtol=1e-9, atol=0.0))
    if hit.size == 0:
        return math.nan
    x = lt[name].isel(torque=int(hit[0]))
    if "member" in x.dims:
        x = x.isel(member=member)
    return float(x.values)


def rating_lines(tree: xr.DataTree, why: str = "", case_arg: str | None = None,
                 method: str | None = None) -> list[str]:
    """The lines ``ltca run`` prints on the rating: per torque and member the standard's
    contact stress beside the LTCA's peak flank pressure and its root stress beside the FE
    peak root stress (where the method gives them), the safeties against pitting and
    bending with their minima, and where every factor is; or the one line ``why`` for an
    analysis without ``/rating``, or "not checked" for a ``/rating`` without the contract.

    Parameters
    ----------
    tree : xarray.DataTree
        The analysis (``/ltca``, optionally ``/rating``).
    why : str
        Why the rating is absent (printed when it is).
    case_arg : str, optional
        The case as typed, for the ``ltca rate`` command the lines name.
    method : str, optional
        The method's registry name as chosen (default: the dataset's ``rating_method``).

    Returns
    -------
    list of str
    """
    import numpy as np

    if "rating" not in tree.children:
        return [why] if why else []
    from tabulate import tabulate

    from contact.load_capacity.contract import safeties
    from geometry.core.text import plain_number

    raw = tree["rating"].to_dataset()
    name = str(raw.attrs.get("rating_method", method or ""))
    ds, lacks = safeties(raw)
    if ds is None:
        return [f"rating by {name or 'an unnamed method'}: not checked: {lacks}"]
    lt = tree["ltca"].to_dataset() if "ltca" in tree.children else None
    standard = str(ds.attrs.get("rating_standard") or name)
    members = (ds["member_label"].values if "member_label" in ds.coords
               else ds["member"].values)
    stresses = {"contact_stress", "root_stress"} <= set(ds.data_vars)
    s_h, s_f = ds["pitting_safety"].transpose("torque", "member"), \
        ds["bending_safety"].transpose("torque", "member")
    rows = []
    for i, t in enumerate(ds["torque"].values):
        for j, member in enumerate(members):
            row = [plain_number(t), str(member)]
            if stresses:
                c = float(ds["contact_stress"].transpose("torque", "member").values[i, j])
                r = float(ds["root_stress"].transpose("torque", "member").values[i, j])
                p = _ltca_at(lt, "pressure_max_flank", float(t), j)
                fe = _ltca_at(lt, "root_stress_max", float(t), j)
                row += [_number(c), _number(p), _number(p / c, 2), _number(r), _number(fe),
                        _number(fe / r, 2)]
            row += [f"{float(s_h.values[i, j]):.2f}", f"{float(s_f.values[i, j]):.2f}"]
            rows.append(tuple(row))
    sym_h = s_h.attrs.get("symbol") or "pitting"
    sym_f = s_f.attrs.get("symbol") or "bending"
    headers = ["T_p [N m]", "member"]
    if stresses:
        ch, rh = (ds["contact_stress"].attrs.get("symbol", "contact"),
                  ds["root_stress"].attrs.get("symbol", "root"))
        headers += [ch, "p_max flank", f"p_max/{ch}", rh, "FE root", f"FE/{rh}"]
    headers += [f"safety {sym_h}", f"safety {sym_f}"]
    mins = "; ".join(
        f"{ds[v].attrs.get('symbol') or v} "
        + " / ".join(f"{x:g}" for x in np.unique(np.asarray(ds[v].values, float)))
        for v in ("pitting_safety_min", "bending_safety_min"))
    speed = (f", n1 {float(ds['pinion_speed']):g} rpm" if "pinion_speed" in ds
             and np.ndim(ds["pinion_speed"].values) == 0 else "")
    side = f", {ds.attrs['side']} side" if ds.attrs.get("side") else ""
    lines = [f"{standard} rating beside the LTCA (method {name}{side}{speed}; /rating, "
             "docs/rating.md)" + (" [MPa]:" if stresses else ":"),
             tabulate(rows, headers=headers, tablefmt="github")]
    if stresses:
        lines.append("p_max/" + ch + ": the LTCA's peak flank pressure over the standard's "
                     "contact stress (with its load factors); FE/" + rh + ": the FE peak "
                     "root stress over the standard's root stress; two measures side by "
                     "side, not a check of either (docs/rating.md).")
    rate = (f"ltca rate {case_arg or str(tree.attrs.get('case', ''))} --method {name} "
            "--torque " + " ".join(f"{t:g}" for t in ds["torque"].values)
            + (f" --speed {float(ds['pinion_speed']):g}" if speed else "")
            + (" --flank coast" if ds.attrs.get("side") == "coast" else ""))
    lines.append(f"safeties per member (pinion / gear) against their minima ({mins}); "
                 f"every factor of the rating is a variable of /rating in the file written "
                 f"below, and `{rate}` prints them")
    return lines
