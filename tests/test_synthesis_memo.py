"""The synthesis memo (``synthesize(..., memo=...)``, geometry.synthesis.case_synthesis):
what the development bearing (contact.optimize.development) keeps between the designs it
synthesises.

Identities: steps 3–6 of a pinion flank (mean point, local synthesis, generating tools,
modified roll) read neither the relief nor the other flank's prescriptions, so a design
that differs only in its relief re-makes nothing but the relief, a design with a new drive
flank synthesises that flank alone (the coast flank's steps 3–6 kept, and its tip plane,
step 8, where its blade and settings recur), and the case is the same, bit for bit, as a
synthesis without the memo.
"""

from __future__ import annotations

from pathlib import Path

DESIGNS = Path(__file__).parent / "data" / "designs"


def test_the_memo_keeps_steps_3_to_6_and_changes_nothing():
    from geometry.synthesis.basic_design import load_basic, with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    memo: dict = {}
    lines: list[str] = []
    synthesize(with_flank_options(basic, "concave", {"path_angle": -60.0}), memo=memo)
    (entries,) = memo.values()  # one design

    def flanks() -> list:  # steps 3-6 kept, per flank (the rest: step 8's placements)
        return [k for k in entries if k[0] in ("concave", "convex")]

    assert len(flanks()) == 2  # its drive (concave) and coast (convex) flank
    assert len(entries) == 7  # their tip planes (step 8), the gear flanks' design points
    # and the blanks
    relieved = with_flank_options(basic, "concave", {"path_angle": -60.0, "tip_relief": 25.0,
                                                      "relief_start": 0.4})
    kept, _ = synthesize(relieved, memo=memo, progress=lines.append)
    assert len(flanks()) == 2  # only the relief was made again
    assert len(entries) == 8  # and the drive flank's tip plane: the coast's was kept
    assert sum("kept from an earlier synthesis" in line for line in lines) == 6
    synthesize(with_flank_options(basic, "concave", {"path_angle": -50.0}), memo=memo)
    assert len(flanks()) == 3  # a new drive flank; the coast flank kept
    fresh, _ = synthesize(relieved)
    assert kept.to_toml() == fresh.to_toml()
    assert kept.pinion.concave.blade.toprem_angle != 0.0
