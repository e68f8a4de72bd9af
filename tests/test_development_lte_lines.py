"""``ltca synthesize``'s line on each flank's written LTE: at its two torques and the
largest between them (contact.optimize.development_lte_lines, issue 71: "LTE p-p <= 60
urad at every torque").

The numbers are those of round 21b's face-hobbed spiral bevel 25x31 (m_et 9.52 mm,
benchmarks/data/unseen_designs): coast 59 / 53 urad at 567 / 3780 N m, 69 urad at 1638 N m
between (``ltca run --flank coast``), and round 21's spiral bevel 17x38 by Method 0: drive
21 / 62 urad at 52.1 / 347.6 N m, 73 urad at 249.1 N m between. The lines are text of given
numbers: compared exactly.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from contact.optimize.development_lte_lines import flank_lte_line, inside, lte_lines


def test_a_peak_between_torques_within_the_limit_is_said_with_the_limit():
    line = flank_lte_line("coast", (567.0, 3780.0), (59.0, 53.0),
                          {"peak": 69.4, "at": 1638.0}, 60.0, 40.0)
    assert line == ("coast LTE p-p 59/53 urad at 567/3780 N m (light/design), 69.4 urad at "
                    "1638 N m between them: above the verdict's limit 60 urad between the "
                    "torques (ltca run --flank coast finds it there)")


def test_a_missed_design_torque_is_said_with_the_peak_between_above_it():
    line = flank_lte_line("drive", (52.1, 347.6), (21.0, 62.0),
                          {"peak": 72.9, "at": 249.1}, 60.0, 40.0)
    assert line == ("drive LTE p-p 21/62 urad at 52.1/347.6 N m (light/design), 72.9 urad "
                    "at 249.1 N m between them: above the verdict's limit 60 urad at its "
                    "torques and between them (ltca run finds it)")
    # the 18x27's coast (this branch): 66 / 60 urad at its torques, 61.7 between
    line = flank_lte_line("coast", (25.2, 168.6), (66.5, 59.6),
                          {"peak": 61.7, "at": 120.8}, 60.0, 40.0)
    assert line.endswith("61.7 urad at 120.8 N m between them: above the verdict's limit 60 "
                         "urad at its torques and between them (ltca run --flank coast finds "
                         "it)")


def test_within_the_target_nothing_is_said_and_the_target_alone_is_named():
    assert flank_lte_line("drive", (27.0, 180.0), (20.0, 37.0),
                          {"peak": 39.0, "at": 100.0}, 60.0, 40.0) is None
    line = flank_lte_line("drive", (27.0, 180.0), (20.0, 45.0),
                          {"peak": 41.0, "at": 120.0}, 60.0, 40.0)
    assert line.endswith("41.0 urad at 120 N m between them: within the verdict's limit 60 "
                         "urad, the development's target 40 urad missed")
    # met at both torques (the development's judgement), above the target between them
    # only: not "missed" beside synthesize's "every target met" (round 24's 14x39 FH:
    # 42.3 urad between, its ends within 40)
    line = flank_lte_line("drive", (43.6, 290.8), (20.0, 38.0),
                          {"peak": 42.3, "at": 200.0}, 60.0, 40.0)
    assert line.endswith("42.3 urad at 200 N m between them: within the verdict's limit 60 "
                         "urad; above the development's target 40 urad between the torques "
                         "only (the development judges it at the light and design torques: "
                         "met there)")
    # not judged between the torques (no record): said so
    assert "not judged between them" in flank_lte_line("drive", (27.0, 180.0), (20.0, 45.0),
                                                       None, 60.0, 40.0)
    assert flank_lte_line("drive", (1.0, 2.0), (math.nan, math.nan), None, 60.0, 40.0) is None


def test_the_development_s_lines_read_its_records_per_flank():
    dev = SimpleNamespace(
        targets=SimpleNamespace(max_lte=40.0),
        best=SimpleNamespace(metrics={"lte_peak_to_peak": np.array([23.0, 29.0])}),
        torque=(567.0, 3780.0), lte_range={"peak": 35.7, "at": 1370.0},
        coast={"lte_peak_to_peak": np.array([59.0, 53.0])},
        coast_design_torques=(567.0, 3780.0),
        coast_lte_range={"torques": (567.0, 1102.0, 1370.0, 1638.0, 2709.0, 3780.0),
                         "lte": (59.3, 56.9, 64.0, 68.6, 60.5, 52.6), "peak": 68.6,
                         "at": 1638.0})
    lines = lte_lines(dev)
    assert len(lines) == 1 and lines[0].startswith("coast LTE p-p 59/53 urad")
    assert "68.6 urad at 1638 N m between them" in lines[0]
    # no coast record: the analysis given instead
    dev.coast_lte_range = None
    assert "69.0 urad" in lte_lines(dev, coast_between={"peak": 69.0, "at": 1638.0})[0]


def test_every_target_met_at_two_torques_is_not_said_met_above_the_limit_between():
    """The headline's "every target met" of a design whose record between its torques is
    above 60 urad names that peak (and the record of another design is not read)."""
    from contact.optimize.development_result import DevelopmentEvaluation, DevelopmentResult

    values = {"ellipse_length": 0.4}
    e = DevelopmentEvaluation(3, values, {}, 1.0, {}, True, "", 0.0,
                              full=(1.0, {}, True), checked=True)
    fake = SimpleNamespace(best=None, coast_best=e, lte_range=None,
                           coast_lte_range={"peak": 68.6, "at": 1638.0, "values": values})
    fake._between_text = lambda x: DevelopmentResult._between_text(fake, x)
    assert DevelopmentResult.missed_text(fake, e) == (
        "every target met at its two torques, but LTE p-p 68.6 urad at 1638 N m between "
        "them (limit 60)")
    fake.coast_lte_range = {"peak": 58.1, "at": 1638.0, "values": values}
    assert DevelopmentResult.missed_text(fake, e) == "every target met"
    fake.coast_lte_range = {"peak": 68.6, "at": 1638.0, "values": {"ellipse_length": 0.5}}
    assert DevelopmentResult.missed_text(fake, e) == "every target met"


def test_inside_reads_the_torques_between_the_ends():
    """The record's ends (the light and the design torque) left out: the 18x27's coast
    (66.5 at its light torque, 61.7 between) reads 61.7."""
    record = {"torques": (25.2, 73.0, 120.8, 168.6), "lte": (66.5, 58.5, 61.7, 59.6)}
    assert inside(record) == {"peak": 61.7, "at": 120.8}
    assert inside({"torques": (1.0, 2.0), "lte": (3.0, 4.0)}) is None
    assert inside(None) is None
    assert inside({"peak": 5.0, "at": 1.0}) == {"peak": 5.0, "at": 1.0}
