"""Inputs of the finite-element model of a member's teeth: one validated dataclass.

:class:`FEOptions` holds everything that shapes the solid, its mesh, its material, its
support and the grid of unit loads of the influence coefficients. Every field enters the
cache key of the influence coefficients (:mod:`contact.compliance.fe.cache`), so a changed
setting builds them again.

Public names
------------
FEOptions          the options, validated on construction
LEVELS             named FE models (FEOptions.at_level) → the fields each sets
LEVEL_ACCURACY     named FE model → its peak root stress against the default model's (words)
CASE_TABLE         the case's table naming the FE level of its root stress ("root_stress")
SYNTHESIS_LEVEL    the level ``ltca synthesize`` writes into a new design's case
fe_level_of        the FE level a case's ``[root_stress]`` table names, validated
case_fe_options    the FE model of a case's root stress: its level's FEOptions
level_name         the level an FEOptions is (None for another model)
level_hint         how to give a level name where an FEOptions goes (for refusals)
with_fe_level      a case with the FE level of its root stress written
ELEMENTS           element name → (scikit-fem element class, nodes per element)
CONSTRAINTS        support name → what is held fixed (words; the facets are chosen in
                   :mod:`contact.compliance.fe.solid`)
SLOT_BOTTOMS       slot-bottom rule of separately cut teeth → what it rounds (words)
FLANK_ROLES        flank role of the pinion ("drive", "coast") → pinion flank
MATING_FLANK       pinion flank → the gear flank it meshes with
member_flank       the flank of a member that plays a role
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass
from typing import Any

import skfem

from geometry.core.errors import InputError
from geometry.core.hertz import STEEL
from geometry.core.validation import integer, one_of, positive, real

__all__ = [
    "CASE_TABLE",
    "CONSTRAINTS",
    "ELEMENTS",
    "FLANK_ROLES",
    "LEVELS",
    "LEVEL_ACCURACY",
    "MATING_FLANK",
    "SLOT_BOTTOMS",
    "SYNTHESIS_LEVEL",
    "FEOptions",
    "case_fe_options",
    "fe_level_of",
    "level_hint",
    "level_name",
    "member_flank",
    "with_fe_level",
]

#: element name → (scikit-fem element, nodes per element). Both are quadratic: the
#: 27-node triquadratic Lagrange hexahedron and the 20-node serendipity one; the geometry
#: is always mapped isoparametrically by 27-node hexahedra (skfem.MeshHex2), so curved
#: flanks and fillets are followed to second order by either.
ELEMENTS: dict[str, tuple[type, int]] = {
    "hex27": (skfem.ElementHex2, 27),
    "hex20": (skfem.ElementHexS2, 20),
}

#: where the member is held: "bore" — the rim's inner surface (the cone parallel to the
#: root cone ``rim_depth`` below the deepest point of the slot bottoms) is fixed, as a gear
#: body seated on a shaft or a pinion's solid shank; "back_face" — the rim's face on the
#: back cone (heel end, below the roots) is fixed, as a gear bolted at its back
CONSTRAINTS: dict[str, str] = {
    "bore": "the rim's inner (bore) surface is fixed",
    "back_face": "the rim's back-cone face at the heel is fixed",
}

#: slot-bottom rule of separately cut teeth (:mod:`contact.compliance.fe.section`) → words
SLOT_BOTTOMS: dict[str, str] = {
    "crossing": "the two cuts' crossing rounded by the largest radius up to the edge "
                "radius that keeps both fillets (down to a tenth of it), else by up to "
                "that tenth",
    "edge_radius": "the two cuts' crossing rounded by the blades' edge radius, the "
                   "cutter tip's corner, also where it replaces a crossed fillet's top",
}

#: pinion flank → the gear flank it meshes with (concave pinion flanks mesh convex ones)
MATING_FLANK: dict[str, str] = {"concave": "convex", "convex": "concave"}

#: flank role → the pinion flank of a case that plays it (as contact.utca.easeoff)
FLANK_ROLES = ("drive", "coast")

#: named FE models (:meth:`FEOptions.at_level`; issue 75) → the fields each sets, every
#: other field at its default. ``"default"``: :class:`FEOptions` as it is. ``"coarse"``:
#: 8 elements along the face instead of 12, the root, flank, half-slot and rim divisions
#: / 1.5 (fillet 4, flank 5, slot 2, rim 3; the elements across the tooth follow the root
#: size) and the unit loads of rows 0, 1, 2, 4, 6, 8, 10 of the 11 only
#: (``load_row_step=2``): 39 282 / 28 572 unknowns and 147 loads per flank on the 10×43
#: hypoid against 83 172 / 73 992 and 231, its build of both members and both flanks 0.42–0.50
#: of the default's CPU. Its peak root stress against the default model's, measured on
#: four designs, both flanks, both members, at each flank's torques: docs/fe.md, "A
#: coarse model for a new design". ``"coarse10"``: the same with 10 elements along the
#: face (its peak root stress −1.03 … +7.08 % of the default model's on the same four
#: designs: low by at most ~1 %, the unsafe side), the root-stress model of the cases
#: ``ltca synthesize`` writes (:data:`SYNTHESIS_LEVEL`; issue 75). A case names its
#: level in ``[root_stress] fe_level`` (:func:`fe_level_of`); absent, the default.
LEVELS: dict[str, dict[str, int]] = {
    "default": {},
    "coarse": {"face_divisions": 8, "fillet_divisions": 4, "flank_divisions": 5,
               "slot_divisions": 2, "rim_divisions": 3, "load_row_step": 2},
    "coarse10": {"face_divisions": 10, "fillet_divisions": 4, "flank_divisions": 5,
                 "slot_divisions": 2, "rim_divisions": 3, "load_row_step": 2},
}

#: level → its peak root stress (``root_stress_max``) against the default model's, as
#: measured on four designs (the default case, the 10×43 and 5×43 hypoids, the
#: face-hobbed 11×46), both flanks, both members, at each flank's torques (docs/fe.md,
#: "A coarse model for a new design"); what ``ltca run``, the file's summary and the
#: verdict say beside a root stress of that level
LEVEL_ACCURACY: dict[str, str] = {
    "default": "mesh-converged within 5 %",
    "coarse": "−3.6 … +6.3 % against the default mesh",
    "coarse10": "−1.0 … +7.1 % against the default mesh",
}

#: the case table that names the FE level of the case's root stress (``fe_level``)
CASE_TABLE = "root_stress"

#: the FE level ``ltca synthesize`` develops a new design with and writes into its case:
#: 0.5–0.6 of the default build's CPU, its peak root stress low by at most ~1 % (the
#: unsafe side) and high by up to 7 % (docs/fe.md)
SYNTHESIS_LEVEL = "coarse10"


def fe_level_of(case_or_table: Any) -> str:
    """The FE level (a key of :data:`LEVELS`) of a case's root stress: its
    ``[root_stress] fe_level``, ``"default"`` where the table or the field is absent.

    Parameters
    ----------
    case_or_table : geometry.case.Case or mapping
        A case (its ``extra["root_stress"]``, the file's ``[root_stress]`` table) or the
        table itself (a basic design file's).

    Returns
    -------
    str — a key of :data:`LEVELS`

    Raises
    ------
    InputError
        The table not a table, a field other than ``fe_level``, or a level not in
        :data:`LEVELS` (the message names ``root_stress.fe_level`` and the levels).
    """
    if hasattr(case_or_table, "extra"):
        table = case_or_table.extra.get(CASE_TABLE, {})
    else:
        table = {} if case_or_table is None else case_or_table
    if not hasattr(table, "keys"):
        raise InputError(f"{CASE_TABLE}: must be a table (fe_level = one of "
                         f"{', '.join(map(repr, LEVELS))}), got {table!r}")
    unknown = sorted(set(table) - {"fe_level"})
    if unknown:
        raise InputError(f"{CASE_TABLE}.{unknown[0]}: unknown field (the table has one: "
                         f"fe_level, the FE model of the root stress)")
    level = table.get("fe_level", "default")
    if not isinstance(level, str) or level not in LEVELS:
        raise InputError(f"{CASE_TABLE}.fe_level: must be one of "
                         f"{', '.join(map(repr, LEVELS))} (the FE model of the root stress, "
                         f"docs/fe.md), got {level!r}")
    return level


def case_fe_options(case) -> FEOptions:
    """The FE model of ``case``'s root stress: :meth:`FEOptions.at_level` of its level
    (:func:`fe_level_of`; ``FEOptions()`` where the case names none).

    Raises
    ------
    InputError — as :func:`fe_level_of`.
    """
    return FEOptions.at_level(fe_level_of(case))


def level_name(options: FEOptions) -> str | None:
    """The key of :data:`LEVELS` whose model ``options`` is (every field equal), else
    None (a model of the user's own)."""
    for name in LEVELS:
        if options == FEOptions.at_level(name):
            return name
    return None


def level_hint(value: Any) -> str:
    """The end of a refusal where an FEOptions goes and ``value`` was given: where it is
    a string (``ltca``'s ``--fe-level`` spelling), how the API says it —
    ``FEOptions.at_level(NAME)`` — and the levels (:data:`LEVELS`); else ``""``.

    Parameters
    ----------
    value : object
        What the caller gave.

    Returns
    -------
    str
        ``"; a named FE level is FEOptions.at_level('coarse') (levels: …)"`` or ``""``.
    """
    if not isinstance(value, str):
        return ""
    known = value in LEVELS
    return (f"; {'the' if known else 'a'} named FE level "
            f"{'is' if known else 'is given as'} "
            f"FEOptions.at_level({value if known else 'NAME'!r}) (levels: "
            f"{', '.join(sorted(LEVELS))})")


def with_fe_level(case, level: str):
    """``case`` with ``[root_stress] fe_level = level`` written into its tables (the
    case ``ltca synthesize`` writes names the level its root-stress checks used).

    Parameters
    ----------
    case : geometry.case.Case
    level : str — a key of :data:`LEVELS`

    Returns
    -------
    geometry.case.Case

    Raises
    ------
    InputError — an unknown level (the message lists :data:`LEVELS`).
    """
    from types import MappingProxyType

    fe_level_of({"fe_level": level})
    extra = {**case.extra, CASE_TABLE: {"fe_level": level}}
    return dataclasses.replace(case, extra=MappingProxyType(extra))


def member_flank(case, member: str, flank: str) -> str:
    """The flank name (``"concave"``/``"convex"``) of ``member`` that plays ``flank``.

    Parameters
    ----------
    case : geometry.case.Case
    member : str — ``"pinion"`` or ``"gear"``
    flank : str — ``"drive"``, ``"coast"`` (the pinion's drive flank is the case's
        ``pair.drive_flank``; the gear's is the one it meshes with) or a flank name

    Returns
    -------
    str — ``"concave"`` or ``"convex"``

    Raises
    ------
    InputError — an unknown member or flank name.
    """
    one_of("member", member, ("pinion", "gear"))
    one_of("flank", flank, (*FLANK_ROLES, *MATING_FLANK))
    if flank in MATING_FLANK:
        return flank
    pinion = case.pair.drive_flank if flank == "drive" else MATING_FLANK[case.pair.drive_flank]
    return pinion if member == "pinion" else MATING_FLANK[pinion]


@dataclass(frozen=True)
class FEOptions:
    """Solid, mesh, material, support and load grid of a member's FE model.

    Parameters
    ----------
    teeth : int — [1]
        Teeth modelled: the loaded tooth in the middle and (teeth − 1)/2 neighbours on
        each side; odd, 3 to 9.
    rim_depth : float or None — [mm]
        Depth of the rim under the slots: its inner surface is the cone parallel to the
        blank's root cone this far below the deepest point of the generated slot
        bottoms. Default None: 1.2 × the outer whole depth, the rim thickness above
        which ISO 6336-3 (rim factor Y_B = 1 for s_R/h_t ≥ 1.2) treats a gear as solid;
        for a member whose body is a solid shaft (a small hypoid pinion, where that rim
        would come near or through the axis) the depth that stops at a quarter of the
        root radius, the core inside held rigid
        (:func:`contact.compliance.fe.solid.default_rim_depth`). > 0.
    constraint : str
        What is fixed, a key of :data:`CONSTRAINTS` (default ``"bore"``).
    element : str
        A key of :data:`ELEMENTS` (default ``"hex20"``: the 27-node element needs ~1.9×
        the unknowns for the same mesh).
    face_divisions : int — [1]
        Elements along the face width (toe → heel), uniform in the lengthwise fraction;
        2 to 60.
    fillet_divisions : int — [1]
        Elements per root fillet: they set the element size h at the root, the shorter of
        the fillet's arc (from the slot bottom to where the flank begins) and a quarter
        circle of the blade's edge radius, over this number; every graded division below
        starts from h; 1 to 20.
    root_element_size : float or None — [mm]
        The element size h at the root fillets instead (default None: from
        ``fillet_divisions``); > 0 and smaller than every fillet's arc (a size that
        leaves no element across the fillet is refused when the solid is built).
    across_divisions : int — [1]
        Elements across a tooth, growing geometrically from both flanks; even, 2 to 20.
        At least: more where the layer at the flanks would otherwise be more than 2 h
        thick (:func:`contact.compliance.fe.solid.mesh_layout`).
    flank_divisions : int — [1]
        Elements up each side of the tooth from the fillet's 45° point to the face
        cone, growing geometrically from h; 2 to 60. At least, as ``across_divisions``
        (growth at most 2.5).
    slot_divisions : int — [1]
        Elements along each half slot (the lower part of the fillet and half the slot
        bottom), growing from h at the fillet (and, where two cuts meet at the slot's
        middle, from h there too); 1 to 20. At least, as ``across_divisions`` (growth
        at most 1.5).
    rim_divisions : int — [1]
        Elements through the rim, from the roots down to its inner surface, growing
        from h at the roots; 1 to 20. At least, as ``across_divisions``.
    youngs_modulus : float — [MPa]
        E of the member's material (default steel, geometry.hertz.STEEL).
    poisson_ratio : float — [1]
        ν, in [0, 0.5).
    load_nu, load_nv : int — [1]
        Grid of unit loads on the working flank, lengthwise × profile (the ease-off
        grid's layout, :func:`geometry.flank.projection_grid`); 2 to 81.
    load_v_limits : (float, float) or None — [1]
        Profile fractions covered by the load grid. Default None: from the generated
        working flank, (max(0.05, v₀ + 0.01), 1.0) with v₀ the highest profile fraction,
        over the model's sections, below which its side is no longer a rising function
        of v (it turns into the fillet's flat bottom; :meth:`contact.compliance.fe.
        section.ToothSections.flank_start`): the ease-off grid's (0.05, 1.0) wherever
        the flank is generated down to 0.04 of the depth, higher where it is not (the
        hypoid example's gear begins at v = 0.093 at the heel).
        Given: 0 ≤ low < high ≤ 1, and the flank must exist down to low.
    load_row_step : int — [1]
        Unit loads solved on every ``load_row_step``-th row of the profile grid only,
        and on every row of the first step, next to the root (1 to 5, ``load_nv − 1`` a
        multiple of it): each solved load is the full grid's hat function, so the
        coefficients are those of the full model at the solved rows, and between them
        the root stress interpolates them linearly in v, as between any two load rows.
        Default 1: every row. 2 solves rows 0, 1, 2, 4, 6, 8, 10 of 11 (147 of 231
        loads); the peak root stress then reads within −0.2 … +0.9 % of the full grid's
        on the four designs measured in docs/fe.md, "Every other load row solved" (rows
        0, 2, …, 10 alone read an edge-loaded peak 2.5 % low: the fillet stress varies
        most steeply with the load's height next to the root) — an option for screening
        builds where a design is only being searched, not the model a verdict rests on.
        Not part of the cache key nor of :meth:`to_json` at its default (the default
        model's keys unchanged).
    slot_bottom : str
        How the slot bottom of separately cut teeth (generated face-milled pinions) is
        rounded where the two cuts cross (:data:`SLOT_BOTTOMS`;
        :mod:`contact.compliance.fe.section`). ``"crossing"`` (the rule before 0.3.0): by the edge
        radius, or the largest smaller radius down to a tenth of it that keeps both
        fillets whole, else by up to that tenth (a notch where the other cut's blade tip
        crosses a fillet near its top). ``"edge_radius"`` (default): every crossing by the blades'
        edge radius, the corner of the cutter tip that makes it, replacing the top of a
        crossed fillet (issue 71: the coast pinion's FE root stress at 1.5–3.2 × ISO
        10300's σ_F at step 2's notch; docs/fe.md, "The slot bottom by the cutter's edge
        radius"). One cut (both flanks in one setting): no effect. Part of every cache
        key (the default changed in 0.3.0: the models cached before, under keys without
        it, are never read as the new default's).

    Raises
    ------
    InputError
        On construction, a field out of its range or of the wrong type (``teeth`` even
        or outside 3–9, a division count outside its range, ``across_divisions`` odd,
        ``rim_depth``, ``root_element_size`` or ``youngs_modulus`` not > 0,
        ``poisson_ratio`` outside [0, 0.5), an unknown ``constraint`` or ``element``,
        ``load_v_limits`` not two fractions 0 ≤ low < high ≤ 1, ``load_row_step``
        outside 1–5 or not dividing ``load_nv − 1``, ``slot_bottom`` not one of
        :data:`SLOT_BOTTOMS`); the message names the field and the accepted range.

    Notes
    -----
    The element counts are the divisions above or more: the solid raises each to what
    keeps the elements at the root at most h long and 2 h thick in every section
    (:func:`contact.compliance.fe.solid.mesh_layout`), so that a refinement (:meth:`refined`)
    refines the root in every direction. The defaults are a mesh whose refinement (every
    division × 1.5) changes the mid-surface compliance and the peak tensile fillet
    stress by less than 3 % (tests/test_fe_tooth.py, tests/test_root_stress.py,
    docs/fe.md, which also gives what converges more slowly). Named cheaper models:
    :meth:`at_level` (:data:`LEVELS`; ``"coarse"``, a new design's build at 0.42–0.50 of the
    default's CPU, its peak root stress within −3.6 … +6.3 % of the default model's on
    four designs: docs/fe.md, "A coarse model for a new design").
    """

    teeth: int = 3
    rim_depth: float | None = None
    constraint: str = "bore"
    element: str = "hex20"
    face_divisions: int = 12
    fillet_divisions: int = 6
    root_element_size: float | None = None
    across_divisions: int = 6
    flank_divisions: int = 8
    slot_divisions: int = 3
    rim_divisions: int = 5
    youngs_modulus: float = STEEL[0]
    poisson_ratio: float = STEEL[1]
    load_nu: int = 21
    load_nv: int = 11
    load_v_limits: tuple[float, float] | None = None
    load_row_step: int = dataclasses.field(default=1, metadata={"key_at_default": False})
    slot_bottom: str = "edge_radius"

    def __post_init__(self) -> None:
        teeth = integer("teeth", self.teeth, 3, 9)
        if teeth % 2 == 0:
            raise InputError(f"teeth: must be an odd integer in [3, 9] (the loaded tooth "
                             f"and as many neighbours on each side), got {teeth}")
        object.__setattr__(self, "teeth", teeth)
        if self.rim_depth is not None:
            object.__setattr__(self, "rim_depth", positive("rim_depth", self.rim_depth,
                                                           "mm"))
        one_of("constraint", self.constraint, CONSTRAINTS)
        one_of("element", self.element, ELEMENTS)
        for name, low, high in (("face_divisions", 2, 60), ("across_divisions", 2, 20),
                                ("fillet_divisions", 1, 20), ("flank_divisions", 2, 60),
                                ("slot_divisions", 1, 20), ("rim_divisions", 1, 20),
                                ("load_nu", 2, 81), ("load_nv", 2, 81)):
            object.__setattr__(self, name, integer(name, getattr(self, name), low, high))
        if self.across_divisions % 2:
            raise InputError(f"across_divisions: must be an even integer in [2, 20] "
                             f"(symmetric grading), got {self.across_divisions}")
        if self.root_element_size is not None:
            object.__setattr__(self, "root_element_size", positive(
                "root_element_size", self.root_element_size, "mm"))
        object.__setattr__(self, "youngs_modulus",
                           positive("youngs_modulus", self.youngs_modulus, "MPa"))
        object.__setattr__(self, "poisson_ratio",
                           real("poisson_ratio", self.poisson_ratio, unit="1", low=0.0,
                                high=0.5, high_open=True))
        if self.load_v_limits is not None:
            given = self.load_v_limits
            lim = tuple(real("load_v_limits", x, unit="1", low=0.0, high=1.0)
                        for x in given) if len(given) == 2 else ()
            if len(lim) != 2 or not lim[0] < lim[1]:
                raise InputError(f"load_v_limits: must be None or two profile fractions "
                                 f"0 <= low < high <= 1, got {given!r}")
            object.__setattr__(self, "load_v_limits", lim)
        step = integer("load_row_step", self.load_row_step, 1, 5)
        if (self.load_nv - 1) % step:
            raise InputError(f"load_row_step: must divide load_nv - 1 = {self.load_nv - 1} "
                             f"(the first and last profile rows solved), an integer in "
                             f"[1, 5], got {step}")
        object.__setattr__(self, "load_row_step", step)
        one_of("slot_bottom", self.slot_bottom, SLOT_BOTTOMS)

    @property
    def solved_rows(self) -> list[int]:
        """Indices [1] of the load grid's profile rows whose unit loads are solved:
        every row of the first ``load_row_step`` (next to the root, where the fillet
        stress varies most steeply with the load's height) and every
        ``load_row_step``-th row after it, the last among them."""
        step = self.load_row_step
        return sorted(set(range(0, min(step, self.load_nv - 1)))
                      | set(range(0, self.load_nv, step)))

    @property
    def neighbours(self) -> int:
        """Neighbours modelled on each side of the loaded tooth, (teeth − 1)/2."""
        return (self.teeth - 1) // 2

    @classmethod
    def at_level(cls, level: str = "default", **changes: Any) -> FEOptions:
        """The FE model named ``level`` (:data:`LEVELS`), with ``changes`` on top.

        Parameters
        ----------
        level : str
            A key of :data:`LEVELS`: ``"default"`` (``FEOptions()``), ``"coarse"``
            (fewer elements along the face and in the depth, every other load row
            above the root's first rows; 0.42–0.50 of the default's build CPU; its accuracy in
            docs/fe.md, "A coarse model for a new design") or ``"coarse10"`` (the same
            with 10 elements along the face: the cases ``ltca synthesize`` writes;
            :data:`LEVEL_ACCURACY`).
        **changes
            Fields set after the level's (e.g. ``youngs_modulus``), as
            :func:`dataclasses.replace`.

        Returns
        -------
        FEOptions
            Validated as any :class:`FEOptions`; its cache key covers every field, so a
            level's coefficients are never read as another's.

        Raises
        ------
        InputError
            An unknown ``level`` (the message lists :data:`LEVELS`), or a field of
            ``changes`` out of its range (as the constructor).
        """
        one_of("level", level, LEVELS)
        return cls(**{**LEVELS[level], **changes})

    def refined(self, factor: float = 1.5) -> FEOptions:
        """The same model with every element division multiplied by ``factor`` (rounded,
        changed by at least one in the direction of ``factor``, the across divisions to an
        even number; the root element size, if given, divided by it): the next mesh of a
        convergence study (factor > 1) or the previous one (factor < 1)."""
        if not factor > 0.0:
            raise InputError(f"factor: must be > 0, got {factor!r}")

        def scale(n: int, low: int) -> int:
            m = round(n * factor)
            if factor > 1.0:
                m = max(m, n + 1)
            elif factor < 1.0:
                m = min(m, n - 1)
            return max(m, low)

        across = scale(self.across_divisions, 2)
        size = None if self.root_element_size is None else self.root_element_size / factor
        return dataclasses.replace(
            self, face_divisions=scale(self.face_divisions, 2),
            across_divisions=max(2, across + across % 2),
            fillet_divisions=scale(self.fillet_divisions, 1), root_element_size=size,
            flank_divisions=scale(self.flank_divisions, 2),
            slot_divisions=scale(self.slot_divisions, 1),
            rim_divisions=scale(self.rim_divisions, 1))

    def to_json(self) -> str:
        """The options as JSON text with sorted keys (cache keys, dataset attributes)."""
        return json.dumps(self.as_dict(), sort_keys=True)

    def as_dict(self) -> dict[str, Any]:
        """The options as a dict of plain values."""
        d = dataclasses.asdict(self)
        for f in dataclasses.fields(self):  # fields added later: absent at their default,
            # so that the default model's dict (and cache keys) stay as they were
            if not f.metadata.get("key_at_default", True) and d[f.name] == f.default:
                del d[f.name]
        if d["load_v_limits"] is not None:
            d["load_v_limits"] = list(d["load_v_limits"])
        return d
