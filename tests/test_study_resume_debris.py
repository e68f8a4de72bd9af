"""Resume that survives its own debris (issue 55, item 3).

A study's parts directory (``OUTPUT.parts/``, :class:`contact.study.store.ResultStore`)
may hold a chunk that cannot be trusted: truncated or empty (a full disk, a copy broken
off), not netCDF at all, another study's, or holding NaN where a finished result belongs.
Resuming such a study names the chunk in one warning, moves it to
``OUTPUT.parts/set-aside/`` (kept), computes its points again and ends with the result of
an uninterrupted run.

Cheap enough for CI: the friction study solves 4 smooth-film conditions on a 64-node grid
(≈ 0.1 s each, this process) per case; the sweep and the duty cycle run two and one
coarse analyses (8 rolls per cycle, 8 segments: about a second each) once, then one again.
"""

from __future__ import annotations

import dataclasses
import logging
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import contact.study.duty_cycle as duty_module
import contact.study.friction_study as fstudy
from contact.study import engine as study_engine
from contact.study.friction_study import run_friction_study
from contact.study.store import SET_ASIDE, ChunkSpec, ResultStore
from friction.study.design import TABLE_5_1, factorial_design
from friction.study.points import SolveSettings
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf, write_netcdf

SETTINGS = SolveSettings(nodes=64)
#: the chunk of point 1 of a study streamed one point per chunk
CHUNK_1 = "chunk-0000001-00001.nc"
STORE_LOGGER = "contact.study.store"


def _design() -> dict[str, np.ndarray]:
    """2 × 2 smooth-film conditions (λ > 10, as tests/test_friction_study.py)."""
    levels = {**{k: (v[0],) for k, v in TABLE_5_1.items()},
              "hertz_pressure": (500.0, 1000.0), "entraining_velocity": (5.0, 10.0),
              "slide_to_roll": (0.2,), "radius": (20.0,), "temperature": (25.0,),
              "roughness_1": (0.1,), "roughness_2": (0.15,)}
    return factorial_design(levels)


def _results(ds: xr.Dataset, timing: tuple[str, ...] = ("solve_time",)) -> xr.Dataset:
    """The dataset without its timing variables (attributes are not compared)."""
    return ds.drop_vars([v for v in timing if v in ds])


def _warnings(caplog) -> list[logging.LogRecord]:
    return [r for r in caplog.records
            if r.name == STORE_LOGGER and r.levelno >= logging.WARNING]


def _assert_one_plain_warning(caplog, chunk: str) -> str:
    """Exactly one warning, on one line, naming the chunk, without library text."""
    found = _warnings(caplog)
    assert len(found) == 1, [r.getMessage() for r in found]
    rec = found[0]
    msg = rec.getMessage()
    assert chunk in msg and "set aside" in msg
    assert "\n" not in msg and rec.exc_info is None
    for raw in ("Errno", "HDF", "NetCDF:", "Traceback", "KeyError"):
        assert raw not in msg, msg
    return msg


@pytest.fixture(scope="module")
def uninterrupted() -> xr.Dataset:
    """The friction study run in one go, in memory (the reference)."""
    return run_friction_study(_design(), SETTINGS, scheduler="synchronous")


# ------------------------------------------------------------------------ the debris
def _truncated(path):
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2])


def _empty(path):
    path.write_bytes(b"")


def _garbage(path):
    path.write_bytes(b"this is not a netCDF file, it was left by something else\n" * 50)


def _no_point(path):
    """A netCDF file of another kind: no ``point`` dimension."""
    write_netcdf(xr.Dataset({"lte_mean": (("bin",), np.array([1.0, 2.0]),
                                          {"units": "urad", "long_name": "x"})}), path)


def _other_study(path):
    """A chunk over ``point`` of another study's kind (a sweep's variables)."""
    ds = xr.Dataset(
        {"lte_mean": (("point", "torque"), np.array([[12.0]]),
                      {"units": "urad", "long_name": "mean loaded transmission error"}),
         "status": (("point",), np.array([0], np.int8), {"units": "1", "long_name": "s"}),
         "reason": (("point",), np.array([""], dtype=object), {"long_name": "why"})},
        coords={"point": ("point", np.array([1]), {"units": "1", "long_name": "index"})})
    write_netcdf(ds, path)


def _nan_mu(path):
    """The friction coefficient NaN at a point whose status says it converged."""
    ds = read_netcdf(path, tree=False)
    assert (ds["status"].values == 0).all()
    ds["friction_coefficient"] = ds["friction_coefficient"].copy(
        data=np.full(ds.sizes["point"], np.nan))
    write_netcdf(ds, path)


def _other_design(path):
    """This study's kind and variables, but another design's point (other inputs)."""
    ds = read_netcdf(path, tree=False)
    ds = ds.assign_coords(hertz_pressure=ds["hertz_pressure"] + 100.0)
    write_netcdf(ds, path)


DEBRIS = {"truncated": _truncated, "empty": _empty, "garbage": _garbage,
          "no_point": _no_point, "other_study": _other_study, "nan_mu": _nan_mu,
          "other_design": _other_design}


@pytest.mark.parametrize("kind", list(DEBRIS))
def test_friction_study_resumes_past_a_bad_chunk(kind, tmp_path, monkeypatch, caplog,
                                                 uninterrupted):
    """Killed while its third point runs (chunks of points 0 and 1 on disk), the chunk
    of point 1 then damaged: the study started again names it in one warning, sets it
    aside (kept), solves points 1, 2, 3 and equals an uninterrupted run."""
    design = _design()
    out = tmp_path / "fs.nc"
    calls: list[int] = []
    real = fstudy.solve_design_point

    def counting(settings, index, point):
        calls.append(index)
        if len(calls) == 3 and not getattr(counting, "resumed", False):
            raise KeyboardInterrupt  # the kill
        return real(settings, index, point)

    monkeypatch.setattr(fstudy, "solve_design_point", counting)
    with pytest.raises(KeyboardInterrupt):
        run_friction_study(design, SETTINGS, output=out, scheduler="synchronous",
                           chunk_size=1)
    parts = ResultStore.parts_dir(out)
    chunk = parts / CHUNK_1
    assert chunk.is_file() and len(list(parts.glob("chunk-*.nc"))) == 2
    DEBRIS[kind](chunk)
    debris = chunk.read_bytes()

    calls.clear()
    counting.resumed = True
    caplog.clear()
    with caplog.at_level(logging.INFO):
        resumed = run_friction_study(design, SETTINGS, output=out, scheduler="synchronous",
                                     chunk_size=1)
    assert sorted(calls) == [1, 2, 3]
    assert resumed.attrs["points_resumed"] == 1
    msg = _assert_one_plain_warning(caplog, CHUNK_1)
    aside = parts / SET_ASIDE / CHUNK_1
    assert f"set aside as {Path(SET_ASIDE) / CHUNK_1}" in msg
    assert aside.read_bytes() == debris  # moved, not deleted or rewritten
    xr.testing.assert_equal(_results(resumed), _results(uninterrupted))
    assert np.isfinite(resumed["friction_coefficient"].values).all()

    # the final file's parts go, the debris stays (and is never read again)
    write_netcdf(resumed, out)
    ResultStore.remove_parts(out)
    assert aside.read_bytes() == debris
    assert [p.name for p in parts.iterdir()] == [SET_ASIDE]


def test_sweep_resumes_past_a_truncated_chunk(tmp_path, monkeypatch, caplog):
    """run_points (two coarse points, one chunk each): a truncated chunk of point 1 is
    named, set aside and point 1 analysed again; the result equals the first run (1e-12:
    the same analysis again, the tooth-model memo's sums aside)."""
    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study import run_points, study_inputs
    from geometry.pair.assembly import Misalignment

    case = dataclasses.replace(resolve_case(None), misalignment=Misalignment())
    shared = study_inputs(case, 250.0, options=LTCAOptions(rolls_per_cycle=8, segments=8))
    points = [{"delta_E": e} for e in (-0.05, 0.05)]
    out = tmp_path / "map.nc"
    first = run_points(shared, points, output=out, scheduler="synchronous", chunk_size=1)
    chunk = ResultStore.parts_dir(out) / CHUNK_1
    _truncated(chunk)
    debris = chunk.read_bytes()

    calls: list[int] = []
    real = study_engine.analyse_point

    def counting(shared_, index, point):
        calls.append(index)
        return real(shared_, index, point)

    monkeypatch.setattr(study_engine, "analyse_point", counting)
    caplog.clear()
    resumed = run_points(shared, points, output=out, scheduler="synchronous", chunk_size=1)
    assert calls == [1]
    assert resumed.attrs["points_resumed"] == 1
    _assert_one_plain_warning(caplog, CHUNK_1)
    assert (ResultStore.parts_dir(out) / SET_ASIDE / CHUNK_1).read_bytes() == debris
    xr.testing.assert_allclose(resumed, first, rtol=1e-12, atol=1e-12)


def test_duty_cycle_resumes_past_a_nan_chunk(tmp_path, monkeypatch, caplog):
    """A one-bin duty cycle streamed to disk, its chunk then holding NaN in the pressure
    envelope of a bin whose status is 0: started again, the chunk is named, set aside and
    the bin analysed again; damage and life equal the first run's."""
    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study.duty_cycle import run_duty_cycle
    from contact.study.duty_cycle_inputs import DutyCycle
    from contact.study.run import StudyRun

    case = resolve_case(None)
    duty = DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e7])
    out = tmp_path / "d.nc"
    run = StudyRun(options=LTCAOptions(rolls_per_cycle=8, segments=8),
                   scheduler="synchronous", output=out)
    first = run_duty_cycle(case, duty, run, root_stress=False)
    chunk = ResultStore.parts_dir(out) / "chunk-0000000-00001.nc"
    ds = read_netcdf(chunk, tree=False)
    assert int(ds["status"].values[0]) == 0
    env = ds["pressure_envelope"].values.copy()
    env[0, 0, 0] = np.nan
    ds["pressure_envelope"] = ds["pressure_envelope"].copy(data=env)
    write_netcdf(ds, chunk)

    calls: list[int] = []
    real = duty_module.analyse_bin

    def counting(shared, index):
        calls.append(index)
        return real(shared, index)

    monkeypatch.setattr(duty_module, "analyse_bin", counting)
    caplog.clear()
    again = run_duty_cycle(case, duty, run, root_stress=False)
    assert calls == [0]
    assert again.attrs["bins_resumed"] == 0
    msg = _assert_one_plain_warning(caplog, "chunk-0000000-00001.nc")
    assert "pressure_envelope" in msg
    assert (ResultStore.parts_dir(out) / SET_ASIDE / "chunk-0000000-00001.nc").is_file()
    xr.testing.assert_allclose(again, first, rtol=1e-12, atol=1e-12)


# ------------------------------------------------------------------------ the store alone
def _chunk(points, **variables) -> xr.Dataset:
    idx = np.asarray(points)
    data = {k: (("point",), np.asarray(v, float), {"units": "1", "long_name": k})
            for k, v in variables.items()}
    data["status"] = (("point",), np.zeros(idx.size, np.int8), {"units": "1",
                                                               "long_name": "status"})
    return xr.Dataset(data, coords={"point": ("point", idx, {"units": "1",
                                                             "long_name": "index"})})


def test_default_store_keeps_good_chunks_and_sets_aside_broken_ones(tmp_path, caplog):
    """Without a ChunkSpec (existing callers) every readable chunk with integer point
    indices is trusted, whatever its variables; an unreadable one, one without points,
    float indices or points repeated from an earlier chunk are set aside, one warning
    each; a second set-aside chunk of the same name does not overwrite the first."""
    store = ResultStore(tmp_path / "s.nc", {"fingerprint": "x"}, chunk_size=2)
    store.add(_chunk([0], mu=[0.1]))
    store.add(_chunk([1], mu=[np.nan]))  # NaN: no spec, nothing says it is wrong
    store.flush()
    parts = store.parts
    write_netcdf(_chunk([1], mu=[0.2]), parts / "chunk-0000001-00001.nc")  # repeats 1
    write_netcdf(_chunk([2.0], mu=[0.3]), parts / "chunk-0000002-00001.nc")  # float index
    (parts / "chunk-0000003-00001.nc").write_bytes(b"\x89HDF\r\n\x1a\n truncated")
    caplog.clear()
    assert store.done() == {0, 1}
    reasons = sorted(r.getMessage() for r in _warnings(caplog))
    assert len(reasons) == 3
    assert "repeats point(s) 1 already in chunk-0000000-00002.nc" in reasons[0]
    assert "not whole numbers" in reasons[1]
    assert "not a readable netCDF file" in reasons[2]
    caplog.clear()
    np.testing.assert_array_equal(store.combined()["point"].values, [0, 1])
    assert _warnings(caplog) == []  # nothing left to set aside
    # the same name set aside again is kept beside the first
    (parts / "chunk-0000003-00001.nc").write_bytes(b"")
    store.done()
    aside = sorted(p.name for p in (parts / SET_ASIDE).iterdir())
    assert aside == ["chunk-0000001-00001.nc", "chunk-0000002-00001.nc",
                     "chunk-0000003-00001-1.nc", "chunk-0000003-00001.nc"]
    assert "is empty" in _warnings(caplog)[-1].getMessage()


@pytest.mark.parametrize(("chunk", "reason"), [
    (_chunk([5], mu=[0.1], h=[1.0]), "beyond this study's 4 points"),
    (_chunk([1], h=[1.0]), "lacks the variable(s) mu"),
    (_chunk([1], mu=[0.1], h=[1.0], lte_mean=[3.0]), "holds variable(s) lte_mean that"),
    (_chunk([1, 2], mu=[0.1, np.inf], h=[1.0, 1.0]), "holds NaN (or infinity) in mu at "
                                                     "point(s) 2, whose status is 0"),
    (_chunk([1], mu=[0.1], h=[1.0]).assign_coords(x=("point", [9.0])),
     "other values of the input x"),
    (_chunk([3], mu=[0.1], h=[-1.0]), "has a negative film"),
])
def test_chunk_spec_reasons(chunk, reason):
    """Each check of a ChunkSpec gives its reason in plain words; a failed point's NaN
    (status not 0) and an optional variable are accepted."""
    spec = ChunkSpec(points=4, variables=("mu", "h", "status"), optional=("extra",),
                     finite=("mu",), coords={"x": [0.0, 1.0, 2.0, 3.0]},
                     check=lambda ds: ("has a negative film" if (ds["h"] < 0).any()
                                       else None))
    if "x" not in chunk.coords:
        chunk = chunk.assign_coords(x=("point", chunk["point"].values.astype(float)))
    assert reason in spec.problem(chunk)
    ok = _chunk([1, 2], mu=[0.1, np.nan], h=[1.0, 1.0], extra=[0.0, 0.0])
    ok["status"] = ok["status"].copy(data=np.array([0, 1], np.int8))
    ok = ok.assign_coords(x=("point", [1.0, 2.0]))
    assert spec.problem(ok) is None


def test_bad_spec_refused():
    with pytest.raises(InputError, match=r"^coords: 'x' must hold one value per point"):
        ChunkSpec(points=3, coords={"x": [1.0, 2.0]})
    with pytest.raises(InputError, match=r"^spec: must be a contact.study.store.ChunkSpec"):
        ResultStore("/nonexistent/s.nc", {}, spec={"variables": ["x"]})
