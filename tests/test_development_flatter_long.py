"""The check's LTE step for a pattern longer than its tolerance on a face contact ratio
below 1 (issue 71, the FH hypoid 7x33 at Σ 80° of benchmarks/data/unseen_designs, ε_vβ
0.95): the profile crowning flattened, the ellipse kept
(contact.optimize.development_check.checked_overlap_lte → checked_flatter_long).

Stand-in analyses whose numbers are those measured at ``ltca run``'s sampling on the
7x33's written drive bearing (37.6 / 251 N m; path −80°, ellipse 0.75, profile crowning
22.36 µm, te_level 10 µrad; ``benchmarks/development_levers.py --check --from-case``,
2026-11-29; docs/synthesis.md, "The FH 7×33's LTE at ε_vβ 0.95: the profile crowning"):
the step's decisions are checked without an LTCA. The independent check of the numbers
themselves is ``ltca run`` of the case ``ltca synthesize`` writes (the same analysis, the
docs' table).
"""

from __future__ import annotations

import pytest
from development_stand_ins import checked as _checked
from development_stand_ins import metrics as _metrics
from development_stand_ins import stand_in

from contact.optimize import development_check as dcheck

#: the 7x33's written drive bearing (the case `ltca synthesize` wrote before the step)
BEARING = {"path_angle": -80.0, "ellipse_length": 0.75, "tip_relief": 15.0,
           "root_relief": 13.99, "relief_start": 0.5, "profile_crowning": 22.36,
           "tip_relief_start": 0.9, "blade_angle_change": 0.0, "te_level": 10.0}

#: (LTE p-p [µrad] at light, design torque; the light-load pattern's toe and heel u [1])
#: by profile crowning [µm], as measured (development_levers, the module docstring)
LAW = {22.36: ([30.7, 56.0], (0.12, 0.90)), 11.18: ([20.8, 39.1], (0.15, 0.88)),
       0.0: ([9.1, 22.2], (0.20, 0.80))}


def _fake(calls, plastic_at=None):
    """The 7x33's metrics by :data:`LAW` (the design torque's pattern 0.05 wider each
    end); every other metric a design meeting its targets. ``plastic_at``: a crowning of
    :data:`LAW` whose design torque carries 0.3 % of the torque plastic."""

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        key = round(case["profile_crowning"], 2)
        calls.append((key, misalignment is not None))
        lte, (toe, heel) = LAW.get(key, ([80.0, 80.0], (0.1, 0.9)))
        return (_metrics(lte_peak_to_peak=lte, pattern_toe_u=[toe, toe - 0.05],
                         pattern_heel_u=[heel, heel + 0.05],
                         plastic_share=[0.0, 0.003 if key == plastic_at else 0.0]),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


def _start(monkeypatch, calls, values=BEARING, **kw):
    targets, setup, chosen = stand_in(monkeypatch, _fake(calls, **kw), [37.6, 251.0])
    start = chosen(values)
    calls.clear()
    return targets, setup, start


@pytest.fixture
def lines():
    return []


def test_the_flat_profile_meets_every_target_of_the_7x33(monkeypatch, lines):
    """The written design misses the length (0.78 against 0.5 ± 0.1) and the LTE (31 / 56
    against 40 µrad), so the overlap step's longer ellipse has no room; the profile
    crowning at its lower bound, the ellipse kept (9 / 22 µrad, 0.60 long): every target
    met, kept, asked for its tolerance once (four excursions), the least LTE recorded."""
    calls = []
    targets, setup, start = _start(monkeypatch, calls)
    assert sorted(k for k, v in start.full[1].items() if v > 0) == ["length", "lte"]
    got = dcheck.checked_overlap_lte(start, targets, setup, None, lines.append,
                                     lambda v: dict(v))
    assert got.met
    assert got.values == BEARING | {"profile_crowning": 0.0}  # the ellipse 0.75 kept
    assert list(got.metrics["lte_peak_to_peak"]) == [9.1, 22.2]
    assert calls == [(0.0, False)] + [(0.0, True)] * 4
    assert "the ellipse kept" in lines[0] and "pattern 0.78 long" in lines[0]
    reach = setup["lte_reach"][(37.6, 251.0)]
    assert (reach["light"], reach["design"], reach["why"]) == (9.1, 22.2, "")
    assert "the profile crowning flattened" in reach["tried"]


def test_half_the_crowning_where_the_flat_profile_loses_a_target(monkeypatch, lines):
    """The flat profile with 0.3 % of the design torque plastic loses a target the design
    met: not kept, no tolerance asked for it; half the crowning (21 / 39 µrad, 0.73
    long: the LTE met, the length still missed, as the design's was) ranks better and
    loses nothing: kept, tolerance asked once."""
    calls = []
    targets, setup, start = _start(monkeypatch, calls, plastic_at=0.0)
    got = dcheck.checked_overlap_lte(start, targets, setup, None, lines.append,
                                     lambda v: dict(v))
    assert got.values == BEARING | {"profile_crowning": 11.18}
    assert calls == [(0.0, False), (11.18, False)] + [(11.18, True)] * 4
    assert [k for k, v in got.full[1].items() if v > 0] == ["length"]
    assert got.full[0] < start.full[0]


def test_a_flat_profile_or_a_short_pattern_is_left_alone(monkeypatch, lines):
    """No analysis where the profile crowning is at its lower bound already (nothing to
    flatten), nor where the pattern misses its length by being too short (the overlap
    step's own gate: no room is not the reason there)."""
    calls = []
    targets, setup, _ = _start(monkeypatch, calls)
    flat = _checked(BEARING | {"profile_crowning": 0.0},
                    _metrics(lte_peak_to_peak=[30.0, 56.0], pattern_toe_u=[0.1, 0.05],
                             pattern_heel_u=[0.9, 0.95]), targets, 0.6)
    short = _checked(BEARING, _metrics(lte_peak_to_peak=[30.0, 56.0],
                                       pattern_toe_u=[0.4, 0.35],
                                       pattern_heel_u=[0.7, 0.75]), targets, 0.6)
    assert flat.full[1]["length"] > 0 and short.full[1]["length"] > 0
    for e in (flat, short):
        assert dcheck.checked_overlap_lte(e, targets, setup, None, lines.append,
                                          lambda v: dict(v)) is e
    assert calls == [] and lines == []
