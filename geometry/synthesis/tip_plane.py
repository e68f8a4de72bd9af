"""The blade-tip plane of a separately cut (Generate) flank: where its cut's bottom lies.

A face-milling blade is its cutting edge above a flat tip; the tip plane is the datum of
every blade height (point radius r_p at h = 0, the edge radius tangent to it, the profile
and relief heights above it). Moving the tip plane along the cutter axis while the cutting
surface stays where it is changes nothing on the flank and everything at the root: the
edge radius, the fillet and the slot bottom move with the tip. That is the blade's **tip
height** over the flank, the one free setting of a separately cut flank's depth.

The synthesis (:func:`geometry.synthesis.case_synthesis.synthesize`) copies the Formate
gear's cutter for the pinion's (cutter axis = the gear cutter's, Litvin & Fuentes 2004
ch. 20), so the generated pinion root line runs along the gear's root cone, not parallel
to the gear's face cone as the ISO 23509 pinion root cone does: the two differ by the
gear's addendum plus dedendum angle (6° on the default case), a uniform-depth pinion slot
under a tapered-depth blank. No tip height makes such a root line lie on the root cone;
the one that makes it **touch the root cone and lie nowhere above it** leaves the gear's
tip its clearance along the whole face and cuts no deeper than that needs
(:func:`tip_plane_on_root_cone`), for each cut separately — so both cuts of a slot reach
the root cone where their root lines are highest, and their bottoms differ only by the
difference of their root lines' inclinations (docs/fe.md, "Root and slot bottom").

Public functions
----------------
move_tip_plane           the same cutting surface with its tip plane moved along the axis
generated_root_line      the root line one cut generates and its depth below the root cone
tip_plane_on_root_cone   the tip plane whose root line touches the root cone from below
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import NamedTuple

import numpy as np
from scipy.optimize import minimize_scalar

from geometry.case import Blank
from geometry.core.errors import InputError
from geometry.machine.cradle import MachineSettings
from geometry.machine.cutter import Blade
from geometry.machine.root_line import below_root_cone, root_line_points

__all__ = [
    "RootLine",
    "TipPlacement",
    "generated_root_line",
    "move_tip_plane",
    "tip_plane_on_root_cone",
]

#: [mm] the root line touches the root cone when its highest point lies this close to it
#: (the generated points are solved to 1e-10 mm; tight, so that a case re-placed from its
#: file reproduces the synthesis to round-off)
TOUCH_TOLERANCE = 1e-9
#: lengthwise fractions where the root line is first sampled (then refined at its highest)
_U_SAMPLES = np.linspace(0.0, 1.0, 11)


def move_tip_plane(blade: Blade, settings: MachineSettings, depth: float
                   ) -> tuple[Blade, MachineSettings]:
    """The blade and settings of the same cutting surface with the tip plane ``depth``
    further along the cutter axis (towards the work: a deeper cut).

    Parameters
    ----------
    blade : geometry.machine.cutter.Blade — a face-milling blade (not placed off the
        head's axial plane)
    settings : geometry.machine.cradle.MachineSettings — its machine settings
    depth : float — [mm] Δ, the tip plane's move along the cutter axis towards the tips
        (> 0 deeper, < 0 shallower)

    Returns
    -------
    (Blade, MachineSettings)
        Every height above the tip grows by Δ (circular profile reference, toprem and
        flankrem heights), the point radius becomes r_p − σ Δ tan α (the nominal line's
        radius at the new tip plane; σ = +1 outside, −1 inside blade); in the machine
        chain the cutter frame is moved by T(0, 0, Δ): its component along the cradle axis
        Δ cos i goes to the sliding base (a shift along the cradle axis commutes with the
        cradle's rotation), the rest Δ sin i (sin j, −cos j) in the cradle plane changes
        the radial setting and turns the cradle angle by δ and the swivel by −δ.

    Raises
    ------
    InputError
        A placed (face-hobbing) blade; a move that leaves a height of the profile below
        the tip (the circular profile's reference height below 0, the toprem corner
        below the edge radius), named by the field.

    Notes
    -----
    The chain is that of :func:`geometry.machine.cradle.machine_transform` (seed
    Eq. 2.7a): M(q) = … R_z(q_c + q) T(S_r, 0, 0) R_z(j) R_x(i); the new settings give
    M'(q) = M(q) T(0, 0, Δ) for every roll q, modified roll and helical motion included
    (tests/test_generated_root.py checks it to 1e-12 mm and that the generated flank is
    unchanged).
    """
    if blade.placed:
        raise InputError("blade: a placed (face-hobbing) blade's tip plane is not moved here")
    d = float(depth)
    if not math.isfinite(d):
        raise InputError(f"depth: must be a finite length [mm], got {depth}")
    sg = blade.sigma
    fields = {"point_radius": blade.point_radius - sg * d * math.tan(blade.blade_angle)}
    if blade.profile == "circular":
        fields["profile_reference_height"] = blade.profile_reference_height + d
    if blade.toprem_angle != 0.0:
        fields["toprem_height"] = blade.toprem_height + d
    if blade.flankrem_angle != 0.0:
        fields["flankrem_height"] = blade.flankrem_height + d
    try:
        new_blade = replace(blade, **fields)
    except InputError as exc:
        raise InputError(f"depth: moving the tip plane by {d:.4g} mm leaves the blade "
                         f"invalid ({exc})") from None
    i, j = settings.tilt, settings.swivel
    a = d * math.sin(i) * math.sin(j)  # R_z(j) R_x(i) (0, 0, Δ) = Δ (sin i sin j,
    b = -d * math.sin(i) * math.cos(j)  # −sin i cos j, cos i)
    x = settings.radial_setting + a
    delta = math.atan2(b, x)
    new_settings = replace(settings, radial_setting=math.hypot(x, b),
                           cradle_angle=settings.cradle_angle + delta,
                           swivel=settings.swivel - delta,
                           sliding_base=settings.sliding_base + d * math.cos(i))
    return new_blade, new_settings


class RootLine(NamedTuple):
    """The root line one cut generates (:func:`generated_root_line`)."""

    u: np.ndarray  # (K,) [1] lengthwise fractions of the sections
    v: np.ndarray  # (K,) [1] profile fraction of the root-line point (NaN: not generated)
    depth: np.ndarray  # (K,) [mm] its depth below the blank's root cone (< 0: above)


def generated_root_line(blade: Blade, settings: MachineSettings, blank: Blank, hand: str,
                        u=_U_SAMPLES) -> RootLine:
    """The root line a cut generates: where its blade's edge radius leaves the tip plane.

    Parameters
    ----------
    blade, settings : the cut's blade and machine settings
    blank : geometry.case.Blank — the member's blank (its root cone is the datum)
    hand : str — ``"left"`` or ``"right"``
    u : array_like (K,) — [1] lengthwise fractions (toe 0, heel 1), K ≥ 1

    Returns
    -------
    RootLine — per section the profile fraction v and the depth [mm] below the root
    cone, perpendicular to its generatrix (:func:`geometry.machine.root_line.
    below_root_cone`).

    Notes
    -----
    The points are the generated points of the blade's s = 0 edge point (seed Eq. 2.7a,
    2.8 solved on each transverse section: :func:`geometry.machine.root_line.
    root_line_points`), the same points as the FE tooth's ``ToothSections.root_line``.
    """
    u = np.atleast_1d(np.asarray(u, dtype=float))
    v = root_line_points(blade, settings, blank, hand, u)[:, 0]
    return RootLine(u, v, below_root_cone(blank, u, v))


class TipPlacement(NamedTuple):
    """Result of :func:`tip_plane_on_root_cone`."""

    blade: Blade
    settings: MachineSettings
    moved: float  # [mm] Δ of :func:`move_tip_plane` from the given tip plane
    u_touch: float  # [1] lengthwise fraction where the root line touches the root cone
    root_line: RootLine  # of the placed tip plane at the sample fractions


def tip_plane_on_root_cone(blade: Blade, settings: MachineSettings, blank: Blank,
                           hand: str, *, tol: float = TOUCH_TOLERANCE) -> TipPlacement:
    """The tip plane whose generated root line touches the blank's root cone from below.

    Parameters
    ----------
    blade, settings : a Generate cut's blade and machine settings (face milling)
    blank : geometry.case.Blank
    hand : str
    tol : float — [mm] accepted distance of the root line's highest point from the
        root cone (default 1e-9 mm)

    Returns
    -------
    TipPlacement — the moved blade and settings (:func:`move_tip_plane`), the move Δ
    [mm], where the root line touches (its highest point relative to the root cone over
    the face width) and the placed root line at 11 fractions.

    Raises
    ------
    InputError — a blade :func:`move_tip_plane` refuses; a root line not generated over
    the face width (no tip height exists).

    Notes
    -----
    The root line must not rise above the root cone anywhere along the face (the mating
    member's face cone keeps its clearance there, ISO 23509's whole depth) and should not
    run deeper than that needs (it weakens the tooth): its highest point is put on the
    root cone. Its height over the face is sampled at 11 sections and refined by a
    bounded scalar search between the neighbours of the highest; the move is solved by
    secant steps (the root line moves with the tip plane nearly one to one).
    """
    if settings.process != "Generate":
        raise InputError("settings: only a Generate cut's tip plane is placed on the root "
                         "cone (a Formate tip plane holds a root generatrix already)")

    def highest(b: Blade, s: MachineSettings) -> tuple[float, float]:
        line = generated_root_line(b, s, blank, hand)
        if not np.all(np.isfinite(line.depth)):
            bad = line.u[~np.isfinite(line.depth)]
            raise InputError(f"{blade.side} blade: its root line is not generated at face "
                             f"fractions {np.round(bad, 2).tolist()}; no tip height puts it "
                             "on the root cone")
        k = int(np.argmin(line.depth))
        u_best, d_best = float(line.u[k]), float(line.depth[k])
        lo, hi = float(line.u[max(k - 1, 0)]), float(line.u[min(k + 1, line.u.size - 1)])
        if 0 < k < line.u.size - 1:
            res = minimize_scalar(
                lambda x: float(generated_root_line(b, s, blank, hand, [x]).depth[0]),
                bounds=(lo, hi), method="bounded", options={"xatol": 1e-4})
            if res.fun < d_best:
                u_best, d_best = float(res.x), float(res.fun)
        return u_best, d_best

    moved, (u_top, top) = 0.0, highest(blade, settings)
    b, s = blade, settings
    prev = None
    for _ in range(12):
        if abs(top) <= tol:
            break
        slope = 1.0 if prev is None or prev[0] == moved else (top - prev[1]) / (moved - prev[0])
        if not 0.5 < slope < 2.0:  # the depth grows with the move nearly one to one
            slope = 1.0
        prev = (moved, top)
        moved -= top / slope
        b, s = move_tip_plane(blade, settings, moved)
        u_top, top = highest(b, s)
    else:
        raise InputError(f"{blade.side} blade: the tip plane does not converge onto the "
                         f"root cone (highest root-line point {top:.3g} mm below it)")
    return TipPlacement(b, s, moved, u_top, generated_root_line(b, s, blank, hand))
