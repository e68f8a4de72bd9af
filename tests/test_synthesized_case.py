"""The Python API writes the case ``ltca synthesize`` writes, with its notes and the
contact-ratio remedies' record (:mod:`contact.optimize.synthesized_case`; issue 71,
branch api88: round 28 of docs/own_gear_set.md found ``contact.develop(...)
.written_case()`` without the ``[contact_ratio_remedies]`` table ``ltca run``'s next step
reads and without the command's cause-and-remedy and LTE notes).

The development is a stand-in around the real synthesis of the spiral bevel 15x28
(ε_vβ 0.91, below 1.25: the notes path and the record are exercised); the remedies'
syntheses, the written case's unloaded TE and the LTE analysis between the torques are
stand-ins too (measured numbers of docs/synthesis.md), so the test runs in seconds."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from development_stand_ins import checked, metrics

import contact
from contact.cli import main
from contact.optimize import development as dev
from contact.optimize import development_deflection, remedy_check
from contact.optimize.development import DevelopmentResult, DevelopmentTargets
from contact.optimize.remedy_check import RECORD_TABLE
from geometry.synthesis.case_synthesis import synthesize

ROOT = Path(__file__).resolve().parents[1]
FIFTEEN = ROOT / "benchmarks" / "data" / "unseen_designs" / "spiral_bevel_15x28_s110.toml"
#: the 15x28's remedy checks as measured (tests/test_development_remedy.py: unloaded TE
#: p-p [µrad], ease-off [µm], valid share [1]) and its written flank's
MEASURED = {"b2": (60.0, 95.0, 0.69), "beta_m": (173.0, 104.0, 0.79)}
WRITTEN = (90.0, 94.0, 0.7)


def _stand_ins(monkeypatch) -> list:
    """``develop`` replaced by a result around the real synthesis of the basic data it is
    given (drive LTE p-p 86/93 µrad, above the verdict's 60: the first lines and the
    deflection note are made), the remedies' checks by :data:`MEASURED`, the LTE analysis
    by a fixed one; returns the results made."""
    made: list = []

    def develop(basic, *, targets=None, progress=None, synthesis_progress=None,
                apply_remedy=False):
        case, report = synthesize(basic)
        t = targets or DevelopmentTargets()
        best = checked({"path_angle": -45.0, "te_level": 128.1},
                       metrics(lte_peak_to_peak=[86.0, 93.0]), t, 0.6)
        result = DevelopmentResult(basic, case, report, best, (best,), (91.8, 612.4),
                                   "given", {}, t, 1.0,
                                   coast=metrics(lte_peak_to_peak=[52.0, 78.0]),
                                   coast_torques=(91.8, 445.5))
        made.append(result)
        return result

    def check(basic, change):
        return remedy_check.ChangeCheck(change, *MEASURED[change.field], "", 0.5)

    monkeypatch.setattr(dev, "develop", develop)
    monkeypatch.setattr(remedy_check, "check_change", check)
    monkeypatch.setattr(remedy_check, "unloaded_te_pp", lambda case: WRITTEN)
    monkeypatch.setattr(remedy_check, "unrelieved_te_pp",
                        lambda basic, memo=None: (math.nan, math.nan))
    found = development_deflection.DeflectionLTE((91.8, 350.0, 612.4), (86.0, 90.0, 93.0),
                                                 (150.0, 400.0, 600.0), 60.0)
    monkeypatch.setattr(development_deflection, "analysed", lambda *a, **k: found)
    return made


def _body(text: str) -> str:
    """The written text but for the development's CPU times (each run's own)."""
    return "\n".join(line for line in text.splitlines()
                     if "seconds =" not in line and not line.startswith((
                         "bearing =", "height =", "relief =", "te =", "check =",
                         "coast =")))


def test_the_api_writes_and_says_what_ltca_synthesize_does(tmp_path, capsys, monkeypatch):
    """``contact.synthesize_case`` gives the text ``ltca synthesize`` writes and the lines
    it prints for the same development, equal (no tolerance: the same functions on the same
    numbers; the stand-in's CPU times alike). The case carries the remedies' record, and
    ``DevelopmentResult.written_case(noted=True)`` is that case; without ``noted`` the
    record is absent (the case as before)."""
    made = _stand_ins(monkeypatch)
    out = tmp_path / "case.toml"
    assert main(["synthesize", str(FIFTEEN), "--no-progress", "-o", str(out)]) == 0
    printed = capsys.readouterr().out.splitlines()
    written = out.read_text(encoding="utf-8")

    api = contact.synthesize_case(FIFTEEN, shown=FIFTEEN.as_posix())
    assert _body(api.text) == _body(written)
    assert api.lines(out) == printed
    assert RECORD_TABLE in api.case.extra
    assert RECORD_TABLE in written
    # the record's checks: the stand-ins' numbers
    checks = {c["field"]: c for c in api.case.extra[RECORD_TABLE]["change"]}
    assert checks["b2"]["unloaded_te_pp_urad"] == 60.0
    assert checks["beta_m"]["unloaded_te_pp_urad"] == 173.0
    # the first lines: the ratio, the LTE above the limit and the checked remedy
    assert printed[0].startswith("face contact ratio eps_vb 0.91 below 1.25: the developed "
                                 "LTE p-p drive 86/93 urad")
    assert printed[1].startswith("  checked remedy: gear face width b2 28 -> 36.5 mm")
    assert any(line.startswith("note: ") for line in api.notes)

    result = made[-1]
    assert api.development is result
    noted = result.written_case(noted=True)
    assert _body(noted.to_toml()) == _body(api.case.to_toml())
    assert RECORD_TABLE not in result.written_case().extra


def test_synthesize_case_refuses_a_bad_fe_level_and_a_remedy_without_development():
    """Bad input named before any work: ``fe_level`` with the levels, ``apply_remedy``
    without a development."""
    from geometry.core.errors import InputError

    with pytest.raises(InputError, match=r"--fe-level: must be one of .*got 'nope'"):
        contact.synthesize_case(FIFTEEN, fe_level="nope")
    with pytest.raises(InputError, match="cannot be combined with --no-development"):
        contact.synthesize_case(FIFTEEN, development=False, apply_remedy=True)


def test_no_development_gives_the_commands_case(tmp_path, capsys, monkeypatch):
    """``development=False`` is ``ltca synthesize --no-development``: the same text but
    for the remedies' checks' CPU times, and the same lines."""
    _stand_ins(monkeypatch)
    out = tmp_path / "plain.toml"
    assert main(["synthesize", str(FIFTEEN), "--no-development", "--no-progress",
                 "-o", str(out)]) == 0
    printed = capsys.readouterr().out.splitlines()
    api = contact.synthesize_case(FIFTEEN, development=False, shown=FIFTEEN.as_posix())
    assert _body(api.text) == _body(out.read_text(encoding="utf-8"))
    assert RECORD_TABLE in api.case.extra
    assert api.lines(out) == printed
    assert api.development is None


def test_progress_reaches_the_development(monkeypatch):
    """Round 30 (issue 71): a script of docs/api.md's example sat silent through its whole
    synthesis; ``progress=print`` (docs/api.md, the docstring) is the command's printing of
    the development's lines. The callable given is the one the development calls, and the
    default None leaves the development its logger (no line dropped)."""
    given = []

    class Stop(Exception):
        pass

    def develop(basic, *, targets=None, progress=None, synthesis_progress=None,
                apply_remedy=False):
        given.append(progress)
        raise Stop

    monkeypatch.setattr(dev, "develop", develop)
    lines: list[str] = []
    with pytest.raises(Stop):
        contact.synthesize_case(FIFTEEN, progress=lines.append)
    with pytest.raises(Stop):
        contact.synthesize_case(FIFTEEN)
    assert given == [lines.append, None]
