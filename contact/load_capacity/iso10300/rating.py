"""The ISO 10300 Method B1 rating of a case: one entry point, one labelled dataset.

:func:`iso10300_rating` rates a case's pair at its torques and speed: the geometry from
the case's ISO 23509 basic design data (its ``[design]`` table, through the blank the
toolkit computes, :func:`geometry.iso23509.blank.blank_geometry`), the rest from its
``[rating]`` table (:class:`~contact.load_capacity.iso10300.inputs.RatingInputs`) and the
members' material (:mod:`contact.load_capacity.iso10300.materials`). :func:`rate_pair` does
the same from the gear data directly (:class:`~contact.load_capacity.iso10300.inputs.GearData`):
what the tests feed ISO/TR
10300-30:2024's printed data to.

The result is the ``/rating`` group of an analysis: an ``xarray.Dataset`` with dimensions
``torque`` (the pinion torques), ``member`` (pinion, gear) and ``line`` (the tip, middle
and root contact lines), every variable with ``units``, a ``long_name`` and the
``clause`` of ISO 10300 it comes from. Angles are in rad, stresses in MPa (N/mm²).
"""

from __future__ import annotations

import dataclasses
import json
import logging
import math
import os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from contact.load_capacity.iso10300 import bending, factors, pitting
from contact.load_capacity.iso10300.inputs import (
    GIVEN_FACTORS,
    GearData,
    RatingInputs,
    gear_data_from_blank,
)
from contact.load_capacity.iso10300.materials import RatingMaterial, rating_material
from contact.load_capacity.iso10300.virtual_gears import virtual_gears
from geometry.core.conventions import data_var, dataset
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords
from geometry.core.validation import positive, real_array
from geometry.core.version import __version__

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "LINES",
    "MEMBERS",
    "case_gear_data",
    "case_rating_inputs",
    "iso10300_rating",
    "rate_pair",
]

log = logging.getLogger(__name__)

MEMBERS = ("pinion", "gear")
LINES = ("tip", "middle", "root")

_P1 = "ISO 10300-1:2014"
_P2 = "ISO 10300-2:2014"
_P3 = "ISO 10300-3:2014"
_A = f"{_P1} Annex A"


def rate_pair(data: GearData, inputs: RatingInputs, torque: Any, speed: float,
              materials: tuple[RatingMaterial, RatingMaterial] | None = None,
              side: str = "drive", name: str = "") -> xr.Dataset:
    """ISO 10300 Method B1 rating of a pair given by its gear data.

    Parameters
    ----------
    data : GearData
        The pair's geometry (from its ISO 23509 blank).
    inputs : RatingInputs
        With ``nu40`` and ``edge_radius`` given (:func:`iso10300_rating` fills them from
        the case).
    torque : array_like, shape (n,) — [N·m]
        Pinion torques, each > 0.
    speed : float — [rpm]
        Pinion speed, > 0.
    materials : (RatingMaterial, RatingMaterial), optional
        Pinion and gear; default the toolkit's default material at
        ``inputs.quality_grade``.
    side : {"drive", "coast"}
        The rated flank (``inputs.side`` when that is given).
    name : str
        The case's name, for the dataset's attributes.

    Returns
    -------
    xarray.Dataset
        Dimensions ``torque``, ``member``, ``line``: every factor of ISO 10300-1/-2/-3
        Method B1 as a variable with ``units``, ``long_name`` and ``clause``
        (docs/rating.md lists them), among them the safety factors ``S_H``, ``S_F``
        (torque, member) and their minima ``S_Hmin``, ``S_Fmin``; where ``inputs`` gives
        load factors (K_v, K_Hβ, K_Fβ, K_Hα, K_Fα) they are used as given and the
        attribute ``given_load_factors`` (JSON) holds each beside the value the method
        computes with the other factors as used.

    Raises
    ------
    InputError
        A bad torque or speed, or ``nu40``/``edge_radius`` missing (named
        ``rating.<field>``).
    """
    torque = real_array("torque", np.atleast_1d(torque), unit="N m", low=0.0,
                        low_open=True, ndim=1)
    speed = positive("speed", speed, "rpm")
    side = inputs.side or side
    for field in ("nu40", "edge_radius"):
        if getattr(inputs, field) is None:
            raise InputError(f"rating.{field}: missing ({field} is needed and was not given)")
    if materials is None:
        from geometry.core.materials import DEFAULT_MATERIAL

        mat = rating_material(DEFAULT_MATERIAL, inputs.quality_grade)
        materials = (mat, mat)
    E = np.array(inputs.youngs_modulus or [m.youngs_modulus for m in materials])
    nu = np.array(inputs.poisson_ratio or [m.poisson_ratio for m in materials])
    s_Hlim = np.array(inputs.sigma_Hlim or [m.sigma_Hlim for m in materials])
    s_Flim = np.array(inputs.sigma_Flim or [m.sigma_Flim for m in materials])

    alpha_n, alpha_e, _ = data.flank_angles(side)
    vg = virtual_gears(data, side, inputs.effective_width_ratio)
    K_A = inputs.application_factor

    # ISO 10300-1: forces, speeds, load factors
    F = factors.nominal_forces(torque, data.d_m1, data.beta_m1, data.beta_m2, vg.beta_v,
                               alpha_n)
    v_mt = np.array(factors.mean_point_speeds(speed, data.d_m1, data.d_m2, data.z1, data.z2))
    if inputs.single_pitch_deviation is not None:
        f_pt_members = np.array(inputs.single_pitch_deviation)
    else:
        d_T = (np.array([data.d_m1, data.d_m2]) + 2.0 * np.array([data.h_am1, data.h_am2])
               * np.cos([data.delta1, data.delta2]))
        f_pt_members = factors.single_pitch_tolerance(d_T, data.m_mn,
                                                      np.array(inputs.accuracy_grade))
    f_pt = float(np.max(f_pt_members))
    C_F = factors.stiffness_correction(F["F_vmt"], K_A, vg.b_v)
    N = factors.resonance_ratio(speed, data.z1, data.d_m1, data.d_m2, alpha_n,
                                materials[1].density, factors.MESH_STIFFNESS * C_F)
    K_v_B, K = factors.dynamic_factor(N, F["F_vmt"], K_A, vg.b_v, f_pt, vg.eps_vg)
    K_v = (np.full(torque.shape, inputs.dynamic_factor) if inputs.dynamic_factor is not None
           else K_v_B)
    K_Hbe = factors.mounting_factor(inputs.mounting, inputs.contact_pattern)
    R_m2 = data.d_m2 / (2.0 * np.sin(data.delta2))
    K_F0 = factors.lengthwise_curvature_factor(data.r_c0, R_m2, data.beta_m2)
    K_Hb_C, K_Fb_C = factors.face_load_factors(K_Hbe, K_F0)
    # a given K_Hbeta carries K_Fbeta = K_Hbeta / K_F0 with it (ISO 10300-1 cl. 8)
    K_Hb = _given(inputs.face_load_factor_contact, K_Hb_C)
    K_Fb = _given(inputs.face_load_factor_bending, K_Hb / K_F0)

    # ISO 10300-2: pitting
    Z_MB = pitting.mid_zone_factor(vg.alpha_vet, vg.d_va, vg.d_vb, vg.z_v, vg.eps_va,
                                   vg.eps_vb)
    Z_LS, p_star = pitting.load_sharing_factor(vg.f, vg.l_b, vg.f_max,
                                               inputs.load_sharing_exponent)
    Y_eps = bending.contact_ratio_factor(vg.eps_va, vg.eps_vb)
    alpha_ = factors.transverse_load_factors(
        F["F_vmt"], K_A, K_v, K_Hb, vg.b_v, f_pt, vg.eps_vg, data.a, data.d_m2,
        limit_H=vg.eps_vg / (vg.eps_va * Z_LS**2), limit_F=vg.eps_vg / (vg.eps_va * Y_eps))
    computed = {"K_v": K_v_B, "K_Hbeta": K_Hb_C, "K_Fbeta": K_Fb_C,
                "K_Halpha": alpha_["K_Halpha"], "K_Falpha": alpha_["K_Falpha"]}
    # a given K_Halpha is K_Falpha too where that is not given (Method B: one value)
    K_Ha = _given(inputs.transverse_load_factor_contact, alpha_["K_Halpha"], torque.shape)
    K_Fa = _given(inputs.transverse_load_factor_bending,
                  K_Ha if inputs.transverse_load_factor_contact is not None
                  else alpha_["K_Falpha"], torque.shape)
    alpha_ = {**alpha_, "K_Halpha": K_Ha, "K_Falpha": K_Fa}
    Z_E = pitting.elasticity_factor(E, nu)
    Z_L = pitting.lubricant_factor(s_Hlim, inputs.nu40)
    Z_v = pitting.speed_factor(s_Hlim, float(v_mt[1]))
    Z_R = pitting.roughness_factor(s_Hlim, inputs.flank_roughness, vg.rho_rel)
    Z_Hyp, slide = pitting.hypoid_factor(data.a, float(v_mt[0]), data.beta_m1, data.beta_m2,
                                         vg.beta_B, alpha_n)
    Z_W = pitting.work_hardening_factor()
    Z_X = np.full(2, pitting.SIZE_FACTOR)
    cycles = (np.array([inputs.load_cycles, inputs.load_cycles * data.z1 / data.z2])
              if inputs.load_cycles is not None else np.full(2, np.nan))
    Z_NT = pitting.life_factor(cycles, *_curve(materials, "contact_curve"))
    sigma_H0 = pitting.nominal_contact_stress(F["F_n"], vg.l_bm, vg.rho_rel, Z_MB, Z_LS, Z_E)
    sigma_H = pitting.contact_stress(sigma_H0, K_A, K_v, K_Hb, alpha_["K_Halpha"])
    # Z_L Z_v Z_R: their long-life values at the knee, 1 in the static range (ISO 6336-2)
    knee_H, static_H, z0_H = _curve(materials, "contact_curve")
    share_H = pitting.long_life_share(cycles, knee_H, static_H)
    sigma_HP = pitting.permissible_contact_stress(s_Hlim, Z_NT, Z_X, Z_L ** share_H,
                                                  Z_v ** share_H, Z_R ** share_H, Z_W, Z_Hyp)
    sigma_HP_long = pitting.permissible_contact_stress(s_Hlim, 1.0, Z_X, Z_L, Z_v, Z_R, Z_W,
                                                       Z_Hyp)

    # ISO 10300-3: bending
    rho_a0 = np.array(inputs.edge_radius)
    x_hm, x_sm = [data.x_hm1, data.x_hm2], [data.x_sm1, data.x_sm2]
    s_pr = np.array(inputs.protuberance)
    formate = np.array([p == "Formate" for p in (inputs.process or ("Generate",) * 2)])
    form = bending.tooth_form(data.m_mn, vg.z_vn, vg.d_van, vg.d_vbn, x_hm, x_sm, data.h_a0,
                              rho_a0, s_pr, alpha_e, alpha_n)
    if formate.any():  # ISO 10300-3: a non-generated member's fillet is the edge radius
        form = bending.member_tooth_forms(form, bending.non_generated_tooth_form(
            data.m_mn, [data.h_am1, data.h_am2], x_hm, x_sm, data.h_a0, rho_a0, s_pr,
            alpha_e, alpha_n), formate)
    Y_Sa, q_s = bending.stress_correction_factor(form.s_Fn, form.h_Fa, form.rho_F)
    Y_BS = bending.bevel_spiral_angle_factor(vg.b_v, vg.beta_v, vg.beta_vb, vg.l_bm,
                                             data.h_am1 + data.h_fm1,
                                             data.h_am2 + data.h_fm2)
    Y_LS = bending.load_sharing_factor(Z_LS)
    Y_R = np.array([float(bending.relative_surface_factor(rz, m.surface_condition,
                                                           m.surface_condition_smooth))
                    for rz, m in zip(inputs.root_roughness, materials, strict=True)])
    Y_d = np.array([float(bending.relative_notch_sensitivity(q, m.slip_layer))
                    for q, m in zip(q_s, materials, strict=True)])
    Y_X = np.full(2, bending.size_factor(data.m_mn))
    Y_NT = pitting.life_factor(cycles, *_curve(materials, "bending_curve"))
    knee_F, static_F, y0_F = _curve(materials, "bending_curve")
    share_F = pitting.long_life_share(cycles, knee_F, static_F)
    sigma_F0 = bending.nominal_root_stress(F["F_vmt"][:, None], vg.b_v, data.m_mn, form.Y_Fa,
                                           Y_Sa, Y_eps, Y_BS, Y_LS)
    sigma_F = bending.root_stress(sigma_F0, K_A, K_v[:, None], K_Fb,
                                  alpha_["K_Falpha"][:, None])
    sigma_FP = bending.permissible_root_stress(s_Flim, Y_NT, Y_d, Y_R ** share_F,
                                               Y_X ** share_F)
    sigma_FP_long = bending.permissible_root_stress(s_Flim, 1.0, Y_d, Y_R, Y_X)

    # the load cycles each torque may run where its long-life safety is below the minimum
    # (pinion cycles N_L1; the gear's are N_L1 z1/z2): on the sloped part the permissible
    # stress rises as (static factor / the influence factors that fall to 1 there)^t
    to_pinion = np.array([1.0, data.z2 / data.z1])
    S_H_long = sigma_HP_long[None, :] / sigma_H[:, None]
    S_F_long = sigma_FP_long[None, :] / sigma_F
    N_H = pitting.permissible_cycles(inputs.min_safety_pitting / S_H_long, knee_H, static_H,
                                     z0_H / (Z_L * Z_v * Z_R)) * to_pinion
    N_F = pitting.permissible_cycles(inputs.min_safety_bending / S_F_long, knee_F, static_F,
                                     y0_F / (Y_R * Y_X)) * to_pinion

    values = dict(
        N_H=N_H, N_F=N_F,
        vg=vg, F=F, v_mt=v_mt, speed=speed, f_pt=f_pt_members, y_alpha=float(
            factors.running_in_allowance(f_pt)), N=N, K=K, K_v=K_v, K_A=K_A,
        K_Hbeta_be=K_Hbe, K_F0=K_F0, K_Hbeta=K_Hb, K_Fbeta=K_Fb, alpha_=alpha_, Z_MB=Z_MB,
        Z_LS=Z_LS, p_star=p_star, Z_E=Z_E, Z_L=Z_L, Z_v=Z_v, Z_R=Z_R, Z_Hyp=Z_Hyp,
        slide=slide, Z_W=Z_W, Z_X=Z_X, Z_NT=Z_NT, sigma_H0=sigma_H0, sigma_H=sigma_H,
        sigma_Hlim=s_Hlim, sigma_HP=sigma_HP, form=form, Y_Sa=Y_Sa, q_s=q_s, Y_eps=Y_eps,
        Y_BS=Y_BS, Y_LS=Y_LS, Y_R=Y_R, Y_d=Y_d, Y_X=Y_X, Y_NT=Y_NT, sigma_F0=sigma_F0,
        sigma_F=sigma_F, sigma_Flim=s_Flim, sigma_FP=sigma_FP, E=E, nu=nu, cycles=cycles,
        computed=computed, formate=formate)
    return _dataset(torque, values, inputs, data, side, name, materials)


def _given(value: float | None, computed, shape: tuple[int, ...] | None = None):
    """The given factor where the ``[rating]`` table gives it (broadcast to ``shape``, the
    torques, for a factor that varies with the load), else the computed one."""
    if value is None:
        return computed
    return np.full(shape, value) if shape is not None else float(value)


def _given_factors(inputs: RatingInputs, v: dict[str, Any]) -> dict[str, Any]:
    """What the ``[rating]`` table gives in place of the computed load factors, each with
    the value the method computes beside it: variable → {field, given, computed,
    computed_by} (a factor that follows from a given one, K_Fbeta of K_Hbeta and K_Falpha
    of K_Halpha, with ``follows``)."""
    out: dict[str, Any] = {}

    def numbers(x):
        x = np.asarray(x, float)
        return float(x) if x.ndim == 0 else [float(e) for e in x.ravel()]

    for field, (name, method) in GIVEN_FACTORS.items():
        value = getattr(inputs, field)
        if value is not None:
            out[name] = {"field": field, "given": float(value),
                         "computed": numbers(v["computed"][name]), "computed_by": method}
    follows = (("K_Fbeta", "face_load_factor_bending", "K_Hbeta",
                "K_Fbeta = K_Hbeta / K_F0 of the given K_Hbeta (ISO 10300-1:2014 cl. 8)"),
               ("K_Falpha", "transverse_load_factor_bending", "K_Halpha",
                "K_Falpha = the given K_Halpha (ISO 10300-1:2014 cl. 9, Method B: one value)"))
    for name, field, source, how in follows:
        if source in out and getattr(inputs, field) is None:
            out[name] = {"follows": how, "value": numbers(v[name] if name in v
                                                           else v["alpha_"][name]),
                         "computed": numbers(v["computed"][name]),
                         "computed_by": GIVEN_FACTORS[field][1]}
    return out


def _curve(materials, attr: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    curves = [getattr(m, attr) for m in materials]
    return (np.array([c.knee_cycles for c in curves]),
            np.array([c.static_cycles for c in curves]),
            np.array([c.static_life_factor for c in curves]))


def _design_torque(inputs, side: str) -> tuple[float, str]:
    """The torque [N·m] the rated side is rated for at long life and the ``[rating]`` field
    it comes from: ``coast_design_torque`` on the coast side where it is given, else
    ``design_torque`` (NaN: every torque)."""
    if side == "coast" and inputs.coast_design_torque is not None:
        return inputs.coast_design_torque, "coast_design_torque"
    return (np.nan if inputs.design_torque is None else inputs.design_torque), "design_torque"


def _dataset(torque: np.ndarray, v: dict[str, Any], inputs: RatingInputs, data: GearData,
             side: str, name: str, materials) -> xr.Dataset:
    """The ``/rating`` dataset: every quantity with units, long name and clause."""
    vg = v["vg"]
    t, m, li = ("torque",), ("member",), ("line",)
    tm = ("torque", "member")
    design_torque, design_field = _design_torque(inputs, side)

    def var(dims, value, units, long_name, clause):
        return data_var(dims, np.asarray(value, dtype=float), units, long_name, clause=clause)

    given = _given_factors(inputs, v)

    def clause(name: str, computed_by: str) -> str:
        """The clause of a load factor, or where the given value comes from."""
        g = given.get(name)
        if g is None:
            return computed_by
        if "field" in g:
            return f"given ([rating] {g['field']}; {g['computed_by']} computes it otherwise)"
        return g["follows"]

    a1 = f"{_A} (A.2, transverse section)"
    a3 = f"{_A} (A.3, normal section)"
    form = v["form"]
    al = v["alpha_"]
    out = {
        # virtual cylindrical gears
        "d_v": var(m, vg.d_v, "mm", "reference diameter of the virtual gear d_v", a1),
        "d_va": var(m, vg.d_va, "mm", "tip diameter of the virtual gear d_va", a1),
        "d_vb": var(m, vg.d_vb, "mm", "base diameter of the virtual gear d_vb", a1),
        "z_v": var(m, vg.z_v, "1", "number of teeth of the virtual gear z_v", a1),
        "u_v": var((), vg.u_v, "1", "ratio of the virtual gears u_v", a1),
        "beta_v": var((), vg.beta_v, "rad", "helix angle of the virtual gears beta_v", a1),
        "alpha_vet": var((), vg.alpha_vet, "rad",
                         "transverse pressure angle of the virtual gears alpha_vet", a1),
        "m_vt": var((), vg.m_vt, "mm", "transverse module of the virtual gears m_vt", a1),
        "beta_vb": var((), vg.beta_vb, "rad", "base helix angle beta_vb", a1),
        "p_vet": var((), vg.p_vet, "mm", "transverse base pitch p_vet", a1),
        "g_va": var((), vg.g_va, "mm", "length of the path of contact g_va", a1),
        "eps_va": var((), vg.eps_va, "1", "transverse contact ratio eps_va", a1),
        "b_veff": var((), vg.b_veff, "mm", "effective face width of the virtual gears b_v,eff",
                      a1),
        "b_v": var((), vg.b_v, "mm", "face width of the virtual gears b_v", a1),
        "gamma": var((), vg.gamma, "rad",
                     "auxiliary angle (skew of the zone of action) gamma", a1),
        "eps_vb": var((), vg.eps_vb, "1", "face contact ratio eps_vb", a1),
        "eps_vg": var((), vg.eps_vg, "1", "virtual contact ratio eps_vg", a1),
        "f": var(li, vg.f, "mm", "distance of the contact line from the middle line f", a1),
        "f_max": var((), vg.f_max, "mm",
                     "distance of the farthest corner of the zone of action f_max", a1),
        "l_b0": var(li, vg.l_b0, "mm", "length of the contact line in the zone l_b0", a1),
        "l_b": var(li, vg.l_b, "mm", "length of the contact line l_b", a1),
        "l_bm": var((), vg.l_bm, "mm", "length of the middle contact line l_bm", a1),
        "rho_t": var((), vg.rho_t, "mm",
                     "radius of relative curvature in the normal section rho_t", a1),
        "beta_B": var((), vg.beta_B, "rad", "inclination of the contact line beta_B", a1),
        "rho_rel": var((), vg.rho_rel, "mm",
                       "radius of relative curvature normal to the contact line rho_rel", a1),
        "z_vn": var(m, vg.z_vn, "1", "number of teeth of the virtual gear, normal section "
                                     "z_vn", a3),
        "d_vn": var(m, vg.d_vn, "mm", "reference diameter, normal section d_vn", a3),
        "d_van": var(m, vg.d_van, "mm", "tip diameter, normal section d_van", a3),
        "d_vbn": var(m, vg.d_vbn, "mm", "base diameter, normal section d_vbn", a3),
        "eps_van": var((), vg.eps_van, "1", "transverse contact ratio, normal section eps_van",
                       a3),
        # forces, speeds (ISO 10300-1 cl. 6)
        "pinion_speed": var((), v["speed"], "rpm", "pinion speed n1", f"{_P1} cl. 6"),
        "v_mt": var(m, v["v_mt"], "m/s", "tangential speed at the mean point v_mt",
                    f"{_P1} cl. 6"),
        "F_mt1": var(t, v["F"]["F_mt1"], "N", "tangential force of the pinion at the mean "
                                              "point F_mt1", f"{_P1} cl. 6"),
        "F_mt2": var(t, v["F"]["F_mt2"], "N", "tangential force of the gear at the mean point "
                                              "F_mt2", f"{_P1} cl. 6"),
        "F_vmt": var(t, v["F"]["F_vmt"], "N", "tangential force of the virtual gears F_vmt",
                     f"{_P1} cl. 6"),
        "F_n": var(t, v["F"]["F_n"], "N", "normal force at the mean point F_n",
                   f"{_P2} cl. 6"),
        # load factors (ISO 10300-1)
        "K_A": var((), v["K_A"], "1", "application factor K_A", f"{_P1} cl. 6"),
        "f_pt": var(m, v["f_pt"], "um", "single pitch deviation f_pt", f"{_P1} cl. 7"),
        "y_alpha": var((), v["y_alpha"], "um", "running-in allowance y_alpha",
                       f"{_P1} cl. 7"),
        "N": var(t, v["N"], "1", "resonance ratio N = n1/n_E1", f"{_P1} cl. 7 (Method B)"),
        "K": var(t, v["K"], "1", "constant K of the subcritical dynamic factor",
                 f"{_P1} cl. 7 (Method B)"),
        "K_v": var(t, v["K_v"], "1", "dynamic factor K_v", clause("K_v",
                                                                  f"{_P1} cl. 7 (Method B)")),
        "K_Hbeta_be": var((), v["K_Hbeta_be"], "1", "mounting factor K_Hbeta-be",
                          f"{_P1} cl. 8"),
        "K_Hbeta": var((), v["K_Hbeta"], "1", "face load factor for contact K_Hbeta",
                       clause("K_Hbeta", f"{_P1} cl. 8")),
        "K_F0": var((), v["K_F0"], "1", "lengthwise curvature factor K_F0", f"{_P1} cl. 8"),
        "K_Fbeta": var((), v["K_Fbeta"], "1", "face load factor for bending K_Fbeta",
                       clause("K_Fbeta", f"{_P1} cl. 8")),
        "F_mtH": var(t, al["F_mtH"], "N", "determinant tangential force F_mtH",
                     f"{_P1} cl. 9"),
        "K_Halpha_star": var(t, al["K_Halpha_star"], "1",
                             "transverse load factor before the offset reduction K*_Halpha",
                             f"{_P1} cl. 9 (Method B)"),
        "a_rel": var((), al["a_rel"], "1", "relative hypoid offset a_rel = 2 a / d_m2",
                     f"{_P1} cl. 9"),
        "K_Halpha": var(t, al["K_Halpha"], "1", "transverse load factor for contact "
                                                "K_Halpha", clause("K_Halpha",
                                                                   f"{_P1} cl. 9 (Method B)")),
        "K_Falpha": var(t, al["K_Falpha"], "1", "transverse load factor for bending "
                                                "K_Falpha", clause("K_Falpha",
                                                                   f"{_P1} cl. 9 (Method B)")),
        # pitting (ISO 10300-2)
        "Z_MB": var((), v["Z_MB"], "1", "mid-zone factor Z_M-B", f"{_P2} cl. 6"),
        "p_star": var(li, v["p_star"], "1", "related peak load of the contact line p*",
                      f"{_P2} cl. 6"),
        "Z_LS": var((), v["Z_LS"], "1", "load sharing factor Z_LS", f"{_P2} cl. 6"),
        "Z_E": var((), v["Z_E"], "MPa^0.5", "elasticity factor Z_E", f"{_P2} cl. 8"),
        "youngs_modulus": var(m, v["E"], "MPa", "Young's modulus E", "material"),
        "poisson_ratio": var(m, v["nu"], "1", "Poisson's ratio nu", "material"),
        "nu40": var((), inputs.nu40, "mm2/s", "kinematic viscosity of the oil at 40 degC "
                                              "nu40", f"{_P2} cl. 8"),
        "Z_L": var(m, v["Z_L"], "1", "lubricant factor Z_L", f"{_P2} cl. 8"),
        # Z_speed, not Z_v: netCDF names are compared case-blind (CF 1.8 §2.3) and z_v is
        # the virtual number of teeth
        "Z_speed": var(m, v["Z_v"], "1", "speed factor Z_v", f"{_P2} cl. 8"),
        "Z_R": var(m, v["Z_R"], "1", "roughness factor Z_R", f"{_P2} cl. 8"),
        "v_g": var((), v["slide"]["v_g"], "m/s", "sliding velocity at the mean point v_g",
                   f"{_P2} cl. 6"),
        "v_g_par": var((), v["slide"]["v_g_par"], "m/s",
                       "sliding velocity along the contact line v_g,par", f"{_P2} cl. 6"),
        "v_sum_vert": _v_sum_vert(var((), v["slide"]["v_sum_vert"], "m/s",
                                      "sum velocity normal to the contact line v_Sigma,vert",
                                      f"{_P2} cl. 6")),
        "Z_Hyp": var((), v["Z_Hyp"], "1", "hypoid factor Z_Hyp", f"{_P2} cl. 6"),
        "Z_K": var((), pitting.BEVEL_GEAR_FACTOR, "1", "bevel gear factor Z_K",
                   f"{_P2} cl. 6"),
        "Z_W": var(m, v["Z_W"], "1", "work hardening factor Z_W", f"{_P2} cl. 8"),
        "Z_X": var(m, v["Z_X"], "1", "size factor for contact Z_X", f"{_P2} cl. 8"),
        "load_cycles": var(m, v["cycles"], "1", "load cycles N_L (NaN: long life)",
                           "[rating] load_cycles"),
        "Z_NT": var(m, v["Z_NT"], "1", "life factor for contact Z_NT", f"{_P2} cl. 8"),
        "sigma_H0": var(t, v["sigma_H0"], "MPa", "nominal contact stress sigma_H0",
                        f"{_P2} cl. 6 (Method B1)"),
        "sigma_H": var(t, v["sigma_H"], "MPa", "contact stress sigma_H",
                       f"{_P2} cl. 6 (Method B1)"),
        "sigma_Hlim": var(m, v["sigma_Hlim"], "MPa",
                          "allowable stress number for contact sigma_H,lim",
                          "ISO 6336-5:2016 (material table or [rating])"),
        "sigma_HP": var(m, v["sigma_HP"], "MPa", "permissible contact stress sigma_HP",
                        f"{_P2} cl. 6 (Method B1)"),
        "S_H": var(tm, v["sigma_HP"][None, :] / v["sigma_H"][:, None], "1",
                   "safety factor for pitting S_H = sigma_HP / sigma_H",
                   f"{_P2} cl. 6 (Method B1)"),
        "S_Hmin": var((), inputs.min_safety_pitting, "1", "minimum safety factor for pitting "
                                                          "S_H,min", "[rating]"),
        "design_torque": var((), design_torque, "N m",
                             "pinion torque rated at long life (NaN: every torque)",
                             f"[rating] {design_field}"),
        "permissible_cycles_pitting": var(
            tm, v["N_H"], "1", "pinion load cycles N_L1 at which S_H reaches S_H,min (inf: "
            "long life; 0: beyond the static strength)", f"{_P2} cl. 8 (life factor Z_NT)"),
        # bending (ISO 10300-3)
        "non_generated": var(m, v["formate"], "1", "tooth form of a non-generated (Formate) "
                                                   "member 1, of a generated member 0",
                             f"{_P3} cl. 6 ([rating] process or the case's members)"),
        "E": var(m, form.E, "mm", "auxiliary quantity of the tooth form E", f"{_P3} cl. 6"),
        "G": var(m, form.G, "1", "auxiliary quantity of the tooth form G", f"{_P3} cl. 6"),
        "H": var(m, form.H, "1", "auxiliary quantity of the tooth form H", f"{_P3} cl. 6"),
        "theta": var(m, form.theta, "rad", "fillet angle at the 30 deg tangent theta",
                     f"{_P3} cl. 6"),
        "s_Fn": var(m, form.s_Fn, "mm", "root chord at the 30 deg tangents s_Fn",
                    f"{_P3} cl. 6"),
        "rho_F": var(m, form.rho_F, "mm", "root fillet radius rho_F", f"{_P3} cl. 6"),
        "alpha_an": var(m, form.alpha_an, "rad", "pressure angle at the tooth tip alpha_an",
                        f"{_P3} cl. 6"),
        "gamma_a": var(m, form.gamma_a, "rad", "auxiliary angle gamma_a", f"{_P3} cl. 6"),
        "alpha_Fan": var(m, form.alpha_Fan, "rad", "load application angle at the tip "
                                                   "alpha_Fan", f"{_P3} cl. 6"),
        "h_Fa": var(m, form.h_Fa, "mm", "bending moment arm h_Fa", f"{_P3} cl. 6"),
        "edge_radius": var(m, inputs.edge_radius, "mm", "cutter edge radius rho_a0",
                           "[rating] or the case's blades"),
        "Y_Fa": var(m, form.Y_Fa, "1", "tooth form factor Y_Fa", f"{_P3} cl. 6"),
        "q_s": var(m, v["q_s"], "1", "notch parameter q_s", f"{_P3} cl. 6"),
        "Y_Sa": var(m, v["Y_Sa"], "1", "stress correction factor Y_Sa", f"{_P3} cl. 6"),
        "Y_eps": var((), v["Y_eps"], "1", "contact ratio factor Y_eps", f"{_P3} cl. 6"),
        "Y_BS": var((), v["Y_BS"], "1", "bevel spiral angle factor Y_BS", f"{_P3} cl. 6"),
        "Y_LS": var((), v["Y_LS"], "1", "load sharing factor for bending Y_LS",
                    f"{_P3} cl. 6"),
        "Y_RrelT": var(m, v["Y_R"], "1", "relative surface condition factor Y_R,relT",
                       f"{_P3} cl. 6"),
        "Y_deltarelT": var(m, v["Y_d"], "1", "relative notch sensitivity factor Y_delta,relT",
                           f"{_P3} cl. 6"),
        "Y_X": var(m, v["Y_X"], "1", "size factor for bending Y_X", f"{_P3} cl. 8"),
        "Y_NT": var(m, v["Y_NT"], "1", "life factor for bending Y_NT", f"{_P3} cl. 8"),
        "Y_ST": var((), bending.STRESS_CORRECTION_TEST_GEAR, "1",
                    "stress correction factor of the test gear Y_ST", f"{_P3} cl. 6"),
        "sigma_F0": var(tm, v["sigma_F0"], "MPa", "nominal tooth root stress sigma_F0",
                        f"{_P3} cl. 6 (Method B1)"),
        "sigma_F": var(tm, v["sigma_F"], "MPa", "tooth root stress sigma_F",
                       f"{_P3} cl. 6 (Method B1)"),
        "sigma_Flim": var(m, v["sigma_Flim"], "MPa",
                          "nominal stress number for bending sigma_F,lim",
                          "ISO 6336-5:2016 (material table or [rating])"),
        "sigma_FP": var(m, v["sigma_FP"], "MPa", "permissible tooth root stress sigma_FP",
                        f"{_P3} cl. 6 (Method B1)"),
        "S_F": var(tm, v["sigma_FP"][None, :] / v["sigma_F"], "1",
                   "safety factor for bending S_F = sigma_FP / sigma_F",
                   f"{_P3} cl. 6 (Method B1)"),
        "S_Fmin": var((), inputs.min_safety_bending, "1", "minimum safety factor for bending "
                                                          "S_F,min", "[rating]"),
        "permissible_cycles_bending": var(
            tm, v["N_F"], "1", "pinion load cycles N_L1 at which S_F reaches S_F,min (inf: "
            "long life; 0: beyond the static strength)", f"{_P3} cl. 8 (life factor Y_NT)"),
    }
    coords = {
        "torque": data_var(t, torque, "N m", "pinion torque T1"),
        "member": data_var(m, list(MEMBERS), None, "member of the pair"),
        "line": data_var(li, list(LINES), None, "contact line (tip, middle, root)"),
    }
    attrs = {
        "title": "ISO 10300 Method B1 load capacity rating",
        # the registry name of the method that made it (contact.load_capacity.METHODS)
        "rating_method": "iso10300",
        "case": name,
        "method": "ISO 10300-1/-2/-3:2014 Method B1 (virtual cylindrical gears, Annex A; "
                  "K_v Method B, K_Hbeta Method C, K_Halpha Method B"
                  + (f"; given: {', '.join(given)}" if given else "") + ")",
        "side": side,
        "rating_inputs": json.dumps(inputs.to_mapping()),
        # the load factors the [rating] table gives, each beside the computed value
        **({"given_load_factors": json.dumps(given)} if given else {}),
        "gear_data": json.dumps(dataclasses.asdict(data)),
        "materials": ", ".join(mat.key for mat in materials),
        "toolkit_version": __version__,
    }
    return dataset(out, coords, attrs)


def case_gear_data(case):
    """The gear data and the ISO 23509 blank of a case's ``[design]`` table.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    (GearData, geometry.iso23509.blank.BlankGeometry)

    Raises
    ------
    InputError
        No ``[design]`` table, or a bad one (``design.<field>``).
    """
    from contact.load_capacity.design_table import design_blank, design_table

    blank = design_blank(design_table(
        case, "the ISO 10300 rating needs the case's ISO 23509 basic design data, a "
              "[design] table (the fields of a basic design file, docs/synthesis.md)"))
    return gear_data_from_blank(blank), blank


#: Rz per Rq of the flanks [1]: Rz = 6 Ra, the approximation of DIN 3990/3991 that gear
#: rating programs use to convert the mean roughness depth (e.g. FVA's, adoc.fva-service.de,
#: attribute 391), with Ra = √(2/π) Rq of Gaussian heights (contact.load_capacity.micropitting):
#: 4.79
RZ_PER_RQ = 6.0 * math.sqrt(2.0 / math.pi)


def case_rating_inputs(case, rating: RatingInputs | Mapping[str, Any] | None = None
                       ) -> RatingInputs:
    """A case's rating inputs, completed from the case where the table leaves them out.

    Parameters
    ----------
    case : geometry.case.Case
    rating : RatingInputs or mapping, optional
        Overrides the case's ``[rating]`` table (a mapping is read as that table).

    Returns
    -------
    RatingInputs
        With ``nu40`` (the case's oil at 40 °C), ``edge_radius`` (the edge radii of the
        blades that cut the rated flanks), ``process`` (the members' ``process``: a
        Formate member is rated by the non-generated tooth form), ``side`` (ISO's drive
        side when the pinion's concave flank drives) and, where the table leaves
        ``flank_roughness`` out, the flanks' Rz from the case's ``[operating] roughness``
        Rq (Rz = 6 Ra = 6 √(2/π) Rq, :data:`RZ_PER_RQ`: the rating's Z_R and the LTCA's
        film then see one roughness) filled in.

    Raises
    ------
    InputError
        No ``[rating]`` table, a bad field (``rating.<field>``), or ν40 neither given nor
        obtainable from the case's oil (``rating.nu40``).
    """
    given: Mapping[str, Any] = {}
    if rating is None:
        table = case.extra.get("rating")
        if table is None:
            raise InputError("rating: the case has no [rating] table (at least "
                             "application_factor, mounting and single_pitch_deviation or "
                             "accuracy_grade; docs/rating.md)")
        rating, given = RatingInputs.from_mapping(table), table
    elif isinstance(rating, Mapping):
        rating, given = RatingInputs.from_mapping(rating), rating
    fill: dict[str, Any] = {}
    if given and "flank_roughness" not in given:
        # one roughness for the rating and the LTCA: the case's Rq as Rz (RZ_PER_RQ)
        rz = round(RZ_PER_RQ * float(case.operating.roughness), 3)
        fill["flank_roughness"] = (rz, rz)
    if rating.side is None:
        fill["side"] = "drive" if case.pair.drive_flank == "concave" else "coast"
    side = fill.get("side", rating.side)
    if rating.nu40 is None:
        fill["nu40"] = _oil_nu40(case.operating.lubricant)
    if rating.process is None:  # the tooth form of ISO 10300-3 by how each member is cut
        fill["process"] = (case.pinion.process, case.gear.process)
    if rating.edge_radius is None:
        pinion_flank = "concave" if side == "drive" else "convex"
        gear_flank = "convex" if pinion_flank == "concave" else "concave"
        fill["edge_radius"] = (case.pinion.flank(pinion_flank).blade.edge_radius,
                               case.gear.flank(gear_flank).blade.edge_radius)
    return dataclasses.replace(rating, **fill) if fill else rating


def _oil_nu40(lubricant: str) -> float:
    from friction.lubricant import kinematic_viscosity, load_lubricant
    from geometry.core.errors import ModelUnavailableError

    try:
        # to 0.001 mm2/s, far below the oil data's own precision: the value is recorded in
        # the file's rating_inputs text, which must not change with the CPU's math kernels
        # in its last digit (tests/test_golden_run.py, other BLAS kernels)
        return round(float(kinematic_viscosity(load_lubricant(lubricant), 40.0)), 3)
    except (InputError, ModelUnavailableError, OSError) as exc:
        raise InputError(f"rating.nu40: missing, and the case's oil {lubricant!r} gives none "
                         f"at 40 degC ({exc}); give nu40 [mm2/s] in [2, 5000]") from None


@renamed_keywords(speed="pinion_speed")
def iso10300_rating(case: Case | str | os.PathLike[str] | None, torque: Any = None,
                    pinion_speed: float | None = None,
                    rating: RatingInputs | Mapping[str, Any] | None = None) -> xr.Dataset:
    """ISO 10300 Method B1 load capacity rating of a case's pair.

    Parameters
    ----------
    case : geometry.case.Case, str or path-like
        A case, a case file or a bundled case name (:func:`contact.catalogue.resolve_case`);
        it needs a ``[design]`` table (ISO 23509 basic design data) and a ``[rating]``
        table (docs/rating.md).
    torque : array_like, shape (n,) — [N·m], optional
        Pinion torques; default the case's ``[operating]`` torques.
    pinion_speed : float — [rpm], optional
        Pinion speed; default the case's ``[operating] pinion_speed`` (> 0; old name
        ``speed``, deprecated).
    rating : RatingInputs or mapping, optional
        Replaces the case's ``[rating]`` table.

    Returns
    -------
    xarray.Dataset
        The ``/rating`` group (:func:`rate_pair`), with the case's name.

    Raises
    ------
    InputError
        A missing or bad ``[design]`` or ``[rating]`` field (named), a torque or speed
        outside the table of physical bounds (:data:`geometry.core.bounds.
        PHYSICAL_BOUNDS`: (0, 1e6] N·m, (0, 5e4] rpm; issue 64: 10¹² rpm was rated).
    """
    from contact.catalogue import resolve_case

    case = resolve_case(case)
    inputs = case_rating_inputs(case, rating)
    data, _ = case_gear_data(case)
    torque = case.operating.torque if torque is None else torque
    speed = case.operating.pinion_speed if pinion_speed is None else pinion_speed
    _check_bounds(torque, speed)
    members = tuple(rating_material(case.member(mm).material, inputs.quality_grade)
                    for mm in MEMBERS)
    log.info("rating %s (%s side) at %s N m, %s rpm", case.name, inputs.side,
             np.atleast_1d(torque), speed)
    return rate_pair(data, inputs, torque, speed, members, side=inputs.side, name=case.name)


def _v_sum_vert(variable):
    """``v_sum_vert`` with a ``comment`` where it is NaN: a pair without hypoid offset
    (a spiral bevel pair) has Z_Hyp = 1 by ISO 10300-2 cl. 6, and v_Σ,vert, which
    enters only the hypoid factor, is not evaluated (issue 64: a NaN says why)."""
    if np.all(np.isfinite(variable[1])):
        return variable
    return (*variable[:2], {**variable[2], "comment": (
        "NaN: not evaluated for a pair without hypoid offset (spiral bevel, a = 0), whose "
        "hypoid factor Z_Hyp is 1 (ISO 10300-2 cl. 6); v_Sigma,vert enters only Z_Hyp")})


def _check_bounds(torque: Any, speed: Any) -> None:
    """Refuse a torque [N·m] or pinion speed [rpm] outside the table of physical bounds
    before any rating (one sentence naming it and the range)."""
    from geometry.core.bounds import check_bound, check_torques

    check_torques(torque)
    check_bound("pinion_speed", speed, field="speed")
