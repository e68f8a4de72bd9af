"""The gear process of a development: the generated gear where the Formate gear's developed
design fails or misses its drive pattern (:func:`contact.optimize.development.develop`,
issue 71).

``[synthesis] gear_process = "auto"`` (the default) synthesises a Formate gear and tries the
generated one only where the Formate synthesis has no solution
(:func:`geometry.synthesis.case_synthesis.gear_processes`); a development keeps the process
of its first successful trial. A low-ratio pair's Formate gear may synthesise and still
develop into a design its own check fails: the spiral bevel 20x30 of
tests/data/generated_gear (δ2 56.3°) developed with its Formate gear to an LTE spread of
0.58 at the light torque (``ltca run`` FAILs it) and a design torque cut to 64.1 of its ISO
capacity's 251.4 N·m, and with a generated gear to 171 of 276.7 N·m, no FAIL
(docs/synthesis.md, "Generated gear"). Here the development is run again with ``gear_process
= "Generate"`` where the first one's outcome fails (:func:`failed_outcome`) and the better
of the two kept (:func:`better_outcome`), and likewise where it fails nothing but misses a
drive pattern target (:data:`PATTERN_TARGETS`, :func:`pattern_missed`: Round 40's FM spiral
bevel 20x31 at Σ 70° kept a Formate gear 0.65 long, centre v 0.64, at 1471 of 2542 N·m
beside a generated gear at its rated 2720 N·m, LTE 15 / 33 µrad against 54 / 59, issue 71);
that generated development stops as soon as its design torque falls below the Formate
design's where that keeps the LTE limit (:func:`kept_torque`). Every design whose Formate
development neither fails nor misses its pattern is the first development's, unchanged.
Where both fail, the one of the higher design torque is kept (a spiral bevel 16x24 kept a
Formate gear cut to 5.8 of 230.8 N m beside a generated gear at 112 N m whose coast LTE
spread failed: issue 71). Where the Formate design's torque is cut, the generated gear's
development stops as soon as its design torque falls below the Formate design's
(:class:`Outclassed`): it could only rank below it (issue 75). And the Formate development
itself stops at its static-capacity step where the upper estimate of its bearing's local
pitting capacity (no FE) is already below :data:`FORESEEN_CUT_MARGIN` ×
:data:`TORQUE_CUT_FRACTION` × the rated torque (:class:`CutForeseen`): its outcome would be
a design torque cut, and the generated gear is developed at once — as where the
static-capacity step has lowered the design torque below half the rated one already
(:func:`static_cut_foreseen`: the torque is only lowered from there; the FM miter 18x18,
branch cpu95); only where that fails too is the Formate development run in full, so the
design kept is the one the two full developments rank first (issue 71/75: the spiral bevel
14x36 at Σ 70°). A design torque the drive LTE window lowered
(:mod:`contact.optimize.development_written_lte`) is the contact ratio's, not the gear
process's: a cut is judged against it (:func:`cut_reference`), and a design within ``ltca
run``'s LTE limit ranks above one beyond it (:func:`lte_over`; the FM spiral bevel 17x23,
issue 71, branch half88).

Public names
------------
TORQUE_CUT_FRACTION   design torque below this share of the rated one: a failed outcome
FORESEEN_CUT_MARGIN   the share of that torque a Formate pitting bound must fall below
cut_foreseen          whether a pitting bound foresees the Formate design's torque cut
flank_fails           the verdict's FAIL criteria a flank's (light, design) metrics meet
static_cut_foreseen   whether the flank's static capacity foresees it (an upper bound)
CutForeseen           a Formate development stopped there
failed_outcome        why a developed design fails its own check (empty where it does not)
PATTERN_TARGETS       the drive targets whose miss has "auto" develop the generated gear too
pattern_missed        those a developed design misses, in words
cut_reference         the torque a cut is judged against: the rated one or the LTE window's
cut_below             whether a design torque is below the cut fraction of that reference
lte_over              the written design's LTE p-p above ltca run's limit, in words
outclassing_torque    the design torque below which a second development cannot win
kept_torque           the same where the Formate design fails nothing but misses its pattern
Outclassed            a development stopped there
better_outcome        the better of two developed designs, and which
with_generated_gear   a development, then the generated gear's where the first one fails
                      or misses its drive pattern
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.ltca.plausibility import LTE_SPREAD_LIMIT, PLASTIC_SHARE_LIMIT
from geometry.core.errors import InputError
from geometry.core.text import plain_number

__all__ = ["AT_CHECK", "AT_CHECK_MARGIN", "AT_STATIC", "FORESEEN_CUT_MARGIN",
           "PATTERN_TARGETS", "TORQUE_CUT_FRACTION", "CutForeseen", "Outclassed",
           "better_outcome", "cut_below", "cut_foreseen", "cut_reference", "failed_outcome",
           "flank_fails", "kept_torque", "lte_over", "outclassing_torque", "pattern_missed",
           "static_cut_foreseen", "with_generated_gear"]

log = logging.getLogger(__name__)

#: [1] a developed design whose design torque the development cut below this share of the
#: rated one (the ISO 10300 capacity or the basic file's) is a failed outcome: the bearing
#: carries less than half of what the blank is rated for. The 20x30's Formate gear: 64.1 of
#: 251.4 N·m (0.25); its generated gear: 171 of 276.7 N·m (0.62) (docs/synthesis.md).
#: Where the drive LTE window lowered the design torque, the share is of that torque
#: (:func:`cut_reference`): the FM 17x23's generated gear at 537.1 of 1449 N·m is no
#: failed outcome (branch half88)
TORQUE_CUT_FRACTION = 0.5

#: [1] a Formate development stops at its static-capacity step (:class:`CutForeseen`) where
#: its bearing's local pitting estimate (:func:`contact.optimize.development_root.
#: pitting_capacity_bound` with b measured on the bearing, branch cut85; b = 1/2 before) is
#: below this share of TORQUE_CUT_FRACTION × the rated torque: a margin for the steps after
#: it (the drive steps again at the lowered torque, the tolerance and edge-peak steps)
#: lowering the bearing's peak. Measured (docs/own_gear_set.md, "The Formate gear's cut
#: foreseen with the bearing's own exponent"): the final torque of the five Formate spiral
#: bevels cut below half was 0.87-1.08 x the estimate (13x41 at Σ 62° 86.6 / 89.0 N·m, 14x36
#: at Σ 70° 102.3 / 104.2, 20x30 90.4 / 83.6, 13x37 at Σ 60° 89.6 / 103.4, 14x35 at Σ 70°
#: 122.4 / 119.2); a stop is wrong only where the final torque is at least half the rated
#: one, which none stopped was. The closest kept: the 13x39 at Σ 80°, estimate 204.2 N·m
#: against the stop's 202.0 (final 329.5)
FORESEEN_CUT_MARGIN = 0.9

#: the rule of :func:`better_outcome`, as the case's ``gear_process_text`` says it
_RULE = ("(contact.optimize.development_process.better_outcome: no failed outcome, then the "
         "LTE p-p within ltca run's limit up to the torques the other design carries, then "
         "the higher design torque, then the development's objective).")

#: the drive targets of :func:`contact.optimize.development_targets.development_score`
#: whose miss by a Formate design that fails nothing has ``gear_process = "auto"`` develop
#: the generated gear too (:func:`pattern_missed`): the light-load pattern's length, its
#: centre and its clearance to the flank's ends, which the gear's flank form sets (Round
#: 40's FM spiral bevel 20x31 at Σ 70°: its Formate gear 0.65 long, centre v 0.64, LTE 54 /
#: 59 µrad at 1471 of 2542 N·m; its generated gear 0.65 long, centre v 0.63, LTE 15 / 33 µrad
#: at its rated 2720 N·m, docs/own_gear_set.md).
#: Not the LTE alone (the face contact ratio's, which both gear processes of a pair share:
#: :func:`flank_fails`' reason), not the relief's targets alone (edge share, plastic share,
#: flank pressure) nor the tolerance: the same levers act on either gear
PATTERN_TARGETS = ("length", "centre_u", "centre_v", "toe", "heel", "root", "tip")

#: each of :data:`PATTERN_TARGETS` in words (:func:`pattern_missed`)
_PATTERN_WORDS = {"length": "pattern length", "centre_u": "centre u", "centre_v": "centre v",
                  "toe": "toe clearance", "heel": "heel clearance", "root": "root clearance",
                  "tip": "tip clearance"}


def flank_fails(metrics: Any, torques: tuple[float, ...], flank: str) -> list[str]:
    """The verdict's FAIL criteria a flank's (light, design) metrics meet: the LTE spread
    and the plastic share beyond :mod:`contact.ltca.plausibility`'s limits — an LTE spread
    the verdict reads as a quiet mesh's own transfer (no edge share, LTE p-p within its
    ``lte`` limit: :func:`contact.study.verdicts.quiet_transfer`) an attention there, and
    no FAIL here. The ``lte`` check's FAIL (an LTE p-p beyond
    :data:`contact.study.verdicts.LTE_FAIL_FACTOR` × its limit) is not counted: it would
    develop the second gear process on every low-contact-ratio design, whose LTE the
    contact ratios set, not the gear process (the spiral bevel 16x24: 183 / 152 µrad
    generated, 337 / 327 µrad Formate, docs/own_gear_set.md)."""
    from contact.study.verdicts import quiet_transfer

    if metrics is None:
        return []
    out = []
    pp = np.asarray(metrics.get("lte_peak_to_peak", (math.nan, math.nan)), float)
    edge = np.asarray(metrics.get("edge_load_share", (math.nan, math.nan)), float)
    quiet = (quiet_transfer(pp, edge) if pp.shape == edge.shape and "edge_load_share"
             in metrics else np.zeros(pp.shape, bool))
    for name, limit, what in (("lte_spread", LTE_SPREAD_LIMIT, "LTE spread"),
                              ("plastic_share", PLASTIC_SHARE_LIMIT, "plastic share")):
        values = np.asarray(metrics.get(name, (math.nan, math.nan)), float)
        for k, v in enumerate(values):
            if name == "lte_spread" and k < quiet.size and quiet[k]:
                continue
            if math.isfinite(v) and v > limit:
                at = f" at {plain_number(torques[k])} N m" if k < len(torques) else ""
                out.append(f"{flank} {what} {v:.2f}{at} (limit {limit:g})")
    return out


def failed_outcome(result: Any, rated: float) -> str:
    """Why a developed design fails its own check, empty where it does not.

    Parameters
    ----------
    result : DevelopmentResult
        Its chosen drive design's ``best.metrics`` and its coast flank's ``coast``
        (:data:`~contact.optimize.development.METRIC_NAMES` at the light and the design
        torque), ``torque``, ``coast_design_torques`` and ``torque_lowered`` are read.
    rated : float — [N·m]
        The design torque before the development lowered it (the ISO 10300 capacity or
        the basic file's); NaN where not known (then no torque criterion).

    Returns
    -------
    str
        ``"; "``-joined reasons: a FAIL criterion of ``ltca run``'s verdict met by the
        drive or the coast flank (LTE spread above
        :data:`~contact.ltca.plausibility.LTE_SPREAD_LIMIT`, plastic share above
        :data:`~contact.ltca.plausibility.PLASTIC_SHARE_LIMIT`, at either torque), or a
        design torque lowered below :data:`TORQUE_CUT_FRACTION` × ``rated`` (× the torque
        the drive LTE window set where that is lower: :func:`cut_reference`), or the coast
        flank's own (``coast_capacity``, the torque its developed bearing carries) below
        the light torque.
    """
    return "; ".join(r for r in (_verdict_fails(result), _torque_cut(result, rated)) if r)


def pattern_missed(result: Any) -> str:
    """The drive pattern targets (:data:`PATTERN_TARGETS`) a developed design misses, in
    words; empty where it meets them all or its score is not known.

    Parameters
    ----------
    result : DevelopmentResult
        Its chosen drive design's ``best.full`` (``development_score``'s triple: the
        shortfalls of the written design's final check) and ``best.metrics`` (the light
        torque's pattern) are read; a ``best`` without ``full`` (not checked): empty.

    Returns
    -------
    str
        ``", "``-joined: ``"pattern length 0.65"``, ``"centre u 0.44"``, ``"centre v
        0.64"`` (the light torque's value, 2 decimals) or ``"toe clearance"`` … for each
        target of :data:`PATTERN_TARGETS` whose shortfall is above 0 (an infinite one, a
        failed analysis, included).

    Notes
    -----
    Source: issue 71 ("meets every drive development target"), Round 40's FM spiral bevel
    20x31 at Σ 70° (docs/own_gear_set.md): :func:`with_generated_gear` develops the
    generated gear where a Formate design that does not fail (:func:`failed_outcome`)
    misses one of these targets.
    """
    full = getattr(result.best, "full", None)
    if full is None:
        return ""
    metrics = getattr(result.best, "metrics", None) or {}
    out = []
    for name in PATTERN_TARGETS:
        if not float(full[1].get(name, 0.0)) > 0.0:
            continue
        value = _light_value(metrics, name)
        out.append(_PATTERN_WORDS[name] + (f" {value:.2f}" if math.isfinite(value) else ""))
    return ", ".join(out)


def _light_value(metrics: Mapping[str, Any], name: str) -> float:
    """The light torque's pattern length or centre of ``metrics`` [1] for a target of
    :data:`PATTERN_TARGETS` (NaN for a clearance or a metric not known:
    :func:`pattern_missed`)."""
    def light(key: str) -> float:
        values = np.asarray(metrics.get(key, (math.nan,)), float).ravel()
        return float(values[0]) if values.size else math.nan

    if name == "length":
        return light("pattern_heel_u") - light("pattern_toe_u")
    if name in ("centre_u", "centre_v"):
        return light("pattern_" + name)
    return math.nan


def _verdict_fails(result: Any) -> str:
    """The verdict's FAIL criteria the drive and coast flank meet (:func:`failed_outcome`)."""
    out = flank_fails(result.best.metrics, tuple(result.torque), "drive")
    return "; ".join(out + flank_fails(result.coast, result.coast_design_torques, "coast"))


def _torque_cut(result: Any, rated: float) -> str:
    """The design torque lowered below :data:`TORQUE_CUT_FRACTION` × ``rated``, or the
    coast flank's own design torque lowered below the light torque, in words. A coast flank
    that carries less than the light test load has no bearing to speak of: a spiral bevel
    19x23's Formate coast flank held only 2.7 N m (12 % of its torque on the edges at 416.7
    N m) beside a drive design torque of 275 of 507.9 N m, and was kept without the
    generated gear being tried (issue 71's unseen designs). (Not half the rated torque, as
    the drive's: coast flanks carrying 0.3-0.5 of it, the hypoid 10x37 at Σ 75° and the
    e-axle 11x39 at Σ 80° of tests/data/designs, are developed designs.)"""
    out = []
    cut = float(result.torque[1])
    ref = cut_reference(result, rated)
    if result.torque_lowered and cut_below(cut, rated,
                                           float(getattr(result, "lte_torque", math.nan))):
        of = (f"{plain_number(ref)} N m, the drive LTE window's (rated {plain_number(rated)} N m)"
              if ref < rated else f"{plain_number(rated)} N m")
        out.append(f"design torque cut to {plain_number(cut)} of {of} (below "
                   f"{TORQUE_CUT_FRACTION:g} of it)")
    coast, light = float(getattr(result, "coast_capacity", math.nan)), float(result.torque[0])
    if math.isfinite(coast) and coast < light:
        out.append(f"coast design torque cut to {plain_number(coast)} N m, below the light torque "
                   f"{plain_number(light)} N m")
    return "; ".join(out)


def cut_reference(result: Any, rated: float) -> float:
    """[N·m] The torque a design torque cut is judged against (:func:`failed_outcome`):
    the smaller of the rated torque and the torque the drive LTE window set.

    Parameters
    ----------
    result : DevelopmentResult
        Its ``lte_torque`` [N·m] is read (NaN or absent: the window lowered nothing).
    rated : float — [N·m]
        As :func:`failed_outcome` (NaN: not known).

    Returns
    -------
    float — [N·m]
        ``min(rated, result.lte_torque)`` of the finite ones; NaN where neither is.

    Notes
    -----
    An LTE-window cut (:mod:`contact.optimize.development_written_lte`) is the contact
    ratio's, not the gear process's: the LTE p-p of a localised bearing falls with
    ε_vβ, which both gear processes of a pair share, as :func:`flank_fails` leaves the
    verdict's LTE FAIL out of the failed outcome. Measured (issue 71, docs/synthesis.md,
    "An LTE-window cut is no failed outcome"): the FM spiral bevel 17x23 (ε_vβ 0.93), its
    generated gear kept 60 µrad up to 537.1 of 1449 N·m; counted as a failed outcome
    (below 0.5 of the rated torque) it developed the Formate gear in full (396.5 s CPU),
    kept at 612.7 N·m with drive / coast LTE 73 / 106 µrad. Source: issue 71.
    """
    return _reference(rated, float(getattr(result, "lte_torque", math.nan)))


def cut_below(torque: float, rated: float, window: float) -> bool:
    """Whether a design torque is a cut: below :data:`TORQUE_CUT_FRACTION` × the smaller of
    the rated torque and the torque the drive LTE window set (:func:`cut_reference`'s
    rule, the one :func:`failed_outcome`, :func:`outclassing_torque` and
    :func:`contact.optimize.development._outclassed` judge a cut by).

    Parameters
    ----------
    torque : float — [N·m]
        The design torque judged.
    rated : float — [N·m]
        The rated torque (the ISO 10300 capacity or the basic file's); NaN: not known;
        ``math.nan`` for the window alone (a development's own stop,
        :func:`contact.optimize.development._outclassed`).
    window : float — [N·m]
        The torque the drive LTE window set (``lte_torque``); NaN: none.

    Returns
    -------
    bool
        ``torque < TORQUE_CUT_FRACTION × cut_reference``, the smaller of the finite ones
        of ``rated`` and ``window``; False where neither is finite (no reference: no cut).

    Notes
    -----
    Source: issue 71 (branch half88's rule (a), docs/synthesis.md "An LTE-window cut is no
    failed outcome": a cut is judged against the LTE window's torque, the contact ratio's,
    where that is below the rated one); one helper for the failed outcome and the
    ``Outclassed`` stop (branch cpu89, no behaviour change).
    """
    ref = _reference(rated, window)
    return math.isfinite(ref) and float(torque) < TORQUE_CUT_FRACTION * ref


def _reference(rated: float, window: float) -> float:
    """[N·m] The smaller of the finite ones of ``rated`` and ``window``; NaN where neither
    is (:func:`cut_reference`, :func:`cut_below`)."""
    finite = [float(t) for t in (rated, window) if math.isfinite(float(t))]
    return min(finite) if finite else math.nan


def lte_over(result: Any, up_to: tuple[float, float] | None = None) -> str:
    """The written design's LTE p-p above ``ltca run``'s limit, in words (empty where it
    keeps it at every torque judged, or none is known).

    Parameters
    ----------
    result : DevelopmentResult
        Its drive ``best.metrics["lte_peak_to_peak"]`` at ``torque`` and ``lte_range``
        (its ``"peak"`` at ``"at"`` and its ``"lte"`` at its ``"torques"`` where given),
        its coast ``coast["lte_peak_to_peak"]`` at ``coast_design_torques`` and
        ``coast_lte_range`` alike [µrad] are read (absent or NaN: not judged).
    up_to : (float, float), optional — [N·m]
        The (drive, coast) torque up to which the LTE is judged (:func:`better_outcome`:
        the other design's design torque on that flank); a value at a higher torque is
        not judged, one at an unknown torque is. Default: every torque.

    Returns
    -------
    str
        ``"; "``-joined: ``"drive LTE p-p 73.1 urad at 612.7 N m"`` per flank, its
        largest value above :data:`contact.study.verdicts.LTE_LIMIT` (60 µrad).

    Notes
    -----
    Source: ``ltca run``'s ``lte`` check (60 µrad at the light and the design torque and
    its ``lte_range`` torques between) and issue 71's Done-when ("LTE p-p ≤ 60 µrad at every
    torque on both flanks").
    """
    from contact.study.verdicts import LTE_LIMIT

    out = []
    metrics = getattr(result.best, "metrics", None) or {}
    coast_torques = tuple(getattr(result, "coast_design_torques", ()) or result.torque)
    limits = (math.inf, math.inf) if up_to is None else tuple(float(t) for t in up_to)
    for (flank, m, judged, torques), top in zip((
            ("drive", metrics, getattr(result, "lte_range", None), tuple(result.torque)),
            ("coast", getattr(result, "coast", None) or {},
             getattr(result, "coast_lte_range", None), coast_torques)), limits, strict=True):
        values = [(float(v), torques[k] if k < len(torques) else math.nan)
                  for k, v in enumerate(np.asarray(m.get("lte_peak_to_peak", ()), float))]
        values += _range_values(judged)
        over = [(v, t) for v, t in values if math.isfinite(v) and v > LTE_LIMIT
                and not (math.isfinite(t) and t > top * (1.0 + 1e-9))]
        if over:
            v, t = max(over)
            at = f" at {plain_number(t)} N m" if math.isfinite(t) else ""
            out.append(f"{flank} LTE p-p {v:.1f} urad{at}")
    return "; ".join(out)


def _range_values(judged: Mapping[str, Any] | None) -> list[tuple[float, float]]:
    """(LTE p-p [µrad], torque [N·m]) pairs of an ``lte_range`` record
    (:func:`contact.optimize.development_range_lte.range_record`): its ``"peak"`` at
    ``"at"`` and each of its ``"torques"`` and ``"lte"`` where both are given and alike in
    length; none where ``judged`` is None (:func:`lte_over`)."""
    if judged is None:
        return []
    out = [(float(judged.get("peak", math.nan)), float(judged.get("at", math.nan)))]
    torques = np.asarray(judged.get("torques", ()), float).ravel()
    lte = np.asarray(judged.get("lte", ()), float).ravel()
    if lte.size and lte.size == torques.size:
        out += [(float(v), float(t)) for v, t in zip(lte, torques, strict=True)]
    return out


class Outclassed(Exception):
    """A development stopped where its design torque was lowered below the torque of the
    design it is compared with (``develop(..., outclassed_below=)``, :func:`outclassing_torque`).

    Attributes
    ----------
    torque : float — [N·m]
        Its design torque when it stopped (an upper bound of the one it would have ended
        at: the development only lowers it from there).
    """

    def __init__(self, torque: float) -> None:
        super().__init__(f"design torque lowered to {plain_number(torque)} N m")
        self.torque = float(torque)


class CutForeseen(Exception):
    """A Formate development stopped at its check or its static-capacity step where its
    local pitting bound foresees a design torque cut below :data:`TORQUE_CUT_FRACTION` × the
    rated torque (``develop(..., foresee_cut=True)``, :func:`cut_foreseen`).

    Attributes
    ----------
    torque : float — [N·m]
        The estimate of the design torque the development would end at.
    rated : float — [N·m]
        The rated torque (the ISO 10300 capacity) the development started at.
    stage : str
        Where it stopped, as the case's ``gear_process_text`` says it: ``"its static
        capacity"`` (after the check's steps) or ``"its check, before the check's steps"``
        (:data:`AT_CHECK`, branch cpu89).
    bound : str
        ``"pitting"`` (``torque`` the local pitting estimate,
        :func:`cut_foreseen`) or ``"static"`` (``torque`` the flank's static capacity, an
        upper bound of the design torque: :func:`static_cut_foreseen`, branch cpu95).
    """

    def __init__(self, torque: float, rated: float, stage: str = "its static capacity",
                 bound: str = "pitting") -> None:
        super().__init__(f"{_BOUND_WORDS[bound]} {plain_number(torque)} of "
                         f"{plain_number(rated)} N m")
        self.torque, self.rated, self.stage = float(torque), float(rated), str(stage)
        self.bound = bound

    def said(self) -> str:
        """The stop in words, as ``ltca synthesize`` says it and the case's
        ``gear_process_text`` writes it: ``"its local pitting capacity about 156.6 N m,
        below 0.9 of 0.5 of its rated 361.8 N m"`` (:attr:`bound` ``"pitting"``) or ``"its
        flank's static capacity 130 N m, below 0.5 of its rated 636.1 N m"``
        (``"static"``, :data:`AT_STATIC`)."""
        share = (f"{TORQUE_CUT_FRACTION:g}" if self.bound == "static"
                 else f"{FORESEEN_CUT_MARGIN:g} of {TORQUE_CUT_FRACTION:g}")
        return (f"its {_BOUND_WORDS[self.bound]} {plain_number(self.torque)} N m, below "
                f"{share} of its rated {plain_number(self.rated)} N m")


#: what a :class:`CutForeseen` bound is, in words (its ``bound``)
_BOUND_WORDS = {"pitting": "local pitting capacity about",
                "static": "flank's static capacity"}


#: :attr:`CutForeseen.stage` of a Formate development stopped on its checked design, before
#: the check's steps (:func:`contact.optimize.development.develop`, branch cpu89)
AT_CHECK = "its check, before the check's steps"

#: :attr:`CutForeseen.stage` of a Formate development stopped where its flank's static
#: capacity is below half the rated torque already (:func:`static_cut_foreseen`, branch
#: cpu95)
AT_STATIC = "its static capacity, before the steps at the lowered torque"

#: The share of :func:`cut_foreseen`'s stop below which the bound taken on the checked
#: design, before the check's steps, stops a Formate development there (branch cpu91).
#: Measured (docs/performance.md, cpu89 and cpu91): the steps moved the bound by 0.63 …
#: 1.745 × on the designs whose bound stayed finite (the 13x41 at Σ 62° 51.0 → 89.0 N·m
#: the most), so a bound below 1 / 1.745 = 0.573 of the stop was below it after the steps
#: on each; the 19x26 at Σ 80° (0.83 of its stop before the steps, inf after: its LTE
#: capacity lowered the torque), which main does not stop, is above 0.55.
AT_CHECK_MARGIN = 0.55


def cut_foreseen(bound: float, rated: float, margin: float = 1.0) -> bool:
    """Whether a Formate bearing's local pitting bound foresees its design torque cut below
    :data:`TORQUE_CUT_FRACTION` × ``rated`` (a failed outcome, :func:`failed_outcome`).

    Parameters
    ----------
    bound : float — [N·m]
        The estimate of the bearing's local pitting capacity without FE
        (:func:`contact.optimize.development_root.pitting_capacity_bound` with
        ``measured=True``: T (S_H,loc / S_Hmin)^(1/b), b measured between the analysis's
        light and design torque in [0.2, 0.5]; inf where S_H,loc ≥ S_Hmin).
    rated : float — [N·m]
        The rated torque (NaN: none known, never foreseen).
    margin : float, optional
        A share of the stop (default 1): :data:`AT_CHECK_MARGIN` where the bound is taken
        on the checked design before the check's steps (branch cpu91).

    Returns
    -------
    bool
        ``bound < margin × FORESEEN_CUT_MARGIN × TORQUE_CUT_FRACTION × rated``.

    Notes
    -----
    Source: issue 71/75, measured in docs/synthesis.md ("The Formate gear's torque cut
    foreseen") and docs/own_gear_set.md ("The Formate gear's cut foreseen with the
    bearing's own exponent", branch cut85). The line contact's S_H,loc ∝ T^(-1/2) left the
    13x41 at Σ 62°'s bound at 118.9 N·m, above the stop (97.9), though its development
    ended at 86.6; with the bearing's own b (0.27-0.34 on the five designs cut) the
    estimate is 0.87-1.08 x the final torque; the margin covers the steps after it
    lowering the bearing's peak.
    """
    return (math.isfinite(rated) and rated > 0.0 and not math.isnan(bound)
            and bound < margin * FORESEEN_CUT_MARGIN * TORQUE_CUT_FRACTION * rated)


def static_cut_foreseen(static: float, rated: float) -> bool:
    """Whether a Formate bearing's flank static capacity foresees its design torque cut
    below :data:`TORQUE_CUT_FRACTION` × ``rated`` (a failed outcome, :func:`failed_outcome`).

    Parameters
    ----------
    static : float — [N·m]
        The design torque the static-capacity step lowered the rated torque to
        (:func:`contact.optimize.development_check.static_capacity`: the LTCA's flank peak
        pressure within the static strength).
    rated : float — [N·m]
        The rated torque it was lowered from (NaN: none known, never foreseen).

    Returns
    -------
    bool
        ``static < TORQUE_CUT_FRACTION × rated`` (no margin: ``static`` bounds the design
        torque from above, it is no estimate).

    Notes
    -----
    Why no margin: once lowered, a development only lowers its design torque (the LTE
    capacity, the root-stress and pitting capacity of the written case, the LTE window), and
    a raise after a capacity cut ends at the torque before that cut
    (:func:`contact.optimize.development._regained`'s ceiling), so the design torque the
    development ends at is at most ``static`` (as :func:`outclassing_torque` argues). The one
    way such a design is no failed outcome: the drive LTE window sets its torque (its cut is
    then judged against the window's torque, :func:`cut_reference`) and it fails no verdict
    criterion — the same exposure as :func:`cut_foreseen`'s stop, and the generated gear is
    kept only where it fails nothing (:func:`with_generated_gear`). Measured on the FM miter
    18x18 by Method 0 (benchmarks/data/unseen_designs, issue 71 round 33): its Formate
    bearing (root relief 0: its root line not generated) read 5177 MPa at the rated 636.1
    N m, its static capacity 130 N m; the full Formate development ended there, cut (its
    local pitting bound inf: the analysis lost contact), and the generated gear was kept
    (docs/performance.md, "The miter's Formate development stopped at its static
    capacity"). Source: issue 71/75 (branch cpu95).
    """
    return (math.isfinite(rated) and rated > 0.0 and math.isfinite(static)
            and static < TORQUE_CUT_FRACTION * rated)


def outclassing_torque(first: Any, rated: float) -> float:
    """[N·m] The design torque below which a second development of the pair cannot rank
    above ``first`` (:func:`better_outcome`), NaN where there is none.

    Where ``first``'s design torque was cut below :data:`TORQUE_CUT_FRACTION` × ``rated``
    (whatever else it fails), a second design whose design torque is lowered below
    ``first``'s is cut too: it fails, as ``first`` does, and ranks below it on the second
    key of :func:`better_outcome`, the higher design torque. A development only lowers its
    design torque once it is lowered (the flank's static capacity, then the root-stress
    and pitting capacity of the written case), so it can stop there (:class:`Outclassed`).
    Where ``first``'s torque is not cut, a second design of a lower torque may fail
    nothing and win: NaN. NaN too where ``first``'s LTE p-p exceeds ``ltca run``'s limit
    (:func:`lte_over`): a second design of a lower torque that keeps it ranks above it
    where both fail, and its LTE is known only at its end.

    Parameters
    ----------
    first : DevelopmentResult
        Its ``torque`` and ``torque_lowered`` are read.
    rated : float — [N·m]
        As :func:`failed_outcome`.
    """
    torque = float(first.torque[1])
    if (not first.torque_lowered
            or not cut_below(torque, rated, float(getattr(first, "lte_torque", math.nan)))
            or lte_over(first)):
        return math.nan
    return torque


def better_outcome(first: Any, second: Any, rated: float) -> tuple[Any, str]:
    """The better of two developed designs of one pair, and which.

    Parameters
    ----------
    first, second : DevelopmentResult
        ``first`` is kept where the two rank equal.
    rated : float — [N·m]
        As :func:`failed_outcome`.

    Returns
    -------
    kept : DevelopmentResult
    which : str
        ``"first"`` or ``"second"``: the one kept.

    Notes
    -----
    Ranked by, in turn: a failed outcome (:func:`failed_outcome`: a FAIL criterion of the
    verdict met or a torque cut; none first), the LTE p-p within ``ltca run``'s limit at
    every torque judged on both flanks (:func:`lte_over`; within first), the higher design
    torque (the one the case writes), then the development's own objective of the chosen
    drive design (:func:`~contact.optimize.development.development_score`, lower first).
    The LTE key judges each design up to the other's design torque on each flank
    (``lte_over(r, up_to=)``): a design is not ranked below for an LTE above the limit at
    torques the other does not carry (Round 40's FM 20x31 at Σ 70°: its generated gear's
    coast 63.1 µrad at 961.5 N·m, above the 644 N·m of its Formate gear's coast flank, kept
    the Formate gear at 1471 against 2720 N·m; branch gen103, docs/own_gear_set.md). A
    verdict FAIL and a torque cut rank alike: where both designs fail, the one that
    carries more is kept, where their LTE ranks alike. The FM spiral bevel 17x23 kept, while
    the LTE did not rank, a Formate gear at 612.7 N·m whose drive / coast LTE p-p 73 / 106
    µrad break the limit above a generated gear within it (issue 71, docs/synthesis.md, "An
    LTE-window cut is no failed outcome"). A spiral bevel 16x24
    (tests/data/generated_gear) kept, while a FAIL ranked below a cut, a Formate gear cut
    to 5.8 of 230.8 N m (LTE 337 µrad) beside its generated gear at 112 N m (LTE 183 µrad:
    over the limit too), whose coast flank's LTE spread 0.66 at the light torque failed
    (issue 71).
    """
    def rank(r: Any, other: Any) -> tuple[bool, bool, float, float]:
        return (bool(failed_outcome(r, rated)), bool(lte_over(r, _carried(other))),
                -float(r.torque[1]), float(r.best.objective))

    a, b = rank(first, second), rank(second, first)
    return (second, "second") if b < a else (first, "first")


def _carried(result: Any) -> tuple[float, float]:
    """[N·m] The (drive, coast) design torque of a developed design
    (:func:`better_outcome`: the torques up to which the other design's LTE is judged)."""
    coast = tuple(getattr(result, "coast_design_torques", ()) or result.torque)
    return float(result.torque[1]), float(max(coast))


def with_generated_gear(run: Callable[[Any], Any], basic: Any,
                        say: Callable[[str], None] | None = None) -> Any:
    """A development of ``basic`` (``run(basic)``) and, where its outcome fails or misses a
    drive pattern target with a Formate gear that ``gear_process = "auto"`` could have
    generated, the development with ``gear_process = "Generate"``, the better of the two
    kept.

    Parameters
    ----------
    run : callable BasicDesign → DevelopmentResult
        The development itself (:func:`contact.optimize.development.develop` without
        this fallback), called with ``foresee_cut=True`` for the Formate development of a
        pair ``"auto"`` generates and ``outclassed_below=`` for a generated one.
    basic : BasicDesign
    say : callable, optional
        Called with a line where the generated gear is developed too, and with the
        choice.

    Returns
    -------
    DevelopmentResult
        The first development's where its gear is not Formate, where ``gear_process`` is
        not ``"auto"`` or the pair not one ``"auto"`` generates
        (:func:`geometry.synthesis.case_synthesis.gear_processes`: face milled, δ2 below
        :data:`~geometry.synthesis.case_synthesis.FORMATE_PITCH_ANGLE_LIMIT`), or where
        its outcome neither fails (:func:`failed_outcome`) nor misses a drive pattern
        target (:func:`pattern_missed`); else the better of the two
        (:func:`better_outcome`), its ``gear_process_text`` saying which and why. The
        generated development is given the torque below which it cannot win
        (``outclassed_below=``: :func:`outclassing_torque` after a failed outcome,
        :func:`kept_torque` after a pattern miss). Where
        the Formate development stops on a foreseen cut (:class:`CutForeseen`), the
        generated gear's design where it does not fail; else the Formate gear is developed
        in full and the two ranked as above (the same design kept as without the stop,
        measured in docs/synthesis.md, "The Formate gear's torque cut foreseen").

    Raises
    ------
    InputError
        As the first development where the generated gear's fails too or the pair is not
        one ``"auto"`` generates (a generated development that fails after a Formate one
        that did not is logged and the first result kept; where the Formate development
        raises, the generated gear's is returned, its text saying why).
    """
    from contact.load_capacity.iso10300.capacity import with_design_torque
    from geometry.synthesis.case_synthesis import gear_processes

    say = say or (lambda _line: None)
    auto = gear_processes(basic) == ("Formate", "Generate")
    second: Any = None  # the generated gear's development where it came first
    try:
        # a pair "auto" can generate: its Formate development stops where its torque cut is
        # foreseen (CutForeseen), the generated gear's developed at once
        first = run(basic, foresee_cut=True) if auto else run(basic)
    except CutForeseen as foreseen:
        second, done = _generated_after_foreseen(run, basic, foreseen, say)
        if done is not None:
            return done
        first = _formate_in_full(run, basic, second)
    except InputError as err:
        if not auto:
            raise
        # the Formate development stopped (a spiral bevel 19x23 at beta_m 46 deg: the
        # written design's pinion tip plane, issue 71's unseen designs): the pair "auto"
        # can generate is developed with the generated gear before the error is given
        return _generated_after_error(run, basic, err, say)
    if not auto or first.report.gear.settings.process != "Formate":
        return first
    rated = with_design_torque(first.case, basic.options.design_torque)[1]
    why = failed_outcome(first, rated)
    missed = "" if why else pattern_missed(first)
    if not why and not missed:
        return first
    # where the Formate design fails nothing but misses its drive pattern, a generated
    # design lowered below its torque ranks below it (kept_torque)
    below = outclassing_torque(first, rated) if why else kept_torque(first)
    state = (f"fails ({why})" if why else
             f"fails nothing but misses its drive pattern targets ({missed})")
    if second is None or (isinstance(second, Outclassed)
                          and not (float(first.torque[1]) > second.torque
                                   and (bool(why) or math.isfinite(below)))):
        # (a generated development stopped below the Formate's bound, not below its design
        # torque: developed again as it is without the foresight)
        if second is None:
            say(f"development: the Formate gear's design {state}; developing the pair "
                "with a generated gear too (gear_process 'auto')")
        second = _developed(run, _generated(basic), below)
    if isinstance(second, Outclassed):
        text = (f"Gear process (auto): Formate. The Formate gear's developed design {state} "
                f"at {plain_number(first.torque[1])} N m; the generated gear's development "
                f"was stopped where its design torque fell to {plain_number(second.torque)} N m, "
                f"below the Formate gear's (it is only lowered from there: "
                "contact.optimize.development_process."
                + ("outclassing_torque" if why else "kept_torque") + "); kept the Formate "
                "gear " + _RULE)
        say("development: " + text)
        return dataclasses.replace(first, gear_process_text=text)
    if isinstance(second, InputError):
        log.info("development: the generated gear has no developed design: %s", second)
        return dataclasses.replace(first, gear_process_text=(
            f"Gear process (auto): Formate; its design {state}, the generated gear "
            f"was developed too and failed ({second})."))
    kept, which = better_outcome(first, second, rated)
    other = failed_outcome(second, rated)
    text = (f"Gear process (auto): {'generated' if which == 'second' else 'Formate'}. The "
            f"Formate gear's developed design {state} at {plain_number(first.torque[1])} N "
            f"m; the generated gear's "
            + (f"fails too ({other})" if other else "does not fail")
            + f" at {plain_number(second.torque[1])} N m"
            + _generated_pattern_said(second, why)
            + "; kept the " + ("generated" if which == "second" else "Formate")
            + " gear " + _RULE)
    say("development: " + text)
    return dataclasses.replace(kept, gear_process_text=text)


def kept_torque(first: Any) -> float:
    """[N·m] The design torque below which a generated development cannot rank above a
    Formate design ``first`` that fails nothing (:func:`better_outcome`), NaN where there
    is none: ``first``'s design torque where its LTE p-p keeps ``ltca run``'s limit
    (:func:`lte_over` empty), else NaN.

    Parameters
    ----------
    first : DevelopmentResult
        A design :func:`failed_outcome` finds nothing in; its ``torque`` and what
        :func:`lte_over` reads are read.

    Returns
    -------
    float — [N·m]

    Notes
    -----
    :func:`better_outcome` ranks by (failed, LTE over the limit up to the other's torques,
    −design torque, objective). ``first`` fails nothing and keeps the LTE limit at every
    torque, so it ranks (False, False, −T1, ·); a second design at T2 < T1 ranks at best
    (False, False, −T2, ·), below it. The development only lowers its design torque once
    it is lowered (:func:`outclassing_torque`), so it stops there (:class:`Outclassed`),
    as after a cut. Where ``first`` breaks the LTE limit, a second design that keeps it at
    a lower torque ranks above it: no stop. Source: issue 71 (Round 40's FM 20x31 at
    Σ 70°, docs/own_gear_set.md).
    """
    return math.nan if lte_over(first) else float(first.torque[1])


def _generated_pattern_said(second: Any, why: str) -> str:
    """Where the generated gear was developed for the Formate's drive pattern (``why``
    empty): whether it meets those targets, in words (:func:`with_generated_gear`)."""
    if why:
        return ""
    missed = pattern_missed(second)
    return (f", missing {missed}" if missed else
            ", its drive pattern targets met" if getattr(second.best, "full", None) is not None
            else "")


def _generated(basic: Any) -> Any:
    """``basic`` with ``gear_process = "Generate"``."""
    return dataclasses.replace(
        basic, options=dataclasses.replace(basic.options, gear_process="Generate"))


def _developed(run: Callable[..., Any], basic: Any, below: float) -> Any:
    """``run(basic)`` given ``outclassed_below=below`` where that is finite; the
    :class:`Outclassed` stop or the :class:`~geometry.core.errors.InputError` it raised in
    its place."""
    try:
        return run(basic) if not math.isfinite(below) else run(basic, outclassed_below=below)
    except (Outclassed, InputError) as stop:
        return stop


def _formate_in_full(run: Callable[..., Any], basic: Any, second: Any) -> Any:
    """The Formate development of ``basic`` in full (no :class:`CutForeseen` stop) where
    the generated gear's development ``second`` failed after a foreseen cut (a result, its
    :class:`Outclassed` stop or its error); where the Formate development raises, the
    generated gear's result (its text saying so; developed in full where it was stopped),
    else the Formate development's error."""
    try:
        return run(basic)
    except InputError as err:
        if isinstance(second, Outclassed):
            second = _developed(run, _generated(basic), math.nan)
        if isinstance(second, InputError):
            raise err from None
        text = (f"Gear process (auto): generated. The Formate gear's development stopped "
                f"({err}); the generated gear's developed at {plain_number(second.torque[1])} "
                "N m.")
        return dataclasses.replace(second, gear_process_text=text)


def _generated_after_foreseen(run: Callable[..., Any], basic: Any, foreseen: CutForeseen,
                              say: Callable[[str], None]) -> tuple[Any, Any]:
    """The generated gear's development of ``basic`` where its Formate development stopped
    at ``foreseen``, and the result to return.

    The generated gear's development is stopped (:class:`Outclassed`) where its design
    torque falls below the Formate bearing's bound ``foreseen.torque``: it is cut then
    (below half the rated torque) and can rank above the Formate design only where that
    ends below it, which the Formate's full development decides. Returns (the generated
    development, or its :class:`Outclassed` stop or :class:`~geometry.core.errors.
    InputError`; the generated design with its ``gear_process_text`` where it does not fail
    (:func:`failed_outcome` at the Formate development's rated torque: it ranks first
    whatever the Formate design ends at, which fails as foreseen), else None: the caller
    develops the Formate gear in full and ranks the two as :func:`with_generated_gear`
    does without the foresight)."""
    what = ("flank's static capacity is" if foreseen.bound == "static"
            else "local pitting capacity is about")
    say(f"development: the Formate gear's {what} {plain_number(foreseen.torque)} N m, "
        f"{foreseen.said().split(' N m, ', 1)[1]} (a design torque cut foreseen); developing "
        "the pair with a generated gear (gear_process 'auto')")
    second = _developed(run, _generated(basic), foreseen.torque)
    other = (failed_outcome(second, foreseen.rated)
             if not isinstance(second, (Outclassed, InputError)) else str(second))
    if other:
        say(f"development: the generated gear's design fails too ({other}); developing the "
            "Formate gear in full")
        return second, None
    text = (f"Gear process (auto): generated. The Formate gear's development was stopped at "
            f"{foreseen.stage}, {foreseen.said()} (a design torque cut, a failed outcome: "
            f"contact.optimize.development_process."
            f"{'static_cut_foreseen' if foreseen.bound == 'static' else 'cut_foreseen'}); "
            f"the generated gear's does not fail at {plain_number(second.torque[1])} N m"
            + _window_said(second) + "; kept the generated gear " + _RULE)
    say("development: " + text)
    return second, dataclasses.replace(second, gear_process_text=text)


def _window_said(result: Any) -> str:
    """``" (its design torque the drive LTE window's, set by the contact ratio, ...)"``
    where the LTE window set ``result``'s design torque (``lte_torque`` finite:
    :func:`cut_reference`), else empty."""
    if not math.isfinite(float(getattr(result, "lte_torque", math.nan))):
        return ""
    return (" (its design torque the drive LTE window's, set by the contact ratio, not the "
            "gear process: no failed outcome)")


def _generated_after_error(run: Callable[[Any], Any], basic: Any, err: InputError,
                           say: Callable[[str], None]) -> Any:
    """The development of ``basic`` with ``gear_process = "Generate"`` where its Formate
    development raised ``err``, the case's ``gear_process_text`` saying so; ``err`` itself
    where the generated gear's development fails too."""
    say(f"development: the Formate gear's development stopped ({err}); developing the pair "
        "with a generated gear (gear_process 'auto')")
    try:
        second = run(_generated(basic))
    except InputError as again:
        log.info("development: the generated gear has no developed design: %s", again)
        raise err from None
    text = (f"Gear process (auto): generated. The Formate gear's development stopped "
            f"({err}); the generated gear's developed at {plain_number(second.torque[1])} N m.")
    say("development: " + text)
    return dataclasses.replace(second, gear_process_text=text)
