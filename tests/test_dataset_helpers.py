"""The result-dataset and memo-key helpers of issue 75's warm analysis.

:func:`geometry.core.conventions.dataset` must make the very Dataset ``xarray.Dataset``
makes of the same ``(dims, values, attrs)`` tuples (its variables, their order, dtypes
and classes, its indexes and attributes), and hand every input it does not take to
xarray, which refuses what is wrong; :func:`geometry.core.conventions.assigned` the
Dataset xarray's ``assign_coords`` and ``assign`` make; the result tree of
:func:`contact.pipeline.run_analysis` (``contact.pipeline._datatree``) the tree
``xarray.DataTree.from_dict`` makes; :func:`geometry.core.caches.row_keys` must give each
row's bytes behind the tag, as the slices of the rows' bytes do. Milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from geometry.core.caches import row_keys
from geometry.core.conventions import assigned, coords_along, data_var, dataset


def _same(a: xr.Dataset, b: xr.Dataset) -> None:
    assert a.identical(b)
    assert list(a.variables) == list(b.variables)
    assert list(a.coords) == list(b.coords)
    assert dict(a.sizes) == dict(b.sizes) and list(a.sizes) == list(b.sizes)
    for name, var in a.variables.items():
        other = b.variables[name]
        assert var.dtype == other.dtype, name
        assert type(var) is type(other), name
        assert var.encoding == other.encoding, name
    assert list(a.xindexes) == list(b.xindexes)
    for name, index in a.xindexes.items():
        assert type(index) is type(b.xindexes[name]) and index.equals(b.xindexes[name])
    assert a.attrs == b.attrs and a.encoding == b.encoding


DATA = {
    "force": data_var(("torque", "roll"), np.arange(6.0).reshape(2, 3), "N", "force"),
    "count": ("roll", [1, 2, 3]),
    "scalar": ((), 3.5, {"units": "1"}),
    "word": (("member",), np.array(["a", "bb"])),
    "flag": data_var("roll", np.array([0, 1, 0], dtype=np.int8), "1", "flag",
                     flag_values=np.arange(2, dtype=np.int8)),
}
COORDS = {
    "torque": ("torque", [50.0, 250.0], {"units": "N m"}),
    "roll": ("roll", np.linspace(-0.1, 0.1, 3)),
    "member": ("member", ["pinion", "gear"], {"long_name": "member"}),
    "gear_torque": ("torque", np.array([150.0, 750.0])),
    "fillet_u": (("member", "roll"), np.zeros((2, 3))),
    "step": ((), 2),
    "pair": ("pair", np.array([-1, 0, 1]), {"units": "1"}),
    "kind": ("kind", np.array(["curve", "edge"], dtype=object)),
}


@pytest.mark.parametrize("data, coords, attrs", [
    (DATA, COORDS, {"title": "t", "n": 3}),
    (DATA, None, None),
    ({}, COORDS, {}),
    (DATA, {"torque": COORDS["torque"]}, {}),
])
def test_dataset_is_xarrays_dataset(data, coords, attrs):
    """The same Dataset as xarray's constructor, variable for variable (values, dtypes
    — text stays text, not object —, order, index and base classes, attributes)."""
    _same(dataset(data, coords, attrs), xr.Dataset(data, coords=coords, attrs=attrs))


def test_kept_index_is_xarrays_and_each_dataset_its_own():
    """A coordinate's pandas index is kept per process by its values (issue 75): the
    dataset made again of the same values is xarray's, the same index, name and dtype as
    the first, and each holds a pandas index object of its own (renaming one dataset's
    index leaves the other's and the kept one alone); other values, dtypes or names make
    their own index, and clear_caches empties the memo."""
    from geometry.core.caches import cache_sizes, clear_caches

    clear_caches()
    key = "geometry.core.conventions._memo_pandas_index"
    first = dataset(DATA, COORDS)
    kept = cache_sizes()[key]
    assert kept >= 3  # torque, roll, member, pair (kind is of objects: not kept)
    second = dataset(DATA, COORDS)
    assert cache_sizes()[key] == kept
    for ds in (first, second):
        _same(ds, xr.Dataset(DATA, coords=COORDS))
    for name in ("torque", "roll", "member", "pair"):
        assert first.xindexes[name].index is not second.xindexes[name].index
    first.xindexes["member"].index.name = "changed"
    assert second.xindexes["member"].index.name == "member"
    _same(dataset(DATA, COORDS), xr.Dataset(DATA, coords=COORDS))
    other = dataset({}, {"torque": ("torque", np.array([50, 250]))})
    assert other.xindexes["torque"].coord_dtype == np.dtype(int)
    _same(other, xr.Dataset(coords={"torque": ("torque", np.array([50, 250]))}))
    renamed = dataset({}, {"roll2": ("roll2", COORDS["roll"][1])})
    assert renamed.xindexes["roll2"].index.name == "roll2"
    assert key in clear_caches() and cache_sizes()[key] == 0


def test_dataset_leaves_what_it_does_not_take_to_xarray():
    """A DataArray among the values, a data variable named as its dimension and sizes
    that disagree go to xarray: the same Dataset, or xarray's own error."""
    da = xr.DataArray([1.0, 2.0], dims="torque", coords={"torque": [50.0, 250.0]})
    _same(dataset({"f": da}, {}), xr.Dataset({"f": da}))
    _same(dataset({"roll": ("roll", [1.0, 2.0])}), xr.Dataset({"roll": ("roll", [1.0, 2.0])}))
    with pytest.raises(ValueError):
        dataset({"a": ("roll", [1.0, 2.0]), "b": ("roll", [1.0, 2.0, 3.0])})
    with pytest.raises(ValueError):
        xr.Dataset({"a": ("roll", [1.0, 2.0]), "b": ("roll", [1.0, 2.0, 3.0])})


def test_coords_along_brings_what_xarrays_dataarray_coordinates_bring():
    """``coords_along(ds, dims)`` as the coordinates of a new Dataset gives the Dataset
    that ``{d: ds.coords[d]}`` gives: each dimension coordinate with the coordinates along
    it alone (``gear_torque`` with ``torque``), in xarray's order; with a scalar
    coordinate it hands over the DataArrays themselves."""
    src = xr.Dataset({"force": (("torque", "roll", "segment"), np.ones((2, 3, 4)))}, coords={
        "torque": ("torque", [50.0, 250.0], {"units": "N m"}),
        "gear_torque": ("torque", [150.0, 750.0]),
        "roll": ("roll", np.linspace(0, 1, 3)), "mesh_cycle": ("roll", [0.0, 0.5, 1.0]),
        "segment": ("segment", np.arange(4)),
        "segment_kind": ("segment", np.array(["curve", "curve", "gear_tip", "curve"])),
        "grid": (("roll", "segment"), np.zeros((3, 4)))})
    dims = ("torque", "roll", "segment")
    data = {"loss": data_var(("torque", "roll"), np.zeros((2, 3)), "W", "loss")}
    want = xr.Dataset(data, coords={d: src.coords[d] for d in dims})
    _same(dataset(data, coords_along(src, dims)), want)
    scalar = src.assign_coords(step=2.0)
    got = coords_along(scalar, dims)
    assert all(isinstance(v, xr.DataArray) for v in got.values())
    _same(dataset(data, got), xr.Dataset(data, coords={d: scalar.coords[d] for d in dims}))


def test_row_keys_are_the_rows_bytes():
    """Each key is the tag and the row's float64 bytes (trailing zero bytes kept: a row
    ending in 0.0), equal rows give equal keys, the input's dtype and order do not
    matter."""
    rows = np.array([[1.0, 0.0], [0.0, 0.0], [1.0, 0.0], [-2.5, 3.0]])
    keys = row_keys(rows, b"m")
    assert keys == [b"m" + r.tobytes() for r in rows]
    assert keys[0] == keys[2] and len(set(keys)) == 3
    assert row_keys(np.asfortranarray(rows.astype(np.float32)), b"") == [
        r.astype(float).tobytes() for r in rows]
    assert row_keys(np.empty((0, 3)), b"x") == []
    with pytest.raises(ValueError):
        row_keys(np.zeros(3))


def test_assigned_is_xarrays_assign():
    """New data variables and coordinates (along their own dimension, with an index, or
    along others; new dimensions among them) added as xarray's ``assign_coords`` and
    ``assign`` add them: the same Dataset, variable for variable and in the same order;
    the dataset itself unchanged."""
    ds = xr.Dataset(DATA, coords=COORDS, attrs={"title": "t"})
    ds.encoding["unlimited_dims"] = {"torque"}
    before = ds.copy()
    data = {"stress": xr.Variable(("torque", "member", "point"), np.ones((2, 2, 4)),
                                  {"units": "MPa"}),
            "peak": xr.Variable(("torque",), [1.0, 2.0])}
    coords = {"point": xr.Variable("point", np.arange(4), {"units": "1"}),
              "point_u": xr.Variable(("member", "point"), np.zeros((2, 4))),
              "tooth": xr.IndexVariable("tooth", [-1, 0, 1])}
    got = assigned(ds, data, coords)
    _same(got, ds.assign_coords(coords).assign(data))
    _same(assigned(ds, data), ds.assign(data))
    _same(ds, before)
    got["stress"].attrs["units"] = "Pa"  # its own variables, as xarray's (not the inputs)
    got["point_u"].attrs["units"] = "1"
    assert data["stress"].attrs == {"units": "MPa"} and coords["point_u"].attrs == {}


def test_assigned_leaves_what_it_does_not_take_to_xarray():
    """A DataArray among the values, a name the dataset holds and sizes that disagree go
    to xarray: the same Dataset, or xarray's own error."""
    ds = xr.Dataset(DATA, coords=COORDS)
    da = xr.DataArray([1.0, 2.0], dims="torque", coords={"torque": [50.0, 250.0]})
    _same(assigned(ds, {"f": da}), ds.assign({"f": da}))
    again = {"force": xr.Variable(("torque", "roll"), np.zeros((2, 3)))}
    _same(assigned(ds, again), ds.assign(again))
    with pytest.raises(ValueError):
        assigned(ds, {"bad": xr.Variable("roll", [1.0, 2.0])})


def test_result_tree_is_xarrays_from_dict():
    """The analysis' tree of groups — nested ones, parents no group names, a child
    group whose coordinates its parent holds (``/rating/flash_temperature``), siblings
    in the order given — is the tree ``DataTree.from_dict`` makes of them."""
    from contact.pipeline import _datatree

    ds = xr.Dataset(DATA, coords=COORDS)
    child = xr.Dataset({"theta": (("torque", "member"), np.ones((2, 2)))},
                       coords={"torque": COORDS["torque"], "member": COORDS["member"]})
    groups = {"/geometry/pinion/concave": ds, "/geometry/gear/convex": ds.copy(),
              "/ltca": ds.drop_vars("flag"), "/rating": ds, "/rating/flash_temperature":
              child, "/": xr.Dataset(attrs={"case": "c"})}
    got, want = _datatree(groups), xr.DataTree.from_dict(groups)
    assert got.identical(want)
    assert [n.path for n in got.subtree] == [n.path for n in want.subtree]
    for a, b in zip(got.subtree, want.subtree, strict=True):
        _same(a.to_dataset(inherit=False), b.to_dataset(inherit=False))
