"""The toolkit's per-process caches (memos), every one clearable by :func:`clear_caches`.

A few results are kept in memory for the rest of the process because analyses of the same
teeth ask for them again: the tooth models of a case, the ease-off's forward-map points,
the seed grids of the equation of meshing, the FE coefficient files read, the bundled
data files parsed (materials, kolivand2009 fits), the solver backends found installed.
Each is a :func:`functools.lru_cache` made by :func:`memoised`, which also registers it
here, so one call empties all of them::

    >>> from geometry.core.caches import clear_caches
    >>> cleared = clear_caches()   # the names of the caches emptied

Nothing else in the toolkit keeps state between calls (tests/test_global_state.py reads
every module for another ``lru_cache`` or ``functools.cache``). The FE influence
coefficients' *disk* cache (``$HYPOID_LTCA_CACHE``, docs/environment.md) is not a memo:
:func:`clear_caches` leaves it alone.

When to clear: after editing a bundled data file in a running session (a notebook), to
measure a cold start, or to give the memory back after a large study in the same process.
Results never depend on it: a memo's entry is what its function computes again.

Public functions
----------------
memoised         decorator: ``functools.lru_cache`` registered with :func:`clear_caches`
clear_caches     empty every registered cache; returns their names
cache_sizes      the number of entries each registered cache holds now
row_keys         each row of a float array as a memo key (its bytes)
rows_not_kept    context: the stores of rows (BatchedRows) bypassed inside it
rows_kept        whether the stores of rows are in use here (not inside rows_not_kept)
read_only        a tuple's arrays made read-only (a memo's shared result is not written)
"""

from __future__ import annotations

import contextlib
import contextvars
import functools
import itertools
import threading
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

__all__ = ["Same", "cache_sizes", "clear_caches", "memoised", "read_only", "row_keys",
           "rows_kept", "rows_not_kept"]

F = TypeVar("F", bound=Callable[..., Any])

#: registered caches: "module.function" → the lru_cache wrapper (cache_clear, cache_info)
_CACHES: dict[str, Any] = {}


def memoised(maxsize: int | None = 128) -> Callable[[F], F]:
    """``functools.lru_cache(maxsize)``, registered so that :func:`clear_caches` empties it.

    Parameters
    ----------
    maxsize : int or None
        Entries kept (least recently used dropped first); None: unbounded (for functions of
        a few constant arguments: bundled data files, a spline of a fixed function).

    Returns
    -------
    callable
        The decorator; the decorated function has ``cache_clear`` and ``cache_info`` as
        any ``lru_cache``'s.

    Raises
    ------
    ValueError
        ``maxsize`` negative.
    """
    if maxsize is not None and (not isinstance(maxsize, int) or maxsize < 0):
        raise ValueError(f"maxsize: must be None or an integer >= 0, got {maxsize!r}")

    def decorate(function: F) -> F:
        wrapped = functools.lru_cache(maxsize=maxsize)(function)
        _CACHES[f"{function.__module__}.{function.__qualname__}"] = wrapped
        return wrapped  # type: ignore[return-value]

    return decorate


def clear_caches() -> list[str]:
    """Empty every per-process cache of the toolkit (those of the modules imported so far;
    a module not imported has nothing cached).

    Returns
    -------
    list of str
        The names (``module.function``) of the caches emptied, sorted.

    Notes
    -----
    Registrations (the solver backends, friction models and compliance models a user
    added: docs/extending.md) are not caches: they stay. The disk cache of FE coefficients
    stays too.
    """
    for wrapped in _CACHES.values():
        wrapped.cache_clear()
    return sorted(_CACHES)


def cache_sizes() -> dict[str, int]:
    """The number of entries each registered cache holds now.

    Returns
    -------
    dict of str to int
        ``module.function`` → entries (``cache_info().currsize``).
    """
    return {name: int(w.cache_info().currsize) for name, w in sorted(_CACHES.items())}


T = TypeVar("T", bound=tuple)


def read_only(value: T) -> T:
    """``value`` (a tuple, e.g. a NamedTuple) with its NumPy arrays marked read-only.

    A memo hands the same result to every caller, so an array one caller wrote in place
    would change what every later caller reads (and the results of a study would then
    depend on its order). Marked read-only, such a write raises ``ValueError:
    assignment destination is read-only`` at the writing line instead.

    Parameters
    ----------
    value : tuple
        The memoised result; its fields that are ``numpy.ndarray`` are marked (in place:
        the same arrays, ``flags.writeable`` False); other fields are left as they are.

    Returns
    -------
    tuple
        ``value`` itself.
    """
    import numpy as np

    for field in value:
        if isinstance(field, np.ndarray):
            field.flags.writeable = False
    return value


class Same:
    """An object as a memo key compared by identity (an ease-off or a tooth model holds
    arrays: no hash of its own); the key holds the object, so its ``id`` is not reused
    while the memo keeps the entry."""

    __slots__ = ("obj",)

    def __init__(self, obj) -> None:
        self.obj = obj

    def __hash__(self) -> int:
        return id(self.obj)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Same) and other.obj is self.obj


class Carried:
    """A value handed through a memo without being part of its key (every carrier
    compares equal): e.g. the case, whose teeth the key holds as ``Case.teeth_key``."""

    __slots__ = ("value",)

    def __init__(self, value) -> None:
        self.value = value

    def __hash__(self) -> int:
        return 0

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Carried)


class BatchedRows:
    """A bounded store of rows kept a batch at a time: ``rows`` maps a row's key (bytes)
    to ``batch << 32 | row`` (its row in a kept batch), ``batches`` the batch serial to
    the batch (any object its user indexes by row), ``lock`` serialises the threads that
    use it. The shell model's columns of Y (:mod:`contact.compliance.shell`) and the tooth
    model's mapped points (:mod:`contact.compliance.mesh`) are kept so: a call's rows are
    gathered a batch at a time, not one by one."""

    __slots__ = ("batches", "lock", "rows", "serial")

    def __init__(self) -> None:
        self.rows: dict[bytes, int] = {}
        self.batches: dict[int, Any] = {}
        self.serial = 0
        self.lock = threading.Lock()

    def add(self, batch: Any, keys: list[bytes]) -> None:
        """Keep ``batch`` (its rows in the order of ``keys``) under ``keys``."""
        self.serial += 1
        self.batches[self.serial] = batch
        base = self.serial << 32
        self.rows.update(zip(keys, range(base, base + len(keys)), strict=True))

    def trim(self, kept: int) -> None:
        """Drop the oldest rows beyond ``kept``, and the batches no row refers to."""
        if len(self.rows) <= kept:
            return
        import numpy as np

        for k in list(itertools.islice(self.rows, len(self.rows) - kept)):
            del self.rows[k]
        used = set(np.unique(np.fromiter(self.rows.values(), dtype=np.int64) >> 32).tolist())
        for b in [b for b in self.batches if b not in used]:
            del self.batches[b]


#: False inside :func:`rows_not_kept` (this thread or task's context only)
_ROWS_KEPT: contextvars.ContextVar[bool] = contextvars.ContextVar("rows_kept", default=True)


@contextlib.contextmanager
def rows_not_kept() -> Iterator[None]:
    """Inside this block the stores of rows (:class:`BatchedRows`: the shell model's
    columns of Y, the tooth model's mapped points) are neither read nor filled: each call
    computes all its rows in one batch, as in a process that kept none.

    For work whose rows are new at every call: a study point (each a new misalignment or
    deviation, so new contact segments; one analysis maps all its torques' segments in two
    calls) paid the stores' keys, look-ups, copies and trims (5–7 % of its CPU) for the
    few rows it shared with its own first call. The rows a block computes are those of a
    process that kept none (bit for bit); outside it, a row found in a store replaces the
    row a batch would give, equal to round-off. The block is per thread and per task
    (:mod:`contextvars`): other analyses of the process keep their rows.

    Yields
    ------
    None
    """
    token = _ROWS_KEPT.set(False)
    try:
        yield
    finally:
        _ROWS_KEPT.reset(token)


def rows_kept() -> bool:
    """Whether the stores of rows are in use here.

    Returns
    -------
    bool
        False inside a :func:`rows_not_kept` block, else True.
    """
    return _ROWS_KEPT.get()


def row_keys(rows, tag: bytes = b"") -> list[bytes]:
    """Each row of a 2-D array of floats as ``tag`` + the row's bytes (float64, C order):
    a memo key per row (a point, a segment) that equal rows share.

    Parameters
    ----------
    rows : array_like (N, W) — the values (converted to float64)
    tag : bytes — a prefix common to every key (what the rows are)

    Returns
    -------
    list of bytes — N keys, each ``len(tag) + 8 W`` bytes

    Notes
    -----
    The rows are copied once into a byte array with the tag in front and read back as one
    fixed-width bytes object per row, ~6× faster than slicing the rows' bytes one by one
    (measured on 1,500 rows of 6 floats: 0.28 against 1.7 ms; issue 75).
    """
    import numpy as np

    r = np.ascontiguousarray(rows, dtype=float)
    if r.ndim != 2:
        raise ValueError(f"rows: must be a 2-D array, got shape {r.shape}")
    width = len(tag) + r.shape[1] * r.itemsize
    buf = np.empty((r.shape[0], width), dtype=np.uint8)
    buf[:, :len(tag)] = np.frombuffer(tag, dtype=np.uint8)
    buf[:, len(tag):] = r.view(np.uint8).reshape(r.shape[0], r.shape[1] * r.itemsize)
    return buf.view(np.dtype((np.void, width))).ravel().tolist()
