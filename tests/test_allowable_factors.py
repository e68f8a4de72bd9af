"""σ_HP,∞ taken apart (contact.load_capacity.iso10300.allowable_factors, issue 71, branch
pitlim85): the product against ISO/TR 10300-30's printed factors, the lowest factor named,
and the hypoid factor held at its lower bound 0.6 as on the unseen hypoid 11×43 at Σ 100°,
a = 0.25 d_e2 (docs/own_gear_set.md, "The 11×43's local pitting limit")."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.load_capacity.iso10300 import iso10300_rating
from contact.load_capacity.iso10300.allowable_factors import (
    contact_allowable_factors,
    contact_allowable_text,
)
from contact.load_capacity.iso10300.pitting import hypoid_factor

ROOT = Path(__file__).resolve().parents[1]
DATA = tomllib.loads((ROOT / "tests" / "data" / "iso10300_30_samples.toml")
                     .read_text(encoding="utf-8"))


def _printed(n: int, name: str) -> float:
    v = DATA[f"sample{n}"]["published"][name]
    return float(v[0] if isinstance(v, list) else v)


@pytest.mark.parametrize(("n", "lowest"), [(2, "Z_R"), (3, "Z_Hyp")])
def test_the_product_is_the_trs_printed_factors_and_names_the_lowest(n, lowest):
    """σ_HP,∞ = σ_Hlim Z_L Z_v Z_R Z_Hyp Z_K (Z_X = Z_W = 1) from the TR's printed factors
    and σ_Hlim (1500, 1510 MPa) of samples 2 and 3 (each printed to 3 decimals: 5
    factors at ±0.0005 relative to ≈ 0.9 give ≤ 0.3 %, so 0.5 %, the rating's stress
    tolerance of issue 52); the lowest factor is the TR's smallest printed one: sample
    2's Z_R 0.939 (below its Z_Hyp 0.952), sample 3's Z_Hyp 0.829."""
    ds = iso10300_rating(f"iso10300_30_sample{n}")
    a = contact_allowable_factors(ds)
    printed = {s: _printed(n, s) for s in ("Z_L", "Z_v", "Z_R", "Z_Hyp")}
    s_hlim = DATA[f"sample{n}"]["rating"]["sigma_Hlim"][0]
    hand = s_hlim * math.prod(printed.values()) * 1.2
    assert a.sigma_HP == pytest.approx(hand, rel=0.005)
    assert a.lowest == lowest == min(printed, key=printed.get)
    assert not a.hypoid_at_bound
    assert f"its lowest factor {lowest}" in contact_allowable_text(ds)


def _rating(v_g_par: float, v_sum_vert: float) -> xr.Dataset:
    """A rating with the 11×43's long-life factors (its `ltca rate` at 280.3 N·m, n1 1500
    rpm) and the given sliding velocities [m/s]."""
    z_hyp = float(np.clip(1.0 - 0.3 * (v_g_par / v_sum_vert - 0.15), 0.6, 1.0))
    member = ("member", [1500.0, 1500.0])
    two = ("member", [1.0, 1.0])
    return xr.Dataset({
        "sigma_Hlim": member, "Z_X": two, "Z_W": two,
        "Z_L": ("member", [0.9608, 0.9608]), "Z_speed": ("member", [0.9736, 0.9736]),
        "Z_R": ("member", [1.0020, 1.0020]), "Z_K": ((), 1.2), "Z_Hyp": ((), z_hyp),
        "v_g_par": ((), v_g_par), "v_sum_vert": ((), v_sum_vert)})


def test_the_hypoid_factor_held_at_its_bound_is_said():
    """The 11×43's sliding, v_g,par 2.968 and v_Σ,vert 1.860 m/s (its rating): the
    standard's 1 − 0.3 (v_g,par/v_Σ,vert − 0.15) = 1 − 0.3 (1.5957 − 0.15) = 0.5663 by
    hand, below 0.6, so Z_Hyp is held at 0.6 and σ_HP,∞ = 1500 × 0.9608 × 0.9736 × 1.0020
    × 1.2 × 0.6 = 1012.3 MPa (the rating printed 1012.3; 0.05 % for the factors' 4
    decimals)."""
    ds = _rating(2.968, 1.860)
    a = contact_allowable_factors(ds)
    assert a.hypoid_unclipped == pytest.approx(1.0 - 0.3 * (2.968 / 1.860 - 0.15), abs=1e-12)
    assert a.hypoid_unclipped == pytest.approx(0.5663, abs=5e-4)
    assert a.hypoid_at_bound and a.lowest == "Z_Hyp" and a.factors["Z_Hyp"] == 0.6
    assert a.sigma_HP == pytest.approx(1012.3, rel=5e-4)
    text = contact_allowable_text(ds)
    assert text.startswith("sigma_HP 1012 MPa = sigma_Hlim 1500 x Z_Hyp 0.60 x Z_K 1.2")
    assert "v_g,par 1.60 x the sum velocity v_Sigma,vert" in text
    assert "the formula's 0.566 held at its lower bound 0.6" in text


def test_a_hypoid_factor_inside_its_range_is_not_said_held():
    """pc_hypoid_10x43's sliding (v_g,par 1.206, v_Σ,vert 3.071 m/s, its rating): Z_Hyp
    1 − 0.3 (0.3928 − 0.15) = 0.9272 by hand, inside [0.6, 1]; still the lowest factor."""
    a = contact_allowable_factors(_rating(1.206, 3.071))
    assert a.factors["Z_Hyp"] == pytest.approx(0.9272, abs=5e-4)
    assert a.lowest == "Z_Hyp" and not a.hypoid_at_bound
    assert "held" not in contact_allowable_text(_rating(1.206, 3.071))


def test_the_hypoid_factor_of_the_11x43_by_the_standards_formula():
    """pitting.hypoid_factor on the 11×43's mean-point data (its rating): β_m1 50°, β_m2
    14.25°, β_B 13.51° and the drive flank's generated pressure angle α_nD 6.90° = α_dD
    22.5° + f_alim α_lim, α_lim −15.60° (ISO 23509; the effective α_eD is 22.5°). Written
    out from ISO 10300-2:2014 cl. 6: v_g = v cos β_m1 (tan β_m1 − tan β_m2), v_g,par =
    v_g cos β_B, v_Σh = 2 v cos β_m1 sin α_n, v_Σl = v (sin β_m1 + sin β_m2 cos β_m1 /
    cos β_m2), v_Σ,vert = |v_Σ| sin(atan(v_Σh/v_Σl) + β_B); v = v_mt1 5.064 m/s. The
    formula gives 0.566 (to 1e-3: the angles' 2 decimals), below 0.6, so 0.6. With α_eD
    22.5° in place of α_nD it would give 0.79: α_n is the angle the TR's samples 2 and 3
    printed (0.952, 0.829; α_e gives 0.958, 0.859), so the low value is the design's
    α_lim, not the angle chosen."""
    b1, b2, bb, an = (math.radians(x) for x in (50.0, 14.25, 13.51, 6.90))
    v = 5.064
    vg = v * math.cos(b1) * (math.tan(b1) - math.tan(b2))
    vh = 2.0 * v * math.cos(b1) * math.sin(an)
    vl = v * (math.sin(b1) + math.sin(b2) * math.cos(b1) / math.cos(b2))
    vert = math.hypot(vh, vl) * math.sin(math.atan2(vh, vl) + bb)
    raw = 1.0 - 0.3 * (vg * math.cos(bb) / vert - 0.15)
    z, slide = hypoid_factor(50.0, v, b1, b2, bb, an)
    assert slide["v_sum_vert"] == pytest.approx(vert, rel=1e-12)
    assert slide["v_g_par"] == pytest.approx(vg * math.cos(bb), rel=1e-12)
    assert raw == pytest.approx(0.566, abs=1e-3)
    assert z == 0.6
    z_e, _ = hypoid_factor(50.0, v, b1, b2, bb, math.radians(22.5))
    assert z_e == pytest.approx(0.792, abs=1e-3)


def _hertz_tree(torques) -> xr.DataTree:
    """An analysis whose peak flank pressure is 1500 (T/100)^(1/3) MPa (no root stress)
    with the 11×43's rating factors (:func:`_rating`), K_A 1, K_v 1.03."""
    t = np.asarray(torques, float)
    lt = xr.Dataset({"pressure_max_flank": ("torque", 1500.0 * (t / 100.0) ** (1 / 3))},
                    coords={"torque": t})
    rt = _rating(2.968, 1.860).assign(
        K_A=1.0, K_v=("torque", np.full(t.shape, 1.03)), S_Hmin=1.0).assign_coords(
        torque=t, member=["pinion", "gear"])
    return xr.DataTree.from_dict({"/": xr.Dataset(), "/ltca": lt, "/rating": rt})


def test_the_torque_cut_line_names_the_lowest_factor(monkeypatch):
    """root_capacity's line for a local pitting cut carries σ_HP,∞'s breakdown, here the
    11×43's (:func:`_rating` at its sliding, its rating's long-life factors), after the
    S_H,loc below S_Hmin; the cut itself is test_development_pitting's (a Hertzian flank,
    p_max 1500 (T/100)^(1/3) MPa against σ_HP,∞ 1012 MPa)."""
    from contact.optimize import development_root as dr

    monkeypatch.setattr(dr, "_root_tree", lambda case, torques: _hertz_tree(torques))
    monkeypatch.setattr(dr, "pitting_allowable_note",
                        lambda case, torque: contact_allowable_text(_rating(2.968, 1.860)))
    setup = {"torques": [15.0, 100.0], "source": "the ISO 10300 capacity, the pinion torque"}
    lines: list[str] = []
    _, _, text = dr.root_capacity(None, setup, 0.15, lines.append)
    assert ("below S_Hmin 1 (sigma_HP 1012 MPa = sigma_Hlim 1500 x Z_Hyp 0.60 x Z_K 1.2"
            in text)
    assert "the formula's 0.566 held at its lower bound 0.6)) at the design torque" in text
    assert text in lines[-1]


def test_no_rating_leaves_the_cut_line_as_it_was():
    """Without a case to rate, the note is empty (logged), never an error."""
    from contact.optimize import development_root as dr

    assert dr.pitting_allowable_note(None, 100.0) == ""
