"""One registry of interchangeable solvers for the loaded-contact problem.

``available_solvers()`` lists every backend that works here: our own exact solver
``active_set`` (the default and the reference), each installed ``qpsolvers`` backend by
its qpsolvers name, ``cvxpy`` and ``cvxpy:NAME``, the backends of installed plug-ins (the
entry-point group :data:`ENTRY_POINT_GROUP`) and those a user registered in this process
(:func:`register_backend`). ``solve_contact(problem, solver=NAME)`` runs one, optionally
polishes its answer (the reduced KKT system on its contact set, solved exactly) and
certifies the result with our own residuals: ``found`` is never taken from a backend.
Wherever a solver is chosen by name (``solve_contact``, ``LTCAOptions.solver``) a
:class:`Backend` or a plain solve function is accepted too (docs/extending.md).

Modelled on qpsolvers' registry (Caron et al.): backends register under
try/except so a missing package removes a backend instead of breaking import.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from contact.errors import SolverNotFoundError
from contact.qp.problem import (
    DEFAULT_TOLERANCE,
    RESIDUALS,
    ContactProblem,
    ContactSolution,
    contact_residuals,
    residuals_and_gaps,
    solve_on_contact_set,
)
from contact.qp.solvers.active_set import block_pivoting
from contact.qp.solvers.backend import ACCURACY_LEVELS, Backend, RawResult
from geometry.core.caches import memoised
from geometry.core.errors import InputError, PluginError, raise_if_interrupted
from geometry.core.registries import (
    callable_name,
    check_model_name,
    entry_point_objects,
    keyword_parameters,
)

__all__ = [
    "DEFAULT_SOLVER",
    "ENTRY_POINT_GROUP",
    "KNOWN_BACKENDS",
    "SOLVERS_EXTRA",
    "Backend",
    "RawResult",
    "SolverLike",
    "as_backend",
    "available_solvers",
    "get_backend",
    "missing_backends",
    "polish",
    "register_backend",
    "solve_contact",
    "solver_name",
    "unregister_backend",
]

log = logging.getLogger(__name__)

#: The default solver: our own exact block-pivoting method.
DEFAULT_SOLVER = "active_set"


def _solve_active_set(
    problem: ContactProblem,
    *,
    accuracy: str = "high",
    initial: np.ndarray | None = None,
    initial_active_set: np.ndarray | None = None,
    max_iterations: int = 50,
    fallback: bool = True,
) -> RawResult:
    del accuracy  # exact method: the accuracy level does not apply
    initial_upper_set = None
    if initial_active_set is None and initial is not None:
        init = np.asarray(initial)
        initial_active_set = init > 0
        if problem.has_bounds:
            # a warm start's segments at (or beyond) their limits start at them
            initial_upper_set = problem.bounded & (
                init >= problem.upper_bound * (1.0 - 1e-9))
    out = block_pivoting(
        problem,
        initial_active_set=initial_active_set,
        initial_upper_set=initial_upper_set,
        max_iterations=max_iterations,
        fallback=fallback,
    )
    return RawResult(
        out["force"],
        out["rotation"],
        out["converged"],
        out["status"],
        0.0,
        out["solve_time"],
        out["iterations"],
        {"fallback": out["fallback"]},
    )


@memoised(maxsize=None)
def _builtin() -> dict[str, Backend]:
    """The toolkit's own backend (no third-party import)."""
    return {
        DEFAULT_SOLVER: Backend(
            DEFAULT_SOLVER,
            "active-set",
            _solve_active_set,
            True,
            "exact block principal pivoting on the KKT system (Cholesky per contact set), "
            "guarded by a primal active-set fallback",
        )
    }


#: the entry-point group in which an installed distribution advertises solver backends:
#: each entry is a :class:`Backend` or a solve function (registered under the entry's
#: name), e.g. in the plug-in's ``pyproject.toml``::
#:
#:     [project.entry-points."hypoid_ltca.solvers"]
#:     my_solver = "my_package.contact:solve"
ENTRY_POINT_GROUP = "hypoid_ltca.solvers"

#: what may stand where a solver is chosen: a registered name, a Backend, a solve function
SolverLike = str | Backend | Callable[..., Any]

#: backends registered in this process by :func:`register_backend` (not a cache:
#: ``clear_caches`` keeps them)
_USER: dict[str, Backend] = {}


@memoised(maxsize=None)
def _discovered() -> dict[str, Backend]:
    """The third-party backends found installed: qpsolvers', cvxpy's, the plug-ins'."""
    reg: dict[str, Backend] = {}
    try:
        from contact.qp.solvers import qpsolvers_backend

        reg.update({b.name: b for b in qpsolvers_backend.backends()})
    except Exception as exc:  # pragma: no cover - a broken install must not break the toolkit
        log.warning("qpsolvers backends unavailable: %s", exc)
    try:
        from contact.qp.solvers import cvxpy_backend

        reg.update({b.name: b for b in cvxpy_backend.backends()})
    except Exception as exc:  # pragma: no cover
        log.warning("cvxpy backends unavailable: %s", exc)
    for name, obj in entry_point_objects(ENTRY_POINT_GROUP).items():
        try:
            reg[name] = obj if isinstance(obj, Backend) else as_backend(obj, name=name)
        except InputError as exc:
            log.warning("entry point %s of group %s is not a solver backend: %s", name,
                        ENTRY_POINT_GROUP, exc)
    return reg


def _registry() -> dict[str, Backend]:
    """Every backend by name: ours, then the installed ones, then the user's."""
    return {**_builtin(), **_discovered(), **_USER}


def available_solvers() -> list[str]:
    """Names of every solver backend that works in this environment.

    Returns
    -------
    list of str
        ``active_set`` first, then qpsolvers backends, then ``cvxpy`` and ``cvxpy:NAME``,
        the plug-ins' backends (:data:`ENTRY_POINT_GROUP`) and those registered with
        :func:`register_backend`.
    """
    return list(_registry())


def _adapted(function: Callable[..., Any], name: str) -> Callable[..., RawResult]:
    """A user's solve function as the registry calls backends: ``solve(problem, *,
    accuracy, initial, **options) -> RawResult``. The function is passed only the keywords
    it declares (all of them if it takes ``**kwargs``) and may return a :class:`RawResult`
    or ``(force [N], rotation [rad])``."""
    required, optional, takes_any = keyword_parameters("solve", function, positional=1)
    unknown = sorted(set(required) - {"accuracy", "initial"})
    if unknown:
        raise InputError(f"solve: parameter(s) {unknown} of {callable_name(function)} have no "
                         "default; a solver is passed the problem, accuracy, initial and "
                         "the caller's options only")
    accepted = {*required, *optional}

    def solve(problem: ContactProblem, **keywords: Any) -> RawResult:
        passed = keywords if takes_any else {k: v for k, v in keywords.items()
                                             if k in accepted}
        t0 = time.perf_counter()
        out = function(problem, **passed)
        elapsed = time.perf_counter() - t0
        if isinstance(out, RawResult):
            return out
        try:
            force, rotation = out
        except (TypeError, ValueError):
            raise PluginError(f"solver {name!r} returned {type(out).__name__} {_short(out)}; "
                              "a solver returns a RawResult or (force [N], rotation [rad]) "
                              "(docs/extending.md)") from None
        try:
            force = None if force is None else np.asarray(force, float)
            rotation = None if rotation is None else float(rotation)
        except (TypeError, ValueError):
            raise PluginError(f"solver {name!r} returned force {_short(force)} and rotation "
                              f"{_short(rotation)}; a solver returns F [N], one number per "
                              "segment, and one rotation [rad] (docs/extending.md)") from None
        return RawResult(force, rotation, True, f"user backend {name!r} returned", 0.0,
                         elapsed)

    return solve


def _short(value: Any, width: int = 60) -> str:
    """``repr(value)`` cut to ``width`` characters, for messages about what a plug-in
    returned."""
    text = repr(value)
    return text if len(text) <= width else text[:width - 1] + "…"


def as_backend(solver: SolverLike, *, name: str | None = None, family: str = "user",
               warm_start: bool = False, description: str = "") -> Backend:
    """A :class:`Backend` of a registered name, a Backend, or a solve function.

    Parameters
    ----------
    solver : str, Backend or callable
        A name (looked up: :func:`get_backend`), a Backend (returned as it is) or a solve
        function ``solve(problem, **keywords)`` of a :class:`~contact.qp.ContactProblem`
        (physical units: ``problem.compliance`` C [mm/N], ``problem.separation`` s [mm],
        ``problem.moment_arm`` R [mm], ``problem.torque`` T [N·mm]; the scaled form
        ``problem.scaled()``) returning a :class:`RawResult` or ``(F [N] (N,), Θ [rad])``.
        Of the keywords ``accuracy`` (``"high"``, ``"default"``, ``"low"``), ``initial``
        (a warm start F [N] or None) and the caller's options it is passed those it
        declares.
    name : str, optional
        The function's name in results (default its ``__name__``).
    family, warm_start, description
        As :class:`Backend` (a function is asked for a warm start only with
        ``warm_start=True``).

    Returns
    -------
    Backend

    Raises
    ------
    InputError
        A function whose signature cannot take the problem by position and the keywords
        by name, or a bad name.
    SolverNotFoundError
        An unknown name.
    """
    if isinstance(solver, Backend):
        return solver
    if isinstance(solver, str):
        return get_backend(solver)
    label = check_model_name("name", name if name is not None else callable_name(solver))
    return Backend(label, family, _adapted(solver, label), bool(warm_start),
                   description or f"user solve function {label}")


def solver_name(solver: SolverLike) -> str:
    """The name a solver is recorded by (results' ``solver`` attribute): the name itself,
    the Backend's name, or the function's name (:func:`as_backend`)."""
    if isinstance(solver, str):
        return solver
    if isinstance(solver, Backend):
        return solver.name
    return callable_name(solver)


def register_backend(name: str, solve: Callable[..., Any] | Backend, *,
                     family: str = "user", warm_start: bool = False, description: str = "",
                     replace: bool = False) -> Backend:
    """Register a solver backend under ``name`` for this process.

    After it, ``name`` is a solver like any other: ``solve_contact(problem, name)``,
    ``LTCAOptions(solver=name)``, ``ltca compare-solvers --solvers name`` (in the same
    process), listed by :func:`available_solvers`, certified by the toolkit's own
    residuals. To make a backend available to every process (``ltca run --solver``, the
    workers of a study), advertise it in the entry-point group :data:`ENTRY_POINT_GROUP`
    of an installed package instead (docs/extending.md).

    Parameters
    ----------
    name : str
        The registry name (no spaces).
    solve : callable or Backend
        The solve function (:func:`as_backend` says what it is given and may return) or a
        ready :class:`Backend` (its own name is replaced by ``name``).
    family : str
        Algorithm family for reports (``active-set``, ``interior-point``, ``ADMM`` …;
        default ``user``).
    warm_start : bool
        Pass the previous roll's forces as ``initial`` (default False).
    description : str
    replace : bool
        Allow replacing a backend registered earlier under ``name`` with this function
        (default False). The toolkit's ``active_set`` is never replaced.

    Returns
    -------
    Backend
        What was registered.

    Raises
    ------
    InputError
        A bad name or solve function, or a name already taken (the message names it).
    """
    check_model_name("name", name)
    if name == DEFAULT_SOLVER:
        raise InputError(f"name: {DEFAULT_SOLVER!r} is the toolkit's reference solver and "
                         "cannot be replaced; register under another name")
    taken = name in _USER or (name in _discovered())
    if taken and not replace:
        raise InputError(f"name: a solver {name!r} is registered already; pass "
                         "replace=True to replace it or choose another name")
    if isinstance(solve, Backend):
        backend = dataclasses.replace(solve, name=name)
    else:
        backend = as_backend(solve, name=name, family=family, warm_start=warm_start,
                             description=description)
    _USER[name] = backend
    return backend


def unregister_backend(name: str) -> None:
    """Remove a backend registered with :func:`register_backend` (nothing if none).

    Parameters
    ----------
    name : str
        The name it was registered under.

    Raises
    ------
    InputError
        ``name`` is not a name of a backend registered with :func:`register_backend`.
    """
    if name not in _USER:
        raise InputError(f"name: {name!r} was not registered with register_backend "
                         f"(registered: {sorted(_USER)})")
    del _USER[name]


def get_backend(name: SolverLike) -> Backend:
    """The registered :class:`Backend` for ``name``.

    The default, ``active_set``, is the toolkit's own and is returned without importing
    the third-party backends (qpsolvers and cvxpy with their solvers: ~0.7 s of CPU, once
    per process — every study worker's, every ``ltca run``'s); so are backends a user
    registered; any other name loads them.

    Parameters
    ----------
    name : str, Backend or callable
        A registered name; a Backend or a solve function is returned as a Backend
        (:func:`as_backend`).

    Raises
    ------
    SolverNotFoundError
        Unknown or uninstalled name; the message lists the available solvers.
    InputError
        A solve function whose signature does not fit (:func:`as_backend`).
    """
    if not isinstance(name, str):
        if not (isinstance(name, Backend) or callable(name)):
            raise InputError("solver: must be a registered solver's name "
                             f"({', '.join(available_solvers())}), a Backend or a solve "
                             f"function, got {type(name).__name__} {name!r}")
        return as_backend(name)
    if name == DEFAULT_SOLVER:
        return _builtin()[name]
    if name in _USER:
        return _USER[name]
    reg = _registry()
    if name not in reg:
        missing = missing_backends()
        hint = (f"{name!r} is an optional backend: {missing[name]}" if name in missing
                else "qpsolvers backends install from PyPI by their package names; the "
                f"open-source ones with {SOLVERS_EXTRA}")
        raise SolverNotFoundError(
            f"solver: {name!r} is not available; available: {', '.join(reg)}. {hint}."
        )
    return reg[name]


#: the open-source qpsolvers backends that install from PyPI: registry name → the
#: distribution that provides it. The design card's (clarabel, osqp) and cvxopt (CHOLMOD
#: for the FE models) are required by the toolkit; the others are the ``solvers`` extra
#: (pyproject.toml); scs and highspy come with cvxpy too.
KNOWN_BACKENDS: dict[str, str] = {
    "clarabel": "clarabel",
    "cvxopt": "cvxopt",
    "daqp": "daqp",
    "ecos": "ecos",
    "highs": "highspy",
    "osqp": "osqp",
    "piqp": "piqp",
    "proxqp": "proxsuite",
    "qpalm": "qpalm",
    "quadprog": "quadprog",
    "scs": "scs",
}

#: the line that installs every optional backend: for an installed package and for a
#: clone of the repository (where the package name would fetch the release from PyPI
#: instead of installing the clone's extra; issue 64), as the FE and kernel hints say it
SOLVERS_EXTRA = "pip install 'hypoid-ltca[solvers]', from a clone: pip install '.[solvers]'"


def missing_backends() -> dict[str, str]:
    """The known open-source backends that are not installed here, with how to install them.

    Returns
    -------
    dict of str to str
        Registry name → the install line (``pip install <distribution>``, or all at once:
        :data:`SOLVERS_EXTRA`), in the order of :data:`KNOWN_BACKENDS`; empty where every
        one is installed. Listed by ``ltca compare-solvers`` and recorded by the solver
        study (:func:`contact.qp.solver_study.compare_solvers`).

    Notes
    -----
    A backend counts as installed when the registry has it (qpsolvers found it importable
    and working), not merely when its distribution is present.
    """
    installed = _registry()
    return {name: f"pip install {dist} (or {SOLVERS_EXTRA})"
            for name, dist in KNOWN_BACKENDS.items() if name not in installed}


#: block-pivoting steps a polish may take from a backend's sets on a problem with force
#: limits (:func:`polish`)
POLISH_PIVOTS = 5


def polish(
    problem: ContactProblem, force: np.ndarray, rotation: float,
    tolerance: float = DEFAULT_TOLERANCE,
) -> tuple[np.ndarray, float] | None:
    """Polish an approximate solution by solving the KKT system on its contact set exactly.

    The contact set is read from the approximate answer: segment i is taken as in
    contact when its relative force exceeds its relative gap, Fᵢ/f > Yᵢ/d (the
    reference magnitudes of :func:`contact_residuals`), and, where it has a force limit,
    at its limit when its relative distance from the limit is below its relative
    penetration, (F_max,ᵢ − Fᵢ)/f < −Yᵢ/d. The reduced system is solved with
    :func:`solve_on_contact_set`; the caller keeps the polished answer only if it
    certifies (complementarity holds).

    With force limits an interior-point answer cannot tell a segment loaded just below its
    limit from one at it (its two bound multipliers are both of the barrier's size there):
    where the answer on the sets read does not certify to ``tolerance``, up to
    :data:`POLISH_PIVOTS` block-pivoting steps from those sets follow
    (:func:`contact.qp.solvers.active_set.block_pivoting`, no fallback). Without limits the
    polish is the one exact solve.

    Returns
    -------
    (F [N], Θ [rad]) or None
    """
    F = np.asarray(force, float)
    sc = problem.scale
    Y = problem.gap(F, rotation)
    f_ref = max(float(np.max(np.abs(F))), sc.force)
    d_ref = max(float(np.max(np.abs(problem.compliance @ F))), sc.length)
    active = F / f_ref > Y / d_ref
    if not problem.has_bounds:
        return solve_on_contact_set(problem, active)
    upper = problem.bounded & ((problem.upper_bound - F) / f_ref < -Y / d_ref)
    active &= ~upper
    sol = solve_on_contact_set(problem, active, upper)
    if sol is not None and _certified(contact_residuals(problem, *sol), tolerance):
        return sol
    out = block_pivoting(problem, initial_active_set=active, initial_upper_set=upper,
                         max_iterations=POLISH_PIVOTS, fallback=False)
    return (out["force"], out["rotation"]) if out["converged"] else sol


def _check_returned(solver: str, raw: RawResult, n: int) -> None:
    """Refuse a backend's answer of the wrong shape: forces F that are not N numbers, a
    rotation Θ that is not one. Not a failure to solve (reported by ``found``) but a
    broken backend, whose forces would otherwise meet the problem's matrices in a NumPy
    shape error.

    Raises
    ------
    PluginError
        Naming the solver, what it returned and what a solver returns (docs/extending.md).
    """
    if raw.force is None or raw.rotation is None:
        return
    force = np.asarray(raw.force)
    if force.shape != (n,) or not np.issubdtype(force.dtype, np.number):
        raise PluginError(f"solver {solver!r} returned forces of shape {force.shape} "
                          f"({force.dtype}) for a problem of {n} segments; a solver returns "
                          f"F [N] of shape ({n},) and the rotation [rad] (docs/extending.md)")
    if np.ndim(raw.rotation) != 0:
        raise PluginError(f"solver {solver!r} returned a rotation of shape "
                          f"{np.shape(raw.rotation)}; a solver returns one rotation [rad]")


def _certified(res: dict[str, float], tolerance: float) -> bool:
    return all(math.isfinite(v) and v <= tolerance for v in res.values())


def solve_contact(
    problem: ContactProblem,
    solver: SolverLike = DEFAULT_SOLVER,
    *,
    accuracy: str = "high",
    polish_solution: bool = True,
    tolerance: float = DEFAULT_TOLERANCE,
    initial: ContactSolution | np.ndarray | None = None,
    **options: Any,
) -> ContactSolution:
    """Solve the loaded-contact problem with a named backend and certify the answer.

    Parameters
    ----------
    problem : ContactProblem
    solver : str, Backend or callable
        A name from :func:`available_solvers` (default ``active_set``, our exact solver),
        a :class:`Backend`, or a solve function (:func:`as_backend`).
    accuracy : {"high", "default", "low"}
        Accuracy level mapped onto each backend's own tolerance parameters on the
        scaled problem (1e-9, backend defaults, 1e-3).
    polish_solution : bool
        If the backend's answer does not certify, solve the KKT system on its
        contact set exactly and keep that if it certifies (default True).
    tolerance : float — [1]
        Relative tolerance on every residual for ``found`` (default 1e-7).
    initial : ContactSolution or array (N,) of forces [N], optional
        Warm start (the previous roll position's solution); ignored by backends
        that cannot use it.
    **options
        Passed to the backend (its own parameter names override the accuracy map;
        for ``active_set``: ``max_iterations``, ``fallback``).

    Returns
    -------
    ContactSolution
        ``found`` is True only if our own residuals are within ``tolerance``.
        A backend that raises, returns nothing, or returns an uncertifiable answer
        gives ``found=False`` with the reason in ``status`` (naming the backend); this
        function does not raise for solver failures.

    Raises
    ------
    SolverNotFoundError
        Unknown solver name.
    ProblemInputError
        Unknown accuracy level or a non-positive tolerance.
    InputError
        A solve function whose signature does not fit (:func:`as_backend`).
    PluginError
        A backend that returned forces of the wrong shape (not one per segment) or more
        than one rotation: a broken backend, not a failed solve (named).

    Notes
    -----
    The problem is the seed's loaded-contact problem (Eq. 3.12–3.14) written as the convex
    QP of Conry & Seireg (1972): compatibility with slack, complementarity and torque
    equilibrium are its KKT conditions, and the residuals that certify a solution are
    those four conditions, computed here (:func:`contact.qp.contact_residuals`).
    """
    from contact.errors import ProblemInputError

    backend = get_backend(solver)
    solver = backend.name
    if accuracy not in ACCURACY_LEVELS:
        raise ProblemInputError(
            f"accuracy: must be one of {sorted(ACCURACY_LEVELS)}, got {accuracy!r}"
        )
    if not (isinstance(tolerance, (int, float)) and 0 < tolerance < 1):
        raise ProblemInputError(f"tolerance: must be in (0, 1), got {tolerance!r}")
    if not isinstance(problem, ContactProblem):
        raise ProblemInputError(f"problem: must be a ContactProblem, got {type(problem).__name__}")
    init = initial.force if isinstance(initial, ContactSolution) else initial
    if init is not None:
        init = np.asarray(init, float)
        if init.shape != (problem.size,) or not backend.warm_start:
            init = None
    try:
        raw = backend.solve(problem, accuracy=accuracy, initial=init, **options)
    except PluginError:  # a broken backend (what it returned), not a failed solve
        raise
    except Exception as exc:  # any backend failure becomes a reported, unfound solution
        # but not the user's stop: a SIGTERM or Ctrl-C inside the compiled pivoting
        # arrives as numba's SystemError chained to it, which this handler took as a
        # failed solve, and `ltca synthesize` ran to its end after SIGTERM (Round 25's
        # 13x41 at Sigma 62 deg, docs/own_gear_set.md)
        raise_if_interrupted(exc)
        log.info("backend %s raised %s: %s", solver, type(exc).__name__, exc)
        raw = RawResult(None, None, False,
                        f"backend {solver!r} raised {type(exc).__name__}: {exc}", 0.0, 0.0)
    n = problem.size
    _check_returned(solver, raw, n)
    extras = dict(raw.extras)
    extras["claimed_success"] = raw.claimed
    if raw.force is None or raw.rotation is None:
        nan = np.full(n, np.nan)
        res = dict.fromkeys(RESIDUALS, math.inf)
        return ContactSolution(
            nan,
            math.nan,
            nan,
            False,
            f"failed: {raw.status}",
            solver,
            raw.build_time,
            raw.solve_time,
            res,
            tolerance,
            raw.iterations,
            extras,
        )
    F, theta = np.asarray(raw.force, float), float(raw.rotation)
    res, slack = residuals_and_gaps(problem, F, theta)
    polished = False
    if not _certified(res, tolerance) and polish_solution:
        t0 = time.perf_counter()
        pol = (polish(problem, F, theta, tolerance)
               if np.all(np.isfinite(F)) and math.isfinite(theta) else None)
        extras["polish_time"] = time.perf_counter() - t0
        raw.solve_time += extras["polish_time"]  # the time to a certified answer includes it
        if pol is not None:
            res_p = contact_residuals(problem, *pol)
            if _certified(res_p, tolerance):
                extras["raw_residuals"] = res
                F, theta, res = pol[0], pol[1], res_p
                slack = None  # of the polished forces: computed below
                polished = True
    found = _certified(res, tolerance)
    if not found:
        worst = max(res, key=res.get)
        status = (
            f"not certified: {worst} residual {res[worst]:.2e} > {tolerance:.0e} "
            f"(backend: {raw.status})"
        )
    elif polished:
        status = "solved (polished)"
    elif raw.status.startswith("solved"):
        status = raw.status  # our own solver, possibly naming its fallback
    elif raw.claimed:
        status = "solved"
    else:
        status = f"solved (certified, although the backend reported: {raw.status})"
    return ContactSolution(
        force=F,
        rotation=theta,
        slack=problem.gap(F, theta) if slack is None else slack,
        found=found,
        status=status,
        solver=solver,
        build_time=raw.build_time,
        solve_time=raw.solve_time,
        residuals=res,
        tolerance=tolerance,
        iterations=raw.iterations,
        extras=extras,
    )
