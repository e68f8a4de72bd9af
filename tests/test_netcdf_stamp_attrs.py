"""The attributes :func:`geometry.core.io.write_netcdf` stamps on every variable, set on
the variables themselves (issue 75, docs/performance.md "The run file's attributes
stamped variable by variable"): the same as the earlier path through ``ds[name]`` (a
DataArray per variable), the input left as it was."""

from __future__ import annotations

import numpy as np
import xarray as xr

from geometry.core.io import _stamp, netcdf_safe_attrs, read_netcdf, write_netcdf


def _stamped_by_name(ds: xr.Dataset) -> dict[str, dict]:
    """The per-variable attributes as the earlier ``_stamp`` set them, through ``ds[name]``
    (the reference this test pins the faster path to)."""
    ds = ds.copy(deep=False)
    for name in ds.variables:
        ds[name].attrs = netcdf_safe_attrs(ds[name].attrs)
        if name in ds.coords:
            kind = "coordinate"
        elif "flag_values" in ds[name].attrs or "flag_masks" in ds[name].attrs:
            kind = "auxiliaryInformation"
        else:
            kind = "modelResult"
        ds[name].attrs.setdefault("coverage_content_type", kind)
    return {str(n): dict(v.attrs) for n, v in ds.variables.items()}


def _dataset() -> xr.Dataset:
    ds = _bare()
    for var in ds.variables.values():
        var.attrs.setdefault("units", "1")
        var.attrs.setdefault("long_name", "a test variable")
    return ds


def _bare() -> xr.Dataset:
    return xr.Dataset(
        {"pressure": (("roll", "u"), np.arange(6.0).reshape(2, 3), {"units": "MPa",
                                                                     "ok": True}),
         "status": ("roll", np.array([0, 1], dtype=np.int8),
                    {"flag_values": np.array([0, 1], dtype=np.int8),
                     "flag_meanings": "ok edge"}),
         "kept": ("u", np.ones(3), {"coverage_content_type": "qualityInformation"})},
        coords={"roll": ("roll", [0.0, 0.5], {"units": "1"}),
                "u": np.linspace(0.0, 1.0, 3),
                "aux": ("u", np.zeros(3), {"long_name": "an auxiliary coordinate"})})


def test_stamped_variable_attributes_equal_the_earlier_path() -> None:
    ds = _dataset()
    before = {str(n): dict(v.attrs) for n, v in ds.variables.items()}
    out = _stamp(ds, "x = 1", created="2026-11-27T00:00:00Z")
    got = {str(n): dict(v.attrs) for n, v in out.variables.items()}
    want = _stamped_by_name(ds)
    assert got.keys() == want.keys()
    for name in want:
        assert got[name].keys() == want[name].keys(), name
        for key, value in want[name].items():
            np.testing.assert_array_equal(got[name][key], value, err_msg=f"{name}.{key}")
    # the caller's dataset untouched, as before
    assert {str(n): dict(v.attrs) for n, v in ds.variables.items()} == before
    assert got["kept"]["coverage_content_type"] == "qualityInformation"
    assert got["status"]["coverage_content_type"] == "auxiliaryInformation"
    assert got["aux"]["coverage_content_type"] == "coordinate"


def test_tree_written_with_the_stamped_attributes(tmp_path) -> None:
    tree = xr.DataTree.from_dict({"/": xr.Dataset(attrs={"title": "t"}),
                                  "/a": _dataset()})
    path = write_netcdf(tree, tmp_path / "t.nc")
    back = read_netcdf(path)
    node = back["a"].to_dataset()
    want = _stamped_by_name(_dataset())
    for name in ("pressure", "status", "kept", "roll", "aux"):
        assert node[name].attrs["coverage_content_type"] == \
            want[name]["coverage_content_type"], name
    np.testing.assert_array_equal(node["pressure"].values, _dataset()["pressure"].values)
