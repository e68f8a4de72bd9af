"""``ltca synthesize``'s lines on the written LTE of each flank: at the light and the
design torque and the largest between them, as ``ltca run``'s verdict judges it (issue 71:
"LTE p-p ≤ 60 µrad at every torque").

The development's summary gave each flank's LTE p-p at its two torques alone; a coast flank
at 59 / 53 µrad there was 69 µrad between them (the face-hobbed spiral bevel 25x31 of m_et
9.52 mm of benchmarks/data/unseen_designs, round 21b), which only ``ltca run --flank
coast`` said. :func:`flank_lte_line` states a flank's three numbers against the verdict's
limit and the development's target; :func:`lte_lines` the lines of a development whose
flank misses one of them.

Public names
------------
flank_lte_line, inside, lte_lines
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from geometry.core.text import plain_number

__all__ = ["flank_lte_line", "inside", "lte_lines"]


def flank_lte_line(flank: str, torques: tuple[float, float], ends: tuple[float, float],
                   between: Mapping[str, Any] | None, limit: float, target: float,
                   floor: float = math.nan, hollow: str = "") -> str | None:
    """One flank's written LTE p-p in words, where it misses the development's target or
    the verdict's limit at a torque or between its torques.

    Parameters
    ----------
    flank : str
        ``"drive"`` or ``"coast"``.
    torques : (float, float) — [N·m]
        The flank's light and design torque.
    ends : (float, float) — [µrad]
        Its LTE p-p at them.
    between : mapping or None
        Its largest LTE at ``ltca run``'s ``lte_range`` torques between the two:
        ``"peak"`` [µrad] and ``"at"`` [N·m] (:func:`inside` of a record); None (or a peak
        not finite) where not judged between the torques.
    limit : float — [µrad]
        The verdict's LTE limit (:data:`contact.study.verdicts.LTE_LIMIT`).
    target : float — [µrad]
        The development's LTE target (``max_lte``).
    floor : float, optional — [µrad]
        The flank's load-sharing floor between its two torques
        (:func:`contact.optimize.development_lte_floor.te_floor`); where finite and the
        target is missed at the two torques within the verdict's limit, the line says it
        against the target (:func:`~contact.optimize.development_lte_floor.floor_text`).
        NaN (default): not said.
    hollow : str, optional
        What limits a hollow profile on the written bearing
        (:func:`~contact.optimize.development_hollow_limit.hollow_text`), appended after
        the floor where the target is missed within the verdict's limit; "" (default):
        not said.

    Returns
    -------
    str or None
        E.g. "coast LTE p-p 59/53 urad at 567/3780 N m (light/design), 69.4 urad at 1638 N
        m between them: above the verdict's limit 60 urad between the torques (ltca run
        --flank coast finds it there)"; None where every value is within ``target`` and
        ``limit`` (or none is finite).

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: ``ltca run``'s ``lte_range`` step and verdict (:mod:`contact.ltca.lte_range`,
    issue 71); the development's target, docs/synthesis.md ("Development bearing").
    """
    light, design = (float(x) for x in ends)
    peak = float(between.get("peak", math.nan)) if between else math.nan
    at = float(between.get("at", math.nan)) if between else math.nan
    known = [x for x in (light, design, peak) if math.isfinite(x)]
    if not known or max(known) <= min(float(target), float(limit)):
        return None
    line = (f"{flank} LTE p-p {light:.0f}/{design:.0f} urad at {plain_number(torques[0])}/"
            f"{plain_number(torques[1])} N m (light/design)")
    line += (f", {peak:.1f} urad at {plain_number(at)} N m between them"
             if math.isfinite(peak) and math.isfinite(at) else ", not judged between them")
    run = "ltca run" + (" --flank coast" if flank == "coast" else "")
    if max(light, design) > limit:
        where = " at its torques" + (" and between them" if peak > limit else "")
        return line + f": above the verdict's limit {limit:g} urad{where} ({run} finds it)"
    if math.isfinite(peak) and peak > limit:
        return (line + f": above the verdict's limit {limit:g} urad between the torques "
                f"({run} finds it there)")
    if max(light, design) <= float(target):
        # met where the development judges its target (its two torques), above it only
        # between them: said so, or "every target met" above reads as contradicted
        # (round 24's 14x39 FH and 17x41 at Sigma 75 deg)
        return line + (f": within the verdict's limit {limit:g} urad; above the development's "
                       f"target {float(target):g} urad between the torques only (the "
                       "development judges it at the light and design torques: met there)")
    from contact.optimize.development_lte_floor import floor_text

    return (line + f": within the verdict's limit {limit:g} urad, the development's target "
            f"{float(target):g} urad missed" + floor_text(floor, target) + hollow)


def inside(record: Mapping[str, Any] | None) -> dict[str, float] | None:
    """The largest LTE p-p of a record of the LTE over the range at its torques strictly
    between the first and the last (the light and the design torque).

    Parameters
    ----------
    record : mapping or None
        ``"torques"`` [N·m] and ``"lte"`` [µrad], ascending
        (:func:`~contact.optimize.development_range_lte.range_record`'s); a mapping with
        ``"peak"`` and ``"at"`` alone is returned as it is (already the torques between).

    Returns
    -------
    dict or None
        ``{"peak": µrad, "at": N·m}``; None where ``record`` is None or has no finite
        value between its ends.

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: ``ltca run``'s ``lte_range`` line, which states the torques between (issue 71).
    """
    if not record:
        return None
    if "lte" not in record or "torques" not in record:
        return dict(record)
    pairs = [(float(y), float(t)) for t, y in zip(list(record["torques"])[1:-1],
                                                  list(record["lte"])[1:-1], strict=True)
             if math.isfinite(float(y))]
    if not pairs:
        return None
    peak, at = max(pairs)
    return {"peak": peak, "at": at}


def lte_lines(development: Any, drive_between: Mapping[str, Any] | None = None,
              coast_between: Mapping[str, Any] | None = None,
              drive_floor: float = math.nan, drive_hollow: str = "") -> list[str]:
    """:func:`flank_lte_line` of a development's written drive and (where checked) coast
    flank.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
        Its ``best`` and ``coast`` metrics (``lte_peak_to_peak`` [µrad]), ``torque`` and
        ``coast_design_torques`` [N·m], ``targets.max_lte`` [µrad], and its records of the
        LTE over the range (``lte_range``, ``coast_lte_range``).
    drive_between, coast_between : mapping, optional
        The flank's LTE over the range where the development holds no record of it (the
        written case analysed, :func:`~contact.optimize.development_deflection.analysed`):
        ``"peak"`` [µrad], ``"at"`` [N·m].
    drive_floor : float, optional — [µrad]
        The written drive flank's load-sharing floor (:func:`flank_lte_line`'s ``floor``;
        NaN: not said).
    drive_hollow : str, optional
        What limits a hollow profile on the written drive bearing (:func:`flank_lte_line`'s
        ``hollow``; "": not said).

    Returns
    -------
    list of str
        The lines of the flanks that miss the target or the limit (none where both keep
        them).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: issue 71 ("LTE p-p ≤ 60 µrad at every torque", both flanks).
    """
    from contact.study.verdicts import LTE_LIMIT

    target = float(development.targets.max_lte)
    lte = development.best.metrics["lte_peak_to_peak"]
    lines = [flank_lte_line("drive", tuple(development.torque), (lte[0], lte[-1]),
                            inside(development.lte_range or drive_between), LTE_LIMIT,
                            target, drive_floor, drive_hollow)]
    if development.coast is not None:
        c = development.coast["lte_peak_to_peak"]
        lines.append(flank_lte_line(
            "coast", tuple(development.coast_design_torques), (c[0], c[-1]),
            inside(getattr(development, "coast_lte_range", None) or coast_between),
            LTE_LIMIT, target))
    return [s for s in lines if s is not None]
