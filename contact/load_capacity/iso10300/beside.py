"""The standard's rating beside the loaded contact: ISO 10300 stresses next to the LTCA's.

A gear engineer reads a bevel or hypoid pair twice: by the rating the standard prescribes
(ISO 10300 Method B1, :func:`contact.load_capacity.iso10300.iso10300_rating`) and by the local
stresses of
the loaded contact (the peak flank pressure of ``/ltca`` and, where root stress was
computed, the FE peak tooth-root stress). Two functions put them side by side:

* :func:`analysis_rating` — the rating of an analysis' case at its torques and speed for
  its flank, or ``None`` and the one-line reason it is absent (no ISO 23509 ``[design]``
  table, no ``[rating]`` table, no speed): what ``ltca run`` stores as ``/rating``;
* :func:`rating_beside_ltca` — per torque and member, the rating's nominal and rated
  stresses (σ_H0, σ_H; σ_F0, σ_F) and the LTCA's (peak flank pressure, FE peak root stress)
  with their ratios: what ``ltca run`` prints and the HTML report shows;
* :func:`bin_ratings` — the rating at each bin's torque and speed of a duty cycle, whose
  safety factors ``ltca duty-cycle`` prints beside its local ones.

The ratios are not a check of either: the rating's stresses are the standard's nominal
values at the mean point with its load factors (K_A, K_v, K_Hβ, K_Hα), the LTCA's are the
peaks of the actual contact at the case's misalignment; docs/rating.md discusses them.
"""

from __future__ import annotations

import logging
from typing import Any

import numpy as np
import xarray as xr

from geometry.core.conventions import data_var
from geometry.core.errors import InputError

__all__ = ["analysis_rating", "bin_ratings", "rating_beside_ltca"]

log = logging.getLogger(__name__)


def analysis_rating(case, torque: Any, speed: float | None, flank: str | None = None
                    ) -> tuple[xr.Dataset | None, str]:
    """The ISO 10300 rating of an analysis' case, or why there is none.

    Parameters
    ----------
    case : geometry.case.Case
    torque : array_like, shape (n,) — [N·m]
        The analysis' pinion torques.
    speed : float or None — [rpm]
        Pinion speed; None or 0: no rating (K_v and Z_v need a speed).
    flank : {"concave", "convex", "drive", "coast"}, optional
        The pinion flank the analysis loads, by name or as the case's drive or coast flank
        (``ltca run --flank``); default the case's drive flank. The rated side follows it:
        ISO 23509's drive side is the pinion's concave flank driving.

    Returns
    -------
    (xarray.Dataset or None, str)
        The ``/rating`` dataset (:func:`contact.load_capacity.iso10300.iso10300_rating`) and
        ``""``; or
        None and one line saying why the rating is absent: the case has no ``[design]``
        table (its ISO 23509 basic data), no ``[rating]`` table, or no speed.

    Raises
    ------
    InputError
        A ``[design]`` or ``[rating]`` table that is there but wrong (the field named):
        refused, as any bad input, before the analysis' work.

    Notes
    -----
    Source: ISO 10300-1/-2/-3:2014 Method B1 through
    :func:`contact.load_capacity.iso10300.rate_pair`.
    """
    from contact.load_capacity.iso10300.inputs import RatingInputs
    from contact.load_capacity.iso10300.method import missing_tables, rated_side
    from contact.load_capacity.iso10300.rating import iso10300_rating

    why = missing_tables(case)
    if why:
        return None, why
    table = case.extra["rating"]
    if speed is None or not speed > 0.0:
        return None, ("ISO 10300 rating not computed: no pinion speed (the case's "
                      "[operating] pinion_speed is 0; give --speed)")
    inputs = RatingInputs.from_mapping(table)  # a bad table is refused here, named
    if flank is not None and inputs.side is None:
        table = {**table, "side": rated_side(case, flank)}
    # the table itself, so that the case fills what it leaves out (case_rating_inputs)
    return iso10300_rating(case, torque, speed, rating=table), ""


#: what the ratio of the LTCA's peak flank pressure to σ_H compares (console, report, file)
PRESSURE_RATIO_NOTE = (
    "p_max/sigma_H: the LTCA's peak Hertzian pressure on the flanks (the local elastic peak "
    "of the actual contact at the case's misalignment and the nominal torque, no load "
    "factors) over ISO 10300-2's contact stress sigma_H = sigma_H0 sqrt(K_A K_v K_Hbeta "
    "K_Halpha) (the mean-point stress of the virtual cylindrical gears with the load "
    "factors); p_max/sigma_H0 leaves the load factors out of both")
#: what the ratio of the FE peak root stress to σ_F compares (console, report, file)
ROOT_RATIO_NOTE = (
    "FE/sigma_F: the FE peak maximum principal tooth-root stress over the fillets and the "
    "mesh cycle (nominal torque, no load factors) over ISO 10300-3's tooth root stress "
    "sigma_F = sigma_F0 K_A K_v K_Fbeta K_Falpha (the 30-degree tangent section of the "
    "virtual cylindrical gears with the load factors); FE/sigma_F0 leaves the load factors "
    "out of both")


def rating_beside_ltca(rating: xr.Dataset, ltca: xr.Dataset) -> xr.Dataset:
    """The rating's stresses beside the loaded contact's, per torque and member.

    Parameters
    ----------
    rating : xarray.Dataset
        The ``/rating`` group (:func:`contact.load_capacity.iso10300.iso10300_rating`) at the
        analysis'
        torques.
    ltca : xarray.Dataset
        The ``/ltca`` group: ``pressure_max_flank`` (torque) and, when root stress was
        computed, ``root_stress_max`` (torque, member).

    Returns
    -------
    xarray.Dataset
        Dimensions ``torque`` (the LTCA's) and ``member``; variables [MPa] ``sigma_H0``,
        ``sigma_H`` (torque), ``pressure_max_flank`` (torque), ``sigma_F0``, ``sigma_F``,
        ``root_stress_max`` (torque, member; NaN without root stress), and the ratios [1]
        ``pressure_to_sigma_H0``, ``pressure_to_sigma_H`` (the LTCA's peak flank pressure
        over the rating's), ``root_stress_to_sigma_F0``, ``root_stress_to_sigma_F`` (the FE
        peak over the rating's).

    Raises
    ------
    InputError
        The rating lacks one of the LTCA's torques (``torque``).

    Notes
    -----
    Source: ISO 10300-2/-3:2014 Method B1 (σ_H0, σ_H, σ_F0, σ_F) and the LTCA's own peaks;
    the ratios are plain quotients.
    """
    t = np.asarray(ltca["torque"].values, float)
    have = np.asarray(rating["torque"].values, float)
    missing = [x for x in t if not np.any(np.isclose(have, x, rtol=1e-12, atol=0.0))]
    if missing:
        raise InputError(f"torque: the rating has no torque {missing[0]:g} N m of the LTCA "
                         f"(it has {', '.join(f'{x:g}' for x in have)})")
    r = rating.sel(torque=t, method="nearest")
    p = np.asarray(ltca["pressure_max_flank"].values, float)
    s_h0, s_h = r["sigma_H0"].values, r["sigma_H"].values
    s_f0, s_f = r["sigma_F0"].values, r["sigma_F"].values
    members = list(rating["member"].values)
    if "root_stress_max" in ltca:
        fe = np.asarray(ltca["root_stress_max"].transpose("torque", "member")
                        .sel(member=members).values, float)
        fe_note = "FE peak tooth-root stress (max principal) over the mesh, /ltca"
    else:
        fe = np.full(s_f.shape, np.nan)
        fe_note = "NaN: no root stress in the analysis (--no-root-stress)"
    T, TM = ("torque",), ("torque", "member")
    c2, c3 = "ISO 10300-2:2014 Method B1", "ISO 10300-3:2014 Method B1"
    out = {
        "sigma_H0": data_var(T, s_h0, "MPa", "nominal contact stress sigma_H0", clause=c2),
        "sigma_H": data_var(T, s_h, "MPa", "contact stress sigma_H", clause=c2),
        "pressure_max_flank": data_var(T, p, "MPa", "LTCA peak flank contact pressure",
                                       clause="the loaded contact, /ltca"),
        "pressure_to_sigma_H0": data_var(T, p / s_h0, "1",
                                         "LTCA peak flank pressure / sigma_H0", clause=c2),
        "pressure_to_sigma_H": data_var(T, p / s_h, "1", "LTCA peak flank pressure / sigma_H",
                                        clause=c2, comment=PRESSURE_RATIO_NOTE),
        "sigma_F0": data_var(TM, s_f0, "MPa", "nominal tooth root stress sigma_F0",
                             clause=c3),
        "sigma_F": data_var(TM, s_f, "MPa", "tooth root stress sigma_F", clause=c3),
        "root_stress_max": data_var(TM, fe, "MPa", "FE peak tooth-root stress",
                                    clause="the loaded contact, /ltca", comment=fe_note),
        "root_stress_to_sigma_F0": data_var(TM, fe / s_f0, "1",
                                            "FE peak root stress / sigma_F0", clause=c3),
        "root_stress_to_sigma_F": data_var(TM, fe / s_f, "1", "FE peak root stress / sigma_F",
                                           clause=c3, comment=ROOT_RATIO_NOTE),
    }
    coords = {"torque": data_var(T, t, "N m", "pinion torque T1"),
              "member": data_var(("member",), members, None, "member of the pair")}
    return xr.Dataset(out, coords=coords,
                      attrs={"title": "ISO 10300 rating beside the LTCA",
                             "side": rating.attrs.get("side", "")})


def bin_ratings(case, torque: Any, speed: Any, flank: str | None = None
                ) -> tuple[xr.Dataset | None, str]:
    """The ISO 10300 rating at each bin of a duty cycle (its torque and its speed).

    Parameters
    ----------
    case : geometry.case.Case
    torque, speed : array_like, shape (n,) — [N·m], [rpm]
        Pinion torque and speed of each bin (speeds > 0).
    flank : {"concave", "convex", "drive", "coast"}, optional
        The loaded pinion flank (:func:`analysis_rating`).

    Returns
    -------
    (xarray.Dataset or None, str)
        Over ``bin`` (and ``member``): ``sigma_H`` [MPa] (bin), ``sigma_F``,
        ``sigma_HP``, ``sigma_FP`` [MPa], ``S_H``, ``S_F`` [1] (bin, member), and for the
        duty cycle's S-N curves the rating's long-life influence factors
        ``contact_allowable_factor`` (Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp),
        ``contact_static_influence`` (Z_L Z_v Z_R), ``bending_allowable_factor``
        (Y_δ,relT Y_R,relT Y_X) and ``bending_static_influence`` (Y_R,relT Y_X) [1]
        (bin, member), ``K_A_K_v`` (bin), ``S_Fmin``, ``S_Hmin`` and ``design_torque``
        [N·m] (), each
        with ``units``, ``long_name`` and ``clause``, and ``""``; or
        None and the one line of :func:`analysis_rating` saying why there is no rating.

    Raises
    ------
    InputError
        A bad ``[design]`` or ``[rating]`` table (the field named), torque and speed of
        different lengths.

    Notes
    -----
    Source: ISO 10300-2/-3:2014 Method B1, one rating per bin (K_v and Z_v depend on the
    bin's speed); cheap (about 10 ms a bin).
    """
    torque = np.atleast_1d(np.asarray(torque, float))
    speed = np.atleast_1d(np.asarray(speed, float))
    if torque.shape != speed.shape:
        raise InputError(f"speed: one per bin, got {speed.size} speeds for {torque.size} "
                         "torques")
    ratings = []
    for t, n in zip(torque, speed, strict=True):
        ds, why = analysis_rating(case, [t], float(n), flank)
        if ds is None:
            return None, why
        ratings.append(ds.isel(torque=0))
    B, BM = ("bin",), ("bin", "member")
    c2, c3 = "ISO 10300-2:2014 Method B1", "ISO 10300-3:2014 Method B1"
    out = {
        "sigma_H": data_var(B, np.array([float(r["sigma_H"]) for r in ratings]), "MPa",
                            "contact stress sigma_H of the bin", clause=c2),
        "sigma_F": data_var(BM, np.stack([r["sigma_F"].values for r in ratings]), "MPa",
                            "tooth root stress sigma_F of the bin", clause=c3),
        "S_H": data_var(BM, np.stack([r["S_H"].values for r in ratings]), "1",
                        "safety factor for pitting S_H of the bin", clause=c2),
        "S_F": data_var(BM, np.stack([r["S_F"].values for r in ratings]), "1",
                        "safety factor for bending S_F of the bin", clause=c3),
        "sigma_HP": data_var(BM, np.stack([r["sigma_HP"].values for r in ratings]), "MPa",
                             "permissible contact stress sigma_HP of the bin", clause=c2),
        "sigma_FP": data_var(BM, np.stack([r["sigma_FP"].values for r in ratings]), "MPa",
                             "permissible tooth root stress sigma_FP of the bin", clause=c3),
        # the rating's allowables for the duty cycle's S-N curves (SNCurve.rated): the
        # long-life influence factors, and the part of them that is 1 for the static stress
        "contact_allowable_factor": data_var(BM, np.stack([_contact_factor(r)
                                                           for r in ratings]), "1",
                                             "sigma_HP / (sigma_Hlim Z_NT) at long life: Z_X "
                                             "Z_L Z_v Z_R Z_W Z_K Z_Hyp of the bin", clause=c2),
        "contact_static_influence": data_var(BM, np.stack([
            (r["Z_L"] * r["Z_speed"] * r["Z_R"]).values for r in ratings]), "1",
            "Z_L Z_v Z_R of the bin (1 for the static stress)", clause=c2),
        "bending_allowable_factor": data_var(BM, np.stack([
            (r["Y_deltarelT"] * r["Y_RrelT"] * r["Y_X"]).values for r in ratings]), "1",
            "sigma_FP / (sigma_Flim Y_ST Y_NT) at long life: Y_delta,relT Y_R,relT Y_X of "
            "the bin", clause=c3),
        "bending_static_influence": data_var(BM, np.stack([
            (r["Y_RrelT"] * r["Y_X"]).values for r in ratings]), "1",
            "Y_R,relT Y_X of the bin (1 for the static stress)", clause=c3),
        # what ltca run's root-stress check needs to judge a bin as it judges its torque
        # (contact.study.verdict_checks.root_safety_severity, issue 71)
        "K_A_K_v": data_var(B, np.array([float(r["K_A"]) * float(r["K_v"])
                                         for r in ratings]), "1",
                            "application factor times dynamic factor K_A K_v of the bin",
                            clause="ISO 10300-1:2014"),
        "S_Fmin": data_var((), float(ratings[0]["S_Fmin"]), "1",
                           "minimum safety factor for bending S_F,min", clause="[rating]"),
        # the duty cycle's rating check judges S_H against it as ltca run does (issue 71)
        "S_Hmin": data_var((), float(ratings[0]["S_Hmin"]), "1",
                           "minimum safety factor for pitting S_H,min", clause="[rating]"),
        "design_torque": data_var((), float(ratings[0]["design_torque"])
                                  if "design_torque" in ratings[0] else np.nan, "N m",
                                  "the rating's design torque (NaN: every torque)",
                                  # the field it is: [rating] coast_design_torque on the
                                  # coast side where given (the duty verdict names it)
                                  clause=str(ratings[0]["design_torque"].attrs.get(
                                      "clause", "[rating]"))
                                  if "design_torque" in ratings[0] else "[rating]"),
    }
    members = list(ratings[0]["member"].values)
    return xr.Dataset(out, coords={"member": data_var(("member",), members, None,
                                                      "member of the pair")},
                      attrs={"side": ratings[0].attrs.get("side", "")}), ""


def _contact_factor(r: xr.Dataset) -> np.ndarray:
    """Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp of one rating (σ_HP/(σ_Hlim Z_NT) at long life)."""
    return (r["Z_X"] * r["Z_L"] * r["Z_speed"] * r["Z_R"] * r["Z_W"] * r["Z_K"]
            * r["Z_Hyp"]).values
