"""The unloaded TCA of a case as labelled datasets: ``/easeoff`` and ``/utca``.

:func:`unloaded_tca` runs the ease-off (:func:`contact.utca.easeoff.ease_off`), the
transitions and the contact curves of every tooth pair over one mesh cycle
(:func:`unloaded_cycle`, with :mod:`contact.utca.contact_curves`) and returns the two
stage datasets; :func:`easeoff_dataset` and :func:`utca_dataset` assemble them from the
computed pieces.
Every variable carries ``units`` and ``long_name``; the attributes record the senses and
phases of the kinematics, the misalignment and the case as TOML text.

Public functions
----------------
unloaded_tca       the whole UTCA of a case: (/easeoff, /utca) Datasets
UnloadedCycle      contact curves and UTE of the tooth pairs over one mesh cycle
unloaded_cycle     compute them from an EaseOff
easeoff_dataset    the ``/easeoff`` Dataset of an EaseOff
utca_dataset       the ``/utca`` Dataset of an UnloadedCycle
ute_dataset        the ``/utca`` Dataset of the UTE alone (no curves: a study point's)

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009, §2.3.2.2, §2.4, §4.4.
"""

from __future__ import annotations

import json
import logging
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import xarray as xr
from scipy.interpolate import RectBivariateSpline

from contact.utca.contact_curves import (
    CURVE_SPACINGS,
    DEFAULT_SEPARATION,
    UTE_METHODS,
    ContactCurves,
    contact_curves,
    pair_transmission_error,
)
from contact.utca.easeoff import EASEOFF_REASONS, EaseOff, ease_off
from contact.utca.fields import EaseOffFields, Same, fields_of
from contact.utca.transitions import transitions
from geometry import __version__
from geometry.core.caches import memoised
from geometry.core.conventions import binary_flag, dataset
from geometry.core.conventions import data_var as _var
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords
from geometry.core.validation import integer, one_of, positive

if TYPE_CHECKING:
    from geometry.case import Case
    from geometry.pair.assembly import Misalignment

__all__ = [
    "UnloadedCycle",
    "easeoff_dataset",
    "unloaded_cycle",
    "unloaded_tca",
    "utca_dataset",
    "ute_dataset",
]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class UnloadedCycle:
    """The unloaded contact of the tooth pairs over one mesh cycle (seed §2.3.2.2, Fig. 2.9).

    Parameters
    ----------
    roll : ndarray (n_roll,) — [rad]
        Roll positions (Q units, driving sense), uniform over one cycle from M1.
    pairs : ndarray (n_pair,) of int
        Tooth-pair offsets (pair k's contact curve at roll r is Q = r − k·pitch).
    curves : ContactCurves
        The pairs' contact curves, batch shape (n_roll, n_pair).
    envelope : ndarray (n_roll,) — [rad]
        Lower envelope of the pairs' UTE: the actual UTE (gear lag).
    transitions : (float, float) — [rad]
        Rolls M1, M2 where the motion passes from pair −1 to 0 and from 0 to +1 (NaN if
        none).
    transition_te : (float, float) — [rad]
        UTE at M1 and M2.
    te_range : (float, float) — [rad]
        Lowest and highest actual UTE over the cycle (the lowest refined by a parabola, the
        highest including the transitions, where the envelope peaks).
    method : str
        The UTE method of the curves (:data:`contact.utca.contact_curves.UTE_METHODS`).
    """

    roll: np.ndarray
    pairs: np.ndarray
    curves: ContactCurves
    envelope: np.ndarray
    transitions: tuple[float, float]
    transition_te: tuple[float, float]
    te_range: tuple[float, float]
    method: str = "second_order"


@renamed_keywords(n_roll="rolls_per_cycle")
def unloaded_tca(case: Case, *, misalignment: Misalignment | None = None,
                 flank: str | None = None, rolls_per_cycle: int = 30, pairs=(-1, 0, 1),
                 separation: float = DEFAULT_SEPARATION, grid: dict | None = None,
                 method: str = "second_order",
                 n_point: int = 41,
                 easeoff: EaseOff | None = None,
                 curves: bool = True) -> tuple[xr.Dataset, xr.Dataset]:
    """Ease-off based unloaded TCA of a case over one mesh cycle (seed §2.3.2, §2.4, §4.4).

    Parameters
    ----------
    case : geometry.case.Case
    misalignment : geometry.pair.assembly.Misalignment, optional
        ΔE, ΔP, ΔG [mm], ΔΣ [rad]; defaults to the case's own ``[misalignment]``; the whole
        UTCA is recomputed in the misaligned frame.
    flank : str, optional
        ``"drive"`` (default), ``"coast"``, or a pinion flank name.
    rolls_per_cycle : int
        Roll positions over one mesh cycle (≥ 4), from the transition M1 (uniform,
        the end point M2 = M1 + pitch excluded); old name ``n_roll``, deprecated.
    pairs : sequence of int
        Tooth-pair offsets; pair k is the pair that comes into mesh k mesh cycles after
        the reference pair 0 (its contact curve at roll r is Q = r − k·pitch).
    separation : float — [mm]
        Separation bounding the unloaded contact line, > 0 (default 0.0063).
    grid : dict, optional
        Gear grid (``nu``, ``nv``, ``u_limits``, ``v_limits``).
    method : str
        ``"second_order"`` (default) or ``"seed"``, see :func:`contact_curves`.
    n_point : int
        Samples along each contact curve (≥ 3).
    easeoff : contact.utca.easeoff.EaseOff, optional
        A precomputed ease-off of the same case, flank, misalignment and grid (the LTCA
        pipeline shares one); ``flank``, ``misalignment`` and ``grid`` are then not used
        to rebuild it.
    curves : bool
        True (default): the whole ``/utca`` (:func:`utca_dataset`). False: the UTE alone
        (:func:`ute_dataset`: the pairs' and the actual UTE, the transitions and the
        peak-to-peak, the same values bit for bit) — the contact curves' flank points,
        normals and arms, the separations, lines and paths are not evaluated (a study
        point's ``utca`` step, :func:`contact.chain.utca_ute`; issue 75).

    Returns
    -------
    easeoff : xarray.Dataset
        See :func:`easeoff_dataset`.
    utca : xarray.Dataset
        Dims ``roll``, ``pair``, ``point``, ``path``, ``transition``, ``xyz``; see
        :func:`utca_dataset`.

    Raises
    ------
    InputError
        For out-of-range arguments (message names the field and range), or when no pair
        is in contact at some roll position.
    ModelUnavailableError
        For a roll-angle surface that cannot be contoured.

    Notes
    -----
    Seed §2.3.2.2: UTE of a pair = minimum of the ease-off along its contact curve; actual
    UTE = lower envelope over the pairs; the pattern of the reference tooth is bounded by
    the contact curves at M1 and M2 and by LPP and RPP (:func:`unloaded_cycle`,
    :func:`utca_dataset`).
    """
    _check_cycle_options(rolls_per_cycle, pairs, method, n_point)
    separation = positive("separation", separation, "mm")
    eo = easeoff if easeoff is not None else ease_off(case, flank=flank,
                                                      misalignment=misalignment, grid=grid)
    cycle = _memo_cycle(_Same(eo), rolls_per_cycle,
                        _check_cycle_options(rolls_per_cycle, pairs, method, n_point),
                        method, n_point, bool(curves))
    if not curves:
        return (easeoff_dataset(eo, case, misalignment=misalignment),
                ute_dataset(eo, cycle, case=case, separation=separation,
                            misalignment=misalignment))
    eo_ds, ds = _memo_datasets(_Same(eo), _Same(cycle), _Same(case), separation,
                               _Same(misalignment))
    # (each call its own datasets: a caller may add variables or attributes)
    return eo_ds.copy(deep=False), ds.copy(deep=False)


@memoised(maxsize=8)
def _memo_datasets(eo: _Same, cycle: _Same, case: _Same, separation: float,
                   misalignment: _Same) -> tuple[xr.Dataset, xr.Dataset]:
    """The ``/easeoff`` and ``/utca`` datasets (:func:`easeoff_dataset`,
    :func:`utca_dataset`) of the ease-off, unloaded cycle, case and misalignment objects
    and the separation: an analysis repeated with the same case object, whose ease-off and
    cycle are memoised, assembles them once (~2.5 ms of a warm analysis, issue 75);
    :func:`unloaded_tca` hands out shallow copies."""
    ds = utca_dataset(eo.obj, cycle.obj, case=case.obj, separation=separation,
                      misalignment=misalignment.obj)
    return easeoff_dataset(eo.obj, case.obj, misalignment=misalignment.obj), ds


_Same = Same  # an object as a memo key compared by identity (contact.utca.fields.Same)


@memoised(maxsize=8)
def _memo_cycle(eo: _Same, n_roll: int, pairs: tuple[int, ...], method: str,
                n_point: int, flank_fields: bool) -> UnloadedCycle:
    """:func:`unloaded_cycle` of the ease-off ``eo.obj``, memoised per process by the
    ease-off object itself (arrays read-only): the analyses of a torque series or an
    analysis repeated in one process share the memoised ease-off
    (:func:`contact.utca.easeoff.ease_off`), and so its unloaded cycle (seed §2.3.2.2),
    which depends on the ease-off alone. With and without the curves' flank fields
    (``flank_fields``) the cycles are two entries."""
    cycle = unloaded_cycle(eo.obj, n_roll=n_roll, pairs=pairs, method=method,
                           n_point=n_point, flank_fields=flank_fields)
    for a in (cycle.roll, cycle.pairs, cycle.envelope, *cycle.curves):
        if isinstance(a, np.ndarray):
            a.flags.writeable = False
    return cycle


def clear_cycle_memo() -> None:
    """Forget the unloaded cycles memoised per process by :func:`contact.utca.unloaded_tca`
    (frees memory; the next call computes afresh)."""
    _memo_cycle.cache_clear()
    _memo_datasets.cache_clear()


def _check_cycle_options(n_roll, pairs, method, n_point) -> tuple[int, ...]:
    """The options of :func:`unloaded_cycle` checked; the pairs as a tuple of int."""
    integer("rolls_per_cycle", n_roll, low=4)
    pairs = tuple(integer("pairs", k) for k in pairs)
    if not pairs or len(set(pairs)) != len(pairs) or 0 not in pairs:
        raise InputError(f"pairs: must be distinct integers including 0, got {pairs!r}")
    one_of("method", method, UTE_METHODS)
    integer("n_point", n_point, low=3)
    return pairs


def unloaded_cycle(eo: EaseOff, *, n_roll: int = 30, pairs=(-1, 0, 1),
                   method: str = "second_order", n_point: int = 41,
                   fields: EaseOffFields | None = None,
                   flank_fields: bool = True) -> UnloadedCycle:
    """The contact curves and UTE of the tooth pairs over one mesh cycle (seed §2.3.2.2).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    n_roll : int
        Roll positions over one mesh cycle (≥ 4), uniform from the transition M1 (the end
        point M2 = M1 + pitch excluded).
    pairs : sequence of int
        Distinct tooth-pair offsets including the reference pair 0.
    method : str
        ``"second_order"`` (default) or ``"seed"``, see :func:`contact_curves`.
    n_point : int
        Samples along each contact curve (≥ 3).
    fields : EaseOffFields, optional
        Pre-built splines of ``eo``.
    flank_fields : bool
        True (default): the curves with their flank points, normals and normal arms
        (what :func:`utca_dataset` reads). False: without them (``normal_arm``,
        ``position``, ``normal`` None; :func:`ute_dataset` reads none of them): the
        curves' places, ease-off and UTE are the same bit for bit (the same solve, the
        flank fields evaluated after it, :func:`contact.utca.contact_curves.contact_curves`).

    Returns
    -------
    UnloadedCycle

    Raises
    ------
    InputError
        For out-of-range arguments (message names the field and range), or when no pair
        is in contact at some roll position.
    ModelUnavailableError
        For a roll-angle surface that cannot be contoured.

    Notes
    -----
    Seed §2.3.2.2, Fig. 2.9: the actual UTE is the lower envelope of the pairs' UTE, the
    transitions M1, M2 (:func:`transitions`) are where it passes from one pair to the next.
    When adjacent pairs never cross (contact ratio below one) the cycle is centred on the
    reference pair's lowest UTE and M1, M2 are NaN.
    """
    pairs = _check_cycle_options(n_roll, pairs, method, n_point)
    f = fields if fields is not None else fields_of(eo)
    p = eo.pitch
    kw = dict(method=method, fields=f, n_point=n_point)
    m1, m2 = transitions(eo, **kw)
    start = _cycle_start(eo, m1, m2, kw)
    roll = start + p * np.arange(int(n_roll)) / int(n_roll)
    pk = np.array(pairs)
    targets = roll[:, None] - pk[None, :] * p
    # the reference pair at the transitions (the cycle's extremes) in the same batch as
    # the cycle's curves: one contact-curve evaluation instead of two (each curve is its
    # own; the batch changes the curve ends, found to 1e-9 of the face width, at
    # round-off: ~1e-16 rad of UTE)
    at = np.flatnonzero(np.isfinite([m1, m2]))
    tg = np.r_[targets.ravel(), np.array([m1, m2])[at]]
    if flank_fields:
        both = contact_curves(eo, tg, **kw)
    else:  # contact_curves' solve without its last step, the flank fields (issue 75)
        both = UTE_METHODS[method](f, tg, CURVE_SPACINGS["uniform"](int(n_point)),
                                   flank_fields=False)
    n = targets.size
    cc = ContactCurves(*(None if a is None else a[:n].reshape(targets.shape + a.shape[1:])
                         for a in both))
    envelope = np.min(np.where(np.isfinite(cc.ute), cc.ute, np.inf), axis=1)
    if not np.all(np.isfinite(envelope)):
        lost = roll[~np.isfinite(envelope)]
        raise InputError(f"case: no tooth pair in contact at roll {lost[0]:.6g} rad "
                         "(contact loss; check the misalignment)")
    # extremes of the actual UTE over the cycle: the refined minimum of the reference pair
    # and the values at the transitions (where the envelope peaks)
    te_min = _lowest_te(cc.ute[:, pairs.index(0)], envelope)
    te_tr = np.array([np.nan, np.nan])
    te_tr[at] = both.ute[n:]
    te_max = float(np.nanmax(np.r_[envelope, te_tr]))
    return UnloadedCycle(roll, pk, cc, envelope, (m1, m2), tuple(te_tr), (te_min, te_max),
                         method)


def _cycle_start(eo: EaseOff, m1: float, m2: float, kw: dict) -> float:
    """First roll [rad] of the cycle: M1, else M2 − pitch, else half a pitch before the
    reference pair's lowest UTE on a scan of Q (no transition found)."""
    p = eo.pitch
    if math.isfinite(m1):
        return m1
    if math.isfinite(m2):
        return m2 - p
    scan = np.linspace(0.0, float(np.nanmax(eo.roll_angle)), 65)
    u0 = pair_transmission_error(eo, scan, **kw)
    if not np.isfinite(u0).any():
        # no roll of the scan meets the flank's valid ease-off (a flank generated far from
        # conjugate: the face-hobbed 16x16 at Σ 60°'s coast flank on its generated gear,
        # its ease-off valid over 29 % of the grid and 54 mm at its largest): a named error,
        # not numpy's "All-NaN slice" (issue 71)
        raise InputError(
            f"case: the pinion {eo.pinion_flank} flank's reference pair is in contact at no "
            f"roll of 0 to {float(np.nanmax(eo.roll_angle)):.4g} rad (its ease-off valid over "
            f"{100.0 * float(np.mean(eo.valid)):.0f} % of the grid): the flank is far from "
            "conjugate to its mate; synthesise it again (other [synthesis] prescriptions)")
    start = float(scan[int(np.nanargmin(u0))]) - 0.5 * p
    log.warning("unloaded_tca: no transition between adjacent pairs found; the cycle is "
                "centred on the reference pair's lowest UTE")
    return start


def _lowest_te(u0: np.ndarray, envelope: np.ndarray) -> float:
    """Lowest actual UTE [rad]: the envelope's least sample, or the vertex of the parabola
    through the reference pair's lowest sample u0 (n_roll,) and its neighbours if lower."""
    te_min = float(envelope.min())
    i = int(np.nanargmin(u0))
    if 0 < i < len(u0) - 1 and np.all(np.isfinite(u0[i - 1:i + 2])):
        em, ec, ep = u0[i - 1], u0[i], u0[i + 1]
        den = em - 2.0 * ec + ep
        if den > 0:
            te_min = min(te_min, float(ec - 0.125 * (em - ep) ** 2 / den))
    return te_min


def utca_dataset(eo: EaseOff, cycle: UnloadedCycle, *, case: Case,
                 separation: float = DEFAULT_SEPARATION,
                 misalignment: Misalignment | None = None) -> xr.Dataset:
    """Assemble the ``/utca`` Dataset of a mesh cycle over (roll, pair).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    cycle : UnloadedCycle
        Contact curves and UTE over the cycle (:func:`unloaded_cycle`).
    case : geometry.case.Case
        The case (recorded in the attributes).
    separation : float — [mm]
        Separation bounding the unloaded contact line, > 0 (default 0.0063).
    misalignment : geometry.pair.assembly.Misalignment, optional
        The misalignment used (recorded in the attributes); defaults to the case's.

    Returns
    -------
    xarray.Dataset
        ``unloaded_transmission_error`` (roll) [µrad], ``pair_transmission_error``
        (roll, pair) [µrad], ``active`` (roll, pair), curve places ``curve_u``,
        ``curve_v``, ``curve_axial_position``, ``curve_radial_position`` and
        ``curve_position``/``curve_normal`` (gear frame), ``curve_ease_off`` [µrad],
        ``separation`` [µm] (normal gap to the actual gear position), ``contact_pattern``
        (roll, pair, point), ``contact_line_length`` [mm], the paths LPP/CPP/RPP
        (``path_u``, ``path_v``, ``path_axial_position``, ``path_radial_position``),
        ``transition_roll``/``transition_transmission_error`` (M1, M2) and
        ``peak_to_peak_transmission_error`` [µrad].

    Raises
    ------
    InputError
        For a separation that is not a finite length > 0.

    Notes
    -----
    Seed §2.3.2.2, Fig. 2.10: along each contact curve the stretch where the ease-off
    exceeds the pair's UTE by no more than ``separation`` is the unloaded contact line;
    its ends trace LPP and RPP, its contact point H the CPP.
    """
    separation = positive("separation", separation, "mm")
    mis = case.misalignment if misalignment is None else misalignment
    cc, envelope = cycle.curves, cycle.envelope
    te = cc.ute
    active = np.isfinite(te) & (te <= envelope[:, None] + 1e-15)
    zr = _plane_places(eo)
    gap = cc.ease_off_angle + cc.gap
    sep_env = cc.normal_arm * (gap - envelope[:, None, None])
    sep_own = cc.normal_arm * (gap - te[..., None])
    pattern, length, path_u, path_v = _contact_lines(cc, sep_own, separation, active)
    data = {
        **_ute_variables(envelope, te, active),
        **_curve_variables(cc, zr, sep_env, pattern),
        **_path_variables(cc, length, path_u, path_v, zr),
        **_cycle_variables(cycle, separation),
    }
    n_point = cc.u.shape[-1]
    # (xarray's Dataset of these tuples, made directly: issue 75)
    return dataset(data, _utca_coords(cycle, n_point), _utca_attrs(eo, case, mis, cycle.method))



def _ute_variables(envelope: np.ndarray, te: np.ndarray, active: np.ndarray) -> dict:
    """The UTE variables :func:`utca_dataset` and :func:`ute_dataset` share: the lower
    envelope (roll) and each pair's UTE (roll, pair) [rad → µrad], and the pairs carrying
    the motion (``active``, roll × pair booleans)."""
    return {
        "unloaded_transmission_error": _var(
            "roll", envelope * 1e6, "urad",
            "unloaded transmission error: lower envelope of the pairs (gear lag)"),
        "pair_transmission_error": _var(
            ("roll", "pair"), te * 1e6, "urad",
            "unloaded transmission error of each tooth pair (min of the ease-off on its "
            "contact curve; NaN out of mesh)"),
        "active": _var(("roll", "pair"), active.astype(np.int8), "1",
                       "1 where the pair carries the motion (its UTE is the lower envelope)",
                       **binary_flag("inactive", "active")),
    }

def ute_dataset(eo: EaseOff, cycle: UnloadedCycle, *, case: Case,
                separation: float = DEFAULT_SEPARATION,
                misalignment: Misalignment | None = None) -> xr.Dataset:
    """The ``/utca`` Dataset of a mesh cycle's UTE alone, without its contact curves.

    What a study point reads of the unloaded TCA (issue 75): its peak-to-peak UTE and the
    transitions the loaded TCA's cycle starts from. The variables are those of
    :func:`utca_dataset` of the same cycle, computed by the same lines (so the same values
    bit for bit), less those of the curves, lines and paths.

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    cycle : UnloadedCycle
        The cycle (:func:`unloaded_cycle`, with or without its flank fields: none is read).
    case : geometry.case.Case
        The case (recorded in the attributes).
    separation : float — [mm]
        Separation bounding the unloaded contact line, > 0 (recorded as
        ``separation_threshold``).
    misalignment : geometry.pair.assembly.Misalignment, optional
        The misalignment used (recorded in the attributes); defaults to the case's.

    Returns
    -------
    xarray.Dataset
        ``unloaded_transmission_error`` (roll) [µrad], ``pair_transmission_error``
        (roll, pair) [µrad], ``active`` (roll, pair), ``transition_roll`` [rad] and
        ``transition_transmission_error`` [µrad] (M1, M2), ``peak_to_peak_transmission_error``
        [µrad], ``separation_threshold`` [µm]; the attributes of :func:`utca_dataset`
        and ``curves`` = "not evaluated".

    Raises
    ------
    InputError
        For a separation that is not a finite length > 0.
    """
    separation = positive("separation", separation, "mm")
    mis = case.misalignment if misalignment is None else misalignment
    envelope, te = cycle.envelope, cycle.curves.ute
    active = np.isfinite(te) & (te <= envelope[:, None] + 1e-15)
    data = {
        **_ute_variables(envelope, te, active),
        **_cycle_variables(cycle, separation),
    }
    coords = {k: v for k, v in _utca_coords(cycle, 1).items()
              if k in ("roll", "pair", "transition")}
    attrs = {**_utca_attrs(eo, case, mis, cycle.method),
             "curves": "not evaluated (the UTE alone: contact.utca.datasets.ute_dataset)"}
    return dataset(data, coords, attrs)


def _plane_places(eo: EaseOff):
    """(u, v) → the gear projection-plane (z, ρ) [mm] by the grid's bilinear map (NaN where
    u or v is NaN)."""
    f_ax = RectBivariateSpline(eo.u, eo.v, eo.axial, kx=1, ky=1)
    f_rd = RectBivariateSpline(eo.u, eo.v, eo.radius, kx=1, ky=1)

    def zr(u, v):
        fin = np.isfinite(u) & np.isfinite(v)
        us, vs = np.where(fin, u, eo.u[0]), np.where(fin, v, eo.v[0])
        return (np.where(fin, f_ax.ev(us, vs), np.nan), np.where(fin, f_rd.ev(us, vs), np.nan))

    return zr


def _contact_lines(cc: ContactCurves, sep_own: np.ndarray, separation: float,
                   active: np.ndarray):
    """The unloaded contact line of each (roll, pair) curve: the stretch around H where the
    separation from the pair's own UTE ``sep_own`` (n_roll, n_pair, n_point) [mm] is within
    ``separation``.

    Returns
    -------
    pattern : int8 (n_roll, n_pair, n_point)
        1 on the line where the pair is active.
    length : (n_roll, n_pair) — [mm]
        Its length on the gear flank.
    path_u, path_v : (n_roll, n_pair, 3)
        LPP, CPP (the contact point H), RPP: the line's ends and H.
    """
    n_point = cc.u.shape[-1]
    s = sep_own - separation
    ok = np.isfinite(s) & (s <= 0)
    k = cc.index.astype(np.intp)
    kc = np.clip(k, 0, n_point - 1)[..., None]
    have = (k >= 0) & np.take_along_axis(ok, kc, -1)[..., 0]  # a stretch around H
    # the run of ok samples holding k, all curves at once (a walk from k either way):
    # lo after the last sample < k that is not ok, hi before the first one > k
    pos = np.arange(n_point)
    last_bad = np.maximum.accumulate(np.where(ok, -1, pos), axis=-1)
    first_bad = np.minimum.accumulate(np.where(ok, n_point, pos)[..., ::-1], axis=-1)[..., ::-1]
    lo = np.take_along_axis(last_bad, kc, -1)[..., 0] + 1
    hi = np.take_along_axis(first_bad, kc, -1)[..., 0] - 1
    lo, hi = np.where(have, lo, 0), np.where(have, hi, 0)

    def at(a, i):
        return np.take_along_axis(a, np.clip(i, 0, a.shape[-1] - 1)[..., None], -1)[..., 0]

    s_lo, s_hi = at(s, lo), at(s, hi)
    s_before, s_after = at(s, lo - 1), at(s, hi + 1)
    ext_lo = have & (lo > 0) & np.isfinite(s_before)
    ext_hi = have & (hi < n_point - 1) & np.isfinite(s_after)
    with np.errstate(invalid="ignore", divide="ignore"):
        flo = np.where(ext_lo, lo - (0.0 - s_lo) / (s_before - s_lo), lo.astype(float))
        fhi = np.where(ext_hi, hi + (0.0 - s_hi) / (s_after - s_hi), hi.astype(float))
    seg = np.linalg.norm(np.diff(cc.position, axis=-2), axis=-1)  # (..., n_point - 1)
    inner = (pos[:-1] >= lo[..., None]) & (pos[:-1] < hi[..., None])
    length = np.where(inner, seg, 0.0).sum(axis=-1)
    length = length + np.where(flo < lo, (lo - flo) * at(seg, lo - 1), 0.0)
    length = length + np.where(fhi > hi, (fhi - hi) * at(seg, hi), 0.0)
    length = np.where(have, length, 0.0)
    flo, fhi = np.where(have, flo, np.nan), np.where(have, fhi, np.nan)
    curve = k >= 0
    path_u = np.stack([_interp_at(cc.u, flo), np.where(curve, cc.contact_u, np.nan),
                       _interp_at(cc.u, fhi)], -1)
    path_v = np.stack([_interp_at(cc.v, flo), np.where(curve, cc.contact_v, np.nan),
                       _interp_at(cc.v, fhi)], -1)
    pattern = (ok & (curve & active)[..., None]).astype(np.int8)
    return pattern, length, path_u, path_v


def _curve_variables(cc: ContactCurves, zr, sep_env: np.ndarray, pattern: np.ndarray) -> dict:
    """The ``/utca`` variables along the contact curves (roll, pair, point)."""
    dims3 = ("roll", "pair", "point")
    cz, cr = zr(cc.u, cc.v)
    return {
        "curve_u": _var(dims3, cc.u, "1", "contact curve: gear lengthwise fraction"),
        "curve_v": _var(dims3, cc.v, "1", "contact curve: gear profile fraction"),
        "curve_axial_position": _var(dims3, cz, "mm",
                                     "contact curve: gear projection-plane axial position"),
        "curve_radial_position": _var(dims3, cr, "mm",
                                      "contact curve: gear projection-plane radius"),
        "curve_position": _var((*dims3, "xyz"), cc.position, "mm",
                               "contact curve point on the real gear flank (gear frame)"),
        "curve_normal": _var((*dims3, "xyz"), cc.normal, "1",
                             "real gear flank unit normal at the contact curve point"),
        "curve_normal_arm": _var(dims3, cc.normal_arm, "mm",
                                 "rho |n.e_theta| at the curve point: normal gap per radian "
                                 "of gear rotation"),
        "curve_ease_off": _var(dims3, cc.ease_off_angle * 1e6, "urad",
                               "angular ease-off along the contact curve"),
        "separation": _var(dims3, sep_env * 1e3, "um",
                           "unloaded separation along the gear normal from the gear at its "
                           "actual (lower-envelope) position"),
        "contact_pattern": _var(dims3, pattern, "1",
                                "1 where the pair is active and its separation is within "
                                "the threshold", **binary_flag("outside", "inside")),
    }


def _path_variables(cc: ContactCurves, length: np.ndarray, path_u: np.ndarray,
                    path_v: np.ndarray, zr) -> dict:
    """The ``/utca`` variables of the contact lines and point paths (roll, pair[, path])."""
    pz, pr = zr(path_u, path_v)
    dims = ("roll", "pair", "path")
    return {
        "contact_line_length": _var(("roll", "pair"), length, "mm",
                                    "unloaded contact line length (on the gear flank) within "
                                    "the separation of the pair's own UTE"),
        "contact_u": _var(("roll", "pair"), cc.contact_u, "1", "contact point H: gear u"),
        "contact_v": _var(("roll", "pair"), cc.contact_v, "1", "contact point H: gear v"),
        "path_u": _var(dims, path_u, "1", "LPP, CPP, RPP: gear lengthwise fraction"),
        "path_v": _var(dims, path_v, "1", "LPP, CPP, RPP: gear profile fraction"),
        "path_axial_position": _var(dims, pz, "mm",
                                    "LPP, CPP, RPP: gear projection-plane axial position"),
        "path_radial_position": _var(dims, pr, "mm",
                                     "LPP, CPP, RPP: gear projection-plane radius"),
    }


def _cycle_variables(cycle: UnloadedCycle, separation: float) -> dict:
    """The ``/utca`` variables of the whole cycle: transitions, peak-to-peak, threshold."""
    p2p = cycle.te_range[1] - cycle.te_range[0]
    return {
        "transition_roll": _var("transition", np.asarray(cycle.transitions, float), "rad",
                                "roll at which the motion passes to the next pair (M1: pair "
                                "-1 to 0, M2: pair 0 to +1)"),
        "transition_transmission_error": _var("transition",
                                              np.asarray(cycle.transition_te, float) * 1e6,
                                              "urad", "unloaded transmission error at M1, M2"),
        "peak_to_peak_transmission_error": _var((), p2p * 1e6, "urad",
                                                "peak-to-peak unloaded transmission error"),
        "separation_threshold": _var((), separation * 1e3, "um",
                                     "separation bounding the unloaded contact line"),
    }


def _utca_coords(cycle: UnloadedCycle, n_point: int) -> dict:
    """The ``/utca`` coordinates."""
    return {
        "roll": ("roll", np.asarray(cycle.roll, float),
                 {"units": "rad", "long_name": "pinion roll (value of Q, driving sense)"}),
        "pair": ("pair", np.asarray(cycle.pairs, dtype=np.int32),
                 {"units": "1", "long_name": "tooth pair offset: mesh cycles after pair 0"}),
        "point": ("point", np.arange(n_point, dtype=np.int32),
                  {"units": "1", "long_name": "sample along the contact curve, toe to heel"}),
        "path": ("path", np.array(["LPP", "CPP", "RPP"]),
                 {"long_name": "left (toe-side) bound, contact point path, right bound"}),
        "transition": ("transition", np.array(["M1", "M2"]),
                       {"long_name": "transition points of the lower envelope"}),
        "xyz": ("xyz", np.array(["x", "y", "z"]), {"long_name": "gear-frame component"}),
    }


def _utca_attrs(eo: EaseOff, case: Case, mis: Misalignment, method: str) -> dict:
    """The ``/utca`` attributes: senses and phases of the kinematics, inputs."""
    return {
        "title": f"{case.name}: unloaded tooth contact analysis (ease-off method)",
        "method": method,
        "case": case.name,
        "pinion_flank": eo.pinion_flank,
        "gear_flank": eo.gear_flank,
        "mesh_period": eo.pitch,
        "mesh_period_units": "rad",
        "roll_zero": eo.roll_zero,
        "roll_zero_units": "rad",
        "drive_sense": eo.drive_sense,
        "gear_phase": eo.gear_phase,
        "gear_phase_units": "rad",
        "ratio": eo.ratio,
        "kinematics": "pinion rotation = roll_zero + drive_sense * roll; ideal gear rotation = "
                      "gear_phase - pinion rotation / ratio; transmission error = gear lag",
        "misalignment": _misalignment_json(mis),
        "toolkit_version": __version__,
        "source": "contact.utca.unloaded_tca (seed 2.3.2.2, 4.4)",
        "inputs": case.to_toml(),
    }


def _misalignment_json(mis: Misalignment) -> str:
    """The misalignment as the JSON text of the datasets' ``misalignment`` attribute
    (:meth:`geometry.pair.assembly.Misalignment.labelled`: mm and deg)."""
    return json.dumps(mis.labelled())


def _interp_at(a, x):
    """Linear interpolation of arrays (..., n) at fractional indices x (...) along the last
    axis (NaN where x is NaN)."""
    n = a.shape[-1]
    fin = np.isfinite(x)
    i = np.minimum(np.maximum(np.floor(np.where(fin, x, 0.0)), 0), n - 2).astype(np.intp)
    t = x - i
    ai = np.take_along_axis(a, i[..., None], -1)[..., 0]
    an = np.take_along_axis(a, (i + 1)[..., None], -1)[..., 0]
    return np.where(fin, (1 - t) * ai + t * an, np.nan)


def easeoff_dataset(eo: EaseOff, case: Case, *,
                    misalignment: Misalignment | None = None) -> xr.Dataset:
    """The ``/easeoff`` Dataset (dims ``u``, ``v``, ``xyz``) with units and long names.

    Parameters
    ----------
    eo : EaseOff
        From :func:`ease_off`.
    case : geometry.case.Case
    misalignment : geometry.pair.assembly.Misalignment, optional
        The misalignment used (recorded in the attributes); defaults to the case's.

    Returns
    -------
    xarray.Dataset
        ``ease_off`` [µm] along the gear normal, ``ease_off_angle`` [µrad] (gear lag),
        ``roll_angle`` [rad] (Q), ``axial_position``/``radial_position`` [mm] (gear
        projection plane), ``mask`` and ``mask_reason``, the mating pinion point's
        projection-plane place, the real gear flank (``gear_position``, ``gear_normal``)
        ``normal_arm`` [mm] and ``gap_curvature`` [1/rad]; attributes with the senses,
        phases and inputs.
    """
    mis = case.misalignment if misalignment is None else misalignment
    coords = {
        "u": ("u", eo.u, {"units": "1", "long_name": "gear lengthwise fraction, toe 0 to heel 1"}),
        "v": ("v", eo.v, {"units": "1", "long_name": "gear profile fraction, root 0 to tip 1"}),
        "xyz": ("xyz", np.array(["x", "y", "z"]), {"long_name": "gear-frame component"}),
    }
    return dataset(_easeoff_variables(eo), coords, _easeoff_attrs(eo, case, mis))


def _easeoff_variables(eo: EaseOff) -> dict:
    """The ``/easeoff`` variables over the gear grid (u, v[, xyz])."""
    uv = ("u", "v")
    codes = np.array(sorted(EASEOFF_REASONS), dtype=np.int8)
    return {
        "ease_off": _var(uv, eo.ease_off * 1e3, "um",
                         "ease-off: real gear to touching conjugate of the pinion, along the "
                         "gear normal (>= 0: gap)"),
        "ease_off_angle": _var(uv, eo.ease_off_angle * 1e6, "urad",
                               "ease-off as gear lag about the gear axis (transmission error)"),
        "roll_angle": _var(uv, eo.roll_angle, "rad",
                           "surface of roll angle Q: pinion roll (driving sense) at which "
                           "the node is in contact, shifted to touch zero"),
        "axial_position": _var(uv, eo.axial, "mm", "gear projection-plane axial position"),
        "radial_position": _var(uv, eo.radius, "mm", "gear projection-plane radius"),
        "pinion_axial_position": _var(uv, eo.pinion_axial, "mm",
                                      "pinion projection-plane axial position of the mate"),
        "pinion_radial_position": _var(uv, eo.pinion_radius, "mm",
                                       "pinion projection-plane radius of the mate"),
        "pinion_u": _var(uv, eo.pinion_u, "1", "pinion lengthwise fraction of the mate"),
        "pinion_v": _var(uv, eo.pinion_v, "1", "pinion profile fraction of the mate"),
        "normal_arm": _var(uv, eo.normal_arm, "mm",
                           "rho |n.e_theta|: normal displacement per radian of gear rotation"),
        "gap_curvature": _var(uv, eo.gap_curvature, "1/rad",
                              "K: angular gap of the pinion to its conjugate at roll Q + t is "
                              "K t^2 / 2"),
        "gear_position": _var(("u", "v", "xyz"), eo.gear_position, "mm",
                              "real gear flank point in the gear frame"),
        "gear_normal": _var(("u", "v", "xyz"), eo.gear_normal, "1",
                            "real gear flank unit normal (out of the material)"),
        "placement_error": _var(uv, eo.placement_error, "mm",
                                "distance of the conjugate point from the node in the "
                                "projection plane"),
        "mask": _var(uv, eo.valid.astype(np.int8), "1",
                     "1 where the pinion can touch the real gear",
                     **binary_flag("masked", "valid")),
        "mask_reason": _var(uv, eo.reason.astype(np.int8), "1", "why a node is masked",
                            flag_values=codes,
                            flag_meanings=" ".join(EASEOFF_REASONS[int(c)] for c in codes)),
    }


def _easeoff_attrs(eo: EaseOff, case: Case, mis: Misalignment) -> dict:
    """The ``/easeoff`` attributes: senses and phases of the kinematics, inputs."""
    return {
        "title": f"{case.name}: ease-off and surface of roll angle",
        "case": case.name,
        "pinion_flank": eo.pinion_flank,
        "gear_flank": eo.gear_flank,
        "drive_sense": eo.drive_sense,
        "lag_sense": eo.lag_sense,
        "roll_zero": eo.roll_zero,
        "roll_zero_units": "rad",
        "gear_phase": eo.gear_phase,
        "gear_phase_units": "rad",
        "ratio": eo.ratio,
        "mesh_period": eo.pitch,
        "mesh_period_units": "rad",
        "kinematics": "pinion rotation = roll_zero + drive_sense * Q; ideal gear rotation = "
                      "gear_phase - pinion rotation / ratio (geometry.pair.assembly frames)",
        "misalignment": _misalignment_json(mis),
        "max_placement_error_mm": float(np.nanmax(eo.placement_error[eo.valid])),
        "toolkit_version": __version__,
        "source": "contact.utca.ease_off (seed Eq. 2.19-2.20, 4.1-4.2)",
        "inputs": case.to_toml(),
    }
