"""The checked contact-ratio remedy applied to the basic data (``ltca synthesize
--apply-remedy``, ``develop(basic, apply_remedy=True)``; contact.optimize.development_remedy,
issue 71: three designs of ε_vβ ≤ 1.00 reach no LTE p-p ≤ 60 µrad at every torque with
any lever of the development).

Fast: the developments are stand-ins (a ``run`` that returns a development result scored
by tests/development_stand_ins), the remedies' syntheses stand-in checks carrying the
numbers measured on the spiral bevel 15×28 at Σ 110° (docs/synthesis.md, "The face
contact ratio's remedies checked": written drive flank unloaded TE p-p 90 µrad, ease-off
94 µm; b2 36.5 mm 60 µrad / 95 µm, β_m 43.9° 173 µrad / 104 µm); the basic data, their
contact ratios and the remedies' values are the real file's."""

from __future__ import annotations

import dataclasses
import json
import math
import types
from pathlib import Path

import numpy as np
import pytest
from development_stand_ins import checked, metrics

from contact.cli import build_parser, main
from contact.optimize import remedy_check
from contact.optimize.development import DevelopmentResult, DevelopmentTargets
from contact.optimize.development_remedy import (
    REMEDY_TABLE,
    applied_table,
    developed_with_remedy,
    ratio_changes,
    remedied_basic,
)
from geometry.core.errors import InputError
from geometry.synthesis.basic_design import load_basic

ROOT = Path(__file__).resolve().parent.parent
UNSEEN = ROOT / "benchmarks" / "data" / "unseen_designs"
FIFTEEN = UNSEEN / "spiral_bevel_15x28_s110.toml"

#: the 15x28's checks as measured (docs/synthesis.md, notes71): (unloaded TE p-p [µrad],
#: ease-off [µm], valid share [1]) per remedy field
MEASURED = {"b2": (60.0, 95.0, 0.69), "beta_m": (173.0, 104.0, 0.79)}
#: its written drive flank's unloaded TE p-p [µrad] and ease-off [µm]
WRITTEN = (90.0, 94.0, 0.7)


def _result(basic, lte, coast_lte=(52.0, 78.0)):
    """A development result of ``basic`` whose chosen design reads ``lte`` (light, design)
    [µrad] at 91.8 / 612.4 N·m (the 15x28's torques) and its coast flank ``coast_lte``."""
    targets = DevelopmentTargets()
    # its written drive bearing's path and TE parabola (docs/synthesis.md, evb71: te_level
    # 128.1 urad, matched to the load on purpose)
    best = checked({"path_angle": -45.0, "te_level": 128.1},
                   metrics(lte_peak_to_peak=list(lte)), targets, 0.6)
    case = types.SimpleNamespace(gear=types.SimpleNamespace(process="Formate"))
    coast = metrics(lte_peak_to_peak=list(coast_lte))
    return DevelopmentResult(basic, case, None, best, (best,), (91.8, 612.4), "given", {},
                             targets, 1.0, coast=coast, coast_torques=(91.8, 445.5))


def _stand_in_checks(monkeypatch, measured, written=WRITTEN):
    """The remedies' syntheses and the written case's unloaded TE replaced by
    ``measured`` (field -> (ute, span, valid) or a failure message); returns the designs
    each check was given."""
    seen: list = []

    def check(basic, change):
        seen.append(change.field)
        m = measured[change.field]
        if isinstance(m, str):
            return remedy_check.ChangeCheck(change, math.nan, math.nan, 0.0, m, 0.5)
        return remedy_check.ChangeCheck(change, *m, "", 0.5)

    monkeypatch.setattr(remedy_check, "check_change", check)
    monkeypatch.setattr(remedy_check, "unloaded_te_pp", lambda case: written)
    # the unloaded TE without the relief (one more synthesis where the written one exceeds
    # the limit): not measured here
    monkeypatch.setattr(remedy_check, "unrelieved_te_pp",
                        lambda basic, memo=None: (math.nan, math.nan))
    return seen


def test_apply_remedy_applies_the_checked_remedy_and_records_it(monkeypatch):
    """The 15x28 (ε_vβ 0.91): the design as given developed first, both remedies checked
    at its written prescriptions, the best that passed (b2 36.5 mm: 60 against 173 µrad)
    applied to the basic data and that design developed; the result carries the change,
    the contact ratios before and after (ε_vβ 0.91 -> 1.25 on the real blank) and the
    design as given's LTE, the remedied basic data say it in their source (the case's
    first sentence) and the case's table records it, TOML-safe."""
    basic = load_basic(FIFTEEN)
    seen = _stand_in_checks(monkeypatch, MEASURED)
    developed: list = []

    def run(b):
        developed.append(b)
        given = len(developed) == 1
        return _result(b, (86.0, 93.0) if given else (20.0, 45.0))

    said: list[str] = []
    result = developed_with_remedy(run, basic, said.append)
    assert seen == ["b2", "beta_m"]  # each remedy the note offers checked once
    assert [b.design.b2 for b in developed] == [28.0, 36.5]
    assert developed[1].design.beta_m == basic.design.beta_m
    applied = result.remedy
    assert applied.check.change.field == "b2" and applied.check.ute == 60.0
    assert applied.before == 28.0 and applied.basic is developed[1]
    assert applied.ratios_before[1] == pytest.approx(0.91, abs=0.005)
    assert 1.25 <= applied.ratios_after[1] < 1.26
    assert applied.given_lte == ("drive 86/93 urad at 91.8/612.4 N m, coast 52/78 urad at "
                                 "91.8/445.5 N m")
    assert applied.given_worst == 93.0
    assert result.best.metrics["lte_peak_to_peak"][1] == 45.0  # the remedied development
    assert developed[1].source == (basic.source.rstrip(".") + "; remedied by ltca synthesize "
                                   "--apply-remedy: gear face width b2 28 -> 36.5 mm, the "
                                   "contact-ratio remedy its note checked (contact.optimize."
                                   "development_remedy; the basic data otherwise as given)")
    assert any("b2 28 -> 36.5 mm applied" in line for line in said)
    table = json.loads(json.dumps(applied_table(applied)))
    assert (table["field"], table["before"], table["after"]) == ("b2", 28.0, 36.5)
    assert table["eps_vb_before"] == pytest.approx(0.912, abs=1e-3)
    assert [c["field"] for c in table["checks"]["change"]] == ["b2", "beta_m"]
    assert table["checks"]["unloaded_te_pp_urad"] == 90.0
    assert REMEDY_TABLE == "applied_remedy"


def test_apply_remedy_takes_the_spiral_angle_where_the_face_width_is_refused(monkeypatch):
    """A remedy the check refuses is never applied: the face width's synthesis failing,
    the spiral angle (β_m 43.9°, in radians in the design data) is the one applied."""
    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, {"b2": "design.b2: the toe's tooth too thin",
                                   "beta_m": MEASURED["beta_m"]})
    developed: list = []
    result = developed_with_remedy(lambda b: developed.append(b) or _result(b, (86, 93)),
                                   basic)
    assert result.remedy.check.change.field == "beta_m"
    assert math.degrees(developed[1].design.beta_m) == pytest.approx(43.9, abs=1e-9)
    assert developed[1].design.b2 == 28.0
    assert "; remedied by ltca synthesize --apply-remedy: mean spiral angle beta_m 35 -> " \
        "43.9 deg, " in developed[1].source


def test_apply_remedy_refuses_where_no_remedy_passed(monkeypatch):
    """Every remedy refused by its check: an InputError that says so with each reason,
    and no second development (the design as given is not returned as if remedied)."""
    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, {"b2": "no solution at M", "beta_m": "no solution at M"})
    developed: list = []
    with pytest.raises(InputError, match=r"no contact-ratio remedy passed its check.*"
                                         r"gear face width b2 of 36.5 mm.*no solution"):
        developed_with_remedy(lambda b: developed.append(b) or _result(b, (86, 93)), basic)
    assert len(developed) == 1


def test_apply_remedy_refuses_a_design_without_a_low_ratio_before_any_work(monkeypatch):
    """The 15x28 at its remedied b2 36.5 mm (ε_vβ 1.25, ε_vα 1.19): nothing to remedy,
    said before any development or check."""
    remedied = remedied_basic(load_basic(FIFTEEN), ratio_changes(load_basic(FIFTEEN).design)[0])
    assert ratio_changes(remedied.design) == []

    def run(b):
        raise AssertionError("developed")

    with pytest.raises(InputError, match=r"no contact ratio of this design is below its "
                                         r"limit \(eps_va 1.19, eps_vb 1.25"):
        developed_with_remedy(run, remedied)


def test_first_lines_say_the_ratio_its_lte_and_the_checked_remedy(monkeypatch):
    """``ltca synthesize``'s first lines without the flag: ε_vβ, the developed LTE, the
    limit and the checked remedy with its contact ratios and check (the unloaded TE named
    instead where it is what the LTE is: remedy_check.lte_diagnosis); with it, what
    changed and both designs' LTE; nothing where the LTE keeps the limit."""
    from contact.commands.synthesize import first_lines
    from contact.optimize.development_remedy import checked_record

    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, MEASURED)
    given = _result(basic, (86.0, 93.0))
    record = checked_record(basic, basic.design, WRITTEN[:2], 60.0)
    lines = first_lines(basic, given, record, "x.toml")
    assert lines[0] == ("face contact ratio eps_vb 0.91 below 1.25: the developed LTE p-p "
                        "drive 86/93 urad at 91.8/612.4 N m, coast 52/78 urad at "
                        "91.8/445.5 N m (light/design), above the verdict's 60 urad")
    assert lines[1].startswith("  checked remedy: gear face width b2 28 -> 36.5 mm: eps_vb "
                               "0.91 -> 1.25, eps_va 1.19 -> 1.19, unloaded TE p-p 60 urad "
                               "at the written prescriptions (the written case's 90)")
    assert "ltca synthesize x.toml --apply-remedy" in lines[1]
    # where the written unloaded TE is what the LTE is (the 8x35 at k_d 2.16 of round 15:
    # 609 urad, LTE 605/600 urad at a te_level of 10), no ratio remedy is offered first —
    # where no check takes that unloaded TE within the limit (b2: 590 urad)
    loud = _result(basic, (605.0, 600.0))
    loud.best.values["te_level"] = 10.0
    _stand_in_checks(monkeypatch, {"b2": (590.0, 850.0, 0.69),
                                   "beta_m": (1300.0, 104.0, 0.79)})
    ute = checked_record(basic, basic.design, (609.0, 859.0), 60.0)
    lines = first_lines(basic, loud, ute, "x.toml")
    assert lines[1] == ("  the drive LTE is the written flank's unloaded TE, not the contact "
                        "ratio's (the note below): no contact-ratio remedy is the lever")
    # a check that takes it within the limit (b2: 60 urad at the same prescriptions, as the
    # spiral bevel 21x21 of round 21, 97 -> 51 urad) is offered, not contradicted
    _stand_in_checks(monkeypatch, MEASURED)
    ute = checked_record(basic, basic.design, (609.0, 859.0), 60.0)
    lines = first_lines(basic, loud, ute, "x.toml")
    assert lines[1].startswith("  checked remedy: gear face width b2 28 -> 36.5 mm: eps_vb "
                               "0.91 -> 1.25, eps_va 1.19 -> 1.19, unloaded TE p-p 60 urad "
                               "at the written prescriptions (the written case's 609)")
    assert first_lines(basic, _result(basic, (30.0, 50.0), (40.0, 55.0)), record,
                       "x.toml") == []
    applied = developed_with_remedy(
        lambda b: _result(b, (86.0, 93.0) if b is basic else (20.0, 45.0), (30.0, 48.0)),
        basic)
    lines = first_lines(applied.remedy.basic, applied, None, "x.toml")
    assert lines[0].startswith("applied remedy (--apply-remedy): gear face width b2 28 -> "
                               "36.5 mm: eps_vb 0.91 -> 1.25")
    assert "drive 86/93 urad" in lines[1] and "above the verdict's 60 urad; not written" \
        in lines[1]
    assert "drive 20/45 urad" in lines[2] and "within the verdict's 60 urad" in lines[2]


def test_apply_remedy_argument(tmp_path, capsys):
    """``--apply-remedy`` (default off: the user's basic data as given); refused with
    ``--no-development`` before any work, and on a design without a low contact ratio
    before the development — neither writes a case."""
    parser = build_parser()
    assert parser.parse_args(["synthesize", "x.toml", "--apply-remedy"]).apply_remedy is True
    assert parser.parse_args(["synthesize", "x.toml"]).apply_remedy is False
    out = tmp_path / "case.toml"
    assert main(["synthesize", str(FIFTEEN), "--apply-remedy", "--no-development",
                 "--no-progress", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--apply-remedy" in err and "--no-development" in err
    assert not out.exists()
    wide = tmp_path / "wide.toml"
    wide.write_text(FIFTEEN.read_text(encoding="utf-8").replace("b2 = 28.0", "b2 = 36.5"),
                    encoding="utf-8")
    assert main(["synthesize", str(wide), "--apply-remedy", "--no-progress", "-o",
                 str(out)]) == 2
    assert "no contact-ratio remedy to apply" in capsys.readouterr().err
    assert not out.exists()


# --- the next checked remedy (contact.optimize.development_remedy_next) -------------------

#: the 15x28's first remedy developed (b2 36.5 mm; measured 2026-11-27, branch
#: remedynext80, and the same in session 19): drive LTE p-p 19.8 / 45.1 urad at its torques
#: and 62.4 urad between them (ltca run's lte_range), its check's record
FIRST_RANGE = ((123.6, 240.4, 298.8, 357.2, 590.7, 824.3),
               (19.8, 32.2, 47.6, 62.4, 59.4, 45.1))
#: the hypoid 15x31 at a = 0.056 d_e2 (benchmarks/data/unseen_designs, ε_vβ 1.00), measured
#: 2026-11-27 (branch remedynext80): its checks (unloaded TE p-p [µrad] at the written
#: prescriptions; the written case's 40), its first remedy's development (b2 32.6 mm:
#: 44.8 / 59.0 urad at 107.3 / 716 N m, 63.3 urad at 513.1 N m between, ltca run's
#: lte_range) and its next's (beta_m 46.3 deg, ε_vα 0.98: 41.5 / 58.1 urad at 77.2 / 514.8
#: N m, 49.0 / 56.3 urad at 223.1 / 368.9 N m between)
HYPOID = UNSEEN / "hypoid_15x31_a10.toml"
HYPOID_CHECKS = {"b2": (32.0, 60.0, 0.7), "beta_m": (60.0, 70.0, 0.7)}
HYPOID_FIRST = ((107.3, 310.2, 360.9, 411.6, 513.1, 716.0),
                (44.8, 53.3, 59.1, 61.6, 63.3, 59.0))


def _judged(result, found):
    """``result`` whose check recorded its chosen design's LTE over ltca run's torques
    (``found``: torques [N m], LTE p-p [urad]), as the development's ``lte_range``."""
    t, y = found
    i = max(range(len(y)), key=lambda k: y[k])
    return dataclasses.replace(result, torque=(t[0], t[-1]), lte_range={
        "torques": t, "lte": y, "peak": y[i], "at": t[i], "values": dict(result.best.values)})


def _next_run(basic, developments):
    """A stand-in development per basic design: the design as given, then each remedy by
    its field (``developments``: field -> result maker or an exception); returns (run, the
    basic data each development was given)."""
    given: list = []

    def run(b):
        given.append(b)
        if len(given) == 1:
            return _result(b, (86.0, 93.0))
        field = "b2" if b.design.b2 != basic.design.b2 else "beta_m"
        made = developments[field]
        if isinstance(made, Exception):
            raise made
        return made(b)

    return run, given


def test_next_remedy_developed_where_the_first_misses_the_lte_between_its_torques(
        monkeypatch):
    """The hypoid 15x31: its first remedy (b2 32.6 mm) developed keeps 44.8 / 59.0 urad at
    its torques and reaches 63.3 urad between them; the next checked remedy (beta_m 46.3
    deg, ranked after: ε_vα 0.98) is developed, its range judged by range_lte on the
    stand-in analysis (its check left no record) and kept, its largest LTE over the range
    58.1 urad within 60 and no target the first met lost; synthesize's first lines say
    both remedies with their numbers and why the one written was kept; the table records
    both."""
    from development_stand_ins import seen_designs

    from contact.commands.synthesize import first_lines
    from contact.optimize import development_remedy_next as nxt

    basic = load_basic(HYPOID)
    _stand_in_checks(monkeypatch, HYPOID_CHECKS, (40.0, 60.0, 0.7))

    def law(case, torques, misalignment, **kw):  # the beta_m design's LTE between
        return {"lte_peak_to_peak": np.asarray([{223.1: 49.0, 368.9: 56.3}[round(t, 1)]
                                                for t in torques])}, {}

    seen, fake = seen_designs(law)
    monkeypatch.setattr("contact.optimize.development_evaluate.analyse_design", fake)

    def spiral(b):
        r = _result(b, (41.5, 58.1))
        return dataclasses.replace(r, torque=(77.2, 514.8),
                                   best=dataclasses.replace(r.best, case={"beta_m": 46.3}))

    run, given = _next_run(basic, {"b2": lambda b: _judged(_result(b, (44.8, 59.0)),
                                                           HYPOID_FIRST),
                                   "beta_m": spiral})
    said: list[str] = []
    result = developed_with_remedy(run, basic, said.append)
    assert len(given) == 3  # the design as given, b2, beta_m: one more development
    assert [b.design.b2 for b in given] == [27.0, 32.6, 27.0]
    assert math.degrees(given[2].design.beta_m) == pytest.approx(46.3, abs=1e-9)
    applied = result.remedy
    assert applied.check.change.field == "beta_m" and applied.basic is given[2]
    assert result.best.metrics["lte_peak_to_peak"][1] == 58.1
    # the b2 design's range was its check's record; the beta_m design analysed once at
    # the two torques between (77.2, 223.1, 368.9, 514.8 N m), no crossing to bisect
    assert seen == [{"beta_m": 46.3}]
    first, second = applied.developed
    assert (first.peak, first.at, second.peak, second.at) == (63.3, 513.1, 58.1, 514.8)
    assert first.why.startswith("the next, mean spiral angle beta_m 40 -> 46.3 deg, kept")
    assert second.why == ""
    assert applied.kept_why == (
        "kept mean spiral angle beta_m 40 -> 46.3 deg: its drive LTE p-p over ltca run's "
        "torques 58.1 urad at 514.8 N m, within 60 urad, where gear face width b2 27 -> "
        "32.6 mm's was 63.3 urad at 513.1 N m; no target the first met lost (the pattern's "
        "length aside)")
    assert any("above 60 urad between its torques; the next checked remedy, mean spiral "
               "angle beta_m 40 -> 46.3 deg, developed" in line for line in said)
    lines = first_lines(applied.basic, result, None, "x.toml")
    assert lines[0].startswith("applied remedy (--apply-remedy): mean spiral angle beta_m "
                               "40 -> 46.3 deg")
    assert lines[3] == (
        "  remedies developed in the check's order: gear face width b2 27 -> 32.6 mm: drive "
        "LTE p-p 44.8/59.0 urad at 107.3/716 N m, 63.3 urad at 513.1 N m over ltca run's "
        "torques (above 60), 1 s CPU; mean spiral angle beta_m 40 -> 46.3 deg: drive LTE p-p "
        "41.5/58.1 urad at 77.2/514.8 N m, 58.1 urad at 514.8 N m over ltca run's torques "
        "(within 60), 1 s CPU")
    assert lines[4] == "  " + applied.kept_why
    table = json.loads(json.dumps(applied_table(applied)))
    assert [(r["field"], r["range_peak_urad"]) for r in table["developed"]] == [
        ("b2", 63.3), ("beta_m", 58.1)]
    assert table["kept_why"] == applied.kept_why
    assert nxt.NEXT_REMEDIES == 1


def test_next_remedy_not_kept_where_it_scores_no_better(monkeypatch):
    """The 15x28: the next remedy's development (beta_m 43.9 deg, measured: 40.8 / 71.7
    urad at 76.4 / 509.7 N m) reaches a higher LTE over the range than the first's 62.4
    urad: the first is kept and written, the reason said in numbers; its development
    failing instead, the first is kept too, the failure said."""
    from contact.commands.synthesize import first_lines

    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, MEASURED)
    first = lambda b: _judged(_result(b, (19.8, 45.1)), FIRST_RANGE)  # noqa: E731
    worse = ((76.4, 509.7), (40.8, 71.7))
    run, given = _next_run(basic, {
        "b2": first, "beta_m": lambda b: _judged(_result(b, (40.8, 71.7)), worse)})
    result = developed_with_remedy(run, basic)
    assert len(given) == 3 and result.remedy.check.change.field == "b2"
    assert result.remedy.basic is given[1]
    assert result.best.metrics["lte_peak_to_peak"][1] == 45.1
    assert result.remedy.kept_why == (
        "kept gear face width b2 28 -> 36.5 mm (its drive LTE p-p over ltca run's torques "
        "62.4 urad at 357.2 N m, above 60 urad): the next, mean spiral angle beta_m 35 -> "
        "43.9 deg (71.7 urad at 509.7 N m), not kept: it scores no better (its drive LTE "
        "p-p over the range 71.7 urad against 62.4)")
    lines = first_lines(result.remedy.basic, result, None, "x.toml")
    assert lines[0].startswith("applied remedy (--apply-remedy): gear face width b2 28 -> "
                               "36.5 mm") and lines[4] == "  " + result.remedy.kept_why

    run, given = _next_run(basic, {"b2": first,
                                   "beta_m": InputError("design.beta_m: no solution")})
    result = developed_with_remedy(run, basic)
    assert len(given) == 3 and result.remedy.check.change.field == "b2"
    assert result.remedy.kept_why.endswith("not kept: its development failed "
                                           "(design.beta_m: no solution)")


def test_next_remedy_within_the_limit_not_kept_where_it_loses_a_met_target(monkeypatch):
    """The next remedy keeps the limit over the range (53 urad) but its edge share at the
    design torque misses the target the first met (8 % against 4 %): not kept, the
    check's keep rule (development_keep.kept_why) says which target."""
    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, MEASURED)

    def edged(b):
        r = _judged(_result(b, (34.0, 53.0)), ((89.4, 509.7), (34.0, 53.0)))
        m = metrics(lte_peak_to_peak=[34.0, 53.0], edge_load_share=[0.0, 0.08])
        return dataclasses.replace(r, best=checked(dict(r.best.values), m,
                                                   DevelopmentTargets(), 0.6))

    run, given = _next_run(basic, {
        "b2": lambda b: _judged(_result(b, (19.8, 45.1)), FIRST_RANGE), "beta_m": edged})
    result = developed_with_remedy(run, basic)
    assert len(given) == 3 and result.remedy.check.change.field == "b2"
    assert result.remedy.kept_why.endswith("not kept: it misses edge")


def test_no_next_remedy_where_the_first_keeps_the_limit_between_its_torques(monkeypatch):
    """The first remedy's development keeps 60 urad over ltca run's torques (the FH 9x37
    at Sigma 85 deg's b2 30.3 mm, every criterion met): nothing more is developed, the
    first lines and the table are those of one remedy."""
    from contact.commands.synthesize import first_lines

    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, MEASURED)
    run, given = _next_run(basic, {"b2": lambda b: _judged(_result(b, (19.8, 45.1)),
                                                           ((123.6, 824.3), (19.8, 45.1))),
                                   "beta_m": InputError("never developed")})
    result = developed_with_remedy(run, basic)
    assert len(given) == 2 and result.remedy.check.change.field == "b2"
    assert len(result.remedy.developed) == 1 and result.remedy.kept_why == ""
    assert len(first_lines(result.remedy.basic, result, None, "x.toml")) == 3
    assert "developed" not in applied_table(result.remedy)


# --- remedies that are no remedy (issue 71, round 22, branch remedy82) ---

SEVEN = UNSEEN / "industrial_hypoid_7x51_m9.toml"
TWENTY_TWO = UNSEEN / "industrial_spiral_bevel_22x33_m8p5.toml"
#: the 7x51's checks as round 22's note printed them (k_d 2.07: 53 urad, 182 um; alpha_dD
#: 20.5 deg: 58 urad, 152 um) and its written drive flank's unloaded TE p-p 52 urad
SEVEN_MEASURED = {"k_d": (53.0, 182.0, 0.7), "alpha_dD": (58.0, 152.0, 0.7)}
SEVEN_WRITTEN = (52.0, 160.0, 0.7)


def _seven_result(basic, lte=(19.0, 14.0), coast_lte=(23.0, 22.0)):
    """The 7x51's development as round 22 measured it: drive 19/14, coast 23/22 urad
    (light/design), every one within the verdict's 60 urad."""
    return _result(basic, lte, coast_lte)


def test_apply_remedy_never_applies_a_change_no_better_than_the_written_design(monkeypatch):
    """The 7x51 (eps_va 0.97, its LTE within 60 urad): both changes check no lower than the
    written 52 urad (53, 58), so --apply-remedy applies neither: an InputError naming each
    as no remedy, after the one development of the design as given (no second one)."""
    from contact.optimize.development_remedy import lte_within

    basic = load_basic(SEVEN)
    seen = _stand_in_checks(monkeypatch, SEVEN_MEASURED, SEVEN_WRITTEN)
    developed: list = []
    with pytest.raises(InputError, match=r"no contact-ratio remedy passed its check.*\(a depth "
                                         r"factor k_d of 2\.07.*: not a remedy here: unloaded "
                                         r"TE p-p 53 urad, no lower than the written case's "
                                         r"52.*alpha_dD of 20\.5 deg.*58 urad"):
        developed_with_remedy(lambda b: developed.append(b) or _seven_result(b), basic)
    assert len(developed) == 1 and seen == ["k_d", "alpha_dD"]
    # the rule's input: the worst of drive and coast, light and design, against the limit
    assert lte_within(_seven_result(basic), 60.0)
    assert not lte_within(_seven_result(basic, coast_lte=(23.0, 61.0)), 60.0)
    assert not lte_within(None, 60.0)


def test_apply_remedy_applies_it_as_a_trial_where_the_written_lte_misses(monkeypatch):
    """The same checks where the written LTE exceeds 60 urad (86/93): the change that
    checks no lower is still applied, the trial the note calls it (the 15x28's beta_m
    43.9 deg checked 173 against 90 urad and developed 34/53 against 90/103): k_d 2.07,
    the lower of the two (53 against 58 urad)."""
    basic = load_basic(SEVEN)
    _stand_in_checks(monkeypatch, SEVEN_MEASURED, SEVEN_WRITTEN)
    developed: list = []

    def run(b):
        developed.append(b)
        return _seven_result(b, (86.0, 93.0) if len(developed) == 1 else (20.0, 45.0))

    result = developed_with_remedy(run, basic)
    assert result.remedy.check.change.field == "k_d" and developed[1].design.k_d == 2.07
    assert result.remedy.record.lte_met is False


def test_apply_remedy_refuses_a_ratio_at_its_target_before_any_work(monkeypatch):
    """The 22x33 (eps_vb 1.247, within 0.01 of 1.25; eps_va 1.23): no change to apply,
    said before any development or check (round 22's note offered b2 48 -> 48.1 mm)."""
    seen = _stand_in_checks(monkeypatch, {})

    def run(b):
        raise AssertionError("developed")

    with pytest.raises(InputError, match=r"no contact ratio of this design is below its "
                                         r"limit \(eps_va 1.23, eps_vb 1.25; limits 1 / 1.25, "
                                         r"AGMA 2005-D03; one within 0.01 below it is at it\)"):
        developed_with_remedy(run, load_basic(TWENTY_TWO))
    assert seen == []


# --- a remedy that gives up load for an LTE the design has (issue 71, round 34) ---

FIVE = UNSEEN / "hypoid_5x48_a36_m1.toml"
#: the 5x48's checks as round 34's note printed them (alpha_dD 16.3 deg: 70 urad, 89 um;
#: k_d 2.26: 71 urad, 129 um) and its written drive flank's unloaded TE p-p 73 urad
FIVE_MEASURED = {"alpha_dD": (70.0, 89.0, 0.7), "k_d": (71.0, 129.0, 0.7)}
FIVE_WRITTEN = (73.0, 89.0, 0.7)


def _five_result(basic, lte, design_torque):
    """A development of the 5x48 whose drive reads ``lte`` (light, design) [µrad] at
    0.15 / 1 x ``design_torque`` [N·m] (its coast 9/13 urad, as round 34 measured)."""
    r = _result(basic, lte, (9.0, 13.0))
    return dataclasses.replace(r, torque=(round(0.15 * design_torque, 1), design_torque))


def test_apply_remedy_refuses_a_remedy_that_gives_up_the_design_torque(monkeypatch):
    """The FM hypoid 5x48 (eps_va 0.90; its LTE p-p 35/29 urad, within 60): round 34's
    --apply-remedy applied alpha_dD 16.3 deg (checked 70 against the written 73 urad) and
    wrote the remedied design at 81.7 N m, 0.40 of the design as given's 206.7, whose
    `ltca run` FAILed on scuffing. A remedy is offered for the LTE; where the design as
    given keeps it, a remedied design torque below the given one is no remedy: an
    InputError naming both torques (the numbers the developments gave, exact) after the
    two developments; nothing returned as remedied."""
    basic = load_basic(FIVE)
    assert sorted(c.field for c in ratio_changes(basic.design)) == ["alpha_dD", "k_d"]
    _stand_in_checks(monkeypatch, FIVE_MEASURED, FIVE_WRITTEN)
    developed: list = []

    def run(b):
        developed.append(b)
        given = len(developed) == 1
        return _five_result(b, (35.0, 29.0) if given else (26.0, 28.0),
                            206.7 if given else 81.7)

    with pytest.raises(InputError, match=r"alpha_dD 22\.5 -> 16\.3 deg developed: its "
                                         r"design torque 81\.7 N m is below the design as "
                                         r"given's 206\.7 N m \(0\.40 of it\), whose LTE p-p "
                                         r"is within the verdict's limit already \(drive "
                                         r"35/29 urad at 31/206\.7 N m.*nothing written"):
        developed_with_remedy(run, basic)
    assert len(developed) == 2  # the remedied design was developed, then refused
    from contact.optimize.development_remedy import torque_given_up

    # the rule alone: the LTE not met (a trial, whatever its torque), an equal torque, or
    # a higher one are no refusal
    given = _five_result(basic, (35.0, 29.0), 206.7)
    assert torque_given_up(given, _five_result(basic, (26.0, 28.0), 81.7), False) == ""
    assert torque_given_up(given, _five_result(basic, (26.0, 28.0), 206.7), True) == ""
    assert torque_given_up(given, _five_result(basic, (26.0, 28.0), 206.74), True) == ""
    assert torque_given_up(given, _five_result(basic, (26.0, 28.0), 206.6), True) != ""


def _targets(result, met):
    """``result`` whose chosen drive design met every target (``met``) or missed one."""
    full = (0.0 if met else 5.0, {} if met else {"length": 0.05}, met)
    return dataclasses.replace(result, best=dataclasses.replace(result.best, full=full))


def test_apply_remedy_keeps_a_lower_torque_that_buys_the_drive_targets(monkeypatch):
    """Round 35 of issue 71: the FM hypoid 12x31 at a = 0.20 d_e2 (eps_vb 1.08; its LTE
    27/34 urad, within 60) missed the pattern length 0.65 and centre v 0.64 and was not
    tolerant; its note's b2 32 -> 36 mm, applied, met every drive target (tolerant) at
    643.8 N m, 0.95 of the design as given's 677.1, and --apply-remedy refused it as
    giving up load "for an LTE the design has". Where the remedied design meets every
    drive target the design as given misses, the torque buys those: applied, no refusal.
    Where the design as given met them (the 5x48, the test above) or the remedy misses
    one too, the refusal stands."""
    from contact.optimize.development_remedy import torque_given_up

    basic = load_basic(FIVE)
    given = _five_result(basic, (27.0, 34.0), 677.1)
    lower = _five_result(basic, (26.0, 39.0), 643.8)
    assert torque_given_up(_targets(given, False), _targets(lower, True), True) == ""
    from contact.optimize.development_remedy import targets_bought

    assert targets_bought(_targets(given, False), _targets(lower, True))
    for g, r in ((True, True), (False, False), (True, False)):
        assert not targets_bought(_targets(given, g), _targets(lower, r))
        assert "is below the design as given's 677.1 N m (0.95 of it)" in torque_given_up(
            _targets(given, g), _targets(lower, r), True)

    # through developed_with_remedy: the remedied design (it buys the targets) returned
    _stand_in_checks(monkeypatch, FIVE_MEASURED, FIVE_WRITTEN)
    developed: list = []

    def run(b):
        developed.append(b)
        first = len(developed) == 1
        return _targets(_five_result(b, (27.0, 34.0) if first else (26.0, 39.0),
                                     677.1 if first else 643.8), not first)

    result = developed_with_remedy(run, basic)
    assert len(developed) == 2 and result.torque[1] == 643.8
    assert result.remedy.check.change.field == "alpha_dD"
    # and why the lower torque was kept is said, with both torques and the targets bought
    # (the stand-in's missed target: length), in the record and on the written lines
    assert result.remedy.torque_why == (
        "its design torque 643.8 N m, 0.95 of the design as given's 677.1 N m: kept, for "
        "the drive targets the design as given misses (length) and it meets (at or above "
        "the 0.909 of it a remedy may give up for targets: one step of the drive LTE "
        "window's torques)")
    from contact.optimize.development_remedy import applied_table, torque_bought

    assert applied_table(result.remedy)["torque_why"] == result.remedy.torque_why
    # none where nothing was bought or no torque given up
    assert torque_bought(_targets(given, True), _targets(lower, True)) == ""
    assert torque_bought(_targets(lower, False), _targets(given, True)) == ""


def test_apply_remedy_keeps_a_remedy_at_the_given_design_torque(monkeypatch):
    """The same 5x48 where the remedied development keeps the design as given's torque:
    applied as before (alpha_dD 16.3 deg, its record's lte_met True)."""
    basic = load_basic(FIVE)
    _stand_in_checks(monkeypatch, FIVE_MEASURED, FIVE_WRITTEN)
    developed: list = []

    def run(b):
        developed.append(b)
        return _five_result(b, (35.0, 29.0) if len(developed) == 1 else (26.0, 28.0), 206.7)

    result = developed_with_remedy(run, basic)
    assert result.remedy.check.change.field == "alpha_dD"
    assert math.degrees(developed[1].design.alpha_dD) == pytest.approx(16.3, abs=1e-9)
    assert result.remedy.record.lte_met is True


# --- the floor on the torque a remedy may give up for targets (issue 71, remedy99) ---


def test_the_torque_floor_is_one_step_of_the_drive_lte_window():
    """The floor is the development's own torque resolution: one step of the drive LTE
    window's torques (a design torque within 1.1 x of one developed is redeveloped no
    more: development_written_lte.WINDOW_LOWER_STEP). Identity, exact."""
    from contact.optimize.development_remedy import REMEDY_TORQUE_FLOOR
    from contact.optimize.development_written_lte import WINDOW_LOWER_STEP

    assert REMEDY_TORQUE_FLOOR == 1.0 / WINDOW_LOWER_STEP
    # round 35's 12x31 (643.8 of 677.1 N m, 0.951) above it, round 34's 5x48 (81.7 of
    # 206.7, 0.395) below it
    assert 643.8 / 677.1 > REMEDY_TORQUE_FLOOR > 81.7 / 206.7


@pytest.mark.parametrize("design_torque, refused, printed", [
    (643.8, False, ""),   # round 35's 12x31: 0.951 of 677.1, kept
    (616.0, False, ""),   # 0.9098: just above the floor 0.9091 (616.0 > 615.55)
    (615.5, True, r"0\.9090 of the design as given's 677\.1 N m: below the 0\.9091"),
    # half the design torque: an engineer's capacity, not a trade
    (338.6, True, r"0\.500 of the design as given's 677\.1 N m: below the 0\.909"),
])
def test_a_lower_torque_that_buys_the_targets_is_kept_only_above_the_floor(
        monkeypatch, design_torque, refused, printed):
    """Both sides of the floor, through developed_with_remedy with the 12x31's torques as
    stand-ins: the remedied design meets every drive target the design as given misses;
    at or above 0.909 of 677.1 N m (615.55) it is applied and its line says the floor,
    below it an InputError names both torques, their ratio and the floor, after the two
    developments, nothing returned. The bound values straddle the floor x 677.1 = 615.55
    N m: 615.5 below, 616.0 above (the torques are compared unrounded; the ratio and the
    floor are printed at 3 decimals, at 4 where 3 would print them the same: 0.9090 below
    0.9091)."""
    from contact.optimize.development_remedy import REMEDY_TORQUE_FLOOR, below_floor

    basic = load_basic(FIVE)
    _stand_in_checks(monkeypatch, FIVE_MEASURED, FIVE_WRITTEN)
    developed: list = []

    def run(b):
        developed.append(b)
        first = len(developed) == 1
        return _targets(_five_result(b, (27.0, 34.0) if first else (26.0, 39.0),
                                     677.1 if first else design_torque), not first)

    given = _targets(_five_result(basic, (27.0, 34.0), 677.1), False)
    lower = _targets(_five_result(basic, (26.0, 39.0), design_torque), True)
    assert below_floor(given, lower) is refused
    assert (design_torque < REMEDY_TORQUE_FLOOR * 677.1) is refused
    if refused:
        with pytest.raises(InputError, match=(
                rf"alpha_dD 22\.5 -> 16\.3 deg developed: its design torque "
                rf"{design_torque:g} N m, {printed} of it a remedy may give up for targets "
                r"\(one step of "
                r"the drive LTE window's torques, 1/1\.1\), though it meets the drive "
                r"targets the design as given misses \(length\); nothing written")):
            developed_with_remedy(run, basic)
        assert len(developed) == 2
    else:
        result = developed_with_remedy(run, basic)
        assert result.torque[1] == design_torque
        assert "at or above the 0.909 of it a remedy may give up for targets" in (
            result.remedy.torque_why)


def test_the_floor_leaves_the_other_torque_rules_as_they_were():
    """The floor is for targets bought only: a remedy that buys none is refused below the
    given torque at any ratio (round 34's rule, its own words), a trial (the design as
    given's LTE above the limit) is kept whatever its torque, an equal torque is no
    lowering."""
    from contact.optimize.development_remedy import torque_given_up

    basic = load_basic(FIVE)
    given = _targets(_five_result(basic, (27.0, 34.0), 677.1), True)
    half = _targets(_five_result(basic, (26.0, 39.0), 338.6), True)
    assert "for an LTE the design has" in torque_given_up(given, half, True)
    assert torque_given_up(_targets(given, False), half, False) == ""
    assert torque_given_up(_targets(given, False), _targets(
        _five_result(basic, (26.0, 39.0), 677.1), True), True) == ""


def _ranged(result, drive, coast):
    """``result`` whose check recorded its drive and coast LTE over ltca run's torques
    (``drive``, ``coast``: torques [N m], LTE p-p [urad], light and design torques first and
    last), as the development's ``lte_range`` and ``coast_lte_range``."""
    def record(found):
        t, y = found
        i = max(range(len(y)), key=lambda k: y[k])
        return {"torques": t, "lte": y, "peak": y[i], "at": t[i]}

    return dataclasses.replace(result, torque=(drive[0][0], drive[0][-1]),
                               coast_torques=(coast[0][0], coast[0][-1]),
                               lte_range=record(drive), coast_lte_range=record(coast))


#: Round 42's FM spiral bevel 16x35 at Sigma 95 deg (benchmarks/data/unseen_designs/
#: spiral_bevel_16x35_s95_m0.toml; /work runs d3, d3r): its LTE p-p [urad] over ltca run's
#: torques [N m] as given (drive, coast) and with the remedy b2 44 -> 44.9 mm applied
SIXTEEN_GIVEN = (((242.7, 701.1, 1160.0, 1618.0), (14.7, 50.5, 48.1, 38.4)),
                 ((242.7, 357.3, 471.9, 701.1, 1160.0, 1618.0),
                  (35.9, 44.5, 60.9, 65.0, 58.9, 50.8)))
SIXTEEN_REMEDIED = (((246.7, 712.8, 1179.0, 1645.0), (17.1, 55.9, 52.1, 37.5)),
                    ((246.7, 479.8, 596.3, 712.8, 1179.0, 1645.0),
                     (30.9, 57.6, 58.8, 60.3, 52.4, 48.2)))


def test_applied_remedy_lines_judge_the_lte_between_the_torques_too(monkeypatch):
    """Round 42's 16x35 at Σ 95° with --apply-remedy printed "the design as given …,
    developed: LTE p-p drive 15/38 urad …, coast 36/51 urad … (light/design), within the
    verdict's 60 urad; not written" and the remedied design "… within the verdict's 60 urad
    (ltca run judges it between its torques too)", while its coast flank read 65.0 (given)
    and 60.3 urad (remedied) between the torques, which the same command's coast line and
    `ltca run --flank coast` called above the limit. Both lines now give the largest LTE
    between the torques the developments recorded and judge the limit on it too; the
    numbers are the runs' (the recorded ranges), the limit the verdict's 60 µrad. The
    design as given's line names its development's CPU (the stand-in's 1 s): the remedied
    headline's "44 s CPU" was half the command's 90.9 s."""
    from contact.commands.synthesize import first_lines

    basic = load_basic(FIFTEEN)
    _stand_in_checks(monkeypatch, MEASURED)

    def run(b):
        if b is basic:
            return _ranged(_result(b, (14.7, 38.4), (35.9, 50.8)), *SIXTEEN_GIVEN)
        return _ranged(_result(b, (17.1, 37.5), (30.9, 48.2)), *SIXTEEN_REMEDIED)

    result = developed_with_remedy(run, basic)
    lines = first_lines(result.remedy.basic, result, None, "x.toml")
    assert lines[1] == (
        "  the design as given (x.toml), developed: LTE p-p drive 15/38 urad at "
        "242.7/1618 N m, coast 36/51 urad at 242.7/1618 N m (light/design); between them "
        "drive 50.5 urad at 701.1 N m, coast 65.0 urad at 701.1 N m: above the verdict's "
        "60 urad between the torques; not written (its development 1 s CPU; the remedied "
        "design's headline counts its own alone)")
    assert lines[2] == (
        "  the remedied design, developed and written: LTE p-p drive 17/38 urad at "
        "246.7/1645 N m, coast 31/48 urad at 246.7/1645 N m (light/design); between them "
        "drive 55.9 urad at 712.8 N m, coast 60.3 urad at 712.8 N m: above the verdict's "
        "60 urad between the torques")
    table = json.loads(json.dumps(applied_table(result.remedy)))
    assert table["given_worst_lte_urad"] == 50.8  # light/design, as before
    assert table["given_between_worst_lte_urad"] == 65.0
    # without a record between the torques the lines say so, as before
    plain = developed_with_remedy(
        lambda b: _result(b, (86.0, 93.0) if b is basic else (20.0, 45.0), (30.0, 48.0)),
        basic)
    lines = first_lines(plain.remedy.basic, plain, None, "x.toml")
    assert lines[1].endswith("(light/design), above the verdict's 60 urad; not written (its "
                             "development 1 s CPU; the remedied design's headline counts its "
                             "own alone)")
    assert lines[2].endswith("(light/design), within the verdict's 60 urad (ltca run "
                             "judges it between its torques too)")
