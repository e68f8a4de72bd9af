"""Lubricant properties versus temperature: viscosity fits, pressure–viscosity coefficient, density.

A :class:`Lubricant` holds a property table at a few temperatures (the seed's Table 5.2
for 75W90 is bundled as ``friction/data/75W90.toml``); the functions here evaluate the
properties at any temperature inside a plausible extrapolation range:

================================  =========================================  ===========
property                          how it is evaluated                        units
================================  =========================================  ===========
dynamic viscosity η₀              Vogel fit (default) or Walther/ASTM D341   Pa s
pressure–viscosity coefficient α  piecewise log-linear in T                  1/GPa
density ρ                         straight line fitted by least squares      kg/m3
thermal conductivity k            constant, or piecewise linear              W/(m K)
temperature–viscosity coeff. β    −d ln η₀/dT of the Vogel fit, or tabulated 1/K
boundary friction μ_b             constant, or linear in T, held at the ends 1
================================  =========================================  ===========

Units: temperature in degC at the boundary (the Vogel constant c is in degC, so the fit
is the same in K or degC); viscosity in Pa s and the pressure–viscosity coefficient in
1/GPa because those are the units of the seed's table and of lubricant data sheets —
:mod:`friction.film` and :mod:`friction.rolling` take them in exactly these units and
convert at their boundary.

Oil files are TOML with the schema of ``friction/data/75W90.toml``: ``name``, ``source``,
``temperature``, ``dynamic_viscosity``, ``pressure_viscosity_coefficient``, ``density``,
``thermal_conductivity`` (one value or one per temperature), optional
``temperature_viscosity_coefficient``, ``thermal_conductivity_source``, ``notes``, the
optional film-traction properties ``eyring_stress`` [MPa], ``limiting_shear_coefficient``
and ``boundary_friction`` [1] with ``traction_source`` (used by the ``mixed_ehl``
friction model, :mod:`friction.mixed_ehl`; ``boundary_friction`` is one number or a
``[boundary_friction]`` table of values measured against temperature with its own
``source``, :class:`BoundaryFrictionTable`, :func:`boundary_friction_coefficient`), the
optional surface-durability properties
``fzg_load_stage`` [1] (the FZG A/8.3/90 scuffing-test failure load stage), ``base_oil``
(the base-oil kind of the scuffing temperature's lubricant factor,
:data:`BASE_OIL_FACTORS`) and ``permissible_specific_film`` [1]
(λ_GFP against micropitting) with ``durability_source`` (used by the scuffing and
micropitting assessment, :mod:`contact.load_capacity.flash_temperature`,
:mod:`contact.load_capacity.micropitting`),
``schema``, an ``[extrapolation]`` table (``below``, ``above`` in K) and a required
``[units]`` table that must state the units above (so a file in other units is refused,
not misread).
"""

from __future__ import annotations

import itertools
import logging
import math
import tomllib
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import minimize_scalar

from friction.validity import FrictionModelRangeWarning
from geometry.core.caches import memoised
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.renamed import renamed_keywords
from geometry.core.toml_files import read_toml
from geometry.core.validation import known_fields, one_of, real, real_array, scalar_or_array

__all__ = [
    "BASE_OIL_FACTORS",
    "LUBRICANT_SCHEMA",
    "VISCOSITY_MODELS",
    "BoundaryFrictionTable",
    "Lubricant",
    "VogelFit",
    "WaltherFit",
    "available_lubricants",
    "boundary_friction_coefficient",
    "boundary_friction_in_range",
    "boundary_friction_source",
    "density",
    "fit_vogel",
    "fit_walther",
    "kinematic_viscosity",
    "load_lubricant",
    "lubricant_from_mapping",
    "pressure_viscosity_coefficient",
    "temperature_range",
    "temperature_viscosity_coefficient",
    "thermal_conductivity",
    "viscosity",
]

#: lubricant factor X_L of the base oil, of the scuffing temperature θ_S and of ISO's mean
#: friction coefficient (ISO/TR 13989-1:2000 Eq. (27); DIN 3990-4:1987 the same values):
#: the base oils an oil file's ``base_oil`` may name (used by
#: :mod:`contact.load_capacity.flash_temperature`)
BASE_OIL_FACTORS: Mapping[str, float] = MappingProxyType({
    "mineral": 1.0,
    "polyalphaolefin": 0.8,
    "polyglycol_non_water_soluble": 0.7,
    "polyglycol_water_soluble": 0.6,
    "phosphate_ester": 1.3,
    "traction_fluid": 1.5,
})

log = logging.getLogger(__name__)

_ABSOLUTE_ZERO_C = -273.15
_WALTHER_SHIFT = 0.7  # ASTM D341: Z = ν + 0.7 for ν ≥ 2 mm²/s

#: Units each field of an oil file must declare in its ``[units]`` table.
_REQUIRED_UNITS: Mapping[str, str] = MappingProxyType(
    {
        "temperature": "degC",
        "dynamic_viscosity": "Pa s",
        "pressure_viscosity_coefficient": "1/GPa",
        "density": "kg/m3",
        "thermal_conductivity": "W/(m K)",
    }
)
_OPTIONAL_UNITS: Mapping[str, str] = MappingProxyType(
    {"temperature_viscosity_coefficient": "1/K", "extrapolation": "K",
     "eyring_stress": "MPa", "limiting_shear_coefficient": "1", "boundary_friction": "1",
     "fzg_load_stage": "1", "permissible_specific_film": "1"}
)
_KNOWN_KEYS = frozenset(
    {
        "schema",
        "name",
        "source",
        "notes",
        "temperature",
        "dynamic_viscosity",
        "pressure_viscosity_coefficient",
        "density",
        "thermal_conductivity",
        "thermal_conductivity_source",
        "temperature_viscosity_coefficient",
        "eyring_stress",
        "limiting_shear_coefficient",
        "boundary_friction",
        "traction_source",
        "fzg_load_stage",
        "base_oil",
        "permissible_specific_film",
        "durability_source",
        "extrapolation",
        "units",
    }
)


# ----------------------------------------------------------------------------- fits
@dataclass(frozen=True)
class VogelFit:
    """Vogel equation η = a · exp(b / (T − c)).

    Attributes
    ----------
    a : float — [Pa s]
    b : float — [K]
    c : float — [degC]
    rms_log_residual : float — [1]
        RMS of ln η_fit − ln η_table at the table points.
    """

    a: float
    b: float
    c: float
    rms_log_residual: float


@dataclass(frozen=True)
class WaltherFit:
    """Walther equation (ASTM D341): log₁₀ log₁₀(ν + 0.7) = A − B log₁₀(T_K), ν in mm²/s.

    Attributes
    ----------
    A : float — [1]
    B : float — [1]
    rms_log_residual : float — [1]
        RMS of ln ν_fit − ln ν_table at the table points.
    """

    A: float
    B: float
    rms_log_residual: float

    def kinematic_viscosity(self, temperature: ArrayLike) -> NDArray[np.float64]:
        """ν [mm²/s] on this line at ``temperature`` [degC] (ASTM D341, Eq. (1)–(2))."""
        t_k = np.asarray(temperature, float) - _ABSOLUTE_ZERO_C
        return 10.0 ** (10.0 ** (self.A - self.B * np.log10(t_k))) - _WALTHER_SHIFT


def _vogel_lsq(c: float, t: NDArray[np.float64], ln_eta: NDArray[np.float64]):
    design = np.column_stack([np.ones_like(t), 1.0 / (t - c)])
    coef, *_ = np.linalg.lstsq(design, ln_eta, rcond=None)
    resid = design @ coef - ln_eta
    return coef, resid


def _vogel_sse_grid(c: NDArray[np.float64], t: NDArray[np.float64],
                    ln_eta: NDArray[np.float64]) -> NDArray[np.float64]:
    """Least-squares SSE of ln η = ln a + b x, x = 1/(T − c), at each c of a grid (m,).

    The straight-line fit's closed form (slope S_xy/S_xx of the centred data) for all m
    values of c at once, the residuals summed directly rather than as S_yy − S_xy²/S_xx,
    which cancels when the fit is close (the coarse scan of :func:`fit_vogel`).
    """
    x = 1.0 / (t[None, :] - c[:, None])
    xc = x - x.mean(axis=1, keepdims=True)
    yc = ln_eta - ln_eta.mean()
    slope = (xc @ yc) / np.einsum("ij,ij->i", xc, xc)
    resid = yc[None, :] - slope[:, None] * xc
    return np.einsum("ij,ij->i", resid, resid)


def fit_vogel(temperature: ArrayLike, dynamic_viscosity: ArrayLike) -> VogelFit:
    """Least-squares Vogel fit ln η = ln a + b/(T − c) to a viscosity table.

    For fixed c the problem is linear in (ln a, b); c is found by a bounded 1-D search
    over (−273.15 °C, min T − 1 K) after a coarse grid (variable projection).

    Parameters
    ----------
    temperature : array (n,) — [degC]
        At least 3 distinct temperatures.
    dynamic_viscosity : array (n,) — [Pa s]
        Positive viscosities at those temperatures.

    Returns
    -------
    VogelFit
        a [Pa s], b [K], c [degC] and the RMS residual of ln η.

    Raises
    ------
    InputError
        Fewer than 3 points, non-positive viscosity, or a fit with b ≤ 0 (viscosity not
        decreasing with temperature).

    Notes
    -----
    Source: Vogel, H., Phys. Z. 22 (1921) 645; the form used for gear oils in e.g.
    Seeton, C. J., Tribol. Lett. 22 (2006) 67. The seed interpolates Table 5.2 without
    saying how (NOTES.md asks for a Vogel or Walther fit, not linear).
    """
    t = real_array("temperature", temperature, unit="degC", low=_ABSOLUTE_ZERO_C,
                   low_open=True).ravel()
    eta = real_array("dynamic_viscosity", dynamic_viscosity, unit="Pa s", low=0.0,
                     low_open=True).ravel()
    if t.size < 3 or t.size != eta.size:
        raise InputError(
            "temperature, dynamic_viscosity: must be of the same length, at least 3, for a"
            f" Vogel fit, got {t.size} and {eta.size}"
        )
    ln_eta = np.log(eta)
    lo, hi = _ABSOLUTE_ZERO_C, float(t.min()) - 1.0

    def sse(c: float) -> float:
        return float(np.sum(_vogel_lsq(c, t, ln_eta)[1] ** 2))

    grid = np.linspace(lo, hi, 200)
    k = int(np.argmin(_vogel_sse_grid(grid, t, ln_eta)))
    bracket = (grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)])
    opt = minimize_scalar(sse, bounds=bracket, method="bounded", options={"xatol": 1e-8})
    c = float(opt.x)
    (ln_a, b), resid = _vogel_lsq(c, t, ln_eta)
    if b <= 0:
        raise InputError(
            "dynamic_viscosity: must decrease with temperature for a Vogel fit, got a fitted"
            f" b = {b:g} K ≤ 0"
        )
    return VogelFit(
        a=math.exp(ln_a),
        b=float(b),
        c=c,
        rms_log_residual=float(np.sqrt(np.mean(resid**2))),
    )


def fit_walther(temperature: ArrayLike, kinematic_viscosity: ArrayLike) -> WaltherFit:
    """Least-squares Walther (ASTM D341) fit log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T_K.

    Parameters
    ----------
    temperature : array (n,) — [degC]
        At least 2 distinct temperatures.
    kinematic_viscosity : array (n,) — [mm²/s] (cSt)
        Kinematic viscosities, each ≥ 2 mm²/s (range of the simple D341 form).

    Returns
    -------
    WaltherFit
        A, B [1] and the RMS residual of ln ν.

    Raises
    ------
    InputError
        Fewer than 2 points or a viscosity below 2 mm²/s.

    Notes
    -----
    Source: ASTM D341, "Standard practice for viscosity–temperature equations and charts
    for liquid petroleum or hydrocarbon products", Eq. (1)–(2) with Z = ν + 0.7 (the
    additional terms of Z below 2 mm²/s are not implemented).
    """
    t = real_array("temperature", temperature, unit="degC", low=_ABSOLUTE_ZERO_C,
                   low_open=True).ravel()
    # ≥ 2 mm²/s: the range of ASTM D341's simple form
    nu = real_array("kinematic_viscosity", kinematic_viscosity, unit="mm2/s", low=2.0).ravel()
    if t.size < 2 or t.size != nu.size:
        raise InputError(
            "temperature, kinematic_viscosity: must be of the same length, at least 2, for a"
            f" Walther fit, got {t.size} and {nu.size}"
        )
    x = np.log10(t - _ABSOLUTE_ZERO_C)
    y = np.log10(np.log10(nu + _WALTHER_SHIFT))
    slope, intercept = np.polyfit(x, y, 1)
    fitted = 10.0 ** (10.0 ** (intercept + slope * x)) - _WALTHER_SHIFT
    return WaltherFit(
        A=float(intercept),
        B=float(-slope),
        rms_log_residual=float(np.sqrt(np.mean(np.log(fitted / nu) ** 2))),
    )


# ----------------------------------------------------------------------------- dataclass
def _float_tuple(field_name: str, value: Any) -> tuple[float, ...]:
    if isinstance(value, (str, bytes)) or not isinstance(value, (Sequence, np.ndarray)):
        value = [value]
    try:
        out = tuple(float(v) for v in value)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{field_name}: must be a list of numbers, got {value!r}") from exc
    return out


def _check_positive(field_name: str, values: tuple[float, ...], units: str) -> None:
    if not values:
        raise InputError(f"{field_name}: must be at least one value [{units}], got none")
    real_array(field_name, values, unit=units, low=0.0, low_open=True)


#: The fields of an oil file's ``[boundary_friction]`` table.
_BOUNDARY_FRICTION_FIELDS = ("temperature", "value", "source")


@dataclass(frozen=True)
class BoundaryFrictionTable:
    """Boundary friction μ_b of an oil measured against temperature.

    The friction of the asperity junctions under the oil's boundary (additive) films: the
    low-speed plateau of a Stribeck curve measured on steel (MTM, ball-on-disc, twin disc)
    at several oil temperatures. Interpolated linearly in temperature and held at the end
    values outside the measured range (:func:`boundary_friction_coefficient`).

    Parameters
    ----------
    temperature : sequence of float (n ≥ 2) — [degC]
        Strictly increasing temperatures of the measurements (the oil file's temperature
        unit, ``units.temperature``).
    value : sequence of float (n) — [1]
        μ_b at those temperatures, each in [0, 1].
    source : str
        Where the values come from (test rig, load, speed, slide-to-roll ratio, materials,
        lab and year); required, non-empty.

    Raises
    ------
    InputError
        On construction, naming the field (``boundary_friction.temperature``,
        ``boundary_friction.value``, ``boundary_friction.source``): fewer than 2 points,
        unequal lengths, temperatures not finite or not strictly increasing, a value
        outside [0, 1], an empty source.

    Notes
    -----
    Source: the oil file (``source``); a table rather than a fit because boundary friction
    against temperature has no accepted functional form (it may rise or fall as the
    additives' films form and desorb).
    """

    temperature: tuple[float, ...]
    value: tuple[float, ...]
    source: str

    def __post_init__(self) -> None:
        t = _float_tuple("boundary_friction.temperature", self.temperature)
        v = _float_tuple("boundary_friction.value", self.value)
        if len(t) < 2:
            raise InputError("boundary_friction.temperature: must be at least 2 values [degC]"
                             f" for a table (a single value: give boundary_friction as one "
                             f"number), got {len(t)}")
        real_array("boundary_friction.temperature", t, unit="degC", low=_ABSOLUTE_ZERO_C,
                   low_open=True)
        if any(b <= a for a, b in itertools.pairwise(t)):
            raise InputError("boundary_friction.temperature: must be strictly increasing "
                             f"[degC], got {t!r}")
        if len(v) != len(t):
            raise InputError(f"boundary_friction.value: must be one value per temperature "
                             f"({len(t)}), got {len(v)}")
        real_array("boundary_friction.value", v, unit="1", low=0.0, high=1.0)
        if not isinstance(self.source, str) or not self.source.strip():
            raise InputError("boundary_friction.source: must be a non-empty string naming "
                             "where the measured values come from (rig, load, speed, slide-"
                             f"to-roll ratio, materials), got {self.source!r}")
        object.__setattr__(self, "temperature", t)
        object.__setattr__(self, "value", v)

    @classmethod
    def from_mapping(cls, table: Mapping[str, Any]) -> BoundaryFrictionTable:
        """The table of an oil file's ``[boundary_friction]`` (keys ``temperature``,
        ``value``, ``source``).

        Parameters
        ----------
        table : mapping
            The parsed TOML table.

        Returns
        -------
        BoundaryFrictionTable

        Raises
        ------
        InputError
            An unknown or missing key (named ``boundary_friction.<key>``), or a check of
            the class.
        """
        known_fields("boundary_friction", table, _BOUNDARY_FRICTION_FIELDS)
        missing = [k for k in _BOUNDARY_FRICTION_FIELDS if k not in table]
        if missing:
            raise InputError(f"boundary_friction.{missing[0]}: missing; a boundary_friction "
                             "table needs temperature [degC], value [1] and source")
        return cls(table["temperature"], table["value"], table["source"])


@dataclass(frozen=True)
class Lubricant:
    """A lubricant's property table versus temperature.

    Parameters
    ----------
    name : str
        Oil name, e.g. ``"75W90"``.
    temperature : sequence of float (n ≥ 3) — [degC]
        Strictly increasing table temperatures.
    dynamic_viscosity : sequence of float (n) — [Pa s]
        Ambient-pressure dynamic viscosity η₀, strictly decreasing with temperature.
    pressure_viscosity_coefficient : sequence of float (n) — [1/GPa]
        Barus pressure–viscosity coefficient α (η = η₀ e^{αp}).
    density : sequence of float (n) — [kg/m3]
    thermal_conductivity : float or sequence of float (1 or n) — [W/(m K)]
    source : str
        Where the table comes from (paper, table number, data sheet).
    temperature_viscosity_coefficient : sequence of float (n) or None — [1/K]
        β = −(1/η) dη/dT; if None it is derived from the Vogel fit.
    extrapolation_below, extrapolation_above : float — [K]
        The accepted temperature range is [min T − below, max T + above].
    thermal_conductivity_source, notes : str
    eyring_stress : float or None — [MPa]
        Eyring stress τ₀ of the film (> 0); None: the model default.
    limiting_shear_coefficient : float or None — [1]
        Λ = τ_L/p in (0, 1]; None: the model default.
    boundary_friction : float, BoundaryFrictionTable, mapping or None — [1]
        μ_b of the asperity contacts: one value in [0, 1], or measured values against
        temperature (a :class:`BoundaryFrictionTable`, or the mapping of an oil file's
        ``[boundary_friction]`` table, made one on construction); None: the model
        default. Evaluated at a temperature by :func:`boundary_friction_coefficient`.
    traction_source : str
        Where the three traction values come from (a table's own ``source`` says where
        its μ_b come from).
    fzg_load_stage : float or None — [1]
        Failure load stage of the FZG A/8.3/90 scuffing test (ISO 14635-1), in [1, 14];
        None: unknown (no scuffing safety).
    base_oil : str or None
        Base-oil kind for the scuffing temperature's lubricant factor, one of
        :data:`BASE_OIL_FACTORS`; None: unknown.
    permissible_specific_film : float or None — [1]
        λ_GFP, the permissible specific film thickness against micropitting (ISO/TS
        6336-22), > 0; None: unknown (no micropitting safety).
    durability_source : str
        Where the three surface-durability values come from.

    Raises
    ------
    InputError
        On construction, naming the field, if a table is empty, of unequal length, not
        finite, not positive, the temperatures are not strictly increasing or the
        viscosity does not decrease with temperature.

    Notes
    -----
    The Vogel and Walther fits are made once, at construction (attributes ``vogel`` and
    ``walther``). Instances are immutable and hashable by value.
    """

    name: str
    temperature: tuple[float, ...]
    dynamic_viscosity: tuple[float, ...]
    pressure_viscosity_coefficient: tuple[float, ...]
    density: tuple[float, ...]
    thermal_conductivity: tuple[float, ...]
    source: str
    temperature_viscosity_coefficient: tuple[float, ...] | None = None
    extrapolation_below: float = 20.0
    extrapolation_above: float = 40.0
    thermal_conductivity_source: str = ""
    notes: str = ""
    eyring_stress: float | None = None
    limiting_shear_coefficient: float | None = None
    boundary_friction: float | BoundaryFrictionTable | None = None
    traction_source: str = ""
    fzg_load_stage: float | None = None
    base_oil: str | None = None
    permissible_specific_film: float | None = None
    durability_source: str = ""
    vogel: VogelFit = field(init=False, repr=False, compare=False)
    walther: WaltherFit = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError(f"name: must be a non-empty string, got {self.name!r}")
        if not isinstance(self.source, str) or not self.source.strip():
            raise InputError("source: must be a non-empty string naming where the table comes "
                             f"from, got {self.source!r}")
        tables = {
            "temperature": "degC",
            "dynamic_viscosity": "Pa s",
            "pressure_viscosity_coefficient": "1/GPa",
            "density": "kg/m3",
            "thermal_conductivity": "W/(m K)",
        }
        for key in tables:
            object.__setattr__(self, key, _float_tuple(key, getattr(self, key)))
        if self.temperature_viscosity_coefficient is not None:
            object.__setattr__(
                self,
                "temperature_viscosity_coefficient",
                _float_tuple(
                    "temperature_viscosity_coefficient", self.temperature_viscosity_coefficient
                ),
            )
        t = self.temperature
        if len(t) < 3:
            raise InputError(f"temperature: must be at least 3 values [degC], got {len(t)}")
        real_array("temperature", t, unit="degC", low=_ABSOLUTE_ZERO_C, low_open=True)
        if any(b <= a for a, b in itertools.pairwise(t)):
            raise InputError(f"temperature: must be strictly increasing [degC], got {t!r}")
        for key, units in tables.items():
            if key != "temperature":
                _check_positive(key, getattr(self, key), units)
        for key in ("dynamic_viscosity", "pressure_viscosity_coefficient", "density"):
            if len(getattr(self, key)) != len(t):
                raise InputError(
                    f"{key}: must be one value per temperature ({len(t)}), got"
                    f" {len(getattr(self, key))}"
                )
        if len(self.thermal_conductivity) not in (1, len(t)):
            raise InputError(
                f"thermal_conductivity: must be 1 value or one per temperature ({len(t)}),"
                f" got {len(self.thermal_conductivity)}"
            )
        beta = self.temperature_viscosity_coefficient
        if beta is not None:
            _check_positive("temperature_viscosity_coefficient", beta, "1/K")
            if len(beta) != len(t):
                raise InputError(
                    f"temperature_viscosity_coefficient: must be one value per temperature"
                    f" ({len(t)}), got {len(beta)}"
                )
        eta = self.dynamic_viscosity
        if any(b >= a for a, b in itertools.pairwise(eta)):
            raise InputError(
                f"dynamic_viscosity: must decrease strictly with temperature [Pa s], got {eta!r}"
            )
        for key in ("extrapolation_below", "extrapolation_above"):
            val = getattr(self, key)
            if not isinstance(val, (int, float)) or not math.isfinite(val) or val < 0:
                raise InputError(f"{key}: must be finite and >= 0 [K], got {val!r}")
        self._check_traction()
        self._check_durability()
        vogel = fit_vogel(t, eta)
        if vogel.c >= t[0] - self.extrapolation_below:
            raise InputError(
                "extrapolation_below: must keep the range above the Vogel pole c ="
                f" {vogel.c:.1f} degC [K], got {self.extrapolation_below!r}"
            )
        object.__setattr__(self, "vogel", vogel)
        nu = np.asarray(eta) / np.asarray(self.density) * 1e6
        object.__setattr__(self, "walther", fit_walther(t, nu))
        log.debug("lubricant %s: %s, %s", self.name, vogel, self.walther)

    def _check_traction(self) -> None:
        """Validate the optional film-traction fields (naming the field); make a
        ``boundary_friction`` mapping (an oil file's table) a :class:`BoundaryFrictionTable`."""
        if isinstance(self.boundary_friction, Mapping):
            object.__setattr__(self, "boundary_friction",
                               BoundaryFrictionTable.from_mapping(self.boundary_friction))
        for key, high, low_open, unit in (("eyring_stress", None, True, "MPa"),
                                           ("limiting_shear_coefficient", 1.0, True, "1"),
                                           ("boundary_friction", 1.0, False, "1")):
            value = getattr(self, key)
            if key == "boundary_friction" and isinstance(value, (Sequence, np.ndarray)) \
                    and not isinstance(value, str):
                raise InputError("boundary_friction: must be one number in [0, 1] [1] or a "
                                 "[boundary_friction] table with temperature [degC], value "
                                 f"[1] and source, got {value!r}")
            if value is not None and not isinstance(value, BoundaryFrictionTable):
                object.__setattr__(self, key, real(key, value, unit=unit, low=0.0,
                                                   low_open=low_open, high=high))

    def _check_durability(self) -> None:
        """Validate the optional surface-durability fields (naming the field)."""
        if self.fzg_load_stage is not None:
            object.__setattr__(self, "fzg_load_stage", real(
                "fzg_load_stage", self.fzg_load_stage, unit="1", low=1.0, high=14.0))
        if self.base_oil is not None:
            one_of("base_oil", self.base_oil, BASE_OIL_FACTORS)
        if self.permissible_specific_film is not None:
            object.__setattr__(self, "permissible_specific_film", real(
                "permissible_specific_film", self.permissible_specific_film, unit="1",
                low=0.0, low_open=True))
        if not isinstance(self.durability_source, str):
            raise InputError("durability_source: must be a string, got "
                             f"{self.durability_source!r}")


# ----------------------------------------------------------------------------- evaluation
def temperature_range(lubricant: Lubricant) -> tuple[float, float]:
    """Accepted temperature range of a lubricant's fits.

    Parameters
    ----------
    lubricant : Lubricant

    Returns
    -------
    (float, float) — [degC]
        ``(min T − extrapolation_below, max T + extrapolation_above)``.

    Notes
    -----
    Source: a choice of this toolkit (defaults 20 K below, 40 K above the table, set per
    oil file): the Vogel and Walther fits of the seed's table diverge by < 0.2 % inside
    it and by ≈ 2 % at 140 °C, so farther extrapolation is refused.
    """
    return (
        lubricant.temperature[0] - lubricant.extrapolation_below,
        lubricant.temperature[-1] + lubricant.extrapolation_above,
    )


def _temperature(lubricant: Lubricant, temperature: ArrayLike) -> NDArray[np.float64]:
    lo, hi = temperature_range(lubricant)
    try:
        return real_array("temperature", temperature, unit="degC", low=lo, high=hi)
    except InputError as exc:
        raise InputError(
            f"{exc} (lubricant {lubricant.name!r}: table {lubricant.temperature[0]:g}–"
            f"{lubricant.temperature[-1]:g} degC plus the extrapolation margins)"
        ) from None


def _vogel_eval(lubricant: Lubricant, t: NDArray[np.float64]) -> NDArray[np.float64]:
    v = lubricant.vogel
    return v.a * np.exp(v.b / (t - v.c))


def _walther_eval(lubricant: Lubricant, t: NDArray[np.float64]) -> NDArray[np.float64]:
    return lubricant.walther.kinematic_viscosity(t) * _density_eval(lubricant, t) * 1e-6


#: Viscosity–temperature models by name: ``(lubricant, T [degC]) -> η₀ [Pa s]``.
VISCOSITY_MODELS: Mapping[str, Callable[[Lubricant, NDArray[np.float64]], NDArray[np.float64]]] = (
    MappingProxyType({"vogel": _vogel_eval, "walther": _walther_eval})
)


def viscosity(
    lubricant: Lubricant, temperature: ArrayLike, method: str = "vogel"
) -> NDArray[np.float64] | float:
    """Dynamic viscosity η₀ at ambient pressure.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]
        Inside :func:`temperature_range`.
    method : {"vogel", "walther"}
        ``"vogel"``: η = a exp(b/(T − c)) (see :func:`fit_vogel`); ``"walther"``: ASTM D341
        on the kinematic viscosity ν = η/ρ, times the fitted density.

    Returns
    -------
    float or array — [Pa s]
        Same shape as ``temperature``.

    Raises
    ------
    InputError
        Temperature outside the accepted range (the message gives the range).
    ModelUnavailableError
        Unknown ``method`` (the message lists the available ones).

    Notes
    -----
    Source: seed Table 5.2 values; Vogel (1921); ASTM D341.
    """
    try:
        model = VISCOSITY_MODELS[method]
    except KeyError:
        raise ModelUnavailableError(
            f"unknown viscosity method {method!r}; available: {sorted(VISCOSITY_MODELS)}"
        ) from None
    return scalar_or_array(model(lubricant, _temperature(lubricant, temperature)))


def kinematic_viscosity(
    lubricant: Lubricant, temperature: ArrayLike, method: str = "vogel"
) -> NDArray[np.float64] | float:
    """Kinematic viscosity ν = η₀/ρ.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]
    method : {"vogel", "walther"}
        As :func:`viscosity`.

    Returns
    -------
    float or array — [mm²/s] (cSt)

    Raises
    ------
    InputError, ModelUnavailableError
        As :func:`viscosity`.

    Notes
    -----
    Source: definition; density from :func:`density`.
    """
    eta = np.asarray(viscosity(lubricant, temperature, method))
    t = real_array("temperature", temperature, unit="degC")
    return scalar_or_array(eta / _density_eval(lubricant, t) * 1e6)


def pressure_viscosity_coefficient(
    lubricant: Lubricant, temperature: ArrayLike
) -> NDArray[np.float64] | float:
    """Pressure–viscosity coefficient α, interpolated log-linearly in temperature.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]
        Inside :func:`temperature_range`; outside the table the end segments are
        extended.

    Returns
    -------
    float or array — [1/GPa]
        The pressure-viscosity coefficient α at the temperature(s).

    Raises
    ------
    InputError
        Temperature outside the accepted range.

    Notes
    -----
    Source: seed Table 5.2. ln α is close to linear in T for mineral oils (e.g. the
    75W90 table: ln α falls by 0.26, 0.20, 0.16 per 25 K); piecewise-linear ln α is
    the reconstruction used here.
    """
    t = _temperature(lubricant, temperature)
    ln_alpha = np.log(lubricant.pressure_viscosity_coefficient)
    return scalar_or_array(np.exp(_piecewise_linear(t, lubricant.temperature, ln_alpha)))


def _piecewise_linear(
    t: NDArray[np.float64], xs: Sequence[float], ys: ArrayLike
) -> NDArray[np.float64]:
    """Piecewise-linear interpolation with the end segments extended linearly."""
    x = np.asarray(xs, dtype=float)
    y = np.asarray(ys, dtype=float)
    out = np.interp(t, x, y)
    lo_slope = (y[1] - y[0]) / (x[1] - x[0])
    hi_slope = (y[-1] - y[-2]) / (x[-1] - x[-2])
    out = np.where(t < x[0], y[0] + lo_slope * (t - x[0]), out)
    return np.where(t > x[-1], y[-1] + hi_slope * (t - x[-1]), out)


def _density_eval(lubricant: Lubricant, t: NDArray[np.float64]) -> NDArray[np.float64]:
    slope, intercept = np.polyfit(lubricant.temperature, lubricant.density, 1)
    return intercept + slope * t


def density(lubricant: Lubricant, temperature: ArrayLike) -> NDArray[np.float64] | float:
    """Density from a straight line fitted to the table by least squares.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]

    Returns
    -------
    float or array — [kg/m3]

    Raises
    ------
    InputError
        Temperature outside the accepted range.

    Notes
    -----
    Source: seed Table 5.2 (whose densities fall exactly 0.6 kg/m3 per K).
    """
    return scalar_or_array(_density_eval(lubricant, _temperature(lubricant, temperature)))


def thermal_conductivity(
    lubricant: Lubricant, temperature: ArrayLike
) -> NDArray[np.float64] | float:
    """Thermal conductivity k: constant, or piecewise linear in T if tabulated.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]

    Returns
    -------
    float or array — [W/(m K)]

    Raises
    ------
    InputError
        Temperature outside the accepted range.

    Notes
    -----
    Source: the lubricant file (``thermal_conductivity_source``); for the bundled 75W90
    an assumed typical value, since the seed gives none.
    """
    t = _temperature(lubricant, temperature)
    k = lubricant.thermal_conductivity
    if len(k) == 1:
        return scalar_or_array(np.full_like(t, k[0], dtype=float))
    return scalar_or_array(_piecewise_linear(t, lubricant.temperature, k))


def temperature_viscosity_coefficient(
    lubricant: Lubricant, temperature: ArrayLike
) -> NDArray[np.float64] | float:
    """Temperature–viscosity coefficient β = −(1/η₀) dη₀/dT.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]

    Returns
    -------
    float or array — [1/K]
        From the tabulated values (piecewise linear) if the lubricant has them, else the
        derivative of the Vogel fit, β = b/(T − c)².

    Raises
    ------
    InputError
        Temperature outside the accepted range.

    Notes
    -----
    Source: definition used in the thermal loading factor L = β η₀ u²/k of Gupta et
    al. (1992) (see :func:`friction.film.thermal_loading`).
    """
    t = _temperature(lubricant, temperature)
    if lubricant.temperature_viscosity_coefficient is not None:
        return scalar_or_array(
            _piecewise_linear(t, lubricant.temperature, lubricant.temperature_viscosity_coefficient)
        )
    v = lubricant.vogel
    return scalar_or_array(v.b / (t - v.c) ** 2)


def boundary_friction_coefficient(
    lubricant: Lubricant, temperature: ArrayLike
) -> NDArray[np.float64] | float:
    """Boundary friction μ_b of the asperity junctions at an oil temperature.

    Parameters
    ----------
    lubricant : Lubricant
        An oil that gives ``boundary_friction`` (one number or a
        :class:`BoundaryFrictionTable`).
    temperature : float or array — [degC]
        The oil temperature at which μ_b is wanted, inside :func:`temperature_range`; the
        efficiency stage and the line-contact solvers pass the inlet (bulk) oil
        temperature of their operating condition.

    Returns
    -------
    float or array — [1]
        μ_b, the shape of ``temperature``: the constant where the oil gives one number;
        for a table, ``numpy.interp`` of its values (linear in temperature between the
        measured points, the end value held below the first and above the last).

    Raises
    ------
    InputError
        The oil gives no ``boundary_friction``, or a temperature outside the accepted
        range.

    Warns
    -----
    FrictionModelRangeWarning
        A temperature outside the table's measured range: μ_b is held at the end value
        there, an extrapolation (:func:`boundary_friction_in_range` says where).

    Notes
    -----
    Source: the oil file (a table's ``source``, a constant's ``traction_source``;
    :func:`boundary_friction_source`). Held, not extended, beyond the table: a boundary
    film's friction has no accepted temperature law to extend by.
    """
    mu_b = lubricant.boundary_friction
    if mu_b is None:
        raise InputError(f"boundary_friction: the lubricant {lubricant.name!r} gives none "
                         "(add boundary_friction to its oil file)")
    t = _temperature(lubricant, temperature)
    if not isinstance(mu_b, BoundaryFrictionTable):
        return scalar_or_array(np.full(t.shape, float(mu_b)))
    outside = ~np.asarray(boundary_friction_in_range(lubricant, t), bool)
    if np.any(outside):
        lo, hi = mu_b.temperature[0], mu_b.temperature[-1]
        first = float(t[outside].flat[0])
        warnings.warn(
            f"lubricant {lubricant.name!r}: boundary_friction measured at {lo:g}-{hi:g} degC"
            f" only; at {int(np.count_nonzero(outside))} of {t.size} temperature(s) outside"
            f" it (e.g. {first:g} degC) held at the end value ({mu_b.value[0]:g} below,"
            f" {mu_b.value[-1]:g} above); result extrapolated",
            FrictionModelRangeWarning,
            stacklevel=2,
        )
    return scalar_or_array(np.interp(t, mu_b.temperature, mu_b.value))


def boundary_friction_in_range(
    lubricant: Lubricant, temperature: ArrayLike
) -> NDArray[np.bool_]:
    """Where an oil's boundary friction is measured, not held at a table's end value.

    Parameters
    ----------
    lubricant : Lubricant
    temperature : float or array — [degC]

    Returns
    -------
    array of bool
        The shape of ``temperature``: True inside the table's measured range (ends
        included), everywhere for a constant μ_b or none.

    Notes
    -----
    Source: the oil file's ``[boundary_friction]`` table (:class:`BoundaryFrictionTable`).
    """
    t = np.asarray(real_array("temperature", temperature, unit="degC"), float)
    mu_b = lubricant.boundary_friction
    if not isinstance(mu_b, BoundaryFrictionTable):
        return np.ones(t.shape, dtype=bool)
    return (t >= mu_b.temperature[0]) & (t <= mu_b.temperature[-1])


def boundary_friction_source(lubricant: Lubricant) -> str:
    """Where an oil's boundary friction comes from, in one line for a dataset's attribute.

    Parameters
    ----------
    lubricant : Lubricant

    Returns
    -------
    str
        For a table: its points and its ``source``; for a constant: the value and the
        oil's ``traction_source`` (or that the oil file gives none); empty without μ_b.

    Notes
    -----
    Source: the oil file.
    """
    mu_b = lubricant.boundary_friction
    if mu_b is None:
        return ""
    if isinstance(mu_b, BoundaryFrictionTable):
        points = ", ".join(f"{v:g} at {t:g} degC" for t, v in zip(mu_b.temperature, mu_b.value,
                                                                  strict=True))
        return (f"oil {lubricant.name!r}: boundary_friction table [1] ({points}), linear in "
                f"temperature, end values held outside; source: {mu_b.source}")
    why = lubricant.traction_source.strip() or "the oil file gives no traction_source"
    return f"oil {lubricant.name!r}: boundary_friction {float(mu_b):g} [1], constant; source: {why}"


# ----------------------------------------------------------------------------- loading
#: The ``schema`` line of an oil file (``friction/data`` also holds other TOML files: the
#: fitted coefficients of ``kolivand2009``, which are no oil).
LUBRICANT_SCHEMA = "hypoid-ltca lubricant 1"


def _bundled() -> dict[str, Any]:
    """The bundled oil files by name (a new dict of the files found once per process)."""
    return dict(_bundled_files())


@memoised(maxsize=1)
def _bundled_files() -> tuple[tuple[str, Any], ...]:
    """(name, file) of the bundled oil files (package data: listed and read once)."""
    folder = resources.files("friction").joinpath("data")
    return tuple(
        (entry.name[: -len(".toml")], entry)
        for entry in folder.iterdir()
        if entry.name.endswith(".toml")
        and f'schema = "{LUBRICANT_SCHEMA}"' in entry.read_text(encoding="utf-8")
    )


def _library_names() -> tuple[str, ...]:
    from friction.oil_library import library_oil_names  # builds on this module

    return library_oil_names()


def available_lubricants() -> tuple[str, ...]:
    """Names of the lubricants bundled with the toolkit: the oil files of ``friction/data``
    (the seed's ``75W90``) and the oil library's grades (:mod:`friction.oil_library`:
    ``ISO_VG68_mineral`` … ``ISO_VG460_PAG``).

    Returns
    -------
    tuple of str
        The bundled files' names (file stems) sorted, then the library's in its order.

    Notes
    -----
    Source: each file's ``source`` field (75W90: seed Table 5.2); the library's in
    ``friction/data/oils/library.toml``.
    """
    return (*sorted(_bundled()), *_library_names())


def lubricant_from_mapping(data: Mapping[str, Any], origin: str = "<mapping>") -> Lubricant:
    """Build a :class:`Lubricant` from a parsed oil-file mapping, validating every field.

    Parameters
    ----------
    data : mapping
        Parsed TOML with the schema of ``friction/data/75W90.toml`` (see module docstring).
    origin : str
        Where the data came from, quoted in error messages.

    Returns
    -------
    Lubricant

    Raises
    ------
    InputError
        Naming the field: a missing or unknown key, a ``[units]`` entry that differs from
        the required unit, or any check of :class:`Lubricant`.

    Notes
    -----
    Source: the schema of this module (module docstring); the bundled 75W90 file holds
    seed Table 5.2.
    """
    unknown = sorted(set(data) - _KNOWN_KEYS)
    if unknown:
        raise InputError(f"{origin}: unknown field(s) {unknown}; known: {sorted(_KNOWN_KEYS)}")
    required = ("name", "source", *_REQUIRED_UNITS, "units")
    missing = [k for k in required if k not in data]
    if missing:
        raise InputError(f"{origin}: missing field(s) {missing}")
    units = data["units"]
    if not isinstance(units, Mapping):
        raise InputError(f"{origin}: units: must be a table of field = unit string, got "
                         f"{type(units).__name__}")
    expected = dict(_REQUIRED_UNITS)
    expected.update({k: v for k, v in _OPTIONAL_UNITS.items() if k in data})
    for key, unit in expected.items():
        if units.get(key) != unit:
            raise InputError(
                f"{origin}: units.{key}: must be {unit!r} (the unit this schema uses), got"
                f" {units.get(key)!r}"
            )
    extra = data.get("extrapolation", {})
    if not isinstance(extra, Mapping) or set(extra) - {"below", "above"}:
        raise InputError(f"{origin}: extrapolation: must be a table with keys below, above "
                         f"[K], got {extra!r}")
    kwargs: dict[str, Any] = {
        key: data[key]
        for key in (
            "name",
            "source",
            "temperature",
            "dynamic_viscosity",
            "pressure_viscosity_coefficient",
            "density",
            "thermal_conductivity",
        )
    }
    for key in ("temperature_viscosity_coefficient", "thermal_conductivity_source", "notes",
                "eyring_stress", "limiting_shear_coefficient", "boundary_friction",
                "traction_source", "fzg_load_stage", "base_oil", "permissible_specific_film",
                "durability_source"):
        if key in data:
            kwargs[key] = data[key]
    if "below" in extra:
        kwargs["extrapolation_below"] = extra["below"]
    if "above" in extra:
        kwargs["extrapolation_above"] = extra["above"]
    try:
        return Lubricant(**kwargs)
    except InputError as exc:
        raise InputError(f"{origin}: {exc}") from exc


@renamed_keywords(path_or_name="lubricant")
def load_lubricant(lubricant: str | Path | Lubricant) -> Lubricant:
    """Load a lubricant by bundled name (e.g. ``"75W90"``) or from a TOML file path.

    Parameters
    ----------
    lubricant : str, Path or Lubricant
        A bundled name (case-insensitive; see :func:`available_lubricants`: a bundled
        file's or an oil library grade's, :mod:`friction.oil_library`) or the path
        of a TOML file with the schema of the module docstring (the ``lubricant`` of
        :class:`friction.OperatingConditions`; old name ``path_or_name``, deprecated);
        an oil already read is returned as it is (:meth:`friction.OperatingConditions.oil`
        reads the conditions' oil once for an analysis' steps).

    Returns
    -------
    Lubricant
        The oil's properties (viscosity, pressure-viscosity and thermal data) and sources.

    Raises
    ------
    ModelUnavailableError
        Neither a bundled name nor an existing file (the message lists the bundled names).
    InputError
        The file is not UTF-8 text (e.g. a binary file), not valid TOML, or fails
        validation (a missing field, a NaN or non-positive property: the message names the
        file and the field).

    Notes
    -----
    Source: bundled files in ``friction/data`` (75W90: seed Table 5.2, thermal
    conductivity assumed — see the file's header).
    """
    if isinstance(lubricant, Lubricant):
        return lubricant
    bundled = {k.lower(): v for k, v in _bundled().items()}
    key = str(lubricant).lower()
    if isinstance(lubricant, str) and key in {n.lower() for n in _library_names()}:
        from friction.oil_library import library_oil_lubricant

        return library_oil_lubricant(lubricant)
    if isinstance(lubricant, str) and key in bundled:
        return _bundled_lubricant(key)
    else:
        path = Path(lubricant)
        if not path.is_file():
            raise ModelUnavailableError(
                f"no lubricant named or at {str(lubricant)!r}; bundled: {available_lubricants()}"
            )
        # one reader for input files: a binary, non-UTF-8 or invalid file is refused in
        # one line naming it (geometry.core.toml_files.read_toml)
        return lubricant_from_mapping(read_toml(path, "lubricant file"), str(path))


@memoised(maxsize=16)
def _bundled_lubricant(key: str) -> Lubricant:
    """A bundled oil (lower-case name ``key``) read and checked once per process: the oil is
    frozen (tuples), the file is package data, and an analysis reads its oil in several
    steps (the rating's ν40 and the conditions' oil: ≈ 3 ms each, issue 75)."""
    path = {k.lower(): v for k, v in _bundled().items()}[key]
    origin = f"bundled lubricant {key!r}"
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{origin}: not valid TOML: {exc}") from exc
    return lubricant_from_mapping(data, origin)
