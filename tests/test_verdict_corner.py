"""``ltca run``'s verdict judges the flank peak pressure the development judges (issue 71):
the ``/ltca`` dataset's ``pressure_max_flank`` without the contact curves shorter than
their own Hertz contact width 2b (:func:`contact.ltca.summary.flank_peak`) — a curve
clipped into a flank corner, µm long, whose load per length is a ratio of vanishing
numbers (it read 2577 vs 2045 MPa under a 1e-13 change of the FM 11×41's settings). The
dataset's ``pressure_max_flank`` stays as written; the verdict says what it left out.

Synthetic datasets: the expected peaks are the numbers put in (no computation), σ_Hlim
and the static life factor read from the material table with ``tomllib``."""

from __future__ import annotations

import tomllib
from importlib import resources

import numpy as np
import pytest
import xarray as xr

from contact.ltca.plausibility import plausibility_flags
from contact.ltca.summary import flank_peak, flank_peak_pressure
from contact.optimize import development_evaluate
from contact.study.verdicts import verdict

MATERIAL = "case_carburised_steel"


def _static() -> tuple[float, float]:
    """(σ_Hlim at MQ, static strength σ_Hlim·Z_NT) [MPa] from the material table."""
    text = (resources.files("geometry.core") / "data" / "materials.toml").read_text("utf-8")
    m = tomllib.loads(text)[MATERIAL]
    grades = m["allowable_stress"]["grades"]
    lim = m["allowable_stress"]["contact_allowable"][grades.index("MQ")]
    return lim, lim * m["sn_contact"]["static_life_factor"]


def _tree(p_long: float, p_corner: float, corner_length: float = 1e-5,
          edge_limit: float = 5262.0) -> xr.DataTree:
    """One torque (500 N·m), one roll, two pairs: pair 0 a curve of 4 segments 2 mm long
    at ``p_long`` (half width 0.3 mm), pair 1 a curve of 4 segments ``corner_length`` long
    each at ``p_corner`` (half width 0.44 mm: 2b = 0.88 mm, as the FM 11×41's corner
    curve). ``pressure_max_flank`` is the dataset's as :mod:`contact.ltca.dataset` writes
    it: the peak over every curve segment."""
    kind = np.array(["curve"] * 4)
    p, b, length = np.zeros((1, 1, 2, 4)), np.zeros((1, 1, 2, 4)), np.zeros((1, 2, 4))
    p[0, 0, 0], b[0, 0, 0], length[0, 0] = p_long, 0.3, 2.0
    p[0, 0, 1], b[0, 0, 1], length[0, 1] = p_corner, 0.44, corner_length
    dims = ("torque", "roll", "pair", "segment")
    ds = xr.Dataset(
        {"pressure_max": (dims, p), "half_width": (dims, b),
         "segment_length": (dims[1:], length),
         "pressure_max_flank": (("torque",), [max(p_long, p_corner)])},
        coords={"torque": [500.0], "segment_kind": ("segment", kind)},
        attrs={"material_pinion": MATERIAL, "material_gear": MATERIAL,
               "edge_pressure_limit_MPa": edge_limit, "flank_pressure_limit_MPa": np.nan})
    return xr.DataTree.from_dict({"/ltca": ds})


def test_the_development_and_the_verdict_read_one_rule():
    assert development_evaluate.flank_peak_pressure is flank_peak_pressure


def test_a_corner_curve_above_the_static_strength_fails_no_design():
    """The corner curve at static + 200 MPa, the line contact at 1400 MPa (< σ_Hlim): the
    verdict passes, a note names the dataset's number and the curve left out; the
    dataset's ``pressure_max_flank`` is unchanged."""
    lim, static = _static()
    assert (lim, static) == (1500.0, 2400.0)
    tree = _tree(1400.0, static + 200.0)
    fp = flank_peak(tree["ltca"].to_dataset())
    assert fp.pressure.tolist() == [1400.0] and fp.dataset.tolist() == [2600.0]
    assert fp.corner_curves.tolist() == [1]
    v = verdict(tree)
    assert v.severity == "pass" and not v.findings
    assert len(v.notes) == 1
    note = v.notes[0]
    assert "1400 MPa at 500 N·m" in note and "reads 2600 MPa with 1 contact curve" in note
    assert "shorter than its Hertz contact width 2b" in note
    assert any(line == f"  note: {note}" for line in v.lines())
    assert float(tree["ltca"]["pressure_max_flank"].values[0]) == 2600.0


def test_a_corner_curve_is_no_flank_above_the_material_limit():
    """The plausibility's flank-above-limit cause (a fail of the verdict) reads the same
    peak: a corner curve above the edge-pressure limit is no cause, a line contact is."""
    ds = _tree(1400.0, 2600.0, edge_limit=2500.0)["ltca"].to_dataset()
    assert not plausibility_flags(ds)["flank_above_limit"].any()
    ds = _tree(2550.0, 2600.0, edge_limit=2500.0)["ltca"].to_dataset()
    assert plausibility_flags(ds)["flank_above_limit"].tolist() == [True]


@pytest.mark.parametrize("corner", [0.0, 2600.0])
def test_a_long_curve_above_the_static_strength_fails_as_before(corner):
    """The line contact at 2450 MPa (> 2400): FAIL on its own number; where the corner
    curve reads more, the reason names the dataset's 2600 MPa and the curve left out."""
    v = verdict(_tree(2450.0, corner))
    assert v.severity == "fail"
    (f,) = [f for f in v.findings if f.check == "flank_pressure"]
    assert f.severity == "fail" and "flank peak pressure 2450 MPa at 500 N·m" in f.reason
    assert ("reads 2600 MPa with 1 contact curve" in f.reason) == bool(corner)
    assert not v.notes


def test_a_corner_curve_long_enough_is_a_line_contact_and_fails():
    """The same curve 4 × 0.25 mm long (1 mm ≥ 2b = 0.88 mm) is a line contact: FAIL."""
    v = verdict(_tree(1400.0, 2600.0, corner_length=0.25))
    assert v.severity == "fail" and "2600 MPa at 500 N·m" in v.findings[0].reason


@pytest.mark.parametrize(("corner_force", "left_out"), [(0.26, True), (242.0, False)])
def test_a_short_curve_is_left_out_only_where_its_load_vanishes(corner_force, left_out):
    # The rule's premise (load per length a ratio of vanishing numbers) holds for a corner
    # clip carrying ~1e-5 of the roll's load (0.26 N on the 11x41), not for a short curve
    # carrying a share of it (the default case's entering curve at 500 N·m: 0.38 mm under
    # its 2b 0.50 mm, 242 N ~ 4 %): that is a concentrated contact and stays in the peak.
    # The limit is contact.ltca.summary.CORNER_LOAD_SHARE (1 %); 0.26 / 6000 and
    # 242 / 6000 lie on either side of it by more than a factor 4.
    from contact.ltca.summary import CORNER_LOAD_SHARE

    ds = _tree(1400.0, 2600.0, corner_length=1e-5)["ltca"].to_dataset()
    force = np.zeros((1, 1, 2, 4))
    force[0, 0, 0] = 6000.0 / 4
    force[0, 0, 1] = corner_force / 4
    ds["force"] = (("torque", "roll", "pair", "segment"), force)
    assert (corner_force / 6000.0 < CORNER_LOAD_SHARE) == left_out
    fp = flank_peak(ds)
    # exact: the peak is one of the two pressures put in
    assert fp.pressure[0] == (1400.0 if left_out else 2600.0)
    assert fp.corner_curves[0] == int(left_out)
