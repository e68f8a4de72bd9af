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
L* P* ≥ (M*/2)² and P* Q* ≥ 0 (checked). Loads on different teeth do not couple
through this term. The base deflects uniformly along the face width (Sainsot's
2-D hypothesis): a load near the toe moves the heel as much as itself.

Public API
----------
SAINSOT_COEFFICIENTS      the coefficient table (A … F for L*, M*, P*, Q*)
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

from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.validation import broadcast, real, real_array

__all__ = [
    "SAINSOT_COEFFICIENTS",
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


def sainsot_coefficients(radius_ratio: float, root_half_angle: float) -> dict[str, float]:
    """L*, M*, P*, Q* of Sainsot et al. (2004) [1].

    Parameters
    ----------
    radius_ratio : float — [1] h_f = r_f / r_int > 1
    root_half_angle : float — [rad] θ_f in (0, π/2)

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
    X* = A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F.
    """
    h = _pos("radius_ratio", radius_ratio, "1")
    if h <= 1.0:
        raise InputError(f"radius_ratio: must be > 1 (r_f > r_int) [1], got {radius_ratio!r}")
    th = _pos("root_half_angle", root_half_angle, "rad", upper=0.5 * math.pi)
    return {
        k: a / th**2 + b * h**2 + c * h / th + d / th + e * h + f
        for k, (a, b, c, d, e, f) in SAINSOT_COEFFICIENTS.items()
    }


@memoised(maxsize=64)
def _warn_indefinite(radius_ratio: float, root_half_angle: float) -> None:
    """Say once per process and foundation (h_f, θ_f) that Sainsot's coefficients give an
    indefinite base coupling: a development builds the same tooth's compliance for each of
    its dozens of trials, and a line per trial buried its progress lines. A memo: after
    ``clear_caches`` it is said again."""
    log.warning(
        "Sainsot coefficients give an indefinite base coupling (h_f=%.3g, theta_f=%.3g): "
        "the fit (Sainsot et al. 2004) is extrapolated there; said once per tooth",
        radius_ratio, root_half_angle)


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
    if g[0, 0] * g[1, 1] < g[0, 1] ** 2 or g[2, 2] < 0.0:
        _warn_indefinite(round(foundation.radius_ratio, 3), round(foundation.root_half_angle, 5))
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
    who give the diagonal only. If G is not positive semi-definite for the
    given h_f, θ_f (outside the fit's range), a warning is logged.
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
    blocks : list of int ndarray
        The loads on one tooth at one roll position each (indices into the N loads).

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
