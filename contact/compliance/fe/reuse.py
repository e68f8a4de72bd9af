"""A member's FE influence coefficients kept for a re-synthesis that moves its tooth by
micrometres (issue 71, issue 75 item 1).

The cache key of a member's coefficients covers every generating input
(:func:`contact.compliance.fe.cache.cache_key`), so a development that re-synthesises a
member — its coast flank developed again at its own design torque, or its drive flank at
a lowered one — gets a new key and, without this module, a whole new FE build (solid,
assembly, factorisation, 2 × 231 unit loads: ~28 s of CPU on a 9x41 hypoid's pinion),
for a tooth whose surfaces moved by a few tens of micrometres (relief, crowning, a
fraction of a degree of blade angle).

:func:`reuse_near_model` compares the two FE solids node by node — the same mesh layout
(element counts), every node of the re-synthesised member's mesh within
:data:`REUSE_DEPTH_FRACTION` of the blank's outer whole depth of the same node of the
earlier one — and where they are that close writes the earlier coefficients of both
flanks under the new member's keys (a copy of each entry: its own key and checksum, the
attributes ``reused_from`` and ``reuse_node_deviation_mm`` saying where from and how far),
so that the development's checks and ``ltca run`` of the written case read them. Any
other case (another layout, a node farther, an entry missing) builds as before.

What it costs in accuracy (docs/fe.md, "Coefficients kept for a re-synthesis"): on the
hypoid 9x41 at Sigma 95 deg (its pinion's coast flank developed again: root relief
15 -> 60 um from v 0.5 -> 0.2 and the bearing's path), whose solids differ by
:data:`REUSE_DEPTH_FRACTION`'s measured 0.65 % of the depth at most, ``ltca run``'s FE
root stress of the pinion changed by 0.42 % (drive, 415 N m) and 0.29 % (coast, 238 N m),
0.8 % at most at the light torque, the peak flank pressure not at all (the LTCA's
compliance is the shell model's by default): a tenth of the FE model's own mesh
convergence (5 %, docs/fe.md).

Public names
------------
REUSE_DEPTH_FRACTION  the largest node deviation kept, a fraction of the whole depth
node_deviation        the largest node distance between two members' FE solids
reuse_near_model      an earlier member's coefficients written for a near member
"""

from __future__ import annotations

import logging
import os

import numpy as np

from contact.compliance.fe.cache import (
    cache_key,
    cache_path,
    read_cache_entry,
    write_cache_entry,
)
from contact.compliance.fe.options import FEOptions

__all__ = ["REUSE_DEPTH_FRACTION", "node_deviation", "reuse_near_model"]

log = logging.getLogger(__name__)

#: [1] the largest distance between corresponding nodes of two FE solids, as a fraction
#: of the member's outer whole depth (h_ae + h_fe of the blank), at which the earlier
#: coefficients are kept: 1 % (0.12 mm on the 9x41's pinion, 0.04 mm on a module-2
#: pinion); measured 0.65 % -> at most 0.8 % in the FE root stress (module docstring)
REUSE_DEPTH_FRACTION = 0.01

_FLANKS = ("concave", "convex")


def node_deviation(case, earlier, member: str, options: FEOptions | None = None
                   ) -> float | None:
    """The largest distance [mm] between corresponding nodes of the FE solids of
    ``member`` in ``case`` and in ``earlier``
    (:func:`contact.compliance.fe.solid.build_tooth_solid`, the same options), or None
    where the two meshes differ in layout (element counts, hence node numbering).

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
    from contact.compliance.fe.solid import build_tooth_solid

    opt = options if options is not None else FEOptions()
    new = build_tooth_solid(case, member, opt)
    old = build_tooth_solid(earlier, member, opt)
    a, b = new.mesh.mesh.doflocs, old.mesh.mesh.doflocs
    if new.layout != old.layout or a.shape != b.shape:
        return None
    return float(np.sqrt(((a - b) ** 2).sum(axis=0)).max())


def reuse_near_model(case, earlier, member: str, options: FEOptions | None = None, *,
                     cache_dir: str | os.PathLike[str] | None = None,
                     fraction: float = REUSE_DEPTH_FRACTION) -> float | None:
    """Write ``earlier``'s cached coefficients of ``member`` (both flanks) under the keys
    of ``case``'s member, where its FE solid lies within ``fraction`` of the whole depth
    of ``earlier``'s node by node (:func:`node_deviation`).

    Parameters
    ----------
    case : geometry.case.Case — the re-synthesised design
    earlier : geometry.case.Case — the design whose coefficients are cached
    member : str — ``"pinion"`` or ``"gear"``
    options : FEOptions, optional — the FE model (default ``FEOptions()``)
    cache_dir : path-like, optional — the cache directory (default
        :func:`contact.compliance.fe.cache.cache_directory`)
    fraction : float — [1] the largest node deviation kept, of the outer whole depth
        (default :data:`REUSE_DEPTH_FRACTION`)

    Returns
    -------
    float or None
        The node deviation [mm] where the coefficients were written (or the member is
        the same: 0.0); None where not: ``case``'s entries cached already, one of
        ``earlier``'s missing, the meshes' layouts differ or a node lies farther. The
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
        deviation = node_deviation(case, earlier, member, opt)
    except Exception as exc:  # the build that follows says what fails
        log.info("FE %s: the node deviation from the earlier design not measured: %s",
                 member, exc)
        return None
    depth = float(new_m.blank.outer_addendum + new_m.blank.outer_dedendum)
    if deviation is None or not deviation <= fraction * depth:
        log.info("FE %s: the earlier design's coefficients not kept (node deviation %s "
                 "mm, bound %.3g mm)", member,
                 "n/a (another mesh layout)" if deviation is None else f"{deviation:.4f}",
                 fraction * depth)
        return None
    entries = {f: read_cache_entry(cache_path(old_keys[f], cache_dir), old_keys[f])
               for f in _FLANKS}
    if any(ds is None for ds in entries.values()):
        return None
    for f, ds in entries.items():
        key = new_keys[f]
        path = cache_path(key, cache_dir)
        if path.exists():
            continue
        out = ds.assign_attrs(reused_from=old_keys[f],
                              reuse_node_deviation_mm=round(deviation, 6))
        write_cache_entry(out, path, key)
    log.info("FE %s: the earlier design's coefficients kept (node deviation %.4f mm <= "
             "%.3g mm)", member, deviation, fraction * depth)
    return deviation
