"""The coast flank's light-edge step (:mod:`contact.optimize.development_coast_light_edge`,
issue 71: no edge contact at 15 % of the design torque, on the coast flank too).

Stand-in analyses whose law follows the FM hypoid 13x33 at Σ 85° of
benchmarks/data/unseen_designs as ``ltca run --flank coast`` read its written case
(2026-11-29, docs/own_gear_set.md "Round 33"): 949 MPa on an edge carrying 0.028 % of the
torque (below the verdict's 0.05 % floor: counted share 0) at its coast light torque 33.1
N m, 15 % of its coast design torque 221 N m, LTE 41.8 / 41.2 µrad. The law's edge is the
pinion's (its tip line), cleared by a tip relief started at or before ``clear_start`` of
the way; the design torque's LTE rises ``per_step`` µrad per 0.1 of a longer tip relief
(made up, of the measured order). The prescriptions are the stand-in's; the tests are the
step's choices, compared exactly with the stand-in's numbers, not numbers of a gear.
"""

from __future__ import annotations

import collections
import dataclasses
import functools
import math

import numpy as np
import xarray as xr
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.ltca.edges import EDGE_KINDS
from contact.optimize import development_coast_light_edge as dcl
from contact.optimize.development_evaluate import light_edge_metrics
from contact.optimize.development_light_edge_relief import TIP_EDGES, light_edge_loaded

#: the stand-in's coast prescriptions
COAST = {"path_angle": -45.0, "ellipse_length": 0.5, "tip_relief": 15.0,
         "root_relief": 40.0, "relief_start": 0.3, "profile_crowning": 0.0,
         "tip_relief_start": 0.85, "blade_angle_change": 0.0}

#: the 13x33's coast torques: light, coast design [N m]
TORQUES = (33.1, 221.0)

#: the kept pinion tooth's key before the coast bearing (the drive bearing's, "coast")
PREFIX = ("drive bearing", "coast")


def _thirteen_by_33(case, torques, misalignment=None, options=None, teeth=None,
                    pinion_key=(), flank="drive", clear_start=0.75, per_step=0.0,
                    kind="pinion_edge", calls=None):
    """The 13x33's coast flank at 33.1 / 221 N m: 949 MPa on the ``kind`` edge at the light
    torque (0.028 % of the torque: counted 0) while the tip relief starts after
    ``clear_start``, none from there on; the design torque's LTE 30 µrad + ``per_step``
    per 0.1 the tip relief starts before 0.85. ``calls`` records each call's flank and
    pinion key."""
    if calls is not None:
        calls.append((flank, tuple(pinion_key)))
    start = float(case["tip_relief_start"])
    light = 0.0 if start <= clear_start + 1e-9 else 949.0
    pressure = {f"edge_pressure_{k}": [light if k == kind else 0.0, 0.0]
                for k in EDGE_KINDS}
    m = _metrics(lte_peak_to_peak=[20.0, 30.0 + per_step * (0.85 - start) / 0.1],
                 pressure_max_edge=[light, 0.0], edge_contact_share=[0.0, 0.0],
                 edge_peak=[0.0, 0.0], edge_static_strength=[2400.0, 2400.0], **pressure)
    return m, (0.0, 1.0, 0.0, 1.0, 2400.0)


def _start(monkeypatch, **law):
    seen, fake = seen_designs(functools.partial(_thirteen_by_33, **law))
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = chosen(dict(COAST))
    seen.clear()
    return seen, targets, setup, start


def test_the_coast_light_edge_is_relieved(monkeypatch):
    """The pinion edge loaded at the coast light torque (949 MPa, its share below the
    verdict's floor, the light pattern on no row): the kind read from the light torque's
    edge pressures, not the drive step's fallback (the gear tip first); the tip relief
    started 0.1 earlier (0.85 → 0.75), clear: kept, on the coast flank under the coast's
    pinion key, the step ends after that one design (at its torques and between them:
    its LTE over ``ltca run --flank coast``'s ``lte_range`` judged)."""
    calls = []
    seen, targets, setup, start = _start(monkeypatch, calls=calls)
    assert start.full[2] and light_edge_loaded(start)
    assert dcl.coast_light_edge_kinds(start) == ("pinion_edge",)
    assert TIP_EDGES[0] == "gear_tip"  # what the rows alone would have tried first
    assert dcl.coast_light_edge_runs_on(start, targets)
    calls.clear()
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX)
    assert got.values == COAST | {"tip_relief_start": 0.75}
    assert got.stage == dcl.STAGE and not light_edge_loaded(got)
    assert {d["tip_relief_start"] for d in seen} == {0.75}
    assert calls and all(f == "coast" and key[:2] == PREFIX for f, key in calls)
    assert any("coast pinion edge: edge contact at the light torque p_max edge 949 MPa"
               in s for s in lines), lines


def test_a_relief_that_loses_a_coast_target_is_refused(monkeypatch):
    """The clearing relief (the tip relief from 0.75, then 0.65) lifts the coast design
    torque's LTE to 45 and 50 µrad, past the 40 µrad target the design met (30): each
    refused (said), no LTE range analysed for a design that misses a hard target; at most
    :data:`COAST_LIGHT_EDGE_STEPS` designs, the design returned as it was."""
    seen, targets, setup, start = _start(monkeypatch, clear_start=0.75, per_step=15.0)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX)
    assert got is start
    assert [d["tip_relief_start"] for d in seen] == [0.75, 0.65]
    assert len(seen) == dcl.COAST_LIGHT_EDGE_STEPS
    assert any("not kept: the coast tip_relief_start 0.75 for the light torque's pinion "
               "edge misses lte" in s for s in lines), lines


def test_a_relief_above_the_capacity_bound_is_refused(monkeypatch):
    """The coast flank's capacity bound: a variant whose flank peak at the coast design
    torque rises above both the design's and the bound is refused ("local pitting"),
    as the coast edge-peak step's."""
    def hotter(case, torques, misalignment=None, **kw):
        m, limits = _thirteen_by_33(case, torques, misalignment, **kw)
        if float(case["tip_relief_start"]) < 0.85:
            m["pressure_max_flank"] = np.asarray([900.0, 1700.0])
        return m, limits

    seen, fake = seen_designs(hotter)
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = chosen(dict(COAST))
    seen.clear()
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=1600.0, key_prefix=PREFIX)
    assert got is start
    assert any("misses local pitting" in s for s in lines), lines
    free = dcl.checked_coast_light_edge(start, targets, setup, None, lambda s: None, dict,
                                        bound=math.inf, key_prefix=PREFIX)
    assert free.values == COAST | {"tip_relief_start": 0.75}


def test_two_designs_at_most(monkeypatch):
    """Nothing clears the edge: two designs tried (the tip relief from 0.75, then 0.65),
    not the drive step's six per kind, each analysed at its two torques only (refused for
    the edge it leaves, its LTE between the torques is not analysed); said; the design
    returned as it was."""
    seen, targets, setup, start = _start(monkeypatch, clear_start=0.0)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX)
    assert got is start
    assert [d["tip_relief_start"] for d in seen] == [0.75, 0.65]
    assert len(seen) == dcl.COAST_LIGHT_EDGE_STEPS
    assert sum("not kept: it still loads an edge at the light torque (p_max edge 949 MPa"
               in s for s in lines) == 2, lines


def test_no_light_edge_no_design(monkeypatch):
    """A coast flank clear at its light torque, or the coast development off: the gate is
    shut, nothing analysed, no outcome returned."""
    seen, targets, setup, start = _start(monkeypatch)
    Outcome = collections.namedtuple("Outcome", "basic best torques")
    clear = dict(COAST) | {"tip_relief_start": 0.7}
    quiet = Outcome(None, dataclasses.replace(
        start, values=clear, metrics=_thirteen_by_33(clear, TORQUES)[0]), TORQUES)
    assert not dcl.coast_light_edge_runs_on(quiet.best, targets)
    assert dcl.coast_light_edge(None, start, targets, setup, None, {}, print, quiet,
                                None) is None
    off = dataclasses.replace(targets, coast_max_evaluations=0)
    loud = Outcome(None, start, TORQUES)
    assert dcl.coast_light_edge(None, start, off, setup, None, {}, print, loud, None) is None
    assert seen == []


def test_the_kinds_follow_the_light_torques_edge_pressures():
    """The edges loaded at the light torque, highest first; without the readings (a
    design scored before them) the drive step's rows or tip edges."""
    from development_stand_ins import checked

    from contact.optimize.development import DevelopmentTargets

    both = _metrics(pressure_max_edge=[949.0, 0.0], edge_pressure_gear_toe=[300.0, 0.0],
                    edge_pressure_pinion_edge=[949.0, 0.0],
                    edge_pressure_gear_tip=[0.0, 500.0])
    e = checked(dict(COAST), both, DevelopmentTargets(), 0.6)
    assert dcl.coast_light_edge_kinds(e) == ("pinion_edge", "gear_toe")
    bare = checked(dict(COAST), _metrics(pressure_max_edge=[949.0, 0.0]),
                   DevelopmentTargets(), 0.6)
    assert dcl.coast_light_edge_kinds(bare) == TIP_EDGES


def test_the_edge_pressures_are_the_segments_peaks():
    """``edge_pressure_<kind>``: the peak of ``pressure_max`` over each kind's segments at
    each torque, whatever their share (identity with the dataset's own
    ``pressure_max_edge``, the largest of them); 0 for a kind without load."""
    kinds = ["curve", "gear_tip", "gear_heel", "pinion_edge", "pinion_edge"]
    p = np.asarray([[[[1500.0, 0.0, 1382.0, 949.0, 700.0]]],
                    [[[1700.0, 2100.0, 0.0, 0.0, 1200.0]]]])
    ds = xr.Dataset(
        {"pressure_max": (("torque", "roll", "pair", "segment"), p),
         "force": (("torque", "roll", "pair", "segment"), np.where(p > 0, 1.0, 0.0)),
         "moment_arm": (("roll", "pair", "segment"), np.ones((1, 1, 5))),
         "segment_kind": (("segment",), np.asarray(kinds)),
         "pressure_max_edge": (("torque",), np.asarray([1382.0, 2100.0]))},
        coords={"torque": [33.1, 221.0]})
    m = light_edge_metrics(ds)
    assert m["edge_pressure_gear_tip"].tolist() == [0.0, 2100.0]
    assert m["edge_pressure_gear_heel"].tolist() == [1382.0, 0.0]
    assert m["edge_pressure_pinion_edge"].tolist() == [949.0, 1200.0]
    assert m["edge_pressure_gear_toe"].tolist() == [0.0, 0.0]  # no such segment
    assert np.array_equal(np.max([m[f"edge_pressure_{k}"] for k in EDGE_KINDS], axis=0),
                          m["pressure_max_edge"])


def test_the_readings_are_not_written():
    """The per-kind readings stay out of the case's ``[development]`` tables (the table's
    ``pressure_max_edge`` is their largest): a case written where the step keeps nothing
    is the same as before it."""
    from contact.optimize import development_result as dr

    m = _thirteen_by_33(dict(COAST), TORQUES)[0]
    assert set(dr.UNWRITTEN_METRICS) <= set(m)
    rows = dr._rounded(m)
    assert not set(rows) & set(dr.UNWRITTEN_METRICS)
    assert rows["pressure_max_edge"] == [949.0, 0.0]


def _capacity(torque, root=2.0):
    from contact.optimize.development_coast import CoastCapacity, CoastCheck

    check = CoastCheck(torque, 1500.0, 2400.0, 0.0, root, 1.5, "gear", math.nan, math.nan,
                       None, 0.0, 1.2, 1.0, "pinion")
    return CoastCapacity(torque, torque, (check,), "", True)


def test_the_development_writes_the_relief_where_the_flank_holds(monkeypatch):
    """The development's call (``development._coast_edges_relieved`` with
    :func:`coast_light_edge`): the design kept written and analysed at the coast design
    torque; kept where it fails no criterion the design before it held there, else the
    written design stays (said) and its FE models are built again. A step that keeps
    nothing writes nothing."""
    from contact.optimize import development as dev

    Outcome = collections.namedtuple("Outcome", "basic best torques")
    relieved = Outcome("relieved basic", "relieved best", TORQUES)
    written = ("coast", "developed", "case", "report")
    writes, builds, lines = [], [], []

    def write(basic):
        writes.append(basic)
        return "new case", "new report"

    def run(after):
        def relieve(developed, drive, targets, setup, teeth, memo, say, coast, cap):
            assert (developed, coast) == ("developed", "coast")
            return relieved if after is not None else None

        monkeypatch.setattr(dev, "coast_flank_capacity",
                            lambda case, basic, edged, *a, **k: (edged, after))
        return dev._coast_edges_relieved(written, None, None, {}, None, {}, lines.append,
                                         _capacity(221.0), None, True, write,
                                         builds.append, relieve,
                                         "the coast light-edge relief")

    assert run(_capacity(221.0)) == (relieved, "relieved basic", "new case", "new report")
    assert writes == ["relieved basic"] and builds == ["new case"]
    assert run(_capacity(221.0, root=1.2)) == written  # the root fails where it held
    assert builds == ["new case", "new case", "case"]
    assert "the coast light-edge relief fails a criterion" in lines[-1]
    writes.clear()
    assert run(None) == written and writes == []



def _two_edges(case, torques, misalignment=None, **kw):
    """The 13x17 at Σ 50°'s coast light torque (18.4 / 122.7 N m, 2026-11-29): its gear
    tip (1640 MPa, 0.23 % on edges) and gear toe (900 MPa, made up) loaded at the light
    torque; the tip cleared by the root relief started at 0.2, the toe by the path turned
    to −50° or beyond or an ellipse of at most 0.4 (made up)."""
    tip = 0.0 if float(case["relief_start"]) <= 0.2 + 1e-9 else 1640.0
    toe = (0.0 if float(case["ellipse_length"]) <= 0.4 + 1e-9
           or float(case["path_angle"]) <= -50.0 + 1e-9 else 900.0)
    pressure = {f"edge_pressure_{k}": [0.0, 0.0] for k in EDGE_KINDS}
    pressure["edge_pressure_gear_tip"] = [tip, 0.0]
    pressure["edge_pressure_gear_toe"] = [toe, 0.0]
    m = _metrics(pressure_max_edge=[max(tip, toe), 0.0],
                 edge_contact_share=[0.0023 if tip or toe else 0.0, 0.0],
                 edge_peak=[0.0, 0.0], edge_static_strength=[2400.0, 2400.0], **pressure)
    return m, (0.0, 1.0, 0.0, 1.0, 2400.0)


def test_two_loaded_edges_relieved_together(monkeypatch):
    """Two edges loaded at the light torque (gear tip above gear toe): each design grows
    both levers at once, since a design clearing one edge alone is never kept. The first
    (root relief from 0.2, the bound; ellipse 0.5 × 0.85) clears the tip but not the toe:
    not kept, said with the edge left. The second (the start at its bound, so the
    profile crowning one step more, 0 → 10 µm, before the root relief deeper:
    :data:`COAST_LEVER_ORDER`; the path turned 2.5° again, −45° → −47.5° → −50°, the
    toe's first lever, before the shorter ellipse) clears both: kept, the ellipse as it
    was."""
    seen, fake = seen_designs(_two_edges)
    targets, setup, chosen = stand_in(monkeypatch, fake, (18.4, 122.7))
    start = chosen(dict(COAST))
    assert dcl.coast_light_edge_kinds(start) == ("gear_tip", "gear_toe")
    seen.clear()
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX)
    first, second = -47.5, -50.0
    tried = [(d["relief_start"], d["profile_crowning"], d["path_angle"]) for d in seen]
    assert tried[0] == (0.2, 0.0, first) and tried[-1] == (0.2, 10.0, second)
    assert set(tried) == {(0.2, 0.0, first), (0.2, 10.0, second)}
    assert {d["ellipse_length"] for d in seen} == {COAST["ellipse_length"]}
    assert got.values == COAST | {"relief_start": 0.2, "profile_crowning": 10.0,
                                  "path_angle": second}
    assert not light_edge_loaded(got)
    assert any("not kept: it still loads an edge at the light torque (p_max edge 900 MPa"
               in s and "gear toe" in s for s in lines), lines


#: the 13x17's coast flank (the FM spiral bevel at Sigma 50 deg): the design the light-edge
#: step read, and the one the coast edge-peak step wrote after it
COAST_17_READ = dict(COAST, ellipse_length=0.75, tip_relief_start=0.5, root_relief=15.0,
                     relief_start=0.5)
COAST_17_WRITTEN = dict(COAST_17_READ, root_relief=22.5, relief_start=0.4)


def _read_and_written():
    from development_stand_ins import checked

    from contact.optimize.development import DevelopmentTargets

    # the readings logged by branch coastedge95 (docs/synthesis.md, "The coast flank's
    # light-torque edge"), the readings of contact.optimize.development_evaluate.
    # light_edge_metrics on `ltca run --flank coast` of both designs (this branch's
    # /work/wt/coastread96_runs): the step's 1640 MPa / 0.23 % on gear tip (1640) and toe
    # (400); the case written 1061 MPa on the gear toe, 3.2e-5 % of the torque: a counted
    # share of 0 (below the verdict's 0.05 %)
    read = checked(dict(COAST_17_READ), _metrics(
        pressure_max_edge=[1640.0, 4994.0], edge_contact_share=[0.0023, 0.01],
        edge_pressure_gear_tip=[1640.0, 4994.0], edge_pressure_gear_toe=[400.0, 4607.0]),
        DevelopmentTargets(), 0.6)
    written = checked(dict(COAST_17_WRITTEN), _metrics(
        pressure_max_edge=[1061.0, 4575.0], edge_contact_share=[0.0, 0.0082],
        edge_pressure_gear_tip=[0.0, 4575.0], edge_pressure_gear_toe=[1061.0, 4467.0]),
        DevelopmentTargets(), 0.6)
    return read, written


def test_the_written_coast_light_edge_is_said_after_a_later_step():
    """Issue 71 (13x17): the light-edge step's line read the coast design before the
    coast edge-peak step (relief_start 0.5, root relief 15 um: 1640 MPa, 0.23 %); the
    case written carries that step's relief_start 0.4, root relief 22.5 um, which `ltca
    run --flank coast` reads as 1061 MPa on the gear toe, 3.2e-5 %. The development says
    the written flank's reading, its changed prescriptions and that the step's was of the
    design before: the numbers are the metrics' own (formatted, no tolerance: exact)."""
    read, written = _read_and_written()
    line = dcl.written_coast_light_edge_line(read, written, 18.4)
    assert line is not None
    assert "relief_start 0.5 -> 0.4" in line and "root_relief 15 -> 22.5" in line, line
    assert "18.4 N m" in line and "ltca run --flank coast" in line, line
    assert ("p_max edge 1061 MPa, edge share below the 0.05 % of the torque the verdict "
            "counts; gear toe;") in line, line
    assert "gear tip" not in line, line  # cleared at the light torque by the later step
    assert "p_max edge 1640 MPa, edge share 0.23 % were of the design before it" in line, line


def test_no_written_line_where_the_read_design_is_written_or_edge_free():
    """Nothing said where the design the step read is the one written (its line is the
    written case's), where it loaded no edge at the light torque (the step said nothing),
    or where the written design carries no light-torque reading."""


    read, written = _read_and_written()
    assert dcl.written_coast_light_edge_line(read, read, 18.4) is None
    clear = dataclasses.replace(read, metrics=_metrics(
        pressure_max_edge=[0.0, 4994.0], edge_contact_share=[0.0, 0.01]))
    assert dcl.written_coast_light_edge_line(clear, written, 18.4) is None
    bare = dataclasses.replace(written, metrics={
        k: v for k, v in written.metrics.items()
        if k not in ("pressure_max_edge", "edge_contact_share")})
    assert dcl.written_coast_light_edge_line(read, bare, 18.4) is None
    assert dcl.written_coast_light_edge_line(None, written, 18.4) is None


def test_the_development_says_the_written_coast_light_edge():
    """The development's wiring: after the coast edge-peak step, the line is said for the
    coast outcome written at its two torques, and nothing for one without them."""
    from contact.optimize import development as dev

    read, written = _read_and_written()
    Outcome = collections.namedtuple("Outcome", "basic best torques")
    lines = []
    dev._say_written_coast_light_edge(read, Outcome(None, written, (18.4, 122.7)),
                                      lines.append)
    assert len(lines) == 1 and "p_max edge 1061 MPa" in lines[0], lines
    dev._say_written_coast_light_edge(read, Outcome(None, written, (18.4,)), lines.append)
    dev._say_written_coast_light_edge(read, None, lines.append)
    assert len(lines) == 1


def _after_peak(case, torques, misalignment=None, tip_rise=0.0, path_plastic=0.0, **kw):
    """The 13x17 at Σ 50°'s coast flank as the coast edge-peak step wrote it (root relief
    22.5 µm from 0.4, ellipse 0.75, path −45°; 18.4 / 122.7 N m): the gear toe loaded at
    the light torque at 1061 MPa with a share below the verdict's floor (counted 0) while
    the ellipse is longer than 0.65 (made up: between the 0.75 written and the 0.6375 the
    toe's lever tries) and the path is short of −47.5°, none from there on; the gear tip's
    edge peak at the design torque 4575 MPa against a static strength of 2400 MPa, the
    toe's 4467 MPa, LTE 51.1 / 91.1 µrad (the written case's readings, docs/synthesis.md),
    the tip's raised by ``tip_rise`` MPa where the ellipse is shorter than the written 0.75
    (made up). At the path −47.5° (the ellipse 0.75): the edge peaks 4332 / 4329 MPa and
    the LTE 55.7 / 90.3 µrad ``ltca run``'s sampling measured there, and a plastic share
    ``path_plastic`` [1] at the design torque (made up; 0 measured)."""
    ellipse, path = float(case["ellipse_length"]), float(case["path_angle"])
    turned = path <= -47.5 + 1e-9
    toe = 1061.0 if ellipse > 0.65 + 1e-9 and not turned else 0.0
    tip = 4575.0 + (tip_rise if ellipse < 0.75 - 1e-9 else 0.0)
    lte, plastic = [51.1, 91.1], [0.0, 0.0]
    toe_peak = 4467.0
    if turned:
        tip, toe_peak = 4332.0, 4329.0
        lte, plastic = [55.7, 90.3], [0.0, path_plastic]
    pressure = {f"edge_pressure_{k}": [0.0, 0.0] for k in EDGE_KINDS}
    pressure["edge_pressure_gear_toe"] = [toe, toe_peak]
    pressure["edge_pressure_gear_tip"] = [0.0, tip]
    peaks = {f"edge_peak_{k}": [0.0, 0.0] for k in EDGE_KINDS}
    peaks["edge_peak_gear_tip"] = [0.0, tip]
    peaks["edge_peak_gear_toe"] = [0.0, toe_peak]
    m = _metrics(pressure_max_edge=[toe, tip], edge_contact_share=[0.0, 0.0082],
                 lte_peak_to_peak=lte, plastic_share=plastic,
                 edge_peak=[0.0, tip], edge_static_strength=[2400.0, 2400.0],
                 **pressure, **peaks)
    return m, (0.0, 1.0, 0.0, 1.0, 2400.0)


def _after_peak_start(monkeypatch, tip_rise, path=False, **law):
    """The stand-in step's inputs on :func:`_after_peak`; ``path`` False: a development
    that does not vary the path angle (the toe's lever the ellipse alone)."""
    seen, fake = seen_designs(functools.partial(_after_peak, tip_rise=tip_rise, **law))
    targets, setup, chosen = stand_in(monkeypatch, fake, (18.4, 122.7))
    if not path:
        targets = dataclasses.replace(targets, variables={
            k: v for k, v in targets.variables.items() if k != "path_angle"})
    start = chosen(dict(COAST_17_WRITTEN))
    seen.clear()
    return seen, targets, setup, start


def test_the_edge_peak_raised_rule():
    """:func:`edge_peak_raised`: the edges' summed excess over the static strength at the
    design torque (4575 - 2400 = 2175 MPa) raised by more than the edge peak's resolution
    (2.5 % of 2400 = 60 MPa, the edge-peak step's own keep rule) is "edge peak"; within
    it, not (the sampling's); a variant without readings (excess inf) is refused, a kept
    design without them judges nothing."""
    def at(tip, static=2400.0):
        return _metrics(edge_peak_gear_tip=[0.0, tip], edge_static_strength=[static, static])

    from development_stand_ins import checked

    from contact.optimize.development import DevelopmentTargets

    t = DevelopmentTargets()
    kept = checked(dict(COAST_17_WRITTEN), at(4575.0), t, 0.6)
    assert dcl.edge_peak_raised(kept, checked(dict(COAST), at(4636.0), t, 0.6)) == [
        "edge peak"]  # 61 MPa more: above the 60 MPa resolution
    assert dcl.edge_peak_raised(kept, checked(dict(COAST), at(4634.0), t, 0.6)) == []
    assert dcl.edge_peak_raised(kept, checked(dict(COAST), at(2000.0), t, 0.6)) == []
    bare = checked(dict(COAST), _metrics(), t, 0.6)
    assert dcl.edge_peak_raised(kept, bare) == ["edge peak"]
    assert dcl.edge_peak_raised(bare, kept) == []


def test_the_light_edge_after_the_edge_peak_step_is_relieved(monkeypatch):
    """Issue 71 on the 13x17: the flank the edge-peak step wrote loads the gear toe at the
    light torque (1061 MPa, below the verdict's floor: counted 0, still edge contact).
    Run again with that step's edges held (``edge_peak_held``), on a development that does
    not vary the path, the toe's lever (the ellipse 0.75 × 0.85 = 0.6375) clears it and
    leaves the design torque's edges as they were: kept after one design."""
    seen, targets, setup, start = _after_peak_start(monkeypatch, tip_rise=0.0)
    assert light_edge_loaded(start) and dcl.coast_light_edge_kinds(start) == ("gear_toe",)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX,
                                       edge_peak_held=True)
    assert got.values == COAST_17_WRITTEN | {"ellipse_length": 0.6375}
    # one design: analysed at its two torques, then its LTE between them (a set)
    assert not light_edge_loaded(got) and {d["ellipse_length"] for d in seen} == {0.6375}


def test_the_light_edge_after_the_edge_peak_step_keeps_its_edges(monkeypatch):
    """A design that clears the light torque's toe but raises the gear tip's edge peak at
    the design torque by 100 MPa (above the 60 MPa resolution) gives back what the
    edge-peak step took off: refused ("edge peak", said) where the step runs after it,
    both designs (0.6375, then 0.6375 × 0.85 = 0.5419) tried, the design returned as it
    was; by 40 MPa (within the resolution) kept. Before the edge-peak step (the flag off)
    the same design is kept: that step still follows there. A development that does not
    vary the path angle (the toe's lever the ellipse alone)."""
    seen, targets, setup, start = _after_peak_start(monkeypatch, tip_rise=100.0)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX,
                                       edge_peak_held=True)
    assert got is start
    assert [d["ellipse_length"] for d in seen] == [0.6375, round(0.85 * 0.6375, 4)]
    assert any("misses edge peak" in s for s in lines), lines
    free = dcl.checked_coast_light_edge(start, targets, setup, None, lambda s: None, dict,
                                        bound=math.inf, key_prefix=PREFIX)
    assert free.values["ellipse_length"] == 0.6375
    seen, targets, setup, start = _after_peak_start(monkeypatch, tip_rise=40.0)
    near = dcl.checked_coast_light_edge(start, targets, setup, None, lambda s: None, dict,
                                        bound=math.inf, key_prefix=PREFIX,
                                        edge_peak_held=True)
    assert near.values["ellipse_length"] == 0.6375


def test_the_coast_edge_steps_run_in_order(monkeypatch):
    """The development's order (``development._coast_edge_steps``): the light-edge step,
    the edge-peak step on what it left, and the light-edge step again on the flank the
    edge-peak step wrote, only where that step kept a design; each outcome passed on,
    the last written. Stand-in steps record their calls; the capacity check holds."""
    from contact.optimize import development as dev

    Outcome = collections.namedtuple("Outcome", "basic best torques")
    calls = []

    def step(name, keeps):
        def relieve(developed, drive, targets, setup, teeth, memo, say, coast, cap):
            calls.append((name, coast.best))
            return Outcome(f"{name} basic", f"{name} best", (18.4, 122.7)) if keeps else None
        return relieve

    def run(light, peak, again):
        calls.clear()
        monkeypatch.setattr(dev, "coast_light_edge", step("light", light))
        monkeypatch.setattr(dev, "coast_edge_peak", step("peak", peak))
        monkeypatch.setattr(dev, "coast_light_edge_after_peak", step("again", again))
        monkeypatch.setattr(dev, "coast_flank_capacity",
                            lambda case, basic, edged, *a, **k: (edged, _capacity(122.7)))
        monkeypatch.setattr(dev, "_say_written_coast_light_edge", lambda *a: None)
        start = (Outcome("basic", "start best", (18.4, 122.7)), "basic", "case", "report")
        return dev._coast_edge_steps(start, None, None, {}, None, {}, lambda s: None,
                                     _capacity(122.7), None, True,
                                     lambda b: (f"case of {b}", "r"), lambda c: None)

    got = run(True, True, True)
    assert calls == [("light", "start best"), ("peak", "light best"), ("again", "peak best")]
    assert got[0].best == "again best" and got[1:3] == ("again basic", "case of again basic")
    got = run(False, True, False)  # the again step keeps nothing: the peak's written
    assert calls == [("light", "start best"), ("peak", "start best"), ("again", "peak best")]
    assert got[0].best == "peak best"
    run(True, False, True)  # the edge-peak step kept nothing: no second light-edge pass
    assert calls == [("light", "start best"), ("peak", "light best")]


def test_the_written_line_after_the_second_pass():
    """Where the light-edge step run again cleared the written flank's light torque, the
    written line says no edge is loaded (not "p_max edge 0 MPa, edge share below …")."""
    read, written = _read_and_written()
    clear = dataclasses.replace(written, values=dict(written.values, ellipse_length=0.6375),
                                metrics=dict(written.metrics,
                                             pressure_max_edge=np.asarray([0.0, 4575.0]),
                                             edge_pressure_gear_toe=np.asarray([0.0, 4467.0])))
    line = dcl.written_coast_light_edge_line(read, clear, 18.4)
    assert "ellipse_length 0.75 -> 0.6375" in line and "no edge loaded (p_max edge 0 MPa)" \
        in line, line
    assert "p_max edge 1640 MPa, edge share 0.23 % were of the design before it" in line


#: the FM hypoid 13x33 at Σ 85°'s coast prescriptions written (docs/synthesis.md, "The
#: coast flank's light-torque edge"): its tip relief starts at its bound 0.5
COAST_33 = {"path_angle": -45.0, "ellipse_length": 0.55, "tip_relief": 15.0,
            "root_relief": 60.0, "relief_start": 0.2, "profile_crowning": 0.0,
            "tip_relief_start": 0.5, "blade_angle_change": -0.146}


def test_the_coast_levers_put_the_profile_crowning_before_the_deeper_relief():
    """:func:`coast_lever_designs` on the default bounds: the 13x33's pinion edge (its tip
    relief start at its bound 0.5) tries the profile crowning 0 -> 10 µm (the height
    stage's step × size_scale 1) before the tip relief 15 -> 22.5 µm (× 1.5, the drive
    step's deeper); the gear tip (its root relief 60 µm and start 0.2 both at their
    bounds) only the crowning; the toe the path turned 2.5° towards the profile, then the
    ellipse (0.55 × 0.85, × 0.7); where the
    start is free it comes first (0.85 -> 0.75); the crowning at its bound (30 µm) is not
    tried; a development that does not vary it, neither. Exact: the bounds' arithmetic."""
    from contact.optimize.development import DevelopmentTargets

    t = DevelopmentTargets()
    assert dcl.coast_lever_designs("pinion_edge", COAST_33, t) == [
        ("profile_crowning", 10.0), ("tip_relief", 22.5)]
    assert dcl.coast_lever_designs("gear_tip", COAST_33, t) == [("profile_crowning", 10.0)]
    assert dcl.coast_lever_designs("gear_toe", COAST_33, t) == [
        ("path_angle", -47.5), ("ellipse_length", 0.4675), ("ellipse_length", 0.385)]
    free = dict(COAST_33, tip_relief_start=0.85)
    assert dcl.coast_lever_designs("pinion_edge", free, t)[0] == ("tip_relief_start", 0.75)
    full = dict(COAST_33, profile_crowning=30.0)
    assert dcl.coast_lever_designs("pinion_edge", full, t) == [("tip_relief", 22.5)]
    fixed = dataclasses.replace(t, variables={k: v for k, v in t.variables.items()
                                              if k != "profile_crowning"})
    assert dcl.coast_lever_designs("gear_tip", COAST_33, fixed) == []


def test_the_13x17_toe_cleared_by_the_path(monkeypatch):
    """The 13x17's written coast flank (path −45°) on the default bounds: the step's first
    design for the gear toe turns the path 2.5° towards the profile (−47.5°, the ellipse
    0.75 as written), which clears the toe at the light torque, lowers the edges' summed
    excess at the design torque ((4575 − 2400) + (4467 − 2400) → (4332 − 2400) + (4329 −
    2400) MPa, the edge-peak step's gain held) and the LTE at the design torque (91.1 →
    90.3 µrad; 55.7 at 18.4 N m): kept after one design, said with its unit. The law is
    ``ltca run``'s sampling measured (docs/synthesis.md, "The coast gear-toe edge at the
    light torque: the path angle"); the check is the step's choice on it."""
    seen, targets, setup, start = _after_peak_start(monkeypatch, tip_rise=100.0, path=True)
    assert dcl.coast_light_edge_kinds(start) == ("gear_toe",)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX,
                                       edge_peak_held=True)
    assert got.values == COAST_17_WRITTEN | {"path_angle": -47.5}
    assert not light_edge_loaded(got)
    assert {(d["path_angle"], d["ellipse_length"]) for d in seen} == {(-47.5, 0.75)}
    assert any("with path_angle -47.5 deg (the coast gear toe" in s for s in lines), lines


def test_a_path_turn_that_loses_a_coast_target_is_refused(monkeypatch):
    """The same turn with 1 % of the design torque on plastic segments (made up: a coast
    target the written flank met, plastic share 0) is refused on the step's rule, and so
    is the second design (the path turned again, −50°, the same law): two designs at
    most, the path's both, the ellipse not reached, the flank returned as it was."""
    seen, targets, setup, start = _after_peak_start(monkeypatch, tip_rise=0.0, path=True,
                                                    path_plastic=0.01)
    lines = []
    got = dcl.checked_coast_light_edge(start, targets, setup, None, lines.append, dict,
                                       bound=math.inf, key_prefix=PREFIX,
                                       edge_peak_held=True)
    assert got is start
    assert sorted({d["path_angle"] for d in seen}) == [-50.0, -47.5]
    assert {d["ellipse_length"] for d in seen} == {0.75}
    assert sum("not kept" in s and "plastic" in s for s in lines) == 2, lines


def test_the_path_turn_at_its_bound():
    """:func:`coast_lever_designs` for a toe or heel: the path turned 2.5° towards the
    profile (−45° → −47.5°), clipped to the variable's bound (−79° → −80°), none at the
    bound (the ellipse alone) or where the development does not vary the path; no path
    design for the profile-end edges. Exact: the bounds' arithmetic."""
    from contact.optimize.development import DevelopmentTargets

    t = DevelopmentTargets()
    assert dcl.coast_lever_designs("gear_heel", COAST_33, t)[0] == ("path_angle", -47.5)
    near = dict(COAST_33, path_angle=-79.0)
    assert dcl.coast_lever_designs("gear_toe", near, t)[0] == ("path_angle", -80.0)
    at = dict(COAST_33, path_angle=-80.0)
    assert [n for n, _ in dcl.coast_lever_designs("gear_toe", at, t)] == [
        "ellipse_length", "ellipse_length"]
    fixed = dataclasses.replace(t, variables={k: v for k, v in t.variables.items()
                                              if k != "path_angle"})
    assert [n for n, _ in dcl.coast_lever_designs("gear_toe", COAST_33, fixed)] == [
        "ellipse_length", "ellipse_length"]
    assert all(n != "path_angle" for kind in dcl.PROFILE_EDGES
               for n, _ in dcl.coast_lever_designs(kind, COAST_33, t))
