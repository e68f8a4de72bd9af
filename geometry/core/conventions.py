"""The labelled-data convention every stage's dataset follows (units and long names).

Every variable of every dataset the toolkit builds carries ``units`` (a UDUNITS string:
``mm``, ``rad``, ``urad``, ``N``, ``MPa``, ``1`` …) and ``long_name`` (DESIGN.md, "Data
model"); :func:`data_var` builds the ``(dims, data, attrs)`` tuple an
``xarray.Dataset`` takes with them. It lives at the bottom of the chain so that
``geometry``, ``contact`` and ``friction`` build their datasets the same way; writing and
checking files (:mod:`geometry.core.io`) sits in the application layer on top.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from geometry.core.caches import Carried, memoised

__all__ = ["assigned", "binary_flag", "coords_along", "data_var", "dataset"]


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


def dataset(data: Mapping[str, tuple], coords: Mapping[str, tuple] | None = None,
            attrs: Mapping[str, Any] | None = None):
    """``xarray.Dataset(data, coords=coords, attrs=attrs)`` of plain tuples, made directly.

    The same Dataset (``identical``, the same variables, dtypes, indexes and order) as
    xarray's constructor makes of ``(dims, values[, attrs])`` tuples, without its merge and
    alignment of the inputs, which tuples never need: ~3× faster (a flank's 14 variables:
    0.3 against 1.0 ms), and an analysis builds some twenty result datasets (issue 75).
    Anything else — a DataArray or a Variable among the values, a data variable named as a
    dimension, sizes that disagree — is left to ``xarray.Dataset``, which says what is wrong.

    Parameters
    ----------
    data : mapping of str to tuple — the data variables, ``(dims, values[, attrs])``
        (:func:`data_var`)
    coords : mapping of str to tuple, optional — the coordinates, ``(dims, values[,
        attrs])``; one along the dimension of its name gets the default (pandas) index
    attrs : mapping, optional — the dataset's attributes

    Returns
    -------
    xarray.Dataset

    Raises
    ------
    ValueError, TypeError
        As ``xarray.Dataset`` (inputs it refuses go to it).

    Notes
    -----
    Uses xarray's ``Dataset._construct_direct`` (its own constructor's last step, there
    since 2019) and the public ``PandasIndex``; where that is missing, xarray's
    constructor. tests/test_dataset_helpers.py compares the two.
    """
    import xarray as xr

    made = _direct_dataset(xr, data, coords or {}, attrs)
    return made if made is not None else xr.Dataset(data, coords=coords, attrs=attrs)


def _direct_dataset(xr, data: Mapping, coords: Mapping, attrs: Mapping | None):
    """:func:`dataset` without xarray's merge, or None where the inputs need it."""
    construct = getattr(xr.Dataset, "_construct_direct", None)
    if construct is None:
        return None
    import pandas as pd
    from xarray.indexes import PandasIndex

    def variable(spec):
        if type(spec) is not tuple or not 2 <= len(spec) <= 3:
            return None
        values = spec[1]
        if type(values) is np.ndarray and values.dtype.kind not in "OMm":
            # a plain array of numbers, text or flags, which xarray's conversions
            # (np.asarray, objects and times) leave as it is: taken as it is (~3 us each)
            return xr.Variable(spec[0], values, spec[2] if len(spec) == 3 else None,
                               fastpath=True)
        if isinstance(values, (xr.DataArray, xr.Variable, xr.Dataset, pd.Index, pd.Series,
                               pd.DataFrame)):
            return None
        return xr.Variable(*spec)

    variables: dict = {}
    indexes: dict = {}
    sizes: dict = {}
    coord_vars: dict = {}
    for name, spec in coords.items():
        var = variable(spec)
        if var is None or not isinstance(name, str):
            return None
        if var.dims == (name,):
            # the index of the plain variable: the same pandas index (and dtype) as of its
            # index variable, whose own pandas index (~30 us) create_variables replaces
            index = _index_of(PandasIndex, name, var)
            made = index.create_variables({name: var})
            coord_vars.update(made)
            indexes.update(dict.fromkeys(made, index))
        elif name in var.dims:
            return None  # (xarray refuses it)
        else:
            coord_vars[name] = var.to_base_variable()
    for name, spec in data.items():
        var = variable(spec)
        if var is None or name in coords or var.dims == (name,) \
                or not isinstance(name, str):
            return None
        variables[name] = var
    variables.update(coord_vars)
    for var in variables.values():
        for dim, size in zip(var.dims, var.shape, strict=True):
            if sizes.setdefault(dim, size) != size:
                return None
    if any(dim in variables and dim not in indexes for dim in sizes):
        return None  # a variable named as a dimension but not along it alone
    try:
        return construct(variables, set(coord_vars), sizes, dict(attrs) if attrs else None,
                         indexes=indexes)
    except TypeError:  # another xarray's private signature: its public constructor
        return None


#: the largest coordinate [bytes] whose pandas index :func:`_index_of` keeps
_INDEX_KEPT_BYTES = 1 << 16


def _index_of(pandas_index, name: str, var):
    """``PandasIndex.from_variables({name: var}, options={})`` of a plain 1-D variable
    along the dimension ``name``, its pandas index made once per process for the same
    values.

    An analysis makes ~60 index coordinates (torque, member, xyz, u, v, roll …) of ~20
    distinct values, and pandas builds each index anew: 45 us a float one, 120 us a text
    one (pandas' string array), ~6 ms of a warm analysis (issue 75). For a coordinate of
    numbers or text (up to 64 kB) the index is kept by its name, dtype, shape and bytes
    (:func:`_memo_pandas_index`), and each dataset gets a shallow copy of it (its own
    ``pandas.Index`` object over the same immutable values, as ``from_variables`` makes
    its own copy), ~5 us: the same index, name and dtype.
    """
    data = var._data
    if type(data) is not np.ndarray or data.dtype.kind not in "biufU" \
            or data.nbytes > _INDEX_KEPT_BYTES:
        return pandas_index.from_variables({name: var}, options={})
    held = _memo_pandas_index(name, data.dtype.str, data.shape, data.tobytes(),
                              Carried(var))
    return pandas_index(held.index.copy(), name, coord_dtype=held.coord_dtype,
                        fastpath=True)


@memoised(maxsize=256)
def _memo_pandas_index(name: str, dtype: str, shape: tuple, values: bytes,
                       var: Carried):
    """The PandasIndex of ``var.value`` (its name, dtype, shape and bytes the key); the
    caller copies its ``pandas.Index``, never hands this one out."""
    from xarray.indexes import PandasIndex

    return PandasIndex.from_variables({name: var.value}, options={})


def assigned(ds, data: Mapping[str, Any], coords: Mapping[str, Any] | None = None):
    """``ds.assign_coords(coords).assign(data)`` of plain ``xarray.Variable`` values, made
    directly.

    The same Dataset (``identical``, the same variables in the same order: ``ds``'s, then
    the new coordinates, then the new data variables; the same indexes and attributes) as
    xarray's ``assign_coords`` and ``assign`` make, without their copy, merge and alignment
    of the dataset's own variables, which new Variables never need: an analysis adds its
    root stress to ``/ltca`` (56 variables) and the rating's contract variables to
    ``/rating`` (111) so (issue 75). Anything else — a DataArray among the values, a name
    ``ds`` holds already, a coordinate named as a dimension but not along it alone, sizes
    that disagree — is left to xarray, which merges, aligns or refuses it.

    Parameters
    ----------
    ds : xarray.Dataset — the dataset (not changed)
    data : mapping of str to xarray.Variable — the data variables to add
    coords : mapping of str to xarray.Variable, optional — the coordinates to add; one
        along the dimension of its name gets the default (pandas) index

    Returns
    -------
    xarray.Dataset — a new dataset; its variables are shallow copies of ``ds``'s and of
        the new ones (their arrays shared, as ``Dataset.copy`` and xarray's merge make
        them)

    Raises
    ------
    ValueError, TypeError
        As xarray's ``assign_coords`` and ``assign`` (inputs it refuses go to them).

    Notes
    -----
    Uses xarray's ``Dataset._construct_direct``, as :func:`dataset` does; where that is
    missing, xarray's methods. tests/test_dataset_helpers.py compares the two.
    """
    import xarray as xr

    coords = coords or {}
    made = _direct_assigned(xr, ds, data, coords)
    if made is not None:
        return made
    return (ds.assign_coords(coords) if coords else ds).assign(data)


def _direct_assigned(xr, ds, data: Mapping, coords: Mapping):
    """:func:`assigned` without xarray's merge, or None where the inputs need it."""
    construct = getattr(xr.Dataset, "_construct_direct", None)
    if construct is None or type(ds) is not xr.Dataset:
        return None
    from xarray.indexes import PandasIndex

    new: dict = {}
    indexes = dict(ds.xindexes)
    coord_names = set(ds.coords)
    for group in (coords, data):
        for name, var in group.items():
            if not isinstance(name, str) or name in ds.variables or name in new \
                    or name in ds.dims:
                return None
            if type(var) is not xr.Variable and not (
                    group is coords and type(var) is xr.IndexVariable
                    and var.dims == (name,)):
                return None  # (a DataArray, or an index variable as a data variable)
            if group is coords:
                if var.dims == (name,):
                    index = _index_of(PandasIndex, name, var)
                    var = index.create_variables({name: var})[name]
                    indexes[name] = index
                elif name in var.dims:
                    return None  # (xarray refuses it)
                else:
                    var = var.copy(deep=False)  # (xarray's merge takes a shallow copy)
                coord_names.add(name)
            elif name in var.dims:
                return None  # a data variable named as a dimension: xarray's way
            else:
                var = var.copy(deep=False)
            new[name] = var
    sizes = dict(ds.sizes)
    for var in new.values():
        for dim, size in zip(var.dims, var.shape, strict=True):
            if sizes.setdefault(dim, size) != size:
                return None
    if any(dim in new and dim not in indexes for dim in sizes):
        return None
    variables = {name: var.copy(deep=False) for name, var in ds.variables.items()}
    variables.update(new)
    try:
        return construct(variables, coord_names, sizes, dict(ds.attrs), indexes=indexes,
                         encoding=dict(ds.encoding))
    except TypeError:  # another xarray's private signature: its public methods
        return None


def coords_along(ds, dims) -> dict[str, tuple]:
    """The coordinates that ``{d: ds.coords[d] for d in dims}`` brings into a new Dataset,
    as :func:`dataset`'s tuples, in the order xarray puts them: each dimension coordinate
    ``d`` followed by the other coordinates of ``ds`` along ``d`` alone (a DataArray
    coordinate carries them: ``gear_torque`` with ``torque``, ``segment_kind`` with
    ``segment``).

    Parameters
    ----------
    ds : xarray.Dataset — the dataset whose coordinates are taken (``/ltca``)
    dims : iterable of str — its dimension coordinates to take

    Returns
    -------
    dict of str to tuple — ``(dims, values, attrs)`` per coordinate; where ``ds`` has a
        scalar coordinate (which every one of them would carry), the DataArrays themselves
        (:func:`dataset` then leaves them to xarray)
    """
    dims = list(dims)
    names = [name for name in ds.coords]
    if any(ds.variables[name].ndim == 0 for name in names):
        return {d: ds.coords[d] for d in dims}
    out: dict[str, tuple] = {}
    for d in dims:
        for name in [d] + [n for n in names if n != d and n not in dims]:
            var = ds.variables[name]
            if var.dims == (d,) and name not in out:
                out[name] = (var.dims, var.values, var.attrs)
    return out
