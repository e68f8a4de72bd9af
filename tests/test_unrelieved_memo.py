"""The contact-ratio note's measure without the relief reads the written flanks' steps 3–6
back from the development's synthesis memo (contact.optimize.remedy_check.memo_options;
issue 71 / issue 75, branch cpu99: on the FH hypoid 13x40 of
benchmarks/data/unseen_designs the note synthesised them again, 2 repeats, 2.5 s of CPU).

Identity: the measure with the memo equals the measure without it, and the memo's options
are taken only where the memo holds that very design's development (stand-ins)."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from contact.optimize import remedy_check
from contact.optimize.remedy_check import memo_options, unrelieved_te_pp
from geometry.synthesis.basic_design import FlankOptions, load_basic

ROOT = Path(__file__).resolve().parent.parent
THIRTEEN = ROOT / "benchmarks" / "data" / "unseen_designs" / "fh_hypoid_13x40_a24_m2_9k.toml"


def _bare(options):
    return dataclasses.replace(options, concave=FlankOptions(), convex=FlankOptions())


def _developed(basic):
    """The written prescriptions of a development (stand-in values, both flanks)."""
    return dataclasses.replace(basic, options=dataclasses.replace(
        basic.options,
        concave=FlankOptions(tip_relief=0.02, root_relief=0.01, path_angle=math.radians(-70.0)),
        convex=FlankOptions(tip_relief=0.015, root_relief=0.01)))


def test_the_memos_options_only_where_it_holds_that_designs_development():
    """memo_options: the development's gear process ("auto") and design torque, with the
    written flanks, where the memo decided the process for that design and every other
    option; the options as given where the memo is empty, the process it decided is
    another, another option or the design data differ."""
    basic = _developed(load_basic(THIRTEEN))
    auto = dataclasses.replace(basic.options, gear_process="auto", design_torque=26.2)
    memo = {("gear process", basic.design, _bare(auto)): ("Formate", "gear"),
            ("other", 1): None}
    # the note's basic data: the written case's process made explicit, no design torque
    noted = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, gear_process="Formate", design_torque=None))
    got = memo_options(noted, memo)
    assert (got.gear_process, got.design_torque) == ("auto", 26.2)
    assert (got.concave, got.convex) == (noted.options.concave, noted.options.convex)
    assert _bare(got) == _bare(auto)
    # nothing to read back: the options as given
    assert memo_options(noted, None) is noted.options
    assert memo_options(noted, {}) is noted.options
    # the memo decided another process than the written case's
    other = {("gear process", basic.design, _bare(auto)): ("Generate", "gear")}
    assert memo_options(noted, other) is noted.options
    # another option (the cutter radius) or other design data: another development's memo
    moved = dataclasses.replace(noted, options=dataclasses.replace(
        noted.options, cutter_radius=(noted.options.cutter_radius or 50.0) + 1.0))
    assert memo_options(moved, memo) is moved.options
    wider = dataclasses.replace(noted, design=dataclasses.replace(noted.design,
                                                                  b2=noted.design.b2 + 1.0))
    assert memo_options(wider, memo) is wider.options


def test_the_measure_with_the_memo_is_the_measure_without_it(monkeypatch):
    """The FH hypoid 13x40 at stand-in prescriptions, synthesised once with a memo (as the
    development's final synthesis) and its gear process then made explicit (as the note's
    prescribed basic data): unrelieved_te_pp with the memo reads both flanks' steps 3–6
    back (none computed) and gives, bit for bit, the measure of a synthesis with a memo of
    its own (whose steps 3–6 are computed as the development's first synthesis computes
    them). Without any memo the tool solve takes another path to the same root
    (WarmTools' empty series aside): within 1e-9 relative, the tolerance
    tests/test_synthesis_memo.py holds a memo's settings to (measured here 1.4e-11; the
    note rounds to 0.001 µrad of ≈ 128)."""
    import geometry.synthesis.case_synthesis as cs

    basic = _developed(load_basic(THIRTEEN))
    memo: dict = {}
    cs.synthesize(basic, memo=memo, tip_planes=False)
    noted = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, gear_process="Formate"))
    computed = []
    real = cs._unrelieved_flank

    def counted(*args, **kw):
        computed.append(args[1])
        return real(*args, **kw)

    monkeypatch.setattr(cs, "_unrelieved_flank", counted)
    with_memo = unrelieved_te_pp(noted, memo)
    assert computed == []  # both flanks' steps 3-6 read back
    assert all(map(math.isfinite, with_memo))  # measured
    own = unrelieved_te_pp(noted, {})
    assert sorted(computed) == ["concave", "convex"]  # computed in a memo of its own
    assert with_memo == own
    assert with_memo == pytest.approx(unrelieved_te_pp(noted), rel=1e-9)
    # the options read back are those of the memo's development (its gear process "auto")
    assert remedy_check.memo_options(noted, memo).gear_process == "auto"
