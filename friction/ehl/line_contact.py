"""One mixed-EHL line contact, steady: pressure, film, load sharing and friction.

:func:`solve_line_contact` solves one contact condition (:class:`LineContactCondition`)
on a grid (:class:`Grid`) and returns a labelled dataset; :func:`line_contact_summary`
returns only the scalars (μ, h_c, h_min, asperity load ratio) for studies.

Conventions (stated once, the toolkit's, :mod:`friction.film`): E′ = 2/Σ((1−νᵢ²)/Eᵢ) = 2E*;
Hertz half-width b = √(8 w′ R/(π E′)), maximum pressure p_h = E′ b/(4R); entraining
velocity u_e = (u₁ + u₂)/2, sliding velocity u_s = u₁ − u₂ = SR·u_e; roughness heights
positive towards the other surface (they reduce the gap); isothermal film at the inlet
temperature; Newtonian flow in the Reynolds equation, Eyring shear (with limiting shear
stress) for the film traction — the usual split for line contacts (Johnson & Tevaarwerk
1977), valid while the film's shear heating is small.

Solution method: Newton's method on the unified Reynolds equation (:mod:`friction.ehl.reynolds`)
with the rigid approach H₀ as the unknown of the load balance, the deflection by DC-FFT
(:mod:`friction.ehl.kernel`) in the residual and the same coefficients as a dense matrix in
the Jacobian, and an active set of contact (H = 0) and cavitation (P = 0) nodes.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import lu_factor, lu_solve

from friction.ehl.complementarity import ConvergenceError
from friction.ehl.kernel import ElasticKernel
from friction.ehl.reynolds import CAVITATION, CONTACT, FLUID, NodeState, assemble, reynolds_residual
from friction.ehl.rheology import (
    VISCOSITY_PRESSURE_MODELS,
    dowson_higginson_density,
    eyring_limited_shear,
)
from friction.lubricant import (
    Lubricant,
    boundary_friction_coefficient,
    load_lubricant,
    pressure_viscosity_coefficient,
    viscosity,
)
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.validation import integer, one_of, real, real_array

__all__ = [
    "STEEL_E_PRIME",
    "ConvergenceError",
    "Grid",
    "LineContactCondition",
    "LineContactSummary",
    "hertz_line_contact",
    "line_contact_summary",
    "solve_line_contact",
]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]

#: E′ = 2E* of a steel pair, E = 206 GPa, ν = 0.3 [MPa].
STEEL_E_PRIME = 206000.0 / (1.0 - 0.3**2)

#: [MPa] the largest Hertz pressure a condition may have: above the shakedown limit of
#: every steel of the materials table (5.26 GPa, case-carburised steel) a contact is no
#: longer an elastic lubricated steel contact (the solvers cap pressures at that limit,
#: docs/ehl.md); a typing slip (50 GPa for 0.5) is refused before any work
MAX_HERTZ_PRESSURE = 6000.0
#: [mm] accepted equivalent radius of curvature: a rounded tooth edge (0.1 mm) to a
#: nearly flat flank (5 m)
RADIUS_RANGE = (0.01, 5000.0)
#: [m/s] the largest entraining velocity (beyond any gear's pitch-line speed)
MAX_ENTRAINING_VELOCITY = 100.0


@dataclass(frozen=True)
class LineContactCondition:
    """One line-contact condition.

    Parameters
    ----------
    load_per_length : float — [N/mm]
        w′ > 0.
    radius : float — [mm]
        Equivalent radius R > 0.
    entraining_velocity : float — [m/s]
        u_e = (u₁ + u₂)/2 > 0.
    slide_to_roll : float — [1]
        SR = (u₁ − u₂)/u_e, in [−2, 2].
    temperature : float — [degC]
        Inlet (oil) temperature.
    lubricant : str or Lubricant
        A bundled oil name or file (:func:`friction.lubricant.load_lubricant`).
    e_prime : float — [MPa]
        E′ = 2E* (default steel on steel).
    roughness_1, roughness_2 : array (n,) or None — [µm]
        Heights of surface 1 and 2 on the solver's grid (positive towards the other
        surface); ``None`` is smooth.
    viscosity_model : {"barus", "roelands"}
        Viscosity–pressure law of the film and its shear (:mod:`friction.ehl.rheology`).
        Barus (default) with the oil table's α: the one law of the solver, the friction
        study and the μ model built on it. Roelands with its index Z matched to the same
        α gives 2 Pa s at 1 GPa for 75W90 at 90 °C, two orders of magnitude below gear
        oils' measured high-pressure viscosity, and a film traction of 0.005–0.01, below
        every published gear-oil value (docs/ehl.md); it stays selectable.
    eyring_stress : float or None — [MPa]
        τ₀; default the lubricant's ``eyring_stress``.
    limiting_shear_coefficient : float or None — [1]
        Λ; default the lubricant's.
    boundary_friction : float or None — [1]
        μ_b on the contact nodes; default the lubricant's at the inlet ``temperature``
        (a measured table's interpolated there, held at its end values outside it,
        :func:`friction.lubricant.boundary_friction_coefficient`; not at the flash
        temperature).
    """

    load_per_length: float
    radius: float
    entraining_velocity: float
    slide_to_roll: float
    temperature: float
    lubricant: str | Lubricant = "75W90"
    e_prime: float = STEEL_E_PRIME
    roughness_1: ArrayLike | None = None
    roughness_2: ArrayLike | None = None
    viscosity_model: str = "barus"
    eyring_stress: float | None = None
    limiting_shear_coefficient: float | None = None
    boundary_friction: float | None = None


@dataclass(frozen=True)
class Grid:
    """Solver grid in units of the Hertz half-width b.

    Parameters
    ----------
    nodes : int
        Number of nodes, 16 … 16384.
    inlet, outlet : float — [1]
        Domain X ∈ [inlet, outlet], inlet ≤ −1.5, outlet ≥ 1.2.
    tolerance : float — [1]
        Convergence: max |ΔP| and the scaled residual below it.
    max_iterations : int
    step_limit : float — [1]
        Largest max |ΔP| of one Newton step (longer steps are scaled down).
    roughness_steps : int
        Steps of the homotopy in the roughness amplitude (rough surfaces).
    cycle_limit : int
        The Newton iteration stops with :class:`ConvergenceError` when the same set of
        contact and cavitation nodes is entered this many times (the sets cycle), ≥ 2.
    """

    nodes: int = 512
    inlet: float = -4.0
    outlet: float = 1.5
    tolerance: float = 1e-9
    max_iterations: int = 200
    step_limit: float = 0.3
    roughness_steps: int = 4
    cycle_limit: int = 4

    def coordinates(self) -> Array:
        """Node abscissae X (nodes,) [1]."""
        return np.linspace(self.inlet, self.outlet, self.nodes)

    def check(self) -> None:
        """Raise :class:`InputError` naming the field out of range."""
        integer("grid.nodes", self.nodes, low=16, high=16384)
        real("grid.inlet", self.inlet, high=-1.5)
        real("grid.outlet", self.outlet, low=1.2)
        real("grid.tolerance", self.tolerance, low=1e-14, high=1e-3)
        integer("grid.max_iterations", self.max_iterations, low=1)
        integer("grid.cycle_limit", self.cycle_limit, low=2)


class LineContactSummary(NamedTuple):
    """Scalar results of one condition (units in the field names' docs)."""

    friction_coefficient: float      #: μ [1]
    fluid_friction: float            #: film part of μ [1]
    boundary_part: float             #: asperity (boundary) part of μ [1]
    film_central: float              #: h_c at X = 0 [µm]
    film_min: float                  #: min h [µm]
    asperity_load_ratio: float       #: ∫_contact p dx / w′ [1]
    contact_area_ratio: float        #: contact length / 2b [1]
    lambda_ratio: float              #: smooth-film h_min / composite Rq [1] (inf if smooth)


def hertz_line_contact(load_per_length: float, radius: float, e_prime: float
                       ) -> tuple[float, float]:
    """Hertz half-width b [mm] and maximum pressure p_h [MPa] of a line contact.

    Parameters
    ----------
    load_per_length : float — [N/mm]
    radius : float — [mm]
    e_prime : float — [MPa]
        E′ = 2E*.

    Returns
    -------
    (b, p_h) : (float [mm], float [MPa])
        b = √(8w′R/(πE′)), p_h = 2w′/(πb) = E′b/(4R).

    Notes
    -----
    Source: Johnson, *Contact Mechanics* (1985), Eq. 4.45 with E* = E′/2.
    """
    b = math.sqrt(8.0 * load_per_length * radius / (math.pi * e_prime))
    return b, 2.0 * load_per_length / (math.pi * b)


@dataclass
class ContactSetup:
    """A line-contact condition made dimensionless on its grid (:func:`contact_setup`).

    Grid X [1], spacing Δ [1], Hertz b [m] and p_h [Pa], R [m], η₀ [Pa s], α [1/Pa], λ̄ [1],
    the summed roughness [H units], the viscosity model, τ₀ [Pa], Λ [1], μ_b [1], the
    composite Rq σ [µm] and the deflection kernel.
    """

    x: Array
    spacing: float
    b: float          # [m]
    ph: float         # [Pa]
    radius: float     # [m]
    eta0: float       # [Pa s]
    alpha: float      # [1/Pa]
    lambda_bar: float
    roughness: Array  # dimensionless sum of heights
    viscosity_fn: object
    tau0: float       # [Pa]
    lim: float
    mu_b: float
    sigma: float      # composite Rq [µm]
    kernel: ElasticKernel = field(repr=False)
    kernel_matrix: Array = field(repr=False)


def condition_boundary_friction(condition: LineContactCondition) -> float:
    """The boundary friction μ_b [1] of a line-contact condition's asperity contacts.

    Parameters
    ----------
    condition : LineContactCondition

    Returns
    -------
    float — [1]
        The condition's ``boundary_friction`` where given, else the lubricant's at the
        condition's inlet temperature (:func:`friction.lubricant.boundary_friction_coefficient`:
        a measured table interpolated linearly, held at its end values outside it).

    Raises
    ------
    InputError
        Neither gives one, or a value outside [0, 1] (naming ``boundary_friction``).

    Warns
    -----
    FrictionModelRangeWarning
        The inlet temperature outside the oil's measured μ_b table.
    """
    if condition.boundary_friction is not None:
        return real("boundary_friction", condition.boundary_friction, unit="1", low=0.0,
                    high=1.0)
    oil = lubricant_of(condition.lubricant)
    if oil.boundary_friction is None:
        raise InputError(f"boundary_friction: the lubricant {oil.name!r} gives none; pass one (1)")
    return float(boundary_friction_coefficient(oil, condition.temperature))


def lubricant_of(lubricant: str | Lubricant) -> Lubricant:
    """The oil of a condition: a Lubricant as given, a bundled name or a file loaded.

    Raises
    ------
    InputError
        An unknown oil (the message names ``lubricant``).
    """
    if isinstance(lubricant, Lubricant):
        return lubricant
    try:
        return load_lubricant(lubricant)
    except ModelUnavailableError as exc:
        raise InputError(f"lubricant: {exc}") from exc


def _roughness(name: str, value: ArrayLike | None, n: int) -> Array:
    if value is None:
        return np.zeros(n)
    try:
        arr = real_array(name, value, unit="µm", ndim=1)
    except InputError:
        raise
    if arr.size != n:
        raise InputError(f"{name}: must have one height per grid node ({n}), got {arr.size}")
    return arr


def _checked(cond: LineContactCondition) -> tuple[float, float, float, float, str, Lubricant]:
    """The condition's scalars checked (named): w′, R, u_e, E′, viscosity model, oil."""
    w = real("load_per_length", cond.load_per_length, unit="N/mm", low=0.0, low_open=True)
    r = real("radius", cond.radius, unit="mm", low=RADIUS_RANGE[0], high=RADIUS_RANGE[1])
    ue = real("entraining_velocity", cond.entraining_velocity, unit="m/s", low=0.0,
              low_open=True, high=MAX_ENTRAINING_VELOCITY)
    real("slide_to_roll", cond.slide_to_roll, unit="1", low=-2.0, high=2.0)
    ep = real("e_prime", cond.e_prime, unit="MPa", low=1e3, high=1e7)
    ph = math.sqrt(w * ep / (2.0 * math.pi * r))
    if ph > MAX_HERTZ_PRESSURE:
        raise InputError(f"load_per_length: {w:g} N/mm on R {r:g} mm gives a Hertz pressure of "
                         f"{ph:.0f} MPa, above {MAX_HERTZ_PRESSURE:g} MPa (beyond the shakedown "
                         "limit of every steel; a lubricated steel contact is refused there)")
    model = one_of("viscosity_model", cond.viscosity_model, VISCOSITY_PRESSURE_MODELS)
    oil = lubricant_of(cond.lubricant)
    viscosity(oil, cond.temperature)                        # the temperature in the oil's range
    return w, r, ue, ep, model, oil


def contact_setup(cond: LineContactCondition, grid: Grid) -> ContactSetup:
    """A condition's dimensionless problem on a grid: Hertz scales, oil, kernel, roughness.

    Parameters
    ----------
    cond : LineContactCondition
    grid : Grid

    Returns
    -------
    ContactSetup

    Raises
    ------
    InputError
        An input out of range (named).
    """
    grid.check()
    w, r, ue, ep, model, oil = _checked(cond)
    eta0 = float(viscosity(oil, cond.temperature))
    alpha = float(pressure_viscosity_coefficient(oil, cond.temperature)) * 1e-9
    b_mm, ph_mpa = hertz_line_contact(w, r, ep)
    b, ph, rm = b_mm * 1e-3, ph_mpa * 1e6, r * 1e-3
    x = grid.coordinates()
    spacing = float(x[1] - x[0])
    r1 = _roughness("roughness_1", cond.roughness_1, grid.nodes)
    r2 = _roughness("roughness_2", cond.roughness_2, grid.nodes)
    rough = (r1 + r2) * 1e-6 * rm / b**2
    sigma = float(math.hypot(np.std(r1), np.std(r2)))

    def param(name: str, given: float | None, oil_value: float | None, unit: str,
              low: float, high: float) -> float:
        value = given if given is not None else oil_value
        if value is None:
            raise InputError(f"{name}: the lubricant {oil.name!r} gives none; pass one ({unit})")
        return real(name, value, unit=unit, low=low, high=high)

    tau0 = param("eyring_stress", cond.eyring_stress, oil.eyring_stress, "MPa", 1e-3, 1e3) * 1e6
    lim = param("limiting_shear_coefficient", cond.limiting_shear_coefficient,
                oil.limiting_shear_coefficient, "1", 0.0, math.inf)
    mu_b = condition_boundary_friction(cond)
    kernel = ElasticKernel(grid.nodes, spacing)
    return ContactSetup(
        x=x, spacing=spacing, b=b, ph=ph, radius=rm, eta0=eta0, alpha=alpha,
        lambda_bar=12.0 * eta0 * ue * rm**2 / (b**3 * ph), roughness=rough,
        viscosity_fn=VISCOSITY_PRESSURE_MODELS[model], tau0=tau0, lim=lim, mu_b=mu_b,
        sigma=sigma, kernel=kernel, kernel_matrix=kernel.matrix(),
    )


def node_state(s: ContactSetup, p: Array, h0: float) -> NodeState:
    """Film, density and viscosity at pressures P (n,) [1] and approach H₀ [1].

    H = H₀ + X²/2 + D P − roughness (DC-FFT), viscosity by the condition's model
    (:mod:`friction.ehl.rheology`), density by Dowson–Higginson.
    """
    film = h0 + 0.5 * s.x**2 + s.kernel.deflection(p) - s.roughness
    eta, dln = s.viscosity_fn(p * s.ph, s.eta0, s.alpha)  # type: ignore[operator]
    rho, drho = dowson_higginson_density(p * s.ph)
    return NodeState(pressure=p, film=film, density=rho, ddensity=drho * s.ph,
                     viscosity=eta / s.eta0, dln_viscosity=dln * s.ph)


def initial_pressure(s: ContactSetup, cond: LineContactCondition) -> tuple[Array, float]:
    """Hertz's pressure and the approach giving Pan–Hamrock's central film: a start (P, H₀)."""
    """Hertz pressure and a rigid approach giving the Pan–Hamrock central film."""
    p = np.sqrt(np.clip(1.0 - s.x**2, 0.0, None))
    p *= (0.5 * math.pi) / (p.sum() * s.spacing)
    e_prime = cond.e_prime * 1e6
    big_u = s.eta0 * cond.entraining_velocity / (e_prime * s.radius)
    big_w = cond.load_per_length * 1e3 / (e_prime * s.radius)
    hc = 2.922 * big_w**-0.166 * big_u**0.692 * (s.alpha * e_prime) ** 0.470  # h_c/R
    hc_dimless = hc * s.radius**2 / s.b**2
    film0 = 0.5 * s.x**2 + s.kernel.deflection(p)
    centre = int(np.argmin(np.abs(s.x)))
    return p, float(hc_dimless - film0[centre])


def _update_sets(kind: NDArray[np.int_], st: NodeState, s: ContactSetup) -> int:
    """Move nodes between fluid, cavitation and contact; return how many changed."""
    old = kind.copy()
    p, h = st.pressure, st.film
    kind[(kind != CAVITATION) & (p < 0.0)] = CAVITATION
    res = reynolds_residual(st, s.spacing, s.lambda_bar)
    # a cavitation node is released only next to a pressurised fluid node, so the
    # cavitation boundary moves at most one node per iteration (no fluid/cavitation cycling)
    wet = (old == FLUID) & (p > 0.0)
    beside = np.zeros_like(wet)
    beside[1:] |= wet[:-1]
    beside[:-1] |= wet[1:]
    kind[(old == CAVITATION) & (res > 0.0) & (h > 0.0) & beside] = FLUID
    kind[(h < 0.0) & (p >= 0.0)] = CONTACT
    kind[0] = kind[-1] = CAVITATION
    return int(np.count_nonzero(kind != old))


_KIND_NAMES = {FLUID: "fluid", CAVITATION: "cavitation", CONTACT: "contact"}


def _check_cycle(kind: NDArray[np.int_], before: NDArray[np.int_], entered: dict[bytes, int],
                 iteration: int, limit: int) -> None:
    """Log a change of the node sets; raise :class:`ConvergenceError` when they cycle.

    ``entered`` counts how often each set has been entered by a change; the same set
    entered ``limit`` times means the iteration goes round a cycle of sets and will not
    settle (the Newton steps between the changes are then wasted).
    """
    moved = np.flatnonzero(kind != before)
    log.debug("newton %d: %d node(s) changed state: %s", iteration, moved.size,
              ", ".join(f"{i} {_KIND_NAMES[int(before[i])]}->{_KIND_NAMES[int(kind[i])]}"
                        for i in moved[:8]))
    key = kind.tobytes()
    entered[key] = entered.get(key, 0) + 1
    if entered[key] >= limit:
        raise ConvergenceError(
            f"line contact: the contact/cavitation node sets cycle (the same set entered "
            f"{entered[key]} times by iteration {iteration}; nodes {moved[:8].tolist()} "
            f"switch, e.g. {_KIND_NAMES[int(before[moved[0]])]} -> "
            f"{_KIND_NAMES[int(kind[moved[0]])]}); the rough mixed regime of this steady "
            f"solver does not converge here (docs/ehl.md, Validity)")


def steady_active_set(s: ContactSetup, p: Array, h0: float, grid: Grid,
                      kind: NDArray[np.int_] | None = None,
                      ) -> tuple[Array, float, NDArray[np.int_], int]:
    """The steady film by Newton's method with an active set of contact and cavitation nodes.

    Parameters
    ----------
    s : ContactSetup
        The condition on its grid (:func:`contact_setup`); ``s.roughness`` frozen.
    p : array (n,) — [1]
        Start P (e.g. :func:`initial_pressure`).
    h0 : float — [1]
        Start rigid approach H₀.
    grid : Grid
        Tolerance, iteration, step and cycle limits.
    kind : int array (n,), optional
        Start node sets (:data:`~friction.ehl.reynolds.FLUID` …); default all fluid.

    Returns
    -------
    (P (n,), H₀, kind (n,), iterations)

    Raises
    ------
    ConvergenceError
        No convergence, a non-finite iterate, or cycling node sets (docs/ehl.md).

    Notes
    -----
    Contact nodes (H = 0) are released only at P < 0, cavitation nodes only beside a
    pressurised fluid node (Christopherson); the Jacobian is
    :func:`friction.ehl.reynolds.assemble`'s. Source: Houpert & Hamrock (1986).
    """
    n = p.size
    if kind is None:
        kind = np.full(n, FLUID)
    kind = kind.copy()
    kind[0] = kind[-1] = CAVITATION
    load_row = np.full(n + 1, s.spacing)
    load_row[-1] = 0.0
    entered: dict[bytes, int] = {}
    for it in range(1, grid.max_iterations + 1):
        st = node_state(s, p, h0)
        res, jac = assemble(st, kind, s.kernel_matrix, s.spacing, s.lambda_bar)
        full = np.vstack([jac, load_row])
        rhs = np.concatenate([res, [p.sum() * s.spacing - 0.5 * math.pi]])
        step = lu_solve(lu_factor(full), -rhs)
        dp, dh0 = step[:n], step[n]
        big = float(np.max(np.abs(dp)))
        omega = min(1.0, grid.step_limit / big) if big > 0 else 1.0
        p = p + omega * dp
        h0 = h0 + omega * dh0
        p[kind == CAVITATION] = 0.0
        st = node_state(s, p, h0)
        before = kind.copy()
        changed = _update_sets(kind, st, s)
        if changed:
            _check_cycle(kind, before, entered, it, grid.cycle_limit)
        p = np.where(kind == CAVITATION, 0.0, np.maximum(p, 0.0))
        if not np.all(np.isfinite(p)) or not math.isfinite(h0):
            raise ConvergenceError("line contact: the Newton iteration diverged (non-finite)")
        if changed == 0 and omega == 1.0 and big < grid.tolerance:
            # the load balance is exact after a full Newton step of a linear row
            p *= (0.5 * math.pi) / (p.sum() * s.spacing)
            return p, h0, kind, it
    raise ConvergenceError(
        f"line contact: no convergence in {grid.max_iterations} Newton iterations "
        f"(last max |ΔP| = {big:.2e}); refine the grid or widen the inlet")


def film_and_boundary_friction(s: ContactSetup, cond: LineContactCondition, st: NodeState,
                               kind: NDArray[np.int_], thermal: bool = False
                               ) -> tuple[Array, float, float, float]:
    """Film shear stress τ(x) [Pa], the fluid and boundary friction forces [N/m], load [N/m].

    Eyring shear with the limiting shear stress on open non-contact nodes, μ_b p on
    contact nodes (seed Eq. 5.7–5.8); the load is ∫ p dx. With ``thermal`` the film
    shears at the surfaces' temperature — the inlet's plus the flash temperature of the
    friction heat (Jaeger's moving band source on both surfaces, split by their speeds,
    :func:`friction.ehl.thermal.flash_temperature`; the materials table's default steel),
    iterated to a fixed point relaxed by half — the stochastic solver's thermal footing
    (:mod:`friction.ehl.stochastic`), so that a rough contact's μ tends to the smooth
    one's as Rq → 0 (issue 61); without it at the inlet temperature.
    """
    b = s.b
    h = np.maximum(st.film, 0.0) * b**2 / s.radius  # [m]
    p = st.pressure * s.ph
    us = cond.slide_to_roll * cond.entraining_velocity
    fluid = (kind != CONTACT) & (h > 0.0)
    rate = np.where(fluid, us / np.where(h > 0.0, h, 1.0), 0.0)
    tau = eyring_limited_shear(st.viscosity * s.eta0, rate, p, s.tau0, s.lim)
    tau = np.where(fluid, tau, 0.0)
    dx = s.spacing * b
    if thermal and us != 0.0:
        tau = _thermal_shear(s, cond, p, rate, fluid, kind, dx)
    f_fluid = float(np.abs(tau).sum() * dx)
    w = float(p.sum() * dx)
    f_boundary = s.mu_b * float(p[kind == CONTACT].sum() * dx)
    return tau, f_fluid, f_boundary, w


def _thermal_shear(s: ContactSetup, cond: LineContactCondition, p: Array, rate: Array,
                   fluid: NDArray[np.bool_], kind: NDArray[np.int_], dx: float) -> Array:
    """τ(x) [Pa] at the inlet temperature plus the flash temperature of the heat of the
    film's shear and of the boundary friction, to a fixed point (0.05 K, ≤ 60 steps)."""
    from friction.ehl.stochastic import film_oil_properties  # (stochastic imports this module)
    from friction.ehl.thermal import flash_temperature
    from geometry.core.materials import DEFAULT_MATERIAL, material

    oil = lubricant_of(cond.lubricant)
    model = VISCOSITY_PRESSURE_MODELS[cond.viscosity_model]
    ue, sr = cond.entraining_velocity, cond.slide_to_roll
    us = abs(sr * ue)
    effusivity = material(DEFAULT_MATERIAL).thermal_effusivity
    speeds = [u for u in (abs(ue * (1.0 + 0.5 * sr)), abs(ue * (1.0 - 0.5 * sr))) if u > 0.0]
    boundary_flux = np.where(kind == CONTACT, s.mu_b * p * us, 0.0)   # [W/m2]
    flash = np.zeros(p.size)
    tau = np.zeros(p.size)
    for _ in range(60):
        eta0, alpha = film_oil_properties(oil, float(cond.temperature) + flash)
        eta, _ = model(p, eta0, alpha)  # type: ignore[operator]
        tau = np.where(fluid, eyring_limited_shear(eta, rate, p, s.tau0, s.lim), 0.0)
        q = 0.5 * (np.abs(tau) * us + boundary_flux)                    # each surface's
        new_flash = 0.5 * sum(flash_temperature(q, dx, u, effusivity) for u in speeds)
        change = float(np.max(np.abs(new_flash - flash)))
        flash = 0.5 * (flash + new_flash)
        if change < 0.05:
            break
    return tau


def smooth_lambda_ratio(s: ContactSetup, cond: LineContactCondition) -> float:
    """λ: Pan–Hamrock's smooth minimum film over the composite Rq (inf if smooth) [1]."""
    if s.sigma == 0.0:
        return math.inf
    e_prime = cond.e_prime * 1e6
    big_u = s.eta0 * cond.entraining_velocity / (e_prime * s.radius)
    big_w = cond.load_per_length * 1e3 / (e_prime * s.radius)
    hmin = 1.714 * big_w**-0.128 * big_u**0.694 * (s.alpha * e_prime) ** 0.568 * s.radius
    return hmin * 1e6 / s.sigma


#: [1] dimensionless film H (units b²/R) at or below which a loaded node counts as closed:
#: a thousand times the round-off of H ≈ 1e-16 seen on contact nodes, far below any film
#: the grid resolves (1e-12 b²/R is ~1e-18 m for b = 0.2 mm, R = 20 mm)
CLOSED_FILM = 1e-12


#: (Moes M, nodes): a smooth film's grid takes the nodes of the first row whose M bound
#: exceeds the condition's (measured against 4096 nodes, central film within 3 %: at
#: M ≈ 200, 1024 nodes were 3 % thin; at M ≈ 770, 27 % thin and 4096 needed)
SMOOTH_NODES = ((30.0, 512), (100.0, 1024), (300.0, 2048), (math.inf, 4096))

#: the most nodes a smooth film is refined to while its solution shows a closed film (the
#: steady solver's dense Newton matrix: 4096 nodes take ~5 s per iteration, 134 MB)
SMOOTH_NODES_MAX = 4096

#: [µm] below this central film (Moes) a smooth contact is dry: a film of under a
#: nanometre is a few molecules, not a continuum (boundary lubrication)
DRY_FILM = 1e-3


def smooth_grid(condition: LineContactCondition) -> Grid:
    """The grid of a smooth film: its nodes from Moes's load parameter M.

    Parameters
    ----------
    condition : LineContactCondition

    Returns
    -------
    Grid
        :data:`SMOOTH_NODES` nodes; the inlet and outlet of
        :func:`friction.ehl.transient.default_transient_grid` (the smooth film's pressure
        build-up with half a Hertz width to spare, 1.5 b behind).

    Notes
    -----
    At large M the pressure spike and the exit constriction narrow, and a grid too coarse
    for them closes the film (the friction study's 256 nodes gave h = 0 and μ ≈ μ_b at
    M ≥ 700, where 4096 nodes give a film within 3–7 % of Pan–Hamrock: issue 51).
    """
    from friction.ehl.transient import default_transient_grid
    from friction.film import moes_load_parameter

    oil = lubricant_of(condition.lubricant)
    m = float(moes_load_parameter(condition.entraining_velocity,
                                  float(viscosity(oil, condition.temperature)),
                                  condition.load_per_length, condition.radius,
                                  condition.e_prime))
    nodes = next(n for bound, n in SMOOTH_NODES if m < bound)
    return default_transient_grid(condition, nodes)


def _moes_film(cond: LineContactCondition) -> float:
    """Moes's central film of the condition [µm]."""
    from friction.film import moes_central

    oil = lubricant_of(cond.lubricant)
    return float(moes_central(cond.entraining_velocity, float(viscosity(oil, cond.temperature)),
                              float(pressure_viscosity_coefficient(oil, cond.temperature)),
                              cond.load_per_length, cond.radius, cond.e_prime))


def _solve(cond: LineContactCondition, grid: Grid | None, thermal: bool = False):
    if grid is not None:
        grid.check()
    _checked(cond)
    # a smooth film of a nanometre or more: on the nodes its Moes M asks, unless given
    film = smooth = cond.roughness_1 is None and cond.roughness_2 is None
    if smooth:
        film = _moes_film(cond) >= DRY_FILM
    if grid is None:
        grid = smooth_grid(cond) if film else Grid()
    while True:
        out = _solve_on(cond, grid, thermal)
        kind = out[2]
        if not film or not np.any(kind == CONTACT):
            return out
        # a smooth film of a nanometre or more never closes: contact nodes are a grid too
        # coarse for the pressure spike and the exit constriction
        if grid.nodes >= SMOOTH_NODES_MAX:
            raise ConvergenceError(
                f"line contact: the smooth film closes (dry contact) even at {grid.nodes} "
                f"nodes, where Moes's formula gives {_moes_film(cond):.4f} um; no "
                f"converged film")
        nodes = min(max(2 * grid.nodes, smooth_grid(cond).nodes), SMOOTH_NODES_MAX)
        log.info("smooth film closed on %d nodes: solved again on %d", grid.nodes, nodes)
        grid = dataclasses.replace(grid, nodes=nodes)


def _solve_on(cond: LineContactCondition, grid: Grid, thermal: bool = False):
    s = contact_setup(cond, grid)
    p, h0 = initial_pressure(s, cond)
    rough = s.roughness
    iterations = 0
    kind = None
    # homotopy in the roughness amplitude: the smooth film first, then the roughness grown
    # in grid.roughness_steps steps, each started from the last (contacts appear gradually,
    # so the active set follows the physical branch instead of jumping into over-contact)
    steps = grid.roughness_steps if np.any(rough != 0.0) else 0
    for fraction in np.linspace(0.0, 1.0, steps + 1) if steps else (1.0,):
        s.roughness = fraction * rough
        p, h0, kind, its = steady_active_set(s, p, h0, grid, kind)
        iterations += its
    st = node_state(s, p, h0)
    # a node the Newton iteration left "fluid" with a closed film (zero to round-off) and a
    # pressure is a contact: the two labels are degenerate there (with ε ≈ 0 the Reynolds
    # row is satisfied either way) and which one the active set ends on depended on the
    # BLAS's round-off (the dry limit gave an asperity load ratio of 0.95 or 1.0 with one
    # or two BLAS threads)
    kind = np.where((kind == FLUID) & (st.film <= CLOSED_FILM) & (st.pressure > 0.0),
                    CONTACT, kind)
    tau, f_fluid, f_boundary, w = film_and_boundary_friction(s, cond, st, kind, thermal)
    return s, st, kind, tau, f_fluid, f_boundary, w, iterations, grid


def _summary(s, cond, st, kind, f_fluid, f_boundary, w) -> LineContactSummary:
    h_um = np.maximum(st.film, 0.0) * s.b**2 / s.radius * 1e6
    p = st.pressure
    centre = int(np.argmin(np.abs(s.x)))
    zone = p > 0.0
    contact_load = float(p[kind == CONTACT].sum() * s.spacing) / (0.5 * math.pi)
    return LineContactSummary(
        friction_coefficient=(f_fluid + f_boundary) / w,
        fluid_friction=f_fluid / w,
        boundary_part=f_boundary / w,
        film_central=float(h_um[centre]),
        film_min=float(h_um[zone].min()) if zone.any() else float(h_um.min()),
        asperity_load_ratio=contact_load,
        contact_area_ratio=float(np.count_nonzero(kind == CONTACT) * s.spacing / 2.0),
        lambda_ratio=smooth_lambda_ratio(s, cond),
    )


def line_contact_summary(condition: LineContactCondition, grid: Grid | None = None, *,
                         thermal: bool = False) -> LineContactSummary:
    """Scalar results of one steady line contact (no dataset built).

    Parameters
    ----------
    condition : LineContactCondition
    grid : Grid, optional
        Default: a smooth film's from Moes's M (:func:`smooth_grid`), :class:`Grid()`
        (512 nodes over −4 … 1.5 b) with rough heights. A smooth film whose solution
        closes anywhere is solved again on twice the nodes (up to
        :data:`SMOOTH_NODES_MAX`), whatever the grid given: a smooth EHL film never closes,
        unless Moes's formula puts it below :data:`DRY_FILM` (a dry contact).
    thermal : bool
        The film's shear at the surfaces' flash temperature, as the stochastic solver's
        (:func:`film_and_boundary_friction`); default False, at the inlet temperature.

    Returns
    -------
    LineContactSummary
        μ and its parts [1], h_c and h_min [µm], the asperity load and contact-area
        ratios [1], the smooth-film λ [1].

    Raises
    ------
    InputError
        An input out of range (named).
    ConvergenceError
        The Newton iteration did not converge.

    Notes
    -----
    Source: the seed's §5.2.2 model (Li & Kahraman 2010) in its steady form; see the
    module docstring and ``docs/ehl.md``.
    """
    s, st, kind, _tau, f_fluid, f_boundary, w, _, _grid = _solve(condition, grid, thermal)
    return _summary(s, condition, st, kind, f_fluid, f_boundary, w)


def condition_attrs(condition: LineContactCondition) -> dict[str, str | float]:
    """The condition as a solution dataset's attributes (every line-contact solver's file
    records it the same way): lubricant and viscosity model, w′ [N/mm], R [mm], u_e [m/s],
    SR [1], inlet temperature [degC] and E′ [MPa], units in the names, and the boundary
    friction μ_b [1] the asperity contacts had (:func:`condition_boundary_friction`)."""
    return {
        "lubricant": lubricant_of(condition.lubricant).name,
        "viscosity_model": condition.viscosity_model,
        "load_per_length_N_per_mm": float(condition.load_per_length),
        "radius_mm": float(condition.radius),
        "entraining_velocity_m_per_s": float(condition.entraining_velocity),
        "slide_to_roll": float(condition.slide_to_roll),
        "temperature_degC": float(condition.temperature),
        "e_prime_MPa": float(condition.e_prime),
        "boundary_friction": condition_boundary_friction(condition),
    }


def _var(data, dims, units: str, long_name: str) -> tuple:
    return data_var(dims, np.asarray(data, dtype=float), units, long_name)


def solve_line_contact(condition: LineContactCondition, grid: Grid | None = None, *,
                       thermal: bool = False) -> xr.Dataset:
    """Solve one steady mixed-EHL line contact and return its dataset.

    Parameters
    ----------
    condition : LineContactCondition
    grid : Grid, optional
        As :func:`line_contact_summary`.
    thermal : bool
        As :func:`line_contact_summary` (the attribute ``thermal`` records it, 0/1).

    Returns
    -------
    xarray.Dataset
        Dimension ``x`` [mm] (from the contact centre, positive in the rolling direction);
        variables ``pressure`` [MPa], ``film_thickness`` [µm], ``roughness`` [µm],
        ``shear_stress`` [MPa], ``contact`` [1] (1 on contact nodes), ``viscosity``
        [Pa s]; scalars ``friction_coefficient``, ``fluid_friction``, ``boundary_friction_part``,
        ``asperity_load_ratio``, ``contact_area_ratio``, ``lambda_ratio`` [1],
        ``film_central``, ``film_min`` [µm], ``hertz_pressure`` [MPa], ``hertz_half_width``
        [mm].

    Raises
    ------
    InputError
        An input out of range (named).
    ConvergenceError
        The Newton iteration did not converge.

    Notes
    -----
    Source: the seed's §5.2.2 model (Li & Kahraman 2010) in its steady form with Hu & Zhu's
    unified Reynolds equation; ``docs/ehl.md`` gives the equations and validity.
    """
    s, st, kind, tau, f_fluid, f_boundary, w, iterations, used = _solve(condition, grid, thermal)
    summ = _summary(s, condition, st, kind, f_fluid, f_boundary, w)
    x_mm = s.x * s.b * 1e3
    h_um = np.maximum(st.film, 0.0) * s.b**2 / s.radius * 1e6
    rough_um = s.roughness * s.b**2 / s.radius * 1e6
    scalar = {
        "friction_coefficient": (summ.friction_coefficient, "1", "friction coefficient μ"),
        "fluid_friction": (summ.fluid_friction, "1", "film (Eyring) part of μ"),
        "boundary_friction_part": (summ.boundary_part, "1", "asperity (boundary) part of μ"),
        "film_central": (summ.film_central, "um", "central film thickness h_c"),
        "film_min": (summ.film_min, "um", "minimum film thickness h_min"),
        "asperity_load_ratio": (summ.asperity_load_ratio, "1",
                                "share of the load carried by contact nodes"),
        "contact_area_ratio": (summ.contact_area_ratio, "1",
                               "contact length over Hertz width 2b"),
        "lambda_ratio": (summ.lambda_ratio if math.isfinite(summ.lambda_ratio) else -1.0, "1",
                         "smooth-film h_min (Pan-Hamrock) over composite Rq; -1 if smooth"),
        "hertz_pressure": (s.ph * 1e-6, "MPa", "Hertz maximum pressure p_h"),
        "hertz_half_width": (s.b * 1e3, "mm", "Hertz half-width b"),
    }
    data = {k: _var(v, (), u, ln) for k, (v, u, ln) in scalar.items()}
    data.update({
        "pressure": _var(st.pressure * s.ph * 1e-6, ("x",), "MPa", "film and contact pressure"),
        "film_thickness": _var(h_um, ("x",), "um", "film thickness h"),
        "roughness": _var(rough_um, ("x",), "um", "sum of the surfaces' roughness heights"),
        "shear_stress": _var(tau * 1e-6, ("x",), "MPa", "film shear stress (Eyring)"),
        "contact": _var((kind == CONTACT).astype(float), ("x",), "1",
                        "1 on asperity-contact nodes"),
        "viscosity": _var(st.viscosity * s.eta0, ("x",), "Pa s", "film viscosity"),
    })
    x_attrs = {"units": "mm", "long_name": "distance from contact centre"}
    ds = xr.Dataset(data, coords={"x": ("x", x_mm, x_attrs)})
    ds.attrs.update({
        "title": "mixed-EHL line contact (steady)",
        **condition_attrs(condition),
        "newton_iterations": iterations,
        "grid_nodes": int(used.nodes), "grid_inlet": float(used.inlet),
        "grid_outlet": float(used.outlet), "thermal": int(thermal),
    })
    return ds
