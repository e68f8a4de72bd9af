"""Root stress where the FE cache cannot be written (issue 72 item 2): the coefficients are
built, used from memory and kept for the process's later analyses; the run says the cache
was not written, and the verdict still checks the root stress.

The unwritable cache is a directory below a regular file (``HYPOID_LTCA_CACHE``, the
variable the cache reads): its creation fails with ENOTDIR for any user, root included
(a read-only mount or a directory without write permission would not stop root). The
builds of the first test are stand-ins (as tests/test_fe_cache.py's); the second builds a
coarse FE model of the default pair for real (the FE options of tests/test_fe_cache.py's
interrupted build, ~10 s per member).
"""

from __future__ import annotations

import logging

import numpy as np
import pytest
import xarray as xr

from contact import AnalysisChain, LTCAOptions, run_analysis, verdict
from contact.catalogue import resolve_case
from contact.compliance.fe import FEOptions
from contact.compliance.fe.cache import CACHE_ENV, NOT_WRITTEN_ATTR
from contact.ltca.root_stress import CACHE_NOTE_ATTR, root_stress_notes


@pytest.fixture
def unwritable(tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    cache = blocker / "cache"
    monkeypatch.setenv(CACHE_ENV, str(cache))
    return cache


def test_coefficients_built_where_the_cache_cannot_be_written_are_used_from_memory(
        unwritable, monkeypatch, caplog):
    from types import SimpleNamespace

    from contact.compliance.fe.contact_compliance import _UNWRITTEN, shared_coefficients

    builds = []

    def model(*args, **kwargs):
        builds.append(1)
        return SimpleNamespace(factor=SimpleNamespace(close=lambda: None))

    def dataset(model, case, *, progress=True, key="", checkpoint=None):
        # the build's checkpoints cannot be kept either: best effort, no error
        checkpoint.write(0, 2, {"compliance": np.ones((3, 2))})
        assert checkpoint.failed is not None
        return xr.Dataset({"compliance": (("u",), np.ones(3))}, attrs={"cache_key": key})

    monkeypatch.setattr("contact.compliance.fe.influence.build_influence_model", model)
    monkeypatch.setattr("contact.compliance.fe.influence.influence_dataset", dataset)
    _UNWRITTEN.clear()
    caplog.set_level(logging.WARNING, logger="contact.compliance.fe.cache")
    case = resolve_case(None)
    first = shared_coefficients(case, "gear")
    assert builds == [1]
    assert first.attrs[NOT_WRITTEN_ATTR].startswith(f"could not write '{unwritable}")
    assert "used from memory, the cache was not written" in caplog.text
    assert shared_coefficients(case, "gear") is first  # not built again in this process
    assert builds == [1]
    assert not unwritable.exists()
    _UNWRITTEN.clear()


def test_the_note_reaches_the_file_and_ltca_run(monkeypatch):
    """Coefficients marked as not written (the session cache's, marked) give the root
    stress as before, with one note per member in ``root_stress_max`` that ``ltca run``
    prints (:func:`contact.ltca.root_stress.root_stress_notes`)."""
    import contact.ltca.root_stress as rs_module

    real = rs_module.pair_coefficients

    def marked(*args, **kwargs):
        return {m: ds.assign_attrs({NOT_WRITTEN_ATTR: f"could not write '/ro/{m}.nc': "
                                    "read-only file system"})
                for m, ds in real(*args, **kwargs).items()}

    monkeypatch.setattr(rs_module, "pair_coefficients", marked)
    tree = run_analysis(None, [250.0], options=LTCAOptions(rolls_per_cycle=4, segments=8),
                        steps=AnalysisChain.contact_only().with_root_stress())
    lt = tree["ltca"].to_dataset()
    assert np.isfinite(lt["root_stress_max"].values).all()
    assert root_stress_notes(lt) == [
        f"root stress: the {m}'s FE coefficients were built and used from memory; the cache "
        f"was not written (could not write '/ro/{m}.nc': read-only file system): the next "
        "run builds them again" for m in ("pinion", "gear")]


@pytest.mark.slow
def test_the_run_says_the_cache_was_not_written_and_the_verdict_checks_root_stress(
        unwritable):
    """A real (coarse) FE build of both members into an unwritable cache (~25 s): the
    analysis has its root stress, ``root_stress_max`` carries the note ``ltca run``
    prints, and the verdict makes the root-stress check."""
    from contact.compliance.fe.contact_compliance import _UNWRITTEN

    coarse = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3,
                       slot_divisions=1, rim_divisions=2, fillet_divisions=2, load_nu=33,
                       load_nv=4)
    _UNWRITTEN.clear()
    tree = run_analysis(None, [250.0], options=LTCAOptions(rolls_per_cycle=4, segments=8),
                        steps=AnalysisChain.contact_only().with_root_stress(coarse))
    lt = tree["ltca"].to_dataset()
    assert np.isfinite(lt["root_stress_max"].values).all()
    assert "root_stress_not_run" not in tree.attrs
    notes = root_stress_notes(lt)
    assert len(notes) == 2 and all("the cache was not written (could not write" in n
                                   for n in notes)
    assert notes[0].startswith("root stress: the pinion's FE coefficients were built and "
                               "used from memory")
    assert CACHE_NOTE_ATTR in lt["root_stress_max"].attrs
    assert "root_stress" in verdict(tree).checks
    assert not unwritable.exists()
    _UNWRITTEN.clear()
