"""The FE influence-coefficient cache checks its entries like input (issue 55 item 4).

An entry (contact.compliance.fe.cache) is used only if it is a readable netCDF file under
the expected key whose data match the SHA-256 stored with them and are finite; any other
entry is renamed aside (kept), one warning names the file and the reason, and the
coefficients are built again. The reader and writer are tested on small synthetic
datasets (building real coefficients takes seconds to minutes); the end-to-end paths
through ``influence_coefficients`` and ``shared_coefficients`` replace the FE build by a
tiny dataset (monkeypatched where the module looks it up) and count the builds.
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import resolve_case
from contact.compliance.fe import FEOptions, cache_key, cache_path, member_flank
from contact.compliance.fe.cache import (
    CHECKSUM_ATTR,
    FORMAT_VERSION,
    data_checksum,
    read_cache_entry,
    write_cache_entry,
)
from geometry.core.errors import LTCAError

LOGGER = "contact.compliance.fe.cache"
KEY = "a" * 64


def _tiny(seed: int = 0) -> xr.Dataset:
    """A small dataset shaped like the coefficients: floats, an int8 flag, int and string
    coordinates, attributes."""
    rng = np.random.default_rng(seed)
    return xr.Dataset(
        {"compliance": (("load_u", "u"), rng.random((6, 7)), {"units": "mm/N"}),
         "fillet_in_root": (("u",), (rng.random(7) > 0.5).astype(np.int8))},
        coords={"load_u": np.linspace(0.05, 0.95, 6), "u": np.linspace(0.05, 0.95, 7),
                "tooth": ("tooth", np.array([-1, 0, 1], dtype=np.int32)),
                "side": ("side", np.array(["concave", "convex"]))},
        attrs={"title": "synthetic coefficients"})


def _warnings(caplog) -> list[logging.LogRecord]:
    return [r for r in caplog.records if r.name == LOGGER and r.levelno >= logging.WARNING]


def _aside(path: Path) -> list[Path]:
    return sorted(path.parent.glob(f"{path.name}.corrupt-*"))


def _written(tmp_path: Path) -> tuple[Path, xr.Dataset]:
    path = tmp_path / f"fe-{KEY}.nc"
    return path, write_cache_entry(_tiny(), path, KEY)


def test_written_entry_reads_back_with_key_and_checksum(tmp_path, caplog):
    # the writer stamps cache_key and data_sha256 (the checksum of the in-memory data);
    # the reader gives back the identical dataset (the checksum survives the netCDF round
    # trip, string coordinates included) and logs nothing; the file is left in place
    caplog.set_level(logging.DEBUG, logger=LOGGER)
    path, written = _written(tmp_path)
    assert written.attrs["cache_key"] == KEY
    assert written.attrs[CHECKSUM_ATTR] == data_checksum(_tiny())
    assert len(written.attrs[CHECKSUM_ATTR]) == 64
    back = read_cache_entry(path, KEY)
    assert back is not None
    xr.testing.assert_identical(back, written)
    assert data_checksum(back) == written.attrs[CHECKSUM_ATTR]
    assert not _warnings(caplog) and not _aside(path) and path.is_file()


def test_checksum_covers_every_value_and_coordinate():
    # one ulp in a data variable, one changed coordinate value or string, a renamed
    # variable each change the checksum; the attributes do not
    ds = _tiny()
    ref = data_checksum(ds)
    bumped = ds.copy(deep=True)
    bumped["compliance"].values[2, 3] = np.nextafter(bumped["compliance"].values[2, 3], 2.0)
    assert data_checksum(bumped) != ref
    assert data_checksum(ds.assign_coords(tooth=np.array([-1, 0, 2], dtype=np.int32))) != ref
    assert data_checksum(ds.assign_coords(side=np.array(["concave", "convey"]))) != ref
    assert data_checksum(ds.rename({"compliance": "compliance2"})) != ref
    assert data_checksum(ds.assign_attrs(title="other")) == ref


def test_missing_entry_is_a_quiet_miss(tmp_path, caplog):
    # no file: None, nothing logged, nothing created
    caplog.set_level(logging.DEBUG, logger=LOGGER)
    assert read_cache_entry(tmp_path / f"fe-{KEY}.nc", KEY) is None
    assert not _warnings(caplog) and list(tmp_path.iterdir()) == []


def test_writer_refuses_non_finite_data(tmp_path):
    # coefficients holding NaN would never be used: not written, the variable named
    ds = _tiny()
    ds["compliance"].values[0, 0] = np.nan
    path = tmp_path / f"fe-{KEY}.nc"
    with pytest.raises(LTCAError, match="'compliance' holds non-finite values"):
        write_cache_entry(ds, path, KEY)
    assert not path.exists()


def test_a_full_disk_said_as_hdf_error_is_a_write_failure(tmp_path, monkeypatch):
    """The netCDF library reports a full disk as "NetCDF: HDF error" (a RuntimeError, no
    errno): the writer says it in words as the OSError its callers catch (FileWriteError,
    so the coefficients are used from memory: ``contact.compliance.fe.cache.not_written``),
    where the disk has less than FULL_DISK_MARGIN free (checked by
    geometry.core.atomic_files.write_failure, as tests/test_refusals.py's output files); with
    room left the library's error stands. Found on a full /tmp (issue 71's unseen designs,
    round 9): "the other flank's influence coefficients not built on this factorisation:
    NetCDF: HDF error"."""
    import shutil

    import geometry.core.atomic_files as af
    from contact.compliance.fe.cache import NOT_WRITTEN_ATTR, not_written
    from geometry.core.errors import FileWriteError

    def hdf_error(self, *args, **kwargs):
        raise RuntimeError("NetCDF: HDF error")

    path = tmp_path / f"fe-{KEY}.nc"
    monkeypatch.setattr(xr.Dataset, "to_netcdf", hdf_error)
    monkeypatch.setattr(af.shutil, "disk_usage",
                        lambda p: shutil._ntuple_diskusage(10**9, 10**9, 1024))
    with pytest.raises(FileWriteError, match=r"could not write .*: no space left on") as err:
        write_cache_entry(_tiny(), path, KEY)
    assert isinstance(err.value, OSError)
    assert not_written(_tiny(), path, err.value).attrs[NOT_WRITTEN_ATTR].startswith(
        f"could not write {str(path)!r}: no space left on")
    monkeypatch.setattr(af.shutil, "disk_usage",
                        lambda p: shutil._ntuple_diskusage(10**9, 10**8, 10**8))
    with pytest.raises(RuntimeError, match="NetCDF: HDF error"):
        write_cache_entry(_tiny(), path, KEY)
    assert list(tmp_path.iterdir()) == []


def _flip_coordinate_bytes(path: Path, ds: xr.Dataset) -> None:
    """Invert a byte inside the stored values of coordinate ``u`` (written uncompressed, so
    its little-endian bytes are in the file): the file stays readable, its data change."""
    raw = bytearray(path.read_bytes())
    needle = np.ascontiguousarray(ds["u"].values, dtype="<f8").tobytes()
    at = raw.find(needle)
    assert at >= 0 and raw.find(needle, at + 1) < 0
    raw[at + 3 * 8 + 2] ^= 0xFF
    path.write_bytes(bytes(raw))


def _truncate(path: Path, ds: xr.Dataset) -> None:
    """Keep the first half of the file (an interrupted copy, a full disk)."""
    raw = path.read_bytes()
    path.write_bytes(raw[: len(raw) // 2])


def _nan_old_checksum(path: Path, ds: xr.Dataset) -> None:
    """Overwrite a variable with NaN and rewrite the file keeping the old attributes (key
    and checksum): what the issue's NaN-holding cache file was."""
    bad = ds.copy(deep=True)
    bad["compliance"].values[:] = np.nan
    bad.to_netcdf(path, engine="netcdf4")


def _nan_new_checksum(path: Path, ds: xr.Dataset) -> None:
    """NaN data with a checksum that matches them (a writer that did not check)."""
    bad = ds.copy(deep=True)
    bad["compliance"].values[1, :] = np.nan
    bad.assign_attrs({CHECKSUM_ATTR: data_checksum(bad)}).to_netcdf(path, engine="netcdf4")


def _foreign_key(path: Path, ds: xr.Dataset) -> None:
    """A valid entry of another key under this key's name."""
    write_cache_entry(ds, path, "b" * 64)


def _no_checksum(path: Path, ds: xr.Dataset) -> None:
    """The right key but no checksum (written as before FORMAT_VERSION 4)."""
    old = ds.copy()
    old.attrs = {"cache_key": KEY}
    old.to_netcdf(path, engine="netcdf4")


def _no_key(path: Path, ds: xr.Dataset) -> None:
    """Some other netCDF file under this key's name (no cache_key attribute)."""
    other = ds.copy()
    other.attrs = {}
    other.to_netcdf(path, engine="netcdf4")


@pytest.mark.parametrize(("damage", "reason"), [
    (_flip_coordinate_bytes, "is corrupt (checksum mismatch)"),
    (_truncate, "is unreadable (not a complete netCDF file)"),
    (_nan_old_checksum, "is corrupt (checksum mismatch)"),
    (_nan_new_checksum, "holds non-finite values (in 'compliance')"),
    (_foreign_key, "holds another key (a foreign entry)"),
    (_no_key, "has no cache key (a foreign file)"),
    (_no_checksum, "is corrupt (no data checksum)"),
], ids=["flipped-bytes", "truncated", "nan-old-checksum", "nan-own-checksum", "foreign-key",
        "no-key", "no-checksum"])
def test_bad_entry_is_set_aside_with_one_warning(tmp_path, caplog, damage, reason):
    # a damaged entry is never used: the reader returns None, logs exactly one warning
    # naming the file, the reason and where it went, and renames the file aside (kept,
    # byte for byte) to a name the lookup never matches: a second read is a quiet miss
    caplog.set_level(logging.DEBUG, logger=LOGGER)
    path, written = _written(tmp_path)
    damage(path, written)
    bad_bytes = path.read_bytes()
    assert read_cache_entry(path, KEY) is None
    records = _warnings(caplog)
    assert len(records) == 1, [r.getMessage() for r in records]
    msg = records[0].getMessage()
    aside = _aside(path)
    assert len(aside) == 1
    assert msg == f"FE cache entry {path} {reason}; set aside as {aside[0]} and rebuilt"
    assert "Error" not in msg and "errno" not in msg.lower()  # no raw library text
    assert not path.exists() and aside[0].read_bytes() == bad_bytes
    caplog.clear()
    assert read_cache_entry(path, KEY) is None
    assert not _warnings(caplog)


def test_entries_set_aside_twice_keep_both(tmp_path, caplog):
    # two bad versions of one entry set aside one after the other are both kept (the
    # names never collide, even within one clock tick)
    caplog.set_level(logging.WARNING, logger=LOGGER)
    path = tmp_path / f"fe-{KEY}.nc"
    for _ in range(2):
        path.write_bytes(b"not a netCDF file")
        assert read_cache_entry(path, KEY) is None
    assert len(_aside(path)) == 2 and len(_warnings(caplog)) == 2


def test_format_version_is_part_of_the_key():
    # the checksum came with format 4: entries of older formats are under other keys
    # (they simply miss and are rebuilt)
    case = resolve_case(None)
    member = case.member("gear")
    assert FORMAT_VERSION >= 4
    assert cache_key(member, "convex", FEOptions()) == cache_key(member, "convex", FEOptions())
    import contact.compliance.fe.cache as cache_mod

    old = cache_mod.FORMAT_VERSION
    try:
        cache_mod.FORMAT_VERSION = 3
        older = cache_key(member, "convex", FEOptions())
    finally:
        cache_mod.FORMAT_VERSION = old
    assert older != cache_key(member, "convex", FEOptions())


# ------------------------------------------------------------------ end to end, no FE build
class _Builds:
    """Stand-ins for build_influence_model/influence_dataset: count the builds and give a
    tiny dataset under the key asked for."""

    def __init__(self):
        self.count = 0

    def model(self, *args, **kwargs):
        from types import SimpleNamespace

        self.count += 1
        return SimpleNamespace(name="model", factor=SimpleNamespace(close=lambda: None))

    def dataset(self, model, case, *, progress=True, key="", checkpoint=None):
        assert model.name == "model"
        return _tiny(seed=self.count).assign_attrs(cache_key=key)


@pytest.fixture
def fake_build(monkeypatch, tmp_path):
    builds = _Builds()
    monkeypatch.setattr("contact.compliance.fe.influence.build_influence_model", builds.model)
    monkeypatch.setattr("contact.compliance.fe.influence.influence_dataset", builds.dataset)
    case = resolve_case(None)
    key = cache_key(case.member("gear"), member_flank(case, "gear", "drive"), FEOptions())
    return builds, case, cache_path(key, tmp_path), key


def test_influence_coefficients_rebuilds_a_corrupt_entry_once(fake_build, tmp_path, caplog):
    # influence_coefficients: a first call builds and caches (with checksum); the issue's
    # NaN-overwritten file is not used: one warning, exactly one rebuild, a new entry that
    # passes every check; the next call reads it (no build)
    from contact.compliance.fe import influence_coefficients

    builds, case, path, key = fake_build
    caplog.set_level(logging.WARNING, logger=LOGGER)
    first = influence_coefficients(case, "gear", cache_dir=tmp_path, progress=False)
    assert builds.count == 1 and first.attrs[CHECKSUM_ATTR] == data_checksum(first)
    _nan_old_checksum(path, first)
    again = influence_coefficients(case, "gear", cache_dir=tmp_path, progress=False)
    assert builds.count == 2
    assert np.isfinite(again["compliance"].values).all()
    assert len(_warnings(caplog)) == 1 and "checksum mismatch" in caplog.text
    assert len(_aside(path)) == 1
    caplog.clear()
    xr.testing.assert_identical(read_cache_entry(path, key), again)
    third = influence_coefficients(case, "gear", cache_dir=tmp_path, progress=False)
    assert builds.count == 2 and not _warnings(caplog)
    xr.testing.assert_identical(third, again)


def test_shared_coefficients_rebuilds_a_corrupt_entry_once(fake_build, tmp_path, caplog):
    # shared_coefficients (the LTCA's and the root stress's reader, memoised per file):
    # a truncated entry is set aside with one warning (not a second one from
    # influence_coefficients), rebuilt exactly once, and the new entry read and kept in
    # memory: later calls neither build nor warn and return the same object
    from contact.compliance.fe.contact_compliance import _read_cached, shared_coefficients

    builds, case, path, key = fake_build
    _read_cached.cache_clear()
    caplog.set_level(logging.WARNING, logger=LOGGER)
    write_cache_entry(_tiny(seed=7), path, key)
    _truncate(path, None)
    got = shared_coefficients(case, "gear", cache_dir=tmp_path)
    assert builds.count == 1
    assert len(_warnings(caplog)) == 1 and "is unreadable" in caplog.text
    assert len(_aside(path)) == 1
    caplog.clear()
    first = shared_coefficients(case, "gear", cache_dir=tmp_path)
    xr.testing.assert_identical(first, got)
    assert shared_coefficients(case, "gear", cache_dir=tmp_path) is first
    assert builds.count == 1 and not _warnings(caplog)
    _read_cached.cache_clear()


def test_a_built_entry_is_kept_in_the_memo_as_written(fake_build, tmp_path, monkeypatch):
    # shared_coefficients after a build (issue 75: the root-stress checks of `ltca
    # synthesize` after its FE build): the entry just written is the memo's, not read back
    # from disk; it is what the file reads back as (values, key, checksum); a file
    # replaced afterwards (another inode, size or time) is read as before
    import contact.compliance.fe.contact_compliance as cc

    builds, case, path, key = fake_build
    cc._read_cached.cache_clear()
    reads = []
    monkeypatch.setattr(cc, "read_cache_entry",
                        lambda p, k: reads.append(p) or read_cache_entry(p, k))
    built = cc.shared_coefficients(case, "gear", cache_dir=tmp_path)
    assert builds.count == 1 and reads == []
    assert cc.shared_coefficients(case, "gear", cache_dir=tmp_path) is built
    assert reads == [] and builds.count == 1
    again = read_cache_entry(path, key)
    xr.testing.assert_identical(again, built)
    assert again.attrs[CHECKSUM_ATTR] == built.attrs[CHECKSUM_ATTR] == data_checksum(built)
    write_cache_entry(_tiny(seed=9), path, key)  # replaced: another file version
    other = cc.shared_coefficients(case, "gear", cache_dir=tmp_path)
    assert len(reads) == 1 and builds.count == 1
    xr.testing.assert_identical(other, read_cache_entry(path, key))
    cc._read_cached.cache_clear()


def test_sigint_during_a_build_leaves_no_entry(tmp_path, monkeypatch):
    """Ctrl-C while ``ltca run`` builds the FE coefficients (root stress is on by default,
    issue 53) into an empty cache: the run stops with the shell's 130 and one line, and the
    cache holds no entry and no temporary file that a later run could trust. The signal is
    sent when the build has started (its first log line, the first member's FE tooth
    sections, read from the pipe: an event, not a time; the stiffness assembly's line came
    after the solid, seconds of CPU later, for the same check); the default model's build
    then runs for seconds more (the solid, the stiffness, ~15 s per member with CHOLMOD),
    so the signal lands inside it."""
    import os
    import signal
    import subprocess
    import sys

    from contact.compliance.fe import CACHE_ENV
    from contact.ltca.root_stress import coefficients_cached

    cache = tmp_path / "cache"
    env = {**os.environ, CACHE_ENV: str(cache),
           "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    proc = subprocess.Popen(
        [sys.executable, "-m", "contact", "run", "--torque", "50", "--rolls-per-cycle", "4",
         "--segments", "8", "--speed", "0", "--no-progress", "-v", "-o",
         str(tmp_path / "r.nc")],
        cwd=tmp_path, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    seen = []
    try:
        for line in proc.stderr:   # ends at EOF if the process exits without the line
            seen.append(line)
            if "contact.compliance.fe.section:" in line and " sections; " in line:
                proc.send_signal(signal.SIGINT)
                break
        else:
            pytest.fail("the FE build never started:\n" + "".join(seen))
        _, err = proc.communicate(timeout=300)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    assert err.strip().splitlines()[-1].startswith("ltca run: interrupted")
    assert not (tmp_path / "r.nc").exists()
    left = sorted(p.name for p in cache.rglob("*") if p.is_file()) if cache.exists() else []
    assert left == [], left
    monkeypatch.setenv(CACHE_ENV, str(cache))
    assert not coefficients_cached(resolve_case(None))


# ------------------------------------------------------- interrupted builds (issue 64)
_BUILD = """
import logging, signal, sys
from contact.catalogue import resolve_case
from contact.cli import _terminate
from contact.compliance.fe import FEOptions, influence_coefficients
logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
signal.signal(signal.SIGTERM, _terminate)   # as `ltca`: SIGTERM raises in the main thread
options = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                    rim_divisions=2, fillet_divisions=2, load_nu=33, load_nv=4)
try:
    influence_coefficients(resolve_case(None), "gear", options=options,
                           cache_dir=sys.argv[1], progress="lines")
except KeyboardInterrupt:
    print("interrupted", file=sys.stderr)
    sys.exit(143)
"""


def _build(cache, *, stop_at=None):
    """Build the coarse gear model (132 unit loads, 3 blocks of 64) into ``cache`` in a child
    Python; with ``stop_at``, send SIGTERM when a stderr line contains it (an event, not a
    time). Returns (exit code, stderr lines)."""
    import os
    import signal
    import subprocess
    import sys

    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[1])}
    proc = subprocess.Popen([sys.executable, "-c", _BUILD, str(cache)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seen = []
    try:
        for line in proc.stderr:
            seen.append(line)
            if stop_at is not None and stop_at in line:
                proc.send_signal(signal.SIGTERM)
                stop_at = None
        proc.wait(timeout=300)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return proc.returncode, seen


def test_sigterm_during_a_build_keeps_the_solved_blocks(tmp_path):
    """SIGTERM while the unit loads are solved (after the first block's event line): the
    build stops (rc 143 from the handler, no traceback) with no entry and the worker
    process that held the factor gone; the blocks solved so far are kept as checksummed
    parts, and a rerun logs that it resumes from them, solves only the others, writes an
    entry equal to an uninterrupted build's to the bit (the same solves; the parts are
    read back from netCDF exactly) and removes the parts. ~25 s: three coarse builds."""
    import psutil

    cache = tmp_path / "cache"
    rc, err = _build(cache, stop_at="unit loads 0-64 of 132 solved")
    assert rc == 143, "".join(err)
    assert "Traceback" not in "".join(err) and err[-1].strip() == "interrupted"
    # the forked worker has the build's command line; none is left running
    assert not [p for p in psutil.process_iter(["cmdline"])
                if str(cache) in (p.info["cmdline"] or [])]
    parts = sorted(p.name for p in cache.glob("fe-*.part-*.nc"))
    assert parts and parts[0].endswith(".part-0000-0064.nc"), parts
    assert not [p for p in cache.glob("fe-*.nc") if ".part-" not in p.name]
    solved_before = 64 * len(parts)
    rc, err = _build(cache)
    assert rc == 0, "".join(err)
    text = "".join(err)
    assert f"resuming, {solved_before} of 132 already solved" in text
    assert "unit loads 0-64 of 132 solved" not in text  # read back, not solved again
    assert not list(cache.glob("fe-*.part-*.nc"))
    (entry,) = cache.glob("fe-*.nc")
    fresh = tmp_path / "fresh"
    assert _build(fresh)[0] == 0
    (ref,) = fresh.glob("fe-*.nc")
    with xr.open_dataset(entry) as a, xr.open_dataset(ref) as b:
        for name in ("compliance", "centreline_compliance", "fillet_stress"):
            np.testing.assert_array_equal(a[name].values, b[name].values)
        assert a.attrs[CHECKSUM_ATTR] == b.attrs[CHECKSUM_ATTR]
