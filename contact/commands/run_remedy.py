"""``ltca run``'s root remedy: the cutter edge radius offered under the verdict, and
applied, checked and judged by ``ltca run --apply-remedy`` (issue 71, branch remedy84;
:mod:`contact.study.edge_radius_remedy`).

Public names
------------
remedy_lines   the lines under the verdict offering the edge radius (the command to paste)
apply_remedy   the case with the edge radius analysed again, compared and judged
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # every module of contact.commands is imported by `ltca --help`: no
    # numerical library at import (tests/test_startup.py)
    import xarray as xr

    from geometry.case import Case

__all__ = ["AppliedRemedy", "apply_remedy", "remedy_lines"]

#: how many of the remedied case's findings ``--apply-remedy`` prints (as the verdict's
#: short form, :data:`contact.commands.run.VERDICT_LINES`)
FINDINGS_SHOWN = 8

#: what ``--apply-remedy`` is in the lines that offer it
APPLY_WORDS = ("--apply-remedy analyses the case with it and keeps it only where the "
               "root improves and no criterion the case met is lost (docs/verdicts.md)")


def remedy_lines(case: Case, verdict, shown: str, side: str, torques: str) -> list[str]:
    """The lines under the verdict that offer the edge radius where the root is below its
    minimum (:func:`contact.study.edge_radius_remedy.edge_radius_offer`), with the command
    that applies it; none where no remedy is offered.

    Parameters
    ----------
    case : geometry.case.Case
    verdict : contact.study.verdicts.Verdict
    shown : str — the CASE argument as the user gave it (or the case's name)
    side : str — ``"drive"`` or ``"coast"``
    torques : str — the run's torques [N·m] as the command takes them

    Returns
    -------
    list of str
        A sentence (two-space indent) and the command (four-space indent, to paste).
    """
    from contact.study.edge_radius_remedy import edge_radius_offer

    remedy, _ = edge_radius_offer(case, verdict)
    if remedy is None:
        return []
    return [f"  next, the root: {remedy.text()}; {APPLY_WORDS}:",
            f"    ltca run {shown} --flank {side} --torque {torques} --apply-remedy"]


@dataclass(frozen=True)
class AppliedRemedy:
    """What ``--apply-remedy`` did.

    Attributes
    ----------
    lines : list of str — what ``ltca run`` prints
    case : Case or None — the remedied case (None where no remedy was applied)
    tree : xarray.DataTree or None — its analysis
    kept : bool — whether the remedy is kept (:func:`contact.study.edge_radius_remedy.
        judged_remedy`)
    """

    lines: list[str]
    case: Case | None = None
    tree: xr.DataTree | None = None
    kept: bool = False


def _rows(tree: xr.DataTree) -> dict[tuple[float, str], tuple[float, float]]:
    """(torque, member) → (σ_FE,max [MPa], S_F,FE [1]) of an analysis."""
    import numpy as np

    from contact.study.verdict_checks import has_iso_rating, member_names, root_stress_safety

    lt = tree["ltca"].to_dataset()
    if "root_stress_max" not in lt:
        return {}
    rs = lt["root_stress_max"].transpose("torque", "member")
    values = np.asarray(rs.values, float)
    rt = tree["rating"].to_dataset() if "rating" in tree.children else None
    sf = (root_stress_safety(values, rt) if has_iso_rating(rt)
          and np.array_equal(rt["torque"].values, rs["torque"].values)
          else np.full(values.shape, np.nan))
    return {(float(t), m): (float(values[i, j]), float(sf[i, j]))
            for i, t in enumerate(rs["torque"].values) for j, m in enumerate(member_names(rs))}


def _comparison(before: xr.DataTree, after: xr.DataTree) -> list[str]:
    """Per torque and member the FE root stress and S_F,FE as given and remedied, and per
    torque the LTE p-p and the flank peak pressure (what else the edge radius moves)."""
    nan = float("nan")
    old, new = _rows(before), _rows(after)
    out = ["  FE root stress [MPa] and S_F,FE, as given -> with the edge radius:"]
    for (t, m), (s0, f0) in old.items():
        s1, f1 = new.get((t, m), (nan, nan))
        out.append(f"    {m} at {t:g} N m: {s0:.0f} -> {s1:.0f} MPa ({100 * (s1 / s0 - 1):+.1f} "
                   f"%), S_F,FE {f0:.3f} -> {f1:.3f}")
    lt0, lt1 = before["ltca"], after["ltca"]
    for i, t in enumerate(lt0["torque"].values):
        out.append(f"    at {t:g} N m: LTE p-p {float(lt0['lte_peak_to_peak'][i]):.1f} -> "
                   f"{float(lt1['lte_peak_to_peak'][i]):.1f} urad, flank p_max "
                   f"{float(lt0['pressure_max_flank'][i]):.0f} -> "
                   f"{float(lt1['pressure_max_flank'][i]):.0f} MPa")
    return out


def apply_remedy(case: Case, tree: xr.DataTree,
                 analyse: Callable[[Case], xr.DataTree]) -> AppliedRemedy:
    """``ltca run --apply-remedy``: the case with the edge radius the verdict's remedy
    offers, analysed as the case was, compared and judged.

    Parameters
    ----------
    case : geometry.case.Case — the case as given
    tree : xarray.DataTree — its analysis (``ltca run``'s)
    analyse : callable Case → DataTree
        The same analysis (torques, misalignment, options, chain) of another case.

    Returns
    -------
    AppliedRemedy
        Where no remedy is offered, the line saying why and nothing applied; else the
        comparison (root stress and S_F,FE per torque and member, LTE and flank peak per
        torque), both verdicts' heads and the judgement
        (:func:`contact.study.edge_radius_remedy.judged_remedy`).

    Raises
    ------
    Whatever the analysis of the remedied case raises (the caller's file of the case as
    given is written first).
    """
    from contact.study.edge_radius_remedy import (
        edge_radius_offer,
        judged_remedy,
        least_root_safety,
        with_edge_radius,
    )
    from contact.study.verdicts import verdict

    before = verdict(tree)
    remedy, why = edge_radius_offer(case, before)
    if remedy is None:
        return AppliedRemedy([f"--apply-remedy: no remedy applied: {why}"])
    remedied = with_edge_radius(case, remedy.radius)
    out = analyse(remedied)
    after = verdict(out)
    judged = judged_remedy(before, after, least_root_safety(tree)[0],
                           least_root_safety(out)[0])
    lines = [f"--apply-remedy: {remedy.text()}, the same analysis of the case with it:"]
    lines += _comparison(tree, out)
    lines.append(f"  verdict as given: {before.lines()[0].split(': ', 1)[1]}; with the edge "
                 f"radius: {after.lines()[0].split(': ', 1)[1]}")
    shown = [f for f in after.findings if judged.kept or f.check in judged.lost]
    lines += [f"    {f.severity}: {f.reason}" for f in shown[:FINDINGS_SHOWN]]
    if len(shown) > FINDINGS_SHOWN:
        lines.append(f"    … and {len(shown) - FINDINGS_SHOWN} more (`ltca report` of the "
                     "remedied file lists them all)")
    lines.append(f"  the edge radius {judged.reason}")
    return AppliedRemedy(lines, remedied, out, judged.kept)
