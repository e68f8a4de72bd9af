"""The REXS model in memory: components with attributes, relations, a load spectrum.

The same structure as the file formats (``.rexs`` XML and ``.rexsj`` JSON,
:mod:`contact.exchange.rexs.files`): a component has an integer ``id``, a ``type`` (the
database's component id, e.g. ``"bevel_gear"``) and attributes; a relation joins
components by id in named roles; a load spectrum holds load cases, each listing components
(by id) with the attributes that vary by load case.

Public
------
Attribute, Component, Ref, Relation, LoadCase, LoadSpectrum, Model
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from geometry.core.errors import InputError

__all__ = ["Attribute", "Component", "LoadCase", "LoadSpectrum", "Model", "Ref", "Relation"]

#: the value types this package reads and writes (a subset of the database's)
SCALAR_TYPES = ("floating_point", "integer", "boolean", "string", "enum",
                "reference_component", "date_time", "file_reference")
ARRAY_TYPES = ("floating_point_array", "integer_array", "string_array", "boolean_array",
               "enum_array")
MATRIX_TYPES = ("floating_point_matrix",)


@dataclass
class Attribute:
    """One attribute: its id, value, unit (as the database spells it; ``"none"`` for a
    number without unit) and value type (:data:`SCALAR_TYPES`, :data:`ARRAY_TYPES`)."""

    id: str
    value: Any
    unit: str = "none"
    value_type: str = "floating_point"


@dataclass
class Component:
    """A component: integer id, type (database component id), optional name, attributes."""

    id: int
    type: str
    name: str = ""
    attributes: list[Attribute] = field(default_factory=list)

    def add(self, attribute_id: str, value: Any, unit: str = "none",
            value_type: str = "floating_point") -> None:
        """Append an attribute (see :class:`Attribute`)."""
        self.attributes.append(Attribute(attribute_id, value, unit, value_type))

    def get(self, attribute_id: str) -> Attribute | None:
        """The attribute of that id, or None."""
        return next((a for a in self.attributes if a.id == attribute_id), None)

    def value(self, attribute_id: str, default: Any = None) -> Any:
        """The value of an attribute, or ``default`` where the component has none."""
        a = self.get(attribute_id)
        return default if a is None else a.value

    def where(self) -> str:
        """``"bevel_gear id 3"``, for messages."""
        return f"{self.type} id {self.id}"


@dataclass
class Ref:
    """One member of a relation: a component id in a role (``hint``: its type, optional)."""

    id: int
    role: str
    hint: str = ""


@dataclass
class Relation:
    """A relation of a type (``"stage"``, ``"flank"``, ``"manufacturing_step"`` …) joining
    components in roles; ``order`` for relations whose database entry requires one."""

    id: int
    type: str
    refs: list[Ref]
    order: int | None = None

    def component(self, role: str) -> int | None:
        """The id of the component in ``role`` (None: no such role in this relation)."""
        return next((r.id for r in self.refs if r.role == role), None)


@dataclass
class LoadCase:
    """One load case: components (ids of the model's components, with the attributes that
    vary by load case; their ``type`` copied from the model for messages)."""

    id: int
    components: list[Component] = field(default_factory=list)


@dataclass
class LoadSpectrum:
    """A load spectrum: an id and its load cases."""

    id: int
    load_cases: list[LoadCase] = field(default_factory=list)


@dataclass
class Model:
    """A REXS model (the root of a file).

    ``version`` is the REXS version (``"1.7"``, ``"2.0.0"``); ``date`` ISO 8601 with a
    ``+hh:mm`` offset, as both schemas require.
    """

    version: str
    application_id: str
    application_version: str
    date: str
    components: list[Component] = field(default_factory=list)
    relations: list[Relation] = field(default_factory=list)
    load_spectrum: LoadSpectrum | None = None
    application_language: str = "en"

    def component(self, component_id: int) -> Component:
        """The component of that id.

        Raises
        ------
        InputError
            No component has it.
        """
        for c in self.components:
            if c.id == component_id:
                return c
        raise InputError(f"REXS: no component of id {component_id}")

    def of_type(self, type_: str) -> list[Component]:
        """The components of a type, in file order."""
        return [c for c in self.components if c.type == type_]

    def relations_of(self, type_: str) -> list[Relation]:
        """The relations of a type, in file order."""
        return [r for r in self.relations if r.type == type_]
