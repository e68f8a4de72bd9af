"""Streaming a study's results to disk as they finish, and resuming a killed study.

A study writing ``map.nc`` keeps its finished points in ``map.nc.parts/``: a
``study.json`` that says which study the parts belong to (a fingerprint of the shared
inputs and the list of points) and chunk files ``chunk-NNNNNNN-NNNNN.nc`` (first point,
number of points), each written atomically (:func:`geometry.core.io.write_netcdf`) with
the results of a few points over a ``point`` dimension. The client holds at most one
chunk in memory, so memory stays flat in the number of points. When every point is in,
the chunks are combined into ``map.nc`` (atomically) and the parts directory is removed.
A study started again with the same output finds the parts, checks that they belong to
the same study, and computes only the points not in them.

Debris
------
Every chunk is checked when the store is opened for resume (:meth:`ResultStore.done`)
and before the chunks are combined (:meth:`ResultStore.combined`): it must be a readable
netCDF file with an integer ``point`` coordinate (points not in an earlier chunk) and
meet the study's :class:`ChunkSpec` (its variables, no NaN where a finished value
belongs, its inputs). A chunk that fails — truncated, empty, not netCDF, of another
study, holding NaN results — is named in one warning with the reason, moved to
``map.nc.parts/set-aside/`` (kept, never read again) and its points are computed again.

Public names
------------
ResultStore   the parts directory of one study output
ChunkSpec     what a study's chunk files must hold (checked at resume and combine)
SET_ASIDE     the subdirectory of the parts directory that debris is moved to
"""

from __future__ import annotations

import json
import logging
import shutil
import time
from collections.abc import Callable, Collection, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf, write_netcdf

__all__ = ["SET_ASIDE", "ChunkSpec", "ResultStore"]

log = logging.getLogger(__name__)

_MANIFEST = "study.json"
_CHUNKS = "chunk-*.nc"

#: the subdirectory of ``OUTPUT.parts`` holding the chunk files that failed their check
#: (never matched by the chunk pattern, kept by :meth:`ResultStore.remove_parts`)
SET_ASIDE = "set-aside"


def _listed(values: Collection[Any], most: int = 5) -> str:
    """``a, b, c`` (the first ``most`` values, then how many more)."""
    vals = [str(v) for v in values]
    text = ", ".join(vals[:most])
    return text + (f" and {len(vals) - most} more" if len(vals) > most else "")


@dataclass(frozen=True)
class ChunkSpec:
    """What the chunk files of one study must hold, beyond a readable ``point`` coordinate.

    Parameters
    ----------
    points : int, optional
        Number of points of the study: every index must be in ``0 … points - 1``
        (default: the length of ``coords``, if given).
    variables : collection of str, optional
        The data variables every chunk of the study holds. Given, a chunk lacking one, or
        holding a data variable neither here nor in ``optional``, is not this study's.
        None (default): any variables.
    optional : collection of str
        Data variables a chunk may also hold (e.g. only at the points that succeeded).
    finite : collection of str
        Variables that must be finite (no NaN or infinity, over all their other dims) at
        every point whose ``status`` is 0 — the points that hold a finished result; the
        chunk must then have a ``status`` variable.
    coords : mapping of str to array_like (points,), optional
        Per-point input coordinates of the study, in point order: a chunk's coordinate
        ``name`` must equal ``coords[name][i]`` at its point ``i`` (its points are this
        study's points).
    check : callable, optional
        ``check(ds) -> str | None``, run last on a chunk that passed the other checks: a
        reason in plain words (completing "chunk X ...") if the chunk is not to be
        trusted, else None.

    Raises
    ------
    InputError
        A negative ``points`` or a ``coords`` entry that is not one value per point.
    """

    points: int | None = None
    variables: Collection[str] | None = None
    optional: Collection[str] = ()
    finite: Collection[str] = ()
    coords: Mapping[str, Any] | None = field(default=None, repr=False)
    check: Callable[[xr.Dataset], str | None] | None = None

    def __post_init__(self) -> None:
        if self.points is not None and (not isinstance(self.points, (int, np.integer))
                                        or self.points < 0):
            raise InputError(f"points: must be a whole number >= 0, got {self.points!r}")
        if self.coords is not None:
            coords = {k: np.asarray(v) for k, v in self.coords.items()}
            for k, v in coords.items():
                if v.ndim != 1 or (self.points is not None and v.size != self.points):
                    raise InputError(f"coords: {k!r} must hold one value per point, got "
                                     f"shape {v.shape}")
            object.__setattr__(self, "coords", coords)

    def problem(self, ds: xr.Dataset) -> str | None:
        """Why ``ds`` (a chunk with a valid ``point`` coordinate) is not this study's.

        Parameters
        ----------
        ds : xarray.Dataset
            A chunk, loaded.

        Returns
        -------
        str or None
            The reason in plain words, completing "chunk FILE ..." (e.g. ``"lacks the
            variable(s) friction_coefficient that this study writes"``), or None if it
            passes.
        """
        idx = ds["point"].values
        n = self.points
        if n is None and self.coords:
            n = min(v.size for v in self.coords.values())
        if n is not None and idx.max() >= n:
            return f"holds point {int(idx.max())}, beyond this study's {n} points"
        if self.variables is not None:
            have = set(ds.data_vars)
            missing = [v for v in self.variables if v not in have]
            if missing:
                return f"lacks the variable(s) {_listed(missing)} that this study writes"
            extra = sorted(have - set(self.variables) - set(self.optional))
            if extra:
                return f"holds variable(s) {_listed(extra)} that this study does not write"
        if self.finite:
            if "status" not in ds.variables:
                return "has no status variable"
            ok = np.asarray(ds["status"].values) == 0
            if ok.shape != idx.shape:
                return "has a status variable that is not one value per point"
            for name in self.finite:
                if name not in ds.variables:
                    return f"lacks the variable {name} that this study writes"
                var = ds[name]
                if "point" not in var.dims or var.dtype.kind not in "fiub":
                    return f"has a variable {name} that is not numbers over points"
                vals = var.transpose("point", ...).values.astype(float)
                good = np.isfinite(vals.reshape(idx.size, -1 if vals.size else 0))
                good = good.all(axis=1)
                bad = idx[ok & ~good]
                if bad.size:
                    return (f"holds NaN (or infinity) in {name} at point(s) "
                            f"{_listed(bad.tolist())}, whose status is 0 (a finished "
                            "result)")
        if self.coords is not None:
            for name, values in self.coords.items():
                if name not in ds.coords:
                    return f"lacks the input coordinate {name} of this study's points"
                got = np.asarray(ds[name].values)
                if got.shape != idx.shape or not np.array_equal(got, values[idx]):
                    return (f"holds other values of the input {name} than this study's "
                            "points (another study's results)")
        if self.check is not None:
            return self.check(ds)
        return None


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
    spec : ChunkSpec, optional
        What the study's chunks hold, checked at :meth:`done` and :meth:`combined` on top
        of the checks every chunk gets (a readable netCDF file whose ``point``
        coordinate holds integer indices >= 0, none of them in an earlier chunk).
        Default: those checks only.

    Raises
    ------
    InputError
        If ``OUTPUT.parts`` holds the parts of a different study, or ``spec`` is not a
        :class:`ChunkSpec`.
    """

    def __init__(self, output: str | Path, manifest: dict, *, chunk_size: int = 32,
                 flush_seconds: float = 30.0, spec: ChunkSpec | None = None) -> None:
        if spec is not None and not isinstance(spec, ChunkSpec):
            raise InputError(f"spec: must be a contact.study.store.ChunkSpec or None, got "
                             f"{type(spec).__name__}")
        self.output = Path(output)
        self.parts = self.parts_dir(output)
        self.chunk_size = max(1, int(chunk_size))
        self.flush_seconds = float(flush_seconds)
        self.spec = spec
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
        """Delete the parts directory of ``output`` (once the final file is written).

        Chunks set aside as debris (``OUTPUT.parts/set-aside/``) are kept, with the
        directory holding them; everything else goes.

        Parameters
        ----------
        output : path-like
            The study's final netCDF file.
        """
        parts = ResultStore.parts_dir(output)
        aside = parts / SET_ASIDE
        if not (aside.is_dir() and any(aside.iterdir())):
            shutil.rmtree(parts, ignore_errors=True)
            return
        for child in parts.iterdir():
            if child.name == SET_ASIDE:
                continue
            if child.is_dir() and not child.is_symlink():
                shutil.rmtree(child, ignore_errors=True)
            else:
                child.unlink(missing_ok=True)
        log.info("kept the chunks set aside in %s", aside)

    def chunks(self) -> list[Path]:
        """The chunk files written so far (not those set aside)."""
        return sorted(self.parts.glob(_CHUNKS))

    def done(self) -> set[int]:
        """Indices of the points whose results are on disk, in chunks that pass the checks.

        Returns
        -------
        set of int
            The points of every trusted chunk. A chunk failing a check (see
            :meth:`trusted`) is logged, set aside and its points are not in the set.
        """
        out: set[int] = set()
        for _, ds in self.trusted():
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

    def combined(self, coords: str = "different") -> xr.Dataset:
        """All points on disk in point order (after :meth:`flush`), from the chunks that
        pass the checks.

        Parameters
        ----------
        coords : {"different", "minimal"}
            ``xarray.concat``'s ``coords``: "different" (default) concatenates over
            ``point`` every coordinate that differs between chunks; "minimal" only those
            along ``point``, the others shared (equal where present, kept from the chunks
            that have them: a failed point's chunk may lack a coordinate of the analysis,
            as a duty-cycle bin without its root stress lacks ``fillet_u``).

        Returns
        -------
        xarray.Dataset
            The trusted chunks concatenated over ``point``, sorted by point index. A chunk
            failing a check is logged and set aside (:meth:`trusted`): its points are
            missing here — the caller compares the count with the study's.

        Raises
        ------
        InputError
            If no chunk is left.
        """
        parts = [ds for _, ds in self.trusted()]
        if not parts:
            raise InputError(f"output: no finished points in {str(self.parts)!r}")
        ds = xr.concat(parts, dim="point", join="outer", coords=coords)
        order = np.argsort(ds["point"].values, kind="stable")
        return ds.isel(point=order)

    def trusted(self) -> Iterator[tuple[Path, xr.Dataset]]:
        """The chunk files that pass the checks, each with its dataset (loaded).

        A chunk must be a readable netCDF file with a ``point`` dimension and an integer
        ``point`` coordinate (indices >= 0, each once, none in an earlier chunk) and meet
        the store's :class:`ChunkSpec`. One that does not is named in one warning with
        the reason (plain words), moved to ``OUTPUT.parts/set-aside/`` (never deleted) and
        skipped; if it cannot be moved it is skipped where it is.

        Yields
        ------
        (pathlib.Path, xarray.Dataset)
            A trusted chunk file and its contents, in file-name order.
        """
        seen: dict[int, str] = {}
        for path in self.chunks():
            ds, reason = self._checked(path, seen)
            if ds is None:
                self._set_aside(path, reason or "failed a check")
                continue
            seen.update(dict.fromkeys((int(i) for i in ds["point"].values), path.name))
            yield path, ds

    def _checked(self, path: Path, seen: Mapping[int, str]
                 ) -> tuple[xr.Dataset | None, str | None]:
        """(dataset, None) if the chunk passes every check, else (None, the reason)."""
        try:
            if path.is_file() and path.stat().st_size == 0:
                return None, "is empty (0 bytes)"
            ds = read_netcdf(path, tree=False)
        except Exception as exc:  # any library's failure to read is one plain reason
            log.debug("chunk %s: reading failed: %s", path, exc)
            return None, "is not a readable netCDF file (truncated, corrupt or not netCDF)"
        if "point" not in ds.dims:
            return None, "has no point dimension (not a study's chunk)"
        if "point" not in ds.coords:
            return None, "has no point coordinate (no point indices)"
        idx = np.asarray(ds["point"].values)
        if idx.ndim != 1 or idx.dtype.kind not in "iu":
            return None, "has point indices that are not whole numbers"
        if idx.size == 0:
            return None, "holds no points"
        if idx.min() < 0:
            return None, f"holds a negative point index ({int(idx.min())})"
        if np.unique(idx).size != idx.size:
            return None, "holds a point more than once"
        again = [int(i) for i in idx if int(i) in seen]
        if again:
            return None, (f"repeats point(s) {_listed(again)} already in "
                          f"{seen[again[0]]}")
        if self.spec is not None:
            reason = self.spec.problem(ds)
            if reason is not None:
                return None, reason
        return ds, None

    def _set_aside(self, path: Path, reason: str) -> None:
        """Move a failed chunk to ``OUTPUT.parts/set-aside/`` and log one warning."""
        aside = self.parts / SET_ASIDE
        target = aside / path.name
        n = 1
        while target.exists():
            target = aside / f"{path.stem}-{n}{path.suffix}"
            n += 1
        try:
            aside.mkdir(exist_ok=True)
            path.rename(target)
        except OSError as exc:
            log.warning("chunk %s %s; could not be set aside (%s), ignored where it is and "
                        "its points computed again", path, reason,
                        exc.strerror or type(exc).__name__)
            return
        log.warning("chunk %s %s; set aside as %s and its points computed again", path,
                    reason, target.relative_to(path.parent))
