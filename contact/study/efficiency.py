"""Efficiency maps on the study engine: one task per torque, the operating grid inside.

Public names
------------
EfficiencyInputs      what every torque of an efficiency map shares
efficiency_at_torque  the LTCA at one torque and the efficiency at every operating point
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact.ltca import LTCAOptions, loaded_tca
from friction.operating import OperatingConditions
from geometry.case import Case

__all__ = ["EfficiencyInputs", "efficiency_at_torque"]


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
        segments where the friction model is extrapolated).

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
