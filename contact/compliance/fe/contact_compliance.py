"""The contact compliance of a gear mesh's segments from both members' FE coefficients.

The FE alternative to :mod:`contact.compliance.mesh` (the shell path) for the LTCA
(seed §3.2–3.3, Eq. 3.12–3.14; issue 35 item 4). At one roll position the N contact
segments' compliance along the contact normal [mm/N] is

    C = C_FE,pinion + C_FE,gear + diag(c_Weber)

* **C_FE,member** — from the member's influence coefficients
  (:func:`contact.compliance.fe.influence_coefficients`): the displacement of the tooth's
  **mid-surface** (``centreline_compliance``) per unit normal load on the working flank,
  bilinearly interpolated from the load grid to the segments (a uniform line load over
  each straight segment: Simpson's rule on its ends and midpoint), on the loaded tooth
  and on the neighbours the FE model has (default ±1 tooth; loads on teeth farther apart
  do not couple). It holds the tooth's bending and shear, the fillets, the slot bottoms and
  the rim down to the FE model's support (the bore held fixed, or the back face): it
  **replaces** the shell path's shell matrices *and* its Sainsot fillet foundation, which
  model the same deformation. There is no rigid-body or base term beyond the support:
  the member rotates rigidly only by the LTCA's unknown Θ (the gear) and its drive (the
  pinion), as in the shell path; shafts and bearings are in neither.
* **Weber** — the contact deformation between the contact point and the tooth's
  centreline (Weber 1949: Hertz plus the compression of the material down to depth h),
  the same term as the shell path with the same depths h (the shell tooth measurement,
  :func:`contact.compliance.tooth.weber_depth`) and linearised the same way.

Why the mid-surface and not the flank compliance: the FE's flank compliance (``compliance``)
contains the local compression under the load's hat (about two grid cells; at the load
itself 35–50 % of the flank compliance on the default case), which Weber's term contains
too (for the Hertzian zone; in its plane-strain form, the whole contact line's
compression): it would be counted twice. The mid-surface's displacement is what the shell
plus foundation model and what Weber's depth reaches to; it is also the FE quantity that
converges (≤ 2.6 % per refinement, docs/fe.md; the flank's at the load +4 … +11 %).

**Symmetry.** Load (on the flank) and response (on the mid-surface) are different
functionals, so the mid-surface compliance is not symmetric: raw relative asymmetry
‖G − Gᵀ‖_F/‖G‖_F 0.27 (gear) and 0.29 (pinion) of the default case's middle-tooth
coefficients, 0.08–0.43 at the LTCA's segments. C is symmetrised, ½(G + Gᵀ), and the
asymmetry reported, as the shell path does with its Ritz blocks. (Taking instead the
entry whose response lies above its load — where no bending strain separates the flank
from the mid-surface — was tried: against the flank compliance away from the load it is
no closer than the mean, 3–56 % against 3–54 % median deviation over the members of the
default and the face-hobbed case.) The flank compliance itself is symmetric to round-off
within a tooth, after the interpolation too (both sides take the same weights;
tests/test_fe_ltca.py).

Public names
------------
FE_VARIABLES              which FE compliance: name → variable of the coefficients
FEPairModel               both members' coefficients and the tooth measurement for Weber
fe_pair_model             build it (the coefficients from the disk cache, built if absent)
shared_coefficients       a member's coefficients, a cache file read once per process
cached_entry              a cache file through the same memo, by path and key
remember_written          coefficients just written to the cache kept as if read back
pair_coefficients         both members' coefficients of the analysed flanks, given or shared
segment_weights           the hat weights of uniform line loads over straight segments
interpolated_compliance   a member's compliance between weighted loads (unsymmetrised)
fe_mesh_compliance_many   C of several roll positions, as :func:`mesh_compliance_many`
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import scipy.sparse as sp
import xarray as xr

from contact.compliance.fe.cache import NOT_WRITTEN_ATTR, cache_key, cache_path, read_cache_entry
from contact.compliance.fe.elasticity import worker_session
from contact.compliance.fe.influence import influence_coefficients
from contact.compliance.fe.options import FEOptions, member_flank
from contact.compliance.fe.superposition import locate_flank_points
from contact.compliance.mesh import ContactSegments, PairComplianceModel
from contact.compliance.tooth import END_TOLERANCE, shell_points_many, weber_depth
from contact.compliance.weber import weber_compliance
from geometry.core.caches import Carried, memoised
from geometry.core.errors import InputError
from geometry.pair.assembly import case_transforms

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "FE_VARIABLES",
    "OFF_FLANK_LIMIT",
    "FEPairModel",
    "cached_entry",
    "fe_mesh_compliance_many",
    "fe_pair_model",
    "interpolated_compliance",
    "pair_coefficients",
    "remember_written",
    "segment_weights",
    "shared_coefficients",
]

log = logging.getLogger(__name__)

#: which FE compliance: ``"centreline"`` the tooth mid-surface's displacement (what the
#: LTCA adds Weber's contact term to), ``"flank"`` the loaded flank's own (local
#: compression under the load's hat included; symmetric)
FE_VARIABLES: dict[str, str] = {"centreline": "centreline_compliance", "flank": "compliance"}

#: [mm] largest distance (along the circumference) of a segment's midpoint from each
#: member's working flank in the FE model: a gross check that the coefficients are of
#: this design (their cache key already ties them to it). Only the point's
#: projection-plane place (u, v) enters the weights, not this distance. The LTCA's points
#: are the gear's (on its flank to ~0.02 mm), but a roll's pool takes in segments that
#: are far from contact: the pinion's mates differ by the initial separation (up to the
#: screening's generous limit, 0.05 mm + 0.15 mm per kN·m of gear torque, along the
#: normal, ~1.5 times that along the circumference) and an edge segment's point lies on
#: its own member's boundary, across its gap from the other's flank (measured: up to
#: 0.6 mm on the pinion, 1.3 mm on the gear at 500 N·m on the default case)
OFF_FLANK_LIMIT: dict[str, float] = {"pinion": 3.0, "gear": 3.0}

#: Simpson's weights of a straight segment's (first end, midpoint, second end)
_SIMPSON = (1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0)

_MEMBERS = ("pinion", "gear")

_MEMO_SIZE = 4  # coefficient files kept in memory by _read_cached (two designs' members)


#: coefficients built where their cache entry could not be written, by (path, key)
_UNWRITTEN: dict[tuple[str, str], xr.Dataset] = {}


@memoised(maxsize=_MEMO_SIZE)
def _read_cached(path: str, stamp: tuple[int, int, int], key: str,
                 written: Carried) -> xr.Dataset | None:
    """A cache file's coefficients, read and checked once per process and file version
    (path, and the file's inode, size and modification time: a study's worker analyses
    many points of one design). None if the entry fails a check of
    :func:`contact.compliance.fe.cache.read_cache_entry` (which sets it aside and logs
    why; then the caller goes through :func:`influence_coefficients`, which rebuilds it)
    or vanished meanwhile. ``written`` (not part of the key: every
    :class:`~geometry.core.caches.Carried` compares equal) carries the dataset this
    process has just written as that file version (:func:`remember_written`), or None."""
    if written.value is not None:
        return written.value
    return read_cache_entry(path, key)


def _stamp(path) -> tuple[int, int, int]:
    st = path.stat()
    return st.st_ino, st.st_size, st.st_mtime_ns


def cached_entry(path, key: str) -> xr.Dataset | None:
    """A cache entry through the process's memo of the files read (:func:`shared_coefficients`):
    :func:`contact.compliance.fe.cache.read_cache_entry` of ``path`` once per file
    version, the same object afterwards (read-only).

    Parameters
    ----------
    path : path-like — the entry's file
    key : str — its cache key

    Returns
    -------
    xarray.Dataset or None — None where the file is missing or fails a check (set
        aside and logged by ``read_cache_entry``)
    """
    try:
        stamp = _stamp(Path(path))
    except OSError:
        return None
    return _read_cached(str(path), stamp, key, Carried(None))


def remember_written(path, key: str, ds: xr.Dataset) -> None:
    """Keep coefficients this process has just written to the cache as ``path`` in the
    memo of the files read (:func:`shared_coefficients`), as if read back: the
    root-stress checks of ``ltca synthesize`` that follow its FE build read the four
    entries it wrote without reading them from disk (~0.07-0.1 s of CPU each on the
    10x43 hypoid's models, issue 75). What :func:`contact.compliance.fe.
    influence_coefficients` hands its ``written`` callback.

    Parameters
    ----------
    path : path-like — the entry's file, just written
    key : str — its cache key
    ds : xarray.Dataset — the dataset written (:func:`contact.compliance.fe.cache.
        write_cache_entry`'s return: its key and checksum attributes set, the values
        read back bit for bit)
    """
    try:
        stamp = _stamp(Path(path))
    except OSError:  # gone meanwhile: nothing to remember
        return
    _read_cached(str(path), stamp, key, Carried(ds))


def shared_coefficients(case, member: str, flank: str = "drive",
                        options: FEOptions | None = None, *, cache: bool = True,
                        cache_dir=None, progress: bool | str = False,
                        solver: str = "auto") -> xr.Dataset:
    """A member's influence coefficients, a cache file read once per process.

    Parameters
    ----------
    case, member, flank, options, cache, cache_dir, progress, solver
        As :func:`contact.compliance.fe.influence_coefficients`.

    Returns
    -------
    xarray.Dataset — as :func:`contact.compliance.fe.influence_coefficients`; an existing
        cache file's dataset, once checked, is kept in memory (the last 4 files, keyed
        by path, inode, size and modification time) and the same object returned to
        every caller of the process: read-only.

    Raises
    ------
    InputError, LTCAError, ModelUnavailableError
        As :func:`contact.compliance.fe.influence_coefficients` (which builds and caches
        the coefficients when no file is found, or when the file fails a check of
        :func:`contact.compliance.fe.cache.read_cache_entry`: unreadable, foreign,
        corrupt or not finite; such a file is set aside and never used).

    Notes
    -----
    A study's worker analyses many points of one design: reading the two compressed files
    (24 + 31 MB on the default case, ~1 s) once instead of at every point. The memo
    (:func:`_read_cached`) and the coefficients built where the cache could not be written
    (:data:`_UNWRITTEN`, the last :data:`_MEMO_SIZE`: used from memory by the later
    analyses of the process, not built again) are the only state of this module.
    """
    opt = options if options is not None else FEOptions()
    if cache and isinstance(opt, FEOptions):
        key = cache_key(case.member(member), member_flank(case, member, flank), opt)
        path = cache_path(key, cache_dir)
        try:
            stamp = _stamp(path)
        except OSError:  # no entry, or a cache directory that cannot be reached
            pass
        else:
            ds = _read_cached(str(path), stamp, key, Carried(None))
            if ds is not None:
                return ds
        kept = _UNWRITTEN.get((str(path), key))
        if kept is not None:
            return kept
    ds = influence_coefficients(case, member, flank, options, cache=cache,
                                cache_dir=cache_dir, progress=progress, solver=solver,
                                written=remember_written)
    if cache and isinstance(opt, FEOptions) and NOT_WRITTEN_ATTR in ds.attrs:
        _UNWRITTEN[(str(path), key)] = ds
        while len(_UNWRITTEN) > _MEMO_SIZE:
            _UNWRITTEN.pop(next(iter(_UNWRITTEN)))
    return ds


@dataclass(frozen=True, eq=False)
class FEPairModel:
    """Both members' FE influence coefficients, with the tooth measurement for Weber.

    Attributes
    ----------
    coefficients : dict — ``{"pinion": Dataset, "gear": Dataset}`` of
        :func:`contact.compliance.fe.influence_coefficients` (working flanks)
    teeth : PairComplianceModel — the shell path's tooth models, used here only for
        Weber's depths (:func:`contact.compliance.tooth.weber_depth`), so that both paths
        take the same contact term
    variable : str — a key of :data:`FE_VARIABLES` (default ``"centreline"``)
    build_time : float — [s] reading (or building) the coefficients
    """

    coefficients: dict
    teeth: PairComplianceModel
    variable: str = "centreline"
    build_time: float = 0.0

    def __post_init__(self) -> None:
        if self.variable not in FE_VARIABLES:
            raise InputError(f"variable: must be one of {sorted(FE_VARIABLES)}, got "
                             f"{self.variable!r}")
        missing = [m for m in _MEMBERS if m not in self.coefficients]
        if missing:
            raise InputError(f"coefficients: lacks the {', '.join(missing)}'s")


def fe_pair_model(case: Case, flanks: dict[str, str], options: FEOptions | None,
                  teeth: PairComplianceModel, *, coefficients: dict | None = None,
                  variable: str = "centreline", cache: bool = True, cache_dir=None,
                  progress: bool | str = False, solver: str = "auto") -> FEPairModel:
    """Both members' FE coefficients of the analysed flanks, from the cache or built.

    Parameters
    ----------
    case : geometry.case.Case
    flanks : dict — ``{"pinion": flank, "gear": flank}`` the working flanks (the
        ease-off's ``pinion_flank``, ``gear_flank``)
    options : FEOptions or None — the FE model (default ``FEOptions()``)
    teeth : PairComplianceModel — the tooth models for Weber's depths
        (:func:`contact.compliance.mesh.pair_compliance_model`)
    coefficients : dict, optional — coefficients already read, by member (then
        ``options`` and the cache are not used for that member)
    variable : str — a key of :data:`FE_VARIABLES`
    cache, cache_dir, progress, solver — as
        :func:`contact.compliance.fe.influence_coefficients`

    Returns
    -------
    FEPairModel

    Raises
    ------
    InputError
        Given coefficients of another flank than the analysed one; bad options.

    Notes
    -----
    The first build of the default model costs 15–60 s per member (docs/fe.md, "Cost");
    afterwards it is read from the disk cache (~1 s), once per process and file: the
    datasets are kept in memory (the last 4 files) and shared — read-only — by the
    analyses of the process (a study's points, a misalignment sweep).
    """
    t0 = time.perf_counter()
    coef = pair_coefficients(case, flanks, options, coefficients, cache=cache,
                             cache_dir=cache_dir, progress=progress, solver=solver)
    return FEPairModel(coef, teeth, variable, time.perf_counter() - t0)


def pair_coefficients(case: Case, flanks: dict[str, str], options: FEOptions | None,
                      coefficients: dict | None = None, *, cache: bool = True,
                      cache_dir=None, progress: bool | str = False, solver: str = "auto"
                      ) -> dict[str, xr.Dataset]:
    """Both members' coefficients of the analysed flanks: those given, the others from
    :func:`shared_coefficients` (read once per process, or built and cached).

    Parameters
    ----------
    case : geometry.case.Case
    flanks : dict — ``{"pinion": flank, "gear": flank}`` the working flank names
    options : FEOptions or None — the FE model (None: the default)
    coefficients : dict, optional — member → coefficients already at hand
    cache, cache_dir, progress, solver — as :func:`shared_coefficients`

    Returns
    -------
    dict — ``"pinion"``, ``"gear"`` → xarray.Dataset

    Raises
    ------
    InputError
        Coefficients given for another flank than the analysed one (named).
    """
    coef = dict(coefficients or {})
    with worker_session():  # both members built in one solver worker (issue 75)
        for name in _MEMBERS:
            if name not in coef:
                coef[name] = shared_coefficients(case, name, flanks[name], options,
                                                 cache=cache, cache_dir=cache_dir,
                                                 progress=progress, solver=solver)
            elif coef[name].attrs.get("flank") != flanks[name]:
                raise InputError(f"coefficients: the {name}'s are of its "
                                 f"{coef[name].attrs.get('flank')} flank, the analysis "
                                 f"loads its {flanks[name]} flank")
    return coef


def segment_weights(coefficients: xr.Dataset, midpoints: np.ndarray, ends: np.ndarray, *,
                    limit: float = OFF_FLANK_LIMIT["gear"]
                    ) -> tuple[sp.csr_matrix, np.ndarray, float]:
    """Hat weights of uniform line loads of 1 N over straight segments on a member's flank.

    Parameters
    ----------
    coefficients : xarray.Dataset — the member's influence coefficients
    midpoints : ndarray (N, 3) — [mm] segment midpoints, member frame
    ends : ndarray (N, 2, 3) — [mm] their ends, member frame
    limit : float — [mm] largest distance of a midpoint from the working flank

    Returns
    -------
    weights : scipy.sparse.csr_matrix (N, nu nv) — [1] the load grid's hat weights of
        each segment's load (Simpson's rule on the ends and midpoint; each row sums to 1)
    tooth : ndarray (N,) of int — the tooth offset of each segment (its midpoint's)
    distance : float — [mm] the largest distance of a midpoint from the working flank

    Raises
    ------
    InputError
        A midpoint more than ``limit`` off the working flank (coefficients of another
        design or flank).

    Notes
    -----
    Points are located as :func:`contact.compliance.fe.locate_flank_points` does, leniently
    (fractions clipped to the load grid: an end segment reaching over the flank's edge
    takes the boundary's weights). An end of a segment takes its midpoint's tooth.
    """
    n = midpoints.shape[0]
    pts = np.concatenate([midpoints, ends[:, 0], ends[:, 1]])
    fp = locate_flank_points(coefficients, pts, strict=False)
    d_mid = np.abs(fp.distance[:n])
    worst = float(d_mid.max()) if n else 0.0
    if worst > limit:
        i = int(np.argmax(d_mid))
        raise InputError(f"points: segment {i} lies {worst:.3g} mm off the "
                         f"{coefficients.attrs.get('member')}'s working flank in the FE model "
                         f"(at most {limit} mm): the coefficients are not of this design")
    w = fp.weights.tocsr()
    weights = (_SIMPSON[1] * w[:n] + _SIMPSON[0] * w[n:2 * n] + _SIMPSON[2] * w[2 * n:])
    return weights.tocsr(), fp.tooth[:n].astype(int), worst


def interpolated_compliance(coefficients: xr.Dataset, weights, tooth,
                            variable: str = "centreline") -> np.ndarray:
    """A member's FE compliance between loads given by hat weights, not symmetrised.

    Parameters
    ----------
    coefficients : xarray.Dataset — the member's influence coefficients
    weights : array_like or sparse (N, nu nv) — [1] hat weights of each load
        (:func:`segment_weights`, or :func:`contact.compliance.fe.locate_flank_points`)
    tooth : array_like (N,) of int — each load's tooth offset
    variable : str — a key of :data:`FE_VARIABLES`

    Returns
    -------
    ndarray (N, N) — [mm/N] C_ij = Σ_ab w_ia w_jb G[b, k_i − k_j, a]: the displacement at
        load i's place (in its weights) per unit load j, from the coefficients G[load,
        response tooth offset, response]; zero where the teeth are farther apart than the
        modelled neighbours.

    Raises
    ------
    InputError
        ``variable`` unknown; ``weights`` and ``tooth`` of different lengths.

    Notes
    -----
    Bilinear hat interpolation of the influence coefficients (docs/fe.md,
    :mod:`contact.compliance.fe.superposition`). Within one tooth, the flank compliance's
    G is symmetric to round-off (Maxwell–Betti), so is this matrix; across teeth and for
    the mid-surface's displacement it is so only approximately.
    """
    if variable not in FE_VARIABLES:
        raise InputError(f"variable: must be one of {sorted(FE_VARIABLES)}, got {variable!r}")
    g = coefficients[FE_VARIABLES[variable]].transpose("load_u", "load_v", "tooth", "u", "v")
    w = weights.toarray() if sp.issparse(weights) else np.asarray(weights, float)
    k = np.asarray(tooth, int).ravel()
    if w.shape[0] != k.size:
        raise InputError(f"tooth: must have one entry per row of weights ({w.shape[0]}), got "
                         f"{k.size}")
    nl = g.sizes["load_u"] * g.sizes["load_v"]
    c = np.zeros((k.size, k.size))
    diff = k[:, None] - k[None, :]  # response tooth i − load tooth j
    for d in g["tooth"].values:
        mask = diff == d
        if not mask.any():
            continue
        rows, cols = np.nonzero(mask)
        ri, ci = np.unique(rows), np.unique(cols)
        gd = g.sel(tooth=d).values.reshape(nl, nl)  # [load a, response b]
        block = w[ri] @ gd.T @ w[ci].T  # [response i, load j]
        sub = mask[np.ix_(ri, ci)]
        c[np.ix_(ri, ci)] = np.where(sub, block, c[np.ix_(ri, ci)])
    return c


def fe_mesh_compliance_many(case: Case, segments: list[ContactSegments], model: FEPairModel, *,
                            weber_kind: str = "secant", load_floor: float = 1.0
                            ) -> list[tuple[np.ndarray, dict[str, Any]]]:
    """Total compliance of the contact segments of several roll positions, FE members.

    Parameters
    ----------
    case : geometry.case.Case — the gear pair (misalignments from ``case.misalignment``)
    segments : list of ContactSegments — N_r segments per roll position, pair frame
    model : FEPairModel — both members' coefficients (:func:`fe_pair_model`)
    weber_kind : {"secant", "tangent"} — Weber linearisation
    load_floor : float — [N/mm] w′ below this is evaluated at this value

    Returns
    -------
    list of (C, info), one per roll position
        C (N_r, N_r) [mm/N] symmetric; info: ``"pinion_fe"``, ``"gear_fe"`` (N_r, N_r)
        [mm/N] the members' FE compliances (symmetrised); ``"weber"`` (N_r, N_r) [mm/N]
        diagonal; ``"asymmetry"`` [1] the largest ‖C − Cᵀ‖_F/‖C‖_F of the members' FE
        matrices before symmetrisation; ``"weber_depth"`` (N_r, 2) [mm]; ``"teeth"``
        (N_r, 2) the member-frame tooth offsets; ``"off_flank"`` [mm] the largest
        distance of a midpoint from an FE flank; ``"blocks"`` {pair: indices};
        ``"model"``; ``"time"`` [s] (the batch's time shared evenly).

    Raises
    ------
    InputError
        Segments off a member's FE flank (:func:`segment_weights`) or off its tooth in the
        tooth measurement; bad Weber inputs.

    Notes
    -----
    Module docstring: C_FE of both members (mid-surface displacement: bending, shear,
    fillets, rim; neighbours coupled) plus Weber's contact term (Weber 1949; seed p. 78).
    Each pinion load presses on the pinion flank, each gear load on the gear flank, so
    the members' compliances add as approaches along the contact normal.
    """
    t0 = time.perf_counter()
    if not segments:
        return []
    if not all(isinstance(seg, ContactSegments) for seg in segments):
        raise InputError("contact_segments: must be ContactSegments")
    teeth = model.teeth
    jobs, parts = [], []
    for seg in segments:
        transforms = case_transforms(case, seg.pinion_rotation, seg.gear_rotation)
        fe_parts, tooth_of = {}, []
        off = 0.0
        for name, t, sign in zip(_MEMBERS, transforms, (1.0, -1.0), strict=True):
            rot, shift = np.asarray(t)[:3, :3], np.asarray(t)[:3, 3]
            mid = (seg.midpoints - shift) @ rot  # r_member = Rᵀ (r_pair − t)
            ends = (seg.ends - shift) @ rot
            w, k, dist = segment_weights(model.coefficients[name], mid, ends,
                                         limit=OFF_FLANK_LIMIT[name])
            raw = interpolated_compliance(model.coefficients[name], w, k, model.variable)
            fe_parts[name] = raw
            tooth_of.append(k)
            off = max(off, dist)
            jobs.append((teeth.member(name), seg.midpoints, sign * seg.normals, t, None))
        parts.append((fe_parts, np.column_stack(tooth_of), off))
    mapped = shell_points_many(jobs, END_TOLERANCE)
    depth = np.concatenate([
        np.column_stack([weber_depth(teeth.member(name), mapped[2 * r + i][0])
                         for i, name in enumerate(_MEMBERS)])
        for r in range(len(segments))])
    tp, tg = teeth.pinion.tooth, teeth.gear.tooth
    c_w = weber_compliance(np.concatenate([seg.load for seg in segments]),
                           np.concatenate([seg.length for seg in segments]),
                           depth[:, 0], depth[:, 1], e1=tp.youngs_modulus,
                           nu1=tp.poisson_ratio, e2=tg.youngs_modulus, nu2=tg.poisson_ratio,
                           r_eq=np.concatenate([seg.r_eq for seg in segments]),
                           kind=weber_kind, load_floor=load_floor)
    offsets = np.concatenate([[0], np.cumsum([seg.size for seg in segments])])
    out = []
    for r, (seg, (fe_parts, tooth_of, off)) in enumerate(zip(segments, parts, strict=True)):
        rows = slice(offsets[r], offsets[r + 1])
        info: dict[str, Any] = {}
        asym = 0.0
        for name in _MEMBERS:
            raw = fe_parts[name]
            norm = float(np.linalg.norm(raw))
            if norm > 0.0:
                asym = max(asym, float(np.linalg.norm(raw - raw.T)) / norm)
            info[f"{name}_fe"] = 0.5 * (raw + raw.T)
        info["weber"] = np.diag(c_w[rows])
        total = info["pinion_fe"] + info["gear_fe"] + info["weber"]
        info.update(asymmetry=asym, weber_depth=depth[rows], teeth=tooth_of, off_flank=off,
                    blocks={int(p): np.flatnonzero(seg.pair_index == p)
                            for p in np.unique(seg.pair_index)}, model=model)
        out.append((total, info))
    share = (time.perf_counter() - t0) / len(segments)
    for _, info in out:
        info["time"] = share
    log.debug("FE mesh compliance: %d roll positions, %.4f s each", len(segments), share)
    return out
