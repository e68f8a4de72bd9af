"""The verdict's ``edge_pressure`` check (issue 71): an edge whose peak pressure exceeds the
static strength of the flank it bears on, at every torque the run analyses, on either flank.

Before it nothing judged ``ltca run``'s ``p_max edge`` column: the face-hobbed spiral
bevel 20x24 at Σ 100° (round 17) written with its coast design torque lowered to 169.4 N·m
(branch coastlte77, without the lead's gate) peaked 2488 MPa on its pinion edge, above the
2400 MPa static strength, and ``ltca run --flank coast`` said only the edge's 0.52 % share;
the ``flank_pressure`` check judges the contact curves (860 MPa there) only.

References independent of the code under test: σ_Hlim and the static life factor read
from the material table with ``tomllib``; the edge peaks as numpy maxima of the dataset's
``pressure_max`` over each edge kind's segments; the shares by
:func:`contact.ltca.summary.edge_load_share` (``kinds=``), a separately tested function.
"""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.chain import AnalysisChain
from contact.ltca import LTCAOptions
from contact.ltca.summary import edge_load_share
from contact.pipeline import run_analysis
from contact.study.verdicts import CHECKS, EDGE_SHARE_MIN, verdict
from geometry.case import load_case

MATERIAL = "case_carburised_steel"
LIMIT = 5262.0  # [MPa] the edges' contact-pressure limit of the material (a plastic edge)
LOWERED = Path(__file__).parent / "data" / "fh_spiral_bevel_20x24_s100_coast_lowered_case.toml"


def _static() -> float:
    """σ_Hlim at MQ × the static life factor Z_NT, from the material table itself."""
    text = (resources.files("geometry.core") / "data" / "materials.toml").read_text("utf-8")
    m = tomllib.loads(text)[MATERIAL]
    grades = m["allowable_stress"]["grades"]
    return (m["allowable_stress"]["contact_allowable"][grades.index("MQ")]
            * m["sn_contact"]["static_life_factor"])


def _tree(ds: xr.Dataset) -> xr.DataTree:
    return xr.DataTree.from_dict({"/ltca": ds})


def _mesh(edge_p: float, edge_force: float = 1.0, flank: str = "convex",
          kind: str = "pinion_edge") -> xr.Dataset:
    """One torque, one roll, one pair: a contact curve (force 99 at 860 MPa) and an edge
    segment of ``kind`` (``edge_force`` at ``edge_p`` MPa), unit arms."""
    force = np.array([99.0, edge_force]).reshape(1, 1, 1, 2)
    p = np.array([860.0, edge_p]).reshape(1, 1, 1, 2)
    return xr.Dataset(
        {"pressure_max_flank": ("torque", [860.0]),
         "pressure_max_edge": ("torque", [edge_p]),
         "pressure_max": (("torque", "roll", "pair", "segment"), p),
         "force": (("torque", "roll", "pair", "segment"), force),
         "moment_arm": (("roll", "pair", "segment"), np.ones((1, 1, 2)))},
        coords={"torque": [169.4], "segment_kind": ("segment", ["curve", kind])},
        attrs={"material_pinion": MATERIAL, "material_gear": MATERIAL,
               "edge_pressure_limit_MPa": LIMIT, "flank_pressure_limit_MPa": np.nan,
               "pinion_flank": flank})


def _edge_findings(ds: xr.Dataset) -> list:
    return [f for f in verdict(_tree(ds)).findings if f.check == "edge_pressure"]


def test_an_edge_above_the_static_strength_is_an_attention_on_either_flank():
    static = _static()  # 2400 MPa
    assert static == 2400.0
    (f,) = _edge_findings(_mesh(static + 1.0))
    assert f.severity == "attention"
    assert f.reason.startswith(f"edge peak pressure above the flank's static strength "
                               f"{static:.0f} MPa")
    assert f"{static + 1:.0f} MPa on the pinion edge at 169.4 N·m" in f.reason
    assert f"the edges' limit {LIMIT:.0f} MPa" in f.reason
    # the flank in contact does not matter: the coast (convex) as the drive (concave)
    assert _edge_findings(_mesh(static + 1.0, flank="concave")) == [f]
    # at the static strength itself, no finding; the edge's share is the edge_contact
    # check's and the flank's own check says nothing either way (its curve at 860 MPa is
    # below σ_Hlim): all the verdict said
    v = verdict(_tree(_mesh(static)))
    assert [f.check for f in v.findings] == ["edge_contact"] and "edge_pressure" in v.checks
    assert "edge_pressure" in CHECKS["analysis"]


def test_an_edge_below_the_discretisation_or_at_its_plastic_limit_is_not_this_finding():
    static = _static()
    # the edge carries less than EDGE_SHARE_MIN of the torque: the discretisation's load
    small = EDGE_SHARE_MIN * 99.0 * 0.9  # its share just below the minimum
    ds = _mesh(static + 500.0, edge_force=small)
    assert float(edge_load_share(ds, kinds=("pinion_edge",))[0]) < EDGE_SHARE_MIN
    assert _edge_findings(ds) == []
    # at the edges' contact-pressure limit the edge is plastic: plastic_edges says it
    plastic = _mesh(LIMIT).assign(plastic_load_share=(("torque", "roll"), [[0.01]]))
    checks = [f.check for f in verdict(_tree(plastic)).findings]
    assert "plastic_edges" in checks and "edge_pressure" not in checks


def test_a_dataset_without_segments_is_judged_on_its_edge_peak():
    static = _static()
    ds = _mesh(static + 88.0).drop_vars(["pressure_max", "force", "moment_arm",
                                         "segment_kind"])
    (f,) = _edge_findings(ds)
    assert f"{static + 88:.0f} MPa at 169.4 N·m" in f.reason and "pinion edge" not in f.reason


def test_the_lowered_coast_bearing_of_the_20x24_is_flagged():
    """The real case (tests/data, the coast flank at its light and lowered coast design
    torque, a coarse mesh cycle): its pinion edge above the static strength at 169.4 N·m,
    its contact curves far below σ_Hlim, so the verdict's only word on it was the edge's
    share."""
    case = load_case(LOWERED)
    tree = run_analysis(case, [90.4, 169.4], flank="coast",
                        options=LTCAOptions(rolls_per_cycle=6, cycles=1),
                        steps=AnalysisChain.analysis().without(
                            "geometry", "root_stress", "mesh_interface"))
    lt = tree["ltca"].to_dataset()
    assert lt.attrs["pinion_flank"] == "convex"  # the coast flank of a concave drive
    static = _static()
    kind = np.asarray(lt["segment_kind"].values).astype(str)
    p = np.nan_to_num(lt["pressure_max"].transpose("torque", ...).values)
    edge = p[..., kind == "pinion_edge"].reshape(2, -1).max(axis=1)
    share = edge_load_share(lt, kinds=("pinion_edge",))
    # 2487 MPa at 6 rolls (2488 at ltca run's 40), above 2400; the curves ~860 MPa
    assert edge[1] > static > 1.5 * float(lt["pressure_max_flank"].max())
    assert edge[1] == pytest.approx(2488.0, rel=0.01)
    assert share[1] >= EDGE_SHARE_MIN and edge[0] < static
    v = verdict(tree)
    assert not [f for f in v.findings if f.check == "flank_pressure"]
    (f,) = [f for f in v.findings if f.check == "edge_pressure"]
    assert f.severity == "attention"
    assert f"{edge[1]:.0f} MPa on the pinion edge at 169.4 N·m" in f.reason
    assert "90.4 N·m" not in f.reason


def _duty(edge_p: list[float], share: list[float], plastic: list[float]) -> xr.Dataset:
    """Three bins of a duty cycle: the variables the duty check reads, the static strength
    per bin and member as the duty cycle stores it (the weaker member's judged)."""
    static = _static()
    return xr.Dataset(
        {"torque": ("bin", [100.0, 200.0, 300.0]), "hours": ("bin", [1.0, 1.0, 1.0]),
         "pressure_max_edge": ("bin", edge_p), "edge_load_share": ("bin", share),
         "plastic_load_share": ("bin", plastic),
         "contact_static_strength": (("bin", "member"),
                                     [[static, static + 50.0]] * 3),
         "contact_safety_factor": ("member", [1.2, 1.3])},
        coords={"member": ["pinion", "gear"]}, attrs={"illustrative": 0})


def test_a_duty_cycle_says_its_bins_edges_above_the_static_strength():
    """``ltca duty-cycle`` prints each bin's edge peak: judged as ``ltca run``'s (the bins'
    total edge share; a plastic bin is the plastic_edges check's)."""
    static = _static()
    ds = _duty([static + 10.0, static + 10.0, LIMIT], [0.01, 0.1 * EDGE_SHARE_MIN, 0.02],
               [0.0, 0.0, 0.01])
    v = verdict(ds)
    assert v.kind == "duty cycle" and "edge_pressure" in v.checks
    (f,) = [f for f in v.findings if f.check == "edge_pressure"]
    assert f.severity == "attention"
    assert f"in 1 of 3 bins: {static + 10:.0f} MPa in bin 0 (100 N·m, static strength " \
        f"{static:.0f} MPa)" in f.reason
    assert "plastic_edges" in {g.check for g in v.findings}
    # at the static strength: no finding; a file without the variables: no check
    assert not [f for f in verdict(_duty([static] * 3, [0.01] * 3, [0.0] * 3)).findings
                if f.check == "edge_pressure"]
    old = verdict(ds.drop_vars("contact_static_strength"))
    assert "edge_pressure" in dict(old.unchecked)
