"""What an optimisation minimises and which engineering limits it must meet.

Each design (a set of variable values) is analysed by :func:`contact.run_analysis` at every
torque and every misalignment of the problem, and summarised by
:func:`contact.study.summary.point_summary` (LTE, edge load share, flank peak pressure,
pattern centre). From these (``docs/optimize.md``):

* **objective terms**, each a mean over torques (weights ``torque_weights``) and
  misalignments, made dimensionless by a reference: LTE peak-to-peak / 10 µrad, edge load
  share / 1 %, flank peak pressure / 1000 MPa, and the pattern's distance from its target
  centre (u*, v*) at the lightest torque, ((u − u*)² + (v − v*)²)/0.1²;
* **constraints** g ≤ 0, the worst misalignment counting, per torque: edge share ≤
  ``max_edge_share``, flank peak pressure ≤ ``max_flank_pressure``, LTE peak-to-peak in
  ``lte_peak_to_peak_range``, and, if given, the LTE mean in ``lte_mean_range``; each g is
  the excess over its limit divided by a scale (1 % share, 100 MPa, 5 µrad, 10 % of the
  mean limit);
* the **objective** f = Σ wᵢ termᵢ + ``penalty`` Σ max(0, g)²: a quadratic exterior
  penalty (Fiacco & McCormick 1968; Nocedal & Wright, *Numerical Optimization*, 2nd ed.,
  §17.1), so that a feasible design always beats an infeasible one of similar terms.

A design whose analysis fails (e.g. the flanks separate) gets f = :data:`FAILED_OBJECTIVE`
and NaN constraints (infeasible).

Public functions
----------------
OptimizeProblem     torques, misalignments, limits, weights (the ``[optimize]`` table)
problem_from_table  the problem from an ``[optimize]`` mapping (file units)
TERM_NAMES          objective term names
constraint_names    the constraint names of a problem
Evaluation          what one design's analyses give
evaluate_design     analyse one design (runs on a Dask worker)
score               terms, constraints and objective of a design's metrics
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from contact.ltca import LTCAOptions
from geometry.case import Case
from geometry.core.errors import InputError, raise_if_interrupted
from geometry.core.validation import known_fields, real
from geometry.pair.assembly import Misalignment

__all__ = ["FAILED_OBJECTIVE", "TERM_NAMES", "Evaluation", "OptimizeProblem",
           "constraint_names", "evaluate_design", "problem_from_table", "score"]

log = logging.getLogger(__name__)

#: objective of a design whose analysis failed
FAILED_OBJECTIVE = 1e6
#: objective terms, in the order of the log's ``term`` dim
TERM_NAMES = ("lte_peak_to_peak", "edge_load_share", "pressure_max_flank", "pattern_offset")
_TERM_REF = {"lte_peak_to_peak": 10.0, "edge_load_share": 0.01, "pressure_max_flank": 1000.0,
             "pattern_offset": 0.1}
_SCALE = {"edge": 0.01, "pressure": 100.0, "lte": 5.0}


@dataclass(frozen=True)
class OptimizeProblem:
    """Torques, misalignments, limits and weights of an optimisation (``[optimize]``).

    Parameters
    ----------
    torque : tuple of float — [N·m]
        Pinion torques, ascending; default ``()``: the case's torques of the flank
        (:func:`contact.pipeline.flank_torques`, taken by :meth:`with_case`), as ``ltca
        optimize`` without ``--torque`` or an ``[optimize]`` torque (api83; before, the
        seed's Table 3.1 50, 250, 500 N·m whatever the case). Without torques the
        per-torque fields take one value (for every torque) and ``lte_mean_range`` none.
    misalignments : tuple of Misalignment
        Analysed assemblies; default the case's own misalignment.
    max_edge_share : tuple of float — [1]
        Per torque, largest share of the torque carried by edge contact; default 1 at every
        torque (no limit). A single value applies to every torque.
    max_flank_pressure : tuple of float — [MPa]
        Per torque, largest flank peak pressure; default inf.
    lte_peak_to_peak_range : (float, float) — [µrad]
        Range of the LTE peak-to-peak at every torque; default (0, inf).
    lte_mean_range : tuple of (float, float) or None — [µrad]
        Per torque, range of the LTE mean; None: no limit.
    weights : mapping term → float — [1]
        Weights of :data:`TERM_NAMES` (each term made dimensionless by its reference);
        default 1, 1, 1, 0.2.
    torque_weights : tuple of float — [1]
        Weights of the torques in the terms (normalised); default equal.
    pattern_target : (float, float) — [1]
        Target pattern centre (u toe→heel, v root→tip of the gear flank); default (0.5, 0.5).
    penalty : float — [1]
        Weight of the squared (normalised) constraint violations; default 100.
    options : contact.ltca.LTCAOptions
        Analysis settings (coarser rolls/segments make an optimisation faster).
    flank : str or None
        ``"drive"``/``"coast"``.

    Raises
    ------
    InputError
        A field out of its range (named): no torque or torques not ascending, limits of
        the wrong length or out of range, torque weights all 0, a reversed range, an
        unknown term in ``weights``.
    """

    torque: tuple[float, ...] = ()
    misalignments: tuple[Misalignment, ...] = ()
    max_edge_share: tuple[float, ...] = ()
    max_flank_pressure: tuple[float, ...] = ()
    lte_peak_to_peak_range: tuple[float, float] = (0.0, math.inf)
    lte_mean_range: tuple[tuple[float, float], ...] | None = None
    weights: Mapping[str, float] = field(default_factory=lambda: {
        "lte_peak_to_peak": 1.0, "edge_load_share": 1.0, "pressure_max_flank": 1.0,
        "pattern_offset": 0.2})
    torque_weights: tuple[float, ...] = ()
    pattern_target: tuple[float, float] = (0.5, 0.5)
    penalty: float = 100.0
    options: LTCAOptions = field(default_factory=LTCAOptions)
    flank: str | None = None

    def __post_init__(self) -> None:
        if isinstance(self.torque, (int, float)):  # one torque given as a number
            object.__setattr__(self, "torque", (self.torque,))
        try:
            nt = len(self.torque)
        except TypeError:
            raise InputError("optimize.torque: must be a sequence of pinion torques [N m], "
                             f"got {self.torque!r}") from None
        torque = tuple(real("optimize.torque", t, unit="N m", low=0.0, low_open=True)
                       for t in self.torque)
        if list(torque) != sorted(torque):
            raise InputError(f"optimize.torque: must be ascending, got {list(torque)}")
        object.__setattr__(self, "torque", torque)

        def per_torque(name, value, default, unit, low, high):
            vals = tuple(value) if value else (default,)
            if nt == 0:  # the case's torques, taken by with_case: one value for all
                if len(vals) != 1:
                    raise InputError(f"optimize.{name}: give one value, or torque= with one "
                                     f"value per torque; without torque= the torques are "
                                     f"the case's (with_case), got {len(vals)} values")
                return tuple(math.inf if v == math.inf else
                             real(f"optimize.{name}", v, unit=unit, low=low, high=high)
                             for v in vals) if value else ()
            if len(vals) == 1:
                vals = vals * nt
            if len(vals) != nt:
                raise InputError(f"optimize.{name}: give one value or one per torque ({nt}), "
                                 f"got {len(vals)}")
            return tuple(math.inf if v == math.inf else  # inf: no limit
                         real(f"optimize.{name}", v, unit=unit, low=low, high=high)
                         for v in vals)

        object.__setattr__(self, "max_edge_share",
                           per_torque("max_edge_share", self.max_edge_share, 1.0, "1", 0.0, 1.0))
        object.__setattr__(self, "max_flank_pressure", per_torque(
            "max_flank_pressure", self.max_flank_pressure, math.inf, "MPa", 0.0, None))
        object.__setattr__(self, "torque_weights", per_torque(
            "torque_weights", self.torque_weights, 1.0, "1", 0.0, None))
        if self.torque_weights and sum(self.torque_weights) <= 0:
            raise InputError("optimize.torque_weights: must not all be 0")
        lo, hi = (math.inf if v == math.inf else
                  real("optimize.lte_peak_to_peak_range", v, unit="urad", low=0.0)
                  for v in self.lte_peak_to_peak_range)
        if not lo < hi:
            raise InputError(f"optimize.lte_peak_to_peak_range: must be low < high, got "
                             f"({lo:g}, {hi:g}) urad")
        object.__setattr__(self, "lte_peak_to_peak_range", (lo, hi))
        if self.lte_mean_range is not None:
            if nt == 0:
                raise InputError("optimize.lte_mean_range: one (low, high) pair per torque: "
                                 "give torque= as well (without it the torques are the "
                                 "case's, taken by with_case)")
            rng = tuple(tuple(r) for r in self.lte_mean_range)
            if len(rng) != nt or any(len(r) != 2 or not 0 <= r[0] < r[1] for r in rng):
                raise InputError(f"optimize.lte_mean_range: give one (low, high) pair per "
                                 f"torque ({nt}) with 0 <= low < high, got {self.lte_mean_range!r}")
            object.__setattr__(self, "lte_mean_range", rng)
        unknown = sorted(set(self.weights) - set(TERM_NAMES))
        if unknown:
            raise InputError(f"optimize.weights.{unknown[0]}: unknown term; accepted: "
                             f"{', '.join(TERM_NAMES)}")
        w = {t: 0.0 for t in TERM_NAMES} | {
            k: real(f"optimize.weights.{k}", v, unit="1", low=0.0) for k, v in self.weights.items()}
        object.__setattr__(self, "weights", w)
        for v in self.pattern_target:
            real("optimize.pattern_target", v, unit="1", low=0.0, high=1.0)
        real("optimize.penalty", self.penalty, unit="1", low=0.0)
        if self.flank not in (None, "drive", "coast"):
            raise InputError(f"optimize.flank: must be 'drive' or 'coast', got {self.flank!r}")

    def with_case(self, case: Case) -> OptimizeProblem:
        """The problem with the case's misalignment where none is given, and the case's
        torques of the problem's flank where none are given
        (:func:`contact.pipeline.flank_torques`: the ``[operating]`` torques, the coast
        flank's up to its coast design torque; as ``ltca optimize``)."""
        changes: dict = {}
        if not self.misalignments:
            changes["misalignments"] = (case.misalignment,)
        if not self.torque:
            from contact.pipeline import flank_torques

            changes["torque"] = tuple(sorted(flank_torques(case, self.flank)[0]))
        return dataclasses.replace(self, **changes) if changes else self


def constraint_names(problem: OptimizeProblem) -> tuple[str, ...]:
    """Names of the problem's constraints (the log's ``constraint`` dim), per torque."""
    out = []
    for t in problem.torque:
        tag = f"{t:g}Nm"
        out += [f"edge_share_{tag}", f"flank_pressure_{tag}", f"lte_pp_low_{tag}",
                f"lte_pp_high_{tag}"]
        if problem.lte_mean_range is not None:
            out += [f"lte_mean_low_{tag}", f"lte_mean_high_{tag}"]
    return tuple(out)


_MIS_KEYS = {"dE": "delta_E", "dP": "delta_P", "dG": "delta_G", "dSigma": "delta_Sigma"}


def problem_from_table(table: Mapping, **override) -> tuple[OptimizeProblem, dict]:
    """The problem and the variable bounds of an ``[optimize]`` table (file units).

    Parameters
    ----------
    table : mapping
        Keys: ``torque`` [N·m], ``misalignments`` (list of tables with ``dE``, ``dP``,
        ``dG`` [mm], ``dSigma`` [deg]), ``max_edge_share`` [1], ``max_flank_pressure``
        [MPa], ``lte_peak_to_peak_range`` [µrad], ``lte_mean_range`` [µrad], ``weights``,
        ``torque_weights``, ``pattern_target``, ``penalty``, ``variables`` (table name →
        [low, high] in the variable's unit), ``method``, ``max_evaluations``,
        ``popsize``, ``seed``, ``relief_start``, ``start`` (table name → start value in
        the variable's unit, replacing the case's own), ``rolls_per_cycle`` and
        ``segments`` (the loaded analysis's sampling, :class:`contact.ltca.LTCAOptions`).
    **override
        Problem fields that replace the table's (e.g. from the command line); ``options``
        as a mapping of :class:`contact.ltca.LTCAOptions` fields is laid over the table's
        sampling (an ``LTCAOptions`` replaces it). A ``torque`` among the table's own
        keeps the per-torque limits the table gives those torques (:data:`PER_TORQUE_FIELDS`).

    Returns
    -------
    problem : OptimizeProblem
    run : dict
        ``variables`` (name → (low, high)) and the optimiser options found.

    Raises
    ------
    InputError
        An unknown key (listing the accepted ones) or a bad value.
    """
    keys = {"torque", "misalignments", "max_edge_share", "max_flank_pressure",
            "lte_peak_to_peak_range", "lte_mean_range", "weights", "torque_weights",
            "pattern_target", "penalty", "variables", "method", "max_evaluations",
            "popsize", "seed", "relief_start", "start", "rolls_per_cycle", "segments"}
    known_fields("optimize", table, sorted(keys))
    table = _per_torque_of(table, override.get("torque"), override)
    kw: dict = {}
    for k in ("torque", "max_edge_share", "max_flank_pressure", "torque_weights"):
        if k in table:
            v = table[k]
            kw[k] = tuple(v) if isinstance(v, (list, tuple)) else (v,)
    for k in ("lte_peak_to_peak_range", "pattern_target"):
        if k in table:
            kw[k] = tuple(table[k])
    if "lte_mean_range" in table:
        kw["lte_mean_range"] = tuple(tuple(r) for r in table["lte_mean_range"])
    if "weights" in table:
        kw["weights"] = dict(table["weights"])
    if "penalty" in table:
        kw["penalty"] = table["penalty"]
    if "misalignments" in table:
        mis = []
        for i, m in enumerate(table["misalignments"]):
            bad = sorted(set(m) - set(_MIS_KEYS))
            if bad:
                raise InputError(f"optimize.misalignments[{i}].{bad[0]}: unknown; accepted: "
                                 f"{', '.join(_MIS_KEYS)}")
            vals = {_MIS_KEYS[k]: (math.radians(v) if k == "dSigma" else v)
                    for k, v in m.items()}
            mis.append(Misalignment(**vals))
        kw["misalignments"] = tuple(mis)
    sampling = {k: table[k] for k in ("rolls_per_cycle", "segments") if k in table}
    for k, v in sampling.items():
        if isinstance(v, bool) or not isinstance(v, int):
            raise InputError(f"optimize.{k}: must be an integer, got {v!r}")
    options = override.get("options")
    if isinstance(options, Mapping):  # command-line analysis options over the table's
        override = {**override, "options": LTCAOptions(**(sampling | dict(options)))}
    elif sampling:
        kw["options"] = LTCAOptions(**sampling)
    kw |= {k: v for k, v in override.items() if v is not None}
    problem = OptimizeProblem(**kw)
    run = {k: table[k] for k in ("method", "max_evaluations", "popsize", "seed",
                                 "relief_start") if k in table}
    start = table.get("start", {})
    if not isinstance(start, Mapping):
        raise InputError("optimize.start: must be a table name = value")
    run["start"] = dict(start)
    variables = table.get("variables", {})
    if not isinstance(variables, Mapping):
        raise InputError("optimize.variables: must be a table name = [low, high]")
    run["variables"] = {}
    for name, pair in variables.items():
        if not isinstance(pair, (list, tuple)) or len(pair) != 2:
            raise InputError(f"optimize.variables.{name}: must be [low, high], got {pair!r}")
        run["variables"][name] = (float(pair[0]), float(pair[1]))
    return problem, run


#: the [optimize] fields given one entry per torque of the table's ``torque``
PER_TORQUE_FIELDS = ("max_edge_share", "max_flank_pressure", "torque_weights",
                     "lte_mean_range")


def _per_torque_of(table: Mapping, torque, override: Mapping) -> dict:
    """The table with its per-torque fields (:data:`PER_TORQUE_FIELDS`) reduced to the
    torques of ``torque`` where these replace the table's own: each kept torque keeps the
    limits the table gives it (``--torque 50 250`` on a table for 50, 250, 500 N·m keeps the
    first two limits). A field of one value, or replaced by ``override``, stays as it is.

    Raises
    ------
    InputError
        A per-torque field where a torque of ``torque`` is not among the table's: which
        field, and the option that gives it.
    """
    table = dict(table)
    if torque is None or "torque" not in table:
        return table
    own = table["torque"]
    own = tuple(float(t) for t in (own if isinstance(own, (list, tuple)) else (own,)))
    new = tuple(float(t) for t in torque)
    options = {"max_edge_share": "--max-edge-share", "max_flank_pressure":
               "--max-flank-pressure"}
    for name in PER_TORQUE_FIELDS:
        v = table.get(name)
        if (override.get(name) is not None or not isinstance(v, (list, tuple))
                or len(v) != len(own) or len(own) == 1 or own == new):
            continue
        missing = [t for t in new if not any(math.isclose(t, o, rel_tol=1e-9) for o in own)]
        if missing:
            how = (f"give {options[name]}" if name in options else
                   f"edit the [optimize] table's {name}")
            raise InputError(
                f"optimize.{name}: the table gives one per torque of its own "
                f"({', '.join(f'{t:g}' for t in own)} N·m), not for "
                f"{', '.join(f'{t:g}' for t in missing)} N·m: {how} for the torques "
                "analysed, or choose among the table's torques")
        table[name] = [v[next(i for i, o in enumerate(own)
                              if math.isclose(t, o, rel_tol=1e-9))] for t in new]
    return table


@dataclass(frozen=True)
class Evaluation:
    """One design's analyses: metrics per (misalignment, torque), terms, constraints."""

    index: int
    x: np.ndarray  # (n_var,) file units
    status: int  # 0 ok, 1 some roll uncertified, 2 failed
    reason: str
    metrics: dict[str, np.ndarray]  # name → (n_mis, n_torque)
    terms: np.ndarray  # (n_term,) dimensionless, unweighted
    constraints: np.ndarray  # (n_con,) normalised, ≤ 0 feasible; NaN if failed
    objective: float
    seconds: float

    @property
    def feasible(self) -> bool:
        c = self.constraints
        return bool(self.status < 2 and not np.any(np.isnan(c)) and np.all(c <= 0.0))


METRICS = ("lte_mean", "lte_peak_to_peak", "edge_load_share", "pressure_max_flank",
           "pressure_max_edge", "pattern_centre_u", "pattern_centre_v")


def score(problem: OptimizeProblem, m: dict[str, np.ndarray]):
    """Objective terms, constraints and objective of a design's metrics (module docstring).

    Parameters
    ----------
    problem : OptimizeProblem
    m : dict of str → ndarray (n_mis, n_torque)
        :data:`METRICS` per misalignment and torque (LTE [µrad], shares [1], pressures
        [MPa], pattern centre [1]).

    Returns
    -------
    terms : ndarray (n_term,)
        Dimensionless, unweighted (:data:`TERM_NAMES`).
    g : ndarray (n_con,)
        Normalised constraints (:func:`constraint_names`), ≤ 0 met; a NaN metric gives inf.
    f : float
        The objective, weighted terms plus the quadratic exterior penalty (Nocedal &
        Wright, *Numerical Optimization*, 2nd ed., §17.1).
    """
    tw = np.asarray(problem.torque_weights) / sum(problem.torque_weights)
    terms = np.array([
        float(np.mean(m["lte_peak_to_peak"] @ tw)) / _TERM_REF["lte_peak_to_peak"],
        float(np.mean(m["edge_load_share"] @ tw)) / _TERM_REF["edge_load_share"],
        float(np.mean(m["pressure_max_flank"] @ tw)) / _TERM_REF["pressure_max_flank"],
        float(np.mean((m["pattern_centre_u"][:, 0] - problem.pattern_target[0]) ** 2
                      + (m["pattern_centre_v"][:, 0] - problem.pattern_target[1]) ** 2))
        / _TERM_REF["pattern_offset"] ** 2,
    ])
    worst = {k: np.max(v, axis=0) for k, v in m.items()}
    least = {k: np.min(v, axis=0) for k, v in m.items()}
    lo, hi = problem.lte_peak_to_peak_range
    g = []
    for it in range(len(problem.torque)):
        g += [(worst["edge_load_share"][it] - problem.max_edge_share[it]) / _SCALE["edge"],
              (worst["pressure_max_flank"][it] - problem.max_flank_pressure[it])
              / _SCALE["pressure"],
              (lo - least["lte_peak_to_peak"][it]) / _SCALE["lte"],
              (worst["lte_peak_to_peak"][it] - hi) / _SCALE["lte"]]
        if problem.lte_mean_range is not None:
            mlo, mhi = problem.lte_mean_range[it]
            g += [(mlo - least["lte_mean"][it]) / (0.1 * mlo if mlo > 0 else 10.0),
                  (worst["lte_mean"][it] - mhi) / (0.1 * mhi)]
    g = np.asarray(g, float)
    g = np.where(np.isnan(g), np.inf, g)  # a NaN summary cannot be shown feasible
    w = np.array([problem.weights[t] for t in TERM_NAMES])
    with np.errstate(invalid="ignore"):
        f = float(w @ np.nan_to_num(terms, nan=FAILED_OBJECTIVE)
                  + problem.penalty * np.sum(np.square(np.clip(g, 0.0, 1e3))))
    return terms, g, f


def evaluate_design(shared, index: int, x) -> Evaluation:
    """Analyse one design at every misalignment and torque (runs on a Dask worker).

    Parameters
    ----------
    shared : contact.optimize.run.SharedDesign
        Case, problem and variable names (scattered once to every worker).
    index : int
        The evaluation's number.
    x : array_like (n_var,)
        Variable values [file units].

    Returns
    -------
    Evaluation
        Never raises for a failing design: status 2, ``reason`` the error,
        f = :data:`FAILED_OBJECTIVE`.
    """
    import time

    from contact.chain import AnalysisChain
    from contact.optimize.variables import case_at
    from contact.pipeline import run_analysis
    from contact.study.summary import point_summary

    t0 = time.perf_counter()
    problem = shared.problem
    x = np.asarray(x, float)
    nm, nt = len(problem.misalignments), len(problem.torque)
    metrics = {k: np.full((nm, nt), np.nan) for k in METRICS}
    status = 0
    try:
        if shared.start is not None and np.array_equal(x, shared.start):
            case = shared.case  # the start design is the case as given, not rebuilt
        else:
            case = case_at(shared.case, shared.pinion_flank, shared.names, x,
                           relief_start=shared.relief_start, basic=shared.basic)
        for im, mis in enumerate(problem.misalignments):
            c = dataclasses.replace(case, misalignment=mis)
            tree = run_analysis(c, list(problem.torque), flank=problem.flank,
                                options=problem.options, deviations=False,
                                # the objective needs no efficiency, root stress or rating
                                steps=AnalysisChain.contact_only().with_mesh_interface())
            s = point_summary(tree, c)
            for k in METRICS:
                metrics[k][im] = s[k]
            if not np.all(s["certified"] > 0):
                status = 1
        terms, g, f = score(problem, metrics)
        reason = ""
    except Exception as exc:  # one failing design never stops an optimisation
        raise_if_interrupted(exc)
        log.info("design %d %s failed: %s", index, x.tolist(), exc)
        status, reason = 2, f"{type(exc).__name__}: {exc}".splitlines()[0]
        terms = np.full(len(TERM_NAMES), np.nan)
        g = np.full(len(constraint_names(problem)), np.nan)
        f = FAILED_OBJECTIVE
    return Evaluation(index, x, status, reason, metrics, terms, g, f,
                      time.perf_counter() - t0)
