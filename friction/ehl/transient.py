"""Transient mixed-EHL line contact: two rough surfaces moving through it with their own speeds.

The seed's friction model (§5.2.2) is the transient mixed-EHL model of Li & Kahraman: the
roughness of each surface is carried through the contact at that surface's speed
(u₁ = u_e(1 + SR/2), u₂ = u_e(1 − SR/2)), so the gap changes in time at every place,

    H(X, T) = H₀(T) + X²/2 + D P(T) − a(T)[z₁(X − c₁T) + z₂(X − c₂T)],   c_k = u_k/u_e,

and the Reynolds equation keeps its squeeze term ∂(ρ̄H)/∂T (T = t u_e/b). The film's oil
moves at u_e, the roughness at u₁ and u₂: under sliding the two cannot stay in step, which
is what loads the asperities, flattens them partly and lets them touch. (A steady solution
with the roughness frozen, :mod:`friction.ehl.line_contact`, has no such motion and no
solution at some nodes in the mixed regime: docs/ehl.md.)

One run (:func:`solve_transient_line_contact`):

1. the smooth steady film on the same grid (:mod:`friction.ehl.line_contact`);
2. the roughness grown from nothing over ``TimeGrid.ramp`` (a(T) rises as a smooth step),
   the surfaces moving, every time step solved implicitly (BDF2, backward Euler for the
   first step and after a reduced step) for the node conditions min(P, H, −R) = 0 and the
   load balance (:mod:`friction.ehl.complementarity`);
3. ``TimeGrid.flush`` for the oil that entered during the ramp to leave the contact;
4. the quantities of the seed's Eq. 5.9 averaged over ``TimeGrid.average``: μ (film shear
   plus μ_b on the contact nodes), the asperity load and contact ratios, the films.

Times are in units of b/u_e (the time the oil takes to cross a Hertz half-width). A step
that does not converge is retried as 2, then 4 … sub-steps (``TimeGrid.substeps``
halvings); a run that still fails raises :class:`ConvergenceError` naming the time.

Source: Li, S., Kahraman, A., "A transient mixed elastohydrodynamic lubrication model for
spur gear pairs", J. Tribol. 132 (2010) 011501; Venner, C. H., Lubrecht, A. A., *Multilevel
Methods in Lubrication*, Elsevier (2000), ch. 10 (moving roughness in the transient
Reynolds equation); the seed's Eq. 5.7–5.9.
"""

from __future__ import annotations

import logging
import math
import time as _time
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from friction.ehl.complementarity import (
    ConvergenceError,
    NewtonOptions,
    solve_node_conditions,
)
from friction.ehl.line_contact import (
    Grid,
    LineContactCondition,
    condition_attrs,
    contact_setup,
    film_and_boundary_friction,
    initial_pressure,
    node_state,
    smooth_lambda_ratio,
    steady_active_set,
)
from friction.ehl.reynolds import CAVITATION, CONTACT, FLUID, Squeeze, couette_difference
from friction.ehl.roughness import GroundSurface, MeasuredSurface, MovingProfile, surface_on_grid
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.materials import DEFAULT_MATERIAL, contact_pressure_limit
from geometry.core.validation import integer, one_of, real

__all__ = ["TimeGrid", "TransientSummary", "default_transient_grid",
           "solve_transient_line_contact", "transient_summary"]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]

Surface = GroundSurface | MeasuredSurface

#: a node whose film is below this fraction of the smooth central film counts as closed
#: (asperity contact): the penalty leaves closed nodes at H ≈ −R/ξ_c, ~1e-12 of the film
CLOSED_FRACTION = 1e-6

#: time-integration schemes of the squeeze term
SCHEMES = ("bdf2", "euler")


@dataclass(frozen=True)
class TimeGrid:
    """Time stepping of a transient run (times in units of b/u_e).

    Parameters
    ----------
    courant : float — [1]
        Node spacings the faster surface moves per step, 0.05 … 8.
    ramp : float — [1]
        Roughness grown from 0 to its full height over this time, ≥ 0.
    flush : float — [1]
        Run after the ramp before averaging (the oil crossing the contact), ≥ 0.
    average : float — [1]
        Averaging window, > 0.
    scheme : {"bdf2", "euler"}
        The squeeze term's backward difference.
    snapshots : int
        Pressure and film profiles stored, evenly over the averaging window, 1 … 1000.
    substeps : int
        Halvings of a step that does not converge before the run fails, 0 … 6.
    newton : NewtonOptions
        The Newton iteration of each step.
    """

    courant: float = 1.0
    ramp: float = 0.5
    flush: float = 2.5
    average: float = 2.0
    scheme: str = "bdf2"
    snapshots: int = 40
    substeps: int = 3
    newton: NewtonOptions = field(default_factory=NewtonOptions)

    def check(self) -> None:
        """Raise :class:`InputError` naming the field out of range."""
        real("time.courant", self.courant, low=0.05, high=8.0)
        real("time.ramp", self.ramp, low=0.0)
        real("time.flush", self.flush, low=0.0)
        real("time.average", self.average, low=0.0, low_open=True)
        one_of("time.scheme", self.scheme, SCHEMES)
        integer("time.snapshots", self.snapshots, low=1, high=1000)
        integer("time.substeps", self.substeps, low=0, high=6)
        self.newton.check()

    @property
    def end(self) -> float:
        """Length of the run [b/u_e]."""
        return self.ramp + self.flush + self.average


class TransientSummary(NamedTuple):
    """Time averages of a transient run (units in the field names' docs)."""

    friction_coefficient: float       #: μ, seed Eq. 5.9 [1]
    fluid_friction: float             #: film part of μ [1]
    boundary_part: float              #: asperity (boundary) part of μ [1]
    film_central: float               #: film at X = 0, time mean [µm]
    film_min: float                   #: min film over the loaded zone, time mean [µm]
    asperity_load_ratio: float        #: ∫_contact p dx / w′ [1]
    contact_area_ratio: float         #: contact length / 2b [1]
    lambda_ratio: float               #: smooth-film h_min / composite Rq [1]
    friction_coefficient_error: float  #: standard error of the time mean of μ [1]
    pressure_max: float               #: largest pressure of the window / p_h [1]
    limit_ratio: float                #: length at the pressure limit / 2b, time mean [1]
    steps: int                        #: time steps
    newton_iterations: int            #: Newton iterations of all steps


def default_transient_grid(condition: LineContactCondition, nodes: int = 512) -> Grid:
    """A grid whose inlet holds the whole pressure build-up of the smooth film.

    Parameters
    ----------
    condition : LineContactCondition
    nodes : int
        Nodes of the grid, 64 … 16384.

    Returns
    -------
    Grid
        outlet 1.5; inlet min(−2, X_s − 0.5) with X_s the first place where the smooth
        steady pressure (256 nodes over −6 … 1.5 b; 512 if that one's node sets cycle)
        reaches 0.1 % of p_h: thick films need a far inlet (fully flooded), thin ones do
        not, and every node spent upstream of the build-up is a node less in the Hertz
        zone. Where neither probe converges, the inlet is −4 (the steady grid's).
    """
    integer("nodes", nodes, low=64, high=16384)
    smooth = LineContactCondition(**{**_condition_fields(condition),
                                     "roughness_1": None, "roughness_2": None})
    for probe_nodes in (256, 512):
        probe = Grid(nodes=probe_nodes, inlet=-6.0, outlet=1.5)
        s = contact_setup(smooth, probe)
        p, h0 = initial_pressure(s, condition)
        try:
            p, _h0, _kind, _its = steady_active_set(s, p, h0, probe)
        except ConvergenceError:
            continue
        onset = float(s.x[np.argmax(p >= 1e-3)])
        return Grid(nodes=nodes, inlet=min(-2.0, onset - 0.5), outlet=1.5)
    log.info("default_transient_grid: the smooth probe did not converge; inlet -4")
    return Grid(nodes=nodes, inlet=-4.0, outlet=1.5)


def _condition_fields(c: LineContactCondition) -> dict:
    return {f: getattr(c, f) for f in c.__dataclass_fields__}


def _smoothstep(t: float) -> float:
    t = min(max(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


def _check_surfaces(condition: LineContactCondition, surfaces) -> tuple[Surface, Surface]:
    if condition.roughness_1 is not None or condition.roughness_2 is not None:
        raise InputError("roughness_1/roughness_2: a transient run moves whole surfaces; "
                         "give them as surfaces=(GroundSurface(...), ...), not as heights on "
                         "the grid")
    if surfaces is None or len(surfaces) != 2:
        raise InputError("surfaces: two surfaces (GroundSurface or MeasuredSurface), one "
                         "per body")
    for k, s in enumerate(surfaces):
        if not isinstance(s, GroundSurface | MeasuredSurface):
            raise InputError(f"surfaces[{k}]: a GroundSurface or MeasuredSurface, got "
                             f"{type(s).__name__}")
        s.check()
    return surfaces[0], surfaces[1]


@dataclass
class _Run:
    """Records of every step of a run."""

    time: list[float] = field(default_factory=list)
    mu: list[float] = field(default_factory=list)
    fluid: list[float] = field(default_factory=list)
    boundary: list[float] = field(default_factory=list)
    load_ratio: list[float] = field(default_factory=list)
    area_ratio: list[float] = field(default_factory=list)
    film_central: list[float] = field(default_factory=list)
    film_min: list[float] = field(default_factory=list)
    pressure_max: list[float] = field(default_factory=list)
    iterations: list[int] = field(default_factory=list)
    held: list[float] = field(default_factory=list)
    snapshots: list[tuple] = field(default_factory=list)


def _pressure_limit(limit: float | str | None) -> float | None:
    """The surfaces' pressure limit [MPa] (None: elastic)."""
    if limit is None:
        return None
    if isinstance(limit, str):
        try:
            return contact_pressure_limit(DEFAULT_MATERIAL, limit)
        except ModelUnavailableError as exc:
            raise InputError(f"pressure_limit: {exc}") from exc
    return real("pressure_limit", limit, unit="MPa", low=0.0, low_open=True)


def _run(condition: LineContactCondition, surfaces, grid: Grid, times: TimeGrid,
         pressure_limit: float | str | None = "shakedown"):
    times.check()
    s1, s2 = _check_surfaces(condition, surfaces)
    limit_mpa = _pressure_limit(pressure_limit)
    s = contact_setup(condition, grid)
    limit = None if limit_mpa is None else limit_mpa * 1e6 / s.ph
    n = grid.nodes
    d = s.spacing
    x = s.x
    # 1. the smooth steady film
    s.roughness = np.zeros(n)
    p, h0 = initial_pressure(s, condition)
    p, h0, kind0, _its = steady_active_set(s, p, h0, grid)
    st = node_state(s, p, h0)
    smooth_centre = float(st.film[np.argmin(np.abs(x))])
    mass_conserving = times.newton.cavitation == "mass_conserving"
    phi = _initial_phi(st, kind0) if mass_conserving else p.copy()
    closed = CLOSED_FRACTION * max(smooth_centre, 1e-300)
    # 2. the surfaces on the material grid, moving at c_k = u_k/u_e
    sr = condition.slide_to_roll
    speeds = (1.0 + 0.5 * sr, 1.0 - 0.5 * sr)
    t_end = times.end
    dt0 = times.courant * d / max(speeds)
    b_mm, r_mm = s.b * 1e3, s.radius * 1e3
    to_h = 1e-3 * r_mm / b_mm**2                      # µm → H units
    moving, cutoffs, rq = [], [], []
    for surface, c in zip((s1, s2), speeds, strict=True):
        start = x[0] - c * t_end - 4.0 * d
        length = (x[-1] + 4.0 * d - start) * b_mm
        heights, cutoff = surface_on_grid(surface, length, d * b_mm)
        moving.append(MovingProfile(heights * to_h, d, start))
        cutoffs.append(cutoff)
        rq.append(float(np.sqrt(np.mean(heights**2))))
    s.sigma = math.hypot(*rq)

    def roughness_at(t: float) -> tuple[Array, Array]:
        """The roughness Z at time t and its exact ∂Z/∂T + ∂Z/∂X."""
        ramp = times.ramp
        amp = _smoothstep(t / ramp) if ramp > 0.0 else 1.0
        damp = (6.0 * (t / ramp) * (1.0 - t / ramp) / ramp) if 0.0 < t < ramp else 0.0
        if amp == 0.0 and damp == 0.0:
            return np.zeros(n), np.zeros(n)
        z = [m.at(x[0], n, c * t) for m, c in zip(moving, speeds, strict=True)]
        dz = [m.at(x[0], n, c * t, derivative=1) for m, c in zip(moving, speeds, strict=True)]
        rough = amp * (z[0] + z[1])
        transport = damp * (z[0] + z[1]) + amp * ((1.0 - speeds[0]) * dz[0]
                                                  + (1.0 - speeds[1]) * dz[1])
        return rough, transport

    def state_of(pp: Array, hh: float):
        return node_state(s, pp, hh)

    rec = _Run()
    centre = int(np.argmin(np.abs(x)))
    h_um = s.b**2 / s.radius * 1e6
    snap_times = set(np.round(np.linspace(t_end - times.average, t_end, times.snapshots)
                              / dt0).astype(int).tolist())
    st.fill = 1.0 + np.minimum(phi, 0.0) if mass_conserving else np.ones(n)
    history = [(st.density * st.fill * st.film, np.zeros(n))]
    t, step = 0.0, 0
    nsteps = math.ceil(t_end / dt0 - 1e-9)
    while step < nsteps:
        step += 1
        t_new = step * dt0
        phi, h0, st, its, history, last = _advance(
            s, state_of, phi, h0, t, t_new, history, roughness_at, times, limit)
        t = t_new
        p, theta = st.pressure, st.fill
        kind = np.where((theta < 1.0) | (p <= 0.0), CAVITATION, FLUID)
        kind[(st.film <= closed) & (p > 0.0)] = CONTACT
        rec.held.append(float(np.count_nonzero(p >= limit * (1.0 - 1e-9)) * d / 2.0)
                        if limit is not None else 0.0)
        tau, _f, f_boundary, w = film_and_boundary_friction(s, condition, st, kind)
        tau = tau * theta                     # a cavitated film shears its oil only
        f_fluid = float(np.abs(tau).sum() * d * s.b)
        loaded = p > 0.0
        rec.time.append(t)
        rec.mu.append((f_fluid + f_boundary) / w)
        rec.fluid.append(f_fluid / w)
        rec.boundary.append(f_boundary / w)
        rec.load_ratio.append(float(p[kind == CONTACT].sum() * d) / (0.5 * math.pi))
        rec.area_ratio.append(float(np.count_nonzero(kind == CONTACT) * d / 2.0))
        film = np.maximum(st.film, 0.0) * h_um
        rec.film_central.append(float(film[centre]))
        rec.film_min.append(float(film[loaded].min()) if loaded.any() else float(film.min()))
        rec.pressure_max.append(float(p.max()))
        rec.iterations.append(its)
        if step in snap_times:
            rec.snapshots.append((t, p.copy(), film, s.roughness * h_um, tau,
                                  (kind == CONTACT).astype(float), theta.copy()))
    info = {"steps": nsteps, "time_step": dt0, "cutoffs": cutoffs, "rq": rq,
            "smooth_central_film": smooth_centre * h_um,
            "pressure_limit": -1.0 if limit_mpa is None else limit_mpa,
            "last_step": last}
    return s, rec, info


def _advance(s, state_of, phi, h0, t, t_new, history, roughness_at, times: TimeGrid,
             limit: float | None):
    """One time step t → t_new, retried as sub-steps (backward Euler) where it fails.

    ``history`` holds (q, Z) of the last two steps (q = ρ̄θH, Z the roughness), newest
    last; the step returns Φ, the approach, the state, the iterations, the new history and
    (squeeze, state, held nodes) of its last solve (for checks of the node conditions).
    """
    for level in range(times.substeps + 1):
        parts = 2**level
        try:
            pp, hh, hist, its_all = phi, h0, list(history), 0
            for k in range(1, parts + 1):
                tk = t + (t_new - t) * k / parts
                dt = (t_new - t) / parts
                rough, transport = roughness_at(tk)
                s.roughness = rough
                (q1, z1) = hist[-1]
                if times.scheme == "bdf2" and len(hist) == 2 and parts == 1:
                    (q0, z0) = hist[0]
                    c, q_ref, z_ref = 1.5 / dt, (4.0 * q1 - q0) / 3.0, (4.0 * z1 - z0) / 3.0
                else:
                    c, q_ref, z_ref = 1.0 / dt, q1, z1
                defect = couette_difference(rough, s.spacing) + c * (rough - z_ref) - transport
                sq = Squeeze(c, q_ref, defect)
                sol = solve_node_conditions(state_of, pp, hh, s.kernel, s.spacing,
                                            s.lambda_bar, sq, times.newton, limit)
                st = sol.state
                pp, hh = np.where(st.fill < 1.0, st.fill - 1.0, st.pressure), sol.approach
                its_all += sol.iterations
                q_new = st.density * st.fill * st.film
                # after sub-steps the history is not uniform: the next step starts with Euler
                hist = [*hist[-1:], (q_new, rough)] if parts == 1 else [(q_new, rough)]
            return pp, hh, st, its_all, hist, (sq, st, sol.held)
        except ConvergenceError as exc:
            if level == times.substeps:
                raise ConvergenceError(
                    f"transient line contact: the step to T = {t_new:.4f} b/u_e did not "
                    f"converge with {parts} sub-step(s): {exc}") from exc
            log.debug("step to T = %.4f: %s; retried with %d sub-steps", t_new, exc, 2 * parts)
    raise AssertionError("unreachable")


def _initial_phi(state, kind) -> Array:
    """Φ of the smooth steady film: its pressure, and in the cavitated outlet the fill θ that
    carries the flux of the film's last pressurised node (Φ = θ − 1)."""
    p = state.pressure
    phi = p.copy()
    wet = np.flatnonzero(p > 0.0)
    if wet.size:
        last = wet[-1]
        flux = state.density[last] * max(state.film[last], 0.0)
        down = np.arange(last + 1, p.size)
        gap = state.density[down] * np.maximum(state.film[down], 1e-300)
        phi[down] = np.minimum(flux / gap, 1.0) - 1.0
    phi[0] = 0.0
    return phi


def _batch_error(values: Array, batches: int = 10) -> float:
    """Standard error of the mean of a correlated series by batch means."""
    if values.size < 2 * batches:
        return float(np.std(values) / math.sqrt(max(values.size - 1, 1)))
    means = np.array([b.mean() for b in np.array_split(values, batches)])
    return float(np.std(means, ddof=1) / math.sqrt(batches))


def _summarise(s, condition, rec: _Run, info, times: TimeGrid) -> TransientSummary:
    t = np.asarray(rec.time)
    window = t > times.end - times.average - 1e-12
    mean = {k: float(np.mean(np.asarray(getattr(rec, k))[window]))
            for k in ("mu", "fluid", "boundary", "load_ratio", "area_ratio", "film_central",
                      "film_min")}
    lam = smooth_lambda_ratio(s, condition)
    return TransientSummary(
        friction_coefficient=mean["mu"], fluid_friction=mean["fluid"],
        boundary_part=mean["boundary"], film_central=mean["film_central"],
        film_min=mean["film_min"], asperity_load_ratio=mean["load_ratio"],
        contact_area_ratio=mean["area_ratio"], lambda_ratio=lam,
        friction_coefficient_error=_batch_error(np.asarray(rec.mu)[window]),
        pressure_max=float(np.max(np.asarray(rec.pressure_max)[window])),
        limit_ratio=float(np.mean(np.asarray(rec.held)[window])),
        steps=int(info["steps"]), newton_iterations=int(np.sum(rec.iterations)))


def transient_summary(condition: LineContactCondition, surfaces, grid: Grid | None = None,
                      time: TimeGrid | None = None,
                      pressure_limit: float | str | None = "shakedown") -> TransientSummary:
    """Time averages of one transient mixed-EHL line contact (no dataset built).

    Parameters
    ----------
    condition : LineContactCondition
        Without ``roughness_1``/``roughness_2`` (the surfaces are given separately).
    surfaces : (GroundSurface | MeasuredSurface, GroundSurface | MeasuredSurface)
        Surface 1 moves at u_e(1 + SR/2), surface 2 at u_e(1 − SR/2).
    grid : Grid, optional
        Default :func:`default_transient_grid` (512 nodes).
    time : TimeGrid, optional
        Default :class:`TimeGrid()`.
    pressure_limit : float [MPa], str or None
        The most pressure the surfaces carry: a limit of the default material
        (:data:`geometry.core.materials.CONTACT_PRESSURE_LIMITS`: ``"shakedown"``, the
        default, 5.26 GPa for case-carburised steel — the limit the LTCA's edges use — or
        ``"first_yield"``), a pressure, or None (elastic to any pressure).

    Returns
    -------
    TransientSummary

    Raises
    ------
    InputError
        An input out of range (named).
    ConvergenceError
        A time step that did not converge with its sub-steps.

    Notes
    -----
    Source: the seed's §5.2.2 (Eq. 5.7–5.9) with the transient model of Li & Kahraman
    (2010); module docstring.
    """
    times = time or TimeGrid()
    g = grid or default_transient_grid(condition)
    s, rec, info = _run(condition, surfaces, g, times, pressure_limit)
    return _summarise(s, condition, rec, info, times)


def _var(data, dims, units: str, long_name: str) -> tuple:
    return data_var(dims, np.asarray(data, dtype=float), units, long_name)


def solve_transient_line_contact(condition: LineContactCondition, surfaces,
                                 grid: Grid | None = None, time: TimeGrid | None = None,
                                 pressure_limit: float | str | None = "shakedown",
                                 ) -> xr.Dataset:
    """Solve one transient mixed-EHL line contact and return its dataset.

    Parameters
    ----------
    condition : LineContactCondition
        Without ``roughness_1``/``roughness_2``.
    surfaces : (GroundSurface | MeasuredSurface, GroundSurface | MeasuredSurface)
        Surface 1 moves at u_e(1 + SR/2), surface 2 at u_e(1 − SR/2).
    grid : Grid, optional
        Default :func:`default_transient_grid` (512 nodes).
    time : TimeGrid, optional
        Default :class:`TimeGrid()`.
    pressure_limit : float [MPa], str or None
        The most pressure the surfaces carry: a limit of the default material
        (:data:`geometry.core.materials.CONTACT_PRESSURE_LIMITS`: ``"shakedown"``, the
        default, 5.26 GPa for case-carburised steel — the limit the LTCA's edges use — or
        ``"first_yield"``), a pressure, or None (elastic to any pressure).

    Returns
    -------
    xarray.Dataset
        Scalars (time means over the averaging window): ``friction_coefficient``,
        ``fluid_friction``, ``boundary_friction_part``, ``asperity_load_ratio``,
        ``contact_area_ratio``, ``lambda_ratio`` [1], ``film_central``, ``film_min`` [µm],
        ``friction_coefficient_error`` [1] (standard error of the mean by batch means),
        ``pressure_max`` [MPa], ``hertz_pressure`` [MPa], ``hertz_half_width`` [mm];
        series over ``time`` [s] (every step): ``friction_coefficient_t``,
        ``asperity_load_ratio_t``, ``film_central_t``, ``film_min_t``, ``pressure_max_t``,
        ``newton_iterations``; profiles over (``snapshot_time`` [s], ``x`` [mm]):
        ``pressure`` [MPa], ``film_thickness`` [µm], ``roughness`` [µm], ``shear_stress``
        [MPa], ``contact`` [1].

    Raises
    ------
    InputError
        An input out of range (named).
    ConvergenceError
        A time step that did not converge with its sub-steps.

    Notes
    -----
    Source: module docstring; ``docs/ehl.md``.
    """
    times = time or TimeGrid()
    g = grid or default_transient_grid(condition)
    t0 = _time.perf_counter()
    s, rec, info = _run(condition, surfaces, g, times, pressure_limit)
    summ = _summarise(s, condition, rec, info, times)
    tscale = s.b / condition.entraining_velocity          # [s] per unit T
    ph = s.ph * 1e-6
    scalar = {
        "friction_coefficient": (summ.friction_coefficient, "1",
                                 "friction coefficient mu, time mean (seed Eq. 5.9)"),
        "fluid_friction": (summ.fluid_friction, "1", "film (Eyring) part of mu"),
        "boundary_friction_part": (summ.boundary_part, "1", "asperity (boundary) part of mu"),
        "friction_coefficient_error": (summ.friction_coefficient_error, "1",
                                       "standard error of the time mean of mu"),
        "film_central": (summ.film_central, "um", "film thickness at x = 0, time mean"),
        "film_min": (summ.film_min, "um", "minimum film over the loaded zone, time mean"),
        "asperity_load_ratio": (summ.asperity_load_ratio, "1",
                                "share of the load carried by contact nodes, time mean"),
        "contact_area_ratio": (summ.contact_area_ratio, "1",
                               "contact length over Hertz width 2b, time mean"),
        "lambda_ratio": (summ.lambda_ratio if math.isfinite(summ.lambda_ratio) else -1.0, "1",
                         "smooth-film h_min (Pan-Hamrock) over composite Rq; -1 if smooth"),
        "pressure_max": (summ.pressure_max * ph, "MPa", "largest pressure in the window"),
        "limit_ratio": (summ.limit_ratio, "1",
                        "length at the pressure limit over Hertz width 2b, time mean"),
        "hertz_pressure": (ph, "MPa", "Hertz maximum pressure p_h"),
        "hertz_half_width": (s.b * 1e3, "mm", "Hertz half-width b"),
    }
    data = {k: _var(v, (), u, ln) for k, (v, u, ln) in scalar.items()}
    series = {
        "friction_coefficient_t": (rec.mu, "1", "friction coefficient mu"),
        "asperity_load_ratio_t": (rec.load_ratio, "1", "asperity load ratio"),
        "film_central_t": (rec.film_central, "um", "film thickness at x = 0"),
        "film_min_t": (rec.film_min, "um", "minimum film over the loaded zone"),
        "pressure_max_t": (np.asarray(rec.pressure_max) * ph, "MPa", "largest pressure"),
        "newton_iterations": (rec.iterations, "1", "Newton iterations of the step"),
    }
    data.update({k: _var(v, ("time",), u, ln) for k, (v, u, ln) in series.items()})
    snaps = rec.snapshots
    profile = {
        "pressure": (1, ph, "MPa", "film and contact pressure"),
        "film_thickness": (2, 1.0, "um", "film thickness h"),
        "roughness": (3, 1.0, "um", "sum of the surfaces' roughness heights"),
        "shear_stress": (4, 1e-6, "MPa", "film shear stress (Eyring)"),
        "contact": (5, 1.0, "1", "1 on asperity-contact nodes"),
        "fill": (6, 1.0, "1", "share of the gap filled with oil (1: pressurised film)"),
    }
    for name, (k, scale, units, ln) in profile.items():
        data[name] = _var(np.array([sn[k] for sn in snaps]) * scale, ("snapshot_time", "x"),
                          units, ln)
    coords = {
        "x": ("x", s.x * s.b * 1e3, {"units": "mm", "long_name": "distance from contact centre"}),
        "time": ("time", np.asarray(rec.time) * tscale,
                 {"units": "s", "long_name": "time since the start of the roughness ramp"}),
        "snapshot_time": ("snapshot_time", np.array([sn[0] for sn in snaps]) * tscale,
                          {"units": "s", "long_name": "time of the stored profiles"}),
    }
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({
        "title": "mixed-EHL line contact (transient, moving roughness)",
        **condition_attrs(condition),
        "grid_nodes": int(g.nodes), "grid_inlet": float(g.inlet), "grid_outlet": float(g.outlet),
        "time_step_b_per_ue": float(info["time_step"]), "steps": int(info["steps"]),
        "courant": float(time.courant if time else TimeGrid().courant),
        "ramp_b_per_ue": float(times.ramp), "flush_b_per_ue": float(times.flush),
        "average_b_per_ue": float(times.average), "scheme": times.scheme,
        "roughness_rq_um": np.asarray(info["rq"], dtype=float),
        "short_cutoff_mm": np.asarray(info["cutoffs"], dtype=float),
        "smooth_central_film_um": float(info["smooth_central_film"]),
        "pressure_limit_MPa": float(info["pressure_limit"]),
        "newton_iterations_total": int(summ.newton_iterations),
        "wall_time_s": float(_time.perf_counter() - t0),
    })
    return ds
