"""The checked contact-ratio remedy applied to the basic data: ``ltca synthesize
--apply-remedy``, ``develop(basic, apply_remedy=True)`` (issue 71, session 19: "LTE p-p ≤
60 µrad at every torque" on a design whose face contact ratio ε_vβ is at or below 1).

Three basic designs of ``benchmarks/data/unseen_designs`` (the spiral bevel 15×28 at Σ 110°,
ε_vβ 0.91; the hypoid 15×31 at a = 0.056 d_e2, ε_vβ 1.00; the face-hobbed spiral bevel
20×24 at Σ 100°, ε_vβ 0.84) reach no LTE p-p ≤ 60 µrad at every torque with any lever of
the development (docs/synthesis.md, "LTE at every torque on a face contact ratio below 1",
"The path turned again for the design torque's LTE"): the basic data must change.
``ltca synthesize``'s note offers the change, each one checked by a synthesis at the
written prescriptions (:mod:`contact.optimize.remedy_check`); the user's basic data stay
the default (a face width is often fixed by the housing). This module applies the best
change that passed its check, on request:

* :func:`ratio_changes` — the changes the note offers (the face contact ratio's where
  ε_vβ < :data:`~contact.load_capacity.iso10300.face_contact.FACE_CONTACT_RATIO_MIN`, then
  the profile contact ratio's where ε_vα <
  :data:`~contact.load_capacity.iso10300.face_contact.PROFILE_CONTACT_RATIO_MIN`), from the
  basic data alone;
* :func:`checked_record` — each change checked (:func:`~contact.optimize.remedy_check.
  check_change`), the :class:`~contact.optimize.remedy_check.RemedyRecord` the note prints
  and the case records; :func:`chosen_check` the best that passed
  (:func:`~contact.optimize.remedy_check.ranked_changes`' first);
* :func:`remedied_basic` — the basic data with that change, the change said in their
  ``source``, which the case's ``source`` cites first;
* :func:`developed_with_remedy` — the development of the basic data as given (the one
  whose written case the check needs), the check, and the development of the remedied
  basic data, returned with :class:`AppliedRemedy` as its ``remedy``; where that
  development's drive LTE exceeds the verdict's limit between its torques, the next
  checked remedy developed too and the better kept
  (:func:`~contact.optimize.development_remedy_next.next_remedies`).

Public names
------------
REMEDY_TABLE, REMEDY_TORQUE_FLOOR, AppliedRemedy, ratio_changes, contact_ratios_of,
prescribed_basic, checked_record, chosen_check, remedied_basic, file_value, change_text,
lte_parts, worst_lte, flanks_above, above_limit_text, lte_within, every_drive_target,
targets_bought, torque_bought, torque_given_up, below_floor, developed_with_remedy,
applied_table
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable
from typing import Any, NamedTuple

from contact.compliance.fe.worker_cpu import cpu_seconds
from geometry.core.text import plain_number

__all__ = ["REMEDY_TABLE", "REMEDY_TORQUE_FLOOR", "AppliedRemedy", "above_limit_text",
           "applied_table", "below_floor", "between_parts", "change_text", "checked_record",
           "chosen_check", "contact_ratios_of", "developed_with_remedy", "every_drive_target",
           "file_value", "flanks_above", "lte_parts", "lte_within", "prescribed_basic",
           "ratio_changes", "remedied_basic", "targets_bought", "torque_bought", "torque_given_up",
           "worst_lte"]

log = logging.getLogger(__name__)

#: the written case's informational table that records the remedy applied to the basic
#: data (:func:`applied_table`)
REMEDY_TABLE = "applied_remedy"

#: [1] the least share of the design as given's design torque a remedied design may keep
#: where its lower torque buys the drive targets the design as given misses
#: (:func:`targets_bought`, :func:`torque_given_up`): one step of the drive LTE window's
#: torques, 1 / :data:`~contact.optimize.development_written_lte.WINDOW_LOWER_STEP`
#: (0.909): the development itself takes a design torque within that step of one developed
#: as the same load (its light torque and load-matched TE change by as little), so a remedy
#: that costs less gives up no load the development tells apart, and one that costs more
#: trades a rating for a bearing. Round 35's 12x31 b2 32 -> 36 mm kept 0.95 (643.8 of
#: 677.1 N m); round 34's 5x48 alpha_dD 16.3 deg 0.40 (a scuffing FAIL). Issue 71, remedy99
REMEDY_TORQUE_FLOOR = 1.0 / 1.1

#: each remedy field: (its name in words, its unit as the basic file gives it, whether the
#: design data hold it in radians)
_FIELDS = {"b2": ("gear face width", "mm", False),
           "beta_m": ("mean spiral angle", "deg", True),
           "k_d": ("depth factor", "", False),
           "alpha_dD": ("drive pressure angle", "deg", True)}


class AppliedRemedy(NamedTuple):
    """The remedy :func:`developed_with_remedy` applied, and the design as given.

    Attributes
    ----------
    check : contact.optimize.remedy_check.ChangeCheck
        The change applied and its check (unloaded TE p-p [µrad], ease-off [µm] at the
        given design's written prescriptions).
    record : contact.optimize.remedy_check.RemedyRecord
        Every change checked (the note's sentence of the design as given).
    basic : geometry.synthesis.basic_design.BasicDesign
        The remedied basic data, as given to the development (the user's prescriptions).
    before : float — [file unit: mm, deg, 1]
        The field's value in the user's basic data.
    ratios_before, ratios_after : (float, float) — [1]
        (ε_vα, ε_vβ) of the design as given and remedied (:func:`contact_ratios_of`).
    given_lte : str
        The developed LTE p-p of the design as given (:func:`lte_parts`).
    given_worst : float — [µrad]
        Its largest LTE p-p, drive or coast, light or design torque.
    developed : tuple of contact.optimize.development_remedy_next.RemedyDeveloped
        Every remedy developed, in the check's order, each judged over ``ltca run``'s
        torques (:func:`~contact.optimize.development_remedy_next.next_remedies`: the next
        one developed where the one before misses the drive LTE limit there); empty where
        not recorded.
    kept_why : str
        Why the remedy applied was kept over the others developed, in numbers (empty
        where one alone was developed).
    torque_why : str
        Why its design torque, below the design as given's, was kept (:func:`torque_bought`;
        empty where it is not below).
    given_between : str
        The design as given's largest LTE p-p between its torques, per flank, as its
        development recorded it (:func:`between_parts`; empty where none was recorded).
    given_between_worst : float — [µrad]
        The largest of them (NaN where none was recorded).
    given_seconds : float — [s]
        CPU time of the design as given's development (NaN where not known): the
        remedied development's headline counts its own alone.
    """

    check: Any
    record: Any
    basic: Any
    before: float
    ratios_before: tuple[float, float]
    ratios_after: tuple[float, float]
    given_lte: str
    given_worst: float
    developed: tuple = ()
    kept_why: str = ""
    torque_why: str = ""
    given_between: str = ""
    given_between_worst: float = math.nan
    given_seconds: float = math.nan


def ratio_changes(design) -> list:
    """The basic-file changes ``ltca synthesize``'s contact-ratio note offers for a design:
    the face contact ratio's (gear face width b2, mean spiral angle β_m:
    :func:`~contact.load_capacity.iso10300.face_contact.overlap_changes`) where ε_vβ is
    below its limit, then the profile contact ratio's (k_d, α_dD:
    :func:`~contact.load_capacity.iso10300.face_contact.profile_changes`) where ε_vα is;
    in the order the note prints them (:func:`~contact.load_capacity.iso10300.face_contact.
    low_ratio_text`).

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign

    Returns
    -------
    list of contact.load_capacity.iso10300.face_contact.RatioChange
        Empty where both ratios meet their limits or are at them (within
        :data:`~contact.load_capacity.iso10300.face_contact.RATIO_AT_TARGET`: a change
        below a meaningful step), or the blank cannot be computed.
    """
    from contact.load_capacity.iso10300.face_contact import (
        at_target,
        overlap_changes,
        overlap_remedy,
        profile_changes,
        profile_remedy,
    )
    from geometry.core.errors import InputError

    # a ratio at its target (within RATIO_AT_TARGET) has no change to offer nor to apply
    out: list = []
    try:
        face = overlap_remedy(design)
    except (InputError, ValueError, ZeroDivisionError):
        face = None
    if (face is not None and face.eps_vb < face.target
            and not at_target(face.eps_vb, face.target)):
        out += overlap_changes(face, design)
    try:
        profile = profile_remedy(design)
    except (InputError, ValueError, ZeroDivisionError, AttributeError):
        profile = None
    if (profile is not None and profile.eps_va < profile.target
            and not at_target(profile.eps_va, profile.target)):
        out += profile_changes(profile)
    return out


def contact_ratios_of(design) -> tuple[float, float]:
    """(ε_vα, ε_vβ) [1] of a basic design on ISO 10300-1's virtual cylindrical gears of its
    ISO 23509 blank (:func:`~contact.load_capacity.iso10300.face_contact.profile_remedy`,
    :func:`~contact.load_capacity.iso10300.face_contact.overlap_remedy`); NaN where the
    blank cannot be computed.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
    """
    from contact.load_capacity.iso10300.face_contact import overlap_remedy, profile_remedy
    from geometry.core.errors import InputError

    try:
        return (float(profile_remedy(design).eps_va), float(overlap_remedy(design).eps_vb))
    except (InputError, ValueError, ZeroDivisionError, AttributeError):
        return math.nan, math.nan


def prescribed_basic(basic, case, development=None):
    """The basic data at the written case's prescriptions: the development's ``basic``
    (both flanks as written), the file's own without a development; its gear process the
    written case's where the file leaves it to ``"auto"`` (the remedies' syntheses then
    make the gear the written case has, not the first process that succeeds).

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
    case : geometry.case.Case
        The written case (its gear's ``process``).
    development : contact.optimize.development.DevelopmentResult, optional

    Returns
    -------
    geometry.synthesis.basic_design.BasicDesign
    """
    prescribed = basic if development is None else development.basic
    process = getattr(case.gear, "process", None)
    if prescribed.options.gear_process == "auto" and process in ("Formate", "Generate"):
        prescribed = dataclasses.replace(prescribed, options=dataclasses.replace(
            prescribed.options, gear_process=process))
    return prescribed


def checked_record(prescribed, design, written: tuple[float, float] | None, limit: float,
                   lte_met: bool = False, memo: dict | None = None):
    """Each change of :func:`ratio_changes` checked by one synthesis at the written
    prescriptions (:func:`~contact.optimize.remedy_check.check_change`).

    Parameters
    ----------
    prescribed : geometry.synthesis.basic_design.BasicDesign
        :func:`prescribed_basic`.
    design : geometry.iso23509.design_data.BevelGearDesign
        The user's design data (the changes' reference).
    written : (float, float) or None
        The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]
        (:func:`~contact.optimize.remedy_check.unloaded_te_pp`); None: not measured.
    limit : float — [µrad]
        The verdict's LTE limit.
    lte_met : bool, optional
        Whether the written design's developed LTE p-p is within ``limit``
        (:func:`worst_lte`): a change whose check measures no lower unloaded TE is then
        no remedy (:func:`~contact.optimize.remedy_check.no_better`). Default False.
    memo : dict, optional
        The synthesis memo of the development that wrote the case
        (:attr:`~contact.optimize.development_result.DevelopmentResult.memo`): the
        measure without the relief reads the written flanks' steps 3–6 back from it
        (:func:`~contact.optimize.remedy_check.unrelieved_te_pp`). Default None.

    Returns
    -------
    contact.optimize.remedy_check.RemedyRecord or None
        None where no contact ratio is below its limit (or at it, within
        :data:`~contact.load_capacity.iso10300.face_contact.RATIO_AT_TARGET`): no change to
        check. Where the written unloaded TE exceeds ``limit``, its ``unrelieved_ute`` is
        measured too (:func:`~contact.optimize.remedy_check.unrelieved_te_pp`, one more synthesis):
        whether the relief or the generation sets it.
    """
    from contact.optimize.remedy_check import RemedyRecord, check_change, unrelieved_te_pp

    changes = ratio_changes(design)
    if not changes:
        return None
    checks = tuple(check_change(prescribed, c) for c in changes)
    unrelieved = (unrelieved_te_pp(prescribed, memo)[0]
                  if written is not None and written[0] > limit else math.nan)
    return RemedyRecord(checks, *(written if written is not None else (math.nan,) * 2),
                        float(limit), unrelieved, bool(lte_met))


def chosen_check(record):
    """The remedy to apply: the first that passed its check
    (:func:`~contact.optimize.remedy_check.ranked_changes`: the lowest unloaded TE p-p,
    a change that takes the other ratio below its limit last), or None where none did.

    Parameters
    ----------
    record : contact.optimize.remedy_check.RemedyRecord or None
    """
    from contact.optimize.remedy_check import ranked_changes

    if record is None:
        return None
    passed, _ = ranked_changes(record.checks, record.reference_ute, record.limit,
                               record.lte_met)
    return passed[0] if passed else None


def _design_fields(change) -> dict[str, float]:
    """The change as design-data fields (angles [rad]); built from ``field`` and ``value``
    where the change was read back from a case (its ``design`` empty)."""
    if change.design:
        return dict(change.design)
    radians = _FIELDS.get(change.field, ("", "", False))[2]
    return {change.field: math.radians(change.value) if radians else float(change.value)}


def file_value(design, field: str) -> float:
    """A design field as the basic file gives it.

    Parameters
    ----------
    design : geometry.iso23509.design_data.BevelGearDesign
    field : str
        A ``[design]`` field (angles held in [rad]).

    Returns
    -------
    float — [file unit: mm, deg, 1]
    """
    value = float(getattr(design, field))
    return math.degrees(value) if _FIELDS.get(field, ("", "", False))[2] else value


def change_text(field: str, before: float, after: float) -> str:
    """A remedy applied in words: "gear face width b2 28 -> 36.5 mm".

    Parameters
    ----------
    field : str
        The ``[design]`` field (b2, beta_m, k_d, alpha_dD).
    before, after : float — [file unit: mm, deg, 1]
    """
    name, unit, _ = _FIELDS.get(field, (field, "", False))
    return f"{name} {field} {before:.4g} -> {after:.4g}" + (f" {unit}" if unit else "")


def remedied_basic(basic, change):
    """The basic data with a remedy applied, the change said at the end of its ``source``
    (the first sentence of the written case's: "...; remedied by ltca synthesize
    --apply-remedy: gear face width b2 28 -> 36.5 mm, ...").

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
    change : contact.load_capacity.iso10300.face_contact.RatioChange

    Returns
    -------
    geometry.synthesis.basic_design.BasicDesign

    Raises
    ------
    InputError
        A field that is no remedy's (``change.field`` not b2, beta_m, k_d, alpha_dD).
    """
    from geometry.core.errors import InputError

    if change.field not in _FIELDS:
        raise InputError(f"apply_remedy: {change.field!r} is no contact-ratio remedy's "
                         f"field; accepted: {', '.join(_FIELDS)}")
    before = file_value(basic.design, change.field)
    design = dataclasses.replace(basic.design, **_design_fields(change))
    said = (f"remedied by ltca synthesize --apply-remedy: "
            f"{change_text(change.field, before, file_value(design, change.field))}, the "
            "contact-ratio remedy its note checked (contact.optimize.development_remedy; the "
            "basic data otherwise as given)")
    return dataclasses.replace(basic, design=design,
                               source=f"{basic.source.strip().rstrip('.')}; {said}")


def lte_parts(development) -> list[str]:
    """A development's written LTE p-p in words: "drive 86/93 urad at 91.8/612.4 N m" and,
    where its coast flank was checked, "coast 52/78 urad at 91.8/445.5 N m" (light/design).

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
    """
    lte = development.best.metrics["lte_peak_to_peak"]
    light, design = development.torque
    parts = [f"drive {lte[0]:.0f}/{lte[1]:.0f} urad at "
             f"{plain_number(light)}/{plain_number(design)} N m"]
    if development.coast is not None:
        c = development.coast["lte_peak_to_peak"]
        cl, cd = development.coast_design_torques
        parts.append(f"coast {c[0]:.0f}/{c[1]:.0f} urad at "
                     f"{plain_number(cl)}/{plain_number(cd)} N m")
    return parts


def between_parts(development) -> tuple[list[str], float]:
    """A development's largest written LTE p-p between its light and design torque, per
    flank, as ``ltca run``'s ``lte_range`` step judges it: "drive 50.5 urad at 701.1 N m",
    "coast 65.0 urad at 701.1 N m" (its check's records ``lte_range`` and, where the coast
    flank was checked, ``coast_lte_range``; :func:`contact.optimize.development_lte_lines.
    inside`), "coast not judged" where the coast flank was checked without a record.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult

    Returns
    -------
    (parts, worst) : (list of str, float)
        The words (empty where neither flank has a record) and the largest LTE p-p among
        them [µrad] (NaN where none).

    Raises
    ------
    Nothing.

    Notes
    -----
    Issue 71, round 42: ``--apply-remedy``'s lines judged both designs at the light and
    design torques alone ("within the verdict's 60 urad") where the coast flank of the
    spiral bevel 16x35 at Σ 95° read 65.0 µrad as given and 60.3 µrad remedied between
    them, which the same command's coast line and ``ltca run --flank coast`` called above.
    """
    from contact.optimize.development_lte_lines import inside

    flanks = [("drive", getattr(development, "lte_range", None))]
    if getattr(development, "coast", None) is not None:
        flanks.append(("coast", getattr(development, "coast_lte_range", None)))
    parts: list[str] = []
    worst = math.nan
    for flank, record in flanks:
        got = inside(record)
        peak = float(got.get("peak", math.nan)) if got else math.nan
        at = float(got.get("at", math.nan)) if got else math.nan
        if not (math.isfinite(peak) and math.isfinite(at)):
            parts.append(f"{flank} not judged")
            continue
        parts.append(f"{flank} {peak:.1f} urad at {plain_number(at)} N m")
        worst = peak if not math.isfinite(worst) else max(worst, peak)
    if not math.isfinite(worst):
        return [], worst
    return parts, worst


def worst_lte(development) -> float:
    """The largest written LTE p-p [µrad] of a development: drive or (where checked)
    coast, light or design torque.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
    """
    worst = float(max(development.best.metrics["lte_peak_to_peak"]))
    if development.coast is not None:
        worst = max(worst, float(max(development.coast["lte_peak_to_peak"])))
    return worst


def flanks_above(development, level: float) -> tuple[bool, bool | None]:
    """Whether the written drive flank's LTE p-p, and the coast flank's where checked,
    exceeds ``level`` [µrad] at the light or the design torque.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
        Its ``best.metrics["lte_peak_to_peak"]`` (2,) [µrad] and ``coast`` (None where the
        coast flank was not checked, else its ``"lte_peak_to_peak"`` (2,) [µrad]).
    level : float — [µrad]
        The development's target or the verdict's limit.

    Returns
    -------
    (drive, coast) : (bool, bool or None)
        ``coast`` None where the coast flank was not checked.
    """
    drive = float(max(development.best.metrics["lte_peak_to_peak"])) > level
    coast = (None if development.coast is None
             else float(max(development.coast["lte_peak_to_peak"])) > level)
    return drive, coast


def above_limit_text(development, limit: float) -> str:
    """The clause that says which written flank's LTE p-p exceeds the verdict's limit, to
    follow :func:`lte_parts`: "" where none does, ", above the verdict's 60 urad" where
    every flank listed does, else naming the one flank that does (issue 71, round 26c: a
    spiral bevel 17x23 read "drive 31/96 urad at 230.5/1537 N m, coast 26/58 urad at
    110.8/739.3 N m (light/design), ..., above the verdict's 60 urad", its coast within).

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
        Its ``best.metrics["lte_peak_to_peak"]`` (2,) [µrad] at the light and design
        torque and, where checked, ``coast["lte_peak_to_peak"]`` (2,) [µrad].
    limit : float
        The verdict's LTE p-p limit [µrad] (:data:`contact.study.verdicts.LTE_LIMIT`).

    Returns
    -------
    str
        The clause, with its leading comma, or "".
    """
    drive, coast = flanks_above(development, limit)
    if not drive and not coast:
        return ""
    which = ("" if coast is None or (drive and coast)
             else " on the drive flank" if drive else " on the coast flank")
    return f", above the verdict's {limit:g} urad{which}"


def lte_within(development, limit: float) -> bool:
    """Whether a development's written LTE p-p is within the verdict's limit: drive and,
    where checked, coast, at the light and the design torque (:func:`worst_lte`); False
    without a development. A contact-ratio change its check measures no better than that
    design is then no remedy (:func:`~contact.optimize.remedy_check.no_better`).

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult or None
    limit : float — [µrad]
        The verdict's LTE limit (:data:`contact.study.verdicts.LTE_LIMIT`).
    """
    return development is not None and worst_lte(development) <= limit


def every_drive_target(development) -> bool:
    """Whether a development's written drive design met every target of the development
    (its chosen design's ``full`` score, :meth:`contact.optimize.development_result.
    DevelopmentResult.missed_text`'s "every target met"); False where not analysed."""
    full = getattr(development.best, "full", None)
    return bool(full is not None and full[2])


def targets_bought(given, remedied) -> bool:
    """Whether the remedied development meets every drive target where the design as
    given's misses one: what a remedy that lowers the design torque then buys is those
    targets (:func:`torque_given_up`).

    Parameters
    ----------
    given, remedied : contact.optimize.development.DevelopmentResult

    Returns
    -------
    bool
    """
    return every_drive_target(remedied) and not every_drive_target(given)


def _torque_lowered(given, remedied) -> tuple[float, float] | None:
    """(design torque as given, remedied) [N·m] where the remedied one is lower at the
    printed 0.1 N·m, else None (equal, higher, or either not finite)."""
    before, after = float(given.torque[1]), float(remedied.torque[1])
    if not (math.isfinite(before) and math.isfinite(after)) or round(after, 1) >= round(
            before, 1):
        return None
    return before, after


def torque_bought(given, remedied) -> str:
    """Why a remedied design torque below the design as given's was kept: the drive targets
    the remedy bought (:func:`targets_bought`), in numbers; empty where it did not lower
    the design torque, bought none, or gave up more than :data:`REMEDY_TORQUE_FLOOR`
    allows (:func:`below_floor`).

    Parameters
    ----------
    given, remedied : contact.optimize.development.DevelopmentResult
        Their ``torque`` (light, design) [N·m]; the design as given's chosen design's
        ``full`` score names the targets it missed.

    Returns
    -------
    str
        E.g. (the FM hypoid 12×31, round 35) "its design torque 643.8 N m, 0.95 of the
        design as given's 677.1 N m: kept, for the drive targets the design as given
        misses (length, centre_v, tolerance) and it meets".

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (round 35): ``--apply-remedy`` printed both torques without saying
    why the lower one was written.
    """
    lowered = _torque_lowered(given, remedied)
    # below the floor no line: refused where the given LTE keeps the limit, and a trial's
    # torque is the trial's, not bought for targets
    if lowered is None or not targets_bought(given, remedied) or below_floor(given, remedied):
        return ""
    before, after = lowered
    return (f"its design torque {plain_number(round(after, 1))} N m, {after / before:.2f} "
            f"of the design as given's {plain_number(round(before, 1))} N m: kept, for "
            f"the drive targets the design as given misses{_missed_names(given)} and it "
            f"meets (at or above the {REMEDY_TORQUE_FLOOR:.3f} of it a remedy may give up "
            "for targets: one step of the drive LTE window's torques)")


def _missed_names(given) -> str:
    """" (length, centre_v)": the drive targets the design as given's chosen design misses
    (its ``full`` score), empty where it names none."""
    full = getattr(given.best, "full", None)
    missed = [k for k, v in (full[1] if full is not None else {}).items() if v > 0]
    return f" ({', '.join(missed)})" if missed else ""


def _ratio_and_floor(ratio: float) -> tuple[str, str]:
    """A torque ratio and :data:`REMEDY_TORQUE_FLOOR` printed at 3 decimals, more (up to 6)
    where they would print the same: a refusal never reads "0.909 ... below the 0.909"."""
    digits = 3
    while digits < 6 and f"{ratio:.{digits}f}" == f"{REMEDY_TORQUE_FLOOR:.{digits}f}":
        digits += 1
    return f"{ratio:.{digits}f}", f"{REMEDY_TORQUE_FLOOR:.{digits}f}"


def below_floor(given, remedied) -> bool:
    """Whether the remedied design torque is below :data:`REMEDY_TORQUE_FLOOR` × the
    design as given's (both finite; compared unrounded).

    Parameters
    ----------
    given, remedied : contact.optimize.development.DevelopmentResult
        Their ``torque`` (light, design) [N·m].

    Returns
    -------
    bool
        False where either design torque is not finite or the given one is not positive.

    Raises
    ------
    Nothing.
    """
    before, after = float(given.torque[1]), float(remedied.torque[1])
    if not (math.isfinite(before) and math.isfinite(after)) or before <= 0.0:
        return False
    return after < REMEDY_TORQUE_FLOOR * before


def torque_given_up(given, remedied, lte_met: bool) -> str:
    """Why a remedied development is no remedy for a design whose LTE already keeps the
    verdict's limit: its design torque below the design as given's; empty where it is not
    (the design as given's LTE above the limit: the remedy is the trial its note offers,
    whatever its torque; or the remedied design torque at or above the given one).

    Parameters
    ----------
    given, remedied : contact.optimize.development.DevelopmentResult
        The development of the basic data as given and of the remedied basic data (their
        ``torque``: light and design torque [N·m]).
    lte_met : bool
        Whether the design as given's developed LTE p-p is within the verdict's limit
        (:func:`lte_within`, the check record's ``lte_met``).

    Returns
    -------
    str
        The reason in numbers (both design torques [N·m], their ratio), or empty.

    Raises
    ------
    Nothing.

    Notes
    -----
    Why (issue 71, round 34): the FM hypoid 5×48 (ε_vα 0.90, its LTE p-p 35/29 µrad) was
    offered α_dD 22.5 → 16.3° (checked 70 against the written 73 µrad unloaded); ``ltca
    synthesize --apply-remedy`` wrote the remedied design at a design torque of 81.7 N·m,
    0.40 of the design as given's 206.7 (its local pitting capacity: the hypoid factor
    Z_Hyp 0.93 → 0.88 with the lengthwise sliding), and its ``ltca run`` FAILed on
    scuffing (S_B 0.82) where the design as given's passed. A contact-ratio remedy is
    offered for the LTE (``ltca run``'s 60 µrad at every torque); where the design as
    given keeps it, the remedied design must not carry less for it. The design torque is
    each development's own (its ISO capacity or the developed bearing's cut), compared at
    the printed 0.1 N·m.

    Not a refusal where the remedy buys the development's drive targets the design as given
    misses (:func:`targets_bought`) and keeps at least :data:`REMEDY_TORQUE_FLOOR` of its
    design torque (:func:`below_floor`; below it the refusal says the floor, with both
    torques and their ratio: issue 71, remedy99): the torque is then given up for those,
    not for an LTE the design has, and both developments' torques are printed beside their
    LTE (issue 71, round 35: the FM hypoid 12×31 at a = 0.20 d_e2, its LTE 27/34 µrad,
    missed the pattern length 0.65 and centre v 0.64 and was not tolerant at ±0.05 mm; its
    b2 32 → 36 mm met every drive target, tolerant, at 643.8 N·m, 0.95 of its 677.1, and
    was refused as giving up load "for an LTE the design has").
    """
    lowered = _torque_lowered(given, remedied)
    if not lte_met or lowered is None:
        return ""
    before, after = lowered
    if targets_bought(given, remedied):
        if not below_floor(given, remedied):
            return ""
        ratio, floor = _ratio_and_floor(after / before)
        return (f"its design torque {plain_number(round(after, 1))} N m, "
                f"{ratio} of the design as given's "
                f"{plain_number(round(before, 1))} N m: below the {floor} "
                "of it a remedy may give up for targets (one step of the drive LTE window's "
                "torques, 1/1.1), though it meets the drive targets the design as given "
                f"misses{_missed_names(given)}")
    return (f"its design torque {plain_number(round(after, 1))} N m is below the design as "
            f"given's {plain_number(round(before, 1))} N m ({after / before:.2f} of it), "
            "whose LTE p-p is within the verdict's limit already "
            f"({', '.join(lte_parts(given))}): the remedy would give up load for an LTE the "
            "design has")


def _refused_text(record) -> str:
    """Why no change is applied: each one's refusal (:func:`~contact.optimize.remedy_check.
    refusal`)."""
    from contact.optimize.remedy_check import ranked_changes

    _, refused = ranked_changes(record.checks, record.reference_ute, record.limit,
                                record.lte_met)
    return "; ".join(f"{c.change.text}: {why}" for c, why in refused)


def developed_with_remedy(run: Callable[[Any], Any], basic,
                          say: Callable[[str], None] | None = None):
    """The development of the remedied basic data: the design as given developed
    (``run(basic)``), its contact-ratio remedies checked at its written prescriptions
    (:func:`checked_record`, the note's check), the best that passed applied
    (:func:`chosen_check`, :func:`remedied_basic`) and that design developed.

    Parameters
    ----------
    run : callable BasicDesign → DevelopmentResult
        The development (:func:`contact.optimize.development.develop` without
        ``apply_remedy``).
    basic : geometry.synthesis.basic_design.BasicDesign
        The user's basic data.
    say : callable, optional
        Called with a line before each development.

    Returns
    -------
    contact.optimize.development.DevelopmentResult
        The remedied design's development, its ``remedy`` the :class:`AppliedRemedy`
        (its ``basic`` the remedied basic data as given).

    Raises
    ------
    InputError
        Before any work: no contact ratio of ``basic`` below its limit, or each at it
        (nothing to remedy). After the first development: no change passed its check
        (each refusal said, a change no better than the design as given among them where
        its LTE is within the verdict's limit:
        :func:`~contact.optimize.remedy_check.no_better`); the design as given is then not
        returned in place of a remedied one. After the remedied development: the design as
        given's LTE within the verdict's limit and the remedied design torque below its
        own (:func:`torque_given_up`), unless the remedy buys the drive targets the design
        as given misses at :data:`REMEDY_TORQUE_FLOOR` of its torque or more; or ``ltca
        run``'s verdict of the remedied design worse than the design as given's on a
        finding of either flank (:func:`~contact.optimize.development_remedy_verdict.
        verdict_worse`: a FAIL, an LTE above the limit, a plastic share, a light-torque
        edge, judged on both developments' measurements).

    Notes
    -----
    Two developments (about twice ``ltca synthesize``'s CPU) and one synthesis without
    tip planes per change checked (0.5-1 s each); where the remedied development's drive
    LTE p-p is above the verdict's limit over ``ltca run``'s torques, the next checked
    remedy developed too (:func:`~contact.optimize.development_remedy_next.next_remedies`,
    at most :data:`~contact.optimize.development_remedy_next.NEXT_REMEDIES` more full
    developments) and the better kept, each remedy developed recorded in the result's
    :class:`AppliedRemedy`. The change reaches its ratio's limit on
    ISO 10300-1's virtual gears (ISO 23509 blank); its LTE is the remedied design's own
    development, never estimated (docs/own_gear_set.md, "The overlap change is a trial").
    """
    from contact.load_capacity.iso10300.face_contact import RATIO_AT_TARGET
    from contact.optimize.development_remedy_next import next_remedies
    from contact.optimize.development_remedy_verdict import verdict_worse
    from contact.optimize.remedy_check import ranked_changes, unloaded_te_pp
    from contact.study.verdicts import LTE_LIMIT
    from geometry.core.errors import InputError, ModelUnavailableError

    said = say or (lambda line: None)
    before = contact_ratios_of(basic.design)
    if not ratio_changes(basic.design):
        raise InputError(
            f"apply_remedy: no contact ratio of this design is below its limit (eps_va "
            f"{before[0]:.2f}, eps_vb {before[1]:.2f}; limits 1 / 1.25, AGMA 2005-D03; one "
            f"within {RATIO_AT_TARGET:g} below it is at it): "
            "there is no contact-ratio remedy to apply; develop it without apply_remedy "
            "(ltca synthesize without --apply-remedy)")
    said("apply_remedy: the design as given developed first (its remedies are checked at "
         "its written prescriptions)")
    first = run(basic)
    try:
        written: tuple[float, float] | None = unloaded_te_pp(first.case)[:2]
    except (InputError, ModelUnavailableError, ValueError) as exc:
        log.info("the written case's unloaded TE not measured: %s", exc)
        written = None
    record = checked_record(prescribed_basic(basic, first.case, first), basic.design,
                            written, LTE_LIMIT, lte_within(first, LTE_LIMIT),
                            memo=getattr(first, "memo", None))
    chosen = chosen_check(record)
    if chosen is None:
        raise InputError(
            "apply_remedy: no contact-ratio remedy passed its check by a synthesis at the "
            f"written prescriptions ({_refused_text(record)}); nothing written: the design "
            "as given is developed and written without apply_remedy (ltca synthesize "
            "without --apply-remedy), its note says why each change is refused")
    given: dict[int, Any] = {}  # the remedied basic data each development was given

    def remedied(check):
        given[id(check)] = remedied_basic(basic, check.change)
        return given[id(check)]

    def text(check) -> str:
        return change_text(check.change.field, file_value(basic.design, check.change.field),
                           file_value(remedied_basic(basic, check.change).design,
                                      check.change.field))

    said(f"apply_remedy: {text(chosen)} applied; the remedied design developed")
    second = run(remedied(chosen))
    # where that development misses the drive LTE limit over `ltca run`'s torques, the next
    # checked remedy developed and the better kept (development_remedy_next)
    passed, _ = ranked_changes(record.checks, record.reference_ute, record.limit,
                               record.lte_met)
    chosen, second, developed, why = next_remedies(
        (chosen, second), [c for c in passed if c is not chosen],
        lambda check: run(remedied(check)), text, LTE_LIMIT, said)
    given_up = torque_given_up(first, second, record.lte_met)
    if given_up:
        raise InputError(
            f"apply_remedy: {text(chosen)} developed: {given_up}; nothing written: the "
            "design as given is developed and written without apply_remedy (ltca "
            "synthesize without --apply-remedy)")
    # the written case judged as `ltca run` judges it, both flanks, on what both
    # developments measured: a remedy whose verdict is worse is not written
    cpu = cpu_seconds()
    worse = verdict_worse(first, second, LTE_LIMIT)
    log.info("apply_remedy: the remedied design's verdict judged against the design as "
             "given's in %.4f s CPU%s", cpu_seconds() - cpu,
             f": worse ({worse})" if worse else ": no worse")
    if worse:
        raise InputError(
            f"apply_remedy: {text(chosen)} developed: ltca run's verdict of the remedied "
            f"design would be worse than the design as given's ({worse}); nothing written: "
            "the design as given is developed and written without apply_remedy (ltca "
            "synthesize without --apply-remedy)")
    kept = given[id(chosen)]
    between, between_worst = between_parts(first)
    applied = AppliedRemedy(chosen, record, kept, file_value(basic.design, chosen.change.field),
                            before, contact_ratios_of(kept.design),
                            ", ".join(lte_parts(first)), worst_lte(first), developed, why,
                            torque_bought(first, second), ", ".join(between), between_worst,
                            float(getattr(first, "seconds", math.nan)))
    return dataclasses.replace(second, remedy=applied)


def applied_table(applied: AppliedRemedy) -> dict[str, Any]:
    """The written case's informational :data:`REMEDY_TABLE` table (TOML-safe: a value not
    measured is left out).

    Parameters
    ----------
    applied : AppliedRemedy

    Returns
    -------
    dict
        ``note``, ``field``, ``before``, ``after`` [file unit], ``text`` (the note's
        phrase), the contact ratios before and after, the design as given's LTE p-p
        (``given_lte``, ``given_worst_lte_urad``; between its torques ``given_between``,
        ``given_between_worst_lte_urad`` where recorded), where more than one remedy was
        developed each of them (``developed``: torques, LTE p-p, its peak over ``ltca
        run``'s torques, CPU, why not kept) and why the applied one was kept
        (``kept_why``), and ``checks``: every change checked
        (:func:`~contact.optimize.remedy_check.remedy_record`).
    """
    from contact.optimize.remedy_check import remedy_record

    change = applied.check.change
    ratios = {"eps_va_before": applied.ratios_before[0], "eps_vb_before":
              applied.ratios_before[1], "eps_va_after": applied.ratios_after[0],
              "eps_vb_after": applied.ratios_after[1],
              "given_worst_lte_urad": applied.given_worst,
              "given_between_worst_lte_urad": applied.given_between_worst}
    return {"note": "informational (contact.optimize.development_remedy): the contact-ratio "
                    "remedy ltca synthesize --apply-remedy applied to the user's basic data, "
                    "checked by a synthesis at the written prescriptions of the design as "
                    "given; this case is the remedied design's development",
            "field": change.field, "before": round(float(applied.before), 6),
            "after": round(file_value(applied.basic.design, change.field), 6),
            "text": change.text,
            **{k: round(float(v), 3) for k, v in ratios.items() if math.isfinite(v)},
            "given_lte": applied.given_lte,
            **({"given_between": applied.given_between} if applied.given_between else {}),
            **({"developed": [_developed_row(d) for d in applied.developed],
                "kept_why": applied.kept_why} if len(applied.developed) > 1 else {}),
            **({"torque_why": applied.torque_why} if applied.torque_why else {}),
            "checks": remedy_record(applied.record)}


def _developed_row(d) -> dict[str, Any]:
    """One remedy developed (:class:`~contact.optimize.development_remedy_next.
    RemedyDeveloped`) as a TOML-safe row (a value not measured left out)."""
    numbers = {"light_torque": d.torques[0], "design_torque": d.torques[1],
               "lte_light_urad": d.lte[0], "lte_design_urad": d.lte[1],
               "range_peak_urad": d.peak, "range_peak_at": d.at, "cpu_s": d.seconds}
    return {"text": d.text, "field": d.field,
            **{k: round(float(v), 3) for k, v in numbers.items() if math.isfinite(v)},
            "why_not_kept": d.why}
