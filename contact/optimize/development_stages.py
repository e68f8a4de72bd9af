"""The search stages of one flank's development: the bearing, the height, the relief and
the TE stage (:func:`search_flank`).

The **bearing** (path angle, ellipse length) by a bounded Nelder–Mead
(:func:`_minimise`); from the best bearings (:func:`_relief_bearings`), the **height**
(:func:`_height_stage`: the root relief, then the blade angle's root-find on the
light-load footprint centre v, :func:`_centre_height`, the profile crowning where the
centred pattern reaches an end) and the **relief** (:func:`_relief_stage`: scrambled
Sobol points then Nelder–Mead, :func:`_sample_then_minimise`, each design re-centred by
one step of the blade angle, :func:`_recentred`); then the **TE stage**
(:func:`_te_stage`: the modified roll's TE level lowered where the LTE misses). Each
design is an ``evaluate`` call (:func:`contact.optimize.development_evaluate.evaluator`).
Split out of :mod:`contact.optimize.development` (issue 71), which re-exports every
public name; the sources are in its docstring.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import (
    StageStop,
    bearing_key,
)
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import (
    CROWNING_NAME,
    FAILED,
    HEIGHT_NAME,
    RELIEF_NAMES,
    TE_NAME,
    TIP_RELIEF_START,
    DevelopmentTargets,
)
from geometry.case import Case
from geometry.synthesis.basic_design import (
    BasicDesign,
    flank_option_values,
)

#: step of the profile crowning in the height stage [µm], × the targets' ``size_scale``
#: (the tooth size: :func:`geometry.synthesis.basic_design.size_scale`)
CROWNING_STEP = 10.0


#: first guess of d(centre v)/d(blade angle change) [1/deg] of the root-find, before it
#: has measured its own: on the passenger-car hypoid 10x43 of tests/data/designs (drive,
#: concave flank, the synthesis' default bearing, coarse LTCA at 15 % of 357 N m) a change
#: of -1/0/+1 deg put the footprint centre at v 0.35/0.68/0.91, i.e. 0.28 per degree
HEIGHT_SLOPE = 0.28
#: least d(centre v)/d(blade angle change) [1/deg] the root-find steps with, half of
#: :data:`HEIGHT_SLOPE`: a secant slope measured below it is taken as it (a continuous
#: floor, not a switch). The coarse LTCA's footprint centre moves by node rows (about 0.05
#: of the depth), so two designs a root-find step apart whose centres differ by less than
#: a row give a slope that is the grid's, not the bearing's; the switch before (a measured
#: slope above 0.05 taken, else :data:`HEIGHT_SLOPE`) made a 0.2 % change of the light
#: torque turn a secant of 0.04 into 0.07 per degree and the next step from −0.15° into
#: −0.57° (the spiral bevel 13x37 at Σ 60° of benchmarks/data/unseen_designs, its second
#: bearing's height stage: 41.8 against 41.88 N m), after which the two searches went
#: different ways
HEIGHT_SLOPE_MIN = 0.5 * HEIGHT_SLOPE


#: most designs of one root-find on the pattern's height (each ≈ 0.3 s CPU: steps 3-6
#: from the memo, the blade turned and relieved again, a coarse LTCA)
HEIGHT_DESIGNS = 4


#: bearings of the first stage whose relief the second stage develops, best first; the
#: second only where the relief of the first misses the LTE target, with
#: :data:`SECOND_BEARING_DESIGNS` of the budget. On the passenger-car hypoid 10x43 of
#: tests/data/designs the best bearing before the relief (ellipse 0.475, LTE 39 urad with
#: the synthesis' default relief) needs a relief that raises its LTE to 56-61 urad, the
#: second (ellipse 0.625, LTE 26 urad) one that leaves it at 39-42 (docs/synthesis.md,
#: "Development bearing": the LTE against the relief)
RELIEF_BEARINGS = 2


#: designs of the relief stage kept for the second bearing (≈ 0.3 s CPU each)
SECOND_BEARING_DESIGNS = 6


def _start(names: list[str], targets: DevelopmentTargets, start: Mapping[str, float],
           basic: BasicDesign) -> np.ndarray:
    """Start values of ``names``: the basic design's prescriptions where the bounds allow
    (else the bound's middle); the ellipse at the target pattern length less the spread
    under light load (about a fifth of it) unless the file bounds it itself."""
    x = []
    for n in names:
        lo, hi = targets.variables[n]
        v = start[n] if lo <= start[n] <= hi else 0.5 * (lo + hi)
        if n == "ellipse_length" and "variables" not in basic.development:
            v = float(np.clip(0.8 * targets.pattern_length, lo, hi))
        x.append(v)
    return np.asarray(x, float)


def _minimise(fun: Callable[[np.ndarray], float], x0: np.ndarray, low: np.ndarray,
              high: np.ndarray) -> None:
    """Bounded Nelder–Mead on the variables scaled to [0, 1], initial simplex 0.25 wide
    (towards the middle of each bound); ``fun`` ends it by raising :class:`StageStop`."""
    from scipy.optimize import minimize

    n = len(x0)
    z0 = (x0 - low) / (high - low)
    simplex = np.vstack([z0] + [np.clip(z0 + 0.25 * np.eye(n)[i]
                                        * (1.0 if z0[i] <= 0.5 else -1.0), 0.0, 1.0)
                                for i in range(n)])
    try:
        minimize(lambda z: fun(low + np.clip(z, 0.0, 1.0) * (high - low)), z0,
                 method="Nelder-Mead", bounds=[(0.0, 1.0)] * n,
                 options={"initial_simplex": simplex, "maxfev": 10_000, "xatol": 0.02,
                          "fatol": 1e-3})
    except StageStop:
        pass


def _sample_then_minimise(fun: Callable[[np.ndarray], float], x0: np.ndarray,
                          low: np.ndarray, high: np.ndarray, n_sample: int) -> None:
    """``x0`` and ``n_sample`` scrambled-Sobol points of the box (``scipy.stats.qmc``, seed
    0: the same designs every run), then :func:`_minimise` from the best: the relief's
    objective has steps where an edge starts or stops carrying, on which a simplex from
    one corner stalls."""
    tried = []
    try:
        tried.append((fun(x0), x0))
        if n_sample:
            # imported here, not above: scipy.stats costs ~0.3 s of CPU to import, spared
            # where the start meets every target (StageStop) (issue 75)
            from scipy.stats import qmc

            m = max(1, math.ceil(math.log2(n_sample)))
            pts = qmc.Sobol(len(x0), scramble=True, seed=0).random_base2(m)[:n_sample]
            for z in pts:
                x = low + z * (high - low)
                tried.append((fun(x), x))
    except StageStop:
        return
    _minimise(fun, min(tried, key=lambda fx: fx[0])[1], low, high)


def flank_start(options: Any, targets: DevelopmentTargets) -> dict[str, float]:
    """A flank's prescriptions as the start of its search [file units]: the basic file's
    (:func:`~geometry.synthesis.basic_design.flank_option_values`), but the tip relief's
    start at :data:`TIP_RELIEF_START` (within its bounds) where the file gives none and
    the development varies it."""
    start = flank_option_values(options)
    name = "tip_relief_start"
    if name in targets.variables and options.tip_relief_start is None:
        start[name] = float(np.clip(TIP_RELIEF_START, *targets.variables[name]))
    return start


def search_flank(evaluate: Callable[..., DevelopmentEvaluation],
                 evals: list[DevelopmentEvaluation],
                 basic_of: Callable[[dict[str, float]], BasicDesign],
                 make: Callable[[BasicDesign], Case], targets: DevelopmentTargets,
                 start: Mapping[str, float], basic: BasicDesign, n_max: int,
                 max_bearings: int = 6) -> bool:
    """The two stages of one flank's search (:func:`develop`), designs appended to
    ``evals``: the **bearing** (the non-relief variables, at most ``max_bearings``
    designs or half of ``n_max``; a synthesis ``make(basic_of(values))`` each), then the
    **relief** (:func:`_relief_stage`, the rest of ``n_max``). ``start``: the flank's
    prescriptions [file units]. Returns whether any design was synthesised and
    analysed."""
    bearing = [n for n in targets.variables
               if n not in (*RELIEF_NAMES, HEIGHT_NAME, CROWNING_NAME, TE_NAME)]
    # the relief stage varies the profile crowning too: the height stage raises it where
    # the centred pattern reaches an end, the relief may do that work with less LTE
    relief = [n for n in targets.variables if n in (*RELIEF_NAMES, CROWNING_NAME)]
    n_bearing = min(max_bearings, max(1, n_max // 2)) if bearing else 1
    fixed = {n: start[n] for n in relief}
    for n in (HEIGHT_NAME, CROWNING_NAME):
        if n in targets.variables:
            fixed[n] = float(np.clip(start[n], *targets.variables[n]))
    low = np.array([targets.variables[n][0] for n in bearing])
    high = np.array([targets.variables[n][1] for n in bearing])

    def bearing_design(x: np.ndarray) -> float:
        values = {n: float(v) for n, v in zip(bearing, x, strict=True)} | fixed
        b = basic_of(values)
        return evaluate(values, "bearing", lambda: make(b), n_bearing,
                        bearing_key(values)).objective

    x0 = _start(bearing, targets, start, basic)
    if bearing:
        _minimise(bearing_design, x0, low, high)
    else:
        try:
            bearing_design(x0)
        except StageStop:
            pass
    ok = [e for e in evals if e.case is not None and e.objective < FAILED]
    if not ok:
        return False
    # stage 2, the relief on the blade of each of the best bearings in turn (the relief a
    # bearing needs to keep its edges elastic costs LTE, so the bearing with the least
    # objective before the relief is not always the one with the least after it)
    te = TE_NAME in targets.variables and n_max - len(evals) > 2 * TE_DESIGNS
    if relief:
        _relief_stage(evaluate, _relief_bearings(ok, RELIEF_BEARINGS), relief, targets,
                      evals, basic_of, make, n_max - (TE_DESIGNS if te else 0))
    if te:
        _te_stage(evaluate, evals, targets, basic_of, make, start, n_max)
    return True


#: most designs of the TE stage (:func:`_te_stage`; each a synthesis of steps 3-6, ≈ 2 s
#: CPU with its coarse LTCA)
TE_DESIGNS = 2


def _te_stage(evaluate: Callable[..., DevelopmentEvaluation],
              evals: list[DevelopmentEvaluation], targets: DevelopmentTargets,
              basic_of: Callable[[dict[str, float]], BasicDesign],
              make: Callable[[BasicDesign], Case], start: Mapping[str, float],
              n_max: int) -> None:
    """The TE stage: where the best design of the search misses the LTE target, the
    modified roll's TE level (:data:`TE_NAME`, the parabola the local synthesis prescribes,
    a21 = 2 te_level/(2π/z1)²) lowered, the design's other inputs kept: first by 20 µrad
    (within its bounds), then, where that scored better and the LTE is still missed, to
    its lower bound; at most :data:`TE_DESIGNS` designs, each a synthesis of steps 3-6.

    Why: with the tip relief short (:data:`TIP_RELIEF_START`) the transfer between tooth
    pairs at light load runs on the unrelieved flank, where the unloaded TE is the
    parabola's; a flatter parabola lets the light load carry more pairs (Litvin & Fuentes
    2004 §9.4: the parabolic function absorbs the linear TE of misalignment, and its
    level is a designer's choice). Measured in :data:`TE_NAME`'s comment
    (:mod:`contact.optimize.development_targets`)."""
    done = [e for e in evals if e.full is not None and e.objective < FAILED]
    if not done:
        return
    best = min(done, key=lambda e: e.full[0])
    lo, hi = targets.variables[TE_NAME]
    level = float(best.values.get(TE_NAME, start[TE_NAME]))
    for x in (max(lo, min(hi, level) - 20.0), lo):
        if best.full[1]["lte"] == 0.0 or x >= float(best.values.get(TE_NAME, level)) - 1e-9:
            return
        values = best.values | {TE_NAME: float(x)}
        b = basic_of(values)
        try:
            e = evaluate(values, "te", lambda b=b: make(b), n_max, bearing_key(values))
        except StageStop:
            return
        if e.full is None or e.full[0] >= best.full[0]:
            return
        best = e


def _relief_stage(evaluate: Callable[..., DevelopmentEvaluation],
                  firsts: list[DevelopmentEvaluation], relief: list[str],
                  targets: DevelopmentTargets, evals: list[DevelopmentEvaluation],
                  basic_of: Callable[[dict[str, float]], BasicDesign],
                  make: Callable[[BasicDesign], Case], n_max: int | None = None) -> None:
    """The relief stage of :func:`develop`: ``relief`` varied on the blade of the best
    bearing (:func:`_sample_then_minimise`), with the budget left (``n_max``, default
    ``targets.max_evaluations``, less the designs in ``evals``) but
    :data:`SECOND_BEARING_DESIGNS`; then, only where its best design misses the LTE
    target, on the blade of the next bearing of ``firsts`` with those designs. Ends at the
    first design meeting every target."""
    n_max = targets.max_evaluations if n_max is None else n_max
    low = np.array([targets.variables[n][0] for n in relief])
    high = np.array([targets.variables[n][1] for n in relief])
    remaining = n_max - len(evals)
    second = min(SECOND_BEARING_DESIGNS, remaining // 2) if len(firsts) > 1 else 0
    budgets = [len(evals) + remaining - second] + [n_max] * (len(firsts) - 1)
    for first, budget in zip(firsts, budgets, strict=True):
        if len(evals) >= budget:
            return
        if HEIGHT_NAME in targets.variables:  # the pattern's height first
            first = _height_stage(evaluate, first, targets, budget, basic_of, make)
            if first is None:
                return  # a design met every target

        # designs kept for the re-centring after the relief, where the budget allows
        relief_budget = budget - (_RECENTRE_DESIGNS if HEIGHT_NAME in targets.variables
                                  and budget - len(evals) > 3 * _RECENTRE_DESIGNS else 0)

        def relief_design(x: np.ndarray, first=first, budget=relief_budget) -> float:
            values = first.values | {n: float(v) for n, v in zip(relief, x, strict=True)}
            # the synthesis itself (steps 3-6 from the memo, the relief made again; the
            # tip plane, which keeps the flank, placed for the designs checked later)
            b = basic_of(values)
            e = evaluate(values, "relief", lambda: make(b), budget,
                         bearing_key(first.values))
            return _recentred(evaluate, e, targets, budget, basic_of, make).objective

        n_sample = min(8, max(0, (budget - len(evals) - HEIGHT_DESIGNS // 2) // 2))
        _sample_then_minimise(relief_design, np.array([first.values[n] for n in relief]),
                              low, high, n_sample=n_sample)
        if any(e.met for e in evals if e.stage in ("relief", "height")):
            return
        key = bearing_key(first.values)  # this bearing's designs, its own included
        done = [e for e in evals if e.full is not None and bearing_key(e.values) == key]
        if done and HEIGHT_NAME in targets.variables:  # the relief moved it: again
            best = min(done, key=lambda e: e.full[0])
            if best.full[1]["centre_v"] > 0.0 and _centre_height(
                    evaluate, best, targets, budget, basic_of, make,
                    _RECENTRE_DESIGNS) is None:
                return
            done = [e for e in evals
                    if e.full is not None and bearing_key(e.values) == key]
        if not done or min(done, key=lambda e: e.full[0]).full[1]["lte"] == 0.0:
            return  # the LTE met: the next bearing is tried for the LTE alone


def _recentred(evaluate: Callable[..., DevelopmentEvaluation], e: DevelopmentEvaluation,
               targets: DevelopmentTargets, budget: int,
               basic_of: Callable[[dict[str, float]], BasicDesign],
               make: Callable[[BasicDesign], Case]) -> DevelopmentEvaluation:
    """A relief design with its pattern put back to the height aimed at: the relief moves
    the light-load pattern in depth (a toprem or flankrem takes the load off one end), so
    where ``e`` misses the centre v one Newton step of the blade-angle change with the
    slope its bearing's height stage measured (:func:`_centre_height`) is analysed too
    (the same stage), and the better of the two returned: the relief stage's objective is
    that of the design re-centred, the relief and the height developed together."""
    slope = getattr(evaluate, "slopes", {}).get(bearing_key(e.values))
    if (slope is None or e.full is None or HEIGHT_NAME not in targets.variables
            or e.full[1]["centre_v"] == 0.0 or not math.isfinite(footprint_centre_v(e))):
        return e
    lo, hi = targets.variables[HEIGHT_NAME]
    f = footprint_centre_v(e) - _target_v(evaluate, targets)
    x = float(np.clip(e.values[HEIGHT_NAME] - f / slope, lo, hi))
    if abs(x - e.values[HEIGHT_NAME]) < 1e-3:
        return e
    values = e.values | {HEIGHT_NAME: x}
    b = basic_of(values)
    e2 = evaluate(values, e.stage, lambda: make(b), budget, bearing_key(values))
    return e2 if e2.objective < e.objective else e


#: designs of the root-find on the pattern's height after a bearing's relief (the relief
#: moves the pattern in depth: its toprem and flankrem take load off one end)
_RECENTRE_DESIGNS = 2


def _centre_height(evaluate: Callable[..., DevelopmentEvaluation],
                   base: DevelopmentEvaluation, targets: DevelopmentTargets, budget: int,
                   basic_of: Callable[[dict[str, float]], BasicDesign],
                   make: Callable[[BasicDesign], Case], n_designs: int = HEIGHT_DESIGNS
                   ) -> DevelopmentEvaluation | None:
    """The pattern's height by the pinion blade's pressure-angle change: a 1-D root-find
    of the light-load footprint centre v (:func:`footprint_centre`) on the target, from the
    design ``base`` (its other inputs kept).

    The change Δα of :data:`HEIGHT_NAME` moves the pattern monotonically and strongly up or
    down the tooth (:data:`HEIGHT_SLOPE`, 0.28 of the depth per degree measured), the lever
    a gear engineer develops the height with (Stadtfeld, *Gleason Bevel Gear Technology*,
    2014; :mod:`geometry.synthesis.blade_change`). The root-find is a secant on
    f(Δα) = v_c(Δα) − v_target, the first step with :data:`HEIGHT_SLOPE`, then with the
    slope measured (at least :data:`HEIGHT_SLOPE_MIN`), kept in a bracket once f changes
    sign (regula falsi), Δα clipped to its bounds; it stops within a quarter of
    ``centre_tolerance``, after ``n_designs`` designs or at the stage's ``budget``. A
    design whose pattern could not be found (NaN centre) halves the last step. Each
    design is ``evaluate``d (stage ``"height"``: every target, so one that meets them all
    ends the development).

    Returns
    -------
    DevelopmentEvaluation or None
        The design of the least objective among those within the centre's tolerance (else
        the one nearest the target), ``base`` included; None where a design met every
        target (the caller stops).
    """
    lo, hi = targets.variables[HEIGHT_NAME]
    if base.full is None or not math.isfinite(footprint_centre_v(base)):
        return base
    target = _target_v(evaluate, targets)
    tried = [(float(base.values[HEIGHT_NAME]), footprint_centre_v(base) - target, base)]
    good = 0.25 * targets.centre_tolerance
    x_prev = None
    for _ in range(n_designs):
        x0, f0, _ = min(tried, key=lambda t: abs(t[1]) if math.isfinite(t[1]) else math.inf)
        if abs(f0) <= good:
            break
        finite = [t for t in tried if math.isfinite(t[1])]
        below = [t for t in finite if t[1] < 0.0]
        above = [t for t in finite if t[1] > 0.0]
        if below and above:  # bracketed: regula falsi between the nearest on each side
            a = min(below, key=lambda t: -t[1])
            b = min(above, key=lambda t: t[1])
            x = a[0] - a[1] * (b[0] - a[0]) / (b[1] - a[1])
        else:
            slope = HEIGHT_SLOPE
            if len(finite) >= 2:
                (xa, fa, _), (xb, fb, _) = sorted(finite, key=lambda t: abs(t[1]))[:2]
                if xa != xb:  # the slope measured, floored (continuous in it)
                    slope = max((fa - fb) / (xa - xb), HEIGHT_SLOPE_MIN)
            x = x0 - f0 / slope
        if x_prev is not None and not math.isfinite(tried[-1][1]):
            x = 0.5 * (x_prev + tried[-1][0])  # the last design failed: half its step
        x = float(np.clip(x, lo, hi))
        if any(abs(x - t[0]) < 1e-3 for t in tried):
            break
        values = base.values | {HEIGHT_NAME: x}
        b = basic_of(values)
        try:
            e = evaluate(values, "height", lambda b=b: make(b), budget,
                         bearing_key(values))
        except StageStop:
            return None if any(e.met for e in _evaluated(evaluate)) else _best_height(tried)
        x_prev = x0
        tried.append((x, footprint_centre_v(e) - target, e))
        _note_slope(evaluate, tried)
    return _best_height(tried)


def footprint_centre_v(e: DevelopmentEvaluation) -> float:
    """The light-load footprint centre v of a design [1]; NaN where it has none."""
    v = e.metrics.get("pattern_centre_v")
    return math.nan if v is None else float(v[0])


def _note_slope(evaluate: Callable[..., DevelopmentEvaluation],
                tried: list[tuple[float, float, DevelopmentEvaluation]]) -> None:
    """The slope d(centre v)/d(blade-angle change) [1/deg] measured between the two
    designs of ``tried`` nearest the target, kept per bearing for :func:`_recentred`,
    floored at :data:`HEIGHT_SLOPE_MIN` (as the root-find's steps)."""
    finite = sorted((t for t in tried if math.isfinite(t[1])), key=lambda t: abs(t[1]))
    if len(finite) < 2 or finite[0][0] == finite[1][0]:
        return
    slope = (finite[0][1] - finite[1][1]) / (finite[0][0] - finite[1][0])
    evaluate.slopes[bearing_key(finite[0][2].values)] = max(  # type: ignore[attr-defined]
        slope, HEIGHT_SLOPE_MIN)


def _height_stage(evaluate: Callable[..., DevelopmentEvaluation],
                  base: DevelopmentEvaluation, targets: DevelopmentTargets, budget: int,
                  basic_of: Callable[[dict[str, float]], BasicDesign],
                  make: Callable[[BasicDesign], Case]) -> DevelopmentEvaluation | None:
    """The height stage of a bearing: its light-load pattern centred in depth by the
    blade-angle change (:func:`_centre_height`); where the centred pattern still reaches
    the gear tip (the ``tip`` clearance) or carries edge contact at light load, the
    profile crowning (:data:`CROWNING_NAME`) raised by :data:`CROWNING_STEP` and the
    pattern centred again, at most twice: a pattern as deep as the working depth cannot be
    centred clear of both its ends, a crowned one can (Stadtfeld 2014: pattern height by
    the pressure angle, its depth by the profile crowning). A pattern above its target
    is first lowered by the root relief (:func:`_root_relief_height`), the blade angle
    then finding what is left; where the centred design scores worse than the one before
    the blade angle (the tilt's LTE and edges beyond the centre's shortfall), the stage
    goes on from the latter. Measured on the spiral bevel 13x39 of tests/data/designs
    (coarse LTCA at 36.98 / 246.5 N m, path −51.9°, ellipse 0.75, root relief 40 µm from
    0.2): the root relief put the footprint centre at v 0.65 (target 0.548 ± 0.08) with
    LTE 37 / 57 µrad, objective 3.65; the blade angle −0.201° at 0.54 with 76 / 73 µrad,
    objective 14.2 — and the relief stage, started from the latter, found nothing better
    than 63 µrad in 16 designs. Returns the best design (None where one met every
    target)."""
    try:
        base = _root_relief_height(evaluate, base, targets, budget, basic_of, make)
    except StageStop:
        if any(x.met for x in _evaluated(evaluate)):
            return None
    e = _centre_height(evaluate, base, targets, budget, basic_of, make)
    if (e is not None and e.full is not None and base.full is not None
            and base.full[0] < e.full[0]):
        # the blade angle centred the pattern at more cost than the centre gains: the
        # stage goes on from the design before it (the objective weighs the centre's
        # shortfall against the LTE and the edges the tilt brings)
        e = base
    for _ in range(2):
        if (e is None or e.full is None or CROWNING_NAME not in targets.variables
                or not math.isfinite(footprint_centre_v(e))):
            return e
        short, m = e.full[1], e.metrics
        if short["tip"] == 0.0 and short["root"] == 0.0 and m["edge_load_share"][0] <= 0.0:
            return e
        lo, hi = targets.variables[CROWNING_NAME]
        crown = float(np.clip(e.values[CROWNING_NAME] + CROWNING_STEP * targets.size_scale,
                              lo, hi))
        if crown == e.values[CROWNING_NAME] or len(_evaluated(evaluate)) >= budget:
            return e
        values = e.values | {CROWNING_NAME: crown}
        b = basic_of(values)
        try:
            crowned = evaluate(values, "height", lambda b=b: make(b), budget,
                               bearing_key(values))
        except StageStop:
            return None if any(x.met for x in _evaluated(evaluate)) else e
        nxt = _centre_height(evaluate, crowned, targets, budget, basic_of, make,
                             HEIGHT_DESIGNS - 1)
        if nxt is None:
            return None
        if nxt.full is None or e.full is None or nxt.full[0] >= e.full[0]:
            return e if nxt.full is None or e.full[0] <= nxt.full[0] else nxt
        e = nxt
    return e


#: the root relief [µm] the height stage first lowers a high pattern with, from the lower
#: bound of ``relief_start`` (:func:`_root_relief_height`), × the targets' ``size_scale``
ROOT_HEIGHT_RELIEF = 40.0


def _root_relief_height(evaluate: Callable[..., DevelopmentEvaluation],
                        base: DevelopmentEvaluation, targets: DevelopmentTargets,
                        budget: int, basic_of: Callable[[dict[str, float]], BasicDesign],
                        make: Callable[[BasicDesign], Case]) -> DevelopmentEvaluation:
    """A light-load pattern above its target lowered by the pinion's root relief: the
    toprem's corner at the lower bound of ``relief_start`` and at least
    :data:`ROOT_HEIGHT_RELIEF` of relief, which takes the gear's tip band (it meets the
    pinion's root) out of the light-load footprint; where that leaves the centre v above
    its tolerance, the root relief's upper bound too. Returns the design whose centre v is
    nearest the target, ``base`` included.

    Why not the blade angle alone: the blade-angle change tilts the whole profile, a
    first-order ease-off whose component along the contact ellipse's major axis (the
    direction of least relative curvature, 2δ/a²) walks the contact towards the heel and
    the root corner. Measured on the spiral bevel 13x39 of tests/data/designs (coarse LTCA
    at 40.6 / 270.8 N m, its bearing path −58.8°, ellipse 0.55, no relief): a change of
    −0.1° put the footprint centre at v 0.52 with an unloaded TE of 109 µrad (13 without)
    and a pattern 0.47 long (0.43 without); −0.24° 207 µrad and 0.55; a root relief of
    60 µm from 0.2 of the way put it at v 0.52 with 35 µrad and 0.43
    (docs/synthesis.md, "What sets the pattern and the LTE")."""
    names = ("root_relief", "relief_start")
    if (base.full is None or not all(n in targets.variables for n in names)
            or not math.isfinite(footprint_centre_v(base))):
        return base
    target = _target_v(evaluate, targets)
    f = footprint_centre_v(base) - target
    if f <= 0.25 * targets.centre_tolerance:
        return base
    lo_r, hi_r = targets.variables["root_relief"]
    best, asked = base, []
    # the second where the first is still high
    for relief in (ROOT_HEIGHT_RELIEF * targets.size_scale, hi_r):
        if abs(footprint_centre_v(best) - target) <= targets.centre_tolerance and best is not base:
            break
        values = base.values | {
            "relief_start": float(targets.variables["relief_start"][0]),
            "root_relief": float(np.clip(max(base.values.get("root_relief", 0.0), relief),
                                         lo_r, hi_r))}
        if values in asked:
            continue
        asked.append(values)
        b = basic_of(values)
        e = evaluate(values, "height", lambda b=b: make(b), budget, bearing_key(values))
        if (e.full is not None and math.isfinite(footprint_centre_v(e))
                and abs(footprint_centre_v(e) - target) < abs(footprint_centre_v(best) - target)):
            best = e
    return best


def _target_v(evaluate: Callable[..., DevelopmentEvaluation],
              targets: DevelopmentTargets) -> float:
    """The footprint centre v aimed at: ``targets.pattern_centre_v``, else the working
    depth's middle the evaluator's first design fixed (:func:`working_depth_centre`)."""
    if targets.pattern_centre_v is not None:
        return float(targets.pattern_centre_v)
    return float(evaluate.setup["centre_v"])  # type: ignore[attr-defined]


def _best_height(tried: list[tuple[float, float, DevelopmentEvaluation]]
                 ) -> DevelopmentEvaluation:
    ok = [t[2] for t in tried if t[2].full is not None and t[2].full[1]["centre_v"] == 0.0]
    if ok:
        return min(ok, key=lambda e: e.full[0])
    return min(tried, key=lambda t: abs(t[1]) if math.isfinite(t[1]) else math.inf)[2]


def _evaluated(evaluate: Callable[..., DevelopmentEvaluation]
               ) -> list[DevelopmentEvaluation]:
    return evaluate.evals  # type: ignore[attr-defined]


def _relief_bearings(designs: list[DevelopmentEvaluation], n: int
                     ) -> list[DevelopmentEvaluation]:
    """The ``n`` best distinct bearings of the first stage (every target of the bearing
    stage met first, then the least objective), whose relief the second stage develops in
    turn."""
    out: list[DevelopmentEvaluation] = []
    keys: set[tuple] = set()
    for e in sorted(designs, key=lambda e: (not e.met, e.objective)):
        k = bearing_key(e.values)
        if k not in keys:
            keys.add(k)
            out.append(e)
    return out[:max(1, n)]

