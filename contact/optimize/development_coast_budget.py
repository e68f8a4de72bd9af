"""The coast flank's search budget extended once (:func:`extended_coast_budget`): where
the coast development (:func:`contact.optimize.development_coast_flank.coast_development`)
spent every design of ``coast_max_evaluations`` and the design it chose still fails one
of issue 71's criteria (:func:`issue71_misses`: edge contact at the light torque, a
plastic segment at either torque, LTE p-p above the verdict's limit at either torque),
its search goes on once, by at most :data:`COAST_EXTRA_DESIGNS` designs.

Why: measured on the face-hobbed spiral bevel 13x30 at Σ 115° of
``benchmarks/data/unseen_designs`` (docs/synthesis.md, "Coast budget extended once";
issue 71, branch coastbudget85, 2026-11-28). With the default 20 designs its coast flank
was written with edge contact at 15 % of the design torque (``p_max edge`` 519 MPa at
40.8 N·m): the bearing stage took 3 designs, the height root-find of the best bearing 5,
its relief stage 4 (the budget that bearing's relief was left, one Sobol point and a
recentring before the minimiser was stopped), the second bearing 6 and the TE stage 2;
the coarse search's best stayed the third design (objective 7.65) from design 4 to 20.
The search was stopped, not converged: its objective no longer fell because the relief
of its best bearing was cut at 4 designs, so "the last designs still improved" does not
tell this flank apart and the rule does not ask it. A design that meets its targets, or
whose search ends before its budget, is never extended (the bundled designs
``tests/data/designs/pc_hypoid_10x43.toml`` and ``fh_spiral_bevel_12x37_m3.toml`` write
the same case).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from geometry.core.errors import InputError

#: designs the coast search may add, once, where it spent its budget with a criterion of
#: issue 71 still failed (:func:`extended_coast_budget`): 20 → 40 at the default budget
COAST_EXTRA_DESIGNS = 20


def issue71_misses(metrics: Mapping[str, np.ndarray], lte_limit: float = 60.0) -> list[str]:
    """Which of issue 71's criteria a coast design's metrics fail.

    Parameters
    ----------
    metrics : mapping name → ndarray (2,)
        :data:`contact.optimize.development_targets.METRIC_NAMES` at the (light, design)
        torque: ``edge_load_share`` [1] (share of the torque the edges carry),
        ``plastic_share`` [1], ``lte_peak_to_peak`` [µrad].
    lte_limit : float
        The verdict's LTE p-p limit [µrad] (:data:`contact.study.verdicts.LTE_LIMIT`,
        60), > 0.

    Returns
    -------
    list of str
        ``"edge at light load"`` (edge share above 0 at the light torque: the issue's "no
        edge contact at 15 % of the design torque"), ``"plastic"`` (a plastic share above
        0 at either torque), ``"LTE above <limit> urad"`` (at either torque); NaN metrics
        (a failed analysis) fail every criterion. Empty where all hold.

    Raises
    ------
    InputError
        ``lte_limit`` not a finite number above 0.

    Source: issue 71's Done-when criteria (no plastic segment, no edge contact at 15 % of
    the design torque, LTE p-p ≤ 60 µrad at every torque).
    """
    if not (isinstance(lte_limit, (int, float)) and math.isfinite(lte_limit)
            and lte_limit > 0.0):
        raise InputError(f"lte_limit: must be a finite number above 0 [urad], got "
                         f"{lte_limit!r}")
    edge = float(np.asarray(metrics["edge_load_share"], float)[0])
    plastic = np.asarray(metrics["plastic_share"], float)
    lte = np.asarray(metrics["lte_peak_to_peak"], float)
    out = []
    if not edge <= 0.0:  # NaN fails
        out.append("edge at light load")
    if not np.all(plastic <= 0.0):
        out.append("plastic")
    if not np.all(lte <= lte_limit):
        out.append(f"LTE above {lte_limit:g} urad")
    return out


def extended_coast_budget(n_done: int, n_max: int, misses: list[str],
                          extra: int = COAST_EXTRA_DESIGNS) -> int:
    """The coast search's budget after its first search: ``n_max + extra`` where it spent
    every design of ``n_max`` (``n_done`` ≥ ``n_max``) and its chosen design still fails a
    criterion of issue 71 (``misses``, :func:`issue71_misses`, not empty), else ``n_max``
    (a search ended by a design meeting every target, or a chosen design meeting the
    issue's criteria, is not extended). Applied once: the caller does not ask again.

    Parameters
    ----------
    n_done : int
        Designs the search analysed, ≥ 0.
    n_max : int
        Its budget (``[development] coast_max_evaluations``), ≥ 1.
    misses : list of str
        The criteria of issue 71 its chosen design fails.
    extra : int
        Designs the extension may add, ≥ 0 (default :data:`COAST_EXTRA_DESIGNS`).

    Returns
    -------
    int
        The budget [designs] the search runs on with.

    Raises
    ------
    InputError
        ``n_done`` below 0, ``n_max`` below 1 or ``extra`` below 0 (or not integers).

    Source: the measurement in this module's docstring (issue 71).
    """
    for name, value, low in (("n_done", n_done, 0), ("n_max", n_max, 1),
                             ("extra", extra, 0)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
            raise InputError(f"{name}: must be an integer >= {low} [designs], got {value!r}")
    if n_done < n_max or not misses:
        return int(n_max)
    return int(n_max + extra)
