"""The remedied design's verdict against the design as given's, before ``ltca synthesize
--apply-remedy`` writes it (issue 71, "the printed remedy is honest", branch remedy99).

``--apply-remedy`` (:mod:`contact.optimize.development_remedy`) develops the design as given
and the remedied basic data, and writes the remedied development. Its rules so far judged
the remedy on its LTE (the next remedy's, :mod:`contact.optimize.development_remedy_next`)
and its design torque (:func:`~contact.optimize.development_remedy.torque_given_up`); a
remedy whose written case ``ltca run`` judges worse on another of its checks was written
all the same (round 34's 5×48: a FAIL where the design as given passed). Here both
developments' written designs, drive and coast flank, are judged on the findings of
``ltca run``'s verdict (:mod:`contact.study.verdicts`) that the development has measured
at ``ltca run``'s sampling (its check's analysis of the written design at the light and
the design torque, and its record of the LTE between them): no analysis is added.

* :func:`flank_findings` — one flank's findings: ``implausible`` (FAIL: an LTE spread or a
  plastic share beyond :mod:`contact.ltca.plausibility`'s limits, as
  :func:`contact.optimize.development_process.failed_outcome` reads them), ``lte``
  (ATTENTION above the limit, FAIL beyond :data:`~contact.study.verdicts.LTE_FAIL_FACTOR`
  × it), ``plastic_edges`` (ATTENTION: a plastic share up to the plausibility limit) and
  ``light_edge`` (ATTENTION: edge contact the verdict counts at the light torque);
* :func:`verdict_worse` — the findings of the remedied design more severe than the design
  as given's on the same flank and check, in words; empty where none is.

Not judged here, as the development does not measure them: the ``/rating``, scuffing and
micropitting checks of ``ltca run`` (the ISO 10300 rating at the written design torque)
and the flank and edge pressure against the static strength. The remedied rating's own
rule is the design torque's (:func:`~contact.optimize.development_remedy.torque_given_up`).

Public names
------------
SEVERITY_RANK, Finding, flank_findings, developed_findings, verdict_worse
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, NamedTuple

import numpy as np

from geometry.core.text import plain_number

__all__ = ["SEVERITY_RANK", "Finding", "developed_findings", "flank_findings",
           "verdict_worse"]

#: the verdict's severities in order (:data:`contact.study.verdicts.SEVERITIES`)
SEVERITY_RANK = {"pass": 0, "attention": 1, "fail": 2}


class Finding(NamedTuple):
    """One finding of ``ltca run``'s verdict read on a development's measurements.

    Attributes
    ----------
    check : str
        ``"implausible"``, ``"lte"``, ``"plastic_edges"`` or ``"light_edge"``.
    severity : str
        ``"attention"`` or ``"fail"``.
    text : str
        The reading in words, with its numbers and torques.
    """

    check: str
    severity: str
    text: str


def _values(metrics: Mapping[str, Any], name: str) -> np.ndarray | None:
    if name not in metrics:
        return None
    return np.atleast_1d(np.asarray(metrics[name], float))


def _at(torques: tuple[float, ...], k: int) -> str:
    return f" at {plain_number(torques[k])} N m" if k < len(torques) else ""


def _lte_finding(metrics: Mapping[str, Any], torques: tuple[float, ...],
                 between: Mapping[str, Any] | None, limit: float) -> Finding | None:
    """The ``lte`` finding: the worst LTE p-p at the two torques (and between them where
    ``between`` records it) above ``limit``."""
    from contact.study.verdicts import LTE_FAIL_FACTOR

    pp = _values(metrics, "lte_peak_to_peak")
    readings = [] if pp is None else [(float(v), _at(torques, k)) for k, v in enumerate(pp)]
    if between is not None:
        readings += [(float(v), f" at {plain_number(float(t))} N m")
                     for t, v in zip(between.get("torques", ()), between.get("lte", ()),
                                     strict=False)]
    readings = [r for r in readings if math.isfinite(r[0])]
    if not readings:
        return None
    worst, where = max(readings, key=lambda r: r[0])
    if worst <= limit:
        return None
    severity = "fail" if worst > LTE_FAIL_FACTOR * limit else "attention"
    return Finding("lte", severity, f"LTE p-p {worst:.1f} urad{where} (limit {limit:g}"
                   + (f", FAIL beyond {LTE_FAIL_FACTOR * limit:g})" if severity == "fail"
                      else ")"))


def _light_edge(metrics: Mapping[str, Any], torques: tuple[float, ...]) -> Finding | None:
    """The ``edge_contact`` finding at the light torque: the counted edge share
    (``edge_contact_share``, :func:`contact.study.verdicts.edge_contact_share`), else the
    edges' load share at least :data:`~contact.ltca.plausibility.EDGE_SHARE_MIN`."""
    from contact.ltca.plausibility import EDGE_SHARE_MIN

    share = _values(metrics, "edge_contact_share")
    if share is None:
        share = _values(metrics, "edge_load_share")
    if share is None or share.size == 0:
        return None
    light = float(np.nan_to_num(share[0]))
    if light < EDGE_SHARE_MIN:
        return None
    return Finding("light_edge", "attention",
                   f"edge contact {100.0 * light:.2g} % of the torque at the light "
                   f"torque{_at(torques, 0)}")


def _plastic(metrics: Mapping[str, Any], torques: tuple[float, ...]) -> Finding | None:
    """The ``plastic_edges`` finding: a plastic share above 0 up to the plausibility
    limit (beyond it: ``implausible``)."""
    from contact.ltca.plausibility import PLASTIC_SHARE_LIMIT

    share = _values(metrics, "plastic_share")
    if share is None:
        return None
    found = [(float(v), k) for k, v in enumerate(share)
             if math.isfinite(v) and 0.0 < v <= PLASTIC_SHARE_LIMIT]
    if not found:
        return None
    v, k = max(found)
    return Finding("plastic_edges", "attention",
                   f"plastic share {100.0 * v:.2g} %{_at(torques, k)} (ATTENTION up to "
                   f"{100.0 * PLASTIC_SHARE_LIMIT:g} %)")


def flank_findings(metrics: Mapping[str, Any] | None, torques: tuple[float, ...],
                   limit: float, between: Mapping[str, Any] | None = None
                   ) -> dict[str, Finding]:
    """One flank's findings of ``ltca run``'s verdict, read on a development's
    measurements of its written design.

    Parameters
    ----------
    metrics : dict name → ndarray (2,) or None
        The design's metrics at (light, design) torque
        (:data:`~contact.optimize.development_targets.METRIC_NAMES`, and
        ``edge_contact_share`` where the analysis recorded it); None: not measured.
    torques : tuple of float — [N·m]
        The (light, design) torque of ``metrics``.
    limit : float — [µrad]
        The verdict's LTE limit (:data:`~contact.study.verdicts.LTE_LIMIT`).
    between : dict, optional
        The development's record of the LTE p-p between the torques (``"torques"`` [N·m],
        ``"lte"`` [µrad]: :attr:`~contact.optimize.development_result.DevelopmentResult.
        lte_range`); None: the two torques alone.

    Returns
    -------
    dict check → Finding
        The finding of each check that has one (``implausible``, ``lte``,
        ``plastic_edges``, ``light_edge``); empty where none has, or ``metrics`` is None.

    Raises
    ------
    Nothing: a reading the metrics lack is no finding.

    Notes
    -----
    Source: :mod:`contact.study.verdicts` (its ``implausible``, ``lte``,
    ``plastic_edges`` and ``edge_contact`` checks and limits) and
    :func:`contact.optimize.development_process.failed_outcome`'s reading of the
    plausibility FAILs on a development's metrics (a quiet transfer's LTE spread no FAIL).
    """
    from contact.optimize.development_process import flank_fails

    if metrics is None:
        return {}
    out: dict[str, Finding] = {}
    fails = flank_fails(metrics, tuple(torques), "")
    if fails:
        out["implausible"] = Finding("implausible", "fail",
                                     "; ".join(f.strip() for f in fails))
    for found in (_lte_finding(metrics, tuple(torques), between, limit),
                  _plastic(metrics, tuple(torques)), _light_edge(metrics, tuple(torques))):
        if found is not None:
            out[found.check] = found
    return out


def developed_findings(result: Any, limit: float, between: tuple[bool, bool] = (True, True)
                       ) -> dict[str, dict[str, Finding]]:
    """Both flanks' findings of a development's written design (:func:`flank_findings`).

    Parameters
    ----------
    result : contact.optimize.development_result.DevelopmentResult
        Its ``best.metrics`` at ``torque`` (drive), ``coast`` at ``coast_design_torques``,
        and the records ``lte_range``, ``coast_lte_range``.
    limit : float — [µrad]
        The verdict's LTE limit.
    between : (bool, bool), optional
        Whether the drive's and the coast's record of the LTE between the torques is read
        (:func:`verdict_worse` reads it only where both developments have one).

    Returns
    -------
    dict flank → dict check → Finding
        Keys ``"drive"`` and ``"coast"`` (empty where the coast flank was not measured).
    """
    drive = flank_findings(getattr(result.best, "metrics", None), tuple(result.torque),
                           limit, result.lte_range if between[0] else None)
    coast = flank_findings(getattr(result, "coast", None),
                           tuple(result.coast_design_torques), limit,
                           result.coast_lte_range if between[1] else None)
    return {"drive": drive, "coast": coast}


def verdict_worse(given: Any, remedied: Any, limit: float) -> str:
    """The findings of the remedied design's ``ltca run`` verdict more severe than the
    design as given's, flank by flank and check by check, in words; empty where none is.

    Parameters
    ----------
    given, remedied : contact.optimize.development_result.DevelopmentResult
        The developments of the basic data as given and of the remedied basic data.
    limit : float — [µrad]
        The verdict's LTE limit.

    Returns
    -------
    str
        E.g. "its coast flank: plastic share 0.8 % at 445.5 N m (ATTENTION up to 5 %),
        where the design as given's has none"; a flank one of the two developments did not
        measure (its coast metrics None) is not judged.

    Raises
    ------
    Nothing.

    Notes
    -----
    "Worse" is the verdict's own order (pass < attention < fail, :data:`SEVERITY_RANK`) on
    the same check of the same flank: a remedied LTE of 45 µrad where the design as given
    read 93 is no finding; a remedy that is a trial for an LTE above the limit (the
    design as given's ATTENTION) is worse only where its own LTE FAILs. The LTE between
    the torques is read only where both developments recorded it on that flank, so both
    are judged on the same readings. Each development's metrics are its check's analysis
    of the written design at ``ltca run``'s sampling: the CPU added is the reading alone
    (below a millisecond). Source: issue 71 (remedy99), :mod:`contact.study.verdicts`.
    """
    both = (getattr(given, "lte_range", None) is not None
            and getattr(remedied, "lte_range", None) is not None,
            getattr(given, "coast_lte_range", None) is not None
            and getattr(remedied, "coast_lte_range", None) is not None)
    was = developed_findings(given, limit, both)
    now = developed_findings(remedied, limit, both)
    parts = []
    for flank in ("drive", "coast"):
        if getattr(given, "coast", None) is None or getattr(remedied, "coast", None) is None:
            if flank == "coast":
                continue
        for check, f in now[flank].items():
            before = was[flank].get(check)
            if SEVERITY_RANK[f.severity] <= SEVERITY_RANK[before.severity if before
                                                         else "pass"]:
                continue
            then = (f"the design as given's {before.severity.upper()}: {before.text}"
                    if before else "the design as given's has none")
            parts.append(f"its {flank} flank's {check} {f.severity.upper()}: {f.text}, "
                         f"where {then}")
    return "; ".join(parts)
