"""One point of the friction study solved by the mixed-EHL line-contact solver.

:func:`solve_design_point` turns a design point (p_h, R, u_e, SR, T, Rq₁, Rq₂; the units of
:data:`friction.study.design.DESIGN_INPUTS`) into a :class:`friction.ehl.line_contact.
LineContactCondition` — load per length from p_h (w′ = 2πR p_h²/E′) — and the two
surfaces: ground profiles (:class:`friction.ehl.roughness.GroundSurface`, seeds 1 and 2,
the seed's "baseline profile multiplied by a constant") of Rq₁ and Rq₂. It solves it
through the solver's public API only: rough points by the stochastic model (the
profiles' statistics, :func:`friction.ehl.stochastic.stochastic_summary`), smooth points
(both Rq 0) by the steady smooth film (:func:`friction.ehl.line_contact.
line_contact_summary`). The resolved models (the profiles moving, transient, or frozen,
steady) left the study in issue 61 (docs/ehl.md, "Why the resolved model left the
commands"). A condition the solver does not converge on is recorded as failed with the
reason, never as a result. It runs on a Dask worker (the runner is
:mod:`contact.study.friction_study`).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from geometry.core.errors import InputError
from geometry.core.validation import integer, one_of, real

__all__ = ["POINT_STATUS", "RESULT_VARIABLES", "SOLVE_MODES", "PointOutcome", "SolveSettings",
           "outcome_arrays", "solve_design_point", "surfaces_of"]

log = logging.getLogger(__name__)

#: status values of a point (CF flag meanings, in order 0, 1, 2)
POINT_STATUS = ("converged", "not_converged", "input_refused")

#: the scalars stored per point: name → (units, long_name)
RESULT_VARIABLES: Mapping[str, tuple[str, str]] = {
    "friction_coefficient": ("1", "friction coefficient mu (solver)"),
    "fluid_friction": ("1", "film (Eyring) part of mu"),
    "boundary_friction_part": ("1", "asperity (boundary) part of mu"),
    "film_central": ("um", "central film thickness h_c (stochastic: mean-plane separation)"),
    "film_min": ("um", "minimum film thickness h_min (stochastic: mean-plane separation)"),
    "asperity_load_ratio": ("1", "share of the load carried by the asperities"),
    "contact_area_ratio": ("1", "contact length (stochastic: real contact area) over Hertz "
                                "width 2b"),
    "lambda_ratio": ("1", "smooth-film h_min (Pan-Hamrock) over composite Rq"),
    "load_per_length": ("N/mm", "normal load per unit length w'"),
    "solve_time": ("s", "wall time of the solver calls on its worker"),
    "realisations_converged": ("1", "roughness realisations the solver converged on"),
    "friction_coefficient_spread": ("1", "standard deviation of mu over the converged "
                                         "realisations (0 for one)"),
    "friction_coefficient_error": ("1", "standard error of the time mean of mu (0: the "
                                        "study's solvers are steady; issue 34's transient "
                                        "studies stored theirs)"),
    "pressure_max": ("MPa", "largest pressure (NaN for a smooth point)"),
    "newton_iterations": ("1", "Newton iterations of the solver calls"),
    "flash_temperature_max": ("K", "largest surface flash temperature (stochastic; 0 else)"),
}

#: solution modes of a rough point: the statistical roughness (friction.ehl.stochastic).
#: The resolved profiles, moving ("transient") or frozen ("steady"), left the study in
#: issue 61: their asperities carried 11–27× less of the load than the stochastic model's
#: on the same surfaces, a share that fell as their grid was refined (docs/ehl.md)
SOLVE_MODES = ("stochastic",)

#: where :class:`SolveSettings` refusing a resolved mode points to
_RESOLVED_GONE = 'docs/ehl.md, "Why the resolved model left the commands"'


@dataclass(frozen=True)
class SolveSettings:
    """What every point of a friction study shares.

    Parameters
    ----------
    nodes : int
        Grid nodes of a rough point over the stochastic solver's domain
        (:func:`friction.ehl.stochastic.stochastic_grid`), 64 … 16384. Smooth points
        (both Rq 0) are the steady smooth film on the grid its Moes M asks.
    max_iterations : int
        Newton iterations before a point counts as failed (the stochastic solver takes at
        least 200).
    lubricant : str
        Bundled oil name or oil TOML file (:func:`friction.lubricant.load_lubricant`).
    profile_seeds : (int, int)
        Seeds of the two surfaces' ground profiles (realisation k uses seeds + 2k).
    realisations : int
        Roughness realisations per condition, 1 … 32: the point's values are the means over
        the realisations the solver converged on (each realisation's profiles have their
        own summit statistics).
    mode : {"stochastic"}
        Rough points by the stochastic model (the roughness's statistics: the asperity
        scale averaged, :mod:`friction.ehl.stochastic`), the only mode. ``"transient"``
        and ``"steady"`` (the resolved profiles moving or frozen) are refused: they left
        the study in issue 61 (docs/ehl.md, "Why the resolved model left the commands");
        :mod:`friction.ehl.transient` itself stays for its tests and that record.
    short_cutoff : float — [mm]
        λs of the ground profiles (:class:`friction.ehl.roughness.GroundSurface`).
    viscosity_model : {"barus", "roelands"}
        Viscosity–pressure model of the film and its traction
        (:data:`friction.ehl.rheology.VISCOSITY_PRESSURE_MODELS`; Barus by default, as
        :class:`friction.ehl.line_contact.LineContactCondition`).
    thermal : bool
        Stochastic runs: the film's shear at the surfaces' flash temperature
        (:class:`friction.ehl.stochastic.StochasticOptions`).

    Raises
    ------
    InputError
        A field out of its range, named (``mode`` other than ``"stochastic"`` with where
        the resolved models went).
    """

    nodes: int = 512
    max_iterations: int = 60
    lubricant: str = "75W90"
    profile_seeds: tuple[int, int] = (1, 2)
    realisations: int = 1
    mode: str = "stochastic"
    short_cutoff: float = 0.008
    viscosity_model: str = "barus"
    thermal: bool = True

    def __post_init__(self) -> None:
        if self.mode not in SOLVE_MODES:
            raise InputError(
                f"mode: must be 'stochastic', got {self.mode!r}; the resolved transient and "
                f"steady models are no longer run by the friction study ({_RESOLVED_GONE})")
        integer("nodes", self.nodes, low=64, high=16384)
        integer("max_iterations", self.max_iterations, low=1, high=10000)
        if not isinstance(self.lubricant, str) or not self.lubricant:
            raise InputError(f"lubricant: must be an oil name, got {self.lubricant!r}")
        from friction.ehl.line_contact import lubricant_of

        try:                            # an unknown or invalid oil refused before any work
            lubricant_of(self.lubricant)
        except InputError as exc:
            raise InputError(f"lubricant: {str(exc).removeprefix('lubricant: ')}") from None
        if len(self.profile_seeds) != 2:
            raise InputError(f"profile_seeds: must be two seeds, got {self.profile_seeds!r}")
        for s in self.profile_seeds:
            integer("profile_seeds", s, low=0)
        integer("realisations", self.realisations, low=1, high=32)
        one_of("viscosity_model", self.viscosity_model, ("barus", "roelands"))
        if not isinstance(self.thermal, bool):
            raise InputError(f"thermal: must be true or false, got {self.thermal!r}")
        real("short_cutoff", self.short_cutoff, unit="mm", low=0.0)

    def as_dict(self) -> dict[str, object]:
        """The settings as plain values (JSON and netCDF attributes)."""
        d = dataclasses.asdict(self)
        d["profile_seeds"] = list(self.profile_seeds)
        return d


@dataclass(frozen=True)
class PointOutcome:
    """One solved (or failed) point: small, whatever the solver's grid."""

    index: int
    status: int                 #: index into :data:`POINT_STATUS`
    reason: str                 #: why it failed ('' when converged)
    values: dict[str, float]    #: :data:`RESULT_VARIABLES` (NaN where failed)


def _smooth_condition(settings: SolveSettings, point: Mapping[str, float]):
    """The point's smooth condition and its two Rq [µm]."""
    from friction.ehl.line_contact import STEEL_E_PRIME, LineContactCondition

    ph = real("hertz_pressure", point["hertz_pressure"], unit="MPa", low=0.0, low_open=True)
    r = real("radius", point["radius"], unit="mm", low=0.0, low_open=True)
    rq = tuple(real(name, point[name], unit="µm", low=0.0, high=50.0)
               for name in ("roughness_1", "roughness_2"))
    load = 2.0 * math.pi * r * ph**2 / STEEL_E_PRIME
    return LineContactCondition(
        load_per_length=load, radius=r, entraining_velocity=float(point["entraining_velocity"]),
        slide_to_roll=float(point["slide_to_roll"]), temperature=float(point["temperature"]),
        lubricant=settings.lubricant, viscosity_model=settings.viscosity_model), rq


def surfaces_of(settings: SolveSettings, point: Mapping[str, float], realisation: int = 0):
    """The point's two surfaces (ground profiles of its Rq₁ and Rq₂).

    Parameters
    ----------
    settings : SolveSettings
    point : mapping of str to float
        As :func:`solve_design_point`.
    realisation : int
        Profile seeds ``settings.profile_seeds`` + 2k.

    Returns
    -------
    (GroundSurface, GroundSurface)
        Rq₁ and Rq₂ of the point, λs ``settings.short_cutoff``.
    """
    from friction.ehl.roughness import GroundSurface

    _cond, rq = _smooth_condition(settings, point)
    return tuple(GroundSurface(q, seed=seed + 2 * realisation,
                               short_cutoff=settings.short_cutoff)
                 for q, seed in zip(rq, settings.profile_seeds, strict=True))


def solve_design_point(settings: SolveSettings, index: int, point: Mapping[str, float]
                       ) -> PointOutcome:
    """Solve one design point (the function Dask runs on a worker).

    Parameters
    ----------
    settings : SolveSettings
    index : int
        The point's place in the design.
    point : mapping of str to float
        Its inputs: ``hertz_pressure`` [MPa], ``radius`` [mm], ``entraining_velocity``
        [m/s], ``slide_to_roll`` [1], ``temperature`` [degC], ``roughness_1``,
        ``roughness_2`` [µm]; w′ = 2πR p_h²/E′ (from p_h = E′b/(4R), b = √(8w′R/(πE′))),
        steel E′.

    Returns
    -------
    PointOutcome
        status 0 converged (the solver's scalars, averaged over the realisations it
        converged on; ``realisations_converged`` says how many), 1 not converged on any
        (:class:`~friction.ehl.line_contact.ConvergenceError`), 2 input refused
        (:class:`~geometry.core.errors.InputError`); ``reason`` the error's first line;
        failed points keep ``load_per_length`` and ``solve_time``, every other value NaN.
        Never raises for a failing condition.

    Notes
    -----
    Runs with one BLAS thread (``threadpoolctl``). Source: the seed's §5.2.3 study (one MEHL
    analysis per Table 5.1 condition), the solver of :mod:`friction.ehl.line_contact` (docs/ehl.md).
    """
    from threadpoolctl import threadpool_limits

    from friction.ehl.line_contact import ConvergenceError, line_contact_summary
    from friction.ehl.stochastic import (
        StochasticOptions,
        roughness_statistics,
        stochastic_grid,
        stochastic_summary,
    )
    values = dict.fromkeys(RESULT_VARIABLES, math.nan)
    t0 = time.perf_counter()
    solved: list = []
    status, reason = 0, ""
    for k in range(settings.realisations):
        try:
            cond, rq = _smooth_condition(settings, point)
            values["load_per_length"] = cond.load_per_length
            # one BLAS thread: the points are the parallelism (a study's workers are
            # single-threaded). The solver's dense LU of ≤ 1 k unknowns gains nothing from
            # threads, and on a busy 2-core machine the default threads made a 256-node
            # rough point 6–45 s instead of 0.3–1 s (measured, issue 34)
            with threadpool_limits(limits=1):
                if max(rq) == 0.0:
                    solved.append(line_contact_summary(cond))
                else:
                    surfaces = surfaces_of(settings, point, k)
                    grid = stochastic_grid(cond, roughness_statistics(surfaces),
                                           settings.nodes)
                    solved.append(stochastic_summary(
                        cond, surfaces, grid, StochasticOptions(
                            max_iterations=max(settings.max_iterations, 200),
                            thermal=settings.thermal)))
        except ConvergenceError as exc:
            status, reason = 1, f"ConvergenceError: {exc}".splitlines()[0]
        except InputError as exc:
            status, reason = 2, f"InputError: {exc}".splitlines()[0]
            break
    values["realisations_converged"] = float(len(solved))
    if solved and status != 2:
        status, reason = 0, ""
        mean = {f: float(np.mean([getattr(s, f) for s in solved])) for f in solved[0]._fields}
        values.update(friction_coefficient=mean["friction_coefficient"],
                      fluid_friction=mean["fluid_friction"],
                      boundary_friction_part=mean["boundary_part"],
                      film_central=mean["film_central"], film_min=mean["film_min"],
                      asperity_load_ratio=mean["asperity_load_ratio"],
                      contact_area_ratio=mean["contact_area_ratio"],
                      lambda_ratio=(solved[0].lambda_ratio
                                    if math.isfinite(solved[0].lambda_ratio) else -1.0),
                      friction_coefficient_spread=float(np.std(
                          [s.friction_coefficient for s in solved])),
                      friction_coefficient_error=mean.get("friction_coefficient_error", 0.0),
                      pressure_max=mean.get("pressure_max", math.nan) * float(
                          point["hertz_pressure"]),
                      newton_iterations=float(sum(getattr(s, "newton_iterations", 0)
                                                  for s in solved)),
                      flash_temperature_max=mean.get("flash_temperature_max", 0.0))
    values["solve_time"] = time.perf_counter() - t0
    if status:
        log.info("friction study point %d %s failed: %s", index, dict(point), reason)
    return PointOutcome(int(index), status, reason, {k: float(v) for k, v in values.items()})


def outcome_arrays(outcomes: list[PointOutcome]) -> dict[str, np.ndarray]:
    """Stack outcomes' values by variable.

    Parameters
    ----------
    outcomes : list of PointOutcome

    Returns
    -------
    dict of str to array (n,)
        :data:`RESULT_VARIABLES` in the outcomes' order (units there).
    """
    return {k: np.array([o.values[k] for o in outcomes]) for k in RESULT_VARIABLES}
