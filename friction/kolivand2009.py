"""The ``kolivand2009`` friction model: the seed's Eq. 5.11 derived again on our solver.

The seed (§5.2.3) ran its mixed-EHL line-contact model over Table 5.1's conditions and
fitted "a friction coefficient formula" (Eq. 5.11a–c, Table 5.3 for 75W90) in three
regimes of the film parameter λ (< 1, 1–3, > 3) and the dimensionless groups λ, SR,
U = η₀u_e/(E′R), G = αE′, H = p_h/E′ and the roughness groups S_c/R, S_eq/R. Our copy of
Eq. 5.11 is garbled (docs/friction.md), so the same method is repeated with the
toolkit's solver (:mod:`friction.ehl`, study :mod:`friction.study`) and a regression of
the same family (:mod:`friction.study.fit`):

    r = Σ_j β_{k,j} f_j(λ, SR, U, G, H, S_eq/S_c, S_c/R),   k = regime of λ (< 1, 1–3, > 3)

with the features f_j of :data:`FEATURES` named in the coefficient file: a product of
power laws with λ-dependent exponents in each regime, as in the seed's exp(…)·Π(group^a)
form. Three structures (the file's ``structure_name``):

* ``regimes``: μ = exp(r), the seed's Eq. 5.11 form;
* ``split``: μ = exp(r) + μ_b ψ, the film shear plus the boundary friction μ_b on the
  asperities' load share ψ (logit ψ linear in features), the seed's Eq. 5.7–5.9 split;
* ``eyring`` (the bundled fit): μ = (1 − ψ) μ_E exp(r) + μ_b ψ, where μ_E is the smooth
  contact's Eyring film traction (:func:`friction.traction.smooth_film_traction`: Hertz
  pressure, the central film, the oil's τ₀ and Λ, the study's viscosity model). μ_E
  carries the traction curve's shape in SR, α p_h and temperature, which power laws
  cannot follow; the regression corrects it for roughness and the film's shape.

The three regimes are fitted jointly with continuity rows at λ = 1 and 3, so μ is
continuous there within the tolerance the file states.

λ is computed here exactly as the solver's: Pan–Hamrock's isothermal h_min over
σ = √(Rq₁² + Rq₂²) (:func:`friction.film.pan_hamrock`), not from the pipeline's thermal λ.
Outside its fitted box (the file's ``[range]``) the model is evaluated at the nearest
point of the box (so μ stays finite) and flagged (:func:`kolivand2009_validity`, the
efficiency stage's per-segment ``friction_model_extrapolated``).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from friction.ehl.rheology import VISCOSITY_PRESSURE_MODELS
from friction.film import pan_hamrock
from friction.traction import smooth_film_traction
from friction.validity import FrictionModelRangeWarning
from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.toml_files import read_toml
from geometry.core.validation import broadcast, real_array, scalar_or_array

__all__ = [
    "BOUNDARY_FEATURES",
    "DATA_DIR",
    "EYRING_BOUNDARY_FEATURES",
    "FEATURES",
    "KOLIVAND2009_SCHEMA",
    "RANGE_INPUTS",
    "STRUCTURES",
    "Kolivand2009Fit",
    "contact_groups",
    "groups_film_traction",
    "kolivand2009",
    "kolivand2009_validity",
    "load_kolivand2009_fit",
]

Array = NDArray[np.float64]

#: Where the bundled coefficient files are (``kolivand2009_<oil>.toml``).
DATA_DIR = Path(__file__).resolve().parent / "data"

#: Schema string of a coefficient file.
KOLIVAND2009_SCHEMA = "hypoid-ltca kolivand2009 fit 1"

#: E′ of steel on steel [MPa] (the solver's default, friction.ehl.line_contact).
_STEEL_E_PRIME = 206000.0 / (1.0 - 0.3**2)

#: The regression's features: name → function of the groups (dict of arrays).
FEATURES: Mapping[str, Callable[[Mapping[str, Array]], Array]] = MappingProxyType({
    "1": lambda g: np.ones_like(g["lambda"]),
    "ln_lambda": lambda g: np.log(g["lambda"]),
    "ln_lambda^2": lambda g: np.log(g["lambda"]) ** 2,
    "ln_lambda^3": lambda g: np.log(g["lambda"]) ** 3,
    "ln_SR": lambda g: np.log(g["SR"]),
    "ln_SR^2": lambda g: np.log(g["SR"]) ** 2,
    "ln_U": lambda g: np.log(g["U"]),
    "ln_G": lambda g: np.log(g["G"]),
    "ln_H": lambda g: np.log(g["H"]),
    "ln_Seq/Sc": lambda g: np.log(g["Seq/Sc"]),
    "ln_SR*ln_lambda": lambda g: np.log(g["SR"]) * np.log(g["lambda"]),
    "ln_H*ln_lambda": lambda g: np.log(g["H"]) * np.log(g["lambda"]),
    "ln_U*ln_SR": lambda g: np.log(g["U"]) * np.log(g["SR"]),
    "ln_Sc/R": lambda g: np.log(g["Sc/R"]),
    # α p_h = G·H, the Barus exponent at the Hertz pressure (ln η(p_h)/η₀), and its
    # product with ln SR: the traction curve's slope in SR falls as the film's viscosity
    # grows (Newtonian at low α p_h, Eyring-limited at high; Johnson & Tevaarwerk 1977)
    "G*H": lambda g: g["G"] * g["H"],
    "G*H*ln_SR": lambda g: g["G"] * g["H"] * np.log(g["SR"]),
    # the flash-temperature group: Blok's (Jaeger's) flash temperature of the film's heat
    # μ p̄ u_s over a band 2b moving at u_e is ∝ μ p_h abs(SR) √(2b u_e)/B (B the steel's
    # effusivity, fixed); F = p_h[GPa] abs(SR) √(2b[mm] u_e[m/s]) carries the viscosity's fall
    # with the surfaces' temperature that the solver's thermal film shear has and the
    # isothermal μ_E has not (held-out RMS 16.7 % → 9.0 % with it, issue 51)
    "ln_1+flash": lambda g: np.log1p(_flash_group(g)),
})


def _flash_group(g: Mapping[str, Array]) -> Array:
    """F = p_h abs(SR) √(2b u_e), p_h in GPa, b in mm, u_e in m/s (the groups' inputs)."""
    b = np.sqrt(8.0 * g["load_per_length"] * g["radius"] / (math.pi * g["e_prime"]))
    return g["hertz_pressure"] * 1e-3 * g["SR"] * np.sqrt(2.0 * b * g["entraining_velocity"])

#: Features of the asperity (boundary) share ψ of the ``split`` structure:
#: logit ψ = Σ θ_j f_j (a file without ``boundary.features`` has these).
BOUNDARY_FEATURES: tuple[str, ...] = ("1", "ln_lambda", "ln_H", "ln_U")

#: Default features of ψ in the ``eyring`` structure (the share's S-curve in ln λ needs
#: the square and cube; measured: 5-fold cross-validated RMS 20.6 % with them, 25.7 %
#: without, on the 75W90 study).
EYRING_BOUNDARY_FEATURES: tuple[str, ...] = ("1", "ln_lambda", "ln_lambda^2", "ln_lambda^3",
                                             "ln_H", "ln_U")

#: The model's structures: ``regimes`` (ln μ regressed directly, the seed's Eq. 5.11
#: form), ``split`` (μ = exp(regression) + μ_b ψ: film shear plus boundary friction on
#: the asperity share, the seed's Eq. 5.7–5.9 split) or ``eyring`` (μ = (1 − ψ) μ_E
#: exp(regression) + μ_b ψ: the split with the film part the smooth contact's Eyring
#: traction μ_E of :func:`friction.traction.smooth_film_traction` corrected by the
#: regression).
STRUCTURES = ("regimes", "split", "eyring")

#: Inputs whose fitted range a coefficient file states: name → units.
RANGE_INPUTS: Mapping[str, str] = MappingProxyType({
    "hertz_pressure": "MPa", "radius": "mm", "entraining_velocity": "m/s",
    "slide_to_roll": "1", "viscosity": "Pa s", "roughness": "um", "lambda": "1",
})


def contact_groups(*, hertz_pressure: ArrayLike, slide_to_roll: ArrayLike,
                   entraining_velocity: ArrayLike, viscosity: ArrayLike,
                   pressure_viscosity: ArrayLike, radius: ArrayLike, roughness_1: ArrayLike,
                   roughness_2: ArrayLike, e_prime: ArrayLike = _STEEL_E_PRIME,
                   ) -> dict[str, Array]:
    """The seed's dimensionless groups of a line contact (Eq. 5.11's variables).

    Parameters
    ----------
    hertz_pressure : array — [MPa]
        p_h > 0.
    slide_to_roll : array — [1]
        SR (sign ignored).
    entraining_velocity : array — [m/s]
        u_e > 0.
    viscosity : array — [Pa s]
        η₀ > 0 at the inlet temperature.
    pressure_viscosity : array — [1/GPa]
        α > 0.
    radius : array — [mm]
        R_eq > 0.
    roughness_1, roughness_2 : array — [µm]
        Rq of each surface, > 0.
    e_prime : array — [MPa]
        E′ = 2E* (default steel, 226.4 GPa).

    Returns
    -------
    dict of str to array (broadcast shape)
        ``lambda`` (Pan–Hamrock h_min/σ), ``SR`` (abs(SR)), ``U`` = η₀u_e/(E′R),
        ``G`` = αE′, ``H`` = p_h/E′, ``W`` = w′/(E′R) = 2πH², ``Sc/R`` = σ/R,
        ``Seq/R`` = Rq₁Rq₂/(Rq₁ + Rq₂)/R, ``Seq/Sc``; also ``load_per_length`` [N/mm]
        (w′ = 2πR p_h²/E′) and ``film_min`` [µm], and the inputs in their units
        (``hertz_pressure``, ``radius``, ``entraining_velocity``, ``viscosity``,
        ``pressure_viscosity``, ``e_prime``: the ``eyring`` structure's film traction).

    Raises
    ------
    InputError
        An input non-finite or out of range (named).

    Notes
    -----
    Source: seed §5.2.3 (the groups of Eq. 5.11: λ, SR, U, G, H = p_h/E_eq, S_c/R_eq with
    S_c = √(Rq₁² + Rq₂²), S_eq/R_eq with S_eq = Rq₁Rq₂/(Rq₁ + Rq₂)); Pan & Hamrock, J. Tribol.
    111 (1989) 246 for h_min; Hertz w′ = πb p_h/2, b = 4Rp_h/E′ (docs/ehl.md).
    """
    ph = real_array("hertz_pressure", hertz_pressure, low=0.0, low_open=True, unit="MPa")
    sr = np.abs(real_array("slide_to_roll", slide_to_roll, unit="1"))
    ue = real_array("entraining_velocity", entraining_velocity, low=0.0, low_open=True,
                    unit="m/s")
    eta = real_array("viscosity", viscosity, low=0.0, low_open=True, high=100.0, unit="Pa s")
    alpha = real_array("pressure_viscosity", pressure_viscosity, low=0.0, low_open=True,
                       high=100.0, unit="1/GPa")
    r = real_array("radius", radius, low=0.0, low_open=True, unit="mm")
    s1 = real_array("roughness_1", roughness_1, low=0.0, low_open=True, high=100.0, unit="µm")
    s2 = real_array("roughness_2", roughness_2, low=0.0, low_open=True, high=100.0, unit="µm")
    ep = real_array("e_prime", e_prime, low=1e3, high=1e7, unit="MPa")
    ph, sr, ue, eta, alpha, r, s1, s2, ep = broadcast(
        hertz_pressure=ph, slide_to_roll=sr, entraining_velocity=ue, viscosity=eta,
        pressure_viscosity=alpha, radius=r, roughness_1=s1, roughness_2=s2, e_prime=ep)
    ph, sr, ue, eta, alpha, r, s1, s2, ep = (np.asarray(v, float) for v in (
        ph, sr, ue, eta, alpha, r, s1, s2, ep))
    load = 2.0 * math.pi * r * ph**2 / ep
    hmin = np.asarray(pan_hamrock(ue, eta, alpha, load, r, ep), float)
    sc = np.hypot(s1, s2)
    seq = s1 * s2 / (s1 + s2)
    h = ph / ep
    return {
        "lambda": hmin / sc, "SR": sr, "U": eta * ue / (ep * 1e6 * r * 1e-3),
        "G": alpha * 1e-9 * ep * 1e6, "H": h, "W": 2.0 * math.pi * h**2,
        "Sc/R": sc * 1e-3 / r, "Seq/R": seq * 1e-3 / r, "Seq/Sc": seq / sc,
        "load_per_length": load, "film_min": hmin,
        "hertz_pressure": ph, "radius": r, "entraining_velocity": ue, "viscosity": eta,
        "pressure_viscosity": alpha, "e_prime": ep,
    }


def groups_film_traction(groups: Mapping[str, Array], *, eyring_stress: float,
                         limiting_shear_coefficient: float,
                         viscosity_model: str = "barus") -> Array:
    """μ_E of the ``eyring`` structure at a contact's groups.

    Parameters
    ----------
    groups : mapping of str to array
        :func:`contact_groups` (its inputs ``hertz_pressure`` [MPa], ``SR``,
        ``entraining_velocity`` [m/s], ``viscosity`` [Pa s], ``pressure_viscosity``
        [1/GPa], ``radius`` [mm], ``e_prime`` [MPa]).
    eyring_stress : float — [MPa]
    limiting_shear_coefficient : float — [1]
    viscosity_model : {"barus", "roelands"}

    Returns
    -------
    array — [1]
        :func:`friction.traction.smooth_film_traction` at those inputs, the groups' shape.

    Raises
    ------
    InputError
        As :func:`friction.traction.smooth_film_traction`.

    Notes
    -----
    Source: see :func:`friction.traction.smooth_film_traction`.
    """
    return np.asarray(smooth_film_traction(
        hertz_pressure=groups["hertz_pressure"], slide_to_roll=groups["SR"],
        entraining_velocity=groups["entraining_velocity"], viscosity=groups["viscosity"],
        pressure_viscosity=groups["pressure_viscosity"], radius=groups["radius"],
        e_prime=groups["e_prime"], eyring_stress=eyring_stress,
        limiting_shear_coefficient=limiting_shear_coefficient,
        viscosity_model=viscosity_model), float)


@dataclass(frozen=True)
class Kolivand2009Fit:
    """The coefficients of one oil's fitted model, with where and how well they fit.

    Attributes
    ----------
    lubricant : str
        The oil the study ran with.
    features : tuple of str
        Names of :data:`FEATURES`, in the order of each regime's coefficients.
    lambda_bounds : (float, float)
        λ where the regimes meet (the seed's 1 and 3).
    coefficients : tuple of 3 tuples of float
        β of the regimes λ < λ₁, λ₁ ≤ λ < λ₂, λ ≥ λ₂.
    ranges : mapping of str to (float, float)
        Fitted box of :data:`RANGE_INPUTS` (units there).
    statistics : mapping
        The fit's statistics (points, RMS and worst relative error on training and
        held-out points, continuity jumps at the regime bounds).
    provenance : mapping
        The study it was fitted to (file, commit, design, solver settings).
    structure : {"regimes", "split", "eyring"}
        ``regimes``: μ = exp(Σβf); ``split``: μ = exp(Σβf) + μ_b ψ; ``eyring``:
        μ = (1 − ψ) μ_E exp(Σβf) + μ_b ψ, μ_E the smooth film's Eyring traction
        (:func:`friction.traction.smooth_film_traction`); logit ψ = Σθ_j f_j over
        ``boundary_features``.
    boundary : tuple of float
        θ of ψ (empty for ``regimes``).
    boundary_friction : float — [1]
        μ_b (the study oil's boundary friction).
    boundary_features : tuple of str
        Features of ψ (default :data:`BOUNDARY_FEATURES`).
    eyring_stress : float — [MPa]
        τ₀ of μ_E (``eyring``: the study oil's, > 0).
    limiting_shear_coefficient : float — [1]
        Λ of μ_E (``eyring``: the study oil's, > 0).
    viscosity_model : {"barus", "roelands"}
        η(p) of μ_E (``eyring``: the study's).
    """

    lubricant: str
    features: tuple[str, ...]
    lambda_bounds: tuple[float, float]
    coefficients: tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]]
    ranges: Mapping[str, tuple[float, float]]
    statistics: Mapping[str, Any]
    provenance: Mapping[str, Any]
    structure: str = "regimes"
    boundary: tuple[float, ...] = ()
    boundary_friction: float = 0.0
    boundary_features: tuple[str, ...] = BOUNDARY_FEATURES
    eyring_stress: float = 0.0
    limiting_shear_coefficient: float = 0.0
    viscosity_model: str = "barus"

    def __post_init__(self) -> None:
        unknown = [f for f in self.features if f not in FEATURES]
        if unknown:
            raise InputError(f"features: unknown {unknown}; known {sorted(FEATURES)}")
        if len(self.coefficients) != 3 or any(len(c) != len(self.features)
                                               for c in self.coefficients):
            raise InputError(f"coefficients: must be 3 regimes of {len(self.features)} "
                             "values (one per feature)")
        if not all(math.isfinite(v) for c in self.coefficients for v in c):
            raise InputError("coefficients: must be finite")
        lo, hi = self.lambda_bounds
        if not 0.0 < lo < hi:
            raise InputError(f"lambda_bounds: must be 0 < λ1 < λ2, got {self.lambda_bounds}")
        missing = sorted(set(RANGE_INPUTS) - set(self.ranges))
        if missing:
            raise InputError(f"range: missing {missing}")
        for k, (a, b) in self.ranges.items():
            if not (math.isfinite(a) and math.isfinite(b) and a <= b):
                raise InputError(f"range.{k}: must be finite, low <= high, got ({a}, {b})")
        if self.structure not in STRUCTURES:
            raise InputError(f"structure: must be one of {STRUCTURES}, got {self.structure!r}")
        if self.structure != "regimes":
            unknown = [f for f in self.boundary_features if f not in FEATURES]
            if unknown:
                raise InputError(f"boundary.features: unknown {unknown}; known "
                                 f"{sorted(FEATURES)}")
            if len(self.boundary) != len(self.boundary_features) or not all(
                    math.isfinite(v) for v in self.boundary):
                raise InputError(f"boundary: must be {len(self.boundary_features)} finite "
                                 f"values (θ of {self.boundary_features})")
            if not 0.0 <= self.boundary_friction <= 1.0:
                raise InputError(f"boundary_friction: must be in [0, 1] [1], got "
                                 f"{self.boundary_friction}")
        if self.structure == "eyring":
            if not (math.isfinite(self.eyring_stress) and self.eyring_stress > 0.0):
                raise InputError(f"film.eyring_stress: must be finite and > 0 [MPa], got "
                                 f"{self.eyring_stress}")
            if not self.limiting_shear_coefficient > 0.0:
                raise InputError("film.limiting_shear_coefficient: must be > 0 [1], got "
                                 f"{self.limiting_shear_coefficient}")
            if self.viscosity_model not in VISCOSITY_PRESSURE_MODELS:
                raise InputError("film.viscosity_model: must be one of "
                                 f"{tuple(VISCOSITY_PRESSURE_MODELS)}, got "
                                 f"{self.viscosity_model!r}")

    def mu(self, groups: Mapping[str, Array],
           raw_groups: Mapping[str, Array] | None = None) -> Array:
        """μ of the fit at the groups (:func:`contact_groups`), no clipping.

        Parameters
        ----------
        groups : mapping of str to array
            At least ``lambda``, ``SR``, ``U``, ``G``, ``H``, ``Seq/Sc``, ``Sc/R``, and for
            ``eyring`` the inputs of :meth:`film_traction`.
        raw_groups : mapping of str to array, optional
            ``eyring``: where the asperity share ψ and μ_E are evaluated, if not at
            ``groups``. :func:`kolivand2009` passes the inputs as they are here and the
            inputs clipped to the fitted box as ``groups``: the regression, a polynomial
            in the logarithms that diverges outside its data, is held at the box's edge,
            while ψ (a logistic share, bounded in (0, 1); the bundled fit's logit falls
            monotonically with ln λ: its derivative, a quadratic in ln λ, has no real
            root) and μ_E (a physical law) follow the inputs.

        Returns
        -------
        array — [1]
            μ = exp(:meth:`log_mu`) (+ μ_b ψ for ``split``; (1 − ψ) μ_E exp(…) + μ_b ψ
            for ``eyring``), the shape of the groups.
        """
        mu = np.exp(self.log_mu(groups))
        if self.structure == "regimes":
            return mu
        at = groups if raw_groups is None or self.structure != "eyring" else raw_groups
        psi = self.asperity_share(at)
        if self.structure == "eyring":
            mu = (1.0 - psi) * self.film_traction(at) * mu
        return mu + self.boundary_friction * psi

    def film_traction(self, groups: Mapping[str, Array]) -> Array:
        """μ_E of the ``eyring`` structure at the groups [1] (1 for the others).

        Parameters
        ----------
        groups : mapping of str to array
            :func:`contact_groups` (its inputs ``hertz_pressure`` … ``e_prime``).

        Returns
        -------
        array — [1]
            :func:`friction.traction.smooth_film_traction` with the fit's τ₀, Λ and
            viscosity model.
        """
        if self.structure != "eyring":
            return np.ones_like(np.asarray(groups["lambda"], float))
        return groups_film_traction(groups, eyring_stress=self.eyring_stress,
                                    limiting_shear_coefficient=self.limiting_shear_coefficient,
                                    viscosity_model=self.viscosity_model)

    def asperity_share(self, groups: Mapping[str, Array]) -> Array:
        """ψ of the ``split`` and ``eyring`` structures (0 for ``regimes``) [1].

        Parameters
        ----------
        groups : mapping of str to array

        Returns
        -------
        array — [1]
            ψ = 1/(1 + exp(−Σθ_j f_j)) ∈ (0, 1).
        """
        if self.structure == "regimes":
            return np.zeros_like(np.asarray(groups["lambda"], float))
        x = np.stack([np.asarray(FEATURES[f](groups), float) for f in self.boundary_features],
                     -1)
        return 1.0 / (1.0 + np.exp(-(x @ np.asarray(self.boundary, float))))

    def log_mu(self, groups: Mapping[str, Array]) -> Array:
        """ln of the regression part at the groups (:func:`contact_groups`), no clipping:
        ln μ for ``regimes``, ln of the film part for ``split``, ln of the film part's
        correction to μ_E for ``eyring``.

        Parameters
        ----------
        groups : mapping of str to array
            At least ``lambda``, ``SR``, ``U``, ``G``, ``H``, ``Seq/Sc``.

        Returns
        -------
        array — [1]
            The regression Σβf of the groups' regime, the shape of the groups.
        """
        x = np.stack([np.asarray(FEATURES[f](groups), float) for f in self.features], -1)
        lam = np.asarray(groups["lambda"], float)
        regime = np.digitize(lam, self.lambda_bounds)  # 0: < λ1, 1: [λ1, λ2), 2: ≥ λ2
        beta = np.asarray(self.coefficients, float)[regime]
        return np.sum(x * beta, axis=-1)


def _fit_from_document(doc: Mapping[str, Any], where: str) -> Kolivand2009Fit:
    if doc.get("schema") != KOLIVAND2009_SCHEMA:
        raise InputError(f"{where}: schema must be {KOLIVAND2009_SCHEMA!r}, got "
                         f"{doc.get('schema')!r}")
    try:
        regimes = doc["regime"]
        return Kolivand2009Fit(
            lubricant=str(doc["lubricant"]),
            features=tuple(doc["features"]),
            lambda_bounds=(float(doc["lambda_bounds"][0]), float(doc["lambda_bounds"][1])),
            coefficients=tuple(tuple(float(v) for v in regimes[k]["coefficients"])
                               for k in ("boundary_mixed", "mixed", "full_film")),  # type: ignore[arg-type]
            ranges={k: (float(v[0]), float(v[1])) for k, v in doc["range"].items()},
            statistics=dict(doc.get("statistics", {})),
            provenance=dict(doc.get("provenance", {})),
            structure=str(doc.get("structure_name", "regimes")),
            boundary=tuple(float(v) for v in doc.get("boundary", {}).get("coefficients", ())),
            boundary_friction=float(doc.get("boundary", {}).get("boundary_friction", 0.0)),
            boundary_features=tuple(doc.get("boundary", {}).get("features",
                                                                BOUNDARY_FEATURES)),
            eyring_stress=float(doc.get("film", {}).get("eyring_stress", 0.0)),
            limiting_shear_coefficient=float(doc.get("film", {}).get(
                "limiting_shear_coefficient", 0.0)),
            viscosity_model=str(doc.get("film", {}).get("viscosity_model", "barus")),
        )
    except (KeyError, IndexError, TypeError, ValueError) as exc:
        raise InputError(f"{where}: missing or malformed field ({exc!r})") from None


@memoised(maxsize=None)
def _bundled(name: str) -> Kolivand2009Fit:
    path = DATA_DIR / f"kolivand2009_{name}.toml"
    if not path.is_file():
        known = sorted(p.stem.removeprefix("kolivand2009_")
                       for p in DATA_DIR.glob("kolivand2009_*.toml"))
        raise InputError(f"coefficients: no bundled kolivand2009 fit for {name!r}; bundled: "
                         f"{known} (or pass a coefficient file path)")
    return _fit_from_document(read_toml(path, "kolivand2009 coefficient file"), str(path))


def load_kolivand2009_fit(coefficients: str | Path | Kolivand2009Fit = "75W90"
                          ) -> Kolivand2009Fit:
    """A fitted ``kolivand2009`` model: a bundled oil's, a coefficient file, or as given.

    Parameters
    ----------
    coefficients : str, path or Kolivand2009Fit
        An oil name with a bundled file ``friction/data/kolivand2009_<oil>.toml``, the path
        of a file written by :func:`friction.study.fit.write_fit` (ending ``.toml``), or a
        fit.

    Returns
    -------
    Kolivand2009Fit
        The fitted coefficients of the friction-coefficient regression and their range.

    Raises
    ------
    InputError
        No such bundled oil or file, or a malformed file (the message names the field).

    Notes
    -----
    Source: the seed's method (§5.2.3: its mixed-EHL line-contact model run over Table 5.1's
    conditions, then a regression of the form of Eq. 5.11a–c) repeated with the toolkit's
    solver, the fit of :mod:`friction.study.fit` (docs/friction.md, "kolivand2009").
    """
    if isinstance(coefficients, Kolivand2009Fit):
        return coefficients
    text = str(coefficients)
    if text.endswith(".toml") or isinstance(coefficients, Path):
        return _fit_from_document(read_toml(text, "kolivand2009 coefficient file"), text)
    return _bundled(text)


def _clip_to_range(fit: Kolivand2009Fit, inputs: dict[str, Array]) -> dict[str, Array]:
    out = dict(inputs)
    for name in ("hertz_pressure", "radius", "entraining_velocity", "viscosity"):
        lo, hi = fit.ranges[name]
        out[name] = np.clip(inputs[name], lo, hi)
    lo, hi = fit.ranges["slide_to_roll"]
    out["slide_to_roll"] = np.clip(np.abs(inputs["slide_to_roll"]), lo, hi)
    lo, hi = fit.ranges["roughness"]
    out["roughness_1"] = np.clip(inputs["roughness_1"], lo, hi)
    out["roughness_2"] = np.clip(inputs["roughness_2"], lo, hi)
    return out


def _outside(fit: Kolivand2009Fit, inputs: Mapping[str, Array], lam: Array
             ) -> dict[str, NDArray[np.bool_]]:
    def out(name: str, v: Array) -> NDArray[np.bool_]:
        lo, hi = fit.ranges[name]
        return np.asarray((v < lo) | (v > hi))

    return {
        "hertz_pressure": out("hertz_pressure", inputs["hertz_pressure"]),
        "radius": out("radius", inputs["radius"]),
        "entraining_velocity": out("entraining_velocity", inputs["entraining_velocity"]),
        "slide_to_roll": out("slide_to_roll", np.abs(inputs["slide_to_roll"])),
        "viscosity": out("viscosity", inputs["viscosity"]),
        "roughness": out("roughness", inputs["roughness_1"]) | out("roughness",
                                                                   inputs["roughness_2"]),
        "lambda": out("lambda", lam),
    }


def kolivand2009(
    *,
    hertz_pressure: ArrayLike,
    slide_to_roll: ArrayLike,
    entraining_velocity: ArrayLike,
    viscosity: ArrayLike,
    pressure_viscosity: ArrayLike,
    radius: ArrayLike,
    roughness_1: ArrayLike,
    roughness_2: ArrayLike,
    e_prime: ArrayLike = _STEEL_E_PRIME,
    coefficients: str | Path | Kolivand2009Fit = "75W90",
) -> NDArray[np.float64] | float:
    """Friction coefficient of the seed's Eq. 5.11 form, fitted to the toolkit's solver.

    Parameters
    ----------
    hertz_pressure : float or array — [MPa]
        p_h > 0.
    slide_to_roll : float or array — [1]
        SR; abs(SR) is used.
    entraining_velocity : float or array — [m/s]
        u_e = (u₁ + u₂)/2 > 0.
    viscosity : float or array — [Pa s]
        η₀ at the inlet temperature, > 0.
    pressure_viscosity : float or array — [1/GPa]
        α at the inlet temperature, > 0.
    radius : float or array — [mm]
        R_eq > 0.
    roughness_1, roughness_2 : float or array — [µm]
        Rq of each surface, > 0.
    e_prime : float or array — [MPa]
        E′ = 2E* (default steel).
    coefficients : str, path or Kolivand2009Fit
        The fit (:func:`load_kolivand2009_fit`); default the bundled 75W90 one.

    Returns
    -------
    float or array — [1]
        μ, broadcast shape of the inputs.

    Raises
    ------
    InputError
        An input out of its accepted range, or a bad coefficient file (named).

    Warns
    -----
    FrictionModelRangeWarning
        Inputs outside the fitted box (the file's ``[range]``, including λ): the fitted
        parts are then taken at the nearest point of the box — all of μ for ``regimes``
        and ``split``; for ``eyring`` the regression only, while μ_E and the asperity
        share ψ take the inputs as they are (μ_E's physics — Hertz pressure, the central
        film, the Eyring law capped at Λp — holds beyond the study's box: at pure rolling
        the film's shear vanishes, at edge pressures it is held at the limiting shear; ψ
        is a logistic share in (0, 1) that keeps rising as λ falls). Checked against the
        solver outside the box: ``friction_study_75W90_outside.nc`` (p_h to 4.5 GPa, SR
        to 0.001, u_e to 0.1 m/s), ``…_flank.nc`` (a gear flank's light-load ends and
        pitch line) and ``…_edge.nc`` (a rounded tooth edge on a flank; docs/friction.md).

    Notes
    -----
    Source: the structure of seed Eq. 5.11a–c (three λ regimes, power laws of λ, SR, U, G,
    H and the roughness groups; Kolivand 2009, §5.2.3), coefficients fitted to
    :mod:`friction.ehl` over Table 5.1's box by :func:`friction.study.fit.fit_kolivand2009`
    (the file's ``[statistics]`` and ``[provenance]``; docs/friction.md). Not the seed's
    Table 5.3 values (garbled in our copy).
    """
    fit = load_kolivand2009_fit(coefficients)
    raw = contact_groups(hertz_pressure=hertz_pressure, slide_to_roll=slide_to_roll,
                         entraining_velocity=entraining_velocity, viscosity=viscosity,
                         pressure_viscosity=pressure_viscosity, radius=radius,
                         roughness_1=roughness_1, roughness_2=roughness_2, e_prime=e_prime)
    inputs = {k: np.asarray(v, float) for k, v in dict(
        hertz_pressure=hertz_pressure, slide_to_roll=slide_to_roll,
        entraining_velocity=entraining_velocity, viscosity=viscosity, radius=radius,
        roughness_1=roughness_1, roughness_2=roughness_2).items()}
    shape = raw["lambda"].shape
    inputs = {k: np.broadcast_to(v, shape) for k, v in inputs.items()}
    for name, bad in _outside(fit, inputs, raw["lambda"]).items():
        n = int(np.count_nonzero(bad))
        if n:
            lo, hi = fit.ranges[name]
            warnings.warn(
                f"kolivand2009: {name} outside the fitted range [{lo:g}, {hi:g}] "
                f"[{RANGE_INPUTS[name]}] at {n} of {bad.size} point(s); "
                + ("the regression taken at the nearest point of the range, the asperity "
                   "share and the film traction at the inputs" if fit.structure == "eyring"
                   else "μ taken at the nearest point of the range"),
                FrictionModelRangeWarning, stacklevel=3)
    clipped = _clip_to_range(fit, inputs)
    groups = contact_groups(
        hertz_pressure=clipped["hertz_pressure"], slide_to_roll=clipped["slide_to_roll"],
        entraining_velocity=clipped["entraining_velocity"], viscosity=clipped["viscosity"],
        pressure_viscosity=pressure_viscosity, radius=clipped["radius"],
        roughness_1=clipped["roughness_1"], roughness_2=clipped["roughness_2"],
        e_prime=e_prime)
    lo, hi = fit.ranges["lambda"]
    groups["lambda"] = np.clip(groups["lambda"], lo, hi)
    return scalar_or_array(fit.mu(groups, raw_groups=raw))


def kolivand2009_validity(*, hertz_pressure: ArrayLike, slide_to_roll: ArrayLike,
                          entraining_velocity: ArrayLike, viscosity: ArrayLike,
                          pressure_viscosity: ArrayLike, radius: ArrayLike,
                          roughness_1: ArrayLike, roughness_2: ArrayLike,
                          e_prime: ArrayLike = _STEEL_E_PRIME,
                          coefficients: str | Path | Kolivand2009Fit = "75W90",
                          **_: Any) -> NDArray[np.bool_]:
    """True where every input (and λ) lies inside the fit's box (the file's ``[range]``).

    Parameters
    ----------
    As :func:`kolivand2009` (other standard inputs are ignored).

    Returns
    -------
    array of bool
        Broadcast shape of the inputs.

    Raises
    ------
    InputError
        An input out of its accepted range (named).
    """
    fit = load_kolivand2009_fit(coefficients)
    raw = contact_groups(hertz_pressure=hertz_pressure, slide_to_roll=slide_to_roll,
                         entraining_velocity=entraining_velocity, viscosity=viscosity,
                         pressure_viscosity=pressure_viscosity, radius=radius,
                         roughness_1=roughness_1, roughness_2=roughness_2, e_prime=e_prime)
    shape = raw["lambda"].shape
    inputs = {k: np.broadcast_to(np.asarray(v, float), shape) for k, v in dict(
        hertz_pressure=hertz_pressure, slide_to_roll=slide_to_roll,
        entraining_velocity=entraining_velocity, viscosity=viscosity, radius=radius,
        roughness_1=roughness_1, roughness_2=roughness_2).items()}
    bad = np.zeros(shape, bool)
    for v in _outside(fit, inputs, raw["lambda"]).values():
        bad |= v
    return ~bad
