"""The roll window in which one tooth pair's contact stays on the unrelieved pinion flank.

A local synthesis (:mod:`geometry.synthesis.case_synthesis`) designs the drive flank's
unloaded TE as a parabola about the mean point M, TE(roll) = te_level · (roll/pitch)², and
the pairs hand the load over where two neighbours' parabolas cross, half a pitch of roll
either side of the vertex. That transfer lies on the designed parabola only while *both*
pairs still touch on the flank the parabola was designed on: between the pinion blade's
relief corners (the flankrem's corner, where the tip relief starts, and the toprem's, where
the root relief starts; :mod:`geometry.machine.relief`) and inside the two blanks' outlines.
How far one pitch of roll carries the contact depends on the path's direction: the contact
point's velocity across the instantaneous contact line is fixed by the kinematics, so a path
near the conjugate contact line runs fast, and on a pinion of few teeth one pitch of a
diagonal path can climb the whole working depth (docs/synthesis.md, "The miter 20×20's
transfer on the tip relief": the FM miter 20×20 at path −45° leaves the unrelieved flank at
−0.35 and +0.25 pitch, its transfer then made by the tip relief, UTE p-p 104 µrad against
the parabola's 2.5).

:func:`path_window` measures that window on a case: the conventional TCA (seed Eq. 2.14,
:func:`geometry.pair.conventional_tca.conventional_tca`) of the flank with its blade's rems
taken off (the same blade and settings, so the path of the unrelieved flank the synthesis
designed), each pinion contact point mapped back to the blade height that cuts it
(:func:`geometry.machine.flank_point.flank_points`), compared with the relieved blade's
corner heights, and its face fraction with the blank's outline.

Public names
------------
PathWindow   the window and the per-roll places it was read from
path_window  measure it on a case's flank
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from geometry.case import Case, FlankTool
from geometry.core.errors import InputError
from geometry.machine.cutter import blade_profile
from geometry.machine.flank import blank_outline, projection_fractions
from geometry.machine.flank_point import flank_points
from geometry.pair.assembly import Misalignment
from geometry.pair.conventional_tca import conventional_tca

__all__ = ["PathWindow", "path_window"]

#: default roll positions [pitch]: ±0.8 pitch in steps of 0.05 (the window's ends are read
#: to that step)
DEFAULT_ROLLS = np.round(np.linspace(-0.8, 0.8, 33), 10)


@dataclass(frozen=True, eq=False)
class PathWindow:
    """Where one tooth pair's contact path lies on the unrelieved pinion flank.

    Attributes
    ----------
    flank : str
        Pinion flank analysed.
    roll : ndarray (K,) — [pitch]
        Pinion roll from the mean contact M, in pinion pitches 2π/z1.
    height : ndarray (K,) — [mm]
        Blade height (above the blade tip) that cuts the pinion contact point; NaN where the
        TCA found no contact.
    face : ndarray (K,) — [1]
        Face fraction u of the pinion contact point in its projection plane (toe 0, heel 1).
    on_unrelieved : ndarray (K,) bool
        Contact found, inside both blanks' outlines and between the relief corners.
    tip_corner, root_corner : float — [mm]
        Blade heights of the flankrem's and the toprem's corners (+inf / −inf where the
        blade has no such rem).
    low, high : float — [pitch]
        Ends of the contiguous run of ``on_unrelieved`` rolls that holds roll 0 (NaN, NaN
        if roll 0 itself is not on the unrelieved flank).
    """

    flank: str
    roll: np.ndarray
    height: np.ndarray
    face: np.ndarray
    on_unrelieved: np.ndarray
    tip_corner: float
    root_corner: float
    low: float
    high: float

    @property
    def span(self) -> float:
        """Length of the window [pitch] (NaN where roll 0 is outside it)."""
        return self.high - self.low

    @property
    def holds_pitch(self) -> bool:
        """True where the window holds ±half a pitch about M, so both transfers of the
        designed parabola lie on the unrelieved flank."""
        return bool(self.low <= -0.5 + 1e-9 and self.high >= 0.5 - 1e-9)

    def leaves_by(self) -> str:
        """Where the path leaves the window on the side it is shortest, in words (for a
        log line or a note): ``"tip relief at +0.25 pitch"`` (past a relief corner), ``"face
        end"`` (past toe or heel), ``"blank's edge"`` (off either blank's outline between
        the corners) or ``"flank's end"`` (no contact found)."""
        if not np.isfinite(self.low):
            return "not on the unrelieved flank at M"
        ends = []
        for end, step in ((self.high, +1), (self.low, -1)):
            k = int(np.argmin(np.abs(self.roll - end))) + step
            if not 0 <= k < len(self.roll):
                continue
            h, u = self.height[k], self.face[k]
            why = ("tip relief" if h > self.tip_corner else "root relief"
                   if h < self.root_corner else "face end" if not 0.0 <= u <= 1.0
                   else "blank's edge" if np.isfinite(h) else "flank's end")
            ends.append((abs(end), f"{why} at {end:+.2f} pitch"))
        return min(ends)[1] if ends else "nowhere within the rolls analysed"


def _run_about_zero(roll: np.ndarray, good: np.ndarray) -> tuple[float, float]:
    """Ends of the contiguous True run of ``good`` holding the roll nearest 0."""
    i0 = int(np.argmin(np.abs(roll)))
    if not good[i0]:
        return math.nan, math.nan
    lo = hi = i0
    while lo > 0 and good[lo - 1]:
        lo -= 1
    while hi < len(roll) - 1 and good[hi + 1]:
        hi += 1
    return float(roll[lo]), float(roll[hi])


def path_window(case: Case, flank: str | None = None, *,
                rolls=DEFAULT_ROLLS) -> PathWindow:
    """Measure the roll window of one pair's contact on the unrelieved pinion flank.

    Parameters
    ----------
    case : geometry.case.Case
        A case whose pinion flank carries its relief as blade rems (a synthesised case).
    flank : str, optional
        Pinion flank (``"concave"`` or ``"convex"``); default the pair's drive flank.
    rolls : array_like (K,) — [pitch]
        Pinion roll positions from the mean contact M, in pitches; sorted, holding 0.
        Default ±0.8 pitch in steps of 0.05.

    Returns
    -------
    PathWindow
        In the nominal assembly (no misalignment: the design's own path).

    Raises
    ------
    InputError
        For rolls not sorted or without 0, or a pair without a mean contact.

    Notes
    -----
    Source: the conventional TCA of seed Eq. 2.14 on the flank without its rems (a relief
    only removes material outside its corners, so between them the unrelieved flank is
    the relieved one, :mod:`geometry.machine.relief`), the relief corners' blade heights of
    the case's blade, the transfer of the designed TE parabola at ±pitch/2 (seed §2.3.1,
    Fig. 2.9). Cost: one conventional TCA of K positions, seconds.
    """
    x = np.asarray(rolls, dtype=float)
    if x.ndim != 1 or x.size < 2 or np.any(np.diff(x) <= 0) or not np.any(np.abs(x) < 1e-12):
        raise InputError("rolls: must be a sorted 1-D array of pinion rolls [pitch] that "
                         "holds 0")
    flank = case.pair.drive_flank if flank is None else flank
    pin = case.pinion
    tool = pin.flank(flank)
    blade = tool.blade
    tip_corner = blade.flankrem_height if blade.flankrem_angle else math.inf
    root_corner = blade.toprem_height if blade.toprem_angle else -math.inf
    bare = dataclasses.replace(blade, flankrem_angle=0.0, toprem_angle=0.0)
    bare_case = dataclasses.replace(case, pinion=dataclasses.replace(
        pin, **{flank: FlankTool(bare, tool.machine)}))
    pitch = 2.0 * math.pi / pin.blank.teeth
    res = conventional_tca(bare_case, x * pitch, flank=flank, misalignment=Misalignment())
    pp = res.pinion_projection
    height = np.full(x.shape, np.nan)
    face = np.full(x.shape, np.nan)
    ok = res.converged & np.isfinite(pp[:, 0])
    if ok.any():
        pts = flank_points(bare, tool.machine, pin.blank, pin.hand, pp[ok, 0], pp[ok, 1])
        params = np.asarray(pts.params)
        h = blade_profile(bare, params[:, 0], params[:, 3].astype(int)).h
        height[ok] = np.where(pts.ok, h, np.nan)
        u, _ = projection_fractions(blank_outline(pin.blank).corners, pp[ok, 0], pp[ok, 1])
        face[ok] = u
    with np.errstate(invalid="ignore"):
        good = (ok & res.on_flank & (height <= tip_corner) & (height >= root_corner)
                & (face >= 0.0) & (face <= 1.0))
    low, high = _run_about_zero(x, good)
    return PathWindow(flank, x, height, face, good, float(tip_corner), float(root_corner),
                      low, high)
