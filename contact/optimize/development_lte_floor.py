"""The load sharing's floor of the LTE between the light and the design torque, and what it
says of the development's LTE target (issue 71: "``ltca synthesize`` meets every
development target on the drive flank").

The loaded TE of a flank at a torque T is TE(φ, T) = UTE(φ) + δ(φ, T): the unloaded TE
(the modified roll's parabola, the crownings, the reliefs) plus the mesh deflection. The
unloaded TE is the same at every torque, so for the light and the design torque

    p-p(TE_design − TE_light) = p-p(δ_design − δ_light) ≤ LTE_light + LTE_design,

hence max(LTE_light, LTE_design) ≥ ½ p-p(TE_design − TE_light), the **floor**: no TE
parabola, crowning or relief that leaves the load sharing as it is gets both torques' LTE
below it (docs/synthesis.md, "The LTE floor of a face contact ratio near 1"). The TE
parabola trades the two torques' LTE about it (the classical rule: its depth matched to
the deflection's change, the two meet near the floor); only a bearing that shares the load
earlier lowers it. Where the development's target ``max_lte`` is at or below the floor of
the written bearing, the target is out of that bearing's TE and relief levers' reach;
where it is above, the floor does not hold the LTE and the bearing's levers might still
reach it. :func:`floor_text` says which, in numbers, on ``ltca synthesize``'s drive LTE
line (:func:`contact.optimize.development_lte_lines.flank_lte_line`).

Measured on the written drive flanks of benchmarks/data/unseen_designs (``benchmarks/
development_levers.py --check --floor 4 --from-case``, 2026-11-29; docs/synthesis.md,
"The drive LTE target against the levers"): the FM spiral bevel 19x33 at Σ 78° (ε_vβ
1.23) floor 37 µrad at 59.2 / 394.7 N m (LTE 25 / 60), its TE parabola deepened to 150
µrad 45 / 44 µrad (floor 41); its bearing developed at 394.7 N m floor 30 (24 / 44), at
te_level 130 µrad 40.7 / 40.5 (floor 38.5): the target at the floor. The FM hypoid 13x33
at Σ 85° (ε_vβ 1.03) floor 27 µrad at 59 / 393.5 N m (LTE 16 / 53): the target above it,
its LTE the bearing's (a hollow profile −8 µm: 25 / 38 µrad, floor 17.5, with 2.3 % of
the torque on the edges).

Public names
------------
te_floor, load_sharing_floor, floor_text
"""

from __future__ import annotations

import logging
import math

import numpy as np
import xarray as xr

from geometry.case import Case

__all__ = ["floor_or_nan", "floor_text", "load_sharing_floor", "te_floor"]

log = logging.getLogger("contact.optimize.development")


def te_floor(ltca: xr.Dataset) -> float:
    """½ p-p over the mesh cycle of the loaded TE at the largest torque less that at the
    least, of an ``/ltca`` dataset analysed at two or more torques.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``transmission_error`` [µrad] with a ``torque`` dimension (pinion torque [N·m]) and
        the roll positions of one mesh cycle; NaN entries (no contact solved there) are
        left out.

    Returns
    -------
    float — [µrad]
        The floor; NaN where fewer than two torques or no roll position has both values.

    Raises
    ------
    KeyError
        ``transmission_error`` or ``torque`` missing.

    Notes
    -----
    The unloaded TE cancels in the difference, so the floor is that of the mesh deflection
    alone: max(LTE_least, LTE_largest) ≥ it whatever the unloaded TE (module docstring;
    docs/synthesis.md, "The LTE floor of a face contact ratio near 1", where it agreed with
    the same bound from the mesh stiffness k_Θ within 2-3 µrad).
    """
    te = ltca["transmission_error"].transpose("torque", ...)
    torques = np.asarray(ltca["torque"].values, float)
    if torques.size < 2:
        return math.nan
    values = np.asarray(te.values, float).reshape(torques.size, -1)
    diff = values[int(np.argmax(torques))] - values[int(np.argmin(torques))]
    diff = diff[np.isfinite(diff)]
    return 0.5 * float(np.ptp(diff)) if diff.size else math.nan


def load_sharing_floor(case: Case, light: float, design: float,
                       flank: str = "drive") -> float:
    """:func:`te_floor` of a written case's flank between its light and design torque,
    analysed as ``ltca run`` does (its default LTCA sampling and compliance, the contact
    analysis alone; one analysis at the two torques).

    Parameters
    ----------
    case : geometry.case.Case
    light, design : float — [N·m]
        The pinion torques, ``0 < light < design``.
    flank : str
        ``"drive"`` (default) or ``"coast"``.

    Returns
    -------
    float — [µrad]

    Raises
    ------
    ValueError
        ``light`` not positive or not below ``design``.
    InputError
        From the analysis (a case it cannot analyse).
    """
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis

    light, design = float(light), float(design)
    if not (0.0 < light < design and math.isfinite(design)):
        raise ValueError(f"load_sharing_floor: torques must satisfy 0 < light < design, "
                         f"got {light} / {design} N m")
    tree = run_analysis(case, [light, design], flank=flank, deviations=False,
                        steps=AnalysisChain.contact_only())
    return te_floor(tree["/ltca"].to_dataset())


def floor_or_nan(case: Case, light: float, design: float) -> float:
    """:func:`load_sharing_floor` of the written case's drive flank [µrad], or NaN where
    the analysis fails (logged, not raised): the development's step after the cut and
    ``ltca synthesize``'s LTE line ask for it as a reading, not as a check.

    Parameters
    ----------
    case : geometry.case.Case
    light, design : float — [N·m]

    Returns
    -------
    float — [µrad], NaN where not analysed.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 (the floor, :func:`te_floor`: ½ p-p(TE_design − TE_light)).
    """
    from geometry.core.errors import InputError

    try:
        return load_sharing_floor(case, light, design)
    except (InputError, ValueError, KeyError) as exc:
        log.info("development: the drive LTE's load-sharing floor not analysed: %s", exc)
        return math.nan


def floor_text(floor: float, target: float) -> str:
    """What the load sharing's floor says of the development's LTE target, in words, for
    ``ltca synthesize``'s drive LTE line where the target is missed.

    Parameters
    ----------
    floor : float — [µrad]
        The written flank's :func:`te_floor` between its light and design torque.
    target : float — [µrad]
        The development's LTE target (``max_lte``).

    Returns
    -------
    str
        "" where ``floor`` is not finite; else, e.g., "; the load sharing's floor 1/2
        p-p(TE_design - TE_light) 37 urad (no TE parabola or relief gets both torques
        below it): the target is above it, so the bearing's LTE, not the contact ratio's
        floor, misses it" or "…: the target is at or below it, out of this bearing's
        reach (its TE parabola trades the two torques' LTE about the floor); a bearing
        that shares the load earlier (longer, flatter) or higher contact ratios lower it".

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: module docstring. The target is never relaxed: the line states the two
    numbers.
    """
    floor, target = float(floor), float(target)
    if not math.isfinite(floor):
        return ""
    said = (f"; the load sharing's floor 1/2 p-p(TE_design - TE_light) {floor:.0f} urad "
            "(no TE parabola or relief gets both torques below it)")
    if floor < target:
        return said + (f": the target {target:g} urad is above it, so the bearing's LTE, "
                       "not the contact ratio's floor, misses it")
    return said + (f": the target {target:g} urad is at or below it, out of this bearing's "
                   "reach (its TE parabola trades the two torques' LTE about the floor); a "
                   "bearing that shares the load earlier (longer, flatter) or higher "
                   "contact ratios lower it")
