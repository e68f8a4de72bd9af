"""The development's check step for a drive LTE at the design torque above the target
where the contact ratios are low (issue 71): the modified roll's TE parabola matched to
the load, then the bearing a step longer.

:func:`checked_matched_te` gives a checked drive design that misses the development's LTE
target (``max_lte``) with the design torque's LTE p-p the larger of the two, on a pair
whose face contact ratio ε_vβ is below :data:`FACE_RATIO_LOW` or whose profile contact
ratio ε_vα is below :data:`~contact.optimize.development_profile_ratio.PROFILE_RATIO_MIN`,
a deeper parabola of the modified roll sized to the gap between the two torques' LTE
(:func:`matched_level`), then the level at which they meet (:func:`secant_level`), then
the ellipse :data:`~contact.optimize.development_lte_steps.ELLIPSE_STEP` longer (less
lengthwise crowning) at the level kept. Each design is kept on the check steps' one rule
(:func:`~contact.optimize.development_keep.kept_why`: ranks better, no met target lost,
tolerant at the mounting excursions). A design that meets its LTE target, whose light
torque's LTE is the larger, or whose contact ratios are not low (:func:`runs_on`) is
returned as it is, without an analysis.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_lte_steps import ELLIPSE_STEP, lte_reached
from contact.optimize.development_profile_ratio import PROFILE_RATIO_MIN
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import TE_NAME, VARIABLES, DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted

log = logging.getLogger("contact.optimize.development")

#: [1] the face contact ratio ε_vβ below which :func:`checked_matched_te` runs: the least
#: bevel-gear design practice asks for (AGMA 2005-D03; ``ltca synthesize``'s contact-ratio
#: note reads the same), below which one pair carries the load alone over part of the
#: mesh cycle and the deflection's change from one to two pairs sets the LTE at the
#: design torque
FACE_RATIO_LOW = 1.25

#: [µrad] the largest ``te_level`` :func:`checked_matched_te` tries where the targets'
#: bounds of it are the defaults (:data:`~contact.optimize.development_targets.VARIABLES`,
#: [10, 45] µrad: the TE stage's search, which lowers the level); bounds the user gave are
#: kept. Four times the default upper bound: on the spiral bevel 15x28 at Σ 110° of
#: benchmarks/data/unseen_designs (its written bearing, 91.8 / 612.4 N m) te_level 250
#: µrad puts the light torque's LTE spread above the verdict's plausibility limit (121 /
#: 81 µrad, one pair alone), 150 µrad does not (100 / 97 µrad)
TE_MATCH_CEILING = 180.0

#: [1] the gap between the design and the light torque's LTE p-p closed per µrad of
#: ``te_level`` in :func:`matched_level`'s first guess: the parabola te_level·(φ/p)²
#: (``te_level`` the unloaded TE at ±1 pitch p of pinion roll) is te_level / 4 at the
#: hand-over (±½ pitch); it raises the light torque's LTE, which is the unloaded TE there,
#: by about that and the deflection at the design torque takes it up, lowering its LTE by
#: about as much: the gap closes by about half the level's rise (measured on the 15x28:
#: te_level 45 → 150 µrad closed 32 → −3 µrad, 0.33 per µrad; the secant corrects it)
GAP_PER_LEVEL = 0.5

#: the step's levers in words, as ``ltca synthesize``'s note lists the levers tried
#: (:func:`~contact.optimize.development_lte_steps.lte_reached`)
PARABOLA_LEVER = "the TE parabola matched to the load"
BEARING_LEVER = "the bearing lengthened"

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "matched te"


def contact_ratios(case: Case) -> tuple[float, float]:
    """The profile and face contact ratios ε_vα, ε_vβ [1] of a case's ISO 23509 basic
    design (its ``[design]`` table), by ISO 10300-1:2014's virtual cylindrical gears.

    Parameters
    ----------
    case : geometry.case.Case
        A case with a ``[design]`` table (every case ``ltca synthesize`` writes).

    Returns
    -------
    (float, float) — [1]
        (ε_vα, ε_vβ); NaN both where the case has no ``[design]`` table or its blank cannot
        be made (logged).

    Raises
    ------
    Nothing: a case without basic design data gives NaN (the step does not run).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A, A.2 (``contact.load_capacity.iso10300``).
    """
    from contact.load_capacity.iso10300.rating import case_gear_data
    from contact.load_capacity.iso10300.virtual_gears import virtual_gears

    try:
        gear_data, _ = case_gear_data(case)
        v = virtual_gears(gear_data)
        return float(v.eps_va), float(v.eps_vb)
    except Exception as exc:  # no [design] table: the step has no ratio to read
        raise_if_interrupted(exc)
        log.info("development: no contact ratios of the case (%s)", exc)
        return math.nan, math.nan


def low_ratios(eps_va: float, eps_vb: float) -> bool:
    """Whether contact ratios are low for :func:`checked_matched_te`: ε_vβ below
    :data:`FACE_RATIO_LOW` (1.25) or ε_vα below
    :data:`~contact.optimize.development_profile_ratio.PROFILE_RATIO_MIN` (1.05).

    Parameters
    ----------
    eps_va, eps_vb : float — [1]
        The profile and face contact ratios (NaN: unknown, not low).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: AGMA 2005-D03 (ε_vβ ≥ 1.25 in bevel-gear practice); ISO 10300-1:2014, Annex A
    (ε_vα below 1: once per pitch no pair in the transverse section).
    """
    return bool(float(eps_vb) < FACE_RATIO_LOW or float(eps_va) < PROFILE_RATIO_MIN)


def lte_ends(e: DevelopmentEvaluation) -> tuple[float, float]:
    """A checked design's LTE p-p at the light and the design torque [µrad].

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics["lte_peak_to_peak"]`` [µrad], light torque first.

    Returns
    -------
    (float, float) — [µrad]

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the development's metrics (:mod:`contact.optimize.development_evaluate`).
    """
    lte = np.asarray(e.metrics["lte_peak_to_peak"], float)
    return float(lte[0]), float(lte[-1])


def level_ceiling(targets: DevelopmentTargets) -> float:
    """The largest ``te_level`` [µrad] :func:`checked_matched_te` tries:
    :data:`TE_MATCH_CEILING` where the targets' bounds of it are the defaults, else the
    upper bound the user gave.

    Parameters
    ----------
    targets : DevelopmentTargets
        Its ``variables[TE_NAME]`` (lower, upper) [µrad].

    Returns
    -------
    float — [µrad]

    Raises
    ------
    KeyError
        Where the targets do not vary ``te_level`` (:func:`runs_on` asks first).

    Notes
    -----
    Source: the development's variables (docs/synthesis.md, "Development bearing":
    bounds given are used as given).
    """
    lo, hi = (float(x) for x in targets.variables[TE_NAME])
    if (lo, hi) == tuple(float(x) for x in VARIABLES[TE_NAME]):
        return max(hi, TE_MATCH_CEILING)
    return hi


def runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
            ratios: Callable[[], tuple[float, float]], level: float = math.nan) -> bool:
    """The step's gate, asked without an analysis: ``best`` is checked, misses the
    development's LTE target with the design torque's LTE p-p above ``max_lte`` and above
    the light torque's, the targets vary ``te_level`` and its ceiling
    (:func:`level_ceiling`) is above the design's level, and the contact ratios
    ``ratios()`` (ε_vα, ε_vβ, read last) are low (:func:`low_ratios`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``max_lte`` [µrad], ``variables``).
    ratios : callable → (float, float)
        The pair's (ε_vα, ε_vβ) [1], called only where every other condition holds.
    level : float, optional — [µrad]
        The flank's own ``te_level`` (the basic file's, else the default 45 µrad: what the
        case is written with), where the design's values carry none (a design no TE step
        changed); NaN (default): such a design is not tried.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (the drive LTE where the contact ratios are low; docs/synthesis.md,
    "The TE parabola matched to the load where the contact ratios are low"). A design
    whose values carry no ``te_level`` has the flank's own (the check's other TE steps read
    it so, :func:`~contact.optimize.development_te_steps.checked_te`); before, the gate
    read NaN there and the step never ran on it: the spiral bevel 19x33 at Σ 78° of
    benchmarks/data/unseen_designs (ε_vβ 1.23; LTE 20 / 67 µrad at 131.9 / 879.8 N m)
    was written without it (docs/synthesis.md, "The drive LTE target against the levers").
    """
    if (not best.checked_full
            or TE_NAME not in targets.variables
            or not float(best.full[1].get("lte", 0.0)) > 0.0):
        return False
    light, design = lte_ends(best)
    if not (design > float(targets.max_lte) and design > light):
        return False
    now = own_level(best, level)
    if not level_ceiling(targets) > now + 1.0:  # NaN: no level known, not tried
        return False
    return low_ratios(*ratios())


def own_level(e: DevelopmentEvaluation, level: float = math.nan) -> float:
    """A design's ``te_level`` [µrad]: its values' where they carry one, else ``level``
    (the flank's own, what the case is written with).

    Parameters
    ----------
    e : DevelopmentEvaluation
        The design (its ``values``, file units).
    level : float, optional — [µrad]
        The flank's own level (NaN: unknown).

    Returns
    -------
    float — [µrad]
        NaN where neither gives one.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the check's TE steps' convention
    (:func:`~contact.optimize.development_te_steps.checked_te`: ``values.get(te_level,
    level)``).
    """
    return float(e.values.get(TE_NAME, level))


def matched_level(now: float, light: float, design: float, ceiling: float) -> float:
    """The first ``te_level`` [µrad] of :func:`checked_matched_te`: the design's level
    raised by the gap between the design and the light torque's LTE p-p over
    :data:`GAP_PER_LEVEL`, at most ``ceiling``.

    Parameters
    ----------
    now : float — [µrad]
        The design's ``te_level``.
    light, design : float — [µrad]
        Its LTE p-p at the light and the design torque.
    ceiling : float — [µrad]
        The largest level tried (:func:`level_ceiling`).

    Returns
    -------
    float — [µrad]

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4 (the
    predesigned parabolic TE absorbs the transfer's jump); the factor measured
    (:data:`GAP_PER_LEVEL`).
    """
    return float(min(float(now) + (float(design) - float(light)) / GAP_PER_LEVEL,
                     float(ceiling)))


def secant_level(x0: float, gap0: float, x1: float, gap1: float, lo: float,
                 ceiling: float) -> float | None:
    """The ``te_level`` [µrad] at which the design and the light torque's LTE p-p meet,
    by the secant through two designs that differ only in it: ``x0`` with the gap
    ``gap0`` (design − light) [µrad], ``x1`` with ``gap1``; within [``lo``,
    ``ceiling``]. Unlike :func:`~contact.optimize.development_lte_steps.crossing_level`
    it extrapolates (the first guess may fall short).

    Parameters
    ----------
    x0, gap0, x1, gap1 : float — [µrad]
    lo, ceiling : float — [µrad]
        The bounds of the level.

    Returns
    -------
    float or None — [µrad]
        None where the gap does not change with the level or a value is not finite.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the secant method (the gap taken linear in the level between the designs).
    """
    vals = (float(x0), float(gap0), float(x1), float(gap1))
    if not all(math.isfinite(v) for v in vals) or abs(vals[1] - vals[3]) < 1e-9:
        return None
    x = vals[0] + (vals[2] - vals[0]) * vals[1] / (vals[1] - vals[3])
    return float(np.clip(x, float(lo), float(ceiling)))


def checked_matched_te(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       setup: Mapping[str, Any], teeth: KeptTeeth | None,
                       say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case], *,
                       eps: tuple[float, float] | None = None,
                       level: float = math.nan) -> DevelopmentEvaluation:
    """A drive design that misses the development's LTE target with the design torque's
    LTE the larger, on a pair of low contact ratios (:func:`runs_on`), given the modified
    roll's TE parabola matched to the load and then a longer bearing: ``te_level`` at
    :func:`matched_level`, then at the level where the two torques' LTE meet
    (:func:`secant_level` through the design and the first; where it differs from the
    first by more than 2 µrad), then the ellipse :data:`~contact.optimize.
    development_lte_steps.ELLIPSE_STEP` longer (within its bounds) at the level kept. Each
    design (a synthesis of steps 3-6) placed and checked at ``ltca run``'s sampling (the
    secant only where the first lowered the design torque's LTE), kept
    where it ranks better, misses no target the design met (the pattern length included)
    and is tolerant at ΔE/ΔP ± 0.05 mm (:func:`~contact.optimize.development_keep.
    kept_why`); at most three designs.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).
    eps : (float, float), optional — [1]
        The pair's (ε_vα, ε_vβ) (default :func:`contact_ratios` of the design's case, read
        only where the LTE gate holds).
    level : float, optional — [µrad]
        The flank's own ``te_level``, the design's where its values carry none
        (:func:`own_level`; the check passes it as its other TE steps get it). NaN
        (default): such a design is not tried.

    Returns
    -------
    DevelopmentEvaluation
        The design kept: ``best`` itself where the gate does not hold or no design scored
        better.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: the LTE p-p at a torque is that of the unloaded TE plus the mesh deflection;
    with low contact ratios one pair carries the load alone over part of the cycle and the
    deflection jumps where the second pair takes up its share. The parabola of the
    modified roll lowers the design torque's LTE where its depth at the hand-over is about
    that jump's, and raises the light torque's by as much (there the unloaded TE is the
    LTE): the larger of the two is least where they meet (Litvin & Fuentes, *Gear
    Geometry and Applied Theory*, 2nd ed., 2004, §9.4; Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: the parabola sized to the load's deflection, the longer bearing
    whose lengthwise crowning lets the second pair share the load earlier). Neither
    lowers the load sharing's floor, ½ p-p(δ_design − δ_light) (docs/synthesis.md, "The
    LTE floor of a face contact ratio near 1"), which a step of the ellipse moves little:
    the step brings the LTE to it.

    Measured at ``ltca run``'s sampling on the face-milled spiral bevel 15x28 at Σ 110° of
    benchmarks/data/unseen_designs (ε_vα 1.19, ε_vβ 0.91; 91.8 / 612.4 N m; its written
    bearing path −45°, ellipse 0.65, root relief 60 µm from 0.2, tip relief 15 µm from
    0.85, no profile crowning, te_level 45 µrad; ``benchmarks/development_levers.py
    --check --floor 4 --tolerance --from-case``, 2026-11-27; LTE p-p light / design
    [µrad], the floor): 82 / 114, 90; te_level 80 / 125 / 135 / 150 / 250: 89 / 107, 95 /
    101, 97 / 100, 100 / 97, 121 / 81 (spread); the ellipse 0.7 with te_level 130: 90 /
    103, length 0.58, tolerant (objective 73.3 → 65.9); the ellipse 0.75 / 0.85: 66 / 129
    (length 0.62), 54 / 117, floor 91 / 82; path −35° / −55°: 131 / 91, 58 / 140; no tip
    relief: 51 / 126, 6.5 % plastic; relief from 0.3: 66 / 138; the floor 82-91 µrad
    with every lever: 60 µrad is out of this bearing's reach at 612.4 N m. ``ltca
    synthesize`` with the step writes it with te_level 128.1 µrad and the ellipse 0.7:
    90 / 103 µrad, tolerant, flank peak 1343 → 1313 MPa. Where the parabola is not the
    lever it raises both torques' LTE and nothing is kept: the 15x28 at β_m 43.9° (ε_vα
    1.00, ε_vβ 1.25; 76.4 / 509.7 N m, path −80°, ellipse 0.75, te_level 10 µrad): 34 /
    54 → te_level 50: 42 / 57 µrad; the face-hobbed hypoid 8x35 at Σ 85° (ε_vα 0.94): 52
    / 57 → te_level 20.6: 54 / 60, the ellipse 0.6: 37 / 41 µrad with the pattern 0.63
    long (a target lost).
    """
    if eps is not None:
        def ratios() -> tuple[float, float]:
            return float(eps[0]), float(eps[1])
    else:
        def ratios() -> tuple[float, float]:
            return contact_ratios(best.case) if best.case is not None else (math.nan,
                                                                             math.nan)
    if not runs_on(best, targets, ratios, level):
        return best
    records: list[tuple[DevelopmentEvaluation, str, str, str]] = []
    kept = _designs(best, targets, setup, teeth, say, placed, records, level)
    # the least-LTE record ltca synthesize's note states: a design kept and then
    # replaced by a later one of the step is not the one written
    lte_reached(setup, best, f"design {best.index + 1} as checked")
    for e, what, why, lever in records:
        if not why and e is not kept:
            why = "a later design of the step scores better"
        lte_reached(setup, e, what, why, lever)
    return kept


def _designs(start: DevelopmentEvaluation, targets: DevelopmentTargets,
             setup: Mapping[str, Any], teeth: KeptTeeth | None,
             say: Callable[[str], None],
             placed: Callable[[Mapping[str, float]], Case],
             records: list[tuple[DevelopmentEvaluation, str, str, str]],
             level: float = math.nan) -> DevelopmentEvaluation:
    """:func:`checked_matched_te`'s designs past its gate: the design kept; each
    design analysed appended to ``records`` (design, words, why not kept, lever)."""
    best = start
    lo = float(targets.variables[TE_NAME][0])
    ceiling = level_ceiling(targets)
    now = own_level(start, level)
    light, design = lte_ends(start)
    first = round(matched_level(now, light, design, ceiling), 1)
    e = said_variant(start, dict(start.values) | {TE_NAME: first}, STAGE,
                     f"with te_level {first:.3g} urad, the parabola matched to its load "
                     f"(LTE {light:.0f}/{design:.0f} urad, the design torque's the larger)",
                     targets, setup, teeth, say, placed)
    if e is None:
        return best
    why = kept_why(best, e, targets, setup, teeth, say, "the matched TE parabola",
                   lost=lost_targets)
    records.append((e, f"design {start.index + 1} with te_level {first:.3g} urad", why,
                    PARABOLA_LEVER))
    if not why:
        best = e
    l1, d1 = lte_ends(e)
    # the secant only where the deeper parabola lowered the design torque's LTE: where it
    # did not (the 15x28 at β_m 43.9°: te_level 10 → 50 µrad, 34 / 53 → 42 / 57 µrad) the
    # parabola is not the lever and its two torques do not meet the lower for it
    meet = (secant_level(now, design - light, first, d1 - l1, lo, ceiling)
            if d1 < design else None)
    if meet is not None and abs(meet - first) > 2.0 and abs(meet - now) > 2.0:
        meet = round(meet, 1)
        e = said_variant(start, dict(start.values) | {TE_NAME: meet}, STAGE,
                         f"with te_level {meet:.3g} urad, where its light and design "
                         "torque's LTE meet", targets, setup, teeth, say, placed)
        if e is not None:
            why = kept_why(best, e, targets, setup, teeth, say,
                           "the TE parabola where the LTE meet", lost=lost_targets)
            records.append((e, f"design {start.index + 1} with te_level {meet:.3g} "
                            "urad", why, PARABOLA_LEVER))
            if not why:
                best = e
    name = "ellipse_length"
    if (name not in targets.variables or name not in best.values
            or not float(best.full[1].get("lte", 0.0)) > 0.0):
        return best
    e_hi = float(max(targets.variables[name]))
    longer = round(min(float(best.values[name]) + ELLIPSE_STEP, e_hi), 4)
    if not longer > float(best.values[name]) + 1e-9:
        return best
    e = said_variant(best, dict(best.values) | {name: longer}, STAGE,
                     f"with ellipse_length {longer:.3g} at te_level "
                     f"{own_level(best, level):.3g} urad (a longer bearing; its LTE "
                     "missed)", targets, setup, teeth, say, placed)
    if e is None:
        return best
    why = kept_why(best, e, targets, setup, teeth, say, "the longer bearing",
                   lost=lost_targets)
    records.append((e, f"design {start.index + 1} with ellipse_length {longer:.3g}, "
                    f"te_level {own_level(best, level):.3g} urad", why, BEARING_LEVER))
    return best if why else e


def matched_after_window(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                         setup: dict[str, Any], teeth: KeptTeeth | None,
                         say: Callable[[str], None],
                         placed: Callable[[Mapping[str, float]], Case],
                         level: float = math.nan) -> DevelopmentEvaluation:
    """The written drive design after the LTE window rule lowered its design torque
    (:func:`~contact.optimize.development_written_lte.written_lte_capacity`): the TE
    parabola matched to the load at the lowered torques (:func:`checked_matched_te`, its
    gate and keep rule), a design kept only where its LTE p-p keeps the verdict's limit at
    every torque of ``ltca run``'s ``lte_range`` too (the rule's own promise), and its range
    recorded (:func:`~contact.optimize.development_range_lte.kept_range_said`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The written design scored at the lowered torques (``setup["torques"]``).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).
    level : float, optional — [µrad]
        The flank's own ``te_level`` (:func:`own_level`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept; ``best`` where the gate does not hold, none ranked better or the
        one kept exceeds the limit between the torques.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: the development matches the parabola at the torque it develops at (the ISO 10300
    capacity); the window rule then lowers the design torque to where the bearing keeps
    60 µrad, and the development's own LTE target at that torque was never aimed at. On the
    FM spiral bevel 19x33 at Σ 78° of benchmarks/data/unseen_designs (ε_vβ 1.23) the
    parabola matched at 879.8 N m raised the design torque's LTE (20 / 67 → 35 / 86 µrad
    at te_level 140: the pattern at the face's ends there), while on the same bearing at
    the lowered 59.2 / 394.7 N m te_level 45 / 90 / 150 µrad gave 25 / 60, 33 / 56, 45 / 44
    µrad (the classical rule: the parabola's depth matched to the deflection's change, the
    two torques' LTE meet near the load sharing's floor, 37-41 µrad;
    ``benchmarks/development_levers.py --check --floor 4 --from-case``, 2026-11-29).
    """
    from contact.optimize.development_range_lte import (
        development_lte_limit,
        kept_range_said,
        range_lte,
        range_peak,
    )

    kept = checked_matched_te(best, targets, setup, teeth, say, placed, level=level)
    if kept is best:
        return best
    limit = development_lte_limit()
    peak, at = range_peak(range_lte(kept, setup, teeth))
    if not peak <= limit:
        say(f"  not kept: the parabola matched at the lowered torques has its LTE p-p "
            f"{peak:.1f} urad at {at:.4g} N m between them, above {limit:g} urad")
        return best
    kept_range_said(setup, best, kept, teeth, say,
                    "the TE parabola matched at the lowered design torque")
    return kept
