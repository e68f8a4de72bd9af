"""The design torque raised back after a capacity cut no further than where the drive
LTE keeps the verdict's limit (issue 71: "LTE p-p ≤ 60 µrad at every torque").

``contact.optimize.development._regained`` raises the design torque back towards the
torque before a capacity cut where the bearing the steps developed at the cut torque
carries more (root stress and local pitting safety, no drive target lost, the mounting
tolerance kept: :mod:`~contact.optimize.development_regain`). The LTE over ``ltca run``'s
torque range was not among its judgements: on the FM spiral bevel 16×16 at Σ 60° of
benchmarks/data/unseen_designs (ε_vβ 0.93) the bearing developed at the local pitting
cut's 278.3 N·m keeps 53 / 51 µrad there and was raised back to 390.7 N·m, where it reads
54 / 95 µrad (docs/synthesis.md, "The FM 16×16 at Σ 60°'s design torque raised back past
its LTE window"). The LTE window rule (:mod:`~contact.optimize.development_written_lte`)
runs before the cut; after it, ``development._lte_after_cut`` runs it again at the cut (or
raised) torques (branch diag92: the 13×17 at Σ 50° remedied to b2 37 mm, 44/62 µrad at the
local pitting cut's 333.4 N·m, written at 267.5 N·m, 49/60 µrad).

:func:`lte_kept_raise` treats the LTE limit as one more thing the raise must not lose:
where the range at the cut torques keeps it and the range at the raised torques does not,
the raise ends where the written bearing keeps it at every torque
(:func:`~contact.optimize.development_written_lte.written_lte_capacity` on the raised
design: the crossing, its own light torque and range analysed), at the cut torque where
no torque above it does.

Public names
------------
LteRaise, lte_kept_raise
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from contact.optimize.development_range_lte import development_lte_limit, range_curve, range_lte
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_written_lte import written_lte_capacity

__all__ = ["LteRaise", "lte_kept_raise"]


@dataclass(frozen=True)
class LteRaise:
    """What :func:`lte_kept_raise` found.

    Attributes
    ----------
    torque : float — [N·m]
        The design torque the raise may reach: the raised one where the LTE limit is not
        lost there (or was not met at the cut torque), the torque up to which the written
        bearing keeps it at every torque, or the cut torque where none above it does.
    why : str
        Where ``torque`` is below the raised one: the LTE at the cut and at the raised
        torques, in words (empty otherwise).
    """

    torque: float
    why: str = ""


def lte_kept_raise(cut: DevelopmentEvaluation, raised: DevelopmentEvaluation,
                   targets: DevelopmentTargets, setup: dict[str, Any], teeth: Any,
                   raised_torques: list[float], say: Callable[[str], None]) -> LteRaise:
    """The highest design torque up to the raised one at which the drive design developed
    at a capacity cut keeps the verdict's LTE limit at every torque ``ltca run`` judges,
    where it keeps it at the cut torque.

    Parameters
    ----------
    cut : DevelopmentEvaluation
        The drive design at the cut torques ``setup["torques"]`` (checked: its ``case``
        and ``metrics["lte_peak_to_peak"]`` [µrad] at them).
    raised : DevelopmentEvaluation
        The same design re-scored at ``raised_torques`` (the raise's analysis of the
        written case).
    targets : DevelopmentTargets
        Its ``light_load`` [1] sets the light torque of a torque between.
    setup : dict
        The development's state: ``torques`` [N·m] (light, design) the cut ones; not
        changed (its LTE range memo gets the analyses).
    teeth : KeptTeeth or None
        The shell teeth kept across the development's designs.
    raised_torques : list of float, shape (2,) — [N·m]
        The (light, design) torques the raise found the capacity holds at.
    say : callable (str) → None
        Progress lines (the search's, where it runs).

    Returns
    -------
    LteRaise
        ``raised_torques[1]`` (no ``why``) where the range at the raised torques keeps the
        limit, the range at the cut torques does not or either is not analysed; else the
        lowered torque of :func:`~contact.optimize.development_written_lte.
        written_lte_capacity` on ``raised`` (the crossing rounded down, kept where its own
        range keeps the limit) where it is above 1.01 × the cut torque, else the cut
        torque; ``why`` says the two ranges.

    Raises
    ------
    Nothing: an analysis that fails leaves the raise as found (logged by
    :func:`~contact.optimize.development_range_lte.range_lte`).

    Notes
    -----
    The LTE of a localised bearing on a face contact ratio below 1 rises with the torque
    above the unloaded TE's reach (the single-pair zone's deflection against the two-pair
    zone's), so a raise on the capacity alone can write a design torque past the window the
    bearing keeps 60 µrad in. Measured on the 16×16 at Σ 60° (docs/synthesis.md, "The FM
    16×16 at Σ 60°'s design torque raised back past its LTE window"): 53 / 51 µrad at
    41.7 / 278.3 N·m, 54 / 95 µrad at 58.6 / 390.7 N·m, 52.5 / 59.4 µrad at 45 / 300 N·m.
    Source: ``ltca run``'s ``lte`` check and issue 71's Done-when.
    """
    new = float(raised_torques[1])
    limit = development_lte_limit()
    trial = {k: v for k, v in setup.items() if k not in ("lte_torque", "lte_window",
                                                        "lte_window_light")}
    trial["torques"] = [float(t) for t in raised_torques]
    high = range_lte(raised, trial, teeth)
    if high is None or not max(high[1]) > limit:
        return LteRaise(new)
    low = range_lte(cut, setup, teeth)
    if low is None or max(low[1]) > limit:  # not met at the cut torque: nothing lost
        return LteRaise(new)
    lines: list[str] = []
    written_lte_capacity(raised, targets, trial, teeth, lines.append)
    within = float(trial.get("lte_torque", math.nan))
    torque = float(setup["torques"][1])
    why = (f"the drive {range_curve(low)} at the cut torques, {range_curve(high)} at the "
           f"raised ones")
    if math.isfinite(within) and within > 1.01 * torque:
        return LteRaise(within, why)
    say(f"  no design torque above {torque:.4g} N m keeps the drive LTE within {limit:g} urad "
        f"at every torque ({'; '.join(lines)})")
    return LteRaise(torque, why)
