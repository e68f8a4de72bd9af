"""Archard wear of the flanks in a single-point observation: the depth of one mesh.

Archard's law in a single-point observation
-------------------------------------------
Archard's law (Archard 1953) gives the worn volume V = k F s of a contact carrying the
normal load F over a sliding distance s, k the dimensional wear coefficient [m²/N =
m³/(N·m)]; per unit area the worn depth is h = k p s (p the contact pressure). A point of a
flank is worn while the loaded band of the contact line passes over it (Flodin &
Andersson's single-point observation): with p(x) the pressure across the band, V_s the
sliding speed of the two surfaces and c the speed of the contact line across the flank
*relative to that flank's material*, the depth of one passage is

    h = k ∫ p |V_s| dt = k |V_s| / c · ∫ p dx = k w |V_s| / c,

w = ∫ p dx the load per unit length of the line [N/mm] — exact for any pressure profile
across the band (Hertz's semi-ellipse, w = π p₀ b / 2) as long as V_s and c are constant
over its width 2b. For a uniform pressure p over the band (w = 2 b p) it is Archard's
h = k p s with the sliding distance s = 2b |V_s| / c of Flodin & Andersson (1997, Eq. 6–7;
Bajpai, Kahraman & Anderson 2004; for hypoid gears Park & Kahraman 2009, Park, Kolivand &
Kahraman 2014, who likewise take s from the contact velocities). The two members differ
only in c: the band passes faster over the faster flank, which therefore wears less.

Speeds per radian of pinion roll: V_s from the rigid-body velocities of the members at the
LTCA's contact points (:func:`friction.kinematics.surface_velocities`, seed Eq. 5.1–5.6);
c from the surface of roll angle Q (:mod:`contact.utca.easeoff`): the contact line at pinion
roll q is the iso-line Q = q on the gear flank (seed §2.3.2.2) and on the pinion flank (the
mates of those gear points), so it moves over a flank with the body-fixed speed
c = 1 / |∇_S Q| per unit roll, ∇_S the surface gradient in arc length on that flank
(:func:`contact_line_speed`). Their difference across the line is the sliding speed across
it, c_g − c_p = V_s·w — an identity of the two independent computations that
``tests/test_wear.py`` checks.

Bookkeeping: the wear depth of a passage is computed at the LTCA's loaded contact-curve
segments (edge contact on the flank boundary is not worn: it is not on the flank grid), in
gear projection-plane fractions for the gear and in the pinion fractions of the mates for
the pinion, and interpolated linearly (Delaunay) onto the nodes of each member's deviation
grid, 0 outside the swept region (Park, Kolivand & Kahraman 2014 interpolate wear depths in
the same way). One *load cycle* is one revolution of the pinion: every pinion tooth meshes
once, every gear tooth z_p/z_g times on average (all teeth wear alike: the toolkit's teeth
are identical). The wear is accumulated as a normal deviation, negative = material removed
(:class:`contact.utca.deviations.SurfaceDeviation`), first order like the deviations
themselves; the contact line speeds are those of the unworn surfaces (µm of wear leave them
unchanged to first order).

Public functions
----------------
archard_depth          depth of one passage of the loaded band, k w |V_s| / c
contact_line_speed     speed of the contact line over a flank per unit roll, 1 / |∇_S Q|
flank_line_speeds      those speeds on the gear grid of an ease-off, gear and pinion
passage_wear           depth of one passage at the loaded segments of an LTCA
depth_on_grid          scattered depths onto a deviation grid (linear, 0 outside)

References
----------
J. F. Archard, "Contact and rubbing of flat surfaces", J. Appl. Phys. 24 (1953) 981–988.
A. Flodin, S. Andersson, "Simulation of mild wear in spur gears", Wear 207 (1997) 16–23.
P. Bajpai, A. Kahraman, N. E. Anderson, "A surface wear prediction methodology for
parallel-axis gear pairs", J. Tribol. 126 (2004) 597–605.
D. Park, A. Kahraman, "A surface wear model for hypoid gear pairs", Wear 267 (2009)
1595–1604 (seed ref. [4.15]).
D. Park, M. Kolivand, A. Kahraman, "An approximate method to predict surface wear of
hypoid gears using surface interpolation", Mech. Mach. Theory 71 (2014) 64–78.
"""

from __future__ import annotations

import logging
import math

import numpy as np
import xarray as xr
from scipy import ndimage
from scipy.interpolate import LinearNDInterpolator, RegularGridInterpolator
from scipy.spatial import QhullError, cKDTree

from contact.utca.easeoff import EaseOff
from friction.kinematics import surface_velocities
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.core.validation import real, real_array
from geometry.machine.flank import flank_at

__all__ = [
    "archard_depth",
    "contact_line_speed",
    "depth_on_grid",
    "flank_line_speeds",
    "passage_wear",
]

log = logging.getLogger(__name__)


#: [mm²/N] per [m²/N]: the wear coefficient is given in m²/N, lengths are in mm
_K_TO_MM = 1e6


#: pinion speed [rpm] at which 1 m/s of surface speed is 1 mm per rad of pinion roll × 1e-3
_UNIT_ROLL_RPM = 60.0 / (2.0 * math.pi)


def archard_depth(load_per_length, sliding_speed, contact_speed, wear_coefficient):
    """Wear depth of one passage of a loaded contact band over a flank point (Archard).

    Parameters
    ----------
    load_per_length : array_like — [N/mm]
        w = ∫ p dx, the load per unit length of the contact line (≥ 0).
    sliding_speed : array_like — [any speed unit]
        |V_s|, the magnitude of the sliding velocity of the two surfaces (≥ 0).
    contact_speed : array_like — [same unit as ``sliding_speed``]
        c > 0, the speed of the contact line across the flank relative to its material.
    wear_coefficient : float — [m²/N]
        Dimensional Archard coefficient k ≥ 0 (= m³/(N·m); converted to mm²/N inside).

    Returns
    -------
    ndarray — [mm]
        h = k w |V_s| / c, broadcast shape; equal to Archard's k p s for a uniform pressure
        p over the band 2b (w = 2bp) and the sliding distance s = 2b |V_s| / c.

    Raises
    ------
    InputError
        Negative or non-finite load or sliding speed, contact speed not > 0, or k < 0.

    Notes
    -----
    Archard (1953); single-point observation of Flodin & Andersson (1997, Eq. 6–7): the
    band passes over a point in 2b / c, during which the surfaces slide |V_s| · 2b / c;
    integrating k p |V_s| dt over the passage gives k w |V_s| / c for any pressure profile.
    """
    w = real_array("load_per_length", load_per_length, unit="N/mm", low=0.0)
    vs = real_array("sliding_speed", sliding_speed, low=0.0)
    c = real_array("contact_speed", contact_speed, low=0.0, low_open=True)
    k = real("wear_coefficient", wear_coefficient, unit="m2/N", low=0.0)
    return k * _K_TO_MM * w * vs / c


def contact_line_speed(position, roll_angle, u, v) -> np.ndarray:
    """Speed of the contact line over a flank per unit pinion roll, c = 1 / |∇_S Q|.

    Parameters
    ----------
    position : array (nu, nv, 3) — [mm]
        Flank points in a frame fixed to the member, over a grid of fractions (u, v)
        (NaN where there is none).
    roll_angle : array (nu, nv) — [rad]
        The pinion roll Q at which each point is on the contact line (the surface of roll
        angle; its iso-lines are the contact lines).
    u, v : array (nu,), (nv,) — [1]
        Uniformly spaced grid fractions (≥ 3 each).

    Returns
    -------
    ndarray (nu, nv) — [mm/rad]
        c = 1 / |∇_S Q| with |∇_S Q|² = (Q_u, Q_v) G⁻¹ (Q_u, Q_v)ᵀ, G the first fundamental
        form of the position over (u, v) (second-order central differences, second-order
        one-sided at the grid edges); NaN where a neighbour is missing or Q is stationary.

    Raises
    ------
    InputError
        Shapes that do not match, fewer than 3 nodes, or a non-uniform grid.

    Notes
    -----
    The contact line at roll q is the iso-line Q = q (seed §2.3.2.2); an iso-line of a
    field moves along its gradient at the speed dq/dt / |∇Q| (level-set kinematics), here
    per unit dq. Used for the sliding distance of the single-point observation
    (:func:`archard_depth`).
    """
    r = np.asarray(position, dtype=float)
    q = np.asarray(roll_angle, dtype=float)
    uu = np.asarray(u, dtype=float)
    vv = np.asarray(v, dtype=float)
    if uu.ndim != 1 or vv.ndim != 1 or uu.size < 3 or vv.size < 3:
        raise InputError(f"u, v: must be 1-D grids of at least 3 fractions, got shapes "
                         f"{uu.shape}, {vv.shape}")
    if r.shape != (uu.size, vv.size, 3) or q.shape != (uu.size, vv.size):
        raise InputError(f"position, roll_angle: must have shapes (nu, nv, 3), (nu, nv) = "
                         f"({uu.size}, {vv.size}[, 3]), got {r.shape}, {q.shape}")
    du, dv = np.diff(uu), np.diff(vv)
    if not (np.allclose(du, du[0], rtol=1e-9) and np.allclose(dv, dv[0], rtol=1e-9)
            and du[0] > 0 and dv[0] > 0):
        raise InputError("u, v: must be uniformly spaced increasing fractions")
    ru = np.gradient(r, du[0], axis=0, edge_order=2)
    rv = np.gradient(r, dv[0], axis=1, edge_order=2)
    qu = np.gradient(q, du[0], axis=0, edge_order=2)
    qv = np.gradient(q, dv[0], axis=1, edge_order=2)
    e = np.sum(ru * ru, -1)
    f = np.sum(ru * rv, -1)
    g = np.sum(rv * rv, -1)
    with np.errstate(divide="ignore", invalid="ignore"):
        grad2 = (g * qu * qu - 2.0 * f * qu * qv + e * qv * qv) / (e * g - f * f)
        c = 1.0 / np.sqrt(grad2)
    return np.where(np.isfinite(c) & (grad2 > 0), c, np.nan)


def flank_line_speeds(case: Case, eo: EaseOff) -> tuple[np.ndarray, np.ndarray]:
    """Speeds of the contact line over the gear flank and over the pinion flank.

    Parameters
    ----------
    case : geometry.case.Case
        The case of ``eo``.
    eo : contact.utca.easeoff.EaseOff
        Its ease-off (theoretical surfaces).

    Returns
    -------
    (gear, pinion) : ndarray (nu, nv) each — [mm/rad]
        :func:`contact_line_speed` on the gear grid of ``eo``: over the gear flank
        (``eo.gear_position``) and over the pinion flank (the pinion mates of the gear
        nodes, solved with :func:`geometry.machine.flank.flank_at` in the pinion frame), per unit
        pinion roll; NaN where undefined.

    Raises
    ------
    InputError
        If ``eo`` is not an EaseOff.

    Notes
    -----
    Both use the roll-angle surface Q (``eo.raw_roll_angle``, seed §2.3.2.2): a gear node
    and its pinion mate are on the contact line at the same roll.
    """
    if not isinstance(eo, EaseOff):
        raise InputError(f"eo: must be a contact.utca.easeoff.EaseOff, got {type(eo).__name__}")
    q = np.asarray(eo.raw_roll_angle, dtype=float)
    gear = contact_line_speed(eo.gear_position, q, eo.u, eo.v)
    have = np.isfinite(eo.pinion_axial) & np.isfinite(eo.pinion_radius)
    mates = np.full(eo.gear_position.shape, np.nan)
    if have.any():
        fs = flank_at(case, "pinion", eo.pinion_flank, eo.pinion_axial[have],
                      eo.pinion_radius[have])
        mates[have] = fs.position
    pinion = contact_line_speed(mates, q, eo.u, eo.v)
    return gear, pinion


def _on_gear_grid(eo: EaseOff, field: np.ndarray, u: np.ndarray, v: np.ndarray, *,
                  fill: bool = False) -> np.ndarray:
    """A field over the gear grid of ``eo`` at gear fractions (u, v), bilinear; NaN outside
    the grid or next to a missing node.

    ``fill``: in a cell with some missing nodes (at the edge of the computed region: e.g.
    a pinion row beyond its blank, masked by the ease-off) the missing nodes take their
    nearest computed node's value, so a loaded segment there still gets a smooth field's
    value (NaN only in a cell with no computed node); in a cell whose nodes are all
    computed this is the plain bilinear value."""
    if not u.size:
        return np.zeros(0)
    pts = np.stack([u, v], -1)
    ok = np.isfinite(field)
    if not fill or ok.all() or not ok.any():
        return RegularGridInterpolator((eo.u, eo.v), field, bounds_error=False,
                                       fill_value=np.nan)(pts)
    idx = ndimage.distance_transform_edt(~ok, return_distances=False, return_indices=True)
    filled = field[tuple(idx)]
    value = RegularGridInterpolator((eo.u, eo.v), filled, bounds_error=False,
                                    fill_value=np.nan)(pts)
    near = RegularGridInterpolator((eo.u, eo.v), ok.astype(float), bounds_error=False,
                                   fill_value=0.0)(pts) > 0
    return np.where(near, value, np.nan)


def passage_wear(ltca: xr.Dataset, eo: EaseOff, speeds: tuple[np.ndarray, np.ndarray],
                 wear_coefficient: float, *, torque_index: int = 0) -> dict[str, np.ndarray]:
    """Wear depth of one passage at the contact-curve segments of an LTCA.

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset of :func:`contact.ltca.loaded_tca` (``load_per_length``,
        ``force``, ``segment_u``, ``segment_v``, ``segment_kind``, ``contact_point``,
        ``contact_normal``, ``contact_tangent``, the axes in its attributes).
    eo : contact.utca.easeoff.EaseOff
        The ease-off of the case (the pinion mates ``pinion_u``, ``pinion_v`` of its gear
        grid).
    speeds : (gear, pinion) arrays (nu, nv) — [mm/rad]
        Contact line speeds over the flanks on the gear grid of ``eo``
        (:func:`flank_line_speeds`).
    wear_coefficient : float — [m²/N]
        Archard's k ≥ 0.
    torque_index : int
        Which torque of ``ltca``.

    Returns
    -------
    dict of 1-D arrays over the contact-curve segments with finite fractions
        ``gear_u``, ``gear_v`` (gear fractions), ``pinion_u``, ``pinion_v`` (pinion
        fractions of the mates, NaN where none) [1]; ``load_per_length`` [N/mm] (0 where
        unloaded); ``sliding_speed``, ``sliding_across`` [mm/rad] (per unit pinion roll);
        ``gear_speed``, ``pinion_speed`` [mm/rad]; ``gear_depth``, ``pinion_depth`` [mm]
        (one passage, :func:`archard_depth`; 0 where unloaded).

    Raises
    ------
    InputError
        Missing variables, bad ``speeds`` shapes or a bad wear coefficient; a loaded
        segment without a finite contact line speed.

    Notes
    -----
    Edge segments (load on the flank boundary, :data:`contact.ltca.EDGE_KINDS`) are left
    out: their load is not on the flank grid (logged at INFO with its share).
    """
    need = ("load_per_length", "force", "segment_u", "segment_v", "segment_kind",
            "contact_point", "contact_normal", "contact_tangent")
    missing = [n for n in need if n not in ltca.variables]
    if missing:
        raise InputError(f"ltca: dataset lacks {missing} (expected contact.ltca.loaded_tca "
                         "output)")
    g_speed, p_speed = (np.asarray(s, dtype=float) for s in speeds)
    if g_speed.shape != eo.raw_roll_angle.shape or p_speed.shape != g_speed.shape:
        raise InputError(f"speeds: must be two arrays of the ease-off grid shape "
                         f"{eo.raw_roll_angle.shape}")
    k = real("wear_coefficient", wear_coefficient, unit="m2/N", low=0.0)
    w = np.nan_to_num(ltca["load_per_length"].values[torque_index])  # (J, K, S)
    force = np.nan_to_num(ltca["force"].values[torque_index])
    su = ltca["segment_u"].values
    sv = ltca["segment_v"].values
    curve = (ltca["segment_kind"].values == "curve")[None, None, :]
    take = curve & np.isfinite(su) & np.isfinite(sv)
    edge_force = float(force[~np.broadcast_to(curve, force.shape)].sum())
    if edge_force > 0:
        log.info("passage_wear: %.3g %% of the load is edge contact (not worn)",
                 100 * edge_force / max(float(force.sum()), 1e-300))
    wt = np.where(force[take] > 0, w[take], 0.0)
    su, sv = su[take], sv[take]
    kin = surface_velocities(
        ltca["contact_point"].values[take], ltca["contact_normal"].values[take],
        ltca["contact_tangent"].values[take],
        pinion_axis=ltca.attrs["pinion_axis"], pinion_origin=ltca.attrs["pinion_origin_mm"],
        gear_axis=ltca.attrs["gear_axis"], gear_origin=ltca.attrs["gear_origin_mm"],
        pinion_speed=_UNIT_ROLL_RPM, ratio=float(ltca.attrs["ratio"]), check_meshing=False)
    vs = kin["sliding_velocity"] * 1e3  # m/s at 1 rad/s → mm/rad
    # the line speeds are smooth fields: a segment beside a missing node takes the computed
    # nodes' values (the mates below stay strict: NaN there, that pinion point is not worn)
    c_g = _on_gear_grid(eo, g_speed, su, sv, fill=True)
    c_p = _on_gear_grid(eo, p_speed, su, sv, fill=True)
    loaded = wt > 0
    bad = loaded & ~(np.isfinite(c_g) & np.isfinite(c_p) & (c_g > 0) & (c_p > 0))
    if bad.any():
        raise InputError(f"speeds: no contact line speed at {int(bad.sum())} loaded "
                         "segments (outside the ease-off's computed nodes)")
    gd = np.zeros(su.shape)
    pd = np.zeros(su.shape)
    if loaded.any():
        gd[loaded] = archard_depth(wt[loaded], vs[loaded], c_g[loaded], k)
        pd[loaded] = archard_depth(wt[loaded], vs[loaded], c_p[loaded], k)
    return {
        "gear_u": su, "gear_v": sv,
        "pinion_u": _on_gear_grid(eo, np.asarray(eo.pinion_u, float), su, sv),
        "pinion_v": _on_gear_grid(eo, np.asarray(eo.pinion_v, float), su, sv),
        "load_per_length": wt, "sliding_speed": vs,
        "sliding_across": kin["sliding_across"] * 1e3,
        "gear_speed": c_g, "pinion_speed": c_p,
        "gear_depth": gd, "pinion_depth": pd,
    }


def depth_on_grid(u, v, depth, grid_u, grid_v) -> np.ndarray:
    """Scattered wear depths interpolated onto the nodes of a deviation grid.

    Parameters
    ----------
    u, v : array_like (N,) — [1]
        Fractions of the points where the depth is known (NaN: left out).
    depth : array_like (N,) — [mm]
        Depths ≥ 0 there (0 on the unloaded parts of the contact lines).
    grid_u, grid_v : array_like (nu,), (nv,) — [1]
        The grid's fractions.

    Returns
    -------
    ndarray (nu, nv) — [mm]
        Linear interpolation over the Delaunay triangulation of the points (duplicate
        points, e.g. the same contact line of two tooth pairs one pitch apart, averaged);
        outside their convex hull the nearest point's depth at nodes within half a grid
        cell (max(Δu, Δv) / 2) of a point — the flank's edges, which the contact lines
        reach but the segment midpoints do not — and 0 beyond (no wear where no contact
        line passes). ≥ 0.

    Raises
    ------
    InputError
        Mismatched lengths or negative depths.

    Notes
    -----
    Park, Kolivand & Kahraman (2014) fit wear depths over the flank from the contact
    zones in the same way (surface interpolation).
    """
    u = np.asarray(u, dtype=float).ravel()
    v = np.asarray(v, dtype=float).ravel()
    d = np.asarray(depth, dtype=float).ravel()
    if not (u.size == v.size == d.size):
        raise InputError(f"u, v, depth: must have equal lengths, got {u.size}, {v.size}, "
                         f"{d.size}")
    ok = np.isfinite(u) & np.isfinite(v) & np.isfinite(d)
    if np.any(d[ok] < 0):
        raise InputError("depth: must be >= 0 [mm]")
    grid_u = np.asarray(grid_u, dtype=float).ravel()
    grid_v = np.asarray(grid_v, dtype=float).ravel()
    gu, gv = np.meshgrid(grid_u, grid_v, indexing="ij")
    if ok.sum() < 3 or not np.any(d[ok] > 0):
        return np.zeros(gu.shape)
    pts = np.round(np.stack([u[ok], v[ok]], -1), 10)
    uniq, inv = np.unique(pts, axis=0, return_inverse=True)
    inv = inv.ravel()
    mean = np.bincount(inv, weights=d[ok]) / np.bincount(inv)
    try:
        interp = LinearNDInterpolator(uniq, mean, fill_value=np.nan)
    except QhullError as exc:  # all points on a line
        log.info("depth_on_grid: no triangulation of the contact points (%s)", exc)
        return np.zeros(gu.shape)
    out = interp(gu, gv)
    outside = np.isnan(out)
    if outside.any():
        reach = 0.5 * max(float(np.max(np.diff(grid_u))), float(np.max(np.diff(grid_v))))
        dist, near = cKDTree(uniq).query(np.stack([gu[outside], gv[outside]], -1))
        out[outside] = np.where(dist <= reach, mean[near], 0.0)
    return np.maximum(out, 0.0)
