"""A DataTree written to netCDF-4 with every variable defined before any data: the
netCDF library then leaves define mode once per file instead of once per variable.

Why (issue 75): xarray writes a variable's data right after defining it, and each write
after a definition makes the netCDF-C library leave define mode (``nc_enddef``), which
writes the file's metadata and flushes the HDF5 file: a cost that grows with the
variables already in the file. The run file of ``ltca run`` (392 variables in 16 groups)
spent ≈ 0.4 s of its ≈ 0.9 s write there; 391 tiny variables written in turn took
0.34 s against 0.11 s defined first, then written (docs/performance.md, helper speed82).
The file is the same: the same groups, variables (defined in the same order), encodings
and attributes; only the order in which the library writes the data blocks differs.

Memory (issue 75, helper speed83): HDF5 keeps a written chunk in its dataset's chunk
cache until the file is closed (the define-mode flushes of xarray's order emptied them),
so writing every variable after every definition held all the data once more until
``close`` (+26 MB for the default case's 31 MB run tree). The variables of at least
:data:`UNCACHED_BYTES` are therefore written past the chunk cache (filtered and written
when their data are), and their encoded data are not kept from their definition: encoded
again by the same store when written, one at a time. Smaller variables keep both (1.0 of
the 31 MB). The write's peak over the tree: +34 → +7 MB, its CPU unchanged
(docs/performance.md, helper speed83).

Public functions
----------------
write_tree_defined_first   write a DataTree with xarray's store, every variable defined first
"""

from __future__ import annotations

import importlib
import logging
import os
from collections.abc import Mapping
from typing import Any

import xarray as xr

__all__ = ["write_tree_defined_first"]

log = logging.getLogger(__name__)

#: data of at least this many bytes [B] are encoded again when written and written past
#: HDF5's chunk cache (:func:`_uncached`); smaller ones are kept from the definition and
#: stay cached (the default case's run tree: 35 of its 391 variables above, 1.0 of its
#: 31 MB below)
UNCACHED_BYTES = 1 << 16


def _xarray_pieces() -> tuple[Any, Any, Any] | None:
    """xarray's array writer, netCDF4 store and ``dump_to_store`` where this xarray has
    them as this module uses them (xarray ≥ 2025: a store's ``get_child_store``), else
    None (the caller writes through ``to_netcdf``)."""
    try:
        from xarray.backends.common import ArrayWriter
        from xarray.backends.netCDF4_ import NetCDF4DataStore
    except ImportError:
        return None
    dump = None
    for module in ("xarray.backends.writers", "xarray.backends.api"):
        try:
            dump = importlib.import_module(module).dump_to_store
            break
        except (ImportError, AttributeError):
            continue
    if dump is None or not hasattr(NetCDF4DataStore, "get_child_store"):
        return None
    return ArrayWriter, NetCDF4DataStore, dump


def _recording_writer(array_writer: type) -> Any:
    """An instance of a subclass of xarray's ``ArrayWriter`` that records where each
    in-memory variable goes (its target and region, in the order the store defines them)
    and keeps its encoded data only where they are small (below :data:`UNCACHED_BYTES`):
    a larger variable's data are dropped, encoded again and written one variable at a
    time after every group is defined (:func:`_write_encoded`), so the encoded copies are
    not all held at once. Chunked (dask) data keep xarray's path (written at ``sync``)."""

    class RecordingWriter(array_writer):
        __slots__ = ("recorded",)

        def __init__(self) -> None:
            super().__init__()
            self.recorded: list[tuple[Any, Any, Any] | None] = []

        def add(self, source, target, region=None):
            if hasattr(source, "chunks") and getattr(source, "chunks", None) is not None:
                self.recorded.append(None)  # written by xarray at sync
                return super().add(source, target, region)
            small = getattr(source, "nbytes", UNCACHED_BYTES) < UNCACHED_BYTES
            self.recorded.append((target, region, source if small else None))
            return None

        def taken(self) -> list[tuple[Any, Any, Any] | None]:
            out, self.recorded = self.recorded, []
            return out

    return RecordingWriter()


class _Captured:
    """Stands in for a store in xarray's ``dump_to_store``: keeps the variables (not yet
    CF-encoded, their encodings set), attributes, encoding checks and unlimited
    dimensions that ``dump_to_store`` hands to ``store.store``."""

    __slots__ = ("args",)

    def __init__(self) -> None:
        self.args: tuple[Any, Any, Any, Any] | None = None

    def store(self, variables, attributes, check_encoding_set=frozenset(), writer=None,
              unlimited_dims=None) -> None:
        self.args = (variables, attributes, check_encoding_set, unlimited_dims)


def _crosses(variables: Mapping[str, Any]) -> bool:
    """Whether a variable's CF encoding reads another variable of its group (a
    ``bounds`` attribute naming one: xarray's ``cf_encoder`` then encodes the bounds
    variable with its parent's time encoding), so the group is encoded as a whole."""
    return any(isinstance(v.attrs.get("bounds"), str) and v.attrs["bounds"] in variables
               for v in variables.values())


def _uncached(target: Any, nbytes: int) -> None:
    """No HDF5 chunk cache for the target's variable where its data hold at least
    :data:`UNCACHED_BYTES`: its chunks are then filtered (compressed) and written when
    its data are, not held in the cache until the file is closed (every variable's
    data at once: +32 MB for the default case's run tree). Setting the cache reopens the
    variable's HDF5 dataset (≈ 0.3 ms), so small variables keep the cache."""
    if nbytes >= UNCACHED_BYTES:
        target.get_array(needs_lock=False).set_var_chunk_cache(size=0, nelems=1,
                                                                 preemption=1.0)


def _write_encoded(store: Any, variables: Mapping[str, Any],
                   recorded: list[tuple[Any, Any, Any] | None]) -> None:
    """Write each of a group's ``variables`` into its recorded target: the data kept
    where small, else encoded again by ``store.encode`` one variable at a time (the
    group's variables together where :func:`_crosses`) and written past the chunk cache
    (:func:`_uncached`); ``recorded`` holds (target, region, kept data or None) in the
    order the store defined the variables (None: a chunked variable xarray writes)."""
    if len(recorded) != len(variables):  # pragma: no cover - xarray's store changed
        raise RuntimeError(f"netCDF tree write: {len(recorded)} targets recorded for "
                           f"{len(variables)} variables")
    whole = None
    for (name, variable), slot in zip(variables.items(), recorded, strict=True):
        if slot is None:
            continue
        target, region, data = slot
        if data is None:
            if whole is None and _crosses(variables):
                whole = store.encode(variables, {})[0]
            data = (whole[name] if whole is not None
                    else store.encode({name: variable}, {})[0][name]).data
            _uncached(target, data.nbytes)
        if region:
            target[region] = data
        else:
            target[...] = data
        del data


def write_tree_defined_first(tree: xr.DataTree, path: str | os.PathLike[str],
                             encoding: Mapping[str, Mapping[str, Any]]) -> bool:
    """Write ``tree`` to a netCDF-4 file as ``tree.to_netcdf(path, engine="netcdf4",
    encoding=encoding)`` does, every group's variables defined before the first data
    are written (module docstring).

    Parameters
    ----------
    tree : xarray.DataTree
        The tree, ready to be written (its attributes netCDF-safe, its text
        coordinates as labels: :func:`geometry.core.io.write_netcdf` prepares it).
    path : path-like
        The file written (created or overwritten).
    encoding : mapping
        Group path → variable name → encoding, as ``DataTree.to_netcdf`` takes it.

    Returns
    -------
    bool
        True where the file was written; False where this xarray lacks the store
        functions used (nothing written: the caller writes with ``to_netcdf``).

    Raises
    ------
    Exception
        Whatever xarray or the netCDF library raise writing (the caller turns it into
        its own error; the file is then incomplete, the caller's temporary file).

    Notes
    -----
    The same steps as xarray's ``DataTree.to_netcdf`` (``_datatree_to_netcdf``, xarray
    2025–2026): one store on the file, a child store per group, ``dump_to_store`` of each
    node's own dataset (the root's with the coordinates it would pass down), one array
    writer for all. Here ``dump_to_store``'s variables are taken before the store encodes
    them; the store defines each group's variables from them (its own encoding; the data
    kept only where below :data:`UNCACHED_BYTES`), and once every group is defined each
    larger variable is encoded again by the same store and written past the chunk cache,
    one at a time (a group whose variables name ``bounds`` of each other, as a whole:
    xarray's ``cf_encoder`` encodes those together). Source: xarray's
    ``backends.common.AbstractWritableDataStore.store``; netCDF-C ``nc_enddef``; HDF5
    ``H5Pset_chunk_cache`` (a chunk larger than the cache is written directly).
    """
    pieces = _xarray_pieces()
    if pieces is None:
        return False
    array_writer, store_class, dump_to_store = pieces
    unknown = set(encoding) - set(tree.groups)
    if unknown:  # as xarray's check
        raise ValueError(f"unexpected encoding group name(s) provided: {unknown}")
    writer = _recording_writer(array_writer)
    root = store_class.open(os.fspath(path), mode="w", format="NETCDF4")
    try:
        defined = []
        for node in tree.subtree:
            at_root = node is tree
            store = root if at_root else root.get_child_store(node.path)
            captured = _Captured()
            dump_to_store(node.to_dataset(inherit=at_root), captured, writer,
                          encoding=encoding.get(node.path))
            variables, attributes, check, unlimited = captured.args
            store.store(variables, attributes, check, writer, unlimited_dims=unlimited)
            defined.append((store, variables, writer.taken()))
        for store, variables, recorded in defined:
            _write_encoded(store, variables, recorded)
        writer.sync()
    finally:
        root.close()
    log.debug("wrote %s, every variable defined first", path)
    return True
