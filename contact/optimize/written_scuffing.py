"""The scuffing safety of the case ``ltca synthesize`` writes, at its design torque and
its own operating conditions (issue 71, branch scuff99).

The design torque ``ltca synthesize`` writes is the ISO 10300 capacity (pitting and
bending) or the user's, and the development's targets are the bearing's (pattern, edge,
plastic, LTE): neither sees the oil. ``ltca run`` of the written case judges the LTCA's
scuffing safety S_B (ISO/TS 6336-20's flash-temperature method on the loaded contact,
docs/scuffing_micropitting.md) at the case's ``[operating]`` speed, oil, inlet
temperature and roughness, and FAILs below 1. Round 37's FM truck hypoid 8×45 (a 88 mm,
1750 N·m) was written with "every target met" and FAILed on S_B 0.93.

:func:`design_scuffing` runs the same analysis steps ``ltca run`` runs for S_B (LTCA,
efficiency, scuffing; no root stress, rating or LTE range, which S_B does not read) at the
design torque on the drive flank, and, where S_B is below the verdict's minimum, the
verdict's own example remedy (the oil inlet 20 K cooler, the flanks half as rough) on the
same LTCA. :func:`scuffing_note` says it. The design torque is **not** lowered for it:
S_B depends on what the operation chooses (oil, its scuffing temperature, inlet
temperature, speed, finish), which the basic file does not fix and which answers it
without a larger gear set, while the pitting capacity is the gear set's own; and the
bundled 75W90's scuffing temperature is a lower bound (FZG stage 12, the test's highest,
which GL-5 axle oils pass). docs/synthesis.md ("Scuffing at the design torque") gives the
argument.

Public names
------------
DesignScuffing, design_scuffing, scuffing_note
"""

from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass

from geometry.core.text import plain_number

__all__ = ["DesignScuffing", "design_scuffing", "scuffing_note"]

logger = logging.getLogger(__name__)

#: the verdict's example remedy (contact.commands.run.next_steps): the inlet this much
#: cooler [K] and the flanks' Rq divided by this
REMEDY_COOLER = 20.0
REMEDY_SMOOTHER = 2.0


@dataclass(frozen=True)
class DesignScuffing:
    """The LTCA's scuffing safety of a written case at its design torque.

    Attributes
    ----------
    torque : float — [N·m] the pinion torque analysed (the design torque)
    safety : float — [1] S_B there at the case's operation (NaN: the oil lacks its data)
    pinion_speed : float — [rpm]
    lubricant : str — the oil's name
    temperature : float — [degC] the oil inlet temperature
    roughness : float — [µm] the flanks' Rq
    scuffing_temperature : float — [degC] the oil's θ_S
    remedy_safety : float — [1] S_B with the inlet :data:`REMEDY_COOLER` K cooler and Rq
        divided by :data:`REMEDY_SMOOTHER` (NaN where not computed: S_B not below 1)
    reason : str — why S_B is NaN (empty otherwise)
    """

    torque: float
    safety: float
    pinion_speed: float
    lubricant: str
    temperature: float
    roughness: float
    scuffing_temperature: float
    remedy_safety: float = math.nan
    reason: str = ""


def _analysis(case, torque: float):
    """The tree of LTCA, efficiency and scuffing (no rating, root stress, LTE range, mesh
    interface or geometry) at ``torque`` on the drive flank, at the case's operation."""
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis

    steps = (AnalysisChain.analysis().with_load_capacity("scuffing_micropitting")
             .without("root_stress", "mesh_interface", "lte_range", "geometry"))
    return run_analysis(case, [float(torque)], flank="drive", steps=steps)


def design_scuffing(case, torque: float) -> DesignScuffing | None:
    """The LTCA's scuffing safety S_B of ``case`` at ``torque`` on its drive flank, at the
    case's ``[operating]`` conditions, as ``ltca run CASE --torque TORQUE`` computes it.

    Parameters
    ----------
    case : geometry.case.Case
        The written case.
    torque : float — [N·m]
        The pinion design torque.

    Returns
    -------
    DesignScuffing or None
        None where the case has no efficiency stage (pinion speed 0: no S_B at all). Where
        S_B is below :data:`contact.study.verdicts.SCUFFING_MIN` also S_B of the verdict's
        example remedy on the same LTCA (the inlet 20 K cooler, Rq halved).

    Raises
    ------
    InputError, SolverError
        As :func:`contact.run_analysis` (the caller says a failure instead of the safety).

    Notes
    -----
    Source: the verdict's scuffing check (:mod:`contact.study.verdicts`, ``scuffing``) and
    its next step (:func:`contact.commands.run.next_steps`); ISO/TS 6336-20
    (docs/scuffing_micropitting.md).
    """
    from contact.load_capacity.scuffing_micropitting import scuffing_micropitting
    from contact.pipeline import operating_conditions
    from contact.study.verdicts import SCUFFING_MIN
    from friction.efficiency import efficiency_analysis

    op = operating_conditions(case)
    if op is None or not op.pinion_speed:
        return None
    tree = _analysis(case, torque)
    if "scuffing_micropitting" not in tree.children:
        return None
    sm = tree["scuffing_micropitting"].to_dataset()
    s_b = float(sm["scuffing_safety"].values[0])
    reason = "" if math.isfinite(s_b) else str(sm["scuffing_safety"].attrs.get("comment", ""))
    remedy = math.nan
    if math.isfinite(s_b) and s_b < SCUFFING_MIN:
        cooler = dataclasses.replace(op, temperature=op.temperature - REMEDY_COOLER,
                                     roughness=op.roughness / REMEDY_SMOOTHER)
        ltca = tree["ltca"].to_dataset()
        again = scuffing_micropitting(ltca, efficiency_analysis(ltca, cooler),
                                      lubricant=cooler.oil())
        remedy = float(again["scuffing_safety"].values[0])
    name = str(sm.attrs.get("lubricant", op.lubricant))
    return DesignScuffing(float(torque), s_b, float(op.pinion_speed), name,
                          float(op.temperature), float(op.roughness),
                          float(sm["scuffing_temperature"]), remedy, reason)


def scuffing_note(found: DesignScuffing | None) -> str | None:
    """The line ``ltca synthesize`` says where the written case's S_B at its design torque
    is below the verdict's minimum (``ltca run`` of it FAILs on scuffing): the value, the
    conditions, why neither the design torque nor the development saw it, and the
    verdict's remedy with its S_B. None where S_B is not below the minimum or unknown.

    Parameters
    ----------
    found : DesignScuffing or None
        :func:`design_scuffing`'s result.

    Returns
    -------
    str or None
    """
    from contact.study.verdicts import SCUFFING_MIN

    if found is None or not math.isfinite(found.safety) or found.safety >= SCUFFING_MIN:
        return None
    remedy = (f" (S_B {found.remedy_safety:.2f} there)"
              if math.isfinite(found.remedy_safety) else "")
    return (f"scuffing: S_B {found.safety:.2f} at the design torque "
            f"{plain_number(found.torque)} N m below {SCUFFING_MIN:g} at the case's "
            f"operation ({plain_number(found.pinion_speed)} rpm, {found.lubricant} at "
            f"{plain_number(found.temperature)} degC, Rq {plain_number(found.roughness)} um; "
            f"the oil's scuffing temperature {found.scuffing_temperature:.0f} degC): "
            "`ltca run` of this case FAILs on scuffing. The design torque (pitting and "
            "bending) and the development's targets (the bearing) do not include it, and "
            "`ltca optimize` does not model it; the operation answers it: a cooler oil "
            "inlet, smoother flanks, a lower speed, or an oil of a higher scuffing "
            "temperature (its FZG load stage, [operating] lubricant) — the inlet "
            f"{plain_number(found.temperature - REMEDY_COOLER)} degC with Rq "
            f"{plain_number(found.roughness / REMEDY_SMOOTHER)} um{remedy} "
            "(docs/synthesis.md, \"Scuffing at the design torque\")")
