"""Running an optimisation: scipy's optimiser, designs analysed on Dask, every one logged.

:func:`optimize` minimises the objective of :mod:`contact.optimize.objective` over the
variables of :mod:`contact.optimize.variables` within their bounds, with
``scipy.optimize.differential_evolution`` (default; a generation's designs are analysed in
parallel through :func:`contact.study.engine.run_tasks`, its ``workers`` argument a map
over Dask) or ``scipy.optimize.minimize(method="Powell")`` with bounds (one design after
the other). The variables are scaled to [0, 1] for the optimiser. The start design is
evaluated first and is part of the initial population (DE ``x0``) or the start (Powell), and
the result is the best design of all evaluated — feasible ones first, then the lowest
objective — so the result's objective never exceeds the start's.

Public functions
----------------
METHODS          the optimisers by name
SharedDesign     what every evaluation shares (scattered once to the workers)
OptimizeResult   the best design, its case, feasibility and the log of every evaluation
optimize         run an optimisation
optimized_case   the best case with a ``[optimize]`` provenance table
"""

from __future__ import annotations

import dataclasses
import logging
import math
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np
import xarray as xr
from scipy.optimize import differential_evolution, minimize

from contact.optimize.methods import METHODS
from contact.optimize.objective import (
    METRICS,
    TERM_NAMES,
    Evaluation,
    OptimizeProblem,
    constraint_names,
    evaluate_design,
)
from contact.optimize.variables import (
    DesignVariable,
    case_at,
    check_variables,
    own_relief_start,
    start_values,
    variable_unit,
)
from contact.study.engine import open_client, run_tasks
from geometry import __version__
from geometry.case import Case
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.core.validation import real
from geometry.synthesis.basic_design import BasicDesign

__all__ = ["METHODS", "OptimizeResult", "SharedDesign", "optimize", "optimized_case"]

log = logging.getLogger(__name__)



@dataclass(frozen=True, eq=False)
class SharedDesign:
    """What every evaluation shares: the start case, the problem, the variables."""

    case: Case
    problem: OptimizeProblem
    pinion_flank: str
    names: tuple[str, ...]
    relief_start: float = 0.5
    basic: BasicDesign | None = None  # the start's basic design: synthesis variables
    start: np.ndarray | None = None  # the start values: that design is ``case`` itself


@dataclass(frozen=True, eq=False)
class OptimizeResult:
    """The outcome of :func:`optimize`.

    Attributes
    ----------
    names, units : tuple of str
    start, best : ndarray (n_var,) — [file units]
    case : geometry.case.Case
        The best design's case (without provenance; see :func:`optimized_case`).
    feasible : bool
        The best design meets every constraint.
    start_evaluation, best_evaluation : Evaluation
    log : xarray.Dataset
        Every evaluation (dim ``evaluation``): variables, terms, constraints, objective,
        metrics per misalignment and torque, status, reason, seconds.
    method : str
    seconds : float
        Wall time [s].
    problem : OptimizeProblem or None
        The problem solved (limits, weights, the analysis's options).
    confirmations : tuple of Confirmation
        The designs confirmed at ``ltca run``'s sampling, in the order tried
        (:func:`contact.optimize.confirm.confirm_design`); empty with ``confirm=0``.
    confirmation : Confirmation or None
        The chosen design's (``best``); None when not confirmed. ``feasible`` is its
        ``met``: the constraints as ``ltca run`` of the written case meets them.
    """

    names: tuple[str, ...]
    units: tuple[str, ...]
    start: np.ndarray
    best: np.ndarray
    case: Case
    feasible: bool
    start_evaluation: Evaluation
    best_evaluation: Evaluation
    log: xr.Dataset
    method: str
    seconds: float
    problem: OptimizeProblem | None = None
    confirmations: tuple = ()
    confirmation: Any = None


def _rank(e: Evaluation) -> tuple:
    """Sort key of the best design: feasible first, then the lowest objective."""
    return (0 if e.feasible else 1, e.objective, e.index)


class _Evaluator:
    """Evaluates designs (cached by their values), in parallel through Dask."""

    def __init__(self, shared: SharedDesign, client: Any, progress: Any) -> None:
        self.shared = shared
        self.client = client
        self.progress = progress
        self.cache: dict[tuple, Evaluation] = {}
        self.done: list[Evaluation] = []
        self.budget: int | None = None

    def run(self, xs: Sequence[np.ndarray]) -> None:
        todo, seen = [], set()
        for x in xs:
            key = tuple(np.round(np.asarray(x, float), 12))
            if key not in self.cache and key not in seen:
                seen.add(key)
                todo.append(key)
        items = [(len(self.done) + i, np.asarray(k)) for i, k in enumerate(todo)]
        if self.client is None:
            results = (evaluate_design(self.shared, *it) for it in items)
        else:
            results = run_tasks(evaluate_design, self.shared, items, client=self.client)
        for ev in results:
            self.cache[tuple(np.round(ev.x, 12))] = ev
            self.done.append(ev)
            if callable(self.progress):  # one line per design (off a terminal)
                self.progress(design_line(self.shared, ev, self.budget))
            elif self.progress is not None:
                self.progress.update()
                self.progress.set_postfix(best=f"{min(e.objective for e in self.done):.4g}")

    def objective(self, x: np.ndarray) -> float:
        key = tuple(np.round(np.asarray(x, float), 12))
        if key not in self.cache:
            self.run([np.asarray(x, float)])
        return self.cache[key].objective


def _stderr_line(line: str) -> None:
    """A progress line on standard error, at once (the ``"lines"`` mode)."""
    print(line, file=sys.stderr, flush=True)


def design_line(shared: SharedDesign, ev: Evaluation, budget: int | None = None) -> str:
    """One progress line of an evaluated design: its number, variable values, the worst
    flank peak [MPa], edge share [%] and LTE p-p [µrad] over misalignments and torques,
    the objective, whether it meets every constraint, and its wall time [s] — or why it
    failed."""
    of = f"/{budget}" if budget else ""
    values = ", ".join(f"{n} {x:.5g}" for n, x in zip(shared.names, ev.x, strict=True))
    head = f"optimize: design {ev.index + 1}{of}{' (start)' if ev.index == 0 else ''}: {values}"
    if ev.status == 2:
        return f"{head}: rejected, {ev.reason} [{ev.seconds:.0f} s]"
    m = ev.metrics
    with np.errstate(invalid="ignore"):
        peak = np.nanmax(m["pressure_max_flank"])
        edge = 100.0 * np.nanmax(m["edge_load_share"])
        pp = np.nanmax(m["lte_peak_to_peak"])
    return (f"{head}: flank peak {peak:.0f} MPa, edge {edge:.2g} %, LTE p-p {pp:.1f} urad; "
            f"objective {ev.objective:.4g}, "
            f"{'constraints met' if ev.feasible else 'not every constraint met'} "
            f"[{ev.seconds:.0f} s]")


def _log_dataset(shared: SharedDesign, evals: Sequence[Evaluation], units: Sequence[str],
                 method: str) -> xr.Dataset:
    problem = shared.problem
    evs = sorted(evals, key=lambda e: e.index)
    cons = constraint_names(problem)
    data = {
        "variable_value": data_var(("evaluation", "variable"), np.stack([e.x for e in evs]),
                                   "1", "variable values, each in its own unit "
                                   "(see the variable_unit coordinate)"),
        "objective_term": data_var(("evaluation", "term"), np.stack([e.terms for e in evs]),
                                   "1",
                         "objective terms, dimensionless, unweighted (docs/optimize.md)"),
        "constraint_value": data_var(("evaluation", "constraint"),
                               np.stack([e.constraints for e in evs]), "1",
                               "normalised constraint values, <= 0 met (docs/optimize.md)"),
        "objective": data_var(("evaluation",), np.array([e.objective for e in evs]), "1",
                              "objective: weighted terms plus penalty"),
        "feasible": data_var(("evaluation",), np.array([int(e.feasible) for e in evs],
                                                       np.int8), "1",
                             "every constraint met (1) or not (0)"),
        "status": data_var(("evaluation",), np.array([e.status for e in evs], np.int8), "1",
                           "0 ok, 1 some roll position uncertified, 2 analysis failed"),
        "reason": data_var(("evaluation",), np.array([e.reason for e in evs], dtype=object),
                           None, "why the analysis failed (empty when it did not)"),
        "seconds": data_var(("evaluation",), np.array([e.seconds for e in evs]), "s",
                            "wall time of the evaluation on its worker"),
    }
    units_of = {"lte_mean": "urad", "lte_peak_to_peak": "urad", "edge_load_share": "1",
                "pressure_max_flank": "MPa", "pressure_max_edge": "MPa",
                "pattern_centre_u": "1", "pattern_centre_v": "1"}
    for k in METRICS:
        data[k] = data_var(("evaluation", "misalignment", "torque"),
                           np.stack([e.metrics[k] for e in evs]), units_of[k],
                           f"{k.replace('_', ' ')} (contact.study.summary.point_summary)")
    mis = problem.misalignments
    coords = {
        "evaluation": ("evaluation", np.array([e.index for e in evs]),
                       {"units": "1", "long_name": "evaluation number, in order of start"}),
        "variable": ("variable", np.array(shared.names, dtype=object),
                     {"long_name": "variable name"}),
        "variable_unit": ("variable", np.array(units, dtype=object),
                          {"long_name": "unit of the variable's values"}),
        "term": ("term", np.array(TERM_NAMES, dtype=object), {"long_name": "objective term"}),
        "constraint": ("constraint", np.array(cons, dtype=object),
                       {"long_name": "constraint"}),
        "torque": ("torque", np.asarray(problem.torque), {"units": "N m",
                                                          "long_name": "pinion torque"}),
        "misalignment": ("misalignment", np.arange(len(mis)),
                         {"units": "1", "long_name": "analysed assembly"}),
        "delta_E": ("misalignment", np.array([m.delta_E for m in mis]),
                    {"units": "mm", "long_name": "offset misalignment dE"}),
        "delta_P": ("misalignment", np.array([m.delta_P for m in mis]),
                    {"units": "mm", "long_name": "pinion axial misalignment dP"}),
        "delta_G": ("misalignment", np.array([m.delta_G for m in mis]),
                    {"units": "mm", "long_name": "gear axial misalignment dG"}),
        "delta_Sigma": ("misalignment", np.array([m.delta_Sigma for m in mis]),
                        {"units": "rad", "long_name": "shaft-angle misalignment dSigma"}),
    }
    ds = xr.Dataset(data, coords=coords)
    for name in ("variable", "variable_unit", "term", "constraint", "reason"):
        ds[name] = ds[name].astype(str)
    ds.attrs = {"title": f"hypoid-ltca optimisation of {shared.case.name}",
                "case": shared.case.name, "method": method, "toolkit_version": __version__,
                "pinion_flank": shared.pinion_flank}
    return ds


def optimize(case: Case, variables: Sequence[DesignVariable], problem: OptimizeProblem, *,
             method: str = "differential_evolution", max_evaluations: int = 200,
             popsize: int | None = None, seed: int | None = 0, relief_start: float | None = None,
             scheduler: Any = None, n_workers: int | None = None,
             progress: bool | str | Callable[[str], None] = False,
             basic: BasicDesign | None = None,
             start: Mapping[str, float] | None = None, confirm: int = 3) -> OptimizeResult:
    """Optimise the pinion flank's variables for a loaded target.

    Parameters
    ----------
    case : geometry.case.Case
        Start design (its misalignment is the default analysed one).
    variables : sequence of DesignVariable
        Names and bounds [file units]; checked against the case before any analysis.
    problem : OptimizeProblem
        Torques, misalignments, limits, weights, analysis options.
    method : str
        A key of :data:`METHODS`.
    max_evaluations : int
        Budget of analysed designs (≥ 2; DE: generations of ``popsize`` × n_var designs
        until the budget, Powell: ``maxfev``).
    popsize : int, optional
        DE population multiplier (default ⌈12 / n_var⌉, reduced to fit the budget; the
        population is at least 5).
    seed : int or None
        DE random seed (reproducible runs).
    relief_start : float, optional
        Where a relief variable starts on a blade without that rem
        (:func:`geometry.machine.relief.relieved_blade`); default the case's synthesis
        record for the flank (``[synthesis.<flank>] relief_start``), else 0.5. A rem the
        blade has keeps its corner (:func:`contact.optimize.variables.case_at`).
    scheduler, n_workers
        Where designs are analysed (:func:`contact.study.engine.open_client`): None a
        LocalCluster, ``"synchronous"`` this process.
    progress : bool, "lines" or callable
        True: a tqdm bar over the evaluations (a terminal); ``"lines"``: one line per
        design on standard error (:func:`design_line`; a log file or a pipe reads it, as
        ``ltca optimize`` prints off a terminal); a callable: called with each line;
        False: nothing.
    basic : geometry.synthesis.basic_design.BasicDesign, optional
        The basic design ``case`` was synthesised from: its flank prescriptions
        (:data:`contact.optimize.variables.SYNTHESIS_VARIABLES`, and the relief) may be
        variables; each design is then re-synthesised.
    start : mapping of str to float, optional
        Start values [file units] of some variables, replacing the case's own (e.g. to go
        on from an earlier run's result); each inside its bounds.
    confirm : int
        Designs to confirm at most (≥ 0): the best is analysed as ``ltca run`` analyses its
        written case (:func:`contact.optimize.confirm.confirm_design`: ``ltca run``'s
        sampling, the rating's verdict, the FE mesh of the pinion tooth); where it fails,
        the next-best designs the optimiser found feasible, until one is accepted. The
        result is the first accepted, else the first whose mesh builds (``feasible``
        False); None of them meshing leaves ``case`` None (nothing to write). 0: no
        confirmation, ``feasible`` the optimiser's own ranking.

    Returns
    -------
    OptimizeResult
        Infeasible constraints are reported (``feasible`` False, the best design found),
        not raised.

    Raises
    ------
    InputError
        Unknown method or variable, bounds outside a setting's valid range, a start value
        outside its bounds, a bad budget — all before any analysis.

    Notes
    -----
    Storn & Price, J. Global Optim. 11 (1997) 341 (differential evolution); Powell,
    Comput. J. 7 (1964) 155. Objective and constraints: :mod:`contact.optimize.objective`.
    """
    t_start = time.perf_counter()
    if method not in METHODS:
        raise InputError(f"method: unknown optimiser {method!r}; accepted: {', '.join(METHODS)}")
    if isinstance(max_evaluations, bool) or int(max_evaluations) != max_evaluations \
            or max_evaluations < 2:
        raise InputError(f"max_evaluations: must be an integer >= 2, got {max_evaluations!r}")
    pinion_flank = _pinion_flank(case, problem.flank)
    check_variables(case, pinion_flank, variables, basic=basic)
    names = tuple(v.name for v in variables)
    units = tuple(variable_unit(n) for n in names)
    lo = np.array([v.low for v in variables], float)
    hi = np.array([v.high for v in variables], float)
    x0 = start_values(case, pinion_flank, names, basic=basic)
    own = x0.copy()  # the case's own values: that design is the case itself
    for n, v in (start or {}).items():
        if n not in names:
            raise InputError(f"optimize.start.{n}: not one of the variables "
                             f"({', '.join(names)})")
        x0[names.index(n)] = real(f"optimize.start.{n}", v, unit=variable_unit(n))
    outside = [(n, x, a, b) for n, x, a, b in zip(names, x0, lo, hi, strict=True)
               if not a <= x <= b]
    if outside:
        n, x, a, b = outside[0]
        raise InputError(f"optimize.bounds.{n}: the start value {x:.8g} {variable_unit(n)} lies "
                         f"outside the bounds ({a:g}, {b:g}); widen them")
    problem = problem.with_case(case)
    if relief_start is None:
        recorded = own_relief_start(case, pinion_flank)
        relief_start = recorded if recorded is not None else 0.5
    shared = SharedDesign(case, problem, pinion_flank, names, relief_start, basic, own)
    span = hi - lo

    def to_x(z):
        return lo + np.clip(np.asarray(z, float), 0.0, 1.0) * span

    bar = None
    if callable(progress):
        bar = progress
    elif progress == "lines":
        bar = _stderr_line
    elif progress is True:
        from tqdm.auto import tqdm

        bar = tqdm(total=int(max_evaluations), desc="optimize", unit="design")
    elif progress is not False and progress is not None:
        raise InputError(f"progress: must be True, False, 'lines' or a callable, got "
                         f"{progress!r}")
    try:
        with open_client(scheduler, n_workers) as client:
            ev = _Evaluator(shared, client, bar)
            ev.budget = int(max_evaluations)
            ev.run([x0])
            z0 = (x0 - lo) / span
            if method == "differential_evolution":
                n = len(names)
                # scipy's population is max(5, popsize · n); a small budget gets a smaller
                # population (one generation at least)
                pop = popsize if popsize is not None else math.ceil(12 / n)
                pop = max(math.ceil(5 / n), min(pop, int(max_evaluations) // n))
                per_gen = max(5, pop * n)
                maxiter = max(0, int(max_evaluations) // per_gen - 1)
                ev.budget = max(int(max_evaluations), per_gen * (maxiter + 1))

                def mapper(func, zs):
                    zs = list(zs)
                    ev.run([to_x(z) for z in zs])
                    return [func(z) for z in zs]

                differential_evolution(
                    lambda z: ev.objective(to_x(z)), [(0.0, 1.0)] * n, maxiter=maxiter,
                    popsize=pop, x0=z0, rng=seed, polish=False, updating="deferred",
                    workers=mapper, tol=0.0, atol=0.0, init="latinhypercube")
            else:
                minimize(lambda z: ev.objective(to_x(z)), z0, method="Powell",
                         bounds=[(0.0, 1.0)] * len(names),
                         options={"maxfev": int(max_evaluations), "xtol": 1e-3,
                                  "ftol": 1e-4})
    finally:
        if bar is not None and hasattr(bar, "close"):
            bar.close()
    evals = ev.done
    best = min(evals, key=_rank)
    feasible = best.feasible
    start = evals[0]
    confirmations: tuple = ()
    chosen_conf = None
    if isinstance(confirm, bool) or int(confirm) != confirm or confirm < 0:
        raise InputError(f"confirm: must be an integer >= 0, got {confirm!r}")
    if confirm:
        best, chosen_conf, confirmations = _confirmed(shared, evals, int(confirm), bar)
        feasible = chosen_conf is not None and chosen_conf.met
    if best is None:
        best_case = None
        best = min(evals, key=_rank)
    elif np.array_equal(best.x, own):
        best_case = case
    else:
        best_case = case_at(case, pinion_flank, names, best.x, relief_start=relief_start,
                            basic=basic)
    log_ds = _log_dataset(shared, evals, units, method)
    if not feasible:
        log.warning("optimize: no design met every constraint%s; best found %s (objective "
                    "%.4g)", " at ltca run's sampling" if confirm else "",
                    dict(zip(names, best.x.tolist(), strict=True)), best.objective)
    return OptimizeResult(names=names, units=units, start=x0, best=best.x, case=best_case,
                          feasible=feasible, start_evaluation=start,
                          best_evaluation=best, log=log_ds, method=method,
                          seconds=time.perf_counter() - t_start, problem=problem,
                          confirmations=confirmations, confirmation=chosen_conf)


def _confirmed(shared: SharedDesign, evals: Sequence[Evaluation], budget: int, say: Any):
    """(evaluation, confirmation, all confirmations) of the design to write.

    The start (``evals[0]``, the case given) is confirmed first, as ``ltca run`` analyses it;
    then the optimiser's feasible designs in rank order, at most ``budget`` besides the
    start, each judged against the start's verdict (:attr:`~contact.optimize.confirm.
    Confirmation.worse_than_start`): the best ranked one ``ltca run``'s analysis accepts
    (:func:`contact.optimize.confirm.confirm_design`); else the start where it is accepted
    (no design beat it by the verdict: round 27's FH 6×43 at Σ 80°, PASS as given, was
    written ATTENTION); else the first whose FE mesh builds, one no worse than the start
    by the verdict first; else (None, None, ...)."""
    from contact.optimize.confirm import confirm_design

    def said(conf, what):
        if callable(say):
            say(f"optimize: {what} at ltca run's sampling: {conf.summary()} "
                f"[{conf.seconds:.0f} s]")

    start_ev = evals[0]
    start_conf = confirm_design(shared, start_ev)
    said(start_conf, f"the start (design {start_ev.index + 1})")
    tried, ranked = [start_conf], 0
    fallback = worse = None
    for e in sorted((e for e in evals if e.status < 2), key=_rank):
        if ranked >= budget or (ranked and not e.feasible):
            break
        ranked += 1
        if e.index == start_ev.index:
            conf = start_conf
        else:
            conf = dataclasses.replace(confirm_design(shared, e),
                                       start_severity=start_conf.severity)
            tried.append(conf)
            said(conf, f"design {e.index + 1}")
        if conf.accepted:
            return e, conf, tuple(tried)
        if not conf.mesh:
            if conf.worse_than_start:
                worse = worse or (e, conf)
            else:
                fallback = fallback or (e, conf)
    if start_conf.accepted:
        return start_ev, start_conf, tuple(tried)
    fallback = fallback or worse
    if fallback is None:
        return None, None, tuple(tried)
    return fallback[0], fallback[1], tuple(tried)


def _pinion_flank(case: Case, flank: str | None) -> str:
    from contact.utca.easeoff import FLANK_ROLES

    return FLANK_ROLES[flank or "drive"](case)


def optimized_case(result: OptimizeResult, *, provenance: Mapping[str, object] | None = None,
                   name: str | None = None) -> Case:
    """The best case with an ``[optimize]`` table saying where it came from.

    Parameters
    ----------
    result : OptimizeResult
    provenance : mapping, optional
        Extra entries (e.g. the source file), TOML-writable.
    name : str, optional
        Default ``<name>_optimized``.

    Returns
    -------
    geometry.case.Case
        ``extra["optimize"]``: source case, method, variables (start, result, bounds,
        units), feasibility, start and result objective and metrics; the start case's own
        ``[optimize]`` problem table is kept under ``problem``.
    """
    case = result.case
    b, s = result.best_evaluation, result.start_evaluation
    lo = result.log
    table: dict[str, Any] = {
        "source_case": case.name,
        "method": f"contact.optimize ({METHODS[result.method]})",
        "feasible": bool(result.feasible),
        "evaluations": int(lo.sizes["evaluation"]),
        "objective_start": float(s.objective),
        "objective_result": float(b.objective),
        "variables": {n: {"start": float(x0), "result": float(x1), "unit": u}
                      for n, x0, x1, u in zip(result.names, result.start, result.best,
                                              result.units, strict=True)},
        "torque_Nm": [float(t) for t in lo["torque"].values],
    }
    if result.problem is not None:  # the sampling the designs were ranked at
        table["flank"] = result.problem.flank or "drive"
        table["rolls_per_cycle"] = int(result.problem.options.rolls_per_cycle)
        table["segments"] = int(result.problem.options.segments)
    conf = result.confirmation
    if conf is not None:  # the design as ltca run analyses the written case
        table["confirmed"] = {
            "sampling": "ltca run's defaults (contact.ltca.LTCAOptions), the rating, the FE "
                        "mesh of the pinion tooth (contact.optimize.confirm)",
            "constraints_met": bool(conf.met), "not_met": list(conf.violated),
            "verdict": conf.severity, "verdict_fail": list(conf.findings),
            "verdict_attention": list(conf.attention),
            "designs_confirmed": len(result.confirmations),
            **{k: np.round(conf.metrics[k], 6).tolist() for k in
               ("lte_mean", "lte_peak_to_peak", "edge_load_share", "pressure_max_flank")}}
    for tag, e in (("start", s), ("result", b)):
        table[tag] = {k: np.round(e.metrics[k], 6).tolist() for k in
                      ("lte_mean", "lte_peak_to_peak", "edge_load_share",
                       "pressure_max_flank", "pattern_centre_u", "pattern_centre_v")}
    table |= dict(provenance or {})
    prev = case.extra.get("optimize")
    if isinstance(prev, Mapping) and "source_case" not in prev:
        table["problem"] = dict(prev)
    extra = {**case.extra, "optimize": table}
    return dataclasses.replace(case, name=name or f"{case.name}_optimized",
                               extra=MappingProxyType(extra))
