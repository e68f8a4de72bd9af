"""The torque capacity of a pair by ISO 10300: the design torque of a synthesis.

:func:`capacity_torque` inverts the ISO 10300 Method B1 rating
(:func:`contact.load_capacity.iso10300.
rating.iso10300_rating`) for the pinion torque at which the long-life safety factors reach
their minimum: S_H = S_H,min (pitting, ISO 10300-2) or S_F = S_F,min (tooth root, ISO
10300-3), whichever comes first. :func:`design_torque` is the torque a synthesised design
is developed for (``[synthesis] design_torque`` of a basic file, ``docs/synthesis.md``):
the case's ``[rating] design_torque`` if given, else that capacity — the most the pair
carries at long life, so the torque its bearing must hold without edge contact.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json
import logging
import math
from collections.abc import Mapping
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from geometry.core.errors import InputError

if TYPE_CHECKING:
    import os

    from geometry.case import Case

__all__ = ["capacity_torque", "design_torque", "floor_capacity", "iso10300_capacity",
           "with_coast_design_torque", "with_design_torque"]

#: the torques [N·m] the capacity is bracketed on (log-spaced, one rating call)
_GRID = np.geomspace(1e-2, 1e6, 161)

#: the bracket's refinement: passes, each one rating of this many torques across it (two
#: passes narrow the grid's step of 0.115 in ln T to 4.4e-7; the crossing interpolated
#: linearly there errs by at most that, ~1e-13 where the safety is smooth)
_REFINE_PASSES, _REFINE_POINTS = 2, 513


def _long_life_safety(case, torque: Any, speed: float,
                      rating: Mapping[str, Any] | None) -> np.ndarray:
    """min over members of S_H/S_H,min and S_F/S_F,min at long life at each torque: rated
    without ``load_cycles`` (below the knee σ_HP is not Z_NT times its long-life value:
    Z_L Z_v Z_R go to 1 towards the static end,
    contact.load_capacity.iso10300.pitting.long_life_share)."""
    from contact.load_capacity.iso10300.rating import iso10300_rating

    table = case.extra.get("rating") if rating is None else rating
    if isinstance(table, Mapping):  # (else: the rating's own error, naming [rating])
        table = {k: v for k, v in table.items() if k != "load_cycles"}
    ds = iso10300_rating(case, torque=np.atleast_1d(torque), pinion_speed=speed, rating=table)
    s_h = ds["S_H"] / ds["S_Hmin"]
    s_f = ds["S_F"] / ds["S_Fmin"]
    return np.minimum(s_h.min("member"), s_f.min("member")).values


def capacity_torque(case, speed: float | None = None,
                    rating: Mapping[str, Any] | None = None) -> float:
    """Pinion torque at which the pair's long-life ISO 10300 safety reaches its minimum.

    Parameters
    ----------
    case : geometry.case.Case, str or path-like
        With ``[design]`` and ``[rating]`` tables (:func:`contact.load_capacity.iso10300.rating.
        iso10300_rating`).
    speed : float — [rpm], optional
        Pinion speed; default the case's ``[operating] pinion_speed``, or 1500 rpm (the
        toolkit's default speed) where the case runs no efficiency stage (speed 0).
    rating : mapping, optional
        Replaces the case's ``[rating]`` table.

    Returns
    -------
    float — [N·m]
        The smallest pinion torque at which S_H/Z_NT = S_H,min or S_F/Y_NT = S_F,min for
        pinion or gear (ISO 10300-2:2014 and -3:2014 cl. 6, Method B1; the life factors
        divided out: the safety at long life, whatever ``load_cycles`` says), to 1e-6
        relative.

    Raises
    ------
    InputError
        No or a bad ``[design]``/``[rating]`` table (named), or no torque in
        [0.01, 1e6] N·m at which the safety crosses its minimum.

    Notes
    -----
    σ_H grows as √T and σ_F as T (times K_v(T), K_Hβ …): the safety falls monotonically
    with the torque. Bracketed on a log grid of 161 torques (one vectorised rating), the
    bracket narrowed twice by a vectorised rating of 513 torques across it (to 4.4e-7 in
    ln T), then the crossing interpolated linearly in ln T: three ratings, where Brent's
    method on log T took one per step (8 in all; issue 75).
    """
    from contact.catalogue import resolve_case
    from geometry.core.operating_defaults import OPERATING_DEFAULTS

    case = resolve_case(case)
    if speed is None:
        speed = case.operating.pinion_speed or OPERATING_DEFAULTS["pinion_speed"]
    with _quiet():
        return _capacity(case, speed, rating)


def iso10300_capacity(case: Case | str | os.PathLike[str] | None = None,
                      pinion_speed: float | None = None,
                      rating: Mapping[str, Any] | None = None, *,
                      flank: str | None = None) -> float:
    """The pair's ISO 10300 long-life capacity: the pinion torque ``ltca synthesize`` takes
    as the design torque where the basic file gives none.

    The public form of :func:`capacity_torque` (issue 71, round 26d: a script user who
    wanted to give a design torque "at 1.0 x its ISO capacity" had only ``ltca synthesize
    --no-development`` to print it, or an internal module).

    Parameters
    ----------
    case : Case, str, path-like or None
        A case with ``[design]`` and ``[rating]`` tables (a synthesised one has them:
        ``geometry.synthesize(geometry.load_basic(FILE))[0]``), a case file's path or a
        bundled case's name (:func:`contact.resolve_case`; None: the default case).
    pinion_speed : float, optional — [rpm]
        Finite and > 0; default the case's ``[operating] pinion_speed``, or 1500 rpm where
        the case gives none (as :func:`capacity_torque`).
    rating : mapping, optional
        Replaces the case's ``[rating]`` table (its fields: docs/rating.md).
    flank : {"drive", "coast"}, optional
        The pinion flank that carries the torque; default ``"drive"``. ``"coast"`` rates
        the other side of the pair (ISO 10300's ``side``), as the case's ``[rating]
        coast_design_torque`` is found.

    Returns
    -------
    float — [N·m]
        The smallest pinion torque at which S_H = S_H,min or S_F = S_F,min for pinion or
        gear at long life, to 1e-6 relative. ``ltca synthesize`` prints it rounded down to
        4 significant digits (:func:`floor_capacity`).

    Raises
    ------
    InputError
        ``pinion_speed`` not finite and > 0, ``flank`` not ``"drive"`` or ``"coast"``, an
        unknown case (the resolver's message), a bad ``[design]`` or ``[rating]`` table
        (named), or no torque in [0.01, 1e6] N·m at which the safety reaches its minimum.

    Notes
    -----
    Source: ISO 10300-2:2014 and -3:2014 cl. 6, Method B1, inverted for the torque
    (:func:`capacity_torque`).

    Examples
    --------
    >>> import contact
    >>> round(contact.iso10300_capacity("hypoid_iso23509_s2"), 1) > 0.0
    True
    """
    from contact.catalogue import resolve_case
    from geometry.core.validation import one_of, positive

    if pinion_speed is not None:
        pinion_speed = positive("pinion_speed", pinion_speed, "rpm")
    side = one_of("flank", "drive" if flank is None else flank, ("drive", "coast"))
    case = resolve_case(case)
    if side == "coast":
        table = dict((case.extra.get("rating") or {}) if rating is None else rating)
        table["side"] = "coast" if case.pair.drive_flank == "concave" else "drive"
        rating = table
    return capacity_torque(case, pinion_speed, rating)


@contextlib.contextmanager
def _quiet():
    """The rating's warnings (K_v in the resonance range …) silenced: they concern the
    bracketing grid's torques, not the user's (``ltca run`` and ``ltca rate`` give them)."""
    logger = logging.getLogger("contact.load_capacity.iso10300")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        yield
    finally:
        logger.setLevel(level)


def _capacity(case, speed: float, rating: Mapping[str, Any] | None) -> float:
    f = _long_life_safety(case, _GRID, speed, rating) - 1.0
    below = np.flatnonzero(f <= 0.0)
    if below.size == 0 or below[0] == 0:
        raise InputError(f"design_torque: the ISO 10300 long-life safety of {case.name!r} "
                         f"does not reach its minimum between {_GRID[0]:g} and "
                         f"{_GRID[-1]:g} N m; give [synthesis] design_torque [N m]")
    k = int(below[0])
    lo, hi, f_lo, f_hi = math.log(_GRID[k - 1]), math.log(_GRID[k]), f[k - 1], f[k]
    # the bracket narrowed by vectorised ratings, each one call on a grid across it
    # (a rating of 513 torques costs about what one of a single torque does: its cost is
    # the pair's setup and its datasets, not the torques), then the crossing interpolated
    for _ in range(_REFINE_PASSES):
        x = np.linspace(lo, hi, _REFINE_POINTS)
        fx = _long_life_safety(case, np.exp(x[1:-1]), speed, rating) - 1.0
        fx = np.r_[f_lo, fx, f_hi]
        j = int(np.flatnonzero(fx <= 0.0)[0])
        lo, hi, f_lo, f_hi = x[j - 1], x[j], fx[j - 1], fx[j]
    t = f_lo / (f_lo - f_hi) if f_lo != f_hi else 0.5
    return math.exp(lo + t * (hi - lo))


def design_torque(case, speed: float | None = None) -> float:
    """The pinion torque [N·m] a design is developed and rated for.

    Parameters
    ----------
    case : geometry.case.Case, str or path-like
    speed : float — [rpm], optional
        As :func:`capacity_torque`.

    Returns
    -------
    float — [N·m]
        The case's ``[rating] design_torque`` if it gives one, else
        :func:`capacity_torque` (S_H = S_H,min or S_F = S_F,min at long life).

    Raises
    ------
    InputError
        As :func:`capacity_torque`.
    """
    from contact.catalogue import resolve_case

    case = resolve_case(case)
    table = case.extra.get("rating")
    if isinstance(table, Mapping) and table.get("design_torque") is not None:
        return float(table["design_torque"])
    return capacity_torque(case, speed)


def with_design_torque(case, torque: float | None = None):
    """The case with its ``[rating] design_torque`` set: the torque its synthesis developed
    the bearing for.

    Parameters
    ----------
    case : geometry.case.Case
        With ``[design]`` and ``[rating]`` tables (a synthesised case has them).
    torque : float — [N·m], optional
        ``[synthesis] design_torque`` of the basic file; default: the case's own
        ``[rating] design_torque`` if it gives one, else :func:`capacity_torque` (rounded
        down to 4 significant digits, so that the design torque is rated at S ≥ S_min).

    Returns
    -------
    case : geometry.case.Case
        ``extra["rating"]`` with ``design_torque`` and a sentence on it appended to its
        ``source``; the case unchanged where the rating cannot give a torque.
    torque : float — [N·m]
        NaN where the rating cannot give one.
    why : str
        Where the torque comes from, or why there is none.
    """
    table = dict(case.extra.get("rating") or {})
    if torque is not None:
        value, why = float(torque), "[synthesis] design_torque of the basic file"
    elif table.get("design_torque") is not None:
        return case, float(table["design_torque"]), "[rating] design_torque of the basic file"
    else:
        try:
            value = floor_capacity(capacity_torque(case))
        except InputError as exc:
            return case, math.nan, f"none: {exc}"
        why = ("the ISO 10300 capacity, the pinion torque at which the long-life safety "
               "reaches S_H,min or S_F,min (contact.load_capacity.iso10300.capacity)")
    return _with_rating_field(case, table, "design_torque", value, why), value, why


def floor_capacity(exact: float) -> float:
    """A capacity rounded *down* to 4 significant digits, as the default design torque is
    written: the capacity is where S = S_min exactly, and a design torque rounded up would
    fail its own rating by round-off.

    Parameters
    ----------
    exact : float — [N·m] the capacity (:func:`capacity_torque`), finite and > 0

    Returns
    -------
    float — [N·m], at most ``exact``, 4 significant digits

    Notes
    -----
    Source: the rounding rule of this module (no standard's): ISO 10300-1:2014 defines
    the safety factors, not how a torque is printed.
    """
    step = 10.0 ** (math.floor(math.log10(exact)) - 3)
    return float(f"{math.floor(exact / step) * step:.4g}")


def _with_rating_field(case, table: dict, name: str, value: float, why: str):
    """The case with ``[rating] name = value`` and a sentence on it, ``why``, appended to
    the table's ``source``."""
    table = {**table, name: value}
    table["source"] = (str(table.get("source", "")).rstrip() + f" {name} {value:g} N m: "
                       f"{why}.").lstrip()
    extra = json.loads(json.dumps({**case.extra, "rating": table}))
    return dataclasses.replace(case, extra=MappingProxyType(extra))


def with_coast_design_torque(case):
    """The case with ``[rating] coast_design_torque`` set where its coast side carries less
    than the design torque at long life.

    A hypoid's coast side (the pinion's convex flank driving) has its own pressure angle and
    virtual gears, so its ISO 10300 long-life capacity is not the drive side's; the torque
    it carries in reverse gear is a load of limited duration. Rating it at the drive side's
    design torque for long life fails a design that is sound (issue 60: three of six
    synthesised hypoids, coast S_H 0.99-0.997, gear S_F 1.18 at the drive side's capacity);
    with the coast side's own long-life torque, a larger torque on that side is rated at a
    finite life with its permissible load cycles stated (the verdict's attention), as above
    the design torque on the drive side.

    Parameters
    ----------
    case : geometry.case.Case
        With ``[design]`` and ``[rating]`` tables and ``[rating] design_torque``.

    Returns
    -------
    case : geometry.case.Case
        ``extra["rating"]`` with ``coast_design_torque`` = the coast side's capacity
        (:func:`capacity_torque` with ``side = "coast"``, rounded down to 4 significant
        digits) and a sentence on it in its ``source``, where that capacity is below the
        design torque; else unchanged (the design torque rates both sides). Unchanged also
        where the table gives ``coast_design_torque`` or ``side``, where the pinion's convex
        flank drives (its coast side is ISO's drive side), or where the rating gives no
        capacity.
    torque : float — [N·m]
        The coast side's design torque; NaN where none is written.

    Raises
    ------
    InputError
        A bad ``[rating]`` table (named), from the rating.

    Notes
    -----
    Source: ISO 10300-2:2014 and -3:2014 rate the drive and the coast side each with its
    own flank angles (ISO 23509:2016 cl. 5: α_nD, α_nC); cl. 8, the life factors of a load
    of finite life.
    """
    table = dict(case.extra.get("rating") or {})
    design = table.get("design_torque")
    if (design is None or table.get("coast_design_torque") is not None
            or table.get("side") is not None or case.pair.drive_flank != "concave"):
        return case, math.nan
    try:
        exact = capacity_torque(case, rating={**table, "side": "coast"})
    except InputError:
        return case, math.nan
    if exact >= float(design):
        return case, math.nan
    value = floor_capacity(exact)
    why = ("the ISO 10300 capacity of the coast side (the pinion's convex flank driving), "
           "below the design torque; above it the coast side is rated at a finite life")
    return _with_rating_field(case, table, "coast_design_torque", value, why), value
