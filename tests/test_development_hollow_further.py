"""The written drive profile one step hollower after a design-torque cut
(:mod:`contact.optimize.development_hollow_further`, issue 71).

Stand-ins with the FM spiral bevel 7x29's measured numbers (docs/synthesis.md, "The
13×33's hollow profile against the edge levers" and "The 7×29's hollow profile one step
further"): written −5 µm, LTE 32.7 / 41.2 µrad at 4.7 / 31.7 N·m against the target 40,
floor 21 µrad; −6 µm 30.6 / 39.9 µrad, flank peak 1600 MPa within the local pitting limit
1606.4 MPa; −7 µm 1613 MPa above it. The analyses are replaced (the step's own is
:func:`~contact.optimize.development_hollow_limit.hollow_probes`', whose record is tested
on a real analysis in tests/test_development_hollow_limit.py); the gate, the designs and
the keep rule are the module's own, the keep rule's ranking and lost targets the check's
(:func:`~contact.optimize.development_keep.kept_why`), its tolerance replaced.
"""

from __future__ import annotations

import math
import types

import numpy as np

from contact.optimize import development_hollow_further as dhf
from contact.optimize import development_keep as dk
from contact.optimize.development_hollow_limit import HOLLOW_STEP, HollowProbe
from contact.optimize.development_result import DevelopmentEvaluation

TARGETS = types.SimpleNamespace(max_lte=40.0, max_edge_share=0.02)
SETUP = {"torques": [4.7, 31.7], "centre_v": 0.55}


def _design(crowning, lte, missed=("lte",), plastic=0.0, edge_light=0.0, objective=None):
    shortfalls = {k: (1.0 if k in missed else 0.0) for k in ("lte", "length", "centre_v")}
    met = not missed
    metrics = {"lte_peak_to_peak": np.array(lte, float),
               "plastic_share": np.array([0.0, plastic]),
               "pressure_max_edge": np.array([edge_light, 0.0]),
               "edge_contact_share": np.array([0.0, 0.0])}
    obj = (0.5 if met else 1.0 + sum(shortfalls.values())) if objective is None else objective
    return DevelopmentEvaluation(
        index=32, values={"profile_crowning": crowning, "tip_relief": 12.0}, metrics=metrics,
        objective=obj, shortfalls=shortfalls, met=met, reason="", seconds=0.0,
        case=f"case {crowning:g}", full=(obj, shortfalls, met), checked=True,
        stage="written")


def _probe(crowning, lte, peak, plastic=0.0, pitting=1606.4):
    return HollowProbe(crowning=crowning, lte=lte, edge_share=0.0, edge_shares={},
                       plastic=plastic, flank_peak=peak, peak_v=0.86,
                       pitting_limit=pitting, static=2400.0)


WRITTEN = _design(-5.0, (32.7, 41.2))
#: the 7x29 at −6 / −7 µm (measured, branch lte97)
MINUS_6 = (_design(-6.0, (30.6, 39.9), missed=()), _probe(-6.0, (30.6, 39.9), 1600.0))
MINUS_7 = (_design(-7.0, (33.3, 38.6), missed=()), _probe(-7.0, (33.3, 38.6), 1613.0))


def test_the_gate_only_where_the_profile_is_hollow_and_the_target_missed_above_the_floor():
    """The 7x29 as written (cut, −5 µm, 41.2 µrad against 40, floor 21): the step runs.
    Not without the cut, on a profile not hollow, with the target met, with the floor at
    or above the target (the contact ratio's, not the bearing's) or unknown, above the
    verdict's limit (other steps act there) or on a design not checked."""
    assert dhf.further_runs_on(WRITTEN, TARGETS, True, 21.0)
    assert not dhf.further_runs_on(WRITTEN, TARGETS, False, 21.0)
    assert not dhf.further_runs_on(_design(0.0, (32.7, 41.2)), TARGETS, True, 21.0)
    assert not dhf.further_runs_on(_design(-5.0, (32.7, 40.0)), TARGETS, True, 21.0)
    assert dhf.further_runs_on(_design(-5.0, (40.5, 39.0)), TARGETS, True, 21.0)
    assert not dhf.further_runs_on(WRITTEN, TARGETS, True, 40.0)
    assert not dhf.further_runs_on(WRITTEN, TARGETS, True, math.nan)
    assert not dhf.further_runs_on(_design(-5.0, (32.7, 61.0)), TARGETS, True, 21.0)
    unchecked = DevelopmentEvaluation(**{**WRITTEN.__dict__, "checked": False})
    assert not dhf.further_runs_on(unchecked, TARGETS, True, 21.0)


def test_the_designs_one_and_two_steps_hollower_at_the_size_scale():
    """At most :data:`FURTHER_DESIGNS` (2), :data:`HOLLOW_STEP` × the size scale apart,
    shallowest first: −5 µm at scale 1 → −6, −7; at 0.5 → −5.5, −6; none without a
    crowning or a size scale."""
    assert dhf.FURTHER_DESIGNS == 2 and HOLLOW_STEP == 1.0
    assert dhf.further_crownings({"profile_crowning": -5.0}, 1.0) == [-6.0, -7.0]
    assert dhf.further_crownings({"profile_crowning": -5.0}, 0.5) == [-5.5, -6.0]
    assert dhf.further_crownings({}, 1.0) == []
    assert dhf.further_crownings({"profile_crowning": -5.0}, math.nan) == []


def test_the_keep_rule_adds_the_pitting_limit_plastic_and_the_light_edge():
    """−6 µm (1600 MPa within 1606.4) loses nothing; −7 µm (1613) the local pitting limit;
    a plastic share, an edge at the light torque and a met target lost are named."""
    assert dhf.further_lost(WRITTEN, *MINUS_6) == []
    assert dhf.further_lost(WRITTEN, *MINUS_7) == [
        "the local pitting limit (flank peak 1613.0 MPa above 1606.4 MPa at the design "
        "torque)"]
    plastic = _design(-6.0, (30.6, 39.9), missed=(), plastic=0.004)
    assert dhf.further_lost(WRITTEN, plastic, _probe(-6.0, (30.6, 39.9), 1600.0,
                                                     plastic=0.004)) == [
        "no plastic (plastic 0.4 %)"]
    edge = _design(-6.0, (30.6, 39.9), missed=(), edge_light=900.0)
    lost = dhf.further_lost(WRITTEN, edge, MINUS_6[1])
    assert len(lost) == 1 and lost[0].startswith("edge contact at the light torque")
    length = _design(-6.0, (30.6, 39.9), missed=("length",))
    assert dhf.further_lost(WRITTEN, length, MINUS_6[1]) == ["length"]


def _run(monkeypatch, readings, *, tolerant=True, cut=True, floor=21.0):
    """The step on the written 7x29 stand-in with ``readings`` (crowning → (design, probe))
    in place of the analyses; returns the result, the crownings written and the lines."""
    written, lines, floors = [], [], []

    def analysed(case, values, crowning, base, targets, setup):
        assert case == f"written {crowning:g}" and values["profile_crowning"] == crowning
        assert values["tip_relief"] == base.values["tip_relief"]  # only the crowning
        return readings[crowning]

    def write(values):
        written.append(values["profile_crowning"])
        return f"written {values['profile_crowning']:g}", "report"

    def read_floor():
        floors.append(floor)
        return floor

    monkeypatch.setattr(dhf, "analysed_further", analysed)
    monkeypatch.setattr(dk, "_tolerant_variant", lambda *a, **k: tolerant)
    monkeypatch.setattr(dk, "_less_intolerant_variant", lambda *a, **k: False)
    monkeypatch.setattr(dk, "_known_missed", lambda *a, **k: ())
    out = dhf.checked_hollow_further(WRITTEN, TARGETS, SETUP, None, lines.append, cut=cut,
                                     scale=1.0, floor=read_floor, write=write)
    return out, written, lines, floors


def test_the_7x29_keeps_minus_6_and_stops_there(monkeypatch):
    """−6 µm meets every target within the local pitting limit: kept, written with its
    case and report, the second design not tried; its reading is recorded for the
    ``ltca synthesize`` line, the floor not (the case written changed)."""
    out, written, lines, floors = _run(monkeypatch, {-6.0: MINUS_6, -7.0: MINUS_7})
    assert written == [-6.0] and floors == [21.0]
    assert out.best is MINUS_6[0] and out.case == "written -6" and out.report == "report"
    assert out.values["profile_crowning"] == -6.0 and out.probes == (MINUS_6[1],)
    assert math.isnan(out.floor)
    assert "profile_crowning -6" in lines[0] and "1600.0 MPa (local pitting limit 1606.4)" \
        in lines[0] and "every target met" in lines[0]
    assert lines[-1].startswith("development: the profile crowning -5 -> -6 um kept")


def test_nothing_kept_above_the_pitting_limit_or_not_tolerant(monkeypatch):
    """Both designs above the local pitting limit: nothing kept, the written design and
    the floor returned with both readings; −6 µm not tolerant: not kept either."""
    above = {-6.0: (MINUS_6[0], _probe(-6.0, (30.6, 39.9), 1610.0)), -7.0: MINUS_7}
    out, written, lines, _ = _run(monkeypatch, above)
    assert written == [-6.0, -7.0] and out.best is WRITTEN and out.case is None
    assert [p.crowning for p in out.probes] == [-6.0, -7.0] and out.floor == 21.0
    assert any("not kept: the hollow profile one step further misses the local pitting "
               "limit" in line for line in lines)
    assert lines[-1].startswith("development: the hollow profile one step further kept "
                                "nothing")
    out, _, _, _ = _run(monkeypatch, {-6.0: MINUS_6, -7.0: MINUS_7}, tolerant=False)
    assert out.case is None


def test_no_analysis_outside_the_gate(monkeypatch):
    """No cut: neither the floor nor any design analysed; a floor at the target: the
    designs not analysed."""
    out, written, _, floors = _run(monkeypatch, {}, cut=False)
    assert out.best is WRITTEN and written == [] and floors == []
    out, written, _, floors = _run(monkeypatch, {}, floor=40.0)
    assert out.best is WRITTEN and written == [] and floors == [40.0]


def test_the_written_line_reuses_the_steps_readings(monkeypatch):
    """``ltca synthesize``'s line: a crowning the step read is not analysed again (−6 µm
    here), the others are (−8 µm), said shallowest first; the floor of a case the step
    left unchanged is the step's."""
    from contact.optimize import development_hollow_limit as dhl
    from contact.optimize.written_notes import written_floor, written_hollow

    asked = []
    minus_8 = _probe(-8.0, (26.7, 37.9), 1625.0)

    def probes(basic, values, torques, written=None, crownings=None):
        asked.append(list(crownings))
        return [minus_8]

    monkeypatch.setattr(dhl, "hollow_probes", probes)
    further = dhf.Further(WRITTEN, probes=(MINUS_6[1], MINUS_7[1]), floor=21.0)
    dev = types.SimpleNamespace(targets=TARGETS, best=WRITTEN, torque=(4.7, 31.7),
                                basic=types.SimpleNamespace(size_scale=lambda: 1.0),
                                hollow_further=further)
    text = written_hollow("case", dev, 21.0)
    assert asked == [[-8.0]]
    assert text == dhl.hollow_text([MINUS_6[1], minus_8], 40.0, 0.02, tried=(-6.0, -7.0))
    # −6 µm free of cost but not kept by the step (its tolerance, say): said so
    assert "at -6 um no edge, plastic or flank-peak cost (tried by the development after " \
        "the design torque was cut and not kept" in text
    from contact.optimize import development_lte_floor as dlf

    analysed = []
    monkeypatch.setattr(dlf, "load_sharing_floor",
                        lambda case, light, design: analysed.append(case) or 22.0)
    assert written_floor("case", dev) == 21.0 and analysed == []  # the step's reading
    kept = types.SimpleNamespace(**{**dev.__dict__, "hollow_further": dhf.Further(
        MINUS_6[0], case="written -6", probes=(MINUS_6[1],))})
    assert written_floor("written -6", kept) == 22.0 and analysed == ["written -6"]


def test_one_analysis_gives_the_score_and_the_probe_alike():
    """:func:`analysed_further` on a real analysis of the bundled default case at 50 / 500
    N·m: the design's record and the probe are of the same analysis (identity: the LTE,
    the flank peak, the edge and plastic shares equal, bit for bit), the score recorded
    as the design's objective and met flag, the stage the step's, the probe's pitting
    limit positive (finite, or inf where the case names no rating)."""
    from pathlib import Path

    from contact.optimize.development_targets import targets_from_table
    from geometry.case import load_case

    root = Path(__file__).resolve().parents[1]
    case = load_case(root / "cases" / "kolivand2009_fm_11x41.toml")
    targets = targets_from_table({})
    base = _design(0.0, (30.0, 45.0))
    e, p = dhf.analysed_further(case, {"profile_crowning": -5.0}, -5.0, base, targets,
                                {"torques": [50.0, 500.0], "centre_v": 0.55})
    lte = np.asarray(e.metrics["lte_peak_to_peak"], float)
    assert p.lte == (float(lte[0]), float(lte[-1]))
    assert p.flank_peak == float(np.asarray(e.metrics["pressure_max_flank"])[-1])
    assert p.plastic == float(np.max(e.metrics["plastic_share"]))
    assert p.edge_share == float(np.nan_to_num(e.metrics["edge_load_share"][-1]))
    assert e.full[0] == e.objective and e.met == e.full[2] and e.checked
    assert e.stage == dhf.STAGE and e.case is case and p.crowning == -5.0
    assert p.pitting_limit > 0.0
