"""The development's mounting tolerance: the drive flank at the mounting excursions ΔE,
ΔP (:func:`tolerance_checks`, :func:`_excursions`), whether a check step's design is
tolerant (:func:`tolerant_variant`), the chosen design made tolerant
(:func:`checked_tolerance`: its tip, then root relief raised; where that does not make
it tolerant, :func:`checked_tolerance_height`: a search on the pattern's height), the
written case's tolerance (:func:`final_tolerance`, reusing the step's excursions) and,
where the design written is still not tolerant, the torque up to which it is
(:func:`tolerant_torque`). The keep rule's questions are answered at as few excursions as
decide them (:func:`known_missed` asked first, :func:`exceeds` stopping
:func:`less_intolerant_variant`; issue 71, branch cpu90a). Split out of
:mod:`contact.optimize.development_check` (issue 71, Deliver 5), which re-exports every
public name; the bodies moved unchanged (the helper they share imported under the private
name they call).
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize import development_evaluate as evaluation
from contact.optimize.development_evaluate import KeptTeeth, bearing_key
from contact.optimize.development_result import (
    TOLERANCE_KEYS,
    DevelopmentEvaluation,
    floor_torque,
)
from contact.optimize.development_stages import footprint_centre_v
from contact.optimize.development_targets import (
    HEIGHT_NAME,
    METRIC_NAMES,
    DevelopmentTargets,
    development_score,
)
from contact.optimize.development_variant import said_variant as _said_variant
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted
from geometry.pair.assembly import Misalignment

#: the development's one logger, whichever of its modules logs
log = logging.getLogger("contact.optimize.development")


def tolerance_checks(case: Case, targets: DevelopmentTargets, setup: Mapping[str, Any],
                     teeth: KeptTeeth | None, values: Mapping[str, float], *,
                     until_missed: bool = False, first: tuple[str, ...] = (),
                     until_over: Mapping[str, float] | None = None
                     ) -> dict[str, tuple[dict[str, np.ndarray], dict[str, float]]]:
    """The drive flank of ``case`` at each mounting excursion (:func:`_excursions`,
    :data:`COARSE_LTCA` at the development's torques): per excursion label, its metrics
    and shortfalls (:func:`development_score`); an analysis that fails counts as missing
    :data:`TOLERANCE_KEYS` (logged, never raised). ``until_missed``: stop after the first
    excursion that misses one of :data:`TOLERANCE_KEYS` (the caller asks only whether
    the design is tolerant; the excursions after it are not in the result). ``first``:
    excursion labels analysed before the others (those a related design missed: with
    ``until_missed``, a design that misses them too costs one analysis; with
    ``until_over`` those already analysed are asked before them); the result is in
    :func:`_excursions`' order either way. ``until_over``: stop after the first excursion
    whose shortfall of a key of :data:`TOLERANCE_KEYS` is above this mapping's (or not
    finite): the caller asks only whether the design misses no more than these bounds
    (:func:`less_intolerant_variant`), which that excursion already answers.

    The excursions of every design are kept in ``setup`` (key ``"tolerance_memo"``, by
    the case object, the torques, the kept pinion tooth's key, the targets and the kept
    teeth): a design checked
    again (a check step's tolerant variant chosen, then the chosen design's tolerance,
    :func:`checked_tolerance`) is not analysed again — the same analyses, the same
    numbers."""
    memo = setup.setdefault("tolerance_memo", {}) if isinstance(setup, dict) else {}
    key = _memo_key(case, targets, setup, teeth, values)
    kept = memo.get(key)
    tolerance = dict(kept[1]) if kept is not None and kept[0] is case else {}
    # ``first`` first; with ``until_over`` those already analysed before them (free): its
    # answer does not depend on the order, only how many are analysed (``until_missed``'s
    # excursions missed steer the tolerance height search: its order kept)
    order = sorted(_excursions(targets),
                   key=lambda x: (until_over is not None and x[0] not in tolerance,
                                  x[0] not in first))  # stable
    for lab, mis in order:
        if lab not in tolerance:
            tolerance[lab] = _excursion(case, targets, setup, teeth, values, lab, mis)
        if until_missed and any(tolerance[lab][1][k] > 0.0 for k in TOLERANCE_KEYS):
            break
        if until_over is not None and exceeds(tolerance[lab][1], until_over):
            break
    memo[key] = (case, tolerance)  # the case held: its id is not reused while kept
    return {lab: tolerance[lab] for lab, _ in _excursions(targets) if lab in tolerance}


def _memo_key(case: Case, targets: DevelopmentTargets, setup: Mapping[str, Any],
              teeth: KeptTeeth | None, values: Mapping[str, float]) -> tuple:
    """A design's key in ``setup["tolerance_memo"]`` (:func:`tolerance_checks`): the case
    object, the torques [N·m], the kept pinion tooth's key, the targets and the kept
    teeth."""
    return (id(case), tuple(float(t) for t in setup["torques"]), bearing_key(values),
            repr(targets), id(teeth))


def _excursion(case: Case, targets: DevelopmentTargets, setup: Mapping[str, Any],
               teeth: KeptTeeth | None, values: Mapping[str, float], lab: str,
               mis: Misalignment) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """One excursion of :func:`tolerance_checks`: metrics and shortfalls. The excursion
    ``mis`` is taken from the case's own mounting (its ``[operating]`` misalignment, the
    nominal analysis' assembly), as the V-H check takes it (:mod:`contact.study.vh_check`:
    "the nominal mounting: the case's own"); before, it replaced that mounting, and the
    bundled 11x41 (ΔE −0.15, ΔP +0.12 mm in its basic file) was judged at ΔE ±0.05 mm
    from no misalignment — 0.1-0.2 mm from its own assembly, every excursion moving its
    light-load pattern 0.12-0.25 of the face to the toe (docs/own_gear_set.md, "The
    pattern's centre along the face")."""
    own = getattr(case, "misalignment", None)  # (a test's stand-in case has none)
    if own is not None:
        mis = own.plus(mis)
    try:
        ms, grid = evaluation.analyse_design(case, setup["torques"], mis, teeth=teeth,
                                             pinion_key=bearing_key(values))
        _, short, _ = development_score(ms, targets, grid[:4], centre_v=setup["centre_v"],
                                        pressure_limit=grid[4])
    except Exception as exc:  # reported, never fatal
        raise_if_interrupted(exc)
        log.info("development tolerance %s failed: %s", lab, exc)
        ms = {k: np.full(2, np.nan) for k in METRIC_NAMES}
        short = dict.fromkeys(TOLERANCE_KEYS, math.inf)
    return ms, short


def _missed_excursion(tolerance: Mapping[str, tuple[dict, dict[str, float]]],
                      say: Callable[[str], None]) -> list[str]:
    """The :data:`TOLERANCE_KEYS` missed at the excursions of ``tolerance``
    (:func:`tolerance_checks` with ``until_missed``), sorted; said as "not kept" at the
    first excursion (in :func:`_excursions`' order) that misses, where any."""
    missed = sorted({k for _, short in tolerance.values() for k in TOLERANCE_KEYS
                     if short[k] > 0.0})
    if missed:  # named: the first that misses (the last analysed in _excursions' order
        # where they were asked in that order; the one asked first may be another)
        where = next(lab for lab, (_, short) in tolerance.items()
                     if any(short[k] > 0.0 for k in TOLERANCE_KEYS))
        say(f"  not kept: at the mounting excursion {where} it misses "
            f"{', '.join(missed)}")
    return missed


def tolerant_variant(e: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None], *, first: tuple[str, ...] = ()) -> bool:
    """Whether a check step's design is tolerant (:func:`tolerance_checks`: clear of toe and
    heel, its edges elastic within their share at every mounting excursion); where not,
    says which it misses. A check step keeps a design only so: a bearing turned or
    relieved for its LTE or height must not lose the assembly's tolerance (the spiral bevel
    13x39 at path −80°, ellipse 0.75: LTE 12 / 39 µrad, every excursion but ΔE +0.05 mm
    elastic, 1.3 % of the design torque plastic there).

    Parameters
    ----------
    e : DevelopmentEvaluation
        The step's design, checked (its ``case`` and ``values`` [file units]).
    targets : DevelopmentTargets
        The development's targets (``offset_tolerance``, ``mounting_tolerance`` [mm]).
    setup : mapping
        The development's state (``torques`` [N·m], ``centre_v`` [1], the memos).
    teeth : KeptTeeth or None
        The kept pinion teeth.
    say : callable str → None
        Where the "not kept" line goes.
    first : tuple of str, optional
        Excursion labels asked first (:func:`known_missed` of the design ``e`` varies,
        the keep rule's): the answer is the same in any order, a variant that misses
        where its design does costs one analysis (issue 71, branch cpu90a).

    Returns
    -------
    bool
        Whether no excursion misses one of :data:`~contact.optimize.development_result.
        TOLERANCE_KEYS` (the excursions after the first that misses are not analysed).

    Notes
    -----
    Source: the issue-71 development's tolerance (docs/synthesis.md, "Development
    bearing"; ΔE, ΔP ± the targets' tolerances, as the V-H check of
    :mod:`contact.study.vh_check`).
    """
    tolerance = tolerance_checks(e.case, targets, setup, teeth, e.values, until_missed=True,
                                 first=first)
    return not _missed_excursion(tolerance, say)


def known_missed(d: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: Mapping[str, Any], teeth: KeptTeeth | None) -> tuple[str, ...]:
    """The mounting excursions at which a design is already known to miss a key of
    :data:`TOLERANCE_KEYS`: those :func:`tolerance_checks` analysed for it (kept in
    ``setup["tolerance_memo"]``), none analysed here.

    Parameters
    ----------
    d : DevelopmentEvaluation
        A design (its ``case`` and ``values`` [file units]).
    targets : DevelopmentTargets
        The development's targets (the excursions, ``offset_tolerance``,
        ``mounting_tolerance`` [mm]).
    setup : mapping
        The development's state (``torques`` [N·m], the memos).
    teeth : KeptTeeth or None
        The kept pinion teeth.

    Returns
    -------
    tuple of str
        The excursion labels (:func:`_excursions`' ``"dE+0.05"`` …) at which ``d`` misses
        a key, in their order; empty where none is known (not analysed, or tolerant).

    Notes
    -----
    Source: issue 71, branch cpu90a: a check step's variant misses where the design it
    varies misses, so the keep rule asks those excursions first (:func:`tolerant_variant`'s
    ``first``); whether it is tolerant does not depend on the order.
    """
    memo = setup.get("tolerance_memo", {}) if isinstance(setup, Mapping) else {}
    if d.case is None:
        return ()
    kept = memo.get(_memo_key(d.case, targets, setup, teeth, d.values))
    if kept is None or kept[0] is not d.case:
        return ()
    return tuple(lab for lab, _ in _excursions(targets) if lab in kept[1]
                 and any(kept[1][lab][1][k] > 0.0 for k in TOLERANCE_KEYS))


def worst_shortfalls(tolerance: Mapping[str, tuple[Mapping, Mapping[str, float]]]
                     ) -> dict[str, float]:
    """The worst shortfall of each of :data:`TOLERANCE_KEYS` over the mounting excursions
    of ``tolerance``.

    Parameters
    ----------
    tolerance : mapping label → (metrics, shortfalls)
        :func:`tolerance_checks` of one design (every excursion; shortfalls [1], as
        :func:`~contact.optimize.development_targets.development_score`'s, inf where an
        excursion's analysis failed).

    Returns
    -------
    dict str → float
        Per key of :data:`TOLERANCE_KEYS` (toe, heel, edge, plastic) its largest shortfall
        [1] over the excursions; 0 where none misses it (and where ``tolerance`` is empty).

    Notes
    -----
    Source: the issue-71 development's tolerance (docs/synthesis.md, "Development bearing";
    the excursions ΔE, ΔP ± the targets' tolerances).
    """
    return {k: max((float(short[k]) for _, short in tolerance.values()), default=0.0)
            for k in TOLERANCE_KEYS}


def exceeds(shortfalls: Mapping[str, float], bounds: Mapping[str, float]) -> bool:
    """Whether one excursion's shortfalls miss more than ``bounds`` on a key of
    :data:`TOLERANCE_KEYS`: a shortfall above its bound, or not finite (a failed analysis).

    Parameters
    ----------
    shortfalls : mapping str → float
        One excursion's shortfalls [1] (:func:`~contact.optimize.development_targets.
        development_score`'s; a key left out counts as inf).
    bounds : mapping str → float
        Per key the largest shortfall allowed [1] (a key left out allows 0).

    Returns
    -------
    bool
        True where :func:`no_more_intolerant` of ``bounds`` against any worst shortfalls
        that include this excursion's must be False (the worst is at least this one's).

    Notes
    -----
    Source: :func:`no_more_intolerant`'s comparison taken one excursion at a time (issue
    71, branch cpu90a: a check step's variant stops being analysed at its excursions once
    one of them decides that it is not less intolerant).
    """
    return any(not (math.isfinite(v := float(shortfalls.get(k, math.inf)))
                    and v <= float(bounds.get(k, 0.0))) for k in TOLERANCE_KEYS)


def no_more_intolerant(kept: Mapping[str, float], variant: Mapping[str, float]) -> bool:
    """Whether a variant not tolerant misses no more at the mounting excursions than the
    design kept, which is not tolerant either: the keep rule's second preference
    (:func:`less_intolerant_variant`; the first is a tolerant variant).

    Parameters
    ----------
    kept, variant : mapping str → float
        :func:`worst_shortfalls` of the design kept and of its variant (per key of
        :data:`TOLERANCE_KEYS`, [1]).

    Returns
    -------
    bool
        True where ``kept`` misses one of :data:`TOLERANCE_KEYS` (a shortfall > 0) and
        every shortfall of ``variant`` is finite and no larger than ``kept``'s; False
        where ``kept`` is tolerant (only a tolerant variant replaces it), where the
        variant misses a key more or one the kept design meets, or where its analysis
        failed (inf).

    Notes
    -----
    Source: round 29 (docs/own_gear_set.md, the spiral bevel 13x50 m_et 6 at 700 N m):
    the check step refused a variant of LTE 28 µrad without plastic as "not tolerant",
    keeping a design not tolerant either (edge 3.0 %, plastic 0.7 % at ΔE/ΔP ±0.05 mm);
    issue 71, branch tol89 (docs/synthesis.md, "The check step: a variant less intolerant
    than the kept design").
    """
    if not any(float(kept.get(k, 0.0)) > 0.0 for k in TOLERANCE_KEYS):
        return False
    return all(math.isfinite(float(variant.get(k, math.inf)))
               and float(variant.get(k, math.inf)) <= float(kept.get(k, 0.0))
               for k in TOLERANCE_KEYS)


def less_intolerant_variant(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
                            targets: DevelopmentTargets, setup: Mapping[str, Any],
                            teeth: KeptTeeth | None, say: Callable[[str], None]) -> bool:
    """Whether a check step's design ``e``, not tolerant (:func:`tolerant_variant`), may
    still replace ``best``: ``best`` is not tolerant either and ``e`` misses no more at
    any mounting excursion (:func:`no_more_intolerant` of their :func:`worst_shortfalls`).
    Asked by the keep rule (:func:`~contact.optimize.development_keep.kept_why`) only
    where ``e`` already ranks better on its nominal targets and gives up none ``best``
    met.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design kept so far (its ``case`` and ``values`` [file units]).
    e : DevelopmentEvaluation
        The step's design, checked, not tolerant.
    targets : DevelopmentTargets
        The development's targets (``offset_tolerance``, ``mounting_tolerance`` [mm]).
    setup : mapping
        The development's state (``torques`` [N·m], ``centre_v`` [1], the memos).
    teeth : KeptTeeth or None
        The kept pinion teeth.
    say : callable str → None
        Where the comparison's line goes.

    Returns
    -------
    bool
        Whether ``e`` replaces ``best`` though not tolerant. Costs at most every
        excursion of both designs not yet analysed (:func:`tolerance_checks` keeps them):
        none of ``e``'s where ``best`` is tolerant (only a tolerant variant replaces it),
        and ``e``'s only up to the first that misses more than ``best``'s worst
        (:func:`exceeds`; ``until_over``), which decides as all of them would: the same
        answer at fewer analyses (issue 71, branch cpu90a).

    Notes
    -----
    Source: round 29 (docs/own_gear_set.md; the scratch rule measured there); issue 71,
    branch tol89.
    """
    if best.case is None or e.case is None:
        return False
    kept = worst_shortfalls(tolerance_checks(best.case, targets, setup, teeth, best.values))
    if not any(kept[k] > 0.0 for k in TOLERANCE_KEYS):
        return False  # a tolerant kept design: no_more_intolerant is False whatever e's
    variant = worst_shortfalls(tolerance_checks(e.case, targets, setup, teeth, e.values,
                                                until_over=kept))
    if not no_more_intolerant(kept, variant):
        return False
    say("  kept though not tolerant: at the mounting excursions it misses no more than "
        "the design it replaces (worst shortfall "
        + ", ".join(f"{k} {variant[k]:.3g} <= {kept[k]:.3g}" for k in TOLERANCE_KEYS) + ")")
    return True


#: the tolerance step's reliefs (:func:`checked_tolerance`): the chosen design's tip, then
#: root relief raised by this factor, at least by :data:`TOLERANCE_RELIEF_STEP` µm
TOLERANCE_RELIEF = 1.5
#: the tolerance step's least raise of a relief [µm], × the targets' ``size_scale``
TOLERANCE_RELIEF_STEP = 5.0
#: the tolerance step's raises of a relief, as fractions of its full raise
#: (:data:`TOLERANCE_RELIEF`), tried largest first: a smaller one only where the larger
#: gives up a target the design met (the edge share falls as the relief rises, the
#: light-load pattern's centre and the LTE move with it)
TOLERANCE_RAISE_FRACTIONS = (1.0, 2.0 / 3.0, 1.0 / 3.0)


def checked_tolerance(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: dict[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case], *,
                      slope: float | None = None) -> DevelopmentEvaluation:
    """The chosen design made tolerant where it meets every target but not the mounting
    excursions' edges: where its drive flank at an excursion (:func:`tolerance_checks`)
    carries more than ``max_edge_share`` on the edges or has a plastic segment, the tip
    relief, then the root relief, raised by :data:`TOLERANCE_RELIEF` (at least
    :data:`TOLERANCE_RELIEF_STEP` µm, within its bound), each raise tried as the
    :data:`TOLERANCE_RAISE_FRACTIONS` of it, largest first, a smaller one only where the
    larger gives up a target the design met; each design placed and checked at
    :data:`CHECK_LTCA` and kept where it still meets every target and is tolerant
    (:func:`_tolerant_variant`), the first such (at most 6 designs; 4 excursions each
    that meets every target). Where none is kept, the pattern's height is searched for a
    tolerant window (:func:`checked_tolerance_height`; ``slope`` [1/deg]: the height
    stage's measured d(centre v)/d(blade angle) on the design's bearing, where known).
    ``setup["tolerance"]`` gets the excursions' result of the design
    returned, with its values and torques, for the final check to reuse.

    Why: the search stops at the first design meeting every target, so a design whose
    edge share at the design torque is just within its limit is kept, and the mounting
    excursions, checked only afterwards, load that edge beyond it. Measured on the hypoid
    12x37 at Σ 105° of tests/data/designs (90.87 / 605.8 N m, path −65.6°, ellipse 0.625,
    tip relief 15 µm from 0.85, root relief 25 µm from 0.2, ``ltca run``'s sampling): edge
    share 1.98 % at the design torque (limit 2 %), of which 1.5 % on the pinion's tip edge;
    at ΔE −0.05 mm 2.8 %, at ΔP −0.05 mm 2.4 % (not tolerant; 2026-11-26). The smaller
    raises: since the Sainsot base compliance held at its fit's range (phys71) the same
    12x37's chosen design (tip relief 15 µm, root relief 25 µm from 0.2, te_level 25; edge
    1.8 %, LTE 25 / 39 µrad) takes 2.4 % at ΔE −0.05 mm and 2.03 % at ΔP −0.05 mm; the tip
    relief 22.5 µm gives up the centre v (0.63 against 0.545 ± 0.08) and the LTE (41 / 40
    µrad), 20 µm the centre v (0.63), 17.5 µm meets every target (edge 1.2 %, LTE 25 / 38
    µrad) and is tolerant (edges 1.5 / 1.5 / 1.4 / 1.2 % at ΔE ± / ΔP ± 0.05 mm; the root
    relief 37.5 µm gives up the LTE, 29 / 48 µrad). The near-miss blade-angle step on the
    22.5 µm (−0.088°, te_level 10 µrad) brought the centre v to 0.59 but the LTE to 40 / 75
    µrad; blade steps of −0.03 / −0.05° without the TE change on 18.75 or 22.5 µm each gave
    up the pattern length or the LTE (2026-11-26, branch tol71b)."""
    if not best.checked_full or not best.met or best.case is None:
        return best
    tolerance = tolerance_checks(best.case, targets, setup, teeth, best.values)
    setup["tolerance"] = (dict(best.values), tuple(setup["torques"]), tolerance)
    if not any(short[k] > 0.0 for _, short in tolerance.values() for k in ("edge", "plastic")):
        return best
    missed = _missed_labels(tolerance)
    for name in ("tip_relief", "root_relief"):
        if name not in targets.variables or name not in best.values:
            continue
        lo, hi = targets.variables[name]
        x0 = float(best.values[name])
        x = float(np.clip(max(TOLERANCE_RELIEF * x0,
                              x0 + TOLERANCE_RELIEF_STEP * targets.size_scale), lo, hi))
        if x <= x0:
            continue
        for fraction in TOLERANCE_RAISE_FRACTIONS:
            xf = x0 + fraction * (x - x0)
            e = _said_variant(best, best.values | {name: xf}, "tolerance",
                              f"with {name} {xf:.3g} um (tolerance)", targets, setup,
                              teeth, say, placed)
            if e is None:
                break
            if not e.met:
                continue  # a smaller raise may keep the target this one gives up
            tolerance = tolerance_checks(e.case, targets, setup, teeth, e.values,
                                         until_missed=True, first=missed)
            if _missed_excursion(tolerance, say):
                break  # a smaller raise loads the edges more
            setup["tolerance"] = (dict(e.values), tuple(setup["torques"]), tolerance)
            return e
    return checked_tolerance_height(best, targets, setup, teeth, say, placed, slope=slope)


#: most designs of the tolerance step's search on the pattern's height
#: (:func:`checked_tolerance_height`), each a synthesis of steps 3-6 and 1-4 coarse
#: analyses at the excursions (a tolerant one also its check at :data:`CHECK_LTCA`)
TOLERANCE_HEIGHT_DESIGNS = 6
#: the height search's first step: the blade-angle change that moves the light-load
#: centre v by this fraction of ``centre_tolerance`` (at the height stage's measured slope
#: d(centre v)/d(blade angle), else :data:`~contact.optimize.development_stages.
#: HEIGHT_SLOPE`), towards the depth centre aimed at
TOLERANCE_HEIGHT_STEP = 0.25
#: [1 of the face per unit of ``ellipse_length``] the light-load pattern's length per unit
#: of the contact ellipse at M (:func:`checked_ellipse`: 0.9 measured), which sizes the
#: height search's shorter ellipse (:func:`_shorter_ellipse`)
LENGTH_PER_ELLIPSE = 0.9
#: the least shortening of the ellipse [1] of :func:`_shorter_ellipse`: one node of the
#: check's grid along the face (0.025 of it) over :data:`LENGTH_PER_ELLIPSE`, rounded down
SHORTER_ELLIPSE_STEP = 0.025


def _missed_labels(tolerance: Mapping[str, tuple[dict, dict[str, float]]]) -> tuple[str, ...]:
    """The excursion labels of ``tolerance`` (:func:`tolerance_checks`) that miss one of
    :data:`TOLERANCE_KEYS`."""
    return tuple(lab for lab, (_, short) in tolerance.items()
                 if any(short[k] > 0.0 for k in TOLERANCE_KEYS))


def _edge_load(ms: Mapping[str, np.ndarray]) -> float:
    """An excursion's load on the edges [1]: its largest plastic share plus its edge share
    at the design torque; inf where its analysis failed (NaN metrics)."""
    x = float(np.max(ms["plastic_share"])) + float(ms["edge_load_share"][-1])
    return x if math.isfinite(x) else math.inf


def _shorter_ellipse(e: DevelopmentEvaluation, targets: DevelopmentTargets
                     ) -> dict[str, float] | None:
    """The prescriptions of a checked design that misses the pattern length alone, too
    long, with the ellipse shortened by what takes the length back within its tolerance
    (the excess over :data:`LENGTH_PER_ELLIPSE`, at least :data:`SHORTER_ELLIPSE_STEP`,
    within the bounds of ``ellipse_length``); None where it misses another target, is
    short, or has no ellipse to shorten."""
    name = "ellipse_length"
    if (e.full is None or name not in targets.variables or name not in e.values
            or [k for k, v in e.full[1].items() if v > 0.0] != ["length"]):
        return None
    length = float(e.metrics["pattern_heel_u"][0] - e.metrics["pattern_toe_u"][0])
    excess = length - (targets.pattern_length + targets.pattern_length_tolerance)
    if not excess > 0.0:
        return None
    lo, _ = (float(x) for x in targets.variables[name])
    now = float(e.values[name])
    x = max(lo, now - max(SHORTER_ELLIPSE_STEP, excess / LENGTH_PER_ELLIPSE))
    return dict(e.values) | {name: x} if x < now - 1e-9 else None


def checked_tolerance_height(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                             setup: dict[str, Any], teeth: KeptTeeth | None,
                             say: Callable[[str], None],
                             placed: Callable[[Mapping[str, float]], Case], *,
                             slope: float | None = None) -> DevelopmentEvaluation:
    """The chosen design made tolerant by the pattern's height where the reliefs of
    :func:`checked_tolerance` did not: a bracketing search on the pinion's blade-angle
    change (:data:`~contact.optimize.development_targets.HEIGHT_NAME`) between the
    design's own (not tolerant) and a tolerant one.

    Applies where ``best`` was checked at :data:`CHECK_LTCA`, meets every target, carries a
    blade-angle change among its developed values and misses an edge or plastic target at
    a mounting excursion (:func:`tolerance_checks`; a pattern off the toe or heel is not
    the height's). The first design steps the blade angle by the change that moves the
    light-load centre v :data:`TOLERANCE_HEIGHT_STEP` of ``centre_tolerance`` towards the
    depth centre aimed at (``slope`` [1/deg]: the height stage's measured d(centre v)/d(blade
    angle) on the design's bearing, at least :data:`~contact.optimize.development_stages.
    HEIGHT_SLOPE_MIN`; else :data:`~contact.optimize.development_stages.HEIGHT_SLOPE`); where
    it is not tolerant and its excursions load the edges no less than the design's, the
    other way (once). Each design is placed as written and asked first for its tolerance
    (the excursions the last one missed first, until one misses): one not tolerant is the
    bracket's near end, and without a tolerant one yet the next step goes twice as far from
    the design's; a tolerant one is checked at :data:`CHECK_LTCA` and kept where it meets
    every target. A tolerant design that misses the pattern length alone, too long, is
    tried next with the ellipse shorter by as much (:func:`_shorter_ellipse`: less
    lengthwise crowning is the length's lever); where that is not kept either, the tolerant
    design is the bracket's far end and the next design halves the bracket (the least
    change that is tolerant gives up least). At most :data:`TOLERANCE_HEIGHT_DESIGNS`
    designs; ``setup["tolerance"]`` gets the excursions of the design kept. Returns the
    design kept, else ``best``.

    Why: the assembly's tolerance is the edges' at the excursion that moves the pattern
    towards one (Stadtfeld, *Gleason Bevel Gear Technology*, 2014: the pressure angle moves
    the pattern's height, the cutter radius its length), and the relief levers may be spent.
    Measured on the truck hypoid 13x43 at Σ 95° of benchmarks/data/unseen_designs (ISO
    capacity 379.3 / 2529 N m; its developed design path −58.75°, ellipse 0.55, tip relief
    24.6 µm from 0.89, root relief 39.1 µm from 0.25, no blade-angle change;
    ``benchmarks/development_levers.py --check --tolerance``, 2026-11-26): every target met,
    pattern 0.20-0.80 (length on its bound 0.6) but 0.6 % of the torque plastic at ΔE
    +0.05 mm; the tolerance step's tip reliefs 37 / 32.9 / 28.8 µm each gave up the pattern
    length (0.63), the root relief 58.6 µm was still plastic there. Blade angle −0.02 /
    −0.03 / −0.04°: 0.5 / 0.4 / 0.4 % plastic at ΔE +0.05 mm; from −0.050° tolerant, but the
    heel end a node further (0.63 long) from −0.051°: the window that meets every target is
    0.001° wide, and a bisection of six designs between −0.036° and −0.071° ended on its
    two sides (−0.0502°: plastic, −0.0513°: 0.63 long). With the ellipse 0.525 the
    tolerant −0.0536° and −0.0714° meet every target (LTE 35 / 37 and 35 / 39 µrad)."""
    from contact.optimize.development_stages import HEIGHT_SLOPE, HEIGHT_SLOPE_MIN

    if (not best.checked_full or not best.met or best.case is None
            or HEIGHT_NAME not in targets.variables or HEIGHT_NAME not in best.values
            or not math.isfinite(footprint_centre_v(best))):
        return best
    base = tolerance_checks(best.case, targets, setup, teeth, best.values)
    if not any(short[k] > 0.0 for _, short in base.values() for k in ("edge", "plastic")):
        return best
    lo, hi = (float(x) for x in targets.variables[HEIGHT_NAME])
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    v0, x0 = footprint_centre_v(best), float(best.values[HEIGHT_NAME])
    s = max(slope if slope is not None and math.isfinite(slope) else HEIGHT_SLOPE,
            HEIGHT_SLOPE_MIN)
    step = math.copysign(TOLERANCE_HEIGHT_STEP * targets.centre_tolerance / s, target - v0)
    first = _missed_labels(base)
    designs = 0

    def trial(values: dict[str, float], label: str
              ) -> tuple[tuple[str, ...], dict, DevelopmentEvaluation | None]:
        """One design placed, asked for its tolerance, and where tolerant checked: its
        missed excursion labels, its tolerance and its check (None where not checked)."""
        nonlocal designs, first
        designs += 1
        try:
            case = placed(values)
        except Exception as exc:  # reported, never fatal: the design stands
            raise_if_interrupted(exc)
            log.info("development tolerance height %s failed: %s", dict(values), exc)
            return ("failed",), {}, None
        tolerance = tolerance_checks(case, targets, setup, teeth, values,
                                     until_missed=True, first=first)
        missed = _missed_labels(tolerance)
        if missed:
            keys = sorted({k for lab in missed for k in TOLERANCE_KEYS
                           if tolerance[lab][1][k] > 0.0})
            say(f"  design {best.index + 1} {label}: at the mounting excursion "
                f"{', '.join(missed)} it misses {', '.join(keys)}")
            first = missed
            return missed, tolerance, None
        return (), tolerance, _said_variant(best, values, "tolerance", label, targets, setup,
                                            teeth, say, placed, case=case)

    near, far, flipped, tried = x0, None, False, []
    x = x0 + step
    while designs < TOLERANCE_HEIGHT_DESIGNS:
        x = float(np.clip(x, lo, hi))
        if abs(x - near) < 1e-4 or any(abs(x - t) < 1e-4 for t in tried):
            break  # a bound reached, or the bracket closed
        tried.append(x)
        values = dict(best.values) | {HEIGHT_NAME: x}
        missed, tolerance, e = trial(
            values, f"with {HEIGHT_NAME} {x:.3g} deg (tolerance: the pattern's height)")
        if missed == ("failed",):
            break
        if missed:
            heavier = all(lab not in base or _edge_load(tolerance[lab][0])
                          >= _edge_load(base[lab][0]) for lab in missed)
            if far is None and not flipped and near == x0 and heavier:
                flipped, step = True, -step  # the other way: this one loads them more
                x = x0 + step
                continue
            near = x
            x = x0 + 2.0 * (x - x0) if far is None else 0.5 * (near + far)
            continue
        if e is None:
            break
        if e.met:
            setup["tolerance"] = (dict(values), tuple(setup["torques"]), tolerance)
            return e
        shorter = _shorter_ellipse(e, targets)
        if shorter is not None and designs < TOLERANCE_HEIGHT_DESIGNS:
            missed, tolerance, e2 = trial(
                shorter, f"with {HEIGHT_NAME} {x:.3g} deg, ellipse_length "
                f"{shorter['ellipse_length']:.3g} (tolerance: the pattern's height, its "
                "length)")
            if not missed and e2 is not None and e2.met:
                setup["tolerance"] = (dict(shorter), tuple(setup["torques"]), tolerance)
                return e2
        far = x
        x = 0.5 * (near + far)
    return best


#: bisection steps of :func:`tolerant_torque` on the torque (geometric, between the light
#: and the design torque): the bracket's ends within (design / light)^(1/2^steps) of each
#: other, 3 % at the default light load 0.15
TOLERANT_TORQUE_STEPS = 6


def _edges_hold(ms: Mapping[str, np.ndarray], targets: DevelopmentTargets, i: int) -> bool:
    """Whether an excursion's metrics at torque index ``i`` keep the edges elastic and
    within their share (``max_plastic_share``, ``max_edge_share``); False where NaN."""
    plastic = float(np.asarray(ms["plastic_share"], float)[i])
    edge = float(np.asarray(ms["edge_load_share"], float)[i])
    return plastic <= targets.max_plastic_share and edge <= targets.max_edge_share


def tolerant_torque(case: Case, targets: DevelopmentTargets, setup: Mapping[str, Any],
                    teeth: KeptTeeth | None, values: Mapping[str, float],
                    tolerance: Mapping[str, tuple[dict[str, np.ndarray], dict[str, float]]]
                    ) -> tuple[float, float]:
    """The torque up to which a design not tolerant at its design torque is: the largest
    pinion torque at which its drive flank at every mounting excursion (:func:`_excursions`,
    from the case's own mounting, :data:`COARSE_LTCA` as :func:`tolerance_checks`) has no
    plastic segment beyond ``max_plastic_share`` and no more than ``max_edge_share`` on
    the edges.

    Parameters
    ----------
    case : Case
        The design written (its drive flank is the one checked).
    targets : DevelopmentTargets
    setup : mapping
        The development's; ``setup["torques"]`` the (light, design) torque [N·m].
    teeth : KeptTeeth or None
        The shell teeth kept (the pinion's under the design's :func:`bearing_key`).
    values : mapping
        The design's prescriptions (its pinion tooth's key).
    tolerance : mapping label → (metrics, shortfalls)
        :func:`tolerance_checks` of the design at ``setup["torques"]``.

    Returns
    -------
    (holds, fails) : (float, float) — [N·m]
        The largest torque found at which every excursion's edges hold (rounded down to
        0.1 N·m, :func:`~contact.optimize.development_result.floor_torque`) and the least
        at which one does not, from :data:`TOLERANT_TORQUE_STEPS` geometric bisections
        between the light torque (the tolerance check's own analysis there) and the design
        torque; (NaN, NaN) where the design misses no edge or plastic target at an
        excursion, or misses a clearance (toe, heel) there, which the torque does not
        mend; (NaN, light torque) where the edges fail at the light torque already.

    Notes
    -----
    What an engineer gets where no tolerant bearing exists at the design torque: the
    design torque is not cut (the rating's capacity, or the bearing's static and root
    capacity, stand), and the torque up to which the assembly's ΔE/ΔP tolerance holds is
    stated beside it, so that the choice between a lower torque and a tighter mounting
    tolerance is the engineer's (docs/synthesis.md, "Not tolerant at the design torque").
    Each step analyses, at the one torque, only the excursions missed at the design torque
    (the last one missed first, until one misses): the edges load monotonically with the
    torque (the edge's share and its pressure rise with the load), so an excursion that
    holds at the design torque holds below it, and the bracket holds. Measured on the
    truck hypoid 13x43 at Σ 95° of benchmarks/data/unseen_designs as its development
    wrote it before the height search (:func:`checked_tolerance_height`; 379.3 / 2529 N m,
    0.57 % plastic at ΔE +0.05 mm): at ΔE +0.05 mm edge 0.30 / 0.44 / 0.54 / 0.64 / 0.73
    % and plastic 0 / 0 / 0 / 0 / 0.46 % at 1500 / 1800 / 2000 / 2200 / 2400 N m, the
    other excursions elastic at each; the bisection: holds at 2245, not at 2312 N m."""
    light, design = (float(t) for t in setup["torques"])
    short = [s for _, s in tolerance.values()]
    if (not any(s[k] > 0.0 for s in short for k in ("edge", "plastic"))
            or any(s[k] > 0.0 for s in short for k in ("toe", "heel"))):
        return math.nan, math.nan
    if not all(_edges_hold(ms, targets, 0) for ms, _ in tolerance.values()):
        return math.nan, light
    own = getattr(case, "misalignment", None)
    # the excursions that hold at the design torque hold below it: only those missed
    missed = [(lab, mis) for lab, mis in _excursions(targets)
              if lab in _missed_labels(tolerance)]

    def holds(torque: float) -> bool:
        nonlocal missed
        for lab, mis in missed:
            try:
                ms, _ = evaluation.analyse_design(
                    case, [torque], mis if own is None else own.plus(mis), teeth=teeth,
                    pinion_key=bearing_key(values))
            except Exception as exc:  # reported, never fatal: counts as not holding
                raise_if_interrupted(exc)
                log.info("development tolerant torque %s at %.4g N m failed: %s", lab,
                         torque, exc)
                ms = None
            if ms is None or not _edges_hold(ms, targets, 0):
                missed = sorted(missed, key=lambda x: x[0] != lab)  # asked first next
                return False
        return True

    lo, hi = light, design
    for _ in range(TOLERANT_TORQUE_STEPS):
        mid = floor_torque(math.sqrt(lo * hi))
        if not lo < mid < hi:
            break
        if holds(mid):
            lo = mid
        else:
            hi = mid
    return lo, hi


def final_tolerance(case: Case, targets: DevelopmentTargets, setup: Mapping[str, Any],
                    teeth: KeptTeeth | None, values: Mapping[str, float]
                    ) -> dict[str, tuple[dict[str, np.ndarray], dict[str, float]]]:
    """The written case's tolerance (:func:`tolerance_checks`), reusing
    :func:`checked_tolerance`'s where the drive flank's values and the torques are those
    it analysed (the written case's drive flank is the placed design's, bit for bit)."""
    kept = setup.get("tolerance")
    if (kept is not None and kept[0] == dict(values)
            and kept[1] == tuple(setup["torques"])):
        return kept[2]
    return tolerance_checks(case, targets, setup, teeth, values)


def _excursions(t: DevelopmentTargets) -> list[tuple[str, Misalignment]]:
    out = []
    for s in (1.0, -1.0):
        if t.offset_tolerance > 0:
            out.append((f"dE{s * t.offset_tolerance:+g}",
                        Misalignment(delta_E=s * t.offset_tolerance)))
    for s in (1.0, -1.0):
        if t.mounting_tolerance > 0:
            out.append((f"dP{s * t.mounting_tolerance:+g}",
                        Misalignment(delta_P=s * t.mounting_tolerance)))
    return out
