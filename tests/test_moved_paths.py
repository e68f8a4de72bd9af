"""Old import paths of ``contact`` and ``geometry`` keep working for one release (issues 20
and 31: contact._moved, geometry._moved).

Every entry of the table imports, warns with a DeprecationWarning naming the new path,
and gives the very module at the new path; the names users import from the old paths
(README, docs) are there.
"""

from __future__ import annotations

import importlib
import sys

import pytest

from contact._moved import MOVED as CONTACT_MOVED
from geometry import MOVED as GEOMETRY_MOVED

MOVED = {**CONTACT_MOVED, **GEOMETRY_MOVED}


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
    ("contact.io", ("read_netcdf", "write_netcdf", "check_conventions")),
    ("contact.deviation_files", ("read_deviations", "write_deviation_netcdf")),
    ("geometry.errors", ("InputError", "LTCAError", "ModelUnavailableError")),
    ("geometry.blank", ("blank_geometry", "BlankGeometry")),
    ("geometry.pitch_cone", ("BevelGearDesign", "pitch_cone")),
    ("geometry.flank", ("flank_surface", "flank_dataset", "projection_grid")),
    ("geometry.assembly", ("Misalignment", "member_transform", "case_transforms")),
    ("geometry.basic_design", ("load_basic", "BasicDesign")),
    ("geometry.correction", ("corrective_settings", "cmm_deviation")),
    ("geometry.conventional_tca", ("conventional_tca",)),
    ("geometry.hertz", ("contact_modulus", "hertz_line_contact")),
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


def test_geometry_packages_that_kept_their_names_export_what_the_modules_did():
    from geometry.machine import MachineSettings, generated_family, settings_from_poses
    from geometry.synthesis import local_synthesis, pinion_generate_tools, synthesize

    assert all(callable(f) for f in (MachineSettings, generated_family, settings_from_poses,
                                     local_synthesis, pinion_generate_tools, synthesize))
