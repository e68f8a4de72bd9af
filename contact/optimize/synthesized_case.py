"""The case ``ltca synthesize`` writes of a basic design, and the lines it says, for the
Python API alike (issue 71, branch api88).

:func:`synthesize_case` is the command's whole sequence without the file: the basic data
checked, developed (or only synthesised), the case with the rating's torques
(:func:`contact.optimize.development_written.written_case`), refused where its drive
flank's unloaded contact cannot be computed
(:func:`contact.optimize.written_contact.checked_contact`), the contact-ratio remedies'
record (:func:`contact.optimize.written_notes.noted_case`), the header and the outcome
lines. ``ltca synthesize`` calls it, writes :attr:`SynthesizedCase.text` and prints
:meth:`SynthesizedCase.lines`; a script gets the same text and lines.

Public names
------------
SynthesizedCase, synthesize_case
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from geometry.case import Case
from geometry.core.text import plain_number


@dataclass(frozen=True)
class SynthesizedCase:
    """The case ``ltca synthesize`` writes and what it says.

    Attributes
    ----------
    case : geometry.case.Case
        The case written: the developed case with the rating's torques and, where a
        contact ratio is low, the remedies' record
        (:data:`contact.optimize.remedy_check.RECORD_TABLE`).
    text : str
        The file's text: :func:`contact.optimize.written_notes.header_text` and
        ``case.to_toml()``.
    head : tuple of str
        The lines said before the file is written (the cause and remedy first, the
        design, its torques, contact ratios and LTE).
    notes : tuple of str
        The lines said after it (each "note: ..."), empty where there is nothing to note.
    development : contact.optimize.development_result.DevelopmentResult or None
        The development (None with ``development=False``).
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic data written: the remedied where a remedy was applied.
    scuffing : dict
        After a development, per flank (``"drive"``, ``"coast"``) the LTCA's scuffing
        safety at its design torque and the case's operation
        (:class:`contact.optimize.written_scuffing.DesignScuffing`: ``.safety`` S_B [1],
        ``.torque`` [N·m], ``.remedy_safety``), None (pinion speed 0: no S_B) or the
        text of what stopped its analysis; empty without a development. The case records
        it in ``[development.scuffing]``.
    scuffing_notes : tuple of str
        The scuffing lines in :attr:`head` (without their "note: "): one per flank whose
        S_B is below the verdict's minimum (``ltca run`` of the case FAILs on it) or
        whose check failed; empty otherwise.
    """

    case: Case
    text: str
    head: tuple[str, ...]
    notes: tuple[str, ...]
    development: Any
    basic: Any
    scuffing: dict = dataclasses.field(default_factory=dict)
    scuffing_notes: tuple[str, ...] = ()

    def lines(self, path: str | os.PathLike[str] | None = None) -> list[str]:
        """The lines ``ltca synthesize`` prints on standard output: :attr:`head`,
        "wrote <path>" (where ``path`` is given) and :attr:`notes`."""
        wrote = [] if path is None else [f"wrote {path}"]
        return [*self.head, *wrote, *self.notes]


def _check_apply(apply_remedy: bool, development: bool) -> None:
    """``apply_remedy`` refused without a development, before the work."""
    from geometry.core.errors import InputError

    if apply_remedy and not development:
        raise InputError("--apply-remedy: the remedy is checked at the developed design's "
                         "written prescriptions and the remedied design is developed; it "
                         "cannot be combined with --no-development")


def _developed(basic, apply_remedy: bool, progress, synthesis_progress):
    """(development, the basic data written, its targets): the development of ``basic``
    to its ``[development]`` targets or, with ``apply_remedy``, that of the remedied basic
    data (:func:`contact.optimize.development_remedy.developed_with_remedy`; each design's
    own targets, its µm amounts following its size)."""
    from contact.optimize import development as dev
    from contact.optimize.development import targets_from_table
    from contact.optimize.written_notes import size_scale

    # the µm amounts follow the design's size
    targets = targets_from_table(basic.development, size_scale=size_scale(basic))
    found = dev.develop(basic, targets=None if apply_remedy else targets,
                        progress=progress, synthesis_progress=synthesis_progress,
                        apply_remedy=apply_remedy)
    if found.remedy is not None:
        return found, found.remedy.basic, found.targets
    return found, basic, targets


def _basic_of(basic, shown: str | None):
    """(basic design, its name as shown): a path loaded, a design as given."""
    from geometry.synthesis.basic_design import load_basic

    if isinstance(basic, (str, os.PathLike)):
        shown = shown if shown is not None else os.fspath(basic).replace(os.sep, "/")
        return dataclasses.replace(load_basic(basic), path=shown), shown
    shown = shown if shown is not None else str(getattr(basic, "path", "") or "basic")
    return basic, shown


def synthesize_case(basic, *, fe_level: str | None = None, development: bool = True,
                    apply_remedy: bool = False,
                    progress: Callable[[str], None] | None = None,
                    synthesis_progress: Any = None,
                    shown: str | None = None) -> SynthesizedCase:
    """The case ``ltca synthesize BASIC`` writes and the lines it prints, without writing
    it (``ltca synthesize`` is this function, the file and the printing).

    Parameters
    ----------
    basic : str, os.PathLike or geometry.synthesis.basic_design.BasicDesign
        The basic design file (TOML, docs/synthesis.md) or its loaded data.
    fe_level : str, optional
        The FE level of the root-stress checks (``--fe-level``,
        :data:`contact.compliance.fe.options.LEVELS`); default the basic file's
        ``[root_stress] fe_level``, else ``"coarse10"``.
    development : bool
        Develop the bearing to the ``[development]`` targets (default); False writes the
        local synthesis as prescribed (``--no-development``).
    apply_remedy : bool
        ``--apply-remedy``: where a contact ratio is below its limit, develop and write
        the checked remedy's design (contact.optimize.development_remedy).
    progress : callable, optional
        Called with each development progress line (``ltca synthesize`` prints them on
        stderr). Default: logged at INFO by :func:`contact.optimize.development.develop`,
        shown by ``logging.basicConfig(level=logging.INFO)``; ``progress=print`` prints
        them. Without either the call is silent for its whole run (a new design's
        development takes 30-120 s of CPU; round 30 of docs/own_gear_set.md).
    synthesis_progress : optional
        The synthesis' step progress (the command's step lines).
    shown : str, optional
        The basic file's name in the header and the lines; default the path as given
        (a loaded design: its ``path``).

    Returns
    -------
    SynthesizedCase
        The case, its text (header and TOML: what ``ltca synthesize`` writes), its lines
        and the development.

    Raises
    ------
    InputError
        A bad basic design (named field), a bad ``fe_level`` (with the levels),
        ``apply_remedy`` without a development, a synthesis no gear process made, or a
        case whose drive flank's unloaded contact cannot be computed
        (:func:`contact.optimize.written_contact.checked_contact`).

    Notes
    -----
    Source: ``ltca synthesize`` (issue 71, round 28 of docs/own_gear_set.md: the API's
    ``written_case()`` lacked the remedies' record and the notes); docs/api.md. After a
    development each flank's scuffing safety at its design torque (the coast flank's
    ``[rating] coast_design_torque`` where it is lower) and the case's operation is
    computed as ``ltca run`` (``--flank coast``) computes it, recorded in the case's
    ``[development.scuffing]`` table and :attr:`SynthesizedCase.scuffing`, and said under
    the development's line, one line per flank, where ``ltca run`` would FAIL on it
    (:attr:`SynthesizedCase.scuffing_notes`; :mod:`contact.optimize.written_scuffing`; two
    more LTCAs at one torque each; docs/synthesis.md, "Scuffing at the design torque").
    """
    import tomllib

    from contact.compliance.fe.options import LEVELS
    from contact.load_capacity.iso10300.capacity import (
        with_coast_design_torque,
        with_design_torque,
    )
    from contact.load_capacity.iso10300.inputs import RatingInputs
    from contact.optimize.development_written import COAST_CAPACITY_WHY, written_case
    from contact.optimize.written_contact import checked_contact
    from contact.optimize.written_notes import (
        checked_basic_rating,
        fe_level_notes,
        first_lines,
        header_text,
        noted_case,
        synthesis_fe_level,
    )
    from geometry.case import case_from_dict
    from geometry.core.errors import InputError
    from geometry.machine.relief import ReliefError
    from geometry.synthesis.case_synthesis import relief_for_profile, synthesize

    if fe_level is not None and fe_level not in LEVELS:
        raise InputError(f"--fe-level: must be one of {', '.join(LEVELS)} (the FE model "
                         f"of the root stress, docs/fe.md), got {fe_level!r}")
    basic, shown = _basic_of(basic, shown)
    # the FE level of the root-stress checks, written into every case the development
    # synthesises (and the one written): the basic file's or fe_level, else coarse10
    basic = dataclasses.replace(basic, root_stress={"fe_level": synthesis_fe_level(
        basic, fe_level)})
    if basic.rating:  # a bad [rating] table refused before the work (rating.<field>)
        checked_basic_rating(basic.rating, RatingInputs.from_mapping)
    _check_apply(apply_remedy, development)
    found = targets = None
    raised: list[str] = []  # default reliefs raised to the blade profile's need
    while True:
        try:
            if development:
                found, written_basic, targets = _developed(basic, apply_remedy, progress,
                                                           synthesis_progress)
                case, report = found.case, found.report
            else:
                (case, report), written_basic = (synthesize(basic,
                                                            progress=synthesis_progress),
                                                 basic)
            break
        except ReliefError as exc:
            adjusted = relief_for_profile(basic, exc)
            if adjusted is None or len(raised) >= 4:
                raise
            value = getattr(adjusted.options.flank(exc.flank), exc.field)
            raised.append(f"synthesis.{exc.flank}.{exc.field} {1e3 * value:.4g} um (the "
                          f"default, raised: the blade's circular profile turns "
                          f"{1e3 * exc.least:.3g} um from its tangent over the relief)")
            basic = adjusted
    basic = written_basic  # the basic data written: the remedied where one was applied
    if found is not None:  # the one sequence DevelopmentResult.written_case calls too
        written = written_case(found, basic.options.design_torque)
        case, torque, torque_why = written.case, written.torque, written.torque_why
        coast_torque, coast_why = written.coast_torque, written.coast_why
    else:
        case, torque, torque_why = with_design_torque(case, basic.options.design_torque)
        case, coast_torque = with_coast_design_torque(case)
        coast_why = COAST_CAPACITY_WHY
    # a case no analysis accepts is not written: its drive flank's unloaded contact
    # computed as `ltca run` computes it first (the 12x12 miter with a 5-in cutter of
    # round 17 was written and then refused); the coast flank's noted
    coast = checked_contact(case, basic.design, basic)
    case, ratios, notes, record = noted_case(basic, case, found)
    notes += coast + fe_level_notes(found, case)
    scuffing = None
    if found is not None:
        # the development's "every target met" is the bearing's: each flank's scuffing
        # safety at its design torque as `ltca run` (--flank coast) computes it, recorded
        # in the [development] table and said under the development's line where `ltca
        # run` of the written case FAILs on it (issue 71, branches scuff99, scuff100)
        scuffing = _scuffing(case, torque)
        case = scuffing.case
    text = header_text(shown, case.gear.process) + case.to_toml()
    # the written text must load back to the same case
    case_from_dict(tomllib.loads(text))
    head = [*first_lines(basic, found, record, shown),
            *_summary_lines(case, report, basic, found, targets, raised,
                            (torque, torque_why, coast_torque, coast_why), ratios)]
    if scuffing is not None and scuffing.lines:
        at = next((i + 1 for i, line in enumerate(head)
                   if line.startswith("  development:")), len(head))
        head[at:at] = ["note: " + line for line in scuffing.lines]
    return SynthesizedCase(case, text, tuple(head),
                           tuple(_note_lines(basic, report, notes, shown)), found, basic,
                           {} if scuffing is None else dict(scuffing.found),
                           () if scuffing is None else scuffing.lines)


def _summary_lines(case, report, basic, found, targets, raised, torques,
                   ratios) -> list[str]:
    """The lines between the cause-and-remedy lines and "wrote": the design, each pinion
    flank's settings, the torques, the contact ratios, the size, the raised reliefs, the
    development's headline and LTE lines and the gear process note."""
    from contact.optimize.written_notes import (
        design_torque_line,
        gear_process_note,
        given_coast_torque,
        given_torque_note,
        size_line,
        written_lte_lines,
    )

    torque, torque_why, coast_torque, coast_why = torques
    geom = report.blank
    out = [f"{case.name}: {geom.design.z1}x{geom.design.z2}, offset {geom.design.a:g} mm, "
           f"beta_m {math.degrees(geom.pinion.beta_m):.2f}/"
           f"{math.degrees(geom.gear.beta_m):.2f} deg, R_e {geom.pinion.Re:.2f}/"
           f"{geom.gear.Re:.2f} mm"]
    for flank, fs in report.flanks.items():
        s = fs.tools.settings
        out.append(f"  pinion {flank}: r_p {fs.tools.blade.point_radius:.3f} mm, R_a "
                   f"{s.ratio_of_roll:.5f}, S_r {s.radial_setting:.3f} mm, E_m "
                   f"{s.blank_offset:.3f} mm, curvature residual "
                   f"{fs.tools.shape_error:.1e} 1/mm")
    out.append(design_torque_line(torque, torque_why, found))
    if math.isfinite(coast_torque):
        out.append(f"  coast design torque: {plain_number(coast_torque)} N m, {coast_why}")
    elif (given_coast := given_coast_torque(case)) is not None:
        # a coast torque the basic file gives was written without a line (round 24's
        # 14x39 FH: 200 N m in the case, said only by the development's lines)
        out.append(f"  coast design torque: {plain_number(given_coast)} N m, given "
                   "([rating] coast_design_torque of the basic file)")
    given = torque_why.startswith(("[synthesis] design_torque", "[rating] design_torque"))
    above = given_torque_note(case, torque, found) if given else None
    if above is not None:
        out.append("note: " + above)
    if ratios is not None:
        out.append(f"  contact ratios (ISO 10300-1 virtual cylindrical gears): profile "
                   f"eps_va {ratios[0]:.2f}, face eps_vb {ratios[1]:.2f}, total "
                   f"{sum(ratios):.2f}")
    size = size_line(basic, targets)
    if size is not None:
        out.append(size)
    out.extend("  " + line for line in raised)
    if found is not None:
        out.append("  " + found.headline())
        # each flank's LTE at its torques and the largest between them where it misses
        # the target or the verdict's limit (issue 71: "at every torque")
        out.extend("  " + line for line in written_lte_lines(case, found))
    process = gear_process_note(found, case)
    if process is not None:
        out.append("note: " + process)
    return out


def _scuffing(case, torque: float):
    """Both flanks' scuffing check of the written case, recorded in it
    (:func:`contact.optimize.written_scuffing.checked_scuffing`)."""
    from contact.optimize.written_scuffing import checked_scuffing

    return checked_scuffing(case, torque)


def _note_lines(basic, report, notes: list[str], shown: str) -> list[str]:
    """The lines after "wrote": the face width note, the LTE and contact notes, and the
    ``[optimize]`` table's."""
    from contact.load_capacity.iso10300.face_contact import face_width_text

    geom = report.blank
    wide = face_width_text(float(geom.design.b2), float(geom.gear.Re), float(geom.met2))
    if wide is not None:
        notes = [wide, *notes]
    out = ["note: " + line for line in notes]
    if basic.optimize:
        out.append(f"note: {shown} carries an [optimize] table: the synthesis alone is "
                   f"written; `ltca optimize {shown}` also optimises the settings it names "
                   "(the bundled case of that name is that optimisation's result)")
    return out
