"""The development's check step for a design torque's LTE above the verdict's limit on the
bearing the check's later steps made (issue 71): the path turned towards the profile
again, the ellipse shortened with it where the pattern is longer than its target.

:func:`checked_path_lte` gives a checked drive design whose LTE p-p at the design torque
exceeds ``ltca run``'s verdict limit (:data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad)
the path angle turned towards the profile by each of :data:`PATH_LTE_STEPS` in turn
(clipped to its bound), the ellipse shortened by the step's amount where the light-load
pattern is longer than the target's middle. Each design is kept on the check steps' one
rule (:func:`~contact.optimize.development_keep.kept_why` with
:func:`~contact.optimize.development_keep.lost_targets`: ranks better, no met target
lost, tolerant at the mounting excursions). The check's first path step
(:func:`~contact.optimize.development_path_steps.checked_path`) runs before the steps
that lengthen the ellipse and place M again; this one runs after the design torque's LTE
steps, on the bearing they leave. A design whose gate does not hold is returned as it is,
without an analysis.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets, ranks_better
from contact.optimize.development_lte_steps import lte_reached
from contact.optimize.development_matched_te import lte_ends
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import pattern_length, said_variant
from geometry.case import Case
from geometry.core.text import plain_number

log = logging.getLogger("contact.optimize.development")

#: the turns of the path angle towards the profile [deg] and the ellipse's shortening [1]
#: (where the light-load pattern is longer than its target's middle) that
#: :func:`checked_path_lte` tries in turn, each from the design the step began with.
#: Measured on the face-hobbed hypoid 8x35 at Σ 85° (Method 3, z0 11, k_d 2.16) of
#: benchmarks/data/unseen_designs at 55.3 / 368.9 N m (``benchmarks/development_levers.py
#: --check --tolerance --at 159.8 264.4 --from-case``, its case written with path
#: −58.75°, ellipse 0.75: LTE 47 / 62 µrad, pattern 0.62 long, largest LTE of the four
#: torques 76 µrad): the path −62° / −65° / −68° / −72° at the ellipse 0.75 gave 32 / 40,
#: 23 / 25, 16 / 13, 17 / 10 µrad (pattern 0.62–0.70 long); −65° / 0.7: 31 / 39 µrad, 0.60
#: long, every target met, tolerant, the four torques' largest 57 µrad; −72° / 0.65: 21 / 23
#: µrad, every target met, tolerant, largest 48; −80° / 0.6: 14 / 12, every target met,
#: tolerant, largest 42 (docs/synthesis.md, "The path turned again for the design torque's
#: LTE")
PATH_LTE_STEPS = ((-6.25, -0.05), (-12.5, -0.1))

#: the step's lever in words, as ``ltca synthesize``'s note lists the levers tried
#: (:func:`~contact.optimize.development_lte_steps.lte_reached`)
LEVER = "the path turned towards the profile"

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "path lte"

#: the names the step varies
NAMES = ("path_angle", "ellipse_length")


def lte_limit() -> float:
    """The design torque's LTE p-p [µrad] above which :func:`checked_path_lte` runs:
    ``ltca run``'s verdict limit.

    Returns
    -------
    float — [µrad]

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the ``lte`` check of ``ltca run``'s verdict (:data:`contact.study.verdicts.
    LTE_LIMIT`, 60 µrad); issue 71, "LTE p-p ≤ 60 µrad at every torque". Not the
    development's own target (40 µrad by default): a design torque's LTE between the two
    is no finding of the verdict, and the step's designs (each a synthesis of steps 3-6)
    are spent where it is.
    """
    from contact.study.verdicts import LTE_LIMIT  # imports contact.ltca

    return float(LTE_LIMIT)


def runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
            peak: float = math.nan) -> bool:
    """The step's gate, asked without an analysis: ``best`` is checked at ``ltca run``'s
    sampling, its LTE p-p at the design torque (or ``peak``, its LTE between the
    development's torques, where given) is above :func:`lte_limit`, and the targets
    and the design vary ``path_angle`` and ``ellipse_length`` with the path not at its
    bound towards the profile (the lower bound of ``path_angle``).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds [deg], [1]).
    peak : float, optional — [µrad]
        The design's largest LTE p-p between the light and the design torque
        (:func:`~contact.optimize.development_range_lte.range_lte`); default NaN: the
        design torque's alone.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (docs/synthesis.md, "The path turned again for the design torque's
    LTE").
    """
    if (not best.checked_full
            or "lte_peak_to_peak" not in best.metrics
            or not all(n in targets.variables and n in best.values for n in NAMES)):
        return False
    if not (lte_ends(best)[1] > lte_limit() or peak > lte_limit()):  # NaN: not run
        return False
    lo = float(targets.variables["path_angle"][0])
    return float(best.values["path_angle"]) > lo + 1e-9


def checked_path_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case], *,
                     peak: tuple[float, float] | None = None,
                     better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool]
                     = ranks_better) -> DevelopmentEvaluation:
    """A drive design whose design torque's LTE exceeds the verdict's limit
    (:func:`runs_on`), its path turned towards the profile: the path angle turned by each
    of :data:`PATH_LTE_STEPS` from the design's (clipped to its bound), the ellipse
    shortened by the step's amount where the design's light-load pattern is longer than the
    target's middle (within its bounds), each placed and checked at ``ltca run``'s
    sampling (a synthesis of steps 3-6) and kept where it ranks better, misses no target
    the design met and is tolerant at ΔE/ΔP ± 0.05 mm
    (:func:`~contact.optimize.development_keep.kept_why` with
    :func:`~contact.optimize.development_keep.lost_targets`); the better of the two by the
    check's rank. At most two designs; one whose turn is clipped to a path tried (the
    bound) is not analysed.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`;
        ``targets.variables``: the bounds of ``path_angle`` [deg] and ``ellipse_length``
        [1]; ``targets.pattern_length`` [1 of the face]).
    peak : (float, float), optional — [µrad], [N·m]
        The design's largest LTE p-p between the light and the design torque and its
        torque, where the step acts on it (:func:`~contact.optimize.development_range_lte.
        checked_range_lte`); default None: on the design torque's.
    better : callable (best, e) → bool, optional
        The keep rule's ``better`` (default
        :func:`~contact.optimize.development_keep.ranks_better`; on a peak between the
        torques, :func:`~contact.optimize.development_range_lte.range_better`: judged on
        the largest LTE over the range).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``stage`` ``"path lte"``): ``best`` itself where the gate does
        not hold or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Why: a path nearer the profile shortens the contact's lengthwise travel over one
    pair's roll, so more pairs share the transfer at the design torque, where the LTE of a
    pair of low contact ratios is made (the check's path step,
    :func:`~contact.optimize.development_path_steps.checked_path`; Stadtfeld, *Gleason
    Bevel Gear Technology*, 2014: the bias of the path sets the contact ratio the bearing
    uses; Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4). The
    check's path step runs on the chosen design before the long bearing's ellipse and M
    are set; on the face-hobbed hypoid 8x35 at Σ 85° (ε_vα 1.00, ε_vβ 1.23) of
    benchmarks/data/unseen_designs the bearing written after them (path −58.75°, ellipse
    0.75, M −0.059 of the face) reads 47 / 62 µrad at 55.3 / 368.9 N m, and turned by
    −6.25° with the ellipse 0.7: 31 / 39 µrad, every target met (:data:`PATH_LTE_STEPS`).
    """
    between = (math.nan, math.nan) if peak is None else tuple(float(x) for x in peak)
    if not runs_on(best, targets, between[0]):
        return best
    start = best
    (p_lo, p_hi), (e_lo, e_hi) = (tuple(float(x) for x in targets.variables[n])
                                  for n in NAMES)
    light, design = lte_ends(start)
    limit = lte_limit()
    long_ = pattern_length(start) > float(targets.pattern_length)
    lte_reached(setup, start, f"design {start.index + 1} as checked")
    tried: list[dict[str, float]] = []
    for turn, shorter in PATH_LTE_STEPS:
        path = round(float(np.clip(float(start.values["path_angle"]) + turn, p_lo, p_hi)), 4)
        ellipse = float(start.values["ellipse_length"])
        if long_:
            ellipse = round(float(np.clip(ellipse + shorter, e_lo, e_hi)), 4)
        values = dict(start.values) | {"path_angle": path, "ellipse_length": ellipse}
        if path == float(start.values["path_angle"]) or any(
                t["path_angle"] == path for t in tried):
            # the turn clipped to a path tried: a shorter ellipse alone is no turn (the
            # spiral bevel 17x29 at Σ 100° of tests/data/designs, path −75°: −80° / 0.7
            # 18 / 88 µrad, −80° / 0.65 21 / 99 µrad against 18 / 85)
            continue
        tried.append(values)
        where = ("the design torque's" if peak is None else
                 f"{between[0]:.0f} urad at {plain_number(between[1])} N m between the torques")
        e = said_variant(start, values, STAGE,
                         f"with path_angle {path:.4g}, ellipse_length {ellipse:.3g} (its "
                         f"LTE {light:.0f}/{design:.0f} urad, {where} above "
                         f"{limit:g})", targets, setup, teeth, say, placed)
        if e is None:
            continue
        why = kept_why(best, e, targets, setup, teeth, say, "the path turned",
                       better=better, lost=lost_targets)
        lte_reached(setup, e, f"design {start.index + 1} with path_angle {path:.4g}, "
                    f"ellipse_length {ellipse:.3g}", why, LEVER)
        if not why:
            best = e
    return best
