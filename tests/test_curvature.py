"""Principal curvatures and directions (seed Eq. 2.9–2.13), relative curvature, R_eq.

References: closed forms for cones and cylinders, second-order finite differences of the
generated surface (a local quadric fitted to solved neighbouring points, whose error must
fall as h²), numpy's symmetric eigen-solver, and Hertz's crossed-cylinder formula.
"""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.curvature import (
    PrincipalCurvatures,
    equivalent_radius,
    normal_curvature,
    principal_from_directional,
    relative_curvature,
)
from geometry.machine.cutter import blade_profile, profile_sections
from geometry.machine.flank import flank_surface
from geometry.machine.meshing import solve_envelope

CASES = Path(__file__).resolve().parents[1] / "cases"
MIRROR = np.array([1.0, -1.0, 1.0])


@cache
def _case(name):
    return load_case(CASES / name)


@pytest.mark.parametrize("flank", ["concave", "convex"])
def test_formate_curvatures_are_the_cone_curvatures(flank):
    """A straight-bladed Formate gear is its cutter cone: principal curvatures 0 (along the
    blade) and −σ cos α/ρ (along the circle swept by the blade), directions along the
    meridian and the parallel (closed form for a cone), to 1e-12."""
    case = _case("spiral_bevel_iso23509_s1.toml")
    tool = case.gear.flank(flank)
    bl = tool.blade
    fs = flank_surface(case, "gear", flank, nu=9, nv=7, v_limits=(0.2, 1.0))
    ok = fs.valid
    rho = blade_profile(bl, fs.s[ok]).rho
    k_par = -bl.sigma * math.cos(bl.blade_angle) / rho
    expected_hi = np.maximum(k_par, 0.0)
    expected_lo = np.minimum(k_par, 0.0)
    np.testing.assert_allclose(fs.kappa1[ok], expected_hi, atol=1e-12)
    np.testing.assert_allclose(fs.kappa2[ok], expected_lo, atol=1e-12)
    # the zero-curvature direction is the blade (meridian): ⟂ to the cutter's parallel circle
    zero_dir = np.where((k_par > 0)[:, None], fs.dir2[ok], fs.dir1[ok])
    from geometry.machine.cradle import cutter_pose

    _, axis = cutter_pose(tool.machine, 0.0)
    # a meridian lies in a plane through the cutter axis: ⟂ to axis × (point − centre)
    centre, _ = cutter_pose(tool.machine, 0.0)
    circ = np.cross(axis, fs.position[ok] - centre)
    circ /= np.linalg.norm(circ, axis=-1, keepdims=True)
    np.testing.assert_allclose((zero_dir * circ).sum(-1), 0.0, atol=1e-12)


def _quadric_fit(p0, n, e1, e2, pts):
    """Principal curvatures of the graph w(x, y) fitted by least squares (cubic terms kept)."""
    d = pts - p0
    x, y, w = d @ e1, d @ e2, d @ n
    a = np.stack([np.ones_like(x), x, y, x * x / 2, x * y, y * y / 2,
                  x**3, x * x * y, x * y * y, y**3], -1)
    c = np.linalg.lstsq(a, w, rcond=None)[0]
    hess = -np.array([[c[3], c[4]], [c[4], c[5]]])  # κ = −w'' with n out of the material
    return np.linalg.eigvalsh(hess)[::-1]


@pytest.mark.parametrize("name, flank, ij", [
    ("spiral_bevel_iso23509_s1.toml", "concave", (3, 3)),
    ("spiral_bevel_iso23509_s1.toml", "convex", (5, 2)),
    ("hypoid_iso23509_s2.toml", "concave", (1, 5)),
    ("hypoid_iso23509_s2.toml", "convex", (4, 4)),
])
def test_generated_curvatures_match_finite_differences(name, flank, ij):
    """Generated pinion (Generate, circular blades): principal curvatures from implicit
    differentiation agree with a quadric fitted to a 5×5 patch of solved points 0.025 mm
    apart to 1e-3 of the largest |κ|; the fit's error falls ~h² (ratio > 3 between
    h = 0.1 and 0.05 mm) — evidence that the difference is the fit's truncation."""
    case = _case(name)
    mem = case.pinion
    tool = mem.flank(flank)
    bl = mem.blank
    fs = flank_surface(case, "pinion", flank, nu=7, nv=7, v_limits=(0.3, 1.0))
    i, j = ij
    assert fs.valid[i, j] and fs.section[i, j] == profile_sections(tool.blade).main
    p0, n = fs.position[i, j], fs.normal[i, j]
    e1, e2 = fs.dir1[i, j], fs.dir2[i, j]
    k_an = np.array([fs.kappa1[i, j], fs.kappa2[i, j]])
    errors = []
    for h in (0.1, 0.05, 0.025):
        a = np.arange(-2, 3) * h
        zz, pp = np.meshgrid(fs.grid.axial[i, j] + a, fs.grid.radius[i, j] + a, indexing="ij")
        sol = solve_envelope(tool.blade, tool.machine, zz, pp,
                             length_scale=bl.outer_cone_distance,
                             depth=bl.outer_addendum + bl.outer_dedendum)
        assert np.all(sol.reason == 0)
        pts = sol.position.reshape(-1, 3)
        if mem.hand == "left":
            pts = pts * MIRROR
        k_fd = _quadric_fit(p0, n, e1, e2, pts)
        errors.append(np.abs(k_fd - k_an).max() / np.abs(k_an).max())
    assert errors[-1] < 1e-3
    assert errors[0] / errors[1] > 3.0


def test_principal_directions_orthonormal_and_right_handed():
    """e1, e2 unit, orthogonal, e2 = n × e1, both ⟂ n (identities of the construction)."""
    fs = flank_surface(_case("hypoid_iso23509_s2.toml"), "pinion", "convex", nu=9, nv=5)
    ok = fs.valid
    e1, e2, n = fs.dir1[ok], fs.dir2[ok], fs.normal[ok]
    np.testing.assert_allclose(np.linalg.norm(e1, axis=-1), 1.0, atol=1e-13)
    np.testing.assert_allclose(np.linalg.norm(e2, axis=-1), 1.0, atol=1e-13)
    np.testing.assert_allclose((e1 * e2).sum(-1), 0.0, atol=1e-13)
    np.testing.assert_allclose((e1 * n).sum(-1), 0.0, atol=1e-13)
    np.testing.assert_allclose(np.cross(n, e1), e2, atol=1e-13)
    assert np.all(fs.kappa1[ok] >= fs.kappa2[ok])


def test_euler_relation_against_eigh():
    """principal_from_directional equals the eigen-decomposition of [[k1, τ], [τ, k2]]
    (numpy.linalg.eigh) to 1e-14."""
    rng = np.random.default_rng(7)
    k1, k2, tau = rng.normal(size=(3, 50)) * 0.05
    t1 = np.tile([1.0, 0.0, 0.0], (50, 1))
    t2 = np.tile([0.0, 1.0, 0.0], (50, 1))
    pc = principal_from_directional(k1, k2, tau, t1, t2)
    for k in range(50):
        w, v = np.linalg.eigh(np.array([[k1[k], tau[k]], [tau[k], k2[k]]]))
        assert pc.kappa1[k] == pytest.approx(w[1], abs=1e-14)
        assert pc.kappa2[k] == pytest.approx(w[0], abs=1e-14)
        assert abs(pc.dir1[k, :2] @ v[:, 1]) == pytest.approx(1.0, abs=1e-12)


def test_principal_direction_sign_is_fixed_by_the_convention():
    """e1 · (t1 + t2) > 0 everywhere (the stated sign convention), and a torsion τ that is
    round-off of either sign (±1e-17 where k_t1 < k_t2: e1 ∥ t2) gives the same e1 to
    1e-15 — the case whose sign flipped between CPUs (issue 31)."""
    rng = np.random.default_rng(11)
    k1, k2, tau = rng.normal(size=(3, 200)) * 0.05
    t1 = np.tile([1.0, 0.0, 0.0], (200, 1))
    t2 = np.tile([0.0, 1.0, 0.0], (200, 1))
    pc = principal_from_directional(k1, k2, tau, t1, t2)
    assert np.all((pc.dir1 * (t1 + t2)).sum(-1) > 0.0)
    plus = principal_from_directional(0.01, 0.05, 1e-17, t1[0], t2[0])
    minus = principal_from_directional(0.01, 0.05, -1e-17, t1[0], t2[0])
    np.testing.assert_allclose(plus.dir1, minus.dir1, atol=1e-15)
    np.testing.assert_allclose(plus.dir2, minus.dir2, atol=1e-15)
    np.testing.assert_allclose(plus.dir1, [0.0, 1.0, 0.0], atol=1e-15)


def _cylinder(radius, axis_angle):
    """Cylinder of radius R, axis in the tangent plane at angle ψ, normal +z (convex)."""
    along = np.array([math.cos(axis_angle), math.sin(axis_angle), 0.0])
    across = np.array([-math.sin(axis_angle), math.cos(axis_angle), 0.0])
    return PrincipalCurvatures(np.array(1.0 / radius), np.array(0.0), across, -along)


def test_normal_curvature_of_a_cylinder():
    """Euler's formula on a cylinder: κ(t) = cos²φ / R with φ from the circumferential
    direction (closed form)."""
    cyl = _cylinder(20.0, 0.3)
    for phi in np.linspace(0, math.pi, 7):
        t = math.cos(phi) * cyl.dir1 + math.sin(phi) * cyl.dir2
        assert normal_curvature(cyl.kappa1, cyl.kappa2, cyl.dir1, t) == pytest.approx(
            math.cos(phi) ** 2 / 20.0, abs=1e-15)


@pytest.mark.parametrize("r1, r2, crossing", [(20.0, 35.0, 0.0), (20.0, 35.0, 0.7),
                                              (15.0, 80.0, 1.2), (30.0, 30.0, math.pi / 2)])
def test_relative_curvature_crossed_cylinders(r1, r2, crossing):
    """Two convex cylinders crossed at angle ψ: the principal relative curvatures are
    A + B ± (B − A) with A + B = ½(1/R1 + 1/R2), B − A = ½ √(1/R1² + 1/R2² + 2 cos 2ψ/(R1 R2))
    (Hertz; Johnson, Contact Mechanics, Eq. 4.17); also the extremes of a brute-force sweep of
    κ_p(t) + κ_g(t) over 3601 directions."""
    p = _cylinder(r1, 0.0)
    g = _cylinder(r2, crossing)
    rel = relative_curvature(p, g)
    s = 0.5 * (1 / r1 + 1 / r2)
    d = 0.5 * math.sqrt(1 / r1**2 + 1 / r2**2 + 2 * math.cos(2 * crossing) / (r1 * r2))
    assert float(rel.kappa1) == pytest.approx(s + d, rel=1e-12)
    assert float(rel.kappa2) == pytest.approx(s - d, abs=1e-12)
    phis = np.linspace(0, math.pi, 3601)
    ts = np.stack([np.cos(phis), np.sin(phis), 0 * phis], -1)
    tot = (normal_curvature(p.kappa1, p.kappa2, p.dir1, ts)
           + normal_curvature(g.kappa1, g.kappa2, g.dir1, ts))
    assert tot.max() == pytest.approx(float(rel.kappa1), rel=1e-6)  # sweep step 0.05°
    assert tot.min() == pytest.approx(float(rel.kappa2), abs=1e-8)
    k_dir = (normal_curvature(p.kappa1, p.kappa2, p.dir1, rel.dir1)
             + normal_curvature(g.kappa1, g.kappa2, g.dir1, rel.dir1))
    assert float(k_dir) == pytest.approx(float(rel.kappa1), rel=1e-12)


def test_equivalent_radius():
    """R_eq = R_p R_g/(R_p + R_g) (seed §2.2.4) for convex–convex and convex–concave pairs;
    +inf where the relative curvature is not positive; non-finite input rejected."""
    rp = np.array([10.0, 25.0, 40.0, 10.0])
    rg = np.array([30.0, 60.0, -80.0, -10.0])
    out = equivalent_radius(1 / rp, 1 / rg)
    np.testing.assert_allclose(out[:3], rp[:3] * rg[:3] / (rp[:3] + rg[:3]), rtol=1e-14)
    assert out[3] == np.inf
    with pytest.raises(InputError, match="kappa_p"):
        equivalent_radius(np.nan, 0.1)
