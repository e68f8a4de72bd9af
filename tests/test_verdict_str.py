"""``print(contact.verdict(tree))`` reads as the command's verdict (issue 71, round 28).

Round 28's Python API user printed the verdict of a design and got the dataclass' repr
(about 3000 characters of ``Verdict(kind=..., findings=(Finding(...` on one line);
``str`` of a verdict is now its text lines, every finding and every reason not checked.
"""

from __future__ import annotations

from contact.study.verdicts import Finding, Verdict


def _verdict() -> Verdict:
    return Verdict(
        kind="analysis",
        findings=(Finding(severity="attention", check="edge_contact",
                          reason="at 97.1 N·m: the loaded pattern reaches the gear's toe"),),
        checks=("edge_contact", "lte", "root_stress"),
        unchecked=(("micropitting", "micropitting_safety NaN at every torque"),),
        notes=("root stress: FE coarse10 level",),
    )


def test_str_of_a_verdict_is_its_lines_as_the_command_prints_them():
    v = _verdict()
    text = str(v)
    # the same text as lines() joined (the full form, every reason on its own line), and
    # checked line by line against the command's layout written out here by hand
    assert text == "\n".join(v.lines())
    assert text.splitlines() == [
        "VERDICT (analysis): ATTENTION, 1 finding",
        "  attention: at 97.1 N·m: the loaded pattern reaches the gear's toe",
        "  note: root stress: FE coarse10 level",
        "  not checked: micropitting (micropitting_safety NaN at every torque)",
    ]
    # repr stays the dataclass' (a script that needs the fields keeps them)
    assert repr(v).startswith("Verdict(kind='analysis', findings=(Finding(")


def test_str_of_a_verdict_without_findings_says_how_many_checks_passed():
    v = Verdict(kind="duty cycle", findings=(), checks=("damage", "safety"), unchecked=(),
                notes=())
    assert str(v) == "VERDICT (duty cycle): PASS, no finding in 2 checks"
