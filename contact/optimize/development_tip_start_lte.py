"""The development's check step for a design torque's LTE above the target where the face
contact ratio is below 1 (issue 71): the tip relief started later, at its bound.

:func:`checked_tip_start_lte` gives a checked drive design that misses the development's
LTE target (``max_lte``) at the design torque, on a pair whose face contact ratio ε_vβ is
below :data:`FACE_RATIO_BELOW`, one design more: its tip relief's start
(``tip_relief_start``, the flankrem's corner as the fraction of the way from M to the tip
end) at the upper bound of the development's variables. It is kept on the check steps' one
rule (:func:`~contact.optimize.development_keep.kept_why`: ranks better, no met target lost,
tolerant at the mounting excursions). A design that meets its LTE target at the design
torque, has no tip relief, whose start is at its bound already or whose ε_vβ is not below
1 is returned as it is, without an analysis.

Why (measured, docs/synthesis.md, "LTE at every torque on a face contact ratio below 1"):
on the face-milled spiral bevel 15x28 at Σ 110° (ε_vβ 0.91) the LTE up to the light torque
is the unloaded TE, at the design torque the deflection's variation where one pair still
carries the load alone; a tip relief that starts later leaves the pair's flank near its tip
to the hand-over, lowering both the unloaded TE (90 → 83 µrad) and the load sharing's
floor (94 → 82 µrad): LTE 90 / 103 → 86 / 93 µrad, every other target kept, tolerant. It
does not reach the verdict's 60 µrad (no lever of the development does on that design; the
face contact ratio is the remedy).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_lte_steps import lte_reached
from contact.optimize.development_matched_te import contact_ratios, lte_ends
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case

__all__ = ["FACE_RATIO_BELOW", "NAME", "STAGE", "TIP_START_LEVER", "checked_tip_start_lte",
           "later_start", "runs_on"]

#: [1] the face contact ratio ε_vβ below which :func:`checked_tip_start_lte` runs: below 1
#: one pair carries the load alone over part of the mesh cycle at any torque a localised
#: bearing is developed for (ISO 10300-1:2014, Annex A: ε_vβ the overlap of the virtual
#: cylindrical gear; the 15x28 at Σ 110°, ε_vβ 0.91: one pair alone over 15 % of the cycle
#: at its ISO capacity)
FACE_RATIO_BELOW = 1.0

#: the prescription the step moves (``[synthesis]`` file units: a fraction [1])
NAME = "tip_relief_start"

#: the step's lever in words, as ``ltca synthesize``'s note lists the levers tried
#: (:func:`~contact.optimize.development_lte_steps.lte_reached`)
TIP_START_LEVER = "the tip relief started later"

#: the check stage of the step's design (:attr:`DevelopmentEvaluation.stage`)
STAGE = "tip start lte"


def later_start(values: Mapping[str, float], targets: DevelopmentTargets) -> float | None:
    """The tip relief's start [1] of :func:`checked_tip_start_lte`'s design: the upper bound
    of ``tip_relief_start`` in the development's variables, where the design has a tip
    relief and its start is more than 0.005 below that bound.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units] (``tip_relief`` [µm], ``tip_relief_start``
        [1]).
    targets : DevelopmentTargets
        Its ``variables["tip_relief_start"]`` (lower, upper) [1].

    Returns
    -------
    float or None — [1]
        None where the step has nothing to try (no tip relief, no start of its own, the
        start not among the variables, or at its bound already).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the development's variables (docs/synthesis.md, "Development bearing": bounds
    given are used as given); the lever measured (module docstring).
    """
    if NAME not in targets.variables or NAME not in values:
        return None
    relief = float(values.get("tip_relief", 0.0))
    now = float(values[NAME])
    hi = float(max(targets.variables[NAME]))
    if not (relief > 0.0 and math.isfinite(now) and hi > now + 0.005):
        return None
    return round(hi, 4)


def runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
            ratios: Callable[[], tuple[float, float]]) -> bool:
    """The step's gate, asked without an analysis: ``best`` is checked, misses the
    development's LTE target at the design torque (its LTE p-p there above ``max_lte``),
    has a later tip-relief start to try (:func:`later_start`) and its face contact ratio
    ``ratios()[1]`` (read last) is below :data:`FACE_RATIO_BELOW`.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``max_lte`` [µrad], ``variables``).
    ratios : callable → (float, float)
        The pair's (ε_vα, ε_vβ) [1], called only where every other condition holds.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (LTE p-p <= 60 µrad at every torque on a face contact ratio below 1;
    docs/synthesis.md, "LTE at every torque on a face contact ratio below 1").
    """
    if (best.full is None or not best.checked or best.metrics is None
            or not float(best.full[1].get("lte", 0.0)) > 0.0):
        return False
    if not lte_ends(best)[1] > float(targets.max_lte):
        return False
    if later_start(best.values, targets) is None:
        return False
    return bool(float(ratios()[1]) < FACE_RATIO_BELOW)


def checked_tip_start_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                          setup: Mapping[str, Any], teeth: KeptTeeth | None,
                          say: Callable[[str], None],
                          placed: Callable[[Mapping[str, float]], Case], *,
                          eps: tuple[float, float] | None = None) -> DevelopmentEvaluation:
    """A drive design that misses the development's LTE target at the design torque on a
    pair whose face contact ratio is below 1 (:func:`runs_on`), given its tip relief
    started at the bound of ``tip_relief_start`` (:func:`later_start`): one design (the
    relief's corner moved, a synthesis of step 7), placed and checked at ``ltca run``'s
    sampling, kept where it ranks better, misses no target the design met and is tolerant
    at ΔE/ΔP ± 0.05 mm (:func:`~contact.optimize.development_keep.kept_why`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).
    eps : (float, float), optional — [1]
        The pair's (ε_vα, ε_vβ) (default
        :func:`~contact.optimize.development_matched_te.contact_ratios` of the design's
        case, read only where the LTE gate holds).

    Returns
    -------
    DevelopmentEvaluation
        The design kept: ``best`` itself where the gate does not hold or the design did
        not score better.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: below ε_vβ 1 one pair carries the load alone over part of the cycle; up to the
    light torque the LTE is the unloaded TE, which the tip relief at the hand-over raises,
    and at the design torque it is the deflection's variation, whose floor
    ½ p-p(δ_design − δ_0) falls where the next pair takes up its share earlier — where its
    flank near the tip is not relieved (the short tip relief of the seed's reference
    designs, ``relief_start`` 0.86; Stadtfeld, *Gleason Bevel Gear Technology*, 2014: the
    flank relief as short as the edge allows). Measured at ``ltca run``'s sampling on the
    face-milled spiral bevel 15x28 at Σ 110° of benchmarks/data/unseen_designs (ε_vα 1.19,
    ε_vβ 0.91; 91.8 / 612.4 N m; its written bearing path −45°, ellipse 0.7, te_level
    128.1 µrad, root relief 60 µm from 0.2, tip relief 15 µm from 0.85;
    ``benchmarks/development_levers.py --check --at 10 200 300 400 500 --tolerance
    --from-case``, 2026-11-27; LTE p-p light / design [µrad], the largest over 10–612.4 N m,
    the floor from 10 N m): as written 90 / 103, 103, 94; tip relief start 0.75: 101 /
    101, 121, 112; **0.9: 86 / 93, 93, 82**, tolerant, objective 66 → 50; 0.95 (beyond
    the default bound): 89 / 92, 94, 82.
    """
    if eps is not None:
        def ratios() -> tuple[float, float]:
            return float(eps[0]), float(eps[1])
    else:
        def ratios() -> tuple[float, float]:
            return contact_ratios(best.case) if best.case is not None else (math.nan,
                                                                             math.nan)
    if not runs_on(best, targets, ratios):
        return best
    start = later_start(best.values, targets)
    if start is None:  # runs_on asked it: not reached
        return best
    light, design = lte_ends(best)
    e = said_variant(best, dict(best.values) | {NAME: start}, STAGE,
                     f"with tip_relief_start {start:.3g} (a later tip relief; LTE "
                     f"{light:.0f}/{design:.0f} urad, eps_vb below {FACE_RATIO_BELOW:g})",
                     targets, setup, teeth, say, placed)
    if e is None:
        return best
    why = kept_why(best, e, targets, setup, teeth, say, "the later tip relief",
                   lost=lost_targets)
    lte_reached(setup, best, f"design {best.index + 1} as checked")
    lte_reached(setup, e, f"design {best.index + 1} with tip_relief_start {start:.3g}", why,
                TIP_START_LEVER)
    return best if why else e
