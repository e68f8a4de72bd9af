"""The labelled-data convention every stage's dataset follows (units and long names).

Every variable of every dataset the toolkit builds carries ``units`` (a UDUNITS string:
``mm``, ``rad``, ``urad``, ``N``, ``MPa``, ``1`` …) and ``long_name`` (DESIGN.md, "Data
model"); :func:`data_var` builds the ``(dims, data, attrs)`` tuple an
``xarray.Dataset`` takes with them. It lives at the bottom of the chain so that
``geometry``, ``contact`` and ``friction`` build their datasets the same way; writing and
checking files (:mod:`contact.io`) sits in the application layer on top.
"""

from __future__ import annotations

from typing import Any

__all__ = ["data_var"]


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
