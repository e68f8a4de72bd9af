"""Whether a contact-ratio remedy ``ltca synthesize`` prints keeps the pair near conjugate,
and whether the unloaded TE of a written case, not its contact ratios, sets its LTE
(issue 71, round 15: "the printed remedy is not honest").

The note on a profile contact ratio ε_vα below 1 offers basic-file changes that each reach
it on the ISO 10300 virtual gears (:func:`contact.load_capacity.iso10300.face_contact.
profile_remedy`: a deeper tooth k_d, a smaller drive pressure angle α_dD). The virtual gears
do not see what the change does to the synthesis. On the face-hobbed hypoid 8×35 at Σ 85°
of benchmarks/data/unseen_designs (ε_vα 0.94; docs/own_gear_set.md, "Round 15") both
reach ε_vα 1.00, but at k_d 2.16 the generated pinion departs from the gear's conjugate
(the written case's unloaded TE p-p 609 µrad, its ease-off 859 µm; 137 µrad and 86 µm at
k_d 2.0; ``ltca run`` FAIL on an LTE of 600 µrad, the design torque cut to 14 %) while
α_dD 18.6° meets every criterion (unloaded TE p-p 28 µrad, ease-off 60 µm, drive LTE
11/15 µrad).

:func:`check_change` measures each change the cheapest way that tells them apart: one
synthesis of the changed basic data at the prescriptions of the written case (no tip-plane
placement, no development, no LTCA), its drive flank's ease-off (seed §4.2) and unloaded TE
over a mesh cycle (seed §2.3.2.2). :func:`refusal` refuses a change whose synthesis fails,
whose flanks are far from conjugate
(:data:`~contact.optimize.development_conjugacy.VALID_NODE_FRACTION_MIN`) or whose unloaded
TE p-p exceeds both the verdict's LTE limit and :data:`UTE_GROWTH_MAX` times the written
case's: a change of the blank that should only lengthen the path of contact has then
moved the synthesis' TE itself, which sets the LTE at light load.
:func:`checked_remedy_text` offers the changes that pass, the lowest unloaded TE first,
and says why each refused one is refused, with its numbers.

:func:`unloaded_te_pp` and :func:`ute_sets_lte` tell, for the LTE diagnosis, where the
written case's own unloaded TE is what its LTE is: its p-p above the verdict's limit and
kept by the load at the light torque (:data:`UTE_KEPT_SHARE`). :func:`unrelieved_te_pp`
tells whether that unloaded TE is the flank's generation or its profile relief: the same
synthesis with the drive flank's tip and root relief 0 (issue 71, ratio 1: the face-hobbed
16×16 at Σ 60° on its generated gear, 156 µrad written, 15 µrad without the relief;
docs/synthesis.md, "The 16×16 at Σ 60° on the generated gear: the relief, not the pinion's
modified roll").

The face contact ratio's remedies (gear face width b2, mean spiral angle β_m:
:func:`contact.load_capacity.iso10300.face_contact.overlap_changes`) are checked the same
way (issue 71, session 17): a wider face or a larger spiral angle at the same
prescriptions is a new blank whose synthesis may fail or depart from the conjugate as a
deeper tooth may; a change that takes ε_vα below 1 comes after one that does not.
:func:`remedy_record` writes the checks into the written case (:data:`RECORD_TABLE`),
and ``ltca run``'s next step offers the remedies from there (:func:`read_record`,
:func:`recorded_judge`): the same sentence, never a change the check refused.
:func:`lte_diagnosis` is the one statement both commands make of what sets the LTE.

Public names
------------
UTE_GROWTH_MAX, UTE_KEPT_SHARE, BLANK_SHARE, ChangeCheck, check_change, blank_lowers,
blank_ute_text, unloaded_te_pp, refusal,
no_better, ranked_changes, checked_remedy_text, ute_sets_lte, ute_lte_text, unrelieved_te_pp,
relief_lte_text, RECORD_TABLE,
RemedyRecord, remedy_record, read_record, recorded_judge, LteDiagnosis, RATIO_TRIAL_TEXT,
lte_diagnosis, lowest_checked, ute_lowered_text, memo_options
"""

from __future__ import annotations

import copy
import dataclasses
import logging
import math
from collections.abc import Sequence
from typing import Any, NamedTuple

from contact.compliance.fe.worker_cpu import cpu_seconds
from contact.optimize.development_conjugacy import VALID_NODE_FRACTION_MIN

__all__ = ["BLANK_SHARE", "RATIO_TRIAL_TEXT", "RECORD_TABLE", "UTE_GROWTH_MAX",
           "UTE_KEPT_SHARE", "ChangeCheck", "LteDiagnosis", "RemedyRecord", "blank_lowers",
           "blank_ute_text", "check_change",
           "checked_remedy_text", "lowest_checked", "lte_diagnosis", "memo_options", "no_better",
           "ranked_changes", "read_record", "recorded_judge", "refusal", "relief_lte_text",
           "remedy_record", "unloaded_te_pp", "unrelieved_te_pp", "ute_lowered_text",
           "ute_lte_text", "ute_sets_lte"]

log = logging.getLogger(__name__)

#: the largest ratio [1] of a remedy's unloaded TE p-p to the written case's that the
#: remedy is taken to leave the synthesis as it was (a change of the blank alone, at the
#: same prescriptions, moves the TE parabola the modified roll sets by little; the 8×35 at
#: Σ 85°: see docs/synthesis.md, "Contact-ratio remedies checked before they are offered")
UTE_GROWTH_MAX = 2.0

#: the least share [1] of its unloaded TE p-p that the LTE p-p at the light torque keeps
#: where the unloaded TE is what the LTE is (the 8×35 at k_d 2.16: 605 of 609 µrad, 0.99;
#: where the load spreads over more pairs, the light torque's LTE falls well below it)
UTE_KEPT_SHARE = 0.5


class ChangeCheck(NamedTuple):
    """One remedy as measured by :func:`check_change`."""

    change: Any  # contact.load_capacity.iso10300.face_contact.RatioChange
    ute: float  # [µrad] unloaded TE p-p of the drive flank (NaN: not measured)
    span: float  # [µm] the drive flank's ease-off over its valid nodes (NaN: not measured)
    valid: float  # [1] share of valid ease-off nodes (0: not measured)
    failed: str  # why the synthesis or its measure failed; "" where it did not
    seconds: float  # [s] the check's CPU


def unloaded_te_pp(case, flank: str = "drive") -> tuple[float, float, float]:
    """A case's unloaded TE p-p over one mesh cycle and its ease-off's extent.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str
        ``"drive"`` (default) or ``"coast"``.

    Returns
    -------
    (ute, span, valid) : (float, float, float)
        The unloaded TE peak-to-peak [µrad] (the ``/utca`` dataset's
        ``peak_to_peak_transmission_error``), the ease-off's largest value over its valid
        nodes [µm] and the share of valid nodes [1], at the case's own misalignment.

    Raises
    ------
    InputError
        No pair in contact over the cycle, or too few valid ease-off nodes (the ease-off's
        message).
    ModelUnavailableError
        A roll-angle surface that cannot be contoured.

    Notes
    -----
    Seed §4.2 (ease-off, :func:`contact.utca.easeoff.ease_off`, memoised per case) and
    §2.3.2.2 (the lower envelope of the pairs' unloaded TE,
    :func:`contact.utca.datasets.unloaded_cycle`, 30 rolls).
    """
    from contact.optimize.development_conjugacy import conjugacy_of
    from contact.utca.datasets import unloaded_cycle
    from contact.utca.easeoff import ease_off

    eo = ease_off(case, flank=flank)
    cycle = unloaded_cycle(eo)
    c = conjugacy_of(eo)
    return 1e6 * float(cycle.te_range[1] - cycle.te_range[0]), c.span, c.fraction


def check_change(basic, change) -> ChangeCheck:
    """One basic-file change synthesised and measured (:func:`unloaded_te_pp`).

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data at the written case's prescriptions (the development's
        ``basic``; the file's own without a development).
    change : contact.load_capacity.iso10300.face_contact.RatioChange
        The change of ``basic.design`` (its ``design`` fields).

    Returns
    -------
    ChangeCheck
        Its drive flank's unloaded TE p-p [µrad], ease-off span [µm] and share of valid
        nodes; ``failed`` the message where the synthesis or the measure has no solution;
        the CPU it took [s] (one synthesis without tip-plane placement: 5-15 s on the
        2-core machine, docs/synthesis.md).

    Notes
    -----
    :func:`geometry.synthesis.case_synthesis.synthesize` with ``tip_planes=False``: the
    flanks are the written ones' (the placement moves only fillets and root lines).
    """
    from geometry.core.errors import LTCAError
    from geometry.synthesis.case_synthesis import synthesize

    t0 = cpu_seconds()
    try:
        changed = dataclasses.replace(basic, design=dataclasses.replace(basic.design,
                                                                        **change.design))
        case = synthesize(changed, tip_planes=False)[0]
        ute, span, valid = unloaded_te_pp(case)
    except (LTCAError, ValueError, ArithmeticError) as exc:
        # a new blank's synthesis that fails in any way the toolkit names is a remedy
        # refused with its message, never a note that ends the command
        log.info("remedy %s not checked: %s", change.text, exc)
        return ChangeCheck(change, math.nan, math.nan, 0.0, str(exc),
                           cpu_seconds() - t0)
    return ChangeCheck(change, ute, span, valid, "", cpu_seconds() - t0)


def unrelieved_te_pp(basic, memo: dict | None = None) -> tuple[float, float]:
    """The written drive flank's unloaded TE p-p and ease-off without its profile relief.

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data at the written case's prescriptions (as :func:`check_change`'s).
    memo : dict, optional
        The synthesis memo of the development that wrote the case
        (:attr:`~contact.optimize.development_result.DevelopmentResult.memo`): the
        synthesis reads the written flanks' steps 3–6 back from it (:func:`memo_options`)
        instead of making them again. Default None: a synthesis of its own.

    Returns
    -------
    (ute, span) : (float, float)
        The unloaded TE p-p [µrad] and the ease-off's largest value over its valid nodes
        [µm] (:func:`unloaded_te_pp`) of the same synthesis with the drive flank's
        ``tip_relief`` and ``root_relief`` 0 (steps 1-6 and the blade unchanged: the relief
        of step 7 lies beyond corners away from M); (NaN, NaN) where that synthesis or its
        measure has no solution (said in the log). One synthesis without tip-plane
        placement, 5-8 s of CPU; with the development's ``memo`` the relief alone (step
        7; the FH hypoid 13x40 of benchmarks/data/unseen_designs: ≈ 2.5 s less, its two
        flanks' face-hobbing tool solves read back).

    Notes
    -----
    Why (issue 71, ratio 1; docs/synthesis.md, "The 16×16 at Σ 60° on the generated gear:
    the relief, not the pinion's modified roll"): the face-hobbed spiral bevel 16×16 at
    Σ 60° (ε_vα 1.17, ε_vβ 0.87) developed on its generated gear wrote a drive flank of
    unloaded TE p-p 156 µrad (LTE 127/224 µrad), which the LTE diagnosis laid on the
    prescriptions (the pinion's generation); the same synthesis without the relief gives
    15 µrad (tip relief alone 59, root relief alone 54): at a face contact ratio below 1
    the pairs hand the load over on the relieved ends of the flank. Source of the
    measure: seed §4.2 and §2.3.2.2 (:func:`unloaded_te_pp`).
    """
    from geometry.core.errors import LTCAError
    from geometry.synthesis.case_synthesis import synthesize

    opt = memo_options(basic, memo)
    drive = opt.drive_flank
    plain = _without_relief(opt.flank(drive))
    try:
        case = synthesize(dataclasses.replace(basic, options=dataclasses.replace(
            opt, **{drive: plain})), tip_planes=False, memo=memo)[0]
        ute, span, _ = unloaded_te_pp(case)
    except (LTCAError, ValueError, ArithmeticError) as exc:
        log.info("the drive flank's unloaded TE without its relief not measured: %s", exc)
        return math.nan, math.nan
    return ute, span


def _without_relief(flank):
    """The flank options ``flank`` with ``tip_relief`` and ``root_relief`` 0 and every
    other field the same float: not through ``dataclasses.replace``, whose validation
    converts each field to its file unit and back (``te_level`` µrad → rad moves the last
    bit: 4.4999999999999996e-05 → 4.499999999999999e-05), which the synthesis memo's keys
    would read as another prescription."""
    plain = copy.copy(flank)
    object.__setattr__(plain, "tip_relief", 0.0)
    object.__setattr__(plain, "root_relief", 0.0)
    return plain


def memo_options(basic, memo: dict | None):
    """``basic``'s synthesis options as the development that holds ``memo`` synthesised
    them, so that a synthesis of ``basic`` with ``memo`` reads that development's entries
    back.

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data at the written prescriptions (:func:`~contact.optimize.
        development_remedy.prescribed_basic`: the gear process the written case's where
        the file leaves it to ``"auto"``; the design torque as given).
    memo : dict or None
        A development's synthesis memo
        (:attr:`~contact.optimize.development_result.DevelopmentResult.memo`).

    Returns
    -------
    geometry.synthesis.basic_design.SynthesisOptions
        ``basic.options`` with the ``gear_process`` and ``design_torque`` of the memo's
        development where the memo decided the gear process for ``basic``'s design and
        options equal but for those two and the pinion flanks' prescriptions, and the
        process it decided is ``basic``'s (or ``basic``'s is ``"auto"``); else
        ``basic.options`` unchanged (a synthesis with ``memo`` then computes its own
        steps, as without it).

    Notes
    -----
    Why this is the same synthesis: :func:`geometry.synthesis.case_synthesis.synthesize`
    reads neither field but to choose the gear process, and the memo holds the process
    it chose for that development (the written case's), so the options here make the
    gear and flanks ``basic``'s own would. The memo's keys hold every other option, so
    only the written development's own entries are read back: steps 3–6 of the written
    flanks, which are the written case's (issue 71, cpu97's count on the FH hypoid 13x40:
    its contact-ratio note synthesised them again, 2 repeats, 2.5 s).
    """
    from geometry.synthesis.basic_design import FlankOptions

    opt = basic.options
    if not memo:
        return opt
    bare = dataclasses.replace(opt, concave=FlankOptions(), convex=FlankOptions())
    for key, decided in memo.items():
        if not (isinstance(key, tuple) and len(key) == 3 and key[0] == "gear process"
                and key[1] == basic.design):
            continue
        theirs = key[2]
        if (opt.gear_process in ("auto", decided[0])
                and dataclasses.replace(theirs, gear_process=opt.gear_process,
                                        design_torque=opt.design_torque) == bare):
            return dataclasses.replace(theirs, concave=opt.concave, convex=opt.convex)
    return opt


def no_better(check: ChangeCheck, reference_ute: float, lte_met: bool) -> bool:
    """Whether a checked remedy is no remedy here: the written bearing's LTE already within
    the verdict's limit and the check measuring the change's unloaded TE p-p no lower than
    the written case's, as the printed whole µrad read.

    Parameters
    ----------
    check : ChangeCheck
    reference_ute : float — [µrad]
        The written case's unloaded TE p-p (NaN: not known, never no better).
    lte_met : bool
        Whether the written design's developed LTE p-p (drive and, where checked, coast;
        light and design torque) is within the verdict's limit.

    Returns
    -------
    bool

    Notes
    -----
    Why (issue 71, round 22, docs/synthesis.md "Remedies that are no remedy"): the
    industrial hypoid 7×51 (ε_vα 0.97, LTE p-p at most 23 µrad) was offered k_d 2.07 and
    α_dD 20.5°, checked at 53 and 58 µrad against the written 52: nothing for the change to
    fix that its check measures. Where the written LTE exceeds the limit, a change that
    checks no lower is still offered, as a trial: the check is unloaded, the higher contact
    ratio's gain is under load (the 15×28 at Σ 110°: β_m 43.9° checked 173 against 90 µrad,
    developed 34/53 against the written 90/103 µrad).
    """
    return (lte_met and math.isfinite(reference_ute) and math.isfinite(check.ute)
            and round(check.ute) >= round(reference_ute))


def refusal(check: ChangeCheck, reference_ute: float, limit: float,
            lte_met: bool = False) -> str | None:
    """Why a checked remedy is not offered, or None where it passes.

    Parameters
    ----------
    check : ChangeCheck
    reference_ute : float — [µrad]
        The written case's unloaded TE p-p (NaN where not known: the limit alone).
    limit : float — [µrad]
        The verdict's LTE p-p limit (:data:`contact.study.verdicts.LTE_LIMIT`).
    lte_met : bool, optional
        Whether the written design's developed LTE p-p is within ``limit``
        (:func:`no_better`); default False (not known: never refused for it).

    Returns
    -------
    str or None
        The reason with its numbers: the synthesis has no solution; its flanks are far
        from conjugate (fewer than
        :data:`~contact.optimize.development_conjugacy.VALID_NODE_FRACTION_MIN` valid
        ease-off nodes); its unloaded TE p-p above ``limit`` and above
        :data:`UTE_GROWTH_MAX` × ``reference_ute``; no better than the written design
        (:func:`no_better`, the reason beginning "not a remedy here").
    """
    if check.failed:
        first = check.failed.split(";")[0]
        return f"its synthesis has no solution ({first})"
    if check.valid < VALID_NODE_FRACTION_MIN:
        # a share just below the bound in tenths: "50 % valid …, at least 50 %" read as met
        share = (f"{100 * check.valid:.0f}" if round(100 * check.valid)
                 < round(100 * VALID_NODE_FRACTION_MIN) else f"{100 * check.valid:.1f}")
        return (f"its synthesis is far from conjugate ({share} % valid "
                f"ease-off nodes, at least {100 * VALID_NODE_FRACTION_MIN:.0f} % on "
                "near-conjugate flanks)")
    bound = (max(limit, UTE_GROWTH_MAX * reference_ute) if math.isfinite(reference_ute)
             else limit)
    if check.ute > bound:
        times = (f", {check.ute / reference_ute:.1f} x the written case's "
                 f"{reference_ute:.0f} urad" if math.isfinite(reference_ute)
                 and reference_ute > 0.0 else "")
        span = (f", its ease-off {check.span:.0f} um" if math.isfinite(check.span) else "")
        return (f"its generated pinion departs from the gear's conjugate: unloaded TE p-p "
                f"{check.ute:.0f} urad{times}{span}, above the verdict's {limit:g} urad "
                "LTE before any load")
    if no_better(check, reference_ute, lte_met):
        return (f"not a remedy here: unloaded TE p-p {check.ute:.0f} urad, no lower than "
                f"the written case's {reference_ute:.0f}, whose LTE p-p is within {limit:g} "
                "urad")
    return None


def ranked_changes(checks: Sequence[ChangeCheck], reference_ute: float, limit: float,
                   lte_met: bool = False
                   ) -> tuple[list[ChangeCheck], list[tuple[ChangeCheck, str]]]:
    """The remedies that pass :func:`refusal`, the lowest unloaded TE p-p first (then the
    smaller ease-off), and the refused ones with their reasons, in the given order; a
    change that takes the other contact ratio below its limit (its ``other``: a larger
    spiral angle's ε_vα, the hypoid 15×31 of round 16 at β_m 46.3°: ε_vα 0.98, LTE 99 → 64
    µrad, still above 60) after every one that does not.

    Parameters
    ----------
    checks : sequence of ChangeCheck
    reference_ute, limit : float — [µrad]
        As :func:`refusal`.
    lte_met : bool, optional
        As :func:`refusal` (default False).

    Returns
    -------
    (passed, refused) : (list of ChangeCheck, list of (ChangeCheck, str))
    """
    passed, refused = [], []
    for c in checks:
        why = refusal(c, reference_ute, limit, lte_met)
        if why is None:
            passed.append(c)
        else:
            refused.append((c, why))
    passed.sort(key=lambda c: (bool(getattr(c.change, "other", "")), c.ute,
                               c.span if math.isfinite(c.span) else math.inf))
    return passed, refused


def _measured(c: ChangeCheck, reference_ute: float) -> str:
    """A passing remedy's numbers in a parenthesis, against the written case's: "lower
    than" as the printed (whole µrad) numbers read, never "25 urad (lower than the written
    case's 25)", which the 6×43 at Σ 80° of round 17 printed for two values 0.5-1 µrad
    apart."""
    span = f", ease-off {c.span:.0f} um" if math.isfinite(c.span) else ""
    lower = round(c.ute) < round(reference_ute) if math.isfinite(reference_ute) else False
    now = (f" ({'lower than' if lower else 'no lower than'} the "
           f"written case's {reference_ute:.0f})" if math.isfinite(reference_ute) else "")
    return f" (checked: unloaded TE p-p {c.ute:.0f} urad{now}{span})"


def checked_remedy_text(checks: Sequence[ChangeCheck], target: float, none: str,
                        reference_ute: float, limit: float, lte_met: bool = False,
                        targets_met: bool = False) -> str:
    """The end of the note's remedy sentence from checked remedies: those that pass, best
    first, each with its numbers, and each refused one with why.

    Parameters
    ----------
    checks : sequence of ChangeCheck
        :func:`check_change` of each change, in the order the note would print them.
    target : float — [1]
        The contact ratio the changes reach.
    none : str
        What no change is (e.g. "no depth factor up to 2.5 nor pressure angle down to
        14.5 deg"), where none is left.
    reference_ute, limit : float — [µrad]
        As :func:`refusal`.
    lte_met : bool, optional
        As :func:`refusal` (default False): a change no better than the written design
        is said in one clause, "not a remedy here: <change> (<numbers>)".
    targets_met : bool, optional
        Whether the written design meets every drive development target
        (:func:`~contact.optimize.development_remedy.every_drive_target`; default False).
        Where it does (and ``lte_met``), ``--apply-remedy`` refuses any lower design torque
        (:func:`~contact.optimize.development_remedy.targets_bought` is false: no target
        left to buy), and the sentence says so instead of "the drive targets the design
        misses" and the floor, which do not apply (issue 71, round 38: the FH hypoid 5×39,
        every drive target met at LTE p-p 3 / 11 µrad, ε_vα 0.92).

    Returns
    -------
    str
        E.g. (the 8x35 at Σ 85°, measured) "a drive pressure angle alpha_dD of 18.6 deg
        (now 22.5) (checked: unloaded TE p-p 114 urad (lower than the written case's 137),
        ease-off 79 um), or, next best, a depth factor k_d of 2.16, above the usual 2 (now
        2) (checked: unloaded TE p-p 138 urad (no lower than the written case's 137),
        ease-off 90 um), the other kept, reaches 1 (each change checked by a synthesis at
        the written case's prescriptions, 5 s of CPU; ...)"; a refused change: "; not
        <change>, which reaches 1 too: <why>" (:func:`refusal`). Where ``lte_met``, the
        changes offered are said not checked for the design torque: "…, not checked for
        the design torque: its development may lower the design torque (`ltca synthesize
        --apply-remedy` develops it and refuses it then, unless it meets the drive targets
        the design misses at 0.909 of its design torque or more)"
        (:func:`~contact.optimize.development_remedy.targets_bought`,
        :data:`~contact.optimize.development_remedy.REMEDY_TORQUE_FLOOR`).

    Notes
    -----
    Why the design torque is said, not checked (issue 71, notes97): the FM hypoid 5×48
    (LTE p-p 35/29 µrad, within the limit) was offered α_dD 16.3° (checked 70 against
    73 µrad unloaded); its development's design torque was 81.7 N·m against the design
    as given's 206.7 (the developed bearing's local pitting), so ``--apply-remedy``
    refused it (:func:`~contact.optimize.development_remedy.torque_given_up`). The cheap
    reading, the ISO 10300 capacity of the changed blank
    (:func:`contact.load_capacity.iso10300.capacity.capacity_torque`, 0.4 s), is 203.5
    N·m at 16.3° (236.5 as given; 271.2 at the other offer, k_d 2.26): an upper bound of
    the development's design torque, 2.5 × the 81.7 developed, which tells the loss only
    by 1.5 % here and not at all where the developed bearing's cut sets it.
    """
    passed, refused = ranked_changes(checks, reference_ute, limit, lte_met)
    # no better than the written design, and refused for that alone: a change whose
    # synthesis is far from conjugate (or departs from it) is refused for that, its
    # unloaded TE measured on such flanks no number to compare (issue 71, round 32: the
    # 19x33 at Sigma 78 deg's b2 34.6 mm, 49.8 % valid nodes, printed as 'checked: unloaded
    # TE p-p 80 urad, no lower than the written case's 25' while its record said far from
    # conjugate)
    idle = [c for c, why in refused if why.startswith("not a remedy here")]
    if passed:
        ways = [c.change.text + _measured(c, reference_ute) for c in passed]
        head = (ways[0] if len(ways) == 1 else
                ways[0] + ", or, next best, " + ", or ".join(ways[1:]) + ", the other kept,")
        out = f"{head} reaches {target:g}"
        if lte_met:
            # the design torque is the development's own: `--apply-remedy` refuses a
            # remedy whose development lowers it below this design's
            # (development_remedy.torque_given_up), which no synthesis here reads
            from contact.optimize.development_remedy import REMEDY_TORQUE_FLOOR

            refused_when = (": the design as given meets every drive target, so no lower "
                            "design torque buys one)" if targets_met else
                            ", unless it meets the drive targets the design misses at "
                            f"{REMEDY_TORQUE_FLOOR:.3f} of its design torque or more)")
            out += (f", {'not' if len(passed) == 1 else 'none'} checked for the design "
                    "torque: its development may lower the design torque "
                    "(`ltca synthesize --apply-remedy` develops it and refuses it then"
                    + refused_when)
    elif idle:
        out = (f"no change that reaches {target:g} checks better than the written design, "
               f"whose LTE p-p is within {limit:g} urad")
    elif len(refused) > len(idle):
        # changes within the ranges reach it, each refused below for its synthesis: "no
        # face width up to R_e2/2 …, nor a change that keeps the synthesis near conjugate,
        # reaches 1.25; not a gear face width b2 of 46.5 mm …, which reaches 1.25 too"
        # denied the change it then named (issue 71, round 40: the FM 20x31 at Sigma 70 deg)
        out = f"{none} that keeps the synthesis near conjugate reaches {target:g}"
    else:
        out = f"{none}, nor a change that keeps the synthesis near conjugate, reaches {target:g}"
    for c, why in refused:
        if c in idle:
            # one short clause: the change named, its check's number against the written
            out += (f"; not a remedy here: {c.change.text} (checked: unloaded TE p-p "
                    f"{c.ute:.0f} urad, no lower than the written case's "
                    f"{reference_ute:.0f})")
        else:
            out += f"; not {c.change.text}, which reaches {target:g} too: {why}"
    cpu = sum(c.seconds for c in checks)
    # whole seconds, but a check under 1 s in tenths: "0 s of CPU" read as none made
    cpu_text = f"{cpu:.0f}" if cpu >= 0.95 else f"{max(cpu, 0.1):.1f}"
    return (out + f" (each change checked by a synthesis at the written case's prescriptions"
            f", {cpu_text} s of CPU; docs/synthesis.md, 'Contact-ratio remedies checked "
            "before they are offered')")


def ute_sets_lte(ute: float, lte: Sequence[float], limit: float,
                 prescribed: float = math.nan) -> bool:
    """Whether a written flank's unloaded TE is what its LTE is.

    Parameters
    ----------
    ute : float — [µrad]
        The flank's unloaded TE p-p (:func:`unloaded_te_pp`).
    lte : sequence of float — [µrad]
        Its LTE p-p at (light, design) torque.
    limit : float — [µrad]
        The verdict's LTE limit.
    prescribed : float, optional — [µrad]
        The TE parabola's level the development prescribed for that flank (its
        ``te_level``); NaN (default): not known.

    Returns
    -------
    bool
        True where ``ute`` exceeds ``limit``, the light torque's LTE p-p keeps at least
        :data:`UTE_KEPT_SHARE` of it and — where ``prescribed`` is known — ``ute`` exceeds
        :data:`UTE_GROWTH_MAX` times it: no contact ratio brings the LTE within the limit
        while the unloaded TE alone exceeds it, and that TE is not the modified roll the
        development chose on purpose (the 15×28 at Σ 110°: a te_level of 128 µrad matched
        to its deflection, unloaded TE 90 µrad, where a higher face contact ratio is the
        lever — docs/synthesis.md, "The TE parabola matched to the load where the contact
        ratios are low"; the 8×35 at k_d 2.16: 609 µrad at a te_level of 10).
    """
    light = float(lte[0])
    on_purpose = math.isfinite(prescribed) and ute <= UTE_GROWTH_MAX * prescribed
    return (math.isfinite(ute) and ute > limit and math.isfinite(light)
            and light >= UTE_KEPT_SHARE * ute and not on_purpose)


def lowest_checked(checks: Sequence[ChangeCheck], reference_ute: float,
                   limit: float) -> ChangeCheck | None:
    """The checked remedy that lowers the written drive flank's unloaded TE the most.

    Parameters
    ----------
    checks : sequence of ChangeCheck
        :func:`check_change` of each contact-ratio remedy (one synthesis each at the
        written case's prescriptions).
    reference_ute : float — [µrad]
        The written drive flank's unloaded TE p-p.
    limit : float — [µrad]
        The verdict's LTE limit (:func:`refusal`).

    Returns
    -------
    ChangeCheck or None
        Of the changes that pass :func:`refusal`, the one of the lowest unloaded TE p-p,
        where that is lower than ``reference_ute`` as the printed whole µrad read; None
        where none is (or ``reference_ute`` is not finite).

    Notes
    -----
    Why (issue 71, round 21, docs/own_gear_set.md "Round 21"): the spiral bevel 21×21 at
    ε_vβ 0.64 wrote a drive flank of unloaded TE p-p 97 µrad (LTE 90/90 µrad), which
    :func:`ute_sets_lte` took for its LTE, and both commands said "a higher contact ratio
    does not lower it" — while the note's own check of b2 39.3 mm (ε_vβ 1.25), one
    synthesis at the same prescriptions, measured 51 µrad.
    """
    if not math.isfinite(reference_ute):
        return None
    passed, _ = ranked_changes(checks, reference_ute, limit)
    kept = [c for c in passed if math.isfinite(c.ute)]
    if not kept:
        return None
    low = min(kept, key=lambda c: c.ute)
    return low if round(low.ute) < round(reference_ute) else None


def ute_lowered_text(ute: float, span: float, low: ChangeCheck, limit: float) -> str:
    """The LTE diagnosis where the written drive flank's unloaded TE exceeds ``limit`` but a
    checked contact-ratio remedy takes it within (:func:`lte_diagnosis`).

    Parameters
    ----------
    ute : float — [µrad]
        The written drive flank's unloaded TE p-p.
    span : float — [µm]
        Its ease-off's extent (NaN: not said).
    low : ChangeCheck
        The remedy's check (:func:`lowest_checked`), its unloaded TE p-p within ``limit``.
    limit : float — [µrad]

    Returns
    -------
    str
        E.g. "the written drive flank's unloaded TE p-p is 97 urad (ease-off 85 um), above
        the verdict's 60 urad before any load, and the remedy b2 = 39.3 takes it to 51 urad
        at the same prescriptions (checked by a synthesis): a higher contact ratio lowers
        it; a higher contact ratio is the lever left, …" (the 21×21 of round 21), ending in
        :data:`RATIO_TRIAL_TEXT`.
    """
    return (f"{_written_ute_said(ute, span, limit)}, and {_check_takes_said(low)}): a higher "
            f"contact ratio lowers it; {RATIO_TRIAL_TEXT}")


#: [1] the least share of the written drive flank's unloaded TE p-p that a checked
#: contact-ratio remedy must remove, at the same prescriptions, for :func:`lte_diagnosis` to
#: name the blank's contact ratio as part of what sets the LTE where that remedy does not
#: take the unloaded TE within the verdict's limit (:func:`blank_lowers`). Measured (one
#: synthesis of the changed basic data each, docs/own_gear_set.md rounds 21 and 30,
#: docs/synthesis.md "Contact-ratio remedies checked before they are offered"): the spiral
#: bevel 14x21 at Σ 125° 130 -> 85 µrad with b2 (35 % removed), the 21x21 97 -> 51 (47 %),
#: against the face-hobbed 8x35 at k_d 2.16, 666 -> 609 µrad (9 %), whose unloaded TE is its
#: prescriptions'. A quarter lies between the two groups with room on each side.
BLANK_SHARE = 0.25


def blank_lowers(ute: float, check_ute: float) -> bool:
    """Whether a checked remedy removes at least :data:`BLANK_SHARE` of the written drive
    flank's unloaded TE.

    Parameters
    ----------
    ute : float — [µrad]
        The written drive flank's unloaded TE p-p.
    check_ute : float — [µrad]
        The remedy's check: the unloaded TE p-p of the changed basic data at the same
        prescriptions (:func:`check_change`).

    Returns
    -------
    bool
        ``check_ute <= (1 - BLANK_SHARE) * ute``; False where either is not finite or
        ``ute`` is not positive.
    """
    if not (math.isfinite(ute) and math.isfinite(check_ute)) or ute <= 0.0:
        return False
    return check_ute <= (1.0 - BLANK_SHARE) * ute


def blank_ute_text(ute: float, span: float, low: ChangeCheck, limit: float,
                   prescriptions: str = "") -> str:
    """The LTE diagnosis where the written drive flank's unloaded TE sets its LTE and a
    checked contact-ratio remedy removes a large share of it (:func:`blank_lowers`), not
    enough to take it within ``limit`` (:func:`lte_diagnosis`, cause ``"contact_ratios"``).

    Parameters
    ----------
    ute : float — [µrad]
        The written drive flank's unloaded TE p-p.
    span : float — [µm]
        Its ease-off's extent (NaN: not said).
    low : ChangeCheck
        The remedy's check (:func:`lowest_checked`).
    limit : float — [µrad]
        The verdict's LTE limit.
    prescriptions : str, optional
        The written drive prescriptions as said ("path_angle -58.8, ellipse_length 0.25,
        te_level 10"); empty: not named.

    Returns
    -------
    str
        E.g. "the written drive flank's unloaded TE p-p is 130 urad (ease-off 160 um), above
        the verdict's 60 urad before any load, and the remedy b2 = 39.3 takes it to 85 urad
        at the same prescriptions (checked by a synthesis: 35 % of it is the blank's
        contact ratio); the rest follows the drive prescriptions the development wrote
        (…): a higher contact ratio is the lever left, …", ending in
        :data:`RATIO_TRIAL_TEXT`.

    Notes
    -----
    Why (issue 71, round 30, docs/own_gear_set.md "Round 30"): the spiral bevel 14x21 at
    Σ 125° (ε_vβ 0.86) wrote a drive flank of unloaded TE p-p 130 µrad that its b2 remedy's
    check took to 85 µrad; both commands said "that, not the contact ratios, sets its LTE".
    """
    named = f" ({prescriptions})" if prescriptions else ""
    share = 100.0 * (1.0 - low.ute / ute)
    return (f"{_written_ute_said(ute, span, limit)}, and {_check_takes_said(low)}: "
            f"{share:.0f} % of it is the blank's contact ratio); the rest follows the drive "
            f"prescriptions the development wrote{named}: {RATIO_TRIAL_TEXT}")


def ute_lte_text(ute: float, span: float, lte: Sequence[float], limit: float,
                 prescriptions: str = "", low: ChangeCheck | None = None) -> str:
    """The LTE diagnosis where :func:`ute_sets_lte`: the written case's unloaded TE sets it.

    Parameters
    ----------
    ute : float — [µrad]
    span : float — [µm]
        The ease-off's extent (NaN: not said).
    lte : sequence of float — [µrad]
        LTE p-p at (light, design) torque.
    limit : float — [µrad]
    prescriptions : str
        The written drive prescriptions that set that TE, as said (e.g. "path_angle
        -58.8, ellipse_length 0.25, te_level 10"); empty: not named.
    low : ChangeCheck, optional
        A checked contact-ratio remedy that lowers the unloaded TE, not within ``limit``
        (:func:`lowest_checked`): said with its number instead of "a higher contact ratio
        does not lower it"; None (default): no check lowered it.

    Returns
    -------
    str
        E.g. "the written drive flank's unloaded TE p-p is 609 urad (ease-off 859 um),
        above the verdict's 60 urad before any load: that, not the contact ratios, sets
        its LTE p-p 605/599 urad (light/design) ...".

    Notes
    -----
    Measured on the 8x35 at Σ 85° and k_d 2.16 (docs/synthesis.md, 'Contact-ratio
    remedies checked before they are offered'): its written prescriptions give an
    unloaded TE p-p of 609 µrad at k_d 2.16 and 666 µrad at k_d 2.0 (the contact ratios
    not the cause), 138 µrad at the prescriptions the k_d 2.0 development wrote.
    """
    named = f" ({prescriptions})" if prescriptions else ""
    return (f"{_written_ute_said(ute, span, limit)}: that, not the contact ratios, "
            f"sets its LTE p-p {float(lte[0]):.0f}/{float(lte[-1]):.0f} urad (light/design), "
            f"{_ratio_effect(low, limit)}; the unloaded TE follows the drive "
            f"prescriptions the development wrote{named}: other [synthesis] prescriptions "
            "(a path angle or an ellipse length of a design whose LTE the development's "
            "lines show lower) are the lever (docs/synthesis.md, 'Contact-ratio remedies "
            "checked before they are offered')")


#: what the user can change where the relief sets the unloaded TE (:func:`relief_lte_text`),
#: as measured on the face-hobbed 16×16 at Σ 60° (docs/synthesis.md, "The 16×16 at Σ 60° on
#: the generated gear: the relief, not the pinion's modified roll")
RELIEF_LEVER_TEXT = ("the relief keeps the pinion's edges out of contact under load, so a "
                     "lighter one ([synthesis.<drive flank>] tip_relief, root_relief) trades "
                     "the one for the other (measured on the face-hobbed 16x16 at Sigma 60 "
                     "deg: 127/224 urad with 15/15 um, 63/270 urad with the root relief "
                     "alone, 83/299 urad and 12 % plastic without), and no modified roll "
                     "lowers it (the synthesis' 6D, 24E give the least unloaded TE there); "
                     "more teeth on the same gear size raise both contact ratios, so that "
                     "the pairs hand over inside the unrelieved flank and share the load "
                     "(measured: that 16x16 as 24x24, ")

#: the end of :data:`RELIEF_LEVER_TEXT`'s measure (docs/synthesis.md, "The 16×16 at Σ 60°
#: on the generated gear: the relief, not the pinion's modified roll")
RELIEF_MEASURED = ("face hobbed: eps_va 1.22, eps_vb 1.30, drive LTE p-p 69/67 urad at "
                   "84/560 N m without plastic, coast 106/63 urad; face milled: eps_vb 1.40, "
                   "19/32 urad at 69/460.5 N m")


def relief_lte_text(ute: float, span: float, unrelieved: float, lte: Sequence[float],
                    limit: float, relief: str = "", measured: str = "") -> str:
    """The LTE diagnosis where the written drive flank's unloaded TE sets its LTE and its
    profile relief sets that unloaded TE (:func:`lte_diagnosis`, cause ``"relief"``).

    Parameters
    ----------
    ute : float — [µrad]
        The written drive flank's unloaded TE p-p (:func:`unloaded_te_pp`).
    span : float — [µm]
        Its ease-off's extent (NaN: not said).
    unrelieved : float — [µrad]
        The same flank's unloaded TE p-p without its relief (:func:`unrelieved_te_pp`),
        within ``limit``.
    lte : sequence of float — [µrad]
        Its LTE p-p at (light, design) torque.
    limit : float — [µrad]
        The verdict's LTE limit.
    relief : str
        The written relief as said (e.g. "tip/root relief 15/15 um"); empty: not named.
    measured : str
        The end of :data:`RELIEF_LEVER_TEXT`'s parenthesis: the more-teeth design's
        measured LTE; empty: the measure of docs/synthesis.md.

    Returns
    -------
    str
        E.g. "the written drive flank's unloaded TE p-p is 156 urad (ease-off 258 um),
        above the verdict's 60 urad before any load, and 15 urad without its profile
        relief (tip/root relief 15/15 um; checked by a synthesis at the same
        prescriptions): its relief, not its generation, sets the unloaded TE its LTE p-p
        127/224 urad (light/design) keeps; the relief keeps …".
    """
    named = f"{relief}; " if relief else ""
    return (f"{_written_ute_said(ute, span, limit)}, and {unrelieved:.0f} urad "
            f"without its profile relief ({named}checked by a synthesis at the same "
            f"prescriptions): its relief, not its generation, sets the unloaded TE its "
            f"LTE p-p {float(lte[0]):.0f}/{float(lte[-1]):.0f} urad (light/design) keeps; "
            + RELIEF_LEVER_TEXT + (measured or RELIEF_MEASURED) + ")")


def _written_ute_said(ute: float, span: float, limit: float) -> str:
    """The opening of every statement of the written drive flank's unloaded TE above the
    verdict's limit: "the written drive flank's unloaded TE p-p is 97 urad (ease-off 85
    um), above the verdict's 60 urad before any load" (``ute`` [µrad], ``span`` [µm], NaN:
    not said, ``limit`` [µrad])."""
    span_said = f" (ease-off {span:.0f} um)" if math.isfinite(span) else ""
    return (f"the written drive flank's unloaded TE p-p is {ute:.0f} urad{span_said}, above "
            f"the verdict's {limit:g} urad before any load")


def _check_takes_said(low: ChangeCheck) -> str:
    """What a remedy's check measured, its parenthesis left open for the reading: "the
    remedy b2 = 39.3 takes it to 51 urad at the same prescriptions (checked by a
    synthesis"."""
    return (f"{_change_said(low)} takes it to {low.ute:.0f} urad at the same prescriptions "
            "(checked by a synthesis")


def _ratio_effect(low: ChangeCheck | None, limit: float) -> str:
    """What a higher contact ratio does to the unloaded TE, as the checks measured it."""
    if low is None:
        return "and a higher contact ratio does not lower it"
    return (f"and a higher contact ratio lowers it only to {low.ute:.0f} urad, above "
            f"{limit:g} ({_change_said(low)}, checked by a synthesis at the same "
            "prescriptions)")


def _change_said(check: ChangeCheck) -> str:
    """A checked change by its basic-file field and value ("the remedy b2 = 39.3"): the
    remedy sentence before it names it in full."""
    return f"the remedy {check.change.field} = {check.change.value:g}"


#: the written case's informational table in which ``ltca synthesize`` records the checks
#: of the contact-ratio remedies its note offers (:func:`remedy_record`); ``ltca run``
#: reads it back (:func:`recorded_judge`), so its next step offers what the note offered
#: and never a change the check refused
RECORD_TABLE = "contact_ratio_remedies"


#: the contact ratio each remedy's field raises
_RATIO_OF = {"b2": "eps_vb", "beta_m": "eps_vb", "k_d": "eps_va", "alpha_dD": "eps_va"}


class RemedyRecord(NamedTuple):
    """The checks of a written case's contact-ratio remedies as its case file records them
    (:func:`remedy_record`, :func:`read_record`)."""

    checks: tuple[ChangeCheck, ...]
    reference_ute: float  # [µrad] the written drive flank's unloaded TE p-p (NaN: not known)
    reference_span: float  # [µm] its ease-off's extent (NaN: not known)
    limit: float  # [µrad] the verdict's LTE limit the checks were judged against
    #: [µrad] the written drive flank's unloaded TE p-p without its relief
    #: (:func:`unrelieved_te_pp`; NaN: not measured)
    unrelieved_ute: float = math.nan
    #: whether the written design's developed LTE p-p is within ``limit`` (drive and
    #: coast, light and design torque; :func:`no_better`); False: above it or not known
    lte_met: bool = False


def remedy_record(record: RemedyRecord) -> dict[str, Any]:
    """A :class:`RemedyRecord` as the case's informational :data:`RECORD_TABLE` table
    (TOML-safe: a value not measured is left out, never written as NaN).

    Parameters
    ----------
    record : RemedyRecord

    Returns
    -------
    dict
        ``note``, ``limit_urad``, ``lte_met`` (the written LTE within it),
        ``unloaded_te_pp_urad`` and ``ease_off_um`` of the written drive flank where
        measured, ``unrelieved_te_pp_urad`` (without its relief) where
        measured, ``cpu_seconds``, and ``change``: one table per checked
        change (``field``, ``value``, ``text``, ``other``, its measures, ``failed``,
        ``cpu_seconds``, and ``refused``: :func:`refusal`'s reason, "" where offered).
    """
    def kept(**values: float) -> dict[str, float]:
        return {k: round(float(v), 3) for k, v in values.items() if math.isfinite(v)}

    changes = []
    for c in record.checks:
        why = refusal(c, record.reference_ute, record.limit, record.lte_met)
        changes.append({"field": c.change.field, "value": float(c.change.value),
                        "text": c.change.text, "other": getattr(c.change, "other", ""),
                        **kept(unloaded_te_pp_urad=c.ute, ease_off_um=c.span,
                               valid_share=c.valid, cpu_seconds=c.seconds),
                        "failed": c.failed, "refused": why or ""})
    return {"note": "informational (contact.optimize.remedy_check): each contact-ratio "
                    "remedy ltca synthesize's note offers, checked by one synthesis at the "
                    "written prescriptions before it is offered (refused: not offered, with "
                    "why); ltca run's next step reads it",
            "limit_urad": float(record.limit), "lte_met": bool(record.lte_met),
            **kept(unloaded_te_pp_urad=record.reference_ute,
                   ease_off_um=record.reference_span,
                   unrelieved_te_pp_urad=record.unrelieved_ute),
            "cpu_seconds": round(sum(c.seconds for c in record.checks), 1),
            "change": changes}


def read_record(extra) -> RemedyRecord | None:
    """The :class:`RemedyRecord` a case's :data:`RECORD_TABLE` table holds; None where the
    case has none (not written by ``ltca synthesize``, or no contact ratio was low) or it
    cannot be read (said in the log).

    Parameters
    ----------
    extra : mapping
        The case's other tables (``geometry.case.Case.extra``).
    """
    from contact.load_capacity.iso10300.face_contact import RatioChange

    table = extra.get(RECORD_TABLE) if hasattr(extra, "get") else None
    if not hasattr(table, "get"):
        return None
    try:
        checks = tuple(
            ChangeCheck(RatioChange(str(c["field"]), float(c["value"]), {}, str(c["text"]),
                                    str(c.get("other", ""))),
                        float(c.get("unloaded_te_pp_urad", math.nan)),
                        float(c.get("ease_off_um", math.nan)),
                        float(c.get("valid_share", 0.0)), str(c.get("failed", "")),
                        float(c.get("cpu_seconds", 0.0)))
            for c in table.get("change", ()))
        return RemedyRecord(checks, float(table.get("unloaded_te_pp_urad", math.nan)),
                            float(table.get("ease_off_um", math.nan)),
                            float(table["limit_urad"]),
                            float(table.get("unrelieved_te_pp_urad", math.nan)),
                            bool(table.get("lte_met", False)))
    except (KeyError, TypeError, ValueError) as exc:
        log.info("the case's %s table not read: %s", RECORD_TABLE, exc)
        return None


def recorded_judge(record: RemedyRecord, targets_met: bool = False):
    """The judge (:func:`contact.load_capacity.iso10300.face_contact.low_ratio_text`'s
    ``judge``) that says each remedy as the checks ``record`` holds say it: the same
    sentence ``ltca synthesize``'s note printed (:func:`checked_remedy_text`), refused
    changes not offered; a ratio whose changes the record does not hold, as unchecked
    equals (the plain sentence) with that said. The record's changes of the same contact
    ratio are said, whatever changes the case's own design data give (the note's).

    Parameters
    ----------
    record : RemedyRecord
    targets_met : bool, optional
        Whether the written design meets every drive development target (as
        :func:`checked_remedy_text`; default False; ``ltca run``'s next step reads the
        written case's ``[development] targets_met``,
        :func:`contact.commands.next_steps.overlap_lines`).

    Returns
    -------
    callable
        ``judge(changes, target, none) -> str``.
    """
    def judge(changes, target, none):
        ratios = {_RATIO_OF.get(c.field, c.field) for c in changes}
        mine = [c for c in record.checks
                if _RATIO_OF.get(c.change.field, c.change.field) in ratios]
        if mine:
            return checked_remedy_text(mine, target, none, record.reference_ute,
                                       record.limit, record.lte_met, targets_met)
        ways = [c.text for c in changes]
        return (" or ".join(ways) + (", the other kept," if len(ways) > 1 else "")
                + f" reaches {target:g} (not checked by a synthesis: the case records no "
                "check of it)")

    return judge


class LteDiagnosis(NamedTuple):
    """What sets a written flank's LTE where it exceeds the verdict's limit and a contact
    ratio is low (:func:`lte_diagnosis`)."""

    cause: str  # "unloaded_te", "relief" (the unloaded TE is the relief's) or "contact_ratios"
    text: str


#: what a higher contact ratio is, where the unloaded TE is not what the LTE is: a trial
#: (docs/own_gear_set.md, "The overlap change is a trial")
RATIO_TRIAL_TEXT = ("a higher contact ratio is the lever left, and the change that takes it "
                    "to its limit is a trial: whether it lowers the LTE is not estimated from "
                    "the basic data, the LTE is the bearing developed on the new blank "
                    "(measured: a 21x29 at beta_m 35 -> 38.5 deg 135/93 -> 46/47 urad, an "
                    "18x27 at 35 -> 39.5 deg 80 -> 81 urad, a 15x31 at 40 -> 46.3 deg 99 -> 64 "
                    "urad at its design torque; docs/own_gear_set.md, 'The overlap change is "
                    "a trial')")


def lte_diagnosis(lte: Sequence[float], limit: float,
                  written: tuple[float, float] | None,
                  prescriptions: Any = None,
                  checks: Sequence[ChangeCheck] = (),
                  unrelieved: float = math.nan) -> LteDiagnosis:
    """What sets the written drive flank's LTE, said the same way by ``ltca synthesize``'s
    note (:func:`contact.optimize.written_notes.reach_text`) and ``ltca run``'s next step
    (:func:`contact.commands.next_steps.overlap_lines`): its unloaded TE
    (:func:`ute_sets_lte`, :func:`ute_lte_text`) or, else, the low contact ratios, whose
    change is a trial (:data:`RATIO_TRIAL_TEXT`).

    Parameters
    ----------
    lte : sequence of float — [µrad]
        The flank's LTE p-p at (light, design) torque.
    limit : float — [µrad]
        The verdict's LTE limit.
    written : (float, float) or None
        The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]
        (:func:`unloaded_te_pp`; ``ltca run``: as the case records it); None: not known.
    prescriptions : mapping, optional
        The drive prescriptions the development wrote (its best design's values; the case's
        ``[development] prescriptions``): ``te_level`` [µrad], the level prescribed on
        purpose (:func:`ute_sets_lte`), and the path angle, ellipse length and TE level
        named in the statement.
    checks : sequence of ChangeCheck, optional
        The contact-ratio remedies' checks (the case's :data:`RECORD_TABLE`): where one
        that passes :func:`refusal` takes the written unloaded TE within ``limit`` at the
        same prescriptions (:func:`lowest_checked`), the unloaded TE is not what keeps the
        LTE above it whatever the contact ratio: the cause is the contact ratios, said
        with that check's number (:func:`ute_lowered_text`; the 21×21 of round 21: 97 →
        51 µrad at b2 39.3 mm). Default none.
    unrelieved : float, optional — [µrad]
        The written drive flank's unloaded TE p-p without its profile relief
        (:func:`unrelieved_te_pp`; the record's ``unrelieved_ute``): where the unloaded TE
        sets the LTE and this is within ``limit``, the relief, not the prescriptions' TE,
        is the cause (:func:`relief_lte_text`). Default NaN: not measured.

    Returns
    -------
    LteDiagnosis
        ``cause`` "unloaded_te" with :func:`ute_lte_text`'s statement, "relief" with
        :func:`relief_lte_text`'s, or
        "contact_ratios" with :data:`RATIO_TRIAL_TEXT` (after :func:`ute_lowered_text`'s
        numbers where a check lowered the unloaded TE within ``limit``, after
        :func:`blank_ute_text`'s where a check removed at least :data:`BLANK_SHARE` of it
        but not within ``limit``, :func:`blank_lowers`; the relief's statement comes
        before the latter).
    """
    values = prescriptions if hasattr(prescriptions, "get") else {}
    try:
        prescribed = float(values.get("te_level", math.nan))
    except (TypeError, ValueError):
        prescribed = math.nan
    if written is not None and ute_sets_lte(written[0], lte, limit, prescribed):
        low = lowest_checked(checks, written[0], limit)
        if low is not None and low.ute <= limit:
            return LteDiagnosis("contact_ratios",
                                ute_lowered_text(written[0], written[1], low, limit))
        if math.isfinite(unrelieved) and unrelieved <= limit:
            return LteDiagnosis("relief", relief_lte_text(
                written[0], written[1], unrelieved, lte, limit, _relief_said(values)))
        named = ", ".join(f"{k} {float(values[k]):.3g}" for k in
                          ("path_angle", "ellipse_length", "te_level") if k in values)
        if low is not None and blank_lowers(written[0], low.ute):
            return LteDiagnosis("contact_ratios", blank_ute_text(
                written[0], written[1], low, limit, named))
        return LteDiagnosis("unloaded_te", ute_lte_text(written[0], written[1], lte, limit,
                                                        named, low))
    return LteDiagnosis("contact_ratios", RATIO_TRIAL_TEXT)


def _relief_said(values: Any) -> str:
    """The written drive relief as the prescriptions give it [µm]: "tip/root relief 15/15
    um"; "" where they do not give both."""
    try:
        tip, root = float(values["tip_relief"]), float(values["root_relief"])
    except (KeyError, TypeError, ValueError):
        return ""
    return f"tip/root relief {tip:g}/{root:g} um"
