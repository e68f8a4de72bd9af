"""The shell compliance model of a GENERATED tooth: dimensions, coordinates, normals.

Connects the Rayleigh–Ritz shell of :mod:`contact.compliance.shell` (seed §3.2,
Eq. 3.1–3.11) to the tooth surfaces that :mod:`geometry.machine.flank` generates from the
machine settings, so that the LTCA can build the compliance of real contact
segments. Per member it measures, on the generated flanks of one tooth,

* the normal tooth thickness across the tooth and the tooth height along the
  profile, and fits them by the linear two-variable thickness function and the
  linear height function of seed Eq. 3.1 → a :class:`~contact.compliance.shell.ShellTooth`;
* the tooth mid-surface and, at every point of the tooth, the local shell frame
  (e_x along the height root → tip, e_θ along the face toe → heel, e_z the
  mid-surface normal towards the convex flank) in which the real flank normals
  are expressed for :func:`~contact.compliance.shell.compliance_matrix`;
* the mid-face virtual spur gear of the Sainsot foundation term
  (:class:`~contact.compliance.foundation.ToothFoundation`) and the Weber depth.

One tooth
---------
Both reference flanks of a member are generated in its own frame (z along the
member axis, reference slot near +x). The tooth's material lies on the side of
the convex flank opposite to its outward normal; the concave flank that bounds
the same tooth is the reference concave flank turned by k pitches 2π/z about the
member axis, k ∈ {−1, 0, 1} chosen so that it lies on the material side within
one pitch. For the example cases this gives k = 0 for the pinions (their two
reference flanks bound a tooth) and k = ±1 for the Formate gears (theirs bound a
slot), as the geometry engineers said — found, not assumed.

Shell coordinates
-----------------
A point of the tooth is turned about the member axis by whole pitches onto the
reference tooth and projected along the mid-surface normal onto the tooth's
mid-surface (the shell's z = 0); its foot is located by the blank's bilinear
projection-plane fractions (u, v) of :func:`geometry.machine.flank.projection_grid` (u toe
→ heel, v root cone → face cone). Then

    θ = (arc length from the toe, along the mid-height lengthwise curve, of the
         mid-surface curve orthogonal to the lengthwise curves through the foot) / R
    x = v h(θ)

i.e. the shell's generators (θ = const) are the real mid-surface's curves
orthogonal to its lengthwise curves, and its face angle measures arc length along
the tooth. The offset of the point from the mid-surface along e_z is ≈ ±t/2 on a
flank. Every tooth maps to the same shell.

Shell radius
------------
The shell is a circular cylinder of radius R (seed §3.2: the cutter radius r_c).
For a face-milled (FM) member R is the mean point radius of the two blades, as the
seed takes it. For a face-hobbed (FH) member (``blade_groups`` ≥ 1) the lengthwise
curve is an extended epicycloid, not a circle of the cutter radius (seed future work
(iii); design note ``FACE_HOBBING.md`` §6), and R is MEASURED: the mid-surface's
normal curvature along its mid-height lengthwise curve, averaged over the arc length
from toe to heel (:func:`shell_tooth_from_case`, Notes). The measurement is made for
every member and reported (``measured_radius``, ``lengthwise_radius``,
``radius_spread``), so the two choices can be compared.

Public API
----------
ToothModelData         frozen dataclass: the fitted ShellTooth, foundation, frames
ShellPoints            shell coordinates, local normals and frames of flank points
shell_tooth_from_case  measure and fit one member's tooth (seed Eq. 3.1)
shell_coordinates      member/pair-frame points and normals → shell coordinates
flank_points           shell coordinates → points on the generated flanks (inverse)
weber_depth            contact-to-centreline distance for Weber's formula
member_foundation      Sainsot coupling matrix of loads on one tooth
member_compliance      N×N bending/shear compliance of points on one tooth
"""

from __future__ import annotations

import functools
import logging
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.polynomial import legendre as leg

from contact.compliance.foundation import (
    ToothFoundation,
    foundation_matrix,
    load_angle_from_normals,
    load_line_height,
)
from contact.compliance.shell import (
    ComplianceMatrix,
    ShellModel,
    ShellTooth,
    build_shell_model,
    compliance_blocks,
)
from contact.compliance.shell import as_points as as_shell_points
from geometry.core.errors import InputError, LTCAError
from geometry.core.hertz import STEEL
from geometry.core.validation import integer, positive, real, real_array
from geometry.machine.cutter import working_sections
from geometry.machine.flank import blank_outline, flank_surface, projection_fractions
from geometry.machine.meshing import solve_envelope

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
    "flank_points",
    "member_compliance",
    "member_foundation",
    "shell_coordinates",
    "shell_tooth_from_case",
    "weber_depth",
]

log = logging.getLogger(__name__)

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

_MIRROR = np.array([1.0, -1.0, 1.0])  # left hand = mirror y → −y (geometry.machine.flank)
_FIT_DEGREE = (6, 4)  # Legendre degrees in (u, v) of the flank-angle fits
_TRAJ_STEPS = 4  # RK4 steps along an orthogonal trajectory: error < 2e-8 in u (~1 nm of
#                  face width; the seed case's compliance moves by < 1e-9 relative, the LTE
#                  by < 1e-6 µrad against 8 steps)
_REF_V = 0.5  # the shell's face angle is measured along the mid-height lengthwise curve
_ARC_MARGIN = 0.3  # the arc-length table extends this far beyond the toe and heel
_ARC_POINTS = 801
_TURN_POINTS = 24  # Gauss points (in u) of the normal's turning along the lengthwise curve
_LOCAL_POINTS = 17  # local lengthwise radii reported at face fractions 0, 1/16, …, 1
_PROJ_ITER = 30


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
    def surface(self) -> _Surface:
        """The mid-surface map of :attr:`corners` and :attr:`angle_coef`, prepared once."""
        return _make_surface(self.corners, self.angle_coef)

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
def _bilinear(corners: np.ndarray, u: np.ndarray, v: np.ndarray):
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


class _Surface(NamedTuple):
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
    #: None for one tooth; for several teeth evaluated in one batch (:func:`_stack_surfaces`)
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


def _make_surface(corners: np.ndarray, coef: np.ndarray) -> _Surface:
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
    return _Surface(z=tuple(float(x[0]) for x in b), rho=tuple(float(x[1]) for x in b),
                    degree=(nu_c - 1, nv_c - 1),
                    power=np.ascontiguousarray(power.reshape(power.shape[0], nu_c * nv_c)))


def _angle_rows(surf: _Surface, u: np.ndarray, v: np.ndarray, rows: slice) -> np.ndarray:
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


def _stack_surfaces(surfs: Sequence[_Surface], sizes: Sequence[int]) -> _Surface:
    """One :class:`_Surface` for several teeth evaluated in one batch of points.

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

    return _Surface(z=per_point([sf.z for sf in surfs]),
                    rho=per_point([sf.rho for sf in surfs]), degree=surfs[0].degree,
                    power=np.stack([sf.power for sf in surfs]),
                    bounds=tuple(int(x) for x in b))


def _blank_rows(surf: _Surface, u: np.ndarray, v: np.ndarray):
    """z, ρ and their u- and v-derivatives of the blank's bilinear map (1-D each)."""
    z0, zu, zv, zuv = surf.z
    r0, ru, rv, ruv = surf.rho
    pu_z, pu_r = zu + zuv * v, ru + ruv * v
    pv_z, pv_r = zv + zuv * u, rv + ruv * u
    return z0 + zu * u + v * pv_z, r0 + ru * u + v * pv_r, pu_z, pu_r, pv_z, pv_r


def _mid_rows(surf: _Surface, u: np.ndarray, v: np.ndarray):
    """M, M_u, M_v at 1-D (u, v) as nine rows (x, y, z components) [mm]."""
    z, rho, pu_z, pu_r, pv_z, pv_r = _blank_rows(surf, u, v)
    phi, phi_u, phi_v = _angle_rows(surf, u, v, slice(0, 3))
    c, s = np.cos(phi), np.sin(phi)
    rc, rs = rho * c, rho * s
    return (rc, rs, z,
            pu_r * c - rs * phi_u, pu_r * s + rc * phi_u, pu_z,
            pv_r * c - rs * phi_v, pv_r * s + rc * phi_v, pv_z)


def _mid_surface(surf: _Surface, u: np.ndarray, v: np.ndarray):
    """Mid-surface point M and its tangents M_u, M_v in the member frame (…, 3)."""
    u = np.asarray(u, dtype=float)
    v = np.broadcast_to(np.asarray(v, dtype=float), u.shape)
    r = _mid_rows(surf, u.ravel(), v.ravel())
    shape = (*u.shape, 3)
    return tuple(np.stack(r[k : k + 3], axis=-1).reshape(shape) for k in (0, 3, 6))


def _frames(surf: _Surface, u: np.ndarray, v: np.ndarray):
    """Mid-surface point and local shell frame (…, 3, 3) rows e_x, e_θ, e_z at (u, v).

    e_z: unit mid-surface normal towards the convex flank; e_θ: unit tangent of the
    lengthwise curve v = const (toe → heel); e_x = ±e_z × e_θ, the in-surface
    direction orthogonal to it (root → tip), i.e. along the shell's generator. The
    handedness of (e_x, e_θ, e_z) follows the member's hand; the shell model only
    needs the components along these directions.
    """
    u = np.asarray(u, dtype=float)
    v = np.broadcast_to(np.asarray(v, dtype=float), u.shape)
    m, mu, mv = _mid_surface(surf, u, v)
    n = np.cross(mu, mv)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    ang = _angle_rows(surf, u.ravel(), v.ravel(), slice(3, 5))  # convex, concave φ
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


def _trajectory(surf: _Surface, u, v0, v1) -> np.ndarray:
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


def _rot_z(angle: np.ndarray, vec: np.ndarray) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * vec[..., 0] - s * vec[..., 1], s * vec[..., 0] + c * vec[..., 1],
                     vec[..., 2]], axis=-1)


# ---------------------------------------------------------------------------------------
# measurement and fit (seed Eq. 3.1)
# ---------------------------------------------------------------------------------------
class _ToothFlanks(NamedTuple):
    """Both flanks of one tooth on the same (u, v) grid (member frame)."""

    u: np.ndarray  # (nu,) [1]
    v: np.ndarray  # (nv,) [1]
    convex: np.ndarray  # (nu, nv, 3) [mm]
    concave: np.ndarray  # (nu, nv, 3) [mm], turned onto the tooth
    phi: tuple[np.ndarray, np.ndarray]  # angles about the member axis [rad], continuous
    ok: tuple[np.ndarray, np.ndarray]  # generated by the blades' working sections
    shift: int  # pitches the reference concave flank is turned by


def _tooth_flanks(case: Case, member: str, nu: int, nv: int) -> _ToothFlanks:
    """Both flanks on the same (u, v) grid, the concave one turned onto the tooth."""
    mem = case.member(member)
    cvx = flank_surface(case, member, "convex", nu=nu, nv=nv, v_limits=(0.0, 1.0))
    ccv = flank_surface(case, member, "concave", nu=nu, nv=nv, v_limits=(0.0, 1.0))
    # the blades' working sections: the profile and its relief lines (not the fillet)
    work = {f: working_sections(mem.flank(f).blade) for f in SIDES}
    ok_v = cvx.valid & np.isin(cvx.section, work["convex"])
    ok_c = ccv.valid & np.isin(ccv.section, work["concave"])
    both = ok_v & ok_c
    if both.sum() < 12:
        raise LTCAError(
            f"{member}: only {int(both.sum())} grid points are generated on both flanks by "
            "the blades' working sections; cannot measure the tooth")
    pitch = 2.0 * math.pi / mem.blank.teeth
    phi_v = np.arctan2(cvx.position[..., 1], cvx.position[..., 0])
    phi_c = np.arctan2(ccv.position[..., 1], ccv.position[..., 0])
    # the material is on the side of the convex flank opposite to its outward normal;
    # the tooth's concave flank is the one within a pitch on that side
    idx = tuple(np.argwhere(both)[int(both.sum()) // 2])
    p, n = cvx.position[idx], cvx.normal[idx]
    e_phi = np.array([-p[1], p[0], 0.0]) / math.hypot(p[0], p[1])
    material = -math.copysign(1.0, float(n @ e_phi))
    gap = math.remainder(float(phi_c[idx] - phi_v[idx]), 2.0 * math.pi)
    shifts = [k for k in (-1, 0, 1) if 0.0 < material * (gap + k * pitch) < pitch]
    if len(shifts) != 1:
        raise LTCAError(f"{member}: cannot find the concave flank that bounds the tooth")
    k = shifts[0]
    # angles continuous over the grid, within ±π of the reference point's (a tooth
    # turns by well under π about the member axis from toe to heel)
    ref = float(phi_v[idx])
    phi_v = ref + np.remainder(phi_v - ref + math.pi, 2 * math.pi) - math.pi
    phi_c = ref + np.remainder(phi_c + k * pitch - ref + math.pi, 2 * math.pi) - math.pi
    return _ToothFlanks(u=cvx.grid.u, v=cvx.grid.v, convex=cvx.position,
                        concave=_rot_z(np.full(phi_c.shape, k * pitch), ccv.position),
                        phi=(phi_v, phi_c), ok=(ok_v, ok_c), shift=k)


def _fit_angles(u, v, phi, ok) -> tuple[np.ndarray, float]:
    uu, vv = np.meshgrid(u, v, indexing="ij")
    a = leg.legvander2d(2 * uu[ok] - 1, 2 * vv[ok] - 1, _FIT_DEGREE)
    coef, *_ = np.linalg.lstsq(a, phi[ok], rcond=None)
    resid = float(np.max(np.abs(a @ coef - phi[ok])))
    return coef.reshape(_FIT_DEGREE[0] + 1, _FIT_DEGREE[1] + 1), resid


def _gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    t, w = leg.leggauss(n)
    return 0.5 * (t + 1.0), 0.5 * w


def _arc_table(surf: _Surface) -> tuple[np.ndarray, float]:
    """Arc length [mm] from the toe along the mid-height lengthwise curve vs u; its length."""
    xi = np.linspace(-_ARC_MARGIN, 1.0 + _ARC_MARGIN, _ARC_POINTS)
    _, mu, _ = _mid_surface(surf, xi, np.full_like(xi, _REF_V))
    speed = np.linalg.norm(mu, axis=-1)
    arc = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(xi))])
    arc -= np.interp(0.0, xi, arc)
    return np.stack([xi, arc]), float(np.interp(1.0, xi, arc))


def _lengthwise_curvature(surf: _Surface, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Normal curvature κ_n [1/mm] of the mid-surface along its mid-height lengthwise curve
    at face fractions u (1-D), positive when the curve bends away from the convex flank
    (as a circular shell's lengthwise circle, whose centre lies on the concave side), and
    the speed |M_u| [mm].

    κ_n = −M_uu·e_z / |M_u|² with M = ρ e_ρ(φ) + z e_z (ρ, z bilinear in (u, v), so
    ρ_uu = z_uu = 0): M_uu = (2 ρ_u φ_u + ρ φ_uu) e_φ − ρ φ_u² e_ρ.
    """
    v = np.full_like(u, _REF_V)
    _, rho, _, ru, _, _ = _blank_rows(surf, u, v)
    phi, fu, fuu = _angle_rows(surf, u, v, slice(None))[[0, 1, 5]]
    c, s = np.cos(phi), np.sin(phi)
    a_phi, a_rho = 2.0 * ru * fu + rho * fuu, -rho * fu * fu
    m_uu = np.stack([a_rho * c - a_phi * s, a_rho * s + a_phi * c, np.zeros_like(u)], axis=-1)
    _, mu, _ = _mid_surface(surf, u, v)
    _, frame = _frames(surf, u, v)
    speed2 = np.sum(mu * mu, axis=-1)
    return -np.sum(m_uu * frame[:, 2, :], axis=-1) / speed2, np.sqrt(speed2)


def _lengthwise_radius(surf: _Surface, length: float):
    """Measured lengthwise radius [mm], the local radii (2, K) and their spread (see
    :class:`ToothModelData`; :func:`shell_tooth_from_case`, Notes)."""
    ug, wg = _gauss01(_TURN_POINTS)
    kappa, speed = _lengthwise_curvature(surf, ug)
    turn = float(np.sum(wg * kappa * speed))  # [rad] ∫ κ_n ds over the face
    measured = length / turn if turn > 0.0 else math.inf
    ul = np.linspace(0.0, 1.0, _LOCAL_POINTS)
    kl, _ = _lengthwise_curvature(surf, ul)
    with np.errstate(divide="ignore"):
        local = np.where(kl > 0.0, 1.0 / kl, math.inf)
    rel = local / measured - 1.0 if math.isfinite(measured) else np.full_like(local, np.nan)
    return measured, np.stack([ul, local]), (float(np.min(rel)), float(np.max(rel)))


def _fit_thickness(surf: _Surface, fl: _ToothFlanks, table: np.ndarray, length: float):
    """Measured normal thickness on the grid and its least-squares fit (seed Eq. 3.1a)."""
    both = fl.ok[0] & fl.ok[1]
    uu, vv = np.meshgrid(fl.u, fl.v, indexing="ij")
    _, frame = _frames(surf, uu, vv)
    t_meas = np.abs(np.sum((fl.convex - fl.concave) * frame[..., 2, :], axis=-1))
    t_meas = np.where(both, t_meas, np.nan)
    # face fraction s = θ/Θ₀ of each grid point, through its orthogonal trajectory
    ss = np.interp(_trajectory(surf, uu, vv, _REF_V), table[0], table[1]) / length
    a = np.column_stack([((1 - ss) * (1 - vv))[both], (ss * (1 - vv))[both], vv[both]])
    fit, *_ = np.linalg.lstsq(a, t_meas[both], rcond=None)
    return fit, t_meas, float(np.max(np.abs(a @ fit - t_meas[both])))


def _fit_heights(surf: _Surface, table: np.ndarray, length: float, n: int):
    """Lengths of the orthogonal trajectories root cone → face cone, and their linear fit."""
    s = np.linspace(0.0, 1.0, n)
    xi = np.interp(s * length, table[1], table[0])
    vg, wg = _gauss01(12)
    vv = np.broadcast_to(vg, (n, vg.size))
    ug = _trajectory(surf, np.broadcast_to(xi[:, None], vv.shape), _REF_V, vv)
    _, mu, mv = _mid_surface(surf, ug, vv)
    # the trajectory's tangent: M_v minus its part along the lengthwise tangent M_u
    tangent = mv - (np.sum(mu * mv, axis=-1) / np.sum(mu * mu, axis=-1))[..., None] * mu
    h_meas = np.linalg.norm(tangent, axis=-1) @ wg
    a = np.column_stack([1 - s, s])
    fit, *_ = np.linalg.lstsq(a, h_meas, rcond=None)
    return fit, h_meas, float(np.max(np.abs(a @ fit - h_meas)))


class _VirtualGear(NamedTuple):
    foundation: ToothFoundation
    spiral_angle: float  # [rad]
    pitch_radius: float  # [mm]
    dedendum: float  # [mm]


def _virtual_gear(member: str, blank, corners, surf: _Surface, blades, t_root: float, length: float,
                  bore_radius: float | None, youngs_modulus: float) -> _VirtualGear:
    """Mid-face normal-section virtual spur gear for the Sainsot foundation."""
    zm, pm = blank_outline(blank).mean_point
    um, vm = projection_fractions(corners, np.array([zm]), np.array([pm]))
    mpt, mu_m, _ = _mid_surface(surf, um, vm)
    d = blank.pitch_angle
    e_r = np.array([mpt[0, 0], mpt[0, 1], 0.0]) / math.hypot(mpt[0, 0], mpt[0, 1])
    gen = math.sin(d) * e_r + math.cos(d) * np.array([0.0, 0.0, 1.0])
    e_t = np.cross([0.0, 0.0, 1.0], e_r)
    beta = math.atan2(abs(float(mu_m[0] @ e_t)), abs(float(mu_m[0] @ gen)))
    # mean dedendum: from the mean point along the pitch-cone normal to the root cone
    root_dir = np.array([math.cos(blank.root_angle), math.sin(blank.root_angle)])
    perp = np.array([-math.sin(d), math.cos(d)])
    s_perp, _ = np.linalg.solve(np.column_stack([perp, -root_dir]),
                                np.array([-blank.root_apex - zm, -pm]))
    h_fm = float(-s_perp)
    scale = 1.0 / (math.cos(d) * math.cos(beta) ** 2)
    r_vn = float(pm) * scale
    r_root = r_vn - h_fm
    r_root_real = float(pm) - h_fm * math.cos(d)
    fillet = sum(b.edge_radius * math.tan(0.25 * math.pi - 0.5 * b.blade_angle)
                 for b in blades.values())
    if bore_radius is None:
        bore = 0.5 * r_root_real
        log.info("%s: bore radius not given, using half the mean root radius: %.3f mm",
                 member, bore)
    else:
        # below the mean root radius
        bore = real("bore_radius", bore_radius, unit="mm", low=0.0, high=r_root_real,
                    low_open=True, high_open=True)
    foundation = ToothFoundation(root_radius=r_root, inner_radius=bore * scale,
                                 root_half_angle=(t_root + fillet) / (2.0 * r_root),
                                 face_width=length, youngs_modulus=youngs_modulus)
    return _VirtualGear(foundation, beta, r_vn, h_fm)


def shell_tooth_from_case(
    case: Case,
    member: str,
    *,
    youngs_modulus: float = STEEL[0],
    poisson_ratio: float = STEEL[1],
    bore_radius: float | None = None,
    nu: int = 17,
    nv: int = 11,
    radius_source: str = "auto",
) -> ToothModelData:
    """Measure one member's generated tooth and fit the shell of seed Eq. 3.1.

    Parameters
    ----------
    case : geometry.case.Case — a loaded case (face milling or face hobbing)
    member : str — ``"pinion"`` or ``"gear"``
    youngs_modulus : float — [MPa] E of the member's material
    poisson_ratio : float — [1] ν, in [0, 0.5)
    bore_radius : float, optional — [mm] radius of the member's bore (the inner
        boundary of the gear body under the teeth), used for the Sainsot foundation;
        default half the mean root radius of the member (logged), since case files
        do not give it
    nu, nv : int — [1] measurement grid over the flank, lengthwise × profile
        (toe → heel, root cone → face cone), 5–200 and 4–200
    radius_source : str — one of :data:`RADIUS_SOURCES`: ``"auto"`` (default) the
        measured lengthwise radius for a face-hobbed member (``blade_groups`` ≥ 1),
        the mean blade point radius for a face-milled one; ``"measured"`` or
        ``"point"`` that one for either process (for studies)

    Returns
    -------
    ToothModelData
        The fitted :class:`ShellTooth` (shell radius R by ``radius_source``;
        Θ₀ = tooth length / R), the measured lengthwise radius and its spread, the
        foundation and the frame data.

    Raises
    ------
    InputError
        Bad member name, material constants, grid sizes or radius source.
    LTCAError
        The flanks do not overlap enough to measure a tooth, the fitted
        dimensions are not physical (non-positive thickness or height), or the
        measured radius is wanted but the mid-surface does not curve lengthwise
        (its normal does not turn, or turns the wrong way, from toe to heel).

    Notes
    -----
    Seed §3.2, Eq. 3.1 and Fig. 3.1–3.2 ("tooth thickness and height
    calculation", "fit a linear function to tooth thickness and height"). The
    extraction loses Eq. 3.1; we use the reconstruction of
    :class:`~contact.compliance.shell.ShellTooth` (root thickness linear from toe
    to heel, constant tip thickness, linear in between; height linear toe → heel)
    and fit its parameters by least squares, which is linear in them:

    * normal thickness t at every grid point where both flanks are generated by
      the blades' profile sections (edge-radius fillets excluded): the chord
      between the two flanks at the same projection-plane place projected on the
      mid-surface normal, t = |(P_convex − P_concave) · e_z|; fitted by
      t = [t_toe (1 − s) + t_heel s] (1 − v) + t_tip v, with v = x/h the profile
      fraction and s = θ/Θ₀ the face fraction of the point's shell coordinates
      (:func:`shell_coordinates`);
    * height h(s): the length of the mid-surface curve orthogonal to the
      lengthwise curves (the shell's generator) from the root cone to the face
      cone; fitted by h = h_toe (1 − s) + h_heel s;
    * tooth length = the mid-surface arc from toe to heel along the mid-height
      lengthwise curve (along the spiral, not the face width b along the pitch
      cone, which is shorter by ~cos β_m); Θ₀ = length / R.

    The mid-surface M(u, v) lies midway (in angle about the member axis) between
    the flanks at each projection-plane place; the flank angles are fitted by
    Legendre polynomials of degree (6, 4) in (u, v) (residual ~1e-7 rad for the
    Formate gears, ~2e-4 rad for the generated pinions), which also extrapolate
    the gear's mid-surface into the root region that the flank grid does not reach
    (fillets). The seed's linear thickness cannot follow a generated pinion's
    curved profile nor a topland that narrows toe → heel; the least-squares misfit
    is kept in ``thickness_fit_error`` (0.05–0.95 mm for the example cases).

    Sainsot foundation (:class:`~contact.compliance.foundation.ToothFoundation`), our
    reading of "base rotation … by an interpolation method" (seed p. 78, whose
    Stegemiller tables are not published): the mid-face normal-section virtual
    spur gear, r_vn = r_m / (cos δ cos² β_m) (Tredgold's approximation and the
    normal section of a helical gear, as ISO 10300-1 builds the virtual gear), root
    radius r_f = r_vn − h_fm, inner radius r_int = r_bore / (cos δ cos² β_m) (the
    bore seen along the back cone in the same section), root thickness
    S_f = t_root(mid face) + Σ r_e tan(π/4 − α/2) — the fitted flank thickness at
    the root plus what each root fillet of radius r_e (the blade edge radius, blade
    angle α) adds at the root line — θ_f = S_f / (2 r_f), face width = the tooth
    length.

    Shell radius (seed §3.2 takes R = r_c, the cutter radius, for face milling and
    face hobbing alike; seed future work (iii) asks for a shell with the epicycloidal
    traces of face hobbing; design note ``FACE_HOBBING.md`` §6 keeps the circular
    shell and measures its radius). The lengthwise circles of the circular shell are
    lines of curvature of its cylinder: normal curvature 1/R, no geodesic curvature.
    On the real mid-surface, along the mid-height lengthwise curve (the curve the
    shell's face angle is measured on, ``arc_table``), the normal curvature
    κ_n(s) = −M_ss·e_z is integrated over the arc length s (24-point Gauss in u):
    Θ_turn = ∫ κ_n ds is the angle the mid-surface normal turns through from toe to
    heel, and the measured radius is R = L / Θ_turn (L the curve's length). So the
    shell subtends the real tooth's turning, Θ₀ = L/R = Θ_turn, and 1/R is the
    arc-length mean of κ_n (its least-squares constant). The local radii 1/κ_n along
    the face and their spread about R are kept as the model-error indicator of one
    circle for the whole tooth.

    Why not a least-squares circle of the curve in its best-fit plane: the
    mid-height curve also bends WITHIN the tooth surface (geodesic curvature: it
    follows the member's cone, ≈ sin²β/(R tan δ)), which a circle fitted in 3-D
    mixes in but a cylindrical shell cannot represent — 40 mm instead of 58.5 mm for
    the hypoid example pinion (δ = 21°); for the nearly plane gear cones the two
    agree within 1–2 %. Why not the curvature at mid face: the shell is one circle
    for the whole tooth; for a trace whose curvature changes nearly linearly along
    the face (the epicycloid) the two agree within 0.2 % (example FH gear), and the
    mean does not hang on the fit at one point. The Legendre fit of the flank
    angles reproduces κ_n of the mid-surface between the exactly generated flanks
    (finite differences of solve_envelope points) within 0.5 %.

    Measured (tests/test_compliance_tooth.py): the FM Formate gears of the bundled
    cases within +0.9 … +1.7 % of their mean point radius (which they keep: their
    lengthwise curve is the cutter circle); the face-hobbed example gear
    (tests/data/fh_iso23509_s2_crown.toml) 75.9 mm, within 0.2 % of ISO 23509's
    lengthwise radius ρ_mβ = 75.8 mm at its mean point and 8 % below r_c0 = 82.55 mm,
    spread −3 … +4 % toe → heel. Generated pinions differ from their cutter: the FM
    pinions' measured radius is 4–14 % below their point radius (they keep the point
    radius, so that FM results do not change; tests/test_compliance_tooth.py
    compares both against FE), the FH example pinion's 8 % above its crown gear's
    ρ_mβ (its radius grows from root to tip on its 21° cone).
    """
    t_start = time.perf_counter()
    if member not in ("pinion", "gear"):
        raise InputError(f"member: must be 'pinion' or 'gear', got {member!r}")
    e_mod = positive("youngs_modulus", youngs_modulus, "MPa")
    nu_p = real("poisson_ratio", poisson_ratio, unit="1", low=0.0, high=0.5, high_open=True)
    nu = integer("nu", nu, 5, 200)
    nv = integer("nv", nv, 4, 200)
    if radius_source not in RADIUS_SOURCES:
        raise InputError(f"radius_source: must be one of {list(RADIUS_SOURCES)}, got "
                         f"{radius_source!r}")
    mem = case.member(member)
    blank = mem.blank

    fl = _tooth_flanks(case, member, nu, nv)
    corners = blank_outline(blank).corners
    coef_v, res_v = _fit_angles(fl.u, fl.v, fl.phi[0], fl.ok[0])
    coef_c, res_c = _fit_angles(fl.u, fl.v, fl.phi[1], fl.ok[1])
    coef = np.stack([coef_v, coef_c])
    surf = _make_surface(corners, coef)
    table, length = _arc_table(surf)
    (t_toe, t_heel, t_tip), t_meas, t_err = _fit_thickness(surf, fl, table, length)
    (h_toe, h_heel), h_meas, h_err = _fit_heights(surf, table, length, nu)

    blades = {f: mem.flank(f).blade for f in SIDES}
    point_radius = 0.5 * (blades["convex"].point_radius + blades["concave"].point_radius)
    measured, local, spread = _lengthwise_radius(surf, length)
    source = radius_source
    if source == "auto":
        source = "measured" if mem.blade_groups >= 1 else "point"
    if source == "measured" and not math.isfinite(measured):
        raise LTCAError(
            f"{member}: the tooth's mid-surface does not curve lengthwise (its normal turns "
            "by <= 0 rad from toe to heel): no circular shell radius can be measured")
    radius = measured if source == "measured" else point_radius
    dims = {"thickness_toe_root": t_toe, "thickness_heel_root": t_heel,
            "thickness_tip": t_tip, "height_toe": h_toe, "height_heel": h_heel}
    bad = {k: val for k, val in dims.items() if not val > 0.0}
    if bad:
        raise LTCAError(f"{member}: fitted tooth dimensions are not physical: {bad}")
    tooth = ShellTooth.from_face_width(
        **{k: float(val) for k, val in dims.items()}, face_width=length, radius=radius,
        youngs_modulus=e_mod, poisson_ratio=nu_p)
    vg = _virtual_gear(member, blank, corners, surf, blades, 0.5 * (t_toe + t_heel), length,
                       bore_radius, e_mod)
    elapsed = time.perf_counter() - t_start
    log.debug("%s tooth measured in %.3f s: %s; shell radius %s (measured %.4g mm, point "
              "%.4g mm)", member, elapsed, tooth, source, measured, point_radius)
    return ToothModelData(
        member=member, tooth=tooth, foundation=vg.foundation, teeth=blank.teeth,
        concave_shift=fl.shift, corners=corners, angle_coef=coef, arc_table=table,
        fillet_radius=(blades["convex"].edge_radius, blades["concave"].edge_radius),
        measured_radius=measured, point_radius=point_radius, radius_source=source,
        lengthwise_radius=local, radius_spread=spread, mean_spiral_angle=vg.spiral_angle,
        virtual_pitch_radius=vg.pitch_radius,
        mean_dedendum=vg.dedendum, measured_thickness=t_meas, measured_height=h_meas,
        grid_u=fl.u, grid_v=fl.v, thickness_fit_error=t_err, height_fit_error=h_err,
        angle_fit_error=max(res_v, res_c), build_time=elapsed, case=case)


# ---------------------------------------------------------------------------------------
# coordinates
# ---------------------------------------------------------------------------------------
def _as_vectors(name: str, value, n: int | None = None) -> np.ndarray:
    a = real_array(name, value)
    if a.ndim == 1 and a.shape[0] == 3:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != 3 or (n is not None and a.shape[0] != n):
        want = f"({n}, 3)" if n is not None else "(N, 3)"
        raise InputError(f"{name}: must be of shape {want}, got {a.shape}")
    return a


def _to_member(transform, points: np.ndarray, normals: np.ndarray | None):
    if transform is None:
        return points, normals
    t = real_array("transform", transform)
    if t.shape != (4, 4):
        raise InputError(f"transform: must be a (4, 4) member → pair matrix, got {t.shape}")
    rot, off = t[:3, :3], t[:3, 3]
    if not np.allclose(rot.T @ rot, np.eye(3), atol=1e-9):
        raise InputError("transform: must be a rigid motion (orthonormal rotation block), got "
                         f"|RᵀR − I| up to {np.max(np.abs(rot.T @ rot - np.eye(3))):.3g}")
    p = (points - off) @ rot
    return p, (None if normals is None else normals @ rot)


def _project_to_mid(surf: _Surface, p: np.ndarray, u, v):
    """Foot (u, v) of points p on the mid-surface along its normal (Newton).

    Minimises |p − M(u, v)|²/2 by Newton's method with the exact Hessian (the
    Gauss–Newton matrix M_u·M_u, M_u·M_v, M_v·M_v minus r·M_uu, r·M_uv, r·M_vv,
    r = p − M): quadratic convergence, 4–6 iterations instead of ~13 of Gauss–Newton
    (the plain formulation kept in tests/test_compliance_fast_paths.py), to the same
    foot (same stopping rule |Δu| + |Δv| < 1e-14). In cylindrical components
    about the member axis (M = ρ e_ρ(φ) + z e_z, ρ and z bilinear in (u, v)), with
    r_ρ = r·e_ρ, r_φ = r·e_φ:

        r·M_u = r_ρ ρ_u + r_φ ρ φ_u + r_z z_u
        r·M_uu = −r_ρ ρ φ_u² + r_φ (2 ρ_u φ_u + ρ φ_uu)
        r·M_uv = r_ρ (ρ_uv − ρ φ_u φ_v) + r_φ (ρ_u φ_v + ρ_v φ_u + ρ φ_uv) + r_z z_uv
        r·M_vv = −r_ρ ρ φ_v² + r_φ (2 ρ_v φ_v + ρ φ_vv)
    """
    u = np.array(u, dtype=float)
    v = np.array(v, dtype=float)
    px, py, pz = np.asarray(p, dtype=float).T
    rho_p = np.hypot(px, py)
    phi_p = np.arctan2(py, px)
    r_uv = surf.rho[3]
    z_uv = surf.z[3]
    for _ in range(_PROJ_ITER):
        z, rho, zu, ru, zv, rv = _blank_rows(surf, u, v)
        phi, fu, fv, fuu, fuv, fvv = _angle_rows(surf, u, v, slice(None))[[0, 1, 2, 5, 6, 7]]
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
        du = (a22 * g1 - a12 * g2) / det
        dv = (a11 * g2 - a12 * g1) / det
        u += du
        v += dv
        if (np.abs(du) + np.abs(dv)).max() < 1e-14:
            break
    return u, v


def _reference_tooth(surf: _Surface, pitch, pm: np.ndarray, u: np.ndarray, v: np.ndarray):
    """Turn points by whole pitches [rad] (a float, or one per point) onto the reference
    tooth of the mid-surface ``surf``; returns (turn, points)."""
    m, _, _ = _mid_surface(surf, u, v)
    gap = np.remainder(np.arctan2(m[:, 1], m[:, 0]) - np.arctan2(pm[:, 1], pm[:, 0]) + math.pi,
                       2 * math.pi) - math.pi
    turn = pitch * np.round(gap / pitch)
    return turn, _rot_z(turn, pm)


def shell_coordinates(
    data: ToothModelData,
    points,
    normals=None,
    *,
    transform=None,
    tolerance: float = 1e-6,
) -> ShellPoints:
    """Shell coordinates and local normals of points on a member's teeth.

    Parameters
    ----------
    data : ToothModelData
    points : array_like (N, 3) — [mm] points on (or in) any tooth of the member,
        in the member frame, or in the pair frame with ``transform``
    normals : array_like (N, 3), optional — [1] outward unit normals of the flank
        at the points (out of the member's material), same frame as ``points``
    transform : array_like (4, 4), optional — the member → pair transform of the
        roll position (:func:`geometry.pair.assembly.member_transform` with the
        member's rotation and the misalignments); ``None``: member frame
    tolerance : float — [1] how far (as a fraction of the face width / depth)
        a point's projection-plane place may lie outside the blank and still be
        clipped onto it

    Returns
    -------
    ShellPoints
        x [mm], θ [rad], (u, v) [1] of the point's foot on the mid-surface, the
        normal on (e_x, e_θ, e_z) [1] (None without normals), the flank side (+1
        convex / −1 concave: from the normal when given, else from the offset),
        the offset [mm] from the mid-surface along e_z and the frames (rows e_x,
        e_θ, e_z in the input frame).

    Raises
    ------
    InputError
        Bad shapes, non-finite values, non-unit normals, a bad transform, points
        whose (axial position, radius) lies outside the blank by more than
        ``tolerance``, or a normal that points into the tooth (its flank side
        disagrees with the point's side of the mid-surface).

    Notes
    -----
    The point is turned about the member axis by a whole number of pitches onto
    the reference tooth and projected along the mid-surface normal onto the
    tooth's mid-surface (the shell's z = 0): its foot (u, v) — NOT the mid-surface
    point at the point's own projection-plane place, which on a spiral tooth lies
    lengthwise ~t/2 · tan β away (≈ 4 % of the face width for the example gear;
    a 3-D FE model of the generated tooth shows the deflection peak there). Then
    θ = (arc length from the toe along the mid-height lengthwise curve) / R of the
    point where the mid-surface curve orthogonal to the lengthwise curves through
    the foot crosses mid height (the shell's generators are orthogonal to its
    lengthwise circles), clipped to [0, Θ₀] (the real toe and heel are oblique,
    the shell's are not), and x = v h(θ). The normal is projected on the frame of
    the foot — orthonormal, so a unit normal stays a unit vector: the "flank
    normal expressed in the local shell frame" that
    :func:`contact.compliance.shell.compliance_matrix` expects (the load acts
    along the flank normal, not the shell normal).
    """
    pts = _as_vectors("points", points)
    nrm = None if normals is None else _as_vectors("normals", normals, pts.shape[0])
    if nrm is not None and np.any(np.abs(np.linalg.norm(nrm, axis=1) - 1.0) > 1e-6):
        raise InputError("normals: must be unit vectors (|n| = 1 within 1e-6) [1], got |n| - 1 "
                         f"up to {np.max(np.abs(np.linalg.norm(nrm, axis=1) - 1.0)):.3g}")
    tol = positive("tolerance", tolerance, "1")
    return _shell_points(data, pts, nrm, transform, tol)[0]


def _shell_points(data: ToothModelData, pts: np.ndarray, nrm: np.ndarray | None, transform,
                  tol: float, extra: np.ndarray | None = None) -> list[ShellPoints]:
    """:func:`shell_coordinates` of checked points (with normals ``nrm`` or None) and,
    in the same batch, of ``extra`` points without normals (e.g. segment ends).

    Returns [ShellPoints of ``pts``] or [that, ShellPoints of ``extra``]. One batch
    evaluates the mid-surface once per iteration for all points (the cost is mostly
    per call); each point's result is its own (to round-off: a batch iterates until
    its slowest point has converged).
    """
    return shell_points_many([(data, pts, nrm, transform, extra)], tol)[0]


def shell_points_many(jobs, tol: float) -> list[list[ShellPoints]]:
    """:func:`_shell_points` of several teeth in ONE batch of points.

    ``jobs``: sequence of (data, pts, nrm, transform, extra) as the arguments of
    :func:`_shell_points`, e.g. the pinion's and the gear's view of the same contact
    segments; returns one :func:`_shell_points` result per job. All points of all jobs
    run through the bilinear inversion, the Newton projection, the frames and the
    trajectory RK4 together (the cost of these is mostly per call, not per point;
    :func:`_stack_surfaces`); the per-tooth parts (transform, turn onto the reference
    tooth, face angle, height, checks) are done per job. Each point's result is its own
    to round-off (a batch iterates until its slowest point has converged). Teeth of
    different fit degrees are mapped one job at a time.
    """
    if len(jobs) > 1 and len({job[0].surface.degree for job in jobs}) != 1:
        return [shell_points_many([job], tol)[0] for job in jobs]
    pm_l, nm_l, sizes, ns = [], [], [], []
    for _data, pts, nrm, transform, extra in jobs:
        every = pts if extra is None else np.concatenate([pts, extra])
        pm, nm = _to_member(transform, every, nrm)
        pm_l.append(pm)
        nm_l.append(nm)
        sizes.append(every.shape[0])
        ns.append(pts.shape[0])
    b = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
    if len(jobs) == 1:
        data = jobs[0][0]
        surf, corners, pitch = data.surface, data.corners, data.pitch
        pm = pm_l[0]
    else:
        surf = _stack_surfaces([job[0].surface for job in jobs], sizes)
        corners = np.repeat(np.stack([job[0].corners for job in jobs]), sizes, axis=0)
        pitch = np.repeat([job[0].pitch for job in jobs], sizes)
        pm = np.concatenate(pm_l)
    rho = np.hypot(pm[:, 0], pm[:, 1])
    u0, v0 = projection_fractions(corners, pm[:, 2], rho)
    outside = (u0 < -tol) | (u0 > 1 + tol) | (v0 < -tol) | (v0 > 1 + tol)
    for k, (data, _, _, _, extra) in enumerate(jobs):
        n = ns[k]
        out_k = outside[b[k]:b[k + 1]]
        for group in ((slice(0, n),) if extra is None else (slice(0, n), slice(n, None))):
            if np.any(out_k[group]):
                i = int(np.flatnonzero(out_k[group])[0])
                uo, vo = u0[b[k]:b[k + 1]][group][i], v0[b[k]:b[k + 1]][group][i]
                raise InputError(
                    f"points: must lie on the {data.member}'s tooth flanks, face fraction u "
                    f"and profile fraction v in [0, 1] (±{tol:g}), got point {i} at "
                    f"u = {uo:.6g}, v = {vo:.6g}")
    turn, p_ref = _reference_tooth(surf, pitch, pm, u0, v0)
    u, v = _project_to_mid(surf, p_ref, u0, v0)
    m, frame = _frames(surf, u, v)
    offset = np.sum((p_ref - m) * frame[:, 2, :], axis=-1)
    xi = _trajectory(surf, u, v, _REF_V)
    v = np.clip(v, 0.0, 1.0)
    frame_all = _rot_z(-turn[:, None], frame)
    results = []
    for k, (data, _, _, transform, extra) in enumerate(jobs):
        sl = slice(b[k], b[k + 1])
        n = ns[k]
        tooth = data.tooth
        theta = np.clip(data.face_angle(xi[sl]), 0.0, tooth.subtended_angle)
        x = v[sl] * tooth.height(theta)
        off = offset[sl]
        side = np.where(off >= 0.0, 1, -1)
        local = None
        nm = nm_l[k]
        if nm is not None:
            local = np.einsum("nij,nj->ni", frame[sl][:n], _rot_z(turn[sl][:n], nm))
            side[:n] = np.where(local[:, 2] >= 0.0, 1, -1)
            half = 0.5 * tooth.thickness(x[:n], theta[:n])
            wrong = (off[:n] * side[:n] < 0.0) & (np.abs(off[:n]) > 0.25 * half)
            if np.any(wrong):
                i = int(np.flatnonzero(wrong)[0])
                raise InputError(
                    f"normals: must point out of the {data.member}'s material, got normal {i} "
                    f"pointing to the {'convex' if side[i] > 0 else 'concave'} side but the "
                    f"point lies {off[i]:.4g} mm from the mid-surface (half thickness "
                    f"{half[i]:.4g} mm)")
        # frames back in the input frame (undo the turn, then the transform's rotation)
        frame_in = frame_all[sl]
        if transform is not None:
            frame_in = frame_in @ np.asarray(transform, dtype=float)[:3, :3].T
        uk = u[sl]
        vk = v[sl]
        out = [ShellPoints(x=x[:n], theta=theta[:n], u=uk[:n], v=vk[:n], normal=local,
                           side=side[:n], offset=off[:n], frame=frame_in[:n])]
        if extra is not None:
            out.append(ShellPoints(x=x[n:], theta=theta[n:], u=uk[n:], v=vk[n:], normal=None,
                                   side=side[n:], offset=off[n:], frame=frame_in[n:]))
        results.append(out)
    return results


def _flank_at(data: ToothModelData, u: float, v: float, flank: str):
    """Generated flank point and normal at projection-plane fractions (u, v), on the tooth."""
    mem = data.case.member(data.member)
    tool = mem.flank(flank)
    blank = mem.blank
    p, _, _ = _bilinear(data.corners, np.array([u]), np.array([v]))
    sol = solve_envelope(tool.blade, tool.machine, p[:, 0], p[:, 1],
                         length_scale=blank.outer_cone_distance,
                         depth=blank.outer_addendum + blank.outer_dedendum)
    pos, nn = sol.position[0], sol.normal[0]
    if mem.hand == "left":
        pos, nn = pos * _MIRROR, nn * _MIRROR
    if flank == "concave":
        turn = np.array(data.concave_shift * data.pitch)
        pos, nn = _rot_z(turn, pos), _rot_z(turn, nn)
    return pos, nn


def flank_points(data: ToothModelData, x, theta, side) -> tuple[np.ndarray, np.ndarray]:
    """Points and outward normals of the generated flanks at shell coordinates.

    The inverse of :func:`shell_coordinates` on the reference tooth: the flank
    point whose foot on the mid-surface has the shell coordinates (x, θ).

    Parameters
    ----------
    data : ToothModelData
    x : array_like (N,) — [mm] height from the root, 0 ≤ x ≤ h(θ)
    theta : array_like (N,) — [rad] face angle, 0 ≤ θ ≤ Θ₀
    side : array_like (N,) or int — [1] +1 convex flank, −1 concave flank

    Returns
    -------
    points : ndarray (N, 3) — [mm] member frame (NaN where the flank is not generated)
    normals : ndarray (N, 3) — [1] out of the material, member frame

    Raises
    ------
    InputError
        Shapes differ, values not finite, off the tooth, or side not ±1.

    Notes
    -----
    (x, θ) → the foot (u, v) on the mid-surface (orthogonal trajectory from mid
    height, :func:`shell_coordinates`); then a fixed-point iteration on the
    projection-plane place (axial position, radius) of the flank point until its
    foot is (u, v) to 1e-12, each flank point solved by the equation of meshing
    (seed Eq. 2.7a–2.8, :func:`geometry.machine.meshing.solve_envelope`; a left-hand member
    is the mirror image y → −y, as in :func:`geometry.machine.flank.flank_surface`). Each
    point is solved on its own with a coarse search, so this is for checks and
    plots, not for the roll loop.
    """
    xs = np.atleast_1d(real_array("x", x, unit="mm"))
    ts = np.atleast_1d(real_array("theta", theta, unit="rad"))
    if xs.shape != ts.shape or xs.ndim != 1:
        raise InputError(f"x, theta: must be 1-D of equal length, got shapes {xs.shape}, "
                         f"{ts.shape}")
    sd = np.broadcast_to(np.atleast_1d(np.asarray(side, dtype=float)), xs.shape)
    if not np.all(np.abs(np.abs(sd) - 1.0) == 0.0):
        raise InputError(f"side: must be +1 (convex flank) or -1 (concave flank), got {side!r}")
    tooth = data.tooth
    th0 = tooth.subtended_angle
    h = tooth.height(np.clip(ts, 0.0, th0))
    v_t = xs / h
    if np.any((ts < -1e-12 * th0) | (ts > th0 * (1 + 1e-12)) | (v_t < -1e-12)
              | (v_t > 1 + 1e-12)):
        raise InputError(
            f"x, theta: must lie on the tooth, 0 <= theta <= {th0:.6g} rad and "
            "0 <= x <= h(theta) mm, got points off it")
    u_t = _trajectory(data.surface, data.face_fraction(ts), _REF_V, v_t)
    pts = np.full((xs.size, 3), np.nan)
    nrm = np.full((xs.size, 3), np.nan)
    for i in range(xs.size):
        flank = "convex" if sd[i] > 0 else "concave"
        u, v = float(u_t[i]), float(v_t[i])
        for _ in range(_PROJ_ITER):
            pos, _ = _flank_at(data, u, v, flank)
            if not np.all(np.isfinite(pos)):
                break
            uf, vf = _project_to_mid(data.surface, pos[None, :],
                                     np.array([u]), np.array([v]))
            du, dv = float(u_t[i] - uf[0]), float(v_t[i] - vf[0])
            u, v = u + du, v + dv
            if abs(du) + abs(dv) < 1e-12:
                break
        pts[i], nrm[i] = _flank_at(data, u, v, flank)
    return pts, nrm


# ---------------------------------------------------------------------------------------
# compliance parts of one member
# ---------------------------------------------------------------------------------------
def weber_depth(data: ToothModelData, shell_points: ShellPoints) -> np.ndarray:
    """Distance from the contact to the tooth centreline along the load [mm].

    Parameters
    ----------
    data : ToothModelData
    shell_points : ShellPoints — with normals (:func:`shell_coordinates`)

    Returns
    -------
    ndarray (N,) — [mm] h = (t(x, θ)/2) / cos α_m, the depth h of Weber's formula
        (:func:`contact.compliance.weber.weber_compliance`)

    Raises
    ------
    InputError
        ``shell_points`` without normals.

    Notes
    -----
    Weber (1949) measures h from the contact point to the tooth centreline along
    the line of action; with the fitted thickness t of seed Eq. 3.1 and the load
    angle α_m of :func:`contact.compliance.foundation.load_angle_from_normals`.
    """
    if shell_points.normal is None:
        raise InputError("shell_points: must carry the flank normals (give normals), got none")
    alpha = load_angle_from_normals(shell_points.normal)
    t = data.tooth.thickness(shell_points.x, shell_points.theta)
    return 0.5 * t / np.cos(alpha)


def member_foundation(data: ToothModelData, shell_points: ShellPoints) -> np.ndarray:
    """Sainsot fillet-foundation coupling of loads on one tooth [mm/N].

    Parameters
    ----------
    data : ToothModelData
    shell_points : ShellPoints — with normals, all on ONE tooth

    Returns
    -------
    ndarray (N, N) — [mm/N] :func:`contact.compliance.foundation.foundation_matrix` of
        the mid-face virtual spur gear, load heights u_f from the contact heights x,
        the fitted thickness and the load angles of the real flank normals

    Raises
    ------
    InputError
        ``shell_points`` without normals; load angles beyond ±π/2.

    Notes
    -----
    Sainsot, Velex & Duverger (2004) (see :mod:`contact.compliance.foundation`); the
    virtual gear is described in :func:`shell_tooth_from_case`.
    """
    if shell_points.normal is None:
        raise InputError("shell_points: must carry the flank normals (give normals), got none")
    alpha = load_angle_from_normals(shell_points.normal)
    t = data.tooth.thickness(shell_points.x, shell_points.theta)
    u_f = load_line_height(shell_points.x, t, alpha)
    return foundation_matrix(data.foundation, u_f, alpha)


def shell_matrices(
    data: ToothModelData,
    sp: ShellPoints,
    ends_sp: ShellPoints | None,
    theory: str,
    n_height: int,
    n_face: int,
    blocks: list[np.ndarray] | None = None,
) -> list[ComplianceMatrix]:
    """Shell compliance of point loads at ``sp`` or of segments with ends ``ends_sp``
    (first N then second N ends), for each block of segment indices (None: all)."""
    model = data.shell_model(theory, n_height, n_face)
    n = sp.x.size
    if ends_sp is None:
        pts = np.column_stack([sp.x, sp.theta])
        pts = np.stack([pts, pts], axis=1)
    else:
        pts = np.stack([np.column_stack([ends_sp.x[:n], ends_sp.theta[:n]]),
                        np.column_stack([ends_sp.x[n:], ends_sp.theta[n:]])], axis=1)
    pts = as_shell_points(model.tooth, pts, "shell", "points")
    return compliance_blocks(model, pts, sp.normal, blocks)


def _shell_matrix(
    data: ToothModelData,
    sp: ShellPoints,
    ends_sp: ShellPoints | None,
    theory: str,
    n_height: int,
    n_face: int,
) -> ComplianceMatrix:
    return shell_matrices(data, sp, ends_sp, theory, n_height, n_face)[0]


def member_compliance(
    data: ToothModelData,
    points,
    normals,
    segment_ends=None,
    theory: str = "seed",
    n_height: int = N_HEIGHT,
    n_face: int = N_FACE,
    *,
    transform=None,
) -> np.ndarray:
    """Bending and shear compliance of loads on one tooth of a member [mm/N].

    Parameters
    ----------
    data : ToothModelData
    points : array_like (N, 3) — [mm] load points (segment midpoints) on the
        flanks of one tooth, member frame (or pair frame with ``transform``)
    normals : array_like (N, 3) — [1] outward unit flank normals at the points;
        each load acts along −n (into the tooth), the deflection is read along −n
    segment_ends : array_like (N, 2, 3), optional — [mm] end points of straight
        contact segments (same frame); each load is then spread uniformly along the
        segment (in shell coordinates), which removes the point-load singularity
        of Mindlin theory; ends overhanging the blank by up to :data:`END_TOLERANCE`
        are clipped onto the tooth. Default: point loads at ``points``
    theory : str — shell kinematics (:data:`contact.compliance.shell.THEORIES`)
    n_height, n_face : int — [1] Ritz modes, default :data:`N_HEIGHT` × :data:`N_FACE`
        = 6 × 21 (not the 5 × 9 that suffices for the short benchmark tooth of
        :mod:`contact.compliance.shell`: see :data:`N_FACE`); the shell model is built
        once per (data, theory, modes) and reused (:meth:`ToothModelData.shell_model`)
    transform : array_like (4, 4), optional — member → pair transform

    Returns
    -------
    ndarray (N, N) — [mm/N] symmetric (Maxwell–Betti), C_ij = deflection along
        load i due to a unit load j (seed Eq. 3.11)

    Raises
    ------
    InputError
        As :func:`shell_coordinates` and
        :func:`contact.compliance.shell.compliance_matrix`.
    ModelUnavailableError
        Unknown ``theory``.

    Notes
    -----
    Seed Eq. 3.10–3.11 through :func:`contact.compliance.shell.compliance_matrix`,
    with the real flank normals expressed in the local shell frame
    (:func:`shell_coordinates`).
    """
    sp = shell_coordinates(data, points, normals, transform=transform)
    ends_sp = None
    if segment_ends is not None:
        ends = np.asarray(segment_ends, dtype=float)
        if ends.shape != (sp.x.size, 2, 3):
            raise InputError(f"segment_ends: must be of shape ({sp.x.size}, 2, 3) [mm], got "
                             f"{ends.shape}")
        ends_sp = shell_coordinates(data, np.concatenate([ends[:, 0], ends[:, 1]]),
                                    transform=transform, tolerance=END_TOLERANCE)
    return _shell_matrix(data, sp, ends_sp, theory, n_height, n_face).matrix
