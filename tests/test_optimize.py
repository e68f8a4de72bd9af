"""Machine-setting optimisation (``contact.optimize``, ``ltca optimize``).

The claims are checked on what the optimiser writes, by an independent analysis: the
written case file is loaded and analysed by :func:`contact.run_analysis` and its edge load
share compared with the stated limits. The analysis is coarse (8 rolls per cycle, 10
segments, a 4 × 10 Ritz shell) and runs in this process (``scheduler="synchronous"``) to
keep the file within the CI budget; the physics is the full model's.

Start design: the bundled 11×41 case under the seed's Table 3.1 misalignment (ΔE = −0.15,
ΔP = 0.12 mm), where the pinion-tip edge carries 7–10 % of the torque at 50–250 N·m; the
variable is the tip relief (0–40 µm), which takes the load off that edge.
"""

from __future__ import annotations

import dataclasses
import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.catalogue import SEED_TABLE_3_1, resolve_case
from contact.cli import main as ltca
from contact.ltca import LTCAOptions
from contact.optimize import (
    DesignVariable,
    OptimizeProblem,
    constraint_names,
    optimize,
    problem_from_table,
)
from contact.pipeline import run_analysis
from contact.study.summary import point_summary
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf

BASIC = Path(__file__).resolve().parents[1] / "cases" / "basic" / "kolivand2009_fm_11x41.toml"

OPTIONS = LTCAOptions(rolls_per_cycle=8, segments=10, n_height=4, n_face=10)
TORQUE = (50.0, 250.0)
#: limits the start violates (edge shares 7 % and 10 % there)
MAX_EDGE = (0.03, 0.06)


def _case():
    # the deliberately edge-loaded start: the long-bearing synthesis without relief (the
    # default case is the reference design this tool found from it)
    return dataclasses.replace(resolve_case("kolivand2009_fm_11x41"),
                               misalignment=SEED_TABLE_3_1["misalignment"])


def _problem(**kw):
    return OptimizeProblem(**({"torque": TORQUE, "max_edge_share": MAX_EDGE,
                               "options": OPTIONS} | kw))


def _edge_share(case):
    tree = run_analysis(case, list(TORQUE), options=OPTIONS, deviations=False,
                        geometry=False, root_stress=False)
    return point_summary(tree, case)["edge_load_share"]


def test_optimum_meets_the_limits_in_the_written_case(tmp_path):
    """``ltca optimize`` from the edge-loaded start writes a case whose independent
    analysis meets the edge-share limits it was given; the objective of the result does
    not exceed the start's; every evaluation is in the ``/optimize`` log with its
    variables, terms, constraints and objective; the case carries its provenance.

    Tolerance of the independent check: the same analysis at the same settings is
    deterministic, so the limits are checked as stated (no margin)."""
    case_file = tmp_path / "start.toml"
    case_file.write_text(_case().to_toml(), encoding="utf-8")
    out = tmp_path / "opt.toml"
    rc = ltca(["optimize", str(case_file), "-o", str(out), "--variable", "tip_relief", "0",
               "40", "--torque", *map(str, TORQUE), "--max-edge-share", *map(str, MAX_EDGE),
               "--rolls-per-cycle", "8", "--segments", "10", "--ritz-modes", "4", "10",
               "--max-evaluations", "5",
               "--scheduler", "synchronous", "--no-progress"])
    assert rc == 0
    written = load_case(out)
    share = _edge_share(written)
    assert np.all(share <= np.asarray(MAX_EDGE)), share
    prov = written.extra["optimize"]
    assert prov["feasible"] is True
    assert prov["objective_result"] <= prov["objective_start"]
    assert prov["variables"]["tip_relief"]["start"] == 0.0
    assert written.pinion.concave.blade.flankrem_angle > 0.0
    # the toolkit's reader restores the text coordinates (stored as CF label variables)
    log = read_netcdf(out.with_suffix(".nc"), tree=True)["/optimize"].to_dataset()
    assert log.sizes["evaluation"] >= 3
    for name in ("variable_value", "objective_term", "constraint_value", "objective",
                 "edge_load_share", "lte_peak_to_peak", "pressure_max_flank"):
        assert "units" in log[name].attrs and "long_name" in log[name].attrs
    assert list(log["constraint"].values) == list(constraint_names(
        _problem().with_case(written)))
    # the written result is the logged best; the start is evaluation 0
    assert float(log["objective"].min()) == pytest.approx(prov["objective_result"])
    assert float(log["objective"].sel(evaluation=0)) == pytest.approx(prov["objective_start"])


def test_infeasible_limits_are_reported_with_the_best_design():
    """A flank pressure limit no design can meet (1 MPa) is reported as infeasible, not
    raised, and the best design found comes back with its (violated) constraints."""
    res = optimize(_case(), [DesignVariable("tip_relief", 0.0, 40.0)],
                   _problem(max_flank_pressure=(1.0,)), method="powell", max_evaluations=2,
                   scheduler="synchronous")
    assert not res.feasible
    assert res.best_evaluation.objective <= res.start_evaluation.objective
    g = res.log["constraint_value"].sel(evaluation=res.best_evaluation.index)
    assert float(g.max()) > 0
    assert res.log["feasible"].values.sum() == 0


@pytest.mark.parametrize("variables, match", [
    ([DesignVariable("cradle_spin", 0.0, 1.0)], "unknown variable 'cradle_spin'"),
    ([DesignVariable("ratio_of_roll", -1.0, 5.0)], r"optimize.bounds.ratio_of_roll: -1 1 "
                                                   "lies outside the setting's valid range"),
    ([DesignVariable("tilt", -1.0, 95.0)], "optimize.bounds.tilt: 95 deg"),
    ([DesignVariable("tip_relief", 0.0, 500.0)], "optimize.bounds.tip_relief: 500 um"),
    ([DesignVariable("tip_relief", 10.0, 40.0)], "start value 0 um lies outside"),
    ([DesignVariable("tip_relief", 40.0, 0.0)], "low < high"),
    ([DesignVariable("ellipse_length", 0.5, 0.8)], "'ellipse_length' is a synthesis input; "
                                                   "start from the basic design file"),
])
def test_bad_variables_are_refused_before_any_analysis(variables, match, monkeypatch):
    """Unknown names and bounds outside a setting's valid range fail at once, naming the
    variable (no analysis runs: run_analysis is replaced by a failing stub)."""
    import contact.pipeline

    def boom(*a, **k):
        raise AssertionError("an analysis ran")

    monkeypatch.setattr(contact.pipeline, "run_analysis", boom)
    with pytest.raises(InputError, match=match):
        optimize(_case(), variables, _problem(), scheduler="synchronous")


def test_optimize_table_is_read_and_checked():
    """The ``[optimize]`` table's fields map onto the problem (file units), one value
    applies to every torque, and unknown fields or wrong lengths are named."""
    problem, run = problem_from_table({
        "torque": [50, 500], "max_edge_share": 0.05, "max_flank_pressure": [1500, 2000],
        "misalignments": [{"dE": -0.15, "dP": 0.12}, {"dSigma": 0.01}],
        "variables": {"tip_relief": [0, 30]}, "method": "powell",
        "start": {"tip_relief": 12.5}, "rolls_per_cycle": 40})
    assert problem.max_edge_share == (0.05, 0.05)
    assert problem.options.rolls_per_cycle == 40 and problem.options.segments == 24
    # command-line analysis options are laid over the table's sampling, not instead of it
    over = problem_from_table({"rolls_per_cycle": 40}, options={"segments": 12})[0].options
    assert (over.rolls_per_cycle, over.segments) == (40, 12)
    assert run["start"] == {"tip_relief": 12.5}
    assert problem.misalignments[1].delta_Sigma == pytest.approx(math.radians(0.01))
    assert run["variables"] == {"tip_relief": (0.0, 30.0)} and run["method"] == "powell"
    with pytest.raises(InputError, match=r"optimize\.colour"):
        problem_from_table({"colour": 1})
    with pytest.raises(InputError, match=r"optimize\.rolls_per_cycle: must be an integer"):
        problem_from_table({"rolls_per_cycle": 40.5})
    with pytest.raises(InputError, match=r"rolls_per_cycle"):
        problem_from_table({"rolls_per_cycle": 2})
    with pytest.raises(InputError, match=r"optimize\.max_flank_pressure: give one value"):
        problem_from_table({"torque": [50, 250, 500], "max_flank_pressure": [1, 2]})


def test_command_line_torques_keep_the_tables_per_torque_limits():
    """``--torque`` among the table's own torques keeps the per-torque limits the table
    gives them (the bundled reference design's table is for 50, 250, 500 N·m: `ltca
    optimize ... --torque 50 250` must not be refused for its three-value limits); an
    option given replaces the table's; a torque the table has no limit for is refused,
    naming the field and the option that gives it."""
    table = {"torque": [50, 250, 500], "max_edge_share": [0.01, 0.05, 0.04],
             "max_flank_pressure": [math.inf, math.inf, 2000.0],
             "lte_mean_range": [[73.3, 165.0], [193.3, 435.0], [400.0, 900.0]],
             "torque_weights": [1, 2, 3]}
    problem = problem_from_table(table, torque=(50.0, 500.0))[0]
    assert problem.torque == (50.0, 500.0)
    assert problem.max_edge_share == (0.01, 0.04)
    assert problem.max_flank_pressure == (math.inf, 2000.0)
    assert problem.lte_mean_range == ((73.3, 165.0), (400.0, 900.0))
    assert problem.torque_weights == (1, 3)
    given = problem_from_table(table, torque=(50.0, 250.0), max_edge_share=(0.02,))[0]
    assert given.max_edge_share == (0.02, 0.02)
    with pytest.raises(InputError, match=r"optimize\.max_edge_share: .*not for 300 N·m: "
                                         r"give --max-edge-share"):
        problem_from_table(table, torque=(50.0, 300.0))
    with pytest.raises(InputError, match=r"optimize\.lte_mean_range: .*edit the \[optimize\]"):
        problem_from_table({"torque": [50, 250], "lte_mean_range": [[1, 2], [3, 4]]},
                           torque=(100.0,))


def test_cli_variables_keep_only_their_own_table_start(tmp_path, monkeypatch):
    """``--variable`` replaces the table's variables, so the table's ``[optimize.start]``
    values go with them: a start is kept for a variable still varied inside the bounds
    given, the others start from the case (the reference design's basic file starts
    te_level, 2C and H1, which `--variable tip_relief ...` does not vary: it was refused as
    "not one of the variables")."""
    import contact.optimize

    seen = {}

    def fake(case, variables, problem, **kw):  # records the call, stops before any work
        seen.update(kw, names=[v.name for v in variables])
        raise InputError("stop")

    monkeypatch.setattr(contact.optimize, "optimize", fake)
    basic = BASIC.with_name("kolivand2009_fm_11x41_reference.toml")
    assert ltca(["optimize", str(basic), "-o", str(tmp_path / "o.toml"), "--torque", "50", "250",
              "--variable", "tip_relief", "0", "60", "--variable", "root_relief", "0", "5",
              "--flank", "coast"]) != 0  # the fake's stop
    assert seen["names"] == ["tip_relief", "root_relief"]
    # the table starts tip_relief 16.5 (kept) and root_relief 7.09 (outside 0-5: dropped)
    assert seen["start"] == {"tip_relief": pytest.approx(16.508817284513)}


def test_cli_without_variables_names_the_ones_it_takes(tmp_path, capsys):
    """A case with no ``[optimize.variables]`` table (every case ``ltca synthesize`` writes)
    and no ``--variable`` is refused before any analysis, naming the variables ``--variable``
    takes with their units and an example (round 18: the refusal named none)."""
    from contact.optimize import RELIEF_VARIABLES
    from geometry.synthesis.correction import SETTING_VARIABLES

    assert ltca(["optimize", "kolivand2009_fm_11x41", "-o", str(tmp_path / "o.toml")]) != 0
    err = capsys.readouterr().err
    assert "variables: give --variable NAME LOW HIGH" in err
    for name, var in SETTING_VARIABLES.items():
        assert f"{name} [{var.unit}]" in err
    for name, unit in RELIEF_VARIABLES.items():
        assert f"{name} [{unit}]" in err
    assert "path_angle" not in err  # a synthesis input only where a basic file starts it
    assert "--variable tip_relief 0 40" in err and not (tmp_path / "o.toml").exists()


def test_cli_checks_the_output_before_work(tmp_path, capsys):
    """An output path in a missing directory is refused before the case is read."""
    rc = ltca(["optimize", "no-such-case", "-o", str(tmp_path / "missing" / "x" / "o.toml"),
               "--log", str(tmp_path / "nodir" / "log.nc"), "--variable", "tip_relief", "0",
               "1"])
    assert rc != 0
    assert "--log" in capsys.readouterr().err


@cache
def _basic():
    from geometry.synthesis.basic_design import load_basic

    return load_basic(BASIC)


def test_synthesis_inputs_are_variables_of_a_basic_design_start():
    """Started from a basic design, the flank prescriptions are variables: their start
    values are the basic file's (file units: deg, µrad, µm), a design re-synthesises the
    basic design with them — the same case, setting for setting, as ``ltca synthesize`` of
    the changed prescriptions (both are :func:`geometry.synthesis.case_synthesis.synthesize`; 1e-12
    relative, the synthesis is deterministic) — and a setting variable is applied on top
    of the re-synthesised flank, whose tip plane is then put back on the root cone
    (:func:`geometry.synthesis.tip_plane.tip_plane_on_root_cone`, as the synthesis' step 8:
    a helical motion tilts the root line). The committed case is the basic file's
    synthesis, so it is the start."""
    from contact.optimize import case_at, start_values
    from geometry.synthesis.basic_design import with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    basic = _basic()
    case = _case()
    names = ["ellipse_length", "te_level", "path_angle", "tip_relief", "H1"]
    x0 = start_values(case, "concave", names, basic=basic)
    np.testing.assert_allclose(x0, [0.75, 30.0, -55.0, 0.0, 0.0], atol=1e-12)
    x = [0.7, 25.0, -58.0, 12.0, -0.1]
    got = case_at(case, "concave", names, x, basic=basic)
    want = synthesize(with_flank_options(basic, "concave", dict(zip(names[:4], x[:4],
                                                                     strict=False))))[0]
    from geometry.synthesis.correction import SETTING_VARIABLES, tool_with_values
    from geometry.synthesis.tip_plane import tip_plane_on_root_cone

    b = tool_with_values(want.pinion.concave, {"H1": -0.1 * SETTING_VARIABLES["H1"].scale})
    placed = tip_plane_on_root_cone(b.blade, b.machine, want.pinion.blank, want.pinion.hand)
    b = dataclasses.replace(b, blade=placed.blade, machine=placed.settings)
    a = got.pinion.concave
    for field in ("radial_setting", "cradle_angle", "ratio_of_roll", "sliding_base",
                  "blank_offset"):
        assert getattr(a.machine, field) == pytest.approx(getattr(b.machine, field),
                                                          rel=1e-12)
    assert a.machine.helical_motion[0] == pytest.approx(-0.1)  # H1 [mm/rad], set on top
    assert a.blade.flankrem_angle == pytest.approx(b.blade.flankrem_angle, rel=1e-12)
    assert a.blade.flankrem_angle > 0
    assert got.misalignment == case.misalignment and got.name == case.name
    assert got.pinion.convex.machine.radial_setting == pytest.approx(
        want.pinion.convex.machine.radial_setting, rel=1e-12)


@pytest.mark.parametrize("variable, match", [
    (DesignVariable("ellipse_length", 0.5, 0.95), r"optimize.bounds.ellipse_length: 0.95 1 "
                                                  r"lies outside the prescription's valid "
                                                  r"range \(synthesis.concave.ellipse_length"),
    (DesignVariable("te_level", -5.0, 40.0), "optimize.bounds.te_level: -5 urad"),
])
def test_bad_synthesis_bounds_are_refused_before_any_synthesis(variable, match):
    """A bound outside a prescription's range is refused naming the variable and the
    prescription's own range, before a design is synthesised."""
    from contact.optimize import check_variables

    with pytest.raises(InputError, match=match):
        check_variables(_case(), "concave", [variable], basic=_basic())


def test_start_values_replace_the_cases_and_are_checked(monkeypatch):
    """``start`` (the ``[optimize.start]`` table) replaces a variable's start value: the
    first design analysed is the case at those values. A start for a name that is not a
    variable, or outside the bounds, is refused before any analysis."""
    import contact.pipeline

    seen = []

    def fake(case, *a, **k):  # records the first design's blade and stops the run
        seen.append(case.pinion.concave.blade.flankrem_angle)
        raise RuntimeError("stop")

    monkeypatch.setattr(contact.pipeline, "run_analysis", fake)
    res = optimize(_case(), [DesignVariable("tip_relief", 0.0, 40.0)], _problem(),
                   method="powell", max_evaluations=2, scheduler="synchronous",
                   start={"tip_relief": 25.0})
    assert res.start[0] == 25.0 and seen[0] > 0  # a relieved blade was analysed first
    with pytest.raises(InputError, match=r"optimize.start.H1: not one of the variables"):
        optimize(_case(), [DesignVariable("tip_relief", 0.0, 40.0)], _problem(),
                 scheduler="synchronous", start={"H1": 0.1})
    with pytest.raises(InputError, match="start value 50 um lies outside"):
        optimize(_case(), [DesignVariable("tip_relief", 0.0, 40.0)], _problem(),
                 scheduler="synchronous", start={"tip_relief": 50.0})


def test_an_optimised_case_names_its_basic_file_and_log_relative_to_itself(tmp_path):
    """``ltca optimize`` records ``basic_design`` and ``log_file`` relative to the case file
    it writes, as the bundled cases do (tests/test_docs_site.py checks those resolve beside
    the installed case): the case and its inputs can move together."""
    from contact.commands.optimize import _shown

    out = tmp_path / "cases" / "mine.toml"
    assert _shown(tmp_path / "cases" / "optimize" / "mine.nc", out) == "optimize/mine.nc"
    assert _shown(tmp_path / "cases" / "basic" / "mine.toml", out) == "basic/mine.toml"
    assert _shown(tmp_path / "elsewhere.toml", out) == "../elsewhere.toml"
