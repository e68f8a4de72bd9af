"""netCDF conventions: atomic writes, safe attributes, identical round trips."""

from __future__ import annotations

import os

import numpy as np
import pytest
import xarray as xr

from geometry import __version__
from geometry.core.errors import InputError
from geometry.core.io import (
    NetCDFError,
    check_conventions,
    netcdf_safe_attrs,
    read_netcdf,
    write_netcdf,
)


def _dataset():
    return xr.Dataset(
        {
            "force": (
                ("roll", "segment"),
                np.arange(6.0).reshape(2, 3),
                {"units": "N", "long_name": "segment force"},
            ),
            "status": (
                ("roll",),
                np.array(["solved", "failed"]),
                {"long_name": "status", "units": "1"},
            ),
        },
        coords={
            "roll": ("roll", [0.0, 0.1], {"units": "rad", "long_name": "pinion roll angle"}),
            "segment": ("segment", [0, 1, 2], {"units": "1", "long_name": "segment index"}),
            "solver": ("solver", ["active_set", "osqp"], {"long_name": "solver"}),
        },
        attrs={"case": "test", "certified": True, "settings": {"eps": 1e-9}},
    )


def test_dataset_round_trip_identical(tmp_path):
    path = write_netcdf(_dataset(), tmp_path / "a.nc", inputs="[pair]\nshaft_angle = 90\n")
    first = read_netcdf(path)
    assert first.attrs["toolkit_version"] == __version__
    assert first.attrs["certified"] == 1
    assert first.attrs["inputs"].startswith("[pair]")
    again = write_netcdf(first, tmp_path / "b.nc")
    xr.testing.assert_identical(read_netcdf(again), first)


def test_datatree_round_trip_identical(tmp_path):
    tree = xr.DataTree.from_dict(
        {
            "/": xr.Dataset(attrs={"case": "x"}),
            "/ltca": _dataset(),
            "/utca": _dataset().drop_vars("status"),
        }
    )
    path = write_netcdf(tree, tmp_path / "t.nc", inputs="case text")
    first = read_netcdf(path)
    assert isinstance(first, xr.DataTree)
    assert set(first.children) == {"ltca", "utca"}
    again = read_netcdf(write_netcdf(first, tmp_path / "t2.nc"))
    xr.testing.assert_identical(again, first)


def test_missing_units_refused_and_nothing_written(tmp_path):
    ds = _dataset()
    ds["bad"] = ("roll", [1.0, 2.0])
    target = tmp_path / "bad.nc"
    with pytest.raises(NetCDFError, match="bad"):
        write_netcdf(ds, target)
    assert not target.exists()
    assert os.listdir(tmp_path) == []


def test_failed_write_leaves_old_file_and_no_temporary(tmp_path, monkeypatch):
    target = write_netcdf(_dataset(), tmp_path / "keep.nc")
    before = target.read_bytes()

    def boom(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", boom)
    with pytest.raises(NetCDFError, match="disk full"):
        write_netcdf(_dataset(), target)
    assert target.read_bytes() == before
    assert sorted(os.listdir(tmp_path)) == ["keep.nc"]


def test_safe_attrs():
    out = netcdf_safe_attrs(
        {"a": True, "b": {"x": 1}, "c": [1, 2], "d": ["p", "q"], "e": 1.5, "f": float("nan")}
    )
    assert out["a"] == 1 and isinstance(out["a"], int)
    assert out["b"] == '{"x": 1}'
    np.testing.assert_array_equal(out["c"], [1, 2])
    assert out["d"] == '["p", "q"]'
    assert out["f"] == "nan"
    with pytest.raises(InputError, match="'g'"):
        netcdf_safe_attrs({"g": None})
    with pytest.raises(InputError, match="'h'"):
        netcdf_safe_attrs({"h": object()})


def test_check_conventions_reports_every_problem():
    ds = _dataset()
    ds["x1"] = ("roll", [1.0, 2.0], {"units": "mm"})
    ds["x2"] = ("roll", [1.0, 2.0], {"long_name": "no units"})
    with pytest.raises(NetCDFError) as info:
        check_conventions(ds)
    assert "x1" in str(info.value) and "x2" in str(info.value)


def test_read_missing_file(tmp_path):
    with pytest.raises(NetCDFError, match="no such"):
        read_netcdf(tmp_path / "nope.nc")


def test_writes_in_memory_data_without_a_cluster_wide_lock(tmp_path):
    """While a distributed Client is dask's default (a study's client), xarray would take a
    distributed.Lock per variable written — a round trip to the scheduler each (~700 per
    121-point study). write_netcdf writes in-memory data under the threaded scheduler's
    lock instead; dask-backed data keep xarray's choice. Checked on an in-process
    cluster: the lock xarray picks inside and outside the block, and a file written and
    read back while the client is the default."""
    distributed = pytest.importorskip("distributed")
    from xarray.backends.locks import get_write_lock

    from geometry.core.io import _local_write_lock

    ds = _dataset()
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1,
                            dashboard_address=None):
        assert isinstance(get_write_lock("x"), distributed.Lock)
        with _local_write_lock(ds):
            assert not isinstance(get_write_lock("x"), distributed.Lock)
        with _local_write_lock(ds.chunk()):  # dask arrays: a cluster may compute them
            assert isinstance(get_write_lock("x"), distributed.Lock)
        write_netcdf(ds, tmp_path / "a.nc")
        back = read_netcdf(tmp_path / "a.nc", tree=False)
    np.testing.assert_array_equal(back["force"].values, ds["force"].values)
