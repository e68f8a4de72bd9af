"""The design torque no higher than where the written drive design keeps its LTE within
the verdict's limit at every torque (issue 71: "LTE p-p ≤ 60 µrad at every torque").

:func:`~contact.optimize.development_lte_capacity.lte_capacity` lowers the design torque
to where the chosen bearing keeps 60 µrad only where its LTE *FAILs* ``ltca run``'s
verdict (above 2 × 60 µrad), and only before the check's last steps: the tolerance step,
the light-edge relief (:mod:`~contact.optimize.development_light_edge_relief`), the edge
peak and the hollow-profile target step, each of which may raise the LTE of the design
written. Measured (2026-11-28, branch lte87): the FM spiral bevel 14x36 at Σ 70° of
benchmarks/data/unseen_designs (ε_vβ 1.16) was written at its ISO capacity with drive LTE
p-p 49 / 84 µrad at 55.6 / 371.2 N m and 60.3 / 71.2 between: the verdict's attention,
below its FAIL level, so the rule never acted; the 19x26 at Σ 80° (144 µrad at its ISO
capacity) was lowered by it.

:func:`written_lte_capacity` applies the same rule to the written design after the drive
development's last step that can raise its LTE, at the verdict's limit itself: where its
LTE p-p over ``ltca run``'s ``lte_range`` torques
(:func:`~contact.optimize.development_range_lte.range_lte`, the crossing bisected) exceeds
60 µrad, the design torque is lowered to the torque up to which it keeps it
(:func:`~contact.study.lte_within.within_torque`, linear between the torques analysed),
and kept there only where the same range at the lowered light and design torque keeps the
limit at every torque. The bearing is not changed (no step runs again: a step could raise
the LTE once more). Where no lowered torque keeps it with that bearing (its LTE falls from
the unloaded TE at light load, and a lower design torque's light torque is lower too), the
window it keeps the limit in is recorded and :func:`redeveloped_in_window` develops the
drive again at its upper end, kept where that development keeps the limit (the 14x36:
211.7 N m, 46.8 / 50.1 µrad); where the bearing developed there breaks the limit, at the
window's geometric middle below it, at most twice (the 17x23: 926.9 and 638.9 N m missed,
530.5 N m kept; branch lowratio95); where the written bearing broke the limit at its own
light torque already, straight at that middle, the upper end not developed
(:func:`light_end_missed`, branch cpu101). A design torque the basic file gives is kept. That
re-development is stopped after its drive steps where its check's own LTE record over
``ltca run``'s range exceeds the limit already (:class:`WindowMissed`,
:func:`window_missed`): it could not be kept, so its coast flank, FE root checks and
case are not made (issue 71, branch cpu90b). After a capacity cut the rule runs again at
the cut torques (``development._lte_after_cut``) and, where it records such a window there,
the drive is developed again at its upper end as before the cut, kept only where the
re-developed bearing's own root-stress and local pitting capacity hold at that torque
(``development._redeveloped_after_cut``, branch diag93).

Public names
------------
written_lte_capacity, lowered_torque, lte_window, redeveloped_in_window, window_name,
window_missed, WindowMissed, judged_where, WINDOW_STRAIGHT_TO_MIDDLE, light_end_missed
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from contact.optimize import development_evaluate as evaluation
from contact.optimize.development_evaluate import CHECK_LTCA, KeptTeeth, bearing_key
from contact.optimize.development_range_lte import (
    development_lte_limit,
    range_lte,
    verdict_lte_limit,
)
from contact.optimize.development_result import (
    DevelopmentEvaluation,
    case_torques,
    floor_torque,
    scored,
)
from contact.optimize.development_targets import DevelopmentTargets
from contact.study.lte_within import within_torque
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number

__all__ = ["WINDOW_STRAIGHT_TO_MIDDLE", "WindowMissed", "given_torque_of", "judged_where",
           "light_end_missed", "lowered_torque", "lte_window", "redeveloped_in_window",
           "window_missed", "window_name", "written_lte_capacity"]

log = logging.getLogger("contact.optimize.development")

#: lowered design torques analysed at most (each one's range adds its torques to those the
#: crossing is interpolated between: the LTE of a localised bearing is no smooth function
#: of the torque)
_TRIES = 3

#: the share of the FAIL level each further try of :func:`_below_fail_level` aims lower
#: (1, 0.95, 0.9 × 120 µrad; a lowered torque is kept where its range keeps 120 itself)
_FAIL_AIM_STEP = 0.05


def lowered_torque(torques: Sequence[float], lte: Sequence[float], limit: float,
                   design: float) -> float:
    """The design torque [N·m] the written case may carry where its LTE p-p exceeds
    ``limit`` at a torque up to ``design``: the crossing rounded down as a case writes it.

    Parameters
    ----------
    torques : sequence of float, shape (n,) — [N·m]
        The torques analysed, ascending (any number ≥ 1).
    lte : sequence of float, shape (n,) — [µrad]
        The LTE p-p at each.
    limit : float — [µrad]
        The verdict's limit (:data:`contact.study.verdicts.LTE_LIMIT`).
    design : float — [N·m]
        The design torque now.

    Returns
    -------
    float — [N·m]
        :func:`~contact.pipeline.floor_torque` of the first crossing of ``limit`` from below
        (:func:`~contact.study.lte_within.within_torque`); NaN where the LTE keeps the limit
        at every torque up to ``design``, exceeds it at the first torque already, a value is
        not finite, or the crossing rounds to ``design`` or above.

    Raises
    ------
    ValueError
        ``torques`` and ``lte`` of different lengths, or empty.

    Notes
    -----
    Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque"); the rule of
    :func:`~contact.optimize.development_lte_capacity.lte_capacity` (the 16x16 at Σ 60°).
    """
    t = np.asarray(torques, float)
    y = np.asarray(lte, float)
    if t.shape != y.shape or t.size == 0:
        raise ValueError(f"lowered_torque: {t.size} torques and {y.size} LTE values")
    up = t <= design
    if not np.any(y[up] > limit):
        return math.nan
    within = within_torque(t[up], y[up], limit)
    if not (math.isfinite(within) and within > 0):
        return math.nan
    new = floor_torque(within)
    return new if new < design else math.nan


def written_lte_capacity(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                         setup: dict[str, Any], teeth: KeptTeeth | None,
                         say: Callable[[str], None]) -> DevelopmentEvaluation:
    """The written drive design at a design torque no higher than where its LTE p-p keeps
    the verdict's limit at every torque ``ltca run`` judges.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The drive design after the development's last drive step (checked at
        :data:`CHECK_LTCA`, its ``metrics`` at ``setup["torques"]``, its ``case``).
    targets : DevelopmentTargets
        Its ``light_load`` [1] sets the light torque of a lowered design torque.
    setup : dict
        The development's setup: ``torques`` [N·m] (light, design), ``source``,
        ``centre_v``; updated (``torques``, ``source``, ``lowered``, ``lte_torque`` [N·m]:
        the lowered design torque) where the torque is
        lowered, its ``source`` extended by the LTE found where no lower torque keeps the
        limit (:func:`lte_window`).
    teeth : KeptTeeth or None
        The shell teeth kept across the development's designs.
    say : callable (str) → None
        Where the step's line goes.

    Returns
    -------
    DevelopmentEvaluation
        ``best`` where it has no case or checked LTE, its LTE keeps the limit over the
        range, no torque below keeps it (the light torque's above it already) or no lowered
        torque tried keeps it over its own range; else ``best`` scored at the lowered light
        and design torques [N·m] (:func:`~contact.pipeline.case_torques`).

    Raises
    ------
    Nothing: an analysis that fails leaves ``best`` as it is
    (:func:`~contact.optimize.development_range_lte.range_lte` logs it).

    Notes
    -----
    Source: ``ltca run``'s verdict (the ``lte`` check, 60 µrad at the light and the design
    torque and its ``lte_range`` torques between) and issue 71's Done-when. Measured on the
    FM spiral bevel 14x36 at Σ 70° (docs/synthesis.md, "The design torque where the
    written design keeps its LTE"). Each lowered torque is analysed at its own light torque
    and range; where that range still exceeds the limit its torques join those the crossing
    is interpolated between (at most :data:`_TRIES` lowered torques).
    """
    limit = development_lte_limit()
    found = range_lte(best, setup, teeth)
    if found is None:
        return best
    if not max(found[1]) > limit:  # keeps the limit at every torque: as it is
        return best
    design = float(setup["torques"][1])
    seen = dict(zip(found[0], found[1], strict=True))
    before = _curve(found)
    tried: list[str] = []
    for _ in range(_TRIES):
        ts = sorted(seen)
        new = lowered_torque(ts, [seen[t] for t in ts], limit, design)
        if not math.isfinite(new):
            break
        at = _written_at(best, targets, setup, teeth, new)
        if at is None:  # a failed analysis keeps the design as it is (logged)
            return best
        lowered, torques, there = at
        if max(there[1]) <= limit:
            source = (f"the torque up to which the written bearing keeps the drive LTE "
                      f"within {limit:g} urad at every torque: at "
                      f"{_rated_as(setup)} "
                      f"{plain_number(design)} N m its LTE p-p was {before} after the "
                      f"drive steps; {_curve(there)} at the lowered torques")
            setup.update(torques=list(torques), source=source, lowered=True,
                         lte_torque=float(torques[1]))
            say(f"  design torque {plain_number(design)} -> {plain_number(torques[1])} N m: "
                f"{source}")
            return lowered
        tried.append(f"at {plain_number(torques[1])} N m {_curve(there)}")
        seen.update(zip(there[0], there[1], strict=True))
        if there[1][0] > limit:  # the lowered light torque above the limit already
            break
    ts = sorted(seen)
    low, high = lte_window(ts, [seen[t] for t in ts], limit)
    if not (math.isfinite(low) and math.isfinite(high) and high < design):
        kept = _below_fail_level(best, targets, setup, teeth, say, seen, before)
        if kept is not None:
            return kept
    window = ""
    if math.isfinite(low) and math.isfinite(high):
        window = (f"; it keeps {limit:g} urad from about {plain_number(round(low, 1))} to "
                  f"{plain_number(round(high, 1))} N m only, and a design torque's light "
                  f"torque is {targets.light_load:g} of it")
    say(f"  the written drive LTE p-p {before}: no design torque below "
        f"{plain_number(design)} N m found where it keeps {limit:g} urad at every torque"
        + (f" (tried {'; '.join(tried)})" if tried else "") + window)
    setup["source"] = (f"{setup['source']}; the written bearing keeps the drive LTE within "
                       f"{limit:g} urad at no lower design torque ({before}{window})")
    if math.isfinite(low) and math.isfinite(high) and high < design:
        setup["lte_window"] = (low, high, before)
        lightest = int(np.argmin(found[0]))
        setup["lte_window_light"] = (float(found[0][lightest]), float(found[1][lightest]))
    return best


def _written_at(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                setup: dict[str, Any], teeth: KeptTeeth | None, torque: float
                ) -> tuple[DevelopmentEvaluation, tuple[float, float],
                           tuple[tuple[float, ...], tuple[float, ...]]] | None:
    """The written drive design ``best`` at the design torque ``torque`` [N·m] (its light
    torque the targets' share of it): analysed at ``ltca run``'s sampling, scored, and
    its LTE p-p over ``ltca run``'s range
    (:func:`~contact.optimize.development_range_lte.range_lte`). Returns (the design
    scored there, its (light, design) torques [N·m], the range's (torques [N·m], LTE p-p
    [µrad])); None where an analysis fails (logged)."""
    torques = case_torques(targets.light_load, torque)
    try:
        ms, grid = evaluation.analyse_design(best.case, torques, options=CHECK_LTCA,
                                             teeth=teeth, pinion_key=bearing_key(best.values))
    except Exception as exc:
        raise_if_interrupted(exc)
        log.info("development: the written design at %.4g N m not analysed: %s",
                 torques[1], exc)
        return None
    lowered = scored(best, ms, grid, targets, setup["centre_v"])
    there = range_lte(lowered, {**setup, "torques": list(torques)}, teeth)
    return None if there is None else (lowered, torques, there)


def _below_fail_level(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: dict[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None], seen: dict[float, float],
                      before: str) -> DevelopmentEvaluation | None:
    """The written design at the torque up to which its drive LTE p-p keeps ``ltca run``'s
    FAIL level (:data:`contact.study.verdicts.LTE_FAIL_FACTOR` × the limit) where no lower
    design torque keeps the limit itself and no window to develop in was found
    (:func:`written_lte_capacity`'s last resort).

    Parameters
    ----------
    best, targets, setup, teeth, say
        As :func:`written_lte_capacity` (``setup`` updated where the torque is lowered).
    seen : dict of float → float — {[N·m]: [µrad]}
        The LTE p-p at each torque analysed so far (extended here).
    before : str
        The written LTE at the design torque as given, in words.

    Returns
    -------
    DevelopmentEvaluation or None
        ``best`` scored at the lowered light and design torques where its LTE p-p exceeds
        the FAIL level at a torque up to the design torque and the lowered torque's own
        range keeps it; None where it keeps the FAIL level already, no crossing is found,
        an analysis fails or the lowered range exceeds it too.

    Notes
    -----
    Issue 71 (round 33, the FM spiral bevel miter 18x18 of benchmarks/data/unseen_designs):
    its written bearing had 60.1 / 112.7 µrad at 97.8 / 652 N m (its ISO capacity) and
    121.7 between, above 2 × 60: ``ltca run`` FAILed the design torque ``ltca synthesize``
    wrote, while no lower design torque kept 60 µrad (its light-load LTE at the limit
    already). Below the FAIL level the verdict says ATTENTION with the LTE's numbers; a
    design torque where the written case FAILs its own run is none a user can take.
    """
    from contact.study.verdicts import LTE_FAIL_FACTOR

    limit = development_lte_limit()
    fail = LTE_FAIL_FACTOR * verdict_lte_limit()
    design = float(setup["torques"][1])
    lowered = there = None
    tried: list[str] = []
    for k in range(_TRIES):
        ts = sorted(seen)
        # aimed a step lower on each try: the LTE of a localised bearing rises and flattens
        # towards its peak, so a straight line between two torques crosses the level below
        # the torque the bearing does (the miter 18x18: 122.2 µrad at the first crossing)
        aim = fail * (1.0 - _FAIL_AIM_STEP * k)
        new = lowered_torque(ts, [seen[t] for t in ts], aim, design)
        if not math.isfinite(new):
            return None
        at = _written_at(best, targets, setup, teeth, new)
        if at is None:
            return None
        lowered, torques, there = at
        seen.update(zip(there[0], there[1], strict=True))
        if max(there[1]) <= fail:
            break
        tried.append(f"at {plain_number(torques[1])} N m {_curve(there)}")
        if there[1][0] > fail:  # the lowered light torque above the FAIL level already
            break
    else:
        there = None
    if there is None or lowered is None or max(there[1]) > fail:
        say(f"  the written drive LTE p-p above ltca run's FAIL level {fail:g} urad: no "
            f"lower design torque found where it keeps it (tried {'; '.join(tried)})")
        return None
    source = (f"the torque up to which the written bearing keeps the drive LTE within "
              f"ltca run's FAIL level {fail:g} urad ({LTE_FAIL_FACTOR:g} x {limit:g}) at "
              f"every torque; no lower design torque keeps {limit:g} urad: at "
              f"{_rated_as(setup)} {plain_number(design)} N m its LTE p-p was {before} "
              f"after the drive steps; {_curve(there)} at the lowered torques (above "
              f"{limit:g} urad: ltca run's attention)")
    setup.update(torques=list(torques), source=source, lowered=True,
                 lte_torque=float(torques[1]))
    say(f"  design torque {plain_number(design)} -> {plain_number(torques[1])} N m: {source}")
    return lowered


def redeveloped_in_window(run: Callable[..., Any], setup: dict[str, Any], basic: Any,
                          say: Callable[[str], None], middle: bool = False,
                          straight: bool | None = None) -> Any:
    """The drive development run again at the upper end of the torque window its written
    bearing kept the verdict's LTE limit in (:func:`written_lte_capacity` records it where
    no lowered torque kept it with that bearing), kept where its own written design keeps
    the limit at every torque ``ltca run`` judges.

    Parameters
    ----------
    run : callable (float) → DevelopmentResult
        The development of the same basic data at a given design torque [N·m] (the
        drive search, the check and its steps, the coast flank and the case, at that
        torque's light and design torque).
    setup : dict
        The development's setup; its ``"lte_window"`` (low, high [N·m], the LTE text)
        where :func:`written_lte_capacity` found no lower torque.
    basic : BasicDesign
        The basic data as given (the result's ``basic``: no design torque of its own).
    say : callable (str) → None
        Where the step's lines go.
    middle : bool, optional
        Default False: one development, at the window's upper end. True (the window
        before any capacity cut, ``development._at_written_lte``): where the bearing
        developed there breaks the limit (stopped by :class:`WindowMissed`, or its LTE
        above the limit: not a failed run), the drive is developed again at
        ``floor_torque(√(low · T))`` below that torque ``T``, at most
        :data:`WINDOW_LOWER_STEPS` times, each below the last one missed and only where
        it is at least :data:`WINDOW_LOWER_STEP` × lower; ``run`` is then given
        ``torque_name`` (:func:`window_name` with ``middle``).
    straight : bool or None, optional
        With ``middle`` only: True develops the drive first at the window's geometric
        middle ``floor_torque(√(low · floor_torque(high)))``, not at its upper end (then
        at the middles below it as above, at most :data:`WINDOW_LOWER_STEPS`
        developments in all); where that middle is within :data:`WINDOW_LOWER_STEP` of
        the upper end, at the upper end as with False. Default None:
        :data:`WINDOW_STRAIGHT_TO_MIDDLE`, and where that is None (its default) the rule
        :func:`light_end_missed`: straight where the written bearing's LTE p-p at its own
        light torque broke the limit already (``setup["lte_window_light"]``).

    Returns
    -------
    DevelopmentResult or None
        The development at ``floor_torque(high)`` — or, with ``middle``, at the first
        middle below it whose bearing keeps the limit — (its design torque raised back towards
        ``setup["torques"][1]`` where its bearing carries more: ``run`` is given it as
        ``raise_to``, :func:`contact.optimize.development.develop`), its design torque the
        development's own
        (``torque_lowered``, ``lte_torque`` that torque, ``torque_source`` saying why,
        ``basic`` its written prescriptions at the design torque as given,
        :func:`given_torque_of`), where its
        drive LTE p-p at the light and design torque and between them (its
        ``lte_range``; where no check judged its written design between the torques and
        its two ends keep the limit, that range analysed here: ``range_lte`` on its
        drive design) keeps the limit; None where no window was recorded, the run fails
        or its LTE does not keep the limit.

    Raises
    ------
    Nothing the run raises but an interrupt (a failed run keeps the first development; a
    run stopped by :class:`WindowMissed` after its drive steps is one whose LTE does not
    keep the limit).

    Notes
    -----
    Why the middles (branch lowratio95): the FM spiral bevel 17x23 of
    benchmarks/data/unseen_designs (ε_vβ 0.93) kept 60 µrad with its written bearing from
    about 440.5 to 926.9 N m only; developed at 926.9 N m it read 72.1 / 77.6 µrad and the
    design was written at its ISO capacity 1537 N m with 96 µrad, though the same basic
    data developed at 530.5 N m keep 60 µrad at every torque (docs/synthesis.md, "The LTE
    window developed again below its upper end"). The LTE of a bearing developed at a
    lower design torque carries less load-induced deflection: a lower torque in the
    window, bisected geometrically as :func:`~contact.optimize.development._window_raised`
    bisects its raise back, which then raises the torque kept as far as the bearing's
    own LTE allows.

    Measured (docs/synthesis.md, "The design torque where the written design keeps its
    LTE"): the 14x36 at Σ 70°'s written bearing keeps 60 µrad from 36.4 to 212.1 N m only
    (its LTE falls from the unloaded TE's 70 µrad at light load), narrower than the light
    torque's 0.15 of a design torque; developed at 212.1 N m it wrote 47 / 50 µrad at 31.8 /
    212.1 N m, 28.4 between. Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque").
    """
    window = setup.get("lte_window")
    if window is None:
        return None
    low, high, _ = window
    limit = development_lte_limit()
    torque = floor_torque(high)
    if straight is None:
        straight = WINDOW_STRAIGHT_TO_MIDDLE
    if straight is None:
        straight = light_end_missed(setup)
    first = floor_torque(math.sqrt(low * torque)) if middle and straight else math.nan
    if math.isfinite(first) and first * WINDOW_LOWER_STEP <= torque:
        return _straight_to_middle(run, setup, basic, say, first)
    say(f"development: the written drive bearing keeps {limit:g} urad from about "
        f"{plain_number(round(low, 1))} to {plain_number(round(high, 1))} N m only; the drive "
        f"developed again at {plain_number(torque)} N m")
    kept, missed = _window_try(run, torque, setup, basic, say, {}, "")
    if not middle:
        return kept
    # the bearing developed there breaks the limit: developed again at the geometric middle
    # of the window below it, at most WINDOW_LOWER_STEPS times, each from the last missed
    # (raised back from the torque kept as far as its own LTE allows:
    # development._window_raised)
    return _lower_middles(run, setup, basic, say, (kept, missed), torque,
                          WINDOW_LOWER_STEPS, "")


def _lower_middles(run: Callable[..., Any], setup: dict[str, Any], basic: Any,
                   say: Callable[[str], None], tried: tuple[Any, str], torque: float,
                   steps: int, lead: str) -> Any:
    """The window's re-developments below a torque missed: where ``tried`` (the design kept
    at ``torque`` [N·m], or None, and why it missed) kept none, the drive developed again
    at the geometric middle of the window below the last torque missed, at most ``steps``
    times; ``lead`` starts each one's torque reason (:func:`redeveloped_in_window` and
    :func:`_straight_to_middle`). Returns the design kept, or None."""
    low = setup["lte_window"][0]
    design = float(setup["torques"][1])
    kept, missed = tried
    misses: list[str] = []
    for _ in range(steps):
        if kept is not None or not missed:
            return kept
        misses.append(f"at {plain_number(torque)} N m {missed}")
        lower = floor_torque(math.sqrt(low * torque))
        if not (math.isfinite(lower) and lower * WINDOW_LOWER_STEP <= torque):
            say(f"development: the design torque kept at {plain_number(design)} N m (the "
                f"window's middle {plain_number(lower)} N m below {plain_number(torque)} N m "
                "too close to it to develop a bearing of its own)")
            return None
        say(f"development: the drive developed again at {plain_number(lower)} N m, the "
            f"geometric middle of {plain_number(round(low, 1))}-{plain_number(torque)} N m "
            f"(at {plain_number(torque)} N m {missed})")
        kept, missed = _window_try(
            run, lower, setup, basic, say,
            {"torque_name": window_name(setup, middle=(torque, missed))},
            f"{lead}{'; '.join(misses)}, so at the window's geometric middle below it; ")
        torque = lower
    return kept


def _straight_to_middle(run: Callable[..., Any], setup: dict[str, Any], basic: Any,
                        say: Callable[[str], None], first: float) -> Any:
    """:func:`redeveloped_in_window` with ``straight``: the drive developed at the window's
    geometric middle ``first`` [N·m] below its upper end (not developed), then, where its
    bearing breaks the limit, at the middle below the last torque missed, at most
    :data:`WINDOW_LOWER_STEPS` developments in all. Returns what
    :func:`redeveloped_in_window` returns."""
    low, high, _ = setup["lte_window"]
    limit = development_lte_limit()
    upper = floor_torque(high)
    say(f"development: the written drive bearing keeps {limit:g} urad from about "
        f"{plain_number(round(low, 1))} to {plain_number(round(high, 1))} N m only; the drive "
        f"developed again at {plain_number(first)} N m, the window's geometric middle below "
        f"its upper end {plain_number(upper)} N m (the upper end not developed)")
    lead = (f"straight at the window's geometric middle below its upper end "
            f"{plain_number(upper)} N m (not developed); ")
    tried = _window_try(run, first, setup, basic, say,
                        {"torque_name": window_name(setup, middle=(upper, ""))}, lead)
    return _lower_middles(run, setup, basic, say, tried, first, WINDOW_LOWER_STEPS - 1, lead)

#: whether :func:`redeveloped_in_window` (``middle``) develops the drive first at the
#: window's geometric middle rather than at its upper end (``straight``; issue 71, branch
#: middle100): None (the default) decides by :func:`light_end_missed` (branch cpu101);
#: True or False for every window (the measurements' switch). docs/performance.md ("The
#: window re-development straight to the middle" and "… where the light end missed").
WINDOW_STRAIGHT_TO_MIDDLE: bool | None = None


def light_end_missed(setup: dict[str, Any]) -> bool:
    """Whether the written drive bearing whose LTE window :func:`written_lte_capacity`
    recorded broke the verdict's LTE limit at its own light torque already: the window
    bounded at both ends (its LTE high at light load, from the unloaded TE, and at the
    design torque), where :func:`redeveloped_in_window` goes straight to the window's
    geometric middle (the upper end not developed).

    Parameters
    ----------
    setup : dict
        The development's setup; its ``"lte_window_light"`` (the light torque [N·m], the
        written bearing's LTE p-p there [µrad]) where a window was recorded.

    Returns
    -------
    bool
        True where that LTE p-p is finite and above
        :func:`~contact.optimize.development_range_lte.verdict_lte_limit`; False where it
        keeps the limit, is not finite or was not recorded (a setup made before it was:
        the upper end first, as before).

    Raises
    ------
    Nothing.

    Notes
    -----
    Why (issue 71, branch cpu101): a bearing whose LTE at light load is above the limit
    shares the light torque too late (a face contact ratio below 1: its unloaded TE
    alone is above the limit), and one developed at the window's upper end keeps that
    light-load LTE — its light torque, 0.15 of the upper end, is below the window's lower
    end — so it missed on every design measured where the light end missed and was kept
    on every one where it kept the limit: the FM 17×23 (94.8 µrad at 230.5 N m; the upper
    end 77.6 µrad), the FH 12×27 (69.7 at 7.5; 255.7) against the FH 10×33 at Σ 80°
    (22.7 at 60.1; kept), the FM 24×29 at Σ 105° (17.1; kept), the FM 15×28 at Σ 110°
    (18.7; kept) and lte87's FM 14×36 at Σ 70° (48.9; kept), measured in
    docs/performance.md ("The window re-development straight to the middle where the
    light end missed"). A measured rule, not a bound: a design whose light end missed
    and whose upper end would keep the limit is written at a lower torque (the middle's,
    raised back by ``development._window_raised``).
    """
    found = setup.get("lte_window_light")
    if found is None:
        return False
    lte = float(found[1])
    return math.isfinite(lte) and lte > verdict_lte_limit()


#: most developments of :func:`redeveloped_in_window` (``middle``) at the geometric middle
#: of the window below the last torque whose bearing broke the limit: the FM spiral bevel
#: 17x23 of benchmarks/data/unseen_designs read 77.6 µrad at the window's upper end
#: 926.9 N m, about 73 at its middle 638.9 (a bearing of its own, the same basic data
#: given that design torque) and within 60 at 530.5, the next middle (branch lowratio95).
#: Each miss is stopped after its drive steps (:class:`WindowMissed`).
WINDOW_LOWER_STEPS = 2

#: the least ratio of a torque whose bearing missed to the middle below it at which
#: :func:`redeveloped_in_window` develops the drive once more there: a design torque
#: within 10 % of one developed already changes the development's light torque and
#: load-matched TE by as little
WINDOW_LOWER_STEP = 1.1


def _window_try(run: Callable[..., Any], torque: float, setup: dict[str, Any], basic: Any,
                say: Callable[[str], None], kw: dict[str, Any], prior: str
                ) -> tuple[Any, str]:
    """One development of :func:`redeveloped_in_window` at the design torque ``torque``
    [N·m] (``run(torque, **kw)``; ``prior`` the words its torque source says before
    "developed at"). Returns (the result as :func:`redeveloped_in_window`
    returns it, or None; where None because its drive LTE p-p broke the limit, its
    reading in words, else "")."""
    low, high, before = setup["lte_window"]
    limit = development_lte_limit()
    design = float(setup["torques"][1])
    try:
        again = run(torque, **kw)
    except WindowMissed as missed:  # stopped after its drive steps: it would not be kept
        found = missed.record
        where = judged_where(found, clause=True)
        reading = (f"its drive LTE p-p {_curve((found['torques'], found['lte']))}, at most "
                   f"{found['peak']:.1f} {where} after its drive steps")
        say(f"development: at {plain_number(torque)} N m {reading} (the check's reading): "
            f"above {limit:g} urad, so not kept (its coast flank, FE root checks and case "
            f"not made); the design torque kept at {plain_number(design)} N m")
        return None, reading
    except Exception as exc:  # the first development stands
        raise_if_interrupted(exc)
        log.info("development: the development at %.4g N m failed: %s", torque, exc)
        say(f"development: the development at {plain_number(torque)} N m failed ({exc}); "
            f"the design torque kept at {plain_number(design)} N m")
        return None, ""
    ends = np.asarray(again.best.metrics["lte_peak_to_peak"], float)
    judged = again.lte_range
    peak = float(judged["peak"]) if judged is not None else math.nan
    reading = "the check's reading"
    if (not math.isfinite(peak) and np.all(np.isfinite(ends)) and np.all(ends <= limit)):
        # its ends keep the limit but no check judged its written design between them
        # (a later step changed it): judged here, one range analysis (branch diag93)
        peak = _range_peak(again)
        reading = "judged on its written drive design"
    if not (np.all(np.isfinite(ends)) and np.all(ends <= limit) and peak <= limit):
        said = (f"its drive LTE p-p {' / '.join(f'{x:.1f}' for x in ends)} urad, at most "
                f"{peak:.1f} over the range")
        say(f"development: at {plain_number(torque)} N m {said}: above {limit:g} urad or not "
            f"judged; the design torque kept at {plain_number(design)} N m")
        # a reading above the limit (not a range left unanalysed) is an LTE miss
        over = bool(np.nanmax(np.append(ends, peak)) > limit)
        return None, said if over else ""
    final = float(again.torque[1])
    raised = (f" and raised on that bearing to {plain_number(final)} N m (of "
              f"{plain_number(design)}), where every capacity criterion holds"
              if final > torque else "")
    source = (f"the torque up to which the developed bearing keeps the drive LTE within "
              f"{limit:g} urad at every torque: at "
              f"{_rated_as(setup)} {plain_number(design)} N m the "
              f"written bearing's LTE p-p was {before}, within {limit:g} urad from about "
              f"{plain_number(round(low, 1))} to {plain_number(round(high, 1))} N m only (its "
              f"light torque a share of the design torque); {prior}developed at "
              f"{plain_number(torque)} N m{raised}: {_curve((again.torque, ends))}, "
              f"at most {peak:.1f} urad over ltca run's range ({reading})")
    say(f"  design torque {plain_number(design)} -> {plain_number(final)} N m: {source}")
    return dataclasses.replace(again, basic=given_torque_of(again.basic, basic),
                               torque_source=source, torque_lowered=True,
                               lte_torque=float(again.torque[1])), ""


def _range_peak(again: Any) -> float:
    """The largest LTE p-p [µrad] over ``ltca run``'s range of the drive design a
    re-development wrote (``again.best``, its case the written one where the written drive
    check re-read it) at its own torques ``again.torque`` [N·m]
    (:func:`~contact.optimize.development_range_lte.range_lte`, the shell teeth built for
    it as ``ltca run`` builds them); NaN where not analysed."""
    from contact.optimize.development_range_lte import range_peak

    found = range_lte(again.best, {"torques": [float(t) for t in again.torque]}, None)
    return range_peak(found)[0]


def given_torque_of(developed: Any, basic: Any) -> Any:
    """The re-development's basic design ``developed`` (its written prescriptions, both
    flanks) with the design torque ``basic``, the basic data as given, names
    (``[synthesis] design_torque``, None where it names none).

    Parameters
    ----------
    developed : geometry.synthesis.basic_design.BasicDesign
        The basic design the development at the window's torque wrote (that torque its
        ``design_torque``).
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data as given.

    Returns
    -------
    BasicDesign
        ``developed`` with ``options.design_torque`` of ``basic``.

    Notes
    -----
    Why both: ``ltca synthesize``'s case reads the design torque the file gave from the
    result's ``basic`` (:func:`contact.optimize.development_written.written_case`; the
    lowered torque is the result's own, ``torque_lowered``), while the contact-ratio
    remedies' checks and the LTE diagnosis synthesise at the result's ``basic`` as the
    written prescriptions (:func:`contact.optimize.development_remedy.prescribed_basic`).
    The basic data as given there checked the remedies at the *start* prescriptions: the
    spiral bevel 15x28 at Σ 110° (benchmarks/data/unseen_designs), re-developed at
    234.6 N·m, had its b2 36.5 mm remedy checked at 116 µrad against the written case's
    45 (its start prescriptions' own unloaded TE 141.6 µrad) and refused
    (docs/synthesis.md, "The remedies checked at the start prescriptions").
    """
    return dataclasses.replace(developed, options=dataclasses.replace(
        developed.options, design_torque=basic.options.design_torque))


class WindowMissed(Exception):
    """A drive development run again in its LTE window
    (:func:`redeveloped_in_window`) stopped after its drive steps, where its check's LTE
    record over ``ltca run``'s range exceeds the verdict's limit (:func:`window_missed`):
    ``record`` is that record (``torques`` [N·m], ``lte`` [µrad], ``peak`` [µrad], ``at``
    [N·m], ``values``)."""

    def __init__(self, record: dict[str, Any]) -> None:
        self.record = record
        super().__init__(f"drive LTE p-p {float(record['peak']):.1f} urad over the range")


def window_missed(setup: dict[str, Any], best: DevelopmentEvaluation) -> dict[str, Any] | None:
    """The check's LTE record over ``ltca run``'s range of the drive design ``best`` at the
    development's torques where it exceeds the verdict's limit: the outcome that makes
    :func:`redeveloped_in_window` not keep a development of a given design torque, known
    after its drive steps.

    Parameters
    ----------
    setup : dict
        The development's state: its ``torques`` [N·m] (light, design) and the check's
        record (:func:`~contact.optimize.development_range_lte.range_record`).
    best : DevelopmentEvaluation
        The drive design after the development's drive steps (its ``values`` [file
        units]).

    Returns
    -------
    dict or None
        The record (``torques`` [N·m], ``lte`` [µrad], ``peak`` [µrad], ``at`` [N·m],
        ``values``) where it is of ``best``'s values and its ``peak`` is above
        :func:`~contact.optimize.development_range_lte.verdict_lte_limit` (60 µrad); where
        no record of ``best`` at these torques has a finite peak, ``best``'s LTE p-p at
        the development's torques as such a record (``judged`` False) where one exceeds
        the limit (:func:`_unjudged_miss`); None otherwise (its peak keeps the limit, or
        neither is known to break it).

    Notes
    -----
    Why the outcome is known there: a development of a given design torque keeps its
    torques, and after its drive steps nothing records the drive LTE over the range again
    (the coast flank's steps judge their own range on a copy of the setup; the gear-root
    bearing step and the written drive check do not judge it). Its result's ``lte_range``
    (:func:`contact.optimize.development._judged`) is then this record, or None where a
    later step changed the drive design; :func:`redeveloped_in_window` keeps neither a
    peak above the limit nor an unjudged range. So stopping there writes the same case
    and saves the development's coast flank, FE root checks and final synthesis. Source:
    issue 71 ("a new design ... within 2 min CPU"); the FM 16x16 at Σ 60°'s re-development
    at 534.3 N·m wrote 116 / 108 µrad and was not kept (docs/synthesis.md, branch regain89).
    """
    from contact.optimize.development_range_lte import range_record

    limit = development_lte_limit()
    found = range_record(setup)
    if found is None or found.get("values") != dict(best.values):
        return _unjudged_miss(setup, best, limit)
    peak = float(found.get("peak", math.nan))
    if not math.isfinite(peak):
        return _unjudged_miss(setup, best, limit)
    return found if peak > limit else None


def judged_where(record: dict[str, Any], clause: bool = False) -> str:
    """Where the LTE p-p of a :func:`window_missed` record was read, as the lines that
    stop or refuse a re-development in the LTE window say it.

    Parameters
    ----------
    record : dict
        A :func:`window_missed` record (its ``judged``: False where it is the LTE at the
        development's own torques, no range judged; absent or True: over the range).
    clause : bool, optional
        Default False: the unjudged case as an aside in brackets (``develop``'s stop line,
        ``"at its torques (the range not judged)"``); True: as a clause between commas
        (:func:`redeveloped_in_window`'s line, ``"at its torques, the range not
        judged,"``).

    Returns
    -------
    str
        ``"over the range"`` where the range was judged, else one of the two texts above.

    Notes
    -----
    One place for the two lines' words (they were written in each, branch diag93).
    Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque"); the record is
    :func:`window_missed`'s.
    """
    if record.get("judged", True):
        return "over the range"
    return ("at its torques, the range not judged," if clause
            else "at its torques (the range not judged)")


def _unjudged_miss(setup: dict[str, Any], best: DevelopmentEvaluation,
                   limit: float) -> dict[str, Any] | None:
    """:func:`window_missed` where the check recorded no finite LTE over the range of
    ``best``: a record of its LTE p-p at the development's own torques (``judged`` False,
    ``peak`` the larger) where either exceeds ``limit`` [µrad], else None.

    Why: nothing records the drive LTE over the range after the drive steps
    (:func:`window_missed`), so the result's ``lte_range`` is then None or NaN, which
    :func:`redeveloped_in_window` does not keep whatever the ends; a later step (the
    gear-root bearing at the given torque) could in principle record one for another
    design, so the stop is asked only where the ends already break the limit too: the
    spiral bevel 17x23 of benchmarks/data/unseen_designs, re-developed at 926.9 N m, read
    72.1 / 77.6 µrad at its torques after its drive steps, no range judged, and was not
    kept after its coast flank, root checks and synthesis: stopped there, its synthesize
    CPU 242.5 -> 223.5 s (-8 %, the two run side by side on the loaded 2-core machine; 124 s
    idle), the case written the same (issue 71, "a new design ... within 2 min CPU")."""
    ends = np.asarray(best.metrics.get("lte_peak_to_peak", (math.nan,)), float)
    if not (ends.size and np.all(np.isfinite(ends)) and float(np.max(ends)) > limit):
        return None
    torques = tuple(float(t) for t in setup["torques"])
    worst = int(np.argmax(ends))
    return {"torques": torques, "lte": tuple(float(x) for x in ends),
            "peak": float(ends[worst]), "at": torques[min(worst, len(torques) - 1)],
            "values": dict(best.values), "judged": False}


def window_name(setup: dict[str, Any], middle: tuple[float, str] | None = None) -> str:
    """What the design torque of the drive developed again in the LTE window is, as its
    progress line and the coast design torque's source name it (in place of the "[synthesis]
    design_torque" of a basic file giving one, which the basic file does not give).

    Parameters
    ----------
    setup : dict
        The development's setup; its ``"lte_window"`` (low, high [N·m], the LTE text)
        where :func:`written_lte_capacity` recorded one.
    middle : (float, str), optional
        Where the development is one at the window's geometric middle below a torque
        whose bearing broke the limit (:func:`redeveloped_in_window`): that torque [N·m]
        and its drive LTE reading in words (empty: the upper end, not developed,
        :func:`redeveloped_in_window` ``straight``). Default None: the upper end's
        development.

    Returns
    -------
    str
        ``"the LTE window's upper end: the written drive bearing kept 60 urad from about
        <low> to <high> N m only"`` (``"the LTE window's geometric middle below <T> N m:
        … only; the drive developed at <T> N m: at <T> N m <reading>"`` with
        ``middle``); empty where no window was recorded.

    Notes
    -----
    Source: issue 71 (the FM 17x23's re-development named its lowered torque "[synthesis]
    design_torque of the basic file", docs/own_gear_set.md, "Re-run on the rebased branch
    (after lte87)").
    """
    window = setup.get("lte_window")
    if window is None:
        return ""
    low, high = float(window[0]), float(window[1])
    kept = (f"the written drive bearing kept {development_lte_limit():g} urad at every torque "
            f"from about {plain_number(round(low, 1))} to {plain_number(round(high, 1))} N m "
            "only")
    if middle is not None and not middle[1]:
        return (f"the LTE window's geometric middle below its upper end "
                f"{plain_number(middle[0])} N m: {kept}; the upper end not developed "
                "(contact.optimize.development_written_lte)")
    if middle is not None:
        return (f"the LTE window's geometric middle below {plain_number(middle[0])} N m: "
                f"{kept}; the drive developed at {plain_number(middle[0])} N m: at "
                f"{plain_number(middle[0])} N m {middle[1]} "
                "(contact.optimize.development_written_lte)")
    return f"the LTE window's upper end: {kept} (contact.optimize.development_written_lte)"


def lte_window(torques: Sequence[float], lte: Sequence[float], limit: float
               ) -> tuple[float, float]:
    """The torques [N·m] between which an LTE p-p keeps ``limit``: the first run of
    torques at which it does, each end linear to the neighbour above the limit.

    Parameters
    ----------
    torques : sequence of float, shape (n,) — [N·m]
        Ascending torques.
    lte : sequence of float, shape (n,) — [µrad]
        The LTE p-p at each.
    limit : float — [µrad]

    Returns
    -------
    (low, high) : (float, float) — [N·m]
        The lower end (the first torque where the run starts at it) and the upper end
        (the last torque where the run ends at it); NaN, NaN where no value keeps the
        limit or a value is not finite.

    Raises
    ------
    ValueError
        ``torques`` and ``lte`` of different lengths, or empty.

    Notes
    -----
    Linear between the torques analysed, as
    :func:`~contact.study.lte_within.within_torque`. Source: issue 71 ("LTE p-p ≤ 60 µrad
    at every torque" from the light torque, 15 % of the design torque, to the design
    torque): a window narrower than that ratio holds no design torque.
    """
    t = np.asarray(torques, float)
    y = np.asarray(lte, float)
    if t.shape != y.shape or t.size == 0:
        raise ValueError(f"lte_window: {t.size} torques and {y.size} LTE values")
    inside = np.flatnonzero(y <= limit)
    if inside.size == 0 or not (np.all(np.isfinite(t)) and np.all(np.isfinite(y))):
        return math.nan, math.nan
    first = int(inside[0])
    last = first
    while last + 1 < t.size and y[last + 1] <= limit:
        last += 1

    def crossing(i: int, j: int) -> float:
        return float(t[i] + (limit - y[i]) / (y[j] - y[i]) * (t[j] - t[i]))

    low = float(t[0]) if first == 0 else crossing(first - 1, first)
    high = float(t[-1]) if last == t.size - 1 else crossing(last, last + 1)
    return low, high


def _rated_as(setup: dict[str, Any]) -> str:
    """The first words of the design torque's source before a lowering ("the ISO 10300
    capacity" of "the ISO 10300 capacity, the pinion torque at which …; …"; "the local
    pitting capacity of the developed bearing" of a capacity cut's "… bearing: its LTCA
    peak flank pressure …", whose words after the colon the lowering's phrase names no
    torque for: branch diag93)."""
    return setup["source"].split(",")[0].split(";")[0].split(":")[0]


def _curve(found: tuple[Sequence[float], Sequence[float]]) -> str:
    """``"a / b / … urad at x / y / … N m"`` of an LTE p-p over torques.

    Each LTE p-p [µrad] to 0.1 µrad, but one above ``ltca run``'s limit
    (:func:`~contact.optimize.development_range_lte.verdict_lte_limit`) that rounds to it
    or below is given to the decimal that shows it above (at most 3: "60.004"): issue 71,
    round 37, the FM 24x29 at Σ 105° read "no design torque … where it keeps 60 urad
    (tried … at 191.7 N m … 60.0 urad …)" for an LTE above 60 by less than 0.05 µrad.
    """
    limit = verdict_lte_limit()
    return (" / ".join(_lte_text(float(x), limit) for x in found[1]) + " urad at "
            + " / ".join(plain_number(float(t)) for t in found[0]) + " N m")


def _lte_text(lte: float, limit: float) -> str:
    """An LTE p-p [µrad] to 0.1 µrad, or to the decimal (at most 3) that shows one above
    ``limit`` [µrad] above it."""
    for digits in (1, 2, 3):
        text = f"{lte:.{digits}f}"
        if not (lte > limit >= float(text)):
            return text
    return f"{lte:.3f}"
