"""The development's check step for a contact path that leaves the unrelieved flank within
one pitch (issue 71): the path turned until one pair's whole pitch lies between the relief
corners.

The synthesis designs the drive TE as a parabola about M, and the pairs hand the load over
half a pitch of roll either side of it. Where one pitch of roll carries the contact past a
relief corner (or off the face) before that, the transfer is made by the relief, not by the
parabola: on the face-milled spiral bevel miter 20×20 of benchmarks/data/unseen_designs
(generated gear, z 20/20, c_ham 0.25, ε_vβ 1.34) the developed path of −45° leaves the
unrelieved flank at −0.35 and +0.25 pitch (the root and the tip relief's corners), its
unloaded TE p-p 104 µrad against the parabola's 2.5, LTE 102 / 116 µrad. On that pair every
path the development's bounds hold (−80° … −25°) leaves it within 0.8 pitch: near the
conjugate contact line (about −15° there) the contact runs fast, and along the profile one
pitch climbs about the whole working depth. Past the contact line (0° … +30°) one pitch
runs along the face, which its face contact ratio covers (docs/synthesis.md, "The miter
20×20's contact path off the unrelieved flank").

:func:`checked_path_window` gives a checked drive design whose LTE p-p exceeds the
verdict's limit at a torque and whose one-pitch window
(:func:`geometry.pair.path_window.path_window`) does not hold ±half a pitch about M the path
turned towards the face (increasing angle, past the contact line), every other
prescription kept: of the angles :data:`PATH_WINDOW_TURN` apart from the design's up to
:data:`PATH_WINDOW_MAX`, those whose window holds the pitch, the largest first — nearest
the direction across the contact line, where one pitch carries the contact least far along
the face, the most compact bearing (on the miter: 0.61 of the face per pitch at 0°, 0.17
at +30°) — each kept on the check steps' rule (better, tolerant at the mounting
excursions, :func:`~contact.optimize.development_keep.kept_why`); one not kept whose
light-load pattern runs to the toe or heel is tried again with M placed to centre its span
(:func:`centred_values`); at most :data:`PATH_WINDOW_DESIGNS` analysed. A design within
the limit is returned as it is,
without any synthesis: the step changes nothing the development writes for such designs.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why
from contact.optimize.development_pattern_steps import SHIFT_BOUNDS, SHIFT_NAME
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.pair.path_window import PathWindow, path_window

__all__ = ["PATH_WINDOW_DESIGNS", "PATH_WINDOW_MAX", "PATH_WINDOW_TE", "PATH_WINDOW_TURN",
           "STAGE",
           "centred_values", "checked_path_window", "path_angles"]

log = logging.getLogger("contact.optimize.development")

#: [deg] the step by which :func:`checked_path_window` turns the path towards the face
PATH_WINDOW_TURN = 15.0
#: [deg] the largest path angle it tries: a path rising towards the heel at 60° from the
#: lengthwise direction is still a diagonal bearing (the miter 20×20's window holds the
#: pitch from 0° to +30°, 0.95 pitch at +45°, 0.9 at +60°)
PATH_WINDOW_MAX = 60.0
#: the most designs :func:`checked_path_window` analyses (each a check at ``ltca run``'s
#: sampling and its tolerance)
PATH_WINDOW_DESIGNS = 3
#: [µrad] the TE level the turned design's second try has at least (:func:`centred_values`):
#: a flatter parabola lets the light-load pattern cover the whole path, which a turned
#: path lays along the face (the miter 20×20 at te_level 10: 0.00–0.85 of it); at +30° and
#: 30 µrad the undeveloped miter reads LTE 53 / 46 / 31 µrad at 50 / 250 / 500 N m (10 µrad:
#: 54 / 46 / 30)
PATH_WINDOW_TE = 30.0
#: the check stage of the step's design (:attr:`DevelopmentEvaluation.stage`)
STAGE = "path window"


def path_angles(start: float, *, turn: float = PATH_WINDOW_TURN,
                most: float = PATH_WINDOW_MAX) -> list[float]:
    """The path angles [deg] :func:`checked_path_window` tries from a design's ``start``
    [deg]: ``start + turn``, ``start + 2 turn`` … up to ``most``, each rounded to 0.01°.

    Parameters
    ----------
    start : float — [deg]
        The design's path angle, in (−90°, 90°).
    turn : float — [deg]
        The step, > 0.
    most : float — [deg]
        The last angle tried, < 90°.

    Returns
    -------
    list of float — [deg]
        Increasing; empty where ``start + turn`` exceeds ``most``.

    Raises
    ------
    InputError
        If ``turn`` is not positive or ``most`` not below 90°.

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "The miter 20×20's
    contact path off the unrelieved flank").
    """
    if not turn > 0.0:
        raise InputError(f"turn: must be > 0 deg, got {turn!r}")
    if not most < 90.0:
        raise InputError(f"most: must be < 90 deg (a path angle), got {most!r}")
    n = int(np.floor((most - start) / turn + 1e-9))
    return [round(start + k * turn, 2) for k in range(1, n + 1)]


def centred_values(e: DevelopmentEvaluation | None, values: Mapping[str, float],
                   targets: DevelopmentTargets) -> dict[str, float] | None:
    """The prescriptions ``values`` [file units] of a turned design ``e`` with M placed so
    that its light-load pattern's span lies midway between toe and heel: ``mean_point_shift``
    moved by ½ ((1 − heel u) − toe u), within the targets' bounds of it (else
    :data:`~contact.optimize.development_pattern_steps.SHIFT_BOUNDS`), and the TE parabola
    at least :data:`PATH_WINDOW_TE` (within ``te_level``'s bounds) to shorten the pattern
    along the path. None where ``e`` is None, has no pattern, keeps its clearance to both
    ends (``targets.clearance``), or nothing moves by 0.01.

    Parameters
    ----------
    e : DevelopmentEvaluation or None
        The turned design, checked.
    values : mapping
        Its prescriptions [file units].
    targets : DevelopmentTargets

    Returns
    -------
    dict or None
        ``values`` with ``mean_point_shift`` [1, of the face width, > 0 towards the heel].

    Notes
    -----
    The pattern follows M along the face about one for one
    (:data:`~contact.optimize.development_pattern_steps.CENTRE_U_SLOPE`, 0.95); a turned
    path's long pattern on the miter 20×20 ran 0.00–0.85 of the face (the toe's edge).
    """
    if e is None or e.metrics is None or "pattern_toe_u" not in e.metrics:
        return None
    toe = float(np.asarray(e.metrics["pattern_toe_u"], float)[0])
    heel = float(np.asarray(e.metrics["pattern_heel_u"], float)[0])
    c = float(targets.clearance)
    if not np.isfinite(toe + heel) or (toe > c and heel < 1.0 - c):
        return None
    lo, hi = (float(x) for x in targets.variables.get(SHIFT_NAME, SHIFT_BOUNDS))
    x0 = float(values.get(SHIFT_NAME, 0.0))
    x = round(float(np.clip(x0 + 0.5 * ((1.0 - heel) - toe), lo, hi)), 4)
    new = dict(values) | {SHIFT_NAME: x}
    if "te_level" in values:
        t_lo, t_hi = (float(v) for v in targets.variables.get("te_level", (0.0, 1000.0)))
        new["te_level"] = float(np.clip(max(float(values["te_level"]), PATH_WINDOW_TE),
                                        t_lo, t_hi))
    if all(abs(float(new[k]) - float(values.get(k, 0.0))) < 0.01 for k in new):
        return None
    return new


def _window(placed: Callable[[Mapping[str, float]], Case], values: Mapping[str, float]
            ) -> tuple[Case, PathWindow] | None:
    """The design ``values`` placed and its drive path's window; None where its synthesis
    or the window's TCA fails (logged)."""
    try:
        case = placed(values)
        return case, path_window(case)
    except Exception as exc:  # a path near the contact line has no ellipse: not tried
        log.info("development %s: path_angle %.4g not tried: %s", STAGE,
                 float(values["path_angle"]), exc)
        return None


def checked_path_window(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                        setup: Mapping[str, Any], teeth: KeptTeeth | None,
                        say: Callable[[str], None],
                        placed: Callable[[Mapping[str, float]], Case], *,
                        lte_limit: float | None = None) -> DevelopmentEvaluation:
    """A drive design whose LTE p-p at the check exceeds the verdict's limit and whose
    contact path leaves the unrelieved flank within ±half a pitch of M, given the path
    turned towards the face to an angle whose window holds the pitch: of
    :func:`path_angles`, those that hold it, the largest first, until one is kept, each
    not kept whose pattern runs to an end followed by the same path with M placed
    (:func:`centred_values`; at most :data:`PATH_WINDOW_DESIGNS` analysed).

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).
    lte_limit : float, optional — [µrad]
        The verdict's ``lte`` limit (default :data:`contact.study.verdicts.LTE_LIMIT`,
        60 µrad).

    Returns
    -------
    DevelopmentEvaluation
        The design kept: ``best`` itself where it is within the limit at every torque, it
        has no path angle, its own window holds the pitch, no angle up to
        :data:`PATH_WINDOW_MAX` does, or none of those analysed was kept.

    Raises
    ------
    Nothing: a design whose synthesis, window or analysis fails is not kept (logged).

    Notes
    -----
    The window is the conventional TCA's (seed Eq. 2.14) of the flank without its rems,
    read against the blade's relief corners (:func:`geometry.pair.path_window.
    path_window`); the transfer at ±pitch/2 of the designed parabola (seed §2.3.1, Fig.
    2.9). Measured on the miter 20×20 (docs/synthesis.md, "The miter 20×20's contact path
    off the unrelieved flank"): path −45° → 0° with the ellipse 0.70, te_level 10 µrad and
    the reliefs 15 µm kept, undeveloped: LTE p-p 101.5 / 108.0 / 100.3 → 32.8 / 33.4 /
    25.7 µrad at 50 / 250 / 500 N m.
    """
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if lte_limit is None else float(lte_limit)
    if (not best.checked_full or "path_angle" not in best.values
            or not np.nanmax(best.metrics["lte_peak_to_peak"]) > limit):
        return best
    own = _window(placed, best.values)
    if own is None or own[1].holds_pitch:
        return best
    start = float(best.values["path_angle"])
    tried = 0
    for angle in reversed(path_angles(start)):  # the most compact bearing first
        values = dict(best.values) | {"path_angle": angle}
        got = _window(placed, values)
        if got is None or not got[1].holds_pitch:
            continue
        case, window = got
        e = said_variant(best, values, STAGE,
                         f"with path_angle {angle:.4g} (its path left the unrelieved flank "
                         f"at the {own[1].leaves_by()}; at {angle:.4g} deg it holds "
                         f"{window.low:+.2f}..{window.high:+.2f} pitch; its LTE above "
                         f"{limit:g} urad)", targets, setup, teeth, say, placed, case=case)
        if not kept_why(best, e, targets, setup, teeth, say,
                        "the path turned onto the unrelieved flank"):
            return e
        tried += 1
        if tried >= PATH_WINDOW_DESIGNS:
            return best
        shifted = centred_values(e, values, targets)
        got = None if shifted is None else _window(placed, shifted)
        if got is None or not got[1].holds_pitch:
            continue
        case, window = got
        e = said_variant(best, shifted, STAGE,
                         f"with path_angle {angle:.4g}, mean_point_shift "
                         f"{shifted[SHIFT_NAME]:.3g} and te_level "
                         f"{shifted.get('te_level', math.nan):.3g} urad (the turned pattern "
                         "centred between toe and heel, shorter; it holds "
                         f"{window.low:+.2f}..{window.high:+.2f} pitch)", targets, setup,
                         teeth, say, placed, case=case)
        if not kept_why(best, e, targets, setup, teeth, say,
                        "the turned path with M placed"):
            return e
        tried += 1
        if tried >= PATH_WINDOW_DESIGNS:
            return best
    if not tried:
        say(f"  design {best.index + 1}: its path leaves the unrelieved flank at the "
            f"{own[1].leaves_by()}, and no path up to {PATH_WINDOW_MAX:g} deg holds a "
            "pitch")
    return best
