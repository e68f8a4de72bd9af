"""The check's steps on the light-load pattern's height: the height by the root relief
instead of a blade-angle change (:func:`checked_blade`), a pattern still above its depth
centre lowered by a shorter tip relief (:func:`checked_tip`, :data:`TIP_FRACTIONS`) and
then by the root relief with a longer ellipse (:func:`checked_root`,
:data:`ROOT_STEP_ELLIPSE`); each step's design given the path step
(:func:`~contact.optimize.development_path_steps.checked_path`) and kept where it scores
better and is tolerant (:func:`kept_height_step`). Where the design is not tolerant
itself, :mod:`contact.optimize.development_height_relief` moves both reliefs together.
Split out of :mod:`contact.optimize.development_check` (issue 71, Deliver 5), which
re-exports every public name; the bodies moved unchanged.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why
from contact.optimize.development_path_steps import checked_path
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import footprint_centre_v
from contact.optimize.development_targets import HEIGHT_NAME, DevelopmentTargets
from contact.optimize.development_variant import pattern_length, said_variant
from geometry.case import Case

#: the check's shorter tip reliefs (:func:`checked_tip`), fractions of the chosen
#: design's tip relief, each started at the upper bound of ``tip_relief_start``, tried in
#: turn until one meets every target
TIP_FRACTIONS = (0.8, 2.0 / 3.0, 0.5)

#: the check's root relief step (:func:`checked_root`): the ellipse lengthened by this
#: [1] with the root relief at its upper bound
ROOT_STEP_ELLIPSE = 0.1


def pattern_high(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: Mapping[str, Any], names: tuple[str, ...]) -> bool:
    """Whether a height step (:func:`checked_tip`, :func:`checked_root`) applies.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far.
    targets : DevelopmentTargets
        The development's targets (``pattern_centre_v`` [1 of the working depth] or None,
        ``variables``).
    setup : mapping
        The development's state (its ``"centre_v"`` [1 of the working depth], the target
        centre where ``targets.pattern_centre_v`` is None).
    names : tuple of str
        The variables the step moves.

    Returns
    -------
    bool
        The design was checked at :data:`~contact.optimize.development_evaluate.
        CHECK_LTCA` and misses its light-load centre v there, its footprint centre v
        (finite, :func:`~contact.optimize.development_stages.footprint_centre_v`) is at or
        above the target centre, and every variable of ``names`` is developed (in the
        targets' variables and the design's values).

    Notes
    -----
    Source: the issue-71 development's height targets (docs/synthesis.md, "Development
    bearing"; docs/own_gear_set.md, "The pattern's height").
    """
    if (not best.checked_full or best.full[1]["centre_v"] == 0.0
            or not all(n in targets.variables and n in best.values for n in names)
            or not math.isfinite(footprint_centre_v(best))):
        return False
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    return footprint_centre_v(best) >= target


def checked_tip(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
                placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """A pattern still above its depth centre at the check lowered by a shorter tip
    relief: where the checked design's light-load footprint centre v is above its
    tolerance (:func:`pattern_high`) and its edge share at the design torque at most half
    its limit, the tip relief shortened to each of :data:`TIP_FRACTIONS` of the design's
    and started at the upper bound of ``tip_relief_start``, in turn; each design placed
    and checked at :data:`~contact.optimize.development_evaluate.CHECK_LTCA`, then, where
    it misses the pattern length or the LTE, given the path step
    (:func:`~contact.optimize.development_path_steps.checked_path`); kept where it scores
    better and is tolerant (:func:`kept_height_step`), until one meets every target (at
    most 3 designs, each with its path step's 2).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``tip_relief`` [µm] and
        ``tip_relief_start`` [1]; ``max_edge_share`` [1]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``stage`` ``"tip"``, or ``"path"`` where its path step's design
        was); ``best`` itself where none was or the step does not apply. A design whose
        synthesis or analysis fails is not kept (logged, not raised).

    Notes
    -----
    Why: the pinion's tip meets the gear's flank low in its working depth, so the tip
    relief takes the lower part of the light-load pattern away and raises its centre,
    without the unloaded TE the blade angle costs (docs/own_gear_set.md, "The pattern's
    height"); the edge share at the design torque and the edges at the mounting
    excursions are what bound it. Measured at ``ltca run``'s sampling (2026-11-25): on
    the spiral bevel 13x39 of tests/data/designs (36.98 / 246.5 N m, path −66.9°,
    ellipse 0.75, root relief 40 µm from 0.2), tip relief 15 µm from 0.85 of the way:
    centre v 0.64 (target 0.548 ± 0.08), LTE 17 / 44 µrad; 12 µm from 0.9: 0.63, 15 / 44;
    10 µm: 0.62, 14 / 49; 7.5 µm: 0.61, 15 / 43 but 1.6 % of the design torque plastic at
    ΔE +0.05 mm; 12 µm from 0.9 with the path −80° (the path step): LTE 10 / 38 µrad,
    every target met, tolerant. On the hypoid 12x41 at Σ 85° (66.48 / 443.2 N m, path
    −60°, ellipse 0.7): 15 µm from 0.85: v 0.63 (0.545 ± 0.08); 12 µm from 0.9: 0.62,
    pattern 0.62 long, tolerant; 10 µm: 0.62, every target met but 0.5 % plastic at ΔE
    +0.05 mm; 12 µm with the path −75°, ellipse 0.65: every target met, tolerant. The
    single step of half the tip relief before (7.5 µm) uncovered the tip edge on both.
    """
    names = ("tip_relief", "tip_relief_start")
    if (not pattern_high(best, targets, setup, names)
            or float(best.metrics["edge_load_share"][1]) > 0.5 * targets.max_edge_share):
        return best
    (r_lo, r_hi), (_, s_hi) = (targets.variables[n] for n in names)
    start, tried = best, []
    for fraction in TIP_FRACTIONS:
        values = start.values | {
            "tip_relief": float(np.clip(fraction * start.values["tip_relief"], r_lo, r_hi)),
            "tip_relief_start": float(s_hi)}
        if values in tried or all(values[n] == start.values[n] for n in names):
            continue
        tried.append(values)
        e = said_variant(start, values, "tip",
                         f"with tip_relief {values['tip_relief']:.3g} from "
                         f"{values['tip_relief_start']:.3g}", targets, setup, teeth, say,
                         placed)
        if e is None:
            continue
        best = kept_height_step(e, best, targets, setup, teeth, say, placed)
        if best.met:
            break
    return best


def kept_height_step(e: DevelopmentEvaluation, best: DevelopmentEvaluation,
                     targets: DevelopmentTargets, setup: Mapping[str, Any],
                     teeth: KeptTeeth | None, say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """A height step's design ``e`` (:func:`checked_tip`, :func:`checked_root`,
    :func:`checked_blade`) given the path step (:func:`~contact.optimize.
    development_path_steps.checked_path`, only where it misses the pattern length or the
    LTE; its designs must rank before ``best`` too), then kept over ``best`` where it
    scores better and is tolerant (the one keep rule, :func:`~contact.optimize.
    development_keep.kept_why`, which asks no lost target here; a design the path step
    kept is tolerant already).

    Parameters
    ----------
    e : DevelopmentEvaluation
        The height step's design, checked at ``ltca run``'s sampling.
    best : DevelopmentEvaluation
        The design the check's steps kept so far.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``path_angle`` [deg] and
        ``ellipse_length`` [1], for the path step).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).

    Returns
    -------
    DevelopmentEvaluation
        The better of the two: the step's design (or its path step's) where kept, else
        ``best``.

    Notes
    -----
    Why tolerant: the tip edge a shorter tip relief uncovers must stay elastic at the
    mounting excursions (the spiral bevel 13x39's 7.5 µm from 0.9: 0.3–1.6 % of the design
    torque plastic at ΔE +0.05 mm; docs/own_gear_set.md, "The pattern's height").
    """
    turned = checked_path(e, targets, setup, teeth, say, placed, bar=best)
    # a design the path step kept is tolerant already: asked only of the step's own
    return best if kept_why(best, turned, targets, setup, teeth, say,
                            tolerant=turned is e) else turned


def checked_blade(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                  setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
                  placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """The pattern's height by the root relief instead of the blade angle: where the
    checked design misses a target and carries a blade-angle change, one design without
    it and with the root relief at its upper bound from the lower bound of
    ``relief_start`` (the height stage's first lever); placed and checked at
    :data:`~contact.optimize.development_evaluate.CHECK_LTCA`, given the path step where
    it misses the length or the LTE, kept where it scores better and is tolerant
    (:func:`kept_height_step`); the tip and root steps after it lower a pattern it leaves
    high.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``blade_angle_change``
        [deg], ``root_relief`` [µm] and ``relief_start`` [1]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``stage`` ``"height"``, or ``"path"`` where its path step's
        design was); ``best`` itself where it was not or the step does not apply (every
        target met, no blade-angle change). A design whose synthesis or analysis fails
        is not kept (logged, not raised).

    Notes
    -----
    Why: the blade-angle change centres the pattern but walks it towards the heel and
    costs unloaded TE (docs/own_gear_set.md, "The pattern's height"). Measured on an
    industrial spiral bevel 12x48 (d_e2 400 mm, b2 60 mm, β_m 35°, Method 0; ``ltca
    run``'s sampling at 273.45 / 1823 N m, path −75°, ellipse 0.45, 2026-11-25): blade
    angle −0.177°: centre v 0.55, pattern 0.65 long (0.5 ± 0.1), LTE 30 / 36 µrad,
    unloaded TE 114 µrad; the ellipse shortened to 0.35 for the length: 54 / 54 µrad; no
    blade-angle change, root relief 60 µm from 0.2: v 0.62, 0.50 long, LTE 13 / 21 µrad,
    every target met, tolerant.
    """
    names = (HEIGHT_NAME, "root_relief", "relief_start")
    if (not best.checked_full or best.met
            or not all(n in targets.variables and n in best.values for n in names)
            or best.values[HEIGHT_NAME] == 0.0):
        return best
    (_, r_hi), (s_lo, _) = (targets.variables[n] for n in names[1:])
    values = best.values | {HEIGHT_NAME: 0.0, "root_relief": float(r_hi),
                            "relief_start": float(s_lo)}
    e = said_variant(best, values, "height",
                     f"without its blade-angle change, root_relief "
                     f"{values['root_relief']:.3g} from {values['relief_start']:.3g}",
                     targets, setup, teeth, say, placed)
    if e is None:
        return best
    return kept_height_step(e, best, targets, setup, teeth, say, placed)


def checked_root(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
                 placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """A pattern still above its depth centre after the tip step lowered by the root
    relief, its LTE bought back by a longer ellipse: where the checked design's
    footprint centre v is above its tolerance (:func:`pattern_high`), the root relief at
    its upper bound from the lower bound of ``relief_start`` (the height stage's lever,
    :mod:`contact.optimize.development_stages`) and the ellipse lengthened by
    :data:`ROOT_STEP_ELLIPSE` where the pattern stays within its length tolerance by that;
    one design (a synthesis of steps 3-6) placed and checked at
    :data:`~contact.optimize.development_evaluate.CHECK_LTCA`, given the path step where
    it misses the length or the LTE, kept where it scores better and is tolerant
    (:func:`kept_height_step`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``root_relief`` [µm],
        ``relief_start`` [1] and ``ellipse_length`` [1]; the pattern length and its
        tolerance [1 of the face]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``stage`` ``"root"``, or ``"path"`` where its path step's design
        was); ``best`` itself where it was not or the step does not apply. A design whose
        synthesis or analysis fails is not kept (logged, not raised).

    Notes
    -----
    Why: the pinion's root relief takes the gear's tip band (which meets the pinion's
    root) out of the light-load footprint, but the load it leaves raises the LTE at the
    design torque, which is why the search does not keep it; a longer ellipse (less
    lengthwise crowning) lowers that LTE again. Measured at ``ltca run``'s sampling on a
    hypoid 9x41 at Σ 95° (d_e2 230 mm, a 30 mm, Method 1; 62.25 / 415 N m, path −58.8°,
    tip relief 15 µm from 0.85, 2026-11-25): ellipse 0.55, root relief 40 µm from 0.2:
    centre v 0.62 (0.542 ± 0.08, missed), LTE 35 / 38 µrad, 2.0 % on edges at ΔE −0.05 mm
    (not tolerant); root relief 60 µm: v 0.61 but LTE 37 / 44 µrad; with the ellipse
    0.65: v 0.61, LTE 23 / 29 µrad, edge 0.9 %, every target met, tolerant. Where the
    edge share leaves no room for a shorter tip relief (1.5 % at the design torque
    there), this is the height's lever left: the blade-angle change costs about 1 µrad
    of unloaded TE per 0.001° (39 → 49 → 65 µrad at 0, −0.03°, −0.06°).
    """
    names = ("root_relief", "relief_start", "ellipse_length")
    if not pattern_high(best, targets, setup, names):
        return best
    (_, r_hi), (s_lo, _), (e_lo, e_hi) = (targets.variables[n] for n in names)
    length = pattern_length(best)
    room = (length + ROOT_STEP_ELLIPSE
            <= targets.pattern_length + targets.pattern_length_tolerance + 1e-9)
    values = best.values | {
        "root_relief": float(r_hi), "relief_start": float(s_lo),
        "ellipse_length": float(np.clip(best.values["ellipse_length"]
                                        + (ROOT_STEP_ELLIPSE if room else 0.0), e_lo, e_hi))}
    if all(values[n] == best.values[n] for n in names):
        return best
    e = said_variant(best, values, "root",
                     f"with root_relief {values['root_relief']:.3g} from "
                     f"{values['relief_start']:.3g}, ellipse_length "
                     f"{values['ellipse_length']:.3g}", targets, setup, teeth, say, placed)
    if e is None:
        return best
    return kept_height_step(e, best, targets, setup, teeth, say, placed)
