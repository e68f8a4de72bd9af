"""What the developments of one basic design share (contact.optimize.development_shared)
and the analyses the kept teeth read back (KeptTeeth.analysed, issue 71: the Formate gear
developed in full after a foreseen cut's stop repeated the stopped development's search
and check, ≈ 90 s of CPU on the FM hypoid 9x31 at Sigma 75 deg)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from contact.optimize import development as dev
from contact.optimize.development_evaluate import COARSE_LTCA, KeptTeeth, analyse_design
from contact.optimize.development_shared import SharedDevelopments, kept_for

DESIGNS = Path(__file__).resolve().parent / "data" / "designs"


def _case():
    from geometry.case import load_case

    return load_case(DESIGNS / "pc_hypoid_10x43_unrelieved.toml")


def _basic():
    from geometry.synthesis.basic_design import load_basic

    return load_basic(DESIGNS / "pc_hypoid_10x43.toml")


@pytest.fixture(scope="module")
def analysed():
    """The unrelieved passenger-car hypoid's coarse LTCA at 50 / 330 N m (≈ 2 s CPU):
    with fresh kept teeth (the reference, an analysis of its own) and with teeth that then
    analyse the same inputs again and other inputs."""
    case = _case()
    own = analyse_design(case, [50.0, 330.0], teeth=KeptTeeth(), pinion_key=("a",))
    teeth = KeptTeeth()
    first = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    return case, own, teeth, first


def test_the_same_inputs_are_read_back_as_their_own_analysis(analysed):
    """A design analysed again with the same case, torques, options, pinion key and flank
    is read back (no LTCA: ``analyses_reused`` counts it), and what is read back is the
    analysis of its own: equal to an independent analysis with new kept teeth to the
    bit (tolerance 0: the same deterministic computation, no seeds carried over outside
    a WarmSeeds block)."""
    case, own, teeth, first = analysed
    again = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    assert teeth.analyses_reused == 1
    assert again[0].keys() == own[0].keys()
    for k, v in again[0].items():
        np.testing.assert_array_equal(v, own[0][k], err_msg=k)
    assert again[1] == own[1] == first[1]


def test_other_inputs_are_analysed(analysed, monkeypatch):
    """Another torque, pinion key, misalignment or option is a new analysis (the LTCA
    runs: counted by a wrapper of it), never one read back."""
    from contact import ltca as ltca_module

    case, _, teeth, _ = analysed
    calls = []
    real = ltca_module.loaded_tca

    def counted(*a, **kw):
        calls.append(1)
        return real(*a, **kw)

    monkeypatch.setattr(ltca_module, "loaded_tca", counted)
    before = teeth.analyses_reused
    from geometry.pair.assembly import Misalignment

    analyse_design(case, [50.0, 331.0], teeth=teeth, pinion_key=("a",))
    analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("b",))
    analyse_design(case, [50.0, 330.0], Misalignment(0.05, 0.0, 0.0, 0.0), teeth=teeth,
                   pinion_key=("a",))
    analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",),
                   options=dataclasses.replace(
                       COARSE_LTCA, rolls_per_cycle=COARSE_LTCA.rolls_per_cycle + 2))
    assert len(calls) == 4 and teeth.analyses_reused == before


def test_a_result_read_back_is_not_changed_by_its_caller(analysed):
    """A caller that changes the metrics it is handed changes its copy alone: the next
    read gives the analysis as computed."""
    case, own, teeth, _ = analysed
    got = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    got[0]["lte_peak_to_peak"][:] = -1.0
    again = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    np.testing.assert_array_equal(again[0]["lte_peak_to_peak"], own[0]["lte_peak_to_peak"])


def test_one_basic_design_shares_its_memo_and_teeth_another_gets_its_own():
    """Equal basic designs (the Formate development stopped on a foreseen cut and run in
    full) get the same synthesis memo and kept teeth; the generated gear's, or another
    design torque's, new ones; without a SharedDevelopments every development its own."""
    basic = _basic()
    shared = SharedDevelopments()
    memo, teeth = shared.kept(basic)
    again = shared.kept(dataclasses.replace(basic))
    assert again[0] is memo and again[1] is teeth
    generated = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, gear_process="Generate"))
    torque = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, design_torque=123.0))
    for other in (generated, torque):
        got = shared.kept(other)
        assert got[0] is not memo and got[1] is not teeth
    assert (shared.developments, shared.repeated) == (4, 1)
    assert kept_for(None, basic)[1] is not kept_for(None, basic)[1]


def test_the_gear_fallback_runs_share_one(monkeypatch):
    """``develop`` with its gear fallback hands every development it runs
    (``with_generated_gear``'s ``run``) the same SharedDevelopments (a stand-in for the
    fallback records it: no development runs)."""
    from contact.optimize import development_process

    seen = []

    def fallback(run, basic, say=None):
        seen.append(run.keywords["shared"])
        return "result"

    monkeypatch.setattr(development_process, "with_generated_gear", fallback)
    assert dev.develop(_basic(), root_stress=False) == "result"
    assert isinstance(seen[0], SharedDevelopments)
    given = SharedDevelopments()
    dev.develop(_basic(), root_stress=False, shared=given)
    assert seen[1] is given
