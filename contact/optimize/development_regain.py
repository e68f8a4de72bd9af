"""The mounting tolerance of a design torque raised back on the final bearing (issue 71
item 2: one design torque that holds).

After a capacity cut the development's steps may write a bearing that carries more than
the cut torque; :func:`contact.optimize.development_root.regained_capacity` raises the
design torque back towards the torque before the cut where its root stress and local
pitting safety hold, and ``contact.optimize.development._regained`` keeps it where the
drive design loses no target. The mounting excursions ΔE/ΔP the development checks its
design at (:func:`~contact.optimize.development_check.tolerance_checks`) are the third
judgement: :func:`tolerant_raise` checks them at the raised torques and, where the raise
costs a tolerance target the cut torque met, bisects for the highest torque that keeps
them (:func:`~contact.optimize.development_check.tolerant_torque`'s logic, between the cut
and the raised torque). Imported by :mod:`contact.optimize.development`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from contact.optimize.development_check import tolerance_checks
from contact.optimize.development_result import TOLERANCE_KEYS, case_torques, floor_torque
from geometry.core.text import plain_number

#: [1] the bisection of :func:`tolerant_raise` ends where the torque that holds and the one
#: that does not are within this ratio (3 %, :func:`~contact.optimize.development_check.
#: tolerant_torque`'s bracket at the default light load 0.15)
RAISE_BRACKET = 1.03
#: most bisection steps of :func:`tolerant_raise` (each 1–4 coarse analyses at the
#: excursions, at the new light and design torque)
RAISE_STEPS = 6


@dataclass(frozen=True)
class TolerantRaise:
    """What :func:`tolerant_raise` found.

    Attributes
    ----------
    torque : float — [N·m]
        The highest design torque found, between the cut and the raised one, at which
        the design keeps every mounting-tolerance target it met at the cut torque (the
        raised torque itself where it does; the cut torque where nothing above it does).
    fails : float — [N·m]
        The least torque found at which it does not (NaN where the raised torque holds).
    lost : tuple of str
        At the raised torque, the excursions and targets lost, "label: key, key" (empty
        where none).
    why : str
        Where the raise is not taken at all: why (empty otherwise).
    """

    torque: float
    fails: float = math.nan
    lost: tuple[str, ...] = ()
    why: str = ""

    @property
    def holds(self) -> bool:
        """Whether the raised torque itself keeps the tolerance (nothing lost there)."""
        return not self.lost and not self.why


def _missed(tolerance: Mapping[str, tuple[dict, dict[str, float]]]) -> set[tuple[str, str]]:
    """(excursion label, key) pairs of :data:`TOLERANCE_KEYS` missed in ``tolerance``."""
    return {(lab, k) for lab, (_, short) in tolerance.items() for k in TOLERANCE_KEYS
            if short[k] > 0.0}


def _lost_text(lost: set[tuple[str, str]]) -> tuple[str, ...]:
    labels = dict.fromkeys(lab for lab, _ in sorted(lost))
    return tuple(f"{lab}: {', '.join(sorted(k for b, k in lost if b == lab))}"
                 for lab in labels)


def tolerant_raise(case: Any, targets: Any, setup: dict[str, Any], teeth: Any,
                   values: Mapping[str, float], raised: float,
                   say: Callable[[str], None]) -> TolerantRaise:
    """The highest design torque up to ``raised`` [N·m] at which the written ``case``
    keeps, at every mounting excursion ΔE = ±``offset_tolerance``, ΔP =
    ±``mounting_tolerance`` (:func:`~contact.optimize.development_check.tolerance_checks`,
    the check the development makes on its final design), every target of
    :data:`~contact.optimize.development_result.TOLERANCE_KEYS` (toe and heel clearance,
    edge share, plastic share) it met at the cut design torque ``setup["torques"][1]``.

    Parameters
    ----------
    case : geometry.case.Case
        The written case (its drive flank is checked).
    targets : DevelopmentTargets
        The development's targets (``light_load`` [1], the excursions [mm]).
    setup : dict
        The development's state; ``setup["torques"]`` the cut (light, design) torques
        [N·m], not changed here (its ``"tolerance_memo"`` gets the analyses: the final
        check, :func:`~contact.optimize.development_check.final_tolerance`, reads them).
    teeth : KeptTeeth or None
        The shell teeth kept (the pinion's under the design's bearing key).
    values : mapping
        The drive design's prescriptions.
    raised : float
        [N·m] The raised design torque whose root stress and local pitting safety hold
        (:func:`~contact.optimize.development_root.regained_capacity`), > the cut one.
    say : callable
        Progress lines.

    Returns
    -------
    TolerantRaise
        ``torque`` = ``raised`` where nothing is lost there; else the torque bisected
        (geometric, at the light torque ``light_load`` × it, :func:`case_torques`) between
        the cut and the raised torque to within :data:`RAISE_BRACKET` (at most
        :data:`RAISE_STEPS` steps), each step analysing the excursions that lost a target
        first and stopping at the first that loses one; the cut torque with ``why`` set
        where the cut torque's edges already fail at an excursion (the edge and plastic
        shares grow with the torque: the torque up to which they hold is below the cut
        one, :func:`~contact.optimize.development_check.tolerant_torque`, and a raise would
        only widen the gap).

    Notes
    -----
    A design torque that is not tolerant is not cut for it (docs/synthesis.md, "Not
    tolerant at the design torque"); a raise is a choice the development makes, and it
    takes it only as far as the assembly's tolerance still holds where it held at the cut
    torque (docs/synthesis.md, "The raised design torque's mounting tolerance"). An
    analysis that fails counts as a target missed (the tolerance check's rule).
    Source: the issue-71 development's tolerance targets (docs/synthesis.md,
    "Development bearing").
    """
    light_load = float(targets.light_load)
    cut = float(setup["torques"][1])
    setup.setdefault("tolerance_memo", {})  # shared by the copies below

    def at(torque: float, **kw: Any) -> dict:
        return tolerance_checks(case, targets, dict(setup, torques=case_torques(
            light_load, torque)), teeth, values, **kw)

    # at the raised torques first: where it misses nothing there, nothing is lost (and
    # the final check reads these analyses: no cost beyond the raise's own)
    high = _missed(at(raised))
    if not high:
        return TolerantRaise(raised)
    before = _missed(tolerance_checks(case, targets, setup, teeth, values))
    if any(k in ("edge", "plastic") for _, k in before):
        bad = sorted({lab for lab, k in before if k in ("edge", "plastic")})
        return TolerantRaise(cut, math.nan, (), f"its edges at the mounting excursion"
                             f"{'s' if len(bad) > 1 else ''} {', '.join(bad)} fail at "
                             f"{plain_number(cut)} N m already")
    lost = high - before
    if not lost:
        return TolerantRaise(raised)
    first = tuple(dict.fromkeys(lab for lab, _ in sorted(lost)))
    say(f"  the mounting tolerance at {plain_number(raised)} N m: "
        f"{'; '.join(_lost_text(lost))} (met at {plain_number(cut)} N m): the highest torque that "
        "keeps it searched")
    lo, hi = cut, raised
    for _ in range(RAISE_STEPS):
        if hi / lo <= RAISE_BRACKET:
            break
        mid = floor_torque(math.sqrt(lo * hi))
        if not lo < mid < hi:
            break
        # a design tolerant at the cut torque: stop at the first excursion that misses
        # (the lost ones first); else every excursion, the misses compared pair by pair
        missed = _missed(at(mid, until_missed=not before, first=first)) - before
        if missed:
            hi = mid
            first = tuple(dict.fromkeys(
                [*(lab for lab, _ in sorted(missed)), *first]))
        else:
            lo = mid
    return TolerantRaise(lo, hi, _lost_text(lost))
