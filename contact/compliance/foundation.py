"""Fillet-foundation (base) compliance of a tooth: Sainsot, Velex & Duverger (2004).

The seed (section 3.2, p. 78) adds "base rotation and base translation effects …
by using an approximate interpolation method similar to the one developed for
helical gears by Stegemiller [3.9]". Stegemiller's interpolation tables are not
published with the seed and cannot be reproduced, so this module uses the
published closed-form alternative (NOTES.md): the body (fillet-foundation)
deflection of Sainsot, Velex & Duverger, J. Mech. Des. 126 (2004) 748–752,
fitted to Muskhelishvili's 2-D solution for a tooth on an elastic annulus::

    δ_f = (F cos²α_m / (E b)) [L* (u_f/S_f)² + M* (u_f/S_f) + P* (1 + Q* tan²α_m)]

    X* = A_i/θ_f² + B_i h_f² + C_i h_f/θ_f + D_i/θ_f + E_i h_f + F_i,  X ∈ {L, M, P, Q}

F the load [N], α_m the angle of the load line to the normal of the tooth
centreline [rad], b the face width [mm], E [MPa], u_f [mm] the distance from the
root circle to where the load line crosses the tooth centreline, S_f [mm] the
tooth thickness at the root circle, h_f = r_f / r_int (root radius over the inner
radius of the gear body: bore or rim), θ_f [rad] half the angle the tooth root
subtends at the gear centre; S_f = 2 r_f θ_f. The formula is plane (2-D, per unit
face width with the load spread over the whole face width): for a hypoid member
use the virtual cylindrical (Tredgold) gear of the mid-face section. Units mm,
N, MPa → mm.

The coefficient table is Sainsot et al.'s as reproduced by the literature that
uses it (e.g. Chaari, Fakhfakh & Haddar, Eur. J. Mech. A/Solids 28 (2009) 461;
the open-source rotordynamics package ROSS, ``GearElementTVMS``, has the same
numbers and takes θ_f in radians, S_f = 2 r_f θ_f, as we do).

Coupling of loads on one tooth
------------------------------
Sainsot's formula is the *diagonal* of a reciprocal (Maxwell–Betti) influence:
the root section's generalised displacements (rotation, tangential and radial
translation) respond linearly to its generalised forces (moment F cos α_m u_f,
shear F cos α_m, normal F sin α_m). Written as a quadratic form in
v_i = cos α_i (u_i/S_f, 1, tan α_i)::

    δ_f,i = F v_iᵀ G v_i / (E b),   G = [[L*, M*/2, 0], [M*/2, P*, 0], [0, 0, P* Q*]]

the deflection along load i due to a unit load j on the same tooth is the
bilinear form C_ij = v_iᵀ G v_j / (E b): a symmetric matrix of rank ≤ 3 whose
diagonal is exactly Sainsot's formula. It is positive semi-definite when
L* P* ≥ (M*/2)² and P* Q* ≥ 0, which holds wherever the coefficients are held to the
fit's range (below). Loads on different teeth do not couple through this term. The
base deflects uniformly along the face width (Sainsot's 2-D hypothesis): a load near
the toe moves the heel as much as itself.

The fit's range, and the coefficients beyond it
----------------------------------------------
The fit is a polynomial in 1/θ_f and h_f; outside its data it is not a model of a
gear body. The coefficient values it was fitted over are published as ranges
(L* 6.82–6.94, M* 1.08–3.29, P* 2.56–13.47, Q* 0.141–0.62; the bounds the
rotordynamics package ROSS warns outside): L* reaches its lower bound 6.82 at
θ_f = 0.0119–0.0133 rad for every h_f in 1.4–7, M* its upper bound 3.29 at θ_f 0.0120
(h_f 2), and P*'s upper bound 13.47 is the fit at h_f = 7.0. Below θ_f ≈ 0.012 the
A/θ_f² terms take over: P* turns down (its maximum is at θ_f = −2A_P/D_P = 0.019),
becomes negative at θ_f ≈ 0.007 (h_f 2: −0.54), and the coupling G goes indefinite
(h_f 2: eigenvalues −3.09 … at θ_f 0.007), so the base term *lowered* the tooth's
compliance of a large gear (virtual tooth count above ~250: an industrial 19×62 gear's
θ_f is 0.0071, a 5×43 hypoid gear's 0.0058).

A large gear's body tends to a half-plane as θ_f → 0 (tooth small against the body):
the root section's rotation under a moment stays finite (L*, M* tend to constants), and
its translations grow only as the logarithm of body depth over tooth width, by
k = 2(1 − ν²)/π = 0.579 per e-fold of 1/θ_f (Flamant, plane strain, ν = 0.3) — the fit's
own slope dP*/d ln(1/θ_f) is 0.50–0.70 over θ_f 0.025–0.08, in agreement, and turns
negative below 0.019. A plane-strain FE of the annulus, fixed at its bore and loaded on
the root arc (tests/test_foundation_fe.py), gives P* 2.95 and P*Q* 1.59 at h_f 2,
θ_f 0.05 (the fit: 3.11, 1.70), and below the range keeps growing by k: P* 3.77, 4.09,
4.28 at θ_f 0.012, 0.007, 0.005 (the bare fit: 3.15, −0.54, −7.47). So below the range
(:data:`SAINSOT_THETA_F_MIN`) L* and M* are those at the bound and the translations
continue as the half-plane's: P* = P*_b + k ℓ and P*Q* = (P*Q*)_b + k ℓ, ℓ = ln(θ_b/θ_f)
(:data:`SAINSOT_LOG_SLOPE`); above h_f 7 (:data:`SAINSOT_H_F_MAX`) the coefficients are
those at h_f 7 (the fit's B h_f² is the body's wind-up to a bore that shrinks to a point;
a member that small-bored sits on its shaft). The geometry, S_f = 2 r_f θ_f, stays the
member's own. The coupling is then positive definite for every h_f > 1 and θ_f in
(0, π/2), continuous across the bound, and its P* at θ_f 0.007 is FE/1.18 (at the bound
FE/1.20: the fit's own offset there, carried on).

Public API
----------
SAINSOT_COEFFICIENTS      the coefficient table (A … F for L*, M*, P*, Q*)
SAINSOT_THETA_F_MIN       the fit's lower bound of θ_f [rad]; below it L*, M* held and the
                          translations continued as a half-plane's
SAINSOT_LOG_SLOPE         that continuation's growth per e-fold of 1/θ_f [1]
SAINSOT_H_F_MAX           the fit's upper bound of h_f [1], coefficients held above it
ToothFoundation           frozen dataclass: r_f, r_int, θ_f, b, E
sainsot_coefficients      L*, M*, P*, Q* for given h_f and θ_f
foundation_compliance     δ_f / F [mm/N] at each load (Sainsot's formula)
foundation_matrix         N×N coupling matrix [mm/N] of loads on one tooth
load_line_height          u_f [mm] from the contact height, thickness and α_m
load_angle_from_normals   α_m [rad] from outward flank normals (shell local frame)

References
----------
Sainsot, P., Velex, P., Duverger, O. (2004). Contribution of gear body to tooth
deflections — a new bidimensional analytical formula. ASME J. Mech. Des. 126(4),
748–752. doi:10.1115/1.1758252
Stegemiller, M. E. (1986). The effects of base flexibility on thin rimmed gear
tooth deflection (seed ref. [3.9], not reproduced).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from geometry.core.errors import InputError
from geometry.core.validation import broadcast, real, real_array

__all__ = [
    "SAINSOT_COEFFICIENTS",
    "SAINSOT_H_F_MAX",
    "SAINSOT_LOG_SLOPE",
    "SAINSOT_THETA_F_MIN",
    "ToothFoundation",
    "foundation_compliance",
    "foundation_matrices",
    "foundation_matrix",
    "load_angle_from_normals",
    "load_line_height",
    "sainsot_coefficients",
]

log = logging.getLogger(__name__)

#: Sainsot, Velex & Duverger (2004), coefficient table: (A, B, C, D, E, F) of
#: X* = A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F, θ_f in rad.
SAINSOT_COEFFICIENTS: dict[str, tuple[float, float, float, float, float, float]] = {
    "L": (-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045),
    "M": (60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086),
    "P": (-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236),
    "Q": (-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904),
}

#: [rad] Lower bound of θ_f of Sainsot's fit: L* leaves its published range (≥ 6.82) at
#: θ_f 0.0119–0.0133 for h_f 1.4–7, M* (≤ 3.29) at 0.0120 for h_f 2 (module docstring).
#: Below it the coefficients are evaluated at the bound.
SAINSOT_THETA_F_MIN: float = 0.012

#: [1] k = 2(1 − ν²)/π at ν = 0.3: the growth of the translational coefficients P* and
#: P* Q* per e-fold of 1/θ_f below :data:`SAINSOT_THETA_F_MIN` (Flamant's half-plane,
#: plane strain; module docstring)
SAINSOT_LOG_SLOPE: float = 2.0 * (1.0 - 0.3**2) / math.pi

#: [1] Upper bound of h_f of Sainsot's fit: P*'s published maximum 13.47 is the fit at
#: h_f = 7.0 (θ_f 0.019). Above it the coefficients are evaluated at the bound.
SAINSOT_H_F_MAX: float = 7.0


def _pos(name: str, value: float, unit: str, upper: float | None = None) -> float:
    """value in (0, upper) [unit] (upper excluded), by :func:`geometry.core.validation.real`."""
    return real(name, value, unit=unit, low=0.0, high=upper, low_open=True, high_open=True)


@dataclass(frozen=True)
class ToothFoundation:
    """The gear body under one tooth, as Sainsot et al. (2004) parameterise it.

    Parameters
    ----------
    root_radius : float — [mm] r_f, root-circle radius (of the virtual spur gear
        for a bevel/hypoid member)
    inner_radius : float — [mm] r_int, inner radius of the body (bore or rim),
        0 < r_int < r_f
    root_half_angle : float — [rad] θ_f, half the angle the tooth root subtends
        at the gear centre, in (0, π/2)
    face_width : float — [mm] b
    youngs_modulus : float — [MPa] E

    Raises
    ------
    InputError
        A field out of its range (the message names it and the range).
    """

    root_radius: float
    inner_radius: float
    root_half_angle: float
    face_width: float
    youngs_modulus: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "root_radius", _pos("root_radius", self.root_radius, "mm"))
        object.__setattr__(
            self,
            "inner_radius",
            _pos("inner_radius", self.inner_radius, "mm", upper=self.root_radius),
        )
        object.__setattr__(
            self,
            "root_half_angle",
            _pos("root_half_angle", self.root_half_angle, "rad", upper=0.5 * math.pi),
        )
        object.__setattr__(self, "face_width", _pos("face_width", self.face_width, "mm"))
        object.__setattr__(
            self, "youngs_modulus", _pos("youngs_modulus", self.youngs_modulus, "MPa")
        )

    @property
    def radius_ratio(self) -> float:
        """h_f = r_f / r_int [1]."""
        return self.root_radius / self.inner_radius

    @property
    def root_thickness(self) -> float:
        """S_f = 2 r_f θ_f [mm], tooth thickness (arc) at the root circle."""
        return 2.0 * self.root_radius * self.root_half_angle


def sainsot_coefficients(
    radius_ratio: float, root_half_angle: float, *, extrapolate: bool = False
) -> dict[str, float]:
    """L*, M*, P*, Q* of Sainsot et al. (2004) [1].

    Parameters
    ----------
    radius_ratio : float — [1] h_f = r_f / r_int > 1
    root_half_angle : float — [rad] θ_f in (0, π/2)
    extrapolate : bool — False (the model): inside the fit's range the polynomial;
        above h_f :data:`SAINSOT_H_F_MAX` the values at it; below θ_f
        :data:`SAINSOT_THETA_F_MIN` = θ_b, L* and M* at θ_b and P* = P*_b + k ℓ, P* Q* =
        (P* Q*)_b + k ℓ, ℓ = ln(θ_b/θ_f), k = :data:`SAINSOT_LOG_SLOPE` (module
        docstring); True: the bare polynomial at (h_f, θ_f), which goes indefinite below
        θ_f ≈ 0.01 (for mapping the fit, not for use)

    Returns
    -------
    dict — keys "L", "M", "P", "Q" [1]

    Raises
    ------
    InputError
        h_f ≤ 1 or θ_f out of range.

    Notes
    -----
    Sainsot, Velex & Duverger (2004), polynomial fits of the coefficients:
    X* = A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F. Held at the fit's bounds
    outside its range (module docstring: the half-plane limit of a large gear's body).
    """
    h = _pos("radius_ratio", radius_ratio, "1")
    if h <= 1.0:
        raise InputError(f"radius_ratio: must be > 1 (r_f > r_int) [1], got {radius_ratio!r}")
    th = _pos("root_half_angle", root_half_angle, "rad", upper=0.5 * math.pi)
    grow = 0.0
    if not extrapolate:
        h = min(h, SAINSOT_H_F_MAX)
        if th < SAINSOT_THETA_F_MIN:
            grow = SAINSOT_LOG_SLOPE * math.log(SAINSOT_THETA_F_MIN / th)
            th = SAINSOT_THETA_F_MIN
    out = {
        k: a / th**2 + b * h**2 + c * h / th + d / th + e * h + f
        for k, (a, b, c, d, e, f) in SAINSOT_COEFFICIENTS.items()
    }
    if grow > 0.0:  # the translations of a half-plane below the range (module docstring)
        p = out["P"] + grow
        out["Q"] = (out["P"] * out["Q"] + grow) / p
        out["P"] = p
    return out


def _load_vectors(
    foundation: ToothFoundation, load_height: np.ndarray, load_angle: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    u = np.atleast_1d(real_array("load_height", load_height, unit="mm"))
    a = np.atleast_1d(real_array("load_angle", load_angle, unit="rad", low=-0.5 * math.pi,
                                 high=0.5 * math.pi, low_open=True, high_open=True))
    u, a = broadcast(load_height=u, load_angle=a)
    c = sainsot_coefficients(foundation.radius_ratio, foundation.root_half_angle)
    g = np.array(
        [[c["L"], 0.5 * c["M"], 0.0], [0.5 * c["M"], c["P"], 0.0], [0.0, 0.0, c["P"] * c["Q"]]]
    )
    v = np.cos(a)[:, None] * np.column_stack(
        [u / foundation.root_thickness, np.ones_like(u), np.tan(a)]
    )
    return v, g


def foundation_compliance(
    foundation: ToothFoundation,
    load_height: np.ndarray | float,
    load_angle: np.ndarray | float,
) -> np.ndarray:
    """Fillet-foundation deflection per unit load along the load line [mm/N].

    Parameters
    ----------
    foundation : ToothFoundation
    load_height : float or ndarray (N,) — [mm] u_f, root circle to the point where
        the load line crosses the tooth centreline (:func:`load_line_height`)
    load_angle : float or ndarray (N,) — [rad] α_m, load line to the normal of the
        tooth centreline, positive when the load pushes towards the root

    Returns
    -------
    ndarray (N,) — [mm/N] δ_f / F =
        cos²α_m/(E b) [L*(u_f/S_f)² + M*(u_f/S_f) + P*(1 + Q* tan²α_m)]

    Raises
    ------
    InputError
        Non-finite inputs, |α_m| ≥ π/2.

    Notes
    -----
    Sainsot, Velex & Duverger (2004), body-deflection formula (module docstring). Replaces
    the seed's Stegemiller interpolation, which is not reproducible.
    """
    v, g = _load_vectors(foundation, load_height, load_angle)
    eb = foundation.youngs_modulus * foundation.face_width
    return np.einsum("ni,ij,nj->n", v, g, v) / eb


def foundation_matrix(
    foundation: ToothFoundation,
    load_height: np.ndarray,
    load_angle: np.ndarray,
) -> np.ndarray:
    """Base-compliance coupling matrix of N loads on the same tooth [mm/N].

    Parameters
    ----------
    foundation : ToothFoundation
    load_height : ndarray (N,) — [mm] u_f of each load
    load_angle : ndarray (N,) — [rad] α_m of each load

    Returns
    -------
    ndarray (N, N) — [mm/N] C_ij = v_iᵀ G v_j / (E b), symmetric, rank ≤ 3,
        diagonal equal to :func:`foundation_compliance`

    Raises
    ------
    InputError
        As :func:`foundation_compliance`.

    Notes
    -----
    The bilinear form of Sainsot's quadratic form (module docstring): the root
    section's rotation (L*), rotation–translation coupling (M*), tangential (P*)
    and radial (P* Q*) translations. Our reading, not stated by Sainsot et al.,
    who give the diagonal only. G is positive definite: outside the fit's range its
    coefficients are the half-plane continuation of :func:`sainsot_coefficients`.
    """
    v, g = _load_vectors(foundation, load_height, load_angle)
    eb = foundation.youngs_modulus * foundation.face_width
    return (v @ g @ v.T) / eb


def foundation_matrices(
    foundation: ToothFoundation,
    load_height: np.ndarray,
    load_angle: np.ndarray,
    blocks: list[np.ndarray],
) -> list[np.ndarray]:
    """:func:`foundation_matrix` of several teeth's loads at once, one matrix per block.

    Parameters
    ----------
    foundation : ToothFoundation
    load_height : ndarray (N,) — [mm] u_f of every load (all teeth, all roll positions)
    load_angle : ndarray (N,) — [rad] α_m of every load
    blocks : list of int ndarray or slice
        The loads on one tooth at one roll position each (indices into the N loads, or
        their slice where they are consecutive: a view of the load vectors, not a copy).

    Returns
    -------
    list of ndarray (n_b, n_b) — [mm/N]
        C_b = v_iᵀ G v_j / (E b) over each block's loads: each equal to
        :func:`foundation_matrix` of the block's loads (the load vectors v_i, which depend
        on their own load only, computed once for all).

    Raises
    ------
    InputError
        As :func:`foundation_compliance`.

    Notes
    -----
    Sainsot, Velex & Duverger (2004), as :func:`foundation_matrix`; the batched form serves
    the LTCA's compliance of all roll positions, assembled in one call
    (:func:`contact.compliance.mesh.mesh_compliance_many`).
    """
    v, g = _load_vectors(foundation, load_height, load_angle)
    eb = foundation.youngs_modulus * foundation.face_width
    out = []
    for idx in blocks:
        vb = v[idx]
        out.append((vb @ g @ vb.T) / eb)
    return out


def load_line_height(
    height: np.ndarray | float,
    thickness: np.ndarray | float,
    load_angle: np.ndarray | float,
) -> np.ndarray:
    """u_f: where the load line crosses the tooth centreline, from the root [mm].

    Parameters
    ----------
    height : float or ndarray — [mm] contact-point height above the root circle
    thickness : float or ndarray — [mm] tooth thickness at that height
    load_angle : float or ndarray — [rad] α_m (positive towards the root)

    Returns
    -------
    ndarray — [mm] u_f = height − (thickness/2) tan α_m

    Raises
    ------
    InputError
        Non-finite inputs or negative thickness.
    """
    x = real_array("height", height, unit="mm")
    t = real_array("thickness", thickness, unit="mm", low=0.0)
    a = real_array("load_angle", load_angle, unit="rad")
    return x - 0.5 * t * np.tan(a)


def load_angle_from_normals(normals: np.ndarray) -> np.ndarray:
    """α_m [rad] of flank loads from outward unit flank normals.

    Parameters
    ----------
    normals : ndarray (N, 3) — [1] outward flank normals on the shell's local frame
        (e_x along the height towards the tip, e_θ, e_z); the load acts along −n

    Returns
    -------
    ndarray (N,) — [rad] α_m = atan2(n_x, |n_z|): positive when the load has a
        component towards the root (flank tilted towards the tip, the usual case)

    Raises
    ------
    InputError
        Wrong shape or non-finite normals, or n_z = 0.
    """
    n = np.asarray(normals, dtype=float)
    if n.ndim != 2 or n.shape[1] != 3 or not np.all(np.isfinite(n)):
        raise InputError(f"normals: must be a finite (N, 3) array [1], got shape {n.shape}")
    if np.any(n[:, 2] == 0.0):
        raise InputError("normals: must have a non-zero e_z component [1], got "
                         f"{int(np.count_nonzero(n[:, 2] == 0.0))} with n_z = 0")
    return np.arctan2(n[:, 0], np.abs(n[:, 2]))
