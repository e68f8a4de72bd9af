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

Public names
------------
CACHE_ENV        the environment variable naming the cache directory
FORMAT_VERSION   version of the file layout (part of every key)
cache_directory  the directory in use
cache_key        the key of one member's coefficients
cache_path       the file of a key
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
from pathlib import Path
from typing import Any

import platformdirs

from geometry import __version__

__all__ = ["CACHE_ENV", "FORMAT_VERSION", "cache_directory", "cache_key", "cache_path"]

#: environment variable that overrides the default cache directory
CACHE_ENV = "HYPOID_LTCA_CACHE"
#: version of the cached files' layout and of the model that made them (2: the slot
#: bottoms rounded continuously along the face, element counts from the root size;
#: 3: fillet_in_root); part of every key
FORMAT_VERSION = 3


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
        return {f.name: _plain(getattr(obj, f.name)) for f in dataclasses.fields(obj)}
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
