"""The LTCA's discretisation of the contact lines (contact.ltca, contact.utca).

Independent checks: the quadratic segment interpolation is exact for quadratics (an
identity), the contact line ends on the pinion blank whatever the segment count (its
length converges), a curve shorter than the coarse scan step is found where a fine scan
of the inside measure finds it, and a pair whose iso-line leaves the contact region keeps
a curve whose UTE varies continuously (the real pinion still touches through its gap).
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.ltca import LTCAOptions, loaded_tca, segment_geometry
from contact.ltca.discretisation import SegmentQuadratic
from contact.utca import CURVE_SPACINGS, EaseOffFields, contact_curves, transitions
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

ROOT = Path(__file__).resolve().parents[1]


@cache
def _case():
    # the long-bearing synthesis without relief (its numbers are the ones quoted below);
    # aligned: the case's [operating] table holds the seed's Table 3.1 misalignment
    return dataclasses.replace(load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml"),
                               misalignment=Misalignment())


@cache
def _easeoff():
    return ease_off(_case())


@pytest.mark.parametrize("spacing", sorted(CURVE_SPACINGS))
def test_segment_quadratic_is_exact_for_quadratics(spacing):
    S = 7
    x = CURVE_SPACINGS[spacing](2 * S + 1)
    quad = SegmentQuadratic(x)
    coef = (0.3, -1.7, 2.9)

    def field(s):
        return coef[0] + coef[1] * s + coef[2] * s**2

    y = field(x)
    rng = np.random.default_rng(3)
    a = rng.uniform(0.0, 0.5, S)
    b = rng.uniform(0.5, 1.0, S)
    x0, x1 = x[0:-1:2], x[2::2]
    # value at a fraction τ of each segment: the place x0 + τ (x1 − x0)
    np.testing.assert_allclose(quad.at(y, a), field(x0 + a * (x1 - x0)), rtol=0, atol=1e-13)
    # mean over [a, b]: the exact integral of the quadratic over the place interval
    pa, pb = x0 + a * (x1 - x0), x0 + b * (x1 - x0)

    def prim(s):
        return coef[0] * s + coef[1] * s**2 / 2 + coef[2] * s**3 / 3

    np.testing.assert_allclose(quad.mean(y, a, b), (prim(pb) - prim(pa)) / (pb - pa),
                               rtol=0, atol=1e-12)
    # vectors interpolate component by component
    vec = np.stack([y, 2 * y, -y], axis=-1)
    np.testing.assert_allclose(quad.at(vec, a, vector=True)[:, 1], 2 * quad.at(y, a),
                               atol=1e-13)


def test_segment_clip_finds_the_crossing_of_a_linear_measure():
    S = 5
    x = CURVE_SPACINGS["cosine"](2 * S + 1)
    quad = SegmentQuadratic(x)
    edge = 0.37  # the measure 0.37 − x is ≥ 0 before the edge only
    a, b = quad.clip(edge - x)
    x0, x1 = x[0:-1:2], x[2::2]
    lo, hi = x0 + a * (x1 - x0), x0 + b * (x1 - x0)
    inside = hi > lo
    # the kept parts tile [0, edge] exactly (a linear measure is crossed exactly)
    assert lo[inside].min() == 0.0
    assert hi[inside].max() == pytest.approx(edge, abs=1e-15)
    np.testing.assert_allclose(np.sum(hi[inside] - lo[inside]), edge, atol=1e-15)
    # no curve (NaN) and a segment wholly outside give an empty part
    a, b = quad.clip(np.full(2 * S + 1, np.nan))
    assert np.all(a == b)


def test_contact_line_length_is_independent_of_the_segment_count():
    """The segments are clipped at the real pinion's blank edge (not dropped whole), so the
    loaded line length converges at second order: S = 12 and S = 48 agree to 0.3 % (the
    chords of a curved line: their deficit falls as 1/S², ~0.1 % at S = 12 here)."""
    case, eo = _case(), _easeoff()
    m1, _ = transitions(eo)
    roll = m1 + np.arange(6) * eo.pitch / 6
    total = []
    for S in (12, 48):
        seg = segment_geometry(case, eo, roll, (-1, 0, 1, 2), S)
        ok = np.isfinite(seg.r_eq)
        total.append(np.where(ok, seg.length, 0.0).sum(axis=(1, 2)))
    np.testing.assert_allclose(total[0], total[1], rtol=3e-3)


def test_short_curves_between_coarse_samples_are_found():
    """Near the end of a pair's contact the curve on the region's corner gets shorter
    than the coarse scan step (1/80 of the face width here). A curve must exist exactly
    where a fine scan (4001 places) of the inside measure along the iso-line finds
    inside places; 1e-3 of the inside measure is the tolerance for curves that a fine
    scan barely catches."""
    eo = _easeoff()
    f = EaseOffFields(eo)
    _, m2 = transitions(eo)
    # the reference pair's exit lies about one pitch after M2 from the other pair's view;
    # scan the rolls where its first-order iso-line shrinks away
    q = np.linspace(m2 + 0.4 * eo.pitch, m2 + 1.1 * eo.pitch, 57)
    cc = contact_curves(eo, q, method="seed", n_point=9)
    uf = np.linspace(float(f.u[0]), float(f.u[-1]), 4001)
    checked = 0
    for k, t in enumerate(q):
        vf = f.solve_v(uf, np.full(uf.shape, t), lattice=f.lattice(uf))
        best = float(np.max(f.measure(uf, vf)))
        exists = bool(np.isfinite(cc.ute[k]))
        if abs(best) > 1e-3:
            assert exists == (best > 0), (k, best)
            checked += 1
    assert checked > 40


def test_near_misses_continue_the_leaving_pair_and_change_nothing_else():
    eo = _easeoff()
    _, m2 = transitions(eo)
    q = np.linspace(m2 - 0.2 * eo.pitch, m2 + 1.3 * eo.pitch, 121)
    plain = contact_curves(eo, q, n_point=25)
    near = contact_curves(eo, q, n_point=25, near_misses=True)
    have = np.isfinite(plain.ute)
    # where the iso-line meets the region the curves are the same, to the end solver's
    # tolerance (1e-9 of the face width; the batch's iteration counts differ): UTE to
    # 1e-12 rad
    np.testing.assert_allclose(near.ute[have], plain.ute[have], rtol=0, atol=1e-12)
    np.testing.assert_allclose(near.u[have], plain.u[have], rtol=0, atol=1e-8)
    # the pair leaves the region within the scan and is continued beyond it
    assert have[0] and not have[-1]
    more = np.isfinite(near.ute) & ~have
    assert more.any()
    # continuity across the exit: the UTE moves by no more than the largest step within
    # the region (the pinion's gap grows smoothly as the iso-line moves away)
    u = near.ute * 1e6
    fin = np.isfinite(u)
    run = np.flatnonzero(fin)
    run = run[: np.argmax(np.diff(run) > 1) + 1] if np.any(np.diff(run) > 1) else run
    steps = np.abs(np.diff(u[run]))
    exit_step = steps[np.flatnonzero(~have[run][1:] & have[run][:-1])]
    assert exit_step.size == 1
    assert exit_step[0] <= 1.5 * steps[: np.flatnonzero(~have[run])[0] - 1].max()
    with pytest.raises(InputError, match="near_misses"):
        contact_curves(eo, q[:3], method="seed", near_misses=True)
    with pytest.raises(InputError, match="spacing"):
        contact_curves(eo, q[:3], spacing="chebyshev")


def test_loaded_share_of_a_leaving_pair_fades():
    """At 500 N·m the leaving pair still carried ~1 % of the torque when its first-order
    iso-line left the region (and vanished with it); with the near misses its share fades:
    at its last loaded roll (80 rolls per cycle) it carries < 0.5 % of the torque
    (measured 0.34 %), and no step of its share exceeds 2 % (measured 1.2 %, the steady
    hand-over within the cycle). The LTE is not bounded here: its largest step, 2.3 µrad,
    is the entering pair's corner entry, which the line model cannot resolve."""
    opts = LTCAOptions(cycles=1, rolls_per_cycle=80, segments=16)
    ds = loaded_tca(_case(), [500.0], options=opts, easeoff=_easeoff())
    share = ds["load_share"].sel(pair=-1).isel(torque=0).values
    fades = np.flatnonzero((share[:-1] > 0) & (share[1:] == 0))
    assert fades.size >= 1
    assert np.max(np.abs(np.diff(share))) < 0.02
    assert np.all(share[fades] < 5e-3)


def test_spacing_is_validated():
    with pytest.raises(InputError, match="spacing"):
        LTCAOptions(spacing="gauss")


def test_refinement_on_the_seed_case():
    """Doubling the segments (24 → 48) changes the LTE by < 0.5 µrad and the peak pressure
    by < 2 % at 50 / 250 / 500 N·m (the issue's bounds; measured 0.13 µrad and 0.5 %);
    doubling the roll positions (20 → 40 per cycle, from the default of ``ltca run``)
    leaves the shared rolls unchanged and moves the cycle's mean and peak-to-peak LTE by
    < 0.5 µrad (measured ≤ 0.4) and the peak pressure by < 2 %. (From 10 rolls per cycle
    the peak-to-peak moves 0.85 µrad at 500 N·m: 10 rolls miss the peak.)"""
    case, eo = _case(), _easeoff()
    torques = [50.0, 250.0, 500.0]

    def run(rolls, segments):
        opts = LTCAOptions(cycles=1, rolls_per_cycle=rolls, segments=segments)
        return loaded_tca(case, torques, options=opts, easeoff=eo)

    a, b, c = run(20, 24), run(20, 48), run(40, 24)
    dte = np.abs(a["transmission_error"] - b["transmission_error"]).max().item()
    assert dte < 0.5
    pa = a["pressure_max"].max(("roll", "pair", "segment")).values
    pb = b["pressure_max"].max(("roll", "pair", "segment")).values
    pc = c["pressure_max"].max(("roll", "pair", "segment")).values
    assert np.all(np.abs(pb / pa - 1) < 0.02)
    assert np.all(np.abs(pc / pa - 1) < 0.02)
    shared = c["transmission_error"].isel(roll=slice(0, None, 2))
    np.testing.assert_allclose(shared.values, a["transmission_error"].values, rtol=0,
                               atol=1e-9)
    for name in ("lte_mean", "lte_peak_to_peak"):
        assert np.all(np.abs(c[name].values - a[name].values) < 0.5), name


def test_spacing_changes_results_only_within_the_discretisation_error():
    """Uniform and cosine spacing are two discretisations of the same problem: their LTE
    agree within the 24-segment error (≤ 0.5 µrad, the refinement bound)."""
    case, eo = _case(), _easeoff()
    base = LTCAOptions(cycles=1, rolls_per_cycle=6, segments=24)
    a = loaded_tca(case, [250.0], options=base, easeoff=eo)
    b = loaded_tca(case, [250.0], options=dataclasses.replace(base, spacing="uniform"),
                   easeoff=eo)
    assert np.abs(a["transmission_error"] - b["transmission_error"]).max().item() < 0.5


def test_edge_contact_flags_the_clipped_pinion_tip_end():
    """The edge flag looks at each curve's first and last *valid* segment: the end on the
    gear blank's edge and the end clipped at the real pinion's blank edge (before, only
    the first and last array slots were looked at, which a clipped curve leaves empty).
    Checked against a direct reading of the stored data, and physically: at 500 N·m the
    leaving pair loads the pinion's tip edge (a flagged end at gear profile v < 0.6 that
    is not the last slot) in some roll positions. A loaded edge segment
    (:mod:`contact.ltca.edges`) flags its pair too."""
    opts = LTCAOptions(cycles=1, rolls_per_cycle=10, segments=16)
    full = loaded_tca(_case(), [500.0], options=opts, easeoff=_easeoff())
    curve = full["segment_kind"].values == "curve"
    edge_loaded = (full["contact"].values[0][..., ~curve] > 0).any(axis=-1)
    ds = full.isel(segment=np.flatnonzero(curve))
    valid = (ds["equivalent_radius"].notnull() & (ds["segment_length"] > 0)).values
    loaded = ds["contact"].values[0] > 0
    v = ds["segment_v"].values
    clipped_tip = 0
    for j in range(valid.shape[0]):
        for k in range(valid.shape[1]):
            idx = np.flatnonzero(valid[j, k])
            expect = bool(idx.size) and bool(loaded[j, k, idx[0]] or loaded[j, k, idx[-1]])
            expect |= bool(edge_loaded[j, k])
            assert bool(ds["edge_contact"].values[0, j, k]) == expect
            if idx.size and idx[-1] < valid.shape[2] - 1 and loaded[j, k, idx[-1]]:
                clipped_tip += int(v[j, k, idx[-1]] < 0.6)
    assert clipped_tip > 0


def test_segment_geometry_repeated_is_the_computed_one():
    """The segment geometry with edge segments is kept per process by its inputs (issue
    75): the same call again gives every field bit for bit as computed afresh (the memo
    emptied), each call its own per-segment arrays; another edge limit is worked out
    anew."""
    from contact.ltca.segments import clear_segment_memo

    case, eo = _case(), _easeoff()
    m1, _ = transitions(eo)
    roll = m1 + np.arange(8) * eo.pitch / 4  # two mesh cycles: rolls repeat
    args = (case, eo, roll, (-1, 0, 1), 8, "cosine", (1.0, 0.5))
    clear_segment_memo()
    fresh = segment_geometry(*args, edge_limit=0.05)
    again = segment_geometry(*args, edge_limit=0.05)
    clear_segment_memo()
    recomputed = segment_geometry(*args, edge_limit=0.05)
    assert fresh.shape[2] > 8  # edge segments among them
    for name in (*fresh.per_segment(), "kind", "ute", "pinion_rotation", "gear_rotation",
                 "source"):
        a, b, c = (getattr(s, name) for s in (fresh, again, recomputed))
        assert a.tobytes() == b.tobytes() == c.tobytes(), name
    assert fresh.edge_arm_max == again.edge_arm_max == recomputed.edge_arm_max
    assert again.length is not fresh.length and again.length.flags.writeable
    wider = segment_geometry(*args, edge_limit=0.5)
    assert np.isfinite(wider.r_eq).sum() >= np.isfinite(fresh.r_eq).sum()


def test_a_trials_curve_segments_are_kept_apart_and_read_again(monkeypatch):
    """Inside a development's trial (a WarmSeeds block) the curve segments are memoised
    apart from the cold memo (issue 75): the same ease-off object analysed again at
    another torque (another edge limit) reads them instead of computing them again, bit
    for bit as computed afresh; the cold memo, which the analyses outside a block read,
    gets none of them."""
    from contact.ltca import segments as segments_module
    from contact.ltca.segments import clear_segment_memo
    from geometry.machine.meshing import WarmSeeds

    case, eo = _case(), _easeoff()
    m1, _ = transitions(eo)
    roll = m1 + np.arange(8) * eo.pitch / 8
    args = (case, eo, roll, (-1, 0, 1), 6, "cosine", (1.0, 0.5))
    computed = []
    original = segments_module._curve_part_of

    def counting(*a, **k):
        computed.append(1)
        return original(*a, **k)

    monkeypatch.setattr(segments_module, "_curve_part_of", counting)
    clear_segment_memo()
    with WarmSeeds():
        first = segment_geometry(*args, edge_limit=0.05)
        again = segment_geometry(*args, edge_limit=0.5)  # another torque's limit
        assert len(computed) == 1
        assert segments_module._memo_trial_curve_part.cache_info().currsize == 1
        assert segments_module._memo_curve_part.cache_info().currsize == 0
        clear_segment_memo()
        fresh = segment_geometry(*args, edge_limit=0.05)
    assert len(computed) == 2
    S = 6
    for name in first.per_segment():
        a, b, c = (getattr(s, name)[:, :, :S] for s in (first, again, fresh))
        assert a.tobytes() == b.tobytes() == c.tobytes(), name
    assert first.ute.tobytes() == again.ute.tobytes() == fresh.ute.tobytes()
    clear_segment_memo()
    assert segments_module._memo_trial_curve_part.cache_info().currsize == 0
