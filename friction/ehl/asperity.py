"""Asperity-scale statistics of two rough flanks and the load their summits carry.

The mixed regime of a gear contact is decided at the scale of the roughness summits
(micrometres), far below what a line-contact grid resolves over a Hertz width; and a
flank's roughness is two-dimensional, so the oil a valley holds can leave around the
summits that bound it — which a one-dimensional resolved profile cannot represent
(docs/ehl.md, "Why the asperities never carried the load"). This module gives the
statistical description the stochastic solver (:mod:`friction.ehl.stochastic`) uses:

* **spectral moments** m₀, m₂, m₄ of a profile (its height, slope and curvature
  variances, :func:`profile_moments`) and of two surfaces together (their sum:
  independent surfaces add their moments, :func:`composite_moments`);
* the **summit statistics** of an isotropic Gaussian surface with those moments
  (Nayak 1971; McCool 1986, :func:`summit_statistics`): summit density η, mean summit
  radius β, summit-height standard deviation σ_s and mean summit height y_s above the
  mean plane;
* the **asperity contact** at a mean-plane separation h (:func:`asperity_contact`):
  Greenwood & Williamson's sum over summits of Gaussian heights, each summit an
  elastic–plastic sphere on a flat (Chang, Etsion & Bogy 1987): Hertzian up to the
  critical interference ω_c = (πKH/(2E*))² β, then plastic at the mean pressure KH
  (H the hardness, K = 0.454 + 0.41ν) — so that no summit carries a pressure steel
  cannot.

The Gaussian tail integrals F_n(t) = ∫_t^∞ (z − t)^n φ(z) dz (:func:`gaussian_tail_integral`)
are evaluated in closed form through the parabolic cylinder function.

Units at the boundary: µm, mm, 1/mm², MPa; the functions are pure and vectorised.

References
----------
Greenwood, J. A., Williamson, J. B. P., "Contact of nominally flat surfaces", Proc. R.
Soc. A 295 (1966) 300–319.
Greenwood, J. A., Tripp, J. H., "The contact of two nominally flat rough surfaces",
Proc. Instn Mech. Engrs 185 (1970) 625–633 (two rough surfaces as one composite).
Nayak, P. R., "Random process model of rough surfaces", J. Lubr. Technol. 93 (1971)
398–407.
McCool, J. I., "Comparison of models for the contact of rough surfaces", Wear 107 (1986)
37–60 (the summit statistics from m₀, m₂, m₄ used here, his Eq. 3–7).
Chang, W. R., Etsion, I., Bogy, D. B., "An elastic-plastic model for the contact of
rough surfaces", J. Tribol. 109 (1987) 257–263.
Hall, P., *Introduction to the Theory of Coverage Processes*, Wiley (1988) (the covered
fraction 1 − e^(−A) of randomly placed spots of total area fraction A).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, NDArray
from scipy.special import gamma, pbdv

from geometry.core.errors import InputError
from geometry.core.validation import real, real_array

__all__ = ["AsperityContact", "SummitStatistics", "asperity_contact", "composite_moments",
           "gaussian_tail_integral", "hardness_factor", "profile_moments", "summit_statistics"]

Array = NDArray[np.float64]

#: Gauss–Legendre nodes for the elastic part of a summit population (in v, ω = a + (b − a)v²)
_GL_NODES, _GL_WEIGHTS = np.polynomial.legendre.leggauss(32)
_GL_V = 0.5 * (_GL_NODES + 1.0)
_GL_W = 0.5 * _GL_WEIGHTS


#: Gauss–Hermite nodes and weights (probabilists', normalised) for F_n deep in contact
_GH_Z, _GH_W = np.polynomial.hermite_e.hermegauss(60)
_GH_W = _GH_W / _GH_W.sum()

#: below this t every summit is in contact and F_n(t) = E[(z − t)^n] to 1e-12: summed
#: over the Gauss–Hermite nodes (the closed form's e^(−t²/4) D(t) is 0 × inf there)
_DEEP = -7.0

#: above this t, F_n(t) < φ(t) < 1e-300: zero (pbdv is not finite that far out)
_FAR = 37.0


def gaussian_tail_integral(order: float, t: ArrayLike) -> Array:
    """F_n(t) = ∫_t^∞ (z − t)^n φ(z) dz for the standard normal density φ.

    Parameters
    ----------
    order : float
        n ≥ 0 (0: the tail probability; 1, 3/2: Greenwood & Williamson's area and load).
    t : array — [1]
        Separation in standard deviations (any finite real value).

    Returns
    -------
    array — [1]
        F_n(t) > 0 (0 beyond t = 37, where it underflows), decreasing in t; ~ |t|^n as
        t → −∞.

    Notes
    -----
    ∫₀^∞ u^n e^(−(u+t)²/2) du = Γ(n+1) e^(−t²/4) D_(−n−1)(t) (Gradshteyn & Ryzhik 3.462.1,
    D the parabolic cylinder function), so F_n(t) = Γ(n+1) e^(−t²/4) D_(−n−1)(t)/√(2π);
    for t < −7 (where that product overflows) the expectation E[(z − t)^n] by 60-point
    Gauss–Hermite quadrature, all of whose nodes lie above t there within 1e-12 of the
    mass. No input checks: the solver's inner loop calls it (the checked public form is
    :func:`friction.mixed_ehl.greenwood_tripp_integral`).
    """
    x = np.asarray(t, dtype=float)
    deep = x < _DEEP
    far = x > _FAR
    safe = np.where(deep | far, 0.0, x)
    d, _ = pbdv(-order - 1.0, safe)
    with np.errstate(under="ignore"):
        value = gamma(order + 1.0) / math.sqrt(2.0 * math.pi) * np.exp(-0.25 * safe * safe) * d
    value = np.where(far, 0.0, value)
    if np.any(deep):
        u = np.maximum(_GH_Z - x[deep][..., None], 0.0)
        value = np.where(deep, 0.0, value)
        value[deep] = (u**order) @ _GH_W
    return value


def profile_moments(heights: ArrayLike, spacing: float) -> tuple[float, float, float]:
    """Spectral moments m₀, m₂, m₄ of an equally spaced, periodic profile.

    Parameters
    ----------
    heights : array (n,) — [µm]
        Finite, n ≥ 16 (treated as one period; the mean is removed).
    spacing : float — [mm]
        Sampling interval, > 0.

    Returns
    -------
    (m0 [µm²], m2 [1], m4 [1/mm²])
        Variances of the heights, of the slope dz/dx and of the curvature d²z/dx², the
        derivatives by Fourier differentiation (exact for the band-limited profile).

    Raises
    ------
    InputError
        Non-finite heights, fewer than 16, or a non-positive spacing.

    Notes
    -----
    Source: Nayak (1971), §2: m₀ = ⟨z²⟩, m₂ = ⟨z′²⟩, m₄ = ⟨z″²⟩ of a profile are the
    spectral moments of the surface along it.
    """
    z = real_array("heights", heights, unit="µm", ndim=1)
    if z.size < 16:
        raise InputError(f"heights: needs at least 16 points, got {z.size}")
    dx = real("spacing", spacing, unit="mm", low=0.0, low_open=True)
    z = z - z.mean()
    k = 2.0 * math.pi * scipy.fft.rfftfreq(z.size, d=dx)          # [1/mm]
    spec = scipy.fft.rfft(z)
    if z.size % 2 == 0:
        spec[-1] = 0.0                              # the Nyquist term has no derivative
    slope = scipy.fft.irfft(1j * k * spec, n=z.size) * 1e-3        # µm/mm → 1
    curv = scipy.fft.irfft(-(k * k) * spec, n=z.size) * 1e-3       # µm/mm² → 1/mm
    return float(np.mean(z * z)), float(np.mean(slope * slope)), float(np.mean(curv * curv))


def composite_moments(*moments: tuple[float, float, float]) -> tuple[float, float, float]:
    """Moments of the sum of independent surfaces: each moment adds (m₀, m₂, m₄)."""
    return tuple(float(sum(m[k] for m in moments)) for k in range(3))  # type: ignore[return-value]


class SummitStatistics(NamedTuple):
    """Summit statistics of an isotropic Gaussian surface (McCool 1986).

    Units in the field comments; ``sigma`` is the surface's RMS height.
    """

    sigma: float          #: RMS roughness √m₀ [µm]
    bandwidth: float      #: Nayak's α = m₀m₄/m₂² [1] (≥ 1.5 for a real surface)
    density: float        #: summits per area η [1/mm²]
    radius: float         #: mean summit radius β [mm]
    summit_sigma: float   #: standard deviation of the summit heights σ_s [µm]
    summit_mean: float    #: mean summit height above the mean plane y_s [µm]


def summit_statistics(m0: float, m2: float, m4: float) -> SummitStatistics:
    """Summit density, radius and height statistics from the spectral moments.

    Parameters
    ----------
    m0 : float — [µm²]
    m2 : float — [1]
    m4 : float — [1/mm²]
        All > 0 (:func:`profile_moments`, :func:`composite_moments`).

    Returns
    -------
    SummitStatistics

    Raises
    ------
    InputError
        A moment ≤ 0, or a bandwidth α < 1.5 (no real surface has it: m₂² ≤ m₀m₄ by
        Cauchy–Schwarz, and Nayak's summit statistics need α well above 1).

    Notes
    -----
    McCool (1986), Eq. 3–7, for an isotropic Gaussian surface: η = m₄/(6π√3 m₂),
    β = 0.375 (π/m₄)^½, σ_s = (1 − 0.8968/α)^½ m₀^½, y_s = 4 m₀^½/(πα)^½.
    """
    m0 = real("m0", m0, unit="µm2", low=0.0, low_open=True)
    m2 = real("m2", m2, unit="1", low=0.0, low_open=True)
    m4 = real("m4", m4, unit="1/mm2", low=0.0, low_open=True)
    m0_mm = m0 * 1e-6                                   # µm² → mm²
    alpha = m0_mm * m4 / (m2 * m2)
    if alpha < 1.5:
        raise InputError(f"moments: bandwidth m0 m4 / m2^2 = {alpha:.3g} < 1.5; these are "
                         f"not the moments of a rough surface")
    return SummitStatistics(
        sigma=math.sqrt(m0),
        bandwidth=alpha,
        density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
        radius=0.375 * math.sqrt(math.pi / m4),
        summit_sigma=math.sqrt((1.0 - 0.8968 / alpha) * m0),
        summit_mean=4.0 * math.sqrt(m0) / math.sqrt(math.pi * alpha),
    )


def hardness_factor(poisson_ratio: float) -> float:
    """K of the mean contact pressure K·H at a summit's yield, K = 0.454 + 0.41ν [1].

    Source: Chang, Etsion & Bogy (1987), Eq. 5 (maximum contact pressure at the onset of
    yield of a sphere, K H = 0.6 × 1.1 … for steel ≈ 0.58 H).
    """
    return 0.454 + 0.41 * real("poisson_ratio", poisson_ratio, unit="1", low=0.0, high=0.5)


class AsperityContact(NamedTuple):
    """The summits' share of a contact at given separations, arrays of its shape."""

    pressure: Array       #: nominal (area-averaged) asperity pressure [MPa]
    area: Array           #: real contact area over apparent area, spots merged [1]
    slope: Array          #: d pressure / d separation [MPa/µm] (≤ 0)


def asperity_contact(separation: ArrayLike, stats: SummitStatistics, e_prime: float,
                     hardness: float, poisson_ratio: float = 0.3) -> AsperityContact:
    """Pressure and real contact area carried by the summits at a mean-plane separation.

    Parameters
    ----------
    separation : array — [µm]
        Distance between the mean planes of the two surfaces (negative where they
        interpenetrate: the summits are then deeply compressed).
    stats : SummitStatistics
        Of the composite surface (:func:`summit_statistics` of the summed moments).
    e_prime : float — [MPa]
        E′ = 2E* (the toolkit's convention, :mod:`friction.film`).
    hardness : float — [MPa]
        Hardness H of the softer surface (:attr:`geometry.core.materials.Material.hardness`).
    poisson_ratio : float — [1]
        For the hardness factor K (:func:`hardness_factor`).

    Returns
    -------
    AsperityContact
        Arrays of the separation's shape. The area is the share of the apparent area the
        summits' spots cover, 1 − e^(−A_s) with A_s the sum of their areas (the spots
        placed at random and merging where they overlap: the covered fraction of a
        Boolean model, Hall 1988), so that it stays below 1.

    Notes
    -----
    Greenwood & Williamson (1966) with Chang, Etsion & Bogy's (1987) summit law: with
    d = separation − y_s (the distance of the summits' mean height from the other
    surface's plane), ω = z − d the interference of a summit of height z,

        elastic, ω ≤ ω_c:  load (4/3)E*β^½ω^{3/2},  area πβω;
        plastic, ω > ω_c:  load πβω(2 − ω_c/ω)·KH, area πβω(2 − ω_c/ω),
        ω_c = (πKH/(2E*))² β,

    summed over η summits per area of Gaussian heights (σ_s):
    p = η[(4/3)E*β^½ ∫₀^{ω_c} ω^{3/2} φ_s dω + πβKH σ_s(2F₁(t_c) + (ω_c/σ_s)F₀(t_c))],
    t_c = (d + ω_c)/σ_s — the elastic part by quadrature in
    v = ((ω − a)/(b − a))^½ over the part [a, b] of [0, ω_c] holding summits (32-point
    Gauss–Legendre), the plastic part in closed form. Without the
    plastic branch (H → ∞) it is Greenwood & Williamson's p = (4/3)E*ηβ^½σ_s^{3/2}F_{3/2}.
    """
    h = np.asarray(separation, dtype=float)
    e_star = 0.5 * e_prime                                    # [MPa]
    kh = hardness_factor(poisson_ratio) * hardness            # [MPa]
    beta = stats.radius * 1e3                                 # mm → µm
    eta = stats.density * 1e-6                                # 1/mm² → 1/µm²
    sig = stats.summit_sigma
    omega_c = (math.pi * kh / (2.0 * e_star)) ** 2 * beta     # [µm]
    d = h - stats.summit_mean
    # elastic summits, 0 < ω < ω_c: ∫ ω^{3/2} φ_s(d + ω) dω over the part of [0, ω_c]
    # where summits exist (within 9 σ_s of their mean at ω = −d), ω = a + (b − a)v²
    lo = np.clip(-d - 9.0 * sig, 0.0, omega_c)[..., None]
    hi = np.clip(-d + 9.0 * sig, 0.0, omega_c)[..., None]
    om = lo + (hi - lo) * _GL_V**2                            # (..., 16)
    zq = (d[..., None] + om) / sig
    dens = np.exp(-0.5 * zq * zq) / (math.sqrt(2.0 * math.pi) * sig)
    jac = 2.0 * (hi - lo) * _GL_V * _GL_W                      # dω = 2(b − a) v dv
    el_load = np.sum(om**1.5 * dens * jac, axis=-1)            # [µm^{3/2}]
    el_area = np.sum(om * dens * jac, axis=-1)                 # [µm]
    # d/dd of ∫ f(ω) φ_s(d + ω) dω = ∫ f φ_s′, φ_s′(z) = −(z/σ_s²) φ_s(z) (the limits
    # 0 and ω_c are fixed; the clipped ones only drop mass below 1e-18)
    el_slope = np.sum(om**1.5 * dens * (-zq / sig) * jac, axis=-1)
    tc = (d + omega_c) / sig
    f0, f1 = gaussian_tail_integral(0.0, tc), gaussian_tail_integral(1.0, tc)
    pl = 2.0 * sig * f1 + omega_c * f0                        # ∫_{ω>ω_c}(2ω − ω_c)φ_s dω [µm]
    c_el = (4.0 / 3.0) * e_star * math.sqrt(beta) * eta       # [MPa / µm^{3/2}]
    c_pl = math.pi * beta * kh * eta                           # [MPa / µm]
    pressure = c_el * el_load + c_pl * pl
    area = math.pi * beta * eta * (el_area + pl)
    # d(pl)/dd = −2F₀(t_c) − (ω_c/σ_s)φ(t_c) (F₁′ = −F₀, F₀′ = −φ); both integrals run
    # over fixed ranges of ω, so the jump of the summit law at ω_c (the plastic load is
    # 3/2 of the elastic one there) adds no boundary term
    phi_c = np.exp(-0.5 * tc * tc) / math.sqrt(2.0 * math.pi)
    dpl = -2.0 * f0 - (omega_c / sig) * phi_c
    slope = c_el * el_slope + c_pl * dpl
    return AsperityContact(pressure=pressure, area=-np.expm1(-area), slope=slope)
