"""Blank trimming, the projection-plane grid, and the flank Dataset (seed §2.2, §2.3.2).

The projection plane of a member is its axial section: axial position z along the member
axis (from the crossing point towards the member's back) × radius ρ from the axis. In it
the tooth flank is bounded by four straight lines: the root cone, the face cone, the front
(toe) cone and the back (heel) cone; the front and back cones are perpendicular to the
pitch cone at the inner and outer cone distances R_i = R_e − b and R_e. The flank grid is
laid bilinearly between the four corners: u lengthwise from toe (0) to heel (1), v along
the profile from root (0) to tip (1).

Public functions
----------------
BlankOutline       the four corners and cone lines of a blank in the projection plane
blank_outline      compute it from a Blank
ProjectionGrid     (u, v) fractions and the (z, ρ) targets of a flank grid
projection_grid    lay the grid
flank_surface      solve one flank on its grid: points, normals, curvatures (FlankSurface)
flank_at           the same at arbitrary projection-plane places
projection_fractions  (u, v) of projection-plane points: the inverse of the grid's map
flank_dataset      the same as an xarray.Dataset with units and long names
geometry_datasets  all four flanks of a case
"""

from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import xarray as xr

from geometry.core.caches import Same, memoised, read_only
from geometry.core.conventions import binary_flag, dataset
from geometry.core.errors import InputError
from geometry.core.version import __version__
from geometry.machine.curvature import surface_curvatures
from geometry.machine.cutter import profile_sections
from geometry.machine.meshing import REASONS, solve_envelope

if TYPE_CHECKING:
    from geometry.case import Blank, Case

__all__ = [
    "DEFAULT_GRID",
    "BlankOutline",
    "FlankSurface",
    "ProjectionGrid",
    "blank_outline",
    "flank_at",
    "flank_dataset",
    "flank_surface",
    "geometry_datasets",
    "line_intersection",
    "projection_fractions",
    "projection_grid",
]

#: default grid: 41 lengthwise × 21 profile points; v starts 5 % of the depth above the root
#: cone (the mate's tip never reaches lower than the clearance, ~6 % of the whole depth)
DEFAULT_GRID = {"nu": 41, "nv": 21, "u_limits": (0.0, 1.0), "v_limits": (0.05, 1.0)}


class BlankOutline(NamedTuple):
    """Blank boundary in the projection plane (z, ρ) [mm]; corners indexed [u][v]."""

    corners: np.ndarray  # (2, 2, 2): [u=toe/heel][v=root/tip][z, ρ]
    pitch_apex: float  # z of the pitch apex [mm]
    face_apex: float
    root_apex: float
    mean_point: np.ndarray  # (2,) pitch point at the mean cone distance [mm]
    whole_depth: float  # outer whole depth hae + hfe [mm]


def line_intersection(p1, d1, p2, d2) -> np.ndarray:
    """The intersection of two lines of a plane, p1 + t d1 and p2 + s d2.

    Parameters
    ----------
    p1, d1, p2, d2 : array_like (2,) — [mm], [1]
        A point and a direction of each line (axial, radial coordinates of a projection
        plane).

    Returns
    -------
    ndarray (2,) — [mm]

    Raises
    ------
    numpy.linalg.LinAlgError
        Parallel lines.
    """
    a = np.array([[d1[0], -d2[0]], [d1[1], -d2[1]]])
    t = np.linalg.solve(a, np.asarray(p2, float) - np.asarray(p1, float))
    return np.asarray(p1, float) + t[0] * np.asarray(d1, float)


def blank_outline(blank: Blank) -> BlankOutline:
    """Corners of the flank region of a blank in its projection plane.

    Parameters
    ----------
    blank : geometry.case.Blank

    Returns
    -------
    BlankOutline
        Corners [u][v] = (toe, heel) × (root, tip) as (z, ρ) [mm], apex positions z [mm],
        the mean pitch point and the outer whole depth. Kept per blank object and shared
        by its callers (:func:`_memo_blank_outline`): its arrays are not to be written.

    Notes
    -----
    Apex positions are given "beyond the crossing point" (ISO 23509 t_z: positive when the
    apex lies beyond the crossing point, away from the member body), so z_apex = −t_z.
    """
    return _memo_blank_outline(Same(blank))


@memoised(maxsize=32)
def _memo_blank_outline(blank: Same) -> BlankOutline:
    """:func:`blank_outline` of the blank ``blank.obj``, once per blank object (a frozen
    dataclass): a study point asked for it 8 times (≈ 0.7 ms of eight small line solves;
    the study's cases share their members, so once per study, issue 75). The same
    arithmetic as before, so the same outline bit for bit; its arrays read-only (shared by
    every caller, :func:`geometry.core.caches.read_only`)."""
    return read_only(_blank_outline(blank.obj))


def _blank_outline(blank: Blank) -> BlankOutline:
    """:func:`blank_outline`, computed."""
    zp, zf, zr = -blank.pitch_apex, -blank.face_apex, -blank.root_apex
    d = blank.pitch_angle
    gen = np.array([math.cos(d), math.sin(d)])
    perp = np.array([-math.sin(d), math.cos(d)])
    apex = np.array([zp, 0.0])
    face_dir = np.array([math.cos(blank.face_angle), math.sin(blank.face_angle)])
    root_dir = np.array([math.cos(blank.root_angle), math.sin(blank.root_angle)])
    corners = np.empty((2, 2, 2))
    for iu, cone_distance in enumerate((blank.outer_cone_distance - blank.face_width,
                                        blank.outer_cone_distance)):
        foot = apex + cone_distance * gen
        corners[iu, 0] = line_intersection([zr, 0.0], root_dir, foot, perp)
        corners[iu, 1] = line_intersection([zf, 0.0], face_dir, foot, perp)
    mean = apex + (blank.outer_cone_distance - 0.5 * blank.face_width) * gen
    return BlankOutline(corners, zp, zf, zr, mean,
                        blank.outer_addendum + blank.outer_dedendum)


def projection_fractions(corners: np.ndarray, axial, radius, *, tol: float = 1e-14,
                         max_iter: int = 30) -> tuple[np.ndarray, np.ndarray]:
    """Projection-plane fractions (u, v) of points (z, ρ): the inverse of the bilinear map.

    The flank region is laid bilinearly between its corners,
    (z, ρ)(u, v) = c₀₀ + u (c₁₀ − c₀₀) + v (c₀₁ − c₀₀) + u v (c₁₁ − c₁₀ − c₀₁ + c₀₀)
    (module docstring); this inverts it by Newton's method from the centre (u, v) = ½,
    which converges quadratically on a blank's (convex, nearly trapezoidal) outline, also
    for points outside it (then u or v lies outside [0, 1]).

    Parameters
    ----------
    corners : array (2, 2, 2), or (P, 2, 2, 2) one outline per point — [mm]
        [u][v] = (toe, heel) × (root, tip) corners as (z, ρ) (:class:`BlankOutline`).
    axial, radius : arrays (...) — [mm]
        z and ρ of the points (with per-point corners: shape (P,)).
    tol : float — [1]
        Stop when every point's Newton step |Δu| + |Δv| is below this (a NaN point's
        step is NaN: it does not keep the loop going).
    max_iter : int
        Cap on the Newton steps.

    Returns
    -------
    (u, v) : arrays (...) — [1]
        Lengthwise fraction, toe 0 → heel 1, and profile fraction, root 0 → tip 1; NaN
        where the point is NaN (callers pass NaN for "no point", e.g. a pair without a
        contact curve, and mask it).

    Raises
    ------
    Nothing of its own: the shapes must broadcast (numpy's error otherwise).

    Notes
    -----
    Source: the projection-plane layout of the flank grid (seed §2.2, this module's
    docstring; the grid is :func:`projection_grid`, of which this is the inverse). Tested
    against the layout's own formula inside and beyond the outline to 1e-12
    (tests/test_case.py).
    """
    c = np.asarray(corners, dtype=float)
    if c.ndim == 4:  # per point: c[i, j] is then (P, 2)
        c = np.moveaxis(c, 0, 2)
    z = np.asarray(axial, dtype=float)
    rho = np.asarray(radius, dtype=float)
    c00 = c[0, 0]
    e = c[1, 0] - c00
    f = c[0, 1] - c00
    g = c[1, 1] - c[1, 0] - c[0, 1] + c00
    hz, hr = z - c00[..., 0], rho - c00[..., 1]
    ez, er, fz, fr, gz, gr = e[..., 0], e[..., 1], f[..., 0], f[..., 1], g[..., 0], g[..., 1]
    u = np.full(np.broadcast_shapes(hz.shape, hr.shape), 0.5)
    v = np.full(u.shape, 0.5)
    for _ in range(max_iter):
        uz, ur = ez + v * gz, er + v * gr  # ∂(z, ρ)/∂u
        vz, vr = fz + u * gz, fr + u * gr  # ∂(z, ρ)/∂v
        rz = u * ez + v * vz - hz  # residual (z, ρ)(u, v) − (z, ρ)
        rr = u * er + v * vr - hr
        det = uz * vr - ur * vz
        du = (rz * vr - rr * vz) / det
        dv = (uz * rr - ur * rz) / det
        u -= du
        v -= dv
        # a NaN point ("no point") has NaN steps: it does not hold the others' loop to
        # max_iter (each point's u, v are those of a batch without it)
        if not np.any(np.abs(du) + np.abs(dv) >= tol):
            break
    return u, v


class ProjectionGrid(NamedTuple):
    """Flank grid in the projection plane: arrays of shape (nu, nv)."""

    u: np.ndarray  # (nu,) lengthwise fraction, toe 0 → heel 1
    v: np.ndarray  # (nv,) profile fraction, root 0 → tip 1
    axial: np.ndarray  # (nu, nv) z [mm]
    radius: np.ndarray  # (nu, nv) ρ [mm]


def projection_grid(blank: Blank, nu: int = 41, nv: int = 21,
                    u_limits: tuple[float, float] = (0.0, 1.0),
                    v_limits: tuple[float, float] = (0.05, 1.0)) -> ProjectionGrid:
    """Lay the flank grid on the projection plane between the four cones of the blank.

    Parameters
    ----------
    blank : geometry.case.Blank
    nu, nv : int
        Number of points lengthwise (toe → heel) and along the profile (root → tip), ≥ 2.
    u_limits, v_limits : (float, float)
        Fractions of the face width and of the depth covered, within [0, 1].

    Returns
    -------
    ProjectionGrid

    Raises
    ------
    InputError
        For fewer than 2 points or limits outside [0, 1].
    """
    for name, val in (("nu", nu), ("nv", nv)):
        if int(val) != val or val < 2:
            raise InputError(f"{name}: must be an integer >= 2, got {val!r}")
    for name, lim in (("u_limits", u_limits), ("v_limits", v_limits)):
        if not (0.0 <= lim[0] < lim[1] <= 1.0):
            raise InputError(f"{name}: must satisfy 0 <= low < high <= 1, got {lim!r}")
    c = blank_outline(blank).corners
    u = np.linspace(u_limits[0], u_limits[1], int(nu))
    v = np.linspace(v_limits[0], v_limits[1], int(nv))
    uu, vv = np.meshgrid(u, v, indexing="ij")
    pts = ((1 - uu)[..., None] * (1 - vv)[..., None] * c[0, 0]
           + uu[..., None] * (1 - vv)[..., None] * c[1, 0]
           + (1 - uu)[..., None] * vv[..., None] * c[0, 1]
           + uu[..., None] * vv[..., None] * c[1, 1])
    return ProjectionGrid(u, v, pts[..., 0], pts[..., 1])


class FlankSurface(NamedTuple):
    """One solved flank: grid, points, normals and curvatures in the member frame.

    Arrays have shape (nu, nv) (+ (3,) for vectors); invalid points hold NaN.
    """

    member: str
    flank: str
    hand: str
    grid: ProjectionGrid | None  # None for flank_at
    position: np.ndarray  # [mm]
    normal: np.ndarray  # [1] out of the material
    kappa1: np.ndarray  # [1/mm] convex positive
    kappa2: np.ndarray  # [1/mm]
    dir1: np.ndarray  # [1]
    dir2: np.ndarray  # [1] normal × dir1
    meshing_residual: np.ndarray  # [1]
    s: np.ndarray  # [mm] blade arc length (right-hand reference)
    theta: np.ndarray  # [rad] blade angle about the cutter axis (right-hand reference)
    q: np.ndarray  # [rad] cradle rotation (right-hand reference)
    section: np.ndarray  # blade section index
    reason: np.ndarray  # int8 mask reason (geometry.machine.meshing.REASONS)

    @property
    def valid(self) -> np.ndarray:
        """Boolean mask of generated points."""
        return self.reason == 0


_MIRROR = np.array([1.0, -1.0, 1.0])


def flank_surface(case: Case, member: str, flank: str, *, nu: int = 41, nv: int = 21,
                  u_limits: tuple[float, float] = (0.0, 1.0),
                  v_limits: tuple[float, float] = (0.05, 1.0)) -> FlankSurface:
    """Generate one flank of one member on its projection-plane grid (seed §2.2).

    Parameters
    ----------
    case : geometry.case.Case
    member : str
        ``"pinion"`` or ``"gear"``.
    flank : str
        ``"concave"`` or ``"convex"``.
    nu, nv, u_limits, v_limits
        Grid, see :func:`projection_grid`.

    Returns
    -------
    FlankSurface
        In the member frame (origin at the crossing point, z along the member axis towards
        its back); a left-hand member is the mirror image y → −y of the right-hand one
        generated from the (right-hand reference) settings.

    Raises
    ------
    InputError
        For bad names or grid parameters, or settings with no envelope inside the blank.

    Notes
    -----
    Seed Eq. 2.7a (machine chain), 2.8 (equation of meshing) and 2.9–2.13 (curvatures);
    the reference slot is the one cut at q = 0 near the +x side of the member frame.
    """
    grid = projection_grid(case.member(member).blank, nu, nv, u_limits, v_limits)
    return flank_at(case, member, flank, grid.axial, grid.radius)._replace(grid=grid)


def flank_at(case: Case, member: str, flank: str, axial, radius,
             guess=None) -> FlankSurface:
    """One flank of one member solved at arbitrary projection-plane places (seed §2.2).

    Parameters
    ----------
    case : geometry.case.Case
    member : str
        ``"pinion"`` or ``"gear"``.
    flank : str
        ``"concave"`` or ``"convex"``.
    axial, radius : array_like, same shape — [mm]
        Axial position z and radius ρ in the member's projection plane.
    guess : tuple, optional
        (s, θ, q[, section]) starting guesses of the envelope parameters from nearby
        solutions, broadcastable to ``axial`` (:func:`geometry.machine.meshing.solve_envelope`:
        points without a finite guess, or not converging from it, are solved as without).

    Returns
    -------
    FlankSurface
        As :func:`flank_surface` with ``grid=None`` and arrays of the shape of ``axial``.

    Raises
    ------
    InputError
        For bad names or mismatched shapes.

    Notes
    -----
    Seed Eq. 2.7a, 2.8, 2.9–2.13; the hand is applied by mirroring y → −y.
    """
    mem = case.member(member)
    tool = mem.flank(flank)
    blank = mem.blank
    z = np.asarray(axial, dtype=float)
    rho = np.asarray(radius, dtype=float)
    if z.shape != rho.shape:
        raise InputError(f"axial, radius: must have equal shapes, got {z.shape} and {rho.shape}")
    try:
        sol = solve_envelope(tool.blade, tool.machine, z, rho,
                             length_scale=blank.outer_cone_distance,
                             depth=blank.outer_addendum + blank.outer_dedendum, guess=guess)
    except InputError as exc:
        if not str(exc).startswith("machine settings:"):
            raise
        # name the table whose settings do not generate the flank, and its main settings
        m = tool.machine
        raise InputError(
            f"{member}.machine.{flank}: {str(exc).removeprefix('machine settings: ')} (check "
            f"{member}.machine.{flank} — radial_setting {m.radial_setting:.4g} mm, "
            f"cradle_angle {math.degrees(m.cradle_angle):.4g} deg, machine_root_angle "
            f"{math.degrees(m.machine_root_angle):.4g} deg — and {member}.cutter.{flank} "
            "against the blank)") from None
    pc = surface_curvatures(sol.family, tool.machine.process == "Generate",
                            blank.outer_cone_distance)
    valid = sol.reason == 0
    nan3 = np.where(valid[..., None], 1.0, np.nan)
    nan1 = np.where(valid, 1.0, np.nan)
    pos, nrm = sol.position, sol.normal
    d1, d2 = pc.dir1 * nan3, pc.dir2 * nan3
    if mem.hand == "left":
        pos, nrm, d1, d2 = pos * _MIRROR, nrm * _MIRROR, d1 * _MIRROR, -(d2 * _MIRROR)
    return FlankSurface(
        member=member, flank=flank, hand=mem.hand, grid=None, position=pos, normal=nrm,
        kappa1=pc.kappa1 * nan1, kappa2=pc.kappa2 * nan1, dir1=d1, dir2=d2,
        meshing_residual=sol.meshing_residual, s=sol.s, theta=sol.theta, q=sol.q,
        section=sol.section, reason=sol.reason)


def _var(dims, data, units, long_name, **attrs):
    return (dims, data, {"units": units, "long_name": long_name, **attrs})


def flank_dataset(case: Case, member: str, flank: str, *, surface: FlankSurface | None = None,
                  **grid) -> xr.Dataset:
    """One flank as an xarray Dataset with units and long names (dims u, v, xyz).

    Parameters
    ----------
    case : geometry.case.Case
    member, flank : str
    surface : FlankSurface, optional
        An already computed :func:`flank_surface` (otherwise computed with ``grid``).
    **grid
        ``nu``, ``nv``, ``u_limits``, ``v_limits`` of :func:`flank_surface`.

    Returns
    -------
    xarray.Dataset
        Variables: position, normal [mm, 1] (member frame), axial_position, radial_position
        [mm], kappa1, kappa2 [1/mm], dir1, dir2 [1], meshing_residual [1], blade_s [mm],
        blade_theta [rad], roll [rad], blade_section, mask, mask_reason; netCDF-safe
        attributes including the case as TOML text (``inputs``).

    Raises
    ------
    InputError
        As :func:`flank_surface`.
    """
    fs = surface if surface is not None else flank_surface(case, member, flank, **grid)
    mem = case.member(member)
    tool = mem.flank(flank)
    sec_names = profile_sections(tool.blade).names
    uv = ("u", "v")
    uvx = ("u", "v", "xyz")
    codes = np.array(sorted(REASONS), dtype=np.int8)
    data = {
        "position": _var(uvx, fs.position, "mm", "tooth surface point in the member frame"),
        "normal": _var(uvx, fs.normal, "1", "unit normal pointing out of the tooth material"),
        "axial_position": _var(uv, fs.grid.axial, "mm",
                               "projection-plane axial position (from the crossing point)"),
        "radial_position": _var(uv, fs.grid.radius, "mm",
                                "projection-plane radius from the member axis"),
        "kappa1": _var(uv, fs.kappa1, "1/mm", "first (largest) principal curvature, "
                       "convex positive"),
        "kappa2": _var(uv, fs.kappa2, "1/mm", "second (smallest) principal curvature, "
                       "convex positive"),
        "dir1": _var(uvx, fs.dir1, "1", "unit principal direction of kappa1"),
        "dir2": _var(uvx, fs.dir2, "1", "unit principal direction of kappa2 (normal x dir1)"),
        "meshing_residual": _var(uv, fs.meshing_residual, "1",
                                 "equation of meshing n.dr/dq / outer cone distance "
                                 "(0 for Formate)"),
        "blade_s": _var(uv, fs.s, "mm", "arc length along the blade edge from the tip"),
        "blade_theta": _var(uv, fs.theta, "rad", "blade angle about the cutter axis "
                            "(right-hand reference)"),
        "roll": _var(uv, fs.q, "rad", "cradle rotation q that generates the point "
                     "(right-hand reference)"),
        "blade_section": _var(uv, fs.section.astype(np.int8), "1",
                              "blade section that generates the point",
                              flag_values=np.arange(len(sec_names), dtype=np.int8),
                              flag_meanings=" ".join(sec_names)),
        "mask": _var(uv, fs.valid.astype(np.int8), "1", "1 where the point is generated",
                     **binary_flag("not_generated", "generated")),
        "mask_reason": _var(uv, fs.reason.astype(np.int8), "1",
                            "why a point is not generated", flag_values=codes,
                            flag_meanings=" ".join(REASONS[int(c)] for c in codes)),
    }
    coords = {
        "u": ("u", fs.grid.u, {"units": "1", "long_name": "lengthwise fraction, toe 0 to heel 1"}),
        "v": ("v", fs.grid.v, {"units": "1", "long_name": "profile fraction, root 0 to tip 1"}),
        "xyz": ("xyz", np.array(["x", "y", "z"]), {"long_name": "member-frame component"}),
    }
    attrs = {
        "title": f"{case.name}: {member} {flank} flank",
        "case": case.name,
        "member": member,
        "flank": flank,
        "hand": mem.hand,
        "process": mem.process,
        "method": case.pair.method,
        "teeth": mem.blank.teeth,
        "blade_side": tool.blade.side,
        "frame": "member frame: origin at the crossing point, z along the member axis "
                 "towards its back, reference slot near +x",
        "curvature_sign": "convex positive (kappa = dn.dr/dr.dr, n out of the material)",
        "n_masked": int((~fs.valid).sum()),
        "max_abs_meshing_residual": float(np.nanmax(np.abs(fs.meshing_residual)))
        if fs.valid.any() else 0.0,
        "toolkit_version": __version__,
        "source": "geometry.machine.flank.flank_dataset (seed Eq. 2.7-2.13)",
        "inputs": case.to_toml(),
        "synthesised": json.dumps(list(case.synthesised)),
    }
    if mem.blade_groups:
        # face hobbing: the cutter's blade groups z0 and the indexing ratio -z0/z
        attrs["blade_groups"] = mem.blade_groups
        attrs["indexing_ratio"] = tool.machine.indexing_ratio
    return dataset(data, coords, attrs)


def geometry_datasets(case: Case, **grid) -> dict[tuple[str, str], xr.Dataset]:
    """All four flanks of a case as Datasets keyed by (member, flank).

    Parameters
    ----------
    case : geometry.case.Case
    **grid
        Grid parameters of :func:`flank_surface`.

    Returns
    -------
    dict
        ``{("pinion", "concave"): Dataset, …}``.
    """
    return {(m, f): flank_dataset(case, m, f, **grid)
            for m in ("pinion", "gear") for f in ("concave", "convex")}
