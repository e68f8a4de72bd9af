"""Scuffing and micropitting of the loaded mesh from the chain's local contact.

The efficiency stage (:func:`friction.efficiency.efficiency_analysis`, the ``/friction``
dataset) gives every loaded contact segment its friction coefficient, film thickness,
sliding, entraining and surface speeds at the oil inlet temperature; the LTCA (``/ltca``)
its load per length, peak pressure, length, equivalent radius, kind (flank or edge) and
the members' materials. :func:`scuffing_micropitting` reads those two datasets, and only
them, and judges the two surface failures they decide (docs/scuffing_micropitting.md):

* scuffing: Blok's flash temperature of each segment's Hertzian band of friction heat
  μ p abs(V_s) shared by the two surfaces moving across the contact line
  (:mod:`contact.load_capacity.flash_temperature`), the contact temperature on ISO/TS
  6336-20's bulk temperature, and the safety S_B against the oil's FZG scuffing
  temperature;
* micropitting: the specific film thickness λ_GF = h_min/Ra with the film at the bulk
  temperature θ_M, and the safety S_λ = λ_GF,min/λ_GFP
  (:mod:`contact.load_capacity.micropitting`).

The result is the ``/scuffing_micropitting`` group of an analysis (:data:`GROUP`); files
written before issue 63 hold the same variables in ``/friction``
(:func:`scuffing_micropitting_of` reads either).

References
----------
Blok, H., "The flash temperature concept", Wear 6 (1963) 483–494.
ISO/TS 6336-20:2017 (ISO/TR 13989-1:2000), flash temperature method, Eq. (22), (23),
(99), (100).
ISO/TS 6336-22:2018 (ISO/TR 15144-1:2014), micropitting, Method B.
"""

from __future__ import annotations

import json
import logging
import math
import os
from typing import NamedTuple

import numpy as np
import xarray as xr

from contact.load_capacity.flash_temperature import (
    ScuffingConditions,
    base_oil_factor,
    blok_flash_temperature,
    bulk_temperature,
    scuffing_safety,
    scuffing_temperature,
)
from contact.load_capacity.micropitting import (
    GAUSSIAN_RA_PER_RQ,
    film_at_bulk_temperature,
    micropitting_safety,
    specific_film_thickness,
)
from friction.efficiency import loaded_segments, uncertified_as_nan
from friction.lubricant import Lubricant, load_lubricant, temperature_range
from geometry.core.conventions import coords_along, data_var, dataset
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.hertz import STEEL, contact_modulus
from geometry.core.materials import DEFAULT_MATERIAL, material

__all__ = ["GROUP", "scuffing_micropitting", "scuffing_micropitting_of"]

log = logging.getLogger(__name__)

#: the group of an analysis' DataTree that holds :func:`scuffing_micropitting`'s dataset
GROUP = "scuffing_micropitting"

#: what the two input datasets must hold
_NEEDED_LTCA = ("force", "load_per_length", "pressure_max", "segment_length",
                "equivalent_radius")
_NEEDED_FRICTION = ("friction_coefficient", "sliding_velocity", "rolling_velocity",
                    "slide_to_roll_total", "film_thickness", "surface_speed")
_NEEDED_ATTRS = ("lubricant", "inlet_temperature_degC", "roughness_rq_um")


def scuffing_micropitting(
    ltca: xr.Dataset,
    friction: xr.Dataset,
    *,
    lubricant: str | os.PathLike | Lubricant | None = None,
    scuffing: ScuffingConditions | None = None,
    youngs_modulus: float | None = None,
    poisson_ratio: float | None = None,
) -> xr.Dataset:
    """Flash and contact temperature, specific film thickness and the safeties against
    scuffing and micropitting of a loaded mesh, from the LTCA and efficiency datasets.

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset (:func:`contact.ltca.loaded_tca`): ``force`` [N],
        ``load_per_length`` [N/mm], ``pressure_max`` [MPa], ``segment_length`` and
        ``equivalent_radius`` [mm] over (torque, roll, pair, segment), optionally
        ``segment_kind`` (edge contacts apart), ``found`` (uncertified rolls), and the
        attributes ``material_pinion``, ``material_gear`` and ``options`` (E, ν).
    friction : xarray.Dataset
        The ``/friction`` dataset of the same LTCA
        (:func:`friction.efficiency.efficiency_analysis`): ``friction_coefficient`` [1],
        ``sliding_velocity``, ``rolling_velocity`` [m/s], ``slide_to_roll_total`` [1],
        ``film_thickness`` [µm] over (torque, roll, pair, segment), ``surface_speed``
        [m/s] over (member, torque, roll, pair, segment), and the attributes
        ``lubricant``, ``inlet_temperature_degC`` [degC] and ``roughness_rq_um`` [µm]
        (each flank's Rq as given: λ_GF's roughness).
    lubricant : str, path-like or friction.lubricant.Lubricant, optional
        The oil the efficiency stage ran (its FZG load stage, base oil and λ_GFP, and its
        viscosity at the bulk temperature); default the ``lubricant`` attribute of
        ``friction`` read as a bundled name (give the file when the oil came from one).
    scuffing : contact.load_capacity.flash_temperature.ScuffingConditions, optional
        Lubrication, meshing gears and structural factor; default
        ``ScuffingConditions()`` (dip lubrication, one mesh, X_W = 1).
    youngs_modulus, poisson_ratio : float, optional — [MPa], [1]
        Material of both members for the film at the bulk temperature; default the LTCA's
        own (its ``options`` attribute), else steel.

    Returns
    -------
    xarray.Dataset
        The ``/scuffing_micropitting`` group: over (``torque``, ``roll``, ``pair``,
        ``segment``) ``flash_temperature`` [K] (Blok, each member's effusivity from the
        material table), ``contact_temperature`` [degC] (bulk + flash) and
        ``specific_film_thickness`` [1] (λ_GF = h_min(θ_M)/Ra, Ra = √(2/π) Rq); over
        ``torque`` ``flash_temperature_mean`` [K] (length-weighted over the loaded flank
        segments and the mesh cycles: θ_flm), ``bulk_temperature`` [degC],
        ``flash_temperature_max`` [K], ``contact_temperature_max`` [degC],
        ``contact_temperature_max_edge`` [degC] (the edge contacts apart),
        ``specific_film_thickness_min`` and ``specific_film_thickness_min_inlet`` [1],
        ``scuffing_safety`` and ``micropitting_safety`` [1]; 0-d ``scuffing_temperature``
        [degC] and ``permissible_specific_film`` [1] of the oil. A safety the oil lacks
        the data for is NaN, the reason in the variable's ``comment``; torques with a roll
        position whose loaded contact has no certified solution are NaN (a comment says
        why), as in ``/friction``.

    Raises
    ------
    InputError
        A dataset lacks a variable or attribute above (named), or ``scuffing`` is not a
        ScuffingConditions.
    ModelUnavailableError
        The lubricant is neither bundled nor a file.

    Notes
    -----
    Blok (1937, 1963); ISO/TR 13989-1:2000 / ISO/TS 6336-20:2017 (bulk temperature
    Eq. (22)–(23), scuffing temperature Eq. (99), safety Eq. (100)); ISO/TR 15144-1:2014 /
    ISO/TS 6336-22:2018 (λ_GF with the film at θ_M, S_λ). Moved out of the efficiency stage
    in issue 63 with the same arithmetic: the values are those ``/friction`` held before.
    """
    _check_inputs(ltca, friction)
    cond = ScuffingConditions() if scuffing is None else scuffing
    if not isinstance(cond, ScuffingConditions):
        raise InputError("scuffing: must be a contact.load_capacity.flash_temperature."
                         f"ScuffingConditions or None, got {scuffing!r}")
    lub = lubricant if isinstance(lubricant, Lubricant) else load_lubricant(
        friction.attrs["lubricant"] if lubricant is None else lubricant)
    op = _Conditions(float(friction.attrs["inlet_temperature_degC"]),
                     float(friction.attrs["roughness_rq_um"]))
    seg = _contact(ltca, friction)
    e_prime = _effective_modulus(ltca, youngs_modulus, poisson_ratio)
    dur = _surface_durability(ltca, seg, lub, op, cond, e_prime)
    coords = coords_along(ltca, ("torque", "roll", "pair", "segment"))
    coords["member"] = ("member", ["pinion", "gear"], {"long_name": "gear pair member"})
    attrs = {
        "title": "scuffing and micropitting of the loaded mesh",
        "method": ("Blok's flash temperature on the LTCA's contact segments, ISO/TS 6336-20 "
                   "bulk and scuffing temperature, ISO/TS 6336-22 specific film thickness"),
        "lubricant": lub.name,
        "inlet_temperature_degC": op.temperature,
        "roughness_rq_um": op.roughness,
        **dur.attrs,
    }
    out = dataset(_durability_variables(dur, seg.loaded), coords, attrs)
    return uncertified_as_nan(out, ltca)


def scuffing_micropitting_of(tree) -> xr.Dataset | None:
    """The scuffing and micropitting dataset of an analysis: its ``/scuffing_micropitting``
    group, else (a file written before issue 63) its ``/friction`` group when that holds
    the variables, else None.

    Parameters
    ----------
    tree : xarray.DataTree
        An analysis (:func:`contact.run_analysis`, a file read back).

    Returns
    -------
    xarray.Dataset or None
    """
    if GROUP in tree.children:
        return tree[GROUP].to_dataset()
    if "friction" in tree.children and "scuffing_safety" in tree["friction"].variables:
        return tree["friction"].to_dataset()
    return None


class _Conditions(NamedTuple):
    """The efficiency stage's conditions the assessment needs."""

    temperature: float  # [degC] oil inlet temperature θ_oil
    roughness: float  # [µm] each flank's Rq as given (λ_GF's roughness)


class _Contact(NamedTuple):
    """The loaded contact segments, each array 1-D over them (n,) but ``loaded``."""

    loaded: np.ndarray  # (T, J, K, S) bool: force finite and > 0
    force: np.ndarray  # [N]
    load_per_length: np.ndarray  # [N/mm]
    pressure_max: np.ndarray  # [MPa]
    length: np.ndarray  # [mm]
    radius: np.ndarray  # [mm] equivalent radius across the contact line
    half_width: np.ndarray  # [mm] Hertzian half-width 2w/(π p_max)
    edge: np.ndarray  # bool: an edge contact (segment_kind not "curve")
    sliding_velocity: np.ndarray  # [m/s]
    rolling_velocity: np.ndarray  # [m/s] entraining, across the contact line
    slide_to_roll_total: np.ndarray  # [1] abs(V_s)/V_r
    pinion_speed_across: np.ndarray  # [m/s]
    gear_speed_across: np.ndarray  # [m/s]
    friction_coefficient: np.ndarray  # [1]
    film_thickness: np.ndarray  # [µm] h_min at the oil inlet temperature


def _check_inputs(ltca: xr.Dataset, friction: xr.Dataset) -> None:
    """Raise :class:`InputError` naming what the two datasets lack."""
    for name, ds, needed in (("ltca", ltca, _NEEDED_LTCA), ("friction", friction,
                                                            _NEEDED_FRICTION)):
        if not isinstance(ds, xr.Dataset):
            raise InputError(f"{name}: must be an xarray.Dataset (the /{name} group), got "
                             f"{type(ds).__name__}")
        missing = [n for n in needed if n not in ds.variables]
        if missing:
            raise InputError(f"{name}: dataset lacks {missing} (expected the /{name} group "
                             "of an analysis)")
    missing = [a for a in _NEEDED_ATTRS if a not in friction.attrs]
    if missing:
        raise InputError(f"friction: dataset lacks the attributes {missing} (expected "
                         "friction.efficiency.efficiency_analysis output)")
    if friction["friction_coefficient"].shape != ltca["force"].shape:
        raise InputError("friction: its (torque, roll, pair, segment) shape "
                         f"{friction['friction_coefficient'].shape} is not the LTCA's "
                         f"{ltca['force'].shape} (the /friction of another analysis?)")


def _contact(ltca: xr.Dataset, friction: xr.Dataset) -> _Contact:
    """The loaded segments (force finite and > 0) of ``ltca`` with their loads and
    geometry from ``ltca`` (:func:`friction.efficiency.loaded_segments`) and their
    friction, film and speeds from ``friction``."""
    seg = loaded_segments(ltca)
    loaded, shape = seg.loaded, seg.loaded.shape
    speed = friction["surface_speed"].transpose("member", ...).values

    def on(name: str) -> np.ndarray:
        return np.broadcast_to(friction[name].values, shape)[loaded]

    return _Contact(
        **seg._asdict(),
        sliding_velocity=on("sliding_velocity"),
        rolling_velocity=on("rolling_velocity"),
        slide_to_roll_total=on("slide_to_roll_total"),
        pinion_speed_across=speed[0][loaded],
        gear_speed_across=speed[1][loaded],
        friction_coefficient=on("friction_coefficient"),
        film_thickness=on("film_thickness"),
    )


def _scatter(values: np.ndarray, loaded: np.ndarray) -> np.ndarray:
    """Per-segment ``values`` of the loaded segments put back on the (T, J, K, S) grid of
    ``loaded``, NaN on the unloaded segments (same unit as ``values``)."""
    out = np.full(loaded.shape, np.nan)
    out[loaded] = values
    return out


def _effective_modulus(ltca: xr.Dataset, youngs_modulus: float | None,
                       poisson_ratio: float | None) -> float:
    """E′ = 2E* [MPa] of two members of the given material (each None: the LTCA's own,
    its ``options`` attribute, else steel), as the efficiency stage's film."""
    try:
        opts = json.loads(ltca.attrs["options"])
        e_mat, nu_mat = float(opts["youngs_modulus"]), float(opts["poisson_ratio"])
    except (KeyError, TypeError, ValueError):
        e_mat, nu_mat = STEEL
    e = e_mat if youngs_modulus is None else youngs_modulus
    nu = nu_mat if poisson_ratio is None else poisson_ratio
    return 2.0 * contact_modulus(e, nu, e, nu)


#: Péclet number below which the high-Péclet moving-source formula overestimates the
#: flash temperature (Jaeger 1942; Archard 1958/59 puts the high-speed regime at Pe > 5–10)
_PECLET_HIGH = 5.0


class _Durability(NamedTuple):
    """Flash and contact temperature, specific film thickness and the safeties of scuffing
    and micropitting: per segment arrays 1-D over the loaded segments (n,), per torque
    (T,)."""

    flash: np.ndarray  # (n,) [K] Blok's flash temperature
    contact: np.ndarray  # (n,) [degC] bulk + flash
    specific_film: np.ndarray  # (n,) [1] λ_GF = h_min / Ra
    flash_mean: np.ndarray  # (T,) [K] θ_flm over the loaded flank segments
    bulk: np.ndarray  # (T,) [degC] θ_M
    flash_max: np.ndarray  # (T,) [K] over the loaded flank segments
    contact_max: np.ndarray  # (T,) [degC] over the loaded flank segments
    contact_max_edge: np.ndarray  # (T,) [degC] over the loaded edge segments
    specific_film_min: np.ndarray  # (T,) [1] over the loaded flank segments, film at θ_M
    specific_film_min_inlet: np.ndarray  # (T,) [1] the same, film at the oil inlet
    scuffing_temperature: float  # [degC] θ_S of the oil (NaN: unknown)
    scuffing_safety: np.ndarray  # (T,) [1] S_B
    permissible_specific_film: float  # [1] λ_GFP of the oil (NaN: unknown)
    micropitting_safety: np.ndarray  # (T,) [1] S_λ
    comments: dict  # variable name → its ``comment`` (how it was made, or why NaN)
    attrs: dict  # the assessment's inputs, as dataset attributes


def _surface_durability(ltca: xr.Dataset, seg: _Contact, lub: Lubricant, op: _Conditions,
                        cond: ScuffingConditions, e_prime: float) -> _Durability:
    """Blok's flash temperature [K] of each loaded segment (μ p abs(V_s) over the Hertzian
    band, each member's surface speed across the line and effusivity), the bulk [degC]
    and contact temperature [degC], the specific film thickness λ_GF = h_min/Ra [1] with
    the film at the bulk temperature θ_M (ISO/TS 6336-22; E′ [MPa] for that film), their
    extremes per torque over the loaded flank segments and the safeties against scuffing
    and micropitting [1] (NaN, with the reason in ``comments``, where the oil lacks the
    data; :mod:`contact.load_capacity.flash_temperature`,
    :mod:`contact.load_capacity.micropitting`)."""
    n_torque = seg.loaded.shape[0]
    torque_of = np.nonzero(seg.loaded)[0]  # the torque index of each loaded segment
    comments: dict[str, str] = {}
    names = [str(ltca.attrs.get(f"material_{m}", DEFAULT_MATERIAL)) for m in ("pinion", "gear")]
    flash = np.full(seg.force.shape, np.nan)
    try:
        effusivity = [material(n).thermal_effusivity for n in names]
        diffusivity = [_thermal_diffusivity(material(n)) for n in names]
    except ModelUnavailableError as exc:
        effusivity = diffusivity = [math.nan, math.nan]
        comments["flash_temperature"] = f"NaN: no thermal properties of the material ({exc})"
        log.info("flash temperature not computed: %s", exc)
    mu, vs = seg.friction_coefficient, seg.sliding_velocity
    v_p, v_g = seg.pinion_speed_across, seg.gear_speed_across
    good = (np.isfinite(mu) & np.isfinite(seg.pressure_max) & np.isfinite(seg.half_width)
            & np.isfinite(vs) & np.isfinite(v_p) & np.isfinite(v_g))
    if math.isfinite(effusivity[0]) and good.any():
        flash[good] = blok_flash_temperature(
            mu[good], seg.pressure_max[good], seg.half_width[good],
            vs[good], v_p[good], v_g[good], effusivity[0], effusivity[1])
        comments["flash_temperature"] = _peclet_comment(seg, effusivity, diffusivity)
    flank = ~seg.edge
    flash_mean = np.full(n_torque, np.nan)
    flash_max = np.full(n_torque, np.nan)
    flash_max_edge = np.full(n_torque, np.nan)
    for i in range(n_torque):
        here = (torque_of == i) & np.isfinite(flash)
        on_flank = here & flank
        length = float(np.sum(seg.length[on_flank]))
        if on_flank.any() and length > 0.0:
            flash_mean[i] = float(np.sum(flash[on_flank] * seg.length[on_flank])) / length
            flash_max[i] = float(np.max(flash[on_flank]))
        if (here & seg.edge).any():
            flash_max_edge[i] = float(np.max(flash[here & seg.edge]))
    bulk = np.full(n_torque, np.nan)
    known = np.isfinite(flash_mean)
    if known.any():
        bulk[known] = bulk_temperature(op.temperature, flash_mean[known], cond)
    contact = bulk[torque_of] + flash
    contact_max, contact_max_edge = bulk + flash_max, bulk + flash_max_edge
    theta_s, s_b = _scuffing(lub, op, cond, contact_max, comments)
    # ISO/TS 6336-22: the film at the bulk temperature θ_M (NaN where θ_M is unknown)
    h_bulk = np.full(seg.film_thickness.shape, np.nan)
    at = np.isfinite(bulk[torque_of])
    # a bulk temperature beyond the oil's data (a hot, rough mesh: B at 100 degC, Rq 0.8 um
    # reaches 142 degC) leaves lambda_GF NaN with the reason, never a failed analysis
    t_lo, t_hi = temperature_range(lub)
    at &= (bulk[torque_of] >= t_lo) & (bulk[torque_of] <= t_hi)
    if at.any():
        h_bulk[at] = film_at_bulk_temperature(
            lub, bulk[torque_of][at], seg.rolling_velocity[at], seg.load_per_length[at],
            seg.radius[at], seg.pressure_max[at], seg.slide_to_roll_total[at], e_prime)
    lam = np.asarray(specific_film_thickness(h_bulk, op.roughness, op.roughness),
                     float).reshape(seg.film_thickness.shape)
    lam_inlet = np.asarray(specific_film_thickness(seg.film_thickness, op.roughness,
                                                   op.roughness), float).reshape(lam.shape)
    lam_min, lam_min_inlet = np.full(n_torque, np.nan), np.full(n_torque, np.nan)
    for i in range(n_torque):
        m = (torque_of == i) & flank & np.isfinite(lam)
        if m.any():
            lam_min[i] = float(np.min(lam[m]))
        m = (torque_of == i) & flank & np.isfinite(lam_inlet)
        if m.any():
            lam_min_inlet[i] = float(np.min(lam_inlet[m]))
    comments["specific_film_thickness"] = (
        "lambda_GF = h_min(theta_M) / Ra: film at the bulk temperature theta_M (ISO/TS "
        "6336-22's temperature; the toolkit's Dowson-Higginson film with Gupta's thermal "
        "factor, not ISO's h_Y), Ra = sqrt(2/pi) Rq = "
        f"{GAUSSIAN_RA_PER_RQ * op.roughness:.3g} um of both flanks (Rq {op.roughness:g} "
        "um, Gaussian heights)"
        + ("" if at.all() else "; NaN where theta_M is unknown (no flash temperature) or "
           "beyond the oil's data range (no film there)"))
    perm = lub.permissible_specific_film
    if perm is None:
        s_l = np.full(n_torque, np.nan)
        comments["micropitting_safety"] = (
            f"NaN: the oil {lub.name} gives no permissible_specific_film (lambda_GFP of its "
            "FVA 54 micropitting test; an optional oil-file field of friction.lubricant)")
        log.info("micropitting safety not computed: %s", comments["micropitting_safety"])
        perm_value = math.nan
    else:
        perm_value = float(perm)
        s_l = np.asarray(micropitting_safety(lam_min, perm_value), float).reshape(n_torque)
        comments["micropitting_safety"] = (
            f"S_lambda = lambda_GF,min / lambda_GFP, lambda_GFP = {perm_value:g} of the oil "
            f"{lub.name} (its source: the attribute durability_source); lambda_GF,min over "
            "the loaded flank segments")
    attrs = {
        "scuffing_lubrication": cond.lubrication,
        "scuffing_meshing_gears": cond.meshing_gears,
        "scuffing_structural_factor": cond.structural_factor,
        "material_pinion": names[0],
        "material_gear": names[1],
        # [W s^0.5 / (m^2 K)]; CF 1.8 §2.3: attribute names of letters, digits, underscores
        "effusivity_pinion_W_s05_per_m2_K": float(effusivity[0]),
        "effusivity_gear_W_s05_per_m2_K": float(effusivity[1]),
        "fzg_load_stage": math.nan if lub.fzg_load_stage is None else float(lub.fzg_load_stage),
        "base_oil": lub.base_oil or "",
        "durability_source": lub.durability_source,
    }
    return _Durability(flash, contact, lam, flash_mean, bulk, flash_max, contact_max,
                       contact_max_edge, lam_min, lam_min_inlet, theta_s, s_b, perm_value,
                       s_l, comments, attrs)


def _scuffing(lub: Lubricant, op: _Conditions, cond: ScuffingConditions,
              contact_max: np.ndarray, comments: dict) -> tuple[float, np.ndarray]:
    """The oil's scuffing temperature θ_S [degC] and the safety S_B [1] per torque of the
    peak contact temperatures ``contact_max`` [degC]; NaN with the reason in
    ``comments["scuffing_safety"]`` where the oil lacks its FZG load stage or base oil."""
    missing = [k for k in ("fzg_load_stage", "base_oil") if getattr(lub, k) is None]
    if missing:
        comments["scuffing_safety"] = (
            f"NaN: the oil {lub.name} gives no {' and no '.join(missing)} (optional oil-file "
            "fields of friction.lubricant), so no scuffing temperature")
        log.info("scuffing safety not computed: %s", comments["scuffing_safety"])
        return math.nan, np.full(contact_max.shape, np.nan)
    x_l = base_oil_factor(lub.base_oil)  # θ_S has no viscosity term (ISO/TR 13989-1)
    theta_s = scuffing_temperature(lub.fzg_load_stage, x_l, cond.structural_factor)
    if theta_s <= op.temperature:
        comments["scuffing_safety"] = (
            f"NaN: the scuffing temperature {theta_s:.0f} degC of the oil {lub.name} is not "
            f"above the oil temperature {op.temperature:g} degC")
        log.info("scuffing safety not computed: %s", comments["scuffing_safety"])
        return theta_s, np.full(contact_max.shape, np.nan)
    rise = contact_max - op.temperature
    s_b = np.full(contact_max.shape, np.nan)
    ok = np.isfinite(rise) & (rise > 0.0)
    if ok.any():
        s_b[ok] = scuffing_safety(theta_s, contact_max[ok], op.temperature)
    s_b[np.isfinite(rise) & (rise <= 0.0)] = np.inf  # no temperature rise: nothing to scuff
    if not np.isfinite(rise).any():
        comments["scuffing_safety"] = (
            f"NaN: no peak contact temperature of the flanks (theta_S {theta_s:.1f} degC; "
            "see the comment of flash_temperature)")
        log.info("scuffing safety not computed: %s", comments["scuffing_safety"])
        return theta_s, s_b
    comments["scuffing_safety"] = (
        f"S_B = (theta_S - theta_oil) / (theta_Bmax - theta_oil), theta_S = {theta_s:.1f} degC "
        f"= 80 + (0.85 + 1.4 X_W) X_L S_FZG^2 with S_FZG {lub.fzg_load_stage:g}, X_L "
        f"{x_l:g} (the {lub.base_oil} base oil's), X_W "
        f"{cond.structural_factor:g} (ISO/TS 6336-20); theta_Bmax over the loaded flank "
        "segments; the oil's data and its source: the attributes fzg_load_stage, base_oil, "
        "durability_source")
    return theta_s, s_b


def _thermal_diffusivity(mat) -> float:
    """κ = k/(ρc) [m²/s] of a material's ``thermal`` group (validated by its
    ``thermal_effusivity``)."""
    g = mat.groups["thermal"]
    return float(g["thermal_conductivity"]) / (float(g["density"]) * float(g["specific_heat"]))


def _peclet_comment(seg: _Contact, effusivity: list, diffusivity: list) -> str:
    """What the ``flash_temperature`` variable is, and where its high-Péclet model is
    stretched: the loaded flank and edge segments at which the surface taking most of the
    heat has Pe = v b/(2κ) < 5 (there the formula overestimates the flash temperature)."""
    share_p = effusivity[0] * np.sqrt(seg.pinion_speed_across)
    share_g = effusivity[1] * np.sqrt(seg.gear_speed_across)
    pe = np.where(share_p >= share_g,
                  seg.pinion_speed_across * seg.half_width * 1e-3 / (2.0 * diffusivity[0]),
                  seg.gear_speed_across * seg.half_width * 1e-3 / (2.0 * diffusivity[1]))
    parts = []
    for name, mask in (("flank", ~seg.edge), ("edge", seg.edge)):
        m = mask & np.isfinite(pe)
        if m.any():
            low = m & (pe < _PECLET_HIGH)
            parts.append(f"{int(low.sum())} of {int(m.sum())} loaded {name} segments (least "
                         f"Pe {float(np.min(pe[m])):.2g})")
    return ("Blok: Hertzian band source mu p abs(V_s) shared by both surfaces moving across the "
            "contact line (Jaeger's moving source at high Peclet number); Pe = v b / (2 kappa) "
            f"of the surface taking most of the heat is below {_PECLET_HIGH:g}, where the "
            "formula overestimates, at " + " and ".join(parts))


def _durability_variables(dur: _Durability, loaded: np.ndarray) -> dict[str, tuple]:
    """The variables of the scuffing and micropitting dataset (see
    :func:`scuffing_micropitting`), each with its ``comment`` where one was made."""
    dims4 = ("torque", "roll", "pair", "segment")
    c = dur.comments

    def note(name: str) -> dict:
        return {"comment": c[name]} if name in c else {}

    return {
        "flash_temperature": data_var(
            dims4, _scatter(dur.flash, loaded), "K",
            "flash temperature (Blok, Hertzian band of friction heat)",
            **note("flash_temperature")),
        "contact_temperature": data_var(
            dims4, _scatter(dur.contact, loaded), "degC",
            "contact temperature: bulk temperature + flash temperature"),
        "specific_film_thickness": data_var(
            dims4, _scatter(dur.specific_film, loaded), "1",
            "specific film thickness lambda_GF = h_min / Ra, film at the bulk temperature "
            "theta_M (ISO/TS 6336-22)", film_temperature="bulk temperature theta_M",
            **note("specific_film_thickness")),
        "flash_temperature_mean": data_var(
            ("torque",), dur.flash_mean, "K",
            "mean flash temperature over the loaded flank segments and the mesh cycles "
            "(length-weighted)"),
        "bulk_temperature": data_var(
            ("torque",), dur.bulk, "degC",
            "bulk temperature theta_oil + 0.47 X_S X_mp theta_flm (ISO/TS 6336-20)"),
        "flash_temperature_max": data_var(
            ("torque",), dur.flash_max, "K",
            "peak flash temperature over the loaded flank segments and the mesh cycles"),
        "contact_temperature_max": data_var(
            ("torque",), dur.contact_max, "degC",
            "peak contact temperature over the loaded flank segments and the mesh cycles"),
        "contact_temperature_max_edge": data_var(
            ("torque",), dur.contact_max_edge, "degC",
            "peak contact temperature of the edge contacts (moving-source formula at low "
            "Peclet number: an overestimate)"),
        "specific_film_thickness_min": data_var(
            ("torque",), dur.specific_film_min, "1",
            "least specific film thickness over the loaded flank segments and the mesh "
            "cycles, film at the bulk temperature theta_M (ISO/TS 6336-22)",
            film_temperature="bulk temperature theta_M"),
        "specific_film_thickness_min_inlet": data_var(
            ("torque",), dur.specific_film_min_inlet, "1",
            "least specific film thickness with the film at the oil inlet temperature (the "
            "friction stage's film; for comparison, not ISO/TS 6336-22's)",
            film_temperature="oil inlet temperature"),
        "scuffing_temperature": data_var(
            (), dur.scuffing_temperature, "degC",
            "scuffing temperature of the oil from its FZG load stage (ISO/TS 6336-20)"),
        "scuffing_safety": data_var(
            ("torque",), dur.scuffing_safety, "1",
            "scuffing safety factor S_B (flash temperature method)", **note("scuffing_safety")),
        "permissible_specific_film": data_var(
            (), dur.permissible_specific_film, "1",
            "permissible specific film thickness lambda_GFP of the oil (ISO/TS 6336-22)"),
        "micropitting_safety": data_var(
            ("torque",), dur.micropitting_safety, "1",
            "safety factor against micropitting S_lambda = lambda_GF,min / lambda_GFP",
            **note("micropitting_safety")),
    }
