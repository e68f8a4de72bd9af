"""A member's FE influence coefficients kept for a re-synthesis that moves its tooth by
micrometres (issue 71, issue 75 item 1).

The cache key of a member's coefficients covers every generating input
(:func:`contact.compliance.fe.cache.cache_key`), so a development that re-synthesises a
member — its coast flank developed again at its own design torque, or its drive flank at
a lowered one — gets a new key and, without this module, a whole new FE build (solid,
assembly, factorisation, 2 × 231 unit loads: ~28 s of CPU on a 9x41 hypoid's pinion),
for a tooth whose surfaces moved by a few tens of micrometres (relief, crowning, a
fraction of a degree of blade angle).

:func:`reuse_near_model` compares the points the coefficients refer to — the load
grid's points on both working flanks and the stress points along the root fillets and
slot bottoms of every modelled tooth (:func:`point_deviation`), with the same mesh layout
(element counts) — and where every one of them lies within :data:`REUSE_DEPTH_FRACTION`
of the blank's outer whole depth of its counterpart it writes the earlier coefficients of
both flanks under the new member's keys (a copy of each entry: its own key and checksum,
the attributes ``reused_from`` and ``reuse_point_deviation_mm`` saying where from and how
far), so that the development's checks and ``ltca run`` of the written case read them.
Any other case (another layout, a point farther, an entry missing) builds as before.

What it costs in accuracy (docs/fe.md, "Coefficients kept for a re-synthesis"): on the
hypoid 9x41 at Sigma 95 deg, whose pinion's coast flank the development re-synthesised
(tip relief 51 -> 15 um, profile crowning 11 -> 0 um, blade angle change -0.12 -> 0 deg,
root relief 56 -> 60 um from v 0.31 -> 0.2), the points moved by 83 um at most (0.74 % of
the depth): ``ltca run``'s FE root stress of the pinion with the earlier coefficients
differs from its own build's by 0.42 % (drive, 415 N m) and 0.29 % (coast, 238 N m), 0.8 %
at most at the light torque, the peak flank pressure not at all (the LTCA's compliance is
the shell model's by default); on the default pinion (coarse test model), 0.028 mm give
0.26 % on the peak fillet stress of the heavy unit loads (tests/test_fe_reuse.py); the
6x41 hypoid's pinion, kept twice at 0.04 mm: 0.15-0.21 %; with the bound at 2 %
(2026-11-26), the pinions of the hypoid 10x43, the 10x37 at Sigma 75 deg and the
face-hobbed 10x37 (Method 2), kept after the coast flank's second development at 1.75,
1.24 and 1.66 % of the depth: 0.52 % at most (drive and coast), the drive flank's
coefficients within 0.05 % on the loads that decide a root stress, the moved coast
flank's up to 11 % at its toe column (loads the developed bearings do not carry). A fifth
of the FE model's own mesh convergence (5 %, docs/fe.md) or less.

Public names
------------
REUSE_DEPTH_FRACTION  the largest point deviation kept, a fraction of the whole depth
point_deviation       the largest distance between two members' load and stress points
reuse_near_model      an earlier member's coefficients written for a near member
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable

import numpy as np
import xarray as xr

from contact.compliance.fe.cache import (
    CHECKSUM_ATTR,
    cache_key,
    cache_path,
    read_cache_entry,
    write_cache_entry,
)
from contact.compliance.fe.options import FEOptions

__all__ = ["REUSE_DEPTH_FRACTION", "point_deviation", "reuse_near_model"]

log = logging.getLogger(__name__)

#: [1] the largest distance between corresponding load and stress points of two members'
#: FE models (:func:`point_deviation`), as a fraction of the member's outer whole depth
#: (h_ae + h_fe of the blank), at which the earlier coefficients are kept: 2 % (0.22 mm
#: on the 9x41's pinion, 0.17 mm on the face-hobbed module-2 10x37's); 1 % before
#: 2026-11-26 (issue 75: the coast flank's second development moves the pinion's points
#: by 1.2-1.7 % of its depth, and its third FE build was 10-20 % of an ``ltca
#: synthesize``); measured: docs/fe.md, "Coefficients kept for a re-synthesis"
REUSE_DEPTH_FRACTION = 0.02

_FLANKS = ("concave", "convex")


def point_deviation(case, earlier, member: str, options: FEOptions | None = None
                    ) -> float | None:
    """The largest distance [mm] between the points the coefficients of ``member`` refer
    to in ``case`` and in ``earlier``: the load grid's points on both working flanks (the
    generated flanks at the grid's fractions, :func:`contact.compliance.fe.influence.
    flank_grid_positions`; the coefficients' ``flank_position``) and the stress points
    along both root fillets and slot bottoms of every modelled tooth (their 2 × 2 Gauss
    points of each root facet of the mesh, as the coefficients' ``fillet_position``).
    None where the two FE meshes differ in layout (element counts: other points).

    Parameters
    ----------
    case, earlier : geometry.case.Case
    member : str — ``"pinion"`` or ``"gear"``
    options : FEOptions, optional — default ``FEOptions()``

    Returns
    -------
    float or None — [mm]

    Raises
    ------
    InputError, LTCAError
        As :func:`contact.compliance.fe.solid.build_tooth_solid`.
    """
    from contact.compliance.fe.influence import flank_grid_positions, load_v_limits
    from contact.compliance.fe.mapped_mesh import facet_points
    from contact.compliance.fe.options import ELEMENTS
    from contact.compliance.fe.solid import kept_tooth_solid

    opt = options if options is not None else FEOptions()
    # the earlier design's solid first: the one its FE build has just made, kept
    # (kept_tooth_solid); the new one is kept for the build that follows a refusal
    old = kept_tooth_solid(earlier, member, opt)
    new = kept_tooth_solid(case, member, opt)
    if new.layout != old.layout or new.mesh.mesh.nelements != old.mesh.mesh.nelements:
        return None
    grid_u = np.linspace(0.0, 1.0, opt.load_nu)
    worst = 0.0
    for flank in _FLANKS:
        grid_v = np.linspace(*load_v_limits(new.sections, flank, opt), opt.load_nv)
        a = flank_grid_positions(new.sections, flank, grid_u, grid_v)
        b = flank_grid_positions(old.sections, flank, grid_u, grid_v)
        worst = max(worst, float(np.linalg.norm(a - b, axis=-1).max()))
    element = ELEMENTS[opt.element][0]()
    k = new.layout.neighbours
    for t in range(-k, k + 1):
        for side in ("left", "right"):
            fa, fb = np.r_[new.fillet_facets(t, side)], np.r_[old.fillet_facets(t, side)]
            if not np.array_equal(fa, fb):
                return None
            a = facet_points(new.mesh, element, fa, 3).x
            b = facet_points(old.mesh, element, fb, 3).x
            worst = max(worst, float(np.linalg.norm(a - b, axis=0).max()))
    return worst


def reuse_near_model(case, earlier, member: str, options: FEOptions | None = None, *,
                     cache_dir: str | os.PathLike[str] | None = None,
                     fraction: float = REUSE_DEPTH_FRACTION,
                     refused: list[str] | None = None,
                     read: Callable[..., xr.Dataset | None] = read_cache_entry,
                     written: Callable[..., None] | None = None) -> float | None:
    """Write ``earlier``'s cached coefficients of ``member`` (both flanks) under the keys
    of ``case``'s member, where its FE solid lies within ``fraction`` of the whole depth
    of ``earlier``'s, point by point (:func:`point_deviation`).

    Parameters
    ----------
    case : geometry.case.Case — the re-synthesised design
    earlier : geometry.case.Case — the design whose coefficients are cached
    member : str — ``"pinion"`` or ``"gear"``
    options : FEOptions, optional — the FE model (default ``FEOptions()``)
    cache_dir : path-like, optional — the cache directory (default
        :func:`contact.compliance.fe.cache.cache_directory`)
    fraction : float — [1] the largest point deviation kept, of the outer whole depth
        (default :data:`REUSE_DEPTH_FRACTION`)
    refused : list of str, optional — where the two were compared and the coefficients
        not kept, one phrase saying why is appended (e.g. "its load and stress points
        0.221 mm from the earlier design's, beyond 0.165 mm (2 % of its whole depth)")
    read : callable, optional — ``read(path, key)``: the earlier design's entries
        (default :func:`contact.compliance.fe.cache.read_cache_entry`; the development
        passes the process's memo of the files read, :func:`contact.compliance.fe.
        contact_compliance.cached_entry`, which holds them where its first pass built or
        read them: issue 75)
    written : callable, optional — called as ``written(path, key, ds)`` with each entry
        written (as :func:`contact.compliance.fe.influence_coefficients`'s ``written``)

    Returns
    -------
    float or None
        The point deviation [mm] where the coefficients were written (or the member is
        the same: 0.0); None where not: ``case``'s entries cached already, one of
        ``earlier``'s missing, the meshes' layouts differ or a point lies farther. The
        caller then builds as before.

    Raises
    ------
    OSError
        An entry cannot be written (the cache's file system).
    """
    opt = options if options is not None else FEOptions()
    new_m, old_m = case.member(member), earlier.member(member)
    new_keys = {f: cache_key(new_m, f, opt) for f in _FLANKS}
    old_keys = {f: cache_key(old_m, f, opt) for f in _FLANKS}
    if new_keys == old_keys:
        return 0.0
    if all(cache_path(k, cache_dir).exists() for k in new_keys.values()):
        return None
    if not all(cache_path(k, cache_dir).exists() for k in old_keys.values()):
        return None
    try:
        deviation = point_deviation(case, earlier, member, opt)
    except Exception as exc:  # the build that follows says what fails
        log.info("FE %s: the point deviation from the earlier design not measured: %s",
                 member, exc)
        if refused is not None:
            refused.append(f"its distance from the earlier design not measured ({exc})")
        return None
    depth = float(new_m.blank.outer_addendum + new_m.blank.outer_dedendum)
    if deviation is None or not deviation <= fraction * depth:
        log.info("FE %s: the earlier design's coefficients not kept (point deviation %s "
                 "mm, bound %.3g mm)", member,
                 "n/a (another mesh layout)" if deviation is None else f"{deviation:.4f}",
                 fraction * depth)
        if refused is not None:
            refused.append(
                "another FE mesh layout (element counts) than the earlier design's"
                if deviation is None else
                f"its load and stress points {deviation:.3f} mm from the earlier design's, "
                f"beyond {fraction * depth:.3f} mm ({100.0 * fraction:g} % of its whole "
                f"depth)")
        return None
    entries = {f: read(cache_path(old_keys[f], cache_dir), old_keys[f]) for f in _FLANKS}
    if any(ds is None for ds in entries.values()):
        return None
    for f, ds in entries.items():
        key = new_keys[f]
        path = cache_path(key, cache_dir)
        if path.exists():
            continue
        out = ds.assign_attrs(reused_from=old_keys[f],
                              reuse_point_deviation_mm=round(deviation, 6))
        # the data as they were checked (written or read by this process): their stored
        # checksum, not computed again
        out = write_cache_entry(out, path, key, checksum=ds.attrs.get(CHECKSUM_ATTR))
        if written is not None:
            written(path, key, out)
    log.info("FE %s: the earlier design's coefficients kept (point deviation %.4f mm <= "
             "%.3g mm)", member, deviation, fraction * depth)
    return deviation
