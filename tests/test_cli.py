"""The ``ltca`` command line: commands listed, compare-solvers writes a readable netCDF."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.cli import main
from contact.qp.benchmark_problems import ltca_like_problem
from contact.qp.solver_study import compare_solvers, shifted_geometric_mean, summarize
from geometry.core.io import read_netcdf, write_netcdf

ROOT = Path(__file__).resolve().parents[1]



def _refusal(err: str) -> str:
    """A refusal's stderr without numba's one-time compile note (``contact.cli.compile_note``:
    printed before the command runs where this machine's kernel cache is still empty, as in
    a fresh CI venv when these tests run before any analysis compiled them; .ci/fresh
    failed 7 tests on it, by test order alone)."""
    return "\n".join(line for line in err.strip().splitlines()
                      if not line.startswith("note: compiling ")).strip()

def test_help_lists_commands(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--help"])
    assert info.value.code == 0
    assert "compare-solvers" in capsys.readouterr().out


def test_python_dash_m_contact():
    out = subprocess.run(
        [sys.executable, "-m", "contact", "--version"], capture_output=True, text=True, check=True
    )
    assert "hypoid-ltca" in out.stdout


def test_compare_solvers_command_writes_netcdf(tmp_path, capsys):
    pytest.importorskip("daqp", reason="an optional backend: pip install 'hypoid-ltca[solvers]'")
    path = tmp_path / "cmp.nc"
    code = main(
        [
            "compare-solvers",
            "--quick",
            "--solvers",
            "active_set",
            "daqp",
            "osqp",
            "--no-progress",
            "-o",
            str(path),
        ]
    )
    assert code == 0
    out = capsys.readouterr().out
    assert "active_set" in out and "time / best" in out
    ds = read_netcdf(path)
    assert ds.sizes["solver"] == 3
    assert int(ds["found"].sum()) == ds.sizes["solver"] * ds.sizes["problem"]
    xr.testing.assert_identical(read_netcdf(write_netcdf(ds, tmp_path / "again.nc")), ds)


def test_unknown_solver_is_a_clean_error(capsys):
    assert main(["compare-solvers", "--quick", "--solvers", "nope", "--no-progress"]) == 2
    assert "available" in capsys.readouterr().err


def test_compare_solvers_lists_the_backends_not_installed(monkeypatch, capsys, tmp_path):
    """A known backend missing here (a name no one installs stands for it) is printed with
    its install line and recorded in the results (``solvers_not_installed``)."""
    from contact.qp import solvers

    monkeypatch.setitem(solvers.KNOWN_BACKENDS, "nosuchqp", "nosuchqp-dist")
    path = tmp_path / "cmp.nc"
    assert main(["compare-solvers", "--quick", "--solvers", "active_set", "--repeats", "1",
                 "--no-progress", "-o", str(path)]) == 0
    out = capsys.readouterr().out
    line = next(x for x in out.splitlines() if x.startswith("not installed here: "))
    assert "nosuchqp" in line and solvers.SOLVERS_EXTRA in line
    assert "nosuchqp" in read_netcdf(path).attrs["solvers_not_installed"]


def test_summary_success_rate_and_relative_time():
    pytest.importorskip("quadprog",
                        reason="an optional backend: pip install 'hypoid-ltca[solvers]'")
    problems = [ltca_like_problem(40, seed=s) for s in range(3)]
    res = compare_solvers(problems, ["active_set", "quadprog"])
    summ = summarize(res)
    assert np.all(summ.success_rate.values == 100.0)
    assert np.min(summ.time_relative.values) == pytest.approx(1.0)
    assert np.all(summ.worst_force_error.values < 1e-8)


def test_shifted_geometric_mean():
    # sh-geom of constant values is that value; against a hand computation otherwise.
    assert shifted_geometric_mean([3.0, 3.0, 3.0], 1.0) == pytest.approx(3.0)
    expected = np.exp((np.log(2.0) + np.log(9.0)) / 2) - 1
    assert shifted_geometric_mean([1.0, 8.0], 1.0) == pytest.approx(expected)


@pytest.mark.parametrize("case", ["cases/kolivand2009_fm_11x41.toml",
                                  "tests/data/fh_iso23509_s2_crown.toml"])
def test_geometry_commands(tmp_path, capsys, case):
    """The geometry commands work unchanged for a face-milled and a face-hobbed case."""
    out = tmp_path / "flanks.nc"
    assert main(["geometry", case, "-o", str(out), "--nu", "9", "--nv", "5"]) == 0
    tree = read_netcdf(out, tree=True)
    assert {"pinion", "gear"} <= set(tree.children)
    for member in ("pinion", "gear"):
        for flank in ("concave", "convex"):
            ds = tree[f"{member}/{flank}"].dataset
            assert ds.sizes["u"] == 9 and ds.sizes["v"] == 5
            assert int(ds["mask"].sum()) > 0.8 * 45  # most grid points generated
    assert main(["plot-geometry", case, "-o", str(tmp_path / "png"), "--nu", "9", "--nv", "5"]) == 0
    pngs = {p.name for p in (tmp_path / "png").glob("*.png")}
    from contact.catalogue import resolve_case

    name = resolve_case(case).name  # the figures carry the case's name
    assert f"{name}_flanks_in_mesh.png" in pngs and f"{name}_grid_gear_convex.png" in pngs
    if "fh_" in case:
        # the face-hobbed file records its process; the meshing residual of every generated
        # point of the generated pinion is at the solver's tolerance (1e-12 normalised)
        ds = tree["pinion/concave"].dataset
        res = ds["meshing_residual"].values[ds["mask"].values.astype(bool)]
        assert np.nanmax(np.abs(res)) <= 1e-9


@pytest.mark.slow  # ~30 s; CI budget (README: slow studies run outside CI)
def test_run_prints_the_deviation_te_table_of_the_file(tmp_path, capsys):
    """`ltca run` of a case with a [deviations] table: the theoretical/deviated TE table
    (seed Tables 4.2, 4.4) shows the values stored in the netCDF; --no-deviations ignores
    the table."""
    from pathlib import Path

    from contact.commands.run import TE_TABLE_HEADERS

    case = Path(__file__).resolve().parents[1] / "cases" / "kolivand2009_fm_11x41_wear.toml"
    # (no root stress: the deviations' table is tested, and the FE build of this design's
    # teeth, ~50 s of CPU, would be the suite's only one of them)
    quick = ["--torque", "200", "--rolls-per-cycle", "6", "--segments", "10", "--speed", "0",
             "--no-progress", "--no-root-stress"]
    out = tmp_path / "wear.nc"
    assert main(["run", str(case), *quick, "-o", str(out), "--plots", str(tmp_path / "png")]) == 0
    text = capsys.readouterr().out
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == len(TE_TABLE_HEADERS) and cells[1] in ("theoretical", "deviated"):
            rows[cells[1]] = [float(c) for c in (cells[0], *cells[2:])]
    assert set(rows) == {"theoretical", "deviated"}
    tree = read_netcdf(out)
    for name, lt, ut in (("deviated", tree["ltca"], tree["utca"]),
                         ("theoretical", tree["theoretical/ltca"], tree["theoretical/utca"])):
        h = lt["lte_harmonics"].values[0]
        stored = [float(lt["torque"][0]), float(lt["lte_mean"][0]),
                  float(lt["lte_peak_to_peak"][0]), h[0], h[1], h[2],
                  float(lt["lte_harmonic_rss"][0]),
                  float(ut["peak_to_peak_transmission_error"])]
        # printed with two decimals: equal to the stored values within half a unit of the
        # last printed digit (0.005 urad); a harmonic the 12 rolls cannot resolve is NaN in
        # both (assert_allclose: NaN equals NaN)
        np.testing.assert_allclose(rows[name], stored, rtol=0, atol=0.005 + 1e-9)
    # the deviations change the result (the table is not two copies of one run)
    assert abs(rows["deviated"][2] - rows["theoretical"][2]) > 1.0  # LTE mean, urad
    # named after the case (issue 38: the runs of one directory keep their own figures)
    # and their torques (issue 56): <case>_T<torques>_<figure>.png
    pngs = {p.name.removeprefix("kolivand2009_fm_11x41_wear_").split("_", 1)[1]
            for p in (tmp_path / "png").glob("kolivand2009_fm_11x41_wear_T*.png")}
    # theoretical and deviated side by side (UTE and LTE in one figure, pressure on one
    # scale); the deviated pattern is the run's own contact_pattern.png
    assert {"deviations_easeoff_change.png", "deviations_transmission_error.png",
            "deviations_easeoff.png", "deviations_contact_pattern_theoretical.png",
            "contact_pattern.png", "deviations_pressure.png"} <= pngs
    plain = tmp_path / "plain.nc"
    assert main(["run", str(case), *quick, "--no-deviations", "-o", str(plain)]) == 0
    assert "theoretical" not in capsys.readouterr().out
    back = read_netcdf(plain)
    assert "theoretical" not in back.children
    # without the deviations the main groups are the theoretical results of the first run:
    # the same computation in another run, to round-off (1e-12 relative: numpy's SIMD
    # loops treat an array's unaligned head apart, so a repeat may differ in the last bits)
    np.testing.assert_allclose(back["ltca"]["transmission_error"].values,
                               tree["theoretical/ltca"]["transmission_error"].values,
                               rtol=1e-12, atol=0)


# ------------------------------------------------------------------ refuse before any work
_FM_CASE = str(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
_FM_BASIC = str(ROOT / "cases" / "basic" / "kolivand2009_fm_11x41.toml")


@pytest.mark.parametrize("argv, message", [
    (["run", "-o", "{missing}/r.nc"], "-o: directory '{missing}' does not exist"),
    (["run", "-o", "{tmp}"], "-o: '{tmp}' is a directory; give a file name"),
    (["run", "--plots", "{file}"], "--plots: '{file}' is a file, not a directory"),
    (["run", "--plots", "{file}/sub"], "--plots: cannot create the directory '{file}/sub'"),
    (["utca", _FM_CASE, "-o", "{missing}/u.nc"], "-o: directory '{missing}' does not exist"),
    (["utca", _FM_CASE, "--plots", "{file}"], "--plots: '{file}' is a file"),
    (["efficiency-map", "-o", "{missing}/e.nc"], "-o: directory '{missing}' does not exist"),
    (["efficiency-map", "--plots", "{file}"], "--plots: '{file}' is a file"),
    (["geometry", _FM_CASE, "-o", "{tmp}"], "-o: '{tmp}' is a directory"),
    (["plot-geometry", _FM_CASE, "--plots", "{file}"], "--plots: '{file}' is a file"),
    (["geometry", "-o", "{missing}/g.nc"], "-o: directory '{missing}' does not exist"),
    (["wear", "--cycles", "1", "--wear-coefficient", "1e-17", "-o", "{tmp}"],
     "-o: '{tmp}' is a directory"),
    (["sweep", "--dE", "0", "-o", "{missing}/s.nc"], "-o: directory '{missing}' does not exist"),
    (["synthesize", _FM_BASIC, "-o", "{file}/sub/c.toml"],
     "-o: cannot create the directory '{file}/sub'"),
    (["compare-solvers", "-o", "{missing}/s.nc"], "-o: directory '{missing}' does not exist"),
])
def test_output_paths_are_refused_before_any_work(argv, message, tmp_path, monkeypatch, capsys):
    """Every sub-command checks the places it writes before it loads a case or computes
    anything (the loaders are replaced by a trap here): a missing directory, a directory
    given as a file, a file given as a directory, a directory that cannot be created.
    Answer: exit status 2 and one line ``ltca CMD: error: OPTION: …`` naming the path."""
    def trap(*args, **kwargs):
        raise AssertionError("work started before the output paths were checked")

    # the lazily imported application packages first: a module first imported while the
    # trap is set would bind it (``from contact.catalogue import resolve_case``) for the
    # rest of the session, and later tests in this process would hit it
    import importlib
    import pkgutil

    import contact.optimize
    import contact.study
    import contact.wear  # (ltca wear imports it before it checks its outputs)

    for pkg in (contact.study, contact.optimize, contact.wear):
        for info in pkgutil.iter_modules(pkg.__path__, pkg.__name__ + "."):
            importlib.import_module(info.name)

    import contact.catalogue
    import contact.qp.benchmark_problems
    import geometry.case
    import geometry.synthesis.basic_design

    for mod, name in ((contact.catalogue, "resolve_case"), (geometry.case, "load_case"),
                      (geometry.synthesis.basic_design, "load_basic"),
                      (contact.qp.benchmark_problems, "standard_problem_set")):
        monkeypatch.setattr(mod, name, trap)
    afile = tmp_path / "afile"
    afile.write_text("x")
    subs = {"missing": str(tmp_path / "missing"), "tmp": str(tmp_path), "file": str(afile)}
    argv = [a.format(**subs) for a in argv]
    assert main(argv) == 2
    err = _refusal(capsys.readouterr().err)
    assert err.count("\n") == 0
    assert err.startswith(f"ltca {argv[0]}: error: {message.format(**subs)}")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


@pytest.mark.parametrize("argv, message", [
    (["geometry", "{bin}.toml", "-o", "{tmp}/g.nc"], "case file '{bin}.toml': not UTF-8 text"),
    (["synthesize", "{bin}.toml", "-o", "{tmp}/c.toml"],
     "basic file '{bin}.toml': not UTF-8 text"),
    (["run", _FM_CASE, "--deviations", "{bin}.csv", "-", "-o", "{tmp}/r.nc"],
     "path: deviation CSV '{bin}.csv' is not UTF-8 text"),
])
def test_binary_input_files_are_refused_in_one_line(argv, message, tmp_path, capsys):
    """A case, basic or deviation file of binary bytes: one line naming the file, no
    UnicodeDecodeError traceback."""
    for ext in (".toml", ".csv"):
        (tmp_path / f"bin{ext}").write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe\x00")
    subs = {"bin": str(tmp_path / "bin"), "tmp": str(tmp_path)}
    argv = [a.format(**subs) for a in argv]
    assert main(argv) == 2
    err = _refusal(capsys.readouterr().err)
    assert err.startswith(f"ltca {argv[0]}: error: {message.format(**subs)}")
    assert err.count("\n") == 0


def test_synthesize_never_writes_its_case_over_the_basic_file(tmp_path, monkeypatch, capsys):
    """Issue 71, unseen (12): ``ltca synthesize my.toml`` run in the directory of
    ``my.toml`` wrote the case to ``my.toml`` (the default, the file's stem) — the user's
    basic file replaced by the case. ``-o`` naming the basic file is refused before any
    work (exit 2, the file untouched); the default there is ``<stem>_case.toml``, and
    ``<stem>.toml`` of this directory elsewhere (as before)."""
    from contact.commands.synthesize import synthesize_output

    basic = tmp_path / "my.toml"
    text = Path(_FM_BASIC).read_text(encoding="utf-8")
    basic.write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    for given in ("my.toml", str(basic), f"{tmp_path}/./my.toml"):
        assert main(["synthesize", "my.toml", "-o", given]) == 2
        err = _refusal(capsys.readouterr().err)
        assert err == (f"ltca synthesize: error: -o: {given!r} is the basic design file "
                       "being read; the case would replace it: give another file (e.g. "
                       "my_case.toml)")
    assert basic.read_text(encoding="utf-8") == text
    assert synthesize_output(Path("my.toml"), None) == Path("my_case.toml")
    assert synthesize_output(basic, None) == Path("my_case.toml")
    assert synthesize_output(basic, "c.toml") == Path("c.toml")
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    assert synthesize_output(basic, None) == Path("my.toml")
    assert synthesize_output(Path(_FM_BASIC), None) == Path("kolivand2009_fm_11x41.toml")


@pytest.mark.parametrize("argv, expected", [
    (["run", "my_case.toml"], "my_case.nc"),
    (["run", "my_case.toml", "--flank", "drive"], "my_case.nc"),
    (["run", "my_case.toml", "--flank", "coast"], "my_case_coast.nc"),
    (["run", "my_case.toml", "--flank", "convex"], "my_case_convex.nc"),
    (["run", "my_case.toml", "--flank", "coast", "-o", "x.nc"], "x.nc"),
    (["duty-cycle", "my_case.toml", "--flank", "coast"], "my_case_coast_duty_cycle.nc"),
    (["utca", "my_case.toml"], "my_case_utca.nc"),
    (["utca", "my_case.toml", "--flank", "coast"], "my_case_coast_utca.nc"),
])
def test_the_coast_flank_default_output_does_not_replace_the_drive_one(argv, expected):
    """``ltca run CASE`` then ``ltca run CASE --flank coast``, every default, wrote both to
    ``CASE.nc``, the coast's over the drive's with the same "wrote" line (issue 71, round
    13, on the unseen 5×39 hypoid): a flank other than the drive's is in the name."""
    from contact.cli import build_parser
    from contact.commands.options import default_output

    args = build_parser().parse_args(argv)
    suffix = {"run": ".nc", "duty-cycle": "_duty_cycle.nc", "utca": "_utca.nc"}[argv[0]]
    assert default_output(args, suffix) == expected


def test_a_command_of_many_analyses_says_before_numba_compiles(monkeypatch):
    """The first ``ltca synthesize`` of a fresh tree printed nothing for 98 s of wall time
    (numba compiling its kernels; issue 71, round 13): a line says so first, where the
    compiled kernels run and numba's cache lacks them, and that the contact analysis's
    compile in the first analysis, after the first lines (round 16); none where they are
    cached or the NumPy path runs."""
    import contact.cli
    import geometry.core.kernels as kernels

    monkeypatch.setenv("LTCA_KERNELS", "numba")
    monkeypatch.setattr(kernels, "cache_ready", lambda name: False)
    note = contact.cli.compile_note()
    assert note is not None and "compiling the numba kernels" in note
    assert "ltca compile" in note
    # numba compiles each kernel at its first call: the contact analysis's only in the
    # first analysis, after the first lines (round 16: 147-163 s of wall time without a
    # line after the development's first; the note had said "before the first lines")
    assert "before the first lines" in note and "within the first analysis" in note
    monkeypatch.setattr(kernels, "cache_ready", lambda name: True)
    assert contact.cli.compile_note() is None
    monkeypatch.setattr(kernels, "cache_ready", lambda name: False)
    monkeypatch.setenv("LTCA_KERNELS", "numpy")
    assert contact.cli.compile_note() is None


@pytest.mark.parametrize("argv, message", [
    (["sweep", "--dE", "0", "-o", "{missing}/s.nc"], "-o: directory '{missing}' does not exist"),
    (["synthesize", _FM_BASIC, "-o", "{basic}"], "-o: '{basic}' is the basic design file"),
    (["sweep", "{missing}/c.toml", "--dE", "0", "-o", "{tmp}/s.nc"],
     "case: no such file '{missing}/c.toml'"),
])
def test_a_refusal_comes_without_the_compile_note(argv, message, tmp_path, monkeypatch,
                                                  capsys):
    """Issue 71 (api83): on a fresh numba cache a command of many analyses printed its
    one-time compile note ("note: compiling the numba kernels …") and then its refusal of a
    bad option, output or input — the note announced a wait that never came. The note is
    now printed when numba starts compiling (``compile_note_when_compiling``): a refusal
    before any kernel runs is the one line alone (read without ``_refusal``'s filter)."""
    import contact.cli
    import geometry.core.kernels as kernels

    monkeypatch.setenv("LTCA_KERNELS", "numba")
    monkeypatch.setattr(kernels, "cache_ready", lambda name: False)  # a fresh cache
    assert contact.cli.compile_note() is not None  # the note the commands would print
    subs = {"missing": str(tmp_path / "missing"), "basic": _FM_BASIC, "tmp": str(tmp_path)}
    argv = [a.format(**subs) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "note: compiling" not in err
    assert err.count("\n") == 0 and err.startswith(
        f"ltca {argv[0]}: error: {message.format(**subs)}")


def test_the_compile_note_is_printed_once_when_numba_starts_compiling(monkeypatch, capsys):
    """The note's other half: the first record of ``COMPILING_LOGGER`` — a compiled module
    handed to a hot loop while numba's cache holds none of its kernels
    (``kernels_module`` → ``announce_compiling``) — prints it, once however many modules
    follow; nothing without a note (``-q``, a warm cache); the logger is as before after."""
    import logging

    import contact.cli
    import geometry.core.kernels as kernels

    envelope = kernels.KERNEL_MODULES[0]
    if kernels.compiled_module(envelope) is None:
        pytest.skip("numba is not installed (the fast extra)")
    logger = logging.getLogger(kernels.COMPILING_LOGGER)
    before = (logger.level, logger.propagate, list(logger.handlers))
    monkeypatch.setattr(kernels, "cache_ready", lambda name: False)
    kernels.announce_compiling.cache_clear()
    with contact.cli.compile_note_when_compiling("note: compiling X") as handler:
        assert capsys.readouterr().err == ""  # nothing before the compiling
        assert kernels.kernels_module(envelope, "numba") is kernels.compiled_module(envelope)
        for name in kernels.KERNEL_MODULES:
            kernels.announce_compiling(name)
        assert handler.printed
    assert capsys.readouterr().err == "note: compiling X\n"
    assert (logger.level, logger.propagate, list(logger.handlers)) == before
    with contact.cli.compile_note_when_compiling(None) as handler:
        logger.info("compiling")
    assert handler is None and "note" not in capsys.readouterr().err
    kernels.announce_compiling.cache_clear()
    monkeypatch.setattr(kernels, "cache_ready", lambda name: True)  # cached: no record
    with contact.cli.compile_note_when_compiling("note: compiling X") as handler:
        assert not kernels.announce_compiling(envelope)
    assert not handler.printed
    kernels.announce_compiling.cache_clear()


def test_ltca_run_prints_a_friction_coefficient_above_0_3_once_on_stderr(tmp_path, capsys):
    """Issue 71 (notchecked83): a model's μ in (MU_CAP, MU_MAX] = (0.3, 1] is kept and
    warned (plugin83); the warning was in ``model_range_warnings`` and the verdict's
    attention, never on the console. ``ltca run`` prints the model's own text once, one
    line on stderr (the table on stdout stays the table); a run without it prints none."""
    from friction.coefficient import register_friction_model, unregister_friction_model

    register_friction_model("mu45", lambda *, slide_to_roll: np.where(
        slide_to_roll > 1.0, 0.45, 0.05), replace=True)
    try:
        code = main(["run", "--friction-model", "mu45", "--rolls-per-cycle", "4",
                     "--segments", "8", "--torque", "250", "--no-rating", "--no-root-stress",
                     "--no-progress", "-o", str(tmp_path / "r.nc")])
    finally:
        unregister_friction_model("mu45")
    out, err = capsys.readouterr()
    assert code == 0
    said = [line for line in err.splitlines() if "friction_coefficient mu up to" in line]
    assert len(said) == 1, err
    assert said[0].startswith("WARNING: mu45: friction_coefficient mu up to 0.45 above 0.3 at ")
    assert "friction_coefficient mu up to" not in out
    # the verdict names it as before (attention: friction extrapolated)
    assert "friction model ran" in out or "friction_extrapolated" in out or "fitted range" in out
    # the bundled model's run at the same settings: no such line
    assert main(["run", "--rolls-per-cycle", "4", "--segments", "8", "--torque", "250",
                 "--no-rating", "--no-root-stress", "--no-progress",
                 "-o", str(tmp_path / "s.nc")]) == 0
    assert "friction_coefficient mu up to" not in capsys.readouterr().err
