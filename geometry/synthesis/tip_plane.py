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

A face-hobbing blade is placed in the head (phase, offset angle, rake and hook; design
note "Face hobbing" §2.3) and the work indexes with the cutter spin, which commutes with a
move along the cutter axis: the same change of datum holds, the reference point and the
placement angles following the edge (:func:`move_tip_plane`). The face-hobbed pinions'
cuts of step 5 (tip plane through the root below M) lay from 0.26 mm above to 0.23 mm
below the root cone at their highest; step 8 places them as the face-milled ones.

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

from geometry.case import Blank
from geometry.core.errors import InputError
from geometry.machine.cradle import MachineSettings
from geometry.machine.cutter import Blade, placement_vectors
from geometry.machine.root_line import below_root_cone, root_line_points, section_envelope

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
#: [1] the step inside an end section at which a root line's highest end section is
#: probed: an end higher than the point this far inside is its interval's highest (a
#: smooth root line does not turn twice between two samples 0.1 apart); lower, the
#: interval is searched (a face-hobbed root line can peak just inside the heel)
_END_PROBE = 1e-3


#: points of each level of :func:`_highest_between`'s search, and its levels: the bracket
#: of two sample intervals (0.2 of the face) narrowed to 2 of 16 steps per level, then a
#: parabola through the last level's three highest points
_REFINE_POINTS = 17
_REFINE_LEVELS = 2
#: [rad, rad, 1] the farthest a root-line point solved at s = 0 from a nearby root line's
#: may lie from its start in θ, q and v (the march otherwise): a tip-plane move of ~1 mm
#: moves them by a few hundredths
_TIP_REACH = 0.1


def _highest_between(depth_at, lo: float, hi: float) -> tuple[float, float]:
    """The lengthwise fraction in [lo, hi] where a root line is highest, and its depth
    [mm] (least depth below the root cone), from ``depth_at(u)`` (depth (n,) [mm] at the
    fractions u (n,), NaN where not generated).

    The root line's points are solved by one fillet march for any number of fractions at
    nearly the cost of one (:func:`geometry.machine.root_line.section_march`), so the
    search evaluates whole grids: :data:`_REFINE_LEVELS` grids of :data:`_REFINE_POINTS`
    fractions, each over the two steps either side of the last one's highest point, then
    the vertex of the parabola through the last grid's highest point and its neighbours
    (kept where it is higher): 3 marches instead of the ~6 of a bounded scalar search
    (``scipy.optimize.minimize_scalar``, xatol 1e-4, used before 2026-11-26; issue 75). The
    vertex lies within ~1e-6 of the maximum on a smooth root line (grid step 1.6e-3 of
    the face), the depth there within round-off of the highest: the placement's
    tolerance (:data:`TOUCH_TOLERANCE`) is met as before.
    """
    best_u, best_d = math.nan, math.inf
    u = d = np.empty(0)
    j = 0
    for _ in range(_REFINE_LEVELS):
        u = np.linspace(lo, hi, _REFINE_POINTS)
        d = np.asarray(depth_at(u), dtype=float)
        d = np.where(np.isfinite(d), d, np.inf)
        j = int(np.argmin(d))
        if d[j] < best_d:
            best_u, best_d = float(u[j]), float(d[j])
        lo, hi = float(u[max(j - 1, 0)]), float(u[min(j + 1, u.size - 1)])
    if 0 < j < u.size - 1 and np.all(np.isfinite(d[j - 1:j + 2])):
        # the parabola's vertex through (u[j-1], u[j], u[j+1]) (equal steps h)
        h = float(u[1] - u[0])
        curv = d[j - 1] - 2.0 * d[j] + d[j + 1]
        if curv > 0.0:
            x = float(u[j]) + 0.5 * h * (d[j - 1] - d[j + 1]) / curv
            dx = float(np.asarray(depth_at(np.array([x])), dtype=float)[0])
            if np.isfinite(dx) and dx < best_d:
                best_u, best_d = x, dx
    return float(best_u), float(best_d)


def move_tip_plane(blade: Blade, settings: MachineSettings, depth: float
                   ) -> tuple[Blade, MachineSettings]:
    """The blade and settings of the same cutting edge with the tip plane ``depth``
    further along the cutter axis (towards the work: a deeper cut).

    Parameters
    ----------
    blade : geometry.machine.cutter.Blade — a face-milling blade, or a placed
        (face-hobbing) blade: phase θ_b, offset angle δ_b, rake and hook γ_h
    settings : geometry.machine.cradle.MachineSettings — its machine settings (the indexing
        ratio of face hobbing included)
    depth : float — [mm] Δ, the tip plane's move along the cutter axis towards the tips
        (> 0 deeper, < 0 shallower)

    Returns
    -------
    (Blade, MachineSettings)
        The new reference point M' is the nominal profile line's point at the new tip
        plane: on the edge's nominal line in the rake plane at the height
        −Δ / cos γ_h below the old tip (the rake plane's "vertical" line a2 leans by the
        hook γ_h from the cutter axis), M' = M + (Δ / cos γ_h)(a2 − σ tan α a1)
        (:func:`geometry.machine.cutter.placement_vectors`; σ = +1 outside, −1 inside
        blade). Every height above the tip grows by Δ / cos γ_h (circular profile
        reference, toprem and flankrem heights); the point radius becomes |M'| in the
        tip plane — r_p − σ Δ tan α for a face-milling blade — and, for a placed blade,
        the phase turns by δ = ∠M' − ∠M and the blade offset angle by −δ, so that the rake
        plane (its directions a1, a2, which depend on θ_b + γ_a and γ_h only) is the same
        plane through M'. In the machine chain the cutter frame is moved by T(0, 0, Δ):
        its component along the cradle axis Δ cos i goes to the sliding base (a shift
        along the cradle axis commutes with the cradle's rotation), the rest
        Δ sin i (sin j, −cos j) in the cradle plane changes the radial setting and turns
        the cradle angle by δ and the swivel by −δ (other δ than the blade's).

    Raises
    ------
    InputError
        A move that leaves a height of the profile below the tip (the circular profile's
        reference height below 0, the toprem corner below the edge radius) or a placement
        angle out of its range, named by the field; a depth that is not finite.

    Notes
    -----
    The chain is that of :func:`geometry.machine.cradle.machine_transform` (seed
    Eq. 2.7a): M(q, θ) = R_z(−φ(q, θ)) … R_z(q_c + q) T(S_r, 0, 0) R_z(j) R_x(i),
    followed by the cutter spin R_z(θ), which commutes with T(0, 0, Δ); the new settings
    give M'(q, θ) = M(q, θ) T(0, 0, Δ) for every roll q and spin θ, modified roll, helical
    motion and the face-hobbing indexing φ = φ_roll(q) + κθ included (κ is unchanged).
    The blade edge e'(s') in the moved cutter frame is the old edge e(s) less (0, 0, Δ),
    point by point above the new edge radius, so the cutting surface — a surface of
    revolution in face milling, the edge swept by spin and indexing in face hobbing
    (design note "Face hobbing" §2.3) — and the generated flank are unchanged
    (tests/test_generated_root.py checks the chain to 1e-12 mm and the flank to 1e-9 mm,
    face milling and face hobbing).
    """
    d = float(depth)
    if not math.isfinite(d):
        raise InputError(f"depth: must be a finite length [mm], got {depth}")
    sg = blade.sigma
    if blade.placed:
        m, a1, a2 = placement_vectors(blade)
        dh = d / math.cos(blade.hook_angle)
        m_new = m + dh * (a2 - sg * math.tan(blade.blade_angle) * a1)
        turn = math.atan2(m_new[1], m_new[0]) - blade.blade_phase
        turn = math.remainder(turn, 2.0 * math.pi)
        phase = blade.blade_phase + turn
        if abs(phase) > 2.0 * math.pi:
            phase = math.remainder(phase, 2.0 * math.pi)
        fields = {"point_radius": math.hypot(m_new[0], m_new[1]), "blade_phase": phase,
                  "blade_offset_angle": blade.blade_offset_angle - turn}
    else:
        dh = d
        fields = {"point_radius": blade.point_radius - sg * d * math.tan(blade.blade_angle)}
    if blade.profile == "circular":
        fields["profile_reference_height"] = blade.profile_reference_height + dh
    if blade.toprem_angle != 0.0:
        fields["toprem_height"] = blade.toprem_height + dh
    if blade.flankrem_angle != 0.0:
        fields["flankrem_height"] = blade.flankrem_height + dh
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
                        u=_U_SAMPLES, *, start: np.ndarray | None = None) -> RootLine:
    """The root line a cut generates: where its blade's edge radius leaves the tip plane.

    Parameters
    ----------
    blade, settings : the cut's blade and machine settings
    blank : geometry.case.Blank — the member's blank (its root cone is the datum)
    hand : str — ``"left"`` or ``"right"``
    u : array_like (K,) — [1] lengthwise fractions (toe 0, heel 1), K ≥ 1
    start : ndarray (K, 4), optional — the fillet march's starts (s [mm], θ [rad], q [rad],
        v [1]) per section, e.g. a nearby cut's (:func:`geometry.machine.root_line.
        root_line_points`); default this cut's own

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
    v = root_line_points(blade, settings, blank, hand, u, start)[:, 0]
    return RootLine(u, v, below_root_cone(blank, u, v))


class TipPlacement(NamedTuple):
    """Result of :func:`tip_plane_on_root_cone`."""

    blade: Blade
    settings: MachineSettings
    moved: float  # [mm] Δ of :func:`move_tip_plane` from the given tip plane
    u_touch: float  # [1] lengthwise fraction where the root line touches the root cone
    root_line: RootLine  # of the placed tip plane at the sample fractions


def _started(blade: Blade, settings: MachineSettings, start: tuple[float, float] | None
             ) -> tuple[Blade, MachineSettings, float]:
    """The cut moved to ``start``'s move Δ [mm] (:func:`tip_plane_on_root_cone`) and Δ;
    the cut itself and 0.0 where there is no start or the blade cannot take it."""
    if start is None or not math.isfinite(start[0]) or start[0] == 0.0:
        return blade, settings, 0.0
    try:
        b, s = move_tip_plane(blade, settings, float(start[0]))
    except InputError:
        return blade, settings, 0.0
    return b, s, float(start[0])


class _RootLines:
    """Root lines of one cut's tip-plane moves (:func:`tip_plane_on_root_cone`):
    ``self(b, s, u)`` is :func:`generated_root_line` of the moved cut ``b, s`` at the
    fractions u (default the samples).

    The fillet march's starts are solved once on the given cut's sampled sections (the
    envelope over a section is a third of a root line's cost) and reused, interpolated
    between the samples, for the moved tip planes and the sections between: the march
    solves each root-line point from them to its Newton tolerance; a line it does not
    complete from them is solved from its own starts. Once a root line over the whole face
    is known, the next root line's points are solved at s = 0 alone from its θ, q, v
    (interpolated between its sections): one Newton solve instead of the march's
    :data:`geometry.machine.root_line.EDGE_STEPS` (issue 75; the same points to the
    Newton tolerance), the march where that solve does not converge within
    :data:`_TIP_REACH` of its start. ``march``: the march in any case — each whole search's
    line over the samples (:func:`tip_plane_on_root_cone`), whose sections the march does
    not reach s = 0 on are "not generated" and refused as before: a solve at s = 0 from a
    near line can converge where the march from the cut's own flank does not (the spiral
    bevel 19x23's heel sections under a large root relief, whose flank is generated only
    from the profile section up; tests/test_development.py).
    """

    def __init__(self, blade: Blade, settings: MachineSettings, blank: Blank, hand: str):
        self.blank, self.hand = blank, hand
        _, _, self.sampled = section_envelope(blade, settings, blank, _U_SAMPLES)
        self.tips: tuple[np.ndarray, np.ndarray] | None = None  # u (n,), θ q v (n, 3)

    def _marched(self, b: Blade, s: MachineSettings, u: np.ndarray):
        blank, hand, sampled = self.blank, self.hand, self.sampled
        if np.all(np.isfinite(sampled)):  # between the samples: interpolated starts
            start = np.column_stack([np.interp(u, _U_SAMPLES, c) for c in sampled.T])
            pts, x = root_line_points(b, s, blank, hand, u, start, solution=True)
            if np.all(np.isfinite(pts[:, 0])):
                return pts, x
        return root_line_points(b, s, blank, hand, u, solution=True)

    def __call__(self, b: Blade, s: MachineSettings, u=_U_SAMPLES, *,
                 march: bool = False) -> RootLine:
        u = np.atleast_1d(np.asarray(u, dtype=float))
        pts = x = None
        if self.tips is not None and not march:
            x0 = np.column_stack([np.interp(u, self.tips[0], c) for c in self.tips[1].T])
            pts, x = root_line_points(b, s, self.blank, self.hand, u, at_tip=x0,
                                      solution=True)
            if not (np.all(np.isfinite(x)) and np.abs(x - x0).max() <= _TIP_REACH):
                pts = None
        if pts is None:
            pts, x = self._marched(b, s, u)
        if (u.size >= _U_SAMPLES.size and u.min() == 0.0 and u.max() == 1.0
                and np.all(np.isfinite(x))):
            ku, first = np.unique(u, return_index=True)
            self.tips = (ku, x[first])
        v = pts[:, 0]
        return RootLine(u, v, below_root_cone(self.blank, u, v))


def tip_plane_on_root_cone(blade: Blade, settings: MachineSettings, blank: Blank,
                           hand: str, *, tol: float = TOUCH_TOLERANCE,
                           start: tuple[float, float] | None = None) -> TipPlacement:
    """The tip plane whose generated root line touches the blank's root cone from below.

    Parameters
    ----------
    blade, settings : a Generate cut's blade and machine settings (face milling or face
        hobbing)
    blank : geometry.case.Blank
    hand : str
    tol : float — [mm] accepted distance of the root line's highest point from the
        root cone (default 1e-9 mm)
    start : (float, float), optional — a near cut's placement (its move Δ [mm] and the
        fraction where its root line touched): the secant steps start there instead of
        at the given tip plane's whole search (a development's variants of one flank
        differ by micrometres; issue 75). The placement found meets ``tol`` and is
        confirmed by the whole search as without it: the same tip plane within ``tol``.
        A start the blade cannot take (:func:`move_tip_plane` refuses it) is ignored.

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
    root cone. Its height over the face is sampled at 11 sections and each sampled local
    highest point refined between its neighbours (grids of fractions, then a parabola:
    :func:`_highest_between`), but for an
    end section lying above the point 0.001 inside it, which is its interval's highest (a
    face-hobbed root line can peak a fraction of a µm between the heel section and the
    next: there the point inside is higher and the interval is searched); the move is
    solved by secant steps (the root line moves with the tip plane nearly one to one, and
    nearly as a whole: between the steps only the samples and the last highest point's
    section are evaluated, and the whole search confirms the converged placement). Each
    whole search's sample line is the fillet march's; the other root lines are solved at
    the blade tip from the last line's points (:class:`_RootLines`; issue 75).
    """
    if settings.process != "Generate":
        raise InputError("settings: only a Generate cut's tip plane is placed on the root "
                         "cone (a Formate tip plane holds a root generatrix already)")

    # the fillet march's starts, solved once on the given cut's sampled sections (the
    # envelope over a section is a third of a root line's cost) and reused, interpolated
    # between the samples, for the moved tip planes and the sections between: the march
    # solves each root-line point from them to its Newton tolerance; a line it does not
    # complete from them is solved from its own starts
    root_line = _RootLines(blade, settings, blank, hand)

    last_search: list = [None]  # (b, s, root line) of the last whole search

    def highest(b: Blade, s: MachineSettings) -> tuple[float, float]:
        line = root_line(b, s, march=True)
        last_search[0] = (b, s, line)
        if not np.all(np.isfinite(line.depth)):
            bad = line.u[~np.isfinite(line.depth)]
            raise InputError(f"{blade.side} blade: its root line is not generated at face "
                             f"fractions {np.round(bad, 2).tolist()}; no tip height puts it "
                             "on the root cone")
        dep, last = line.depth, line.u.size - 1
        k = int(np.argmin(dep))
        u_best, d_best = float(line.u[k]), float(dep[k])
        # every sampled local height maximum, an end section's too (a face-hobbed root
        # line can rise a fraction of a µm between the heel section and its neighbour),
        # refined between its neighbours
        for k in range(last + 1):
            if (k > 0 and dep[k] > dep[k - 1]) or (k < last and dep[k] > dep[k + 1]):
                continue
            if k in (0, last):  # an end section higher than just inside it is the highest
                x = float(line.u[k]) + (_END_PROBE if k == 0 else -_END_PROBE)
                if float(root_line(b, s, [x]).depth[0]) >= dep[k]:
                    continue
            u_k, d_k = _highest_between(
                lambda x, b=b, s=s: root_line(b, s, x).depth,
                float(line.u[max(k - 1, 0)]), float(line.u[min(k + 1, last)]))
            if d_k < d_best:
                u_best, d_best = u_k, d_k
        return u_best, d_best

    def near(b: Blade, s: MachineSettings, u_last: float) -> tuple[float, float]:
        # the sampled sections and the last highest point's: the root line moves with the
        # tip plane nearly as a whole, so its highest point stays where it was found
        line = root_line(b, s, np.r_[_U_SAMPLES, u_last])
        if not np.all(np.isfinite(line.depth)):
            return highest(b, s)
        k = int(np.argmin(line.depth))
        return float(line.u[k]), float(line.depth[k])

    b, s, moved = _started(blade, settings, start)
    searched = moved == 0.0  # (u_top, top) from the whole search, not from near()
    u_top, top = (highest(b, s) if searched
                  else near(b, s, float(np.clip(start[1], 0.0, 1.0))))
    prev = None
    for _ in range(16):
        if abs(top) <= tol:
            if searched:
                break
            u_top, top = highest(b, s)  # the whole search confirms it, or goes on
            searched = True
            if abs(top) <= tol:
                break
        slope = 1.0 if prev is None or prev[0] == moved else (top - prev[1]) / (moved - prev[0])
        if not 0.5 < slope < 2.0:  # the depth grows with the move nearly one to one
            slope = 1.0
        prev = (moved, top)
        moved -= top / slope
        b, s = move_tip_plane(blade, settings, moved)
        u_top, top = near(b, s, u_top)
        searched = False
    else:
        raise InputError(f"{blade.side} blade: the tip plane does not converge onto the "
                         f"root cone (highest root-line point {top:.3g} mm below it)")
    # the placed root line: the last whole search's where it searched this placement
    # (the same call, the same line), else computed
    kept = last_search[0]
    line = kept[2] if kept is not None and kept[0] is b and kept[1] is s else root_line(b, s)
    return TipPlacement(b, s, moved, u_top, line)
