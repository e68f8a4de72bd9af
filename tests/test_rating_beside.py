"""The ISO 10300 rating beside the loaded contact (issue 52 item 2).

``ltca run`` rates the case (contact.load_capacity.iso10300.analysis_rating) at its torques
and speed,
stores ``/rating`` and prints the rating's stresses beside the LTCA's peaks
(rating_beside_ltca); the HTML report shows the same table; ``ltca duty-cycle`` prints its
local safety factors beside the rating's per bin (bin_ratings). A case without the tables
runs without the rating and says why in one line; a bad ``[rating]`` table is refused
before the work. The rating's own numbers are checked against ISO/TR 10300-30 in
tests/test_rating_iso10300.py; here the wiring, each value compared with the function that
computes it or with a quotient done by hand.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import resolve_case
from contact.cli import main
from contact.load_capacity.iso10300 import (
    analysis_rating,
    bin_ratings,
    iso10300_rating,
    rating_beside_ltca,
)
from geometry.case import case_from_dict
from geometry.core.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
SAMPLE1 = ROOT / "cases" / "iso10300_30_sample1.toml"
#: a small, quick loaded contact of the TR's sample 1 (the rating does not depend on it)
QUICK = ["--no-root-stress", "--rolls-per-cycle", "8", "--segments", "8", "--no-progress"]


def _case(drop: str | None = None, **rating):
    raw = tomllib.loads(SAMPLE1.read_text(encoding="utf-8"))
    if drop:
        del raw[drop]
    raw["rating"] = {**raw.get("rating", {}), **rating} if "rating" in raw else None
    if raw["rating"] is None:
        del raw["rating"]
    return case_from_dict(raw)


def _ltca(torque, pressure, root=None) -> xr.Dataset:
    ds = xr.Dataset({"pressure_max_flank": ("torque", np.asarray(pressure, float))},
                    coords={"torque": np.asarray(torque, float)})
    if root is not None:
        ds["root_stress_max"] = (("torque", "member"), np.asarray(root, float))
        ds = ds.assign_coords(member=["pinion", "gear"])
    return ds


# --------------------------------------------------------------------------- functions


def test_beside_ratios_are_the_quotients():
    rating = iso10300_rating("iso10300_30_sample1", torque=[150.0, 300.0], pinion_speed=1200.0)
    side = rating_beside_ltca(rating, _ltca([150.0, 300.0], [2000.0, 3000.0],
                                            [[400.0, 500.0], [700.0, 800.0]]))
    s_h = rating["sigma_H"].values
    s_f = rating["sigma_F"].values
    assert side["pressure_to_sigma_H"].values == pytest.approx([2000.0, 3000.0] / s_h,
                                                               rel=1e-14)
    assert side["pressure_to_sigma_H0"].values == pytest.approx(
        [2000.0, 3000.0] / rating["sigma_H0"].values, rel=1e-14)
    assert side["root_stress_to_sigma_F"].values == pytest.approx(
        np.array([[400.0, 500.0], [700.0, 800.0]]) / s_f, rel=1e-14)
    for name, var in side.data_vars.items():
        assert var.attrs.get("units") and var.attrs.get("long_name"), name


def test_beside_without_root_stress_and_with_a_torque_order():
    rating = iso10300_rating("iso10300_30_sample1", torque=[300.0, 150.0], pinion_speed=1200.0)
    side = rating_beside_ltca(rating, _ltca([150.0, 300.0], [2000.0, 3000.0]))
    assert np.all(np.isnan(side["root_stress_to_sigma_F"].values))
    assert "no root stress" in side["root_stress_max"].attrs["comment"]
    # the LTCA's torque order, whatever the rating's
    assert float(side["sigma_H"][0]) == pytest.approx(float(rating["sigma_H"][1]), rel=1e-15)


def test_beside_refuses_a_torque_the_rating_lacks():
    rating = iso10300_rating("iso10300_30_sample1", torque=[300.0], pinion_speed=1200.0)
    with pytest.raises(InputError, match=r"^torque: the rating has no torque 150"):
        rating_beside_ltca(rating, _ltca([150.0, 300.0], [2000.0, 3000.0]))


@pytest.mark.parametrize(("drop", "speed", "words"), [
    ("design", 1200.0, "no [design] table"),
    ("rating", 1200.0, "no [rating] table"),
    (None, 0.0, "no pinion speed"),
])
def test_analysis_without_the_data_says_why(drop, speed, words):
    ds, why = analysis_rating(_case(drop), [300.0], speed)
    assert ds is None
    assert why.startswith("ISO 10300 rating not computed") and words in why
    assert "\n" not in why


def test_analysis_refuses_a_bad_rating_table():
    with pytest.raises(InputError, match=r"^rating\.application_factor"):
        analysis_rating(_case(application_factor=0.5), [300.0], 1200.0)


@pytest.mark.parametrize(("flank", "side"), [(None, "drive"), ("drive", "drive"),
                                             ("concave", "drive"), ("coast", "coast"),
                                             ("convex", "coast")])
def test_analysis_rates_the_loaded_flank(flank, side):
    ds, why = analysis_rating(_case(), [300.0], 1200.0, flank)
    assert why == "" and ds.attrs["side"] == side


def test_bin_ratings_are_the_rating_at_each_bin():
    case = resolve_case("iso10300_30_sample1")
    iso, why = bin_ratings(case, [100.0, 300.0], [3000.0, 1200.0])
    assert why == ""
    for i, (t, n) in enumerate(((100.0, 3000.0), (300.0, 1200.0))):
        one = iso10300_rating(case, [t], n).isel(torque=0)
        assert iso["S_H"].values[i] == pytest.approx(one["S_H"].values, rel=1e-15)
        assert iso["S_F"].values[i] == pytest.approx(one["S_F"].values, rel=1e-15)
        # what the duty cycle's root-stress check needs to judge a bin as ltca run does
        assert iso["K_A_K_v"].values[i] == pytest.approx(
            float(one["K_A"]) * float(one["K_v"]), rel=1e-15)
        assert float(iso["S_Fmin"]) == float(one["S_Fmin"])
        np.testing.assert_equal(float(iso["design_torque"]), float(one["design_torque"])
                                if "design_torque" in one else np.nan)
    with pytest.raises(InputError, match=r"^speed: one per bin"):
        bin_ratings(case, [100.0, 300.0], [3000.0])
    assert bin_ratings(_case("design"), [100.0], [3000.0])[0] is None


def test_duty_cycle_safety_lines():
    """The duty-cycle table: local and ISO safety factors per bin, pinion / gear."""
    from contact.commands.duty_cycle import safety_lines

    bm = ("bin", "member")
    ds = xr.Dataset({
        "torque": ("bin", [100.0, 300.0]), "speed": ("bin", [3000.0, 1200.0]),
        "local_contact_safety": (bm, [[2.5, 2.5], [1.1, 1.1]]),
        "iso_contact_safety": (bm, [[2.4, 2.4], [0.94, 0.94]]),
        "iso_bending_safety": (bm, [[4.1, 3.9], [1.38, 1.33]]),
    }, attrs={"iso_rating": "ISO 10300-1/-2/-3:2014 Method B1"})
    lines = safety_lines(ds)
    assert "no local S_F" in lines[0]
    assert re.search(r"\|\s+1 \|\s+300 \|\s+1200 \| 1.10 / 1.10 \| 0.94 / 0.94 \| - "
                     r"\s*\| 1.38 / 1.33 \|", lines[1])
    assert lines[-1] == "ISO rating: ISO 10300-1/-2/-3:2014 Method B1"


# --------------------------------------------------------------------------- ltca run


@pytest.fixture(scope="module")
def sample1_run(tmp_path_factory):
    """``ltca run`` of the TR's sample 1 (quick options), its output and file."""
    path = tmp_path_factory.mktemp("run") / "s1.nc"
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["run", "iso10300_30_sample1", "-o", str(path), *QUICK])
    return code, out.getvalue(), path


def test_run_stores_and_prints_the_rating(sample1_run):
    code, out, path = sample1_run
    assert code == 0
    line = next(ln for ln in out.splitlines() if re.match(r"\|\s+300 \| pinion", ln))
    cells = [c.strip() for c in line.strip("|").split("|")]
    with xr.open_dataset(path, group="rating", engine="netcdf4") as ra, \
            xr.open_dataset(path, group="ltca", engine="netcdf4") as lt:
        s_h = float(ra["sigma_H"].isel(torque=0))
        p = float(lt["pressure_max_flank"].isel(torque=0))
        assert s_h == pytest.approx(1712.8, rel=0.005)  # the TR's sample 1
        # the console reads the result contract: contact_stress = sigma_H, root_stress =
        # sigma_F, the safeties S_H, S_F (contact.load_capacity.contract)
        assert float(cells[2]) == pytest.approx(s_h, abs=0.5)
        assert float(cells[3]) == pytest.approx(p, abs=0.5)
        assert float(cells[4]) == pytest.approx(p / s_h, abs=0.005)
        assert float(cells[5]) == pytest.approx(float(ra["sigma_F"].isel(torque=0)[0]),
                                                abs=0.5)
        assert cells[8:] == [f"{float(ra[s].isel(torque=0)[0]):.2f}" for s in ("S_H", "S_F")]
        for name, var in ra.data_vars.items():
            assert var.attrs.get("clause") or var.attrs.get("source"), name
    assert cells[8:] == ["0.94", "1.38"]  # the TR's sample 1: S_H 0.944, S_F 1.385
    assert "ISO 10300 rating beside the LTCA (method iso10300, drive side, n1 1200 rpm" in out
    assert "`ltca rate iso10300_30_sample1 --method iso10300 --torque 300 --speed 1200` " \
           "prints them" in out


def test_report_shows_the_rating_table(sample1_run):
    from contact.plots.report import report_context
    from geometry.core.io import read_netcdf

    tree = read_netcdf(sample1_run[2], tree=True)
    ctx = report_context(tree, figures=[])
    rows = ctx["rating"]["rows"]
    assert [(r["torque"], r["member"]) for r in rows] == [("300", "pinion"), ("300", "gear")]
    cells = {c["key"]: float(c["value"]) for c in rows[1]["cells"] if c["value"]}
    ra = tree["rating"].to_dataset()
    assert cells["root_stress"] == pytest.approx(float(ra["sigma_F"].isel(torque=0)[1]),
                                                 rel=1e-12)
    assert cells["bending_safety"] == pytest.approx(float(ra["S_F"].isel(torque=0)[1]),
                                                    rel=1e-12)
    assert ctx["rating"]["headers"][2] == "ISO 10300 σ_H [MPa]"
    assert "root_stress_max" not in cells  # --no-root-stress: an empty cell
    assert "/rating" not in [a["group"] for a in ctx["absent"]]


def test_run_without_rating(tmp_path, capsys):
    """--no-rating leaves the rating out, not the rest of the load capacity: scuffing and
    micropitting on the LTCA's contact (/scuffing_micropitting, issue 63) are written and
    printed as with the rating."""
    path = tmp_path / "s1.nc"
    assert main(["run", "iso10300_30_sample1", "-o", str(path), "--no-rating", *QUICK]) == 0
    out = capsys.readouterr().out
    assert "ISO 10300 rating not computed (--no-rating)" in out
    assert "scuffing safety S_B" in out
    from contact.plots.report import report_context
    from geometry.core.io import read_netcdf

    tree = read_netcdf(path, tree=True)
    assert "rating" not in tree.children
    assert "scuffing_safety" in tree["scuffing_micropitting"].variables
    ctx = report_context(tree, figures=[])
    assert ctx["rating"] is None and "/rating" in [a["group"] for a in ctx["absent"]]


def test_run_of_a_case_without_design_says_why(tmp_path, capsys):
    text = SAMPLE1.read_text(encoding="utf-8")
    text = re.sub(r"^\[design\]\n(?:[^\[\n].*\n)*", "", text + "\n", flags=re.M)
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    assert "design" not in tomllib.loads(text) and "rating" in tomllib.loads(text)
    assert main(["run", str(case), "-o", str(tmp_path / "c.nc"), *QUICK]) == 0
    out = capsys.readouterr().out
    lines = [ln for ln in out.splitlines() if ln.startswith("ISO 10300 rating")]
    assert lines == ["ISO 10300 rating not computed: the case has no [design] table (its ISO "
                     "23509 basic design data, docs/rating.md)"]
    # and the verdict says it could not make its rating check (issue 64)
    assert any(ln.strip().startswith("not checked: rating") for ln in out.splitlines())


def test_run_refuses_a_bad_rating_before_the_work(tmp_path, capsys):
    text = SAMPLE1.read_text(encoding="utf-8").replace('mounting = "one"', 'mounting = "two"')
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    out = tmp_path / "c.nc"
    assert main(["run", str(case), "-o", str(out), *QUICK]) == 2
    captured = capsys.readouterr()
    assert "rating.mounting" in captured.err and "time [s]" not in captured.out
    assert not out.exists()
