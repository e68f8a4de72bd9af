"""The boundary of a member's FE solid as a triangulated surface (STL).

Every boundary facet of the quadratic mesh is evaluated on a 3 × 3 grid of points of its
isoparametric map (so the curved flanks and fillets keep their shape to the mesh's own
accuracy) and split into eight triangles, oriented with their normals out of the solid.
The file is binary STL, written atomically.

Public names
------------
boundary_triangles  the boundary of a solid as triangles (T, 3, 3) [mm]
write_stl           write them as a binary STL file
"""

from __future__ import annotations

import os
import struct
from pathlib import Path

import numpy as np
import skfem

from contact.compliance.fe.mapped_mesh import MappedMesh, facet_points
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError

__all__ = ["boundary_triangles", "write_stl"]

#: the 3 × 3 grid of a facet: (i, j) node of the facet's two parameter directions
_GRID = np.array([(i, j) for j in range(3) for i in range(3)]) / 2.0
#: eight triangles of the 3 × 3 grid (node indices i + 3 j)
_TRIANGLES = np.array([[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4],
                       [3, 4, 7], [3, 7, 6], [4, 5, 8], [4, 8, 7]])


def boundary_triangles(mesh: MappedMesh) -> np.ndarray:
    """The boundary of a mapped mesh as triangles with outward orientation.

    Parameters
    ----------
    mesh : MappedMesh

    Returns
    -------
    ndarray (T, 3, 3) — [mm] T = 8 × boundary facets triangles, vertices counter-clockwise
        seen from outside (normal by the right-hand rule pointing out of the solid).
    """
    param = mesh.param
    facets = param.boundary_facets()
    tind = param.f2t[0, facets]
    corners = param.p[:, param.facets[:, facets]]  # (3, 4, F) parameter corners
    lo, hi = corners.min(axis=1), corners.max(axis=1)  # a facet is axis-aligned
    axes = np.argsort(hi - lo, axis=0)[1:]  # its two in-plane parameter directions
    pts = np.repeat(lo[:, None, :], 9, axis=1)  # (3, 9, F)
    f_idx = np.arange(facets.size)
    for k in range(2):
        ax = axes[k]
        pts[ax, :, f_idx] = (lo[ax, f_idx][:, None] + _GRID[:, k][None, :]
                             * (hi[ax, f_idx] - lo[ax, f_idx])[:, None])
    pmap = param.mapping()
    ref = pmap.invF(pts.transpose(0, 2, 1), tind=tind)  # (3, F, 9)
    x = mesh.mesh.mapping().F(ref, tind=tind).transpose(1, 2, 0)  # (F, 9, 3)
    tri = x[:, _TRIANGLES]  # (F, 8, 3, 3)
    normal = np.cross(tri[..., 1, :] - tri[..., 0, :], tri[..., 2, :] - tri[..., 0, :])
    # the outward normal at each facet's centre (Nanson's formula, facet_points)
    out = facet_points(mesh, skfem.ElementHex1(), facets, 1).normal[:, :, 0].T  # (F, 3)
    outward = np.sum(normal * out[:, None, :], axis=-1) >= 0.0
    tri = np.where(outward[..., None, None], tri, tri[..., ::-1, :])
    return tri.reshape(-1, 3, 3)


def write_stl(mesh: MappedMesh, path: str | os.PathLike[str], *, name: str = "solid") -> Path:
    """Write the boundary of a mapped mesh as a binary STL file.

    Parameters
    ----------
    mesh : MappedMesh — e.g. ``ToothSolid.mesh``
    path : path — the file to write (``.stl``)
    name : str — the header text (at most 80 characters are kept)

    Returns
    -------
    Path — the file written.

    Raises
    ------
    InputError — a path without the ``.stl`` suffix.
    """
    target = Path(path)
    if target.suffix.lower() != ".stl":
        raise InputError(f"path: must end in .stl, got {str(target)!r}")
    tri = boundary_triangles(mesh)
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    record = np.zeros(len(tri), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)),
                                        ("attr", "<u2")])
    record["n"], record["v"] = normal, tri
    header = name.encode("ascii", "replace")[:80].ljust(80, b" ")
    with atomic_path(target) as tmp, open(tmp, "wb") as fh:
        fh.write(header)
        fh.write(struct.pack("<I", len(tri)))
        fh.write(record.tobytes())
    return target
