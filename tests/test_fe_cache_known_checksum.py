"""A cache entry written with its checksum known (:func:`contact.compliance.fe.cache.
write_cache_entry`'s ``checksum``: an entry kept for a re-synthesis under a new key,
issue 75) is the entry written without it: the same attributes and data read back, and
it passes every check of :func:`contact.compliance.fe.cache.read_cache_entry`."""

from __future__ import annotations

import numpy as np
import xarray as xr

from contact.compliance.fe.cache import (
    CHECKSUM_ATTR,
    data_checksum,
    read_cache_entry,
    write_cache_entry,
)


def _entry() -> xr.Dataset:
    rng = np.random.default_rng(75)
    return xr.Dataset({"compliance": (("load_u", "u"), rng.random((4, 5))),
                       "fillet_in_root": ("u", np.array([0, 1, 1, 0, 1], dtype=np.int8))},
                      coords={"load_u": np.linspace(0.0, 1.0, 4),
                              "side": ("side", np.array(["left", "right"]))})


def test_an_entry_written_with_its_known_checksum_equals_one_hashed(tmp_path) -> None:
    ds = _entry()
    hashed = write_cache_entry(ds, tmp_path / "a.nc", "k")
    given = write_cache_entry(ds, tmp_path / "b.nc", "k",
                              checksum=hashed.attrs[CHECKSUM_ATTR])
    xr.testing.assert_identical(hashed, given)
    a, b = read_cache_entry(tmp_path / "a.nc", "k"), read_cache_entry(tmp_path / "b.nc", "k")
    assert a is not None and b is not None
    xr.testing.assert_identical(a, b)
    assert b.attrs[CHECKSUM_ATTR] == data_checksum(b) == data_checksum(ds)


def test_a_wrong_known_checksum_is_caught_on_reading(tmp_path) -> None:
    """A stale checksum handed in is not trusted on reading: the entry is set aside as
    corrupt (and built again by its caller), never used."""
    write_cache_entry(_entry(), tmp_path / "c.nc", "k", checksum="0" * 64)
    assert read_cache_entry(tmp_path / "c.nc", "k") is None
