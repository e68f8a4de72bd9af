"""What `ltca run` prints after a FAIL verdict (``contact.commands.run.next_steps``).

The lines must be commands a user can paste: each is parsed by the ``ltca`` parser, and the
optimize command's variables are checked against the case by the optimiser's own
validation (:func:`contact.optimize.variables.check_variables`) and centred on the flank's
own setting (read independently from the case). The verdict is replaced by a stated one so
that no analysis runs; that the command turns the reference design's failing coast flank
into ATTENTION is measured in docs/optimize.md ("A flank that fails"), too slow for here.
"""

from __future__ import annotations

import shlex

import numpy as np
import pytest
import xarray as xr

import contact.study.verdicts
from contact.catalogue import resolve_case
from contact.cli import build_parser
from contact.commands.run import BEARING_VARIABLES, next_steps
from contact.optimize.variables import DesignVariable, check_variables
from contact.study.verdicts import Finding, Verdict

CASE = "kolivand2009_fm_11x41_reference"


def _tree(torques=(50.0, 250.0)):
    ltca = xr.Dataset(coords={"torque": np.asarray(torques)})
    return xr.DataTree.from_dict({"/ltca": ltca})


def _verdict(monkeypatch, *findings):
    v = Verdict("analysis", tuple(Finding(*f) for f in findings), ("rating",))
    monkeypatch.setattr(contact.study.verdicts, "verdict", lambda result: v)


def _commands(lines):
    return [shlex.split(line) for line in lines if line.startswith("    ltca ")]


def test_no_step_for_a_verdict_that_is_not_fail(monkeypatch):
    _verdict(monkeypatch, ("attention", "edge_contact", "edge contact 3 %"))
    assert next_steps(_tree(), resolve_case(CASE), None, "coast") == []


@pytest.mark.parametrize("given, flank, member_flank", [
    ("coast", "coast", "convex"), ("drive", "drive", "concave"), (None, "drive", "concave"),
    ("convex", "coast", "convex")])  # the reference design drives on the pinion's concave
def test_a_bearing_failure_names_a_development_of_that_flank(monkeypatch, given, flank,
                                                             member_flank):
    case = resolve_case(CASE)
    assert case.pair.drive_flank == "concave"
    _verdict(monkeypatch, ("fail", "implausible", "plastic contact 5.7 %"))
    lines = next_steps(_tree(), case, None, given)
    commands = _commands(lines)
    assert [c[1] for c in commands] == ["vh-check", "optimize"]
    parser = build_parser()
    for c in commands:  # the ltca parser accepts them as printed
        parser.parse_args(c[1:])
    opt = commands[1]
    assert opt[opt.index("--flank") + 1] == flank
    assert opt[opt.index("--torque") + 1: opt.index("--torque") + 3] == ["50", "250"]
    variables = {}
    for i, tok in enumerate(opt):
        if tok == "--variable":
            variables[opt[i + 1]] = (float(opt[i + 2]), float(opt[i + 3]))
    assert set(variables) == set(BEARING_VARIABLES) | {"tip_relief", "root_relief"}
    check_variables(case, member_flank, [DesignVariable(n, lo, hi)
                                         for n, (lo, hi) in variables.items()])
    # centred on the flank's own settings (4 significant digits printed)
    blade = getattr(case.pinion, member_flank).blade
    machine = getattr(case.pinion, member_flank).machine
    own = {"point_radius": blade.point_radius, "ratio_of_roll": machine.ratio_of_roll}
    for name, value in own.items():
        lo, hi = variables[name]
        assert (lo + hi) / 2 == pytest.approx(value, rel=1e-3)
        assert hi - lo == pytest.approx(2 * BEARING_VARIABLES[name], rel=1e-2)


def test_a_capacity_failure_names_the_rating(monkeypatch):
    _verdict(monkeypatch, ("fail", "rating", "S_F 1.1 below 1.3"))
    lines = next_steps(_tree((500.0,)), resolve_case(CASE), "my_case.toml", "drive")
    commands = _commands(lines)
    assert commands == [["ltca", "rate", "my_case.toml", "--torque", "500"]]
    build_parser().parse_args(commands[0][1:])


def test_a_scuffing_failure_names_the_oil_temperature_and_roughness(monkeypatch):
    """Issue 71: the e-axle hypoid (11x39, Sigma 80 deg, 8000 rpm) failed its coast run on
    S_B 0.98 alone of the scuffing side, and nothing said what moves it: the line names
    the inputs of ISO/TS 6336-20's flash and scuffing temperatures, and the same run with
    them is a command the parser accepts (placeholders for the user's values)."""
    _verdict(monkeypatch, ("fail", "scuffing", "scuffing safety S_B 0.982 at 327.6 N m"))
    lines = next_steps(_tree((49.1, 327.6)), resolve_case(CASE), "e.toml", "coast")
    assert "oil" in lines[0] and "smoother flanks" in lines[0] and "FZG" in lines[0]
    commands = _commands(lines)
    assert len(commands) == 1 and commands[0][:3] == ["ltca", "run", "e.toml"]
    args = build_parser().parse_args(commands[0][1:])
    assert args.flank == "coast" and args.torque == [49.1, 327.6]
    case = resolve_case(CASE)  # the example: 20 K below the case's inlet, half its Rq
    assert args.temperature == case.operating.temperature - 20.0
    assert args.roughness == case.operating.roughness / 2.0


def test_a_scuffing_failure_is_not_answered_by_the_bearings_optimisation(monkeypatch):
    """Issue 71, Round 37: the truck hypoid 8x45 FAILed on S_B 0.93 alone, with a bearing
    attention beside it (the pattern at the gear's heel and tip, 0.07 % edge share); the
    verdict printed `ltca optimize` first, whose objective and constraints hold no S_B: run
    as printed it kept its start and the FAIL. A scuffing FAIL gets the operation's remedy
    alone; a bearing finding that fails itself still gets the bearing's steps."""
    edge = ("attention", "edge_contact", "at 1750 N m: the loaded pattern reaches the gear's "
            "heel and tip; edge contact carries 0.07 % of the torque")
    scuff = ("fail", "scuffing", "scuffing safety S_B 0.927 at 1750 N m below 1")
    _verdict(monkeypatch, scuff, edge)
    lines = next_steps(_tree((262.5, 1750.0)), resolve_case(CASE), "case.toml", "drive")
    commands = _commands(lines)
    assert [c[1] for c in commands] == ["run"], lines
    assert lines[0].startswith("  next, scuffing:")
    assert "`ltca optimize` (the bearing) does not model it" in lines[0]
    args = build_parser().parse_args(commands[0][1:])
    assert args.torque == [262.5, 1750.0]
    # a failing bearing finding beside it: both answered, each by its own step
    _verdict(monkeypatch, scuff, ("fail", "edge_contact", "edge contact 5 %"))
    both = [c[1] for c in _commands(next_steps(_tree((262.5, 1750.0)), resolve_case(CASE),
                                               "case.toml", "drive"))]
    assert both == ["vh-check", "optimize", "run"]
    # a FAIL the bearing can change (here the LTE spread's plasticity check) keeps the
    # optimisation for a bearing attention beside it, as before
    _verdict(monkeypatch, ("fail", "implausible", "plastic contact 5.7 %"), edge)
    assert "optimize" in [c[1] for c in _commands(
        next_steps(_tree(), resolve_case(CASE), None, "drive"))]
