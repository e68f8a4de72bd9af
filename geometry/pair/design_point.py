"""The mean contact point M of a gear flank: the design point of a pair (projection plane).

The point where the local synthesis (:mod:`geometry.synthesis.case_synthesis`; Litvin & Fuentes
2004 ch. 9) places the contact of the mean roll position and where the conventional TCA
(:mod:`geometry.pair.conventional_tca`) takes its reference (roll 0): on the gear flank at the
gear's mean cone distance, centred in roll within the working depth, i.e. the point that the
ideal motion brings onto the surface of action n·v⁽¹²⁾ = 0 halfway through the roll range
between the gear tip and the lowest point the pinion tip reaches. A module below both
:mod:`geometry.synthesis.case_synthesis` (which re-exports these functions) and
:mod:`geometry.pair.conventional_tca`, so that neither imports the other for it.

Public functions
----------------
mean_addendum          mean addendum of a case blank (ISO 23509)
action_rotation        gear rotation at which gear-frame points lie on the surface of action
design_point           mean contact point M on a gear flank (projection plane)
design_point_of_case   the same for a case and pinion flank
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from geometry.case import Blank, Case
from geometry.core.errors import InputError
from geometry.core.validation import real
from geometry.machine.cradle import MachineSettings
from geometry.machine.cutter import Blade, working_sections
from geometry.machine.flank import blank_outline
from geometry.machine.flank_point import FlankPoint, flank_points
from geometry.pair.assembly import member_transform

__all__ = ["action_rotation", "design_point", "design_point_of_case", "mean_addendum"]

_OTHER = {"concave": "convex", "convex": "concave"}


def _depth_missed(offs: np.ndarray, ok: np.ndarray) -> str:
    """Where on the working-depth line :func:`mean_point` checks the gear flank is not
    generated, in words: ``offs`` [mm] the points' heights above the gear's pitch cone (the
    first the lowest point the pinion tip reaches, −h_am1; the last the gear tip, h_am2),
    ``ok`` which are generated. The FM spiral bevel 14x19 at Sigma 60 deg (round 36 of
    issue 71's unseen designs, branch unseen98) stopped every gear process on the bare
    sentence; its generated gear missed the lowest of the nine points only (an envelope
    solver's miss on the 1-D line, recovered by :func:`_line_points` since branch gen98)."""
    bad = np.flatnonzero(~ok)
    if bad.size == 0:
        return ""
    at = (f"{offs[bad[0]]:+.2f} mm" if bad.size == 1
          else f"{offs[bad].min():+.2f} to {offs[bad].max():+.2f} mm")
    where = ("its lowest point, where the pinion tip reaches" if bad.tolist() == [0]
             else "the gear tip" if bad.tolist() == [len(offs) - 1]
             else f"{bad.size} of its {len(offs)} points")
    return (f": {where}, at {at} from the pitch cone, is not generated (the line runs "
            f"{offs[0]:+.2f} to {offs[-1]:+.2f} mm: the pinion's mean addendum below the "
            "pitch cone to the gear's above)")


def mean_addendum(blank: Blank) -> float:
    """Mean addendum h_am [mm] of a case blank: h_ae − (b/2) tan(δ_a − δ) (ISO 23509 cl. 6).

    Parameters
    ----------
    blank : geometry.case.Blank

    Returns
    -------
    float — [mm]
    """
    return blank.outer_addendum - 0.5 * blank.face_width * math.tan(
        blank.face_angle - blank.pitch_angle)


def action_rotation(points, normals, pinion_blank: Blank, gear_blank: Blank, *,
                    shaft_angle: float, offset: float, gear_hand: str) -> np.ndarray:
    """Gear rotation at which gear-frame points lie on the surface of action of the pair.

    Parameters
    ----------
    points : array_like (K, 3) — [mm]
        Gear flank points in the gear frame.
    normals : array_like (K, 3) — [1]
        Their unit normals, out of the gear material.
    pinion_blank, gear_blank : geometry.case.Blank
    shaft_angle : float — [rad]
    offset : float — [mm]
    gear_hand : str
        ``"right"`` or ``"left"`` (the assembly of :func:`geometry.pair.assembly.member_transform`,
        nominal, pinion at rotation 0).

    Returns
    -------
    ndarray (K,) — [rad]
        For each point the gear rotation φ_g in [−π, π] (right-handed about the gear's +z)
        at which n · v⁽¹²⁾ = 0 for the ideal motion (members turning in opposite senses at
        z1/z2) and the point is in the mesh zone (x > 0 in the pair frame); of several, the
        one whose place in the pinion projection plane is nearest the pinion's mean point.
        NaN where there is none.

    Raises
    ------
    InputError
        For a bad hand or shaft angle (:func:`geometry.pair.assembly.member_transform`).

    Notes
    -----
    Surface of action of the ideal motion (Litvin & Fuentes 2004 ch. 6; seed Eq. 2.19 with
    R = z2/z1), v⁽¹²⁾ = ω₁ × (r − o₁) − ω₂ × (r − o₂). Scan over 721 gear rotations, each
    sign change refined by Brent's method (1e-15 rad).
    """
    points = np.asarray(points, dtype=float)
    normals = np.asarray(normals, dtype=float)
    kw = dict(shaft_angle=shaft_angle, offset=offset, gear_hand=gear_hand)
    ratio = pinion_blank.teeth / gear_blank.teeth
    tp = member_transform("pinion", **kw)
    a_p, o_p = tp[:3, 2], tp[:3, 3]
    pm1 = blank_outline(pinion_blank).mean_point

    def state(phi_g, k):
        tg = member_transform("gear", rotation=phi_g, **kw)
        rot = tg[..., :3, :3]
        r = np.einsum("...ij,j->...i", rot, points[k]) + tg[..., :3, 3]
        n = -np.einsum("...ij,j->...i", rot, normals[k])
        v12 = np.cross(a_p, r - o_p) + ratio * np.cross(tg[..., :3, 2], r - tg[..., :3, 3])
        return (n * v12).sum(-1), r

    grid = np.linspace(-math.pi, math.pi, 721)
    out = np.full(len(points), np.nan)
    for k in range(len(points)):
        vals, rs = state(grid, k)
        best = None
        for i in np.flatnonzero(vals[:-1] * vals[1:] < 0):
            if rs[i, 0] <= 0:
                continue
            x = brentq(lambda g, k=k: float(state(g, k)[0]), grid[i], grid[i + 1],
                       xtol=1e-15, rtol=1e-15)
            r = state(x, k)[1]
            loc = tp[:3, :3].T @ (r - o_p)
            dist = math.hypot(loc[2] - pm1[0], math.hypot(loc[0], loc[1]) - pm1[1])
            if best is None or dist < best[0]:
                best = (dist, x)
        if best is not None:
            out[k] = best[1]
    return out


def design_point(gear_blade: Blade, gear_settings: MachineSettings, gear_blank: Blank,
                 pinion_blank: Blank, *, gear_hand: str, shaft_angle: float,
                 offset: float, shift: float = 0.0) -> np.ndarray:
    """Projection-plane place (z, ρ) [mm] of the mean contact point M on a gear flank.

    Parameters
    ----------
    gear_blade, gear_settings : geometry.machine.cutter.Blade,
    geometry.machine.cradle.MachineSettings
        The tool of the gear flank (right-hand reference settings).
    gear_blank, pinion_blank : geometry.case.Blank
    gear_hand : str
        ``"right"`` or ``"left"``.
    shaft_angle : float — [rad]
        Σ.
    offset : float — [mm]
        Hypoid offset E (ISO 23509 sign).
    shift : float, optional — [1]
        M placed off the mean cone distance by ``shift`` × the gear face width along the
        pitch generatrix, > 0 towards the heel (default 0: at the mean cone distance);
        in (−0.5, 0.5). The local synthesis' M may lie anywhere on the flank (Litvin &
        Fuentes 2004 §9.2); placed towards the toe it moves the bearing towards the toe
        (the development's lever for the pattern's centre along the face,
        ``mean_point_shift`` of :class:`geometry.synthesis.basic_design.FlankOptions`).

    Returns
    -------
    ndarray (2,) — [mm]
        On the normal to the pitch cone at the gear's mean cone distance (moved by
        ``shift``), between the gear
        tip (h_am2 above the pitch cone) and the lowest point the pinion tip reaches (h_am1
        below it; h_am the mean addenda), the point that the ideal motion brings onto the
        surface of action at the middle of the roll range of that working depth.

    Raises
    ------
    InputError
        If the working-depth line is not generated or never meets the surface of action,
        or ``shift`` is out of range.

    Notes
    -----
    Over a mesh cycle the contact of a localised bearing crosses the profile at the speed of
    the conjugate contact lines (fixed by the kinematics; for a face-milled Formate pair the
    lines run nearly lengthwise), i.e. about one working depth per pitch of roll. Centring M
    in roll, rather than at the pitch point or the middle of the depth, keeps the contact on
    both flanks for as long as possible on either side of M. Each point's roll is the gear
    rotation at which it meets the surface of action of the ideal motion (n·v⁽¹²⁾ = 0,
    Litvin & Fuentes 2004 ch. 6), interpolated over nine points of the line.
    """
    shift = real("mean_point_shift", shift, unit="1, fraction of the face width", low=-0.5,
                 high=0.5, low_open=True, high_open=True)
    pm = blank_outline(gear_blank).mean_point
    d = gear_blank.pitch_angle
    up = np.array([-math.sin(d), math.cos(d)])
    if shift:
        pm = pm + shift * gear_blank.face_width * np.array([math.cos(d), math.sin(d)])
    lo, hi = -mean_addendum(pinion_blank), mean_addendum(gear_blank)
    offs = np.linspace(lo, hi, 9)
    zp = pm + offs[:, None] * up
    pt = _line_points(gear_blade, gear_settings, gear_blank, gear_hand, zp)
    if not pt.ok.all():
        raise InputError("synthesis: the gear flank is not generated along the working depth "
                         f"at the mean cone distance{_depth_missed(offs, np.asarray(pt.ok))}")
    if gear_settings.process == "Generate":
        lo = _generated_flank_start(gear_blade, gear_settings, gear_blank, gear_hand, pm, up,
                                    offs, pt.params[:, 3])
        if lo > offs[0]:
            offs = np.linspace(lo, hi, 9)
            zp = pm + offs[:, None] * up
            pt = _line_points(gear_blade, gear_settings, gear_blank, gear_hand, zp)
            if not pt.ok.all():
                raise InputError("synthesis: the gear flank is not generated along the "
                                 "working depth at the mean cone distance")
    q = action_rotation(pt.r, pt.n, pinion_blank, gear_blank, shaft_angle=shaft_angle,
                        offset=offset, gear_hand=gear_hand)
    if not np.all(np.isfinite(q)) or not (np.all(np.diff(q) > 0) or np.all(np.diff(q) < 0)):
        raise InputError("synthesis: the working depth does not cross the surface of action "
                         "monotonically; cannot centre the mean point")
    target = 0.5 * (q[0] + q[-1])
    order = np.argsort(q)
    o = float(np.interp(target, q[order], offs[order]))
    return pm + o * up


def _line_points(blade: Blade, settings: MachineSettings, blank: Blank, hand: str,
                 zp: np.ndarray) -> FlankPoint:
    """:func:`geometry.machine.flank_point.flank_points` at the working-depth line's points
    ``zp`` (n, 2) [mm, (z, ρ)]; on a generated flank the points the line's solve misses are
    solved alone (each its own seed search) and the line solved again from those roots and
    its own (its ``guess``), so that each recovered point passes the line's checks against
    the line's seed (the undercut test's sign of ∂f/∂q, the blade sections).

    Why: the envelope solver continues from converged neighbours on 2-D grids only; on this
    1-D line every point is predicted from the middle one (first order), and across a blade
    section junction Newton may not converge from that prediction (nor from a neighbour's on
    the other section). The FM spiral bevel 14x19 at Sigma 60 deg (issue 71, round 36;
    branch gen98) lost its generated gear so: the line's lowest point, -4.79 mm (the pinion
    tip's reach), cut by the gear blade's edge radius (s 0.78 mm, section 0), solves alone
    but not from the middle point 3.2 mm above it on the profile section (at beta_m 42 deg,
    -4.34 mm, not from its neighbour 0.72 mm above either). A Formate gear's line is not
    retried: the auto process choice
    (:func:`geometry.synthesis.case_synthesis.gear_processes`) follows the Formate gear's
    failures, and a point its imprint misses is the documented Formate limit."""
    pt = flank_points(blade, settings, blank, hand, zp[:, 0], zp[:, 1])
    ok = np.asarray(pt.ok)
    if ok.all() or not ok.any() or settings.process != "Generate":
        return pt
    guess = np.array(pt.params, dtype=float)
    for k in np.flatnonzero(~ok):
        alone = flank_points(blade, settings, blank, hand, zp[k:k + 1, 0], zp[k:k + 1, 1])
        if bool(alone.ok[0]):
            guess[k] = alone.params[0]
    if not np.isfinite(guess[~ok]).any():
        return pt
    return flank_points(blade, settings, blank, hand, zp[:, 0], zp[:, 1], guess=guess)


def _generated_flank_start(blade: Blade, settings: MachineSettings, blank: Blank, hand: str,
                           pm: np.ndarray, up: np.ndarray, offs: np.ndarray,
                           sections: np.ndarray) -> float:
    """Lowest offset [mm] along the working-depth line ``pm + o up`` that a generated flank's
    working blade sections cut: a generated gear's fillet (the envelope of the edge radius
    in roll) rises above a Formate gear's and may reach into the working depth; the mean
    point is centred on the flank above it. ``offs`` the sampled offsets, ``sections``
    their blade sections (:func:`geometry.machine.cutter.profile_sections` index)."""
    work = np.isin(sections, working_sections(blade))
    if work[0]:
        return float(offs[0])
    if not work.any():
        raise InputError("synthesis: the generated gear flank's fillet covers the working "
                         "depth at the mean cone distance; give a smaller edge_radius")
    k = int(np.argmax(work))
    a, b = float(offs[k - 1]), float(offs[k])
    for _ in range(30):  # bisection to ~1e-9 of the depth step
        c = 0.5 * (a + b)
        z, p = pm + c * up
        pc = flank_points(blade, settings, blank, hand, [z], [p])
        if pc.ok[0] and np.isin(pc.params[0, 3], working_sections(blade)):
            b = c
        else:
            a = c
    return b


def design_point_of_case(case: Case, flank: str) -> np.ndarray:
    """:func:`design_point` of the gear flank that meshes pinion flank ``flank`` of a case.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str
        Pinion flank (``"concave"`` or ``"convex"``).

    Returns
    -------
    ndarray (2,) — [mm]
        (z, ρ) in the gear projection plane.

    Raises
    ------
    InputError
        For a bad flank name, or as :func:`design_point`.
    """
    if flank not in _OTHER:
        raise InputError(f"flank: must be one of {list(_OTHER)} (the pinion flank), got "
                         f"{flank!r}")
    tool = case.gear.flank(_OTHER[flank])
    return design_point(tool.blade, tool.machine, case.gear.blank, case.pinion.blank,
                        gear_hand=case.gear.hand, shaft_angle=case.pair.shaft_angle,
                        offset=case.pair.offset)
