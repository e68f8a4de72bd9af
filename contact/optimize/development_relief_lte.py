"""The development's check steps for an LTE the reliefs set (issue 71): one trigger table
(:data:`RELIEFS`: which miss triggers which relief variant, in which order) and one loop
(:func:`checked_relief_variants`) through the check's shared helpers.

Each row of the table (a :class:`Relief`) has a gate asked without an analysis and its
designs (step 7 only: the reliefs move, the bearing is not synthesised again). The loop
places and checks each design at ``ltca run``'s sampling and says it
(:func:`~contact.optimize.development_variant.said_variant`), keeps it by the check's one
rule (:func:`~contact.optimize.development_keep.kept_why` with
:func:`~contact.optimize.development_keep.lost_targets`: ranks better, no met target lost,
tolerant at ΔE/ΔP ± 0.05 mm), records the LTE of the designs whose lever it names in the
development's least-LTE record ``ltca synthesize``'s note states
(:func:`~contact.optimize.development_lte_steps.lte_reached`), and ends a variant at the
first design kept that meets every target. In the check's order (after the matched-TE
step, before the near-miss step, :func:`~contact.optimize.development_check.check_steps`):

=================  =====================================  ==================================
variant (stage)    its miss (the gate)                    its designs, in turn
=================  =====================================  ==================================
:data:`TIP_START`  the design torque's LTE above          the tip relief's start at the
                   ``max_lte`` on a pair of ε_vβ < 1      bound of ``tip_relief_start``
                   (:func:`tip_start_runs_on`)            (:func:`later_start`)
:data:`LIGHTER`    the LTE target alone, by at most       the tip relief, then the root
                   10 µrad (:func:`lte_alone_near`)       relief × 0.75
:data:`TIP_LTE`    the design torque's LTE above          the tip relief × 0.8, ⅔, ½, then
                   :func:`lte_limit`, its contact on a    the relief kept started 0.1
                   tip edge (:func:`tip_lte_runs_on`)     earlier (longer)
=================  =====================================  ==================================

Measured (``benchmarks/development_levers.py --check --tolerance``, 2026-11-27;
docs/synthesis.md, "LTE at every torque on a face contact ratio below 1", "The lighter
relief for an LTE just missed", "The tip relief for the design torque's LTE"): the
face-milled spiral bevel 15x28 at Σ 110° (ε_vβ 0.91) 90 / 103 → 86 / 93 µrad by the later
start, the FM spiral bevel 13x39 at Σ 80° 10.8 / 41.1 → 10.3 / 38.0 µrad by the lighter tip
relief, the FM hypoid 15x31 at a = 0.056 d_e2 31 / 99 → 30 / 80 µrad by the tip relief
24.6 → 16.4 µm (each of benchmarks/data/unseen_designs).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Generator, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_lte_steps import lte_reached
from contact.optimize.development_matched_te import contact_ratios, lte_ends
from contact.optimize.development_pattern_steps import LENGTH_RELIEF_FRACTION, LENGTH_RELIEF_LTE
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case

__all__ = ["FACE_RATIO_BELOW", "LIGHTER", "LIGHTER_LEVER", "LONGER_LEVER", "RELIEFS",
           "RELIEF_NAMES", "TIP_LTE", "TIP_LTE_FRACTIONS", "TIP_LTE_START_STEP", "TIP_START",
           "TIP_START_LEVER", "Relief", "Try", "checked_relief_variants", "later_start",
           "lte_alone_near", "lte_limit", "reaches_tip", "tip_lte_runs_on",
           "tip_start_runs_on"]

#: [1] the face contact ratio ε_vβ below which :data:`TIP_START` runs: below 1 one pair
#: carries the load alone over part of the mesh cycle at any torque a localised bearing is
#: developed for (ISO 10300-1:2014, Annex A: ε_vβ the overlap of the virtual cylindrical
#: gear; the 15x28 at Σ 110°, ε_vβ 0.91: one pair alone over 15 % of the cycle at its ISO
#: capacity)
FACE_RATIO_BELOW = 1.0

#: the reliefs :data:`LIGHTER` lightens, in turn: the tip relief first (a lighter tip
#: relief lowered the flank's peak pressure too on the spiral bevel 13x39 at Σ 80°, the
#: shallower root relief raised it: 1448 / 1616 MPa from 1472 MPa)
RELIEF_NAMES = ("tip_relief", "root_relief")

#: the tip relief's amounts :data:`TIP_LTE` tries, fractions of the design's, in turn (its
#: start kept): on the FM hypoid 15x31 at a = 0.056 d_e2 (94.1 / 627.7 N m, tip relief
#: 24.6 µm from 0.893) 20 / 16 / 12 µm gave LTE 31 / 92, 30 / 80, 29 / 76 µrad against
#: 31 / 99, the lightest not tolerant (2.1–2.4 % on edges at ΔP), 8 µm and less uncovering
#: the tip edge (3.2–6.4 % on edges); docs/synthesis.md, "The matched TE parabola on the
#: hypoid 15×31"
TIP_LTE_FRACTIONS = (0.8, 2.0 / 3.0, 0.5)

#: [1] how much earlier (of the way from M to the tip) :data:`TIP_LTE`'s last design starts
#: the tip relief kept: a longer relief of the same amount (the 15x31: from 0.893 → 0.8,
#: LTE 31 / 99 → 39 / 83 µrad, the light-load centre v lost)
TIP_LTE_START_STEP = 0.1

#: the levers in words, as ``ltca synthesize``'s note lists the levers tried
#: (:func:`~contact.optimize.development_lte_steps.lte_reached`)
TIP_START_LEVER = "the tip relief started later"
LIGHTER_LEVER = "a lighter tip relief"
LONGER_LEVER = "a longer tip relief"

#: why :func:`kept_why` refused a design after which :data:`TIP_LTE` still tries a lighter
#: relief (any other refusal — its LTE fails, it loses a met target or is not tolerant —
#: says a lighter relief uncovers the tip edge further)
_SCORES_NO_BETTER = "it scores no better"


def later_start(values: Mapping[str, float], targets: DevelopmentTargets) -> float | None:
    """The tip relief's start [1] of :data:`TIP_START`'s design: the upper bound of
    ``tip_relief_start`` in the development's variables, where the design has a tip relief
    and its start is more than 0.005 below that bound.

    Parameters
    ----------
    values : mapping
        The design's prescriptions [file units] (``tip_relief`` [µm], ``tip_relief_start``
        [1]).
    targets : DevelopmentTargets
        Its ``variables["tip_relief_start"]`` (lower, upper) [1].

    Returns
    -------
    float or None — [1]
        None where there is nothing to try (no tip relief, no start of its own, the start
        not among the variables, or at its bound already).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the development's variables (docs/synthesis.md, "Development bearing": bounds
    given are used as given); the lever measured (:data:`TIP_START`).
    """
    if "tip_relief_start" not in targets.variables or "tip_relief_start" not in values:
        return None
    relief = float(values.get("tip_relief", 0.0))
    now = float(values["tip_relief_start"])
    hi = float(max(targets.variables["tip_relief_start"]))
    if not (relief > 0.0 and math.isfinite(now) and hi > now + 0.005):
        return None
    return round(hi, 4)


def tip_start_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      ratios: Callable[[], tuple[float, float]]) -> bool:
    """:data:`TIP_START`'s gate: ``best`` is checked, misses the development's LTE target
    at the design torque (its LTE p-p there above ``max_lte``), has a later tip-relief
    start to try (:func:`later_start`) and its face contact ratio ``ratios()[1]`` (read
    last) is below :data:`FACE_RATIO_BELOW`.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``max_lte`` [µrad], ``variables``).
    ratios : callable → (float, float)
        The pair's (ε_vα, ε_vβ) [1], called only where every other condition holds.

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (LTE p-p <= 60 µrad at every torque on a face contact ratio below 1;
    docs/synthesis.md, "LTE at every torque on a face contact ratio below 1").
    """
    if (not best.checked_full
            or not float(best.full[1].get("lte", 0.0)) > 0.0):
        return False
    if not lte_ends(best)[1] > float(targets.max_lte):
        return False
    if later_start(best.values, targets) is None:
        return False
    return bool(float(ratios()[1]) < FACE_RATIO_BELOW)


def lte_alone_near(e: DevelopmentEvaluation | None, limit: float = LENGTH_RELIEF_LTE) -> bool:
    """:data:`LIGHTER`'s gate: whether a checked design misses its LTE target and no other,
    by at most ``limit``.

    Parameters
    ----------
    e : DevelopmentEvaluation or None
        A design scored at the check (its ``full``: objective, shortfalls, every target met).
    limit : float, optional
        The most LTE shortfall, in :func:`~contact.optimize.development_targets.
        development_score`'s units (1.0: 10 µrad; default :data:`~contact.optimize.
        development_pattern_steps.LENGTH_RELIEF_LTE`).

    Returns
    -------
    bool
        ``e`` was checked, misses the LTE alone and by no more than ``limit``.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "The lighter relief for
    an LTE just missed").
    """
    if e is None or not e.checked_full or e.full[2]:
        return False
    short = e.full[1]
    return ([k for k, v in short.items() if v > 0.0] == ["lte"]
            and float(short["lte"]) <= limit)


def lte_limit(targets: DevelopmentTargets) -> float:
    """The design torque's LTE p-p [µrad] above which :data:`TIP_LTE` runs: the smaller of
    the development's target ``max_lte`` and ``ltca run``'s verdict limit.

    Parameters
    ----------
    targets : DevelopmentTargets
        Its ``max_lte`` [µrad].

    Returns
    -------
    float — [µrad]

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the ``lte`` check of ``ltca run``'s verdict (:data:`contact.study.verdicts.
    LTE_LIMIT`, 60 µrad) and the development's targets (docs/synthesis.md, "Development
    bearing"); issue 71, "LTE p-p ≤ 60 µrad at every torque".
    """
    from contact.study.verdicts import LTE_LIMIT  # imports contact.ltca

    return float(min(float(targets.max_lte), float(LTE_LIMIT)))


def reaches_tip(e: DevelopmentEvaluation) -> bool:
    """Whether a checked design's contact at the design torque reaches a tip edge: its
    ``tip_edge_share`` at the design torque (the last) is above 0.

    Parameters
    ----------
    e : DevelopmentEvaluation
        A design with ``metrics`` (``tip_edge_share`` [1] per torque, light first).

    Returns
    -------
    bool
        False where its metrics carry no ``tip_edge_share`` or it is not finite (no load).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the tip edges of the flank boundary (:mod:`contact.ltca.edges`,
    :data:`~contact.optimize.development_evaluate.TIP_EDGE_KINDS`).
    """
    if e.metrics is None or "tip_edge_share" not in e.metrics:
        return False
    share = float(np.asarray(e.metrics["tip_edge_share"], float)[-1])
    return bool(math.isfinite(share) and share > 0.0)


def tip_lte_runs_on(best: DevelopmentEvaluation, targets: DevelopmentTargets) -> bool:
    """:data:`TIP_LTE`'s gate: ``best`` is checked at ``ltca run``'s sampling, its LTE p-p
    at the design torque is above :func:`lte_limit`, its contact there reaches a tip edge
    (:func:`reaches_tip`), and the targets and the design vary ``tip_relief`` and
    ``tip_relief_start`` with the relief above its lower bound.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps kept.
    targets : DevelopmentTargets
        The development's targets (``max_lte`` [µrad], ``variables``).

    Returns
    -------
    bool

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (docs/synthesis.md, "The tip relief for the design torque's LTE").
    """
    if (not best.checked_full
            or "lte_peak_to_peak" not in best.metrics
            or not all(n in targets.variables and n in best.values
                       for n in ("tip_relief", "tip_relief_start"))):
        return False
    design = lte_ends(best)[1]
    if not design > lte_limit(targets):  # NaN: not run
        return False
    lo = float(targets.variables["tip_relief"][0])
    return float(best.values["tip_relief"]) > lo + 1e-9 and reaches_tip(best)


@dataclasses.dataclass(frozen=True)
class Try:
    """One design a :class:`Relief` tries: its prescriptions and its change in words.

    Attributes
    ----------
    values : dict
        The design's prescriptions [file units].
    said : str
        The change as :func:`~contact.optimize.development_variant.said_variant`'s line
        says it ("with tip_relief 16.4 um from 0.893 (...)").
    change : str
        The change as :func:`~contact.optimize.development_keep.kept_why`'s "not kept"
        line names it ("the lighter tip relief").
    noted : str
        The design in the least-LTE record after "design <n> " ("with tip_relief 16.4
        um"); unused without a ``lever``.
    lever : str
        The lever in words for that record; empty: the design is not recorded.
    """

    values: dict[str, float]
    said: str
    change: str
    noted: str = ""
    lever: str = ""


#: what a :class:`Relief`'s designs generator is given back after each design: the design
#: kept so far and why the design was not kept ("" kept, None: not analysed)
Sent = tuple[DevelopmentEvaluation, str | None]


@dataclasses.dataclass(frozen=True)
class Relief:
    """One row of the trigger table :data:`RELIEFS`: a relief variant of the check.

    Attributes
    ----------
    stage : str
        The check stage of its designs (:attr:`DevelopmentEvaluation.stage`).
    runs_on : callable (best, targets, ratios) → bool
        Its gate, asked without an analysis (``ratios()``: the pair's (ε_vα, ε_vβ) [1],
        read only where needed).
    tries : callable (start, targets) → generator of Try
        Its designs in turn; each ``yield`` is given back :data:`Sent`.
    lost_first : bool
        :func:`~contact.optimize.development_keep.kept_why` asks for a lost target before
        the rank (says it whether or not the design is better).
    noted_at_gate : bool
        The design as checked goes into the least-LTE record once the gate holds (else
        with the variant's first design analysed).
    better : callable (best, e) → bool or None
        Whether a design is better (:func:`~contact.optimize.development_keep.kept_why`'s
        ``better``); None: it ranks better (the check's rank,
        :func:`~contact.optimize.development_keep.ranks_better`).
    ends : callable (e) → bool or None
        Whether the design kept so far ends the variant; None: it meets every target.
    lost : callable (best, e) → list of str or None
        The targets ``best`` met that ``e`` misses (``kept_why``'s ``lost``); None:
        :func:`~contact.optimize.development_keep.lost_targets`.
    """

    stage: str
    runs_on: Callable[[DevelopmentEvaluation, DevelopmentTargets,
                       Callable[[], tuple[float, float]]], bool]
    tries: Callable[[DevelopmentEvaluation, DevelopmentTargets],
                    Generator[Try, Sent, None]]
    lost_first: bool = False
    noted_at_gate: bool = False
    better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool] | None = None
    ends: Callable[[DevelopmentEvaluation], bool] | None = None
    lost: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], list[str]] | None = None


def _later_start(best: DevelopmentEvaluation, targets: DevelopmentTargets
                 ) -> Generator[Try, Sent, None]:
    # Why: below ε_vβ 1 one pair carries the load alone over part of the cycle; up to the
    # light torque the LTE is the unloaded TE, which the tip relief at the hand-over
    # raises, and at the design torque it is the deflection's variation, whose floor
    # ½ p-p(δ_design − δ_0) falls where the next pair takes up its share earlier — where
    # its flank near the tip is not relieved (the short tip relief of the seed's reference
    # designs, relief_start 0.86; Stadtfeld, Gleason Bevel Gear Technology, 2014). The
    # 15x28 at Σ 110° (ε_vα 1.19, ε_vβ 0.91; 91.8 / 612.4 N m; tip relief 15 µm from 0.85;
    # LTE p-p light / design, the largest over 10–612.4 N m, the floor [µrad]): as written
    # 90 / 103, 103, 94; start 0.75: 101 / 101, 121, 112; 0.9: 86 / 93, 93, 82, tolerant,
    # objective 66 → 50; 0.95 (beyond the default bound): 89 / 92, 94, 82.
    start = later_start(best.values, targets)
    if start is None:  # the gate asked it: not reached
        return
    light, design = lte_ends(best)
    yield Try(dict(best.values) | {"tip_relief_start": start},
              f"with tip_relief_start {start:.3g} (a later tip relief; LTE {light:.0f}/"
              f"{design:.0f} urad, eps_vb below {FACE_RATIO_BELOW:g})",
              "the later tip relief", f"with tip_relief_start {start:.3g}", TIP_START_LEVER)


def _lighter(best: DevelopmentEvaluation, targets: DevelopmentTargets
             ) -> Generator[Try, Sent, None]:
    # Why: a relief deeper than the teeth deflect at the design torque takes away flank
    # where the next pair would take up its load, so the design torque's LTE rises
    # (Stadtfeld 2014: the relief sized to the load's deflection; Litvin & Fuentes 2004
    # §9.4); the other steps try the shallower root relief only above 60 µrad
    # (checked_relief_variants) or on a design of the ellipse search (checked_length). The
    # 13x39 at Σ 80° (40.7 / 271.4 N m; tip relief 10 µm from 0.9, root relief 40 µm from
    # 0.2): LTE 10.8 / 41.1 µrad (the target 40 missed, every other met), 1472 MPa; tip
    # relief 7.5 µm: 10.3 / 38.0, 1448 MPa; root relief 30 µm: 10.9 / 39.1, 1616 MPa;
    # both: 10.1 / 35.9, each every target met and tolerant; root relief 20 µm: centre v
    # missed.
    for name in RELIEF_NAMES:
        if (name not in targets.variables or name not in best.values
                or not float(best.values[name]) > 0.0):
            continue
        lo, hi = (float(x) for x in targets.variables[name])
        now = float(best.values[name])
        x = float(np.clip(LENGTH_RELIEF_FRACTION * now, lo, hi))
        if not x < now - 1e-9:
            continue
        best, _ = yield Try(dict(best.values) | {name: x},
                            f"with {name} {x:.3g} um (its LTE just above "
                            f"{targets.max_lte:g} urad)", f"the lighter {name}")


def _tip_lte(start: DevelopmentEvaluation, targets: DevelopmentTargets
             ) -> Generator[Try, Sent, None]:
    # Why: once the loaded pattern spans the working depth the mesh's transfer runs onto
    # the tip relief's ramp, and the relief's depth is unloaded TE the load does not take
    # up (Stadtfeld 2014: the tip relief sized to the design load's deflection, no deeper;
    # Litvin & Fuentes 2004 §9.4); a lighter relief lowers it until the tip edge carries
    # load at the mounting excursions. The 15x31 at a = 0.056 d_e2 (ε_vβ 1.00; 94.1 /
    # 627.7 N m; tip relief 24.6 µm from 0.893): LTE 31 / 99 µrad, the gear's tip edge
    # loaded from ≈ 272 N m; tip relief 0 / 8 / 16 / 24.6 / 40 µm: 49 / 69 / 80 / 99 / 117
    # µrad at the design torque; 16 µm every target met, tolerant, objective 35.8 → 16.8;
    # 12 µm 76 µrad but 2.1–2.4 % on edges at ΔP; from 0.8: 39 / 83, centre v lost.
    (r_lo, r_hi), (s_lo, s_hi) = (tuple(float(x) for x in targets.variables[n])
                                  for n in ("tip_relief", "tip_relief_start"))
    light, design = lte_ends(start)
    limit = lte_limit(targets)
    best, tried = start, []
    for fraction in TIP_LTE_FRACTIONS:
        amount = round(float(np.clip(fraction * float(start.values["tip_relief"]),
                                     r_lo, r_hi)), 2)
        values = dict(start.values) | {"tip_relief": amount}
        if values in tried or values == dict(start.values):
            continue
        tried.append(values)
        best, why = yield Try(values, f"with tip_relief {amount:.3g} um from "
                              f"{float(values['tip_relief_start']):.3g} (its LTE {light:.0f}/"
                              f"{design:.0f} urad above {limit:g}, the design torque's "
                              "contact on a tip edge)", "the lighter tip relief",
                              f"with tip_relief {amount:.3g} um", LIGHTER_LEVER)
        if why not in (None, "", _SCORES_NO_BETTER):
            break
    kept_design = lte_ends(best)[1]
    s_now = float(best.values["tip_relief_start"])
    earlier = round(float(np.clip(s_now - TIP_LTE_START_STEP, s_lo, s_hi)), 4)
    if best.full[2] or not (kept_design > limit and earlier < s_now - 1e-9):
        return
    relief = f"with tip_relief {float(best.values['tip_relief']):.3g} um from {earlier:.3g}"
    yield Try(dict(best.values) | {"tip_relief_start": earlier},
              f"{relief} (a longer tip relief; its LTE {kept_design:.0f} urad at the design "
              f"torque above {limit:g})", "the longer tip relief", relief, LONGER_LEVER)


#: the later tip-relief start, on a face contact ratio below 1
TIP_START = Relief("tip start lte", tip_start_runs_on, _later_start)
#: a lighter tip, then root relief, where the LTE alone is missed by a little
LIGHTER = Relief("lighter relief", lambda best, targets, ratios: lte_alone_near(best),
                 _lighter, lost_first=True)
#: a lighter, then a longer tip relief, where a tip edge carries the design torque
TIP_LTE = Relief("tip lte", lambda best, targets, ratios: tip_lte_runs_on(best, targets),
                 _tip_lte, noted_at_gate=True)

#: the trigger table: the relief variants in the check's order
RELIEFS = (TIP_START, LIGHTER, TIP_LTE)


def checked_relief_variants(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       setup: Mapping[str, Any], teeth: KeptTeeth | None,
                       say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case], *,
                       reliefs: tuple[Relief, ...] = RELIEFS,
                       eps: tuple[float, float] | None = None, flank: str = "drive",
                       key_prefix: tuple | None = None,
                       tolerant: bool = True) -> DevelopmentEvaluation:
    """A drive design whose LTE a relief sets given each variant of ``reliefs`` whose gate
    holds, in turn (module docstring): each of its designs placed and checked at ``ltca
    run``'s sampling, kept where it ranks better, misses no target the design met and is
    tolerant at ΔE/ΔP ± 0.05 mm (a row's own ``better``, ``lost`` where it gives them); a
    variant ends at the first design kept that meets every target (or its ``ends``). At
    most one, two and four designs by the three variants.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`;
        ``targets.variables``: the bounds of the reliefs [µm] and ``tip_relief_start``
        [1]).
    reliefs : tuple of Relief, optional
        The variants, in turn (default :data:`RELIEFS`).
    eps : (float, float), optional — [1]
        The pair's (ε_vα, ε_vβ) (default
        :func:`~contact.optimize.development_matched_te.contact_ratios` of the design's
        case, read only where a gate needs it).
    flank : str, optional
        The flank the designs are checked on (``"drive"``, default, or ``"coast"``:
        :func:`~contact.optimize.development_variant.said_variant`'s).
    key_prefix : tuple, optional
        The kept pinion tooth's key before the design's bearing (the coast flank's:
        the drive design's bearing key and ``"coast"``); default the bearing alone.
    tolerant : bool, optional
        Ask the mounting tolerance at ΔE/ΔP ± 0.05 mm (default True; the coast flank's
        steps do not: the tolerance is the drive flank's, :func:`~contact.optimize.
        development_keep.kept_why`'s ``tolerant``).

    Returns
    -------
    DevelopmentEvaluation
        The design kept last (its ``stage`` the variant's); ``best`` itself where no gate
        held or no design was kept.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    Source: issue 71; the check's keep rule (docs/synthesis.md, "Development bearing") and
    the levers measured (module docstring; Stadtfeld, *Gleason Bevel Gear Technology*,
    2014: the relief sized to the design load's deflection).
    """
    for relief in reliefs:
        def ratios(case=best.case) -> tuple[float, float]:
            if eps is not None:
                return float(eps[0]), float(eps[1])
            return contact_ratios(case) if case is not None else (math.nan, math.nan)

        if not relief.runs_on(best, targets, ratios):
            continue
        start, noted = best, relief.noted_at_gate
        if noted:
            lte_reached(setup, start, f"design {start.index + 1} as checked")
        tries = relief.tries(start, targets)
        t = next(tries, None)
        while t is not None:
            e = said_variant(best, t.values, relief.stage, t.said, targets, setup, teeth,
                             say, placed, flank=flank, key_prefix=key_prefix)
            why = None
            if e is not None:
                rule = {} if relief.better is None else {"better": relief.better}
                why = kept_why(best, e, targets, setup, teeth, say, t.change,
                               lost=relief.lost or lost_targets,
                               lost_first=relief.lost_first, tolerant=tolerant, **rule)
                if t.lever:
                    if not noted:
                        lte_reached(setup, start, f"design {start.index + 1} as checked")
                        noted = True
                    lte_reached(setup, e, f"design {start.index + 1} {t.noted}", why,
                                t.lever)
                best = best if why else e
                if best.full[2] if relief.ends is None else relief.ends(best):
                    break
            try:
                t = tries.send((best, why))
            except StopIteration:
                t = None
    return best
