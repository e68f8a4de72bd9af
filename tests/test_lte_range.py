"""The LTE p-p between the torques an analysis runs at (contact.ltca.lte_range, the chain's
``lte_range`` step, the verdict's ``lte`` check on it; issue 71: "LTE p-p ≤ 60 µrad at
every torque")."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import xarray as xr

from contact import AnalysisChain, run_analysis, verdict
from contact.ltca.lte_range import (
    LTE_BISECTIONS,
    LTE_TORQUES,
    bisected,
    lte_range,
    lte_range_torques,
)
from geometry.core.io import read_netcdf

#: the contact alone of the same case at the same torque, alone or in another batch of
#: torques: the LTCA's Newton and active-set iterations stop at 1e-9 of their scales
#: (tests/test_golden_run.py), so two analyses of one torque agree to that
SAME = 1e-9


def test_the_torques_judged():
    # a synthesised case's two torques: numpy.linspace, synthesize's note's torques
    assert lte_range_torques((97.4, 649.4), 649.4) == tuple(np.linspace(97.4, 649.4, 4))
    # the default run's 50 / 250 / 500 N m at a design torque of 250 N m: up to it
    assert lte_range_torques((500.0, 50.0, 250.0), 250.0) == pytest.approx(
        (50.0, 116.6667, 183.3333, 250.0), rel=1e-6)
    # the design torque between two analysed torques: the range ends at it
    assert lte_range_torques((100.0, 400.0), 250.0, n=3) == (100.0, 175.0, 250.0)
    # the run's own torques kept where they fall between the grid's
    assert lte_range_torques((10.0, 15.0, 40.0), n=4) == (10.0, 15.0, 20.0, 30.0, 40.0)
    # a grid torque within 1e-9 of an analysed one is that one
    assert lte_range_torques((10.0, 20.0 * (1 + 1e-12), 40.0), n=4) == (
        10.0, 20.0 * (1 + 1e-12), 30.0, 40.0)
    assert lte_range_torques((300.0,), 250.0) == ()  # nothing judged below the design torque
    assert lte_range_torques((100.0, 300.0), 100.0) == (100.0,)
    assert LTE_TORQUES == 4
    with pytest.raises(ValueError, match="n must be >= 2"):
        lte_range_torques((1.0, 2.0), n=1)
    with pytest.raises(ValueError, match="design torque NaN"):
        lte_range_torques((1.0, 2.0), math.nan)


def test_the_crossing_bisected():
    # the 16x16's shape: 38 / 53 / 109 / 117 at 97.4 / 281.4 / 465.4 / 649.4, a stand-in
    # LTE that jumps at 400 N m: the bracket 281.4-465.4 halved twice, 60 at the first
    seen = []

    def jump(t):
        seen.append(t)
        return 55.0 if t < 400.0 else 105.0

    t, y, added = bisected((97.4, 281.4, 465.4, 649.4), (38.0, 53.0, 109.0, 117.0), 60.0,
                           jump)
    assert LTE_BISECTIONS == 2
    assert added == (373.4, 419.4) == tuple(seen)
    assert t == (97.4, 281.4, 373.4, 419.4, 465.4, 649.4)
    assert y == (38.0, 53.0, 55.0, 105.0, 109.0, 117.0)
    # nothing to bracket: within at every torque, above at the first, NaN before it
    for lte in ((38.0, 53.0), (61.0, 70.0), (math.nan, 70.0)):
        assert bisected((1.0, 2.0), lte, 60.0, jump)[2] == ()
    assert len(seen) == 2
    with pytest.raises(ValueError, match="2 torques and 1 LTE"):
        bisected((1.0, 2.0), (1.0,), 60.0, jump)


def _ltca(torques, lte, between=None):
    """A stand-in ``/ltca``: LTE p-p at the run's torques and, optionally, ``between`` =
    (torques, LTE p-p, source) of the lte_range step."""
    ds = xr.Dataset({"lte_peak_to_peak": (("torque",), np.asarray(lte, float))},
                    coords={"torque": list(torques)})
    if between is not None:
        t, y, s = between
        ds = ds.assign_coords(lte_torque=("lte_torque", np.asarray(t, float)))
        ds["lte_range_peak_to_peak"] = (("lte_torque",), np.asarray(y, float))
        ds["lte_range_source"] = (("lte_torque",), np.asarray(s, np.int8))
    return ds


def test_the_lte_check_judges_the_torques_between():
    from contact.study.verdicts import _lte

    # the FH 8x35 k_d 2.16's shape: 47 / 58 urad at light and design, 64 / 76 between
    run = _ltca([100.0, 400.0], [47.0, 58.0])
    assert _lte(run, None, 60.0) == []  # the run's torques alone: nothing seen
    ds = _ltca([100.0, 400.0], [47.0, 58.0],
               ([100.0, 200.0, 300.0, 400.0], [47.0, 64.0, 76.0, 58.0], [0, 1, 1, 0]))
    found = _lte(ds, None, 60.0)
    assert [f.severity for f in found] == ["attention", "attention"]
    assert all("a torque between the run's" in f.reason for f in found)
    assert found[0].reason.startswith("LTE peak-to-peak 64 µrad at 200 N·m")
    # 60 urad at 100 + 13/17 * 100 N m, said once, on the largest torque above the limit,
    # with every torque's LTE and where the ones between come from
    clause = ("it stays within 60 µrad up to about 176.5 N·m (LTE p-p 47 / 64 / 76 µrad at "
              "100 / 200 / 300 N·m), interpolated linearly between the torques analysed for "
              "it (the run's and, between them, the contact alone's")
    assert clause not in found[0].reason
    assert clause in found[1].reason
    # a rating's design torque of 250 N m: the torque between above it is not judged
    rating = xr.Dataset({"design_torque": ((), 250.0)})
    (below,) = _lte(ds, rating, 60.0)
    assert "at 200 N·m" in below.reason and "71 % of the design torque" in below.reason
    # a torque between without a certified contact solution (NaN): not judged
    ds["lte_range_peak_to_peak"][2] = math.nan
    (left,) = _lte(ds, None, 60.0)
    assert "at 200 N·m" in left.reason


def test_the_run_prints_the_lte_between():
    from contact.commands.run import lte_between_line

    ds = _ltca([100.0, 400.0], [47.0, 58.0],
               ([100.0, 200.0, 300.0, 400.0], [47.0, 64.04, math.nan, 58.0], [0, 1, 1, 0]))
    assert lte_between_line(ds) == (
        "LTE p-p between the torques, the contact alone (/ltca/lte_range_peak_to_peak; the "
        "verdict judges them up to the design torque): 64.0 / nan urad at 200 / 300 N m")
    assert lte_between_line(_ltca([100.0], [47.0])) is None  # a file from before
    assert lte_between_line(_ltca([100.0], [47.0], ([100.0], [47.0], [0]))) is None


def _within(text: str) -> float:
    found = re.search(r"within [0-9.]+ u?µ?rad up to about ([0-9.]+) N", text)
    assert found is not None, text
    return float(found.group(1))


def test_run_and_synthesize_say_the_same_torque():
    """The run's lte_range step and ``ltca synthesize``'s deflection note
    (development_deflection.analysed) analyse the same torques of a case run at its light
    and design torque: the same LTE p-p at each (to :data:`SAME`) and the same torque
    within a limit, which the stand-in (the default case at 50 and 500 N m, no rating)
    crosses between its two torques."""
    from contact.catalogue import resolve_case
    from contact.optimize.development_deflection import analysed, deflection_text

    case = resolve_case(None)
    steps = AnalysisChain.contact_only().with_steps(lte_range="ltca")
    tree = run_analysis(case, [50.0, 500.0], steps=steps)
    lt = tree["/ltca"]
    torques = lt["lte_torque"].values
    assert list(lt["lte_range_source"].values) == [0, 1, 1, 0]
    note = analysed(case, 50.0, 500.0)  # synthesize's four torques, one batch
    assert note.torques == tuple(torques)
    np.testing.assert_allclose(lt["lte_range_peak_to_peak"].values, note.lte, rtol=SAME)
    # a limit the LTE crosses between the light torque and the next
    lte = np.asarray(note.lte)
    limit = 0.5 * (lte[0] + lte[1:].max())
    assert lte[0] < limit < lte[-1]
    run = [f.reason for f in verdict(tree, lte_limit=limit).findings if f.check == "lte"]
    said = deflection_text(note._replace(limit=limit))
    assert said is not None
    assert _within(run[-1]) == _within(said)
    assert _within(said) == pytest.approx(note._replace(limit=limit).within, rel=1e-3)
    assert 50.0 < _within(said) < 500.0
    # at that limit both bisect the crossing's interval alike: the same torques, the same
    # LTE at each (the step's function at the limit, the note's analyses at it)
    step = lte_range(lt.to_dataset(), case, limit=limit)
    bisecting = analysed(case, 50.0, 500.0, limit=limit)
    assert len(bisecting.torques) == len(torques) + LTE_BISECTIONS
    np.testing.assert_allclose(step["lte_torque"].values, bisecting.torques, rtol=1e-15)
    np.testing.assert_allclose(step["lte_range_peak_to_peak"].values, bisecting.lte,
                               rtol=SAME)
    assert list(step["lte_range_source"].values) == [0] + [1] * (len(torques) - 2
                                                               + LTE_BISECTIONS) + [0]


def test_the_default_run_judges_its_lte_between_its_torques(default_run_file):
    """The default run (50 / 250 / 500 N m, design torque 250 N m): the LTE p-p at 116.7
    and 183.3 N m from the contact alone, the same as an analysis of those torques; at a
    limit of 17.5 µrad the LTE keeps it at 50 and 250 N m and not at 183.3 N m, which the
    ``lte`` check names."""
    tree = read_netcdf(default_run_file, tree=True)
    lt = tree["/ltca"]
    t = lt["lte_torque"].values
    np.testing.assert_allclose(t, [50.0, 350.0 / 3.0, 550.0 / 3.0, 250.0], rtol=1e-15)
    y = lt["lte_range_peak_to_peak"].values
    np.testing.assert_array_equal(y[[0, 3]], lt["lte_peak_to_peak"].values[:2])
    alone = run_analysis(None, list(t[1:3]), steps=AnalysisChain.contact_only())
    np.testing.assert_allclose(y[1:3], alone["/ltca"]["lte_peak_to_peak"].values, rtol=SAME)
    assert y[0] < 17.5 and y[3] < 17.5 and y[2] > 17.5
    (finding,) = [f for f in verdict(tree, lte_limit=17.5).findings if f.check == "lte"]
    assert finding.reason.startswith("LTE peak-to-peak 18 µrad at 183.3 N·m (a torque between")
    assert "up to about" in finding.reason


def test_the_step_is_in_the_analysis_not_in_the_contact_alone():
    assert AnalysisChain().lte_range == "ltca"
    assert AnalysisChain.contact_only().lte_range is None
    assert AnalysisChain.analysis().without("lte_range").lte_range is None
