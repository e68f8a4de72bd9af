"""The check's steps on the light-load pattern's length and place: the ellipse searched
for a pattern length still missed (:func:`checked_length`), the pattern's centre along
the face by the mean point's place (:func:`checked_centre_u`, on either flank) and a
small blade-angle step with the TE level lowered for a centre v just off its band
(:func:`checked_near_miss`, :func:`near_miss`). Each design placed and checked at
``ltca run``'s sampling and kept by :func:`~contact.optimize.development_keep.kept_why`.
Split out of :mod:`contact.optimize.development_check` (issue 71, Deliver 5), which
re-exports every public name; the bodies moved unchanged (the helpers they share
imported under the private names they call).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_band_edge import band_edge_designs
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import (
    kept_why,
)
from contact.optimize.development_keep import lost_targets as _lost_targets
from contact.optimize.development_keep import pressure_raised as _pressure_raised
from contact.optimize.development_keep import ranks_better as _ranks_better
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import footprint_centre_v
from contact.optimize.development_targets import (
    HEIGHT_NAME,
    TE_NAME,
    VARIABLES,
    DevelopmentTargets,
)
from contact.optimize.development_tolerance import LENGTH_PER_ELLIPSE, SHORTER_ELLIPSE_STEP
from contact.optimize.development_variant import pattern_length
from contact.optimize.development_variant import said_variant as _said_variant
from geometry.case import Case


def _lost_but_depth(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
    """:func:`_lost_targets`, the light-load centre v apart (:func:`checked_centre_u`: the
    height steps after it re-centre the depth)."""
    return [k for k in _lost_targets(best, e) if k != "centre_v"]


#: the check's pattern-length step (:func:`checked_length`): most designs of its search on
#: the ellipse (each a synthesis of steps 3-6 and a check)
LENGTH_DESIGNS = 4
#: [1 of the face per unit of ``ellipse_length``] the least slope d(length)/d(ellipse) the
#: step's secant takes (the light-load pattern moves by nodes of 0.025 of the face, so a
#: secant over less than a node is the grid's); measured 0.5 on the face-hobbed 6x61 at
#: its light torque, 0.6-0.8 on the 7x39, 0.9 on face-milled pairs
LENGTH_SLOPE_MIN = 0.3
#: [1 of the face] how far inside the length's band the step aims a pattern too long: half
#: a node of the check's grid along the face (the longest ellipse within the band is the
#: one with the least LTE); a pattern too short is aimed at the band's middle
LENGTH_AIM_MARGIN = 0.0125
#: [µrad] ``te_level`` lowered by this (within its bounds) on the step's design that meets
#: the length and misses, of the targets the design met, the LTE alone and by at most
#: :data:`NEAR_MISS` of its unit (5 µrad): measured 2.3-2.4 µrad less LTE at both torques
#: for ``te_level`` 25 → 15 on the 7x39 (:func:`checked_length`)
LENGTH_TE_STEP = 10.0
#: the root relief of :func:`checked_length`'s design that meets the length and misses,
#: of the targets the design met, the LTE alone by at most :data:`LENGTH_RELIEF_LTE` (after
#: the lower ``te_level``, or where it is at its bound): this fraction of the design's, tried
#: once. The relief is the long bearing's (:func:`~contact.optimize.development_lte_steps.
#: checked_long` sizes it for its longer ellipse), deeper than the shorter ellipse's
#: pattern needs at the design torque: measured on the FH hypoid 10x37 at Σ 95° of
#: benchmarks/data/unseen_designs (``ltca run``'s sampling at 56.1 / 374.4 N m, ellipse
#: 0.681, path −75°, ``te_level`` 10 at its bound; ``benchmarks/development_levers.py
#: --check --tolerance``, 2026-11-27): root relief 23.0 µm from 0.5: pattern 0.60 long,
#: LTE 23.4 / 45.2 µrad (the target 40 missed at the design torque); 19.6 µm (× 0.85):
#: 21.7 / 35.5; 17.3 (× 0.75): 21.5 / 35.1, edge 0.9 %; 15.0: 21.2 / 34.6, edge 1.2 %
#: — every target met, tolerant; 11.5 (× 0.5): 21.3 / 41.0, the pattern on the tip row
LENGTH_RELIEF_FRACTION = 0.75
#: the most LTE shortfall (:func:`development_score`'s units: 10 µrad) of
#: :data:`LENGTH_RELIEF_FRACTION`'s try: the 10x37's 45.2 µrad at its design torque (0.52:
#: beyond :data:`NEAR_MISS`, which gates the lower ``te_level``) fell 10 µrad by it
LENGTH_RELIEF_LTE = 1.0
#: the ellipse's upper bound of :func:`checked_length` on a pattern too short, where
#: ``ellipse_length``'s bounds are the defaults (:data:`~contact.optimize.
#: development_targets.VARIABLES`, upper 0.75): one :data:`~contact.optimize.
#: development_lte_steps.ELLIPSE_STEP` (0.05) below the synthesis' own limit 0.9
#: (:class:`geometry.synthesis.basic_design.FlankOptions`). Why: the default bound is the
#: ellipse at which a face-milled pinion's light-load pattern (0.9 of the face per unit of
#: ellipse, :data:`LENGTH_PER_ELLIPSE`) is 0.68 long, beyond the band; a face-hobbed
#: pinion's grows 0.3-0.5 per unit and stays short there. Measured on the FH spiral bevel
#: 11x23 at Σ 70° of benchmarks/data/unseen_designs (ε_vβ 1.00; ``benchmarks/
#: development_levers.py --check --tolerance --edges --from-case``, 8.8 / 59.1 N m,
#: path −65.6°, 2026-11-29, docs/synthesis.md "The FH 11x23's short pattern: the
#: ellipse's bound"): ellipse 0.625 / 0.7 / 0.75 / 0.8 / 0.85: pattern 0.38 / 0.40 /
#: 0.40 / 0.45 / 0.45 long, LTE p-p 56.8 / 47.9 / 43.4 / 39.2 / 35.1 µrad at the light
#: torque, 58.5 / 70.4 / 70.0 / 68.6 / 62.7 at the design torque, the gear tip's edge
#: peak 3246 / 2936 / 2746 / 2582 / 2439 MPa, objective 6.92 / 10.6 / 9.83 / 8.88 /
#: 5.80, every one tolerant; at path −80° the ellipse 0.85 is 0.48 long, 21.2 / 57.0
#: µrad (objective 3.47)
LENGTH_ELLIPSE_MAX = 0.85


def length_aim(length: float, targets: DevelopmentTargets) -> float:
    """[1 of the face] The light-load pattern length :func:`checked_length` aims a
    pattern of ``length`` [1] at: a pattern too long just inside the band's upper edge
    (:data:`LENGTH_AIM_MARGIN`: the longest ellipse within the band has the least LTE), one
    too short at the band's middle (``targets.pattern_length``: a longer ellipse lowers
    the LTE too)."""
    hi = targets.pattern_length + targets.pattern_length_tolerance
    return hi - LENGTH_AIM_MARGIN if length > hi else targets.pattern_length


def length_bound(targets: DevelopmentTargets, too_long: bool) -> float:
    """[1 of the face] The upper bound of ``ellipse_length`` in :func:`checked_length`:
    ``targets.variables``' own, or :data:`LENGTH_ELLIPSE_MAX` on a pattern too short
    (``too_long`` False) where those bounds are the defaults of :data:`~contact.optimize.
    development_targets.VARIABLES` (bounds given in ``[development] variables`` are used
    as given; the same bounds given explicitly read as the defaults).

    Raises
    ------
    KeyError
        ``ellipse_length`` not among ``targets.variables``.
    """
    name = "ellipse_length"
    lo, hi = (float(x) for x in targets.variables[name])
    if not too_long and (lo, hi) == tuple(float(x) for x in VARIABLES[name]):
        return max(hi, LENGTH_ELLIPSE_MAX)
    return hi


def checked_length(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                   setup: Mapping[str, Any], teeth: KeptTeeth | None,
                   say: Callable[[str], None],
                   placed: Callable[[Mapping[str, float]], Case], *,
                   level: float = math.nan, flank: str = "drive",
                   key_prefix: tuple | None = None) -> DevelopmentEvaluation:
    """A pattern length missed at the check after the LTE steps, found by the ellipse
    (the lengthwise crowning): a secant search on ``ellipse_length`` for the light-load
    pattern length, aimed by :func:`length_aim` (first step at
    :data:`LENGTH_PER_ELLIPSE`, then the measured slope, at least
    :data:`LENGTH_SLOPE_MIN`), bisecting once a design has met the length or overshot it
    and one has not, at most :data:`LENGTH_DESIGNS` designs (each a synthesis of steps 3-6
    placed and checked at :data:`CHECK_LTCA`, every other prescription kept). On a pattern
    too short the ellipse goes up to :func:`length_bound` (:data:`LENGTH_ELLIPSE_MAX`
    where the bounds are the defaults), and a design that meets the length short of the
    aim and is not kept is stepped on towards the aim like one that misses it (a longer
    ellipse lowers the light torque's LTE: on the FH 11x23 at Σ 70° the ellipse 0.75 met
    the length at 0.40, objective 9.83 against the design's 6.92, 0.85 at 0.45, 5.80),
    not halved back towards the design. The first
    design that meets the length, scores better, misses no target the design met and is
    tolerant is kept (:func:`kept_why`); where one meets the length and gives up the LTE
    alone, by at most :data:`NEAR_MISS` of its unit, it is tried once more with
    ``te_level`` :data:`LENGTH_TE_STEP` lower (``level`` [µrad]: the flank's own, where
    the design's values carry none), then once more with its root relief ×
    :data:`LENGTH_RELIEF_FRACTION` where the LTE is missed by at most
    :data:`LENGTH_RELIEF_LTE` (:func:`_shallower_relief`), before the search goes on.
    ``flank``: the flank analysed; on the coast flank (``key_prefix`` its kept pinion
    tooth's key before the design's bearing, :func:`checked_best`) no mounting excursion is
    analysed (the development's tolerance is the drive flank's) and a design is not kept
    whose flank peak pressure at any torque of the check exceeds ``best``'s, whatever the
    targets' ``max_flank_pressure`` (:func:`_length_lost`: the coast design torque, set
    by the coast flank's capacity, is not given up for the length).

    Why: no other check step moves a pattern into its length band. The path step turns
    the path (and shortens the ellipse only with a turn, lengthens it only where no turn
    is left), :func:`checked_ellipse` lengthens it by one step where only the LTE is
    missed, and :func:`checked_long` takes it to its upper bound, giving up the length for
    the LTE. On face-hobbed hypoids of benchmarks/data/unseen_designs (``benchmarks/
    development_levers.py --check --from-case``, 2026-11-27): the 6x61 at a 40 mm offset,
    its design torque lowered to its local pitting capacity (131 → 60.3 N m) after the
    search, so its light torque 19.6 → 9.0 N m: ellipse 0.55 at path −80°: pattern 0.35
    long (0.40 at path −58.8°, unchanged by the turn), 0.65: 0.40, 0.717: 0.43 (LTE 13 /
    13 µrad, tolerant), 0.75: 0.45 — 0.5 of the face per unit of ellipse at that light
    torque. The 7x39 at Σ 85° (ε_vβ 1.247, 23.8 / 159.2 N m, path −80°, ``te_level`` 25):
    the long bearing's ellipse 0.75: 0.70 long, LTE 16 / 20 µrad; 0.65: 0.62, 29 / 31;
    0.605: 0.62; 0.6: 0.60, 38 / 40.5 (the LTE target 40 missed); 0.59: 0.58, 40 / 43;
    0.6 with ``te_level`` 15: 0.60, 36 / 38 µrad, every target met. The step on it in
    ``ltca synthesize``: 0.625 (0.63 long), 0.562 (0.57, 46 / 49 µrad), 0.594 (0.57, 39 /
    42), 0.594 with ``te_level`` 15 (37 / 39 µrad, every target met, tolerant, kept); on
    the 6x61 one design, 0.717 (docs/synthesis.md, "The pattern's length at the
    check"). The coast flank had no length step: the spiral bevel 13x39 at Σ 80° of
    benchmarks/data/unseen_designs, its coast flank developed again at 48.9 / 197 N m
    (path −45°, ellipse 0.55): pattern 0.65 long against 0.5 ± 0.1, every other target
    met (docs/synthesis.md, "The coast flank's pattern length")."""
    name = "ellipse_length"
    if (not best.checked_full or best.full[1]["length"] == 0.0
            or name not in targets.variables or name not in best.values):
        return best
    lo, hi = (float(x) for x in targets.variables[name])
    x0, length0 = float(best.values[name]), pattern_length(best)
    band_hi = targets.pattern_length + targets.pattern_length_tolerance
    too_long = length0 > band_hi
    hi = length_bound(targets, too_long)
    aim = length_aim(length0, targets)
    far = [(x0, length0)]  # designs whose pattern misses the length as the design's does
    near: float | None = None  # the nearest ellipse that met the length or overshot it
    for _ in range(LENGTH_DESIGNS):
        fx, fl = far[-1]
        if near is None:
            slope = LENGTH_PER_ELLIPSE
            if len(far) > 1 and far[-1][0] != far[-2][0]:
                measured = abs((far[-1][1] - far[-2][1]) / (far[-1][0] - far[-2][0]))
                slope = max(LENGTH_SLOPE_MIN, measured) if math.isfinite(measured) else slope
            step = (aim - fl) / slope
            step = math.copysign(max(abs(step), SHORTER_ELLIPSE_STEP), step)
            x = float(np.clip(fx + step, lo, hi))
        else:
            x = 0.5 * (fx + near)
        x = round(x, 4)
        if abs(x - fx) < 1e-9 or any(abs(x - t) < 1e-9 for t, _ in far):
            break
        e = _said_variant(best, best.values | {name: x}, "length",
                          f"with the ellipse {x:.3g} (its pattern {length0:.2f} long)",
                          targets, setup, teeth, say, placed, flank=flank,
                          key_prefix=key_prefix)
        if e is None:
            break
        length = pattern_length(e)
        if e.full[1]["length"] > 0.0 and (length > band_hi) == too_long:
            far.append((x, length))
            continue
        if e.full[1]["length"] > 0.0:  # overshot the band
            near = x
            continue
        lost = _length_lost(targets, flank)
        tolerant = flank == "drive"
        why = kept_why(best, e, targets, setup, teeth, say, "the ellipse for the length",
                       lost=lost, tolerant=tolerant)
        if not why:
            return e
        if not too_long and length < aim - 1e-9 and x < hi - 1e-9:
            far.append((x, length))  # short of the aim: a longer ellipse still may keep it
        else:
            near = x
        if (lost(best, e) == ["lte"] and e.full[1]["lte"] <= NEAR_MISS
                and TE_NAME in targets.variables):
            t_lo = float(targets.variables[TE_NAME][0])
            now = float(e.values.get(TE_NAME, level))
            level = max(t_lo, now - LENGTH_TE_STEP)
            if math.isfinite(now) and level < now - 1e-9:
                f = _said_variant(best, e.values | {TE_NAME: level}, "length",
                                  f"with the ellipse {x:.3g} at {TE_NAME} {level:.3g} urad "
                                  "(the length met, its LTE missed)",
                                  targets, setup, teeth, say, placed, flank=flank,
                                  key_prefix=key_prefix)
                if not kept_why(best, f, targets, setup, teeth, say,
                                "the ellipse for the length with the lower TE level",
                                lost=lost, tolerant=tolerant):
                    return f
        if (lost(best, e) == ["lte"] and e.full[1]["lte"] <= LENGTH_RELIEF_LTE
                and (f := _shallower_relief(best, e, x, targets, setup, teeth, say,
                                            placed, flank=flank,
                                            key_prefix=key_prefix)) is not None):
            return f
    return best


def _shallower_relief(best: DevelopmentEvaluation, e: DevelopmentEvaluation, x: float,
                      targets: DevelopmentTargets, setup: Mapping[str, Any],
                      teeth: KeptTeeth | None, say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case], *,
                      flank: str = "drive", key_prefix: tuple | None = None
                      ) -> DevelopmentEvaluation | None:
    """:func:`checked_length`'s design ``e`` (the ellipse ``x``) that meets the length
    and gives up the LTE alone, by at most :data:`LENGTH_RELIEF_LTE`, tried with its root relief
    × :data:`LENGTH_RELIEF_FRACTION` (within its bounds; step 7 only); the design kept
    (:func:`kept_why`), else None."""
    name = "root_relief"
    if name not in targets.variables or not float(e.values.get(name, 0.0)) > 0.0:
        return None
    r_lo, r_hi = (float(v) for v in targets.variables[name])
    now = float(e.values[name])
    r = float(np.clip(LENGTH_RELIEF_FRACTION * now, r_lo, r_hi))
    if not r < now - 1e-9:
        return None
    f = _said_variant(best, e.values | {name: r}, "length",
                      f"with the ellipse {x:.3g} and {name} {r:.3g} um (the length met, "
                      "its LTE missed)", targets, setup, teeth, say, placed, flank=flank,
                      key_prefix=key_prefix)
    if kept_why(best, f, targets, setup, teeth, say,
                "the ellipse for the length with the shallower root relief",
                lost=_length_lost(targets, flank), tolerant=flank == "drive"):
        return None
    return f


def _length_lost(targets: DevelopmentTargets, flank: str
                 ) -> Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]]:
    """:func:`checked_length`'s lost targets on ``flank``: :func:`_lost_targets`; on the
    coast flank with the flank peak pressure raised above ``best``'s at any torque of the
    check, the light one too, whatever the targets' ``max_flank_pressure``
    (:func:`_pressure_raised` with no bound; not said twice where the ``pressure`` target
    itself is lost): the length step does not trade the coast flank's capacity for the
    length.

    Why every torque and no bound: the coast design torque is searched after the coast
    development, on the developed bearing, from the drive's design torque down to where
    the coast flank holds (:func:`~contact.optimize.development_coast_flank.
    coast_flank_capacity`: its static strength and local pitting safety S_H,loc ∝ 1/p
    among its criteria), and a later step may raise it again where the peak allows
    (:func:`~contact.optimize.development_coast_steps.checked_coast_peak`). The drive's
    design torque may be cut after the coast development, so the search starts between
    the light torque and the torque the coast flank was developed at; and the bound of a
    coast flank developed again at its own design torque (its local pitting safety at
    S_Hmin there, :func:`~contact.optimize.development_coast_flank.pitting_pressure`)
    holds that torque only, not the higher one the search or the peak step would find on
    a bearing of lower peak. A bearing whose peak is no higher than ``best``'s at both
    ends of the check's range allows the search no lower torque. Measured on the FM
    hypoid 5x35 at Σ 85° (benchmarks/data/unseen_designs, ``ltca synthesize``,
    2026-11-27; issue 71): its coast flank developed at 11.1 / 72.9 N m kept the ellipse
    0.465 for the length at 848 / 2367 MPa against the design's 807 / 2378 MPa (S_H,loc
    0.77 at the coast design torque 51.1 N m, where the design has 0.82); developed again
    at 33.7 N m, the ellipse 0.481 at 788 / 1157 MPa against 777 / 1128 (within the
    pitting bound 1420 MPa) replaced the first design, whose lighter tip relief carries
    40.2 N m: its coast design torque 40.2 → 28.4 N m with the length step as it was,
    40.2 with this rule (docs/synthesis.md, "The coast length step keeps the coast
    capacity")."""
    if flank == "drive":
        return _lost_targets
    unbounded = dataclasses.replace(targets, max_flank_pressure=None)

    def lost(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        gone = _lost_targets(best, e)
        raised = ""
        if "pressure" not in gone:
            # the design torque first (its text as the other coast steps'), then the rest
            n = len(e.metrics["pressure_max_flank"])
            for i in (-1, *range(n - 1)):
                raised = _pressure_raised(best, e, unbounded, index=i)
                if raised:
                    break
        return gone + ([raised] if raised else [])

    return lost


#: the near-miss step (:func:`checked_near_miss`): a missed target is near where its
#: shortfall (:func:`development_score`'s units) is at most this: the light-load centre v
#: within half its tolerance beyond it (0.04 of the working depth by default), the LTE
#: within 5 µrad, the pattern length within 0.05 of the face
NEAR_MISS = 0.5
#: where the near-miss step aims the light-load centre v: this fraction of
#: ``centre_tolerance`` inside the band's nearer bound (a step to the bound itself leaves
#: the centre on it, a node of the check's grid off)
NEAR_MISS_AIM = 0.25
#: [µrad] how far the near-miss step lowers ``te_level`` with its blade-angle step (the TE
#: stage's step at the check, :func:`checked_te`)
NEAR_MISS_TE_STEP = 20.0
#: most designs of the near-miss step (:func:`checked_near_miss`)
NEAR_MISS_DESIGNS = 3


def _met_count(e: DevelopmentEvaluation) -> int:
    """The number of targets a checked design meets (its shortfalls at 0)."""
    return sum(1 for v in e.full[1].values() if v == 0.0)


def near_miss(e: DevelopmentEvaluation, limit: float = NEAR_MISS) -> bool:
    """Whether a checked design misses its light-load centre v, and misses nothing by more
    than ``limit`` (:data:`NEAR_MISS`, in :func:`development_score`'s shortfall units)."""
    if not e.checked_full or e.full[2]:
        return False
    short = e.full[1]
    return short.get("centre_v", 0.0) > 0.0 and max(short.values()) <= limit


def checked_near_miss(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: Mapping[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case], level: float, *,
                      slope: float | None = None) -> DevelopmentEvaluation:
    """A design that misses its targets by a small margin after every other check step,
    its light-load centre v among them (:func:`near_miss`), given a small blade-angle
    step with its TE level lowered: the pinion's blade-angle change
    (:data:`~contact.optimize.development_targets.HEIGHT_NAME`) stepped so that the centre
    v moves :data:`NEAR_MISS_AIM` of its tolerance inside the band (linear, ``slope``
    [1/deg] d(centre v)/d(blade angle): the slope the height stage measured on the
    design's bearing where given, else :data:`~contact.optimize.development_stages.
    HEIGHT_SLOPE`), and ``te_level`` lowered by :data:`NEAR_MISS_TE_STEP` (within its
    bounds; ``level`` [µrad]: the flank's own level where the design's values do not
    give one). Each design (a synthesis of steps 3-6) placed and checked at
    :data:`CHECK_LTCA`; where one is not kept, the next takes the slope measured (a
    secant: between the design and the first step, then between the last two steps, at
    the same TE level), towards the same aim. At most
    :data:`NEAR_MISS_DESIGNS` designs; a design is kept only where it meets more targets,
    gives up none it met and is tolerant (:func:`_tolerant_variant`) — not on the
    objective, whose LTE term may prefer the design as it was. Where a blade step gave up
    the edge or plastic target, the blade step aimed at the target centre with the
    pinion's tip edge relieved and the profile crowned
    (:func:`~contact.optimize.development_height_relieved.checked_height_relieved`); where
    that keeps nothing and the smallest blade
    step was refused for the LTE or the pattern length alone, two more
    (:func:`~contact.optimize.development_band_edge.band_edge_designs`): the smallest
    blade step into the band, then with the path turned.

    Why: the search and the check's other steps develop the height with large levers
    (the root-find of the height stage, the tip and root reliefs); where the check leaves
    the centre just outside its band, the height stage has not run on that bearing or
    its step was coarse, and a blade-angle step small enough to keep the LTE costs a
    little unloaded TE at the light torque, which the TE level buys back (the parabola of
    the modified roll absorbs the tilt's transfer; Litvin & Fuentes 2004 §9.4; Stadtfeld,
    *Gleason Bevel Gear Technology*, 2014: pressure angle for the height). Measured on the
    unseen hypoid 10x41 at its user's 100 N m (benchmarks/data/unseen_designs; ``ltca
    run``'s sampling at 15 / 100 N m, ``benchmarks/development_levers.py --check``,
    2026-11-26; v, LTE p-p light / design): as written 0.63 (0.543 ± 0.08), 33.7 / 22.1
    µrad; blade angle −0.036°: 0.60, 40.6 / 21.4 (the LTE target 40 missed); −0.06°: 0.58,
    45.0 / 22.5; ``te_level`` 45 → 25 alone: 0.63, 28.8 / 23.8; both: 0.60, 34.6 / 25.9 µrad,
    every target met."""
    from contact.optimize.development_stages import HEIGHT_SLOPE

    if (not near_miss(best) or HEIGHT_NAME not in targets.variables
            or HEIGHT_NAME not in best.values or not math.isfinite(footprint_centre_v(best))):
        return best
    lo, hi = (float(x) for x in targets.variables[HEIGHT_NAME])
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    v0, x0 = footprint_centre_v(best), float(best.values[HEIGHT_NAME])
    aim = target + math.copysign((1.0 - NEAR_MISS_AIM) * targets.centre_tolerance,
                                 v0 - target)
    te = dict(best.values).get(TE_NAME, level) if TE_NAME in targets.variables else None
    lowered = (None if te is None else
               float(max(targets.variables[TE_NAME][0], float(te) - NEAR_MISS_TE_STEP)))
    if lowered is not None and lowered >= float(te) - 1e-9:
        lowered = None
    s = slope if slope is not None and slope > 0.05 else HEIGHT_SLOPE
    te_text = f", {TE_NAME} {lowered:.3g} urad" if lowered is not None else ""
    steps: list[tuple[float, float]] = []  # (blade angle, centre v) of each design
    refused: list[DevelopmentEvaluation] = []  # the designs analysed and not kept
    for _ in range(NEAR_MISS_DESIGNS):
        xa, va = steps[-1] if steps else (x0, v0)
        x = float(np.clip(xa - (va - aim) / s, lo, hi))
        if abs(x - x0) < 1e-4 or any(abs(x - t) < 1e-3 for t, _ in steps):
            break
        values = dict(best.values) | {HEIGHT_NAME: x}
        if lowered is not None:
            values[TE_NAME] = lowered
        e = _said_variant(best, values, "near miss",
                          f"with {HEIGHT_NAME} {x:.3g} deg{te_text} (its centre v just off "
                          "its band)", targets, setup, teeth, say, placed)
        if e is None:
            break
        if not kept_why(best, e, targets, setup, teeth, say, "the blade-angle step",
                        lost=_lost_targets, lost_first=True,
                        better=lambda b, x: _met_count(x) > _met_count(b)):
            return e
        refused.append(e)
        v = footprint_centre_v(e)
        if not math.isfinite(v):
            break  # no pattern to step from
        steps.append((x, v))
        (xa, va), (xb, vb) = ((x0, v0), steps[0]) if len(steps) == 1 else steps[-2:]
        if not (vb - va) / (xb - xa) > 0.05:
            break  # no slope to step on
        s = (vb - va) / (xb - xa)  # the slope measured: the next design a secant
    # the blade steps that gave up the edge or plastic target: the same aimed at the
    # target centre with the pinion's tip edge relieved and the profile crowned
    # (development_height_relieved; the truck hypoid 8x47)
    from contact.optimize.development_height_relieved import checked_height_relieved
    relieved = checked_height_relieved(best, refused, targets, setup, teeth, say, placed,
                                       better=lambda b, x: _met_count(x) > _met_count(b))
    if relieved is not None:
        return relieved
    values = dict(best.values) | ({TE_NAME: lowered} if lowered is not None else {})
    return band_edge_designs(best, refused, targets, setup, teeth, say, placed,
                             centre_v=footprint_centre_v,
                             better=lambda b, x: _met_count(x) > _met_count(b),
                             values=values, te_text=te_text)


#: the lever of the pattern's centre along the face (toe–heel): the mean point M placed
#: off the gear's mean cone distance, a fraction of the face width, > 0 towards the heel
#: (:class:`geometry.synthesis.basic_design.FlankOptions` ``mean_point_shift``, step 3 of
#: the synthesis)
SHIFT_NAME = "mean_point_shift"
#: the bounds of :data:`SHIFT_NAME` [1, fraction of the face width] where the targets'
#: ``variables`` do not give them: M a fifth of the face either side of the mean cone
#: distance keeps the contact ellipse at M (0.4-0.75 of the face long) on the flank
SHIFT_BOUNDS = (-0.2, 0.2)
#: first guess of d(centre u)/d(:data:`SHIFT_NAME`) [1] of :func:`checked_centre_u`'s
#: secant, before it has measured its own: on the bundled basic file
#: cases/basic/kolivand2009_fm_11x41.toml (its development's design 35, ``ltca run``'s
#: sampling at 61.9 N m) M placed 0 / −0.1 / −0.2 of the face off the mean cone distance
#: put the light-load centre u at 0.62 / 0.52 / 0.43 (path −55°, ellipse 0.55) and 0.68 /
#: 0.58 (path −70°, ellipse 0.6): 0.96 per unit, the pattern following M along the face
CENTRE_U_SLOPE = 0.95
#: least secant slope d(centre u)/d(shift) [1] :func:`checked_centre_u` steps on; below it
#: (the pattern did not follow M) the step ends
CENTRE_U_LEAST_SLOPE = 0.2
#: :func:`checked_centre_u` aims this fraction of the centre tolerance inside the band, on
#: the side the centre missed it (the band's near half: a pattern moved no further
#: towards the toe or heel than the target needs)
CENTRE_U_AIM = 0.5
#: most designs of :func:`checked_centre_u` (each a synthesis of steps 3-6 and an analysis
#: at :data:`CHECK_LTCA`)
CENTRE_U_DESIGNS = 3
#: [1] :func:`checked_centre_u` stops where a design's centre u is this close to its aim:
#: less than a node of ``ltca run``'s gear grid (0.025 of the face), a secant step on
#: would not move the pattern (the bundled 11x41: −0.137 gave u 0.49 at the aim 0.49, and
#: the step on, −0.139, the same pattern)
CENTRE_U_CLOSE = 0.02


def centre_u_of(e: DevelopmentEvaluation) -> float:
    """[1] The light-load footprint centre u of a design (toe 0 → heel 1), NaN where its
    metrics have none."""
    if e.metrics is None or "pattern_centre_u" not in e.metrics:
        return math.nan
    return float(np.asarray(e.metrics["pattern_centre_u"], float)[0])


def checked_centre_u(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case], *,
                     flank: str = "drive", key_prefix: tuple | None = None
                     ) -> DevelopmentEvaluation:
    """The pattern's centre along the face by the mean point's place: where the chosen
    design misses its light-load centre u at the check, M placed off the mean cone
    distance (:data:`SHIFT_NAME`, within ``targets.variables``' bounds where given, else
    :data:`SHIFT_BOUNDS`) by a 1-D root-find on u, the secant of the height stage's on v
    (:data:`CENTRE_U_SLOPE` first, then the slope measured): aimed
    :data:`CENTRE_U_AIM` of the tolerance inside the band on the side it missed, at most
    :data:`CENTRE_U_DESIGNS` designs, each placed and checked at :data:`CHECK_LTCA`
    (a synthesis of steps 3-6: the local synthesis at the new M) and kept by
    :func:`kept_why` (better — it ranks before the design, or it meets more targets, as
    :func:`checked_near_miss` counts them: the objective's LTE terms may prefer a pattern
    off its centre to one a few µrad louder — no met target lost but the centre v,
    tolerant). ``flank``: the flank analysed (``"coast"``: the coast flank's own M,
    :func:`_coast_centre_kept`'s rule; ``key_prefix`` its kept pinion tooth's key before
    the design's bearing, as :func:`checked_coast_lte`'s). The centre
    v may be lost: M is centred in roll within the working depth at its new cone
    distance, which moves the pattern's height a little, and the height steps after this
    one (:func:`checked_tip`, :func:`checked_root`, :func:`checked_near_miss`) take a
    pattern off its depth band back (a blade-angle step with it was tried and cost more
    than it gave: below). A design that meets its centre u is returned as it is, without
    an analysis.

    Why: the bearing's other levers move the pattern in depth (the blade angle, the
    profile crowning, the reliefs) or change its length and bias (the path angle and the
    ellipse), not its place along the face; in the field the pattern is moved toe/heel by
    the pinion's spiral angle, the linear lengthwise term of the ease-off (e(u) =
    c (u − u0)² = c u² − 2 c u0 u + …: the crowning's vertex u0 moves), which in the local
    synthesis is the mean contact point M placed off the mean cone distance (Litvin &
    Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.2: M is any point of
    the gear flank; Stadtfeld, *Gleason Bevel Gear Technology*, 2014: the spiral angle
    for the toe-heel position). Measured on the bundled basic file
    cases/basic/kolivand2009_fm_11x41.toml (:data:`CENTRE_U_SLOPE`): every one of the
    35 designs its search analysed put u at 0.57-0.73 (target 0.45 ± 0.08); its chosen
    design (path −70°, ellipse 0.6, ``ltca run``'s sampling at 61.9 / 412.9 N m: u 0.67,
    v 0.60, LTE 47 / 53 µrad, 0.4 % plastic, objective 25.8) with M placed −0.192 of the
    face: u 0.50, v 0.63 (band 0.543 ± 0.08), LTE 45 / 59 µrad, no plastic segment,
    objective 4.41; the same M with the blade angle stepped 0.0415 → −0.113° to bring v
    back: v 0.55 but LTE 86 / 81 µrad and 0.1 % plastic, objective 41.2. A design whose
    centre u is met but which is not kept (not tolerant, or a target given up) is followed
    by M half-way back to the design kept, where the pattern, linear in M, still meets its
    band: the 11x41's second M step, from −0.137 (u 0.54) to −0.192 (u 0.49), was not
    tolerant (a plastic segment at ΔP −0.05 mm)."""
    if not best.checked_full or best.full[1].get("centre_u", 0.0) == 0.0:
        return best
    u0 = centre_u_of(best)
    if not math.isfinite(u0):
        return best
    lo, hi = (float(x) for x in targets.variables.get(SHIFT_NAME, SHIFT_BOUNDS))
    x0 = float(best.values.get(SHIFT_NAME, 0.0))
    aim = targets.pattern_centre_u + math.copysign(
        (1.0 - CENTRE_U_AIM) * targets.centre_tolerance, u0 - targets.pattern_centre_u)
    start, s = best, CENTRE_U_SLOPE
    kept = (x0, u0)  # (shift, centre u) of the design kept so far
    steps: list[tuple[float, float]] = []  # (shift, centre u) of each design
    x = float(np.clip(x0 - (u0 - aim) / s, lo, hi))
    for _ in range(CENTRE_U_DESIGNS):
        x = round(x, 4)
        if abs(x - x0) < 1e-3 or any(abs(x - t) < 1e-3 for t, _ in steps):
            break
        side = "toe" if x < x0 else "heel"
        values = dict(start.values) | {SHIFT_NAME: x}
        e = _said_variant(start, values, "centre u",
                          f"with M placed {x:+.3g} of the face off the mean cone distance "
                          f"(towards the {side}: its centre u {u0:.2f} off "
                          f"{targets.pattern_centre_u:g} ± {targets.centre_tolerance:g})",
                          targets, setup, teeth, say, placed, flank=flank,
                          key_prefix=key_prefix)
        if e is None:
            break
        u = centre_u_of(e)
        if flank == "drive":
            why = kept_why(best, e, targets, setup, teeth, say, "M's place",
                           lost=_lost_but_depth,
                           better=lambda b, x: _ranks_better(b, x)
                           or _met_count(x) > _met_count(b))
        else:
            why = _coast_centre_kept(best, e, targets, say)
        if not why:
            best, kept = e, (x, u)
            if e.full[1]["centre_u"] == 0.0:
                break
        if not math.isfinite(u):
            break  # no pattern to step from
        steps.append((x, u))
        if why and e.full[1]["centre_u"] == 0.0:
            # its centre met, but not kept (not tolerant, or a target given up): M half-way
            # back to the design kept, where the pattern (linear) still meets its band
            if abs(0.5 * (u + kept[1]) - targets.pattern_centre_u) >= targets.centre_tolerance:
                break
            x = 0.5 * (x + kept[0])
            continue
        if abs(u - aim) < CENTRE_U_CLOSE:
            break  # a step on would move the pattern less than a node
        (xa, ua), (xb, ub) = ((x0, u0), steps[0]) if len(steps) == 1 else steps[-2:]
        if not (ub - ua) / (xb - xa) > CENTRE_U_LEAST_SLOPE:
            break  # the pattern did not follow M
        s = (ub - ua) / (xb - xa)  # the slope measured: the next design a secant
        x = float(np.clip(xb - (ub - aim) / s, lo, hi))
    return best


def _coast_centre_kept(best: DevelopmentEvaluation, e: DevelopmentEvaluation | None,
                       targets: DevelopmentTargets, say: Callable[[str], None]) -> str:
    """:func:`checked_centre_u`'s keep rule on the coast flank: why ``e`` does not replace
    ``best``, empty where it does. Kept where it is better (it ranks before ``best`` or
    meets more targets, as on the drive flank), gives up no target ``best`` met
    (:func:`_lost_targets`: no height step follows on the coast flank to re-centre the
    depth) and its flank peak pressure at the design torque is no higher than ``best``'s
    or within the targets' ``max_flank_pressure`` (:func:`_pressure_raised`: the coast
    design torque, set afterwards by the coast flank's capacity, is not given up for it).
    No mounting excursion is analysed (the development's tolerance is the drive
    flank's)."""
    if e is None:
        return "it could not be analysed"
    if not (_ranks_better(best, e) or _met_count(e) > _met_count(best)):
        return "it scores no better"
    lost = _lost_targets(best, e)
    raised = _pressure_raised(best, e, targets)
    if raised:
        lost.append(raised)
    if lost:
        say(f"  not kept: M's place misses {', '.join(lost)}")
        return f"it misses {', '.join(lost)}"
    return ""
