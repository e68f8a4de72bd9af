"""Synthesis to a development bearing: basic data → settings whose loaded pattern is released.

Litvin's local synthesis (:mod:`geometry.synthesis`) makes the pinion from prescriptions at
the mean point M (contact-path angle, TE level, contact-ellipse length, profile relief);
it says nothing of the pattern under load, of the edges or of the mounting tolerances.
The **development** closes that loop the way a gear engineer does on the test stand and in
Gleason CAGE or Klingelnberg KIMoS: the prescriptions are varied until the loaded pattern
is a production bearing (:class:`DevelopmentTargets`):

* at light load (``light_load`` × the design torque) the pattern is about half the face
  width long, its centre slightly towards the toe and at mid-height, and it stays clear of
  toe, heel, tip and root;
* at the design torque no edge carries more than ``max_edge_share`` of the torque and no
  segment is plastic (at its contact-pressure limit);
* the LTE peak-to-peak stays below ``max_lte`` at both torques;
* the developed design is then checked at the mounting excursions ``offset_tolerance``
  (ΔE = ±V) and ``mounting_tolerance`` (ΔP = ±H) — the V-H check's two directions
  (:mod:`contact.study.vh_check`) at a typical assembly tolerance — and the result says
  whether the pattern stays clear of toe and heel and the edges elastic there.

Three stages per flank (:func:`develop`), with the levers a gear engineer develops a
bearing with (Stadtfeld, *Gleason Bevel Gear Technology*, 2014; Litvin & Fuentes 2004 ch.
9): the **bearing** (path angle, ellipse length: the pattern's bias and length), each design
a synthesis of its drive flank (:func:`geometry.synthesis.case_synthesis.synthesize` with
a memo: the coast flank, not varied there, is synthesised once); the **height**
(:func:`_height_stage`): the pinion blade's pressure-angle change
(:data:`HEIGHT_NAME`, :mod:`geometry.synthesis.blade_change`) found by a 1-D root-find on
the light-load footprint centre v (:func:`_centre_height`: secant, then regula falsi), with
the profile crowning (:data:`CROWNING_NAME`) raised where the centred pattern still
reaches an end of the working depth; then the **relief** (tip and root relief, the root relief's
start and the tip relief's own, ``tip_relief_start``), each relief design re-centred by one
step of the blade angle with the slope the height stage measured (:func:`_recentred`);
the height stage first lowers a high pattern by the root relief
(:func:`_root_relief_height`), and a **TE stage** (:func:`_te_stage`) lowers the modified
roll's ``te_level`` where the LTE misses (issue 71; docs/synthesis.md, "What sets the
pattern and the LTE"). The height and relief designs are the
synthesis' step 7 alone (steps 3-6 from the memo), ≈ 0.3 s CPU each. Each design is
analysed on its drive flank by a coarse LTCA (:data:`COARSE_LTCA`: one mesh cycle, 8 roll
positions, 12 segments per curve, shell compliance with the teeth kept across designs,
:class:`KeptTeeth`; no root stress) at the light and the design torque, summarised by
:func:`contact.study.summary.point_summary`. The best designs are then checked at
``ltca run``'s sampling (:data:`CHECK_LTCA`), the chosen one given the TE stage's steps
again (:func:`checked_te`) and its path turned towards the profile where it misses its
length or LTE there (:func:`checked_path`), and where the chosen one's flank peak
pressure at the rating's capacity exceeds the static strength the design torque is
lowered to what the bearing carries (:func:`static_capacity`): a design never fails its
own check at its own design torque; where the chosen one's checked LTE still FAILs
``ltca run``'s verdict (no design checked passed it), to the torque up to which its
bearing keeps the verdict's 60 µrad
(:func:`~contact.optimize.development_lte_capacity.lte_capacity`); where it exceeds the
local pitting limit, a longer
pattern and one centred lower are tried first
(:mod:`contact.optimize.development_pitting`). After the last drive step, the design
torque no higher than where the written drive design keeps 60 µrad at every torque ``ltca
run`` judges, else the drive developed again where its bearing's window ends
(:mod:`contact.optimize.development_written_lte`). Then the **coast flank**
(:func:`~contact.optimize.development_coast_flank.coast_development`): the chosen
design's coast flank, synthesised from its own prescriptions, is checked at
:data:`CHECK_LTCA` at the same light and design torque against the same targets (it
carries the full torque in reverse gear), and where it misses one it gets the same
stages and check on its own prescriptions (its own blade-angle change) with its own
budget (``coast_max_evaluations``); the drive flank's result stays as chosen, and the
coast side's design torque is capped at the coast flank's static capacity
(:meth:`DevelopmentResult.with_coast_capacity`). The objective
(:func:`development_score`) is a sum of squared, dimensionless shortfalls, minimised by a
bounded Nelder–Mead (``scipy.optimize.minimize``; the relief stage first samples its box
with scrambled Sobol points, ``scipy.stats.qmc``) that stops as soon as every target is
met. When the targets conflict (a short pattern and a low LTE on a pinion of few teeth),
the least objective wins and the case says which targets were missed, with their values.

The module is split by concern: the targets and their score in
:mod:`contact.optimize.development_targets`; one design analysed and scored (the coarse
LTCA, its metrics, the search's objective, the kept teeth) in
:mod:`contact.optimize.development_evaluate`; the search's stages (bearing, height, relief,
TE) in :mod:`contact.optimize.development_stages`; the final check at ``ltca run``'s
sampling (its steps, the static and root-stress capacity, the mounting tolerance) in
:mod:`contact.optimize.development_check` and the modules it is split into (a step's
design in ``development_variant``, the keep rule in ``development_keep``, the tolerance
in ``development_tolerance``, the pattern, LTE and coast steps in
``development_pattern_steps``, ``development_lte_steps``, ``development_coast_steps``);
the coast flank's development in
:mod:`contact.optimize.development_coast_flank`, its LTE within the flank's capacity (its
last step) in :mod:`contact.optimize.development_coast_capacity_lte` and its design torque in
:mod:`contact.optimize.development_coast`; the root-stress and pitting capacity in
:mod:`contact.optimize.development_root`; one design and the result (its text and its
records in the case) in :mod:`contact.optimize.development_result`; the orchestration
(:func:`develop`) here. Every public name, and every name these modules took from here, is
importable from here.

Public names
------------
DevelopmentTargets   the targets (the ``[development]`` table of a basic file)
targets_from_table   the targets from that table (file units), validated
VARIABLES            the developed synthesis inputs and their default bounds
SIZE_SCALED_VARIABLES, scaled_variables   those whose µm bounds follow the tooth size
RELIEF_NAMES         those of the relief stage
HEIGHT_NAME, CROWNING_NAME   the height stage's levers (blade angle, profile crowning)
COAST_STATUS         what the coast flank's development did, in words
COARSE_LTCA          the LTCA settings inside the loop
CHECK_LTCA           the LTCA settings of the final check (ltca run's)
KeptTeeth            the shell teeth kept across a development's designs
lte_spread           the LTE spread the verdict's plausibility check reads
development_score    objective, per-target shortfalls and whether all are met
footprint_centre     the light-load pattern's centre the development judges
working_depth_centre the depth centre aimed at by default
DevelopmentEvaluation, DevelopmentResult   one design, the whole development
develop              run the development of a basic design
design_torque_of     the torque the bearing is checked at
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import math
import os
from collections.abc import Callable
from typing import Any

from contact.compliance.fe.worker_cpu import cpu_seconds

# every public name of the development's modules importable from here, but the seams tests
# replace (development_evaluate.analyse_design, development_coast_flank.coast_development):
# those are called through their modules, and patched there
from contact.optimize import development_coast_flank as coast_flank
from contact.optimize.development_basic_arg import basic_design_of
from contact.optimize.development_centre_after import checked_after_edge_peak, height_by_reliefs
from contact.optimize.development_check import (
    PATH_STEPS,
    VERIFIED_DESIGNS,
    check_steps,
    checked_best,
    checked_root_capacity,
    checked_tolerance,
    final_tolerance,
    placed_case,
    rescored,
    static_capacity,
    steps_on_each,
    tolerance_checks,  # noqa: F401  (re-exported)
    tolerant_torque,
)
from contact.optimize.development_coast import (  # noqa: F401
    CoastCapacity,
    CoastCheck,
    coast_capacity,
)
from contact.optimize.development_coast_capacity_lte import (
    coast_lte_within_capacity,
    coast_torque_that_holds,
)
from contact.optimize.development_coast_edge_peak import coast_edge_peak, holds_as_before
from contact.optimize.development_coast_flank import (  # noqa: F401
    COAST_BEARING_DESIGNS,
    COAST_REDEVELOP,
    coast_at_its_torque,
    coast_capacity_said,
    coast_flank_capacity,
    coast_rated_torque,
    coast_start,
    coast_torque_searched,
)
from contact.optimize.development_coast_light_edge import (
    coast_light_edge,
    coast_light_edge_after_peak,
    written_coast_light_edge_line,
)
from contact.optimize.development_coast_lte_torque import coast_lte_torque
from contact.optimize.development_confirm import confirmer
from contact.optimize.development_drive_at_cut import redeveloped_drive_at_cut
from contact.optimize.development_edge_peak import checked_edge_peak
from contact.optimize.development_evaluate import (  # noqa: F401
    CHECK_LTCA,
    COARSE_LTCA,
    KeptTeeth,
    StageStop,
    bearing_key,
    design_metrics,
    design_torque_of,
    evaluation_line,
    evaluator,
    flank_peak_pressure,
    grid_bounds,
    ltca_metrics,
    lte_spread,
    static_strength,
)
from contact.optimize.development_hollow_target import checked_hollow_target
from contact.optimize.development_light_edge_relief import checked_light_edge
from contact.optimize.development_lte_capacity import lte_capacity
from contact.optimize.development_pitting import checked_pitting
from contact.optimize.development_range_lte import range_lte, range_record, recorded_range
from contact.optimize.development_result import (  # noqa: F401
    COAST_STATUS,
    STATIC_MARGIN,
    TOLERANCE_KEYS,
    DevelopmentEvaluation,
    DevelopmentResult,
    metrics_text,
)
from contact.optimize.development_root import (
    at_decided_level,
    capacity_holds,
    design_torque_kept,
    given_torque_root,
)
from contact.optimize.development_shared import SharedDevelopments, kept_for, log_reused
from contact.optimize.development_stages import (  # noqa: F401
    CROWNING_STEP,
    HEIGHT_DESIGNS,
    HEIGHT_SLOPE,
    RELIEF_BEARINGS,
    ROOT_HEIGHT_RELIEF,
    SECOND_BEARING_DESIGNS,
    TE_DESIGNS,
    flank_start,
    footprint_centre_v,
    search_flank,
)
from contact.optimize.development_targets import (
    CROWNING_NAME,
    EDGE_ROW_SHORTFALL,
    FAILED,
    HEIGHT_NAME,
    METRIC_NAMES,
    RELIEF_NAMES,
    SIZE_SCALED_VARIABLES,
    STAGE_TERMS,
    TE_NAME,
    TIP_RELIEF_START,
    VARIABLES,
    DevelopmentTargets,
    development_score,
    footprint_centre,
    scaled_variables,
    targets_from_table,
    working_depth_centre,
)
from contact.optimize.development_written import with_synthesis_fe_level
from contact.optimize.development_written_drive import written_drive_check
from contact.optimize.development_written_lte import (
    WindowMissed,
    judged_where,
    redeveloped_in_window,
    window_missed,
    window_name,
    written_lte_capacity,
)
from geometry.case import Case
from geometry.core.blas import blas_threads
from geometry.core.errors import InputError, raise_if_interrupted
from geometry.core.text import plain_number
from geometry.synthesis.basic_design import (
    BasicDesign,
    flank_option_values,
    with_flank_options,
)

__all__ = ["CHECK_LTCA", "COARSE_LTCA", "COAST_STATUS", "CROWNING_NAME", "CROWNING_STEP",
           "EDGE_ROW_SHORTFALL", "FAILED", "HEIGHT_DESIGNS", "HEIGHT_NAME", "HEIGHT_SLOPE",
           "METRIC_NAMES",
           "PATH_STEPS", "RELIEF_NAMES", "SIZE_SCALED_VARIABLES", "STAGE_TERMS", "TE_DESIGNS",
           "TE_NAME", "TIP_RELIEF_START", "VARIABLES", "VERIFIED_DESIGNS",
           "DevelopmentEvaluation", "DevelopmentResult", "DevelopmentTargets", "KeptTeeth",
           "design_torque_of", "develop", "development_score", "footprint_centre",
           "lte_spread", "scaled_variables", "static_strength", "targets_from_table",
           "working_depth_centre"]

log = logging.getLogger(__name__)


def _wrapped(basic: BasicDesign, apply_remedy: bool, **kw: Any) -> DevelopmentResult:
    """:func:`develop` with ``apply_remedy`` (the design as given, its remedies checked,
    the best applied: :func:`contact.optimize.development_remedy.developed_with_remedy`)
    or ``gear_fallback`` (the generated gear too where the Formate gear's design fails or
    misses its drive pattern:
    :func:`contact.optimize.development_process.with_generated_gear`)."""
    if apply_remedy:
        from contact.optimize.development_remedy import developed_with_remedy

        return developed_with_remedy(functools.partial(develop, **kw), basic,
                                     kw.get("progress"))
    from contact.optimize.development_process import with_generated_gear

    kw.pop("outclassed_below", None)
    # a basic design developed twice (the Formate gear in full after a foreseen cut's
    # stop) reads its syntheses, teeth and analyses back (development_shared)
    kw["shared"] = kw.get("shared") or SharedDevelopments()
    return with_generated_gear(functools.partial(develop, **{**kw, "gear_fallback": False}),
                               basic, kw.get("progress"))


@blas_threads()  # small dense matrices: one BLAS thread (geometry.core.blas)
def develop(basic: BasicDesign | str | os.PathLike[str], *,
            targets: DevelopmentTargets | None = None,
            progress: Callable[[str], None] | None = None,
            synthesis_progress: Any = None, root_stress: bool = True,
            gear_fallback: bool = True, outclassed_below: float = math.nan,
            foresee_cut: bool = False, apply_remedy: bool = False,
            torque_name: str = "",
            shared: SharedDevelopments | None = None,
            stop_over_lte: bool = False, raise_to: float = math.nan) -> DevelopmentResult:
    """Develop the drive flank, then the coast flank, of a basic design to the bearing of
    ``targets``.

    Parameters
    ----------
    basic : BasicDesign, str or path-like
        The design, or its basic design file's path (read as ``ltca synthesize FILE``
        reads it; :func:`~contact.optimize.development_basic_arg.basic_design_of`). The
        design (its drive flank's ``[synthesis]`` prescriptions are the start where a
        variable's bound allows, else the middle of the bound). Its root stress is checked
        on its ``[root_stress] fe_level``, else on the level ``ltca synthesize`` uses
        (:func:`~contact.optimize.development_written.with_synthesis_fe_level`).
    targets : DevelopmentTargets, optional
        Default: the basic file's ``[development]`` table (:func:`targets_from_table`), its
        µm amounts following the design's size (``size_scale``,
        :meth:`geometry.synthesis.basic_design.BasicDesign.size_scale`).
    progress : callable, optional
        Called with one plain line per analysed design (the CLI prints them). Default:
        the lines go to this module's logger at INFO (``logging.basicConfig(level=
        logging.INFO)`` shows them; ``progress=print`` prints them), not dropped: a
        development runs 30-120 s of CPU (issue 71, round 26d).
    synthesis_progress : optional
        The ``progress`` of the final synthesis of the developed design
        (:func:`geometry.synthesis.case_synthesis.synthesize`).
    root_stress : bool, optional
        Check the written case's FE root stress at the design torque and lower the design
        torque to its root-stress capacity where S_F,FE < S_Fmin
        (:func:`contact.optimize.development_root.root_capacity`; default True: one FE
        model build, ``ltca run``'s own, which it then reads from the cache).
    gear_fallback : bool, optional
        Default True: where ``gear_process = "auto"`` synthesised a Formate gear that it
        could have generated (face milled, δ2 < 63°) and the developed design fails (a
        FAIL criterion of ``ltca run``'s verdict, or the design torque cut below half the
        rated one) or misses a drive pattern target (its length, centre or clearance:
        :data:`~contact.optimize.development_process.PATTERN_TARGETS`), the pair is
        developed with a generated gear too and the better kept
        (:func:`contact.optimize.development_process.with_generated_gear`). False: the
        one development.
    outclassed_below : float, optional — [N·m]
        Stop the development (:class:`~contact.optimize.development_process.Outclassed`)
        as soon as its design torque is lowered below this torque: the design torque is
        only lowered after that (static, root-stress and pitting capacity), so the
        outcome could not beat the design it is compared with
        (:func:`~contact.optimize.development_process.with_generated_gear`, which gives
        it). Default NaN: never.
    foresee_cut : bool, optional
        Default False. True (a pair ``gear_process = "auto"`` can generate, given by
        :func:`~contact.optimize.development_process.with_generated_gear`): a Formate
        gear's development at its rated torque stops at its static-capacity step
        (:class:`~contact.optimize.development_process.CutForeseen`) where its bearing's
        local pitting bound foresees a design torque cut below half the rated torque
        (:func:`~contact.optimize.development_process.cut_foreseen`).
    torque_name : str, optional
        What the design torque ``basic`` gives is, where it is the development's own and
        not the basic file's (the drive developed again at the upper end of its LTE window:
        :func:`~contact.optimize.development_written_lte.window_name`): said in the
        progress line and the coast design torque's source in place of "[synthesis]
        design_torque". Default "": the basic file's.
    apply_remedy : bool, optional
        Default False: the basic data as given. True: develop the design as given, check
        its contact-ratio remedies at its written prescriptions as ``ltca synthesize``'s
        note does, apply the best that passed to the basic data (a gear face width b2 or
        mean spiral angle β_m where ε_vβ < 1.25, a depth factor k_d or pressure angle
        α_dD where ε_vα < 1) and return the remedied design's development, its
        ``remedy`` saying what changed
        (:func:`contact.optimize.development_remedy.developed_with_remedy`; about twice
        the CPU, three times where the first remedy's drive LTE exceeds the verdict's
        limit between the torques and the next checked remedy is developed too).
    shared : SharedDevelopments, optional
        The synthesis memo and kept teeth (with their analyses) of each basic design
        developed (:class:`~contact.optimize.development_shared.SharedDevelopments`): a
        development of a basic design developed before in it reads back what that one
        computed with the same inputs. Default: new ones (the ``gear_fallback`` wrapper
        makes one for the developments it runs: the Formate gear developed in full after a
        foreseen cut's stop repeats the stopped development's search and check). The
        drive developed again at a given design torque (its LTE window's) is handed it
        too: its memo is seeded with the first development's syntheses but their tip
        planes (:func:`~geometry.synthesis.case_synthesis.memo_at_torque`).
    stop_over_lte : bool, optional
        Default False. True (the drive developed again in its LTE window,
        :func:`~contact.optimize.development_written_lte.redeveloped_in_window`, which
        keeps it only where its LTE keeps ``ltca run``'s limit): stop after the drive
        steps where the check's LTE record over the range already exceeds the limit
        (:class:`~contact.optimize.development_written_lte.WindowMissed`,
        :func:`~contact.optimize.development_written_lte.window_missed`): no coast flank,
        FE root check or case for a result that would not be kept.
    raise_to : float, optional
        [N·m] Default NaN (a design torque the basic file gives stands). The torque the
        drive developed again in its LTE window
        (:func:`~contact.optimize.development_written_lte.redeveloped_in_window`) was
        rated at before the window cut it: the design torque raised back towards it on the
        bearing developed in the window, as after a capacity cut (:func:`_window_raised`).

    Returns
    -------
    DevelopmentResult
        The developed basic design and its synthesised case, the chosen design and every
        design analysed, the light and design torque, the chosen design's metrics at
        the mounting excursions, and what became of the coast flank (its check, its
        search's designs, the coast design written). Its
        :meth:`~contact.optimize.development_result.DevelopmentResult.written_case` is
        the case ``ltca synthesize`` writes (the design torques in its ``[rating]``).

    Raises
    ------
    InputError
        ``basic`` neither a BasicDesign nor a path (named), bad targets, or no design
        could be synthesised and analysed (the reasons);
        ``apply_remedy`` where no contact ratio is below its limit (before any work) or
        no remedy passed its check (each refusal said).
    Outclassed
        The design torque lowered below ``outclassed_below``.
    CutForeseen
        ``foresee_cut`` and the Formate bearing's local pitting bound below the share of
        the rated torque :func:`~contact.optimize.development_process.cut_foreseen` names.
    WindowMissed
        ``stop_over_lte`` and the drive design's LTE over the range above the limit after
        the drive steps.

    Notes
    -----
    Two stages on the drive flank, as a bearing is developed on the test stand
    (:data:`VARIABLES`), then the coast flank (3.):

    1. **bearing**: the path angle and ellipse length (and any other non-relief input)
       varied, each design the full synthesis
       (:func:`geometry.synthesis.case_synthesis.synthesize` with the drive flank's
       prescriptions replaced) and :data:`COARSE_LTCA` at the light and the design
       torque, scored by :func:`development_score` (stage ``"bearing"``: pattern length,
       centre, toe and heel clearance, LTE, flank pressure, LTE spread); at most 6
       designs or half the budget; the coast flank is synthesised once (the memo);
    2. **relief**: from the best bearing, the tip and root relief and their start varied,
       each design the synthesis with steps 3–6 from the memo (the relief, step 7, and
       the tip plane made again), scored on every target, until the budget
       ``max_evaluations`` is spent but :data:`SECOND_BEARING_DESIGNS`; where the best
       of them misses the LTE target, the same on the next-best bearing with those
       designs (:func:`~contact.optimize.development_stages._relief_stage`: the relief
       that keeps the edges elastic is what makes the LTE, docs/synthesis.md "The LTE
       against the relief").

    Each stage is a bounded Nelder–Mead (``scipy.optimize.minimize``, variables scaled to
    [0, 1]) that stops at the first design meeting every target of its stage. The search
    analyses the drive flank, coarsely (:data:`COARSE_LTCA`); then the best designs
    are checked in turn at :data:`CHECK_LTCA` (at most :data:`VERIFIED_DESIGNS`, until one
    meets every target) and the chosen one is scored by that check. Where the design
    torque is the rating's capacity (the default) and the chosen design's flank peak
    pressure there exceeds the static strength, the design torque is lowered to the
    bearing's static flank capacity (:func:`static_capacity`); where it is not and the
    peak exceeds the local pitting limit at that torque, a longer pattern and one centred
    lower are tried and the lowest peak that keeps the targets kept
    (:func:`~contact.optimize.development_pitting.checked_pitting`); after the final synthesis,
    where the written case's FE root stress gives S_F,FE < S_Fmin, or its LTCA peak flank
    pressure a local pitting safety at long life S_H,loc < S_Hmin, at the design torque,
    to that capacity (:func:`contact.optimize.development_root.root_capacity`;
    ``root_stress``), the drive and coast flank analysed again at the new torques; the
    check's steps then run at them and, where they write another bearing whose capacity
    holds, the torque is raised back as far as its capacity, its drive targets and its
    mounting tolerance hold (:func:`_rewritten_after_cut`); then the LTE window rule runs
    again at the torques the cut left (:func:`_lte_after_cut`) and, where no lower torque
    keeps the verdict's LTE limit with that bearing, the drive is developed again at its
    window's upper end, kept where it keeps the limit and its own capacity holds there
    (:func:`_redeveloped_after_cut`).

    3. **coast flank**
       (:func:`~contact.optimize.development_coast_flank.coast_development`): the
       chosen design's coast flank, as synthesised from its own prescriptions, analysed
       at :data:`CHECK_LTCA` at the same light and design torque and scored on the same
       targets — the coast flank carries the full torque in reverse gear; where it
       misses a target and
       ``coast_max_evaluations`` > 0, stages 1 and 2 and the check on the coast flank's
       own prescriptions with that budget (at most :data:`COAST_BEARING_DESIGNS`
       bearings), the best checked design kept where it scores better than the flank as
       synthesised. The drive flank is placed first and the coast flank against it, so the
       drive flank's chosen design does not depend on this stage; its numbers do (the
       pinion tooth's shell compliance reads both flanks): they are read again on the
       written case (:mod:`contact.optimize.development_written_drive`).

    The chosen design is synthesised once more with both flanks' prescriptions (the
    written case, the very design checked on either flank; the memo makes this its relief
    alone), and its drive flank is checked at the excursions ΔE = ±``offset_tolerance``,
    ΔP = ±``mounting_tolerance``; where its edges fail there, the torque up to which they
    hold is found and stated (:func:`~contact.optimize.development_check.tolerant_torque`),
    the design torque kept.

    Sources: the varied inputs are the prescriptions of Litvin's local synthesis at the
    mean point (Litvin & Fuentes 2004, §9.4–9.5;
    :func:`geometry.synthesis.local.local_synthesis`) and the blade's tip and root
    relief that keep the loaded pattern off the edges (Stadtfeld, *Handbook of Bevel and
    Hypoid Gears*, 1993, ch. 3; :mod:`geometry.machine.relief`); the light-load pattern
    aimed at is the satisfactory hypoid pattern of US Army TM 9-2320-273-34 §10-29, fig. 10-27
    (:class:`DevelopmentTargets`); the loop follows the development of a bearing on
    the roll tester and in Gleason CAGE or Klingelnberg KIMoS (docs/synthesis.md,
    "Development bearing"). The search is the Nelder–Mead simplex (Nelder & Mead 1965,
    *Computer Journal* 7, 308–313), as in :func:`scipy.optimize.minimize`.
    """
    from geometry.machine.relief import ReliefError
    from geometry.synthesis.case_synthesis import synthesize, tried_text

    # the FE level of the root-stress checks ``ltca synthesize`` uses where the basic
    # design names none, so that the API and the command develop the same design
    basic = with_synthesis_fe_level(basic_design_of(basic))
    progress = progress or log.info
    if apply_remedy or gear_fallback:
        return _wrapped(basic, apply_remedy, targets=targets, progress=progress,
                        synthesis_progress=synthesis_progress, root_stress=root_stress,
                        gear_fallback=gear_fallback, outclassed_below=outclassed_below,
                        shared=shared)
    t0 = cpu_seconds()
    basic.blank()  # blanks the basic data cannot make: its own error, before any trial
    targets = targets or targets_from_table(basic.development, size_scale=basic.size_scale())
    say = progress or (lambda line: None)
    flank = basic.options.drive_flank
    start = flank_start(basic.options.flank(flank), targets)
    evals: list[DevelopmentEvaluation] = []
    setup: dict[str, Any] = {}
    # kept across designs: steps 3-6 of each pinion flank's synthesis (the coast flank is
    # synthesised once per coast bearing; the relief stage and the final synthesis re-make
    # only the relief) and the shell tooth models (the gear's once, the pinion's once per
    # bearing design)
    # (the same objects for a development of this basic design again: development_shared)
    memo, teeth = kept_for(shared, basic)
    reused = teeth.analyses_reused

    def make(b: BasicDesign) -> Case:  # a design of the coarse search: no tip planes
        return synthesize(b, memo=memo, tip_planes=False)[0]

    # the check's `placed` (its memo keyed by it): a coarse "all met" stop confirmed at
    # the default sampling before it ends the search (development_confirm)
    placed = functools.partial(placed_case, basic, flank, memo)
    confirmed_lines: set[int] = set()  # the designs whose check line the confirmation said
    evaluate = evaluator(basic, targets, setup, teeth, say, evals, "drive",
                         targets.max_evaluations, torque_name=torque_name,
                         confirm=confirmer(targets, setup, teeth, say, placed,
                                           said_lines=confirmed_lines))
    ok = search_flank(evaluate, evals, lambda values: with_flank_options(basic, flank, values),
                      make, targets, start, basic, targets.max_evaluations)
    # the torque the search scored its designs at (a cut below it may ask the drive's
    # plastic and edge again there: development_drive_at_cut)
    searched_at = float(setup.get("torques", (math.nan, math.nan))[1])
    if not ok:
        reasons = "; ".join(sorted({e.reason for e in evals}))
        try:  # the basic data as given: its own error is the one to fix, not the bounds
            synthesize(basic, memo=memo, tip_planes=False)
        except ReliefError:
            # a default relief the blade's profile cannot make: `ltca synthesize` raises it
            # to the blade's need and develops again, as with --no-development (the 12x12
            # miter with a 5-in cutter of round 17 was told "--no-development says the
            # same", which wrote its case with the raised relief)
            raise
        except InputError as err:
            from contact.optimize.development_basic_error import levers_tried_text

            levers = levers_tried_text(err, [e.reason for e in evals],
                                       [e.values for e in evals],
                                       tapered=bool(basic.design.theta_a2
                                                    or basic.design.theta_f2))
            raise InputError(f"{err}{tried_text(err)} (the basic design as given, before "
                             "any development; ltca synthesize --no-development says the "
                             f"same{levers})") from err
        # a tooth the FE model finds too thin at the toe is the basic data's face width,
        # which no bounds change (tooth_measurement._toe_hint names it)
        change = ("change the basic data's design.b2" if "design.b2" in reasons
                  else "change [development] variables bounds")
        raise InputError(f"development: the drive flank could not be synthesised and "
                         f"analysed ({reasons}); {change}")
    # the final check at the default sampling (ltca run's): the best designs of the
    # coarse search in turn until one meets every target (the coarse LTCA's peak pressure
    # is a few % low: 2387 against 2539 MPa on the spiral bevel 13x39)
    c_check = cpu_seconds()
    others: list = []  # the checked designs not chosen: their steps may repair them
    best = checked_best(evals, targets, setup, teeth, say, placed, slopes=evaluate.slopes,
                        others=others, said_lines=confirmed_lines)
    steps = functools.partial(check_steps, targets=targets, setup=setup, teeth=teeth,
                              say=say, placed=placed, level=start[TE_NAME],
                              slopes=evaluate.slopes)
    outclassable = (math.isfinite(outclassed_below) and root_stress
                    and not basic.gives_design_torque)
    if outclassable and best.case is not None:
        # a second gear process: stopped before the check's steps where the checked
        # design's local pitting bound at the rated torque is below the first one's
        # design torque already (the bound only falls as the torque is lowered: the
        # 13x37 at Sigma 60 deg's generated gear, 59.76 N m at 279.2 N m against the
        # Formate design's 77.9 N m: ~50 s less CPU, the case written the same)
        _pitting_outclassed(best.case, setup, outclassed_below, say)
    # a Formate gear "auto" could generate: its torque cut foreseen on the checked design
    # already, before the check's steps, as after them (branch cpu89)
    _cut_foreseen_at_check(best, basic, setup, foresee_cut and root_stress, say)
    best = steps_on_each(best, others, steps)
    if not basic.gives_design_torque:
        best = _at_capacity(best, targets, setup, teeth, say, steps, placed,
                            evaluate.slopes, outclassed_below,
                            foresee_cut and root_stress)
    if outclassable and best.case is not None:
        # a second gear process: stopped before its coast flank and its FE build where
        # its local pitting capacity cannot reach the first one's design torque
        _pitting_outclassed(best.case, setup, outclassed_below, say)
    # the chosen design at the mounting excursions; its relief raised where their edges
    # take more than the design torque's share (the search stops at the first design
    # meeting every target, whose edge share may be just within it)
    best = checked_tolerance(best, targets, setup, teeth, say, placed,
                             slope=evaluate.slopes.get(bearing_key(best.values)))
    # the end of the drive development: an edge whose peak at the design torque is above
    # the flank's static strength (ltca run's edge_pressure attention) given the relief
    # that takes the load off it, kept where no met target is lost (development_edge_peak)
    # edge contact at the light torque, as ltca run reads it (p_max edge above 0): the
    # relief of the edge the light-load pattern reaches, grown until it is clear, kept
    # where no met target is lost (development_light_edge_relief)
    best = checked_light_edge(best, targets, setup, teeth, say, placed)
    # the check's steps again on the design the edge-peak step changed, and the pattern
    # still high alone lowered by both reliefs (development_centre_after)
    best = checked_after_edge_peak(
        best, checked_edge_peak(best, targets, setup, teeth, say, placed), targets, say,
        steps, functools.partial(height_by_reliefs, targets=targets, setup=setup,
                                 teeth=teeth, say=say, placed=placed))
    # the development's own LTE target alone missed: the hollow profile with the tip
    # relief deeper, on the design as it is written (after the edge-peak step's relief;
    # development_hollow_target)
    best = checked_hollow_target(best, targets, setup, teeth, say, placed)
    # the development of the same basic data at a given design torque (a torque window's;
    # its synthesis memo seeded with this one's syntheses: development_shared)
    rerun = functools.partial(_at_given_torque, basic, targets=targets, progress=progress,
                              synthesis_progress=synthesis_progress, root_stress=root_stress,
                              outclassed_below=outclassed_below, shared=shared)
    # after the last drive step that can raise its LTE: the design torque no higher than
    # where the written bearing keeps the verdict's LTE limit at every torque, else the
    # drive developed again where it could (development_written_lte)
    best, again = _at_written_lte(best, basic, targets, setup, teeth, say, outclassed_below,
                                  rerun, placed, start[TE_NAME], since=t0)
    if again is not None:
        return again
    # a re-development in the LTE window, kept only where its LTE keeps the limit: stopped
    # where that is known to fail already (development_written_lte.window_missed)
    _stop_where_missed(setup, best, stop_over_lte, say)
    developed = with_flank_options(basic, flank, best.values)
    # the coast flank, after the drive flank is chosen (which it does not change): checked
    # at the default sampling as synthesised, developed where it misses a target
    c_coast = cpu_seconds()
    # at the coast side's own design torque: the smaller of the design torque and the
    # coast side's ISO 10300 capacity (or the basic file's coast_design_torque)
    coast_iso = coast_rated_torque(best.case if best.case is not None else None, basic,
                                   setup["torques"][1])
    # (its light torque the same share of it as the drive's of the design torque: as
    # `ltca run --flank coast` analyses the case written, flank_torques)
    coast_setup = coast_flank.coast_setup(setup, min(setup["torques"][1], coast_iso))
    coast = coast_flank.coast_development(developed, best, targets, coast_setup, teeth, memo,
                                          say, make)
    coast_seconds = cpu_seconds() - c_coast
    pre_coast, developed = developed, coast.basic
    case, report = synthesize(developed, progress=synthesis_progress, memo=memo)
    root_safety, root_text, given_root_text = math.nan, "", ""
    built: list[Case] = []  # the case whose FE models were built last (_both_flanks_built)
    given = basic.gives_design_torque
    _both_flanks_built(case, root_stress and coast.best is not None, built, say, setup)
    if root_stress and not given:
        # the FE root stress and the local pitting safety of the written case at the
        # design torque (ltca run's FE model, cached: ltca run reads it), the torque
        # lowered to its capacity if below (development_root.root_capacity)
        ceiling = float(setup["torques"][1])  # the torque before a capacity cut
        best, root_safety, root_text = checked_root_capacity(case, best, targets, setup, say)
        # a second gear process cut below the first one's design torque stops here, not
        # after the steps again, a re-synthesis and its FE build (the torque is only
        # lowered from here: the miter 20x20 of benchmarks/data/unseen_designs, its
        # generated gear's development, ~10 % of the synthesize CPU)
        _outclassed(setup, outclassed_below)
        again = steps(best) if root_text else best
        if again is not best:  # a better drive flank at the lowered torques: written,
            # and its root stress checked again at them (lowered further if below)
            best, developed, case, report, root_text, root_safety = _rewritten_after_cut(
                again, with_flank_options(developed, flank, again.values), flank, steps,
                targets, setup, teeth, ceiling, root_text, say,
                functools.partial(synthesize, progress=synthesis_progress, memo=memo),
                functools.partial(_both_flanks_built, wanted=root_stress
                                  and coast.best is not None, built=built, say=say,
                                  setup=setup))
        _outclassed(setup, outclassed_below)
        _pitting_tried_said(setup, root_text)
        # the LTE window rule again at the cut torques (it ran before them)
        window: dict[str, Any] = {}
        best, root_text, root_safety = _lte_after_cut(case, best, targets, setup, teeth,
                                                      root_text, root_safety, say, window)
        # no lower torque keeps the limit with this bearing: the drive developed again at
        # the window's upper end, as before a cut, kept where both flanks keep the limit
        # and its own capacity holds there
        # else, where the design torque was cut well below the torque the search ran at,
        # the drive's plastic and edge asked there, the drive developed again where it
        # misses them (coast_at_its_torque on the drive: development_drive_at_cut)
        redone = _redone_after_cut(window, basic, root_text, say, rerun, best, setup,
                                   searched_at)
        if redone is not None:
            return dataclasses.replace(redone, seconds=cpu_seconds() - t0)
    else:
        # a design torque the basic file gives stands as given, but its root stress is
        # checked as ltca run judges it (on the default FE model where the coarse level
        # fails: the case written names it) and a failure said (development_root)
        root_safety, given_root_text = _given_root(case, setup, say, root_stress)
        # where the root binds at the given torque: the drive bearing of the highest
        # root safety that loses no met target (development_given_root)
        best, developed, case, report, root_safety, given_root_text = _given_root_bearing(
            (best, developed, case, report), targets, setup, teeth, say, placed,
            functools.partial(synthesize, progress=synthesis_progress, memo=memo),
            functools.partial(_both_flanks_built, wanted=root_stress
                              and coast.best is not None, built=built, say=say,
                              setup=setup),
            root_safety, given_root_text, flank, root_stress,
            evaluate.slopes.get(bearing_key(best.values)),
            lambda radius: functools.partial(placed_case, _with_edge_radius(basic, radius),
                                             flank, memo))
        # a larger fillet kept: the coast flank's steps below synthesise with it too
        pre_coast, basic = (_with_edge_radius(b, developed.options.edge_radius)
                            for b in (pre_coast, basic))
        # the drive developed again in its LTE window: raised back towards the torque it
        # was rated at where the bearing developed there carries more
        best, root_safety = _window_raised(case, best, targets, setup, teeth, raise_to,
                                           root_safety, root_stress, say)
    # the coast flank at its own design torque as `ltca run --flank coast` analyses it,
    # the coast design torque lowered to what its developed bearing carries (flank static
    # strength, no plastic segment, root stress) where that is less
    c_cap = cpu_seconds()
    coast_cap = None
    if coast.best is not None:
        start, start_name = coast_start(case, basic, setup["torques"][1])
        # searched with a design torque given too: that torque is the drive's, and a
        # coast flank that cannot carry it gets its own (coast_torque_searched)
        searched = coast_torque_searched(basic)
        coast, coast_cap = coast_flank_capacity(case, basic, coast, targets, setup, start,
                                                root_stress, searched, say, start_name)
        again = coast_at_its_torque(pre_coast, best, targets, setup, teeth, memo, say, make,
                                    coast, coast_cap, coast_setup["torques"][1])
        if again is not None:  # the coast flank developed again at its own design torque
            coast, developed = again, again.basic
            case, report = synthesize(developed, progress=synthesis_progress, memo=memo)
            _both_flanks_built(case, root_stress, built, say, setup)
            first = coast_cap
            coast, second = coast_flank_capacity(case, basic, coast, targets, setup,
                                                 first.torque, root_stress, searched,
                                                 say)
            coast_cap = first if second is None else CoastCapacity(
                second.torque, first.start, first.checks + second.checks,
                (f"{first.reason}; the coast flank developed again at "
                 f"{plain_number(first.torque)} N m"
                 if first.reason else f"the coast flank developed again at its design "
                 f"torque {plain_number(first.torque)} N m (developed at "
                 f"{plain_number(coast_setup['torques'][1])} N m before the design torque was cut)")
                + (f", then {second.reason}" if second.lowered else ", where it holds"),
                second.holds)
        else:
            # a lighter coast tip relief where the flank's peak set its design torque:
            # written and its capacity searched again, kept where that is higher
            relieved = coast_flank.coast_peak_relief(developed, best, targets, setup, teeth,
                                                     memo, say, coast, coast_cap)
            if relieved is not None:
                held = (coast, developed, case, report)
                coast, developed = relieved, relieved.basic
                case, report = synthesize(developed, progress=synthesis_progress, memo=memo)
                _both_flanks_built(case, root_stress, built, say, setup)
                coast, again_cap = coast_flank_capacity(case, basic, coast, targets, setup,
                                                        coast_cap.start, root_stress,
                                                        searched, say, start_name)
                if (again_cap is not None and again_cap.holds
                        and again_cap.torque > coast_cap.torque):
                    say(f"development: coast design torque {plain_number(coast_cap.torque)} -> "
                        f"{plain_number(again_cap.torque)} N m with the lighter tip relief")
                    coast_cap = CoastCapacity(
                        again_cap.torque, coast_cap.start, coast_cap.checks + again_cap.checks,
                        f"{again_cap.reason or 'it holds there'} (the coast tip relief "
                        f"made lighter: {plain_number(coast_cap.torque)} N m before)", True)
                else:
                    say("development: the lighter coast tip relief carries no more; the "
                        "coast design kept")
                    coast, developed, case, report = held
                    _both_flanks_built(case, root_stress, built, say, setup)
            # the coast LTE steps again where its torque was lowered after them
            level = flank_option_values(
                pre_coast.options.flank(coast_flank.coast_side(developed))).get(TE_NAME)
            lte = coast_flank.coast_lte_at_its_torques(
                developed, best, targets, setup, teeth, memo, say, coast, coast_cap,
                coast_setup["torques"][1], level)
            if lte is not None:  # written, and analysed as `ltca run --flank coast` does
                coast, developed = lte, lte.basic
                case, report = synthesize(developed, progress=synthesis_progress, memo=memo)
                _both_flanks_built(case, root_stress, built, say, setup)
                coast, _ = coast_flank_capacity(case, basic, coast, targets, setup,
                                                float(coast.torques[1]), root_stress,
                                                False, say)
        # its LTE still above the verdict's limit: a bearing whose peak may rise past the
        # local pitting bound, up to the static strength (development_coast_capacity_lte),
        # written, and the coast design torque searched again on it (the local pitting
        # safety among its criteria), kept where its LTE is within the limit there
        within = coast_lte_within_capacity(developed, best, targets, setup, teeth, memo,
                                           say, coast, coast_cap)
        if within is not None:  # written, and analysed as `ltca run --flank coast` does
            held = (coast, developed, case, report)
            coast = within[0]
            developed = coast.basic
            case, report = synthesize(developed, progress=synthesis_progress, memo=memo)
            _both_flanks_built(case, root_stress, built, say, setup)
            holds = coast_torque_that_holds(case, basic, coast, coast_cap, targets, setup,
                                            root_stress, say)
            if holds is None:  # no torque that holds with it: the design before the step
                coast, developed, case, report = held
                _both_flanks_built(case, root_stress, built, say, setup)
            else:
                coast, coast_cap = holds
        # edge contact at the coast light torque, as ltca run --flank coast reads it
        # (p_max edge above 0): the relief of the edge it loads, at most two designs
        # (development_coast_light_edge), then an edge above the static strength at the
        # coast design torque: its relief (development_coast_edge_peak); each written
        # where the coast flank holds as before (the drive's order: light edge first)
        write = functools.partial(synthesize, progress=synthesis_progress, memo=memo)
        rebuilt = functools.partial(_both_flanks_built, wanted=root_stress, built=built,
                                    say=say, setup=setup)
        coast, developed, case, report = _coast_edge_steps(
            (coast, developed, case, report), best, targets, setup, teeth, memo, say,
            coast_cap, basic, root_stress, write, rebuilt)
        # the written coast bearing's LTE still above the verdict's limit over its torques
        # after every coast step: the coast design torque no higher than where it keeps it
        # (development_coast_lte_torque; the drive's written_lte_capacity on the coast)
        coast, coast_cap = coast_lte_torque(case, basic, coast, coast_cap, best, targets,
                                            setup, teeth, root_stress, say,
                                            own_torque=bool(torque_name))
    coast_seconds += cpu_seconds() - c_cap
    # a root-limited torque decided on the default FE model: the case written names it
    # (ltca run reads the model the torque was decided with)
    case, developed = at_decided_level(case, developed, setup)
    # the drive flank as `ltca run` reads the written case: its pinion tooth now carries
    # the coast flank written, which the drive check's did not (the shell bends the whole
    # tooth; the 10x41 a 32's pinion edge 2484 -> 2551 MPa), so the record, the lines and
    # the targets met are the written case's (development_written_drive)
    best = written_drive_check(case, best, targets, setup, say)
    # the drive LTE target still missed above the load sharing's floor on a profile hollow
    # already, after the design torque was cut: the profile one step hollower at the
    # written torque, written where kept (development_hollow_further)
    further, best, case, report, developed = _hollow_further(
        (best, case, report, developed), targets, setup, teeth, say,
        cut=bool(root_text) and not given,
        write=lambda b: synthesize(b, progress=synthesis_progress, memo=memo))
    tolerance = final_tolerance(case, targets, setup, teeth, best.values)
    # not tolerant at the design torque: the torque up to which it is, stated (the design
    # torque is not cut for it)
    upto = tolerant_torque(case, targets, setup, teeth, best.values, tolerance)
    result = DevelopmentResult(developed, case, report, best, tuple(evals),
                               tuple(setup["torques"]), setup["source"], tolerance, targets,
                               cpu_seconds() - t0,
                               targets.pattern_centre_v or setup["centre_v"],
                               coast.best.metrics if coast.best is not None else None,
                               cpu_seconds() - c_check - coast_seconds,
                               setup["lowered"], coast.best, tuple(coast.evaluations),
                               coast.status, coast.before, coast_seconds,
                               setup.get("pressure_limit", math.inf), root_safety,
                               root_text, coast.torques,
                               coast_cap.torque if coast_cap is not None and coast_cap.lowered
                               else math.nan,
                               coast_capacity_said(basic, coast_cap, torque_name,
                                                   design=_raised_design(setup, raise_to)),
                               lte_reach=setup.get("lte_reach", {}).get(
                                   tuple(float(t) for t in setup["torques"])),
                               tolerant_torque=upto, lte_range=_judged(setup, best),
                               fe_level_text=design_torque_kept(setup),
                               given_root_text=given_root_text,
                               lte_torque=float(setup.get("lte_torque", math.nan)),
                               coast_lte_range=_coast_judged(setup, coast, best, teeth),
                               hollow_further=further,
                               root_ceiling=float(setup.get("root_ceiling", math.nan)),
                               memo=memo)
    log_reused(teeth, reused)
    say(result.headline())
    return result


def _given_root(case: Case, setup: dict[str, Any], say: Callable[[str], None],
                root_stress: bool) -> tuple[float, str]:
    """:func:`~contact.optimize.development_root.given_torque_root` of the written case at
    the design torque the basic file gives; (NaN, "") where ``root_stress`` is off (no FE
    model is built)."""
    if not root_stress:
        return math.nan, ""
    return given_torque_root(case, setup, say)


def _given_root_bearing(written: tuple, targets: DevelopmentTargets, setup: dict[str, Any],
                        teeth: KeptTeeth, say: Callable[[str], None],
                        placed: Callable, write: Callable[[BasicDesign], tuple],
                        built: Callable[[Case], Any], safety: float, text: str, flank: str,
                        root_stress: bool, slope: float | None,
                        edged: Callable[[float], Callable] | None = None) -> tuple:
    """The written (drive design, basic design, case, report, S_F,FE, note) with the
    larger fillet of :func:`~contact.optimize.development_given_root.checked_edge_radius`
    and the drive bearing of :func:`~contact.optimize.development_given_root.
    checked_given_root` where they keep one (written, its FE models built, its root stress
    at the given torque checked again as ``ltca run`` judges it), the note extended by
    what was tried. ``written`` itself with ``safety`` and ``text`` where the root is not
    the binding limit (``setup["given_root"]`` unset) or nothing was tried. ``edged``: the
    synthesis as written (``placed``) with another edge radius [mm] given; None: the edge
    radius is not tried."""
    from contact.optimize.development_given_root import (
        checked_edge_radius,
        checked_given_root,
        edge_radius_to_try,
        edge_text,
        tried_text,
    )
    from contact.optimize.development_root import decided_case, root_safety

    best, developed, case, report = written
    given = setup.get("given_root")
    if given is None or not root_stress:
        return (*written, safety, text)
    s0, s_min, _ = given
    torques = [float(t) for t in setup["torques"]]

    def root_with(basic: BasicDesign):
        def root_of(values):
            c = write(with_flank_options(basic, flank, values), progress=None)[0]
            s, _, member = root_safety(_root_tree_of(decided_case(c, setup), torques))
            return float(s[-1]), member
        return root_of

    # the fillet first: the largest edge radius the slots and the clearance allow, the
    # bearing as written (development_given_root.larger_edge_radius)
    start, s_start, edge, edge_kept = best, s0, None, False
    radius = (edge_radius_to_try(developed, _edge_radius_of(case)) if edged is not None
              else None)
    if radius is not None:
        widened = _with_edge_radius(developed, radius)
        say(f"development: the given design torque {plain_number(torques[1])} N m is above "
            f"the written bearing's root capacity (S_F,FE {s0:.3f} < {s_min:g}); the "
            f"largest edge radius the slots allow tried (the fillet)")
        start, s_start, edge = checked_edge_radius(
            best, s0, radius, _edge_radius_of(case), targets, setup, teeth, say,
            edged(radius), root_with(widened))
        if start is not best:
            edge_kept, developed, placed = True, widened, edged(radius)
    if edge_kept and s_start >= s_min:  # the root holds: the pattern is not its lever
        kept, s_kept, trials = start, s_start, []
    else:
        kept, s_kept, trials = checked_given_root(start, s_start, s_min, targets, setup,
                                                  teeth, say, placed, root_with(developed),
                                                  slope)
    fillet = edge_text(edge, edge_kept)
    if kept is best:
        tried = "; ".join(t for t in (fillet, tried_text(trials, s0, s_min, False)) if t)
        return (*written, safety, f"{text}; {tried}" if tried else text)
    developed = with_flank_options(developed, flank, kept.values)
    case, report = write(developed)
    built(case)
    setup.pop("given_root", None)
    safety, again = given_torque_root(case, setup, say)
    tried = "; ".join(t for t in (fillet, tried_text(trials, s_kept, s_min, kept is not start))
                      if t)
    if again:
        return kept, developed, case, report, safety, f"{again}; {tried}"
    say(f"development: {tried}; it holds the given design torque "
        f"{plain_number(torques[1])} N m")
    # the design torque's source line says it (the note on a failing root is gone)
    how = ("the blade edge radius made the largest the slots allow"
           if kept is start else "the drive pattern centred lower")
    if edge_kept and kept is not start:
        how = f"the blade edge radius made the largest the slots allow and {how[4:]}"
    setup["source"] = (f"{setup['source']}; {how} for the gear root, which binds there: "
                       f"S_F,FE {s0:.2f} -> {safety:.2f} >= S_Fmin {s_min:g}")
    if setup.get("fe_level_why"):  # the FE level's note was of the design before
        setup["fe_level_why"] = (f"{setup['fe_level_why']}, of the design before the gear "
                                 f"root's step; {how}, S_F,FE {safety:.2f} on it")
    return kept, developed, case, report, safety, ""


def _edge_radius_of(case: Case) -> float:
    """[mm] the written case's blade edge radius (the gear's drive blade: the synthesis
    gives both members one)."""
    return float(case.gear.flank("concave").blade.edge_radius)


def _with_edge_radius(basic: BasicDesign, radius: float) -> BasicDesign:
    """``basic`` with ``[synthesis] edge_radius`` = ``radius`` [mm] (``basic`` itself where
    it gives that one)."""
    if basic.options.edge_radius == radius:
        return basic
    return dataclasses.replace(basic, options=dataclasses.replace(basic.options,
                                                                  edge_radius=radius))


def _root_tree_of(case: Case, torques: list[float]):
    """:func:`contact.optimize.development_root._root_tree` (``ltca run``'s drive analysis
    with the root stress and the rating), looked up when called (tests replace it)."""
    from contact.optimize import development_root

    return development_root._root_tree(case, torques)


def _say_written_coast_light_edge(read: DevelopmentEvaluation | None, coast: Any,
                                  say: Callable[[str], None]) -> None:
    """Say the written coast flank's light-torque edge where a coast step after the
    light-edge step changed the design it read (``read``; ``coast``: the coast outcome
    written, its ``best`` checked at its two ``torques`` [N·m];
    :func:`~contact.optimize.development_coast_light_edge.written_coast_light_edge_line`).
    Raises nothing."""
    if coast is None or len(coast.torques) != 2:
        return
    line = written_coast_light_edge_line(read, coast.best, float(coast.torques[0]))
    if line:
        say(line)


def _coast_edge_steps(written: tuple, drive: DevelopmentEvaluation,
                      targets: DevelopmentTargets, setup: dict[str, Any], teeth: KeptTeeth,
                      memo: dict, say: Callable[[str], None], cap: CoastCapacity | None,
                      basic: BasicDesign, root_stress: bool,
                      write: Callable[[BasicDesign], tuple],
                      built: Callable[[Case], None]) -> tuple:
    """The written (coast outcome, basic design, case, report) after the coast edge
    steps, each through :func:`_coast_edges_relieved`: the light-edge relief
    (:func:`~contact.optimize.development_coast_light_edge.coast_light_edge`), the
    edge-peak relief (:func:`~contact.optimize.development_coast_edge_peak.
    coast_edge_peak`) and, where that kept a design, the light-edge relief again on it
    (:func:`~contact.optimize.development_coast_light_edge.coast_light_edge_after_peak`);
    then the written flank's light-torque line (:func:`_say_written_coast_light_edge`).
    Arguments as :func:`_coast_edges_relieved`'s. Raises nothing."""
    # edge contact at the coast light torque, as ltca run --flank coast reads it
    # (p_max edge above 0): the relief of the edge it loads, at most two designs
    # (development_coast_light_edge), then an edge above the static strength at the
    # coast design torque: its relief (development_coast_edge_peak); each written
    # where the coast flank holds as before (the drive's order: light edge first)
    common = (drive, targets, setup, teeth, memo, say, cap, basic, root_stress, write, built)
    written = _coast_edges_relieved(written, *common, coast_light_edge,
                                    "the coast light-edge relief")
    read = written[0].best if written[0] is not None else None
    peaked = _coast_edges_relieved(written, *common, coast_edge_peak,
                                   "the coast edges' relief")
    if peaked[0] is not written[0]:
        # the edge-peak step changed the relief the light-edge step read: where the
        # light torque now loads an edge (issue 71 counts any), the light-edge step
        # again on the flank it wrote, at most two more designs, its edges at the coast
        # design torque held (development_coast_light_edge.coast_light_edge_after_peak;
        # the 13x17 at Σ 50°'s gear toe, 1061 MPa)
        peaked = _coast_edges_relieved(peaked, *common, coast_light_edge_after_peak,
                                       "the coast light-edge relief after the edge-peak "
                                       "step")
    # the light-edge step read the design before the edge-peak step: where a later step
    # changed it, the written flank's light torque said as ltca run reads it
    _say_written_coast_light_edge(read, peaked[0], say)
    return peaked


def _coast_edges_relieved(written: tuple, drive: DevelopmentEvaluation,
                          targets: DevelopmentTargets, setup: dict[str, Any],
                          teeth: KeptTeeth, memo: dict, say: Callable[[str], None],
                          cap: CoastCapacity | None, basic: BasicDesign, root_stress: bool,
                          write: Callable[[BasicDesign], tuple], built: Callable[[Case], None],
                          relieve: Callable[..., Any] = coast_edge_peak,
                          what: str = "the coast edges' relief") -> tuple:
    """The written (coast outcome, basic design, case, report) with a coast edge relief
    ``relieve`` — :func:`~contact.optimize.development_coast_edge_peak.coast_edge_peak`
    (default) or :func:`~contact.optimize.development_coast_light_edge.coast_light_edge`,
    called as ``relieve(developed, drive, targets, setup, teeth, memo, say, coast, cap)``
    — where it keeps one: written (``write``, ``built``) and analysed as ``ltca run
    --flank coast`` does at the coast design torque (:func:`coast_flank_capacity`), kept
    where it fails no criterion the design before it held there
    (:func:`~contact.optimize.development_coast_edge_peak.holds_as_before`); else
    ``written`` (its FE models built again). ``what`` names the relief in the refusal's
    line."""
    coast, developed = written[0], written[1]
    edged = relieve(developed, drive, targets, setup, teeth, memo, say, coast, cap)
    if edged is None:
        return written
    case, report = write(edged.basic)
    built(case)
    again, after = coast_flank_capacity(case, basic, edged, targets, setup,
                                        float(edged.torques[1]), root_stress, True, say)
    if holds_as_before(after, cap):
        return again, edged.basic, case, report
    say(f"development: {what} fails a criterion of the coast design torque the design "
        "before it held; that design written")
    built(written[2])
    return written


def _rewritten_after_cut(best: DevelopmentEvaluation, developed: BasicDesign, flank: str,
                         steps: Callable[[DevelopmentEvaluation], DevelopmentEvaluation],
                         targets: DevelopmentTargets, setup: dict[str, Any],
                         teeth: KeptTeeth | None, ceiling: float, root_text: str,
                         say: Callable[[str], None],
                         synthesise: Callable[[BasicDesign], tuple[Case, Any]],
                         built: Callable[[Case], bool]
                         ) -> tuple[DevelopmentEvaluation, BasicDesign, Case, Any, str, float]:
    """The drive design the check's steps made at the torques of a capacity cut
    (``best``, its basic design ``developed``), written and its capacity checked again at
    them (:func:`~contact.optimize.development_check.checked_root_capacity`): where it
    holds, the design torque raised back towards ``ceiling`` [N·m] (:func:`_regained`);
    where it is cut a second time and that costs a target the steps had met, one more
    step (:func:`step_after_cut`), the case written again where it is better, its
    capacity checked once more where its FE model changed and, where that holds, the
    torque raised back as after the first cut.

    ``synthesise`` (basic design → (case, report)) writes a design; ``built`` (case →
    whether its FE model changed, :func:`_both_flanks_built`) builds both members' FE
    models. Returns the drive design, its basic design, the case and its synthesis report,
    the case's torque phrase and S_F,FE at the design torque (NaN where not computed).

    Why the raise after the second cut too: the bearing the step after it writes was
    developed at the second cut's torques, which were measured on the bearing before it —
    the premise of the raise after the first cut (docs/synthesis.md, "The raised design
    torque's mounting tolerance"); the raise keeps the same judgements (each capacity
    criterion at the new torque, no drive target lost, the mounting tolerance kept; where
    the step's case keeps the FE model, so that its capacity is not checked again, the
    raise's own check at the cut torque stands for it:
    :func:`~contact.optimize.development_root.regained_capacity` raises nothing where the
    cut torque fails). It is not tried where no step follows the second cut (the bearing
    is the one the cut measured, at its capacity to the cut's margin)."""
    case, report = synthesise(developed)
    built(case)
    before = best
    best, root_safety, text = checked_root_capacity(case, best, targets, setup, say)
    root_text = text or root_text
    if not text:  # the bearing developed at the cut torques may carry more
        best, root_text, root_safety = _regained(case, best, targets, setup, teeth, ceiling,
                                                 root_text, root_safety, say)
        return best, developed, case, report, root_text, root_safety
    # the second cut may cost a target the steps had met (no step follows it): one more
    # step where it did, the case written again where it is better, and its root capacity
    # taken once more only where its FE model changed
    regained = step_after_cut(before, best, steps, say)
    if regained is best:
        return best, developed, case, report, root_text, root_safety
    best, developed = regained, with_flank_options(developed, flank, regained.values)
    case, report = synthesise(developed)
    text = ""
    if built(case):
        best, root_safety, text = checked_root_capacity(case, best, targets, setup, say)
        root_text = text or root_text
    if not text:  # developed at the second cut's torques: it may carry more (where its
        # FE model was kept, the raise checks the cut torque itself before it raises)
        best, root_text, root_safety = _regained(case, best, targets, setup, teeth, ceiling,
                                                 root_text, root_safety, say)
    return best, developed, case, report, root_text, root_safety


def _lte_after_cut(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
                   setup: dict[str, Any], teeth: KeptTeeth | None, root_text: str,
                   root_safety: float, say: Callable[[str], None],
                   found: dict[str, Any] | None = None
                   ) -> tuple[DevelopmentEvaluation, str, float]:
    """The written drive design after a capacity cut judged by the LTE window rule
    (:func:`~contact.optimize.development_written_lte.written_lte_capacity`), which ran
    before the cut only: where its LTE p-p over ``ltca run``'s range at the cut torques
    exceeds the verdict's limit and a lower design torque keeps it, that torque, its root
    stress and local pitting safety read again there (:func:`checked_root_capacity`: they
    only rise as the torque falls).

    Parameters
    ----------
    case : Case
        The written case (both flanks).
    best : DevelopmentEvaluation
        The drive design at the cut torques ``setup["torques"]`` [N·m].
    targets, setup, teeth, say
        The development's; ``setup``'s ``torques``, ``source``, ``lowered`` and
        ``lte_torque`` [N·m] updated only where the torque is lowered (the rule's own
        record of a window it found no torque in goes to ``found``, not ``setup``: the
        design stays at its capacity unless :func:`_redeveloped_after_cut` keeps a
        re-development in that window).
    root_text : str
        The case's torque phrase after the cut.
    root_safety : float
        S_F,FE at the cut's design torque [1].
    found : dict, optional
        Where given, filled with the rule's own setup where it recorded a window with no
        design torque in it (its ``lte_window``: low, high [N·m], the LTE text; its
        ``torques`` the cut ones, its ``source`` the cut's phrase extended by the rule's
        finding), for :func:`_redeveloped_after_cut`; left empty otherwise. ``setup``
        itself is not changed in that case.

    Returns
    -------
    (DevelopmentEvaluation, str, float)
        The drive design, the case's torque phrase and S_F,FE at the design torque: as
        given where no cut was made (``root_text`` empty), the limit is kept at the cut
        torques or no lower torque keeps it. Where the root or pitting capacity cuts again
        below the rule's torque, the phrase (and ``setup["source"]``) names the three in
        order: the first cut's phrase, "then" the rule's, "then" the second cut's (whose
        own words name the rule as what set the torque it was cut from).

    Raises
    ------
    Nothing (a failed analysis keeps the design as it is).

    Notes
    -----
    Measured on round 31's FM spiral bevel 13×17 at Σ 50° remedied to b2 37 mm
    (docs/synthesis.md, "The 13×17's remedied design above 60 µrad"): the rule kept
    45/59 µrad at the ISO capacity 379.8 N·m; the local pitting cut to 333.4 N·m came
    after it and the bearing the steps kept there read 44/62 µrad (61.8 at 286.2 N·m
    between), written so and judged ATTENTION by ``ltca run``. Source: issue 71 ("LTE p-p
    ≤ 60 µrad at every torque").
    """
    if not root_text:  # no cut: the rule's judgement before it stands
        return best, root_text, root_safety
    torque = float(setup["torques"][1])
    trial = dict(setup)
    lowered = written_lte_capacity(best, targets, trial, teeth, say)
    new = float(trial["torques"][1])
    if not new < torque:
        if found is not None and trial.get("lte_window") is not None:
            found.update(trial)  # no torque in the window: a re-development may find one
        return best, root_text, root_safety
    source = f"{root_text}; then {trial['source']}"
    # the capacity read again at the rule's torque: its phrase, where it cuts again, names
    # the rule as what set the torque it cuts from (root_capacity quotes the source's first
    # words), and the case's phrase keeps the first cut and the rule before it
    setup.update(torques=list(trial["torques"]), source=trial["source"], lowered=True,
                 lte_torque=new)
    again, safety, text = checked_root_capacity(case, lowered, targets, setup, say)
    if text:  # cut again below the rule's torque (the LTE there not judged again)
        log.info("development: the root capacity cut again below the LTE torque: %s", text)
        source = f"{source}; then {text}"
    setup["source"] = source
    return again, source, safety


def _pitting_tried_said(setup: dict[str, Any], root_text: str) -> None:
    """A torque cut for the local pitting capacity (``root_text`` set, ``setup["source"]``
    naming pitting) says what was tried before it: ``setup["source"]`` extended by
    ``setup["pitting_tried"]`` where that is set (:func:`develop`, after the cut)."""
    if root_text and setup.get("pitting_tried") and "pitting" in setup["source"]:
        setup["source"] = f"{setup['source']}; {setup['pitting_tried']}"


def _redone_after_cut(window: dict[str, Any], basic: BasicDesign, root_text: str,
                      say: Callable[[str], None], rerun: Callable[..., DevelopmentResult],
                      best: DevelopmentEvaluation, setup: dict[str, Any],
                      searched_at: float) -> DevelopmentResult | None:
    """The drive developed again after a capacity cut: in the LTE window where the window
    rule found no torque (:func:`_redeveloped_after_cut`), else at the cut torque where it
    is below 0.9 of ``searched_at`` [N·m] (the torque the drive's search ran at) and the
    drive misses its plastic or edge target there
    (:func:`~contact.optimize.development_drive_at_cut.redeveloped_drive_at_cut`, its
    capacity checked by :func:`~contact.optimize.development_root.capacity_holds`); None
    where neither is kept."""
    return (_redeveloped_after_cut(window, basic, root_text, say, rerun)
            or redeveloped_drive_at_cut(best, setup, searched_at, say, rerun,
                                        functools.partial(capacity_holds, say=say)))


def _redeveloped_after_cut(window: dict[str, Any], basic: BasicDesign, root_text: str,
                           say: Callable[[str], None],
                           rerun: Callable[..., DevelopmentResult]
                           ) -> DevelopmentResult | None:
    """The drive developed again at the upper end of the LTE window after a capacity cut,
    where the window rule at the cut torques found no lower design torque at which the
    written bearing keeps the verdict's limit at every torque (:func:`_lte_after_cut`'s
    ``found``), as :func:`_at_written_lte` does before the cut
    (:func:`~contact.optimize.development_written_lte.redeveloped_in_window`, stopped after
    its drive steps where its LTE already breaks the limit); kept only where it keeps the
    limit, where its coast flank keeps it too at the coast torques
    (:func:`~contact.optimize.development_process.lte_over` names no flank) and where its
    own root-stress and local pitting capacity hold at its design torque
    (:func:`~contact.optimize.development_root.capacity_holds`).

    Parameters
    ----------
    window : dict
        The rule's setup where it recorded a window with no torque in it (``lte_window``:
        low, high [N·m], the LTE text; ``torques`` [N·m] the cut ones; ``source`` the cut's
        phrase extended by the rule's); empty: nothing to do.
    basic : BasicDesign
        The basic data as given (no design torque of its own).
    root_text : str
        The cut's torque phrase.
    say : callable (str) → None
        Where the lines go.
    rerun : callable (float, **kw) → DevelopmentResult
        The development of ``basic`` at a given design torque [N·m]
        (:func:`_at_given_torque` with the development's arguments).

    Returns
    -------
    DevelopmentResult or None
        The re-development, its torque source the cut's phrase "then" the window's; None
        where no window was recorded, the re-development is not kept by
        ``redeveloped_in_window``, either flank's LTE at its torques is above the limit or
        its capacity fails (or is not known) at its torque.

    Raises
    ------
    Nothing the re-development raises but an interrupt.

    Notes
    -----
    Why after a cut as before it: the cut torque is the capacity of the bearing developed
    at the rated torque, and the window rule's finding (its LTE falls from the unloaded TE
    at light load, so no lower design torque with its light torque keeps the limit) is the
    same finding that re-develops the drive before a cut; without it the design is written
    above the limit at its torque (``ltca run``'s ATTENTION). The window's upper end is
    below the cut torque (:func:`~contact.optimize.development_written_lte.
    written_lte_capacity` records it only there), so the torque is only lowered; the
    bearing developed there is another bearing, whose capacity the cut did not measure:
    checked at its torque, not kept where it fails (the cut design then stands, at its
    capacity). CPU: one more development at most (its coast flank, FE build and case not
    made where its drive steps already miss the limit) and one analysis with the root
    stress, paid only by a cut design in that case. Source: issue 71 ("LTE p-p ≤ 60 µrad
    at every torque"); branch diag93.
    """
    from contact.optimize.development_process import lte_over
    from contact.optimize.development_range_lte import verdict_lte_limit
    from contact.optimize.development_root import capacity_holds

    if window.get("lte_window") is None:
        return None
    cut = float(window["torques"][1])
    # (raised back towards the cut torque where its own bearing carries more, as before a
    # cut: _window_raised)
    again = redeveloped_in_window(
        functools.partial(rerun, torque_name=window_name(window), stop_over_lte=True,
                          raise_to=cut),
        window, basic, say)
    if again is None:
        return None
    torque = float(again.torque[1])
    over = lte_over(again)  # its coast flank too: a flank above the limit for another
    if over:  # is no remedy of the ATTENTION
        say(f"development: the bearing developed at {plain_number(torque)} N m: {over}, "
            f"above {verdict_lte_limit():g} urad, so not kept; the design torque kept at "
            f"{plain_number(cut)} N m, its capacity")
        return None
    holds, text = capacity_holds(again.case, again.torque, say)
    if not holds:
        say(f"development: the bearing developed at {plain_number(torque)} N m: {text} "
            f"there, so not kept; the design torque kept at {plain_number(cut)} N m, its "
            "capacity")
        return None
    say(f"development: the bearing developed at {plain_number(torque)} N m holds its "
        f"capacity there ({text}): kept")
    return dataclasses.replace(again, torque_source=f"{root_text}; then {again.torque_source}")


def _regained(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
              setup: dict[str, Any], teeth: KeptTeeth | None, ceiling: float,
              root_text: str, root_safety: float,
              say: Callable[[str], None]) -> tuple[DevelopmentEvaluation, str, float]:
    """The design torque raised back towards ``ceiling`` [N·m] on the bearing developed
    after a capacity cut (:func:`contact.optimize.development_root.regained_capacity`),
    kept only where the drive design re-scored at the new torques loses no target it met
    at the cut ones, and only as far as the written case keeps the mounting tolerance it
    had at the cut torque (:func:`contact.optimize.development_regain.tolerant_raise`: the
    excursions ΔE/ΔP at the raised torques, the highest torque that keeps them bisected
    where they do not; that torque's capacity and targets checked again), and only as far
    as the drive LTE keeps the verdict's limit at every torque where it keeps it at the cut
    torque (:func:`contact.optimize.development_regain_lte.lte_kept_raise`; ``setup``'s
    ``lte_torque`` then the torque it set); ``setup``'s torques and source updated where
    kept. Returns the design, the case's torque phrase and S_F,FE at the design torque."""
    from contact.optimize.development_range_lte import verdict_lte_limit
    from contact.optimize.development_regain import tolerant_raise
    from contact.optimize.development_regain_lte import lte_kept_raise

    torque = float(setup["torques"][1])
    up = _raised_to(case, best, targets, setup, ceiling, torque, say)
    if up is None:
        return best, root_text, root_safety
    raised, torques, new, safety = up
    held = tolerant_raise(case, targets, setup, teeth, best.values, new, say)
    tolerance = ""
    if not held.holds:
        why = held.why or (f"the mounting tolerance it has at {plain_number(torque)} N m holds "
                           f"up to {plain_number(held.torque)} N m only (not at "
                           f"{plain_number(held.fails)}; at {plain_number(new)} N m "
                           f"{'; '.join(held.lost)})")
        up = _lowered_raise(case, best, targets, setup, torque, new,
                            math.nan if held.why else held.torque, why,
                            " (the mounting tolerance's)", say)
        if up is None:
            return best, root_text, root_safety
        raised, torques, capacity, safety = up
        tolerance = (f" — its capacity {plain_number(new)} N m, the mounting tolerance it has at "
                     f"{plain_number(torque)} N m held up to {plain_number(held.torque)} N m (not "
                     f"at {plain_number(held.fails)}; at {plain_number(new)} N m "
                     f"{'; '.join(held.lost)})")
        new = capacity
    # the drive LTE the verdict judges, where the cut torque keeps its limit: the raise
    # ends where the written bearing keeps it at every torque (development_regain_lte)
    kept = lte_kept_raise(best, raised, targets, setup, teeth, list(torques), say)
    window = ""
    if kept.torque < new:
        up = _lowered_raise(case, best, targets, setup, torque, new, kept.torque,
                            f"it would lose the drive LTE limit it keeps ({kept.why})",
                            " (the LTE window's)", say)
        if up is None:
            return best, root_text, root_safety
        raised, torques, capacity, safety = up
        # (after the tolerance's clause, which names the capacity already)
        window = ("; " if tolerance else f" — its capacity {plain_number(new)} N m, ") + (
            f"the drive LTE within {verdict_lte_limit():g} urad at every torque up to "
            f"{plain_number(capacity)} N m only ({kept.why})")
        new = capacity
    source = (f"{setup['source']}; on the bearing developed at {plain_number(torque)} N m, "
              f"raised back to {plain_number(new)} N m (of {plain_number(ceiling)}), where every "
              f"capacity criterion holds{tolerance}{window}")
    say(f"  design torque {plain_number(torque)} -> {plain_number(new)} N m: the bearing "
        f"developed at the lowered torque carries it (S_F,FE and S_H,loc at or above their minima"
        + (f"; the mounting tolerance holds to it{tolerance}" if tolerance else
           ", the mounting tolerance kept") + window + ")")
    setup.update(torques=torques, source=source)
    # the design torque back at all of the torque the cut was made from: the result's
    # headline says the cut raised back, not "lowered" (DevelopmentResult.root_ceiling)
    setup["root_ceiling"] = float(ceiling)
    if window:  # the LTE window set it (development_process.cut_reference)
        setup["lte_torque"] = float(new)
    return raised, source, safety


def _raised_design(setup: dict[str, Any], raise_to: float) -> float | None:
    """[N·m] The drive's design torque where :func:`_window_raised` may have raised it
    above the torque the basic data give (``raise_to`` finite); None otherwise (the
    given torque names it)."""
    return float(setup["torques"][1]) if math.isfinite(raise_to) else None


#: most bisections of :func:`_window_raised` after its raise to the rated torque (each a
#: geometric mean of the highest torque raised to and the lowest refused: the last one
#: within (refused / raised)^(1/8), ≈ 15 % of a threefold range)
WINDOW_RAISE_STEPS = 3


def _window_raised(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
                   setup: dict[str, Any], teeth: KeptTeeth | None, ceiling: float,
                   root_safety: float, root_stress: bool, say: Callable[[str], None]
                   ) -> tuple[DevelopmentEvaluation, float]:
    """The drive developed again in its LTE window (at the design torque
    ``setup["torques"][1]`` [N·m]) with its design torque raised back towards ``ceiling``
    [N·m], the torque it was rated at before the window cut (:func:`develop`'s
    ``raise_to``), as after a capacity cut (:func:`_regained`: every capacity criterion
    at the raised torque, no drive target lost, the mounting tolerance and the drive LTE
    limit at every torque kept); the LTE over ``ltca run``'s range at the raised torques
    recorded (:func:`~contact.optimize.development_range_lte.recorded_range`: the window
    re-development is kept only where it keeps the limit). ``setup``'s torques and source
    updated where raised. Where the raise to ``ceiling`` is refused (a drive target it
    would lose: its light torque, a share of the design torque, rises with it) the torque
    is bisected geometrically (:data:`WINDOW_RAISE_STEPS`), each raise from the last one
    kept. Returns the drive design and S_F,FE at the design torque.

    Why: the window's upper end is where the *first* bearing kept 60 µrad; the bearing
    developed there may carry much more. Measured on an FH hypoid 10×33 at Σ 80°, offset
    30 mm (the lead's unseen design of session 32, 2026-11-29): ISO capacity 401.3 N·m,
    its first bearing 65 µrad at 145.4 N·m, developed again at 130.1 N·m and written
    there; that case at 200 / 300 / 401.3 N·m reads LTE p-p 28 / 21 / 12 µrad, flank peak
    1035 / 1157 / 1256 MPa (p_max/σ_H 0.85 at 401.3), no plastic segment."""
    torque = float(setup["torques"][1])
    if not (root_stress and math.isfinite(ceiling) and ceiling > 1.01 * torque):
        return best, root_safety
    chosen, lo, hi = best, torque, ceiling
    for k in range(WINDOW_RAISE_STEPS + 1):
        aim = hi if k == 0 else math.sqrt(lo * hi)  # the rated torque, then bisected
        if not aim > 1.01 * lo:
            break
        raised, _, safety = _regained(case, chosen, targets, setup, teeth, aim,
                                      str(setup.get("source", "")), root_safety, say)
        now = float(setup["torques"][1])
        if raised is chosen or not now > lo:  # a target lost or nothing carried: lower
            hi = aim
            continue
        chosen, root_safety, lo = raised, safety, now
        if now < 0.999 * aim:  # a capacity criterion set it: no higher torque holds
            break
    if chosen is best:
        return best, root_safety
    found = range_lte(chosen, setup, teeth)
    if found is not None:
        recorded_range(setup, chosen, found)
    return chosen, root_safety


def _lowered_raise(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
                   setup: dict[str, Any], torque: float, new: float, limit: float, why: str,
                   what: str, say: Callable[[str], None]
                   ) -> tuple[DevelopmentEvaluation, tuple, float, float] | None:
    """:func:`_regained`'s raise from ``torque`` [N·m] ended below the capacity ``new``
    [N·m] at ``limit`` [N·m] (the mounting tolerance's or the LTE window's: every capacity
    criterion holds there, S falls with T): :func:`_raised_to` that torque, or None —
    said with ``why`` — where ``limit`` is not above 1.01 × ``torque`` (NaN: refused)."""
    if not limit > 1.01 * torque:
        say(f"  design torque not raised {plain_number(torque)} -> {plain_number(new)} N m on "
            f"the bearing developed at it: {why}")
        return None
    return _raised_to(case, best, targets, setup, limit, torque, say, what)


def _raised_to(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
               setup: dict[str, Any], ceiling: float, torque: float,
               say: Callable[[str], None], what: str = ""
               ) -> tuple[DevelopmentEvaluation, tuple, float, float] | None:
    """:func:`_regained`'s raise from the design torque ``torque`` towards ``ceiling``
    [N·m] (:func:`contact.optimize.development_root.regained_capacity`), the drive design
    re-scored at it (:func:`rescored`): the design, the torques, the torque raised to
    [N·m] and its S_F,FE; None where it raises nothing or the design would lose a target
    it met (said, ``what`` after the torque: which raise)."""
    from contact.optimize.development_root import regained_capacity

    up = regained_capacity(case, setup, targets.light_load, ceiling, say)
    if up is None:
        return None
    tree, torques, new, safety = up
    raised = rescored(best, tree, case, targets, setup)
    lost = _lost_at(best, raised)
    if lost:
        say(f"  design torque not raised {plain_number(torque)} -> {plain_number(new)} N m{what} "
            f"on the bearing developed at it: it would miss {', '.join(lost)}")
        return None
    return raised, torques, new, safety


def _lost_at(best: DevelopmentEvaluation, raised: DevelopmentEvaluation) -> list[str]:
    """The drive targets ``raised`` (re-scored at a raised torque) misses that ``best``
    met, sorted."""
    return sorted(k for k, v in raised.shortfalls.items()
                  if v > 0 and not (best.shortfalls or {}).get(k, 0.0) > 0)


def _judged(setup: dict[str, Any], best: DevelopmentEvaluation) -> dict[str, Any] | None:
    """The check's record of the LTE over the range (:func:`~contact.optimize.
    development_range_lte.range_record`) where it is of the drive design written (its
    prescriptions) at the development's final torques; None otherwise (a later step
    changed the design, or the torques changed after the check's steps: ``ltca
    synthesize``'s note then analyses the written case itself)."""
    found = range_record(setup)
    if found is None or found.get("values") != dict(best.values):
        return None
    return found


def _coast_judged(setup: dict[str, Any], coast: Any, drive: DevelopmentEvaluation,
                  teeth: KeptTeeth) -> dict[str, Any] | None:
    """The written coast design's LTE over ``ltca run --flank coast``'s ``lte_range``
    torques (:func:`~contact.optimize.development_range_lte.range_lte` on the coast flank
    at its own torques, the analyses the coast steps made reused), as the drive's record
    (:func:`~contact.optimize.development_range_lte.range_record`'s keys); None where the
    coast flank was not checked at two torques or the analysis failed (logged)."""
    from contact.optimize.development_range_lte import range_peak

    e = coast.best if coast is not None else None
    if e is None or len(coast.torques) != 2:
        return None
    at = dict(setup, torques=[float(t) for t in coast.torques])
    found = range_lte(e, at, teeth, flank="coast",
                      key_prefix=(*bearing_key(drive.values), "coast"))
    if found is None:
        return None
    peak, torque = range_peak(found)
    return {"torques": found[0], "lte": found[1], "peak": peak, "at": torque,
            "values": dict(e.values)}


def _outclassed(setup: dict[str, Any], below: float) -> None:
    """Raise :class:`~contact.optimize.development_process.Outclassed` where the
    development's design torque (``setup["torques"][1]`` [N·m]) was lowered below
    ``below`` [N·m] (NaN: never), but where the drive LTE window lowered it
    (``setup["lte_torque"]``, :func:`~contact.optimize.development_written_lte.
    written_lte_capacity`) and it is not below
    :data:`~contact.optimize.development_process.TORQUE_CUT_FRACTION` of that: such a cut
    is the contact ratio's, no failed outcome, and may rank above the design compared
    with (:func:`~contact.optimize.development_process.failed_outcome`; the half judged
    by :func:`~contact.optimize.development_process.cut_below`, as that does)."""
    from contact.optimize.development_process import Outclassed, cut_below

    torque = float(setup["torques"][1])
    window = float(setup.get("lte_torque", math.nan))
    # (a torque the window lowered stops only where it is cut below half of the window's
    # torque, judged as failed_outcome judges it; no rated torque here)
    if (setup["lowered"] and torque < below
            and (math.isnan(window) or cut_below(torque, math.nan, window))):
        raise Outclassed(torque)


def _pitting_outclassed(case: Case, setup: dict[str, Any], below: float,
                        say: Callable[[str], None]) -> None:
    """Raise :class:`~contact.optimize.development_process.Outclassed` where the upper
    estimate of the chosen drive design's local pitting capacity
    (:func:`contact.optimize.development_root.pitting_capacity_bound`, at the
    development's torques ``setup["torques"]``) is below ``below`` [N·m]: the root-stress
    and pitting capacity of the written case would lower the design torque below it."""
    from contact.optimize.development_process import Outclassed
    from contact.optimize.development_root import pitting_capacity_bound

    bound = pitting_capacity_bound(case, setup["torques"])
    if bound < below:
        say(f"  local pitting capacity at most {plain_number(bound)} N m (S_H,loc at "
            f"{plain_number(float(setup['torques'][1]))} N m), below {plain_number(below)} N m: "
            f"stopped")
        raise Outclassed(bound)


def _at_written_lte(best: DevelopmentEvaluation, basic: BasicDesign,
                    targets: DevelopmentTargets, setup: dict[str, Any], teeth: KeptTeeth,
                    say: Callable[[str], None], outclassed_below: float,
                    rerun: Callable[[float], DevelopmentResult],
                    placed: Callable[[Any], Case] | None = None,
                    level: float = math.nan, since: float = math.nan
                    ) -> tuple[DevelopmentEvaluation, DevelopmentResult | None]:
    """The written drive design at a design torque where it keeps the verdict's LTE limit
    at every torque (:func:`~contact.optimize.development_written_lte.written_lte_capacity`),
    else the development ``rerun`` at the upper end of the window its bearing keeps it in
    (:func:`~contact.optimize.development_written_lte.redeveloped_in_window`); a design
    torque the basic file gives is kept (``best``, None). The 14x36 at Sigma 70 deg: 84
    urad at its ISO capacity, below the FAIL level ``lte_capacity`` acts on. Where the
    rule lowered the torque, the TE parabola matched to the load there (``placed``, the
    flank's own ``level`` [µrad]; :func:`~contact.optimize.development_matched_te.
    matched_after_window`). ``since`` [s]: the ``cpu_seconds()`` at which the whole
    development began; where finite, a re-development kept carries the CPU time since
    then as its ``seconds`` (its own run's alone leaves out the first development and any
    re-development that missed: the FH 12x27 of benchmarks/data/unseen_designs said "71 s
    CPU" of a 160 s ``ltca synthesize``, branch unseen98), as after a capacity cut."""
    if basic.gives_design_torque:
        return best, None
    rated = float(setup["torques"][1])
    best = written_lte_capacity(best, targets, setup, teeth, say)
    if float(setup["torques"][1]) < rated and placed is not None:
        # the TE parabola matched to the load at the lowered torques, where the design
        # misses its LTE target there (development_matched_te.matched_after_window)
        from contact.optimize.development_matched_te import matched_after_window

        best = matched_after_window(best, targets, setup, teeth, say, placed, level)
    _outclassed(setup, outclassed_below)
    # the re-development's torque named as what it is (not the basic file's)
    # (stopped after its drive steps where its LTE already breaks the limit it is kept by;
    # raised back towards the rated torque where its bearing carries more: _window_raised)
    rerun = functools.partial(rerun, torque_name=window_name(setup), stop_over_lte=True,
                              raise_to=rated)
    # (where the bearing developed at the window's upper end breaks the limit, once more
    # at the window's geometric middle: the FM 17x23 of benchmarks/data/unseen_designs)
    again = redeveloped_in_window(rerun, setup, basic, say, middle=True)
    if again is not None and math.isfinite(since):
        # DevelopmentResult.seconds is the CPU time of the whole development
        again = dataclasses.replace(again, seconds=cpu_seconds() - since)
    return best, again


def _stop_where_missed(setup: dict[str, Any], best: DevelopmentEvaluation, stop: bool,
                       say: Callable[[str], None]) -> None:
    """Where ``stop`` (:func:`develop`'s ``stop_over_lte``), raise
    :class:`~contact.optimize.development_written_lte.WindowMissed` where the check's LTE
    record over the range of the drive design ``best`` exceeds the verdict's limit after
    the drive steps (:func:`~contact.optimize.development_written_lte.window_missed`),
    said through ``say``."""
    missed = window_missed(setup, best) if stop else None
    if missed is not None:
        where = judged_where(missed)
        say(f"  its drive LTE p-p at most {missed['peak']:.1f} urad {where} after the "
            "drive steps: stopped (a re-development in the LTE window is not kept above "
            "the limit)")
        raise WindowMissed(missed)


def _at_given_torque(basic: BasicDesign, torque: float, **kw: Any) -> DevelopmentResult:
    """:func:`develop` of ``basic`` at the design torque ``torque`` [N·m] (as a basic file
    giving it: ``[synthesis] design_torque``), the one gear process."""
    given = dataclasses.replace(basic, options=dataclasses.replace(basic.options,
                                                                   design_torque=torque))
    return develop(given, gear_fallback=False, **kw)


def _at_capacity(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: dict[str, Any], teeth: KeptTeeth, say: Callable[[str], None],
                 steps: Callable[[DevelopmentEvaluation], DevelopmentEvaluation],
                 placed: Callable[..., Any], slopes: dict, outclassed_below: float,
                 foresee_cut: bool) -> DevelopmentEvaluation:
    """The checked drive design at the rated torque's capacities (:func:`develop`): the
    design torque lowered to the flank's static and LTE capacity and the steps again there,
    else the peak brought within the local pitting limit; a second gear process stopped
    below ``outclassed_below`` [N·m] (:func:`_outclassed`), a Formate gear's development
    where ``foresee_cut`` foresees its torque cut (:func:`_cut_foreseen`)."""
    # a Formate gear "auto" could generate: its design torque cut foreseen from the
    # bearing's local pitting bound at its static capacity (development_process)
    foresee = foresee_cut and _formate(best.case)
    rated = _rated(setup)
    best = static_capacity(best, targets, setup, teeth, say)
    if foresee:  # the static capacity itself below half the rated torque (branch cpu95)
        _static_cut_foreseen(setup, rated, say)
    # where the chosen design's LTE still FAILs ltca run's verdict (no design checked
    # passed it: the 16x16 at Sigma 60 deg, 122 urad at its ISO capacity), the torque
    # up to which its bearing keeps the verdict's limit (development_lte_capacity)
    best = lte_capacity(best, targets, setup, teeth, say)
    _outclassed(setup, outclassed_below)
    if setup["lowered"]:  # the steps again at the torques the bearing carries
        if foresee:
            _cut_foreseen(best.case, setup, rated, say)
        return steps(best)
    # at the ISO capacity: its peak within the local pitting limit where a longer pattern
    # or one centred lower does it (the pitting capacity of the written case would else
    # cut the design torque, development_root)
    best = checked_pitting(best, targets, setup, teeth, say, placed,
                           slope=slopes.get(bearing_key(best.values)))
    if foresee:
        _cut_foreseen(best.case, setup, rated, say)
    return best


def _formate(case: Case | None) -> bool:
    """Whether ``case``'s gear is cut Formate (no case: False)."""
    return case is not None and getattr(case.gear, "process", None) == "Formate"


def _rated(setup: dict[str, Any]) -> float:
    """The rated torque [N·m] a foreseen cut is judged against: the development's design
    torque ``setup["torques"][1]`` while it is the one it started at, NaN once lowered
    (:func:`_cut_foreseen`: no test then)."""
    return float(setup["torques"][1]) if not setup["lowered"] else math.nan


def _cut_foreseen_at_check(best: DevelopmentEvaluation, basic: BasicDesign,
                           setup: dict[str, Any], foresee: bool,
                           say: Callable[[str], None]) -> None:
    """:func:`_cut_foreseen` on the checked drive design before the check's steps (stage
    :data:`~contact.optimize.development_process.AT_CHECK`) where ``foresee`` (a pair
    ``gear_process = "auto"`` can generate, root stress checked), the basic file gives no
    design torque and the gear is Formate; the same test as at the static-capacity step
    after the steps, at the rated torque ``setup["torques"][1]`` [N·m] (NaN where already
    lowered: no test).

    The test here asks the bound below :data:`~contact.optimize.development_process.
    AT_CHECK_MARGIN` (0.55) of that stop: the steps may raise the bound.

    Why: the check's steps are most of a stopped Formate development's CPU (the FM spiral
    bevel 14x36 at Σ 70°'s A on base91: about 60 % of its synthesize). Measured (branches
    cpu89 and cpu91, docs/performance.md "The 14×36 at Σ 70°'s Formate development stopped
    at its check"): the bound before the steps / at the stop after them, N·m, against the
    stop: 17x23 427.1 / 427.1 (652.1: 0.65, not stopped here with the margin); 13x41 at Σ
    62° 51.0 / 89.0 (97.9: 0.52, stopped here); 14x36 at Σ 70° 76.0 / 104.2 (162.8: 0.47,
    stopped here; base91 74.5 / 125.5); 9x31 191.4 / 120.4 (174.2; base91 95.0 / 82.85:
    0.546, stopped here, the same case but the text); 13x39 at Σ 80° (a kept Formate design)
    204.7 / 204.2 (202.0); the 19x26 at Σ 80° 485.2 / inf (581.4: 0.83, not stopped here;
    main does not stop it: its LTE capacity lowers the torque to 282.9, where S_H,loc
    holds). Source: issue 71.
    """
    from contact.optimize.development_process import AT_CHECK, AT_CHECK_MARGIN

    if foresee and not basic.gives_design_torque and _formate(best.case):
        _cut_foreseen(best.case, setup, _rated(setup), say, stage=AT_CHECK,
                      margin=AT_CHECK_MARGIN)


def _static_cut_foreseen(setup: dict[str, Any], rated: float,
                         say: Callable[[str], None]) -> None:
    """Raise :class:`~contact.optimize.development_process.CutForeseen` (bound
    ``"static"``, stage :data:`~contact.optimize.development_process.AT_STATIC`) where the
    static-capacity step lowered the design torque ``setup["torques"][1]`` [N·m] below
    half the rated ``rated`` [N·m]
    (:func:`~contact.optimize.development_process.static_cut_foreseen`): the design torque
    the development would end at is at most that, a cut, so neither the steps at the
    lowered torque, the coast flank, the synthesis nor the FE build are run for it (the FM
    miter 18x18's Formate gear, static capacity 130 of 636.1 N m: about half its
    synthesize CPU, docs/performance.md). No analysis is made (the local pitting bound
    :func:`_cut_foreseen` takes after it needs one, and lost contact on that miter)."""
    from contact.optimize.development_process import (
        AT_STATIC,
        CutForeseen,
        static_cut_foreseen,
    )

    torque = float(setup["torques"][1])
    if setup.get("lowered") and static_cut_foreseen(torque, rated):
        say(f"  the flank's static capacity {plain_number(torque)} N m is below half the rated "
            f"{plain_number(rated)} N m (the design torque is only lowered from here): a design "
            "torque cut foreseen, stopped at its static capacity")
        raise CutForeseen(torque, rated, AT_STATIC, bound="static")


def _cut_foreseen(case: Case | None, setup: dict[str, Any], rated: float,
                  say: Callable[[str], None], stage: str = "", margin: float = 1.0) -> None:
    """Raise :class:`~contact.optimize.development_process.CutForeseen` where the upper
    estimate of the chosen drive design's local pitting capacity
    (:func:`contact.optimize.development_root.pitting_capacity_bound`, one analysis at
    the development's torques ``setup["torques"]`` [N·m], no FE; its exponent measured
    between those two torques, branch cut85) foresees its design torque cut below half of
    ``rated`` [N·m] (:func:`contact.optimize.development_process.cut_foreseen`); the bound
    logged either way (issue 71/75: the spiral bevel 14x36 at Σ 70°'s Formate gear,
    docs/synthesis.md; the 13x41 at Σ 62°'s, docs/own_gear_set.md). ``stage``: where it
    stops (:attr:`~contact.optimize.development_process.CutForeseen.stage`; default ""
    the static-capacity step's); ``margin``: the share of the stop asked (default 1,
    :func:`~contact.optimize.development_process.cut_foreseen`)."""
    from contact.optimize.development_process import CutForeseen, cut_foreseen
    from contact.optimize.development_root import pitting_capacity_bound

    if case is None:
        return
    torque = float(setup["torques"][1])
    bound = pitting_capacity_bound(case, setup["torques"], measured=True)
    log.info("development: Formate local pitting bound %.1f N m at %.1f N m (rated %.1f N m)",
             bound, torque, rated)
    if cut_foreseen(bound, rated, margin):
        say(f"  local pitting capacity about {plain_number(bound)} N m (S_H,loc at "
            f"{plain_number(torque)} N m and its exponent measured), below half the rated "
            f"{plain_number(rated)} N m with the margin: a design torque cut foreseen, stopped"
            + (f" at {stage}" if stage else ""))
        raise CutForeseen(bound, rated, *((stage,) if stage else ()))


def _hollow_further(written: tuple, targets: DevelopmentTargets, setup: dict[str, Any],
                    teeth: KeptTeeth | None, say: Callable[[str], None], *, cut: bool,
                    write: Callable[[BasicDesign], tuple[Case, Any]]) -> tuple:
    """:func:`~contact.optimize.development_hollow_further.checked_hollow_further` on the
    written design ``written`` = (drive design read on the case, case, report, basic
    design): the load-sharing floor analysed on the case only where the rest of the gate
    holds, each design written with ``write`` (basic design → (case, report)) from the
    basic design with its drive prescriptions. Returns its
    :class:`~contact.optimize.development_hollow_further.Further` followed by
    ``written`` as it is after the step (the kept design's where one was kept)."""
    best, case, report, developed = written
    from contact.optimize.development_hollow_further import checked_hollow_further
    from contact.optimize.development_lte_floor import floor_or_nan

    flank = developed.options.drive_flank

    def floor() -> float:
        return floor_or_nan(case, *(float(t) for t in setup["torques"]))

    try:
        scale = float(developed.size_scale())
    except (ValueError, ArithmeticError):
        scale = math.nan
    further = checked_hollow_further(
        best, targets, setup, teeth, say, cut=cut, scale=scale, floor=floor,
        write=lambda values: write(with_flank_options(developed, flank, values)))
    if further.case is None:
        return further, best, case, report, developed
    return (further, further.best, further.case, further.report,
            with_flank_options(developed, flank, further.values))


def step_after_cut(before: DevelopmentEvaluation, cut: DevelopmentEvaluation,
                   steps: Callable[[DevelopmentEvaluation], DevelopmentEvaluation],
                   say: Callable[[str], None]) -> DevelopmentEvaluation:
    """The drive design after a second root-capacity cut (the check's steps ran at the
    first cut's torques; :func:`develop`): where ``cut`` (``before`` analysed at the lowered
    torques, :func:`~contact.optimize.development_check.checked_root_capacity`) misses a
    target ``before`` met at its check, the check's steps ``steps``
    (:func:`~contact.optimize.development_check.check_steps`) once more at the lowered
    torques. Each step runs only where its target is missed, so a design that lost only its
    light-load centre v takes the tip and root relief steps for a high pattern and, last,
    the near-miss step (:func:`~contact.optimize.development_check.checked_near_miss`: a
    small blade-angle step with the TE level lowered, at most
    :data:`~contact.optimize.development_check.NEAR_MISS_DESIGNS` designs). Returns the
    steps' design where it is better, else ``cut`` itself (also where no target was lost:
    no step runs).

    Why: the light torque follows the design torque (``light_load`` × it), and the
    light-load pattern moves as both fall. Measured on the unseen spiral bevel 13x37 at
    Σ 60° (benchmarks/data/unseen_designs, 2026-11-26): the steps met every drive target
    at 110.4 N m; the second (local pitting) cut to 89.6 N m moved the light-load centre
    v to 0.6301, just over its bound 0.6295, and the design was written missing it. There
    the near-miss step alone kept nothing: its blade-angle steps of −0.035 to −0.077°
    brought the centre v to 0.58–0.61 but raised the light-load LTE from 38 to 47–64 µrad
    (target 40), at the TE level lowered 25 → 10 µrad and at 25 alike."""
    if before.full is None or cut.full is None:
        return cut
    lost = sorted(k for k, v in cut.full[1].items()
                  if v > 0.0 and before.full[1].get(k, 1.0) == 0.0)
    if not lost:
        return cut
    say(f"  the second cut lost {', '.join(lost)}: the check's steps again at the lowered "
        "torques")
    return steps(cut)


def _both_flanks_built(case: Case, wanted: bool, built: list[Case],
                       say: Callable[[str], None],
                       setup: dict[str, Any] | None = None) -> bool:
    """Where ``wanted`` (root stress on, both flanks checked), both members' FE models of
    the case about to be checked, built once for both flanks
    (:func:`contact.optimize.development_root.both_flanks_built`): each re-synthesis after
    the first (the drive flank again at a lowered design torque, the coast flank again at
    its own) changes the pinion, whose drive and coast checks — and ``ltca run`` of the
    case written — would otherwise build its model once per flank (a first ``ltca run``
    after synthesize rebuilt the drive model for 27 s CPU on a face-hobbed 8x39). A
    member of the re-synthesis whose FE load and stress points lie within 2 % of its
    whole depth of the last built one's keeps that one's coefficients (said through
    ``say``; ``built`` holds the last case built, updated here).

    ``setup`` (the development's state): where a root check moved the development to
    another FE level (:func:`contact.optimize.development_root.refined_for_root`), the
    models built are those of that level, the ones every root check after reads
    (:func:`contact.optimize.development_root.decided_case`), each member's built as a
    check's own build would be (no earlier coefficients kept: the same numbers as before),
    and none of the case's own level, which no check reads (issue 75: the face-hobbed
    11x46's coast re-synthesis had its coarse10 models kept and written for nothing, and
    `ltca run` of its case built the default drive model again: 11 s of CPU against 5,
    docs/performance.md).

    Returns whether the case's FE model changed: True where a member's coefficients are
    neither the last built case's (the same cache key) nor kept from them, or where
    nothing was built here (not ``wanted``, or no case before: unknown)."""
    if not wanted:
        return True
    from contact.compliance.fe import cache_key
    from contact.compliance.fe.options import case_fe_options
    from contact.optimize.development_root import both_flanks_built, decided_case

    earlier = built[-1] if built else None
    checked = decided_case(case, setup) if setup is not None else case
    # the level the checks read: built there without keeping an earlier design's
    # coefficients (a check's own build), the case's own level not at all
    kept = (both_flanks_built(case, earlier, say) if checked is case
            else both_flanks_built(checked, None, say))
    built[:] = [case]
    if earlier is None:
        return True
    try:
        opt = case_fe_options(case)  # the case's FE level ([root_stress] fe_level)
        return any(m not in kept and cache_key(case.member(m), "concave", opt)
                   != cache_key(earlier.member(m), "concave", case_fe_options(earlier))
                   for m in ("pinion", "gear"))
    except Exception as exc:  # unknown: taken as changed (the root capacity taken again)
        raise_if_interrupted(exc)
        return True
