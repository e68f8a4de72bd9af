"""Old import paths of ``contact`` keep working for one release (issue 20, contact._moved).

Every entry of the table imports, warns with a DeprecationWarning naming the new path,
and gives the very module at the new path; the names users import from the old paths
(README, docs) are there.
"""

from __future__ import annotations

import importlib
import sys

import pytest

from contact._moved import MOVED


@pytest.mark.parametrize("old", sorted(MOVED))
def test_old_path_gives_the_new_module_with_a_warning(old):
    if old == "contact.qpbenchmark_set":
        pytest.importorskip("qpbenchmark")  # the [bench] extra
    sys.modules.pop(old, None)
    with pytest.warns(DeprecationWarning, match=MOVED[old].replace(".", r"\.")):
        module = importlib.import_module(old)
    assert module is importlib.import_module(MOVED[old])


@pytest.mark.parametrize("old, names", [
    ("contact.easeoff", ("EaseOff", "ease_off")),
    ("contact.problem", ("ContactProblem", "ContactSolution", "contact_residuals")),
    ("contact.solvers", ("available_solvers", "solve_contact", "get_backend")),
    ("contact.solvers.active_set", ("block_pivoting",)),
    ("contact.deviations", ("read_deviations", "apply_deviations", "SurfaceDeviation",
                            "write_deviation_netcdf")),
    ("contact.tca", ("conventional_tca", "mean_contact")),
    ("contact.edge", ("EDGE_KINDS", "flank_boundary")),
    ("contact.transmission_error", ("transmission_error_summary",)),
    ("contact.compliance.hertz", ("weber_compliance", "contact_modulus")),
    ("contact.compliance.base", ("foundation_matrix",)),
])
def test_names_users_import_from_old_paths(old, names):
    sys.modules.pop(old, None)
    with pytest.warns(DeprecationWarning):
        module = importlib.import_module(old)
    for name in names:
        assert hasattr(module, name), f"{old}.{name}"


def test_packages_that_kept_their_names_export_what_the_modules_did():
    from contact.ltca import LTCAOptions, loaded_tca, ltca_problems, segment_geometry
    from contact.utca import (
        CURVE_SPACINGS,
        DEFAULT_SEPARATION,
        UTE_METHODS,
        ContactCurves,
        contact_curves,
        pair_transmission_error,
        transitions,
        unloaded_tca,
        utca_dataset,
    )

    assert callable(loaded_tca) and callable(unloaded_tca) and callable(ltca_problems)
    assert callable(segment_geometry) and callable(contact_curves)
    assert callable(pair_transmission_error) and callable(transitions)
    assert callable(utca_dataset) and LTCAOptions().solver
    assert DEFAULT_SEPARATION == 0.0063 and set(UTE_METHODS) == {"seed", "second_order"}
    assert "cosine" in CURVE_SPACINGS and ContactCurves._fields[0] == "target"
