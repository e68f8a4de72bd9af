"""Files other tools check (issue 21 item 4; issue 38 part 3): the IOOS compliance-checker
(CF-1.8 and ACDD-1.3) and, where installed, the CF checker ``cfchecks`` on every group of a
small ``ltca run`` output, and the writer's CF/ACDD encoding checked directly (no
``_FillValue`` on coordinates, compression, ACDD global attributes, CF flags).

The compliance-checker and ``cfchecks`` read the root group of a file only, so each group
is copied to a flat file of its own (``tests/cf_check.py``) and checked there.

What the tests assert
---------------------
- CF 1.8 (``compliance-checker --test cf:1.8``): no failed check of any priority in any
  group (64-bit integers are written as int32, text as CF char arrays, text dimension
  coordinates such as ``xyz`` as CF label variables ``xyz_label``).
- ``cfchecks`` (cfchecker 4.1, the reference CF checker; it needs the UDUNITS-2 C library,
  so it is not a test dependency: the test skips where it does not run): no error and
  no warning in any group. Its tables are given locally (the standard-name table the
  compliance-checker ships; empty area-type and region tables: the files use neither),
  as the test machine has no network.
- ACDD 1.3 on the root: no failure of high priority and, of the recommended and
  suggested attributes, only those that do not apply to a computed gear analysis (no
  position on the earth or time coverage, no instrument or platform, no published e-mail
  or web address: ``geometry.core.io.ACDD_NOT_APPLICABLE``). The data groups fail one ACDD
  check, documented here: ACDD wants a ``standard_name`` on every variable, the CF
  standard-name table has no names for gear quantities (ease-off, transmission error,
  Hertzian pressure …), and an invented one is itself a CF error.
- The root's ``summary`` states the result per torque (LTE, peak pressures, edge share,
  efficiency, mesh stiffness), so a catalogue shows something.
"""

from __future__ import annotations

import re
from pathlib import Path

import netCDF4
import numpy as np
import pytest

from contact.cli import main
from geometry.core.io import ACDD_ATTRS, CONVENTIONS, write_netcdf

#: the small run: two torques, 8 rolls per mesh cycle, with the efficiency stage
SMALL_RUN = ["--torque", "50", "250", "--rolls-per-cycle", "8", "--no-progress"]

_STANDARD_NAME_ONLY = re.compile(r'^variable "\w+" missing the following attributes:: '
                                 r"standard_name$")


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("cf") / "ltca.nc"
    assert main(["run", *SMALL_RUN, "-o", str(out)]) == 0
    return out


def _groups(nc, where="/"):
    yield where, nc
    for name, child in nc.groups.items():
        yield from _groups(child, f"{where.rstrip('/')}/{name}")


@pytest.fixture(scope="module")
def checker_report(small_run):
    pytest.importorskip("compliance_checker", reason="pip install compliance-checker")
    from cf_check import check_file

    return check_file(small_run)


def test_every_group_passes_cf_1_8(checker_report):
    assert {"/", "/ltca", "/utca", "/easeoff", "/mesh_interface", "/friction",
            "/geometry/gear/convex"} <= set(checker_report)
    failures = [f"{group} [{p}] {fail}" for group, by in checker_report.items()
                for p, fails in by["cf:1.8"].items() for fail in fails]
    assert not failures, "\n".join(failures)


def test_acdd_root_complete_and_groups_only_lack_standard_names(checker_report):
    from geometry.core.io import ACDD_NOT_APPLICABLE

    failures = []
    for group, by in checker_report.items():
        for fail in by["acdd:1.3"]["high"]:
            if group != "/" and _STANDARD_NAME_ONLY.match(fail):
                continue
            failures.append(f"{group} {fail}")
    assert not failures, "\n".join(failures)
    # the root's recommended/suggested attributes: only those that do not apply
    missing = []
    for fail in checker_report["/"]["acdd:1.3"]["medium"] + \
            checker_report["/"]["acdd:1.3"]["low"]:
        missing += re.findall(r"(\w+) not present", fail)
        missing += re.findall(r"(\w+)/\w+ not present", fail)
        missing += re.findall(r"(\w+)/\w+ attribute not found", fail)
        missing += re.findall(r"Attr (\w+) is not present", fail)
    missing = [m for m in missing if m != "is"]
    applicable = [m for m in missing if not m.startswith(ACDD_NOT_APPLICABLE)]
    assert not applicable, applicable


def _cfchecks_runs() -> bool:
    try:
        import cfchecker.cfchecks  # noqa: F401  (imports cfunits, which loads UDUNITS-2)
    except Exception:
        return False
    return True


def test_cfchecks_accepts_every_group(small_run, tmp_path):
    if not _cfchecks_runs():
        pytest.skip("cfchecks not installed (pip install cfchecker; it needs the UDUNITS-2 "
                    "C library, e.g. apt-get install libudunits2-0)")
    import subprocess
    import sys

    from cf_check import extract_group, group_paths

    names = Path(__import__("compliance_checker").__file__).parent / "data" / \
        "cf-standard-name-table.xml"
    area, region = tmp_path / "area.xml", tmp_path / "region.xml"
    area.write_text('<?xml version="1.0"?><area_type_table><version_number>0'
                    "</version_number><date>none</date></area_type_table>")
    region.write_text('<?xml version="1.0"?><standardized_region_list><version_number>0'
                      "</version_number><date>none</date></standardized_region_list>")
    bad = []
    for i, group in enumerate(group_paths(small_run)):
        flat = extract_group(small_run, group, tmp_path / f"group{i}.nc")
        run = subprocess.run([sys.executable, "-m", "cfchecker.cfchecks", "-s", str(names),
                              "-a", str(area), "-r", str(region), "-v", "1.8", str(flat)],
                             capture_output=True, text=True, timeout=300)
        out = run.stdout + run.stderr
        if run.returncode != 0 or "ERRORS detected: 0" not in out or \
                "WARNINGS given: 0" not in out:
            bad.append(f"{group}:\n" + "\n".join(
                ln for ln in out.splitlines() if ln.startswith(("ERROR", "WARN", "Trace"))))
    assert not bad, "\n".join(bad)


def test_conventions_parse_as_cfchecks_and_the_acdd_checker_read_them():
    """cfchecks splits a comma-separated Conventions at commas and strips each name
    (cfchecker 4.1 ``getFileCFVersion``; it knows CF up to 1.8); the compliance-checker's
    ACDD removes blanks and splits at commas."""
    cf = [c.strip() for c in CONVENTIONS.split(",")]
    assert "CF-1.8" in cf
    assert "ACDD-1.3" in CONVENTIONS.replace(" ", "").split(",")


def test_no_text_coordinate_variable(small_run):
    """A CF coordinate variable is numeric (CF 1.8 §5): text labels are auxiliary label
    variables; read back, the text coordinates are what the stage made."""
    from geometry.core.io import read_netcdf

    with netCDF4.Dataset(small_run) as nc:
        for where, g in _groups(nc):
            for name, var in g.variables.items():
                if var.dimensions == (name,):
                    assert var.dtype != str and var.dtype.kind in "iuf", f"{where}/{name}"
            for var in g.variables.values():
                assert var.dtype != np.int64, f"{where}/{var.name} is int64"
    tree = read_netcdf(small_run, tree=True)
    assert list(tree["ltca"]["xyz"].values) == ["x", "y", "z"]
    assert "xyz" in tree["ltca"].indexes
    assert list(tree["utca"]["path"].values) == ["LPP", "CPP", "RPP"]


def test_root_summary_states_the_result(small_run):
    with netCDF4.Dataset(small_run) as nc:
        summary = nc.summary
        assert nc.id.startswith("hypoid-ltca:kolivand2009_fm_11x41_reference:")
    for torque in ("T_p 50 N m", "T_p 250 N m"):
        assert torque in summary
    for what in ("LTE mean", "peak-to-peak", "peak pressure flank", "edge", "efficiency",
                 "mesh stiffness"):
        assert what in summary, what


def test_no_fill_value_on_coordinates_and_nan_fill_where_missing(small_run):
    with netCDF4.Dataset(small_run) as nc:
        for where, g in _groups(nc):
            for name, var in g.variables.items():
                if name in g.dimensions:  # a coordinate variable
                    assert "_FillValue" not in var.ncattrs(), f"{where}/{name}"
        force = nc["ltca/force"]
        assert np.isnan(force.getncattr("_FillValue"))
        assert np.isnan(force[...].filled(np.nan)).any()
        assert "_FillValue" not in nc["ltca/found"].ncattrs()


def test_data_variables_compressed_by_default(small_run):
    with netCDF4.Dataset(small_run) as nc:
        for name in ("force", "pressure_max", "contact", "transmission_error"):
            f = nc["ltca"][name].filters()
            assert f["zlib"] and f["shuffle"] and f["complevel"] == 4, name


def test_compression_can_be_turned_off(tmp_path):
    import xarray as xr

    ds = xr.Dataset({"p": ("x", np.r_[1.0, np.nan], {"units": "MPa", "long_name": "p"})},
                    coords={"x": ("x", [0.0, 1.0], {"units": "mm", "long_name": "x"})})
    plain = write_netcdf(ds, tmp_path / "plain.nc", complevel=0)
    with netCDF4.Dataset(plain) as nc:
        assert not nc["p"].filters()["zlib"]
        assert "_FillValue" not in nc["x"].ncattrs()


def test_acdd_attributes_on_every_group(small_run):
    with netCDF4.Dataset(small_run) as nc:
        for where, g in _groups(nc):
            attrs = g.__dict__
            assert attrs["Conventions"] == CONVENTIONS == "CF-1.8, ACDD-1.3", where
            for key in ("title", "summary", "keywords", "license", "institution",
                        "creator_name", "date_created", "source", "history",
                        "references", "product_version"):
                assert attrs.get(key), f"{where} lacks {key}"
            assert attrs["license"] == "BSD-3-Clause"
            assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", attrs["date_created"])
            for name, var in g.variables.items():
                assert var.getncattr("coverage_content_type") in (
                    "coordinate", "modelResult", "auxiliaryInformation",
                    "qualityInformation"), f"{where}/{name}"
        assert "Kolivand" in nc.references
        assert nc.source.startswith("hypoid-ltca ")
        assert set(ACDD_ATTRS) <= set(nc.ncattrs())


def test_flag_variables_are_cf_flags(small_run):
    with netCDF4.Dataset(small_run) as nc:
        for path in ("ltca/found", "ltca/contact", "ltca/in_problem", "ltca/edge_contact",
                     "utca/active", "utca/contact_pattern", "easeoff/mask",
                     "easeoff/mask_reason"):
            var = nc[path]
            values = np.asarray(var.getncattr("flag_values"))
            meanings = var.getncattr("flag_meanings").split()
            assert values.dtype == var.dtype and len(values) == len(meanings), path
            data = np.asarray(var[...])
            assert np.isin(data, values).all(), path
        status = nc["ltca/status"]
        assert status.long_name  # text: CF asks no units of it
