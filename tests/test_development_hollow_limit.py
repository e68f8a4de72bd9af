"""What limits a hollow profile on a written drive bearing whose LTE misses the
development's target above the load sharing's floor, said on ``ltca synthesize``'s drive
LTE line (:mod:`contact.optimize.development_hollow_limit`, issue 71).

The words are tested on stand-ins with the 13x33 at Σ 85°'s measured numbers (docs/
synthesis.md, "The 13×33's hollow profile against the edge levers"); the record a probe
reads from an analysis on a real analysis of the bundled default case, against an identity
(the edges' per-kind shares of the torque add up to their total share: Σ F·R over disjoint
sets of segments, seed Eq. 3.14).
"""

from __future__ import annotations

import math
import types
from pathlib import Path

import numpy as np
import pytest

from contact.optimize import development_hollow_limit as dhl
from contact.optimize.development_lte_lines import flank_lte_line

ROOT = Path(__file__).resolve().parents[1]


def _probe(crowning, lte, edge, shares, plastic, peak, v=0.86, pitting=1630.0,
           static=2400.0):
    return dhl.HollowProbe(crowning=crowning, lte=lte, edge_share=edge, edge_shares=shares,
                           plastic=plastic, flank_peak=peak, peak_v=v, pitting_limit=pitting,
                           static=static)


#: the 13x33's written bearing with the profile crowning −5 and −8 µm (2026-11-29, this
#: branch: hollow_probes on the written case)
MINUS_5 = _probe(-5.0, (17.5, 43.0), 0.0168, {"gear_tip": 0.0030, "gear_heel": 0.0014,
                                              "gear_toe": 0.0, "pinion_edge": 0.0124},
                 0.0, 2040.0)
MINUS_8 = _probe(-8.0, (25.3, 38.2), 0.0234, {"gear_tip": 0.0053, "gear_heel": 0.0014,
                                              "gear_toe": 0.0, "pinion_edge": 0.0167},
                 0.0046, 2423.0, v=1.0)


def test_the_words_name_the_edge_the_plastic_share_and_the_peak_against_its_limit():
    """−5 µm keeps the edge target (1.7 % ≤ 2 %) and no segment plastic: its cost is the
    flank peak above the local pitting limit (below the static strength), said with where
    it sits; −8 µm: the edges above 2 %, the pinion edge (the largest share) named,
    the plastic share, and the peak above the static strength (the larger limit said)."""
    text = dhl.hollow_text([MINUS_5, MINUS_8], 40.0, 0.02)
    assert text.startswith("; a hollow profile lowers it (-5 um: 18/43 urad, -8 um: 25/38 "
                           "urad) but the profile's ends it loads limit it: ")
    five, eight = text.split("limit it: ")[1].split("; at ")
    assert "local pitting limit 1630 MPa" in five and "2040 MPa at v 0.86" in five
    assert "edges carry" not in five and "plastic" not in five
    assert "towards the gear's tip, the pinion's root" in five
    assert "the edges carry 2.3 % of the torque (limit 2 %; the pinion edge 1.7 %)" in eight
    assert "plastic 0.5 %" in eight
    assert "above the static strength 2400 MPa" in eight and "local pitting" not in eight


def test_a_probe_within_every_limit_and_none_at_all():
    """A probe at the target with none of the costs is said so (the other targets decide);
    one that does not reach the target and costs nothing is said not to reach it; no
    probe: nothing."""
    free = _probe(-6.0, (30.6, 39.9), 0.0, {"gear_tip": 0.0}, 0.0, 1600.0, pitting=1606.4)
    text = dhl.hollow_text([free], 40.0, 0.02)
    assert text.startswith("; a hollow profile lowers it (-6 um: 31/40 urad): at -6 um no "
                           "edge, plastic or flank-peak cost") and "limit it" not in text
    # the 7x29's (-6 µm within its local pitting limit, -8 µm above it): the free one first
    deeper = _probe(-8.0, (26.7, 37.9), 0.0, {"gear_tip": 0.0}, 0.0, 1625.0, pitting=1606.4)
    both = dhl.hollow_text([free, deeper], 40.0, 0.02)
    assert both.index("at -6 um no edge") < both.index("; hollower, the profile's ends it "
                                                       "loads limit it: at -8 um the flank "
                                                       "peak 1625 MPa")
    short = _probe(-5.0, (30.0, 45.0), 0.01, {"gear_tip": 0.01}, 0.0, 1500.0)
    assert dhl.hollow_text([short], 40.0, 0.02) == ("; a hollow profile (-5 um: 30/45 "
                                                    "urad) does not reach 40 urad either")
    assert dhl.hollow_text([], 40.0, 0.02) == ""


def test_the_drive_line_ends_with_the_hollow_profile_after_the_floor():
    """The 13x33's drive line (53 µrad against 40 above the floor 29): the floor, then the
    hollow profile's limit; nothing added where the target is met."""
    args = ("drive", (59.0, 393.5), (16.0, 53.0), {"peak": 54.5, "at": 282.0}, 60.0, 40.0)
    hollow = dhl.hollow_text([MINUS_5, MINUS_8], 40.0, 0.02)
    floor_only = flank_lte_line(*args, floor=29.0)
    line = flank_lte_line(*args, floor=29.0, hollow=hollow)
    assert line == floor_only + hollow
    assert flank_lte_line("drive", (59.0, 393.5), (16.0, 38.0), None, 60.0, 40.0,
                          floor=29.0, hollow=hollow) is None


def test_the_probe_record_on_a_real_analysis_of_the_default_case():
    """The bundled default case at 50 / 500 N m (``ltca run``'s sampling): the per-kind
    edge shares add up to the edge share (disjoint sets of segments of one sum; 1e-12 of
    the share: round-off of a sum of a few hundred terms), the LTE is the dataset's own,
    the peak's depth a node of the gear grid in [0, 1]."""
    from contact.chain import AnalysisChain
    from contact.ltca.summary import edge_load_share
    from contact.pipeline import run_analysis
    from geometry.case import load_case

    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    tree = run_analysis(case, [50.0, 500.0], flank="drive", deviations=False,
                        steps=AnalysisChain.contact_only())
    ltca = tree["/ltca"].to_dataset()
    p = dhl.probe_of(ltca, case, -5.0, math.inf, 2400.0)
    total = float(np.nan_to_num(edge_load_share(ltca)[-1]))
    assert p.edge_share == pytest.approx(total, abs=1e-15)
    assert sum(p.edge_shares.values()) == pytest.approx(total, rel=1e-12, abs=1e-15)
    assert p.lte == pytest.approx(tuple(np.asarray(ltca["lte_peak_to_peak"].values,
                                                   float)), rel=0, abs=0)
    assert p.peak_v in set(np.asarray(ltca["v"].values, float)) and 0.0 <= p.peak_v <= 1.0


def test_bad_torques_and_the_gate_of_the_written_line():
    """Torques not 0 < light < design: ValueError naming them. The written line's probe
    runs only where the floor is finite and below the target (no analysis otherwise: a
    stand-in development without a basic design would fail one)."""
    from contact.optimize.written_notes import written_hollow

    with pytest.raises(ValueError, match="0 < light < design"):
        dhl.hollow_probes(None, {}, (100.0, 50.0))
    dev = types.SimpleNamespace(targets=types.SimpleNamespace(max_lte=40.0,
                                                              max_edge_share=0.02),
                                best=types.SimpleNamespace(values={"profile_crowning": 0.0}),
                                basic=None, torque=(59.0, 393.5))
    assert written_hollow(None, dev, 41.0) == ""
    assert written_hollow(None, dev, math.nan) == ""


def test_the_written_line_probes_only_hollower_profiles_at_the_size_scale(monkeypatch):
    """The probes are :data:`HOLLOW_PROBES` × the design's size scale, those hollower than
    the written crowning alone (a written −3 µm at the scale 0.5: −4 µm probed, −2.5 not),
    and a written hollow profile :data:`HOLLOW_STEP` × the scale hollower too (−3.5 µm),
    shallowest first, at the development's torques, on its basic design and the written
    case; their words are :func:`hollow_text`'s with the development's edge target. A
    profile not hollow gets the probes alone."""
    from contact.optimize.written_notes import written_hollow

    seen = {}

    def probes(basic, values, torques, written=None, crownings=None):
        seen.update(basic=basic, values=dict(values), torques=torques, written=written,
                    crownings=list(crownings))
        return [MINUS_8]

    monkeypatch.setattr(dhl, "hollow_probes", probes)
    basic = types.SimpleNamespace(size_scale=lambda: 0.5)
    dev = types.SimpleNamespace(targets=types.SimpleNamespace(max_lte=40.0,
                                                              max_edge_share=0.02),
                                best=types.SimpleNamespace(values={"profile_crowning": -3.0}),
                                basic=basic, torque=(59.0, 393.5))
    text = written_hollow("case", dev, 29.0)
    assert seen == {"basic": basic, "values": {"profile_crowning": -3.0},
                    "torques": (59.0, 393.5), "written": "case", "crownings": [-3.5, -4.0]}
    assert text == dhl.hollow_text([MINUS_8], 40.0, 0.02)
    dev.best.values["profile_crowning"] = 0.0  # not hollow: the probes alone
    written_hollow("case", dev, 29.0)
    assert seen["crownings"] == [-2.5, -4.0]
    dev.best.values["profile_crowning"] = -4.0  # hollower than both: the step alone
    written_hollow("case", dev, 29.0)
    assert seen["crownings"] == [-4.5]
