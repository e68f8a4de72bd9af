"""The development's check step for a design torque's LTE set by a tip edge (issue 71):
a lighter, then a longer tip relief.

:func:`checked_tip_lte` gives a checked drive design whose LTE p-p at the design torque
misses the development's LTE target (``max_lte``) or ``ltca run``'s verdict limit
(:data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad), and whose contact at the design
torque reaches a tip edge (the gear's tip or the pinion's edge carries load there: the
``tip_edge_share`` metric, :data:`~contact.optimize.development_evaluate.TIP_EDGE_KINDS`),
the tip relief's amount × each of :data:`TIP_LTE_FRACTIONS` in turn (its start kept),
then the relief kept started :data:`TIP_LTE_START_STEP` lower (longer). Each design is
kept on the check steps' one rule (:func:`~contact.optimize.development_keep.kept_why`:
ranks better, no met target lost, tolerant at the mounting excursions). The other check
steps lower a tip relief only for a light-load pattern above its depth centre
(:func:`~contact.optimize.development_height_steps.checked_tip`); a design whose gate
does not hold is returned as it is, without an analysis.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_lte_steps import lte_reached
from contact.optimize.development_matched_te import lte_ends
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case

log = logging.getLogger("contact.optimize.development")

#: the tip relief's amounts :func:`checked_tip_lte` tries, fractions of the design's, in
#: turn (its start kept): on the FM hypoid 15x31 at a = 0.056 d_e2 of
#: benchmarks/data/unseen_designs (94.1 / 627.7 N m, tip relief 24.6 µm from 0.893) 20 /
#: 16 / 12 µm gave LTE 31 / 92, 30 / 80, 29 / 76 µrad against 31 / 99, the lightest not
#: tolerant (2.1–2.4 % on edges at ΔP), 8 µm and less uncovering the tip edge (3.2–6.4 %
#: on edges); docs/synthesis.md, "The matched TE parabola on the hypoid 15×31"
TIP_LTE_FRACTIONS = (0.8, 2.0 / 3.0, 0.5)

#: [1] how much earlier (of the way from M to the tip) :func:`checked_tip_lte`'s last
#: design starts the tip relief kept: a longer relief of the same amount (the 15x31: from
#: 0.893 → 0.8, LTE 31 / 99 → 39 / 83 µrad, the light-load centre v lost)
TIP_LTE_START_STEP = 0.1

#: the step's levers in words, as ``ltca synthesize``'s note lists the levers tried
#: (:func:`~contact.optimize.development_lte_steps.lte_reached`)
LIGHTER_LEVER = "a lighter tip relief"
LONGER_LEVER = "a longer tip relief"

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "tip lte"

#: the names the step varies
NAMES = ("tip_relief", "tip_relief_start")

#: why :func:`kept_why` refused a design for which a still lighter relief is not tried
#: (its LTE fails, it loses a met target or is not tolerant: a lighter relief uncovers
#: the tip edge further)
_SCORES_NO_BETTER = "it scores no better"


def lte_limit(targets: DevelopmentTargets) -> float:
    """The design torque's LTE p-p [µrad] above which :func:`checked_tip_lte` runs: the
    smaller of the development's target ``max_lte`` and ``ltca run``'s verdict limit.

    Parameters
    ----------
    targets : DevelopmentTargets
        Its ``max_lte`` [µrad].

    Returns
    -------
    float — [µrad]

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the ``lte`` check of ``ltca run``'s verdict (:data:`contact.study.verdicts.
    LTE_LIMIT`, 60 µrad) and the development's targets (docs/synthesis.md, "Development
    bearing"); issue 71, "LTE p-p ≤ 60 µrad at every torque".
    """
    from contact.study.verdicts import LTE_LIMIT  # imports contact.ltca

    return float(min(float(targets.max_lte), float(LTE_LIMIT)))


def reaches_tip(e: DevelopmentEvaluation) -> bool:
    """Whether a checked design's contact at the design torque reaches a tip edge: its
    ``tip_edge_share`` at the design torque (the last) is above 0.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics`` (``tip_edge_share`` [1] per torque, light first).

    Returns
    -------
    bool
        False where its metrics carry no ``tip_edge_share`` or it is not finite (no load).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the tip edges of the flank boundary (:mod:`contact.ltca.edges`,
    :data:`~contact.optimize.development_evaluate.TIP_EDGE_KINDS`).
    """
    if e.metrics is None or "tip_edge_share" not in e.metrics:
        return False
    share = float(np.asarray(e.metrics["tip_edge_share"], float)[-1])
    return bool(math.isfinite(share) and share > 0.0)


def runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets) -> bool:
    """The step's gate, asked without an analysis: ``best`` is checked at ``ltca run``'s
    sampling, its LTE p-p at the design torque is above :func:`lte_limit`, its contact
    there reaches a tip edge (:func:`reaches_tip`), and the targets and the design vary
    ``tip_relief`` and ``tip_relief_start`` with the relief above its lower bound.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``max_lte`` [µrad], ``variables``).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (docs/synthesis.md, "The tip relief for the design torque's LTE").
    """
    if (best.full is None or not best.checked or best.metrics is None
            or "lte_peak_to_peak" not in best.metrics
            or not all(n in targets.variables and n in best.values for n in NAMES)):
        return False
    design = lte_ends(best)[1]
    if not design > lte_limit(targets):  # NaN: not run
        return False
    lo = float(targets.variables["tip_relief"][0])
    return float(best.values["tip_relief"]) > lo + 1e-9 and reaches_tip(best)


def checked_tip_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                    setup: Mapping[str, Any], teeth: KeptTeeth | None,
                    say: Callable[[str], None],
                    placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """A drive design whose design torque's LTE misses its target with the contact there
    on a tip edge (:func:`runs_on`), given a lighter tip relief, then a longer one: the
    tip relief × each of :data:`TIP_LTE_FRACTIONS` of the design's (within its bounds, its
    start kept) in turn, until a design meets every target or one is refused for more
    than scoring no better (its LTE fails the verdict, it loses a met target or is not
    tolerant: a lighter relief still uncovers the tip edge further); then, where the
    design kept still misses :func:`lte_limit` at the design torque, its relief started
    :data:`TIP_LTE_START_STEP` earlier (within the bounds of ``tip_relief_start``). Each
    design (the relief only: no new bearing synthesis) placed and checked at ``ltca
    run``'s sampling, kept where it ranks better, misses no target the design met and is
    tolerant at ΔE/ΔP ± 0.05 mm (:func:`~contact.optimize.development_keep.kept_why` with
    :func:`~contact.optimize.development_keep.lost_targets`); at most four designs.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`;
        ``targets.variables``: the bounds of ``tip_relief`` [µm] and ``tip_relief_start``
        [1]).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``stage`` ``"tip lte"``): ``best`` itself where the gate does
        not hold or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: once the loaded pattern spans the working depth the mesh's transfer runs onto
    the tip relief's ramp, and the relief's depth is unloaded TE that the load does not
    take up: the design torque's LTE grows with the relief (Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: the tip relief sized to the design load's deflection, no deeper;
    Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4). A lighter
    relief lowers it until the tip edge carries load at the mounting excursions. Measured
    at ``ltca run``'s sampling on the FM hypoid 15x31 at a = 0.056 d_e2 of
    benchmarks/data/unseen_designs (ε_vβ 1.00; 94.1 / 627.7 N m; its written bearing path
    −65.6°, ellipse 0.625, tip relief 24.6 µm from 0.893, root relief 39.1 µm from 0.251,
    te_level 10 µrad; ``benchmarks/development_levers.py --check --tolerance
    --from-case``, 2026-11-27): LTE 31 / 99 µrad, the gear's tip edge loaded from ≈ 272
    N m (1583 MPa there, 5158 MPa at 627.7 N m); tip relief 0 / 8 / 16 / 24.6 / 40 µm: 49
    / 69 / 80 / 99 / 117 µrad at the design torque; 16 µm every target the written design
    meets, tolerant, objective 35.8 → 16.8; 12 µm 76 µrad but 2.1–2.4 % on edges at ΔP;
    the relief from 0.8: 39 / 83 µrad, the light-load centre v lost.
    """
    if not runs_on(best, targets):
        return best
    start = best
    (r_lo, r_hi), (s_lo, s_hi) = (tuple(float(x) for x in targets.variables[n])
                                  for n in NAMES)
    light, design = lte_ends(start)
    limit = lte_limit(targets)
    lte_reached(setup, start, f"design {start.index + 1} as checked")
    tried: list[dict[str, float]] = []
    for fraction in TIP_LTE_FRACTIONS:
        amount = round(float(np.clip(fraction * float(start.values["tip_relief"]),
                                     r_lo, r_hi)), 2)
        values = dict(start.values) | {"tip_relief": amount}
        if values in tried or values == dict(start.values):
            continue
        tried.append(values)
        e = said_variant(start, values, STAGE,
                         f"with tip_relief {amount:.3g} um from "
                         f"{float(values['tip_relief_start']):.3g} (its LTE {light:.0f}/"
                         f"{design:.0f} urad above {limit:g}, the design torque's contact "
                         "on a tip edge)", targets, setup, teeth, say, placed)
        if e is None:
            continue
        why = kept_why(best, e, targets, setup, teeth, say, "the lighter tip relief",
                       lost=lost_targets)
        lte_reached(setup, e, f"design {start.index + 1} with tip_relief {amount:.3g} um",
                    why, LIGHTER_LEVER)
        if not why:
            best = e
        if best.full[2] or (why and why != _SCORES_NO_BETTER):
            break
    if best.full[2]:
        return best
    kept_design = lte_ends(best)[1]
    s_now = float(best.values["tip_relief_start"])
    earlier = round(float(np.clip(s_now - TIP_LTE_START_STEP, s_lo, s_hi)), 4)
    if not (kept_design > limit and earlier < s_now - 1e-9):
        return best
    values = dict(best.values) | {"tip_relief_start": earlier}
    e = said_variant(best, values, STAGE,
                     f"with tip_relief {float(values['tip_relief']):.3g} um from {earlier:.3g}"
                     f" (a longer tip relief; its LTE {kept_design:.0f} urad at the design "
                     f"torque above {limit:g})", targets, setup, teeth, say, placed)
    if e is None:
        return best
    why = kept_why(best, e, targets, setup, teeth, say, "the longer tip relief",
                   lost=lost_targets)
    lte_reached(setup, e, f"design {start.index + 1} with tip_relief "
                f"{float(values['tip_relief']):.3g} um from {earlier:.3g}", why,
                LONGER_LEVER)
    return best if why else e
