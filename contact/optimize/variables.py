"""The design variables of a machine-setting optimisation and how they change a case.

A variable is a setting of the pinion flank's tools — any name of
:data:`geometry.synthesis.correction.SETTING_VARIABLES` (machine settings, modified roll 2C…120F,
helical motion H1…H4, vertical motion V1…V4, blade angle, point radius), in its case-file
unit — or a profile relief (``tip_relief``, ``root_relief`` [µm], made by the blade's
flankrem and toprem, :func:`geometry.machine.relief.relieved_blade`). Values are handled in file
units (deg, mm, µm, 1/rad …) so bounds read as engineers write them.

When the start is a basic design (:class:`geometry.synthesis.basic_design.BasicDesign`, a
``cases/basic`` file), the local-synthesis inputs of the optimised flank are variables too
(:data:`SYNTHESIS_VARIABLES`: path angle, TE level, ellipse length, elastic approach,
relief start — and the relief, then a synthesis input): every design is then
re-synthesised (:func:`geometry.synthesis.case_synthesis.synthesize`, ≈ 6 s) before its settings
are set, so the flank keeps the synthesis' contact path, TE and ellipse at M (Litvin &
Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., ch. 9; seed future work (iv)).

Public functions
----------------
RELIEF_VARIABLES   the relief variables, name → unit
SYNTHESIS_VARIABLES the local-synthesis inputs (a basic-design start), name → unit
DesignVariable     a variable with its bounds (file units)
variable_unit      the file unit of a variable name
start_values       a variable's value in a case (file units)
synthesised_case   a basic design synthesised in the place of a case
case_at            the case with variable values set
check_variables    validate names and bounds against the case (before any work)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from geometry.case import Case
from geometry.core.errors import InputError
from geometry.machine.relief import blade_relief, relieved_blade
from geometry.synthesis.basic_design import (
    FLANK_OPTION_UNITS,
    BasicDesign,
    flank_option_values,
    with_flank_options,
)
from geometry.synthesis.correction import SETTING_VARIABLES, setting_value, tool_with_values
from geometry.synthesis.tip_plane import tip_plane_on_root_cone

__all__ = ["RELIEF_VARIABLES", "SYNTHESIS_VARIABLES", "DesignVariable", "case_at",
           "check_variables", "own_relief_start", "start_values", "synthesised_case",
           "variable_unit"]

#: relief variables (µm of normal relief at the flank's tip end / root end, mean section)
RELIEF_VARIABLES: Mapping[str, str] = {"tip_relief": "um", "root_relief": "um"}
_RELIEF_MAX = 200.0  # [µm] geometry.machine.relief's limit (0.2 mm)
#: local-synthesis inputs of the optimised flank (a basic-design start only), file units
SYNTHESIS_VARIABLES: Mapping[str, str] = {k: u for k, u in FLANK_OPTION_UNITS.items()
                                          if k not in RELIEF_VARIABLES}


def _synthesised(names: Sequence[str], basic: BasicDesign | None) -> set[str]:
    """The names that are synthesis inputs: SYNTHESIS_VARIABLES, and the relief when the
    start is a basic design."""
    if basic is None:
        return set()
    return {n for n in names if n in SYNTHESIS_VARIABLES or n in RELIEF_VARIABLES}


@dataclass(frozen=True)
class DesignVariable:
    """One optimisation variable.

    Parameters
    ----------
    name : str
        A key of :data:`geometry.synthesis.correction.SETTING_VARIABLES` or
        :data:`RELIEF_VARIABLES`.
    low, high : float
        Bounds in the variable's file unit (:func:`variable_unit`), low < high.
    """

    name: str
    low: float
    high: float


def variable_unit(name: str) -> str:
    """File unit of variable ``name``; InputError naming the accepted ones if unknown."""
    if name in RELIEF_VARIABLES:
        return RELIEF_VARIABLES[name]
    if name in SETTING_VARIABLES:
        return SETTING_VARIABLES[name].unit
    if name in SYNTHESIS_VARIABLES:
        return SYNTHESIS_VARIABLES[name]
    raise InputError(f"optimize.variables: unknown variable {name!r}; accepted: "
                     f"{', '.join([*SETTING_VARIABLES, *RELIEF_VARIABLES])}, and with a "
                     f"basic-design start {', '.join(SYNTHESIS_VARIABLES)}")


def _measured_relief(case: Case, flank: str) -> tuple[float, float]:
    """(tip, root) relief [µm] that the case's pinion flank's blade rems make
    (:func:`geometry.machine.relief.blade_relief`; 0, 0 for a blade without rems)."""
    mem = case.pinion
    tool = mem.flank(flank)
    tip, root = blade_relief(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    return 1e3 * tip, 1e3 * root


def start_values(case: Case, flank: str, names: Sequence[str], *,
                 basic: BasicDesign | None = None) -> np.ndarray:
    """Values of the variables ``names`` in the case's pinion flank ``flank`` [file units].

    Relief variables are the relief the blade's rems make at the flank's two ends, measured
    on the blade (:func:`geometry.machine.relief.blade_relief`; 0 without rems) — or, with a basic
    design ``basic`` (the design ``case`` was synthesised from), its prescriptions, as are
    the :data:`SYNTHESIS_VARIABLES`.
    """
    tool = case.pinion.flank(flank)
    synth = _synthesised(names, basic)
    prescribed = flank_option_values(basic.options.flank(flank)) if synth else {}
    out = []
    relief = None
    for name in names:
        if name in synth:
            out.append(prescribed[name])
        elif name in RELIEF_VARIABLES:
            if relief is None:
                relief = _measured_relief(case, flank)
            out.append(relief[0] if name == "tip_relief" else relief[1])
        else:
            var = SETTING_VARIABLES[name]
            out.append(setting_value(tool, name) / var.scale)
    return np.asarray(out, float)


def own_relief_start(case: Case, flank: str) -> float | None:
    """The ``relief_start`` [1] the case's synthesis recorded for its pinion flank ``flank``
    (``[synthesis.<flank>]``, written by ``ltca synthesize``), or None."""
    rec = case.extra.get("synthesis", {})
    rec = rec.get(flank) if isinstance(rec, Mapping) else None
    value = rec.get("relief_start") if isinstance(rec, Mapping) else None
    return float(value) if isinstance(value, (int, float)) else None


def synthesised_case(case: Case, basic: BasicDesign) -> Case:
    """``basic`` synthesised, in the place of ``case``.

    Parameters
    ----------
    case : geometry.case.Case
        The case being replaced: its name, misalignment, operating point and extra tables
        are kept (the synthesis' own ``extra["synthesis"]`` record replaces the old one).
    basic : geometry.synthesis.basic_design.BasicDesign
        The design to synthesise (angles in rad, lengths in mm inside).

    Returns
    -------
    geometry.case.Case

    Raises
    ------
    InputError
        A synthesis step without a solution (named by
        :func:`geometry.synthesis.case_synthesis.synthesize`:
        ISO 23509 blank, Litvin local synthesis, Litvin & Fuentes 2004 ch. 9).
    """
    from geometry.synthesis.case_synthesis import synthesize

    new = synthesize(basic)[0]
    return dataclasses.replace(new, name=case.name, misalignment=case.misalignment,
                               operating=case.operating,
                               extra=type(new.extra)({**case.extra, **new.extra}))


def case_at(case: Case, flank: str, names: Sequence[str], values, *,
            relief_start: float = 0.5, basic: BasicDesign | None = None) -> Case:
    """The case with the pinion flank's variables set.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str
        Pinion flank ``"concave"``/``"convex"``.
    names : sequence of str
        Variable names.
    values : array_like (len(names),)
        Values in file units (deg, mm, µm …).
    relief_start : float
        Where a relief starts (:func:`geometry.machine.relief.relieved_blade`) on a blade
        without that rem; a rem the blade has keeps its corner (the relief measured there
        by :func:`start_values` is the variable's start, so the start values give the case
        itself). Unused with ``basic`` (the basic design's own ``relief_start``, or the
        variable, holds).
    basic : geometry.synthesis.basic_design.BasicDesign, optional
        The design ``case`` was synthesised from: synthesis variables (and the relief) are
        set in its prescriptions for ``flank`` and the design re-synthesised
        (:func:`synthesised_case`) before the settings are set.

    Returns
    -------
    geometry.case.Case

    Raises
    ------
    InputError
        A value outside the setting's valid range (the dataclass's message), a relief the
        blade cannot make, or a synthesis that has no solution (named by the synthesis).

    Notes
    -----
    With ``basic``, synthesis first; then the settings are set (a value equal to the
    case's own leaves the setting as it is); a relief variable without ``basic`` then
    re-makes the blade's rems at their own corners on the new flank (both reliefs, the one
    not varied kept at its start value measured on the case) where a setting or a relief
    changed. Values equal to the case's own (:func:`start_values`) return ``case`` itself.
    """
    synth = _synthesised(names, basic)
    if synth:
        prescribed = {n: float(v) for n, v in zip(names, values, strict=True) if n in synth}
        case = synthesised_case(case, with_flank_options(basic, flank, prescribed))
        kept = [(n, v) for n, v in zip(names, values, strict=True) if n not in synth]
        names, values = [n for n, _ in kept], [v for _, v in kept]
    mem = case.pinion
    tool = mem.flank(flank)
    # a setting at the case's own value leaves the tool as it is (no re-placed tip plane),
    # so that the start design is the case itself
    settings = {}
    for n, v in zip(names, values, strict=True):
        if n in RELIEF_VARIABLES:
            continue
        value = float(v) * SETTING_VARIABLES[n].scale
        if not math.isclose(value, setting_value(tool, n), rel_tol=1e-12, abs_tol=1e-15):
            settings[n] = value
    new = tool_with_values(tool, settings) if settings else tool
    if settings and new.machine.process == "Generate":
        # a setting moves the cut's root line: its tip plane back onto the root cone, as
        # the synthesis' step 8 (the flank is unchanged)
        placed = tip_plane_on_root_cone(new.blade, new.machine, mem.blank, mem.hand)
        new = dataclasses.replace(new, blade=placed.blade, machine=placed.settings)
    relief = {n: float(v) for n, v in zip(names, values, strict=True) if n in RELIEF_VARIABLES}
    if relief:
        own = dict(zip(RELIEF_VARIABLES, _measured_relief(case, flank), strict=True))
        relief = own | relief
        if settings or any(not math.isclose(relief[n], own[n], rel_tol=1e-12, abs_tol=1e-9)
                           for n in RELIEF_VARIABLES):
            # the blade's own rem corners kept (the relief measured there is the
            # variable's start), a rem the blade lacks from relief_start
            b = tool.blade
            corners = (b.flankrem_height if b.flankrem_angle != 0.0 else None,
                       b.toprem_height if b.toprem_angle != 0.0 else None)
            blade = relieved_blade(new.blade, new.machine, mem.blank, mem.hand,
                                   case.gear.blank, tip_relief=1e-3 * relief["tip_relief"],
                                   root_relief=1e-3 * relief["root_relief"],
                                   start=relief_start, corners=corners)
            new = dataclasses.replace(new, blade=blade)
    if new is tool:
        return case
    return dataclasses.replace(case, pinion=dataclasses.replace(mem, **{flank: new}))


def check_variables(case: Case, flank: str, variables: Sequence[DesignVariable], *,
                    basic: BasicDesign | None = None) -> None:
    """Refuse unknown names and bounds outside a variable's valid range, before any work.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str
    variables : sequence of DesignVariable
    basic : geometry.synthesis.basic_design.BasicDesign, optional
        The design ``case`` was synthesised from; needed by :data:`SYNTHESIS_VARIABLES`.

    Raises
    ------
    InputError
        No variables, a name given twice or unknown, a setting the pinion's process lacks,
        a synthesis variable without a basic design, bounds not finite or not low < high,
        or a bound at which the setting or prescription is invalid (the message names the
        variable, the bound and the setting's own complaint).
    """
    if not variables:
        raise InputError("optimize.variables: give at least one variable")
    names = [v.name for v in variables]
    for v in variables:
        unit = variable_unit(v.name)
        if names.count(v.name) > 1:
            raise InputError(f"optimize.variables: {v.name!r} given twice")
        var = SETTING_VARIABLES.get(v.name)
        if var is not None and var.generate_only and case.pinion.process != "Generate":
            raise InputError(f"optimize.variables: {v.name!r} exists only for a generated "
                             f"pinion, this one is {case.pinion.process!r}")
        if not (math.isfinite(v.low) and math.isfinite(v.high) and v.low < v.high):
            raise InputError(f"optimize.bounds.{v.name}: must be finite with low < high, got "
                             f"({v.low:g}, {v.high:g}) {unit}")
        if v.name in SYNTHESIS_VARIABLES and basic is None:
            raise InputError(f"optimize.variables: {v.name!r} is a synthesis input; start "
                             "from the basic design file (e.g. ltca optimize "
                             "cases/basic/NAME.toml), not a case")
        for b in (v.low, v.high):
            if v.name in SYNTHESIS_VARIABLES or (basic is not None and
                                                 v.name in RELIEF_VARIABLES):
                try:
                    with_flank_options(basic, flank, {v.name: b})
                except InputError as exc:
                    raise InputError(f"optimize.bounds.{v.name}: {b:g} {unit} lies outside "
                                     f"the prescription's valid range ({exc})") from None
                continue
            if v.name in RELIEF_VARIABLES:
                if not 0.0 <= b < _RELIEF_MAX:
                    raise InputError(f"optimize.bounds.{v.name}: {b:g} um lies outside the "
                                     f"valid range [0, {_RELIEF_MAX:g}) um")
                continue
            try:
                tool_with_values(case.pinion.flank(flank), {v.name: b * var.scale})
            except InputError as exc:
                raise InputError(f"optimize.bounds.{v.name}: {b:g} {unit} lies outside the "
                                 f"setting's valid range ({exc})") from None
