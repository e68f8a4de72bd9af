"""A coarse "all targets met" stop confirmed at the default sampling before it ends the
development's search (contact.optimize.development_confirm; issue 71, branch plastic102).

Round 41's FM spiral bevel 10x51 (benchmarks/data/unseen_designs/spiral_bevel_10x51_m0.toml)
stopped its drive search at design 6 of 36: the coarse search read plastic 0.0 % at
518.1 N·m, the check of the case as written 1.0 % (design 5: 0.0 against 1.4 %), and the
case was written with plastic at its design torque. The search's case has no tip planes
(the pinion's root line, next to which the gear's tip edge runs, not placed) and 8 roll
positions; measured in the module's docstring. Stand-ins for the analysis (their metrics
those measured numbers), so that the rule is checked without an LTCA and without the
wall clock.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from development_stand_ins import FLANK_GRID, metrics

from contact.optimize import development_evaluate
from contact.optimize.development import DevelopmentTargets, StageStop, development_score
from contact.optimize.development_confirm import REFUTED_STOPS, confirmer
from contact.optimize.development_evaluate import CHECK_LTCA, evaluator
from contact.optimize.development_result import DevelopmentEvaluation

#: the static strength the stand-in's grid returns [MPa] (the 10x51's flank, 2400 MPa)
STRENGTH = 2400.0
#: the development's torques [N·m] and the depth centre aimed at [1] (the 10x51's)
SETUP = {"torques": [77.7, 518.1], "centre_v": 0.6, "lowered": False, "source": "ISO"}


def _grid():
    return (*FLANK_GRID, STRENGTH)


def _design(plastic: float, **over) -> DevelopmentEvaluation:
    """A design the coarse search scored: every target met (its plastic share the
    coarse read, 0.0 on the 10x51's designs 5 and 6)."""
    m = metrics(plastic_share=[0.0, plastic], **over)
    full = development_score(m, DevelopmentTargets(), FLANK_GRID, centre_v=0.6,
                             pressure_limit=STRENGTH)
    return DevelopmentEvaluation(5, {"root_relief": 40.0}, m, full[0], full[1], full[2], "",
                                 0.0, case="coarse case", full=full, stage="height")


def _checked_law(monkeypatch, **check):
    """The analysis stand-in: at the default sampling (CHECK_LTCA) the metrics ``check``
    gives (the case as written), else the coarse search's (every target met); records
    the options of each call."""
    calls = []

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        calls.append(options)
        m = metrics(**check) if options is CHECK_LTCA else metrics()
        return m, _grid()

    monkeypatch.setattr(development_evaluate, "analyse_design", fake)
    return calls


def test_a_coarse_stop_the_check_refutes_on_plastic_is_refuted(monkeypatch):
    """The 10x51's design 6: the coarse search's "all met" (plastic 0.0 %) refuted where
    the case as written reads 1.0 % at the default sampling: the design returned with
    ``met`` False and the check's objective (plastic 1.0 % over the 0.1 % unit: a squared
    shortfall of (1.0 / 0.1)² = 100 at least), so the search walks away from it."""
    calls = _checked_law(monkeypatch, plastic_share=[0.0, 0.010])
    lines: list[str] = []
    confirm = confirmer(DevelopmentTargets(), dict(SETUP), None, lines.append,
                        lambda values: "case as written")
    e = _design(0.0)
    assert e.met and e.full[2]
    refuted = confirm(e)
    assert calls == [CHECK_LTCA]
    assert refuted is not None and not refuted.met and not refuted.full[2]
    assert refuted.shortfalls["plastic"] == pytest.approx(10.0)  # (1.0 - 0) % / 0.1 %
    assert refuted.objective >= 100.0 and refuted.objective == refuted.full[0]
    assert refuted.values == e.values and refuted.index == e.index
    assert "refuted (plastic 1.0 % as written" in lines[-1]
    assert "the search goes on" in lines[-1]


def test_a_check_that_misses_only_the_pattern_confirms_the_stop(monkeypatch):
    """A check that misses only the centre v (the coarse footprint a node off:
    checked_best's re-centring repairs it) or meets everything confirms the stop (None);
    one whose edge share at the design torque exceeds the limit (the default 2 %) refutes
    it as the plastic does."""
    for check, stands in (({"pattern_centre_v": [0.80, 0.80]}, True), ({}, True),
                          ({"edge_load_share": [0.0, 0.025]}, False)):
        _checked_law(monkeypatch, **check)
        lines: list[str] = []
        confirm = confirmer(DevelopmentTargets(), dict(SETUP), None, lines.append,
                            lambda values: "case as written")
        assert (confirm(_design(0.0)) is None) is stands, check
        assert ("stop confirmed" in lines[-1]) is stands


def test_refutations_are_bounded(monkeypatch):
    """At most REFUTED_STOPS refutations per search (each a placed synthesis and a check:
    CPU): past them a coarse "all met" stops the search as before (None, no analysis)."""
    calls = _checked_law(monkeypatch, plastic_share=[0.0, 0.014])
    confirm = confirmer(DevelopmentTargets(), dict(SETUP), None, lambda s: None,
                        lambda values: "case as written")
    for i in range(REFUTED_STOPS):
        e = _design(0.0)
        e = DevelopmentEvaluation(i, {"root_relief": 40.0 + i}, e.metrics, e.objective,
                                  e.shortfalls, True, "", 0.0, case="c", full=e.full)
        assert confirm(e) is not None
    assert len(calls) == REFUTED_STOPS
    e = _design(0.0)
    past = DevelopmentEvaluation(9, {"root_relief": 60.0}, e.metrics, e.objective,
                                 e.shortfalls, True, "", 0.0, case="c", full=e.full)
    assert confirm(past) is None and len(calls) == REFUTED_STOPS
    # a design asked again keeps its first answer (refuted), costing no check
    first = DevelopmentEvaluation(0, {"root_relief": 40.0}, e.metrics, e.objective,
                                  e.shortfalls, True, "", 0.0, case="c", full=e.full)
    assert confirm(first) is not None and len(calls) == REFUTED_STOPS


def test_a_design_the_check_cannot_place_keeps_the_stop(monkeypatch):
    """The case as written cannot be made (its error is the check's to say): the stop
    stands, as before the rule."""
    _checked_law(monkeypatch, plastic_share=[0.0, 0.010])

    def placed(values):
        raise RuntimeError("tip plane")

    confirm = confirmer(DevelopmentTargets(), dict(SETUP), None, lambda s: None, placed)
    assert confirm(_design(0.0)) is None


def _search_evaluator(monkeypatch, confirm):
    """The drive search's objective (:func:`evaluator`) with the coarse analysis a
    stand-in meeting every target; its set-up given (no design torque to rate)."""
    monkeypatch.setattr(development_evaluate, "analyse_design",
                        lambda *a, **k: (metrics(), _grid()))
    evals: list[DevelopmentEvaluation] = []
    evaluate = evaluator(object(), DevelopmentTargets(), dict(SETUP), None, lambda s: None,
                         evals, "drive", 36, confirm=confirm)
    return evaluate, evals


def test_the_search_goes_on_past_a_refuted_stop(monkeypatch):
    """:func:`evaluator` with ``confirm``: a design the coarse analysis scores "all
    met" raises no StageStop where ``confirm`` refutes it; its record (and the memo the
    simplex returns to) is the refuted design, so the relief stage's "a design met every
    target" test (``e.met``) does not end the search either. A design ``confirm`` lets
    stand stops it (StageStop), and without ``confirm`` the coarse "all met" stops it at
    once (the behaviour before)."""
    asked: list[int] = []

    def confirm(e):
        asked.append(e.index)
        if e.values["root_relief"] < 50.0:  # refuted: the check read plastic 1.0 %
            full = (116.0, {**e.full[1], "plastic": 10.0}, False)
            return DevelopmentEvaluation(e.index, e.values, e.metrics, 116.0, full[1], False,
                                         "", 0.0, case=e.case, full=full, stage=e.stage)
        return None

    evaluate, evals = _search_evaluator(monkeypatch, confirm)
    e = evaluate({"root_relief": 40.0}, "relief", lambda: "case", 36, ())
    assert e.objective == 116.0 and not e.met and not evals[-1].met
    again = evaluate({"root_relief": 40.0}, "relief", lambda: "case", 36, ())
    assert again is e and asked == [0]  # the memo: no second analysis, no StageStop
    assert not any(x.met for x in evals)
    with pytest.raises(StageStop):
        evaluate({"root_relief": 60.0}, "relief", lambda: "case", 36, ())
    assert asked == [0, 1] and evals[-1].met and len(evals) == 2

    evaluate, evals = _search_evaluator(monkeypatch, None)
    with pytest.raises(StageStop):
        evaluate({"root_relief": 40.0}, "relief", lambda: "case", 36, ())


def test_a_bearing_met_is_confirmed_where_the_relief_stage_reaches_it(monkeypatch):
    """The bearing stage scores fewer targets (no plastic, no edge): its "met" ends only
    that stage and is not checked at the default sampling, even where the design meets
    every target on the coarse read (the 10x51's bearing design 5). The relief stage
    starts from that bearing's values (the memo's relief copy, met): there the stop is
    confirmed, and refuted the relief stage goes on from the refuted design."""
    monkeypatch.setattr(development_evaluate, "analyse_design",
                        lambda *a, **k: (metrics(), _grid()))
    asked: list[int] = []

    def confirm(e):
        asked.append(e.index)
        full = (200.0, {**e.full[1], "plastic": 14.0}, False)
        return DevelopmentEvaluation(e.index, e.values, e.metrics, 200.0, full[1], False,
                                     "", 0.0, case=e.case, full=full, stage=e.stage)

    evals: list[DevelopmentEvaluation] = []
    evaluate = evaluator(object(), DevelopmentTargets(), dict(SETUP), None, lambda s: None,
                         evals, "drive", 36, confirm=confirm)
    values = {"path_angle": -65.6, "root_relief": 15.0}
    with pytest.raises(StageStop):
        evaluate(values, "bearing", lambda: "case", 36, ())
    assert asked == [] and evals[-1].full[2]
    e = evaluate(values, "relief", lambda: "case", 36, ())
    assert asked == [0] and not e.met and e.objective == 200.0 and len(evals) == 1


# --- the coast flank's search (branch coast104) -------------------------------------------

DESIGNS = Path(__file__).parent / "data" / "designs"


def _coast_search(monkeypatch, refuted_below: float):
    """``coast_development`` of the passenger-car hypoid (coast flank convex) with
    stand-ins: the synthesis returns the basic design (``placed`` and the coarse ``make``
    alike), the coarse analysis (8 rolls, no tip planes) meets every target on every
    design, and the check at the default sampling (CHECK_LTCA) reads the case as written:
    1.0 % of the design torque on plastic segments (the 10x51's design 6) where the coast
    root relief is below ``refuted_below`` [mm] and on the flank as synthesised (so that it
    is developed), every target met otherwise. Returns the outcome, the check's analyses
    at the development's torques as (root relief [mm] or None for the flank as synthesised,
    pinion key, the coast flank's options' repr) and the lines."""
    import geometry.synthesis.case_synthesis as cs
    from contact.optimize import development_coast_flank as dcoast
    from geometry.synthesis.basic_design import load_basic

    checks: list[tuple] = []

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        assert flank == "coast"
        if options is not CHECK_LTCA:
            return metrics(), _grid()
        relief = None if isinstance(case, str) else case.options.convex.root_relief
        if list(torques) == [50.0, 330.0]:  # (not the LTE between the torques)
            checks.append((relief, tuple(pinion_key),
                           None if isinstance(case, str) else repr(case.options.convex)))
        if misalignment is None and (relief is None or relief < refuted_below):
            return metrics(plastic_share=[0.0, 0.010]), _grid()
        return metrics(), _grid()

    monkeypatch.setattr(development_evaluate, "analyse_design", fake)
    monkeypatch.setattr(cs, "synthesize", lambda b, memo=None, **kw: (b, None))
    basic = load_basic(DESIGNS / "pc_hypoid_10x43.toml")
    drive = DevelopmentEvaluation(0, {"tip_relief": 20.0}, metrics(), 0.0, {}, True, "",
                                  0.0, "as synthesised", checked=True)
    setup = {"torques": [50.0, 330.0], "centre_v": 0.6, "source": "s", "lowered": False,
             "pressure_limit": STRENGTH}
    lines: list[str] = []
    out = dcoast.coast_development(basic, drive, DevelopmentTargets(coast_max_evaluations=20),
                                   setup, None, {}, lines.append, lambda b: b)
    return out, checks, lines


def test_the_coast_search_does_not_stop_on_a_coarse_all_met_the_check_refutes(monkeypatch):
    """The coast flank's search (development_coast_flank.coast_development) stopped at its
    first coarse "all targets met" as the drive's did before plastic102: here every design
    is met on the coarse read and the check refutes those with a coast root relief below
    a level no design of the search reaches (1 mm), so before the rule the search ended at
    its first design (1 evaluation); now each coarse "all met" is checked, refuted at
    most REFUTED_STOPS times, and the search ends at the next one (REFUTED_STOPS + 1
    designs). The refuted designs carry the check's objective (plastic 1.0 %: a
    shortfall of 10 units of 0.1 %), and the check's analyses are keyed as the coast
    check's (the drive bearing's key, then "coast"), so ``checked_best`` reads them back
    from its memo: each design analysed once at the default sampling (counted calls)."""
    out, checks, lines = _coast_search(monkeypatch, refuted_below=1.0)
    refuted = [e for e in out.evaluations if e.shortfalls.get("plastic", 0.0) > 0.0]
    # the first design met the bearing stage's fewer targets (not confirmed: no plastic,
    # no edge scored there); its relief-stage copy, designs 2 and 3 refuted; design 4's
    # coarse "all met" past REFUTED_STOPS refutations stops the search, as before
    assert len(out.evaluations) == REFUTED_STOPS + 1
    assert out.evaluations[0].stage == "bearing" and out.evaluations[-1].met
    assert len([x for x in lines if "refuted" in x]) == REFUTED_STOPS
    assert len(refuted) == REFUTED_STOPS - 1 and not any(e.met for e in refuted)
    for e in refuted:
        assert e.shortfalls["plastic"] == pytest.approx(10.0)  # (1.0 - 0) % / 0.1 %
    said = [x for x in lines if "its coarse 'all targets met'" in x]
    assert len(said) == REFUTED_STOPS and all("refuted (plastic 1.0 %" in x for x in said)
    # the check's analyses: the flank as synthesised, then the designs of the search and
    # the check steps' variants, under the coast's key (the drive bearing's key, here
    # empty: a tip relief only, then "coast"), so that checked_best reads each confirmed
    # design back from its memo: none analysed twice (counted calls)
    searched = [c for c in checks if c[0] is not None]
    assert searched and all(c[1][:1] == ("coast",) for c in searched)
    flanks = [c[2] for c in searched]
    assert len(flanks) == len(set(flanks))


def test_the_coast_search_stops_on_a_confirmed_all_met(monkeypatch):
    """The check confirms the coast search's coarse "all met" (every design met as
    written): the search stops at its first design, as before, the line saying so."""
    out, _, lines = _coast_search(monkeypatch, refuted_below=-1.0)
    assert len(out.evaluations) == 1 and out.evaluations[0].met
    assert any("check of coast design 1 at the default sampling" in x
               and "stop confirmed" in x for x in lines)


def test_the_check_does_not_print_a_confirmed_design_line_twice(monkeypatch):
    """The 10x51's log printed design 13's check line twice: once by the confirmation of
    the coarse stop, once by checked_best reading the same analysis back. The
    confirmation records the design it said (``said_lines``); checked_best then says a
    short line for it (same analysis, same numbers), and the full line for a design the
    confirmation did not check."""
    from contact.optimize.development_check import checked_best

    _checked_law(monkeypatch)  # the check meets every target: the stop confirmed
    lines: list[str] = []
    said: set[int] = set()
    setup = dict(SETUP)
    confirm = confirmer(DevelopmentTargets(), setup, None, lines.append,
                        lambda values: "case as written", said_lines=said)
    e = _design(0.0)
    assert confirm(e) is None and said == {e.index}
    assert lines[-1].endswith("the coarse search's stop confirmed")
    first = len(lines)
    best = checked_best([e], DevelopmentTargets(), setup, None, lines.append,
                        lambda values: "case as written", said_lines=said)
    assert best.index == e.index
    checks = [s for s in lines[first:] if s.startswith(f"  check of design {e.index + 1}")]
    assert checks == [f"  check of design {e.index + 1} at the default sampling: as "
                      "confirmed above"]
    # without the record (a design the confirmation did not check): the full line
    lines.clear()
    checked_best([e], DevelopmentTargets(), dict(SETUP), None, lines.append,
                 lambda values: "case as written")
    full = [s for s in lines if s.startswith(f"  check of design {e.index + 1}")]
    assert len(full) == 1 and "pattern" in full[0] and "as confirmed" not in full[0]
