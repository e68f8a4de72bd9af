"""The development's LTE margin below the verdict's 60 µrad
(:func:`contact.optimize.development_range_lte.development_lte_limit`, issue 71: "LTE p-p
≤ 60 µrad at every torque", branch margin101).

``ltca run`` samples a mesh cycle at 20 roll positions; a p-p over more rolls catches more
of the extremes, so a bearing the development writes at 59.5 µrad reads 60.3 with 40 rolls
a cycle (the FM spiral bevel 24x29 at Σ 105° of benchmarks/data/unseen_designs,
docs/synthesis.md "The development's LTE margin"). The development's keep and lower
decisions aim at the verdict's limit less :data:`LTE_SAMPLING_MARGIN`; the verdict's limit
is not touched.

The margin is off by default (0: the development aims at the verdict's 60 µrad and writes
what main wrote): on the 24x29 a 2 % margin cut the design torque from 503 to 259.7 N·m
(docs/synthesis.md). These tests set the 2 % the measurement justifies and hold it against
two independent references: the closed form of a sampled sinusoid's missed extremes (N
samples a cycle, the extremes halfway between two samples: the sampled p-p is cos(π/N) of
the true one) and the excesses measured on the written cases. The stand-ins are the
rule's choices on laws whose numbers are the written cases' (each cited), not numbers of a
gear.
"""

from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace

import numpy as np
import pytest
from development_stand_ins import metrics as _metrics
from development_stand_ins import seen_designs, stand_in

from contact.ltca import LTCAOptions
from contact.ltca.lte_range import lte_range_torques
from contact.optimize import development_coast_lte_torque as lte_torque
from contact.optimize import development_range_lte as drl
from contact.optimize.development_coast import CoastCapacity, CoastCheck
from contact.optimize.development_targets import DevelopmentTargets
from contact.study.verdicts import LTE_LIMIT

#: the written cases within 3 µrad of 60 whose LTE p-p converges with the rolls a cycle: the
#: largest at ``ltca run``'s sampling and the finest of 40 / 80 / 160 rolls a cycle, 48
#: segments and 12 torques from the light to the design torque [µrad] (docs/synthesis.md,
#: "The development's LTE margin"; benchmarks/data/unseen_designs, ``ltca synthesize`` on
#: main f59c9052, 2026-11-29). The FM 14x19 at Σ 60°'s coast (59.6 → 63.7 µrad at 160
#: rolls, 6.7 %) is not among them: a narrow feature 20 rolls do not resolve, which no
#: margin of this size covers (docs/synthesis.md; the lead's decision)
MEASURED = {
    "FM spiral bevel 24x29 at Sigma 105, drive at 217.9 N m (160 rolls)": (59.54, 60.383),
    "FH spiral bevel 12x27, drive at 36.7 N m (48 segments)": (59.789, 60.025),
    "FH spiral bevel 12x27, coast at 15.1 N m (160 rolls)": (59.976, 60.579),
}


#: the margin the measurement justifies (docs/synthesis.md): it covers the closed form's
#: 1.2 % and the converged excesses below (1.4 % at most)
MARGIN = 0.02


@pytest.fixture
def margin(monkeypatch):
    """The development's aim with the 2 % margin set."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", MARGIN)
    return MARGIN


def test_by_default_the_development_aims_at_the_verdicts_limit():
    """Off by default: the aim is the verdict's 60 µrad exactly (the cases main wrote)."""
    assert LTE_LIMIT == 60.0 and drl.verdict_lte_limit() == 60.0
    assert drl.LTE_SAMPLING_MARGIN == 0.0
    assert drl.development_lte_limit() == 60.0


def test_the_verdicts_limit_stays_60_and_the_development_aims_below_it(margin):
    """With the margin set the verdict's limit is still 60 µrad; the development's aim is it
    less the margin (identity, to rounding): 58.8 µrad."""
    assert LTE_LIMIT == 60.0 and drl.verdict_lte_limit() == 60.0
    aim = drl.development_lte_limit()
    assert aim == pytest.approx(60.0 * (1.0 - margin), rel=1e-15)
    assert aim == pytest.approx(58.8, rel=1e-12)


def test_the_margin_covers_a_sampled_sinusoids_missed_extremes(margin):
    """Closed form: a sinusoid of amplitude a sampled at N evenly spaced rolls a cycle whose
    extremes fall halfway between two rolls reads the p-p 2 a cos(π/N) (N even). A curve
    read at the development's aim at ``ltca run``'s N = 20 is at most aim / cos(π/20)
    = aim × 1.0125: within 60 µrad. Checked on 20 000 samples too (the dense p-p to
    1e-6 of the closed form: cos of half the dense step, 1 - 2.5e-8)."""
    n = LTCAOptions().rolls_per_cycle
    assert n == 20
    aim = drl.development_lte_limit()
    a = 0.5 * aim / math.cos(math.pi / n)  # the sampled p-p at the aim, worst phase
    rolls = (np.arange(n) + 0.5) * 2.0 * math.pi / n
    sampled = np.ptp(a * np.sin(rolls + math.pi / 2.0))
    assert sampled == pytest.approx(aim, rel=1e-12)
    dense = np.ptp(a * np.sin(np.linspace(0.0, 2.0 * math.pi, 20001)))
    assert dense == pytest.approx(2.0 * a, rel=1e-6)
    assert dense <= LTE_LIMIT
    assert margin >= 1.0 - math.cos(math.pi / n)


@pytest.mark.parametrize("name", sorted(MEASURED))
def test_the_margin_covers_the_measured_sampling_excess(name, margin):
    """A written case at the aim whose LTE rises by the measured share at a finer sampling
    stays within 60 µrad: (1 - margin) × fine / coarse ≤ 1 (the measured pairs above)."""
    coarse, fine = MEASURED[name]
    assert fine > coarse  # a finer sampling reads more: the margin's reason
    assert drl.development_lte_limit() * fine / coarse <= LTE_LIMIT


# --- the drive range step (checked_range_lte) on the 24x29's curve -------------------------

#: the 24x29's written case: light / design torque [N·m], its drive LTE p-p [µrad] at ltca
#: run's lte_range torques 75.4 / 217.9 / 360.5 / 503 (docs/synthesis.md): 20.8 / 59.5 /
#: 52.2 / 40.9 with the ellipse 0.80; the 0.85 ellipse's (development_levers): 20 / 53 /
#: 46 / 37
TORQUES = (75.4, 503.0)
GRID = lte_range_torques(TORQUES, TORQUES[1])
WRITTEN = {"path_angle": -80.0, "ellipse_length": 0.8, "tip_relief": 11.25,
           "root_relief": 40.0, "relief_start": 0.2, "profile_crowning": 0.0,
           "tip_relief_start": 0.85, "blade_angle_change": 0.0, "te_level": 10.0}
CURVES = {0.8: (20.8, 59.5, 52.2, 40.9), 0.85: (20.0, 53.0, 46.0, 37.0)}


def _law(curves=CURVES):
    def law(case, torques, misalignment=None, **kw):
        ts = tuple(float(t) for t in torques) or TORQUES
        row = curves.get(round(float(case["ellipse_length"]), 4), (80.0,) * 4)
        m = {k: np.resize(v, len(ts)) for k, v in _metrics().items()}
        m["lte_peak_to_peak"] = np.asarray(np.interp(ts, GRID, row), float)
        return m, (0.0, 1.0, 0.0, 1.0, 2400.0)

    return law


def _start(chosen):
    start = chosen(dict(WRITTEN))
    return dataclasses.replace(start, case=dict(start.values))


def _range_step(monkeypatch):
    """The range step on the stand-in law from its start design: (start, setup, the design
    it returns, its lines)."""
    _seen, fake = seen_designs(_law())
    targets, setup, chosen = stand_in(monkeypatch, fake, TORQUES)
    start = _start(chosen)
    lines: list[str] = []
    got = drl.checked_range_lte(start, targets, setup, None, lines.append,
                                lambda v: dict(v))
    return start, setup, got, lines


def test_the_range_step_acts_on_a_peak_between_the_aim_and_60(monkeypatch, margin):
    """59.5 µrad at 217.9 N m between the torques: within the verdict's 60 but above the
    development's aim, so the range step acts on it (before this branch it returned the
    design as it was); the design it keeps reads 53 µrad there (the 0.85 ellipse: in the
    written case the tolerance rule refused it, docs/synthesis.md; the stand-in's law is
    tolerant, the step's choice is what is tested)."""
    start, setup, got, lines = _range_step(monkeypatch)
    aim = drl.development_lte_limit()
    assert aim < 59.5 < LTE_LIMIT
    assert f"is above {aim:g} urad" in lines[0]
    assert got is not start and got.values["ellipse_length"] == pytest.approx(0.85)
    assert drl.range_record(setup)["peak"] == pytest.approx(53.0)


def test_with_no_margin_the_range_step_leaves_59_5(monkeypatch):
    """The same law with the margin 0 (the default): the aim is the verdict's 60 and 59.5
    is kept (main's rule; what the margin changes)."""
    monkeypatch.setattr(drl, "LTE_SAMPLING_MARGIN", 0.0)
    start, _setup, got, lines = _range_step(monkeypatch)
    assert got is start and not lines


# --- the coast design torque lowered to the aim (coast_lte_torque) on the 12x27's law -------

#: the FH 12x27's coast LTE law (tests/test_development_coast_lte_torque.py's TWELVE): 39.5 /
#: 61.7 / 74.2 µrad at 3.3 / 16.17 / 22.6 N m, light torque 0.146 of the design torque
KNOTS = ((3.3, 39.5), (16.17, 61.7), (22.6, 74.2))


def _interp(t):
    ts, xs = zip(*KNOTS, strict=True)
    return float(np.interp(t, ts, xs))


def test_the_coast_design_torque_is_lowered_to_the_aim(monkeypatch, margin):
    """The crossing is interpolated at the aim, not at 60: 39.5 / 56.15 / 74.2 µrad at 3.3 /
    12.95 / 22.6 N m, the aim's crossing 12.95 + (aim − 56.15) / 18.05 × 9.65 N m written
    rounded down to 0.1 (60's would be 15.0 N m); its own range keeps the aim."""
    light, design = 3.3, 22.6
    share = light / design
    calls: list[float] = []

    def fake_range(e, setup, teeth, *a, **k):
        lo, hi = (float(t) for t in setup["torques"])
        ts = (lo, 0.5 * (lo + hi), hi)
        return ts, tuple(_interp(t) for t in ts)

    def fake_capacity(case, basic, coast, targets, setup, start, root_stress, lower, say):
        calls.append(start)
        best = SimpleNamespace(checked_full=True, values=dict(coast.best.values),
                               metrics={"lte_peak_to_peak": [_interp(share * start),
                                                             _interp(start)]})
        check = CoastCheck(start, 1400.0, 2400.0, edge_peak=float("nan"))
        return (SimpleNamespace(best=best, torques=(share * start, start)),
                CoastCapacity(start, start, (check,), "", True))

    monkeypatch.setattr(lte_torque, "range_lte", fake_range)
    monkeypatch.setattr(lte_torque, "coast_flank_capacity", fake_capacity)
    coast = SimpleNamespace(best=SimpleNamespace(
        checked_full=True, values={"ellipse_length": 0.65},
        metrics={"lte_peak_to_peak": [_interp(light), _interp(design)]}),
        torques=(light, design))
    cap = CoastCapacity(design, design, (CoastCheck(design, 1500.0, 2400.0),), "", True)
    lines: list[str] = []
    outcome, got = lte_torque.coast_lte_torque(
        None, SimpleNamespace(gives_design_torque=False, rating={}), coast, cap,
        SimpleNamespace(values={"path_angle": -60.0}), DevelopmentTargets(),
        {"torques": [5.5, 36.7]}, None, True, lines.append)
    aim = drl.development_lte_limit()
    middle = _interp(12.95)
    crossing = 12.95 + (aim - middle) / (74.2 - middle) * (22.6 - 12.95)
    assert crossing < 15.0  # below 60's crossing (15.01 N m)
    assert calls == [pytest.approx(math.floor(crossing * 10.0) / 10.0)]
    assert got.torque == pytest.approx(calls[0]) and got.lowered
    assert max(outcome.best.metrics["lte_peak_to_peak"]) <= aim
