"""The root-stress capacity of a developed design (issue 71 item 2: one design torque that
holds).

The development's design torque is by default the ISO 10300 capacity, which rates the root
by torque-independent factors (Y_Fa·Y_Sa, K_Fβ of a nominal bearing). The verdict judges the
FE peak root stress of the developed bearing itself (:mod:`contact.study.verdict_checks`,
"Root stress": S_F,FE = σ_FP / (σ_FE,max·K_A·K_v) against S_Fmin). :func:`root_capacity`
computes that safety on the written case at ``ltca run``'s sampling with the same FE model
``ltca run`` builds by default (cached by the members' geometry, so ``ltca run`` afterwards
reads it) and, where S_F,FE is below S_Fmin at the design torque, lowers the design torque
to the root-stress capacity :func:`root_capacity_step`. Imported by
:mod:`contact.optimize.development`.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from contact.optimize.development_result import STATIC_MARGIN

log = logging.getLogger(__name__)

#: most steps of :func:`root_capacity` (each an LTCA and the root stress at the new torques)
ROOT_STEPS = 2


def root_capacity_step(torque: float, safety: float, s_min: float,
                       margin: float = STATIC_MARGIN) -> float:
    """The root-stress capacity [N·m] from a safety at one torque: T · m · S_F,FE / S_Fmin,
    rounded down to 0.1 N·m (4 significant digits).

    The FE root stress is linear in the load to first order (σ_FE,max ∝ T: the fillet's
    influence coefficients are linear, the load sharing between teeth changes little with
    the torque), so S_F,FE ∝ 1/T and S_F,FE reaches S_Fmin at T·S_F,FE/S_Fmin. K_v depends
    weakly on the torque (ISO 10300-1 Method B: K_v − 1 ∝ 1/(F/b), so it grows a little as
    the torque falls): the margin ``m`` (default 0.99, :data:`STATIC_MARGIN`, as the flank
    capacity) covers most of that, and :func:`root_capacity` checks the result and steps
    again.

    Parameters
    ----------
    torque : float — [N·m] the pinion torque the safety was computed at (> 0)
    safety : float — [1] S_F,FE of the weaker member there
    s_min : float — [1] the rating's S_Fmin (> 0)
    margin : float — [1] in (0, 1]

    Returns
    -------
    float — [N·m]

    Raises
    ------
    ValueError
        A non-positive or non-finite input.
    """
    if not (torque > 0 and s_min > 0 and safety > 0 and 0 < margin <= 1
            and math.isfinite(torque * safety * s_min)):
        raise ValueError(f"root capacity: torque {torque}, S_F,FE {safety}, S_Fmin {s_min} "
                         f"and margin {margin} must be finite and > 0 (margin <= 1)")
    t = torque * margin * safety / s_min
    return float(f"{math.floor(10.0 * t) / 10.0:.4g}")


def root_safety(tree) -> tuple[np.ndarray, float, str]:
    """(S_F,FE of the weaker member per torque [1], S_Fmin [1], its member) of an analysis
    with root stress and an ISO 10300 ``/rating`` at the same torques — the verdict's
    :func:`contact.study.verdict_checks.root_stress_safety`.

    Raises
    ------
    LookupError
        No ``root_stress_max`` or no ISO ``/rating`` at the same torques (the reason).
    """
    from contact.study.verdict_checks import _iso_rating, _member_names, root_stress_safety

    lt = tree["/ltca"].to_dataset()
    if "root_stress_max" not in lt:
        why = lt.attrs.get("root_stress_not_run", "") or "no root_stress_max"
        raise LookupError(f"no root stress ({why})")
    rt = tree["/rating"].to_dataset() if "/rating" in tree.groups else None
    rs = lt["root_stress_max"].transpose("torque", "member")
    if not _iso_rating(rt) or not np.array_equal(rt["torque"].values, rs["torque"].values):
        raise LookupError("no ISO 10300 rating at the analysed torques (a pinion speed and a "
                          "[rating] material are needed)")
    s = root_stress_safety(np.asarray(rs.values, float), rt)
    j = int(np.nanargmin(s[-1]))
    return s[:, j], float(rt["S_Fmin"]), _member_names(rs)[j]


def _root_tree(case, torques: list[float]):
    """``ltca run``'s drive-flank analysis of ``case`` at ``torques`` with the root stress
    (its default FE model) and the ISO 10300 rating, without the mesh interface (the
    efficiency stage is run: the rating takes the pinion speed from it, as in
    ``ltca run``)."""
    from contact.chain import AnalysisChain
    from contact.optimize.development import CHECK_LTCA
    from contact.pipeline import run_analysis

    steps = (AnalysisChain.contact_only().with_root_stress().with_efficiency()
             .with_load_capacity())
    return run_analysis(case, torques, flank="drive", options=CHECK_LTCA, deviations=False,
                        steps=steps)


def root_capacity(case, setup: dict[str, Any], light_load: float,
                  say: Callable[[str], None]) -> tuple[Any, float, str]:
    """Check the written ``case``'s FE root stress at the design torque
    (``setup["torques"][1]``) and lower the design torque to its root-stress capacity where
    S_F,FE < S_Fmin there: T ← :func:`root_capacity_step`, checked at the new light
    (``light_load`` × T) and design torque and stepped again from the new safety while
    still below (at most :data:`ROOT_STEPS`). ``setup`` gets the new torques, source and
    ``lowered`` where lowered.

    Returns
    -------
    (tree or None, S_F,FE, text)
        The analysis at the torques finally kept where the torque was lowered (its drive
        metrics replace the check's), else None; the weaker member's S_F,FE at the design
        torque written (NaN where not computed); one phrase for the case's records (empty
        where nothing was lowered).
    """
    torque = float(setup["torques"][1])
    try:
        safety, s_min, member = root_safety(_root_tree(case, [torque]))
    except Exception as exc:  # reported, never fatal (ltca run says it)
        log.info("development root stress check not made: %s", exc)
        say(f"development: root stress not checked ({exc})")
        return None, math.nan, ""
    s = float(safety[-1])
    if not (math.isfinite(s) and s < s_min):
        say(f"development: FE root stress at {torque:.4g} N m: S_F,FE {s:.2f} ({member}) "
            f">= S_Fmin {s_min:g}")
        return None, s, ""
    first, t, tree, torques = (s, torque), torque, None, list(setup["torques"])
    for _ in range(ROOT_STEPS):
        t = root_capacity_step(t, s, s_min)
        torques = [light_load * t, t]
        tree = _root_tree(case, torques)
        safety, s_min, member = root_safety(tree)
        s = float(safety[-1])
        if s >= s_min:
            break
    source = (f"the root-stress capacity of the developed bearing: its FE root stress gives "
              f"S_F,FE {first[0]:.2f} ({member}) below S_Fmin {s_min:g} at the design "
              f"torque {first[1]:.4g} N m ({setup['source'].split(',')[0].split(':')[0]}); "
              f"T S_F,FE/S_Fmin x {STATIC_MARGIN:g} -> {t:.4g} N m, where S_F,FE is "
              f"{s:.2f}{'' if s >= s_min else ' (still below)'}")
    say(f"  design torque {first[1]:.4g} -> {t:.4g} N m: {source}")
    setup.update(torques=torques, source=source, lowered=True)
    return tree, s, source
