"""Asperity summits of two gear flanks from their roughness, and the pressure they carry.

``mixed_ehl`` (:mod:`friction.mixed_ehl`) describes the asperities by two fixed numbers,
ηβσ = 0.05 and σ/β = 0.01, so a rougher flank gets proportionally blunter summits and the
roughness reaches the friction only through λ (issue 74). This module derives the summits
from the flank's roughness instead:

* **The profile.** A ground flank's roughness profile is the toolkit's reproducible
  ground profile (:class:`friction.ehl.roughness.GroundSurface`: exponential
  autocorrelation, correlation length 10 µm, skewness −0.5, seen through the stylus
  filter λs 8 µm, inside the ranges measured on ground gear flanks — that module's
  sources) *scaled in height to the flank's Rq*: the seed's own construction of its
  rough surfaces ("a baseline ground profile multiplied by a constant", Kolivand 2009
  §5.2.3). Its spectral moments m₀, m₂, m₄ then scale with
  Rq², each surface's computed once at unit Rq (:func:`unit_profile_moments`).
* **The summits** of the composite surface (the two flanks' moments added, Greenwood &
  Tripp 1970) follow from the moments by Nayak (1971) / McCool (1986)
  (:func:`friction.ehl.asperity.summit_statistics`): density η = m₄/(6π√3 m₂), mean
  radius β = 0.375 √(π/m₄), summit-height deviation σ_s and mean height y_s. With the
  profile scaled by Rq, η stays, β ∝ 1/Rq and σ_s ∝ Rq: a rougher ground flank has
  sharper summits (σ/β ∝ Rq²), where the fixed constants made them blunter.
* **The pressure they carry** is Greenwood & Tripp's two-rough-surface law
  p_a = K′E′F_{5/2}(h/σ), K′ = (8√2/15)π(ηβσ)²√(σ/β) (:func:`friction.mixed_ehl.
  asperity_pressure`) with ηβσ and σ/β of those summits (:func:`greenwood_tripp_parameters`):
  ηβσ = 0.0558 at any Rq and σ/β = 0.154 σ² [σ in µm] — 0.0014 / 0.091 / 0.24 at the
  run-in Rq 0.068 / 0.544 / 0.884 µm of each flank (given Rq 0.1 / 0.8 / 1.3 µm), where the
  fixed constants held 0.01.
* **The height distribution** is the profiles' own, not a Gaussian: a ground flank's
  heights are negatively skewed (the generator's −0.5, −0.36 / −0.48 after the λs filter,
  :func:`unit_profile_skewness`), so the composite's upper tail is thinner and F_{5/2} in
  Greenwood & Tripp's law is the skewed heights' (:func:`height_tail_integral`: 0.88 /
  0.63 / 0.25 × the Gaussian's at h/σ = 0 / 1 / 2).

Greenwood & Tripp's constant was derived with each surface's own summit density and radius;
the composite surface's are taken here (the toolkit's convention for two flanks, as its
stochastic solver): for two flanks of one profile K′ is then 2^(−3/4) = 0.59 × the
per-surface value (:func:`greenwood_tripp_parameters`; both measured in docs/friction.md).

Measured alternative, not adopted: Greenwood & Williamson's one-surface sum over the same
summits with their mean height y_s above the mean plane and Chang, Etsion & Bogy's (1987)
elastic–plastic summits (:func:`friction.ehl.asperity.asperity_contact`, the stochastic
solver's law; Greenwood & Williamson's plasticity index :func:`plasticity_index` is 0.6 /
4.8 / 7.9 at those Rq on 697 HV steel) carries 2–6× the load of the two-surface law at the
separations of a gear's mixed film; in the load sharing it put the flank μ at 2.0–2.1×
ISO/TR 14179-2 at the seed's point (docs/friction.md, "Asperities from the roughness").

Running-in is a change of roughness (:attr:`friction.operating.OperatingConditions.
effective_roughness`, Rq × 0.68 after AGMA 925-A03): the run-in flank's summits are those
of the profile at the run-in Rq — blunter (β / 0.68) — so running-in lowers σ/β by
0.68² = 0.46 as well as σ.

References
----------
Kolivand, M., PhD dissertation, Ohio State University (2009), §5.2.3 (scaled profiles).
Li, S., Kahraman, A., Tribol. Int. 43 (2010) 1034 (the ground profile's parameter ranges,
via :mod:`friction.ehl.roughness`).
Fleishman, A. I., "A method for simulating non-normal distributions", Psychometrika 43
(1978) 521–532 (the skewed heights' transform).
Nayak, P. R., J. Lubr. Technol. 93 (1971) 398–407.
McCool, J. I., "Comparison of models for the contact of rough surfaces", Wear 107 (1986)
37–60.
Greenwood, J. A., Williamson, J. B. P., Proc. R. Soc. A 295 (1966) 300–319 (and their
plasticity index).
Greenwood, J. A., Tripp, J. H., Proc. Instn Mech. Engrs 185 (1970) 625–633.
Chang, W. R., Etsion, I., Bogy, D. B., J. Tribol. 109 (1987) 257–263 (the alternative).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import CubicSpline

from friction.ehl.asperity import (
    SummitStatistics,
    composite_moments,
    profile_moments,
    summit_statistics,
)
from friction.ehl.roughness import (
    GroundSurface,
    gaussian_lowpass,
    skewness_transform_coefficient,
)
from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.validation import real, real_array

__all__ = ["FLANK_FINISHES", "flank_summit_statistics", "greenwood_tripp_parameters",
           "height_tail_integral", "plasticity_index", "unit_profile_moments",
           "unit_profile_skewness"]

Array = NDArray[np.float64]

#: finish → (the two surfaces' profile generators at unit Rq, source). Only a ground
#: finish has a stated profile; a lapped or superfinished flank's summits need its measured
#: profile (friction.ehl.roughness.MeasuredSurface through friction.ehl.stochastic.
#: roughness_statistics), not a guessed one.
FLANK_FINISHES = {
    "ground": ((GroundSurface(1.0, seed=1), GroundSurface(1.0, seed=2)),
               "the toolkit's ground profile (friction.ehl.roughness.GroundSurface, seeds 1 "
               "and 2: exponential ACF 10 µm, skewness −0.5, λs 8 µm) scaled to Rq (seed "
               "§5.2.3)"),
}

#: [mm] length of each profile the moments are taken over (as the stochastic solver's)
_MOMENT_LENGTH = 10.0


@memoised(maxsize=None)
def unit_profile_moments(finish: str = "ground") -> tuple[tuple[float, float, float], ...]:
    """Spectral moments (1 [µm²], m₂/m₀ [1/µm²], m₄/m₀ [1/(mm² µm²)]) of each of the two
    surfaces of a finish, at unit Rq.

    Parameters
    ----------
    finish : str
        A key of :data:`FLANK_FINISHES`.

    Returns
    -------
    tuple of two (m₀, m₂, m₄) — per unit Rq² ([1], [1/µm²], [1/(mm² µm²)])

    Raises
    ------
    InputError
        An unknown finish (the message lists the known ones).

    Notes
    -----
    Each profile over 10 mm seen through its λs (Gaussian profile filter, ISO 16610-21)
    and its moments by Fourier differentiation (:func:`friction.ehl.asperity.
    profile_moments`, Nayak 1971).
    """
    if finish not in FLANK_FINISHES:
        raise InputError(f"finish: {finish!r} is not one of {sorted(FLANK_FINISHES)}; a "
                         "lapped or superfinished flank needs its measured profile "
                         "(friction.ehl.roughness.MeasuredSurface)")
    out = []
    for s in FLANK_FINISHES[finish][0]:
        raw, dx = s.profile(_MOMENT_LENGTH)
        z = gaussian_lowpass(raw, dx, float(s.short_cutoff))
        m0, m2, m4 = profile_moments(z, dx)
        out.append((1.0, m2 / m0, m4 / m0))
    return tuple(out)


def flank_summit_statistics(roughness_1: float, roughness_2: float,
                            finish: str = "ground") -> SummitStatistics:
    """Summit statistics of the composite surface of two flanks of a finish at given Rq.

    Parameters
    ----------
    roughness_1, roughness_2 : float — [µm]
        RMS roughness of each flank, ≥ 0, not both 0.
    finish : str
        A key of :data:`FLANK_FINISHES`.

    Returns
    -------
    SummitStatistics
        σ [µm], bandwidth [1], density [1/mm²], radius [mm], summit σ_s and mean y_s [µm].

    Raises
    ------
    InputError
        A roughness out of range, both zero, or an unknown finish.

    Notes
    -----
    Independent surfaces add their moments; McCool (1986) / Nayak (1971) give the
    summits (module docstring).
    """
    r1 = real("roughness_1", roughness_1, unit="µm", low=0.0, high=50.0)
    r2 = real("roughness_2", roughness_2, unit="µm", low=0.0, high=50.0)
    if r1 == 0.0 and r2 == 0.0:
        raise InputError("roughness_1, roughness_2: both 0; smooth surfaces have no summits")
    u1, u2 = unit_profile_moments(finish)
    parts = [tuple(m * r * r for m in u) for u, r in ((u1, r1), (u2, r2)) if r > 0.0]
    return summit_statistics(*composite_moments(*parts))


def plasticity_index(stats: SummitStatistics, e_prime: float, hardness: float) -> float:
    """Greenwood & Williamson's plasticity index ψ = (E*/H)√(σ_s/β) [1].

    Parameters
    ----------
    stats : SummitStatistics
    e_prime : float — [MPa] E′ = 2E*
    hardness : float — [MPa] H of the softer surface

    Returns
    -------
    float — [1]; ψ < 0.6 elastic summits, ψ > 1 most summits yield at first contact.

    Notes
    -----
    Greenwood & Williamson (1966), Eq. 14.
    """
    return 0.5 * e_prime / hardness * math.sqrt(stats.summit_sigma * 1e-3 / stats.radius)


def greenwood_tripp_parameters(roughness_1: float, roughness_2: float,
                               finish: str = "ground") -> tuple[float, float]:
    """ηβσ and σ/β [1] of Greenwood & Tripp's asperity law for two flanks of a finish.

    Parameters
    ----------
    roughness_1, roughness_2 : float — [µm]
        RMS roughness of each flank (:func:`flank_summit_statistics`).
    finish : str
        A key of :data:`FLANK_FINISHES`.

    Returns
    -------
    (float, float) — [1], [1]
        η β σ (summit density × mean radius × composite σ; the same at every Rq of a
        finish, 0.0558 for the ground profile) and σ/β (∝ Rq² at a fixed ratio Rq₂/Rq₁:
        0.154 σ² [σ in µm] for the ground profile, capped at 1).

    Raises
    ------
    InputError
        As :func:`flank_summit_statistics`.

    Notes
    -----
    McCool (1986) summits of the composite surface (module docstring) in the form
    :func:`friction.mixed_ehl.asperity_pressure` takes (Greenwood & Tripp 1970, with
    their approximations: summit heights spread by the composite σ about its mean plane).
    Greenwood & Tripp's constant was derived with each surface's own η and β; the
    composite's (the toolkit's convention for two flanks, as
    :func:`friction.ehl.stochastic.roughness_statistics`) gives, for two flanks of one
    profile, a K′ 2^(−3/4) = 0.59 × that (docs/friction.md, "Which summits enter Greenwood &
    Tripp's constant", measures both).
    """
    s = flank_summit_statistics(roughness_1, roughness_2, finish)
    beta_um = s.radius * 1e3
    return s.density * 1e-6 * beta_um * s.sigma, min(s.sigma / beta_um, 1.0)


@memoised(maxsize=None)
def unit_profile_skewness(finish: str = "ground") -> tuple[float, float]:
    """Skewness [1] of each of the two surfaces' profiles of a finish, seen through λs.

    Parameters
    ----------
    finish : str
        A key of :data:`FLANK_FINISHES`.

    Returns
    -------
    (float, float) — [1]
        ⟨z³⟩/⟨z²⟩^{3/2} of each profile over 10 mm after the λs filter (the ground profile:
        −0.36 and −0.48; generated at −0.5 in expectation, the λs filter's averaging
        lowers it).

    Raises
    ------
    InputError
        An unknown finish.

    Notes
    -----
    The sample skewness of the profile whose moments :func:`unit_profile_moments` takes.
    """
    unit_profile_moments(finish)  # validates the finish
    out = []
    for s in FLANK_FINISHES[finish][0]:
        raw, dx = s.profile(_MOMENT_LENGTH)
        z = gaussian_lowpass(raw, dx, float(s.short_cutoff))
        z = z - z.mean()
        out.append(float(np.mean(z**3) / np.mean(z * z) ** 1.5))
    return out[0], out[1]


#: t = h/σ over which the composite heights' F_{5/2} is tabulated; below it evaluated
#: directly, above it 0 (F_{5/2}(8) < 1e-17 for the Gaussian, less for negative skewness)
_TAIL_RANGE = (-8.0, 8.0)
#: standard-normal abscissae and trapezoid weights of each surface's Gaussian parent
_Z = np.linspace(-9.0, 9.0, 2001)
_WZ = np.exp(-0.5 * _Z * _Z) * (_Z[1] - _Z[0]) / math.sqrt(2.0 * math.pi)


def _composite_heights(skew_1: float, skew_2: float, weight_1: float
                       ) -> tuple[Array, Array]:
    """Histogram (bin centres, probabilities) of z = w₁y₁ + w₂y₂, w₁² + w₂² = 1, each y_i
    the unit-variance Fleishman transform (z + a(z² − 1))/√(1 + 2a²) of a standard normal
    with the skewness skew_i; bins of 0.002 over ±12."""
    w1 = weight_1
    w2 = math.sqrt(max(1.0 - w1 * w1, 0.0))
    ys = []
    for sk in (skew_1, skew_2):
        a = skewness_transform_coefficient(sk)
        ys.append((_Z + a * (_Z * _Z - 1.0)) / math.sqrt(1.0 + 2.0 * a * a))
    x = np.add.outer(w1 * ys[0], w2 * ys[1]).ravel()
    p = np.multiply.outer(_WZ, _WZ).ravel()
    edges = np.arange(-12.0, 12.0 + 1e-9, 0.002)
    hist, _ = np.histogram(x, bins=edges, weights=p)
    centres = 0.5 * (edges[1:] + edges[:-1])
    mean = float(np.sum(hist * centres) / hist.sum())
    sd = math.sqrt(float(np.sum(hist * (centres - mean) ** 2) / hist.sum()))
    return (centres - mean) / sd, hist / hist.sum()


@memoised(maxsize=32)
def _tail_table(finish: str, weight_1: float) -> tuple[CubicSpline, Array, Array]:
    skew = unit_profile_skewness(finish)
    x, p = _composite_heights(skew[0], skew[1], weight_1)
    t = np.linspace(*_TAIL_RANGE, 321)
    f = np.array([np.sum(p * np.maximum(x - ti, 0.0) ** 2.5) for ti in t])
    keep = f > 1e-300
    return CubicSpline(t[keep], np.log(f[keep])), x, p


def height_tail_integral(separation: ArrayLike, roughness_1: float, roughness_2: float,
                         finish: str = "ground") -> Array:
    """F_{5/2}(t) = E[(z − t)₊^{5/2}] [1] of the two flanks' composite height distribution.

    Parameters
    ----------
    separation : array — [1]
        t = h/σ, the mean-plane separation over the composite RMS roughness.
    roughness_1, roughness_2 : float — [µm]
        RMS roughness of each flank (they weight the two surfaces' heights).
    finish : str
        A key of :data:`FLANK_FINISHES`.

    Returns
    -------
    array — [1]
        The shape of ``separation``; positive, decreasing; for zero skewness the
        Gaussian's (:func:`friction.mixed_ehl.greenwood_tripp_integral`).

    Raises
    ------
    InputError
        A roughness out of range, both zero, an unknown finish, a non-finite separation.

    Notes
    -----
    Greenwood & Tripp's (1970) asperity pressure takes the heights' F_{5/2}; they take the
    heights Gaussian. A ground flank's heights are negatively skewed (plateaux and
    valleys): each flank's heights are the Fleishman (1978) transform of a Gaussian with
    its profile's skewness (:func:`unit_profile_skewness`; the generator's own law,
    :func:`friction.ehl.roughness.ground_profile`), the composite the sum of the two
    independent flanks weighted by their Rq (w_i = Rq_i/σ), normalised to zero mean and
    unit variance. The sum's distribution by quadrature (2001 Gaussian nodes per flank,
    binned at 0.002 σ), F_{5/2} by summation, tabulated as a spline of ln F over
    t ∈ [−8, 8] (321 nodes), summed directly below, 0 above. The ground pair at equal Rq:
    composite skewness −0.30, F_{5/2} 0.88 / 0.78 / 0.63 / 0.25 × the Gaussian's at t = 0 /
    0.5 / 1 / 2.
    """
    r1 = real("roughness_1", roughness_1, unit="µm", low=0.0, high=50.0)
    r2 = real("roughness_2", roughness_2, unit="µm", low=0.0, high=50.0)
    if r1 == 0.0 and r2 == 0.0:
        raise InputError("roughness_1, roughness_2: both 0; smooth surfaces have no heights")
    t = real_array("separation", separation, unit="1")
    spline, x, p = _tail_table(finish, round(r1 / math.hypot(r1, r2), 6))
    lo, hi = _TAIL_RANGE
    with np.errstate(under="ignore"):
        out = np.where(t > hi, 0.0, np.exp(spline(np.clip(t, lo, hi))))
    low = t < lo
    if np.any(low):
        out = np.array(out, dtype=float)
        out[low] = [float(np.sum(p * np.maximum(x - ti, 0.0) ** 2.5)) for ti in t[low]]
    return np.asarray(out, dtype=float)
