"""The edge-peak steps' light-torque rule (issue 71, Done-when "no edge contact at 15 % of
the design torque"): a relief kept for an edge's peak at the design torque must not bring
edge contact at the light torque where the design it starts from had none.

The check's targets read the light torque's pattern clearance to the grid's rows but not
its edge load; the coast edge-peak step of the face-hobbed 13×30 at Σ 115° kept the relief
start 0.5 → 0.4 for the gear tip at 272.1 N·m and wrote 519 MPa on an edge at 40.8 N·m
(its edge share there below :data:`~contact.study.verdicts.EDGE_SHARE_MIN`, the design it
started from with none: docs/synthesis.md, "The coast search's budget").
:func:`light_edge_lost` refuses such a variant on ``ltca run``'s own two readings of the
light torque (:func:`~contact.optimize.development_evaluate.light_edge_metrics`).
"""

from __future__ import annotations

import numpy as np

from contact.optimize.development_result import DevelopmentEvaluation

__all__ = ["LIGHT_EDGE", "light_edge", "light_edge_lost"]

#: the lost target's name in the steps' refusal lines
LIGHT_EDGE = "edge contact at the light torque"


def light_edge(e: DevelopmentEvaluation) -> tuple[float, float] | None:
    """The edge contact of ``e`` at its check's light torque (the first).

    Parameters
    ----------
    e : DevelopmentEvaluation
        A checked design (its metrics per torque, light first).

    Returns
    -------
    tuple (float, float) or None
        ``(pressure_max_edge [MPa], edge_contact_share [1])`` at the light torque, NaN
        for one the metrics lack; None where they carry neither (not analysed so).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s table column ``p_max edge`` and its verdict's ``edge_contact``
    check (:func:`contact.study.verdicts.edge_contact_share`).
    """
    m = e.metrics or {}
    got = [float(np.asarray(m[k], float)[0]) if k in m else np.nan
           for k in ("pressure_max_edge", "edge_contact_share")]
    return None if all(np.isnan(got)) else (got[0], got[1])


def light_edge_lost(start: DevelopmentEvaluation, e: DevelopmentEvaluation) -> list[str]:
    """``[<LIGHT_EDGE> (p_max edge <p> MPa, edge share <s> %)]`` where the variant ``e``
    loads an edge at the light torque (``p_max edge`` above 0 or an edge share the verdict
    counts) and ``start``, the design it would replace, loads none there; else ``[]``.

    Parameters
    ----------
    start, e : DevelopmentEvaluation
        The design kept so far and its variant, both checked at the same torques [N·m]
        (light first).

    Returns
    -------
    list of str

    Raises
    ------
    Nothing: a design without the readings (:func:`light_edge` None) is not judged.

    Notes
    -----
    Any edge load counts, not only a share at least
    :data:`~contact.study.verdicts.EDGE_SHARE_MIN`: the issue reads the light torque's
    ``p_max edge`` (519 MPa on the 13×30 at a share below that floor). Source: issue 71.
    """
    was, new = light_edge(start), light_edge(e)
    if was is None or new is None:
        return []

    def loaded(r: tuple[float, float]) -> bool:
        return bool(np.nan_to_num(r[0]) > 0.0 or np.nan_to_num(r[1]) > 0.0)

    if loaded(was) or not loaded(new):
        return []
    return [f"{LIGHT_EDGE} (p_max edge {np.nan_to_num(new[0]):.0f} MPa, edge share "
            f"{100.0 * np.nan_to_num(new[1]):.2g} %)"]
