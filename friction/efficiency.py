"""Mechanical power loss and efficiency of a loaded mesh (seed §5.2, Eq. 5.7–5.14).

For every loaded contact segment of an LTCA (the ``/ltca`` dataset of
:func:`contact.ltca.loaded_tca`) at a pinion speed and an oil inlet temperature:

1. kinematics (:func:`friction.kinematics.surface_velocities`): sliding speed V_s,
   entraining speed V_r across the contact line, slide-to-roll ratio SR;
2. lubricant (:mod:`friction.lubricant`): η₀, α at the inlet temperature, β, k;
3. film (:mod:`friction.film`): h_min (Dowson–Higginson, Gupta thermal factor) and the
   lambda ratio λ = h_min/σ with σ = √(Rq₁² + Rq₂²);
4. friction coefficient μ by a registered model (:mod:`friction.coefficient`), with the
   thermal factor φ_T and the oil's film-traction properties for the models that use
   them (``mixed_ehl``; the boundary friction μ_b at the inlet temperature, a measured
   table's interpolated there), and a per-segment flag where the model is extrapolated;
5. losses: sliding P_s = μ F V_s, rolling P_r = F_R L V_r with F_R the Goksem–Hargreaves
   rolling traction per length (:mod:`friction.rolling`);
6. per roll position the instantaneous power loss and efficiency
   η = 1 − (ΣP_s + ΣP_r)/P_in, P_in = T_p ω_p; their mean over the mesh cycles.

Scuffing and micropitting of the same local contact (flash and contact temperature,
specific film thickness, their safeties) are load capacity, not friction: the chain's
load-capacity step computes them from this dataset and ``/ltca``
(``contact.load_capacity.scuffing_micropitting``, docs/scuffing_micropitting.md); this
stage gives the inputs they need (μ, film, speeds, each flank's speed across the line).

Bookkeeping identities hold by construction and are tested: each segment's sliding loss
is μ·F·V_s, totals are sums.
"""

from __future__ import annotations

import dataclasses
import inspect
import json
import logging
import math
import warnings
from typing import NamedTuple

import numpy as np
import xarray as xr

from friction.coefficient import (
    MU_CAP,
    FrictionModelLike,
    FrictionModelRangeWarning,
    friction_coefficient,
    friction_model_validity,
    get_friction_model,
)
from friction.film import (
    composite_roughness,
    lambda_ratio,
    minimum_film_thickness,
    thermal_loading,
    thermal_reduction_factor,
)
from friction.kinematics import surface_velocities
from friction.lubricant import (
    Lubricant,
    boundary_friction_coefficient,
    boundary_friction_source,
    load_lubricant,
    pressure_viscosity_coefficient,
    temperature_range,
    temperature_viscosity_coefficient,
    thermal_conductivity,
    viscosity,
)
from friction.operating import OperatingConditions
from friction.rolling import rolling_traction
from geometry.core.conventions import binary_flag, coords_along, data_var, dataset
from geometry.core.errors import InputError
from geometry.core.hertz import STEEL, contact_modulus
from geometry.core.text import plain_number

__all__ = ["LoadedSegments", "efficiency_analysis", "extrapolated_segments",
           "extrapolation_summary", "loaded_segments", "uncertified_as_nan"]

log = logging.getLogger(__name__)


def _material(ltca: xr.Dataset) -> tuple[float, float]:
    """(E [MPa], ν [1]) the LTCA ran with: its ``options`` attribute, else steel."""
    try:
        opts = json.loads(ltca.attrs["options"])
        return float(opts["youngs_modulus"]), float(opts["poisson_ratio"])
    except (KeyError, TypeError, ValueError):
        return STEEL


def efficiency_analysis(
    ltca: xr.Dataset,
    operating: OperatingConditions | None = None,
    *,
    pinion_speed: float | None = None,
    lubricant: str | None = None,
    temperature: float | None = None,
    roughness: float | None = None,
    friction_model: str | None = None,
    youngs_modulus: float | None = None,
    poisson_ratio: float | None = None,
) -> xr.Dataset:
    """Friction, power loss and mechanical efficiency of an LTCA result (seed ch. 5).

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset (needs ``force``, ``load_per_length``, ``pressure_max``,
        ``segment_length``, ``equivalent_radius``, ``contact_point``, ``contact_normal``,
        ``contact_tangent`` and the axes in its attributes).
    operating : friction.operating.OperatingConditions, optional
        Pinion speed, lubricant, inlet temperature, roughness and friction model; default
        ``OperatingConditions()`` (1500 rpm, 75W90 at 90 °C, Rq 0.8 µm, kolivand2009).
    pinion_speed : float, optional — [rpm], > 0
    lubricant : str, optional
        Bundled oil name or TOML path (:func:`friction.lubricant.load_lubricant`).
    temperature : float, optional — [degC] oil inlet temperature
    roughness : float, optional — [µm] RMS roughness Rq of each surface (> 0)
    friction_model : str, optional
        A registered friction model.
        These five override the fields of ``operating`` of the same names (None: keep).
    youngs_modulus, poisson_ratio : float, optional — [MPa], [1]
        Material of both members; default the LTCA's own (the ``options`` attribute of
        ``ltca``), else steel (:data:`geometry.core.hertz.STEEL`).

    Returns
    -------
    xarray.Dataset
        The ``/friction`` dataset: over (``torque``, ``roll``, ``pair``, ``segment``)
        ``sliding_velocity``, ``rolling_velocity`` [m/s], ``slide_to_roll`` [1] (signed,
        across the contact line), ``slide_to_roll_total`` [1] (abs(V_s)/V_r: the friction
        model's and the thermal factors' SR),
        ``film_thickness`` [µm], ``lambda_ratio`` [1], ``friction_coefficient`` [1],
        ``sliding_loss``, ``rolling_loss`` [W]; over (``torque``, ``roll``)
        ``power_loss`` [W] and ``efficiency`` [1]; over ``torque`` the cycle means
        ``power_loss_mean`` [W] and ``efficiency_mean`` [1]. Inputs outside a model's
        fitted range are logged (INFO) and listed in the ``model_range_warnings`` attribute;
        the segments concerned are flagged per segment in ``friction_model_extrapolated``
        (int8 0/1, CF ``flag_values``/``flag_meanings``). For a model that takes the
        oil's boundary friction (``mixed_ehl``) the attributes ``boundary_friction`` [1]
        — μ_b of the asperity junctions as the model used it, the oil's evaluated at the
        inlet temperature (:func:`friction.lubricant.boundary_friction_coefficient`; no
        flash temperature) — and ``boundary_friction_source`` (the oil file's table or
        constant and its source); an inlet temperature outside the oil's measured
        μ_b table holds μ_b at the table's end value and flags every loaded segment,
        the range warning saying why.

        Over (``member``, ``torque``, ``roll``, ``pair``, ``segment``)
        ``surface_speed`` [m/s], each flank's speed across the contact line (through the
        Hertzian band: the speeds of Blok's flash temperature, which the load-capacity
        step computes from this dataset). Roll positions whose loaded contact has no
        certified solution (``ltca["found"]`` 0) have NaN values over (torque, roll), and
        their torques NaN values over torque (a comment says why): no contact forces, no
        efficiency (never a loss-free 100 %).

    Raises
    ------
    InputError
        Missing variables, or operating conditions or material out of range (the message
        names the field).
    ModelUnavailableError
        An unknown lubricant or friction model.

    Notes
    -----
    Seed §5.2, Eq. 5.7–5.14; the EHL groups are written in the effective modulus
    E′ = 2E* (Dowson & Higginson), E* of :func:`geometry.core.hertz.contact_modulus`.
    Scuffing and micropitting of the same contact are the load-capacity step's
    (``contact.load_capacity.scuffing_micropitting``, from this dataset and ``/ltca``).
    """
    _check_variables(ltca)
    op = _operating_conditions(
        operating,
        pinion_speed=pinion_speed,
        lubricant=lubricant,
        temperature=temperature,
        roughness=roughness,
        friction_model=friction_model,
    )
    e_prime = _effective_modulus(ltca, youngs_modulus, poisson_ratio)
    oil = _oil_at_inlet(op.oil(), op.temperature)
    # the film and μ on the flanks' roughness in their surface state (run-in by default,
    # friction.operating.RUNNING_IN_FACTORS); λ_GF of the durability checks on Rq as given
    rq = op.effective_roughness
    sigma = float(composite_roughness(rq, rq))
    seg = _loaded_segments(ltca, op.pinion_speed)
    fric = _film_and_friction(seg, oil, e_prime, sigma, op)
    for note in fric.range_warnings:
        log.info("%s", note)
    losses = _power_losses(seg, fric, ltca.variables["torque"].values, op.pinion_speed)
    return uncertified_as_nan(_friction_dataset(ltca, seg, fric, losses, op, oil), ltca)


def uncertified_as_nan(friction: xr.Dataset, ltca: xr.Dataset) -> xr.Dataset:
    """A stage's dataset with its values over (torque, roll) NaN at the roll positions whose
    loaded contact has no certified solution (``ltca["found"]`` 0), and its values over
    torque NaN at the torques with such a roll, each with a ``comment`` saying why.

    A roll without a certified contact solution has no forces (NaN, read as 0 by the
    power loss): its efficiency would be a loss-free 100 %, not a result; the means over
    the mesh cycle are NaN as the LTE summary is (:mod:`contact.ltca.dataset`).

    Parameters
    ----------
    friction : xarray.Dataset
        A dataset over (torque, roll, …) made from ``ltca`` (``/friction``, the
        load-capacity step's scuffing and micropitting).
    ltca : xarray.Dataset
        The ``/ltca`` dataset, with ``found`` (torque, roll) where it was written.

    Returns
    -------
    xarray.Dataset
        ``friction`` itself when every roll is certified (or ``found`` is absent), else a
        copy with those values NaN.
    """
    if "found" not in ltca.variables:
        return friction
    found = np.asarray(ltca.variables["found"].values) > 0
    if found.all():
        return friction
    torques = np.asarray(ltca.variables["torque"].values, float)
    some = ~found.all(axis=1)
    where = ", ".join(f"T_p {plain_number(t)} N m ({int((~found[i]).sum())} of {found.shape[1]})"
                      for i, t in enumerate(torques) if some[i])
    why = (f"NaN where the loaded contact has no certified solution (roll positions of {where}; "
           "/ltca/found, /ltca/status): no efficiency, temperature or safety without contact "
           "forces")
    out = friction.copy()
    for name, var in friction.data_vars.items():
        if var.dims == ("torque", "roll"):
            values = np.where(found, var.values, np.nan)
        elif var.dims == ("torque",) and np.issubdtype(var.dtype, np.floating):
            values = np.where(some, np.nan, var.values)
        else:
            continue
        out[name] = var.copy(data=values).assign_attrs(comment=why)
    return out


_NEEDED = (
    "force",
    "load_per_length",
    "pressure_max",
    "segment_length",
    "equivalent_radius",
    "contact_point",
    "contact_normal",
    "contact_tangent",
)


def _check_variables(ltca: xr.Dataset) -> None:
    """Raise :class:`InputError` naming the variables of ``_NEEDED`` that ``ltca`` lacks."""
    missing = [n for n in _NEEDED if n not in ltca.variables]
    if missing:
        raise InputError(f"ltca: dataset lacks {missing} (expected contact.ltca.loaded_tca output)")


def _operating_conditions(
    operating: OperatingConditions | None, **overrides: float | str | None
) -> OperatingConditions:
    """The operating conditions of the analysis: ``operating`` (default
    ``OperatingConditions()``) with the fields of ``overrides`` that are not None replaced,
    and so validated again on construction (speed [rpm], temperature [degC], Rq [µm])."""
    op = OperatingConditions() if operating is None else operating
    given = {k: v for k, v in overrides.items() if v is not None}
    if given:
        op = dataclasses.replace(op, **given)  # validated again on construction
    return op


def _effective_modulus(
    ltca: xr.Dataset, youngs_modulus: float | None, poisson_ratio: float | None
) -> float:
    """E′ = 2E* [MPa], the Dowson–Higginson modulus the EHL groups of :mod:`friction.film`
    are written in, of two members of the given material (E [MPa], ν [1]; each None: the
    LTCA's own, :func:`_material`)."""
    e_mat, nu_mat = _material(ltca)
    youngs_modulus = e_mat if youngs_modulus is None else youngs_modulus
    poisson_ratio = nu_mat if poisson_ratio is None else poisson_ratio
    return 2.0 * contact_modulus(youngs_modulus, poisson_ratio, youngs_modulus, poisson_ratio)


class _Oil(NamedTuple):
    """The lubricant's properties at the oil inlet temperature."""

    name: str
    viscosity: float  # η₀ [Pa s]
    pressure_viscosity: float  # α [1/GPa]
    temperature_viscosity: float  # β [1/K]
    thermal_conductivity: float  # k [W/(m K)]
    traction: dict  # the oil's film-traction parameters that are set (mixed_ehl), by name
    lubricant: Lubricant  # the oil as read (its surface-durability fields among them)
    # why μ_b is held at its table's end value (the range warning); empty: measured there
    boundary_friction_notes: list[str]


def _oil_at_inlet(lubricant, temperature: float) -> _Oil:
    """Name, η₀ [Pa s], α [1/GPa], β [1/K], k [W/(m K)] and the film-traction parameters
    of the lubricant (bundled name, TOML path or the oil read) at the inlet temperature [degC] — the
    boundary friction μ_b [1] too, a table's interpolated there
    (:func:`friction.lubricant.boundary_friction_coefficient`; no flash temperature), with
    the range warning where it lies outside the table's measured range."""
    oil = load_lubricant(lubricant)
    traction = {k: getattr(oil, k) for k in ("eyring_stress", "limiting_shear_coefficient")
                if getattr(oil, k) is not None}
    notes: list[str] = []
    if oil.boundary_friction is not None:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", FrictionModelRangeWarning)
            traction["boundary_friction"] = float(boundary_friction_coefficient(oil, temperature))
        notes = sorted({str(w.message) for w in caught
                        if issubclass(w.category, FrictionModelRangeWarning)})
    return _Oil(
        oil.name,
        float(viscosity(oil, temperature)),
        float(pressure_viscosity_coefficient(oil, temperature)),
        float(temperature_viscosity_coefficient(oil, temperature)),
        float(thermal_conductivity(oil, temperature)),
        traction,
        oil,
        notes,
    )


def _boundary_friction_used(oil: _Oil, model: FrictionModelLike) -> tuple[float, str] | None:
    """The boundary friction μ_b [1] the friction model ``model`` ran with and where it
    comes from — the oil's at the inlet temperature, else the model's own default —; None
    for a model that takes no ``boundary_friction``."""
    fm = get_friction_model(model)
    if "boundary_friction" not in fm.optional:
        return None
    if "boundary_friction" in oil.traction:
        return oil.traction["boundary_friction"], boundary_friction_source(oil.lubricant)
    default = inspect.signature(fm.function).parameters["boundary_friction"].default
    if isinstance(default, bool) or not isinstance(default, (int, float)):
        return None  # a plug-in's own default that is not a number: nothing to record
    return float(default), (f"the default of the friction model {fm.name!r} (the oil "
                            f"{oil.name!r} gives no boundary_friction)")


class _Segments(NamedTuple):
    """The loaded contact segments of an LTCA, each array 1-D over them (n,)."""

    loaded: np.ndarray  # (T, J, K, S) bool: force finite and > 0
    force: np.ndarray  # [N]
    load_per_length: np.ndarray  # [N/mm]
    pressure_max: np.ndarray  # [MPa]
    length: np.ndarray  # [mm]
    radius: np.ndarray  # [mm] equivalent radius across the contact line
    sliding_velocity: np.ndarray  # [m/s]
    rolling_velocity: np.ndarray  # [m/s] entraining, across the contact line
    slide_to_roll: np.ndarray  # [1] signed, sliding across the line / rolling
    slide_to_roll_total: np.ndarray  # [1] abs(V_s) / V_r, the μ model's SR (seed Eq. 5.5, 5.7)
    pinion_speed_across: np.ndarray  # [m/s] |pinion surface velocity across the line|
    gear_speed_across: np.ndarray  # [m/s] |gear surface velocity across the line|
    half_width: np.ndarray  # [mm] Hertzian half-width 2w/(π p_max)
    edge: np.ndarray  # bool: an edge contact (segment_kind not "curve")


class LoadedSegments(NamedTuple):
    """The loaded contact segments of an LTCA (:func:`loaded_segments`): ``loaded`` on the
    LTCA's (torque, roll, pair, segment) grid, every other array 1-D over the loaded ones
    (n,), in the order of ``ltca["force"].values[loaded]``."""

    loaded: np.ndarray  # (T, J, K, S) bool: force finite and > 0
    force: np.ndarray  # [N]
    load_per_length: np.ndarray  # [N/mm]
    pressure_max: np.ndarray  # [MPa]
    length: np.ndarray  # [mm]
    radius: np.ndarray  # [mm] equivalent radius across the contact line
    half_width: np.ndarray  # [mm] Hertzian half-width 2w/(π p_max)
    edge: np.ndarray  # bool: an edge contact (segment_kind not "curve")


def loaded_segments(ltca: xr.Dataset) -> LoadedSegments:
    """Which segments of an LTCA carry load, and their loads and contact geometry.

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` group: ``force`` [N] over (torque, roll, pair, segment),
        ``load_per_length`` [N/mm], ``pressure_max`` [MPa], ``segment_length`` [mm],
        ``equivalent_radius`` [mm] and, where present, ``segment_kind``.

    Returns
    -------
    LoadedSegments
        ``loaded`` (force finite and > 0, shape of ``force``) and, 1-D over the loaded
        segments: force [N], load per length [N/mm], peak pressure [MPa], length and
        equivalent radius [mm], the Hertzian half-width b = 2w/(π p_max) [mm] (NaN where
        p_max is not > 0) and whether each is an edge contact.

    Notes
    -----
    The segments of the loaded TCA (seed §3.3); b is the Hertz line contact's (Johnson
    1985, Eq. 4.45), as the LTCA's own ``half_width``.
    """
    F = ltca.variables["force"].values  # (T, J, K, S)
    loaded = np.isfinite(F) & (F > 0)
    shape = F.shape
    w = ltca.variables["load_per_length"].values[loaded]
    p = ltca.variables["pressure_max"].values[loaded]
    kind = ltca.variables["segment_kind"].values if "segment_kind" in ltca else None
    edge = (np.broadcast_to(kind != "curve", shape)[loaded] if kind is not None
            else np.zeros(w.shape, bool))
    return LoadedSegments(
        loaded=loaded,
        force=F[loaded],
        load_per_length=w,
        pressure_max=p,
        length=np.broadcast_to(ltca.variables["segment_length"].values, shape)[loaded],
        radius=np.broadcast_to(ltca.variables["equivalent_radius"].values, shape)[loaded],
        # b = 2w/(π p_max) (hertz_half_width, without its checks: a NaN stays NaN here)
        half_width=_half_width(w, p),
        edge=edge,
    )


def _loaded_segments(ltca: xr.Dataset, pinion_speed: float) -> _Segments:
    """The loaded segments of ``ltca`` (:func:`loaded_segments`) with their sliding and
    entraining speeds [m/s] and slide-to-roll ratios [1] — the signed one across the
    contact line, and the total abs(V_s)/V_r the friction model is fed — at the pinion
    speed [rpm] (:func:`friction.kinematics.surface_velocities`), and each member's surface
    speed across the contact line [m/s] (the speed at which it passes through the band,
    the flash temperature's)."""
    seg = loaded_segments(ltca)
    loaded = seg.loaded
    shape = loaded.shape
    pts = np.broadcast_to(ltca.variables["contact_point"].values, (*shape, 3))
    nrm = np.broadcast_to(ltca.variables["contact_normal"].values, (*shape, 3))
    tan = np.broadcast_to(ltca.variables["contact_tangent"].values, (*shape, 3))
    kin = surface_velocities(
        pts[loaded],
        nrm[loaded],
        tan[loaded],
        pinion_axis=ltca.attrs["pinion_axis"],
        pinion_origin=ltca.attrs["pinion_origin_mm"],
        gear_axis=ltca.attrs["gear_axis"],
        gear_origin=ltca.attrs["gear_origin_mm"],
        pinion_speed=pinion_speed,
        ratio=float(ltca.attrs["ratio"]),
        check_meshing=False,
    )
    across = np.cross(nrm[loaded], tan[loaded])  # unit: n ⟂ t
    return _Segments(
        **seg._asdict(),
        sliding_velocity=kin["sliding_velocity"],
        rolling_velocity=kin["rolling_velocity"],
        slide_to_roll=kin["slide_to_roll"],
        slide_to_roll_total=_total_slide_to_roll(kin["sliding_velocity"],
                                                 kin["rolling_velocity"]),
        pinion_speed_across=np.abs(np.sum(kin["pinion_tangential"] * across, axis=-1)),
        gear_speed_across=np.abs(np.sum(kin["gear_tangential"] * across, axis=-1)),
    )


def _half_width(w: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The Hertzian half-width 2w/(π p_max) [mm] of load per length w [N/mm] and peak
    pressure p [MPa] (Hertz line contact; NaN where p is not > 0, as the LTCA's own
    ``half_width``)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(p > 0.0, 2.0 * w / (math.pi * np.where(p > 0.0, p, 1.0)), np.nan)


def _total_slide_to_roll(sliding: np.ndarray, rolling: np.ndarray) -> np.ndarray:
    """abs(V_s)/V_r [1] from the total sliding speed abs(V_s) (seed Eq. 5.5, both components)
    and the rolling speed across the contact line V_r (Eq. 5.6) [m/s]; +inf where V_r = 0
    and the surfaces slide (0 where neither moves).

    Why the total (docs/friction.md, "Which slide-to-roll ratio"): the film's shear
    stress is η_eff abs(V_s)/h (seed Eq. 5.7, V_s of Eq. 5.5) — the oil is sheared by the
    whole relative velocity, along the line as well as across it, and the Eyring stress
    and the shear heat follow the magnitude of the shear rate — and the loss the μ is
    multiplied by is μ F abs(V_s). The line-contact study that μ is fitted to slides across
    its line only, where the two ratios are one."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(rolling > 0.0, sliding / np.where(rolling > 0.0, rolling, 1.0),
                        np.where(sliding > 0.0, np.inf, 0.0))


class _Friction(NamedTuple):
    """Film and friction of the loaded segments, each array 1-D over them (n,)."""

    film_thickness: np.ndarray  # h_min [µm]
    lambda_ratio: np.ndarray  # λ = h_min/σ [1]
    friction_coefficient: np.ndarray  # μ [1]
    extrapolated: np.ndarray  # bool: μ's model evaluated outside its validity range
    rolling_traction: np.ndarray  # F_R [N/mm]
    range_warnings: list[str]  # the friction models' out-of-range notes, sorted, unique


def _film_and_friction(
    seg: _Segments, oil: _Oil, e_prime: float, sigma: float, op: OperatingConditions
) -> _Friction:
    """Minimum film thickness h_min [µm] (Dowson–Higginson with Gupta's thermal factor),
    λ = h_min/σ [1] (σ [µm] the composite roughness), friction coefficient μ [1] of the
    model ``op.friction_model`` and rolling traction F_R [N/mm] (Goksem–Hargreaves) of
    each loaded segment, E′ [MPa]; the :class:`FrictionModelRangeWarning` s raised on the
    way are caught and returned as their sorted, distinct messages."""
    eta0, alpha = oil.viscosity, oil.pressure_viscosity
    beta, k_oil = oil.temperature_viscosity, oil.thermal_conductivity
    ph, w, R = seg.pressure_max, seg.load_per_length, seg.radius
    vs, vr, sr = seg.sliding_velocity, seg.rolling_velocity, seg.slide_to_roll_total
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FrictionModelRangeWarning)
        loading = thermal_loading(beta, eta0, vr, k_oil)
        phi_t = thermal_reduction_factor(loading, ph, e_prime, sr)
        h = np.asarray(
            minimum_film_thickness(vr, eta0, alpha, w, R, e_prime, thermal_factor=phi_t), float
        )
        lam = np.asarray(lambda_ratio(h, sigma), float)
        inputs = dict(
            hertz_pressure=ph,
            slide_to_roll=sr,
            entraining_velocity=vr,
            sliding_velocity=vs,
            load_per_length=w,
            viscosity=eta0,
            radius=R,
            roughness_1=op.effective_roughness,
            roughness_2=op.effective_roughness,
            lambda_ratio=lam,
            pressure_viscosity=alpha,
            e_prime=e_prime,
            temperature=op.temperature,
            thermal_factor=phi_t,
            temperature_viscosity=beta,
            oil_thermal_conductivity=k_oil,
            pressure_viscosity_temperature=_alpha_temperature_coefficient(
                oil.lubricant, op.temperature),
        )
        accepted = get_friction_model(op.friction_model).optional
        inputs.update({k: v for k, v in oil.traction.items() if k in accepted})
        mu = np.asarray(friction_coefficient(op.friction_model, **inputs), float)
        outside = ~np.broadcast_to(friction_model_validity(op.friction_model, **inputs),
                                   seg.force.shape)
        # a μ beyond lubricated steel contacts (the model's warning says it; issue 71):
        # flagged as outside the model's range, so that the verdict names it
        outside = outside | np.broadcast_to(mu > MU_CAP, seg.force.shape)
        fr = np.asarray(rolling_traction(vr, sr, eta0, alpha, w, R, e_prime, beta, k_oil), float)
    range_notes = {str(w.message) for w in caught
                   if issubclass(w.category, FrictionModelRangeWarning)}
    if "boundary_friction" in accepted and "boundary_friction" in oil.traction \
            and oil.boundary_friction_notes:
        # μ_b held at its table's end value: every segment's μ rests on it
        outside = np.ones(seg.force.shape, bool)
        range_notes.update(oil.boundary_friction_notes)
    range_notes = sorted(range_notes)
    return _Friction(h, lam, np.broadcast_to(mu, seg.force.shape), outside, fr, range_notes)


def _alpha_temperature_coefficient(lubricant: Lubricant, temperature: float) -> float:
    """−d ln α/dT [1/K] of the oil at ``temperature`` [degC]: the central difference over
    ±5 K of :func:`friction.lubricant.pressure_viscosity_coefficient` (its table's
    piecewise log-linear α), held inside the oil's accepted temperature range."""
    lo, hi = temperature_range(lubricant)
    t1, t2 = max(temperature - 5.0, lo), min(temperature + 5.0, hi)
    if t2 <= t1:
        return 0.0
    a1, a2 = (float(pressure_viscosity_coefficient(lubricant, t)) for t in (t1, t2))
    return max(-math.log(a2 / a1) / (t2 - t1), 0.0)


class _Losses(NamedTuple):
    """Power losses [W] and efficiency [1] of the mesh."""

    sliding: np.ndarray  # (T, J, K, S) [W], NaN where unloaded
    rolling: np.ndarray  # (T, J, K, S) [W], NaN where unloaded
    total: np.ndarray  # (T, J) [W] instantaneous power loss
    efficiency: np.ndarray  # (T, J) [1] instantaneous mechanical efficiency


def _scatter(values: np.ndarray, loaded: np.ndarray) -> np.ndarray:
    """Per-segment ``values`` of the loaded segments put back on the (T, J, K, S) grid of
    ``loaded``, NaN on the unloaded segments (same unit as ``values``)."""
    out = np.full(loaded.shape, np.nan)
    out[loaded] = values
    return out


def _scatter_flag(flags: np.ndarray, loaded: np.ndarray) -> np.ndarray:
    """Per-segment booleans of the loaded segments on the (T, J, K, S) grid of ``loaded``
    as int8 0/1 (0 on the unloaded segments)."""
    out = np.zeros(loaded.shape, dtype=np.int8)
    out[loaded] = flags
    return out


def _power_losses(
    seg: _Segments, fric: _Friction, torque: np.ndarray, pinion_speed: float
) -> _Losses:
    """Sliding loss μ F V_s and rolling loss F_R L V_r [W] of each segment, their sum per
    roll position [W] and the efficiency 1 − loss/(T_p ω_p) [1] (pinion torque [N·m] per
    ``torque`` level, pinion speed [rpm])."""
    p_slide = fric.friction_coefficient * seg.force * seg.sliding_velocity  # N · m/s = W
    p_roll = fric.rolling_traction * seg.length * seg.rolling_velocity  # (N/mm) · mm · m/s = W
    sl, rl = _scatter(p_slide, seg.loaded), _scatter(p_roll, seg.loaded)
    loss = np.nansum(sl, axis=(2, 3)) + np.nansum(rl, axis=(2, 3))  # (T, J)
    omega = 2 * math.pi * pinion_speed / 60.0
    p_in = torque[:, None] * omega  # N·m · rad/s = W
    eff = 1.0 - loss / p_in
    return _Losses(sl, rl, loss, eff)


def _friction_dataset(
    ltca: xr.Dataset,
    seg: _Segments,
    fric: _Friction,
    losses: _Losses,
    op: OperatingConditions,
    oil: _Oil,
) -> xr.Dataset:
    """The ``/friction`` dataset: per-segment speeds [m/s], film [µm], friction and losses
    [W] on (torque, roll, pair, segment), the power loss [W] and efficiency [1] per roll
    position and their cycle means, the flash and contact temperatures [K], [degC], the
    specific film thickness [1] and the safeties against scuffing and micropitting [1],
    the coordinates of ``ltca`` and the conditions as attributes (see
    :func:`efficiency_analysis`)."""
    loaded = seg.loaded
    loss, eff = losses.total, losses.efficiency
    dims4 = ("torque", "roll", "pair", "segment")
    data = {
        "sliding_velocity": data_var(
            dims4, _scatter(seg.sliding_velocity, loaded), "m/s", "sliding velocity"
        ),
        "rolling_velocity": data_var(
            dims4, _scatter(seg.rolling_velocity, loaded), "m/s",
            "rolling (entraining) velocity across the contact line",
        ),
        "slide_to_roll": data_var(
            dims4, _scatter(seg.slide_to_roll, loaded), "1",
            "slide-to-roll ratio across the contact line",
        ),
        "slide_to_roll_total": data_var(
            dims4, _scatter(seg.slide_to_roll_total, loaded), "1",
            "total slide-to-roll ratio abs(V_s) / V_r (the friction model's input)",
        ),
        "film_thickness": data_var(
            dims4, _scatter(fric.film_thickness, loaded), "um", "minimum film thickness"
        ),
        "lambda_ratio": data_var(
            dims4, _scatter(fric.lambda_ratio, loaded), "1", "lambda ratio h_min / sigma"
        ),
        "friction_coefficient": data_var(
            dims4, _scatter(fric.friction_coefficient, loaded), "1",
            "sliding friction coefficient",
        ),
        "friction_model_extrapolated": data_var(
            dims4, _scatter_flag(fric.extrapolated, loaded), "1",
            "friction model evaluated outside its validity range (0 on unloaded segments)",
            **binary_flag("no", "yes"),
        ),
        "sliding_loss": data_var(dims4, losses.sliding, "W", "sliding friction power loss"),
        "rolling_loss": data_var(dims4, losses.rolling, "W", "rolling (EHL) power loss"),
        "power_loss": data_var(("torque", "roll"), loss, "W", "instantaneous mesh power loss"),
        "efficiency": data_var(("torque", "roll"), eff, "1", "instantaneous mechanical efficiency"),
        "power_loss_mean": data_var(
            ("torque",), loss.mean(axis=1), "W", "mean power loss over the mesh cycles"
        ),
        "efficiency_mean": data_var(
            ("torque",), eff.mean(axis=1), "1", "mean mechanical efficiency over the mesh cycles"
        ),
        "surface_speed": data_var(
            ("member", *dims4), np.stack([_scatter(seg.pinion_speed_across, loaded),
                                          _scatter(seg.gear_speed_across, loaded)]), "m/s",
            "each flank's speed across the contact line (through the Hertzian band: the "
            "speeds of Blok's flash temperature)"),
    }
    coords = coords_along(ltca, ("torque", "roll", "pair", "segment"))
    coords["member"] = ("member", ["pinion", "gear"], {"long_name": "gear pair member"})
    attrs = {
        "title": "mechanical power loss and efficiency",
        "pinion_speed_rpm": op.pinion_speed,
        "lubricant": oil.name,
        "inlet_temperature_degC": op.temperature,
        "roughness_rq_um": op.roughness,
        "surface_state": op.surface_state,
        "roughness_effective_rq_um": op.effective_roughness,
        "friction_model": op.friction_model_name,
        "inlet_viscosity_Pa_s": oil.viscosity,
        "pressure_viscosity_1_per_GPa": oil.pressure_viscosity,
        "model_range_warnings": json.dumps(fric.range_warnings),
        "model_range_by_contact": json.dumps(_range_by_contact(ltca, seg, fric)),
    }
    used = _boundary_friction_used(oil, op.friction_model)
    if used is not None:
        # the μ_b [1] of the asperity junctions the model ran with, at the inlet temperature
        attrs["boundary_friction"], attrs["boundary_friction_source"] = used
    return dataset(data, coords, attrs)


#: The inputs whose spans :func:`_range_by_contact` reports: name → (symbol, units, digits).
_SPAN_INPUTS = {"hertz_pressure": ("p_h", "MPa", 0), "radius": ("R_eq", "mm", 2),
                "lambda_ratio": ("λ", "", 3), "slide_to_roll": ("abs(V_s)/V_r", "", 4),
                "entraining_velocity": ("u_e", "m/s", 2)}


def _range_by_contact(ltca: xr.Dataset, seg: _Segments, fric: _Friction) -> dict[str, dict]:
    """The extrapolated segments split by the kind of contact — ``flank`` (the contact
    curves: line contact of two flanks, what a line-contact study covers) and ``edge``
    (a rounded tooth edge on the mating flank, R_eq ≈ the edge radius) — each with its
    loaded and flagged segment counts, the flagged share of the load [1] and the spans
    (min, max) of p_h [MPa], R_eq [mm], λ, the total slide-to-roll ratio abs(V_s)/V_r [1]
    and u_e [m/s] over the flagged ones: what lies outside the model's range, and where
    (the flag says why)."""
    kind = ltca.variables["segment_kind"].values if "segment_kind" in ltca else None
    is_edge = (np.broadcast_to(kind != "curve", seg.loaded.shape)[seg.loaded]
               if kind is not None else np.zeros(seg.force.shape, bool))
    total = float(np.sum(seg.force)) or 1.0
    values = {"hertz_pressure": seg.pressure_max, "radius": seg.radius,
              "lambda_ratio": fric.lambda_ratio, "slide_to_roll": seg.slide_to_roll_total,
              "entraining_velocity": seg.rolling_velocity}
    out = {}
    for name, mask in (("flank", ~is_edge), ("edge", is_edge)):
        flagged = mask & np.asarray(fric.extrapolated, bool)
        entry: dict = {"loaded": int(mask.sum()), "extrapolated": int(flagged.sum()),
                       # rounded, as the spans: a text attribute is compared as text,
                       # and its last digits would follow the machine's round-off
                       "load_share": round(float(np.sum(seg.force[flagged]) / total), 5)}
        if flagged.any():
            entry["spans"] = {k: [round(float(np.min(values[k][flagged])), d),
                                  round(float(np.max(values[k][flagged])), d)]
                              for k, (_, _, d) in _SPAN_INPUTS.items()}
        out[name] = entry
    return out


def extrapolation_summary(friction: xr.Dataset) -> str:
    """One sentence on where the friction model ran outside its fitted range: on the
    flanks and on the edges, how many segments, their share of the load and the spans of
    their inputs (the ``model_range_by_contact`` attribute of :func:`efficiency_analysis`).

    Parameters
    ----------
    friction : xarray.Dataset
        A ``/friction`` dataset.

    Returns
    -------
    str
        Empty when nothing was extrapolated or the dataset predates the attribute.
    """
    try:
        parts = json.loads(friction.attrs.get("model_range_by_contact", "{}"))
    except (TypeError, ValueError):
        return ""
    texts = []
    for name, what in (("flank", "on the flanks"), ("edge", "on the edges (a rounded tooth "
                                                           "edge on the mating flank)")):
        e = parts.get(name)
        if not e or not e.get("extrapolated"):
            continue
        spans = ", ".join(
            f"{_SPAN_INPUTS[k][0]} {lo:g}-{hi:g} {_SPAN_INPUTS[k][1]}".rstrip()
            for k, (lo, hi) in e.get("spans", {}).items() if k in _SPAN_INPUTS)
        texts.append(f"{e['extrapolated']} of {e['loaded']} segments {what}, "
                     f"{e['load_share']:.1%} of the load ({spans})")
    return "; ".join(texts)


def extrapolated_segments(friction: xr.Dataset, torque_index: int | None = None
                          ) -> tuple[int, int]:
    """How many loaded segments had the friction model evaluated outside its fitted range.

    Parameters
    ----------
    friction : xarray.Dataset
        The ``/friction`` dataset of :func:`efficiency_analysis`
        (``friction_model_extrapolated`` and ``friction_coefficient`` over torque, roll,
        pair, segment).
    torque_index : int, optional
        One torque; default all.

    Returns
    -------
    (int, int)
        Segments flagged, loaded segments (those with a friction coefficient); (0, 0)
        for a dataset without the flag.

    Notes
    -----
    The flag is set per segment by the friction models (FrictionModelRangeWarning,
    :mod:`friction.validity`); this only counts it, for summaries and plots.
    """
    if "friction_model_extrapolated" not in friction or "friction_coefficient" not in friction:
        return 0, 0
    flag = friction["friction_model_extrapolated"]
    loaded = friction["friction_coefficient"].notnull()
    if torque_index is not None:
        flag, loaded = flag.isel(torque=torque_index), loaded.isel(torque=torque_index)
    return int((flag.values == 1).sum()), int(loaded.values.sum())
