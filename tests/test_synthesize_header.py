"""The comment a case written by ``ltca synthesize`` starts with names the gear's process as
the case holds it (issue 71, round 26c, branch unseen87: the spiral bevel 17x23 whose
generated gear ``gear_process = "auto"`` kept read "ISO 23509 blank, Formate gear" in its
first line, its ``[gear] process = "Generate"``)."""

from __future__ import annotations

import tomllib
from pathlib import Path

from contact.cli import main
from contact.commands.synthesize import header_text

#: a basic file whose [synthesis] gear_process forces the generated gear
GENERATE = (Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"
            / "spiral_bevel_20x20_miter_generate.toml")


def test_the_header_names_the_gear_process():
    formate = header_text("a.toml", "Formate")
    generated = header_text("a.toml", "Generate")
    assert "ISO 23509 blank, Formate gear,\n" in formate
    assert "ISO 23509 blank, generated gear,\n" in generated
    assert "Formate" not in generated
    assert formate.startswith("# Written by `ltca synthesize a.toml`")
    assert formate.endswith("Do not edit by hand.\n") and formate.count("\n") == 2


def test_a_generated_gears_case_says_so_in_its_first_line(tmp_path):
    """Written without the development (a few seconds): the header's gear process is the
    one the written case's ``[gear] process`` holds, read back from the file itself."""
    out = tmp_path / "c.toml"
    assert main(["synthesize", str(GENERATE), "--no-development", "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert tomllib.loads(text)["gear"]["process"] == "Generate"
    first = text.splitlines()[0]
    assert first.endswith("ISO 23509 blank, generated gear,")
