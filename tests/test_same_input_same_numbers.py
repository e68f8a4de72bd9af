"""One input, one answer (issue 71, determ89): a design's analysis in one process does not
depend on what the process ran before it.

Reference: the same analysis computed first in a fresh process state
(:func:`geometry.core.caches.clear_caches`). The process's memos (the tooth models, the
forward map's points, the flanks on their grids, the seeds of the equation of meshing,
the ease-offs) and a development's trials inside a :class:`geometry.machine.meshing.
WarmSeeds` block (their seeds continued from other designs', their ease-offs not
memoised) must leave a later cold analysis bit for bit as computed fresh: a memo's entry
is what its function computes again (geometry.core.caches). The tolerance is zero: any
difference here is state, not round-off of one computation against another (the kernel
paths' round-off, which a development does amplify, is docs/performance.md's "One
input, one answer: the kernel path").
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

DESIGNS = Path(__file__).resolve().parent / "data" / "designs"
TORQUES = [50.0, 300.0]  # [N·m] the passenger-car hypoid's light and a high torque


@pytest.fixture(scope="module")
def designs():
    """The passenger-car hypoid 10x43's drive design as synthesised and a bearing trial
    beside it (path angle +4°, ellipse +0.05: another pinion, the same gear)."""
    from geometry.synthesis.basic_design import (
        flank_option_values,
        load_basic,
        with_flank_options,
    )
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    flank = basic.options.drive_flank
    start = flank_option_values(basic.options.flank(flank))
    other = dict(start, path_angle=start["path_angle"] + 4.0,
                 ellipse_length=start["ellipse_length"] + 0.05)
    memo: dict = {}
    return [synthesize(with_flank_options(basic, flank, v), memo=memo, tip_planes=False)[0]
            for v in (start, other)]


def _metrics(case):
    from contact.optimize.development_evaluate import analyse_design

    metrics, grid = analyse_design(case, TORQUES)
    return {k: np.asarray(v, dtype=float) for k, v in metrics.items()}, tuple(grid)


def _same(a, b) -> list[str]:
    """The names whose values differ in any bit (NaN equal to NaN)."""
    (ma, ga), (mb, gb) = a, b
    differ = [k for k in ma if not np.array_equal(ma[k], mb[k], equal_nan=True)]
    return differ + (["grid"] if ga != gb else [])


def test_an_analysis_is_the_same_fresh_from_memos_and_after_other_designs(designs):
    from contact.optimize.development_evaluate import KeptTeeth, analyse_design
    from geometry.core.caches import cache_sizes, clear_caches
    from geometry.machine.meshing import WarmSeeds

    case, other = designs
    clear_caches()
    fresh = _metrics(case)
    assert np.isfinite(fresh[0]["lte_peak_to_peak"]).all()
    # the same input again in the same process: every memo hit
    assert sum(cache_sizes().values()) > 0
    assert _same(fresh, _metrics(case)) == []
    # after the other design analysed cold and the two as a development's trials (inside
    # one WarmSeeds block, seeds continued from each other's, kept teeth): memos filled
    # in another order and inside blocks
    clear_caches()
    _metrics(other)
    seeds, teeth = WarmSeeds(), KeptTeeth()
    for c in (other, case):
        with seeds:
            analyse_design(c, TORQUES, teeth=teeth, pinion_key=("trial",))
    assert seeds.searched > 0
    assert _same(fresh, _metrics(case)) == []
