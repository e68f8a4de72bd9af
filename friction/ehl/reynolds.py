"""The unified Reynolds equation of a line contact, discretised, with its Newton Jacobian.

Dimensionless steady form (Hamrock–Dowson variables X = x/b, P = p/p_h, H = hR/b²,
ρ̄ = ρ/ρ₀, η̄ = η/η₀, with b and p_h of Hertz):

    d/dX(ε dP/dX) − d(ρ̄H)/dX − (b/u_e) ∂(ρ̄H)/∂t = 0,     ε = ρ̄ H³ / (η̄ λ̄),
    λ̄ = 12 η₀ u_e R² / (b³ p_h),

the Poiseuille term central (ε at half nodes as the mean of its neighbours), the Couette
term by second-order upwind differences (first order next to the inlet), the squeeze
term by backward Euler. Following Hu & Zhu (2000) the same equation is used at every
node: where the film closes (H → 0) ε vanishes like H³, the Poiseuille term drops out and
the equation reduces to the Couette (and squeeze) terms. A node where the gap would become
negative is a contact node and takes the reduced equation's limit H = 0 (the elastic
contact condition); a node of negative pressure is a cavitation node, P = 0.

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
import scipy.sparse as sp
from numpy.typing import NDArray

__all__ = ["CAVITATION", "CONTACT", "FLUID", "NodeState", "assemble"]

Array = NDArray[np.float64]

#: Node types of the unified equation.
FLUID, CAVITATION, CONTACT = 0, 1, 2


@dataclass
class NodeState:
    """Everything the residual needs at the current iterate (all dimensionless, (n,)).

    Attributes
    ----------
    pressure, film : P and H (H already includes roughness and deflection)
    density, ddensity : ρ̄ and dρ̄/dP
    viscosity, dln_viscosity : η̄ and d ln η̄/dP
    """

    pressure: Array
    film: Array
    density: Array
    ddensity: Array
    viscosity: Array
    dln_viscosity: Array


def _couette_matrix(n: int, spacing: float) -> sp.csr_matrix:
    """Second-order upwind d/dX (first order at node 1; rows 0 and n−1 unused)."""
    rows, cols, vals = [], [], []
    for i in range(1, n - 1):
        if i == 1:
            rows += [i, i]
            cols += [i, i - 1]
            vals += [1.0 / spacing, -1.0 / spacing]
        else:
            rows += [i, i, i]
            cols += [i, i - 1, i - 2]
            vals += [1.5 / spacing, -2.0 / spacing, 0.5 / spacing]
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n))


def assemble(
    state: NodeState, kind: NDArray[np.int_], kernel_matrix: Array, spacing: float,
    lambda_bar: float, squeeze: tuple[float, Array] | None = None,
) -> tuple[Array, Array]:
    """Residual of every node equation and its Jacobian in (P, H₀).

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
    squeeze : (float, array (n,)), optional
        (c, ρ̄H at the previous time step) with c = b/(u_e Δt) for the transient term.

    Returns
    -------
    residual : array (n,)
        Reynolds rows scaled by Δ; contact rows H_i; cavitation/boundary rows P_i.
    jacobian : array (n, n + 1)
        Derivatives by P_j and (last column) by H₀.
    """
    p, h = state.pressure, state.film
    n = p.size
    d2 = spacing * spacing
    hc = np.maximum(h, 0.0)
    eps = state.density * hc**3 / (state.viscosity * lambda_bar)
    deps_local = eps * (state.ddensity / state.density - state.dln_viscosity)
    deps_h = 3.0 * state.density * hc**2 / (state.viscosity * lambda_bar)
    e_half = 0.5 * (eps[1:] + eps[:-1])                      # (n−1,) at i+½
    dp = np.diff(p)                                          # P_{i+1} − P_i
    flux = e_half * dp                                       # (n−1,)
    poiseuille = np.zeros(n)
    poiseuille[1:-1] = (flux[1:] - flux[:-1]) / d2
    q = state.density * h
    couette = _couette_matrix(n, spacing) @ q
    res = poiseuille - couette
    dq_local = state.ddensity * h
    if squeeze is not None:
        c, q_old = squeeze
        res = res - c * (q - q_old)
    # Jacobian of the Reynolds rows (banded operators applied to dense rows, O(n²)) ----
    jac = np.zeros((n, n + 1))
    kh = np.zeros((n, n + 1))                      # dH/d(P, H₀) = [D | 1]
    kh[:, :n] = kernel_matrix
    kh[:, n] = 1.0
    # d ε_k = deps_local_k dP_k + deps_h_k dH_k ; d q_k = dq_local_k dP_k + ρ̄_k dH_k
    deps = deps_h[:, None] * kh
    deps[np.arange(n), np.arange(n)] += deps_local
    dq = state.density[:, None] * kh
    dq[np.arange(n), np.arange(n)] += dq_local
    idx = np.arange(1, n - 1)
    jac[idx, idx - 1] += e_half[:-1] / d2
    jac[idx, idx] -= (e_half[1:] + e_half[:-1]) / d2
    jac[idx, idx + 1] += e_half[1:] / d2
    bl = -dp[:-1] / (2.0 * d2)
    bd = (dp[1:] - dp[:-1]) / (2.0 * d2)
    bu = dp[1:] / (2.0 * d2)
    jac[1:-1] += bl[:, None] * deps[:-2] + bd[:, None] * deps[1:-1] + bu[:, None] * deps[2:]
    # second-order upwind Couette rows (first order at node 1)
    jac[1] -= (dq[1] - dq[0]) / spacing
    jac[2:-1] -= (1.5 * dq[2:-1] - 2.0 * dq[1:-2] + 0.5 * dq[:-3]) / spacing
    if squeeze is not None:
        c, _ = squeeze
        jac[1:-1] -= c * dq[1:-1]
    res = res * spacing
    jac *= spacing
    # Contact, cavitation and boundary rows ---------------------------------------------
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


def reynolds_residual(state: NodeState, spacing: float, lambda_bar: float,
                      squeeze: tuple[float, Array] | None = None) -> Array:
    """The Reynolds rows alone (scaled by Δ), at every interior node, (n,) [1].

    Used to decide whether a cavitation node is released (a positive residual at P = 0
    means fluid accumulates there: the node must carry pressure).
    """
    p, h = state.pressure, state.film
    n = p.size
    hc = np.maximum(h, 0.0)
    eps = state.density * hc**3 / (state.viscosity * lambda_bar)
    e_half = 0.5 * (eps[1:] + eps[:-1])
    flux = e_half * np.diff(p)
    res = np.zeros(n)
    res[1:-1] = (flux[1:] - flux[:-1]) / spacing**2
    q = state.density * h
    res -= _couette_matrix(n, spacing) @ q
    if squeeze is not None:
        c, q_old = squeeze
        res -= c * (q - q_old)
    res[0] = res[-1] = 0.0
    return res * spacing
