"""Envelope seeds continued between a development's trials (``geometry.machine.meshing.
WarmSeeds``, issue 75): inside a block, a seed the search's first pass does not give is
continued by Newton's method from an earlier tool's seed.

Reference: the same solves outside a block (the seed search over every blade section, as
before). A seed is only the start of the continuation and the reference of its
predictions; every point's root is then converged to the envelope solver's tolerance
(|Δz|, |Δρ| < 1e-10 mm), so the ease-off of a gear node (an angle about the gear axis,
radius ~90 mm) may differ by ~1e-12 rad: the tests allow 1e-9 rad (and 1e-9 of the
pinion fractions), and the nodes' reason codes must be the same.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

DESIGNS = Path(__file__).parent / "data" / "designs"


@pytest.fixture(scope="module")
def trials():
    """Four drive-flank designs of the passenger-car hypoid 10x43 as its development's
    bearing stage tries them (path angle and ellipse varied), then its height stage (the
    root relief and its start: the blade's flankrem section ends move), synthesised
    once."""
    from geometry.synthesis.basic_design import (
        flank_option_values,
        load_basic,
        with_flank_options,
    )
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    flank = basic.options.drive_flank
    start = flank_option_values(basic.options.flank(flank))
    memo: dict = {}
    out = []
    for d_path, d_ellipse, relief in ((0.0, 0.0, {}), (4.0, 0.05, {}), (-3.0, 0.1, {}),
                                      (-3.0, 0.1, {"root_relief": 40.0,
                                                   "relief_start": 0.2})):
        values = dict(start, path_angle=start["path_angle"] + d_path,
                      ellipse_length=start["ellipse_length"] + d_ellipse, **relief)
        out.append(synthesize(with_flank_options(basic, flank, values), memo=memo,
                              tip_planes=False)[0])
    return out


def test_warm_ease_offs_are_the_cold_ones_to_the_solver_tolerance(trials, monkeypatch):
    from contact.utca.conjugate_map import clear_memos
    from contact.utca.easeoff import _memoised_ease_off, ease_off
    from geometry.machine import meshing
    from geometry.machine.meshing import WarmSeeds, warm_seeds_active

    clear_memos()
    cold = [ease_off(c, flank="drive") for c in trials]
    clear_memos()
    seeds = WarmSeeds()
    assert not warm_seeds_active()
    searches = []  # the whole searches (every blade section) a block still runs
    whole = meshing._seed_memoised
    monkeypatch.setattr(meshing, "_seed_memoised",
                        lambda *a: searches.append(a) or whole(*a))
    warm, searched = [], []
    for c in trials:
        with seeds:
            assert warm_seeds_active()
            warm.append(ease_off(c, flank="drive"))
        assert not warm_seeds_active()
        searched.append(len(searches))
    # the trials' ease-offs are not memoised (an analysis outside a block is computed cold)
    assert _memoised_ease_off.cache_info().currsize == 0
    # seeds were continued (the ease-off's placement seeds a target on the tip relief,
    # which the search's first pass does not give) and some searched (the first trial's)
    assert seeds.used > 0
    assert seeds.searched > 0
    # and only the first trial's: a hint whose root leaves its blade section (the last
    # trial's relief moved the section ends) is continued on the section it entered
    assert searched[1:] == searched[:1] * 3
    for a, b in zip(cold, warm, strict=True):
        np.testing.assert_array_equal(a.reason, b.reason)
        np.testing.assert_allclose(b.ease_off_angle, a.ease_off_angle, rtol=0, atol=1e-9)
        np.testing.assert_allclose(b.roll_angle, a.roll_angle, rtol=0, atol=1e-9)
        np.testing.assert_allclose(b.pinion_u, a.pinion_u, rtol=0, atol=1e-9)
        np.testing.assert_allclose(b.pinion_v, a.pinion_v, rtol=0, atol=1e-9)


def test_a_block_is_reentrant_and_keeps_its_hints():
    from geometry.machine.meshing import WarmSeeds, warm_seeds_active

    seeds = WarmSeeds()
    with seeds:
        with seeds:
            assert warm_seeds_active()
        assert warm_seeds_active()
    assert not warm_seeds_active()
    assert seeds.used == 0 and seeds.searched == 0
