"""ANSI/AGMA 2003-D19 as a method of the load-capacity registry (``"agma2003"``).

:func:`rate` is the registry's protocol (:class:`contact.load_capacity.methods.RatingMethod`):
from the case's ``[design]`` table (ISO 23509 basic data of a pair without offset) and its
``[agma2003]`` table (:class:`~contact.load_capacity.agma2003.inputs.AGMAInputs`), the pinion
torques and speed, it returns the ``/rating`` dataset: every factor, the contact and bending
stress numbers s_c, s_t (Eq. 1M, 5M), the permissible s_wc, s_wt (Eq. 2M, 6M), the power
ratings P_ac, P_at (Eq. 4M, 8M) and the ratios s_wc/s_c, s_wt/s_t. :func:`tables` is what
``ltca rate --method agma2003`` prints; :func:`missing` says why a case cannot be rated
(no ``[design]`` or ``[agma2003]`` table, a hypoid offset).

Checked against the standard's Annex E worked example (tests/test_rating_agma2003.py).
"""

from __future__ import annotations

import dataclasses
import json
import logging
import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import xarray as xr

from contact.load_capacity.agma2003 import factors as fac
from contact.load_capacity.agma2003 import stresses as st
from contact.load_capacity.agma2003.allowables import allowable_stress_numbers
from contact.load_capacity.agma2003.inputs import (
    AGMAInputs,
    geometry_from_case,
    offset_refusal,
)
from contact.load_capacity.contract import contract_variables
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.core.materials import material
from geometry.core.text import plain_number
from geometry.core.validation import positive, real_array

__all__ = ["agma2003_rating", "missing", "rate", "tables"]

log = logging.getLogger(__name__)

#: the standard, as the dataset and the tables name it
STANDARD = "ANSI/AGMA 2003-D19"
_MEMBERS = ("pinion", "gear")


def missing(case) -> str:
    """Why ANSI/AGMA 2003-D19 cannot rate ``case`` although nothing in it is wrong, or ``""``.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    str
        One line: no ``[design]`` table, no ``[agma2003]`` table, or a hypoid offset (the
        standard rates bevel gears without offset); ``""`` when the case can be rated.

    Notes
    -----
    ANSI/AGMA 2003-D19 clause 1 (scope: straight, Zerol and spiral bevel gears).
    """
    design = case.extra.get("design")
    if not isinstance(design, Mapping):
        return (f"{STANDARD} rating not computed: the case has no [design] table (its "
                "basic design data, docs/rating.md)")
    why = offset_refusal(design)
    if why:
        return why
    if case.extra.get("agma2003") is None:
        return (f"{STANDARD} rating not computed: the case has no [agma2003] table "
                "(geometry factors, overload factor, accuracy, mounting, life; "
                "docs/rating.md)")
    return ""


def rate(case, torque: np.ndarray, speed: float, *, flank: str | None = None,
         datasets: Mapping[str, xr.Dataset] | None = None,
         agma2003: AGMAInputs | Mapping[str, Any] | None = None) -> xr.Dataset:
    """The ANSI/AGMA 2003-D19 ``/rating`` dataset of a case (the registry's ``"agma2003"``).

    Parameters
    ----------
    case : geometry.case.Case
        With a ``[design]`` table (a pair without offset) and an ``[agma2003]`` table.
    torque : numpy.ndarray, shape (n,) — [N·m]
        Pinion torques (≥ 0).
    speed : float — [rpm]
        Pinion speed (> 0).
    flank : {"concave", "convex", "drive", "coast"}, optional
        The pinion flank the analysis loads; recorded (the geometry factors of the table
        are those of the flank they were determined for).
    datasets : mapping of str to xarray.Dataset, optional
        The analysis' groups; unused (the standard rates the nominal geometry).
    agma2003 : AGMAInputs or mapping, optional
        Replaces the case's ``[agma2003]`` table.

    Returns
    -------
    xarray.Dataset
        :func:`agma2003_rating`'s dataset.

    Raises
    ------
    InputError
        No ``[design]`` or ``[agma2003]`` table, a hypoid offset, or a bad field, torque or
        speed (named).

    Notes
    -----
    ANSI/AGMA 2003-D19 clauses 5–21; checked against its Annex E.
    """
    table = case.extra.get("agma2003") if agma2003 is None else agma2003
    if table is None:
        raise InputError("agma2003: the case has no [agma2003] table (geometry factors, "
                         "overload factor, accuracy, mounting, life; docs/rating.md), and "
                         "none was given")
    out = agma2003_rating(case, torque, speed, inputs=table)
    if flank is not None:
        out.attrs["flank"] = flank
    # the result contract (contact.load_capacity.contract): the standard's stress safety
    # s_wc S_H / s_c = s_ac C_L C_H / (K_T C_R s_c) against S_H (Eq. 1M, 2M), and
    # s_wt S_F / s_t against S_F (Eq. 5M, 6M): below its S_H exactly where s_c > s_wc
    out["stress_safety_pitting"] = (out["safety_pitting"] * out["S_H"]).assign_attrs(
        units="1", long_name="calculated safety for pitting s_wc S_H/s_c",
        source="ANSI/AGMA 2003-D19 Eq. 1M, 2M")
    out["stress_safety_bending"] = (out["safety_bending"] * out["S_F"]).assign_attrs(
        units="1", long_name="calculated safety for bending s_wt S_F/s_t",
        source="ANSI/AGMA 2003-D19 Eq. 5M, 6M")
    return contract_variables(
        out, pitting=("stress_safety_pitting", "S_H", "s_wc S_H/s_c", "S_H"),
        bending=("stress_safety_bending", "S_F", "s_wt S_F/s_t", "S_F"),
        stresses=("s_c", "s_t"))


def _inputs(table: AGMAInputs | Mapping[str, Any]) -> AGMAInputs:
    return table if isinstance(table, AGMAInputs) else AGMAInputs.from_mapping(table)


def _materials(case, inputs: AGMAInputs) -> dict[str, np.ndarray]:
    """s_ac, s_at, E, ν per member [MPa, MPa, MPa, 1]: the table's, else the material's."""
    keys = (case.pinion.material, case.gear.material)
    if inputs.s_ac is not None and inputs.s_at is not None:
        s_ac, s_at = inputs.s_ac, inputs.s_at
    else:
        pairs = [allowable_stress_numbers(k, g)
                 for k, g in zip(keys, inputs.grade, strict=True)]  # type: ignore[arg-type]
        s_ac = inputs.s_ac or tuple(p[0] for p in pairs)
        s_at = inputs.s_at or tuple(p[1] for p in pairs)
    e = inputs.youngs_modulus or tuple(material(k).youngs_modulus for k in keys)
    nu = inputs.poisson_ratio or tuple(material(k).poisson_ratio for k in keys)
    return {"s_ac": np.asarray(s_ac, float), "s_at": np.asarray(s_at, float),
            "E": np.asarray(e, float), "nu": np.asarray(nu, float)}


def agma2003_rating(case, torque, speed: float, *,
                    inputs: AGMAInputs | Mapping[str, Any]) -> xr.Dataset:
    """Rate a bevel gear pair by ANSI/AGMA 2003-D19 (pitting resistance, bending strength).

    Parameters
    ----------
    case : geometry.case.Case
        Its ``[design]`` table gives the geometry (:func:`~contact.load_capacity.agma2003.
        inputs.geometry_from_case`), its members' ``material`` the allowable stress numbers
        and elastic constants where ``inputs`` does not, its ``[operating]`` temperature
        the blank temperature where ``inputs`` does not.
    torque : array_like, shape (n,) — [N·m]
        Pinion torques T1 (≥ 0).
    speed : float — [rpm]
        Pinion speed n1 (> 0).
    inputs : AGMAInputs or mapping
        The ``[agma2003]`` table.

    Returns
    -------
    xarray.Dataset
        Coordinates ``torque`` [N·m] and ``member`` (pinion, gear); the factors (K_o, K_v,
        C_s, K_s, K_mb, K_m, C_xc, K_x, I, J, C_p, C_L, K_L, C_H, K_T, C_R, K_R), the
        geometry (d_e, m_et, b, R_e, R_m, beta_m, r_c0), the allowable and permissible
        stress numbers s_ac, s_at, s_wc, s_wt [MPa] and power ratings P_ac, P_at, P_a [kW]
        per member, and per torque the gear torque T2 [N·m], the transmitted power P [kW],
        s_c (torque) and s_t (torque, member) [MPa], the ratios ``safety_pitting`` =
        s_wc/s_c and ``safety_bending`` = s_wt/s_t, and the power ratios P_ac/P, P_at/P.
        Every variable has ``units`` and ``long_name`` (with its equation); attributes
        ``title``, ``case``, ``standard``, ``rating_method`` ("agma2003") and
        ``agma2003_inputs`` (the inputs as JSON).

    Raises
    ------
    InputError
        A bad torque, speed, ``[design]`` or ``[agma2003]`` field (named).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 1M, 2M, 4M, 5M, 6M, 8M, 9M with the factors of clauses 7–21
    (:mod:`contact.load_capacity.agma2003.factors`). The geometry factors I and J are
    inputs: Annex E reads them off the Annex D charts; the toolkit does not compute Annex
    C(M). The standard's equations were read from a public implementation with a self-test
    against Annex E (docs/rating.md); every Annex E number is a test.
    """
    t1 = real_array("torque", np.atleast_1d(torque), unit="N m", low=0.0, ndim=1)
    n1 = positive("speed", speed, "rpm")
    inp = _inputs(inputs)
    g = geometry_from_case(case)
    mat = _materials(case, inp)
    temperature = (inp.temperature if inp.temperature is not None
                   else float(case.operating.temperature))

    v_et = fac.pitch_line_velocity(g.de1, n1)
    if inp.accuracy_number is not None:
        k_v = fac.dynamic_factor(inp.accuracy_number, v_et)
        v_max = fac.max_pitch_line_velocity(inp.accuracy_number)
        if v_et > v_max:
            log.warning("%s: v_et %.3g m/s exceeds %.3g m/s, the highest pitch-line velocity "
                        "for Q_v %d (Eq. 17M): a higher Q_v or a dynamic analysis (clause "
                        "10.7)", case.name, v_et, v_max, inp.accuracy_number)
    else:
        k_v, v_max = float(inp.dynamic_factor), math.nan  # type: ignore[arg-type]
    k_o = inp.overload_factor
    c_s = fac.size_factor_pitting(g.b)
    k_s = fac.size_factor_bending(g.m_et)
    k_mb = fac.MOUNTING_MODIFIER[inp.mounting]
    if inp.load_distribution_factor is not None:
        k_m = inp.load_distribution_factor
    else:
        try:
            k_m = fac.load_distribution_factor(inp.mounting, g.b)
        except InputError as exc:
            raise InputError(f"design.{exc}; or give agma2003.load_distribution_factor "
                             "(K_m)") from None
    c_xc = (inp.crowning_factor if inp.crowning_factor is not None
            else fac.CROWNING_FACTOR[inp.crowned])
    k_x = fac.lengthwise_curvature_factor(g.beta_m, g.r_c0, g.R_m)
    i_geo = inp.geometry_factor_I
    j_geo = np.asarray(inp.geometry_factor_J, float)
    n_l = np.asarray(inp.load_cycles, float)
    try:
        c_l = (np.asarray(inp.stress_cycle_factor_pitting, float)
               if inp.stress_cycle_factor_pitting is not None
               else np.array([fac.pitting_stress_cycle_factor(n) for n in n_l]))
        k_l = (np.asarray(inp.stress_cycle_factor_bending, float)
               if inp.stress_cycle_factor_bending is not None
               else np.array([fac.bending_stress_cycle_factor(n, inp.critical_service)
                              for n in n_l]))
    except InputError as exc:
        raise InputError(f"agma2003.{exc} (or give stress_cycle_factor_pitting, "
                         "stress_cycle_factor_bending)") from None
    c_h = np.array([1.0, inp.hardness_ratio_factor])
    k_t = fac.temperature_factor(temperature)
    c_r, k_r = fac.reliability_factors(inp.reliability)
    c_p = fac.elastic_coefficient(tuple(mat["E"]), tuple(mat["nu"]))
    s_h, s_f = inp.safety_factor_pitting, inp.safety_factor_bending

    de = np.array([g.de1, g.de2])
    t2 = t1 * g.z2 / g.z1
    power = st.power_from_torque(t1, n1)
    common = dict(b=g.b, de1=g.de1, I=i_geo, C_p=c_p, K_o=k_o, K_v=k_v, K_m=k_m, C_s=c_s,
                  C_xc=c_xc)
    s_c = st.contact_stress(t1, **common)
    s_wc = st.permissible_contact_stress(mat["s_ac"], C_L=c_l, C_H=c_h, S_H=s_h, K_T=k_t,
                                         C_R=c_r)
    p_ac = st.pitting_power(n1, s_wc, **common)
    bend = dict(b=g.b, m_et=g.m_et, K_o=k_o, K_v=k_v, K_s=k_s, K_m=k_m, K_x=k_x)
    s_t = st.bending_stress(np.stack([t1, t2], axis=1), de=de, J=j_geo, **bend)
    s_wt = st.permissible_bending_stress(mat["s_at"], K_L=k_l, S_F=s_f, K_T=k_t, K_R=k_r)
    p_at = st.bending_power(n1, s_wt, de1=g.de1, J=j_geo, **bend)
    p_a = float(min(p_ac.min(), p_at.min()))
    with np.errstate(divide="ignore", invalid="ignore"):
        safety_c = np.where(s_c[:, None] > 0, s_wc[None, :] / s_c[:, None], np.inf)
        safety_t = np.where(s_t > 0, s_wt[None, :] / s_t, np.inf)
        ratio_c = np.where(power[:, None] > 0, p_ac[None, :] / power[:, None], np.inf)
        ratio_t = np.where(power[:, None] > 0, p_at[None, :] / power[:, None], np.inf)

    def var(dims, value, units, long_name, eq):
        return data_var(dims, value, units, long_name, source=f"{STANDARD} {eq}")

    M, T, TM = ("member",), ("torque",), ("torque", "member")
    data = {
        "pinion_speed": var((), n1, "rpm", "pinion speed n1", "clause 6"),
        "gear_speed": var((), n1 * g.z1 / g.z2, "rpm", "gear speed n2", "clause 6"),
        "v_et": var((), v_et, "m/s", "pitch-line velocity at the outer pitch diameter v_et",
                    "Eq. 16M"),
        "v_et_max": var((), v_max, "m/s", "highest pitch-line velocity of the accuracy "
                                           "number (NaN: K_v given)", "Eq. 17M"),
        "d_e": var(M, de, "mm", "outer pitch diameter d_e", "Table 1"),
        "m_et": var((), g.m_et, "mm", "outer transverse module m_et", "Table 1"),
        "b": var((), g.b, "mm", "net face width b", "Table 1"),
        "R_e": var((), g.R_e, "mm", "outer cone distance R_e", "Table 1"),
        "R_m": var((), g.R_m, "mm", "mean cone distance R_m = R_e - b/2", "Eq. 21M"),
        "beta_m": var((), g.beta_m, "rad", "mean spiral angle beta_m", "Table 1"),
        "r_c0": var((), g.r_c0, "mm", "cutter radius r_c0", "Eq. 21M"),
        "K_o": var((), k_o, "1", "overload factor K_o", "clause 7"),
        "K_v": var((), k_v, "1", "dynamic factor K_v", "Eq. 13M"),
        "C_s": var((), c_s, "1", "size factor for pitting resistance C_s", "Eq. 18M"),
        "K_s": var((), k_s, "1", "size factor for bending strength K_s", "Eq. 19M"),
        "K_mb": var((), k_mb, "1", "load distribution modifier K_mb (mounting)", "Figure 4"),
        "K_m": var((), k_m, "1", "load distribution factor K_m", "Eq. 20M"),
        "C_xc": var((), c_xc, "1", "crowning factor for pitting resistance C_xc",
                    "clause 13"),
        "K_x": var((), k_x, "1", "lengthwise curvature factor for bending strength K_x",
                   "Eq. 21M-23M"),
        "I": var((), i_geo, "1", "pitting resistance geometry factor I (input)",
                 "clause 15"),
        "J": var(M, j_geo, "1", "bending strength geometry factor J (input)", "clause 15"),
        "C_p": var((), c_p, "MPa^0.5", "elastic coefficient C_p", "Eq. 32M"),
        "youngs_modulus": var(M, mat["E"], "MPa", "Young's modulus E", "Eq. 32M"),
        "poisson_ratio": var(M, mat["nu"], "1", "Poisson's ratio nu", "Eq. 32M"),
        "N_L": var(M, n_l, "1", "number of load cycles N_L", "clause 16"),
        "C_L": var(M, c_l, "1", "stress cycle factor for pitting resistance C_L",
                   "Figure 5"),
        "K_L": var(M, k_l, "1", "stress cycle factor for bending strength K_L", "Figure 6"),
        "C_H": var(M, c_h, "1", "hardness ratio factor for pitting resistance C_H",
                   "clause 17"),
        "temperature": var((), temperature, "degC", "gear blank temperature", "clause 18"),
        "K_T": var((), k_t, "1", "temperature factor K_T", "Eq. 31M"),
        "reliability": var((), inp.reliability, "1", "reliability (probability of no "
                                                     "failure)", "Table 2"),
        "C_R": var((), c_r, "1", "reliability factor for pitting C_R", "Table 2"),
        "K_R": var((), k_r, "1", "reliability factor for bending K_R", "Table 2"),
        "S_H": var((), s_h, "1", "safety factor for pitting S_H (in s_wc)", "Eq. 2M"),
        "S_F": var((), s_f, "1", "safety factor for bending S_F (in s_wt)", "Eq. 6M"),
        "s_ac": var(M, mat["s_ac"], "MPa", "allowable contact stress number s_ac",
                    "clause 21"),
        "s_at": var(M, mat["s_at"], "MPa", "allowable bending stress number s_at",
                    "clause 21"),
        "s_wc": var(M, s_wc, "MPa", "permissible contact stress number s_wc", "Eq. 2M"),
        "s_wt": var(M, s_wt, "MPa", "permissible bending stress number s_wt", "Eq. 6M"),
        "P_ac": var(M, p_ac, "kW", "allowable transmitted power for pitting resistance "
                                   "P_ac", "Eq. 4M"),
        "P_at": var(M, p_at, "kW", "allowable transmitted power for bending strength P_at",
                    "Eq. 8M"),
        "P_a": var((), p_a, "kW", "allowable transmitted power, the least of P_ac and "
                                  "P_at", "clause 5"),
        "T2": var(T, t2, "N m", "gear torque T2 = T1 z2/z1", "clause 6"),
        "P": var(T, power, "kW", "transmitted power P", "Eq. 9M"),
        "s_c": var(T, s_c, "MPa", "calculated contact stress number s_c", "Eq. 1M"),
        "s_t": var(TM, s_t, "MPa", "calculated bending stress number s_t", "Eq. 5M"),
        "safety_pitting": var(TM, safety_c, "1", "pitting margin s_wc/s_c", "Eq. 1M, 2M"),
        "safety_bending": var(TM, safety_t, "1", "bending margin s_wt/s_t", "Eq. 5M, 6M"),
        "power_ratio_pitting": var(TM, ratio_c, "1", "allowable over transmitted power "
                                                     "P_ac/P", "Eq. 4M, 9M"),
        "power_ratio_bending": var(TM, ratio_t, "1", "allowable over transmitted power "
                                                     "P_at/P", "Eq. 8M, 9M"),
    }
    coords = {"torque": data_var(T, t1, "N m", "pinion torque T1"),
              "member": data_var(M, np.array(_MEMBERS), None, "gear pair member")}
    rating_inputs = {k: v for k, v in dataclasses.asdict(inp).items() if v is not None}
    attrs = {"title": f"{STANDARD} rating (pitting resistance and bending strength)",
             "case": case.name, "standard": STANDARD, "rating_method": "agma2003",
             "agma2003_inputs": json.dumps(rating_inputs)}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def tables(ds: xr.Dataset) -> str:
    """The rating as text, what ``ltca rate --method agma2003`` prints: the geometry and
    factors, a table of the members' allowables and ratings, then per torque the stress
    numbers and margins (ASCII, stresses in MPa, powers in kW).

    Parameters
    ----------
    ds : xarray.Dataset
        A ``/rating`` dataset of :func:`rate`.

    Returns
    -------
    str
        The tables, lines separated by newlines.
    """
    from tabulate import tabulate

    def f(name, digits=3):
        return f"{float(ds[name]):.{digits}f}"

    deg = 180.0 / math.pi
    out = [f"{STANDARD}: {ds.attrs.get('case', '')}, n1 {float(ds['pinion_speed']):g} rpm "
           f"(n2 {float(ds['gear_speed']):.1f} rpm), v_et {f('v_et')} m/s",
           f"geometry: d_e1 {float(ds['d_e'][0]):.3f} mm, d_e2 {float(ds['d_e'][1]):.3f} mm, "
           f"m_et {f('m_et', 4)} mm, b {f('b')} mm, R_e {f('R_e')} mm, beta_m "
           f"{float(ds['beta_m']) * deg:.3f} deg, r_c0 {f('r_c0')} mm",
           "factors: " + "  ".join(f"{n} {f(n, 4)}" for n in (
               "K_o", "K_v", "K_mb", "K_m", "C_s", "K_s", "C_xc", "K_x", "I")),
           "         " + "  ".join(f"{n} {f(n, 4)}" for n in (
               "K_T", "C_R", "K_R", "S_H", "S_F")) + f"  C_p {f('C_p', 1)} MPa^0.5",
           f"         (K_T at the blank temperature {f('temperature', 1)} degC; C_R, K_R at "
           f"the reliability {float(ds['reliability']):g})",
           ""]
    rows = [(label, *(f"{float(v):.{d}f}" for v in ds[name].values)) for name, label, d in (
        ("J", "J", 3), ("youngs_modulus", "E [MPa]", 0), ("poisson_ratio", "nu", 3),
        ("N_L", "N_L", 0), ("C_L", "C_L", 3), ("K_L", "K_L", 3), ("C_H", "C_H", 3),
        ("s_ac", "s_ac [MPa]", 1), ("s_at", "s_at [MPa]", 1),
        ("s_wc", "s_wc [MPa]", 1), ("s_wt", "s_wt [MPa]", 1), ("P_ac", "P_ac [kW]", 2),
        ("P_at", "P_at [kW]", 2))]
    out.append(tabulate(rows, headers=("", "pinion", "gear"), tablefmt="simple",
                        disable_numparse=True))
    out.append(f"allowable transmitted power P_a {f('P_a', 2)} kW")
    for t in ds["torque"].values:
        one = ds.sel(torque=t)
        out += ["", f"T1 = {plain_number(t)} N m (T2 {float(one['T2']):.1f} N m), P "
                    f"{float(one['P']):.2f} kW: contact stress number s_c "
                    f"{float(one['s_c']):.1f} MPa",
                tabulate([(label, *(f"{float(v):.{d}f}" for v in one[name].values))
                          for name, label, d in (
                              ("s_t", "s_t [MPa]", 1), ("safety_pitting", "s_wc/s_c", 3),
                              ("safety_bending", "s_wt/s_t", 3),
                              ("pitting_safety", "s_wc S_H/s_c", 3),
                              ("bending_safety", "s_wt S_F/s_t", 3),
                              ("power_ratio_pitting", "P_ac/P", 3),
                              ("power_ratio_bending", "P_at/P", 3))],
                         headers=("", "pinion", "gear"), tablefmt="simple",
                         disable_numparse=True)]
        low = [f"{what} of the {m}" for what, name in (("pitting", "safety_pitting"),
                                                       ("bending", "safety_bending"))
               for m, v in zip(ds["member"].values, one[name].values, strict=True) if v < 1.0]
        if low:
            out.append("stress number above the permissible: " + ", ".join(low))
    return "\n".join(out)
