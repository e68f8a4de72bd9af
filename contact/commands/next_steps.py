"""What a FAIL verdict prints next: commands that answer its findings, never one whose
result it has already seen fail.

``ltca run`` prints, under a FAIL on the bearing (plastic or edge contact, flank pressure),
an ``ltca optimize`` of the flank's settings and relief (:func:`bearing_lines`). A case
that *is* such an optimisation's result records it (its ``[optimize]`` table: the flank,
the variables, the command); when ``ltca run`` of it FAILs again, printing the same
optimisation would send the user round in a circle. So the lines read the provenance: an
optimisation over the same variables is answered by a wider set (the first-order modified
roll 2C and helical motion H1: bias and lengthwise position, docs/optimize.md), and once
that too is the case's own, by no ``ltca optimize`` at all — the bearing's re-development
from its basic data, the V–H check, and a lower torque (``ltca rate``).

``ltca duty-cycle`` prints :func:`duty_cycle_lines` under its FAIL: the bin that does most
of the damage, analysed as ``ltca run`` (whose verdict then says what answers it), and the
rating at that torque.

Public functions
----------------
optimised_variables   the variables of the optimisation a case is the result of
static_flank_strength the static contact strength the verdict's flank check uses [MPa]
bearing_lines         the next-step lines of a bearing finding
duty_cycle_lines      the next-step lines of a FAILed duty cycle
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from geometry.core.text import plain_number

__all__ = ["bearing_lines", "duty_cycle_lines", "optimised_variables", "overlap_lines",
           "static_flank_strength"]

#: the wider set offered once the bearing variables' optimisation is the case's own, with
#: their half-range about the flank's value (file units): bias and lengthwise position
WIDER_VARIABLES = {"2C": 0.02, "H1": 0.4}


def optimised_variables(case, side: str) -> tuple[frozenset[str], str]:
    """(variable names, command) of the ``ltca optimize`` run whose result ``case`` is, for
    its flank ``side`` (``"drive"``/``"coast"``); (empty, "") for a case that is none. A
    table without a ``flank`` (written before it was recorded) counts for either flank."""
    table = case.extra.get("optimize")
    if not isinstance(table, Mapping) or "source_case" not in table:
        return frozenset(), ""
    if table.get("flank", side) != side:
        return frozenset(), ""
    names = table.get("variables", {})
    return frozenset(names) if isinstance(names, Mapping) else frozenset(), \
        str(table.get("command", ""))


def static_flank_strength(lt) -> float:
    """The static contact strength σ_Hlim·Z_NT,stat·Z_W·Z_X [MPa] of the weaker member's
    material at the verdict's grade (:func:`contact.study.verdicts.flank_static_strength`,
    the limit of the verdict's flank check, ISO 6336-2 at the static stress); NaN without
    materials."""
    from contact.study.verdicts import flank_static_strength

    found = flank_static_strength(lt)
    return math.nan if found is None else float(found.strength)


def _parts(case, pinion_flank: str, half_ranges: Mapping[str, float]) -> list[str]:
    """``--variable NAME LOW HIGH`` of each variable about the flank's own value, those the
    pinion's process has."""
    from contact.optimize.variables import DesignVariable, check_variables, start_values
    from geometry.core.errors import InputError

    parts = []
    for name, half in half_ranges.items():
        try:
            (x,) = start_values(case, pinion_flank, (name,))
            var = DesignVariable(name, float(x) - half, float(x) + half)
            check_variables(case, pinion_flank, [var])
        except (InputError, KeyError, ValueError):
            continue  # not a variable of this pinion's process
        parts.append(f"--variable {name} {var.low:.4g} {var.high:.4g}")
    return parts


def bearing_lines(case, shown: str, side: str, torques: str, variables: Mapping[str, float],
                  pressure_limit: float | None = None, rate: bool = True) -> list[str]:
    """The next-step lines of a bearing finding of ``ltca run``'s verdict.

    Parameters
    ----------
    case : geometry.case.Case
    shown : str
        The case as the command names it.
    side : str
        ``"drive"``/``"coast"``.
    torques : str
        The analysed torques [N·m], as the command line gives them.
    variables : mapping name → half-range
        The bearing variables (file units) about the flank's own values.
    pressure_limit : float, optional — [MPa]
        The static strength a flank peak exceeded: given to the optimisation as
        ``--max-flank-pressure``, so that its "constraints met" covers the finding.
    rate : bool
        Offer ``ltca rate`` (a lower torque) where the bearing variables are exhausted;
        False where the caller prints it already (a capacity finding).

    Returns
    -------
    list of str
        The V–H check and an ``ltca optimize`` command — a wider one, or none, where the
        case is already the result of that optimisation (:func:`optimised_variables`).
    """
    from contact.utca.easeoff import FLANK_ROLES

    pinion_flank = FLANK_ROLES[side](case)
    done, command = optimised_variables(case, side)
    base = _parts(case, pinion_flank, variables)
    relief = ["--variable tip_relief 0 60", "--variable root_relief 0 60"]
    limits = "--max-edge-share 0.02" + (
        f" --max-flank-pressure {math.floor(pressure_limit):d}"
        if pressure_limit is not None and math.isfinite(pressure_limit) else "")
    first = set(variables) | {"tip_relief", "root_relief"}
    vh = f"    ltca vh-check {shown} --flank {side}"
    if not done or not first <= done:
        return [f"  next, the {side} flank's bearing: the pattern over the mounting positions, "
                "then its settings and relief developed against the loaded result, the other "
                "flank kept (docs/optimize.md, \"A flank that fails\"):", vh,
                f"    ltca optimize {shown} --flank {side} --torque {torques} "
                f"{' '.join(base + relief)} {limits} --max-evaluations 100"]
    seen = (f"this case is the result of `{command}`" if command else
            f"this case is `ltca optimize`'s result over {', '.join(sorted(done))}")
    wider = _parts(case, pinion_flank, {k: v for k, v in WIDER_VARIABLES.items()
                                        if k not in done})
    if wider:
        return [f"  next, the {side} flank's bearing: {seen} (its [optimize] table), and "
                "optimising those variables again does not answer the finding; the pattern "
                "over the mounting positions, then a wider set — the modified roll 2C and "
                "helical motion H1 (bias, lengthwise position) beside them (docs/optimize.md):",
                vh, f"    ltca optimize {shown} --flank {side} --torque {torques} "
                f"{' '.join(base + wider + relief)} {limits} --max-evaluations 150"] + (
                ["  or a lower torque: the rating's capacity at these torques "
                 "(docs/rating.md):", f"    ltca rate {shown} --torque {torques}"]
                if rate else [])
    return [f"  next, the {side} flank's bearing: {seen} (its [optimize] table), over the "
            "settings and relief a flank prescription has; optimising them again does not "
            "answer the finding. What would: the pattern over the mounting positions, the "
            "bearing re-developed from the basic data (`ltca synthesize`, docs/synthesis.md), "
            "or a lower torque (the rating's capacity, docs/rating.md):", vh] + (
            [f"    ltca rate {shown} --torque {torques}"] if rate else [])


def overlap_lines(case, what: str = "the LTE spread", lte: Sequence[float] | None = None,
                  side: str = "drive") -> list[str]:
    """The next-step line of an LTE finding (the LTE-spread FAIL, or ``ltca run``'s ``lte``
    attention) whose cause may be the design's own low contact ratios: ε_vβ below 1.25 and the
    face width and spiral angle that reach it, ε_vα below 1 and the depth factor and
    pressure angle that reach it
    (:func:`contact.load_capacity.iso10300.face_contact.low_ratio_text`); a bearing change
    offsets it only in part (docs/own_gear_set.md, "A face contact ratio below 1.25").
    Empty where the case has no ``[design]`` table or both ratios meet their limits.

    The remedies are those ``ltca synthesize``'s note offered, as its checks (one synthesis
    each) recorded them in the case
    (:func:`contact.optimize.remedy_check.recorded_judge`): the same order and numbers,
    never a change the check refused; a case without the record offers them unchecked,
    said so. Where the case's ``[development]`` records every drive target met
    (``targets_met = 1``), the torque clause is the note's too ("the design as given meets
    every drive target, so no lower design torque buys one"). What sets the LTE is stated
    as ``ltca synthesize`` states it
    (:func:`contact.optimize.remedy_check.lte_diagnosis`): where the written drive flank's
    unloaded TE is what its LTE is, that, and no contact-ratio change as the trial.

    The change is printed as a trial, never as the LTE's remedy: no estimate from the basic
    data supports one (the LTE is the bearing the development finds on the new blank; the
    loaded contact ratio scaled by the total contact ratio predicted neither outcome
    measured): the 21×29 at β_m 35 → 38.5° went 135/93 → 46/47 µrad at 288/1920 N·m, the
    18×27 at β_m 35 → 39.5° 80 → 81 µrad at its design torque, with two pairs over the whole
    cycle after (docs/own_gear_set.md, "The overlap change is a trial").

    Parameters
    ----------
    case : geometry.case.Case
    what : str
        The finding named: ``"the LTE spread"`` (default) or ``"the LTE"``.
    lte : sequence of float, optional — [µrad]
        The analysed flank's LTE p-p at (light, design) torque (``ltca run``'s); None: the
        unloaded TE is not judged (``ltca duty-cycle``).
    side : str
        The analysed flank's role, ``"drive"`` (default) or ``"coast"``: the unloaded TE
        judged is the drive flank's, so only a drive flank's LTE is judged by it.

    Returns
    -------
    list of str
    """
    from contact.load_capacity.design_table import design_blank, design_table
    from contact.load_capacity.iso10300.face_contact import low_ratio_text
    from contact.optimize.remedy_check import (
        RATIO_TRIAL_TEXT,
        lte_diagnosis,
        read_record,
        recorded_judge,
    )
    from contact.study.verdicts import LTE_LIMIT
    from geometry.core.errors import InputError

    limited = _generation_limit(case) if lte is not None and side == "drive" else None
    try:
        design = design_blank(design_table(case, "")).design
    except (InputError, KeyError, ValueError, AttributeError):
        design = None
    record = read_record(case.extra)
    # the written design's drive development targets, as the case records them: the
    # remedy's torque clause then reads as synthesize's note did (issue 71, round 42: the
    # 16x35 at Sigma 95 deg met every drive target; its run said "the drive targets the
    # design misses")
    development = case.extra.get("development")
    met = (isinstance(development, Mapping)
           and development.get("targets_met") in (1, True))
    said = (None if design is None else
            low_ratio_text(design, judge=recorded_judge(record, met) if record is not None
                           else None))
    if limited is not None:
        # said first, before the contact ratios and the bearing's prescriptions: the
        # 15x15 hypoid's next line blamed the prescriptions alone while its pinion's drive
        # flank was generated over 64 % of the blank (issue 71, branch ratio95)
        then = "" if said is None else f"; then the contact ratios: {said}"
        return [f"  next, {what}: first, {limited}{then}; a trial: ltca synthesize "
                "BASIC.toml with more teeth at the same size, then ltca run of the case it "
                "writes"]
    if said is None:
        return []
    cause = RATIO_TRIAL_TEXT
    if lte is not None and side == "drive":
        development = case.extra.get("development")
        prescriptions = (development.get("prescriptions")
                         if hasattr(development, "get") else None)
        diagnosis = lte_diagnosis(lte, LTE_LIMIT, _written_ute(case, record), prescriptions,
                                  () if record is None else record.checks,
                                  math.nan if record is None else record.unrelieved_ute)
        if diagnosis.cause == "relief":
            return [f"  next, {what} is not the design's contact ratios: {diagnosis.text}; a "
                    "trial: ltca synthesize BASIC.toml with a lighter drive relief or more "
                    "teeth, then ltca run of the case it writes"]
        if diagnosis.cause == "unloaded_te":
            return [f"  next, {what} is not the design's contact ratios: {diagnosis.text}; a "
                    "trial: ltca synthesize BASIC.toml with other [synthesis] prescriptions, "
                    "then ltca run of the case it writes"]
        cause = diagnosis.text
    unchecked = ("" if record is not None else
                 " (not checked by a synthesis: this case records no check; `ltca "
                 "synthesize` of its basic file checks each)")
    return [f"  next, {what} may be the design's: {said}{unchecked}; {cause}; a trial: ltca "
            "synthesize BASIC.toml --apply-remedy (the best change that passes its check "
            "applied and developed; contact.optimize.development_remedy), then ltca run of "
            "the case it writes"]


def _generation_limit(case) -> str | None:
    """The generation limit of the case's pinion drive flank in words
    (:func:`contact.optimize.development_conjugacy.generation_limit_text`), None where it
    is generated over its working depth or cannot be generated (the analysis said so)."""
    from contact.optimize.development_conjugacy import generation, generation_limit_text
    from geometry.core.errors import InputError, ModelUnavailableError

    try:
        return generation_limit_text(generation(case))
    except (InputError, ModelUnavailableError):
        return None


def _written_ute(case, record) -> tuple[float, float] | None:
    """The written drive flank's unloaded TE p-p [µrad] and ease-off span [µm]: as the
    case's remedy record holds it (``ltca synthesize`` measured it), else, for a case a
    development wrote (its ``[development]`` table: the prescriptions that set that TE),
    measured (:func:`contact.optimize.remedy_check.unloaded_te_pp`); None otherwise (a case
    of settings given by hand: no prescriptions to name) or where it cannot be measured
    (said in the log)."""
    if record is not None and math.isfinite(record.reference_ute):
        return record.reference_ute, record.reference_span
    if not hasattr(case.extra.get("development"), "get"):
        return None
    from contact.optimize.remedy_check import unloaded_te_pp
    from geometry.core.errors import InputError, ModelUnavailableError

    try:
        ute, span, _ = unloaded_te_pp(case)
    except (InputError, ModelUnavailableError, ValueError) as exc:
        import logging

        logging.getLogger(__name__).info("the case's unloaded TE not measured: %s", exc)
        return None
    return ute, span


def spread_failed(findings: Sequence) -> bool:
    """Whether a verdict's findings FAIL on the LTE spread.

    Parameters
    ----------
    findings : sequence of contact.study.verdicts.Finding
        A verdict's findings (``ltca run``'s or a duty cycle's bins').

    Returns
    -------
    bool
        True where one finding of severity ``fail`` and check ``implausible`` names the
        LTE spread (the plausibility cause ``lte_spread``, docs/verdicts.md).

    Raises
    ------
    AttributeError
        Where an item has no ``severity``, ``check`` or ``reason``.
    """
    return any(f.severity == "fail" and f.check == "implausible"
               and ("LTE spread" in f.reason or "lte spread" in f.reason)
               for f in findings)


def duty_cycle_lines(ds, shown: str, flank: str | None,
                     fail_checks: Sequence[str], case=None) -> list[str]:
    """The next-step lines under a FAILed duty cycle (``ltca duty-cycle``).

    Parameters
    ----------
    ds : xarray.Dataset
        ``/duty_cycle`` (:func:`contact.study.duty_cycle.run_duty_cycle`): ``torque``,
        ``flank_damage`` (bin, member, u, v), ``damage`` (member).
    shown : str
        The case as the command names it.
    flank : str or None
        The analysed flank (``--flank``).
    fail_checks : sequence of str
        The checks of the verdict's failing findings.
    case : geometry.case.Case, optional
        The analysed case: where the verdict FAILs on an LTE spread and the case's face
        contact ratio is below 1.25, :func:`overlap_lines` first.

    Returns
    -------
    list of str
        The bin that does most of the damage at the first point to fail, analysed as
        ``ltca run`` (whose verdict prints what answers its bearing), and the rating at its
        torque; a failing bin otherwise; nothing without a failing finding.
    """
    import numpy as np

    if not fail_checks:
        return []
    first: list[str] = []
    if case is not None and "implausible" in fail_checks:
        from contact.study.verdicts import verdict

        if spread_failed(verdict(ds).findings):
            first = overlap_lines(case)
    torque = np.asarray(ds["torque"].values, float)
    flag = f" --flank {flank}" if flank else ""
    worst, why, bin_flags = None, "", ""
    if ("root_stress" in fail_checks and "damage" not in fail_checks
            and "root_stress_safety" in ds):  # the bin ltca run fails on its root (issue 71)
        from contact.study.verdict_checks import root_safety_severity
        from contact.study.verdicts import shown_below

        safety = np.asarray(ds["root_stress_safety"].transpose("bin", "member").values, float)
        design = (float(ds["rating_design_torque"]) if "rating_design_torque" in ds
                  else np.nan)
        failed = [b for b in range(safety.shape[0]) if any(
            root_safety_severity(float(x), float(ds["bending_safety_min"]),
                                 float(torque[b]), design) == "fail" for x in safety[b])]
        worst = min(failed or range(safety.shape[0]), key=lambda b: np.nanmin(safety[b]))
        s_min = float(ds["bending_safety_min"])
        why = (f"bin {worst} ({plain_number(torque[worst])} N m) has the lowest FE root "
               f"safety S_F,FE {shown_below(float(np.nanmin(safety[worst])), s_min)}, below "
               f"S_Fmin {s_min:g} as ltca run judges it")
        bin_flags = _bin_misalignment_flags(ds, worst)
        if bin_flags:
            why += " at the bin's misalignment (the deflection table's and the assembly's)"
    elif "flank_damage" in ds and "damage" in ds:
        k = int(np.argmax(ds["damage"].values))
        fd = np.nan_to_num(np.asarray(ds["flank_damage"].isel(member=k).values, float))
        if fd.size and fd.sum() > 0:
            total = fd.sum(axis=0)
            iu, iv = np.unravel_index(int(np.argmax(total)), total.shape)
            per_bin = fd[:, iu, iv]
            worst = int(np.argmax(per_bin))
            member = ds["member"].values[k]
            # a file whose member dimension has no labels stores its index (pinion 0, gear 1)
            member = (("pinion", "gear")[int(member)] if np.issubdtype(
                np.asarray(member).dtype, np.integer) else str(member))
            why = (f"bin {worst} ({plain_number(torque[worst])} N m) does "
                   f"{100 * per_bin[worst] / per_bin.sum():.0f} % of the {member}'s flank "
                   "damage at its first point to fail")
    if worst is None:
        worst = int(np.argmax(torque))
        why = f"the peak-torque bin {worst} ({plain_number(torque[worst])} N m)"
    t = f"{torque[worst]:g}"
    return [*first,
            f"  next: {why}; its bearing at that torque as ltca run analyses it (the verdict "
            "there prints what answers a high or edge-loaded pattern), then the rating's "
            "capacity — a lower spectrum, or a larger or stronger gear set (docs/rating.md):",
            f"    ltca run {shown}{flag} --torque {t}{bin_flags}",
            f"    ltca rate {shown} --torque {t}"]


def _bin_misalignment_flags(ds, b: int) -> str:
    """`` --dE .. --dP .. --dG .. --dSigma ..`` of duty bin ``b``'s misalignment (the
    deflection table's and the assembly's, ΔΣ stored in rad, given in degrees as the
    command takes it), so that ``ltca run`` analyses the bin the duty cycle judged; ``""``
    where the dataset holds none or it is zero (issue 71: the pc_hypoid_10x43's bin at
    357 N·m fails its gear root at ΔE 0.05 mm, the run at 357 N·m without it does not)."""
    import math

    from contact.study.verdict_checks import duty_bin_misalignment

    d = duty_bin_misalignment(ds, b)
    if d is None or not all(math.isfinite(x) for x in d) or not any(d):
        return ""
    return "".join(f" --{flag} {x:.4g}" for flag, x in zip(("dE", "dP", "dG", "dSigma"), d,
                                                          strict=True))
