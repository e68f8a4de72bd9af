"""The drive bearing that carries a given design torque at the gear root (issue 71: a
design torque the basic file gives, above the developed bearing's FE root capacity).

A design torque the basic file gives (``[synthesis]`` or ``[rating] design_torque``)
stands as given: the development does not lower it
(:func:`contact.optimize.development_root.given_torque_root` checks the root stress of
the written case there and says when ``ltca run`` will rate it FAIL). Where the root is
the binding limit, the fillet is the first lever (:func:`checked_edge_radius`: the written
bearing with the largest blade edge radius the point widths and the clearance allow,
:func:`geometry.synthesis.edge_radius.largest_edge_radius`, where the basic file gives
none; on the 8×47 2.36 mm against the default 1.574 took the gear's FE fillet stress 657 →
576 MPa, S_F,FE 1.246 → 1.40, the bearing unchanged), then the bearing itself: the FE
root stress follows where
the load sits on the tooth height. :func:`checked_given_root` tries the drive pattern
centred lower by the pinion blade's pressure-angle change (the pattern's height lever,
:data:`~contact.optimize.development_targets.HEIGHT_NAME`), alone and with a longer tip
relief (which takes the pinion tip edge's load off the gear's lower flank that a lower
pattern reaches), checks each at ``ltca run``'s sampling and its FE root stress at the
given torque on the model ``ltca run`` reads, and keeps the one of the highest root
safety that misses no target the written design met and is tolerant; what it tried is
said in numbers either way (:func:`tried_text`).

Measured on the truck hypoid 8×47 at a = 45 mm given 1765 N·m (0.95 × its ISO 10300
capacity; benchmarks/data/unseen_designs, round 21), the written case's drive flank at
``ltca run``'s sampling: the blade-angle change 0 / −0.2 / −0.35 / −0.6° put the
light-load centre v at 0.64 / 0.54 / 0.46 / 0.39 and the gear's FE root safety at 1.246 /
1.331 / 1.369 / 1.379 (the pinion's 1.53 / 1.46 / 1.41 / 1.33): the lower pattern loads
the gear nearer its root, so its fillet stress falls (657 → 598 MPa at −0.35°); the tip
relief 21 → 32 µm at −0.2° raises it again (S_F,FE 1.287) — docs/own_gear_set.md, "A given
torque above the gear's root capacity". There, at 1765 N·m, every lower pattern that keeps
the pinion tip edge elastic misses the pattern length (0.62 of the face against 0.6 at
most) and none is kept: the note says so with each variant's numbers. Imported by
:mod:`contact.optimize.development`.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_stages import HEIGHT_SLOPE, HEIGHT_SLOPE_MIN
from contact.optimize.development_targets import HEIGHT_NAME, DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case
from geometry.core.errors import InputError, raise_if_interrupted
from geometry.core.text import plain_number

log = logging.getLogger("contact.optimize.development")

#: [1 of the centre tolerance] how far below the target centre v the second height of
#: :func:`root_variants` aims (the lower pattern carries more root safety, measured on the
#: 8×47: S_F,FE 1.331 at v 0.54, 1.369 at v 0.46; its tolerance band's lower part)
LOWER_CENTRE = 0.75

#: the tip relief factors :func:`root_variants` combines with each lowered pattern (× the
#: design's tip relief, clipped to the variable's bound): the tip relief clears the pinion
#: tip edge a lower pattern reaches, at some of the root safety it bought. Measured on the
#: 8×47 at −0.2° (centre v 0.54): tip relief 21.4 µm plastic 2.5 %, 32.2 µm (× 1.5) 0.9 %,
#: 45 µm (× 2.1) none (centre v 0.585, S_F,FE 1.247 against the written 1.246)
TIP_FACTORS = (1.0, 1.5, 2.1)

#: [1] the later start of the tip relief :func:`root_variants` also tries with the tip
#: relief × 1.5 (``tip_relief_start`` + this, clipped to its bound): the flankrem kept to
#: the pinion's tip, where the edge is. Measured on the 8×47 at −0.2°: 32.2 µm from 0.61
#: plastic 0.94 %, S_F,FE 1.287; from 0.7 no plastic, edge 1.41 %, S_F,FE 1.297
LATER_START = 0.1

#: [1] the least rise of S_F,FE for which a variant replaces the written design
ROOT_GAIN = 0.005

#: [1] the least ratio of the largest allowed edge radius to the written one for which
#: :func:`larger_edge_radius` tries it (a few per cent is within the FE model's accuracy)
EDGE_GAIN = 1.05


@dataclass(frozen=True)
class RootTrial:
    """One variant of :func:`checked_given_root`, for its sentence.

    Attributes
    ----------
    label : str — the change in words
    safety : float — [1] S_F,FE of the weaker member at the given torque (NaN: not computed)
    member : str — that member ("" where not computed)
    missed : tuple of str — the targets the written design met that it misses
    centre_v : float — [1] its light-load centre v (NaN where it has none)
    """

    label: str
    safety: float
    member: str
    missed: tuple[str, ...]
    centre_v: float


def root_variants(values: Mapping[str, float], centre_v: float, target_v: float,
                  tolerance: float, bounds: Mapping[str, tuple[float, float]],
                  slope: float = HEIGHT_SLOPE) -> list[tuple[dict[str, float], str]]:
    """The drive designs :func:`checked_given_root` tries, in order: the light-load
    pattern centred at ``target_v`` by the blade-angle change, then at
    ``target_v − LOWER_CENTRE × tolerance``, each with the design's tip relief × each of
    :data:`TIP_FACTORS`, then × 1.5 from a start :data:`LATER_START` later.

    Parameters
    ----------
    values : mapping — the written design's prescriptions [file units]
    centre_v : float — [1] its light-load footprint centre v (finite)
    target_v : float — [1] the centre v aimed at
    tolerance : float — [1] the centre's tolerance (> 0)
    bounds : mapping — the development's variable bounds (``blade_angle_change`` [deg],
        ``tip_relief`` [µm], ``tip_relief_start`` [1])
    slope : float — [1/deg] d(centre v)/d(blade-angle change), floored at
        :data:`~contact.optimize.development_stages.HEIGHT_SLOPE_MIN`

    Returns
    -------
    list of (dict, str)
        Each variant's prescriptions and its change in words; empty where the blade angle
        is not developed, the pattern is at or below the heights aimed at, or the bound
        stops the change.

    Raises
    ------
    InputError
        A non-finite centre v or target, or a tolerance <= 0.

    Notes
    -----
    Source: the pattern's height by the pressure-angle change (Stadtfeld, *Gleason Bevel
    Gear Technology*, 2014; :mod:`geometry.synthesis.blade_change`); the tip relief by the
    blade's flankrem (:func:`geometry.machine.relief.relieved_blade`).
    """
    if not (math.isfinite(centre_v) and math.isfinite(target_v)):
        raise InputError(f"root variants: centre_v {centre_v} and target_v {target_v} "
                         "must be finite")
    if not tolerance > 0.0:
        raise InputError(f"root variants: tolerance must be > 0, got {tolerance}")
    if HEIGHT_NAME not in bounds or HEIGHT_NAME not in values:
        return []
    lo, hi = (float(x) for x in bounds[HEIGHT_NAME])
    now = float(values[HEIGHT_NAME])
    s = max(float(slope), HEIGHT_SLOPE_MIN)
    out: list[tuple[dict[str, float], str]] = []
    seen: list[dict[str, float]] = []
    for aim in (target_v, target_v - LOWER_CENTRE * tolerance):
        dv = aim - centre_v
        if not dv < 0.0:
            continue
        blade = float(np.clip(now + dv / s, lo, hi))
        if abs(blade - now) < 1e-4:
            continue
        for factor in TIP_FACTORS:
            v = dict(values) | {HEIGHT_NAME: blade}
            label = f"centred lower ({HEIGHT_NAME} {blade:.3g} deg, aimed at v {aim:.2f})"
            if factor != 1.0:
                if "tip_relief" not in bounds or "tip_relief" not in values:
                    continue
                t_lo, t_hi = (float(x) for x in bounds["tip_relief"])
                tip = float(np.clip(float(values["tip_relief"]) * factor, t_lo, t_hi))
                if abs(tip - float(values["tip_relief"])) < 1e-6:
                    continue
                v["tip_relief"] = tip
                label += f", tip relief {tip:.3g} um"
            if v not in seen:
                seen.append(v)
                out.append((v, label))
        later = _later_start(values, bounds, blade, aim)
        if later is not None and later[0] not in seen:
            seen.append(later[0])
            out.append(later)
    return out


def _later_start(values: Mapping[str, float], bounds: Mapping[str, tuple[float, float]],
                 blade: float, aim: float) -> tuple[dict[str, float], str] | None:
    """The variant at ``blade`` [deg] with the tip relief × 1.5 from a start
    :data:`LATER_START` later (both clipped to their bounds); None where either is not
    developed or the start is at its bound."""
    names = ("tip_relief", "tip_relief_start")
    if not all(n in bounds and n in values for n in names):
        return None
    t_lo, t_hi = (float(x) for x in bounds["tip_relief"])
    s_lo, s_hi = (float(x) for x in bounds["tip_relief_start"])
    start = float(np.clip(float(values["tip_relief_start"]) + LATER_START, s_lo, s_hi))
    if abs(start - float(values["tip_relief_start"])) < 1e-6:
        return None
    tip = float(np.clip(float(values["tip_relief"]) * 1.5, t_lo, t_hi))
    v = dict(values) | {HEIGHT_NAME: blade, "tip_relief": tip, "tip_relief_start": start}
    return v, (f"centred lower ({HEIGHT_NAME} {blade:.3g} deg, aimed at v {aim:.2f}), tip "
               f"relief {tip:.3g} um from {start:.3g}")


def larger_edge_radius(current: float, largest: float, given: bool) -> float | None:
    """The blade edge radius :func:`checked_edge_radius` tries: the largest the design's
    point widths and clearance allow, where the basic file gives none (the synthesis'
    default ``min(0.25 m_mn, 0.4 W)`` written) and it is at least :data:`EDGE_GAIN` × the
    written one.

    Parameters
    ----------
    current : float — [mm] the written case's edge radius (> 0)
    largest : float — [mm] :func:`geometry.synthesis.edge_radius.largest_edge_radius`'s
    given : bool — whether the basic file gives ``[synthesis] edge_radius`` (the user's
        tool: kept)

    Returns
    -------
    float or None — [mm] ``largest``; None where not tried

    Raises
    ------
    InputError
        ``current`` not > 0 or a radius not finite, named.

    Notes
    -----
    Source: the fillet radius ρ_F of the root's notch grows with the tool's edge radius
    ρ_a0 (ISO 10300-3:2014, the stress correction factor Y_S), and a gear engineer takes
    the largest the blade point and the clearance allow first where the root binds
    (Stadtfeld, *Gleason Bevel Gear Technology*, 2014; AGMA 929-A06). Measured on the 8×47
    (docs/own_gear_set.md, "The cutter edge radius as the root's lever").
    """
    if not (math.isfinite(current) and current > 0.0):
        raise InputError(f"edge radius: the written edge radius must be finite and > 0 mm, "
                         f"got {current}")
    if not math.isfinite(largest):
        raise InputError(f"edge radius: the largest edge radius must be finite, got {largest}")
    if given or largest < EDGE_GAIN * current:
        return None
    return float(largest)


def edge_radius_to_try(basic: Any, current: float) -> float | None:
    """[mm] :func:`larger_edge_radius` of a developed basic design whose written case has
    the edge radius ``current`` [mm]: the largest of
    :func:`geometry.synthesis.edge_radius.largest_edge_radius` (the basic file's blade
    angles, else the generated pressure angles); None where not tried (a face-hobbed
    design, a radius the basic file gives, one not larger by :data:`EDGE_GAIN`, a slot
    that closes: logged)."""
    from geometry.synthesis.edge_radius import largest_edge_radius

    opt = basic.options
    if opt.edge_radius is not None or basic.design.z0 != 0:
        return None
    try:
        limit = largest_edge_radius(basic.blank(), opt.blade_angle_drive,
                                    opt.blade_angle_coast)
        return larger_edge_radius(current, limit.radius, False)
    except InputError as exc:
        log.info("development given root: no larger edge radius (%s)", exc)
        return None


def checked_edge_radius(best: DevelopmentEvaluation, safety: float, radius: float,
                        current: float, targets: DevelopmentTargets,
                        setup: Mapping[str, Any], teeth: KeptTeeth | None,
                        say: Callable[[str], None],
                        placed: Callable[[Mapping[str, float]], Case],
                        root_of: Callable[[Mapping[str, float]], tuple[float, str]]
                        ) -> tuple[DevelopmentEvaluation, float, RootTrial]:
    """The written drive design with the blade edge radius ``radius`` (both members'
    blades, the prescriptions as written): checked at ``ltca run``'s sampling, its FE root
    safety at the given torque computed (the lever's effect, said), kept where it misses no
    target the written design met, its S_F,FE is higher by :data:`ROOT_GAIN` (or within
    it while more targets are met) and it is tolerant.

    Parameters
    ----------
    best : DevelopmentEvaluation — the written drive design, checked
    safety : float — [1] its S_F,FE at the given torque
    radius, current : float — [mm] the edge radius tried (:func:`larger_edge_radius`) and
        the written one
    targets, setup, teeth, say
        As :func:`checked_given_root`'s.
    placed : callable values → Case
        The synthesis as written with the edge radius ``radius``.
    root_of : callable values → (S_F,FE [1], member)
        The weaker member's FE root safety at the given torque of the case written with
        the edge radius ``radius`` and the drive prescriptions ``values``.

    Returns
    -------
    (DevelopmentEvaluation, float, RootTrial)
        The design kept (``best`` where not) and its S_F,FE, and the trial for the note.

    Raises
    ------
    Nothing: a synthesis or analysis that fails is said and the written design stands.

    Notes
    -----
    Source: :func:`larger_edge_radius`; the keep rule of :func:`checked_given_root`.
    """
    label = f"edge radius {radius:.3g} mm (was {current:.4g}; the largest the slots allow)"
    e = said_variant(best, best.values, "given root", label, targets, setup, teeth, say,
                     placed, key_prefix=("edge_radius", float(radius)))
    if e is None or e.full is None or e.metrics is None:
        return best, safety, RootTrial(label, math.nan, "", ("analysis",), math.nan)
    gone = tuple(lost_targets(best, e))
    cv = float(e.metrics["pattern_centre_v"][0])
    try:
        sf, member = root_of(best.values)
    except Exception as exc:  # said, never fatal: the written design stands
        raise_if_interrupted(exc)
        log.info("development given root: %s not computed: %s", label, exc)
        sf, member = math.nan, ""
    trial = RootTrial(label, sf, member, gone, cv)
    say(f"  {label}: S_F,FE {sf:.3f} ({member or 'n/a'}) at the given torque"
        + (f"; misses {', '.join(gone)}" if gone else ""))
    if gone or not _better(best, safety, e, sf):
        return best, safety, trial
    if kept_why(best, e, targets, setup, teeth, say, label, better=lambda *_: True,
                lost=lost_targets):
        return best, safety, trial
    return e, sf, trial


def checked_given_root(best: DevelopmentEvaluation, safety: float, s_min: float,
                       targets: DevelopmentTargets, setup: Mapping[str, Any],
                       teeth: KeptTeeth | None, say: Callable[[str], None],
                       placed: Callable[[Mapping[str, float]], Case],
                       root_of: Callable[[Mapping[str, float]], tuple[float, str]],
                       slope: float | None = None
                       ) -> tuple[DevelopmentEvaluation, float, list[RootTrial]]:
    """The written drive design, or the variant of :func:`root_variants` with the highest
    FE root safety at the given design torque that misses no target it met.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The written drive design, checked at ``ltca run``'s sampling (its metrics'
        ``pattern_centre_v`` [1]).
    safety : float — [1] its S_F,FE at the given torque (below ``s_min``)
    s_min : float — [1] the rating's S_Fmin
    targets, setup, teeth, say, placed
        As every check step's (:func:`~contact.optimize.development_check.check_steps`;
        ``setup["torques"]`` [N·m], light and the given design torque; ``centre_v``).
    root_of : callable values → (S_F,FE [1], member)
        The weaker member's FE root safety at the given torque of the case written with
        the drive prescriptions ``values`` (its coast flank as written), on the FE model
        ``ltca run`` reads; raises where it cannot be computed.
    slope : float, optional — [1/deg] the bearing's measured d(centre v)/d(blade angle)

    Returns
    -------
    (DevelopmentEvaluation, float, list of RootTrial)
        The design kept (``best`` where none), its S_F,FE at the given torque, and each
        variant tried.

    Raises
    ------
    Nothing: a variant whose synthesis or analysis fails is said and not kept.

    Notes
    -----
    The first variant's measured d(centre v)/d(blade angle) (where at least
    :data:`~contact.optimize.development_stages.HEIGHT_SLOPE_MIN`) sets the blade angle of
    the others. Kept where no target ``best`` met is lost
    (:func:`~contact.optimize.development_keep.lost_targets`), S_F,FE rises by at least
    :data:`ROOT_GAIN` over the design kept so far or stays within it while more targets
    are met (:func:`_better`), and it is tolerant (the mounting excursions). Variants are
    tried in :func:`root_variants`' order; the step ends at the first kept that reaches
    ``s_min`` and meets every target. The root stress (an ``ltca
    run`` analysis with the FE root stress, ~7-9 s of CPU on the 8×47) is computed for
    the first variant (the lever's effect, said) and for those that lose no target.
    Source: the verdict's root-stress check (ISO 10300-3 σ_FP on the FE fillet stress,
    :func:`contact.study.verdict_checks.root_stress_safety`).
    """
    trials: list[RootTrial] = []
    if not best.checked_full or best.metrics is None or not math.isfinite(safety):
        return best, safety, trials
    v0 = float(best.metrics["pattern_centre_v"][0])
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else float(setup["centre_v"]))
    s = slope if slope is not None and abs(slope) >= HEIGHT_SLOPE_MIN else HEIGHT_SLOPE
    try:
        variants = root_variants(best.values, v0, target, targets.centre_tolerance,
                                 targets.variables, s)
    except InputError as exc:
        log.info("development given root: no variants (%s)", exc)
        return best, safety, trials
    if not variants:
        return best, safety, trials
    say(f"development: the given design torque {plain_number(float(setup['torques'][1]))} "
        f"N m is above the written bearing's root capacity (S_F,FE {safety:.3f} < "
        f"{s_min:g}); a pattern centred lower (the gear loaded nearer its root) tried")
    chosen, chosen_safety = best, safety
    b0 = float(best.values[HEIGHT_NAME])
    n = 0
    while n < len(variants):
        values, label = variants[n]
        n += 1
        e = said_variant(best, values, "given root", label, targets, setup, teeth, say,
                         placed)
        if n == 1 and e is not None and e.metrics is not None:
            # the slope the first variant measured (the bearing's own: the 8x47's 0.5 per
            # degree against the default 0.28) sets the heights of the others
            db = float(values[HEIGHT_NAME]) - b0
            dv = float(e.metrics["pattern_centre_v"][0]) - v0
            if db != 0.0 and math.isfinite(dv) and dv / db >= HEIGHT_SLOPE_MIN:
                variants = variants[:1] + root_variants(
                    best.values, v0, target, targets.centre_tolerance, targets.variables,
                    dv / db)[1:]
        if e is None or e.full is None:
            trials.append(RootTrial(label, math.nan, "", ("analysis",), math.nan))
            continue
        gone = tuple(lost_targets(best, e))
        cv = float(e.metrics["pattern_centre_v"][0])
        if gone and trials:  # the first variant's root always (the lever's sign said)
            trials.append(RootTrial(label, math.nan, "", gone, cv))
            say(f"  not kept: {label} misses {', '.join(gone)} (root stress not computed)")
            continue
        try:
            sf, member = root_of(values)
        except Exception as exc:  # said, never fatal: the written design stands
            raise_if_interrupted(exc)
            log.info("development given root: %s not computed: %s", label, exc)
            sf, member = math.nan, ""
        trials.append(RootTrial(label, sf, member, gone, cv))
        say(f"  {label}: S_F,FE {sf:.3f} ({member or 'n/a'}) at the given torque"
            + (f"; misses {', '.join(gone)}" if gone else ""))
        if gone or not _better(chosen, chosen_safety, e, sf):
            continue
        why = kept_why(best, e, targets, setup, teeth, say, label,
                       better=lambda *_: True, lost=lost_targets)
        if why:
            continue
        chosen, chosen_safety = e, sf
        if sf >= s_min and e.full[2]:
            break
    return chosen, chosen_safety, trials


def _better(chosen: DevelopmentEvaluation, chosen_safety: float, e: DevelopmentEvaluation,
            safety: float) -> bool:
    """Whether a variant that loses no met target replaces ``chosen``: its S_F,FE is
    higher by :data:`ROOT_GAIN`, or within it and the variant meets more targets (a
    drive target gained at the same root, e.g. its centre v)."""
    if not math.isfinite(safety):
        return False
    if safety >= chosen_safety + ROOT_GAIN:
        return True
    met = sum(v == 0.0 for v in e.full[1].values())
    was = sum(v == 0.0 for v in chosen.full[1].values())
    return safety >= chosen_safety - ROOT_GAIN and met > was


def tried_text(trials: list[RootTrial], safety: float, s_min: float, kept: bool) -> str:
    """The sentence of what :func:`checked_given_root` tried, for the note on the given
    torque: each variant's S_F,FE and the targets it misses, and whether one was kept.

    Parameters
    ----------
    trials : list of RootTrial
    safety : float — [1] S_F,FE of the design written at the given torque
    s_min : float — [1] S_Fmin
    kept : bool — whether a variant replaced the design

    Returns
    -------
    str — empty where nothing was tried
    """
    if not trials:
        return ""
    parts = []
    for t in trials:
        sf = f"S_F,FE {t.safety:.2f}" if math.isfinite(t.safety) else "S_F,FE not computed"
        cv = f"centre v {t.centre_v:.2f}, " if math.isfinite(t.centre_v) else ""
        parts.append(f"{t.label}: {cv}{sf}"
                     + (f", misses {', '.join(t.missed)}" if t.missed else ""))
    head = ("a pattern centred lower was tried (the gear loaded nearer its root): "
            + "; ".join(parts))
    if kept:
        return head + (f"; the bearing of the highest root safety that loses no target "
                       f"kept (S_F,FE {safety:.2f}, S_Fmin {s_min:g})")
    return head + ("; none kept (each raising the root safety misses a target the "
                   f"written design meets, S_Fmin {s_min:g})")


def edge_text(trial: RootTrial | None, kept: bool) -> str:
    """The sentence of :func:`checked_edge_radius`'s trial, for the note on the given
    torque: its S_F,FE, the targets it misses and whether it was kept; empty where none was
    tried."""
    if trial is None:
        return ""
    sf = (f"S_F,FE {trial.safety:.2f}" if math.isfinite(trial.safety)
          else "S_F,FE not computed")
    cv = f"centre v {trial.centre_v:.2f}, " if math.isfinite(trial.centre_v) else ""
    miss = f", misses {', '.join(trial.missed)}" if trial.missed else ""
    return (f"a larger fillet was tried (the blade's {trial.label}): {cv}{sf}{miss}; "
            + ("kept" if kept else "not kept"))
