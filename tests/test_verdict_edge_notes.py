"""``ltca run``'s verdict on edges that carry load below the ``edge_contact`` floor
(issue 71: "no edge contact at 15 % of the design torque"): no finding — the floor
:data:`~contact.study.verdicts.EDGE_SHARE_MIN` (0.05 % of the torque) judges the edges'
load and stays — but a note naming each loaded edge, its share and ``p_max edge``, so that
the verdict is not silent on what the table prints (the FM hypoid 13×33 at Σ 85°'s coast
pinion edge: 949 MPa carrying 0.028 % at 33.1 N·m, converged under 4× the roll positions
and 2× the segments; docs/verdicts.md, "Findings a reader trusts").

Synthetic datasets: the shares are the forces put in over their total (arms 1, so Σ F·arm
is Σ F), compared exactly; the pressures are the numbers put in."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact.study.verdicts import EDGE_SHARE_MIN, verdict

MATERIAL = "case_carburised_steel"


def _tree(edge_forces: list[float], p_edge: float = 949.0) -> xr.DataTree:
    """One torque (33.1 N·m), one roll, one pair: a contact curve of one segment carrying
    the rest of 1 N and one segment per edge kind (gear tip, heel, toe, pinion edge)
    carrying ``edge_forces`` [N], every arm 1 mm; the pinion edge at ``p_edge`` MPa where
    it is loaded."""
    kinds = np.array(["curve", "gear_tip", "gear_heel", "gear_toe", "pinion_edge"])
    force = np.asarray([[[[1.0 - sum(edge_forces), *edge_forces]]]])
    p = np.where(force > 0, 700.0, 0.0)
    p[..., 1:] = np.where(force[..., 1:] > 0, p_edge, 0.0)
    dims = ("torque", "roll", "pair", "segment")
    ds = xr.Dataset(
        {"pressure_max": (dims, p), "force": (dims, force),
         "moment_arm": (dims[1:], np.ones((1, 1, 5))),
         "segment_kind": (("segment",), kinds),
         "pressure_max_flank": (("torque",), [700.0]),
         "pressure_max_edge": (("torque",), [float(p[..., 1:].max())])},
        coords={"torque": [33.1]},
        attrs={"material_pinion": MATERIAL, "material_gear": MATERIAL,
               "edge_pressure_limit_MPa": 5262.0, "flank_pressure_limit_MPa": np.nan})
    return xr.DataTree.from_dict({"/ltca": ds})


def _edge_notes(v) -> list[str]:
    return [n for n in v.notes if n.startswith("edge_contact:")]


def test_an_edge_below_the_floor_is_noted_not_found():
    """The 13×33's coast light torque: the pinion edge carrying 0.0278 % of the torque at
    949 MPa — no ``edge_contact`` finding (below 0.05 %), the verdict's severity as
    without it, one note with the edge, its share and the pressure."""
    v = verdict(_tree([0.0, 0.0, 0.0, 2.78e-4]))
    assert not [f for f in v.findings if f.check == "edge_contact"]
    notes = _edge_notes(v)
    assert notes == ["edge_contact: at 33.1 N·m edges carry load below the 0.05 % of the "
                     "torque a finding counts (pinion edge 0.028 %; p_max edge 949 MPa): "
                     "edge contact all the same by issue 71's reading (any edge load)"]
    assert v.severity == verdict(_tree([0.0, 0.0, 0.0, 0.0])).severity


def test_at_the_floor_a_finding_and_no_note():
    """Edges that carry the floor together (the gear tip 0.02 % and the pinion edge 0.03 %:
    0.05 %) are a finding, not a note; no edge load, neither."""
    at = verdict(_tree([2e-4, 0.0, 0.0, 3e-4]))
    assert [f.check for f in at.findings if f.check == "edge_contact"] == ["edge_contact"]
    assert _edge_notes(at) == []
    none = verdict(_tree([0.0, 0.0, 0.0, 0.0]))
    assert _edge_notes(none) == []
    assert not [f for f in none.findings if f.check == "edge_contact"]


@pytest.mark.parametrize("forces", [[1e-4, 0.0, 2e-4, 0.0], [0.0, 1e-9, 0.0, 0.0]])
def test_every_loaded_edge_is_named_largest_first(forces):
    """Each loaded edge named with its share (largest first), the floor's number in the
    note taken from EDGE_SHARE_MIN."""
    note = _edge_notes(verdict(_tree(forces)))
    assert len(note) == 1 and f"{100 * EDGE_SHARE_MIN:g} %" in note[0]
    words = {0: "gear tip", 1: "gear heel", 2: "gear toe", 3: "pinion edge"}
    named = [words[i] for i in np.argsort(forces)[::-1] if forces[i] > 0]
    positions = [note[0].index(w) for w in named]
    assert positions == sorted(positions)
