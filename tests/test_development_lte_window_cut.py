"""An LTE-window cut is the contact ratio's, not the gear process's (issue 71, branch half88).

The FM spiral bevel 17x23 of benchmarks/data/unseen_designs (ε_vβ 0.93, rated 1449 N·m):
its generated gear's written drive bearing kept LTE p-p ≤ 60 µrad up to 537.1 N·m only
(contact.optimize.development_written_lte), below half the rated torque, which
``failed_outcome`` counted as a failed outcome; ``gear_process = "auto"`` then developed the
Formate gear in full (396.5 s CPU for synthesize) and ``better_outcome`` kept it at 612.7
N·m with drive LTE p-p 44.4 / 73.1 µrad and coast 105.7 / 73.8 µrad (docs/own_gear_set.md,
"Re-run on the rebased branch (after lte87)"). The rule tested here on stand-ins (no
LTCA): a torque cut is judged against the torque the LTE window set (``cut_reference``),
and a design within ``ltca run``'s LTE limit ranks above one beyond it (``lte_over``).
"""

from __future__ import annotations

import math
import types
from pathlib import Path

import numpy as np
import pytest

from contact.optimize import development_range_lte as drl
from contact.optimize.development_process import (
    CutForeseen,
    better_outcome,
    cut_reference,
    failed_outcome,
    lte_over,
    outclassing_torque,
    with_generated_gear,
)
from contact.optimize.development_result import DevelopmentResult
from geometry.synthesis.basic_design import load_basic


@pytest.fixture(autouse=True)
def _aim_at_the_verdicts_limit(monkeypatch):
    """The rule's choices written at its aim of 60 µrad: the development's sampling margin
    below the verdict's limit (development_range_lte.development_lte_limit) set to 0 here;
    the margin is tests/test_development_lte_margin.py's."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)


UNSEEN = Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"

#: the 17x23's rated torque (its ISO 10300 capacity) and the torques of its two outcomes
#: before this branch [N·m] (docs/own_gear_set.md)
RATED, WINDOW, FORMATE = 1449.0, 537.1, 612.7


def _outcome(process, *, torque, lowered=True, lte=(40.0, 50.0), coast_lte=(40.0, 50.0),
             between=None, lte_torque=math.nan, objective=1.0):
    """A stub DevelopmentResult with what the gear-process choice reads: LTE p-p [µrad] at
    the light and design torque of each flank, the drive's largest between them."""
    best = types.SimpleNamespace(
        metrics={"lte_spread": np.array([0.2, 0.1]), "plastic_share": np.zeros(2),
                 "lte_peak_to_peak": np.asarray(lte, float)}, objective=objective)
    gear = types.SimpleNamespace(settings=types.SimpleNamespace(process=process))
    return DevelopmentResult(
        basic=None, case=types.SimpleNamespace(process=process),
        report=types.SimpleNamespace(gear=gear), best=best, evaluations=(),
        torque=(0.15 * torque, torque), torque_source="", tolerance={}, targets=None,
        seconds=0.0, coast={"lte_spread": np.array([0.2, 0.1]),
                            "plastic_share": np.zeros(2),
                            "lte_peak_to_peak": np.asarray(coast_lte, float)},
        torque_lowered=lowered, lte_torque=lte_torque,
        lte_range=None if between is None else {"peak": between, "at": 0.5 * torque})


def _formate():
    """The 17x23's Formate outcome before this branch: cut to 612.7 of 1449 N·m by its
    pitting capacity, drive 44.4 / 73.1 µrad (66.6 between), coast 105.7 / 73.8 µrad."""
    return _outcome("Formate", torque=FORMATE, lte=(44.4, 73.1), between=66.6,
                    coast_lte=(105.7, 73.8))


def _generated():
    """Its generated outcome on this branch: developed again at the LTE window's upper
    end, 537.1 N·m; measured (`ltca run`): drive 42.4 / 44.4 µrad at 80.5 / 537.1 N·m, at
    most 44.6 between (the check's reading), coast 36.5 / 39.9 µrad."""
    return _outcome("Generate", torque=WINDOW, lte=(42.4, 44.4), between=44.6,
                    coast_lte=(36.5, 39.9), lte_torque=WINDOW, objective=30.0)


def test_a_cut_to_the_lte_window_is_no_failed_outcome():
    """537.1 of 1449 N·m is below 0.5 of the rated torque, but it is the LTE window's own
    torque: judged against it (cut_reference = min(rated, window)), no cut. Without the
    window (a pitting cut, as the Formate's 612.7) it fails as before; a root cut after
    the window below half of it fails, the text naming the window's torque."""
    generated = _generated()
    assert cut_reference(generated, RATED) == WINDOW
    assert failed_outcome(generated, RATED) == ""
    assert "cut to 612.7 of 1449 N m" in failed_outcome(_formate(), RATED)
    root_cut = _outcome("Generate", torque=250.0, lte_torque=WINDOW)
    assert failed_outcome(root_cut, RATED) == (
        "design torque cut to 250 of 537.1 N m, the drive LTE window's (rated 1449 N m) "
        "(below 0.5 of it)")
    # no window, no rated torque: nothing to judge against
    assert math.isnan(cut_reference(_outcome("Formate", torque=FORMATE), math.nan))


def test_lte_over_names_each_flank_s_largest_value_above_60_urad():
    """The verdict's limit 60 µrad (contact.study.verdicts.LTE_LIMIT) at the light and
    design torque and between them (the drive's lte_range peak): the Formate 17x23's drive
    73.1 µrad at 612.7 N·m and coast 105.7 µrad at its light torque (the coast torques
    default to the drive's here); 60.0 itself keeps it; NaN is not judged."""
    assert lte_over(_formate()) == ("drive LTE p-p 73.1 urad at 612.7 N m; coast LTE p-p "
                                    "105.7 urad at 91.91 N m")
    assert lte_over(_generated()) == ""
    assert lte_over(_outcome("Formate", torque=100.0, lte=(60.0, math.nan),
                             coast_lte=(math.nan, 60.0))) == ""
    assert lte_over(_outcome("Formate", torque=100.0, between=61.0)) == (
        "drive LTE p-p 61.0 urad at 50 N m")


def test_better_outcome_ranks_the_lte_limit_kept_above_the_higher_torque():
    """Where neither fails, or both do, the design within 60 µrad is kept over one beyond
    it whatever their torques; where both keep it, or both break it, the higher torque as
    before. A verdict FAIL still ranks below: a failed outcome first."""
    formate, generated = _formate(), _generated()
    # the 17x23 before this branch: both "failed" (both below 0.5 x 1449), Formate kept
    # on the higher torque; now the generated gear's window cut fails nothing
    assert better_outcome(formate, generated, RATED) == (generated, "second")
    # neither fails (no rated torque known): the LTE within the limit ranks first
    assert better_outcome(formate, generated, math.nan)[1] == "second"
    # both beyond the limit or both within it: the higher torque
    over = _outcome("Generate", torque=WINDOW, lte=(42.4, 75.0), lte_torque=WINDOW)
    assert better_outcome(_outcome("Formate", torque=FORMATE, lte=(44.4, 73.1)), over,
                          math.nan)[1] == "first"
    within = _outcome("Formate", torque=FORMATE)
    assert better_outcome(within, generated, math.nan)[1] == "first"
    # a verdict FAIL (LTE spread 0.58, above 0.5) within the LTE limit ranks below a
    # design beyond the limit that fails nothing
    fail = _generated()
    fail.best.metrics["lte_spread"] = np.array([0.58, 0.1])
    assert better_outcome(fail, _outcome("Formate", torque=FORMATE, lowered=False,
                                         lte=(44.4, 73.1)), RATED)[1] == "second"


def test_no_outclassing_torque_below_a_first_design_beyond_the_lte_limit():
    """outclassing_torque lets a second development stop once it cannot rank above the
    first; a first design beyond 60 µrad ranks below any second one within it, whose LTE
    is known only at its end: no stop (NaN). Within the limit the rule stands (the 13x37's
    110.4 of 279.2 N m, tests/test_synthesis_generated_gear.py)."""
    assert math.isnan(outclassing_torque(_formate(), RATED))
    assert outclassing_torque(_outcome("Formate", torque=110.4), 279.2) == 110.4
    # the first's own cut judged against its LTE window: not cut, no stop
    assert math.isnan(outclassing_torque(_generated(), RATED))


def test_the_generated_gear_kept_at_its_lte_window_without_the_formate_in_full(
        monkeypatch):
    """with_generated_gear on the 17x23's basic data: the Formate development stops on a
    foreseen cut (CutForeseen), the generated gear's ends at its LTE window (537.1 of 1449
    N·m): no failed outcome, so it is kept and the Formate gear is not developed in full
    (before: a third development, 396.5 s CPU for synthesize in all)."""
    import contact.load_capacity.iso10300.capacity as capacity

    monkeypatch.setattr(capacity, "with_design_torque", lambda case, t: (case, RATED, ""))
    basic = load_basic(UNSEEN / "spiral_bevel_17x23_m1.toml")
    given: list = []

    def run(b, **kw):
        given.append((b.options.gear_process, sorted(kw)))
        if b.options.gear_process == "Generate":
            return _generated()
        if kw.get("foresee_cut"):
            raise CutForeseen(600.0, RATED)
        return _formate()

    lines: list[str] = []
    kept = with_generated_gear(run, basic, lines.append)
    assert given == [("auto", ["foresee_cut"]), ("Generate", ["outclassed_below"])]
    assert kept.report.gear.settings.process == "Generate" and kept.torque[1] == WINDOW
    assert ("the generated gear's does not fail at 537.1 N m (its design torque the drive "
            "LTE window's, set by the contact ratio") in kept.gear_process_text
    assert "then the LTE p-p within ltca run's limit" in kept.gear_process_text


def test_the_re_development_names_its_torque_the_lte_window_s():
    """The drive developed again at the window's upper end gives the basic data a design
    torque; its progress line and the coast design torque's source said "[synthesis]
    design_torque" of a basic file that has none. window_name says what it is, and
    coast_capacity_said uses it in that place."""
    from contact.optimize import development_coast_flank as coast_flank
    from contact.optimize.development_written_lte import window_name

    assert window_name({"torques": [55.6, 371.2]}) == ""
    name = window_name({"lte_window": (36.377, 212.147, "48.9 / 83.9 urad")})
    assert name == ("the LTE window's upper end: the written drive bearing kept 60 urad at "
                    "every torque from about 36.4 to 212.1 N m only "
                    "(contact.optimize.development_written_lte)")
    basic = load_basic(UNSEEN / "spiral_bevel_17x23_m1.toml")
    given = basic.__class__(**{**basic.__dict__, "options": type(basic.options)(
        **{**basic.options.__dict__, "design_torque": WINDOW})})
    cap = types.SimpleNamespace(lowered=True, reason="at 537.1 N m flank peak ...")
    assert coast_flank.coast_capacity_said(given, cap, name) == (
        f"the drive's design torque 537.1 N m ({name}) is not the coast flank's: "
        "at 537.1 N m flank peak ...")
    assert coast_flank.coast_capacity_said(given, cap).startswith(
        "the drive's design torque 537.1 N m ([synthesis] design_torque)")
    # raised above the window's torque on the bearing developed there (_window_raised):
    # the torque as the development ended with it, and where it was raised from
    assert coast_flank.coast_capacity_said(given, cap, name, design=700.25) == (
        f"the drive's design torque 700.2 N m (raised from 537.1 N m, {name}) is not the "
        "coast flank's: at 537.1 N m flank peak ...")
    assert coast_flank.coast_capacity_said(given, cap, name, design=WINDOW) == (
        coast_flank.coast_capacity_said(given, cap, name))


@pytest.mark.parametrize("window, raised", [(WINDOW, False), (math.nan, True)])
def test_a_development_cut_by_its_lte_window_is_not_outclassed(window, raised):
    """development._outclassed stops a second development lowered below the first's
    torque (it would rank below it); a torque the LTE window lowered (setup["lte_torque"])
    is no failed outcome and may rank above: not stopped, unless lowered further below
    half of it."""
    from contact.optimize import development
    from contact.optimize.development_process import Outclassed

    setup = {"torques": [80.5, WINDOW], "lowered": True, "lte_torque": window}
    if raised:
        with pytest.raises(Outclassed):
            development._outclassed(setup, 600.0)
    else:
        development._outclassed(setup, 600.0)
    with pytest.raises(Outclassed):
        development._outclassed({"torques": [30.0, 200.0], "lowered": True,
                                 "lte_torque": WINDOW}, 600.0)


@pytest.mark.parametrize("rated", [RATED, 1000.0, math.nan])
@pytest.mark.parametrize("window", [WINDOW, 300.0, math.nan])
@pytest.mark.parametrize("torque", [100.0, 268.5, 268.55, 300.0, 612.7, 1449.0])
def test_cut_below_is_the_rule_failed_outcome_and_outclassed_wrote_inline(rated, window,
                                                                          torque):
    """cut_below (branch cpu89) is the one helper of the cut rule that _torque_cut and
    development._outclassed wrote inline before it: judged against the expressions as they
    stood (the reference: the smaller finite one of the rated and the window's torque; the
    stop: no window, or below half of it), exactly (a comparison, no tolerance). 268.55 is
    half the window's 537.1: not below it."""
    from contact.optimize import development
    from contact.optimize.development_process import Outclassed, cut_below

    finite = [t for t in (rated, window) if math.isfinite(t)]
    ref = min(finite) if finite else math.nan
    assert cut_below(torque, rated, window) == (math.isfinite(ref) and torque < 0.5 * ref)
    stopped = torque < 600.0 and not torque >= 0.5 * window  # _outclassed's former rule
    setup = {"torques": [0.15 * torque, torque], "lowered": True, "lte_torque": window}
    if stopped:
        with pytest.raises(Outclassed):
            development._outclassed(setup, 600.0)
    else:
        development._outclassed(setup, 600.0)
    result = _outcome("Generate", torque=torque, lte_torque=window)
    assert bool(failed_outcome(result, rated)) == cut_below(torque, rated, window)
