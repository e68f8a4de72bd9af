"""The coast flank's LTE bought with its local pitting margin, within its capacity (issue 71).

The coast LTE steps (:mod:`contact.optimize.development_coast_steps`) keep a design only
where its flank peak pressure at the coast design torque is no higher than the design's
or within the targets' ``max_flank_pressure`` — where the coast design torque was set by
its local pitting safety, the peak at which S_H,loc = S_Hmin
(:func:`~contact.optimize.development_coast_flank.pitting_pressure`). On a flank at that
bound every bearing that brings its LTE within the verdict's 60 µrad is refused, however
far its peak stays below the static strength, and the case is written with an LTE the
verdict flags. :func:`checked_coast_capacity_lte` gives such a coast design the longest
ellipse, its light-load pattern's clearance to toe and heel by M's place and lighter
reliefs, and keeps one on a rule of its own (:func:`capacity_kept`): the verdict's LTE
limit met at every torque where the design misses it — at its two torques and between
them, as ``ltca run --flank coast``'s ``lte_range`` step judges it (:func:`coast_range_peak`,
the development's :func:`~contact.optimize.development_range_lte.range_lte` on the coast
flank) —, no plastic segment, no target the
design met lost but the pattern length, the pitting bound and the edge share at the design
torque where its edges are no harder loaded (:func:`edges_harder`), and its peak within the
flank's static strength — the verdict's FAIL limit and the bound of the coast capacity
search's ``flank`` criterion. The coast design torque is at or below the coast side's ISO
10300 capacity already (:func:`~contact.optimize.development_coast_flank.
coast_rated_torque`; or the basic file's ``coast_design_torque``), and the rating reads the
basic data, not the bearing: the rating's S_H at it is the same whatever the bearing. The
local safety S_H,loc the kept design has at the coast design torque is said (∝ 1/p: the
pitting bound × S_Hmin / p, :func:`capacity_text`). :func:`coast_lte_within_capacity` runs
it on the written case's coast flank at its own torques, after every other coast step;
:func:`coast_torque_that_holds` then searches the coast design torque again on the bearing
kept, down to where it holds on every criterion, S_H,loc ≥ S_Hmin among them, and keeps it
where its LTE is within the limit there (else the design before the step is written): the
coast design torque written is one at which the coast flank holds, its LTE included.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_coast import CoastCapacity
from contact.optimize.development_coast_ellipse_between import ellipse_between_designs
from contact.optimize.development_coast_flank import (
    coast_flank_capacity,
    pitting_pressure,
    written_coast,
)
from contact.optimize.development_coast_steps import COAST_LIGHTER_RELIEF_STEPS
from contact.optimize.development_deflection import within_torque
from contact.optimize.development_edge_peak import edge_gain
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import lost_targets
from contact.optimize.development_pattern_steps import (
    CENTRE_U_SLOPE,
    SHIFT_BOUNDS,
    SHIFT_NAME,
)
from contact.optimize.development_range_lte import range_lte, range_peak
from contact.optimize.development_result import DevelopmentEvaluation, floor_torque
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import changed_values, lte_fails, said_variant
from geometry.case import Case
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import BasicDesign

log = logging.getLogger("contact.optimize.development")

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "coast lte capacity"

#: the targets a design of :func:`checked_coast_capacity_lte` may give up: the pattern
#: length (as every coast LTE step, :func:`~contact.optimize.development_keep.
#: lost_but_length`) and the flank pressure target, which on the coast flank at its
#: pitting-set design torque is the local pitting bound, not the static strength (that
#: one :func:`capacity_kept` asks itself)
MAY_LOSE = ("length", "pressure")

#: the step's last designs, each on the longest-ellipse design with its clearance back
#: (factors [1] of its reliefs, within their bounds): its root relief × ⅔, then the coast
#: LTE steps' lighter reliefs (:data:`~contact.optimize.development_coast_steps.
#: COAST_LIGHTER_RELIEF_STEPS`: the tip relief × ⅔; the tip and root relief × ⅔). The
#: root relief first: on the 10x31 z0 3 the lighter tip relief put 2.2 % of the coast
#: design torque on the edges (the target 2 %, met before), the root relief did not
LIGHTER_RELIEFS = ((("root_relief", 2.0 / 3.0),), *COAST_LIGHTER_RELIEF_STEPS)

#: [1 of the face] what :func:`clearance_shift` gives a pattern end beyond the targets'
#: ``clearance``: a node column of ``ltca run``'s sampling (0.025 of the face), the
#: pattern's ends being read on its nodes
CLEARANCE_MARGIN = 0.025

#: least change of M's place [1 of the face] :func:`clearance_shift` asks for before a
#: design is made of it
SHIFT_LEAST = 0.005


def longest_ellipse(values: Mapping[str, float], targets: DevelopmentTargets
                    ) -> dict[str, float] | None:
    """The first design of :func:`checked_coast_capacity_lte`: ``values`` [file units] with
    ``ellipse_length`` at the upper bound of its variable; None where the targets do not
    vary it or ``values`` lack it. (At the bound already: ``values`` as they are.)

    Parameters
    ----------
    values : mapping name → float
        The coast design's prescriptions [file units].
    targets : DevelopmentTargets
        Its ``variables`` (the bounds).

    Returns
    -------
    dict or None

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4 (the
    contact ellipse's length, the lengthwise crowning); docs/synthesis.md, "The coast LTE
    within the flank's capacity".
    """
    name = "ellipse_length"
    if name not in targets.variables or name not in values:
        return None
    return dict(values) | {name: float(max(targets.variables[name]))}


def clearance_shift(e: DevelopmentEvaluation, targets: DevelopmentTargets) -> float:
    """M's place [1 of the face, ``mean_point_shift``] that gives ``e``'s light-load
    pattern, where one end is short of the targets' ``clearance`` to the toe or the heel,
    that clearance plus :data:`CLEARANCE_MARGIN` there: its place plus the gap missing over
    :data:`~contact.optimize.development_pattern_steps.CENTRE_U_SLOPE` (the pattern
    following M along the face), towards the other end, no further than centres the
    pattern between the two, within the variable's bounds
    (:data:`~contact.optimize.development_pattern_steps.SHIFT_BOUNDS` where the targets do
    not vary it). Its own place where both ends have their clearance (or both miss it);
    NaN where the pattern's ends are not finite.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A checked design (its ``pattern_toe_u``, ``pattern_heel_u`` at the light torque,
        [1 of the face]).
    targets : DevelopmentTargets
        Its ``clearance`` [1] and ``variables`` (the bounds).

    Returns
    -------
    float — [1]

    Raises
    ------
    Nothing.

    Notes
    -----
    The least move: the pattern centred between its ends put the 10x31's centre u off its
    band (0.45 ± 0.08), a target the design met. Source:
    :func:`~contact.optimize.development_pattern_steps.checked_centre_u` (M placed off the
    mean cone distance moves the pattern along the face; Litvin & Fuentes 2004, §9.2).
    """
    toe = float(e.metrics["pattern_toe_u"][0])
    gap_heel = 1.0 - float(e.metrics["pattern_heel_u"][0])
    now = float(e.values.get(SHIFT_NAME, 0.0))
    if not (math.isfinite(toe) and math.isfinite(gap_heel)):
        return math.nan
    need = targets.clearance + CLEARANCE_MARGIN
    half = 0.5 * (gap_heel - toe)  # [1 of the face] the move that centres it, > 0 heel
    if toe < targets.clearance <= gap_heel:
        du = min(need - toe, half)
    elif gap_heel < targets.clearance <= toe:
        du = max(-(need - gap_heel), half)
    else:
        return now
    lo, hi = (float(x) for x in targets.variables.get(SHIFT_NAME, SHIFT_BOUNDS))
    return float(np.clip(now + du / CENTRE_U_SLOPE, lo, hi))


def lighter_reliefs(values: Mapping[str, float], targets: DevelopmentTargets
                    ) -> list[dict[str, float]]:
    """The designs of :data:`LIGHTER_RELIEFS` about ``values`` [file units]: each relief ×
    its factor within its variable's bounds; a step naming a relief the targets do not
    vary or ``values`` lack, or that changes nothing, left out.

    Parameters
    ----------
    values : mapping name → float
        The design's prescriptions [file units].
    targets : DevelopmentTargets
        Its ``variables`` (the bounds).

    Returns
    -------
    list of dict

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: :func:`~contact.optimize.development_coast_steps.checked_coast_lighter_relief`
    (the relief sized to the load's deflection; Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014).
    """
    out: list[dict[str, float]] = []
    for changes in LIGHTER_RELIEFS:
        new = dict(values)
        for name, factor in changes:
            if name not in targets.variables or name not in values:
                break
            lo, hi = (float(x) for x in targets.variables[name])
            new[name] = float(np.clip(factor * float(values[name]), lo, hi))
        else:
            if any(abs(new[n] - float(values[n])) > 1e-9 for n, _ in changes):
                out.append(new)
    return out


def capacity_kept(best: DevelopmentEvaluation, e: DevelopmentEvaluation | None,
                  targets: DevelopmentTargets, limit: float, static: float, *,
                  between: tuple[float, float] | None = None) -> str:
    """Why the coast design ``e`` does not replace ``best`` on the rule of
    :func:`checked_coast_capacity_lte`, empty where it does.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design kept so far, checked; its LTE p-p above ``limit`` at a torque.
    e : DevelopmentEvaluation or None
        The step's design (None: its synthesis or analysis failed).
    targets : DevelopmentTargets
        Its ``max_plastic_share`` [1].
    limit : float — [µrad]
        The verdict's LTE limit.
    static : float — [MPa]
        The coast flank's static strength (the verdict's flank-pressure FAIL limit).
    between : (float, float), optional — [µrad], [N·m]
        ``e``'s largest LTE p-p over ``ltca run``'s ``lte_range`` torques on the coast
        flank and its torque (:func:`~contact.optimize.development_range_lte.range_peak`
        of :func:`~contact.optimize.development_range_lte.range_lte`, its own two torques
        among them); judged where given and finite, else the LTE at its own torques alone.

    Returns
    -------
    str
        Empty where ``e`` is kept: its LTE p-p within ``limit`` at every torque (and
        between them where ``between`` is given), no plastic share above
        ``max_plastic_share``, no target ``best`` met missed but those of
        :data:`MAY_LOSE` (and the edge share where :func:`edges_harder` is False: the
        edge peak not raised), and its flank peak pressure at the design torque within
        ``static``; else the reason.

    Raises
    ------
    Nothing.

    Notes
    -----
    The peak may rise past the coast flank's local pitting bound, which the coast LTE
    steps' rule (:func:`~contact.optimize.development_keep.pressure_raised`) does not
    allow: what the coast design torque needs is the static strength (the verdict's
    FAIL) and the rating's S_H ≥ S_Hmin, which the torque holds at or below the coast
    side's ISO 10300 capacity (ISO 10300-2:2014, the capacity search of
    :mod:`contact.load_capacity.iso10300.capacity`); the LTE limit is the verdict's own
    (:data:`contact.study.verdicts.LTE_LIMIT`). Source: issue 71 ("LTE p-p ≤ 60 µrad at
    every torque", both flanks).
    """
    if e is None or e.full is None or e.metrics is None:
        return "it could not be analysed"
    lte = float(np.nanmax(e.metrics["lte_peak_to_peak"]))
    if not lte <= limit:
        return f"its LTE p-p {lte:.0f} urad above {limit:g}"
    if between is not None and math.isfinite(between[0]) and not between[0] <= limit:
        return (f"its LTE p-p {between[0]:.1f} urad at {plain_number(between[1])} N m, "
                f"between the torques, above {limit:g}")
    plastic = float(np.max(e.metrics["plastic_share"]))
    if plastic > targets.max_plastic_share:
        return f"plastic segments carry {100 * plastic:.2g} % of the torque"
    gone = [k for k in lost_targets(best, e) if k not in MAY_LOSE]
    if "edge" in gone and not edges_harder(best, e):
        gone.remove("edge")
    if gone:
        return f"it misses {', '.join(gone)}" + _edge_said(best, e, gone)
    peak = float(e.metrics["pressure_max_flank"][-1])
    if not peak <= static:
        return f"its flank peak {peak:.0f} MPa above the static strength {static:.0f} MPa"
    return ""


def edges_harder(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> bool:
    """Whether the coast design ``e`` loads its edges harder than ``best`` at the design
    torque: its largest edge peak (``metrics["edge_peak"]``, ``ltca run``'s
    ``edge_pressure`` check's) above ``best``'s by more than the sampling's resolution
    (:func:`~contact.optimize.development_edge_peak.edge_gain`). Where either lacks the
    edge peak (no material named), True: the edge share target is then kept as it is.

    Parameters
    ----------
    best, e : DevelopmentEvaluation
        The coast design kept so far and the step's design, checked at the coast flank's
        light and design torque (``edge_peak`` [MPa] per torque, light first).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    :func:`capacity_kept` lets a design give up the edge share target (at most
    ``max_edge_share`` of the design torque on the edges, 2 %) where its edges are no
    harder loaded than the design's: the share at the design torque is no criterion of
    issue 71's (its verdict says edge contact at the design torque as an attention at any
    share from :data:`~contact.ltca.plausibility.EDGE_SHARE_MIN`; no edge contact at 15 %
    of the design torque is the light-load pattern's clearance, a target kept), the edge
    peak pressure is what the flank under the edge carries (``ltca run``'s
    ``edge_pressure`` attention) and no plastic segment is asked by
    :func:`capacity_kept` itself. Measured on the face-hobbed spiral bevel 13x31 z0 7's
    coast flank (round 21, 44.1 / 294 N m, ``benchmarks/development_levers.py --flank coast
    --from-case --check --at``): the design 64 / 77 µrad (80 at 210.7 N m), 1.8 % on the
    edges at a peak of 4455 MPa; its longest ellipse with the lighter tip and root reliefs
    37 / 49 µrad (53 at most between), 2.9 % on the edges at 4421 MPa, flank peak 1642 →
    1582 MPa. Source: issue 71 ("no edge contact at 15 % of the design torque, LTE p-p
    ≤ 60 µrad at every torque").
    """
    if (e.metrics is None or best.metrics is None or "edge_peak" not in e.metrics
            or "edge_peak" not in best.metrics):
        return True
    was = float(np.asarray(best.metrics["edge_peak"], float)[-1])
    now = float(np.asarray(e.metrics["edge_peak"], float)[-1])
    if not (math.isfinite(was) and math.isfinite(now)):
        return True
    return now > was + edge_gain(best)


def _edge_said(best: DevelopmentEvaluation, e: DevelopmentEvaluation,
               gone: list[str]) -> str:
    """The edge numbers behind a lost ``"edge"`` target in :func:`capacity_kept`'s
    reason: ``e``'s edge share at the design torque and its edge peak against
    ``best``'s [MPa]; empty where the edge is not among ``gone`` or the peaks are
    unknown."""
    if ("edge" not in gone or e.metrics is None or best.metrics is None
            or "edge_peak" not in e.metrics or "edge_peak" not in best.metrics):
        return ""
    share = 100.0 * float(e.metrics["edge_load_share"][-1])
    now = float(np.asarray(e.metrics["edge_peak"], float)[-1])
    was = float(np.asarray(best.metrics["edge_peak"], float)[-1])
    return (f" ({share:.1f} % of the torque on the edges, its edge peak {now:.0f} MPa above "
            f"the design's {was:.0f})")


def coast_range_peak(e: DevelopmentEvaluation | None, setup: Mapping[str, Any],
                     teeth: KeptTeeth | None, key_prefix: tuple = ()) -> tuple[float, float]:
    """A coast design's largest LTE p-p over ``ltca run --flank coast``'s ``lte_range``
    torques and its torque: :func:`~contact.optimize.development_range_lte.range_peak` of
    :func:`~contact.optimize.development_range_lte.range_lte` on the coast flank (its own
    two torques among them, the analyses kept in ``setup``).

    Parameters
    ----------
    e : DevelopmentEvaluation or None
        A coast design checked at ``setup["torques"]`` [N·m] (the coast flank's light and
        design torque).
    setup : mapping
        The development's state at the coast flank's torques.
    teeth : KeptTeeth or None
        The kept shell teeth.
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing (the coast's).

    Returns
    -------
    (float, float) — [µrad], [N·m]
        NaN, NaN where ``e`` is None or not analysed between the torques (logged by
        ``range_lte``).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``lte_range`` step and verdict (:mod:`contact.ltca.lte_range`,
    issue 71: "LTE p-p ≤ 60 µrad at every torque", both flanks), as the coast LTE steps
    judge it (:func:`~contact.optimize.development_coast_steps.checked_coast_lte`).
    """
    if e is None:
        return math.nan, math.nan
    return range_peak(range_lte(e, setup, teeth, flank="coast", key_prefix=key_prefix))


def between_wanted(best: DevelopmentEvaluation, longest: DevelopmentEvaluation | None,
                   targets: DevelopmentTargets, limit: float, static: float) -> bool:
    """Whether :func:`checked_coast_capacity_lte`, having kept none of its designs, tries
    the ellipses between the design's and the longest
    (:func:`~contact.optimize.development_coast_ellipse_between.ellipse_between_designs`):
    where the longest ellipse was analysed, keeps ``limit`` at its two torques and was
    refused for something else (:func:`capacity_kept` with no LTE limit: a plastic
    segment, a target the design met lost, its peak above ``static``).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design, checked.
    longest : DevelopmentEvaluation or None
        Its longest ellipse as analysed (None: not tried, or it failed).
    targets : DevelopmentTargets
        The development's.
    limit : float — [µrad]
        The verdict's LTE limit.
    static : float — [MPa]
        The coast flank's static strength.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    The LTE falls as the ellipse lengthens (Litvin & Fuentes 2004, §9.4): where the
    longest ellipse is above the limit at a torque the shorter ones between are not tried
    (the 10x31 z0 3: 62 µrad; the 20x24 at Σ 100°: 87), which keeps the step's cost where
    it was on those. On the 25x31 of m_et 9.52 mm the longest was 23 / 31 µrad at 567 /
    3780 N m with 0.5 % of the torque on plastic segments (docs/synthesis.md, "The coast
    ellipse between, its height kept").
    """
    if longest is None or longest.metrics is None or longest.full is None:
        return False
    if not float(np.nanmax(longest.metrics["lte_peak_to_peak"])) <= limit:
        return False
    return bool(capacity_kept(best, longest, targets, math.inf, static))


def checked_coast_capacity_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                               setup: Mapping[str, Any], teeth: KeptTeeth | None,
                               say: Callable[[str], None],
                               placed: Callable[[Mapping[str, float]], Case], *,
                               static: float, key_prefix: tuple = (),
                               limit: float | None = None,
                               near: list[DevelopmentEvaluation] | None = None
                               ) -> DevelopmentEvaluation:
    """A coast design whose LTE p-p at the check exceeds the verdict's limit at a torque
    or between its torques (:func:`coast_largest`), given the longest ellipse
    (:func:`longest_ellipse`), its light-load pattern given its clearance to the toe and
    heel back by M's place (:func:`clearance_shift`) and, on that, lighter reliefs
    (:func:`lighter_reliefs`): at most four designs, each placed and checked at
    ``ltca run``'s sampling on the coast flank at ``setup["torques"]`` and judged by
    :func:`capacity_kept` against ``best``, one that meets its rule at the two torques
    judged on its LTE between them too (:func:`coast_range_peak`: ``ltca run --flank
    coast``'s ``lte_range`` torques, one analysis of the two torques between and the
    crossing's bisections); of those kept (each within the limit over the range), the one
    of least flank peak pressure at the design torque (the capacity the LTE is bought
    with). Where none is kept and the longest ellipse kept the limit at its torques but
    was refused for what it costs (:func:`between_wanted`), the ellipses between the
    design's and the longest, each with its light-load pattern's height kept by the blade
    angle (:func:`~contact.optimize.development_coast_ellipse_between.
    ellipse_between_designs`: at most three ellipses of up to three designs each), the
    first kept.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design, checked at the coast flank's light and design torque.
    targets, setup, teeth, say, placed
        As every coast check step's (:func:`~contact.optimize.development_coast_steps.
        checked_coast_lte`).
    static : float — [MPa]
        The coast flank's static strength.
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing.
    limit : float, optional — [µrad]
        The verdict's LTE limit (default :data:`contact.study.verdicts.LTE_LIMIT`).
    near : list, optional
        Where given, the step's designs refused for their LTE alone (each meeting the
        rule of :func:`capacity_kept` but the limit, at their torques or between them)
        are appended to it: the designs whose
        coast design torque :func:`coast_torque_that_holds` may lower to where their LTE
        keeps the limit (:func:`coast_lte_within_capacity`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept, or ``best`` itself (nothing tried where ``best`` is within
        ``limit`` at its torques and between them, unchecked, ``static`` is not finite or
        the targets do not vary the ellipse).

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    A longer contact ellipse (less lengthwise crowning) lets more of the face share the
    load as the pairs hand over (Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd
    ed., 2004, §9.4; Stadtfeld, *Gleason Bevel Gear Technology*, 2014) but reaches the toe
    or heel at light load unless M, about which the local synthesis makes it, is moved to
    centre it; a relief lighter than the one set against the edges at the torque the flank
    was first developed at keeps the flank where the next pair takes up its load. Each
    raises the peak a little. Measured on the face-hobbed spiral bevel 10x31 z0 3's coast
    flank as written (benchmarks/data/unseen_designs; 17.3 / 90.5 N m, path −45°, ellipse
    0.55, tip relief 10 µm from 0.5, root relief 26.7 µm from 0.2; ``benchmarks/
    development_levers.py --flank coast --from-case --check``, 2026-11-27; LTE p-p light /
    design [µrad], peak [MPa]): 49.4 / 74.8, 1522 (its pitting bound 1537, static strength
    2400); ellipse 0.75: 44.4 / 62.1, 1654, light-load pattern 0.03-0.85 (the toe's
    clearance lost); with M +0.0368 of the face: 45.5 / 61.2, 1564, 0.08-0.90; with the root
    relief 17.8 µm (× ⅔) too: 43.2 / 55.1, 1852, every target the design met kept; with the
    tip relief 6.7 µm (× ⅔) instead: 31.2 / 55.2, 1529, but 2.2 % on the edges (docs/
    synthesis.md, "The coast LTE within the flank's capacity").
    """
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if limit is None else float(limit)
    first = longest_ellipse(best.values, targets)
    if (not best.checked_full or first is None or not math.isfinite(static)
            or not coast_largest(best, setup, teeth, key_prefix, limit) > limit):
        return best
    kept: list[DevelopmentEvaluation] = []

    def tried(values: Mapping[str, float], why: str) -> DevelopmentEvaluation | None:
        e = said_variant(best, values, STAGE,
                         f"with {changed_values(values, best.values)} ({why}; its LTE above "
                         f"{limit:g} urad, its peak up to the static strength "
                         f"{static:.0f} MPa)", targets, setup, teeth, say, placed,
                         flank="coast", key_prefix=key_prefix)
        refused = capacity_kept(best, e, targets, limit, static)
        if not refused:  # kept at its two torques: judged between them too, as ltca run
            # --flank coast's lte_range step judges it (the 20x24 at Sigma 100 deg remedied:
            # its lighter tip relief 44 / 54 urad at its torques, 80.8 between)
            refused = capacity_kept(best, e, targets, limit, static,
                                    between=coast_range_peak(e, setup, teeth, key_prefix))
        if refused:
            say(f"  not kept: {refused}")
            if near is not None and not capacity_kept(best, e, targets, math.inf, static):
                near.append(e)  # refused for its LTE alone
        elif e is not None:
            kept.append(e)
        return e

    base = best
    longest = None
    if any(abs(float(first[k]) - float(best.values[k])) > 1e-9 for k in first):
        base = longest = tried(first, "the longest ellipse")
    if base is not None:
        x = clearance_shift(base, targets)
        if (math.isfinite(x)
                and abs(x - float(base.values.get(SHIFT_NAME, 0.0))) >= SHIFT_LEAST):
            centred = tried(dict(base.values) | {SHIFT_NAME: round(x, 4)},
                            "its light-load pattern off the toe and heel by M's place")
            base = centred if centred is not None else base
        if base is not best and capacity_kept(best, base, targets, math.inf, static):
            # the longer ellipse loses a target the design met (its clearance to toe and
            # heel both, which M's place cannot give back): the lighter reliefs on the
            # design itself (the 20x24 at Sigma 100 deg: the pattern 0.00-0.98 of the face)
            base = best
        for values in lighter_reliefs(base.values, targets):
            tried(values, "lighter relief")
    if not kept and between_wanted(best, longest, targets, limit, static):
        # none kept, the longest ellipse within the limit at its torques but refused for
        # what the longer ellipse costs: an ellipse between the design's and the longest,
        # its light-load pattern's height kept by the blade angle (the 25x31 of m_et 9.52
        # mm: the longest 23 / 31 urad with 0.5 % plastic, the lighter reliefs plastic;
        # the ellipse 0.5 re-centred 57 urad at most over the range against the design's
        # 68.6)
        ellipse_between_designs(best, targets, tried, lambda e: any(k is e for k in kept),
                                limit)
    if not kept:
        return best
    return min(kept, key=lambda e: float(e.metrics["pressure_max_flank"][-1]))


def coast_lte_within_capacity(developed: BasicDesign, drive: DevelopmentEvaluation,
                              targets: DevelopmentTargets, setup: dict[str, Any],
                              teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                              coast: Any, cap: CoastCapacity | None
                              ) -> tuple[Any, str] | None:
    """:func:`checked_coast_capacity_lte` on the written case's coast flank at its own
    torques (``coast.torques``, as ``ltca run --flank coast`` analyses it), after every
    other coast step, where its LTE p-p there still exceeds the verdict's limit.

    Parameters
    ----------
    developed : BasicDesign
        The basic design written (both flanks' prescriptions).
    drive : DevelopmentEvaluation
        The drive design written (its bearing keys the kept pinion teeth).
    targets, setup, teeth, memo, say
        The development's.
    coast : NamedTuple
        The coast outcome of :func:`~contact.optimize.development_coast_flank.
        coast_flank_capacity` (its ``best`` checked at its ``torques`` [N·m]).
    cap : CoastCapacity or None
        The coast capacity search's result (its last check: the static strength and the
        local pitting safety at the coast design torque).

    Returns
    -------
    (outcome, text) or None
        The coast outcome with the design kept (its ``basic`` carrying its coast
        prescriptions) and what it gave up at the coast design torque
        (:func:`capacity_text`, said; its torque is then searched again,
        :func:`coast_torque_that_holds`), or None (nothing kept; nothing analysed where the
        LTE is within the limit, the coast development is off, or no check gives the
        static strength).

    Raises
    ------
    Nothing.

    Notes
    -----
    The step runs where the coast design's LTE exceeds the limit at its torques or between
    them (:func:`coast_largest`; it read the two torques alone, as the coast flank of the
    25x31 of m_et 9.52 mm of benchmarks/data/unseen_designs shows, 59 / 53 µrad at 567 /
    3780 N·m and 69 µrad at 1638 N·m between; its coast design torque, the given design
    torque, is checked by the coast capacity search, which holds there: the step runs on
    it, and keeps the ellipse between, :func:`between_wanted`). The
    designs are judged on their LTE at the coast torques and between them
    (:func:`coast_range_peak`); where none is kept and the coast design's LTE fails the
    verdict, the one written nearest the limit is the one of least LTE over that range,
    and :func:`capacity_text` says the LTE over it. Source: issue 71; docs/synthesis.md,
    "The coast LTE within the flank's capacity" and "The coast capacity LTE step judged
    between the torques".
    """
    from contact.study.verdicts import LTE_LIMIT

    old = coast.best if coast is not None else None
    final = cap.final if cap is not None else None
    if (old is None or not old.checked_full or len(coast.torques) != 2
            or final is None or targets.coast_max_evaluations == 0):
        return None
    written = written_coast(developed, drive, memo)
    at = dict(setup, torques=list(coast.torques))
    # above the limit at its torques, else between them as ltca run --flank coast's
    # lte_range step judges it (the range analysis only where both torques keep it)
    largest = coast_largest(old, at, teeth, written.key_prefix)
    if not largest > LTE_LIMIT:
        return None
    static = float(final.limit)
    lte = np.asarray(old.metrics["lte_peak_to_peak"], float)
    ends = "/".join(f"{x:.0f}" for x in lte)
    between = ""
    if not float(np.nanmax(lte)) > LTE_LIMIT:  # above between alone: said (memoised)
        peak = coast_range_peak(old, at, teeth, written.key_prefix)
        between = f", {peak[0]:.1f} urad at {plain_number(peak[1])} N m between them"
    say(f"development: coast flank LTE p-p {ends} urad at {plain_number(coast.torques[0])}/"
        f"{plain_number(coast.torques[1])} N m{between} after its LTE steps: bearings whose "
        f"peak may rise up to the static strength {static:.0f} MPa")
    near: list[DevelopmentEvaluation] = []

    def over(e: DevelopmentEvaluation) -> tuple[float, float]:
        # its largest LTE over ltca run --flank coast's lte_range torques (kept in the
        # setup's memo: the step's analyses reused)
        return coast_range_peak(e, at, teeth, written.key_prefix)

    got = checked_coast_capacity_lte(old, targets, at, teeth, say, written.placed,
                                     static=static, key_prefix=written.key_prefix, near=near)
    if got is old:
        if not near or not lte_fails(old):
            return None
        # none within the limit at the coast design torque, where the coast design's LTE
        # fails the verdict (above 2 x 60 urad; as the drive's design torque is lowered
        # only then, development_lte_capacity): the one nearest the limit, its coast
        # design torque lowered by coast_torque_that_holds to where its LTE keeps it. An
        # LTE between 60 and 120 urad is an attention the verdict says, not a reason to
        # cut the coast design torque (the 20x24 at Sigma 100 deg: 104 urad at 603.3 N m
        # would cut it to 169.4, 28 % of the drive's; after every coast step
        # development_coast_lte_torque lowers it for such an LTE, never below half of it).
        # Nearest by its largest LTE over the range (its own torques' where not analysed
        # between them)
        got = min(near, key=lambda e: _largest(e, over(e)))
        say(nearest_text(float(coast.torques[1]), _largest(got, over(got)), LTE_LIMIT))
    text = capacity_text(got, cap, float(coast.torques[1]), between=over(got))
    if text:
        say(f"development: coast flank {text}")
    return written.outcome(coast, got), text


def nearest_text(torque: float, lte: float, limit: float) -> str:
    """The line said where no coast bearing keeps the verdict's LTE limit at the coast
    design torque and the nearest is written: what is done next, not its outcome.

    Parameters
    ----------
    torque : float — [N·m]
        The coast design torque the bearings were checked at.
    lte : float — [µrad]
        The nearest bearing's largest LTE p-p (its torques' and between them).
    limit : float — [µrad]
        The verdict's LTE limit.

    Returns
    -------
    str
        ``"development: coast flank: no bearing within …"``: the nearest written and its
        coast design torque searched again on it (:func:`coast_torque_that_holds`), which
        lowers it only where a lower torque keeps the limit; else the coast design before
        the step is written (that search's own line says which).

    Raises
    ------
    Nothing.

    Notes
    -----
    The line said "written where its coast design torque, lowered, keeps the limit"
    before the search ran; on the 14x21 of docs/own_gear_set.md the nearest (123 µrad)
    was said so, yet no torque kept 60 µrad (its light torque's LTE 110 µrad already) and
    the coast design torque stayed 150.5 N·m, the design before the step written.
    Source: issue 71.
    """
    return (f"development: coast flank: no bearing within {limit:g} urad at "
            f"{plain_number(torque)} N m; the nearest (LTE p-p {lte:.0f} urad) written "
            "and its coast design torque searched again on it: lowered where a lower "
            "torque keeps the limit, else the coast design before this step kept")


def coast_largest(e: DevelopmentEvaluation, setup: Mapping[str, Any],
                  teeth: KeptTeeth | None, key_prefix: tuple = (),
                  limit: float | None = None) -> float:
    """A checked coast design's largest LTE p-p [µrad] as ``ltca run --flank coast``'s
    verdict judges it: at its two torques where one exceeds the verdict's limit, else over
    the ``lte_range`` torques between them (:func:`coast_range_peak`, analysed only then).

    Parameters
    ----------
    e : DevelopmentEvaluation
        A coast design checked at ``setup["torques"]`` (``metrics["lte_peak_to_peak"]``
        [µrad]).
    setup : mapping
        The development's state at the coast flank's torques [N·m].
    teeth : KeptTeeth or None
        The kept shell teeth.
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing (the coast's).
    limit : float, optional — [µrad]
        The verdict's LTE limit (default :data:`contact.study.verdicts.LTE_LIMIT`).

    Returns
    -------
    float — [µrad]
        The larger of its two torques' LTE p-p and, where both keep the limit, its
        largest between them (the two torques' where that analysis fails).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque", both flanks); the verdict's
    limit :data:`contact.study.verdicts.LTE_LIMIT`.
    """
    from contact.study.verdicts import LTE_LIMIT

    own = float(np.nanmax(e.metrics["lte_peak_to_peak"]))
    if own > (LTE_LIMIT if limit is None else float(limit)):
        return own
    return _largest(e, coast_range_peak(e, setup, teeth, key_prefix))


def _largest(e: DevelopmentEvaluation, between: tuple[float, float] | None) -> float:
    """``e``'s largest LTE p-p [µrad]: over the range where ``between`` (range_peak's) is
    finite, else at its own torques."""
    own = float(np.nanmax(e.metrics["lte_peak_to_peak"]))
    if between is None or not math.isfinite(between[0]):
        return own
    return max(own, float(between[0]))


def capacity_text(e: DevelopmentEvaluation, cap: CoastCapacity, torque: float, *,
                  between: tuple[float, float] | None = None) -> str:
    """What the coast design ``e`` kept by :func:`checked_coast_capacity_lte` gave up at the
    coast design torque it ran at (said before :func:`coast_torque_that_holds` searches
    that torque again): its LTE p-p, its flank peak against the static
    strength and its local pitting safety S_H,loc at ``torque`` [N·m] (the capacity
    search's last check's × its pitting bound over ``e``'s peak, S_H,loc ∝ 1/p), where the
    peak exceeds that bound; empty where it does not (or the bound is unknown).

    Parameters
    ----------
    e : DevelopmentEvaluation
        The kept coast design, checked at the coast flank's torques.
    cap : CoastCapacity
        The coast capacity search's result (its last check at the coast design torque).
    torque : float — [N·m]
        The coast design torque.
    between : (float, float), optional — [µrad], [N·m]
        ``e``'s largest LTE p-p over ``ltca run``'s ``lte_range`` torques and its torque
        (:func:`coast_range_peak`): the LTE said; default (or NaN) its own torques'.

    Returns
    -------
    str

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: :func:`~contact.optimize.development_coast_flank.pitting_pressure` (the local
    pitting safety σ_HP / (p √(K_A K_v)), ISO 10300-2 with the bearing's own peak); the
    LTE over ``ltca run --flank coast``'s ``lte_range`` torques (:mod:`contact.ltca.
    lte_range`).
    """
    final = cap.final
    bound = pitting_pressure(cap)
    peak = float(e.metrics["pressure_max_flank"][-1])
    if final is None or not (math.isfinite(bound) and peak > bound):
        return ""
    s_min = float(final.s_h_min)
    lte = (f"{_largest(e, between):.0f} urad at its torques and between them"
           if between is not None and math.isfinite(between[0]) else
           f"{float(np.nanmax(e.metrics['lte_peak_to_peak'])):.0f} urad")
    return (f"LTE p-p {lte} within "
            f"60 urad bought with its local pitting margin: flank peak {peak:.0f} MPa "
            f"(static strength {float(final.limit):.0f} MPa), S_H,loc "
            f"{s_min * bound / peak:.2f} at {plain_number(torque)} N m below S_Hmin {s_min:g}; the "
            "rating's S_H holds there (at or below the coast side's ISO 10300 capacity)")


#: the criteria of the coast capacity search (:attr:`~contact.optimize.development_coast.
#: CoastCheck.failures`' keys) in the words :func:`coast_torque_that_holds` names the bound
#: that set the coast design torque with
BOUND_NAMES = {"flank": "static strength", "plastic": "plastic segments",
               "root": "FE root stress", "pitting": "local pitting safety"}


def coast_torque_that_holds(case: Case, basic: BasicDesign, coast: Any,
                            cap: CoastCapacity, targets: DevelopmentTargets,
                            setup: dict[str, Any], root_stress: bool,
                            say: Callable[[str], None]
                            ) -> tuple[Any, CoastCapacity] | None:
    """The coast design torque searched again on the bearing
    :func:`coast_lte_within_capacity` kept, written as ``case``: from the coast design
    torque down to the largest torque where the coast flank holds on every criterion of
    the capacity search (:func:`~contact.optimize.development_coast_flank.
    coast_flank_capacity`: flank peak within the static strength, no plastic segment,
    S_F,FE ≥ S_Fmin and the local pitting safety S_H,loc ≥ S_Hmin), kept where the coast
    LTE p-p is within the verdict's limit there at both torques.

    Parameters
    ----------
    case : Case
        The case written with the coast design kept by :func:`coast_lte_within_capacity`.
    basic : BasicDesign
        The basic file as given (its ``operating`` and ``rating`` tables).
    coast : NamedTuple
        That coast outcome (its ``torques`` [N·m]: the light and the coast design torque
        the step ran at).
    cap : CoastCapacity
        The coast capacity search's result before the step (its ``start`` [N·m], its
        checks and reason).
    targets, setup
        The development's (``setup["torques"]``: the drive's light and design torque
        [N·m]).
    root_stress : bool
        Check S_F,FE and S_H,loc (the FE root stress and the rating: ``ltca run``'s).
    say : callable str → None
        Where the lines go.

    Returns
    -------
    (outcome, CoastCapacity) or None
        The coast outcome at the torque that holds (its metrics and torques those of the
        check there) and the coast capacity written (its reason: the one before, the
        step's bearing and the search again, naming the bound that set the torque,
        :data:`BOUND_NAMES`: the criteria failing at the lowest torque that fails); None
        where no torque holds, the search fails or the LTE p-p there exceeds the limit
        (the design before the step is then written).

    Raises
    ------
    Nothing: a failed analysis ends the search (said).

    Notes
    -----
    The step lets the peak rise past the local pitting bound at the coast design torque
    (S_H,loc 0.91 on the 10x31 z0 3 at 90.5 N m), which a gear engineer does not sign:
    the coast design torque is the torque at which the coast flank holds, its LTE within
    60 µrad among its criteria (issue 71 item 2, "both flanks, one design torque that
    holds"). Measured on the face-hobbed spiral bevel 10x31 z0 3
    (benchmarks/data/unseen_designs; the written case's coast flank as ``ltca run --flank
    coast`` analyses it, 2026-11-27): the step's bearing at 90.5 / 81.7 / 70.4 N m peaks
    1778 / 1477 / 1246 MPa (S_H,loc 0.91 / 1.10 / 1.30) at LTE p-p 54.8 / 54.8 / 55.3
    µrad (light 43.6); the bearing before the step keeps 72.8 / 70.0 / 65.4 µrad at 81.7 /
    70.4 / 60 N m, so no torque that holds is higher on it. Source: ISO 10300-2 with the
    bearing's own peak (:func:`~contact.optimize.development_coast_flank.
    pitting_pressure`); the search of :func:`contact.optimize.development_coast.
    coast_capacity`; the LTE limit :data:`contact.study.verdicts.LTE_LIMIT`.
    """
    from contact.study.verdicts import LTE_LIMIT

    start = float(coast.torques[1])
    again, found = coast_flank_capacity(case, basic, coast, targets, setup, start,
                                        root_stress, True, say)
    if found is None or not found.holds or again.best is None:
        say(f"development: the coast flank holds at no torque up to {plain_number(start)} N m on "
            "the bearing whose LTE was within 60 urad; the coast design before it written")
        return None
    lte = float(np.nanmax(again.best.metrics["lte_peak_to_peak"]))
    by_lte = False
    if not lte <= LTE_LIMIT:
        lowered = coast_torque_for_lte(case, basic, again, found, targets, setup,
                                       root_stress, say)
        if lowered is not None:
            again, found = lowered
            lte = float(np.nanmax(again.best.metrics["lte_peak_to_peak"]))
            by_lte = True
    if not lte <= LTE_LIMIT:
        say(f"development: at the coast design torque {plain_number(found.torque)} N m, where it "
            f"holds, its LTE p-p {lte:.0f} urad is above {LTE_LIMIT:g} urad; the coast "
            "design before the step written")
        return None
    if not found.lowered:
        say(f"development: coast design torque {plain_number(start)} N m kept on the bearing "
            f"whose LTE p-p is {lte:.0f} urad there (within {LTE_LIMIT:g} urad)")
        return again, cap
    failed = [c for c in found.checks if c.failures]
    bound = ", ".join(BOUND_NAMES.get(k, k) for k in failed[-1].failures) if failed else ""
    if by_lte:
        bound = f"LTE p-p within {LTE_LIMIT:g} urad"
    say(f"development: coast design torque {plain_number(start)} -> {plain_number(found.torque)} "
        f"N m on the bearing whose LTE p-p is {lte:.0f} urad there, set by its {bound}")
    reason = (f"{cap.reason}; then a coast bearing whose LTE p-p is within "
              f"{LTE_LIMIT:g} urad (the longest ellipse; development_coast_capacity_lte) "
              f"and the coast design torque searched again on it, set by its {bound}: "
              f"{found.reason}; LTE p-p {lte:.0f} urad there")
    return again, CoastCapacity(found.torque, cap.start, cap.checks + found.checks, reason,
                                True)


#: analyses of a coast design torque lowered for the LTE at most
#: (:func:`coast_torque_for_lte`; as the drive's
#: :func:`~contact.optimize.development_lte_capacity.lte_capacity`)
LTE_TRIES = 3


def coast_torque_for_lte(case: Case, basic: BasicDesign, coast: Any, found: CoastCapacity,
                         targets: DevelopmentTargets, setup: dict[str, Any],
                         root_stress: bool, say: Callable[[str], None]
                         ) -> tuple[Any, CoastCapacity] | None:
    """The coast design torque lowered below ``found.torque``, where the coast flank
    holds but its LTE p-p exceeds the verdict's limit, to where the bearing keeps it:
    the crossing of the limit (:func:`~contact.optimize.development_deflection.
    within_torque`, linear between the torques analysed: the light and the coast design
    torque, then each lowered one), the coast capacity searched from there
    (:func:`~contact.optimize.development_coast_flank.coast_flank_capacity`, every
    criterion), at most :data:`LTE_TRIES` times.

    Parameters
    ----------
    case : Case
        The case written with the coast bearing.
    basic : BasicDesign
        The basic file as given.
    coast : NamedTuple
        The coast outcome checked at ``found.torque`` (its ``torques`` [N·m], light and
        design, and ``best.metrics``' ``lte_peak_to_peak`` [µrad] there).
    found : CoastCapacity
        The coast capacity search at which the flank holds.
    targets, setup, root_stress, say
        As :func:`coast_torque_that_holds`'.

    Returns
    -------
    (outcome, CoastCapacity) or None
        The coast outcome at the lowered torque and that search (its checks after
        ``found``'s), where the flank holds there with its LTE p-p within the limit at
        both torques; None where no torque is found (the LTE above the limit at the light
        torque already, a search that fails or holds nowhere, or a design torque or
        coast design torque the basic file gives: kept, as
        :func:`~contact.optimize.development_lte_capacity.lte_capacity` keeps it).

    Raises
    ------
    Nothing: a failed analysis ends the search (said by the capacity search).

    Notes
    -----
    The coast flank's LTE at its design torque is a share of the teeth's deflection
    there, which falls with the torque (docs/synthesis.md, "The LTE at the design torque:
    the teeth's deflection"); where no bearing of the coast steps keeps 60 µrad at the
    coast design torque (the face-hobbed spiral bevel 20x24 at Σ 100°, ε_vβ 0.84: the
    nearest 38 / 71 µrad at 90.4 / 603.3 N m), the coast design torque is the one where
    the coast flank holds, its LTE included (issue 71: LTE p-p ≤ 60 µrad at every
    torque, both flanks), as the drive's design torque is lowered for a FAIL-level LTE
    (:func:`~contact.optimize.development_lte_capacity.lte_capacity`). Source: ``ltca
    run``'s verdict (:data:`contact.study.verdicts.LTE_LIMIT`).
    """
    from contact.study.verdicts import LTE_LIMIT

    if basic is not None and (basic.gives_design_torque
                              or basic.rating.get("coast_design_torque") is not None):
        return None  # a design torque the basic file gives is kept (as lte_capacity's)
    seen = [float(t) for t in coast.torques]
    lte = [float(x) for x in coast.best.metrics["lte_peak_to_peak"]]
    checks = tuple(found.checks)
    for _ in range(LTE_TRIES):
        within = within_torque(seen, lte, LTE_LIMIT)
        if not math.isfinite(within):
            return None
        new = floor_torque(within)
        if new >= min(seen[-1], found.torque) or new in seen:
            return None
        again, there = coast_flank_capacity(case, basic, coast, targets, setup, new,
                                            root_stress, True, say)
        if there is None or not there.holds or again.best is None:
            return None
        checks = checks + tuple(there.checks)
        got = [float(x) for x in again.best.metrics["lte_peak_to_peak"]]
        if max(got) <= LTE_LIMIT:
            say(f"development: coast design torque {plain_number(found.torque)} -> "
                f"{plain_number(there.torque)}"
                f" N m where its LTE p-p is within {LTE_LIMIT:g} urad "
                f"({' / '.join(f'{x:.0f}' for x in got)} urad at "
                f"{' / '.join(f'{plain_number(t)}' for t in again.torques)} N m)")
            reason = (f"{there.reason + '; ' if there.reason else ''}its LTE p-p "
                      f"{' / '.join(f'{x:.0f}' for x in [*lte, got[1]])} urad at "
                      f"{' / '.join(f'{plain_number(t)}' for t in [*seen, again.torques[1]])} N m "
                      f"(the light torque, then each coast design torque tried), within "
                      f"{LTE_LIMIT:g} urad up "
                      f"to {plain_number(there.torque)} N m")
            return again, CoastCapacity(there.torque, found.start, checks, reason, True)
        order = np.argsort([*seen, float(again.torques[1])])
        pairs = [*zip(seen, lte, strict=True), (float(again.torques[1]), got[1])]
        seen = [pairs[i][0] for i in order]
        lte = [pairs[i][1] for i in order]
    return None
