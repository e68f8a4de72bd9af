"""The seed's 11×41 pair at its Table 3.1 conditions (seed §3.4, Figs. 3.6, 3.7, Table 3.1).

The seed's machine settings are not published: the default case is our reference design
of its basic data (cases/basic/kolivand2009_fm_11x41_reference.toml: the local synthesis
with profile relief, its inputs and the pinion's 2C, H1 chosen by ``ltca optimize``;
docs/optimize.md), so these tests compare magnitudes and trends, with the bounds the LTCA
issue states, not curves. The limits the reference design was optimised for are tested in
tests/test_reference_design.py. The
misalignment signs of Table 3.1 were lost in the text extraction; the reading used here
is :data:`contact.catalogue.SEED_TABLE_3_1` (ΔE = −0.15 mm, ΔP = +0.12 mm), argued there.

Seed values, read from Fig. 3.6 (axis ranges 90–130, 270–310, 580–620 µrad) and Table 3.1:
LTE mean ≈ 110 / 290 / 600 µrad and LTE peak-to-peak 12.8 / 15.9 / 21.9 µrad at a pinion
torque of 50 / 250 / 500 N·m.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np

from contact.catalogue import DEFAULT_CASE, SEED_TABLE_3_1
from contact.ltca import loaded_tca
from geometry.case import load_case
from geometry.pair.assembly import Misalignment

ROOT = Path(__file__).resolve().parents[1]
TORQUES = SEED_TABLE_3_1["torque"]
SEED_LTE_MEAN = np.array([110.0, 290.0, 600.0])  # [µrad], seed Fig. 3.6


@cache
def _case():
    return load_case(ROOT / "cases" / DEFAULT_CASE)


@cache
def _run(mis: Misalignment = SEED_TABLE_3_1["misalignment"], torques=TORQUES):
    # the options of `ltca run` (two mesh cycles, 20 rolls per cycle, 24 segments per curve)
    return loaded_tca(_case(), list(torques), misalignment=mis)


def _centre(ds):
    """Pressure-weighted place of the loaded contact on the gear flank, per torque:
    (u toe 0 → heel 1, v root 0 → tip 1); the weight is the pressure times the segment
    length (segments are graded towards the curve ends)."""
    p = ds["pressure_max"].fillna(0.0) * ds["segment_length"].fillna(0.0)
    dims = ("roll", "pair", "segment")
    u = ds["segment_u"].broadcast_like(p).fillna(0.0)
    v = ds["segment_v"].broadcast_like(p).fillna(0.0)
    w = p.sum(dims)
    return (p * u).sum(dims).values / w.values, (p * v).sum(dims).values / w.values


def test_every_roll_position_is_solved_and_certified():
    ds = _run()
    assert ds["found"].all()
    # equilibrium re-checked from the stored forces: Σ F R = T_g to 1e-9 relative
    ratio = _case().gear.blank.teeth / _case().pinion.blank.teeth
    moment = (ds["force"].fillna(0.0) * ds["moment_arm"]).sum(("pair", "segment"))
    t_gear = ds["torque"] * ratio * 1e3  # [N·mm]
    assert float(np.abs(moment / t_gear - 1.0).max()) < 1e-9


def test_lte_mean_is_of_the_seed_magnitude_and_nearly_linear():
    """Within a factor of two of the seed's Fig. 3.6 (measured 154 / 397 / 633 µrad: 1.40,
    1.37, 1.06 × the seed; our tooth compliance is checked against FE and ISO 6336 in the
    compliance tests, so the difference is the unpublished design). Monotonic, and nearly
    linear: the slopes over 50–250 and 250–500 N·m agree within a factor 1.5 (measured
    1.22 and 0.95 µrad/(N·m): ours flattens where the seed's steepens, 0.9 and 1.24)."""
    mean = _run()["lte_mean"].values
    ratio = mean / SEED_LTE_MEAN
    assert np.all((ratio > 0.5) & (ratio < 2.0)), mean
    slopes = np.diff(mean) / np.diff(TORQUES)
    assert np.all(slopes > 0)
    assert 1 / 1.5 < slopes[1] / slopes[0] < 1.5


def test_lte_peak_to_peak_is_in_the_seed_range():
    """5–40 µrad (the LTCA issue's bound around the seed's 12.8–21.9; measured 16.1 / 22.6 /
    22.5: it rises from 50 to 250 N·m as the seed's does, then stays flat where the seed's
    goes on rising)."""
    pp = _run()["lte_peak_to_peak"].values
    assert np.all((pp > 5.0) & (pp < 40.0)), pp


def test_peak_pressure_grows_with_torque_and_stays_below_2_5_gpa():
    """The seed's line contact of the flanks: measured 0.69 / 1.24 / 1.79 GPa on the
    contact curves (1.85 GPa at 500 N·m converged in the roll positions,
    tests/test_reference_design.py). The edge contact (contact.ltca.edges, 0.5 mm edge
    rounding on the mating flank), which the seed's line model does not have, is reported
    apart and is far higher on its small share of the torque: 2.4 / 4.8 / 6.4 GPa (the
    seed's "edge loading at the tip and root", Fig. 3.7b–c)."""
    ds = _run()
    p = ds["pressure_max_flank"].values
    assert np.all(np.diff(p) > 0)
    assert p[-1] < 2500.0
    curve = ds["segment_kind"] == "curve"
    np.testing.assert_array_equal(
        p, ds["pressure_max"].where(curve).max(("roll", "pair", "segment")).values)
    edge = ds["pressure_max_edge"].values
    assert np.all(np.diff(edge) > 0) and np.all(edge > p)


def test_contact_spreads_and_edge_load_grows_with_torque():
    """Seed Fig. 3.7a–c: the pattern spreads as torque rises, with edge loading at the tip
    and root. Measured: flank area of the pressure envelope 282 → 479 → 573 cells of the
    41 × 21 grid; share of the gear torque carried by the edge contact (contact.ltca.edges)
    0.28 → 1.6 → 4.5 % over the mesh cycle. Every torque touches an edge, at 50 N·m with
    0.28 % of the torque (the seed's Fig. 3.7a shows none; the long-bearing synthesis
    without relief, kolivand2009_fm_11x41, carries 6.9 % there)."""
    ds = _run()
    area = (ds["pressure_envelope"].fillna(0.0) > 0).sum(("u", "v")).values
    assert np.all(np.diff(area) > 0)
    moment = (ds["force"].fillna(0.0) * ds["moment_arm"].fillna(0.0)).values
    edge = ds["segment_kind"].values != "curve"
    share = moment[..., edge].sum(axis=(1, 2, 3)) / moment.sum(axis=(1, 2, 3))
    assert np.all(np.diff(share) > 0), share
    assert np.all(ds["edge_contact"].any(("roll", "pair")).values)


def test_table_3_1_misalignments_move_the_pattern_as_the_seed_describes():
    """Seed p. 91, Fig. 3.7d–e at 50 N·m: (0.08, 0.05) mm moves the loaded pattern towards
    toe and root compared with (0.15, 0.12); (0.26, 0.13) towards the heel. In the reading
    of SEED_TABLE_3_1 (ΔE negative, ΔP positive). Measured centres (u, v), weighted by
    pressure × length: (a) 0.725, 0.585; (d) 0.581, 0.578; (e) 0.832, 0.514. The lengthwise
    moves are asserted (threshold 5 % of the face width). In profile (d) moves 0.007 of
    the depth towards the root (the seed's "and root" in direction, hardly in amount): the
    test holds it within 1 % of the depth of (a), so that a move towards the tip fails."""
    ua, va = _centre(_run(torques=(50.0,)))
    ud, vd = _centre(_run(Misalignment(delta_E=-0.08, delta_P=0.05), (50.0,)))
    ue, _ = _centre(_run(Misalignment(delta_E=-0.26, delta_P=0.13), (50.0,)))
    assert ud[0] < ua[0] - 0.05 and vd[0] < va[0] + 0.01
    assert ue[0] > ua[0] + 0.05


def test_aligned_pair_is_centred_and_of_the_seed_magnitude():
    """Aligned, the local synthesis (kolivand2009_fm_11x41: the mean point M centred on the
    flank, no relief) carries its load about the flank's middle (pressure centre within
    10 % of the face width of u = 0.5; measured 0.50–0.52) with LTE means 127 / 373 / 603
    µrad (within a factor 2 of the seed's misaligned values). The reference design's
    optimisation moved its pattern for the mounted pair (Table 3.1: centre 0.73 / 0.67 /
    0.62): aligned it sits towards the toe, 0.39 / 0.45 / 0.48, with LTE means 169 / 409 /
    639 µrad."""
    ds = loaded_tca(load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml"), list(TORQUES),
                    misalignment=Misalignment())
    u, _ = _centre(ds)
    assert np.all(np.abs(u - 0.5) < 0.1), u
    ratio = ds["lte_mean"].values / SEED_LTE_MEAN
    assert np.all((ratio > 0.5) & (ratio < 2.0))
