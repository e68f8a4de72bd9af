"""The regression of the ``kolivand2009`` friction model to a friction study's results.

:func:`fit_kolivand2009` fits ln μ of the converged points of a study
(:mod:`friction.study`, ``ltca friction-study``) by linear least squares in the features
of :data:`friction.kolivand2009.FEATURES`, one coefficient set per λ regime (λ < 1,
1 ≤ λ < 3, λ ≥ 3, the seed's Eq. 5.11a–c), all three solved together with

* **continuity rows**: at every training point's groups moved to λ = 1 (and 3) the two
  neighbouring regimes' ln μ are asked to agree (weight ``continuity_weight``), so μ is
  continuous there to the tolerance the statistics state;
* **a ridge** on the standardised features (``ridge``), which keeps a regime with few
  converged points (today the rough mixed regime, where the solver often fails) tied to
  its neighbours instead of fitting noise.

Any oil: run the study with that oil (``ltca friction-study --lubricant FILE``), then
``ltca friction-fit STUDY.nc --held-out HELD.nc -o kolivand2009_OIL.toml`` (or this
module's functions) and pass the file as the model's ``coefficients``.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from friction.kolivand2009 import (
    BOUNDARY_FEATURES,
    EYRING_BOUNDARY_FEATURES,
    FEATURES,
    KOLIVAND2009_SCHEMA,
    STRUCTURES,
    Kolivand2009Fit,
    contact_groups,
    groups_film_traction,
    kolivand2009,
)
from friction.lubricant import (
    BoundaryFrictionTable,
    load_lubricant,
    pressure_viscosity_coefficient,
    viscosity,
)
from friction.study.design import TABLE_5_1_RANGE
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.toml_files import dump_toml

__all__ = ["DEFAULT_FEATURES", "EYRING_FEATURES", "RESOLVED_MODEL_SETTINGS", "SAMPLING_SETTINGS",
           "combine_studies", "fit_kolivand2009", "fit_statistics", "study_inputs", "write_fit"]

Array = NDArray[np.float64]

#: The default features of every regime (the seed's groups as power laws, with λ- and
#: SR-dependent exponents).
DEFAULT_FEATURES: tuple[str, ...] = ("1", "ln_lambda", "ln_lambda^2", "ln_SR", "ln_SR^2",
                                     "ln_U", "ln_G", "ln_H", "ln_Seq/Sc", "ln_SR*ln_lambda",
                                     "G*H", "G*H*ln_SR")

#: The default features of the ``eyring`` structure's correction to the smooth film's
#: traction (which carries the SR, pressure and temperature shape itself): λ to the third
#: power, the seed's groups, α p_h, and the flash-temperature group ln(1 + F) (issue 51:
#: the solver's film shear is thermal, μ_E isothermal; with it the held-out RMS of the
#: 75W90 study fell from 16.7 % to 9.0 %, a quadratic in F or its product with α p_h
#: moved it by < 0.2 %).
EYRING_FEATURES: tuple[str, ...] = ("1", "ln_lambda", "ln_lambda^2", "ln_lambda^3", "ln_SR",
                                    "ln_U", "ln_G", "ln_H", "ln_Seq/Sc", "ln_Sc/R", "G*H",
                                    "ln_1+flash")

_REGIMES = ("boundary_mixed", "mixed", "full_film")


#: Solver settings of a study that set how a point is sampled, not what is solved: studies
#: that differ only in these combine (:func:`combine_studies`).
SAMPLING_SETTINGS = ("solver_realisations",)

#: Settings that studies written before issue 61 carry and later ones do not: read only by
#: the resolved models (the steady grid's and the transient time stepping's), which left
#: the study (docs/ehl.md), never by the stochastic solver. A stored study and a new one
#: that differ in these alone combine; the first study's values are kept.
RESOLVED_MODEL_SETTINGS = ("solver_inlet", "solver_outlet", "solver_step_limit",
                           "solver_roughness_steps", "solver_courant", "solver_ramp",
                           "solver_flush", "solver_average", "solver_cavitation")


def _plain(value: object) -> str:
    """An attribute as a user reads it: ``np.int64(256)`` → ``256``, text quoted."""
    if isinstance(value, np.generic):
        value = value.item()
    return repr(value) if isinstance(value, str) else str(value)


def combine_studies(studies: Sequence[xr.Dataset]) -> xr.Dataset:
    """Several friction studies of one oil and solver settings as one (e.g. a Sobol design
    and its continuation).

    Parameters
    ----------
    studies : sequence of xarray.Dataset
        Friction studies (``ltca friction-study``) with equal ``solver_*`` attributes but
        the :data:`SAMPLING_SETTINGS` (how many roughness realisations: the same model
        sampled more often), which may differ and are then joined (``"; "``), and the
        :data:`RESOLVED_MODEL_SETTINGS` that only studies written before issue 61 carry.

    Returns
    -------
    xarray.Dataset
        Their points in order, renumbered 0 … n−1; the first study's attributes, with
        ``design_*`` and ``wall_time`` of every study joined (``"; "``) and summed.

    Raises
    ------
    InputError
        No studies, or studies of different solver settings or oils (the attribute named).
    """
    if not studies:
        raise InputError("studies: at least one friction study is needed")
    first = studies[0]
    for k, v in first.attrs.items():
        if k.startswith("solver_") and k not in ("solver_commit", *SAMPLING_SETTINGS,
                                                  *RESOLVED_MODEL_SETTINGS):
            for other in studies[1:]:
                if other.attrs.get(k) != v:
                    raise InputError(
                        f"studies: {k} differs ({_plain(v)} in the first, "
                        f"{_plain(other.attrs.get(k))} in another); only studies of one oil "
                        "and one solver setting combine")
    if len(studies) == 1:
        return first
    ds = xr.concat(list(studies), dim="point", combine_attrs="override")
    ds = ds.assign_coords(point=("point", np.arange(ds.sizes["point"]), ds["point"].attrs))
    attrs = dict(first.attrs)
    for k in {k for st in studies for k in st.attrs if k.startswith("design_")}:
        attrs[k] = "; ".join(str(st.attrs.get(k, "")) for st in studies)
    attrs["solver_commit"] = "; ".join(sorted({str(st.attrs.get("solver_commit", ""))
                                               for st in studies}))
    for k in SAMPLING_SETTINGS:
        values = [str(st.attrs.get(k, "")) for st in studies]
        if len(set(values)) > 1:
            attrs[k] = "; ".join(values)
    attrs["wall_time"] = float(sum(float(st.attrs.get("wall_time", 0.0)) for st in studies))
    attrs["points_converged"] = int(np.count_nonzero(ds["status"].values == 0))
    ds.attrs = attrs
    return ds


def study_inputs(study: xr.Dataset, *, converged: bool = True) -> dict[str, Array]:
    """The model inputs and the solver's μ of a study's points.

    Parameters
    ----------
    study : xarray.Dataset
        A friction study (:func:`contact.study.friction_study.run_friction_study`).
    converged : bool
        Only the converged points with μ > 0 (default), else all.

    Returns
    -------
    dict of str to array (n,)
        ``hertz_pressure`` [MPa], ``slide_to_roll`` [1], ``entraining_velocity`` [m/s],
        ``viscosity`` [Pa s], ``pressure_viscosity`` [1/GPa] (the study oil's at each
        temperature), ``radius`` [mm], ``roughness_1``, ``roughness_2`` [µm], and
        ``friction_coefficient`` [1], ``lambda_ratio`` [1] (the solver's), ``status``.

    Raises
    ------
    InputError
        Not a friction study (a missing variable is named), or an unknown oil.
    """
    need = ("hertz_pressure", "radius", "entraining_velocity", "slide_to_roll", "temperature",
            "roughness_1", "roughness_2", "friction_coefficient", "status", "lambda_ratio",
            "asperity_load_ratio")
    missing = [k for k in need if k not in study.variables]
    if missing:
        raise InputError(f"study: not a friction study (no {missing})")
    oil = load_lubricant(str(study.attrs.get("solver_lubricant", "75W90")))
    mu = study["friction_coefficient"].values.astype(float)
    keep = np.ones(mu.shape, bool)
    if converged:
        keep = (study["status"].values == 0) & np.isfinite(mu) & (mu > 0.0)
    t = study["temperature"].values[keep].astype(float)
    out = {k: study[k].values[keep].astype(float) for k in need if k not in ("temperature",)}
    out["viscosity"] = np.asarray(viscosity(oil, t), float)
    out["pressure_viscosity"] = np.asarray(pressure_viscosity_coefficient(oil, t), float)
    out["temperature"] = t
    return out


def _model_inputs(d: Mapping[str, Array]) -> dict[str, Array]:
    keys = ("hertz_pressure", "slide_to_roll", "entraining_velocity", "viscosity",
            "pressure_viscosity", "radius", "roughness_1", "roughness_2")
    return {k: d[k] for k in keys}


def _features(features: Sequence[str], groups: Mapping[str, Array]) -> Array:
    return np.stack([np.asarray(FEATURES[f](groups), float) for f in features], -1)


def fit_statistics(fit: Kolivand2009Fit, study: xr.Dataset) -> dict[str, float]:
    """How well a fit reproduces a study's converged points.

    Parameters
    ----------
    fit : Kolivand2009Fit
    study : xarray.Dataset
        A friction study (training or held-out).

    Returns
    -------
    dict
        ``points`` (converged points used), ``failed`` (points the solver did not
        converge on), ``rms_relative_error``, ``max_relative_error`` (|μ_fit/μ − 1|),
        ``rms_log_error`` [1], and ``inside`` (points inside the fit's box; the errors are
        over these).

    Raises
    ------
    InputError
        As :func:`study_inputs`.
    """
    import warnings

    from friction.kolivand2009 import kolivand2009_validity
    from friction.validity import FrictionModelRangeWarning

    d = study_inputs(study)
    n_failed = int(np.count_nonzero(study["status"].values != 0))
    inside = np.asarray(kolivand2009_validity(**_model_inputs(d), coefficients=fit), bool)
    if not np.any(inside):
        return {"points": 0, "failed": n_failed, "inside": 0, "rms_relative_error": math.nan,
                "max_relative_error": math.nan, "rms_log_error": math.nan}
    sel = {k: v[inside] for k, v in _model_inputs(d).items()}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        mu_fit = np.atleast_1d(np.asarray(kolivand2009(**sel, coefficients=fit), float))
    mu = d["friction_coefficient"][inside]
    rel = mu_fit / mu - 1.0
    return {"points": int(mu.size), "failed": n_failed, "inside": int(inside.sum()),
            "rms_relative_error": float(np.sqrt(np.mean(rel**2))),
            "max_relative_error": float(np.max(np.abs(rel))),
            "rms_log_error": float(np.sqrt(np.mean(np.log(mu_fit / mu) ** 2)))}


def _continuity_jump(fit: Kolivand2009Fit, groups: Mapping[str, Array], at: float) -> float:
    """max |μ(λ⁺)/μ(λ⁻) − 1| at λ = ``at`` over the groups' other values."""
    lo, hi = dict(groups), dict(groups)
    lo["lambda"] = np.full_like(groups["lambda"], np.nextafter(at, 0.0))
    hi["lambda"] = np.full_like(groups["lambda"], at)
    return float(np.max(np.abs(fit.mu(hi) / fit.mu(lo) - 1.0)))


def fit_kolivand2009(
    study: xr.Dataset,
    *,
    heldout: xr.Dataset | None = None,
    features: Sequence[str] | None = None,
    lambda_bounds: tuple[float, float] = (1.0, 3.0),
    continuity_weight: float = 10.0,
    ridge: float = 1e-3,
    structure: str = "eyring",
    boundary_features: Sequence[str] | None = None,
    box: Mapping[str, tuple[float, float, bool]] | None = TABLE_5_1_RANGE,
    provenance: Mapping[str, Any] | None = None,
) -> Kolivand2009Fit:
    """Fit the ``kolivand2009`` model to a friction study's converged points.

    Parameters
    ----------
    study : xarray.Dataset
        The training study (:func:`contact.study.friction_study.run_friction_study`).
    heldout : xarray.Dataset, optional
        Points not used in the fit; their statistics go into the fit's ``statistics``.
    features : sequence of str, optional
        Names of :data:`friction.kolivand2009.FEATURES`; ``"1"`` (the intercept) required.
        Default :data:`EYRING_FEATURES` for ``eyring``, :data:`DEFAULT_FEATURES` else.
    lambda_bounds : (float, float)
        Regime bounds of λ (the seed's 1 and 3).
    continuity_weight : float
        Weight of the continuity rows relative to a data row, > 0.
    ridge : float
        Ridge parameter on the standardised features (intercepts not penalised), ≥ 0.
    structure : {"eyring", "split", "regimes"}
        ``regimes``: ln μ linear in the features (seed Eq. 5.11's form), solved by linear
        least squares; ``split``: μ = exp(Σβf) + μ_b ψ, logit ψ linear in the
        boundary features, μ_b the study oil's boundary friction (the solver's), fitted to
        ln μ by ``scipy.optimize.least_squares`` started from linear fits (β to ln μ, θ
        to the solver's asperity load ratio); ``eyring`` (default): μ = (1 − ψ) μ_E
        exp(Σβf) + μ_b ψ, μ_E the smooth film's Eyring traction with the study oil's τ₀
        and Λ and the study's viscosity model
        (:func:`friction.traction.smooth_film_traction`), fitted likewise (β started
        from ln of the solver's film part over (1 − ψ) μ_E).
    boundary_features : sequence of str, optional
        Features of logit ψ (default
        :data:`~friction.kolivand2009.EYRING_BOUNDARY_FEATURES` for ``eyring``,
        :data:`~friction.kolivand2009.BOUNDARY_FEATURES` for ``split``).
    box : mapping or None
        The design's box (:data:`friction.study.design.TABLE_5_1_RANGE`, the default):
        the fitted range of p_h, R, u_e, SR and Rq, and of η₀ (the oil's at the box's
        temperatures); None: the extremes of the study's points. λ's range is always that
        of the converged points.
    provenance : mapping, optional
        Stored with the fit (default the study's provenance attributes).

    Returns
    -------
    Kolivand2009Fit
        Coefficients, the fitted box (the design's inputs; λ of the converged points),
        statistics (``training_*``, ``heldout_*``, ``continuity_jump_lambda_1/3``
        = max |μ(λ⁺)/μ(λ⁻) − 1| over the training points' groups, ``points_per_regime``).

    Raises
    ------
    InputError
        Bad features or parameters (named), or fewer converged points than features, or
        a 'split'/'eyring' structure on an oil whose ``boundary_friction`` is a table
        against temperature (the fit holds one μ_b; named ``boundary_friction``).

    Notes
    -----
    Source: the seed's method (§5.2.3: a regression to the μ of every Table 5.1 condition,
    Eq. 5.11's three λ regimes); linear least squares (``numpy.linalg.lstsq``) on ln μ
    with equality-penalty rows (continuity) and Tikhonov regularisation.
    """
    features, boundary_features = _resolve_features(structure, features, boundary_features)
    if not continuity_weight > 0 or not math.isfinite(continuity_weight):
        raise InputError(f"continuity_weight: must be > 0, got {continuity_weight}")
    if not ridge >= 0 or not math.isfinite(ridge):
        raise InputError(f"ridge: must be >= 0, got {ridge}")
    lo_b, hi_b = (float(v) for v in lambda_bounds)
    if not 0.0 < lo_b < hi_b:
        raise InputError(f"lambda_bounds: must be 0 < λ1 < λ2, got {lambda_bounds}")
    oil = load_lubricant(str(study.attrs.get("solver_lubricant", "75W90")))
    if isinstance(oil.boundary_friction, BoundaryFrictionTable) and structure != "regimes":
        raise InputError(
            f"boundary_friction: the lubricant {oil.name!r} gives a table against temperature,"
            f" but the {structure!r} structure holds one mu_b and kolivand2009 takes no"
            " temperature; give the oil one boundary_friction for the fit, or fit"
            " structure='regimes'")
    d = study_inputs(study)
    n = d["friction_coefficient"].size
    nf = len(features)
    if n < 2 * nf:
        raise InputError(f"study: {n} converged points, the fit needs at least {2 * nf}")
    groups = contact_groups(**_model_inputs(d))
    x = _features(features, groups)
    y = np.log(d["friction_coefficient"])
    mu_b = float(oil.boundary_friction or 0.0) if structure != "regimes" else 0.0
    film: dict[str, Any] = {}
    y_start, mu_e = y, None
    if structure == "eyring":
        missing = [k for k in ("eyring_stress", "limiting_shear_coefficient")
                   if getattr(oil, k) is None]
        if missing:
            raise InputError(f"lubricant: {oil.name} has no {missing}, which the 'eyring' "
                             "structure's film traction needs (give them in its TOML, or "
                             "fit structure='split')")
        film = {"eyring_stress": float(oil.eyring_stress),
                "limiting_shear_coefficient": float(oil.limiting_shear_coefficient),
                "viscosity_model": str(study.attrs.get("solver_viscosity_model", "roelands"))}
        y_start, mu_e = _eyring_start(d, groups, mu_b, film)
    # standardise the non-intercept features: the ridge then weighs them alike
    j0 = features.index("1")
    mean = x.mean(axis=0)
    scale = x.std(axis=0)
    mean[j0], scale[j0] = 0.0, 1.0
    scale[scale == 0.0] = 1.0
    z = (x - mean) / scale
    regime = np.digitize(groups["lambda"], (lo_b, hi_b))
    rows, rhs = [], []
    a = np.zeros((n, 3 * nf))
    for r in range(3):
        a[regime == r, r * nf:(r + 1) * nf] = z[regime == r]
    rows.append(a)
    rhs.append(y_start)
    for i, at in enumerate((lo_b, hi_b)):
        g = dict(groups)
        g["lambda"] = np.full(n, at)
        zc = (_features(features, g) - mean) / scale
        c = np.zeros((n, 3 * nf))
        c[:, i * nf:(i + 1) * nf] = continuity_weight * zc
        c[:, (i + 1) * nf:(i + 2) * nf] = -continuity_weight * zc
        rows.append(c)
        rhs.append(np.zeros(n))
    if ridge > 0:
        pen = np.sqrt(ridge * n) * np.eye(3 * nf)
        for r in range(3):
            pen[r * nf + j0, r * nf + j0] = 0.0
        rows.append(pen)
        rhs.append(np.zeros(3 * nf))
    beta_z, *_ = np.linalg.lstsq(np.vstack(rows), np.concatenate(rhs), rcond=None)
    boundary: tuple[float, ...] = ()
    if structure != "regimes":
        beta_z, boundary = _fit_split(a, rows[1:3], y, groups, beta_z, mu_b,
                                      float(np.sqrt(ridge * n)) if ridge > 0 else 0.0,
                                      [r * nf + j0 for r in range(3)],
                                      d["asperity_load_ratio"], boundary_features, mu_e)
    coefficients = []
    for r in range(3):
        bz = beta_z[r * nf:(r + 1) * nf]
        b = bz / scale
        b[j0] = bz[j0] - float(np.sum(bz * mean / scale))
        coefficients.append(tuple(float(v) for v in b))
    all_inputs = study_inputs(study, converged=False)
    if box is not None:
        t_box = np.array(box["temperature"][:2])
        all_inputs = dict(all_inputs)
        for name in ("hertz_pressure", "radius", "entraining_velocity", "slide_to_roll",
                     "roughness_1", "roughness_2"):
            all_inputs[name] = np.array(box[name][:2], float)
        all_inputs["viscosity"] = np.asarray(viscosity(oil, t_box), float)
    lam = groups["lambda"]
    ranges = {
        "hertz_pressure": _span(all_inputs["hertz_pressure"]),
        "radius": _span(all_inputs["radius"]),
        "entraining_velocity": _span(all_inputs["entraining_velocity"]),
        "slide_to_roll": _span(np.abs(all_inputs["slide_to_roll"])),
        "viscosity": _span(all_inputs["viscosity"]),
        "roughness": _span(np.concatenate([all_inputs["roughness_1"],
                                           all_inputs["roughness_2"]])),
        "lambda": _span(lam),
    }
    prov = dict(provenance if provenance is not None else
                {k: v for k, v in study.attrs.items()
                 if k.startswith(("solver", "design", "toolkit", "wall_time", "points"))})
    fit = Kolivand2009Fit(
        lubricant=str(study.attrs.get("solver_lubricant", "75W90")), features=features,
        lambda_bounds=(lo_b, hi_b), coefficients=tuple(coefficients),  # type: ignore[arg-type]
        ranges=ranges, statistics={}, provenance=prov, structure=structure,
        boundary=boundary, boundary_friction=mu_b,
        boundary_features=boundary_features if structure != "regimes" else BOUNDARY_FEATURES,
        **film)
    stats: dict[str, Any] = {f"training_{k}": v for k, v in fit_statistics(fit, study).items()}
    if heldout is not None:
        stats.update({f"heldout_{k}": v for k, v in fit_statistics(fit, heldout).items()})
        for k in ("design_method", "design_seed", "solver_average", "solver_realisations"):
            if k in heldout.attrs:
                stats[f"heldout_{k}"] = heldout.attrs[k]
    stats["continuity_jump_lambda_1"] = _continuity_jump(fit, groups, lo_b)
    stats["continuity_jump_lambda_3"] = _continuity_jump(fit, groups, hi_b)
    stats["points_per_regime"] = [int(np.count_nonzero(regime == r)) for r in range(3)]
    stats["continuity_weight"] = float(continuity_weight)
    stats["ridge"] = float(ridge)
    return dataclasses.replace(fit, statistics=stats)


def _resolve_features(structure: str, features: Sequence[str] | None,
                      boundary_features: Sequence[str] | None
                      ) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The structure's features and ψ's features, defaults filled in and names checked."""
    if structure not in STRUCTURES:
        raise InputError(f"structure: must be one of {STRUCTURES}, got {structure!r}")
    if features is None:
        features = EYRING_FEATURES if structure == "eyring" else DEFAULT_FEATURES
    if boundary_features is None:
        boundary_features = (EYRING_BOUNDARY_FEATURES if structure == "eyring"
                             else BOUNDARY_FEATURES)
    features, boundary_features = tuple(features), tuple(boundary_features)
    if "1" not in features:
        raise InputError("features: the intercept '1' is required")
    for name, names in (("features", features), ("boundary_features", boundary_features)):
        unknown = [f for f in names if f not in FEATURES]
        if unknown:
            raise InputError(f"{name}: unknown {unknown}; known {sorted(FEATURES)}")
    return features, boundary_features


def _eyring_start(d: Mapping[str, Array], groups: Mapping[str, Array], mu_b: float,
                  film: Mapping[str, Any]) -> tuple[Array, Array]:
    """The ``eyring`` fit's linear start and μ_E: ln of the solver's film part (μ less
    μ_b times its asperity load ratio, at least 5 % of μ) over (1 − ratio) μ_E."""
    mu_e = groups_film_traction(groups, **film)
    share = np.clip(d["asperity_load_ratio"], 0.0, 0.99)
    mu = d["friction_coefficient"]
    film_part = np.maximum(mu - mu_b * share, 0.05 * mu)
    return np.log(film_part / ((1.0 - share) * mu_e)), mu_e


def _fit_split(a: Array, continuity: list[Array], y: Array, groups: Mapping[str, Array],
               beta0: Array, mu_b: float, ridge_root: float, intercepts: list[int],
               share: Array, boundary_features: Sequence[str],
               film_traction: Array | None) -> tuple[Array, tuple[float, ...]]:
    """β (standardised) and θ of μ = exp(aβ) + μ_b ψ(θ) (``split``) or of
    μ = (1 − ψ) μ_E exp(aβ) + μ_b ψ (``eyring``: ``film_traction`` μ_E given) by nonlinear
    least squares on ln μ, with the continuity rows and ridge of the linear fit."""
    from scipy.optimize import least_squares
    from scipy.special import expit

    xb = _features(boundary_features, groups)
    # start: logit ψ from the solver's asperity load ratio (clipped away from 0 and 1)
    psi = np.clip(share, 0.01, 0.99)
    theta0, *_ = np.linalg.lstsq(xb, np.log(psi / (1.0 - psi)), rcond=None)
    c = np.vstack(continuity)
    nb = beta0.size
    mask = np.ones(nb)
    mask[intercepts] = 0.0

    def residual(q: Array) -> Array:
        beta, theta = q[:nb], q[nb:]
        psi = expit(xb @ theta)
        film = np.exp(a @ beta)
        if film_traction is not None:
            film = (1.0 - psi) * film_traction * film
        mu = film + mu_b * psi
        return np.concatenate([np.log(mu) - y, c @ beta, ridge_root * mask * beta])

    res = least_squares(residual, np.concatenate([beta0, theta0]), method="trf",
                        x_scale="jac", max_nfev=5000)
    return res.x[:nb], tuple(float(v) for v in res.x[nb:])


def _span(v: Array) -> tuple[float, float]:
    return float(np.min(v)), float(np.max(v))


def write_fit(fit: Kolivand2009Fit, path: str | os.PathLike[str]) -> Path:
    """Write a fit as a coefficient file (TOML, atomically), readable by the model.

    Parameters
    ----------
    fit : Kolivand2009Fit
    path : path-like
        The ``.toml`` file (its directory must exist).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        A value TOML cannot hold, or the directory does not exist.
    """
    p = Path(path)
    if not p.parent.is_dir():
        raise InputError(f"output: directory {str(p.parent)!r} does not exist")

    def clean(v: Any) -> Any:
        if isinstance(v, (np.integer, np.floating)):
            return v.item()
        if isinstance(v, (list, tuple)):
            return [clean(x) for x in v]
        return v

    doc = {
        "schema": KOLIVAND2009_SCHEMA,
        "model": "kolivand2009",
        "lubricant": fit.lubricant,
        "structure": {"split": "mu = exp(r) + boundary_friction * psi, logit psi = sum_j"
                               " boundary.coefficients[j] * boundary.features[j]",
                      "eyring": "mu = (1 - psi) * mu_E * exp(r) + boundary_friction * psi,"
                                " mu_E of [film], logit psi = sum_j boundary.coefficients[j]"
                                " * boundary.features[j]",
                      "regimes": "mu = exp(r)"}[fit.structure]
        + "; r = sum_j regime.<name>.coefficients[j] * features[j](lambda, SR, U, G, H,"
        " Seq/Sc, Sc/R);"
        " regimes boundary_mixed: lambda < lambda_bounds[0], mixed: up to lambda_bounds[1],"
        " full_film: above (seed Eq. 5.11a-c); friction.kolivand2009",
        "structure_name": fit.structure,
        "features": list(fit.features),
        "lambda_bounds": list(fit.lambda_bounds),
        "regime": {name: {"coefficients": list(c)}
                   for name, c in zip(_REGIMES, fit.coefficients, strict=True)},
        "boundary": ({"features": list(fit.boundary_features),
                      "coefficients": list(fit.boundary),
                      "boundary_friction": fit.boundary_friction}
                     if fit.structure != "regimes" else {}),
        "film": ({"eyring_stress": fit.eyring_stress,
                  "limiting_shear_coefficient": fit.limiting_shear_coefficient,
                  "viscosity_model": fit.viscosity_model,
                  "traction": "mu_E = friction.traction.smooth_film_traction (Eyring shear "
                              "over the Hertz zone at the Dowson-Toyoda central film, "
                              "capped at limiting_shear_coefficient * p)"}
                 if fit.structure == "eyring" else {}),
        "range": {k: list(v) for k, v in fit.ranges.items()},
        "range_units": {"hertz_pressure": "MPa", "radius": "mm", "entraining_velocity": "m/s",
                        "slide_to_roll": "1", "viscosity": "Pa s", "roughness": "um",
                        "lambda": "1"},
        "statistics": {k: clean(v) for k, v in fit.statistics.items()
                       if not (isinstance(v, float) and math.isnan(v))},
        "provenance": {k: clean(v) for k, v in fit.provenance.items()},
    }
    with atomic_path(p) as tmp:
        tmp.write_text(dump_toml(doc), encoding="utf-8")
    return p
