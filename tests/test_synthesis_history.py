"""A design synthesised with the development's memo does not depend on which other designs
the memo synthesised before it (issue 71, branch state90).

The memo (``synthesize(..., memo=...)``, geometry.synthesis.case_synthesis) continues a
new flank's step 5 (the pinion tools, :class:`~geometry.synthesis.pinion.WarmTools`) and
its step 8 (the tip plane's placement) from an earlier synthesis of the series. Both land
on their root only to a tolerance (the warm iteration's 1e-12 residual, the placement's
1e-9 mm), and the modified roll tuned from the tools carries their ~1e-13 on as ~1e-7:
continued from the *last* synthesis, the design a development writes moved when a step
that kept nothing had run before it (the miter 12x12 at beta_m 35 deg of
benchmarks/data/unseen_designs on branch miter89: settings in their 9th digit; on the
passenger-car hypoid 10x43 below, the drive flank's modified roll 1.2e-7 relative, the
blade's profile radius 1e-10). Continued from the series' *first* synthesis, a design's
case is a function of its own inputs and of that first synthesis alone: the same bit for
bit whichever syntheses ran between. The comparison is exact (tolerance 0): the property
tested is that the same arithmetic runs, not that two roots agree.
"""

from __future__ import annotations

from pathlib import Path

import pytest

DESIGNS = Path(__file__).resolve().parents[1] / "tests" / "data" / "designs"

#: the first synthesis of the series (a development's search start), the design kept and
#: written, and a trial between them whose prescriptions are far from both (the miter89
#: step's turned path at its 250 µrad parabola)
FIRST = {"path_angle": -60.0}
KEPT = {"path_angle": -50.0, "te_level": 40.0}
BETWEEN = {"path_angle": 10.0, "te_level": 250.0}


def _written(basic, trials: list[dict]) -> tuple[str, dict]:
    """The case file (TOML text) of the last of ``trials`` (drive-flank prescriptions),
    each synthesised in turn with one memo, and that memo's design entries."""
    from geometry.synthesis.basic_design import with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    memo: dict = {}
    flank = basic.options.drive_flank
    for values in trials:
        case, _ = synthesize(with_flank_options(basic, flank, values), memo=memo)
    (entries,) = [v for v in memo.values() if isinstance(v, dict)]
    return case.to_toml(), entries


@pytest.mark.parametrize("name", ["pc_hypoid_10x43.toml", "fh_hypoid_11x43.toml"])
def test_a_trial_between_leaves_the_written_case_bit_for_bit(name):
    """FM (the 10x43) and FH (the 11x43, whose tool solve continues its inner cutter pose
    too): the kept design's case file the same text with and without a far trial
    synthesised between the series' first synthesis and it."""
    from geometry.synthesis.basic_design import load_basic

    basic = load_basic(DESIGNS / name)
    direct, entries = _written(basic, [FIRST, KEPT])
    between, entries_between = _written(basic, [FIRST, BETWEEN, KEPT])
    assert between == direct
    flank = basic.options.drive_flank
    # the trial between was synthesised (a new drive flank each: three against two)...
    solves = [(e.used + e.cold) for e in (entries[("warm starts", flank)],
                                          entries_between[("warm starts", flank)])]
    assert solves == [2, 3]
    # ... and the series' start is its first synthesis in both
    first = entries[("warm starts", flank)]
    assert (first.x == entries_between[("warm starts", flank)].x).all()
    side = [k for k in entries if k[0] == "tip plane first"]
    assert side and all(entries[k] == entries_between[k] for k in side)


def test_a_fork_leaves_the_series_start_and_the_anchor_keeps_the_first():
    """:meth:`WarmTools.fork` copies (a solve that changes the fork leaves the series as
    it was); :meth:`WarmTools.anchor` keeps the first solution and counts every solve."""
    import numpy as np

    from geometry.synthesis.pinion import WarmTools

    series = WarmTools()
    first = series.fork()
    assert first.x is None and first.used == first.cold == 0
    first.x, first.jac, first.cold = np.array([1.0, 2.0, 3.0]), np.eye(3), 1
    series.anchor(first)
    second = series.fork()
    second.x[0] = 9.0  # a later solve moves its own copy only
    second.x, second.used = np.array([4.0, 5.0, 6.0]), 1
    series.anchor(second)
    np.testing.assert_array_equal(series.x, [1.0, 2.0, 3.0])
    assert (series.used, series.cold) == (1, 1)
    assert series.params is None and series.inner is None
