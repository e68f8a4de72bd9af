"""The verdict's root-stress and scuffing checks (issue 72 item 2): the FE peak root stress
against a permissible stress, and the standard's S_B beside the one the verdict judges.

Called from :func:`contact.study.verdicts.verdict` for an analysis (one place,
``_analysis``); the findings are :class:`contact.study.verdicts.Finding`.

**Root stress** (check ``root_stress``). The FE peak ``root_stress_max`` [MPa] (torque,
member) of ``/ltca`` is the largest maximum principal stress over the fillets and the mesh
cycle, from the LTCA's segment forces at the nominal torque (docs/fe.md). It is a local
notch stress: the stress concentration of the real fillet (ISO's Y_Fa·Y_Sa), the share of
the load each tooth carries (K_Fα, Y_ε, Y_LS) and its distribution along the face at the
case's misalignment (K_Fβ; Y_BS) are in it — the LTCA and the FE resolve what those factors
approximate. Not in it: the application factor K_A and the dynamic factor K_v (the LTCA is
quasi-static at the nominal torque). The criterion is therefore ISO 10300-3:2014's
(cl. 6, Method B1) with the factors applied once each::

    σ_F,FE = σ_FE,max · K_A · K_v
    S_F,FE = σ_FP / σ_F,FE,     σ_FP = σ_Flim · Y_ST · Y_NT · Y_δrelT · Y_RrelT · Y_X

(σ_FP as ``/rating`` stores it, without S_Fmin; its S_F = σ_FP/σ_F), judged against the
rating's S_Fmin: fail below it; where the rating rates a torque above its
``design_torque`` at long life, attention instead (a load of finite life, as the rating
check), unless σ_F,FE exceeds the static strength σ_FP·Y_NT,static/Y_NT (the bending S–N
curve's static end, ISO 6336-3 Table 2: 2.5 for case-hardened steel), which fails. K_Fβ,
K_Fα and the form factors are *not* applied to the FE stress (they are in it). The
permissible side keeps Y_δrelT, Y_RrelT, Y_X: they relate the real notch, roughness and
size to the test gear's, which σ_Flim·Y_ST is measured on.

Without ISO 10300's ``/rating`` (no rating, or another method's), the material's bending
endurance of the weaker member at ISO 6336-5 grade MQ is the permissible stress — σ_FE =
σ_Flim·Y_ST (850 MPa for the bundled case-carburised steel) with K_A = K_v = 1, Y_δrelT =
Y_RrelT = Y_X = 1 and no minimum safety, stated in the finding: attention above σ_FE (a
finite life), fail above the static strength σ_FE·Y_NT,static.

Where ``/ltca`` has no ``root_stress_max``, the check is listed as not made with why: the
root attribute ``root_stress_not_run`` (the step skipped, or the FE model failed) or "no
root stress in /ltca".

**Scuffing** (checks ``scuffing`` — in contact.study.verdicts — and ``scuffing_standard``).
The verdict judges the LTCA's S_B (``/scuffing_micropitting/scuffing_safety``: Blok's flash
temperature on every loaded segment of the LTCA, ISO/TS 6336-20's bulk and scuffing
temperatures) against 1: it is the one computed on the contact as it runs — the
localised pattern's peak pressure, its curvature and its sliding, the hypoid's lengthwise
sliding among it. The standard's method on ISO 10300's virtual cylindrical gears
(``/rating/flash_temperature``) spreads the load over b_v,eff and, as written, lacks the
lengthwise sliding; its ``lengthwise_sliding`` variant adds it (not a standard); their
uncertain constants (μ_m in ISO's or DIN 3990-4's form, θ_S with or without η^−0.05) give
a range. Neither is judged, but where either variant's S_B, or the low end of its range,
is below :data:`contact.study.verdicts.SCUFFING_MIN`, an attention finding says so, with
the judged S_B beside it (docs/scuffing_micropitting.md, docs/verdicts.md).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from geometry.core.text import plain_number

__all__ = ["CHECKS", "analysis_checks", "has_iso_rating", "member_names",
           "root_safety_severity", "root_stress_safety", "unchecked_reason"]

#: the checks of this module, in the order they are listed after contact.study.verdicts'
CHECKS = ("root_stress", "scuffing_standard")

#: ISO 6336-5 grade of the material fallback (contact.study.verdicts.GRADE)
_GRADE = "MQ"

#: how the findings name the standard's variants
_VARIANT_WORDS = {
    "standard": "ISO/TS 6336-20 on the ISO 10300 virtual cylindrical gears (the standard)",
    "lengthwise_sliding": "ISO/TS 6336-20 with the hypoid's lengthwise sliding (not a "
                          "standard)",
}


def _t(torque: float) -> str:
    return f"{plain_number(torque)} N·m"


def member_names(ds: xr.Dataset | xr.DataArray) -> list[str]:
    """The member names of a dataset's ``member`` axis: its ``member_label`` coordinate (a
    file read back), else ``member``, else pinion, gear."""
    if "member_label" in ds.coords:
        return [str(m) for m in ds["member_label"].values]
    if "member" in ds.coords:
        return [str(m) for m in ds["member"].values]
    return ["pinion", "gear"][:ds.sizes.get("member", 2)]


def has_iso_rating(rt: xr.Dataset | None) -> bool:
    """Whether a ``/rating`` dataset holds the ISO 10300 bending factors the FE root-stress
    check applies (σ_FP, K_A, K_v, S_Fmin; ISO 10300-3:2014 cl. 6)."""
    return rt is not None and {"sigma_FP", "K_A", "K_v", "S_Fmin"} <= set(rt.variables)


def _static_factor(lt: xr.Dataset, j: int) -> float:
    """Y_NT at the bending S–N curve's static end of member ``j``'s material (NaN where
    unknown)."""
    from contact.load_capacity.durability import sn_curves

    mat = lt.attrs.get(("material_pinion", "material_gear")[j] if j < 2 else "")
    if not mat:
        return float("nan")
    try:
        return float(sn_curves(str(mat), _GRADE)["bending"].static_life_factor)
    except Exception:  # a material the tables lack: no static distinction
        return float("nan")


def root_safety_severity(safety: float, minimum: float, torque: float, design_torque: float,
                         *, long_life: bool = True, above_static: bool = False) -> str | None:
    """The judgement of a root safety S_F,FE, one rule for ``ltca run`` and ``ltca
    duty-cycle`` (issue 71: the same design at the same torque, the same verdict).

    Parameters
    ----------
    safety : float — [1]
        S_F,FE = σ_FP / (σ_FE,max · K_A · K_v) (:func:`root_stress_safety`; in the duty
        cycle a bin's, at long life).
    minimum : float — [1]
        The rating's S_F,min (the case's ``[rating] min_safety_bending``, default 1.3).
    torque, design_torque : float — [N·m]
        The pinion torque judged and the rating's ``design_torque`` (NaN: every torque is
        a design torque).
    long_life : bool
        The permissible stress is at long life (Y_NT of the rating's knee or beyond).
    above_static : bool
        σ_FE,max · K_A · K_v exceeds the static strength (the bending S–N curve's static
        end): no life at any count of cycles.

    Returns
    -------
    {"fail", "attention"} or None
        None at or above the minimum (or a NaN safety: the caller says it is not checked);
        "fail" below it at the design torque or under, or above the static strength;
        "attention" below it above the design torque at long life — a load of finite life
        whose damage ``ltca duty-cycle`` counts.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (S_F ≥ S_F,min), the verdict's rule for a rated torque
    above the design torque (docs/verdicts.md); docs/duty_cycle.md ("The duty cycle's root
    safety against S_F,min").
    """
    if not (np.isfinite(safety) and safety < minimum):
        return None
    if above_static:
        return "fail"
    if long_life and torque > design_torque:
        return "attention"
    return "fail"


def root_stress_safety(root_stress_max: np.ndarray, rt: xr.Dataset) -> np.ndarray:
    """S_F,FE = σ_FP / (σ_FE,max · K_A · K_v) per (torque, member) (module docstring).

    Parameters
    ----------
    root_stress_max : (n_torque, n_member) array — [MPa]
        The FE peak root stress at the rating's torques.
    rt : xarray.Dataset
        The ISO 10300 ``/rating`` (``sigma_FP`` (member), ``K_A``, ``K_v`` (torque)).

    Returns
    -------
    (n_torque, n_member) array — [1]
    """
    k_a = float(rt["K_A"])
    k_v = np.broadcast_to(np.asarray(rt["K_v"].values, float).reshape(-1, 1)
                          if rt["K_v"].ndim else float(rt["K_v"]), root_stress_max.shape)
    fp = np.broadcast_to(np.asarray(rt["sigma_FP"].values, float), root_stress_max.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        return fp / (root_stress_max * k_a * k_v)


def _not_computed(rs: xr.DataArray, names: list[str], torques: np.ndarray,
                  values: np.ndarray) -> list:
    """An attention finding per member and torque whose root stress is NaN (not checked
    there), with the reason the root-stress step stored (``not_computed``,
    :func:`contact.ltca.root_stress.root_stress`)."""
    from contact.study.verdicts import Finding

    said = str(rs.attrs.get("not_computed", "")).splitlines()
    out = []
    for i, t in enumerate(torques):
        for j, m in enumerate(names):
            if np.isfinite(values[i, j]):
                continue
            why = next((line.split(": ", 1)[1] for line in said
                        # as root_stress writes it; a file of before round 19: "{t:g}"
                        if line.startswith((f"{m} at {plain_number(t)} N m:",
                                            f"{m} at {t:g} N m:"))), "no reason recorded")
            out.append(Finding("attention", "root_stress",
                               f"root stress of the {m} at {_t(t)} not checked: {why}"))
    return out


def _root_stress(lt: xr.Dataset, rt: xr.Dataset | None) -> list:
    from contact.study.verdicts import Finding

    rs = lt["root_stress_max"].transpose("torque", "member")
    level = rs.attrs.get("fe_level")  # a named cheaper FE model (absent: the default)
    fe = f"FE root stress ({level} level)" if level else "FE root stress"
    names = member_names(rs)
    torques = rs["torque"].values
    values = np.asarray(rs.values, float)
    out = _not_computed(rs, names, torques, values)
    if has_iso_rating(rt) and np.array_equal(rt["torque"].values, torques):
        safety = root_stress_safety(values, rt)
        smin = float(rt["S_Fmin"])
        design = float(rt["design_torque"]) if "design_torque" in rt else np.nan
        cycles = (np.asarray(rt["load_cycles"].values, float).ravel()
                  if "load_cycles" in rt else np.full(1, np.nan))
        y_nt = (np.atleast_1d(np.asarray(rt["Y_NT"].values, float)).reshape(-1)
                if "Y_NT" in rt else np.ones(1))
        k_a = float(rt["K_A"])
        for i, t in enumerate(torques):
            k_v = float(np.atleast_1d(rt["K_v"].values)[min(i, rt["K_v"].size - 1)])
            for j, m in enumerate(names):
                s = float(safety[i, j])
                long_life = not np.isfinite(cycles[j % cycles.size])
                if root_safety_severity(s, smin, float(t), design, long_life=long_life) is None:
                    continue  # at or above S_Fmin (the static strength only matters below)
                eff = values[i, j] * k_a * k_v
                fp = float(np.atleast_1d(rt["sigma_FP"].values)[j])
                ynt = float(y_nt[j % y_nt.size])
                static = fp * _static_factor(lt, j) / ynt
                above = bool(np.isfinite(static) and eff > static)
                severity = root_safety_severity(s, smin, float(t), design,
                                                long_life=long_life, above_static=above)
                reason = (f"{fe} of the {m} at {_t(t)}: {values[i, j]:.0f} MPa × "
                          f"K_A {k_a:g} × K_v {k_v:.3f} = {eff:.0f} MPa against σ_FP "
                          f"{fp:.0f} MPa (ISO 10300-3, σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X): "
                          f"S_F {s:.2f} below S_Fmin {smin:g}")
                if above:
                    out.append(Finding("fail", "root_stress",
                                       reason + f"; above the static strength {static:.0f} "
                                       "MPa (Y_NT at the S–N curve's static end): no life"))
                elif severity == "attention":
                    out.append(Finding("attention", "root_stress",
                                       reason + f" at long life: above the design torque "
                                       f"{_t(design)} a load of finite life (ltca duty-cycle "
                                       "counts the root damage)"))
                else:
                    out.append(Finding("fail", "root_stress", reason))
        return out
    # no ISO 10300 rating: the material's bending endurance (module docstring)
    from contact.load_capacity.durability import sn_curves

    mats = [lt.attrs.get(k) for k in ("material_pinion", "material_gear")][:len(names)]
    for j, m in enumerate(names):
        mat = mats[j] if j < len(mats) else None
        if not mat:
            continue
        curve = sn_curves(str(mat), _GRADE)["bending"]
        limit, static = curve.allowable, curve.allowable * curve.static_life_factor
        for i, t in enumerate(torques):
            x = values[i, j]
            if not np.isfinite(x) or x <= limit:
                continue
            bits = (f"{fe} of the {m} at {_t(t)}: {x:.0f} MPa (no ISO 10300 "
                    f"rating: K_A = K_v = 1, Y_δrelT = Y_RrelT = Y_X = 1) above")
            if x > static:
                out.append(Finding("fail", "root_stress",
                                   f"{bits} the static strength {static:.0f} MPa (σ_FE "
                                   f"{limit:.0f} MPa × Y_NT {curve.static_life_factor:g}, "
                                   f"{mat}, grade {_GRADE}): no life at this torque"))
            else:
                out.append(Finding("attention", "root_stress",
                                   f"{bits} σ_FE = σ_Flim·Y_ST {limit:.0f} MPa ({mat}, ISO "
                                   f"6336-5 grade {_GRADE}): beyond the bending endurance, a "
                                   "finite life at this torque (ltca duty-cycle counts the "
                                   "damage)"))
    return out


def _scuffing_standard(flash: xr.Dataset, judged: xr.Dataset | None) -> list:
    from contact.study.verdicts import SCUFFING_MIN, Finding

    out = []
    if "variant" in flash.dims:
        labels = (flash["variant_label"].values if "variant_label" in flash.coords
                  else flash["variant"].values if "variant" in flash.coords
                  else list(_VARIANT_WORDS)[:flash.sizes["variant"]])
        variants = [(str(v), flash.isel(variant=k)) for k, v in enumerate(labels)]
    else:
        variants = [(None, flash)]
    numbers = {v: [_safeties(one, i) for i in range(one.sizes["torque"])]
               for v, one in variants}
    for v, one in variants:
        what = _VARIANT_WORDS.get(v, "ISO/TS 6336-20 on the virtual cylindrical gears")
        for i, t in enumerate(one["torque"].values):
            s, lo, hi = numbers[v][i]
            if not (s < SCUFFING_MIN or lo < SCUFFING_MIN):
                continue
            if v != "standard" and _same(numbers.get("standard"), i, (s, lo, hi)):
                continue  # said once, on the standard's finding (no offset: no sliding)
            same = ("; its lengthwise-sliding variant (not a standard) gives the same "
                    "numbers (no offset)"
                    if v == "standard" and _same(numbers.get("lengthwise_sliding"), i,
                                                 (s, lo, hi)) else "")
            spread = (f" ({lo:.2f}–{hi:.2f} over its uncertain constants)"
                      if np.isfinite(lo) else "")
            if s < SCUFFING_MIN:
                head = f"{what} gives S_B {s:.2f}{spread} at {_t(t)}, below {SCUFFING_MIN:g}"
            else:
                head = (f"{what} gives S_B {s:.2f} at {_t(t)}, but its uncertain constants "
                        f"(μ_m's form, θ_S with η^−0.05) put it down to {lo:.2f}, below "
                        f"{SCUFFING_MIN:g}")
            beside = ""
            at = (np.flatnonzero(judged["torque"].values == t)
                  if judged is not None and "scuffing_safety" in judged else [])
            if len(at):
                sb = float(judged["scuffing_safety"].values[at[0]])
                if np.isfinite(sb):
                    beside = f"; the verdict judges the LTCA's S_B, {sb:.2f}"
            out.append(Finding("attention", "scuffing_standard",
                               head + same + beside + " (docs/verdicts.md, Scuffing)"))
    return out


def _safeties(one: xr.Dataset, i: int) -> tuple[float, float, float]:
    """(S_B, its low and high end) of one variant at the torque index ``i`` (NaN where
    the dataset gives no range)."""
    s = float(one["scuffing_safety"].values[i])
    lo = float(one["scuffing_safety_low"].values[i]) if "scuffing_safety_low" in one else np.nan
    hi = (float(one["scuffing_safety_high"].values[i]) if "scuffing_safety_high" in one
          else np.nan)
    return s, lo, hi


def _same(numbers: list | None, i: int, these: tuple[float, float, float]) -> bool:
    """Another variant's numbers at the torque index ``i`` equal ``these`` (to 1e-9
    relative; NaN equal to NaN): a spiral bevel's lengthwise-sliding variant is the
    standard's, line for line (issue 71, round 26d: an FH 18x22 listed the finding twice,
    the second naming "the hypoid's lengthwise sliding")."""
    if numbers is None or i >= len(numbers):
        return False
    return bool(np.allclose(numbers[i], these, rtol=1e-9, atol=0.0, equal_nan=True))


def analysis_checks(tree: xr.DataTree, lt: xr.Dataset | None, rt: xr.Dataset | None,
                    sm: xr.Dataset | None) -> tuple[list, list[str]]:
    """The findings and checks made of this module's checks on an analysis.

    Parameters
    ----------
    tree : xarray.DataTree
        The analysis.
    lt, rt, sm : xarray.Dataset or None
        Its ``/ltca``, ``/rating`` and ``/scuffing_micropitting`` groups.

    Returns
    -------
    (list of Finding, list of str)
        The findings and the checks made (:data:`CHECKS`).
    """
    findings: list = []
    checks: list[str] = []
    if lt is not None and "root_stress_max" in lt:
        checks.append("root_stress")
        findings += _root_stress(lt, rt)
    flash = None
    if "rating" in tree.children and "flash_temperature" in tree["rating"].children:
        flash = tree["rating/flash_temperature"].to_dataset()
    if flash is not None and "scuffing_safety" in flash:
        checks.append("scuffing_standard")
        findings += _scuffing_standard(flash, sm)
    return findings, checks


def unchecked_reason(tree: xr.DataTree, check: str) -> str:
    """Why ``check`` (:data:`CHECKS`) was not made on the analysis ``tree``."""
    attrs = getattr(tree, "attrs", {})
    if check == "root_stress":
        said = str(attrs.get("root_stress_not_run", ""))
        if "ltca" not in tree.children:
            return "no root stress: no /ltca group"
        if said.startswith("not requested"):
            return "no root stress: the chain skipped its step (--no-root-stress, steps)"
        if said:
            return f"no root stress: {said}"
        return "no root stress: /ltca has no root_stress_max"
    said = str(attrs.get("load_capacity_not_run", ""))
    if "rating" not in tree.children:
        return ("no /rating/flash_temperature: no /rating group"
                + (f" ({said})" if said else ""))
    if "friction" not in tree.children:
        return "no /rating/flash_temperature: the analysis ran without an efficiency stage"
    rating_attrs = tree["rating"].attrs
    why = str(rating_attrs.get("flash_temperature_not_run", ""))
    if why:
        return f"no /rating/flash_temperature: {why}"
    from contact.load_capacity.methods import METHODS

    method = str(rating_attrs.get("rating_method", ""))
    entry = METHODS.get(method)
    if entry is not None and "flash_temperature" in entry.companions:
        # the method computes it, and the chain records why where it could not: this
        # /rating was put in the tree without the chain's step (found on the gallery's
        # "own gear set" example, whose tree["rating"] = contact.iso10300_rating(...)
        # replaced the chain's rating and its flash temperature)
        return (f"no /rating/flash_temperature: this /rating ({method}) was not written by "
                "the analysis chain's rating step, which computes it beside the rating "
                "(contact.iso10300_rating rates only; run_analysis rates by default, or "
                "contact.chain.scuffing_flash_temperature(rating, friction))")
    return "no /rating/flash_temperature: the rating method gives no virtual gears for it"


def duty_bin_misalignment(ds: xr.Dataset, b: int) -> tuple[float, float, float, float] | None:
    """Duty bin ``b``'s misalignment (ΔE, ΔP, ΔG [mm], ΔΣ [deg]): the deflection table's
    at the bin's torque and the case's assembly misalignment, as the bin was analysed.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``/duty_cycle`` dataset (``delta_E``, ``delta_P``, ``delta_G`` [mm] and
        ``delta_Sigma`` [rad, or the unit its ``units`` attribute names] over ``bin``).
    b : int
        The bin's index.

    Returns
    -------
    tuple of float or None
        ΔE, ΔP, ΔG in mm and ΔΣ in degrees (as ``ltca run``'s ``--dSigma`` and the case
        files take it); None where the dataset holds no misalignment.

    Raises
    ------
    IndexError
        ``b`` outside the dataset's bins.

    Notes
    -----
    Source: :class:`contact.study.duty_cycle_inputs.DeflectionTable` (issue 71: a duty
    bin's stresses are of its deflection, the run's of the assembly's alone).
    """
    names = ("delta_E", "delta_P", "delta_G", "delta_Sigma")
    if not all(n in ds for n in names):
        return None
    d = [float(np.asarray(ds[n].values, float).reshape(-1)[b]) for n in names]
    if str(ds["delta_Sigma"].attrs.get("units", "rad")) == "rad":
        d[3] = float(np.degrees(d[3]))
    return d[0], d[1], d[2], d[3]
