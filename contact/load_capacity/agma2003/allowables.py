"""Allowable stress numbers and elastic constants of the ANSI/AGMA 2003-D19 rating.

The numbers come from the toolkit's one material table
(``geometry/core/data/materials.toml``): the group ``agma2003_allowable`` of a material
holds s_ac and s_at by metallurgical grade (clause 21), ``elastic`` its E and ν. A
``[agma2003]`` table may give s_ac, s_at, E and ν itself
(:class:`contact.load_capacity.agma2003.inputs.AGMAInputs`).
"""

from __future__ import annotations

from geometry.core.errors import InputError
from geometry.core.materials import material

__all__ = ["allowable_stress_numbers"]


def allowable_stress_numbers(material_key: str, grade: int) -> tuple[float, float]:
    """(s_ac, s_at) [MPa] of a material of the table at a metallurgical grade.

    Parameters
    ----------
    material_key : str
        A name of the material table (a case member's ``material``).
    grade : int
        Metallurgical grade, 1, 2 or 3.

    Returns
    -------
    (float, float) — [MPa]
        The allowable contact and bending stress numbers s_ac, s_at (for 1e9 and 1e7 load
        cycles at 99 % reliability).

    Raises
    ------
    InputError
        A material without the group ``agma2003_allowable`` (give s_ac and s_at in the
        ``[agma2003]`` table) or a grade it does not list.

    Notes
    -----
    ANSI/AGMA 2003-D19 clause 21 (its SI tables of allowable stress numbers); the source of
    the numbers is the group's ``source`` in the table.
    """
    group = material(material_key).groups.get("agma2003_allowable")
    if group is None:
        raise InputError(f"grade: the material {material_key!r} has no ANSI/AGMA 2003 "
                         "allowable stress numbers (group agma2003_allowable of "
                         "geometry/core/data/materials.toml); give s_ac and s_at "
                         "[pinion, gear] [MPa] in the [agma2003] table")
    grades = list(group["grades"])
    if grade not in grades:
        raise InputError(f"grade: must be one of {grades} for {material_key!r}, got {grade!r}")
    i = grades.index(grade)
    return float(group["contact_allowable"][i]), float(group["bending_allowable"][i])
