"""Both flanks of a member from one FE build (issue 75 item 1): ``influence_coefficients(...,
other_flank=True)`` caches the other flank's coefficients from the same solid and
factorisation. The reference is a build of that flank of its own: the same solid, the
same stiffness and the same loads, so the coefficients must agree to round-off (the
factorisation is repeated on the same matrix with the same ordering)."""

import numpy as np
import xarray as xr

from contact.catalogue import bundled_case_path
from contact.compliance.fe import (
    CACHE_ENV,
    FEOptions,
    cache_key,
    cache_path,
    influence_coefficients,
)
from contact.compliance.fe.options import member_flank
from geometry.case import load_case

#: the coarse model of the CI tests (tests/test_fe_tooth.py)
COARSE = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                   rim_divisions=2, fillet_divisions=2, load_nu=5, load_nv=4)


def _case():
    """The default case (kolivand2009_fm_11x41_reference)."""
    return load_case(bundled_case_path())


def test_the_other_flank_from_the_same_build_equals_a_build_of_its_own(tmp_path):
    """The gear's drive build with ``other_flank`` leaves its coast entry in the cache
    (its own key and checksum, read back by ``read_cache_entry``), equal to a separate
    coast build in every data variable within 1e-10 of the variable's largest magnitude
    (the same matrix and loads: what a repeated factorisation may change is round-off)
    and with the same coordinates; a second call finds both cached and builds nothing.
    ~10 s of CPU (three coarse builds' worth)."""
    case = _case()
    both, alone = tmp_path / "both", tmp_path / "alone"
    drive = influence_coefficients(case, "gear", "drive", COARSE, cache_dir=both,
                                   progress=False, other_flank=True)
    coast_name = member_flank(case, "gear", "coast")
    path = cache_path(cache_key(case.member("gear"), coast_name, COARSE), both)
    assert path.exists() and sorted(both.glob("*.part-*")) == []
    shared = influence_coefficients(case, "gear", "coast", COARSE, cache_dir=both,
                                    progress=False)
    assert shared.attrs["flank"] == coast_name != drive.attrs["flank"]
    own = influence_coefficients(case, "gear", "coast", COARSE, cache_dir=alone,
                                 progress=False)
    assert shared.attrs["cache_key"] == own.attrs["cache_key"]
    for name, var in own.data_vars.items():
        a, b = np.asarray(shared[name].values), np.asarray(var.values)
        assert a.shape == b.shape, name
        if a.dtype.kind == "f":
            scale = max(float(np.abs(b).max()), 1e-300)
            assert float(np.abs(a - b).max()) <= 1e-10 * scale, name
        else:
            assert np.array_equal(a, b), name
    for name in own.coords:
        xr.testing.assert_allclose(shared[name], own[name], rtol=1e-12)
    stamps = {p: p.stat().st_mtime_ns for p in both.glob("fe-*.nc")}
    influence_coefficients(case, "gear", "drive", COARSE, cache_dir=both, progress=False,
                           other_flank=True)
    assert {p: p.stat().st_mtime_ns for p in both.glob("fe-*.nc")} == stamps


def test_without_the_cache_the_other_flank_is_not_built(tmp_path, monkeypatch):
    """``other_flank`` only fills the cache: with ``cache=False`` nothing is written and
    the model is built once. A coarse build's worth of CPU."""
    import contact.compliance.fe.influence as influence

    calls = []
    monkeypatch.setattr(influence, "_other_flank_entry",
                        lambda *a, **k: calls.append(a))
    influence_coefficients(_case(), "gear", "drive", COARSE, cache=False, cache_dir=tmp_path,
                           progress=False, other_flank=True)
    assert calls == [] and list(tmp_path.iterdir()) == []


def test_the_development_builds_both_flanks_of_each_member_and_survives_a_failure(
        monkeypatch, caplog, tmp_path):
    """``both_flanks_built`` (called by the development before its drive check where the
    coast flank is checked too) asks each member's default model for its drive flank with
    ``other_flank``, and a member whose model fails is logged, not raised: its checks then
    build their own and say why (as before). Milliseconds: the builds are stubbed."""
    import logging

    import contact.compliance.fe as fe
    from contact.optimize.development_root import both_flanks_built

    calls = []

    def fake(case, member, flank="drive", options=None, **kw):
        calls.append((member, flank, options, kw.get("other_flank")))
        if member == "pinion":
            raise RuntimeError("mapped fillet inverted")

    monkeypatch.setattr(fe, "influence_coefficients", fake)
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))  # nothing cached: both built
    said: list[str] = []
    with caplog.at_level(logging.INFO, logger="contact.optimize.development_root"):
        both_flanks_built(_case(), say=said.append)
    # the case's FE level (no [root_stress] table: the default model)
    assert calls == [("pinion", "drive", FEOptions(), True),
                     ("gear", "drive", FEOptions(), True)]
    assert "pinion's FE models of both flanks not built: mapped fillet inverted" in caplog.text
    # each cold build is announced before it starts (issue 71, unseen (12): `ltca
    # synthesize` was silent for up to 138 s of wall time there on a loaded machine)
    assert [line.split(" FE models")[0] for line in said] == [
        "development: building the pinion's", "development: building the gear's"]


def test_the_development_builds_the_level_its_case_names(monkeypatch, tmp_path):
    """A case that names an FE level (``[root_stress] fe_level``, as ``ltca synthesize``
    writes ``coarse10``): ``both_flanks_built`` builds that level's models, the ones the
    root-stress checks and ``ltca run`` of the case read (issue 75). Stubbed: milliseconds."""
    import contact.compliance.fe as fe
    from contact.compliance.fe.options import with_fe_level
    from contact.optimize.development_root import both_flanks_built

    calls = []
    monkeypatch.setattr(fe, "influence_coefficients",
                        lambda case, member, flank="drive", options=None, **kw:
                        calls.append((member, options)))
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    both_flanks_built(with_fe_level(_case(), "coarse10"))
    coarse = FEOptions.at_level("coarse10")
    assert calls == [("pinion", coarse), ("gear", coarse)]


def test_the_development_reads_a_cached_drive_model_once_for_its_checks(monkeypatch,
                                                                        tmp_path):
    """Where a member's drive entry is cached, ``both_flanks_built`` reads it through the
    process's memo that the root-stress checks read it from
    (``contact_compliance.shared_coefficients``; issue 75: read there and again in the
    check before), and builds nothing. The reads are stubbed: milliseconds."""
    import contact.compliance.fe as fe
    import contact.compliance.fe.contact_compliance as cc
    from contact.optimize.development_root import both_flanks_built

    case = _case()
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    key = cache_key(case.member("gear"), member_flank(case, "gear", "drive"), FEOptions())
    cache_path(key).write_bytes(b"")  # the gear's entry exists (its content not read)
    built, read = [], []
    monkeypatch.setattr(fe, "influence_coefficients",
                        lambda case, member, flank="drive", *a, **kw: built.append(member))
    monkeypatch.setattr(cc, "shared_coefficients",
                        lambda case, member, flank="drive", *a, **kw: read.append(member))
    said: list[str] = []
    both_flanks_built(case, say=said.append)
    assert built == ["pinion"] and read == ["gear"]
    assert len(said) == 1 and "building the pinion's FE models" in said[0]  # not the gear


def test_a_failing_other_flank_leaves_this_flanks_result_and_cache(tmp_path, monkeypatch,
                                                                     caplog):
    """Where the other flank's build fails, the asked flank's coefficients are returned and
    cached as without ``other_flank`` and the failure is a warning naming the member; no
    entry of the other flank is left. A coarse build's worth of CPU."""
    import logging

    import contact.compliance.fe.influence as influence

    def broken(model):
        raise influence.LTCAError("the other flank's load grid reaches beyond its flank")

    monkeypatch.setattr(influence, "_other_flank_model", broken)
    case = _case()
    with caplog.at_level(logging.WARNING, logger="contact.compliance.fe.influence"):
        ds = influence_coefficients(case, "gear", "drive", COARSE, cache_dir=tmp_path,
                                    progress=False, other_flank=True)
    assert ds.attrs["flank"] == member_flank(case, "gear", "drive")
    assert [p.name for p in tmp_path.glob("fe-*")] == [
        cache_path(ds.attrs["cache_key"], tmp_path).name]
    assert "gear: the other flank's influence coefficients not built" in caplog.text
