"""The check's steps on the drive flank's LTE: the ellipse a step longer
(:func:`checked_ellipse`), the long bearing (:func:`checked_long`, :func:`long_bearing`;
on the coast flank too), a shallower root relief where the LTE exceeds the verdict's
60 µrad (:func:`checked_relief_lte`, :func:`shallower_root_relief`: the loop both
flanks share), a flatter profile and a deeper TE parabola (:func:`checked_crowning_lte`,
recording the least LTE the development reached; :func:`crossing_level`; the crowning
matched to the load, :func:`matched_crowning`), the TE level
raised back to the flank's own (:func:`checked_te_back`) and less crowning both ways
where the development's own LTE target is still missed (:func:`checked_overlap_lte`; on a
pattern longer than its tolerance the flatter profile alone, :func:`checked_flatter_long`).
Each design placed and checked at ``ltca run``'s sampling and kept by
:func:`~contact.optimize.development_keep.kept_why`. Split out of
:mod:`contact.optimize.development_check` (issue 71, Deliver 5), which re-exports every
public name; the bodies moved unchanged (the helpers they share imported under the
private names they call).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import (
    kept_why,
)
from contact.optimize.development_keep import lost_but_length as _lost_but_length
from contact.optimize.development_keep import lost_targets as _lost_targets
from contact.optimize.development_pattern_steps import checked_centre_u
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import CROWNING_NAME, TE_NAME, DevelopmentTargets
from contact.optimize.development_variant import pattern_length as _pattern_length
from contact.optimize.development_variant import said_variant as _said_variant
from geometry.case import Case

#: the check's lengthwise-crowning step (:func:`checked_ellipse`): the ellipse this much
#: longer [1, fraction of the face]; half the coast step (:data:`COAST_LTE_STEPS`), since
#: the drive pattern's length is a target (0.9 of the face per unit of ellipse measured)
ELLIPSE_STEP = 0.05


def checked_ellipse(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                    setup: Mapping[str, Any], teeth: KeptTeeth | None,
                    say: Callable[[str], None],
                    placed: Callable[[Mapping[str, float]], Case]) -> DevelopmentEvaluation:
    """An LTE still missed at the check after the other steps, the pattern's length met:
    the ellipse :data:`ELLIPSE_STEP` longer (less lengthwise crowning, within its bounds),
    every other prescription kept; one design (a synthesis of steps 3-6) placed and
    checked at :data:`CHECK_LTCA`, kept where it scores better, misses no target the design
    met (the length included: the LTE is not bought with a pattern beyond its tolerance)
    and is tolerant (:func:`_tolerant_variant`). Before the long bearing
    (:func:`checked_long`), which takes the ellipse to its upper bound at once.

    Why: the coarse search stops at the first design that meets every target at the
    coarse LTCA, whose LTE reads a few µrad low; the check's TE and path steps cannot
    lower it where ``te_level`` is at its lower bound already and the path step shortens
    the ellipse, and the long bearing overshoots the length. Measured on the unseen
    industrial spiral bevel 19x62 (m_mn 7.75 mm, ε_vβ 2.00; its developed bearing path
    −45°, ellipse 0.4, tip relief 43 µm from 0.65, profile crowning 28.8 µm, te_level 10
    µrad, blade angle −0.168°; ``benchmarks/development_levers.py --check`` at 1013 /
    6759 N m, 2026-11-26; LTE p-p light / design, pattern length): 36 / 44 µrad, 0.53
    (the design chosen, "design 13 of 13", LTE target 40 missed); ellipse 0.5: 18 / 26
    µrad, 0.62 (the length's tolerance 0.5 ± 0.1 missed); 0.6: 8 / 16 µrad, 0.72; profile
    crowning 45 / 60 µm: 39 / 49, 42 / 51 µrad; te_level 25: 39 / 47; tip relief 30 µm:
    35 / 41 µrad, 1.2 % on edges."""
    if (not best.checked_full or best.full[1]["lte"] == 0.0
            or best.full[1]["length"] > 0.0 or "ellipse_length" not in targets.variables
            or "ellipse_length" not in best.values):
        return best
    lo, hi = (float(x) for x in targets.variables["ellipse_length"])
    now = float(best.values["ellipse_length"])
    x = float(np.clip(now + ELLIPSE_STEP, lo, hi))
    if abs(x - now) < 1e-9:
        return best
    e = _said_variant(best, best.values | {"ellipse_length": x}, "ellipse",
                      f"with the ellipse {x:.3g} (its LTE missed)", targets, setup, teeth,
                      say, placed)
    return best if kept_why(best, e, targets, setup, teeth, say, "the longer ellipse",
                            lost=_lost_targets) else e


def long_bearing(values: Mapping[str, float], targets: DevelopmentTargets
                 ) -> dict[str, float] | None:
    """The long bearing of :func:`checked_long` for a design's prescriptions ``values``
    [file units]: the ellipse at the upper bound of ``ellipse_length`` (where that is
    longer), the root relief's start at the upper bound of ``relief_start``, its depth
    scaled by (1 − new start)/(1 − old start) so that its slope towards the root is kept
    (:data:`~contact.optimize.development_targets.VARIABLES`' bounds, clipped to the
    root relief's). None where the design's values or the targets' variables do not
    carry these three, or where the values are that bearing already."""
    names = ("ellipse_length", "relief_start", "root_relief")
    if not all(n in targets.variables and n in values for n in names):
        return None
    (_, e_hi), (_, s_hi), (r_lo, r_hi) = (targets.variables[n] for n in names)
    start = float(values["relief_start"])
    depth = float(values["root_relief"]) * (1.0 - s_hi) / max(1.0 - start, 1e-9)
    new = dict(values) | {
        "ellipse_length": float(max(values["ellipse_length"], e_hi)),
        "relief_start": float(max(start, s_hi)),
        "root_relief": float(np.clip(depth, r_lo, r_hi)) if start < s_hi
        else float(values["root_relief"])}
    if all(abs(new[n] - float(values[n])) < 1e-9 for n in names):
        return None
    return new


def checked_long(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                 setup: Mapping[str, Any], teeth: KeptTeeth | None,
                 say: Callable[[str], None],
                 placed: Callable[[Mapping[str, float]], Case], *,
                 flank: str = "drive", key_prefix: tuple = ()) -> DevelopmentEvaluation:
    """An LTE still missed at the check after every other step bought back by a long
    bearing: the ellipse at its upper bound (the least lengthwise crowning) and the root
    relief entering at the upper bound of ``relief_start``, its slope kept
    (:func:`long_bearing`); one design (a synthesis of steps 3-6) placed and checked at
    :data:`CHECK_LTCA` on ``flank``, kept where it scores better, misses no target the
    design met but the pattern length (the LTE is bought with the length alone, not with
    an edge or a clearance) and, on the drive flank, is tolerant
    (:func:`_tolerant_variant`). ``key_prefix``: the kept pinion tooth's key before the
    design's bearing (the coast flank's, :func:`checked_best`).

    Why: with a face contact ratio ε_vβ near 1 one tooth pair carries the load over much
    of the mesh cycle; a gear engineer lowers the LTE of such a pair by a longer bearing
    and a relief that enters outside the part of the cycle the pair carries alone
    (Stadtfeld, *Gleason Bevel Gear Technology*, 2014; Litvin & Fuentes 2004 §9.4: the
    contact path's length and the TE parabola's level). The search's bearing stage
    ranks the ellipse before the relief, so a longer ellipse whose edges the default
    root relief (from 0.2 of the way) loads is not kept. Measured at ``ltca run``'s
    sampling on a hypoid 8x41 with a narrow face (b2 22 mm, β_m1 52°, a 30 mm, Method 1;
    ε_vβ 1.03, ε_vα 0.94; 27 / 180 N m; its developed bearing path −80°, ellipse 0.6,
    root relief 60 µm from 0.2, tip relief 15 µm from 0.85, te_level 10 µrad; 2026-11-26):
    LTE 63 / 74 µrad; the ellipse 0.75 with the root relief 60 µm from 0.5: 26 / 58 µrad
    but 0.7 % of the design torque plastic at ΔE +0.05 mm; with 40 µm from 0.5: 25 / 52
    µrad, pattern 0.60 long, tolerant; the ellipse 0.85: 17 / 54 µrad, pattern 0.68 long
    (beyond 0.5 ± 0.1). On the coast flank, whose search ends at the check of its best
    designs, it is the only step (:func:`contact.optimize.development_coast_flank.
    coast_development`)."""
    if (not best.checked_full or best.full[1]["lte"] == 0.0):
        return best
    values = long_bearing(best.values, targets)
    if values is None:
        return best
    e = _said_variant(best, values, "long",
                      f"with the long bearing (ellipse_length {values['ellipse_length']:.3g}"
                      f", root_relief {values['root_relief']:.3g} from "
                      f"{values['relief_start']:.3g})", targets, setup, teeth, say, placed,
                      flank=flank, key_prefix=key_prefix)
    # the LTE bought with the pattern's length alone: no other target it met given up
    # (the spiral bevel 17x29's coast flank: LTE 73 / 83 -> 50 / 62 urad, but its
    # light-load pattern 0.03-0.98 of the face, on toe and heel, 2.7 % on edges)
    return best if kept_why(best, e, targets, setup, teeth, say, "the long bearing",
                            lost=_lost_but_length, tolerant=flank == "drive") else e


#: the root relief of :func:`checked_relief_lte`'s designs, as fractions of the design's,
#: tried in turn (its start and every other prescription kept)
RELIEF_LTE_FRACTIONS = (0.5, 1.0 / 3.0)


def checked_relief_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                       setup: Mapping[str, Any], teeth: KeptTeeth | None,
                       say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case], *,
                       lte_limit: float | None = None) -> DevelopmentEvaluation:
    """A drive design whose LTE p-p at the check still exceeds the verdict's limit at a
    torque after every other step given a shallower root relief: the root relief ×
    :data:`RELIEF_LTE_FRACTIONS` in turn (within its bounds, its start kept), each design
    (step 7 only: the relief, no new synthesis) placed and checked at :data:`CHECK_LTCA`,
    kept where it scores better, misses no target the design met (the pattern length
    included) and is tolerant (:func:`_tolerant_variant`); the first kept within the limit
    at every torque ends it. ``lte_limit`` [µrad]: the verdict's ``lte`` limit (default
    :data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad); a design within it at every torque,
    or without a root relief to lower, is returned as it is, without an analysis.

    Why: where the contact ratios are low (ε_vβ ≲ 1.15, ε_vα near 1) the LTE at the design
    torque is that of the pairs handing over: the root relief takes away the flank where
    the pinion's root meets the gear's tip, which is where the next pair takes up its
    load, and a relief deeper than the teeth deflect at the design torque keeps the loaded
    contact ratio below what the geometry gives (Stadtfeld, *Gleason Bevel Gear
    Technology*, 2014: the relief sized to the load's deflection; Litvin & Fuentes 2004
    §9.4). The search's relief stage sets the relief against the edges at the design
    torque and the mounting excursions, the LTE only as one term of its objective.
    Measured at ``ltca run``'s sampling on the spiral bevel 17x26 at Σ 120° of
    benchmarks/data/unseen_designs (ε_vα 1.11, ε_vβ 1.14; 71.7 / 477.7 N m; path −80°,
    ellipse 0.75, root relief 60 µm from 0.2, tip relief 15 µm from 0.85, te_level 25
    µrad; ``benchmarks/development_levers.py --check --tolerance``, 2026-11-26): LTE
    38 / 96 µrad, loaded contact ratio 1.50 / 2.15; root relief 30 µm: 35 / 73; 20 µm:
    33 / 60, 1.50 / 2.30, edge 0.9 % at the design torque, tolerant; 20 µm from 0.35:
    25 / 59; none: 39 / 29 µrad but 9.1 % on the edges. ``te_level`` 10 (38 / 95) and the
    relief starting at 0.5 (26 / 74, 37.5 µm from 0.5: plastic at ΔP +0.05 mm) did less."""
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if lte_limit is None else float(lte_limit)

    def tried(best: DevelopmentEvaluation, values: dict[str, float],
              said: str) -> DevelopmentEvaluation:
        e = _said_variant(best, values, "relief lte", said, targets, setup, teeth, say,
                          placed)
        if not kept_why(best, e, targets, setup, teeth, say, "the shallower root relief",
                        lost=_lost_targets):
            return e
        return best

    return shallower_root_relief(best, targets, limit, tried)


def shallower_root_relief(
        best: DevelopmentEvaluation, targets: DevelopmentTargets, limit: float,
        tried: Callable[[DevelopmentEvaluation, dict[str, float], str],
                        DevelopmentEvaluation]) -> DevelopmentEvaluation:
    """The shallower-root-relief loop both flanks' LTE checks share
    (:func:`checked_relief_lte`, :func:`checked_coast_relief`): while the checked design's
    LTE p-p exceeds ``limit`` [µrad] at a torque, its root relief × each of
    :data:`RELIEF_LTE_FRACTIONS` of the starting design's (clipped to its bounds; a step
    that changes nothing skipped) is handed to ``tried(best, values, said)``, which
    analyses it on its flank and returns the design kept (``best`` where its flank's keep
    rule refuses it). A design without a positive root relief, or within ``limit``, is
    returned as it is.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The checked design (its ``root_relief`` [µm], LTE p-p [µrad]).
    targets : DevelopmentTargets
        The development's targets (the bounds of ``root_relief`` [µm]).
    limit : float
        The LTE p-p limit [µrad].
    tried : callable (best, values, said) → DevelopmentEvaluation
        The flank's analysis and keep rule of one design.

    Returns
    -------
    DevelopmentEvaluation
        The design kept last (``best`` where none was).

    Notes
    -----
    Source: the issue-71 development's check (docs/synthesis.md, "Development bearing";
    the root relief against the LTE, docs/own_gear_set.md).
    """
    name = "root_relief"
    if (name not in targets.variables or name not in best.values
            or not float(best.values[name]) > 0.0):
        return best
    lo, hi = (float(x) for x in targets.variables[name])
    now = float(best.values[name])
    for fraction in RELIEF_LTE_FRACTIONS:
        if (not best.checked_full
                or not np.nanmax(best.metrics["lte_peak_to_peak"]) > limit):
            return best
        x = float(np.clip(fraction * now, lo, hi))
        if abs(x - float(best.values[name])) < 1e-9:
            continue
        best = tried(best, dict(best.values) | {name: x},
                     f"with {name} {x:.3g} um (its LTE above {limit:g} urad)")
    return best


def checked_te_back(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                    setup: Mapping[str, Any], teeth: KeptTeeth | None,
                    say: Callable[[str], None],
                    placed: Callable[[Mapping[str, float]], Case], level: float
                    ) -> DevelopmentEvaluation:
    """The TE level re-examined on the bearing the check's steps ended at: where the
    checked design misses a target and its ``te_level`` is below the flank's own level
    ``level`` [µrad] (lowered by the coarse search's TE stage or the check's, on the
    bearing as it was before the steps turned its path, changed its ellipse, its relief
    or its blade angle), one design at ``level`` (within the bounds of
    :data:`~contact.optimize.development_targets.TE_NAME`), every other prescription
    kept; placed and checked at :data:`CHECK_LTCA` and kept where it ranks better
    (:func:`_check_rank`) and is tolerant (:func:`_tolerant_variant`).

    Why: the TE stage chooses the level for the bearing of its design, the check's steps
    change the bearing after it and keep the level, and no step raises it back. On the
    unseen spiral bevel 13x37 at Σ 60° (benchmarks/data/unseen_designs, drive, ``ltca
    run``'s sampling at 41.8 / 279.2 N m, 2026-11-26) the search with the light torque
    41.8 N m ran its TE stage on one design (te_level 45 → 10), that with 41.88 N m on
    another, and the check's steps took both to the same bearing (path −80°, ellipse 0.7,
    root relief 60 µm from 0.2, no blade-angle change): with te_level 10 the flank peaked
    at 2779 MPa at the design torque (above the static strength 2400 MPa, so the design
    torque was lowered to 217.7 N m), with 45 at 2142 MPa (LTE 87 µrad): the outcome
    followed which design the search's TE stage met, a 0.2 % change of a torque apart."""
    if (not best.checked_full or best.met or TE_NAME not in targets.variables
            or TE_NAME not in best.values):
        return best
    lo, hi = (float(x) for x in targets.variables[TE_NAME])
    now, x = float(best.values[TE_NAME]), float(np.clip(level, lo, hi))
    if not x > now + 1.0:
        return best
    e = _said_variant(best, dict(best.values) | {TE_NAME: x}, "te back",
                      f"at {TE_NAME} {x:.3g} urad (its own level, on the bearing the "
                      "steps ended at)", targets, setup, teeth, say, placed)
    return best if kept_why(best, e, targets, setup, teeth, say) else e


def checked_overlap_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                        setup: Mapping[str, Any], teeth: KeptTeeth | None,
                        say: Callable[[str], None],
                        placed: Callable[[Mapping[str, float]], Case]
                        ) -> DevelopmentEvaluation:
    """A drive design that still misses the development's own LTE target
    (``targets.max_lte``) after every other step given less crowning both ways: the ellipse
    :data:`ELLIPSE_STEP` longer (less lengthwise crowning) and the profile crowning at the
    lower bound of its variable, in one design (a synthesis of steps 3-6), and — where that
    moved the light-load centre u off the band the design met — M placed again
    (:func:`checked_centre_u` on it); the result placed and checked at :data:`CHECK_LTCA`
    and kept where it ranks better (:func:`_check_rank`), misses no target the design met
    (the pattern length and centre u included) and is tolerant
    (:func:`_tolerant_variant`). A design that meets its LTE target or its pattern
    length's upper tolerance (no room for a longer ellipse) is returned as it is, without
    an analysis.

    Why: with a face contact ratio near 1 the LTE at both torques together has a floor
    that no unloaded TE reaches. The LTE p-p at a torque T is that of UTE(φ) + δ(φ, T),
    the unloaded TE plus the mesh deflection δ = ∫ dT_g / k_Θ(φ, T_g) (k_Θ the torsional
    mesh stiffness at the roll φ, :mod:`contact.ltca.mesh_interface`); the unloaded TE
    (the modified roll's parabola, the reliefs) is the same at both torques, so
    p-p(TE_design − TE_light) = p-p(δ_design − δ_light) ≤ LTE_light + LTE_design, and
    max(LTE_light, LTE_design) ≥ ½ p-p(δ_design − δ_light): the part of the deflection
    that changes with the number of pairs sharing the load between the two torques. It is
    the bearing's load sharing that lowers it — a longer, flatter contact that lets the
    next pair take up load earlier — not ``te_level`` or the relief, which move the
    unloaded TE and trade one torque's LTE against the other's. Measured at ``ltca run``'s
    sampling on the bundled basic file cases/basic/kolivand2009_fm_11x41.toml (ε_vα 1.06,
    ε_vβ 1.13; 61.9 / 412.9 N m; its developed bearing path −80°, ellipse 0.55, profile
    crowning 2.6 µm, root relief 20 µm from 0.2, tip relief 24.6 µm from 0.89, te_level
    10 µrad, M −0.164 of the face; 2026-11-26, docs/synthesis.md "The LTE floor of a face
    contact ratio near 1"): LTE 49 / 58 µrad, loaded contact ratio 1.45 / 2.25, the bound
    ½ p-p(δ_design − δ_light) 47 µrad — 40 out of reach on that bearing whatever its
    TE level (te_level 5 / 20 / 30 / 45: 47 / 57, 45 / 59, 57 / 60, 57 / 56 µrad); the
    ellipse 0.6 with no profile crowning and M −0.2: 37 / 38.5 µrad, 1.50 / 2.30, the
    bound 33 µrad, every target met, tolerant. Each alone did less (ellipse 0.6: 43 / 43
    µrad, centre u missed; no crowning: 43 / 51 µrad, centre v missed)."""
    if not best.checked_full or best.full[1]["lte"] == 0.0:
        return best
    if best.full[1]["length"] > 0.0:
        band_hi = targets.pattern_length + targets.pattern_length_tolerance
        if _pattern_length(best) > band_hi:
            return checked_flatter_long(best, targets, setup, teeth, say, placed)
        return best
    values = dict(best.values)
    if "ellipse_length" in targets.variables and "ellipse_length" in values:
        lo, hi = (float(x) for x in targets.variables["ellipse_length"])
        values["ellipse_length"] = round(float(np.clip(float(values["ellipse_length"])
                                                       + ELLIPSE_STEP, lo, hi)), 4)
    if CROWNING_NAME in targets.variables and CROWNING_NAME in values:
        values[CROWNING_NAME] = float(targets.variables[CROWNING_NAME][0])
    if all(abs(float(values[k]) - float(best.values[k])) < 1e-9 for k in values):
        return best
    e = _said_variant(best, values, "overlap lte",
                      "with less crowning both ways (ellipse_length "
                      f"{values.get('ellipse_length', math.nan):.3g}, {CROWNING_NAME} "
                      f"{values.get(CROWNING_NAME, math.nan):.3g} um; its LTE above "
                      f"{targets.max_lte:g} urad)", targets, setup, teeth, say, placed)
    if e is None:
        return best
    placed_again = e
    if best.full[1].get("centre_u", 0.0) == 0.0 and e.full[1].get("centre_u", 0.0) > 0.0:
        placed_again = checked_centre_u(e, targets, setup, teeth, say, placed)
    # a design checked_centre_u kept was found tolerant there
    why = kept_why(best, placed_again, targets, setup, teeth, say,
                   "the longer, flatter bearing", lost=_lost_targets,
                   tolerant=placed_again is e)
    _reached(setup, placed_again, f"design {best.index + 1} with less crowning both ways",
             why)
    return best if why else placed_again


#: the profile crowning of :func:`checked_flatter_long`'s designs, as fractions of the
#: design's, tried in turn (clipped to the variable's lower bound; every other
#: prescription kept): the flat profile first, which on the FH hypoid 7x33 at Σ 80° met
#: every target, then half the crowning, which met all but the length
FLATTER_LONG_FRACTIONS = (0.0, 0.5)


def checked_flatter_long(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                         setup: Mapping[str, Any], teeth: KeptTeeth | None,
                         say: Callable[[str], None],
                         placed: Callable[[Mapping[str, float]], Case]
                         ) -> DevelopmentEvaluation:
    """A drive design that misses the development's LTE target with its light-load pattern
    longer than the length's tolerance given a flatter profile, the ellipse kept: the
    profile crowning × :data:`FLATTER_LONG_FRACTIONS` in turn (clipped to its variable's
    lower bound), each design (a synthesis of steps 3-6) placed and checked at
    :data:`CHECK_LTCA`, M placed again where it moved the light-load centre u off the band
    the design met (:func:`checked_centre_u`); the first kept where it ranks better,
    misses no target the design met (the length was missed already; the centre u and
    the edges, plastic and pressure included) and is tolerant (:func:`_tolerant_variant`).
    Called by :func:`checked_overlap_lte` where the pattern is too long for its longer
    ellipse. A design whose crowning is at its lower bound already, or not a variable,
    is returned as it is, without an analysis.

    Why: on a face contact ratio below 1 the profile crowning takes the next pair's flank
    away at the hand-over, so one pair carries the load longer and the deflection's jump
    sets the design torque's LTE; with less of it the pairs share the load earlier, which
    lowers the load sharing's floor itself (not only the unloaded TE), and the light-load
    pattern, which the crowning spreads lengthwise, shortens with it. The other LTE steps
    miss such a design: :func:`checked_crowning_lte` runs only above the verdict's 60
    µrad, this step's longer ellipse would lengthen the pattern further, the length step's
    shorter ellipse raises the LTE and the TE parabola raises both torques' LTE where the
    crowning already makes the light torque's (Stadtfeld 2014, bearing development for
    low loaded TE: less profile crowning where the face contact ratio is low). Measured on
    the FH hypoid 7x33 at Σ 80° of benchmarks/data/unseen_designs (ε_vα 1.03, ε_vβ 0.95;
    its written bearing path −80°, ellipse 0.75, profile crowning 22.4 µm, te_level 10
    µrad; ``benchmarks/development_levers.py --check --floor 4 --from-case`` at 37.6 / 251
    N m, 2026-11-29; LTE p-p light / design, pattern length, the floor ½ p-p(TE_design −
    TE_light)): as written 31 / 56 µrad, 0.78, floor 42; crowning 15 µm: 25 / 46, 0.72,
    33; 8 µm: 17 / 34, 0.68, 25; 0: 9 / 22, 0.60, 14 — every target met; te_level 30 / 60
    / 90 / 130: 35 / 60 … 58 / 75 (both up); path −70° / −60°: 45 / 67, 70 / 85; ellipse
    0.8 / 0.85: 24 / 54, 18 / 52 (0.83 long) (docs/synthesis.md, "The FH 7×33's LTE at
    ε_vβ 0.95: the profile crowning")."""
    if CROWNING_NAME not in targets.variables or CROWNING_NAME not in best.values:
        return best
    lo, _ = (float(x) for x in targets.variables[CROWNING_NAME])
    now = float(best.values[CROWNING_NAME])
    tried: list[float] = []
    for fraction in FLATTER_LONG_FRACTIONS:
        x = float(max(lo, fraction * now))
        if not x < now - 1e-9 or any(abs(x - t) < 1e-9 for t in tried):
            continue
        tried.append(x)
        e = _said_variant(best, dict(best.values) | {CROWNING_NAME: x}, "flatter long",
                          f"with profile_crowning {x:.3g} um, the ellipse kept (its LTE "
                          f"above {targets.max_lte:g} urad, its pattern "
                          f"{_pattern_length(best):.2f} long)", targets, setup, teeth, say,
                          placed)
        if e is None:
            continue
        placed_again = e
        if (best.full[1].get("centre_u", 0.0) == 0.0
                and e.full[1].get("centre_u", 0.0) > 0.0):
            placed_again = checked_centre_u(e, targets, setup, teeth, say, placed)
        why = kept_why(best, placed_again, targets, setup, teeth, say,
                       "the flatter profile", lost=_lost_targets,
                       tolerant=placed_again is e)
        _reached(setup, placed_again, f"design {best.index + 1} with profile_crowning "
                 f"{x:.3g} um", why)
        _tried(setup, "the profile crowning flattened")
        if not why:
            return placed_again
    return best


#: the profile crowning of :func:`checked_crowning_lte`'s designs, as fractions of the
#: design's, tried in turn (every other prescription kept)
CROWNING_LTE_FRACTIONS = (0.5, 0.0)


def _lte_ends(e: DevelopmentEvaluation) -> tuple[float, float]:
    """[µrad] A checked design's LTE p-p at the light and the design torque."""
    lte = np.asarray(e.metrics["lte_peak_to_peak"], float)
    return float(lte[0]), float(lte[-1])


def _reached(setup: Mapping[str, Any], e: DevelopmentEvaluation, what: str,
             why: str = "") -> None:
    """Record in ``setup["lte_reach"]`` (by the development's torques) the design of least
    LTE p-p (the larger of light and design torque) :func:`checked_crowning_lte` and
    :func:`checked_overlap_lte` have seen:
    ``{"light", "design"}`` [µrad], ``"what"`` it is, ``"why"`` it was not kept (empty
    where it was, or is the design the step began with), ``"tried"`` the levers the
    step analysed (:func:`_tried`) and ``"evaluation"`` the design itself (its missed
    targets, which ``ltca synthesize``'s note names where it "scores no better")."""
    if not isinstance(setup, dict) or e.metrics is None:
        return
    light, design = _lte_ends(e)
    if not (math.isfinite(light) and math.isfinite(design)):
        return
    key = tuple(float(t) for t in setup["torques"])
    kept = setup.setdefault("lte_reach", {}).get(key)
    if kept is None or max(light, design) < max(kept["light"], kept["design"]) - 1e-9:
        setup["lte_reach"][key] = {"light": light, "design": design, "what": what,
                                   "why": why,
                                   "tried": () if kept is None else kept["tried"],
                                   "evaluation": e}


def _tried(setup: Mapping[str, Any], lever: str) -> None:
    """Add ``lever`` (a lever's name in words) to the ``"tried"`` of the development's
    ``setup["lte_reach"]`` record at its torques (:func:`_reached`)."""
    key = tuple(float(t) for t in setup["torques"])
    kept = setup.get("lte_reach", {}).get(key) if isinstance(setup, dict) else None
    if kept is not None and lever not in kept["tried"]:
        kept["tried"] = (*kept["tried"], lever)


def lte_reached(setup: Mapping[str, Any], e: DevelopmentEvaluation, what: str,
                why: str = "", lever: str = "") -> None:
    """Record a check step's drive design in the development's least-LTE record
    (``setup["lte_reach"]``, which ``ltca synthesize``'s contact-ratio note states, :func:`
    contact.optimize.written_notes.reach_text`): kept where its larger LTE p-p of the light
    and design torque is the least seen, and ``lever`` added to the levers tried.

    Parameters
    ----------
    setup : mapping
        The development's state (``"torques"`` [N·m]); a non-dict records nothing.
    e : DevelopmentEvaluation
        The design, checked (its ``metrics["lte_peak_to_peak"]`` [µrad]).
    what : str
        The design in words ("design 35 with te_level 128 urad").
    why : str, optional
        Why it was not kept (empty: kept).
    lever : str, optional
        The lever in words, added to the record's ``"tried"`` (empty: none).

    Returns
    -------
    None

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the record :func:`checked_crowning_lte` and :func:`checked_overlap_lte` keep
    (issue 71; docs/synthesis.md, "Low contact ratios"), for the check steps of other
    modules (:mod:`contact.optimize.development_matched_te`).
    """
    if e is None or e.metrics is None:
        return
    _reached(setup, e, what, why)
    if lever:
        _tried(setup, lever)


def checked_crowning_lte(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                         setup: Mapping[str, Any], teeth: KeptTeeth | None,
                         say: Callable[[str], None],
                         placed: Callable[[Mapping[str, float]], Case], *,
                         level: float | None = None, lte_limit: float | None = None
                         ) -> DevelopmentEvaluation:
    """A drive design whose LTE p-p at the check still exceeds the verdict's limit after
    every other step given a flatter profile, then a deeper TE parabola: the profile
    crowning × :data:`CROWNING_LTE_FRACTIONS` in turn (within its bounds), then, where the
    design torque's LTE is still above the limit and above the light torque's, the
    ``te_level`` (the modified roll's parabola, :data:`TE_NAME`) at its upper bound and,
    where the light and design LTE cross between the two, at their crossing
    (:func:`crossing_level`); each design (a synthesis of steps 3-6) placed and checked at
    :data:`CHECK_LTCA`, kept where it scores better, misses no target the design met (the
    pattern length included) and is tolerant (:func:`_tolerant_variant`); at most five
    designs, none where the design is within the limit at every torque; last, where the
    design torque's LTE is still the larger and above the limit and the flatter profiles
    widened its lead, the crowning raised to the two LTE's crossing
    (:func:`matched_crowning`, at most × :data:`CROWNING_MATCH_MAX`; the fifth design,
    kept by the same rule: the crowning is the TE parabola matched to the load, which a
    ``te_level`` of 10–45 µrad beside it cannot deepen). ``level`` [µrad]:
    the flank's own TE level, where the design's values do not give one; ``lte_limit``
    [µrad]: the verdict's ``lte`` limit (default
    :data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad). Each design's LTE is recorded
    (``setup["lte_reach"]``, :func:`_reached`): the least the development reached, which
    ``ltca synthesize`` states where it stays above the limit.

    Why: with low contact ratios (ε_vα near 1, ε_vβ below 1.25) one pair carries the load
    over much of the mesh cycle and hands it over where the profile crowning has taken
    its flank away: the light-load LTE is then the crowning's unloaded TE, and the loaded
    contact ratio at the design torque what the crowning leaves of the profile. Practice
    for such sets is less profile crowning and a larger parabolic TE of the modified roll,
    which the pairs' deflection at the design torque takes up (Stadtfeld, *Gleason Bevel
    Gear Technology*, 2014; Litvin & Fuentes 2004 §9.4, the predesigned parabolic TE).
    Measured at ``ltca run``'s sampling on the spiral bevel 19x23 at β_m 46° of
    benchmarks/data/unseen_designs (ε_vα 0.98, ε_vβ 1.27; 33.78 / 225.2 N m; its written
    bearing path −60°, ellipse 0.7, root relief 20 µm from 0.2, profile crowning 16.8 µm,
    te_level 10 µrad; ``benchmarks/development_levers.py --check --from-case``,
    2026-11-26; LTE p-p light / design [µrad], unloaded TE p-p): 221 / 111, 253; crowning
    8 µm: 169 / 87, 192; 0: 109 / 97, 106 (pattern 0.38 long: the length missed);
    te_level 45 / 80 µrad: 229 / 113, 236 / 117 (the light LTE up, the design's no
    lower). About the long bearing (path −80°, ellipse 0.75): 139 / 89; crowning 4 µm,
    te_level 25 / 45: 81 / 84, 85 / 79; crowning 0, te_level 10 / 45 / 80: 62 / 64, 60 /
    79, 67 / 73 µrad (1.1-1.2 % of the design torque on the edges, 2.0-2.4 % at ΔE, ΔP
    −0.05 mm) — the crowning the lever, the TE level trading the light against the
    design LTE, and 60 µrad not reached. ``ltca synthesize`` with this step (2026-11-26)
    writes the 19x23's drive flank as before (crowning 8.4 µm: an LTE spread above 0.5;
    none: 109 / 96 µrad, the pattern 0.38 long: neither kept), the spiral bevel 18x22's
    likewise (te_level 45 µrad: 204 / 206 against 192 / 208 µrad, no better score); what
    it adds there is the least LTE reached, which ``ltca synthesize`` states."""
    from contact.study.verdicts import LTE_LIMIT

    limit = LTE_LIMIT if lte_limit is None else float(lte_limit)
    if not best.checked_full:
        return best
    _reached(setup, best, f"design {best.index + 1} as checked")

    def above(e: DevelopmentEvaluation) -> bool:
        return bool(np.nanmax(e.metrics["lte_peak_to_peak"]) > limit)

    if not above(best):
        return best
    # the crowning's LTE trade as the fractions measure it: (crowning [µm], (light, design))
    seen: list[tuple[float, tuple[float, float]]] = []
    if CROWNING_NAME in targets.variables and CROWNING_NAME in best.values:
        lo, hi = (float(x) for x in targets.variables[CROWNING_NAME])
        now = float(best.values[CROWNING_NAME])
        seen.append((now, _lte_ends(best)))
        for fraction in CROWNING_LTE_FRACTIONS:
            x = float(np.clip(fraction * now, lo, hi))
            if not above(best) or not x < float(best.values[CROWNING_NAME]) - 1e-9:
                continue
            what = f"design {best.index + 1} with profile_crowning {x:.3g} um"
            e = _said_variant(best, dict(best.values) | {CROWNING_NAME: x}, "crowning lte",
                              f"with profile_crowning {x:.3g} um (its LTE above {limit:g} "
                              "urad)", targets, setup, teeth, say, placed)
            if e is None:
                continue
            seen.append((x, _lte_ends(e)))
            _tried(setup, "the profile crowning flattened")
            why = kept_why(best, e, targets, setup, teeth, say, "the flatter profile",
                           lost=_lost_targets)
            _reached(setup, e, what, why)
            if not why:
                best = e
    if TE_NAME in targets.variables and above(best):
        best = _deeper_te_level(best, targets, setup, teeth, say, placed, level, limit, above)
    if above(best):
        best = _matched_crowning(best, targets, setup, teeth, say, placed, seen, limit, above)
    return best


def _deeper_te_level(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                     setup: Mapping[str, Any], teeth: KeptTeeth | None,
                     say: Callable[[str], None],
                     placed: Callable[[Mapping[str, float]], Case], level: float | None,
                     limit: float, above: Callable[[DevelopmentEvaluation], bool]
                     ) -> DevelopmentEvaluation:
    """The te_level step of :func:`checked_crowning_lte` (its body moved unchanged): the
    TE level at its upper bound and at the light and design LTE's crossing."""
    light, design = _lte_ends(best)
    _lo, hi = (float(x) for x in targets.variables[TE_NAME])
    now = float(best.values.get(TE_NAME, hi if level is None else level))
    if not (design > limit and design > light and hi > now + 1.0):
        return best
    base, tried = best, [hi]
    while tried:
        x = tried.pop()
        e = _said_variant(base, dict(base.values) | {TE_NAME: x}, "te lte",
                          f"with te_level {x:.3g} urad (its LTE above {limit:g} urad at the design "
                          "torque)", targets, setup, teeth, say, placed)
        if e is None:
            break
        _tried(setup, "the modified roll's TE parabola deepened")
        why = kept_why(best, e, targets, setup, teeth, say, "the deeper TE parabola",
                       lost=_lost_targets)
        _reached(setup, e, f"design {base.index + 1} with te_level {x:.3g} urad", why)
        if not why:
            best = e
        if x == hi and above(e):
            cross = crossing_level(now, (light, design), hi, _lte_ends(e))
            if cross is not None and now + 1.0 < cross < hi - 1.0:
                tried.append(round(cross, 1))
    return best


#: the most :func:`checked_crowning_lte` raises a profile crowning to match its TE to the
#: load, × the design's crowning (its linear reach: the light and design LTE's trade
#: measured on the 16×16 at Σ 60° from 0 to 9.3 µm, docs/synthesis.md)
CROWNING_MATCH_MAX = 2.0


def matched_crowning(seen: list[tuple[float, tuple[float, float]]]) -> float | None:
    """[µm] The profile crowning at which the light and design torque's LTE p-p cross,
    from the design's own crowning and a flatter one of the same design.

    Parameters
    ----------
    seen : list of (float, (float, float))
        (crowning [µm], (light, design) LTE p-p [µrad])): the design's own first, then the
        flatter designs :func:`checked_crowning_lte` analysed.

    Returns
    -------
    float or None
        The crowning [µm] above the design's where design − light, linear in the crowning
        through the design's and the flatter design nearest it, reaches 0; clipped to
        :data:`CROWNING_MATCH_MAX` × the design's. None where the design's LTE is not the
        design torque's, the flatter one did not widen the gap (the crowning is not the
        TE parabola matched to the load), or a value is not finite.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the profile crowning's TE identity (:func:`geometry.synthesis.crowning_te.
    crowning_te_rate`): a crowning c adds the TE parabola k·c, which at light load is the
    unloaded TE and at the design torque absorbs the deflection's transfer between tooth
    pairs (Litvin & Fuentes 2004 §9.4, the predesigned parabolic TE), so the LTE's larger
    end is least where the light LTE, rising with c, meets the design LTE, falling with it
    (as :func:`crossing_level` for the TE level). Measured on the 16×16 at Σ 60° as
    written (path −88°, 58.6 / 390.7 N m, ``ltca run``'s sampling): crowning 0 / 2.33 /
    4.67 / 7 / 9.3 µm: 21 / 108, 38 / 108, 54 / 95, 64 / 81, 78 / 72 µrad.
    """
    if len(seen) < 2:
        return None
    now, (light, design) = seen[0]
    flatter = [(c, ends) for c, ends in seen[1:] if c < now]
    if not flatter or not now > 0.0:
        return None
    c1, (l1, d1) = max(flatter, key=lambda t: t[0])
    g0, g1 = design - light, d1 - l1
    if not all(math.isfinite(v) for v in (g0, g1)) or not (0.0 < g0 < g1):
        return None
    return float(min(now + (now - c1) * g0 / (g1 - g0), CROWNING_MATCH_MAX * now))


def _matched_crowning(best: DevelopmentEvaluation, targets: DevelopmentTargets,
                      setup: Mapping[str, Any], teeth: KeptTeeth | None,
                      say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case],
                      seen: list[tuple[float, tuple[float, float]]], limit: float,
                      above: Callable[[DevelopmentEvaluation], bool]
                      ) -> DevelopmentEvaluation:
    """The last step of :func:`checked_crowning_lte`: where the design torque's LTE is
    still above the limit and the light torque's, the profile crowning raised to where
    the two cross (:func:`matched_crowning`, within its bounds), one design placed and
    checked, kept by :func:`~contact.optimize.development_keep.kept_why`."""
    light, design = _lte_ends(best)
    if (not (design > limit and design > light) or CROWNING_NAME not in best.values
            or not seen or float(best.values[CROWNING_NAME]) != seen[0][0]):
        return best  # a flatter profile kept: the trade points the other way
    x = matched_crowning(seen)
    if x is None:
        return best
    x = float(np.clip(x, *(float(v) for v in targets.variables[CROWNING_NAME])))
    if not x > float(best.values[CROWNING_NAME]) + 1e-3:
        return best
    what = f"design {best.index + 1} with profile_crowning {x:.3g} um"
    e = _said_variant(best, dict(best.values) | {CROWNING_NAME: x}, "crowning lte",
                      f"with profile_crowning {x:.3g} um, its TE matched to the load (its LTE "
                      f"{light:.0f}/{design:.0f} urad, the design torque's above {limit:g})",
                      targets, setup, teeth, say, placed)
    if e is None:
        return best
    _tried(setup, "the profile crowning matched to the load")
    why = kept_why(best, e, targets, setup, teeth, say, "the crowning matched to the load",
                   lost=_lost_targets)
    _reached(setup, e, what, why)
    return best if why else e


def crossing_level(x0: float, lte0: tuple[float, float], x1: float,
                   lte1: tuple[float, float]) -> float | None:
    """[µrad] The TE level at which the light- and design-torque LTE p-p cross, linear
    between two designs that differ only in it: ``x0`` with LTE ``lte0`` (light, design)
    [µrad] and ``x1`` with ``lte1``. None where they do not cross between them (the same
    order of light and design at both ends, or a NaN). The LTE's larger end is least
    there where the light LTE rises and the design LTE falls with the level (a deeper
    parabola of the modified roll is the unloaded TE at light load and absorbs the
    deflection's transfer at the design torque)."""
    g0 = float(lte0[1]) - float(lte0[0])  # design − light
    g1 = float(lte1[1]) - float(lte1[0])
    if not (np.isfinite(g0) and np.isfinite(g1)) or g0 * g1 >= 0.0:
        return None
    return float(x0 + (x1 - x0) * g0 / (g0 - g1))
