"""Measured-like roughness profiles of ground gear flanks, reproducible and scaled to any Rq.

A ground surface's profile is modelled as a stationary random process with

* an exponential autocorrelation R(τ) = Rq² exp(−|τ|/β*) (the usual model of ground and
  other finished surfaces, Whitehouse & Archard 1970; Patir 1978), i.e. the one-sided
  power spectrum S(k) ∝ 1/(1 + (kβ*)²), band-limited at the ISO 4287/4288 roughness cutoff
  λc (0.8 mm by default: longer waves are form and waviness, not roughness);
* a negative skewness (ground surfaces: −0.3 … −1, plateaux with valleys), obtained by the
  monotone Hermite transform z ↦ z + a(z² − 1) of the Gaussian process, a chosen so that
  the transformed process has the target skewness exactly in expectation
  (skew = (6a + 8a³)/(1 + 2a²)^{3/2});
* finally shifted to zero mean and scaled to the requested Rq (sample RMS exactly).

The seed (§5.2.3) uses a measured ground profile of Rq 0.5 µm that is not published; this
generator gives a stated stand-in: the default correlation length β* = 10 µm and skewness
−0.5 lie inside the ranges reported for ground gear flanks (e.g. Li & Kahraman, Tribol.
Int. 43 (2010) 1034; Sharif et al., Wear 1998).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from geometry.core.errors import InputError
from geometry.core.validation import integer, real, real_array

__all__ = ["ground_profile", "scale_to_rq", "skewness_transform_coefficient"]

Array = NDArray[np.float64]


def skewness_transform_coefficient(skewness: float) -> float:
    """Coefficient a of z + a(z² − 1) giving a target skewness for standard normal z.

    Parameters
    ----------
    skewness : float — [1]
        Target, |skewness| ≤ 2.5.

    Returns
    -------
    float — [1]
        a with (6a + 8a³)/(1 + 2a²)^{3/2} = skewness (same sign as skewness).

    Notes
    -----
    Source: moments of a Gaussian: E[z³] = 0, E[z⁴] = 3, E[z⁶] = 15 (Fleishman, B.,
    Psychometrika 43 (1978) 521, the quadratic case).
    """
    s = real("skewness", skewness, unit="1", low=-2.5, high=2.5)
    if s == 0.0:
        return 0.0

    def f(a: float) -> float:
        return (6.0 * a + 8.0 * a**3) / (1.0 + 2.0 * a * a) ** 1.5 - abs(s)

    return math.copysign(brentq(f, 0.0, 50.0, xtol=1e-14), s)


def scale_to_rq(heights: ArrayLike, rq: float) -> Array:
    """A profile shifted to zero mean and scaled to a given RMS roughness.

    Parameters
    ----------
    heights : array (n,) — [µm]
        Finite, not constant.
    rq : float — [µm]
        Target Rq ≥ 0 (0 gives a smooth profile).

    Returns
    -------
    array (n,) — [µm]

    Raises
    ------
    InputError
        NaN/inf heights, fewer than 2 points, or a constant profile with rq > 0.
    """
    z = real_array("roughness", heights, unit="µm", ndim=1)
    target = real("rq", rq, unit="µm", low=0.0, high=50.0)
    if z.size < 2:
        raise InputError(f"roughness: needs at least 2 heights, got {z.size}")
    z = z - z.mean()
    s = float(np.sqrt(np.mean(z * z)))
    if target == 0.0:
        return np.zeros_like(z)
    if s == 0.0:
        raise InputError("roughness: a constant profile cannot be scaled to Rq > 0")
    return z * (target / s)


def ground_profile(
    x: ArrayLike, rq: float, *, correlation_length: float = 0.010, skewness: float = -0.5,
    cutoff: float = 0.8, seed: int = 2009,
) -> Array:
    """A reproducible measured-like ground profile on equally spaced abscissae.

    Parameters
    ----------
    x : array (n,) — [mm]
        Equally spaced, increasing, n ≥ 16.
    rq : float — [µm]
        RMS roughness of the result (exact for the sample), ≥ 0.
    correlation_length : float — [mm]
        β* of the exponential autocorrelation, > 0.
    skewness : float — [1]
        Target skewness (in expectation), |·| ≤ 2.5.
    cutoff : float — [mm]
        Long-wavelength cutoff λc (wavelengths longer than it are removed), > 0.
    seed : int
        Seed of the random generator (``numpy.random.default_rng``): same seed, same profile.

    Returns
    -------
    array (n,) — [µm]

    Raises
    ------
    InputError
        A parameter out of range or x not equally spaced.

    Notes
    -----
    Source: spectral synthesis of a random process by filtering white noise (Hu, Y. Z.,
    Tonder, K., Int. J. Mach. Tools Manufact. 32 (1992) 83) with the exponential ACF's
    spectrum; the skewness transform of :func:`skewness_transform_coefficient`.
    """
    xs = real_array("x", x, unit="mm", ndim=1)
    if xs.size < 16:
        raise InputError(f"x: needs at least 16 points, got {xs.size}")
    dx = np.diff(xs)
    if np.any(dx <= 0.0) or np.ptp(dx) > 1e-6 * abs(dx.mean()):
        raise InputError("x: must be equally spaced and increasing")
    beta = real("correlation_length", correlation_length, unit="mm", low=0.0, low_open=True)
    lc = real("cutoff", cutoff, unit="mm", low=0.0, low_open=True)
    integer("seed", seed, low=0)
    a = skewness_transform_coefficient(skewness)
    n = xs.size
    m = 2 * n                                  # pad: no wrap-around correlation
    rng = np.random.default_rng(seed)
    noise = rng.standard_normal(m)
    k = 2.0 * math.pi * scipy.fft.rfftfreq(m, d=float(dx.mean()))
    amplitude = 1.0 / np.sqrt(1.0 + (k * beta) ** 2)
    amplitude[k < 2.0 * math.pi / lc] = 0.0
    z = scipy.fft.irfft(scipy.fft.rfft(noise) * amplitude, n=m)[:n]
    z = (z - z.mean()) / z.std()
    z = z + a * (z * z - 1.0)
    return scale_to_rq(z, rq)
