"""Step 5's second lever for the twist: the modified roll's 2C that cancels the TE's third
order at M.

Step 5 (:func:`geometry.synthesis.pinion.pinion_generate_tools`) makes the local
synthesis's mismatch by the pinion cutter's point radius, its blade's profile curvature
and the ratio of roll R_a. Where R_a must move far from the conjugate's (the face-milled
spiral bevel miter 12x12 at β_m 35°: −22 %), the flank it generates departs from the
prescribed TE at third, fourth and higher order (+192 / −1050 µrad at ±pitch/4 against
the parabola's 2.8 µrad), more than step 6's 6D and 24E can correct. The modified roll's
2C (the generating motion's second order, φ(q) = R_a (q − C q² − …)) bends the flank at M
too, so step 5 meets the same shape operator with a given 2C and another R_a; this module
finds the 2C at which the step-5 flank's TE has no third-order term at M (the cubic c3 of
:func:`geometry.synthesis.modified_roll.third_order_te` zero), by the secant method.

Not called by :func:`geometry.synthesis.case_synthesis.synthesize` (issue 71, branch
miter84, docs/own_gear_set.md "The 12-tooth miter and the modified roll's 2C"): on the
12x12 it cancels the cubic (TE at ±pitch/4 +192 / −1050 → −29 / −30 µrad) but leaves a
quartic whose 24E (−16.7) leaves the mean section's M and root end ungenerated, and with
the quartic left in (24E 0) the written case has a UTE of 2516 µrad p-p.

Public functions
----------------
RollCurvature             the 2C found, its tools and the cubic before and after
third_order_cancelling    the 2C at which the TE's cubic at M vanishes (secant)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, NamedTuple

from geometry.core.errors import InputError

__all__ = ["ROLL_CURVATURE_STEP", "RollCurvature", "third_order_cancelling"]

#: [1/rad] the secant's first step in 2C from 0 (the 12x12 miter's root is −0.078; its
#: TE's odd part at ±pitch/8, +85.4 / +8.2 / −20.0 µrad at 2C 0 / −0.07 / −0.10, lies off
#: the line through the ends by 4 % of its 2C-free value, docs/own_gear_set.md)
ROLL_CURVATURE_STEP = -0.02

#: [1/rad] the largest |2C| the search accepts (a machine's modified roll stays well below;
#: the 12x12 miter's is 0.08)
ROLL_CURVATURE_LIMIT = 0.5


class RollCurvature(NamedTuple):
    """Result of :func:`third_order_cancelling`."""

    c2: float  # [1/rad] the modified roll's 2C
    tools: Any  # step 5's tools at that 2C
    c3_before: float  # [1/rad²] the TE's cubic at M without 2C
    c3: float  # [1/rad²] the TE's cubic at M at c2


def third_order_cancelling(tools_at: Callable[[float], Any], cubic: Callable[[Any], float], *,
                           c3_zero: float | None = None, tools_zero: Any = None,
                           tol: float = 1e-3, steps: int = 4) -> RollCurvature:
    """The modified roll's 2C at which step 5's flank has no third-order TE at M.

    Parameters
    ----------
    tools_at : callable
        ``tools_at(c2)`` → step 5's tools generated with the modified roll's 2C ``c2``
        [1/rad] (:func:`geometry.synthesis.pinion.pinion_generate_tools`'s
        ``roll_curvature``); raises InputError where step 5 has no solution.
    cubic : callable
        ``cubic(tools)`` → the TE's coefficient of roll³ at M [1/rad²]
        (:func:`geometry.synthesis.modified_roll.third_order_te`'s ``c3``).
    c3_zero, tools_zero : optional
        The cubic and tools at 2C = 0 where known (the failed synthesis's).
    tol : float — [1]
        Accepted |c3| as a fraction of |c3| at 2C = 0 (default 1e-3).
    steps : int
        Secant steps after the first (default 4).

    Returns
    -------
    RollCurvature
        2C, its tools, the cubic at 2C = 0 and at 2C.

    Raises
    ------
    InputError
        Where the cubic does not change with 2C, the secant leaves |2C| <=
        :data:`ROLL_CURVATURE_LIMIT` or misses ``tol`` after ``steps`` steps (the
        message names the last 2C and cubic); a step-5 or TE failure of ``tools_at`` or
        ``cubic`` as itself.

    Notes
    -----
    The secant method on c3(2C), which is nearly linear (the 12x12 miter's drive flank: the
    odd part of its TE at ±pitch/8 +85.4, +8.2, −20.0 µrad at 2C 0, −0.07, −0.10; the
    secant from 0 and −0.02 lands on −0.0784 in three steps, c3 0.1339 → 2.8e-5). Source
    of the lever: the modified roll's second-order coefficient changes the generated
    flank's curvature at the mean point (Litvin & Fuentes 2004 ch. 6, the curvatures of an
    envelope under a non-uniform generating motion; Stadtfeld 2014, "modified roll" among
    the basic settings of the pinion's flank form).
    """
    c_prev = 0.0
    if tools_zero is None:
        tools_zero = tools_at(0.0)
    f_prev = cubic(tools_zero) if c3_zero is None else c3_zero
    c3_before = f_prev
    c = ROLL_CURVATURE_STEP
    tools = tools_at(c)
    f = cubic(tools)
    for _ in range(steps + 1):
        if abs(f) <= tol * abs(c3_before):
            return RollCurvature(c, tools, c3_before, f)
        if f == f_prev or not math.isfinite(f):
            break
        c_next = c - f * (c - c_prev) / (f - f_prev)
        if not abs(c_next) <= ROLL_CURVATURE_LIMIT:
            break
        c_prev, f_prev, c = c, f, c_next
        tools = tools_at(c)
        f = cubic(tools)
    raise InputError(f"synthesis: no modified roll 2C within +/-{ROLL_CURVATURE_LIMIT} "
                     f"1/rad cancels the TE's third order at M (2C {c:.4g}: cubic "
                     f"{f:.4g} 1/rad^2 against {c3_before:.4g} without it)")
