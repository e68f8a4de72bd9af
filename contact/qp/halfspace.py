"""Elastic half-space influence coefficients and Hertz's solutions: the QP's analytical check.

Discretising a Hertz contact on an elastic half-space gives a contact problem of
exactly the LTCA form (compliance, initial separation, one rigid-body approach
as the multiplier of the load equilibrium), with a closed-form answer. These
functions build such problems; the tests and ``ltca compare-solvers`` use them.

References
----------
Love, A. E. H. (1929). The stress produced in a semi-infinite solid by pressure on
part of the boundary. Phil. Trans. R. Soc. A 228, 377–420.
Johnson, K. L. (1985). *Contact Mechanics*. Cambridge University Press:
Eq. (3.25) (uniform pressure on a rectangle), Eq. (2.25) (uniform pressure on a
strip, plane strain), Eq. (4.22)–(4.23) (Hertz, spheres), Eq. (4.43)–(4.45)
(Hertz, cylinders).
"""

from __future__ import annotations

import math

import numpy as np

from geometry.core.errors import InputError
from geometry.core.hertz import contact_modulus, hertz_line_contact  # the one E* and line contact
from geometry.core.validation import positive

__all__ = [
    "contact_modulus",
    "hertz_line",
    "hertz_point",
    "rectangle_influence",
    "strip_influence",
]


def rectangle_influence(
    x: np.ndarray, y: np.ndarray, half_x: float, half_y: float, modulus: float
) -> np.ndarray:
    """Surface normal displacement at the cell centres of a uniform grid under unit cell forces.

    Love's closed form for a uniform pressure on a rectangle of half-sides a, b
    (Johnson Eq. 3.25), evaluated between every pair of cell centres, divided by
    the cell area 4ab so that column j is the displacement due to a unit force on
    cell j.

    Parameters
    ----------
    x, y : array (N,) — [mm]
        Cell centres; cells are rectangles of half-sides ``half_x``, ``half_y``.
    half_x, half_y : float — [mm]
    modulus : float — [MPa]
        Contact modulus E* of the pair (:func:`contact_modulus`).

    Returns
    -------
    ndarray (N, N) — [mm/N]
        Symmetric influence (compliance) matrix.

    Raises
    ------
    InputError
        A half-side or the modulus not finite and > 0, or centres off a regular grid of
        the cell size.

    Notes
    -----
    Evaluated at cell centres of a regular grid, x − x_j ± a is never zero, so the
    logarithms are regular.
    """
    a = positive("half_x", half_x, "mm")
    b = positive("half_y", half_y, "mm")
    E = positive("modulus", modulus, "MPa")
    X = np.asarray(x, float)[:, None] - np.asarray(x, float)[None, :]
    Y = np.asarray(y, float)[:, None] - np.asarray(y, float)[None, :]

    def term(u, v):  # u ln[(v + √(u²+v²))] pieces combined below
        return np.sqrt(u * u + v * v)

    xp, xm, yp, ym = X + a, X - a, Y + b, Y - b
    r_pp, r_pm, r_mp, r_mm = term(xp, yp), term(xp, ym), term(xm, yp), term(xm, ym)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = (
            xp * np.log((yp + r_pp) / (ym + r_pm))
            + yp * np.log((xp + r_pp) / (xm + r_mp))
            + xm * np.log((ym + r_mm) / (yp + r_mp))
            + ym * np.log((xm + r_mm) / (xp + r_pm))
        )
    if not np.all(np.isfinite(u)):
        raise InputError("x, y: cell centres must lie on a regular grid of the given cell size")
    return u / (math.pi * E) / (4 * a * b)


def strip_influence(x: np.ndarray, half_width: float, modulus: float, datum: float) -> np.ndarray:
    """Plane-strain surface displacement at strip centres under unit line loads per strip.

    For a uniform pressure p on the strip |s − x_j| ≤ c of a half-plane, the
    surface displacement relative to a datum at distance d is
    u(x) = (2p/(π E*)) ∫ ln(d/|x − s|) ds (Johnson Eq. 2.25, two bodies through E*);
    with F(t) = t ln(d/|t|) + t the integral is F(x − x_j + c) − F(x − x_j − c).
    Column j is divided by the strip width 2c: unit force per unit length on strip j.

    Parameters
    ----------
    x : array (N,) — [mm]
        Strip centres, strips of half-width ``half_width``.
    half_width : float — [mm]
    modulus : float — [MPa]
        Contact modulus E*.
    datum : float — [mm]
        Distance d of the displacement datum; several times the loaded width keeps
        the kernel positive definite.

    Returns
    -------
    ndarray (N, N) — [mm per (N/mm)]

    Raises
    ------
    InputError
        ``half_width``, ``modulus`` or ``datum`` not finite and > 0.
    """
    c = positive("half_width", half_width, "mm")
    E = positive("modulus", modulus, "MPa")
    d = positive("datum", datum, "mm")
    t = np.asarray(x, float)[:, None] - np.asarray(x, float)[None, :]

    def F(u):
        with np.errstate(divide="ignore", invalid="ignore"):
            out = u * np.log(d / np.abs(u)) + u
        return np.where(u == 0.0, 0.0, out)

    return (2.0 / (math.pi * E)) * (F(t + c) - F(t - c)) / (2 * c)


def hertz_point(load: float, radius: float, modulus: float) -> dict[str, float]:
    """Hertz contact of a sphere on a flat (Johnson Eq. 4.22–4.23).

    Parameters
    ----------
    load : float — [N]
    radius : float — [mm]
        Relative radius of curvature.
    modulus : float — [MPa]
        Contact modulus E*.

    Returns
    -------
    dict: ``radius`` a [mm] = (3PR/(4E*))^(1/3), ``peak_pressure`` p₀ [MPa] = 3P/(2πa²),
    ``approach`` δ [mm] = a²/R.

    Raises
    ------
    InputError
        An input not finite and > 0 (the message names it).
    """
    P = positive("load", load, "N")
    R = positive("radius", radius, "mm")
    E = positive("modulus", modulus, "MPa")
    a = (3 * P * R / (4 * E)) ** (1 / 3)
    return {"radius": a, "peak_pressure": 3 * P / (2 * math.pi * a * a), "approach": a * a / R}


def hertz_line(
    load_per_length: float, radius: float, modulus: float, datum: float
) -> dict[str, float]:
    """Hertz contact of a cylinder on a flat, plane strain (Johnson Eq. 4.43–4.45).

    Parameters
    ----------
    load_per_length : float — [N/mm]
    radius : float — [mm]
    modulus : float — [MPa]
        Contact modulus E*.
    datum : float — [mm]
        Distance of the displacement datum, as in :func:`strip_influence`.

    Returns
    -------
    dict: ``half_width`` b [mm] = √(4P′R/(πE*)), ``peak_pressure`` p₀ [MPa] = 2P′/(πb)
    (both from :func:`geometry.core.hertz.hertz_line_contact`), ``approach`` δ [mm] =
    (2P′/(πE*)) (ln(2d/b) + ½), the displacement at the centre relative to the datum,
    from ∫₋₁¹ √(1−t²) ln|t| dt = −(π/2)(ln 2 + ½).

    Raises
    ------
    InputError
        An input not finite and > 0 (the message names it).
    """
    P = positive("load_per_length", load_per_length, "N/mm")
    R = positive("radius", radius, "mm")
    E = positive("modulus", modulus, "MPa")
    d = positive("datum", datum, "mm")
    hz = hertz_line_contact(P, R, E)
    b = float(hz.half_width)
    return {
        "half_width": b,
        "peak_pressure": float(hz.peak_pressure),
        "approach": 2 * P / (math.pi * E) * (math.log(2 * d / b) + 0.5),
    }
