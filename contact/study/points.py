"""The inputs of a design study: what is swept per point and what every point shares.

Public names
------------
POINT_INPUTS   the inputs a study varies per point, with their units
StudyInputs    what every point of a study shares (case, torques, speeds, options …)
check_point    validate one point's inputs (names, finite values)
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from contact.ltca import LTCAOptions
from contact.ltca.options import json_options
from contact.utca.deviations import SurfaceDeviation
from friction.operating import OperatingConditions
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

__all__ = ["POINT_INPUTS", "StudyInputs", "check_point", "misalignment_of"]

#: The inputs a study may vary per point: name → (units, long name). The misalignments
#: are those of :class:`geometry.pair.assembly.Misalignment` (ΔΣ in rad, as there);
#: ``deviation_scale`` multiplies the case's surface deviations (its ``[deviations]``
#: table, seed ch. 4): 0 the theoretical flanks, 1 the measured ones.
POINT_INPUTS: Mapping[str, tuple[str, str]] = {
    "delta_E": ("mm", "offset misalignment dE (pinion offset change)"),
    "delta_P": ("mm", "pinion axial misalignment dP (pinion mounting distance change)"),
    "delta_G": ("mm", "gear axial misalignment dG (gear mounting distance change)"),
    "delta_Sigma": ("rad", "shaft-angle misalignment dSigma"),
    "deviation_scale": ("1", "factor on the case's measured surface deviations"),
}


def check_point(point: Mapping[str, float], where: str = "point") -> dict[str, float]:
    """One point's inputs as floats, refusing unknown names and non-finite values.

    Parameters
    ----------
    point : mapping of str to float
        Names from :data:`POINT_INPUTS` (units there).
    where : str
        How the error message names the point.

    Returns
    -------
    dict of str to float

    Raises
    ------
    InputError
        Unknown name (the message lists the accepted ones) or a value that is not a
        finite number.
    """
    out = {}
    for name, value in point.items():
        if name not in POINT_INPUTS:
            raise InputError(f"{where}: unknown study input {name!r}; accepted: "
                             f"{', '.join(POINT_INPUTS)}")
        try:
            x = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{name}: must be a number [{POINT_INPUTS[name][0]}], got "
                             f"{value!r}") from None
        if not math.isfinite(x):
            raise InputError(f"{name}: must be finite [{POINT_INPUTS[name][0]}], got {x}")
        out[name] = x
    return out


def misalignment_of(base: Misalignment, point: Mapping[str, float]) -> Misalignment:
    """The case's misalignment ``base`` with the point's ΔE, ΔP, ΔG, ΔΣ put in."""
    fields = {k: v for k, v in point.items() if k in ("delta_E", "delta_P", "delta_G",
                                                      "delta_Sigma")}
    return dataclasses.replace(base, **fields) if fields else base


@dataclass(frozen=True, eq=False)
class StudyInputs:
    """What every point of a study shares.

    Attributes
    ----------
    case : geometry.case.Case
        The analysed case; inputs a point does not set keep the case's values.
    torque : tuple of float — [N·m]
        Pinion torques, analysed together at every point (one LTCA per point).
    speed : tuple of float — [rpm]
        Pinion speeds of the efficiency stage; empty for none.
    operating : friction.operating.OperatingConditions or None
        Lubricant, temperature, roughness and friction model of the efficiency stage
        (its speed replaced by each of ``speed``).
    options : contact.ltca.LTCAOptions
    flank : str or None
        ``"drive"`` / ``"coast"`` (None: drive).
    deviations : (SurfaceDeviation or None, SurfaceDeviation or None) or None
        The case's surface deviations of (pinion, gear), read once on the client, scaled
        by each point's ``deviation_scale``; None for theoretical flanks.
    root_stress : bool or contact.compliance.fe.FEOptions
        Also the peak tooth-root stress of both members (``root_stress_max`` over
        (torque, member), :func:`contact.run_analysis`'s ``root_stress``): the FE
        coefficients are built once per design (cached on disk) and reused by every point
        of the same design. Default False (the output has no ``root_stress_max``).
    coefficients : tuple of xarray.Dataset
        The FE influence coefficients the client built or read for the study (set by the
        engine, not by the user): handed to every worker with these inputs, which writes
        them into its own cache before its first point (:func:`contact.compliance.fe.
        prime_cache`), so that no worker builds them, whatever its cache directory
        (issue 53). Not part of the fingerprint.
    """

    case: Case
    torque: tuple[float, ...]
    speed: tuple[float, ...] = ()
    operating: OperatingConditions | None = None
    options: LTCAOptions = dataclasses.field(default_factory=LTCAOptions)
    flank: str | None = None
    deviations: tuple[SurfaceDeviation | None, SurfaceDeviation | None] | None = None
    root_stress: Any = False
    coefficients: tuple = ()

    def deviations_at(self, scale: float | None) -> tuple | bool:
        """The (pinion, gear) deviations scaled by ``scale`` (None: unscaled); False for
        theoretical flanks (what :func:`contact.run_analysis` takes)."""
        if self.deviations is None:
            if scale not in (None, 0.0):
                raise InputError("deviation_scale: the case has no [deviations] table to "
                                 "scale")
            return False
        if scale is None or scale == 1.0:
            return self.deviations
        return tuple(None if d is None else SurfaceDeviation(d.u, d.v, d.deviation * scale)
                     for d in self.deviations)

    def fingerprint(self) -> str:
        """A hash of everything that decides the points' results (case, torques, speeds,
        operating conditions, options, flank, deviations): a resumed study must match."""
        dev = [] if self.deviations is None else [
            None if d is None else [d.u.tolist(), d.v.tolist(), d.deviation.tolist()]
            for d in self.deviations]
        text = json.dumps({
            "case": self.case.to_toml(), "torque": list(self.torque),
            "speed": list(self.speed),
            "operating": None if self.operating is None else repr(self.operating),
            "options": json_options(self.options), "flank": self.flank, "deviations": dev,
            # only when asked for, so that the fingerprints of studies without it stay
            **({} if self.root_stress is False else {"root_stress": repr(self.root_stress)}),
        }, sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()
