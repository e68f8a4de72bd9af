"""The Newton system of the line contact: J = A + B [D | 1] with the load row, and its solvers.

Every row of the discretised equations depends on the pressures and films of a few
neighbouring nodes only (the bands A = ∂F/∂P and B = ∂F/∂H of :mod:`friction.ehl.reynolds`
and of the penalty terms), but the film depends on every pressure through the elastic
deflection H = H₀ + X²/2 + D P − roughness. The Newton system in (ΔP, ΔH₀) is

    (A + B D) ΔP + B 1 ΔH₀ = −F,        Δ Σ ΔP = −F_load,

dense through D. Two interchangeable solvers (:data:`LINEAR_SOLVERS`):

* ``"dense"``: the matrix formed (4n² operations from the bands) and factorised by LU,
  O(n³) — the fastest up to ~600 nodes;
* ``"krylov"``: GMRES on the exact operator (D applied by DC-FFT, O(n log n)),
  preconditioned by a banded LU of the **differential-deflection** form of the same
  system: with the films W = D ΔP + ΔH₀ as extra unknowns, the dense relation W = D ΔP is
  replaced by its second differences W_(i−1) − 2W_i + W_(i+1) = Σ_k G_k ΔP_(i−k), whose
  coefficients G_k = D_(k−1) − 2D_k + D_(k+1) decay like 1/k² and are kept for |k| ≤ m
  (Evans & Hughes; Holmes, Evans & Snidle), closed by the two boundary films W_0, W_(n−1)
  (the full deflection rows, outside the band as a rank-3 border with the load row and
  ΔH₀). Interleaving (ΔP_i, W_i) makes a band of half-width 2m + 2, factorised by LAPACK
  in O(n m²); GMRES converges in ~5–20 iterations. O(n m² + iterations · n log n).

Source: Evans, H. P., Hughes, T. G., "Evaluation of deflection in semi-infinite bodies by
a differential method", Proc. IMechE C 214 (2000) 563; Holmes, M. J. A., Evans, H. P.,
Hughes, T. G., Snidle, R. W., "Transient elastohydrodynamic point contact analysis using a
new coupled differential deflection method", Proc. IMechE J 217 (2003) 289; Saad, Y.,
Schultz, M. H., "GMRES", SIAM J. Sci. Stat. Comput. 7 (1986) 856.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numpy.typing import NDArray
from scipy.linalg import lu_factor, lu_solve
from scipy.linalg.lapack import dgbtrf, dgbtrs

from friction.ehl.kernel import ElasticKernel
from friction.ehl.reynolds import BAND_OFFSETS
from geometry.core.errors import InputError, LTCAError

__all__ = ["LINEAR_SOLVERS", "LinearSolveError", "NewtonSystem", "solve_newton_system"]

Array = NDArray[np.float64]

#: up to this many nodes "auto" forms the dense matrix; above it, Krylov (measured
#: crossover on one core: dense LU of 512 nodes ≈ 6 ms, 1024 ≈ 35 ms)
DENSE_UP_TO = 640


class LinearSolveError(LTCAError, RuntimeError):
    """A Newton system could not be solved (singular, or GMRES did not converge)."""


def _band_matrix(bands: Array) -> sp.csr_matrix:
    """(4, n) row-indexed bands (column offsets BAND_OFFSETS) as a sparse (n, n) matrix."""
    n = bands.shape[1]
    rows, cols, vals = [], [], []
    i = np.arange(n)
    for k, o in enumerate(BAND_OFFSETS):
        c = i + o
        ok = (c >= 0) & (c < n) & (bands[k] != 0.0)
        rows.append(i[ok])
        cols.append(c[ok])
        vals.append(bands[k][ok])
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(n, n))


@dataclass
class NewtonSystem:
    """One Newton system of the line contact.

    Attributes
    ----------
    dp, dh : array (4, n) — [1]
        Bands of ∂F/∂P and ∂F/∂H (column offsets :data:`~friction.ehl.reynolds.BAND_OFFSETS`),
        boundary and penalty rows included.
    kernel : ElasticKernel
        The deflection coefficients D.
    spacing : float — [1]
        Δ (the load row is Δ Σ ΔP).
    mask : array (n,) or None — [1]
        dP_j/dΦ_j when the unknowns Φ are not the pressures themselves (the universal
        variable of a mass-conserving cavitation: P = max(Φ, 0), so 1 where the film
        carries pressure and 0 where it is cavitated); the deflection and the load row
        see mask ⊙ ΔΦ. None: the unknowns are the pressures.
    """

    dp: Array
    dh: Array
    kernel: ElasticKernel
    spacing: float
    mask: Array | None = None

    @property
    def nodes(self) -> int:
        return int(self.dp.shape[1])

    def dense(self) -> Array:
        """The full (n + 1, n + 1) matrix [[A + B D, B 1], [Δ 1ᵀ, 0]]."""
        n = self.nodes
        j = np.empty((n + 1, n + 1))
        j[:n, :n] = self._b @ self.kernel.matrix()
        if self.mask is not None:
            j[:n, :n] *= self.mask[None, :]
        i = np.arange(n)
        for k, o in enumerate(BAND_OFFSETS):
            ok = (i + o >= 0) & (i + o < n)
            j[i[ok], i[ok] + o] += self.dp[k, ok]
        j[:n, n] = self.dh.sum(axis=0)
        j[n, :n] = self.spacing if self.mask is None else self.spacing * self.mask
        j[n, n] = 0.0
        return j

    def matvec(self, x: Array) -> Array:
        """J x for x = (ΔP, ΔH₀), (n + 1,), with D applied by DC-FFT."""
        n = self.nodes
        v, v0 = x[:n], x[n]
        vm = v if self.mask is None else v * self.mask
        w = self.kernel.deflection(vm) + v0
        out = np.empty(n + 1)
        out[:n] = self._a @ v + self._b @ w
        out[n] = self.spacing * vm.sum()
        return out

    def __post_init__(self) -> None:
        self._a = _band_matrix(self.dp)
        self._b = _band_matrix(self.dh)


class DifferentialPreconditioner:
    """Banded LU of the differential-deflection form of a :class:`NewtonSystem`.

    Parameters
    ----------
    system : NewtonSystem
    half_width : int
        m: second-difference deflection coefficients kept for |k| ≤ m (≥ 1).

    Notes
    -----
    Unknowns interleaved as (ΔP_0, W_0, ΔP_1, W_1, …), rows (F_i, film row i); the two
    boundary film rows' deflection coefficients outside the band, the load row and the
    ΔH₀ column form a rank-3 border solved by block elimination (3 extra banded solves per
    factorisation). Source: module docstring.
    """

    def __init__(self, system: NewtonSystem, half_width: int = 16) -> None:
        n = system.nodes
        coef = system.kernel.coefficients
        mask = np.ones(n) if system.mask is None else system.mask
        c0 = n - 1
        m = max(1, min(int(half_width), n - 2))
        self.n = n
        kl = ku = 2 * m + 2
        self.kl, self.ku = kl, ku
        ab = np.zeros((2 * kl + ku + 1, 2 * n))

        def put(r: Array, c: Array, v: Array) -> None:
            np.add.at(ab, (kl + ku + r - c, c), v)

        i = np.arange(n)
        for k, o in enumerate(BAND_OFFSETS):
            j = i + o
            ok = (j >= 0) & (j < n)
            put(2 * i[ok], 2 * j[ok], system.dp[k, ok])
            put(2 * i[ok], 2 * j[ok] + 1, system.dh[k, ok])
        ii = np.arange(1, n - 1)
        for o, val in ((-1, 1.0), (0, -2.0), (1, 1.0)):
            put(2 * ii + 1, 2 * (ii + o) + 1, np.full(ii.size, val))
        for k in range(-m, m + 1):
            g = coef[c0 + k - 1] - 2.0 * coef[c0 + k] + coef[c0 + k + 1]
            j = ii - k
            ok = (j >= 0) & (j < n)
            put(2 * ii[ok] + 1, 2 * j[ok], -g * mask[j[ok]])
        border = np.zeros((3, 2 * n))
        cols = 2 * np.arange(n)
        for rr, (row, node) in enumerate(((1, 0), (2 * n - 1, n - 1))):
            put(np.array([row]), np.array([row]), np.array([1.0]))
            drow = -coef[c0 + node - np.arange(n)] * mask    # −D_(node − j) m_j
            inband = np.abs(row - cols) <= min(kl, ku)
            put(np.full(int(inband.sum()), row), cols[inband], drow[inband])
            border[rr, cols[~inband]] = drow[~inband]
        border[2, 0::2] = system.spacing * mask
        self.border = border
        lub, piv, info = dgbtrf(ab, kl, ku)
        if info != 0:
            raise LinearSolveError(f"differential preconditioner: banded LU singular "
                                   f"(LAPACK info {info})")
        self.lub, self.piv = lub, piv
        u = np.zeros((2 * n, 3))
        u[1, 0] = u[2 * n - 1, 1] = 1.0
        u[1, 2] = u[2 * n - 1, 2] = 1.0
        self.y = self._band_solve(u)
        s = border @ self.y
        s[0, 0] += 1.0
        s[1, 1] += 1.0
        self.schur = lu_factor(s)

    def _band_solve(self, g: Array) -> Array:
        x, _info = dgbtrs(self.lub, self.kl, self.ku, g, self.piv)
        return x

    def __call__(self, r: Array) -> Array:
        """Approximate J⁻¹ r for r (n + 1,)."""
        n = self.n
        g = np.zeros(2 * n)
        g[0::2] = r[:n]
        yg = self._band_solve(g)
        rhs = self.border @ yg
        rhs[2] -= r[n]
        z = lu_solve(self.schur, rhs)
        y = yg - self.y @ z
        out = np.empty(n + 1)
        out[:n] = y[0::2]
        out[n] = -z[2]
        return out


def _solve_dense(system: NewtonSystem, rhs: Array, **_: object) -> Array:
    j = system.dense()
    with np.errstate(all="ignore"):
        lu = lu_factor(j, check_finite=False)
    if not np.all(np.isfinite(lu[0])) or np.any(np.diag(lu[0]) == 0.0):
        raise LinearSolveError("dense Newton system singular or not finite")
    return lu_solve(lu, rhs)


def _solve_krylov(system: NewtonSystem, rhs: Array, *, half_width: int = 16,
                  rtol: float = 1e-10, max_iterations: int = 80, **_: object) -> Array:
    n = system.nodes
    precond = DifferentialPreconditioner(system, half_width)
    # GMRES on the left-preconditioned system M⁻¹J x = M⁻¹ rhs: the penalty rows (ξ ~ 1e6)
    # would otherwise dominate the residual norm GMRES minimises
    op = spla.LinearOperator((n + 1, n + 1), matvec=lambda v: precond(system.matvec(v)))
    target = precond(rhs)
    x, info = spla.gmres(op, target, rtol=rtol, atol=0.0, restart=max_iterations, maxiter=1)
    if info != 0 or not np.all(np.isfinite(x)):
        res = float(np.linalg.norm(op.matvec(x) - target)
                    / max(float(np.linalg.norm(target)), 1e-300))
        if not (math.isfinite(res) and res < 1e3 * rtol):
            raise LinearSolveError(f"GMRES did not converge in {max_iterations} iterations "
                                   f"(relative residual {res:.1e})")
    return x


#: name → solver(system, rhs, **options) → (ΔP, ΔH₀) as (n + 1,)
LINEAR_SOLVERS: Mapping[str, Callable[..., Array]] = MappingProxyType({
    "dense": _solve_dense,
    "krylov": _solve_krylov,
})


def solve_newton_system(system: NewtonSystem, rhs: Array, method: str = "auto",
                        **options: object) -> Array:
    """Solve J x = rhs for one Newton step.

    Parameters
    ----------
    system : NewtonSystem
        n nodes.
    rhs : array (n + 1,) — [1]
        −F (node rows, then the load row).
    method : {"auto", "dense", "krylov"}
        "auto": dense up to :data:`DENSE_UP_TO` nodes, Krylov above.
    **options
        Passed to the solver (Krylov: ``half_width``, ``rtol``, ``max_iterations``).

    Returns
    -------
    array (n + 1,) — [1]
        (ΔP, ΔH₀).

    Raises
    ------
    InputError
        An unknown method (the known ones named).
    LinearSolveError
        A singular system or GMRES not converging.
    """
    if method == "auto":
        method = "dense" if system.nodes <= DENSE_UP_TO else "krylov"
    if method not in LINEAR_SOLVERS:
        raise InputError(f"linear_solver: {method!r} is not one of "
                         f"{['auto', *LINEAR_SOLVERS]}")
    return LINEAR_SOLVERS[method](system, rhs, **options)
