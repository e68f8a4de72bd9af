"""A small library of common gear oils, selectable by name like the bundled 75W90.

The ISO 3448 viscosity grades VG 68, 100, 150, 220, 320 and 460 of three base stocks —
mineral (CLP), polyalphaolefin (CLP HC) and water-soluble polyglycol (CLP PG) — each
described by what a data sheet gives and built into an oil file by
:mod:`friction.oil_data_sheet` (ASTM D341 viscosity, ISO/TR 15144-1 density and
pressure–viscosity coefficient of the base stock). Names: ``ISO_VG<grade>_<class>``, e.g.
``ISO_VG220_mineral``, ``ISO_VG320_PAO``, ``ISO_VG150_PAG``; a case takes one as
``[operating] lubricant = "ISO_VG220_mineral"``, a command as ``--lubricant``, and
``ltca oil --list`` lists them.

===================  ============================================  =========================
value                relation                                      source
===================  ============================================  =========================
ν40 [mm²/s]          the grade's mid-point                         ISO 3448:1992
ν100 [mm²/s]         ν40 and the class's VI, ASTM D2270 inverted   ASTM D2270 (= ISO 2909)
VI [1]               mineral 95, PAO 150, PAG 220                  assumed class values
ρ15 [kg/m³]          mineral 890, PAO 850, PAG 1060                assumed class values
FZG stage [1]        12 (a lower bound)                            DIN 51517-3 (CLP)
α, ρ(θ), η(θ), …     :mod:`friction.oil_data_sheet`                ISO/TR 15144-1, ASTM D341
===================  ============================================  =========================

Each value's source is written in ``friction/data/oils/library.toml`` and carried into the
built oil's ``source`` and ``durability_source``. These are **class values, not one
product's**: a real oil's own data sheet (``ltca oil``) replaces them. What a data sheet
does not give (thermal conductivity, Eyring stress, limiting shear, boundary friction) takes
:mod:`friction.oil_data_sheet`'s stated assumptions.

Check (``tests/test_oil_library.py``): ASTM D2270's VI of each stored (ν40, ν100) pair,
computed by an independent implementation of the standard (``chemicals``), equals the
class VI within 0.1; each built oil's ν40 and ν100 within 1 %; a case with a library oil
runs through ``ltca run``.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from types import MappingProxyType
from typing import Any

from friction.lubricant import Lubricant
from friction.oil_data_sheet import OilDataSheet, lubricant_from_data_sheet
from geometry.core.caches import memoised
from geometry.core.errors import InputError, ModelUnavailableError

__all__ = ["LIBRARY_SCHEMA", "LibraryOil", "library_oil", "library_oil_lubricant",
           "library_oil_names", "library_oils"]

#: The ``schema`` line of ``friction/data/oils/library.toml``.
LIBRARY_SCHEMA = "hypoid-ltca oil library 1"

_UNITS = {"kinematic_viscosity_40": "mm2/s", "kinematic_viscosity_100": "mm2/s",
          "viscosity_index": "1", "density_15": "kg/m3", "fzg_load_stage": "1"}
_OIL_KEYS = {"class", "kinematic_viscosity_40", "kinematic_viscosity_100", "viscosity_index",
             "density_15", "base_oil"}
_CLASS_KEYS = {"description", "viscosity_index", "viscosity_index_source", "density_15",
               "density_source", "fzg_load_stage", "fzg_source"}


@dataclass(frozen=True)
class LibraryOil:
    """One oil of the library: its data sheet and where each value comes from.

    Attributes
    ----------
    name : str
        ``ISO_VG<grade>_<class>``.
    sheet : OilDataSheet
        ν40, ν100 [mm²/s], ρ15 [kg/m³], base stock, FZG stage [1] and the composed source.
    viscosity_index : float — [1]
        The class's VI, from which ν100 was computed (ASTM D2270).
    oil_class : str
        ``mineral``, ``PAO`` or ``PAG``.
    description : str
        The class in words.
    """

    name: str
    sheet: OilDataSheet
    viscosity_index: float
    oil_class: str
    description: str


def _library_text() -> str:
    return resources.files("friction").joinpath("data", "oils", "library.toml").read_text(
        encoding="utf-8")


def _parse(data: Mapping[str, Any], origin: str) -> dict[str, LibraryOil]:
    if data.get("schema") != LIBRARY_SCHEMA:
        raise InputError(f"{origin}: schema: must be {LIBRARY_SCHEMA!r}, got "
                         f"{data.get('schema')!r}")
    if dict(data.get("units", {})) != _UNITS:
        raise InputError(f"{origin}: units: must be {_UNITS}, got {data.get('units')!r}")
    classes = data.get("class", {})
    oils: dict[str, LibraryOil] = {}
    for name, row in data.get("oil", {}).items():
        if set(row) != _OIL_KEYS:
            raise InputError(f"{origin}: oil.{name}: fields must be {sorted(_OIL_KEYS)}, got "
                             f"{sorted(row)}")
        cls = classes.get(row["class"])
        if cls is None or set(cls) != _CLASS_KEYS:
            raise InputError(f"{origin}: oil.{name}.class: {row['class']!r} is no complete "
                             f"[class] table (fields {sorted(_CLASS_KEYS)})")
        for key in ("viscosity_index", "density_15"):
            if float(row[key]) != float(cls[key]):
                raise InputError(f"{origin}: oil.{name}.{key}: {row[key]!r} differs from its "
                                 f"class's {cls[key]!r}")
        source = (
            f"hypoid-ltca oil library (friction/data/oils/library.toml), {cls['description']}"
            f", class values, not one product's: nu40 the ISO 3448 grade's mid-point; nu100 "
            f"from nu40 and VI {row['viscosity_index']:g} by ASTM D2270; VI: "
            f"{cls['viscosity_index_source']}; density: {cls['density_source']}; FZG load "
            f"stage {cls['fzg_load_stage']:g}: {cls['fzg_source']}")
        sheet = OilDataSheet(
            name=name, kinematic_viscosity_40=row["kinematic_viscosity_40"],
            kinematic_viscosity_100=row["kinematic_viscosity_100"],
            density_15=row["density_15"], base_oil=row["base_oil"], source=source,
            fzg_load_stage=cls["fzg_load_stage"])
        oils[name] = LibraryOil(name, sheet, float(row["viscosity_index"]), row["class"],
                                cls["description"])
    return oils


@memoised(maxsize=None)
def library_oils() -> Mapping[str, LibraryOil]:
    """The library's oils by name (read once from ``friction/data/oils/library.toml``).

    Returns
    -------
    mapping of str to LibraryOil
        Read-only, in the file's order (grades rising within each class).

    Raises
    ------
    InputError
        The bundled file fails its schema (a broken installation), naming the field.

    Notes
    -----
    Sources: module docstring; each value's in the file.
    """
    return MappingProxyType(_parse(tomllib.loads(_library_text()),
                                   "friction/data/oils/library.toml"))


def library_oil_names() -> tuple[str, ...]:
    """Names of the library's oils (``ISO_VG68_mineral`` … ``ISO_VG460_PAG``)."""
    return tuple(library_oils())


def library_oil(name: str) -> LibraryOil:
    """The library oil called ``name`` (case-insensitive).

    Raises
    ------
    ModelUnavailableError
        No such oil (the message lists the names).
    """
    by_lower = {k.lower(): v for k, v in library_oils().items()}
    try:
        return by_lower[str(name).lower()]
    except KeyError:
        raise ModelUnavailableError(f"no library oil {name!r}; library: "
                                    f"{list(library_oil_names())}") from None


def library_oil_lubricant(name: str) -> Lubricant:
    """The :class:`~friction.lubricant.Lubricant` of the library oil ``name``, built from
    its data sheet by :func:`friction.oil_data_sheet.lubricant_from_data_sheet` (the tables
    at 20–120 °C, accepted 0–160 °C).

    Raises
    ------
    ModelUnavailableError
        No such oil.
    """
    return _built(library_oil(name).name)


@memoised(maxsize=None)
def _built(name: str) -> Lubricant:
    return lubricant_from_data_sheet(library_oils()[name].sheet)
