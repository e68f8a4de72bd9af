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


def _large_tree() -> xr.DataTree:
    """A tree with variables above the writer's ``UNCACHED_BYTES`` (80 kB floats with
    missing values, 80 kB integers) beside small ones, and a time coordinate with bounds
    (xarray's ``cf_encoder`` encodes a bounds variable with its parent's time units)."""
    rng = np.random.default_rng(7)
    big = rng.normal(size=(100, 100))
    big[3, 5] = np.nan
    times = np.array(["2026-01-01", "2026-01-02", "2026-01-03"], dtype="datetime64[ns]")
    bounds = np.stack([times, times + np.timedelta64(1, "D")], axis=1)
    timed = xr.Dataset(
        {"level": (("time",), np.array([1.0, 2.0, 4.0]), {"units": "mm"}),
         "time_bnds": (("time", "nv"), bounds)},
        coords={"time": ("time", times, {"bounds": "time_bnds"})})
    tree = _tree()
    tree["ltca/big"] = xr.DataTree(xr.Dataset({
        "pressure": (("row", "col"), big, {"units": "MPa"}),
        "count": (("row", "col"), np.arange(10_000, dtype=np.int64).reshape(100, 100),
                  {"units": "1"})}))
    tree["timed"] = xr.DataTree(timed)
    return tree


@pytest.mark.parametrize("uncached_bytes", [0, 1 << 16])
def test_variables_encoded_again_give_xarrays_file(tmp_path, monkeypatch, uncached_bytes):
    """Independent reference: xarray's ``DataTree.to_netcdf`` of the same tree and
    encoding. The variables above ``UNCACHED_BYTES`` are encoded a second time when
    written (all of them at 0, the 80 kB ones at the default): the data read back are
    identical (exact: the same encoder on the same input) and the layout (order, dtypes,
    filters, chunking, attributes, the time bounds' units) is the same."""
    monkeypatch.setattr(tree_write, "UNCACHED_BYTES", uncached_bytes)
    tree = _large_tree()
    enc = _encoding(tree)
    enc["/timed"]["time"] = {"_FillValue": None, "units": "hours since 2026-01-01"}
    assert write_tree_defined_first(tree, tmp_path / "new.nc", enc)
    tree.to_netcdf(tmp_path / "old.nc", engine="netcdf4", encoding=enc)
    with xr.open_datatree(tmp_path / "new.nc") as new, \
            xr.open_datatree(tmp_path / "old.nc") as old:
        assert new.load().identical(old.load())
    assert _layout(tmp_path / "new.nc") == _layout(tmp_path / "old.nc")


def test_only_large_variables_bypass_the_chunk_cache(tmp_path, monkeypatch):
    """The chunk cache is switched off for the variables of at least ``UNCACHED_BYTES``
    (their data written, compressed, when they are written, not all held until the
    file closes) and for those only (setting it reopens the HDF5 dataset): the two
    80 kB variables of the tree, nothing else."""
    seen = []
    real = tree_write._uncached

    def spy(target, nbytes):
        if nbytes >= tree_write.UNCACHED_BYTES:
            seen.append((target.variable_name, nbytes))
        return real(target, nbytes)

    monkeypatch.setattr(tree_write, "_uncached", spy)
    tree = _large_tree()
    enc = _encoding(tree)
    enc["/timed"]["time"] = {"_FillValue": None, "units": "hours since 2026-01-01"}
    assert write_tree_defined_first(tree, tmp_path / "t.nc", enc)
    assert sorted(seen) == [("count", 80_000), ("pressure", 80_000)]
