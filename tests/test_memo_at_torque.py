"""A development of the same basic data at another design torque (the drive developed again
in its LTE window) reads the first development's syntheses back, not its tip planes
(geometry.synthesis.case_synthesis.memo_at_torque, contact.optimize.development_shared;
issue 71 / issue 75, branch cpu99: the FH spiral bevel 12x27 of
benchmarks/data/unseen_designs re-made 10 of its rated development's steps 3–6, 5.4 s).

Identity: a synthesis with the seeded memo is the synthesis the new development makes with a
memo of its own — bit for bit (``Case.to_toml``), read back or continued from the same
anchor (every development's first synthesis is the start of its search)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

DESIGNS = Path(__file__).parent / "data" / "designs"


def _at(basic, torque):
    return dataclasses.replace(basic, options=dataclasses.replace(basic.options,
                                                                  design_torque=torque))


def test_a_memo_at_another_torque_serves_that_torques_series_bit_for_bit(monkeypatch):
    """The passenger-car hypoid 10x43: a series (the start, then a drive path angle of
    -60 deg) synthesised with a memo; the memo at 300 N m (memo_at_torque) against a memo
    of the 300 N m series' own (its start first, as a development's): the -60 deg design
    is read back (no steps 3–6 made) and equals its own series' synthesis, a new design
    (-50 deg) is continued from the same anchor and equal too; the memo given is not
    changed and the tip planes are not carried over."""
    import geometry.synthesis.case_synthesis as cs
    from geometry.synthesis.basic_design import load_basic, with_flank_options

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    p = with_flank_options(basic, "concave", {"path_angle": -60.0})
    q = with_flank_options(basic, "concave", {"path_angle": -50.0})
    memo: dict = {}
    for b in (basic, p):
        cs.synthesize(b, memo=memo, tip_planes=False)
    cs.synthesize(p, memo=memo)  # a checked design: its tip planes placed
    before = {k: dict(v) if isinstance(v, dict) else v for k, v in memo.items()}
    seeded = cs.memo_at_torque(memo, 300.0)
    assert {k: dict(v) if isinstance(v, dict) else v for k, v in memo.items()} == before
    (entries,) = [v for v in seeded.values() if isinstance(v, dict)]
    assert not [k for k in entries if isinstance(k, tuple) and k[0].startswith("tip plane")]
    (placed,) = [v for v in memo.values() if isinstance(v, dict)]
    assert [k for k in placed if isinstance(k, tuple) and k[0] == "tip plane"]  # were there
    own: dict = {}
    cs.synthesize(_at(basic, 300.0), memo=own, tip_planes=False)  # its own series' start
    made = []
    real = cs._unrelieved_flank
    monkeypatch.setattr(cs, "_unrelieved_flank",
                        lambda *a, **k: made.append(a[1]) or real(*a, **k))
    read, _ = cs.synthesize(_at(p, 300.0), memo=seeded, tip_planes=False)
    assert made == []  # both flanks' steps 3-6 read back
    mine, _ = cs.synthesize(_at(p, 300.0), memo=own, tip_planes=False)
    assert made == ["concave"]  # its own series makes the new drive flank
    assert read.to_toml() == mine.to_toml()
    new_a, _ = cs.synthesize(_at(q, 300.0), memo=seeded, tip_planes=False)
    new_b, _ = cs.synthesize(_at(q, 300.0), memo=own, tip_planes=False)
    assert made == ["concave"] * 3 and new_a.to_toml() == new_b.to_toml()


def test_a_development_at_another_torque_gets_a_seeded_memo_of_its_own():
    """SharedDevelopments.kept: the same basic data at another design torque gets a new
    memo seeded from the first development's (not that memo itself) and new kept teeth;
    at the same torque again the same objects (a repeat); other basic data a new empty
    memo."""
    from contact.optimize.development_shared import SharedDevelopments
    from geometry.synthesis.basic_design import load_basic

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    shared = SharedDevelopments()
    memo, teeth = shared.kept(basic)
    memo[("gear process", basic.design, "stand-in")] = ("Formate", "gear")
    memo[(basic.design, "stand-in")] = {"blank": "B", ("tip plane", "b", "s"): "T",
                                        ("tip plane first", "concave"): (0.1, 0.2)}
    lower, lower_teeth = shared.kept(_at(basic, 45.5))
    assert lower is not memo and lower_teeth is not teeth
    assert lower[("gear process", basic.design, "stand-in")] == ("Formate", "gear")
    assert lower[(basic.design, "stand-in")] == {"blank": "B"}  # no tip planes
    assert (shared.seeded, shared.repeated) == (1, 0)
    again, _ = shared.kept(_at(basic, 45.5))
    assert again is lower and shared.repeated == 1
    # the next torque is seeded from the first development's memo, not the last one's
    lower[("only", "in 45.5")] = 1
    third, _ = shared.kept(_at(basic, 26.2))
    assert ("only", "in 45.5") not in third and shared.seeded == 2
    other = dataclasses.replace(basic, design=dataclasses.replace(basic.design,
                                                                  b2=basic.design.b2 + 1.0))
    fresh, _ = shared.kept(other)
    assert fresh == {} and shared.seeded == 2
