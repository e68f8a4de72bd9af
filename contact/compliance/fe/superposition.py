"""Superposition of FE influence coefficients: compliance and fillet stress of contact loads.

The LTCA gives, at each roll position, contact segments on the flanks with their normal
forces. With a member's influence coefficients (:func:`contact.compliance.fe.influence.
influence_coefficients`) these functions give

* the **compliance matrix** C (N × N) [mm/N] between the segments' points on the member,
  for the LTCA's compatibility C F + s − R Θ = Y (seed Eq. 3.12–3.14), and
* the **fillet stress** along the face width of every tooth the loads reach, for the
  segment forces [N].

A point p of the working flank of tooth k (k pitches from the reference tooth) with a
normal force F acts as the hat loads of the grid with the bilinear weights N_a(p) (the
consistent reading of the hat-load coefficients, :mod:`~contact.compliance.fe.influence`),
so by linearity

    C_ij = Σ_a Σ_b N_a(p_i) N_b(p_j) G[a, k_j − k_i, b],
    σ(tooth k + d, fillet point) = Σ_i F_i Σ_a N_a(p_i) S[a, d, fillet point],

with G and S the coefficients of loads on the model's middle tooth, moved by whole pitches
(every tooth of the member is the same). Offsets beyond the modelled neighbours give zero.
The blocks between teeth are averaged with their transposes (Maxwell–Betti holds exactly
for the middle tooth's own block; the model's loads on a neighbour are read from its loads
on the middle tooth, which the finite sector makes slightly unsymmetric).

Public names
------------
FlankPoints                 where points lie on a member's working flank
locate_flank_points         find it (fractions, tooth, distance off the flank)
fe_compliance_matrix        C between points [mm/N]
fillet_stress               fillet stress of point forces, a Dataset [MPa]
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import xarray as xr
from scipy.interpolate import RectBivariateSpline

from contact.compliance.fe.influence import hat_weights, principal_stresses
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.core.validation import real_array
from geometry.machine.flank import projection_fractions

__all__ = ["FlankPoints", "fe_compliance_matrix", "fillet_stress", "locate_flank_points"]

#: [1] points may lie this far (in face or profile fractions) outside the load grid (a
#: contact curve's end segment); they take the grid's boundary weights
GRID_TOLERANCE = 0.05
#: [mm] largest distance of a point from the working flank of its tooth
FLANK_TOLERANCE = 0.1


class FlankPoints(NamedTuple):
    """Points on a member's working flank.

    u, v : (N,) [1] projection-plane fractions; tooth : (N,) [1] offset of the point's tooth
    from the reference (loaded) tooth; distance : (N,) [mm] distance from the working flank
    along the circumference; weights : scipy.sparse (N, nu nv) bilinear hat weights.
    """

    u: np.ndarray
    v: np.ndarray
    tooth: np.ndarray
    distance: np.ndarray
    weights: object


def _grid(coefficients: xr.Dataset):
    return coefficients.variables["u"].values, coefficients.variables["v"].values


def locate_flank_points(coefficients: xr.Dataset, points, *,
                        strict: bool = True) -> FlankPoints:
    """Where points of the member frame lie on the working flank of the member's teeth.

    Parameters
    ----------
    coefficients : xarray.Dataset — a member's influence coefficients
    points : array_like (N, 3) — [mm] points in the member frame, on the working flank of
        any tooth
    strict : bool — True (default): refuse points off the grid or the flank (below);
        False: locate them anyway (fractions clipped to the grid for the weights, the
        tooth and distance as found), e.g. to tell the tooth of segments that are not
        loaded

    Returns
    -------
    FlankPoints

    Raises
    ------
    InputError
        ``points`` not (N, 3) and finite; a point more than :data:`GRID_TOLERANCE` outside
        the load grid, or more than :data:`FLANK_TOLERANCE` mm off the working flank.

    Notes
    -----
    (u, v) by inverting the blank's projection-plane map (:func:`geometry.flank.
    projection_fractions`); the tooth by the point's angle about the member axis against
    the working flank's angle at (u, v), a bicubic spline through the load grid's points
    on the FE flank (``flank_position``).
    """
    p = real_array("points", points, unit="mm")
    if p.ndim != 2 or p.shape[1] != 3:
        raise InputError(f"points: must have shape (N, 3), got {p.shape}")
    corners = coefficients.variables["blank_corners"].values
    gu, gv = _grid(coefficients)
    rho = np.hypot(p[:, 0], p[:, 1])
    u, v = projection_fractions(corners, p[:, 2], rho)
    lo_u, hi_u, lo_v, hi_v = gu[0], gu[-1], gv[0], gv[-1]
    out = (u < lo_u - GRID_TOLERANCE) | (u > hi_u + GRID_TOLERANCE) | \
        (v < lo_v - GRID_TOLERANCE) | (v > hi_v + GRID_TOLERANCE)
    if strict and out.any():
        i = int(np.flatnonzero(out)[0])
        raise InputError(f"points: point {i} lies at face/profile fractions ({u[i]:.3f}, "
                         f"{v[i]:.3f}), outside the load grid [{lo_u:g}, {hi_u:g}] x "
                         f"[{lo_v:g}, {hi_v:g}] of the influence coefficients")
    w = hat_weights(gu, gv, u, v, outside="clip")
    pos = coefficients.variables["flank_position"].values
    phi_grid = np.arctan2(pos[..., 1], pos[..., 0])
    ref = phi_grid.flat[phi_grid.size // 2]
    phi_grid = ref + np.remainder(phi_grid - ref + math.pi, 2 * math.pi) - math.pi
    spline = RectBivariateSpline(gu, gv, phi_grid, kx=min(3, gu.size - 1),
                                 ky=min(3, gv.size - 1))
    phi_flank = spline(np.clip(u, lo_u, hi_u), np.clip(v, lo_v, hi_v), grid=False)
    pitch = float(coefficients.attrs["pitch"])
    dphi = np.arctan2(p[:, 1], p[:, 0]) - phi_flank
    dphi = np.remainder(dphi + math.pi, 2 * math.pi) - math.pi
    tooth = np.rint(dphi / pitch).astype(int)
    distance = rho * (dphi - tooth * pitch)
    off = np.abs(distance) > FLANK_TOLERANCE
    if strict and off.any():
        i = int(np.flatnonzero(off)[0])
        raise InputError(f"points: point {i} is {distance[i]:.3g} mm off the working "
                         f"({coefficients.attrs['flank']}) flank of the "
                         f"{coefficients.attrs['member']}'s teeth (at most "
                         f"{FLANK_TOLERANCE} mm)")
    return FlankPoints(u, v, tooth, distance, w)


def fe_compliance_matrix(coefficients: xr.Dataset, points) -> np.ndarray:
    """The FE compliance matrix between points of a member's working flank.

    Parameters
    ----------
    coefficients : xarray.Dataset — the member's influence coefficients
    points : array_like (N, 3) — [mm] points in the member frame (the LTCA's segment
        points on this member, turned into its frame), on the working flank of any tooth

    Returns
    -------
    ndarray (N, N) — [mm/N] C_ij: normal displacement (into the tooth) at point i per unit
        normal load at point j; symmetric, zero between teeth farther apart than the
        modelled neighbours.

    Raises
    ------
    InputError — as :func:`locate_flank_points`.

    Notes
    -----
    The tooth compliance matrix of the seed's LTCA (seed §3.2, Eq. 3.11: w_ij, the
    deflection at segment i due to a unit load at segment j, after Vaidyanathan, Houser &
    Busby 1993, seed ref. [3.5]), which enters the compatibility condition
    C F + s − R Θ = Y (seed Eq. 3.12–3.14). The seed builds it from a Rayleigh–Ritz
    shell and checks that against an FE model (seed Fig. 3.4, §3.2); here it is the FE
    model's own unit-load influence coefficients
    (:func:`contact.compliance.fe.influence.influence_coefficients`; scikit-fem:
    Gustafsson & McBain 2020, *JOSS* 5(52), 2369),
    superposed by linearity with the bilinear hat interpolation of the coefficients
    G[a, tooth, b] (module docstring) — the influence-coefficient method of the FE
    tooth models the seed cites (Wilcox, Chimner & Nowell 1997, seed ref. [3.1]).
    """
    fp = locate_flank_points(coefficients, points)
    g = coefficients["compliance"]
    nl = g.sizes["load_u"] * g.sizes["load_v"]
    w = fp.weights.toarray()
    n = len(fp.u)
    c = np.zeros((n, n))
    diff = fp.tooth[None, :] - fp.tooth[:, None]  # k_j − k_i: response tooth − load tooth
    for d in g["tooth"].values:
        mask = diff == d
        if not mask.any():
            continue
        gd = g.sel(tooth=d).values.reshape(nl, nl)  # [load a, response b]
        block = w @ gd @ w.T  # [i load, j response]
        c[mask] = block[mask]
    # c[i, j]: response at j of a load at i; the compliance matrix is its transpose
    # (displacement at i per load at j); symmetric within a tooth, averaged across teeth
    return 0.5 * (c + c.T)


def fillet_stress(coefficients: xr.Dataset, points, forces) -> xr.Dataset:
    """Root fillet stress of normal point forces on a member's working flanks.

    Parameters
    ----------
    coefficients : xarray.Dataset — the member's influence coefficients
    points : array_like (N, 3) — [mm] load points in the member frame
    forces : array_like (N,) — [N] normal forces at the points (pressing on the flank)

    Returns
    -------
    xarray.Dataset
        Over (tooth, side, station, arc): ``stress`` (+ component) [MPa], the stress
        tensor at the fillet points; ``max_principal``, ``min_principal`` [MPa]; over
        (tooth, side, station): ``max_principal_along_face`` and
        ``min_principal_along_face`` [MPa], their extremes over each fillet's root
        points (``fillet_in_root``: not the flank above the fillet) at each face
        station (the fillet stress along the face width: tension on the side of
        the loaded flank, compression on the other); ``tooth`` counts from the
        reference tooth.

    Raises
    ------
    InputError — bad points (:func:`locate_flank_points`) or forces not (N,) finite.

    Notes
    -----
    Linear superposition of the unit-load fillet stresses of the member's FE model
    (:func:`contact.compliance.fe.influence.influence_coefficients`; scikit-fem:
    Gustafsson & McBain 2020, *JOSS* 5(52), 2369) with the point forces spread on the
    load grid by the bilinear hat weights (module docstring) — the FE route to the root
    stress of bevel and hypoid teeth the seed cites (Wilcox, Chimner & Nowell 1997, seed
    ref. [3.1]; the shell model's root stresses: Vaidyanathan, Houser & Busby 1993, seed
    ref. [3.5]). The fillet stress reported is the maximum principal stress at the root
    fillet points (tension on the loaded side) and the minimum (compression on the
    other); it is checked against the 30°-tangent tooth-form formula of ISO 10300-3
    Method B1 (Y_Fa, Y_Sa) in docs/fe.md, which gives the measured FE/formula ratios.
    """
    fp = locate_flank_points(coefficients, points)
    f = real_array("forces", forces, unit="N")
    if f.shape != fp.u.shape:
        raise InputError(f"forces: must have shape {fp.u.shape} (one per point), got {f.shape}")
    s = coefficients["fillet_stress"]  # (lu, lv, tooth, side, station, arc, comp)
    nl = s.sizes["load_u"] * s.sizes["load_v"]
    offsets = s["tooth"].values
    teeth = np.arange(fp.tooth.min() + offsets.min(), fp.tooth.max() + offsets.max() + 1)
    shape = (len(teeth), *s.shape[3:])
    out = np.zeros(shape)
    sv = s.values.reshape(nl, len(offsets), -1)
    for k in np.unique(fp.tooth):
        sel = fp.tooth == k
        load = fp.weights[sel].T @ f[sel]  # (nl,) hat loads [N]
        contrib = np.einsum("a,atp->tp", load, sv).reshape(len(offsets), *shape[1:])
        start = int(k + offsets.min() - teeth[0])
        out[start:start + len(offsets)] += contrib
    smax, smin = principal_stresses(out)
    root = coefficients["fillet_in_root"].isel(tooth=0).transpose(
        "side", "station", "arc").values.astype(bool)  # the same on every tooth
    dims = ("tooth", "side", "station", "arc")
    coords = {"tooth": ("tooth", teeth.astype(np.int32), {
        "units": "1", "long_name": "tooth offset from the reference tooth"})}
    for name in ("side", "station", "arc", "component"):
        coords[name] = coefficients[name].variable
    return xr.Dataset({
        "stress": data_var((*dims, "component"), out, "MPa",
                           "stress at the root fillet point, member frame"),
        "max_principal": data_var(dims, smax, "MPa", "maximum principal stress at the root "
                                                     "fillet point"),
        "min_principal": data_var(dims, smin, "MPa", "minimum principal stress at the root "
                                                     "fillet point"),
        "max_principal_along_face": data_var(
            dims[:3], np.where(root, smax, -np.inf).max(axis=-1), "MPa",
            "largest maximum principal stress over the fillet's root points at the face "
            "station (tension)"),
        "min_principal_along_face": data_var(
            dims[:3], np.where(root, smin, np.inf).min(axis=-1), "MPa",
            "smallest minimum principal stress over the fillet's root points at the face "
            "station (compression)"),
    }, coords=coords, attrs={"member": coefficients.attrs["member"],
                             "flank": coefficients.attrs["flank"],
                             "source": "contact.compliance.fe.superposition.fillet_stress"})
