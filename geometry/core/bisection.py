"""Bisection for the largest argument at which a trial still succeeds.

:func:`largest_found` serves the searches that ask "how far can this go": the largest shaft
angle at which an ISO 23509 method still closes the pitch cone
(:mod:`geometry.iso23509.pitch_cone`), the largest rounding radius whose arc still fits a
tooth section (:mod:`contact.compliance.fe.section`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

__all__ = ["largest_found"]

T = TypeVar("T")


def largest_found(trial: Callable[[float], T | None], lo: float, hi: float, steps: int,
                  found: T | None = None) -> tuple[float, T | None]:
    """The largest x in [lo, hi] found, by ``steps`` bisections, at which ``trial(x)`` is
    not None, with that value.

    Parameters
    ----------
    trial : callable
        ``trial(x)``: a result where x succeeds, None where it fails; taken to succeed below
        some x* and fail above it (a monotone trial).
    lo, hi : float
        The interval's ends, in the unit of x; ``hi`` taken to fail (it is not tried).
    steps : int
        Bisections (the interval is halved ``steps`` times: x is found to
        (hi − lo) / 2**steps).
    found : optional
        ``trial(lo)`` where the caller has it (None: lo not known to succeed).

    Returns
    -------
    (float, result or None)
        The largest x tried that succeeded (``lo`` where none did) and its result
        (``found`` where none did).

    Notes
    -----
    Plain interval halving (bisection method); no gear model.
    """
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        result = trial(mid)
        if result is None:
            hi = mid
        else:
            lo, found = mid, result
    return lo, found
