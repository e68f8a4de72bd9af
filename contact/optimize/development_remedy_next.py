"""The next checked remedy developed where the first one's development misses the drive
LTE between its torques (``ltca synthesize --apply-remedy``; issue 71, "LTE p-p ≤ 60 µrad
at every torque").

``--apply-remedy`` (:mod:`contact.optimize.development_remedy`) develops the best checked
contact-ratio remedy (the lowest unloaded TE p-p at the written prescriptions,
:func:`~contact.optimize.remedy_check.ranked_changes`). Two of the designs it was made for
kept their drive LTE within 60 µrad at both torques of the remedied development and not
between them, as ``ltca run``'s ``lte_range`` step judges it (2026-11-27, session 19): the
spiral bevel 15×28 at Σ 110° (b2 28 → 36.5 mm: 19.8 / 45.1 µrad, 62.4 between) and the
hypoid 15×31 at a = 0.056 d_e2 (b2 27 → 32.6 mm: 45.1 / 58.2 µrad, 63.3 between). The
check's unloaded TE ranks the remedies before any load; which remedy's developed bearing
keeps the limit under load only its development says.

:func:`next_remedies` judges the first remedied development's drive LTE over ``ltca
run``'s torques (:func:`developed_range`:
:func:`~contact.optimize.development_range_lte.range_lte`, or the check's own record of
the written design, :attr:`~contact.optimize.development_result.DevelopmentResult.
lte_range`) and, where it is above the verdict's limit, develops the next checked remedy
in the check's order (at most :data:`NEXT_REMEDIES` more: each is a full development),
keeping the better by the check's keep rule (:func:`remedy_kept_why`:
:func:`~contact.optimize.development_keep.kept_why` with
:func:`~contact.optimize.development_range_lte.peak_better`, each design judged at its
own torques). A first remedy whose development keeps the limit over the range is returned
as before, nothing more developed.

Public names
------------
NEXT_REMEDIES, RemedyDeveloped, developed_range, remedy_kept_why, next_remedies,
developed_text
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any, NamedTuple

from contact.optimize.development_keep import kept_why, lost_but_length, lost_targets
from contact.optimize.development_range_lte import peak_better, range_lte, range_peak
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number

__all__ = ["NEXT_REMEDIES", "RemedyDeveloped", "developed_range", "developed_text",
           "next_remedies", "remedy_kept_why"]

log = logging.getLogger(__name__)

#: how many checked remedies after the first ``--apply-remedy`` develops at most, where the
#: one before misses the drive LTE limit over ``ltca run``'s torques: each is a full
#: development (the 15×31's and 15×28's: docs/synthesis.md, "The next checked remedy")
NEXT_REMEDIES = 1


class RemedyDeveloped(NamedTuple):
    """One remedy ``--apply-remedy`` developed, as its development judged it.

    Attributes
    ----------
    text : str
        The change in words (:func:`~contact.optimize.development_remedy.change_text`).
    field : str
        The ``[design]`` field changed.
    torques : (float, float) — [N·m]
        The development's light and design torque.
    lte : (float, float) — [µrad]
        The written drive design's LTE p-p at them.
    peak, at : float — [µrad], [N·m]
        Its largest drive LTE p-p over ``ltca run``'s ``lte_range`` torques and where
        (:func:`developed_range`); NaN where not judged.
    seconds : float — [s]
        The development's CPU (its ``seconds``).
    why : str
        Why it was not kept (empty for the one kept), or where its development failed.
    """

    text: str
    field: str
    torques: tuple[float, float]
    lte: tuple[float, float]
    peak: float
    at: float
    seconds: float
    why: str = ""


def developed_range(result) -> tuple[tuple[float, ...], tuple[float, ...]] | None:
    """A development's written drive design judged over ``ltca run``'s ``lte_range``
    torques: the check's own record where it is of that design at the development's
    final torques (:attr:`~contact.optimize.development_result.DevelopmentResult.
    lte_range`), else :func:`~contact.optimize.development_range_lte.range_lte` of its
    chosen design at them (the check's sampling, fresh shell teeth).

    Parameters
    ----------
    result : contact.optimize.development_result.DevelopmentResult

    Returns
    -------
    (torques, lte) : (tuple of float, tuple of float) — [N·m], [µrad], or None
        None where it could not be analysed (logged by ``range_lte``).

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: ``ltca run``'s ``lte_range`` step (:mod:`contact.ltca.lte_range`, issue 71);
    the analysis :func:`~contact.optimize.development_range_lte.range_lte` (about two
    check analyses, more where the LTE crosses the limit) only where the check did not
    record it.
    """
    judged = getattr(result, "lte_range", None)
    if judged is not None:
        return tuple(judged["torques"]), tuple(judged["lte"])
    return range_lte(result.best, {"torques": [float(t) for t in result.torque]}, None)


def _developed(check, result, text: str, seconds: float, why: str = "") -> RemedyDeveloped:
    found = developed_range(result)
    peak, at = range_peak(found)
    lte = result.best.metrics["lte_peak_to_peak"]
    return RemedyDeveloped(text, check.change.field,
                           (float(result.torque[0]), float(result.torque[1])),
                           (float(lte[0]), float(lte[-1])), peak, at, float(seconds), why)


def _within(d: RemedyDeveloped, limit: float) -> bool:
    return d.peak <= limit


def remedy_kept_why(kept: tuple[RemedyDeveloped, Any], other: tuple[RemedyDeveloped, Any],
                    limit: float, say: Callable[[str], None]) -> str:
    """Why the development of a next remedy (``other``) does not replace the one kept so
    far, empty where it does: the check's keep rule
    (:func:`~contact.optimize.development_keep.kept_why`) on the two chosen drive designs,
    "better" judged on their largest LTE over ``ltca run``'s torques, each at its own
    development's torques (:func:`~contact.optimize.development_range_lte.peak_better`);
    the pattern's length may be given up by a design whose LTE over the range keeps the
    limit (:func:`~contact.optimize.development_keep.lost_but_length`), else no target the
    kept one met (:func:`~contact.optimize.development_keep.lost_targets`); the mounting
    tolerance each development's own final check (never lost).

    Parameters
    ----------
    kept, other : (RemedyDeveloped, DevelopmentResult)
        The remedy kept so far and the next, each with its development.
    limit : float — [µrad]
        The verdict's LTE limit.
    say : callable str → None
        Where the "not kept" lines go.

    Returns
    -------
    str
        Empty where ``other`` replaces ``kept``; else why not, in numbers where it scores
        no better.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: the check's keep rule (issue 71, docs/synthesis.md "Development bearing") and
    ``ltca run``'s ``lte_range`` verdict.
    """
    (a, ra), (b, rb) = kept, other
    if ra.best.full is None or rb.best.full is None:
        return "its chosen design was not scored"
    peaks = {id(ra.best): a.peak, id(rb.best): b.peak}

    def better(best, e) -> bool:
        return peak_better(peaks[id(best)], peaks[id(e)], best, e, limit)

    def lost(best, e) -> list[str]:
        return (lost_but_length(best, e) if peaks[id(e)] <= limit
                else lost_targets(best, e))

    why = kept_why(ra.best, rb.best, rb.targets, {}, None, say, b.text, better=better,
                   lost=lost, tolerant=False)
    if why == "it scores no better":
        return (f"it scores no better (its drive LTE p-p over the range {b.peak:.1f} urad "
                f"against {a.peak:.1f})")
    if not why and ra.tolerant and not rb.tolerant:
        return "not tolerant at its mounting excursions (the kept one is)"
    return why


def next_remedies(first: tuple[Any, Any], rest, develop: Callable[[Any], Any],
                  text: Callable[[Any], str], limit: float,
                  say: Callable[[str], None] | None = None
                  ) -> tuple[Any, Any, tuple[RemedyDeveloped, ...], str]:
    """The first remedy's development judged over ``ltca run``'s torques and, where its
    drive LTE is above ``limit`` there, the next checked remedies developed in the check's
    order (at most :data:`NEXT_REMEDIES`), the better kept (:func:`remedy_kept_why`),
    until one keeps the limit.

    Parameters
    ----------
    first : (ChangeCheck, DevelopmentResult)
        The best checked remedy and its development.
    rest : sequence of ChangeCheck
        The other remedies that passed their check, in the check's order
        (:func:`~contact.optimize.remedy_check.ranked_changes`).
    develop : callable ChangeCheck → DevelopmentResult
        The development of the basic data with a remedy applied.
    text : callable ChangeCheck → str
        The change in words.
    limit : float — [µrad]
        The verdict's LTE limit.
    say : callable, optional
        Called with a line before each development and with each verdict.

    Returns
    -------
    (check, result, developed, why) : (ChangeCheck, DevelopmentResult, tuple of
    RemedyDeveloped, str)
        The remedy kept and its development, every remedy developed in order (its ``why``
        empty for the one kept), and why the kept one was kept, in numbers (empty where
        only the first was developed).

    Raises
    ------
    Nothing: a next remedy whose development fails is not kept (said, logged).

    Notes
    -----
    Cost: one full development per next remedy (:data:`NEXT_REMEDIES` at most), about the
    first's CPU each; the judging over the range reads the check's record, or analyses
    the two torques between (and the bisections) at the check's sampling.
    """
    said = say or (lambda line: None)
    check, result = first
    kept = (_developed(check, result, text(check), result.seconds), result)
    kept_check, done, why = check, [kept[0]], ""
    for nxt in list(rest)[:NEXT_REMEDIES]:
        if _within(kept[0], limit) or not math.isfinite(kept[0].peak):
            break  # within the limit over the range, or not judged: nothing more spent
        said(f"apply_remedy: {kept[0].text} developed: its drive LTE p-p "
             f"{kept[0].peak:.1f} urad at {plain_number(kept[0].at)} N m, above "
             f"{limit:g} urad between its torques; the next checked remedy, "
             f"{text(nxt)}, developed")
        try:
            developed = develop(nxt)
        except Exception as exc:  # reported, never fatal: the remedy kept so far stays
            raise_if_interrupted(exc)
            log.info("apply_remedy: %s not developed: %s", text(nxt), exc)
            failed = f"its development failed ({str(exc).splitlines()[0] if str(exc) else exc})"
            done.append(RemedyDeveloped(text(nxt), nxt.change.field, (math.nan, math.nan),
                                        (math.nan, math.nan), math.nan, math.nan, 0.0,
                                        failed))
            why = _kept_text(kept[0], done[-1], limit)
            continue
        other = (_developed(nxt, developed, text(nxt), developed.seconds), developed)
        refused = remedy_kept_why(kept, other, limit, said)
        if refused:
            done.append(other[0]._replace(why=refused))
            why = _kept_text(kept[0], done[-1], limit)
        else:
            i = done.index(kept[0])
            done[i] = kept[0]._replace(why=f"the next, {other[0].text}, kept over it")
            done.append(other[0])
            why = _replaced_text(other[0], kept[0], limit)
            kept, kept_check = other, nxt
        said(f"apply_remedy: {why}")
    return kept_check, kept[1], tuple(done), why


def _peak_text(d: RemedyDeveloped) -> str:
    if not math.isfinite(d.peak):
        return "its LTE over the range not judged"
    return f"{d.peak:.1f} urad at {plain_number(d.at)} N m"


def _kept_text(kept: RemedyDeveloped, refused: RemedyDeveloped, limit: float) -> str:
    """Why ``kept`` stays where the next remedy's development ``refused`` was not kept."""
    return (f"kept {kept.text} (its drive LTE p-p over ltca run's torques "
            f"{_peak_text(kept)}, above {limit:g} urad): the next, {refused.text}"
            + (f" ({_peak_text(refused)})" if math.isfinite(refused.peak) else "")
            + f", not kept: {refused.why}")


def _replaced_text(kept: RemedyDeveloped, first: RemedyDeveloped, limit: float) -> str:
    """Why the next remedy ``kept`` replaced ``first``."""
    over = "within" if kept.peak <= limit else "above"
    return (f"kept {kept.text}: its drive LTE p-p over ltca run's torques "
            f"{_peak_text(kept)}, {over} {limit:g} urad, where {first.text}'s was "
            f"{_peak_text(first)}; no target the first met lost"
            + (" (the pattern's length aside)" if kept.peak <= limit else ""))


def developed_text(developed: tuple[RemedyDeveloped, ...], limit: float) -> str:
    """The remedies developed in one line (``ltca synthesize``'s first lines): each with
    its drive LTE p-p at its torques and over the range, and its CPU.

    Parameters
    ----------
    developed : tuple of RemedyDeveloped
        :func:`next_remedies`' record.
    limit : float — [µrad]
        The verdict's LTE limit.

    Returns
    -------
    str
        Empty where one remedy alone was developed.

    Raises
    ------
    Nothing.

    Notes
    -----
    Source: :func:`next_remedies` (issue 71).
    """
    if len(developed) < 2:
        return ""
    parts = []
    for d in developed:
        if not math.isfinite(d.torques[1]):
            parts.append(f"{d.text}: {d.why}")
            continue
        over = ("within" if d.peak <= limit else "above" if d.peak > limit
                else "not judged against")
        parts.append(f"{d.text}: drive LTE p-p {d.lte[0]:.1f}/{d.lte[1]:.1f} urad at "
                     f"{plain_number(d.torques[0])}/{plain_number(d.torques[1])} N m, "
                     f"{_peak_text(d)} over ltca run's torques ({over} {limit:g}), "
                     f"{d.seconds:.0f} s CPU")
    return "remedies developed in the check's order: " + "; ".join(parts)
