"""Inputs of the ANSI/AGMA 2003-D19 rating: the pair's basic data and the ``[agma2003]`` table.

* :class:`AGMAGeometry` — what the rating takes from the pair's geometry (teeth, outer
  pitch diameters, outer transverse module, net face width, cone distances, mean spiral
  angle, cutter radius); :func:`geometry_from_case` computes it from the case's
  ``[design]`` table (ISO 23509 basic data, the blank of
  :func:`geometry.iso23509.blank.blank_geometry`) and refuses a hypoid offset;
* :class:`AGMAInputs` — the method's own inputs, a case's ``[agma2003]`` table
  (:data:`FIELDS` lists each field with its unit and accepted range); the geometry factors
  I and J are inputs (read off the standard's Annex D charts or computed elsewhere: the
  toolkit does not compute Annex C(M)).

A bad value raises :class:`~geometry.core.errors.InputError` naming the field
(``agma2003.<field>``, ``design.<field>``) and the accepted range.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from contact.load_capacity.agma2003.factors import MOUNTING_MODIFIER, RELIABILITY_FACTORS
from geometry.core.errors import InputError
from geometry.core.validation import integer, known_fields, one_of, real

__all__ = ["FIELDS", "AGMAGeometry", "AGMAInputs", "geometry_from_case"]

#: the fields of the ``[agma2003]`` table: name → (unit, what it is and its range)
FIELDS: dict[str, tuple[str, str]] = {
    "geometry_factor_I": ("1", "I, pitting resistance geometry factor, in (0, 1]; "
                               "required (Annex D charts or Annex C(M))"),
    "geometry_factor_J": ("1", "J [pinion, gear], bending strength geometry factors, "
                               "each in (0, 1]; required"),
    "overload_factor": ("1", "K_o, in [1, 5] (clause 7, Annex A); required"),
    "accuracy_number": ("1", "Q_v, transmission accuracy number, an integer in [5, 11]; "
                             "one of it and dynamic_factor is required"),
    "dynamic_factor": ("1", "K_v given, in [1, 3] (clause 10.7-10.8)"),
    "mounting": ("", "straddle-mounted members: 'both', 'one' or 'neither'; required"),
    "load_distribution_factor": ("1", "K_m given, in [1, 3]; default Eq. 20M"),
    "crowned": ("", "teeth properly crowned (true: C_xc 1.5, false: 2.0); required"),
    "crowning_factor": ("1", "C_xc given, in [1.5, 3]; default from crowned"),
    "load_cycles": ("1", "N_L [pinion, gear], in [1e3, 1e10]; required"),
    "critical_service": ("", "K_L on the critical-service edge of Figure 6; default "
                             "false"),
    "reliability": ("1", "0.9999, 0.999, 0.99, 0.9 or 0.5 (Table 2); default 0.99"),
    "temperature": ("degC", "gear blank temperature, >= 0; default the case's "
                            "[operating] temperature"),
    "grade": ("1", "metallurgical grade [pinion, gear], 1, 2 or 3: s_ac and s_at of the "
                   "members' material; required unless s_ac and s_at are given"),
    "s_ac": ("MPa", "allowable contact stress numbers [pinion, gear], in (0, 3000]; "
                    "default from grade"),
    "s_at": ("MPa", "allowable bending stress numbers [pinion, gear], in (0, 1000]; "
                    "default from grade"),
    "stress_cycle_factor_pitting": ("1", "C_L [pinion, gear] given, in (0, 3]; default "
                                         "Figure 5 (carburised steel)"),
    "stress_cycle_factor_bending": ("1", "K_L [pinion, gear] given, in (0, 3]; default "
                                         "Figure 6 (carburised steel)"),
    "hardness_ratio_factor": ("1", "C_H of the gear, in [1, 1.2]; default 1 (equal "
                                   "hardness; the pinion's is 1)"),
    "youngs_modulus": ("MPa", "E [pinion, gear], in (0, 1e6]; default the members' "
                              "material"),
    "poisson_ratio": ("1", "nu [pinion, gear], in [0, 0.5); default the members' material"),
    "safety_factor_pitting": ("1", "S_H, in [0.5, 5]; default 1"),
    "safety_factor_bending": ("1", "S_F, in [0.5, 5]; default 1"),
    "source": ("", "where the values come from (text), optional"),
}


def _pair(name: str, value: Any, **bounds: Any) -> tuple[float, float]:
    """One number for both members or [pinion, gear], each within the bounds."""
    if isinstance(value, (list, tuple)):
        if len(value) != 2:
            raise InputError(f"{name}: must be one number or [pinion, gear], got "
                             f"{list(value)!r}")
        vals = value
    else:
        vals = (value, value)
    return tuple(real(name, v, **bounds) for v in vals)  # type: ignore[return-value]


def _flag(name: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise InputError(f"{name}: must be true or false, got {value!r}")
    return value


@dataclass(frozen=True, kw_only=True)
class AGMAInputs:
    """The inputs of the ANSI/AGMA 2003-D19 rating beyond the geometry (``[agma2003]``).

    Parameters
    ----------
    geometry_factor_I : float — [1]
        Pitting resistance geometry factor I, in (0, 1] (clause 15: Annex C(M) or the Annex
        D charts; an input here). Required.
    geometry_factor_J : (float, float) — [1]
        Bending strength geometry factors J1, J2, each in (0, 1]. Required.
    overload_factor : float — [1]
        K_o, in [1, 5] (clause 7, Annex A). Required.
    accuracy_number : int, optional
        Q_v in [5, 11] (clause 10.6): K_v by Eq. 13M. One of it and ``dynamic_factor``.
    dynamic_factor : float — [1], optional
        K_v given, in [1, 3].
    mounting : {"both", "one", "neither"}
        Straddle-mounted members, K_mb of Eq. 20M. Required.
    load_distribution_factor : float — [1], optional
        K_m given, in [1, 3] (default Eq. 20M).
    crowned : bool
        Teeth properly crowned (C_xc 1.5) or not (2.0), clause 13. Required.
    crowning_factor : float — [1], optional
        C_xc given, in [1.5, 3].
    load_cycles : (float, float) — [1]
        N_L of pinion and gear, in [1e3, 1e10]. Required.
    critical_service : bool
        K_L on Figure 6's critical-service edge (default False: general applications).
    reliability : float — [1]
        0.9999, 0.999, 0.99, 0.9 or 0.5 (Table 2); default 0.99.
    temperature : float — [degC], optional
        Gear blank temperature, ≥ 0; default the case's ``[operating]`` temperature.
    grade : (int, int), optional
        Metallurgical grades 1–3 of pinion and gear: s_ac, s_at from the members'
        material (``agma2003_allowable`` of geometry/core/data/materials.toml).
    s_ac, s_at : (float, float) — [MPa], optional
        Allowable contact and bending stress numbers given, in (0, 3000] and (0, 1000].
        Required where ``grade`` is absent.
    stress_cycle_factor_pitting, stress_cycle_factor_bending : (float, float), optional
        C_L, K_L given, in (0, 3] (default Figures 5 and 6, carburised steel).
    hardness_ratio_factor : float — [1]
        C_H of the gear, in [1, 1.2]; default 1 (equal hardness; Eq. 27M–30M are not
        implemented).
    youngs_modulus : (float, float) — [MPa], optional
        E of pinion and gear, in (0, 1e6]; default the members' material.
    poisson_ratio : (float, float) — [1], optional
        ν of pinion and gear, in [0, 0.5); default the members' material.
    safety_factor_pitting, safety_factor_bending : float — [1]
        S_H, S_F of Eq. 2M and 6M, in [0.5, 5]; default 1.
    source : str
        Where the values come from.

    Raises
    ------
    InputError
        A value out of its range, or a required one absent (named).

    Notes
    -----
    ANSI/AGMA 2003-D19 clauses 7–21 (the symbols of its Table 1).
    """

    geometry_factor_I: float
    geometry_factor_J: tuple[float, float]
    overload_factor: float
    mounting: str
    crowned: bool
    load_cycles: tuple[float, float]
    accuracy_number: int | None = None
    dynamic_factor: float | None = None
    load_distribution_factor: float | None = None
    crowning_factor: float | None = None
    critical_service: bool = False
    reliability: float = 0.99
    temperature: float | None = None
    grade: tuple[int, int] | None = None
    s_ac: tuple[float, float] | None = None
    s_at: tuple[float, float] | None = None
    stress_cycle_factor_pitting: tuple[float, float] | None = None
    stress_cycle_factor_bending: tuple[float, float] | None = None
    hardness_ratio_factor: float = 1.0
    youngs_modulus: tuple[float, float] | None = None
    poisson_ratio: tuple[float, float] | None = None
    safety_factor_pitting: float = 1.0
    safety_factor_bending: float = 1.0
    source: str = ""

    def __post_init__(self) -> None:
        def put(name: str, value: Any) -> None:
            object.__setattr__(self, name, value)

        put("geometry_factor_I", real("geometry_factor_I", self.geometry_factor_I, low=0.0,
                                      high=1.0, low_open=True))
        put("geometry_factor_J", _pair("geometry_factor_J", self.geometry_factor_J,
                                       low=0.0, high=1.0, low_open=True))
        put("overload_factor", real("overload_factor", self.overload_factor, low=1.0,
                                    high=5.0))
        if (self.accuracy_number is None) == (self.dynamic_factor is None):
            raise InputError("accuracy_number, dynamic_factor: give one of them (Q_v, an "
                             "integer in [5, 11], or K_v in [1, 3])")
        if self.accuracy_number is not None:
            put("accuracy_number", integer("accuracy_number", self.accuracy_number, 5, 11,
                                           allow_float=True))
        else:
            put("dynamic_factor", real("dynamic_factor", self.dynamic_factor, low=1.0,
                                       high=3.0))
        put("mounting", one_of("mounting", self.mounting, tuple(MOUNTING_MODIFIER)))
        if self.load_distribution_factor is not None:
            put("load_distribution_factor", real("load_distribution_factor",
                                                 self.load_distribution_factor, low=1.0,
                                                 high=3.0))
        put("crowned", _flag("crowned", self.crowned))
        if self.crowning_factor is not None:
            put("crowning_factor", real("crowning_factor", self.crowning_factor, low=1.5,
                                        high=3.0))
        put("load_cycles", _pair("load_cycles", self.load_cycles, low=1e3, high=1e10))
        put("critical_service", _flag("critical_service", self.critical_service))
        r = real("reliability", self.reliability, low=0.0, high=1.0, low_open=True)
        if not any(math.isclose(r, k, rel_tol=0.0, abs_tol=1e-9) for k in RELIABILITY_FACTORS):
            raise InputError(f"reliability: must be one of {sorted(RELIABILITY_FACTORS)} "
                             f"(Table 2), got {r!r}")
        put("reliability", r)
        if self.temperature is not None:
            put("temperature", real("temperature", self.temperature, unit="degC", low=0.0))
        if self.grade is not None:
            g = self.grade if isinstance(self.grade, (list, tuple)) else (self.grade,) * 2
            if len(g) != 2:
                raise InputError(f"grade: must be 1, 2 or 3, or [pinion, gear], got {g!r}")
            put("grade", tuple(integer("grade", x, 1, 3) for x in g))
        for name, high in (("s_ac", 3000.0), ("s_at", 1000.0)):
            value = getattr(self, name)
            if value is not None:
                put(name, _pair(name, value, unit="MPa", low=0.0, high=high, low_open=True))
            elif self.grade is None:
                raise InputError(f"{name}: give the allowable stress numbers [pinion, gear] "
                                 "[MPa] or the members' grade (1, 2 or 3)")
        for name in ("stress_cycle_factor_pitting", "stress_cycle_factor_bending"):
            if getattr(self, name) is not None:
                put(name, _pair(name, getattr(self, name), low=0.0, high=3.0,
                                low_open=True))
        put("hardness_ratio_factor", real("hardness_ratio_factor",
                                          self.hardness_ratio_factor, low=1.0, high=1.2))
        if self.youngs_modulus is not None:
            put("youngs_modulus", _pair("youngs_modulus", self.youngs_modulus, unit="MPa",
                                        low=0.0, high=1e6, low_open=True))
        if self.poisson_ratio is not None:
            put("poisson_ratio", _pair("poisson_ratio", self.poisson_ratio, low=0.0,
                                       high=0.5, high_open=True))
        for name in ("safety_factor_pitting", "safety_factor_bending"):
            put(name, real(name, getattr(self, name), low=0.5, high=5.0))
        if not isinstance(self.source, str):
            raise InputError(f"source: must be text, got {self.source!r}")

    @classmethod
    def from_mapping(cls, table: Mapping[str, Any]) -> AGMAInputs:
        """Read a case's ``[agma2003]`` table.

        Parameters
        ----------
        table : mapping
            The fields of :data:`FIELDS`.

        Returns
        -------
        AGMAInputs

        Raises
        ------
        InputError
            Not a table, an unknown or missing field, or a bad value: named
            ``agma2003.<field>`` with the accepted range.
        """
        if not isinstance(table, Mapping):
            raise InputError(f"agma2003: must be a table of the fields {sorted(FIELDS)}, got "
                             f"{type(table).__name__}")
        known_fields("agma2003", table, FIELDS)
        required = [f.name for f in dataclasses.fields(cls)
                    if f.default is dataclasses.MISSING and f.name not in table]
        if required:
            name = required[0]
            raise InputError(f"agma2003.{name}: required ({FIELDS[name][1]})")
        try:
            return cls(**dict(table))
        except InputError as exc:
            raise InputError(f"agma2003.{exc}") from None


@dataclass(frozen=True)
class AGMAGeometry:
    """The geometry ANSI/AGMA 2003-D19 rates (its Table 1 symbols).

    Attributes
    ----------
    z1, z2 : int
        Numbers of teeth.
    de1, de2 : float — [mm]
        Outer pitch diameters.
    m_et : float — [mm]
        Outer transverse module d_e2/z2.
    b : float — [mm]
        Net face width (the narrower of the members' face widths).
    R_e, R_m : float — [mm]
        Outer cone distance and mean cone distance R_e − b/2.
    beta_m : float — [rad]
        Mean spiral angle (0: straight or Zerol bevel gears).
    r_c0 : float — [mm]
        Cutter radius (nominal, of the ``[design]`` table).
    """

    z1: int
    z2: int
    de1: float
    de2: float
    m_et: float
    b: float
    R_e: float
    R_m: float
    beta_m: float
    r_c0: float


def offset_refusal(design: Mapping[str, Any]) -> str:
    """Why a ``[design]`` table with a hypoid offset cannot be rated, or ``""``."""
    a = design.get("a", 0.0)
    if isinstance(a, (int, float)) and not isinstance(a, bool) and a != 0.0:
        return (f"ANSI/AGMA 2003-D19 rating not computed: the pair has a hypoid offset "
                f"(design.a = {a:g} mm); the standard rates straight, Zerol and spiral "
                "bevel gears without offset (its scope; ISO 10300 rates hypoid gears)")
    return ""


def geometry_from_case(case) -> AGMAGeometry:
    """The geometry of a case's ``[design]`` table, as ANSI/AGMA 2003-D19 rates it.

    Parameters
    ----------
    case : geometry.case.Case
        With a ``[design]`` table (ISO 23509 basic data) of a pair without offset.

    Returns
    -------
    AGMAGeometry
        From the ISO 23509 blank (:func:`geometry.iso23509.blank.blank_geometry`): the
        gear's outer pitch diameter and module, the pinion's d_e1 = z1 m_et, the narrower
        face width, the gear's outer cone distance, ``beta_m`` and ``rc0`` of the table.

    Raises
    ------
    InputError
        No ``[design]`` table, a bad one (``design.<field>``), or a hypoid offset
        (``design.a``: the standard covers bevel gears without offset).

    Notes
    -----
    ANSI/AGMA 2003-D19 clause 1 (scope) and Table 1 (symbols).
    """
    from contact.load_capacity.design_table import design_blank, design_table

    design = design_table(case, "the ANSI/AGMA 2003-D19 rating needs the case's basic "
                                "design data, a [design] table (docs/rating.md)")
    why = offset_refusal(design)
    if why:
        raise InputError(f"design.a: must be 0 (no hypoid offset): {why}")
    blank = design_blank(design)
    b = min(blank.pinion.b, blank.gear.b)
    m_et = blank.met2
    r_e = blank.gear.Re
    return AGMAGeometry(z1=blank.pinion.z, z2=blank.gear.z, de1=blank.pinion.z * m_et,
                        de2=blank.gear.de, m_et=m_et, b=b, R_e=r_e, R_m=r_e - 0.5 * b,
                        beta_m=float(math.radians(float(design["beta_m"]))),
                        r_c0=float(design.get("rc0", 0.0)))
