"""The flank evaluator of the TCA and the synthesis (geometry.machine.flank_point.flank_points).

References: the flank solved by ``geometry.machine.flank.flank_at`` (the toolkit's flank Dataset
path: points, normals, principal curvatures), central finite differences of the points
along the projection-plane coordinates (the tangents ∂r/∂Z, ∂r/∂P) and of the normals along
the surface (the shape operator, dn = W dr), and the right-hand flank mirrored y → −y (the
left-hand member).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.flank import blank_outline, flank_at
from geometry.machine.flank_point import MemberFlank, flank_points

ROOT = Path(__file__).resolve().parents[1]
CASE = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")  # left-hand pinion
MIRROR = np.array([1.0, -1.0, 1.0])


def _places(member: str) -> tuple[np.ndarray, np.ndarray]:
    """Five places around the mean point of a member's projection plane [mm]."""
    pm = blank_outline(CASE.member(member).blank).mean_point
    dz = np.array([0.0, -3.0, 3.0, 1.0, -2.0])
    dp = np.array([0.0, 1.0, -1.0, 0.5, 0.8])
    return pm[0] + dz, pm[1] + dp


@pytest.mark.parametrize("member, flank", [("pinion", "concave"), ("pinion", "convex"),
                                           ("gear", "concave")])
def test_points_normals_and_curvature_match_flank_at(member, flank):
    """Same points and normals as flank_at (1e-10 mm, 1e-12) and a shape operator with
    flank_at's principal curvatures and directions (1e-10 1/mm)."""
    z, p = _places(member)
    fp = MemberFlank.of_case(CASE, member, flank).points(z, p)
    fs = flank_at(CASE, member, flank, z, p)
    assert fp.ok.all()
    np.testing.assert_allclose(fp.r, fs.position, atol=1e-10)
    np.testing.assert_allclose(fp.n, fs.normal, atol=1e-12)
    for k in range(len(z)):
        w = (fs.kappa1[k] * np.outer(fs.dir1[k], fs.dir1[k])
             + fs.kappa2[k] * np.outer(fs.dir2[k], fs.dir2[k]))
        np.testing.assert_allclose(fp.shape[k], w, atol=1e-10)
    np.testing.assert_allclose(np.linalg.norm(fp.r_s, axis=-1), 1.0, atol=1e-12)
    assert np.abs((fp.r_s * fp.n).sum(-1)).max() < 1e-9


@pytest.mark.parametrize("member, flank", [("pinion", "convex"), ("gear", "convex")])
def test_tangents_and_shape_operator_match_finite_differences(member, flank):
    """∂r/∂Z, ∂r/∂P from central differences (h = 1e-4 mm: 1e-6), and dn = W dr along them."""
    mf = MemberFlank.of_case(CASE, member, flank)
    z, p = _places(member)
    fp = mf.points(z, p)
    h = 1e-4
    for j, (ez, ep) in enumerate(((h, 0.0), (0.0, h))):
        plus, minus = mf.points(z + ez, p + ep), mf.points(z - ez, p - ep)
        dr = (plus.r - minus.r) / (2 * h)
        dn = (plus.n - minus.n) / (2 * h)
        np.testing.assert_allclose(fp.tangents[..., j], dr, atol=1e-6)
        np.testing.assert_allclose(np.einsum("kij,kj->ki", fp.shape, dr), dn, atol=1e-6)
        # a tangent moves Z (or P) by one and P (or Z) not at all
        rho = np.hypot(fp.r[:, 0], fp.r[:, 1])
        e_rho = np.stack([fp.r[:, 0] / rho, fp.r[:, 1] / rho, 0 * rho], -1)
        np.testing.assert_allclose(fp.tangents[:, 2, j], [1.0 - j] * len(z), atol=1e-12)
        np.testing.assert_allclose((fp.tangents[..., j] * e_rho).sum(-1), [float(j)] * len(z),
                                   atol=1e-12)


def test_left_hand_is_the_mirrored_right_hand_flank():
    """The left-hand pinion is the right-hand flank of the same settings mirrored y → −y."""
    mf = MemberFlank.of_case(CASE, "pinion", "concave")
    assert mf.hand == "left"
    z, p = _places("pinion")
    left, right = mf.points(z, p), mf._replace(hand="right").points(z, p)
    np.testing.assert_array_equal(left.r, right.r * MIRROR)
    np.testing.assert_array_equal(left.n, right.n * MIRROR)
    np.testing.assert_array_equal(left.r_s, right.r_s * MIRROR)
    np.testing.assert_array_equal(left.tangents, right.tangents * MIRROR[:, None])
    np.testing.assert_array_equal(left.shape, right.shape * MIRROR[:, None] * MIRROR)
    np.testing.assert_array_equal(left.params, right.params)


def test_guess_shapes_and_invalid_targets():
    """A guess from the result itself gives the same points (1e-10 mm); any target shape;
    non-finite or on-axis targets are not ok and NaN; bad shapes or hands raise."""
    mf = MemberFlank.of_case(CASE, "gear", "convex")
    z, p = _places("gear")
    fp = mf.points(z, p)
    again = mf.points(z, p, guess=fp.params)
    np.testing.assert_allclose(again.r, fp.r, atol=1e-10)
    grid = flank_points(*mf, z[:4].reshape(2, 2), p[:4].reshape(2, 2))
    assert grid.r.shape == (2, 2, 3) and grid.shape.shape == (2, 2, 3, 3)
    assert grid.tangents.shape == (2, 2, 3, 2) and grid.params.shape == (2, 2, 4)
    np.testing.assert_allclose(grid.r.reshape(4, 3), fp.r[:4], atol=1e-10)
    bad = mf.points(np.array([z[0], np.nan, z[1]]), np.array([p[0], p[1], 0.0]))
    assert bad.ok.tolist() == [True, False, False]
    assert np.isnan(bad.r[1:]).all() and np.isnan(bad.shape[1:]).all()
    with pytest.raises(InputError, match="shapes differ"):
        flank_points(*mf, z, p[:2])
    with pytest.raises(InputError, match="hand"):
        flank_points(mf.blade, mf.machine, mf.blank, "up", z, p)
