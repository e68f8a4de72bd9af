"""The coast flank's check steps: where its LTE exceeds the verdict's limit, the ellipse
longer, the path nearer the lengthwise direction and the tip relief started later
(:func:`checked_coast_lte`, :data:`COAST_LTE_STEPS`, :data:`COAST_TIP_START_STEP`), its
TE level raised back (:func:`checked_coast_te`), a shallower root relief
(:func:`checked_coast_relief`) and, below the development's own LTE target, lighter
reliefs (:func:`checked_coast_lighter_relief`); where its peak pressure set its design
torque, a lighter tip relief (:func:`checked_coast_peak`). Each design placed and checked
on the coast flank at ``ltca run``'s sampling and kept by the check steps' one rule
(:func:`_coast_kept`: ``ltca run``'s verdict first, no flank peak pressure given up).
Split out of
:mod:`contact.optimize.development_check` (issue 71, Deliver 5), which re-exports every
public name; the bodies moved unchanged (the helpers they share imported under the
private names they call).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why as _kept_why
from contact.optimize.development_keep import lost_but_length as _lost_but_length
from contact.optimize.development_keep import pressure_raised as _pressure_raised
from contact.optimize.development_lte_steps import crossing_level
from contact.optimize.development_lte_steps import (
    shallower_root_relief as _shallower_root_relief,
)
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import TE_NAME, DevelopmentTargets
from contact.optimize.development_variant import check_rank as _check_rank
from contact.optimize.development_variant import said_variant as _said_variant
from geometry.case import Case
from geometry.core.text import plain_number

#: the coast check's steps (:func:`checked_coast_lte`), each a change of one prescription
#: [file units] from the design kept so far, tried in turn while its LTE exceeds the
#: verdict's limit: the ellipse longer (less lengthwise crowning), then the path angle
#: turned towards the lengthwise direction (less negative), each within its bounds
COAST_LTE_STEPS = (("ellipse_length", 0.1), ("path_angle", 15.0))

#: the coast check's last bearing step (:func:`checked_coast_lte`), after
#: :data:`COAST_LTE_STEPS`: the tip relief started later (``tip_relief_start`` towards its
#: upper bound) with the ellipse longer, both changes [file units] from the design kept
#: so far, each within its bounds; tried where the design has a tip relief
COAST_TIP_START_STEP = (("ellipse_length", 0.3), ("tip_relief_start", 0.35))


def checked_coast_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: Mapping[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case], *,
                      key_prefix: tuple = (), lte_limit: float | None = None,
                      level: float | None = None) -> DevelopmentEvaluation:
    """A coast flank whose LTE p-p at the check exceeds the verdict's limit at a torque
    given the bearing steps of :data:`COAST_LTE_STEPS` in turn while it does: the ellipse
    0.1 longer, then the path angle turned 15° towards the lengthwise direction (each
    within the bounds of its variable), then the tip relief started later with the ellipse
    longer (:data:`COAST_TIP_START_STEP`: ``tip_relief_start`` 0.35 and ``ellipse_length``
    0.3 on, each within its bounds; where the design has a tip relief), every other
    prescription kept; each one design (a
    synthesis of steps 3-6) placed and checked at :data:`CHECK_LTCA` on the coast flank,
    kept where it scores better, misses no target the design met but the pattern length
    (as :func:`checked_long`) and its flank peak pressure at the design torque is no
    higher than the design's or within the targets' ``max_flank_pressure`` (the coast
    redevelopment's pitting bound,
    :func:`contact.optimize.development_coast_flank.pitting_pressure`): the coast design
    torque, set afterwards by the coast flank's capacity, is not given up for it.
    ``lte_limit`` [µrad]: the development's LTE aim (default
    :func:`~contact.optimize.development_range_lte.development_lte_limit`, the verdict's
    60 µrad less the sampling margin); a design within it at its light and
    design torque is judged between them as ``ltca run --flank coast`` judges it
    (:func:`~contact.optimize.development_range_lte.range_lte` on the coast flank: its
    ``lte_range`` torques, the crossing bisected) and returned as it is where it keeps the
    limit there too; where it exceeds it there alone, the steps below act on that peak,
    each design judged on its largest LTE over the range
    (:func:`~contact.optimize.development_range_lte.range_better`, as the drive's last
    check step). ``key_prefix``: the kept pinion tooth's key
    before the design's bearing (:func:`checked_best`). Last, where the LTE still exceeds
    the limit at the design torque, the TE level raised back towards ``level`` (the coast
    flank's own ``te_level`` [µrad]; :func:`checked_coast_te`); then, where it exceeds
    the limit at a torque, a shallower root relief (:func:`checked_coast_relief`); last,
    where the design entered the steps above the limit and its LTE still misses the
    development's own target, lighter tip and root reliefs
    (:func:`checked_coast_lighter_relief`).

    Why: the coast flank's search has three bearings (the initial simplex of path angle
    and ellipse, :data:`~contact.optimize.development_coast_flank.COAST_BEARING_DESIGNS`)
    and its check no step of the bearing but the long bearing, whose root relief from
    half-way puts its pressure above the coast flank's pitting capacity. A longer contact
    ellipse (less lengthwise crowning) and a path nearer the lengthwise direction let more
    of the face share the load as the pairs hand over (Litvin & Fuentes 2004 §9.4;
    Stadtfeld 2014); the drive flank's path step turns the other way, towards the profile,
    which raised the coast LTE (the 11x33 below: −60° / −75° gave 84 / 90 and 104 / 120
    µrad against 62 / 68). Measured at ``ltca run``'s sampling on the coast flanks as
    written (``benchmarks/development_levers.py --flank coast --from-case``, 2026-11-26;
    LTE p-p light / design, objective): the hypoid 8x41 with b2 22 mm (28.8 / 119 N m,
    path −58.75°, ellipse 0.4) 67 / 62 µrad, 12.7; ellipse 0.5: 46 / 60 µrad, pattern 0.70
    long, flank peak 1479 → 1320 MPa, 6.15 (0.45: 56 / 75; 0.55: 1.1 % plastic; path
    −48.75°: 1.3 % plastic); the face-hobbed spiral bevel 11x33 (35.6 / 180.8 N m, path
    −45°, ellipse 0.55) 51 / 64 µrad, 9.55; ellipse 0.65: 44 / 57 µrad, 1576 → 1586 MPa
    (its redevelopment's pitting bound 1635 MPa), 6.66; path −35°: 43 / 56 µrad but
    1730 MPa; the generated-gear spiral bevel 20x30 (26.3 / 175.6 N m, path −45°,
    ellipse 0.55) 51 / 95 µrad, 33.1; ellipse 0.65: 56 / 115; path −40° / −35° / −30°:
    43 / 81, 36 / 67, 26 / 55 µrad (1170 → 1114 MPa), 3.35. A tip relief entering
    later leaves the tooth tip's share of the hand-over to the longer ellipse instead of
    lowering it: the unseen spiral bevel 13x37 at Σ 60° (coast 13.4 / 89.6 N m as written,
    path −58.75°, ellipse 0.4, tip relief from 0.5: LTE 111 / 68 µrad, 1389 MPa); ellipse
    0.7 with the tip relief from 0.85: 54 / 38 µrad, 1079 MPa, pattern 0.60 long, no edge
    (``python -m contact run --flank coast`` on the case edited by hand, 2026-11-26)."""
    from contact.optimize.development_range_lte import (
        development_lte_limit,
        range_better,
        range_lte,
        range_peak,
    )

    limit = development_lte_limit() if lte_limit is None else float(lte_limit)
    entered = best

    def between(e: DevelopmentEvaluation) -> float:  # its largest LTE over ltca run's range
        return range_peak(range_lte(e, setup, teeth, flank="coast", key_prefix=key_prefix))[0]

    def above(e: DevelopmentEvaluation) -> bool:  # at its own torques, else between them
        return bool(np.nanmax(e.metrics["lte_peak_to_peak"]) > limit or between(e) > limit)

    # above the limit between the torques alone: each step judged on the LTE over the range
    # (as the drive's, development_range_lte.checked_range_lte)
    better = (range_better(setup, teeth, limit, flank="coast", key_prefix=key_prefix)
              if best.checked_full
              and not np.nanmax(best.metrics["lte_peak_to_peak"]) > limit else None)
    if better is not None and above(best):
        found = range_lte(best, setup, teeth, flank="coast", key_prefix=key_prefix)
        peak, at = range_peak(found)
        say(f"  coast design {best.index + 1}: its LTE p-p {peak:.1f} urad at "
            f"{plain_number(at)} N m, "
            f"between the light and the design torque, is above {limit:g} urad (LTE p-p "
            f"{' / '.join(f'{x:.0f}' for x in found[1])} urad at "
            f"{' / '.join(plain_number(t) for t in found[0])} N m, ltca run's lte_range "
            "torques)")
    for changes in (*(((n, s),) for n, s in COAST_LTE_STEPS), COAST_TIP_START_STEP):
        if not best.checked_full or not above(best):
            return (best if best is entered else
                    checked_coast_lighter_relief(best, targets, setup, teeth, say, placed,
                                                 key_prefix=key_prefix))
        values = _coast_step_values(best.values, targets, changes)
        if values is None:
            continue
        name = " and ".join(n for n, _ in changes)
        said = ", ".join(f"{n} {values[n]:.4g}" for n, _ in changes)
        e = _said_variant(best, values, "coast lte",
                          f"with {said} (its LTE above {limit:g} urad)", targets,
                          setup, teeth, say, placed, flank="coast", key_prefix=key_prefix)
        if e is None:
            continue
        if _coast_kept(best, e, targets, name, say, better=better):
            best = e
    best = checked_coast_te(best, targets, setup, teeth, say, placed, key_prefix=key_prefix,
                            limit=limit, level=level)
    best = checked_coast_relief(best, targets, setup, teeth, say, placed,
                                key_prefix=key_prefix, limit=limit)
    return checked_coast_lighter_relief(best, targets, setup, teeth, say, placed,
                                        key_prefix=key_prefix)


def checked_coast_relief(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                         setup: Mapping[str, Any], teeth: KeptTeeth | None,
                         say: Callable[[str], None],
                         placed: Callable[[Mapping[str, float]], Case], *,
                         key_prefix: tuple = (), limit: float = 60.0
                         ) -> DevelopmentEvaluation:
    """The coast check's shallower root relief, after its other LTE steps
    (:func:`checked_coast_lte`): a coast design whose LTE p-p still exceeds ``limit``
    [µrad] at a torque gets its root relief × :data:`RELIEF_LTE_FRACTIONS` in turn (within
    its bounds, its start kept: step 7 only, no new local synthesis), each placed and
    checked at :data:`CHECK_LTCA` on the coast flank and kept on the rule of the coast
    LTE steps (:func:`_coast_kept`: it scores better, misses no target the design met but
    the pattern length, and its flank peak pressure at the design torque is no higher than
    the design's or within the targets' ``max_flank_pressure``); the first kept within
    ``limit`` at every torque ends it. A design within ``limit`` or without a root relief
    is returned as it is, without an analysis.

    Why: the drive flank's :func:`checked_relief_lte` for the coast flank. The coast
    flank's search sets its root relief against the edges and the pattern's height at the
    torque it is developed at, and a relief deeper than the teeth deflect keeps the loaded
    contact ratio below what the geometry gives (Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: the relief sized to the load's deflection). Measured on the unseen
    face-hobbed spiral bevel 9x33 (Method 1; benchmarks/data/unseen_designs), its coast
    flank as written at 15.4 / 79.9 N m (path −45°, ellipse 0.75, root relief 40 µm from
    0.2, tip relief 15 µm from 0.85, te_level 45; ``benchmarks/development_levers.py
    --flank coast --from-case --check``, 2026-11-26): LTE p-p 29.0 / 63.9 µrad, flank peak
    1369 MPa, objective 6.92; root relief 20 µm: 25.3 / 59.7 µrad, 1272 MPa, 5.03, no
    target lost; 13.3 µm: 25.6 / 56.6 µrad, 1230 MPa, but the centre v 0.64 off its band;
    none: 32 / 47 µrad with 1.6 % on the edges and 2482 MPa. The path (−35°: 26 / 61,
    1555 MPa), M's place (±0.05 of the face: 30 / 70, 27 / 63) and the profile crowning
    (5 µm: 41 / 68) did less."""

    def tried(best: DevelopmentEvaluation, values: dict[str, float],
              said: str) -> DevelopmentEvaluation:
        e = _said_variant(best, values, "coast lte", said, targets, setup, teeth, say,
                          placed, flank="coast", key_prefix=key_prefix)
        if e is not None and _coast_kept(best, e, targets, "shallower root relief", say):
            return e
        return best

    return _shallower_root_relief(best, targets, limit, tried)


#: the coast LTE steps' lighter reliefs (:func:`checked_coast_lighter_relief`): each a set
#: of (prescription, factor [1]) applied to the design the step starts from, within the
#: variable's bounds: the tip relief × ⅔; the tip and the root relief × ⅔ together
COAST_LIGHTER_RELIEF_STEPS = ((("tip_relief", 2.0 / 3.0),),
                              (("tip_relief", 2.0 / 3.0), ("root_relief", 2.0 / 3.0)))


def checked_coast_lighter_relief(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                                 setup: Mapping[str, Any], teeth: KeptTeeth | None,
                                 say: Callable[[str], None],
                                 placed: Callable[[Mapping[str, float]], Case], *,
                                 key_prefix: tuple = ()) -> DevelopmentEvaluation:
    """The coast LTE steps' last (:func:`checked_coast_lte`, run where the coast design
    entered them above the verdict's limit): a coast design whose LTE p-p still exceeds the
    development's own target ``targets.max_lte`` [µrad] at a torque gets lighter reliefs,
    each of :data:`COAST_LIGHTER_RELIEF_STEPS` on the design the step starts from (the tip
    relief × ⅔; the tip and root relief × ⅔ together; within their bounds, their starts
    kept: step 7 only, no new local synthesis), each placed and checked at
    :data:`CHECK_LTCA` on the coast flank; of those kept on the rule of the coast LTE
    steps (:func:`_coast_kept` against the design the step starts from: it scores better,
    misses no target that design met but the pattern length, and its flank peak pressure
    at the design torque is no higher or within the targets' ``max_flank_pressure``) the
    best scored is returned. A design within ``max_lte``, unchecked, or without a tip
    relief is returned as it is, without an analysis; at most 2 analyses.

    Why: the coast LTE steps stop at the verdict's 60 µrad, so a coast flank can be
    written a hair below it: the face-hobbed spiral bevel 9x33 (Method 1; benchmarks/data/
    unseen_designs) at 59.7 µrad. Its LTE at the coast design torque is not its floor (½
    p-p of the deflection between the light and the design torque, docs/synthesis.md,
    "The LTE floor of a face contact ratio near 1": 28-30 µrad) but the relief: the tip
    and root relief its relief stage set against the edges at the torque it was first
    developed at take the flank away where the next pair takes up its load (Stadtfeld,
    *Gleason Bevel Gear Technology*, 2014: the relief sized to the load's deflection).
    Measured on its coast flank as written at 15.4 / 79.9 N m (path −45°, ellipse 0.75,
    tip relief 15 µm from 0.85, root relief 20 µm from 0.2, te_level 45;
    ``benchmarks/development_levers.py --flank coast --from-case --check --floor 4``,
    2026-11-27): LTE p-p 25.3 / 59.7 µrad, flank peak 1272 MPa, objective 5.04; tip relief
    10 µm: 27.2 / 59.5 µrad, 1261 MPa, 4.98; with the root relief 13.3 µm: 27.5 / 55.6
    µrad, 1221 MPa, 3.55, no edge, no target lost (the root relief 13.3 µm alone: centre v
    0.64, off its band). Both are blade changes in a completing face-hobbing process
    (the blade's toprem and flankrem): the coast flank's alone, as every coast
    prescription of the synthesis is (docs/synthesis.md, "Face hobbing")."""
    if (not best.checked_full
            or not np.nanmax(best.metrics["lte_peak_to_peak"]) > targets.max_lte
            or not float(best.values.get("tip_relief", 0.0)) > 0.0):
        return best
    start, chosen = best, best
    for changes in COAST_LIGHTER_RELIEF_STEPS:
        values = dict(start.values)
        for name, factor in changes:
            if name not in targets.variables or name not in values:
                break
            lo, hi = (float(x) for x in targets.variables[name])
            values[name] = float(np.clip(factor * float(values[name]), lo, hi))
        else:
            if all(abs(values[n] - float(start.values[n])) < 1e-9 for n, _ in changes):
                continue
            said = ", ".join(f"{n} {values[n]:.3g} um" for n, _ in changes)
            e = _said_variant(start, values, "coast lte",
                              f"with {said} (its LTE above the target "
                              f"{targets.max_lte:g} urad)", targets, setup, teeth, say,
                              placed, flank="coast", key_prefix=key_prefix)
            if (e is not None and _coast_kept(start, e, targets, "lighter relief", say)
                    and _check_rank(e) < _check_rank(chosen)):
                chosen = e
    return chosen


#: the coast capacity step's lighter tip reliefs (:func:`checked_coast_peak`), each a
#: change [file units] of the written coast design: the tip relief halved, then started
#: 0.2 later (towards the tip), each within its variable's bounds
COAST_PEAK_STEPS = (("tip_relief", 0.5), ("tip_relief_start", 0.2))
#: least relative drop of the coast flank's peak pressure at the torque its capacity
#: search started at for :func:`checked_coast_peak` to keep a step [1]: the local pitting
#: safety is inversely proportional to it, and a drop below a node's worth of the
#: LTCA's pressure is not a capacity gained
COAST_PEAK_GAIN = 0.03


def checked_coast_peak(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       setup: Mapping[str, Any], teeth: KeptTeeth | None,
                       say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case], *, peak: float,
                       met: set[str], lte: float, key_prefix: tuple = ()
                       ) -> DevelopmentEvaluation | None:
    """The coast flank's lighter tip relief where its peak pressure set its design torque:
    the written coast design ``best`` with each step of :data:`COAST_PEAK_STEPS` (the tip
    relief halved; started 0.2 later), placed (step 7 only: no new local synthesis) and
    checked at :data:`CHECK_LTCA` on the coast flank at ``setup["torques"]`` (the light
    torque and the torque the coast capacity search started at). A step is kept where its
    flank peak pressure at that torque is at least :data:`COAST_PEAK_GAIN` below
    ``peak`` [MPa] (the capacity search's there) and below the steps' before, it meets
    every target in ``met`` (those the written design meets at its own torques) and its LTE
    p-p is within ``lte`` [µrad] at both torques. Returns the design of least peak kept,
    None where none is (nothing analysed where the design has no tip relief).

    Why: the coast flank's relief stage sets its tip relief against the edges at the
    torque it is developed at, and a deep relief from half-way narrows the profile band
    that carries the load: the coast design torque, which its local pitting safety then
    sets, falls with it. Measured on the unseen hypoid 6x45 (a 44 mm; benchmarks/data/
    unseen_designs), its coast flank as written at 11.4 / 76.4 N m (the drive's design
    torque; tip relief 51 µm from 0.556, root relief 56 µm from 0.31, ellipse 0.4;
    ``benchmarks/development_levers.py --flank coast --from-case --check``, 2026-11-26):
    flank peak 1588 MPa (S_H,loc 0.87: coast design torque 41.8 N m, 55 % of the drive's);
    tip relief 25.5 µm: 1474 MPa; from 0.75: 1469 MPa; each with every target met, no
    edge, LTE 20 / 22 µrad; the root relief halved or started earlier left it at 1584-1591
    MPa."""
    if (best.full is None or not float(best.values.get("tip_relief", 0.0)) > 0.0
            or not math.isfinite(peak)):
        return None
    chosen, least = None, (1.0 - COAST_PEAK_GAIN) * float(peak)
    for name, step in COAST_PEAK_STEPS:
        if name not in targets.variables or name not in best.values:
            continue
        lo, hi = (float(x) for x in targets.variables[name])
        now = float(best.values[name])
        x = float(np.clip(now * step if name == "tip_relief" else now + step, lo, hi))
        if abs(x - now) < 1e-9:
            continue
        e = _said_variant(best, dict(best.values) | {name: x}, "coast capacity",
                          f"with {name} {x:.3g} (its peak {peak:.0f} MPa set the coast "
                          "design torque)", targets, setup, teeth, say, placed,
                          flank="coast", key_prefix=key_prefix)
        if e is None:
            continue
        p = float(e.metrics["pressure_max_flank"][-1])
        lost = sorted(k for k in met if e.full[1].get(k, 0.0) > 0.0)
        loud = not np.nanmax(e.metrics["lte_peak_to_peak"]) <= lte
        if lost or loud:
            say(f"  not kept: the {name} step misses "
                + ", ".join(lost + ([f"LTE (above {lte:.0f} urad)"] if loud else [])))
            continue
        if p < least:
            chosen, least = e, p
    return chosen


def _coast_step_values(values: Mapping[str, float], targets: DevelopmentTargets,
                       changes: tuple[tuple[str, float], ...]) -> dict[str, float] | None:
    """A coast LTE step's prescriptions: ``values`` with each of ``changes`` (name, step
    [file units]) added, clipped to the variable's bounds; None where a variable is not
    varied or not in ``values``, where the last change does not move (at its bound), or
    where a later tip relief start is asked of a design without tip relief."""
    out = dict(values)
    for name, step in changes:
        if name not in targets.variables or name not in values:
            return None
        lo, hi = (float(x) for x in targets.variables[name])
        out[name] = float(np.clip(float(values[name]) + step, lo, hi))
    last = changes[-1][0]
    if abs(out[last] - float(values[last])) < 1e-9:
        return None
    if last == "tip_relief_start" and not float(values.get("tip_relief", 1.0)) > 0.0:
        return None
    return out


def _coast_kept(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                targets: DevelopmentTargets, name: str, say: Callable[[str], None],
                better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool]
                | None = None) -> bool:
    """Whether a coast LTE step's design ``e`` replaces ``best``, on the check steps' one
    keep rule (:func:`~contact.optimize.development_keep.kept_why`, its mounting tolerance
    not asked: the tolerance is the drive flank's): ``ltca run``'s verdict first
    (:func:`~contact.optimize.development_keep.verdict_lost`: a design whose checked LTE
    the verdict FAILs never replaces one it passes; one it passes replaces one it FAILs
    where it gives up no target ``best`` met but the pattern's length and centre, and
    raises no peak), else it ranks better (:func:`_check_rank`), misses no target ``best``
    met but the pattern length (:func:`_lost_but_length`) and its flank peak pressure at
    the design torque is no higher than ``best``'s or within the targets'
    ``max_flank_pressure`` (:func:`_pressure_raised`); where a lost target refuses it, one
    line said.

    Why the verdict first: the rank alone kept a coast design whose LTE the verdict FAILs
    over a step's passing design that moved the pattern's centre off its band, so the
    case was written with the FAIL a user reads first (the drive flank's steps ask it
    since the 8x35 k_d 2.16, docs/synthesis.md "A verdict the design does not
    deserve"; issue 71)."""

    def lost(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        raised = _pressure_raised(best, e, targets)
        return _lost_but_length(best, e) + ([raised] if raised else [])

    rank = {} if better is None else {"better": better}
    return not _kept_why(best, e, targets, {}, None, say, f"the {name} step", lost=lost,
                         tolerant=False, **rank)


def _limit_rank(e: DevelopmentEvaluation, limit: float) -> tuple[bool, bool, float]:
    """A coast LTE step's rank: its LTE p-p within ``limit`` [µrad] at every torque first,
    then :func:`_check_rank`."""
    return (not np.nanmax(e.metrics["lte_peak_to_peak"]) <= limit, *_check_rank(e))


def checked_coast_te(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case], *,
                     key_prefix: tuple = (), limit: float = 60.0,
                     level: float | None = None) -> DevelopmentEvaluation:
    """The coast check's last LTE step: a coast design whose LTE p-p still exceeds
    ``limit`` [µrad] at its design torque, above its light-load LTE, and whose ``te_level``
    the coarse search's TE stage lowered below ``level`` (the coast flank's own TE level
    [µrad], :data:`TE_NAME`) gets the TE level raised back: first to ``level`` (within its
    bounds); where the light and design LTE cross between the two, a second design at
    their crossing (:func:`crossing_level`). Each one design (a synthesis of steps 3-6)
    placed and checked at :data:`CHECK_LTCA` on the coast flank and acceptable on the
    rules of :func:`checked_coast_lte` against the design before the step
    (:func:`_coast_kept`); of the two the one within ``limit`` at every torque kept
    first, then the better score; at most 2 designs, none where ``level`` is None.

    Why: the TE stage lowers the level on the coarse LTCA, whose LTE reads low, and
    flattens the parabola the coast flank hands its pairs over on at the design torque. On
    the unseen spiral bevel 13x37 at Σ 60° (ε_vβ 1.13; coast 16.5 / 106.3 N m, its search
    lowered te_level 45 → 25 µrad; ``benchmarks/development_levers.py --flank coast
    --from-case``, ``ltca run``'s sampling, 2026-11-26) the LTE p-p light / design was 56 /
    63 µrad at 25, 59.2 / 59.6 at 40 (1405 MPa, objective 8.16 against 8.51), 60.3 / 58.5
    at 45 (1367 MPa): the light LTE rises with the level and the design LTE falls, their
    larger least where they cross; the ellipse and path steps before it scored worse or
    peaked higher there."""
    if (level is None or not best.checked_full
            or TE_NAME not in targets.variables or TE_NAME not in best.values):
        return best
    lte = best.metrics["lte_peak_to_peak"]
    light, design = float(lte[0]), float(lte[-1])
    if not (design > limit and design > light):
        return best
    lo, hi = (float(x) for x in targets.variables[TE_NAME])
    now = float(best.values[TE_NAME])
    top = float(np.clip(level, lo, hi))
    if not top > now + 1.0:
        return best
    base, tried = best, [top]
    while tried:
        x = tried.pop()
        values = dict(base.values) | {TE_NAME: x}
        e = _said_variant(base, values, "coast lte",
                          f"with {TE_NAME} {x:.3g} urad (its LTE above {limit:g} urad at "
                          "the design torque)", targets, setup, teeth, say, placed,
                          flank="coast", key_prefix=key_prefix)
        if e is None:
            break
        # each against the design before the step (its peak, its met targets); of the
        # two, the one within the limit first (what the step is for: the verdict's
        # limit at every torque, where the objective's sum of squares may prefer 60.3 /
        # 58.5 to 59.4 / 59.4), then the better score
        if (_coast_kept(base, e, targets, TE_NAME, say)
                and _limit_rank(e, limit) < _limit_rank(best, limit)):
            best = e
        if x == top and not np.nanmax(e.metrics["lte_peak_to_peak"]) <= limit:
            lte1 = e.metrics["lte_peak_to_peak"]
            cross = crossing_level(now, (light, design), top, (float(lte1[0]), float(lte1[-1])))
            if cross is not None and now + 1.0 < cross < top - 1.0:
                tried.append(round(cross, 1))
    return best
