"""Summary statistics of a transmission-error curve over whole mesh cycles (seed Table 3.1, 4.2).

The seed characterises loaded and unloaded TE by its mean, peak-to-peak value,
the amplitudes of the first three mesh harmonics and an "RMS" value. Table 3.1's
numbers show what that RMS is: at 50 N·m, p-p 12.8 µrad with a first-harmonic
amplitude 6.3 (p-p of a pure sine is 2A), and RMS 6.3 = √(6.3² + 0.6² + 0.1²);
at 500 N·m, √(9.9² + 2.3² + 0.5²) = 10.2 against the printed 10.1. So the seed's
RMS is the root-sum-square of the harmonic (peak) amplitudes, √2 times the RMS of
the fluctuation about the mean. Both are reported here, under distinct names:
``rms`` (the statistical RMS of TE − mean) and ``harmonic_rss`` (the seed's value).
"""

from __future__ import annotations

import math

import numpy as np

from geometry.core.errors import InputError

__all__ = ["mesh_harmonics", "transmission_error_summary"]


def _check(roll, te, mesh_period: float) -> tuple[np.ndarray, np.ndarray, float]:
    phi = np.asarray(roll, float)
    y = np.asarray(te, float)
    if phi.ndim != 1 or y.shape != phi.shape:
        raise InputError(f"roll, te: must be 1-D of equal length, got {phi.shape} and {y.shape}")
    if phi.size < 4:
        raise InputError(f"roll: needs at least 4 positions, got {phi.size}")
    if not (np.all(np.isfinite(phi)) and np.all(np.isfinite(y))):
        raise InputError("roll, te: must be finite (a failed roll position must be removed)")
    if not (math.isfinite(mesh_period) and mesh_period > 0):
        raise InputError(f"mesh_period: must be finite and > 0 [rad], got {mesh_period}")
    step = np.diff(phi)
    if np.any(step <= 0):
        raise InputError("roll: must be strictly increasing")
    span = phi[-1] - phi[0] + float(np.median(step))
    cycles = span / mesh_period
    if cycles < 1 - 1e-6 or abs(cycles - round(cycles)) > 1e-3 * max(1.0, cycles):
        raise InputError(
            f"roll: must cover a whole number of mesh cycles (uniform samples without the "
            f"repeated end point); covers {cycles:.4f} mesh periods"
        )
    return phi, y, float(round(cycles))


def mesh_harmonics(roll, te, mesh_period: float, n_harmonics: int = 3) -> np.ndarray:
    """Peak amplitudes of the first mesh harmonics of a TE curve.

    A least-squares Fourier fit in the mesh frequency over whole mesh cycles,
    te ≈ c₀ + Σₖ (aₖ cos 2πkφ/T + bₖ sin 2πkφ/T), which on uniform samples equals
    the discrete Fourier transform; Aₖ = √(aₖ² + bₖ²).

    Parameters
    ----------
    roll : array (K,) — [rad]
        Pinion roll angles, uniform, covering whole mesh cycles, end point excluded.
    te : array (K,) — any unit (e.g. [µrad])
    mesh_period : float — [rad]
        One mesh cycle of pinion roll, 2π/z_p.
    n_harmonics : int
        Number of harmonics returned (≥ 1).

    Returns
    -------
    ndarray (n_harmonics,)
        Peak amplitudes in the unit of ``te``.

    Raises
    ------
    InputError
        Shapes, non-finite values, non-increasing roll, or not whole mesh cycles.

    Notes
    -----
    Source: the first mesh harmonics of the TE as the seed reports them (Table 3.1, 4.2), by
    a discrete Fourier series over whole mesh cycles; module docstring.
    """
    phi, y, cycles = _check(roll, te, mesh_period)
    if not (isinstance(n_harmonics, int) and n_harmonics >= 1):
        raise InputError(f"n_harmonics: must be an integer ≥ 1, got {n_harmonics!r}")
    # fit every resolvable mesh harmonic so the low ones are not aliased by the rest
    n_fit = max(n_harmonics, int((phi.size // 2 - 1) / cycles))
    if 2 * n_fit + 1 > phi.size:
        raise InputError(
            f"roll: {phi.size} positions cannot resolve {n_harmonics} mesh harmonics "
            f"over {cycles:.0f} cycle(s)"
        )
    w = 2 * np.pi * (phi - phi[0]) / mesh_period
    k = np.arange(1, n_fit + 1)
    A = np.column_stack([np.ones_like(w), np.cos(np.outer(w, k)), np.sin(np.outer(w, k))])
    coef = np.linalg.lstsq(A, y, rcond=None)[0]
    amp = np.hypot(coef[1 : n_fit + 1], coef[n_fit + 1 :])
    return amp[:n_harmonics]


def transmission_error_summary(
    roll, te, mesh_period: float, n_harmonics: int = 3
) -> dict[str, float | np.ndarray]:
    """Mean, peak-to-peak, mesh-harmonic amplitudes and RMS of a TE curve (seed Table 3.1).

    Parameters
    ----------
    roll, te, mesh_period, n_harmonics
        As :func:`mesh_harmonics`.

    Returns
    -------
    dict
        ``mean``, ``peak_to_peak``, ``harmonics`` (n_harmonics,), ``rms`` (RMS of
        te − mean), ``harmonic_rss`` (√Σ Aₖ² over the returned harmonics: the seed's
        "RMS"), all in the unit of ``te``.
    """
    phi, y, _ = _check(roll, te, mesh_period)
    amp = mesh_harmonics(phi, y, mesh_period, n_harmonics)
    mean = float(np.mean(y))
    return {
        "mean": mean,
        "peak_to_peak": float(np.ptp(y)),
        "harmonics": amp,
        "rms": float(np.sqrt(np.mean((y - mean) ** 2))),
        "harmonic_rss": float(np.sqrt(np.sum(amp**2))),
    }
