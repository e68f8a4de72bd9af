"""Numbers in the texts users read (geometry.core.text.plain_number): plain digits, four
significant figures, never an exponent for a torque, pressure, angle or length.

Round 19 of issue 71: ``ltca synthesize`` of an industrial 24x36 (m_et 13 mm) printed
"design torque: 1.044e+04 N m" (``.4g``), and ``ltca run``'s LTE-between line "at 72.8667 /
120.533 N m" (``g``). The expected strings below are written by hand from the rule
(rounded to four significant figures, positional, trailing zeros dropped): exact text.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

from geometry.core.text import plain_number


@pytest.mark.parametrize(("value", "text"), [
    (10440.0, "10440"),  # the industrial pair's ISO capacity: "1.044e+04" with .4g
    (1.044e4, "10440"),
    (10437.3, "10440"),  # four significant figures, the rest zeros
    (15660.0, "15660"),
    (852.24, "852.2"),
    (72.8667, "72.87"),  # the lte_range line's 72.8667 with g
    (120.533, "120.5"),
    (0.0452, "0.0452"),  # trailing zeros dropped
    (0.1, "0.1"),
    (330.0, "330"),  # no trailing point
    (1566.0, "1566"),
    (999999.0, "1000000"),  # rounding carries into the next decade, still plain
    (1.0e6, "1000000"),
    (1234567.0, "1235000"),
    (9.99996, "10"),
    (0.000123, "0.000123"),  # tiny but still a value users meet: plain
    (0.0001, "0.0001"),
    (1.5e-7, "1.5e-07"),  # below 1e-4 only a degenerate value: an exponent
    (1.0e12, "1e+12"),
    (0.0, "0"),
    (-0.0, "0"),
    (-72.8667, "-72.87"),
    (-10440.0, "-10440"),
    (np.float64(10440.0), "10440"),
    (math.nan, "NaN"),
    (math.inf, "inf"),
    (-math.inf, "-inf"),
])
def test_plain_number(value, text):
    assert plain_number(value) == text


def test_plain_number_digits():
    assert plain_number(10437.3, digits=6) == "10437.3"
    assert plain_number(72.8667, digits=1) == "70"
    assert plain_number(72.8667, digits=2) == "73"
    with pytest.raises(ValueError, match="digits: must be >= 1, got 0"):
        plain_number(1.0, digits=0)


def test_plain_number_agrees_with_4g_where_it_has_no_exponent():
    """Where ``.4g`` writes no exponent (1e-4 ≤ |x| < 1e4) the text is the same: the
    messages of smaller designs read as before."""
    rng = np.random.default_rng(19)
    for x in 10.0 ** rng.uniform(-4, 4, 2000):
        assert plain_number(x) == f"{x:.4g}", x


def test_the_run_line_of_a_large_torque_has_no_exponent():
    """``ltca run``'s LTE-between line of an industrial pair (the lte_range step's torques
    between 7287 and 12050 N m) in plain digits (a stand-in ``/ltca``)."""
    from contact.commands.run import lte_between_line

    t = [4000.0, 7286.67, 12053.3, 16000.0]
    ds = xr.Dataset({"lte_peak_to_peak": (("torque",), [40.0, 50.0])},
                    coords={"torque": [4000.0, 16000.0]})
    ds = ds.assign_coords(lte_torque=("lte_torque", np.asarray(t)))
    ds["lte_range_peak_to_peak"] = (("lte_torque",), np.array([40.0, 45.2, 48.0, 50.0]))
    ds["lte_range_source"] = (("lte_torque",), np.array([0, 1, 1, 0], np.int8))
    line = lte_between_line(ds)
    assert line.endswith(": 45.2 / 48.0 urad at 7287 / 12050 N m")
    assert "e+0" not in line


def test_the_synthesize_note_of_a_large_torque_has_no_exponent():
    """``ltca synthesize``'s LTE note of the developed bearing for the industrial 24x36's
    10440 N m (a stand-in development result, nothing analysed)."""
    from contact.commands.synthesize import low_overlap_lte

    dev = SimpleNamespace(best=SimpleNamespace(metrics={"lte_peak_to_peak": [20.0, 30.0]}),
                          torque=(1566.0, 10440.0), coast={"lte_peak_to_peak": [25.0, 35.0]},
                          coast_design_torques=(1566.0, 15660.0),
                          targets=SimpleNamespace(max_lte=40.0), lte_reach=None)
    text = low_overlap_lte(dev)
    assert text.startswith("the developed bearing's LTE p-p: drive 20/30 urad at "
                           "1566/10440 N m, coast 25/35 urad at 1566/15660 N m (light/design)")
    assert "e+0" not in text


def test_the_default_run_says_its_torques_and_hours_in_plain_digits(default_run_file):
    """The default run's texts: the verdict's finite-life hours (9.6e7 gear load cycles
    at 1500 rpm, 1067 h) read "1070 h", not "1.07e+03 h"; its LTE between the torques at
    550/3 N·m reads "183.3 N·m", not "183.333"."""
    from contact.commands.run import lte_between_line
    from contact.study.verdicts import verdict
    from geometry.core.io import read_netcdf

    tree = read_netcdf(default_run_file, tree=True)
    reasons = [f.reason for f in verdict(tree).findings]
    hours = [r for r in reasons if " h at 1500 rpm" in r]
    assert hours and not any("e+0" in r.split("cycles, ")[1] for r in hours)
    assert any("pinion load cycles, 1070 h at 1500 rpm" in r for r in hours)
    assert lte_between_line(tree["ltca"]).endswith(" urad at 116.7 / 183.3 N m")


@pytest.mark.parametrize(("given", "runs"), [
    (2865.6, "2865"),  # the round-20 19x57: 4 digits rounded read "2866"
    (99.96, "99.9"),  # 0.1 N m floor; 4 digits read "99.96", above it
    (99.996, "99.9"),  # 4 digits read "100"
    (3184.0, "3184"),  # nothing to round: the given torque, no aside
])
def test_the_printed_design_torque_is_the_one_the_case_runs(given, runs):
    """``ltca synthesize``'s "design torque:" line prints the torque the development
    analysed and writes as the case's operating design torque (``case_torques``, rounded
    down by ``floor_torque``), not the given one rounded to nearest: round 20 of issue 71,
    the 19x57 given 2865.6 N m printed "2866 N m" and ran at 2865. The given torque is
    named where the rounding lowered it; without the development (no operating torque
    written from it) the line prints the ``[rating] design_torque`` written, unrounded."""
    from contact.optimize.development_result import case_torques
    from contact.optimize.written_notes import design_torque_line

    why = "[synthesis] design_torque of the basic file"
    written = case_torques(0.15, given)  # DevelopmentResult.torque, as recorded() writes it
    line = design_torque_line(given, why, SimpleNamespace(torque=tuple(written)))
    number = line.removeprefix("  design torque: ").split(" N m")[0]
    assert number == runs
    assert float(number) == written[1]
    aside = f" ({given:g} N m given, rounded down: the torque the case runs)"
    assert line == (f"  design torque: {runs} N m, {why}"
                    + (aside if written[1] < given else ""))
    # --no-development: the given torque is the [rating] design_torque written, as given
    plain = design_torque_line(given, why, None)
    assert plain == f"  design torque: {given:g} N m, {why}"
    assert float(plain.split()[2]) == given
    assert design_torque_line(math.nan, "none: no rating", None) == (
        "  design torque: none: no rating")
