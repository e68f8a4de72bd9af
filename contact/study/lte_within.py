"""The torque up to which an LTE peak-to-peak keeps the verdict's limit, from its values at
a few torques, and the words that state it (issue 71: ``ltca synthesize``'s deflection note
and ``ltca run``'s ``lte`` finding say it with one function).

The LTE p-p of a localised bearing is no smooth function of the torque (on the ratio-1
spiral bevel 16x16 at Σ 60° it stays at 45-47 µrad up to 281 N m and jumps to 111 µrad at
465 N m), so the crossing is linear between the torques analysed and only as close as
they are: both texts name the torques and the LTE at each.

Public names
------------
within_torque, within_text
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from geometry.core.text import plain_number

__all__ = ["within_text", "within_torque"]


def within_torque(torques: Sequence[float], lte: Sequence[float], limit: float) -> float:
    """The largest torque up to which an LTE p-p keeps a limit, from its values at a few
    torques.

    Parameters
    ----------
    torques : sequence of float, shape (n,) — [N·m]
        Ascending torques.
    lte : sequence of float, shape (n,) — [µrad]
        The LTE peak-to-peak at each.
    limit : float — [µrad]

    Returns
    -------
    float — [N·m]
        The first torque's crossing of ``limit`` from below, linear between the two torques
        that bracket it; the last torque where the LTE keeps the limit at each; NaN where it
        exceeds the limit at the first torque already, or a value is not finite.

    Raises
    ------
    ValueError
        ``torques`` and ``lte`` of different lengths, or empty.

    Notes
    -----
    Linear interpolation between analysed torques (the LTE p-p of a localised bearing is
    no smooth function of the torque: on the 16x16 at Σ 60° it stays at 45-47 µrad up to
    281 N m and jumps to 111 at 465 N m, so the crossing is only as close as the torques
    analysed: :data:`contact.ltca.lte_range.LTE_TORQUES`, which ``ltca run`` and ``ltca
    synthesize`` both analyse). Source: issue
    71, docs/own_gear_set.md ("The 16×16 at Σ 60° and its β_m 43.5° remedy").
    """
    t = np.asarray(torques, float)
    y = np.asarray(lte, float)
    if t.shape != y.shape or t.size == 0:
        raise ValueError(f"within_torque: {t.size} torques and {y.size} LTE values")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(y))) or y[0] > limit:
        return math.nan
    above = np.flatnonzero(y > limit)
    if above.size == 0:
        return float(t[-1])
    i = int(above[0])
    return float(t[i - 1] + (limit - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]))


def within_text(torques: Sequence[float], lte: Sequence[float], limit: float,
                design: float = math.nan, *, urad: str = "µrad", nm: str = "N·m"
                ) -> str | None:
    """The words "within <limit> up to about <torque> (<share> % of the design torque;
    LTE p-p … at …)" of an LTE p-p that exceeds ``limit`` at its last torque.

    Parameters
    ----------
    torques : sequence of float, shape (n,) — [N·m]
        Ascending torques, n ≥ 2.
    lte : sequence of float, shape (n,) — [µrad]
        The LTE peak-to-peak at each.
    limit : float — [µrad]
        The verdict's limit (:data:`contact.study.verdicts.LTE_LIMIT`).
    design : float, optional — [N·m]
        The design torque the share is of (default NaN: no share said).
    urad, nm : str
        The units' words (``ltca synthesize``'s notes are ASCII: ``"urad"``, ``"N m"``).

    Returns
    -------
    str or None
        None where fewer than two torques are given, the LTE keeps ``limit`` at the last
        torque, or exceeds it at the first already (:func:`within_torque` NaN): no torque
        to name.

    Raises
    ------
    ValueError
        ``torques`` and ``lte`` of different lengths, or empty (:func:`within_torque`).

    Notes
    -----
    :func:`within_torque`, linear between the torques given; the text names them and the
    LTE at each, so that the reader sees how close they bracket the crossing.
    """
    within = within_torque(torques, lte, limit)
    if len(torques) < 2 or not math.isfinite(within) or not float(lte[-1]) > limit:
        return None
    shown = " / ".join(f"{x:.0f}" for x in lte)
    at = " / ".join(plain_number(t) for t in torques)
    share = (f"{100 * within / design:.0f} % of the design torque; "
             if math.isfinite(design) and design > 0.0 else "")
    return (f"within {limit:g} {urad} up to about {plain_number(within)} {nm} ({share}LTE p-p "
            f"{shown} {urad} at {at} {nm})")
