"""What the developments of one basic design share within one ``ltca synthesize``: the
synthesis memo and the kept teeth with their analyses (issue 71, "a new design … within
2 min CPU").

``gear_process = "auto"`` may develop one basic design twice: the Formate gear's
development stops where its torque cut is foreseen
(:class:`~contact.optimize.development_process.CutForeseen`), and where the generated
gear's design fails too, the Formate gear is developed again in full
(:func:`~contact.optimize.development_process.with_generated_gear`). The second run
repeats the first one's drive search, its check and the check's steps design for design
(the same basic data, the same targets, the same deterministic search) before it goes past
the stop: on the FM hypoid 9x31 at Σ 75° of benchmarks/data/unseen_designs, 15 % of its
``ltca synthesize`` (≈ 40–70 s of CPU; docs/performance.md, "Two new designs over issue
71's 2 min").

:class:`SharedDevelopments` hands each development of :func:`contact.optimize.
development.develop` the synthesis memo (:func:`geometry.synthesis.case_synthesis.
synthesize`'s ``memo``) and the :class:`~contact.optimize.development_evaluate.KeptTeeth`
of its basic design — the same objects for equal basic designs, new ones for any other
(the generated gear's, another design torque's) — so that a repeated synthesis, tooth
model or analysis is read back instead of computed again: the n-th analysis of the same
inputs in the second run is the first run's n-th (:meth:`~contact.optimize.
development_evaluate.KeptTeeth.analysed`: keyed by the analysed case to the last bit, its
torques, options, pinion-tooth key and flank), so that the repeated run's numbers are the
first run's; within one run every analysis is computed, as before.

Public names
------------
SharedDevelopments   the memo and kept teeth of each basic design developed
kept_for             a development's memo and kept teeth (shared or new)
log_reused           the log line of the analyses a development read back
"""

from __future__ import annotations

import dataclasses
import logging
from typing import Any

from contact.optimize.development_evaluate import KeptTeeth
from geometry.synthesis.case_synthesis import memo_at_torque, options_at_torque

__all__ = ["SharedDevelopments", "kept_for", "log_reused"]

log = logging.getLogger("contact.optimize.development")


class SharedDevelopments:
    """The synthesis memo and kept teeth of each basic design developed in one command
    (module docstring). One instance per ``ltca synthesize`` (or API call of
    :func:`contact.optimize.development.develop`); not shared between processes.

    Attributes
    ----------
    developments : int
        How many developments asked for their memo and teeth.
    repeated : int
        How many of them were of a basic design developed before (its memo and teeth
        handed over again).
    seeded : int
        How many of them were of a basic design developed before at another design torque
        only (a new memo holding that first development's syntheses but its tip planes,
        :func:`~geometry.synthesis.case_synthesis.memo_at_torque`; new kept teeth).
    """

    def __init__(self) -> None:
        self._kept: dict[str, tuple[dict, KeptTeeth]] = {}
        # the memo of the first development of each basic design whatever its design torque
        self._first: dict[str, dict] = {}
        self.developments = 0
        self.repeated = 0
        self.seeded = 0

    def kept(self, basic: Any) -> tuple[dict, KeptTeeth]:
        """The synthesis memo and kept teeth of ``basic``'s developments: those of an equal
        basic design developed before (its ``repr``, every field and float to the last
        bit), else new ones, kept for the next.

        Parameters
        ----------
        basic : geometry.synthesis.basic_design.BasicDesign
            The basic design as the development synthesises it (its FE level and options
            set).

        Returns
        -------
        (dict, KeptTeeth)
            The memo of :func:`geometry.synthesis.case_synthesis.synthesize` and the kept
            teeth (:class:`~contact.optimize.development_evaluate.KeptTeeth`).
        """
        key = repr(basic)
        self.developments += 1
        if key in self._kept:
            self.repeated += 1
        else:
            # the same basic data developed before at another design torque (the drive
            # developed again in its LTE window): its syntheses' steps 1-7 read back, not
            # its tip planes (case_synthesis.memo_at_torque)
            free = _torque_free(basic)
            first = self._first.get(free)
            memo = {} if first is None else memo_at_torque(first, basic.options.design_torque)
            self.seeded += first is not None
            self._first.setdefault(free, memo)
            self._kept[key] = (memo, KeptTeeth())
        memo, teeth = self._kept[key]
        teeth.begin_development()  # its analyses counted anew: the n-th reads the n-th
        return memo, teeth


def _torque_free(basic: Any) -> str:
    """``repr`` of ``basic`` with no design torque of its own (every other field and float
    as it is: :func:`~geometry.synthesis.case_synthesis.options_at_torque`)."""
    return repr(dataclasses.replace(basic, options=options_at_torque(basic.options, None)))


def kept_for(shared: SharedDevelopments | None, basic: Any) -> tuple[dict, KeptTeeth]:
    """A development's synthesis memo and kept teeth: ``shared``'s for ``basic``
    (:meth:`SharedDevelopments.kept`), new ones where ``shared`` is None.

    Parameters
    ----------
    shared : SharedDevelopments or None
    basic : geometry.synthesis.basic_design.BasicDesign

    Returns
    -------
    (dict, KeptTeeth)
    """
    return shared.kept(basic) if shared is not None else ({}, KeptTeeth())


def log_reused(teeth: KeptTeeth, before: int) -> None:
    """Log (INFO) how many analyses a development read back: ``teeth.analyses_reused``
    above ``before`` (its count when the development began); nothing where none."""
    if teeth.analyses_reused > before:
        log.info("development: %d analyses read back (the same inputs analysed before)",
                 teeth.analyses_reused - before)
