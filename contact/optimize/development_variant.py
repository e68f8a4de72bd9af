"""A check step's design: placed as it is written, analysed at ``ltca run``'s sampling
(:data:`~contact.optimize.development_evaluate.CHECK_LTCA`) and scored.

:func:`checked_analysis` places and analyses a design of the check (kept in the
development's ``setup``: a design the steps reach again is neither synthesised nor
analysed again); :func:`checked_variant` scores it as a variant of a checked design,
:func:`said_variant` also says its line; :func:`check_rank` ranks checked designs (a
FAIL-level LTE last, :func:`lte_fails`; every target met first). The lowest of the final
check's modules (issue 71, Deliver 5: split out of
:mod:`contact.optimize.development_check`, which re-exports every public name; the
bodies moved unchanged).
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize import development_evaluate as evaluation
from contact.optimize.development_evaluate import (
    CHECK_LTCA,
    MEMO_DECIMALS,
    KeptTeeth,
    bearing_key,
    evaluation_line,
)
from contact.optimize.development_result import DevelopmentEvaluation, scored
from contact.optimize.development_targets import DevelopmentTargets
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted

#: the development's one logger, whichever of its modules logs
log = logging.getLogger("contact.optimize.development")


def _rounded_key(key: tuple) -> tuple:
    """``key`` with its float members (nested in tuples too) rounded to
    :data:`MEMO_DECIMALS` decimals; its other members as they are."""
    return tuple(_rounded_key(k) if isinstance(k, tuple)
                 else round(float(k), MEMO_DECIMALS) if isinstance(k, float) else k
                 for k in key)


def checked_analysis(setup: Mapping[str, Any], placed: Callable[[Mapping[str, float]], Case],
                     values: Mapping[str, float], teeth: KeptTeeth | None,
                     pinion_key: tuple, flank: str = "drive", *, case: Case | None = None
                     ) -> tuple[Case, dict, tuple]:
    """A design of the check placed as it is written (``placed(values)``) and its
    ``flank`` analysed at :data:`CHECK_LTCA` at the development's torques
    (``setup["torques"]`` [N·m]), the pinion tooth kept under ``pinion_key``
    (:class:`KeptTeeth`): the case, the metrics and the grid bounds of
    :func:`~contact.optimize.development_evaluate.analyse_design`. Its errors propagate.
    ``case``: ``placed(values)`` already made (not made again).

    Kept in ``setup`` (key ``"check_memo"``, by ``placed``, the flank, the values, the
    torques, the pinion key and the kept teeth), an error too: a design the check's
    steps reach again — the steps of each checked design (:func:`steps_on_each`), a path
    step after a height step (:func:`kept_height_step`), the long bearing of designs that
    differ only in what it sets — is neither synthesised nor analysed again, the same
    numbers (issue 71: the spiral bevel 13x37 at Σ 60° checked one long bearing three
    times, each a synthesis and an ease-off that found too few nodes). The values (and
    the pinion key's numbers) are keyed to :data:`MEMO_DECIMALS` decimals, as the coarse
    search's own memo (:func:`~contact.optimize.development_evaluate.evaluator`): a step
    that reaches a design again through another computation of the same number (the TE
    level raised back to the flank's own level after the deeper-TE step tried its upper
    bound, branch cpu92) keeps it, the first computation's case and metrics."""
    memo = setup.setdefault("check_memo", {}) if isinstance(setup, dict) else {}
    key = (id(placed), flank, tuple((k, round(float(v), MEMO_DECIMALS))
                                    for k, v in values.items()),
           tuple(float(t) for t in setup["torques"]), _rounded_key(pinion_key), id(teeth))
    kept = memo.get(key)
    if kept is not None and kept[0] is placed and kept[1] is teeth:
        log.debug("development: check of %s at %s N m kept", dict(values), key[3])
        if isinstance(kept[2], Exception):
            raise kept[2]
        return kept[2]
    try:
        case = placed(values) if case is None else case
        ms, grid = evaluation.analyse_design(case, setup["torques"], options=CHECK_LTCA,
                                             teeth=teeth, pinion_key=pinion_key, flank=flank)
    except Exception as exc:
        memo[key] = (placed, teeth, exc)  # held: their ids are not reused while kept
        raise
    memo[key] = (placed, teeth, (case, ms, grid))
    return case, ms, grid


def lte_fails(e: DevelopmentEvaluation) -> bool:
    """Whether a checked design's LTE fails ``ltca run``'s verdict: its LTE peak-to-peak
    at a torque of the check above :data:`contact.study.verdicts.LTE_FAIL_FACTOR` × the
    verdict's limit :data:`contact.study.verdicts.LTE_LIMIT` (2 × 60 µrad).

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design; only one checked at ``ltca run``'s sampling (``checked``, its
        ``metrics``' ``lte_peak_to_peak`` [µrad] at the light and the design torque) can
        fail (the coarse search's LTE is its own sampling's, not the verdict's).

    Returns
    -------
    bool
        True where the checked LTE p-p exceeds the verdict's FAIL level at any torque;
        False where the design is not checked or its metrics carry no LTE.

    Notes
    -----
    Source: the ``lte`` check of ``ltca run``'s verdict (:mod:`contact.study.verdicts`);
    issue 71: the face-hobbed hypoid 8x35 at Σ 85° (k_d 2.16) ended on 605 / 600 µrad
    after its steps had seen 24 / 21 µrad (not tolerant) and 204 / 37 µrad (pattern
    length), docs/synthesis.md "A verdict the design does not deserve".
    """
    from contact.study.verdicts import LTE_FAIL_FACTOR, LTE_LIMIT  # imports contact.ltca

    if not e.checked or e.metrics is None or "lte_peak_to_peak" not in e.metrics:
        return False  # no checked LTE: nothing the verdict's LTE check could fail
    lte = np.asarray(e.metrics["lte_peak_to_peak"], float)
    return bool(np.any(lte > LTE_FAIL_FACTOR * LTE_LIMIT))


def check_rank(e: DevelopmentEvaluation) -> tuple[bool, bool, float]:
    """A checked design's rank: a design whose LTE ``ltca run``'s verdict FAILs last
    (:func:`lte_fails`), then every target met first, then the least objective.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design scored (its ``full``: objective [1], shortfalls, every target met).

    Returns
    -------
    (bool, bool, float)
        Sorts last the design whose checked LTE fails the verdict, first the design that
        meets every target, then the least objective [1].

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    The LTE's squared shortfall alone did not keep a FAIL-level bearing behind a nearer
    one that missed a softer target: the 8x35 k_d 2.16's steps refused 24 / 21 µrad (not
    tolerant) and 204 / 37 µrad (pattern length) and ended on 605 / 600 µrad
    (docs/synthesis.md, "A verdict the design does not deserve").
    """
    return (lte_fails(e), not e.full[2], e.full[0])


def pattern_length(e: DevelopmentEvaluation) -> float:
    """A checked design's light-load pattern length [1 of the face].

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics`` (``pattern_toe_u``, ``pattern_heel_u`` [1], light torque
        first).

    Returns
    -------
    float
        ``pattern_heel_u - pattern_toe_u`` at the light torque [1].

    Notes
    -----
    Source: the issue-71 development's pattern targets (docs/synthesis.md, "Development
    bearing").
    """
    return float(e.metrics["pattern_heel_u"][0] - e.metrics["pattern_toe_u"][0])


def changed_values(values: Mapping[str, float], base: Mapping[str, float]) -> str:
    """The prescriptions of ``values`` that differ from ``base``'s, as said in a check
    step's line ("path_angle -75, ellipse_length 0.35").

    Parameters
    ----------
    values, base : mapping str → float
        The variant's and the design's prescriptions [file units].

    Returns
    -------
    str

    Notes
    -----
    Source: the issue-71 development's check lines (docs/synthesis.md).
    """
    return ", ".join(f"{k} {float(v):.3g}" for k, v in values.items()
                     if float(v) != float(base.get(k, math.nan)))


def checked_variant(base: DevelopmentEvaluation, values: Mapping[str, float], stage: str,
                    targets: DevelopmentTargets, setup: Mapping[str, Any],
                    teeth: KeptTeeth, placed: Callable[[Mapping[str, float]], Case], *,
                    pinion_key: tuple | None = None, flank: str = "drive",
                    case: Case | None = None) -> DevelopmentEvaluation | None:
    """``base`` with the prescriptions ``values``: its case placed as it is written
    (``placed``; ``case``: that case already made), analysed at :data:`CHECK_LTCA` at the
    development's torques and scored (:func:`development_score`), recorded as checked at
    ``stage``. ``pinion_key``: the kept pinion tooth's key (default the design's bearing,
    :func:`bearing_key`). None where the synthesis or the analysis failed (logged: the
    design it would replace stands).

    Parameters
    ----------
    base : DevelopmentEvaluation
        The design varied (its index and other fields kept).
    values : mapping
        The variant's prescriptions [file units, :data:`~contact.optimize.
        development_targets.VARIABLES`].
    stage : str
        The check step recorded as the variant's stage.
    targets : DevelopmentTargets
        The development's targets.
    setup : mapping
        The development's state (``torques`` [N·m], ``centre_v`` [1], the memos).
    teeth : KeptTeeth
        The kept pinion teeth.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).
    pinion_key : tuple, optional
        The kept pinion tooth's key; default the design's bearing.
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    case : Case, optional
        ``placed(values)`` already made.

    Returns
    -------
    DevelopmentEvaluation or None
        The variant, checked at :data:`CHECK_LTCA`; None where it failed.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    """
    try:
        case, ms, grid = checked_analysis(
            setup, placed, values, teeth,
            bearing_key(values) if pinion_key is None else pinion_key, flank, case=case)
    except Exception as exc:  # reported, never fatal
        raise_if_interrupted(exc)
        log.info("development %s check of %s failed: %s", stage, dict(values), exc)
        return None
    return scored(base, ms, grid, targets, setup["centre_v"], values=values, case=case,
                  checked=True, stage=stage)


def said_variant(base: DevelopmentEvaluation, values: Mapping[str, float], stage: str,
                 label: str, targets: DevelopmentTargets, setup: Mapping[str, Any],
                 teeth: KeptTeeth, say: Callable[[str], None],
                 placed: Callable[[Mapping[str, float]], Case], *,
                 flank: str = "drive", key_prefix: tuple | None = None,
                 case: Case | None = None) -> DevelopmentEvaluation | None:
    """A check step's design: :func:`checked_variant` of ``base`` with ``values`` on
    ``flank`` (``case``: its case already placed), and where it was analysed one line
    said, ``design <n> <label>, at the default sampling: <its metrics>`` (``<flank>
    design`` off the drive flank). ``key_prefix``: where given, the kept pinion tooth's
    key is it followed by the design's bearing (:func:`bearing_key`; default the bearing
    alone). None where the synthesis or the analysis failed.

    Parameters
    ----------
    base, values, stage, targets, setup, teeth, placed, flank, case
        As :func:`checked_variant`'s (``values`` [file units]).
    label : str
        The variant's change in words, for the line said.
    say : callable str → None
        Where the line goes.
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing.

    Returns
    -------
    DevelopmentEvaluation or None
        The variant, checked at :data:`CHECK_LTCA`; None where it failed.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    """
    key = None if key_prefix is None else (*key_prefix, *bearing_key(values))
    e = checked_variant(base, values, stage, targets, setup, teeth, placed,
                        pinion_key=key, flank=flank, case=case)
    if e is not None:
        what = "design" if flank == "drive" else f"{flank} design"
        say(f"  {what} {base.index + 1} {label}, at the default sampling: "
            + evaluation_line(e, targets.max_evaluations).split(": ", 2)[-1])
    return e
