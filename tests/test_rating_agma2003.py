"""ANSI/AGMA 2003-D19 (the load-capacity registry's ``"agma2003"`` method) against the
standard's Annex E worked example (issue 63 item 2).

The reference: ``tests/data/agma2003_d19_annex_e_published.toml``, Annex E's inputs and published
numbers in US units, as a public implementation's self-test of the standard gives them
(the standard's text was not at hand; the file says so). Annex E works in psi, hp and
lb·in; we rate in SI (the standard's "M" equations) and convert the published numbers with
exact factors. Where the two unit systems differ the tolerance says by how much:

* Eq. 13M takes √(200 v_et) for the US equation's √(v_t) with v_t in ft/min (196.85 per
  m/s): K_v 1.0822 in SI against Annex E's 1.081 (+0.1 %);
* C_p in SI from E = 207 000 MPa is 190.3 MPa^0.5; Annex E's 2290 psi^0.5 (from
  30e6 psi, printed to 4 digits) is 190.15 MPa^0.5 (+0.08 %);
* the SI table's s_ac 1380 MPa is 200 152 psi (+0.08 %), its s_at 205 MPa is 29 733 psi
  (−0.89 %): the SI and US tables are rounded separately;
* Annex E prints C_L and K_L to two decimals (±0.005, up to 0.53 % of K_L).

The issue's acceptance tolerance for the stress numbers s_c, s_t1, s_t2 is 1 %; measured
0.11–0.13 % (K_v and C_p's unit-system differences above, 0.1 % and 0.08 %), and each is
also held to 0.25 %, the sum of those two, so a drift shows long before 1 %.
"""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact import rate_load_capacity, resolve_case
from contact.cli import main
from contact.load_capacity import METHODS, available_methods
from contact.load_capacity.agma2003 import AGMAInputs, missing
from contact.load_capacity.agma2003 import factors as fac
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf

DATA = tomllib.loads((Path(__file__).parent / "data" / "agma2003_d19_annex_e_published.toml")
                     .read_text(encoding="utf-8"))
INPUTS, PUBLISHED = DATA["inputs"], DATA["published"]
CASE = "agma2003_d19_annex_e"

#: exact unit factors: the international inch and pound (1959), g_n = 9.80665 m/s²
INCH = 25.4                                            # mm
LBF = 0.45359237 * 9.80665                             # N
PSI = LBF / INCH**2                                    # MPa (N/mm²): 6.894757e-3
LBF_IN = LBF * INCH / 1000.0                           # N·m: 0.1129848
HP = 550.0 * 0.3048 * LBF / 1000.0                     # kW: 0.7456999

T1 = INPUTS["pinion_torque"] * LBF_IN                  # 162.698 N·m
N1 = INPUTS["pinion_speed"]


def _table(**changes) -> dict:
    """The [agma2003] table of Annex E's inputs (SI), with ``changes``."""
    keys = ("geometry_factor_I", "geometry_factor_J", "overload_factor", "accuracy_number",
            "mounting", "crowned", "load_cycles", "reliability", "temperature",
            "safety_factor_pitting", "safety_factor_bending")
    table = {k: INPUTS[k] for k in keys}
    table.update(grade=[INPUTS["grade"]] * 2, youngs_modulus=[INPUTS["youngs_modulus"]] * 2,
                 poisson_ratio=[INPUTS["poisson_ratio"]] * 2, critical_service=False)
    table.update(changes)
    return table


@pytest.fixture(scope="module")
def annex_e():
    """The bundled case rated at Annex E's T1 and n1 by the registry's method."""
    return rate_load_capacity(CASE, [T1], N1, method="agma2003")


@pytest.fixture(scope="module")
def annex_e_us_allowables():
    """The same with Annex E's own (US table) s_ac 200 000 psi and s_at 30 000 psi."""
    table = _table(s_ac=PUBLISHED["s_ac"] * PSI, s_at=PUBLISHED["s_at"] * PSI)
    return rate_load_capacity(CASE, [T1], N1, method="agma2003", agma2003=table)


def test_the_bundled_case_is_annex_e():
    """The case's [agma2003] table is Annex E's inputs; its [design] gives Annex E's
    geometry: d_e1 = z1 · 25.4/5.6 (the design's d_e2 176.893 is printed to 1e-3 mm:
    1e-4 mm on d_e1), b 1.0 in, β_m 35°, r_c0 4.5 in exactly, R_e 3.70 in to the 0.01 in
    Annex E prints (±0.127 mm)."""
    case = resolve_case(CASE)
    table = dict(case.extra["agma2003"])
    table.pop("source")
    assert AGMAInputs.from_mapping(table) == AGMAInputs.from_mapping(_table())
    assert case.operating.torque == pytest.approx([T1], abs=0.005)  # 162.70 printed
    assert case.operating.pinion_speed == N1
    assert case.extra["design"]["a"] == 0.0
    ds = rate_load_capacity(CASE, [T1], N1, method="agma2003")
    m_et = INCH / INPUTS["diametral_pitch"]
    assert float(ds["d_e"][0]) == pytest.approx(INPUTS["z1"] * m_et, abs=1e-4)
    assert float(ds["m_et"]) == pytest.approx(m_et, abs=1e-5)
    assert float(ds["b"]) == pytest.approx(INPUTS["face_width"] * INCH, abs=1e-9)
    assert float(ds["beta_m"]) == pytest.approx(math.radians(35.0), abs=1e-12)
    assert float(ds["r_c0"]) == pytest.approx(INPUTS["cutter_radius"] * INCH, abs=1e-9)
    assert float(ds["R_e"]) == pytest.approx(INPUTS["outer_cone_distance"] * INCH,
                                             abs=0.005 * INCH)


def test_closed_form_factors_match_annex_e(annex_e):
    """The closed forms to Annex E's printed digits (half a unit of the last digit): C_s,
    K_s, K_m to 5e-5, K_mb, C_xc, K_x, C_H exactly; C_L, K_L to ±0.005 (two decimals
    printed); K_v to 0.2 % and C_p to 0.1 % (the SI equations' constants, module
    docstring); s_ac, s_at of the SI table against the US one: 0.1 % and 0.9 %."""
    ds = annex_e
    for name in ("C_s", "K_s", "K_m"):
        assert float(ds[name]) == pytest.approx(PUBLISHED[name], abs=5e-5), name
    for name in ("K_mb", "C_xc", "K_x"):
        assert float(ds[name]) == PUBLISHED[name], name
    np.testing.assert_array_equal(ds["C_H"].values, [PUBLISHED["C_H"]] * 2)
    np.testing.assert_allclose(ds["C_L"].values, PUBLISHED["C_L"], atol=0.005)
    np.testing.assert_allclose(ds["K_L"].values, PUBLISHED["K_L"], atol=0.005)
    assert float(ds["K_v"]) == pytest.approx(PUBLISHED["K_v"], rel=2e-3)
    assert float(ds["C_p"]) == pytest.approx(PUBLISHED["C_p"] * math.sqrt(PSI), rel=1e-3)
    np.testing.assert_array_equal(ds["s_ac"].values, [PUBLISHED["s_ac_si"]] * 2)
    np.testing.assert_array_equal(ds["s_at"].values, [PUBLISHED["s_at_si"]] * 2)
    assert PUBLISHED["s_ac_si"] == pytest.approx(PUBLISHED["s_ac"] * PSI, rel=1e-3)
    assert PUBLISHED["s_at_si"] == pytest.approx(PUBLISHED["s_at"] * PSI, rel=9e-3)
    assert float(ds["T2"][0]) == pytest.approx(PUBLISHED["T2"] * LBF_IN, abs=0.5 * LBF_IN)


def test_stress_numbers_match_annex_e(annex_e):
    """s_c, s_t1, s_t2 within the issue's 1 %, and within 0.25 % (K_v's and C_p's SI
    constants, module docstring)."""
    s_c = float(annex_e["s_c"][0])
    s_t = annex_e["s_t"].isel(torque=0).values
    assert s_c == pytest.approx(PUBLISHED["s_c"] * PSI, rel=0.01)
    np.testing.assert_allclose(s_t, np.array(PUBLISHED["s_t"]) * PSI, rtol=0.01)
    assert s_c == pytest.approx(PUBLISHED["s_c"] * PSI, rel=2.5e-3)
    np.testing.assert_allclose(s_t, np.array(PUBLISHED["s_t"]) * PSI, rtol=2.5e-3)


def test_permissible_stresses_and_power_ratings_match_annex_e(annex_e,
                                                              annex_e_us_allowables):
    """With Annex E's (US table) allowables: s_wc within 0.45 % (C_L printed to two
    decimals, the gear's 1.0637 as 1.06: 0.35 %), s_wt within 0.6 % (K_L printed to two
    decimals: ±0.005 / 0.94), P_ac ∝ s_wc²/(K_v C_p²) within 1 % (0.7 % + 0.1 % + 0.16 %),
    P_at ∝ s_wt/K_v within 0.7 %. With the SI table's s_at (−0.89 %, module docstring)
    s_wt and P_at of the pinion lie 1.2 % and 1.3 % below Annex E: within 1.5 %."""
    us = annex_e_us_allowables
    np.testing.assert_allclose(us["s_wc"].values, np.array(PUBLISHED["s_wc"]) * PSI,
                               rtol=4.5e-3)
    np.testing.assert_allclose(us["s_wt"].values, np.array(PUBLISHED["s_wt"]) * PSI,
                               rtol=6e-3)
    np.testing.assert_allclose(us["P_ac"].values, np.array(PUBLISHED["P_ac"]) * HP,
                               rtol=0.01)
    np.testing.assert_allclose(us["P_at"].values, np.array(PUBLISHED["P_at"]) * HP,
                               rtol=7e-3)
    np.testing.assert_allclose(annex_e["s_wt"].values, np.array(PUBLISHED["s_wt"]) * PSI,
                               rtol=0.015)
    np.testing.assert_allclose(annex_e["P_at"].values, np.array(PUBLISHED["P_at"]) * HP,
                               rtol=0.015)
    assert float(annex_e["P_a"]) == pytest.approx(
        min(float(annex_e["P_ac"].min()), float(annex_e["P_at"].min())), rel=1e-15)


def test_ratings_are_the_stress_numbers_reaching_the_permissible(annex_e):
    """Identities of clause 5: at the pinion torque of P_ac (Eq. 9M) s_c = s_wc of that
    member, at that of P_at s_t = s_wt; the margins are s_wc/s_c, s_wt/s_t and the power
    ratios their squares (pitting, s_c ∝ √T) and themselves (bending, s_t ∝ T)."""
    ds = annex_e
    for i in range(2):
        at_pac = rate_load_capacity(CASE, [float(ds["P_ac"][i]) * 30000 / (math.pi * N1)],
                                    N1, method="agma2003")
        assert float(at_pac["s_c"][0]) == pytest.approx(float(ds["s_wc"][i]), rel=1e-12)
        at_pat = rate_load_capacity(CASE, [float(ds["P_at"][i]) * 30000 / (math.pi * N1)],
                                    N1, method="agma2003")
        assert float(at_pat["s_t"][0, i]) == pytest.approx(float(ds["s_wt"][i]), rel=1e-12)
    one = ds.isel(torque=0)
    np.testing.assert_allclose(one["power_ratio_pitting"], one["safety_pitting"] ** 2,
                               rtol=1e-12)
    np.testing.assert_allclose(one["power_ratio_bending"], one["safety_bending"],
                               rtol=1e-12)


def test_elastic_coefficient_is_iso10300s_elasticity_factor():
    """C_p (Eq. 32M) and ISO 10300's Z_E are the same Hertz constant: the ISO method of
    the same case (E 207 000 MPa, ν 0.3 in both tables) through its own code, to 1e-12."""
    iso = rate_load_capacity(CASE, [T1], N1, method="iso10300")
    agma = rate_load_capacity(CASE, [T1], N1, method="agma2003")
    assert float(agma["C_p"]) == pytest.approx(float(iso["Z_E"]), rel=1e-12)


def test_stress_cycle_factors_meet_at_the_knee():
    """Figure 6's two lines meet (K_L continuous at the knee, ≈ 3e6 cycles, to 1e-12) for
    both edges of its band; Figure 5's C_L is 2.0 at 1e4 cycles and 1.0 at 1e9 to its
    4-digit coefficients (±3e-4)."""
    for critical in (False, True):
        low, high = fac._BENDING_LOW, fac._BENDING_HIGH[critical]
        knee = (high[0] / low[0]) ** (1.0 / (low[1] - high[1]))
        assert 2e6 < knee < 4e6
        below = fac.bending_stress_cycle_factor(knee * (1 - 1e-13), critical)
        above = fac.bending_stress_cycle_factor(knee * (1 + 1e-13), critical)
        assert below == pytest.approx(above, rel=1e-12)
    assert fac.pitting_stress_cycle_factor(1e4) == pytest.approx(2.0, abs=3e-4)
    assert fac.pitting_stress_cycle_factor(1e9) == pytest.approx(1.0, abs=3e-4)


def test_every_variable_is_labelled_and_the_file_round_trips(annex_e, tmp_path):
    from geometry.core.io import write_netcdf

    for name, var in {**annex_e.data_vars, **annex_e.coords}.items():
        assert var.attrs.get("long_name"), name
        if var.dtype.kind == "f":
            assert var.attrs.get("units"), name
    tree = xr.DataTree.from_dict({"/rating": annex_e})
    back = read_netcdf(write_netcdf(tree, tmp_path / "r.nc"))
    read = back["rating"].to_dataset()
    xr.testing.assert_equal(read, annex_e)  # the writer adds its own global attributes
    assert {k: read.attrs[k] for k in annex_e.attrs} == annex_e.attrs
    for name, var in annex_e.variables.items():
        assert {k: read[name].attrs[k] for k in var.attrs} == var.attrs, name


def test_registry_lists_agma2003_and_stamps_rating():
    assert {"agma2003", "iso10300"} <= set(available_methods())
    entry = METHODS["agma2003"]
    assert "AGMA 2003-D19" in entry.title and "Annex E" in entry.source
    assert callable(entry.tables) and callable(entry.missing)
    ds = rate_load_capacity(CASE, [T1], N1, method="agma2003")
    assert ds.attrs["rating_method"] == "agma2003"
    assert ds.attrs["rating_method_title"] == entry.title


def _number(pattern: str, text: str) -> float:
    match = re.search(pattern, text)
    assert match, pattern
    return float(match.group(1))


def test_ltca_rate_prints_annex_e_stress_numbers(capsys, tmp_path):
    """The issue's acceptance command: ``ltca rate agma2003_d19_annex_e --method agma2003
    --torque 162.70 --speed 1750`` prints s_c and s_t of both members within 1 % of Annex
    E's (as printed, 0.1 MPa), in ASCII with MPa; its file's /rating says the method."""
    out = tmp_path / "agma.nc"
    argv = ["rate", CASE, "--method", "agma2003", "--torque", "162.70", "--speed", "1750"]
    assert main([*argv, "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert text.isascii() and "N/mm" not in text
    s_c = _number(r"contact stress number s_c ([\d.]+) MPa", text)
    s_t = re.search(r"^s_t \[MPa\]\s+([\d.]+)\s+([\d.]+)", text, re.M)
    assert s_c == pytest.approx(PUBLISHED["s_c"] * PSI, rel=0.01)
    np.testing.assert_allclose([float(s_t.group(1)), float(s_t.group(2))],
                               np.array(PUBLISHED["s_t"]) * PSI, rtol=0.01)
    assert read_netcdf(out)["rating"].attrs["rating_method"] == "agma2003"


def test_hypoid_offset_is_refused_and_missing_says_why():
    """A pair with offset (ISO/TR 10300-30 sample 2, a = 15 mm): missing() gives the
    reason (the chain records it), rate() refuses it naming design.a."""
    hypoid = resolve_case("iso10300_30_sample2")
    why = missing(hypoid)
    assert "hypoid offset" in why and "design.a = 15" in why
    with pytest.raises(InputError, match=r"design\.a: must be 0"):
        rate_load_capacity(hypoid, [250.0], 1200.0, method="agma2003", agma2003=_table())
    assert "[agma2003] table" in missing(resolve_case("iso10300_30_sample1"))
    assert missing(resolve_case(CASE)) == ""
    with pytest.raises(InputError, match=r"agma2003: the case has no \[agma2003\]"):
        rate_load_capacity("iso10300_30_sample1", [250.0], 1200.0, method="agma2003")


@pytest.mark.parametrize(("changes", "field"), [
    ({"accuracy_number": 12}, r"agma2003\.accuracy_number: .*\[5, 11\]"),
    ({"accuracy_number": None}, r"agma2003\.accuracy_number, dynamic_factor"),
    ({"dynamic_factor": 1.1}, r"agma2003\.accuracy_number, dynamic_factor"),
    ({"mounting": "two"}, r"agma2003\.mounting"),
    ({"reliability": 0.95}, r"agma2003\.reliability: must be one of"),
    ({"load_cycles": [1e9, 1e11]}, r"agma2003\.load_cycles"),
    ({"geometry_factor_J": [0.2]}, r"agma2003\.geometry_factor_J"),
    ({"geometry_factor_I": 0.0}, r"agma2003\.geometry_factor_I"),
    ({"overload_factor": 0.5}, r"agma2003\.overload_factor"),
    ({"crowned": "yes"}, r"agma2003\.crowned: must be true or false"),
    ({"grade": [1, 4]}, r"agma2003\.grade"),
    ({"grade": None}, r"agma2003\.s_ac: give"),
    ({"temperature": -10.0}, r"agma2003\.temperature"),
    ({"K_o": 1.0}, r"agma2003\.K_o: unknown field"),
    ({"load_cycles": [1e9, 5e3]}, r"agma2003\.load_cycles: .*stress_cycle_factor"),
])
def test_bad_fields_are_refused_naming_them(changes, field):
    table = {k: v for k, v in _table(**changes).items() if v is not None}
    with pytest.raises(InputError, match=field):
        rate_load_capacity(CASE, [T1], N1, method="agma2003", agma2003=table)


def test_a_required_field_is_named():
    table = _table()
    del table["geometry_factor_I"]
    with pytest.raises(InputError, match=r"agma2003\.geometry_factor_I: required"):
        rate_load_capacity(CASE, [T1], N1, method="agma2003", agma2003=table)


def test_the_chain_rates_by_agma2003_chosen_by_name():
    """The analysis chain's load-capacity step by the registry name: ``/rating`` is the
    method's, at the run's torque and the case's speed, equal to the direct rating; a
    case without an [agma2003] table runs without /rating and says why (a small LTCA,
    4 rolls × 8 segments, ~6 s)."""
    from contact import LTCAOptions, run_analysis

    small = LTCAOptions(rolls_per_cycle=4, segments=8)
    tree = run_analysis(CASE, [T1], options=small, geometry=False, root_stress=False,
                        mesh_interface=False, steps={"load_capacity": "agma2003"})
    rating = tree["rating"].to_dataset()
    assert rating.attrs["rating_method"] == "agma2003"
    direct = rate_load_capacity(CASE, [T1], N1, method="agma2003")
    np.testing.assert_allclose(rating["s_c"].values, direct["s_c"].values, rtol=1e-12)
    np.testing.assert_allclose(rating["s_t"].values, direct["s_t"].values, rtol=1e-12)


def test_the_chain_refuses_a_bad_table_before_the_contact_analysis():
    """A bad [agma2003] field stops ``run_analysis`` before any step runs (the rating is
    analytic: the chain rates first), naming the field."""
    from contact import run_analysis
    from geometry.case import case_from_dict

    doc = tomllib.loads(resolve_case(CASE).to_toml())
    doc["agma2003"]["accuracy_number"] = 12
    with pytest.raises(InputError, match=r"agma2003\.accuracy_number"):
        run_analysis(case_from_dict(doc), [T1], steps={"load_capacity": "agma2003"})


def test_the_docs_name_every_field_and_variable(annex_e):
    """docs/rating.md's table lists every field of the [agma2003] table, and
    docs/nomenclature.md's /rating row of the method every variable it writes."""
    from contact.load_capacity.agma2003 import FIELDS

    docs = Path(__file__).resolve().parents[1] / "docs"
    rating = (docs / "rating.md").read_text(encoding="utf-8")
    assert [f for f in FIELDS if f"`{f}`" not in rating] == []
    row = next(ln for ln in (docs / "nomenclature.md").read_text(encoding="utf-8")
               .splitlines() if '"agma2003"' in ln)
    assert [v for v in annex_e.data_vars if f"`{v}`" not in row] == []
