"""The ISO 23509 Method 1 inputs of a face-hobbing method's pitch cone, face milled.

Methods 2 (Oerlikon) and 3 (Klingelnberg) are implemented for face hobbing only (z0 ≥ 1
blade groups); a face-milled pair typed by them is refused, and the user retypes it by
Method 1, which takes the gear's outer pitch diameter d_e2 and the pinion's mean spiral angle
β_m1. :func:`method_1_inputs` gives those two numbers of the typed method's pitch cone in its
face-milling limit z0 → 0 (the cutter's lead angle ν = 0, the lengthwise radius r_c0), so
that the refusal can name them (issue 71, round 28: three rounds of unseen designs worked
them out by hand from a face-hobbed twin of the blank).

Public names
------------
method_1_inputs     (d_e2, β_m1) of a Method 2 or 3 design in the face-milling limit
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geometry.core.errors import InputError

if TYPE_CHECKING:
    from geometry.iso23509.design_data import BevelGearDesign

__all__ = ["method_1_inputs"]


def method_1_inputs(design: BevelGearDesign) -> tuple[float, float] | None:
    """The Method 1 inputs of ``design``'s pitch cone in the face-milling limit.

    Parameters
    ----------
    design : BevelGearDesign
        A validated design of ``method`` 2 or 3 (its ``z0`` is taken as given: 0 for the
        face-milling limit).

    Returns
    -------
    (float, float) or None
        The gear's outer pitch diameter d_e2 = 2 R_e2 sin δ2 [mm] and the pinion's mean
        spiral angle β_m1 [deg] of that pitch cone; None where the method finds no pitch
        cone for these data (its own refusal then stands alone).

    Raises
    ------
    InputError
        ``design.method`` not 2 or 3.

    Notes
    -----
    Source: ISO 23509:2016 cl. 5 (Methods 2 and 3; Method 1's input data d_e2, β_m1), with
    the face-hobbing trace of :func:`geometry.iso23509.pitch_cone.face_hobbing_trace` at
    z0 = 0. Method 1 solves another closing condition (Gleason's: the limit radius equals
    r_c0), so retyped with these two numbers it gives back the typed d_m2 and β_m2 only
    nearly: d_m2 199.3 mm for 200 and β_m2 34.965° for 35° on the 14×45 at Σ 84° of round 28
    (tests/test_synthesize_basic_errors.py).
    """
    from geometry.iso23509.pitch_cone import PITCH_CONE_METHODS

    if design.method not in (2, 3):
        raise InputError(f"method: must be 2 or 3 (a face-hobbing method) [1], got "
                         f"{design.method!r}")
    try:
        cone = PITCH_CONE_METHODS[design.method](design)
    except InputError:
        return None
    de2 = 2.0 * cone.Re2 * math.sin(cone.delta2)
    if not (math.isfinite(de2) and math.isfinite(cone.beta_m1)):
        return None
    return de2, math.degrees(cone.beta_m1)
