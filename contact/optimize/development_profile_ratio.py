"""The development's check step for a profile contact ratio below 1 (issue 71): the load
handed over along the face.

:func:`checked_profile_ratio` gives a drive design whose LTE p-p at the check exceeds the
verdict's limit, on a pair whose profile contact ratio ε_vα is below 1 or just above it
(below :data:`PROFILE_RATIO_MIN`, 1.05), the bearing that
lets the face overlap bridge the profile's shortfall: the contact path turned to the
profile bound of its variable together with the long bearing (the ellipse at its upper
bound, the root relief entering at the upper bound of its start, its slope kept,
:func:`~contact.optimize.development_check.long_bearing`) and no profile crowning; then,
where that is kept and the LTE is still above the limit, its tip relief halved and entering
at the upper bound of its start. Each design is kept on the check steps' one rule
(:func:`~contact.optimize.development_check.kept_why`: better, no met target lost,
tolerant at the mounting excursions). A design within the limit, or of
ε_vα ≥ :data:`PROFILE_RATIO_MIN`, is returned as it is, without an analysis: the step
changes nothing the development writes for such designs.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_check import long_bearing
from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import (
    CROWNING_NAME,
    DevelopmentTargets,
)
from contact.optimize.development_variant import said_variant
from geometry.case import Case

log = logging.getLogger("contact.optimize.development")

#: [1] the profile contact ratio ε_vα below which :func:`checked_profile_ratio` runs: below
#: 1 the transverse section has, once per pitch, no pair in mesh (ISO 10300-1:2014, Annex
#: A; :data:`contact.load_capacity.iso10300.face_contact.PROFILE_CONTACT_RATIO_MIN`), and
#: a localised bearing's tip and root relief take the flank away where the pairs hand over,
#: so that a ratio just above 1 hands over no better: the face-hobbed spiral bevel 10x31 at
#: β_m 41.2° of benchmarks/data/unseen_designs (ε_vα 1.01, ε_vβ 1.25) was written with an
#: LTE of 309 / 268 µrad at 10.8 / 72.6 N m on a path of −45° (one pair alone over 90 % of
#: the mesh cycle); with this step at 1.05 the development writes 46 / 50 µrad at 19.3 /
#: 128.7 N m, its full ISO capacity (docs/synthesis.md, "The profile-ratio bearing just
#: above a ratio of 1"). The designs of tests/data/designs with ε_vα in [1, 1.05) meet the
#: LTE limit, which the step reads first, and are written as before
PROFILE_RATIO_MIN = 1.05

#: [1] the tip relief of :func:`checked_profile_ratio`'s second design, a fraction of the
#: first's (entering at the upper bound of its start, :func:`lighter_tip_relief`): the
#: first of the root relief's fractions of the drive LTE step
#: (:data:`~contact.optimize.development_check.RELIEF_LTE_FRACTIONS`)
TIP_RELIEF_FRACTION = 0.5

#: the check stage of the step's designs (:attr:`DevelopmentEvaluation.stage`)
STAGE = "profile ratio"


def profile_ratio(case: Case) -> float:
    """The profile (transverse) contact ratio ε_vα [1] of a case's ISO 23509 basic design
    (its ``[design]`` table), by ISO 10300-1:2014's virtual cylindrical gears
    (:func:`contact.load_capacity.iso10300.virtual_gears.virtual_gears`, drive side).

    Parameters
    ----------
    case : geometry.case.Case
        A case with a ``[design]`` table (every case ``ltca synthesize`` writes).

    Returns
    -------
    float — [1]
        ε_vα = g_vα / p_vet; NaN where the case has no ``[design]`` table or its blank
        cannot be made (logged).

    Raises
    ------
    Nothing: a case without basic design data gives NaN (the step does not run).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A, A.2 (``contact.load_capacity.iso10300``).
    """
    from contact.optimize.development_matched_te import contact_ratios

    return contact_ratios(case)[0]


def profile_ratio_bearing(values: Mapping[str, float], targets: DevelopmentTargets
                          ) -> dict[str, float] | None:
    """The first design of :func:`checked_profile_ratio` for a design's prescriptions
    ``values`` [file units]: ``path_angle`` at its bound towards the profile (the lower
    bound of its variable), the long bearing of
    :func:`~contact.optimize.development_check.long_bearing` on it (the ellipse at its upper
    bound, the root relief from the upper bound of ``relief_start``, its slope kept) and
    the profile crowning at the lower bound of its variable, each where the targets vary
    it and the design carries it. None where ``values`` lack the path angle or the
    ellipse, or are that bearing already."""
    names = ("path_angle", "ellipse_length")
    if not all(n in targets.variables and n in values for n in names):
        return None
    new = dict(values)
    new["path_angle"] = float(min(targets.variables["path_angle"]))
    new = long_bearing(new, targets) or new
    new["ellipse_length"] = float(max(float(new["ellipse_length"]),
                                      float(max(targets.variables["ellipse_length"]))))
    if CROWNING_NAME in targets.variables and CROWNING_NAME in new:
        new[CROWNING_NAME] = float(min(targets.variables[CROWNING_NAME]))
    if all(abs(float(new[k]) - float(values[k])) < 1e-9 for k in new):
        return None
    return new


def lighter_tip_relief(values: Mapping[str, float], targets: DevelopmentTargets
                       ) -> dict[str, float] | None:
    """The second design of :func:`checked_profile_ratio` for a design's prescriptions
    ``values`` [file units]: the tip relief × :data:`TIP_RELIEF_FRACTION` (within its
    variable's bounds) entering at the upper bound of ``tip_relief_start`` (where that is
    later than the design's), every other prescription kept. None where the targets do
    not vary the tip relief, the design has none, or it would not be lighter."""
    name, start = "tip_relief", "tip_relief_start"
    if name not in targets.variables or not float(values.get(name, 0.0)) > 0.0:
        return None
    lo, hi = (float(x) for x in targets.variables[name])
    x = float(np.clip(TIP_RELIEF_FRACTION * float(values[name]), lo, hi))
    if not x < float(values[name]) - 1e-9:
        return None
    new = dict(values) | {name: x}
    if start in targets.variables and start in values:
        new[start] = float(max(float(values[start]), max(targets.variables[start])))
    return new


def checked_profile_ratio(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                          setup: Mapping[str, Any], teeth: KeptTeeth | None,
                          say: Callable[[str], None],
                          placed: Callable[[Mapping[str, float]], Case], *,
                          lte_limit: float | None = None, eps_va: float | None = None
                          ) -> DevelopmentEvaluation:
    """A drive design on a pair of profile contact ratio below :data:`PROFILE_RATIO_MIN`
    (1.05) whose LTE p-p at the check
    exceeds the verdict's limit at a torque, given the bearing that hands the load over
    along the face: :func:`profile_ratio_bearing` (the path at its profile bound, the long
    bearing, no profile crowning), then, where that design is kept and its LTE is still
    above the limit, its tip relief × :data:`TIP_RELIEF_FRACTION` entering at the upper
    bound of ``tip_relief_start`` (:func:`lighter_tip_relief`). Each
    design (a synthesis of steps 3-6) placed and checked at ``ltca run``'s sampling and kept
    where it scores better, misses no target the design met (the pattern length included)
    and is tolerant at ΔE/ΔP ± 0.05 mm (:func:`~contact.optimize.development_check.
    kept_why`); at most two designs.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The design the check's steps have kept so far (checked).
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`).
    lte_limit : float, optional — [µrad]
        The verdict's ``lte`` limit (default :data:`contact.study.verdicts.LTE_LIMIT`,
        60 µrad).
    eps_va : float, optional — [1]
        The pair's profile contact ratio (default :func:`profile_ratio` of the design's
        case, read only where the LTE exceeds the limit).

    Returns
    -------
    DevelopmentEvaluation
        The design kept: ``best`` itself where it is within the limit at every torque, its
        ε_vα is at least :data:`PROFILE_RATIO_MIN` (or unknown), it is that bearing
        already, or no design scored better.

    Raises
    ------
    Nothing: a design whose synthesis or analysis fails is not kept (logged).

    Notes
    -----
    With ε_vα < 1 the transverse section has, once per pitch, no pair in mesh: the load
    passes to the next pair only along the face (ISO 10300-1:2014, Annex A, ε_vγ = ε_vα +
    ε_vβ), which a localised bearing shortens. A contact path near the profile direction
    lays each instantaneous contact line (the ellipse's long axis, normal to the path)
    along the face; the longest ellipse, a root relief entering outside the part of the
    cycle one pair carries alone, and no profile crowning keep the flank where the pairs
    hand over, and the bearing's lower flank peak needs less tip relief, entering as late
    as the root relief does (Stadtfeld, *Gleason Bevel Gear Technology*, 2014: the long
    bearing and the relief sized to the load's deflection; Litvin & Fuentes, *Gear
    Geometry and Applied Theory*, 2nd ed., 2004, §9.4). The check's other steps reach
    neither change alone: the path turn alone and the ellipse alone each leave one pair
    alone over most of the light torque's cycle, an LTE spread above the verdict's
    plausibility limit, which the objective ranks after a design of ten times their LTE
    but no spread.

    Measured at ``ltca run``'s sampling on the face-hobbed hypoid 13x29 by ISO 23509
    Method 2 of benchmarks/data/unseen_designs (ε_vα 0.91, ε_vβ 1.27; 45.9 / 306.3 N m;
    its developed bearing path −58.75°, ellipse 0.4, root relief 24.1 µm from 0.25, tip
    relief 24.6 µm from 0.89, profile crowning 2.6 µm, te_level 10 µrad;
    ``benchmarks/development_levers.py --check --tolerance --from-case``, 2026-11-27;
    LTE p-p light / design [µrad]): 518 / 448, pattern 0.33 long at the gear's tip; path
    −80°: 237 / 113 (spread); the ellipse 0.75 alone: 183 / 59 (spread); path −80° with
    the long bearing (ellipse 0.75, root relief 16.1 µm from 0.5): 65 / 67, 0.55 long,
    tolerant; with no crowning: 61 / 62; with the tip relief 12.3 µm too: 59 / 60,
    tolerant; 5 µm or none from 0.9: edge contact at the mounting excursions. At 68.3 /
    455.7 N m (its ISO capacity): 516 / 363 → 51 / 73 µrad (no crowning), flank peak 1666
    → 1184 MPa. At 41.3 / 275.5 N m (the design torque its developed bearing carries):
    the tip relief 12.3 µm from 0.89: 60.4 / 56.0 µrad; from 0.9: 59.2 / 55.7, tolerant.
    """
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if lte_limit is None else float(lte_limit)

    def above(e: DevelopmentEvaluation) -> bool:
        return bool(np.nanmax(e.metrics["lte_peak_to_peak"]) > limit)

    if (not best.checked_full or not above(best)):
        return best
    values = profile_ratio_bearing(best.values, targets)
    if values is None:
        return best
    ratio = profile_ratio(best.case) if eps_va is None else float(eps_va)
    if not ratio < PROFILE_RATIO_MIN:  # NaN too: no ratio read, nothing tried
        return best
    e = said_variant(best, values, STAGE,
                 f"with the bearing of a profile contact ratio {ratio:.2f} below "
                 f"{PROFILE_RATIO_MIN:g} "
                 f"(path_angle {values['path_angle']:.3g}, ellipse_length "
                 f"{values['ellipse_length']:.3g}, root_relief "
                 f"{values.get('root_relief', math.nan):.3g} from "
                 f"{values.get('relief_start', math.nan):.3g}, {CROWNING_NAME} "
                 f"{values.get(CROWNING_NAME, math.nan):.3g} um; its LTE above {limit:g} urad)",
                 targets, setup, teeth, say, placed)
    if kept_why(best, e, targets, setup, teeth, say, "the profile-ratio bearing",
                lost=lost_targets):
        return best
    best = e
    if not above(best):
        return best
    values = lighter_tip_relief(best.values, targets)
    if values is None:
        return best
    e = said_variant(best, values, STAGE,
                 f"with tip_relief {values['tip_relief']:.3g} um from "
                 f"{values.get('tip_relief_start', math.nan):.3g} (its LTE above "
                 f"{limit:g} urad)", targets, setup, teeth, say, placed)
    return best if kept_why(best, e, targets, setup, teeth, say,
                            "the profile-ratio bearing's lighter tip relief",
                            lost=lost_targets) else e
