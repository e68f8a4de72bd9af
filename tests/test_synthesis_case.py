"""The case ``ltca synthesize`` writes is complete (issue 60, item 2): the basic file's
``[design]``, a ``[rating]`` table (the basic file's, else stated defaults) with the
design torque, provenance naming the user's basic file (also in the report of its run),
progress lines off a terminal.

The design torque's default is the ISO 10300 capacity
(:mod:`contact.load_capacity.iso10300.capacity`);
it is checked against the structure of ISO 10300-2/-3 rather than against itself:
σ_H = σ_H0 √(K_A K_v K_Hβ K_Hα) with σ_H0 ∝ √T, and σ_F ∝ T K_v K_Fβ K_Fα, so from any
torque T the capacity follows in closed form up to the load-dependent factors.
"""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest

from contact.cli import main as ltca
from contact.load_capacity.iso10300.capacity import (
    capacity_torque,
    design_torque,
    with_design_torque,
)
from contact.load_capacity.iso10300.inputs import RatingInputs
from contact.load_capacity.iso10300.rating import iso10300_rating
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.synthesis.basic_design import DEFAULT_RATING, load_basic

ROOT = Path(__file__).resolve().parents[1]
BASIC = ROOT / "cases" / "basic" / "kolivand2009_fm_11x41.toml"


def test_capacity_inverts_the_pitting_rating():
    """hypoid_iso23509_s2 (ISO/TR 10300-30 sample 2's rating inputs): pitting governs. From
    T/2, T_cap = (T/2) S_H(T/2)² K_v(T/2) K_Hα(T/2) / (K_v(T_cap) K_Hα(T_cap)) (σ_H0 ∝ √T,
    ISO 10300-2 cl. 6), to 1e-6 (Brent's xtol 1e-7 on ln T); bending is not reached."""
    t_cap = capacity_torque("hypoid_iso23509_s2")
    ds = iso10300_rating("hypoid_iso23509_s2", torque=[0.5 * t_cap, t_cap])
    s_h = (ds["S_H"] / ds["Z_NT"] / ds["S_Hmin"]).min("member").values
    k = (ds["K_v"] * ds["K_Halpha"]).values
    assert 0.5 * t_cap * s_h[0] ** 2 * k[0] / k[1] == pytest.approx(t_cap, rel=1e-6)
    s_f = (ds["S_F"] / ds["Y_NT"] / ds["S_Fmin"]).min("member").values
    assert s_f[1] > 1.0


def test_capacity_takes_the_first_limit_reached():
    """With S_F,min = 3 bending governs: T_cap = T S_F(T)/S_F,min K_v(T) K_Fα(T) / (K_v
    K_Fα)(T_cap) (σ_F ∝ T, ISO 10300-3 cl. 6), to 1e-6; the pitting safety is still above
    its minimum there."""
    table = dict(load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml").extra["rating"])
    table["min_safety_bending"] = 3.0
    t_cap = capacity_torque("hypoid_iso23509_s2", rating=table)
    ds = iso10300_rating("hypoid_iso23509_s2", torque=[0.5 * t_cap, t_cap], rating=table)
    s_f = (ds["S_F"] / ds["Y_NT"] / ds["S_Fmin"]).min("member").values
    k = (ds["K_v"] * ds["K_Falpha"]).values
    assert 0.5 * t_cap * s_f[0] * k[0] / k[1] == pytest.approx(t_cap, rel=1e-6)
    s_h = (ds["S_H"] / ds["Z_NT"] / ds["S_Hmin"]).min("member").values
    assert s_h[1] > 1.0


def test_design_torque_prefers_the_rating_table():
    """A case whose ``[rating]`` gives ``design_torque`` (the default case: 250 N m) keeps
    it; the capacity is only the default."""
    assert design_torque("kolivand2009_fm_11x41") == 250.0
    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    same, torque, why = with_design_torque(case)
    assert same is case and torque == 250.0 and "[rating]" in why
    given, torque, why = with_design_torque(case, 123.0)
    assert torque == 123.0 and given.extra["rating"]["design_torque"] == 123.0
    assert "[synthesis] design_torque" in given.extra["rating"]["source"]


def test_default_design_torque_is_rated_at_its_minimum_safety():
    """Without a design torque the capacity is the default, rounded *down* to 4 significant
    digits: the design torque then rates at S_H ≥ S_H,min and S_F ≥ S_F,min (the rating
    itself, independent of the rounding), and lies within 1e-3 of the capacity."""
    from contact.load_capacity.iso10300 import iso10300_rating

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    table = {k: v for k, v in case.extra["rating"].items() if k != "design_torque"}
    bare = dataclasses.replace(case, extra=MappingProxyType({**case.extra, "rating": table}))
    rated, torque, _ = with_design_torque(bare)
    exact = capacity_torque(bare)
    assert torque <= exact and torque == pytest.approx(exact, rel=1e-3)
    assert torque == float(f"{torque:.4g}")
    r = iso10300_rating(rated, [torque], bare.operating.pinion_speed or 1500.0)
    assert float(r["S_H"].min()) >= float(r["S_Hmin"])
    assert float(r["S_F"].min()) >= float(r["S_Fmin"])


def test_default_rating_table_is_valid_and_sourced():
    """The stated defaults are a valid ``[rating]`` table, and their source names each
    value's origin (K_A, mounting, accuracy grades, load cycles, materials)."""
    inputs = RatingInputs.from_mapping(DEFAULT_RATING)
    assert inputs.application_factor == 1.0 and inputs.mounting == "one"
    assert inputs.accuracy_grade == (6, 8) and inputs.load_cycles is None
    for word in ("K_A", "mounting", "accuracy grades", "load cycles", "materials"):
        assert word in DEFAULT_RATING["source"]


def test_default_rating_source_says_the_flank_roughness_the_rating_uses():
    """The stated defaults give no flank_roughness, so the rating takes the case's Rq as
    Rz = 6 √(2/π) Rq (contact.load_capacity.iso10300.rating.case_rating_inputs): the
    source says so, not the former "flank/root Rz 8/16 um" (branch iso87: on the FH hypoid
    10x41 a45 Rz 8 would have given an ISO capacity of 124.9 N m, not 141.1), and its
    3.83 um at Rq 0.8 is what the rating uses (to the 0.01 um quoted)."""
    from contact.load_capacity.iso10300.rating import RZ_PER_RQ

    source = DEFAULT_RATING["source"]
    assert "flank/root Rz 8/16" not in source
    assert "[operating] roughness Rq as Rz = 6 sqrt(2/pi) Rq (3.83 um at Rq 0.8 um" in source
    assert "flank_roughness" not in DEFAULT_RATING
    assert RZ_PER_RQ * 0.8 == pytest.approx(3.83, abs=5e-3)


def _basic_with_rating(tmp_path: Path, rating: dict | None) -> Path:
    text = BASIC.read_text(encoding="utf-8")
    if rating is not None:
        lines = [f"{k} = {v!r}".replace("'", '"') for k, v in rating.items()]
        text += "\n[rating]\n" + "\n".join(lines) + "\n"
    path = tmp_path / "my_design.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_synthesised_case_is_rated(tmp_path, capsys):
    """``ltca synthesize`` of a user's basic file (the default design with its own
    ``[rating]`` table) writes ``[design]`` = the fitted basic design data, the basic
    file's ``[rating]`` copied with the design torque added (its capacity), and a source
    that starts with the user's file; ``ltca rate`` rates the written case; off a terminal
    the ten steps are plain lines on standard error."""
    own = {"application_factor": 1.25, "mounting": "both", "accuracy_grade": [5, 7],
           "source": "my rating inputs"}
    basic_path = _basic_with_rating(tmp_path, own)
    out = tmp_path / "my_case.toml"
    # the plain synthesis (the development bearing, tested elsewhere, writes the same
    # tables on top)
    assert ltca(["synthesize", str(basic_path), "-o", str(out), "--no-development"]) == 0
    cap = capsys.readouterr()
    assert "synthesize: step 10/10, the case" in cap.err
    assert "design torque:" in cap.out
    raw = tomllib.loads(out.read_text(encoding="utf-8"))
    assert raw["design"] == load_basic(basic_path).design.to_degrees()
    rating = raw["rating"]
    for key, value in own.items():
        if key != "source":
            assert rating[key] == value
    assert rating["source"].startswith("my rating inputs")
    case = load_case(out)
    assert rating["design_torque"] == pytest.approx(capacity_torque(case), rel=1e-3)
    assert case.source.startswith(f"Synthesised from the basic design file {basic_path}")
    assert ltca(["rate", str(out)]) == 0
    # ltca run rates it beside the LTCA, and its report cites the user's file, with the
    # toolkit's method reference labelled as such
    nc, page = tmp_path / "my_run.nc", tmp_path / "my_run.html"
    assert ltca(["run", str(out), "--torque", "100", "--rolls-per-cycle", "4", "--segments",
                 "10", "--no-progress", "--no-root-stress", "-o", str(nc)]) == 0
    assert ltca(["report", str(nc), "-o", str(page), "--no-progress"]) == 0
    from geometry.core.io import read_netcdf

    assert "rating" in read_netcdf(nc, tree=True).children
    html = page.read_text(encoding="utf-8")
    assert (f"<tr><td>design source</td><td>Synthesised from the basic design file "
            f"{basic_path}: Kolivand") in html
    assert "<td>method (the toolkit&#39;s references)</td><td>Kolivand, M., 2009." in html


def test_default_rating_goes_into_a_case_without_one():
    """The API: a basic design without ``[rating]`` gives a case with
    :data:`DEFAULT_RATING` (the design torque is the command's), rated by ISO 10300."""
    from geometry.synthesis.case_synthesis import synthesize

    case, _ = synthesize(load_basic(BASIC))
    assert dict(case.extra["rating"]) == dict(DEFAULT_RATING)
    assert case.extra["design"] == load_basic(BASIC).design.to_degrees()
    ds = iso10300_rating(case, torque=[250.0])
    assert float(ds["S_H"].min()) > 0.0


def test_bad_rating_table_is_refused_before_the_work(tmp_path, capsys):
    """K_A 0.5 in the basic file's [rating]: rc 2 at once, the field named, no file."""
    basic_path = _basic_with_rating(tmp_path, {"application_factor": 0.5, "mounting": "one",
                                               "accuracy_grade": 6})
    out = tmp_path / "never.toml"
    assert ltca(["synthesize", str(basic_path), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "application_factor" in err and "synthesize: step" not in err
    assert not out.exists()


def test_coast_design_torque_is_the_coast_sides_capacity_below_the_design_torque():
    """A synthesised hypoid whose coast side carries less than its design torque at long
    life gets ``coast_design_torque``: the torque at which the coast side's own rating
    (``side = "coast"``, computed here by the rating, not by the capacity search) reaches
    its minimum safety, to the 4-digit rounding (1e-3) and not above it; the coast side's
    rating then reports that torque as its design torque, and a larger one at a finite
    life (permissible cycles finite). A case where the coast side carries the design torque,
    or whose table sets the field, is unchanged."""
    from contact.load_capacity.iso10300 import iso10300_rating
    from contact.load_capacity.iso10300.capacity import with_coast_design_torque

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    table = dict(case.extra["rating"])
    coast_rating = {**table, "side": "coast"}
    speed = case.operating.pinion_speed or 1500.0
    # a design torque above the coast side's long-life capacity
    cap = capacity_torque(case, rating=coast_rating)
    high = dataclasses.replace(case, extra=MappingProxyType(
        {**case.extra, "rating": {**table, "design_torque": 1.5 * cap}}))
    rated, torque = with_coast_design_torque(high)
    assert torque <= cap and torque == pytest.approx(cap, rel=1e-3)
    assert rated.extra["rating"]["coast_design_torque"] == torque
    assert "coast_design_torque" in rated.extra["rating"]["source"]
    r = iso10300_rating(rated, [torque, 1.5 * cap], speed,
                        rating={**rated.extra["rating"], "side": "coast"})
    safety = np.minimum((r["S_H"] / r["Z_NT"] / r["S_Hmin"]).min("member").values,
                        (r["S_F"] / r["Y_NT"] / r["S_Fmin"]).min("member").values)
    assert safety[0] >= 1.0 - 1e-9 and safety[1] < 1.0
    assert float(r["design_torque"]) == torque
    assert r["design_torque"].attrs["clause"] == "[rating] coast_design_torque"
    # the drive side keeps the design torque
    d = iso10300_rating(rated, [torque], speed, rating=rated.extra["rating"])
    assert float(d["design_torque"]) == 1.5 * cap
    # below the coast capacity, or given by the table: unchanged
    low = dataclasses.replace(case, extra=MappingProxyType(
        {**case.extra, "rating": {**table, "design_torque": 0.5 * cap}}))
    assert with_coast_design_torque(low)[0] is low
    given = dataclasses.replace(case, extra=MappingProxyType(
        {**case.extra, "rating": {**table, "design_torque": 1.5 * cap,
                                  "coast_design_torque": 100.0}}))
    assert with_coast_design_torque(given)[0] is given


def test_coast_design_torque_is_validated():
    """The field is refused outside (0, 1e6] N m, naming it."""
    with pytest.raises(InputError, match="coast_design_torque"):
        RatingInputs.from_mapping({**DEFAULT_RATING, "coast_design_torque": -1.0})
