"""``ltca synthesize`` says a coast design torque the basic file gives (issue 71, round 24:
the face-hobbed 14x39 by Method 3 with ``[rating] coast_design_torque = 200`` wrote it into
its case and printed no "coast design torque" line; only a coast capacity computed below
the design torque was printed)."""

from __future__ import annotations

from pathlib import Path

from contact.cli import main

BASIC = (Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"
         / "fh_spiral_bevel_14x39_m3_coast.toml")


def test_a_given_coast_design_torque_is_printed(tmp_path, capsys):
    out = tmp_path / "c.toml"
    assert main(["synthesize", str(BASIC), "--no-development", "-o", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    said = [x.strip() for x in lines if x.strip().startswith("coast design torque:")]
    # the basic file's value, once, with where it comes from
    assert said == ["coast design torque: 200 N m, given ([rating] coast_design_torque of "
                    "the basic file)"]
    assert "coast_design_torque = 200.0" in out.read_text(encoding="utf-8")


def test_the_given_coast_torque_reader_takes_finite_numbers_only():
    from types import SimpleNamespace

    from contact.optimize.written_notes import given_coast_torque

    assert given_coast_torque(SimpleNamespace(extra={"rating": {
        "coast_design_torque": 200}})) == 200.0
    for extra in ({}, {"rating": None}, {"rating": {"coast_design_torque": "x"}},
                  {"rating": {"coast_design_torque": float("nan")}}):
        assert given_coast_torque(SimpleNamespace(extra=extra)) is None
