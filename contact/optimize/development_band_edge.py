"""The near-miss step's band-edge designs (issue 71): where every blade-angle step of
:func:`~contact.optimize.development_pattern_steps.checked_near_miss` (aimed
:data:`~contact.optimize.development_pattern_steps.NEAR_MISS_AIM` of the tolerance inside
the light-load centre band) gave up the LTE or the pattern length (:data:`BAND_EDGE_LOST`),
the smallest blade step that just meets the band (:data:`BAND_EDGE_AIM`) and, where that
misses the LTE alone, the same with the path turned towards the profile by
:data:`BAND_EDGE_PATH_TURN`. Each design placed and
checked at ``ltca run``'s sampling (:func:`~contact.optimize.development_variant.
said_variant`) and kept by the check's one rule (:func:`~contact.optimize.
development_keep.kept_why`, :func:`~contact.optimize.development_keep.lost_targets`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from contact.optimize.development_evaluate import KeptTeeth
from contact.optimize.development_keep import kept_why, lost_targets
from contact.optimize.development_result import DevelopmentEvaluation
from contact.optimize.development_targets import HEIGHT_NAME, DevelopmentTargets
from contact.optimize.development_variant import said_variant
from geometry.case import Case

#: [1] where the band-edge design aims the light-load centre v: this fraction of
#: ``centre_tolerance`` from the target, on the side the centre missed (just inside the
#: band's nearer bound, a margin of 0.1 of the tolerance for the linear step's error)
BAND_EDGE_AIM = 0.9
#: [deg] the band-edge design's path turn towards the profile where its blade step meets
#: the band and misses the LTE alone: the FM hypoid 11x39 at α 24° / 16°
#: (benchmarks/data/unseen_designs, ``ltca run``'s sampling at 56.7 / 378.4 N m), path
#: −65.6° → −70° with blade −0.03°: LTE 34.8 / 42.5 → 27.0 / 36.5 µrad, every target met
#: and tolerant (docs/synthesis.md, "The length step's LTE bought back ...")
BAND_EDGE_PATH_TURN = -5.0
#: the path angle's name among the development's variables
PATH_NAME = "path_angle"
#: the targets met before that the near-miss step's smallest blade step may have given up
#: for the band-edge pair to run: the LTE (a blade tilt costs unloaded TE in proportion to
#: its size) and the pattern length (the tilt walks the pattern towards the heel, by less
#: for a smaller step; checked_blade's notes). Measured on the FM hypoid 9x38 at Σ 95° of
#: benchmarks/data/unseen_designs (``ltca run``'s sampling at 62.6 / 417.6 N m, path
#: −65.6°, ellipse 0.625, ``te_level`` 45 → 25; ``benchmarks/development_levers.py --check
#: --tolerance``, 2026-11-27): as developed v 0.630 (0.542 ± 0.08), 0.58 long, LTE 37.4 /
#: 39.4 µrad; the near-miss aim −0.0425°: v 0.61, 0.62 long (0.5 ± 0.1, lost); −0.035° /
#: −0.03° / −0.025°: v 0.61 / 0.61 / 0.62, 0.60 / 0.60 / 0.58 long, LTE 36.2 / 38.5, 35.5 /
#: 37.6, 35.2 / 36.9 µrad, every target met, tolerant; −0.02°: v 0.62 still above the band
BAND_EDGE_LOST = ("length", "lte")


def _misses_only_lte(e: DevelopmentEvaluation) -> bool:
    """Whether a scored design misses its LTE and no other target."""
    return [k for k, v in e.full[1].items() if v > 0.0] == ["lte"]


def band_edge_designs(best: DevelopmentEvaluation, refused: Sequence[DevelopmentEvaluation],
                      targets: DevelopmentTargets, setup: Mapping[str, Any],
                      teeth: KeptTeeth | None, say: Callable[[str], None],
                      placed: Callable[[Mapping[str, float]], Case], *,
                      centre_v: Callable[[DevelopmentEvaluation], float],
                      better: Callable[[DevelopmentEvaluation, DevelopmentEvaluation], bool],
                      values: Mapping[str, float], te_text: str = ""
                      ) -> DevelopmentEvaluation:
    """The near-miss step's last pair of designs: the smallest blade step that meets the
    light-load centre band, then that step with the path turned.

    Parameters
    ----------
    best : DevelopmentEvaluation
        The near-miss design (checked; its centre v just off its band).
    refused : sequence of DevelopmentEvaluation
        The near-miss step's blade-angle designs, each refused; the pair runs only where
        the one of the smallest step gave up, of the targets ``best`` met, no more than
        the LTE and the pattern length (:func:`~contact.optimize.development_keep.
        lost_targets` within :data:`BAND_EDGE_LOST`: a smaller step costs less of both;
        the FM hypoid 9x38's −0.0425° gave up the length alone).
    targets, setup, teeth, say, placed
        As the check steps' (the centre target, its tolerance and the variables' bounds
        from ``targets``; ``setup["centre_v"]`` where the targets give no centre).
    centre_v : callable design → float
        [1] A design's light-load centre v (NaN where none).
    better : callable (best, e) → bool
        The near-miss step's rank (it meets more targets).
    values : mapping
        The near-miss designs' values but the blade angle (its TE level lowered, where it
        was) [deg, µrad, …].
    te_text : str, optional
        The lowered TE level in words, for the design's line.

    Returns
    -------
    DevelopmentEvaluation
        The first design kept by :func:`~contact.optimize.development_keep.kept_why`
        (better, no met target lost, tolerant), ``stage`` ``"near miss"``; ``best`` where
        none is or the pair does not apply (no slope measured, the step's blade angle
        at a step tried or at ``best``'s).

    Notes
    -----
    The blade angle is stepped on the secant between ``best`` and the refused design
    nearest it, to :data:`BAND_EDGE_AIM` of the tolerance from the target; the path (where
    developed) turned by :data:`BAND_EDGE_PATH_TURN` within its bounds. Why: a blade tilt
    costs unloaded TE at the light torque in proportion to its size (Litvin & Fuentes
    2004 §9.4), so the smallest step into the band keeps the most of the LTE, and a path
    nearer the profile keeps more tooth pairs in contact (:func:`~contact.optimize.
    development_path_steps.checked_path`). Measured on the FM hypoid 11x39 at α 24° / 16°
    (56.7 / 378.4 N m): blade −0.115° / −0.0595° (the near-miss aims): v 0.57 / 0.60, LTE
    43 / 54 and 36.6 / 45.7 µrad; −0.03°: v 0.62 (met), 34.8 / 42.5; with the path −70°:
    v 0.62, 0.60 long, 27.0 / 36.5 µrad, edge 1.1 %, every target met, tolerant
    (docs/synthesis.md).
    """
    x0, v0 = float(best.values[HEIGHT_NAME]), centre_v(best)
    if not refused:
        return best
    near = min(refused, key=lambda e: abs(float(e.values[HEIGHT_NAME]) - x0))
    lost = lost_targets(best, near)
    if not lost or not set(lost) <= set(BAND_EDGE_LOST):
        return best  # the smallest blade step gave up more than the LTE and the length
    lo, hi = (float(x) for x in targets.variables[HEIGHT_NAME])
    target = (targets.pattern_centre_v if targets.pattern_centre_v is not None
              else setup["centre_v"])
    xn, vn = float(near.values[HEIGHT_NAME]), centre_v(near)
    if not (math.isfinite(vn) and abs(xn - x0) > 1e-9 and (vn - v0) / (xn - x0) > 0.05):
        return best  # no slope to step on
    s = (vn - v0) / (xn - x0)
    aim = target + math.copysign(BAND_EDGE_AIM * targets.centre_tolerance, v0 - target)
    x = float(np.clip(x0 - (v0 - aim) / s, lo, hi))
    if abs(x - x0) < 1e-4 or any(abs(x - float(e.values[HEIGHT_NAME])) < 1e-3
                                 for e in refused):
        return best
    edge = dict(values) | {HEIGHT_NAME: x}
    e = said_variant(best, edge, "near miss",
                     f"with {HEIGHT_NAME} {x:.3g} deg{te_text} (its centre v just inside "
                     "its band)", targets, setup, teeth, say, placed)
    if not kept_why(best, e, targets, setup, teeth, say, "the band-edge blade step",
                    lost=lost_targets, lost_first=True, better=better):
        return e
    if e is None or not _misses_only_lte(e) or PATH_NAME not in targets.variables \
            or PATH_NAME not in edge:
        return best
    p_lo, p_hi = (float(p) for p in targets.variables[PATH_NAME])
    p0 = float(edge[PATH_NAME])
    p = float(np.clip(p0 + BAND_EDGE_PATH_TURN, p_lo, p_hi))
    if abs(p - p0) < 1e-3:
        return best  # the path at its bound
    f = said_variant(best, edge | {PATH_NAME: p}, "near miss",
                     f"with {HEIGHT_NAME} {x:.3g} deg{te_text} and {PATH_NAME} {p:.3g} deg "
                     "(its centre v just inside its band, the LTE by the path)",
                     targets, setup, teeth, say, placed)
    if not kept_why(best, f, targets, setup, teeth, say,
                    "the band-edge blade step with the path turned",
                    lost=lost_targets, lost_first=True, better=better):
        return f
    return best
