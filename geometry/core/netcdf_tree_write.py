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

Public functions
----------------
write_tree_defined_first   write a DataTree with xarray's store, its data queued to the end
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


def _queued_writer(array_writer: type) -> Any:
    """An instance of a subclass of xarray's ``ArrayWriter`` that queues the writes of
    in-memory data (xarray's writes them at once) until :meth:`write_queued`; chunked
    (dask) data keep xarray's path (written at ``sync``)."""

    class QueuedWriter(array_writer):
        __slots__ = ("queued",)

        def __init__(self) -> None:
            super().__init__()
            self.queued: list[tuple[Any, Any, Any]] = []

        def add(self, source, target, region=None):
            if hasattr(source, "chunks") and getattr(source, "chunks", None) is not None:
                return super().add(source, target, region)
            self.queued.append((source, target, region))
            return None

        def write_queued(self) -> None:
            while self.queued:
                source, target, region = self.queued.pop(0)
                if region:
                    target[region] = source
                else:
                    target[...] = source

    return QueuedWriter()


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
    writer for all; here the writer queues the data until every group is defined.
    """
    pieces = _xarray_pieces()
    if pieces is None:
        return False
    array_writer, store_class, dump_to_store = pieces
    unknown = set(encoding) - set(tree.groups)
    if unknown:  # as xarray's check
        raise ValueError(f"unexpected encoding group name(s) provided: {unknown}")
    writer = _queued_writer(array_writer)
    root = store_class.open(os.fspath(path), mode="w", format="NETCDF4")
    try:
        for node in tree.subtree:
            at_root = node is tree
            store = root if at_root else root.get_child_store(node.path)
            dump_to_store(node.to_dataset(inherit=at_root), store, writer,
                          encoding=encoding.get(node.path))
        writer.write_queued()
        writer.sync()
    finally:
        root.close()
    log.debug("wrote %s, every variable defined first", path)
    return True
