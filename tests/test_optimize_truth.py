"""An optimiser that tells the truth (issue 71, item 3): ``ltca optimize`` starts from the
very case it is given, says "constraints met" only where ``ltca run`` of its written case
meets them, prints one line per design off a terminal, never writes a case the FE model
cannot mesh; the verdict's next steps never print a command whose result they have seen
fail, and a failed duty cycle prints its next steps.

Every claim is checked against an independent :func:`contact.run_analysis` of the case (the
analysis ``ltca run`` makes), not against the optimiser's own numbers.
"""

from __future__ import annotations

import dataclasses
from types import MappingProxyType

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import SEED_TABLE_3_1, resolve_case
from contact.cli import main as ltca
from contact.ltca import LTCAOptions
from contact.optimize import DesignVariable, OptimizeProblem, optimize
from contact.optimize.objective import METRICS, evaluate_design, score
from contact.optimize.run import SharedDesign, _pinion_flank
from contact.optimize.variables import _measured_relief, case_at, start_values
from contact.pipeline import run_analysis
from contact.study.summary import point_summary
from contact.study.verdicts import verdict
from geometry.case import load_case

#: the optimiser's coarse sampling in these tests (ltca run's is LTCAOptions())
COARSE = LTCAOptions(rolls_per_cycle=8, segments=10, n_height=4, n_face=10)


def _ltca_run(case, torque, flank=None):
    """What ``ltca run`` computes of the LTCA (its defaults; the root stress and the rating
    do not feed back into the contact): the summary metrics per torque."""
    tree = run_analysis(case, list(torque), flank=flank, deviations=False, geometry=False,
                        root_stress=False)
    return point_summary(tree, case)


def test_the_start_row_is_ltca_run_of_the_case_given():
    """Design 0 of an optimisation over settings and relief of the default case (whose
    relief starts at 0.859 of the way to the ends, not the optimiser's former 0.5) is the
    case itself: its flank peak, LTE and edge share equal ``ltca run``'s of the case.

    Tolerance: none beyond 1e-9 relative — the same case and the same deterministic
    analysis (the optimiser used to rebuild the blade's rems at relief_start 0.5, which
    moved the e-axle's flank peaks of issue 71 from 1072/1444/1832 to 1336/1947/2479 MPa).
    A relief variable moved by 2 µm moves the relief measured on the blade by 2 µm at the
    blade's own rem corner, and the other relief not at all (1e-6 µm: the rem angle's
    root-finding)."""
    case = resolve_case(None)
    names = ("point_radius", "tip_relief", "root_relief")
    flank = _pinion_flank(case, "drive")
    x0 = start_values(case, flank, names)
    assert case_at(case, flank, names, x0, relief_start=0.5) is case
    torque = (50.0, 500.0)
    problem = OptimizeProblem(torque=torque).with_case(case)
    ev = evaluate_design(SharedDesign(case, problem, flank, names, 0.5, None, x0), 0, x0)
    assert ev.status == 0, ev.reason
    ref = _ltca_run(case, torque)
    for k in ("pressure_max_flank", "lte_peak_to_peak", "lte_mean", "edge_load_share",
              "pattern_centre_v"):
        np.testing.assert_allclose(ev.metrics[k][0], ref[k], rtol=1e-9, err_msg=k)
    moved = case_at(case, flank, names, x0 + np.array([0.0, 0.0, 2.0]), relief_start=0.5)
    tip, root = _measured_relief(moved, flank)
    assert tip == pytest.approx(x0[1], abs=1e-6) and root == pytest.approx(x0[2] + 2.0,
                                                                          abs=1e-6)
    blade, own = moved.pinion.flank(flank).blade, case.pinion.flank(flank).blade
    assert blade.toprem_height == own.toprem_height  # the corner kept
    assert blade.flankrem_angle == pytest.approx(own.flankrem_angle, rel=1e-9)  # re-solved


def _edge_case():
    # the long-bearing synthesis under the seed's Table 3.1 misalignment: edge-loaded
    return dataclasses.replace(resolve_case("kolivand2009_fm_11x41"),
                               misalignment=SEED_TABLE_3_1["misalignment"])


def test_constraints_met_agree_with_ltca_run_of_the_written_case(tmp_path, capsys):
    """``ltca optimize`` ranked at a coarse sampling confirms its design at ``ltca run``'s
    before it says "constraints met": the written case's ``[optimize.confirmed]`` metrics
    are those of an independent ``ltca run``-equivalent analysis of the written file, and
    its ``feasible`` is whether that analysis meets the constraints. Off a terminal (as
    under pytest) it prints one line per design and per confirmation on standard error.

    Tolerance: 1e-6 absolute, the table's rounding of the metrics to 6 decimals (the same
    analysis of the same case, read back from TOML, whose floats round-trip exactly)."""
    torque, max_edge = (50.0, 250.0), (0.03, 0.06)
    start = tmp_path / "start.toml"
    start.write_text(_edge_case().to_toml(), encoding="utf-8")
    out = tmp_path / "opt.toml"
    rc = ltca(["optimize", str(start), "-o", str(out), "--variable", "tip_relief", "0", "40",
               "--torque", *map(str, torque), "--max-edge-share", *map(str, max_edge),
               "--rolls-per-cycle", "8", "--segments", "10", "--ritz-modes", "4", "10",
               "--method", "powell", "--max-evaluations", "3", "--confirm", "2",
               "--scheduler", "synchronous"])
    assert rc == 0
    captured = capsys.readouterr()
    prov = load_case(out).extra["optimize"]
    conf = prov["confirmed"]
    design_lines = [ln for ln in captured.err.splitlines()
                    if ln.startswith("optimize: design ") and "ltca run's sampling" not in ln]
    assert len(design_lines) == prov["evaluations"]
    assert design_lines[0].startswith("optimize: design 1/") and "(start)" in design_lines[0]
    confirm_lines = [ln for ln in captured.err.splitlines() if "ltca run's sampling" in ln]
    assert len(confirm_lines) == conf["designs_confirmed"] >= 1
    written = load_case(out)
    from contact.chain import AnalysisChain

    tree = run_analysis(written, list(torque), deviations=False,
                        steps=AnalysisChain.analysis().without("geometry", "root_stress"))
    ref = point_summary(tree, written)
    for k in ("pressure_max_flank", "lte_peak_to_peak", "edge_load_share", "lte_mean"):
        np.testing.assert_allclose(np.asarray(conf[k])[0], ref[k], rtol=1e-9, atol=1e-6,
                                   err_msg=k)
    # its verdict and the reasons of an ATTENTION are the independent analysis's (round 27:
    # a confirmed ATTENTION used to be printed without its reason)
    v = verdict(tree)
    assert conf["verdict"] == v.severity
    attention = list(dict.fromkeys(f.reason for f in v.findings if f.severity == "attention"))
    assert conf["verdict_attention"] == attention
    if v.severity == "attention":
        assert all(r in captured.err for r in attention)
    problem = OptimizeProblem(torque=torque, max_edge_share=max_edge)
    _, g, _ = score(problem, {k: np.asarray(ref[k], float)[None, :] for k in METRICS})
    met = bool(np.all(g <= 0))
    assert prov["feasible"] is met and conf["constraints_met"] is met
    head = captured.out.splitlines()[0]
    assert ("all constraints met, confirmed at ltca run's sampling" in head) is met


def test_a_design_the_fe_model_cannot_mesh_is_never_written(tmp_path, monkeypatch, capsys):
    """A design whose pinion tooth the FE model cannot mesh (the mapping's Jacobian check,
    as ``ltca duty-cycle`` met it in issue 71) is rejected with a line saying so, the next
    designs are tried, and with none meshing no case is written (exit 1), only the log."""
    import contact.compliance.fe.solid as solid
    from geometry.core.errors import LTCAError

    def no_mesh(case, member, options=None):
        raise LTCAError("mesh mapping: element 996 (parameter centre [1 2 3]) is inverted "
                        "or collapsed; refine the mesh or check the geometry")

    monkeypatch.setattr(solid, "build_tooth_solid", no_mesh)
    start = tmp_path / "start.toml"
    start.write_text(_edge_case().to_toml(), encoding="utf-8")
    out = tmp_path / "opt.toml"
    rc = ltca(["optimize", str(start), "-o", str(out), "--variable", "tip_relief", "0", "40",
               "--torque", "50", "--rolls-per-cycle", "8", "--segments", "10",
               "--ritz-modes", "4", "10", "--method", "powell", "--max-evaluations", "2",
               "--scheduler", "synchronous", "--no-progress"])
    text = capsys.readouterr().out
    assert rc == 1 and not out.exists() and out.with_suffix(".nc").exists()
    assert "rejected: the FE model cannot mesh its pinion tooth (mesh mapping: element 996" \
        in text
    assert "no case written" in text


def _fail_tree(torque=(44.7, 298.3)):
    lt = xr.Dataset(coords={"torque": ("torque", np.asarray(torque))},
                    attrs={"material_pinion": "case_carburised_steel",
                           "material_gear": "case_carburised_steel"})
    return xr.DataTree.from_dict({"/ltca": lt})


def _optimised(case, names, command="ltca optimize start.toml --flank drive"):
    table = {"source_case": case.name, "flank": "drive", "command": command,
             "variables": {n: {"start": 0.0, "result": 0.0, "unit": "1"} for n in names}}
    return dataclasses.replace(case, extra=MappingProxyType({**case.extra,
                                                             "optimize": table}))


def test_next_steps_never_print_the_optimisation_whose_result_failed(monkeypatch):
    """Under a FAIL on the flank pressure (above the static strength) ``ltca run`` prints
    an ``ltca optimize`` that limits the flank peak to that strength; of a case that is
    that optimisation's result (its ``[optimize]`` table), a wider one (2C, H1); of the
    wider one's result, no ``ltca optimize`` at all but the V-H check and the rating."""
    import contact.study.verdicts as verdicts
    from contact.commands.run import next_steps
    from contact.study.verdicts import Finding, Verdict

    fail = Verdict("analysis", (Finding("fail", "flank_pressure", "flank peak pressure "
                                        "2736 MPa above the static strength 2400 MPa"),),
                   ("flank_pressure",))
    monkeypatch.setattr(verdicts, "verdict", lambda tree: fail)
    case = resolve_case(None)
    tree = _fail_tree()
    first = next_steps(tree, case, "c.toml", None)
    cmd = [ln for ln in first if ln.startswith("    ltca optimize")]
    assert len(cmd) == 1 and "--max-flank-pressure 2400" in cmd[0]
    assert "--variable point_radius" in cmd[0] and "2C" not in cmd[0]
    base = ("point_radius", "blade_angle", "ratio_of_roll", "tip_relief", "root_relief")
    again = next_steps(tree, _optimised(case, base), "c.toml", None)
    cmd2 = [ln for ln in again if ln.startswith("    ltca optimize")]
    assert len(cmd2) == 1 and cmd2[0] != cmd[0]
    assert "--variable 2C" in cmd2[0] and "--variable H1" in cmd2[0]
    assert any("does not answer the finding" in ln for ln in again)
    last = next_steps(tree, _optimised(case, (*base, "2C", "H1")), "c.toml", None)
    assert not any(ln.startswith("    ltca optimize") for ln in last)
    assert "    ltca rate c.toml --torque 44.7 298.3" in last
    assert "    ltca vh-check c.toml --flank drive" in last
    # an optimisation of the other flank does not count for this one
    coast = _optimised(case, base)
    coast.extra["optimize"]["flank"] = "coast"
    assert next_steps(tree, coast, "c.toml", None) == first


def test_a_failed_duty_cycle_prints_its_next_steps():
    """The bin that does most of the damage at the first point to fail is named with its
    share, and ``ltca run``/``ltca rate`` at its torque printed (issue 71: 80 % of the
    pinion's damage from the 150 N·m bin, no next step printed); nothing without a FAIL."""
    from contact.commands.next_steps import duty_cycle_lines

    fd = np.zeros((3, 2, 4, 5))
    fd[:, 0, 2, 3] = [0.05, 0.8, 0.15]  # pinion, the failing point
    fd[:, 1, 1, 1] = [0.1, 0.1, 0.1]
    ds = xr.Dataset({"torque": ("bin", [40.0, 150.0, 300.0]),
                     "flank_damage": (("bin", "member", "u", "v"), fd),
                     "damage": ("member", [1.0, 0.3])},
                    coords={"member": ["pinion", "gear"]})
    lines = duty_cycle_lines(ds, "e.toml", "coast", ["damage"])
    assert "bin 1 (150 N m) does 80 % of the pinion's flank damage" in lines[0]
    assert lines[1:] == ["    ltca run e.toml --flank coast --torque 150",
                         "    ltca rate e.toml --torque 150"]
    assert duty_cycle_lines(ds, "e.toml", None, []) == []


def test_optimize_api_progress_lines_and_confirmation(monkeypatch):
    """The API's ``progress`` callable gets one line per design, then one per confirmed
    design; ``confirm=0`` confirms nothing and leaves ``feasible`` the optimiser's."""
    lines: list[str] = []
    res = optimize(_edge_case(), [DesignVariable("tip_relief", 0.0, 40.0)],
                   OptimizeProblem(torque=(50.0,), options=COARSE), method="powell",
                   max_evaluations=2, scheduler="synchronous", progress=lines.append,
                   confirm=0)
    assert res.confirmation is None and res.confirmations == ()
    assert len(lines) == res.log.sizes["evaluation"]
    assert all(ln.startswith(f"optimize: design {i + 1}/") for i, ln in enumerate(lines))


def test_a_limit_met_only_at_the_coarse_sampling_is_not_reported_met():
    """A limit set between the start's flank peak (or LTE p-p) at the optimiser's coarse
    sampling and at ``ltca run``'s — which the coarse one under-samples — is met by every
    design the optimiser ranks (2C varied by ±1e-9 1/rad: the start's flank), and met by
    none as ``ltca run`` analyses them: the result says "not met", names the constraint,
    and the headline does not say "constraints met"."""
    from contact.commands.optimize import _outcome

    case, torque = _edge_case(), (250.0,)
    coarse = point_summary(run_analysis(case, list(torque), options=COARSE,
                                        deviations=False, geometry=False, root_stress=False),
                           case)
    full = _ltca_run(case, torque)
    key, name = next((k, n) for k, n in (("pressure_max_flank", "flank_pressure_250Nm"),
                                         ("lte_peak_to_peak", "lte_pp_high_250Nm"))
                     if float(coarse[k][0]) < float(full[k][0]) - 1e-3)
    limit = 0.5 * (float(coarse[key][0]) + float(full[key][0]))
    kw = ({"max_flank_pressure": (limit,)} if key == "pressure_max_flank"
          else {"lte_peak_to_peak_range": (0.0, limit)})
    (c0,) = start_values(case, "concave", ("2C",))
    res = optimize(case, [DesignVariable("2C", c0 - 1e-9, c0 + 1e-9)],
                   OptimizeProblem(torque=torque, options=COARSE, **kw), method="powell",
                   max_evaluations=2, scheduler="synchronous", confirm=2)
    assert bool(res.log["feasible"].values.all())  # the optimiser's own ranking: all met
    assert not res.feasible and res.confirmation is not None
    assert name in res.confirmation.violated
    assert len(res.confirmations) == 2
    assert "NOT every constraint met at ltca run's sampling" in _outcome(res, 2)


def test_a_confirmed_attention_says_why():
    """A confirmation whose constraints are met but whose verdict is ATTENTION names the
    ATTENTION findings in its line (round 27: the FH 6×43 at Σ 80° printed "ltca run's
    verdict ATTENTION" alone, its pattern reaching the gear's tip); a FAIL names its FAIL
    findings only, a PASS nothing. Exact strings: the line is built from the findings."""
    from contact.optimize.confirm import Confirmation

    def conf(severity, findings=(), attention=()):
        return Confirmation(2, np.zeros(1), {}, np.zeros(0), (), severity, findings, "", 1.0,
                            False, attention)

    tip = "at 80.1 N m: the loaded pattern reaches the gear's tip"
    assert conf("attention", attention=(tip,)).summary() == (
        f"constraints met; ltca run's verdict ATTENTION ({tip})")
    assert conf("fail", ("S_F 1.1 below 1.3",), (tip,)).summary() == (
        "constraints met; ltca run's verdict FAIL (S_F 1.1 below 1.3)")
    assert conf("pass").summary() == "constraints met; ltca run's verdict PASS"


def _stand_in_evals(objectives):
    from contact.optimize.objective import Evaluation

    return [Evaluation(i, np.array([float(i)]), 0, "", {}, np.zeros(0), np.zeros(1), o, 0.0)
            for i, o in enumerate(objectives)]


def _stand_in_confirm(severities):
    """confirm_design's stand-in: design i met every constraint with verdict
    ``severities[i]``."""
    from contact.optimize.confirm import Confirmation

    def confirm(shared, ev, **kw):
        return Confirmation(ev.index, ev.x, {}, np.zeros(0), (), severities[ev.index], (),
                            "", 0.0, False, ())
    return confirm


@pytest.mark.parametrize(("severities", "written", "worse"), [
    # the start PASS, the better-ranked designs ATTENTION: the start is written (round 27's
    # FH 6x43 at Sigma 80 deg, PASS as synthesised, was written ATTENTION)
    (("pass", "attention", "attention"), 0, True),
    # the start ATTENTION, the best ranked PASS: that design is written
    (("attention", "attention", "pass"), 2, False),
    # the start FAIL, an ATTENTION design is better: written
    (("fail", "attention", "fail"), 2, False),
])
def test_a_design_worse_than_the_start_by_the_verdict_is_not_written(
        monkeypatch, severities, written, worse):
    """The optimiser confirms the start as ``ltca run`` analyses it and accepts no design
    whose verdict is worse than the start's; where every better-ranked design is worse, the
    start is the design written and the headline says why. Exact: the rule compares
    severities only (the stand-in's designs all meet their constraints)."""
    import contact.optimize.confirm as confirm_module
    from contact.commands.optimize import _outcome
    from contact.optimize.run import _confirmed

    monkeypatch.setattr(confirm_module, "confirm_design", _stand_in_confirm(severities))
    # objectives: design 2 ranks first, then 1, then the start
    evals = _stand_in_evals([3.0, 2.0, 1.0])
    lines: list[str] = []
    e, conf, tried = _confirmed(None, evals, 5, lines.append)
    assert e.index == written and conf.index == written
    assert lines[0].startswith("optimize: the start (design 1) at ltca run's sampling")
    assert len(tried) == len(lines)  # one line per confirmation, the start once
    assert any(c.worse_than_start for c in tried) is worse
    assert conf.accepted and not conf.worse_than_start
    if worse:
        assert all("worse than the start's PASS: not accepted" in ln for ln in lines[1:])

        class _R:  # the result fields _outcome reads
            confirmation, confirmations, case, feasible = conf, tried, object(), True
        assert "the start case is written" in _outcome(_R, 5)
