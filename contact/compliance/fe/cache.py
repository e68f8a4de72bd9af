"""The on-disk cache of influence coefficients: where it lives and the key of an entry.

An entry is one netCDF file per member, design and FE model, named by a SHA-256 key of
everything that generates it: the member's blank, cutters and blades, machine settings,
hand, process and face-hobbing data (the whole :class:`geometry.case.Member`), the
working flank, the :class:`~contact.compliance.fe.options.FEOptions`, the toolkit's
version and this cache's format version. A study or an optimisation that comes back to a
design reuses its file; any changed setting gives another key, so the coefficients are
built again (never read stale).

The directory is, in order: the ``cache_dir`` argument, the environment variable
:data:`CACHE_ENV` (``HYPOID_LTCA_CACHE``), or the user's cache directory
(``platformdirs.user_cache_dir("hypoid-ltca")``, e.g. ``~/.cache/hypoid-ltca`` on
Linux) with ``fe/`` below it.

A cache entry is data, checked like input. Every entry is written by
:func:`write_cache_entry`, which stores two global attributes: ``cache_key`` (the key of
its file name) and ``data_sha256`` (:data:`CHECKSUM_ATTR`, a SHA-256 of the bytes of every
data variable and coordinate, :func:`data_checksum`). Every entry is read by
:func:`read_cache_entry`, which uses it only if it is a readable netCDF file, holds the
expected key, matches its checksum and holds finite values only; any other entry is
renamed aside (``fe-<key>.nc.corrupt-<UTC time>``, a name the lookup never matches,
kept for inspection), one warning naming the file and the reason is logged, and the
caller builds and caches the coefficients again.

Public names
------------
BlockCheckpoint    the solved unit-load blocks of an interrupted build, kept for the next
CACHE_ENV          the environment variable naming the cache directory
CHECKSUM_ATTR      the global attribute holding an entry's data checksum
prime_cache        write coefficients handed over by a study's client into this cache
FORMAT_VERSION     version of the file layout (part of every key)
cache_directory    the directory in use
cache_key          the key of one member's coefficients
cache_path         the file of a key
data_checksum      SHA-256 of a dataset's data variables and coordinates
read_cache_entry   an entry's dataset if it passes every check, else None (set aside)
write_cache_entry  write an entry atomically, with its key and checksum
"""

from __future__ import annotations

import dataclasses
import datetime
import hashlib
import json
import logging
import os
from pathlib import Path
from typing import Any

import numpy as np
import platformdirs
import xarray as xr

from geometry import __version__
from geometry.core.atomic_files import atomic_path, write_failure
from geometry.core.errors import FileWriteError, InputError, LTCAError

__all__ = [
    "CACHE_ENV",
    "CHECKSUM_ATTR",
    "FORMAT_VERSION",
    "NOT_WRITTEN_ATTR",
    "BlockCheckpoint",
    "cache_directory",
    "cache_key",
    "cache_path",
    "data_checksum",
    "not_written",
    "prime_cache",
    "read_cache_entry",
    "write_cache_entry",
]

log = logging.getLogger(__name__)

#: attribute of coefficients built but not cached: why the entry could not be written (a
#: read-only or full file system); they are used from memory (issue 72)
NOT_WRITTEN_ATTR = "cache_not_written"


def not_written(ds: xr.Dataset, path: str | os.PathLike[str], exc: OSError) -> xr.Dataset:
    """``ds`` marked as built but not cached: the attribute :data:`NOT_WRITTEN_ATTR` holds
    why (one sentence: :func:`geometry.core.atomic_files.write_failure`, e.g. "could not
    write '…': read-only file system"), one warning logged. The caller uses ``ds`` from
    memory; the next process builds it again.

    Parameters
    ----------
    ds : xarray.Dataset — the built coefficients
    path : path-like — the entry that could not be written
    exc : OSError — what the write raised

    Returns
    -------
    xarray.Dataset
    """
    from geometry.core.atomic_files import write_failure
    from geometry.core.errors import FileWriteError

    reason = (str(exc) if isinstance(exc, FileWriteError)
              else write_failure(path, exc) or f"could not write {str(path)!r}: {exc}")
    log.warning("FE influence coefficients used from memory, the cache was not written: %s",
                reason)
    return ds.assign_attrs({NOT_WRITTEN_ATTR: reason})

#: environment variable that overrides the default cache directory
CACHE_ENV = "HYPOID_LTCA_CACHE"
#: version of the cached files' layout and of the model that made them (2: the slot
#: bottoms rounded continuously along the face, element counts from the root size;
#: 3: fillet_in_root; 4: the data checksum ``data_sha256``; 5: a crossing of the slot
#: bottom's cuts rounded into the fillet where no blend keeps both fillets whole, which
#: changes the sections of a few pinions, e.g. ISO 23509 sample 2's); part of every key, so the
#: entries of an older format simply miss (another file name) and are built again (the
#: old files are left where they are, never read)
FORMAT_VERSION = 5
#: global attribute of an entry holding the SHA-256 (hex) of its data (:func:`data_checksum`)
CHECKSUM_ATTR = "data_sha256"
#: the suffix before the UTC time of an entry set aside (``fe-<key>.nc.corrupt-<time>``)
_ASIDE_SUFFIX = ".corrupt-"


def cache_directory(cache_dir: str | os.PathLike[str] | None = None) -> Path:
    """The cache directory: ``cache_dir``, else ``$HYPOID_LTCA_CACHE``, else the user's
    cache directory for hypoid-ltca with ``fe`` below it (not created here)."""
    if cache_dir is not None:
        return Path(cache_dir)
    env = os.environ.get(CACHE_ENV)
    if env:
        return Path(env)
    return Path(platformdirs.user_cache_dir("hypoid-ltca")) / "fe"


def _plain(obj: Any) -> Any:
    """Dataclasses, tuples and numpy scalars as JSON-able plain values."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        # a field marked ``key_at_default: False`` (added after entries were cached) is
        # left out at its default value: the keys of the models before it stay the same
        return {f.name: _plain(getattr(obj, f.name)) for f in dataclasses.fields(obj)
                if f.metadata.get("key_at_default", True)
                or getattr(obj, f.name) != f.default}
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_plain(v) for v in obj]
    if hasattr(obj, "item") and callable(obj.item):
        return obj.item()
    return obj


def cache_key(member, flank: str, options, *, version: str = __version__) -> str:
    """SHA-256 key (hex) of one member's influence coefficients.

    Parameters
    ----------
    member : geometry.case.Member — blank, blades, machine settings, hand, process
    flank : str — the working flank's name (``"concave"``/``"convex"``)
    options : FEOptions
    version : str — the toolkit version (default the installed one)

    Returns
    -------
    str — 64 hexadecimal digits.
    """
    doc = {"member": _plain(member), "flank": flank, "options": _plain(options),
           "version": version, "format": FORMAT_VERSION}
    text = json.dumps(doc, sort_keys=True, default=repr)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def cache_path(key: str, cache_dir: str | os.PathLike[str] | None = None) -> Path:
    """The file of an entry: ``<cache directory>/fe-<key>.nc``."""
    return cache_directory(cache_dir) / f"fe-{key}.nc"


# ------------------------------------------------------------------ checked entries
def _canonical(values: Any) -> tuple[str, Any]:
    """An array's type tag and bytes, the same in memory and read back from netCDF: numbers
    and booleans little-endian and C-ordered; strings (``<U``, ``S`` or object arrays of
    str, which a netCDF round trip interchanges) as the JSON of their flat list."""
    arr = np.asarray(values)
    if arr.dtype.kind in "OUS":
        items = [x.decode("utf-8") if isinstance(x, bytes) else str(x) for x in arr.ravel()]
        return "str", json.dumps(items, ensure_ascii=False).encode("utf-8")
    dtype = arr.dtype.newbyteorder("<")
    return dtype.str, memoryview(np.ascontiguousarray(arr, dtype=dtype)).cast("B")


def data_checksum(ds: xr.Dataset) -> str:
    """SHA-256 (hex) of a dataset's data: every data variable and coordinate.

    Parameters
    ----------
    ds : xarray.Dataset
        The dataset (loaded or lazily read; its values are read).

    Returns
    -------
    str
        64 hexadecimal digits over, in a fixed order (the data variables by name, then the
        coordinates by name), each variable's name, dimensions, shape, type and value
        bytes (:func:`_canonical`). Attributes are not covered (the key is checked by
        itself); the same for a dataset in memory and its netCDF file read back.
    """
    h = hashlib.sha256()
    groups = (("data", ds.data_vars), ("coord", ds.coords))
    for group, variables in groups:
        for name in sorted(map(str, variables)):
            var = variables[name].variable
            tag, data = _canonical(var.values)
            head = json.dumps([group, name, list(map(str, var.dims)), list(var.shape), tag])
            h.update(head.encode("utf-8"))
            h.update(len(data).to_bytes(8, "little"))
            h.update(data)
    return h.hexdigest()


def _nonfinite(ds: xr.Dataset) -> str | None:
    """The name of the first float data variable (by name) holding NaN or ±inf, or None."""
    for name in sorted(map(str, ds.data_vars)):
        values = ds[name].values
        if values.dtype.kind in "fc" and not np.all(np.isfinite(values)):
            return name
    return None


def write_cache_entry(ds: xr.Dataset, path: str | os.PathLike[str], key: str, *,
                      compress: bool = False, checksum: str | None = None) -> xr.Dataset:
    """Write a cache entry atomically, with its key and data checksum.

    Parameters
    ----------
    ds : xarray.Dataset
        The influence coefficients (:func:`contact.compliance.fe.influence_dataset`).
    path : path-like
        The entry's file, normally ``cache_path(key)``; its directory is created.
    key : str
        The entry's key (:func:`cache_key`), stored as the attribute ``cache_key``.
    compress : bool
        zlib level 4 on the data variables; default False: on the default pinion model
        zlib took 1.38 s of CPU to write and 0.28 s to read for a file 17 % smaller (44.6
        against 53.8 MB), uncompressed 0.04 s each way (issue 75, docs/performance.md).
        Either is read alike (the checksum covers the values, not their encoding).
    checksum : str, optional
        :func:`data_checksum` of ``ds`` where it is known already: the entry's stored
        one, of an entry this process wrote or read and checked, written again under
        another key (:func:`contact.compliance.fe.reuse.reuse_near_model`: ~0.02 s of CPU
        per 26 MB entry not hashed again, issue 75). Default None: computed here.

    Returns
    -------
    xarray.Dataset
        ``ds`` with the attributes ``cache_key`` and :data:`CHECKSUM_ATTR` (``data_sha256``)
        set: what :func:`read_cache_entry` gives back from the file.

    Raises
    ------
    LTCAError
        A float data variable holds NaN or ±inf (named): such an entry would never be
        used, so it is not written.
    OSError
        The file cannot be written (the cache's old file, if any, is left as it was:
        :func:`geometry.core.atomic_files.atomic_path`); a full disk the netCDF library
        reports as "HDF error" too, as :class:`~geometry.core.errors.FileWriteError`
        (:func:`geometry.core.atomic_files.write_failure`).
    """
    path = Path(path)
    bad = _nonfinite(ds)
    if bad is not None:
        raise LTCAError(f"FE influence coefficients: '{bad}' holds non-finite values; "
                        f"not cached in {path}")
    out = ds.assign_attrs({"cache_key": key,
                           CHECKSUM_ATTR: checksum if checksum else data_checksum(ds)})
    path.parent.mkdir(parents=True, exist_ok=True)
    enc = {name: {"zlib": True, "complevel": 4} if compress else {}
           for name in out.data_vars}
    try:
        with atomic_path(path) as tmp:
            out.to_netcdf(tmp, engine="netcdf4", encoding=enc)
    except OSError:
        raise
    except RuntimeError as exc:
        # the netCDF library says a full disk as "NetCDF: HDF error" (a RuntimeError, no
        # errno), which atomic_path does not read: put in words where the disk is full, as
        # geometry.core.io.write_netcdf does, so that the caller uses the entry from memory
        # (issue 71's unseen designs, round 9: "the other flank's influence coefficients
        # not built on this factorisation: NetCDF: HDF error" on a full /tmp)
        reason = write_failure(path, exc)
        if reason is None:
            raise
        raise FileWriteError(reason) from exc
    return out


def _identity(st: os.stat_result) -> tuple[int, int, int, int]:
    return st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns


def _set_aside(path: Path, seen: tuple[int, int, int, int], reason: str) -> None:
    """Rename a failed entry aside (``<name>.corrupt-<UTC time>``) and log one warning."""
    stamp = datetime.datetime.now(datetime.UTC).strftime("%Y%m%dT%H%M%S.%fZ")
    aside = path.with_name(f"{path.name}{_ASIDE_SUFFIX}{stamp}")
    n = 1
    while aside.exists():
        aside = path.with_name(f"{path.name}{_ASIDE_SUFFIX}{stamp}-{n}")
        n += 1
    try:
        if _identity(path.stat()) != seen:
            log.warning("FE cache entry %s %s; it was replaced meanwhile (left in place) and "
                        "is rebuilt", path, reason)
            return
        path.rename(aside)
    except FileNotFoundError:
        log.warning("FE cache entry %s %s; already set aside by another process, rebuilt",
                    path, reason)
        return
    except OSError as exc:
        log.warning("FE cache entry %s %s; could not be set aside (%s), rebuilt", path,
                    reason, exc.strerror or type(exc).__name__)
        return
    log.warning("FE cache entry %s %s; set aside as %s and rebuilt", path, reason, aside)


def _check(path: Path, key: str) -> tuple[xr.Dataset | None, str | None]:
    """(dataset, None) if the entry passes every check, else (None, the reason)."""
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except (OSError, ValueError, RuntimeError, KeyError, IndexError, TypeError,
            AttributeError) as exc:
        log.debug("FE cache entry %s: reading failed", path, exc_info=exc)
        return None, "is unreadable (not a complete netCDF file)"
    found = ds.attrs.get("cache_key")
    if found != key:
        return None, ("holds another key (a foreign entry)" if found
                      else "has no cache key (a foreign file)")
    stored = ds.attrs.get(CHECKSUM_ATTR)
    if not isinstance(stored, str) or not stored:
        return None, "is corrupt (no data checksum)"
    if data_checksum(ds) != stored:
        return None, "is corrupt (checksum mismatch)"
    bad = _nonfinite(ds)
    if bad is not None:
        return None, f"holds non-finite values (in '{bad}')"
    return ds, None


def read_cache_entry(path: str | os.PathLike[str], key: str) -> xr.Dataset | None:
    """An entry's coefficients if the entry can be trusted, else None (and set aside).

    The checks, in order: the file is a readable netCDF file; its ``cache_key`` attribute
    is ``key`` (else a foreign entry); its data's checksum (:func:`data_checksum`) equals
    the stored :data:`CHECKSUM_ATTR` (else corrupt; a missing checksum too); every float
    data variable is finite. An entry failing one is renamed to
    ``<name>.corrupt-<UTC time>`` beside it (kept, and never matched by the lookup) and
    one warning naming the file and the reason is logged; the caller builds and caches
    the coefficients again.

    Parameters
    ----------
    path : path-like
        The entry's file, normally ``cache_path(key)``.
    key : str
        The expected key (:func:`cache_key`, 64 hexadecimal digits).

    Returns
    -------
    xarray.Dataset or None
        The loaded dataset (attributes ``cache_key`` and ``data_sha256`` included), or
        None if the file does not exist or its status cannot be read (the cache
        directory not reachable: a miss, nothing logged; the build that follows says if
        its entry cannot be written) or fails a check. A bad entry never raises.

    Notes
    -----
    An entry that cannot be renamed aside (permissions), or that another process replaced
    meanwhile, is left in place (the warning says so) and overwritten atomically by the
    rebuilt entry. The data are checked at every read (the hash takes ~0.05 s per 100 MB,
    little beside reading the compressed file;
    :func:`contact.compliance.fe.contact_compliance.shared_coefficients` reads a file
    once per process).
    """
    path = Path(path)
    try:
        seen = _identity(path.stat())
    except OSError:  # no entry, or a cache directory that cannot be reached: a miss
        return None
    ds, reason = _check(path, key)
    if ds is None:
        _set_aside(path, seen, reason or "failed a check")
    return ds


# ------------------------------------------------------------------ partial entries
class BlockCheckpoint:
    """The unit-load blocks of an interrupted build, kept for the next one (issue 64).

    While :func:`contact.compliance.fe.influence_dataset` solves the unit loads block by
    block, each solved block's responses are written beside the entry as
    ``fe-<key>.part-<first>-<end>.nc`` (atomically, with its own key
    ``<key>/loads <first>-<end>`` and data checksum, as an entry: :func:`write_cache_entry`).
    A build of the same key that finds such parts reads them (:func:`read_cache_entry`:
    a part that fails a check is set aside and solved again) and solves only the other
    blocks; once the entry is written the parts are removed. A part of another block
    layout simply does not match a block's name and is never read.

    Parameters
    ----------
    path : path-like — the entry's file (``cache_path(key)``)
    key : str — the entry's key
    """

    def __init__(self, path: str | os.PathLike[str], key: str) -> None:
        self.path = Path(path)
        self.key = key
        #: why a block could not be kept (None: every block written so far was)
        self.failed: str | None = None

    def part(self, first: int, end: int) -> Path:
        """The file of the block of unit loads ``first`` … ``end`` − 1."""
        return self.path.with_name(f"{self.path.stem}.part-{first:04d}-{end:04d}.nc")

    def _key(self, first: int, end: int) -> str:
        return f"{self.key}/loads {first}-{end}"

    def read(self, first: int, end: int) -> dict[str, np.ndarray] | None:
        """The block's arrays (name → ndarray) if its part exists and passes every check,
        else None."""
        ds = read_cache_entry(self.part(first, end), self._key(first, end))
        return None if ds is None else {name: ds[name].values for name in ds.data_vars}

    def write(self, first: int, end: int, arrays: dict[str, np.ndarray]) -> None:
        """Keep a solved block (name → ndarray, the loads along the last axis). Best
        effort: where the cache cannot be written (read-only or full file system) the
        build goes on without its checkpoints, the reason kept in :attr:`failed` and
        logged once at INFO (the entry's own write says it at WARNING)."""
        if self.failed is not None:
            return
        ds = xr.Dataset({name: (tuple(f"{name}_{i}" for i in range(a.ndim)), a)
                         for name, a in arrays.items()})
        try:
            write_cache_entry(ds, self.part(first, end), self._key(first, end),
                              compress=False)
        except OSError as exc:
            self.failed = str(exc)
            log.info("FE build checkpoints not kept: %s", exc)

    def clear(self) -> int:
        """Remove every part of this entry (of any block layout); the number removed."""
        n = 0
        for part in self.path.parent.glob(f"{self.path.stem}.part-*.nc"):
            try:
                part.unlink()
                n += 1
            except FileNotFoundError:
                pass
        return n


def prime_cache(coefficients, cache_dir: str | os.PathLike[str] | None = None) -> int:
    """Write influence coefficients read elsewhere into this process's cache, where the
    cache lacks a valid entry of their key: what a study's worker does with the
    coefficients its client built and handed over through the engine (issue 53), so that
    every path that reads the cache — the root stress, the FE compliance — finds them and
    no worker builds them, whatever its cache directory (another machine's, empty). An
    entry already there is left alone (a stat, so that priming costs nothing per point);
    the reader checks it when it reads it (key, checksum, finiteness) and rebuilds a bad
    one with a warning.

    Parameters
    ----------
    coefficients : iterable of xarray.Dataset
        Influence-coefficient datasets, each with its ``cache_key`` attribute (as
        :func:`contact.compliance.fe.influence_coefficients` returns them).
    cache_dir : path-like, optional
        The cache directory (default :func:`cache_directory`).

    Returns
    -------
    int
        The entries written (0 when the cache had an entry of every key).

    Raises
    ------
    InputError
        A dataset without a ``cache_key`` attribute.
    """
    written = 0
    for ds in coefficients:
        key = ds.attrs.get("cache_key")
        if not isinstance(key, str) or not key:
            raise InputError("coefficients: a dataset without its cache_key attribute "
                             "(not influence coefficients of this toolkit)")
        path = cache_path(key, cache_dir)
        if path.exists():  # one stat per point: the reader checks the entry when it reads it
            continue
        write_cache_entry(ds, path, key)
        written += 1
    if written:
        log.info("FE cache %s: %d entr%s written from the study's client",
                 cache_directory(cache_dir), written, "y" if written == 1 else "ies")
    return written
