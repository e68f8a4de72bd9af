"""The check's lighter-relief step (issue 71): a drive design that misses its LTE target
alone, by a small margin (:data:`~contact.optimize.development_pattern_steps.
LENGTH_RELIEF_LTE` of its unit), after every other LTE step, given a lighter tip relief
and then a shallower root relief (:data:`RELIEF_NAMES`, each × :data:`~contact.optimize.
development_pattern_steps.LENGTH_RELIEF_FRACTION` of the design's); each design placed and
checked at ``ltca run``'s sampling (:func:`~contact.optimize.development_variant.
said_variant`) and kept by the check's one rule (:func:`~contact.optimize.
development_keep.kept_why` with :func:`~contact.optimize.development_keep.lost_targets`,
asked first: no met target given up, better, tolerant).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_pattern_steps import LENGTH_RELIEF_FRACTION, LENGTH_RELIEF_LTE
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case

#: the reliefs :func:`checked_lighter_relief` lightens, in turn: the tip relief first (a
#: lighter tip relief lowered the flank's peak pressure too on the spiral bevel 13x39 at
#: Σ 80°, the shallower root relief raised it: 1448 / 1616 MPa from 1472 MPa)
RELIEF_NAMES = ("tip_relief", "root_relief")

#: the check stage's name of the step's designs
STAGE = "lighter relief"


def lte_alone_near(e: DevelopmentEvaluation | None, limit: float = LENGTH_RELIEF_LTE) -> bool:
    """Whether a checked design misses its LTE target and no other, by at most ``limit``.

    Parameters
    ----------
    e : DevelopmentEvaluation or None
        A design scored at the check (its ``full``: objective, shortfalls, every target met).
    limit : float, optional
        The most LTE shortfall, in :func:`~contact.optimize.development_targets.
        development_score`'s units (1.0: 10 µrad; default :data:`~contact.optimize.
        development_pattern_steps.LENGTH_RELIEF_LTE`).

    Returns
    -------
    bool
        ``e`` was checked, misses the LTE alone and by no more than ``limit``.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "The lighter relief for
    an LTE just missed").
    """
    if e is None or e.full is None or not e.checked or e.full[2]:
        return False
    short = e.full[1]
    return ([k for k, v in short.items() if v > 0.0] == ["lte"]
            and float(short["lte"]) <= limit)


def checked_lighter_relief(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                           setup: Mapping[str, Any], teeth: KeptTeeth | None,
                           say: Callable[[str], None],
                           placed: Callable[[Mapping[str, float]], Case]
                           ) -> DevelopmentEvaluation:
    """A drive design that misses its LTE target alone by a small margin
    (:func:`lte_alone_near`) given a lighter relief: each of :data:`RELIEF_NAMES` (where
    developed and positive) × :data:`~contact.optimize.development_pattern_steps.
    LENGTH_RELIEF_FRACTION` (within its bounds; its start and every other prescription
    kept: step 7 only), in turn; each design placed and checked at ``ltca run``'s
    sampling and kept by :func:`~contact.optimize.development_keep.kept_why` (no target
    the design met given up, said first; better; tolerant at the mounting excursions);
    the first kept that meets every target ends it.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept so far, checked at ``ltca run``'s sampling.
    targets : DevelopmentTargets
        The development's targets (the bounds of ``tip_relief`` and ``root_relief`` [µm];
        ``max_lte`` [µrad]).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable str → None
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis as written (:func:`~contact.optimize.development_check.placed_case`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept last (``stage`` :data:`STAGE`); ``best`` itself where none was or
        the step does not apply (every target met, another target missed, the LTE missed
        by more than the margin, no relief to lighten). A design whose synthesis or
        analysis fails is not kept (logged, not raised).

    Notes
    -----
    Why: the reliefs are sized by the search against the edges at the design torque and
    the mounting excursions, and shortened or deepened by the height steps for the
    pattern's depth; a relief deeper than the teeth deflect at the design torque takes
    away flank where the next pair would take up its load, so the loaded contact ratio
    stays below what the geometry gives and the design torque's LTE rises (Stadtfeld,
    *Gleason Bevel Gear Technology*, 2014: the relief sized to the load's deflection;
    Litvin & Fuentes 2004 §9.4). The shallower root relief is tried by
    :func:`~contact.optimize.development_lte_steps.checked_relief_lte` only above the
    verdict's 60 µrad, and by :func:`~contact.optimize.development_pattern_steps.
    checked_length` only on a design of its ellipse search; a design that meets its
    length and misses the development's LTE target by a µrad or two got neither.
    Measured at ``ltca run``'s sampling on the FM spiral bevel 13x39 at Σ 80° of
    benchmarks/data/unseen_designs (40.7 / 271.4 N m; path −80°, ellipse 0.725, tip
    relief 10 µm from 0.9, root relief 40 µm from 0.2, te_level 10 µrad, the levers at
    their bounds; ``benchmarks/development_levers.py --check --tolerance``, 2026-11-27):
    LTE 10.8 / 41.1 µrad (the target 40 missed, every other met), 1472 MPa; tip relief
    7.5 µm: 10.3 / 38.0, edge 0.5 %, 1448 MPa; root relief 30 µm: 10.9 / 39.1, 1616 MPa;
    both: 10.1 / 35.9 — each every target met and tolerant; root relief 20 µm: centre v
    missed; 30 µm from 0.3: 17.1 / 32.2 but centre v missed.
    """
    if not lte_alone_near(best):
        return best
    for name in RELIEF_NAMES:
        if (name not in targets.variables or name not in best.values
                or not float(best.values[name]) > 0.0):
            continue
        lo, hi = (float(x) for x in targets.variables[name])
        now = float(best.values[name])
        x = float(np.clip(LENGTH_RELIEF_FRACTION * now, lo, hi))
        if not x < now - 1e-9:
            continue
        e = said_variant(best, dict(best.values) | {name: x}, STAGE,
                         f"with {name} {x:.3g} um (its LTE just above {targets.max_lte:g} "
                         "urad)", targets, setup, teeth, say, placed)
        if not kept_why(best, e, targets, setup, teeth, say, f"the lighter {name}",
                        lost=lost_targets, lost_first=True):
            best = e
            if best.met:
                break
    return best
