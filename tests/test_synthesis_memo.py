"""The synthesis memo (``synthesize(..., memo=...)``, geometry.synthesis.case_synthesis):
what the development bearing (contact.optimize.development) keeps between the designs it
synthesises.

Identities: steps 3–6 of a pinion flank (mean point, local synthesis, generating tools,
modified roll) read neither the relief nor the other flank's prescriptions, so a design
that differs only in its relief re-makes nothing but the relief, a design with a new drive
flank synthesises that flank alone (the coast flank's steps 3–6 kept, and its tip plane,
step 8, where its blade and settings recur), and the case is the same as a synthesis
without the memo: bit for bit but the tip plane, which the memo starts from the blade
side's last placement (the same placement within its 1e-9 mm tolerance).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

DESIGNS = Path(__file__).parent / "data" / "designs"


def _assert_same_case(a, b, path: str = "") -> None:
    """Two parsed case files alike: strings and integers equal, floats within 1e-9
    relative (or 1e-9 absolute near zero)."""
    if isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for k in a:
            _assert_same_case(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _assert_same_case(x, y, f"{path}[{i}]")
    elif isinstance(a, float):
        assert math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9), (path, a, b)
    else:
        assert a == b, path


def test_the_memo_keeps_steps_3_to_6_and_changes_nothing():
    from geometry.synthesis.basic_design import load_basic, with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    memo: dict = {}
    lines: list[str] = []
    synthesize(with_flank_options(basic, "concave", {"path_angle": -60.0}), memo=memo)
    # one design (and its gear process, kept beside it: "gear process", design)
    (entries,) = [v for v in memo.values() if isinstance(v, dict)]

    def flanks() -> list:  # steps 3-6 kept, per flank (the rest: step 8's placements)
        return [k for k in entries if k[0] in ("concave", "convex")]

    assert len(flanks()) == 2  # its drive (concave) and coast (convex) flank
    assert len(entries) == 9  # their tip planes (step 8), the gear flanks' design points,
    # the blanks, and each blade side's last placement (the next placement's start)
    relieved = with_flank_options(basic, "concave", {"path_angle": -60.0, "tip_relief": 25.0,
                                                      "relief_start": 0.4})
    kept, _ = synthesize(relieved, memo=memo, progress=lines.append)
    assert len(flanks()) == 2  # only the relief was made again
    assert len(entries) == 10  # and the drive flank's tip plane: the coast's was kept
    assert sum("kept from an earlier synthesis" in line for line in lines) == 6
    synthesize(with_flank_options(basic, "concave", {"path_angle": -50.0}), memo=memo)
    assert len(flanks()) == 3  # a new drive flank; the coast flank kept
    fresh, _ = synthesize(relieved)
    # the same case as a fresh synthesis, to the tip plane's placement tolerance: the memo
    # starts a placement from the last one of the blade side (1e-9 mm, measured 1e-14 to
    # 3e-12 relative on the settings), so bit for bit no more
    _assert_same_case(tomllib.loads(kept.to_toml()), tomllib.loads(fresh.to_toml()))
    assert kept.pinion.concave.blade.toprem_angle != 0.0
