"""The drive flank developed again at a design torque cut well below the torque its search
ran at, where it misses its plastic or edge target there (:func:`redeveloped_drive_at_cut`;
issue 71, "no plastic segment at any torque"; branch coast104).

The drive's search (:func:`~contact.optimize.development_stages.search_flank`) scores its
designs at the rated torque (the ISO 10300 capacity where the basic file gives no design
torque); the flank's static capacity, its FE root stress or its local pitting capacity may
then cut the design torque (:func:`~contact.optimize.development_check.static_capacity`,
:func:`~contact.optimize.development_check.checked_root_capacity`). The check's steps run
again at the cut torques, but they move the pattern and the LTE, not the relief the search
chose against the edges: a relief that keeps the edges elastic at the rated torque is not
the search's choice at 0.65 of it. The coast flank has the same rule at its own design
torque (:func:`~contact.optimize.development_coast_flank.coast_at_its_torque`, below
:data:`~contact.optimize.development_coast_flank.COAST_REDEVELOP` of the torque it was
developed at, where it misses a target there); this is its mirror on the drive, asked only
of the targets the coarse search misreads (:data:`~contact.optimize.development_confirm.
REFUTED_KEYS`, the plastic and the edge share): a drive that meets them at its cut torque
is stated with its numbers and not developed again (the design torque only falls with a
cut, and the loads at the edges with it, as a rule).
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

from contact.optimize.development_coast_flank import COAST_REDEVELOP, redeveloped_at
from contact.optimize.development_confirm import REFUTED_KEYS, refuted_share
from contact.optimize.development_keep import ranks_better
from contact.optimize.development_result import DevelopmentEvaluation, DevelopmentResult
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number

log = logging.getLogger("contact.optimize.development")

__all__ = ["DRIVE_REDEVELOP", "drive_missed_at_cut", "redeveloped_drive_at_cut"]

#: the design torque, as a fraction of the torque the drive's search ran at, below which
#: :func:`redeveloped_drive_at_cut` asks the drive's plastic and edge targets again [1]:
#: the coast flank's (:data:`~contact.optimize.development_coast_flank.COAST_REDEVELOP`)
DRIVE_REDEVELOP = COAST_REDEVELOP


def drive_missed_at_cut(best: DevelopmentEvaluation) -> list[str]:
    """The targets of :data:`~contact.optimize.development_confirm.REFUTED_KEYS` (plastic,
    edge) the drive design ``best`` misses as scored (its ``full`` shortfalls at the
    development's torques); empty where it meets them or carries no score.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The drive design, scored at the cut torques (its ``full``: objective, shortfalls,
        every target met).

    Returns
    -------
    list of str
        The keys missed, in :data:`REFUTED_KEYS`' order.
    """
    if best.full is None:
        return []
    return [k for k in REFUTED_KEYS if float(best.full[1].get(k, 0.0)) > 0.0]


def _shares_text(metrics: Mapping[str, Any]) -> str:
    """"plastic 0.3 %, edge 1.1 %" of a design's metrics (:func:`refuted_share`), NaN-safe."""
    parts = []
    for k in REFUTED_KEYS:
        try:
            parts.append(f"{k} {100.0 * refuted_share(metrics, k):.1f} %")
        except (KeyError, IndexError, ValueError):
            continue
    return ", ".join(parts)


def redeveloped_drive_at_cut(best: DevelopmentEvaluation, setup: Mapping[str, Any],
                             searched_at: float, say: Callable[[str], None],
                             rerun: Callable[..., DevelopmentResult],
                             holds: Callable[[Any, Any], tuple[bool, str]]
                             ) -> DevelopmentResult | None:
    """The drive developed again at its cut design torque where that torque is below
    :data:`DRIVE_REDEVELOP` × ``searched_at`` and the drive design there misses its plastic
    or edge target (:func:`drive_missed_at_cut`); kept where its drive ranks before
    ``best`` (:func:`~contact.optimize.development_keep.ranks_better`: a checked LTE
    ``ltca run``'s verdict FAILs last, then every target met, then the objective) and its
    own capacity holds at its design torque (``holds``).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The drive design written, scored at the cut torques ``setup["torques"]`` [N·m].
    setup : mapping
        The development's state: ``torques`` [light, design] [N·m] (the cut ones),
        ``source`` (the cut's phrase).
    searched_at : float
        [N·m] The design torque the drive's search ran at.
    say : callable (str) → None
        Where the lines go.
    rerun : callable (float, **kw) → DevelopmentResult
        The development of the same basic data at a given design torque [N·m]
        (``development._at_given_torque`` with the development's arguments; its
        ``torque_name`` the design torque's source).
    holds : callable (case, torques) → (bool, str)
        Whether a written case holds its capacity at its design torque, and its text
        (:func:`~contact.optimize.development_root.capacity_holds` with ``say``).

    Returns
    -------
    DevelopmentResult or None
        The re-development (its torque source the cut's, then the reason it was developed
        again); None where the torque was not cut below the fraction, the drive meets its
        plastic and edge targets there (said, with the shares), the re-development fails
        (said), ranks no better or does not hold its capacity (said).

    Raises
    ------
    Nothing the re-development raises but an interrupt.

    Notes
    -----
    Source: issue 71 ("no plastic segment at any torque"); the coast flank's rule
    (:func:`~contact.optimize.development_coast_flank.coast_at_its_torque`). CPU: one more
    development (its drive search, checks, coast flank and FE build), paid only by a drive
    cut below 0.9 of its search's torque that carries plastic or edge load there.
    """
    torque = float(setup["torques"][1])
    if not redeveloped_at(torque, searched_at):
        return None
    at = (f"at its design torque {plain_number(torque)} N m (its search ran at "
          f"{plain_number(searched_at)} N m)")
    missed = drive_missed_at_cut(best)
    shares = _shares_text(best.metrics)
    if not missed:
        say(f"development: drive flank {at}: {shares or 'plastic and edge'} there, within "
            "their targets; not developed again")
        return None
    say(f"development: drive flank {at}: {shares} there, missing {', '.join(missed)}; "
        "developed again at that torque")
    source = str(setup.get("source", ""))
    try:
        again = rerun(torque, torque_name=source)
    except Exception as exc:  # the first design stands; its failure said
        raise_if_interrupted(exc)
        log.info("development: drive re-development at %s N m failed: %s", torque, exc)
        say(f"development: the drive developed again at {plain_number(torque)} N m failed "
            f"({type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}); the "
            "first design kept")
        return None
    new = again.best
    if new is None or new.full is None or best.full is None or not ranks_better(best, new):
        objective = new.full[0] if new is not None and new.full is not None else math.nan
        say(f"development: drive flank at {plain_number(torque)} N m: the first design kept "
            f"(objective {best.full[0] if best.full else math.nan:.3g}; developed there "
            f"{objective:.3g}, {_shares_text(new.metrics) if new is not None else ''})")
        return None
    ok, text = holds(again.case, again.torque)
    if not ok:
        say(f"development: the drive developed again at {plain_number(torque)} N m: {text} "
            "there, so not kept; the first design kept")
        return None
    say(f"development: drive flank at {plain_number(torque)} N m: the design developed there "
        f"kept (objective {new.full[0]:.3g}, {_shares_text(new.metrics)}; the first "
        f"{best.full[0]:.3g}); its capacity holds ({text})")
    return dataclasses.replace(
        again, torque_source=f"{source}; the drive developed again at it (the design "
        f"developed at {plain_number(searched_at)} N m missed {', '.join(missed)} there)")
