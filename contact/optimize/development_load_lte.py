"""The design torque's LTE of a drive design that is not tolerant itself (issue 71): the
check's LTE levers judged against the design's own tolerance, not against a tolerance it
does not have.

The check's steps (:mod:`contact.optimize.development_check`) keep a design only where it
is tolerant at the mounting excursions (``kept_why``'s last rule). Where the design they
start from is not tolerant itself, every variant that leaves its excursions as they are is
refused on that rule, however much LTE it saves, and the development writes the design the
steps began with. :func:`checked_load_lte` tries the path turned towards the profile, the
ellipse with it (the bearing that lowers the design torque's LTE,
:func:`load_lte_designs`), and keeps a design where it ranks better, misses no target the
design met and is **no less tolerant** than it (:func:`no_less_tolerant`); the tolerance
step after the check (``checked_tolerance``) then works on the design kept.
:func:`checked_relief_ellipse_lte` gives a design whose design torque's LTE still exceeds
the verdict's 60 µrad a little less root relief with a longer ellipse
(:data:`RELIEF_ELLIPSE_FRACTIONS`), on the same rule.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_check import (
    ELLIPSE_STEP,
    PATH_STEPS,
    tolerance_checks,
)
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import lost_targets, verdict_lost
from contact.optimize.development_result import TOLERANCE_KEYS, DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import (
    changed_values,
    check_rank,
    pattern_length,
    said_variant,
)
from geometry.case import Case

log = logging.getLogger("contact.optimize.development")

#: [1] how much more of the design torque a variant may put on edges at a mounting
#: excursion than the design it replaces and still count as no less tolerant
#: (:func:`no_less_tolerant`): 0.1 % of the torque, the coarse LTCA's spread between
#: neighbouring bearings of one design (the 22x33's dP +0.05 mm: 2.3-2.4 % over five
#: bearings, docs/synthesis.md "The design torque's LTE where the design is not tolerant")
EDGE_SLACK = 0.001


#: the mounting-tolerance targets (:data:`~contact.optimize.development_result.
#: TOLERANCE_KEYS`) a design :func:`checked_load_lte` works on may miss: the edge share at
#: an excursion alone (elastic edges beyond their share). A design with plastic segments,
#: or its pattern on toe or heel, at an excursion is the tolerance step's, not an LTE
#: step's: on the spiral bevel 25x36 at Σ 75° the step took a second checked design with
#: 0.5 % plastic at ΔP +0.05 mm to 23 / 55 µrad, ranked it before the first (tolerant,
#: 21 / 58 µrad), and its flank peak 1857 MPa (local pitting limit 1662 MPa) lowered the
#: design torque 1003 → 738 N m (2026-11-27)
ELASTIC_MISSES = ("edge",)


def load_lte_designs(values: Mapping[str, float], length: float,
                     targets: DevelopmentTargets) -> list[dict[str, float]]:
    """The bearings :func:`checked_load_lte` tries for a design's prescriptions ``values``
    [file units] whose light-load pattern is ``length`` [1 of the face] long: the path
    angle turned towards the profile by each of :data:`~contact.optimize.
    development_check.PATH_STEPS`' turns (clipped to the bounds of ``path_angle``), the
    ellipse :data:`~contact.optimize.development_check.ELLIPSE_STEP` longer where the
    pattern has that much room below its length's upper tolerance and as much shorter
    where it has not (a turn lengthens the pattern: 0.60 → 0.65 on the m_mn 12 hypoid
    11x43), each within the bounds of ``ellipse_length``; duplicates and the design
    itself left out. Empty where the targets' variables or ``values`` carry no path or
    ellipse.

    Raises nothing; a pure function of its inputs."""
    names = ("path_angle", "ellipse_length")
    if not all(n in targets.variables and n in values for n in names):
        return []
    (p_lo, p_hi), (e_lo, e_hi) = ((float(a), float(b)) for a, b in
                                  (targets.variables[n] for n in names))
    longest = targets.pattern_length + targets.pattern_length_tolerance
    step = ELLIPSE_STEP if length + ELLIPSE_STEP <= longest + 1e-9 else -ELLIPSE_STEP
    now = {n: float(values[n]) for n in names}
    out: list[dict[str, float]] = []
    for turn, _ in PATH_STEPS:
        new = {"path_angle": float(np.clip(now["path_angle"] + turn, p_lo, p_hi)),
               "ellipse_length": round(float(np.clip(now["ellipse_length"] + step,
                                                     e_lo, e_hi)), 4)}
        if all(abs(new[n] - now[n]) < 1e-9 for n in names):
            continue
        design = dict(values) | new
        if design not in out:
            out.append(design)
    return out


def no_less_tolerant(before: Mapping[str, tuple[dict, dict[str, float]]],
                     after: Mapping[str, tuple[dict, dict[str, float]]],
                     slack: float = EDGE_SLACK) -> bool:
    """Whether a variant's mounting excursions ``after`` are no worse than those of the
    design it would replace, ``before`` (each :func:`~contact.optimize.development_check.
    tolerance_checks`' result, every excursion analysed): at every excursion the variant
    misses none of :data:`~contact.optimize.development_result.TOLERANCE_KEYS` the design
    met there, and at each excursion where it misses the edge share, its share of the
    design torque on edges is at most the design's + ``slack`` [1].

    Raises nothing; an excursion one of them lacks counts as missed by the variant."""
    for lab, (ms_b, short_b) in before.items():
        if lab not in after:
            return False
        ms_a, short_a = after[lab]
        for k in TOLERANCE_KEYS:
            if short_a[k] > 0.0 and not short_b[k] > 0.0:
                return False
        if short_a.get("edge", 0.0) > 0.0 and not (
                float(ms_a["edge_load_share"][-1])
                <= float(ms_b["edge_load_share"][-1]) + slack):
            return False
    return True


def _tolerance_missed(tolerance: Mapping[str, tuple[dict, dict[str, float]]]) -> list[str]:
    return [lab for lab, (_, short) in tolerance.items()
            if any(short[k] > 0.0 for k in TOLERANCE_KEYS)]


def checked_load_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case]
                     ) -> DevelopmentEvaluation:
    """A drive design that misses the development's LTE target (``targets.max_lte``) at the
    check, and no other target, and is not tolerant itself by its edge share at a mounting
    excursion alone (:data:`ELASTIC_MISSES`) given the bearing nearer the profile: each
    design of
    :func:`load_lte_designs` (a synthesis of steps 3-6, placed and checked at
    :data:`~contact.optimize.development_evaluate.CHECK_LTCA`; the check's path step
    tried the same bearings, so these are mostly its memo's) kept where it ranks better
    (every target met first, then the objective), raises the flank peak at the design
    torque no higher (the local pitting capacity is checked after the check), misses no
    target the design met and is no less tolerant than it (:func:`no_less_tolerant`:
    every mounting excursion of both analysed, :func:`~contact.optimize.
    development_check.tolerance_checks`); the first kept that meets every target ends it.
    A design that meets its LTE target, misses another, or is tolerant is returned as it
    is (the check's own steps judge it), a tolerant one after its mounting excursions
    (memoised: the tolerance step asks them again).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept (checked at ``ltca run``'s sampling).
    targets : DevelopmentTargets
        The development's targets (``variables``: the bounds of ``path_angle`` [deg] and
        ``ellipse_length`` [1]; ``max_lte`` [µrad]).
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
        The design kept (``best`` where none was), ``stage`` ``"load lte"``.

    Notes
    -----
    Why: the check's LTE steps (the path turned, the ellipse, the long bearing, the
    shallower relief) keep a design only where it is tolerant; a design not tolerant
    itself keeps its LTE whatever they find. Measured at ``ltca run``'s sampling
    (``benchmarks/development_levers.py --check --tolerance --from-case``, the cases
    ``ltca synthesize`` wrote before this step, 2026-11-27): the face-hobbed spiral bevel
    22x33 (ε_vβ 1.05; 76.5 / 510 N m; path −65.6°, ellipse 0.625) LTE 39 / 68 µrad, edge
    2.4 % at ΔP +0.05 mm; path −80°, ellipse 0.675: 17 / 39 µrad, every target met at the
    check, the same 2.4 % at ΔP +0.05 mm and nothing else missed. The m_mn 12 hypoid
    11x43 (ε_vβ 1.37; 2001 / 13340 N m; path −45°, ellipse 0.4; centre v, tip clearance,
    plastic 0.9 % missed) 58 / 63 µrad; path −75°, ellipse 0.35: 23 / 29 µrad, plastic
    0.7 %, no target lost. Stadtfeld, *Gleason Bevel Gear Technology* (2014): a path
    nearer the profile direction keeps more pairs in the transfer; the levers at the
    design torque are the bearing's length and bias, not the TE parabola (the 22x33:
    ``te_level`` 10 / 45 / 80 µrad gave 68 / 71 / 75 µrad at 510 N m).
    """
    if (not best.checked_full
            or best.case is None or best.full[1].get("lte", 0.0) == 0.0
            or any(v > 0.0 for k, v in best.full[1].items() if k != "lte")):
        return best
    own = tolerance_checks(best.case, targets, setup, teeth, best.values)
    missed = {k for _, short in own.values() for k in TOLERANCE_KEYS if short[k] > 0.0}
    if not missed or missed - set(ELASTIC_MISSES):
        return best
    length = pattern_length(best)
    for values in load_lte_designs(best.values, length, targets):
        e = said_variant(best, values, "load lte",
                         f"with {changed_values(values, best.values)} (its LTE missed, "
                         "not tolerant)", targets, setup, teeth, say, placed)
        if e is not None and not (float(e.metrics["pressure_max_flank"][-1])
                                  <= float(best.metrics["pressure_max_flank"][-1])):
            say("  not kept: the bearing nearer the profile raises the flank peak at the "
                "design torque")
            continue
        kept = _kept(best, e, own, targets, setup, teeth, say, "the bearing nearer the profile")
        if kept is not None:
            best, own = e, kept
            if e.met:
                break
    return best


def replacement(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                own: Mapping[str, tuple[dict, dict[str, float]]], targets: DevelopmentTargets,
                setup: Mapping[str, Any], teeth: KeptTeeth | None
                ) -> tuple[str, Any]:
    """Whether the checked variant ``e`` replaces the design ``best`` that is not tolerant
    itself (its mounting excursions ``own``): it ranks better
    (:func:`~contact.optimize.development_variant.check_rank`), misses no target ``best``
    met (:func:`~contact.optimize.development_keep.lost_targets`) and is no less tolerant
    (:func:`no_less_tolerant` of its own excursions,
    :func:`~contact.optimize.development_tolerance.tolerance_checks`); where ``best``'s
    LTE fails ``ltca run``'s verdict and ``e``'s does not
    (:func:`~contact.optimize.development_keep.verdict_lost`), it replaces it where it
    gives up no target but the pattern's length and centre, its tolerance not asked (the
    FAIL ranks below any softer miss).

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The design kept and its variant, both checked and scored.
    own : mapping
        ``best``'s excursions (:func:`tolerance_checks`: label → (metrics, shortfalls)).
    targets, setup, teeth
        The development's (as :func:`checked_load_lte`'s).

    Returns
    -------
    (str, object)
        ``("", e's excursions)`` where ``e`` replaces ``best``; else ``("rank", None)``,
        ``("lost", the targets lost)`` or ``("tolerance", e's excursions)``.

    Notes
    -----
    Source: the issue-71 development's keep rule for a design not tolerant itself
    (docs/synthesis.md, "The design torque's LTE where the design is not tolerant").
    """
    if not check_rank(e) < check_rank(best):
        return "rank", None
    fails = verdict_lost(best, e)  # ranked before it: e's LTE passes (check_rank)
    if fails:
        return "lost", fails
    if fails is not None:
        return "", tolerance_checks(e.case, targets, setup, teeth, e.values)
    if lost := lost_targets(best, e):
        return "lost", lost
    theirs = tolerance_checks(e.case, targets, setup, teeth, e.values)
    return ("" if no_less_tolerant(own, theirs) else "tolerance"), theirs


def _kept(best: DevelopmentEvaluation, e: DevelopmentEvaluation | None,
          own: Mapping[str, tuple[dict, dict[str, float]]], targets: DevelopmentTargets,
          setup: Mapping[str, Any], teeth: KeptTeeth | None, say: Callable[[str], None],
          what: str) -> dict | None:
    """The mounting excursions of ``e`` where it replaces ``best`` (:func:`replacement`),
    else None (the reason said)."""
    if e is None:
        return None
    why, found = replacement(best, e, own, targets, setup, teeth)
    if why == "lost":
        say(f"  not kept: {what} misses {', '.join(found)}")
    elif why == "tolerance":
        say(f"  not kept: {what} is less tolerant "
            f"(it misses {', '.join(_tolerance_missed(found))})")
    return None if why else found


#: the root relief of :func:`checked_relief_ellipse_lte`'s designs, as fractions of the
#: design's, tried in turn (each with the ellipse :data:`RELIEF_ELLIPSE_STEP`
#: longer): between the design's
#: and the check's shallower relief (× 1/2, 1/3, which load the edges where the pattern
#: is tall: the 25x36's 30 µm put 0.9 % of the design torque on plastic segments)
RELIEF_ELLIPSE_FRACTIONS = (5.0 / 6.0, 2.0 / 3.0)

#: [1] how much longer :func:`checked_relief_ellipse_lte`'s designs make the ellipse: half
#: the check's :data:`~contact.optimize.development_check.ELLIPSE_STEP`, one node of the
#: check's grid along the face (the 25x36 at Σ 75°: ellipse 0.675 / 0.7 / 0.725 → light-load
#: pattern 0.57 / 0.57 / 0.62 long, the last beyond the length's tolerance 0.5 ± 0.1)
RELIEF_ELLIPSE_STEP = 0.025


def checked_relief_ellipse_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                               setup: Mapping[str, Any], teeth: KeptTeeth | None,
                               say: Callable[[str], None],
                               placed: Callable[[Mapping[str, float]], Case], *,
                               lte_limit: float | None = None) -> DevelopmentEvaluation:
    """A drive design whose LTE p-p at the design torque still exceeds the verdict's limit
    (and its light torque's) after the check's steps given a little less root relief and
    a longer ellipse together: the root relief × each of :data:`RELIEF_ELLIPSE_FRACTIONS`
    (its start kept, within its bounds) with the ellipse :data:`RELIEF_ELLIPSE_STEP`
    longer (within its bounds; a synthesis of steps 3-6), each placed and checked at
    ``ltca run``'s sampling and kept where it ranks better, misses no target the design
    met (the pattern length included) and is no less tolerant than it
    (:func:`no_less_tolerant`; for a tolerant design: tolerant); at most two designs.
    ``lte_limit`` [µrad]: the verdict's ``lte`` limit (default
    :data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad). A design within it, whose light
    torque's LTE is the larger, that misses another target at the check, or without a
    root relief, is returned as it is without an analysis; one with plastic segments or
    its pattern on toe or heel at a mounting excursion (:data:`ELASTIC_MISSES`) after its
    excursions.

    Parameters and returns as :func:`checked_load_lte`.

    Notes
    -----
    Why: a root relief deeper than the teeth deflect at the design torque keeps the next
    pair off its load at the transfer (docs/synthesis.md, "Where the contact ratios are
    low"); the check's shallower-relief step halves it, which on a tall pattern puts the
    gear's tip on the pinion's root, and its longer-ellipse steps keep the relief. Measured
    at ``ltca run``'s sampling on the spiral bevel 25x36 at Σ 75° of
    benchmarks/data/unseen_designs (ε_vα 1.24, ε_vβ 1.15; 150.4 / 1003 N m; path −80°,
    ellipse 0.675, root relief 60 µm from 0.2, ``te_level`` 45 µrad;
    ``benchmarks/development_levers.py --check --tolerance --from-case``, 2026-11-27; LTE
    p-p light / design): 21 / 61 µrad, tolerant; root relief 50 µm: 22 / 61, tolerant;
    45: 22 / 56, 0.2 % plastic at ΔP +0.05 mm; 30: 24 / 53 but 0.9 % plastic at the design
    torque; the ellipse 0.725: 20 / 56, pattern 0.62 long; root relief 50 µm with the
    ellipse 0.7: 21 / 58, tolerant, every other target met; ``te_level`` 10 / 80 / 120
    µrad: 25 / 77, 24 / 68, 30 / 73."""
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if lte_limit is None else float(lte_limit)
    name = "root_relief"
    if (not best.checked_full or best.case is None
            or name not in targets.variables or not float(best.values.get(name, 0.0)) > 0.0
            or any(v > 0.0 for k, v in best.full[1].items() if k != "lte")):
        return best
    light, design = (float(x) for x in np.asarray(best.metrics["lte_peak_to_peak"])[[0, -1]])
    if not (design > limit and design > light):
        return best
    lo, hi = (float(x) for x in targets.variables[name])
    now = float(best.values[name])
    longer = {}
    if "ellipse_length" in targets.variables and "ellipse_length" in best.values:
        e_lo, e_hi = (float(x) for x in targets.variables["ellipse_length"])
        longer = {"ellipse_length": round(float(np.clip(
            float(best.values["ellipse_length"]) + RELIEF_ELLIPSE_STEP, e_lo, e_hi)), 4)}
    own = tolerance_checks(best.case, targets, setup, teeth, best.values)
    if {k for _, short in own.values() for k in TOLERANCE_KEYS
            if short[k] > 0.0} - set(ELASTIC_MISSES):
        return best
    start = best
    for fraction in RELIEF_ELLIPSE_FRACTIONS:
        values = dict(start.values) | longer | {name: float(np.clip(fraction * now, lo, hi))}
        if values == best.values:
            continue
        e = said_variant(best, values, "load lte",
                         f"with {changed_values(values, best.values)} (its LTE above "
                         f"{limit:g} urad at the design torque)", targets, setup, teeth, say,
                         placed)
        kept = _kept(best, e, own, targets, setup, teeth, say,
                     "the shallower relief with the longer ellipse")
        if kept is not None:
            best, own = e, kept
    return best
