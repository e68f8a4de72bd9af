"""What every solver backend returns to the registry, and the accuracy levels."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["ACCURACY_LEVELS", "Backend", "RawResult", "quiet_highs_banner"]

#: Absolute tolerance asked of a backend on the scaled problem (see
#: ``ContactProblem.scaled``), per accuracy level — the levels of qpbenchmark.
#: "high" is what certification at the toolkit tolerance needs for solvers that
#: are not polished; "default" leaves each backend at its own defaults.
ACCURACY_LEVELS: dict[str, float | None] = {"high": 1e-9, "default": None, "low": 1e-3}


@dataclass
class RawResult:
    """A backend's answer in physical units, before our own certification.

    ``force`` [N] and ``rotation`` [rad] may be None when the backend returned
    nothing; ``claimed`` is the backend's own success flag.
    """

    force: np.ndarray | None
    rotation: float | None
    claimed: bool
    status: str
    build_time: float
    solve_time: float
    iterations: int = -1
    extras: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Backend:
    """A registered solver.

    Attributes
    ----------
    name : str
        Registry name (qpsolvers name, ``cvxpy``, ``cvxpy:NAME``, ``active_set``).
    family : str
        ``active-set``, ``interior-point``, ``ADMM``, ``augmented-Lagrangian``,
        ``conic``, ``modelling`` — used for tolerance tables and reports.
    solve : callable
        ``solve(problem, *, accuracy, initial, **options) -> RawResult``.
    warm_start : bool
        Accepts a previous solution as a warm start.
    description : str
    """

    name: str
    family: str
    solve: Callable[..., RawResult]
    warm_start: bool
    description: str


#: whether this process has made its first HiGHS object (:func:`quiet_highs_banner`)
_highs_started = False


def quiet_highs_banner() -> None:
    """Make the process's first HiGHS object with the C-level standard output on the null
    device: highspy prints its banner ("Running HiGHS …", two lines) to file descriptor 1
    when the first ``Highs()`` is made, before any option (``log_to_console``, which
    qpsolvers sets off) can be set — in the middle of whatever the CLI prints then
    (`ltca compare-solvers`' table header). Later objects print nothing. Once per process;
    a failure leaves the banner, never the solve."""
    global _highs_started
    if _highs_started:
        return
    _highs_started = True
    import os
    import sys

    try:
        import highspy
    except ImportError:  # pragma: no cover - qpsolvers lists highs only where it imports
        return
    sys.stdout.flush()
    try:
        saved = os.dup(1)
    except OSError:  # pragma: no cover - no file descriptor 1
        return
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            highspy.Highs()
    finally:
        os.dup2(saved, 1)
        os.close(saved)
