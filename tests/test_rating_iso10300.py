"""ISO 10300 Method B1 rating (contact.load_capacity.iso10300) against ISO/TR 10300-30:2024's
three samples.

The reference is tests/data/iso10300_30_samples.toml: the TR's printed gear data, rating
inputs and every intermediate and final value of its samples 1-3 that the public
transcription gives (its header says where from). Two paths are checked:

* :func:`contact.load_capacity.iso10300.rate_pair` fed the TR's own printed gear data: every
published
  intermediate quantity within the TR's printed precision — one unit of its last printed
  digit (the TR's own rounding of the value, half a unit, and of the numbers it computed
  it from, half a unit) plus the effect of the rounding of the printed gear data we start
  from (each rounded input moved by half a unit of its last digit, the changes added: a
  worst-case linear bound, computed here); the stresses, permissible stresses and safety
  factors within 0.5 % (issue 52);
* :func:`contact.load_capacity.iso10300.iso10300_rating` on the bundled cases
  ``iso10300_30_sample1..3``,
  whose geometry is the toolkit's own ISO 23509 blank of the same basic data (not the TR's
  printed gear data): the stresses, permissible stresses and safety factors within 0.5 %.

Where the TR is inconsistent with its own equations a test of its own states the TR's
value, ours and the arithmetic (sample 2's K*_Hα, sample 3's K_v and l_bm); sample 2's
Z_LS, which the transcription could not reproduce, is shown to follow from the clipped
contact lines. Bad ``[rating]`` values are refused naming the field, through the function
and through ``ltca rate`` (exit code 2, one line).
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.cli import main
from contact.load_capacity.iso10300 import GearData, RatingInputs, iso10300_rating, rate_pair
from contact.load_capacity.iso10300.materials import rating_material
from contact.load_capacity.iso10300.virtual_gears import contact_line_ends
from geometry.core.errors import InputError
from geometry.core.materials import DEFAULT_MATERIAL

ROOT = Path(__file__).resolve().parents[1]
DATA = tomllib.loads((ROOT / "tests" / "data" / "iso10300_30_samples.toml")
                     .read_text(encoding="utf-8"))
SAMPLES = (1, 2, 3)
#: published quantities printed in degrees (radians in the dataset)
ANGLES = {"beta_v", "alpha_vet", "beta_vb", "beta_B", "theta", "alpha_an", "gamma_a",
          "alpha_Fan"}
#: the rating's results, checked within 0.5 % (issue 52)
STRESSES = {"sigma_H0", "sigma_H", "sigma_HP", "S_H", "sigma_F0", "sigma_F", "sigma_FP",
            "S_F"}
#: published values the TR computed inconsistently with its own equations: each has a
#: test of its own below
MISPRINTS = {(2, "K_Halpha_star"), (3, "K_v")}
#: published values the TR computed from data that differ from its printed gear data by
#: more than their rounding ("0.5 % where it rounds", issue 52): sample 2's normal-section
#: gear (d_vn, d_van, d_vbn 0.005 % below ours, while its z_vn agrees) and its normal force
#: (F_n = 15298.7 N with the printed F_mt1 = 9366.1 N means α_nD = 17.742°, printed
#: 17.748°: ours 15299.2 N, +0.003 %)
ROUNDS = {(2, "d_vn"), (2, "d_van"), (2, "d_vbn"), (2, "F_n")}
STRESS_TOLERANCE = 0.005


def _sample(n: int) -> dict:
    return DATA[f"sample{n}"]


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def _gear_data(n: int, shift: str | None = None) -> GearData:
    """The TR's printed gear data of sample ``n`` (text: rounded values), the field
    ``shift`` moved up by half a unit of its last printed digit."""
    values = {}
    for name, v in _sample(n)["gear_data"].items():
        x = float(v)
        if name == shift:
            x += 0.5 * 10.0 ** -_decimals(v)
        values[name] = x if isinstance(v, str) else v
    values["h_a0"] = DATA["common"]["tool_addendum_factor"] * values["m_mn"]
    return GearData.from_degrees(**values)


def _rounded_fields(n: int) -> list[str]:
    return [k for k, v in _sample(n)["gear_data"].items() if isinstance(v, str)]


def _inputs(n: int, **override) -> RatingInputs:
    return RatingInputs(**{**DATA["common"]["rating"], **_sample(n)["rating"], **override})


def _rate_tr(n: int, shift: str | None = None, **override) -> xr.Dataset:
    """rate_pair on the TR's printed data of sample ``n`` (its density 7.86e-6 kg/mm³).
    Sample 3 takes the TR's printed K_v = 1.000 as given: its published downstream values
    were computed with it (test_sample3_dynamic_factor_misprint)."""
    s = _sample(n)
    if n == 3:
        override.setdefault("dynamic_factor", 1.0)
    mat = dataclasses.replace(rating_material(DEFAULT_MATERIAL),
                              density=DATA["common"]["density"])
    return rate_pair(_gear_data(n, shift), _inputs(n, **override), [s["operating"]["torque"]],
                     s["operating"]["pinion_speed"], (mat, mat))


def _value(ds: xr.Dataset, name: str) -> np.ndarray:
    """Our value of a published quantity, in the TR's units (degrees for angles)."""
    ds = ds.isel(torque=0)
    if name == "a_v":  # centre distance of the virtual gears (d_v1 + d_v2)/2
        return np.atleast_1d(0.5 * float(ds["d_v"].sum()))
    if name == "middle_line_ends":  # (x1, y1, x2) of the middle contact line
        return contact_line_ends(float(ds["f"][1]), float(ds["beta_vb"]), float(ds["gamma"]),
                                 float(ds["g_va"]), float(ds["b_veff"]))[:3]
    v = np.atleast_1d(ds[{"Z_v": "Z_speed"}.get(name, name)].values).astype(float)
    return np.degrees(v) if name in ANGLES else v


def _published(n: int, names=None):
    """(name, index, printed text) of sample ``n``'s published values."""
    for name, printed in _sample(n)["published"].items():
        if names is not None and name not in names:
            continue
        for i, text in enumerate([printed] if isinstance(printed, str) else printed):
            if text:
                yield name, i, text


INTERMEDIATES = [(n, name, i, text) for n in SAMPLES for name, i, text in _published(n)
                 if name not in STRESSES and (n, name) not in MISPRINTS]
RESULTS = [(n, name, i, text) for n in SAMPLES for name, i, text in _published(n, STRESSES)]
#: what the bundled cases must give within 0.5 % (issue 62): the stresses and the tooth form
#: and stress correction factors
CASE_RESULTS = [(n, name, i, text) for n in SAMPLES
                for name, i, text in _published(n, STRESSES | {"Y_Fa", "Y_Sa"})]


@pytest.fixture(scope="module")
def tr_runs():
    """Per sample: the rating of the TR's printed data and of each rounded input moved by
    half a unit of its last digit."""
    return {n: (_rate_tr(n), {f: _rate_tr(n, f) for f in _rounded_fields(n)})
            for n in SAMPLES}


@pytest.fixture(scope="module")
def case_runs():
    return {n: iso10300_rating(f"iso10300_30_sample{n}") for n in SAMPLES}


@pytest.mark.parametrize(("n", "name", "i", "text"), INTERMEDIATES,
                         ids=[f"s{n}-{name}-{i}" for n, name, i, _ in INTERMEDIATES])
def test_intermediate_values_at_the_printed_precision(tr_runs, n, name, i, text):
    """Every published intermediate quantity from the TR's printed gear data, within one
    unit of the last printed digit plus the propagated rounding of that data."""
    base, shifted = tr_runs[n]
    ours = _value(base, name)
    ours = float(ours[i] if ours.size > 1 else ours[0])
    spread = 0.0
    for ds in shifted.values():
        moved = _value(ds, name)
        spread += abs(float(moved[i] if moved.size > 1 else moved[0]) - ours)
    tolerance = 10.0 ** -_decimals(text) + spread
    if (n, name) in ROUNDS:
        tolerance = max(tolerance, STRESS_TOLERANCE * abs(float(text)))
    assert abs(ours - float(text)) <= tolerance, (
        f"sample {n} {name}[{i}]: TR {text}, ours {ours:.6g}, tolerance {tolerance:.3g} "
        f"(input rounding {spread:.3g})")


@pytest.mark.parametrize(("n", "name", "i", "text"), RESULTS,
                         ids=[f"s{n}-{name}-{i}" for n, name, i, _ in RESULTS])
def test_stresses_from_the_printed_gear_data(tr_runs, n, name, i, text):
    ours = _value(tr_runs[n][0], name)
    ours = float(ours[i] if ours.size > 1 else ours[0])
    assert ours == pytest.approx(float(text), rel=STRESS_TOLERANCE), (
        f"sample {n} {name}[{i}]: TR {text}, ours {ours:.5g}")


@pytest.mark.parametrize(("n", "name", "i", "text"), CASE_RESULTS,
                         ids=[f"s{n}-{name}-{i}" for n, name, i, _ in CASE_RESULTS])
def test_stresses_of_the_bundled_cases(case_runs, n, name, i, text):
    """The bundled case rates the toolkit's own ISO 23509 blank (sample 3's at the TR's gear
    pitch angle, test_sample3_case_has_the_published_pitch_cone) with the TR's inputs,
    sample 3's printed K_v = 1.000 among them (``[rating] dynamic_factor``,
    test_sample3_dynamic_factor_misprint): every printed stress, permissible stress and
    safety factor, and Y_Fa and Y_Sa, within 0.5 % (issue 62)."""
    ds = case_runs[n]
    ours = _value(ds, name)
    ours = float(ours[i] if ours.size > 1 else ours[0])
    assert ours == pytest.approx(float(text), rel=STRESS_TOLERANCE), (
        f"sample {n} {name}[{i}]: TR {text}, ours {ours:.5g}")


def test_sample1_acceptance_values(case_runs):
    """Issue 52's acceptance line: σ_H 1712.8 and σ_F 680.1 / 700.1 N/mm² of sample 1
    (the case's own blank: 1713.1 and 680.2 / 700.2)."""
    ds = case_runs[1].isel(torque=0)
    assert float(ds["sigma_H"]) == pytest.approx(1712.8, rel=STRESS_TOLERANCE)
    assert ds["sigma_F"].values == pytest.approx([680.1, 700.1], rel=STRESS_TOLERANCE)


def test_sample3_case_has_the_published_pitch_cone(case_runs):
    """ISO 23509's Method 2 reaches its closing condition (pinion apex on the line from the
    gear apex through the cutter centre) by an iteration that stops at a tolerance: Annex
    F sample 3 prints δ2 = 63.212°, 0.3 % short of it (exact closure 63.145°). The bundled
    case gives that δ2 (``[design] delta2``); the hypoid pitch cone through it then
    reproduces what Annex F and the TR print from it and the exact closure does not:
    R_m2 82.168, R_e2 95.168, b1 31.139, δ_a1 24.765 (Annex F, printed to 0.001) and the
    TR's δ1 24.763, d_v 56.448 / 325.506 (to its rounding of δ1, 0.002°, and 0.05 %)."""
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.rating import case_gear_data

    ds = case_runs[3].isel(torque=0)
    _, blank = case_gear_data(resolve_case("iso10300_30_sample3"))
    p = blank.pitch
    assert math.degrees(p.delta2) == pytest.approx(63.212, abs=1e-9)
    assert p.Rm2 == pytest.approx(82.168, abs=1e-3)
    assert p.Re2 == pytest.approx(95.168, abs=1e-3)
    assert blank.pinion.b == pytest.approx(31.139, abs=1e-3)
    assert math.degrees(p.delta1) == pytest.approx(24.763, abs=3e-3)
    assert ds["d_v"].values == pytest.approx([56.448, 325.506], rel=5e-4)
    # the exact closure, for comparison: d_v2 0.23 % below the TR's
    exact = rate_pair(*_case_without_delta2(), [250.0], 4500.0, _materials())
    assert float(exact["d_v"][1]) == pytest.approx(325.506 * (1 - 0.0023), rel=3e-4)


def _case_without_delta2():
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.rating import case_gear_data, case_rating_inputs
    from geometry.case import case_from_dict

    case = resolve_case("iso10300_30_sample3")
    doc = tomllib.loads(case.to_toml())
    doc["design"].pop("delta2")
    case = case_from_dict(doc)
    return case_gear_data(case)[0], case_rating_inputs(case, None)


def _materials():
    mat = rating_material(DEFAULT_MATERIAL)
    return mat, mat


def test_sample3_case_gives_the_tr_dynamic_factor_beside_method_b(case_runs):
    """Issue 74: the bundled sample 3 gives the TR's printed K_v = 1.000 as a sourced input
    (``[rating] dynamic_factor`` and ``source``, written by
    cases/derive_iso10300_samples.py); the rating uses it, says so in the variable's clause
    and records Method B's 1.049 (N K + 1 at the TR's N 0.084, K 0.589) beside it. With it
    the case reproduces the TR's σ_H 1609.2 and σ_F 568.9 / 590.5 N/mm² directly (measured:
    1609.6, 568.2 / 591.4); without it, by Method B, σ_H is √1.049 and σ_F 1.049 times
    those (σ_H ∝ √K_v, σ_F ∝ K_v, K_Hα = 1 at a_rel 0.433), to round-off."""
    import json

    from contact.catalogue import resolve_case

    ds = case_runs[3].isel(torque=0)
    table = resolve_case("iso10300_30_sample3").extra["rating"]
    assert table["dynamic_factor"] == 1.0 and "K_v = 1.000" in table["source"]
    assert float(ds["K_v"]) == 1.0
    assert "[rating] dynamic_factor" in ds["K_v"].attrs["clause"]
    given = json.loads(case_runs[3].attrs["given_load_factors"])
    assert set(given) == {"K_v"}
    assert given["K_v"]["given"] == 1.0 and given["K_v"]["field"] == "dynamic_factor"
    k_v_b = given["K_v"]["computed"][0]
    assert k_v_b == pytest.approx(float(ds["N"] * ds["K"]) + 1.0, rel=1e-12)
    assert k_v_b == pytest.approx(1.0494, abs=5e-4)
    assert float(ds["sigma_H"]) == pytest.approx(1609.2, rel=STRESS_TOLERANCE)
    assert ds["sigma_F"].values == pytest.approx([568.9, 590.5], rel=STRESS_TOLERANCE)
    table = {k: v for k, v in table.items() if k not in ("dynamic_factor", "source")}
    method_b = iso10300_rating("iso10300_30_sample3", rating=table)
    assert "given_load_factors" not in method_b.attrs
    method_b = method_b.isel(torque=0)
    assert float(method_b["K_v"]) == pytest.approx(k_v_b, rel=1e-12)
    assert float(method_b["sigma_H"]) == pytest.approx(
        float(ds["sigma_H"]) * math.sqrt(k_v_b), rel=1e-12)
    assert method_b["sigma_F"].values == pytest.approx(ds["sigma_F"].values * k_v_b,
                                                       rel=1e-12)


def test_sample2_transverse_load_factor_misprint(tr_runs):
    """Sample 2 prints K*_Hα = 0.900. ISO 10300-1 Method B (ε_vγ > 2):
    K*_Hα = 0.9 + 0.4 √(2(ε_vγ − 1)/ε_vγ) c_γ (f_pt − y_α) / (F_mtH / b_v), f_pt and y_α
    in µm, gives 1.208 — the same formula that gives sample 1's printed 1.161. Taking
    f_pt − y_α in mm gives 0.900: a unit slip. Without effect: a_rel = 0.211 ≥ 0.1 makes
    K_Hα = K* − (K* − 1) = 1 whatever K* is, and the TR prints K_Hα = 1.000."""
    ds = tr_runs[2][0].isel(torque=0)
    eps, b_v, f_mtH = float(ds["eps_vg"]), float(ds["b_v"]), float(ds["F_mtH"])
    f_pt = 23.5  # the larger of pinion and gear [um]
    y_a = min(0.075 * f_pt, 3.0)
    x_um = 20.0 * (f_pt - y_a) / (f_mtH / b_v)  # c_gamma = 20 N/(mm um), C_F = 1
    star_um = 0.9 + 0.4 * math.sqrt(2.0 * (eps - 1.0) / eps) * x_um
    star_mm = 0.9 + 0.4 * math.sqrt(2.0 * (eps - 1.0) / eps) * x_um * 1e-3
    assert float(ds["K_Halpha_star"]) == pytest.approx(star_um, rel=1e-12)
    assert star_um == pytest.approx(1.208, abs=1e-3)
    assert round(star_mm, 3) == float(_sample(2)["published"]["K_Halpha_star"])  # 0.900
    assert float(ds["a_rel"]) >= 0.1 and float(ds["K_Halpha"]) == 1.0
    # sample 1, no offset: the µm reading is the printed 1.161
    assert float(tr_runs[1][0]["K_Halpha_star"].isel(torque=0)) == pytest.approx(1.161,
                                                                                 abs=1e-3)


def test_sample3_dynamic_factor_misprint(tr_runs):
    """Sample 3 prints N = 0.084, K = 0.589 and K_v = 1.000, but Method B's subcritical
    range (N ≤ 0.75) gives K_v = N K + 1 = 0.084 × 0.589 + 1 = 1.049. The TR computed on
    with 1.000: its F_mtH = F_vmt K_A K_v K_Hβ = 11567.5 × 1.1 × 1.000 × 1.65 = 20995.2 N
    (with 1.049: 22033 N). Our Method B reproduces N and K and gives 1.049; given the TR's
    K_v = 1.000 it reproduces F_mtH, K*_Hα = 1.109 and σ_H = 1609.2 N/mm² (the other tests
    of this module).

    The standard's text, as far as it can be checked here: ISO 10300-1's Method B has one
    formula per range of N (subcritical N K + 1, main resonance, intermediate,
    supercritical) and no branch that gives 1 for N > 0 (K_v = 1 is Method A's or the
    user's choice, ``[rating] dynamic_factor``). The TR itself applies the subcritical
    formula to samples 1 and 2 (also subcritical): their printed K_v 1.020 and 1.016 are
    N K + 1 of their own N and K. So 1.000 in sample 3 is not a different reading of the
    method but a value the TR set; the bundled case gives it as such, a sourced input
    (``[rating] dynamic_factor`` = 1.0 with its ``source``), and records Method B's 1.049
    beside it (test_sample3_case_gives_the_tr_dynamic_factor_beside_method_b)."""
    for n, printed in ((1, 1.020), (2, 1.016)):
        other = tr_runs[n][0].isel(torque=0)
        assert float(other["N"]) < 0.75  # subcritical, as sample 3
        assert float(other["K_v"]) == pytest.approx(float(other["N"] * other["K"]) + 1.0,
                                                    rel=1e-12)
        assert float(other["K_v"]) == pytest.approx(printed, abs=1e-3)
    pub = _sample(3)["published"]
    ds = _rate_tr(3, dynamic_factor=None).isel(torque=0)
    n_tr, k_tr = float(pub["N"]), float(pub["K"])
    assert float(ds["N"]) == pytest.approx(n_tr, abs=1e-3)
    assert float(ds["K"]) == pytest.approx(k_tr, abs=1e-3)
    assert float(ds["K_v"]) == pytest.approx(n_tr * k_tr + 1.0, abs=1e-3)  # 1.049
    assert float(ds["K_v"]) == pytest.approx(1.049, abs=1e-3)
    assert float(pub["K_v"]) == 1.0
    # the TR's F_mtH from its printed F_vmt (rounded to 0.1 N): 20995.0 against 20995.2
    assert 11567.5 * 1.1 * 1.000 * 1.65 == pytest.approx(float(pub["F_mtH"]), rel=1e-4)
    assert float(ds["F_mtH"]) == pytest.approx(11567.5 * 1.1 * 1.049 * 1.65, rel=1e-3)


def test_sample3_middle_contact_line_is_clipped_at_the_face_edge(tr_runs):
    """Sample 3 prints the middle line's ends x1 = 19.918, y1 = −6.712, x2 = 0.000 mm and
    l_bm = 21.377 mm. ISO 10300-1's Formula A.30 as the transcription reads it,
    x2 = [f cos β_vb + tan β_vb (f sin β_vb + b_v,eff/2) − (g_vα − b_v,eff tan γ)/2] /
    (tan γ + tan β_vb), gives x2 = −2.094 mm, beyond the face edge x = 0: the whole line
    l_b0 = 25.620 mm, and l_bm = 23.228 mm with the transcription's correction
    (+8.7 %, σ_H0 +4 %), 23.623 mm with ours. The TR clips the line at the edge: so does
    contact.load_capacity.iso10300 (the line inside the zone of action, l_b0 = 23.183 mm), which
    gives its
    x2 = 0 and l_bm = 21.376 mm."""
    ds = tr_runs[3][0].isel(torque=0)
    f, bvb, gam = float(ds["f"][1]), float(ds["beta_vb"]), float(ds["gamma"])
    g, b, b_v, fmax = (float(ds[k]) for k in ("g_va", "b_veff", "b_v", "f_max"))
    tb, cb, sb, tg = math.tan(bvb), math.cos(bvb), math.sin(bvb), math.tan(gam)
    bracket = f * cb + tb * (f * sb + 0.5 * b)
    x1 = (bracket + 0.5 * (g + b * tg)) / (tg + tb)
    x2 = (bracket - 0.5 * (g - b * tg)) / (tg + tb)
    y1, y2 = -x1 * tb + bracket, -x2 * tb + bracket
    l_b0 = math.hypot(x1 - x2, y1 - y2)
    k = 1.0 - math.sqrt(b / b_v)
    r2 = (f / fmax) ** 2
    assert x2 == pytest.approx(-2.094, abs=1e-3)
    assert l_b0 == pytest.approx(25.620, abs=1e-3)
    assert l_b0 * (1.0 - math.sqrt(r2 + k * k * (1.0 - r2))) == pytest.approx(23.228, abs=1e-3)
    assert l_b0 * (1.0 - k * math.sqrt(1.0 - r2)) == pytest.approx(23.623, abs=1e-3)
    ends = contact_line_ends(f, bvb, gam, g, b)
    assert ends[0] == pytest.approx(x1, abs=1e-9)  # the same end x1 = 19.916 inside
    assert ends[2] == pytest.approx(0.0, abs=1e-9)  # the TR's x2 = 0.000
    assert float(ds["l_b0"][1]) == pytest.approx(23.183, abs=1e-3)
    assert float(ds["l_bm"]) == pytest.approx(21.377, abs=2e-3)


def test_sample2_load_sharing_factor_follows_from_clipped_lines(tr_runs):
    """Sample 2 prints Z_LS = 0.703, which the transcription calls a limitation of its
    reading (unclipped lines, l_b = l_b0 [1 − √((f/f_max)² + k² (1 − (f/f_max)²))],
    k = 1 − √(b_v,eff/b_v): 0.776). With the tip and root lines clipped to the zone of
    action and l_b = l_b0 [1 − k √(1 − (f/f_max)²)] (contact.load_capacity.iso10300.virtual_gears),
    the
    TR's 0.703 follows; the same reading gives samples 1 and 3 (0.935, 0.961)."""
    ds = tr_runs[2][0].isel(torque=0)
    bvb, gam = float(ds["beta_vb"]), float(ds["gamma"])
    g, b, b_v, fmax = (float(ds[k]) for k in ("g_va", "b_veff", "b_v", "f_max"))
    tb, cb, sb, tg = math.tan(bvb), math.cos(bvb), math.sin(bvb), math.tan(gam)
    k = 1.0 - math.sqrt(b / b_v)
    areas = []
    for f in ds["f"].values:
        bracket = f * cb + tb * (f * sb + 0.5 * b)
        x1 = (bracket + 0.5 * (g + b * tg)) / (tg + tb)
        x2 = (bracket - 0.5 * (g - b * tg)) / (tg + tb)
        l_b0 = math.hypot(x1 - x2, tb * (x1 - x2))
        r2 = (f / fmax) ** 2
        areas.append((1.0 - abs(f / fmax) ** 3) * l_b0 * (1.0 - math.sqrt(r2 + k * k * (1 - r2))))
    assert math.sqrt(areas[1] / sum(areas)) == pytest.approx(0.776, abs=1e-3)
    assert float(ds["Z_LS"]) == pytest.approx(0.703, abs=1e-3)
    # the tip and root lines: clipped, 9.369 mm inside the zone; unclipped 14.532 mm
    assert ds["l_b0"].values == pytest.approx([9.369, 14.532, 9.369], abs=1e-3)


# --------------------------------------------------------------------------- the output


def test_dataset_says_what_every_variable_is(case_runs):
    """Every variable of /rating has units, a long name and the clause it comes from; the
    names the verdicts (issue 56) read are there."""
    ds = case_runs[1]
    for name, var in ds.data_vars.items():
        assert "units" in var.attrs and var.attrs.get("long_name"), name
        assert var.attrs.get("clause"), name
    for name in ("S_H", "S_F", "S_Hmin", "S_Fmin"):
        assert name in ds.data_vars
    assert ds["S_F"].dims == ("torque", "member") and ds["S_H"].dims == ("torque", "member")


def test_rating_round_trip(case_runs, tmp_path):
    from geometry.core.io import read_netcdf, without_stamps, write_netcdf

    ds = case_runs[3]
    path = write_netcdf(ds, tmp_path / "rating.nc")
    back = read_netcdf(path)
    xr.testing.assert_identical(without_stamps(back, ds), ds)


def test_torques_broadcast_and_scale():
    """σ_H0 ∝ √T and σ_F0 ∝ T (Method B1 is linear in the force up to the load factors)."""
    ds = iso10300_rating("iso10300_30_sample1", torque=[150.0, 300.0, 600.0], pinion_speed=1200.0)
    s_h0, s_f0 = ds["sigma_H0"].values, ds["sigma_F0"].values
    assert s_h0[2] / s_h0[1] == pytest.approx(math.sqrt(2.0), rel=1e-12)
    assert s_f0[0] / s_f0[1] == pytest.approx([0.5, 0.5], rel=1e-12)


# --------------------------------------------------------------------------- refusals

BAD_RATING = [
    ("application_factor", -1.0, ["rating.application_factor", "[1, 5]"]),
    ("application_factor", "high", ["rating.application_factor"]),
    ("mounting", "loose", ["rating.mounting", "both", "one", "neither"]),
    ("contact_pattern", "guessed", ["rating.contact_pattern"]),
    ("single_pitch_deviation", [12.0, -3.0], ["rating.single_pitch_deviation"]),
    ("flank_roughness", 0.0, ["rating.flank_roughness"]),
    ("nu40", 1.0, ["rating.nu40", "[2, 5000]"]),
    ("quality_grade", "MX", ["rating.quality_grade"]),
    ("min_safety_bending", 0.0, ["rating.min_safety_bending"]),
    ("side", "left", ["rating.side"]),
    ("accuracy_grade", 6, ["rating.single_pitch_deviation", "both"]),
    ("unknown_field", 1.0, ["rating.unknown_field", "unknown field"]),
    ("dynamic_factor", 0.9, ["rating.dynamic_factor", "[1, 3]"]),
    ("face_load_factor_contact", math.nan, ["rating.face_load_factor_contact", "[1, 3]"]),
    ("face_load_factor_bending", "1.5", ["rating.face_load_factor_bending"]),
    ("transverse_load_factor_contact", 3.5, ["rating.transverse_load_factor_contact",
                                             "[1, 3]"]),
    ("transverse_load_factor_bending", math.inf, ["rating.transverse_load_factor_bending",
                                                  "[1, 3]"]),
]


def _sample1_table() -> dict:
    raw = tomllib.loads((ROOT / "cases" / "iso10300_30_sample1.toml").read_text("utf-8"))
    return dict(raw["rating"])


@pytest.mark.parametrize(("field", "value", "words"), BAD_RATING,
                         ids=[f"{f}-{v}" for f, v, _ in BAD_RATING])
def test_bad_rating_value_refused_by_the_function(field, value, words):
    table = {**_sample1_table(), field: value}
    with pytest.raises(InputError) as err:
        iso10300_rating("iso10300_30_sample1", rating=table)
    for w in words:
        assert w in str(err.value)


def test_given_load_factors_replace_the_computed_ones():
    """Issue 74: each load factor may be given in [rating]. On sample 3 (K_Hα = 1 by the
    offset, a_rel 0.433, so σ_H ∝ √(K_Hβ K_Hα) and σ_F ∝ K_Fβ K_Fα hold exactly): a given
    K_Hβ carries K_Fβ = K_Hβ/K_F0 with it (ISO 10300-1 cl. 8), a given K_Hα is K_Fα too
    (Method B's one value), a given K_Fβ or K_Fα moves σ_F alone; each is recorded in
    ``given_load_factors`` beside the computed value (a following one with ``follows``)."""
    import json

    from contact.catalogue import resolve_case

    table = dict(resolve_case("iso10300_30_sample3").extra["rating"])
    base = iso10300_rating("iso10300_30_sample3", rating=table).isel(torque=0)
    h0, f0, k_f0 = float(base["sigma_H"]), base["sigma_F"].values, float(base["K_F0"])
    assert float(base["K_Hbeta"]) == pytest.approx(1.65, rel=1e-12)
    assert float(base["K_Halpha"]) == 1.0 and float(base["K_Falpha"]) == 1.0

    def rated(**given):
        ds = iso10300_rating("iso10300_30_sample3", rating={**table, **given})
        return ds.isel(torque=0), json.loads(ds.attrs["given_load_factors"])

    ds, rec = rated(face_load_factor_contact=1.8)
    assert float(ds["K_Hbeta"]) == 1.8
    assert float(ds["K_Fbeta"]) == pytest.approx(1.8 / k_f0, rel=1e-12)
    assert float(ds["sigma_H"]) == pytest.approx(h0 * math.sqrt(1.8 / 1.65), rel=1e-12)
    assert ds["sigma_F"].values == pytest.approx(f0 * 1.8 / 1.65, rel=1e-12)
    assert rec["K_Hbeta"]["computed"] == pytest.approx(1.65, rel=1e-12)
    assert rec["K_Fbeta"]["computed"] == pytest.approx(1.65 / k_f0, rel=1e-12)
    assert "follows" in rec["K_Fbeta"] and "given" not in rec["K_Fbeta"]

    ds, rec = rated(face_load_factor_bending=1.5)
    assert float(ds["sigma_H"]) == pytest.approx(h0, rel=1e-12)
    assert ds["sigma_F"].values == pytest.approx(f0 * 1.5 / (1.65 / k_f0), rel=1e-12)
    assert set(rec) == {"K_v", "K_Fbeta"}

    ds, rec = rated(transverse_load_factor_contact=1.2)
    assert float(ds["K_Falpha"]) == 1.2
    assert float(ds["sigma_H"]) == pytest.approx(h0 * math.sqrt(1.2), rel=1e-12)
    assert ds["sigma_F"].values == pytest.approx(f0 * 1.2, rel=1e-12)
    assert rec["K_Halpha"]["computed"] == [1.0] and "follows" in rec["K_Falpha"]

    ds, _ = rated(transverse_load_factor_contact=1.2, transverse_load_factor_bending=1.1)
    assert ds["sigma_F"].values == pytest.approx(f0 * 1.1, rel=1e-12)
    assert "[rating] transverse_load_factor_bending" in ds["K_Falpha"].attrs["clause"]


def test_cli_prints_the_given_load_factors(capsys):
    """``ltca rate`` says which load factors the case gives and what the method computes
    beside them (sample 3: the TR's K_v 1.000, Method B 1.049), not the Method B note."""
    assert main(["rate", "iso10300_30_sample3"]) == 0
    out = capsys.readouterr().out
    assert ("given load factors: K_v 1.000 ([rating] dynamic_factor; ISO 10300-1:2014 "
            "cl. 7 (Method B) gives 1.049)") in out
    assert "K_v Method B: resonance ratio" not in out
    assert "load factors: K_A 1.100  K_v 1.000" in out


@pytest.mark.parametrize("field", ["application_factor", "mounting"])
def test_required_rating_field_missing(field):
    table = {k: v for k, v in _sample1_table().items() if k != field}
    with pytest.raises(InputError, match=rf"rating\.{field}: missing"):
        RatingInputs.from_mapping(table)


def test_missing_nu40_refused():
    """No ν40 given and none from the case's oil: refused naming rating.nu40 (rate_pair
    never guesses it)."""
    inputs = _inputs(1, nu40=None)
    with pytest.raises(InputError, match=r"rating\.nu40: missing"):
        rate_pair(_gear_data(1), inputs, [300.0], 1200.0)


def test_case_without_design_table_refused():
    from geometry.case import case_from_dict

    raw = tomllib.loads((ROOT / "cases" / "iso10300_30_sample1.toml").read_text("utf-8"))
    del raw["design"]
    with pytest.raises(InputError, match=r"^design: .*\[design\] table"):
        iso10300_rating(case_from_dict(raw))


def _case_file(tmp_path: Path, old: str, new: str) -> Path:
    text = (ROOT / "cases" / "iso10300_30_sample1.toml").read_text(encoding="utf-8")
    text, n = re.subn(old, new, text, count=1, flags=re.M)
    assert n == 1, old
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    return path


CLI_BAD = [
    ("K_A-negative", r"^application_factor = .*$", "application_factor = -1.1",
     ["rating.application_factor", "-1.1"]),
    ("mounting-unknown", r"^mounting = .*$", 'mounting = "loose"', ["rating.mounting"]),
    ("nu40-missing", r"^nu40 = .*\n", "", ["rating.nu40", "missing"]),
    ("no-rating-table", r"^\[rating\]\n", "[not_rating]\n", ["rating", "no [rating] table"]),
]


@pytest.mark.parametrize(("old", "new", "words"), [c[1:] for c in CLI_BAD],
                         ids=[c[0] for c in CLI_BAD])
def test_bad_rating_value_refused_by_the_command(tmp_path, capsys, old, new, words):
    path = _case_file(tmp_path, old, new)
    if "nu40" in words[0]:  # and an oil that gives no viscosity at 40 degC
        text = path.read_text(encoding="utf-8").replace('lubricant = "75W90"',
                                                        'lubricant = "SAE90"')
        path.write_text(text, encoding="utf-8")
    code = main(["rate", str(path)])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err


# --------------------------------------------------------------------------- ltca rate


def _row(out: str, label: str) -> list[float]:
    line = next(ln for ln in out.splitlines() if ln.startswith(label))
    return [float(x) for x in line[len(label):].split()]


def test_cli_acceptance_line(capsys):
    """``ltca rate iso10300_30_sample1 --torque 300 --speed 1200`` prints σ_H 1712.8 and
    σ_F 680.1 / 700.1 N/mm² (ISO/TR 10300-30 sample 1) within 0.5 %."""
    assert main(["rate", "iso10300_30_sample1", "--torque", "300", "--speed", "1200"]) == 0
    out = capsys.readouterr().out
    assert _row(out, "sigma_H [MPa]") == pytest.approx([1712.8], rel=STRESS_TOLERANCE)
    assert _row(out, "sigma_F [MPa]") == pytest.approx([680.1, 700.1],
                                                         rel=STRESS_TOLERANCE)
    assert _row(out, "Z_LS") == pytest.approx([0.935], abs=1e-3)


def test_cli_writes_the_rating_group(tmp_path, capsys):
    path = tmp_path / "f.nc"
    assert main(["rate", "iso10300_30_sample3", "-o", str(path)]) == 0
    assert f"wrote {path}" in capsys.readouterr().out
    with xr.open_dataset(path, group="rating", engine="netcdf4") as ds:
        assert ds.sizes["member"] == 2 and ds.sizes["line"] == 3
        for name, var in ds.data_vars.items():
            assert var.attrs.get("units") is not None, name
            assert var.attrs.get("long_name") and var.attrs.get("clause"), name
        assert float(ds["sigma_H0"].isel(torque=0)) == pytest.approx(1194.5,
                                                                     rel=STRESS_TOLERANCE)


def test_static_range_takes_the_film_factors_as_one():
    """ISO 6336-2 (and ISO 10300-2 cl. 8 after it): Z_L Z_v Z_R are 1 for the static stress
    and their calculated values at the knee, log-linear in N_L between; bending likewise
    Y_R,relT and Y_X (ISO 6336-3). Sample 1 (Z_L Z_v Z_R = 0.992 · 0.974 · 0.930 = 0.899):
    at N_L = 10⁵ (the contact curve's static end) σ_HP = σ_Hlim Z_NT,stat Z_K = 1500 · 1.6 ·
    1.2 = 2880 N/mm², not 0.899 × that; at the knee and beyond, the TR's 1617.8; halfway in
    log N_L, half the exponent; the long-life permissible cycles solve σ_HP(N) = S_min σ_H
    on that curve."""
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.rating import case_rating_inputs

    case = resolve_case("iso10300_30_sample1")
    inputs = case_rating_inputs(case, None)

    def rated(n):
        return iso10300_rating(case, rating=dataclasses.replace(inputs, load_cycles=n)).isel(
            torque=0)

    long = rated(None)
    zlvr = float(long["Z_L"][0] * long["Z_speed"][0] * long["Z_R"][0])
    assert zlvr == pytest.approx(0.992 * 0.974 * 0.930, abs=2e-3)
    static = rated(1e5)
    assert static["sigma_HP"].values[0] == pytest.approx(1500.0 * 1.6 * 1.2, rel=1e-12)
    assert rated(1e9)["sigma_HP"].values[0] == pytest.approx(1617.8, abs=0.05)
    mid = rated(math.sqrt(1e5 * 5e7))  # halfway between static end and knee in log N_L
    assert mid["sigma_HP"].values[0] == pytest.approx(
        1500.0 * 1.2 * math.sqrt(1.6) * math.sqrt(zlvr), rel=1e-12)
    # bending (pinion): Y_R,relT Y_X = 1 at the static end 10³, Y_δ,relT kept
    yrx = float(long["Y_RrelT"][0] * long["Y_X"][0])
    static_f = rated(1e3)
    assert static_f["sigma_FP"].values[0] == pytest.approx(
        long["sigma_FP"].values[0] * 2.5 / yrx, rel=1e-12)
    # the permissible cycles land on the curve: σ_HP(N_H) = S_Hmin σ_H at a torque whose
    # long-life S_H is 0.944 (sample 1's), pinion
    n_h = float(long["permissible_cycles_pitting"].values[0])
    assert 1e5 < n_h < 5e7
    at = rated(n_h)
    assert float(at["sigma_HP"][0]) == pytest.approx(
        float(at["S_Hmin"]) * float(at["sigma_H"]), rel=1e-9)


def test_dynamic_factor_warning_names_the_loads_in_the_main_resonance_range(caplog):
    """The warning gives the N of the loads in the main resonance range (0.75, 1.25], not
    the largest N of all torques (issue 62: 'N = 1.31 in the main resonance range' while
    the loads in it had N = 1.06). Sample 1 at 30000 rpm: N = 3.38 (5 N·m, supercritical),
    1.07 and 0.95 (50 and 300 N·m, main resonance) — the stiffness correction C_F of the
    light load raises its N."""
    import logging

    with caplog.at_level(logging.WARNING, logger="contact.load_capacity.iso10300.factors"):
        ds = iso10300_rating("iso10300_30_sample1", torque=[5.0, 50.0, 300.0], pinion_speed=30000.0)
    n = ds["N"].values
    assert n[0] > 1.5 and 0.75 < n[1] <= 1.25 and 0.75 < n[2] <= 1.25
    text = " ".join(r.getMessage() for r in caplog.records if "resonance" in r.getMessage())
    assert f"N = {n[1]:.3g}, {n[2]:.3g} in the main resonance range" in text
    assert "at 2 of 3 loads" in text
    assert f"{n[0]:.3g}" not in text


def test_one_roughness_for_the_rating_and_the_ltca():
    """A [rating] table without flank_roughness rates the flanks at the case's own Rq (the
    LTCA's and the film's): Rz = 6 Ra (DIN 3990/3991's approximation) with Ra = √(2/π) Rq
    (Gaussian heights), 4.79 Rq — Rz 3.83 µm for the default case's Rq 0.8 µm, not the
    former default 8 µm; a table that gives it keeps it (the TR's samples: Rz 8, 3)."""
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.rating import RZ_PER_RQ, case_rating_inputs

    assert RZ_PER_RQ == pytest.approx(6.0 * math.sqrt(2.0 / math.pi), rel=1e-15)
    case = resolve_case(None)
    assert "flank_roughness" not in case.extra["rating"]
    rz = case_rating_inputs(case).flank_roughness
    assert rz == pytest.approx((3.830, 3.830), abs=1e-3)
    assert rz[0] == pytest.approx(RZ_PER_RQ * case.operating.roughness, abs=5e-4)
    assert case_rating_inputs(resolve_case("iso10300_30_sample3")).flank_roughness == (3.0, 3.0)


def test_capacity_is_the_long_life_one_whatever_the_load_cycles():
    """The capacity torque (S_H or S_F at its minimum at long life) does not depend on the
    [rating] load_cycles: below the knee σ_HP is not Z_NT times its long-life value (Z_L
    Z_v Z_R go to 1 towards the static end), so the capacity rates without them (1e-9: the
    same root search)."""
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.capacity import capacity_torque

    case = resolve_case("iso10300_30_sample1")
    table = dict(case.extra["rating"])
    long = capacity_torque(case, rating=table)
    assert capacity_torque(case, rating={**table, "load_cycles": 3e5}) == pytest.approx(
        long, rel=1e-9)


def test_cli_says_where_the_flank_roughness_comes_from(capsys):
    """``ltca rate`` of the default case (no flank_roughness in its [rating]) says the
    flanks' Rz is its Rq as Rz = 6 √(2/π) Rq; a case that gives it (the TR's sample 1) says
    nothing of it."""
    assert main(["rate"]) == 0
    out = capsys.readouterr().out
    assert ("flank roughness Rz 3.83 / 3.83 um: the case's [operating] roughness Rq 0.8 um "
            "(the flanks the analysis runs) as Rz = 6 Ra = 6 sqrt(2/pi) Rq") in out
    assert main(["rate", "iso10300_30_sample1", "--torque", "300", "--speed", "1200"]) == 0
    assert "flank roughness Rz" not in capsys.readouterr().out


# --------------------------------------------------------------------------- non-generated


def _non_generated_teeth():
    """(m_mn, h_am, x_hm, x_sm, h_a0, rho_a0, alpha) of two straight-sided tool copies:
    sample 3's gear (TR data) and a deep, thin tooth with a large edge radius."""
    g = _gear_data(3)
    return [(g.m_mn, g.h_am2, g.x_hm2, g.x_sm2, g.h_a0, 1.2, g.alpha_eD),
            (5.0, 3.5, -0.3, -0.08, 6.25, 2.0, math.radians(17.0))]


@pytest.mark.parametrize("tooth", _non_generated_teeth(), ids=["sample3-gear", "deep"])
def test_non_generated_form_from_the_tool_copied_slot(tooth):
    """The non-generated tooth form against a direct construction of the slot the blade
    copies (issue 74): in the normal section the tooth's right flank is the line
    x = (π/4 + x_sm) m − (y − x_hm m) tan α, the slot bottom the tool tip line
    y = x_hm m − h_a0, rounded with the edge radius ρ_a0 tangent to both; the 30° tangent
    point is the point of that outline where the line at 30° to the tooth's centre line
    touches it (the minimum of x cos 30° + y sin 30° over a dense outline), and the load at
    the tip corner along the flank normal meets the centre line at y = h_am − x_a tan α.
    The fillet radius there is the edge radius (identity); s_Fn and h_Fa agree to the
    outline's sampling: the arc's step ρ_a0 Δφ (< 1e-5 mm) moves the tangent point by at
    most that, s_Fn by twice it."""
    from contact.load_capacity.iso10300.bending import non_generated_tooth_form

    m, h_am, x_hm, x_sm, h_a0, rho, alpha = tooth
    ta = math.tan(alpha)

    def flank_x(y):
        return (0.25 * math.pi + x_sm) * m - (y - x_hm * m) * ta

    y_root = x_hm * m - h_a0
    yc = y_root + rho
    xc = flank_x(yc) + rho / math.cos(alpha)  # the centre ρ off the flank, in the slot
    phi = np.linspace(math.pi + alpha, 1.5 * math.pi, 400001)
    arc = np.stack([xc + rho * np.cos(phi), yc + rho * np.sin(phi)])
    y_flank = np.linspace(yc - rho * math.sin(alpha), h_am, 20001)
    flank = np.stack([flank_x(y_flank), y_flank])
    bottom = np.stack([np.linspace(xc, 0.5 * math.pi * m, 2001), np.full(2001, y_root)])
    outline = np.concatenate([arc, flank, bottom], axis=1)
    k = np.argmin(math.cos(math.pi / 6) * outline[0] + math.sin(math.pi / 6) * outline[1])
    x30, y30 = outline[:, k]
    assert math.hypot(x30 - xc, y30 - yc) == pytest.approx(rho, abs=1e-12)  # on the fillet
    x_a = flank_x(h_am)
    h_fa = h_am - x_a * ta - y30

    form = non_generated_tooth_form(m, [h_am], [x_hm], [x_sm], [h_a0], [rho], [0.0], alpha,
                                    alpha)
    assert float(form.rho_F[0]) == rho
    step = rho * (phi[1] - phi[0])
    assert float(form.s_Fn[0]) == pytest.approx(2.0 * x30, abs=2.0 * step)
    assert float(form.h_Fa[0]) == pytest.approx(h_fa, abs=step)
    assert float(form.alpha_Fan[0]) == alpha


@pytest.mark.parametrize("tooth", _non_generated_teeth(), ids=["sample3-gear", "deep"])
def test_generated_form_tends_to_the_non_generated_one(tooth):
    """A tool-copied slot is what a generated one becomes with no roll left to generate:
    ISO 10300-3's generated equations on a virtual gear of z_vn teeth (involute of the
    tool's pressure angle) converge to the non-generated s_Fn, h_Fa, ρ_F and Y_Fa as z_vn
    grows, their difference falling as 1/z_vn (×10 teeth: ÷10 ± 20 %)."""
    from contact.load_capacity.iso10300.bending import non_generated_tooth_form, tooth_form

    m, h_am, x_hm, x_sm, h_a0, rho, alpha = tooth
    rack = non_generated_tooth_form(m, [h_am], [x_hm], [x_sm], [h_a0], [rho], [0.0], alpha,
                                    alpha)
    errors = []
    for z in (1e3, 1e4, 1e5):
        d = z * m
        gen = tooth_form(m, [z], [d + 2.0 * h_am], [d * math.cos(alpha)], [x_hm], [x_sm],
                         h_a0, rho, 0.0, alpha, alpha)
        errors.append(np.array([float(getattr(gen, k)[0] - getattr(rack, k)[0])
                                for k in ("s_Fn", "h_Fa", "rho_F", "Y_Fa")]))
    assert np.all(np.abs(errors[2]) < 2e-3)
    assert np.abs(errors[1]) / np.abs(errors[2]) == pytest.approx(np.full(4, 10.0), rel=0.2)


def test_tr_samples_rate_their_gears_as_generated(tr_runs):
    """The TR's printed gear q_s (2.166, 2.073, 2.118) and Y_Sa are the generated fillet's
    (the intermediate tests), not the non-generated one's: the edge radius 1.2 mm as the
    fillet gives q_s 3.008, 2.427, 3.796 — so the bundled samples give ``process =
    "Generate"`` (cases/derive_iso10300_samples.py), although their gears are cut Formate
    for the contact analysis."""
    for n, q_gear in ((1, 3.008), (2, 2.427), (3, 3.796)):
        ds = _rate_tr(n, process=["Generate", "Formate"]).isel(torque=0)
        assert float(ds["q_s"][1]) == pytest.approx(q_gear, abs=1e-3)
        printed = float(_sample(n)["published"]["q_s"][1])
        assert abs(float(ds["q_s"][1]) - printed) > 0.3
        assert float(tr_runs[n][0]["q_s"][1]) == pytest.approx(printed,
                                                                              abs=2e-3)
        assert float(ds["rho_F"][1]) == 1.2 and float(ds["non_generated"][1]) == 1.0
        assert float(ds["Y_Fa"][0]) == float(tr_runs[n][0]["Y_Fa"][0])


def test_a_formate_gear_is_rated_by_its_edge_radius():
    """A case whose [rating] table leaves ``process`` out is rated by its members' own:
    the default case's Formate gear gets the non-generated tooth form, its fillet radius
    the gear blade's edge radius (0.813 mm, where the generated equations give 1.37 mm: a
    generating roll widens the fillet beyond the edge radius), the pinion the generated
    one; the bundled samples keep the TR's generated gears."""
    from contact.catalogue import resolve_case
    from contact.load_capacity.iso10300.rating import case_rating_inputs

    case = resolve_case(None)
    assert (case.pinion.process, case.gear.process) == ("Generate", "Formate")
    assert "process" not in case.extra["rating"]
    inputs = case_rating_inputs(case)
    assert inputs.process == ("Generate", "Formate")
    ds = iso10300_rating(case).isel(torque=0)
    assert ds["non_generated"].values.tolist() == [0.0, 1.0]
    assert float(ds["rho_F"][1]) == float(ds["edge_radius"][1]) == 0.813
    generated = iso10300_rating(case, rating=dataclasses.replace(
        inputs, process=("Generate", "Generate"))).isel(torque=0)
    assert float(generated["rho_F"][1]) > float(ds["rho_F"][1]) + 0.3
    assert float(generated["rho_F"][0]) == float(ds["rho_F"][0])
    assert resolve_case("iso10300_30_sample1").extra["rating"]["process"] == "Generate"


def test_cli_names_the_non_generated_member(capsys):
    """``ltca rate`` of the default case prints the tooth form's s_Fn, h_Fa, ρ_F and says
    its gear is rated non-generated, its fillet the edge radius (0.813 mm); the TR's
    sample 1, rated generated, says nothing of it."""
    assert main(["rate"]) == 0
    out = capsys.readouterr().out
    assert ("tooth form of the gear: non-generated (Formate), its root fillet the cutter's "
            "edge radius (ISO 10300-3)") in out
    assert _row(out, "rho_F [mm]")[1] == 0.813
    assert main(["rate", "iso10300_30_sample1"]) == 0
    assert "non-generated" not in capsys.readouterr().out
