"""3-D linear-elastic finite-element model of the tapered shell tooth (scikit-fem).

The independent reference for the Rayleigh–Ritz shell model of
``contact.compliance.shell`` (seed Fig. 3.4 compares the shell model with ANSYS
the same way): the SAME tooth — a segment of a circular cylindrical shell of mean
radius R, height h(θ), thickness t(x, θ) (seed Eq. 3.1) — meshed as a solid by
mapping a structured box mesh onto the shell geometry, triquadratic hexahedra
(ElementHex2, 27 nodes), isotropic linear elasticity (no shell kinematics, no
shear correction, no plane-stress assumption), clamped on the whole root face,
loaded by a uniform pressure on a small patch of the convex surface (a patch, not
a point, so that the 3-D solution is bounded), deflection read along the tip at
mid-thickness. Units: mm, N, MPa.

This is a plain module used by ``tests/test_compliance_shell.py`` and
``benchmarks/compliance.py``, not a test file.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import skfem
from skfem.helpers import dot
from skfem.models.elasticity import lame_parameters, linear_elasticity

from contact.compliance import ShellModel, ShellTooth, flank_normals, shell_deflection

__all__ = ["FEToothResult", "shell_patch_tip_deflection", "solve_fe_tooth"]


@dataclass(frozen=True, eq=False)
class FEToothResult:
    """FE solution along the tip line.

    theta : (P,) [rad] face angles of the tip nodes (mid-thickness)
    deflection : (P,) [mm/N] displacement along the load direction (−e_r) per
        unit applied force
    n_dofs : number of unknowns; solve_time, total_time : [s]
    """

    theta: np.ndarray
    deflection: np.ndarray
    n_dofs: int
    assemble_time: float
    solve_time: float
    total_time: float


def _grid(n: int, marks: tuple[float, ...]) -> np.ndarray:
    """Uniform grid on [0, 1] with ``n`` cells plus the patch edges ``marks``.

    Uniform nodes closer than 0.3 cell to a mark are dropped (no slivers).
    """
    uni = np.linspace(0.0, 1.0, n + 1)
    m = np.asarray(marks, dtype=float)
    near = np.min(np.abs(uni[:, None] - m[None, :]), axis=1) < 0.3 / n
    near[[0, -1]] = False
    return np.union1d(uni[~near], m)


def _map_to_tooth(tooth: ShellTooth, unit: np.ndarray) -> np.ndarray:
    """Map unit-box points (s, f, ζ) to Cartesian points of the shell tooth.

    θ = f Θ₀, x = s h(θ), z = (ζ − ½) t(x, θ); the cylinder axis is Z, the
    mid-face radial direction is X, and the mid-surface at mid-face is at X = 0.
    """
    s, f, zeta = unit
    th = f * tooth.subtended_angle
    x = s * tooth.height(th)
    z = (zeta - 0.5) * tooth.thickness(x, th)
    phi = th - 0.5 * tooth.subtended_angle
    r = tooth.radius + z
    return np.vstack([r * np.cos(phi) - tooth.radius, r * np.sin(phi), x])


def solve_fe_tooth(
    tooth: ShellTooth,
    *,
    load_fraction: tuple[float, float] = (0.5, 0.5),
    patch_fraction: tuple[float, float] = (0.1, 0.06),
    n_height: int = 6,
    n_face: int = 16,
    n_thick: int = 2,
) -> FEToothResult:
    """Solve the 3-D FE tooth under a unit patch load on the convex surface.

    Parameters
    ----------
    tooth : ShellTooth
    load_fraction : (profile fraction x/h, face fraction θ/Θ₀) of the patch centre
    patch_fraction : full size of the patch in (profile, face) fractions
    n_height, n_face, n_thick : cells of the structured box mesh; ``n_thick``
        must be even so that a node row lies on the mid-surface

    Returns
    -------
    FEToothResult
        Tip-line deflection along the load per unit force [mm/N].
    """
    if n_thick % 2:
        raise ValueError("n_thick must be even")
    t0 = time.perf_counter()
    (ps, pf), (ds, df) = load_fraction, patch_fraction
    s_marks = (ps - 0.5 * ds, ps + 0.5 * ds)
    f_marks = (pf - 0.5 * df, pf + 0.5 * df)
    unit = skfem.MeshHex.init_tensor(
        _grid(n_height, s_marks), _grid(n_face, f_marks), np.linspace(0.0, 1.0, n_thick + 1)
    )
    p_unit = unit.p.copy()
    mesh = skfem.MeshHex(_map_to_tooth(tooth, p_unit), unit.t)

    elem = skfem.ElementVector(skfem.ElementHex2())
    basis = skfem.Basis(mesh, elem, intorder=4)
    lam, mu = lame_parameters(tooth.youngs_modulus, tooth.poisson_ratio)
    stiffness = skfem.asm(linear_elasticity(lam, mu), basis)

    # patch facets: on the convex surface (ζ = 1) and inside the patch (unit coords)
    fmid = p_unit[:, unit.facets].mean(axis=1)  # (3, nfacets)
    eps = 1e-9
    on_patch = (
        (np.abs(fmid[2] - 1.0) < eps)
        & (fmid[0] > s_marks[0] - eps)
        & (fmid[0] < s_marks[1] + eps)
        & (fmid[1] > f_marks[0] - eps)
        & (fmid[1] < f_marks[1] + eps)
    )
    facets = np.nonzero(on_patch)[0]
    fbasis = skfem.FacetBasis(mesh, elem, facets=facets, intorder=4)
    area = skfem.Functional(lambda w: 1.0 + 0.0 * w.x[0]).assemble(
        skfem.FacetBasis(mesh, skfem.ElementHex1(), facets=facets, intorder=4)
    )

    @skfem.LinearForm
    def pressure(v, w):
        return -dot(w.n, v) / area  # unit total force along −n (into the tooth)

    load = skfem.asm(pressure, fbasis)
    root = basis.get_dofs(lambda x: np.abs(x[2]) < 1e-9).all()
    t1 = time.perf_counter()
    u = skfem.solve(*skfem.condense(stiffness, load, D=root))
    t2 = time.perf_counter()

    tip = np.nonzero((np.abs(p_unit[0] - 1.0) < eps) & (np.abs(p_unit[2] - 0.5) < eps))[0]
    tip = tip[np.argsort(p_unit[1, tip])]
    theta = p_unit[1, tip] * tooth.subtended_angle
    phi = theta - 0.5 * tooth.subtended_angle
    ux = u[basis.nodal_dofs[0, tip]]
    uy = u[basis.nodal_dofs[1, tip]]
    u_r = ux * np.cos(phi) + uy * np.sin(phi)
    return FEToothResult(
        theta=theta,
        deflection=-u_r,
        n_dofs=int(stiffness.shape[0]),
        assemble_time=t1 - t0,
        solve_time=t2 - t1,
        total_time=t2 - t0,
    )


def shell_patch_tip_deflection(
    model: ShellModel,
    theta: np.ndarray,
    *,
    load_fraction: tuple[float, float] = (0.5, 0.5),
    patch_fraction: tuple[float, float] = (0.1, 0.06),
    n_gauss: int = 4,
    on_flank: bool = True,
) -> np.ndarray:
    """Shell-model tip deflection [mm/N] under the same unit patch load as the FE.

    ``on_flank=True``: the load acts along the inward flank normal on the convex
    flank, as the FE pressure does; ``False``: along the shell normal on the
    mid-surface (the seed's idealisation).

    The patch load is the average of unit point loads over a Gauss grid on the
    patch (superposition), uniform in the (profile, face) fractions like the FE
    pressure to within the patch's small curvature.
    """
    tooth = model.tooth
    g, w = np.polynomial.legendre.leggauss(n_gauss)
    (ps, pf), (ds, df) = load_fraction, patch_fraction
    s = ps + 0.5 * ds * g
    f = pf + 0.5 * df * g
    S, F = np.meshgrid(s, f, indexing="ij")
    W = np.outer(w, w).ravel() / 4.0
    loads = np.column_stack([S.ravel(), F.ravel()])
    theta = np.asarray(theta, dtype=float)
    tip = np.column_stack([np.ones_like(theta), theta / tooth.subtended_angle])
    normals = flank_normals(tooth, loads, +1.0, coords="normalised") if on_flank else None
    w_tip = shell_deflection(model, loads, tip, load_normals=normals, coords="normalised")
    # the FE pushes into the convex flank (−n, ≈ −e_z): deflection along the load is −W
    return -(w_tip @ W) if on_flank else w_tip @ W
