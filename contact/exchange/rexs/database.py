"""The REXS attribute databases (FVA, Apache-2.0), bundled in ``data/`` (its README).

A REXS file is valid when it follows the file schema (XSD / JSON schema) *and* the
attribute database of its version: which components exist, which attributes each may
carry, every attribute's unit (spelled as the database spells it), value type, range and
enumeration, and which relations join which components in which roles. This module reads
that database into frozen dataclasses; :mod:`contact.exchange.rexs.validate` applies it.

Public
------
VERSIONS            the REXS versions bundled (``"1.7"``, ``"2.0.0"``)
AttributeSpec       one attribute of the database
RelationSpec        one relation type with its roles and allowed combinations
Database            one version's database
load_database       the database of a version (read once, cached)
"""

from __future__ import annotations

import gzip
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import cache
from importlib import resources

from geometry.core.errors import InputError

__all__ = ["VERSIONS", "AttributeSpec", "Database", "RelationSpec", "load_database"]

#: the REXS versions whose attribute databases are bundled (data/README.md)
VERSIONS: tuple[str, ...] = ("1.7", "2.0.0")


@dataclass(frozen=True)
class AttributeSpec:
    """One attribute of the database.

    ``unit`` is the unit's name as the database spells it (``"mm"``, ``"deg"``, ``"none"``,
    ``"N m"``, ``"1 / min"``); ``value_type`` the REXS value type (``"floating_point"``,
    ``"integer"``, ``"enum"``, ``"floating_point_array"`` …); the range bounds are None
    where the database gives none, ``*_open`` whether the bound itself is excluded;
    ``enum_values`` the permitted values of an enum (empty otherwise).
    """

    id: str
    name: str
    unit: str
    value_type: str
    symbol: str = ""
    range_min: float | None = None
    range_max: float | None = None
    min_open: bool = False
    max_open: bool = False
    enum_values: tuple[str, ...] = ()

    def in_range(self, value: float) -> bool:
        """Whether ``value`` lies in the attribute's range (True where it has none)."""
        if self.range_min is not None and (
                value < self.range_min or (self.min_open and value == self.range_min)):
            return False
        return not (self.range_max is not None and (
            value > self.range_max or (self.max_open and value == self.range_max)))

    def range_text(self) -> str:
        """The range as an interval, e.g. ``(0, 180)`` or ``[0, inf)``."""
        lo = "-inf" if self.range_min is None else f"{self.range_min:g}"
        hi = "inf" if self.range_max is None else f"{self.range_max:g}"
        left = "(" if self.min_open or self.range_min is None else "["
        right = ")" if self.max_open or self.range_max is None else "]"
        return f"{left}{lo}, {hi}{right}"


@dataclass(frozen=True)
class RelationSpec:
    """One relation type: its roles, whether it needs an ``order``, and the allowed
    combinations (each a tuple of (component type, role) pairs)."""

    id: str
    ordered: bool
    roles: tuple[str, ...]
    combinations: tuple[tuple[tuple[str, str], ...], ...]


@dataclass(frozen=True)
class Database:
    """One REXS version's attribute database (:func:`load_database`)."""

    version: str
    components: frozenset[str]
    attributes: dict[str, AttributeSpec]
    mapping: dict[str, frozenset[str]]
    relations: dict[str, RelationSpec]
    units: frozenset[str]

    def attribute(self, component: str, attribute: str) -> AttributeSpec:
        """The spec of ``attribute`` on a component of type ``component``.

        Raises
        ------
        InputError
            The component type is not in the database, or the attribute is not mapped to
            it (the message names both and the version).
        """
        if component not in self.components:
            raise InputError(f"REXS {self.version}: unknown component type {component!r}")
        if attribute not in self.mapping.get(component, frozenset()):
            raise InputError(f"REXS {self.version}: component type {component!r} has no "
                             f"attribute {attribute!r}")
        return self.attributes[attribute]

    def has(self, component: str, attribute: str) -> bool:
        """Whether ``attribute`` is mapped to component type ``component``."""
        return attribute in self.mapping.get(component, frozenset())


def _float(text: str | None) -> float | None:
    return None if text is None else float(text)


def _parse(root: ET.Element, version: str) -> Database:
    units = {u.get("id"): u.get("name") for u in root.find("units")}
    types = {t.get("id"): t.get("name") for t in root.find("valueTypes")}
    components = frozenset(c.get("componentId") for c in root.find("components"))
    attributes = {}
    for a in root.find("attributes"):
        aid = a.get("attributeId")
        attributes[aid] = AttributeSpec(
            id=aid, name=a.get("name", ""), unit=units[a.get("unit")],
            value_type=types[a.get("valueType")], symbol=a.get("symbol", ""),
            range_min=_float(a.get("rangeMin")), range_max=_float(a.get("rangeMax")),
            min_open=a.get("rangeMinIntervalOpen") == "true",
            max_open=a.get("rangeMaxIntervalOpen") == "true",
            enum_values=tuple(e.get("value") for e in a.iter("enumValue")))
    mapping: dict[str, set[str]] = {}
    for m in root.find("componentAttributeMappings"):
        mapping.setdefault(m.get("componentId"), set()).add(m.get("attributeId"))
    relations = {}
    for r in root.find("relations"):
        rid = r.get("relationId")
        roles = tuple(x.get("roleId") for x in r.find("roles"))
        combos = tuple(
            tuple((x.get("componentId"), x.get("roleId")) for x in c)
            for c in r.iter("allowedCombination"))
        relations[rid] = RelationSpec(rid, r.get("orderRequired") == "true", roles, combos)
    return Database(version=version, components=components, attributes=attributes,
                    mapping={k: frozenset(v) for k, v in mapping.items()},
                    relations=relations, units=frozenset(units.values()))


@cache
def load_database(version: str) -> Database:
    """The attribute database of a REXS version (bundled, read once per process).

    Parameters
    ----------
    version : str
        One of :data:`VERSIONS`.

    Returns
    -------
    Database

    Raises
    ------
    InputError
        A version that is not bundled (the message lists those that are).

    Source: FVA REXS attribute databases ``rexs_schema_<version>_en.xml``
    (fva-net/rexs-api-cpp, ``models/``; data/README.md).
    """
    if version not in VERSIONS:
        raise InputError(f"version: REXS {version!r} is not supported; supported: "
                         f"{', '.join(VERSIONS)}")
    name = f"rexs_schema_{version}_en.xml.gz"
    data = resources.files(__package__).joinpath("data", name).read_bytes()
    return _parse(ET.fromstring(gzip.decompress(data)), version)


def data_file(name: str) -> bytes:
    """The bytes of a bundled data file (``rexs-file.xsd``, ``rexs-file.json``)."""
    return resources.files(__package__).joinpath("data", name).read_bytes()
