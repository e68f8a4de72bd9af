"""The check's path step: the chosen design's bearing turned towards the profile where it
misses its pattern length or LTE at ``ltca run``'s sampling (:func:`checked_path`,
:data:`PATH_STEPS`; a generated gear's pattern too short :data:`GENERATED_PATH_STEPS`),
each design kept by :func:`~contact.optimize.development_keep.kept_why`. The height steps
give their designs this step too (:mod:`contact.optimize.development_height_steps`), and
:mod:`contact.optimize.development_load_lte` turns by :data:`PATH_STEPS`' angles. Split
out of :mod:`contact.optimize.development_check` (issue 71, Deliver 5), which re-exports
every public name; the body moved unchanged.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, ranks_better
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import VARIABLES, DevelopmentTargets
from contact.optimize.development_variant import pattern_length, said_variant
from geometry.case import Case

#: the development's one logger, whichever of its modules logs
log = logging.getLogger("contact.optimize.development")


#: the check's steps of the path angle towards the profile [deg] and of the ellipse
#: [1] (:func:`checked_path`): one design each
PATH_STEPS = ((-15.0, -0.05), (-30.0, -0.1))


#: the check's steps of the path angle towards the profile [deg] and of the ellipse [1]
#: where a **generated** gear's light-load pattern is too short (:func:`checked_path`):
#: the turns of :data:`PATH_STEPS` with the ellipse lengthened by 0.04 (0.05 and more
#: ran the 20x30's pattern onto the heel at the mounting excursions) and the far turn
#: without it (at the ISO capacity the longer ellipse loads the heel edge; after the
#: design torque is lowered the steps run again, and there it does not)
GENERATED_PATH_STEPS = ((-15.0, 0.04), (-30.0, 0.0), (-30.0, 0.04))


#: [deg] how far :data:`GENERATED_PATH_STEPS` turn the path where the development's
#: ``path_angle`` bounds are the defaults (:data:`~contact.optimize.development_targets.
#: VARIABLES`, whose −80° the Formate designs' steps keep): nearly along the profile,
#: where the light-load pattern is the ellipse alone and the most tooth pairs share the
#: transfer (the 20x30's numbers in :func:`checked_path`)
GENERATED_PATH_LIMIT = -88.0


def checked_path(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
                 placed: Callable[[Mapping[str, float]], Case], *,
                 bar: DevelopmentEvaluation | None = None) -> DevelopmentEvaluation:
    """The chosen design's bearing turned towards the profile at the check: where it
    misses the pattern length or the LTE at ``ltca run``'s sampling, the path angle turned
    by :data:`PATH_STEPS` towards the profile direction (clipped to its bound) and, where
    the pattern is too long (beyond its tolerance), the ellipse shortened with it; where
    the LTE alone is missed, the ellipse lengthened by as much where the pattern stays
    within its length tolerance by that; each design placed and checked at
    :data:`~contact.optimize.development_evaluate.CHECK_LTCA` and kept where it scores
    better and is tolerant (:func:`~contact.optimize.development_keep.kept_why`), until
    one meets every target (at most 2 designs, each a synthesis of steps 3-6). A
    **generated** gear's pattern too short (below the target's middle, beyond its
    tolerance) takes :data:`GENERATED_PATH_STEPS` instead: the ellipse lengthened with
    the turn, the path turned as far as :data:`GENERATED_PATH_LIMIT` where its bounds are
    the defaults (at most 3 designs). A Formate design's pattern too short with no turn
    left (the path at its bound already, or the step's turn clipped to a path tried) has
    the ellipse lengthened by the step's amount instead.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``path_angle`` [deg] and
        ``ellipse_length`` [1]; the pattern length and its tolerance [1 of the face]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).
    bar : DevelopmentEvaluation, optional
        Where given (a height step's design, :func:`~contact.optimize.
        development_height_steps.kept_height_step`), a design is kept only where it also
        ranks before ``bar``, the design the step's outcome must beat: one that does not
        is not asked for its tolerance (the mounting excursions, up to four coarse
        analyses), which could not change the outcome.

    Returns
    -------
    DevelopmentEvaluation
        The design kept, ``stage`` ``"path"``; ``best`` itself where none was, or where
        the step does not apply (path or ellipse not developed, not checked, its length
        and LTE met). A design whose synthesis or analysis fails is not kept (logged, not
        raised).

    Notes
    -----
    Why: the light-load pattern is the ellipse plus the path's lengthwise travel over the
    roll of one tooth pair, and a path nearer the profile both shortens that travel and
    keeps more tooth pairs in contact. Measured on the truck hypoid 9x37 of
    tests/data/designs (its developed design, ``ltca run``'s sampling at 312 / 2082 N m):
    path −58.75° / ellipse 0.55: pattern 0.62 long, LTE 39 / 38 µrad, 1.55 pairs in
    contact at light load; −70° / 0.55: 0.62, 18 / 20 µrad, 1.70; −80° / 0.45: 0.58, 25 /
    23 µrad, 1.65 pairs, every target met; the ellipse alone 0.55 → 0.45 at −58.75°:
    0.53 long but 71 / 64 µrad (docs/synthesis.md, "What sets the pattern and the
    LTE"). A longer ellipse (less lengthwise crowning) lowers the LTE at the design
    torque, where a spiral bevel's LTE is made: on the spiral bevel 13x39 (its developed
    design, path −66.9°, ellipse 0.7, ``ltca run``'s sampling at 36.98 / 246.5 N m; LTE
    19 / 50 µrad, pattern 0.53 long) the ellipse 0.75 gave 17 / 44 µrad, 0.55 long, as
    the path −75° did; the earlier rule, the ellipse shortened wherever the pattern was
    longer than its target's middle, had taken it from 0.75 to 0.7 (2026-11-25).

    A **generated** gear's pattern too short (below the target's middle, beyond its
    tolerance) takes :data:`GENERATED_PATH_STEPS` instead: the ellipse lengthened with the
    turn, the path turned as far as :data:`GENERATED_PATH_LIMIT` where its bounds are the
    defaults (at most 3 designs). The generated spiral bevel 20x30 of
    tests/data/generated_gear (ε_vβ 1.26; its developed relief, ``te_level`` 10 µrad,
    ``ltca run``'s sampling at 25.65 / 171 N m): path −80° / ellipse 0.4 (the −80° bound
    reached): pattern 0.35–0.73, LTE 45 / 92 µrad; −88° / 0.45: 0.35–0.80, 31 / 53 µrad,
    edge 0.5 %, no plastic segment; the pattern's heel end jumps to the heel at 0.47 (its
    ease-off falls towards the heel at the tip), so 0.04 per step. At the ISO capacity
    (41.5 / 276.7 N m) −88° / 0.4 gives 30 / 62 µrad, no plastic, and −88° / 0.45 2.1 % of
    the torque plastic at the heel. With steps of 0.05 its development wrote −88° / 0.4
    (``ltca run`` at 26.3 / 175.6 N m: 38.7 / 81.7 µrad, against 43.3 / 92.4 at −80°): the
    0.45 reaches the heel at the mounting excursions, not kept; at those torques −88° /
    0.44 gives 0.35–0.78, 32 / 58 µrad and stays clear of toe and heel at every
    excursion (docs/synthesis.md, "Why the pattern is short and the LTE high"). Formate
    designs keep :data:`PATH_STEPS` (their developed
    cases unchanged); where their pattern is too short and no turn is left (the path at
    its bound already, or the step's turn clipped to a path tried), the step lengthens the
    ellipse by its amount instead (a face-hobbed hypoid 5x45 at a 50 mm offset,
    benchmarks/data/unseen_designs: −65.6° → −80°, ellipse 0.625, pattern 0.35 long at
    4.6 N m, where nothing more was tried)."""
    names = ("path_angle", "ellipse_length")
    if (not best.checked_full
            or not all(n in targets.variables and n in best.values for n in names)):
        return best
    short = best.full[1]
    if short["length"] == 0.0 and short["lte"] == 0.0:
        return best
    (p_lo, p_hi), (e_lo, e_hi) = (targets.variables[n] for n in names)
    length = pattern_length(best)
    longest = targets.pattern_length + targets.pattern_length_tolerance
    base, tried = best, []
    # a generated gear's pattern too short: the ellipse lengthened at each turn, the path
    # turned nearly along the profile where the bounds are the defaults
    lengthen = (getattr(getattr(best.case, "gear", None), "process", None) == "Generate"
                and short["length"] > 0.0 and length < targets.pattern_length)
    if lengthen and tuple(targets.variables["path_angle"]) == tuple(VARIABLES["path_angle"]):
        p_lo = min(p_lo, GENERATED_PATH_LIMIT)
    for turn, shorter in GENERATED_PATH_STEPS if lengthen else PATH_STEPS:
        # the ellipse shortened where the pattern is too long; lengthened where the LTE
        # alone is missed and the pattern has room for it (the lengthwise crowning
        # lowered: more of the face carries the transfer at the design torque)
        change = (shorter if lengthen
                  else shorter if short["length"] > 0.0 and length > targets.pattern_length
                  else -shorter if short["length"] == 0.0 and length - shorter <= longest
                  else 0.0)
        path = float(np.clip(base.values["path_angle"] + turn, p_lo, p_hi))
        if (not lengthen and short["length"] > 0.0 and length < targets.pattern_length
                and (path == base.values["path_angle"]
                     or any(t["path_angle"] == path for t in tried))):
            # a Formate design's pattern too short with no turn left (the path at its
            # bound already, or the turn clipped to a path tried): the ellipse lengthened
            # by as much instead (less lengthwise crowning) — the face-hobbed 5x45 of
            # unseen round 10 (−65.6° → −80°, ellipse 0.625: pattern 0.35 long at its
            # light torque 4.6 N m) tried nothing more
            change = -shorter
            log.info("check: the pattern %.3g long with the path at its bound %.3g deg: "
                     "the ellipse %.3g longer", length, path, change)
        values = base.values | {
            "path_angle": path,
            "ellipse_length": float(np.clip(base.values["ellipse_length"] + change,
                                            e_lo, e_hi))}
        if values in tried or all(values[n] == base.values[n] for n in names):
            continue
        tried.append(values)
        e = said_variant(best, values, "path",
                         f"with path_angle {values['path_angle']:.3g}, ellipse_length "
                         f"{values['ellipse_length']:.3g}", targets, setup, teeth, say,
                         placed)
        if e is not None and not kept_why(
                best, e, targets, setup, teeth, say,
                better=lambda b, x: ranks_better(b, x) and (bar is None
                                                            or ranks_better(bar, x))):
            best = e
            if e.met:
                break
    return best


