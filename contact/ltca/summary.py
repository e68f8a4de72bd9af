"""Summaries of an ``/ltca`` dataset that more than one layer reports.

Public functions
----------------
edge_load_share   the share of the gear torque the edge segments carry, per torque
flank_peak        the flank's peak Hertzian pressure per torque without the contact curves
                  shorter than their own contact width, and how many were left out
flank_peak_pressure  its pressure alone (the development's and ``ltca run``'s verdict's)
certification     whether every roll position of every torque has a certified contact
                  solution: the analysis' status and the sentence that says why not
"""

from __future__ import annotations

import logging
from typing import NamedTuple

import numpy as np
import xarray as xr

from geometry.core.errors import InputError
from geometry.core.text import plain_number

__all__ = ["ANALYSIS_STATUS", "Certification", "FlankPeak", "certification",
           "edge_load_share", "flank_peak", "flank_peak_pressure"]

log = logging.getLogger(__name__)

#: an analysis' ``analysis_status`` (root attribute of its file, :func:`certification`):
#: every roll position of every torque certified; some torque with rolls uncertified; some
#: torque without one certified roll (no contact solution at that torque: the analysis failed)
ANALYSIS_STATUS = ("ok", "uncertified", "failed")


class FlankPeak(NamedTuple):
    """The flank's peak pressure a verdict judges (:func:`flank_peak`).

    Attributes
    ----------
    pressure : ndarray (torque,) — [MPa] the peak over the contact curves that are line
        contacts; 0 where none carries load
    dataset : ndarray (torque,) — [MPa] the dataset's ``pressure_max_flank`` as written
    corner_curves : ndarray of int (torque,) — the loaded contact curves (one per roll
        position and pair) left out: shorter than their contact width 2b
    line : ndarray of bool (torque, roll, pair) — the contact curves kept (line
        contacts, or curves without load); False for the curves left out. What the duty
        cycle's damage and local S_H read the same rule by
        (:func:`contact.study.duty_cycle.analyse_bin`)
    """

    pressure: np.ndarray
    dataset: np.ndarray
    corner_curves: np.ndarray
    line: np.ndarray


#: [1] Largest share of a roll position's load a contact curve shorter than its Hertz
#: contact width may carry and be left out of the flank peak (:func:`flank_peak`): the
#: corner clips the rule is for carry ~1e-5 of it (0.26 N of ~5 kN on the bundled 11×41);
#: the default case's entering curve at 500 N·m (0.38 mm, 2b 0.50 mm, 242 N ≈ 4 %) is a
#: concentrated contact that stays in.
CORNER_LOAD_SHARE = 0.01


def flank_peak(ltca: xr.Dataset) -> FlankPeak:
    """The peak Hertzian pressure on the contact curves per torque [MPa], without the
    curves that are no line contact — a (roll, pair)'s contact curve whose length (the sum
    of its curve segments' ``segment_length``) is below the contact width 2b of its most
    loaded segment, b = 2w/(π p₀) of its Hertz line load w and peak pressure p₀, and which
    carries at most :data:`CORNER_LOAD_SHARE` of its roll position's load — beside
    the dataset's ``pressure_max_flank`` and the number of curves left out.

    The one rule of the flank peak that the development
    (:mod:`contact.optimize.development_evaluate`), ``ltca run``'s verdict
    (:mod:`contact.study.verdicts`, :func:`contact.ltca.plausibility.plausibility_flags`)
    and the duty cycle's static check, damage and local S_H
    (:mod:`contact.study.duty_cycle`, by ``line``) judge; the dataset's
    ``pressure_max_flank`` keeps every curve (what users read).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` of :func:`contact.ltca.loaded_tca`: ``pressure_max_flank`` (torque)
        [MPa], ``pressure_max`` (torque, roll, pair, segment) [MPa], ``half_width`` (same)
        [mm], ``segment_length`` (roll, pair, segment) [mm], ``force`` (torque, roll,
        pair, segment) [N] (without it, no load condition) and the coordinate
        ``segment_kind`` (segment); without ``pressure_max`` … ``segment_kind``, the dataset's
        ``pressure_max_flank`` as it is (no curve left out).

    Returns
    -------
    FlankPeak
        ``pressure`` and ``dataset`` (torque,) [MPa], ``corner_curves`` (torque,) [1],
        ``line`` (torque, roll, pair) bool (without the segment data (torque, 0, 0)).

    Raises
    ------
    KeyError
        ``pressure_max_flank`` absent where the segment data are too.

    Notes
    -----
    Hertz's line contact (Johnson, *Contact Mechanics*, 1985, §4.3 and Eq. 4.43–4.45)
    holds for a contact much longer than its width; a curve clipped to a corner of the
    flank, a few µm long, is a point touching the corner, whose load per length F/L is
    the ratio of two vanishing numbers. Why (issue 71): on the bundled FM 11×41
    (cases/basic/kolivand2009_fm_11x41.toml) the coast search's first trial (coarse LTCA,
    392.1 N·m) read 2577 MPa from such a curve at the toe-tip corner (4 segments of 1e-5
    mm, 0.26 N in all, w 1787 N/mm) and 2045 MPa with the pinion's machine settings
    changed by 1e-13 relative (the curve gone); the coast design torque the development
    wrote moved 69.5 ↔ 112.2 N·m with it. Tested in tests/test_development_roundoff.py
    and tests/test_verdicts.py (synthetic datasets).
    """
    need = {"pressure_max", "half_width", "segment_length", "segment_kind"}
    if not need <= set(ltca.variables):
        raw = np.asarray(ltca["pressure_max_flank"].values, float)
        return FlankPeak(raw, raw, np.zeros(raw.shape, int), np.ones((*raw.shape, 0, 0), bool))
    curve = np.asarray(ltca["segment_kind"].values) == "curve"
    p = np.nan_to_num(np.asarray(ltca["pressure_max"].values, float)[..., curve])
    b = np.nan_to_num(np.asarray(ltca["half_width"].values, float)[..., curve])
    length = np.nan_to_num(np.asarray(ltca["segment_length"].values, float)[..., curve])
    total = length.sum(axis=-1)  # (roll, pair): each curve's length
    line = total[None] >= 2.0 * b.max(axis=-1)  # (torque, roll, pair)
    if "force" in ltca.variables:
        # a short curve is left out only where its load vanishes beside the roll's: a
        # short curve that carries a share of the load is a real, concentrated contact
        force = np.nan_to_num(np.asarray(ltca.variables["force"].values, float))
        curve_load = force[..., curve].sum(axis=-1)  # (torque, roll, pair)
        roll_load = force.sum(axis=(-2, -1))[..., None]  # (torque, roll, 1)
        line = line | (curve_load > CORNER_LOAD_SHARE * roll_load)
    nt = p.shape[0]
    if p.size:
        peak = np.where(line[..., None], p, 0.0).max(axis=(1, 2, 3))
        corner = ((~line) & (p.max(axis=-1) > 0.0)).sum(axis=(1, 2))
    else:
        peak, corner = np.zeros(nt), np.zeros(nt, int)
    raw = (np.asarray(ltca["pressure_max_flank"].values, float)
           if "pressure_max_flank" in ltca else (p.max(axis=(1, 2, 3)) if p.size else peak))
    if np.any(peak != raw):
        log.info("flank peak pressure: contact curves shorter than their contact width left "
                 "out, %s -> %s MPa", np.round(raw), np.round(peak))
    # a curve without load is no corner clip: kept (it adds nothing to a peak either way)
    kept = line | ~(p.max(axis=-1) > 0.0) if p.size else line
    return FlankPeak(peak, raw, corner.astype(int), kept)


def flank_peak_pressure(ltca: xr.Dataset) -> np.ndarray:
    """The peak Hertzian pressure on the contact curves per torque [MPa] (NT,): the
    ``/ltca`` dataset's ``pressure_max_flank`` without the curves that are no line
    contact (shorter than their own contact width 2b): :func:`flank_peak`'s
    ``pressure`` (its parameters, notes and source). 0 where no curve carries load."""
    return flank_peak(ltca).pressure


def edge_load_share(ltca: xr.Dataset, kinds: tuple[str, ...] | None = None) -> np.ndarray:
    """[1] Per torque, the share of the gear torque carried by the edge segments over the
    mesh cycles: Σ F·R over the edge segments / Σ F·R over all (seed Eq. 3.14's moments;
    :mod:`contact.ltca.edges`).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca``: ``force`` (torque, roll, pair, segment) [N], ``moment_arm`` (roll, pair,
        segment) [mm], ``segment_kind`` (segment).
    kinds : tuple of str, optional
        The edges counted, of :data:`contact.ltca.edges.EDGE_KINDS` (``"gear_tip"``,
        ``"gear_heel"``, ``"gear_toe"``, ``"pinion_edge"``); default every edge (every
        segment that is not a contact curve's).

    Returns
    -------
    ndarray (NT,)
        In [0, 1]: the arms are positive on either flank (the sense the gear torque loads
        it; a pinion edge's on the coast flank since issue 60: files written before carry
        negative ones there and give a negative share). NaN where no segment carries load.

    Raises
    ------
    InputError
        If ``ltca`` lacks one of the variables, or ``kinds`` names no edge of
        :data:`contact.ltca.edges.EDGE_KINDS`.
    """
    from contact.ltca.edges import EDGE_KINDS

    missing = [k for k in ("force", "moment_arm", "segment_kind") if k not in ltca.variables]
    if missing:
        raise InputError(f"ltca: lacks {', '.join(missing)} (not an /ltca dataset)")
    if kinds is not None and (not kinds or any(k not in EDGE_KINDS for k in kinds)):
        raise InputError(f"kinds: must name edges of {EDGE_KINDS}, got {kinds!r}")
    moment = (np.nan_to_num(ltca.variables["force"].values)
              * np.nan_to_num(ltca.variables["moment_arm"].values)[None])
    kind = np.asarray(ltca.variables["segment_kind"].values).astype(str)
    edge = kind != "curve" if kinds is None else np.isin(kind, list(kinds))
    total = moment.sum(axis=(1, 2, 3))
    on_edges = moment[..., edge].sum(axis=(1, 2, 3))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(total > 0, on_edges / total, np.nan)


class Certification(NamedTuple):
    """What :func:`certification` finds: ``status`` one of :data:`ANALYSIS_STATUS`,
    ``reason`` one sentence (empty for ``"ok"``), ``certified`` and ``rolls`` (NT,) the
    certified and all roll positions per torque.

    Notes
    -----
    A roll position is certified when its solution satisfies seed Eq. (3.12)–(3.14) —
    compatibility with the slack Y, complementarity F·Y = 0 and the torque equilibrium
    RᵀF = T — within the residual tolerances, computed by the toolkit (DESIGN.md, the loaded
    contact problem).
    """

    status: str
    reason: str
    certified: np.ndarray
    rolls: int


def certification(ltca: xr.Dataset) -> Certification:
    """Whether the loaded contact of an analysis is certified at every roll and torque.

    A roll position's solution is certified when the toolkit's own residuals of the four
    contact conditions (primal and dual feasibility, complementarity, torque equilibrium;
    DESIGN "The loaded contact problem", seed Eq. 3.12–3.14) are within the tolerance
    (:func:`contact.qp.solve_contact`, ``/ltca/found``). A torque none of whose rolls is
    certified has no contact solution at all: its LTE, pressures and efficiency are not
    results, and the analysis has *failed*. A torque with some rolls uncertified has
    no LTE summary over the mesh cycle (NaN): the analysis is *uncertified*.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca``: ``found`` (torque, roll) int8 0/1, ``status`` (torque, roll) text,
        ``torque`` [N·m].

    Returns
    -------
    Certification
        The reason names the torques and the first uncertified roll's solver status,
        e.g. ``"no certified contact solution at T_p 250 N m (0 of 16 roll positions;
        roll 0: failed: backend raised RuntimeError: …)"``.

    Raises
    ------
    InputError
        If ``ltca`` lacks ``found``.
    """
    if "found" not in ltca.variables:
        raise InputError("ltca: lacks found (not an /ltca dataset)")
    found = np.asarray(ltca.variables["found"].values) > 0
    found = found.reshape(found.shape[0] if found.ndim > 1 else 1, -1)
    torques = np.atleast_1d(np.asarray(ltca.variables["torque"].values, float))
    status = (np.asarray(ltca.variables["status"].values, dtype=object).reshape(found.shape)
              if "status" in ltca.variables else np.full(found.shape, "", dtype=object))
    certified = found.sum(axis=1)
    rolls = found.shape[1]
    if bool(found.all()):
        return Certification("ok", "", certified, rolls)
    none = [i for i in range(found.shape[0]) if certified[i] == 0]
    which = none or [i for i in range(found.shape[0]) if certified[i] < rolls]
    first = which[0]
    j = int(np.argmin(found[first]))
    why = str(status[first, j]).strip()
    where = ", ".join(f"T_p {plain_number(torques[i])} N m ({certified[i]} of {rolls} roll "
                      "positions certified)" for i in which)
    detail = f"; roll {j}: {why}" if why else ""
    if none:
        return Certification("failed", f"no certified contact solution at {where}{detail}",
                             certified, rolls)
    return Certification("uncertified", f"roll positions without a certified contact "
                         f"solution at {where}{detail}; the LTE summary over the mesh cycle "
                         "is undefined there (NaN)", certified, rolls)
