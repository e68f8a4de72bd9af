"""The development's edge-peak step (issue 71, "a gear you would sign off"): a drive design
whose edge carries the design torque at a peak pressure above the flank's static strength
given the relief that takes the load off that edge.

``ltca run``'s verdict says an ``edge_pressure`` attention where an edge kind carrying at
least :data:`~contact.study.verdicts.EDGE_SHARE_MIN` of the torque peaks above the weaker
member's static strength σ_Hlim·Z_NT,static below the edges' contact-pressure limit
(:func:`contact.study.verdicts.edge_peaks`). The check's steps clear plastic edges and
edge contact at the light torque, and the edge share within its target at the design
torque, but none read that peak: five of eight developed designs re-measured on
2026-11-27 carried it at the design torque (2476–4385 MPa against 2400 MPa;
docs/own_gear_set.md, "Eight designs on the tree of the eighteenth session").

The step reads the development's ``edge_peak_<kind>`` metrics at the design torque
(:func:`~contact.optimize.development_evaluate.edge_peak_metrics`, the verdict's reading)
and, for each kind above the static strength (by more than the peak's resolution), worst
first, tries its lever
(:data:`LEVERS`): the pinion's tip relief for the pinion's edge (its tip on the gear
flank), the pinion's root relief for the gear's tip edge (on the pinion's root, which
a tip relief does not touch), a shorter contact ellipse (more lengthwise crowning) for
the gear's heel and toe — each relief first deeper (:func:`deeper`; deeper again while
each deeper one is kept and its edge still above, up to the relief's bound), then started
earlier (:func:`earlier`), the ellipse shortened by :data:`ELLIPSE_FRACTIONS`. Each design goes
through the check's one relief loop
(:func:`~contact.optimize.development_relief_lte.checked_relief_variants`, the table row
:data:`EDGE_PEAK`): placed and checked at ``ltca run``'s sampling, kept by the check's
keep rule (:func:`~contact.optimize.development_keep.kept_why`: no target the design met
lost — asked first, the local pitting bound at the design torque among them
(:func:`pitting_lost`) —, tolerant at ΔE/ΔP ± 0.05 mm) where its edges' excess over the
static strength (:func:`edge_excess`) is lower by at least the edge peak's resolution at
that sampling (:func:`lower_excess`, :data:`EDGE_GAIN_MIN`: 2.5 % of the static strength);
an edge above the static strength by less is not acted on (:func:`edges_to_relieve`), and
the step ends at the first design kept with no edge above it by as much.

Measured (``ltca synthesize`` then ``ltca run``, 2026-11-27; docs/synthesis.md, "The edge
peak at the design torque"): the spiral bevel 15x45 Method 0 (gear tip 2731 MPa at 282.1
N m) clears it by the root relief 40 → 60 µm; the face-hobbed truck hypoid 8x41 Method 3
(gear heel 4385, tip 3802, pinion edge 3551 MPa at 2629 N m) all three by the ellipse 0.5 →
0.425, the root relief → 58.6 µm and the tip relief → 37 µm (LTE 11 / 8 → 28 / 25 µrad);
the truck hypoid 9x37 its gear tip (4059 MPa), its pinion edge left at 2419 MPa; on the
10x37 at Σ 95° each relief loses the LTE target and on the 10x43 the deeper tip relief its
local pitting bound (:func:`pitting_lost`): both written as before. Deeper again
(2026-11-29, docs/synthesis.md "Deeper again"): the FH industrial spiral bevel 16x41's tip
relief 15 → 22.5 µm left its pinion edge at 2800 MPa at 1927 N m (kept), 33.75 µm clears it
with every target kept; before, the step tried the start next and wrote 2915 MPa.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Generator, Mapping
from typing import Any

import numpy as np

from contact.ltca.edges import EDGE_KINDS
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import lost_targets
from contact.optimize.development_light_edge import light_edge_lost
from contact.optimize.development_relief_lte import Relief, Sent, Try, checked_relief_variants
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted

log = logging.getLogger("contact.optimize.development")

__all__ = ["DEEPER_FACTOR", "DEEPER_RANGE", "EARLIER_STEP", "EDGE_GAIN_MIN", "EDGE_PEAK",
           "EDGE_WORDS", "ELLIPSE_FRACTIONS", "LEVERS", "checked_edge_peak", "deeper",
           "earlier", "edge_designs_once", "edge_excess", "edge_gain", "edge_peak_runs_on",
           "edges_above", "edges_to_relieve", "lever_designs", "lower_excess", "lte_lost",
           "pitting_lost"]

#: the prescriptions that take the load off each edge kind (:data:`contact.ltca.edges.
#: EDGE_KINDS`), tried in turn: the pinion's edge (its tip line on the gear flank) by the
#: pinion's tip relief (the blade's flankrem), deeper then longer; the gear's tip edge,
#: which bears on the pinion's root, by the root relief (the toprem) and its start
#: (``relief_start``); the gear's heel and toe by a shorter contact ellipse — the
#: lengthwise crowning the synthesis gives the bearing (Litvin & Fuentes 2004, §9.4;
#: Stadtfeld, *Handbook of Bevel and Hypoid Gears*, 1993, ch. 3: the relief and the
#: crowning sized to the design load's deflection keep the edges out of the loaded
#: pattern)
LEVERS: Mapping[str, tuple[str, ...]] = {
    "pinion_edge": ("tip_relief", "tip_relief_start"),
    "gear_tip": ("root_relief", "relief_start"),
    "gear_heel": ("ellipse_length",),
    "gear_toe": ("ellipse_length",),
}

#: the edge kinds in words (the lines said)
EDGE_WORDS = {"gear_heel": "gear heel", "gear_toe": "gear toe", "gear_tip": "gear tip",
              "pinion_edge": "pinion edge"}

#: [1] a relief :func:`deeper` tries: this multiple of the design's …
DEEPER_FACTOR = 1.5
#: [1] … and at least this fraction of its range above the lower bound (a relief of 0 µm
#: made one); clipped to the range's upper bound
DEEPER_RANGE = 0.25
#: [1] how much earlier (of the way from M to the flank's end) :func:`earlier` starts a
#: relief: :data:`~contact.optimize.development_relief_lte.TIP_LTE_START_STEP`'s step
EARLIER_STEP = 0.1
#: the contact ellipse's lengths tried for a heel or toe edge, fractions of the design's
#: (clipped to its range)
ELLIPSE_FRACTIONS = (0.85, 0.7)

#: [1] the least fall of the edges' summed excess over the static strength for which
#: :data:`EDGE_PEAK` keeps a design, and the least excess of an edge it acts on, as a
#: fraction of that strength (:func:`edge_gain`): 2.5 %, 60 MPa at the case-carburised
#: steel's 2400 MPa — the edge peak's own resolution at ``ltca run``'s sampling (20 roll
#: positions, 24 segments per contact curve). The peak is the largest of the edge
#: segments' Hertzian pressures at the roll positions sampled, so it moves with the
#: sampling: measured 2026-11-27 (docs/synthesis.md, "The edge-excess keep rule's minimum
#: gain") on the bundled default case at 50 / 250 / 500 N m and on written cases of
#: rounds 19/19b, the peaks above 2400 MPa of edges carrying 0.2 % of the torque or more
#: moved by up to 58 MPa between 20 and 24 or 30 roll positions and up to 40 MPa between
#: 24 and 28 or 32 segments (16 roll positions: up to 103 MPa; edges near the 0.05 %
#: share floor, at 0.069–0.093 %: up to 279 MPa). A fall smaller than that is the
#: sampling's, not the relief's (the 15x45's coast root relief 17.1 → 25.7 µm was kept on
#: 3916 → 3914 MPa, lifting the coast flank peak 1465 → 1530 MPa), and an edge above the
#: static strength by less is not resolved from it
EDGE_GAIN_MIN = 0.025

#: the relief amounts (µm) among the levers; the other levers are starts (fractions of the
#: way from M) or the ellipse's length
_AMOUNTS = ("tip_relief", "root_relief")


def edges_above(e: DevelopmentEvaluation) -> dict[str, float]:
    """The edge kinds whose peak pressure at the design torque (the metrics' last) exceeds
    the flank's static strength, each with its peak [MPa], worst first.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics`` (``edge_peak_<kind>`` [MPa] and ``edge_static_strength``
        [MPa] per torque, light first:
        :func:`~contact.optimize.development_evaluate.edge_peak_metrics`).

    Returns
    -------
    dict str → float — [MPa]
        Empty where the metrics carry no edge peaks (no material named, a failed
        analysis) or none is above the static strength.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``edge_pressure`` attention
    (:func:`contact.study.verdicts.edge_peaks`: ISO 6336-2's Z_NT at the S–N curve's
    static end, ISO 6336-5's σ_Hlim).
    """
    m = e.metrics or {}
    if "edge_static_strength" not in m:
        return {}
    static = float(np.asarray(m["edge_static_strength"], float)[-1])
    if not math.isfinite(static):
        return {}
    peaks = {k: float(np.asarray(m[f"edge_peak_{k}"], float)[-1]) for k in EDGE_KINDS
             if f"edge_peak_{k}" in m}
    above = {k: p for k, p in peaks.items() if math.isfinite(p) and p > static}
    return dict(sorted(above.items(), key=lambda kv: -kv[1]))


def edge_excess(e: DevelopmentEvaluation) -> float:
    """The edges' excess over the flank's static strength at the design torque [MPa]: the
    sum over the edge kinds of their peak above it (:func:`edges_above`), 0 where none is
    above; the quantity :data:`EDGE_PEAK` lowers (a design that lowers one edge and lifts
    another by as much is no better).

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with the edge-peak metrics.

    Returns
    -------
    float — [MPa]
        inf where ``e`` has no metrics (a failed analysis).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``edge_pressure`` attention (:func:`edges_above`).
    """
    if e.metrics is None or "edge_static_strength" not in e.metrics:
        return math.inf
    static = float(np.asarray(e.metrics["edge_static_strength"], float)[-1])
    return float(sum(p - static for p in edges_above(e).values()))


def edge_gain(e: DevelopmentEvaluation) -> float:
    """The edge peak's resolution at the design torque [MPa]: :data:`EDGE_GAIN_MIN` × the
    flank's static strength there — the least fall of the summed excess
    (:func:`lower_excess`) and the least excess of an edge (:func:`edges_to_relieve`)
    :data:`EDGE_PEAK` acts on.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics["edge_static_strength"]`` [MPa] per torque, light first.

    Returns
    -------
    float — [MPa]
        inf where ``e`` has no such metrics or its static strength is not finite.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the sampling's resolution of the edge peak, measured (:data:`EDGE_GAIN_MIN`);
    the static strength σ_Hlim·Z_NT,stat·Z_W·Z_X of ISO 6336-2
    (:func:`contact.study.verdicts.flank_static_strength`).
    """
    if e.metrics is None or "edge_static_strength" not in e.metrics:
        return math.inf
    static = float(np.asarray(e.metrics["edge_static_strength"], float)[-1])
    return EDGE_GAIN_MIN * static if math.isfinite(static) else math.inf


def edges_to_relieve(e: DevelopmentEvaluation) -> dict[str, float]:
    """The edge kinds :data:`EDGE_PEAK` acts on: those of :func:`edges_above` whose peak
    exceeds the static strength by at least :func:`edge_gain` (the sampling's resolution),
    each with its peak [MPa], worst first.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with the edge-peak metrics.

    Returns
    -------
    dict str → float — [MPa]
        Empty where no edge is above the static strength by that much: no relief could
        lower the summed excess by :func:`edge_gain` by clearing one of them.

    Raises
    ------
    Nothing.

    Notes
    -----
    ``ltca run``'s ``edge_pressure`` attention still names the others (its criterion, the
    static strength itself). Source: :data:`EDGE_GAIN_MIN`.
    """
    above = edges_above(e)
    if not above:
        return {}
    static = float(np.asarray(e.metrics["edge_static_strength"], float)[-1])
    gain = edge_gain(e)
    return {k: p for k, p in above.items() if p - static >= gain}


def lower_excess(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> bool:
    """:data:`EDGE_PEAK`'s ``better``: the edges' summed excess over the static strength
    (:func:`edge_excess`) of ``e`` is below ``best``'s by at least :func:`edge_gain` of
    ``best`` (the sampling's resolution, :data:`EDGE_GAIN_MIN`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design kept so far (the edge-peak metrics).
    e : DevelopmentEvaluation
        The step's design.

    Returns
    -------
    bool
        False where either has no metrics (inf excess or resolution).

    Raises
    ------
    Nothing.

    Notes
    -----
    A design that lowers one edge and lifts another by as much is no better, nor one that
    lowers the sum by less than the peak's resolution (the 15x45's coast root relief kept
    on 3916 → 3914 MPa before). Source: :data:`EDGE_GAIN_MIN`.
    """
    old = edge_excess(best)
    return math.isfinite(old) and edge_excess(e) <= old - edge_gain(best)


def deeper(values: Mapping[str, float], name: str, targets: DevelopmentTargets
           ) -> float | None:
    """A deeper relief ``name`` [µm]: :data:`DEEPER_FACTOR` × the design's, at least
    :data:`DEEPER_RANGE` of its range above the lower bound, clipped to the upper bound.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units].
    name : str
        ``"tip_relief"`` or ``"root_relief"``.
    targets : DevelopmentTargets
        Its ``variables[name]`` (lower, upper) [µm].

    Returns
    -------
    float or None — [µm]
        None where the relief is not developed or at its upper bound already.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the development's variables (docs/synthesis.md, "Development bearing"); the
    relief sized to the design load's deflection (Stadtfeld 1993, ch. 3).
    """
    if name not in targets.variables or name not in values:
        return None
    lo, hi = (float(x) for x in targets.variables[name])
    now = float(values[name])
    x = round(float(np.clip(max(DEEPER_FACTOR * now, lo + DEEPER_RANGE * (hi - lo)),
                            lo, hi)), 2)
    return x if x > now + 1e-6 else None


def earlier(values: Mapping[str, float], name: str, targets: DevelopmentTargets
            ) -> float | None:
    """A relief start ``name`` [1] :data:`EARLIER_STEP` nearer M (a longer relief),
    clipped to its range's lower bound.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units].
    name : str
        ``"tip_relief_start"`` or ``"relief_start"``.
    targets : DevelopmentTargets
        Its ``variables[name]`` (lower, upper) [1].

    Returns
    -------
    float or None — [1]
        None where the start is not developed or at its lower bound already.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the development's variables (docs/synthesis.md, "Development bearing").
    """
    if name not in targets.variables or name not in values:
        return None
    lo = float(targets.variables[name][0])
    now = float(values[name])
    x = round(float(max(now - EARLIER_STEP, lo)), 4)
    return x if x < now - 1e-6 else None


def lever_designs(kind: str, values: Mapping[str, float], targets: DevelopmentTargets
                  ) -> list[tuple[str, float]]:
    """The designs of an edge kind's lever (:data:`LEVERS`) from a design, in turn: a
    relief :func:`deeper`, its start :func:`earlier`, the ellipse shortened by
    :data:`ELLIPSE_FRACTIONS` (clipped to its range).

    Parameters
    ----------
    kind : str
        An edge kind of :data:`LEVERS`.
    values : mapping
        The design's prescriptions [file units].
    targets : DevelopmentTargets
        The levers' bounds (``variables``).

    Returns
    -------
    list of (str, float)
        (prescription, value [file units]); only the levers the development varies and
        the design has, and a value other than the design's.

    Raises
    ------
    KeyError
        ``kind`` not in :data:`LEVERS`.

    Notes
    -----
    Source: the levers of :data:`LEVERS` (Litvin & Fuentes 2004, §9.4).
    """
    out = []
    for name in LEVERS[kind]:
        if name == "ellipse_length":
            if name not in targets.variables or name not in values:
                continue
            lo, hi = (float(x) for x in targets.variables[name])
            now = float(values[name])
            out += [(name, round(float(np.clip(f * now, lo, hi)), 4))
                    for f in ELLIPSE_FRACTIONS if np.clip(f * now, lo, hi) < now - 1e-6]
        else:
            x = (deeper if name in _AMOUNTS else earlier)(values, name, targets)
            if x is not None:
                out.append((name, x))
    return out


def edge_peak_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      ratios: Callable[[], tuple[float, float]] | None = None) -> bool:
    """:data:`EDGE_PEAK`'s gate: ``best`` is checked at ``ltca run``'s sampling, an edge
    kind's peak at its design torque exceeds the static strength (:func:`edges_above`)
    and the development varies a lever of such a kind (:data:`LEVERS`).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the drive development kept.
    targets : DevelopmentTargets
        The development's targets (``variables``).
    ratios : callable, optional
        Unused (the relief table's gate signature).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``edge_pressure`` attention (module docstring).
    """
    if not best.checked_full:
        return False
    return any(lever_designs(k, best.values, targets) for k in edges_to_relieve(best))


def _edge_designs(start: DevelopmentEvaluation, targets: DevelopmentTargets, *,
                  again: bool = True) -> Generator[Try, Sent, None]:
    # Why: an edge carries load where the flank's ease-off at the edge is less than the
    # approach the design torque gives there; the relief (or the crowning) at that edge
    # deeper or longer than the deflection keeps the edge out of the loaded pattern
    # (Litvin & Fuentes 2004, §9.4; Stadtfeld 1993, ch. 3). Each kind above the static
    # strength by more than the peak's resolution (EDGE_GAIN_MIN), worst first, from the
    # design kept so far.
    best, done = start, set()
    while True:
        above = {k: p for k, p in edges_to_relieve(best).items() if k not in done}
        if not above:
            return
        kind, peak = next(iter(above.items()))
        done.add(kind)
        static = float(np.asarray(best.metrics["edge_static_strength"], float)[-1])
        queue = lever_designs(kind, best.values, targets)
        while queue:
            name, x = queue.pop(0)
            if kind not in edges_to_relieve(best):  # cleared by the design kept
                break
            peak = edges_to_relieve(best)[kind]  # the kept design's, not the first one's
            now = float(best.values[name])
            if abs(x - now) < 1e-6:
                continue
            unit = " um" if name in _AMOUNTS else ""
            change = f"{name} {x:.4g}{unit}"
            best, _ = yield Try(
                dict(best.values) | {name: x},
                f"with {change} (the {EDGE_WORDS[kind]}'s peak {peak:.0f} MPa at the design "
                f"torque above the static strength {static:.0f} MPa)",
                f"the {change} for the {EDGE_WORDS[kind]}")
            # a deeper relief kept that lowered the edge but left it above: deeper again
            # (the FH 16x41's tip relief 15 -> 22.5 um, pinion edge 4680 -> 2877 MPa,
            # then 33.75 um: cleared, every target kept), before the relief's start
            kept = abs(float(best.values[name]) - x) < 1e-6  # (a failed analysis is not)
            again = (deeper(best.values, name, targets)
                     if again and kept and name in _AMOUNTS
                     and kind in edges_to_relieve(best)
                     else None)
            if again is not None:
                queue.insert(0, (name, again))


def edge_designs_once(start: DevelopmentEvaluation, targets: DevelopmentTargets
                      ) -> Generator[Try, Sent, None]:
    """:data:`EDGE_PEAK`'s designs with one deeper design per relief (no deeper again), as
    both flanks' edge-peak steps tried them before edge101 (drive) and coastedge101 (coast;
    docs/synthesis.md "Deeper again on the coast flank"): no step uses it now; kept to
    measure a step against its one-deeper designs (``dataclasses.replace(EDGE_PEAK,
    tries=edge_designs_once)``).

    Parameters
    ----------
    start : DevelopmentEvaluation
        The design the step starts from (checked).
    targets : DevelopmentTargets
        The levers' bounds (``variables``).

    Returns
    -------
    generator of Try
        Each design in turn; each ``yield`` is given back (the design kept, why not).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: :data:`LEVERS` (Litvin & Fuentes 2004, §9.4).
    """
    return _edge_designs(start, targets, again=False)


#: the edge-peak variant: the relief (or the crowning) of each edge above the static
#: strength at the design torque by more than the peak's resolution, kept where the
#: edges' excess falls by at least that resolution (:func:`lower_excess`); ends where no
#: edge is above by as much
EDGE_PEAK = Relief("edge peak", edge_peak_runs_on, _edge_designs, lost_first=True,
                   better=lower_excess, ends=lambda e: not edges_to_relieve(e))


def pitting_lost(limit: float) -> Callable[[DevelopmentEvaluation, DevelopmentEvaluation],
                                          list[str]]:
    """:data:`EDGE_PEAK`'s lost targets: those of
    :func:`~contact.optimize.development_keep.lost_targets` and ``"local pitting"`` where
    the variant's flank peak at the design torque rises above both the design's and
    ``limit`` (the bearing's local pitting bound there: the design torque would be cut
    to a capacity the design held).

    Parameters
    ----------
    limit : float — [MPa]
        The flank peak at which S_H,loc reaches S_Hmin at the design torque
        (:func:`~contact.optimize.development_pitting.pitting_pressure_limit`); inf: none.

    Returns
    -------
    callable (best, e) → list of str

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 item 2 (one design torque that holds); measured on the 10x43: the
    tip relief 15 → 22.5 µm cleared its pinion edge (2770 MPa at 357 N m) and the written
    case's design torque fell to 325.5 N m (S_H,loc 0.98 at 357; docs/synthesis.md, "The
    edge peak at the design torque").
    """
    def lost(best: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        gone = lost_targets(best, e)
        p_new = float(e.metrics["pressure_max_flank"][-1])
        p_old = float(best.metrics["pressure_max_flank"][-1])
        if not p_new <= max(p_old, limit):
            gone.append("local pitting")
        return gone

    return lost


def lte_lost(setup: Mapping[str, Any], teeth: KeptTeeth | None, limit: float,
             floor: float = 0.0
             ) -> Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]]:
    """:data:`EDGE_PEAK`'s LTE rule on the drive flank: a relief that takes the load off an
    edge is not bought with an LTE above the verdict's limit.

    Parameters
    ----------
    setup : mapping
        The development's state (``torques`` [N·m], light and design; the range analyses
        kept in it: :func:`~contact.optimize.development_range_lte.range_lte`).
    teeth : KeptTeeth or None
        The kept shell teeth.
    limit : float — [µrad]
        The verdict's LTE p-p limit (:data:`~contact.study.verdicts.LTE_LIMIT`).
    floor : float, optional — [µrad]
        The LTE p-p at the two torques up to which a raised LTE is not judged over the
        range (the development's own target ``max_lte``, to spare the range's LTCAs where
        the bearing keeps its target at both torques; the hypoid 13x41 of round 20 whose
        range passed 60 µrad read 22/56 µrad there, above it; default 0, always judged).

    Returns
    -------
    callable (kept, e) → list of str
        ``["LTE p-p <x> urad at <T> N m (the design kept <y>)"]`` where the variant ``e``'s
        LTE p-p rises above ``limit`` and above the kept design's by more than
        :data:`~contact.optimize.development_range_lte.SAME_PEAK`; else ``[]``. Judged
        first on the two torques' LTE the check measured (no analysis); where the variant
        raises it there above ``floor`` but keeps ``limit``, over ``ltca run``'s
        ``lte_range`` torques (:func:`~contact.optimize.development_range_lte.range_lte`,
        a few LTCAs), as the verdict judges it. A variant that does not raise the LTE at
        the two torques above ``floor`` costs nothing.

    Raises
    ------
    Nothing: a range not analysed (logged by ``range_lte``) is not judged.

    Notes
    -----
    Why (issue 71, round 21, docs/own_gear_set.md "Round 21"): the drive step kept a
    variant where no met target was lost, and an LTE target already missed is none. The
    spiral bevel 17×38 Method 0 (ε_vβ 1.20) went from 21/62 µrad at 52.1/347.6 N·m through
    the root relief 50 µm (gear tip 3601 → 3252 MPa; 21/71 µrad) and the tip relief 15 µm
    (pinion edge cleared; 23/94 µrad): ``ltca run`` then judged LTE 64–94 µrad from 175 N·m
    up. The coast flank's step has the same rule over its range
    (:func:`~contact.optimize.development_coast_edge_peak.checked_coast_edge_peak`).
    """
    from contact.optimize.development_range_lte import SAME_PEAK, range_lte, range_peak

    def ends(e: DevelopmentEvaluation) -> tuple[float, float]:
        lte = np.asarray(e.metrics["lte_peak_to_peak"], float)
        i = int(np.nanargmax(lte)) if np.any(np.isfinite(lte)) else 0
        return float(lte[i]), float(setup["torques"][i])

    def lost(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        (new, at), (was, _) = ends(e), ends(kept)
        if not new > was + SAME_PEAK:  # not raised where the check measured it
            return []
        if not new > limit:  # raised within the limit there: judged over the range
            if not new > floor:
                return []
            new, at = range_peak(range_lte(e, setup, teeth))
            if not new > limit:
                return []
            was = max(was, range_peak(range_lte(kept, setup, teeth))[0])
            if not new > was + SAME_PEAK:
                return []
        return [f"LTE p-p {new:.1f} urad at {at:.4g} N m (the design kept {was:.1f})"]

    return lost


def design_pitting_limit(best: DevelopmentEvaluation, setup: Mapping[str, Any]) -> float:
    """The local pitting limit of the design's case at the development's design torque.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design (its ``case``).
    setup : mapping
        The development's state (``"torques"`` [N·m], light and design).

    Returns
    -------
    float
        [MPa] :func:`~contact.optimize.development_pitting.pitting_pressure_limit` at the
        design torque; ``inf`` where it cannot be had (no case or no rating: logged).

    Raises
    ------
    Nothing (a missing rating is logged and gives ``inf``).

    Notes
    -----
    Source: ISO 10300-2:2014, the permissible contact stress σ_HP (the limit's
    definition in :mod:`contact.optimize.development_pitting`).
    """
    from contact.optimize.development_pitting import pitting_pressure_limit

    try:
        return float(pitting_pressure_limit(best.case, float(setup["torques"][1])))
    except Exception as exc:  # no rating or no case (a stand-in): no bound
        raise_if_interrupted(exc)
        log.info("development edge peak: no local pitting bound (%s)", exc)
        return math.inf


def checked_edge_peak(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: Mapping[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """The drive design ``best`` with its edges' peak at the design torque within the
    flank's static strength where a relief does it: :data:`EDGE_PEAK` through the check's
    relief loop (module docstring). Per edge kind above the static strength (four kinds):
    at most one design per lever, but for a relief deepened again after each deeper one
    kept (× :data:`DEEPER_FACTOR` up to its bound: at most four from 15 µm to 60 µm).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The drive design the development kept (checked at ``ltca run``'s sampling; its
        metrics carry the edge peaks).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`;
        ``targets.variables``: the levers' bounds).

    Returns
    -------
    DevelopmentEvaluation
        The design kept last (stage ``"edge peak"``); ``best`` itself where no edge is
        above the static strength, no lever is developed or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Source: issue 71 ("a gear you would sign off"); ``ltca run``'s ``edge_pressure``
    attention (ISO 6336-2 Z_NT at the static end × ISO 6336-5 σ_Hlim); the levers:
    Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4; Stadtfeld,
    *Handbook of Bevel and Hypoid Gears*, 1993, ch. 3.
    """
    if not edge_peak_runs_on(best, targets):
        return best
    from contact.study.verdicts import LTE_LIMIT

    pitting = pitting_lost(design_pitting_limit(best, setup))
    lte = lte_lost(setup, teeth, LTE_LIMIT, float(targets.max_lte))

    def lost(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        # no met target lost, the local pitting bound kept, and then the LTE not raised
        # above the verdict's limit for the edge (lte_lost: the 17x38 of round 21, 62 ->
        # 94 urad; its range analysed only where nothing else refuses the variant)
        # nor edge contact brought to the light torque (light_edge_lost: the coast
        # step's 13x30 at Σ 115°, 519 MPa at 40.8 N m; coastedge86)
        return pitting(kept, e) or light_edge_lost(kept, e) or lte(kept, e)

    relief = dataclasses.replace(EDGE_PEAK, lost=lost)
    return checked_relief_variants(best, targets, setup, teeth, say, placed,
                                   reliefs=(relief,), eps=(math.nan, math.nan))
