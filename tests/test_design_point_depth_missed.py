"""The mean point's refusal says where the working-depth line is not generated
(``geometry.pair.design_point``; round 36 of issue 71's unseen designs, branch unseen98).

The FM spiral bevel 14x19 at Sigma 60 deg (benchmarks/data/unseen_designs,
``spiral_bevel_14x19_s60_m0.toml``) stopped every gear process with "the gear flank is not
generated along the working depth at the mean cone distance" alone; with the generated gear
the lowest of the nine points (the pinion's mean addendum below the gear's pitch cone) is
the one missed. The words are checked on the helper directly (exact text, the heights its
own arguments); the design's generated gear synthesises since branch gen98 (the miss was
the envelope solver's on the 1-D line, tests/test_design_point_line_retry.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from geometry.pair.design_point import _depth_missed

BASIC = (Path(__file__).parent.parent / "benchmarks" / "data" / "unseen_designs"
         / "spiral_bevel_14x19_s60_m0.toml")


def test_the_words_name_the_points_missed():
    offs = np.linspace(-4.79, 1.60, 9)
    ok = np.ones(9, bool)
    assert _depth_missed(offs, ok) == ""
    ok[0] = False
    assert _depth_missed(offs, ok) == (
        ": its lowest point, where the pinion tip reaches, at -4.79 mm from the pitch cone, "
        "is not generated (the line runs -4.79 to +1.60 mm: the pinion's mean addendum below "
        "the pitch cone to the gear's above)")
    ok[:] = True
    ok[-1] = False
    assert _depth_missed(offs, ok).startswith(": the gear tip, at +1.60 mm")
    ok[:] = True
    ok[:3] = False
    assert _depth_missed(offs, ok).startswith(": 3 of its 9 points, at -4.79 to -3.19 mm")


def test_the_14x19_generated_gear_synthesises():
    """Since branch gen98 the 14x19's generated gear is synthesised: its lowest point was a
    miss of the envelope solver on the 1-D line, re-solved from its neighbour
    (tests/test_design_point_line_retry.py)."""
    import dataclasses

    import geometry
    from geometry.synthesis.case_synthesis import synthesize

    basic = geometry.load_basic(BASIC)
    basic = dataclasses.replace(basic, options=dataclasses.replace(
        basic.options, gear_process="Generate"))
    case, _ = synthesize(basic)
    for flank in ("concave", "convex"):
        assert case.gear.flank(flank).machine.process == "Generate"
