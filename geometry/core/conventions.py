"""The labelled-data convention every stage's dataset follows (units and long names).

Every variable of every dataset the toolkit builds carries ``units`` (a UDUNITS string:
``mm``, ``rad``, ``urad``, ``N``, ``MPa``, ``1`` …) and ``long_name`` (DESIGN.md, "Data
model"); :func:`data_var` builds the ``(dims, data, attrs)`` tuple an
``xarray.Dataset`` takes with them. It lives at the bottom of the chain so that
``geometry``, ``contact`` and ``friction`` build their datasets the same way; writing and
checking files (:mod:`geometry.core.io`) sits in the application layer on top.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["binary_flag", "data_var"]


def data_var(dims, data, units: str | None, long_name: str, **attrs: Any) -> tuple:
    """A ``(dims, data, attrs)`` tuple for an ``xarray.Dataset`` with the conventions' attributes.

    Parameters
    ----------
    dims : str or tuple of str
        Dimension names.
    data : array_like
        Values (shape matching ``dims``).
    units : str or None
        UDUNITS string; None only for text variables.
    long_name : str
        What the variable is, in words.
    **attrs
        Further attributes (e.g. ``flag_values``), kept after ``units`` and ``long_name``.

    Returns
    -------
    tuple
        ``(dims, data, {"units": units, "long_name": long_name, **attrs})`` (no
        ``units`` key when ``units`` is None).
    """
    a = {"long_name": long_name, **attrs}
    if units is not None:
        a = {"units": units, **a}
    return (dims, data, a)


def binary_flag(off: str, on: str) -> dict[str, Any]:
    """CF flag attributes of a 0/1 variable stored as int8 (CF 3.5).

    Parameters
    ----------
    off, on : str
        One word each (no spaces; words joined by ``_``): the meaning of 0 and of 1.

    Returns
    -------
    dict
        ``flag_values`` (int8 array ``[0, 1]``, the variable's type) and
        ``flag_meanings`` (``"off on"``), to pass to :func:`data_var` as ``**attrs``.
    """
    for word in (off, on):
        if not word or " " in word:
            raise ValueError(f"a flag meaning is one word without spaces, not {word!r}")
    return {"flag_values": np.array([0, 1], dtype=np.int8), "flag_meanings": f"{off} {on}"}
