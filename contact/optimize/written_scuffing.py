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
design torque of a flank (drive or coast), and, where S_B is below the verdict's minimum, the
verdict's own example remedy (the oil inlet 20 K cooler, the flanks half as rough) on the
same LTCA. :func:`scuffing_note` says it. The design torque is **not** lowered for it:
S_B depends on what the operation chooses (oil, its scuffing temperature, inlet
temperature, speed, finish), which the basic file does not fix and which answers it
without a larger gear set, while the pitting capacity is the gear set's own; and the
bundled 75W90's scuffing temperature is a lower bound (FZG stage 12, the test's highest,
which GL-5 axle oils pass). docs/synthesis.md ("Scuffing at the design torque") gives the
argument.

Both flanks are checked, each at its own design torque (the coast flank's
:func:`coast_design_torque`, as ``ltca run --flank coast`` caps it), and the check is
recorded in the written case's ``[development.scuffing]`` table (:func:`checked_scuffing`,
:func:`scuffing_table`; issue 71, branch scuff100).

Public names
------------
CheckedScuffing, DesignScuffing, checked_scuffing, coast_design_torque, design_scuffing,
scuffing_note, scuffing_table
"""

from __future__ import annotations

import dataclasses
import json
import logging
import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from geometry.core.text import plain_number

__all__ = ["CheckedScuffing", "DesignScuffing", "checked_scuffing", "coast_design_torque",
           "design_scuffing", "scuffing_note", "scuffing_table"]

logger = logging.getLogger(__name__)

#: the verdict's example remedy (contact.commands.run.next_steps): the inlet this much
#: cooler [K] and the flanks' Rq divided by this
REMEDY_COOLER = 20.0
REMEDY_SMOOTHER = 2.0
#: the flanks checked, each at its own design torque (issue 71, branch scuff100)
FLANKS = ("drive", "coast")
#: the ``[development]`` table's sub-table that records the check in the written case
TABLE = "scuffing"


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
    flank : str — ``"drive"`` or ``"coast"`` (issue 71, branch scuff100)
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
    flank: str = "drive"


def _analysis(case, torque: float, flank: str = "drive"):
    """The tree of LTCA, efficiency and scuffing (no rating, root stress, LTE range, mesh
    interface or geometry) at ``torque`` on ``flank``, at the case's operation."""
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis

    steps = (AnalysisChain.analysis().with_load_capacity("scuffing_micropitting")
             .without("root_stress", "mesh_interface", "lte_range", "geometry"))
    return run_analysis(case, [float(torque)], flank=flank, steps=steps)


def design_scuffing(case, torque: float, flank: str = "drive") -> DesignScuffing | None:
    """The LTCA's scuffing safety S_B of ``case`` at ``torque`` on ``flank``, at the
    case's ``[operating]`` conditions, as ``ltca run CASE --torque TORQUE [--flank coast]``
    computes it.

    Parameters
    ----------
    case : geometry.case.Case
        The written case.
    torque : float — [N·m]
        The pinion design torque of ``flank`` (the coast flank's:
        :func:`coast_design_torque`).
    flank : str
        ``"drive"`` (default) or ``"coast"``.

    Returns
    -------
    DesignScuffing or None
        None where the case has no efficiency stage (pinion speed 0: no S_B at all). Where
        S_B is below :data:`contact.study.verdicts.SCUFFING_MIN` also S_B of the verdict's
        example remedy on the same LTCA (the inlet 20 K cooler, Rq halved).

    Raises
    ------
    InputError, SolverError
        As :func:`contact.run_analysis` (the caller says a failure instead of the safety;
        a ``flank`` other than drive or coast: InputError naming ``flank``).

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

    if flank not in FLANKS:
        from geometry.core.errors import InputError

        raise InputError(f"flank: must be one of {', '.join(FLANKS)}, got {flank!r}")
    op = operating_conditions(case)
    if op is None or not op.pinion_speed:
        return None
    tree = _analysis(case, torque, flank)
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
                          float(sm["scuffing_temperature"]), remedy, reason, flank)


def scuffing_note(found: DesignScuffing | None) -> str | None:
    """The line ``ltca synthesize`` says where the written case's S_B at a flank's design
    torque is below the verdict's minimum (``ltca run`` of it, ``--flank coast`` for the
    coast flank, FAILs on scuffing): the value, the conditions, why neither the design
    torque nor the development saw it, and the verdict's remedy with its S_B. None where
    S_B is not below the minimum or unknown.

    Parameters
    ----------
    found : DesignScuffing or None
        :func:`design_scuffing`'s result.

    Returns
    -------
    str or None
        The drive flank's line starts ``"scuffing: S_B "``, the coast flank's
        ``"scuffing, coast flank: S_B "``.
    """
    from contact.study.verdicts import SCUFFING_MIN

    if found is None or not math.isfinite(found.safety) or found.safety >= SCUFFING_MIN:
        return None
    remedy = (f" (S_B {found.remedy_safety:.2f} there)"
              if math.isfinite(found.remedy_safety) else "")
    coast = found.flank == "coast"
    what, at, run = (("scuffing, coast flank:", "its design torque", "`ltca run --flank coast`")
                     if coast else ("scuffing:", "the design torque", "`ltca run`"))
    return (f"{what} S_B {found.safety:.2f} at {at} "
            f"{plain_number(found.torque)} N m below {SCUFFING_MIN:g} at the case's "
            f"operation ({plain_number(found.pinion_speed)} rpm, {found.lubricant} at "
            f"{plain_number(found.temperature)} degC, Rq {plain_number(found.roughness)} um; "
            f"the oil's scuffing temperature {found.scuffing_temperature:.0f} degC): "
            f"{run} of this case FAILs on scuffing. The design torque (pitting and "
            "bending) and the development's targets (the bearing) do not include it, and "
            "`ltca optimize` does not model it; the operation answers it: a cooler oil "
            "inlet, smoother flanks, a lower speed, or an oil of a higher scuffing "
            "temperature (its FZG load stage, [operating] lubricant) — the inlet "
            f"{plain_number(found.temperature - REMEDY_COOLER)} degC with Rq "
            f"{plain_number(found.roughness / REMEDY_SMOOTHER)} um{remedy} "
            "(docs/synthesis.md, \"Scuffing at the design torque\")")


def coast_design_torque(case, torque: float) -> float:
    """The coast flank's design torque [N·m] as ``ltca run --flank coast`` caps it
    (:func:`contact.pipeline.flank_torques`): the case's ``[rating]
    coast_design_torque`` where it lies in (0, ``torque``), else ``torque``.

    Parameters
    ----------
    case : geometry.case.Case
        The written case.
    torque : float — [N·m]
        The (drive) design torque written, its ``[rating] design_torque``.

    Returns
    -------
    float — [N·m]
    """
    from contact.optimize.written_notes import given_coast_torque

    coast = given_coast_torque(case)
    return coast if coast is not None and 0.0 < coast < torque else float(torque)


def _finite(**values: float) -> dict[str, float]:
    """The finite ones of ``values`` to 4 decimals, as the ``[development]`` table's
    ``root_safety_fe`` (TOML has no NaN: a value not computed is left out, as that table
    leaves out ``tolerant_up_to_Nm``)."""
    return {k: round(float(v), 4) for k, v in values.items() if math.isfinite(float(v))}


def scuffing_table(found: dict[str, DesignScuffing | str | None]) -> dict:
    """The ``[development.scuffing]`` table recording the check in the written case:
    per flank its design torque, S_B (to 4 decimals), the conditions and, where S_B is
    below the verdict's minimum, the remedy's conditions and S_B; TOML-safe (a value not computed
    left out, a flank not checked with its reason).

    Parameters
    ----------
    found : dict
        Per flank (``"drive"``, ``"coast"``) :func:`design_scuffing`'s result, None (no
        efficiency stage: pinion speed 0) or the text of what stopped the analysis.

    Returns
    -------
    dict
        ``{"note": str, "drive": {...}, "coast": {...}}`` (JSON- and TOML-safe).
    """
    from contact.study.verdicts import SCUFFING_MIN

    out: dict = {"note": (
        "informational (contact.optimize.written_scuffing): the LTCA's scuffing safety "
        "S_B (ISO/TS 6336-20 flash temperature on the loaded contact) of each flank at its "
        "design torque and the case's [operating] conditions, as ltca run (--flank coast) "
        f"computes it; below {SCUFFING_MIN:g} its verdict FAILs, and remedy holds S_B with "
        f"the oil inlet {REMEDY_COOLER:g} K cooler and Rq / {REMEDY_SMOOTHER:g} "
        "(docs/synthesis.md, 'Scuffing at the design torque')")}
    for flank, one in found.items():
        if one is None:
            out[flank] = {"checked": "no: the case's pinion speed is 0 (no efficiency "
                                     "stage, no S_B)"}
            continue
        if isinstance(one, str):
            out[flank] = {"checked": f"no: {one}"}
            continue
        row: dict = {"torque_Nm": float(one.torque),
                     **_finite(safety=one.safety),
                     "pinion_speed_rpm": float(one.pinion_speed),
                     "lubricant": one.lubricant,
                     "oil_inlet_temperature_degC": float(one.temperature),
                     "roughness_rq_um": float(one.roughness),
                     **_finite(scuffing_temperature_degC=one.scuffing_temperature)}
        if one.reason:
            row["reason"] = one.reason
        if math.isfinite(one.remedy_safety):
            row["remedy"] = {
                "oil_inlet_temperature_degC": float(one.temperature - REMEDY_COOLER),
                "roughness_rq_um": float(one.roughness / REMEDY_SMOOTHER),
                **_finite(safety=one.remedy_safety)}
        out[flank] = row
    return out


def _checked(case, torque: float, flank: str) -> DesignScuffing | str | None:
    """:func:`design_scuffing`, or the text of what stopped its analysis (said, not
    hidden)."""
    from geometry.core.errors import LTCAError

    try:
        return design_scuffing(case, torque, flank)
    # ValueError: a coast flank whose unloaded contact cannot be computed (written_contact
    # notes it and writes the case) fails as its analysis does there
    except (LTCAError, ValueError, ArithmeticError, RuntimeError) as exc:
        logger.info("scuffing of the %s flank not checked at %g N m: %s", flank, torque, exc)
        return str(exc)


@dataclass(frozen=True)
class CheckedScuffing:
    """The written case with its scuffing check recorded, and what ``ltca synthesize``
    says of it.

    Attributes
    ----------
    case : geometry.case.Case
        The case with ``[development.scuffing]`` (:func:`scuffing_table`).
    found : dict
        Per flank, :func:`design_scuffing`'s result, None or the text of what stopped it.
    lines : tuple of str
        One line per flank whose S_B is below the verdict's minimum
        (:func:`scuffing_note`) or whose check failed; each without its "note: ".
    """

    case: Any
    found: dict
    lines: tuple[str, ...]


def checked_scuffing(case, torque: float) -> CheckedScuffing:
    """Both flanks' scuffing safety of the written case at their design torques, recorded
    in its ``[development]`` table and said where ``ltca run`` would FAIL on it.

    Parameters
    ----------
    case : geometry.case.Case
        The written case (with its ``[development]`` table, which gains ``scuffing``).
    torque : float — [N·m]
        Its design torque; the coast flank's is :func:`coast_design_torque`.

    Returns
    -------
    CheckedScuffing

    Notes
    -----
    Two LTCAs at one torque each (drive, coast), plus the remedy's efficiency and
    scuffing steps on a failing flank's LTCA (no new LTCA). A torque that is not finite
    and positive checks nothing and records nothing. Source: :func:`design_scuffing`.
    """
    if not math.isfinite(torque) or torque <= 0.0:
        return CheckedScuffing(case, {}, ())
    torques = {"drive": float(torque), "coast": coast_design_torque(case, torque)}
    found = {flank: _checked(case, t, flank) for flank, t in torques.items()}
    lines = []
    for flank, one in found.items():
        if isinstance(one, str):
            which = "the design torque" if flank == "drive" else "the coast flank's design torque"
            run = "`ltca run`" if flank == "drive" else "`ltca run --flank coast`"
            lines.append(f"scuffing not checked at {which} {plain_number(torques[flank])} "
                         f"N m: {one} ({run} of the case judges it)")
        elif (line := scuffing_note(one)) is not None:
            lines.append(line)
    development = case.extra.get("development")
    if hasattr(development, "get"):
        extra = json.loads(json.dumps(
            {**case.extra, "development": {**development, TABLE: scuffing_table(found)}}))
        case = dataclasses.replace(case, extra=MappingProxyType(extra))
    return CheckedScuffing(case, found, tuple(lines))
