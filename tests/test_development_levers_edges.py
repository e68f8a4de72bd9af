"""``benchmarks/development_levers.py --edges``'s LTE between the torques (issue 71, branch
edge87): :func:`range_line` analyses ``ltca run``'s evenly spaced ``lte_range`` torques
between the light and the design torque and says the largest LTE p-p and where.

A stand-in analysis replaces the LTCA (its LTE p-p a known function of the torque); the
torques it is asked for are checked against ``numpy.linspace`` from the light to the design
torque with :data:`contact.ltca.lte_range.LTE_TORQUES` points, the definition
``lte_range_torques`` documents for a synthesised case's two torques.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.ltca.lte_range import LTE_TORQUES

ROOT = Path(__file__).resolve().parents[1]


def _levers():
    spec = importlib.util.spec_from_file_location(
        "development_levers", ROOT / "benchmarks" / "development_levers.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_range_line_reads_the_largest_lte_at_ltca_runs_torques(monkeypatch):
    """The 12x31 at Σ 112.5°'s torques 51.7 / 345.1 N m, an LTE p-p peaking mid-range (a
    parabola, 60 µrad at 200 N m): the line names the largest LTE of the torques analysed,
    rounded to 1 µrad, and the torque it is at (exact: the law is evaluated at the torques
    asked for)."""
    import contact.pipeline

    asked = []

    def fake(case, torques, **kw):
        asked.append(list(torques))
        t = np.asarray(torques, float)
        lte = 60.0 - 1e-3 * (t - 200.0) ** 2
        return {"/ltca": xr.Dataset({"lte_peak_to_peak": (("torque",), lte)})}

    monkeypatch.setattr(contact.pipeline, "run_analysis", fake)
    line = _levers().range_line(None, [51.7, 345.1], None, "drive")
    expected = np.linspace(51.7, 345.1, LTE_TORQUES)
    assert asked[0] == pytest.approx(expected, abs=1e-9)
    lte = 60.0 - 1e-3 * (expected - 200.0) ** 2
    k = int(np.argmax(lte))
    assert line == f"between: {lte[k]:.0f} urad at {expected[k]:g} N m"


def test_light_line_reads_the_light_torques_edges():
    """:func:`light_line` (branch coasttoe97): the light torque's ``p_max edge``, the
    counted share and each edge kind's peak, the first entry of each metric (light, then
    design torque), as the 13x17's written coast flank read them (1061 MPa on the gear
    toe, share 0: below the verdict's floor); metrics without the readings say so. Exact:
    the line formats the numbers it is given."""
    from contact.ltca.edges import EDGE_KINDS

    m = {"pressure_max_edge": np.array([1060.74, 4574.67]),
         "edge_contact_share": np.array([0.0, 0.008233])}
    m |= {f"edge_pressure_{k}": np.array([1060.74 if k == "gear_toe" else 0.0, 4000.0])
          for k in EDGE_KINDS}
    line = _levers().light_line(m)
    assert line.startswith("edges at LIGHT: p_max edge 1061 MPa, share 0 % (")
    assert "gear_toe 1061" in line and "gear_tip 0" in line and "4000" not in line
    assert _levers().light_line({}) == "edges at LIGHT: not read"
