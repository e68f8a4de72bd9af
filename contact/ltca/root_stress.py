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

import numpy as np
import scipy.sparse as sp
import xarray as xr

from contact.compliance.fe import FEOptions, locate_flank_points
from contact.compliance.fe.contact_compliance import pair_coefficients
from contact.ltca.segments import roll_phases
from contact.utca import EaseOff
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.pair.assembly import case_transforms

__all__ = ["MEMBERS", "coefficients_cached", "member_contact_points", "prepare_coefficients",
           "root_stress"]

log = logging.getLogger(__name__)

#: [mm] largest distance of a loaded segment's point from the FE model's working flank
OFF_FLANK_LIMIT = 0.5

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
                         progress: bool = True) -> dict[str, xr.Dataset]:
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
        The FE model (default ``FEOptions()``).
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
    return pair_coefficients(case, flanks, options, progress=progress)


def coefficients_cached(case, flank: str | None = None, options=None, *,
                        cache_dir=None) -> bool:
    """Whether both members' FE influence coefficients of the analysed flanks are in the
    cache, so that the root stress adds only reading them and the superposition.

    Parameters
    ----------
    case : geometry.case.Case
    flank : str or None — the working flank role or name, as :func:`contact.run_analysis`
        takes it
    options : contact.compliance.fe.FEOptions, optional — the FE model (default
        ``FEOptions()``)
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

    opt = options if options is not None else FEOptions()
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
    """
    if "contact_point" not in ltca.variables:
        raise InputError("ltca: lacks contact_point (not an /ltca dataset)")
    p = ltca["contact_point"].transpose("roll", "pair", "segment", "xyz").values
    rp, rg = _roll_rotations(easeoff, np.asarray(ltca["roll"].values, float),
                             np.asarray(ltca["pair"].values, int))
    out = {}
    for name, t in zip(MEMBERS, case_transforms(case, rp, rg), strict=True):
        rot, shift = t[:, :3, :3], t[:, :3, 3]
        # r_member = Rᵀ (r_pair − t), per roll: (r − t)ᵀ R as one batched product
        d = (p - shift[:, None, None, :]).reshape(p.shape[0], -1, 3)
        out[name] = np.matmul(d, rot).reshape(p.shape)
    return out


def _pair_teeth(coef: xr.Dataset, pts: np.ndarray, pairs: np.ndarray) -> np.ndarray:
    """(K,) the member-frame tooth offset of each pair's tooth, from its segments' points
    (J, K, S, 3); pairs without a point continue the neighbours' step."""
    finite = np.all(np.isfinite(pts), axis=-1)
    tooth = np.empty(0, int)
    if finite.any():  # one location of every pair's points
        tooth = locate_flank_points(coef, pts[finite], strict=False).tooth
    return _teeth_of_pairs(tooth, np.nonzero(finite)[1], pairs)


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


def _member_stress(coef: xr.Dataset, pts: np.ndarray, force: np.ndarray,
                   pairs: np.ndarray) -> np.ndarray:
    """(NT, J, K, station) [MPa] root stress of one member: forces (NT, J, K, S) [N],
    points (J, K, S, 3) [mm] in its frame.

    The points are located on the flank once for all torques; each (torque, roll)'s
    forces become hat loads per loaded tooth, the distinct ones kept once (rolls whole
    mesh cycles apart); one sparse product of the (pair, distinct loads) rows with the
    coefficients S[a, d] gives every pair's fillet stress tensors, reduced block by block
    to the largest maximum principal stress over the root points (docs/fe.md, "Root
    stress in the analysis", for the cost).
    """
    nt, nj, nk, _ = force.shape
    # the variable, not a DataArray: its many coordinates cost more than the transpose
    s = coef.variables["fillet_stress"].transpose("load_u", "load_v", "tooth", "side",
                                                  "station", "arc", "component")
    offsets = np.asarray(coef["tooth"].values, int)
    nl = s.sizes["load_u"] * s.sizes["load_v"]
    # every segment point located once, for the pairs' teeth and the loads of all torques
    finite = np.all(np.isfinite(pts), axis=-1)  # (J, K, S)
    point = np.full(finite.shape, -1)
    point[finite] = np.arange(np.count_nonzero(finite))
    fp = locate_flank_points(coef, pts[finite], strict=False) if finite.any() else None
    tooth_of_pair = _teeth_of_pairs(fp.tooth if fp is not None else np.empty(0, int),
                                    np.nonzero(finite)[1], pairs)
    f = np.nan_to_num(force)
    t, j, k, m = np.nonzero(f > 0)  # the loaded segments of every torque
    out = np.zeros((nt, nj, nk, s.sizes["station"]))
    if not t.size:
        return out
    p = point[j, k, m]
    if np.any(p < 0):
        raise InputError("ltca: a loaded segment has no contact point")
    # the contact point is the gear's; the pinion's mate differs by the separation (and
    # an edge segment's by its rounding), and edge segments lie on the flank's boundary:
    # located leniently, then checked against a looser bound than a flank point's
    worst = float(np.max(np.abs(fp.distance[p])))
    if worst > OFF_FLANK_LIMIT:
        raise InputError(f"ltca: a loaded segment lies {worst:.3g} mm off the "
                         f"{coef.attrs['member']}'s working flank in the FE model (at most "
                         f"{OFF_FLANK_LIMIT} mm): the coefficients are not of this design")
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
    loads = sp.csr_matrix((np.concatenate(lv), (np.concatenate(lr), np.concatenate(lc))),
                          shape=(nk * nu, nl * offsets.size))
    root = root_points(coef)  # (side, station, arc): the flank above the fillet excluded
    # a row without loads (a pair the loads' neighbours do not reach) has no stress
    smax = np.broadcast_to(np.where(root.any(axis=(0, 2)), 0.0, -np.inf),
                           (nk * nu, s.sizes["station"])).copy()
    reached = np.flatnonzero(np.diff(loads.indptr))
    tensor = (loads[reached] @ s.values.reshape(nl * offsets.size, -1)).reshape(
        reached.size, *s.shape[3:])  # (row, side, station, arc, component) [MPa]
    for r0 in range(0, reached.size, ROW_BLOCK):  # a block's temporaries stay in the cache
        block = slice(r0, r0 + ROW_BLOCK)
        # the largest over the sides and the fillet arc
        smax[reached[block]] = np.where(root, _max_principal(tensor[block]),
                                        -np.inf).max(axis=(1, 3))
    out[:] = smax.reshape(nk, nu, -1)[:, inverse].swapaxes(0, 1).reshape(out.shape)
    return out


def root_points(coef: xr.Dataset) -> np.ndarray:
    """(side, station, arc) bool: the fillet points of a member's coefficients that lie in
    the root (``fillet_in_root``: the half slot and the element rows up to the fillet's
    junction with the flank, the same on every tooth), over which the root stress is the
    largest."""
    return coef.variables["fillet_in_root"].isel(tooth=0).transpose(
        "side", "station", "arc").values.astype(bool)


def _max_principal(t: np.ndarray) -> np.ndarray:
    """Largest principal value [MPa] of stresses in Voigt order (..., 6) (xx, yy, zz, yz,
    xz, xy): the closed form of the symmetric 3 × 3 eigenproblem (Smith, Comm. ACM 4
    (1961) 168), ~7× faster than ``numpy.linalg.eigvalsh`` on many small tensors (measured:
    0.03 s against 0.20 s CPU for 200 000) and
    equal to it within ~1e-10 of the tensor's norm (tests/test_root_stress.py)."""
    q = (t[..., 0] + t[..., 1] + t[..., 2]) / 3.0
    a, b, c = t[..., 0] - q, t[..., 1] - q, t[..., 2] - q
    p1 = t[..., 3] ** 2 + t[..., 4] ** 2 + t[..., 5] ** 2
    p = np.sqrt((a * a + b * b + c * c + 2.0 * p1) / 6.0)
    safe = np.where(p > 0, p, 1.0)
    a, b, c = a / safe, b / safe, c / safe
    yz, xz, xy = t[..., 3] / safe, t[..., 4] / safe, t[..., 5] / safe
    det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz)
    phi = np.arccos(np.clip(0.5 * det, -1.0, 1.0)) / 3.0
    return np.where(p > 0, q + 2.0 * p * np.cos(phi), q)


def root_stress(case, easeoff: EaseOff, ltca: xr.Dataset,
                options: FEOptions | None = None, *,
                coefficients: dict[str, xr.Dataset] | None = None, cache: bool = True,
                cache_dir=None, progress: bool = False, solver: str = "auto") -> xr.Dataset:
    """Root (fillet) stress of both members from the LTCA's segment forces.

    Parameters
    ----------
    case : geometry.case.Case — the case as analysed (with its misalignment)
    easeoff : contact.utca.EaseOff — the analysis' ease-off (its flanks, roll rotations)
    ltca : xarray.Dataset — ``/ltca`` of :func:`contact.ltca.loaded_tca`: ``force``
        (torque, roll, pair, segment) [N], ``contact_point`` (roll, pair, segment, xyz)
        [mm]
    options : contact.compliance.fe.FEOptions, optional — the FE model (default
        ``FEOptions()``; its coefficients are built once per member and design, then
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
        the station's lengthwise fraction of the fillet.

    Raises
    ------
    InputError — ``ltca`` lacks a variable; a loaded segment's point lies off the FE
        model's load grid or working flank (:func:`contact.compliance.fe.
        locate_flank_points`); bad ``options``.

    Notes
    -----
    Superposition of the FE unit-load stresses (module docstring; docs/fe.md); tested
    against a direct FE solve of the same forces (tests/test_root_stress.py).
    """
    missing = [v for v in ("force", "contact_point") if v not in ltca.variables]
    if missing:
        raise InputError(f"ltca: lacks {', '.join(missing)} (not an /ltca dataset)")
    t0 = time.perf_counter()
    flanks = {"pinion": easeoff.pinion_flank, "gear": easeoff.gear_flank}
    # read once per process (a study's worker, a duty cycle's bins)
    coef = pair_coefficients(case, flanks, options, coefficients, cache=cache,
                             cache_dir=cache_dir, progress=progress, solver=solver)
    t1 = time.perf_counter()
    pts = member_contact_points(case, easeoff, ltca)
    force = ltca["force"].transpose("torque", "roll", "pair", "segment").values
    pairs = np.asarray(ltca["pair"].values, int)
    stress = np.stack([_member_stress(coef[m], pts[m], force, pairs) for m in MEMBERS], axis=2)
    n_st = {coef[m].sizes["station"] for m in MEMBERS}
    if len(n_st) != 1:
        raise InputError("coefficients: the members' FE models have different numbers of "
                         f"face stations {sorted(n_st)}")
    dims = ("torque", "roll", "member", "tooth", "fillet_point")
    peak = np.max(stress, axis=(1, 3, 4))
    ds = xr.Dataset({
        "root_stress": data_var(dims, stress, "MPa",
                                "tooth-root stress along the face width: largest maximum "
                                "principal stress over both fillets at the face station"),
        "root_stress_max": data_var(("torque", "member"), peak, "MPa",
                                    "peak tensile tooth-root stress over the mesh cycles"),
    }, coords={
        "torque": ltca["torque"].variable, "roll": ltca["roll"].variable,
        "member": ("member", np.array(MEMBERS), {"long_name": "gear member"}),
        "tooth": ("tooth", pairs, {"units": "1",
                                   "long_name": "tooth of the tooth pair (pair offset)"}),
        "fillet_point": ("fillet_point", np.arange(n_st.pop()),
                         {"units": "1", "long_name": "root fillet face station index"}),
        "fillet_u": (("member", "fillet_point"),
                     np.stack([coef[m]["station"].values for m in MEMBERS]),
                     {"units": "1", "long_name": "lengthwise fraction of the fillet face "
                                                 "station (toe 0, heel 1)"}),
    })
    ds["root_stress"].attrs["fe_cache_keys"] = " ".join(
        str(coef[m].attrs.get("cache_key", "")) for m in MEMBERS)
    ds["root_stress"].attrs["source"] = ("superposition of FE fillet-stress influence "
                                         "coefficients (contact.ltca.root_stress; docs/fe.md)")
    log.info("root stress: coefficients %.2f s, superposition %.3f s", t1 - t0,
             time.perf_counter() - t1)
    ds.attrs["time_root_stress_coefficients_s"] = t1 - t0
    ds.attrs["time_root_stress_s"] = time.perf_counter() - t1
    return ds
