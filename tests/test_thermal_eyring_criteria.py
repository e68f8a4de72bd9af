"""The opt-in ``thermal_eyring`` against issue 74's "Done when" relations it meets.

On small LTCAs of the seed's Table 5.4 designs A and B (one mesh cycle, 6 rolls, 12
segments, 100 / 500 / 1000 N·m, cached per session by ``test_face_hobbing_chain._run``,
as tests/test_efficiency_trends.py), at 1500 rpm and 500 N·m, run-in flanks, 75W90
unless stated, against ISO/TR 14179-2 (Schlenk's correlation of FZG gear measurements,
``iso_tr_14179_2``) evaluated on the same segments:

* Rq 0.1 → 1.3 µm costs 0.5–2 × ISO/TR 14179-2's cost at 50 °C and at 90 °C (measured at
  full resolution, ``benchmarks/friction_correlation_map.py``: A 1.04 / 1.56 ×, B 1.13 /
  1.66 ×);
* at Rq 1.3 µm 100 °C is not better than 50 °C (A 97.06 against 97.87 %, B 95.25 against
  96.74 %);
* at 50 °C and Rq 0.1 µm the flank μ at 6000 rpm is below that at 1500 rpm (A 0.0123
  against 0.0260, B 0.0084 against 0.0197);
* the flank μ at the seed's point (90 °C, Rq 0.8 µm) within 0.7–1.4 × ISO/TR 14179-2's
  (A 1.23, B 1.23);
* A − B within 1.0–2.0 efficiency points there (1.41; ISO/TR 14179-2's μ gives 1.23);
* an ISO VG 220 mineral oil built from its data sheet (ν40 220, ν100 19.4 mm²/s, ρ15 890
  kg/m³: class values) within ±15 % of the 75W90's flank μ at 50 and 90 °C, Rq 0.8 µm
  (A −3.4 / −5.5 %, B −14.8 / −10.2 %).

All of them since the model's load sharing is Zhou & Hoeprich's (1991) asperity load ratio
exp(−B Λ^C) (``load_sharing="zhou_hoeprich"``, its default; docs/friction.md, "Zhou &
Hoeprich's load share"). With Johnson, Greenwood & Poon's sharing on the ground summits
(``load_sharing="johnson_greenwood_poon"``, the default before) two rows were missed and
written here as strict xfails: the roughness cost at 90 °C (A 2.43 ×, B 2.63 × ISO's) and
B's VG 220 at 90 °C (−18.2 %) — that sharing turned boundary at λ ≈ 0.1–0.15, where
deterministic mixed-EHL solutions keep 10–15 % of the load on the film.

The other rows of the "Done when" are tested elsewhere: the 75W90 rebuilt from ν40/ν100
against Table 5.2 within 5 % (tests/test_oil_data_sheet.py), the VG 220 from its data sheet
and a library oil through ``ltca run`` with the rating from another working directory
(tests/test_oil_library.py).

Tolerances: the issue's bounds themselves. At this resolution the efficiencies are within
0.02 point and the ratios to ISO within 0.04 of the full-resolution LTCAs'
(tests/test_efficiency_trends.py). The smallest margins here: B's VG 220 at 50 °C
(−14.8 %, 0.2 % of μ from the bound) and A's hot-against-cold at Rq 1.3 (−0.81 point); at
this resolution the VG 220 measures −14.8 % as at full resolution (the two oils' μ on the
same segments: the LTCA's resolution acts on both alike).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from test_face_hobbing_chain import _run

from friction.coefficient import FrictionModelRangeWarning
from friction.efficiency import efficiency_analysis
from friction.oil_data_sheet import OilDataSheet, oil_file_mapping
from friction.operating import OperatingConditions
from geometry.core.toml_files import dump_toml

CASES = ("kolivand2009_table54_A_fh", "kolivand2009_table54_B_fh")
TORQUES = (100.0, 500.0, 1000.0)
MODEL = "thermal_eyring"
ISO = "iso_tr_14179_2"
AT = 1  # the 500 N·m torque


@pytest.fixture(scope="module")
def ltcas():
    return {name: _run(name, TORQUES, 6, 12) for name in CASES}


def _result(lt, **operating):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        fr = efficiency_analysis(lt, OperatingConditions(**operating))
    force = lt["force"].fillna(0.0).where(lt["segment_kind"] == "curve", 0.0)
    dims = ("roll", "pair", "segment")
    mu = ((fr["friction_coefficient"].fillna(0.0) * force).sum(dims) / force.sum(dims)).values
    return float(mu[AT]), 100.0 * float(fr["efficiency_mean"].values[AT])


def _cost_ratio(lt, temperature):
    cost = {m: _result(lt, friction_model=m, temperature=temperature, roughness=0.1)[1]
            - _result(lt, friction_model=m, temperature=temperature, roughness=1.3)[1]
            for m in (MODEL, ISO)}
    return cost[MODEL] / cost[ISO], cost


@pytest.mark.parametrize("case", CASES)
def test_roughness_cost_at_50_degrees_within_half_to_twice_iso(ltcas, case):
    ratio, cost = _cost_ratio(ltcas[case], 50.0)
    assert 0.5 <= ratio <= 2.0, cost


@pytest.mark.parametrize("case", CASES)
def test_roughness_cost_at_90_degrees_within_half_to_twice_iso(ltcas, case):
    ratio, cost = _cost_ratio(ltcas[case], 90.0)
    assert 0.5 <= ratio <= 2.0, cost


@pytest.mark.parametrize("case", CASES)
def test_hot_oil_not_better_on_rough_flanks(ltcas, case):
    lt = ltcas[case]
    hot = _result(lt, friction_model=MODEL, temperature=100.0, roughness=1.3)[1]
    cold = _result(lt, friction_model=MODEL, temperature=50.0, roughness=1.3)[1]
    assert hot <= cold, (hot, cold)
    # as the correlation on the same segments (−0.17 / −0.28 point)
    iso = [_result(lt, friction_model=ISO, temperature=t, roughness=1.3)[1]
           for t in (100.0, 50.0)]
    assert iso[0] <= iso[1], iso


@pytest.mark.parametrize("case", CASES)
def test_full_film_friction_falls_from_1500_to_6000_rpm(ltcas, case):
    lt = ltcas[case]
    mu, iso = ([_result(lt, friction_model=m, temperature=50.0, roughness=0.1,
                        pinion_speed=n)[0] for n in (1500.0, 6000.0)] for m in (MODEL, ISO))
    assert mu[1] < mu[0], mu
    assert iso[1] < iso[0], iso  # the correlation falls too (−24 %)


@pytest.mark.parametrize("case", CASES)
def test_level_at_the_seeds_point_within_the_measured_band(ltcas, case):
    lt = ltcas[case]
    mu = _result(lt, friction_model=MODEL, temperature=90.0, roughness=0.8)[0]
    iso = _result(lt, friction_model=ISO, temperature=90.0, roughness=0.8)[0]
    assert 0.7 <= mu / iso <= 1.4, (mu, iso)


def test_a_ahead_of_b_by_one_to_two_points(ltcas):
    eff = [_result(ltcas[c], friction_model=MODEL, temperature=90.0, roughness=0.8)[1]
           for c in CASES]
    assert 1.0 <= eff[0] - eff[1] <= 2.0, eff
    # the band is the correlation's on the same segments: ISO/TR 14179-2's μ gives 1.23
    iso = [_result(ltcas[c], friction_model=ISO, temperature=90.0, roughness=0.8)[1]
           for c in CASES]
    assert 1.0 <= iso[0] - iso[1] <= 2.0, iso


@pytest.mark.parametrize(("case", "temperature"), [
    (CASES[0], 50.0), (CASES[1], 50.0), (CASES[0], 90.0), (CASES[1], 90.0)])
def test_vg220_mineral_from_its_data_sheet_ranks_within_15_percent(ltcas, case,
                                                                   temperature, tmp_path):
    sheet = OilDataSheet(name="VG220_mineral", kinematic_viscosity_40=220.0,
                         kinematic_viscosity_100=19.4, density_15=890.0, base_oil="mineral",
                         source="typical ISO VG 220 mineral EP gear oil (class values)")
    path = tmp_path / "vg220.toml"
    path.write_text(dump_toml(oil_file_mapping(sheet)), encoding="utf-8")
    lt = ltcas[case]
    ref = _result(lt, friction_model=MODEL, temperature=temperature, roughness=0.8)[0]
    vg = _result(lt, friction_model=MODEL, temperature=temperature, roughness=0.8,
                 lubricant=str(path))[0]
    assert np.isfinite(vg)
    # the correlation ranks the two oils within ±15 % on the same segments (−4 / −2 %)
    iso = [_result(lt, friction_model=ISO, temperature=temperature, roughness=0.8,
                   lubricant=oil)[0] for oil in ("75W90", str(path))]
    assert abs(iso[1] / iso[0] - 1.0) <= 0.15, iso
    assert abs(vg / ref - 1.0) <= 0.15, (vg, ref)
