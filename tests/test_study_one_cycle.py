"""A study point's LTCA over one mesh cycle (issue 75): the same summaries as the study's
own ``cycles``, and one cycle's segments handed out as computed.

The rolls of the later mesh cycles repeat the first cycle's (their targets agree to 1e-12
pitch, :func:`contact.ltca.segments.roll_phases`) and every summary of a point is over
whole cycles, so a point analysed over one cycle equals :func:`contact.run_analysis` over
the study's cycles but for the order of floating-point sums (20 or 8 rolls summed instead
of 40 or 24): 1e-12 relative, as tests/test_study.py's comparison of a study with single
analyses (measured ≤ 4e-16, the LTE harmonics ≤ 1e-14 of the largest, docs/performance.md
"A study point over one mesh cycle").
"""

from __future__ import annotations

import dataclasses

import numpy as np
from threadpoolctl import threadpool_limits

from contact.catalogue import resolve_case
from contact.chain import AnalysisChain
from contact.ltca import LTCAOptions, segment_geometry
from contact.ltca.options import edge_radii
from contact.pipeline import run_analysis
from contact.study import SUMMARY_VARIABLES, point_summary
from contact.study.engine import analyse_point, one_cycle
from contact.study.points import StudyInputs
from contact.utca.easeoff import ease_off
from contact.utca.transitions import cycle_transitions

#: coarse, as tests/test_study.py (what is tested does not depend on the resolution)
OPTIONS = LTCAOptions(rolls_per_cycle=8, segments=8, cycles=3)
TORQUE = 250.0


def test_one_cycle_changes_only_the_cycles():
    opts = one_cycle(OPTIONS)
    assert opts.cycles == 1
    assert dataclasses.replace(opts, cycles=OPTIONS.cycles) == OPTIONS
    single = LTCAOptions(cycles=1)
    assert one_cycle(single) is single


def test_a_point_over_one_cycle_equals_run_analysis_over_three():
    """The point's summaries (one cycle) equal those of run_analysis over the study's three
    cycles at the same misalignment, to 1e-12 (the order of sums, module docstring)."""
    case = resolve_case(None)
    shared = StudyInputs(case=case, torque=(TORQUE,), options=OPTIONS)
    point = {"delta_E": case.misalignment.delta_E + 0.04,
             "delta_P": case.misalignment.delta_P - 0.02}
    res = analyse_point(shared, 0, point)
    assert res.status == 0, res.reason
    mis = dataclasses.replace(case.misalignment, delta_E=point["delta_E"],
                              delta_P=point["delta_P"])
    with threadpool_limits(1):  # as a study's workers: sums in the same order
        tree = run_analysis(dataclasses.replace(case, misalignment=mis), [TORQUE],
                            options=OPTIONS, theoretical=False,
                            steps=AnalysisChain.contact_only().with_root_stress(False))
    assert tree["/ltca"].sizes["roll"] == 3 * OPTIONS.rolls_per_cycle
    ref = point_summary(tree, case)
    for name in SUMMARY_VARIABLES:
        np.testing.assert_allclose(res.summary[name], ref[name], rtol=1e-12, atol=1e-12,
                                   err_msg=name)


def test_one_cycles_segments_are_the_computed_ones_read_only():
    """Over one cycle every roll is its own: the segments are those of the first cycle of
    a two-cycle call bit for bit, handed out without a copy (read-only: the analysis only
    reads them); over two cycles the second cycle's rolls are writable copies of the
    first's."""
    case = resolve_case(None)
    eo = ease_off(case)
    m1, _ = cycle_transitions(eo)
    n = 8
    roll = m1 + np.arange(2 * n) * eo.pitch / n
    pairs, step = (-1, 0, 1, 2), (0.25, edge_radii(case, LTCAOptions()))
    two = segment_geometry(case, eo, roll, pairs, 8, edges=step)
    one = segment_geometry(case, eo, roll[:n], pairs, 8, edges=step)
    np.testing.assert_array_equal(one.source, np.arange(n))
    np.testing.assert_array_equal(two.source, np.r_[np.arange(n), np.arange(n)])
    for name, a in one.per_segment().items():
        b = two.per_segment()[name]
        np.testing.assert_array_equal(a, b[:n], err_msg=name)
        np.testing.assert_array_equal(b[n:], b[:n], err_msg=name)
        assert not a.flags.writeable, name
        assert b.flags.writeable, name
