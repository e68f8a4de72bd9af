"""Fast paths of the compliance assembly against the formulations they replaced.

The per-roll LTCA loop uses faster but equivalent internals of
:mod:`contact.compliance.tooth` and :mod:`contact.compliance.shell`:

* the orthogonal-trajectory RK4 with the v-dependent parts evaluated once
  (:func:`_trajectory`) against the plain RK4 (:func:`_trajectory_reference`);
* the Newton projection onto the mid-surface (:func:`_project_to_mid`) against the
  Gauss–Newton projection (:func:`_project_to_mid_reference`) and against feet known by
  construction;
* C = Yᵀ Y with Y = U⁻ᵀ S Φ (one triangular solve) against Φᵀ (K⁻¹ Φ) (``cho_solve``).

The trajectory and the projection are checked on both implementations: NumPy and the
compiled kernels (:mod:`contact.compliance.tooth_map_numba`), one tooth at a time and two
teeth stacked in one batch.
"""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
import pytest

from contact.compliance.shell import ShellTooth, build_shell_model, compliance_blocks
from contact.compliance.shell_tooth import THEORIES
from contact.compliance.tooth import _PROJ_ITER, _project_to_mid, shell_tooth_from_case
from contact.compliance.tooth_map import _TRAJ_STEPS, KERNEL_MODULE, _mid_rows, stack_surfaces
from contact.compliance.tooth_map import angle_rows as _angle_rows
from contact.compliance.tooth_map import blank_rows as _blank_rows
from contact.compliance.tooth_map import frames as _frames
from contact.compliance.tooth_map import trajectory as _trajectory
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.core.kernels import compiled_module
from geometry.machine.flank import projection_fractions

ROOT = Path(__file__).resolve().parents[1]


# ----------------------------------------------------------- the replaced formulations
def _slope(surf, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """du/dv along the mid-surface curves orthogonal to the lengthwise curves v = const.

    At 1-D (u, v): −(M_u·M_v)/(M_u·M_u) with M = (ρ cos φ, ρ sin φ, z); the rotation
    terms cancel, M_u·M_v = p_u·p_v + ρ² φ_u φ_v and |M_u|² = |p_u|² + ρ² φ_u² with
    p = (z, ρ) the blank map.
    """
    _, rho, pu_z, pu_r, pv_z, pv_r = _blank_rows(surf, u, v)
    phi_u, phi_v = _angle_rows(surf, u, v, slice(1, 3))
    rfu = rho * rho * phi_u
    return -(pu_z * pv_z + pu_r * pv_r + rfu * phi_v) / (pu_z * pu_z + pu_r * pu_r
                                                        + rfu * phi_u)


def _trajectory_reference(surf, u, v0, v1) -> np.ndarray:
    """u at profile fraction v1 on the orthogonal trajectory through (u, v0) (RK4).

    The plain formulation (:func:`_slope` at every stage) that :func:`_trajectory`
    replaced: the same scheme with the v-dependent parts evaluated once.
    """
    u = np.asarray(u, dtype=float)
    shape = u.shape
    u = u.ravel().copy()
    v = np.broadcast_to(np.asarray(v0, dtype=float), shape).ravel().copy()
    h = (np.broadcast_to(np.asarray(v1, dtype=float), shape).ravel() - v) / _TRAJ_STEPS
    h2 = 0.5 * h
    h6 = h / 6.0
    for _ in range(_TRAJ_STEPS):
        vh = v + h2
        k1 = _slope(surf, u, v)
        k2 = _slope(surf, u + h2 * k1, vh)
        k3 = _slope(surf, u + h2 * k2, vh)
        v = v + h
        k4 = _slope(surf, u + h * k3, v)
        u = u + h6 * (k1 + 2.0 * (k2 + k3) + k4)
    return u.reshape(shape)



def _project_to_mid_reference(surf, p: np.ndarray, u, v):
    """Foot (u, v) of points p on the mid-surface along its normal (Gauss–Newton): the
    formulation that :func:`_project_to_mid` (Newton, exact Hessian) replaced.

    Solves (p − M)·M_u = (p − M)·M_v = 0; the neglected curvature terms are
    O(offset / radius of curvature) ≈ 0.05, so each step gains > 1 digit.
    """
    u = np.array(u, dtype=float)
    v = np.array(v, dtype=float)
    px, py, pz = np.asarray(p, dtype=float).T
    for _ in range(_PROJ_ITER):
        mx, my, mz, ux, uy, uz, vx, vy, vz = _mid_rows(surf, u, v)
        rx, ry, rz = px - mx, py - my, pz - mz
        g1 = rx * ux + ry * uy + rz * uz
        g2 = rx * vx + ry * vy + rz * vz
        a11 = ux * ux + uy * uy + uz * uz
        a12 = ux * vx + uy * vy + uz * vz
        a22 = vx * vx + vy * vy + vz * vz
        det = a11 * a22 - a12 * a12
        du = (a22 * g1 - a12 * g2) / det
        dv = (a11 * g2 - a12 * g1) / det
        u += du
        v += dv
        if (np.abs(du) + np.abs(dv)).max() < 1e-14:
            break
    return u, v


@functools.cache
def _tooth(member: str):
    return shell_tooth_from_case(load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml"), member)


#: the point mapping's implementations: NumPy and, where numba is installed, the compiled
#: kernels (contact.compliance.tooth_map_numba: the same formulas point by point)
KERNEL_PATHS = ["numpy", pytest.param("numba", marks=pytest.mark.skipif(
    compiled_module(KERNEL_MODULE) is None, reason="numba (the 'fast' extra) is not installed"))]


@pytest.mark.parametrize("kernels", KERNEL_PATHS)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_trajectory_fast_equals_reference(member, kernels, monkeypatch):
    monkeypatch.setenv("LTCA_KERNELS", kernels)
    data = _tooth(member)
    rng = np.random.default_rng(3)
    u = rng.uniform(-0.05, 1.05, 200)
    v = rng.uniform(-0.05, 1.05, 200)
    # same RK4 scheme, only the evaluation order differs: agreement to round-off; 1e-13
    # in u is ~100 ulp of the [0, 1] fractions
    for args in ((u, v, 0.5), (u, 0.5, v)):
        np.testing.assert_allclose(_trajectory(data.surface, *args),
                                   _trajectory_reference(data.surface, *args), rtol=0, atol=1e-13)


@pytest.mark.parametrize("kernels", KERNEL_PATHS)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_newton_projection_finds_known_feet(member, kernels, monkeypatch):
    monkeypatch.setenv("LTCA_KERNELS", kernels)
    data = _tooth(member)
    rng = np.random.default_rng(4)
    u = rng.uniform(0.0, 1.0, 150)
    v = rng.uniform(0.0, 1.0, 150)
    m, frame = _frames(data.surface, u, v)
    # points up to a half tooth thickness off the mid-surface along its normal: their foot
    # is (u, v) by construction (the normal is orthogonal to M_u and M_v)
    half = 0.5 * data.tooth.thickness(v * data.tooth.height(0.3), 0.3)
    pts = m + (rng.uniform(-1.0, 1.0, u.size) * half)[:, None] * frame[:, 2, :]
    u0, v0 = projection_fractions(data.corners, pts[:, 2], np.hypot(pts[:, 0], pts[:, 1]))
    un, vn = _project_to_mid(data.surface, pts, u0, v0)
    ur, vr = _project_to_mid_reference(data.surface, pts, u0, v0)
    # both iterate until |du| + |dv| < 1e-14; 1e-13 leaves room for the round-off of M
    np.testing.assert_allclose(un, u, rtol=0, atol=1e-13)
    np.testing.assert_allclose(vn, v, rtol=0, atol=1e-13)
    np.testing.assert_allclose(un, ur, rtol=0, atol=1e-13)
    np.testing.assert_allclose(vn, vr, rtol=0, atol=1e-13)


@pytest.mark.parametrize("kernels", KERNEL_PATHS)
def test_stacked_teeth_map_as_each_alone(kernels, monkeypatch):
    """Both members' points in one batch (stack_surfaces: per-point blank maps, each tooth
    its own angle polynomials) give each point what its tooth alone gives: the projection
    and the trajectory per point, to round-off (1e-13 in the fractions, as above)."""
    monkeypatch.setenv("LTCA_KERNELS", kernels)
    teeth = [_tooth("pinion"), _tooth("gear")]
    rng = np.random.default_rng(9)
    sizes = (70, 90)
    pts, starts, alone = [], [], []
    for data, n in zip(teeth, sizes, strict=True):
        u = rng.uniform(0.0, 1.0, n)
        v = rng.uniform(0.0, 1.0, n)
        m, frame = _frames(data.surface, u, v)
        p = m + rng.uniform(-0.5, 0.5, n)[:, None] * frame[:, 2, :]
        u0, v0 = projection_fractions(data.corners, p[:, 2], np.hypot(p[:, 0], p[:, 1]))
        uf, vf = _project_to_mid(data.surface, p, u0, v0)
        alone.append((uf, vf, _trajectory(data.surface, uf, vf, 0.5)))
        pts.append(p)
        starts.append((u0, v0))
    surf = stack_surfaces([t.surface for t in teeth], sizes)
    uf, vf = _project_to_mid(surf, np.concatenate(pts), *(np.concatenate(a) for a in
                                                         zip(*starts, strict=True)))
    xi = _trajectory(surf, uf, vf, 0.5)
    for got, want in zip((uf, vf, xi), zip(*alone, strict=True), strict=True):
        np.testing.assert_allclose(got, np.concatenate(want), rtol=0, atol=1e-13)


@pytest.mark.parametrize("modes", [(5, 9), (6, 21)])  # (6, 21): the LTCA's default model
def test_half_solve_compliance_equals_cho_solve(modes):
    tooth = ShellTooth.from_face_width(thickness_toe_root=8.0, thickness_heel_root=10.0,
                                       thickness_tip=3.0, height_toe=9.0, height_heel=11.0,
                                       face_width=40.0, radius=80.0, youngs_modulus=206000.0,
                                       poisson_ratio=0.3)
    model = build_shell_model(tooth, *modes)
    rng = np.random.default_rng(5)
    n = 12
    theta = rng.uniform(0.05, 0.9, n) * tooth.subtended_angle
    x = rng.uniform(0.1, 0.9, n) * tooth.height(theta)
    ends = np.stack([np.column_stack([x, theta]),
                     np.column_stack([x, theta + 0.04 * tooth.subtended_angle])], axis=1)
    normal = np.tile([0.1, 0.05, 1.0], (n, 1))
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    blocks = [np.arange(5), np.arange(5, n)]
    got = compliance_blocks(model, ends, normal, blocks)
    # reference: C = Φᵀ K⁻¹ Φ with the two-sided Cholesky solve, Φ the segment-averaged
    # load vectors (4 Gauss points, as compliance_blocks)
    s, w = np.polynomial.legendre.leggauss(4)
    s, w = 0.5 * (s + 1.0), 0.5 * w
    gp = (ends[:, None, 0] + s[None, :, None] * (ends[:, None, 1] - ends[:, None, 0]))
    gp = gp.reshape(-1, 2)
    zs = 0.5 * tooth.thickness(gp[:, 0], gp[:, 1])
    phi = model.load_vectors(gp[:, 0], gp[:, 1], -np.repeat(normal, 4, axis=0), zs)
    phi = (phi.reshape(-1, n, 4) * w).sum(axis=2)
    full = phi.T @ model.solve(phi)
    for idx, cm in zip(blocks, got, strict=True):
        ref = full[np.ix_(idx, idx)]
        # same matrix in exact arithmetic; 1e-12 relative covers the round-off of the
        # factorisation (condition of the Jacobi-scaled stiffness ~1e6)
        np.testing.assert_allclose(cm.matrix, 0.5 * (ref + ref.T), rtol=1e-12,
                                   atol=1e-12 * np.abs(ref).max())


def test_half_solve_with_the_scale_folded_equals_the_scaled_loads_product():
    """half_solve's operator U⁻ᵀ S (the scale folded in once, issue 75) against the
    product it replaced, U⁻ᵀ (S F) with U⁻ᵀ formed from the model's own Cholesky factor:
    the same numbers but for the order each term's two products are rounded in. On the
    default case's pinion model (378 unknowns) at 1,576 study-point load vectors the
    measured difference is 9.6e-15 of max |Y| and 1.3e-15 of max |YᵀY| (each Y entry a sum of
    ≤ 378 terms, each rounded once more or less: ≲ 378 ε of the terms' magnitude, and the
    terms' cancellation is bounded by cond U ≤ 2e6); the tolerances 1e-13 on Y and 1e-14
    on the compliance YᵀY hold that with an order of magnitude to spare and are far below
    the sweep guard's 1e-9."""
    from scipy import linalg

    model = build_shell_model(_tooth("pinion").tooth, 6, 21)
    rng = np.random.default_rng(12)
    n, g = 1576, 4
    tth = model.tooth
    theta = rng.uniform(0.0, 1.0, n * g) * tth.subtended_angle
    x = rng.uniform(0.0, 1.0, n * g) * tth.height(theta)
    d = rng.normal(size=(n * g, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    zs = rng.uniform(-1.0, 1.0, n * g)
    phi = model.load_vectors(x, theta, d, zs, group_weights=np.full(g, 1.0 / g))
    inverse = np.asfortranarray(np.tril(linalg.solve_triangular(
        model._factor[0], np.eye(model.n_dof), trans="T", lower=False)))
    want = linalg.blas.dtrmm(1.0, inverse, np.multiply(model._scale[:, None], phi, order="F"),
                             lower=1, overwrite_b=1)
    got = model.half_solve(phi)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-13 * np.abs(want).max())
    c_got, c_want = got.T @ got, want.T @ want
    np.testing.assert_allclose(c_got, c_want, rtol=0, atol=1e-14 * np.abs(c_want).max())


def test_half_solve_in_place_equals_the_copy():
    """half_solve(F, overwrite_loads=True): the same Y bit for bit as with a copy, written
    into F where F is a Fortran-ordered float array (no copy), and F left as it was where
    it is not (a C-ordered array is copied as without the flag)."""
    tooth = ShellTooth.from_face_width(thickness_toe_root=8.0, thickness_heel_root=10.0,
                                       thickness_tip=3.0, height_toe=9.0, height_heel=11.0,
                                       face_width=40.0, radius=80.0, youngs_modulus=206000.0,
                                       poisson_ratio=0.3)
    model = build_shell_model(tooth, 5, 9)
    loads = np.random.default_rng(3).normal(size=(model.n_dof, 11))
    want = model.half_solve(loads)
    for order, in_place in (("F", True), ("C", False)):
        f = np.array(loads, order=order)
        got = model.half_solve(f, overwrite_loads=True)
        np.testing.assert_array_equal(got, want)
        assert np.shares_memory(got, f) is in_place
        if not in_place:
            np.testing.assert_array_equal(f, loads)


@pytest.mark.parametrize("kernels", KERNEL_PATHS)
@pytest.mark.parametrize("theory", sorted(THEORIES))
def test_grouped_load_vectors_equal_the_weighted_sums(theory, kernels, monkeypatch):
    """load_vectors(..., group_weights=w): each group's Σ w_g φ_g, as the per-point
    vectors summed (the same products in another order: round-off, 1e-13 of the
    largest entry), for every theory (a rotating family's ∂W/∂θ term, families without
    work of a force: the one stacked product of every family), the factors filled by
    NumPy or by the compiled kernel; a group size that does not divide the points is
    refused."""
    monkeypatch.setenv("LTCA_KERNELS", kernels)
    tooth = ShellTooth.from_face_width(thickness_toe_root=8.0, thickness_heel_root=10.0,
                                       thickness_tip=3.0, height_toe=9.0, height_heel=11.0,
                                       face_width=40.0, radius=80.0, youngs_modulus=206000.0,
                                       poisson_ratio=0.3)
    model = build_shell_model(tooth, 5, 9, theory=theory)
    rng = np.random.default_rng(8)
    n, g = 7, 3
    theta = rng.uniform(0.05, 0.9, n * g) * tooth.subtended_angle
    x = rng.uniform(0.1, 0.9, n * g) * tooth.height(theta)
    d = rng.normal(size=(n * g, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    zs = rng.uniform(-1.0, 1.0, n * g)
    w = np.array([0.2, 0.5, 0.3])
    per_point = model.load_vectors(x, theta, d, zs)
    grouped = model.load_vectors(x, theta, d, zs, group_weights=w)
    ref = (per_point.reshape(-1, n, g) * w).sum(axis=2)
    np.testing.assert_allclose(grouped, ref, rtol=0, atol=1e-13 * np.abs(ref).max())
    with pytest.raises(InputError, match="group_weights"):
        model.load_vectors(x, theta, d, zs, group_weights=np.ones(4))


@pytest.mark.skipif(compiled_module(KERNEL_MODULE) is None,
                    reason="numba (the 'fast' extra) is not installed")
@pytest.mark.parametrize("theory", sorted(THEORIES))
def test_grouped_load_vectors_compiled_equal_numpy_bit_for_bit(theory):
    """The compiled fill of the grouped load vectors' factors
    (contact.compliance.shell_loads_numba) forms every entry by the NumPy path's own
    operations in its order, so the vectors are the NumPy path's bit for bit (tolerance 0),
    for every theory and for the default case's pinion model at a study point's segment
    count and Gauss points (4 a segment)."""
    tooth = ShellTooth.from_face_width(thickness_toe_root=8.0, thickness_heel_root=10.0,
                                       thickness_tip=3.0, height_toe=9.0, height_heel=11.0,
                                       face_width=40.0, radius=80.0, youngs_modulus=206000.0,
                                       poisson_ratio=0.3)
    models = [build_shell_model(tooth, 5, 9, theory=theory)]
    if theory == "seed":  # the default case's pinion model (the seed theory, 378 unknowns)
        models.append(build_shell_model(_tooth("pinion").tooth, 6, 21, theory=theory))
    rng = np.random.default_rng(11)
    for model in models:
        tth = model.tooth
        n, g = 1576, 4
        theta = rng.uniform(0.0, 1.0, n * g) * tth.subtended_angle
        x = rng.uniform(0.0, 1.0, n * g) * tth.height(theta)
        d = rng.normal(size=(n * g, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        zs = rng.uniform(-1.0, 1.0, n * g)
        w = np.array([0.17, 0.33, 0.33, 0.17])
        xi = x / model.reference_height
        eta = 2.0 * theta / tth.subtended_angle - 1.0
        got = model._grouped_load_vectors(xi, eta, d, zs, w, kernels="numba")
        want = model._grouped_load_vectors(xi, eta, d, zs, w, kernels="numpy")
        np.testing.assert_array_equal(got, want)


def test_segment_geometry_cycle_reuse_equals_direct():
    """Rolls whole mesh cycles apart are computed once: equal to computing every roll."""
    from contact.ltca.segments import _segment_geometry, segment_geometry
    from contact.utca.easeoff import ease_off

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    eo = ease_off(case)
    roll = 0.1 + np.arange(8) * eo.pitch / 4  # two mesh cycles of 4 rolls
    pairs = np.array([-1, 0, 1])
    seg = segment_geometry(case, eo, roll, pairs, 6)
    np.testing.assert_array_equal(seg.source, [0, 1, 2, 3, 0, 1, 2, 3])
    cycle = np.floor((roll - roll[0]) / eo.pitch + 1e-9)
    target = roll[:, None] - (cycle[:, None] + pairs[None, :]) * eo.pitch
    rp = eo.roll_zero + eo.drive_sense * (roll - cycle * eo.pitch)
    direct = _segment_geometry(case, eo, target, rp, 6, "cosine")
    for key in ("midpoint_pair", "ends_pair", "normal_pair", "length", "moment_arm", "lag",
                "r_eq", "ute", "pinion_rotation"):
        # the second cycle's targets differ from the first's by round-off (~1e-16 rad);
        # the iterative curve and curvature solvers reach the same points to ~1e-12
        np.testing.assert_allclose(getattr(seg, key), getattr(direct, key), rtol=1e-9, atol=1e-12,
                                   equal_nan=True, err_msg=key)


def _flank_points(data, rng, n):
    """Points on both flanks of a member's reference tooth (member frame) with outward
    normals: mid-surface feet pushed ±(half thickness) along the shell normal e_z."""
    u = rng.uniform(0.15, 0.85, n)  # away from the blank's edges: the offset points'
    v = rng.uniform(0.15, 0.85, n)  # projection-plane places stay on the blank
    m, frame = _frames(data.surface, u, v)
    side = np.where(rng.uniform(size=n) < 0.5, -1.0, 1.0)
    half = 0.5 * data.tooth.thickness(v * data.tooth.height(0.3), 0.3)
    return m + (side * half)[:, None] * frame[:, 2, :], side[:, None] * frame[:, 2, :]


def test_shell_points_of_both_members_in_one_batch_equal_separate():
    """Both members' points mapped in one batch (shell_points_many, the LTCA's path)
    equal each member mapped on its own (_shell_points, one tooth per batch)."""
    from contact.compliance.tooth import _shell_points, shell_points_many

    rng = np.random.default_rng(6)
    jobs = []
    for member in ("pinion", "gear"):
        data = _tooth(member)
        pts, nrm = _flank_points(data, rng, 40)
        extra, _ = _flank_points(data, rng, 30)
        jobs.append((data, pts, nrm, None, extra))
    both = shell_points_many(jobs, 1e-6)
    for job, got in zip(jobs, both, strict=True):
        alone = _shell_points(job[0], *job[1:4], 1e-6, extra=job[4])
        for sp_got, sp_ref in zip(got, alone, strict=True):
            for name in ("x", "theta", "u", "v", "side", "offset", "frame", "normal"):
                a, b = getattr(sp_got, name), getattr(sp_ref, name)
                if b is None:
                    assert a is None
                    continue
                # same arithmetic per point; the batch may take one more Newton step
                # (it iterates until its slowest point converged, |Δu| + |Δv| < 1e-14):
                # 1e-12 in mm, rad or [1] is a few hundred ulp of these magnitudes
                np.testing.assert_allclose(a, b, rtol=0, atol=1e-12, err_msg=name)


def test_distinct_ends_rebuild_the_segment_ends():
    from contact.compliance.mesh import _distinct_ends

    rng = np.random.default_rng(7)
    # two curves of 5 and 3 chained segments, then one lone segment
    curves = [rng.normal(size=(6, 3)), rng.normal(size=(4, 3)), rng.normal(size=(2, 3))]
    ends = np.concatenate([np.stack([c[:-1], c[1:]], axis=1) for c in curves])
    points, index = _distinct_ends(ends)
    # identity: every end is found again bit for bit, each shared end listed once
    np.testing.assert_array_equal(points[index].reshape(2, -1, 3).transpose(1, 0, 2), ends)
    assert points.shape[0] == ends.shape[0] + len(curves)


def test_loaded_tca_given_transitions_equals_computed():
    """The pipeline hands the UTCA's M1, M2 to loaded_tca: same analysis as computing them."""
    from contact.ltca import LTCAOptions, loaded_tca
    from contact.utca import unloaded_tca
    from contact.utca.easeoff import ease_off
    from geometry.core.errors import InputError

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    eo = ease_off(case)
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8)
    _, ut = unloaded_tca(case, easeoff=eo)
    given = loaded_tca(case, 200.0, options=opts, easeoff=eo,
                       transitions=tuple(ut["transition_roll"].values))
    computed = loaded_tca(case, 200.0, options=opts, easeoff=eo)
    # the same transitions function with the same defaults: the same rolls and results,
    # to round-off (1e-12 relative: two runs of one computation may differ in the last bits
    # where numpy's SIMD loops treat an array's unaligned head apart)
    for name in ("roll", "transmission_error", "force"):
        np.testing.assert_allclose(given[name].values, computed[name].values, rtol=1e-12,
                                   atol=0, err_msg=name)
    with pytest.raises(InputError, match="transitions"):
        loaded_tca(case, 200.0, options=opts, easeoff=eo, transitions="M1")


def test_mesh_compliance_of_several_rolls_in_one_batch_equals_one_by_one():
    """mesh_compliance_many maps all rolls' segments onto the shells in one batch and
    solves all their tooth pairs' shell loads together: each roll's matrices equal
    mesh_compliance of that roll alone to round-off (1e-12 relative: the batched Newton
    and RK4 iterate until the slowest point converges, the triangular solve is the same)."""
    from contact.compliance.mesh import mesh_compliance, mesh_compliance_many

    case, batch = _three_rolls()
    # a roll with two tooth pairs in mesh: blocks of several pairs per roll are covered
    assert max(len(np.unique(b.pair_index)) for b in batch) >= 2
    many = mesh_compliance_many(case, batch)
    for b, (C, info) in zip(batch, many, strict=True):
        C1, info1 = mesh_compliance(case, b)
        np.testing.assert_allclose(C, C1, rtol=1e-12, atol=1e-12 * np.abs(C1).max())
        np.testing.assert_allclose(info["weber_depth"], info1["weber_depth"], rtol=1e-12)
    assert mesh_compliance_many(case, []) == []


def test_kept_points_and_columns_equal_a_fresh_assembly():
    """Each point's shell coordinates and each segment's column of Y kept per tooth model
    (issue 75 item 4: ``_point_store``, ``_half_vector_store``): a repeat, whose points and
    columns are all kept, gives the fresh assembly's matrices to the bit (the kept values
    are that assembly's own); rolls of which only some are kept (the first roll alone
    first, then all three) agree with it to round-off (1e-12 relative: the kept values come
    from another batch, whose triangular product and mapping iterations differ in the
    last bits); so do the matrices after the stores are emptied."""
    from contact.compliance import mesh as mesh_mod
    from contact.compliance import shell as shell_mod
    from contact.compliance.mesh import mesh_compliance_many, pair_compliance_model

    def empty():
        mesh_mod._point_store.cache_clear()
        shell_mod._half_vector_store.cache_clear()

    case, batch = _three_rolls()
    model = pair_compliance_model(case)
    empty()
    fresh = mesh_compliance_many(case, batch, model=model)
    again = mesh_compliance_many(case, batch, model=model)
    empty()
    mesh_compliance_many(case, batch[:1], model=model)
    partly = mesh_compliance_many(case, batch, model=model)
    for (c0, i0), (c1, i1), (c2, i2) in zip(fresh, again, partly, strict=True):
        np.testing.assert_array_equal(c1, c0)
        np.testing.assert_array_equal(i1["weber_depth"], i0["weber_depth"])
        np.testing.assert_allclose(c2, c0, rtol=1e-12, atol=1e-12 * np.abs(c0).max())
        np.testing.assert_allclose(i2["weber_depth"], i0["weber_depth"], rtol=1e-12)
    assert mesh_mod._point_store.cache_info().currsize == 2  # one store per member
    empty()


def test_rows_not_kept_compute_as_a_process_that_kept_none():
    """Inside ``rows_not_kept`` (a study point, issue 75 item 4) the stores of mapped points
    and columns are neither read nor filled: with rows of the first roll kept before, the
    block's matrices are the fresh assembly's bit for bit (all rows in one batch, as with
    empty stores), and the stores hold what they held before the block."""
    from contact.compliance import mesh as mesh_mod
    from contact.compliance import shell as shell_mod
    from contact.compliance.mesh import mesh_compliance_many, pair_compliance_model
    from geometry.core.caches import Same, rows_kept, rows_not_kept

    def empty():
        mesh_mod._point_store.cache_clear()
        shell_mod._half_vector_store.cache_clear()

    case, batch = _three_rolls()
    model = pair_compliance_model(case)
    empty()
    fresh = mesh_compliance_many(case, batch, model=model)
    empty()
    mesh_compliance_many(case, batch[:1], model=model)  # the first roll's rows kept
    stores = [mesh_mod._point_store(Same(model.member(m))) for m in ("pinion", "gear")]
    before = [dict(st.rows) for st in stores]
    assert all(before)  # (the stores the assembly uses, each holding the first roll's)
    assert rows_kept()
    with rows_not_kept():
        assert not rows_kept()
        inside = mesh_compliance_many(case, batch, model=model)
    assert rows_kept()
    assert [dict(st.rows) for st in stores] == before
    for (c0, i0), (c1, i1) in zip(fresh, inside, strict=True):
        np.testing.assert_array_equal(c1, c0)
        np.testing.assert_array_equal(i1["weber_depth"], i0["weber_depth"])
    empty()


def _three_rolls():
    """The segments of three roll positions of the ISO 23509 hypoid as ContactSegments."""
    from contact.compliance.mesh import ContactSegments
    from contact.ltca import segment_geometry
    from contact.utca.easeoff import ease_off

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    eo = ease_off(case)
    roll = 0.1 + np.arange(3) * eo.pitch / 3
    pairs = np.array([-1, 0, 1])
    seg = segment_geometry(case, eo, roll, pairs, 8)
    batch = []
    for j in range(roll.size):
        k, s = np.nonzero(np.isfinite(seg.r_eq[j]) & (seg.length[j] > 0))
        batch.append(ContactSegments(
            midpoints=seg.midpoint_pair[j, k, s], ends=seg.ends_pair[j, k, s],
            normals=seg.normal_pair[j, k, s], length=seg.length[j, k, s],
            r_eq=seg.r_eq[j, k, s], pair_index=pairs[k], load=seg.length[j, k, s],
            pinion_rotation=float(seg.pinion_rotation[j]),
            gear_rotation=float(seg.gear_rotation[j])))
    return case, batch


def test_members_mapped_in_one_job_equal_the_rolls_mapped_one_job_each():
    """mesh_compliance_many turns every roll's points into the member's frame and maps each
    member's points of all rolls as one job (issue 75 item 4); the jobs of one roll and
    member each, with the roll's transform (as before), give every ShellPoints field —
    x, θ, (u, v), normal, side, offset and the frames back in the pair frame — equal to
    round-off (1e-12: the same transforms' products and the same per-point iterations)."""
    from contact.compliance.mesh import _map_members, _map_rolls, pair_compliance_model

    case, batch = _three_rolls()
    model = pair_compliance_model(case)
    per_roll, _, both = _map_members(case, batch, model)
    jobs = _map_rolls(case, batch, model)
    for r in range(len(batch)):
        for i, name in enumerate(("pinion", "gear")):
            ref_mid = jobs[2 * r + i][0]
            for field in ref_mid._fields:
                np.testing.assert_allclose(getattr(per_roll[r][name], field),
                                           getattr(ref_mid, field), rtol=1e-12, atol=1e-12,
                                           err_msg=f"roll {r} {name} {field}")
    # the ends in shell_matrices' order: every roll's first ends, then their second ends
    n = [seg.size for seg in batch]
    assert both["pinion"].x.shape == (2 * sum(n),)
    from contact.compliance.mesh import _distinct_ends
    _, idx = _distinct_ends(batch[1].ends)
    np.testing.assert_allclose(both["gear"].theta[n[0]:n[0] + n[1]],
                               jobs[3][1].theta[idx[:n[1]]], rtol=1e-12)
    np.testing.assert_allclose(both["gear"].theta[sum(n) + n[0]:sum(n) + n[0] + n[1]],
                               jobs[3][1].theta[idx[n[1]:]], rtol=1e-12)


def test_point_off_the_tooth_is_named_within_its_roll():
    """A midpoint off the tooth in the second roll of a batch: the error names the point's
    index within that roll (the batch maps again roll by roll to say so)."""
    import dataclasses

    from contact.compliance.mesh import mesh_compliance_many

    case, batch = _three_rolls()
    far = batch[1].midpoints.copy()
    far[2] = far[2] * 3.0  # three times as far from the axes: off the blank
    batch[1] = dataclasses.replace(batch[1], midpoints=far)
    with pytest.raises(InputError, match="got point 2 at"):
        mesh_compliance_many(case, batch)


def _segment_fields(n: int = 9) -> dict:
    rng = np.random.default_rng(75)
    nrm = rng.normal(size=(n, 3))
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    return dict(midpoints=rng.normal(size=(n, 3)), ends=rng.normal(size=(n, 2, 3)),
                normals=nrm, length=rng.random(n) + 0.1, r_eq=rng.random(n) + 1.0,
                pair_index=np.array([-1, 0, 1] * (n // 3)), load=rng.random(n),
                pinion_rotation=0.25, gear_rotation=-0.125)


def test_contact_segments_checked_at_once_store_what_the_general_checks_store():
    """ContactSegments' one-pass check of the LTCA's float64 arrays (issue 75) stores the
    values, dtypes and shapes the general path stores from the same data given as lists,
    as new arrays (never the caller's)."""
    from contact.compliance.mesh import ContactSegments

    fields = _segment_fields()
    fast = ContactSegments(**fields)
    general = ContactSegments(**{k: v.tolist() if isinstance(v, np.ndarray) else v
                                 for k, v in fields.items()})
    for name in ("midpoints", "ends", "normals", "length", "r_eq", "load", "pair_index",
                 "pinion_rotation", "gear_rotation"):
        a, b = getattr(fast, name), getattr(general, name)
        assert type(a) is type(b) and np.asarray(a).dtype == np.asarray(b).dtype, name
        assert np.array_equal(a, b), name
        if isinstance(a, np.ndarray):
            assert not np.shares_memory(a, fields[name]), name


@pytest.mark.parametrize(("field", "value", "message"), [
    ("length", 0.0, "length: must be finite and > 0"),
    ("r_eq", np.nan, "r_eq: must be finite and > 0"),
    ("load", -1.0, "load: must be finite and >= 0"),
    ("midpoints", np.inf, "midpoints: must be"),
    ("normals", 2.0, "normals: must be unit vectors"),
])
def test_contact_segments_refuse_through_the_general_messages(field, value, message):
    """An array the one-pass check does not accept (non-finite, out of range, not unit)
    falls to the general checks and their messages."""
    from contact.compliance.mesh import ContactSegments

    fields = _segment_fields()
    bad = fields[field].copy()
    bad[1] = value
    fields[field] = bad
    with pytest.raises(InputError, match=message.replace("(", r"\(")):
        ContactSegments(**fields)


# ------------------------------------------- whole-array passes over rolls (issue 75 item 4)
def _interp_rows(a: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """The row-by-row form fill_rows replaced: numpy.interp of each row's valid entries."""
    out = np.array(a, dtype=float)
    idx = np.arange(out.shape[1])
    for i in range(out.shape[0]):
        good = valid[i] & np.isfinite(out[i])
        out[i] = np.interp(idx, idx[good], out[i, good])
    return out


def test_fill_rows_equals_numpy_interp_row_by_row():
    """fill_rows fills all rows in whole-array passes with numpy.interp's arithmetic: every
    row equal to numpy.interp of its valid entries bit for bit (tolerance 0: the same
    operations on the same operands), on rows with gaps at the start, inside and at the
    end, a single valid entry, none missing, and NaN entries marked valid."""
    from contact.ltca.discretisation import fill_rows

    rng = np.random.default_rng(79)
    for _ in range(300):
        rows, cols = int(rng.integers(1, 40)), int(rng.integers(1, 20))
        a = rng.normal(size=(rows, cols)) * 10.0 ** rng.uniform(-3, 3)
        valid = rng.random((rows, cols)) < rng.uniform(0.1, 1.0)
        a[rng.random((rows, cols)) < 0.05] = np.nan  # invalid whatever valid says
        empty = ~(valid & np.isfinite(a)).any(axis=1)
        j = rng.integers(0, cols, size=int(empty.sum()))
        valid[np.flatnonzero(empty), j] = True
        a[np.flatnonzero(empty), j] = 1.5
        np.testing.assert_array_equal(fill_rows(a, valid), _interp_rows(a, valid))
    with pytest.raises(ValueError, match="no valid entry"):
        fill_rows(np.ones((2, 3)), np.array([[True, False, True], [False] * 3]))


def test_distinct_ends_of_rolls_equal_each_roll_alone():
    """The distinct ends of all rolls in one pass are each roll's (_distinct_ends of its
    segments alone), roll after roll, bit for bit; an end shared across two rolls (a
    roll's last segment ending where the next roll's first starts) is listed in both."""
    from contact.compliance.mesh import _distinct_ends, _distinct_ends_of_rolls

    rng = np.random.default_rng(80)
    rolls = []
    for r in range(5):
        curves = [rng.normal(size=(int(rng.integers(2, 7)), 3)) for _ in range(1 + r % 3)]
        rolls.append(np.concatenate([np.stack([c[:-1], c[1:]], axis=1) for c in curves]))
    rolls[2][0, 0] = rolls[1][-1, 1]  # shared across the roll boundary: not merged
    counts = np.array([e.shape[0] for e in rolls])
    points, at, index = _distinct_ends_of_rolls(np.concatenate(rolls), counts)
    alone = [_distinct_ends(e) for e in rolls]
    np.testing.assert_array_equal(points, np.concatenate([p for p, _ in alone]))
    np.testing.assert_array_equal(np.diff(at), [p.shape[0] for p, _ in alone])
    n = counts.sum()
    for r, (_, idx) in enumerate(alone):
        rows = slice(counts[:r].sum(), counts[:r + 1].sum())
        np.testing.assert_array_equal(index[:n][rows], at[r] + idx[:counts[r]])
        np.testing.assert_array_equal(index[n:][rows], at[r] + idx[counts[r]:])


def test_pair_blocks_equal_each_rolls_own():
    """The tooth-pair blocks of all rolls (one pass over rolls ordered by pair; the
    look-up roll by roll where a roll is not) are each roll's {pair: indices} and its
    slices among the concatenated segments."""
    from contact.compliance.mesh import _pair_blocks

    class Roll:  # (only pair_index is read)
        def __init__(self, pairs):
            self.pair_index = np.asarray(pairs)

    for pairs in ([[-1, -1, 0, 0, 0, 1], [0, 0, 1], [1]],  # ordered: one pass
                  [[-1, -1, 0, 0], [0, 1, 0]]):  # a roll not ordered: roll by roll
        segments = [Roll(p) for p in pairs]
        offsets = np.concatenate([[0], np.cumsum([len(p) for p in pairs])])
        blocks, flat = _pair_blocks(segments, offsets)
        k = 0
        for r, seg in enumerate(segments):
            want = {int(p): np.flatnonzero(seg.pair_index == p)
                    for p in np.unique(seg.pair_index)}
            assert list(blocks[r]) == list(want)
            for p, idx in want.items():
                np.testing.assert_array_equal(blocks[r][p], idx)
                np.testing.assert_array_equal(np.arange(offsets[-1])[flat[k]],
                                              offsets[r] + idx)
                k += 1
        assert k == len(flat)


def test_contact_segments_of_rolls_equal_one_per_roll():
    """ContactSegments.of_rolls (the LTCA pool's rolls, checked in one pass) gives each
    roll what ContactSegments of its rows gives, field by field and bit for bit; a roll
    the checks refuse raises that roll's message, a roll without segments the N >= 1
    message, counts that do not add up say so."""
    from contact.compliance.mesh import ContactSegments

    fields = _segment_fields(12)
    del fields["pinion_rotation"], fields["gear_rotation"]  # (each roll's own here)
    counts = np.array([3, 6, 3])
    pin, gear = np.array([0.1, 0.2, 0.3]), np.array([-0.4, -0.5, -0.6])
    batch = ContactSegments.of_rolls(counts, pin, gear, **fields)
    at = np.concatenate([[0], np.cumsum(counts)])
    names = ("midpoints", "ends", "normals", "length", "r_eq", "load", "pair_index",
             "pinion_rotation", "gear_rotation")
    for r, seg in enumerate(batch):
        one = ContactSegments(**{k: v[at[r]:at[r + 1]] for k, v in fields.items()},
                              pinion_rotation=float(pin[r]), gear_rotation=float(gear[r]))
        for name in names:
            a, b = getattr(seg, name), getattr(one, name)
            assert type(a) is type(b) and np.asarray(a).dtype == np.asarray(b).dtype, name
            np.testing.assert_array_equal(a, b, err_msg=name)
        assert not np.shares_memory(seg.midpoints, fields["midpoints"])
    bad = dict(fields, length=fields["length"].copy())
    bad["length"][4] = 0.0
    with pytest.raises(InputError, match="length: must be finite and > 0"):
        ContactSegments.of_rolls(counts, pin, gear, **bad)
    with pytest.raises(InputError, match=r"N >= 1"):
        ContactSegments.of_rolls(np.array([3, 0, 9]), pin, gear, **fields)
    with pytest.raises(InputError, match="add up"):
        ContactSegments.of_rolls(np.array([3, 6, 2]), pin, gear, **fields)


def test_several_rolls_parts_add_up_to_their_compliance():
    """mesh_compliance_many sums all rolls' parts in one buffer: each roll's C is its
    shell, foundation and Weber parts added (symmetrised) — to the bit where the parts
    are symmetric — and its parts equal those of mesh_compliance of the roll alone
    (1e-12 relative: the mapping's batch, as the C of
    test_mesh_compliance_of_several_rolls_in_one_batch_equals_one_by_one)."""
    from contact.compliance.mesh import mesh_compliance, mesh_compliance_many

    case, batch = _three_rolls()
    parts = ("pinion_shell", "gear_shell", "pinion_foundation", "gear_foundation", "weber")
    for b, (c, info) in zip(batch, mesh_compliance_many(case, batch), strict=True):
        total = info[parts[0]] + info[parts[1]]
        for name in parts[2:]:
            total = total + info[name]
        np.testing.assert_allclose(c, 0.5 * (total + total.T), rtol=0,
                                   atol=1e-15 * np.abs(c).max())
        _, alone = mesh_compliance(case, b)
        for name in parts:
            np.testing.assert_allclose(info[name], alone[name], rtol=1e-12,
                                       atol=1e-12 * np.abs(alone[name]).max(), err_msg=name)


def test_pool_of_several_rolls_equals_each_roll_assembled_alone():
    """CompliancePool.assemble gathers and checks every roll's pool at once: each roll's
    structural compliance and Weber depths equal that roll's pool assembled alone (to
    1e-12 relative: the one-roll batch maps its points in a batch of its own)."""
    from contact.ltca import LTCAOptions, segment_geometry
    from contact.ltca.pool import CompliancePool
    from contact.utca.easeoff import ease_off

    case = load_case(ROOT / "cases" / "hypoid_iso23509_s2.toml")
    eo = ease_off(case)
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8)
    roll = 0.1 + np.arange(4) * eo.pitch / 4
    seg = segment_geometry(case, eo, roll, opts.pairs, opts.segments)
    jobs = [(j, np.isfinite(seg.r_eq[j]) & (seg.length[j] > 0)) for j in (0, 2, 3)]
    together = CompliancePool(case, seg, opts, eo)
    together.assemble(jobs)
    for j, mask in jobs:
        alone = CompliancePool(case, seg, opts, eo)
        alone.assemble([(j, mask)])
        np.testing.assert_array_equal(together.mask(j), mask)
        a, da = together.restricted(j, mask)
        b, db = alone.restricted(j, mask)
        np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * np.abs(b).max())
        np.testing.assert_allclose(da, db, rtol=1e-12)
        # the whole pool selected: the pool's own (read-only) matrix, the same as the
        # gather of a selection that leaves one segment out, on the rows it keeps
        assert not a.flags.writeable
        keep = mask.copy()
        keep.flat[np.flatnonzero(mask)[0]] = False
        part, dpart = together.restricted(j, keep)
        np.testing.assert_array_equal(part, a[1:, 1:])
        np.testing.assert_array_equal(dpart, da[1:])


def test_legendre_rows_in_place_equal_the_recurrence_and_legendre():
    """The shell's face and height rows (``_legendre_rows``, formed in place, issue 75)
    are the rows of Bonnet's recurrence written with temporaries bit for bit (the same
    operations in the same order), and they are the Legendre polynomials and their
    derivatives (NumPy's ``legvander`` and ``legder``, an independent evaluation) to 1e-12
    (degree ≤ 20 on [−1, 1]: values ≤ 1, derivatives ≤ n(n + 1)/2 = 210)."""
    from numpy.polynomial import legendre as leg

    from contact.compliance.shell_tooth import _legendre_rows

    t = np.r_[-1.0, np.random.default_rng(7).uniform(-1.0, 1.0, 997), 1.0, 0.0]
    count = 21
    p, dp = _legendre_rows(t, count)
    ref_p, ref_dp = np.empty((count, t.size)), np.empty((count, t.size))
    ref_p[0], ref_dp[0] = 1.0, 0.0
    ref_p[1], ref_dp[1] = t, 1.0
    for k in range(1, count - 1):
        ref_p[k + 1] = ((2 * k + 1) * t * ref_p[k] - k * ref_p[k - 1]) / (k + 1)
        ref_dp[k + 1] = ref_dp[k - 1] + (2 * k + 1) * ref_p[k]
    np.testing.assert_array_equal(p, ref_p)
    np.testing.assert_array_equal(dp, ref_dp)
    eye = np.eye(count)
    np.testing.assert_allclose(p, leg.legvander(t, count - 1).T, rtol=0, atol=1e-12)
    d = np.stack([leg.legval(t, leg.legder(eye[n])) for n in range(count)])
    np.testing.assert_allclose(dp, d, rtol=1e-12, atol=1e-12)
