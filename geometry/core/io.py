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
without_stamps      a dataset read back without what write_netcdf stamped (round-trip tests)
read_netcdf         read a file written by :func:`write_netcdf` fully into memory
"""

from __future__ import annotations

import contextlib
import datetime as _dt
import hashlib
import json
import logging
import os
import sys
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from geometry.core.atomic_files import atomic_path, write_failure
from geometry.core.conventions import data_var
from geometry.core.errors import FileWriteError, InputError, LTCAError
from geometry.core.netcdf_tree_write import write_tree_defined_first
from geometry.core.validation import integer
from geometry.core.version import __version__

__all__ = [
    "ACDD_ATTRS",
    "ACDD_NOT_APPLICABLE",
    "CONVENTIONS",
    "DEFAULT_COMPLEVEL",
    "STAMPED_ATTRS",
    "STAMPED_VARIABLE_ATTRS",
    "NetCDFError",
    "check_conventions",
    "data_var",
    "netcdf_safe_attrs",
    "read_netcdf",
    "without_stamps",
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


#: the conventions every file declares (CF for the variables, ACDD for the discovery
#: attributes of every group)
CONVENTIONS = "CF-1.8, ACDD-1.3"
#: what the toolkit does, in one sentence (the default ``summary`` of a group)
_DESCRIPTION = (
    "Loaded tooth contact analysis of hypoid and spiral bevel gears: machine-setting "
    "geometry, ease-off unloaded tooth contact analysis, shell compliance, quadratic-"
    "programming load distribution and mixed-EHL efficiency"
)
#: ACDD 1.3 discovery attributes stamped on every group (so that a group extracted on its
#: own still says what it is, who made it and under which licence); docs/nomenclature.md
ACDD_ATTRS = {
    "keywords": (
        "hypoid gears, spiral bevel gears, tooth contact analysis, loaded tooth contact "
        "analysis, ease-off, transmission error, contact pressure, mechanical efficiency"
    ),
    "license": "BSD-3-Clause",
    "institution": "the hypoid-ltca developers",
    "creator_name": "the hypoid-ltca developers",
    "creator_type": "group",
    "product_version": __version__,
    "references": (
        "Kolivand, M., 2009. Development of tooth contact and mechanical efficiency models "
        "for face-milled and face-hobbed hypoid and spiral bevel gears. Ph.D. dissertation, "
        "The Ohio State University"
    ),
    "naming_authority": "hypoid-ltca",
    "project": "hypoid-ltca: loaded tooth contact analysis of hypoid and spiral bevel gears",
    "program": "hypoid-ltca",
    "processing_level": "model output: computed from a case file by hypoid-ltca (no "
                        "measured data unless the case names surface-deviation files)",
    "publisher_name": "the hypoid-ltca developers",
    "publisher_type": "group",
    "publisher_institution": "the hypoid-ltca developers",
    "creator_institution": "the hypoid-ltca developers",
    "acknowledgement": "Method after M. Kolivand's 2009 Ohio State dissertation (seed "
                       "Eq. 2.1-5.11); ISO 23509 blank geometry",
    "comment": "Units are UDUNITS strings on every variable (mm, rad, urad, N, N/mm, MPa, "
               "m/s, degC, Pa s, W, 1); names follow docs/nomenclature.md. Text coordinates "
               "(xyz, path, transition) are written as CF label variables <dim>_label; "
               "geometry.core.io.read_netcdf restores them.",
}
#: ACDD attributes (prefixes) that do not apply to a computed gear analysis and are never
#: written: no position on the earth or time coverage (geospatial_*, time_coverage_*), no
#: instrument or platform, no standard names (standard_name_vocabulary: the CF table has
#: none for gear quantities), no published e-mail or web address (creator_/publisher_
#: email, url, metadata_link), no controlled keyword vocabulary, no contributors beyond the
#: creator, no formal issue (date_issued)
ACDD_NOT_APPLICABLE = ("geospatial_", "time_coverage_", "instrument", "platform",
                       "standard_name_vocabulary", "creator_email", "creator_url",
                       "publisher_email", "publisher_url", "metadata_link",
                       "keywords_vocabulary", "contributor_", "date_issued")
#: group attributes :func:`write_netcdf` adds where the data do not set them
STAMPED_ATTRS = ("toolkit", "toolkit_version", "Conventions", "title", "summary", *ACDD_ATTRS,
                 "source", "date_created", "date_modified", "date_metadata_modified", "history",
                 "inputs", "id")
#: variable attributes :func:`write_netcdf` adds where the data do not set them
STAMPED_VARIABLE_ATTRS = ("coverage_content_type",)
#: zlib level of the data variables unless the caller says otherwise (lossless; the
#: default ``ltca run`` file shrinks from 23.6 MB to ~3 MB, most of it NaN padding)
DEFAULT_COMPLEVEL = 4


def _stamp(ds: xr.Dataset, inputs: str | None, *, created: str, path: str = "/",
           root_title: str | None = None) -> xr.Dataset:
    ds = ds.copy(deep=False)
    ds.attrs = netcdf_safe_attrs(ds.attrs)
    # each variable's own attributes (the shallow copy's Variable objects, as ds[name]
    # holds them), not through ds[name]: a DataArray built with its coordinates per
    # call, 0.2 s of the 392 variables of a 10x43's ``ltca run`` file (issue 75)
    coords = set(ds.coords)
    for name, var in ds.variables.items():
        var.attrs = netcdf_safe_attrs(var.attrs)
        var.attrs.setdefault("coverage_content_type",
                             _content_type_of(var.attrs, name in coords))
    ds.attrs.setdefault("toolkit", "hypoid-ltca")
    ds.attrs["toolkit_version"] = __version__
    ds.attrs["Conventions"] = CONVENTIONS
    if "title" not in ds.attrs:
        ds.attrs["title"] = (f"{root_title}: {path}" if root_title and path != "/"
                             else f"hypoid-ltca output {path}")
    ds.attrs.setdefault("summary", f"{ds.attrs['title']}. {_DESCRIPTION}.")
    for key, value in ACDD_ATTRS.items():
        ds.attrs.setdefault(key, value)
    ds.attrs.setdefault("source", f"hypoid-ltca {__version__}")
    ds.attrs.setdefault("date_created", created)
    ds.attrs.setdefault("date_modified", created)  # a file is written once, whole
    ds.attrs.setdefault("date_metadata_modified", created)
    ds.attrs.setdefault("history", f"{created} written by hypoid-ltca {__version__}")
    if inputs is not None:
        ds.attrs["inputs"] = inputs
        # ACDD id: unique within the naming authority and the same for the same inputs
        digest = hashlib.sha256(inputs.encode("utf-8")).hexdigest()[:16]
        ds.attrs.setdefault("id", f"hypoid-ltca:{ds.attrs.get('case', 'output')}:{digest}")
    return ds


def _content_type_of(attrs: dict[str, Any], coordinate: bool) -> str:
    """ACDD ``coverage_content_type`` (ISO 19115-1 code) of a variable the stage left
    unlabelled, from its attributes and whether it is a coordinate: coordinates are
    ``coordinate``, enumerations (``flag_values``) ``auxiliaryInformation``, everything
    else a ``modelResult``."""
    if coordinate:
        return "coordinate"
    if "flag_values" in attrs or "flag_masks" in attrs:
        return "auxiliaryInformation"
    return "modelResult"


def _encoding(ds: xr.Dataset, complevel: int) -> dict[str, dict[str, Any]]:
    """netCDF encoding of each variable: no ``_FillValue`` on coordinates (CF 2.5.1) nor
    on a variable without missing values; NaN as the fill of float data that has NaN;
    zlib (with shuffle) at ``complevel`` on numeric data variables (0: none)."""
    out: dict[str, dict[str, Any]] = {}
    for name, var in ds.variables.items():
        enc: dict[str, Any] = {k: v for k, v in var.encoding.items() if k == "dtype"}
        kind = var.dtype.kind
        missing = (name not in ds.coords and kind in "fc"
                   and bool(np.isnan(np.asarray(var.values)).any()))
        if kind in "fciub":
            enc["_FillValue"] = np.nan if missing else None
        if kind == "i" and var.dtype.itemsize > 4 and _fits_int32(var):
            # CF 1.8 §2.2 knows no 64-bit integers: counts and indices fit 32 bits
            enc["dtype"] = np.dtype("int32")
        if kind in "UO" and _is_text(var):
            # text as CF's char arrays (CF 1.8 §2.2; a string-length dimension), which
            # every CF reader and checker takes; read back as text by xarray
            enc["dtype"] = "S1"
        if name not in ds.coords and kind in "fciub" and var.ndim > 0 and complevel > 0:
            enc.update(zlib=True, complevel=int(complevel), shuffle=True)
        out[str(name)] = enc
    return out


#: the attribute that marks a text label variable written for a text dimension coordinate
LABEL_OF = "label_of_dimension"


def _text_labels(ds: xr.Dataset) -> xr.Dataset:
    """Text dimension coordinates (``xyz`` = x, y, z …) as CF label variables: a CF
    coordinate variable must be numeric (CF 1.8 §1.3, §5), so ``xyz`` is written as the
    auxiliary coordinate ``xyz_label`` along ``xyz`` (CF §6.1), marked with
    :data:`LABEL_OF`; :func:`read_netcdf` restores the coordinate."""
    text = [d for d in ds.dims if d in ds.coords and ds[d].dtype.kind in "UO"]
    if not text:
        return ds
    out = ds.rename_vars({d: f"{d}_label" for d in text})
    for d in text:
        out[f"{d}_label"].attrs[LABEL_OF] = str(d)
    return out.drop_indexes([f"{d}_label" for d in text if f"{d}_label" in out.xindexes],
                            errors="ignore")


def _restore_labels(ds: xr.Dataset) -> xr.Dataset:
    """The text dimension coordinates :func:`_text_labels` wrote as label variables."""
    labels = {k: str(v.attrs[LABEL_OF]) for k, v in ds.coords.items() if LABEL_OF in v.attrs}
    if not labels:
        return ds
    out = ds.rename_vars(labels)
    for d in labels.values():
        out[d].attrs.pop(LABEL_OF)
        out = out.set_xindex(d)
    return out


def _fits_int32(var: xr.Variable) -> bool:
    values = np.asarray(var.values)
    info = np.iinfo(np.int32)
    return values.size == 0 or (int(values.min()) >= info.min and int(values.max()) <= info.max)


def _is_text(var: xr.Variable) -> bool:
    return all(isinstance(v, str) for v in np.ravel(np.asarray(var.values, dtype=object)))


def without_stamps(written: xr.Dataset, original: xr.Dataset) -> xr.Dataset:
    """``written`` (a dataset read back) without the attributes :func:`write_netcdf`
    stamped on it that ``original`` (the dataset given to it) did not have: for
    round-trip comparisons."""
    out = written.copy(deep=False)
    out.attrs = {k: v for k, v in out.attrs.items()
                 if k in original.attrs or k not in STAMPED_ATTRS}
    for name in out.variables:
        before = original[name].attrs if name in original.variables else {}
        out[name].attrs = {k: v for k, v in out[name].attrs.items()
                           if k in before or k not in STAMPED_VARIABLE_ATTRS}
    return out


def write_netcdf(
    obj: xr.Dataset | xr.DataTree,
    path: str | os.PathLike[str],
    *,
    inputs: str | None = None,
    complevel: int = DEFAULT_COMPLEVEL,
) -> Path:
    """Write a Dataset or DataTree to netCDF4 atomically.

    The data are checked against :func:`check_conventions`, attributes are made
    netCDF-safe, every group is stamped with the toolkit version, the conventions
    (:data:`CONVENTIONS`), the ACDD discovery attributes (:data:`ACDD_ATTRS`, a
    ``summary``, ``date_created``, ``history``) and every variable with its
    ``coverage_content_type``, where the data do not set them; the root group also
    records ``inputs`` (e.g. the case as TOML text). Coordinates and variables without
    missing values carry no ``_FillValue``; numeric data variables are zlib-compressed
    (lossless). The file is written to a temporary file beside ``path`` which is renamed
    onto ``path`` only once complete; an interrupt (Ctrl-C, SIGTERM) during the write
    leaves the old file and no temporary file (:func:`geometry.core.atomic_files.atomic_path`).
    A DataTree's variables are all defined before their data are written
    (:func:`geometry.core.netcdf_tree_write.write_tree_defined_first`: the same file,
    ≈ 0.5 s less for ``ltca run``'s 392 variables, issue 75).

    Parameters
    ----------
    obj : xarray.Dataset or xarray.DataTree
    path : path-like
        Target file; its directory must exist.
    inputs : str, optional
        Text recording what produced the data (stored in the ``inputs`` attribute).
    complevel : int
        zlib level 1–9 of the numeric data variables; 0 writes them uncompressed.

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
    complevel = integer("complevel", complevel, 0, 9)
    check_conventions(obj)
    created = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%dT%H:%M:%SZ")
    encoding: dict[str, Any]
    if isinstance(obj, xr.DataTree):
        tree = obj.copy()
        title = tree.attrs.get("title")
        for node in tree.subtree:
            node.dataset = _stamp(_text_labels(node.to_dataset(inherit=False)),
                                  inputs if node.is_root else None, created=created,
                                  path=node.path, root_title=title)
        encoding = {node.path: _encoding(node.to_dataset(inherit=False), complevel)
                    for node in tree.subtree}
        out: xr.Dataset | xr.DataTree = tree
    else:
        out = _stamp(_text_labels(obj), inputs, created=created)
        encoding = _encoding(out, complevel)
    try:
        # a temporary file renamed onto path once complete; Ctrl-C/SIGTERM held until the
        # HDF5 library returns, then the old file kept (geometry.core.atomic_files)
        with atomic_path(path) as tmp, _local_write_lock(out):
            # a tree's variables all defined before its data are written: the netCDF
            # library leaves define mode once, not per variable (issue 75, speed82)
            if not (isinstance(out, xr.DataTree)
                    and write_tree_defined_first(out, tmp, encoding)):
                out.to_netcdf(tmp, engine=_ENGINE, encoding=encoding)
    except FileWriteError as exc:   # the disk's or the directory's fault, said in words
        raise NetCDFError(str(exc)) from exc
    except Exception as exc:
        # the netCDF library reports a full disk as "HDF error": put in words when it is
        reason = write_failure(path, exc)
        raise NetCDFError(reason or f"could not write {str(path)!r}: {exc}") from exc
    log.info("wrote %s", path)
    return path


@contextlib.contextmanager
def _local_write_lock(obj: xr.Dataset | xr.DataTree) -> Iterator[None]:
    """The write of in-memory data under the HDF5 library's thread lock only.

    xarray takes a write lock for the dask scheduler in use, and while a
    ``distributed.Client`` is the default (a study's client) that is a cluster-wide
    ``distributed.Lock``: a round trip to the scheduler for every variable written
    (~700 for a 121-point study's chunk files; ~1 s of the client's CPU, which the two
    workers of a 2-core machine then lack). Data held in memory are written by this
    thread alone, so within the block dask's scheduler is the threaded one (xarray's
    lock is then its per-file thread lock, with the netCDF library's own). Data that are
    dask arrays, which a cluster may compute, keep xarray's choice. (dask's configuration
    is the process's, not the thread's: for the write's duration another thread's
    ``dask.compute`` would also run threaded; the study client computes nothing on dask
    while it writes its chunks.)
    """
    dask = sys.modules.get("dask")
    nodes = obj.subtree if isinstance(obj, xr.DataTree) else [obj]
    lazy = any(v.chunks is not None for node in nodes for v in node.variables.values())
    if dask is None or lazy:
        yield
        return
    with dask.config.set(scheduler="threads"):
        yield


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
        The file's data and attributes: a DataTree when the file has groups.

    Raises
    ------
    NetCDFError
        If the file is missing or unreadable.
    """
    path = Path(path)
    if not path.is_file():
        raise NetCDFError(f"no such netCDF file: {str(path)!r}")
    problem = _not_readable(path)
    if problem:
        raise NetCDFError(f"could not read {str(path)!r}: {problem}")
    try:
        if tree is None:
            import netCDF4

            with netCDF4.Dataset(path) as nc:
                tree = bool(nc.groups)
        if tree:
            with xr.open_datatree(path, engine=_ENGINE) as dt:
                out = dt.load().copy()
            for node in out.subtree:
                node.dataset = _restore_labels(node.to_dataset(inherit=False))
            return out
        with xr.open_dataset(path, engine=_ENGINE) as ds:
            return _restore_labels(ds.load())
    except NetCDFError:
        raise
    except Exception as exc:
        log.debug("reading %s failed: %r", path, exc)
        raise NetCDFError(f"could not read {str(path)!r}: "
                          f"{_not_readable(path, failed=True)}") from exc


#: the first bytes of a netCDF file: classic (CDF\x01, \x02, \x05) or netCDF-4 (HDF5)
_HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


def _not_readable(path: Path, *, failed: bool = False) -> str | None:
    """Why a file cannot be a readable netCDF file, in words (None if it looks like one
    and ``failed`` is False): empty, not a netCDF file (and what it looks like: UTF-8 text
    such as a case or oil file), no permission, or — when the netCDF library failed on a
    file that starts as netCDF does — truncated or damaged."""
    try:
        size = path.stat().st_size
        with open(path, "rb") as f:
            head = f.read(512)
    except PermissionError:
        return "no permission to read it"
    except OSError as exc:
        return f"it cannot be opened ({exc.strerror or 'operating-system error'})"
    if size == 0:
        return "the file is empty (0 bytes), not a netCDF file"
    if not (head[:3] == b"CDF" or head[:8] == _HDF5_SIGNATURE):
        try:
            text = head.decode("utf-8")
        except UnicodeDecodeError:
            return "not a netCDF file (binary data of another format)"
        looks = ("a TOML file (a case, oil or coefficient file?)"
                 if "=" in text or text.lstrip().startswith(("#", "[")) else "a text file")
        return f"not a netCDF file: it is UTF-8 text, {looks}"
    if failed:
        return f"a netCDF file that is truncated or damaged ({size} bytes)"
    return None
