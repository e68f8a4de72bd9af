"""The pattern length a low face contact ratio's LTE needs, and the length a development
gave up for it said (contact.optimize.development_length_trade; issue 71, docs/synthesis.md
"The pattern length on a low face contact ratio")."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from development_stand_ins import checked, metrics

from contact.load_capacity.iso10300.face_contact import FACE_CONTACT_RATIO_MIN
from contact.optimize.development import DevelopmentTargets
from contact.optimize.development_length_trade import (
    FACE_OVERLAP_LENGTH,
    fits_the_face,
    length_trade_text,
    no_length_text,
    overlap_length,
    traded_length,
)
from contact.optimize.written_notes import FACE_CONTACT_RATIO_NOTE, length_trade
from geometry.core.errors import InputError

#: the measured least light-load pattern length [1] at which the LTE p-p kept 40 µrad at
#: the light and design torque and 60 µrad between them, with each design's ε_vβ
#: (benchmarks/development_levers.py --check --at, ltca run's sampling, 2026-11-27;
#: docs/synthesis.md): the hypoid 13x41 at β_m1 30° (ellipse 0.875, no profile crowning:
#: 0.80, 13 / 40.5 µrad, 45 between), the bundled 11x41 (0.60: 37 / 38.5 µrad), the spiral
#: bevel 27x34 at β_m 30° (0.60 with 61 µrad between, the least; 0.65 the tolerant one)
MEASURED = ((0.831, 0.80), (1.134, 0.60), (1.173, 0.60), (1.173, 0.65))

#: the 27x34 at β_m 30° as `ltca synthesize` wrote it (2026-11-27, this tree): pattern
#: 0.175-0.825 at the light torque, LTE 31 / 40 µrad, every drive target met but the length
WRITTEN_27X34 = {"pattern_toe_u": [0.175, 0.0], "pattern_heel_u": [0.825, 1.0],
                 "pattern_centre_u": [0.50, 0.49], "pattern_centre_v": [0.61, 0.62],
                 "lte_peak_to_peak": [31.1, 39.7]}


def _development(over: dict, targets: DevelopmentTargets | None = None):
    t = DevelopmentTargets() if targets is None else targets
    best = checked({}, metrics(**over), t, 0.6)
    return SimpleNamespace(best=best, targets=t)


def test_the_law_lies_within_the_measured_products():
    # the constant is no fit to one design: it lies within the length x eps_vb each design
    # needed (0.66-0.76), and the law's length is within 0.06 of every measured least length
    products = [length * eps for eps, length in MEASURED]
    assert min(products) <= FACE_OVERLAP_LENGTH <= max(products)
    for eps, length in MEASURED:
        assert abs(overlap_length(eps) - length) <= 0.06  # a node of 0.025 and the margin


def test_the_law_within_the_target_band_from_agma_least_ratio():
    # at AGMA 2005-D03's least eps_vb 1.25 the need is inside 0.5 +/- 0.1 (the target
    # stays for every design meeting the least ratio), and the band's upper end 0.6 holds
    # down to eps_vb 0.7 / 0.6 = 1.167
    t = DevelopmentTargets()
    upper = t.pattern_length + t.pattern_length_tolerance
    assert overlap_length(FACE_CONTACT_RATIO_MIN) == pytest.approx(0.56)
    assert overlap_length(FACE_OVERLAP_LENGTH / upper) == pytest.approx(upper)
    assert overlap_length(0.5) > 1.0  # no pattern on the face is long enough


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, True, "1.2"])
def test_overlap_length_refuses_a_bad_ratio(bad):
    with pytest.raises(InputError, match="eps_vb"):
        overlap_length(bad)


def test_traded_length_only_a_long_pattern_missed_alone():
    t = DevelopmentTargets()
    e = _development(WRITTEN_27X34).best
    assert traded_length(e.metrics, e.full[1], 0.5, 0.1) == pytest.approx(0.65)
    # the same pattern with a wider band: met, nothing traded
    assert traded_length(e.metrics, {"length": 0.0}, 0.5, 0.2) is None
    # a short pattern missed (0.3 long) is not a length given up for the LTE
    short = _development({"pattern_toe_u": [0.3, 0.2], "pattern_heel_u": [0.6, 0.8]}).best
    assert short.full[1]["length"] > 0.0
    assert traded_length(short.metrics, short.full[1], 0.5, 0.1) is None
    # the length and the LTE missed (the 13x41 at beta_m1 30 deg: 0.62, 56 urad)
    both = _development(WRITTEN_27X34 | {"lte_peak_to_peak": [21.0, 56.0]}, t).best
    assert both.full[1]["lte"] > 0.0
    assert traded_length(both.metrics, both.full[1], 0.5, 0.1) is None


def test_the_note_on_the_27x34():
    d = _development(WRITTEN_27X34)
    said = length_trade_text(d, 1.173, FACE_CONTACT_RATIO_NOTE)
    assert said.startswith("the drive pattern is 0.65 of the face width long, above the "
                           "target 0.5 +/- 0.1, its one target missed")
    assert "at eps_vb 1.17 needs a light-load pattern of about 0.60" in said
    assert "at eps_vb 1.25 the LTE needs 0.56, within it" in said
    assert length_trade(d, (1.36, 1.173)) == "; " + said


def test_no_note_where_nothing_was_traded():
    d = _development(WRITTEN_27X34)
    # eps_vb at the least ratio: the note's remedy has nothing to give
    assert length_trade_text(d, 1.25, FACE_CONTACT_RATIO_NOTE) == ""
    # every target met
    assert length_trade_text(_development({}), 1.0, FACE_CONTACT_RATIO_NOTE) == ""
    # the LTE missed too
    lte = _development(WRITTEN_27X34 | {"lte_peak_to_peak": [21.0, 56.0]})
    assert length_trade_text(lte, 0.83, FACE_CONTACT_RATIO_NOTE) == ""
    assert length_trade(None, (1.36, 1.173)) == ""


def test_the_note_names_apply_remedy_where_a_change_passed(monkeypatch):
    # the record's first passed change is what --apply-remedy develops (measured on the
    # 27x34: beta_m 31.7 deg, eps_vb 1.25, every drive target met, the pattern 0.60 long)
    import contact.optimize.development_remedy as remedy

    d = _development(WRITTEN_27X34)
    record = object()
    monkeypatch.setattr(remedy, "chosen_check", lambda r: "passed" if r is record else None)
    said = length_trade(d, (1.36, 1.173), record)
    assert said.endswith("within it; ltca synthesize --apply-remedy develops the checked "
                         "change")
    # none passed its check (or none checked): the flag is not named
    assert not length_trade(d, (1.36, 1.173), object()).endswith("change")
    assert length_trade(d, (1.36, 1.173), None).endswith("within it")


#: the written 21x21 at eps_vb 0.64 (`ltca synthesize` with every default, 2026-11-27,
#: branch contact82): pattern 0.28-0.83 at 83.7 N m, LTE p-p 90.1 / 89.7 urad at 83.7 /
#: 558.5 N m, every drive target met but the LTE
WRITTEN_21X21 = {"pattern_toe_u": [0.28, 0.25], "pattern_heel_u": [0.83, 0.9],
                 "pattern_centre_u": [0.50, 0.52], "pattern_centre_v": [0.60, 0.60],
                 "lte_peak_to_peak": [90.1, 89.7]}

#: measured (benchmarks/development_levers.py --check and the written drive bearing's
#: ellipse lengthened, ltca run's sampling, 2026-11-27, branch contact82; docs/synthesis.md
#: "A longer pattern below a face contact ratio of 0.76"): eps_vb and whether some longer
#: light-load pattern took the LTE p-p within the verdict's 60 urad at the light and the
#: design torque: the 21x21 (0.64: 0.82 long, 41 / 118 urad) and the 16x20 at Sigma 75 deg
#: (0.71: 0.60 long, 46 / 84 urad) did not; the 13x41 at beta_m1 30 deg (0.83: 0.75 long,
#: 13 / 45) and the 20x40 at beta_m 25 deg (0.87: 0.80 long, 46 / 54) of branch len81 did
LONGER_PATTERN_REACHED = ((0.64, False), (0.71, False), (0.83, True), (0.87, True))


def test_the_pattern_fits_the_face_where_a_longer_one_was_measured_to_help():
    # the law's length against the 0.92 of the face the default clearance 0.04 leaves: it
    # separates the measured designs exactly (no tolerance: a yes/no per design)
    clearance = DevelopmentTargets().clearance
    for eps, reached in LONGER_PATTERN_REACHED:
        assert fits_the_face(eps, clearance) is reached
    # the boundary: eps_vb = 0.7 / 0.92
    edge = FACE_OVERLAP_LENGTH / (1.0 - 2.0 * clearance)
    assert edge == pytest.approx(0.761, abs=5e-4)
    assert fits_the_face(edge, clearance) and not fits_the_face(edge - 1e-6, clearance)
    # no clearance: the whole face, eps_vb 0.7
    assert fits_the_face(0.7, 0.0) and not fits_the_face(0.69, 0.0)


@pytest.mark.parametrize("bad", [-0.01, 0.5, math.nan, True, "0.04"])
def test_fits_the_face_refuses_a_bad_clearance(bad):
    with pytest.raises(InputError, match="clearance"):
        fits_the_face(0.8, bad)


def test_the_note_on_the_21x21_says_no_length_is_long_enough():
    d = _development(WRITTEN_21X21)
    said = no_length_text(d, 0.64, 60.0)
    # 0.7 / 0.64 = 1.094 of the face, 1 - 2 x 0.04 = 0.92 left by the clearance
    assert said.startswith("a longer light-load pattern is no lever here: at eps_vb 0.64 "
                           "the LTE would need one about 1.09 of the face long")
    assert "more than the 0.92 the toe and heel clearance leave" in said
    assert said.endswith("the length target stays")
    # the command's hook: the LTE missed, so no length trade before it
    assert length_trade(d, (1.23, 0.64)) == "; " + said


def test_no_length_note_where_a_pattern_fits_or_the_lte_holds():
    d = _development(WRITTEN_21X21)
    assert no_length_text(d, 0.83, 60.0) == ""  # the 13x41's ratio: a pattern fits
    assert no_length_text(d, 0.64, 95.0) == ""  # within the limit given
    held = _development(WRITTEN_21X21 | {"lte_peak_to_peak": [41.0, 59.0]})
    assert no_length_text(held, 0.64, 60.0) == ""
    # the 27x34's trade is said alone (eps_vb 1.17: the pattern fits)
    d27 = _development(WRITTEN_27X34)
    assert length_trade(d27, (1.36, 1.173)) == "; " + length_trade_text(
        d27, 1.173, FACE_CONTACT_RATIO_NOTE)
    # the 16x20 at Sigma 75 deg (eps_vb 0.71, LTE 55 / 84 urad written): 0.99 of the face
    fh = _development(WRITTEN_21X21 | {"lte_peak_to_peak": [55.2, 84.0]})
    assert "at eps_vb 0.71 the LTE would need one about 0.99 of the face" in no_length_text(
        fh, 0.71, 60.0)
