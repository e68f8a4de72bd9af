"""Monte Carlo tolerance analysis: random or quasi-random draws of the study inputs.

Public functions
----------------
sample            analyse a case at n draws of its inputs from scipy.stats distributions
draw_points       the draws alone (unit-cube points from scipy.stats.qmc, mapped by ppf)
parse_distribution  a distribution from text such as ``normal:0:0.05`` (the CLI's form)
sensitivity       which input drives the spread of an output: rank correlation and
                  standardised regression coefficients
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr
from scipy import stats
from scipy.stats import qmc

from contact.study.engine import run_points, write_study
from contact.study.grid import study_inputs
from contact.study.points import POINT_INPUTS
from contact.study.run import StudyRun, study_run
from contact.study.sample_size import DEFAULT_SAMPLES, SAMPLES_RANGE, samples_message
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords

__all__ = ["DISTRIBUTIONS", "METHODS", "draw_points", "draw_values", "parse_distribution",
           "sample", "sensitivity"]

#: Sampling methods: quasi-random Sobol' (scrambled) and Latin hypercube from
#: :mod:`scipy.stats.qmc`, or plain pseudo-random (numpy's default generator).
METHODS = ("sobol", "lhs", "random")

#: Distributions of :func:`parse_distribution`: name → (scipy.stats maker, parameters).
DISTRIBUTIONS: Mapping[str, tuple[Any, str]] = {
    "normal": (lambda m, s: stats.norm(m, s), "mean:std"),
    "uniform": (lambda lo, hi: stats.uniform(lo, hi - lo), "low:high"),
    "truncnormal": (lambda m, s, lo, hi: stats.truncnorm((lo - m) / s, (hi - m) / s, m, s),
                    "mean:std:low:high"),
    "triangular": (lambda lo, mode, hi: stats.triang((mode - lo) / (hi - lo), lo, hi - lo),
                   "low:mode:high"),
}


def parse_distribution(name: str, text: str, scale: float = 1.0) -> Any:
    """A frozen scipy.stats distribution from ``KIND:P1:P2…`` (e.g. ``normal:0:0.05``).

    Parameters
    ----------
    name : str
        The input it is for (named in errors).
    text : str
        ``normal:mean:std``, ``uniform:low:high``, ``truncnormal:mean:std:low:high`` or
        ``triangular:low:mode:high``, in the input's units (:data:`POINT_INPUTS`) or in
        units ``scale`` times smaller.
    scale : float
        Factor on every parameter (all are locations or widths), e.g. π/180 for a ΔΣ
        typed in degrees.

    Returns
    -------
    scipy.stats frozen distribution

    Raises
    ------
    InputError
        Unknown kind, wrong number of parameters, non-numeric or invalid parameters.
    """
    kind, *params = str(text).split(":")
    if kind not in DISTRIBUTIONS:
        raise InputError(f"{name}: unknown distribution {kind!r}; accepted: "
                         + ", ".join(f"{k}:{v[1]}" for k, v in DISTRIBUTIONS.items()))
    maker, form = DISTRIBUTIONS[kind]
    if len(params) != form.count(":") + 1:
        raise InputError(f"{name}: {kind} takes {form}, got {text!r}")
    try:
        p = [float(x) for x in params]
    except ValueError:
        raise InputError(f"{name}: parameters of {kind} must be numbers ({form}), got "
                         f"{text!r}") from None
    if not np.all(np.isfinite(p)):
        raise InputError(f"{name}: parameters must be finite, got {text!r}")
    p = [x * float(scale) for x in p]
    if (kind == "normal" and p[1] <= 0) or (kind == "truncnormal" and (p[1] <= 0 or p[2] >= p[3])):
        raise InputError(f"{name}: {kind} needs std > 0 (and low < high), got {text!r}")
    if kind == "uniform" and p[0] >= p[1]:
        raise InputError(f"{name}: uniform needs low < high, got {text!r}")
    if kind == "triangular" and (not p[0] <= p[1] <= p[2] or p[0] == p[2]):
        raise InputError(f"{name}: triangular needs low <= mode <= high, low < high, got "
                         f"{text!r}")
    return maker(*p)


def draw_points(distributions: Mapping[str, Any], n: int, *, method: str = "sobol",
                seed: int | None = None) -> dict[str, np.ndarray]:
    """n draws of the inputs: unit-cube points mapped through each distribution's ppf.

    Parameters
    ----------
    distributions : mapping of str to scipy.stats frozen distribution
        Input name (:data:`POINT_INPUTS`) → its distribution, in the input's units.
    n : int
        Number of draws, in :data:`contact.study.sample_size.SAMPLES_RANGE` ([2, 10^7], as
        ``ltca tolerance -n``; Sobol' balances best at powers of two).
    method : str
        ``"sobol"`` (scrambled, :class:`scipy.stats.qmc.Sobol`), ``"lhs"``
        (:class:`scipy.stats.qmc.LatinHypercube`) or ``"random"``.
    seed : int, optional
        Seed of the generator: the same seed gives the same draws.

    Returns
    -------
    dict of str to ndarray (n,)

    Raises
    ------
    InputError
        No or unknown input, an object without ``ppf``, bad n or method, draws that are
        not finite (a distribution with infinite support mapped at 0 or 1).
    """
    if not distributions:
        raise InputError("distributions: give at least one input and its distribution")
    for name, dist in distributions.items():
        if name not in POINT_INPUTS:
            raise InputError(f"distributions: unknown study input {name!r}; accepted: "
                             f"{', '.join(POINT_INPUTS)}")
        if not callable(getattr(dist, "ppf", None)):
            raise InputError(f"{name}: must be a scipy.stats distribution (with ppf), got "
                             f"{type(dist).__name__}")
    low, high = SAMPLES_RANGE
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not low <= n <= high:
        raise InputError(f"n: {samples_message(n)}")
    if method not in METHODS:
        raise InputError(f"method: must be one of {', '.join(METHODS)}, got {method!r}")
    d = len(distributions)
    if method == "random":
        unit = np.random.default_rng(seed).random((int(n), d))
    else:
        engine = (qmc.Sobol(d, scramble=True, rng=seed) if method == "sobol"
                  else qmc.LatinHypercube(d, rng=seed))
        with warnings.catch_warnings():
            # Sobol' warns when n is not a power of two: the balance is then only
            # approximate, which a tolerance study can accept
            warnings.filterwarnings("ignore", message=".*balance properties.*")
            unit = engine.random(int(n))
    out = {}
    for k, (name, dist) in enumerate(distributions.items()):
        x = np.asarray(dist.ppf(unit[:, k]), float)
        if not np.all(np.isfinite(x)):
            raise InputError(f"{name}: the distribution gave non-finite draws")
        out[name] = x
    return out


@renamed_keywords(speed="pinion_speed")
def sample(
    case: Case | str | os.PathLike[str] | None,
    distributions: Mapping[str, Any],
    n: int = DEFAULT_SAMPLES,
    *,
    method: str = "sobol",
    seed: int | None = 0,
    torque: Any = None,
    pinion_speed: Any = None,
    run: StudyRun | None = None,
    **legacy: Any,
) -> xr.Dataset:
    """Monte Carlo tolerance analysis: the case at n draws of its inputs, on Dask.

    Parameters
    ----------
    case : Case, path, bundled name or None (the default case)
    distributions : mapping of str to scipy.stats frozen distribution
        e.g. ``{"delta_E": scipy.stats.norm(0, 0.05), "delta_P": …}`` ([mm], [rad]
        for ``delta_Sigma``, [1] for ``deviation_scale``; :data:`POINT_INPUTS`).
    n : int, optional
        Number of draws: default 256 (:data:`contact.study.sample_size.DEFAULT_SAMPLES`),
        as ``ltca tolerance -n``; accepted 2 to 10^7 as the command accepts (before
        plugin83 ``n`` was required and the command's parser let ``-n 1`` through to
        this function's refusal).
    method : str
        ``"sobol"`` (default), ``"lhs"`` or ``"random"``, as :func:`draw_points`.
    seed : int or None, optional
        Seed of the draws: default 0, as ``ltca tolerance --seed`` (the same draws each
        call; before api83 None); None: other draws each call.
    torque : float or sequence — [N·m], optional
        Pinion torques, as :func:`contact.study.sweep` (default the case's
        ``[operating]`` torques).
    pinion_speed : float or sequence — [rpm], optional
        Pinion speeds (old name ``speed``, deprecated), as :func:`contact.study.sweep`.
    run : contact.study.StudyRun, optional
        Where and how the points run, as :func:`contact.study.sweep`.
    **legacy
        The former run keywords (fields of :class:`StudyRun`), deprecated.

    Returns
    -------
    xarray.Dataset
        dims ``sample`` (+ ``torque``, ``harmonic``, ``speed``); the drawn inputs as
        coordinates over ``sample``; the summaries, ``status`` and ``reason`` of
        :func:`contact.study.sweep`. Attributes ``method``, ``seed``, ``distributions``
        and the sweep's ``not_checked``.

    Raises
    ------
    InputError
        As :func:`draw_points` and :func:`contact.study.sweep`.
    """
    run = study_run(run, legacy, "sample")
    draws = draw_points(distributions, n, method=method, seed=seed)
    shared = study_inputs(case, torque, pinion_speed, operating=run.operating, options=run.options,
                          flank=run.flank, root_stress=run.study_root_stress)
    names = list(draws)
    points = [{k: float(draws[k][i]) for k in names} for i in range(int(n))]
    flat = run_points(shared, points, names=names, output=run.output, scheduler=run.scheduler,
                      n_workers=run.n_workers, progress=run.progress, kind="sample",
                      force=run.force)
    ds = flat.rename({"point": "sample"})
    ds.attrs.update(method=method, seed=-1 if seed is None else int(seed),
                    distributions="; ".join(f"{k}: {_describe(v)}"
                                            for k, v in distributions.items()))
    from contact.study.verdicts import study_not_checked_attrs

    # what the summary prints and no limit judges, in the file too (issue 71)
    ds.attrs.update(study_not_checked_attrs(ds))
    if run.output is not None:
        write_study(ds, run.output, shared)
    return ds


def _describe(dist: Any) -> str:
    name = getattr(getattr(dist, "dist", None), "name", type(dist).__name__)
    args = ", ".join(f"{a:g}" for a in getattr(dist, "args", ()))
    kwds = ", ".join(f"{k}={v:g}" for k, v in getattr(dist, "kwds", {}).items())
    return f"{name}({', '.join(x for x in (args, kwds) if x)})"


def sensitivity(ds: xr.Dataset, variable: str, *, inputs: Sequence[str] | None = None,
                dim: str = "sample") -> xr.Dataset:
    """Which inputs drive the spread of ``variable`` over a Monte Carlo study.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`sample` result (points with ``status`` 2 are left out).
    variable : str
        A summary variable, e.g. ``"lte_peak_to_peak"`` (other dims, e.g. ``torque``,
        are kept).
    inputs : sequence of str, optional
        The drawn inputs (default every :data:`POINT_INPUTS` coordinate on ``dim``).
    dim : str
        The sample dimension.

    Returns
    -------
    xarray.Dataset
        Over ``input`` (and the variable's other dims): ``spearman`` (rank correlation,
        :func:`scipy.stats.spearmanr`), ``src`` (standardised regression coefficient of
        a linear least-squares fit, :func:`numpy.linalg.lstsq`; Σ src² ≈ R² for
        independent inputs) and ``r_squared`` of that fit.

    Raises
    ------
    InputError
        Unknown variable or input, or fewer valid points than inputs + 2.

    Notes
    -----
    Saltelli et al., *Global Sensitivity Analysis: The Primer* (Wiley 2008), §1.2.5:
    SRCs rank the inputs' shares of the output variance when the model is close to
    linear (R² near 1); the rank correlation still ranks them when it is monotonic.
    """
    if variable not in ds.data_vars:
        raise InputError(f"variable: {variable!r} is not in the study (have "
                         f"{', '.join(ds.data_vars)})")
    names = list(inputs) if inputs is not None else [
        n for n in POINT_INPUTS if n in ds.coords and ds[n].dims == (dim,)]
    for name in names:
        if name not in ds.coords:
            raise InputError(f"inputs: {name!r} is not an input of the study")
    ok = ds["status"].values != 2
    X = np.column_stack([ds[n].values[ok] for n in names])
    y_all = ds[variable].transpose(dim, ...)
    rest = y_all.dims[1:]
    Y = y_all.values[ok].reshape(int(ok.sum()), -1)
    n_rest = Y.shape[1]
    sp = np.full((len(names), n_rest), np.nan)
    src = np.full((len(names), n_rest), np.nan)
    r2 = np.full(n_rest, np.nan)
    for j in range(n_rest):
        good = np.isfinite(Y[:, j])
        if good.sum() < len(names) + 2:
            continue
        x, y = X[good], Y[good, j]
        sx, sy = x.std(axis=0), y.std()
        if sy == 0 or np.any(sx == 0):
            continue
        for k in range(len(names)):
            sp[k, j] = stats.spearmanr(x[:, k], y).statistic
        A = np.column_stack([np.ones(len(y)), (x - x.mean(0)) / sx])
        coef, *_ = np.linalg.lstsq(A, (y - y.mean()) / sy, rcond=None)
        src[:, j] = coef[1:]
        fit = A @ coef
        r2[j] = 1.0 - np.sum(((y - y.mean()) / sy - fit) ** 2) / len(y)
    shape_rest = tuple(y_all.sizes[d] for d in rest)
    coords = {"input": ("input", names, {"long_name": "drawn study input"})}
    for d in rest:
        if d in ds.coords:
            coords[d] = ds[d]
    return xr.Dataset(
        {"spearman": (("input", *rest), sp.reshape(len(names), *shape_rest),
                      {"units": "1", "long_name": f"Spearman rank correlation with {variable}"}),
         "src": (("input", *rest), src.reshape(len(names), *shape_rest),
                 {"units": "1",
                  "long_name": f"standardised regression coefficient of {variable}"}),
         "r_squared": (rest, r2.reshape(shape_rest),
                       {"units": "1", "long_name": "R^2 of the linear fit"})},
        coords=coords, attrs={"variable": variable})


def draw_values(ds: xr.Dataset, name: str, torque: float) -> np.ndarray:
    """The finite values of one summary over the draws that did not fail, at one torque.

    Parameters
    ----------
    ds : xarray.Dataset
        A :func:`sample` result (dims ``sample``, ``torque`` and maybe ``speed``).
    name : str
        A summary variable of ``ds`` (its units in its ``units`` attribute).
    torque : float — [N·m]
        One of ``ds``'s pinion torques.

    Returns
    -------
    ndarray (k,)
        In the variable's units; at the first speed where it has a speed dimension;
        draws with ``status`` 2 (failed) and non-finite values left out.
    """
    da = ds[name].sel(torque=torque)
    if "speed" in da.dims:
        da = da.isel(speed=0)
    x = da.values[ds["status"].values != 2]
    return x[np.isfinite(x)]

