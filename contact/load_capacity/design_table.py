"""A case's ``[design]`` table — its ISO 23509 basic design data — as the rating methods
read it: the table, or the refusal naming it, and its blank.

Public names
------------
design_table   the case's [design] table, or InputError saying the method needs one
design_blank   the ISO 23509 blank of a [design] table, errors naming ``design.<field>``
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["design_blank", "design_table"]


def design_table(case, needs: str) -> Mapping[str, Any]:
    """The case's ``[design]`` table.

    Parameters
    ----------
    case : geometry.case.Case
    needs : str
        What needs it and where the table is described, the refusal's text after
        ``"design: "`` up to ``"; this case has none"`` (e.g. ``"the ANSI/AGMA 2003-D19
        rating needs the case's basic design data, a [design] table (docs/rating.md)"``).

    Returns
    -------
    Mapping
        The table's fields (ISO 23509 basic data: z1, z2, de2, b2, beta_m … in degrees
        and mm, as a basic design file's ``[design]``).

    Raises
    ------
    InputError
        The case has no ``[design]`` table.
    """
    design = case.extra.get("design")
    if not isinstance(design, Mapping):
        raise InputError(f"design: {needs}; this case has none")
    return design


def design_blank(design: Mapping[str, Any]):
    """The ISO 23509 blank geometry of a ``[design]`` table.

    Parameters
    ----------
    design : Mapping
        The table (:func:`design_table`): the keywords of
        :meth:`geometry.iso23509.pitch_cone.BevelGearDesign.from_degrees`.

    Returns
    -------
    geometry.iso23509.blank.BlankGeometry
        ISO 23509's blank data (pitch cone, Annex C/D/E relations).

    Raises
    ------
    InputError
        A bad field, named ``design.<field>`` with its accepted range, or an unknown one.
    """
    from geometry.iso23509.pitch_cone import BevelGearDesign

    try:
        bevel = BevelGearDesign.from_degrees(**design)
        try:
            hash(bevel)
        except TypeError:  # a field of a type the memo cannot key: computed afresh
            from geometry.iso23509.blank import blank_geometry

            return blank_geometry(bevel)
        return _blank(bevel)
    except InputError as exc:
        raise InputError(f"design.{exc}") from None
    except TypeError as exc:
        raise InputError(f"design: {exc}") from None


@memoised(maxsize=32)
def _blank(design):
    """:func:`geometry.iso23509.blank.blank_geometry` of a design (frozen, hashable; the
    blank is frozen too): a warm analysis rates the same design again, and its pitch cone
    (Method 1's iteration over ``brentq``) cost ≈ 2 % of it (issue 75)."""
    from geometry.iso23509.blank import blank_geometry

    return blank_geometry(design)
