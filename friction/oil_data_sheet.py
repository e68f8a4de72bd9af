"""An oil file from the values of its data sheet: ν40, ν100, ρ15 and the base stock.

A gear oil's data sheet gives its kinematic viscosity at 40 and 100 °C, its density at
15 °C and its base stock, seldom more. The LTCA's efficiency stage, film thickness and
scuffing assessment need the dynamic viscosity, the pressure–viscosity coefficient and the
density over the operating temperatures (:class:`friction.lubricant.Lubricant`). This
module makes those tables with cited correlations:

=================================  ==========================================  =============
property                           relation                                    source
=================================  ==========================================  =============
kinematic viscosity ν(T)           log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T_K     ASTM D341
                                   through (40 °C, ν40) and (100 °C, ν100)
density ρ(θ)                       ρ15 − 0.7 (θ + 273 − 289) kg/m³              ISO/TR 15144-1
dynamic viscosity η(θ)             ν(θ) ρ(θ)                                   definition
pressure–viscosity α at 38 °C      a η38^b (η38 in N s/m², α in m²/N):          ISO/TR 15144-1
                                   mineral a = 2.657e-8, b = 0.1348;
                                   polyalphaolefin 1.466e-8, 0.0507;
                                   polyglycol 1.392e-8, 0.1572
α(θ)                               α38 (1 + 516 (1/(θ + 273) − 1/311))          ISO/TR 15144-1
=================================  ==========================================  =============

ISO/TR 15144-1:2014 (micropitting; its successor ISO/TS 6336-22:2018 keeps the same
lubricant relations) gives α for mineral, polyalphaolefin and polyglycol base stocks;
for another base stock (an ester, a traction fluid) the data sheet's or a measured α at
38 °C must be given. What a data sheet does not give — the thermal conductivity, the
film-traction constants — takes the values the bundled 75W90 takes, with the same stated
assumption, unless given.

Check (tests/test_oil_data_sheet.py): the seed's 75W90 (Table 5.2) rebuilt from its
ν40, ν100 and ρ15 reproduces the table's dynamic viscosity at 25–100 °C within 5 %.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from friction.lubricant import (
    BASE_OIL_FACTORS,
    BoundaryFrictionTable,
    Lubricant,
    fit_walther,
    lubricant_from_mapping,
)
from geometry.core.errors import InputError

__all__ = [
    "PRESSURE_VISCOSITY_CORRELATIONS",
    "OilDataSheet",
    "density_from_data_sheet",
    "kinematic_viscosity_astm_d341",
    "lubricant_from_data_sheet",
    "oil_file_mapping",
    "pressure_viscosity_from_data_sheet",
]

#: ISO/TR 15144-1 α₃₈ = a η₃₈^b [m²/N, η in N s/m²] by base stock (the names of
#: :data:`friction.lubricant.BASE_OIL_FACTORS`); both polyglycols take the standard's
#: polyglycol relation.
PRESSURE_VISCOSITY_CORRELATIONS: Mapping[str, tuple[float, float]] = {
    "mineral": (2.657e-8, 0.1348),
    "polyalphaolefin": (1.466e-8, 0.0507),
    "polyglycol_non_water_soluble": (1.392e-8, 0.1572),
    "polyglycol_water_soluble": (1.392e-8, 0.1572),
}

#: Table temperatures of a built oil [degC]: the range of gear-oil data sheets and of the
#: efficiency studies (the oil file's extrapolation margins add 20 K below, 40 K above).
TABLE_TEMPERATURES: tuple[float, ...] = (20.0, 40.0, 60.0, 80.0, 100.0, 120.0)

# what a data sheet does not give: the bundled 75W90's stated assumptions
# (friction/data/75W90.toml), so an oil built here and the bundled oil differ only in what
# their data say
_ASSUMED = {
    "thermal_conductivity": 0.135,
    "thermal_conductivity_source": "assumed typical gear-oil value (0.13-0.15 W/(m K) for "
    "mineral and PAO oils at ambient pressure); not on the data sheet",
    "eyring_stress": 5.0,
    "limiting_shear_coefficient": 0.08,
    "boundary_friction": 0.1,
    "traction_source": "assumed typical values, as the bundled 75W90's: Eyring stress 2-10 "
    "MPa (Evans & Johnson, Proc. IMechE C 200 (1986) 303), limiting shear stress / pressure "
    "0.07-0.1 (Bair & Winer, J. Lubr. Technol. 101 (1979) 258), boundary friction 0.08-0.13 "
    "of steel with additive-containing oils; not on the data sheet",
}


@dataclass(frozen=True)
class OilDataSheet:
    """The values of a gear oil's data sheet.

    Parameters
    ----------
    name : str
        The oil's name (what results record as ``lubricant``).
    kinematic_viscosity_40, kinematic_viscosity_100 : float — [mm²/s]
        ν at 40 and 100 °C (ISO 3104), ν40 > ν100 ≥ 2 (the range of ASTM D341's form).
    density_15 : float — [kg/m³]
        ρ at 15 °C (ISO 12185), in [700, 1300]; a sheet giving g/ml × 1000.
    base_oil : str
        The base stock, one of :data:`friction.lubricant.BASE_OIL_FACTORS`.
    source : str
        The data sheet (maker, product, edition).
    pressure_viscosity_38 : float or None — [1/GPa]
        A measured α at 38 °C, required where the base stock has no correlation
        (:data:`PRESSURE_VISCOSITY_CORRELATIONS`); else None (the correlation).
    fzg_load_stage : float or None — [1]
        FZG A/8.3/90 failure load stage (ISO 14635-1), in [1, 14].
    boundary_friction : float, BoundaryFrictionTable, mapping or None — [1]
        μ_b measured on the oil (the low-speed plateau of its Stribeck curve on steel): one
        number in [0, 1], or measured at several oil temperatures — a
        :class:`friction.lubricant.BoundaryFrictionTable` or a mapping with ``temperature``
        [degC], ``value`` [1] and ``source`` (made one on construction), written to the oil
        file as its ``[boundary_friction]`` table (docs/friction.md, "Boundary friction of
        your oil"); None: the assumed 0.1 at every temperature.
    permissible_specific_film : float or None — [1]
        λ_GFP from the oil's FVA 54 micropitting test, > 0.
    thermal_conductivity : float or None — [W/(m K)]
        None: the assumed 0.135.
    """

    name: str
    kinematic_viscosity_40: float
    kinematic_viscosity_100: float
    density_15: float
    base_oil: str
    source: str
    pressure_viscosity_38: float | None = None
    fzg_load_stage: float | None = None
    boundary_friction: float | BoundaryFrictionTable | Mapping[str, Any] | None = None
    permissible_specific_film: float | None = None
    thermal_conductivity: float | None = None

    def __post_init__(self) -> None:
        for key in ("name", "source"):
            v = getattr(self, key)
            if not isinstance(v, str) or not v.strip():
                raise InputError(f"{key}: must be a non-empty string, got {v!r}")
        nu40, nu100 = (_finite(k, getattr(self, k)) for k in
                       ("kinematic_viscosity_40", "kinematic_viscosity_100"))
        if not 2.0 <= nu100 < nu40 <= 1e5:
            raise InputError(
                "kinematic_viscosity_40, kinematic_viscosity_100: must satisfy 2 <= nu100 < "
                f"nu40 <= 1e5 [mm2/s] (ASTM D341's range), got nu40 {nu40:g}, nu100 "
                f"{nu100:g}")
        rho = _finite("density_15", self.density_15)
        if not 700.0 <= rho <= 1300.0:
            raise InputError(f"density_15: must be in [700, 1300] [kg/m3] (a data sheet's "
                             f"g/ml times 1000), got {rho:g}")
        if self.base_oil not in BASE_OIL_FACTORS:
            raise InputError(f"base_oil: must be one of {sorted(BASE_OIL_FACTORS)}, got "
                             f"{self.base_oil!r}")
        alpha = self.pressure_viscosity_38
        if alpha is None and self.base_oil not in PRESSURE_VISCOSITY_CORRELATIONS:
            raise InputError(
                f"pressure_viscosity_38: required for base_oil {self.base_oil!r} [1/GPa, at "
                "38 degC]: ISO/TR 15144-1 gives alpha for "
                f"{sorted(PRESSURE_VISCOSITY_CORRELATIONS)} only")
        if alpha is not None and not 1.0 <= _finite("pressure_viscosity_38", alpha) <= 60.0:
            raise InputError(f"pressure_viscosity_38: must be in [1, 60] [1/GPa], got "
                             f"{alpha:g}")
        if isinstance(self.boundary_friction, Mapping):
            object.__setattr__(self, "boundary_friction",
                               BoundaryFrictionTable.from_mapping(self.boundary_friction))
        bounds = {"fzg_load_stage": (1.0, 14.0), "permissible_specific_film": (1e-6, 10.0),
                  "thermal_conductivity": (0.05, 0.5)}
        for key, (lo, hi) in bounds.items():
            v = getattr(self, key)
            if v is not None and not lo <= _finite(key, v) <= hi:
                raise InputError(f"{key}: must be in [{lo:g}, {hi:g}], got {v:g}")
        mu_b = self.boundary_friction
        if mu_b is not None and not isinstance(mu_b, BoundaryFrictionTable) \
                and not 0.0 <= _finite("boundary_friction", mu_b) <= 1.0:
            raise InputError(f"boundary_friction: must be in [0, 1] or a table of values "
                             f"measured against temperature, got {mu_b:g}")


def _finite(key: str, value: Any) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{key}: must be a number, got {value!r}") from None
    if not math.isfinite(v):
        raise InputError(f"{key}: must be finite, got {v}")
    return v


def kinematic_viscosity_astm_d341(kinematic_viscosity_40: float,
                                  kinematic_viscosity_100: float,
                                  temperature: np.ndarray | float) -> np.ndarray:
    """ν at ``temperature`` on the ASTM D341 (Walther) line through ν40 and ν100.

    Parameters
    ----------
    kinematic_viscosity_40, kinematic_viscosity_100 : float — [mm²/s]
    temperature : float or array — [degC]

    Returns
    -------
    numpy.ndarray — [mm²/s]
        log₁₀ log₁₀(ν + 0.7) linear in log₁₀ T_K through the two points (the line of
        :func:`friction.lubricant.fit_walther` through them).

    Notes
    -----
    Source: ASTM D341, "Standard practice for viscosity–temperature equations and charts
    for liquid petroleum or hydrocarbon products" (the simple form, ν ≥ 2 mm²/s).
    """
    line = fit_walther([40.0, 100.0], [kinematic_viscosity_40, kinematic_viscosity_100])
    return line.kinematic_viscosity(temperature)


def density_from_data_sheet(density_15: float, temperature: np.ndarray | float) -> np.ndarray:
    """ρ(θ) = ρ15 − 0.7 (θ + 273 − 289) [kg/m³] (ISO/TR 15144-1:2014, the lubricant data of
    the micropitting calculation; θ in degC)."""
    return density_15 - 0.7 * (np.asarray(temperature, float) + 273.0 - 289.0)


def pressure_viscosity_from_data_sheet(sheet: OilDataSheet,
                                       temperature: np.ndarray | float) -> np.ndarray:
    """The pressure–viscosity coefficient α(θ) [1/GPa] of a data sheet's oil.

    α₃₈ is the sheet's ``pressure_viscosity_38`` or ISO/TR 15144-1's a η₃₈^b of its base
    stock (:data:`PRESSURE_VISCOSITY_CORRELATIONS`; η₃₈ in N s/m² from ASTM D341 and the
    density relation); α(θ) = α₃₈ (1 + 516 (1/(θ + 273) − 1/311)) (ISO/TR 15144-1:2014).

    Parameters
    ----------
    sheet : OilDataSheet
    temperature : float or array — [degC]

    Returns
    -------
    numpy.ndarray — [1/GPa]
    """
    if sheet.pressure_viscosity_38 is not None:
        alpha38 = sheet.pressure_viscosity_38
    else:
        a, b = PRESSURE_VISCOSITY_CORRELATIONS[sheet.base_oil]
        nu38 = kinematic_viscosity_astm_d341(sheet.kinematic_viscosity_40,
                                             sheet.kinematic_viscosity_100, 38.0)
        eta38 = float(nu38) * 1e-6 * float(density_from_data_sheet(sheet.density_15, 38.0))
        alpha38 = a * eta38 ** b * 1e9  # m²/N -> 1/GPa
    theta = np.asarray(temperature, float)
    return alpha38 * (1.0 + 516.0 * (1.0 / (theta + 273.0) - 1.0 / 311.0))


def oil_file_mapping(sheet: OilDataSheet,
                     temperature: tuple[float, ...] = TABLE_TEMPERATURES) -> dict[str, Any]:
    """The oil file (the schema of :mod:`friction.lubricant`) of a data sheet, as a mapping
    ready for :func:`geometry.core.toml_files.dump_toml` or
    :func:`friction.lubricant.lubricant_from_mapping`.

    Parameters
    ----------
    sheet : OilDataSheet
    temperature : tuple of float — [degC]
        The table's temperatures (default :data:`TABLE_TEMPERATURES`).

    Returns
    -------
    dict
        ``name``, ``source`` (the sheet and the correlations), the tables over
        ``temperature`` (dynamic viscosity [Pa s], α [1/GPa], density [kg/m³]), the thermal
        and traction values (given or the stated assumptions), ``base_oil`` and the given
        durability values, ``[extrapolation]`` and ``[units]``.
    """
    t = np.asarray(temperature, float)
    nu = kinematic_viscosity_astm_d341(sheet.kinematic_viscosity_40,
                                       sheet.kinematic_viscosity_100, t)
    rho = density_from_data_sheet(sheet.density_15, t)
    alpha = pressure_viscosity_from_data_sheet(sheet, t)
    alpha_how = ("the data sheet's alpha at 38 degC" if sheet.pressure_viscosity_38
                 is not None else f"ISO/TR 15144-1's alpha_38 of a {sheet.base_oil} oil")
    doc: dict[str, Any] = {
        "schema": "hypoid-ltca lubricant 1",
        "name": sheet.name,
        "source": (f"{sheet.source}: nu40 {sheet.kinematic_viscosity_40:g}, nu100 "
                   f"{sheet.kinematic_viscosity_100:g} mm2/s, rho15 {sheet.density_15:g} "
                   f"kg/m3, {sheet.base_oil}; viscosity by ASTM D341 through nu40 and nu100, "
                   "density by ISO/TR 15144-1, pressure-viscosity coefficient by "
                   f"{alpha_how} with ISO/TR 15144-1's temperature relation "
                   "(friction.oil_data_sheet)"),
        "notes": "built from the data sheet by ltca oil / friction.oil_data_sheet",
        "temperature": [float(x) for x in t],
        "dynamic_viscosity": [float(f"{x:.6g}") for x in nu * 1e-6 * rho],
        "pressure_viscosity_coefficient": [float(f"{x:.5g}") for x in alpha],
        "density": [float(f"{x:.6g}") for x in rho],
        "thermal_conductivity": (_ASSUMED["thermal_conductivity"]
                                 if sheet.thermal_conductivity is None
                                 else sheet.thermal_conductivity),
        "thermal_conductivity_source": (_ASSUMED["thermal_conductivity_source"]
                                        if sheet.thermal_conductivity is None
                                        else "the data sheet"),
        "eyring_stress": _ASSUMED["eyring_stress"],
        "limiting_shear_coefficient": _ASSUMED["limiting_shear_coefficient"],
        "boundary_friction": _boundary_friction_entry(sheet.boundary_friction),
        "traction_source": _ASSUMED["traction_source"] + (
            "" if sheet.boundary_friction is None else
            "; boundary friction measured on the oil (the data sheet's value)"
            if not isinstance(sheet.boundary_friction, BoundaryFrictionTable) else
            "; boundary friction measured on the oil against temperature (its "
            "[boundary_friction] table and source)"),
        "base_oil": sheet.base_oil,
    }
    durability = {k: getattr(sheet, k) for k in ("fzg_load_stage", "permissible_specific_film")
                  if getattr(sheet, k) is not None}
    doc.update(durability)
    doc["durability_source"] = (
        f"the data sheet ({sheet.source}): " + ", ".join(durability) if durability
        else "base_oil from the data sheet; no FZG load stage or lambda_GFP given (no "
        "scuffing or micropitting safety)")
    doc["extrapolation"] = {"below": 20.0, "above": 40.0}
    doc["units"] = {"temperature": "degC", "dynamic_viscosity": "Pa s",
                    "pressure_viscosity_coefficient": "1/GPa", "density": "kg/m3",
                    "thermal_conductivity": "W/(m K)", "eyring_stress": "MPa",
                    "limiting_shear_coefficient": "1", "boundary_friction": "1",
                    "extrapolation": "K"}
    doc["units"].update({k: "1" for k in durability})
    return doc


def _boundary_friction_entry(mu_b: float | BoundaryFrictionTable | None
                             ) -> float | dict[str, Any]:
    """The oil file's ``boundary_friction``: the assumed number, the given one, or the
    given table as the file's ``[boundary_friction]`` table."""
    if mu_b is None:
        return _ASSUMED["boundary_friction"]
    if isinstance(mu_b, BoundaryFrictionTable):
        return {"temperature": [float(t) for t in mu_b.temperature],
                "value": [float(v) for v in mu_b.value], "source": mu_b.source}
    return float(mu_b)


def lubricant_from_data_sheet(sheet: OilDataSheet) -> Lubricant:
    """The :class:`~friction.lubricant.Lubricant` of a data sheet (:func:`oil_file_mapping`,
    validated as an oil file is).

    Raises
    ------
    InputError
        A data-sheet value out of range (on :class:`OilDataSheet`'s construction), naming
        the field.
    """
    return lubricant_from_mapping(oil_file_mapping(sheet), f"data sheet of {sheet.name!r}")
