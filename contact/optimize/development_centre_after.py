"""The check's steps again on the drive design the edge-peak step left (issue 71,
"``ltca synthesize`` meets every development target on the drive flank", branch len99).

The check's steps (:func:`~contact.optimize.development_check.check_steps`) run before the
edge-peak step (:func:`~contact.optimize.development_edge_peak.checked_edge_peak`); the
relief that step gives an edge changes what those steps can do: a design refused for its
tolerance before may be tolerant on the deeper relief, and a design that missed the edge
target (outside the near-miss step's margin) becomes a near miss on its pattern.

Public names
------------
AFTER_TARGETS, after_runs_on, checked_after_edge_peak
"""

from __future__ import annotations

from collections.abc import Callable

from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets

__all__ = ["AFTER_TARGETS", "after_runs_on", "checked_after_edge_peak"]

#: the targets the design after the edge-peak step may miss for the check's steps to run
#: again on it: the light-load pattern's length and height and the LTE (those steps'
#: own targets); a design missing any other (an edge, a clearance, plastic) is left as
#: the edge-peak step wrote it
AFTER_TARGETS = frozenset({"length", "centre_v", "lte"})


def after_runs_on(before: DevelopmentEvaluation, after: DevelopmentEvaluation,
                  targets: DevelopmentTargets) -> bool:
    """Whether the check's steps run again on ``after``: the edge-peak step changed the
    design (``after`` is not ``before``), ``after`` was checked at ``ltca run``'s sampling
    and misses a target, every one it misses among :data:`AFTER_TARGETS`.

    Parameters
    ----------
    before, after : DevelopmentEvaluation
        The drive design before and after the edge-peak step.
    targets : DevelopmentTargets
        The development's targets (unused but for the signature every gate has).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.
    """
    del targets
    if after is before or not after.checked_full or bool(after.full[2]):
        return False
    missed = {k for k, v in after.full[1].items() if v > 0.0}
    return bool(missed) and missed <= AFTER_TARGETS


def checked_after_edge_peak(before: DevelopmentEvaluation, after: DevelopmentEvaluation,
                            targets: DevelopmentTargets, say: Callable[[str], None],
                            steps: Callable[[DevelopmentEvaluation], DevelopmentEvaluation]
                            ) -> DevelopmentEvaluation:
    """The check's steps (``steps``) again on the design the edge-peak step wrote, where
    :func:`after_runs_on`; their design kept where it ranks before it (every target met
    first, then the least objective: :func:`~contact.optimize.development_variant.
    check_rank`), else ``after``.

    Parameters
    ----------
    before, after : DevelopmentEvaluation
        The drive design before and after the edge-peak step.
    targets : DevelopmentTargets
        The development's targets.
    say : callable str → None
        Gets the step's line.
    steps : callable DevelopmentEvaluation → DevelopmentEvaluation
        The check's steps (:func:`~contact.optimize.development_check.check_steps` with
        the development's state bound).

    Returns
    -------
    DevelopmentEvaluation

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (the steps log it).
    """
    if not after_runs_on(before, after, targets):
        return after
    missed = ", ".join(k for k, v in after.full[1].items() if v > 0.0)
    say(f"  the check's steps again on the design the edge-peak step wrote (it misses "
        f"{missed})")
    again = steps(after)
    if again is after:
        return after
    if not bool(again.full[2]):
        say(f"  not kept: the check's steps again end on a design that misses "
            f"{', '.join(k for k, v in again.full[1].items() if v > 0.0)} (kept only "
            "where every target is met)")
        return after
    return again
