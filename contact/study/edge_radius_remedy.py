"""The cutter edge radius as the remedy of a tooth root that ``ltca run`` finds below its
minimum safety (issue 71, branch remedy84; the development's own step is
:func:`contact.optimize.development_given_root.checked_edge_radius`).

Where the verdict of an analysis has a ``root_stress`` finding (the FE root safety S_F,FE
below S_Fmin, or the FE root stress above the material's bending endurance), the lever a
gear engineer reaches for first is the fillet: the blades' edge radius r_e (ISO 10300-3's
ρ_a0), up to the largest the point widths and the clearance allow
(:func:`geometry.synthesis.edge_radius.largest_edge_radius`, from the case's ``[design]``
table). ``ltca run`` offers "edge radius r → r_max" under the verdict and, with
``--apply-remedy``, runs the same analysis of the case with every blade's edge radius
r_max; the remedy is **kept only where it improves the root and loses no criterion the
case met** (:func:`judged_remedy`): issue 71's rule that a command whose result the
toolkit has already seen fail is never printed.

Public names
------------
EdgeRadiusRemedy     the remedy offered: the case's edge radius and the largest
edge_radius_offer    the remedy of a case and its verdict, or why none is offered
with_edge_radius     the case with every blade's edge radius (and the rating's ρ_a0)
least_root_safety    the least S_F,FE of an analysis (torque, member)
RemedyJudgement      kept or not, and why
judged_remedy        the rule: root improved, no met criterion lost
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Sequence
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
import xarray as xr

from contact.study.verdicts import Finding, Verdict
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.synthesis.edge_radius import EdgeRadiusLimit

__all__ = ["ROOT_GAIN", "EdgeRadiusRemedy", "RemedyJudgement", "edge_radius_offer",
           "judged_remedy", "least_root_safety", "with_edge_radius"]

log = logging.getLogger(__name__)

#: [1] the least rise of the least S_F,FE for which the remedy counts as an improvement
#: (the development's :data:`contact.optimize.development_given_root.ROOT_GAIN`)
ROOT_GAIN = 0.005

#: [1] the least ratio of the largest edge radius to the case's for which it is offered
#: (:data:`contact.optimize.development_given_root.EDGE_GAIN`: a few per cent is within
#: the FE model's accuracy)
EDGE_GAIN = 1.05


@dataclass(frozen=True)
class EdgeRadiusRemedy:
    """The edge-radius remedy offered for a root below its minimum.

    Attributes
    ----------
    current : float — [mm] the case's edge radius (the smallest of its four blades')
    limit : EdgeRadiusLimit — the largest both members' blades allow, and each limit
    """

    current: float
    limit: EdgeRadiusLimit

    @property
    def radius(self) -> float:
        """[mm] the edge radius the remedy writes (:attr:`limit`'s radius)."""
        return float(self.limit.radius)

    def text(self) -> str:
        """The remedy in words: ``"edge radius 0.81 -> 0.97 mm (…)"``."""
        return (f"edge radius {self.current:.4g} -> {self.radius:.4g} mm on every blade (the "
                f"largest the point widths and the clearance allow; the {self.limit.binding} "
                "binds)")


def _case_edge_radius(case: Case) -> float:
    """[mm] the smallest edge radius of the case's four blades."""
    return min(float(case.member(m).flank(f).blade.edge_radius)
               for m in ("pinion", "gear") for f in ("concave", "convex"))


def _root_findings(findings: Sequence[Finding]) -> list[Finding]:
    """The ``root_stress`` findings that judge a stress (not the not-checked ones)."""
    return [f for f in findings if f.check == "root_stress" and "not checked" not in f.reason
            and not f.reason.startswith("root stress not computed")]


def edge_radius_offer(case: Case, verdict: Verdict) -> tuple[EdgeRadiusRemedy | None, str]:
    """The edge-radius remedy of a case whose analysis' verdict finds the root below its
    minimum, or why none is offered.

    Parameters
    ----------
    case : geometry.case.Case
        The analysed case; its ``[design]`` table gives the blank the largest edge radius
        is computed from (the generated normal pressure angles α_nD, α_nC, the synthesis'
        default blade angles).
    verdict : contact.study.verdicts.Verdict
        The analysis' verdict (:func:`contact.study.verdicts.verdict`).

    Returns
    -------
    (EdgeRadiusRemedy or None, str)
        The remedy and ``""``; or None and why none is offered: no ``root_stress``
        finding, a face-hobbed case, no ``[design]`` table, a slot that closes, or a
        largest edge radius not :data:`EDGE_GAIN` × the case's.

    Raises
    ------
    Nothing: a case the limit cannot be computed for is said in the reason.

    Notes
    -----
    Source: :func:`geometry.synthesis.edge_radius.largest_edge_radius` (AGMA 929-A06's
    form of the point-width and clearance limits); the rule of
    :func:`contact.optimize.development_given_root.larger_edge_radius`. Measured on the
    truck hypoid 8×47 (docs/own_gear_set.md, "The cutter edge radius as the root's lever").
    """
    if not _root_findings(verdict.findings):
        return None, "the verdict finds no root below its minimum"
    if case.pinion.blade_groups or case.gear.blade_groups:
        return None, ("the largest edge radius is that of a face-milled design; this case is "
                      "face-hobbed")
    from contact.load_capacity.design_table import design_blank, design_table
    from geometry.synthesis.edge_radius import largest_edge_radius

    try:
        blank = design_blank(design_table(case, "the largest edge radius needs the case's "
                                                "basic design data"))
        limit = largest_edge_radius(blank)
    except InputError as exc:
        return None, f"no largest edge radius: {exc}"
    current = _case_edge_radius(case)
    if not (current > 0.0 and limit.radius >= EDGE_GAIN * current):
        return None, (f"the case's edge radius {current:.4g} mm is within {EDGE_GAIN - 1:.0%} "
                      f"of the largest the point widths and the clearance allow, "
                      f"{limit.radius:.4g} mm ({limit.binding})")
    return EdgeRadiusRemedy(current, limit), ""


def with_edge_radius(case: Case, radius: float) -> Case:
    """The case with every blade's edge radius ``radius`` (both members, both flanks) and,
    where its ``[rating]`` table gives the tool's ρ_a0 (``edge_radius``), that too; named
    ``<name>_edge_radius``, its source saying the change.

    Parameters
    ----------
    case : geometry.case.Case
    radius : float — [mm] the new edge radius, in (0, 20]

    Returns
    -------
    geometry.case.Case
        The flanks' machine settings and the other blade data unchanged.

    Raises
    ------
    InputError
        ``radius`` not finite or outside (0, 20] mm, named ``edge_radius``.

    Notes
    -----
    Source: the case schema's blade table (``edge_radius``, ISO 10300-3's ρ_a0).
    """
    if not (math.isfinite(radius) and 0.0 < radius <= 20.0):
        raise InputError(f"edge_radius: must be finite and in (0, 20] mm, got {radius}")
    members = {}
    for m in ("pinion", "gear"):
        member = case.member(m)
        tools = {f: dataclasses.replace(
            member.flank(f), blade=dataclasses.replace(member.flank(f).blade,
                                                       edge_radius=float(radius)))
            for f in ("concave", "convex")}
        members[m] = dataclasses.replace(member, **tools)
    extra = dict(case.extra)
    rating = extra.get("rating")
    if isinstance(rating, dict | MappingProxyType) and "edge_radius" in rating:
        extra["rating"] = {**rating, "edge_radius": [float(radius), float(radius)]}
    was = _case_edge_radius(case)
    return dataclasses.replace(
        case, name=f"{case.name}_edge_radius",
        source=(f"{case.source}; every blade's edge radius {was:.4g} -> {radius:.4g} mm by "
                "ltca run --apply-remedy (contact.study.edge_radius_remedy)"),
        pinion=members["pinion"], gear=members["gear"], extra=MappingProxyType(extra))


def least_root_safety(tree: xr.DataTree) -> tuple[float, str]:
    """The least FE root safety S_F,FE of an analysis over its torques and members.

    Parameters
    ----------
    tree : xarray.DataTree
        An analysis with ``/ltca/root_stress_max`` (torque, member) [MPa] and an ISO 10300
        ``/rating`` at the same torques.

    Returns
    -------
    (float, str)
        [1] S_F,FE = σ_FP / (σ_FE,max K_A K_v) at its least and where (``"gear at 1765 N
        m"``); NaN and ``""`` where the tree has no root stress or no ISO 10300 rating.

    Notes
    -----
    Source: :func:`contact.study.verdict_checks.root_stress_safety` (ISO 10300-3:2014,
    Method B1, with the FE peak root stress).
    """
    from contact.study.verdict_checks import has_iso_rating, member_names, root_stress_safety

    if "ltca" not in tree.children or "rating" not in tree.children:
        return math.nan, ""
    lt, rt = tree["ltca"].to_dataset(), tree["rating"].to_dataset()
    if "root_stress_max" not in lt or not has_iso_rating(rt):
        return math.nan, ""
    rs = lt["root_stress_max"].transpose("torque", "member")
    if not np.array_equal(rt["torque"].values, rs["torque"].values):
        return math.nan, ""
    sf = root_stress_safety(np.asarray(rs.values, float), rt)
    if not np.isfinite(sf).any():
        return math.nan, ""
    i, j = np.unravel_index(np.nanargmin(sf), sf.shape)
    where = f"{member_names(rs)[j]} at {float(rs['torque'].values[i]):g} N m"
    return float(sf[i, j]), where


@dataclass(frozen=True)
class RemedyJudgement:
    """Whether a remedy applied is kept, and why.

    Attributes
    ----------
    kept : bool
    reason : str — one sentence: the root's S_F,FE before and after, what was lost
    lost : tuple of str — the checks the case met (or only drew attention on) that the
        remedied case fails or no longer makes
    """

    kept: bool
    reason: str
    lost: tuple[str, ...] = ()


def _worst(verdict: Verdict) -> dict[str, str]:
    """Each check's worst severity (``"pass"`` for a check made without a finding)."""
    from contact.study.verdicts import SEVERITIES

    out = dict.fromkeys(verdict.checks, "pass")
    for f in verdict.findings:
        now = out.get(f.check, "pass")
        out[f.check] = max(now, f.severity, key=SEVERITIES.index)
    return out


def judged_remedy(before: Verdict, after: Verdict, safety_before: float,
                  safety_after: float) -> RemedyJudgement:
    """The rule of ``--apply-remedy``: the remedied case is kept only where its least
    root safety rises by :data:`ROOT_GAIN` and no criterion is lost.

    Parameters
    ----------
    before, after : contact.study.verdicts.Verdict
        The verdicts of the case as given and of the remedied case (same torques,
        misalignment and options).
    safety_before, safety_after : float — [1] their least S_F,FE
        (:func:`least_root_safety`); NaN where not computed

    Returns
    -------
    RemedyJudgement
        Not kept where either safety is NaN, the rise is below :data:`ROOT_GAIN`, or a
        check other than ``root_stress`` is worse after: a check met (no finding) that
        has a finding after, one that drew attention that fails after, or one made before
        and not after (a criterion lost, named in :attr:`RemedyJudgement.lost`).

    Notes
    -----
    Source: issue 71 item 3 ("never print a command whose result it has already seen
    fail"); the keep rule of :func:`contact.optimize.development_given_root.
    checked_edge_radius` (no target the written design met lost, S_F,FE higher by
    ROOT_GAIN).
    """
    from contact.study.verdicts import SEVERITIES

    was, now = _worst(before), _worst(after)
    lost = tuple(c for c, s in was.items() if c != "root_stress" and (
        c not in now or SEVERITIES.index(now[c]) > SEVERITIES.index(s)))
    root = f"least S_F,FE {safety_before:.3f} -> {safety_after:.3f}"
    if not (math.isfinite(safety_before) and math.isfinite(safety_after)):
        return RemedyJudgement(False, f"not kept: the root safety was not computed ({root})",
                               lost)
    if safety_after < safety_before + ROOT_GAIN:
        return RemedyJudgement(False, f"not kept: the root does not improve ({root}, a rise "
                                      f"of {ROOT_GAIN:g} at least asked)", lost)
    if lost:
        return RemedyJudgement(False, f"not kept: the root improves ({root}) but "
                                      f"{', '.join(lost)} {'is' if len(lost) == 1 else 'are'} "
                                      "worse than the case as given", lost)
    still = _root_findings(after.findings)
    return RemedyJudgement(True, f"kept: the root improves ({root}) and no criterion the case "
                                 "met is lost" + (
                                     "; the root is still below its minimum "
                                     f"({', '.join(sorted({f.severity for f in still}))}): the "
                                     "edge radius alone does not hold these torques"
                                     if still else ""))
