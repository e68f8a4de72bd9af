"""The contact problem of one roll with Weber's load-dependent contact compliance.

Weber's contact compliance depends on the load (logarithmically,
:func:`contact.compliance.weber.weber_compliance`). It is solved by Newton's method on the
contact deformation δ(F): about the current loads F₀, δ ≈ c_s F₀ + c_t (F − F₀) (c_s the
secant, c_t the tangent compliance), i.e. the problem takes the diagonal c_t and the
separation s + (c_s − c_t) F₀; solve (:func:`contact.qp.solve_contact`), linearise again
at the new loads, solve again, until the LTE changes by less than
``LTCAOptions.weber_tolerance`` (default 1e-3 µrad), or its quadratically shrinking steps
foretell a next step ten times smaller; 3–5 solves are typical. The first loads share the
torque evenly over the roll's curve segments (so a roll's result depends on that roll
alone). Where c_t is not well positive (Hertz half-width near the depth) or a load is at
the cap, the secant is used there (the fixed-point iteration).

Weber's formula holds while the Hertz half-width b is well below the depth h
(ln(2h/b) − ν/(2(1−ν)) > 0): loads are capped where b would reach h, i.e.
w′ ≤ π E* h²/(4 R_eq); beyond that a segment is in gross edge contact and its secant
compliance is frozen at the cap (logged).

Public functions
----------------
RollSelection   the data of one roll's contact problem on its selected segments
WeberSolution   the solution, the final problem, iterations and time
even_share      the first loads: the gear torque shared over the curve segments
weber_solve     the Newton iteration on Weber's compliance

References
----------
C. Weber (1949), The deformation of loaded gears and the effect on their load-carrying
capacity; seed §3.2 (p. 78) and Eq. 3.12–3.14.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass
from types import ModuleType

import numpy as np

from contact.compliance.weber import WeberSegments
from contact.errors import NotPositiveDefiniteError
from contact.ltca.options import LTCAOptions
from contact.qp import DEFAULT_TOLERANCE, ContactProblem, ContactSolution, solve_contact
from contact.qp.problem import ProblemScale, mean_of, residuals_and_gaps
from contact.qp.solvers import DEFAULT_SOLVER
from contact.qp.solvers.active_set import PIVOTING_KERNELS, pivoting_thresholds
from geometry.core.kernels import kernels_module

__all__ = ["RollSelection", "WeberSolution", "even_share", "weber_solve"]

log = logging.getLogger(__name__)

#: [1] Newton's step takes Weber's tangent compliance only where it exceeds this share of
#: the secant (else the secant: b near the depth h); the same share bounds every
#: iteration's contact compliance from below (the base problem checked once per roll)
_TANGENT_SHARE = 0.5

#: the block pivoting's iteration cap (:func:`contact.qp.solve_contact`'s default for the
#: ``active_set`` backend)
_PIVOT_ITERATIONS = 50


@dataclass(frozen=True, eq=False)
class RollSelection:
    """The data of one roll's contact problem on its N selected segments.

    Attributes
    ----------
    roll : int
        Roll index (for messages and the problem's name).
    pairs, segments : ndarray (N,) of int
        Pair and segment index of each selected segment (row-major order).
    structural : ndarray (N, N) — [mm/N]
        Compliance of the shells and foundations (without Weber's contact).
    depth : ndarray (N, 2) — [mm]
        Distances from the contact to each member's tooth centreline (Weber's h).
    length, r_eq, moment_arm, separation : ndarray (N,) — [mm]
        Segment length, equivalent radius, moment arm about the gear axis and initial
        separation.
    upper_bound : ndarray (N,) — [N], optional
        Force limits F_max of the elastic–perfectly-plastic segments (``inf`` where none;
        default None: none).
    """

    roll: int
    pairs: np.ndarray
    segments: np.ndarray
    structural: np.ndarray
    depth: np.ndarray
    length: np.ndarray
    r_eq: np.ndarray
    moment_arm: np.ndarray
    separation: np.ndarray
    upper_bound: np.ndarray | None = None


@dataclass(frozen=True, eq=False)
class WeberSolution:
    """The outcome of :func:`weber_solve`.

    Attributes
    ----------
    solution : contact.qp.ContactSolution
        The last solve (``found`` False if a solve failed).
    problem : contact.qp.ContactProblem
        The last problem solved (Weber's compliance linearised at the final loads).
    iterations : int
        Solves that succeeded.
    time : float — [s]
        Build and solve time over the iterations.
    """

    solution: ContactSolution
    problem: ContactProblem
    iterations: int
    time: float


def even_share(gear_torque: float, arms: np.ndarray) -> float:
    """[N] the load per segment that shares ``gear_torque`` [N·mm] evenly over segments
    with moment arms ``arms`` [mm] (Weber's first loads)."""
    return gear_torque / max(float(np.sum(arms)), 1e-12)


def weber_solve(sel: RollSelection, gear_torque: float, first_load: float,
                options: LTCAOptions, modulus: float, *, prior: np.ndarray | None = None,
                name: str = "") -> WeberSolution:
    """One roll's contact problem with Weber's compliance iterated to the loads.

    Parameters
    ----------
    sel : RollSelection
        The roll's selected segments (N).
    gear_torque : float — [N·mm]
    first_load : float — [N]
        The first loads (:func:`even_share`).
    options : LTCAOptions
        ``solver``, ``weber_tolerance`` [µrad], ``max_weber_iterations``, materials.
    modulus : float — [MPa]
        Contact modulus E* of the pair (:func:`geometry.core.hertz.contact_modulus`), for the
        load cap.
    prior : ndarray (N,), optional — [N]
        Forces of a neighbouring solution (NaN where unknown): the solver's warm start.
    name : str
        The problems' name.

    Returns
    -------
    WeberSolution

    Raises
    ------
    contact.errors.ProblemInputError
        The force limits (``sel.upper_bound``) cannot carry the torque.
    """
    e, nu = options.youngs_modulus, options.poisson_ratio
    length, r_eq, depth = sel.length, sel.r_eq, sel.depth
    cap = np.pi * modulus * np.min(depth, axis=1) ** 2 / (4 * r_eq) * length  # [N]
    load = np.minimum(np.full(length.size, first_load), cap)
    start = None if prior is None else _nan_to_zero(prior)
    # the segments' lengths, depths and radii are the same at every iteration: validated
    # once, evaluated at each iteration's loads
    segments = WeberSegments.of(length, depth[:, 0], depth[:, 1], e1=e, nu1=nu, e2=e, nu2=nu,
                                r_eq=r_eq)
    # every iteration's problem is a base problem with a larger diagonal: Weber's secant
    # compliance falls with the load, which never exceeds the cap, and the Newton tangent
    # is taken only where it exceeds half the secant, so each contact compliance is at
    # least half the secant at the cap. The base with that diagonal is checked positive
    # definite once (its Cholesky); each iteration's problem is then so by Weyl's
    # inequality (ContactProblem.with_diagonal), where a Cholesky per iteration cost 60 %
    # of an LTCA's time (issue 60's CPU budget). Where the base is not positive definite,
    # each problem is made and checked as before.
    # (the secant at the cap: finite loads ≥ 0, Weber's secant as compliance(cap) has it)
    floor = _TANGENT_SHARE * segments.secant_tangent(cap)[0]
    try:
        base = ContactProblem(sel.structural + np.diag(floor), sel.separation,
                              sel.moment_arm, gear_torque, name=name,
                              upper_bound=sel.upper_bound)
    except NotPositiveDefiniteError:
        base = None
    diagonal = np.diagonal(sel.structural)  # the structural part of C's diagonal
    # the compiled warm solve where the default solver runs compiled (issue 75): each
    # iteration's problem is the base's with another diagonal and separations, solved from
    # the last forces, without a ContactProblem and a ContactSolution per iteration; the
    # last iteration's are made at the end (the general path where it does not certify)
    warm = _warm_kernels(options.solver) if base is not None else None
    lte_prev = step_prev = None
    sol = problem = None
    last = None  # the last solve's (diagonal, separation, warm start) where compiled
    force = start  # the warm start of the next solve: the last solution's forces
    n_it = time_used = 0
    for w_it in range(1, options.max_weber_iterations + 1):
        # Newton on Weber's δ(F): δ ≈ c_s F₀ + c_t (F − F₀), c_s the secant and c_t the
        # tangent compliance at the loads F₀, i.e. compliance c_t and separation
        # s + (c_s − c_t) F₀; the secant alone where c_t is not well positive (b near the
        # depth h) or the load is at the cap (frozen there)
        cs, ct = segments.secant_tangent(load)  # the loads are finite, in [0, cap]
        newton = (ct > _TANGENT_SHARE * cs) & (load < cap)
        cw = np.where(newton, ct, cs)
        separation = sel.separation + np.where(newton, (cs - ct) * load, 0.0)
        solved = None
        if warm is not None and force is not None:
            solved = _warm_solve(warm, base, diagonal + cw, separation, force)
        if solved is not None:
            F, theta, solve_time, last = solved
            time_used += solve_time
        else:
            last = None
            if base is not None:
                problem = base.with_diagonal(diagonal + cw, separation)
            elif problem is None:
                problem = ContactProblem(sel.structural + np.diag(cw), separation,
                                         sel.moment_arm, gear_torque, name=name,
                                         upper_bound=sel.upper_bound)
            else:  # only C's diagonal and s change: the rest was checked at the first
                problem = problem.with_diagonal(diagonal + cw, separation)
            sol = solve_contact(problem, options.solver, initial=force)
            time_used += sol.solve_time + sol.build_time
            if not sol.found:
                break
            F, theta = sol.force, sol.rotation
        force = F
        load = np.minimum(np.maximum(F, 0.0), cap)
        if log.isEnabledFor(logging.INFO) and np.any(F > cap):
            log.info("roll %d: Weber load cap reached on %d segments", sel.roll,
                     int(np.sum(F > cap)))
        lte = theta * 1e6
        n_it = w_it
        if lte_prev is not None:
            step = abs(lte - lte_prev)
            if _converged(step, step_prev, options.weber_tolerance, newton, load):
                break
            step_prev = step
        lte_prev = lte
    if last is not None:  # the last solve was the compiled one: its problem and solution
        sol, problem, extra = _warm_solution(options.solver, base, F, theta, *last)
        time_used += extra
    return WeberSolution(sol, problem, n_it, time_used)


def _nan_to_zero(prior: np.ndarray) -> np.ndarray:
    """``np.nan_to_num(prior)`` (a new array, NaN → 0) in fewer passes where ``prior`` is
    a float64 array with no infinity (the LTCA's warm starts)."""
    if not (isinstance(prior, np.ndarray) and prior.dtype == np.float64):
        return np.nan_to_num(prior)
    out = prior.copy()
    nan = np.isnan(out)
    out[nan] = 0.0
    if np.isinf(out).any():
        return np.nan_to_num(prior)
    return out


def _warm_kernels(solver) -> ModuleType | None:
    """The compiled warm solve's module where ``solver`` is the default ``active_set``
    and its block pivoting runs compiled (:func:`geometry.core.kernels.kernels_module`),
    else None (every solve by :func:`contact.qp.solve_contact`)."""
    if not (isinstance(solver, str) and solver == DEFAULT_SOLVER):
        return None
    return kernels_module(PIVOTING_KERNELS)


def _warm_solve(kernels: ModuleType, base: ContactProblem, diagonal: np.ndarray,
                separation: np.ndarray, start: np.ndarray
                ) -> tuple[np.ndarray, float, float, tuple] | None:
    """The problem ``base.with_diagonal(diagonal, separation)`` solved from the forces
    ``start`` [N] as :func:`contact.qp.solve_contact` solves it with the default solver
    (the same start sets, block pivoting and certification), compiled
    (:func:`contact.qp.solvers.pivoting_numba.warm_solve`): (F [N], Θ [rad], time [s],
    what :func:`_warm_solution` takes), or None where that solve needs the general path
    (a cold start, the fallback, a polish)."""
    t0 = time.perf_counter()
    sc = base.scale
    # the new problem's scale (ContactProblem.with_diagonal: f₀ and r₀ the base's, δ₀ of
    # the new diagonal) and its block pivoting's thresholds
    scale = ProblemScale(force=sc.force, length=sc.force * mean_of(diagonal),
                         arm=sc.arm)
    f_tol, y_tol, floor = pivoting_thresholds(scale)
    F, theta, its, outcome, certified = kernels.warm_solve(
        base.compliance, diagonal, separation, base.moment_arm, float(base.torque),
        base.upper_bound, base.bounded, base.has_bounds, f_tol, y_tol, floor, start,
        DEFAULT_TOLERANCE, scale.force, scale.length, scale.arm, _PIVOT_ITERATIONS)
    if outcome != kernels.SOLVED or not certified:
        return None
    elapsed = time.perf_counter() - t0
    return F, float(theta), elapsed, (diagonal, separation, start, int(its), elapsed)


def _warm_solution(solver: str, base: ContactProblem, F: np.ndarray, theta: float,
                   diagonal: np.ndarray, separation: np.ndarray, start: np.ndarray,
                   iterations: int, elapsed: float
                   ) -> tuple[ContactSolution, ContactProblem, float]:
    """The last compiled solve's problem and its :class:`ContactSolution`, as
    :func:`contact.qp.solve_contact` gives them (its residuals, slack, status and
    extras); solved again by it where its own certification disagrees (a residual within
    round-off of the tolerance). Returns the solution, the problem and the time [s] of
    that second solve (0 where none)."""
    problem = base.with_diagonal(diagonal, separation)
    res, slack = residuals_and_gaps(problem, F, theta)
    if not all(math.isfinite(v) and v <= DEFAULT_TOLERANCE for v in res.values()):
        sol = solve_contact(problem, solver, initial=start)
        return sol, problem, sol.solve_time + sol.build_time
    return ContactSolution(F, theta, slack, True, "solved", solver, 0.0, elapsed, res,
                           DEFAULT_TOLERANCE, iterations,
                           {"fallback": False, "claimed_success": True}), problem, 0.0


def _converged(step: float, step_prev: float | None, tolerance: float, newton: np.ndarray,
               load: np.ndarray) -> bool:
    """Whether the Weber iteration stops after an LTE step [µrad]: below the tolerance,
    or — Newton's steps shrinking quadratically once close (the last step below 1000
    tolerances) where every loaded segment took it — a next step of about
    step²/(last step) foretold to be ten times below the tolerance."""
    quadratic = (step_prev is not None and step_prev < 1000.0 * tolerance
                 and bool(np.all(newton[load > 0])))
    return step < tolerance or (quadratic and step * step < 0.1 * tolerance * step_prev)
