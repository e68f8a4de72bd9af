"""Deviation files: measured (CMM) or wear deviations of the flanks, read and written.

The exchange side of the real-surface analysis (seed §4.3, §4.5.2): grids of normal
deviations of a flank, positive = material added, as CSV (one grid per file) or netCDF
(pinion and/or gear grids, written atomically with :func:`geometry.core.io.write_netcdf`). The
model they feed — :class:`contact.utca.deviations.SurfaceDeviation` and the ease-off
update :func:`contact.utca.deviations.apply_deviations` — is in the UTCA layer and is
re-exported here, so that ``from contact.utca.deviation_files import read_deviations,
apply_deviations`` gives the whole chain.

Public functions
----------------
read_deviation_csv          read one grid from a CSV file
read_deviation_netcdf       read one member's grid from a netCDF file
write_deviation_netcdf      write the pinion and/or gear grids to a netCDF file (atomic)
read_deviations             either reader, chosen by the file suffix (:data:`READERS`)
"""

from __future__ import annotations

import csv
import math
import os
from collections.abc import Callable
from pathlib import Path

import numpy as np
import xarray as xr

from contact.utca.deviations import (
    DEFAULT_MEASUREMENT_GRID,
    MAX_DEVIATION,
    SurfaceDeviation,
    apply_deviations,
    weighted_average_deviation,
)
from geometry.core.errors import InputError
from geometry.core.io import NetCDFError, read_netcdf, write_netcdf

__all__ = [
    "DEFAULT_MEASUREMENT_GRID",
    "DEVIATION_UNITS",
    "MAX_DEVIATION",
    "READERS",
    "SurfaceDeviation",
    "apply_deviations",
    "read_deviation_csv",
    "read_deviation_netcdf",
    "read_deviations",
    "weighted_average_deviation",
    "write_deviation_netcdf",
]


def read_deviation_csv(path: str | os.PathLike[str]) -> SurfaceDeviation:
    """Read a deviation grid from a CSV file.

    Format (wide): lines starting with ``#`` are comments; the first row is a label cell
    followed by the lengthwise fractions u (toe 0 → heel 1); every further row is a profile
    fraction v (root 0 → tip 1) followed by the deviations [mm] at (u, v), positive =
    material added (outward normal)::

        # gear convex, CMM 2026-11-21, mm
        v\\u, 0.0, 0.125, ..., 1.0
        0.05, 0.0012, ...
        ...

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    SurfaceDeviation

    Raises
    ------
    InputError
        For a missing file, ragged rows, non-numeric cells (naming row and column) or as
        :class:`SurfaceDeviation`.
    """
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            rows = [r for r in csv.reader(fh)
                    if r and any(c.strip() for c in r) and not r[0].lstrip().startswith("#")]
    except OSError as exc:
        raise InputError(f"path: cannot read deviation CSV {os.fspath(path)!r}: {exc}") from exc
    except UnicodeDecodeError as exc:
        raise InputError(f"path: deviation CSV {os.fspath(path)!r} is not UTF-8 text (byte "
                         f"{exc.start})") from None
    if len(rows) < 2:
        raise InputError(f"path: {os.fspath(path)!r} needs a header row of u values and at "
                         "least one row of deviations")

    def num(cell: str, where: str) -> float:
        try:
            x = float(cell)
        except ValueError:
            raise InputError(f"deviation: non-numeric cell {cell!r} at {where} of "
                             f"{os.fspath(path)!r}") from None
        if not math.isfinite(x):
            raise InputError(f"deviation: {cell.strip()!r} at {where} of {os.fspath(path)!r}: "
                             "every cell must be a finite number (a point not measured "
                             "needs a value, e.g. from its neighbours)")
        return x

    u = [num(c, f"header column {j + 2}") for j, c in enumerate(rows[0][1:])]
    v, d = [], []
    for i, r in enumerate(rows[1:], start=2):
        if len(r) != len(u) + 1:
            raise InputError(f"deviation: row {i} of {os.fspath(path)!r} has {len(r) - 1} "
                             f"values, the header has {len(u)} u values")
        v.append(num(r[0], f"row {i} column 1"))
        d.append([num(c, f"row {i} column {j + 2}") for j, c in enumerate(r[1:])])
    return SurfaceDeviation(np.array(u), np.array(v), np.array(d).T)


#: accepted ``units`` of a netCDF deviation variable → factor to mm
DEVIATION_UNITS: dict[str, float] = {"mm": 1.0, "um": 1e-3, "µm": 1e-3, "micrometer": 1e-3}


_MEMBERS = ("pinion", "gear")


def _check_member(member: str) -> str:
    if member not in _MEMBERS:
        raise InputError(f"member: must be one of {list(_MEMBERS)}, got {member!r}")
    return member


def read_deviation_netcdf(path: str | os.PathLike[str], member: str = "pinion",
                          ) -> SurfaceDeviation:
    """Read one member's deviation grid from a netCDF file.

    Format (as written by :func:`write_deviation_netcdf`): a Dataset with a variable
    ``pinion_deviation`` and/or ``gear_deviation`` over two dimensions, the lengthwise
    fraction ``u`` (toe 0 → heel 1) and the profile fraction ``v`` (root 0 → tip 1), each
    with a coordinate of fractions; member-specific dimension names ``u_pinion``,
    ``v_pinion`` (``u_gear``, ``v_gear``) are accepted for grids that differ between the
    members, and either dimension order. The variable's ``units`` attribute must be one of
    :data:`DEVIATION_UNITS` (``"mm"`` or ``"um"``); values are converted to mm. Positive =
    material added (outward normal), as :class:`SurfaceDeviation`.

    Parameters
    ----------
    path : str or os.PathLike
    member : {"pinion", "gear"}
        Which variable to read.

    Returns
    -------
    SurfaceDeviation
        Deviations in [mm] on the file's (u, v) grid.

    Raises
    ------
    InputError
        Unknown member, missing or unreadable file (``path``), missing variable (naming
        it and listing the file's variables), wrong dimensions, missing coordinates, missing
        or unknown ``units``, or as :class:`SurfaceDeviation`.

    Notes
    -----
    Source: the measurement grid of the seed §4.5.2 (CMM deviations on a 5 × 9 grid along
    the surface normal); the file layout is the toolkit's (geometry.core.io conventions).
    """
    _check_member(member)
    try:
        ds = read_netcdf(path, tree=False)
    except NetCDFError as exc:
        raise InputError(f"path: cannot read deviation netCDF {os.fspath(path)!r}: {exc}"
                         ) from exc
    name = f"{member}_deviation"
    if name not in ds.data_vars:
        raise InputError(f"{name}: no such variable in {os.fspath(path)!r}; it has "
                         f"{sorted(map(str, ds.data_vars))}")
    var = ds[name]
    dims = tuple(map(str, var.dims))
    for du, dv in (("u", "v"), (f"u_{member}", f"v_{member}")):
        if set(dims) == {du, dv}:
            break
    else:
        raise InputError(f"{name}: must have the dimensions (u, v) or (u_{member}, "
                         f"v_{member}) of lengthwise and profile fractions, got {dims}")
    for d in (du, dv):
        if d not in ds.coords:
            raise InputError(f"{name}: dimension {d!r} has no coordinate of fractions")
    units = var.attrs.get("units")
    if units not in DEVIATION_UNITS:
        raise InputError(f"{name}: units attribute must be one of {list(DEVIATION_UNITS)}, "
                         f"got {units!r}")
    values = var.transpose(du, dv).values * DEVIATION_UNITS[units]
    bad = np.argwhere(~np.isfinite(values))
    if bad.size:
        i, j = bad[0]
        raise InputError(f"{name}: {values[i, j]} at {du} = {ds[du].values[i]:g}, {dv} = "
                         f"{ds[dv].values[j]:g} (index {i}, {j}) of {os.fspath(path)!r}: every "
                         f"value must be finite ({len(bad)} are not)")
    return SurfaceDeviation(ds[du].values, ds[dv].values, values)


def write_deviation_netcdf(path: str | os.PathLike[str], *,
                           pinion: SurfaceDeviation | None = None,
                           gear: SurfaceDeviation | None = None,
                           units: str = "mm", description: str = "") -> Path:
    """Write pinion and/or gear deviation grids to a netCDF file, atomically.

    The layout is the one :func:`read_deviation_netcdf` reads: variables
    ``pinion_deviation`` / ``gear_deviation`` over dimensions (``u``, ``v``) with fraction
    coordinates when both members share one grid, else over (``u_pinion``, ``v_pinion``)
    and (``u_gear``, ``v_gear``). Written with :func:`geometry.core.io.write_netcdf` (conventions
    checked, version stamped, temporary file + rename).

    Parameters
    ----------
    path : str or os.PathLike
        Target file (its directory must exist).
    pinion, gear : SurfaceDeviation, optional
        At least one is required.
    units : {"mm", "um"}
        Unit the values are stored in (converted from the grids' [mm]).
    description : str
        Free text stored as the ``description`` attribute (e.g. the CMM report).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        Neither grid given, a grid not a SurfaceDeviation, or unknown ``units``.
    geometry.core.io.NetCDFError
        If the file cannot be written (an existing file is left untouched).

    Notes
    -----
    Source: as :func:`read_deviation_netcdf` (seed §4.5.2 grid; toolkit file layout).
    """
    grids = {"pinion": pinion, "gear": gear}
    if all(g is None for g in grids.values()):
        raise InputError("pinion, gear: at least one deviation grid is needed")
    for name, g in grids.items():
        if g is not None and not isinstance(g, SurfaceDeviation):
            raise InputError(f"{name}: must be a SurfaceDeviation or None, got "
                             f"{type(g).__name__}")
    if units not in ("mm", "um"):
        raise InputError(f"units: must be 'mm' or 'um', got {units!r}")
    given = {k: g for k, g in grids.items() if g is not None}
    first = next(iter(given.values()))
    shared = all(np.array_equal(g.u, first.u) and np.array_equal(g.v, first.v)
                 for g in given.values())
    data, coords = {}, {}
    for name, g in given.items():
        du, dv = ("u", "v") if shared else (f"u_{name}", f"v_{name}")
        coords[du] = (du, g.u, {"units": "1", "long_name": "lengthwise fraction of the "
                                "projection plane, toe 0 to heel 1"})
        coords[dv] = (dv, g.v, {"units": "1", "long_name": "profile fraction of the "
                                "projection plane, root 0 to tip 1"})
        data[f"{name}_deviation"] = ((du, dv), g.deviation / DEVIATION_UNITS[units], {
            "units": units,
            "long_name": f"{name} flank normal deviation, positive = material added "
                         "(outward normal)"})
    ds = xr.Dataset(data, coords=coords, attrs={
        "title": "hypoid-ltca flank deviations (seed section 4.3)",
        "description": description or "normal deviations on a measurement grid"})
    return write_netcdf(ds, path)


def _read_netcdf_member(path: str | os.PathLike[str], member: str) -> SurfaceDeviation:
    return read_deviation_netcdf(path, member=member)


def _read_csv_member(path: str | os.PathLike[str], member: str) -> SurfaceDeviation:
    return read_deviation_csv(path)


#: file suffix → reader(path, member) of :func:`read_deviations`
READERS: dict[str, Callable[[str | os.PathLike[str], str], SurfaceDeviation]] = {
    ".csv": _read_csv_member,
    ".nc": _read_netcdf_member,
    ".nc4": _read_netcdf_member,
    ".netcdf": _read_netcdf_member,
}


def read_deviations(path: str | os.PathLike[str], member: str = "pinion") -> SurfaceDeviation:
    """Read a deviation grid from a CSV or netCDF file, chosen by the suffix (:data:`READERS`).

    Parameters
    ----------
    path : str or os.PathLike
        ``*.csv`` (:func:`read_deviation_csv`, one grid per file) or ``*.nc``/``*.nc4``/
        ``*.netcdf`` (:func:`read_deviation_netcdf`).
    member : {"pinion", "gear"}
        The member whose variable a netCDF file is read for (a CSV holds one grid).

    Returns
    -------
    SurfaceDeviation
        [mm], positive = material added.

    Raises
    ------
    InputError
        Unknown suffix (listing the accepted ones), unknown member, or as the reader.

    Notes
    -----
    Source: seed §4.3 and §4.5.2 (deviations along the normal on the measurement grid).
    """
    _check_member(member)
    suffix = Path(path).suffix.lower()
    if suffix not in READERS:
        raise InputError(f"path: unknown deviation file type {suffix or '(none)'!r} of "
                         f"{os.fspath(path)!r}; accepted suffixes: {', '.join(READERS)}")
    return READERS[suffix](path, member)
