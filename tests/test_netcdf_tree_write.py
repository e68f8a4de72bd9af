"""A tree's netCDF file with every variable defined before its data
(geometry.core.netcdf_tree_write, issue 75): the same file as xarray's ``to_netcdf``."""

from __future__ import annotations

import netCDF4
import numpy as np
import pytest
import xarray as xr

import geometry.core.io as io
import geometry.core.netcdf_tree_write as tree_write
from geometry.core.io import read_netcdf, write_netcdf
from geometry.core.netcdf_tree_write import write_tree_defined_first


def _group(n_vars: int, seed: int) -> xr.Dataset:
    """A group as a stage writes one: coordinates, float and integer data, attributes."""
    rng = np.random.default_rng(seed)
    data = {f"v{i}": (("roll", "segment"), rng.normal(size=(4, 5)),
                      {"units": "mm", "long_name": f"variable {i}"}) for i in range(n_vars)}
    data["count"] = (("roll",), np.arange(4, dtype=np.int64), {"units": "1",
                                                             "long_name": "count"})
    data["with_nan"] = (("segment",), np.array([1.0, np.nan, 2.0, 3.0, np.nan]),
                        {"units": "Pa", "long_name": "some missing"})
    return xr.Dataset(data, coords={
        "roll": ("roll", np.linspace(0.0, 0.3, 4), {"units": "rad", "long_name": "roll"}),
        "segment": ("segment", np.arange(5), {"units": "1", "long_name": "segment"}),
    }, attrs={"stage": f"s{seed}", "n": seed})


def _tree() -> xr.DataTree:
    return xr.DataTree.from_dict({
        "/": xr.Dataset({"torque": ((), 250.0, {"units": "N m", "long_name": "torque"})},
                        attrs={"title": "t"}),
        "/ltca": _group(30, 1), "/ltca/detail": _group(3, 2), "/friction": _group(12, 3)})


def _encoding(tree: xr.DataTree) -> dict:
    """zlib on the float data, no fill value on the coordinates (as write_netcdf's)."""
    out = {}
    for node in tree.subtree:
        ds = node.to_dataset(inherit=False)
        enc = {k: {"zlib": True, "complevel": 4} for k, v in ds.data_vars.items()
               if v.dtype.kind == "f" and v.ndim}
        enc.update({k: {"_FillValue": None} for k in ds.coords})
        out[node.path] = enc
    return out


def _layout(path) -> list:
    """Every group's dimensions, variables (in their order, with dtype, filters,
    chunking, attributes) and attributes: what a reader of the file sees besides data."""
    rows: list = []

    def walk(g) -> None:
        rows.append(("dims", g.path, [(n, len(d)) for n, d in g.dimensions.items()]))
        for name, v in g.variables.items():
            attrs = [(k, repr(np.asarray(v.getncattr(k)).tolist())) for k in v.ncattrs()]  # NaN
            rows.append((g.path, name, v.dimensions, str(v.dtype), v.filters(),
                         v.chunking(), attrs))
        rows.append(("attrs", g.path, [(k, str(g.getncattr(k))) for k in g.ncattrs()]))
        for child in g.groups.values():
            walk(child)

    with netCDF4.Dataset(path) as ds:
        walk(ds)
    return rows


def test_the_file_is_xarrays_file(tmp_path):
    """Independent reference: the same tree and encoding written by xarray's
    ``DataTree.to_netcdf``. Exact: the same data read back (``identical``, NaN included)
    and the same layout (variable order, dtypes, filters, chunking, attributes); only the
    order in which the data blocks are written differs."""
    tree, enc = _tree(), _encoding(_tree())
    assert write_tree_defined_first(tree, tmp_path / "new.nc", enc)
    tree.to_netcdf(tmp_path / "old.nc", engine="netcdf4", encoding=enc)
    with xr.open_datatree(tmp_path / "new.nc") as new, \
            xr.open_datatree(tmp_path / "old.nc") as old:
        assert new.load().identical(old.load())
    assert _layout(tmp_path / "new.nc") == _layout(tmp_path / "old.nc")


def test_chunked_data_keep_xarrays_path(tmp_path):
    """A dask variable is written by xarray's own ``sync`` (the queue takes in-memory
    data only): the values read back equal the computed ones exactly."""
    pytest.importorskip("dask.array")
    tree = _tree()
    lazy = tree["ltca"].to_dataset(inherit=False).chunk({"roll": 2})
    tree["ltca"] = xr.DataTree(lazy)
    assert write_tree_defined_first(tree, tmp_path / "lazy.nc", {})
    with xr.open_datatree(tmp_path / "lazy.nc") as back:
        np.testing.assert_array_equal(back["ltca"]["v7"].values, lazy["v7"].values)


def test_an_unknown_group_in_the_encoding_is_refused_before_writing(tmp_path):
    with pytest.raises(ValueError, match="unexpected encoding group"):
        write_tree_defined_first(_tree(), tmp_path / "x.nc", {"/nowhere": {}})
    assert not (tmp_path / "x.nc").exists()


def test_without_xarrays_store_functions_write_netcdf_falls_back(tmp_path, monkeypatch):
    """Where this xarray lacks the store functions used, nothing is written by the new
    path and write_netcdf writes through ``to_netcdf``: the same round trip."""
    monkeypatch.setattr(tree_write, "_xarray_pieces", lambda: None)
    assert not write_tree_defined_first(_tree(), tmp_path / "none.nc", {})
    assert not (tmp_path / "none.nc").exists()
    path = write_netcdf(_tree(), tmp_path / "fallback.nc")
    assert read_netcdf(path)["ltca"]["v3"].values.shape == (4, 5)


def test_write_netcdf_of_a_tree_goes_the_defined_first_way(tmp_path, monkeypatch):
    """write_netcdf writes a tree through write_tree_defined_first (not ``to_netcdf``),
    and the file reads back as the tree written."""
    calls = []
    real = io.write_tree_defined_first

    def spy(*args, **kwargs):
        calls.append(args[1])
        return real(*args, **kwargs)

    def no_to_netcdf(*args, **kwargs):  # pragma: no cover - the failure's message
        raise AssertionError("DataTree.to_netcdf called")

    monkeypatch.setattr(io, "write_tree_defined_first", spy)
    monkeypatch.setattr(xr.DataTree, "to_netcdf", no_to_netcdf)
    tree = _tree()
    back = read_netcdf(write_netcdf(tree, tmp_path / "t.nc"))
    assert len(calls) == 1
    for node in tree.subtree:
        for name, var in node.to_dataset(inherit=False).data_vars.items():
            np.testing.assert_array_equal(back[node.path][name].values, var.values)
