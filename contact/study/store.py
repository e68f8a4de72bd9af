"""Streaming a study's results to disk as they finish, and resuming a killed study.

A study writing ``map.nc`` keeps its finished points in ``map.nc.parts/``: a
``study.json`` that says which study the parts belong to (a fingerprint of the shared
inputs and the list of points) and chunk files ``chunk-NNNNNNN.nc``, each written
atomically (:func:`geometry.core.io.write_netcdf`) with the results of a few points. The
client holds at most one chunk in memory, so memory stays flat in the number of points.
When every point is in, the chunks are combined into ``map.nc`` (atomically) and the
parts directory is removed. A study started again with the same output finds the parts,
checks that they belong to the same study, and computes only the points not in them.

Public names
------------
ResultStore   the parts directory of one study output
"""

from __future__ import annotations

import json
import logging
import shutil
import time
from pathlib import Path

import numpy as np
import xarray as xr

from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf, write_netcdf

__all__ = ["ResultStore"]

log = logging.getLogger(__name__)

_MANIFEST = "study.json"


class ResultStore:
    """The parts directory of a study output (``OUTPUT.parts``).

    Parameters
    ----------
    output : path-like
        The study's final netCDF file.
    manifest : dict
        JSON-serialisable description of the study (fingerprint of the shared inputs
        and the points); parts left by a study with another manifest are refused.
    chunk_size : int
        Points per chunk file (a chunk is also written after ``flush_seconds``).
    flush_seconds : float
        Longest time [s] a finished point waits in memory before its chunk is written.

    Raises
    ------
    InputError
        If ``OUTPUT.parts`` holds the parts of a different study.
    """

    def __init__(self, output: str | Path, manifest: dict, *, chunk_size: int = 32,
                 flush_seconds: float = 30.0) -> None:
        self.output = Path(output)
        self.parts = self.parts_dir(output)
        self.chunk_size = max(1, int(chunk_size))
        self.flush_seconds = float(flush_seconds)
        self._buffer: list[xr.Dataset] = []
        self._since = time.monotonic()
        text = json.dumps(manifest, sort_keys=True)
        path = self.parts / _MANIFEST
        if path.is_file():
            if path.read_text(encoding="utf-8") != text:
                raise InputError(
                    f"output: {str(self.parts)!r} holds the finished points of a different "
                    "study (other case, inputs or points); remove it to start afresh, or "
                    "choose another output file")
        else:
            self.parts.mkdir(parents=True, exist_ok=True)
            with atomic_path(path) as tmp:
                tmp.write_text(text, encoding="utf-8")

    @staticmethod
    def parts_dir(output: str | Path) -> Path:
        """The parts directory of the study output ``output``."""
        out = Path(output)
        return out.with_name(out.name + ".parts")

    @staticmethod
    def remove_parts(output: str | Path) -> None:
        """Delete the parts directory of ``output`` (once the final file is written)."""
        shutil.rmtree(ResultStore.parts_dir(output), ignore_errors=True)

    def chunks(self) -> list[Path]:
        """The chunk files written so far."""
        return sorted(self.parts.glob("chunk-*.nc"))

    def done(self) -> set[int]:
        """Indices of the points whose results are on disk."""
        out: set[int] = set()
        for f in self.chunks():
            ds = read_netcdf(f, tree=False)
            out.update(int(i) for i in ds["point"].values)
        return out

    def add(self, result: xr.Dataset) -> None:
        """Keep a finished point's results (a dataset over a ``point`` dim of length 1);
        write a chunk when it is full or old enough."""
        self._buffer.append(result)
        if (len(self._buffer) >= self.chunk_size
                or time.monotonic() - self._since >= self.flush_seconds):
            self.flush()

    def flush(self) -> None:
        """Write the points in memory as one chunk file (atomically)."""
        if not self._buffer:
            self._since = time.monotonic()
            return
        ds = xr.concat(self._buffer, dim="point")
        first = int(ds["point"].values.min())
        name = self.parts / f"chunk-{first:07d}-{len(self._buffer):05d}.nc"
        write_netcdf(ds, name, complevel=1)
        log.debug("wrote %s", name)
        self._buffer.clear()
        self._since = time.monotonic()

    def combined(self) -> xr.Dataset:
        """All points on disk in point order (after :meth:`flush`)."""
        parts = [read_netcdf(f, tree=False) for f in self.chunks()]
        if not parts:
            raise InputError(f"output: no finished points in {str(self.parts)!r}")
        ds = xr.concat(parts, dim="point")
        order = np.argsort(ds["point"].values, kind="stable")
        return ds.isel(point=order)
