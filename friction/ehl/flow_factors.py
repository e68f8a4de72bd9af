"""Flow of oil through the gap between two rough surfaces, averaged over the roughness.

Patir & Cheng's average-flow Reynolds equation replaces the gap h(x, y) between two rough
surfaces by three functions of the nominal separation H = h/σ (h between the mean planes,
σ the composite RMS roughness) that say how the roughness changes the flow:

* the **mean gap** h_T = σ E[max(H − z, 0)] = σ(H Φ(H) + φ(H)) (Gaussian heights z): the
  oil a unit area holds, which the surfaces carry along (the Couette term) — positive
  for every H, ~0.4σ where the mean planes meet (:func:`mean_gap`);
* the **pressure-flow factor** φ_x: the Poiseuille flow of the rough gap is φ_x h³/(12η)
  times the pressure gradient (:func:`pressure_flow_conductance` returns g = φ_x H³ in
  units of σ³). Patir & Cheng's fit for an isotropic surface (Peklenik number γ = 1),
  φ_x = 1 − 0.90 e^{−0.56H}, holds for H ≥ 0.5 (their simulations' range, rigid
  surfaces); below it the conductance is continued smoothly (value and slope) as
  g(0.5)((H − H_p)/(0.5 − H_p))^m down to zero at the percolation separation H_p, where
  the open gaps stop forming a connected path and the oil left in the valleys is
  trapped; zero below. For rigid Gaussian surfaces H_p = 0 (half the area in contact:
  the threshold of a symmetric two-dimensional random field; Bruggeman's effective-medium
  theory gives the same point); the stochastic solver passes the separation at which its
  summits' real contact area reaches the percolation threshold of elastic rough contacts
  (:data:`PERCOLATION_AREA`), since summits flatten and the rigid overlap overstates the
  contact;
* the **shear-flow factor** Φ_s: two surfaces of unequal roughness sliding carry an extra
  flow (U₁ − U₂)/2 · σΦ_s with Φ_s = V_r1 Φ_s(H) − V_r2 Φ_s(H), V_ri = σ_i²/σ²
  (:func:`shear_flow_factor` gives Φ_s(H) of an isotropic surface: 1.899 H^0.98
  e^{−0.92H + 0.05H²} for H ≤ 5, 1.126 e^{−0.25H} above; 0 for H ≤ 0).

Every function returns the value and its derivative by H (for the Newton Jacobian) and
accepts arrays. The smooth limit σ → 0 (H → ∞): g → H³, h_T → h, Φ_s → 0.

References
----------
Patir, N., Cheng, H. S., "An average flow model for determining effects of
three-dimensional roughness on partial hydrodynamic lubrication", J. Lubr. Technol. 100
(1978) 12–17 (φ_x, Table 1: γ = 1, C = 0.90, r = 0.56; H > 0.5; the shear-flow term).
Patir, N., Cheng, H. S., "Application of average flow model to lubrication between rough
sliding surfaces", J. Lubr. Technol. 101 (1979) 220–229 (Φ_s, Table 2: γ = 1).
Stauffer, D., Aharony, A., *Introduction to Percolation Theory*, 2nd ed., Taylor &
Francis (1994) (the continuum percolation threshold of a symmetric random field in two
dimensions at half the area).
Dapp, W. B., Lücke, A., Persson, B. N. J., Müser, M. H., "Self-affine elastic contacts:
percolation and leakage", Phys. Rev. Lett. 108 (2012) 244301 (the free volume between
elastic rough surfaces stops percolating at a relative contact area of about 0.42).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import ndtr

__all__ = ["FIT_LOWER_LIMIT", "PERCOLATION_AREA", "mean_gap", "pressure_flow_conductance",
           "shear_flow_factor"]

Array = NDArray[np.float64]

#: H below which Patir & Cheng's isotropic pressure-flow fit is not used [1]
FIT_LOWER_LIMIT = 0.5

#: real contact area over apparent area at which the open gaps of elastic rough surfaces
#: stop percolating (Dapp et al. 2012) [1]
PERCOLATION_AREA = 0.42

_C, _R = 0.90, 0.56                                  # Patir & Cheng (1978), γ = 1
_PHI_V = 1.0 - _C * math.exp(-_R * FIT_LOWER_LIMIT)
_G_V = _PHI_V * FIT_LOWER_LIMIT**3
_DG_V = _C * _R * math.exp(-_R * FIT_LOWER_LIMIT) * FIT_LOWER_LIMIT**3 \
    + 3.0 * _PHI_V * FIT_LOWER_LIMIT**2


def pressure_flow_conductance(h: ArrayLike, percolation: float = 0.0) -> tuple[Array, Array]:
    """g(H) = φ_x(H) H³ of an isotropic rough gap and dg/dH, H = h/σ [1].

    Parameters
    ----------
    h : array — [1]
        Nominal separation over the composite RMS roughness.
    percolation : float — [1]
        H_p < 0.5, the separation at which the open gaps stop percolating (0: rigid
        Gaussian surfaces).

    Returns
    -------
    (g, dg/dH) : arrays — [1]
        g ≥ 0, C¹ in H, 0 for H ≤ H_p.

    Notes
    -----
    Patir & Cheng (1978), γ = 1, for H ≥ 0.5; below, g(0.5) r^m with
    r = (H − H_p)/(0.5 − H_p) and m = (0.5 − H_p) g′(0.5)/g(0.5), which matches the value
    and the slope at H = 0.5 (module docstring).
    """
    x = np.asarray(h, dtype=float)
    span = FIT_LOWER_LIMIT - float(percolation)
    if not span > 0.0:
        raise ValueError(f"percolation: must be below {FIT_LOWER_LIMIT}, got {percolation}")
    m = span * _DG_V / _G_V
    xv = np.maximum(x, FIT_LOWER_LIMIT)
    e = _C * np.exp(-_R * xv)
    g_hi = (1.0 - e) * xv**3
    dg_hi = _R * e * xv**3 + 3.0 * (1.0 - e) * xv**2
    r = np.clip((x - percolation) / span, 0.0, 1.0)
    g_lo = _G_V * r**m
    dg_lo = _G_V * m * r ** (m - 1.0) / span
    hi = x >= FIT_LOWER_LIMIT
    return np.where(hi, g_hi, g_lo), np.where(hi, dg_hi, np.where(r > 0.0, dg_lo, 0.0))


def mean_gap(h: ArrayLike) -> tuple[Array, Array]:
    """h_T/σ = H Φ(H) + φ(H) and its derivative Φ(H) (Gaussian heights), H = h/σ [1].

    Returns
    -------
    (h_T/σ, d(h_T/σ)/dH) : arrays — [1]
        The expected gap over the roughness, where the surfaces do not touch; > 0.
    """
    x = np.asarray(h, dtype=float)
    cdf = ndtr(x)
    return x * cdf + np.exp(-0.5 * x * x) / math.sqrt(2.0 * math.pi), cdf


def shear_flow_factor(h: ArrayLike) -> tuple[Array, Array]:
    """Φ_s(H) of an isotropic surface and its derivative, H = h/σ [1].

    Returns
    -------
    (Φ_s, dΦ_s/dH) : arrays — [1]
        Patir & Cheng (1979), γ = 1: 1.899 H^0.98 e^{−0.92H + 0.05H²} (H ≤ 5),
        1.126 e^{−0.25H} (H > 5); 0 for H ≤ 0 (no open gap to carry it).
    """
    x = np.asarray(h, dtype=float)
    xp = np.maximum(x, 1e-12)
    xl = np.minimum(xp, 5.0)                       # the fit below H = 5 (no overflow above)
    lo = 1.899 * xl**0.98 * np.exp(-0.92 * xl + 0.05 * xl * xl)
    dlo = lo * (0.98 / xl - 0.92 + 0.10 * xl)
    hi = 1.126 * np.exp(-0.25 * xp)
    near = xp <= 5.0
    value = np.where(near, lo, hi)
    slope = np.where(near, dlo, -0.25 * hi)
    open_ = x > 0.0
    return np.where(open_, value, 0.0), np.where(open_, slope, 0.0)
