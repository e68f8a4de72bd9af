"""The API's defaults are the command's ("API = CLI", issue 71 items 3/4, branch api82).

A script following the docs calls the public function with its defaults where a user of the
command types the command with its defaults; both must analyse the same thing and reach the
same verdict:

* ``contact.run_duty_cycle`` computes the root stress (and with it the bending side) by
  default, as ``ltca duty-cycle`` (``--root-stress`` on); before, the API's default was off
  and its verdict lacked the ``bending`` check;
* ``contact.example_duty_cycle`` is the spectrum ``ltca duty-cycle`` runs for a case
  without a ``[duty_cycle]`` table: its top bin at the flank's top torque;
* ``contact.vh_check`` at the case's first ``[operating]`` torque, as ``ltca vh-check``
  (before: 50 N·m whatever the case).

The FE model of the root stress is replaced by a coarse one in both paths (the same for the
API and the command: the test is of their defaults, not of the FE model), and the LTCA is
sampled coarsely, so that the test runs in ~20 s.
"""

from __future__ import annotations

import dataclasses
import inspect

import numpy as np
import pytest
import xarray as xr

import contact
from contact.compliance.fe import CACHE_ENV, FEOptions
from geometry.core.errors import InputError

#: a coarse FE model (tests/test_root_stress.py's): a few seconds per member
COARSE = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                   rim_divisions=2, fillet_divisions=2, load_nu=5, load_nv=4)

#: one bin of the default case, as a ``[duty_cycle]`` file the command reads (--duty)
DUTY_TOML = """\
[duty_cycle]
name = "one bin"
torque = [250.0]
speed = [1500.0]
hours = [100.0]
"""


@pytest.fixture
def coarse_fe(monkeypatch, tmp_path):
    """Every root stress of the process on :data:`COARSE`, cached under ``tmp_path``."""
    import contact.ltca.root_stress as rs

    monkeypatch.setenv(CACHE_ENV, str(tmp_path / "fe_cache"))
    monkeypatch.setattr(rs, "case_fe_options", lambda case: COARSE)


def _numeric(ds: xr.Dataset) -> dict[str, np.ndarray]:
    return {k: np.asarray(v.values, float) for k, v in ds.data_vars.items()
            if v.dtype.kind in "fiub"}


def test_run_duty_cycle_default_is_the_command(coarse_fe, tmp_path, monkeypatch, capsys):
    """``run_duty_cycle(case, duty, run)`` with its defaults and ``ltca duty-cycle`` with its
    defaults (same sampling, in this process) give the same bins and the same verdict:
    the root stress on in both (the bending side available), every numeric variable equal
    (rtol 1e-12: the same computation in the same process, so equal but for the order of
    floating-point sums — identical in practice)."""
    from contact.cli import main

    monkeypatch.chdir(tmp_path)
    duty_file = tmp_path / "duty.toml"
    duty_file.write_text(DUTY_TOML, encoding="utf-8")
    out = tmp_path / "cli.nc"
    code = main(["duty-cycle", "--duty", str(duty_file), "--rolls-per-cycle", "4",
                 "--segments", "8", "--scheduler", "synchronous", "--no-progress",
                 "-o", str(out)])
    assert code == 0, capsys.readouterr().err
    cli = contact.read_netcdf(out)["duty_cycle"].to_dataset()
    api = contact.run_duty_cycle(
        None, contact.read_duty_cycle(duty_file),
        contact.StudyRun(options=contact.LTCAOptions(rolls_per_cycle=4, segments=8),
                         scheduler="synchronous"))
    assert api.attrs["bending"] == cli.attrs["bending"] == "available"
    assert "root_life" in api and "root_life" in cli
    a, c = _numeric(api), _numeric(cli)
    timing = {k for k in a if "time" in k}
    assert set(a) - timing == set(c) - timing
    for name in sorted(set(a) - timing):
        np.testing.assert_allclose(a[name], c[name], rtol=1e-12, atol=0, equal_nan=True,
                                   err_msg=name)
    va, vc = contact.verdict(api), contact.verdict(cli)
    assert va.severity == vc.severity
    assert "bending" in va.checks and "bending" in vc.checks
    assert [(f.check, f.severity) for f in va.findings] == [
        (f.check, f.severity) for f in vc.findings]


def test_run_duty_cycle_root_stress_settings():
    """``root_stress`` given and ``StudyRun.root_stress`` set agree or are refused, naming
    both; a value of another type is refused naming ``root_stress`` (before any work)."""
    from contact.study.duty_cycle import duty_root_stress

    assert duty_root_stress(None, False) is True  # the command's default
    assert duty_root_stress(False, False) is False
    assert duty_root_stress(None, COARSE) == COARSE  # the run's setting is read
    assert duty_root_stress(COARSE, COARSE) == COARSE
    with pytest.raises(InputError, match=r"^root_stress, run\.root_stress: two different"):
        duty_root_stress(False, True)
    duty = contact.DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e6])
    with pytest.raises(InputError, match=r"^root_stress: must be None, True, False or a "):
        contact.run_duty_cycle(None, duty, contact.StudyRun(scheduler="synchronous"),
                               root_stress="yes")


def test_example_duty_cycle_is_public_and_the_commands_spectrum():
    """``contact.example_duty_cycle`` is exported, documented with units and a source,
    and its top bin is at the flank's top torque as ``ltca duty-cycle`` takes it: the
    default case's 500 N·m (its ``[operating]`` torques 50/250/500), and on a coast flank
    with a coast design torque of 200 N·m (design torque 250) that 200 N·m — the rule of
    ``contact.pipeline.flank_torques``: a torque at or above the design torque is taken at
    the coast design torque. The proportions are the module's table, exactly (1e-12)."""
    assert "example_duty_cycle" in contact.__all__
    doc = inspect.getdoc(contact.example_duty_cycle)
    for word in ("[N·m]", "[rpm]", "[h]", "Source", "Raises"):
        assert word in doc, word
    from contact.study.duty_cycle_inputs import EXAMPLE_BINS

    d = contact.example_duty_cycle()
    assert d.illustrative and d.n_bins == len(EXAMPLE_BINS) == 7
    np.testing.assert_allclose(d.torque, [500.0 * r[0] for r in EXAMPLE_BINS], rtol=1e-12)
    np.testing.assert_allclose(d.pinion_speed, [3000.0 * r[1] for r in EXAMPLE_BINS],
                               rtol=1e-12)
    assert d.hours.sum() == pytest.approx(2000.0, rel=1e-12)

    case = contact.resolve_case(None)
    rating = {**case.extra.get("rating", {}), "design_torque": 250.0,
              "coast_design_torque": 200.0}
    coast_case = dataclasses.replace(case, extra={**case.extra, "rating": rating})
    assert contact.example_duty_cycle(case=coast_case).torque[-1] == 500.0  # drive
    coast = contact.example_duty_cycle(case=coast_case, flank="coast")
    assert coast.torque[-1] == pytest.approx(200.0, rel=1e-12)
    assert contact.example_duty_cycle(100.0, case=coast_case).torque[-1] == 100.0
    with pytest.raises(InputError, match=r"^flank: must be one of drive, coast"):
        contact.example_duty_cycle(flank="heel")
    with pytest.raises(InputError, match=r"^max_torque: must be a finite number > 0"):
        contact.example_duty_cycle(-1.0)
    with pytest.raises(InputError, match=r"^bins: must be in \[1, 7\]"):
        contact.example_duty_cycle(bins=8)


def test_the_commands_default_spectrum_is_example_duty_cycle(monkeypatch, tmp_path, capsys):
    """``ltca duty-cycle`` without ``--duty`` on a case without ``[duty_cycle]`` runs
    exactly ``contact.example_duty_cycle(case=…, flank=…)`` (its work replaced: the spectrum
    handed to it is compared bin by bin)."""
    from contact.cli import main

    seen = {}

    class Stop(Exception):
        pass

    def stop(case, duty, run=None, **kw):
        seen["duty"], seen["kw"] = duty, kw
        raise Stop

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("contact.study.duty_cycle.run_duty_cycle", stop)
    with pytest.raises(Stop):
        main(["duty-cycle", "--flank", "coast", "-o", str(tmp_path / "o.nc"),
              "--no-progress"])
    expected = contact.example_duty_cycle(flank="coast")
    for field in ("torque", "pinion_speed", "revolutions"):
        np.testing.assert_array_equal(getattr(seen["duty"], field), getattr(expected, field))
    assert seen["kw"] == {"root_stress": True}


def test_vh_check_default_torque_is_the_commands():
    """``contact.vh_check``'s torque defaults to the case's first ``[operating]`` torque
    (``ltca vh-check``'s default), 50 N·m on the default case; the signature says so."""
    from contact.study.vh_check import default_vh_torque

    case = contact.resolve_case(None)
    assert default_vh_torque(case) == float(case.operating.torque[0]) == 50.0
    light = dataclasses.replace(case, operating=dataclasses.replace(
        case.operating, torque=(7.0, 46.9)))
    assert default_vh_torque(light) == 7.0
    assert inspect.signature(contact.vh_check).parameters["torque"].default is None


def test_rate_load_capacity_default_method_is_the_cases(tmp_path, monkeypatch, capsys):
    """``contact.rate_load_capacity(case)`` rates by the case's ``[rating] method`` as
    ``ltca rate CASE`` does (before: ISO 10300 whatever the case named). On the AGMA 2003
    Annex E case with ``method = "agma2003"`` written into its ``[rating]`` table, the API's
    default, the API with the method named and the command's file hold the same /rating
    (identical: the same computation)."""
    from contact.cli import main

    case = contact.resolve_case("agma2003_d19_annex_e")
    named = dataclasses.replace(case, extra={
        **case.extra, "rating": {**case.extra["rating"], "method": "agma2003"}})
    path = tmp_path / "agma_named.toml"
    path.write_text(named.to_toml(), encoding="utf-8")
    api = contact.rate_load_capacity(path)
    assert api.attrs["rating_method"] == "agma2003"
    xr.testing.assert_identical(api, contact.rate_load_capacity(path, method="agma2003"))
    monkeypatch.chdir(tmp_path)
    assert main(["rate", str(path), "-o", str(tmp_path / "rate.nc")]) == 0
    capsys.readouterr()
    cli = contact.read_netcdf(tmp_path / "rate.nc")["rating"].to_dataset()
    for name in api.data_vars:
        np.testing.assert_array_equal(np.asarray(cli[name].values),
                                      np.asarray(api[name].values), err_msg=name)
    # a case naming none: ISO 10300, as before
    assert contact.rate_load_capacity(case).attrs["rating_method"] == "iso10300"


def _same_study(api: xr.Dataset, cli: xr.Dataset) -> None:
    """The same variables and every numeric one equal (rtol 1e-12: the same computation in
    the same process, equal but for the order of floating-point sums), timings apart."""
    a, c = _numeric(api), _numeric(cli)
    timing = {k for k in set(a) | set(c) if "time" in k}
    assert set(a) - timing == set(c) - timing
    for name in sorted(set(a) - timing):
        np.testing.assert_allclose(a[name], c[name], rtol=1e-12, atol=0, equal_nan=True,
                                   err_msg=name)
    for dim in ("torque", "delta_E"):
        if dim in api.coords:
            np.testing.assert_array_equal(api[dim].values, cli[dim].values)


def test_sweep_and_sample_defaults_are_the_commands(coarse_fe, tmp_path, monkeypatch, capsys):
    """Issue 71 (api83): ``contact.sweep`` and ``contact.sample`` with their defaults ran at
    250 N·m without the root stress (and ``sample`` with other draws each call) where
    ``ltca sweep`` and ``ltca tolerance`` with theirs run the case's ``[operating]``
    torques with the root stress and seed 0. Now the function's result equals the
    command's file: two points of the default case (its torques 50, 250, 500 N·m), the
    same sampling, in this process on the NumPy kernels (so both runs take one path)."""
    import scipy.stats

    from contact.cli import main

    monkeypatch.setenv("LTCA_KERNELS", "numpy")
    monkeypatch.chdir(tmp_path)
    run = contact.StudyRun(options=contact.LTCAOptions(rolls_per_cycle=4),
                           scheduler="synchronous")
    case = contact.resolve_case(None)
    out = tmp_path / "sweep.nc"
    assert main(["sweep", "--dE", "0,0.05", "--rolls-per-cycle", "4", "--scheduler",
                 "synchronous", "--no-progress", "-o", str(out)]) == 0, \
        capsys.readouterr().err
    cli = contact.read_netcdf(out)
    api = contact.sweep(None, delta_E=[0.0, 0.05], run=run)
    assert api["torque"].values.tolist() == list(case.operating.torque) == [50.0, 250.0, 500.0]
    assert "root_stress_max" in api and "root_stress_max" in cli
    assert np.all(np.isfinite(api["root_stress_max"].values))
    _same_study(api, cli)

    out = tmp_path / "tolerance.nc"
    assert main(["tolerance", "--dE", "normal:0:0.02", "-n", "2", "--torque", "250",
                 "--rolls-per-cycle", "4", "--scheduler", "synchronous", "--no-progress",
                 "-o", str(out)]) == 0, capsys.readouterr().err
    cli = contact.read_netcdf(out)
    api = contact.sample(None, {"delta_E": scipy.stats.norm(0.0, 0.02)}, 2, torque=250.0,
                         run=run)
    np.testing.assert_array_equal(api["delta_E"].values, cli["delta_E"].values)  # seed 0
    assert "root_stress_max" in api and "root_stress_max" in cli
    _same_study(api, cli)


def test_study_run_root_stress_default_and_settings():
    """``StudyRun.root_stress`` defaults to None (not set): a sweep or a sample computes the
    root stress (``study_root_stress`` True, the commands' ``--root-stress``), the duty cycle
    its own default; False and an FEOptions are kept; anything else is refused, named."""
    from contact.study.duty_cycle import duty_root_stress

    assert contact.StudyRun().root_stress is None
    assert contact.StudyRun().study_root_stress is True
    assert contact.StudyRun(root_stress=False).study_root_stress is False
    assert contact.StudyRun(root_stress=COARSE).study_root_stress == COARSE
    assert duty_root_stress(None, None) is True and duty_root_stress(False, None) is False
    with pytest.raises(InputError, match=r"^root_stress: must be None, True, False or a "):
        contact.StudyRun(root_stress="on")
    assert inspect.signature(contact.sample).parameters["seed"].default == 0
    case = contact.resolve_case("iso10300_30_sample1")  # its one [operating] torque
    from contact.study import study_inputs

    assert study_inputs(case).torque == tuple(case.operating.torque) == (300.0,)


def test_optimize_problem_torques_default_to_the_cases():
    """``OptimizeProblem()`` optimised at 50, 250, 500 N·m whatever the case; ``ltca
    optimize`` at the case's (the flank's, ``flank_torques``). The default is now no torque,
    taken from the case by ``with_case`` (which the optimiser calls): the ISO/TR 10300-30
    sample 1 at its one 300 N·m, the default case at its 50, 250, 500 N·m (the case files'
    ``[operating]`` tables are the reference). Without torques a per-torque field takes one
    value; several, or an ``lte_mean_range``, are refused naming the field."""
    from contact.optimize import OptimizeProblem
    from contact.pipeline import flank_torques

    sample1 = contact.resolve_case("iso10300_30_sample1")
    assert OptimizeProblem().torque == ()
    assert OptimizeProblem().with_case(sample1).torque == tuple(sample1.operating.torque) \
        == (300.0,)
    default = contact.resolve_case(None)
    assert OptimizeProblem().with_case(default).torque == (50.0, 250.0, 500.0)
    coast = OptimizeProblem(flank="coast").with_case(default)
    assert coast.torque == flank_torques(default, "coast")[0]
    one = OptimizeProblem(max_edge_share=(0.05,)).with_case(default)
    assert one.max_edge_share == (0.05, 0.05, 0.05)
    assert OptimizeProblem(torque=(100.0,)).with_case(default).torque == (100.0,)
    with pytest.raises(InputError, match=r"^optimize\.max_edge_share: give one value, or "
                                         r"torque="):
        OptimizeProblem(max_edge_share=(0.05, 0.1))
    with pytest.raises(InputError, match=r"^optimize\.lte_mean_range: one \(low, high\) "):
        OptimizeProblem(lte_mean_range=((0.0, 50.0),))


def test_sample_takes_the_commands_number_of_draws():
    """Issue 71 (plugin83): ``contact.sample`` required ``n`` where ``ltca tolerance`` defaults
    to 256; now the function's default is the parser's (read from the parser itself)."""
    from contact.cli import build_parser
    from contact.study.sample_size import DEFAULT_SAMPLES

    args = build_parser().parse_args(["tolerance", "--dE", "normal:0:0.02"])
    assert inspect.signature(contact.sample).parameters["n"].default == args.n \
        == DEFAULT_SAMPLES == 256
    assert inspect.signature(contact.sample).parameters["n"].kind \
        is inspect.Parameter.POSITIONAL_OR_KEYWORD  # sample(case, dists, 64) still works


@pytest.mark.parametrize("n", [1, 0, -3, 10_000_001])
def test_sample_and_tolerance_refuse_the_same_numbers_of_draws_alike(n, capsys):
    """Issue 71 (plugin83): the command's parser accepted ``-n 1`` (count(1, 10^7)), printed
    its header and then failed on the function's ``n: must be an integer >= 2``; the
    function had no upper bound. Now both accept [2, 10^7] and refuse anything else before
    any work with the same text: the API after ``n: ``, the command after ``argument -n: ``."""
    import scipy.stats

    from contact.cli import main

    said = f"must be an integer in [2, 10000000], got {n}"
    with pytest.raises(InputError) as info:
        contact.sample(None, {"delta_E": scipy.stats.norm(0.0, 0.02)}, n)
    assert str(info.value) == f"n: {said}"
    with pytest.raises(SystemExit) as exit_:  # the parser's refusal: argparse's exit 2
        main(["tolerance", "--dE", "normal:0:0.02", "-n", str(n), "--no-progress"])
    out, err = capsys.readouterr()
    assert exit_.value.code == 2 and out == ""  # no header: refused by the parser
    assert err.strip().splitlines()[-1] == f"ltca tolerance: error: argument -n: {said}"


def test_the_smallest_number_of_draws_is_accepted_by_both():
    """n = 2, the least both accept: the draws the command makes (``draw_points`` is what
    ``ltca tolerance`` prints the range of) are those of ``sample``'s (seed 0), and the
    parser takes ``-n 2`` (the full 2-draw study of both is run by
    test_sweep_and_sample_defaults_are_the_commands)."""
    import scipy.stats

    from contact.cli import build_parser
    from contact.study import draw_points

    args = build_parser().parse_args(["tolerance", "--dE", "normal:0:0.02", "-n", "2"])
    assert args.n == 2
    draws = draw_points({"delta_E": scipy.stats.norm(0.0, 0.02)}, 2, seed=0)
    assert draws["delta_E"].shape == (2,) and np.all(np.isfinite(draws["delta_E"]))
