"""The shell tooth model's data, and the projection-plane map of a generated tooth.

:class:`ToothModelData` is what :func:`contact.compliance.tooth_measurement.shell_tooth_from_case`
measures on the generated flanks of one tooth of a member (the fitted
:class:`~contact.compliance.shell.ShellTooth` of seed Eq. 3.1, its mid-surface, the virtual
gear of the foundation term); :class:`ShellPoints` are contact points in that model's shell
coordinates. The map from the flank's projection-plane fractions (u, v) to the tooth's
flank angle (the angular position of each flank about the member axis, fitted by Legendre
polynomials) gives the mid-surface, its frames and the orthogonal trajectories the shell
coordinates are measured along (``contact/compliance/tooth.py``'s docstring).
"""

from __future__ import annotations

import functools
import logging
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.polynomial import legendre as leg

from contact.compliance.foundation import (
    ToothFoundation,
)
from contact.compliance.shell import (
    ShellModel,
    ShellTooth,
    build_shell_model,
)
from geometry.core.kernels import kernels_module

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "END_TOLERANCE",
    "N_FACE",
    "N_HEIGHT",
    "RADIUS_SOURCES",
    "SIDES",
    "ShellPoints",
    "ToothModelData",
]

log = logging.getLogger(__name__)


#: the point mapping's compiled kernels (trajectory, projection onto the mid-surface)
KERNEL_MODULE = "contact.compliance.tooth_map_numba"

_TRAJ_STEPS = 4  # RK4 steps along an orthogonal trajectory: error < 2e-8 in u (~1 nm of


#: side code of a flank in the shell frame: convex at z = +t/2, concave at z = −t/2
SIDES: dict[str, int] = {"convex": 1, "concave": -1}


#: Default Ritz modes for generated teeth (height ICF × face IFF). Real teeth are long for
#: their height (tooth length / mean height 4–8 for the example cases, against ~3 for the
#: benchmark tooth of :mod:`contact.compliance.shell`), so a point load needs more face
#: modes: against 3-D FE of the generated teeth (benchmarks/compliance_tooth.py) the tip
#: deflection with 5 × 9 modes is 1–30 % low, with 6 × 21 within −9 … +12 % of the FE and
#: within 3 % of 8 × 30 modes.
N_HEIGHT = 6


N_FACE = 21


#: how :func:`shell_tooth_from_case` chooses the shell radius R: ``"auto"`` — measured for a
#: face-hobbed member (blade_groups ≥ 1), the mean blade point radius for a face-milled one
#: (the seed's choice, kept so that FM results do not change); ``"measured"``, ``"point"``
#: — that one for every member (studies, e.g. the FE comparison of
#: tests/test_compliance_tooth.py)
RADIUS_SOURCES = ("auto", "measured", "point")


#: [1] segment end points may overhang the blank by this fraction of the face width or
#: depth (a discretised contact curve's last segment); they are clipped onto the tooth
END_TOLERANCE = 0.05


# ---------------------------------------------------------------------------------------
# data
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class ToothModelData:
    """Everything the compliance needs about one member's generated tooth.

    Build it with :func:`shell_tooth_from_case`. Lengths [mm], angles [rad].

    Attributes
    ----------
    member : str — ``"pinion"`` or ``"gear"``
    tooth : ShellTooth — the fitted tapered shell (seed Eq. 3.1): thicknesses,
        heights, shell radius R (``radius_source``), Θ₀ = tooth length / R, E, ν
    foundation : ToothFoundation — mid-face virtual spur gear (Sainsot 2004)
    teeth : int — [1] number of teeth z
    concave_shift : int — [1] k: the tooth's concave flank is the reference
        concave flank turned by k · 2π/z about the member axis
    corners : ndarray (2, 2, 2) — [mm] projection-plane corners [u][v] = (z, ρ)
        of the blank (:func:`geometry.machine.flank.blank_outline`)
    angle_coef : ndarray (2, 7, 5) — [rad] Legendre coefficients in (2u − 1, 2v − 1)
        of the angular positions about the member axis of the tooth's convex (0) and
        concave (1) flanks
    arc_table : ndarray (2, K) — ([1], [mm]) face fraction u at mid height and the
        mid-surface arc length from the toe along the mid-height lengthwise curve
        (R θ of the shell)
    fillet_radius : tuple (float, float) — [mm] blade edge radii of the convex and
        concave flanks (the root fillets)
    measured_radius : float — [mm] the measured lengthwise radius of the tooth: its
        mid-height lengthwise length divided by the angle its mid-surface normal turns
        through from toe to heel (:func:`shell_tooth_from_case`, Notes); ``inf`` if the
        normal does not turn (straight tooth) or turns the wrong way
    point_radius : float — [mm] mean point radius of the two blades that cut this
        member's flanks (the seed's shell radius, seed §3.2)
    radius_source : str — ``"measured"`` or ``"point"``: which of the two the shell
        uses (:data:`RADIUS_SOURCES`), i.e. ``tooth.radius``
    lengthwise_radius : ndarray (2, 17) — ([1], [mm]) face fraction u (toe 0 → heel 1)
        at mid height and the LOCAL lengthwise radius 1/κ_n there (κ_n the mid-surface's
        normal curvature along the lengthwise curve; ``inf`` where κ_n ≤ 0)
    radius_spread : tuple (float, float) — [1] min and max over the face of the local
        lengthwise radius relative to ``measured_radius``, minus 1: how far the real
        tooth departs from one circle, a model-error indicator of the circular shell
    mean_spiral_angle : float — [rad] β_m of the tooth's mid-surface at the mean point
    virtual_pitch_radius : float — [mm] r_m / (cos δ cos² β_m), normal-section
        virtual spur gear at mid face
    mean_dedendum : float — [mm] pitch cone to root cone at the mean point
    measured_thickness : ndarray (nu, nv) — [mm] normal thickness measured on the grid
        (NaN where a flank is not generated by its blade's profile section)
    measured_height : ndarray (nu,) — [mm] tooth height along the mid-surface profile
    grid_u, grid_v : ndarray — [1] the measurement grid fractions
    thickness_fit_error : float — [mm] max |measured − fitted| thickness
    height_fit_error : float — [mm] max |measured − fitted| height
    angle_fit_error : float — [rad] max residual of the flank-angle fits
    build_time : float — [s]
    """

    member: str
    tooth: ShellTooth
    foundation: ToothFoundation
    teeth: int
    concave_shift: int
    corners: np.ndarray
    angle_coef: np.ndarray
    arc_table: np.ndarray
    fillet_radius: tuple[float, float]
    measured_radius: float
    point_radius: float
    radius_source: str
    lengthwise_radius: np.ndarray
    radius_spread: tuple[float, float]
    mean_spiral_angle: float
    virtual_pitch_radius: float
    mean_dedendum: float
    measured_thickness: np.ndarray
    measured_height: np.ndarray
    grid_u: np.ndarray
    grid_v: np.ndarray
    thickness_fit_error: float
    height_fit_error: float
    angle_fit_error: float
    build_time: float
    case: Case = field(repr=False)
    _models: dict = field(default_factory=dict, repr=False)

    def face_angle(self, xi: np.ndarray) -> np.ndarray:
        """Shell face angle θ [rad] of the trajectory through face fraction ``xi`` at mid height."""
        return np.interp(xi, self.arc_table[0], self.arc_table[1]) / self.tooth.radius

    def face_fraction(self, theta: np.ndarray) -> np.ndarray:
        """Inverse of :meth:`face_angle`: face fraction at mid height [1] of θ [rad]."""
        return np.interp(np.asarray(theta) * self.tooth.radius, self.arc_table[1],
                         self.arc_table[0])

    @functools.cached_property
    def surface(self) -> Surface:
        """The mid-surface map of :attr:`corners` and :attr:`angle_coef`, prepared once."""
        return make_surface(self.corners, self.angle_coef)

    @property
    def shell_radius(self) -> float:
        """Radius R of the shell's mid-surface [mm] (``tooth.radius``; see ``radius_source``)."""
        return self.tooth.radius

    @property
    def pitch(self) -> float:
        """Angular pitch 2π/z [rad]."""
        return 2.0 * math.pi / self.teeth

    def shell_model(
        self, theory: str = "seed", n_height: int = N_HEIGHT, n_face: int = N_FACE
    ) -> ShellModel:
        """The built, factorised shell model of this tooth, memoised on this object.

        Parameters
        ----------
        theory : str — key of :data:`contact.compliance.shell.THEORIES`
        n_height, n_face : int — [1] Ritz modes (ICF, IFF)

        Returns
        -------
        ShellModel — built once per (theory, n_height, n_face) and reused (seed
            Fig. 3.2: "it is done only once and is valid for all mesh positions")

        Raises
        ------
        InputError, ModelUnavailableError, LTCAError
            As :func:`contact.compliance.shell.build_shell_model`.
        """
        key = (theory, n_height, n_face)
        model = self._models.get(key)
        if model is None:
            model = build_shell_model(self.tooth, n_height, n_face, theory=theory)
            self._models[key] = model
            log.debug("%s shell model %s built in %.3f s", self.member, key, model.build_time)
        return model


class ShellPoints(NamedTuple):
    """Flank points in shell coordinates (result of :func:`shell_coordinates`).

    x : (N,) [mm] height from the root along the tooth; theta : (N,) [rad] face
    angle from the toe; u, v : (N,) [1] projection-plane fractions of the point's foot
    on the mid-surface (v = x/h; u differs from θ/Θ₀ by the spiral's skew);
    normal : (N, 3) [1] outward flank normal on (e_x, e_θ, e_z), or None;
    side : (N,) [1] +1 convex flank, −1 concave flank; offset : (N,) [mm] signed
    distance of the point from the mid-surface along e_z (≈ side · t/2 on a flank);
    frame : (N, 3, 3) [1] rows e_x, e_θ, e_z in the input frame (member or pair).
    """

    x: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    v: np.ndarray
    normal: np.ndarray | None
    side: np.ndarray
    offset: np.ndarray
    frame: np.ndarray


# ---------------------------------------------------------------------------------------
# projection-plane (u, v) map and flank-angle fits
# ---------------------------------------------------------------------------------------
def bilinear(corners: np.ndarray, u: np.ndarray, v: np.ndarray):
    """(z, ρ) and their u- and v-derivatives of the blank's bilinear map.

    ``corners`` (2, 2, 2) [mm], or (P, 2, 2, 2) per point (several members in one batch).
    """
    c = np.asarray(corners)
    if c.ndim == 4:  # per point: c[i, j] is then (P, 2), like u[..., None] * c[i, j]
        c = np.moveaxis(c, 0, 2)
    u = np.asarray(u, dtype=float)[..., None]
    v = np.asarray(v, dtype=float)[..., None]
    p = (1 - u) * (1 - v) * c[0, 0] + u * (1 - v) * c[1, 0] + (1 - u) * v * c[0, 1] \
        + u * v * c[1, 1]
    pu = (1 - v) * (c[1, 0] - c[0, 0]) + v * (c[1, 1] - c[0, 1])
    pv = (1 - u) * (c[0, 1] - c[0, 0]) + u * (c[1, 1] - c[1, 0])
    return p, pu, pv


class Surface(NamedTuple):
    """The tooth's mid-surface map M(u, v), prepared once for fast evaluation.

    The flank-angle fits (Legendre in t_u = 2u − 1, t_v = 2v − 1) and their u- and
    v-derivatives are converted once to power-basis coefficients in (t_u, t_v), so
    that an evaluation at many points is one Vandermonde product and one small matrix
    product (instead of ``legder``/``legvander2d`` per call); the bilinear blank map
    (z, ρ)(u, v) = b₀ + u b_u + v b_v + u v b_uv is kept as its coefficients. The same
    polynomials: results agree with direct Legendre evaluation to round-off
    (~1e-15 rad). Points are evaluated as rows (quantity, point), i.e. flattened.
    """

    z: tuple[float, float, float, float]  # [mm] z: b₀, b_u, b_v, b_uv
    rho: tuple[float, float, float, float]  # [mm] ρ: b₀, b_u, b_v, b_uv
    degree: tuple[int, int]  # [1] power-basis degrees in t_u, t_v
    #: (8, (du+1)(dv+1)) [rad] rows φ, φ_u, φ_v (mid), φ convex, φ concave, φ_uu, φ_uv, φ_vv
    #: (mid); column i (dv+1) + j multiplies t_u^i t_v^j
    power: np.ndarray
    #: None for one tooth; for several teeth evaluated in one batch (:func:`stack_surfaces`)
    #: the point ranges (b₀ = 0, b₁, …, b_M) of each tooth: ``power`` is then (M, 8, …) and
    #: the entries of ``z`` and ``rho`` are per-point arrays (P,)
    bounds: tuple[int, ...] | None = None


def _leg_to_power(n: int) -> np.ndarray:
    """(n, n) matrix L with Σ_k c_k P_k(t) = Σ_j (L c)_j t^j."""
    out = np.zeros((n, n))
    for k in range(n):
        p = leg.leg2poly(np.eye(n)[k])
        out[: p.size, k] = p
    return out


def make_surface(corners: np.ndarray, coef: np.ndarray) -> Surface:
    """Prepare the mid-surface map of blank corners (2, 2, 2) and angle fits (2, nu, nv)."""
    nu_c, nv_c = coef.shape[1:]
    def pad(c: np.ndarray) -> np.ndarray:
        full = np.zeros((nu_c, nv_c))
        full[: c.shape[0], : c.shape[1]] = c
        return full

    cols = []
    for axis in (None, 0, 1):
        for k in range(2):
            cols.append(pad(coef[k] if axis is None else leg.legder(coef[k], scl=2.0,
                                                                    axis=axis)))
    mid = 0.5 * (coef[0] + coef[1])
    d_u = leg.legder(mid, scl=2.0, axis=0)
    # [φ, φ_u, φ_v] of the mid-surface (mean of the flanks), then the two flanks' φ, then
    # the mid-surface's φ_uu, φ_uv, φ_vv (Newton projection, _project_to_mid)
    leg_rows = np.stack([0.5 * (cols[0] + cols[1]), 0.5 * (cols[2] + cols[3]),
                         0.5 * (cols[4] + cols[5]), cols[0], cols[1],
                         pad(leg.legder(d_u, scl=2.0, axis=0)),
                         pad(leg.legder(d_u, scl=2.0, axis=1)),
                         pad(leg.legder(mid, m=2, scl=2.0, axis=1))])
    power = np.einsum("ai,kij,bj->kab", _leg_to_power(nu_c), leg_rows, _leg_to_power(nv_c))
    c = np.asarray(corners, dtype=float)
    b = (c[0, 0], c[1, 0] - c[0, 0], c[0, 1] - c[0, 0], c[1, 1] - c[1, 0] - c[0, 1] + c[0, 0])
    return Surface(z=tuple(float(x[0]) for x in b), rho=tuple(float(x[1]) for x in b),
                    degree=(nu_c - 1, nv_c - 1),
                    power=np.ascontiguousarray(power.reshape(power.shape[0], nu_c * nv_c)))


def angle_rows(surf: Surface, u: np.ndarray, v: np.ndarray, rows: slice) -> np.ndarray:
    """Rows ``rows`` of [φ, φ_u, φ_v, φ_convex, φ_concave] [rad] at 1-D (u, v): (k, N)."""
    du, dv = surf.degree
    t = np.empty((max(du, dv) + 1, 2, u.size))
    t[0] = 1.0
    if t.shape[0] > 1:
        np.subtract(2.0 * u, 1.0, out=t[1, 0])
        np.subtract(2.0 * v, 1.0, out=t[1, 1])
    for k in range(2, t.shape[0]):
        np.multiply(t[k - 1], t[1], out=t[k])
    basis = (t[: du + 1, 0, None, :] * t[None, : dv + 1, 1]).reshape(-1, u.size)
    if surf.bounds is None:
        return surf.power[rows] @ basis
    b = surf.bounds
    return np.concatenate([surf.power[m, rows] @ basis[:, b[m]:b[m + 1]]
                           for m in range(len(b) - 1)], axis=1)


def stack_surfaces(surfs: Sequence[Surface], sizes: Sequence[int]) -> Surface:
    """One :class:`Surface` for several teeth evaluated in one batch of points.

    The first ``sizes[0]`` points belong to ``surfs[0]``, the next ``sizes[1]`` to
    ``surfs[1]`` …: the bilinear-map coefficients become per-point arrays (the same
    arithmetic, so the same results to the last bit) and each tooth's angle polynomials
    multiply its own columns of the basis. The teeth must share the fit degrees.
    """
    if len({sf.degree for sf in surfs}) != 1:
        raise ValueError("surfaces of different fit degrees cannot be stacked")
    b = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
    rep_ = np.repeat(np.arange(len(surfs)), sizes)

    def per_point(vals):
        return tuple(np.asarray(col, dtype=float)[rep_] for col in zip(*vals, strict=True))

    return Surface(z=per_point([sf.z for sf in surfs]),
                    rho=per_point([sf.rho for sf in surfs]), degree=surfs[0].degree,
                    power=np.stack([sf.power for sf in surfs]),
                    bounds=tuple(int(x) for x in b))


def blank_rows(surf: Surface, u: np.ndarray, v: np.ndarray):
    """z, ρ and their u- and v-derivatives of the blank's bilinear map (1-D each)."""
    z0, zu, zv, zuv = surf.z
    r0, ru, rv, ruv = surf.rho
    pu_z, pu_r = zu + zuv * v, ru + ruv * v
    pv_z, pv_r = zv + zuv * u, rv + ruv * u
    return z0 + zu * u + v * pv_z, r0 + ru * u + v * pv_r, pu_z, pu_r, pv_z, pv_r


def projection_step(rho_p, phi_p, pz, z, rho, zu, ru, zv, rv, z_uv, r_uv, phi, fu, fv, fuu,
                    fuv, fvv):
    """The Newton step (Δu, Δv) [1] of the foot of points on the mid-surface
    (:func:`contact.compliance.tooth._project_to_mid`, whose docstring gives the
    gradient and the exact Hessian of |p − M(u, v)|²/2 in cylindrical components).

    Plain arithmetic on floats or broadcastable arrays (the NumPy path's batch; the
    compiled kernel's points, :mod:`contact.compliance.tooth_map_numba`, one by one).

    Parameters
    ----------
    rho_p, phi_p, pz : [mm], [rad], [mm]
        The points in cylindrical coordinates about the member axis.
    z, rho, zu, ru, zv, rv, z_uv, r_uv : [mm]
        The blank map at the iterate and its u-, v- and mixed derivatives
        (:func:`blank_rows`; z_uv, r_uv its coefficients b_uv).
    phi, fu, fv, fuu, fuv, fvv : [rad]
        The mid-surface angle and its derivatives at the iterate (:func:`angle_rows`,
        rows 0, 1, 2, 5, 6, 7).

    Returns
    -------
    (Δu, Δv) : [1]
    """
    d = phi_p - phi
    r_r = rho_p * np.cos(d) - rho
    r_f = rho_p * np.sin(d)
    r_z = pz - z
    rfu, rfv = rho * fu, rho * fv
    g1 = r_r * ru + r_f * rfu + r_z * zu
    g2 = r_r * rv + r_f * rfv + r_z * zv
    a11 = ru * ru + rfu * rfu + zu * zu + r_r * rfu * fu - r_f * (2.0 * ru * fu + rho * fuu)
    a22 = rv * rv + rfv * rfv + zv * zv + r_r * rfv * fv - r_f * (2.0 * rv * fv + rho * fvv)
    a12 = (ru * rv + rfu * rfv + zu * zv - r_r * (r_uv - rfu * fv)
           - r_f * (ru * fv + rv * fu + rho * fuv) - r_z * z_uv)
    det = a11 * a22 - a12 * a12
    return (a22 * g1 - a12 * g2) / det, (a11 * g2 - a12 * g1) / det


def _mid_rows(surf: Surface, u: np.ndarray, v: np.ndarray):
    """M, M_u, M_v at 1-D (u, v) as nine rows (x, y, z components) [mm]."""
    z, rho, pu_z, pu_r, pv_z, pv_r = blank_rows(surf, u, v)
    phi, phi_u, phi_v = angle_rows(surf, u, v, slice(0, 3))
    c, s = np.cos(phi), np.sin(phi)
    rc, rs = rho * c, rho * s
    return (rc, rs, z,
            pu_r * c - rs * phi_u, pu_r * s + rc * phi_u, pu_z,
            pv_r * c - rs * phi_v, pv_r * s + rc * phi_v, pv_z)


def mid_surface(surf: Surface, u: np.ndarray, v: np.ndarray):
    """Mid-surface point M and its tangents M_u, M_v in the member frame (…, 3)."""
    u = np.asarray(u, dtype=float)
    v = np.broadcast_to(np.asarray(v, dtype=float), u.shape)
    r = _mid_rows(surf, u.ravel(), v.ravel())
    shape = (*u.shape, 3)
    return tuple(np.stack(r[k : k + 3], axis=-1).reshape(shape) for k in (0, 3, 6))


def frames(surf: Surface, u: np.ndarray, v: np.ndarray):
    """Mid-surface point and local shell frame (…, 3, 3) rows e_x, e_θ, e_z at (u, v).

    e_z: unit mid-surface normal towards the convex flank; e_θ: unit tangent of the
    lengthwise curve v = const (toe → heel); e_x = ±e_z × e_θ, the in-surface
    direction orthogonal to it (root → tip), i.e. along the shell's generator. The
    handedness of (e_x, e_θ, e_z) follows the member's hand; the shell model only
    needs the components along these directions.
    """
    u = np.asarray(u, dtype=float)
    v = np.broadcast_to(np.asarray(v, dtype=float), u.shape)
    m, mu, mv = mid_surface(surf, u, v)
    n = np.cross(mu, mv)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    ang = angle_rows(surf, u.ravel(), v.ravel(), slice(3, 5))  # convex, concave φ
    cvx, ccv = ang[0].reshape(u.shape), ang[1].reshape(u.shape)
    # towards the convex flank: the convex flank lies at angle cvx > or < ccv
    phi = 0.5 * (cvx + ccv)
    e_phi = np.stack([-np.sin(phi), np.cos(phi), np.zeros_like(phi)], axis=-1)
    sgn = np.sign(np.sum(n * e_phi, axis=-1) * (cvx - ccv))
    e_z = n * sgn[..., None]
    e_t = mu / np.linalg.norm(mu, axis=-1, keepdims=True)
    e_x = np.cross(e_z, e_t)
    e_x *= np.sign(np.sum(e_x * mv, axis=-1))[..., None]
    return m, np.stack([e_x, e_t, e_z], axis=-2)


def trajectory(surf: Surface, u, v0, v1) -> np.ndarray:
    """u at profile fraction v1 on the orthogonal trajectory through (u, v0) (RK4).

    The classical RK4 scheme with :data:`_TRAJ_STEPS` steps in v on the slope
    du/dv = −(M_u·M_v)/(M_u·M_u) of the mid-surface M = (ρ cos φ, ρ sin φ, z) (the
    rotation terms cancel: M_u·M_v = p_u·p_v + ρ² φ_u φ_v, |M_u|² = |p_u|² + ρ² φ_u²,
    p = (z, ρ) the blank map); the RK4 stages sit at the 2·steps + 1
    profile fractions v0 + k h/2, known in advance, so every v-dependent part of the
    slope (blank-map terms, and the angle polynomials' coefficients of t_u^i) is
    evaluated once for all stages; a stage then costs one polynomial in t_u. Same
    result to round-off (~1e-16).
    """
    u = np.asarray(u, dtype=float)
    shape = u.shape
    u = u.ravel().copy()
    n_pts = u.size
    v0 = np.broadcast_to(np.asarray(v0, dtype=float), shape).ravel()
    kernels = kernels_module(KERNEL_MODULE)
    if kernels is not None:  # the same scheme point by point, compiled
        v1f = np.ascontiguousarray(np.broadcast_to(np.asarray(v1, dtype=float), shape).ravel())
        # (writable arrays: a read-only one, e.g. a broadcast view, would compile and load
        # a second specialisation of the kernel in every process)
        return kernels.trajectory(u, np.require(v0, requirements=["C", "W"]), v1f,
                                  *kernel_surface(surf, n_pts), *surf.degree,
                                  _TRAJ_STEPS).reshape(shape)
    h = (np.broadcast_to(np.asarray(v1, dtype=float), shape).ravel() - v0) / _TRAJ_STEPS
    h2 = 0.5 * h
    h6 = h / 6.0
    du, dv = surf.degree
    r0, ru, rv, r_uv = surf.rho
    _, zu, zv, z_uv = surf.z
    levels = v0[None, :] + np.arange(2 * _TRAJ_STEPS + 1)[:, None] * h2[None, :]  # (L, P)
    tv = 2.0 * levels - 1.0
    tvp = np.empty((dv + 1, *tv.shape))
    tvp[0] = 1.0
    for j in range(1, dv + 1):
        np.multiply(tvp[j - 1], tv, out=tvp[j])
    # q[k, i, l, p] = Σ_j c[k][i, j] t_v^j: coefficients of t_u^i of φ_u (k=0), φ_v (k=1)
    if surf.bounds is None:
        q = (surf.power[1:3].reshape(2 * (du + 1), dv + 1) @ tvp.reshape(dv + 1, -1))
        q = q.reshape(2, du + 1, *tv.shape)
    else:
        b = surf.bounds
        q = np.concatenate([
            (surf.power[m, 1:3].reshape(2 * (du + 1), dv + 1)
             @ tvp[:, :, b[m]:b[m + 1]].reshape(dv + 1, -1)).reshape(2, du + 1, tv.shape[0], -1)
            for m in range(len(b) - 1)], axis=3)
    # q[:, :, l] is level l's (2, du + 1, P) block: a view (contiguous along the points)
    pu_z = zu + z_uv * levels  # z_u, ρ_u at each level (L, P)
    pu_r = ru + r_uv * levels
    pu2 = pu_z * pu_z + pu_r * pu_r
    rho0 = r0 + rv * levels  # ρ = rho0 + ρ_u u
    tup = np.empty((du + 1, n_pts))
    tup[0] = 1.0

    def slope(uu: np.ndarray, lv: int) -> np.ndarray:
        tu = 2.0 * uu - 1.0
        if du:
            np.cumprod(np.broadcast_to(tu, (du, n_pts)), axis=0, out=tup[1:])
        phi_u, phi_v = (q[:, :, lv] * tup).sum(axis=1)
        rho = rho0[lv] + pu_r[lv] * uu
        rfu = rho * rho * phi_u
        return -(pu_z[lv] * (zv + z_uv * uu) + pu_r[lv] * (rv + r_uv * uu) + rfu * phi_v) / (
            pu2[lv] + rfu * phi_u)

    for step in range(_TRAJ_STEPS):
        lv = 2 * step
        k1 = slope(u, lv)
        k2 = slope(u + h2 * k1, lv + 1)
        k3 = slope(u + h2 * k2, lv + 1)
        k4 = slope(u + h * k3, lv + 2)
        u = u + h6 * (k1 + 2.0 * (k2 + k3) + k4)
    return u.reshape(shape)


def kernel_surface(surf: Surface, n_pts: int):
    """A :class:`Surface` as the compiled kernels take it (:mod:`contact.compliance.
    tooth_map_numba`) for ``n_pts`` points: the blank map's coefficients per point z, ρ (4,
    P) [mm], the teeth's angle polynomials (M, 8, ·) [rad] and each point's tooth (P,)."""
    if surf.bounds is None:
        z = np.repeat(np.array(surf.z, dtype=float)[:, None], n_pts, axis=1)
        rho = np.repeat(np.array(surf.rho, dtype=float)[:, None], n_pts, axis=1)
        return z, rho, surf.power[None], np.zeros(n_pts, dtype=np.int64)
    b = np.asarray(surf.bounds)
    member = np.repeat(np.arange(b.size - 1, dtype=np.int64), np.diff(b))
    return (np.stack([np.asarray(c, dtype=float) for c in surf.z]),
            np.stack([np.asarray(c, dtype=float) for c in surf.rho]),
            np.ascontiguousarray(surf.power), member)


def rot_z(angle: np.ndarray, vec: np.ndarray) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * vec[..., 0] - s * vec[..., 1], s * vec[..., 0] + c * vec[..., 1],
                     vec[..., 2]], axis=-1)
