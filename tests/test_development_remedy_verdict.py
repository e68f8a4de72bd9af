"""The remedied design's ``ltca run`` verdict judged against the design as given's before
``ltca synthesize --apply-remedy`` writes it (contact.optimize.development_remedy_verdict;
issue 71, branch remedy99).

Fast: the developments are stand-ins (tests/development_stand_ins' metrics of a design
meeting every default target, with the one reading each test changes); the limits each
finding is judged against are the verdict's own constants, and each test puts its reading
on both sides of them (the bounds stated beside the numbers). The basic data, contact
ratios and remedies are the real FM hypoid 5x48's (as tests/test_development_remedy)."""

from __future__ import annotations

import dataclasses
import types
from pathlib import Path

import pytest
from development_stand_ins import checked, metrics

from contact.ltca.plausibility import EDGE_SHARE_MIN, LTE_SPREAD_LIMIT, PLASTIC_SHARE_LIMIT
from contact.optimize import remedy_check
from contact.optimize.development import DevelopmentResult, DevelopmentTargets
from contact.optimize.development_remedy import developed_with_remedy
from contact.optimize.development_remedy_verdict import flank_findings, verdict_worse
from contact.study.verdicts import LTE_FAIL_FACTOR, LTE_LIMIT
from geometry.core.errors import InputError
from geometry.synthesis.basic_design import load_basic

ROOT = Path(__file__).resolve().parent.parent
FIVE = ROOT / "benchmarks" / "data" / "unseen_designs" / "hypoid_5x48_a36_m1.toml"
TORQUES = (31.0, 206.7)
COAST_TORQUES = (22.7, 151.9)


def _result(basic=None, drive=None, coast=None, design_torque=206.7, **extra):
    """A development whose written drive design reads ``metrics(**drive)`` at (31, 206.7)
    N m, its coast flank ``metrics(**coast)`` at (22.7, 151.9) N m (the 5x48's torques,
    round 34); ``coast`` False: the coast flank not measured."""
    targets = DevelopmentTargets()
    best = checked({"path_angle": -30.0}, metrics(**(drive or {})), targets, 0.6)
    case = types.SimpleNamespace(gear=types.SimpleNamespace(process="Formate"))
    return DevelopmentResult(basic, case, None, best, (best,), (31.0, design_torque),
                             "given", {}, targets, 1.0,
                             coast=None if coast is False else metrics(**(coast or {})),
                             coast_torques=COAST_TORQUES, **extra)


def test_findings_at_the_verdicts_own_limits():
    """Each finding at its limit and just beyond (the verdict's constants: LTE 60 urad,
    FAIL beyond 2 x; plastic share above 0 an attention, beyond 5 % implausible; an LTE
    spread beyond 0.5 implausible unless a quiet transfer; an edge share at the light
    torque from 5e-4 of the torque); the stand-in design meets every target: none."""
    assert flank_findings(metrics(), TORQUES, LTE_LIMIT) == {}
    assert flank_findings(None, TORQUES, LTE_LIMIT) == {}
    at = {"lte_peak_to_peak": [20.0, LTE_LIMIT]}
    assert flank_findings(metrics(**at), TORQUES, LTE_LIMIT) == {}
    lte = flank_findings(metrics(lte_peak_to_peak=[20.0, LTE_LIMIT + 0.1]), TORQUES,
                         LTE_LIMIT)["lte"]
    assert lte.severity == "attention" and "60.1 urad at 206.7 N m" in lte.text
    fail = LTE_FAIL_FACTOR * LTE_LIMIT
    assert flank_findings(metrics(lte_peak_to_peak=[fail, 30.0]), TORQUES,
                          LTE_LIMIT)["lte"].severity == "attention"
    assert flank_findings(metrics(lte_peak_to_peak=[fail + 0.1, 30.0]), TORQUES,
                          LTE_LIMIT)["lte"].severity == "fail"
    # plastic: attention above 0 up to the limit, implausible (FAIL) beyond it
    assert flank_findings(metrics(plastic_share=[0.0, PLASTIC_SHARE_LIMIT]), TORQUES,
                          LTE_LIMIT)["plastic_edges"].severity == "attention"
    over = flank_findings(metrics(plastic_share=[0.0, PLASTIC_SHARE_LIMIT + 0.01]),
                          TORQUES, LTE_LIMIT)
    assert "plastic_edges" not in over and over["implausible"].severity == "fail"
    assert "plastic share 0.06 at 206.7 N m (limit 0.05)" in over["implausible"].text
    # LTE spread beyond its limit with an edge share: implausible; as a quiet transfer
    # (no edge share, LTE p-p within the limit): none
    spread = {"lte_spread": [LTE_SPREAD_LIMIT + 0.1, 0.1]}
    assert "implausible" in flank_findings(
        metrics(edge_load_share=[0.01, 0.01], **spread), TORQUES, LTE_LIMIT)
    assert "implausible" not in flank_findings(
        metrics(edge_load_share=[0.0, 0.0], **spread), TORQUES, LTE_LIMIT)
    # light-torque edge: the edge share at the light torque from EDGE_SHARE_MIN; the
    # counted share (edge_contact_share) read where recorded
    below = metrics(edge_load_share=[0.9 * EDGE_SHARE_MIN, 0.05])
    assert "light_edge" not in flank_findings(below, TORQUES, LTE_LIMIT)
    edge = flank_findings(metrics(edge_load_share=[EDGE_SHARE_MIN, 0.0]), TORQUES,
                          LTE_LIMIT)["light_edge"]
    assert edge.severity == "attention" and "at the light torque at 31 N m" in edge.text
    counted = metrics(edge_load_share=[0.01, 0.0], edge_contact_share=[0.0, 0.0])
    assert "light_edge" not in flank_findings(counted, TORQUES, LTE_LIMIT)
    # the LTE between the torques read where recorded
    between = {"torques": [31.0, 120.0, 206.7], "lte": [20.0, 64.0, 30.0]}
    assert "64.0 urad at 120 N m" in flank_findings(metrics(), TORQUES, LTE_LIMIT,
                                                    between)["lte"].text


def test_worse_is_the_verdicts_order_flank_by_flank():
    """A finding the remedied design has and the design as given has not, or has at a
    lower severity, on the same flank and check, is worse; the same severity is not
    (a trial for an LTE above the limit may stay above it, not FAIL); the other flank's
    finding is no excuse."""
    given = _result()
    assert verdict_worse(given, _result(), LTE_LIMIT) == ""
    coast_plastic = _result(coast={"plastic_share": [0.0, 0.008]})
    worse = verdict_worse(given, coast_plastic, LTE_LIMIT)
    assert worse == ("its coast flank's plastic_edges ATTENTION: plastic share 0.8 % at "
                     "151.9 N m (ATTENTION up to 5 %), where the design as given's has none")
    assert verdict_worse(coast_plastic, coast_plastic, LTE_LIMIT) == ""
    # the given's drive plastic share does not excuse the remedied coast one
    assert "coast flank" in verdict_worse(_result(drive={"plastic_share": [0.0, 0.01]}),
                                          coast_plastic, LTE_LIMIT)
    # an LTE trial: the given at 93 urad (attention), the remedied at 100 (attention): no
    # worse; at 121 (beyond 2 x 60: FAIL) worse
    trial = _result(drive={"lte_peak_to_peak": [86.0, 93.0]})
    assert verdict_worse(trial, _result(drive={"lte_peak_to_peak": [80.0, 100.0]}),
                         LTE_LIMIT) == ""
    failing = verdict_worse(trial, _result(drive={"lte_peak_to_peak": [80.0, 121.0]}),
                            LTE_LIMIT)
    assert failing.startswith("its drive flank's lte FAIL: LTE p-p 121.0 urad at 206.7 N m")
    assert "where the design as given's ATTENTION: LTE p-p 93.0 urad" in failing
    # a lower LTE is no finding
    assert verdict_worse(trial, given, LTE_LIMIT) == ""


def test_coast_and_range_judged_only_where_both_developments_measured_them():
    """A coast flank one development did not measure is not judged; the LTE between the
    torques is read only where both developments recorded it on that flank."""
    light_edge = {"edge_load_share": [0.01, 0.01]}
    assert verdict_worse(_result(coast=False), _result(coast=light_edge), LTE_LIMIT) == ""
    assert "coast flank's light_edge" in verdict_worse(_result(), _result(coast=light_edge),
                                                       LTE_LIMIT)
    above = {"torques": [31.0, 120.0, 206.7], "lte": [20.0, 64.0, 30.0]}
    within = {"torques": [31.0, 120.0, 206.7], "lte": [20.0, 40.0, 30.0]}
    assert verdict_worse(_result(), _result(lte_range=above), LTE_LIMIT) == ""
    assert "64.0 urad at 120 N m" in verdict_worse(_result(lte_range=within),
                                                   _result(lte_range=above), LTE_LIMIT)


def _stand_in_checks(monkeypatch):
    """The 5x48's checks as round 34's note printed them (alpha_dD 16.3 deg 70 urad, k_d
    2.26 71 urad; written 73)."""
    def check(basic, change):
        m = {"alpha_dD": (70.0, 89.0, 0.7), "k_d": (71.0, 129.0, 0.7)}[change.field]
        return remedy_check.ChangeCheck(change, *m, "", 0.5)

    monkeypatch.setattr(remedy_check, "check_change", check)
    monkeypatch.setattr(remedy_check, "unloaded_te_pp", lambda case: (73.0, 89.0, 0.7))
    monkeypatch.setattr(remedy_check, "unrelieved_te_pp",
                        lambda basic, memo=None: (float("nan"),) * 2)


@pytest.mark.parametrize("coast, refused", [
    ({}, False),
    ({"edge_load_share": [0.02, 0.02]}, True),   # a coast light-torque edge
    ({"plastic_share": [0.0, 0.06]}, True),      # implausible: a FAIL
])
def test_apply_remedy_refuses_a_remedy_whose_verdict_is_worse(monkeypatch, coast, refused):
    """Through developed_with_remedy: the design as given (the 5x48, LTE within 60, no
    finding) and a remedied development at the same design torque whose coast flank has
    a light-torque edge or a plastic share beyond the plausibility limit: an InputError
    naming the flank, the check and its reading after the two developments, nothing
    returned; without the finding the remedy is applied."""
    basic = load_basic(FIVE)
    _stand_in_checks(monkeypatch)
    developed: list = []

    def run(b):
        developed.append(b)
        first = len(developed) == 1
        r = _result(b, {"lte_peak_to_peak": [35.0, 29.0] if first else [26.0, 28.0]},
                    {} if first else coast)
        return dataclasses.replace(r, basic=b)

    if refused:
        with pytest.raises(InputError, match=r"alpha_dD 22\.5 -> 16\.3 deg developed: ltca "
                                             r"run's verdict of the remedied design would be "
                                             r"worse than the design as given's \(its coast "
                                             r"flank's .*, where the design as given's has "
                                             r"none\); nothing written"):
            developed_with_remedy(run, basic)
        assert len(developed) == 2
    else:
        result = developed_with_remedy(run, basic)
        assert result.remedy.check.change.field == "alpha_dD"
