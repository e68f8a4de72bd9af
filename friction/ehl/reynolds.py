"""The unified Reynolds equation of a line contact, discretised, with its Newton Jacobian.

Dimensionless form (Hamrock–Dowson variables X = x/b, P = p/p_h, H = hR/b², ρ̄ = ρ/ρ₀,
η̄ = η/η₀, with b and p_h of Hertz; time T = t u_e/b):

    ∂/∂X(ε ∂P/∂X) − ∂(ρ̄H)/∂X − ∂(ρ̄H)/∂T = 0,     ε = ρ̄ H³ / (η̄ λ̄),
    λ̄ = 12 η₀ u_e R² / (b³ p_h),

the Poiseuille term central (ε at half nodes as the mean of its neighbours), the Couette
term by second-order upwind differences (first order next to the inlet), the squeeze
term ∂(ρ̄H)/∂T by a backward difference c(ρ̄H − q*) (backward Euler: c = 1/ΔT, q* the last
step's ρ̄H; BDF2: c = 3/(2ΔT), q* = (4q⁽ⁿ⁾ − q⁽ⁿ⁻¹⁾)/3). Following Hu & Zhu (2000) the same
equation holds at every node: where the film closes ε vanishes like H³, the Poiseuille
term drops out and the equation reduces to its Couette and squeeze terms.

The residual's Jacobian is local in P and in H: every row depends on P and H at the nodes
i − 2 … i + 1 only, so it is returned as two bands, dR = A dP + B dH. The film H depends
on every pressure through the elastic deflection (H = H₀ + X²/2 + D P − roughness), so
the Newton Jacobian in (P, H₀) is A + B [D | 1]: :mod:`friction.ehl.newton_system`
assembles and solves it.

Source: Hu, Y.-Z., Zhu, D., "A full numerical solution to the mixed lubrication in point
contacts", J. Tribol. 122 (2000) 1–9; Li, S., Kahraman, A., "A transient mixed
elastohydrodynamic lubrication model for spur gear pairs", J. Tribol. 132 (2010) 011501;
the discretisation and the Newton Jacobian follow Houpert, L. G., Hamrock, B. J., "Fast
approach for calculating film thicknesses and pressures in elastohydrodynamically
lubricated contacts at high loads", J. Tribol. 108 (1986) 411–420.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["BAND_OFFSETS", "CAVITATION", "CONTACT", "FLUID", "NodeState", "ReynoldsBands",
           "Squeeze", "assemble", "couette_difference", "flow_bands", "reynolds_bands",
           "reynolds_residual"]

Array = NDArray[np.float64]

#: Node types (labels of a solution: fluid, cavitated, asperity contact).
FLUID, CAVITATION, CONTACT = 0, 1, 2

#: Column offsets of the Jacobian bands: row i depends on nodes i − 2 … i + 1.
BAND_OFFSETS = (-2, -1, 0, 1)


@dataclass
class NodeState:
    """Everything the residual needs at the current iterate (all dimensionless, (n,)).

    Attributes
    ----------
    pressure, film : P and H (H already includes roughness and deflection)
    density, ddensity : ρ̄ and dρ̄/dP
    viscosity, dln_viscosity : η̄ and d ln η̄/dP
    fill : θ, the share of the gap the oil fills (1 where it carries pressure, < 1 in a
        cavitated zone: Jakobsson–Floberg–Olsson); None is a full film everywhere
    """

    pressure: Array
    film: Array
    density: Array
    ddensity: Array
    viscosity: Array
    dln_viscosity: Array
    fill: Array | None = None


@dataclass(frozen=True)
class Squeeze:
    """The discretised squeeze term c (ρ̄H − q*) of one implicit time step.

    Attributes
    ----------
    coefficient : float — [1]
        c = 1/ΔT (backward Euler) or 3/(2ΔT) (BDF2), ΔT in units of b/u_e.
    reference : array (n,) — [1]
        q* = ρ̄H of the last step (backward Euler) or (4q⁽ⁿ⁾ − q⁽ⁿ⁻¹⁾)/3 (BDF2).
    transport_defect : array (n,) or None — [1]
        δ = L_h[Z] − L[Z] of the moving roughness Z: the discrete Couette-and-squeeze
        operator L_h (the same differences as for ρ̄H) applied to the roughness minus the
        exact ∂Z/∂T + ∂Z/∂X. The rows then use L_h[ρ̄H] + ρ̄δ, which carries the roughness
        through the contact exactly where ρ̄ is uniform: a wave of a few nodes per
        wavelength is otherwise damped by the differences as if the film had flattened it
        (pure rolling, λ = b/4, 14 nodes per wavelength: 30 % lost before X = 0).
    """

    coefficient: float
    reference: Array
    transport_defect: Array | None = None


@dataclass
class ReynoldsBands:
    """Residual of the Reynolds rows and its Jacobian bands (all scaled by Δ).

    Attributes
    ----------
    residual : array (n,)
        R_i at the interior nodes (rows 0 and n − 1 are 0: the boundary nodes are P = 0).
    dp, dh, dfill : array (4, n)
        ``dp[k, i]`` = ∂R_i/∂P_(i+o), ``dh[k, i]`` = ∂R_i/∂H_(i+o), ``dfill[k, i]`` =
        ∂R_i/∂θ_(i+o), o = BAND_OFFSETS[k] (zero outside the grid and on the boundary rows).
    """

    residual: Array
    dp: Array
    dh: Array
    dfill: Array


def couette_difference(values: Array, spacing: float) -> Array:
    """The upwind difference of the Couette term applied to any field (n,) → (n,) [1/Δ].

    Rows 0 and n − 1 are 0; row 1 first order, the others second order — the differences
    :func:`reynolds_bands` applies to ρ̄H.
    """
    cw = _couette_weights(values.size, spacing)
    out = np.zeros(values.size)
    out[1:-1] = (cw[2, 1:-1] * values[1:-1] + cw[1, 1:-1] * values[:-2]
                 + cw[0, 1:-1] * np.concatenate(([0.0], values[:-3])))
    return out


def _couette_weights(n: int, spacing: float) -> Array:
    """∂(Couette_i)/∂q_(i+o) for o = −2, −1, 0 as (3, n) (first order at node 1)."""
    w = np.zeros((3, n))
    w[2, 1], w[1, 1] = 1.0 / spacing, -1.0 / spacing
    w[2, 2:-1], w[1, 2:-1], w[0, 2:-1] = 1.5 / spacing, -2.0 / spacing, 0.5 / spacing
    return w


def reynolds_bands(state: NodeState, spacing: float, lambda_bar: float,
                   squeeze: Squeeze | None = None) -> ReynoldsBands:
    """Residual of the Reynolds equation at every node and its banded Jacobian.

    Parameters
    ----------
    state : NodeState
        The current iterate, n ≥ 4 nodes.
    spacing : float — [1]
        Node spacing Δ (in units of b).
    lambda_bar : float — [1]
        λ̄ = 12 η₀ u_e R²/(b³ p_h).
    squeeze : Squeeze, optional
        The time derivative of one implicit step; ``None`` for the steady equation.

    Returns
    -------
    ReynoldsBands
        R (n,) and the bands ∂R/∂P, ∂R/∂H (4, n), every row multiplied by Δ.

    Notes
    -----
    R_i = [ε_(i+½)(P_(i+1) − P_i) − ε_(i−½)(P_i − P_(i−1))]/Δ² − C_i(q) − c(q_i − q*_i)
    − ρ̄_iθ_i δ_i with q = ρ̄θH the oil's mass per length (θ = 1 but in a cavitated zone) and
    δ the roughness transport defect of ``squeeze``, if any;
    ε_(i±½) the mean of the neighbours' ε, C the upwind difference; ε uses max(H, 0) (a
    closed film carries no Poiseuille flow). Source: module docstring.
    """
    h = state.film
    hc = np.maximum(h, 0.0)
    # q uses the film itself, slightly negative at a penetrating (closed) node: the rows stay
    # regular there (with max(H, 0) a closed node's column vanishes, measured to stall the
    # iteration) and the penalty holds the penetration at ~1e-6 of the film
    return flow_bands(state, hc**3, 3.0 * hc**2, h, np.ones(h.size), spacing, lambda_bar,
                      squeeze)


def flow_bands(state: NodeState, conductance: Array, dconductance: Array, content: Array,
               dcontent: Array, spacing: float, lambda_bar: float,
               squeeze: Squeeze | None = None) -> ReynoldsBands:
    """The discretised Reynolds rows for any gap's conductance and oil content.

    Parameters
    ----------
    state : NodeState
        Pressure P (the oil's), density, viscosity and fill θ at the nodes (its ``film``
        is not used here).
    conductance : array (n,) — [1]
        g of the Poiseuille term ε = ρ̄ g/(η̄ λ̄): H³ for a smooth gap
        (:func:`reynolds_bands`), φ_x H³ of a rough one (:mod:`friction.ehl.flow_factors`).
    dconductance : array (n,) — [1]
        dg/dH.
    content : array (n,) — [1]
        The gap's oil per area the surfaces carry (the Couette and squeeze terms act on
        q = ρ̄θ·content): H for a smooth gap, the mean gap h_T (plus the shear-flow
        term) for a rough one.
    dcontent : array (n,) — [1]
        d content/dH.
    spacing, lambda_bar, squeeze
        As :func:`reynolds_bands`.

    Returns
    -------
    ReynoldsBands
        The rows and their bands in P and in H (``dh`` through the conductance and the
        content), every row multiplied by Δ.
    """
    p = state.pressure
    n = p.size
    d2 = spacing * spacing
    eps = state.density * conductance / (state.viscosity * lambda_bar)
    deps_p = eps * (state.ddensity / state.density - state.dln_viscosity)
    deps_h = state.density * dconductance / (state.viscosity * lambda_bar)
    e_half = 0.5 * (eps[1:] + eps[:-1])                      # (n − 1,) at i + ½
    dpres = np.diff(p)
    flux = e_half * dpres
    res = np.zeros(n)
    res[1:-1] = (flux[1:] - flux[:-1]) / d2
    fill = np.ones(n) if state.fill is None else state.fill
    rho_f = state.density * fill                            # ρ̄θ: the oil's mass per gap
    gap = content
    q = rho_f * gap
    cw = _couette_weights(n, spacing)
    couette = np.zeros(n)
    couette[1:-1] = (cw[2, 1:-1] * q[1:-1] + cw[1, 1:-1] * q[:-2]
                     + cw[0, 1:-1] * np.concatenate(([0.0], q[:-3])))
    res -= couette
    if squeeze is not None:
        res[1:-1] -= squeeze.coefficient * (q[1:-1] - squeeze.reference[1:-1])
        cw[2, 1:-1] += squeeze.coefficient
    defect = None if squeeze is None else squeeze.transport_defect
    if defect is not None:
        res[1:-1] -= rho_f[1:-1] * defect[1:-1]
    res[0] = res[-1] = 0.0
    a = np.zeros((4, n))
    b = np.zeros((4, n))
    f = np.zeros((4, n))
    i = np.arange(1, n - 1)
    # Poiseuille term, directly in P
    a[1, i] += e_half[:-1] / d2
    a[2, i] -= (e_half[1:] + e_half[:-1]) / d2
    a[3, i] += e_half[1:] / d2
    # … and through ε_k (k = i − 1, i, i + 1): ∂ε_k = deps_p dP_k + deps_h dH_k
    for k, coef in ((1, -dpres[:-1] / (2.0 * d2)),
                    (2, (dpres[1:] - dpres[:-1]) / (2.0 * d2)),
                    (3, dpres[1:] / (2.0 * d2))):
        a[k, i] += coef * deps_p[i + k - 2]
        b[k, i] += coef * deps_h[i + k - 2]
    if defect is not None:
        a[2, i] -= state.ddensity[i] * fill[i] * defect[i]
        f[2, i] -= state.density[i] * defect[i]
    # Couette and squeeze terms through q_k = ρ̄_k θ_k c_k (k = i − 2, i − 1, i)
    dq_p = state.ddensity * fill * gap
    dq_h = rho_f * dcontent
    dq_f = state.density * gap
    for k in (0, 1, 2):
        rows = i[i + k - 2 >= 0]
        a[k, rows] -= cw[k, rows] * dq_p[rows + k - 2]
        b[k, rows] -= cw[k, rows] * dq_h[rows + k - 2]
        f[k, rows] -= cw[k, rows] * dq_f[rows + k - 2]
    return ReynoldsBands(residual=res * spacing, dp=a * spacing, dh=b * spacing,
                         dfill=f * spacing)


def reynolds_residual(state: NodeState, spacing: float, lambda_bar: float,
                      squeeze: Squeeze | None = None) -> Array:
    """The Reynolds rows alone (scaled by Δ), at every interior node, (n,) [1].

    Used to decide whether a cavitation node is released (a positive residual at P = 0
    means fluid accumulates there: the node must carry pressure).
    """
    return reynolds_bands(state, spacing, lambda_bar, squeeze).residual


def assemble(
    state: NodeState, kind: NDArray[np.int_], kernel_matrix: Array, spacing: float,
    lambda_bar: float, squeeze: Squeeze | None = None,
) -> tuple[Array, Array]:
    """Residual of every node equation of an active set and its dense Jacobian in (P, H₀).

    Parameters
    ----------
    state : NodeState
        The current iterate, n nodes.
    kind : int array (n,)
        :data:`FLUID`, :data:`CAVITATION` or :data:`CONTACT` per node (nodes 0 and n−1
        are always P = 0 boundary nodes).
    kernel_matrix : array (n, n) — [1]
        Dimensionless influence coefficients D (H = H₀ + X²/2 + D P − roughness).
    spacing : float — [1]
        Δ.
    lambda_bar : float — [1]
        λ̄ = 12 η₀ u_e R²/(b³ p_h).
    squeeze : Squeeze, optional
        The implicit time step's squeeze term.

    Returns
    -------
    residual : array (n,)
        Reynolds rows scaled by Δ; contact rows H_i; cavitation/boundary rows P_i.
    jacobian : array (n, n + 1)
        Derivatives by P_j and (last column) by H₀: the bands of :func:`reynolds_bands`
        as A + B [D | 1].
    """
    bands = reynolds_bands(state, spacing, lambda_bar, squeeze)
    p, h = state.pressure, state.film
    n = p.size
    jac = np.zeros((n, n + 1))
    for k, o in enumerate(BAND_OFFSETS):
        lo, hi = max(0, -o), min(n, n - o)
        rows = np.arange(lo, hi)
        jac[rows, rows + o] += bands.dp[k, lo:hi]
        jac[lo:hi, :n] += bands.dh[k, lo:hi, None] * kernel_matrix[lo + o:hi + o]
        jac[lo:hi, n] += bands.dh[k, lo:hi]
    res = bands.residual
    contact = kind == CONTACT
    res[contact] = h[contact]
    jac[contact, :n] = kernel_matrix[contact]
    jac[contact, n] = 1.0
    fixed = kind == CAVITATION
    fixed[0] = fixed[-1] = True
    res[fixed] = p[fixed]
    jac[fixed] = 0.0
    jac[np.flatnonzero(fixed), np.flatnonzero(fixed)] = 1.0
    return res, jac
