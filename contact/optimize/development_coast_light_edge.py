"""The coast flank's light-edge step (issue 71, Done-when "no edge contact at 15 % of the
design torque", both flanks): the written case's coast flank that loads an edge at its
light torque, as ``ltca run --flank coast`` reads it, given the relief (or the crowning)
that takes the light torque off that edge.

The drive flank's step (:mod:`contact.optimize.development_light_edge_relief`) ran on the
drive flank only; on the coast flank the steps only refused a relief that *brought* edge
contact to the light torque (:func:`~contact.optimize.development_light_edge.
light_edge_lost`, in :mod:`contact.optimize.development_coast_edge_peak`), so an edge the
coast search's design carried there stayed. Measured (2026-11-29, round 33 of
docs/own_gear_set.md): the FM hypoid 13×33 at Σ 85° (benchmarks/data/unseen_designs)
wrote a coast flank with 949 MPa on an edge carrying 0.028 % of the torque at its light
torque 33.1 N·m, 15 % of its coast design torque 221 N·m.

:func:`checked_coast_light_edge` runs the drive step's levers and rule on the coast
flank through the check's one relief loop
(:func:`~contact.optimize.development_relief_lte.checked_relief_variants`, ``flank="coast"``,
the coast's kept-teeth key, the mounting tolerance not asked: the drive flank's, as every
coast step's): the edge kinds the light torque loads (:func:`coast_light_edge_kinds`: the
``edge_pressure_<kind>`` readings at the light torque, largest first; else the drive
step's rows or tip edges), the levers of every such kind grown together from the design,
each in :data:`COAST_LEVER_ORDER` (the drive step's :data:`~contact.optimize.
development_light_edge_relief.LEVER_ORDER`, the relief longer before deeper, with the
profile crowning between for :data:`PROFILE_EDGES`), at most :data:`COAST_LIGHT_EDGE_STEPS`
designs, the first clear of the light torque's edges kept where it loses no coast target
the design met nor its capacity bound
(:func:`~contact.optimize.development_edge_peak.pitting_lost` with
:func:`~contact.optimize.development_coast_edge_peak.coast_edge_bound`), does not raise
its LTE above the verdict's limit at its torques where the design kept it within
(:func:`~contact.optimize.development_light_edge_relief.lte_limit_lost`), nor between its
torques (``ltca run --flank coast``'s ``lte_range``, as the coast edge-peak step's rule).
:func:`coast_light_edge` runs it on the written case's coast flank after every other coast
step but the edge peak's; the development writes the design kept and keeps it where its
coast flank, analysed as ``ltca run --flank coast`` does at its design torque, fails no
capacity criterion the design before it held
(:func:`~contact.optimize.development_coast_edge_peak.holds_as_before`). Where the coast
edge-peak step then keeps a design, :func:`coast_light_edge_after_peak` runs the step again
on the flank it wrote (at most :data:`COAST_LIGHT_EDGE_STEPS` more designs, the design
torque's edges held: :func:`edge_peak_raised`). For an edge at an end of the profile
(:data:`PROFILE_EDGES`) the step also tries the profile crowning one step more, after the
relief longer and before deeper (:func:`coast_lever_designs`; measured on the 13×33:
docs/synthesis.md, "The light-edge step again after the coast edge-peak step"); for an
edge at an end of the face (:data:`LENGTHWISE_EDGES`) it first turns the path angle
:data:`PATH_TURN` towards the profile, before the shorter ellipse (measured on the 13×17:
docs/synthesis.md, "The coast gear-toe edge at the light torque: the path angle").
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Generator, Mapping
from typing import Any

import numpy as np

from contact.ltca.edges import EDGE_KINDS
from contact.optimize.development_band_edge import PATH_NAME
from contact.optimize.development_coast import CoastCapacity
from contact.optimize.development_coast_capacity_lte import coast_range_peak
from contact.optimize.development_coast_edge_peak import coast_peak_bound
from contact.optimize.development_coast_flank import written_coast
from contact.optimize.development_edge_peak import (
    EDGE_WORDS,
    edge_excess,
    edge_gain,
    lever_designs,
    pitting_lost,
)
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import SOFT_TARGETS
from contact.optimize.development_light_edge import LIGHT_EDGE, light_edge
from contact.optimize.development_light_edge_relief import (
    LIGHT_EDGE_RELIEF,
    light_edge_kinds,
    light_edge_loaded,
    light_edge_runs_on,
    lte_limit_lost,
)
from contact.optimize.development_range_lte import SAME_PEAK
from contact.optimize.development_relief_lte import Sent, Try, checked_relief_variants
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import CROWNING_STEP
from contact.optimize.development_targets import CROWNING_NAME, DevelopmentTargets
from contact.study.verdicts import EDGE_SHARE_MIN, LTE_LIMIT
from geometry.case import Case
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import BasicDesign

__all__ = ["COAST_LEVER_ORDER", "COAST_LIGHT_EDGE_STEPS", "LENGTHWISE_EDGES", "PATH_TURN",
           "PROFILE_EDGES", "STAGE",
           "checked_coast_light_edge", "coast_lever_designs", "coast_light_edge",
           "coast_light_edge_after_peak", "coast_light_edge_kinds", "coast_light_edge_runs_on",
           "edge_peak_raised"]

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "coast light edge"

#: [1] most designs the step tries on the coast flank, over every edge kind: the coast
#: side's steps each cost an analysis at ``ltca run``'s sampling (and its LTE between the
#: torques), and a design kept one more write, FE build and capacity check; the drive's
#: step tries up to :data:`~contact.optimize.development_light_edge_relief.
#: LIGHT_EDGE_STEPS` per kind. Two: the levers of the edges the light torque loads grown
#: twice (the relief longer, then longer or deeper), all of them in each design (a design
#: is kept only where no edge is loaded at the light torque)
COAST_LIGHT_EDGE_STEPS = 2

#: the edge kinds at an end of the profile (the pinion's tip line on the gear flank; the
#: gear's tip line on the pinion's root), whose light-torque contact the pinion blade's
#: profile crowning eases off as well as the relief at that end
PROFILE_EDGES = ("pinion_edge", "gear_tip")

#: the coast step's order of an edge's levers: the drive step's
#: (:data:`~contact.optimize.development_light_edge_relief.LEVER_ORDER`: the relief longer before
#: deeper) with the profile crowning one step more (:func:`coast_lever_designs`) after the relief
#: longer and before the relief deeper, and for the toe and heel the path turned towards the profile
#: (:data:`PATH_TURN`) before the shorter ellipse. Why: measured 2026-11-29 on the FM hypoid 13x33
#: at Σ 85° (docs/synthesis.md, "The light-edge step again after the coast edge-peak step"), whose
#: coast tip relief already starts at its bound: the deeper tip relief (15 -> 22.5 µm) lifts the
#: flank peak at the coast design torque past the capacity bound (1625 MPa); the profile crowning 0
#: -> 10 µm clears the 949 MPa pinion edge at 33.1 N m and lowers that peak (1620 -> 1498 MPa), no
#: coast target lost
COAST_LEVER_ORDER = ("relief_start", "tip_relief_start", CROWNING_NAME, "root_relief",
                     "tip_relief", PATH_NAME, "ellipse_length")

#: the edge kinds at an end of the face (the gear's toe and heel), whose light-torque
#: contact the coast step first takes off by turning the contact path towards the profile
#: (:data:`PATH_TURN`), before the shorter ellipse of the drive step's levers
LENGTHWISE_EDGES = ("gear_heel", "gear_toe")

#: [deg] the turn of the coast path angle towards the profile each design of the coast step
#: makes for a :data:`LENGTHWISE_EDGES` kind (clipped to the variable's bounds): a diagonal
#: path (−45°) sweeps the contact along the face as it rolls, and turned towards the
#: profile it reaches less far along the face, so the light-load pattern's ends come off
#: the toe and the heel while the ellipse (the lengthwise crowning) stays as long. Measured
#: 2026-11-29 on the FM spiral bevel 13x17 at Σ 50° (its coast flank written, ``ltca run``'s
#: sampling at 18.4 / 122.7 N m; ``benchmarks/development_levers.py --flank coast --check
#: --edges``; docs/synthesis.md, "The coast gear-toe edge at the light torque: the path
#: angle"): path −45° (written) loads the gear toe at 1061 MPa at 18.4 N m, LTE 51.1 /
#: 91.1 µrad, flank peak 1367 MPa, edge peaks 4575 (tip) / 4467 (toe) MPa; −47.5° clears
#: the toe, LTE 55.7 / 90.3, between the torques 90.3, flank peak 1268, edge peaks 4332 /
#: 4329, no target lost (centre u met); −50° clears it too but lifts the LTE to 60.3 µrad
#: at 18.4 N m and 91.8 between the torques; −55° / −60° clear it at 66.4 / 71.9 µrad at
#: 18.4 N m (−60° loses the LTE-spread target). The shorter ellipse (0.6375), the step's
#: lever before, clears it but lifts the gear tip's peak to 5072 MPa and the LTE to 102.4
#: µrad. 2.5°: the least turn that cleared it, half the band-edge step's
#: (:data:`~contact.optimize.development_band_edge.BAND_EDGE_PATH_TURN`)
PATH_TURN = 2.5


def coast_lever_designs(kind: str, values: Mapping[str, float], targets: DevelopmentTargets
                        ) -> list[tuple[str, float]]:
    """The designs of an edge kind's levers the coast step tries, in
    :data:`COAST_LEVER_ORDER`: the drive's (:func:`~contact.optimize.development_edge_peak.
    lever_designs`); for :data:`PROFILE_EDGES`, the profile crowning raised by the
    height stage's step (:data:`~contact.optimize.development_stages.CROWNING_STEP` ×
    ``targets.size_scale``, clipped to its range); for :data:`LENGTHWISE_EDGES`, the path
    angle [deg] turned :data:`PATH_TURN` towards the profile (clipped to its range), before
    the shorter ellipse.

    Parameters
    ----------
    kind : str
        An edge kind of :data:`~contact.optimize.development_edge_peak.LEVERS`.
    values : mapping
        The design's prescriptions [file units: µm, 1].
    targets : DevelopmentTargets
        The levers' bounds (``variables``) and ``size_scale``.

    Returns
    -------
    list of (str, float)
        (prescription, value); only levers the development varies and the design has,
        each at a value other than the design's.

    Raises
    ------
    KeyError
        ``kind`` not an edge kind of the levers' table.

    Notes
    -----
    Source: Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4
    (the profile's parabolic modification keeps the contact off the tooth's top edge; the
    path's direction on the flank sets how far along the face the contact travels);
    the 13x33 and the 13x17 measured (:data:`COAST_LEVER_ORDER`, :data:`PATH_TURN`).
    """
    out = list(lever_designs(kind, values, targets))
    if kind in LENGTHWISE_EDGES and PATH_NAME in targets.variables and PATH_NAME in values:
        lo, hi = (float(x) for x in targets.variables[PATH_NAME])
        now = float(values[PATH_NAME])
        turn = -PATH_TURN if now <= 0.0 else PATH_TURN  # towards the profile (±90°)
        x = round(float(np.clip(now + turn, lo, hi)), 4)
        if abs(x - now) > 1e-6:
            out.append((PATH_NAME, x))
    if (kind in PROFILE_EDGES and CROWNING_NAME in targets.variables
            and CROWNING_NAME in values):
        lo, hi = (float(x) for x in targets.variables[CROWNING_NAME])
        now = float(values[CROWNING_NAME])
        x = float(np.clip(now + CROWNING_STEP * targets.size_scale, lo, hi))
        if x > now + 1e-9:
            out.append((CROWNING_NAME, round(x, 4)))
    return sorted(out, key=lambda d: COAST_LEVER_ORDER.index(d[0]))


def coast_light_edge_kinds(e: DevelopmentEvaluation) -> tuple[str, ...]:
    """The edge kinds whose lever the step tries for ``e``, in turn: those whose segments
    peak above 0 at its light torque (``edge_pressure_<kind>`` [MPa], the first torque),
    the highest first; where the metrics carry no such reading, the drive step's
    (:func:`~contact.optimize.development_light_edge_relief.light_edge_kinds`: the rows
    the light-load pattern is on, else the tip edges).

    Parameters
    ----------
    e : DevelopmentEvaluation
        A checked design (its metrics per torque, light first;
        :func:`~contact.optimize.development_evaluate.light_edge_metrics`).

    Returns
    -------
    tuple of str
        Kinds of :data:`contact.ltca.edges.EDGE_KINDS`.

    Raises
    ------
    Nothing.

    Notes
    -----
    Why the reading, not the rows alone: an edge can carry load at the light torque
    inside the pattern's extent (the 13×33's coast light torque, 0.028 % of the torque on
    an edge: too little to move the pattern onto a row), and with two designs the lever
    must be the loaded edge's. Source: ``ltca run``'s ``p_max edge`` (the peak over the
    edge segments of each kind, :func:`contact.study.verdicts.edge_peaks`).
    """
    read = _light_edge_pressures(e)
    loaded = sorted((k for k, p in read.items() if p > 0.0), key=lambda k: -read[k])
    return tuple(loaded) if loaded else light_edge_kinds(e)


def _light_edge_pressures(e: DevelopmentEvaluation) -> dict[str, float]:
    """``p_max edge`` [MPa] of each edge kind at ``e``'s light torque (its first
    ``edge_pressure_<kind>``; NaN read as 0), in :data:`EDGE_KINDS`' order, for the kinds
    its metrics carry a reading of."""
    m = e.metrics or {}
    return {k: float(np.nan_to_num(np.asarray(m[f"edge_pressure_{k}"], float)[0]))
            for k in EDGE_KINDS if f"edge_pressure_{k}" in m}


def _loaded_edge_words(e: DevelopmentEvaluation) -> list[str]:
    """The edges ``e``'s light torque loads (``p_max edge`` above 0), in words, in
    :data:`EDGE_KINDS`' order."""
    return [EDGE_WORDS[k] for k, p in _light_edge_pressures(e).items() if p > 0.0]


def coast_light_edge_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                             ratios: Callable[[], tuple[float, float]] | None = None) -> bool:
    """The step's gate: ``best`` is checked at ``ltca run``'s sampling, loads an edge at
    its light torque (:func:`~contact.optimize.development_light_edge_relief.
    light_edge_loaded`: ``p_max edge`` above 0 or a counted edge share) and the
    development varies a lever of one of its kinds (:func:`coast_light_edge_kinds`):
    the drive step's gate (:func:`~contact.optimize.development_light_edge_relief.
    light_edge_runs_on`) with this step's kinds. Asked without an analysis: no design is
    tried where it does not hold.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design written.
    targets : DevelopmentTargets
        The development's targets (``variables``: the levers' bounds).
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
    Source: issue 71 (module docstring).
    """
    return light_edge_runs_on(best, targets, kinds=coast_light_edge_kinds,
                              designs=coast_lever_designs)


def _coast_light_edge_designs(start: DevelopmentEvaluation, targets: DevelopmentTargets
                              ) -> Generator[Try, Sent, None]:
    # Why: as the drive step's (development_light_edge_relief._light_edge_designs): an
    # edge carries load at the light torque where the flank's ease-off there is less than
    # the light torque's approach; the relief at that edge longer (then deeper), or for
    # toe and heel the path turned towards the profile (then the lengthwise crowning),
    # keeps it out of the light-load pattern (Litvin
    # & Fuentes 2004, §9.4; Stadtfeld 1993, ch. 3). A design is kept only where no edge is
    # loaded at the light torque (_cleared), so where the light torque loads two edges
    # (the spiral bevel 13x17 at Σ 50°'s gear tip and toe) one lever alone cannot be
    # kept: each design grows the lever of every loaded edge at once (a lever two kinds
    # share, the ellipse of toe and heel, once), from the design before it; at most
    # COAST_LIGHT_EDGE_STEPS designs.
    p, s = light_edge(start) or (math.nan, math.nan)
    kinds = coast_light_edge_kinds(start)
    values = dict(start.values)
    best = start
    for _ in range(COAST_LIGHT_EDGE_STEPS):
        if not light_edge_loaded(best):
            return
        changes: list[tuple[str, str, float]] = []
        for kind in kinds:
            designs = coast_lever_designs(kind, values, targets)
            if designs and designs[0][0] not in {n for _, n, _ in changes}:
                changes.append((kind, *designs[0]))
        if not changes:
            return
        for _, name, x in changes:
            values[name] = x
        change = ", ".join(f"{name} {x:.4g}{_unit(name)}" for _, name, x in changes)
        edges = " and ".join(EDGE_WORDS[k] for k, _, _ in changes)
        best, _ = yield Try(
            dict(values),
            f"with {change} (the coast {edges}: {LIGHT_EDGE} p_max edge "
            f"{np.nan_to_num(p):.0f} MPa, edge share {100.0 * np.nan_to_num(s):.2g} %)",
            f"the coast {change} for the light torque's {edges}")


def _unit(name: str) -> str:
    """The file unit said after a lever's value: µm of a relief or crowning, deg of the
    path angle, none of a fraction."""
    if name.endswith(("relief", "crowning")):
        return " um"
    return " deg" if name == PATH_NAME else ""


def _cleared_said(say: Callable[[str], None]
                  ) -> Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool]:
    def better(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> bool:
        # the drive step's rule (LIGHT_EDGE_RELIEF.better), the design left said: its
        # line of metrics does not show the light torque's edge
        if light_edge_loaded(kept) and not light_edge_loaded(e):
            return True
        p, s = light_edge(e) or (math.nan, math.nan)
        loaded = _loaded_edge_words(e)
        say(f"  not kept: it still loads an edge at the light torque (p_max edge "
            f"{np.nan_to_num(p):.0f} MPa, edge share {100.0 * np.nan_to_num(s):.2g} %"
            + (f"; {', '.join(loaded)}" if loaded else "") + ")")
        return False

    return better


def edge_peak_raised(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
    """``["edge peak"]`` where ``e`` raises the edges' excess over the flank's static
    strength at the design torque (:func:`~contact.optimize.development_edge_peak.
    edge_excess`, ``ltca run``'s ``edge_pressure`` attention) above ``kept``'s by more than
    the edge peak's resolution (:func:`~contact.optimize.development_edge_peak.edge_gain`
    of ``kept``: 2.5 % of the static strength, 60 MPa at 2400 MPa); else ``[]``.

    Parameters
    ----------
    kept, e : DevelopmentEvaluation
        The design kept and a variant, checked at the light and the design torque (their
        metrics carry ``edge_peak_<kind>`` and ``edge_static_strength`` [MPa] per torque).

    Returns
    -------
    list of str

    Raises
    ------
    Nothing.

    Notes
    -----
    Why: the light-edge step run again after the coast edge-peak step
    (:func:`coast_light_edge_after_peak`) must not give back what that step took off the
    edges at the design torque: no edge-peak step runs after it. A variant without the
    readings (a failed analysis: excess inf) is refused. Within the resolution a rise is
    the peak's sampling, not the design's (the edge-peak step's own keep rule,
    :data:`~contact.optimize.development_edge_peak.EDGE_GAIN_MIN`). Source: issue 71;
    docs/synthesis.md, "The light-edge step again after the coast edge-peak step".
    """
    was, now = edge_excess(kept), edge_excess(e)
    if math.isinf(was) or now <= was + edge_gain(kept):
        return []
    return ["edge peak"]


def _coast_lost(bound: float, setup: Mapping[str, Any], teeth: KeptTeeth | None,
                key_prefix: tuple, edge_peak_held: bool = False
                ) -> Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]]:
    pitting = pitting_lost(bound)
    lte = lte_limit_lost(float(LTE_LIMIT))

    def lost(kept: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
        # no coast target the design met lost and its capacity bound kept (pitting_lost),
        # its LTE not raised above the verdict's limit at its torques where it was within
        # (the drive step's rule), then between its torques (the coast edge-peak step's);
        # run after the coast edge-peak step, its edges at the design torque not raised
        # past what that step left (edge_peak_raised)
        gone = pitting(kept, e) + lte(kept, e)
        if edge_peak_held:
            gone += edge_peak_raised(kept, e)
        if any(k not in SOFT_TARGETS for k in gone):  # refused whatever its LTE between
            # the torques (kept_why refuses on a target beyond the soft ones): not analysed
            return gone
        if light_edge_loaded(e):  # refused by the step's rule (_cleared_said, asked
            # next) whatever its LTE between the torques: not analysed either (the 13x17
            # at Σ 50°'s two designs, 2026-11-29: their range analysed, then refused on it)
            return gone
        peak = coast_range_peak(e, setup, teeth, key_prefix)[0]
        if peak > LTE_LIMIT:
            was = coast_range_peak(kept, setup, teeth, key_prefix)[0]
            if not was > LTE_LIMIT:
                gone = [*gone, f"LTE p-p {peak:.1f} urad between the torques"]
            elif peak > was + SAME_PEAK:
                gone = [*gone, f"LTE p-p {peak:.1f} urad between the torques (the design "
                               f"kept {was:.1f})"]
        return gone

    return lost


def checked_coast_light_edge(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                             setup: Mapping[str, Any], teeth: KeptTeeth | None,
                             say: Callable[[str], None],
                             placed: Callable[[Mapping[str, float]], Case], *,
                             bound: float, key_prefix: tuple = (),
                             edge_peak_held: bool = False) -> DevelopmentEvaluation:
    """The coast design ``best`` without edge contact at its light torque where a relief
    (or a shorter ellipse) of the edge does it (module docstring), at most
    :data:`COAST_LIGHT_EDGE_STEPS` designs tried, none where it loads no edge there.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The coast design, checked at the coast flank's light and design torque (its
        metrics carry ``pressure_max_edge`` [MPa], ``edge_contact_share`` [1] and
        ``edge_pressure_<kind>`` [MPa] per torque, light first).
    targets, setup, teeth, say, placed
        As every coast check step's (:func:`~contact.optimize.development_coast_steps.
        checked_coast_lte`; ``setup["torques"]``: the coast flank's own [N·m]).
    bound : float — [MPa]
        The flank peak at the coast design torque a design may not rise above where it
        is above ``best``'s (:func:`~contact.optimize.development_coast_edge_peak.
        coast_edge_bound`; inf: none).
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing.
    edge_peak_held : bool, optional
        Run after the coast edge-peak step: a design that raises the edges' excess over
        the static strength at the design torque is refused too (:func:`edge_peak_raised`).

    Returns
    -------
    DevelopmentEvaluation
        The design kept (stage :data:`STAGE`); ``best`` itself where the gate
        (:func:`coast_light_edge_runs_on`) does not hold or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Source: issue 71 (Done-when: no edge contact at 15 % of the design torque, each flank
    at its own); ``ltca run --flank coast``'s ``p_max edge``; the levers: Litvin &
    Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4; Stadtfeld,
    *Handbook of Bevel and Hypoid Gears*, 1993, ch. 3.
    """
    relief = dataclasses.replace(LIGHT_EDGE_RELIEF, stage=STAGE,
                                 runs_on=coast_light_edge_runs_on,
                                 tries=_coast_light_edge_designs,
                                 better=_cleared_said(say),
                                 lost=_coast_lost(bound, setup, teeth, key_prefix,
                                                  edge_peak_held))
    return checked_relief_variants(best, targets, setup, teeth, say, placed,
                                   reliefs=(relief,), eps=(math.nan, math.nan),
                                   flank="coast", key_prefix=key_prefix, tolerant=False)


def coast_light_edge(developed: BasicDesign, drive: DevelopmentEvaluation,
                     targets: DevelopmentTargets, setup: dict[str, Any], teeth: KeptTeeth,
                     memo: dict, say: Callable[[str], None], coast: Any,
                     cap: CoastCapacity | None, *, after_peak: bool = False) -> Any | None:
    """:func:`checked_coast_light_edge` on the written case's coast flank at its own
    torques (``coast.torques``, as ``ltca run --flank coast`` analyses it).

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
        The coast capacity search's result (the flank peak bound,
        :func:`~contact.optimize.development_coast_edge_peak.coast_edge_bound`; None or
        without one: the flank's static strength, ``edge_static_strength`` [MPa]).
    after_peak : bool, optional
        Run on the coast flank the coast edge-peak step wrote
        (:func:`coast_light_edge_after_peak`): said so, and its designs held to that
        step's edges too (``edge_peak_held``).

    Returns
    -------
    NamedTuple or None
        The coast outcome with the design kept (its ``basic`` carrying its coast
        prescriptions), or None (nothing kept; nothing analysed where the coast flank
        loads no edge at its light torque or the coast development is off).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71; docs/synthesis.md, "The coast flank's light-torque edge".
    """
    old = coast.best if coast is not None else None
    if (old is None or len(coast.torques) != 2 or targets.coast_max_evaluations == 0
            or not coast_light_edge_runs_on(old, targets)):
        return None
    bound = coast_peak_bound(cap, old)
    p, s = light_edge(old) or (math.nan, math.nan)
    kinds = ", ".join(EDGE_WORDS[k] for k in coast_light_edge_kinds(old))
    which = ("the coast flank the coast edge-peak step wrote; its edges at the coast design "
             "torque held" if after_peak else "the coast design as the earlier coast steps "
             "left it")
    say(f"development: coast flank's edge at its light torque "
        f"{plain_number(coast.torques[0])} N m (p_max edge {np.nan_to_num(p):.0f} MPa, "
        f"edge share {100.0 * np.nan_to_num(s):.2g} %; {kinds}; {which}, at ltca run's "
        f"default sampling): its relief, at most {COAST_LIGHT_EDGE_STEPS} designs")
    written = written_coast(developed, drive, memo)
    got = checked_coast_light_edge(old, targets, dict(setup, torques=list(coast.torques)),
                                   teeth, say, written.placed, bound=bound,
                                   key_prefix=written.key_prefix, edge_peak_held=after_peak)
    if got is old:
        return None
    return written.outcome(coast, got)


def coast_light_edge_after_peak(developed: BasicDesign, drive: DevelopmentEvaluation,
                                targets: DevelopmentTargets, setup: dict[str, Any],
                                teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                                coast: Any, cap: CoastCapacity | None) -> Any | None:
    """:func:`coast_light_edge` run again on the coast flank the coast edge-peak step
    wrote (``after_peak``): at most :data:`COAST_LIGHT_EDGE_STEPS` more designs, kept only
    by the step's own rule (clear of the light torque's edges; no coast target, capacity
    bound or LTE lost) and where it does not raise the edges' excess over the static
    strength at the coast design torque past what that step left
    (:func:`edge_peak_raised`). The development calls it only where the edge-peak step
    kept a design; its gate (:func:`coast_light_edge_runs_on`) asks that the light torque
    loads an edge.

    Parameters
    ----------
    developed, drive, targets, setup, teeth, memo, say, coast, cap
        As :func:`coast_light_edge`'s (``coast``: the outcome the edge-peak step wrote).

    Returns
    -------
    NamedTuple or None
        As :func:`coast_light_edge`'s.

    Raises
    ------
    Nothing.

    Notes
    -----
    Why: issue 71 counts any edge contact at 15 % of the design torque. The edge-peak step
    changes the coast relief after the light-edge step read the light torque; on the FM
    spiral bevel 13×17 at Σ 50° it wrote a 1061 MPa gear-toe edge there (3.2·10⁻⁵ % of the
    torque) that no step had read. Source: docs/synthesis.md, "The light-edge step again
    after the coast edge-peak step".
    """
    return coast_light_edge(developed, drive, targets, setup, teeth, memo, say, coast, cap,
                            after_peak=True)


def written_coast_light_edge_line(read: DevelopmentEvaluation | None,
                                  written: DevelopmentEvaluation | None,
                                  torque: float) -> str | None:
    """The development's line on the coast flank *written* at its light torque, where a
    later coast step (the coast edge-peak step, :mod:`~contact.optimize.
    development_coast_edge_peak`) changed the design whose light-torque edge this step
    read (``read``): its ``p_max edge`` [MPa], edge share [%] and loaded edge kinds, as
    ``ltca run --flank coast`` reads the written case (the same torque, the same default
    sampling), beside the reading of the design before that step.

    Parameters
    ----------
    read : DevelopmentEvaluation or None
        The coast design the light-edge step read (its metrics per torque, light first).
    written : DevelopmentEvaluation or None
        The coast design written (after every coast step).
    torque : float
        The coast light torque [N·m].

    Returns
    -------
    str or None
        The line; None where ``read`` loads no edge at the light torque (the light-edge
        step said nothing), where the prescriptions did not change after it (its line is
        the written case's), or where ``written`` carries no light-torque edge reading.

    Raises
    ------
    Nothing.

    Notes
    -----
    Why: on the FM spiral bevel 13×17 at Σ 50° the light-edge step read 1640 MPa and
    0.23 % at 18.4 N·m on the coast design with relief_start 0.5 and root relief 15 µm;
    the coast edge-peak step then wrote relief_start 0.4 and root relief 22.5 µm, whose
    light torque ``ltca run --flank coast`` reads as 1061 MPa on the gear toe and
    3.2·10⁻⁵ % of the torque (below the verdict's floor: a counted share of 0). The same
    torque, the same sampling: ``ltca run`` of the design before that step reads 1640 MPa
    and 0.23 %, LTE 46.4 / 98.4 µrad, as the development did (docs/synthesis.md). Both
    readings are right for the design each measured; the line names the written one so
    that it is not taken for the run's. Source: issue 71; docs/synthesis.md, "The coast
    flank's light-torque edge".
    """
    if read is None or written is None or not light_edge_loaded(read):
        return None
    changed = {k: (v, written.values[k]) for k, v in read.values.items()
               if k in written.values and not math.isclose(float(v), float(written.values[k]),
                                                            rel_tol=1e-9, abs_tol=1e-12)}
    got = light_edge(written)
    if not changed or got is None:
        return None
    before = light_edge(read) or (math.nan, math.nan)
    kinds = _loaded_edge_words(written)
    steps = ", ".join(f"{k} {plain_number(a)} -> {plain_number(b)}"
                      for k, (a, b) in changed.items())
    where = f"; {', '.join(kinds)}" if kinds else ""
    now = (f"p_max edge {np.nan_to_num(got[0]):.0f} MPa, {_share_words(got[1])}{where}"
           if light_edge_loaded(written) else "no edge loaded (p_max edge 0 MPa)")
    return (f"development: the coast flank written ({steps} after the light-edge step) "
            f"at its light torque {plain_number(torque)} N m, as ltca run --flank coast "
            f"reads it (the same torque and default sampling): {now}; the "
            f"light-edge step's p_max edge {np.nan_to_num(before[0]):.0f} MPa, "
            f"{_share_words(before[1])} were of the design before it")


def _share_words(share: float) -> str:
    """``edge share <s> %`` of a counted share [1] (the verdict's ``edge_contact_share``),
    or that it is below the floor the verdict counts from where it is 0."""
    s = float(np.nan_to_num(share))
    if s > 0.0:
        return f"edge share {100.0 * s:.2g} %"
    return (f"edge share below the {100.0 * EDGE_SHARE_MIN:.2g} % of the torque the "
            "verdict counts")
