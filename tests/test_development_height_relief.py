"""The check's step for a high pattern with plastic segments on a design not tolerant
itself (:func:`contact.optimize.development_height_relief.checked_height_relief`, issue
71): both pinion reliefs, then the bearing nearer the profile, judged against the design's
own tolerance.

Stand-in analyses whose laws are the m_mn 12 industrial hypoid 11x43 of
benchmarks/data/unseen_designs as measured with ``benchmarks/development_levers.py --check
--tolerance --from-case`` on the case ``ltca synthesize`` wrote before the step
(2026-11-27; the numbers in the step's docstring): the tests are the step's choices, not
numbers of a gear.
"""

from __future__ import annotations

import dataclasses

from development_stand_ins import metrics as _metrics
from development_stand_ins import stand_in

from contact.optimize import development_height_relief as hr
from contact.optimize.development_targets import DevelopmentTargets

#: the 11x43's developed prescriptions (as written before the step)
_VALUES = {"path_angle": -45.0, "ellipse_length": 0.4, "tip_relief": 43.1,
           "tip_relief_start": 0.653, "root_relief": 15.0, "relief_start": 0.453,
           "te_level": 25.0}

#: both reliefs: the root relief at its upper bound (60 µm) from the lower bound of its
#: start (0.2), the tip relief 0.8 of the design's from the upper bound of its start (0.9)
_RELIEVED = {"tip_relief": 0.8 * 43.1, "tip_relief_start": 0.9, "root_relief": 60.0,
             "relief_start": 0.2}

#: (path, ellipse, relieved) → light-load pattern (toe, heel), (root v, tip v), centre v,
#: LTE p-p (light, design) [µrad], design torque's edge and plastic share, the
#: excursions (dE+, dE-, dP+, dP-) with plastic segments
_DESIGNS = {
    (-45.0, 0.4, False): ((0.20, 0.80), (0.38, 1.00), 0.67, (58.4, 63.3), 0.013, 0.009,
                          "dE+0.05 dE-0.05 dP+0.05 dP-0.05"),
    (-45.0, 0.4, True): ((0.20, 0.80), (0.29, 0.91), 0.60, (60.3, 64.2), 0.005, 0.0,
                         "dE+0.05 dP+0.05"),
    (-60.0, 0.35, True): ((0.23, 0.78), (0.29, 0.91), 0.60, (41.7, 47.5), 0.004, 0.0, ""),
    (-75.0, 0.35, True): ((0.20, 0.80), (0.29, 0.91), 0.60, (23.8, 28.7), 0.003, 0.0, ""),
}

_CENTRE_V = 0.543  # the 11x43's working depth centre


def _label(m) -> str:
    return f"d{'E' if m.delta_E else 'P'}{'+' if (m.delta_E or m.delta_P) > 0 else '-'}0.05"


def _eleven_by_43(designs=_DESIGNS):
    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        relieved = case["root_relief"] == 60.0
        key = (case["path_angle"], case["ellipse_length"], relieved)
        (toe, heel), (root, tip), centre, lte_pp, edge, plastic, plastic_at = designs[key]
        if misalignment is not None:
            plastic = 0.007 if _label(misalignment) in plastic_at.split() else 0.0
        return (_metrics(pattern_toe_u=[toe, 0.1], pattern_heel_u=[heel, 0.9],
                         pattern_centre_u=[0.5, 0.5], pattern_root_v=[root, 0.2],
                         pattern_tip_v=[tip, 0.95], pattern_centre_v=[centre, 0.6],
                         edge_load_share=[0.0, edge], plastic_share=[0.0, plastic],
                         lte_peak_to_peak=list(lte_pp)),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


def _start(monkeypatch, fake, values=_VALUES):
    seen = []

    def counted(case, torques, misalignment=None, **kw):
        seen.append((case["path_angle"], case["ellipse_length"], case["root_relief"],
                     misalignment))
        return fake(case, torques, misalignment, **kw)

    targets, setup, chosen = stand_in(monkeypatch, counted, [2001.0, 13340.0],
                                      centre_v=_CENTRE_V)
    start = dataclasses.replace(chosen(values), case=dict(values))
    seen.clear()
    return targets, setup, start, seen


def test_the_high_pattern_with_plastic_gets_both_reliefs_and_the_turned_bearing(monkeypatch):
    """The 11x43: both reliefs alone (plastic at two excursions, the design at four: no
    less tolerant) kept, then the path −60° (tolerant, LTE 48 µrad) and −75° with the
    ellipse 0.35 (every target met, tolerant): three designs, the last written."""
    targets, setup, start, seen = _start(monkeypatch, _eleven_by_43())
    assert {k for k, v in start.full[1].items() if v > 0.0} == {
        "centre_v", "tip", "plastic", "lte"}
    assert hr.height_relief_applies(start, targets, setup)
    lines = []
    got = hr.checked_height_relief(start, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    assert got.stage == "height relief" and got.full[2]
    assert got.values == _VALUES | _RELIEVED | {"path_angle": -75.0,
                                                "ellipse_length": 0.35}
    nominal = [(p, e) for p, e, _, m in seen if m is None]
    assert nominal == [(-45.0, 0.4), (-60.0, 0.35), (-75.0, 0.35)]
    assert not any(s.startswith("  not kept") for s in lines)
    assert "(its pattern high, plastic)" in lines[0]


def test_a_variant_less_tolerant_than_the_design_is_not_kept(monkeypatch):
    """The design plastic at ΔE +0.05 mm alone, both reliefs at ΔE and ΔP +0.05 mm (and
    its turns at ΔP −0.05 mm): each misses a target the design met there; none kept, the
    design returned."""
    designs = dict(_DESIGNS)
    designs[(-45.0, 0.4, False)] = (*designs[-45.0, 0.4, False][:-1], "dE+0.05")
    for key in ((-60.0, 0.35, True), (-75.0, 0.35, True)):
        designs[key] = (*designs[key][:-1], "dP-0.05")
    targets, setup, start, _ = _start(monkeypatch, _eleven_by_43(designs))
    lines = []
    got = hr.checked_height_relief(start, targets, setup, None, lines.append,
                                   lambda v: dict(v))
    assert got is start
    assert sum("not kept: both reliefs are less tolerant (they miss plastic)" in s
               for s in lines) == 9  # three tip reliefs, three bearings each


def test_nothing_is_tried_where_the_step_does_not_apply(monkeypatch):
    """A tolerant design: its excursions analysed, no design tried; a design without
    plastic segments, or whose pattern is low, or without a root relief developed:
    nothing analysed at all."""
    designs = dict(_DESIGNS)
    designs[(-45.0, 0.4, False)] = (*designs[-45.0, 0.4, False][:-1], "")
    targets, setup, start, seen = _start(monkeypatch, _eleven_by_43(designs))
    got = hr.checked_height_relief(start, targets, setup, None, lambda s: None,
                                   lambda v: dict(v))
    assert got is start and len(seen) == 4 and all(m is not None for *_, m in seen)
    seen.clear()
    no_plastic = dataclasses.replace(
        start, full=(start.full[0], start.full[1] | {"plastic": 0.0}, False))
    low = dataclasses.replace(start, metrics=start.metrics | {
        "pattern_centre_v": start.metrics["pattern_centre_v"] * 0 + 0.4})
    no_root = dataclasses.replace(start, values={k: v for k, v in _VALUES.items()
                                                 if k != "root_relief"})
    for e in (no_plastic, low, no_root):
        assert not hr.height_relief_applies(e, targets, setup)
        assert hr.checked_height_relief(e, targets, setup, None, lambda s: None,
                                        lambda v: dict(v)) is e
    assert seen == []


def test_the_designs_tried():
    """The groups: per tip relief (0.8, 2/3, 1/2 of 43.1 µm from 0.9), both reliefs then
    the turns (the pattern 0.60 long: the ellipse 0.05 shorter); a relief at its bound
    clipped; a design without reliefs developed: none."""
    t = DevelopmentTargets()
    groups = hr.height_relief_designs(_VALUES, 0.60, t)
    assert len(groups) == 3 and all(len(g) == 3 for g in groups)
    assert groups[0][0] == _VALUES | _RELIEVED
    assert [(d["path_angle"], d["ellipse_length"]) for d in groups[0]] == [
        (-45.0, 0.4), (-60.0, 0.35), (-75.0, 0.35)]
    assert [g[0]["tip_relief"] for g in groups] == [0.8 * 43.1, 43.1 * 2.0 / 3.0,
                                                    0.5 * 43.1]
    lo = t.variables["tip_relief"][0]
    tiny = hr.height_relief_designs(_VALUES | {"tip_relief": lo}, 0.60, t)
    assert len(tiny) == 1 and tiny[0][0]["tip_relief"] == lo  # clipped: one group
    assert hr.height_relief_designs({"path_angle": -45.0, "ellipse_length": 0.4},
                                    0.6, t) == []
