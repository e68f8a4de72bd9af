"""Efficiency maps on the study engine: one task per torque, the operating grid inside.

Public names
------------
efficiency_map        efficiency over speed × torque × temperature × roughness (seed §5.3)
EFFICIENCY_MAP_TORQUES, EFFICIENCY_MAP_SPEEDS   its default grid
EfficiencyInputs      what every torque of an efficiency map shares
efficiency_at_torque  the LTCA at one torque and the efficiency at every operating point
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass

import numpy as np
import xarray as xr

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.summary import ANALYSIS_STATUS, certification
from contact.pipeline import check_analysis_arguments, misalignment_attrs
from contact.study.engine import run_tasks
from friction.operating import OperatingConditions
from geometry import __version__
from geometry.case import OPERATING_DEFAULTS, Case
from geometry.core.bounds import check_bound, check_torques
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

__all__ = ["EFFICIENCY_MAP_SPEEDS", "EFFICIENCY_MAP_TORQUES", "EfficiencyInputs",
           "efficiency_at_torque", "efficiency_map"]


@dataclass(frozen=True, eq=False)
class EfficiencyInputs:
    """The shared inputs of an efficiency map.

    Attributes
    ----------
    case : geometry.case.Case
        With its misalignment.
    options : contact.ltca.LTCAOptions
    operating : friction.operating.OperatingConditions
        Lubricant and friction model (speed, temperature, roughness swept).
    speed, temperature, roughness : tuple of float — [rpm], [degC], [µm]
    flank : str or None
        The pinion flank in contact (None: drive).
    progress : bool
        A progress bar over each torque's roll positions (useful in this process only).
    """

    case: Case
    options: LTCAOptions
    operating: OperatingConditions
    speed: tuple[float, ...]
    temperature: tuple[float, ...]
    roughness: tuple[float, ...]
    flank: str | None = None
    progress: bool = False


def efficiency_at_torque(shared: EfficiencyInputs, index: int,
                         torque: float) -> tuple[int, dict[str, np.ndarray]]:
    """The LTCA at one pinion torque and its efficiency at every operating point.

    Parameters
    ----------
    shared : EfficiencyInputs
    index : int
        The torque's place in the map.
    torque : float — [N·m]

    Returns
    -------
    (int, dict of str to ndarray (n_speed, n_temperature, n_roughness))
        ``index`` and ``efficiency`` [1], ``power_loss`` [W] (means over the mesh
        cycles), ``friction_coefficient_mean``, ``lambda_ratio_mean`` [1] (load-weighted
        over the loaded segments), ``extrapolated_share`` [1] (share of the loaded
        segments where the friction model is extrapolated); ``analysis_status`` (index
        into :data:`contact.ltca.summary.ANALYSIS_STATUS`) and ``analysis_status_reason``
        of the LTCA (:func:`contact.ltca.summary.certification`; NaN efficiencies where
        it is not certified).

    Raises
    ------
    InputError, ModelUnavailableError
        As :func:`contact.ltca.loaded_tca` and
        :func:`friction.efficiency.efficiency_analysis`.

    Notes
    -----
    Seed §5.3: the static LTCA once, the efficiency stage (seed Eqs. 5.1–5.16) at every
    speed, temperature and roughness on its loads.
    """
    from friction.efficiency import efficiency_analysis, extrapolated_segments

    lt = loaded_tca(shared.case, [float(torque)], options=shared.options, flank=shared.flank,
                    progress=shared.progress)
    shape = (len(shared.speed), len(shared.temperature), len(shared.roughness))
    out = {k: np.full(shape, np.nan) for k in ("efficiency", "power_loss",
                                               "friction_coefficient_mean",
                                               "lambda_ratio_mean",
                                               "extrapolated_share")}
    cert = certification(lt)  # a torque without certified contact has no efficiency
    out["analysis_status"] = np.int8(ANALYSIS_STATUS.index(cert.status))
    out["analysis_status_reason"] = cert.reason
    F = lt["force"].fillna(0.0)
    dims = ("roll", "pair", "segment")
    for j, n in enumerate(shared.speed):
        for k, temp in enumerate(shared.temperature):
            for m, rq in enumerate(shared.roughness):
                fr = efficiency_analysis(lt, shared.operating, pinion_speed=float(n),
                                         temperature=float(temp), roughness=float(rq))
                out["efficiency"][j, k, m] = fr["efficiency_mean"].values[0]
                out["power_loss"][j, k, m] = fr["power_loss_mean"].values[0]
                out["friction_coefficient_mean"][j, k, m] = (
                    (fr["friction_coefficient"].fillna(0) * F).sum(dims) / F.sum(dims)
                ).values[0]
                out["lambda_ratio_mean"][j, k, m] = (
                    (fr["lambda_ratio"].fillna(0) * F).sum(dims) / F.sum(dims)).values[0]
                flagged, loaded = extrapolated_segments(fr)
                out["extrapolated_share"][j, k, m] = flagged / loaded if loaded else 0.0
    return index, out


#: The default grid of :func:`efficiency_map` (and ``ltca efficiency-map``): pinion
#: torques [N·m] and pinion speeds [rpm] (the toolkit's choice: light to full load, low
#: to high speed).
EFFICIENCY_MAP_TORQUES = (100.0, 250.0, 500.0)
EFFICIENCY_MAP_SPEEDS = (500.0, 1000.0, 1500.0, 2500.0, 4000.0)


def efficiency_map(
    case: Case | str | os.PathLike[str] | None = None,
    torque=None,
    speed=None,
    *,
    temperature=None,
    roughness=None,
    operating: OperatingConditions | None = None,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    progress: bool = False,
    scheduler="synchronous",
    n_workers: int | None = None,
) -> xr.Dataset:
    """Efficiency over operating points: speed × torque × temperature × roughness (seed §5.3).

    The LTCA (static) runs once per torque — each torque one task of the study engine
    (:func:`contact.study.engine.run_tasks`, Dask) —; the efficiency stage
    (:func:`friction.efficiency.efficiency_analysis`) then runs for every speed,
    temperature and roughness on those loads.

    Parameters
    ----------
    case : Case, path, bundled name or None (default case)
    torque : sequence, optional — [N·m]
        Pinion torques; default :data:`EFFICIENCY_MAP_TORQUES` (100, 250, 500).
    speed : sequence, optional — [rpm]
        Pinion speeds; default :data:`EFFICIENCY_MAP_SPEEDS` (500 … 4000).
    temperature : sequence, optional — [degC]
        Oil inlet temperatures; default the one of ``operating``.
    roughness : sequence, optional — [µm]
        RMS roughness Rq of each surface; default the one of ``operating``.
    operating : friction.operating.OperatingConditions, optional
        The lubricant and friction model (and the default temperature and roughness);
        its pinion speed is replaced by the swept ones. Default the case's ``[operating]``
        table (:func:`contact.pipeline.operating_conditions`).
    misalignment, flank, options
        As :func:`contact.pipeline.run_analysis` (default the case's misalignment, the drive flank).
    progress : bool
        tqdm progress bar over the torques (and, run in this process, over each
        torque's roll positions).
    scheduler, n_workers
        Where the torques run (:func:`contact.study.engine.open_client`): default
        ``"synchronous"`` (this process, one after the other); None a LocalCluster of
        ``n_workers`` processes; an address or a ``distributed.Client`` a cluster.

    Returns
    -------
    xarray.Dataset
        dims (``torque``, ``speed``, ``temperature``, ``roughness``): ``efficiency`` [1],
        ``power_loss`` [W] (means over the mesh cycles), ``friction_coefficient_mean``,
        ``lambda_ratio_mean`` [1] (load-weighted means over the loaded segments),
        ``friction_model_extrapolated_share`` [1] (share of the loaded segments where the
        friction model is extrapolated, flagged per segment by the efficiency stage);
        ``analysis_status`` (torque) int8, 0 ok, 1 uncertified, 2 failed
        (:data:`contact.ltca.summary.ANALYSIS_STATUS`: the torque's loaded contact
        certified at every roll, at some, at none), why in the attribute
        ``analysis_status_reason``; the efficiencies of a torque not certified at every
        roll are NaN.

    Raises
    ------
    InputError
        Bad case, options or operating point (the message names the field); a torque,
        speed, temperature or roughness outside the table of physical bounds
        (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`) or a temperature outside the oil's
        range, refused before any work.
    ModelUnavailableError
        Unknown lubricant or friction model.

    Notes
    -----
    Seed §5.3 (efficiency over operating conditions).
    """
    check_analysis_arguments(case, torque, misalignment, flank, options)
    c = resolve_case(case)
    if misalignment is not None:
        c = dataclasses.replace(c, misalignment=misalignment)
    if operating is None:  # the case's conditions; the speeds are swept
        operating = OperatingConditions.from_point(
            c.operating, pinion_speed=c.operating.pinion_speed or OPERATING_DEFAULTS[
                "pinion_speed"])
    op = operating
    torque = EFFICIENCY_MAP_TORQUES if torque is None else torque
    speed = EFFICIENCY_MAP_SPEEDS if speed is None else speed
    temperature = (op.temperature,) if temperature is None else temperature
    roughness = (op.roughness,) if roughness is None else roughness
    _check_sweep(op, torque, speed, temperature, roughness)  # all of it, before any work
    shared = EfficiencyInputs(c, options or LTCAOptions(), op,
                              tuple(float(x) for x in speed),
                              tuple(float(x) for x in temperature),
                              tuple(float(x) for x in roughness), flank=flank,
                              progress=bool(progress) and scheduler == "synchronous")
    shape = (len(torque), len(speed), len(temperature), len(roughness))
    eff, loss, mu_m, lam_m, extra = (np.full(shape, np.nan) for _ in range(5))
    status = np.zeros(len(torque), np.int8)
    reasons = [""] * len(torque)
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=len(torque), desc="efficiency map", unit="torque")
    for it, res in run_tasks(efficiency_at_torque, shared,
                             [(i, float(t)) for i, t in enumerate(torque)],
                             scheduler=scheduler, n_workers=n_workers):
        eff[it], loss[it] = res["efficiency"], res["power_loss"]
        mu_m[it], lam_m[it] = res["friction_coefficient_mean"], res["lambda_ratio_mean"]
        extra[it] = res["extrapolated_share"]
        status[it], reasons[it] = res["analysis_status"], res["analysis_status_reason"]
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    dims4 = ("torque", "speed", "temperature", "roughness")
    return xr.Dataset(
        {
            "efficiency": (dims4, eff, {"units": "1", "long_name": "mean mechanical efficiency"}),
            "power_loss": (dims4, loss, {"units": "W", "long_name": "mean mesh power loss"}),
            "friction_coefficient_mean": (
                dims4,
                mu_m,
                {"units": "1", "long_name": "load-weighted mean friction coefficient"},
            ),
            "lambda_ratio_mean": (
                dims4,
                lam_m,
                {"units": "1", "long_name": "load-weighted mean lambda ratio"},
            ),
            "friction_model_extrapolated_share": (
                dims4,
                extra,
                {"units": "1", "long_name": "share of the loaded segments where the friction "
                 "model is evaluated outside its fitted range"},
            ),
            "analysis_status": (
                ("torque",),
                status,
                {"units": "1", "long_name": "certification of the torque's loaded contact",
                 "flag_values": np.arange(len(ANALYSIS_STATUS), dtype=np.int8),
                 "flag_meanings": " ".join(ANALYSIS_STATUS)},
            ),
        },
        coords={
            "torque": (
                "torque",
                np.asarray(torque, float),
                {"units": "N m", "long_name": "pinion torque"},
            ),
            "speed": (
                "speed",
                np.asarray(speed, float),
                {"units": "rpm", "long_name": "pinion speed"},
            ),
            "temperature": (
                "temperature",
                np.asarray(temperature, float),
                {"units": "degC", "long_name": "oil inlet temperature"},
            ),
            "roughness": (
                "roughness",
                np.asarray(roughness, float),
                {"units": "um", "long_name": "RMS roughness Rq of each surface"},
            ),
        },
        attrs={
            "title": "mechanical efficiency map",
            "case": c.name,
            **misalignment_attrs(c.misalignment),
            "lubricant": str(op.lubricant),
            "friction_model": op.friction_model_name,
            "toolkit_version": __version__,
            "analysis_status_reason": "; ".join(r for r in reasons if r),
        },
    )


def _check_sweep(op: OperatingConditions, torque, speed, temperature, roughness) -> None:
    """Every value of an efficiency map's sweep against the table of physical bounds
    (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`) and the temperatures against the oil's
    range, before the LTCA (issue 64: a bad speed or temperature was refused only after
    the geometry and ease-off of the first torque)."""
    check_torques(torque)
    for name, values, bound in (("speed", speed, "pinion_speed"),
                                ("temperature", temperature, "temperature"),
                                ("roughness", roughness, "roughness")):
        if isinstance(values, (str, bytes)) or np.ndim(values) != 1 or not len(values):
            raise InputError(f"{name}: must be a sequence of one or more numbers, got "
                             f"{values!r}")
        for v in values:
            check_bound(bound, v, field=name, positive=name == "roughness")
    for t in temperature:
        dataclasses.replace(op, temperature=float(t)).check_oil_temperature()
