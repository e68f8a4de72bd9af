"""Input validators of the whole toolkit: one set, one message style.

Every public function checks its physical inputs at the boundary and raises
:class:`geometry.core.errors.InputError` naming the field and the accepted range, so a bad value
never reaches numpy (no NaN passed on, no crash deep inside). The messages all read

    ``<field>: must be <accepted> [<unit>], got <value>``

e.g. ``roughness: must be finite and > 0 [µm], got -1.0`` or
``poisson_ratio: must be in [0, 0.5) [1], got 0.6``; the unit is left out for counts and
names. The case-file loader (:mod:`geometry.case`) prefixes the field with its dotted path
(``pinion.machine.concave.ratio_of_roll: …``) in the same style.

These functions sit at the bottom of the chain (``geometry``) so that ``contact`` and
``friction`` use them too (the package rules of docs/design.md).

Public functions
----------------
real             a finite real number, optionally within bounds
positive         a finite real number > 0 (optionally ≤ an upper bound)
real_array       a finite float array, optionally within bounds and of a given rank
broadcast        arrays broadcast together, or an error naming them and their shapes
scalar_or_array  a Python float for a 0-d result, the array otherwise
integer          an integer within bounds (bool refused)
one_of           a value from a fixed set of choices
known_fields     a table's field names all accepted, else the first unknown one named
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable
from typing import Any

import numpy as np

from geometry.core.errors import InputError

__all__ = ["broadcast", "integer", "known_fields", "one_of", "positive", "real", "real_array",
           "scalar_or_array"]


def _unit(unit: str) -> str:
    return f" [{unit}]" if unit else ""


def _accepted(low: float | None, high: float | None, low_open: bool, high_open: bool,
              scale: float = 1.0) -> str:
    """Words for the accepted set: 'finite', 'finite and > 0', 'in [0, 0.5)' …"""
    if low is None and high is None:
        return "finite"
    if high is None:
        return f"finite and {'>' if low_open else '>='} {low / scale:g}"
    if low is None:
        return f"finite and {'<' if high_open else '<='} {high / scale:g}"
    return (f"in {'(' if low_open else '['}{low / scale:g}, {high / scale:g}"
            f"{')' if high_open else ']'}")


def _inside(v, low, high, low_open, high_open):
    """Finite and within the bounds: a bool for a float (without NumPy: :func:`real` runs
    a few hundred times per analysis), a bool array for an array."""
    ok = math.isfinite(v) if isinstance(v, float) else np.isfinite(v)
    if low is not None:
        ok &= (v > low) if low_open else (v >= low)
    if high is not None:
        ok &= (v < high) if high_open else (v <= high)
    return ok


def real(name: str, value: Any, *, unit: str = "", low: float | None = None,
         high: float | None = None, low_open: bool = False, high_open: bool = False,
         scale: float = 1.0) -> float:
    """A finite real number within optional bounds, as a Python float.

    Parameters
    ----------
    name : str
        The field's name, as the caller's signature or the case file spells it.
    value : Any
        The value given (bool and text are refused: they are not numbers here).
    unit : str
        UDUNITS unit shown in the message (``"mm"``, ``"rad"``, ``"1"``; ``""`` for none).
    low, high : float, optional
        Bounds; ``low_open``/``high_open`` exclude them.
    scale : float
        Size of one ``unit`` in the value's own unit: the message shows the bounds and the
        value divided by it (an angle held in rad is reported in deg with
        ``unit="deg", scale=math.pi / 180``); the value returned is not scaled.

    Returns
    -------
    float

    Raises
    ------
    InputError
        ``<name>: must be <accepted> [<unit>], got <value>``.
    """
    if isinstance(value, (bool, np.bool_, str, bytes)):
        raise InputError(f"{name}: must be a real number, "
                         f"{_accepted(low, high, low_open, high_open, scale)}{_unit(unit)}, "
                         f"got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be a real number, "
                         f"{_accepted(low, high, low_open, high_open, scale)}{_unit(unit)}, "
                         f"got {value!r}") from None
    if not _inside(v, low, high, low_open, high_open):
        got = (_shortest_outside(v, low, high, low_open, high_open)
               if scale == 1.0 and isinstance(value, (float, np.floating)) else
               repr(value) if scale == 1.0 else f"{v / scale:g}")
        raise InputError(f"{name}: must be "
                         f"{_accepted(low, high, low_open, high_open, scale)}{_unit(unit)}, "
                         f"got {got}")
    return v


def _shortest_outside(v: float, low, high, low_open: bool, high_open: bool) -> str:
    """``v`` as its repr where that is short, else with the fewest significant digits (4,
    6, 8, 12, 17) that still read outside the accepted range: "got 0.9881", not "got
    0.9881414345523601" (a computed value, round 14's flash-temperature note), never a
    rounding that reads inside the range."""
    if len(repr(v)) <= 10:  # as typed: "got 0.0", "got 1e+12"
        return repr(v)
    for digits in (4, 6, 8, 12):
        text = f"{v:.{digits}g}"
        if not _inside(float(text), low, high, low_open, high_open):
            return text
    return repr(v)


def positive(name: str, value: Any, unit: str = "", *, high: float | None = None) -> float:
    """A finite real number > 0 (and ≤ ``high`` if given), as a Python float.

    Parameters
    ----------
    name, value, unit
        As :func:`real`.
    high : float, optional
        Inclusive upper bound.

    Returns
    -------
    float

    Raises
    ------
    InputError
        ``<name>: must be finite and > 0 [<unit>], got <value>`` (or ``in (0, high]``).
    """
    return real(name, value, unit=unit, low=0.0, high=high, low_open=True)


def real_array(name: str, value: Any, *, unit: str = "", low: float | None = None,
               high: float | None = None, low_open: bool = False, high_open: bool = False,
               ndim: int | None = None) -> np.ndarray:
    """A finite float array within optional bounds (a new array, never a view of ``value``).

    Parameters
    ----------
    name, unit, low, high, low_open, high_open
        As :func:`real`.
    value : array_like
        Numbers (any shape, or exactly ``ndim`` dimensions; text and booleans refused).
    ndim : int, optional
        Required number of dimensions.

    Returns
    -------
    ndarray of float

    Raises
    ------
    InputError
        Not numeric, of the wrong rank, or with entries outside the accepted set (the
        message gives how many and the first of them).
    """
    # (the accepted set is worded only for a message: this check runs on every call of
    # the compliance and contact models, a few hundred times per analysis)
    if isinstance(value, (bool, np.bool_, str, bytes)):
        raise InputError(f"{name}: must be real numbers, "
                         f"{_accepted(low, high, low_open, high_open)}{_unit(unit)}, "
                         f"got {value!r}")
    try:
        if not isinstance(value, np.ndarray):
            value = np.asarray(value)
        if value.dtype.kind in "USb":  # text and booleans are not numbers here
            raise TypeError
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be real numbers, "
                         f"{_accepted(low, high, low_open, high_open)}{_unit(unit)}, got "
                         f"{type(value).__name__}") from None
    if ndim is not None and arr.ndim != ndim:
        raise InputError(f"{name}: must be {ndim}-dimensional, got shape {arr.shape}")
    ok = _inside(arr, low, high, low_open, high_open)
    if not ok.all():
        bad = arr[~ok]
        raise InputError(f"{name}: must be {_accepted(low, high, low_open, high_open)}"
                         f"{_unit(unit)}, got {bad.size} of {arr.size} value(s) outside, "
                         f"e.g. {float(bad.flat[0])!r}")
    return arr


def broadcast(**arrays: Any) -> tuple[np.ndarray, ...]:
    """The arrays broadcast together (read-only views), in the order given.

    Parameters
    ----------
    **arrays : ndarray
        Each array by its field name (the names appear in the message).

    Returns
    -------
    tuple of ndarray
        The broadcast arrays, one per keyword.

    Raises
    ------
    InputError
        ``<name>, <name>: must broadcast together, got shapes <shape>, <shape>``.
    """
    try:
        return tuple(np.broadcast_arrays(*arrays.values()))
    except ValueError:
        shapes = ", ".join(str(np.shape(v)) for v in arrays.values())
        raise InputError(f"{', '.join(arrays)}: must broadcast together, got shapes "
                         f"{shapes}") from None


def scalar_or_array(value: Any) -> float | np.ndarray:
    """A Python float for a 0-d result, the array otherwise (the vectorised functions' return).

    Parameters
    ----------
    value : array_like

    Returns
    -------
    float or ndarray
    """
    arr = np.asarray(value)
    return float(arr) if arr.ndim == 0 else arr


def integer(name: str, value: Any, low: int | None = None, high: int | None = None, *,
            allow_float: bool = False) -> int:
    """An integer within optional inclusive bounds (bool refused).

    Parameters
    ----------
    name, value
        As :func:`real`.
    low, high : int, optional
        Inclusive bounds.
    allow_float : bool
        Accept a float with an integral value (``11.0``, e.g. read from a file); by
        default every float is refused.

    Returns
    -------
    int

    Raises
    ------
    InputError
        ``<name>: must be an integer in [low, high], got <value>``.
    """
    lo = "-inf" if low is None else str(low)
    hi = "inf" if high is None else str(high)
    accepted = f"an integer in [{lo}, {hi}]"
    integral_float = (allow_float and isinstance(value, (float, np.floating))
                      and bool(np.isfinite(value)) and float(value).is_integer())
    if isinstance(value, (bool, np.bool_)) or not (
            isinstance(value, (int, np.integer)) or integral_float):
        raise InputError(f"{name}: must be {accepted}, got {value!r}")
    v = int(value)
    if (low is not None and v < low) or (high is not None and v > high):
        raise InputError(f"{name}: must be {accepted}, got {value!r}")
    return v


def one_of(name: str, value: Any, choices: Collection[Any]) -> Any:
    """``value`` if it is one of ``choices``.

    Raises
    ------
    InputError
        ``<name>: must be one of [...], got <value>`` (choices sorted when they can be).
    """
    try:
        ok = value in choices
    except TypeError:  # an unhashable value is not one of the choices
        ok = False
    if not ok:
        try:
            listed = sorted(choices)
        except TypeError:
            listed = list(choices)
        raise InputError(f"{name}: must be one of {listed}, got {value!r}")
    return value


def known_fields(where: str, table: Collection[str], accepted: Iterable[str]) -> None:
    """Refuse a table (an input file's, or its mapping) with a field not in ``accepted``.

    Parameters
    ----------
    where : str
        The table's name in the message (``rating``, ``pinion.concave`` …).
    table : collection of str
        The table's field names (a mapping: its keys).
    accepted : iterable of str
        The accepted names, listed in the message in this order.

    Raises
    ------
    InputError
        ``<where>.<name>: unknown field; accepted: <a>, <b>, …`` for the first unknown name
        in alphabetical order.
    """
    accepted = list(accepted)
    unknown = sorted(set(table) - set(accepted))
    if unknown:
        raise InputError(f"{where}.{unknown[0]}: unknown field; accepted: "
                         f"{', '.join(accepted)}")
