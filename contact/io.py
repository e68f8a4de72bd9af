"""netCDF conventions of the toolkit: one module, used by every stage.

Every stored variable carries ``units`` (UDUNITS strings) and ``long_name``;
attributes are only netCDF-safe types (str, int, float, or 1-D arrays of
numbers); every file records the toolkit version and the inputs that made it;
writing is atomic (a temporary file in the target directory, then a rename), so
a failure never leaves a half-written file behind.

Public functions
----------------
netcdf_safe_attrs   convert an attribute dict to netCDF-safe types (bool → 0/1, dict → JSON)
check_conventions   raise if a variable lacks ``units``/``long_name`` or an attribute is unsafe
write_netcdf        write a Dataset or DataTree atomically, stamped with version and inputs
read_netcdf         read a file written by :func:`write_netcdf` fully into memory
"""

from __future__ import annotations

import datetime as _dt
import json
import logging
import os
import tempfile
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from geometry import __version__
from geometry.conventions import data_var
from geometry.errors import InputError, LTCAError

__all__ = [
    "NetCDFError",
    "check_conventions",
    "data_var",
    "netcdf_safe_attrs",
    "read_netcdf",
    "write_netcdf",
]

log = logging.getLogger(__name__)

_ENGINE = "netcdf4"


class NetCDFError(LTCAError, OSError):
    """A file could not be written or read, or a dataset breaks the conventions."""


def _safe_value(key: str, value: Any) -> Any:
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    if isinstance(value, (str, int, float, np.integer, np.floating)):
        if isinstance(value, (float, np.floating)) and not np.isfinite(value):
            # NaN attributes do not compare equal after a round trip; store as text
            return str(float(value))
        return value
    if isinstance(value, Mapping):
        return json.dumps(value, sort_keys=True, default=str)
    if isinstance(value, (list, tuple, np.ndarray)):
        arr = np.asarray(value)
        if arr.ndim == 1 and arr.dtype.kind in "iuf" and arr.size > 0:
            return arr
        if arr.ndim == 1 and arr.dtype.kind == "b" and arr.size > 0:
            return arr.astype(np.int8)
        return json.dumps(np.asarray(value, dtype=object).tolist(), default=str)
    if value is None:
        raise InputError(
            f"attribute {key!r} is None: netCDF has no null attribute; omit it or give a value"
        )
    raise InputError(
        f"attribute {key!r} has type {type(value).__name__}; netCDF accepts str, int, float "
        "or 1-D numeric arrays (dicts and lists are stored as JSON text)"
    )


def netcdf_safe_attrs(attrs: Mapping[str, Any]) -> dict[str, Any]:
    """Return a copy of ``attrs`` with every value converted to a netCDF-safe type.

    Parameters
    ----------
    attrs : mapping of str to value
        Booleans become 0/1, mappings and non-numeric sequences become JSON text,
        non-finite floats become their text, 1-D numeric sequences become arrays.

    Returns
    -------
    dict
        New attribute dictionary.

    Raises
    ------
    InputError
        For ``None`` or a type netCDF cannot store (the message names the key).
    """
    return {str(k): _safe_value(str(k), v) for k, v in attrs.items()}


def _datasets(obj: xr.Dataset | xr.DataTree) -> list[tuple[str, xr.Dataset]]:
    if isinstance(obj, xr.DataTree):
        return [(node.path, node.to_dataset(inherit=False)) for node in obj.subtree]
    return [("/", obj)]


def check_conventions(obj: xr.Dataset | xr.DataTree) -> None:
    """Check a Dataset or every node of a DataTree against the toolkit's conventions.

    Every numeric variable (data or coordinate) must carry ``units`` and
    ``long_name``; every text variable a ``long_name``; every attribute must be
    netCDF-safe.

    Raises
    ------
    NetCDFError
        Listing each offending variable or attribute with its group path.
    """
    problems: list[str] = []
    for path, ds in _datasets(obj):
        for name, var in ds.variables.items():
            numeric = var.dtype.kind in "iufcbmM"
            required = ("units", "long_name") if numeric else ("long_name",)
            for key in required:
                if key not in var.attrs:
                    problems.append(f"{path}:{name} has no {key!r}")
            for key, val in var.attrs.items():
                try:
                    _safe_value(key, val)
                except InputError as exc:
                    problems.append(f"{path}:{name}: {exc}")
        for key, val in ds.attrs.items():
            try:
                _safe_value(key, val)
            except InputError as exc:
                problems.append(f"{path} (group attribute): {exc}")
    if problems:
        raise NetCDFError("dataset breaks the netCDF conventions:\n  " + "\n  ".join(problems))


def _stamp(ds: xr.Dataset, inputs: str | None) -> xr.Dataset:
    ds = ds.copy(deep=False)
    ds.attrs = netcdf_safe_attrs(ds.attrs)
    for name in ds.variables:
        ds[name].attrs = netcdf_safe_attrs(ds[name].attrs)
    ds.attrs.setdefault("toolkit", "hypoid-ltca")
    ds.attrs["toolkit_version"] = __version__
    ds.attrs.setdefault("Conventions", "CF-1.10")
    if inputs is not None:
        ds.attrs["inputs"] = inputs
    return ds


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_netcdf(
    obj: xr.Dataset | xr.DataTree,
    path: str | os.PathLike[str],
    *,
    inputs: str | None = None,
) -> Path:
    """Write a Dataset or DataTree to netCDF4 atomically.

    The data are checked against :func:`check_conventions`, attributes are made
    netCDF-safe, the root group is stamped with the toolkit version, the creation
    time (``history``) and ``inputs`` (e.g. the case as TOML text), then written to a
    temporary file beside ``path`` which is renamed onto ``path`` only once complete.

    Parameters
    ----------
    obj : xarray.Dataset or xarray.DataTree
    path : path-like
        Target file; its directory must exist.
    inputs : str, optional
        Text recording what produced the data (stored in the ``inputs`` attribute).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    NetCDFError
        If the data break the conventions or the file cannot be written; a
        pre-existing file at ``path`` is then left untouched.
    """
    path = Path(path)
    if not path.parent.exists():
        raise NetCDFError(f"output directory {str(path.parent)!r} does not exist")
    check_conventions(obj)
    created = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%dT%H:%M:%SZ")
    if isinstance(obj, xr.DataTree):
        tree = obj.copy()
        for node in tree.subtree:
            node.dataset = _stamp(node.to_dataset(inherit=False), None)
        root = tree.to_dataset(inherit=False)
        root = _stamp(root, inputs)
        root.attrs.setdefault("history", f"{created} written by hypoid-ltca {__version__}")
        tree.dataset = root
        out: xr.Dataset | xr.DataTree = tree
    else:
        out = _stamp(obj, inputs)
        out.attrs.setdefault("history", f"{created} written by hypoid-ltca {__version__}")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        out.to_netcdf(tmp, engine=_ENGINE)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp creates 0600; give the usual mode
        os.replace(tmp, path)
    except Exception as exc:
        Path(tmp).unlink(missing_ok=True)
        raise NetCDFError(f"could not write {str(path)!r}: {exc}") from exc
    log.info("wrote %s", path)
    return path


def read_netcdf(path: str | os.PathLike[str], *, tree: bool | None = None):
    """Read a file written by :func:`write_netcdf`, fully into memory.

    Parameters
    ----------
    path : path-like
    tree : bool, optional
        Return an ``xarray.DataTree`` (True) or a ``Dataset`` (False). By default a
        DataTree when the file has groups, else a Dataset.

    Returns
    -------
    xarray.Dataset or xarray.DataTree

    Raises
    ------
    NetCDFError
        If the file is missing or unreadable.
    """
    path = Path(path)
    if not path.is_file():
        raise NetCDFError(f"no such netCDF file: {str(path)!r}")
    try:
        if tree is None:
            import netCDF4

            with netCDF4.Dataset(path) as nc:
                tree = bool(nc.groups)
        if tree:
            with xr.open_datatree(path, engine=_ENGINE) as dt:
                return dt.load().copy()
        with xr.open_dataset(path, engine=_ENGINE) as ds:
            return ds.load()
    except NetCDFError:
        raise
    except Exception as exc:
        raise NetCDFError(f"could not read {str(path)!r}: {exc}") from exc
