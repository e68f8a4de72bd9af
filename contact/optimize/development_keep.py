"""The check steps' one keep rule: why a check step's design does not replace the design
kept so far (:func:`kept_why`: better, no met target lost, tolerant), and its parts —
:func:`ranks_better`, the targets a design gives up (:func:`lost_targets`,
:func:`lost_but_length`) and the coast flank's pressure bound (:func:`pressure_raised`).
Split out of :mod:`contact.optimize.development_check` (issue 71, Deliver 5), which
re-exports every public name; the bodies moved unchanged (the helpers they share
imported under the private names they call).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_tolerance import known_missed as _known_missed
from contact.optimize.development_tolerance import (
    less_intolerant_variant as _less_intolerant_variant,
)
from contact.optimize.development_tolerance import tolerant_variant as _tolerant_variant
from contact.optimize.development_variant import check_rank as _check_rank
from contact.optimize.development_variant import lte_fails as _lte_fails


def lost_targets(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
    """The targets ``best`` met at its check and its variant ``e`` misses, sorted.

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept so far and its variant, both scored (their ``full``).

    Returns
    -------
    list of str
        The targets (the shortfalls' keys: ``"lte"``, ``"length"``, ``"centre_v"`` …)
        whose shortfall is positive for ``e`` and zero for ``best``.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    """
    was = {k for k, v in best.full[1].items() if v > 0.0}
    return sorted(k for k, v in e.full[1].items() if v > 0.0 and k not in was)


def lost_but_length(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
    """:func:`lost_targets`, the pattern length apart (a check step may buy the LTE with
    the length alone).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept so far and its variant, both scored.

    Returns
    -------
    list of str
        The targets ``best`` met that ``e`` misses, ``"length"`` left out.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    """
    return [k for k in lost_targets(best, e) if k != "length"]


def pressure_raised(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                    targets: DevelopmentTargets, *, index: int = -1) -> str:
    """``"pressure (<p> MPa above <bound>)"`` where ``e``'s flank peak pressure at the
    design torque exceeds both ``best``'s and the targets' ``max_flank_pressure``, else
    empty (:func:`_coast_kept`, :func:`_coast_centre_kept`).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept so far and its variant, both checked (their metrics'
        ``pressure_max_flank`` [MPa] per torque of the check).
    targets : DevelopmentTargets
        Its ``max_flank_pressure`` [MPa] or None.
    index : int, optional
        The torque of the check compared (default -1, the design torque; 0 the light
        torque, where the text says "at the light torque").

    Returns
    -------
    str
        Empty where the pressure is no higher than ``best``'s or within the bound.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing").
    """
    p_new = float(e.metrics["pressure_max_flank"][index])
    p_old = float(best.metrics["pressure_max_flank"][index])
    bound = (float(targets.max_flank_pressure) if targets.max_flank_pressure is not None
             else -math.inf)
    if not p_new <= max(p_old, bound):
        where = "" if index in (-1, len(e.metrics["pressure_max_flank"]) - 1) else (
            " at the light torque" if index == 0 else f" at torque {index}")
        return f"pressure ({p_new:.0f} MPa above {max(p_old, bound):.0f}{where})"
    return ""


def ranks_better(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> bool:
    """Whether a checked design ``e`` ranks before ``best`` (:func:`~contact.optimize.
    development_variant.check_rank`).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept so far and its variant, both scored.

    Returns
    -------
    bool
        ``best``'s checked LTE fails ``ltca run``'s verdict and ``e``'s does not, or
        both or neither do and ``e`` meets every target and ``best`` does not, or as many
        and a lower objective.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing",
    "A verdict the design does not deserve"); the coast flank's development ranks its
    designs by it too (:mod:`contact.optimize.development_coast_flank`).
    """
    return _check_rank(e) < _check_rank(best)


#: the targets a design that passes ``ltca run``'s verdict may give up to replace one whose
#: LTE the verdict FAILs (:func:`verdict_lost`): the light-load pattern's length and
#: centre (and the mounting tolerance, not a shortfall); the durability targets (edge and
#: plastic shares, pressure, LTE spread) and the pattern's clearances are kept
SOFT_TARGETS = ("length", "centre_u", "centre_v")


def verdict_lost(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                 lost: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]]
                 | None = lost_targets) -> list[str] | None:
    """The keep rule between a design whose checked LTE ``ltca run``'s verdict FAILs and
    one whose LTE it passes (:func:`~contact.optimize.development_variant.lte_fails`).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept so far and its variant, both scored.
    lost : callable (best, e) → list of str, optional
        The targets ``best`` met that ``e`` misses (default :func:`lost_targets`); None:
        none asked.

    Returns
    -------
    list of str or None
        None where both or neither fail the verdict on their LTE (the step's own rule
        applies); ``["lte"]`` where ``e`` fails and ``best`` does not (never kept);
        where ``best`` fails and ``e`` does not, the targets ``best`` met that ``e``
        misses beyond :data:`SOFT_TARGETS` (empty: ``e`` replaces ``best`` whatever its
        ``objective`` and its tolerance).

    Notes
    -----
    Source: ``ltca run``'s verdict (:mod:`contact.study.verdicts`, the ``lte`` FAIL above
    2 × 60 µrad); issue 71, the 8x35 k_d 2.16 (docs/synthesis.md, "A verdict the design
    does not deserve").
    """
    if _lte_fails(e) == _lte_fails(best):
        return None
    if _lte_fails(e):
        return ["lte"]
    gone = lost(best, e) if lost is not None else []
    return [k for k in gone if k not in SOFT_TARGETS]


def kept_why(best: DevelopmentEvaluation, e: DevelopmentEvaluation | None,
             targets: DevelopmentTargets, setup: Mapping[str, Any],
             teeth: KeptTeeth | None, say: Callable[[str], None], what: str = "", *,
             better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool]
             = ranks_better,
             lost: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]]
             | None = None,
             lost_first: bool = False, tolerant: bool = True) -> str:
    """The check steps' one keep rule: why a check step's design ``e`` does not replace
    ``best``, empty where it does.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design kept so far (checked at :data:`CHECK_LTCA`).
    e : DevelopmentEvaluation or None
        The step's design (:func:`_said_variant`); None (its synthesis or analysis failed)
        is never kept.
    targets, setup, teeth, say
        As the check steps'; ``say`` gets the "not kept" lines.
    what : str
        The step's change in words, for the "not kept: <what> misses ..." line.
    better : callable (best, e) → bool, optional
        Whether ``e`` is better (default: it ranks before ``best``, :func:`_check_rank`:
        every target met first, then the least objective; the near-miss step counts the
        targets met, :func:`_met_count`).
    lost : callable (best, e) → list of str, optional
        The targets ``best`` met that ``e`` misses (:func:`_lost_targets`, or
        :func:`_lost_but_length` where the LTE may be bought with the pattern's length);
        None: not asked.
    lost_first : bool, optional
        Ask ``lost`` before ``better`` (the near-miss step says a lost target whether or
        not the design is better); default False.
    tolerant : bool, optional
        Ask last whether ``e`` is tolerant (:func:`_tolerant_variant`: the mounting
        excursions, up to four coarse analyses, so asked only where every other rule
        keeps it); where it is not, it still replaces a ``best`` that is not tolerant
        either and misses no more at any excursion (:func:`~contact.optimize.
        development_tolerance.less_intolerant_variant`: the worst toe, heel, edge and
        plastic shortfalls, issue 71, branch tol89); default True.

    Returns
    -------
    str
        Empty where ``e`` replaces ``best``; else ``"it could not be analysed"``, ``"its
        LTE fails the verdict"``, ``"it scores no better"``, ``"it misses <targets>"`` or
        ``"not tolerant at dE/dP +/-0.05 mm"``.

    Notes
    -----
    One rule for :func:`checked_ellipse`, :func:`checked_long`,
    :func:`checked_relief_lte`, :func:`checked_crowning_lte`, :func:`checked_te_back`,
    :func:`checked_near_miss` and :func:`checked_path`, each of which wrote its own
    "better, no met target lost, tolerant" loop before (issue 71); their order of
    asking is kept, so the lines said and the analyses run are theirs. Asked first
    (:func:`verdict_lost`): a design whose checked LTE ``ltca run``'s verdict FAILs
    (above 2 × 60 µrad) never replaces one it does not fail, and one it does not fail
    replaces one it fails where it gives up no target ``lost`` names but the pattern's
    length and centre (:data:`SOFT_TARGETS`), its objective and tolerance not asked.
    """
    if e is None:
        return "it could not be analysed"
    # a FAIL-level LTE (ltca run's verdict, :func:`~contact.optimize.development_variant.
    # lte_fails`) ranks below any design the verdict does not fail, whichever ``better``
    # the step asks: such a design is never kept over one that passes, and one that
    # passes replaces it where it loses no target but the soft ones (issue 71: the 8x35
    # k_d 2.16 refused 57 / 80 urad on its centre u and 24 / 21 urad, not tolerant, and
    # ended on 605 / 600 urad)
    fails = verdict_lost(best, e, lost)
    if fails is not None:
        if _lte_fails(e):
            return "its LTE fails the verdict"
        if fails:
            say(f"  not kept: {what} misses {', '.join(fails)}")
            return f"it misses {', '.join(fails)}"
        return ""

    def missed() -> str:
        gone = lost(best, e) if lost is not None else []
        if gone:
            say(f"  not kept: {what} misses {', '.join(gone)}")
            return f"it misses {', '.join(gone)}"
        return ""

    if lost_first and (why := missed()):
        return why
    if not better(best, e):
        return "it scores no better"
    if not lost_first and (why := missed()):
        return why
    if (tolerant and not _tolerant_variant(e, targets, setup, teeth, say,
                                           first=_known_missed(best, targets, setup, teeth))
            and not _less_intolerant_variant(best, e, targets, setup, teeth, say)):
        return "not tolerant at dE/dP +/-0.05 mm"
    return ""
