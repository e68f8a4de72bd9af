"""Mechanical power loss and efficiency of a loaded mesh (seed §5.2, Eq. 5.7–5.14).

For every loaded contact segment of an LTCA (the ``/ltca`` dataset of
:func:`contact.ltca.loaded_tca`) at a pinion speed and an oil inlet temperature:

1. kinematics (:func:`friction.kinematics.surface_velocities`): sliding speed V_s,
   entraining speed V_r across the contact line, slide-to-roll ratio SR;
2. lubricant (:mod:`friction.lubricant`): η₀, α at the inlet temperature, β, k;
3. film (:mod:`friction.film`): h_min (Dowson–Higginson, Gupta thermal factor) and the
   lambda ratio λ = h_min/σ with σ = √(Rq₁² + Rq₂²);
4. friction coefficient μ by a registered model (:mod:`friction.coefficient`);
5. losses: sliding P_s = μ F V_s, rolling P_r = F_R L V_r with F_R the Goksem–Hargreaves
   rolling traction per length (:mod:`friction.rolling`);
6. per roll position the instantaneous power loss and efficiency
   η = 1 − (ΣP_s + ΣP_r)/P_in, P_in = T_p ω_p; their mean over the mesh cycles.

Bookkeeping identities hold by construction and are tested: each segment's sliding loss
is μ·F·V_s, totals are sums.
"""

from __future__ import annotations

import dataclasses
import json
import logging
import math
import warnings

import numpy as np
import xarray as xr

from friction.coefficient import FrictionModelRangeWarning, friction_coefficient
from friction.film import (
    composite_roughness,
    lambda_ratio,
    minimum_film_thickness,
    thermal_loading,
    thermal_reduction_factor,
)
from friction.kinematics import surface_velocities
from friction.lubricant import (
    load_lubricant,
    pressure_viscosity_coefficient,
    temperature_viscosity_coefficient,
    thermal_conductivity,
    viscosity,
)
from friction.operating import OperatingConditions
from friction.rolling import rolling_traction
from geometry.conventions import data_var
from geometry.errors import InputError
from geometry.hertz import STEEL, contact_modulus

__all__ = ["efficiency_analysis"]

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
        ``OperatingConditions()`` (1500 rpm, 75W90 at 90 °C, Rq 0.8 µm, xu2007).
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
        ``ltca``), else steel (:data:`geometry.hertz.STEEL`).

    Returns
    -------
    xarray.Dataset
        The ``/friction`` dataset: over (``torque``, ``roll``, ``pair``, ``segment``)
        ``sliding_velocity``, ``rolling_velocity`` [m/s], ``slide_to_roll`` [1],
        ``film_thickness`` [um], ``lambda_ratio`` [1], ``friction_coefficient`` [1],
        ``sliding_loss``, ``rolling_loss`` [W]; over (``torque``, ``roll``)
        ``power_loss`` [W] and ``efficiency`` [1]; over ``torque`` the cycle means
        ``power_loss_mean`` [W] and ``efficiency_mean`` [1]. Inputs outside a model's
        fitted range are logged (INFO) and listed in the ``model_range_warnings`` attribute.

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
    E′ = 2E* (Dowson & Higginson), E* of :func:`geometry.hertz.contact_modulus`.
    """
    need = (
        "force",
        "load_per_length",
        "pressure_max",
        "segment_length",
        "equivalent_radius",
        "contact_point",
        "contact_normal",
        "contact_tangent",
    )
    missing = [n for n in need if n not in ltca.variables]
    if missing:
        raise InputError(f"ltca: dataset lacks {missing} (expected contact.ltca.loaded_tca output)")
    op = OperatingConditions() if operating is None else operating
    overrides = {k: v for k, v in (("pinion_speed", pinion_speed), ("lubricant", lubricant),
                                   ("temperature", temperature), ("roughness", roughness),
                                   ("friction_model", friction_model)) if v is not None}
    if overrides:
        op = dataclasses.replace(op, **overrides)  # validated again on construction
    pinion_speed, temperature, roughness = op.pinion_speed, op.temperature, op.roughness
    friction_model = op.friction_model
    e_mat, nu_mat = _material(ltca)
    youngs_modulus = e_mat if youngs_modulus is None else youngs_modulus
    poisson_ratio = nu_mat if poisson_ratio is None else poisson_ratio
    # E′ = 2E*, the Dowson–Higginson modulus the EHL groups of friction.film are written in
    e_prime = 2.0 * contact_modulus(youngs_modulus, poisson_ratio, youngs_modulus,
                                    poisson_ratio)
    oil = load_lubricant(op.lubricant)
    eta0 = float(viscosity(oil, temperature))
    alpha = float(pressure_viscosity_coefficient(oil, temperature))
    beta = float(temperature_viscosity_coefficient(oil, temperature))
    k_oil = float(thermal_conductivity(oil, temperature))
    sigma = float(composite_roughness(roughness, roughness))

    F = ltca["force"].values  # (T, J, K, S)
    loaded = np.isfinite(F) & (F > 0)
    shape = F.shape
    pts = np.broadcast_to(ltca["contact_point"].values, (*shape, 3))
    nrm = np.broadcast_to(ltca["contact_normal"].values, (*shape, 3))
    tan = np.broadcast_to(ltca["contact_tangent"].values, (*shape, 3))
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
    f = F[loaded]
    w = ltca["load_per_length"].values[loaded]
    ph = ltca["pressure_max"].values[loaded]
    L = np.broadcast_to(ltca["segment_length"].values, shape)[loaded]
    R = np.broadcast_to(ltca["equivalent_radius"].values, shape)[loaded]
    vs, vr, sr = kin["sliding_velocity"], kin["rolling_velocity"], np.abs(kin["slide_to_roll"])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", FrictionModelRangeWarning)
        loading = thermal_loading(beta, eta0, vr, k_oil)
        phi_t = thermal_reduction_factor(loading, ph, e_prime, sr)
        h = np.asarray(
            minimum_film_thickness(vr, eta0, alpha, w, R, e_prime, thermal_factor=phi_t), float
        )
        lam = np.asarray(lambda_ratio(h, sigma), float)
        mu = np.asarray(
            friction_coefficient(
                friction_model,
                hertz_pressure=ph,
                slide_to_roll=sr,
                entraining_velocity=vr,
                sliding_velocity=vs,
                load_per_length=w,
                viscosity=eta0,
                radius=R,
                roughness_1=roughness,
                roughness_2=roughness,
                lambda_ratio=lam,
                pressure_viscosity=alpha,
                e_prime=e_prime,
                temperature=temperature,
            ),
            float,
        )
        fr = np.asarray(rolling_traction(vr, sr, eta0, alpha, w, R, e_prime, beta, k_oil), float)
    range_notes = sorted({str(w.message) for w in caught
                          if issubclass(w.category, FrictionModelRangeWarning)})
    for note in range_notes:
        log.info("%s", note)
    mu = np.broadcast_to(mu, f.shape)
    p_slide = mu * f * vs  # N · m/s = W
    p_roll = fr * L * vr  # (N/mm) · mm · m/s = W

    def scatter(values):
        out = np.full(shape, np.nan)
        out[loaded] = values
        return out

    sl, rl = scatter(p_slide), scatter(p_roll)
    loss = np.nansum(sl, axis=(2, 3)) + np.nansum(rl, axis=(2, 3))  # (T, J)
    omega = 2 * math.pi * pinion_speed / 60.0
    p_in = ltca["torque"].values[:, None] * omega  # N·m · rad/s = W
    eff = 1.0 - loss / p_in
    dims4 = ("torque", "roll", "pair", "segment")
    data = {
        "sliding_velocity": data_var(dims4, scatter(vs), "m/s", "sliding velocity"),
        "rolling_velocity": data_var(
            dims4, scatter(vr), "m/s", "rolling (entraining) velocity across the contact line"
        ),
        "slide_to_roll": data_var(
            dims4, scatter(kin["slide_to_roll"]), "1", "slide-to-roll ratio across the contact line"
        ),
        "film_thickness": data_var(dims4, scatter(h), "um", "minimum film thickness"),
        "lambda_ratio": data_var(dims4, scatter(lam), "1", "lambda ratio h_min / sigma"),
        "friction_coefficient": data_var(dims4, scatter(mu), "1", "sliding friction coefficient"),
        "sliding_loss": data_var(dims4, sl, "W", "sliding friction power loss"),
        "rolling_loss": data_var(dims4, rl, "W", "rolling (EHL) power loss"),
        "power_loss": data_var(("torque", "roll"), loss, "W", "instantaneous mesh power loss"),
        "efficiency": data_var(("torque", "roll"), eff, "1", "instantaneous mechanical efficiency"),
        "power_loss_mean": data_var(
            ("torque",), loss.mean(axis=1), "W", "mean power loss over the mesh cycles"
        ),
        "efficiency_mean": data_var(
            ("torque",), eff.mean(axis=1), "1", "mean mechanical efficiency over the mesh cycles"
        ),
    }
    coords = {k: ltca.coords[k] for k in ("torque", "roll", "pair", "segment")}
    attrs = {
        "title": "mechanical power loss and efficiency",
        "pinion_speed_rpm": pinion_speed,
        "lubricant": oil.name,
        "inlet_temperature_degC": temperature,
        "roughness_rq_um": roughness,
        "friction_model": friction_model,
        "inlet_viscosity_Pa_s": eta0,
        "pressure_viscosity_1_per_GPa": alpha,
        "model_range_warnings": json.dumps(range_notes),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)
