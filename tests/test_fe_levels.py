"""Named FE models (issue 75: ``FEOptions.at_level``): the default level is
``FEOptions()`` itself (its cache keys unchanged), the coarse level sets exactly the
fields :data:`contact.compliance.fe.options.LEVELS` names and is another cache key, and an
unknown level or a bad change is refused naming the field. The coarse model's accuracy
against the default is measured, not tested here: docs/fe.md, "A coarse model for a new
design" (``benchmarks/fe_mesh_convergence.py --levels default coarse``)."""

import dataclasses

import pytest

from contact.catalogue import bundled_case_path
from contact.compliance.fe import FEOptions, cache_key
from contact.compliance.fe.options import LEVELS
from geometry.case import load_case
from geometry.core.errors import InputError


def test_the_default_level_is_the_default_model():
    assert FEOptions.at_level() == FEOptions()
    assert FEOptions.at_level("default") == FEOptions()
    assert FEOptions.at_level("default").to_json() == FEOptions().to_json()


def test_the_coarse_level_sets_its_fields_only_and_is_another_key():
    coarse = FEOptions.at_level("coarse")
    default = FEOptions()
    changed = {f.name for f in dataclasses.fields(FEOptions)
               if getattr(coarse, f.name) != getattr(default, f.name)}
    assert changed == set(LEVELS["coarse"])
    assert (coarse.face_divisions, coarse.fillet_divisions, coarse.flank_divisions,
            coarse.slot_divisions, coarse.rim_divisions, coarse.load_row_step) == (
        8, 4, 5, 2, 3, 2)
    assert coarse.solved_rows == [0, 1, 2, 4, 6, 8, 10]
    member = load_case(bundled_case_path()).member("pinion")
    assert cache_key(member, "concave", coarse) != cache_key(member, "concave", default)


def test_changes_apply_on_top_of_the_level():
    o = FEOptions.at_level("coarse", youngs_modulus=210000.0, face_divisions=10)
    assert o.youngs_modulus == 210000.0 and o.face_divisions == 10
    assert o.fillet_divisions == 4 and o.load_row_step == 2


@pytest.mark.parametrize("level, changes, text", [
    ("fine", {}, "level"),
    ("coarse", {"face_divisions": 1}, "face_divisions"),
    ("coarse", {"load_row_step": 3}, "load_row_step"),
])
def test_bad_levels_and_changes_are_refused_naming_the_field(level, changes, text):
    with pytest.raises(InputError, match=text):
        FEOptions.at_level(level, **changes)
