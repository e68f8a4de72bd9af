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
ROOT_STEPS = 3


def root_capacity_step(torque: float, safety: float, s_min: float,
                       margin: float = STATIC_MARGIN, exponent: float = 1.0) -> float:
    """The root-stress capacity [N·m] from a safety at one torque:
    T · (m · S_F,FE / S_Fmin)^(1/b), rounded down to 0.1 N·m (4 significant digits).

    With S_F,FE ∝ T^(−b): b = 1 where the FE root stress is linear in the load (the
    fillet's influence coefficients are linear; T·S_F,FE/S_Fmin). A localised bearing
    spreads its load over more of the face and more teeth as the torque grows, so the peak
    root stress grows more slowly than the torque (measured b ≈ 0.55 near the design
    torque of the 10×43 hypoid): :func:`root_capacity` measures b on the bearing. K_v
    depends weakly on the torque (ISO 10300-1 Method B: K_v − 1 ∝ 1/(F/b), it grows a
    little as the torque falls); it is in the measured S_F,FE, and the margin ``m``
    (default 0.99, :data:`STATIC_MARGIN`, as the flank capacity) covers the rest.

    Parameters
    ----------
    torque : float — [N·m] the pinion torque the safety was computed at (> 0)
    safety : float — [1] S_F,FE of the weaker member there
    s_min : float — [1] the rating's S_Fmin (> 0)
    margin : float — [1] in (0, 1]
    exponent : float — [1] b of S_F,FE ∝ T^(−b), in [0.2, 1.5]

    Returns
    -------
    float — [N·m]

    Raises
    ------
    ValueError
        A non-positive or non-finite input.
    """
    if not (torque > 0 and s_min > 0 and safety > 0 and 0 < margin <= 1
            and 0.2 <= exponent <= 1.5 and math.isfinite(torque * safety * s_min)):
        raise ValueError(f"root capacity: torque {torque}, S_F,FE {safety}, S_Fmin {s_min} "
                         f"and margin {margin} must be finite and > 0 (margin <= 1), "
                         f"exponent {exponent} in [0.2, 1.5]")
    t = torque * (margin * safety / s_min) ** (1.0 / exponent)
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
    from contact.study.verdict_checks import has_iso_rating, member_names, root_stress_safety

    lt = tree["/ltca"].to_dataset()
    if "root_stress_max" not in lt:
        why = lt.attrs.get("root_stress_not_run", "") or "no root_stress_max"
        raise LookupError(f"no root stress ({why})")
    rt = tree["/rating"].to_dataset() if "/rating" in tree.groups else None
    rs = lt["root_stress_max"].transpose("torque", "member")
    if not has_iso_rating(rt) or not np.array_equal(rt["torque"].values, rs["torque"].values):
        raise LookupError("no ISO 10300 rating at the analysed torques (a pinion speed and a "
                          "[rating] material are needed)")
    s = root_stress_safety(np.asarray(rs.values, float), rt)
    j = int(np.nanargmin(s[-1]))
    return s[:, j], float(rt["S_Fmin"]), member_names(rs)[j]


def both_flanks_built(case) -> None:
    """Both members' default FE models of the written ``case`` built once for both flanks
    (:func:`contact.compliance.fe.influence_coefficients` with ``other_flank``: the coast
    flank's coefficients on the drive build's solid and factorisation, the same numbers as
    a build of their own), cached for the drive flank's root-stress check, the coast
    flank's and ``ltca run`` afterwards: 1.4–1.5 builds per member instead of 2 (issue 75).
    Nothing where both are cached. A failure is logged and not raised: each check then
    builds (or fails to build) its own model and says so, as before."""
    from contact.compliance.fe import influence_coefficients

    for member in ("pinion", "gear"):
        try:
            influence_coefficients(case, member, "drive", progress=False, other_flank=True)
        except Exception as exc:  # the checks build their own and report (never fatal)
            log.info("development: the %s's FE models of both flanks not built: %s",
                     member, exc)


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
    S_F,FE < S_Fmin there: T ← :func:`root_capacity_step` with the exponent b of
    S_F,FE ∝ T^(−b) measured between the light and the design torque, checked at the new
    light (``light_load`` × T) and design torque and stepped again, b measured between the
    last two design torques, while still below (at most :data:`ROOT_STEPS`). ``setup``
    gets the new torques, source and ``lowered`` where lowered. An analysis that fails is
    said through ``say`` and never raised (the torque last checked is kept).

    Returns
    -------
    (tree or None, S_F,FE, text)
        The analysis at the torques finally kept where the torque was lowered (its drive
        metrics replace the check's), else None; the weaker member's S_F,FE at the design
        torque written (NaN where not computed); one phrase for the case's records (empty
        where nothing was lowered).
    """
    torques = [float(t) for t in setup["torques"]]
    torque = torques[1]
    try:
        safety, s_min, member = root_safety(_root_tree(case, torques))
    except Exception as exc:  # reported, never fatal (ltca run says it)
        log.info("development root stress check not made: %s", exc)
        say(f"development: root stress not checked ({exc})")
        return None, math.nan, ""
    s = float(safety[-1])
    if not (math.isfinite(s) and s < s_min):
        say(f"development: FE root stress at {torque:.4g} N m: S_F,FE {s:.2f} ({member}) "
            f">= S_Fmin {s_min:g}")
        return None, s, ""
    # the exponent b of S_F,FE ∝ T^(-b) first from the light and the design torque, then
    # from the last two design torques (the local slope)
    first, t, tree, used = (s, torque, member), torque, None, []
    b = _exponent(torques[0], float(safety[0]), torque, s)
    for _ in range(ROOT_STEPS):
        new = root_capacity_step(t, s, s_min, exponent=b)
        if new >= t:
            break
        try:
            step = _root_tree(case, [light_load * new, new])
            safety, s_min, member = root_safety(step)
        except Exception as exc:  # reported, never fatal: the last torque checked is kept
            log.info("development root stress at %g N m failed: %s", new, exc)
            say(f"development: root stress at {new:.4g} N m not computed ({exc})")
            break
        tree, torques, used = step, [light_load * new, new], [*used, b]
        b = _exponent(new, float(safety[-1]), t, s, b)
        t, s = new, float(safety[-1])
        if s >= s_min:
            break
    if tree is None:  # no lower torque checked
        return None, first[0], ""
    source = (f"the root-stress capacity of the developed bearing: its FE root stress gives "
              f"S_F,FE {first[0]:.2f} ({first[2]}) below S_Fmin {s_min:g} at the design "
              f"torque {first[1]:.4g} N m ({setup['source'].split(',')[0].split(':')[0]}); "
              f"T (0.99 S_F,FE/S_Fmin)^(1/b) in {len(used)} step"
              f"{'s' if len(used) > 1 else ''}, b = "
              f"{'/'.join(f'{x:.2f}' for x in used)} measured (S_F,FE ~ T^-b) -> "
              f"{t:.4g} N m, where S_F,FE ({member}) is "
              f"{s:.2f}{'' if s >= s_min else ' (still below)'}")
    say(f"  design torque {first[1]:.4g} -> {t:.4g} N m: {source}")
    setup.update(torques=torques, source=source, lowered=True)
    return tree, s, source


def _exponent(t1: float, s1: float, t2: float, s2: float, default: float = 1.0) -> float:
    """b of S_F,FE ∝ T^(−b) between two torques, bounded to [0.3, 1] (``default`` where not
    measurable)."""
    if not (t1 > 0 and t2 > 0 and t1 != t2 and s1 > 0 and s2 > 0
            and math.isfinite(s1 * s2)):
        return default
    return min(1.0, max(0.3, math.log(s1 / s2) / math.log(t2 / t1)))
