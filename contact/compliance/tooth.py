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

import math
from typing import TYPE_CHECKING

import numpy as np

from contact.compliance.foundation import (
    foundation_matrices,
    foundation_matrix,
    load_angle_from_normals,
    load_line_height,
)
from contact.compliance.shell import (
    ComplianceMatrix,
    compliance_blocks,
)
from contact.compliance.shell import as_points as as_shell_points
from contact.compliance.tooth_map import (
    END_TOLERANCE,
    KERNEL_MODULE,
    N_FACE,
    N_HEIGHT,
    RADIUS_SOURCES,
    SIDES,
    ShellPoints,
    Surface,
    ToothModelData,
    angle_rows,
    bilinear,
    blank_rows,
    frames,
    kernel_surface,
    mid_surface,
    projection_step,
    rot_z,
    stack_surfaces,
    trajectory,
)
from contact.compliance.tooth_measurement import shell_tooth_from_case
from geometry.core.errors import InputError
from geometry.core.kernels import kernels_module
from geometry.core.validation import positive, real_array
from geometry.machine.flank import projection_fractions
from geometry.machine.meshing import solve_envelope

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
    "member_foundations",
    "shell_coordinates",
    "shell_tooth_from_case",
    "weber_depth",
]

_MIRROR = np.array([1.0, -1.0, 1.0])  # left hand = mirror y → −y (geometry.machine.flank)


#                  face width; the seed case's compliance moves by < 1e-9 relative, the LTE
#                  by < 1e-6 µrad against 8 steps)
_REF_V = 0.5  # the shell's face angle is measured along the mid-height lengthwise curve


_PROJ_ITER = 30


if TYPE_CHECKING:
    pass


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


def _project_to_mid(surf: Surface, p: np.ndarray, u, v):
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
    kernels = kernels_module(KERNEL_MODULE)
    if kernels is not None:  # the same Newton steps point by point, compiled
        pts = np.asarray(p, dtype=float).reshape(-1, 3)
        uf, vf = kernels.project_to_mid(
            np.ascontiguousarray(pts[:, 0]), np.ascontiguousarray(pts[:, 1]),
            np.ascontiguousarray(pts[:, 2]), u.ravel(), v.ravel(),
            *kernel_surface(surf, u.size), *surf.degree, _PROJ_ITER)
        return uf.reshape(u.shape), vf.reshape(v.shape)
    px, py, pz = np.asarray(p, dtype=float).T
    rho_p = np.hypot(px, py)
    phi_p = np.arctan2(py, px)
    r_uv = surf.rho[3]
    z_uv = surf.z[3]
    for _ in range(_PROJ_ITER):
        z, rho, zu, ru, zv, rv = blank_rows(surf, u, v)
        phi, fu, fv, fuu, fuv, fvv = angle_rows(surf, u, v, slice(None))[[0, 1, 2, 5, 6, 7]]
        du, dv = projection_step(rho_p, phi_p, pz, z, rho, zu, ru, zv, rv, z_uv, r_uv, phi,
                                 fu, fv, fuu, fuv, fvv)
        u += du
        v += dv
        if (np.abs(du) + np.abs(dv)).max() < 1e-14:
            break
    return u, v


def _reference_tooth(surf: Surface, pitch, pm: np.ndarray, u: np.ndarray, v: np.ndarray):
    """Turn points by whole pitches [rad] (a float, or one per point) onto the reference
    tooth of the mid-surface ``surf``; returns (turn, points)."""
    m, _, _ = mid_surface(surf, u, v)
    gap = np.remainder(np.arctan2(m[:, 1], m[:, 0]) - np.arctan2(pm[:, 1], pm[:, 0]) + math.pi,
                       2 * math.pi) - math.pi
    turn = pitch * np.round(gap / pitch)
    return turn, rot_z(turn, pm)


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
    :func:`stack_surfaces`); the per-tooth parts (transform, turn onto the reference
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
        surf = stack_surfaces([job[0].surface for job in jobs], sizes)
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
    m, frame = frames(surf, u, v)
    offset = np.sum((p_ref - m) * frame[:, 2, :], axis=-1)
    xi = trajectory(surf, u, v, _REF_V)
    v = np.clip(v, 0.0, 1.0)
    frame_all = rot_z(-turn[:, None], frame)
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
            local = np.einsum("nij,nj->ni", frame[sl][:n], rot_z(turn[sl][:n], nm))
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
    p, _, _ = bilinear(data.corners, np.array([u]), np.array([v]))
    sol = solve_envelope(tool.blade, tool.machine, p[:, 0], p[:, 1],
                         length_scale=blank.outer_cone_distance,
                         depth=blank.outer_addendum + blank.outer_dedendum)
    pos, nn = sol.position[0], sol.normal[0]
    if mem.hand == "left":
        pos, nn = pos * _MIRROR, nn * _MIRROR
    if flank == "concave":
        turn = np.array(data.concave_shift * data.pitch)
        pos, nn = rot_z(turn, pos), rot_z(turn, nn)
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
    u_t = trajectory(data.surface, data.face_fraction(ts), _REF_V, v_t)
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


def member_foundations(data: ToothModelData, shell_points: ShellPoints,
                       blocks: list[np.ndarray]) -> list[np.ndarray]:
    """:func:`member_foundation` of several teeth's loads at once [mm/N].

    Parameters
    ----------
    data : ToothModelData
    shell_points : ShellPoints — with normals, the loads of all blocks
    blocks : list of int ndarray or slice — the loads on one tooth (at one roll position)
        each

    Returns
    -------
    list of ndarray (n_b, n_b) — [mm/N] each block's :func:`member_foundation`

    Raises
    ------
    InputError
        As :func:`member_foundation`.

    Notes
    -----
    Sainsot, Velex & Duverger (2004); the load heights, thickness and load angles are
    computed once for all loads (:func:`contact.compliance.foundation.foundation_matrices`).
    """
    if shell_points.normal is None:
        raise InputError("shell_points: must carry the flank normals (give normals), got none")
    alpha = load_angle_from_normals(shell_points.normal)
    t = data.tooth.thickness(shell_points.x, shell_points.theta)
    u_f = load_line_height(shell_points.x, t, alpha)
    return foundation_matrices(data.foundation, u_f, alpha, blocks)


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
