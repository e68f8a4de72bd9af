"""Bad input and broken files in the commands added last (issue 55): each class of mistake
or fault is refused before any work, in one line naming the field (or the file) and the
accepted range, never with exit 0 and never with a raw library error.

Every case is cheap: refusals happen before any solve; the one study that runs fails
every point by a patched solver in this process.
"""

from __future__ import annotations

import errno
import re

import numpy as np
import pytest
import xarray as xr

from contact.cli import main
from friction.lubricant import load_lubricant
from geometry.core.errors import FileWriteError, InputError
from geometry.core.io import NetCDFError, read_netcdf, write_netcdf

#: what a user must never see: library error codes, tracebacks, Python exception names
RAW = re.compile(r"Errno|NetCDF:|HDF|Traceback|UnicodeDecodeError|KeyError|np\.int64")

EHL = ["ehl", "--pressure", "1.0", "--radius", "20", "--speed", "1"]


def _oil_file(tmp_path, replace: tuple[str, str] | None = None):
    """The bundled 75W90 oil file copied, with one text replacement."""
    from friction.lubricant import _bundled

    text = _bundled()["75W90"].read_text(encoding="utf-8")
    if replace:
        assert replace[0] in text
        text = text.replace(*replace)
    path = tmp_path / "oil.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _binary(tmp_path, name="bin.toml"):
    path = tmp_path / name
    path.write_bytes(bytes(range(256)) * 4)
    return path


def _refused(argv, capsys, pattern):
    """Exit 2, one error line on stderr matching ``pattern``, no raw library text."""
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert re.search(pattern, err), err
    assert not RAW.search(err), err
    return err


# --------------------------------------------------------------------------- ltca ehl
@pytest.mark.parametrize(("extra", "pattern"), [
    # a typing slip of 50 for 0.5 GPa: refused with the range, not solved
    (["--pressure", "50"], r"--pressure: must be in \[0.01, 6\] \[GPa\], got 50"),
    # no gear contact carries 1e-9 GPa: refused at once, not solved for 30 s to a Newton
    # failure (issue 64); the bound is the table's (geometry.core.bounds)
    (["--pressure", "1e-9"], r"--pressure: must be in \[0.01, 6\] \[GPa\], got 1e-09"),
    (["--radius", "0"], r"--radius: must be in \[0.01, 5000\] \[mm\]"),
    (["--speed", "250"], r"--speed: must be in \(0, 100\] \[m/s\]"),
    (["--slide-to-roll", "3"], r"--slide-to-roll: must be in \[-2, 2\]"),
    (["--temperature", "300"], r"--temperature: must be in \[5, 140\] \[degC\]"),
    # a plain negative number is a value (not "expected 2 arguments"), refused by range
    (["--roughness", "-0.3", "0.3"], r"--roughness RQ1: must be in \[0, 5\] \[um\], got -0.3"),
    (["--lubricant", "NO-SUCH-OIL"], r"--lubricant: no lubricant named or at 'NO-SUCH-OIL'"),
])
def test_ehl_refuses_out_of_range_before_any_work(extra, pattern, tmp_path, capsys,
                                                  monkeypatch):
    monkeypatch.chdir(tmp_path)
    _refused([*EHL, *extra, "-o", "e.nc"], capsys, pattern)
    assert not (tmp_path / "e.nc").exists()


def test_ehl_refuses_a_binary_or_nan_oil_file(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _refused([*EHL, "--lubricant", str(_binary(tmp_path))], capsys,
             r"--lubricant: lubricant file .*bin\.toml.*: not UTF-8 text")
    nan = _oil_file(tmp_path, ("dynamic_viscosity = [0.1626", "dynamic_viscosity = [nan"))
    _refused([*EHL, "--lubricant", str(nan)], capsys,
             r"oil\.toml: dynamic_viscosity: must be finite and > 0")
    zero = _oil_file(tmp_path, ("thermal_conductivity = 0.135", "thermal_conductivity = 0.0"))
    _refused([*EHL, "--lubricant", str(zero)], capsys, r"thermal_conductivity")


def test_line_contact_library_refuses_steel_beyond_shakedown():
    # the library itself (not only the command): a load that gives p_h > 6 GPa is named
    from friction.ehl.line_contact import LineContactCondition, line_contact_summary

    cond = LineContactCondition(load_per_length=1.39e6, radius=20.0, entraining_velocity=1.0,
                                slide_to_roll=0.3, temperature=90.0)
    with pytest.raises(InputError, match=r"^load_per_length: .* Hertz pressure of \d+ MPa, "
                                         r"above 6000 MPa"):
        line_contact_summary(cond)


# ------------------------------------------------------------------------ input files
def test_lubricant_reader_names_file_and_field(tmp_path):
    with pytest.raises(InputError, match=r"^lubricant file .*: not UTF-8 text"):
        load_lubricant(_binary(tmp_path))
    with pytest.raises(InputError, match=r"density: must be finite and > 0"):
        load_lubricant(_oil_file(tmp_path, ("density = [844.3", "density = [-844.3")))


def test_duty_cycle_spectrum_binary_file_refused(tmp_path, capsys):
    _refused(["duty-cycle", "--duty", str(_binary(tmp_path)), "--no-root-stress",
              "-o", str(tmp_path / "d.nc")], capsys,
             r"duty_cycle: spectrum file .*bin\.toml.*: not UTF-8 text")


# ------------------------------------------------------------------------- the study
def test_friction_study_refuses_a_bad_oil_before_any_work(tmp_path, capsys):
    out = tmp_path / "fs.nc"
    base = ["friction-study", "-n", "2", "--nodes", "64", "--scheduler", "synchronous",
            "--no-progress", "-o", str(out)]
    _refused([*base, "--lubricant", "NO-SUCH-OIL"], capsys, r"^ltca friction-study: error: "
             r"--lubricant: no lubricant named or at 'NO-SUCH-OIL'")
    nan = _oil_file(tmp_path, ("dynamic_viscosity = [0.1626", "dynamic_viscosity = [nan"))
    _refused([*base, "--lubricant", str(nan)], capsys, r"--lubricant: .*dynamic_viscosity")
    _refused([*base, "--lubricant", str(_binary(tmp_path))], capsys,
             r"--lubricant: lubricant file .*: not UTF-8 text")
    assert not out.exists() and not (tmp_path / "fs.nc.parts").exists()


def test_design_temperatures_checked_against_the_oil():
    from friction.study.design import DESIGN_INPUTS, check_design

    point = {k: [0.5] for k in DESIGN_INPUTS}
    point.update(hertz_pressure=[1000.0], radius=[20.0], entraining_velocity=[1.0],
                 temperature=[200.0])
    check_design(point)                       # without an oil: only the coarse bounds
    with pytest.raises(InputError, match=r"^temperature: must be in \[5, 140\] \[degC\], "
                                         r"got 200"):
        check_design(point, lubricant="75W90")
    with pytest.raises(InputError, match=r"^hertz_pressure: must be in \(0, 6000\]"):
        check_design({**point, "temperature": [90.0], "hertz_pressure": [5e4]})


def test_a_study_of_which_no_point_converges_is_an_error(tmp_path, capsys, monkeypatch):
    # one failed point is a result; all failed is an error naming the first point's reason
    import contact.study.friction_study as fs
    from friction.study.points import POINT_STATUS, RESULT_VARIABLES, PointOutcome

    def fail(settings, index, point):
        return PointOutcome(index, POINT_STATUS.index("not_converged"),
                            "Newton did not converge in 1 iteration",
                            dict.fromkeys(RESULT_VARIABLES, float("nan")))

    monkeypatch.setattr(fs, "solve_design_point", fail)
    out = tmp_path / "fs.nc"
    _refused(["friction-study", "-n", "2", "--nodes", "64", "--scheduler", "synchronous",
              "--no-progress", "-o", str(out)], capsys,
             r"none of the 2 conditions converged; the first \(point 0\): Newton did not "
             r"converge in 1 iteration")
    assert read_netcdf(out, tree=False).sizes["point"] == 2   # the reasons are kept


def test_combining_studies_names_the_setting_in_plain_numbers():
    from friction.kolivand2009 import DATA_DIR
    from friction.study.fit import combine_studies

    held = read_netcdf(DATA_DIR / "friction_study_75W90_heldout.nc", tree=False)
    other = held.copy()
    other.attrs = {**held.attrs, "solver_nodes": np.int64(1024)}
    with pytest.raises(InputError, match=r"solver_nodes differs \(512 in the first, 1024 in "
                                         r"another\)"):
        combine_studies([held, other])


# ------------------------------------------------------------------- options bounding work
@pytest.mark.parametrize(("argv", "pattern"), [
    (["compare-solvers", "--repeats", "0"], r"--repeats: must be an integer in \[1, 100\]"),
    (["optimize", "--max-evaluations", "0"],
     r"--max-evaluations: must be an integer in \[2, 1000000\], got 0"),
    (["sweep", "--workers", "0"], r"--workers: must be an integer in \[1, 1024\]"),
    (["tolerance", "-n", "-5"], r"-n: must be an integer in \[2, 10000000\], got -5"),  # plugin83
    (["friction-study", "-n", "0"], r"--points: must be an integer"),
    (["run", "--rolls-per-cycle", "2"], r"--rolls-per-cycle: must be an integer in \[4, 400\]"),
    (["ehl", "--pressure", "1", "--radius", "20", "--speed", "1", "--nodes", "8"],
     r"argument --nodes: must be an integer in \[16, 16384\], got 8"),
])
def test_options_that_bound_work_refused_by_the_parser(argv, pattern, capsys):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert re.search(pattern, err), err


# ---------------------------------------------------------------------------- files
def _study_file(tmp_path):
    ds = xr.Dataset({"a": ("x", np.arange(3.0), {"units": "1", "long_name": "a"})},
                    coords={"x": ("x", np.arange(3), {"units": "1", "long_name": "x"})})
    return write_netcdf(ds, tmp_path / "good.nc")


@pytest.mark.parametrize(("make", "pattern"), [
    (lambda p: p.write_bytes(b""), r"the file is empty \(0 bytes\), not a netCDF file"),
    (lambda p: p.write_text("schema = 1\n[blank]\n", encoding="utf-8"),
     r"not a netCDF file: it is UTF-8 text, a TOML file"),
    (lambda p: p.write_bytes(bytes(range(256))), r"not a netCDF file \(binary data"),
])
def test_reading_a_file_that_is_not_netcdf_says_what_it_is(make, pattern, tmp_path):
    path = tmp_path / "bad.nc"
    make(path)
    with pytest.raises(NetCDFError, match=pattern) as err:
        read_netcdf(path)
    assert not RAW.search(str(err.value))


def test_reading_a_truncated_file_says_truncated(tmp_path, capsys):
    good = _study_file(tmp_path)
    data = good.read_bytes()
    cut = tmp_path / "cut.nc"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(NetCDFError, match=r"'.*cut\.nc': a netCDF file that is truncated or "
                                          r"damaged \(\d+ bytes\)$") as err:
        read_netcdf(cut)
    assert not RAW.search(str(err.value))
    # and through a command: one line, exit 2 (friction-fit of a truncated study)
    _refused(["friction-fit", str(cut), "-o", str(tmp_path / "k.toml")], capsys,
             r"truncated or damaged")


@pytest.mark.parametrize("code", [errno.ENOSPC, errno.EROFS])
def test_writing_onto_a_full_or_read_only_disk_is_a_sentence(code, tmp_path, monkeypatch):
    path = _study_file(tmp_path)
    before = path.read_bytes()
    ds = read_netcdf(path)

    def refuse(self, *args, **kwargs):
        raise OSError(code, "raised by the test")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", refuse)
    text = {errno.ENOSPC: "no space left on", errno.EROFS: "read-only file system"}[code]
    with pytest.raises(NetCDFError, match=rf"could not write '.*good\.nc': .*{text}"):
        write_netcdf(ds, path)
    assert path.read_bytes() == before                    # the previous file untouched
    assert sorted(p.name for p in tmp_path.iterdir()) == ["good.nc"]  # no temporary left


def test_full_disk_reported_by_the_netcdf_library_as_hdf_error(tmp_path, monkeypatch):
    # the library says "HDF error" without errno on a full disk: put in words when the
    # disk has (almost) no space left
    import shutil

    import geometry.core.atomic_files as af

    path = _study_file(tmp_path)
    ds = read_netcdf(path)

    def hdf_error(self, *args, **kwargs):
        raise RuntimeError("NetCDF: HDF error")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", hdf_error)
    monkeypatch.setattr(af.shutil, "disk_usage",
                        lambda p: shutil._ntuple_diskusage(10**9, 10**9, 1024))
    with pytest.raises(NetCDFError, match=r"no space left on") as err:
        write_netcdf(ds, path)
    assert not RAW.search(str(err.value))


def test_text_files_written_atomically_report_a_full_disk(tmp_path, monkeypatch):
    # every atomic write (case files, reports) names the disk's fault in one sentence
    from geometry.core.atomic_files import atomic_path

    target = tmp_path / "case.toml"
    target.write_text("old", encoding="utf-8")

    def full(self, *args, **kwargs):
        raise OSError(errno.ENOSPC, "raised by the test")

    with pytest.raises(FileWriteError, match=r"could not write .*case\.toml.*: no space left "
                                             r"on "), atomic_path(target) as tmp:
        monkeypatch.setattr(type(tmp), "write_text", full)
        tmp.write_text("new", encoding="utf-8")
    monkeypatch.undo()
    assert target.read_text(encoding="utf-8") == "old"


@pytest.mark.parametrize(("free", "text"), [
    (1024, r"no space left on"),                    # a full disk, whatever the library said
    (10**9, r"no permission to write in"),          # room left: the permission is the cause
])
def test_a_full_disk_is_reported_as_such_before_trusting_eacces(free, text, tmp_path,
                                                               monkeypatch):
    # the netCDF library may report a full disk as EACCES (issue 64: ltca rate and
    # efficiency-map said "no permission to write" on a full disk): the free space is read
    # first, and EACCES trusted only where there is room
    import shutil

    import geometry.core.atomic_files as af

    path = _study_file(tmp_path)
    ds = read_netcdf(path)

    def eacces(self, *args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", eacces)
    monkeypatch.setattr(af.shutil, "disk_usage",
                        lambda p: shutil._ntuple_diskusage(10**10, 10**10 - free, free))
    with pytest.raises(NetCDFError, match=rf"could not write '.*good\.nc': {text}") as err:
        write_netcdf(ds, path)
    assert not RAW.search(str(err.value))


# --------------------------------------------------------------------------- issue 64
# the table of physical bounds, the public API's arguments and output that misled

def test_the_table_of_bounds_is_the_line_contact_solvers_range():
    """One table: ``ltca ehl``'s bounds, the friction study's and the line-contact
    library's are the same numbers (the library keeps its own names for them)."""
    from friction.ehl.line_contact import (
        MAX_ENTRAINING_VELOCITY,
        MAX_HERTZ_PRESSURE,
        RADIUS_RANGE,
    )
    from geometry.core.bounds import PHYSICAL_BOUNDS as B

    assert B["hertz_pressure"].high == MAX_HERTZ_PRESSURE
    assert (B["radius"].low, B["radius"].high) == RADIUS_RANGE
    assert B["entraining_velocity"].high == MAX_ENTRAINING_VELOCITY
    # the operating defaults lie inside (a default refused would be a broken table)
    from geometry.core.operating_defaults import OPERATING_DEFAULTS as D

    for name in ("pinion_speed", "temperature", "roughness"):
        assert B[name].low < D[name] <= B[name].high
    assert all(B["torque"].low < t <= B["torque"].high for t in D["torque"])


@pytest.mark.parametrize(("argv", "pattern"), [
    # ISO ratings at 10^12 rpm or N m printed full tables (S_H 1.688)
    (["rate", "--speed", "1e12"], r"--speed: must be in \(0, 50000\] \[rpm\], got 1e\+12"),
    (["rate", "--torque", "1e12"], r"--torque: must be in \(0, 1e\+06\] \[N m\], got 1e\+12"),
    # efficiency maps at 10^12 rpm (98.54 %) or Rq 100 um (95.58 %), after 15 s of work
    (["efficiency-map", "--speed", "1e12"], r"--speed: must be in \(0, 50000\] \[rpm\]"),
    (["efficiency-map", "--roughness", "100"], r"--roughness: must be in \(0, 5\] \[um\], "
                                               r"got 100"),
    (["run", "--temperature", "500"], r"--temperature: must be in \[-40, 200\] \[degC\]"),
    (["mesh-interface", "--torque", "2e6"], r"--torque: must be in \(0, 1e\+06\] \[N m\]"),
    (["sweep", "--speed", "1e12"], r"--speed: must be in \(0, 50000\] \[rpm\]"),
])
def test_absurd_magnitudes_are_refused_by_every_command(argv, pattern, capsys, tmp_path,
                                                        monkeypatch):
    import contact.ltca

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(contact.ltca, "loaded_tca", None)  # nothing may run
    _refused(argv, capsys, pattern)
    assert list(tmp_path.iterdir()) == []


def test_efficiency_map_checks_its_sweep_before_any_geometry(monkeypatch):
    """An oil temperature outside the oil's data (inside the table's bound) is refused
    before the first torque's LTCA, which took ~15 s of geometry and ease-off."""
    import contact.study.efficiency as ef

    def no_work(*args, **kwargs):
        raise AssertionError("the LTCA ran before the sweep was checked")

    monkeypatch.setattr(ef, "loaded_tca", no_work)
    with pytest.raises(InputError, match=r"^temperature: must be in \[5, 140\] \[degC\] for "
                                         r"the lubricant '75W90'.*got 150$"):
        ef.efficiency_map(None, [250.0], [1500.0], temperature=[90.0, 150.0])
    with pytest.raises(InputError, match=r"^speed: must be in \(0, 50000\] \[rpm\], got "
                                         r"1e\+12$"):
        ef.efficiency_map(None, [250.0], [1e12])
    with pytest.raises(InputError, match=r"^roughness: must be in \(0, 5\] \[um\], got 100$"):
        ef.efficiency_map(None, [250.0], [1500.0], roughness=[100.0])


def test_a_duty_cycle_of_absurd_bins_is_refused_bin_by_bin():
    from contact.study.duty_cycle_inputs import DutyCycle

    with pytest.raises(InputError, match=r"^duty_cycle\.speed \(bin 1\): must be in \(0, "
                                         r"50000\] \[rpm\], got 1e\+12$"):
        DutyCycle(torque=[100.0, 200.0], pinion_speed=[1500.0, 1e12], revolutions=[1e5, 1e5])


def _api_calls():
    from contact.pipeline import run_analysis
    from geometry import load_case

    return [
        (lambda: run_analysis(None, torque="abc"),
         r"^torque: must be a number or a sequence of numbers in \(0, 1e\+06\] \[N m\] "
         r"\(pinion torques\), got 'abc'$"),
        (lambda: run_analysis(None, torque=1e12),
         r"^torque: must be in \(0, 1e\+06\] \[N m\], got 1e\+12$"),
        (lambda: run_analysis(case=42), r"^case: must be a geometry\.case\.Case, the path of a "
                                        r"case file, the name of a bundled case or None"),
        (lambda: run_analysis(None, 50.0, options="fast"),
         r"^options: must be a contact\.ltca\.LTCAOptions or None \(the defaults\), got str "
         r"'fast'$"),
        # a flank, not a misalignment ("reduce them together")
        (lambda: run_analysis(None, 50.0, flank="up"),
         r"^flank: must be 'drive' or 'coast' \(or a pinion flank name, 'concave' or "
         r"'convex'\), got 'up'$"),
        (lambda: run_analysis(None, 50.0, misalignment=(0.1, 0.0)),
         r"^misalignment: must be a geometry\.pair\.assembly\.Misalignment"),
        (lambda: run_analysis(None, 50.0, geometry="yes"),
         r"^geometry: must be True or False, got 'yes'$"),
        (lambda: load_case(None), r"^path: must be the path of a case file \(str or "
                                  r"os\.PathLike\), got NoneType None$"),
        (lambda: load_case(42), r"^path: must be the path of a case file .*got int 42$"),
    ]


@pytest.mark.parametrize("k", range(9))
def test_the_public_api_refuses_bad_arguments_in_one_sentence(k):
    call, pattern = _api_calls()[k]
    with pytest.raises(InputError, match=pattern) as info:
        call()
    assert "\n" not in str(info.value)


def test_write_report_of_a_tree_without_ltca_variables_names_them(tmp_path):
    from contact import write_report

    tree = xr.DataTree.from_dict({"/ltca": xr.Dataset({"lte_mean": ("torque", [1.0])})})
    with pytest.raises(InputError, match=r"^tree: /ltca lacks force, found, "
                                         r"transmission_error, lte_peak_to_peak, "
                                         r"pressure_max_flank, pressure_max_edge, which the "
                                         r"report reads"):
        write_report(tree, tmp_path / "r.html")
    with pytest.raises(InputError, match=r"^tree: has no /ltca group \(groups: easeoff\)"):
        write_report(xr.DataTree.from_dict({"/easeoff": xr.Dataset()}), tmp_path / "r.html")
    with pytest.raises(InputError, match=r"^tree: must be the xarray\.DataTree"):
        write_report(xr.Dataset(), tmp_path / "r.html")
    assert list(tmp_path.iterdir()) == []


def test_rating_a_basic_design_file_says_what_it_is(capsys):
    from contact.commands.synthesize import resolve_basic

    basic = resolve_basic("iso23509_sample2_fm")
    _refused(["rate", str(basic)], capsys,
             r"is a basic design file \(\[design\] without \[pair\], \[pinion\], \[gear\]\); "
             r"make a case of it first: ltca synthesize .*iso23509_sample2_fm\.toml.* -o "
             r"CASE\.toml")


def test_a_spiral_bevel_rating_says_why_v_sum_vert_is_nan():
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300 import iso10300_rating

    case = resolve_case("iso10300_30_sample1")
    assert case.pair.offset == 0.0                     # a spiral bevel pair
    ds = iso10300_rating(case)
    assert np.isnan(float(ds["v_sum_vert"]))
    assert float(ds["Z_Hyp"]) == 1.0                # ISO 10300-2 cl. 6 for a = 0
    assert ds["v_sum_vert"].attrs["comment"].startswith("NaN: not evaluated for a pair "
                                                        "without hypoid offset")
    hypoid = iso10300_rating(resolve_case("iso10300_30_sample2"))
    assert np.isfinite(float(hypoid["v_sum_vert"]))
    assert "comment" not in hypoid["v_sum_vert"].attrs


def test_the_verdict_of_a_tree_without_ltca_names_the_checks_it_could_not_make():
    from contact.study.verdicts import CHECKS, verdict

    tree = xr.DataTree.from_dict({"/easeoff": xr.Dataset()})
    v = verdict(tree)
    contact_checks = ("implausible", "flank_pressure", "edge_contact", "plastic_edges",
                      "edge_pressure", "certification", "lte")
    assert [c for c, _ in v.unchecked] == [c for c in CHECKS["analysis"]]
    lines = v.lines()
    assert lines[1] == ("  not checked: " + ", ".join(contact_checks)
                        + " (no /ltca group: the tree holds no loaded contact)")
    # the root stress with the reason of its own check (contact.study.verdict_checks)
    assert any(line.startswith("  not checked: root_stress") for line in lines)
    assert any(line.startswith("  not checked: friction_extrapolated, efficiency (no "
                               "/friction group") for line in lines)
    # scuffing and micropitting are the load-capacity step's group (issue 63)
    assert any(line.startswith("  not checked: scuffing, micropitting (no "
                               "/scuffing_micropitting group") for line in lines)


def test_ehl_never_prints_a_negative_film(tmp_path, capsys, monkeypatch):
    """Rough surfaces at 3 GPa and 0.05 m/s interlock: the stochastic model's mean-plane
    separation is negative there; it is printed as a separation, with the mean gap."""
    monkeypatch.chdir(tmp_path)
    assert main([*EHL[:2], "3", "--radius", "20", "--speed", "0.05", "--roughness", "1.5",
                 "1.5", "-o", "e.nc"]) == 0
    out = capsys.readouterr().out
    ds = xr.open_dataset(tmp_path / "e.nc")
    sep = float(ds["film_central"])
    ds.close()
    assert sep < 0.0   # the case of the issue: the mean planes interpenetrate
    assert "h_c" not in out and "h_min" not in out
    assert re.search(rf"no film: the mean planes interpenetrate \(asperities in contact\), "
                     rf"separation of the mean planes {sep:.4f} um at x = 0", out), out
    assert re.search(r"mean gap \(oil\) \d+\.\d+ um", out)   # the gap is never negative


@pytest.mark.parametrize(("torque", "speed", "pattern"), [
    (1e12, None, r"^torque: must be in \(0, 1e\+06\] \[N m\], got 1e\+12$"),
    (None, 1e12, r"^speed: must be in \(0, 50000\] \[rpm\], got 1e\+12$"),
    ("lots", None, r"^torque: must be a number or a sequence of numbers"),
])
def test_the_rating_api_applies_the_table_of_bounds(torque, speed, pattern):
    # the API as the command: 10^12 rpm printed S_H 1.688 before (issue 64)
    from contact.load_capacity.iso10300 import iso10300_rating

    with pytest.raises(InputError, match=pattern):
        iso10300_rating("iso10300_30_sample1", torque, speed)
