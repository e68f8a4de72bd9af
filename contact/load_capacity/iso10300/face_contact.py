"""The face contact ratio of a basic design and what raises it to the least design
practice asks for (issue 71: the low-overlap designs whose LTE no bearing reaches).

A localised bearing hands the load from pair to pair through one pair over much of the
mesh cycle where the face contact ratio ε_vβ (ISO 10300-1:2014, Annex A, A.2: ε_vβ =
b_v,eff sin β_v / (π m_mn)) is low; bevel-gear design practice asks for at least
:data:`FACE_CONTACT_RATIO_MIN` (AGMA 2005-D03, face contact ratio m_F ≥ 1.25 for a
quiet spiral bevel pair). Measured on the spiral bevel 17x29 at Σ 100° of
tests/data/designs (ε_vβ 0.96, docs/own_gear_set.md, "A face contact ratio below 1.25"):
over 40 bearings of the development's levers (modified-roll level, ellipse length, tip
and root relief and their starts, path angle, profile crowning), none brought the LTE p-p
at the design torque below 86 µrad (coarse LTCA), where the target is 60.

:func:`overlap_remedy` finds, from the ISO 23509 blank of the basic data, the gear face
width b2 and the mean spiral angle β_m that each, the other kept, raise ε_vβ to the
target (a root of ε_vβ(b2) and of ε_vβ(β_m), Brent's method on the blank and the virtual
gears of :func:`contact.load_capacity.iso10300.virtual_gears.virtual_gears`);
:func:`overlap_text` says it in a sentence for ``ltca synthesize``, ``ltca run`` and
``ltca duty-cycle``.

Where the profile contact ratio ε_vα is below :data:`PROFILE_CONTACT_RATIO_MIN` (a high
spiral angle lowers it: the spiral bevel 19x23 at β_m 46° of
benchmarks/data/unseen_designs, ε_vα 0.98), :func:`profile_remedy` finds the depth factor
k_d and the drive flank's pressure angle α_dD that each raise it to 1, and
:func:`low_ratio_text` says both remedies in one sentence; :func:`loaded_ratio_text`
states an analysis' loaded contact ratio (the tooth pairs carrying the torque) beside
them (``ltca run``'s ``lte`` finding, issue 71).

Public functions
----------------
overlap_remedy     ε_vβ of a design and the b2, β_m that reach the target
overlap_changes    those as basic-file changes (RatioChange), as the note prints them
overlap_text       that as a sentence, or None where ε_vβ meets the target
teeth_remedy       the tooth numbers at the same d_e2, b2, β_m that reach it, where
                   neither b2 nor β_m alone does
profile_remedy     ε_vα of a design and the k_d, α_dD that reach the target
profile_changes    those as basic-file changes (RatioChange), as the note prints them
low_ratio_text     the sentence of every contact ratio below its limit, or None
loaded_ratio_text  the contact ratios and the loaded contact ratio of an analysis
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass

__all__ = [
    "FACE_CONTACT_RATIO_MIN",
    "FACE_WIDTH_LIMIT",
    "FACE_WIDTH_MODULES",
    "FACE_WIDTH_OUTER",
    "PROFILE_CONTACT_RATIO_MIN",
    "RATIO_AT_TARGET",
    "OverlapRemedy",
    "ProfileRemedy",
    "RatioChange",
    "at_target",
    "at_target_text",
    "face_width_text",
    "loaded_ratio_text",
    "low_ratio_text",
    "overlap_changes",
    "overlap_remedy",
    "overlap_text",
    "profile_changes",
    "profile_remedy",
    "teeth_remedy",
]

#: the least face contact ratio ε_vβ bevel-gear design practice asks for (AGMA 2005-D03,
#: face contact ratio m_F); below it ``ltca synthesize`` adds a note and the LTE-spread
#: findings of ``ltca run`` and ``ltca duty-cycle`` name it
FACE_CONTACT_RATIO_MIN = 1.25

#: the least profile (transverse) contact ratio ε_vα below which the virtual cylindrical
#: gears' transverse section has, once per base pitch, no pair in mesh (ISO 10300-1:2014,
#: Annex A: ε_vα = g_vα / p_vet): the load is handed over only along the face (ε_vβ), which
#: a localised bearing shortens to the pattern's length
PROFILE_CONTACT_RATIO_MIN = 1.0

#: how far below its target [1] a contact ratio is taken to be at it: no remedy offered,
#: the ratio said at its target (issue 71, round 22: the spiral bevel 22×33 of m_et 8.5 at
#: ε_vβ 1.247 was offered b2 48 → 48.1 mm, whose check measured its unloaded TE no lower,
#: 14 against 14 µrad). 0.01 is the resolution every line prints a contact ratio at: a
#: ratio within it prints at its target ("eps_vb 1.25"), and the change that closes it is a
#: fraction of a per cent of the field (b2 +0.1 mm, β_m +0.1°), below the blank's own
#: tolerances (docs/synthesis.md, "Remedies that are no remedy")
RATIO_AT_TARGET = 0.01

#: the usual largest gear face width as a fraction of the outer cone distance R_e2
#: (AGMA 2005-D03 and Gleason practice: b2 ≤ 0.3 R_e2; wider, the toe's teeth become too
#: small and the pattern's movement under load too large)
FACE_WIDTH_LIMIT = 0.3

#: the widest gear face bevel-gear practice accepts, as a fraction of R_e2 and as a multiple
#: of the outer transverse module m_et2 (Niemann & Winter, *Maschinenelemente* III:
#: b ≤ R_e/3; AGMA 2005-D03: b ≤ 0.3 A_o and ≤ 10/P_d = 10 m_et): :func:`face_width_text`
#: notes a face above either; :data:`FACE_WIDTH_LIMIT` is the usual largest the remedies
#: stay within
FACE_WIDTH_OUTER = 1.0 / 3.0
FACE_WIDTH_MODULES = 10.0

#: the largest mean spiral angle tried [deg] (spiral bevel and hypoid practice stays at or
#: below 45°; the thrust grows with tan β_m)
_SPIRAL_ANGLE_MAX = 50.0

#: the usual depth factor k_d of spiral bevel and hypoid teeth (ISO 23509 data type II,
#: h_mw = k_d m_mn: 2.0 for spiral bevel gears, AGMA 2005-D03 / Gleason); a deeper tooth
#: narrows its top land
DEPTH_FACTOR_USUAL = 2.0

#: the largest depth factor and the least pressure angle :func:`profile_remedy` tries
#: [1], [deg] (a deeper tooth's top land and a smaller pressure angle's undercut of a
#: small pinion bound them; 14.5° is the least standard pressure angle)
_DEPTH_FACTOR_MAX = 2.5
_PRESSURE_ANGLE_MIN = 14.5


@dataclass(frozen=True)
class OverlapRemedy:
    """The face contact ratio of a design and the changes that reach a target.

    Attributes
    ----------
    eps_vb : float — [1]
        Face contact ratio ε_vβ of the design (ISO 10300-1, drive side).
    target : float — [1]
        The ε_vβ aimed at.
    b2 : float — [mm]
        The design's gear face width.
    b2_needed : float — [mm]
        The gear face width that gives ``target``, β_m kept; NaN where no face width up
        to half the outer cone distance does (or the blank refuses it).
    b2_limit : float — [mm]
        :data:`FACE_WIDTH_LIMIT` × R_e2, the usual largest face width.
    beta_m : float — [deg]
        The design's mean spiral angle (the basic file's ``beta_m``).
    beta_m_needed : float — [deg]
        The mean spiral angle that gives ``target``, b2 kept; NaN where none up to 50°
        does.
    """

    eps_vb: float
    target: float
    b2: float
    b2_needed: float
    b2_limit: float
    beta_m: float
    beta_m_needed: float


def _eps_vb(design, blank=None) -> float:
    """ε_vβ [1] of ``design`` from its ISO 23509 blank (``blank`` where already made)."""
    from contact.load_capacity.iso10300.inputs import gear_data_from_blank
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears
    from geometry.iso23509.blank import blank_geometry

    blank = blank_geometry(design) if blank is None else blank
    return float(virtual_gears(gear_data_from_blank(blank)).eps_vb)


def _root(f, x0: float, x1: float, steps: int = 12) -> float:
    """The first x in [x0, x1] where f(x) = 0 (f(x0) < 0), by a scan of ``steps`` then
    Brent's method; NaN where f stays negative or the blank refuses every x beyond."""
    from scipy.optimize import brentq

    from geometry.core.errors import InputError

    def g(x: float) -> float:
        try:
            return f(x)
        except (InputError, ValueError, ZeroDivisionError):
            return math.nan

    a, fa = x0, g(x0)
    if not math.isfinite(fa):
        return math.nan
    for k in range(1, steps + 1):
        b = x0 + (x1 - x0) * k / steps
        fb = g(b)
        if not math.isfinite(fb):
            return math.nan
        if fb >= 0.0:
            return float(brentq(g, a, b, xtol=1e-3))
        a, fa = b, fb
    return math.nan


def _check_target(target: float) -> None:
    """InputError naming ``target`` where it is not a number in (0, 5]."""
    from geometry.core.errors import InputError

    if not (isinstance(target, (int, float)) and math.isfinite(target) and 0.0 < target <= 5.0):
        raise InputError(f"target: the face contact ratio aimed at must be a number in "
                         f"(0, 5], got {target!r}")


def overlap_remedy(design, target: float = FACE_CONTACT_RATIO_MIN) -> OverlapRemedy:
    """The face contact ratio ε_vβ of a basic design and the face width and spiral angle
    that reach ``target``.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
        The basic design data (``[design]`` of a basic file or of a case; lengths [mm],
        angles [rad]).
    target : float — [1]
        The face contact ratio aimed at, in (0, 5]; default :data:`FACE_CONTACT_RATIO_MIN`.

    Returns
    -------
    OverlapRemedy
        ε_vβ of ``design``; the gear face width b2 [mm] (β_m kept) and the mean spiral angle
        β_m [deg] (b2 kept) at which ε_vβ = ``target`` (to 0.001 mm / 0.001°), each NaN
        where none up to R_e2/2 or 50° reaches it; where ε_vβ already meets the target,
        the design's own values.

    Raises
    ------
    InputError
        ``target`` not a number in (0, 5]; a design the ISO 23509 blank refuses (its
        message, ``design.<field>``).

    Notes
    -----
    ε_vβ from the ISO 23509:2016 blank (:func:`geometry.iso23509.blank.blank_geometry`)
    and ISO 10300-1:2014 Annex A (:func:`contact.load_capacity.iso10300.virtual_gears.
    virtual_gears`, effective face width 0.85 b2); at a fixed outer pitch diameter a wider
    face lowers the mean normal module, so ε_vβ grows faster than b2 (the 17x29 of
    tests/data/designs: 0.96 at 24 mm, 1.25 at 30.0 mm).
    """
    from geometry.iso23509.blank import blank_geometry

    _check_target(target)
    blank = blank_geometry(design)
    eps, re2 = _eps_vb(design, blank), float(blank.gear.Re)
    b2, beta = float(design.b2), math.degrees(float(design.beta_m))
    if eps >= target:
        return OverlapRemedy(eps, float(target), b2, b2, FACE_WIDTH_LIMIT * re2, beta, beta)
    b_need = _root(lambda b: _eps_vb(dataclasses.replace(design, b2=b)) - target,
                   b2, max(b2, 0.5 * re2))
    beta_need = _root(lambda d: _eps_vb(dataclasses.replace(design, beta_m=math.radians(d)))
                      - target, beta, max(beta, _SPIRAL_ANGLE_MAX))
    return OverlapRemedy(eps, float(target), b2, b_need, FACE_WIDTH_LIMIT * re2, beta,
                         beta_need)


def _eps_vb_or_nan(design, **change) -> float:
    """ε_vβ [1] of ``design`` with the ``[design]`` ``change``; NaN where the blank refuses
    it."""
    from geometry.core.errors import InputError

    try:
        return _eps_vb(dataclasses.replace(design, **change))
    except (InputError, ValueError, ZeroDivisionError):
        return math.nan


def teeth_remedy(design, target: float = FACE_CONTACT_RATIO_MIN) -> tuple[int, int] | None:
    """The fewest teeth, at the same outer pitch diameter, face width and spiral angle,
    whose face contact ratio ε_vβ reaches ``target``: the lever left where neither the
    face width nor the spiral angle alone reaches it (:func:`overlap_text`).

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
        The basic design data (``z1``, ``z2`` [1]; lengths [mm], angles [rad]).
    target : float — [1]
        The face contact ratio aimed at; default :data:`FACE_CONTACT_RATIO_MIN`.

    Returns
    -------
    (z1, z2) : (int, int) or None
        The least pinion tooth number z1 above the design's (up to 4 z1 and 500), with
        z2 = round(z1 u) at the design's ratio u (z2 ≥ z1), whose ISO 23509 blank gives
        ε_vβ ≥ ``target``; None where the design already reaches it or none up to that
        does (or the blank refuses each).

    Notes
    -----
    At a fixed outer pitch diameter d_e2 and face width b2 the cone distances are kept and
    the mean normal module m_mn = 2 R_m sin δ2 cos β_m / z2 falls as 1/z2, so ε_vβ =
    b_v,eff sin β_v / (π m_mn) (ISO 10300-1:2014, A.2) grows in proportion to the tooth
    numbers: the spiral bevel 12x12 miter of benchmarks/data/unseen_designs (d_e2 90 mm,
    b2 19 mm = 0.3 R_e2, β_m 35°), ε_vβ 0.564, reaches 1.25 at 27x27 (1.269 = 0.564 ·
    27/12), where no face width up to R_e2/2 (1.07) nor spiral angle up to 50° (0.96)
    alone does (docs/own_gear_set.md, "Four FM generated-gear designs re-measured on the
    corrected gear").

    Raises
    ------
    InputError
        ``target`` not a number in (0, 5].
    """
    _check_target(target)
    z1, z2 = int(design.z1), int(design.z2)
    if not _eps_vb_or_nan(design) < target:
        return None
    u = z2 / z1
    for n1 in range(z1 + 1, min(4 * z1, 500) + 1):
        n2 = max(n1, round(n1 * u))
        if n2 > 500:
            return None
        if _eps_vb_or_nan(design, z1=n1, z2=n2) >= target:
            return n1, n2
    return None


def _none_text(design, r: OverlapRemedy) -> str:
    """The phrase for no face width nor spiral angle alone reaching ``r.target``, with
    the ε_vβ each reaches at its bound (R_e2/2, :data:`_SPIRAL_ANGLE_MAX`) where its blank
    can be computed."""
    half = 0.5 * r.b2_limit / FACE_WIDTH_LIMIT
    at_b = _eps_vb_or_nan(design, b2=max(r.b2, half))
    at_beta = _eps_vb_or_nan(design, beta_m=math.radians(max(r.beta_m, _SPIRAL_ANGLE_MAX)))
    b_said = f" (eps_vb {at_b:.2f} at {half:.1f} mm)" if math.isfinite(at_b) else ""
    beta_said = f" ({at_beta:.2f})" if math.isfinite(at_beta) else ""
    return (f"no face width up to R_e2/2{b_said} nor spiral angle up to "
            f"{_SPIRAL_ANGLE_MAX:g} deg{beta_said}")


#: ``check(z1, z2) -> str | None`` of a tooth-count remedy (:func:`overlap_text`)
_CountsCheck = Callable[[int, int], "str | None"]

#: tooth counts tried by :func:`_teeth_text`'s check: the least that reaches the target,
#: then steps of :data:`_TEETH_STEP` pinion teeth (ratio kept), at most
#: :data:`_TEETH_TRIALS` syntheses of 1-2 s of CPU each (issue 71, round 96: the 15x15
#: hypoid's 57x57 has no unloaded contact at rc0 76.2 mm, 62x62 has)
_TEETH_STEP, _TEETH_TRIALS = 5, 4


def _teeth_text(design, target: float, check: _CountsCheck | None = None) -> str:
    """"; " and the tooth numbers of :func:`teeth_remedy` as the note's last clause, or
    "" where none is found; with ``check`` (``check(z1, z2) -> str | None``: None where
    the counts synthesise into a case whose unloaded contact is computed, else what
    failed) the offer is checked: the least count that reaches ``target`` and passes,
    of :data:`_TEETH_TRIALS` tried, or what failed and no offer."""
    z = teeth_remedy(design, target)
    if z is None:
        return ""
    z1, z2 = int(design.z1), int(design.z2)
    ratio = ("" if z[1] * z1 == z[0] * z2 else
             f", the ratio then {z[1] / z[0]:.3f} (now {z2 / z1:.3f})")
    from geometry.iso23509.blank import blank_geometry

    lever = ("; the module is the lever left: more teeth at the same d_e2, b2 and beta_m "
             "lower the mean normal module and raise eps_vb in proportion")
    m_now = float(blank_geometry(design).m_mn)
    if check is None:
        m_then = float(blank_geometry(dataclasses.replace(design, z1=z[0], z2=z[1])).m_mn)
        return (f"{lever}, z1 {z[0]} and z2 {z[1]} (now {z1} and {z2}{ratio}; m_mn "
                f"{m_then:.2f} mm, now {m_now:.2f}) reach {target:g} (not checked by a "
                "synthesis)")
    failed = []
    for n1, n2 in _teeth_trials(design, z, target):
        why = check(n1, n2)
        if why is None:
            m_then = float(blank_geometry(dataclasses.replace(design, z1=n1, z2=n2)).m_mn)
            ratio = ("" if n2 * z1 == n1 * z2 else
                     f", the ratio then {n2 / n1:.3f} (now {z2 / z1:.3f})")
            before = f"; not {'; '.join(failed)}" if failed else ""
            return (f"{lever}, z1 {n1} and z2 {n2} (now {z1} and {z2}{ratio}; m_mn "
                    f"{m_then:.2f} mm, now {m_now:.2f}) reach {target:g}, checked by a "
                    "synthesis of the file with these counts (`--no-development`): its "
                    f"unloaded contact is computed{before}")
        failed.append(f"{n1}x{n2}: {why}")
    rc0 = getattr(design, "rc0", None)
    limit = ("" if rc0 is None else
             f"; at the cutter radius rc0 {rc0:g} mm the tooth count does not reach it")
    return (f"{lever}, z1 {z[0]} and z2 {z[1]} would reach {target:g}, but no synthesis "
            f"of the file with {len(failed)} counts from {z[0]}x{z[1]} up has an unloaded "
            f"contact `ltca run` computes ({'; '.join(failed)}){limit}")


def _teeth_trials(design, z: tuple[int, int], target: float) -> list[tuple[int, int]]:
    """The tooth counts :func:`_teeth_text` checks: ``z`` (the least that reaches
    ``target``) and those :data:`_TEETH_STEP` pinion teeth apart that reach it too, the
    ratio kept, at most :data:`_TEETH_TRIALS`."""
    u = z[1] / z[0]
    out = [z]
    n1 = z[0]
    while len(out) < _TEETH_TRIALS:
        n1 += _TEETH_STEP
        n2 = max(n1, round(n1 * u))
        if n2 > 500:
            break
        if _eps_vb_or_nan(design, z1=n1, z2=n2) >= target:
            out.append((n1, n2))
    return out


def _profile_after(design, **change) -> str:
    """"; eps_va then 0.98, below 1" where the basic-file ``change`` an overlap remedy
    offers takes the profile contact ratio ε_vα below :data:`PROFILE_CONTACT_RATIO_MIN`;
    "" otherwise or where its blank cannot be computed. A larger spiral angle lowers ε_vα
    (the virtual transverse pressure angle grows): the hypoid 15x31 of issue 71's round
    16 (ε_vα 1.10, ε_vβ 1.00) at the β_m of 46.3° its note offered reached ε_vβ 1.25 with
    ε_vα 0.98, and its next note offered k_d or α_dD for that; the note had not said so.
    """
    from geometry.core.errors import InputError

    try:
        eps = _eps_va(dataclasses.replace(design, **change))
    except (InputError, ValueError, ZeroDivisionError):
        return ""
    if not eps < PROFILE_CONTACT_RATIO_MIN:
        return ""
    return f"; eps_va then {_below(eps, PROFILE_CONTACT_RATIO_MIN)}, below " \
           f"{PROFILE_CONTACT_RATIO_MIN:g}"


def overlap_changes(r: OverlapRemedy, design) -> list[RatioChange]:
    """The basic-file changes of an :class:`OverlapRemedy` that reach its target, as the
    note prints them: the gear face width rounded up to 0.1 mm, the mean spiral angle up to
    0.1° (each then reaches the target), each saying where it takes the profile contact
    ratio below :data:`PROFILE_CONTACT_RATIO_MIN` (its ``other``).

    Parameters
    ----------
    r : OverlapRemedy
    design : geometry.iso23509.design_data.BevelGearDesign
        The design ``r`` is of (for ε_vα after each change).

    Returns
    -------
    list of RatioChange
        The face width's change first, then the spiral angle's; a change that no value
        within the tried range makes is left out (empty where neither).
    """
    ways = []
    if math.isfinite(r.b2_needed):
        b2 = math.ceil(r.b2_needed * 10) / 10
        over = (f", above the usual {FACE_WIDTH_LIMIT:g} R_e2 = {r.b2_limit:.1f} mm"
                if r.b2_needed > r.b2_limit else "")
        other = _profile_after(design, b2=b2)
        ways.append(RatioChange("b2", b2, {"b2": b2}, f"a gear face width b2 of {b2:.1f} mm"
                                f"{over} (now {r.b2:g}{other})", other.lstrip("; ")))
    if math.isfinite(r.beta_m_needed):
        beta = math.ceil(r.beta_m_needed * 10) / 10
        other = _profile_after(design, beta_m=math.radians(beta))
        ways.append(RatioChange("beta_m", beta, {"beta_m": math.radians(beta)},
                                f"a mean spiral angle beta_m of {beta:.1f} deg (now "
                                f"{r.beta_m:g}{other})", other.lstrip("; ")))
    return ways


def overlap_text(design, target: float = FACE_CONTACT_RATIO_MIN, judge=None,
                 teeth_check: _CountsCheck | None = None) -> str | None:
    """The cause and the remedy of a low face contact ratio in one sentence (``ltca
    synthesize``'s note, the LTE-spread next step of ``ltca run`` and ``ltca duty-cycle``);
    None where ε_vβ meets ``target`` or the blank cannot be computed.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
    target : float — [1]
        Default :data:`FACE_CONTACT_RATIO_MIN`.
    judge : callable, optional
        ``judge(changes, target, none) -> str``: the end of the sentence from the
        :class:`RatioChange` list (:func:`overlap_changes`), where each change is checked
        before it is offered (:func:`low_ratio_text`); by default they are offered as
        equals.
    teeth_check : callable, optional
        ``teeth_check(z1, z2) -> str | None``: where no face width nor spiral angle
        reaches ``target``, the tooth counts offered are checked by it (None: they
        synthesise into a case whose unloaded contact is computed; else what failed) and
        the least count that reaches ``target`` and passes is offered, or none with what
        failed (:func:`contact.optimize.development_conjugacy.teeth_checker`); by default
        the least count is offered "not checked by a synthesis".

    Returns
    -------
    str or None
        E.g. "face contact ratio eps_vb 0.96 is below 1.25 (...); a gear face width b2 of
        30.1 mm, above the usual 0.3 R_e2 = 26.0 mm (now 24) or a mean spiral angle
        beta_m of 42.5 deg (now 35), the other kept, reaches 1.25" (each value rounded up
        to 0.1).
    """
    from geometry.core.errors import InputError

    try:
        r = overlap_remedy(design, target)
    except (InputError, ValueError, ZeroDivisionError):
        return None
    if r.eps_vb >= r.target:
        return None
    changes = overlap_changes(r, design)
    if at_target(r.eps_vb, r.target):
        return at_target_text("face contact ratio eps_vb", r.eps_vb, r.target, changes)
    none = _none_text(design, r) if not changes else \
        f"no face width up to R_e2/2 nor spiral angle up to {_SPIRAL_ANGLE_MAX:g} deg"
    remedy = (judge(changes, r.target, none) if judge is not None and changes
              else _either([c.text for c in changes], r.target, none)
              + ("" if changes else _teeth_text(design, r.target, teeth_check)))
    return (f"face contact ratio eps_vb {_below(r.eps_vb, r.target)} is below {r.target:g}, "
            "the least "
            "bevel-gear design practice asks for (AGMA 2005-D03): a localised bearing then "
            "hands the load from pair to pair through one pair over much of the mesh cycle, "
            "which the bearing's levers (a longer ellipse, a relief entering later, a flatter "
            "TE parabola) offset only in part (docs/own_gear_set.md, 'A face contact ratio "
            f"below 1.25'); {remedy}")


@dataclass(frozen=True)
class ProfileRemedy:
    """The profile contact ratio of a design and the changes that reach a target.

    Attributes
    ----------
    eps_va : float — [1]
        Profile (transverse) contact ratio ε_vα of the design (ISO 10300-1, drive side).
    target : float — [1]
        The ε_vα aimed at.
    k_d : float — [1]
        The design's depth factor (``[design] k_d``, ISO 23509 data type II).
    k_d_needed : float — [1]
        The depth factor that gives ``target``, the rest kept; NaN where none up to 2.5
        does, or the design gives its depth by data type I.
    alpha_d : float — [deg]
        The drive flank's design pressure angle (``[design] alpha_dD``).
    alpha_d_needed : float — [deg]
        The drive flank's pressure angle that gives ``target``, the rest kept; NaN where
        none down to 14.5° does.
    """

    eps_va: float
    target: float
    k_d: float
    k_d_needed: float
    alpha_d: float
    alpha_d_needed: float


def _eps_va(design) -> float:
    """ε_vα [1] of ``design`` from its ISO 23509 blank (drive side)."""
    from contact.load_capacity.iso10300.inputs import gear_data_from_blank
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears
    from geometry.iso23509.blank import blank_geometry

    return float(virtual_gears(gear_data_from_blank(blank_geometry(design))).eps_va)


def profile_remedy(design, target: float = PROFILE_CONTACT_RATIO_MIN) -> ProfileRemedy:
    """The profile contact ratio ε_vα of a basic design and the depth factor and drive
    pressure angle that reach ``target``.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
        The basic design data (lengths [mm], angles [rad]).
    target : float — [1]
        The profile contact ratio aimed at, in (0, 5]; default
        :data:`PROFILE_CONTACT_RATIO_MIN`.

    Returns
    -------
    ProfileRemedy
        ε_vα of ``design``; the depth factor k_d [1] (α_dD kept) and the drive flank's
        pressure angle α_dD [deg] (k_d kept) at which ε_vα = ``target`` (to 1e-3), each NaN
        where none up to 2.5 / down to 14.5° reaches it; where ε_vα already meets the
        target, the design's own values.

    Raises
    ------
    InputError
        ``target`` not a number in (0, 5]; a design the ISO 23509 blank refuses.

    Notes
    -----
    ε_vα = g_vα / p_vet (ISO 10300-1:2014, Annex A, A.2) of the virtual cylindrical gears
    (:func:`contact.load_capacity.iso10300.virtual_gears.virtual_gears`): a deeper tooth
    (h_mw = k_d m_mn, ISO 23509 data type II) lengthens the path of contact g_vα, a
    smaller pressure angle too; a larger spiral angle lowers ε_vα (the virtual transverse
    pressure angle grows). The spiral bevel 19x23 of benchmarks/data/unseen_designs at
    β_m 46°: ε_vα 0.976; k_d 2.2 gives 1.066, α_dD 18° 1.025.
    """
    from geometry.core.errors import InputError

    if not (isinstance(target, (int, float)) and math.isfinite(target) and 0.0 < target <= 5.0):
        raise InputError(f"target: the profile contact ratio aimed at must be a number in "
                         f"(0, 5], got {target!r}")
    eps = _eps_va(design)
    k_d = float(design.k_d) if getattr(design, "k_d", None) is not None else math.nan
    alpha = math.degrees(float(design.alpha_dD))
    if eps >= target:
        return ProfileRemedy(eps, float(target), k_d, k_d, alpha, alpha)
    k_need = (_root(lambda k: _eps_va(dataclasses.replace(design, k_d=k)) - target,
                    k_d, max(k_d, _DEPTH_FACTOR_MAX)) if math.isfinite(k_d) else math.nan)
    drop = _root(lambda d: _eps_va(dataclasses.replace(
        design, alpha_dD=math.radians(alpha - d))) - target, 0.0,
        max(0.0, alpha - _PRESSURE_ANGLE_MIN))
    return ProfileRemedy(eps, float(target), k_d, k_need, alpha, alpha - drop)


def _below(value: float, limit: float) -> str:
    """``value`` [1] with 2 decimals, more where 2 would print it at ``limit`` or above
    (ε_vβ 1.2497 "is below 1.25", not "1.25 is below 1.25"; at most 6)."""
    digits = 2
    while digits < 6 and round(value, digits) >= limit:
        digits += 1
    return f"{value:.{digits}f}"


def at_target(value: float, target: float) -> bool:
    """Whether a contact ratio below its target is at it: within :data:`RATIO_AT_TARGET`.

    Parameters
    ----------
    value, target : float — [1]
        The contact ratio (ε_vα or ε_vβ, ISO 10300-1 virtual gears) and its target.

    Returns
    -------
    bool
        True where ``target - RATIO_AT_TARGET <= value < target`` (a change to close the
        gap is below a meaningful step; source: issue 71, round 22, :data:`RATIO_AT_TARGET`).
    """
    return math.isfinite(value) and target - RATIO_AT_TARGET <= value < target


def at_target_text(name: str, value: float, target: float, changes) -> str:
    """The note's clause for a contact ratio at its target (:func:`at_target`): said at
    its target, the change that closes the gap named as no remedy in one clause.

    Parameters
    ----------
    name : str
        "face contact ratio eps_vb" or "profile contact ratio eps_va".
    value, target : float — [1]
    changes : list of RatioChange
        The changes that would reach ``target`` (the first is named).

    Returns
    -------
    str
        E.g. "face contact ratio eps_vb 1.247 is at its target 1.25 (0.003 below it,
        within 0.01; not a remedy here: a gear face width b2 of 48.1 mm (now 48), below a
        meaningful step)".
    """
    said = (f"; not a remedy here: {changes[0].text}, below a meaningful step"
            if changes else "")
    return (f"{name} {_below(value, target)} is at its target {target:g} "
            f"({target - value:.3f} below it, within {RATIO_AT_TARGET:g}{said})")


def _either(ways: list[str], target: float, none: str) -> str:
    """A remedy sentence's end: the basic-file changes ``ways`` joined by "or" ("the other
    kept" where there are two) that reach ``target``, or, with none, "``none`` alone
    reaches ``target``" (:func:`overlap_text`, :func:`_profile_text`)."""
    if not ways:
        return f"{none} alone reaches {target:g}"
    return (" or ".join(ways) + (", the other kept," if len(ways) > 1 else "")
            + f" reaches {target:g}")


@dataclass(frozen=True)
class RatioChange:
    """One basic-file change that raises a contact ratio to its target (a remedy the
    note offers), as the basic file gives it and as the design data takes it.

    Attributes
    ----------
    field : str
        The ``[design]`` field changed (``"k_d"``, ``"alpha_dD"``, ``"b2"``, ``"beta_m"``).
    value : float — [file unit: 1, deg, mm]
        Its new value as the basic file gives it (rounded as the note prints it).
    design : dict of str to float
        The same change as :class:`~geometry.iso23509.design_data.BevelGearDesign`
        fields take it (angles [rad]), for ``dataclasses.replace``.
    text : str
        The phrase the note prints, e.g. "a depth factor k_d of 2.16, above the usual 2
        (now 2)".
    other : str
        Where the change takes the other contact ratio below its limit, that said (e.g.
        "eps_va then 0.98, below 1": a larger spiral angle lowers ε_vα); "" otherwise. A
        checked remedy that does so is offered after one that does not
        (:func:`contact.optimize.remedy_check.ranked_changes`).
    """

    field: str
    value: float
    design: dict
    text: str
    other: str = ""


def profile_changes(r: ProfileRemedy) -> list[RatioChange]:
    """The basic-file changes of a :class:`ProfileRemedy` that reach its target, as the
    note prints them: the depth factor rounded up to 0.01, the drive pressure angle down to
    0.1° (each then reaches the target).

    Parameters
    ----------
    r : ProfileRemedy

    Returns
    -------
    list of RatioChange
        The depth factor's change first, then the pressure angle's; a change that no
        value within the tried range makes is left out (empty where neither).
    """
    ways = []
    if math.isfinite(r.k_d_needed):
        k_d = math.ceil(r.k_d_needed * 100) / 100
        over = (f", above the usual {DEPTH_FACTOR_USUAL:g}"
                if r.k_d_needed > DEPTH_FACTOR_USUAL + 1e-9 else "")
        ways.append(RatioChange("k_d", k_d, {"k_d": k_d},
                                f"a depth factor k_d of {k_d:.2f}{over} (now {r.k_d:g})"))
    if math.isfinite(r.alpha_d_needed):
        alpha = math.floor(r.alpha_d_needed * 10) / 10
        ways.append(RatioChange("alpha_dD", alpha, {"alpha_dD": math.radians(alpha)},
                                f"a drive pressure angle alpha_dD of {alpha:.1f} deg (now "
                                f"{r.alpha_d:g})"))
    return ways


def _profile_text(r: ProfileRemedy, judge=None) -> str:
    """The remedy sentence of a low ε_vα (:func:`low_ratio_text`); ``judge``, where given,
    says the remedies (:func:`low_ratio_text`)."""
    none = (f"no depth factor up to {_DEPTH_FACTOR_MAX:g} nor pressure angle down to "
            f"{_PRESSURE_ANGLE_MIN:g} deg")
    changes = profile_changes(r)
    if at_target(r.eps_va, r.target):
        return at_target_text("profile contact ratio eps_va", r.eps_va, r.target, changes)
    remedy = (judge(changes, r.target, none) if judge is not None and changes
              else _either([c.text for c in changes], r.target, none))
    return (f"profile contact ratio eps_va {_below(r.eps_va, r.target)} is below "
            f"{r.target:g}: the "
            "transverse section has, once per pitch, no pair in mesh and the load passes "
            "to the next pair only along the face, which a localised bearing shortens; "
            + remedy)


def low_ratio_text(design, face_target: float = FACE_CONTACT_RATIO_MIN,
                   profile_target: float = PROFILE_CONTACT_RATIO_MIN,
                   judge=None, teeth_check: _CountsCheck | None = None) -> str | None:
    """The cause and the remedy, in basic-file fields, of every contact ratio of a design
    below its limit: the face contact ratio (:func:`overlap_text`) and the profile contact
    ratio (:func:`profile_remedy`: the depth factor ``k_d``, the pressure angle
    ``alpha_dD``); None where both meet their limits or the blank cannot be computed.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
    face_target, profile_target : float — [1]
        Defaults :data:`FACE_CONTACT_RATIO_MIN`, :data:`PROFILE_CONTACT_RATIO_MIN`.
    judge : callable, optional
        ``judge(changes, target, none) -> str``: the end of each remedy's sentence from
        its :class:`RatioChange` list (:func:`overlap_changes`, :func:`profile_changes`),
        the target and the phrase for none, where each change is checked before it is
        offered (``ltca synthesize``: :func:`contact.optimize.remedy_check.
        checked_remedy_text`; ``ltca run``: the checks the case records); by default the
        changes are offered as equals ("… or …, the other kept, reaches 1").
    teeth_check : callable, optional
        The face contact ratio's tooth-count check (:func:`overlap_text`).

    Returns
    -------
    str or None
        E.g. "profile contact ratio eps_va 0.98 is below 1: ...; a depth factor k_d of
        2.05, above the usual 2 (now 2) or a drive pressure angle alpha_dD of 19.0 deg
        (now 20), the other kept, reaches 1" (k_d rounded up to 0.01, α_dD down to 0.1°).
    """
    from geometry.core.errors import InputError

    parts = []
    face = overlap_text(design, face_target, judge, teeth_check)
    if face is not None:
        parts.append(face)
    try:
        r = profile_remedy(design, profile_target)
    except (InputError, ValueError, ZeroDivisionError, AttributeError):
        r = None
    if r is not None and r.eps_va < r.target:
        parts.append(_profile_text(r, judge))
    return "; and the ".join(parts) if parts else None


def loaded_ratio_text(eps_va: float, eps_vb: float, pairs) -> str:
    """An analysis' contact ratios in one clause: ISO 10300-1's profile, face and total
    contact ratios of the virtual gears, each below its limit said so, and the loaded
    contact ratio the LTCA measured at one torque.

    Parameters
    ----------
    eps_va, eps_vb : float — [1]
        ε_vα, ε_vβ (``/rating``'s ``eps_va``, ``eps_vb``; NaN where not rated).
    pairs : array_like, shape (n_roll,) — [1]
        The tooth pairs carrying load at each roll position of the mesh cycle at that
        torque (``/ltca``'s ``pairs_in_contact``).

    Returns
    -------
    str
        E.g. "contact ratios eps_va 1.11, eps_vb 1.14 (below 1.25), total 2.25 (ISO
        10300-1); loaded contact ratio 2.15 (the mean of the tooth pairs carrying load,
        two pairs or more at every roll of the mesh cycle)"; where one pair carries the
        load alone at some rolls, "one pair alone over 30 % of the mesh cycle".

    Notes
    -----
    The loaded contact ratio is at most the total ε_vγ = ε_vα + ε_vβ of the flanks in
    mesh (a localised bearing's pattern is shorter than the flank): where it is near 1
    one pair carries the torque alone over much of the cycle and the LTE follows that
    pair's compliance and its TE parabola; nearer ε_vγ, the LTE is the stiffness variation
    of the pairs in mesh, which only more overlap (ε_vβ, ε_vα) lowers.
    """
    import numpy as np

    n = np.asarray(pairs, float)
    n = n[np.isfinite(n)]
    out = []
    if math.isfinite(eps_va) and math.isfinite(eps_vb):
        low_a = (f" (below {PROFILE_CONTACT_RATIO_MIN:g})"
                 if eps_va < PROFILE_CONTACT_RATIO_MIN else "")
        low_b = (f" (below {FACE_CONTACT_RATIO_MIN:g})"
                 if eps_vb < FACE_CONTACT_RATIO_MIN else "")
        out.append(f"contact ratios eps_va {eps_va:.2f}{low_a}, eps_vb {eps_vb:.2f}{low_b}, "
                   f"total {eps_va + eps_vb:.2f} (ISO 10300-1)")
    if n.size:
        alone = float(np.mean(n <= 1))
        share = (f"one pair alone over {100 * alone:.0f} % of the mesh cycle" if alone > 0.0
                 else "two pairs or more at every roll of the mesh cycle")
        out.append(f"loaded contact ratio {n.mean():.2f} (the mean of the tooth pairs "
                   f"carrying load, {share})")
    return "; ".join(out)


def face_width_text(b2: float, re2: float, met2: float) -> str | None:
    """``ltca synthesize``'s note on a gear face wider than bevel-gear practice accepts, or
    None where it is within.

    Parameters
    ----------
    b2 : float — [mm]
        Gear face width.
    re2 : float — [mm]
        Gear outer cone distance R_e2 (ISO 23509 blank).
    met2 : float — [mm]
        Gear outer transverse module m_et2 = d_e2 / z2.

    Returns
    -------
    str or None
        E.g. "gear face width b2 44.9 mm is above R_e2/3 = 34.4 mm (bevel-gear practice:
        b2 <= 0.3 R_e2 and <= 10 m_et, here 30.9 mm; …) …";
        None where b2 ≤ R_e2/3 and b2 ≤ 10 m_et (or an input is not a positive number).

    Notes
    -----
    Source: Niemann & Winter, *Maschinenelemente* III (b ≤ R_e/3, the outer end of bevel
    gear practice) and AGMA 2005-D03 (b ≤ 0.3 A_o and ≤ 10/P_d, i.e. 10 m_et). A wider face
    makes the toe's teeth small (top land and root strength at the toe) and the bearing
    move far along the face under load and mounting deflections; the tool analyses the
    face as given and says so (round 26d: an FM 11×35 at Σ 105° took b2 60 mm without a
    word).
    """
    vals = (b2, re2, met2)
    if not all(isinstance(v, (int, float)) and math.isfinite(v) and v > 0.0 for v in vals):
        return None
    outer, modules = FACE_WIDTH_OUTER * re2, FACE_WIDTH_MODULES * met2
    over = [f"R_e2/3 = {outer:.1f} mm" if b2 > outer else "",
            f"{FACE_WIDTH_MODULES:g} m_et = {modules:.1f} mm" if b2 > modules else ""]
    over = [o for o in over if o]
    if not over:
        return None
    usual = min(FACE_WIDTH_LIMIT * re2, modules)
    return (f"gear face width b2 {b2:g} mm is above {' and '.join(over)} (bevel-gear "
            "practice: b2 <= 0.3 R_e2 and <= 10 m_et, here "
            f"{usual:.1f} mm; AGMA 2005-D03): the toe's teeth become small (top "
            "land, root strength) and the bearing moves far along the face under load and "
            "mounting deflections; the face is analysed as given")
