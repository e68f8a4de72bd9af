"""The design variables of a machine-setting optimisation and how they change a case.

A variable is a setting of the pinion flank's tools — any name of
:data:`geometry.correction.SETTING_VARIABLES` (machine settings, modified roll 2C…120F,
helical motion H1…H4, vertical motion V1…V4, blade angle, point radius), in its case-file
unit — or a profile relief (``tip_relief``, ``root_relief`` [µm], made by the blade's
flankrem and toprem, :func:`geometry.relief.relieved_blade`). Values are handled in file
units (deg, mm, µm, 1/rad …) so bounds read as engineers write them.

Public functions
----------------
RELIEF_VARIABLES   the relief variables, name → unit
DesignVariable     a variable with its bounds (file units)
variable_unit      the file unit of a variable name
start_values       a variable's value in a case (file units)
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
from geometry.correction import SETTING_VARIABLES, setting_value, tool_with_values
from geometry.errors import InputError
from geometry.relief import blade_relief, relieved_blade

__all__ = ["RELIEF_VARIABLES", "DesignVariable", "case_at", "check_variables",
           "start_values", "variable_unit"]

#: relief variables (µm of normal relief at the flank's tip end / root end, mean section)
RELIEF_VARIABLES: Mapping[str, str] = {"tip_relief": "um", "root_relief": "um"}
_RELIEF_MAX = 200.0  # [um] geometry.relief's limit (0.2 mm)


@dataclass(frozen=True)
class DesignVariable:
    """One optimisation variable.

    Parameters
    ----------
    name : str
        A key of :data:`geometry.correction.SETTING_VARIABLES` or :data:`RELIEF_VARIABLES`.
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
    raise InputError(f"optimize.variables: unknown variable {name!r}; accepted: "
                     f"{', '.join([*SETTING_VARIABLES, *RELIEF_VARIABLES])}")


def _measured_relief(case: Case, flank: str) -> tuple[float, float]:
    """(tip, root) relief [µm] that the case's pinion flank's blade rems make
    (:func:`geometry.relief.blade_relief`; 0, 0 for a blade without rems)."""
    mem = case.pinion
    tool = mem.flank(flank)
    tip, root = blade_relief(tool.blade, tool.machine, mem.blank, mem.hand, case.gear.blank)
    return 1e3 * tip, 1e3 * root


def start_values(case: Case, flank: str, names: Sequence[str]) -> np.ndarray:
    """Values of the variables ``names`` in the case's pinion flank ``flank`` [file units].

    Relief variables are the relief the blade's rems make at the flank's two ends, measured
    on the blade (:func:`geometry.relief.blade_relief`; 0 without rems).
    """
    tool = case.pinion.flank(flank)
    out = []
    relief = None
    for name in names:
        if name in RELIEF_VARIABLES:
            if relief is None:
                relief = _measured_relief(case, flank)
            out.append(relief[0] if name == "tip_relief" else relief[1])
        else:
            var = SETTING_VARIABLES[name]
            out.append(setting_value(tool, name) / var.scale)
    return np.asarray(out, float)


def case_at(case: Case, flank: str, names: Sequence[str], values, *,
            relief_start: float = 0.5) -> Case:
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
        Where a relief starts (:func:`geometry.relief.relieved_blade`).

    Returns
    -------
    geometry.case.Case

    Raises
    ------
    InputError
        A value outside the setting's valid range (the dataclass's message), or a relief
        the blade cannot make.

    Notes
    -----
    The settings are set first; a relief variable then re-makes the blade's rems on the new
    flank (both reliefs, the one not varied kept at its start value measured on the case).
    """
    mem = case.pinion
    tool = mem.flank(flank)
    settings = {n: float(v) * SETTING_VARIABLES[n].scale
                for n, v in zip(names, values, strict=True) if n not in RELIEF_VARIABLES}
    new = tool_with_values(tool, settings) if settings else tool
    relief = {n: float(v) for n, v in zip(names, values, strict=True) if n in RELIEF_VARIABLES}
    if relief:
        missing = [n for n in RELIEF_VARIABLES if n not in relief]
        if missing:
            kept = _measured_relief(case, flank)
            relief |= {n: kept[list(RELIEF_VARIABLES).index(n)] for n in missing}
        blade = relieved_blade(new.blade, new.machine, mem.blank, mem.hand, case.gear.blank,
                               tip_relief=1e-3 * relief["tip_relief"],
                               root_relief=1e-3 * relief["root_relief"], start=relief_start)
        new = dataclasses.replace(new, blade=blade)
    return dataclasses.replace(case, pinion=dataclasses.replace(mem, **{flank: new}))


def check_variables(case: Case, flank: str, variables: Sequence[DesignVariable]) -> None:
    """Refuse unknown names and bounds outside a variable's valid range, before any work.

    Raises
    ------
    InputError
        No variables, a name given twice or unknown, a setting the pinion's process lacks,
        bounds not finite or not low < high, or a bound at which the setting is invalid
        (the message names the variable, the bound and the setting's own complaint).
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
        for b in (v.low, v.high):
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
