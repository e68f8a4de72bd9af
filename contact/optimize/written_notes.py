"""The notes, the remedies' record and the outcome lines of the case ``ltca synthesize``
writes of a development (issue 71, branch api88): moved out of the command
(``contact/commands/synthesize.py``) so that the Python API writes the same case and says
the same lines (:mod:`contact.optimize.synthesized_case`).

Before, a script that ran ``contact.develop(...)`` and wrote ``.written_case()`` got no
:data:`~contact.optimize.remedy_check.RECORD_TABLE` table (the record ``ltca run``'s next
step reads) and none of the command's cause-and-remedy or LTE notes (round 28 of
docs/own_gear_set.md): they were private functions of the command.

Public names
------------
FACE_CONTACT_RATIO_NOTE, PROFILE_CONTACT_RATIO_NOTE, header_text, noted_case,
with_record, contact_ratios, low_overlap_lte, reach_text, first_lines, gear_process_note,
fe_level_notes, synthesis_fe_level, checked_basic_rating, written_lte_lines,
written_floor, written_hollow
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

from geometry.core.text import plain_number

_HEADER = ("# Written by `ltca synthesize {basic}` (geometry.synthesis.case_synthesis: "
           "ISO 23509 blank, {gear} gear,\n# pinion by Litvin local synthesis); see `source` and "
           "docs/synthesis.md. Do not edit by hand.\n")


def header_text(shown: str, gear_process: str) -> str:
    """The comment a written case starts with: the basic file and the methods, the gear's
    process as the case holds it (issue 71, round 26c: a spiral bevel 17x23 whose generated
    gear was kept read "Formate gear" there, its ``[gear] process = "Generate"``).

    Parameters
    ----------
    shown : str
        The basic file as the user named it.
    gear_process : str
        The case's ``gear.process``: "Formate" or "Generate" (geometry.machine).

    Returns
    -------
    str
        Two comment lines, ending in a newline.
    """
    gear = "generated" if gear_process == "Generate" else "Formate"
    return _HEADER.format(basic=shown, gear=gear)


#: the face contact ratio below which ``ltca synthesize`` adds a note: the least that
#: bevel-gear design practice asks for (AGMA 2005-D03, face contact ratio m_F); the
#: spiral bevel 17x29 at 0.96 carried its light torque on one pair over 75 % of the cycle
#: (LTE 57/138 urad), the 15x45 at 1.49 met every target (docs/own_gear_set.md); the
#: same number as :data:`contact.load_capacity.iso10300.face_contact.FACE_CONTACT_RATIO_MIN`
#: (tested; not imported here, to keep the command's import light)
FACE_CONTACT_RATIO_NOTE = 1.25
#: the profile contact ratio below which ``ltca synthesize`` adds the same note (the
#: spiral bevel 19x23 at β_m 46°: ε_vα 0.98, its LTE 223 / 118 µrad, one pair alone over
#: 85 % of the cycle at the light torque); the same number as
#: :data:`contact.load_capacity.iso10300.face_contact.PROFILE_CONTACT_RATIO_MIN` (tested)
PROFILE_CONTACT_RATIO_NOTE = 1.0


def contact_ratios(case) -> tuple[float, float] | None:
    """(ε_vα, ε_vβ) [1] of ISO 10300-1's virtual cylindrical gears of the case written
    (Annex A: transverse and face contact ratio), None where the rating's inputs are not
    there (a case the rating cannot read: said by ``ltca run`` itself).

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    (float, float) or None
    """
    from contact.load_capacity.iso10300.rating import iso10300_rating
    from geometry.core.errors import InputError

    try:
        ds = iso10300_rating(case, torque=[max(case.operating.torque)])
    except (InputError, KeyError, ValueError):
        return None
    return float(ds["eps_va"]), float(ds["eps_vb"])


def low_overlap_lte(development, written_ute: tuple[float, float] | None = None,
                    checks: Sequence = (), unrelieved: float = math.nan) -> str:
    """What the development's bearing did for the LTE of a design whose face contact ratio
    is below :data:`FACE_CONTACT_RATIO_NOTE`, in numbers (``ltca synthesize``'s note): the
    LTE p-p of the written drive flank and, where checked, coast flank at their light and
    design torques (:data:`contact.optimize.development.CHECK_LTCA`, ``ltca run``'s
    sampling) against the development's target ``max_lte``.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
    written_ute : (float, float), optional
        The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]
        (:func:`contact.optimize.remedy_check.unloaded_te_pp`), for :func:`reach_text`.
    checks : sequence of contact.optimize.remedy_check.ChangeCheck, optional
        The contact-ratio remedies' checks, for :func:`reach_text`.
    unrelieved : float, optional — [µrad]
        The written drive flank's unloaded TE p-p without its relief, for
        :func:`reach_text` (NaN: not measured).

    Returns
    -------
    str
        E.g. "the developed bearing's LTE p-p: drive 25/52 urad at 27/180 N m, coast 30/48
        urad at 27/121 N m (light/design), the development's target 40 urad missed".
    """
    from contact.optimize.development_remedy import above_limit_text, flanks_above, lte_parts
    from contact.study.verdicts import LTE_LIMIT

    parts = lte_parts(development)
    target = development.targets.max_lte
    drive, coast = flanks_above(development, target)
    # which flank misses, where one does and the other not (a face-hobbed 8x37 read
    # "drive 10/20, coast 42/50 ..., the development's target 40 urad missed")
    said = ("met" if not (drive or coast) else "missed" if coast is None or drive == coast
            else "met on the drive flank, missed on the coast" if coast
            else "missed on the drive flank, met on the coast")
    return (f"the developed bearing's LTE p-p: {', '.join(parts)} (light/design), the "
            f"development's target {target:g} urad " + said
            + above_limit_text(development, LTE_LIMIT)
            + reach_text(development, LTE_LIMIT, written_ute, checks, unrelieved))


def reach_text(development, limit: float,
               written_ute: tuple[float, float] | None = None,
               checks: Sequence = (), unrelieved: float = math.nan) -> str:
    """What the development's drive designs reached where the written drive flank's LTE
    p-p exceeds ``limit`` [µrad] (the verdict's): the least LTE p-p its check's last LTE
    step saw (``development.lte_reach``,
    :func:`contact.optimize.development_check.checked_crowning_lte`: the profile crowning
    flattened, the TE parabola deepened), what design that was and why it was not
    written (where it "scores no better", the targets it misses in numbers, its
    ``"evaluation"``'s :meth:`~contact.optimize.development_result.DevelopmentResult.
    missed_text`); beyond ``limit`` the statement that the limit is out of the basic data's
    reach, higher contact ratios the lever left, and the change that takes them to
    their limits (the note's first part) a trial whose LTE is not estimated
    (:func:`contact.commands.next_steps.overlap_lines`). Empty where the
    drive flank is within ``limit`` or the step did not run.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
    limit : float — [µrad]
    written_ute : (float, float), optional
        The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]; where
        that unloaded TE is what the LTE is
        (:func:`contact.optimize.remedy_check.ute_sets_lte`), the statement says so
        instead of naming the contact ratios (the 8x35 at Sigma 85 deg and k_d 2.16 of
        benchmarks/data/unseen_designs: unloaded TE p-p 609 urad, LTE 605/600 urad),
        with ": none it checked within <limit> urad" before it where the step's least
        LTE exceeds ``limit`` too (the prescriptions it names as the lever were then not
        found by the check: the FH 16x16 at Sigma 60 deg, least 509/197 urad). Also said
        where the step did not run.
    checks : sequence of contact.optimize.remedy_check.ChangeCheck, optional
        The contact-ratio remedies' checks: one that takes the unloaded TE within
        ``limit`` makes the contact ratios the cause
        (:func:`contact.optimize.remedy_check.lte_diagnosis`).
    unrelieved : float, optional — [µrad]
        The written drive flank's unloaded TE p-p without its relief
        (:func:`contact.optimize.remedy_check.unrelieved_te_pp`): within ``limit``, the
        relief is said to set the unloaded TE (the face-hobbed 16x16 at Sigma 60 deg on its
        generated gear: 156 urad written, 15 without the relief). NaN: not measured.

    Returns
    -------
    str
        E.g. "; the development's least drive LTE p-p 109/96 urad (design 35 with
        profile_crowning 0 um, not written: it scores no better): LTE p-p <= 60 urad at
        every torque is out of this basic data's reach (the profile crowning flattened
        tried); a higher contact ratio is the lever left, and the change that takes it
        to its limit is a trial (…)" (the spiral bevel 19x23 at beta_m 46 deg of
        benchmarks/data/unseen_designs; the change is no promise of 60 urad: its k_d
        2.06, eps_va 1.00, gave 75/107 urad). The cause stated is
        :func:`contact.optimize.remedy_check.lte_diagnosis`'s, which ``ltca run``'s next
        step states too.
    """
    from contact.optimize.remedy_check import lte_diagnosis

    reach = getattr(development, "lte_reach", None)
    lte = development.best.metrics["lte_peak_to_peak"]
    if not max(float(lte[0]), float(lte[-1])) > limit:
        return ""
    said = ""
    if reach:
        why = f", not written: {reach['why']}" if reach.get("why") else ""
        e = reach.get("evaluation")
        if (reach.get("why") == "it scores no better" and getattr(e, "full", None)
                is not None and not e.full[2] and hasattr(development, "missed_text")):
            # what it gives up for its LTE, in numbers (the FH 9x37 at Sigma 85 deg of
            # round 19b: 7/17 urad with the edge share 7.8 %, limit 2 %)
            why += (", missing " + development.missed_text(e).removeprefix(
                "not every target met: ").replace("; ", ", "))
        said = (f"; the development's least drive LTE p-p {reach['light']:.0f}/"
                f"{reach['design']:.0f} urad ({reach['what']}{why})")
    # what sets the LTE: the one statement `ltca run`'s next step makes too
    diagnosis = lte_diagnosis(lte, limit, written_ute,
                              getattr(development.best, "values", None) or {}, checks,
                              unrelieved)
    least = max(reach["light"], reach["design"]) if reach else math.nan
    if diagnosis.cause in ("unloaded_te", "relief"):
        # the lever it names is untried where no checked design came within the limit
        # (round 20b: the FH 16x16 at Sigma 60 deg, least 509/197 urad, written 511/315)
        none = f": none it checked within {limit:g} urad" if least > limit else ""
        return said + none + "; " + diagnosis.text
    if not reach:
        return ""
    tried = " and ".join(reach.get("tried", ()))
    tried = (f"{tried} tried" if tried else "no flatter profile or deeper TE parabola "
             "left to try")
    if least > limit:
        return (said + f": LTE p-p <= {limit:g} urad at every torque is out of this basic "
                f"data's reach ({tried}); " + diagnosis.text)
    return said + f": within {limit:g} urad, but not written"


def gear_process_note(development, case) -> str | None:
    """``ltca synthesize``'s note on the gear process ``gear_process = "auto"`` chose after
    developing both (the development's ``gear_process_text``, until now only in the case's
    ``source``), with the gear pitch angle where a Formate gear was kept below
    :data:`~geometry.synthesis.case_synthesis.FORMATE_PITCH_ANGLE_LIMIT`, whose deep working
    depth the generated pinion does not cover (docs/synthesis.md, "Known limits").

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult or None
    case : geometry.case.Case
        The case written (its gear's ``process`` and blank ``pitch_angle`` [rad]).

    Returns
    -------
    str or None
        None where the development chose no gear process (its ``gear_process_text``
        empty) or there was no development; a face-hobbed pair's choice by its
        third-order TE (``case.source``'s sentence from
        :data:`~geometry.synthesis.case_synthesis.RULE_TEXT_MARKER` on) where the
        development chose none.

    Notes
    -----
    Found on a spiral bevel miter 20x20 (issue 71, unseen (8)): "auto" kept the Formate gear
    at delta2 45 deg (design torque 49.4 of 309.1 N m, LTE p-p 855 urad; the generated
    gear's development stopped at 19.6 N m), and the command's output said nothing of it.
    The same file with ``gear_process = "Generate"`` is no better: 19.6 N m, LTE p-p
    309 urad, root stress not computed (docs/own_gear_set.md, "unseen (8)").
    """
    from geometry.synthesis.case_synthesis import (
        FORMATE_PITCH_ANGLE_LIMIT,
        RULE_TEXT_END,
        RULE_TEXT_MARKER,
    )

    text = getattr(development, "gear_process_text", "") if development is not None else ""
    source = getattr(case, "source", "")
    if not text and RULE_TEXT_MARKER in source:
        # a face-hobbed pair's gear chosen by its third-order TE (issue 71, ratio 1): the
        # synthesis's sentence, up to its reference (a development's text may follow it)
        start = source.index(RULE_TEXT_MARKER)
        end = source.find(RULE_TEXT_END, start)
        return source[start:] if end < 0 else source[start:end + len(RULE_TEXT_END)]
    if not text:
        return None
    gear = case.gear
    delta2 = math.degrees(float(gear.blank.pitch_angle))
    if gear.process == "Formate" and delta2 < FORMATE_PITCH_ANGLE_LIMIT:
        text += (f" The Formate gear's pitch angle delta2 {delta2:.1f} deg is below about "
                 f"{FORMATE_PITCH_ANGLE_LIMIT:g} deg, where its deep working depth lies beyond "
                 "the surface of action; a higher ratio, a larger shaft angle or a smaller "
                 "c_ham moves it within reach, and gear_process 'Generate' forces the "
                 "generated gear, whose outcome is said above (docs/synthesis.md, 'Known "
                 "limits').")
    return text


def _lte_notes(basic, case, development, ratios) -> tuple[list[str], object]:
    """``ltca synthesize``'s notes on the written drive flank's LTE: flanks far from
    conjugate (:func:`_conjugacy_notes`) or else low contact ratios, and a coarse trial the
    check contradicts; made before the case is written, so that the contact-ratio remedies'
    checks go into it (:data:`contact.optimize.remedy_check.RECORD_TABLE`, which ``ltca
    run``'s next step reads).

    Returns
    -------
    (lines, record) : (list of str, contact.optimize.remedy_check.RemedyRecord or None)
        The notes to print (each without its "note: "), and the remedies' checks where the
        contact-ratio note checked any.
    """
    lines: list[str] = []
    record = None
    limited = _generation_note(case, basic)
    if limited is not None:  # said first: the flank the contact needs is not there
        lines.append(limited)
    far, misjudged = _conjugacy_notes(case, development, ratios, limited is None)
    if far is not None:
        lines.append(far)
    elif ratios is not None and (ratios[1] < FACE_CONTACT_RATIO_NOTE
                                 or ratios[0] < PROFILE_CONTACT_RATIO_NOTE):
        # the cause and the remedy in numbers: the face width and the spiral angle that
        # reach the least face contact ratio, the depth factor and the pressure angle that
        # reach the least profile contact ratio (contact.load_capacity.iso10300.face_contact),
        # each checked by a synthesis before it is offered; the written case's unloaded TE,
        # where it is what the LTE is, named instead of the contact ratios
        from contact.load_capacity.iso10300.face_contact import low_ratio_text
        from contact.optimize.development_conjugacy import teeth_checker
        from contact.optimize.development_remedy import (
            checked_record,
            every_drive_target,
            lte_within,
        )
        from contact.optimize.remedy_check import recorded_judge
        from contact.study.verdicts import LTE_LIMIT

        written = _written_ute(case, development, ratios)
        # each change checked once (the record the case keeps and --apply-remedy applies),
        # the sentence said from those checks
        # a change its check measures no better is no remedy where the written LTE
        # is already within the limit (contact.optimize.remedy_check.no_better)
        # (the measure without the relief reads the written flanks' steps 3-6 back from
        # the development's synthesis memo: remedy_check.memo_options)
        record = checked_record(prescribed_basic_of(basic, case, development), basic.design,
                                written, LTE_LIMIT, lte_within(development, LTE_LIMIT),
                                memo=getattr(development, "memo", None))
        checks = () if record is None else record.checks
        unrel = math.nan if record is None else record.unrelieved_ute
        said = low_ratio_text(basic.design, FACE_CONTACT_RATIO_NOTE,
                              PROFILE_CONTACT_RATIO_NOTE,
                              judge=None if record is None else recorded_judge(
                                  record, development is not None
                                  and every_drive_target(development)),
                              teeth_check=teeth_checker(basic))
        lines.append((said if said is not None else
                      f"contact ratios eps_va {ratios[0]:.2f}, eps_vb {ratios[1]:.2f}: "
                      f"below {PROFILE_CONTACT_RATIO_NOTE:g} / {FACE_CONTACT_RATIO_NOTE:g}"
                      ", the least bevel-gear design practice asks for (AGMA 2005-D03); "
                      "a wider face (b2) or a larger spiral angle (beta_m) raises eps_vb, "
                      "a deeper tooth (k_d) or a smaller pressure angle (alpha_dD) eps_va")
                     + (f"; {low_overlap_lte(development, written, checks, unrel)}"
                        if development is not None else "")
                     + length_trade(development, ratios, record))
    if misjudged is not None:
        lines.append(misjudged)
    if far is None and development is not None:
        said = deflection_note(case, development)
        if said is not None:
            lines.append(said)
    return lines, record


def length_trade(development, ratios, record=None) -> str:
    """"; " and :func:`contact.optimize.development_length_trade.length_trade_text` (the
    drive pattern's length given up for the LTE on a face contact ratio below
    :data:`FACE_CONTACT_RATIO_NOTE`; ``--apply-remedy`` named where a change of the
    remedies' ``record`` passed its check), then "; " and :func:`~contact.optimize.
    development_length_trade.no_length_text` (no pattern long enough below ε_vβ ≈ 0.76,
    the drive LTE above the verdict's limit), or "" where there is no development or
    nothing to say."""
    if development is None:
        return ""
    from contact.optimize.development_length_trade import length_trade_text, no_length_text
    from contact.optimize.development_remedy import chosen_check
    from contact.study.verdicts import LTE_LIMIT

    said = length_trade_text(development, ratios[1], FACE_CONTACT_RATIO_NOTE,
                             remedy=record is not None and chosen_check(record) is not None)
    # below eps_vb ~0.76 no pattern the targets allow is long enough (branch contact82)
    none = no_length_text(development, ratios[1], LTE_LIMIT)
    return "".join(f"; {s}" for s in (said, none) if s)


def _written_ute(case, development, ratios) -> tuple[float, float] | None:
    """The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]
    (:func:`contact.optimize.remedy_check.unloaded_te_pp`, < 1 s: the ease-off is the one
    the conjugacy check made), where the note needs it: a contact ratio below
    :data:`PROFILE_CONTACT_RATIO_NOTE` or :data:`FACE_CONTACT_RATIO_NOTE` (the remedies'
    reference) or a drive LTE above the verdict's limit (its diagnosis); None otherwise or
    where it cannot be measured (said in the log)."""
    from contact.study.verdicts import LTE_LIMIT
    from geometry.core.errors import InputError, ModelUnavailableError

    high = (development is not None
            and float(max(development.best.metrics["lte_peak_to_peak"])) > LTE_LIMIT)
    if not (high or ratios[0] < PROFILE_CONTACT_RATIO_NOTE
            or ratios[1] < FACE_CONTACT_RATIO_NOTE):
        return None
    from contact.optimize.remedy_check import unloaded_te_pp

    try:
        ute, span, _ = unloaded_te_pp(case)
    except (InputError, ModelUnavailableError, ValueError) as exc:
        import logging

        logging.getLogger(__name__).info("the written case's unloaded TE not measured: %s",
                                         exc)
        return None
    return ute, span


def prescribed_basic_of(basic, case, development):
    """The basic data at the written case's prescriptions: the development's ``basic``
    (both flanks as written), the file's own without a development; its gear process the
    written case's where the file leaves it to ``"auto"`` (the remedies' syntheses then
    make the gear the written case has, not the first process that succeeds)."""
    from contact.optimize.development_remedy import prescribed_basic

    return prescribed_basic(basic, case, development)


def noted_case(basic, case, development):
    """The case to write with its LTE notes made before it is written
    (:func:`_lte_notes`) and the contact-ratio remedies' checks recorded in it
    (:func:`with_record`) for ``ltca run``'s next step.

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data written (its ``design``: the remedies' changes; with a development
        the remedies are checked at its ``basic``, the written prescriptions).
    case : geometry.case.Case
        The case to write (:func:`contact.optimize.development_written.written_case`).
    development : contact.optimize.development_result.DevelopmentResult or None
        None: the local synthesis as prescribed (``--no-development``).

    Returns
    -------
    (case, ratios, notes, record)
        The case (with :data:`~contact.optimize.remedy_check.RECORD_TABLE` where a remedy
        was checked), the contact ratios (ε_vα, ε_vβ) [1] or None, the notes (each
        without its "note: ") and the :class:`~contact.optimize.remedy_check.RemedyRecord`
        or None.

    Notes
    -----
    Source: ``ltca synthesize`` (issue 71); the limits :data:`FACE_CONTACT_RATIO_NOTE`
    (AGMA 2005-D03) and :data:`PROFILE_CONTACT_RATIO_NOTE`.
    """
    ratios = contact_ratios(case)
    notes, record = _lte_notes(basic, case, development, ratios)
    return ((case if record is None else with_record(case, record)), ratios, notes,
            record)


def _ratios_text(before: tuple[float, float], after: tuple[float, float]) -> str:
    """"eps_vb 0.91 -> 1.25, eps_va 1.19 -> 1.18": both contact ratios before and after a
    remedy (:func:`contact.optimize.development_remedy.contact_ratios_of`)."""
    return (f"eps_vb {before[1]:.2f} -> {after[1]:.2f}, eps_va {before[0]:.2f} -> "
            f"{after[0]:.2f}")


def _limit_text(ends: float, between: str, peak: float, limit: float) -> str:
    """The clause of an ``--apply-remedy`` line on a design's LTE p-p against the verdict's
    ``limit`` [µrad]: its largest at the light and design torque ``ends`` and, where its
    development recorded it, between them (``between`` in words, :func:`~contact.
    optimize.development_remedy.between_parts`, its largest ``peak``), as ``ltca run``'s
    verdict judges both (issue 71, round 42: "within the verdict's 60 urad" read off the
    two torques where the coast flank was 65.0 µrad between them)."""
    if not between or not math.isfinite(peak):
        return f", {'above' if ends > limit else 'within'} the verdict's {limit:g} urad"
    where = ("at and between the torques" if (ends > limit) == (peak > limit)
             else "at the torques" if ends > limit else "between the torques")
    over = "above" if max(ends, peak) > limit else "within"
    return f"; between them {between}: {over} the verdict's {limit:g} urad {where}"


def _given_cpu(seconds: float) -> str:
    """The ``--apply-remedy`` line's clause on the design as given's development CPU [s]:
    the remedied design's headline ("…; 44 s CPU") counts its own development alone, the
    command both (issue 71, round 42: the 16x35 at Σ 95° printed 44 s, `/usr/bin/time` read
    90.9 s); empty where not known."""
    if not math.isfinite(seconds):
        return ""
    return (f" (its development {seconds:.0f} s CPU; the remedied design's headline counts "
            "its own alone)")


def first_lines(basic, development, record, shown: str) -> list[str]:
    """``ltca synthesize``'s first lines where a contact ratio is below its limit and the
    developed LTE p-p exceeds the verdict's limit, or a remedy was applied: the ratio, the
    LTE it leads to, the limit and the checked remedy (its contact ratios and its check's
    unloaded TE p-p), or what ``--apply-remedy`` changed and both designs' LTE (issue 71:
    the remedy said first and in numbers; :mod:`contact.optimize.development_remedy`).

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data written (remedied where a remedy was applied).
    development : contact.optimize.development.DevelopmentResult or None
    record : contact.optimize.remedy_check.RemedyRecord or None
        The remedies' checks of the case written (:func:`_lte_notes`).
    shown : str
        The basic file as the user named it.

    Returns
    -------
    list of str
        Empty without a development, or where no ratio is low (nothing checked) and no
        remedy was applied, or where every written LTE p-p is within the limit. Where the
        written drive flank's unloaded TE is what its LTE is
        (:func:`contact.optimize.remedy_check.lte_diagnosis`), that is said instead of a
        remedy.
    """
    from contact.optimize.development_remedy import (
        above_limit_text,
        between_parts,
        change_text,
        chosen_check,
        contact_ratios_of,
        file_value,
        lte_parts,
        remedied_basic,
        worst_lte,
    )
    from contact.study.verdicts import LTE_LIMIT

    if development is None:
        return []
    worst = worst_lte(development)
    within = "within" if worst <= LTE_LIMIT else "above"
    applied = getattr(development, "remedy", None)
    if applied is not None:
        change = applied.check.change
        after = file_value(applied.basic.design, change.field)
        said = change_text(change.field, applied.before, after)
        ratios = _ratios_text(applied.ratios_before, applied.ratios_after)
        parts, peak = between_parts(development)
        return [f"applied remedy (--apply-remedy): {said}: {ratios} (checked: "
                f"unloaded TE p-p {applied.check.ute:.0f} urad at the written prescriptions "
                f"of the design as given, whose own is {applied.record.reference_ute:.0f})",
                f"  the design as given ({shown}), developed: LTE p-p "
                f"{applied.given_lte} (light/design)"
                + _limit_text(applied.given_worst, getattr(applied, "given_between", ""),
                              getattr(applied, "given_between_worst", math.nan), LTE_LIMIT)
                + "; not written" + _given_cpu(getattr(applied, "given_seconds", math.nan)),
                f"  the remedied design, developed and written: LTE p-p "
                f"{', '.join(lte_parts(development))} (light/design)"
                + (_limit_text(worst, ", ".join(parts), peak, LTE_LIMIT) if parts else
                   f", {within} the verdict's {LTE_LIMIT:g} urad (ltca run judges it "
                   "between its torques too)"),
                *([f"  {applied.torque_why}"] if getattr(applied, "torque_why", "") else []),
                *_developed_lines(applied)]
    if record is None or worst <= LTE_LIMIT:
        return []
    before = contact_ratios_of(basic.design)
    low = (f"face contact ratio eps_vb {before[1]:.2f} below {FACE_CONTACT_RATIO_NOTE:g}"
           if before[1] < FACE_CONTACT_RATIO_NOTE else
           f"profile contact ratio eps_va {before[0]:.2f} below "
           f"{PROFILE_CONTACT_RATIO_NOTE:g}")
    lines = [f"{low}: the developed LTE p-p {', '.join(lte_parts(development))} "
             f"(light/design){above_limit_text(development, LTE_LIMIT)}"]
    if ute_is_the_lte(development, record):
        return [*lines, "  the drive LTE is the written flank's unloaded TE, not the contact "
                        "ratio's (the note below): no contact-ratio remedy is the lever"]
    chosen = chosen_check(record)
    if chosen is None:
        return [*lines, "  no contact-ratio remedy passed its check by a synthesis (the "
                        "note below says why each is refused)"]
    remedied = remedied_basic(basic, chosen.change)
    field = chosen.change.field
    old, new = (file_value(b.design, field) for b in (basic, remedied))
    return [*lines, f"  checked remedy: {change_text(field, old, new)}: "
                    f"{_ratios_text(before, contact_ratios_of(remedied.design))}, unloaded "
                    f"TE p-p {chosen.ute:.0f} urad at the written prescriptions (the written "
                    f"case's {record.reference_ute:.0f}); its LTE is its own development's, "
                    f"not estimated: ltca synthesize {shown} --apply-remedy applies it and "
                    "writes that development"]


def _developed_lines(applied) -> list[str]:
    """Where ``--apply-remedy`` developed more than one remedy (the first's drive LTE above
    the verdict's limit over ``ltca run``'s torques,
    :func:`contact.optimize.development_remedy_next.next_remedies`): each remedy developed
    with its numbers, and why the one written was kept; empty otherwise."""
    from contact.optimize.development_remedy_next import developed_text
    from contact.study.verdicts import LTE_LIMIT

    said = developed_text(tuple(getattr(applied, "developed", ())), LTE_LIMIT)
    if not said:
        return []
    return [f"  {said}", f"  {applied.kept_why}"]


def with_record(case, record):
    """``case`` with the remedies' checks as its informational
    :data:`~contact.optimize.remedy_check.RECORD_TABLE` table.

    Parameters
    ----------
    case : geometry.case.Case
    record : contact.optimize.remedy_check.RemedyRecord

    Returns
    -------
    geometry.case.Case
        A copy, its ``extra`` JSON-safe (:func:`contact.optimize.remedy_check.remedy_record`).
    """
    import dataclasses
    import json
    from types import MappingProxyType

    from contact.optimize.remedy_check import RECORD_TABLE, remedy_record

    extra = json.loads(json.dumps({**case.extra, RECORD_TABLE: remedy_record(record)}))
    return dataclasses.replace(case, extra=MappingProxyType(extra))


def given_coast_torque(case) -> float | None:
    """The ``[rating] coast_design_torque`` [N·m] of ``case`` where it is a finite number,
    else None (``ltca synthesize`` prints it as the coast design torque; issue 71)."""
    value = (case.extra.get("rating") or {}).get("coast_design_torque")
    try:
        value = float(value)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def written_lte_lines(case, development) -> list[str]:
    """Each flank's written LTE at its light and design torque and its largest between
    them, where it misses the development's target or the verdict's limit
    (:func:`contact.optimize.development_lte_lines.lte_lines`); the drive flank's range
    from the check's record, else, where the drive misses its target, the written case
    analysed at ``ltca run``'s ``lte_range`` torques
    (:func:`contact.optimize.development_deflection.analysed`, 10 s CPU measured on the
    loaded machine; a failed
    analysis logged and the line says "not judged between them")."""
    from contact.optimize.development_deflection import analysed
    from contact.optimize.development_lte_lines import lte_lines
    from geometry.core.errors import InputError

    drive = None
    lte = development.best.metrics["lte_peak_to_peak"]
    if development.lte_range is None and float(max(lte)) > float(
            development.targets.max_lte):
        try:
            found = analysed(case, *(float(t) for t in development.torque))
        except (InputError, ValueError, KeyError) as exc:
            import logging

            logging.getLogger(__name__).info("the drive LTE between the torques not "
                                             "analysed: %s", exc)
        else:
            drive = {"torques": tuple(found.torques), "lte": tuple(found.lte)}
    floor = written_floor(case, development)
    return lte_lines(development, drive_between=drive, drive_floor=floor,
                     drive_hollow=written_hollow(case, development, floor))


def written_hollow(case, development, floor: float) -> str:
    """What limits a hollow profile on the written drive bearing, in words
    (:func:`contact.optimize.development_hollow_limit.hollow_text`), where its LTE misses
    the development's target above the load sharing's ``floor`` [µrad] (the bearing, not
    the contact ratio, misses; :func:`written_floor`): the written drive prescriptions with
    each profile crowning of :data:`~contact.optimize.development_hollow_limit.
    HOLLOW_PROBES` hollower than the written one (× the size scale) and, where the written
    one is hollow already, one :data:`~contact.optimize.development_hollow_limit.
    HOLLOW_STEP` hollower than it, shallowest first, synthesised and analysed at ``ltca
    run``'s sampling (2 × ≈ 1.7 s CPU on the 13x33 of docs/synthesis.md). "" where the
    floor is not finite or at or above the target, the design carries no prescriptions,
    or no probe could be analysed (logged)."""
    from contact.optimize.development_hollow_limit import (
        HOLLOW_PROBES,
        HOLLOW_STEP,
        hollow_probes,
        hollow_text,
    )

    target = float(development.targets.max_lte)
    values = getattr(development.best, "values", None) or {}
    if not (math.isfinite(floor) and floor < target) or not values:
        return ""
    basic = development.basic
    try:
        scale = float(basic.size_scale())
    except (ValueError, ArithmeticError) as exc:
        import logging

        logging.getLogger(__name__).info("the hollow profile not probed: %s", exc)
        return ""
    own = float(values.get("profile_crowning", 0.0))
    crownings = {round(c * scale, 4) for c in HOLLOW_PROBES if c * scale < own}
    if own < 0.0:  # hollow already: one step hollower too (the 7x29's -5 -> -6 um)
        crownings.add(round(own - HOLLOW_STEP * scale, 4))
    crownings = sorted(crownings, reverse=True)
    if not crownings:
        return ""
    # the development's own readings of the same designs (its hollow profile one step
    # further, development_hollow_further: the written prescriptions with only the
    # crowning changed, analysed alike): not analysed again
    from contact.optimize.development_hollow_further import probes_for

    further = getattr(development, "hollow_further", None)
    read = probes_for(getattr(further, "probes", ()), crownings)
    left = [c for c in crownings if c not in read]
    probes = (hollow_probes(basic, values, tuple(development.torque), written=case,
                            crownings=left) if left else [])
    if read:  # shallowest first, as probed
        probes = sorted([*read.values(), *probes], key=lambda p: -p.crowning)
    return hollow_text(probes, target, float(development.targets.max_edge_share),
                       tried=tuple(read))


def written_floor(case, development) -> float:
    """The written drive flank's load-sharing floor between its light and design torque
    [µrad] (:func:`contact.optimize.development_lte_floor.load_sharing_floor`, one
    analysis at ``ltca run``'s sampling) where its LTE p-p misses the development's target
    at those torques within the verdict's limit; NaN elsewhere or where the analysis fails
    (logged)."""
    from contact.optimize.development_hollow_further import lte_missed
    from contact.optimize.development_lte_floor import floor_or_nan

    if not lte_missed(development.best, development.targets):
        return math.nan
    further = getattr(development, "hollow_further", None)
    if (further is not None and further.case is None
            and math.isfinite(float(further.floor))):
        return float(further.floor)  # the development's reading of this case: not again
    return floor_or_nan(case, *(float(t) for t in development.torque))


def deflection_note(case, development) -> str | None:
    """What sets the written drive flank's LTE at the design torque, where it exceeds the
    verdict's limit: the teeth's mean deflection, the LTE's share of it and the torque up
    to which the written bearing keeps the limit; where it keeps the limit at the light
    and the design torque and exceeds it between them, that peak, its torque and the
    limit (:mod:`contact.optimize.development_deflection`: the written case analysed at
    ``ltca run``'s ``lte_range`` torques, its sampling); None where it keeps the limit at
    every torque or the case cannot be analysed (said in the log).

    Analysed only where the development's check did not judge the written bearing within
    the limit between its torques: its LTE at the design torque above the limit, or the
    check's record of the LTE over the range
    (:func:`contact.optimize.development_range_lte.range_record`, the development's
    ``lte_range``) above it or missing (its torques changed after the check's steps);
    analysing always cost 1.5-3 s CPU a synthesis (docs/synthesis.md, "The LTE between the
    development's torques")."""
    from contact.optimize.development_deflection import (
        analysed,
        between_text,
        curvature_ratio,
        deflection_text,
    )
    from contact.study.verdicts import LTE_LIMIT
    from geometry.core.errors import InputError

    lte = development.best.metrics["lte_peak_to_peak"]
    judged = getattr(development, "lte_range", None)
    if not float(lte[-1]) > LTE_LIMIT and judged is not None and not (
            float(judged.get("peak", math.nan)) > LTE_LIMIT):
        return None
    light, design = (float(t) for t in development.torque)
    try:
        found = analysed(case, light, design)
    except (InputError, ValueError, KeyError) as exc:
        import logging

        logging.getLogger(__name__).info("the LTE's deflection note not made: %s", exc)
        return None
    if not found.lte[-1] > found.limit:
        return between_text(found)
    pinion, gear = case.pinion.blank, case.gear.blank
    return deflection_text(found, curvature_ratio(pinion.teeth, gear.teeth,
                                                  float(pinion.pitch_angle),
                                                  float(gear.pitch_angle)))


def _generation_note(case, basic=None) -> str | None:
    """``ltca synthesize``'s first note where the written pinion's drive flank is not
    generated over its working depth (:func:`contact.optimize.development_conjugacy.
    generation_limit_text`, with and without the development), its lever (more teeth)
    checked by syntheses of ``basic`` where given (:func:`~contact.optimize.
    development_conjugacy.checked_teeth_text`); None where it is, or where the flank cannot
    be generated at all (the analysis' own check says so)."""
    from contact.optimize.development_conjugacy import (
        checked_teeth_text,
        conjugacy,
        generation,
        generation_limit_text,
    )
    from geometry.core.errors import InputError, ModelUnavailableError

    try:
        found = generation(case)
    except (InputError, ModelUnavailableError):
        return None
    if found.complete:
        return None
    teeth = "" if basic is None else checked_teeth_text(basic)
    return generation_limit_text(found, conjugacy(case), teeth)


def _conjugacy_notes(case, development, ratios, generated: bool = True
                     ) -> tuple[str | None, str | None]:
    """(flanks far from conjugate, coarse trial misjudged): ``ltca synthesize``'s notes of
    a developed case whose drive LTE p-p is above the verdict's limit
    (:mod:`contact.optimize.development_conjugacy`: the criteria and their calibration),
    each None where it does not apply; the first replaces the contact-ratio note. Where
    the pinion's drive flank is not ``generated`` over its working depth the first is
    None: the generation limit (:func:`_generation_note`) is the cause of the few valid
    ease-off nodes, said before the contact ratios (issue 71, the 15x15 hypoid)."""
    if development is None:
        return None, None
    from contact.optimize.development_conjugacy import (
        conjugacy,
        misjudged_trial_text,
        non_conjugate_text,
    )
    from contact.study.verdicts import LTE_LIMIT

    far = None
    if generated and float(max(development.best.metrics["lte_peak_to_peak"])) > LTE_LIMIT:
        far = non_conjugate_text(conjugacy(case), ratios)
    return far, misjudged_trial_text(development)


def above_capacity_note(case, torque: float) -> str | None:
    """A note where the design torque the basic file gives (``[synthesis] design_torque``
    or ``[rating] design_torque``) is above the written pair's ISO 10300 long-life capacity
    (:func:`contact.load_capacity.iso10300.capacity.capacity_torque`, S_H = S_H,min or
    S_F = S_F,min at Z_NT = Y_NT = 1, the case's own ``[rating]`` inputs): ``ltca run``
    rates that torque FAIL at long life, and the user is told before running it. None at
    or below the capacity, where the torque is not finite, or where the rating cannot give
    a capacity (said by ``ltca run`` itself). Found on a hypoid 7x37 whose user's 150 N m,
    meant as "well below capacity", was above its 113 N m: S_H 0.87, ``ltca run`` FAIL
    with every development target met."""
    from contact.load_capacity.iso10300.capacity import capacity_torque, floor_capacity
    from geometry.core.errors import InputError

    if not math.isfinite(torque):
        return None
    try:
        capacity = capacity_torque(case)
    except (InputError, KeyError, ValueError):
        return None
    if torque <= capacity * (1.0 + 1e-6):
        return None
    # the capacity rounded down to 4 digits, as the default design torque is written
    # (below the torque, which is shown as given): a user's 265 N m typed for the 264.96
    # N m capacity read "265 N m is above ... capacity 265 N m" (issue 71, unseen designs)
    return (f"the design torque {torque:g} N m is above the pair's ISO 10300 long-life "
            f"capacity {plain_number(floor_capacity(capacity))} N m (the torque at which S_H or "
            "S_F reaches its minimum): `ltca run` rates it FAIL at long life; a design torque at "
            "or below "
            "the capacity (the default, without [synthesis] design_torque), or the duty's "
            "load cycles as [rating] load_cycles, rates it for what it is")


def design_torque_line(torque: float, why: str, development) -> str:
    """The printed "design torque:" line: the torque the case written runs and ``ltca run``
    analyses, as written, and where it comes from (``why``). Where the development ran,
    its design torque (``development.torque[1]``, :func:`contact.optimize.
    development_result.floor_torque` of the given one: the case's operating torque), the
    given ``torque`` named where that rounding lowered it; else ``torque``, the ``[rating]
    design_torque`` written. Eight significant figures: the written value, not rounded
    (four rounded the 19x57's given 2865.6 N m up to "2866 N m" while the development and
    ``ltca run`` analysed 2865, issue 71 round 20)."""
    if not math.isfinite(torque):
        return "  design torque: " + why
    if development is not None and float(development.torque[1]) < torque:
        why += (f" ({plain_number(torque, 8)} N m given, rounded down: the torque the case "
                "runs)")
        torque = float(development.torque[1])
    return f"  design torque: {plain_number(torque, 8)} N m, {why}"


def given_torque_note(case, torque: float, development) -> str | None:
    """The note on a design torque the basic file gives: above the pair's ISO 10300
    capacity (:func:`above_capacity_note`), else above the developed bearing's
    root-stress capacity (S_F,FE < S_Fmin there, which ``ltca run`` rates FAIL:
    :attr:`contact.optimize.development_result.DevelopmentResult.given_root_text`); None
    where neither."""
    above = above_capacity_note(case, torque)
    if above is None and development is not None and development.given_root_text:
        return development.given_root_text
    return above


def size_scale(basic) -> float:
    """The basic design's :func:`geometry.synthesis.basic_design.size_scale`; 1 where its
    blank cannot be made (the synthesis then names why)."""
    from geometry.core.errors import InputError

    try:
        return basic.size_scale()
    except InputError:
        return 1.0


def size_line(basic, targets) -> str | None:
    """The line saying the µm-sized defaults were scaled to a small module; None at a
    scale of 1."""
    from geometry.synthesis.basic_design import REFERENCE_MODULE

    scale = size_scale(basic)
    if scale >= 1.0:
        return None
    o = basic.options.flank(basic.options.drive_flank)
    line = (f"  small module: m_mn {scale * REFERENCE_MODULE:.3g} mm below "
            f"{REFERENCE_MODULE:g} mm, the um-sized defaults x {scale:.3g} (a value the file "
            f"gives is kept): drive flank approach {1e3 * o.approach:.3g} um, relief "
            f"{1e3 * o.tip_relief:.3g}/{1e3 * o.root_relief:.3g} um")
    if basic.options.edge_break_radius is not None:
        line += f", edge break radius {basic.options.edge_break_radius:.3g} mm"
    if targets is not None and "tip_relief" in targets.variables:
        lo, hi = targets.variables["tip_relief"]
        line += f", the development's relief bounds {lo:.3g}-{hi:.3g} um"
    if targets is not None:
        line += (f", its mounting excursions dE/dP +/-{targets.offset_tolerance:.3g}/"
                 f"{targets.mounting_tolerance:.3g} mm")
    return line + " (docs/synthesis.md)"


def fe_level_notes(development, case) -> list[str]:
    """The note that says which FE model decided a root-limited torque and why, where the
    development moved the case written to the default model
    (:attr:`contact.optimize.development_result.DevelopmentResult.fe_level_text`,
    :func:`contact.optimize.development_root.refined_for_root`); empty where the case
    keeps the level it was developed with (or no development ran)."""
    if development is None or not development.fe_level_text:
        return []
    from contact.compliance.fe.options import fe_level_of

    return [f"{development.fe_level_text}; the case written names [root_stress] fe_level "
            f"= \"{fe_level_of(case)}\" (ltca run reads the model the torque was decided "
            "with)"]


def synthesis_fe_level(basic, given: str | None = None) -> str:
    """The FE level (:data:`contact.compliance.fe.options.LEVELS`) of a new design's root
    stress: ``given`` (``--fe-level``), else the basic design's ``[root_stress] fe_level``,
    else :data:`contact.compliance.fe.options.SYNTHESIS_LEVEL` (``"coarse10"``: its peak
    root stress −1.0 … +7.1 % of the default model's at about half its build CPU,
    docs/fe.md). ``ltca synthesize`` checks the design's root stress on it and writes it
    into the case, which ``ltca run`` then reads.

    Raises
    ------
    InputError — a bad ``[root_stress]`` table of the basic design (named, with the
        levels).
    """
    from contact.compliance.fe.options import SYNTHESIS_LEVEL, fe_level_of

    own = fe_level_of(basic.root_stress)
    if given is not None:
        return given
    return own if "fe_level" in basic.root_stress else SYNTHESIS_LEVEL


def ute_is_the_lte(development, record) -> bool:
    """Whether the written drive flank's unloaded TE is what its LTE is
    (:func:`contact.optimize.remedy_check.lte_diagnosis`, the note's and ``ltca run``'s one
    statement), from the remedies' record's unloaded TE: then no contact-ratio remedy is
    offered first."""
    from contact.optimize.remedy_check import lte_diagnosis
    from contact.study.verdicts import LTE_LIMIT

    written = ((record.reference_ute, record.reference_span)
               if math.isfinite(record.reference_ute) else None)
    diagnosis = lte_diagnosis(development.best.metrics["lte_peak_to_peak"], LTE_LIMIT,
                              written, getattr(development.best, "values", None) or {},
                              record.checks, record.unrelieved_ute)
    return diagnosis.cause in ("unloaded_te", "relief")


def checked_basic_rating(rating: dict[str, Any], check: Callable[[dict[str, Any]], object]) -> None:
    """Refuse a bad ``[rating]`` table of a basic design file before the synthesis starts.

    Parameters
    ----------
    rating : dict
        The basic file's ``[rating]`` table (non-empty).
    check : callable
        The rating inputs' reader, ``RatingInputs.from_mapping`` (raises InputError naming
        ``rating.<field>``).

    Raises
    ------
    InputError
        ``check``'s, naming the field; where a required field is missing it adds that the
        basic file's table replaces the stated defaults whole (docs/synthesis.md, "The
        written case"), so that a user who gives only ``coast_design_torque`` (round 24,
        branch unseen84) learns which fields to copy.
    """
    from geometry.core.errors import InputError

    try:
        check(rating)
    except InputError as exc:
        if ": missing (" not in str(exc):
            raise
        raise InputError(
            f"{exc}; a basic file's [rating] table replaces the stated defaults whole "
            "(docs/synthesis.md, 'The written case'): give application_factor, mounting "
            "and accuracy_grade too, e.g. the case's [rating] that `ltca synthesize "
            "--no-development` writes (1.0, \"one\", [6, 8])") from None
