"""The bundled reference design of the seed's 11×41 pair (issue 19, item 3), the default case.

``cases/kolivand2009_fm_11x41_reference.toml`` is written by ``ltca optimize`` from
``cases/basic/kolivand2009_fm_11x41_reference.toml`` (synthesis prescriptions and
settings chosen against the loaded analysis; docs/optimize.md, "Reference design"). These
tests check, by an analysis independent of the optimiser's log (``run_analysis`` of the
written file, at the case's own ``[operating]`` conditions: the seed's Table 3.1), that it
meets the limits the issue states, that its flank peak has converged in the roll
positions, and that the file is what its basic file and ``[optimize]`` record give.

Seed values (Fig. 3.6, Table 3.1): LTE mean ≈ 110 / 290 / 600 µrad, LTE peak-to-peak
12.8 / 15.9 / 21.9 µrad at 50 / 250 / 500 N·m.
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.ltca import LTCAOptions
from contact.pipeline import run_analysis
from contact.study.summary import point_summary
from geometry.case import load_case

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "kolivand2009_fm_11x41_reference.toml"
BASIC = ROOT / "cases" / "basic" / "kolivand2009_fm_11x41_reference.toml"
SEED_LTE_MEAN = np.array([110.0, 290.0, 600.0])  # [µrad], seed Fig. 3.6


@cache
def _case():
    return load_case(CASE)


@cache
def _run(rolls_per_cycle: int = 20, torque: tuple = (50.0, 250.0, 500.0)):
    case = _case()
    tree = run_analysis(case, list(torque), options=LTCAOptions(
        rolls_per_cycle=rolls_per_cycle), deviations=False, geometry=False, operating=False)
    return tree, point_summary(tree, case)


def test_the_case_holds_the_seed_table_3_1_conditions():
    op = _case().operating
    assert tuple(op.torque) == (50.0, 250.0, 500.0)
    m = _case().misalignment
    assert (m.delta_E, m.delta_P, m.delta_G, m.delta_Sigma) == (-0.15, 0.12, 0.0, 0.0)


def test_reference_design_meets_the_edge_pressure_and_mean_limits():
    """At Table 3.1, with the edge-contact model on (the default), every roll certified,
    at 40 roll positions per cycle (where the flank peak has converged, below):

    * edges ≤ 1 % of the torque at 50 N·m and ≤ 5 % at 500 N·m (measured 0.27 / 1.6 /
      4.3 %),
    * flank peak pressure at 500 N·m ≤ 2.0 GPa (measured 0.69 / 1.28 / 1.85 GPa),
    * LTE means within ×1.5 of the seed's 110 / 290 / 600 µrad (measured 152 / 395 /
      632 µrad).

    The limits are the issue's, not fitted to the result. The edge peaks stay high
    (2.4 / 4.8 GPa, and at 500 N·m the plastic limit of the edges, 5.26 GPa, where the
    segments at it carry at most 2.5 % of the torque at a roll: issue 37; elastic they
    reach 6.4 GPa) on that small share of the torque."""
    tree, s = _run(40)
    assert np.all(s["certified"] > 0)
    e = s["edge_load_share"]
    assert e[0] <= 0.01 and e[-1] <= 0.05, e
    assert s["pressure_max_flank"][-1] <= 2000.0, s["pressure_max_flank"]
    ratio = s["lte_mean"] / SEED_LTE_MEAN
    assert np.all((ratio >= 1 / 1.5) & (ratio <= 1.5)), s["lte_mean"]
    assert tree["/ltca"].to_dataset()["found"].all()


def test_lte_peak_to_peak_meets_the_limit_at_the_default_roll_positions():
    """At ``ltca run``'s 20 roll positions per cycle the LTE peak-to-peak lies in 5–25 µrad
    at each torque (measured 16.4 / 15.4 / 22.6 µrad; the seed's 12.8 / 15.9 / 21.9)."""
    pp = _run()[1]["lte_peak_to_peak"]
    assert np.all((pp >= 5.0) & (pp <= 25.0)), pp


def test_lte_peak_to_peak_meets_the_limit_when_converged():
    """The issue's LTE peak-to-peak limit (5–25 µrad) at 40 roll positions per cycle
    (measured 16.7 / 15.5 / 22.6 µrad) and at 80 (250 and 500 N·m, where it rises; the
    sampling the final optimisation ranked designs at, against 23 µrad: measured 15.6 /
    22.7 µrad; at 160, not tested for the budget, 15.7 / 22.8). A contact onset is a kink
    of the LTE between samples, so the peak-to-peak creeps up as the rolls are refined (an
    earlier result met the limit at 20 rolls and failed at 40: 28.5 µrad at 500 N·m; the
    one before this, ranked at 40 rolls on the ease-off with holes at the pinion's flankrem
    corner, gave 26.4 / 27.6 µrad at 40 / 80 rolls once the corner was filled)."""
    pp = _run(40)[1]["lte_peak_to_peak"]
    assert np.all((pp >= 5.0) & (pp <= 25.0)), pp
    pp = _run(80, (250.0, 500.0))[1]["lte_peak_to_peak"]
    assert np.all((pp >= 5.0) & (pp <= 25.0)), pp


def test_flank_peak_pressure_converges_in_the_roll_positions():
    """Doubling the roll positions from 40 to 80 per cycle moves the flank peak pressure
    at 500 N·m by at most 2 % (the issue's criterion; measured 1848 → 1848 MPa, 1855 at
    160; the unrelieved long-bearing case's peak sat on a tiny end segment by the gear-tip
    edge and did not settle). ``ltca run``'s 20 give 1848 MPa too."""
    p40 = _run(40)[1]["pressure_max_flank"][-1]
    p80 = _run(80, (250.0, 500.0))[1]["pressure_max_flank"][-1]
    assert abs(p80 / p40 - 1.0) <= 0.02, (p40, p80)


@pytest.mark.slow  # two syntheses, ~30 s in the suite; CI budget
def test_case_is_its_basic_design_at_the_recorded_optimum():
    """The file is reproducible from what it records: the basic file synthesised, with the
    result values of its ``[optimize]`` table set by :func:`contact.optimize.case_at`,
    gives the same drive-flank settings and blade (1e-9 relative: the values are stored
    to 12 digits)."""
    from contact.optimize import case_at
    from geometry.synthesis.basic_design import load_basic
    from geometry.synthesis.case_synthesis import synthesize

    case = _case()
    table = case.extra["optimize"]
    assert table["basic_design"] == "basic/kolivand2009_fm_11x41_reference.toml"  # beside the case
    names = list(table["variables"])
    values = [table["variables"][n]["result"] for n in names]
    basic = load_basic(BASIC)
    start = dataclasses.replace(synthesize(basic)[0], name=case.name)
    again = case_at(start, "concave", names, values, basic=basic)
    a, b = again.pinion.concave, case.pinion.concave
    for field in ("radial_setting", "cradle_angle", "ratio_of_roll", "sliding_base",
                  "blank_offset", "tilt", "swivel"):
        assert getattr(a.machine, field) == pytest.approx(getattr(b.machine, field),
                                                          rel=1e-9, abs=1e-12)
    # the modified roll is the Newton result of TEs followed to the contact solve's
    # residual (1e-7, geometry.synthesis.modified_roll): reproducible to that, not to the
    # settings' round-off (measured 3.7e-7 relative after the local synthesis' Newton
    # started from the last trial's root instead of a seed search, the tools equal to
    # 1e-13); 2e-6 relative moves the TE at ±pitch/4 by < 1e-4 µrad
    np.testing.assert_allclose(a.machine.modified_roll, b.machine.modified_roll, rtol=2e-6,
                               atol=1e-12)
    np.testing.assert_allclose(a.machine.helical_motion, b.machine.helical_motion,
                               rtol=1e-9, atol=1e-12)
    for field in ("point_radius", "blade_angle", "flankrem_angle", "toprem_angle"):
        assert getattr(a.blade, field) == pytest.approx(getattr(b.blade, field), rel=1e-9)
