"""The node conditions of the mixed-EHL line contact as one semismooth system, and its Newton.

Unknowns: the universal variable Φ of Elrod at every node and the rigid approach H₀. Φ ≥ 0
is the pressure of a full film (P = Φ, θ = 1); Φ < 0 a cavitated one, P = 0 and the oil
fills the share θ = 1 + Φ of the gap (Jakobsson–Floberg–Olsson: the oil's mass ρ̄θH is
conserved through cavitation and reformation, so a valley that opens takes only the oil
that flows into it, and a cavitated zone that closes again is not refilled from nothing
— the Reynolds (Christopherson) condition would create that oil). The mass balance R = 0
(:func:`friction.ehl.reynolds.reynolds_bands`, with q = ρ̄θH) then holds at every node
that is not in asperity contact.

Asperity contact (the gap closed, H = 0, at a pressure P ≥ 0) takes the node's balance
as a sink, R ≤ 0: a closed node whose pressure drives oil away faster than it arrives
stays closed, one that receives more than it can hold (R > 0) opens. With that sign the
node's condition min(H, −R) = 0 has one root for given neighbours (both H and −R rise
with the node's pressure) — a condition asking R ≥ 0 at contacts has none under asperity
peaks (the failure of an earlier attempt, docs/ehl.md). It is solved in penalty form

    F_i = R_i − ξ_c min(H_i, 0) = 0

(Wu's penalty; a closed node settles at H ≈ R/ξ_c < 0, a penetration of order 1e-6 of
the film). Two bounds close the conditions, each as a max/min of two functions that both
fall with the node's Φ (so each node keeps one root): θ ≥ 0, F = max(G, −ξ(1 + Φ)) (a
gap emptied of oil stays empty while its balance would take oil it has not got), and an
optional pressure limit P_y of the surfaces (elastic–perfectly plastic asperities, the
toolkit's shakedown limit by default), F = min(G, ξ(P_y − Φ)). The load balance
Δ Σ P = π/2 closes the system with H₀.

Newton's method on F (a semismooth function: its rows change only with the signs of Φ,
H and the bounds — no active-set loop to cycle), steps limited to ``step_limit`` in
max |ΔΦ| and, after ``BACKTRACK_AFTER`` iterations, halved while they raise ‖F‖ (a node
on a kink can otherwise swing across it and back).

Source: Elrod, H. G., "A cavitation algorithm", J. Lubr. Technol. 103 (1981) 350;
Giacopini, M., Fowell, M. T., Dini, D., Strozzi, A., "A mass-conserving complementarity
formulation to study lubricant films in the presence of cavitation", J. Tribol. 132 (2010)
041702; Wu, S. R., "A penalty formulation and numerical approximation of the Reynolds–
Hertz problem of elastohydrodynamic lubrication", Int. J. Eng. Sci. 24 (1986) 1001;
Hu & Zhu (2000) for the unified equation; Qi, L., Sun, J., "A nonsmooth version of
Newton's method", Math. Program. 58 (1993) 353.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from friction.ehl.kernel import ElasticKernel
from friction.ehl.newton_system import (
    LINEAR_SOLVERS,
    LinearSolveError,
    NewtonSystem,
    solve_newton_system,
)
from friction.ehl.reynolds import BAND_OFFSETS, NodeState, Squeeze, reynolds_bands
from geometry.core.errors import LTCAError
from geometry.core.validation import integer, one_of, real

#: Newton iterations taken at full (limited) steps before a step that raises ‖F‖ is halved
BACKTRACK_AFTER = 4

#: dP/dΦ in a cavitated zone (pressure_and_fill)
CAVITATION_SLOPE = 1e-9

#: cavitation conditions of NewtonOptions.cavitation
CAVITATION_MODELS = ("reynolds", "mass_conserving")

__all__ = ["ConvergenceError", "NewtonOptions", "NodeSolution", "pressure_and_fill",
           "solve_node_conditions"]

Array = NDArray[np.float64]


class ConvergenceError(LTCAError, RuntimeError):
    """The Newton iteration of the line contact did not converge."""


@dataclass(frozen=True)
class NewtonOptions:
    """Settings of the semismooth Newton iteration.

    Parameters
    ----------
    tolerance : float — [1]
        Converged when a full Newton step changes no pressure by more than this (in p_h)
        and changes no node's sign pattern (1e-14 … 1e-3).
    max_iterations : int
        Newton iterations before :class:`ConvergenceError` (≥ 1).
    step_limit : float — [1]
        Largest max |ΔP| of one step; longer steps are scaled down (> 0).
    cavitation_penalty : float — [1]
        ξ of the bound rows (θ ≥ 0, the pressure limit), ≥ 1e2.
    contact_penalty : float — [1]
        ξ_c (≥ 1e2): the rows are scaled by Δ, so a closed node settles at H ≈ R/ξ_c.
        Larger values close the gap more exactly but make the contact kink sharper:
        1e6 left nodes at the kink swinging between open and closed (halving their
        residual per iteration); 1e4 (default) and 1e3 gave the same μ and asperity
        load to 4 digits on a rough condition at λ 0.65.
    linear_solver : str
        "auto", "dense" or "krylov" (:data:`friction.ehl.newton_system.LINEAR_SOLVERS`).
    cavitation : {"reynolds", "mass_conserving"}
        "reynolds" (default): the Reynolds (Christopherson) condition, P ≥ 0 with the oil
        always filling the gap, in penalty form R − ξ_p min(P, 0) (Φ = P); not mass
        conserving: a cavitated valley that closes again acts as if full of oil.
        "mass_conserving": Elrod's universal variable (JFO), the oil's mass conserved
        through cavitation; converges on fewer rough conditions (docs/ehl.md).
    """

    tolerance: float = 1e-9
    max_iterations: int = 60
    step_limit: float = 3.0
    cavitation_penalty: float = 1e6
    contact_penalty: float = 1e4
    linear_solver: str = "auto"
    cavitation: str = "reynolds"

    def check(self) -> None:
        """Raise :class:`~geometry.core.errors.InputError` naming the field out of range."""
        real("newton.tolerance", self.tolerance, low=1e-14, high=1e-3)
        integer("newton.max_iterations", self.max_iterations, low=1)
        real("newton.step_limit", self.step_limit, low=0.0, low_open=True)
        real("newton.cavitation_penalty", self.cavitation_penalty, low=1e2)
        real("newton.contact_penalty", self.contact_penalty, low=1e2)
        one_of("newton.cavitation", self.cavitation, CAVITATION_MODELS)
        one_of("newton.linear_solver", self.linear_solver, ("auto", *LINEAR_SOLVERS))


@dataclass
class NodeSolution:
    """A converged iterate: pressure, rigid approach, the state, iterations, held nodes."""

    pressure: Array
    approach: float
    state: NodeState
    iterations: int
    held: Array


def _slopes(phi: Array, options: NewtonOptions) -> tuple[Array, Array]:
    """dP/dΦ and dθ/dΦ of the unknowns."""
    if options.cavitation == "reynolds":
        return np.ones(phi.size), np.zeros(phi.size)
    return np.where(phi >= 0.0, 1.0, CAVITATION_SLOPE), (phi < 0.0).astype(float)


def _residual(state: NodeState, phi: Array, spacing: float, lambda_bar: float,
              squeeze: Squeeze | None, options: NewtonOptions, pressure_limit: float | None
              ) -> tuple[Array, Array, Array, Array]:
    """F, its bands ∂F/∂Φ (local) and ∂F/∂H, and the nodes held at the pressure limit."""
    bands = reynolds_bands(state, spacing, lambda_bar, squeeze)
    h = state.film
    n = h.size
    f = bands.residual
    closed = h < 0.0
    f[1:-1] -= options.contact_penalty * np.minimum(h, 0.0)[1:-1]
    wet, dry = _slopes(phi, options)                     # dP/dΦ, dθ/dΦ
    reynolds = options.cavitation == "reynolds"
    if reynolds:                                         # Φ = P: Wu's penalty for P ≥ 0
        f[1:-1] -= options.cavitation_penalty * np.minimum(phi, 0.0)[1:-1]
    i = np.arange(n)
    dphi = np.zeros_like(bands.dp)
    for k, o in enumerate(BAND_OFFSETS):
        j = np.clip(i + o, 0, n - 1)
        dphi[k] = bands.dp[k] * wet[j] + bands.dfill[k] * dry[j]
    dh = bands.dh
    dh[2, closed] -= options.contact_penalty
    if reynolds:
        dphi[2, phi < 0.0] -= options.cavitation_penalty
    # θ ≥ 0: F = max(G, −ξ(1 + Φ)), both falling with Φ: an emptied gap (Φ = −1) stays
    # empty while its balance G ≤ 0 (it would lose oil it does not have)
    empty_row = -options.cavitation_penalty * (1.0 + phi)
    empty = np.zeros(n, dtype=bool)
    if not reynolds:
        empty[1:-1] = empty_row[1:-1] > f[1:-1]
    f[empty] = empty_row[empty]
    dphi[:, empty] = 0.0
    dh[:, empty] = 0.0
    dphi[2, empty] = -options.cavitation_penalty
    held = np.zeros(n, dtype=bool)
    if pressure_limit is not None:
        # F = min(G, ξ(P_y − Φ)): both fall as the node's pressure rises, so the node has
        # one root — below the limit G = 0, at it G ≥ 0 (the elastic balance would need
        # more pressure than the surfaces can carry)
        cap = options.cavitation_penalty * (pressure_limit - phi)
        held[1:-1] = cap[1:-1] < f[1:-1]
        f[held] = cap[held]
        dphi[:, held] = 0.0
        dh[:, held] = 0.0
        dphi[2, held] = -options.cavitation_penalty
    # inlet: flooded at ambient pressure (Φ = 0); outlet: ambient, the fill carried out
    for node in (0, n - 1):
        dphi[:, node] = 0.0
        dh[:, node] = 0.0
        dphi[2, node] = 1.0
    f[0] = phi[0]
    if reynolds:                                 # ambient pressure at the outlet
        f[-1] = phi[-1]
    else:                                        # ambient, the fill carried out
        f[-1] = phi[-1] - min(phi[-2], 0.0)
        dphi[1, -1] = -dry[-2]
    return f, dphi, dh, held


def pressure_and_fill(phi: Array, cavitation: str = "mass_conserving"
                      ) -> tuple[Array, Array]:
    """P and θ of the unknowns Φ, (n,) each [1].

    ``cavitation="reynolds"``: P = Φ (held ≥ 0 by a penalty), θ = 1. Otherwise:

    P = max(Φ, 0) + s min(Φ, 0), θ = 1 + min(Φ, 0), with s = :data:`CAVITATION_SLOPE`: in a
    cavitated zone (Φ < 0) the pressure is −s(1 − θ) ≥ −1e-6 p_h, zero to the model's
    precision, but its slope keeps the node's column of the Newton matrix from vanishing
    where the gap is closed as well (there θ multiplies a zero film and decides nothing).
    """
    if cavitation == "reynolds":
        return phi.copy(), np.ones(phi.size)
    return np.maximum(phi, 0.0) + CAVITATION_SLOPE * np.minimum(phi, 0.0), \
        1.0 + np.minimum(phi, 0.0)


def solve_node_conditions(
    state_of: Callable[[Array, float], NodeState], phi: Array, approach: float,
    kernel: ElasticKernel, spacing: float, lambda_bar: float, squeeze: Squeeze | None,
    options: NewtonOptions, pressure_limit: float | None = None,
) -> NodeSolution:
    """Solve the node conditions (penalty form) and the load balance by Newton's method.

    Parameters
    ----------
    state_of : callable (P (n,), H₀) → NodeState
        The film, density and viscosity at an iterate (H = H₀ + X²/2 + D P − roughness).
    phi : array (n,) — [1]
        Start Φ (node 0 is held at 0, the outlet node at the fill carried out).
    approach : float — [1]
        Start H₀.
    kernel : ElasticKernel
        The deflection coefficients of the same grid.
    spacing : float — [1]
        Δ.
    lambda_bar : float — [1]
        λ̄.
    squeeze : Squeeze or None
        The implicit time step's squeeze term, None for the steady problem.
    options : NewtonOptions
    pressure_limit : float or None — [1]
        P_y = p_y/p_h: the surfaces carry no more (elastic–perfectly plastic asperities:
        a node at the limit takes P = P_y instead of its balance); None: elastic.

    Returns
    -------
    NodeSolution
        P = max(Φ, 0) with Δ Σ P = π/2 to round-off, H₀, the state there (its ``fill`` θ),
        the Newton iterations, the nodes at the pressure limit.

    Raises
    ------
    ConvergenceError
        No convergence in ``options.max_iterations`` iterations, a non-finite iterate, or a
        singular Newton system; never an unconverged answer.
    """
    phi = np.array(phi, dtype=float)
    h0 = float(approach)
    n = phi.size
    half_pi = 0.5 * math.pi

    mode = options.cavitation

    def evaluate(ph: Array, hh: float):
        p, theta = pressure_and_fill(ph, mode)
        st = state_of(p, hh)
        st.fill = theta
        # a closed gap holds no void: a closed node on the cavitated branch (Φ < 0, where
        # its pressure has a slope of only CAVITATION_SLOPE) is put at Φ = 0, on the pressure
        # branch, so that Newton's method can raise its contact pressure
        move = (st.film < 0.0) & (ph < 0.0) if mode == "mass_conserving" else None
        if move is not None and move.any():
            ph[move] = 0.0
            p, theta = pressure_and_fill(ph, mode)
            st = state_of(p, hh)
            st.fill = theta
        return st

    state = evaluate(phi, h0)
    f, dphi, dh, held = _residual(state, phi, spacing, lambda_bar, squeeze, options,
                                  pressure_limit)
    big = math.inf
    for it in range(1, options.max_iterations + 1):
        rhs = -np.concatenate([f, [state.pressure.sum() * spacing - half_pi]])
        try:
            step = solve_newton_system(
                NewtonSystem(dphi, dh, kernel, spacing, _slopes(phi, options)[0]), rhs,
                options.linear_solver)
        except LinearSolveError as exc:
            raise ConvergenceError(f"line contact: Newton step {it}: {exc}") from exc
        dstep, dh0 = step[:n], float(step[n])
        big = float(np.max(np.abs(dstep)))
        omega = min(1.0, options.step_limit / big) if big > 0.0 else 1.0
        signs = (phi > 0.0, state.film < 0.0, held)
        merit = float(f @ f)
        for _halving in range(6 if it > BACKTRACK_AFTER else 1):
            # θ = 1 + Φ ≥ 0: a step that would empty a gap below nothing stops at empty
            trial_phi, trial_h0 = phi + omega * dstep, h0 + omega * dh0
            if mode == "mass_conserving":
                trial_phi = np.maximum(trial_phi, -1.0)
            if not (np.all(np.isfinite(trial_phi)) and math.isfinite(trial_h0)):
                raise ConvergenceError(f"line contact: the Newton iteration diverged "
                                       f"(non-finite at iteration {it})")
            trial = evaluate(trial_phi, trial_h0)
            res = _residual(trial, trial_phi, spacing, lambda_bar, squeeze, options,
                            pressure_limit)
            # after BACKTRACK_AFTER iterations a step that raises the residual is halved:
            # a node at the cavitation or contact kink can otherwise swing across it and
            # back for ever (a 2-cycle of the semismooth iteration)
            if it <= BACKTRACK_AFTER or float(res[0] @ res[0]) <= merit:
                break
            omega *= 0.5
        phi, h0, state = trial_phi, trial_h0, trial
        f, dphi, dh, held = res
        same = (np.array_equal(signs[0], phi > 0.0) and np.array_equal(signs[1], state.film < 0.0)
                and np.array_equal(signs[2], held))
        # a node that sits on a kink (Φ or H zero to round-off) may flip its sign with a
        # round-off step: both of its rows hold there, so such a flip does not count
        if big <= options.tolerance and (same or big <= 1e-3 * options.tolerance):
            return NodeSolution(state.pressure, h0, state, it, held)
    raise ConvergenceError(
        f"line contact: no convergence in {options.max_iterations} Newton iterations "
        f"(last max |ΔΦ| = {big:.2e})")
