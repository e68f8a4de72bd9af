"""A coarse "all targets met" stop confirmed at the default sampling before it ends the
search (:func:`confirmer`).

The coarse search (:data:`~contact.optimize.development_evaluate.COARSE_LTCA`) analyses a
design's case without its tip planes (step 8 of :func:`geometry.synthesis.case_synthesis.
synthesize`, left out for its 1-2 s of CPU: the flanks the same, the pinion's fillets and
root lines not) and at 8 roll positions of one mesh cycle; it ends the search at the first
design meeting every target (:class:`~contact.optimize.development_evaluate.StageStop`).
Where the plastic and edge loads sit at the gear's tip edge, which meets the pinion next to
its root line, neither reads them as the check does (the case written, ``ltca run``'s 2 × 20
rolls). Measured on Round 41's FM spiral bevel 10x51 (benchmarks/data/unseen_designs/
spiral_bevel_10x51_m0.toml, 77.7 / 518.1 N·m; issue 71, branch plastic102), the plastic
share at the design torque of its designs 5 and 6, the search's case → the case as written:

=========================  =================  =================
sampling                   design 5           design 6
=========================  =================  =================
coarse, 1 × 8 rolls        0.0 % → 0.30 %     0.0 % → 1.03 %
1 × 20 rolls, 12 segments  0.0 % → 1.38 %     0.0 % → 1.03 %
default, 2 × 20, 24 seg.   0.0 % → 1.38 %     0.0 % → 1.03 %
=========================  =================  =================

(gear-tip edge peak 4167 → 5262 MPa, the shakedown limit, on design 5): the tip planes
make most of it, the roll positions the rest; the segments per curve none. Design 6 had
stopped the search at 6 of 36 designs and no later step removed the plastic.

So a coarse "all met" stops the search only where the check at the default sampling
(:func:`~contact.optimize.development_variant.checked_analysis`, the very analysis
:func:`~contact.optimize.development_check.checked_best` reads back from its memo) does
not refute it on the plastic or the edge share; a refuted design scores its checked
objective (the search walks away from it) and the search goes on, at most
:data:`REFUTED_STOPS` times (then a coarse "all met" stops it as before).
"""

from __future__ import annotations

import dataclasses
import logging
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_check import cut_variant
from contact.optimize.development_evaluate import (
    MEMO_DECIMALS,
    KeptTeeth,
    bearing_key,
    evaluation_line,
)
from contact.optimize.development_result import DevelopmentEvaluation, scored
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import checked_analysis
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted

log = logging.getLogger("contact.optimize.development")

__all__ = ["REFUTED_KEYS", "REFUTED_STOPS", "confirmer", "refuted_share"]

#: the targets on which a check at the default sampling refutes a coarse "all met" stop:
#: the loads at the flank's edges, which the coarse search's case (no tip planes) and its
#: 8 roll positions miss (module docstring). A pattern a node off (centre, length) is the
#: check's steps' to repair, as before (:func:`~contact.optimize.development_check.
#: checked_best`'s re-centring)
REFUTED_KEYS = ("plastic", "edge")

#: most coarse "all met" stops refuted per search: each costs a placed synthesis (step 8)
#: and an analysis at the default sampling, and the search goes on (the 10x51: one
#: refutation, 13 designs in place of 6, 36 s of CPU in place of 24 for the whole
#: synthesis); past them a coarse "all met" stops the search as before
REFUTED_STOPS = 3


def confirmer(targets: DevelopmentTargets, setup: Mapping[str, Any], teeth: KeptTeeth,
              say: Callable[[str], None],
              placed: Callable[[Mapping[str, float]], Case], *, side: str = "drive",
              n_max: int | None = None, key_prefix: tuple = (),
              said_lines: set[int] | None = None
              ) -> Callable[[DevelopmentEvaluation], DevelopmentEvaluation | None]:
    """The confirmation of a coarse "all targets met" stop, for
    :func:`~contact.optimize.development_evaluate.evaluator`'s ``confirm``.

    Parameters
    ----------
    targets : DevelopmentTargets
    setup : mapping
        The development's set-up (``torques`` [N·m], ``centre_v`` [1]; its check memo).
    teeth : KeptTeeth
        The shell teeth kept (the pinion's under the design's bearing).
    say : callable
        Called with the check's line.
    placed : callable values → Case
        A design's case as written (its tip planes placed): the check's own ``placed``,
        so that :func:`~contact.optimize.development_check.checked_best` reads the
        analysis back from the memo.
    side : str
        The flank (``"drive"`` or ``"coast"``).
    n_max : int, optional
        The budget the lines name (default ``targets.max_evaluations``).
    key_prefix : tuple, optional
        The kept pinion teeth's key before the design's bearing (:class:`KeptTeeth`): the
        coast search's (the drive bearing's key and ``"coast"``), as its check's
        (:func:`~contact.optimize.development_check.checked_best`'s ``key_prefix``), so
        that the check reads the confirmation back from its memo; default () (the drive's).
    said_lines : set of int, optional
        Filled with the index of each design whose check line this confirmation printed
        (given to :func:`~contact.optimize.development_check.checked_best` as its
        ``said_lines``, so that the check does not print the same line again).

    Returns
    -------
    callable DevelopmentEvaluation → DevelopmentEvaluation or None
        Given a design the coarse search scored "all targets met": None where the stop
        stands (the check confirms it, refutes it on none of :data:`REFUTED_KEYS`, could
        not analyse it, or :data:`REFUTED_STOPS` stops were refuted already), else the
        design refuted: ``met`` False, its ``objective`` and ``full`` score the check's
        (its metrics the coarse search's record).
    """
    n_max = targets.max_evaluations if n_max is None else n_max
    what = "design" if side == "drive" else f"{side} design"
    refuted: list[int] = []
    said: dict[tuple, DevelopmentEvaluation | None] = {}  # a design asked again: the answer

    def confirm(e: DevelopmentEvaluation) -> DevelopmentEvaluation | None:
        key = tuple(sorted((k, round(float(v), MEMO_DECIMALS)) for k, v in e.values.items()))
        if key in said:
            return said[key]
        if len(refuted) >= REFUTED_STOPS:
            return None
        said[key] = answer = _confirmed(e)
        return answer

    def _confirmed(e: DevelopmentEvaluation) -> DevelopmentEvaluation | None:
        try:
            case, values = cut_variant(placed, e.values)
            if values != e.values:  # the check analyses another design: not this one's
                return None
            _, ms, grid = checked_analysis(setup, placed, values, teeth,
                                           (*key_prefix, *bearing_key(values)), side,
                                           case=case)
        except Exception as exc:  # the check's own failure is the check's to say
            raise_if_interrupted(exc)
            log.info("development: confirmation of %s %d failed: %s", what, e.index + 1, exc)
            return None
        checked = scored(e, ms, grid, targets, setup["centre_v"], checked=True)
        short = checked.full[1]
        missed = [k for k in REFUTED_KEYS if short.get(k, 0.0) > 0.0]
        line = evaluation_line(checked, n_max).split(": ", 2)[-1]
        if said_lines is not None:
            said_lines.add(e.index)
        if not missed:
            say(f"  check of {what} {e.index + 1} at the default sampling: {line}; the coarse "
                "search's stop confirmed")
            return None
        refuted.append(e.index)
        shares = ", ".join(f"{k} {100.0 * refuted_share(checked.metrics, k):.1f} %" for k in missed)
        say(f"  check of {what} {e.index + 1} at the default sampling: {line}; its coarse "
            f"'all targets met' refuted ({shares} as written: the coarse search's case has no "
            f"tip planes and 8 rolls): the search goes on "
            f"({len(refuted)} of at most {REFUTED_STOPS})")
        return dataclasses.replace(e, objective=checked.full[0], met=False,
                                   shortfalls=checked.full[1], full=checked.full)

    return confirm


def refuted_share(metrics: Mapping[str, Any], key: str) -> float:
    """The share [1] a refuted target reads: the plastic share's worst torque, the edge
    share's at the design torque (as :func:`~contact.optimize.development_targets.
    development_score` scores them)."""
    if key == "plastic":
        return float(np.max(metrics["plastic_share"]))
    return float(np.asarray(metrics["edge_load_share"])[1])
