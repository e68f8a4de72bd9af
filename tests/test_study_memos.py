"""What a study computes once per worker process, and the workers' environment (issue 32).

* The pinion's points of the ease-off's forward map (861 solutions of the equation of
  meshing on the extended pinion grid) and the real gear flank on the ease-off's grid do
  not depend on the misalignment: they are memoised per process under the key of their
  flank alone (``flank_key``: a pinion-only change keeps the gear's nodes, issue 75), and
  an ease-off computed with the memos equals, bit for bit, one computed without them.
* The pipeline's ``/geometry`` group takes the gear flanks from that memo (one solve per
  analysis instead of two) and equals the geometry layer's own datasets.
* A LocalCluster the study engine starts runs its workers without distributed's
  ``MALLOC_TRIM_THRESHOLD_`` (a quarter of a point's CPU time in page faults).

Cheap enough for CI: four ease-offs of the long-bearing case (about 0.1 s each on a quiet
core), eight flanks, and a look at Dask's configuration (no cluster is started).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.study.engine import WORKER_ENVIRON_UNSET, worker_environment
from contact.utca import ease_off
from contact.utca.conjugate_map import clear_memos, memo_info
from geometry.pair.assembly import Misalignment


@pytest.fixture(scope="module")
def case():
    return resolve_case("kolivand2009_fm_11x41")


def test_teeth_alone_are_solved_once_per_process_and_change_nothing(case):
    clear_memos()
    a = ease_off(case, misalignment=Misalignment(delta_E=0.05))
    b = ease_off(case, misalignment=Misalignment(delta_E=-0.05, delta_P=0.03))
    for name, info in memo_info().items():
        assert (info.hits, info.misses) == (1, 1), name
    # the same case with other deviations or misalignment has the same key
    assert (dataclasses.replace(case, misalignment=Misalignment(delta_P=0.1)).teeth_key()
            == case.teeth_key())
    # and with another operating point: run_analysis writes the torques run into the case,
    # and a torque series is of the same teeth
    assert (dataclasses.replace(case, operating=dataclasses.replace(
        case.operating, torque=(123.0,), pinion_speed=999.0)).teeth_key() == case.teeth_key())
    clear_memos()
    fresh = ease_off(case, misalignment=Misalignment(delta_E=-0.05, delta_P=0.03))
    for name in ("ease_off_angle", "roll_angle", "gap_curvature", "pinion_u", "pinion_v",
                 "placement_error"):
        np.testing.assert_array_equal(getattr(b, name), getattr(fresh, name), err_msg=name)
    assert not np.allclose(np.nan_to_num(a.ease_off_angle), np.nan_to_num(b.ease_off_angle))


def test_replaced_case_carries_the_teeth_key_only_where_the_teeth_stay(case):
    """Case.replaced (a study's points, the case as run): a new misalignment, operating
    point or deviations carry the case's teeth key, the same object and equal to the key
    the new case would make from its repr; a change of the teeth makes its own."""
    mis = case.replaced(misalignment=Misalignment(delta_E=0.07, delta_G=-0.02))
    run = mis.replaced(operating=dataclasses.replace(case.operating, torque=(321.0,)))
    assert mis.misalignment == Misalignment(delta_E=0.07, delta_G=-0.02)
    assert mis.teeth_key() is case.teeth_key() and run.teeth_key() is case.teeth_key()
    fresh = dataclasses.replace(run)  # a new object: its key made from its repr
    assert fresh.teeth_key() is not case.teeth_key()
    assert fresh.teeth_key() == run.teeth_key()
    assert fresh.teeth_key().text == run.teeth_key().text
    other = case.replaced(name="other teeth")
    assert other.teeth_key() != case.teeth_key()


def test_an_ease_off_is_computed_once_per_teeth_and_misalignment(case):
    """The ease-off of the same teeth, misalignment and flank (a torque series in one
    process, an analysis repeated) is computed once: the same object, its arrays
    read-only, equal bit for bit (NaN where NaN) to a fresh computation; the case's own
    misalignment and its deviations are not part of the key where the misalignment is
    given."""
    from contact.utca.easeoff import _ease_off

    clear_memos()
    mis = Misalignment(delta_E=0.05, delta_P=-0.02)
    a = ease_off(case, misalignment=mis)
    b = ease_off(dataclasses.replace(case, misalignment=Misalignment(delta_G=0.1)),
                 misalignment=Misalignment(delta_E=0.05, delta_P=-0.02))
    assert b is a
    assert ease_off(case, misalignment=Misalignment(delta_E=0.05, delta_P=0.02)) is not a
    fresh = _ease_off(case, None, mis, None, 0.0, 0.0)
    for name, value in a._asdict().items():
        if isinstance(value, np.ndarray):
            assert not value.flags.writeable, name
            np.testing.assert_array_equal(value, getattr(fresh, name), err_msg=name)
        elif name != "kinematics":
            assert value == getattr(fresh, name), name
    np.testing.assert_array_equal(a.kinematics.pinion_place, fresh.kinematics.pinion_place)
    np.testing.assert_array_equal(a.kinematics.gear_place, fresh.kinematics.gear_place)


def test_the_unloaded_cycle_of_one_ease_off_is_computed_once(case):
    """The UTCA of the same ease-off object (a torque series shares the memoised ease-off)
    computes its unloaded cycle once; its datasets equal those of a fresh computation
    exactly (xarray's identity: values, attributes, coordinates)."""
    import xarray as xr

    from contact.utca import unloaded_tca
    from contact.utca.datasets import _memo_cycle

    clear_memos()
    eo = ease_off(case)
    first = unloaded_tca(case, easeoff=eo)
    second = unloaded_tca(case, easeoff=eo)
    info = _memo_cycle.cache_info()
    assert (info.hits, info.misses) == (1, 1)
    clear_memos()
    fresh = unloaded_tca(case, easeoff=ease_off(case))
    for a, b, c in zip(first, second, fresh, strict=True):
        xr.testing.assert_identical(a, c)
        xr.testing.assert_identical(b, c)
def test_the_ease_off_fields_are_built_once_per_ease_off(case):
    """The unloaded cycle and the LTCA's segment geometry of one analysis read the fields
    of one ease-off object (:func:`contact.utca.fields.fields_of`): one build, the same
    object to both; another ease-off object, another kernel choice or emptied memos
    give their own. The fields hold no result of their own (splines and lazily computed
    lattices of the same arithmetic), so sharing them changes no number: the datasets
    equal those of fresh fields (tests/test_study_memos.py's cycle test, the golden
    files)."""
    from contact.utca.fields import EaseOffFields, _memo_fields, fields_of

    clear_memos()
    eo = ease_off(case)
    f = fields_of(eo)
    assert isinstance(f, EaseOffFields) and f.eo is eo
    assert fields_of(eo) is f
    assert fields_of(eo, "numpy") is not f or f.kernels is None
    from contact.utca.easeoff import clear_ease_off_memo

    clear_ease_off_memo()
    other = ease_off(case)  # an equal ease-off, another object
    assert other is not eo and fields_of(other) is not f
    clear_memos()
    assert _memo_fields.cache_info().currsize == 0
    assert fields_of(eo) is not f


def test_operating_point_and_rating_are_not_teeth(case):
    """The development's checks analyse one case at several design torques, each written
    into its ``[operating]`` and ``[rating]`` tables (issue 71): neither changes a tooth,
    so the key is the same and the memos compute from the case without them (another
    table, or another tooth, is still another key)."""
    from types import MappingProxyType

    rated = dataclasses.replace(
        case, operating=dataclasses.replace(case.operating, torque=(12.5, 99.0)),
        extra=MappingProxyType({**case.extra, "rating": {"design_torque": 99.0}}))
    assert rated.teeth_key() == case.teeth_key()
    assert rated.teeth_key().case.operating == dataclasses.replace(case).teeth_key().case.operating
    assert "rating" not in rated.teeth_key().case.extra
    other = dataclasses.replace(case, extra=MappingProxyType({**case.extra, "fe": {"x": 1}}))
    assert other.teeth_key() != case.teeth_key()
    clear_memos()
    a = ease_off(case)
    b = ease_off(rated)
    assert b is a  # the ease-off memo (keyed by the teeth) hit
    for name in ("ease_off_angle", "roll_angle", "gap_curvature", "placement_error"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_a_case_changed_in_code_is_other_teeth(case):
    """A field the case's TOML does not state (the indexing ratio, derived from the blade
    groups and the teeth when a file is read) changed in code gives another key: the memos
    compute from the case itself, not from its TOML read back (which would be the original
    teeth; the face-hobbing conjugacy test's negative controls failed so)."""
    flank = case.pinion.concave
    other = dataclasses.replace(case, pinion=dataclasses.replace(case.pinion, concave=(
        dataclasses.replace(flank, machine=dataclasses.replace(
            flank.machine, indexing_ratio=-0.5)))))
    assert other.teeth_toml() == case.teeth_toml()  # what the TOML key could not tell
    assert other.teeth_key() != case.teeth_key()
    assert other.teeth_key().case is not case


def test_local_cluster_workers_start_without_malloc_trim():
    """The Nanny's pre-spawn environment (what distributed puts into a new worker's
    environment) has no MALLOC_TRIM_THRESHOLD_ while the engine starts its cluster, and the
    configuration is restored afterwards."""
    import dask
    pytest.importorskip("distributed")

    key = "distributed.nanny.pre-spawn-environ"
    before = dict(dask.config.get(key))
    with worker_environment():
        env = {k: v for k, v in dask.config.get(key).items() if v is not None}
        for name in WORKER_ENVIRON_UNSET:
            assert name not in env
        assert env.get("OMP_NUM_THREADS") in (1, "1")  # the rest as distributed sets it
    assert dict(dask.config.get(key)) == before


@pytest.mark.parametrize("ready", [True, False])
def test_local_cluster_workers_run_the_kernels_this_process_runs(monkeypatch, ready):
    """A study's workers get this process's resolved kernels choice (``auto`` resolved by
    numba's cache as this process saw it), so that a point computed on a worker equals the
    same analysis in this process even when the cache fills in between (the NumPy and
    numba paths agree to ~1e-11 only; test_study.py compares at 1e-12)."""
    import dask
    pytest.importorskip("distributed")

    from geometry.core import kernels

    monkeypatch.setenv("LTCA_KERNELS", "auto")
    monkeypatch.setattr(kernels, "cache_ready", lambda name: ready)
    monkeypatch.setattr(kernels, "_AUTO_CHOICE", {})  # this process's first choice
    key = "distributed.nanny.pre-spawn-environ"
    with worker_environment():
        assert dask.config.get(key)["LTCA_KERNELS"] == ("numba" if ready else "numpy")
    monkeypatch.setenv("LTCA_KERNELS", "numpy")
    with worker_environment():
        assert dask.config.get(key)["LTCA_KERNELS"] == "numpy"


def test_geometry_group_takes_the_flanks_of_the_memo_and_changes_nothing(case):
    """The pipeline's /geometry group (contact.pipeline.geometry_datasets) takes the four
    flanks from the per-process memo the ease-off reads, so an analysis solves the gear's
    once and a second analysis of the same teeth none: its datasets equal, bit for bit,
    those of geometry.machine.flank.geometry_datasets (solved afresh), and the ease-off's
    gear nodes are then a memo hit. Cheap: eight flanks of 41 × 21 nodes (about 0.1 s
    each) and one ease-off."""
    import xarray as xr

    from contact.pipeline import geometry_datasets
    from geometry.machine.flank import geometry_datasets as fresh_datasets

    clear_memos()
    ours = geometry_datasets(case)
    fresh = fresh_datasets(case)
    assert ours.keys() == fresh.keys()
    for key in fresh:
        xr.testing.assert_identical(ours[key], fresh[key])
    assert memo_info()["flank_nodes"].misses == 4  # the four flanks, once each
    ease_off(case)
    assert memo_info()["flank_nodes"].hits == 1
    again = geometry_datasets(case)
    assert memo_info()["flank_nodes"].misses == 4
    for key in fresh:
        xr.testing.assert_identical(again[key], fresh[key])


def _with_setting(case, member: str, flank: str, **changed):
    """``case`` with ``member``'s ``flank`` machine settings changed (``changed``)."""
    mem = case.member(member)
    tool = mem.flank(flank)
    tool = dataclasses.replace(tool, machine=dataclasses.replace(tool.machine, **changed))
    return dataclasses.replace(case, **{member: dataclasses.replace(mem, **{flank: tool})})


def test_a_flank_is_memoised_by_itself_and_a_changed_setting_is_solved_afresh(case):
    """The flank memos (issue 75) are keyed by the flank alone (``flank_key``: the member's
    hand and blank, the flank's blade and machine settings, exactly): a development's
    trial that changes the pinion keeps the gear's nodes, and a changed gear keeps the
    pinion's forward-map points. Identities, bit for bit (NaN where NaN): what the memo
    serves equals a fresh solve of the flank; an ease-off computed with the memos equals
    one computed after clearing them; a changed setting of the flank itself is a new key,
    solved afresh (and moves the flank, so the test sees a stale entry). The change is
    small (the pinion's radial setting +0.01 mm, the gear's cradle angle +1e-4 rad): a
    trial's step."""
    from contact.utca.conjugate_map import flank_key, flank_nodes
    from contact.utca.easeoff import _grid_options, working_flanks
    from geometry.machine.flank import flank_surface

    pf, gf = working_flanks(case, None)  # the drive flanks
    grid = _grid_options(None)
    pinion_moved = _with_setting(case, "pinion", pf, radial_setting=(
        case.pinion.flank(pf).machine.radial_setting + 0.01))
    gear_moved = _with_setting(case, "gear", gf, cradle_angle=(
        case.gear.flank(gf).machine.cradle_angle + 1e-4))
    assert flank_key(pinion_moved, "gear", gf) == flank_key(case, "gear", gf)
    assert flank_key(pinion_moved, "pinion", pf) != flank_key(case, "pinion", pf)
    assert flank_key(gear_moved, "gear", gf) != flank_key(case, "gear", gf)
    # the other flank of the same member is a key of its own
    assert flank_key(pinion_moved, "pinion", "convex") == flank_key(case, "pinion", "convex")

    def same(a, b):
        for name in ("position", "normal", "kappa1", "kappa2", "s", "theta", "q", "section",
                     "reason"):
            np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)

    clear_memos()
    flank_nodes(case, "gear", gf, grid)
    served = flank_nodes(pinion_moved, "gear", gf, grid)  # a pinion-only change
    assert memo_info()["flank_nodes"][:2] == (1, 1)
    same(served, flank_surface(pinion_moved, "gear", gf, **grid))
    moved = flank_nodes(gear_moved, "gear", gf, grid)  # the gear's own setting changed
    assert memo_info()["flank_nodes"][:2] == (1, 2)
    same(moved, flank_surface(gear_moved, "gear", gf, **grid))
    assert not np.array_equal(np.nan_to_num(moved.position), np.nan_to_num(served.position))

    # the ease-offs: the gear nodes kept across a pinion change, the forward-map points
    # across a gear change, each equal to a computation from empty memos
    clear_memos()
    ease_off(case)
    eo_pinion = ease_off(pinion_moved)
    eo_gear = ease_off(gear_moved)
    info = memo_info()
    assert info["flank_nodes"][:2] == (1, 2)  # the gear's: pinion_moved's a hit
    assert info["forward_points"][:2] == (1, 2)  # the pinion's: gear_moved's a hit
    for moved_case, eo in ((pinion_moved, eo_pinion), (gear_moved, eo_gear)):
        clear_memos()
        fresh = ease_off(moved_case)
        for name in ("ease_off_angle", "roll_angle", "gap_curvature", "pinion_u", "pinion_v",
                     "placement_error", "gear_position", "gear_normal"):
            np.testing.assert_array_equal(getattr(eo, name), getattr(fresh, name),
                                          err_msg=name)
