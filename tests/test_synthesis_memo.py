"""The synthesis memo (``synthesize(..., memo=...)``, geometry.synthesis.case_synthesis):
what the development bearing (contact.optimize.development) keeps between the designs it
synthesises.

Identities: steps 3–6 of a pinion flank (mean point, local synthesis, generating tools,
modified roll) read neither the relief nor the other flank's prescriptions, so a design
that differs only in its relief re-makes nothing but the relief, a design with a new drive
flank synthesises that flank alone (the coast flank's steps 3–6 kept, and its tip plane,
step 8, where its blade and settings recur), and the case is the same as a synthesis
without the memo: bit for bit but the tip plane, which the memo starts from the blade
side's first placement (the same placement within its 1e-9 mm tolerance). A new flank of
the series continues step 5 from the flank's first synthesis (issue 75, ``WarmTools``):
the same tools as a fresh synthesis to 1e-12 relative. ``WarmRoll`` (step 6 from the last
tune, not used by the synthesis) within its tolerance of a cold tune.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

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


def _assert_warm_flank_as_cold(warm, cold) -> None:
    """The concave flank of a synthesis continued from an earlier one (step 5) as a cold
    synthesis'. The tools: the warm root of the same square system, to its noise floor
    (max residual 1e-12, or where it stalls below 1e-10, against the least squares' 5e-15
    to 2e-13; measured 1e-12 relative on the settings): 1e-9 relative, as the committed
    cases' test. The modified roll, tuned cold from those tools by the same Newton steps:
    1e-6 relative (measured 3e-8: the tools' 1e-13 through the tune's TE evaluations)."""
    a, b = warm.pinion.concave, cold.pinion.concave
    for field in ("radial_setting", "cradle_angle", "tilt", "swivel", "machine_root_angle",
                  "sliding_base", "blank_offset", "ratio_of_roll", "indexing_ratio"):
        assert math.isclose(getattr(a.machine, field), getattr(b.machine, field),
                            rel_tol=1e-9, abs_tol=1e-9), field
    for field in ("point_radius", "profile_radius", "blade_angle", "blade_phase",
                  "blade_offset_angle"):
        assert math.isclose(getattr(a.blade, field), getattr(b.blade, field), rel_tol=1e-9,
                            abs_tol=1e-12), field
    for x, y in zip(a.machine.modified_roll, b.machine.modified_roll, strict=True):
        assert math.isclose(x, y, rel_tol=1e-6, abs_tol=1e-12)


def _level(basic, pf: str) -> float:
    """The TE level a21 h²/2 [rad] at the tune's rolls ±pitch/4 of flank ``pf``."""
    z1 = basic.design.z1
    h = 0.25 * 2.0 * math.pi / z1
    return 0.5 * 2.0 * basic.options.flank(pf).te_level / (2.0 * math.pi / z1) ** 2 * h * h


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

    def reliefs() -> list:  # step 7 kept, per flank and prescriptions
        return [k for k in entries if k[0] == "relieved"]

    assert len(flanks()) == 2  # its drive (concave) and coast (convex) flank
    assert len(reliefs()) == 2  # and their reliefs
    assert len(entries) - len(reliefs()) == 11  # their tip planes (step 8), the gear
    # flanks' design points, the blanks, each blade side's first placement (the next
    # placement's start) and each flank's warm start of step 5
    relieved = with_flank_options(basic, "concave", {"path_angle": -60.0, "tip_relief": 25.0,
                                                      "relief_start": 0.4})
    kept, _ = synthesize(relieved, memo=memo, progress=lines.append)
    assert len(flanks()) == 2  # only the relief was made again
    assert len(reliefs()) == 3  # the drive flank's: the coast flank's relief was kept
    assert len(entries) - len(reliefs()) == 12  # and the drive flank's tip plane: the
    # coast's was kept
    assert sum("kept from an earlier synthesis" in line for line in lines) == 6
    assert sum("tip and root relief" in line for line in lines) == 2  # said as made
    other = with_flank_options(basic, "concave", {"path_angle": -50.0})
    warm, _ = synthesize(other, memo=memo, tip_planes=False)
    assert len(flanks()) == 3  # a new drive flank; the coast flank kept
    tools = entries[("warm starts", "concave")]
    assert (tools.used, tools.cold) == (1, 1)  # continued
    _assert_warm_flank_as_cold(warm, synthesize(other, tip_planes=False)[0])
    fresh, _ = synthesize(relieved)
    # the same case as a fresh synthesis, to the tip plane's placement tolerance: the memo
    # starts a placement from the first one of the blade side (1e-9 mm, measured 1e-14 to
    # 3e-12 relative on the settings), so bit for bit no more
    _assert_same_case(tomllib.loads(kept.to_toml()), tomllib.loads(fresh.to_toml()))
    assert kept.pinion.concave.blade.toprem_angle != 0.0


def test_a_design_synthesised_again_from_the_memo_is_the_same_bit_for_bit(monkeypatch):
    """Step 7 kept (issue 75): a design synthesised again with the memo (a development's
    coast flank developed again at its own torque, a trial checked) re-makes no relief and
    is the first synthesis bit for bit; a design whose drive flank's relief alone changes
    re-makes that relief alone, and its case (the coast flank's relief from the memo) is a
    synthesis without a memo bit for bit (step 8 left out: the memo starts a placement from
    the first one, the same placement to its 1e-9 mm tolerance only)."""
    import geometry.synthesis.case_synthesis as cs
    from geometry.synthesis.basic_design import load_basic, with_flank_options

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    memo: dict = {}
    first, _ = cs.synthesize(basic, memo=memo, tip_planes=False)
    made = []
    real = cs.relieved_blade
    monkeypatch.setattr(cs, "relieved_blade", lambda *a, **k: made.append(a) or real(*a, **k))
    again, _ = cs.synthesize(basic, memo=memo, tip_planes=False)
    assert made == [] and again.to_toml() == first.to_toml()
    other = with_flank_options(basic, "concave", {"tip_relief": 25.0, "relief_start": 0.4})
    kept, _ = cs.synthesize(other, memo=memo, tip_planes=False)
    assert len(made) == 1  # the drive flank's new relief only
    fresh, _ = cs.synthesize(other, tip_planes=False)
    assert len(made) == 3  # both flanks' reliefs made without a memo
    assert kept.to_toml() == fresh.to_toml()
    assert kept.pinion.concave.blade.toprem_angle != first.pinion.concave.blade.toprem_angle


def test_a_face_hobbed_flank_continues_from_the_last_as_a_cold_synthesis():
    """The face-hobbed hypoid 11x43: a drive flank synthesised after another of the series
    continues its tools (and each tool's cutter pose) and its modified roll from it and is
    a cold synthesis' within the tolerances of :func:`_assert_warm_flank_as_cold`."""
    from geometry.synthesis.basic_design import load_basic, with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(DESIGNS / "fh_hypoid_11x43.toml")
    memo: dict = {}
    synthesize(with_flank_options(basic, "concave", {"path_angle": -60.0}), memo=memo,
               tip_planes=False)
    other = with_flank_options(basic, "concave", {"path_angle": -50.0,
                                                  "ellipse_length": 0.5})
    warm, _ = synthesize(other, memo=memo, tip_planes=False)
    (entries,) = [v for v in memo.values() if isinstance(v, dict)]
    tools = entries[("warm starts", "concave")]
    assert tools.used == 1 and tools.inner is not None
    _assert_warm_flank_as_cold(warm, synthesize(other, tip_planes=False)[0])


def test_a_warm_roll_tune_is_a_cold_one_within_the_tolerance(monkeypatch):
    """``WarmRoll`` (step 6 continued from the last tune): the second flank of a series
    tuned from the first's 6D, 24E, Jacobian and contact puts the TE at ±pitch/4 within
    1e-5 of its level (WARM_ROLL_TOLERANCE), and lies within the cold tune's own tolerance
    of it: both TE misses below 0.5 % of the level a21 h²/2, which the inverse of the
    tune's Jacobian of the misses per unit of (6D, 24E) maps to the bounds asserted
    (2.6e-3 of 6D and 0.15 of 24E on the 10x43; measured 1.4e-5 and 9.4e-5)."""
    from geometry.synthesis import case_synthesis as cs
    from geometry.synthesis import modified_roll as mr
    from geometry.synthesis.basic_design import load_basic, with_flank_options

    calls = []
    monkeypatch.setattr(cs, "tune_roll", lambda *a, **k: calls.append((a, k)) or mr.tune_roll(
        *a, **k))
    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    other = with_flank_options(basic, "concave", {"path_angle": -50.0})
    for b in (with_flank_options(basic, "concave", {"path_angle": -60.0}), other):
        cs.synthesize(b, tip_planes=False)
    (a1, k1), (a2, k2) = calls[0], calls[2]  # the concave flank's tunes (then the convex)
    roll = mr.WarmRoll()
    mr.tune_roll(*a1, **k1, warm=roll)
    warm = mr.tune_roll(*a2, **k2, warm=roll).settings.modified_roll
    cold = mr.tune_roll(*a2, **k2).settings.modified_roll
    assert (roll.used, roll.cold) == (1, 1)
    level = _level(other, "concave")
    assert roll.miss < 1e-5 * level
    bound = np.abs(np.linalg.inv(roll.jac)) @ np.full(2, (5e-3 + 1e-5) * level)
    assert warm[0] == cold[0] == 0.0
    assert abs(warm[1] - cold[1]) < bound[0] and abs(warm[2] - cold[2]) < bound[1]
