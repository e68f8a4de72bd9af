"""The design torque lowered to where the developed drive bearing keeps its LTE, where the
check's chosen design's LTE at the design torque FAILs ``ltca run``'s verdict (issue 71:
the ratio-1 spiral bevel 16x16 at Σ 60°).

The FAIL-level rank (:func:`~contact.optimize.development_variant.lte_fails`,
:func:`~contact.optimize.development_variant.check_rank`,
:func:`~contact.optimize.development_keep.verdict_lost`) replaces a design whose checked
LTE the verdict FAILs by one it passes where the check found one; where every design
checked FAILs (the 16x16 at Σ 60°: each bearing lever left 90-126 µrad at its ISO
capacity 649.4 N m, the LTE a share of the teeth's mean deflection,
:mod:`~contact.optimize.development_deflection`), the development wrote it at its ISO
capacity and ``ltca run`` FAILed it (LTE p-p 45 / 122 µrad at 97.4 / 649.4 N m). The
design torque is the development's own choice where the basic file gives none (the ISO
10300 capacity, lowered already to the bearing's static flank capacity, its FE root
stress and local pitting capacity): :func:`lte_capacity` lowers it as well, to the
torque up to which the chosen bearing keeps the verdict's limit
(:func:`~contact.optimize.development_deflection.within_torque` of its LTE p-p at
:data:`~contact.optimize.development_deflection.LTE_TORQUES` torques from the light to
the design torque, analysed as the check analyses: :data:`CHECK_LTCA`, ``ltca run``'s
sampling). A design torque the basic file gives is kept (``ltca synthesize``'s note says
where the bearing keeps the limit).

Public names
------------
lte_capacity
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from contact.optimize import development_evaluate as evaluation
from contact.optimize.development_deflection import LTE_TORQUES, within_torque
from contact.optimize.development_evaluate import CHECK_LTCA, KeptTeeth, bearing_key
from contact.optimize.development_result import (
    DevelopmentEvaluation,
    case_torques,
    floor_torque,
    scored,
)
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import lte_fails
from geometry.core.text import plain_number

__all__ = ["lte_capacity"]

#: analyses of a lowered design torque at most (the LTE of a localised bearing is no
#: smooth function of the torque: each one adds its torque to those the crossing is
#: interpolated between)
_TRIES = 3


def lte_capacity(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: dict[str, Any], teeth: KeptTeeth, say: Callable[[str], None], *,
                 n: int = LTE_TORQUES) -> DevelopmentEvaluation:
    """The design torque lowered to where the chosen design's drive LTE keeps the
    verdict's limit, where its checked LTE the verdict FAILs
    (:func:`~contact.optimize.development_variant.lte_fails`) at the light or the design
    torque or, as the check's last step judged it, between them
    (:func:`~contact.optimize.development_range_lte.range_record`: ``ltca run``'s
    ``lte_range`` torques).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The check's chosen design (its ``metrics`` at ``setup["torques"]``, checked).
    targets : DevelopmentTargets
        Its ``light_load`` [1] sets the light torque of a lowered design torque.
    setup : dict
        The development's setup: ``torques`` [N·m] (light, design), ``source``,
        ``centre_v``; updated (``torques``, ``source``, ``lowered``) where the torque is
        lowered.
    teeth : KeptTeeth
        The shell teeth kept across the development's designs.
    say : callable (str) → None
        Where the step's line goes.
    n : int
        Torques analysed from the light to the design torque, ≥ 2 (default
        :data:`~contact.optimize.development_deflection.LTE_TORQUES`).

    Returns
    -------
    DevelopmentEvaluation
        ``best`` where its LTE passes the verdict, it has no case, no torque below the
        design torque keeps the limit (:func:`within_torque` NaN: the light torque's LTE
        above the limit already), or the lowered torque's LTE still FAILs; else ``best``
        scored at the lowered light and design torques [N·m] (``case_torques``).

    Raises
    ------
    InputError
        From the analysis (a case it cannot analyse).

    Notes
    -----
    Source: ``ltca run``'s verdict (:mod:`contact.study.verdicts`, the ``lte`` check,
    60 µrad, FAIL beyond 2 ×); issue 71, the 16x16 at Σ 60° (docs/own_gear_set.md, "The
    design torque lowered for a FAIL-level LTE"): LTE p-p 45 / 47 / 111 / 122 µrad at
    97.4 / 281 / 465 / 649.4 N m, within 60 µrad up to ≈ 319 N m; its basic file with
    ``design_torque = 300`` measured 57 / 55 µrad (docs/synthesis.md, "The LTE at the
    design torque: the teeth's deflection"). Linear between the torques analysed; each
    lowered torque is analysed at its own light torque and, where its LTE is above the
    limit, added to the torques the crossing is interpolated between (at most
    :data:`_TRIES` analyses).
    """
    from contact.study.verdicts import LTE_LIMIT  # imports contact.ltca

    between = _between_peak(best, setup)
    if not (lte_fails(best) or between > _fail_level(LTE_LIMIT)) or best.case is None:
        return best
    light, design = (float(t) for t in setup["torques"])
    key = bearing_key(best.values)

    def analyse(torques: list[float]):
        return evaluation.analyse_design(best.case, torques, options=CHECK_LTCA,
                                         teeth=teeth, pinion_key=key)

    seen = [float(t) for t in np.linspace(light, design, max(2, int(n)))]
    lte = [float(x) for x in analyse(seen)[0]["lte_peak_to_peak"]]
    before = (" / ".join(f"{x:.0f}" for x in lte), " / ".join(f"{plain_number(t)}" for t in seen))
    accepted = None
    for _ in range(_TRIES):
        within = within_torque(seen, lte, LTE_LIMIT)
        if not math.isfinite(within):
            break
        new = floor_torque(within)
        if new >= design or new in seen[1:]:
            break
        torques = case_torques(targets.light_load, new)
        ms, grid = analyse(torques)
        here = float(ms["lte_peak_to_peak"][1])
        lowered = scored(best, ms, grid, targets, setup["centre_v"])
        if not lte_fails(lowered):  # the verdict passes its LTE there: kept
            accepted = (torques, lowered)
        if not here > LTE_LIMIT:
            break
        order = np.argsort([*seen, new])
        seen = [[*seen, new][i] for i in order]
        lte = [[*lte, here][i] for i in order]
    if accepted is None:
        return best
    torques, lowered = accepted
    ends = [float(x) for x in lowered.metrics["lte_peak_to_peak"]]
    shown = " / ".join(f"{x:.0f}" for x in ends)
    # the bearing as it stood when the torque was lowered: the development at the new
    # torque follows and writes its own LTE; a light torque above the limit is said (the
    # 13x17 at Σ 50°: "61 / 58" read as the written design's, docs/own_gear_set.md)
    over = (f", the light torque's above {LTE_LIMIT:g} urad" if ends[0] > LTE_LIMIT else "")
    source = (f"the torque up to which the developed bearing keeps the drive LTE within "
              f"{LTE_LIMIT:g} urad: checked at {setup['source'].split(',')[0]} "
              f"{plain_number(design)} N m its LTE p-p was {max(_worst(best), between):.0f} urad, "
              "above ltca run's "
              f"FAIL level {_fail_level(LTE_LIMIT):g} urad (LTE p-p {before[0]} urad at "
              f"{before[1]} N m); at the lowering {shown} urad at "
              f"{plain_number(torques[0])} / {plain_number(torques[1])} N m{over} (the "
              "bearing before its development at this torque; the written design's LTE: "
              "the development line)")
    setup.update(torques=torques, source=source, lowered=True)
    say(f"  design torque {plain_number(design)} -> {plain_number(torques[1])} N m: {source}")
    return lowered


def _between_peak(best: DevelopmentEvaluation, setup: dict[str, Any]) -> float:
    """The largest LTE p-p [µrad] the check's last step judged ``best`` at between the
    development's torques (:func:`~contact.optimize.development_range_lte.range_record`),
    NaN where it judged another design or none at these torques."""
    from contact.optimize.development_range_lte import range_record

    found = range_record(setup)
    if found is None or found["values"] != dict(best.values):
        return math.nan
    return float(found["peak"])


def _worst(e: DevelopmentEvaluation) -> float:
    """The largest checked LTE p-p [µrad] of a design (light or design torque)."""
    return float(np.nanmax(np.asarray(e.metrics["lte_peak_to_peak"], float)))


def _fail_level(limit: float) -> float:
    """The LTE p-p [µrad] above which ``ltca run``'s verdict FAILs."""
    from contact.study.verdicts import LTE_FAIL_FACTOR

    return LTE_FAIL_FACTOR * limit
