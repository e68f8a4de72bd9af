"""The contact region through a relief narrower than two profile steps of the ease-off grid
(issue 71, docs/synthesis.md "The 16×16's design-torque LTE on the default grid: the
relief strip's corner hole").

The FM spiral bevel 16×16 at Σ 60° (``benchmarks/data/unseen_designs/
spiral_bevel_16x16_s60.toml``) as ``ltca synthesize`` wrote it at ``main`` f2dd3489
(``tests/data/spiral_bevel_16x16_s60_written390_case.toml``: tip relief 16.2 µm from 0.9
of the way to the tip, design torque 390.7 N·m). On the default 41 × 21 gear grid the
pinion's tip relief (its last 10 % of the profile) falls between gear profile nodes 7 and
9: node 8 is the corner's hole (no conjugate mate), node 7 the only sheet node on the
relief. The hole was filled only with two sheet nodes on each side, so it stayed
uncomputed, its two cells left the contact region, and the region ended on the grid line
v 0.4775 — 19 % of the pinion's profile short of its tip — at u 0.35–0.65. The
design-torque LTE p-p read 87.8 µrad; with the holes filled (on 81 × 81 the strip holds
runs of two) it reads 127.6 µrad, the grids of ≥ 41 profile nodes 111–121 µrad.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.ltca.mesh_cycle import loaded_tca
from contact.utca.easeoff import _corner_nodes, _fill_corner_nodes, ease_off
from contact.utca.fields import fields_of
from geometry.case import load_case

CASE = (Path(__file__).resolve().parents[1] / "tests" / "data"
        / "spiral_bevel_16x16_s60_written390_case.toml")
FINE = {"nu": 81, "nv": 81}


@cache
def _case():
    return load_case(CASE)


@cache
def _ease_off(nu: int, nv: int):
    return ease_off(_case(), flank="drive", grid={"nu": nu, "nv": nv})


def _column():
    """One profile column as the 16×16's u 0.5 on 41 × 21 reads (read off its ease-off):
    nodes 0–6 off the sheet (beyond the pinion's tip on the gear's fillet; 6 computed),
    node 7 the relief's only sheet node (pinion section 3), node 8 the corner's hole,
    nodes 9–20 on the profile (section 2)."""
    n = 21
    v = np.linspace(0.05, 1.0, n)
    reason = np.array([3] * 8 + [2] + [0] * 12, dtype=np.int8)[None]
    smooth = np.array([0] * 7 + [1, 0] + [1] * 12, dtype=bool)[None]
    section = np.array([3] * 8 + [2] * 13)[None]
    eps = np.full((1, n), np.nan)
    eps[0, 6:8] = [1763.47e-6, 903.58e-6]
    eps[0, 9:] = 22.25e-6 - 340e-6 * (v[9:] - v[9])  # the profile's nodes, slope −340 µrad
    q = np.where(np.isnan(eps), np.nan, -v[None])
    return v, reason, smooth, section, eps, q


def test_a_relief_with_one_sheet_node_has_its_corner_hole_filled():
    """The hole between the relief's single sheet node and the profile is a corner node
    (before: not, for want of a second relief node on the sheet), and its ε is the
    profile's linear continuation to it (exact for the linear profile data here: 1e-18
    rad is round-off) — not the relief side's, whose second node lies off the sheet (on
    the gear's fillet); Q is interpolated between the two neighbours."""
    v, reason, smooth, section, eps, q = _column()
    corner = _corner_nodes(reason, smooth, section, [2, 3])
    assert np.flatnonzero(corner[0]).tolist() == [8]
    e, qq = _fill_corner_nodes(corner, v, eps, q, section=section,
                               sheet=(reason == 0) | smooth)
    assert e[0, 8] == pytest.approx(22.25e-6 + 340e-6 * (v[9] - v[8]), abs=1e-18)
    assert qq[0, 8] == pytest.approx(-v[8], abs=1e-15)
    # two sheet nodes on each side: the larger of the two continuations, as before
    smooth2 = smooth.copy()
    smooth2[0, 6] = True
    corner2 = _corner_nodes(reason, smooth2, section, [2, 3])
    e2, _ = _fill_corner_nodes(corner2, v, eps, q, section=section,
                               sheet=(reason == 0) | smooth2)
    relief = 903.58e-6 + (903.58e-6 - 1763.47e-6)
    assert e2[0, 8] == pytest.approx(max(relief, 22.25e-6 + 340e-6 * (v[9] - v[8])),
                                     abs=1e-18)


def test_the_default_grid_reaches_the_pinion_tip_through_the_relief():
    """The contact region's lowest profile place (first place inside on a scan of step
    5e-4) at u 0.3–0.6 on 41 × 21 within 0.01 of the 81 × 81 grid's (measured ≤ 0.0065:
    the pinion mate's margin interpolated over a coarser cell; the pinion's tip at v
    0.38–0.41). Before: 0.4775 (the grid line beyond the hole) at u 0.4 and 0.5."""
    vs = np.linspace(0.05, 1.0, 1901)

    def lowest(f, u):
        return vs[np.argmax(f.inside(np.full_like(vs, u), vs.copy()))]

    coarse, fine = fields_of(_ease_off(41, 21)), fields_of(_ease_off(**FINE))
    for u in (0.3, 0.4, 0.5, 0.6):
        assert lowest(coarse, u) == pytest.approx(lowest(fine, u), abs=0.01)


def test_the_design_torque_lte_on_the_default_grid_reads_the_fine_grids():
    """Drive LTE p-p at 390.7 N·m on 41 × 21 against the 81 × 81 grid's (measured 127.6
    against 111.8 µrad; before 87.8 against 120.5, the 81 × 81's two-node corner holes
    unfilled too). No longer below it by more than 5 µrad: the grids of ≥ 41 profile nodes
    read 111.4–121.2 µrad (41 × 41, 41 × 81, 81 × 41, 81 × 81, 121 × 61, 161 × 81), half
    their spread 4.9 µrad (the trough rolls' share between the two pairs moves with the
    grid; 40 rolls and 48 segments per curve move none of them by more than 0.4 µrad);
    before, 23.6 µrad below the lowest. Above by at most 17 µrad: 41 × 21 and 81 × 21 read
    11.4 µrad above the fine grids' mean 116.2 (the relief corner's own cell at the coarse
    profile step, left open), and the 81 × 81 lies 4.4 below it."""
    lte = {}
    for g in ((41, 21), (81, 81)):
        ds = loaded_tca(_case(), [390.7], easeoff=_ease_off(*g))
        lte[g] = float(ds.lte_peak_to_peak.values[0])
    assert lte[(81, 81)] - 5.0 < lte[(41, 21)] < lte[(81, 81)] + 17.0
