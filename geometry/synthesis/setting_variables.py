"""The machine settings and blade data of one flank as named variables.

Corrective settings (:mod:`geometry.synthesis.correction`) and the optimisation of machine
settings (:mod:`contact.optimize`) change a flank's tool by name: the cradle angle, radial
setting, ratio of roll, modified-roll and helical-motion coefficients, blade angle, point
radius … Each :class:`SettingVariable` says where the value lives (machine settings or
blade), its unit in files and reports, the step of its finite-difference sensitivity and
the processes it applies to (:data:`SETTING_VARIABLES`; :data:`DEFAULT_VARIABLES` per
process); :func:`setting_value`, :func:`tool_with_values` and :func:`case_with_values` read
and set them. :data:`COND_MAX` is the subset selection's limit of the correction (here,
with the names, so that ``ltca correct --help`` need not import the correction).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from geometry.core.errors import InputError

if TYPE_CHECKING:
    from geometry.case import Case, FlankTool

__all__ = [
    "COND_MAX",
    "DEFAULT_VARIABLES",
    "SETTING_VARIABLES",
    "SettingVariable",
    "case_with_values",
    "setting_value",
    "tool_with_values",
]

_DEG = math.pi / 180.0


@dataclass(frozen=True)
class SettingVariable:
    """One correctable setting of a flank's tools.

    Parameters
    ----------
    name : str
        The variable's name (the case file's field, or the summary's name of a Taylor
        coefficient: 2C, 6D, 24E, 120F, H1…H4, V1…V4).
    owner : str
        ``"machine"`` (:class:`geometry.machine.cradle.MachineSettings`) or ``"blade"``
        (:class:`geometry.machine.cutter.Blade`).
    field : str
        The dataclass field that holds it.
    index : int or None
        Position in the field's tuple of Taylor coefficients, None for a scalar field.
    unit : str
        Unit in case files and tables (``deg`` for angles).
    scale : float
        Internal value (rad, mm) per file unit (π/180 for ``deg``, else 1).
    step : float
        Trial finite-difference step in internal units (rescaled to move the flank by
        about 2 µm before the central difference).
    generate_only : bool
        Only a generated (rolled) flank has it.
    """

    name: str
    owner: str
    field: str
    index: int | None
    unit: str
    scale: float
    step: float
    generate_only: bool = False


def _registry() -> dict[str, SettingVariable]:
    out: dict[str, SettingVariable] = {}
    for name, unit, step in (("radial_setting", "mm", 1e-3), ("cradle_angle", "deg", 1e-5),
                             ("swivel", "deg", 1e-5), ("tilt", "deg", 1e-5),
                             ("machine_root_angle", "deg", 1e-5),
                             ("machine_center_to_back", "mm", 1e-3),
                             ("sliding_base", "mm", 1e-3), ("blank_offset", "mm", 1e-3)):
        out[name] = SettingVariable(name, "machine", name, None, unit,
                                    _DEG if unit == "deg" else 1.0, step)
    out["ratio_of_roll"] = SettingVariable("ratio_of_roll", "machine", "ratio_of_roll", None,
                                           "1", 1.0, 1e-5, True)
    for k, name in enumerate(("2C", "6D", "24E", "120F")):
        out[name] = SettingVariable(name, "machine", "modified_roll", k,
                                    "1/rad" if k == 0 else f"1/rad^{k + 1}", 1.0,
                                    1e-4 * 10.0**k, True)
    for field, letter in (("helical_motion", "H"), ("vertical_motion", "V")):
        for k in range(4):
            out[f"{letter}{k + 1}"] = SettingVariable(
                f"{letter}{k + 1}", "machine", field, k,
                "mm/rad" if k == 0 else f"mm/rad^{k + 1}", 1.0, 1e-3 * 10.0**k, True)
    out["point_radius"] = SettingVariable("point_radius", "blade", "point_radius", None,
                                          "mm", 1.0, 1e-3)
    out["blade_angle"] = SettingVariable("blade_angle", "blade", "blade_angle", None,
                                         "deg", _DEG, 1e-5)
    return out


#: correctable settings: name → :class:`SettingVariable`
SETTING_VARIABLES: Mapping[str, SettingVariable] = MappingProxyType(_registry())


#: default variables per process: those a gear shop changes to correct a flank (the
#: summary's basic settings, the modified roll of first orders, the blade's angle and point
#: radius); held fixed where the measurement does not determine them (module docstring)
DEFAULT_VARIABLES: Mapping[str, tuple[str, ...]] = MappingProxyType({
    "Generate": ("radial_setting", "cradle_angle", "ratio_of_roll", "sliding_base",
                 "blank_offset", "machine_center_to_back", "2C", "6D", "blade_angle",
                 "point_radius"),
    "Formate": ("radial_setting", "cradle_angle", "machine_root_angle",
                "machine_center_to_back", "blank_offset", "blade_angle", "point_radius"),
})


#: largest condition number of the unit-column Jacobian of the settings kept free: with
#: 1 µm measurement noise a combination of settings at σ₁/σ = 100 is uncertain by about
#: 100 µm of flank motion (column norm), i.e. about 15 µm RMS on a 45-point grid — beyond
#: that the measurement cannot tell the settings apart
COND_MAX = 100.0


def variables_of(process: str, names: Sequence[str] | None) -> list[SettingVariable]:
    """The variables ``names`` of a member's process (None: :data:`DEFAULT_VARIABLES`).

    Raises
    ------
    InputError
        An empty list, an unknown name, or a variable of the other process (``settings: …``).
    """
    names = DEFAULT_VARIABLES[process] if names is None else names
    if isinstance(names, str) or not isinstance(names, Sequence) or not names:
        raise InputError(f"settings: must be a non-empty list of names from "
                         f"{list(SETTING_VARIABLES)}, got {names!r}")
    out = []
    for name in names:
        if name not in SETTING_VARIABLES:
            raise InputError(f"settings: unknown setting {name!r}; accepted: "
                             f"{', '.join(SETTING_VARIABLES)}")
        var = SETTING_VARIABLES[name]
        if var.generate_only and process != "Generate":
            raise InputError(f"settings: {name!r} exists only for a generated flank (process "
                             f"'Generate'), this flank is {process!r}")
        if var in out:
            raise InputError(f"settings: {name!r} given twice")
        out.append(var)
    return out


def setting_value(tool: FlankTool, name: str) -> float:
    """A setting's value in a flank's tools.

    Parameters
    ----------
    tool : geometry.case.FlankTool
    name : str
        A key of :data:`SETTING_VARIABLES`.

    Returns
    -------
    float
        In internal units (rad, mm; Taylor coefficients as in
        :class:`geometry.machine.cradle.MachineSettings`); a coefficient beyond the given list is 0.

    Raises
    ------
    InputError
        For an unknown name.
    """
    _known(name)
    var = SETTING_VARIABLES[name]
    val = getattr(getattr(tool, var.owner), var.field)
    if var.index is None:
        return float(val)
    return float(val[var.index]) if var.index < len(val) else 0.0


def _known(name: str) -> None:
    """InputError unless ``name`` is a setting variable (the message lists them)."""
    # (imported here: the names and COND_MAX above serve `ltca correct --help`, which
    # should not import NumPy)
    from geometry.core.validation import one_of

    one_of("settings", name, list(SETTING_VARIABLES))


def tool_with_values(tool: FlankTool, values: Mapping[str, float]) -> FlankTool:
    """The flank's tools with some settings replaced, validated as a case file's are.

    Parameters
    ----------
    tool : geometry.case.FlankTool
    values : mapping name → float
        New values in internal units (rad, mm).

    Returns
    -------
    geometry.case.FlankTool

    Raises
    ------
    InputError
        For an unknown name or a value outside the setting's valid range (the message of
        :class:`geometry.machine.cradle.MachineSettings` / :class:`geometry.machine.cutter.Blade`).
    """
    changes: dict[str, dict] = {"machine": {}, "blade": {}}
    for name, value in values.items():
        _known(name)
        var = SETTING_VARIABLES[name]
        obj = getattr(tool, var.owner)
        if var.index is None:
            changes[var.owner][var.field] = float(value)
        else:
            seq = list(changes[var.owner].get(var.field, getattr(obj, var.field)))
            seq += [0.0] * (var.index + 1 - len(seq))
            seq[var.index] = float(value)
            changes[var.owner][var.field] = tuple(seq)
    machine = replace(tool.machine, **changes["machine"]) if changes["machine"] else tool.machine
    blade = replace(tool.blade, **changes["blade"]) if changes["blade"] else tool.blade
    return replace(tool, machine=machine, blade=blade)


def case_with_values(case: Case, member: str, flank: str, values: Mapping[str, float],
                     *, tool: FlankTool | None = None) -> Case:
    """A case with one flank's settings replaced (:func:`tool_with_values`).

    Parameters
    ----------
    case : geometry.case.Case
    member, flank : str
        ``"pinion"``/``"gear"``, ``"concave"``/``"convex"``.
    values : mapping name → float
        New values in internal units (rad, mm).
    tool : geometry.case.FlankTool, optional
        Use these tools instead of the case's (``values`` then apply to them).

    Returns
    -------
    geometry.case.Case

    Raises
    ------
    InputError
        As :func:`tool_with_values`, or for bad member/flank names.
    """
    mem = case.member(member)
    new = tool_with_values(mem.flank(flank) if tool is None else tool, values)
    return replace(case, **{member: replace(mem, **{flank: new})})
