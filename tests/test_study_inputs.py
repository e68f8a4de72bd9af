"""Study inputs (issue 56 item 1): ranges, the values a study prints before it starts,
misalignments beyond the blanks refused unless forced, every point's plausibility flagged.

Independent references: the plausible misalignment is recomputed from the bundled case
file's own face widths and outer cone distance (read with ``tomllib``, not through the
toolkit's case loader); the flag of a forced point is compared with
:func:`contact.ltca.plausibility.plausibility_warnings` of a single analysis at its inputs
(the sentences ``ltca run`` prints), so the study flags exactly what the command warns of.
Refusals run no analysis; the forced sweep runs three points at one torque on one mesh
cycle of 6 rolls (~2 s).
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from contact.catalogue import DEFAULT_CASE, bundled_case_path, resolve_case
from contact.cli import main
from contact.commands.study import parse_range, values_line
from contact.ltca import LTCAOptions
from contact.ltca.plausibility import (
    CAUSES,
    MISALIGNMENT_LIMIT_FRACTION,
    misalignment_limits,
    misalignment_warnings,
    plausibility_warnings,
)
from contact.pipeline import run_analysis
from contact.study import StudyRun, sweep
from contact.study import engine as study_engine
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

OPTS = LTCAOptions(rolls_per_cycle=6, cycles=1)
QUICK = ["--rolls-per-cycle", "6", "--scheduler", "synchronous", "--no-progress",
         "--no-root-stress", "--torque", "50"]


def _case_file() -> dict:

    text = bundled_case_path(DEFAULT_CASE).read_text(encoding="utf-8")
    return tomllib.loads(text)


def test_the_plausible_misalignment_is_a_fraction_of_the_face_width():
    """5 % of the smaller face width for ΔE, ΔP, ΔG; ΔΣ the angle moving R_e by as much —
    recomputed from the case file's numbers."""
    raw = _case_file()
    b = min(raw["pinion"]["blank"]["face_width"], raw["gear"]["blank"]["face_width"])
    r_e = raw["gear"]["blank"]["outer_cone_distance"]
    lim = misalignment_limits(resolve_case(None))
    assert MISALIGNMENT_LIMIT_FRACTION == 0.05
    for name in ("delta_E", "delta_P", "delta_G"):
        assert lim[name] == pytest.approx(0.05 * b, rel=1e-12)
    assert lim["delta_Sigma"] == pytest.approx(0.05 * b / r_e, rel=1e-12)
    assert 1.50 < lim["delta_E"] < 1.51  # 30.158 mm face of the gear
    case = resolve_case(None)
    assert misalignment_warnings(case, case.misalignment) == []  # Table 3.1's mounting
    words = misalignment_warnings(case, Misalignment(delta_E=5.0, delta_Sigma=math.radians(1)))
    assert len(words) == 2 and "ΔE = 5 mm" in words[0] and "ΔΣ = 1 deg" in words[1]


@pytest.mark.parametrize("text, values", [
    ("-0.2:0.2:5", [-0.2, -0.1, 0.0, 0.1, 0.2]),
    ("-0.2,0.2,5", [-0.2, 0.2, 5.0]),  # a comma list is values, never a range
    ("0.1", [0.1]),
])
def test_a_range_is_only_start_stop_n(text, values):
    np.testing.assert_allclose(parse_range("--dE", text), values, atol=1e-15)


def test_a_three_value_comma_list_says_how_a_range_is_typed():
    line = values_line("--dE", "-0.2,0.2,5", parse_range("--dE", "-0.2,0.2,5"), "mm")
    assert "3 values: -0.2, 0.2, 5" in line and "-0.2:0.2:5" in line
    plain = values_line("--dE", "-0.1,0,0.1", parse_range("--dE", "-0.1,0,0.1"), "mm")
    assert "range" not in plain  # 0.1 is no count


def test_the_comma_slip_prints_its_values_and_is_refused(tmp_path, capsys):
    """The issue's command: the values are printed before anything runs, the 5 mm point
    refused naming the value, the limit and --force; no file, no parts."""
    out_file = tmp_path / "s.nc"
    assert main(["sweep", "--dE", "-0.2,0.2,5", *QUICK, "-o", str(out_file)]) == 2
    cap = capsys.readouterr()
    assert "--dE [mm]: 3 values: -0.2, 0.2, 5" in cap.out
    assert "-0.2:0.2:5" in cap.out
    assert "delta_E 5 mm (1 point) beyond ±1.51 mm" in cap.err and "--force" in cap.err
    assert not out_file.exists() and not (tmp_path / "s.nc.parts").exists()


def test_tolerance_and_vh_check_print_their_values_and_refuse_the_slip(tmp_path, capsys):
    assert main(["tolerance", "--dE", "normal:0:2", "-n", "8", *QUICK,
                 "-o", str(tmp_path / "t.nc")]) == 2
    cap = capsys.readouterr()
    assert "--dE [mm]: normal:0:2: draws from" in cap.out and "beyond ±1.51 mm" in cap.err
    vh = [a for a in QUICK if a != "--no-root-stress"]  # vh-check has no root stress
    assert main(["vh-check", "--dE", "-5:5:3", *vh, "-o", str(tmp_path / "v.nc")]) == 2
    cap = capsys.readouterr()
    assert "--dE (V) [mm]: 3 values: -5, 0, 5" in cap.out and "--force" in cap.err


def test_forced_points_are_flagged_as_ltca_run_warns(tmp_path, capsys):
    """--force runs the slip; the 5 mm point's flag holds the causes plausibility_warnings
    names for a single analysis there, plus the misalignment's bit; the others none; the
    summary counts them."""
    out_file = tmp_path / "s.nc"
    assert main(["sweep", "--dE", "-0.2,0.2,5", *QUICK, "--force", "-o", str(out_file)]) == 0
    out = capsys.readouterr().out
    from geometry.core.io import read_netcdf

    ds = read_netcdf(out_file)
    flag = ds["plausibility"]
    assert flag.dims == ("delta_E", "torque")
    assert flag.attrs["flag_meanings"].split() == list(CAUSES)
    assert flag.attrs["flag_masks"].tolist() == [1, 2, 4, 8]
    case = resolve_case(None)
    for e, bits in zip(ds["delta_E"].values, flag.values[:, 0], strict=True):
        mis = Misalignment(delta_E=float(e), delta_P=case.misalignment.delta_P)
        tree = run_analysis(case, [50.0], misalignment=mis, options=LTCAOptions(
            rolls_per_cycle=6), geometry=False, theoretical=False, operating=False,
            root_stress=False)
        said = {w.split(":")[0] for w in plausibility_warnings(tree["ltca"].to_dataset())}
        names = {"plastic contact": 1, "flank above the material's limit": 2,
                 "LTE spread": 4}
        expected = sum(names[s] for s in said) + (8 if abs(e) > 1.51 else 0)
        assert int(bits) == expected, (e, said)
    assert int(flag.values[2, 0]) & 8 and int(flag.values[0, 0]) == 0
    assert "WARNING: plausibility: 1 of 3 points flagged implausible" in out
    assert "misalignment beyond blank 1" in out


def test_the_library_refuses_unless_forced():
    with pytest.raises(InputError, match=r"delta_P 2 mm \(1 point\).*force=True"):
        sweep(None, delta_P=[0.0, 2.0], torque=50.0,
              run=StudyRun(options=OPTS, scheduler="synchronous",
                           root_stress=False))


def test_a_failed_point_keeps_its_input_flag(monkeypatch):
    """A point whose analysis raises still says its misalignment was beyond the blank."""
    import contact.pipeline

    def boom(*a, **k):
        raise RuntimeError("flanks separate")

    monkeypatch.setattr(contact.pipeline, "run_analysis", boom)
    from contact.study.grid import study_inputs

    shared = study_inputs(None, [50.0, 250.0], options=OPTS)
    bad = study_engine.analyse_point(shared, 0, {"delta_E": 3.0})
    ok = study_engine.analyse_point(shared, 1, {"delta_E": 0.1})
    assert bad.status == ok.status == 2
    assert bad.summary["plausibility"].tolist() == [8, 8]
    assert ok.summary["plausibility"].tolist() == [0, 0]
