"""The drive flank of the written case read as ``ltca run`` reads it (issue 71, "a gear you
would sign off": the development's edge judgement must be ``ltca run``'s of the case it
writes).

The drive flank is developed and checked first (:data:`~contact.optimize.
development_evaluate.CHECK_LTCA`, ``ltca run``'s sampling, at the written torques), each
design's pinion carrying its coast flank *as synthesised*; the coast flank is developed
after it (:func:`~contact.optimize.development_coast_flank.coast_development`) and written
with its own blade, machine settings and reliefs. The drive flank's geometry is the
checked design's, bit for bit, but the pinion tooth it bends with is not: the LTCA's shell
compliance (seed Eq. 3.1–3.11, :func:`contact.compliance.tooth.shell_tooth_from_case`)
fits the tooth's thickness and mid-surface over the whole tooth, both flanks. So the
drive numbers the development checked, judged and recorded (``[development.achieved]``)
were not those ``ltca run`` gives of the written case.

Traced on the face-milled hypoid 10x41 a 32 mm (benchmarks/data/unseen_designs, round
19b) at its design torque 331 N m (2026-11-27, docs/synthesis.md, "The written case's
drive flank, read as ltca run reads it"): the check's pinion edge 2484.3 MPa, ``ltca
run`` 2551.1 MPa (+66.8; gear heel 3084.2 → 3075.8, edge share 0.493 → 0.530 %, LTE
39.16 → 39.22 µrad). Of that: sampling 0 (the check is at ``ltca run``'s 2 × 20 rolls ×
24 segments), the TOML round trip of the machine settings 0, the torque 0 (the check's
torques are the written ones, :func:`contact.pipeline.case_torques`), the compliance
model 0 (the shell model both; coarse10 is the root stress's FE level, not the
contact's), the edge reading 0 (both :func:`contact.study.verdicts.edge_peaks`); the
written geometry with the checked design's pinion tooth 2484.3, the checked geometry with
the written pinion tooth 2551.1: all of it is the pinion tooth's coast side. The face-
hobbed 10x41 a 35 mm (round 20b): pinion edge 2474.0 → 2487.3 MPa, the same cause.

:func:`written_drive_check` therefore analyses the written case's drive flank once more
at the development's torques with its own teeth, as ``ltca run`` does, wherever the
written pinion is not the checked design's, and the development's result (its record,
its lines, its targets met) carries that reading.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.compliance.fe.worker_cpu import cpu_seconds
from contact.ltca.edges import EDGE_KINDS
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets, development_score
from geometry.case import Case
from geometry.core.errors import raise_if_interrupted

log = logging.getLogger("contact.optimize.development")

__all__ = ["reread_needed", "written_drive_check", "written_drive_text"]

#: the edge kinds in words (the line said)
_WORDS = {"gear_heel": "gear heel", "gear_toe": "gear toe", "gear_tip": "gear tip",
          "pinion_edge": "pinion edge"}


def reread_needed(checked: Case | None, written: Case) -> bool:
    """Whether the written case's drive flank must be analysed again: its pair or either
    member differs from the checked design's (to the last bit of every setting).

    Parameters
    ----------
    checked : Case or None
        The case the drive flank's final check analysed (``best.case``).
    written : Case
        The case the development writes.

    Returns
    -------
    bool
        False where ``checked`` is None (nothing checked to compare) or its pair, pinion and
        gear are those written: the check analysed the written teeth.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the shell compliance reads both flanks of each tooth (module docstring).
    """
    if checked is None:
        return False
    return any(repr(getattr(checked, k)) != repr(getattr(written, k))
               for k in ("pair", "pinion", "gear"))


def written_drive_check(case: Case, best: DevelopmentEvaluation, targets: DevelopmentTargets,
                        setup: Mapping[str, Any], say: Callable[[str], None]
                        ) -> DevelopmentEvaluation:
    """The drive design ``best`` as the written ``case`` is: its drive flank analysed at
    :data:`~contact.optimize.development_evaluate.CHECK_LTCA` at the development's torques
    with the written case's own teeth (``ltca run``'s shell compliance), scored on every
    target, where :func:`reread_needed`.

    Parameters
    ----------
    case : Case
        The case the development writes (both flanks developed).
    best : DevelopmentEvaluation
        The drive design the development chose (checked at ``ltca run``'s sampling).
    targets : DevelopmentTargets
        The development's targets.
    setup : mapping
        ``"torques"`` (light, design) [N·m] as written, ``"centre_v"`` [1].
    say : callable
        Called with one line where the reading differs from the check's.

    Returns
    -------
    DevelopmentEvaluation
        ``best`` with the written case's metrics, score and case (stage unchanged,
        ``checked`` True); ``best`` itself where no re-reading is needed, ``best`` is not
        checked at ``ltca run``'s sampling, or the analysis fails (logged: ``ltca run``
        would say the same failure).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (module docstring); one LTCA at two torques where the coast flank was
    developed (1–2 s of CPU), none where it was not.
    """
    from contact.optimize import development_evaluate as evaluation

    if not best.checked_full or not reread_needed(best.case, case):
        return best
    c0 = cpu_seconds()
    try:
        ms, grid = evaluation.analyse_design(case, list(setup["torques"]),
                                             options=evaluation.CHECK_LTCA)
    except Exception as exc:
        raise_if_interrupted(exc)
        log.info("development: the written case's drive flank could not be analysed (%s); "
                 "the check's reading kept", exc)
        return best
    full = development_score(ms, targets, grid[:4], centre_v=setup["centre_v"],
                             pressure_limit=grid[4])
    e = dataclasses.replace(best, metrics=ms, objective=full[0], shortfalls=full[1],
                            met=full[2], full=full, case=case, checked=True,
                            seconds=best.seconds + cpu_seconds() - c0)
    text = written_drive_text(best, e)
    if text:
        say(text)
    return e


def written_drive_text(before: DevelopmentEvaluation, after: DevelopmentEvaluation) -> str:
    """The line :func:`written_drive_check` says: the edge peaks, edge share and LTE at the
    design torque that moved, the check's → the written case's, and a target lost or met.

    Parameters
    ----------
    before, after : DevelopmentEvaluation
        The check's design and the written case's reading (``metrics`` per torque, light
        first; ``full``).

    Returns
    -------
    str
        Empty where nothing it names moved by 0.5 MPa, 0.005 % of the torque or 0.05 µrad
        and the targets met are the same.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: :func:`written_drive_check`.
    """
    a, b = before.metrics, after.metrics
    parts = []
    for k in EDGE_KINDS:
        name = f"edge_peak_{k}"
        if name in a and name in b:
            x, y = float(np.asarray(a[name])[-1]), float(np.asarray(b[name])[-1])
            if math.isfinite(x) and math.isfinite(y) and abs(y - x) >= 0.5:
                parts.append(f"{_WORDS[k]} {x:.0f} -> {y:.0f} MPa")
    x, y = (100 * float(np.asarray(m["edge_load_share"])[-1]) for m in (a, b))
    if abs(y - x) >= 0.005:
        parts.append(f"edge share {x:.2f} -> {y:.2f} %")
    x, y = (float(np.asarray(m["lte_peak_to_peak"])[-1]) for m in (a, b))
    if abs(y - x) >= 0.05:
        parts.append(f"LTE p-p {x:.1f} -> {y:.1f} urad")
    met_a = bool(before.full and before.full[2])
    met_b = bool(after.full and after.full[2])
    if met_a != met_b:
        parts.append("every target met" if met_b else
                     "a target missed: " + ", ".join(
                         k for k, v in after.full[1].items() if v > 0))
    if not parts:
        return ""
    return ("development: the written case's drive flank as ltca run reads it (its pinion "
            "tooth bends with the coast flank written, which the drive check's did not "
            "carry) at the design torque: " + "; ".join(parts))
