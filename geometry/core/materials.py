"""Material data of the gear members and the contact-pressure limits they set.

The material table ``geometry/core/data/materials.toml`` (schema ``hypoid-ltca materials 1``)
holds one entry per material, made of property groups, each with its numbers and the
``source`` they come from: ``elastic`` (E, ν), ``hardness`` (surface hardness, HRC and its
Vickers equivalent) and ``yield`` (Tabor's constraint factor, from which the yield stress
of the surface layer follows). Groups this module does not parse (e.g. ISO 6336-5
allowable stress numbers and S–N curves for the durability code) are kept, with their
sources, in :attr:`Material.groups`. No gear in this module: it is of the toolkit's low
layer, read by the edge model of the LTCA and, later, the durability code alike.

The contact-pressure limits of a line contact (:data:`CONTACT_PRESSURE_LIMITS`) are the
elastic–perfectly-plastic limits of K. L. Johnson, *Contact Mechanics* (Cambridge 1985),
ch. 6 and §9.3, expressed as the peak Hertz pressure p₀ of the line contact:

* ``"first_yield"``: the onset of yield below the surface (von Mises): p₀ = 1.79 Y for
  ν = 0.3 (Johnson ch. 6: p₀ = 3.1 k von Mises, 3.3 k Tresca = 1.67 Y), computed here
  for the material's ν from the stresses on the contact's axis (McEwen 1949);
* ``"shakedown"``: the largest p₀ under repeated rolling (or repeated normal load) at
  which the residual stresses of the first passes leave the contact elastic thereafter
  (Melan's theorem): p₀ = 4 k, the orthogonal shear stress τ_xz of the Hertz line contact
  (at most p₀/4, at x = ±0.87 a, z = 0.5 a) reaching the yield stress in shear k, which
  no residual stress of a line contact can relieve (Johnson 1985, ch. 6 and §9.3;
  Johnson & Jefferis 1963). k = Y/√3 (von Mises).

Why the LTCA takes the shakedown limit (its default, ``LTCAOptions.edge_pressure_limit``):
a tooth edge passes through the mesh once per revolution, 10⁶–10⁹ times in a gear's life.
Below the shakedown limit the first passes yield a little, build residual stresses, and
the edge then carries its load elastically for good (so first yield, 22 % lower, would
bound it too tightly). Above it every pass adds plastic strain (ratchetting): the edge
flattens and wears until its pressure has fallen to the limit — it cannot carry more, and
the rest of the load passes to its neighbours: the elastic–perfectly-plastic bound of the
contact problem. The fully plastic limit (mean pressure ≈ hardness ≈ 3 Y, Johnson §6.2)
is that of a single static overload, whose width is set by plastic flow and not by
Hertz's elastic contact, and is reached only after many passes above shakedown.

Public functions
----------------
DEFAULT_MATERIAL         name of the toolkit's default material (case-carburised steel)
Material                 one material's data, with its sources
available_materials      names of the bundled materials
material                 a bundled material by name
read_material_table      parse a material table (TOML text or mapping)
CONTACT_PRESSURE_LIMITS  registry: limit name → p₀ [MPa] of a line contact
contact_pressure_limit   the peak Hertz pressure of a line contact at a named limit
first_yield_factor       p₀/Y at first yield of a line contact (von Mises), for ν
SHAKEDOWN_FACTOR         p₀/k at the shakedown limit of a line contact (4)

References
----------
K. L. Johnson (1985). *Contact Mechanics*. Cambridge University Press: §4.2 (stresses of
the Hertz line contact), ch. 6 (onset of yield, §6.2–6.3 indentation and hardness),
§9.3 (shakedown in rolling).
K. L. Johnson and J. A. Jefferis (1963). Plastic flow and residual stresses in rolling
and sliding contact. Proc. IMechE Symposium on Fatigue in Rolling Contact, 54–65.
J. E. McEwen (1949). Stresses in elastic cylinders in contact along a generatrix.
Phil. Mag. 40, 454–459.
D. Tabor (1951). *The Hardness of Metals*. Oxford University Press.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from importlib import resources
from types import MappingProxyType
from typing import Any

from geometry.core.caches import memoised
from geometry.core.errors import InputError, ModelUnavailableError

__all__ = [
    "CONTACT_PRESSURE_LIMITS",
    "DEFAULT_MATERIAL",
    "SHAKEDOWN_FACTOR",
    "Material",
    "available_materials",
    "contact_pressure_limit",
    "first_yield_factor",
    "material",
    "read_material_table",
]

#: the material of both members unless a case names another (``[<member>] material``)
DEFAULT_MATERIAL = "case_carburised_steel"

#: the ``schema`` field of a material table
SCHEMA = "hypoid-ltca materials 1"

#: standard gravity [m/s²]: a Vickers number (kgf/mm²) in MPa is HV × 9.80665
_G = 9.80665

#: the fields this module parses: (group, field) → unit in the table's [units]
_FIELDS = {
    ("elastic", "youngs_modulus"): "MPa",
    ("elastic", "poisson_ratio"): "1",
    ("hardness", "surface_hrc"): "HRC",
    ("hardness", "surface_hrc_range"): "HRC",
    ("hardness", "surface_hv"): "HV",
    ("yield", "constraint_factor"): "1",
}

#: p₀/k at the shakedown limit of a frictionless line contact: the orthogonal shear
#: stress τ_xz of the Hertz line contact peaks at p₀/4 (Johnson 1985 §4.2, §9.3)
SHAKEDOWN_FACTOR = 4.0


@dataclass(frozen=True)
class Material:
    """One material of the table, with the sources of its numbers.

    Attributes
    ----------
    key : str
        The table name (what a case file gives, e.g. ``"case_carburised_steel"``).
    name : str
        Its name in words.
    youngs_modulus : float — [MPa]
    poisson_ratio : float — [1]
    surface_hrc : float — [HRC]
        Nominal surface (case) hardness, Rockwell C.
    surface_hrc_range : (float, float) — [HRC]
    surface_hv : float — [HV]
        The same as a Vickers number (kgf/mm²).
    constraint_factor : float — [1]
        Tabor's c in H = c Y (H the Vickers hardness in pressure units).
    sources : mapping of str to str
        Source of each property group (``elastic``, ``hardness``, ``yield``, and any other).
    groups : mapping of str to mapping
        Every property group as read (including those this module does not parse).
    notes : str
    """

    key: str
    name: str
    youngs_modulus: float
    poisson_ratio: float
    surface_hrc: float
    surface_hrc_range: tuple[float, float]
    surface_hv: float
    constraint_factor: float
    sources: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))
    groups: Mapping[str, Mapping[str, Any]] = field(
        default_factory=lambda: MappingProxyType({}))
    notes: str = ""

    @property
    def hardness(self) -> float:
        """Vickers hardness in pressure units H = HV × 9.80665 — [MPa]."""
        return self.surface_hv * _G

    @property
    def yield_strength(self) -> float:
        """Uniaxial yield stress of the surface layer Y = H / c (Tabor) — [MPa]."""
        return self.hardness / self.constraint_factor

    @property
    def shear_yield_strength(self) -> float:
        """Yield stress in shear k = Y/√3 (von Mises) — [MPa]."""
        return self.yield_strength / math.sqrt(3.0)

    @property
    def thermal_effusivity(self) -> float:
        """Thermal effusivity B = √(kρc) of the surface layer — [W s^0.5/(m2 K)].

        From the ``thermal`` group (conductivity, density, specific heat): the
        coefficient of a moving heat source's flash temperature (Jaeger 1942).

        Raises
        ------
        ModelUnavailableError
            The material has no ``thermal`` group.
        """
        group = self.groups.get("thermal")
        if group is None:
            raise ModelUnavailableError(f"material {self.key!r}: no thermal properties "
                                        f"(a [{self.key}.thermal] table)")
        values = []
        for name in ("thermal_conductivity", "density", "specific_heat"):
            values.append(_number(f"{self.key}.thermal.{name}", group.get(name), low=0.0))
        return math.sqrt(values[0] * values[1] * values[2])


def _number(where: str, value: Any, low: float | None = None,
            high: float | None = None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{where}: must be a number, got {value!r}")
    from geometry.core.validation import real  # NumPy: not at import (`ltca --help`)

    return real(where, value, low=low, high=high, low_open=low is not None)


def _group(entry: Mapping, key: str, group: str) -> Mapping[str, Any]:
    where = f"{key}.{group}"
    tab = entry.get(group)
    if not isinstance(tab, Mapping):
        raise InputError(f"{where}: missing table (each material needs elastic, hardness "
                         "and yield groups)")
    src = tab.get("source")
    if not isinstance(src, str) or not src.strip():
        raise InputError(f"{where}.source: every property group names its source")
    return tab


def _material(key: str, entry: Any, units: Mapping[str, str]) -> Material:
    if not isinstance(entry, Mapping):
        raise InputError(f"{key}: must be a table of property groups")
    groups = {g: v for g, v in entry.items() if isinstance(v, Mapping)}
    for g in groups:
        _group(entry, key, g)
    el, hd, yl = (_group(entry, key, g) for g in ("elastic", "hardness", "yield"))
    for (group, name), unit in _FIELDS.items():
        if name not in entry[group]:
            raise InputError(f"{key}.{group}.{name}: missing [{unit}]")
        if units.get(name) != unit:
            raise InputError(f"units.{name}: must be {unit!r}, got {units.get(name)!r}")
    rng = hd["surface_hrc_range"]
    if not (isinstance(rng, list) and len(rng) == 2):
        raise InputError(f"{key}.hardness.surface_hrc_range: must be [low, high] [HRC], "
                         f"got {rng!r}")
    lo = _number(f"{key}.hardness.surface_hrc_range", rng[0], 0.0, 80.0)
    hi = _number(f"{key}.hardness.surface_hrc_range", rng[1], lo, 80.0)
    hrc = _number(f"{key}.hardness.surface_hrc", hd["surface_hrc"], 0.0, 80.0)
    if not lo <= hrc <= hi:
        raise InputError(f"{key}.hardness.surface_hrc: must lie in surface_hrc_range "
                         f"[{lo:g}, {hi:g}] HRC, got {hrc:g}")
    return Material(
        key=key,
        name=str(entry.get("name", key)),
        youngs_modulus=_number(f"{key}.elastic.youngs_modulus", el["youngs_modulus"], 0.0),
        poisson_ratio=_number(f"{key}.elastic.poisson_ratio", el["poisson_ratio"], 0.0, 0.5),
        surface_hrc=hrc,
        surface_hrc_range=(lo, hi),
        surface_hv=_number(f"{key}.hardness.surface_hv", hd["surface_hv"], 0.0, 3000.0),
        constraint_factor=_number(f"{key}.yield.constraint_factor", yl["constraint_factor"],
                                  1.0, 5.0),
        sources=MappingProxyType({g: str(v["source"]) for g, v in groups.items()}),
        groups=MappingProxyType({g: MappingProxyType(dict(v)) for g, v in groups.items()}),
        notes=str(entry.get("notes", "")),
    )


def read_material_table(table: str | Mapping[str, Any],
                        origin: str = "<table>") -> dict[str, Material]:
    """Parse a material table (the schema of ``geometry/core/data/materials.toml``).

    Parameters
    ----------
    table : str or mapping
        TOML text or the parsed mapping.
    origin : str
        Where it came from, quoted in errors.

    Returns
    -------
    dict of str to Material
        Keyed by table name.

    Raises
    ------
    InputError
        Bad TOML, a wrong ``schema``, a missing group, field, unit or ``source``, or a
        number out of range (the message names the field).
    """
    if isinstance(table, str):
        try:
            table = tomllib.loads(table)
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"{origin}: not valid TOML ({exc})") from None
    if table.get("schema") != SCHEMA:
        raise InputError(f"{origin}: schema must be {SCHEMA!r}, got {table.get('schema')!r}")
    units = table.get("units", {})
    if not isinstance(units, Mapping):
        raise InputError(f"{origin}: units must be a table")
    return {k: _material(k, v, units) for k, v in table.items()
            if k not in ("schema", "units")}


@memoised(maxsize=None)
def _bundled() -> dict[str, Material]:
    text = resources.files("geometry.core").joinpath("data", "materials.toml").read_text(
        encoding="utf-8")
    return read_material_table(text, "geometry/core/data/materials.toml")


def available_materials() -> tuple[str, ...]:
    """Names of the bundled materials (``geometry/core/data/materials.toml``), sorted."""
    return tuple(sorted(_bundled()))


def material(name: str) -> Material:
    """A bundled material by name.

    Parameters
    ----------
    name : str
        A name from :func:`available_materials`.

    Returns
    -------
    Material

    Raises
    ------
    ModelUnavailableError
        Unknown name (the message lists the available ones).
    """
    table = _bundled()
    if name not in table:
        raise ModelUnavailableError(
            f"material: {name!r} is not in the material table; available: "
            f"{', '.join(sorted(table))}")
    return table[name]


def _axis_stresses(zeta: float, nu: float) -> tuple[float, float, float]:
    """(σ_x, σ_y, σ_z)/p₀ on the axis of a Hertz line contact at depth ζ = z/a, plane
    strain (McEwen 1949; Johnson 1985 §4.2; σ_y = ν(σ_x + σ_z))."""
    r = math.sqrt(1.0 + zeta * zeta)
    sx = -((1.0 + 2.0 * zeta * zeta) / r - 2.0 * zeta)
    sz = -1.0 / r
    return sx, nu * (sx + sz), sz


def first_yield_factor(poisson_ratio: float) -> float:
    """p₀/Y at the onset of yield (von Mises) in a frictionless Hertz line contact.

    Parameters
    ----------
    poisson_ratio : float — [1]
        ν in [0, 0.5).

    Returns
    -------
    float — [1]
        Y / max √(3 J₂)/p₀ over the depth on the contact's axis (where the maximum lies):
        1.79 for ν = 0.3.

    Raises
    ------
    InputError
        ν out of range.

    Notes
    -----
    Johnson (1985) ch. 6: a line contact first yields below the surface at p₀ = 3.1 k =
    1.79 Y (von Mises, ν = 0.3; Tresca: 3.3 k = 1.67 Y, at z = 0.78 a); the subsurface
    stresses of McEwen (1949), Johnson §4.2. Checked in tests/test_materials.py against
    the whole stress field and Johnson's numbers.
    """
    from geometry.core.validation import real

    nu = real("poisson_ratio", poisson_ratio, unit="1", low=0.0, high=0.5, high_open=True)

    def neg_vm(zeta: float) -> float:
        sx, sy, sz = _axis_stresses(zeta, nu)
        return -math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))

    import scipy.optimize  # here: the case schema imports this module, `ltca --help` too

    res = scipy.optimize.minimize_scalar(neg_vm, bounds=(0.0, 3.0), method="bounded",
                                         options={"xatol": 1e-10})
    return 1.0 / -float(res.fun)


def _first_yield(m: Material) -> float:
    return first_yield_factor(m.poisson_ratio) * m.yield_strength


def _shakedown(m: Material) -> float:
    return SHAKEDOWN_FACTOR * m.shear_yield_strength


#: limit name → function(Material) → peak Hertz pressure p₀ [MPa] of a line contact at
#: that limit (module docstring)
CONTACT_PRESSURE_LIMITS: Mapping[str, Callable[[Material], float]] = MappingProxyType({
    "first_yield": _first_yield,
    "shakedown": _shakedown,
})


def contact_pressure_limit(mat: Material | str, limit: str = "shakedown") -> float:
    """The peak Hertz pressure of a line contact at a named elastic–plastic limit.

    Parameters
    ----------
    mat : Material or str
        The material (or its name in the table).
    limit : str
        A name of :data:`CONTACT_PRESSURE_LIMITS`: ``"shakedown"`` (default; p₀ = 4 k,
        the limit the LTCA uses) or ``"first_yield"`` (p₀ = 1.79 Y for ν = 0.3).

    Returns
    -------
    float — [MPa]
        p₀ at the limit: 5262 MPa (shakedown) and 4087 MPa (first yield) for the default
        case-carburised steel (697 HV: Y = 2279 MPa, k = 1316 MPa).

    Raises
    ------
    ModelUnavailableError
        Unknown material or limit name (the message lists the available ones).

    Notes
    -----
    Johnson (1985) ch. 6 and §9.3 (module docstring). With the load per length
    w′ = π R p₀²/E* of a Hertz line contact of equivalent radius R
    (:func:`geometry.core.hertz.hertz_line_load`) it gives the force a segment can carry.
    """
    m = material(mat) if isinstance(mat, str) else mat
    if limit not in CONTACT_PRESSURE_LIMITS:
        raise ModelUnavailableError(
            f"contact pressure limit: {limit!r} is not known; available: "
            f"{', '.join(CONTACT_PRESSURE_LIMITS)}")
    return float(CONTACT_PRESSURE_LIMITS[limit](m))
