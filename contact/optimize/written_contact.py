"""``ltca synthesize``'s check that the case it is about to write can be analysed: the
unloaded contact of its flanks computed as ``ltca run`` and ``ltca utca`` compute it first
(the ease-off and its contouring splines), so that the command never writes a case that no
analysis accepts.

Found on the spiral bevel 12×12 miter at β_m 35° with a 5-in cutter (round 17 of the unseen
designs, ``benchmarks/data/unseen_designs/spiral_bevel_12x12_miter_b35_rc63p5.toml``,
ε_vβ 0.56): ``ltca synthesize --no-development`` wrote its case and ``ltca run`` /
``ltca utca`` then refused it, "contact curves: the roll-angle surface is not monotone …"
(:class:`contact.utca.fields.EaseOffFields`).
"""

from __future__ import annotations


def unloaded_contact_failure(case, flank: str = "drive") -> str | None:
    """Why the unloaded contact of one flank of ``case`` cannot be computed, or None where
    it can: the ease-off (:func:`contact.utca.easeoff.ease_off`, the case's own
    misalignment), its splines (:func:`contact.utca.fields.fields_of`) and the unloaded
    cycle (:func:`contact.utca.datasets.unloaded_tca` as ``ltca run``'s chain calls it:
    a roll where no tooth pair is in contact), the first steps of ``ltca run``'s and
    ``ltca utca``'s analysis, which raise the same errors.

    Parameters
    ----------
    case : geometry.case.Case
        The case to write.
    flank : {"drive", "coast"}
        The flank checked (``ltca run`` and ``ltca utca`` analyse ``"drive"`` by default).

    Returns
    -------
    str or None
        The analysis' own error message (e.g. "contact curves: the roll-angle surface is
        not monotone along the profile direction …"), None where the contact is computed.

    Raises
    ------
    InputError
        ``flank`` not "drive" or "coast" (from :func:`contact.utca.easeoff.ease_off`).

    Notes
    -----
    Source: the analysis' own construction (seed §2.3.2, §4.2: ease-off, surface of roll
    angle), called as the analysis calls it; both results are memoised per process, so
    the analyses that follow (the notes' unloaded TE, ``ltca run`` in a notebook) reuse
    them. CPU measured on the loaded 2-core machine, drive and coast flanks together:
    0.20 s (the 12×12 miter's refusal), 0.24 s (the default 11×41 without the
    development), 0.18 s (after its development, of 40.7 s).
    """
    from contact.utca.datasets import unloaded_tca
    from contact.utca.easeoff import ease_off
    from contact.utca.fields import fields_of
    from geometry.core.errors import InputError, ModelUnavailableError

    if flank not in ("drive", "coast"):
        raise InputError(f"flank: must be 'drive' or 'coast', got {flank!r}")
    try:
        eo = ease_off(case, flank=flank)
        fields_of(eo)
        # the unloaded cycle as `ltca run`'s chain computes it (its defaults, memoised):
        # the 15x15 hypoid's --no-development case had an ease-off and its splines, and
        # `ltca run` then stopped at "no tooth pair in contact at roll 0.414909 rad"
        # (issue 71, branch ratio95: its pinion's drive flank generated over 67 % of
        # the blank)
        unloaded_tca(case, flank=flank, easeoff=eo)
    except (ValueError, ModelUnavailableError) as exc:  # InputError is a ValueError
        return str(exc)
    return None


def refusal_text(case, design, why: str, basic=None) -> str:
    """``ltca synthesize``'s error where the drive flank's unloaded contact of the case it
    made cannot be computed: what failed, that no case is written, and the remedies the
    notes know — the contact ratios below their limits with the basic-file changes that
    reach them (:func:`contact.load_capacity.iso10300.face_contact.low_ratio_text` at the
    limits of ``ltca synthesize``'s note; a tooth-count remedy checked by a synthesis of
    the counts where ``basic`` is given, :func:`contact.optimize.development_conjugacy.
    teeth_checker`), and the cutter radius.

    Parameters
    ----------
    case : geometry.case.Case
        The case made (its drive flank, gear process).
    design : geometry.iso23509.design_data.BevelGearDesign
        The basic design's ISO 23509 data (``rc0`` [mm], for the contact ratios).
    why : str
        :func:`unloaded_contact_failure`'s message.
    basic : geometry.synthesis.basic_design.BasicDesign, optional
        The basic data: where the pinion's drive flank is not generated over its working
        depth (said first, "First: …"), the tooth count that generates it is checked by
        syntheses of it (:func:`contact.optimize.development_conjugacy.checked_teeth_text`).

    Returns
    -------
    str
        E.g. "the unloaded contact of the synthesised case's drive flank
        (pinion concave) cannot be computed, so `ltca run` and `ltca utca` would refuse
        the case: contact curves: …; no case written. Changes to try: face contact ratio eps_vb
        0.56 is below 1.25 …; another cutter radius rc0 (now 63.5 mm; …) (…)".

    Notes
    -----
    Source: the 12×12 miter of round 17 (module docstring); its 3.5-in cutter was refused
    by every gear process and its 5-in one gave this case: the cutter radius and the face
    contact ratio (docs/own_gear_set.md, round 17) are what the notes know to change.
    """
    from contact.load_capacity.iso10300.face_contact import low_ratio_text
    from contact.optimize.development_conjugacy import teeth_checker
    from contact.optimize.written_notes import (
        FACE_CONTACT_RATIO_NOTE,
        PROFILE_CONTACT_RATIO_NOTE,
    )
    from geometry.core.errors import InputError

    flank = case.pair.drive_flank
    try:
        ratios = low_ratio_text(design, FACE_CONTACT_RATIO_NOTE, PROFILE_CONTACT_RATIO_NOTE,
                                teeth_check=None if basic is None else teeth_checker(basic))
    except (InputError, ValueError, ZeroDivisionError):
        ratios = None
    limited = _generation_cause(case, basic)
    changes = [ratios] if ratios else []
    rc0 = getattr(design, "rc0", None)
    if rc0 is not None:
        changes.append(f"another cutter radius rc0 (now {rc0:g} mm; the flanks' "
                       "lengthwise curvature and the bearing's path follow it)")
    return (f"the unloaded contact of the synthesised case's drive flank "
            f"(pinion {flank}) cannot be computed, so `ltca run` and `ltca utca` would "
            f"refuse the case: {why}; no case written. "
            + ("" if limited is None else f"First: {limited}. ")
            + "Changes to try: "
            + "; ".join(changes) + " (docs/own_gear_set.md, round 17)")


def _generation_cause(case, basic=None) -> str | None:
    """The generation limit of the case's pinion drive flank in words
    (:func:`contact.optimize.development_conjugacy.generation_limit_text`), said before the
    changes to try; None where the flank is generated over its working depth or cannot be
    generated at all. Found on the 15x15 hypoid of issue 71 (branch ratio95): its
    ``--no-development`` case lost contact at a roll, its pinion's drive flank generated
    over 67 % of the blank."""
    from contact.optimize.development_conjugacy import (
        checked_teeth_text,
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
    return generation_limit_text(found, None,
                                 "" if basic is None else checked_teeth_text(basic))


def coast_note(case) -> str | None:
    """``ltca synthesize``'s note where the coast flank's unloaded contact of the written
    case cannot be computed (``ltca run --flank coast`` refuses it; the drive flank is
    analysed): None where it can.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    str or None

    Notes
    -----
    Source: :func:`unloaded_contact_failure` on the coast flank.
    """
    why = unloaded_contact_failure(case, "coast")
    if why is None:
        return None
    return (f"the coast flank's unloaded contact cannot be computed: {why}; `ltca run "
            "--flank coast` refuses the case (the drive flank is analysed)")


def checked_contact(case, design, basic=None) -> list[str]:
    """``ltca synthesize``'s check of the case it is about to write: refused where its
    drive flank's unloaded contact cannot be computed (:func:`unloaded_contact_failure`,
    :func:`refusal_text`), the coast flank's failure a note.

    Parameters
    ----------
    case : geometry.case.Case
    design : geometry.iso23509.design_data.BevelGearDesign
    basic : geometry.synthesis.basic_design.BasicDesign, optional
        For :func:`refusal_text`'s checked lever.

    Returns
    -------
    list of str
        The notes (each without its "note: "): :func:`coast_note`'s, where it has one.

    Raises
    ------
    InputError
        The case cannot be written as TOML (a value TOML cannot hold, its key named:
        said as that, not as the unloaded contact's failure, which the analyses' memo of
        the case's text would raise the same), or the drive flank's unloaded contact cannot
        be computed (the message: :func:`refusal_text`).

    Notes
    -----
    Source: the analysis' own construction (:func:`unloaded_contact_failure`). The FM
    spiral bevel 14x19 at Sigma 60 (branch unseen98) was refused as "the unloaded contact
    … cannot be computed …: to_toml: non-finite value nan" for a NaN in its informational
    ``[development]`` table.
    """
    from geometry.core.errors import InputError

    try:
        case.to_toml()
    except InputError as exc:
        raise InputError(f"the synthesised case cannot be written: {exc}; no case "
                         "written") from None
    why = unloaded_contact_failure(case, "drive")
    if why is not None:
        raise InputError(refusal_text(case, design, why, basic))
    coast = coast_note(case)
    return [] if coast is None else [coast]
