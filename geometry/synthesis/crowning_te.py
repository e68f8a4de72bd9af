"""The TE parabola a pinion's profile crowning (step 7a) adds to a synthesised pair.

Step 7a of the synthesis (:func:`geometry.synthesis.blade_change.blade_profile_crowned`)
crowns the pinion blade after steps 4–6 have put the unloaded TE on the prescribed
parabola TE(roll) = te_level · (roll/pitch)². The crowned blade's cutting edge leaves the
flank by ε(s) = c · ((s − s_M)/m_mn)² (c the crowning at ±m_mn, s the position along the
blade), and the generated flank by the same normal distance at the point that blade
position generates. The contact point of the pair travels along the contact path at a
rate ds/dφ₁ across the blade's coordinate, so to first order in c (the envelope theorem:
the contact point is a stationary point of the gap along its contact line, so the TE
changes by the gap change there) the crowning adds the parabola

    ΔTE(φ₁) = c · (ds/dφ₁ · φ₁)² / (m_mn² · L₂),

L₂ the lever of the flank normal about the gear axis at M (TE as gear rotation): a
``te_level`` of its own, ΔTE at ±1 pitch = c · (ds/dφ₁ · 2π/z₁)² / (m_mn² · L₂). It does
not depend on the path's direction as such but on how fast the contact crosses the
blade's coordinate, which every path does within about one pitch (the contact lines sweep
the profile): on the spiral bevel 16×16 at Σ 60° (te_level 10 µrad, ellipse 0.63)
ds/dφ₁ is 20.6 mm/rad on the path −88° and 24.0 on −45°, 56.8 and 77.1 µrad per µm of
crowning, the conventional TCA's 57.3 and 79.8 (docs/synthesis.md, "The profile crowning's
TE").

Public names
------------
crowning_te_rate   the TE at ±1 pitch a profile crowning adds per mm of crowning
"""

from __future__ import annotations

import math

import numpy as np

from geometry.case import Case
from geometry.core.errors import InputError
from geometry.machine.flank_point import MemberFlank, flank_points
from geometry.pair.assembly import member_transform

__all__ = ["crowning_te_rate"]

#: [mm] the finite-difference step of the blade coordinate's gradient on the flank
#: (:func:`crowning_te_rate`): central differences, error O(step²) of a flank whose blade
#: coordinate changes over millimetres
GRADIENT_STEP = 0.05


def crowning_te_rate(case: Case, report, flank: str | None = None) -> float:
    """[rad/mm] The TE at ±1 pitch (gear rotation) that a profile crowning of the pinion
    blade adds to the synthesised pair, per mm of crowning at ±m_mn (step 7a).

    Parameters
    ----------
    case : geometry.case.Case
        The synthesised case (its pinion flank's blade and settings, its pair: Σ [rad], E
        [mm], the gear's hand); the crowning and relief of its blade do not change the
        blade coordinate's gradient at M.
    report : geometry.synthesis.case_synthesis.SynthesisReport
        The synthesis's report of ``case``: ``flanks[flank]`` (the mean point M and the
        local synthesis's contact-point velocity [mm/rad of pinion roll]) and
        ``blank.m_mn`` [mm], the crowning's reach.
    flank : str, optional
        ``"concave"`` or ``"convex"`` (default the pair's drive flank).

    Returns
    -------
    float
        k [rad/mm]: a crowning c [mm] adds TE(roll) = k · c · (roll/pitch)² to first order
        in c; k · c is comparable with the flank's ``te_level`` [rad]. × 1e3 gives µrad per
        µm.

    Raises
    ------
    InputError
        ``flank`` not synthesised in ``report``, or the flank not generated about M (the
        blade coordinate's gradient not found).

    Notes
    -----
    ΔTE(φ₁) = c (ds/dφ₁ φ₁)² / (m_mn² L₂): the crowned blade's normal departure
    ε(s) = c ((s − s_M)/m_mn)² (:func:`geometry.synthesis.blade_change.
    blade_profile_crowned`, Δκ = 2c/m_mn²) carried to the generated flank at the point the
    blade position s generates (the envelope's normal offset), read along the contact path
    (Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4: the TE of
    a mismatch is its ease-off at the contact point, to first order); ds/dφ₁ = ∇s · v₁
    from the flank's envelope parameters (:func:`geometry.machine.flank_point.
    flank_points`) and the local synthesis's velocity v₁ (seed §2.3, Litvin et al. 2002).
    Second order in c the contact path turns away from the crowned direction and the TE
    grows less (16×16 at −88°: 57.3 µrad/µm at 0.25 µm, 54.8 at 2 µm).
    """
    pf = case.pair.drive_flank if flank is None else flank
    if pf not in getattr(report, "flanks", {}):
        raise InputError(f"flank: {pf!r} not synthesised in the report (accepted: "
                         f"{', '.join(sorted(getattr(report, 'flanks', {})))})")
    fs = report.flanks[pf]
    mp, ls = fs.mean, fs.local
    kw = dict(shaft_angle=case.pair.shaft_angle, offset=case.pair.offset,
              gear_hand=case.gear.hand)
    tp = member_transform("pinion", rotation=mp.pinion_rotation, **kw)
    tg = member_transform("gear", rotation=mp.gear_rotation, **kw)
    lever = abs(float(np.cross(tg[:3, 2], mp.point - tg[:3, 3]) @ mp.normal))
    rot = tp[:3, :3]
    local = rot.T @ (mp.point - tp[:3, 3])
    velocity = rot.T @ ls.path_pinion
    axial, radius = float(local[2]), math.hypot(local[0], local[1])
    radial = np.array([local[0], local[1], 0.0]) / radius
    h = GRADIENT_STEP
    zz = np.array([axial + h, axial - h, axial, axial])
    pp = np.array([radius, radius, radius + h, radius - h])
    mf = MemberFlank.of_case(case, "pinion", pf)
    fp = flank_points(mf.blade, mf.machine, mf.blank, mf.hand, zz, pp)
    s = fp.params[:, 0]
    if not (np.all(fp.ok) and np.all(np.isfinite(s))) or lever <= 0.0:
        raise InputError(f"flank: the pinion's {pf} flank is not generated about M "
                         "(its blade coordinate's gradient not found)")
    ds_dphi = ((s[0] - s[1]) * velocity[2] + (s[2] - s[3]) * float(velocity @ radial)) / (2 * h)
    pitch = 2.0 * math.pi / case.pinion.blank.teeth
    return float((ds_dphi * pitch) ** 2 / (report.blank.m_mn ** 2 * lever))
