"""The coast flank's development: its check as synthesised, its own search where it misses
a target, and its analysis at its own design torque.

:func:`coast_development` checks the chosen drive design's coast flank at
:data:`CHECK_LTCA` and, where it misses a target, runs the drive flank's stages and check
on the coast flank's own prescriptions (:data:`COAST_BEARING_DESIGNS` bearings, budget
``coast_max_evaluations``). :func:`coast_rated_torque` is the coast side's rated torque;
:func:`_coast_check` analyses the written case's coast flank as ``ltca run --flank
coast`` does (:func:`_as_run`) and :func:`coast_flank_capacity` lowers its design torque to
what it carries (:func:`contact.optimize.development_coast.coast_capacity`);
:func:`coast_at_its_torque` develops it again where that fell below
:data:`COAST_REDEVELOP` of the torque it was developed at; :func:`coast_peak_relief` gives
it a lighter tip relief where its peak pressure set its design torque. Split out of
:mod:`contact.optimize.development` (issue 71), which re-exports every public
name.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from contact.compliance.fe.worker_cpu import cpu_seconds
from contact.optimize import development_evaluate as evaluation
from contact.optimize.development_check import (
    checked_best,
    checked_centre_u,
    checked_coast_lte,
    checked_length,
    checked_long,
)
from contact.optimize.development_coast import CoastCapacity, CoastCheck, coast_capacity
from contact.optimize.development_confirm import confirmer
from contact.optimize.development_evaluate import (
    CHECK_LTCA,
    MEMO_DECIMALS,
    KeptTeeth,
    bearing_key,
    design_metrics,
    evaluator,
    grid_bounds,
    static_strength,
)
from contact.optimize.development_keep import ranks_better
from contact.optimize.development_result import (
    DevelopmentEvaluation,
    floor_torque,
    metrics_text,
)
from contact.optimize.development_root import decided_case, refined_for_root
from contact.optimize.development_stages import search_flank
from contact.optimize.development_targets import (
    FAILED,
    METRIC_NAMES,
    TE_NAME,
    DevelopmentTargets,
    development_score,
)
from contact.pipeline import coast_flank_torques
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import (
    BasicDesign,
    flank_option_values,
    with_flank_options,
)

#: the development's one logger, whichever of its modules logs
log = logging.getLogger("contact.optimize.development")


#: most bearings of the coast flank's search (each a synthesis, ≈ 2 s CPU face milled, 4 s
#: face hobbed): the initial simplex of the path angle and the ellipse. On four designs of
#: docs/own_gear_set.md (hypoids 12x41, 10x43, 9x37 face milled, 11x43 face hobbed) 6
#: bearings of 12 designs chose the same coast design as 3 of 10 or of 8, for 40-50 % more
#: CPU (18.7 against 12.3 s on the 12x41, 28.7 against 20.3 s on the 11x43): the coast
#: flank's shortfalls are its edges, which its relief answers
COAST_BEARING_DESIGNS = 3


def coast_rated_torque(case: Case | None, basic: BasicDesign, design: float) -> float:
    """The torque [N·m] the coast side is rated for at long life: the basic file's
    ``[rating] coast_design_torque``, else the coast side's ISO 10300 capacity where it is
    below ``design`` (:func:`contact.load_capacity.iso10300.capacity.
    with_coast_design_torque`), else ``design``."""
    from contact.load_capacity.iso10300.capacity import (
        with_coast_design_torque,
        with_design_torque,
    )

    given = basic.rating.get("coast_design_torque")
    if given is not None:
        return float(given)
    if case is None:
        return design
    try:
        value = with_coast_design_torque(with_design_torque(case, design)[0])[1]
    except Exception as exc:  # reported, never fatal: the design torque rates both sides
        raise_if_interrupted(exc)
        log.info("coast side's ISO capacity not computed: %s", exc)
        return design
    return float(value) if math.isfinite(value) and value < design else design


def coast_start(case: Case | None, basic: BasicDesign, design: float) -> tuple[float, str]:
    """The coast design torque the coast flank is first analysed at, and what it is: the
    smaller of the design torque ``design`` and the coast side's rated torque
    (:func:`coast_rated_torque`), named so that the search's reason says what the number is
    (round 20 of issue 71: "at 466.1 N m …" did not say it was the coast side's ISO
    capacity).

    Parameters
    ----------
    case : geometry.case.Case or None
        The synthesised case (its rating gives the coast side's ISO capacity).
    basic : BasicDesign
        Its ``[rating] coast_design_torque``, if given.
    design : float — [N·m]
        The design torque (the drive's).

    Returns
    -------
    (torque [N·m], name) — name "its [rating] coast_design_torque", "its ISO 10300
    capacity" or "the design torque".

    Raises
    ------
    Nothing (the rating's failure is logged: the design torque then).

    Notes
    -----
    Source: ISO 10300-2/-3:2014 rate each side with its own flank angles
    (:func:`contact.load_capacity.iso10300.capacity.with_coast_design_torque`).
    """
    rated = coast_rated_torque(case, basic, design)
    if rated >= design:
        return design, "the design torque"
    if basic.rating.get("coast_design_torque") is not None:
        return rated, "its [rating] coast_design_torque"
    return rated, "its ISO 10300 capacity"


def coast_torque_searched(basic: BasicDesign) -> bool:
    """Whether the coast design torque is searched down to what the coast flank's
    developed bearing carries (:func:`coast_flank_capacity` with ``lower``): everywhere
    but where the basic file gives its own ``[rating] coast_design_torque``. A design
    torque given (``[synthesis] design_torque`` or ``[rating] design_torque``) is the
    drive's: the coast flank that cannot carry it gets its own lower design torque, as
    where none is given (issue 71 item 2, "both flanks, one design torque that holds").

    Why: with the user's design torque the coast flank was only analysed at it. Measured
    on the industrial spiral bevel 24x36 m_et 13 given 8350 N m (benchmarks/data/
    unseen_designs/industrial_spiral_bevel_24x36_m13_t8350.toml, 2026-11-27): written
    with no coast design torque, its `ltca run --flank coast` carried 2.0 % of the torque
    on plastic edges (verdict ATTENTION)."""
    return basic.rating.get("coast_design_torque") is None


def coast_capacity_said(basic: BasicDesign, cap: CoastCapacity | None,
                        torque_name: str = "", design: float | None = None) -> str:
    """Why the coast design torque is what the coast capacity search ``cap``
    (:func:`coast_flank_capacity`) found, in numbers: its reason, preceded — where the
    basic file gives a design torque (the drive's) and the search lowered the coast design
    torque — by "the drive's design torque Y N m ([synthesis] design_torque) is not the
    coast flank's: " (Y as the case runs it, rounded down by
    :func:`~contact.optimize.development_result.floor_torque`; the reason then gives what
    the torque the search started at does to the coast flank: its peak against the static
    strength, its plastic share); empty where ``cap`` is None. ``torque_name``, where
    given, names the design torque in place of "[synthesis] design_torque": the
    development's own torque the basic data carry (the drive developed again in its LTE
    window, :func:`contact.optimize.development_written_lte.window_name`); ``design``
    [N·m], where given, is that torque as the development ended with it (raised above the
    given one: :func:`contact.optimize.development._window_raised`)."""
    if cap is None:
        return ""
    name, first = torque_name or "[synthesis] design_torque", basic.options.design_torque
    if design is not None and first is not None and design > float(first):
        name = f"raised from {plain_number(floor_torque(float(first)))} N m, {name}"
    given = (name, first if design is None else design)
    if given[1] is None:
        given = ("[rating] design_torque", basic.rating.get("design_torque"))
    if given[1] is None or not cap.lowered:
        return cap.reason
    # as the case runs it (floor_torque): the 19x57's given 2865.6 read "2866" (round 20)
    return (f"the drive's design torque {plain_number(floor_torque(float(given[1])))} N m "
            f"({given[0]}) "
            f"is not the coast flank's: {cap.reason}")


def _as_run(case: Case, basic: BasicDesign, setup: dict[str, Any], coast: float) -> Case:
    """``case`` as ``ltca synthesize`` writes it for the torques in ``setup``: its
    ``[operating]`` torques the light and the design torque (to 0.1 N·m, rounded down,
    :meth:`DevelopmentResult.recorded`) where the basic file gives none, ``[rating]
    design_torque`` the design torque and ``coast_design_torque`` ``coast`` where it is
    below it — the case whose ``ltca run --flank coast`` runs at
    :func:`contact.pipeline.flank_torques`."""
    import json
    from types import MappingProxyType

    design = float(setup["torques"][1])
    rating = dict(case.extra.get("rating") or {}) | {"design_torque": design}
    rating.pop("coast_design_torque", None)
    if coast < design:
        rating["coast_design_torque"] = float(coast)
    more: dict[str, Any] = {}
    if "torque" not in basic.operating:
        more["operating"] = dataclasses.replace(
            case.operating, torque=tuple(floor_torque(t) for t in setup["torques"]))
    extra = json.loads(json.dumps({**case.extra, "rating": rating}))
    return dataclasses.replace(case, extra=MappingProxyType(extra), **more)


def _coast_check(case: Case, basic: BasicDesign, setup: dict[str, Any], torque: float,
                 root_stress: bool, plastic_limit: float = 0.0,
                 edge_limit: bool = False) -> CoastCheck:
    """The coast flank of the written ``case`` analysed as ``ltca run --flank coast``
    analyses it with the coast design torque ``torque`` (:func:`_as_run`,
    :func:`contact.pipeline.flank_torques`; :data:`CHECK_LTCA`, the FE root stress where
    ``root_stress`` and the ISO 10300 rating of the coast side); ``plastic_limit``: the
    plastic share allowed [1] (the development's ``max_plastic_share``); ``edge_limit``:
    the counted edges' peak judged against the static strength too (the development's
    ``coast_edge_capacity``)."""
    from contact.chain import AnalysisChain
    from contact.optimize.development_root import pitting_safety, root_safety
    from contact.pipeline import flank_torques, run_analysis

    c = _as_run(case, basic, setup, torque)
    torques = list(flank_torques(c, "coast")[0])
    steps = AnalysisChain.contact_only()
    if root_stress:
        steps = steps.with_root_stress().with_efficiency().with_load_capacity()
    tree = run_analysis(c, torques, flank="coast", options=CHECK_LTCA, deviations=False,
                        steps=steps)
    ms = light_and_design(design_metrics(tree, c))
    lt = tree["/ltca"]
    k = int(np.argmax(lt["torque"].values))
    safety, s_min, member = np.full(len(torques), np.nan), math.nan, ""
    pit, s_h_min, pit_member = np.full(len(torques), np.nan), math.nan, ""
    if root_stress:
        try:
            safety, s_min, member = root_safety(tree)
        except LookupError as exc:  # the verdict says it; the contact criteria stand
            log.info("development coast root stress not checked: %s", exc)
        try:  # the local pitting safety at long life (development_root.pitting_safety)
            pit, s_h_min, pit_member = pitting_safety(tree)
        except LookupError as exc:
            log.info("development coast pitting safety not checked: %s", exc)
    grid = (*grid_bounds(tree), static_strength(tree))
    rounding = False
    if member and math.isfinite(safety[k]) and safety[k] < s_min:
        # a root failure at the FE model's step-2 slot-bottom rounding is a lower bound
        # (contact.ltca.root_stress.slot_bottom_notes; issue 71): said with the failure
        from contact.ltca.root_stress import slot_bottom_notes

        rounding = any(line.startswith(f"root stress: the {member}'s peak")
                       for line in slot_bottom_notes(c, lt.to_dataset(), "coast"))
    return CoastCheck(float(torques[k]), float(ms["pressure_max_flank"][k]),
                      float(grid[4]), float(np.max(ms["plastic_share"])),
                      float(safety[k]), float(s_min), member,
                      float(safety[1 - k]) if len(torques) == 2 else math.nan,
                      float(torques[1 - k]) if len(torques) == 2 else math.nan,
                      (ms, grid, tuple(float(t) for t in torques)), plastic_limit,
                      float(pit[k]), s_h_min, pit_member,
                      float(pit[1 - k]) if len(torques) == 2 else math.nan, rounding,
                      float(ms["edge_peak"][k]) if "edge_peak" in ms else math.nan,
                      edge_limit)


def light_and_design(metrics: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """The development's metrics (each of shape (torque, ...)) at the (light, design)
    torque the scores read: as given where the analysis ran at two torques; where it ran at
    one — the coast design torque at or below the light torque, onto which
    :func:`contact.pipeline.flank_torques` limits both, as ``ltca run --flank coast`` does —
    that one analysis stands for both (a spiral bevel 19x23 whose Formate coast flank held
    only below the light torque: ``IndexError`` out of ``ltca synthesize``, issue 71)."""
    return {name: (np.repeat(np.asarray(v)[:1], 2, axis=0) if np.ndim(v) and len(v) == 1
                   else v) for name, v in metrics.items()}


def coast_flank_capacity(case: Case, basic: BasicDesign, coast: _CoastOutcome,
                         targets: DevelopmentTargets, setup: dict[str, Any], start: float,
                         root_stress: bool, lower: bool, say: Callable[[str], None],
                         start_name: str = "") -> tuple[_CoastOutcome, CoastCapacity | None]:
    """The written case's coast flank at its own design torque ``start`` (the smaller of
    the design torque and the coast side's rated torque), as ``ltca run --flank coast``
    analyses it (:func:`_coast_check`), and — where ``lower`` (no ``[rating]
    coast_design_torque`` given in the basic file, :func:`coast_torque_searched`; a design
    torque given is the drive's) — the coast design torque lowered to what the developed bearing
    carries (:func:`contact.optimize.development_coast.coast_capacity`: flank peak within
    the static strength, no plastic segment, S_F,FE >= S_Fmin). The coast outcome's
    metrics and torques become those of the last check at the torque kept. The root
    stress on the FE level the development decides root-limited torques on
    (:func:`contact.optimize.development_root.decided_case`; a coarse level's failing root
    check taken again on the default model, :func:`~contact.optimize.development_root.
    refined_for_root`); ``start_name`` names what ``start`` is in the search's reason
    (:func:`coast_start`)."""
    refined_at: list[float] = []  # the coast torque whose coarse root check moved the level

    def analyse(torque: float) -> CoastCheck:
        check = _coast_check(decided_case(case, setup), basic, setup, torque, root_stress,
                             targets.max_plastic_share, targets.coast_edge_capacity)
        if "root" in check.failures and refined_for_root(
                decided_case(case, setup), setup, coast_root_torque_text(torque),
                check.root_safety, check.s_min, say) is not None:
            refined_at.append(torque)
            # a coarse level's failing root check: the coast torque decided on the default
            check = _coast_check(decided_case(case, setup), basic, setup, torque,
                                 root_stress, targets.max_plastic_share,
                                 targets.coast_edge_capacity)
        return check

    try:
        if lower:
            cap = coast_capacity(analyse, start, say, start_name=start_name)
            check = cap.final
            if refined_at:
                setup["fe_level_why"] = coast_root_torque_kept(
                    setup.get("fe_level_why", ""), refined_at[0], cap.torque)
        else:
            cap, check = None, analyse(start)
    except Exception as exc:  # reported, never fatal: the coast search's metrics stay
        raise_if_interrupted(exc)
        log.info("development coast capacity not checked: %s", exc)
        say(f"development: coast flank not checked at its design torque ({exc})")
        return coast, None
    if check is None or check.result is None:
        return coast, cap
    mc, gc, torques = check.result
    fc = development_score(mc, targets, gc[:4], centre_v=setup["centre_v"],
                           pressure_limit=gc[4])
    best = dataclasses.replace(coast.best, metrics=mc, objective=fc[0], shortfalls=fc[1],
                               met=fc[2], full=fc)
    return coast._replace(best=best, torques=torques), cap


def coast_root_torque_text(torque: float) -> str:
    """The coast torque ``torque`` [N·m] of a failing coarse-level root check as the FE
    level's note names it (:func:`contact.optimize.development_root.refined_for_root`):
    "coast design torque (T N m)"; :func:`coast_root_torque_kept` rewrites it where the
    coast capacity search then writes another torque."""
    return f"coast design torque ({plain_number(torque)} N m)"


def coast_root_torque_kept(why: str, torque: float, kept: float) -> str:
    """The FE level's note ``why`` with its coast torque ``torque`` [N·m] named for what it
    is once the coast flank's capacity search has ended at ``kept`` [N·m]: unchanged where
    ``kept`` is ``torque`` (to the digits printed), else "coast torque T N m, one the coast
    flank's capacity search checked (the coast design torque written: K N m)".

    ``ltca synthesize`` prints ``why`` as a note of the case written; a torque the search
    went on from is not the coast design torque the case carries.

    Parameters
    ----------
    why : str — the note (:func:`contact.optimize.development_root.refined_for_root`); a
        note without :func:`coast_root_torque_text` of ``torque`` is returned as given
    torque : float — [N·m] the coast torque whose coarse root check moved the FE level
    kept : float — [N·m] the coast design torque the search kept

    Returns
    -------
    str

    Notes
    -----
    Source: issue 71, round 35 (helper unseen97): the FH hypoid 14×37 at Σ 85° printed
    "the coarse10 FE level reads S_F,FE 1.25 < S_Fmin 1.3 at the coast design torque
    (331.1 N m)" where the coast design torque written is 286.7 N·m (its local pitting
    capacity; S_F,FE 1.54 there on the default model): 331.1 N·m was the search's start.
    """
    named = coast_root_torque_text(torque)
    if named not in why or plain_number(kept) == plain_number(torque):
        return why
    return why.replace(named, f"coast torque {plain_number(torque)} N m, one the coast "
                              f"flank's capacity search checked (the coast design torque "
                              f"written: {plain_number(kept)} N m)", 1)


def coast_setup(setup: dict[str, Any], coast: float) -> dict[str, Any]:
    """The development's ``setup`` with the coast flank's torques for its design torque
    ``coast``: the drive's light and design torque (``setup["torques"]``) taken at the same
    shares of ``coast`` as of the design torque, as ``ltca run --flank coast`` analyses the
    case written (:func:`contact.pipeline.coast_flank_torques`); a ``coast`` at or above
    the design torque leaves them.

    Parameters
    ----------
    setup : dict
        The development's state; ``setup["torques"]``: [light, design] [N·m], the light
        torque ``light_load`` × the design torque (:func:`contact.pipeline.case_torques`).
    coast : float — [N·m], the coast design torque, finite and > 0

    Returns
    -------
    dict
        A copy of ``setup`` whose ``"torques"`` are the coast flank's [light, design].

    Raises
    ------
    ValueError
        ``coast`` not finite or not > 0 (:func:`~contact.pipeline.coast_flank_torques`).

    Notes
    -----
    Source: issue 71 (no edge contact at 15 % of the design torque, each flank at its
    own: the user's ``light_load`` share on the coast flank too).
    """
    torques = setup["torques"]
    return dict(setup, torques=list(coast_flank_torques(torques, coast, torques[1])))


def coast_side(basic: BasicDesign) -> str:
    """The pinion flank side of the coast flank: ``"convex"`` where the drive flank is the
    concave, else ``"concave"``.

    Parameters
    ----------
    basic : BasicDesign
        Its ``options.drive_flank``.

    Returns
    -------
    str

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the seed's convention of the pinion's concave (drive) and convex (coast) flank
    of a left-hand pinion; geometry.synthesis.basic_design's flank options.
    """
    return "convex" if basic.options.drive_flank == "concave" else "concave"


class WrittenCoast(NamedTuple):
    """The coast flank of a written basic design as a step after the coast development
    varies it (:func:`written_coast`): the basic design, its coast side
    (:func:`coast_side`), ``placed`` (coast prescriptions → the case synthesised, with the
    development's memo) and the coast's kept-teeth key prefix (the drive bearing's key and
    ``"coast"``)."""

    basic: BasicDesign
    side: str
    placed: Callable[[dict], Case]
    key_prefix: tuple

    def outcome(self, coast: Any, got: DevelopmentEvaluation) -> Any:
        """``coast`` (a coast outcome) with the design ``got`` kept: its ``basic`` carrying
        ``got``'s coast prescriptions, its ``best`` ``got``."""
        return coast._replace(basic=with_flank_options(self.basic, self.side, got.values),
                              best=got)


def written_coast(developed: BasicDesign, drive: DevelopmentEvaluation,
                  memo: dict) -> WrittenCoast:
    """What a step on the written case's coast flank needs to vary it
    (:func:`coast_lte_at_its_torques`, :func:`coast_peak_relief`, the coast LTE within
    the flank's capacity, the coast edge peak).

    Parameters
    ----------
    developed : BasicDesign
        The basic design written (both flanks' prescriptions).
    drive : DevelopmentEvaluation
        The drive design written (its bearing keys the kept pinion teeth).
    memo : dict
        The development's synthesis memo.

    Returns
    -------
    WrittenCoast

    Raises
    ------
    Nothing (the synthesis raises where ``placed`` is called).

    Notes
    -----
    Source: issue 71 (the coast flank developed on the drive's targets).
    """
    from geometry.synthesis.case_synthesis import synthesize

    side = coast_side(developed)

    def placed(values: dict) -> Case:
        return synthesize(with_flank_options(developed, side, values), memo=memo)[0]

    return WrittenCoast(developed, side, placed, (*bearing_key(drive.values), "coast"))


class _CoastOutcome(NamedTuple):
    """What :func:`coast_development` did: the basic design with the chosen coast
    prescriptions, the chosen coast design (None where its analysis failed), the designs
    of its search, its status (:data:`COAST_STATUS`) and the coast flank's metrics as
    synthesised where the search ran (else None), and the (light, design) torques [N·m]
    of its metrics (its own design torque: :func:`coast_flank_capacity`)."""

    basic: BasicDesign
    best: DevelopmentEvaluation | None
    evaluations: list[DevelopmentEvaluation]
    status: str
    before: dict[str, np.ndarray] | None
    torques: tuple[float, ...] = ()


def coast_development(developed: BasicDesign, drive: DevelopmentEvaluation,
                      targets: DevelopmentTargets, setup: dict[str, Any],
                      teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                      make: Callable[[BasicDesign], Case]) -> _CoastOutcome:
    """The coast flank of :func:`develop`, after the drive flank ``drive`` is chosen
    (``developed`` carries its prescriptions): analysed as synthesised at
    :data:`CHECK_LTCA` at the same light and design torque; where it misses a target and
    ``targets.coast_max_evaluations`` > 0, the two stages of the drive flank's search
    (:func:`search_flank`) on the coast flank's own prescriptions with that budget, the best
    checked at :data:`CHECK_LTCA` (:func:`checked_best`; where its LTE exceeds the
    verdict's 60 µrad the coast LTE steps, :func:`checked_coast_lte`, then, where the LTE
    target is still missed, the long bearing, :func:`checked_long`; where the pattern
    length is missed, the ellipse searched for it, :func:`checked_length`) and chosen where it
    scores better than the flank as synthesised. The drive flank is the same in every design
    (the synthesis places the coast flank against it, never the reverse), so its result
    stands; the coast designs' pinion teeth are kept under the drive's bearing and the
    coast's (:class:`KeptTeeth`). ``make``: the coarse search's synthesis (no tip
    planes); the designs checked are synthesised as written (with the memo), so the
    chosen one is the case written, bit for bit."""
    from geometry.synthesis.case_synthesis import synthesize

    side = coast_side(developed)
    start = flank_option_values(developed.options.flank(side))
    drive_key = bearing_key(drive.values)
    torques = tuple(setup["torques"])  # the coast side's own light and design torque
    c0 = cpu_seconds()
    try:  # the flank as synthesised (its pinion tooth is the drive bearing's: the same)
        case0 = drive.case if drive.checked else synthesize(developed, memo=memo)[0]
        m0, grid = evaluation.analyse_design(case0, setup["torques"], options=CHECK_LTCA,
                                             teeth=teeth, pinion_key=drive_key, flank="coast")
        full = development_score(m0, targets, grid[:4], centre_v=setup["centre_v"],
                                 pressure_limit=grid[4])
    except Exception as exc:  # reported, never fatal
        raise_if_interrupted(exc)
        log.info("development coast check failed: %s", exc)
        # the reason itself, not only its type: "InputError" alone named no cause (the
        # unseen industrial 11x43 of m_mn 12, issue 71 round 13)
        failed = (f"its analysis at {plain_number(torques[0])}/{plain_number(torques[1])} "
                  f"N m failed: {type(exc).__name__}: {exc}")
        if targets.coast_max_evaluations == 0:
            say(f"development: coast flank {side}: not checked ({failed})")
            return _CoastOutcome(developed, None, [], "not checked", None, torques)
        # developed all the same: a coast flank as synthesised whose pairs lose contact
        # over the mesh cycle (its short default ellipse on a low face contact ratio: the
        # spiral bevel 13x17 at Sigma 50 deg, eps_vb 0.70, issue 71 round 31) is what the
        # search's longer ellipses and turned paths are for
        m0, full = None, (FAILED, {}, False)
        say(f"development: coast flank {side} as synthesised: {failed}; developing it at "
            f"{plain_number(torques[0])}/{plain_number(torques[1])} N m (light/design) on "
            f"the same targets: varying {', '.join(targets.variables)} (at most "
            f"{targets.coast_max_evaluations} designs, coarse LTCA)")
        case0 = None
    synthesised = DevelopmentEvaluation(
        -1, {k: start[k] for k in targets.variables},
        m0 if m0 is not None else {k: np.full(2, np.nan) for k in METRIC_NAMES},
        full[0], full[1], full[2], "", cpu_seconds() - c0, case0, full,
        checked=m0 is not None, stage="synthesised")
    n_max = targets.coast_max_evaluations
    if m0 is not None:
        missed = [k for k, v in full[1].items() if v > 0]
        head = (f"development: coast flank {side} as synthesised, at the default sampling: "
                f"{metrics_text(m0)}; ")
        if full[2]:
            say(head + "every target met: not developed")
            return _CoastOutcome(developed, synthesised, [], "met", None, torques)
        if n_max == 0:
            say(head + f"misses {', '.join(missed)}; coast development off "
                "(coast_max_evaluations = 0)")
            return _CoastOutcome(developed, synthesised, [], "off", None, torques)
        say(head + f"misses {', '.join(missed)}; developing it at "
            f"{plain_number(torques[0])}/{plain_number(torques[1])} N m (light/design) on "
            f"the same targets: varying {', '.join(targets.variables)} (at most {n_max} "
            "designs, coarse LTCA)")
    evals: list[DevelopmentEvaluation] = []
    prefix = (*drive_key, "coast")

    def basic_of(values: dict[str, float]) -> BasicDesign:
        return with_flank_options(developed, side, values)

    def placed(values):
        return synthesize(basic_of(values), memo=memo)[0]

    # a coarse "all met" stop confirmed at the default sampling before it ends the coast
    # search, as the drive's (development_confirm; the check below reads it back: the same
    # `placed`, the same kept-teeth key)
    confirmed_lines: set[int] = set()  # the designs whose check line the confirmation said
    evaluate = evaluator(developed, targets, setup, teeth, say, evals, "coast", n_max,
                         key_prefix=prefix,
                         confirm=confirmer(targets, setup, teeth, say, placed, side="coast",
                                           n_max=n_max, key_prefix=prefix,
                                           said_lines=confirmed_lines))
    chosen = synthesised
    if search_flank(evaluate, evals, basic_of, make, targets, start, developed, n_max,
                    COAST_BEARING_DESIGNS):
        best = checked_best(evals, targets, setup, teeth, say, placed, side="coast",
                            key_prefix=prefix, n_max=n_max, slopes=evaluate.slopes,
                            said_lines=confirmed_lines)
        # a pattern off its centre along the face: the coast flank's own M placed off the
        # mean cone distance (the drive flank's M stays where it is)
        best = checked_centre_u(best, targets, setup, teeth, say, placed, flank="coast",
                                key_prefix=prefix)
        # an LTE above the verdict's limit: the ellipse longer, the path turned lengthwise
        best = checked_coast_lte(best, targets, setup, teeth, say, placed,
                                 key_prefix=prefix, level=start.get(TE_NAME))
        # an LTE still missed: the long bearing (the drive flank's last check step)
        best = checked_long(best, targets, setup, teeth, say, placed, flank="coast",
                            key_prefix=prefix)
        # a pattern length still missed: the ellipse searched for it (the drive flank's
        # length step; the 13x39 at Sigma 80: 0.65 long at 48.9 / 197 N m, no step moved it)
        best = checked_length(best, targets, setup, teeth, say, placed,
                              level=start.get(TE_NAME, math.nan), flank="coast",
                              key_prefix=prefix)
        as_synthesised = all(round(v, MEMO_DECIMALS) == round(start[k], MEMO_DECIMALS)
                             for k, v in best.values.items())
        # the check's one rank (check_rank): a coast LTE ltca run's verdict FAILs (above
        # 2 x 60 urad) last, then every target met, then the objective (issue 71)
        # (where the flank as synthesised could not be analysed, any design of the
        # search that could is better)
        if best.checked and not as_synthesised and (
                ranks_better(synthesised, best) if m0 is not None else best.full[0] < FAILED):
            chosen = best
    if chosen is synthesised and m0 is None:
        say(f"development: coast flank {side}: no design of its search could be analysed "
            "either; not checked")
        return _CoastOutcome(developed, None, evals, "not checked", None, torques)
    if chosen is synthesised:
        say(f"development: coast flank {side}: no design of its search did better than "
            "as synthesised; kept")
        return _CoastOutcome(developed, synthesised, evals, "not improved", m0, torques)
    return _CoastOutcome(basic_of(chosen.values), chosen, evals, "developed", m0, torques)


#: the coast design torque, as a fraction of the torque the coast flank was developed at,
#: below which :func:`coast_at_its_torque` develops it again at its own design torque [1]
COAST_REDEVELOP = 0.9


def pitting_pressure(cap: CoastCapacity) -> float:
    """[MPa] The coast flank's peak pressure at which its local pitting safety at long life
    is the rating's S_Hmin, from the check at the coast design torque (``cap.final``):
    p · S_H,loc / S_Hmin, the safety σ_HP / (p √(K_A K_v)) inversely proportional to the
    peak pressure p (:func:`contact.optimize.development_root.pitting_safety`). NaN where
    that check has no finite pressure, safety or S_Hmin.

    Why: the coast flank developed again at its capacity (:func:`coast_at_its_torque`) is
    scored on its targets, not on the capacity it was developed at. Measured on a
    face-hobbed spiral bevel 11x33 (Method 0, d_e2 170 mm, b2 26 mm, z0 5; issue 71): the
    first coast design held at 180.8 N m (1619 MPa, S_H,loc 1.01); the design developed
    there reached S_H,loc 0.75 at it, and the coast design torque fell to 119.2 N m, with
    LTE p-p 61 µrad there (2026-11-26)."""
    c = cap.final
    if c is None:
        return math.nan
    p, s, s_min = float(c.pressure), float(c.pitting_safety), float(c.s_h_min)
    if not (math.isfinite(p) and math.isfinite(s) and math.isfinite(s_min) and s_min > 0.0):
        return math.nan
    return p * s / s_min


def redeveloped_at(torque: float, developed_at: float) -> bool:
    """Whether the coast flank is developed again at its design torque ``torque`` [N·m]
    (:func:`coast_at_its_torque`): where it is below :data:`COAST_REDEVELOP` ×
    ``developed_at`` [N·m], the torque the coast flank was developed at, whatever lowered
    it — the coast flank's own capacity (:func:`coast_flank_capacity`) or the drive's
    root-stress or pitting capacity, which cuts the design torque after the coast flank
    is developed (the coast design torque is no higher than the drive's).

    Why the drive's cut too: the coast search scores its designs at the torques it runs
    at, and a bearing whose relief keeps its edges elastic there is not the best at a
    torque 0.6 of it. The face-hobbed hypoid 13x29 by Method 2 (benchmarks/data/
    unseen_designs; issue 71): its coast flank developed at 68.3 / 436.6 N m and written
    at 41.6 / 277.6 N m (the drive's root-stress capacity) had LTE p-p 50 / 64.5 µrad,
    objective 11.7 there; the long bearing of a design of its own search (ellipse 0.75,
    root relief 37.5 µm from 0.5, no crowning) 27 / 40 µrad, objective 5.5 at 277.6 N m,
    but 31.5 against 25.8 at 436.6 N m, where the search had ranked it
    (``benchmarks/development_levers.py --flank coast --from-case --check``,
    2026-11-27)."""
    return (math.isfinite(torque) and math.isfinite(developed_at)
            and torque < COAST_REDEVELOP * developed_at)


def coast_at_its_torque(pre_coast: BasicDesign, drive: DevelopmentEvaluation,
                        targets: DevelopmentTargets, setup: dict[str, Any],
                        teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                        make: Callable[[BasicDesign], Case], coast: _CoastOutcome,
                        cap: CoastCapacity | None, developed_at: float
                        ) -> _CoastOutcome | None:
    """The coast flank developed again where its design torque is well below the torque it
    was developed at (below :data:`COAST_REDEVELOP` × ``developed_at``,
    :func:`redeveloped_at`: its own static, plastic, root-stress or local pitting capacity,
    :func:`coast_flank_capacity`, or the drive's capacity cut), now at the torques ``ltca
    run --flank coast`` analyses (the new coast design torque and its light torque, the same
    share of it as the drive's of the design torque:
    :func:`contact.pipeline.coast_flank_torques`): :func:`coast_development` from the coast
    flank as synthesised (``pre_coast`` with the drive flank of ``drive``, and the basic
    file's coast prescriptions), with the budget ``coast_max_evaluations``, its flank peak
    pressure bounded by what the new coast design torque allows (:func:`pitting_pressure`).
    Returns its outcome where its chosen design ranks before the design chosen first at
    those torques (:func:`~contact.optimize.development_keep.ranks_better`: a checked LTE
    ``ltca run``'s verdict FAILs last, then every target met, then the objective;
    ``coast``'s metrics :func:`coast_flank_capacity` measured there), else None.

    Why: the relief that keeps a coast bearing elastic at a torque its flank cannot carry
    costs LTE at the torque it can (issue 71, the e-axle 11×39 at Σ 80°: developed at
    292.9 N·m with 30 µm tip relief and a −0.3° blade-angle change, its coast LTE p-p was
    72 µrad at its root-stress capacity 143.8 N·m)."""
    if (cap is None or coast.best is None or not redeveloped_at(cap.torque, developed_at)
            or targets.coast_max_evaluations == 0):
        return None
    if coast.best.full is not None and coast.best.full[2]:
        # the first design meets every target at the new torques (coast_flank_capacity
        # analysed it there as `ltca run --flank coast` does): that one analysis stands for
        # a search, whose design would replace it only where it met every target as well
        say(f"development: coast flank at its own design torque {plain_number(cap.torque)} N m (it "
            f"was developed at {plain_number(developed_at)} N m): every target met there; not "
            "developed again")
        return None
    say(f"development: coast flank developed again at its own design torque "
        f"{plain_number(cap.torque)} N m (it was developed at {plain_number(developed_at)} N m)")
    redo_setup = coast_setup(setup, cap.torque)
    # the flank peak pressure the new coast design torque allows (its local pitting
    # safety at S_Hmin) bounds the redevelopment's: a design developed there must carry
    # the torque it is developed at
    limit = pitting_pressure(cap)
    if math.isfinite(limit):
        held = (targets.max_flank_pressure if targets.max_flank_pressure is not None
                else setup.get("pressure_limit", math.inf))
        targets = dataclasses.replace(targets, max_flank_pressure=float(min(held, limit)))
    # the drive flank of every design is ``drive``'s, whatever design ``pre_coast`` was
    # made from: where the root-stress capacity gave the drive flank the check's steps
    # again after the first coast development (a new drive design at the lowered
    # torques), a ``pre_coast`` of the first carried the drive flank before them into the
    # case written. Measured on the truck hypoid 8x39 (a 45 mm, d_e2 400 mm;
    # tests/data/designs/truck_hypoid_8x39_a45.toml): the case kept path -58.75 deg,
    # ellipse 0.4 where the chosen design had -80 deg, 0.5; its `ltca run` found LTE
    # 99 / 115 urad and FAILed (spread 0.55) where the check of the chosen one gave 23 / 31
    pre_coast = with_flank_options(pre_coast, pre_coast.options.drive_flank, drive.values)
    again = coast_development(pre_coast, drive, targets, redo_setup, teeth, memo, say, make)
    old, new = coast.best, again.best
    if new is None or old.full is None or new.full is None:
        return None
    if ranks_better(old, new):  # a FAIL-level coast LTE never replaces a passing one
        say(f"development: coast flank at {plain_number(cap.torque)} N m: the design developed "
            f"there (objective {new.full[0]:.3g}) kept, not the first ({old.full[0]:.3g})")
        return again
    say(f"development: coast flank at {plain_number(cap.torque)} N m: the first design kept "
        f"(objective {old.full[0]:.3g}; developed there {new.full[0]:.3g})")
    return None



def coast_lte_at_its_torques(developed: BasicDesign, drive: DevelopmentEvaluation,
                             targets: DevelopmentTargets, setup: dict[str, Any],
                             teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                             coast: _CoastOutcome, cap: CoastCapacity | None,
                             developed_at: float, level: float | None = None
                             ) -> _CoastOutcome | None:
    """The coast LTE steps (:func:`checked_coast_lte`) once more, at the coast flank's
    final torques (``coast.torques``, those of :func:`coast_flank_capacity`'s check as
    ``ltca run --flank coast`` analyses the written case), where its design torque is
    below :data:`COAST_REDEVELOP` × ``developed_at`` (the torque the coast flank was
    developed and its LTE steps run at) and its LTE p-p there exceeds the verdict's limit
    (:data:`contact.study.verdicts.LTE_LIMIT`) at a torque. The coast design ``coast.best``
    (its metrics at those torques) is the base; the steps' acceptance is theirs
    (:func:`_coast_kept`), their flank peak pressure bounded as well by what the coast
    design torque allows (:func:`pitting_pressure` of ``cap``, where finite).
    ``developed``: the basic design written (both flanks' prescriptions); ``level``: the
    basic file's coast ``te_level`` [µrad] (:func:`checked_coast_te`); ``drive``: the drive
    design written (its bearing keys the kept pinion teeth). Returns the outcome with the
    design kept (its basic design carrying its coast prescriptions) where a step was
    kept, else None (nothing
    analysed where the LTE is within the limit or the torque was not lowered).

    Why: the coast LTE steps run at the torque the coast flank is developed at; where the
    drive's root-stress or pitting capacity lowers the design torque afterwards, a step
    refused there for its peak pressure can be the one the LTE needs at the torque written.
    The unseen spiral bevel 13x37 at Σ 60° (issue 71): its coast steps ran at 279.2 N m,
    where ellipse 0.5 peaked at 3906 MPa and was refused; written at 13.4 / 89.6 N m its
    coast LTE p-p was 111 / 68 µrad (1389 MPa), with the ellipse 0.7 and the tip relief
    from 0.85 54 / 38 µrad (1079 MPa)."""
    from contact.study.verdicts import LTE_LIMIT

    old = coast.best
    if (old is None or not old.checked_full or len(coast.torques) != 2
            or not float(coast.torques[1]) < COAST_REDEVELOP * float(developed_at)
            or not np.nanmax(old.metrics["lte_peak_to_peak"]) > LTE_LIMIT
            or targets.coast_max_evaluations == 0):
        return None
    limit = pitting_pressure(cap) if cap is not None else math.nan
    if math.isfinite(limit):
        held = (targets.max_flank_pressure if targets.max_flank_pressure is not None
                else setup.get("pressure_limit", math.inf))
        targets = dataclasses.replace(targets, max_flank_pressure=float(min(held, limit)))
    say(f"development: coast flank LTE p-p "
        f"{np.nanmax(old.metrics['lte_peak_to_peak']):.0f} urad at its own torques "
        f"{plain_number(coast.torques[0])}/{plain_number(coast.torques[1])} N m (its LTE steps "
        f"ran at {plain_number(developed_at)} N m): the coast LTE steps there")
    written = written_coast(developed, drive, memo)
    got = checked_coast_lte(old, targets, dict(setup, torques=list(coast.torques)), teeth,
                            say, written.placed, key_prefix=written.key_prefix, level=level)
    if got is old:
        return None
    return written.outcome(coast, got)


def peak_relief_text(first: CoastCheck, cap: CoastCapacity) -> str:
    """The progress line of :func:`coast_peak_relief`: the coast flank's peak at the torque
    its capacity search started at, the criterion that peak failed (the static strength
    or the local pitting safety, with their numbers) and the design torque it set.

    Round 23 (issue 71): the 7x43 at 0.8 of its ISO capacity printed "coast flank's peak
    1703 MPa at 105.8 N m set its design torque 57.1 N m" where the flank's limit the
    summary prints is 2400 MPa; the criterion was the pinion's local pitting safety 0.86.

    Parameters
    ----------
    first : CoastCheck
        The check at ``cap.start`` (its ``failures`` name the criterion).
    cap : CoastCapacity
        The coast capacity search (its ``start`` and ``torque``, [N·m]).

    Returns
    -------
    str
        One line, ``development: coast flank's peak … MPa at … N m (<criterion>) set its
        design torque … N m: a lighter tip relief``.
    """
    failures = first.failures
    why = "; ".join(failures[k] for k in ("flank", "pitting") if k in failures)
    return (f"development: coast flank's peak {first.pressure:.0f} MPa at "
            f"{plain_number(cap.start)} N m" + (f" ({why})" if why else "")
            + f" set its design torque {plain_number(cap.torque)} N m: a lighter tip relief")


def coast_peak_relief(developed: BasicDesign, drive: DevelopmentEvaluation,
                      targets: DevelopmentTargets, setup: dict[str, Any],
                      teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                      coast: _CoastOutcome, cap: CoastCapacity | None
                      ) -> _CoastOutcome | None:
    """The coast flank's lighter tip relief where its peak pressure lowered its design
    torque: where the coast capacity search (``cap``, :func:`coast_flank_capacity`)
    lowered it for the flank's static strength or its local pitting safety at the torque
    it started at, :func:`~contact.optimize.development_check.checked_coast_peak` on the
    written coast design (``coast.best``) at that one and its light torque
    (:func:`contact.pipeline.coast_flank_torques`), its peak
    there the search's, the targets the written design meets at its own torques kept and
    its LTE p-p within the verdict's limit (or the written design's, where above).
    ``developed``: the basic design written (both flanks' prescriptions); ``drive``: the
    drive design written (its bearing keys the kept pinion teeth). Returns the outcome
    with the step's design (its basic design carrying its coast prescriptions; the caller
    writes it and searches its capacity again, keeping it only where that is higher),
    else None (nothing analysed where the torque was not lowered for the peak).

    Why: :func:`~contact.optimize.development_check.checked_coast_peak` (the unseen hypoid
    6x45 at a 44 mm offset: its coast design torque 55 % of the drive's, set by the
    pinion's local pitting safety 0.87 at 76.4 N m under a 51 µm tip relief from half-way)."""
    from contact.optimize.development_check import checked_coast_peak
    from contact.study.verdicts import LTE_LIMIT

    old = coast.best
    if (cap is None or not cap.lowered or old is None or not old.checked_full
            or targets.coast_max_evaluations == 0):
        return None
    first = next((c for c in cap.checks if c.torque == cap.start), None)
    if first is None or not {"flank", "pitting"} & set(first.failures):
        return None
    met = {k for k, v in old.full[1].items() if v == 0.0}
    lte = max(LTE_LIMIT, float(np.nanmax(old.metrics["lte_peak_to_peak"])))
    say(peak_relief_text(first, cap))
    written = written_coast(developed, drive, memo)
    got = checked_coast_peak(old, targets, coast_setup(setup, cap.start),
                             teeth, say, written.placed, peak=first.pressure, met=met,
                             lte=lte, key_prefix=written.key_prefix)
    if got is None:
        return None
    return written.outcome(coast, got)
