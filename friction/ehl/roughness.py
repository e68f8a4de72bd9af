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
from dataclasses import dataclass

import numpy as np
import scipy.fft
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from geometry.core.errors import InputError
from geometry.core.validation import integer, real, real_array

__all__ = ["DEFAULT_SHORT_CUTOFF", "GroundSurface", "MeasuredSurface", "MovingProfile",
           "gaussian_lowpass", "ground_profile", "scale_to_rq", "skewness_transform_coefficient",
           "surface_on_grid"]

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


def gaussian_lowpass(heights: ArrayLike, spacing: float, cutoff: float) -> Array:
    """A profile's roughness seen through the ISO Gaussian profile filter of cutoff λs.

    Parameters
    ----------
    heights : array (n,) — [µm]
        Equally spaced heights (treated as one period of a periodic profile).
    spacing : float — [mm]
        Sampling interval, > 0.
    cutoff : float — [mm]
        λs ≥ 0: wavelengths at λs keep half their amplitude, shorter ones are removed
        (0 returns the profile unchanged).

    Returns
    -------
    array (n,) — [µm]

    Notes
    -----
    Transmission exp(−π(αλs/λ)²), α = √(ln 2/π), applied in the Fourier domain.
    Source: ISO 16610-21:2011, Eq. (2) (the Gaussian profile filter of ISO 11562).
    """
    z = real_array("heights", heights, unit="µm", ndim=1)
    d = real("spacing", spacing, unit="mm", low=0.0, low_open=True)
    lam = real("cutoff", cutoff, unit="mm", low=0.0)
    if lam == 0.0:
        return z.copy()
    f = scipy.fft.rfftfreq(z.size, d=d)                       # 1/wavelength [1/mm]
    alpha = math.sqrt(math.log(2.0) / math.pi)
    return scipy.fft.irfft(scipy.fft.rfft(z) * np.exp(-math.pi * (alpha * lam * f) ** 2),
                           n=z.size)


class MovingProfile:
    """One surface's roughness in the contact's frame as it moves: z(X − cT) at the nodes.

    Parameters
    ----------
    heights : array (m,) — [1]
        The surface's heights (dimensionless, H units) on material places ξ₀ + jΔ, band-
        limited below the grid's Nyquist wavelength 2Δ (e.g. filtered at 4Δ).
    spacing : float — [1]
        Δ, the solver's node spacing.
    start : float — [1]
        ξ₀, the material place of the first height.

    Notes
    -----
    The heights at any shift are the band-limited (trigonometric) interpolant of the
    samples, evaluated by a phase shift of their discrete Fourier transform: exact at whole
    node shifts and free of the amplitude loss of linear interpolation between them. The
    profile is periodic with its length; a caller asks for shifts that stay inside it.
    """

    def __init__(self, heights: Array, spacing: float, start: float) -> None:
        self.heights = np.asarray(heights, dtype=float)
        self.spacing = float(spacing)
        self.start = float(start)
        self._spectrum = scipy.fft.rfft(self.heights)
        self._wavenumber = 2.0 * math.pi * scipy.fft.rfftfreq(self.heights.size, d=spacing)

    def at(self, first: float, nodes: int, shift: float, derivative: int = 0) -> Array:
        """Heights z(X_i − shift) (or their X-derivative) at X_i = first + iΔ, i < nodes.

        Parameters
        ----------
        first : float — [1]
            X of the first node.
        nodes : int
        shift : float — [1]
            How far the surface has moved.
        derivative : {0, 1}
            0: the heights; 1: the slope dz/dX of the same interpolant.

        Returns
        -------
        array (nodes,) — [1]

        Raises
        ------
        ValueError
            The nodes' material places leave the stored profile.
        """
        offset = (first - shift - self.start) / self.spacing
        j = math.floor(offset)
        frac = offset - j
        if j < 0 or j + nodes > self.heights.size:
            raise ValueError("moving profile: the nodes leave the stored material profile")
        if frac == 0.0 and derivative == 0:
            return self.heights[j:j + nodes].copy()
        spectrum = self._spectrum * np.exp(1j * self._wavenumber * frac * self.spacing)
        if derivative:
            spectrum = spectrum * (1j * self._wavenumber)
            if self.heights.size % 2 == 0:
                spectrum[-1] = 0.0                      # the Nyquist term has no slope
        return scipy.fft.irfft(spectrum, n=self.heights.size)[j:j + nodes]


#: [mm] λs of a stylus profile paired with λc = 2.5 mm (ISO 3274 Table 1), the default
#: short-wave limit of a ground profile: with the default correlation length and skewness
#: a ground profile of Rq 0.5 µm then has RΔq ≈ 0.10 rad and RSm ≈ 32 µm, inside the
#: ranges measured on ground gear flanks
DEFAULT_SHORT_CUTOFF = 0.008


@dataclass(frozen=True)
class GroundSurface:
    """A ground flank's roughness, generated as long as a transient run needs it.

    Parameters
    ----------
    rq : float — [µm]
        RMS roughness of the profile seen through λs, 0 … 50 (0: smooth).
    seed : int
        Realisation (:func:`ground_profile`'s seed).
    correlation_length, skewness, long_cutoff : float
        As :func:`ground_profile` ([mm], [1], [mm]).
    short_cutoff : float — [mm]
        λs of the Gaussian profile filter (:func:`gaussian_lowpass`), ≥ 0.
    sampling : float — [mm]
        Spacing on which the profile is generated before it is filtered and resampled to a
        solver's grid, > 0; the same seed and sampling give the same profile whatever the
        solver's grid (a grid-convergence study compares one surface).

    Notes
    -----
    A Gaussian random profile of exponential autocorrelation, the form measured on ground
    and other finished surfaces (Whitehouse & Archard 1970; Patir 1978), synthesised by
    filtering white noise (Hu & Tonder 1992; :func:`ground_profile`).
    """

    rq: float
    seed: int = 1
    correlation_length: float = 0.010
    skewness: float = -0.5
    short_cutoff: float = DEFAULT_SHORT_CUTOFF
    long_cutoff: float = 0.8
    sampling: float = 0.0005

    def check(self) -> None:
        """Raise :class:`InputError` naming the field out of range."""
        real("rq", self.rq, unit="µm", low=0.0, high=50.0)
        integer("seed", self.seed, low=0)
        real("correlation_length", self.correlation_length, unit="mm", low=0.0,
             low_open=True)
        real("short_cutoff", self.short_cutoff, unit="mm", low=0.0)
        real("long_cutoff", self.long_cutoff, unit="mm", low=0.0, low_open=True)
        real("sampling", self.sampling, unit="mm", low=1e-6, high=0.1)
        skewness_transform_coefficient(self.skewness)

    def profile(self, length: float) -> tuple[Array, float]:
        """Heights over a material length, unfiltered, unit RMS, and their spacing.

        Parameters
        ----------
        length : float — [mm]
            At least this long (rounded up to whole millimetres so that a slightly
            different run length draws the same random numbers).

        Returns
        -------
        (array (m,) [1], float [mm])
        """
        self.check()
        m = round(math.ceil(max(length, 1e-3)) / self.sampling) + 1
        x = np.arange(max(m, 16)) * self.sampling
        return ground_profile(x, 1.0, correlation_length=self.correlation_length,
                              skewness=self.skewness, cutoff=self.long_cutoff,
                              seed=self.seed), self.sampling


@dataclass(frozen=True)
class MeasuredSurface:
    """A measured roughness profile (heights along the rolling direction).

    Parameters
    ----------
    heights : array (m,) — [µm]
        Equally spaced, finite, m ≥ 16 (repeated periodically where a run needs more).
    spacing : float — [mm]
        Sampling interval, > 0.
    short_cutoff : float — [mm]
        λs the profile is seen through (0: as sampled).
    rq : float or None — [µm]
        Scale the profile to this Rq; None keeps the measured Rq.
    """

    heights: ArrayLike
    spacing: float
    short_cutoff: float = 0.0
    rq: float | None = None

    def check(self) -> None:
        """Raise :class:`InputError` naming the field out of range."""
        z = real_array("heights", self.heights, unit="µm", ndim=1)
        if z.size < 16:
            raise InputError(f"heights: a measured profile needs at least 16 points, "
                             f"got {z.size}")
        real("spacing", self.spacing, unit="mm", low=0.0, low_open=True)
        real("short_cutoff", self.short_cutoff, unit="mm", low=0.0)
        if self.rq is not None:
            real("rq", self.rq, unit="µm", low=0.0, high=50.0)

    @property
    def target_rq(self) -> float:
        """The Rq the solver scales the profile to [µm]."""
        if self.rq is not None:
            return float(self.rq)
        z = np.asarray(self.heights, dtype=float)
        return float(np.sqrt(np.mean((z - z.mean()) ** 2)))

    def profile(self, length: float) -> tuple[Array, float]:
        """The measured heights, repeated to cover ``length`` [mm], and their spacing."""
        self.check()
        z = np.asarray(self.heights, dtype=float)
        reps = math.ceil(length / (z.size * self.spacing)) + 1
        return np.tile(z - z.mean(), reps), float(self.spacing)


def surface_on_grid(surface: GroundSurface | MeasuredSurface, length: float, spacing: float,
                    ) -> tuple[Array, float]:
    """A surface's heights on a solver's material grid, filtered and scaled to its Rq.

    Parameters
    ----------
    surface : GroundSurface or MeasuredSurface
    length : float — [mm]
        Material length needed.
    spacing : float — [mm]
        The solver's node spacing Δ.

    Returns
    -------
    heights : array (ceil(length/spacing) + 1,) — [µm]
        Zero mean, RMS exactly the surface's Rq.
    cutoff : float — [mm]
        The short-wave cutoff applied, max(λs, 4Δ): wavelengths the grid cannot resolve
        (four nodes per wavelength) are removed, and the rest scaled back to the Rq.

    Notes
    -----
    Filtered by :func:`gaussian_lowpass` on the profile's own sampling, then interpolated
    linearly to the grid (the filter leaves no wavelength under 4Δ: the interpolation moves
    heights by < 1 % of Rq).
    """
    rq = surface.rq if isinstance(surface, GroundSurface) else surface.target_rq
    m = math.ceil(length / spacing) + 1
    if rq == 0.0:
        return np.zeros(m), 0.0
    raw, d = surface.profile(length + 4.0 * spacing)
    cutoff = max(float(surface.short_cutoff), 4.0 * spacing)
    z = gaussian_lowpass(raw, d, cutoff)
    xs = np.arange(raw.size) * d
    return scale_to_rq(np.interp(np.arange(m) * spacing, xs, z), rq), cutoff
