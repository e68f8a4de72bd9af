"""An analysis without a certified contact solution is a failure (issue 64 item 1).

A plug-in backend that fails every solve stands for a solver that never converges: the
analysis still writes its file, with the status and the reason at the root, but ``ltca
run`` exits 1 (not 0), a study point and a duty-cycle bin are *failed* (status 2, with the
reason), and no efficiency is computed from the missing forces (it was a loss-free 100 %).

The analyses are the default case at one torque on a coarse mesh cycle (4 rolls per
cycle, 8 segments): each takes a few seconds.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from contact.cli import main
from contact.ltca import LTCAOptions
from contact.ltca.summary import ANALYSIS_STATUS, certification
from contact.qp.solvers import register_backend, unregister_backend
from geometry.core.io import read_netcdf

#: what a user must never see
RAW = re.compile(r"Traceback|KeyError|ValueError|matmul")

COARSE = ["--rolls-per-cycle", "4", "--segments", "8", "--torque", "250", "--no-rating",
          "--no-root-stress", "--no-progress"]


def _never_converges(problem):
    """A backend that fails every solve, as an iterative solver that never converges."""
    raise RuntimeError("iteration limit reached")


def _fails_first_call():
    """A backend whose first solve fails (the first roll's) and every later one is the
    reference solver's."""
    calls = {"n": 0}

    def solve(problem):
        from contact.qp import solve_contact

        calls["n"] += 1
        if calls["n"] == 1:
            raise RuntimeError("iteration limit reached")
        sol = solve_contact(problem, "active_set")
        return sol.force, sol.rotation

    return solve


@pytest.fixture
def failing_solver():
    register_backend("never_converges", _never_converges, replace=True)
    yield "never_converges"
    unregister_backend("never_converges")


def test_certification_reads_found_per_torque():
    """The status is the one the ``found`` flags give, by the definition: every roll of
    every torque certified → ok; a torque with none → failed; else uncertified."""
    import xarray as xr

    def ltca(found):
        found = np.asarray(found, np.int8)
        return xr.Dataset({"found": (("torque", "roll"), found),
                           "status": (("torque", "roll"),
                                      np.where(found > 0, "solved", "failed: x"))},
                          coords={"torque": [50.0, 250.0][:found.shape[0]]})

    assert certification(ltca([[1, 1], [1, 1]])).status == "ok"
    assert certification(ltca([[1, 1], [1, 1]])).reason == ""
    part = certification(ltca([[1, 0], [1, 1]]))
    assert part.status == "uncertified"
    assert "T_p 50 N m (1 of 2 roll positions certified)" in part.reason
    assert "roll 1: failed: x" in part.reason
    failed = certification(ltca([[1, 0], [0, 0]]))
    assert failed.status == "failed"   # one torque without any certified roll decides
    assert failed.reason.startswith("no certified contact solution at T_p 250 N m "
                                    "(0 of 2 roll positions certified)")
    assert list(failed.certified) == [1, 0]
    assert ANALYSIS_STATUS == ("ok", "uncertified", "failed")


def test_the_api_returns_a_failed_analysis_with_its_status_and_no_efficiency(failing_solver):
    from contact.pipeline import run_analysis

    tree = run_analysis(None, 250.0, options=LTCAOptions(rolls_per_cycle=4, segments=8,
                                                          solver=failing_solver))
    assert tree.attrs["analysis_status"] == "failed"
    reason = tree.attrs["analysis_status_reason"]
    # the reason names the torque, the count and the backend with what it raised
    assert reason.startswith("no certified contact solution at T_p 250 N m (0 of 8 roll "
                             "positions certified)"), reason
    assert "backend 'never_converges' raised RuntimeError: iteration limit reached" in reason
    fr = tree["friction"].to_dataset()
    # no forces, no efficiency: NaN with the reason, never the loss-free 100 %
    assert np.all(np.isnan(fr["efficiency"].values))
    assert math.isnan(float(fr["efficiency_mean"].values[0]))
    assert fr["efficiency_mean"].attrs["comment"].startswith(
        "NaN where the loaded contact has no certified solution")
    # the verdict fails it for the same reason
    from contact.study.verdicts import verdict

    v = verdict(tree)
    assert v.severity == "fail"
    assert any(f.check == "certification" and "no certified contact solution at 250 N·m"
               in f.reason for f in v.findings)


def test_ltca_run_with_a_solver_that_fails_every_roll_exits_1(failing_solver, tmp_path,
                                                              capsys):
    out = tmp_path / "r.nc"
    code = main(["run", *COARSE, "--solver", failing_solver, "-o", str(out)])
    captured = capsys.readouterr()
    assert code == 1, captured.out
    err = captured.err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("ltca run: error: analysis failed: no "
                                               "certified contact solution at T_p 250 N m")
    assert not RAW.search(captured.err)
    # the file is written, and says so itself
    tree = read_netcdf(out, tree=True)
    assert tree.attrs["analysis_status"] == "failed"
    assert "never_converges" in tree.attrs["analysis_status_reason"]
    # the summary row of the torque prints no LTE, pressure or efficiency (it printed
    # LTE nan, p_max flank 0 and efficiency 100.00): "-", and the count certified
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in captured.out.splitlines() if line.startswith("|")]
    cells = next(r for r in rows if r[0] == "250")
    row = " | ".join(cells)
    assert cells[1:10] == ["-"] * 9 and cells[10] == "0/8" and cells[11] == "-", row
    assert "100.00" not in captured.out


def test_a_partly_certified_run_is_uncertified_and_exits_1(tmp_path, capsys):
    register_backend("fails_first", _fails_first_call(), replace=True)
    try:
        code = main(["run", *COARSE, "--solver", "fails_first", "-o", str(tmp_path / "r.nc")])
    finally:
        unregister_backend("fails_first")
    err = capsys.readouterr().err
    assert code == 1
    assert "ltca run: error: analysis uncertified: roll positions without a certified " \
           "contact solution at T_p 250 N m" in err
    tree = read_netcdf(tmp_path / "r.nc", tree=True)
    found = tree["ltca"]["found"].values
    assert 0 < found.sum() < found.size   # some certified, some not: uncertified
    assert tree.attrs["analysis_status"] == "uncertified"


def test_a_study_point_without_certified_contact_is_failed(failing_solver):
    from contact.catalogue import resolve_case
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs

    shared = StudyInputs(resolve_case(None), (250.0,), speed=(1500.0,),
                         options=LTCAOptions(rolls_per_cycle=4, segments=8,
                                             solver=failing_solver))
    res = analyse_point(shared, 0, {})
    assert res.status == 2   # failed, not "uncertified" (1) and never "ok"
    assert res.reason.startswith("no certified contact solution at T_p 250 N m")
    assert np.all(np.isnan(res.summary["efficiency"]))


def test_a_duty_cycle_bin_without_certified_contact_is_failed(failing_solver):
    from contact.catalogue import resolve_case
    from contact.study.duty_cycle import DutyInputs, analyse_bin
    from contact.study.duty_cycle_inputs import DutyCycle

    duty = DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e6])
    shared = DutyInputs(resolve_case(None), duty,
                        LTCAOptions(rolls_per_cycle=4, segments=8, solver=failing_solver))
    ds = analyse_bin(shared, 0)
    assert int(ds["status"].values[0]) == 2
    assert str(ds["reason"].values[0]).startswith("no certified contact solution")
    assert math.isnan(float(ds["efficiency"].values[0]))


def test_ltca_mesh_interface_without_certified_contact_exits_1(failing_solver, tmp_path,
                                                              capsys):
    out = tmp_path / "m.csv"
    code = main(["mesh-interface", "--solver", failing_solver, "--rolls-per-cycle", "4",
                 "--segments", "8", "--torque", "250", "--no-progress", "-o", str(out)])
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert err.startswith("ltca mesh-interface: error: analysis failed: no certified contact "
                          "solution at T_p 250 N m") and err.endswith("m.csv holds what was "
                                                                      "found")
    assert out.exists()


def test_an_efficiency_map_torque_without_certified_contact_is_failed(failing_solver,
                                                                     tmp_path, capsys):
    from contact.study.efficiency import efficiency_map

    emap = efficiency_map(None, [250.0], [1500.0, 3000.0],
                          options=LTCAOptions(rolls_per_cycle=4, segments=8,
                                              solver=failing_solver))
    assert emap["analysis_status"].values.tolist() == [ANALYSIS_STATUS.index("failed")]
    assert emap["analysis_status"].attrs["flag_meanings"] == "ok uncertified failed"
    assert emap.attrs["analysis_status_reason"].startswith(
        "no certified contact solution at T_p 250 N m")
    assert np.all(np.isnan(emap["efficiency"].values))   # was 98.5 % of no contact at all


def test_a_duty_cycle_with_a_failed_bin_ends_in_analysis_failed():
    import xarray as xr

    from contact.catalogue import resolve_case
    from contact.errors import AnalysisFailedError
    from contact.study.duty_cycle import _durability
    from contact.study.duty_cycle_inputs import DutyCycle

    duty = DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e6])
    bins = xr.Dataset({"status": ("bin", np.array([2], np.int8)),
                       "reason": ("bin", np.array(["no certified contact solution at T_p "
                                                   "250 N m (0 of 8 roll positions "
                                                   "certified)"], dtype=object))})
    with pytest.raises(AnalysisFailedError, match=r"^duty_cycle bin 0: its analysis failed "
                                                  r"\(no certified contact solution at T_p "
                                                  r"250 N m"):
        _durability(resolve_case(None), duty, bins)


def test_a_failed_bin_of_the_illustrative_spectrum_names_its_deflection_table():
    """Issue 71, unseen (12): a bin of the bundled spectrum whose misalignment separates
    the flanks (a 16x16 spiral bevel at Sigma 60 deg of d_e2 120 mm: its illustrative
    deflections at 3.5 N m) said only the bounds of ``ltca run``'s --dE/--dP options;
    the message now says the misalignment is the ILLUSTRATIVE deflection table's at the
    bin's torque and how to give the design's own. A reason of another kind gets no
    such sentence."""
    import xarray as xr

    from contact.catalogue import resolve_case
    from contact.errors import AnalysisFailedError
    from contact.study.duty_cycle import _durability
    from contact.study.duty_cycle_inputs import example_duty_cycle

    duty = example_duty_cycle(13.9, bins=2)
    why = ("InputError: misalignment: separates the flanks (the pinion meets the gear "
           "inside both blanks at too few points: 8 valid ease-off nodes, at least 16 needed)")
    bins = xr.Dataset({"status": ("bin", np.array([0, 2], np.int8)),
                       "reason": ("bin", np.array(["", why], dtype=object))})
    with pytest.raises(AnalysisFailedError, match=r"^duty_cycle bin 1: its analysis failed "
                       r"\(InputError: misalignment: separates .*; no damage without every "
                       r"bin; bin 1's misalignment is the \[duty_cycle\] deflection table's "
                       r"at its 3.475 N m plus the case's own — the ILLUSTRATIVE table of "
                       r"`ltca duty-cycle` without --duty .*\(--duty FILE, docs/cases.md\)$"):
        _durability(resolve_case(None), duty, bins)
    bins["reason"] = ("bin", np.array(["", "no certified contact solution"], dtype=object))
    with pytest.raises(AnalysisFailedError, match=r"no certified contact solution\); no "
                                                  r"damage without every bin$"):
        _durability(resolve_case(None), duty, bins)
