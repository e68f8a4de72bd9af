"""The FE model's default body of a small pinion, a solid shaft (issue 71, item 4).

A 5-tooth hypoid pinion (tests/data/hypoid_5x43_case.toml, synthesised from the user
design tests/data/designs/hypoid_5x43.toml) is a shaft with teeth: the default rim of
1.2 × the outer whole depth under the slots would put the rim's inner cone through the
member axis (radius −5.4 mm at the toe), and ``ltca run`` refused it (rc 2, "rim_depth …
at or through the member axis"). The default now follows the member's size
(:func:`contact.compliance.fe.solid.default_rim_depth`).

References, none taken from the code under test: the blank's root cone (the inner cone's
radius at each end must be the stated fraction of its radius at the slot bottoms, an
identity of the construction), the unchanged default of a member with room for the full
rim (the gear, the default case's pinion: 1.2 h_e from the blank's own addendum and
dedendum), the mesh's Jacobian (positive: no element inverted or collapsed), and the
analysis itself (root stress finite and positive on both members).

CI: the coarse FE model of tests/test_fe_tooth.py (≈ 4 s per member) and the small LTCA
of tests/test_root_stress.py; the default model's whole ``ltca run`` is the slow test.
"""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.compliance.fe import FEOptions, build_tooth_solid
from contact.compliance.fe.section import tooth_sections
from contact.compliance.fe.solid import (
    SOLID_CORE_FRACTION,
    _rim_end_radii,
    default_rim_depth,
)
from contact.ltca import LTCAOptions
from geometry.case import load_case
from geometry.core.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
SMALL_PINION = ROOT / "tests" / "data" / "hypoid_5x43_case.toml"
#: the coarse model of the CI tests (as tests/test_fe_tooth.py)
COARSE = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                   rim_divisions=2, fillet_divisions=2, load_nu=5, load_nv=4)
#: a small LTCA: one mesh cycle, 4 rolls, 8 segments per curve
SMALL = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8)


@functools.cache
def _case(path: Path = SMALL_PINION):
    return load_case(path)


@functools.cache
def _sections(member: str, path: Path = SMALL_PINION):
    return tooth_sections(_case(path), member, np.linspace(0.0, 1.0, 9))


def _full(case, member: str) -> float:
    blank = case.member(member).blank
    return 1.2 * (blank.outer_addendum + blank.outer_dedendum)


def test_small_pinion_default_body_is_a_solid_shaft_with_a_positive_radius():
    """The 5-tooth pinion's default rim stops short of the axis at both ends: the inner
    cone's radius is SOLID_CORE_FRACTION of its radius at the slot bottoms at the toe
    and at the heel (1e-9 mm: the radius is affine in the depth, so the solved depth is
    exact to round-off), both depths below 1.2 h_e (which reaches through the axis
    here: the reason for the default), and the coarse solid built on it has no
    inverted element (its worst Jacobian ratio > 0.1; measured 0.23, the default case's
    pinion 0.3)."""
    case = _case()
    sections = _sections("pinion")
    full = _full(case, "pinion")
    assert np.min(_rim_end_radii(sections, full)) < 0.0  # the old default: through the axis
    depth = default_rim_depth(sections, case.member("pinion").blank)
    assert isinstance(depth, tuple) and len(depth) == 2
    assert 0.0 < depth[0] < depth[1] <= full  # the toe, nearer the root apex, is shallower
    radii = _rim_end_radii(sections, depth)
    np.testing.assert_allclose(radii, SOLID_CORE_FRACTION * _rim_end_radii(sections, 0.0),
                               rtol=0, atol=1e-9)
    assert np.all(radii > 0.0)
    solid = build_tooth_solid(case, "pinion", COARSE)
    assert solid.rim_depth == pytest.approx(depth[0], abs=1e-12)
    assert solid.mesh.min_jacobian > 0.1
    assert solid.constrained_nodes().size > 0


def test_members_with_room_for_the_rim_keep_the_iso_6336_default():
    """A member whose 1.2 h_e rim stays clear of the axis keeps it, a float (the model,
    its cache key and its numbers unchanged): the 5x43's gear and the default case's
    pinion, 1.2 × (outer addendum + dedendum) of their blanks to 1e-12 mm."""
    case = _case()
    gear = default_rim_depth(_sections("gear"), case.member("gear").blank)
    assert isinstance(gear, float) and gear == pytest.approx(_full(case, "gear"), abs=1e-12)
    default = resolve_case(None)
    sections = tooth_sections(default, "pinion", np.linspace(0.0, 1.0, 9))
    pinion = default_rim_depth(sections, default.member("pinion").blank)
    assert isinstance(pinion, float)
    assert pinion == pytest.approx(_full(default, "pinion"), abs=1e-12)


def test_a_given_rim_depth_through_the_axis_is_still_refused():
    """The user's own ``rim_depth`` is taken as given: one that reaches through the
    pinion's axis is an InputError naming the field (the default adapts, a given value
    does not)."""
    with pytest.raises(InputError, match="rim_depth"):
        build_tooth_solid(_case(), "pinion", FEOptions(rim_depth=12.0, face_divisions=4))


def test_five_tooth_pinion_runs_with_root_stress(tmp_path, monkeypatch):
    """``run_analysis`` of the 5-tooth pinion with root stress on (coarse FE model, small
    LTCA, a fresh FE cache) at 80 N·m, just below its design torque (83.86 N·m, the ISO
    10300 capacity the synthesis wrote): it runs, and the root stress of both members is
    finite and positive (it was refused before the FE model's default rim could follow
    a solid shaft). ≈ 15 s."""
    from contact.compliance.fe import CACHE_ENV
    from contact.pipeline import run_analysis

    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    tree = run_analysis(str(SMALL_PINION), [80.0], root_stress=COARSE, options=SMALL,
                        operating=False, geometry=False, mesh_interface=False)
    lt = tree["ltca"].to_dataset()
    peak = lt["root_stress_max"].isel(torque=0)
    assert set(peak["member"].values) == {"pinion", "gear"}
    assert np.all(np.isfinite(peak.values)) and np.all(peak.values > 0)


# ------------------------------------------------------------------ folded envelopes
FOLDED = ROOT / "tests" / "data" / "spiral_bevel_14x35_s70_case.toml"


def test_a_fold_of_the_side_is_cut_at_its_lowest_level():
    """A side that rises, turns down and rises again (a Z of samples, as the
    envelope's swallowtail): the boundary follows the first branch to the fold's lowest
    level, v = 0.2, and the last branch from there — the point on the first branch at
    that level interpolated by hand (v 0.1 → 0.3 over φ 0 → 0.2: φ 0.1) —, and the
    rest is kept; a side that only rises, or whose fold is below the tolerance, is
    returned unchanged."""
    from contact.compliance.fe.section import _FOLD_TOLERANCE, _without_folds

    v = np.array([-0.1, 0.0, 0.1, 0.3, 0.25, 0.2, 0.4, 1.0])
    phi = np.array([0.0, 0.0, 0.0, 0.2, 0.21, 0.22, 0.25, 0.3])
    s = np.arange(v.size, dtype=float)
    rho = np.full(v.size, 20.0)
    nv, nphi, ns, _ = _without_folds(v, phi, s, rho, 10.0)
    np.testing.assert_allclose(nv, [-0.1, 0.0, 0.1, 0.2, 0.2, 0.4, 1.0], atol=1e-15)
    np.testing.assert_allclose(nphi, [0.0, 0.0, 0.0, 0.1, 0.22, 0.25, 0.3], atol=1e-15)
    np.testing.assert_allclose(ns, [0.0, 1.0, 2.0, 2.5, 5.0, 6.0, 7.0], atol=1e-15)
    assert np.all(np.diff(nv) >= 0)
    rising = np.sort(v)
    assert all(np.array_equal(a, b) for a, b in
               zip(_without_folds(rising, phi, s, rho, 10.0), (rising, phi, s, rho),
                   strict=True))
    tiny = v.copy()
    tiny[4:6] = 0.3 - 0.5 * _FOLD_TOLERANCE / 10.0  # half the tolerance deep
    assert _without_folds(tiny, phi, s, rho, 10.0)[0].size == v.size


def test_the_sigma_70_spiral_bevel_pinion_meshes_by_default():
    """Issue 71: the 14x35 spiral bevel pinion at Σ = 70° (synthesised with every
    default) ran without root stress: its concave side's samples fold at the toe (up to
    0.25 of the depth, down to 0.17, up the flank) and the default mesh's rows, placed by
    arc length along the side, inverted 138 elements. With the fold cut every side rises
    from its lowest point to the tip (within the tolerance) and the default solid has no
    inverted element (worst Jacobian ratio measured 0.47 > 0.1)."""
    from contact.compliance.fe.section import _FOLD_TOLERANCE

    case = load_case(FOLDED)
    solid = build_tooth_solid(case, "pinion", FEOptions())
    assert solid.mesh.min_jacobian > 0.1
    for sec in solid.sections.sections:
        for side in (sec.left, sec.right):
            rest = side.v[int(np.argmin(side.v)):]
            drop = np.maximum.accumulate(rest) - rest
            assert drop.max() * sec.length_v < _FOLD_TOLERANCE
