"""The pattern's height and the plastic segments of a drive design that is not tolerant
itself (issue 71): both pinion reliefs moved together, the bearing turned towards the
profile with them, each judged against the design's own tolerance.

The check's height steps (:mod:`contact.optimize.development_height_steps`) each move one
relief and keep a design only where it is tolerant at the mounting excursions: the tip
step (``checked_tip``, a shorter tip relief) is barred where the design torque's edge
share exceeds half its limit, the root step (``checked_root``, the root relief at its
upper bound) is refused on the tolerance, and the blade step (``checked_blade``) acts
only on a design with a blade-angle change. On a design whose light-load pattern runs onto
the gear's tip (its edge share is the gear tip on the pinion's root, which a tip relief
does not touch) and which is not tolerant itself, none of them acts, and the
development writes the high pattern with its plastic segments. :func:`checked_height_relief`
tries the root relief at its upper bound (the gear's tip band out of the footprint) with
the tip relief shortened (the pattern's lower end down the flank), then the path turned
towards the profile with it (:func:`~contact.optimize.development_load_lte.
load_lte_designs`, the LTE the root relief raises bought back), and keeps a design where it
ranks better, misses no target the design met and is **no less tolerant** than it
(:func:`~contact.optimize.development_load_lte.no_less_tolerant`).
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_check import TIP_FRACTIONS, tolerance_checks
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_load_lte import load_lte_designs, replacement
from contact.optimize.development_result import TOLERANCE_KEYS, DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import changed_values, pattern_length, said_variant
from geometry.case import Case

log = logging.getLogger("contact.optimize.development")

#: the prescriptions :func:`checked_height_relief` moves (each developed, in the design's
#: values and the targets' variables, or the step does not apply)
RELIEF_NAMES = ("tip_relief", "tip_relief_start", "root_relief", "relief_start")


def height_relief_applies(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                          setup: Mapping[str, Any]) -> bool:
    """Whether :func:`checked_height_relief` works on the checked design ``best``: it
    misses its light-load centre v with the pattern above the target centre
    (``targets.pattern_centre_v``, else ``setup["centre_v"]`` [1 of the working depth])
    and carries plastic segments at a torque of the development (its ``plastic``
    target missed), and both reliefs (:data:`RELIEF_NAMES`) are developed.

    Raises nothing; a pure function of its inputs (no analysis)."""
    if (not best.checked_full
            or best.case is None
            or not all(n in targets.variables and n in best.values for n in RELIEF_NAMES)):
        return False
    short = best.full[1]
    if not (short.get("centre_v", 0.0) > 0.0 and short.get("plastic", 0.0) > 0.0):
        return False
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    centre = float(np.asarray(best.metrics["pattern_centre_v"])[0])
    return bool(np.isfinite(centre) and centre > float(target))


def height_relief_designs(values: Mapping[str, float], length: float,
                          targets: DevelopmentTargets) -> list[list[dict[str, float]]]:
    """The designs :func:`checked_height_relief` tries for a design's prescriptions
    ``values`` [file units] whose light-load pattern is ``length`` [1 of the face] long,
    in groups, one per tip relief: the root relief at the upper bound of ``root_relief``
    from the lower bound of ``relief_start``, with the tip relief at each of
    :data:`~contact.optimize.development_check.TIP_FRACTIONS` of the design's (within its
    bounds) from the upper bound of ``tip_relief_start``; each group that design first,
    then its bearing turned towards the profile (:func:`~contact.optimize.
    development_load_lte.load_lte_designs`: the path by each of the check's turns, the
    ellipse a step longer where the pattern has room, shorter where it has not).
    Duplicates and the design itself left out; empty where a relief is not developed.

    Raises nothing; a pure function of its inputs."""
    if not all(n in targets.variables and n in values for n in RELIEF_NAMES):
        return []
    (t_lo, t_hi), (_, s_hi), (_, r_hi), (r_s_lo, _) = (
        (float(a), float(b)) for a, b in (targets.variables[n] for n in RELIEF_NAMES))
    seen: list[dict[str, float]] = [dict(values)]
    groups: list[list[dict[str, float]]] = []
    for fraction in TIP_FRACTIONS:
        relieved = dict(values) | {
            "tip_relief": float(np.clip(fraction * float(values["tip_relief"]), t_lo, t_hi)),
            "tip_relief_start": s_hi, "root_relief": r_hi, "relief_start": r_s_lo}
        group = [d for d in [relieved, *load_lte_designs(relieved, length, targets)]
                 if d not in seen]
        seen.extend(group)
        if group:
            groups.append(group)
    return groups


def checked_height_relief(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                          setup: Mapping[str, Any], teeth: KeptTeeth | None,
                          say: Callable[[str], None],
                          placed: Callable[[Mapping[str, float]], Case]
                          ) -> DevelopmentEvaluation:
    """A drive design whose light-load pattern is high on the flank and which carries
    plastic segments at the check (:func:`height_relief_applies`), and is not tolerant
    itself, given both reliefs and the bearing nearer the profile together: each design
    of :func:`height_relief_designs` placed and checked at ``ltca run``'s sampling
    (a synthesis of steps 3-6 where the path or ellipse changes) and kept where it ranks
    better (every target met first, then the objective), misses no target the design
    kept so far met and is no less tolerant than it (:func:`~contact.optimize.
    development_load_lte.no_less_tolerant`: every mounting excursion of both analysed);
    the first design that meets every target ends it; the next tip relief is tried only
    where its group kept nothing (at most 9 designs). A design the step does not apply
    to, or which is tolerant, is returned as it is (the check's own height steps judge
    it; a tolerant one after its excursions).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept (checked at ``ltca run``'s sampling).
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of the reliefs [µm, 1], of
        ``path_angle`` [deg] and ``ellipse_length`` [1]).
    setup : mapping
        The development's setup (``"torques"`` [N·m], light and design; ``"centre_v"``).
    teeth : KeptTeeth or None
        The kept pinion teeth of the development.
    say : callable
        Gets one line per design analysed and per design refused.
    placed : callable values → Case
        The synthesis with step 8 (the case as written).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (``best`` where none was), ``stage`` ``"height relief"``.

    Notes
    -----
    Why the check's height steps did not act: on the m_mn 12 industrial hypoid 11x43 of
    benchmarks/data/unseen_designs (ε_vβ 1.37; 2001 / 13340 N m; path −45°, ellipse 0.4,
    tip relief 43.1 µm from 0.65, root relief 15 µm from 0.45, profile crowning 28.8 µm,
    no blade-angle change) the light-load pattern runs 0.38-1.00 of the working depth
    (centre v 0.67 against 0.543 ± 0.08), 1.3 % of the design torque on the gear's tip
    edge, 0.9 % plastic, plastic at all four excursions (0.7-1.0 %). The blade step needs
    a blade-angle change; the tip step is barred by the edge share (1.3 % > half the
    limit); the root step's design (root relief 60 µm from 0.2: tip v 0.91, centre v 0.64,
    plastic 0.1 %) and its path turns (−60°: 0.0 %, LTE 32 / 40 µrad) were refused for
    plastic at one or two excursions, a design with plastic at all four kept instead.
    Measured at ``ltca run``'s sampling (``benchmarks/development_levers.py --check
    --tolerance --from-case``, 2026-11-27), root relief 60 µm from 0.2 with the tip
    relief 34.5 µm (0.8 of it) from 0.85: path −45°: centre v 0.60, plastic 0.0 %, LTE
    60 / 64 µrad, plastic at ΔE, ΔP +0.05 mm only; path −60°, ellipse 0.35: 42 / 48 µrad,
    tolerant; path −75°, ellipse 0.35: **every target met, tolerant**, centre v 0.60,
    pattern 0.60 long, LTE 24 / 29 µrad, edge 0.3 %, no plastic segment, flank peak 1234
    (1339) MPa. Stadtfeld, *Gleason Bevel Gear Technology* (2014): the pattern's height
    by the profile relief at the mating member's tip, its transmission error by the path.
    """
    if not height_relief_applies(best, targets, setup):
        return best
    own = tolerance_checks(best.case, targets, setup, teeth, best.values)
    if not any(short[k] > 0.0 for _, short in own.values() for k in TOLERANCE_KEYS):
        return best
    start = best
    for group in height_relief_designs(best.values, pattern_length(best), targets):
        for values in group:
            e = said_variant(start, values, "height relief",
                             f"with {changed_values(values, start.values)} (its pattern "
                             "high, plastic)", targets, setup, teeth, say, placed)
            if e is None:
                continue
            why, theirs = _refused(best, e, own, targets, setup, teeth)
            if why:
                say(f"  not kept: both reliefs {why}")
                continue
            best, own = e, theirs
            if e.met:
                return best
        if best is not start:
            break  # a shorter tip relief only where this one kept nothing
    return best


def _refused(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
             own: Mapping[str, tuple[dict, dict[str, float]]], targets: DevelopmentTargets,
             setup: Mapping[str, Any], teeth: KeptTeeth | None
             ) -> tuple[str, Mapping[str, tuple[dict, dict[str, float]]] | None]:
    """Why ``e`` does not replace ``best`` (whose excursions are ``own``), empty where it
    does (then with ``e``'s excursions): :func:`~contact.optimize.development_load_lte.
    replacement`'s reason in this step's words."""
    why, found = replacement(best, e, own, targets, setup, teeth)
    if why == "rank":
        return "score no better", None
    if why == "lost":
        return f"miss {', '.join(found)}", None
    if why == "tolerance":
        missed = sorted({k for _, s in found.values() for k in TOLERANCE_KEYS
                         if s[k] > 0.0})
        return f"are less tolerant (they miss {', '.join(missed)})", None
    return "", found
