"""The FE level of a case's root stress (issue 75): ``[root_stress] fe_level``.

``ltca synthesize`` develops a new design with the root stress of the ``"coarse10"`` level
(``contact.compliance.fe.options.SYNTHESIS_LEVEL``) and writes the level into the case;
``ltca run`` and :func:`contact.run_analysis` compute the root stress on the level the
case names (absent: the default model, so every case written before and every bundled
case runs as before) and say it, with its accuracy, beside the root-stress table, in the
file's summary and in the verdict's notes; ``--fe-level`` / ``fe_level=`` names another.
The level's accuracy against the default model is measured, not tested here (docs/fe.md,
"A coarse model for a new design"; tests/test_fe_levels.py bounds the coarse level's on
the default case)."""

import dataclasses
import tomllib

import pytest

from contact.catalogue import bundled_cases, resolve_case
from contact.compliance.fe import FEOptions, cache_key
from contact.compliance.fe.options import (
    CASE_TABLE,
    LEVEL_ACCURACY,
    LEVELS,
    SYNTHESIS_LEVEL,
    case_fe_options,
    fe_level_of,
    level_name,
    with_fe_level,
)
from geometry.case import case_from_dict
from geometry.core.errors import InputError

#: the CI tests' coarse FE model (as tests/test_root_stress.py): stands in for the
#: coarse10 level where a test runs the whole analysis (the wiring, not the numbers)
TINY = {"face_divisions": 4, "across_divisions": 2, "flank_divisions": 3,
        "slot_divisions": 1, "rim_divisions": 2, "fillet_divisions": 2, "load_nu": 5,
        "load_nv": 4}


def test_a_case_without_the_table_is_the_default_model():
    """Every bundled case names no level (or the default): its root stress is
    ``FEOptions()``, as before issue 75's levels."""
    for name in bundled_cases():
        case = resolve_case(name.removesuffix(".toml"))
        assert fe_level_of(case) == "default", name
        assert case_fe_options(case) == FEOptions()


def test_the_level_round_trips_through_the_case_file():
    case = resolve_case(None)
    coarse = with_fe_level(case, "coarse10")
    again = case_from_dict(tomllib.loads(coarse.to_toml()))
    assert dict(again.extra[CASE_TABLE]) == {"fe_level": "coarse10"}
    assert fe_level_of(again) == "coarse10"
    assert case_fe_options(again) == FEOptions.at_level("coarse10")
    # no tooth depends on it: the per-process memos of the teeth are shared
    assert again.teeth_key() == case.teeth_key()
    assert fe_level_of(with_fe_level(case, "default")) == "default"


def test_the_synthesis_level_is_coarse_with_ten_along_the_face():
    assert SYNTHESIS_LEVEL == "coarse10"
    ten = FEOptions.at_level("coarse10")
    assert ten == FEOptions.at_level("coarse", face_divisions=10)
    assert level_name(ten) == "coarse10" and level_name(FEOptions()) == "default"
    assert level_name(FEOptions(face_divisions=11)) is None
    assert set(LEVEL_ACCURACY) == set(LEVELS)
    member = resolve_case(None).member("pinion")
    keys = {cache_key(member, "concave", FEOptions.at_level(name)) for name in LEVELS}
    assert len(keys) == len(LEVELS)  # each level's coefficients cached apart


@pytest.mark.parametrize("table, text", [
    ({"fe_level": "fine"}, r"root_stress\.fe_level: must be one of 'default', 'coarse', "
                           r"'coarse10'.*got 'fine'"),
    ({"fe_level": 10}, r"root_stress\.fe_level: must be one of"),
    ({"level": "coarse"}, r"root_stress\.level: unknown field"),
    ("coarse", r"root_stress: must be a table"),
])
def test_a_bad_table_is_refused_naming_the_field(table, text):
    case = resolve_case(None)
    bad = dataclasses.replace(case, extra={**case.extra, CASE_TABLE: table})
    with pytest.raises(InputError, match=text):
        fe_level_of(bad)
    with pytest.raises(InputError, match=text):  # before any work
        from contact import run_analysis

        run_analysis(bad, [250.0])
    with pytest.raises(InputError, match=r"root_stress\.fe_level"):
        with_fe_level(case, "fine")


def test_run_analysis_fe_level_is_checked_and_overrides_the_case():
    from contact import AnalysisChain, run_analysis
    from contact.pipeline import _fe_level_options

    coarse = with_fe_level(resolve_case(None), "coarse10")
    assert _fe_level_options(coarse, None, None) is None  # the step reads the case's
    assert _fe_level_options(coarse, "default", None) == FEOptions()
    with pytest.raises(InputError, match=r"fe_level: must be one of"):
        run_analysis(None, [250.0], fe_level="fine")
    with pytest.raises(InputError, match=r"fe_level: FE options were given too"):
        run_analysis(None, [250.0], fe_level="default",
                     steps=AnalysisChain.analysis().with_root_stress(FEOptions()))


def test_ltca_run_refuses_an_unknown_level(capsys):
    from contact.cli import main

    assert main(["run", "--fe-level", "fine", "--no-progress"]) != 0
    err = capsys.readouterr().err
    assert "--fe-level: must be one of default, coarse, coarse10" in err
    from contact.commands.options import FE_LEVEL_NAMES

    assert FE_LEVEL_NAMES == tuple(LEVELS)  # the help text names the levels there are


def test_synthesize_writes_the_level(tmp_path, monkeypatch):
    """The level ``ltca synthesize`` uses: ``--fe-level``, else the basic file's
    ``[root_stress] fe_level``, else coarse10; every case the synthesis makes carries it
    (the development's root-stress checks read it from there)."""
    from contact.commands.synthesize import synthesis_fe_level
    from geometry.synthesis.basic_design import load_basic
    from geometry.synthesis.case_synthesis import synthesize

    basic = load_basic(_default_basic())
    assert basic.root_stress == {}
    assert synthesis_fe_level(basic) == "coarse10"
    assert synthesis_fe_level(basic, "default") == "default"
    own = dataclasses.replace(basic, root_stress={"fe_level": "default"})
    assert synthesis_fe_level(own) == "default"
    assert synthesis_fe_level(own, "coarse") == "coarse"
    with pytest.raises(InputError, match=r"root_stress\.fe_level"):
        synthesis_fe_level(dataclasses.replace(basic, root_stress={"fe_level": "x"}))
    case = synthesize(dataclasses.replace(basic, root_stress={"fe_level": "coarse10"}))[0]
    assert fe_level_of(case) == "coarse10"
    assert fe_level_of(synthesize(basic)[0]) == "default"  # no table: none written


def _default_basic():
    from contact.commands.synthesize import resolve_basic

    return resolve_basic(None)


def test_synthesize_no_development_writes_coarse10(tmp_path, capsys):
    from contact.cli import main

    out = tmp_path / "case.toml"
    assert main(["synthesize", "--no-development", "--no-progress", "-o", str(out)]) == 0
    raw = tomllib.loads(out.read_text(encoding="utf-8"))
    assert raw[CASE_TABLE] == {"fe_level": "coarse10"}
    capsys.readouterr()
    assert main(["synthesize", "--no-development", "--fe-level", "fine", "-o",
                 str(tmp_path / "other.toml")]) != 0
    assert "--fe-level: must be one of default, coarse, coarse10" in capsys.readouterr().err
    assert not (tmp_path / "other.toml").exists()


def test_ltca_run_of_a_coarse_case_names_its_level(tmp_path, monkeypatch, capsys):
    """``ltca run`` of a case whose ``[root_stress] fe_level`` is coarse10 computes the
    root stress on that level and says so with its accuracy: under the root-stress table,
    in the file's summary, in ``/ltca``'s attributes and in the verdict's notes. The
    level's fields are the CI tests' coarse model here (monkeypatched: seconds, not the
    ~10 s of the real level's build; the wiring is what is tested)."""
    from contact.compliance.fe import CACHE_ENV
    from contact.ltca import root_stress as rs_module

    monkeypatch.setenv(CACHE_ENV, str(tmp_path / "fe"))
    monkeypatch.setitem(LEVELS, "coarse10", TINY)
    # the memo of which level coefficients are: its answer for TINY not kept for the next
    # test (TINY is the CI tests' coarse model, no level of its own)
    rs_module._coefficients_level.cache_clear()
    try:
        _run_coarse(tmp_path, capsys)
    finally:
        rs_module._coefficients_level.cache_clear()


def _run_coarse(tmp_path, capsys):
    import xarray as xr

    from contact.cli import main
    from contact.study.verdicts import verdict

    case_path = tmp_path / "coarse.toml"
    case_path.write_text(with_fe_level(resolve_case(None), "coarse10").to_toml(),
                         encoding="utf-8")
    nc = tmp_path / "coarse.nc"
    main(["run", str(case_path), "--rolls-per-cycle", "4", "--segments", "8", "--torque",
          "250", "--no-progress", "-o", str(nc)])
    out = capsys.readouterr().out
    said = f"root stress: FE coarse10 level ({LEVEL_ACCURACY['coarse10']}, docs/fe.md"
    assert said in out.replace("\n    ", " ")  # the table's line and the verdict's note
    assert "mesh-converged within 5 %" not in out
    tree = xr.open_datatree(nc)
    rs = tree["/ltca"]["root_stress_max"]
    assert rs.attrs["fe_level"] == "coarse10"
    assert rs.attrs["fe_level_accuracy"] == LEVEL_ACCURACY["coarse10"]
    assert "Root stress: FE coarse10 level" in tree.attrs["summary"]
    assert any(n.startswith("root stress: FE coarse10 level") for n in verdict(tree).notes)
    # the keys of the level's models, not the default's
    opt = FEOptions.at_level("coarse10")
    case = resolve_case(case_path)
    keys = tree["/ltca"]["root_stress"].attrs["fe_cache_keys"].split()
    flank = case.pair.drive_flank
    assert keys[0] == cache_key(case.member("pinion"), flank, opt)


def test_the_level_is_that_of_the_coefficients_used():
    """The level a root stress names is read from the coefficients it used (their
    ``options`` attribute), so a study's or a duty cycle's coefficients, built once and
    handed to each point, say it too; members of different models, or a model of no
    level, name none."""
    from contact.ltca.root_stress import _coefficients_level

    default, coarse = FEOptions().to_json(), FEOptions.at_level("coarse10").to_json()
    assert _coefficients_level(default, default) == "default"
    assert _coefficients_level(coarse, coarse) == "coarse10"
    assert _coefficients_level(default, coarse) is None
    own = FEOptions(face_divisions=11).to_json()
    assert _coefficients_level(own, own) is None
    assert _coefficients_level("", "") is None
