"""Mixed-EHL line contact with the roughness described statistically: full film to dry.

The solver that carries the seed's friction study (§5.2.2–5.2.3): one line contact of
two rough flanks under a load, speed, slide-to-roll ratio and oil temperature, solved
for the pressure the oil carries, the pressure the roughness summits carry, the film
between them and the friction of both. The roughness enters through its statistics
(:mod:`friction.ehl.asperity`), measured on the same ground profiles the resolved model
(:mod:`friction.ehl.transient`) moves through the contact; why the asperity scale is
described statistically and not resolved on the grid is the finding of docs/ehl.md
("Why the asperities never carried the load").

Equations (dimensionless as :mod:`friction.ehl.reynolds`: X = x/b, P = p/p_h,
H = hR/b², σ̄ = σR/b² with σ the composite RMS roughness):

* **Separation of the mean planes** H = H₀ + X²/2 + D P, D the line contact's elastic
  deflection of the *total* pressure P = P_f + P_a (:mod:`friction.ehl.kernel`).
* **Asperities**: P_a = p_a(H)/p_h, Greenwood & Williamson's summits with Chang, Etsion &
  Bogy's elastic–plastic law on the composite summit statistics
  (:func:`friction.ehl.asperity.asperity_contact`).
* **Oil**: P_f = P − P_a ≥ 0 obeys the average-flow Reynolds equation of Patir & Cheng,
  d/dX(ρ̄ φ_x H³/(η̄λ̄) dP_f/dX) = d/dX[ρ̄(h_T + (SR/2)σ̄ Φ_s)], with the pressure- and
  shear-flow factors and the mean gap h_T of :mod:`friction.ehl.flow_factors`, the
  viscosity η̄(P_f) and density ρ̄(P_f) of the oil at its own pressure (not the summits'),
  and the Reynolds (Christopherson) cavitation condition P_f ≥ 0 by an active set of
  cavitated nodes (as the steady smooth solver), the nodes that keep switching by the
  semismooth row min(P_f, −κR).
* **Load**: Δ Σ P = π/2.

Newton's method on (P, H₀) with the exact Jacobian: every row is local in P_f and H, so
the Newton matrix is A + B[D | 1] of :class:`friction.ehl.newton_system.NewtonSystem`
(the dense and Krylov solvers of the resolved model); steps limited in P (0.3 p_h) and in
the separation (σ̄); the cavitated set updated after every step.

**Friction** (seed Eq. 5.7–5.9 averaged over the roughness): at each node the oil shears
in every open gap σ̄(H/σ̄ − z) of the Gaussian composite heights z (48-point Gauss–
Hermite) with Eyring's law capped by the limiting shear stress ΛP_f, at the viscosity of
the surfaces' temperature (:mod:`friction.ehl.thermal`: the inlet's plus the flash
temperature the friction heat raises, iterated to a fixed point; ``thermal=False`` keeps
the inlet temperature); the summits rub with the oil's boundary friction μ_b on P_a.
μ = (∫τ dx + μ_b∫p_a dx)/w′.

Limits (tested): σ → 0 is the smooth film; u_e → 0 is Greenwood & Williamson's dry rough
contact (P_f → 0, μ → μ_b); the asperity load ratio rises monotonically as the film
thins.

Sources: Patir, N., Cheng, H. S., J. Lubr. Technol. 100 (1978) 12 and 101 (1979) 220
(average flow); Greenwood & Williamson (1966), McCool (1986), Chang, Etsion & Bogy
(1987) (:mod:`friction.ehl.asperity`); the same construction as the stochastic
mixed-EHL line-contact models of Zhu, D., Cheng, H. S., "Effect of surface roughness on
the point contact EHL", J. Tribol. 110 (1988) 32–37, and Masjedi, M., Khonsari, M. M.,
"Film thickness and asperity load formulas for line-contact elastohydrodynamic
lubrication with provision for surface roughness", J. Tribol. 134 (2012) 011503; the
seed's Eq. 5.7–5.9.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time as _time
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from friction.ehl.asperity import (
    AsperityContact,
    SummitStatistics,
    asperity_contact,
    composite_moments,
    profile_moments,
    summit_statistics,
)
from friction.ehl.complementarity import ConvergenceError
from friction.ehl.flow_factors import (
    FIT_LOWER_LIMIT,
    PERCOLATION_AREA,
    mean_gap,
    pressure_flow_conductance,
    shear_flow_factor,
)
from friction.ehl.line_contact import (
    ContactSetup,
    Grid,
    LineContactCondition,
    condition_attrs,
    contact_setup,
    initial_pressure,
    lubricant_of,
    smooth_grid,
    smooth_lambda_ratio,
)
from friction.ehl.newton_system import (
    LINEAR_SOLVERS,
    LinearSolveError,
    NewtonSystem,
    solve_newton_system,
)
from friction.ehl.reynolds import BAND_OFFSETS, NodeState, flow_bands
from friction.ehl.rheology import (
    VISCOSITY_PRESSURE_MODELS,
    dowson_higginson_density,
    eyring_limited_shear,
)
from friction.ehl.roughness import GroundSurface, MeasuredSurface, gaussian_lowpass
from friction.ehl.thermal import flash_temperature
from friction.lubricant import (
    Lubricant,
    pressure_viscosity_coefficient,
    temperature_range,
    viscosity,
)
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.core.materials import DEFAULT_MATERIAL, Material, material
from geometry.core.validation import integer, one_of, real

__all__ = ["RoughnessStatistics", "StochasticOptions", "StochasticSummary", "roughness_statistics",
           "solve_stochastic_line_contact", "stochastic_grid", "stochastic_summary"]

log = logging.getLogger(__name__)

Array = NDArray[np.float64]

Surface = GroundSurface | MeasuredSurface

#: [mm] length of profile over which a ground surface's moments are measured: 20 000
#: samples at 0.5 µm, 12 500 correlation lengths (the moments' sampling scatter < 1 %)
MOMENT_LENGTH = 10.0

#: Gauss–Hermite nodes and weights over the composite heights (probabilists')
_GH_Z, _GH_W = np.polynomial.hermite_e.hermegauss(48)
_GH_W = _GH_W / _GH_W.sum()

#: [degC] highest film temperature at which the oil's Vogel and α fits are evaluated
#: (extrapolated above the oil's table; the rise beyond is reported, not used)
FILM_TEMPERATURE_CAP = 300.0


class RoughnessStatistics(NamedTuple):
    """The two surfaces' roughness as the stochastic solver uses it.

    ``summits`` are of the composite (summed) surface; ``rq`` the RMS roughness of each
    surface [µm] (Patir & Cheng's variance ratios V_ri = Rq_i²/σ²), ``short_cutoff`` the
    λs each was seen through [mm].
    """

    summits: SummitStatistics
    rq: tuple[float, float]
    short_cutoff: tuple[float, float]


def _unit_moments(surface: Surface) -> tuple[tuple[float, float, float], float]:
    """Moments of a surface's profile seen through its λs, scaled to unit Rq, and the λs."""
    if isinstance(surface, GroundSurface):
        raw, spacing = surface.profile(MOMENT_LENGTH)
        cutoff = float(surface.short_cutoff)
    else:
        surface.check()
        raw = np.asarray(surface.heights, dtype=float)
        spacing = float(surface.spacing)
        cutoff = float(surface.short_cutoff)
    z = gaussian_lowpass(raw, spacing, cutoff) if cutoff > 0.0 else raw - raw.mean()
    m0, m2, m4 = profile_moments(z, spacing)
    return (1.0, m2 / m0, m4 / m0), cutoff


def roughness_statistics(surfaces: tuple[Surface, Surface]) -> RoughnessStatistics:
    """Summit statistics of the composite surface of two flanks.

    Parameters
    ----------
    surfaces : (GroundSurface | MeasuredSurface, GroundSurface | MeasuredSurface)
        Each seen through its own short-wave cutoff λs (a ground surface over
        :data:`MOMENT_LENGTH` mm of its reproducible profile; a measured one over its
        heights) and scaled to its Rq.

    Returns
    -------
    RoughnessStatistics

    Raises
    ------
    InputError
        Not two surfaces, both smooth, or a profile whose moments are not a rough
        surface's.

    Notes
    -----
    Independent surfaces add their spectral moments (:func:`friction.ehl.asperity.
    composite_moments`); McCool (1986) turns them into the summit density, radius and
    height statistics.
    """
    if surfaces is None or len(surfaces) != 2:
        raise InputError("surfaces: two surfaces (GroundSurface or MeasuredSurface), one "
                         "per body")
    rq, cut, moments = [], [], []
    for k, s in enumerate(surfaces):
        if not isinstance(s, GroundSurface | MeasuredSurface):
            raise InputError(f"surfaces[{k}]: a GroundSurface or MeasuredSurface, got "
                             f"{type(s).__name__}")
        s.check()
        r = float(s.rq) if isinstance(s, GroundSurface) else float(s.target_rq)
        rq.append(r)
        if r == 0.0:
            cut.append(0.0)
            continue
        unit, c = _unit_moments(s)
        cut.append(c)
        moments.append(tuple(m * r * r for m in unit))
    if not moments:
        raise InputError("surfaces: both smooth; the smooth film is the steady solver's "
                         "(friction.ehl.line_contact.solve_line_contact)")
    return RoughnessStatistics(summit_statistics(*composite_moments(*moments)),
                               (rq[0], rq[1]), (cut[0], cut[1]))


@dataclass(frozen=True)
class StochasticOptions:
    """Settings of the stochastic solver.

    Parameters
    ----------
    tolerance : float — [1]
        Converged when a full Newton step changes no pressure by more than this (in p_h),
        1e-13 … 1e-4.
    max_iterations : int
        Newton iterations before :class:`ConvergenceError`, ≥ 1.
    step_limit : float — [1]
        Largest max |ΔP| of one step (in p_h), > 0.
    separation_step : float — [1]
        Largest change of the separation in one step, in composite RMS roughness, > 0.
    linear_solver : str
        "auto", "dense" or "krylov" (:data:`friction.ehl.newton_system.LINEAR_SOLVERS`).
    thermal : bool
        Evaluate the film's shear at the surfaces' temperature (inlet + flash,
        :mod:`friction.ehl.thermal`); False: at the inlet temperature.
    thermal_tolerance : float — [K]
        The temperatures' fixed point stops when no temperature changes by more, > 0.
    shear_flow : bool
        Include Patir & Cheng's shear-flow term (nonzero only for unequal roughness):
        off by default — it moved μ by 1.4 % RMS (7.7 % at most) and the asperity load
        ratio by 0.013 RMS over 122 conditions of the gear box, and made the Newton
        iteration fail on 2 % more of them (docs/ehl.md).
    material : str
        Of both surfaces (hardness for the summits' plastic limit, thermal effusivity for
        the flash temperature): a name of :func:`geometry.core.materials.available_materials`.
    """

    tolerance: float = 1e-9
    max_iterations: int = 200
    step_limit: float = 0.3
    separation_step: float = 1.0
    linear_solver: str = "auto"
    thermal: bool = True
    thermal_tolerance: float = 0.05
    shear_flow: bool = False
    material: str = DEFAULT_MATERIAL

    def check(self) -> Material:
        """Raise :class:`InputError` naming a field out of range; return the material."""
        real("options.tolerance", self.tolerance, low=1e-13, high=1e-4)
        integer("options.max_iterations", self.max_iterations, low=1)
        real("options.step_limit", self.step_limit, low=0.0, low_open=True)
        real("options.separation_step", self.separation_step, low=0.0, low_open=True)
        one_of("options.linear_solver", self.linear_solver, ("auto", *LINEAR_SOLVERS))
        real("options.thermal_tolerance", self.thermal_tolerance, low=0.0, low_open=True)
        try:
            return material(self.material)
        except Exception as exc:  # ModelUnavailableError: name the field
            raise InputError(f"options.material: {exc}") from None


class StochasticSummary(NamedTuple):
    """Scalars of one solution (units in the field comments)."""

    friction_coefficient: float       #: μ, seed Eq. 5.9 [1]
    fluid_friction: float             #: film part of μ [1]
    boundary_part: float              #: asperity (boundary) part of μ [1]
    film_central: float               #: mean-plane separation at X = 0 [µm]
    film_min: float                   #: least mean-plane separation over the loaded zone [µm]
    mean_gap_central: float           #: mean gap h_T (the oil) at X = 0 [µm]
    asperity_load_ratio: float        #: ∫p_a dx / w′ [1]
    contact_area_ratio: float         #: real contact area / 2b [1]
    lambda_ratio: float               #: Pan–Hamrock smooth h_min over composite Rq [1]
    specific_film_min: float          #: least separation over composite Rq, loaded zone [1]
    temperature_max: float            #: hottest oil (surface) temperature [degC]
    flash_temperature_max: float      #: largest surface flash temperature [K]
    pressure_max: float               #: largest total pressure over p_h [1]
    newton_iterations: int


def _moes_m(condition: LineContactCondition, oil: Lubricant) -> float:
    """Moes' load parameter M = W(2U)^(−1/2) of the condition [1]."""
    ep = condition.e_prime * 1e6
    r = condition.radius * 1e-3
    eta0 = float(viscosity(oil, condition.temperature))
    big_w = condition.load_per_length * 1e3 / (ep * r)
    big_u = eta0 * condition.entraining_velocity / (ep * r)
    return big_w / math.sqrt(2.0 * big_u)


def stochastic_grid(condition: LineContactCondition, stats: RoughnessStatistics,
                    nodes: int = 512) -> Grid:
    """The solver's grid: the inlet's pressure build-up and the rough contact's spread.

    Parameters
    ----------
    condition : LineContactCondition
    stats : RoughnessStatistics
    nodes : int
        64 … 16384.

    Returns
    -------
    Grid
        inlet min(−2, X_s − 0.5), X_s where the smooth film's pressure reaches 0.1 % of p_h
        (as :func:`friction.ehl.transient.default_transient_grid`); outlet where the Hertz
        gap outside the contact, (X|X|... ) reaches six composite RMS roughnesses plus the
        summits' mean height (no summit touches beyond), at least 1.5.
    """
    from friction.ehl.transient import default_transient_grid

    integer("nodes", nodes, low=64, high=16384)
    smooth = default_transient_grid(condition, nodes)
    b_mm = math.sqrt(8.0 * condition.load_per_length * condition.radius
                     / (math.pi * condition.e_prime))
    to_h = 1e-3 * condition.radius / b_mm**2              # µm → H units
    reach = (6.0 * stats.summits.sigma + stats.summits.summit_mean) * to_h
    # Hertz gap outside a line contact, X > 1: X√(X²−1) − ln(X + √(X²−1)) (in b²/R units)
    xs = np.linspace(1.0, 30.0, 30000)
    gap = xs * np.sqrt(xs * xs - 1.0) - np.log(xs + np.sqrt(xs * xs - 1.0))
    edge = float(xs[min(np.searchsorted(gap, reach), xs.size - 1)])
    return Grid(nodes=nodes, inlet=min(smooth.inlet, -edge - 0.5), outlet=max(1.5, edge + 0.25))


@dataclass
class _Problem:
    """One condition on its grid, with what the residual needs."""

    s: ContactSetup
    cond: LineContactCondition
    stats: RoughnessStatistics
    sigma: float            # σ̄ [H units]
    to_um: float            # µm per H unit (b²/R)
    shear_coefficient: float  # (SR/2)(V₁ − V₂), of σ̄Φ_s in the content
    e_prime: float          # [MPa]
    hardness: float         # [MPa]
    poisson: float
    viscosity_fn: object
    percolation: float      # H_p/σ: the open gaps stop percolating below it [1]

    def asperities(self, h: Array) -> tuple[Array, Array, AsperityContact]:
        """P_a(H) and dP_a/dH [1], and the contact in physical units."""
        c = asperity_contact(h * self.to_um, self.stats.summits, self.e_prime, self.hardness,
                             self.poisson)
        ph = self.s.ph * 1e-6
        return c.pressure / ph, c.slope * self.to_um / ph, c

    def residual(self, p: Array, h0: float, cavitated: NDArray[np.bool_]):
        """Rows F (n,) and their bands dp, dh (4, n) for NewtonSystem, the Reynolds rows
        before the cavitation rows replaced them, and the fields.

        Fluid nodes: the average-flow Reynolds row R. Cavitated nodes: the oil's pressure
        P_f = P − P_a(H) = 0. Both ends: P = 0.
        """
        s = self.s
        n = p.size
        h = h0 + 0.5 * s.x**2 + s.kernel.deflection(p)
        pa, dpa, contact = self.asperities(h)
        pf = p - pa
        pos = np.maximum(pf, 0.0) * s.ph
        eta, dln = self.viscosity_fn(pos, s.eta0, s.alpha)  # type: ignore[operator]
        rho, drho = dowson_higginson_density(pos)
        state = NodeState(pressure=pf, film=h, density=rho, ddensity=drho * s.ph,
                          viscosity=eta / s.eta0, dln_viscosity=dln * s.ph)
        sig = self.sigma
        sv = h / sig
        g, dg = pressure_flow_conductance(sv, self.percolation)
        ht, dht = mean_gap(sv)
        fs, dfs = shear_flow_factor(sv)
        c = self.shear_coefficient
        bands = flow_bands(state, g * sig**3, dg * sig**2, sig * (ht + c * fs), dht + c * dfs,
                           s.spacing, s.lambda_bar)
        reynolds = bands.residual
        a, b = bands.dp, bands.dh
        i = np.arange(n)
        # P_f = P − P_a(H): the rows' H-dependence through the oil's pressure
        dh = b.copy()
        for k, o in enumerate(BAND_OFFSETS):
            j = np.clip(i + o, 0, n - 1)
            dh[k] -= a[k] * dpa[j]
        dp = a.copy()
        f = reynolds.copy()
        cav = cavitated.copy()
        cav[0] = cav[-1] = True
        dp[:, cav] = 0.0
        dh[:, cav] = 0.0
        dp[2, cav] = 1.0
        dh[2, cav] = -dpa[cav]
        f[cav] = pf[cav]
        for node in (0, n - 1):                       # ambient pressure at both ends
            dh[2, node] = 0.0
            f[node] = p[node]
        return f, dp, dh, reynolds, (h, pa, pf, contact, rho, eta)


def _problem(condition: LineContactCondition, stats: RoughnessStatistics, grid: Grid,
             options: StochasticOptions, mat: Material) -> _Problem:
    if condition.roughness_1 is not None or condition.roughness_2 is not None:
        raise InputError("roughness_1/roughness_2: the stochastic solver takes the surfaces "
                         "(surfaces=(GroundSurface(...), ...)), not heights on the grid")
    s = contact_setup(condition, grid)
    to_um = s.b**2 / s.radius * 1e6
    sigma_um = stats.summits.sigma
    s.sigma = math.hypot(*stats.rq)
    v1, v2 = (r * r / (sigma_um * sigma_um) for r in stats.rq)
    percolation = _percolation(stats, float(condition.e_prime), mat)
    return _Problem(
        s=s, cond=condition, stats=stats, sigma=sigma_um / to_um, to_um=to_um,
        shear_coefficient=(0.5 * condition.slide_to_roll * (v1 - v2)
                           if options.shear_flow else 0.0),
        e_prime=float(condition.e_prime), hardness=mat.hardness, poisson=mat.poisson_ratio,
        viscosity_fn=VISCOSITY_PRESSURE_MODELS[condition.viscosity_model],
        percolation=percolation,
    )


def _percolation(stats: RoughnessStatistics, e_prime: float, mat: Material) -> float:
    """H_p/σ: the separation at which the summits' real contact area reaches
    :data:`~friction.ehl.flow_factors.PERCOLATION_AREA` (bisection; the area falls
    monotonically with the separation), at most just below the flow factors' fit."""
    sig = stats.summits.sigma

    def area(t: float) -> float:
        c = asperity_contact(np.array([t * sig]), stats.summits, e_prime, mat.hardness,
                             mat.poisson_ratio)
        return float(c.area[0]) - PERCOLATION_AREA

    lo, hi = -20.0, FIT_LOWER_LIMIT - 1e-3
    if area(hi) >= 0.0:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if area(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _start(pr: _Problem) -> tuple[Array, float]:
    """Hertz's pressure, the mean planes apart by the smooth central film or by the
    summits' mean height plus one σ_s, whichever is larger."""
    s = pr.s
    s.roughness = np.zeros(s.x.size)
    p, h0 = initial_pressure(s, pr.cond)
    centre = int(np.argmin(np.abs(s.x)))
    film = h0 + 0.5 * s.x**2 + s.kernel.deflection(p)
    want = max(float(film[centre]),
               (pr.stats.summits.summit_mean + pr.stats.summits.summit_sigma) / pr.to_um)
    return p, h0 + want - float(film[centre])


#: a node that has switched between fluid and cavitated this many times takes the
#: complementarity row min(P_f, −κR) instead (it sits where both are nearly zero)
SWITCH_LIMIT = 3


def _complementarity_rows(pr: _Problem, p: Array, h0: float, rows: NDArray[np.bool_],
                          f: Array, dp: Array, dh: Array, fields: tuple) -> None:
    """Give the nodes ``rows`` the row min(P_f, −κR), κ = 1/|∂R_i/∂P_i| (in place)."""
    ff, fdp, fdh, _r, _fields = pr.residual(p, h0, np.zeros(p.size, dtype=bool))
    kappa = 1.0 / np.maximum(np.abs(fdp[2]), 1e-300)
    pf = fields[2]
    dpa = pr.asperities(fields[0])[1]
    for i in np.flatnonzero(rows):
        if pf[i] <= -kappa[i] * ff[i]:
            f[i] = pf[i]
            dp[:, i] = 0.0
            dh[:, i] = 0.0
            dp[2, i] = 1.0
            dh[2, i] = -dpa[i]
        else:
            f[i] = -kappa[i] * ff[i]
            dp[:, i] = -kappa[i] * fdp[:, i]
            dh[:, i] = -kappa[i] * fdh[:, i]


def _newton(pr: _Problem, p: Array, h0: float, options: StochasticOptions
            ) -> tuple[Array, float, int, tuple]:
    """Newton's method on (P, H₀) with an active set of cavitated nodes, limited steps.

    A fluid node whose oil pressure P_f falls below zero cavitates (its row becomes
    P_f = 0); a cavitated node whose Reynolds row says oil accumulates (R > 0) is released
    — the Reynolds (Christopherson) condition, as the steady smooth solver's active set.
    A node that keeps switching (:data:`SWITCH_LIMIT` times) lies where P_f and R are both
    nearly zero; it takes the semismooth row min(P_f, −κR), which has its root there.

    Raises
    ------
    ConvergenceError
        No convergence in ``options.max_iterations``, a non-finite iterate or a singular
        system.
    """
    s = pr.s
    n = p.size
    half_pi = 0.5 * math.pi
    cav = np.zeros(n, dtype=bool)
    switches = np.zeros(n, dtype=int)
    semismooth = np.zeros(n, dtype=bool)
    big = math.inf
    for it in range(1, options.max_iterations + 1):
        f, dp, dh, _reynolds, fields = pr.residual(p, h0, cav & ~semismooth)
        if semismooth.any():
            _complementarity_rows(pr, p, h0, semismooth, f, dp, dh, fields)
        load = float(p.sum() * s.spacing - half_pi)
        try:
            step = solve_newton_system(NewtonSystem(dp, dh, s.kernel, s.spacing),
                                       -np.concatenate([f, [load]]), options.linear_solver)
        except LinearSolveError as exc:
            raise ConvergenceError(f"stochastic line contact: Newton step {it}: {exc}") from exc
        dpp, dh0 = step[:-1], float(step[-1])
        big = float(np.max(np.abs(dpp)))
        dsep = float(np.max(np.abs(s.kernel.deflection(dpp) + dh0)))
        omega = min(1.0, options.step_limit / big if big > 0.0 else 1.0,
                    options.separation_step * pr.sigma / dsep if dsep > 0.0 else 1.0)
        p, h0 = p + omega * dpp, h0 + omega * dh0
        if not (np.all(np.isfinite(p)) and math.isfinite(h0)):
            raise ConvergenceError(f"stochastic line contact: the Newton iteration diverged "
                                   f"(non-finite at iteration {it})")
        _f, _dp, _dh, reynolds, fields = pr.residual(p, h0, cav)
        old = cav.copy()
        cav |= fields[2] < 0.0
        cav[old & (reynolds > 0.0)] = False
        cav[0] = cav[-1] = False
        switched = cav != old
        switches += switched
        semismooth |= switches >= SWITCH_LIMIT
        if not (switched & ~semismooth).any() and omega == 1.0 and big <= options.tolerance:
            return p, h0, it, fields
    raise ConvergenceError(f"stochastic line contact: no convergence in "
                           f"{options.max_iterations} Newton iterations (last max |ΔP| = "
                           f"{big:.2e})")


def film_oil_properties(oil: Lubricant, temperature: Array) -> tuple[Array, Array]:
    """η₀ [Pa s] and α [1/Pa] at film temperatures, extrapolated above the oil's table.

    Parameters
    ----------
    oil : Lubricant
    temperature : array_like — [degC]
        Film temperatures (inlet plus flash), clipped to the oil's lowest tabulated
        temperature and :data:`FILM_TEMPERATURE_CAP`.

    Returns
    -------
    (ndarray, ndarray)
        Ambient-pressure viscosity [Pa s] from the oil's Vogel law, and the
        pressure-viscosity coefficient [1/Pa] from its table, continued above it on the
        last segment's slope of ln α (the oil data's source: friction.lubricant).
    """
    lo, hi = temperature_range(oil)
    t = np.clip(temperature, lo, FILM_TEMPERATURE_CAP)
    inside = np.clip(t, lo, hi)
    v = oil.vogel
    eta0 = v.a * np.exp(v.b / (t - v.c))
    alpha = np.asarray(pressure_viscosity_coefficient(oil, inside), dtype=float)
    # above the table, ln α continues on its last segment's slope
    tt = oil.temperature
    slope = math.log(oil.pressure_viscosity_coefficient[-1]
                     / oil.pressure_viscosity_coefficient[-2]) / (tt[-1] - tt[-2])
    alpha = alpha * np.exp(slope * np.maximum(t - hi, 0.0))
    return eta0, alpha * 1e-9


class _Friction(NamedTuple):
    shear: Array            # mean film shear stress per apparent area [Pa]
    temperature: Array      # the oil's (the surfaces') temperature [degC]
    flash: Array            # mean of the surfaces' flash temperatures [K]
    fluid: float            # ∫τ dx [N/m]
    boundary: float         # μ_b ∫p_a dx [N/m]
    load: float             # ∫p dx [N/m]


def _friction(pr: _Problem, pf: Array, h: Array, pa: Array, oil: Lubricant,
              options: StochasticOptions, mat: Material) -> _Friction:
    """Film shear over the open gaps and boundary friction, with the thermal fixed point.

    The oil at a node shears at the temperature of the surfaces there: the inlet
    temperature plus the mean of the two surfaces' flash temperatures, which the heat of
    the film's shear and of the boundary friction raises (Jaeger's moving source,
    :func:`friction.ehl.thermal.flash_temperature`, the heat shared equally); iterated
    to a fixed point (relaxed by half: the traction falls as the oil heats).
    """
    s, cond = pr.s, pr.cond
    ue, sr = cond.entraining_velocity, cond.slide_to_roll
    us = abs(sr * ue)
    dx = s.spacing * s.b
    sig_m = pr.stats.summits.sigma * 1e-6
    sep_m = h * pr.to_um * 1e-6
    gaps = sep_m[:, None] - sig_m * _GH_Z[None, :]
    open_ = gaps > 0.0
    rate = np.where(open_, us / np.where(open_, gaps, 1.0), 0.0)      # [1/s]
    p_oil = np.maximum(pf, 0.0) * s.ph
    p_asp = np.maximum(pa, 0.0) * s.ph
    t_in = float(cond.temperature)
    boundary_flux = s.mu_b * p_asp * us                                # [W/m2]
    speeds = [abs(ue * (1.0 + 0.5 * sr)), abs(ue * (1.0 - 0.5 * sr))]
    effusivity = mat.thermal_effusivity
    flash = np.zeros(pf.size)
    model = pr.viscosity_fn
    for _ in range(60):
        if options.thermal:
            eta0, alpha = film_oil_properties(oil, t_in + flash)
        else:
            eta0, alpha = s.eta0, s.alpha
        eta, _ = model(p_oil, eta0, alpha)  # type: ignore[operator]
        tau = np.abs(eyring_limited_shear(eta[:, None], rate, p_oil[:, None], s.tau0, s.lim))
        mean_tau = np.where(open_, tau, 0.0) @ _GH_W
        if not options.thermal or us == 0.0:
            break
        q = 0.5 * (mean_tau * us + boundary_flux)              # each surface's share
        new_flash = 0.5 * sum(flash_temperature(q, dx, u, effusivity)
                              for u in speeds if u > 0.0)
        change = float(np.max(np.abs(new_flash - flash)))
        flash = 0.5 * (flash + new_flash)
        if change < options.thermal_tolerance:
            break
    return _Friction(shear=mean_tau, temperature=t_in + flash, flash=flash,
                     fluid=float(mean_tau.sum() * dx), boundary=float(s.mu_b * p_asp.sum() * dx),
                     load=float((p_oil + p_asp).sum() * dx))


#: speed factors of the continuation a condition falls back on when Newton's method does
#: not converge from Hertz's pressure: solved at 8, 4 and 2 times its speed first
CONTINUATION = (8.0, 4.0, 2.0, 1.0)


#: [1] asperity load ratio below which the film carries most of the load, and a default
#: grid is refined to the nodes Moes's M asks of a smooth film (:func:`_solve`)
FILM_CARRIED = 0.5


def _solve(condition: LineContactCondition, surfaces, grid: Grid | None,
           options: StochasticOptions | None):
    """One condition: on ``grid``, or — by default — on :func:`stochastic_grid`'s 512
    nodes and, where the film carries most of the load (asperity load ratio below
    :data:`FILM_CARRIED`) and Moes's load parameter M asks a smooth film for more
    (:data:`friction.ehl.line_contact.SMOOTH_NODES`), again on those nodes over the same
    domain. The pressure spike and the exit constriction of a heavily loaded film narrow
    as M grows; measured against 4096 nodes (issue 61): p_h 2 GPa, u_e 0.05 m/s, Rq
    0.05 µm (M 894, load ratio 0.15): h_c 40 % thin and μ +3.5 % on 512 nodes; where the
    asperities carry the load (load ratio 0.59–0.96 at M 8–571) 512 nodes are within 6 %
    of h_c and 0.2 % of μ, at 6–30× less time."""
    if grid is not None:
        return _solve_on(condition, surfaces, grid, options)
    stats = roughness_statistics(surfaces)
    out = _solve_on(condition, surfaces, stochastic_grid(condition, stats), options)
    _pr, g, _stats, p, _h0, _its, fields, _fr = out
    pa = fields[1]
    if float(pa.sum() / p.sum()) >= FILM_CARRIED:
        return out
    nodes = smooth_grid(condition).nodes
    if nodes <= g.nodes:
        return out
    log.debug("film-carried contact at Moes M asking %d nodes: solved again", nodes)
    return _solve_on(condition, surfaces, dataclasses.replace(g, nodes=nodes), options)


def _solve_on(condition: LineContactCondition, surfaces, g: Grid,
              options: StochasticOptions | None):
    opts = options or StochasticOptions()
    mat = opts.check()
    stats = roughness_statistics(surfaces)
    pr = _problem(condition, stats, g, opts, mat)
    oil = lubricant_of(condition.lubricant)
    p0, h00 = _start(pr)
    try:
        p, h0, its, fields = _newton(pr, p0, h00, opts)
    except ConvergenceError as first:
        # continuation in speed on the same grid: the faster contact's film is thicker and
        # its Newton iteration starts closer to the smooth film it begins from
        log.debug("%s; continuing from %g times the speed", first, CONTINUATION[0])
        p, h0, its = p0, h00, 0
        try:
            for factor in CONTINUATION:
                fast = dataclasses.replace(condition, entraining_velocity=(
                    condition.entraining_velocity * factor))
                step = _problem(fast, stats, g, opts, mat)
                p, h0, k, fields = _newton(step, p, h0, opts)
                its += k
        except ConvergenceError as exc:
            raise ConvergenceError(f"{first}; continuation in speed: {exc}") from exc
        pr = step
    h, pa, pf, _contact, _rho, _eta = fields
    fr = _friction(pr, pf, h, pa, oil, opts, mat)
    return pr, g, stats, p, h0, its, fields, fr


def _summary(pr: _Problem, p: Array, its: int, fields, fr: _Friction) -> StochasticSummary:
    s = pr.s
    h, pa, _pf, contact, _rho, _eta = fields
    w = fr.load
    centre = int(np.argmin(np.abs(s.x)))
    loaded = p > 1e-3
    sep_um = h * pr.to_um
    ht_um = mean_gap(h / pr.sigma)[0] * pr.stats.summits.sigma
    return StochasticSummary(
        friction_coefficient=(fr.fluid + fr.boundary) / w,
        fluid_friction=fr.fluid / w,
        boundary_part=fr.boundary / w,
        film_central=float(sep_um[centre]),
        film_min=float(sep_um[loaded].min()) if loaded.any() else float(sep_um.min()),
        mean_gap_central=float(ht_um[centre]),
        asperity_load_ratio=float(pa.sum() / p.sum()),
        contact_area_ratio=float(contact.area.sum() * s.spacing / 2.0),
        lambda_ratio=smooth_lambda_ratio(s, pr.cond),
        specific_film_min=float((sep_um[loaded].min() if loaded.any() else sep_um.min())
                                / pr.stats.summits.sigma),
        temperature_max=float(fr.temperature.max()),
        flash_temperature_max=float(fr.flash.max()),
        pressure_max=float(p.max()),
        newton_iterations=int(its),
    )


def stochastic_summary(condition: LineContactCondition, surfaces, grid: Grid | None = None,
                       options: StochasticOptions | None = None) -> StochasticSummary:
    """Scalars of one mixed-EHL line contact with statistical roughness (no dataset built).

    Parameters
    ----------
    condition : LineContactCondition
        Without ``roughness_1``/``roughness_2`` (the surfaces are given separately).
    surfaces : (GroundSurface | MeasuredSurface, GroundSurface | MeasuredSurface)
        Surface 1 moves at u_e(1 + SR/2), surface 2 at u_e(1 − SR/2); not both smooth.
    grid : Grid, optional
        Default :func:`stochastic_grid` (512 nodes).
    options : StochasticOptions, optional

    Returns
    -------
    StochasticSummary
        The contact's scalars: μ [1] and its fluid and boundary parts, film thickness
        [µm], asperity load and area ratios [1], λ [1], temperatures [degC, K] and the
        peak pressure over p_h [1] (the class's fields say which).

    Raises
    ------
    InputError
        An input out of range (named).
    ConvergenceError
        The Newton iteration did not converge (never an unconverged answer).

    Notes
    -----
    Source: the average-flow Reynolds equation of Patir & Cheng (1978, 1979) with
    Greenwood & Williamson (1966) summits and the seed's friction, Eq. 5.7–5.9 (module
    docstring; docs/ehl.md).
    """
    pr, _g, _stats, p, _h0, its, fields, fr = _solve(condition, surfaces, grid, options)
    return _summary(pr, p, its, fields, fr)


def _var(data, dims, units: str, long_name: str) -> tuple:
    return data_var(dims, np.asarray(data, dtype=float), units, long_name)


def solve_stochastic_line_contact(condition: LineContactCondition, surfaces,
                                  grid: Grid | None = None,
                                  options: StochasticOptions | None = None) -> xr.Dataset:
    """Solve one mixed-EHL line contact with statistical roughness; its dataset.

    Parameters
    ----------
    condition : LineContactCondition
        The contact, without roughness (the surfaces are given separately).
    surfaces : (GroundSurface | MeasuredSurface, GroundSurface | MeasuredSurface)
        Surface 1 moves at u_e(1 + SR/2), surface 2 at u_e(1 − SR/2); not both smooth.
    grid : Grid, optional
        Default :func:`stochastic_grid` (512 nodes).
    options : StochasticOptions, optional
        The solver's settings, as :func:`stochastic_summary`.

    Returns
    -------
    xarray.Dataset
        Over ``x`` [mm]: ``pressure``, ``fluid_pressure``, ``asperity_pressure`` [MPa],
        ``separation`` (mean planes), ``mean_gap`` [µm], ``contact_area`` [1] (real over
        apparent), ``shear_stress`` [MPa] (the film's, per apparent area),
        ``temperature`` [degC] (the oil's: inlet + flash), ``flash_temperature`` [K]; the scalars of
        :class:`StochasticSummary` (``friction_coefficient`` … ``flash_temperature_max``),
        ``hertz_pressure`` [MPa], ``hertz_half_width`` [mm]; the summit statistics and the
        settings as attributes.

    Raises
    ------
    InputError, ConvergenceError
        As :func:`stochastic_summary`.

    Notes
    -----
    The model of :func:`stochastic_summary`: Patir & Cheng's average-flow Reynolds equation
    (1978, 1979), Greenwood & Williamson (1966) summits, the seed's friction (Eq. 5.7–5.9).
    """
    t0 = _time.perf_counter()
    pr, g, stats, p, _h0, its, fields, fr = _solve(condition, surfaces, grid, options)
    summ = _summary(pr, p, its, fields, fr)
    opts = options or StochasticOptions()
    s = pr.s
    h, pa, pf, contact, _rho, _eta = fields
    ph = s.ph * 1e-6
    scalar_units = {
        "friction_coefficient": ("1", "friction coefficient mu (seed Eq. 5.9)"),
        "fluid_friction": ("1", "film (Eyring) part of mu"),
        "boundary_friction_part": ("1", "asperity (boundary) part of mu"),
        "film_central": ("um", "separation of the mean planes at x = 0"),
        "film_min": ("um", "least separation of the mean planes over the loaded zone"),
        "mean_gap_central": ("um", "mean gap (oil per area) at x = 0"),
        "asperity_load_ratio": ("1", "share of the load carried by the asperities"),
        "contact_area_ratio": ("1", "real contact area over Hertz width 2b"),
        "lambda_ratio": ("1", "smooth-film h_min (Pan-Hamrock) over composite Rq"),
        "specific_film_min": ("1", "least separation over composite Rq, loaded zone"),
        "temperature_max": ("degC", "hottest oil (surface) temperature"),
        "flash_temperature_max": ("K", "largest surface flash temperature rise"),
        "pressure_max": ("MPa", "largest total pressure"),
    }
    values = summ._asdict()
    values["boundary_friction_part"] = values.pop("boundary_part")
    values["pressure_max"] *= ph
    data = {k: _var(values[k], (), u, ln) for k, (u, ln) in scalar_units.items()}
    data["hertz_pressure"] = _var(ph, (), "MPa", "Hertz maximum pressure p_h")
    data["hertz_half_width"] = _var(s.b * 1e3, (), "mm", "Hertz half-width b")
    sep_um = h * pr.to_um
    profiles = {
        "pressure": (p * ph, "MPa", "total pressure (oil and asperities)"),
        "fluid_pressure": (np.maximum(pf, 0.0) * ph, "MPa", "oil pressure"),
        "asperity_pressure": (pa * ph, "MPa", "asperity contact pressure (nominal)"),
        "separation": (sep_um, "um", "separation of the surfaces' mean planes"),
        "mean_gap": (mean_gap(h / pr.sigma)[0] * stats.summits.sigma, "um",
                     "mean gap: oil per area"),
        "contact_area": (contact.area, "1", "real contact area over apparent area"),
        "shear_stress": (fr.shear * 1e-6, "MPa", "film shear stress per apparent area"),
        "temperature": (fr.temperature, "degC", "oil temperature: inlet plus flash"),
        "flash_temperature": (fr.flash, "K", "surface flash temperature rise, mean of both"),
    }
    data.update({k: _var(v, ("x",), u, ln) for k, (v, u, ln) in profiles.items()})
    ds = xr.Dataset(data, coords={"x": ("x", s.x * s.b * 1e3,
                                        {"units": "mm",
                                         "long_name": "distance from contact centre"})})
    sm = stats.summits
    ds.attrs.update({
        "title": "mixed-EHL line contact (stochastic roughness, steady)",
        **condition_attrs(condition),
        "roughness_rq_um": np.asarray(stats.rq, dtype=float),
        "short_cutoff_mm": np.asarray(stats.short_cutoff, dtype=float),
        "composite_rq_um": float(sm.sigma),
        "summit_density_per_mm2": float(sm.density),
        "summit_radius_mm": float(sm.radius),
        "summit_sigma_um": float(sm.summit_sigma),
        "summit_mean_um": float(sm.summit_mean),
        "bandwidth_alpha": float(sm.bandwidth),
        "material": opts.material,
        "thermal": int(opts.thermal),
        "grid_nodes": int(g.nodes), "grid_inlet": float(g.inlet), "grid_outlet": float(g.outlet),
        "newton_iterations": int(its),
        "wall_time_s": float(_time.perf_counter() - t0),
    })
    return ds
