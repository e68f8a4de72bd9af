"""The case ``ltca synthesize`` writes of a development, for the Python API alike
(issue 71: "from basic data, through the CLI and the Python API alike").

:func:`contact.optimize.development.develop` returns the developed, synthesised case
(:attr:`~contact.optimize.development_result.DevelopmentResult.case`); ``ltca synthesize``
writes it with the torques the development decided: the rating's design torque (the basic
file's ``[synthesis] design_torque``, else the ISO 10300 long-life capacity, else the
bearing's own lowered capacity), the development's record and operating torques, and the
coast side's design torque (its ISO 10300 capacity, no higher than what the coast flank's
bearing carries). :func:`written_case` is that one sequence, which the command and a
script both call, so that ``ltca run`` of the written file and ``run_analysis`` of the
returned case rate and judge the same torques.

:func:`with_synthesis_fe_level` gives a basic design without a ``[root_stress]
fe_level`` the level ``ltca synthesize`` checks its root stress on
(:data:`contact.compliance.fe.options.SYNTHESIS_LEVEL`), which ``develop`` applies.

Public names
------------
WrittenCase, written_case, with_synthesis_fe_level
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

from geometry.case import Case

#: What the coast side's design torque is where the development did not lower it.
COAST_CAPACITY_WHY = ("the ISO 10300 capacity of the coast side (above it the coast side is "
                      "rated at a finite life)")


@dataclass(frozen=True)
class WrittenCase:
    """The case ``ltca synthesize`` writes and the torques it states.

    Attributes
    ----------
    case : geometry.case.Case
        The developed case with ``[rating] design_torque`` (and ``coast_design_torque``
        where the coast side carries less), the ``[development]`` table and the operating
        torques (light, design) [N·m] where the basic file gave none.
    torque : float — [N·m]
        The drive side's design torque written.
    torque_why : str
        Where it comes from (words).
    coast_torque : float — [N·m]
        The coast side's design torque written (NaN where it is the design torque).
    coast_why : str
        Where it comes from (words).
    """

    case: Case
    torque: float
    torque_why: str
    coast_torque: float
    coast_why: str


def written_case(development: Any, design_torque: float | None = None) -> WrittenCase:
    """The case of a development as ``ltca synthesize`` writes it.

    Parameters
    ----------
    development : contact.optimize.development_result.DevelopmentResult
        What :func:`contact.optimize.development.develop` returned.
    design_torque : float — [N·m], optional
        The basic file's ``[synthesis] design_torque``; default: that of the developed
        basic design (``development.basic``; the remedied one where a remedy was applied).

    Returns
    -------
    WrittenCase
        The case and the drive and coast design torques written, with their reasons.

    Raises
    ------
    InputError
        A case whose ``[design]`` or ``[rating]`` table the rating refuses (the field
        named, :func:`contact.load_capacity.iso10300.capacity.with_design_torque`).

    Notes
    -----
    The sequence of ``ltca synthesize`` (``contact/commands/synthesize.py``): the rating's
    design torque (:func:`~contact.load_capacity.iso10300.capacity.with_design_torque`:
    the given torque, else the ISO 10300 long-life capacity, ISO 10300-2/-3:2014), the
    development's record (:meth:`~contact.optimize.development_result.DevelopmentResult.
    recorded`, which writes a design torque the development lowered to the bearing's
    capacity), the coast side's ISO 10300 capacity
    (:func:`~contact.load_capacity.iso10300.capacity.with_coast_design_torque`), capped
    at the coast flank's bearing capacity
    (:meth:`~contact.optimize.development_result.DevelopmentResult.with_coast_capacity`).
    """
    from contact.load_capacity.iso10300.capacity import (
        with_coast_design_torque,
        with_design_torque,
    )

    basic = development.basic
    given = basic.options.design_torque if design_torque is None else design_torque
    case, torque, torque_why = with_design_torque(development.case, given)
    case = development.recorded(case)
    if development.torque_lowered:  # the developed bearing's own capacity
        torque, torque_why = float(development.torque[1]), development.torque_source
    case, coast_torque = with_coast_design_torque(case)
    coast_why = COAST_CAPACITY_WHY
    case, capacity = development.with_coast_capacity(case)
    if math.isfinite(capacity):  # no higher than what the coast flank's bearing carries
        coast_torque, coast_why = capacity, development.coast_capacity_text
    return WrittenCase(case, float(torque), torque_why, coast_torque, coast_why)


def with_synthesis_fe_level(basic: Any) -> Any:
    """``basic`` with ``[root_stress] fe_level`` = the level ``ltca synthesize`` checks a
    new design's root stress on where the basic design names none.

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign

    Returns
    -------
    BasicDesign
        ``basic`` itself where its ``root_stress`` names a level, else a copy naming
        :data:`contact.compliance.fe.options.SYNTHESIS_LEVEL` (``"coarse10"``: its peak root
        stress −1.0 … +7.1 % of the default model's at about half its build CPU,
        docs/fe.md).
    """
    from contact.compliance.fe.options import SYNTHESIS_LEVEL

    if "fe_level" in basic.root_stress:
        return basic
    return dataclasses.replace(basic, root_stress={**dict(basic.root_stress),
                                                   "fe_level": SYNTHESIS_LEVEL})
