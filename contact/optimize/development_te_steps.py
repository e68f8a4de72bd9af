"""The check's TE step: the TE stage again at ``ltca run``'s sampling, the chosen design's
``te_level`` lowered where it misses the LTE target there (:func:`checked_te`, the first
of :func:`~contact.optimize.development_check.check_steps`). Split out of
:mod:`contact.optimize.development_check` (issue 71, Deliver 5), which re-exports it; the
body moved unchanged.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import TE_NAME, DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case


def checked_te(best: DevelopmentEvaluation, targets: DevelopmentTargets,
               setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
               placed: Callable[[Mapping[str, float]], Case], level: float
               ) -> DevelopmentEvaluation:
    """The TE stage again at the check: where the chosen design misses the LTE target at
    ``ltca run``'s sampling, its ``te_level`` lowered by 20 µrad, then to the lower bound,
    each design placed and checked at :data:`~contact.optimize.development_evaluate.
    CHECK_LTCA` and kept where it scores better (the TE stage's steps, by the one keep
    rule :func:`~contact.optimize.development_keep.kept_why` without its tolerance; at
    most 2 designs).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The chosen design, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (``variables["te_level"]``: its bounds [µrad]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).
    level : float
        The flank's own TE level [µrad], where the design's values do not give one.

    Returns
    -------
    DevelopmentEvaluation
        The design kept, ``stage`` ``"te"``; ``best`` itself where no step scored better
        or the step does not apply (no ``te_level`` developed, not checked, the LTE met).
        A design whose synthesis or analysis fails ends the step (logged, not raised).

    Notes
    -----
    Why: the coarse LTCA's LTE is a few µrad low: 38 against 43 µrad at ``ltca run``'s
    sampling on the face-hobbed hypoid 11x43 of tests/data/designs, whose search stopped
    at its fifth design, every target met coarsely. Source: the issue-71 development's TE
    stage (docs/synthesis.md, "Development bearing").
    """
    if (TE_NAME not in targets.variables or not best.checked_full
            or best.full[1]["lte"] == 0.0):
        return best
    lo, hi = targets.variables[TE_NAME]
    current = float(best.values.get(TE_NAME, level))
    for x in (max(lo, min(hi, current) - 20.0), lo):
        if best.full[1]["lte"] == 0.0 or x >= current - 1e-9:
            break
        e = said_variant(best, best.values | {TE_NAME: float(x)}, "te",
                         f"at {TE_NAME} {x:.3g} urad", targets, setup, teeth, say, placed)
        if kept_why(best, e, targets, setup, teeth, say, tolerant=False):
            break  # not analysed, or it scores no better (the TE step asks no tolerance)
        best, current = e, float(x)
    return best
