"""An earlier design's FE coefficients kept for a re-synthesis that moves the tooth by
micrometres (:mod:`contact.compliance.fe.reuse`, issue 71). The reference is the
re-synthesised member's own build: the kept coefficients must agree with it within the
error docs/fe.md states for the bound (the FE root stress within 1 %), and a member moved
farther than the bound must be built, not kept."""

import dataclasses
import shutil

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import bundled_case_path
from contact.compliance.fe import FEOptions, cache_key, cache_path, influence_coefficients
from contact.compliance.fe.cache import CHECKSUM_ATTR, data_checksum, read_cache_entry
from contact.compliance.fe.reuse import REUSE_DEPTH_FRACTION, point_deviation, reuse_near_model
from geometry.case import load_case

#: the coarse model of the CI tests (tests/test_fe_tooth.py)
COARSE = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                   rim_divisions=2, fillet_divisions=2, load_nu=5, load_nv=4)


def _moved(case, d_blade: float, d_flankrem: float):
    """``case`` with its pinion's convex blade turned by ``d_blade`` [rad] and its flank
    relief angle by ``d_flankrem`` [rad] (a re-synthesis's micro-geometry)."""
    pinion = case.member("pinion")
    tool = pinion.convex
    blade = dataclasses.replace(tool.blade, blade_angle=tool.blade.blade_angle + d_blade,
                                flankrem_angle=tool.blade.flankrem_angle + d_flankrem)
    moved = dataclasses.replace(pinion, convex=dataclasses.replace(tool, blade=blade))
    return dataclasses.replace(case, pinion=moved)


def _peak_per_load(ds) -> np.ndarray:
    """The largest maximum principal fillet stress of each unit load [MPa/N] (load_u,
    load_v): the root stress a load there gives."""
    return ds["fillet_max_principal"].max(("tooth", "side", "station", "arc")).values


@pytest.fixture(scope="module")
def earlier_build(tmp_path_factory):
    """The earlier design's coarse pinion build (its drive flank and, on the same
    factorisation, its coast flank), made once for both tests: each copies the entries to a
    directory of its own (the tests write beside them and list them)."""
    case = load_case(bundled_case_path())
    built = tmp_path_factory.mktemp("earlier")
    influence_coefficients(case, "pinion", "drive", COARSE, cache_dir=built,
                           progress=False, other_flank=True)
    return case, built


def _copy_of(earlier_build, target):
    case, built = earlier_build
    shutil.copytree(built, target)
    return case


def test_a_near_member_keeps_the_earlier_coefficients_within_the_stated_error(
        earlier_build, tmp_path):
    """The pinion's coast (convex) blade turned by 0.05 deg and its flank relief by 0.2 deg:
    its load and stress points move by less than the bound (2 % of the whole depth), so the earlier
    coefficients of both flanks are written under the new keys (with where from and how
    far); against the moved pinion's own build, the peak fillet stress of the unit loads
    agrees within 1 % at the loads carrying at least half the largest (where a root
    stress is decided) and the loaded tooth's own compliance within 1 %. The moved
    pinion's own coefficients of both flanks come from one build (``other_flank``: the
    coast flank on the drive build's factorisation, equal to a build of its own within
    1e-10, tests/test_fe_both_flanks.py), as the earlier design's do. One coarse build
    here (~7 s of CPU), the earlier design's shared with the next test. The entries the
    reuse and the build write are handed to their ``written`` callbacks as the files read
    back (the development keeps them in its memo instead of reading them: issue 75), and
    the earlier entries come through ``read``."""
    kept_dir, own_dir = tmp_path / "kept", tmp_path / "own"
    case = _copy_of(earlier_build, kept_dir)
    moved = _moved(case, np.radians(0.05), np.radians(0.2))
    depth = (case.member("pinion").blank.outer_addendum
             + case.member("pinion").blank.outer_dedendum)
    reads, written = [], {}

    def read(path, key):
        reads.append(key)
        return read_cache_entry(path, key)

    def keep(path, key, ds):  # the entries of both directories carry the same keys
        assert path == cache_path(key, path.parent) and (path.parent, key) not in written
        written[path.parent, key] = ds

    deviation = reuse_near_model(moved, case, "pinion", COARSE, cache_dir=kept_dir,
                                 read=read, written=keep)
    assert deviation is not None and 0.0 < deviation <= REUSE_DEPTH_FRACTION * depth
    assert reads == [cache_key(case.member("pinion"), f, COARSE)
                     for f in ("concave", "convex")] and len(written) == 2
    for flank in ("drive", "coast"):
        kept = influence_coefficients(moved, "pinion", flank, COARSE, cache_dir=kept_dir,
                                      progress=False)
        assert kept.attrs["reuse_point_deviation_mm"] == round(deviation, 6)
        assert kept.attrs["reused_from"] != kept.attrs["cache_key"]
        # written with the earlier entry's stored checksum (not hashed again, issue 75):
        # the same as the data's own, and as the earlier entry's
        earlier_entry = read_cache_entry(cache_path(kept.attrs["reused_from"], kept_dir),
                                         kept.attrs["reused_from"])
        assert kept.attrs[CHECKSUM_ATTR] == data_checksum(kept) \
            == earlier_entry.attrs[CHECKSUM_ATTR]
        xr.testing.assert_identical(written[kept_dir, kept.attrs["cache_key"]], kept)
        own = influence_coefficients(moved, "pinion", flank, COARSE, cache_dir=own_dir,
                                     progress=False, other_flank=True, written=keep)
        assert "reused_from" not in own.attrs
        # both flanks written by the first build, the second flank's read back as written
        assert len(written) == 4
        xr.testing.assert_identical(written[own_dir, own.attrs["cache_key"]], own)
        a, b = _peak_per_load(kept), _peak_per_load(own)
        heavy = b >= 0.5 * b.max()
        err = float(np.max(np.abs(a - b)[heavy] / b[heavy]))
        assert err <= 0.01, (flank, err)
        ga = kept["compliance"].sel(tooth=0).values
        gb = own["compliance"].sel(tooth=0).values
        n = ga.shape[0] * ga.shape[1]
        da, db = np.diag(ga.reshape(n, n)), np.diag(gb.reshape(n, n))
        assert float(np.max(np.abs(da - db) / db)) <= 0.01, flank


def test_a_member_moved_farther_is_built_not_kept(earlier_build, tmp_path):
    """The coast blade turned by 3 deg moves its points by more than the bound: nothing is
    written (and why is said), and a member unchanged keeps its own entries (deviation 0,
    nothing written).
    No build: the earlier design's entries are the module's (``earlier_build``)."""
    tmp_path = tmp_path / "cache"
    case = _copy_of(earlier_build, tmp_path)
    far = _moved(case, np.radians(3.0), 0.0)
    before = sorted(p.name for p in tmp_path.iterdir())
    depth = far.member("pinion").blank.outer_addendum + far.member("pinion").blank.outer_dedendum
    assert point_deviation(far, case, "pinion", COARSE) > REUSE_DEPTH_FRACTION * depth
    why: list[str] = []
    assert reuse_near_model(far, case, "pinion", COARSE, cache_dir=tmp_path,
                            refused=why) is None
    assert len(why) == 1 and "mm from the earlier design's, beyond" in why[0]
    assert reuse_near_model(case, case, "pinion", COARSE, cache_dir=tmp_path) == 0.0
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    key = cache_key(far.member("pinion"), "convex", COARSE)
    assert not cache_path(key, tmp_path).exists()
