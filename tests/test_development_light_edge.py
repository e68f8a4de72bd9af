"""The edge-peak steps' light-torque rule (:mod:`contact.optimize.development_light_edge`,
issue 71: no edge contact at 15 % of the design torque) and the verdict's reading it uses
(:func:`contact.study.verdicts.edge_contact_share`). Numbers are the stand-in's; the
comparisons are with 0 and exact."""

from __future__ import annotations

import numpy as np
import xarray as xr
from development_stand_ins import checked
from development_stand_ins import metrics as _metrics

from contact.optimize.development import DevelopmentTargets
from contact.optimize.development_light_edge import LIGHT_EDGE, light_edge, light_edge_lost
from contact.study.verdicts import EDGE_SHARE_MIN, edge_contact_share


def _design(p_light: float | None, share_light: float | None):
    over = {}
    if p_light is not None:
        over["pressure_max_edge"] = [p_light, 4000.0]
    if share_light is not None:
        over["edge_contact_share"] = [share_light, 0.03]
    return checked({"relief_start": 0.5}, _metrics(**over), DevelopmentTargets(), 0.6)


def test_an_edge_brought_to_the_light_torque_is_lost():
    """None at the light torque → 519 MPa there (share below the floor, 0 counted): lost,
    with its pressure; the same edge on a design that had one already, or a variant with
    none, is not this rule's."""
    got = light_edge_lost(_design(0.0, 0.0), _design(519.0, 0.0))
    assert got == [f"{LIGHT_EDGE} (p_max edge 519 MPa, edge share 0 %)"]
    assert light_edge_lost(_design(0.0, 0.0), _design(0.0, 0.0)) == []
    assert light_edge_lost(_design(300.0, 0.0), _design(519.0, 0.0)) == []
    # the verdict's counted share alone (a dataset without p_max edge) is edge contact too
    assert light_edge_lost(_design(None, 0.0), _design(None, 0.01))


def test_a_design_without_the_readings_is_not_judged():
    """Metrics without either reading (analysed before they were kept): not judged."""
    assert light_edge(_design(None, None)) is None
    assert light_edge_lost(_design(None, None), _design(519.0, 0.0)) == []
    assert light_edge_lost(_design(0.0, 0.0), _design(None, None)) == []


def test_the_verdicts_edge_contact_share_counts_from_its_floor():
    """Two edge segments per torque: the shares Σ F·arm of the edge kinds over the flank's
    and edges' (one roll, one pair): 0 below EDGE_SHARE_MIN, the total above it. Exact
    (sums of the numbers given, tolerance 1e-12 for the division)."""
    f = np.array([[1.0, 1e-4, 0.0], [1.0, 0.1, 0.05]])  # torque × segment
    lt = xr.Dataset(
        {"force": (("torque", "roll", "pair", "segment"), f[:, None, None, :]),
         "moment_arm": (("roll", "pair", "segment"), np.ones((1, 1, 3))),
         "segment_kind": (("segment",), np.array(["flank", "gear_tip", "pinion_edge"]))},
        coords={"torque": [40.8, 272.1]})
    got = edge_contact_share(lt)
    assert 1e-4 / 1.0001 < EDGE_SHARE_MIN
    assert got[0] == 0.0
    assert abs(got[1] - 0.15 / 1.15) < 1e-12
