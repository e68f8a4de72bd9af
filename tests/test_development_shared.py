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


def test_within_one_run_the_same_inputs_are_analysed_again(analysed, monkeypatch):
    """Within one development's run an analysis of inputs analysed before is computed
    again, as before this module (the LTCA runs: counted by a wrapper of it): a search's
    envelope seeds and the process memos can make it another result."""
    from contact import ltca as ltca_module

    case, _, teeth, _ = analysed
    calls = []
    real = ltca_module.loaded_tca
    monkeypatch.setattr(ltca_module, "loaded_tca",
                        lambda *a, **kw: calls.append(1) or real(*a, **kw))
    before = teeth.analyses_reused
    analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    assert len(calls) == 1 and teeth.analyses_reused == before


def test_a_run_again_reads_back_the_first_run_s_nth_analysis(analysed):
    """A development run again with the same teeth (begin_development) reads back the
    n-th analysis of the same inputs as the first run computed it — equal to an
    independent analysis with new kept teeth to the bit (tolerance 0: the same
    deterministic computation of the same case outside a WarmSeeds block) — and
    ``analyses_reused`` counts each."""
    case, own, _, _ = analysed
    teeth = KeptTeeth()
    first = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    teeth.begin_development()
    again = analyse_design(case, [50.0, 330.0], teeth=teeth, pinion_key=("a",))
    assert teeth.analyses_reused == 1
    assert again[0].keys() == own[0].keys() == first[0].keys()
    for k, v in again[0].items():
        np.testing.assert_array_equal(v, own[0][k], err_msg=k)
    assert again[1] == own[1] == first[1]


def test_the_nth_of_a_key_reads_the_nth_and_a_caller_changes_its_copy_alone():
    """Stand-in analyses (each call a new result): within a run every call computes; the
    run again reads the first run's results in their order, then computes past them; a
    caller that changes what it is handed changes its copy alone."""
    teeth = KeptTeeth()
    made = iter(range(100))

    def analyse():
        return {"x": np.array([float(next(made))])}, (0.0,)

    run1 = [teeth.analysed(("k",), analyse)[0]["x"][0] for _ in range(2)]
    teeth.begin_development()
    got = teeth.analysed(("k",), analyse)
    got[0]["x"][:] = -1.0
    teeth.begin_development()
    run3 = [teeth.analysed(("k",), analyse)[0]["x"][0] for _ in range(3)]
    assert run1 == [0.0, 1.0] and run3 == [0.0, 1.0, 2.0]
    assert teeth.analyses_reused == 3


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
