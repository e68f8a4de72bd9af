"""Bending and shear compliance of a hypoid tooth as a tapered cylindrical shell.

Rayleigh–Ritz model of seed section 3.2 (Eq. 3.1–3.11), after Vaidyanathan's shell
model (seed refs. [3.4–3.6]): the tooth is a segment of a circular cylindrical
shell about the cutter axis, of mean radius R (the cutter radius for face milling, the
measured lengthwise radius for face hobbing: :mod:`contact.compliance.tooth`),
clamped along the root and free at the tip, toe and heel; its thickness varies
linearly over the height and the face width and its height varies linearly along
the face width. Transverse deflection W and shear rotations follow Mindlin's
first-order shear theory (shear correction factor κ = 5/6; a higher-order
through-thickness field is available as an option); the strain energy is
integrated by Gauss quadrature over the tapered volume, the trial functions are
polynomials (seed Eq. 3.8), the stiffness matrix (seed Eq. 3.10) is assembled and
Cholesky-factorised once per tooth and reused for every load position; the
compliance matrix (seed Eq. 3.11) is then ``Φᵀ K⁻¹ Φ``.

Coordinates (seed Fig. 3.1)
---------------------------
``x`` [mm] along the tooth height from the root (along the cylinder axis),
``θ`` [rad] along the face width from the toe, about the cutter axis,
``z`` [mm] through the thickness along the outward shell normal (``z = 0`` on the
mid-surface). The deflection W is positive along +z.

Public API
----------
ShellTooth          frozen dataclass: the dimensions of the idealised tooth (Eq. 3.1)
ShellModel          a built, factorised Ritz model of one tooth
build_shell_model   assemble and factorise the stiffness matrix (Eq. 3.2–3.10)
shell_deflection    deflection W at evaluation points due to unit point loads
compliance_matrix   N×N compliance of load points or segments (Eq. 3.11)
flank_normals       outward normals of the idealised flanks (load directions)
ComplianceMatrix    the result: matrix, asymmetry, load centres
THEORIES            registry of kinematic theories (seed Mindlin, Mindlin, higher-order)
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy import linalg

from contact.compliance._basis import face_basis, height_basis
from contact.compliance.shell_tooth import (
    SHEAR_CORRECTION,
    THEORIES,
    Family,
    ShellModel,
    ShellTooth,
    Theory,
)
from contact.errors import ASYMMETRY_LIMIT, AsymmetricComplianceError
from geometry.core.caches import BatchedRows, Same, memoised, row_keys, rows_kept
from geometry.core.errors import InputError, LTCAError, ModelUnavailableError
from geometry.core.validation import integer, one_of, positive, real_array
from geometry.machine.meshing import warm_seeds_active

__all__ = [
    "THEORIES",
    "ComplianceMatrix",
    "ShellModel",
    "ShellTooth",
    "build_shell_model",
    "compliance_matrix",
    "flank_normals",
    "shell_deflection",
]

log = logging.getLogger(__name__)


_U, _V, _W = 0, 1, 2


def _gauss(n: int, lo: float, hi: float) -> tuple[np.ndarray, np.ndarray]:
    t, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (hi - lo) * t + 0.5 * (hi + lo), 0.5 * (hi - lo) * w


def _family_fields(
    fam: Family,
    z: np.ndarray,
    hx: tuple[np.ndarray, np.ndarray, np.ndarray],
    gt: tuple[np.ndarray, np.ndarray, np.ndarray],
    dxi: float,
    deta: float,
    radius: float,
) -> dict[str, np.ndarray]:
    """Displacement components and first derivatives of one family at points.

    Returns arrays of shape (P, count_x · count_θ) keyed ``"U", "U_x", "U_t", "U_z"``
    and the same for V and W (``_t`` is ∂/∂θ); missing keys are zero.
    """
    f, df, ddf = hx
    g, dg, ddg = gt

    def outer(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return (a[:, None, :] * b[None, :, :]).reshape(-1, a.shape[1]).T

    k = fam.z_power
    zk = (z**k)[:, None]
    dzk = (k * z ** (k - 1))[:, None] if k > 0 else None
    base = outer(f, g)
    name = "UVW"[fam.component]
    out = {
        name: zk * base,
        name + "_x": zk * outer(df, g) * dxi,
        name + "_t": zk * outer(f, dg) * deta,
    }
    if dzk is not None:
        out[name + "_z"] = dzk * base
    if fam.rotates:  # U = −z ∂W/∂x, V = −(z/R) ∂W/∂θ (seed: β = ψ − ∇W)
        zc = z[:, None]
        w_x = outer(df, g) * dxi
        w_t = outer(f, dg) * deta
        out["U"] = -zc * w_x
        out["U_x"] = -zc * outer(ddf, g) * dxi**2
        out["U_t"] = -zc * outer(df, dg) * dxi * deta
        out["U_z"] = -w_x
        out["V"] = -zc * w_t / radius
        out["V_x"] = -zc * outer(df, dg) * dxi * deta / radius
        out["V_t"] = -zc * outer(f, ddg) * deta**2 / radius
        out["V_z"] = -w_t / radius
    return out


def build_shell_model(
    tooth: ShellTooth,
    n_height: int = 5,
    n_face: int = 9,
    *,
    theory: str = "seed",
    shear_factor: float = SHEAR_CORRECTION,
    quadrature: tuple[int, int, int] | None = None,
) -> ShellModel:
    """Assemble and Cholesky-factorise the Ritz stiffness matrix of a tooth.

    Parameters
    ----------
    tooth : ShellTooth
    n_height : int — [1] number of height (clamped–free, "ICF") modes M, 1–20
    n_face : int — [1] number of face-width (free–free, "IFF") modes N, 1–30
    theory : str — key of :data:`THEORIES`: ``"seed"`` (default), ``"mindlin"``
        or ``"higher-order"``; see Notes
    shear_factor : float — [1] shear correction κ of the plane-stress (Mindlin)
        theories, default 5/6; ignored by ``"higher-order"``
    quadrature : (int, int, int), optional — [1] Gauss points over height, face
        and thickness; default ``(M + 4, N + M + 4, 2 p + 2)`` with p the highest
        power of z in the displacement field: exact for the polynomial part of the
        energy on the tapered domain, and the 1/(R + z) factors to
        O((t/2R)^(2p+4))

    Returns
    -------
    ShellModel
        Holds the Jacobi-scaled Cholesky factor of the stiffness.

    Raises
    ------
    InputError
        Mode counts or quadrature orders out of range, κ not in (0, 1].
    ModelUnavailableError
        Unknown ``theory`` (the message lists the available ones).
    LTCAError
        The stiffness matrix is not positive definite (should not happen for a
        valid tooth; reported rather than returning garbage).

    Notes
    -----
    Source: seed Eq. 3.2–3.10 (after Vaidyanathan, seed refs. [3.4–3.6]). The
    extraction loses most symbols; we reconstruct Eq. 3.4–3.5 from the exact
    linear strains of a body in the cylindrical coordinates (x, θ, r = R + z)
    of seed Eq. 3.2 (the general relations of seed Eq. 3.4 with α = x, β = θ,
    A = 1, B = R, R_α = ∞, R_β = R)::

        ε_x  = ∂U/∂x              ε_θ  = (∂V/∂θ + W)/(R + z)
        γ_xθ = ∂V/∂x + ∂U/∂θ/(R + z)      γ_xz = ∂U/∂z + ∂W/∂x
        γ_θz = ∂V/∂z − V/(R + z) + ∂W/∂θ/(R + z)

    (ε_z does not enter: all theories assume plane stress, σ_z = 0, with W
    independent of z.)

    With the seed's Mindlin field U = z(ψ_x − ∂W/∂x), V = z(ψ_θ − ∂W/∂θ/R),
    W = W(x, θ) they give exactly the five relations of seed Eq. 3.5::

        ε_x  = z (∂ψ_x/∂x − ∂²W/∂x²)                                     (3.5a)
        ε_θ  = [z (∂ψ_θ/∂θ − ∂²W/∂θ²/R) + W] / (R + z)                    (3.5b)
        γ_xθ = z ∂ψ_θ/∂x + z ∂ψ_x/∂θ/(R + z) − z(2R + z)/(R(R + z)) ∂²W/∂x∂θ   (3.5c)
        γ_θz = ψ_θ R/(R + z)                                               (3.5d)
        γ_xz = ψ_x                                                         (3.5e)

    (the surviving tokens of Eq. 3.5c, "(2 r_c + z)" and "r_c (r_c + z)", match).
    The strain energy is seed Eq. 3.6a, volume element (R + z) dx dθ dz, with the
    shear correction κ for the Mindlin theories (κ = 1 for ``"higher-order"``)::

        SE = ½ ∫ [E/(1−ν²)(ε_x² + ε_θ² + 2ν ε_x ε_θ) + G (γ_xθ² + κ γ_xz² + κ γ_θz²)] dV

    and a point load F along the normal at (x₀, θ₀) does work F W(x₀, θ₀, z = 0)
    (Eq. 3.6b; the flank-to-mid-surface compression belongs to the Weber term);
    a flank load also works through its moment about the mid-surface
    (:meth:`ShellModel.load_vectors`).

    Theories (:data:`THEORIES`):

    * ``"seed"`` (default): seed Eq. 3.9 as read, W = ∂W/∂x = ψ_x = ψ_θ = 0 at the
      root, trial functions (x/a)^(m+1) for W and (x/a)^m for ψ (seed p. 77): the
      clamp W = ψ = 0 with the seed's ICF/IFF families. Forcing the root shear strain to zero
      over-constrains shear a little; it still converges to Timoshenko beam
      theory in the beam limit, more slowly than ``"mindlin"``.
    * ``"mindlin"``: the usual Mindlin clamp W = β = 0 with unknowns W, β
      (W ∈ span{ξ … ξ^(M+1)}, β ∈ span{ξ … ξ^M}, no shear locking in the thin
      limit); exact for a Timoshenko cantilever with M ≥ 2.
    * ``"higher-order"`` (our extension): U = u₀ + z β + z³ φ (same for V),
      W(x, θ), plane stress, no κ. It adds the mid-surface stretching the seed
      omits (which stiffens thin curved shells: ~10 % at t = 2 mm, R = 95 mm)
      and lets the shear strain vary through the thickness, which matters for a
      strongly tapered tooth. A variant with W quadratic in z and 3-D Hooke's law
      was tried and is ~10 % too stiff (lateral contraction locked at the clamp by
      the polynomial field), so it is not offered.

    Against 3-D finite elements of the same tooth (typical hypoid tooth, flank
    load at mid face and mid profile; ``benchmarks/compliance.py``) the tip
    deflection of all three is within 10 % from 5 × 9 modes on: peak ratio
    shell/FE 1.02–1.07 (``"seed"``), 1.05–1.07 (``"mindlin"``), 0.93–0.95
    (``"higher-order"``); max error over the tip line 5.5 %, 7.4 %, 5–7 %. The
    load must act on the flank along the flank normal (:func:`compliance_matrix`
    with ``normals``): the tapered flank tilts the force, and its tangential part
    acting at z = ±t/2 changes the tip deflection by ~25 %.

    Implementation choices (not in the seed): Legendre polynomials in mapped
    coordinates span the seed's monomial spaces (``_basis``); the stiffness is
    Jacobi-scaled before the Cholesky factorisation.
    """
    if theory not in THEORIES:
        raise ModelUnavailableError(
            f"theory {theory!r} is not available; choose one of {sorted(THEORIES)}"
        )
    m = integer("n_height", n_height, 1, 20)
    n = integer("n_face", n_face, 1, 30)
    kappa = positive("shear_factor", shear_factor, "1", high=1.0)
    th = THEORIES[theory]
    nq_x, nq_t, nq_z = _quadrature_orders(th, m, n, quadrature)

    t0 = time.perf_counter()
    a = max(tooth.height_toe, tooth.height_heel)
    quad = _volume_quadrature(tooth, a, nq_x, nq_t, nq_z)
    layout, n_dof = _dof_layout(th, m, n)
    K = _stiffness(tooth, th, kappa, layout, n_dof, n, quad, a)
    factor, scale, half = _scaled_cholesky(K, n_dof)
    elapsed = time.perf_counter() - t0
    log.debug(
        "shell model: %d unknowns (M=%d, N=%d, %s), %d quadrature points, %.3f s",
        n_dof, m, n, theory, quad.xi.size * nq_z, elapsed,
    )
    return ShellModel(
        tooth=tooth,
        n_height=m,
        n_face=n,
        theory=theory,
        shear_factor=kappa,
        n_dof=n_dof,
        build_time=elapsed,
        reference_height=a,
        _layout=layout,
        _factor=factor,
        _scale=scale,
        _half_operator=half,
    )


def _quadrature_orders(
    th: Theory, m: int, n: int, quadrature: tuple[int, int, int] | None
) -> tuple[int, int, int]:
    """Gauss points [1] over height, face and thickness: ``quadrature`` checked, or by
    default (M + 4, N + M + 4, 2 p + 2) with p the highest power of z in the displacement
    field of theory ``th`` (see :func:`build_shell_model`)."""
    p_z = max(fam.z_power + (1 if fam.rotates else 0) for fam in th.families)
    if quadrature is None:
        quadrature = (m + 4, n + m + 4, 2 * p_z + 2)
    if len(quadrature) != 3:
        raise InputError(f"quadrature: must be three integers, got {quadrature!r}")
    nq_x = integer("quadrature[0]", quadrature[0], 1, 200)
    nq_t = integer("quadrature[1]", quadrature[1], 1, 400)
    nq_z = integer("quadrature[2]", quadrature[2], 1, 50)
    return nq_x, nq_t, nq_z


class _VolumeQuadrature(NamedTuple):
    """Gauss points over the tapered tooth: P = nq_θ · nq_x mid-surface points (θ-major,
    x = s h(θ)), each with nq_z points z = ζ t/2 through the thickness."""

    xi: np.ndarray  # (P,) [1] ξ = x / a
    eta: np.ndarray  # (P,) [1] η = 2θ/Θ₀ − 1
    thickness: np.ndarray  # (P,) [mm] t(x, θ)
    area_weight: np.ndarray  # (P,) [mm rad] w_θ w_s h(θ)
    zeta: np.ndarray  # (nq_z,) [1] ζ in [−1, 1]
    zeta_weight: np.ndarray  # (nq_z,) [1]


def _volume_quadrature(
    tooth: ShellTooth, a: float, nq_x: int, nq_t: int, nq_z: int
) -> _VolumeQuadrature:
    """Gauss points and weights over the tapered volume of ``tooth``: θ [rad] over the
    face, then x = s h(θ) [mm] over the height (ξ = x/a, a [mm] the reference height),
    then z = ζ t/2 [mm] through the thickness."""
    th0 = tooth.subtended_angle
    th_q, wth_q = _gauss(nq_t, 0.0, th0)
    s_q, ws_q = _gauss(nq_x, 0.0, 1.0)
    zeta_q, wz_q = _gauss(nq_z, -1.0, 1.0)
    h_q = tooth.height(th_q)
    x_tq = h_q[:, None] * s_q[None, :]
    t_flat = tooth.thickness(x_tq, th_q[:, None]).ravel()
    w_area = (wth_q[:, None] * ws_q[None, :] * h_q[:, None]).ravel()
    xi = (x_tq / a).ravel()
    eta = np.repeat(2.0 * th_q / th0 - 1.0, nq_x)
    return _VolumeQuadrature(xi, eta, t_flat, w_area, zeta_q, wz_q)


def _dof_layout(th: Theory, m: int, n: int) -> tuple[tuple, int]:
    """Where each family of theory ``th`` sits among the Ritz unknowns: a tuple of
    (family, offset, x_power, x_count) with x_count = M + x_extra height functions times
    N face functions each, and the number of unknowns n_dof [1]."""
    layout, off = [], 0
    for fam in th.families:
        key = (fam.x_power, m + fam.x_extra)
        layout.append((fam, off, *key))
        off += key[1] * n
    return tuple(layout), off


def _stiffness(
    tooth: ShellTooth,
    th: Theory,
    kappa: float,
    layout: tuple,
    n_dof: int,
    n: int,
    quad: _VolumeQuadrature,
    a: float,
) -> np.ndarray:
    """The Ritz stiffness matrix K (n_dof, n_dof) of seed Eq. 3.10, strain energy
    ½ qᵀ K q [N·mm] of the unknowns q: seed Eq. 3.6a (plane stress [MPa], shear × κ for the
    Mindlin theories) integrated over the quadrature ``quad`` and symmetrised; a [mm] the
    height that normalises x, n the number of face functions."""
    radius = tooth.radius
    dxi, deta = 1.0 / a, 2.0 / tooth.subtended_angle
    gt = face_basis(quad.eta, n)
    hx = {}
    for _, _, power, count in layout:
        if (power, count) not in hx:
            hx[(power, count)] = height_basis(quad.xi, power, count)

    e_mod, nu = tooth.youngs_modulus, tooth.poisson_ratio
    g_mod = tooth.shear_modulus
    k_s = kappa if th.shear_corrected else 1.0
    # the energy density εᵀ C ε with C = L Lᵀ: plane stress E/(1−ν²) [[1, ν], [ν, 1]] =
    # L Lᵀ with L = √(E/(1−ν²)) [[1, 0], [ν, √(1−ν²)]], shear G (1, κ, κ) diagonal; so
    # K = Σ Gᵀ G with G = √w Lᵀ ε, one symmetric rank-k product per thickness point (half
    # the multiplications of Eᵀ (w C E); the same K to round-off, 2e-16 of its largest
    # term on the 11x41's pinion)
    root_c = math.sqrt(e_mod / (1.0 - nu**2))
    l00, l10, l11 = root_c, nu * root_c, root_c * math.sqrt(1.0 - nu**2)
    root_sh = np.sqrt(g_mod * np.array([1.0, k_s, k_s]))  # γ_xθ, γ_xz, γ_θz

    t_flat = quad.thickness
    K = np.zeros((n_dof, n_dof))
    for zeta, wz in zip(quad.zeta, quad.zeta_weight, strict=True):
        z = 0.5 * zeta * t_flat
        E = _strains(layout, n_dof, n, z, hx, gt, dxi, deta, radius)
        # (R+z) dθ dx dz
        root_w = np.sqrt(quad.area_weight * wz * 0.5 * t_flat * (radius + z))[None, :, None]
        G = np.empty_like(E)
        G[0] = l00 * E[0] + l10 * E[1]
        G[1] = l11 * E[1]
        G[2:] = root_sh[:, None, None] * E[2:]
        G *= root_w
        G2 = G.reshape(-1, n_dof)
        K += G2.T @ G2  # NumPy's syrk for a product with its own transpose
    return 0.5 * (K + K.T)


def _strains(
    layout: tuple,
    n_dof: int,
    n: int,
    z: np.ndarray,
    hx: dict[tuple[int, int], tuple[np.ndarray, ...]],
    gt: tuple[np.ndarray, ...],
    dxi: float,
    deta: float,
    radius: float,
) -> np.ndarray:
    """Strains [ε_x, ε_θ, γ_xθ, γ_xz, γ_θz] [1] per unit of each Ritz unknown at the
    points (P,) at distance z [mm] from the mid-surface: a (5, P, n_dof) array (the exact
    linear strains of a cylindrical body of radius [mm], see :func:`build_shell_model`)."""
    inv = (1.0 / (radius + z))[:, None]
    E = np.zeros((5, z.size, n_dof))
    for fam, o, power, count in layout:
        sz = count * n
        f = _family_fields(fam, z, hx[(power, count)], gt, dxi, deta, radius)
        zero = 0.0
        E[0, :, o : o + sz] = f.get("U_x", zero)
        E[1, :, o : o + sz] = (f.get("V_t", zero) + f.get("W", zero)) * inv
        E[2, :, o : o + sz] = f.get("V_x", zero) + f.get("U_t", zero) * inv
        E[3, :, o : o + sz] = f.get("U_z", zero) + f.get("W_x", zero)
        E[4, :, o : o + sz] = f.get("V_z", zero) + (f.get("W_t", zero) - f.get("V", zero)) * inv
    return E


def _scaled_cholesky(K: np.ndarray, n_dof: int) -> tuple[tuple, np.ndarray, np.ndarray]:
    """Cholesky factor (upper, as :func:`scipy.linalg.cho_factor`) of the Jacobi-scaled
    stiffness S K S = UᵀU [1], the scale S = diag(K)^(−1/2), and U⁻ᵀ S (lower triangular,
    Fortran order; the half solve's operator, :meth:`ShellModel.half_solve`: the scale
    folded into U⁻ᵀ's columns once, so a half solve is one triangular product, issue 75);
    raises :class:`LTCAError` for a zero or non-finite diagonal term or a K that is not
    positive definite."""
    d = np.sqrt(np.diag(K))
    if not np.all(np.isfinite(d)) or np.any(d <= 0.0):
        raise LTCAError("shell stiffness has a zero or non-finite diagonal term")
    scale = 1.0 / d
    try:
        factor = linalg.cho_factor(
            K * scale[:, None] * scale[None, :], lower=False, check_finite=False
        )
    except linalg.LinAlgError as exc:
        raise LTCAError(
            f"shell stiffness ({n_dof} unknowns) is not positive definite: "
            "reduce the number of modes or check the tooth dimensions"
        ) from exc
    inverse = linalg.solve_triangular(factor[0], np.eye(n_dof, order="F"), trans="T",
                                      lower=False, check_finite=False, overwrite_b=True)
    return factor, scale, np.asfortranarray(np.tril(inverse) * scale[None, :])


# ---------------------------------------------------------------------------------------
# load points and segments
# ---------------------------------------------------------------------------------------
def _to_shell_coords(tooth: ShellTooth, pts: np.ndarray, coords: str) -> np.ndarray:
    """Map (…, 2) points to shell coordinates (x [mm], θ [rad])."""
    conv: dict[str, Callable[[np.ndarray], np.ndarray]] = {
        "shell": lambda p: p,
        "normalised": lambda p: np.stack(
            [p[..., 0] * tooth.height(p[..., 1] * tooth.subtended_angle),
             p[..., 1] * tooth.subtended_angle],
            axis=-1,
        ),
    }
    if coords not in conv:
        one_of("coords", coords, sorted(conv))
    return conv[coords](pts)


def _check_inside(tooth: ShellTooth, x: np.ndarray, theta: np.ndarray, name: str) -> None:
    tol = 1e-9
    th0 = tooth.subtended_angle
    bad_t = (theta < -tol * th0) | (theta > th0 * (1 + tol))
    h = tooth.height(np.clip(theta, 0.0, th0))
    bad_x = (x < -tol * h) | (x > h * (1 + tol))
    if np.any(bad_t) or np.any(bad_x):
        raise InputError(
            f"{name}: must lie on the tooth, 0 <= theta <= {th0:.6g} rad and "
            "0 <= x <= h(theta) mm (or fractions in [0, 1] with coords='normalised'), got "
            f"{int(np.count_nonzero(bad_t | bad_x))} point(s) off it"
        )


def as_points(tooth: ShellTooth, points: np.ndarray, coords: str, name: str) -> np.ndarray:
    """Points (N, 2) or segment ends (N, 2, 2) in ``coords`` ("shell" (x, θ) or "flank") as
    shell coordinates, checked to be finite and on the shell; InputError names ``name``."""
    pts = real_array(name, points)
    if pts.ndim == 1 and pts.shape[0] == 2:
        pts = pts[None, :]
    if pts.ndim < 2 or pts.shape[-1] != 2:
        raise InputError(f"{name}: must be of shape (N, 2) or (N, 2, 2), got {pts.shape}")
    pts = _to_shell_coords(tooth, pts, coords)
    _check_inside(tooth, pts[..., 0], pts[..., 1], name)
    return pts


def flank_normals(
    tooth: ShellTooth, points: np.ndarray, side: float | np.ndarray = 1.0, *, coords: str = "shell"
) -> np.ndarray:
    """Outward unit normals of the idealised flanks z = ±t(x, θ)/2 in the local frame.

    Parameters
    ----------
    tooth : ShellTooth
    points : array_like, shape (N, 2) — (x [mm], θ [rad]) or fractions with
        ``coords="normalised"``
    side : float or array_like (N,) — +1 for the convex flank (z = +t/2, away
        from the shell axis), −1 for the concave flank (z = −t/2)
    coords : {"shell", "normalised"}

    Returns
    -------
    ndarray, shape (N, 3) — [1] components on (e_x, e_θ, e_z); the tilt away from
        ±e_z is the flank's taper: n ∝ side · (−a b, −c, b), a = side ∂t/∂x / 2,
        b = R + z_s, c = side ∂t/∂θ / 2.

    Raises
    ------
    InputError
        Points off the tooth or ``side`` not ±1.

    Notes
    -----
    Geometry of seed Eq. 3.1 (as reconstructed in :class:`ShellTooth`); for the
    LTCA the real flank normals from the tooth geometry may be used instead.
    """
    pts = as_points(tooth, points, coords, "points").reshape(-1, 2)
    sd = np.broadcast_to(np.asarray(side, dtype=float), (pts.shape[0],))
    if not np.all(np.abs(np.abs(sd) - 1.0) == 0.0):
        raise InputError(f"side: must be +1 (convex flank) or -1 (concave flank), got {side!r}")
    t_x, t_t = tooth.thickness_gradient(pts[:, 0], pts[:, 1])
    zs = 0.5 * sd * tooth.thickness(pts[:, 0], pts[:, 1])
    a = 0.5 * sd * t_x
    b = tooth.radius + zs
    c = 0.5 * sd * t_t
    n = sd[:, None] * np.column_stack([-a * b, -c, b])
    return n / np.linalg.norm(n, axis=1)[:, None]


def _flank_loads(
    tooth: ShellTooth, x: np.ndarray, theta: np.ndarray, normals: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray]:
    """Force directions (−n, into the tooth) and application offsets z_s [mm].

    Without normals: a force along +e_z on the mid-surface.
    """
    n_pts = x.size
    if normals is None:
        d = np.zeros((n_pts, 3))
        d[:, 2] = 1.0
        return d, np.zeros(n_pts)
    nrm = np.asarray(normals, dtype=float)
    if nrm.shape != (n_pts, 3) or not np.all(np.isfinite(nrm)):
        raise InputError(
            f"normals: must be finite with shape ({n_pts}, 3), outward unit normals of the "
            f"loaded flank in the local frame (e_x, e_theta, e_z) [1], got shape {nrm.shape}"
        )
    if np.any(np.abs(np.linalg.norm(nrm, axis=1) - 1.0) > 1e-6):
        raise InputError("normals: must be unit vectors (|n| = 1 within 1e-6) [1], got |n| - 1 "
                         f"up to {np.max(np.abs(np.linalg.norm(nrm, axis=1) - 1.0)):.3g}")
    if np.any(nrm[:, 2] == 0.0):
        raise InputError("normals: must have a non-zero e_z component (which flank is loaded) "
                         f"[1], got {int(np.count_nonzero(nrm[:, 2] == 0.0))} with n_z = 0")
    zs = 0.5 * np.sign(nrm[:, 2]) * tooth.thickness(x, theta)
    return -nrm, zs


def shell_deflection(
    model: ShellModel,
    load_points: np.ndarray,
    eval_points: np.ndarray,
    *,
    load_normals: np.ndarray | None = None,
    coords: str = "shell",
) -> np.ndarray:
    """Mid-surface deflection W at evaluation points due to unit point loads.

    Parameters
    ----------
    model : ShellModel
    load_points : array_like, shape (L, 2) — (x [mm], θ [rad]) of the unit loads,
        or fractions with ``coords="normalised"``
    eval_points : array_like, shape (P, 2) — where W (along +e_z, at z = 0) is read
    load_normals : array_like, shape (L, 3), optional — outward unit normals of the
        loaded flank (local frame); the load then acts along −n on that flank
        (see :func:`compliance_matrix`). Default: along +e_z on the mid-surface.
    coords : {"shell", "normalised"}

    Returns
    -------
    ndarray, shape (P, L) — [mm/N] W at point p due to a unit load at l

    Raises
    ------
    InputError
        Points not of shape (·, 2), not finite or off the tooth; bad normals.

    Notes
    -----
    Source: seed Eq. 3.10–3.11 (the Ritz solution evaluated at other points).
    """
    tooth = model.tooth
    lp = as_points(tooth, load_points, coords, "load_points").reshape(-1, 2)
    ep = as_points(tooth, eval_points, coords, "eval_points").reshape(-1, 2)
    d, zs = _flank_loads(tooth, lp[:, 0], lp[:, 1], load_normals)
    loads = model.load_vectors(lp[:, 0], lp[:, 1], d, zs)
    return model.w_functions(ep[:, 0], ep[:, 1]).T @ model.solve(loads)


@dataclass(frozen=True, eq=False)
class ComplianceMatrix:
    """Result of :func:`compliance_matrix`.

    Attributes
    ----------
    matrix : ndarray, shape (N, N) — [mm/N] symmetrised compliance; entry (i, j) is
        the deflection along the load direction at i due to a unit load at j
    asymmetry : float — [1] ‖C − Cᵀ‖_F / ‖C‖_F before symmetrisation
    centres : ndarray, shape (N, 2) — (x [mm], θ [rad]) of the load centres
    """

    matrix: np.ndarray
    asymmetry: float
    centres: np.ndarray


@memoised(maxsize=32)
def _segment_gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre points and weights on [0, 1] (memoised; read-only arrays)."""
    t, w = np.polynomial.legendre.leggauss(n)
    s, w = 0.5 * (t + 1.0), 0.5 * w
    s.flags.writeable = False
    w.flags.writeable = False
    return s, w


def compliance_matrix(
    model: ShellModel,
    points: np.ndarray,
    normals: np.ndarray | None = None,
    segment_length: float | np.ndarray | None = None,
    *,
    coords: str = "shell",
    n_segment_gauss: int = 4,
) -> ComplianceMatrix:
    """Compliance matrix of a tooth at N load points or segments (seed Eq. 3.11).

    Parameters
    ----------
    model : ShellModel — built by :func:`build_shell_model`
    points : array_like — either shape (N, 2): load centres (x [mm], θ [rad]);
        or shape (N, 2, 2): the two end points of N straight segments
        (``points[i, 0]`` and ``points[i, 1]``), each loaded uniformly per unit
        length of the developed mid-surface. With ``coords="normalised"`` the pairs
        are (profile fraction x/h(θ), face fraction θ/Θ₀) in [0, 1].
    normals : array_like, shape (N, 3), optional — outward unit normal of the
        loaded flank at each load, components on the local frame (e_x, e_θ, e_z);
        the contact force acts along −n on the flank z_s = sign(n_z) t/2, and the
        deflection is read along −n there (see :func:`flank_normals`). Default:
        a force along +e_z on the mid-surface, deflection W.
    segment_length : float or array_like (N,), optional — [mm] with (N, 2) points,
        spread each load uniformly over a segment of this length centred on the
        point and running along the face width (θ direction); this removes the
        point-load singularity of Mindlin theory (W ~ F ln r near the load).
    coords : {"shell", "normalised"}
    n_segment_gauss : int — [1] Gauss points per segment (load and read-out)

    Returns
    -------
    ComplianceMatrix
        ``matrix`` [mm/N], ``asymmetry`` [1], ``centres`` (x [mm], θ [rad]).

    Raises
    ------
    InputError
        Bad shapes, non-finite or off-tooth points, segments leaving the tooth,
        non-positive segment lengths, normals that are not unit vectors.

    Notes
    -----
    Source: seed Eq. 3.11, ``w_ij`` = deflection at i due to a unit load at j. The
    Ritz solution gives ``C = Φᵀ K⁻¹ Φ`` where column j of Φ is the generalised
    load vector of load j (:meth:`ShellModel.load_vectors`; averaged over the
    segment for segment loads); the same vector reads the deflection along the
    load, which keeps reciprocity. A flank force is not along the shell normal:
    the flank is tilted by the taper, and the tangential component acting at
    z_s = ±t/2 bends the tooth through its moment about the mid-surface (it
    lowers the tip deflection of a typical tooth by ~25 %; the seed keeps only
    the normal component). The matrix is symmetric in exact arithmetic (Maxwell–Betti); the
    relative asymmetry of the computed product is returned and the matrix is
    symmetrised.
    """
    tooth = model.tooth
    pts = np.asarray(points, dtype=float)
    if pts.ndim == 3 and pts.shape[1:] == (2, 2):
        ends = as_points(tooth, pts, coords, "points")
    elif pts.ndim == 2 and pts.shape[1] == 2:
        centres = as_points(tooth, pts, coords, "points")
        if segment_length is None:
            ends = np.stack([centres, centres], axis=1)
        else:
            seg = np.broadcast_to(real_array("segment_length", segment_length, unit="mm",
                                             low=0.0, low_open=True), (centres.shape[0],))
            dth = 0.5 * seg / tooth.radius
            ends = np.stack(
                [
                    np.column_stack([centres[:, 0], centres[:, 1] - dth]),
                    np.column_stack([centres[:, 0], centres[:, 1] + dth]),
                ],
                axis=1,
            )
            _check_inside(tooth, ends[..., 0], ends[..., 1], "points ± segment_length/2")
    else:
        raise InputError(f"points: must be of shape (N, 2) or (N, 2, 2), got {pts.shape}")
    return compliance_blocks(model, ends, normals, None, n_segment_gauss)[0]


def _as_range(idx):
    """An index array of consecutive integers as the slice it is (a view, not a copy);
    anything else as it is."""
    if isinstance(idx, slice):
        return idx
    idx = np.asarray(idx)
    if idx.ndim == 1 and idx.size and idx.dtype.kind in "iu" \
            and int(idx[-1]) - int(idx[0]) == idx.size - 1 and np.all(np.diff(idx) == 1):
        return slice(int(idx[0]), int(idx[-1]) + 1)
    return idx


#: columns of Y kept per shell model by :func:`_half_vectors` (each n_dof floats: 3 kB on
#: the default 378 unknowns; two analyses of the default case's ~1,500 segments a member)
HALF_VECTORS_KEPT = 4096


class _ColumnStore(BatchedRows):
    """The columns of Y kept for one shell model (:func:`_half_vector_store`): a
    :class:`~geometry.core.caches.BatchedRows` whose batches are the (N, n_dof) C-ordered,
    read-only Yᵀ of one product each."""

    __slots__ = ()


@memoised(maxsize=4)
def _half_vector_store(model: Same) -> _ColumnStore:
    """The columns of Y = U⁻ᵀ S Φ computed so far for segments on the tooth of the shell
    model ``model.obj``, by the segment's bytes (ends, normal, Gauss points): one store per
    model, emptied with the memo (``clear_caches``); :func:`_half_vectors` keeps the last
    :data:`HALF_VECTORS_KEPT` (the oldest dropped first)."""
    return _ColumnStore()


def _half_vectors(model: ShellModel, ends: np.ndarray, normals: np.ndarray | None,
                  ng: int) -> np.ndarray:
    """Y = U⁻ᵀ S Φ (n_dof, N), Fortran order, of segments with ``ends`` (N, 2, 2) [mm, rad]
    on the tooth and ``normals`` (N, 3) or None, Φ their mean load vectors over ``ng``
    Gauss points (:meth:`ShellModel.load_vectors`, :meth:`ShellModel.half_solve`).

    A segment's column depends on the model, its ends and normal alone, so it is kept per
    process (:func:`_half_vector_store`) and not computed again: the analyses of a torque
    series or one repeated at one misalignment map the same segments (the memoised curve
    segments, :mod:`contact.ltca.segments`). The columns computed here are those of the
    segments not kept, in one load-vector build and one triangular product as before; a
    call with none kept gives the same array as that product. The kept columns are copied
    in a batch at a time (a take of the batch's rows)."""
    nrm = None if normals is None else np.asarray(normals, dtype=float)
    # a development's trial (its teeth new at every trial), a study point (its segments
    # new at every point, geometry.core.caches.rows_not_kept): nothing kept
    if warm_seeds_active() or not rows_kept():
        return _half_vectors_of(model, ends, nrm, ng)
    n_pts = ends.shape[0]
    rows = [ends.reshape(n_pts, 4)] + ([] if nrm is None else [nrm])
    rows = np.ascontiguousarray(np.concatenate(rows, axis=1), dtype=float)
    tag = ng.to_bytes(2, "little") + (b"n" if nrm is not None else b"-")
    keys = row_keys(rows, tag)
    store = _half_vector_store(Same(model))
    with store.lock:  # (an analysis per thread: one at a time per model)
        get = store.rows.get
        code = np.array([get(k, -1) for k in keys], dtype=np.int64)
        miss = np.flatnonzero(code < 0)
        if miss.size == n_pts:  # nothing kept: the product's own array
            y = _half_vectors_of(model, ends, nrm, ng)
            y.flags.writeable = False  # its columns are kept
            store.add(y.T, keys)
        else:
            y = np.empty((model.n_dof, n_pts), order="F")
            yt = y.T  # (C order): a kept column is one contiguous row of it
            if miss.size:
                new = _half_vectors_of(model, ends[miss], None if nrm is None else nrm[miss],
                                       ng)
                new.flags.writeable = False  # its columns are kept
                yt[miss] = new.T
                store.add(new.T, [keys[i] for i in miss.tolist()])
            hit = np.flatnonzero(code >= 0)
            batch, row = code[hit] >> 32, code[hit] & 0xFFFFFFFF
            for b in np.unique(batch).tolist():
                sel = batch == b
                yt[hit[sel]] = store.batches[b][row[sel]]
        store.trim(HALF_VECTORS_KEPT)  # the oldest first, in one pass
    return y


def _half_vectors_of(model: ShellModel, ends: np.ndarray, normals: np.ndarray | None,
                     ng: int) -> np.ndarray:
    """Y = U⁻ᵀ S Φ (n_dof, N) of the segments (:func:`_half_vectors`), computed."""
    tooth = model.tooth
    # h(θ) is linear, so the developed tooth is convex: a chord between two
    # on-tooth end points stays on the tooth.
    s, w = _segment_gauss(ng)
    p0 = ends[:, 0, :]
    p1 = ends[:, 1, :]
    gp = (p0[:, None, :] + s[None, :, None] * (p1 - p0)[:, None, :]).reshape(-1, 2)
    nrm = None if normals is None else np.repeat(normals, ng, axis=0)
    d, zs = _flank_loads(tooth, gp[:, 0], gp[:, 1], nrm)
    # the segments' mean load vectors (n_dof, N): Gauss sums over their G points
    phi = model.load_vectors(gp[:, 0], gp[:, 1], d, zs, group_weights=w)
    # one triangular product for all segments (same matrix to round-off as Φᵀ (K⁻¹ Φ))
    return model.half_solve(phi, overwrite_loads=True)  # (phi is this call's own)


def compliance_blocks(
    model: ShellModel,
    ends: np.ndarray,
    normals: np.ndarray | None,
    blocks: list[np.ndarray] | None,
    n_segment_gauss: int = 4,
) -> list[ComplianceMatrix]:
    """:func:`compliance_matrix` of several groups of segments on one tooth at once.

    ``ends`` (N, 2, 2) [mm, rad] on the tooth (checked), ``normals`` (N, 3) or None,
    ``blocks`` a list of index arrays into the N segments (None: one block of all).
    The load vectors of all segments are built together and solved with one
    ``cho_solve`` (all right-hand sides); each block's matrix and asymmetry are those
    :func:`compliance_matrix` gives for that block alone (to round-off).
    """
    n_pts = ends.shape[0]
    if n_pts == 0:
        raise InputError("points: must hold at least one load, got none")
    ng = integer("n_segment_gauss", n_segment_gauss, 1, 32)
    if normals is not None and np.asarray(normals).shape != (n_pts, 3):
        raise InputError(
            f"normals: must be of shape ({n_pts}, 3) [1], got {np.asarray(normals).shape}"
        )
    p0 = ends[:, 0, :]
    p1 = ends[:, 1, :]
    # C = Φᵀ K⁻¹ Φ = Yᵀ Y with Y = U⁻ᵀ S Φ (K's scaled Cholesky factor): each segment's
    # column of Y once per process and shell model (_half_vectors)
    y = _half_vectors(model, ends, normals, ng)
    centres = 0.5 * (p0 + p1)
    out = []
    for idx in [slice(None)] if blocks is None else blocks:
        idx = _as_range(idx)
        yb = y[:, idx]
        cmat = yb.T @ yb
        # BLAS's symmetric rank-k product for YᵀY gives C symmetric to the bit; the
        # measure and the symmetrisation below are for a product that is not (the test
        # element-wise: np.array_equal's, without its conversions, a few µs a block)
        if (cmat == cmat.T).all():
            out.append(ComplianceMatrix(matrix=cmat, asymmetry=0.0, centres=centres[idx]))
            continue
        norm = float(np.linalg.norm(cmat))
        asym = float(np.linalg.norm(cmat - cmat.T) / norm) if norm > 0.0 else 0.0
        if asym > ASYMMETRY_LIMIT:
            raise AsymmetricComplianceError(
                f"compliance: shell compliance asymmetry {asym:.3g} exceeds "
                f"{ASYMMETRY_LIMIT:g} (Maxwell–Betti: the Ritz product is symmetric; the "
                "shell model is ill-conditioned here)")
        if asym > 1e-8:
            log.warning("shell compliance asymmetry %.3g before symmetrisation", asym)
        cmat = 0.5 * (cmat + cmat.T)
        out.append(ComplianceMatrix(matrix=cmat, asymmetry=asym, centres=centres[idx]))
    return out
