"""The coast flank's own design torque (issue 71 item 2: each flank's design torque no
higher than what its own developed bearing carries).

The coast side of a hypoid has its own pressure angle and its own bearing: its ISO 10300
long-life capacity (``[rating] coast_design_torque``,
:func:`contact.load_capacity.iso10300.capacity.with_coast_design_torque`) is not the
drive side's, and its developed bearing may peak above the static strength, carry plastic
edges or overstress the root below it. :func:`coast_capacity` checks the written case's
coast flank at ``ltca run --flank coast``'s sampling and torques
(:func:`contact.pipeline.flank_torques`: the coast design torque and its light torque, the
same share of it as the case's of the design torque) and lowers the coast design torque,
one verified step at a time, until the flank peak pressure is within the static strength,
no segment is plastic, the FE root stress's safety S_F,FE is at least S_Fmin and the local
pitting safety at long life S_H,loc
(:func:`contact.optimize.development_root.pitting_safety`) at least S_Hmin
(:func:`coast_torque_step`). Every
lowering is recorded with its reason (:attr:`CoastCapacity.reason`), which the case's
``[rating] source`` and ``ltca synthesize`` print. Imported by
:mod:`contact.optimize.development`.

Public names
------------
CoastCheck        one analysis of the coast flank at its light and design torque
CoastCapacity     the coast design torque found, its checks and why it was lowered
coast_torque_step the next torque of the search from one or two checks (pure)
coast_capacity    the search on a case (an analysis callable: testable without an LTCA)
COAST_STEPS, REFINE_STEPS, CLOSENESS, PLASTIC_STEP, EDGE_EXPONENT
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from contact.optimize.development_result import STATIC_MARGIN, floor_torque
from contact.optimize.development_root import root_capacity_step
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number

__all__ = ["CLOSENESS", "COAST_STEPS", "EDGE_EXPONENT", "PLASTIC_STEP", "REFINE_STEPS",
           "CoastCapacity", "CoastCheck", "coast_capacity", "coast_torque_step"]

log = logging.getLogger(__name__)

#: most lowering steps of :func:`coast_capacity` (each one coast-flank analysis at
#: ``ltca run``'s sampling with the FE root stress, ≈ 5 s CPU with the FE model cached)
COAST_STEPS = 4
#: most steps back up between the highest torque that holds and the lowest that fails
REFINE_STEPS = 3
#: the search ends where the lowest torque that fails is within this factor of the highest
#: that holds [1]
CLOSENESS = 1.05
#: the factor a torque with plastic segments is lowered by in one step [1]: a plastic
#: segment is at its pressure limit, so its pressure says nothing of how far below the
#: torque lies where it is elastic; 0.85 per step reaches 0.52 of the start in 4 steps
PLASTIC_STEP = 0.85
#: the exponent a of an edge's peak pressure p ∝ T^a for the first step of the ``edge``
#: criterion [1]: 1/2, Hertz's line contact of the edge's rounding on the mating flank
#: (Johnson 1985, eq. 4.45); measured on the FH 13×30 at Σ 115°'s coast pinion edge
#: between 80 and 272.1 N m: 2097 → 4481 MPa, a = 0.62 (docs/own_gear_set.md, "The FH
#: 13×30's coast edges at its design torque: relief or capacity")
EDGE_EXPONENT = 0.5


@dataclass(frozen=True)
class CoastCheck:
    """One analysis of the coast flank at its light and design torque.

    Attributes
    ----------
    torque : float — [N·m] the coast design torque analysed (with its light torque)
    pressure : float — [MPa] the LTCA's flank peak pressure at ``torque``
    limit : float — [MPa] the static strength σ_Hlim·Z_NT,static (the verdict's fail limit)
    plastic : float — [1] the largest share of the torque on plastic segments, over both
        torques and every roll position
    root_safety : float — [1] S_F,FE of the weaker member at ``torque`` (NaN: not computed)
    s_min : float — [1] the rating's S_Fmin (NaN: not known)
    member : str — the weaker member of ``root_safety``
    light_root_safety : float — [1] S_F,FE at the light torque (for the exponent; NaN)
    light_torque : float — [N·m]
    result : Any — what the analysis returned (its metrics), for the caller
    plastic_limit : float — [1] the plastic share allowed (the development's
        ``max_plastic_share``, default 0: no plastic segment)
    pitting_safety : float — [1] the local pitting safety at long life S_H,loc of the
        weaker member at ``torque``
        (:func:`contact.optimize.development_root.pitting_safety`; NaN: not computed)
    s_h_min : float — [1] the rating's S_Hmin (NaN: not known)
    pitting_member : str — the weaker member of ``pitting_safety``
    light_pitting_safety : float — [1] S_H,loc at the light torque (for the exponent; NaN)
    root_at_rounding : bool — the weaker member's root-stress peak lies where the FE model
        rounds the slot bottom of its loaded fillet by step 2's small arc
        (:func:`contact.ltca.root_stress.slot_bottom_notes`): its S_F,FE is then a lower
        bound, set by the model's radius (docs/fe.md, "The coast design torque of two
        spiral bevels"), and the root failure says so
    edge_peak : float — [MPa] the largest edge peak pressure at ``torque`` that ``ltca
        run``'s ``edge_pressure`` check counts (:func:`contact.study.verdicts.edge_peaks`:
        edge kinds carrying at least ``EDGE_SHARE_MIN`` of the torque, below the edges'
        contact-pressure limit; 0: none; NaN: not known)
    edge_limit : bool — the edges are judged against the static strength ``limit`` too
        (``[development] coast_edge_capacity``; default False: the edges are ``ltca
        run``'s attention, not a criterion of the coast design torque)
    """

    torque: float
    pressure: float
    limit: float
    plastic: float = 0.0
    root_safety: float = math.nan
    s_min: float = math.nan
    member: str = ""
    light_root_safety: float = math.nan
    light_torque: float = math.nan
    result: Any = None
    plastic_limit: float = 0.0
    pitting_safety: float = math.nan
    s_h_min: float = math.nan
    pitting_member: str = ""
    light_pitting_safety: float = math.nan
    root_at_rounding: bool = False
    edge_peak: float = math.nan
    edge_limit: bool = False

    @property
    def failures(self) -> dict[str, str]:
        """What fails at this torque, criterion → phrase with the numbers (empty: holds)."""
        from contact.study.verdicts import shown_below

        out = {}
        if math.isfinite(self.pressure) and self.pressure > self.limit:
            out["flank"] = (f"flank peak pressure {self.pressure:.0f} MPa above the static "
                            f"strength {self.limit:.0f} MPa")
        if self.edge_limit and math.isfinite(self.edge_peak) and self.edge_peak > self.limit:
            out["edge"] = (f"edge peak pressure {self.edge_peak:.0f} MPa above the static "
                           f"strength {self.limit:.0f} MPa")
        if self.plastic > self.plastic_limit:
            out["plastic"] = (f"plastic segments carry {100 * self.plastic:.2g} % of the "
                              "torque")
        if (math.isfinite(self.root_safety) and math.isfinite(self.s_min)
                and self.root_safety < self.s_min):
            out["root"] = (f"FE root stress S_F,FE "
                           f"{shown_below(self.root_safety, self.s_min)} ({self.member}) "
                           f"below S_Fmin {self.s_min:g}"
                           + (", its peak at the FE model's smallest slot-bottom rounding "
                              "(a lower bound: docs/fe.md, 'The coast design torque of two "
                              "spiral bevels')" if self.root_at_rounding else ""))
        if (math.isfinite(self.pitting_safety) and math.isfinite(self.s_h_min)
                and self.pitting_safety < self.s_h_min):
            out["pitting"] = (f"local pitting safety S_H,loc "
                              f"{shown_below(self.pitting_safety, self.s_h_min)} "
                              f"({self.pitting_member}) below S_Hmin {self.s_h_min:g}")
        return out


@dataclass(frozen=True)
class CoastCapacity:
    """What :func:`coast_capacity` found.

    Attributes
    ----------
    torque : float — [N·m] the coast design torque (the start where nothing failed there)
    start : float — [N·m] the torque the search started at
    checks : tuple of CoastCheck — every analysis, in order
    reason : str — why the torque was lowered, with the numbers (empty where not)
    holds : bool — the last check analysed at ``torque`` meets every criterion
    """

    torque: float
    start: float
    checks: tuple[CoastCheck, ...]
    reason: str
    holds: bool

    @property
    def lowered(self) -> bool:
        return self.torque < self.start

    @property
    def final(self) -> CoastCheck | None:
        """The check at :attr:`torque` (None where none was made)."""
        return next((c for c in reversed(self.checks) if c.torque == self.torque), None)


def _exponent(t1: float, x1: float, t2: float, x2: float, default: float,
              low: float, high: float) -> float:
    """d ln x / d ln T between two points, bounded to [low, high] (``default`` where not
    measurable)."""
    if not (t1 > 0 and t2 > 0 and t1 != t2 and x1 > 0 and x2 > 0
            and math.isfinite(x1 * x2)):
        return default
    return min(high, max(low, abs(math.log(x2 / x1) / math.log(t2 / t1))))


def coast_torque_step(check: CoastCheck, previous: CoastCheck | None = None,
                      margin: float = STATIC_MARGIN) -> tuple[float, str]:
    """The next, lower coast design torque [N·m] after ``check`` failed, and the criterion
    that set it (``""`` and ``check.torque`` where nothing fails).

    The least of, for each criterion that fails at ``check.torque`` = T:

    * flank: T (m p_lim / p)^(1/a), with p ∝ T^a — a = 1/3, Hertz's point contact, for the
      first step; then a measured between ``previous`` and ``check``, bounded to
      [0.2, 1] (a pattern that grows under load raises its peak more slowly);
    * root: :func:`contact.optimize.development_root.root_capacity_step` with
      S_F,FE ∝ T^(−b), b measured between ``previous`` and ``check``, else between the
      light and the design torque of ``check``, else 1, bounded to [0.3, 1];
    * pitting: :func:`contact.optimize.development_root.root_capacity_step` on the local
      pitting safety S_H,loc ∝ T^(−b), b measured as for the root stress, else 1/3
      (Hertz's point contact), bounded to [0.2, 1];
    * plastic: T × :data:`PLASTIC_STEP`;
    * edge (``check.edge_limit`` only): T (m p_lim / p_edge)^(1/a), a =
      :data:`EDGE_EXPONENT` for the first step (the edge rounding's Hertzian line
      contact), then measured as for the flank.

    Rounded down (:func:`contact.optimize.development_result.floor_torque`: 0.1 N·m,
    two significant digits below 1 N·m).

    Parameters
    ----------
    check, previous : CoastCheck
        The last check and the one before it (None for the first step).
    margin : float — [1] aimed below each limit (default :data:`STATIC_MARGIN`, 0.99)

    Returns
    -------
    (torque [N·m], criterion) — criterion one of ``"flank"``, ``"root"``, ``"pitting"``,
    ``"plastic"``, ``"edge"``.

    Notes
    -----
    Source: Hertz's p_max ∝ F^(1/3) for a point contact (Johnson, *Contact Mechanics*,
    1985, eq. 4.23), p_max ∝ F^(1/2) for a line contact (eq. 4.45); the root stress
    linear in the load for fixed influence coefficients
    (:func:`contact.optimize.development_root.root_capacity_step`).
    """
    fails = check.failures
    if not fails:
        return check.torque, ""
    t = check.torque
    steps = {}
    if "flank" in fails:
        a = (1.0 / 3.0 if previous is None else
             _exponent(previous.torque, previous.pressure, t, check.pressure, 1.0 / 3.0,
                       0.2, 1.0))
        steps["flank"] = t * (margin * check.limit / check.pressure) ** (1.0 / a)
    if "edge" in fails:
        a = (EDGE_EXPONENT if previous is None else
             _exponent(previous.torque, previous.edge_peak, t, check.edge_peak,
                       EDGE_EXPONENT, 0.2, 1.0))
        steps["edge"] = t * (margin * check.limit / check.edge_peak) ** (1.0 / a)
    if "root" in fails:
        if previous is not None and math.isfinite(previous.root_safety):
            b = _exponent(previous.torque, previous.root_safety, t, check.root_safety, 1.0,
                          0.3, 1.0)
        else:
            b = _exponent(check.light_torque, check.light_root_safety, t,
                          check.root_safety, 1.0, 0.3, 1.0)
        steps["root"] = root_capacity_step(t, check.root_safety, check.s_min, margin,
                                           exponent=b)
    if "pitting" in fails:
        if previous is not None and math.isfinite(previous.pitting_safety):
            b = _exponent(previous.torque, previous.pitting_safety, t, check.pitting_safety,
                          1.0 / 3.0, 0.2, 1.0)
        else:
            b = _exponent(check.light_torque, check.light_pitting_safety, t,
                          check.pitting_safety, 1.0 / 3.0, 0.2, 1.0)
        steps["pitting"] = root_capacity_step(t, check.pitting_safety, check.s_h_min,
                                              margin, exponent=b)
    if "plastic" in fails:
        steps["plastic"] = t * PLASTIC_STEP
    why = min(steps, key=steps.get)
    return floor_torque(steps[why]), why


def coast_capacity(analyse: Callable[[float], CoastCheck], start: float,
                   say: Callable[[str], None] = lambda line: None,
                   n_steps: int = COAST_STEPS, n_refine: int = REFINE_STEPS,
                   closeness: float = CLOSENESS, start_name: str = "") -> CoastCapacity:
    """The coast flank's design torque: ``start`` where the coast flank holds there, else
    the largest torque found below it where it holds, each torque tried analysed.

    Two phases: **down**, :func:`coast_torque_step` from the last failing check until one
    holds (at most ``n_steps``); then **up**, between the highest torque that holds and the
    lowest that fails, the step of :func:`coast_torque_step` from the failing one with the
    exponents measured between the two (plastic: their geometric mean), kept inside the
    bracket (at least a tenth of its log-width from either end), until the two are within
    ``closeness`` or the estimate is within 1 % of the torque that holds (at most
    ``n_refine``). A first step that lands far below the capacity
    (the Hertzian exponent of a peak that sits on an edge) is so brought back up: the
    torque written is what the bearing carries, not an arbitrary torque below it.

    Parameters
    ----------
    analyse : callable torque [N·m] → CoastCheck
        The coast flank analysed at its light and design torque (``ltca run --flank
        coast``'s analysis of the case with that coast design torque). An exception ends
        the search (said through ``say``; the torques checked are kept).
    start : float — [N·m] > 0
        The coast design torque to check first: the smaller of the design torque and the
        coast side's ISO 10300 capacity.
    say : callable, optional
        Called with one line where the torque was lowered.
    n_steps, n_refine : int
        Most steps down (default :data:`COAST_STEPS`) and up (:data:`REFINE_STEPS`).
    closeness : float — [1]
        The bracket's ratio below which the search ends (default :data:`CLOSENESS`).
    start_name : str, optional
        What ``start`` is, named before it in the reason ("at its ISO 10300 capacity
        466.1 N m …"; the round-20 reason read "at 466.1 N m …", the number unexplained);
        default none.

    Returns
    -------
    CoastCapacity
        ``holds`` False where no torque tried holds (the reason says "still"); the torque
        is then the last one analysed.

    Raises
    ------
    ValueError
        ``start`` not finite and > 0.
    """
    if not (math.isfinite(start) and start > 0):
        raise ValueError(f"coast capacity: start torque {start} must be finite and > 0")
    checks: list[CoastCheck] = []

    def check_at(t: float) -> CoastCheck | None:
        try:
            c = analyse(t)
        except Exception as exc:  # reported, never fatal: the torques checked are kept
            raise_if_interrupted(exc)
            log.info("coast capacity check at %g N m failed: %s", t, exc)
            say(f"development: coast flank not analysed at {plain_number(t)} N m ({exc})")
            return None
        checks.append(c)
        return c

    first = check_at(start)
    if first is None:
        return CoastCapacity(start, start, (), "", False)
    if not first.failures:
        return CoastCapacity(start, start, tuple(checks), "", True)
    bad, ok, previous = first, None, None
    for _ in range(n_steps):  # down until one holds
        new, _why = coast_torque_step(bad, previous)
        if not (0.0 < new < bad.torque):
            break
        c = check_at(new)
        if c is None:
            break
        if not c.failures:
            ok = c
            break
        previous, bad = bad, c
    for _ in range(n_refine if ok is not None else 0):  # up, inside the bracket
        if bad.torque <= closeness * ok.torque:
            break
        estimate, new = _inside(bad, ok)
        if estimate <= 1.01 * ok.torque or not ok.torque < new < bad.torque:
            break  # the torque that holds is at the capacity (to the margin) already
        c = check_at(new)
        if c is None:
            break
        if c.failures:
            bad = c
        else:
            ok = c
    last = ok if ok is not None else checks[-1]
    holds = ok is not None
    now = "; ".join(_within(last)) if holds else "; ".join(last.failures.values())
    n = len(checks) - 1
    reason = (f"the coast flank's capacity at its developed bearing (ltca run --flank "
              f"coast's analysis): at {start_name + ' ' if start_name else ''}"
              f"{plain_number(start)} N m "
              f"{'; '.join(first.failures.values())}; "
              f"{n} torque{'s' if n != 1 else ''} below checked, the largest that holds "
              f"{plain_number(last.torque)} N m, where {'still ' if not holds else ''}{now}"
              + (f" (at {plain_number(bad.torque)} N m: {'; '.join(bad.failures.values())})"
                 if holds and bad is not first else ""))
    say(f"  coast design torque {plain_number(start)} -> {plain_number(last.torque)} N m: {reason}")
    return CoastCapacity(last.torque, start, tuple(checks), reason, holds)


def _inside(bad: CoastCheck, ok: CoastCheck) -> tuple[float, float]:
    """The capacity estimated between ``ok`` (holds) and ``bad`` (fails) — the step from
    ``bad`` with the exponents measured between the two (:func:`coast_torque_step`;
    plastic, or an edge that carries nothing counted at ``ok``'s torque: their geometric
    mean) — and the next torque to check: that estimate kept a tenth of the bracket's
    log-width from either end, rounded down (``floor_torque``).

    An edge without a counted peak at ``ok`` gives no exponent: the 13×30 at Σ 115°'s
    coast flank stopped at 86.5 N·m (the first step's estimate again) with its edges
    within the static strength up to ≈ 94 N·m."""
    lo, hi = math.log(ok.torque), math.log(bad.torque)
    t, why = coast_torque_step(bad, ok)
    if why == "plastic" or not t > 0 or (why == "edge" and not ok.edge_peak > 0):
        t = math.sqrt(ok.torque * bad.torque)
    x = min(max(math.log(t), lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo))
    return t, floor_torque(math.exp(x))


def _within(c: CoastCheck) -> list[str]:
    """The checked criteria of a check that holds, in numbers."""
    out = [f"flank peak pressure {c.pressure:.0f} MPa within {c.limit:.0f} MPa",
           "no plastic segment" if c.plastic == 0.0 else
           f"plastic share {100 * c.plastic:.2g} % within {100 * c.plastic_limit:g} %"]
    if c.edge_limit and math.isfinite(c.edge_peak):
        out.append(f"edge peak pressure {c.edge_peak:.0f} MPa within {c.limit:.0f} MPa")
    if math.isfinite(c.root_safety) and math.isfinite(c.s_min):
        out.append(f"S_F,FE {c.root_safety:.2f} ({c.member}) >= S_Fmin {c.s_min:g}")
    if math.isfinite(c.pitting_safety) and math.isfinite(c.s_h_min):
        out.append(f"S_H,loc {c.pitting_safety:.2f} ({c.pitting_member}) >= S_Hmin "
                   f"{c.s_h_min:g}")
    return out
