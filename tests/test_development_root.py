"""The development's root-stress capacity (issue 71 item 2, contact/optimize/
development_root.py) against hand calculations on hand-made ``/ltca`` + ``/rating``
(built as in tests/test_verdict_checks.py).

The synthetic analysis is a root stress linear in the torque (σ_FE,max = c·T, the first-
order model the capacity step assumes) and a K_v of ISO 10300-1 Method B's form,
K_v = 1 + k/T (K_v − 1 ∝ 1/(F/b)). The safety is the verdict's own
(:func:`contact.study.verdict_checks.root_stress_safety`), so the test checks the capacity
arithmetic and the stepping; the tolerances are exact arithmetic (1e-12) or the 0.1 N·m the
capacity is rounded down to.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from contact.optimize import development_root as dr
from contact.study.verdict_checks import root_stress_safety

MAT = "case_carburised_steel"
FP = 425 * 2 * 1.0 * 0.99 * 0.98 * 1.0  # σ_FP = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X [MPa]
K_A = 1.25


def _tree(torques, c=(5.0, 4.0), k_v=10.0):
    """Root stress c·T [MPa] per member, K_v = 1 + k_v/T, S_Fmin 1.3."""
    t = np.asarray(torques, float)
    lt = xr.Dataset({"root_stress_max": (("torque", "member"), np.outer(t, c))},
                    coords={"torque": t, "member_label": ("member", ["pinion", "gear"])},
                    attrs={"material_pinion": MAT, "material_gear": MAT})
    rt = xr.Dataset({"sigma_FP": ("member", [FP, FP]), "K_A": K_A,
                     "K_v": ("torque", 1.0 + k_v / t), "S_Fmin": 1.3,
                     "Y_NT": ("member", [1.0, 1.0]), "design_torque": t[-1]},
                    coords={"torque": t})
    return xr.DataTree.from_dict({"/": xr.Dataset(), "/ltca": lt, "/rating": rt})


def test_capacity_step_by_hand():
    """The 10x43's numbers: 357 N·m, S_F,FE 1.20 against 1.3, margin 0.99:
    357·0.99·1.20/1.3 = 326.243 N·m, rounded down to 326.2."""
    assert dr.root_capacity_step(357.0, 1.20, 1.3) == 326.2
    assert dr.root_capacity_step(100.0, 1.3, 1.3, margin=1.0) == 100.0
    with pytest.raises(ValueError, match="S_Fmin"):
        dr.root_capacity_step(100.0, 1.2, 0.0)
    with pytest.raises(ValueError, match="S_F,FE"):
        dr.root_capacity_step(100.0, math.nan, 1.3)


def test_root_safety_is_the_verdicts():
    """At 100 N·m: pinion 500 MPa, K_v 1.1: σ_F,FE = 500·1.25·1.1 = 687.5 MPa,
    S_F,FE = 824.67/687.5 = 1.1995 (the weaker member); gear 400 MPa: 1.499."""
    s, s_min, member = dr.root_safety(_tree([15.0, 100.0]))
    assert member == "pinion" and s_min == 1.3
    np.testing.assert_allclose(s[-1], FP / 687.5, rtol=1e-12)
    rt = _tree([100.0])["/rating"].to_dataset()
    np.testing.assert_allclose(s[-1], root_stress_safety(np.array([[500.0, 400.0]]), rt)[0, 0],
                               rtol=1e-12)


def test_lowered_torque_holds(monkeypatch):
    """T_cap = 100·0.99·1.1995/1.3 = 91.35 → 91.3 N·m; there σ = 456.5 MPa, K_v
    = 1 + 10/91.3 = 1.10953, S_F,FE = 824.67/(456.5·1.25·1.10953) = 1.3025 ≥ 1.3: one
    step; the case's torques become (0.15·91.3, 91.3) and the source says why."""
    monkeypatch.setattr(dr, "_root_tree", lambda case, torques: _tree(torques))
    setup = {"torques": [15.0, 100.0], "source": "the ISO 10300 capacity, the pinion torque"}
    lines: list[str] = []
    tree, s, text = dr.root_capacity(None, setup, 0.15, lines.append)
    assert setup["torques"] == [pytest.approx(0.15 * 91.3), 91.3] and setup["lowered"]
    hand = FP / (5.0 * 91.3 * K_A * (1.0 + 10.0 / 91.3))
    assert s == pytest.approx(hand, rel=1e-12) and s >= 1.3
    assert "S_F,FE 1.20 (pinion) below S_Fmin 1.3 at the design torque 100 N m" in text
    assert "-> 91.3 N m, where S_F,FE is 1.30" in text and "still below" not in text
    assert setup["source"] == text and tree is not None


def test_second_step_when_kv_grows(monkeypatch):
    """A strong K_v (1 + 60/T): at 100 N·m S = 824.67/(500·1.25·1.6) = 0.8247;
    T1 = 100·0.99·0.8247/1.3 = 62.80 → 62.8, K_v 1.9554, S = 824.67/(314·1.25·1.9554)
    = 1.0745 < 1.3: a second step, T2 = 62.8·0.99·1.0745/1.3 = 51.38 → 51.3, where
    S = 824.67/(256.5·1.25·2.1696) = 1.1855, still below after the two steps allowed:
    said so."""
    monkeypatch.setattr(dr, "_root_tree", lambda case, torques: _tree(torques, k_v=60.0))
    setup = {"torques": [15.0, 100.0], "source": "the ISO 10300 capacity"}
    _, s, text = dr.root_capacity(None, setup, 0.15, lambda line: None)
    assert setup["torques"][1] == 51.3
    assert s == pytest.approx(FP / (5.0 * 51.3 * K_A * (1.0 + 60.0 / 51.3)), rel=1e-12)
    assert "(still below)" in text


def test_nothing_lowered_when_it_holds(monkeypatch):
    """S_F,FE 824.67/(300·1.25·1.1) = 1.999 ≥ 1.3 at 100 N·m: the torque stays."""
    monkeypatch.setattr(dr, "_root_tree", lambda case, torques: _tree(torques, c=(3.0, 2.0)))
    setup = {"torques": [15.0, 100.0], "source": "the ISO 10300 capacity"}
    tree, s, text = dr.root_capacity(None, setup, 0.15, lambda line: None)
    assert tree is None and text == "" and "lowered" not in setup
    assert s == pytest.approx(FP / (300.0 * K_A * 1.1), rel=1e-12)
