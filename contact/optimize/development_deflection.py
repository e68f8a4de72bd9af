"""The drive LTE at the design torque against the teeth's mean deflection there (issue 71:
the ratio-1 spiral bevel 16x16 at Σ 60°, which FAILs on its LTE at its ISO capacity with
conjugate flanks).

The loaded TE of a pair at a torque is its unloaded TE plus the mesh deflection (the gear's
lag under load); its peak-to-peak, the LTE, is the part of that sum which varies over the
mesh cycle. At a given bearing the LTE at the design torque is thus a share — the *spread*
of the deflection — of the mean deflection there, and the mean deflection is set by the
design torque and the teeth's compliance, not by the bearing's levers. Measured at ``ltca
run``'s sampling on the written cases of ``ltca synthesize`` with every default
(2026-11-27; docs/synthesis.md, "The LTE at the design torque: the teeth's deflection"):

* spiral bevel 13x39 (ratio 3, every target met): mean deflection 492 µrad at its design
  torque 246.5 N m, LTE p-p 38 µrad, 7.7 % of it;
* spiral bevel 16x16 at Σ 60° (ratio 1, ε_vβ 0.93): 922 µrad at 649.4 N m, 122 µrad,
  13.2 %; every bearing lever tried on it (TE level 10–80 µrad, profile crowning 0, the
  ellipse up to 0.89 of the face, path −50° to −80°, no relief) left 90–126 µrad there.

A ratio-1 pair at its ISO 10300 capacity deflects about twice as far in gear angle as a
ratio-3 pair: the line load its pitting capacity allows follows the flanks' relative
curvature radius ρ_red, and the gear angle is the deflection over the gear's mean radius
(ρ_red / r_m2 0.58 on the 16x16, 0.32 on the 13x39, :func:`curvature_ratio`; their line
loads 390 and 354 N/mm, linear deflections 48 and 38 µm on gears of 52 and 77 mm mean
radius). Within 60 µrad its LTE would need a spread of 60 / 922 = 6.5 %, below even the
ratio-3 pair's. Measured remedies (the 16x16's basic file changed, ``ltca synthesize`` and
``ltca run`` with every default): the design torque 300 N m (LTE p-p 57 / 55 µrad, drive
ATTENTION without an LTE finding); 24x24 teeth on the same d_e2 (ε_vα 1.22, ε_vβ 1.40:
19 / 32 µrad at 69 / 460.5 N m, its local pitting capacity; 5.2 % of 616 µrad); not a
wider face or a larger spiral angle (β_m 43.5°, ε_vβ 1.26: 92 µrad at 676.6 N m; b2 36 mm
with β_m 40°, ε_vβ 1.28: 114 µrad at 729.6 N m — the ISO capacity and the deflection rise
with them). :func:`deflection_text` says so in numbers where the written
design's LTE exceeds the verdict's limit: the mean deflection, the LTE's share of it and
the share the limit needs, and the torque up to which the written bearing keeps the LTE
within the limit (analysed at :data:`LTE_TORQUES` torques from the light to the design
torque).

Public names
------------
LTE_TORQUES (of :mod:`contact.ltca.lte_range`, which `ltca run`'s ``lte_range`` step
shares), CURVATURE_RATIO_NOTE, DeflectionLTE, deflection_lte, within_torque (of
:mod:`contact.study.lte_within`, which `ltca run`'s verdict shares), analysed,
curvature_ratio, deflection_text, between_text
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import xarray as xr

from contact.ltca.lte_range import LTE_TORQUES, bisected, lte_range_torques
from contact.study.lte_within import within_text, within_torque
from geometry.case import Case
from geometry.core.text import plain_number

__all__ = ["CURVATURE_RATIO_NOTE", "LTE_TORQUES", "DeflectionLTE", "analysed",
           "between_text", "curvature_ratio", "deflection_lte", "deflection_text",
           "within_torque"]

#: the virtual gears' relative curvature radius over the gear's mean radius [1]
#: (:func:`curvature_ratio`) above which :func:`deflection_text` says the pair deflects the
#: more for it: 0.58 on the 16x16 at Σ 60°, 0.71 on a miter, 0.55 at a ratio of 1.5 at
#: Σ 90°, 0.32 on the 13x39 (ratio 3) whose deflection at its ISO capacity is half the
#: 16x16's in gear angle
CURVATURE_RATIO_NOTE = 0.45


class DeflectionLTE(NamedTuple):
    """The LTE and the mean mesh deflection of one flank at several torques
    (:func:`deflection_lte`)."""

    torques: tuple[float, ...]  # [N·m] pinion torques, ascending
    lte: tuple[float, ...]  # [µrad] LTE peak-to-peak at each
    deflection: tuple[float, ...]  # [µrad] mean loaded TE less mean unloaded TE at each
    limit: float  # [µrad] the verdict's LTE limit

    @property
    def share(self) -> float:
        """LTE p-p over the mean deflection [1] at the last (design) torque."""
        d = self.deflection[-1]
        return self.lte[-1] / d if d > 0.0 else math.nan

    @property
    def share_needed(self) -> float:
        """The share [1] of the mean deflection at the last torque the limit allows."""
        d = self.deflection[-1]
        return self.limit / d if d > 0.0 else math.nan

    @property
    def within(self) -> float:
        """The torque [N·m] up to which the LTE p-p keeps the limit (:func:`within_torque`)."""
        return within_torque(self.torques, self.lte, self.limit)


def deflection_lte(ltca: xr.Dataset, limit: float | None = None) -> DeflectionLTE:
    """The LTE p-p and the mean mesh deflection at each torque of an LTCA result.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` of :func:`contact.pipeline.run_analysis`: ``transmission_error`` (torque,
        roll) [µrad], ``unloaded_transmission_error`` (roll) [µrad], ``lte_peak_to_peak``
        (torque) [µrad], coordinate ``torque`` [N·m]; ``found`` (torque, roll) [1] where
        the LTCA gives it (a roll position's contact solution certified).
    limit : float, optional — [µrad]
        Default :data:`contact.study.verdicts.LTE_LIMIT` (60 µrad).

    Returns
    -------
    DeflectionLTE
        Its LTE NaN at a torque where a roll position has no certified contact solution
        (``found`` 0): no LTE to judge there, as ``ltca run``'s ``lte_range`` step says
        (:func:`contact.ltca.lte_range.lte_range`).

    Raises
    ------
    KeyError
        A variable named above missing.

    Notes
    -----
    The mean deflection is the mean over the roll positions of the loaded TE less the
    unloaded TE (the loaded TE is the unloaded TE plus the gear's lag under load,
    :mod:`contact.ltca`), the quantity whose spread over the mesh cycle the LTE is.
    """
    if limit is None:
        from contact.study.verdicts import LTE_LIMIT

        limit = LTE_LIMIT
    te = np.asarray(ltca["transmission_error"].values, float)
    ute = np.asarray(ltca["unloaded_transmission_error"].values, float)
    deflection = np.nanmean(te - ute, axis=-1)
    lte = np.asarray(ltca["lte_peak_to_peak"].values, float)
    if "found" in ltca.variables:  # an uncertified solve: NaN, never a number (lte_range)
        found = ltca["found"]
        rest = [d for d in found.dims if d != "torque"]
        lte = np.where(np.asarray(found.astype(bool).all(dim=rest).values, bool), lte,
                       math.nan)
    order = np.argsort(np.asarray(ltca["torque"].values, float))
    return DeflectionLTE(
        tuple(float(x) for x in np.asarray(ltca["torque"].values, float)[order]),
        tuple(float(x) for x in lte[order]),
        tuple(float(x) for x in deflection[order]), float(limit))


def curvature_ratio(z1: int, z2: int, delta1: float, delta2: float) -> float:
    """The relative curvature radius of a bevel pair's virtual cylindrical gears over the
    gear's mean pitch radius.

    Parameters
    ----------
    z1, z2 : int
        Pinion and gear teeth.
    delta1, delta2 : float — [rad]
        Pitch angles.

    Returns
    -------
    float — [1]
        ρ_red / r_m2 = r_v1 r_v2 / ((r_v1 + r_v2) r_m2), r_vi = r_mi / cos δ_i, r_m1 / r_m2
        = z1 / z2 (the pressure angle's sine, common to both, left out).

    Raises
    ------
    ValueError
        Teeth not positive or a pitch angle outside (0, π/2).

    Notes
    -----
    ISO 10300-1:2014 §6.2 (the virtual cylindrical gears' reference radii r_v = r_m /
    cos δ); the flank's relative curvature radius at the pitch point is ρ_red sin α
    (Hertz's line contact of the two virtual involutes). At the pitting capacity the line
    load is ∝ ρ_red (σ_H² ∝ F/(b ρ_red)), the teeth's deflection ∝ the line load, and the
    deflection in gear angle ∝ ρ_red / r_m2.
    """
    if z1 <= 0 or z2 <= 0:
        raise ValueError(f"curvature_ratio: teeth must be positive, got {z1}, {z2}")
    if not (0.0 < delta1 < 0.5 * math.pi and 0.0 < delta2 < 0.5 * math.pi):
        raise ValueError(f"curvature_ratio: pitch angles must be in (0, pi/2) rad, got "
                         f"{delta1}, {delta2}")
    rv1 = (z1 / z2) / math.cos(delta1)
    rv2 = 1.0 / math.cos(delta2)
    return rv1 * rv2 / (rv1 + rv2)


def analysed(case: Case, light: float, design: float, flank: str = "drive",
             n: int = LTE_TORQUES, limit: float | None = None) -> DeflectionLTE:
    """:func:`deflection_lte` of a written case at ``n`` torques from ``light`` to
    ``design``, analysed as ``ltca run`` does (its default LTCA sampling and compliance;
    the contact analysis alone): the torques of ``ltca run``'s ``lte_range`` step
    (:func:`contact.ltca.lte_range.lte_range_torques`, the interval where the LTE first
    exceeds the limit :func:`contact.ltca.lte_range.bisected` as the step bisects it), so
    that the note and the run's ``lte`` finding say the same torque (issue 71).

    Parameters
    ----------
    case : geometry.case.Case
    light, design : float — [N·m]
        The development's light and design pinion torques.
    flank : str
        ``"drive"`` (default) or ``"coast"``.
    n : int
        Torques evenly spaced, ≥ 2 (default :data:`LTE_TORQUES`; the bisections' more).
    limit : float, optional — [µrad]
        The limit (default :data:`contact.study.verdicts.LTE_LIMIT`, 60 µrad) whose first
        crossing is bisected.

    Returns
    -------
    DeflectionLTE

    Raises
    ------
    InputError
        From the analysis (a case it cannot analyse).
    ValueError
        ``n`` below 2.
    """
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis

    if n < 2:
        raise ValueError(f"analysed: n must be >= 2, got {n}")
    # the torques `ltca run`'s lte_range step judges a case analysed at (light, design)
    torques = list(lte_range_torques((float(light), float(design)), float(design), int(n)))
    tree = run_analysis(case, torques, flank=flank, deviations=False,
                        steps=AnalysisChain.contact_only())
    found = deflection_lte(tree["/ltca"].to_dataset(), limit)
    more: dict[float, float] = {}  # the bisections' mean deflection [µrad] by torque

    def alone(torque: float) -> float:
        one = deflection_lte(run_analysis(case, [torque], flank=flank, deviations=False,
                                          steps=AnalysisChain.contact_only())
                             ["/ltca"].to_dataset())
        more[torque] = one.deflection[0]
        return one.lte[0]

    # the crossing bracketed closer, as the lte_range step does
    t, lte, _ = bisected(found.torques, found.lte, found.limit, alone)
    deflection = dict(zip(found.torques, found.deflection, strict=True)) | more
    return DeflectionLTE(t, lte, tuple(deflection[x] for x in t), found.limit)


def deflection_text(found: DeflectionLTE, curvature: float = math.nan) -> str | None:
    """``ltca synthesize``'s note where the written drive flank's LTE p-p at the design
    torque exceeds the limit: what sets it, in numbers, and the torque the bearing keeps
    it to.

    Parameters
    ----------
    found : DeflectionLTE
        The written drive flank's (:func:`analysed`), its last torque the design torque.
    curvature : float, optional — [1]
        The pair's :func:`curvature_ratio`; above :data:`CURVATURE_RATIO_NOTE` the note says
        that it makes the deflection large (default NaN: not said).

    Returns
    -------
    str or None
        None where the LTE at the last torque keeps the limit or the deflection is not
        positive.
    """
    if not found.lte[-1] > found.limit or not found.deflection[-1] > 0.0:
        return None
    torque = found.torques[-1]
    within = within_text(found.torques, found.lte, found.limit, torque, urad="urad",
                         nm="N m")
    curved = curvature > CURVATURE_RATIO_NOTE
    # the 16x16 is named by the curvature clause where it is said; without it (a pair far
    # from ratio 1) the note introduces it here, not as "that 16x16" the reader never met
    # (round 22: the spiral bevel 14x36 at Sigma 70 deg's note)
    sixteen = ("that 16x16" if curved else
               "a ratio-1 spiral bevel 16x16 at a shaft angle of 60 deg, its ISO capacity "
               "649.4 N m")
    up_to = ("" if within is None else
             f"; the written bearing keeps it {within}: a design torque at or below it "
             f"([synthesis] design_torque) is the step that keeps the limit (measured: "
             f"{sixteen} at 300 N m, LTE p-p 57/55 urad at 45/300 N m)")
    return (f"what sets the drive LTE at the design torque: the teeth deflect "
            f"{found.deflection[-1]:.0f} urad on average at {plain_number(torque)} N m (the "
            f"gear's lag under load, the mean loaded TE less the unloaded), and the LTE p-p "
            f"{found.lte[-1]:.0f} urad is {100 * found.share:.1f} % of it; within "
            f"{found.limit:g} urad it would be {100 * found.share_needed:.1f} % (a ratio-3 "
            "spiral bevel 13x39 whose every target is met: 7.7 % of 492 urad)"
            + (f"; its flanks' relative curvature radius is {curvature:.2f} of the gear's "
               "mean radius (0.32 on that 13x39, 0.58 on a 16x16 at a shaft angle of 60 deg: "
               "a ratio near 1), and the line load the pitting capacity allows, hence the "
               "deflection in gear angle at the ISO capacity, follows it; more teeth on the "
               "same gear size (a smaller module) raise both contact ratios and share the "
               "load (measured: that 16x16 as 24x24, eps_va 1.22, eps_vb 1.40, LTE p-p 19/32 "
               "urad at 69/460.5 N m, its local pitting capacity; a wider face or a larger "
               "spiral angle to eps_vb 1.26-1.28 kept 92-114 urad at 677-730 N m)"
               if curved
               else "") + up_to
            + " (docs/synthesis.md, 'The LTE at the design torque: the teeth's deflection')")


def between_text(found: DeflectionLTE) -> str | None:
    """``ltca synthesize``'s note where the written drive flank's LTE p-p keeps the limit at
    the light and the design torque and exceeds it between them: the peak, its torque and
    the limit, in numbers.

    Parameters
    ----------
    found : DeflectionLTE
        The written drive flank's (:func:`analysed`: ``ltca run``'s ``lte_range``
        torques), its first torque the light and its last the design torque.

    Returns
    -------
    str or None
        None where no torque's LTE exceeds the limit, or the first or the last does (the
        design torque's note, :func:`deflection_text`, or the light torque's own finding).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``lte_range`` step and verdict (:mod:`contact.ltca.lte_range`,
    issue 71, "LTE p-p ≤ 60 µrad at every torque"); the development's check judges the
    same torques (:mod:`contact.optimize.development_range_lte`).
    """
    lte = np.asarray(found.lte, float)
    if lte.size < 3 or not np.any(lte > found.limit):
        return None
    if lte[0] > found.limit or lte[-1] > found.limit:
        return None
    i = int(np.nanargmax(lte))
    curve = (f"LTE p-p {' / '.join(f'{x:.0f}' for x in lte)} urad at "
             f"{' / '.join(f'{plain_number(t)}' for t in found.torques)} N m")
    return (f"the drive LTE p-p is {lte[i]:.1f} urad at {plain_number(found.torques[i])} N m, "
            f"between the light {plain_number(found.torques[0])} and the design torque "
            f"{plain_number(found.torques[-1])} "
            f"N m, above the limit {found.limit:g} urad it keeps at both ({curve}, ltca "
            "run's lte_range torques): `ltca run`'s verdict finds it there; the "
            "development's check judged its designs between the torques too (the path turned "
            "towards the profile where its bound allows, the ellipse lengthened, "
            "contact.optimize.development_range_lte): no design it tried kept the limit "
            "there with its other targets and its mounting tolerance (docs/synthesis.md, "
            "'The LTE between the development's torques')")
