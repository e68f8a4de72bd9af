"""Tooth-root (fillet) stress of the loaded contact, from FE influence coefficients.

The LTCA gives, per torque and roll position, the normal forces F_i of the contact
segments (seed Eq. 3.12–3.14). Each member's FE influence coefficients
(:func:`contact.compliance.fe.influence_coefficients`: the stress tensor at the root
fillet points of the loaded tooth and its neighbours per unit normal load on the working
flank, docs/fe.md) give by linear superposition the stress in the fillets of every tooth
the loads reach (:mod:`contact.compliance.fe.superposition`):

    σ(tooth m, fillet point) = Σ_i F_i Σ_a N_a(p_i) S[a, m − k_i, fillet point],

with p_i the segment's contact point carried into the member's frame at the roll
position, k_i the tooth it lies on and N_a the bilinear hat weights of the load grid.
The **root stress** at a face station is the largest maximum principal stress over both
fillets of the tooth at that station — over their root points (``fillet_in_root``: the
half slot and the element rows up to the fillet's junction with the flank, not the flank
above, where a contact load's own stress lies) — (the tension side is the loaded flank's
fillet);
its peak over the mesh cycle, per torque and member, is ``root_stress_max``.

Each load is placed where it acts on the member (:func:`member_contact_points`): a pinion
tip edge's load on the gear at the foot of the gear flank's normal through the edge point,
on the pinion at the edge point, on the tip edge of its FE tooth. A loaded segment the FE
model cannot place — more than :data:`OFF_FLANK_LIMIT` off the working flank of its tooth
or :data:`GRID_LIMIT` outside the load grid (an edge contact past the model's face, a
deflection beyond its range) — never ends the analysis: if such segments carry at most
:data:`UNPLACED_SHARE` of the member's load at that torque they are left out (said in the
attribute ``left_out``), else the member's root stress at that torque is NaN and the
attribute ``not_computed`` of ``root_stress`` and ``root_stress_max`` says why (one
sentence per member and torque, logged as a warning too). Coefficients on which this
design's loaded contact curves do not lie (of another design) are refused.

Teeth are labelled by the LTCA's tooth-pair offset: tooth k of each member is the one in
pair k (the segment window of :func:`contact.ltca.segments.segment_geometry` repeats per
mesh cycle, so pair k is always the same tooth of the member frame at the cycle's roll
rotations). A tooth that carries no load at a roll still has the stress its loaded
neighbours cause through the rim.

Public functions
----------------
member_contact_points   the segments' contact points in a member's frame
root_stress             the ``root_stress`` variables of an ``/ltca`` dataset
prepare_coefficients    both members' coefficients built (or read) once, before a study
coefficients_cached     whether both members' coefficients are in the cache already
"""

from __future__ import annotations

import logging
import time
from typing import NamedTuple

import numpy as np
import scipy.sparse as sp
import xarray as xr

from contact.compliance.fe import FEOptions, locate_flank_points
from contact.compliance.fe.contact_compliance import pair_coefficients
from contact.compliance.fe.options import LEVEL_ACCURACY, case_fe_options, level_name
from contact.compliance.fe.superposition import GRID_TOLERANCE
from contact.ltca.segments import roll_phases
from contact.utca import EaseOff
from geometry.core.caches import Same, memoised
from geometry.core.conventions import data_var, dataset
from geometry.core.errors import InputError, LTCAError
from geometry.core.text import plain_number
from geometry.pair.assembly import case_transforms

__all__ = ["DESIGN_LIMIT", "FE_ACCURACY_ATTR", "FE_LEVEL_ATTR", "GRID_LIMIT",
           "LEFT_OUT_ATTR", "MEMBERS", "NOT_COMPUTED_ATTR", "OFF_FLANK_LIMIT",
           "UNPLACED_SHARE", "Unplaced", "coefficients_cached", "fe_level_note",
           "member_contact_points", "prepare_coefficients", "root_stress",
           "root_stress_notes", "slot_bottom_notes", "unplaced_reason"]

log = logging.getLogger(__name__)

#: [mm] largest distance (along the circumference) of a loaded segment's point from the
#: working flank of its tooth in a member's FE model, for its load to be placed there.
#: Only the point's projection-plane place (z, ρ) enters the hat weights: a point d off
#: the flank along the circumference is misplaced in (z, ρ) by d n_θ (1 − n_θ²)^½ ≤ d/2
#: (n_θ the flank normal's circumferential component), at this limit ≤ 0.25 mm, a third of
#: the smallest load-grid cell of the bundled cases' default models (0.7–1.7 mm up the
#: profile, 1.3–2.8 mm along the face). Moving *every* loaded point of the default case by
#: 0.25 mm in ρ changes the peak root stress by ≤ 2.2 % (50–500 N·m, both members), along
#: the face by ≤ 3.3 %, except the pinion's at 500 N·m, whose peak lies at a face end (12 %):
#: the error stays within the FE model's 5 % mesh convergence where the points are this
#: close. Loaded points that belong to the member lie much closer (measured, default case
#: drive and coast, ISO/TR 10300-30 sample 3 drive, 50–500 N·m): the gear's within 0.001 mm
#: (they are its flank points; a pinion edge's on the gear is the foot under it,
#: :func:`member_contact_points`), the pinion's within 0.17 mm (its mate differs by the
#: loaded approach, tens of µm along the normal, ~2× that along the circumference; a
#: pinion tip-edge point lies on its member's edge). Beyond it lie only a few gear
#: tip-edge points on the pinion (sample 3 at 500 N·m: up to 0.65 mm, 0.008 % of the
#: load), and the loads an FE model cannot place (an edge contact past its face, a
#: deflection beyond its range)
OFF_FLANK_LIMIT = 0.5
#: [1] how far (in face or profile fractions) a loaded point may lie outside the load grid
#: and take the grid boundary's weights (an end segment of a contact curve, an edge):
#: :data:`contact.compliance.fe.superposition.GRID_TOLERANCE`, 1.5 mm on a 30 mm face
GRID_LIMIT = GRID_TOLERANCE
#: [mm] the median distance from a member's FE flank of the loaded contact-curve points
#: above which the coefficients are refused as not of this design (an error, not NaN):
#: those points are the gear's flank points (≤ 0.001 mm off its FE flank) and their
#: pinion mates (≤ 0.17 mm, the loaded approach), while another design's flank lies
#: millimetres away (a tenth of a pitch is 1.3 mm on the default gear)
DESIGN_LIMIT = 1.0
#: [1] the largest share of a member's load at one torque (over all rolls) that loaded
#: segments the FE model cannot place may carry and be left out, the rest superposed (the
#: share stored: :data:`LEFT_OUT_ATTR`): leaving out a load share s lowers no fillet
#: stress by more than s times the ratio of the largest unit-load stress to the loads'
#: mean, ~3 on the default case, so ≤ 0.3 %. A larger share: the member's root stress at
#: that torque is NaN, the reason stored (:data:`NOT_COMPUTED_ATTR`)
UNPLACED_SHARE = 1e-3

#: the attribute of ``root_stress`` and ``root_stress_max`` that says, one sentence per
#: member and torque, why a torque's root stress is NaN (absent where all were computed)
NOT_COMPUTED_ATTR = "not_computed"
#: the attribute that says, one sentence per member and torque, which loads (at most
#: :data:`UNPLACED_SHARE` of them) the FE model could not place and left out
LEFT_OUT_ATTR = "left_out"
#: the attribute that says, one sentence per member, that its FE coefficients were built
#: and used from memory because the cache could not be written (issue 72)
CACHE_NOTE_ATTR = "fe_cache_not_written"
#: the attributes that name the FE level of a root stress computed on a named cheaper
#: model (:data:`contact.compliance.fe.options.LEVELS`: the case's ``[root_stress]
#: fe_level`` or the options given) and its stated accuracy against the default model;
#: absent for the default model
FE_LEVEL_ATTR = "fe_level"
FE_ACCURACY_ATTR = "fe_level_accuracy"

#: rows (pair, distinct loads) whose fillet stresses are superposed and reduced at once
ROW_BLOCK = 32

#: the member labels of the ``member`` dimension
MEMBERS = ("pinion", "gear")


def _roll_rotations(eo: EaseOff, roll: np.ndarray,
                    pairs=(0,)) -> tuple[np.ndarray, np.ndarray]:
    """(J,) pinion and gear rotations [rad] at the LTCA's roll positions (of its ``pairs``),
    as :func:`contact.ltca.segments.segment_geometry` sets them: periodic in the cycle, a
    roll whole cycles after another with its rotations (not ones differing by round-off,
    so the two have the same loads in the member frames, superposed once)."""
    _, rp, source = roll_phases(eo, roll, pairs)
    rp = rp[source]
    return rp, eo.gear_phase - rp / eo.ratio


def prepare_coefficients(case, flank: str | None = None, options=None, *,
                         progress: bool | str = True) -> dict[str, xr.Dataset]:
    """Both members' FE influence coefficients, built or read from the cache, once.

    A study (sweep, duty cycle) whose points all use one design calls this in the client
    before it dispatches the points and hands the coefficients to its workers with the
    shared inputs (scattered once per worker); each writes them into its own cache
    (:func:`contact.compliance.fe.prime_cache`), so no worker builds them, on a local
    cluster or on machines that share no cache directory (issue 53).

    Parameters
    ----------
    case : geometry.case.Case
    flank : str or None
        The working flank role or name, as :func:`contact.run_analysis` takes it.
    options : contact.compliance.fe.FEOptions, optional
        The FE model (default the case's level, ``[root_stress] fe_level``:
        :func:`contact.compliance.fe.options.case_fe_options`; ``FEOptions()`` where it
        names none).
    progress : bool
        A progress bar while unit loads are solved.

    Returns
    -------
    dict
        ``"pinion"``, ``"gear"`` → the coefficient datasets
        (:func:`contact.compliance.fe.influence_coefficients`).

    Raises
    ------
    InputError, LTCAError, ModelUnavailableError
        As :func:`contact.compliance.fe.influence_coefficients`; an unknown flank.
    """
    from contact.utca.easeoff import working_flanks

    flanks = dict(zip(MEMBERS, working_flanks(case, flank), strict=True))
    opt = options if options is not None else case_fe_options(case)
    return pair_coefficients(case, flanks, opt, progress=progress)


def coefficients_cached(case, flank: str | None = None, options=None, *,
                        cache_dir=None) -> bool:
    """Whether both members' FE influence coefficients of the analysed flanks are in the
    cache, so that the root stress adds only reading them and the superposition.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str or None — the working flank role or name, as :func:`contact.run_analysis`
        takes it
    options : contact.compliance.fe.FEOptions, optional — the FE model (default the
        case's level, :func:`contact.compliance.fe.options.case_fe_options`)
    cache_dir : path, optional — as :func:`contact.compliance.fe.influence_coefficients`

    Returns
    -------
    bool — True when both cache files exist (their contents are checked when read).

    Raises
    ------
    InputError — an unknown flank.
    """
    from contact.compliance.fe import cache_key, cache_path
    from contact.utca.easeoff import working_flanks

    opt = options if options is not None else case_fe_options(case)
    return all(cache_path(cache_key(case.member(m), f, opt), cache_dir).exists()
               for m, f in zip(MEMBERS, working_flanks(case, flank), strict=True))


def member_contact_points(case, easeoff: EaseOff, ltca: xr.Dataset) -> dict[str, np.ndarray]:
    """The LTCA segments' contact points in each member's frame.

    Parameters
    ----------
    case : geometry.case.Case — the case as analysed (its misalignment)
    easeoff : contact.utca.EaseOff — the analysis' ease-off
    ltca : xarray.Dataset — ``/ltca``: ``contact_point`` (roll, pair, segment, xyz) [mm]
        in the pair frame and the ``roll`` coordinate [rad]

    Returns
    -------
    dict — ``"pinion"``, ``"gear"``: ndarray (J, K, S, 3) [mm], NaN where a segment has
        no point

    Raises
    ------
    InputError — ``ltca`` lacks ``contact_point``.

    Notes
    -----
    ``contact_point`` is where the load acts on the member whose flank carries it: the
    gear's flank point on a contact curve, the gear's edge point x of a gear edge (on the
    pinion flank), and the pinion's edge point P of a pinion edge
    (:mod:`contact.ltca.edges`). A pinion edge presses on the gear flank at the foot g of
    the gear flank's normal through P, not at P (P lies the edge's gap off g along the
    normal: the loaded approach, ≤ 0.014 mm on the default case's coast flank at 500 N·m;
    up to ~0.8 mm at 250 N·m before issue 60's fix of the coast pinion edges' moment arms,
    which loaded open edges): the gear's
    point of such a segment is g (``segment_position``, on the reference gear tooth),
    turned by whole gear pitches onto P's tooth — the tip edge of the pinion's FE tooth
    takes P, the gear's FE flank takes g.
    """
    if "contact_point" not in ltca.variables:
        raise InputError("ltca: lacks contact_point (not an /ltca dataset)")
    p = ltca.variables["contact_point"].transpose("roll", "pair", "segment", "xyz").values
    rp, rg = _roll_rotations(easeoff, np.asarray(ltca.variables["roll"].values, float),
                             np.asarray(ltca.variables["pair"].values, int))
    out = {}
    for name, t in zip(MEMBERS, case_transforms(case, rp, rg), strict=True):
        rot, shift = t[:, :3, :3], t[:, :3, 3]
        # r_member = Rᵀ (r_pair − t), per roll: (r − t)ᵀ R as one batched product
        d = (p - shift[:, None, None, :]).reshape(p.shape[0], -1, 3)
        out[name] = np.matmul(d, rot).reshape(p.shape)
    edge = _pinion_edges(ltca)
    if edge is not None and edge.any():
        # (the pinion edges' segments alone: the same points, a fraction of the work)
        g = ltca.variables["segment_position"].transpose("roll", "pair", "segment", "xyz").values
        e = np.flatnonzero(edge)
        gear = out["gear"]  # (made above: this function's own array)
        gear[:, :, e] = _onto_tooth(g[:, :, e], gear[:, :, e],
                                    2 * np.pi / case.member("gear").blank.teeth)
    return out


def _pinion_edges(ltca: xr.Dataset) -> np.ndarray | None:
    """(S,) bool: the segments that are pinion edges (``segment_kind``), or None where the
    dataset does not say (no ``segment_kind`` or ``segment_position``)."""
    if "segment_kind" not in ltca.variables or "segment_position" not in ltca.variables:
        return None
    return np.asarray(ltca.variables["segment_kind"].values).astype(str) == "pinion_edge"


def _onto_tooth(ref: np.ndarray, near: np.ndarray, pitch: float) -> np.ndarray:
    """Points ``ref`` (..., 3) [mm] of a member's reference tooth turned about its axis (z)
    by the whole pitches [rad] that bring them nearest to the points ``near`` (..., 3)."""
    turn = pitch * np.rint((np.arctan2(near[..., 1], near[..., 0])
                            - np.arctan2(ref[..., 1], ref[..., 0])) / pitch)
    turn = np.nan_to_num(turn)
    c, s = np.cos(turn), np.sin(turn)
    return np.stack([c * ref[..., 0] - s * ref[..., 1], s * ref[..., 0] + c * ref[..., 1],
                     ref[..., 2]], axis=-1)


def _pair_teeth(coef: xr.Dataset, pts: np.ndarray, pairs: np.ndarray) -> np.ndarray:
    """(K,) the member-frame tooth offset of each pair's tooth, from its segments' points
    (J, K, S, 3); pairs without a point continue the neighbours' step."""
    finite = _finite_points(pts)
    tooth = np.empty(0, int)
    if finite.any():  # one location of every pair's points
        tooth = locate_flank_points(coef, pts[finite], strict=False).tooth
    return _teeth_of_pairs(tooth, np.nonzero(finite)[1], pairs)


def _distinct_rolls(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The first of each distinct roll's points (J, ...) (rolls whose points are equal bit
    for bit, NaN included, are one) and each roll's index among those firsts: ``pts[first]
    [roll_of]`` is ``pts``."""
    seen: dict[bytes, int] = {}
    roll_of = np.array([seen.setdefault(np.ascontiguousarray(r).tobytes(), len(seen))
                        for r in pts], dtype=int)
    first = np.unique(roll_of, return_index=True)[1]
    return first, roll_of


def _finite_points(pts: np.ndarray) -> np.ndarray:
    """(...) bool: the points (..., 3) whose three coordinates are finite (the same as
    ``np.all(np.isfinite(pts), axis=-1)``, whose reduction over an axis of three costs ten
    times as much)."""
    f = np.isfinite(pts)
    return f[..., 0] & f[..., 1] & f[..., 2]


def _teeth_of_pairs(tooth: np.ndarray, pair_index: np.ndarray,
                    pairs: np.ndarray) -> np.ndarray:
    """(K,) the member-frame tooth offset of each pair: the most frequent tooth of its
    located points (``tooth`` (N,), their pair's index ``pair_index`` (N,)); pairs without
    a point continue the neighbours' step."""
    teeth = np.full(pairs.size, np.nan)
    for k in np.unique(pair_index):
        t = tooth[pair_index == k]
        teeth[k] = np.bincount(t - t.min()).argmax() + t.min()
    known = np.flatnonzero(np.isfinite(teeth))
    if known.size == 0:
        raise InputError("ltca: no segment has a contact point; no root stress")
    step = 1.0
    if known.size > 1:
        step = float(np.sign(np.polyfit(pairs[known], teeth[known], 1)[0])) or 1.0
    k0 = known[0]
    fill = teeth[k0] + step * (pairs - pairs[k0])
    return np.where(np.isfinite(teeth), teeth, fill).astype(int)


def _unique_rows(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct rows of a 2-D array (in order of first appearance) and each row's
    index among them, by exact equality of the rows' bytes (``numpy.unique(axis=0)``
    sorts the rows as structured records, several times slower)."""
    first: dict[bytes, int] = {}
    inverse = np.array([first.setdefault(row.tobytes(), len(first)) for row in a], dtype=int)
    _, row = np.unique(inverse, return_index=True)
    return a[row], inverse


class Unplaced(NamedTuple):
    """The loaded segments of one torque that a member's FE model cannot place.

    segments : int — how many; share : float — [1] their share of the member's load at
    that torque (the sum of their forces over all forces, all rolls); distance : float —
    [mm] the largest distance of one from the working flank of its tooth; outside : float —
    [1] the largest face or profile fraction by which one lies outside the load grid;
    kinds : tuple of str — their ``segment_kind`` (``"curve"``, ``"gear_tip"`` …)
    """

    segments: int
    share: float
    distance: float
    outside: float
    kinds: tuple


def _grid_excess(coef: xr.Dataset, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """[1] how far points at fractions (u, v) lie outside the coefficients' load grid (the
    larger of the face and the profile excess; 0 inside)."""
    gu, gv = coef.variables["u"].values, coef.variables["v"].values
    return np.maximum.reduce([gu[0] - u, u - gu[-1], gv[0] - v, v - gv[-1],
                              np.zeros_like(u)])


def _check_design(coef: xr.Dataset, distance: np.ndarray, excess: np.ndarray,
                  curve: np.ndarray) -> None:
    """Refuse coefficients that are not of the analysed design: the loaded contact-curve
    segments (``curve``, all loaded segments where none is a curve's), which lie on the
    member's flank and inside the load grid for the design the coefficients are of, lie
    more than :data:`DESIGN_LIMIT` off it or :data:`GRID_LIMIT` outside it at their
    median."""
    sel = curve if curve.any() else np.ones_like(curve)
    d, e = float(np.median(np.abs(distance[sel]))), float(np.median(excess[sel]))
    if d > DESIGN_LIMIT or e > GRID_LIMIT:
        member = coef.attrs.get("member", "member")
        raise InputError(
            f"coefficients: the {member}'s loaded contact lies a median {d:.3g} mm off its "
            f"working flank ({e:.3g} outside the load grid) in the FE model of case "
            f"{coef.attrs.get('case', '?')!r} (at most {DESIGN_LIMIT:g} mm, {GRID_LIMIT:g}): "
            "the coefficients are not of this design")


def _member_stress(coef: xr.Dataset, pts: np.ndarray, force: np.ndarray,
                   pairs: np.ndarray, kinds: np.ndarray | None = None
                   ) -> tuple[np.ndarray, dict[int, Unplaced]]:
    """(NT, J, K, station) [MPa] root stress of one member: forces (NT, J, K, S) [N],
    points (J, K, S, 3) [mm] in its frame, segment kinds (S,) (default all curves); and
    the torques (their index) whose loaded segments the FE model cannot place, with what
    it could not place: their stress is NaN.

    The points are located on the flank once for all torques; each (torque, roll)'s
    forces become hat loads per loaded tooth, the distinct ones kept once (rolls whole
    mesh cycles apart); one sparse product of the (pair, distinct loads) rows with the
    coefficients S[a, d] gives every pair's fillet stress tensors, reduced block by block
    to the largest maximum principal stress over the root points (docs/fe.md, "Root
    stress in the analysis", for the cost). A loaded segment more than
    :data:`OFF_FLANK_LIMIT` off the flank or :data:`GRID_LIMIT` outside the load grid
    makes its torque's stress NaN; coefficients on which the loaded curves themselves do
    not lie are refused (:func:`_check_design`).
    """
    nt, nj, nk, ns = force.shape
    kinds = np.full(ns, "curve") if kinds is None else np.asarray(kinds).astype(str)
    # the variable, not a DataArray: its many coordinates cost more than the transpose
    s = coef.variables["fillet_stress"].transpose("load_u", "load_v", "tooth", "side",
                                                  "station", "arc", "component")
    offsets = np.asarray(coef.variables["tooth"].values, int)
    nl = s.sizes["load_u"] * s.sizes["load_v"]
    # every segment point located once, for the pairs' teeth and the loads of all torques:
    # the points of the distinct rolls alone (a roll whole mesh cycles after another has
    # its points, bit for bit: _roll_rotations), each roll's taken from its first
    first, roll_of = _distinct_rolls(pts)
    finite_u = _finite_points(pts[first])  # (J', K, S)
    point_u = np.full(finite_u.shape, -1)
    point_u[finite_u] = np.arange(np.count_nonzero(finite_u))
    point = point_u[roll_of]  # (J, K, S): each point's index among the located ones
    finite = point >= 0
    fp = locate_flank_points(coef, pts[first][finite_u], strict=False) \
        if finite_u.any() else None
    tooth_of_pair = _teeth_of_pairs(fp.tooth[point[finite]] if fp is not None
                                    else np.empty(0, int), np.nonzero(finite)[1], pairs)
    f = np.nan_to_num(force)
    t, j, k, m = np.nonzero(f > 0)  # the loaded segments of every torque
    out = np.zeros((nt, nj, nk, s.sizes["station"]))
    if not t.size:
        return out, {}
    p = point[j, k, m]
    if np.any(p < 0):
        raise InputError("ltca: a loaded segment has no contact point")
    # the contact points are where the load acts on the member whose flank carries it
    # (member_contact_points): the mate's differs by the loaded approach, an edge's lies
    # on the flank's boundary; located leniently, then checked (OFF_FLANK_LIMIT)
    dist = np.abs(fp.distance[p])
    excess = _grid_excess(coef, fp.u[p], fp.v[p])
    _check_design(coef, dist, excess, kinds[m] == "curve")
    bad = (dist > OFF_FLANK_LIMIT) | (excess > GRID_LIMIT)
    unplaced: dict[int, Unplaced] = {}
    for ti in np.unique(t[bad]):
        sel = bad & (t == ti)
        unplaced[int(ti)] = Unplaced(int(sel.sum()),
                                     float(f[t[sel], j[sel], k[sel], m[sel]].sum()
                                           / f[ti].sum()),
                                     float(dist[sel].max()), float(excess[sel].max()),
                                     tuple(sorted(set(kinds[m[sel]]))))
    # a torque's few unplaced loads are left out; with more, its stress is NaN
    nan_t = [ti for ti, u in unplaced.items() if u.share > UNPLACED_SHARE]
    keep = ~(bad | np.isin(t, nan_t))
    t, j, k, m, p = t[keep], j[keep], k[keep], m[keep], p[keep]
    out[nan_t] = np.nan
    if not t.size:
        return out, unplaced
    # hat loads [N] per (torque, roll, loaded tooth of the member frame, grid node)
    teeth = np.unique(fp.tooth[p])
    rows = (t * nj + j) * teeth.size + np.searchsorted(teeth, fp.tooth[p])
    gather = sp.csr_matrix((f[t, j, k, m], (rows, p)),
                           shape=(nt * nj * teeth.size, fp.tooth.size))
    hat = (gather @ fp.weights).toarray().reshape(nt * nj, teeth.size * nl)
    # rolls whole mesh cycles apart (and torques) with the same loads are superposed once
    hat, inverse = _unique_rows(hat)
    nu = hat.shape[0]
    # one sparse product for every (pair, distinct loads): row kk nu + r holds the hat
    # loads of the tooth d teeth before pair kk's in columns (a, d) of S[a, d, ...]; a
    # roll's loads reach only the grid nodes near its contact lines
    r, src, a = np.nonzero(hat.reshape(nu, teeth.size, nl))
    load = hat.reshape(nu, teeth.size, nl)[r, src, a]
    lr, lc, lv = [np.empty(0, int)], [np.empty(0, int)], [np.empty(0)]
    for kk in range(nk):
        for i, d in enumerate(offsets):
            at = np.searchsorted(teeth, tooth_of_pair[kk] - d)
            if at < teeth.size and teeth[at] == tooth_of_pair[kk] - d:
                sel = src == at
                lr.append(kk * nu + r[sel])
                lc.append(a[sel] * offsets.size + i)
                lv.append(load[sel])
    rows_of = np.concatenate(lr)
    # a row without loads (a pair the loads' neighbours do not reach) has no stress
    reached, row = np.unique(rows_of, return_inverse=True)
    # column-major: each coefficient row S[a, d] read once from memory (the 20–30 MB of
    # a member's coefficients do not stay in the cache), the same sums in the same order
    # as the row-major product (for each output, its loads by increasing column)
    loads = sp.csc_matrix((np.concatenate(lv), (row, np.concatenate(lc))),
                          shape=(reached.size, nl * offsets.size))
    # the coefficients' columns at the root points alone, component-major (the flank
    # above the fillet, whose stress the peak leaves out, is never superposed)
    lay = _root_layout(Same(coef))
    smax = np.broadcast_to(np.where(lay.has_root, 0.0, -np.inf),
                           (nk * nu, lay.has_root.size)).copy()
    tensor = (loads @ lay.stress).reshape(reached.size, 6, -1)  # [MPa]
    for r0 in range(0, reached.size, ROW_BLOCK):  # a block's temporaries stay in the cache
        block = slice(r0, r0 + ROW_BLOCK)
        # the largest over the sides and the fillet arc
        smax[reached[block]] = _root_peak_of(tensor[block], lay)
    done = np.ones(nt, bool)
    done[nan_t] = False
    out[done] = smax.reshape(nk, nu, -1)[:, inverse].swapaxes(0, 1).reshape(
        -1, nj, nk, out.shape[-1])[done]
    return out, unplaced


def unplaced_reason(member: str, torque: float, unplaced: Unplaced) -> str:
    """One sentence: which loads of ``member`` at ``torque`` [N·m] its FE model could not
    place, and whether its root stress there is NaN (their share above
    :data:`UNPLACED_SHARE`) or computed without them."""
    where = []
    if unplaced.distance > OFF_FLANK_LIMIT:
        where.append(f"up to {unplaced.distance:.3g} mm off its working flank (at most "
                     f"{OFF_FLANK_LIMIT:g} mm)")
    if unplaced.outside > GRID_LIMIT:
        where.append(f"up to {unplaced.outside:.3g} of the face or depth outside the load "
                     f"grid (at most {GRID_LIMIT:g})")
    n = unplaced.segments
    what = (f"{n} loaded segment{'s' if n != 1 else ''} ({', '.join(unplaced.kinds)}; "
            f"{100 * unplaced.share:.2g} % of the load over the mesh cycle) lie "
            f"{' and '.join(where)} in the FE model, which cannot place their load")
    if unplaced.share > UNPLACED_SHARE:
        return f"{member} at {plain_number(torque)} N m: not computed (NaN): {what}."
    return (f"{member} at {plain_number(torque)} N m: {what}; left out (at most "
            f"{100 * UNPLACED_SHARE:g} % of the load may be).")


def root_stress_notes(ltca: xr.Dataset) -> list[str]:
    """Why a member's root stress at a torque is NaN, which loads its FE model could not
    place and left out, and whose FE coefficients were used from memory because the cache
    could not be written: the lines of the ``not_computed``, ``left_out`` and
    ``fe_cache_not_written`` attributes of ``root_stress_max`` (:func:`root_stress`), each
    prefixed ``"root stress: "``, as ``ltca run`` prints them under its table.

    Parameters
    ----------
    ltca : xarray.Dataset — ``/ltca`` with ``root_stress_max``

    Returns
    -------
    list of str — one sentence per member and torque; empty when every value was computed
        from every load (or the dataset has no root stress)
    """
    if "root_stress_max" not in ltca.variables:
        return []
    attrs = ltca["root_stress_max"].attrs
    return [f"root stress: {line}"
            for attr in (NOT_COMPUTED_ATTR, LEFT_OUT_ATTR, CACHE_NOTE_ATTR)
            for line in str(attrs.get(attr, "")).splitlines() if line]


@memoised(maxsize=16)
def _coefficients_level(*options: str) -> str | None:
    """The level (:data:`contact.compliance.fe.options.LEVELS`) of the FE model whose
    coefficients carry these ``options`` attributes (``FEOptions.to_json``), one per member:
    the coefficients used, whether built here, read from the cache or given (a study's,
    a duty cycle's); None where the members' models differ, are no named level or do not
    say."""
    import json

    try:
        names = {level_name(FEOptions(**json.loads(text))) for text in options}
    except (ValueError, TypeError, InputError):
        return None
    return names.pop() if len(names) == 1 else None


def fe_level_note(ltca: xr.Dataset) -> str | None:
    """The sentence that names the FE level of a root stress on a named cheaper model and
    its stated accuracy (the ``fe_level`` and ``fe_level_accuracy`` attributes of
    ``root_stress_max``, :func:`root_stress`), as ``ltca run``, the file's summary and the
    verdict say it; None for the default model (or no root stress).

    Parameters
    ----------
    ltca : xarray.Dataset — ``/ltca``

    Returns
    -------
    str or None — e.g. ``"root stress: FE coarse10 level (−1.0 … +7.1 % against the
        default mesh, docs/fe.md)"``
    """
    if "root_stress_max" not in ltca.variables:
        return None
    attrs = ltca.variables["root_stress_max"].attrs
    level = attrs.get(FE_LEVEL_ATTR)
    if not level:
        return None
    return (f"root stress: FE {level} level ({attrs.get(FE_ACCURACY_ATTR, '')}, docs/fe.md; "
            "`ltca run --fe-level default` gives the default model)")


#: the end of a slot bottom's kind (:attr:`contact.compliance.fe.section.ToothSections.
#: kinds`) where the FE model rounds the two cuts' crossing by step 2's small arc
NOTCHED_KIND = ", rounded into a fillet"


def slot_bottom_notes(case, ltca: xr.Dataset, flank: str = "drive",
                      slot_bottom: str | None = None) -> list[str]:
    """Where a member's peak root stress lies at a slot bottom that the FE model rounds
    into a fillet: one line per such member, as ``ltca run`` prints under its table.

    Where a pinion's flanks are cut separately, the FE model's slot bottom is the two cuts'
    crossing (:mod:`contact.compliance.fe.section`); where one cut's tip crosses the other
    side's fillet near its top, the crossing is rounded by at most a tenth of the blade's
    edge radius (kind "…, rounded into a fillet"), a notch whose stress that radius sets —
    the model's reading of the two cuts, not case data. The machine leaves the union of
    the cuts, in which the crossed fillet stays whole: on the spiral bevels 15×28 at
    Σ 110° β_m 43.9° and 25×36 at Σ 75° the coast pinion's peak lay there at 1.5–1.9 ×
    ISO 10300's σ_F, 0.65–0.86 × with the other tip plane moved below the fillet's top,
    the flanks and loads the same (docs/fe.md, "The coast design torque of two spiral
    bevels").

    Parameters
    ----------
    case : geometry.case.Case — the case analysed
    ltca : xarray.Dataset — ``/ltca`` with ``root_stress`` (torque, roll, member, tooth,
        fillet_point) [MPa] and its coordinate ``fillet_u`` (member, fillet_point) [1]
    flank : str — the pinion flank analysed: ``"drive"`` (default), ``"coast"`` or a flank
        name (:func:`contact.compliance.fe.options.member_flank`). Only a fillet of a
        member's loaded flank counts (the tension side of its loaded tooth): the other
        fillet's rounding does not set that member's peak
    slot_bottom : str, optional — the FE model's slot-bottom rule (``FEOptions.
        slot_bottom``) the root stress was computed with (default: ``FEOptions()``'s):
        ``"edge_radius"`` rounds every crossing by the edge radius (no step-2 notch), so
        no line is said

    Returns
    -------
    list of str — per member whose peak (over rolls and teeth, at any torque) lies at a
        face station whose slot bottom, or a neighbouring station's, is rounded into a
        fillet of its loaded flank (where step 2 hands over to step 1 the kinds may
        alternate between neighbours, step 1's radius there barely above step 2's): one
        sentence prefixed
        ``"root stress: "`` with the torques [N·m], the station u [1], the span of such
        stations and the edge radius [mm]; empty otherwise, without root stress, or for
        a member cut in one setting (a straight slot bottom)

    Raises
    ------
    InputError — a bad ``flank``; a case whose member lacks a blade edge radius (as
        :func:`contact.compliance.fe.section.tooth_sections`; its FE model could not have
        been built). A section the generated flanks cannot make (LTCAError) gives no line
        and a logged warning.

    Notes
    -----
    The sections are computed again at the FE model's face stations (~0.4 s CPU per
    separately cut member). Source: the slot-bottom rules of :mod:`contact.compliance.fe.section`.
    """
    from contact.compliance.fe.options import FEOptions, member_flank
    from contact.compliance.fe.section import tooth_sections

    if slot_bottom is None:
        slot_bottom = FEOptions().slot_bottom
    loaded = {m: member_flank(case, m, flank) for m in MEMBERS}
    if "root_stress" not in ltca.variables or slot_bottom == "edge_radius":
        return []
    rs = ltca["root_stress"]
    torques = np.asarray(ltca["torque"].values, float)
    lines = []
    for member in MEMBERS:
        mem = case.member(member)
        if mem.concave.machine == mem.convex.machine:
            continue  # one cut: the bottom is straight between the fillets
        face = rs.sel(member=member).max(("roll", "tooth")).transpose("torque", ...).values
        fu = np.asarray(ltca["fillet_u"].sel(member=member).values, float)
        peaks: dict[int, list[float]] = {}
        for i, row in enumerate(face):
            if np.isfinite(row).any():
                peaks.setdefault(int(np.nanargmax(row)), []).append(float(torques[i]))
        if not peaks:
            continue
        u, where = np.unique(np.clip(fu, 0.0, 1.0), return_inverse=True)
        if u.size < 2:
            continue
        try:
            secs = tooth_sections(case, member, u)
        except LTCAError as exc:
            log.warning("root stress: the %s's slot bottoms not checked: %s", member, exc)
            continue
        # step 2's arc at the fillet of the loaded flank: the side cut within its fillet
        # (its first generated sample above the cut: s > 0), not along its blade's tip
        notched = np.array([k.endswith(NOTCHED_KIND) and _crossed(sec, loaded[member])
                            for k, sec in zip(secs.kinds, secs.sections, strict=True)])
        # at the station or a neighbour: where step 2 hands over to step 1 the kinds may
        # alternate between neighbouring stations, step 1's radius there barely above
        # step 2's (the 25×36 at Σ 75°)
        hit = {k: t for k, t in peaks.items()
               if notched[max(where[k] - 1, 0):where[k] + 2].any()}
        if not hit:
            continue
        edge = min(secs.edge_radius.values())
        at = "; ".join(f"{', '.join(f'{plain_number(t)}' for t in ts)} N m at u {fu[k]:.2f}"
                       for k, ts in sorted(hit.items()))
        lines.append(
            f"root stress: the {member}'s peak ({at}) lies where the FE model rounds its slot "
            f"bottom into a fillet (u {u[notched].min():.2f}-{u[notched].max():.2f}: the "
            f"other cut's blade tip crosses the fillet near its top, and the crossing is "
            f"rounded by about a tenth of the edge radius {edge:.3g} mm, the model's "
            f"reading of the two cuts, not case data): that radius sets the value, up to "
            f"2.8 x the whole fillet's on two spiral bevels, so read it as an upper bound "
            f"(docs/fe.md, 'The coast design torque of two spiral bevels')")
    return lines


def _crossed(section, flank: str) -> bool:
    """Whether ``flank``'s side of a section is cut within its fillet at the slot bottom
    (the other cut's tip crosses it), not along its own blade's tip line: its first
    generated sample above the cut has a blade arc length s > 0."""
    side = section.left if section.left.flank == flank else section.right
    s = side.s[np.isfinite(side.s)]
    return bool(s.size and s[0] > 0.0)


def root_points(coef: xr.Dataset) -> np.ndarray:
    """(side, station, arc) bool: the fillet points of a member's coefficients that lie in
    the root (``fillet_in_root``: the half slot and the element rows up to the fillet's
    junction with the flank, the same on every tooth), over which the root stress is the
    largest."""
    return coef.variables["fillet_in_root"].isel(tooth=0).transpose(
        "side", "station", "arc").values.astype(bool)


class RootLayout(NamedTuple):
    """The root points of a member's coefficients, as the superposition takes them.

    stress : ndarray (nl · nd, 6 · P), read-only — [MPa per N] the fillet stress
    coefficients S[a, d] at the P root points alone, component-major (Voigt order), the
    points ordered by face station, then side and fillet arc; station : (P,) int — each
    point's face station; starts : (M,) int — where each of the M stations with root points
    begins among the P; has_root : (station,) bool — the stations with root points;
    slot : (P,) int — each point's station among the M.
    """

    stress: np.ndarray
    station: np.ndarray
    starts: np.ndarray
    has_root: np.ndarray
    slot: np.ndarray


def _layout_of(root: np.ndarray) -> tuple[np.ndarray, ...]:
    """(order, station, starts, has_root, slot) of root points ``root`` (side, station,
    arc): ``order`` the flat (side, station, arc) indices of the root points ordered by
    station, then side and arc; the others as in :class:`RootLayout`."""
    by_station = np.moveaxis(root, 1, 0)  # (station, side, arc)
    st, side, arc = np.nonzero(by_station)
    order = np.ravel_multi_index((side, st, arc), root.shape)
    has_root = by_station.any(axis=(1, 2))
    starts = np.searchsorted(st, np.flatnonzero(has_root))
    slot = np.searchsorted(starts, np.arange(st.size), side="right") - 1
    return order, st, starts, has_root, slot


@memoised(maxsize=4)
def _root_layout(coef: Same) -> RootLayout:
    """The :class:`RootLayout` of a member's coefficients ``coef.obj``, made once per
    process and coefficients (the coefficient files are read once per process,
    :func:`contact.compliance.fe.contact_compliance.pair_coefficients`): a gather of their
    root points' columns (~80 % of them, 30 MB on the default pinion) that every analysis
    of the design would otherwise repeat or superpose at the flank points above the
    fillet too."""
    ds = coef.obj
    s = ds.variables["fillet_stress"].transpose("load_u", "load_v", "tooth", "side",
                                                "station", "arc", "component").values
    order, station, starts, has_root, slot = _layout_of(root_points(ds))
    rows = s.shape[0] * s.shape[1] * s.shape[2]  # (load_u, load_v, tooth)
    stress = s.reshape(rows, -1, 6)[:, order, :]  # (row, root point, component)
    stress = np.ascontiguousarray(stress.transpose(0, 2, 1)).reshape(rows, -1)
    stress.flags.writeable = False
    return RootLayout(stress, station, starts, has_root, slot)


def _root_peak(t: np.ndarray, root: np.ndarray) -> np.ndarray:
    """(R, station) [MPa] the largest maximum principal stress over the sides and the
    fillet arc of stresses ``t`` (R, side, station, arc, 6) in Voigt order, over the root
    points ``root`` (side, station, arc) alone; −inf at a station without root points
    (:func:`_root_peak_of` on the root points' stresses)."""
    order, *layout = _layout_of(root)
    flat = t.reshape(t.shape[0], -1, 6)[:, order, :].transpose(0, 2, 1)
    return _root_peak_of(flat, RootLayout(np.empty((0, 0)), *layout))


def _root_peak_of(t: np.ndarray, lay: RootLayout) -> np.ndarray:
    """(R, station) [MPa] the largest maximum principal stress over the root points of
    each face station, of stresses ``t`` (R, 6, P) [MPa] in Voigt order at the root points
    of ``lay``; −inf at a station without root points.

    The same values as the largest of :func:`_max_principal` over all root points: with
    q the mean stress and p the deviator's scale of Smith's closed form, every principal
    value lies in [q − 2p, q + 2p] and the largest in [q + p, q + 2p] (its angle φ/3 ∈
    [0, π/3]); a point whose q + 2p is below the largest q + p of its station cannot be
    the station's largest, so the closed form's angles are evaluated only at the others
    (a margin of 1e-9 of the values keeps round-off from dropping the largest).
    """
    xx, yy, zz, yz, xz, xy = (t[:, i] for i in range(6))
    q = (xx + yy + zz) / 3.0
    a, b, c = xx - q, yy - q, zz - q
    p = np.sqrt((a * a + b * b + c * c + 2.0 * (yz ** 2 + xz ** 2 + xy ** 2)) / 6.0)
    out = np.full((t.shape[0], lay.has_root.size), -np.inf)
    if not lay.station.size:
        return out
    low = np.maximum.reduceat(q + p, lay.starts, axis=1)[:, lay.slot]
    high = q + 2.0 * p
    cand = high + 1e-9 * (np.abs(high) + np.abs(low)) >= low
    peak = np.full(q.shape, -np.inf)
    peak[cand] = _max_principal_of(xx[cand], yy[cand], zz[cand], yz[cand], xz[cand],
                                   xy[cand])
    out[:, lay.has_root] = np.maximum.reduceat(peak, lay.starts, axis=1)
    return out


def _max_principal(t: np.ndarray) -> np.ndarray:
    """Largest principal value [MPa] of stresses in Voigt order (..., 6) (xx, yy, zz, yz,
    xz, xy): the closed form of the symmetric 3 × 3 eigenproblem (Smith, Comm. ACM 4
    (1961) 168), ~7× faster than ``numpy.linalg.eigvalsh`` on many small tensors (measured:
    0.03 s against 0.20 s CPU for 200 000) and
    equal to it within ~1e-10 of the tensor's norm (tests/test_root_stress.py)."""
    return _max_principal_of(*(t[..., i] for i in range(6)))


def _max_principal_of(xx, yy, zz, yz, xz, xy) -> np.ndarray:
    """:func:`_max_principal` of the six components [MPa] given apart (equal shapes)."""
    q = (xx + yy + zz) / 3.0
    a, b, c = xx - q, yy - q, zz - q
    p1 = yz ** 2 + xz ** 2 + xy ** 2
    p = np.sqrt((a * a + b * b + c * c + 2.0 * p1) / 6.0)
    safe = np.where(p > 0, p, 1.0)
    a, b, c = a / safe, b / safe, c / safe
    yz, xz, xy = yz / safe, xz / safe, xy / safe
    det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz)
    phi = np.arccos(np.clip(0.5 * det, -1.0, 1.0)) / 3.0
    return np.where(p > 0, q + 2.0 * p * np.cos(phi), q)


def root_stress(case, easeoff: EaseOff, ltca: xr.Dataset,
                options: FEOptions | None = None, *,
                coefficients: dict[str, xr.Dataset] | None = None, cache: bool = True,
                cache_dir=None, progress: bool | str = False, solver: str = "auto") -> xr.Dataset:
    """Root (fillet) stress of both members from the LTCA's segment forces.

    Parameters
    ----------
    case : geometry.case.Case — the case as analysed (with its misalignment)
    easeoff : contact.utca.EaseOff — the analysis' ease-off (its flanks, roll rotations)
    ltca : xarray.Dataset — ``/ltca`` of :func:`contact.ltca.loaded_tca`: ``force``
        (torque, roll, pair, segment) [N], ``contact_point`` (roll, pair, segment, xyz)
        [mm]
    options : contact.compliance.fe.FEOptions, optional — the FE model (default the
        case's level, ``[root_stress] fe_level``
        (:func:`contact.compliance.fe.options.case_fe_options`): ``FEOptions()`` where the
        case names none; its coefficients are built once per member and design, then
        read from the cache: docs/fe.md gives the cost, ~0.5–1.5 min per member with PARDISO)
    coefficients : dict, optional — ``{"pinion": ds, "gear": ds}`` influence coefficients
        of the ease-off's working flanks (then ``options`` and the cache are not used)
    cache, cache_dir, progress, solver — as
        :func:`contact.compliance.fe.influence_coefficients`

    Returns
    -------
    xarray.Dataset
        ``root_stress`` [MPa] over (torque, roll, member, tooth, fillet_point): the
        largest maximum principal stress over both root fillets of the tooth at each face
        station; ``root_stress_max`` [MPa] over (torque, member): its peak over the mesh
        cycles and teeth; coordinates ``member`` ("pinion", "gear"), ``tooth`` (the
        tooth-pair offset), ``fillet_point`` and ``fillet_u`` (member, fillet_point) [1]
        the station's lengthwise fraction of the fillet. NaN for a member and torque whose
        loaded segments the FE model cannot place (beyond :data:`OFF_FLANK_LIMIT` or
        :data:`GRID_LIMIT`, carrying more than :data:`UNPLACED_SHARE` of its load); the
        attributes ``not_computed`` (:data:`NOT_COMPUTED_ATTR`) and ``left_out``
        (:data:`LEFT_OUT_ATTR`) of both variables say, one line per member and torque,
        why a value is NaN and which few loads were left out (absent when none).

    Raises
    ------
    InputError — ``ltca`` lacks a variable; coefficients of another design (the loaded
        contact curves lie a median beyond :data:`DESIGN_LIMIT` off the FE flank or
        :data:`GRID_LIMIT` outside its load grid); bad ``options``.

    Notes
    -----
    Superposition of the FE unit-load stresses (module docstring; docs/fe.md); tested
    against a direct FE solve of the same forces (tests/test_root_stress.py).

    Source: linear superposition of the FE influence coefficients (docs/fe.md) over the
    segment forces of the loaded contact (seed Eq. 3.12–3.14); module docstring.
    """
    missing = [v for v in ("force", "contact_point") if v not in ltca.variables]
    if missing:
        raise InputError(f"ltca: lacks {', '.join(missing)} (not an /ltca dataset)")
    t0 = time.perf_counter()
    flanks = {"pinion": easeoff.pinion_flank, "gear": easeoff.gear_flank}
    opt = options if options is not None else case_fe_options(case)
    # read once per process (a study's worker, a duty cycle's bins)
    coef = pair_coefficients(case, flanks, opt, coefficients, cache=cache,
                             cache_dir=cache_dir, progress=progress, solver=solver)
    t1 = time.perf_counter()
    pts = member_contact_points(case, easeoff, ltca)
    force = ltca.variables["force"].transpose("torque", "roll", "pair", "segment").values
    pairs = np.asarray(ltca.variables["pair"].values, int)
    kinds = ltca.variables["segment_kind"].values if "segment_kind" in ltca.variables else None
    torques = np.asarray(ltca.variables["torque"].values, float)
    parts, notes, left = [], [], []
    for m in MEMBERS:
        st, unplaced = _member_stress(coef[m], pts[m], force, pairs, kinds)
        parts.append(st)
        for i, u in sorted(unplaced.items()):
            (notes if u.share > UNPLACED_SHARE else left).append(
                unplaced_reason(m, torques[i], u))
    stress = np.stack(parts, axis=2)
    for note in notes:
        log.warning("root stress: %s", note)
    for note in left:
        log.info("root stress: %s", note)
    n_st = {coef[m].sizes["station"] for m in MEMBERS}
    if len(n_st) != 1:
        raise InputError("coefficients: the members' FE models have different numbers of "
                         f"face stations {sorted(n_st)}")
    dims = ("torque", "roll", "member", "tooth", "fillet_point")
    peak = np.max(stress, axis=(1, 3, 4))  # NaN where a torque's loads were not placed
    torque, roll = ltca.variables["torque"], ltca.variables["roll"]
    ds = dataset({
        "root_stress": data_var(dims, stress, "MPa",
                                "tooth-root stress along the face width: largest maximum "
                                "principal stress over both fillets at the face station"),
        "root_stress_max": data_var(("torque", "member"), peak, "MPa",
                                    "peak tensile tooth-root stress over the mesh cycles"),
    }, {
        "torque": ("torque", torque.values, torque.attrs),
        "roll": ("roll", roll.values, roll.attrs),
        "member": ("member", np.array(MEMBERS), {"long_name": "gear member"}),
        "tooth": ("tooth", pairs, {"units": "1",
                                   "long_name": "tooth of the tooth pair (pair offset)"}),
        "fillet_point": ("fillet_point", np.arange(n_st.pop()),
                         {"units": "1", "long_name": "root fillet face station index"}),
        "fillet_u": (("member", "fillet_point"),
                     np.stack([coef[m].variables["station"].values for m in MEMBERS]),
                     {"units": "1", "long_name": "lengthwise fraction of the fillet face "
                                                 "station (toe 0, heel 1)"}),
    })
    for attr, text in ((NOT_COMPUTED_ATTR, notes), (LEFT_OUT_ATTR, left)):
        if text:  # why a torque's root stress is NaN, which loads were left out: in the file
            for name in ("root_stress", "root_stress_max"):
                ds[name].attrs[attr] = "\n".join(text)
    from contact.compliance.fe.cache import NOT_WRITTEN_ATTR

    unwritten = [f"the {m}'s FE coefficients were built and used from memory; the cache was "
                 f"not written ({coef[m].attrs[NOT_WRITTEN_ATTR]}): the next run builds them "
                 "again" for m in MEMBERS if NOT_WRITTEN_ATTR in coef[m].attrs]
    if unwritten:
        for name in ("root_stress", "root_stress_max"):
            ds[name].attrs[CACHE_NOTE_ATTR] = "\n".join(unwritten)
    ds["root_stress"].attrs["fe_cache_keys"] = " ".join(
        str(coef[m].attrs.get("cache_key", "")) for m in MEMBERS)
    ds["root_stress"].attrs["source"] = ("superposition of FE fillet-stress influence "
                                         "coefficients (contact.ltca.root_stress; docs/fe.md)")
    level = _coefficients_level(*(str(coef[m].attrs.get("options", "")) for m in MEMBERS))
    if level not in (None, "default"):  # a named cheaper model: said with its accuracy
        # (the default model's dataset as before: no attribute)
        for name in ("root_stress", "root_stress_max"):
            ds[name].attrs[FE_LEVEL_ATTR] = level
            ds[name].attrs[FE_ACCURACY_ATTR] = LEVEL_ACCURACY[level]
    log.info("root stress: coefficients %.2f s, superposition %.3f s", t1 - t0,
             time.perf_counter() - t1)
    ds.attrs["time_root_stress_coefficients_s"] = t1 - t0
    ds.attrs["time_root_stress_s"] = time.perf_counter() - t1
    return ds
