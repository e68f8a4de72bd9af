"""``ltca synthesize``'s note on a gear face wider than bevel-gear practice accepts
(:func:`contact.load_capacity.iso10300.face_contact.face_width_text`; round 26d: an FM
11x35 at Sigma 105 deg took b2 60 mm without a word)."""
from __future__ import annotations

from pathlib import Path

import pytest

from contact.load_capacity.iso10300.face_contact import face_width_text
from geometry.iso23509.blank import blank_geometry
from geometry.synthesis.basic_design import load_basic

UNSEEN = Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"


def test_face_width_limits_by_hand():
    # R_e2 90 mm: R_e2/3 = 30 mm; m_et 4 mm: 10 m_et = 40 mm. The limits are the
    # standard's numbers, compared exactly at their boundaries (no arithmetic between).
    assert face_width_text(30.0, 90.0, 4.0) is None
    said = face_width_text(31.0, 90.0, 4.0)
    assert said is not None and "above R_e2/3 = 30.0 mm" in said and "m_et =" not in said
    # the usual largest is the smaller of 0.3 R_e2 = 27 mm and 10 m_et = 40 mm
    assert "here 27.0 mm" in said
    both = face_width_text(41.0, 90.0, 4.0)
    assert "R_e2/3 = 30.0 mm and 10 m_et = 40.0 mm" in both
    # 10 m_et alone: a coarse module's pair whose cone is long
    alone = face_width_text(41.0, 150.0, 4.0)
    assert alone is not None and "R_e2/3" not in alone and "10 m_et = 40.0 mm" in alone


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf")])
def test_face_width_text_no_note_on_bad_numbers(bad):
    assert face_width_text(bad, 90.0, 4.0) is None
    assert face_width_text(31.0, bad, 4.0) is None


def test_face_width_note_on_a_remedied_unseen_design():
    # the hypoid 16x28 at Sigma 115 deg widened by its own eps_vb remedy to b2 44.9 mm,
    # against R_e2/3 of its blank (34.4 mm to the printed 0.1 mm); its unwidened file is not
    # noted (b2 within both limits)
    wide = load_basic(UNSEEN / "hypoid_16x28_s115_a20_right_b44p9.toml").design
    blank = blank_geometry(wide)
    said = face_width_text(wide.b2, blank.gear.Re, blank.met2)
    assert said is not None and "b2 44.9 mm is above R_e2/3 = 34.4 mm" in said
    plain = load_basic(UNSEEN / "hypoid_16x28_s115_a20_right.toml").design
    blank = blank_geometry(plain)
    assert face_width_text(plain.b2, blank.gear.Re, blank.met2) is None
